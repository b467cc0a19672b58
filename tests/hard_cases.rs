//! Stewart failure modes that must end in a typed error naming time, body, joint or row,
//! never in a panic or a silently wrong answer: NaN or infinity in a state or a force, a
//! driver that demands an unreachable pose, a leg driven to zero length. The faults are
//! injected by wrapping the generated paper platform, so the rest of the model is the real one.

use symbody_benchmark_mechanisms::stewart_6_6::Exact;
use symbody_runtime::{
    Error, HhtBuilder, KinematicOutputs, KinematicPath, Mechanism, MechanismInfo, NewtonOutputs,
};

/// The paper platform with a fault: `force_nan_from` makes Q NaN from that time on;
/// `extend` adds `extend(t)` to the length leg `leg`'s driver asks for.
struct Faulty {
    force_nan_from: f64,
    leg: usize,
    extend: fn(f64) -> (f64, f64),
}

impl Faulty {
    fn row(&self) -> usize {
        let info = Exact.info();
        info.joints[info.joint_index(&format!("act{}", self.leg)).unwrap()].row_start
    }
    fn poison(&self, t: f64, out: &mut [f64]) {
        if t >= self.force_nan_from {
            out[7] = f64::NAN;
        }
    }
}

/// No fault: the paper's drivers.
fn none(_: f64) -> (f64, f64) {
    (0.0, 0.0)
}

impl Mechanism for Faulty {
    fn info(&self) -> &'static MechanismInfo {
        Exact.info()
    }
    fn phi(&self, q: &[f64], t: f64, out: &mut [f64]) {
        Exact.phi(q, t, out);
        // Φ_D = d(q) − c(t): a longer prescribed length lowers the row.
        out[self.row()] -= (self.extend)(t).0;
    }
    fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) {
        Exact.phi_q(q, t, out)
    }
    fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) {
        Exact.phi_t(q, t, out);
        out[self.row()] -= (self.extend)(t).1;
    }
    fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        // The extensions used here are linear in t: Φtt gains nothing.
        Exact.gamma(q, qd, t, out)
    }
    fn mass(&self, q: &[f64], out: &mut [f64]) {
        Exact.mass(q, out)
    }
    fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        Exact.force(q, qd, t, out);
        self.poison(t, out);
    }
    fn potential(&self, q: &[f64]) -> f64 {
        Exact.potential(q)
    }
    fn power_nc(&self, q: &[f64], qd: &[f64], t: f64) -> f64 {
        Exact.power_nc(q, qd, t)
    }
    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        let NewtonOutputs {
            phi,
            phi_q,
            mass,
            force,
        } = out;
        self.phi(q, t, phi);
        self.phi_q(q, t, phi_q);
        self.mass(q, mass);
        self.force(q, qd, t, force);
    }
    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
        let KinematicOutputs {
            phi,
            phi_q,
            phi_t,
            gamma,
        } = out;
        self.phi(q, t, phi);
        self.phi_q(q, t, phi_q);
        self.phi_t(q, t, phi_t);
        self.gamma(q, qd, t, gamma);
    }
}

#[test]
fn nan_or_infinity_in_the_initial_state_is_refused_at_t0() {
    let info = Exact.info();
    let mut q = info.q0.to_vec();
    q[1] = f64::NAN;
    for err in [
        HhtBuilder::new().q0(&q).build(Exact).err().unwrap(),
        KinematicPath::<_>::from_position(Exact, 0.0, &q, Default::default())
            .err()
            .unwrap(),
    ] {
        assert!(
            matches!(err, Error::NotFinite { time, .. } if time == 0.0),
            "{err}"
        );
    }
    let mut qd = info.qd0.to_vec();
    qd[0] = f64::INFINITY;
    let err = HhtBuilder::new()
        .qd0(&qd)
        .project_velocities(true)
        .build(Exact)
        .err();
    // A given velocity is projected onto the constraints: an infinite one cannot be.
    assert!(
        matches!(err, Some(Error::NotFinite { time, .. }) if time == 0.0),
        "{err:?}"
    );
}

#[test]
fn a_force_turning_nan_mid_run_stops_the_run_at_that_time() {
    let mech = Faulty {
        force_nan_from: 0.5,
        leg: 1,
        extend: none,
    };
    let mut it = HhtBuilder::new().step(1e-3).build(&mech).unwrap();
    let err = it.advance_to(1.0).unwrap_err();
    let time = match &err {
        Error::NotFinite { time, .. } | Error::StepSizeTooSmall { time, .. } => *time,
        other => panic!("{other}"),
    };
    assert!((0.499..=0.5).contains(&time), "{err}");
    assert!(it.t() < 0.5 && it.q().iter().all(|x| x.is_finite()));

    let mut path = KinematicPath::<_>::new(&mech, 0.0).unwrap();
    path.advance_to(0.4).unwrap();
    let err = path.advance_to(0.5).unwrap_err();
    assert!(
        matches!(err, Error::NotFinite { time, .. } if time == 0.5),
        "{err}"
    );
    // The failed output leaves the last good state.
    assert_eq!(path.t(), 0.4);
}

/// Leg 3 lengthened by 0.5 m/s: the other five legs cannot follow beyond a fold of the
/// workspace.
fn overextend(t: f64) -> (f64, f64) {
    (0.5 * t, 0.5)
}

#[test]
fn a_driver_demanding_an_unreachable_pose_is_named() {
    let mech = Faulty {
        force_nan_from: f64::INFINITY,
        leg: 3,
        extend: overextend,
    };
    let mut path = KinematicPath::<_>::new(&mech, 0.0).unwrap();
    let mut err = None;
    for k in 1..=200 {
        if let Err(e) = path.advance_to(k as f64 * 0.01) {
            err = Some(e);
            break;
        }
    }
    // Measured: "position analysis: Newton iteration failed at t = 0.210000 s after 30
    // iterations, constraint residual |Φ|∞ = 1.9e-4, largest in row 4 `upper_sph2.y`".
    let err = err.expect("the pose must become unreachable");
    match &err {
        Error::NewtonFailed { time, row, .. } => {
            assert!(*time > 0.1 && *time < 0.5, "{err}");
            let row = row.as_ref().expect("the failing row is named");
            assert!(!row.joint.is_empty(), "{err}");
        }
        other => panic!("{other}"),
    }
}

#[test]
fn a_zero_or_negative_leg_length_is_refused_not_tracked() {
    // Before the check, `fk --lengths 0,…` tracked the pose into a parallel singularity at
    // path parameter 0.28 and reported that instead of the impossible input.
    let entry = symbody_benchmark_mechanisms::find("stewart_6_6").unwrap();
    let p = symbody::fk::platform(entry).unwrap();
    for bad in [0.0, -0.1, f64::NAN] {
        let mut lengths = [0.40004; 6];
        lengths[1] = bad;
        let req = symbody::fk::Request {
            lengths: Some(lengths),
            from: None,
            at: 0.0,
        };
        let err = symbody::fk::solve(&p, &req).unwrap_err().to_string();
        assert!(
            err.contains("leg length") && err.contains("positive"),
            "{err}"
        );
        let err = symbody::fk::all_modes(&p, &lengths, None)
            .unwrap_err()
            .to_string();
        assert!(err.contains("leg length"), "{err}");
    }
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_symbody"))
        .args(["fk", "stewart_6_6", "--lengths", "0.4,0,0.4,0.4,0.4,0.4"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        !out.status.success() && stderr.contains("leg 2 is 0 m long"),
        "{stderr}"
    );
}

/// Why α = 0 needs velocity projection (issue "Hard cases"): trapezoidal HHT on index-3
/// constraints keeps Φ = 0 but has no damping on the velocity constraints Φq q̇ + Φt = 0, and
/// on the quaternion pendulum their residual grows exponentially (measured 3.6e-6 at 1 s,
/// 1.8e-3 at 4 s, 0.27 at 6 s) until the energy is off by 3.8e3 J and the step fails at
/// t ≈ 8.5 s. Projecting the velocities after each step (what `simulate <name>` does with its
/// α = 0 default) keeps the energy to 2.7e-8 J over 60 s.
#[test]
fn alpha_zero_drifts_off_the_velocity_constraints_unless_projected() {
    let mech = symbody_benchmark_mechanisms::find("spherical_pendulum")
        .unwrap()
        .default_mechanism();
    let info = mech.info();
    let mut watch = symbody_runtime::ResidualWatch::new(info);
    let mut it = HhtBuilder::new()
        .alpha(0.0)
        .qd0(info.qd0)
        .build(mech)
        .unwrap();
    let mut residual = |it: &mut symbody_runtime::Integrator<_>, t: f64| {
        it.advance_to(t).unwrap();
        watch
            .check(&mech, it.t(), it.q(), it.qd())
            .unwrap()
            .velocity
    };
    let (r1, r4) = (residual(&mut it, 1.0), residual(&mut it, 4.0));
    assert!(r1 < 1e-5 && r4 > 1e2 * r1, "{r1:e} → {r4:e}");
    let failed = (1..=600).any(|k| it.advance_to(4.0 + k as f64 * 0.1).is_err());
    assert!(failed, "unprojected α = 0 ran to t = {}", it.t());

    let mut it = HhtBuilder::new()
        .alpha(0.0)
        .qd0(info.qd0)
        .project_velocities(true)
        .build(mech)
        .unwrap();
    let e0 = it.energy();
    it.advance_to(60.0).unwrap();
    assert!((it.energy() - e0).abs() < 1e-6, "{:e}", it.energy() - e0);
}
