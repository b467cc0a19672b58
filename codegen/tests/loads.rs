//! Applied loads as generalized forces, checked against independent references at random
//! states: the conservative part of Q is −∇V by central differences of the generated
//! potential; the non-conservative power equals the virtual power of the loads computed by
//! hand (nalgebra: point velocities and angular velocities by finite differences of the
//! body poses), and the generalized forces reproduce that power for any velocity.

use nalgebra::{Matrix3, Vector3};
use symbody_codegen::equations::{build, System};
use symbody_codegen::expr::Var;
use symbody_codegen::model::load;

/// Two Euler bodies (paper formulation: Q is gravity plus the loads, no velocity terms)
/// joined by a revolute joint, with a spring–damper–actuator, a torsion spring–damper in
/// the joint, and an applied force and torque in body axes.
const FILE: &str = r#"name = "loads"
formulations = ["paper"]
rotation = "euler"
gravity = [0.0, -9.81, 0.0]

[[body]]
name = "a"
mass = 2.0
inertia = [0.1, 0.2, 0.3]
position = [0.0, 0.0, 0.0]

[[body]]
name = "b"
mass = 1.0
inertia = [0.05, 0.06, 0.07]
position = [1.0, 0.0, 0.0]
angles = [0.1, 0.2, 0.3]

[[joint]]
name = "hinge"
type = "revolute"
body1 = "a"
body2 = "b"
at = [0.5, 0.0, 0.0]
axis = [0.0, 0.0, 1.0]

[[force]]
name = "spring"
type = "spring"
body1 = "ground"
body2 = "b"
at1 = [0.0, 2.0, 0.0]
at2 = [1.2, 0.1, 0.0]
stiffness = 40.0
damping = DAMPING
free_length = 1.5
actuator = "ACTUATOR"

[[force]]
name = "coil"
type = "torsion"
joint = "hinge"
stiffness = 3.0
damping = DAMPING
free_angle = 0.4
actuator = "ACTUATOR"

[[force]]
name = "push"
type = "force"
body = "a"
point = [0.3, 0.1, -0.2]
value = ["FORCE", "2.0 * FORCE", "-FORCE"]
axes = "body"

[[force]]
name = "twist"
type = "torque"
body = "b"
value = ["0.5 * FORCE", "FORCE", "0.25 * FORCE"]
axes = "body"
"#;

fn system(damping: f64, actuator: &str, force: &str) -> System {
    let text = FILE
        .replace("DAMPING", &damping.to_string())
        .replace("ACTUATOR", actuator)
        .replace("FORCE", force);
    let model = load("loads.toml", &text).unwrap_or_else(|e| panic!("{e}"));
    build(&model)
}

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
}

fn eval(
    sys: &System,
    ids: &[symbody_codegen::expr::Id],
    q: &[f64],
    qd: &[f64],
    t: f64,
) -> Vec<f64> {
    sys.arena.eval_many(ids, &|v| match v {
        Var::Q(i) => q[i as usize],
        Var::Qd(i) => qd[i as usize],
        Var::T => t,
        Var::P(_) | Var::K(_) => unreachable!("built with the parameters' values"),
        Var::Dq(_) | Var::Dqd(_) | Var::Dp(_) => unreachable!("built without tangents"),
    })
}

/// Q without gravity.
fn loads(sys: &System, q: &[f64], qd: &[f64], t: f64) -> Vec<f64> {
    let mut f = eval(sys, &sys.dynamics[0].force, q, qd, t);
    for (b, m) in [(0, 2.0), (1, 1.0)] {
        f[6 * b + 1] += 9.81 * m;
    }
    f
}

fn rot(a: &[f64]) -> Matrix3<f64> {
    nalgebra::Rotation3::from_euler_angles(a[0], a[1], a[2]).into_inner()
}

fn random_state(rng: &mut Rng) -> Vec<f64> {
    (0..12).map(|_| rng.next()).collect()
}

#[test]
fn conservative_loads_are_minus_the_gradient_of_the_potential() {
    let sys = system(0.0, "0.0", "0.0");
    let mut rng = Rng(0x1234_5678_9abc_def1);
    for _ in 0..20 {
        let q = random_state(&mut rng);
        let zero = vec![0.0; 12];
        let f = loads(&sys, &q, &zero, 0.3);
        // Potential without gravity: V − Σ(−m g·r).
        let v =
            |q: &[f64]| eval(&sys, &[sys.potential], q, &zero, 0.0)[0] - 9.81 * (2.0 * q[1] + q[7]);
        for i in 0..12 {
            let h = 1e-6;
            let (mut p, mut m) = (q.clone(), q.clone());
            p[i] += h;
            m[i] -= h;
            let grad = (v(&p) - v(&m)) / (2.0 * h);
            assert!(
                (f[i] + grad).abs() < 1e-6 * (1.0 + grad.abs()),
                "coordinate {i}: Q = {}, −∂V/∂q = {}",
                f[i],
                -grad
            );
        }
        let p = eval(&sys, &[sys.power_nc], &q, &zero, 0.3)[0];
        assert_eq!(p, 0.0, "no damping, actuator or applied load");
    }
}

/// Virtual power of every non-conservative load, written out by hand: the spring's
/// damper and actuator along the line, the torsion damper and actuator about the hinge
/// axis, the applied force at its point and the applied torque.
fn hand_power(q: &[f64], qd: &[f64], t: f64, c: f64, theta_dot: f64) -> f64 {
    let h = 1e-6;
    let at = |s: f64| -> Vec<f64> { q.iter().zip(qd).map(|(a, b)| a + s * b).collect() };
    let pose = |q: &[f64], b: usize| {
        let o = 6 * b;
        (
            Vector3::new(q[o], q[o + 1], q[o + 2]),
            rot(&q[o + 3..o + 6]),
        )
    };
    let d = |f: &dyn Fn(&[f64]) -> Vector3<f64>| (f(&at(h)) - f(&at(-h))) / (2.0 * h);
    // Spring from ground (0, 2, 0) to b's point placed at (1.2, 0.1, 0) initially.
    let a_b0 = rot(&[0.1, 0.2, 0.3]);
    let pb_local = a_b0.transpose() * (Vector3::new(1.2, 0.1, 0.0) - Vector3::new(1.0, 0.0, 0.0));
    let spring_vec = |q: &[f64]| {
        let (r, a) = pose(q, 1);
        r + a * pb_local - Vector3::new(0.0, 2.0, 0.0)
    };
    let len = spring_vec(q).norm();
    let len_dot = spring_vec(q).dot(&d(&spring_vec)) / len;
    let act = (2.0 * t).sin();
    let spring = (-c * len_dot + act) * len_dot;
    // Torsion: the hinge turns at θ̇ (the state is built that way).
    let rel = theta_dot;
    let torsion = (-c * rel + act) * rel;
    // Applied force on a at local (0.3, 0.1, −0.2), body axes; torque on b, body axes.
    let f_local = Vector3::new(3.0, 6.0, -3.0) * t;
    let p_local = Vector3::new(0.3, 0.1, -0.2);
    let point = |q: &[f64]| {
        let (r, a) = pose(q, 0);
        r + a * p_local
    };
    let force = (pose(q, 0).1 * f_local).dot(&d(&point));
    // Angular velocity of b: skew(ω) = Ȧ Aᵀ.
    let (a, ad) = (
        pose(q, 1).1,
        (pose(&at(h), 1).1 - pose(&at(-h), 1).1) / (2.0 * h),
    );
    let w = ad * a.transpose();
    let omega = Vector3::new(w[(2, 1)], w[(0, 2)], w[(1, 0)]);
    let tau = a * Vector3::new(1.5, 3.0, 0.75) * t;
    spring + torsion + force + tau.dot(&omega)
}

/// A state whose orientations keep the hinge aligned (b turned by θ about a's z from its
/// initial relative orientation), with random positions and rates: the torsion rate is
/// then exactly θ̇. Velocities are the derivative of that path, by central differences.
fn hinge_state(rng: &mut Rng) -> (Vec<f64>, Vec<f64>, f64) {
    let (a0, ad): (Vec<f64>, Vec<f64>) = (0..3).map(|_| (rng.next(), 2.0 * rng.next())).unzip();
    let (th0, thd) = (3.0 * rng.next(), 2.0 * rng.next());
    let (r0, rd): (Vec<f64>, Vec<f64>) = (0..6).map(|_| (rng.next(), 2.0 * rng.next())).unzip();
    let rel = rot(&[0.1, 0.2, 0.3]);
    let path = |s: f64| -> Vec<f64> {
        let aa: Vec<f64> = (0..3).map(|k| a0[k] + s * ad[k]).collect();
        let ab = rot(&aa)
            * *nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), th0 + s * thd).matrix()
            * rel;
        let (roll, pitch, yaw) = nalgebra::Rotation3::from_matrix_unchecked(ab).euler_angles();
        let r: Vec<f64> = (0..6).map(|k| r0[k] + s * rd[k]).collect();
        vec![
            r[0], r[1], r[2], aa[0], aa[1], aa[2], r[3], r[4], r[5], roll, pitch, yaw,
        ]
    };
    let h = 1e-6;
    let qd = path(h)
        .iter()
        .zip(path(-h))
        .map(|(p, m)| (p - m) / (2.0 * h))
        .collect();
    (path(0.0), qd, thd)
}

#[test]
fn non_conservative_power_and_forces_match_the_hand_written_virtual_power() {
    let c = 0.7;
    let sys = system(c, "sin(2.0 * t)", "3.0 * t");
    let conservative = system(0.0, "0.0", "0.0");
    let mut rng = Rng(0x0fed_cba9_8765_4321);
    for _ in 0..20 {
        let (q, qd, theta_dot) = hinge_state(&mut rng);
        let t = 0.5 + rng.next();
        let expect = hand_power(&q, &qd, t, c, theta_dot);
        let got = eval(&sys, &[sys.power_nc], &q, &qd, t)[0];
        assert!(
            (got - expect).abs() < 1e-6 * (1.0 + expect.abs()),
            "power_nc {got} vs hand-written {expect}"
        );
        // The generalized forces deliver that power: (Q − Q_conservative)·q̇.
        let f = loads(&sys, &q, &qd, t);
        let f0 = loads(&conservative, &q, &qd, t);
        let power: f64 = (0..12).map(|i| (f[i] - f0[i]) * qd[i]).sum();
        assert!(
            (power - expect).abs() < 1e-6 * (1.0 + expect.abs()),
            "Q·q̇ {power} vs hand-written {expect}"
        );
    }
}
