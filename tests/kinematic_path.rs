//! Why the paper's scene may skip integration (docs/design.md, decision 22): the Stewart
//! legs' spins about their own axes are free directions, but axisymmetric legs give them no
//! momentum, so the kinematic path (least-energy velocity at every output) is the motion the
//! equations of motion produce. Checked against HHT integration of the same model, which must
//! converge to the kinematic path as its step shrinks, and whose integrated legs must keep a
//! zero spin rate. The paper formulation's diagonal mass matrix drives the spins; there the
//! check must refuse the kinematic path, and the kinematic answer must indeed be wrong.

use symbody::scenario::{self, Options, Run};
use symbody_benchmark_mechanisms::stewart_6_6::{Exact, Paper};
use symbody_runtime::kinematic_path::Outputs;
use symbody_runtime::{
    angular_velocity, free_motion, joint_force, rotation_matrix, Formulation, Mechanism,
    MAX_ACCELERATION_MISMATCH,
};

/// The paper's reported forces (upper joints on the platform, global frame) from a state.
fn upper_forces<M: Mechanism>(mech: &M) -> Box<Outputs<'_>> {
    let info = mech.info();
    let platform = info.body_index("platform").unwrap();
    Box::new(
        move |_q: &[f64], _qd: &[f64], lambda: &[f64], phi_q: &[f64]| {
            let mut out = Vec::new();
            for i in 1..=6 {
                let j = info.joint_index(&format!("upper_sph{i}")).unwrap();
                out.extend(joint_force(info, phi_q, lambda, j, platform)?);
            }
            Ok(out)
        },
    )
}

fn options(formulation: Formulation, step: f64) -> Options {
    Options {
        formulation,
        t_end: 1.0,
        step,
        output_step: 0.04,
        ..Options::default()
    }
}

/// Largest difference of the upper-joint and actuator forces (N).
fn force_difference(a: &Run, b: &Run) -> f64 {
    let upper = a
        .max_difference(b, |r, k| r.upper[k].as_flattened())
        .unwrap()
        .0;
    let act = a.max_difference(b, |r, k| &r.actuators[k]).unwrap().0;
    upper.max(act)
}

#[test]
fn axisymmetric_legs_spin_idle_so_the_kinematic_path_is_the_integrated_motion() {
    // The check: six free directions (the spins) whose momentum stays zero and whose motion
    // changes no force. Measured: mismatch 2.2e-10, output change 2.8e-13.
    let mut outputs = upper_forces(&Exact);
    let free = free_motion(&Exact, 0.0, Exact.info().q0, &mut *outputs).unwrap();
    assert_eq!(free.dof, 6);
    assert!(free.acceleration_mismatch < 1e-8, "{free:?}");
    assert!(free.output_change < 1e-10, "{free:?}");
    let platform = Exact.info().body_index("platform").unwrap();
    assert!(!free.moved_bodies.contains(&platform));

    // HHT converges to the kinematic path at second order. Measured: 4.0e-9 N at h = 2e-4 s,
    // 9.8e-10 N at 1e-4 s (ratio 4.1); the platform pose agrees to 8.9e-14.
    let kinematic = scenario::kinematic(
        &symbody_benchmark_mechanisms::REGISTRY,
        &options(Formulation::Exact, 0.0),
    )
    .unwrap();
    let coarse = scenario::simulate(
        &symbody_benchmark_mechanisms::REGISTRY,
        &options(Formulation::Exact, 2e-4),
    )
    .unwrap();
    let fine = scenario::simulate(
        &symbody_benchmark_mechanisms::REGISTRY,
        &options(Formulation::Exact, 1e-4),
    )
    .unwrap();
    let (e2, e1) = (
        force_difference(&coarse, &kinematic),
        force_difference(&fine, &kinematic),
    );
    assert!(e1 < 1.5e-9, "h = 1e-4: {e1:e} N");
    assert!((3.0..5.0).contains(&(e2 / e1)), "{e2:e} / {e1:e}");
    let pose = fine
        .max_difference(&kinematic, |r, k| &r.platform[k])
        .unwrap()
        .0;
    assert!(pose < 1e-12, "{pose:e}");

    // The integrated legs do not spin: ω · (leg axis) goes to zero with the step in the HHT
    // runs (measured 2.9e-5 and 1.4e-5 rad/s: first order, HHT's velocity error in a
    // direction nothing constrains), and is zero on the kinematic path (4e-13 rad/s), while
    // the legs swing at up to 0.3 rad/s.
    let spin = |run: &Run| {
        let info = Exact.info();
        let (mut spin, mut swing) = (0.0f64, 0.0f64);
        for (q, qd) in run.q.iter().zip(&run.qd) {
            for b in info.bodies.iter().filter(|b| b.name != "platform") {
                let w = angular_velocity(b, q, qd).unwrap();
                let axis = rotation_matrix(b, q).unwrap().column(1).into_owned();
                spin = spin.max(w.dot(&axis).abs());
                swing = swing.max(w.norm());
            }
        }
        (spin, swing)
    };
    let (s0, swing) = spin(&kinematic);
    let (s2, s1) = (spin(&coarse).0, spin(&fine).0);
    assert!(s0 < 1e-11 && swing > 0.1, "spin {s0:e}, swing {swing}");
    assert!(
        s1 < 3e-5 && (1.7..2.3).contains(&(s2 / s1)),
        "{s2:e} {s1:e}"
    );
}

#[test]
fn the_paper_formulation_drives_the_spins_so_it_must_be_integrated() {
    // The diagonal Euler-rate mass matrix couples the spins to the swing: the check sees
    // momentum (measured mismatch 1.8e-2) ...
    let mut outputs = upper_forces(&Paper);
    let free = free_motion(&Paper, 0.0, Paper.info().q0, &mut *outputs).unwrap();
    assert!(
        free.acceleration_mismatch > 1e3 * MAX_ACCELERATION_MISMATCH,
        "{free:?}"
    );
    assert!(!free.kinematic_is_exact(&[]));
    // ... and rightly: followed kinematically anyway, its forces leave the integrated ones.
    let kinematic = scenario::kinematic(
        &symbody_benchmark_mechanisms::REGISTRY,
        &options(Formulation::Paper, 0.0),
    )
    .unwrap();
    let integrated = scenario::simulate(
        &symbody_benchmark_mechanisms::REGISTRY,
        &options(Formulation::Paper, 1e-4),
    )
    .unwrap();
    let d = force_difference(&kinematic, &integrated);
    assert!(d > 1e-4, "{d:e} N");
}

/// The energy balance of a kinematic run (`symbody run` on a scene solved without
/// integration, `generic::run_kinematic`) must be as tight as the integrated run's, which
/// sums the power at every 1 ms step: the kinematic path's work of the drivers, taken from
/// the outputs alone (every 10 ms), left |ΔT + ΔV − W| at 1.8e-6 of the energy scale on the
/// four-bar against 1.5e-10 integrated. Reference: `generic::run` (HHT, the CLI's defaults)
/// on the same mechanism and span, an independent integration of the same equations; both
/// balances relative to the energy scale.
#[test]
fn a_kinematic_run_balances_its_energy_as_tightly_as_an_integrated_one() {
    use symbody::generic::{run, run_kinematic, Options};
    for name in ["four_bar", "slider_crank"] {
        let entry = symbody_benchmark_mechanisms::find(name).unwrap();
        let opts = Options {
            t_end: Some(2.0),
            output_step: 0.01,
            ..Options::default()
        };
        let relative = |rec: &symbody::generic::Recording| {
            let (drift, scale) = rec.energy_balance().expect("the work is integrated");
            assert!(scale > 0.1, "{name}: energy scale {scale}");
            drift / scale
        };
        let kinematic = run_kinematic(entry, &opts).unwrap();
        let integrated = run(entry, &opts).unwrap();
        let (k, i) = (relative(&kinematic), relative(&integrated));
        // Over whole turns the work returns to zero; in between it does not.
        let work = kinematic
            .energy
            .iter()
            .map(|e| e.work.abs())
            .fold(0.0, f64::max);
        eprintln!(
            "{name}: |ΔT + ΔV − W| / scale: kinematic {k:e}, integrated {i:e}; max |W| = {work} J"
        );
        assert!(work > 0.01, "{name}: the drivers must do work: {work}");
        assert!(
            k <= (10.0 * i).max(1e-9),
            "{name}: kinematic {k:e} vs integrated {i:e}"
        );
        assert_eq!(kinematic.t.len(), 201, "{name}: outputs only");
        assert_eq!(kinematic.kinematic.unwrap().outputs, 201, "{name}");
    }
}

/// `Options::states` off leaves out only the states: the same times, poses, forces and
/// energies, bit for bit, as the run that keeps them (one state per output there).
#[test]
fn a_run_without_its_states_records_the_same_tables() {
    let registry = &symbody_benchmark_mechanisms::REGISTRY;
    let with = Options {
        t_end: 0.5,
        ..Options::default()
    };
    let kept = scenario::kinematic(registry, &with).unwrap();
    let left = scenario::kinematic(
        registry,
        &Options {
            states: false,
            ..with
        },
    )
    .unwrap();
    assert_eq!((kept.q.len(), kept.qd.len()), (kept.t.len(), kept.t.len()));
    assert!(left.q.is_empty() && left.qd.is_empty());
    assert_eq!(left.t, kept.t);
    assert_eq!(left.platform, kept.platform);
    assert_eq!(left.upper, kept.upper);
    assert_eq!(left.lower, kept.lower);
    assert_eq!(left.actuators, kept.actuators);
    assert_eq!(left.energy, kept.energy);
    assert_eq!(left.actuator_power, kept.actuator_power);
}
