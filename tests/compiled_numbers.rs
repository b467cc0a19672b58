//! Parameters that reach the model's numbers (joint points, lengths, placements, drivers'
//! constants) set at run time on the compiled code (decision 36): the file is loaded at the
//! new values, the compiled code takes the numbers it gives, and the file derived again gives
//! the pose and the dependent rows.
//!
//! Reference: the mechanism file derived again with the same values and interpreted
//! (`files::derive`: the file edited to that value, `tests/parameters.rs`), whose equations
//! and runs the compiled code must reproduce to roundoff, and whose tables the route must
//! keep (pose, dependent rows, masses).

use symbody::files;
use symbody_mechanisms::REGISTRY;
use symbody_runtime::{Entry, KinematicOutputs, Mechanism, MechanismInfo, NewtonOutputs, Origin};
use symbody_testkit::common::{dense_mass, dense_phi_q, hht_positions, max_rel};

fn owned(set: &[(&str, f64)]) -> Vec<(String, f64)> {
    set.iter().map(|(k, v)| (k.to_string(), *v)).collect()
}

/// Every equation of `m` at the file's pose moved a little, with velocities: Φ, Φq, Φt, γ, M,
/// Q and the potential.
fn equations(m: &dyn Mechanism) -> Vec<f64> {
    let info = m.info();
    let q: Vec<f64> = info
        .q0
        .iter()
        .enumerate()
        .map(|(i, v)| v + 1e-3 * (i as f64).sin())
        .collect();
    let qd: Vec<f64> = (0..q.len()).map(|i| 0.3 * (i as f64).cos()).collect();
    let t = 0.4;
    let (n, c) = (info.n_coords, info.n_constraints);
    let (mut phi, mut phi_q, mut phi_t, mut gamma) = (
        vec![0.0; c],
        vec![0.0; info.phi_q_nnz()],
        vec![0.0; c],
        vec![0.0; c],
    );
    m.eval_kinematics(
        &q,
        &qd,
        t,
        KinematicOutputs {
            phi: &mut phi,
            phi_q: &mut phi_q,
            phi_t: &mut phi_t,
            gamma: &mut gamma,
        },
    );
    let (mut phi2, mut phi_q2, mut mass, mut force) = (
        vec![0.0; c],
        vec![0.0; info.phi_q_nnz()],
        vec![0.0; info.mass_nnz()],
        vec![0.0; n],
    );
    m.eval_newton(
        &q,
        &qd,
        t,
        NewtonOutputs {
            phi: &mut phi2,
            phi_q: &mut phi_q2,
            mass: &mut mass,
            force: &mut force,
        },
    );
    assert_eq!((&phi, &phi_q), (&phi2, &phi_q2), "one Φ, fused or not");
    let mut out = phi;
    out.extend(dense_phi_q(info, &phi_q).iter());
    out.extend(phi_t);
    out.extend(gamma);
    out.extend(dense_mass(info, &mass).iter());
    out.extend(force);
    out.push(m.potential(&q));
    out
}

/// The positions after 0.3 s of HHT from the file's pose.
fn run(m: &dyn Mechanism) -> Vec<f64> {
    hht_positions(m, 0.3)
}

/// `name` with `set` on the compiled route, and the file derived with it.
fn both(name: &str, set: &[(&str, f64)]) -> (&'static Entry, &'static Entry) {
    let entry = REGISTRY.find(name).unwrap();
    let set = owned(set);
    let compiled = files::reparametrized(entry, &set).unwrap();
    let note = files::note(compiled).unwrap();
    assert!(
        matches!(compiled.origin, Origin::Compiled { .. }),
        "{name}: {note}"
    );
    assert!(note.contains("the code takes the numbers"), "{note}");
    (compiled, files::derive(entry, &set).unwrap().entry)
}

#[test]
fn geometry_set_at_run_time_is_the_file_derived_with_it() {
    for (name, set) in [
        ("slider_crank", &[("r", 0.12)][..]),
        ("slider_crank", &[("len", 0.4), ("e", 0.03)][..]),
        ("stewart_6_6", &[("r_platform", 0.11)][..]),
        (
            "stewart_6_6",
            &[("r_base", 0.25), ("half", 0.13), ("m_cyl", 0.4)][..],
        ),
        ("four_bar", &[("b", 0.37)][..]),
        ("spherical_pendulum", &[("l", 0.8)][..]),
    ] {
        let (compiled, derived) = both(name, set);
        let (c, d) = (compiled.default_mechanism(), derived.default_mechanism());
        // The pose, dependent rows and bodies are the derived file's.
        assert_eq!(c.info().q0, d.info().q0, "{name}");
        assert_eq!(c.info().redundant_rows, d.info().redundant_rows, "{name}");
        let mass = |i: &MechanismInfo| i.bodies.iter().map(|b| b.mass).collect::<Vec<_>>();
        assert_eq!(mass(c.info()), mass(d.info()), "{name}");
        let (a, b) = (equations(c), equations(d));
        assert!(
            max_rel(&a, &b) <= 1e-13,
            "{name} {set:?}: {:e}",
            max_rel(&a, &b)
        );
        // And the file's values would not do.
        let file = equations(REGISTRY.find(name).unwrap().default_mechanism());
        assert!(
            max_rel(&file, &b) > 1e-6,
            "{name}: the set changes the equations"
        );
        let (qa, qb) = (run(c), run(d));
        println!(
            "{name} {set:?}: equations {:.1e}, 0.3 s of HHT {:.1e}",
            max_rel(&a, &b),
            max_rel(&qa, &qb)
        );
        assert!(
            max_rel(&qa, &qb) <= 1e-12,
            "{name}: {:e}",
            max_rel(&qa, &qb)
        );
    }
}

#[test]
fn a_set_that_changes_a_held_constant_runs_the_file_interpreted() {
    // An actuator amplitude of 0 makes the driver's value `initial`, without the term in
    // sin t the compiled code has: another expression, so the file runs interpreted.
    let entry = REGISTRY.find("stewart_6_6").unwrap();
    let e = files::reparametrized(entry, &owned(&[("a1", 0.0)])).unwrap();
    assert!(
        matches!(e.origin, Origin::Interpreted { .. }),
        "{:?}",
        e.origin
    );
    let note = files::note(e).unwrap();
    assert!(
        note.contains("the compiled code does not take them")
            && note.contains("expression in t, whose terms change"),
        "{note}"
    );
    // The four-bar's initial crank angle is a derived parameter: set, it moves numbers the
    // code holds fixed, and the note says whose.
    let e = files::reparametrized(
        REGISTRY.find("four_bar").unwrap(),
        &owned(&[("theta0", 1.2)]),
    )
    .unwrap();
    let note = files::note(e).unwrap();
    assert!(
        matches!(e.origin, Origin::Interpreted { .. }) && note.contains("holds fixed (joint `a0`)"),
        "{note}"
    );
    // A value that does not load is the file's error, naming the parameter.
    let err = files::reparametrized(REGISTRY.find("four_bar").unwrap(), &owned(&[("b", 0.01)]))
        .unwrap_err()
        .to_string();
    assert!(err.contains("b = 0.01"), "{err}");
}

#[test]
fn a_study_row_with_geometry_runs_the_compiled_code_and_frees_it() {
    let entry = REGISTRY.find("slider_crank").unwrap();
    let set = owned(&[("r", 0.12)]);
    let derived = files::derive(entry, &set).unwrap().entry;
    let reference = equations(derived.default_mechanism());
    let row = files::with_compiled_at(entry, &set, |e| {
        assert!(matches!(e.origin, Origin::Compiled { .. }));
        equations(e.default_mechanism())
    })
    .unwrap()
    .expect("the compiled route");
    assert!(
        max_rel(&row, &reference) <= 1e-13,
        "{:e}",
        max_rel(&row, &reference)
    );
}

/// The compiled planar model serves other link lengths: it pins the same coordinates (z, θ, β
/// at 0), so a reduced run at the new values records the full model's series; where the
/// substitutions read the model's numbers (the slider-crank's slider line), the full model
/// runs.
#[test]
fn the_reduced_model_serves_values_that_keep_what_it_pins() {
    use symbody::generic::{self, Options};
    let entry = REGISTRY.find("four_bar").unwrap();
    let set = owned(&[("b", 0.37), ("c", 0.32)]);
    let e = files::reparametrized(entry, &set).unwrap();
    assert!(matches!(e.origin, Origin::Compiled { .. }));
    let opts = Options {
        t_end: Some(0.5),
        ..Options::default()
    };
    let full = generic::run(e, &opts).unwrap();
    let red = generic::run(
        e,
        &Options {
            reduce: true,
            ..opts
        },
    )
    .unwrap();
    assert_eq!(red.reduced, Some(9), "the planar model ran");
    let flat = |v: &[Vec<f64>]| -> Vec<f64> { v.iter().flatten().copied().collect() };
    let (q, efforts) = (
        max_rel(&flat(&red.q), &flat(&full.q)),
        max_rel(&flat(&red.efforts), &flat(&full.efforts)),
    );
    assert!(q.max(efforts) <= 1e-8, "{q:e} {efforts:e}");
    // And the file's values would not do: the reduced run moved with the set.
    let file = generic::run(entry, &opts).unwrap();
    assert!(max_rel(&flat(&red.q), &flat(&file.q)) > 1e-3);
    let crank = files::reparametrized(
        REGISTRY.find("slider_crank").unwrap(),
        &owned(&[("e", 0.03)]),
    );
    assert!(
        crank.unwrap().reduced.is_none(),
        "the slider's line is a substitution's offset"
    );
}

/// Every number parameter of every shipped mechanism, moved by 3 % on its own: where the
/// compiled code takes the values, its equations are the file's derived at them. What a slot
/// missed (a number the code holds but the parameter moves, unnoticed) would show here.
#[test]
fn every_parameter_of_every_mechanism_runs_as_the_file_derived() {
    let (mut compiled, mut interpreted, mut worst) = (0, 0, 0.0f64);
    for entry in REGISTRY.iter() {
        let parameters = files::derive(entry, &[]).unwrap().parameters;
        for p in parameters.iter().filter(|p| p.expression.is_none()) {
            let value = if p.value == 0.0 { 0.01 } else { 1.03 * p.value };
            let set = vec![(p.name.clone(), value)];
            let Ok(e) = files::reparametrized(entry, &set) else {
                continue; // a value the file refuses (the fuzz test covers those)
            };
            if !matches!(e.origin, Origin::Compiled { .. }) {
                interpreted += 1;
                continue;
            }
            compiled += 1;
            let derived = files::derive(entry, &set).unwrap().entry;
            let (a, b) = (
                equations(e.default_mechanism()),
                equations(derived.default_mechanism()),
            );
            let d = max_rel(&a, &b);
            assert!(d <= 1e-12, "{} {} = {value}: {d:e}", entry.name, p.name);
            worst = worst.max(d);
        }
    }
    println!("{compiled} sets ran compiled (worst {worst:.1e}), {interpreted} interpreted");
    // A 3 % move keeps every shipped file's structure: none should need the interpreter.
    assert_eq!(interpreted, 0, "{compiled} compiled");
}
