//! The generated reduced Stewart model (`stewart_6_6::reduced`, 60 coordinates and 54 rows
//! after substituting the 18 Euler-angle equalities) against the full 78-coordinate model:
//! the same HHT settings must give the same motion and, read back through `REDUCTION`, the
//! same joint and actuator forces.

use symbody_benchmark_mechanisms::stewart_6_6::{self, reduced, Exact};
use symbody_runtime::{
    actuator_force, joint_force, FullState, HhtBuilder, Kinematics, Mechanism, MechanismInfo,
};

/// The recorded forces of the paper's scene at a full state: upper and lower joint forces and
/// actuator forces (N), from the multipliers `lambda` of the full model's rows.
fn forces(info: &MechanismInfo, phi_q: &[f64], lambda: &[f64]) -> Vec<f64> {
    let platform = info.body_index("platform").unwrap();
    let mut out = Vec::new();
    for i in 1..=6 {
        let j = info.joint_index(&format!("upper_sph{i}")).unwrap();
        out.extend(joint_force(info, phi_q, lambda, j, platform).unwrap());
        let j = info.joint_index(&format!("lower_sph{i}")).unwrap();
        let lower = info.body_index(&format!("lower{i}")).unwrap();
        out.extend(joint_force(info, phi_q, lambda, j, lower).unwrap());
        let a = info.joint_index(&format!("act{i}")).unwrap();
        out.push(actuator_force(info, lambda, a).unwrap());
    }
    out
}

#[test]
fn the_reduced_model_has_60_coordinates_and_54_rows() {
    let r = reduced::Exact.info();
    assert_eq!((r.n_coords, r.n_constraints), (60, 54));
    assert_eq!(
        (Exact.info().n_coords, Exact.info().n_constraints),
        (78, 72)
    );
    assert_eq!(reduced::SUBSTITUTIONS.len(), 18);
    // The reduced start is the full one restricted.
    let mut q = vec![0.0; 78];
    reduced::REDUCTION.expand(r.q0, 0.0, 0, &mut q).unwrap();
    assert_eq!(q, stewart_6_6::Q0);
}

/// HHT (α = −0.05, h = 1 ms) on both models over 1 s, compared every 0.05 s. Measured:
/// coordinates 3.1e-13, velocities 1.2e-11 (both within HHT's Newton tolerance, which the two
/// models meet along different iterates), forces 5.3e-12 N, every multiplier 8.6e-12 (the
/// eliminated rows', ≈ 0.1 N·m, read back through `FullState`).
#[test]
fn reduced_and_full_models_move_and_react_alike() {
    let full_info = Exact.info();
    let mut full = HhtBuilder::new()
        .alpha(-0.05)
        .step(1e-3)
        .build(Exact)
        .unwrap();
    let mut red = HhtBuilder::new()
        .alpha(-0.05)
        .step(1e-3)
        .build(reduced::Exact)
        .unwrap();
    let mut kin_full: Kinematics = Kinematics::new(full_info).unwrap();
    let mut kin_red: Kinematics = Kinematics::new(reduced::Exact.info()).unwrap();
    let (n, m) = (78, 72);
    let (mut qdd, mut lambda) = (vec![0.0; n], vec![0.0; m]);
    let (mut qdd_r, mut lambda_r) = (vec![0.0; 60], vec![0.0; 54]);
    let (mut q, mut qd) = (vec![0.0; n], vec![0.0; n]);
    let mut back = FullState::new(&reduced::REDUCTION, full_info).unwrap();
    let mut phi_q = vec![0.0; full_info.phi_q_nnz()];
    let (mut motion, mut rates, mut force) = (0.0f64, 0.0f64, 0.0f64);
    let mut multiplier = 0.0f64;
    for k in 1..=20 {
        let t = k as f64 * 0.05;
        full.advance_to(t).unwrap();
        red.advance_to(t).unwrap();
        let r = &reduced::REDUCTION;
        r.expand(red.q(), t, 0, &mut q).unwrap();
        r.expand(red.qd(), t, 1, &mut qd).unwrap();
        for (x, y) in q.iter().zip(full.q()) {
            motion = motion.max((x - y).abs());
        }
        for (x, y) in qd.iter().zip(full.qd()) {
            rates = rates.max((x - y).abs());
        }
        // Forces recovered at each model's own state, as the scenario records them.
        kin_full
            .acceleration(&Exact, t, full.q(), full.qd(), &mut qdd, &mut lambda)
            .unwrap();
        kin_red
            .acceleration(
                &reduced::Exact,
                t,
                red.q(),
                red.qd(),
                &mut qdd_r,
                &mut lambda_r,
            )
            .unwrap();
        back.read(&Exact, t, red.q(), red.qd(), &qdd_r, &lambda_r)
            .unwrap();
        assert_eq!((&back.q, &back.qd), (&q, &qd));
        Exact.phi_q(full.q(), t, &mut phi_q);
        let f_full = forces(full_info, &phi_q, &lambda);
        let f_red = forces(full_info, &back.phi_q, &back.lambda);
        // Every row's multiplier, the eliminated rows' (which no recorded force reads) too.
        for (x, y) in lambda.iter().zip(&back.lambda) {
            multiplier = multiplier.max((x - y).abs());
        }
        for (x, y) in f_full.iter().zip(&f_red) {
            force = force.max((x - y).abs());
        }
    }
    assert!(motion <= 1e-12, "coordinates differ by {motion:e}");
    assert!(rates <= 1e-10, "velocities differ by {rates:e}");
    assert!(force <= 1e-10, "forces differ by {force:e} N");
    assert!(multiplier <= 1e-10, "multipliers differ by {multiplier:e}");
}

/// The paper scenario run on the reduced model (`scenario::simulate_reduced`) records the same
/// series as on the full one. Measured over 1 s at h = 1 ms: forces 5.3e-12 N, pose 8.8e-16.
#[test]
fn the_paper_scenario_on_the_reduced_model_records_the_same_series() {
    use symbody::scenario::{simulate, simulate_reduced, Options};
    let opts = Options {
        t_end: 1.0,
        output_step: 0.05,
        ..Options::default()
    };
    let (full, red) = (
        simulate(&symbody_benchmark_mechanisms::REGISTRY, &opts).unwrap(),
        simulate_reduced(&symbody_benchmark_mechanisms::REGISTRY, &opts).unwrap(),
    );
    let (forces, pose, _) = differences(&red, &full);
    assert!(forces <= 1e-10, "forces {forces:e} N");
    assert!(pose <= 1e-12, "{pose:e}");
}

/// The largest differences of two runs' recorded forces (N), platform pose and energy (J).
fn differences(a: &symbody::scenario::Run, b: &symbody::scenario::Run) -> (f64, f64, f64) {
    let most = |f: fn(&symbody::scenario::Run, usize) -> &[f64]| a.max_difference(b, f).unwrap().0;
    let forces = most(|r, k| r.upper[k].as_flattened())
        .max(most(|r, k| r.lower[k].as_flattened()))
        .max(most(|r, k| &r.actuators[k]));
    let pose = most(|r, k| &r.platform[k]);
    let energy = most(|r, k| std::slice::from_ref(&r.energy[k]));
    (forces, pose, energy)
}

/// The paper's kinematic path followed on the reduced model (what `scenes/paper.toml` runs)
/// records the same series as on the full model, and the full model's residuals at the
/// read-back states are roundoff. Measured over 1 s: forces 1.0e-12 N, pose 7.7e-14.
#[test]
fn the_kinematic_path_on_the_reduced_model_records_the_full_models_series() {
    use std::sync::atomic::AtomicBool;
    use symbody::scenario::{kinematic_until, Options};
    let opts = Options {
        t_end: 1.0,
        output_step: 0.01,
        ..Options::default()
    };
    let run = |reduced| kinematic_until(Exact, reduced, &opts, &AtomicBool::new(false)).unwrap();
    let (full, red) = (run(None), run(Some((&reduced::Exact, &reduced::REDUCTION))));
    assert_eq!((full.reduced, red.reduced), (None, Some(60)));
    assert_eq!(red.t.len(), 101);
    let (forces, pose, energy) = differences(&red, &full);
    assert!(forces <= 1e-10, "forces {forces:e} N");
    assert!(pose <= 1e-12, "{pose:e}");
    assert!(energy <= 1e-12, "energy {energy:e} J");
    assert!(red.max_phi <= 1e-14, "{:e}", red.max_phi);
    assert!(
        red.max_velocity_residual <= 1e-12,
        "{:e}",
        red.max_velocity_residual
    );
}

/// Work given to `kinematic_beside` runs on the recording thread before it records, and its
/// answer comes back: when it sets `stop` (a choice of integration), the path stops at its
/// next output with `Interrupted`; when it does not, the run is the one `kinematic_until`
/// makes, output for output.
#[test]
fn work_beside_the_path_runs_once_and_may_stop_it() {
    use std::sync::atomic::{AtomicBool, Ordering};
    use symbody::scenario::{kinematic_beside, kinematic_until, Options, ScenarioError};
    let opts = Options {
        t_end: 0.5,
        output_step: 0.01,
        ..Options::default()
    };
    let reduced = Some((&reduced::Exact as _, &reduced::REDUCTION));
    let stop = AtomicBool::new(false);
    let mut calls = 0;
    let (run, answer) = kinematic_beside(Exact, reduced, &opts, &stop, || {
        calls += 1;
        42
    });
    let (run, alone) = (
        run.unwrap(),
        kinematic_until(Exact, reduced, &opts, &stop).unwrap(),
    );
    assert_eq!((calls, answer), (1, 42));
    assert_eq!(run.t, alone.t);
    assert_eq!(run.platform, alone.platform);
    assert_eq!(run.actuators, alone.actuators);

    // More outputs than the recorder's queue holds (32 batches of 16): the path cannot finish
    // before the recorder takes a batch, which it does only after `beside` has set `stop`,
    // so the path sees it whatever the threads' order.
    let long = Options {
        t_end: 10.0,
        ..opts
    };
    let (run, answer) = kinematic_beside(Exact, reduced, &long, &stop, || {
        stop.store(true, Ordering::Relaxed);
        "integrate"
    });
    assert_eq!(answer, "integrate");
    match run {
        Err(ScenarioError::Interrupted { time }) => assert!(time < long.t_end, "{time}"),
        other => panic!("{:?}", other.map(|r| r.t.len())),
    }
}

/// `Options::reduce` (scenes: `[solver] reduce = "auto"`): a generic run integrates the
/// reduced model of every mechanism that has one, or follows it by the kinematic path, and
/// records the same series as the full model's run with the same settings, read back at
/// every step.
#[test]
fn generic_runs_on_the_reduced_model_record_the_full_models_series() {
    use symbody::generic::{self, Options};
    // The last, the kinematic path (driven, spins idle) on the reduced model.
    for (name, n_reduced, kinematic) in [
        ("stewart_6_6", 60, false),
        ("slider_crank", 0, false),
        ("oscillators", 0, false),
        ("simple_pendulum", 3, false),
        ("four_bar", 9, false),
        ("stewart_6_6", 60, true),
    ] {
        let entry = generic::find(&symbody_mechanisms::REGISTRY, name).unwrap();
        let opts = Options {
            t_end: Some(0.5),
            ..Options::default()
        };
        let run = |opts: &Options| match kinematic {
            true => generic::run_kinematic(entry, opts).unwrap(),
            false => generic::run(entry, opts).unwrap(),
        };
        let full = run(&opts);
        let red = run(&Options {
            reduce: true,
            ..opts
        });
        assert_eq!(red.kinematic.is_some(), kinematic);
        assert_eq!(full.reduced, None);
        let n = red.reduced.expect("followed the reduced model");
        assert!(n < full.info.n_coords, "{name}: {n} coordinates");
        if n_reduced > 0 {
            assert_eq!(n, n_reduced);
        }
        assert_eq!(red.t, full.t);
        let diff = |a: &[Vec<f64>], b: &[Vec<f64>]| {
            let scale = b.iter().flatten().fold(1e-300f64, |m, v| m.max(v.abs()));
            a.iter()
                .flatten()
                .zip(b.iter().flatten())
                .fold(0.0f64, |m, (x, y)| m.max((x - y).abs() / scale))
        };
        let flat = |r: &generic::Recording| -> Vec<Vec<f64>> {
            r.wrenches
                .iter()
                .map(|w| {
                    w.iter()
                        .flat_map(|w| w.force.into_iter().chain(w.moment))
                        .collect()
                })
                .collect()
        };
        let (q, efforts, wrenches) = (
            diff(&red.q, &full.q),
            diff(&red.efforts, &full.efforts),
            diff(&flat(&red), &flat(&full)),
        );
        println!(
            "{name}: reduced {n} of {}: q {q:.1e}, efforts {efforts:.1e}, wrenches {wrenches:.1e}",
            full.info.n_coords
        );
        // The kinematic path solves each output to roundoff on both models.
        let bound = if kinematic { 1e-12 } else { 1e-8 };
        assert!(
            q.max(efforts).max(wrenches) <= bound,
            "{name}: {q:e} {efforts:e} {wrenches:e}"
        );
    }
}
