//! HHT-α against analytic results (pendulum period, static reaction, prescribed motion),
//! an independent RK4 reference (convergence order), and its own error paths.

use super::*;
use crate::energy::EnergyMeter;
use crate::kkt::DenseKkt;
use crate::testmodels::{
    CircleDriver, Pendulum, QuaternionPendulum, TwoBallHinge, CIRCLE_C0, CIRCLE_D, CIRCLE_V, G,
    PENDULUM_INERTIA, PENDULUM_LENGTH, PENDULUM_MASS,
};

/// Pendulum swung by `phi` about Z in the X–Y plane, at rest (exactly consistent).
fn planar_q0(phi: f64) -> [f64; 6] {
    let l = PENDULUM_LENGTH;
    [l * phi.sin(), -l * phi.cos(), 0.0, 0.0, 0.0, phi]
}

/// (I_zz + m L²) φ̈ = −m g L sin φ: the planar pendulum reduced to one coordinate, integrated
/// by classical RK4 with a step far below HHT's — an independent reference.
fn rk4_planar(phi0: f64, t_end: f64) -> f64 {
    let ip = PENDULUM_INERTIA[2] + PENDULUM_MASS * PENDULUM_LENGTH * PENDULUM_LENGTH;
    let k = PENDULUM_MASS * G * PENDULUM_LENGTH / ip;
    let f = |x: [f64; 2]| [x[1], -k * x[0].sin()];
    let n = 200_000;
    let h = t_end / n as f64;
    let mut x = [phi0, 0.0];
    for _ in 0..n {
        let k1 = f(x);
        let k2 = f([x[0] + 0.5 * h * k1[0], x[1] + 0.5 * h * k1[1]]);
        let k3 = f([x[0] + 0.5 * h * k2[0], x[1] + 0.5 * h * k2[1]]);
        let k4 = f([x[0] + h * k3[0], x[1] + h * k3[1]]);
        for i in 0..2 {
            x[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
    }
    x[0]
}

#[test]
fn small_amplitude_period_matches_the_compound_pendulum() {
    let ip = PENDULUM_INERTIA[2] + PENDULUM_MASS * PENDULUM_LENGTH * PENDULUM_LENGTH;
    let phi0 = 0.01;
    // T = 2π √(I_p / m g L), with the finite-amplitude factor 1 + φ0²/16.
    let period = 2.0
        * std::f64::consts::PI
        * (ip / (PENDULUM_MASS * G * PENDULUM_LENGTH)).sqrt()
        * (1.0 + phi0 * phi0 / 16.0);
    for mech in [Pendulum::paper(), Pendulum::exact()] {
        let mut hht = HhtBuilder::new()
            .step(1e-3)
            .q0(&planar_q0(phi0))
            .build(mech)
            .unwrap();
        // Upward zero crossings of X (γ), interpolated linearly between outputs.
        let mut crossings = Vec::new();
        let (mut t_prev, mut x_prev) = (hht.t(), hht.q()[0]);
        let dt = 1e-3;
        for k in 1..=(3.5 * period / dt) as usize {
            hht.advance_to(k as f64 * dt).unwrap();
            let x = hht.q()[0];
            if x_prev < 0.0 && x >= 0.0 {
                crossings.push(t_prev + (hht.t() - t_prev) * (-x_prev) / (x - x_prev));
            }
            (t_prev, x_prev) = (hht.t(), x);
        }
        assert!(crossings.len() >= 3, "{crossings:?}");
        let measured =
            (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
        assert!(
            (measured - period).abs() < 1e-5 * period,
            "{:?}: period {measured} vs {period}",
            mech.formulation
        );
    }
}

#[test]
fn positions_converge_at_second_order() {
    let phi0 = 0.8;
    let t_end = 1.0;
    let reference = rk4_planar(phi0, t_end);
    for alpha in [0.0, -0.05, -0.3] {
        let errs: Vec<f64> = [0.02, 0.01, 0.005]
            .iter()
            .map(|&h| {
                let mut hht = HhtBuilder::new()
                    .alpha(alpha)
                    .step(h)
                    .rel_tol(1e-10)
                    .abs_tol_acceleration(1e-10)
                    .abs_tol_lambda(1e-10)
                    .max_iterations(20)
                    .q0(&planar_q0(phi0))
                    .build(Pendulum::paper())
                    .unwrap();
                hht.advance_to(t_end).unwrap();
                assert_eq!(hht.t(), t_end);
                (hht.q()[5] - reference).abs()
            })
            .collect();
        for w in errs.windows(2) {
            let ratio = w[0] / w[1];
            assert!((3.4..4.6).contains(&ratio), "α = {alpha}: errors {errs:?}");
        }
    }
}

#[test]
fn trapezoidal_hht_keeps_energy_of_the_paper_formulation() {
    // Paper formulation: constant M, gravity, scleronomic joint ⇒ ½q̇ᵀMq̇ + V is a
    // constant of the motion. With α = 0 the drift is bounded and O(h²). (The paper's
    // pseudo-inertia lets β run off towards 90° after ~1 s of this swing, so stop at 0.8 s.)
    let q0 = [0.0, 0.0, 0.0, 0.5, 0.1, -0.4];
    let qd0 = [0.0, 0.0, 0.0, 0.0, 0.5, 0.0];
    let drift = |mech: Pendulum, h: f64| {
        let mut hht = HhtBuilder::new()
            .alpha(0.0)
            .step(h)
            .q0(&q0)
            .qd0(&qd0)
            .build(mech)
            .unwrap();
        let e0 = hht.energy();
        let scale = PENDULUM_MASS * G * PENDULUM_LENGTH;
        let mut worst = 0.0f64;
        let mut beta_max = 0.0f64;
        for k in 1..=80 {
            hht.advance_to(k as f64 * 0.01).unwrap();
            worst = worst.max((hht.energy() - e0).abs());
            beta_max = beta_max.max(hht.q()[4].abs());
        }
        eprintln!(
            "{:?} h={h}: drift {} beta_max {beta_max} {:?}",
            mech.formulation,
            worst / scale,
            hht.stats()
        );
        worst / scale
    };
    for mech in [Pendulum::paper(), Pendulum::exact()] {
        let (d1, d2) = (drift(mech, 2e-3), drift(mech, 1e-3));
        assert!(
            d2 < 1e-6,
            "{:?}: relative energy drift {d2}",
            mech.formulation
        );
        assert!(
            d1 / d2 > 3.0,
            "{:?}: drift not O(h²): {d1} {d2}",
            mech.formulation
        );
    }
}

#[test]
fn hanging_pendulum_stays_put_and_carries_its_weight() {
    let mut hht = HhtBuilder::new().build(Pendulum::exact()).unwrap();
    for _ in 0..100 {
        hht.step().unwrap();
    }
    let f = hht.joint_force(0, 0).unwrap();
    let w = PENDULUM_MASS * G;
    assert!(
        (f[1] - w).abs() < 1e-9 * w && f[0].abs() < 1e-9 && f[2].abs() < 1e-9,
        "{f:?}"
    );
    assert!(hht
        .q()
        .iter()
        .zip(Pendulum::exact().info().q0)
        .all(|(a, b)| (a - b).abs() < 1e-12));
    let s = hht.stats();
    assert_eq!(s.steps, 100);
    assert_eq!(s.rejected_steps, 0);
}

#[test]
fn prescribed_motion_follows_the_driver_then_fails_with_an_error() {
    // Y(t) = √(c(t)² − d²) until c reaches d at t = 2, where Φq loses rank and Ẏ → ∞.
    let mut hht = HhtBuilder::new().step(1e-3).build(CircleDriver).unwrap();
    hht.advance_to(1.0).unwrap();
    let c = CIRCLE_C0 - CIRCLE_V;
    let y = (c * c - CIRCLE_D * CIRCLE_D).sqrt();
    assert!((hht.q()[1] - y).abs() < 1e-10, "{} vs {y}", hht.q()[1]);
    assert!((hht.qd()[1] - c * -CIRCLE_V / y).abs() < 1e-6);
    let err = hht.advance_to(2.5).unwrap_err();
    let t_fail = match &err {
        Error::StepSizeTooSmall { time, .. } => *time,
        Error::SingularJacobian { time, rows } => {
            assert!(!rows.is_empty());
            *time
        }
        Error::NewtonFailed { time, .. } => *time,
        other => panic!("unexpected error {other:?}"),
    };
    assert!(t_fail > 1.9 && t_fail <= 2.0, "{err}");
    assert_eq!(hht.t(), t_fail, "state must stay at the last accepted step");
    assert!(hht.t() <= 2.0);
    // Whatever was accepted satisfies the constraints.
    let mut phi = [0.0; 6];
    hht.mechanism().phi(hht.q(), hht.t(), &mut phi);
    assert!(inf_norm(&phi) <= 1e-10);
    assert!(err.to_string().contains("t = "));
}

#[test]
fn output_times_are_hit_exactly() {
    let mut hht = HhtBuilder::new()
        .step(0.003)
        .q0(&planar_q0(0.3))
        .build(Pendulum::paper())
        .unwrap();
    for k in 1..=50 {
        let t = k as f64 * 0.01;
        hht.advance_to(t).unwrap();
        assert_eq!(hht.t(), t);
    }
    let s = hht.stats();
    // 0.01 = 3 steps of 0.003 + a remainder of 0.001; evened to 2×0.003 + 2×0.002.
    assert_eq!(s.steps, 200);
    assert!(s.newton_iterations <= 3 * s.steps, "{s:?}");
    assert_eq!(s.rejected_steps, 0, "{s:?}");
    assert_eq!(s.factorizations, s.steps, "{s:?}");
}

#[test]
fn output_times_closer_than_the_minimum_step_are_refused() {
    // A 1 ns step would accept accelerations judged against roundoff / (βh²): refuse it.
    let mut hht = HhtBuilder::new()
        .q0(&planar_q0(0.3))
        .build(Pendulum::exact())
        .unwrap();
    hht.advance_to(0.1).unwrap();
    let q = hht.q().to_vec();
    match hht.advance_to(0.1 + 1e-9) {
        Err(Error::InvalidSetting { name: "t_out", .. }) => {}
        other => panic!("expected a refused output time, got {other:?}"),
    }
    assert_eq!(hht.q(), &q[..], "a refused request leaves the state alone");
    hht.advance_to(0.2).unwrap();
}

#[test]
fn statistics_and_factorization_reuse() {
    let run = |reuse: bool| {
        let mut hht = HhtBuilder::new()
            .reuse_factorization(reuse)
            .q0(&planar_q0(0.5))
            .build(Pendulum::exact())
            .unwrap();
        hht.advance_to(1.0).unwrap();
        (hht.stats(), hht.q().to_vec())
    };
    let (a, qa) = run(false);
    let (b, qb) = run(true);
    assert_eq!(a.steps, 1000);
    assert_eq!(a.rejected_steps, 0);
    assert_eq!(a.factorizations, 1000);
    assert!(a.newton_iterations <= 2 * a.steps, "{a:?}");
    assert_eq!(a.evaluations, a.newton_iterations + a.steps + 1);
    assert!(b.factorizations < a.factorizations / 10, "{b:?}");
    // Both converge to the same steps within the Newton tolerances (rel 1e-6 on q̈, so
    // ~1e-6·h²·|q̈| per step, accumulated over 1000 steps).
    for (x, y) in qa.iter().zip(&qb) {
        assert!((x - y).abs() < 1e-7, "{x} vs {y}");
    }
}

#[test]
fn the_rate_test_saves_newton_iterations_within_the_tolerance() {
    // The reference is the same step equations solved far below the default tolerances
    // without the rate test: the limit both default runs approximate.
    let run = |rate: bool, tol: f64| {
        let mut hht = HhtBuilder::new()
            .rate_test(rate)
            .rel_tol(tol)
            .abs_tol_acceleration(tol)
            .abs_tol_lambda(tol)
            .q0(&planar_q0(1.2))
            .build(Pendulum::exact())
            .unwrap();
        hht.advance_to(1.0).unwrap();
        (hht.stats(), hht.q().to_vec())
    };
    let (_, exact) = run(false, 1e-11);
    let off_by = |q: &[f64]| -> f64 {
        q.iter()
            .zip(&exact)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max)
    };
    let (on, q_on) = run(true, 1e-6);
    let (off, q_off) = run(false, 1e-6);
    // Without the test a step ends only after an increment within the tolerance: a second
    // one in nearly every step to show the first was enough (measured: 1 960 increments in
    // 1 000 steps; the first guess is that close in the other 40).
    assert!(10 * off.newton_iterations >= 19 * off.steps, "{off:?}");
    // With it, one increment per step, and a second in every eleventh (after `RATE_AGE_MAX`
    // steps on a borrowed rate) to measure the rate again.
    assert!(10 * on.newton_iterations <= 12 * on.steps, "{on:?}");
    assert_eq!(on.evaluations, on.newton_iterations + on.steps + 1);
    // An accepted q̈ may be off by the tolerance, rel 1e-6 of |q̈| ≲ 20 rad/s², which moves
    // q by βh² times that per step (β = 0.276 at α = −0.05): over 1000 steps at most
    // 5.5e-9. The second increment of the runs without the test converges to roundoff.
    assert!(off_by(&q_off) < 1e-13, "{}", off_by(&q_off));
    assert!(off_by(&q_on) < 5.5e-9, "{}", off_by(&q_on));
}

#[test]
fn dense_and_structured_solvers_give_the_same_trajectory() {
    let q0 = [0.0, 0.0, 0.0, 0.6, 0.4, -0.5];
    let mut a = HhtBuilder::new().q0(&q0).build(Pendulum::exact()).unwrap();
    let mut b = HhtBuilder::new()
        .q0(&q0)
        .build_with_solver::<_, DenseKkt>(Pendulum::exact())
        .unwrap();
    a.advance_to(0.5).unwrap();
    b.advance_to(0.5).unwrap();
    for (x, y) in a.q().iter().zip(b.q()) {
        assert!((x - y).abs() < 1e-10);
    }
    // λ agrees to well inside its Newton tolerance (1e-6 relative).
    for (x, y) in a.lambda().iter().zip(b.lambda()) {
        assert!((x - y).abs() < 1e-7 * x.abs().max(1.0), "{x} vs {y}");
    }
}

#[test]
fn spinning_into_the_euler_singularity_is_reported_by_body() {
    // Hanging at rest but spinning about the vertical arm: β grows at 2 rad/s and reaches
    // the error threshold (|β| = acos 0.035 ≈ 88°) at t ≈ 0.768 s, where the exact
    // formulation's mass matrix (through the Euler-rate map) is about to become singular.
    let mut hht = HhtBuilder::new()
        .qd0(&[0.0, 0.0, 0.0, 0.0, 2.0, 0.0])
        .build(Pendulum::exact())
        .unwrap();
    let err = hht.advance_to(2.0).unwrap_err();
    let t_limit = 0.035f64.acos() / 2.0;
    match err {
        Error::EulerSingularity { time, body, beta } => {
            assert_eq!(body, "bob");
            assert!((time - t_limit).abs() < 2e-3, "{time} vs {t_limit}");
            assert!(beta.cos() < 0.035);
        }
        other => panic!("{other:?}"),
    }
    let w = hht.first_euler_warning().expect("warned before failing");
    assert!((w.time - 0.17f64.acos() / 2.0).abs() < 2e-3);
    assert!(hht.q()[4].cos() >= 0.035);
}

#[test]
fn a_constant_mass_matrix_spins_through_the_euler_singularity_with_a_warning() {
    // The same spin with the paper's constant diagonal mass matrix: the saddle-point system
    // stays regular at β = 90°, so the run goes on, warns, and β keeps growing at 2 rad/s.
    let mut hht = HhtBuilder::new()
        .qd0(&[0.0, 0.0, 0.0, 0.0, 2.0, 0.0])
        .build(Pendulum::paper())
        .unwrap();
    hht.advance_to(1.5).unwrap();
    let w = hht.first_euler_warning().expect("warned at 80°");
    assert!((w.time - 0.17f64.acos() / 2.0).abs() < 2e-3);
    assert!((hht.q()[4] - 3.0).abs() < 1e-6, "β = {}", hht.q()[4]);
}

#[test]
fn bad_settings_are_rejected() {
    let b = || HhtBuilder::new();
    assert!(b().alpha(0.1).build(Pendulum::paper()).is_err());
    assert!(b().alpha(-0.4).build(Pendulum::paper()).is_err());
    assert!(b().step(-1.0).build(Pendulum::paper()).is_err());
    assert!(b().step(f64::NAN).build(Pendulum::paper()).is_err());
    assert!(b().min_step(1.0).build(Pendulum::paper()).is_err());
    assert!(b().q0(&[0.0; 3]).build(Pendulum::paper()).is_err());
    assert!(b()
        .rel_tol(0.0)
        .abs_tol_lambda(0.0)
        .build(Pendulum::paper())
        .is_err());
    let mut hht = b().build(Pendulum::paper()).unwrap();
    hht.advance_to(0.01).unwrap();
    assert!(hht.advance_to(0.0).is_err());
    assert!(hht.advance_to(f64::INFINITY).is_err());
    // Starting from an impossible position is a kinematic failure, not a panic.
    assert!(HhtBuilder::new().t0(3.0).build(CircleDriver).is_err());
}

#[test]
fn given_initial_velocities_are_projected_in_the_kinetic_energy_norm() {
    // The hinge at rest, hanging: the only admissible velocity is the swing about Z,
    // v₁ = (L, 0, 0, 0, 0, 1) per unit γ̇, and M = diag(m, m, m, I) there. The projection of
    // a given q̇* is v₁ (v₁ᵀ M q̇*) / (v₁ᵀ M v₁).
    let given = [0.3, -0.2, 0.5, 1.3, -0.8, 0.6];
    let (m, i, l) = (PENDULUM_MASS, PENDULUM_INERTIA, PENDULUM_LENGTH);
    let s = (m * l * given[0] + i[2] * given[5]) / (m * l * l + i[2]);
    let expect = [l * s, 0.0, 0.0, 0.0, 0.0, s];
    let hht = HhtBuilder::new()
        .qd0(&given)
        .build(TwoBallHinge::new(0.0))
        .unwrap();
    for (a, b) in hht.qd().iter().zip(&expect) {
        assert!((a - b).abs() < 1e-12, "{:?} vs {expect:?}", hht.qd());
    }
    // Without qd0 the mechanism's own (zero) qd0 is projected: at rest.
    let hht = HhtBuilder::new().build(TwoBallHinge::new(0.0)).unwrap();
    assert!(hht.qd().iter().all(|v| v.abs() < 1e-14), "{:?}", hht.qd());
}

#[test]
fn a_hinge_with_a_redundant_row_swings_like_the_compound_pendulum() {
    // Two ball joints on the Z axis make a hinge: six rows of rank five. The redundant
    // row is dropped (λ = 0), Newton converges as for the pendulum, every row holds, and
    // the period is the compound pendulum's about Z.
    let phi0 = 0.01;
    let ip = PENDULUM_INERTIA[2] + PENDULUM_MASS * PENDULUM_LENGTH * PENDULUM_LENGTH;
    let period = 2.0
        * std::f64::consts::PI
        * (ip / (PENDULUM_MASS * G * PENDULUM_LENGTH)).sqrt()
        * (1.0 + phi0 * phi0 / 16.0);
    let mech = TwoBallHinge::new(0.0);
    let mut a = HhtBuilder::new().q0(&planar_q0(phi0)).build(mech).unwrap();
    let mut b = HhtBuilder::new()
        .q0(&planar_q0(phi0))
        .build_with_solver::<_, DenseKkt>(mech)
        .unwrap();
    let mut crossings = Vec::new();
    let (mut t_prev, mut x_prev) = (a.t(), a.q()[0]);
    let mut phi = [0.0; 6];
    for k in 1..=(2.5 * period / 1e-3) as usize {
        a.advance_to(k as f64 * 1e-3).unwrap();
        let x = a.q()[0];
        if x_prev < 0.0 && x >= 0.0 {
            crossings.push(t_prev + (a.t() - t_prev) * (-x_prev) / (x - x_prev));
        }
        (t_prev, x_prev) = (a.t(), x);
        assert_eq!(a.lambda()[5], 0.0);
        mech.phi(a.q(), a.t(), &mut phi);
        assert!(inf_norm(&phi) <= 1e-10, "{phi:?}");
    }
    let measured = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
    assert!(
        (measured - period).abs() < 1e-5 * period,
        "period {measured} vs {period}"
    );
    let s = a.stats();
    assert_eq!(s.rejected_steps, 0, "{s:?}");
    assert!(s.newton_iterations <= 3 * s.steps, "{s:?}");
    // The dense reference agrees.
    b.advance_to(a.t()).unwrap();
    for (x, y) in a.q().iter().zip(b.q()) {
        assert!((x - y).abs() < 1e-10, "{x} vs {y}");
    }
    // And a misaligned hinge does not start: its redundant row contradicts the others.
    match HhtBuilder::new().build(TwoBallHinge::new(0.01)) {
        Err(Error::InconsistentConstraints { rows, .. }) => assert_eq!(rows[0].row, 5),
        other => panic!("expected an inconsistency, got {:?}", other.map(|_| ())),
    }
}

/// The quaternion pendulum swung by `phi` about Z, at rest.
fn planar_quaternion_q0(phi: f64) -> [f64; 7] {
    let l = PENDULUM_LENGTH;
    let (s, c) = (0.5 * phi).sin_cos();
    [l * phi.sin(), -l * phi.cos(), 0.0, c, 0.0, 0.0, s]
}

#[test]
fn quaternion_pendulum_has_the_compound_pendulum_period() {
    let ip = PENDULUM_INERTIA[2] + PENDULUM_MASS * PENDULUM_LENGTH * PENDULUM_LENGTH;
    let phi0 = 0.01;
    let period = 2.0
        * std::f64::consts::PI
        * (ip / (PENDULUM_MASS * G * PENDULUM_LENGTH)).sqrt()
        * (1.0 + phi0 * phi0 / 16.0);
    let mut hht = HhtBuilder::new()
        .q0(&planar_quaternion_q0(phi0))
        .build(QuaternionPendulum)
        .unwrap();
    let mut crossings = Vec::new();
    let (mut t_prev, mut x_prev) = (hht.t(), hht.q()[0]);
    for k in 1..=(2.5 * period / 1e-3) as usize {
        hht.advance_to(k as f64 * 1e-3).unwrap();
        let x = hht.q()[0];
        if x_prev < 0.0 && x >= 0.0 {
            crossings.push(t_prev + (hht.t() - t_prev) * (-x_prev) / (x - x_prev));
        }
        (t_prev, x_prev) = (hht.t(), x);
    }
    let measured = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
    assert!(
        (measured - period).abs() < 1e-5 * period,
        "period {measured} vs {period}"
    );
    assert_eq!(hht.stats().rejected_steps, 0, "{:?}", hht.stats());
}

#[test]
fn a_quaternion_body_spins_through_the_euler_singularity() {
    // The Euler-angle pendulum spinning about its vertical arm fails at β ≈ 88° after
    // 0.77 s (see above); with Euler parameters the same motion runs on for 2 s, with
    // unit |e|, no watchdog warnings, conserved energy, and no moment at the pivot.
    let mech = QuaternionPendulum;
    let info = mech.info();
    // Swung by 0.05 rad about Z, spinning about the arm (the body's local y) at 2 rad/s:
    // ė = ½ G(e)ᵀ ω' with ω' = (0, 2, 0) for e = (c, 0, 0, s) is (0, −s, c, 0).
    let q0 = planar_quaternion_q0(0.05);
    let (c, s) = (q0[3], q0[6]);
    let mut hht = HhtBuilder::new()
        .alpha(0.0)
        .q0(&q0)
        .qd0(&[0.0, 0.0, 0.0, 0.0, -s, c, 0.0])
        .build(mech)
        .unwrap();
    let mut meter = EnergyMeter::<SchurKkt>::new(info).unwrap();
    let first = meter.record(&mech, hht.t(), hht.q(), hht.qd()).unwrap();
    let scale = PENDULUM_MASS * G * PENDULUM_LENGTH;
    let mut worst = 0.0f64;
    // |cos β| of the Rz·Ry·Rx angles the same orientation would have.
    let mut min_cos_beta = 1.0f64;
    for k in 1..=2000 {
        hht.advance_to(k as f64 * 1e-3).unwrap();
        let (q, qd) = (hht.q(), hht.qd());
        let e2: f64 = q[3..7].iter().map(|x| x * x).sum();
        assert!((e2 - 1.0).abs() < 1e-10, "|e|² = {e2}");
        let s = meter.record(&mech, hht.t(), q, qd).unwrap();
        worst = worst.max((s.balance() - first.balance()).abs());
        let w = crate::reactions::joint_wrench(info, q, meter.phi_q(), meter.lambda(), 0).unwrap();
        let f = w.force.iter().map(|x| x * x).sum::<f64>().sqrt();
        let m = w.moment.iter().map(|x| x * x).sum::<f64>().sqrt();
        assert!(
            m < 1e-10 * f * PENDULUM_LENGTH,
            "moment {m} at t = {}",
            hht.t()
        );
        let a = crate::pose::rotation_matrix(&info.bodies[0], q).unwrap();
        min_cos_beta = min_cos_beta.min(a[(0, 0)].hypot(a[(1, 0)]));
    }
    assert!(min_cos_beta < 0.035, "never near β = 90°: {min_cos_beta}");
    assert_eq!(hht.stats().euler_warnings, 0);
    assert!(hht.first_euler_warning().is_none());
    assert!(worst < 1e-6 * scale, "energy drift {}", worst / scale);
}

#[test]
fn a_non_finite_start_is_refused_with_a_typed_error() {
    // Found by the interpreter fuzzer: a NaN in a coordinate or velocity no row holds used
    // to pass the consistent start and come back `Ok` with a NaN state.
    for bad in [f64::NAN, f64::INFINITY] {
        for k in 0..6 {
            let mut q = planar_q0(0.3);
            q[k] = bad;
            let e = HhtBuilder::new()
                .q0(&q)
                .build(Pendulum::paper())
                .err()
                .unwrap();
            assert!(matches!(e, Error::NotFinite { .. }), "{e:?}");
            let mut qd = [0.0; 6];
            qd[k] = bad;
            let e = HhtBuilder::new()
                .q0(&planar_q0(0.3))
                .qd0(&qd)
                .build(Pendulum::paper())
                .err()
                .unwrap();
            assert!(matches!(e, Error::NotFinite { .. }), "{e:?}");
        }
    }
}

/// A controlled run of the planar pendulum swung to `phi0` (large: slow near the turning
/// points, fast at the bottom, so steps should vary) up to `t_end`: (error of φ against
/// RK4, stats).
fn controlled_swing(rtol: f64, alpha: f64, t_end: f64, reference: f64) -> (f64, Stats) {
    let mut hht = HhtBuilder::new()
        .alpha(alpha)
        .tolerances(rtol, rtol)
        .q0(&planar_q0(2.5))
        .build(Pendulum::paper())
        .unwrap();
    hht.advance_to(t_end).unwrap();
    assert_eq!(hht.t(), t_end);
    ((hht.q()[5] - reference).abs(), hht.stats())
}

#[test]
fn step_control_error_follows_the_tolerance_with_fewer_steps_than_a_fixed_step() {
    let t_end = 3.0;
    let reference = rk4_planar(2.5, t_end);
    for alpha in [-0.05, 0.0] {
        let mut last = f64::INFINITY;
        for rtol in [1e-3, 1e-5, 1e-7] {
            let (err, s) = controlled_swing(rtol, alpha, t_end, reference);
            // Measured 2–3× rtol at every tolerance (error per unit step keeps the global
            // error proportional to the tolerance); 10× leaves room, not chance: the run is
            // deterministic.
            assert!(
                err < 10.0 * rtol,
                "α {alpha} rtol {rtol:e}: error {err:e}, {s:?}"
            );
            assert!(
                err < 0.1 * last,
                "α {alpha} rtol {rtol:e}: {err:e} after {last:e}"
            );
            last = err;
            // The steps vary with the motion, and few attempts are wasted.
            assert!(s.largest_step > 5.0 * s.smallest_step, "{s:?}");
            assert!(s.rejected_steps < 20, "{s:?}");
            assert_eq!(s.rejected_steps, s.error_test_failures, "{s:?}");
            // A fixed step taking as many steps is less accurate; the error of a fixed step
            // grows with it (second order), so every fixed step at least as cheap is too.
            let h = t_end / s.steps as f64;
            let mut fixed = HhtBuilder::new()
                .alpha(alpha)
                .step(h)
                .q0(&planar_q0(2.5))
                .build(Pendulum::paper())
                .unwrap();
            fixed.advance_to(t_end).unwrap();
            let fixed_err = (fixed.q()[5] - reference).abs();
            assert!(
                fixed_err > 2.0 * err,
                "α {alpha} rtol {rtol:e}: fixed h {h:e} error {fixed_err:e} vs {err:e}"
            );
        }
    }
}

#[test]
fn step_control_lands_on_output_times_and_keeps_its_step_across_them() {
    let build = || {
        HhtBuilder::new()
            .tolerances(1e-4, 1e-4)
            .q0(&planar_q0(2.5))
            .build(Pendulum::paper())
            .unwrap()
    };
    let mut free = build();
    free.advance_to(2.0).unwrap();
    let mut out = build();
    // Output times that fit no step pattern: every 0.137 s.
    let mut n_out = 0;
    for k in 1.. {
        let t = (k as f64 * 0.137).min(2.0);
        out.advance_to(t).unwrap();
        assert_eq!(out.t(), t);
        n_out += 1;
        if t == 2.0 {
            break;
        }
    }
    // Landing on an output costs at most the one or two steps that even out the
    // remainder; it does not make the steps after it smaller.
    let (a, b) = (free.stats(), out.stats());
    assert!(b.steps <= a.steps + 2 * n_out, "{a:?} vs {b:?}");
    // A sliver of a step to an output close ahead leaves the proposed step as it was.
    let h = out.step_size();
    out.advance_to(2.0 + 1e-3 * h).unwrap();
    assert_eq!(out.t(), 2.0 + 1e-3 * h);
    assert!(out.step_size() >= h, "{} < {h}", out.step_size());
}

#[test]
fn step_control_settings_are_checked_and_an_unmet_tolerance_is_reported() {
    let b = || HhtBuilder::new().q0(&planar_q0(2.5));
    for (rtol, atol) in [
        (0.0, 1e-6),
        (1e-6, -1.0),
        (f64::NAN, 1e-6),
        (1e-6, f64::INFINITY),
    ] {
        match b().tolerances(rtol, atol).build(Pendulum::paper()) {
            Err(Error::InvalidSetting { name, .. }) => assert!(name == "rtol" || name == "atol"),
            other => panic!("({rtol}, {atol}) accepted: {other:?}"),
        }
    }
    assert!(b()
        .step(1e-2)
        .max_step(1e-3)
        .build(Pendulum::paper())
        .is_err());
    // A tolerance the minimum step cannot meet is an error with the time, the step and
    // the coordinate, and the integrator keeps its last accepted state.
    let mut hht = b()
        .tolerances(1e-14, 1e-14)
        .min_step(1e-4)
        .build(Pendulum::paper())
        .unwrap();
    let q = hht.q().to_vec();
    match hht.advance_to(0.1) {
        Err(e @ Error::ToleranceNotMet { .. }) => {
            let Error::ToleranceNotMet {
                time, step, error, ..
            } = e
            else {
                unreachable!()
            };
            assert!(time >= 0.0 && step < 1e-4 && error > 1.0, "{e}");
            assert!(e.to_string().contains("t = "), "{e}");
        }
        other => panic!("expected ToleranceNotMet, got {other:?}"),
    }
    assert!(hht.t() < 0.1);
    if hht.t() == 0.0 {
        assert_eq!(hht.q(), &q[..]);
    }
}
