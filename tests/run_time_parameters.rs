//! Run-time parameters of the compiled code (`<Type>::with_parameters`, decision 30): the
//! parameters that reach only masses, inertias and springs' stiffness and damping are inputs
//! of the generated functions.
//!
//! References: the mechanism file derived again with the same values and interpreted
//! (`files::derive`; the file edited to that value, as `tests/parameters.rs` shows), which
//! must give the same equations and the same run; Newton's second law for the platform, which
//! a payload's feedforward forces must obey; and the unit types, which the file's own values
//! must reproduce.

use symbody::files;
use symbody_mechanisms::{oscillators, stewart_6_6, REGISTRY};
use symbody_runtime::parameters::ParameterError;
use symbody_runtime::{joint_force, HhtBuilder, Kinematics, Mechanism, NewtonOutputs, Origin};
use symbody_testkit::common::{hht_positions, max_rel};

/// `eval_newton` of `m` at the file's pose, moved a little so that nothing is symmetric,
/// with velocities (so that every velocity term counts).
fn newton(m: &dyn Mechanism) -> Vec<f64> {
    let info = m.info();
    let q: Vec<f64> = info
        .q0
        .iter()
        .enumerate()
        .map(|(i, v)| v + 1e-3 * (i as f64).sin())
        .collect();
    let qd: Vec<f64> = (0..q.len()).map(|i| 0.3 * (i as f64).cos()).collect();
    let mut phi = vec![0.0; info.n_constraints];
    let mut phi_q = vec![0.0; info.phi_q_nnz()];
    let mut mass = vec![0.0; info.mass_nnz()];
    let mut force = vec![0.0; info.n_coords];
    m.eval_newton(
        &q,
        &qd,
        0.4,
        NewtonOutputs {
            phi: &mut phi,
            phi_q: &mut phi_q,
            mass: &mut mass,
            force: &mut force,
        },
    );
    let mut out = mass;
    out.extend(force);
    out.push(m.potential(&q));
    out
}

/// The positions after 0.5 s of HHT from the file's pose.
fn run(m: impl Mechanism) -> Vec<f64> {
    hht_positions(m, 0.5)
}

fn owned(set: &[(&str, f64)]) -> Vec<(String, f64)> {
    set.iter().map(|(k, v)| (k.to_string(), *v)).collect()
}

/// The file of `name` derived again with `set` and interpreted.
fn interpreted(name: &str, set: &[(&str, f64)]) -> &'static (dyn Mechanism + Sync) {
    let entry = REGISTRY.find(name).unwrap();
    let loaded = files::derive(entry, &owned(set)).unwrap();
    assert!(matches!(loaded.entry.origin, Origin::Interpreted { .. }));
    loaded.entry.default_mechanism()
}

#[test]
fn the_paper_platform_with_other_masses_is_the_file_derived_with_them() {
    // The payload (with the platform) 40 % heavier, the cylinders and pistons of the legs
    // heavier and thicker.
    let set = [
        ("m_platform", 2.5),
        ("m_cyl", 0.45),
        ("m_pis", 0.31),
        ("r_cyl", 0.02),
    ];
    let compiled = stewart_6_6::Exact::with_parameters(&set).unwrap();
    let reference = interpreted("stewart_6_6", &set);
    let (a, b) = (newton(&compiled), newton(reference));
    assert!(max_rel(&a, &b) <= 1e-13, "{:e}", max_rel(&a, &b));
    // And the values made a difference.
    assert!(max_rel(&newton(&stewart_6_6::Exact), &b) > 1e-2);
    let (qa, qb) = (run(compiled), run(reference));
    assert!(max_rel(&qa, &qb) <= 1e-12, "{:e}", max_rel(&qa, &qb));
}

#[test]
fn the_oscillators_with_another_mass_are_the_file_derived_with_it() {
    // And stiffer, more damped springs (linear and torsion).
    let set = [
        ("m", 3.5),
        ("k", 80.0),
        ("c", 1.1),
        ("kt", 3.0),
        ("ct", 0.05),
    ];
    let compiled = oscillators::Exact::with_parameters(&set).unwrap();
    let reference = interpreted("oscillators", &set);
    let (a, b) = (newton(&compiled), newton(reference));
    assert!(max_rel(&a, &b) <= 1e-13, "{:e}", max_rel(&a, &b));
    let (qa, qb) = (run(compiled), run(reference));
    assert!(max_rel(&qa, &qb) <= 1e-12, "{:e}", max_rel(&qa, &qb));
}

#[test]
fn the_file_values_give_the_unit_type_to_the_last_bit() {
    let at = stewart_6_6::Exact::with_parameters(&[]).unwrap();
    assert_eq!(newton(&at), newton(&stewart_6_6::Exact));
    let named = stewart_6_6::PARAMETERS.len();
    assert_eq!(&at.0.values()[..named], &stewart_6_6::PARAMETER_VALUES[..]);
    assert_eq!(at.0.values(), &stewart_6_6::P0[..]);
}

#[test]
fn refused_sets_name_the_parameter_or_body_and_change_nothing() {
    let mut p = stewart_6_6::Parameters::file_values();
    let before = p.values().to_vec();
    match p.set(&[("m_platfrom", 2.0)]) {
        Err(ParameterError::Unknown { closest, .. }) => assert_eq!(closest, Some("m_platform")),
        other => panic!("{other:?}"),
    }
    // Geometry decides the assembly: set on the file instead.
    assert!(matches!(
        p.set(&[("r_base", 0.3)]),
        Err(ParameterError::NotRunTime { .. })
    ));
    assert!(matches!(
        p.set(&[("m_cyl", f64::NAN)]),
        Err(ParameterError::NotFinite { .. })
    ));
    // A valid value first, then the bad one: nothing of the set is applied.
    match p.set(&[("m_cyl", 0.5), ("m_platform", -1.0)]) {
        Err(e @ ParameterError::Mass { body, .. }) => {
            assert_eq!(body, "platform");
            assert!(
                e.to_string()
                    .contains("with m_cyl = 0.5, m_platform = -1 set"),
                "{e}"
            );
        }
        other => panic!("{other:?}"),
    }
    // A cylinder thicker than it is long is still a rigid body; zero radius is not allowed.
    assert!(matches!(
        p.set(&[("r_cyl", 0.0)]),
        Err(ParameterError::Inertia { .. })
    ));
    assert_eq!(p.values(), &before[..]);
    p.set(&[("m_cyl", 0.5)]).unwrap();
    // A spring's constants: negative is refused, naming the force.
    let mut o = oscillators::Parameters::file_values();
    match o.set(&[("k", -5.0)]) {
        Err(e @ ParameterError::ForceConstant { field, .. }) => {
            assert_eq!(field, "stiffness");
            assert!(e.to_string().contains("with k = -5 set"), "{e}");
        }
        other => panic!("{other:?}"),
    }
    assert_ne!(p.values(), &before[..]);
}

/// `files::with_parameters` (what `--set`, Python, C and scenes use) takes the compiled
/// route when every value set is a run-time parameter, and derives the file otherwise.
#[test]
fn setting_only_masses_runs_the_compiled_code() {
    let set = owned(&[("m_platform", 2.5)]);
    let e = files::with_parameters(&REGISTRY, "stewart_6_6", &set).unwrap();
    assert!(
        matches!(e.origin, Origin::Compiled { parameters, .. } if parameters == [("m_platform", 2.5)])
    );
    assert!(files::note(e).unwrap().contains("m_platform = 2.5"));
    let direct = stewart_6_6::Exact::with_parameters(&[("m_platform", 2.5)]).unwrap();
    assert_eq!(newton(e.default_mechanism()), newton(&direct));
    // A geometric value among them: the compiled code takes the numbers of the file loaded
    // at these values (tests/compiled_numbers.rs).
    let mixed = owned(&[("m_platform", 2.5), ("r_base", 0.28)]);
    let e = files::with_parameters(&REGISTRY, "stewart_6_6", &mixed).unwrap();
    assert!(matches!(e.origin, Origin::Compiled { parameters, .. } if parameters.len() == 2));
    assert!(files::note(e)
        .unwrap()
        .contains("the code takes the numbers"));
}

/// A payload on the paper's platform, following the same prescribed motion: the legs'
/// forces on the platform change by exactly what Newton's second law asks for the added
/// mass, Δm (a − g), with `a` the platform's acceleration (the motion is the same).
#[test]
fn a_payload_changes_the_legs_forces_by_its_weight_and_inertia() {
    let dm = 0.5;
    let light = stewart_6_6::Exact::with_parameters(&[]).unwrap();
    let i = stewart_6_6::PARAMETERS
        .iter()
        .position(|n| *n == "m_platform")
        .unwrap();
    let heavy = stewart_6_6::Exact::with_parameters(&[(
        "m_platform",
        stewart_6_6::PARAMETER_VALUES[i] + dm,
    )])
    .unwrap();
    let info = light.info();
    // A state on the prescribed motion: 0.7 s into the scenario's run.
    let mut it = HhtBuilder::new()
        .alpha(-0.05)
        .step(1e-3)
        .build(light.clone())
        .unwrap();
    it.advance_to(0.7).unwrap();
    let (t, q, qd) = (it.t(), it.q().to_vec(), it.qd().to_vec());
    let platform = info.body_index("platform").unwrap();
    let mut kin: Kinematics = Kinematics::new(info).unwrap();
    let mut phi_q = vec![0.0; info.phi_q_nnz()];
    let mut on_platform = |m: &dyn Mechanism| {
        let (mut qdd, mut lambda) = (vec![0.0; info.n_coords], vec![0.0; info.n_constraints]);
        kin.acceleration(&m, t, &q, &qd, &mut qdd, &mut lambda)
            .unwrap();
        m.phi_q(&q, t, &mut phi_q);
        let mut sum = [0.0; 3];
        for (j, joint) in info.joints.iter().enumerate() {
            if joint.body1 == Some(platform) || joint.body2 == Some(platform) {
                let f = joint_force(info, &phi_q, &lambda, j, platform).unwrap();
                for k in 0..3 {
                    sum[k] += f[k];
                }
            }
        }
        let off = info.bodies[platform].coord_offset;
        (sum, [qdd[off], qdd[off + 1], qdd[off + 2]])
    };
    let (f_light, a_light) = on_platform(&light);
    let (f_heavy, a_heavy) = on_platform(&heavy);
    // The same prescribed motion (the solves differ in roundoff only).
    for k in 0..3 {
        assert!(
            (a_light[k] - a_heavy[k]).abs() <= 1e-12,
            "{a_light:?} {a_heavy:?}"
        );
    }
    for k in 0..3 {
        let want = dm * (a_light[k] - info.gravity[k]);
        let got = f_heavy[k] - f_light[k];
        assert!(
            (got - want).abs() <= 1e-9 * (1.0 + want.abs()),
            "{k}: {got} vs {want}"
        );
    }
}

/// A mechanism on the compiled route keeps its reduced model (the planar four-bar, the
/// oscillators' substituted one) at the values set: a run on it records the full model's run
/// at the same values, to the integrator's agreement (as `tests/reduced_stewart.rs` pins for
/// the file's values), and the values set take effect on it.
#[test]
fn the_reduced_models_take_the_run_time_parameters_too() {
    use symbody::generic::{self, Options};
    for (name, set) in [
        (
            "oscillators",
            owned(&[("m", 3.0), ("k", 80.0), ("kt", 3.0)]),
        ),
        ("four_bar", owned(&[("rod", 2e-4)])),
    ] {
        let entry = files::with_parameters(&REGISTRY, name, &set).unwrap();
        assert!(entry.reduced.is_some(), "{name}");
        let opts = Options {
            t_end: Some(0.5),
            ..Options::default()
        };
        let full = generic::run(entry, &opts).unwrap();
        let reduce = Options {
            reduce: true,
            ..opts
        };
        let red = generic::run(entry, &reduce).unwrap();
        assert!(red.reduced.is_some(), "{name}: ran reduced");
        let flat = |r: &generic::Recording| r.q.iter().flatten().copied().collect::<Vec<f64>>();
        let d = max_rel(&flat(&red), &flat(&full));
        assert!(d <= 1e-8, "{name}: {d:e}");
        if name == "oscillators" {
            let base = generic::run(REGISTRY.find(name).unwrap(), &reduce).unwrap();
            assert!(
                max_rel(&flat(&red), &flat(&base)) > 1e-3,
                "{name}: values took effect"
            );
        }
    }
}
