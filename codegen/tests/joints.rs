//! Every joint type against its textbook definition: the rank and mobility the generator
//! reports, and which rigid motions of the body its rows allow (Φq·q̇ = 0) or forbid, with the
//! body's rates computed independently (nalgebra quaternion kinematics, ė = ½ ω ⊗ e). Driver
//! rows: Φ vanishes at the start, Φt is −f'(t), and the sign the generator records for the
//! effort (∂Φ/∂s) is the derivative along the driven motion.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use symbody_codegen::assembly::assemble;
use symbody_codegen::equations::{build, System};
use symbody_codegen::expr::Var;
use symbody_codegen::model::load;

/// One quaternion body hung from the ground by `joint` (TOML lines) at (0.5, 0, 0),
/// with `driver` (TOML lines, may be empty).
fn mechanism(joint: &str, driver: &str) -> String {
    format!(
        r#"name = "one"
[[body]]
name = "b"
mass = 1.0
inertia = [0.1, 0.2, 0.3]
position = [0.3, 0.2, 0.1]
angles = [0.2, -0.3, 0.4]

[[joint]]
name = "j"
body1 = "ground"
body2 = "b"
{joint}
{driver}"#
    )
}

struct Case {
    sys: System,
    q0: Vec<f64>,
    mobility: usize,
    redundant: usize,
}

fn case(text: &str) -> Case {
    let model = load("one.toml", text).unwrap_or_else(|e| panic!("{e}\n{text}"));
    let sys = build(&model);
    let asm = assemble(&model, &sys, "one.toml").unwrap_or_else(|e| panic!("{e}"));
    Case {
        q0: asm.q0,
        mobility: asm.report.mobility,
        redundant: asm.report.redundant.len(),
        sys,
    }
}

impl Case {
    fn env<'a>(&'a self, t: f64) -> impl Fn(Var) -> f64 + 'a {
        move |v| match v {
            Var::Q(i) => self.q0[i as usize],
            Var::Qd(_) => 0.0,
            Var::T => t,
            Var::P(_) | Var::K(_) => unreachable!("built with the parameters' values"),
            Var::Dq(_) | Var::Dqd(_) | Var::Dp(_) => unreachable!("built without tangents"),
        }
    }
    /// Φq·q̇ per row at the start.
    fn rate(&self, qd: &[f64]) -> Vec<f64> {
        let ids: Vec<_> = self.sys.phi_q.iter().map(|e| e.2).collect();
        let vals = self.sys.arena.eval_many(&ids, &self.env(0.0));
        let mut out = vec![0.0; self.sys.n_constraints];
        for (&(r, c, _), v) in self.sys.phi_q.iter().zip(vals) {
            out[r as usize] += v * qd[c as usize];
        }
        out
    }
    /// Coordinate rates of the rigid motion "turn at ω about the line through p, and
    /// translate at v".
    fn twist(&self, omega: [f64; 3], p: [f64; 3], v: [f64; 3]) -> Vec<f64> {
        let q = &self.q0;
        let (w, p, v) = (Vector3::from(omega), Vector3::from(p), Vector3::from(v));
        let r = Vector3::new(q[0], q[1], q[2]);
        let rd = v + w.cross(&(r - p));
        let e = Quaternion::new(q[3], q[4], q[5], q[6]);
        let ed = Quaternion::from_imag(w) * e * 0.5;
        vec![rd.x, rd.y, rd.z, ed.w, ed.i, ed.j, ed.k]
    }
}

const P: [f64; 3] = [0.5, 0.0, 0.0];
const O: [f64; 3] = [0.0; 3];
const X: [f64; 3] = [1.0, 0.0, 0.0];
const Y: [f64; 3] = [0.0, 1.0, 0.0];
const Z: [f64; 3] = [0.0, 0.0, 1.0];

/// The joint rows (all but the normalization row, which is last) allow this motion.
fn allows(c: &Case, qd: &[f64], what: &str) {
    let r = c.rate(qd);
    let joint_rows = &r[..r.len() - 1];
    let worst = joint_rows.iter().fold(0.0f64, |a, b| a.max(b.abs()));
    assert!(worst < 1e-12, "{what} should be allowed: Φq q̇ = {r:?}");
    assert!(r[r.len() - 1].abs() < 1e-12, "the motion keeps |e| = 1");
}

fn forbids(c: &Case, qd: &[f64], what: &str) {
    let r = c.rate(qd);
    let worst = r[..r.len() - 1].iter().fold(0.0f64, |a, b| a.max(b.abs()));
    assert!(worst > 1e-2, "{what} should be forbidden: Φq q̇ = {r:?}");
}

#[test]
fn spherical_allows_every_rotation_about_its_point() {
    let c = case(&mechanism("type = \"spherical\"\nat = [0.5, 0.0, 0.0]", ""));
    assert_eq!((c.mobility, c.redundant), (3, 0));
    for w in [X, Y, Z] {
        allows(&c, &c.twist(w, P, O), "rotation about the point");
    }
    forbids(&c, &c.twist(O, P, X), "translation");
}

#[test]
fn revolute_allows_rotation_about_its_axis_only() {
    let c = case(&mechanism(
        "type = \"revolute\"\nat = [0.5, 0.0, 0.0]\naxis = [0.0, 0.0, 1.0]",
        "",
    ));
    assert_eq!((c.mobility, c.redundant), (1, 0));
    allows(&c, &c.twist(Z, P, O), "rotation about the axis");
    forbids(&c, &c.twist(X, P, O), "rotation about a cross axis");
    forbids(&c, &c.twist(O, P, Z), "sliding along the axis");
}

#[test]
fn universal_allows_rotation_about_both_cross_axes() {
    let c = case(&mechanism(
        "type = \"universal\"\nat = [0.5, 0.0, 0.0]\naxis = [0.0, 0.0, 1.0]\ncross_axis = [1.0, 0.0, 0.0]",
        "",
    ));
    assert_eq!((c.mobility, c.redundant), (2, 0));
    allows(&c, &c.twist(Z, P, O), "rotation about the ground's axis");
    allows(
        &c,
        &c.twist(X, P, O),
        "rotation about the body's cross axis",
    );
    forbids(&c, &c.twist(Y, P, O), "rotation about the third axis");
}

#[test]
fn cylindrical_allows_turning_and_sliding_along_its_axis() {
    let c = case(&mechanism(
        "type = \"cylindrical\"\nat = [0.5, 0.0, 0.0]\naxis = [0.0, 0.0, 1.0]",
        "",
    ));
    assert_eq!((c.mobility, c.redundant), (2, 0));
    allows(&c, &c.twist(Z, P, O), "rotation about the axis");
    allows(&c, &c.twist(O, P, Z), "sliding along the axis");
    forbids(&c, &c.twist(O, P, X), "sliding across the axis");
    forbids(&c, &c.twist(Y, P, O), "rotation about a cross axis");
}

#[test]
fn prismatic_allows_sliding_along_its_axis_only() {
    let c = case(&mechanism(
        "type = \"prismatic\"\nat = [0.5, 0.0, 0.0]\naxis = [0.0, 0.0, 1.0]",
        "",
    ));
    assert_eq!((c.mobility, c.redundant), (1, 0));
    allows(&c, &c.twist(O, P, Z), "sliding along the axis");
    forbids(&c, &c.twist(Z, P, O), "rotation about the axis");
    forbids(&c, &c.twist(O, P, Y), "sliding across the axis");
}

#[test]
fn fixed_allows_nothing() {
    let c = case(&mechanism("type = \"fixed\"\nat = [0.5, 0.0, 0.0]", ""));
    assert_eq!((c.mobility, c.redundant), (0, 0));
    for w in [X, Y, Z] {
        forbids(&c, &c.twist(w, P, O), "rotation");
        forbids(&c, &c.twist(O, P, w), "translation");
    }
}

#[test]
fn distance_allows_everything_but_stretching() {
    let c = case(&mechanism(
        "type = \"distance\"\nat1 = [0.5, 0.0, 0.0]\nat2 = [0.3, 0.2, 0.1]",
        "",
    ));
    assert_eq!((c.mobility, c.redundant), (5, 0));
    // The line from the ground point to the body's point (its centre of mass here).
    let d = [-0.2, 0.2, 0.1];
    for w in [X, Y, Z] {
        allows(&c, &c.twist(w, P, O), "rotation about the ground point");
    }
    allows(
        &c,
        &c.twist(Z, [0.3, 0.2, 0.1], O),
        "rotation about the body's point",
    );
    forbids(&c, &c.twist(O, P, d), "stretching");
}

/// The driver row (the last but one: the normalization row is last): Φ = 0 at the start,
/// Φt = −f'(0) × ∂Φ/∂s, and Φq q̇ along the driven motion equals the recorded sign.
fn check_driver(c: &Case, driven: &[f64], f_dot: f64) {
    let row = c.sys.n_constraints - 2;
    let sign = c.sys.driver_signs[0];
    let phi = c.sys.arena.eval(c.sys.phi[row], &c.env(0.0));
    assert!(phi.abs() < 1e-12, "driver residual at the start {phi}");
    let along = c.rate(driven)[row];
    assert!(
        (along - sign).abs() < 1e-12,
        "∂Φ/∂s = {along}, recorded {sign}"
    );
    let phi_t = c.sys.arena.eval(c.sys.phi_t[row], &c.env(0.0));
    assert!((phi_t + sign * f_dot).abs() < 1e-12, "Φt = {phi_t}");
}

#[test]
fn drivers_of_each_kind_prescribe_their_coordinate() {
    let rev = "type = \"revolute\"\nat = [0.5, 0.0, 0.0]\naxis = [0.0, 0.0, 1.0]";
    let c = case(&mechanism(
        rev,
        "[[driver]]\nname = \"d\"\njoint = \"j\"\nvalue = \"initial + 2.0 * t\"",
    ));
    check_driver(&c, &c.twist(Z, P, O), 2.0);

    let pri = "type = \"prismatic\"\nat = [0.5, 0.0, 0.0]\naxis = [0.0, 0.0, 1.0]";
    let c = case(&mechanism(
        pri,
        "[[driver]]\nname = \"d\"\njoint = \"j\"\nvalue = \"initial + 0.5 * t\"",
    ));
    check_driver(&c, &c.twist(O, P, Z), 0.5);

    let sph = "type = \"spherical\"\nat = [0.5, 0.0, 0.0]";
    let c = case(&mechanism(
        sph,
        "[[driver]]\nname = \"d\"\nbody = \"b\"\ncoordinate = \"y\"\nvalue = \"initial - 3.0 * t\"",
    ));
    // Turning about z through the pivot moves the centre at ω × (r − p): with r − p =
    // (−0.2, 0.2, 0.1), ω = (0, 0, −5) gives ẏ = 1.
    check_driver(&c, &c.twist([0.0, 0.0, -5.0], P, O), -3.0);

    let c = case(&mechanism(
        sph,
        "[[driver]]\nname = \"d\"\nbody1 = \"ground\"\nat1 = [0.0, 0.0, 0.0]\nbody2 = \"b\"\nat2 = [0.3, 0.2, 0.1]\nvalue = \"initial + t\"",
    ));
    // Turning about the pivot moves the centre on a sphere about P; the distance from the
    // origin changes at (r/|r|)·ṙ. Take the rate that gives a unit change.
    let r = Vector3::new(0.3, 0.2, 0.1);
    let w = Vector3::new(0.0, 0.0, 1.0);
    let rd = w.cross(&(r - Vector3::from(P)));
    let scale = 1.0 / r.normalize().dot(&rd);
    check_driver(&c, &c.twist((w * scale).into(), P, O), 1.0);
}

#[test]
fn initial_orientation_is_a_unit_quaternion() {
    let c = case(&mechanism("type = \"spherical\"\nat = [0.5, 0.0, 0.0]", ""));
    let e = UnitQuaternion::from_euler_angles(0.2, -0.3, 0.4);
    let q = &c.q0;
    let got = Quaternion::new(q[3], q[4], q[5], q[6]);
    assert!((got - *e.quaternion()).norm() < 1e-14 || (got + *e.quaternion()).norm() < 1e-14);
}
