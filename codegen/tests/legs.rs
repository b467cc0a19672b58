//! Six-leg platform detection: the Stewart platform files are recognized with the joint centres
//! their parameters define, small platforms on point-distance and S-P-S legs are recognized,
//! and anything else on the platform, a missing leg, or a slide off the leg line (or measured
//! against the leg length) is not. For a recognized leg, `|leg(q)| − Φ_row(q, t)` is the same
//! at every extension of the leg: the unit slope the runtime's forward kinematics relies on.

use symbody_codegen::assembly::{assemble, Assembly};
use symbody_codegen::equations::{build, System};
use symbody_codegen::expr::Var;
use symbody_codegen::geometry::{euler_matrix, v3, V3};
use symbody_codegen::legs::Platform;
use symbody_codegen::model::{load, Model};

struct Case {
    model: Model,
    sys: System,
    asm: Assembly,
}

fn case(name: &str, text: &str) -> Case {
    let model = load(name, text).unwrap_or_else(|e| panic!("{e}\n{text}"));
    let sys = build(&model);
    let asm = assemble(&model, &sys, name).unwrap_or_else(|e| panic!("{e}"));
    Case { model, sys, asm }
}

impl Case {
    fn platform(&self) -> &Platform {
        self.asm.platform.as_ref().expect("a six-leg platform")
    }
    fn phi(&self, q: &[f64], t: f64) -> Vec<f64> {
        let env = |v: Var| match v {
            Var::Q(i) => q[i as usize],
            Var::Qd(_) => 0.0,
            Var::T => t,
            Var::P(_) | Var::K(_) => unreachable!("Φ reads no run-time parameter"),
            Var::Dq(_) | Var::Dqd(_) | Var::Dp(_) => unreachable!("built without tangents"),
        };
        self.sys.arena.eval_many(&self.sys.phi, &env)
    }
    /// `|leg(q)|` of the platform's leg `k` (in driver order): platform joint centre minus
    /// base joint centre.
    fn leg_length(&self, q: &[f64], k: usize) -> f64 {
        let p = self.platform();
        let leg = &p.legs[k];
        let off = self.model.bodies[p.body].offset;
        let c = &q[off..off + 7];
        let e = nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
            c[3], c[4], c[5], c[6],
        ));
        let top = V3::new(c[0], c[1], c[2]) + e * v3(leg.platform);
        (top - v3(leg.base)).norm()
    }
}

fn close(a: [f64; 3], b: [f64; 3], tol: f64) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() <= tol)
}

/// `(R cos a, 0, −R sin a)`, `a` in degrees: the Stewart files' joint circle.
fn circle(r: f64, deg: f64) -> [f64; 3] {
    let a = deg.to_radians();
    [r * a.cos(), 0.0, -r * a.sin()]
}

fn workspace_file(name: &str) -> String {
    let path = format!("{}/../mechanisms/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

#[test]
fn the_stewart_platforms_are_recognized_with_their_joint_centres() {
    const PHI: [f64; 6] = [10.5, 109.5, 130.5, 229.5, 250.5, 349.5];
    const ALPHA: [f64; 6] = [49.5, 70.5, 169.5, 190.5, 289.5, 310.5];
    for file in ["stewart_6_6.toml", "ups_stewart.toml"] {
        let c = case(file, &workspace_file(file));
        let p = c.platform();
        assert_eq!(c.model.bodies[p.body].name, "platform", "{file}");
        assert_eq!(p.legs.len(), 6);
        for (k, leg) in p.legs.iter().enumerate() {
            let name = format!("act{}", k + 1);
            assert_eq!(c.model.drivers[leg.driver].name, name, "{file}");
            assert_eq!(c.sys.row_names[leg.row], name, "{file}: the driver's row");
            assert!(
                close(leg.base, circle(0.27, PHI[k]), 1e-15),
                "{file} {name}"
            );
            assert!(
                close(leg.platform, circle(0.105, ALPHA[k]), 1e-15),
                "{file} {name}"
            );
        }
    }
    let report = case("stewart_6_6.toml", &workspace_file("stewart_6_6.toml"))
        .asm
        .report;
    assert!(report.to_string().contains(
        "platform: body \"platform\" held by 6 driven legs (act1, act2, act3, act4, act5, act6)"
    ));
}

#[test]
fn the_other_mechanisms_are_not_platforms() {
    for file in [
        "bricard.toml",
        "four_bar.toml",
        "oscillators.toml",
        "slider_crank.toml",
        "spherical_pendulum.toml",
    ] {
        let c = case(file, &workspace_file(file));
        assert!(c.asm.platform.is_none(), "{file}");
        assert!(c.asm.report.platform.is_none(), "{file}");
    }
}

const BASE_DEG: [f64; 6] = [0.0, 100.0, 120.0, 220.0, 240.0, 340.0];
const TOP_DEG: [f64; 6] = [50.0, 70.0, 170.0, 190.0, 290.0, 310.0];
const PLATE_AT: [f64; 3] = [0.05, 0.6, -0.02];
const PLATE_ANGLES: [f64; 3] = [0.05, 0.1, -0.08];

fn base(k: usize) -> [f64; 3] {
    circle(0.5, BASE_DEG[k])
}
fn top_local(k: usize) -> [f64; 3] {
    circle(0.2, TOP_DEG[k])
}
/// Global platform joint centre of leg `k` at the initial pose.
fn top(k: usize) -> V3 {
    v3(PLATE_AT) + euler_matrix(PLATE_ANGLES) * v3(top_local(k))
}

fn vec(v: V3) -> String {
    format!("[{:?}, {:?}, {:?}]", v.x, v.y, v.z)
}

/// A quaternion plate over the ground, and its legs: `legs` (TOML) and the point-distance
/// legs `distance_legs` (leg indices).
fn plate(distance_legs: &[usize], legs: &str) -> String {
    let mut s = format!(
        "name = \"plate\"\nrotation = \"quaternion\"\n\n[[body]]\nname = \"plate\"\nmass = 2.0\ninertia = [0.1, 0.2, 0.1]\nposition = {PLATE_AT:?}\nangles = {PLATE_ANGLES:?}\n{legs}"
    );
    for &k in distance_legs {
        s += &format!(
            "\n[[driver]]\nname = \"leg{}\"\nbody1 = \"ground\"\npoint1 = {:?}\nbody2 = \"plate\"\npoint2 = {:?}\nvalue = \"initial + 0.01 * sin(t)\"\n",
            k + 1,
            base(k),
            top_local(k)
        );
    }
    s
}

/// An S-P-S leg `k` whose slide joint has `kind`, (global) `axis`, and its point `off` from
/// the leg's middle; `upper_first` puts the platform-side body first in the slide joint.
fn sps_leg(k: usize, kind: &str, axis: V3, off: V3, upper_first: bool) -> String {
    let (b, t) = (v3(base(k)), top(k));
    let d = t - b;
    let (lower, upper) = (format!("lower{k}"), format!("upper{k}"));
    let (body1, body2) = if upper_first {
        (&upper, &lower)
    } else {
        (&lower, &upper)
    };
    format!(
        r#"
[[body]]
name = "{lower}"
mass = 0.3
inertia = [0.01, 0.001, 0.01]
position = {lp}

[[body]]
name = "{upper}"
mass = 0.2
inertia = [0.01, 0.001, 0.01]
position = {up}

[[joint]]
name = "base{k}"
type = "spherical"
body1 = "ground"
body2 = "{lower}"
at = {b}

[[joint]]
name = "slide{k}"
type = "{kind}"
body1 = "{body1}"
body2 = "{body2}"
at = {mid}
axis = {axis}

[[joint]]
name = "top{k}"
type = "spherical"
body1 = "plate"
body2 = "{upper}"
at = {t}

[[driver]]
name = "act{k}"
joint = "slide{k}"
coordinate = "distance"
value = "initial + 0.01 * sin(t)"
"#,
        lp = vec(b + 0.25 * d),
        up = vec(b + 0.75 * d),
        b = vec(b),
        mid = vec(b + 0.5 * d + off),
        t = vec(t),
        axis = vec(axis),
    )
}

/// Five point-distance legs and leg 5 an S-P-S leg.
fn with_sps(kind: &str, axis: V3, upper_first: bool) -> Case {
    with_sps_at(kind, axis, V3::zeros(), upper_first)
}

fn with_sps_at(kind: &str, axis: V3, off: V3, upper_first: bool) -> Case {
    let leg = sps_leg(5, kind, axis, off, upper_first);
    case("plate.toml", &plate(&[0, 1, 2, 3, 4], &leg))
}

fn leg_dir() -> V3 {
    (top(5) - v3(base(5))).normalize()
}

#[test]
fn six_point_distance_drivers_hold_a_platform() {
    let c = case("plate.toml", &plate(&[0, 1, 2, 3, 4, 5], ""));
    let p = c.platform();
    assert_eq!(p.body, 0);
    assert_eq!(p.legs.len(), 6);
    for (k, leg) in p.legs.iter().enumerate() {
        assert_eq!(leg.driver, k);
        assert_eq!(leg.row, k, "no joints: the drivers' rows come first");
        assert_eq!(c.sys.row_names[leg.row], format!("leg{}", k + 1));
        assert_eq!(leg.base, base(k));
        assert_eq!(leg.platform, top_local(k));
        // Φ = |leg| − f(t), so |leg| − Φ is f(t) exactly.
        let q = &c.asm.q0;
        let f = c.leg_length(q, k) + 0.01 * 0.7f64.sin();
        let got = c.leg_length(q, k) - c.phi(q, 0.7)[leg.row];
        assert!((got - f).abs() < 1e-14, "{got} vs {f}");
    }
}

#[test]
fn a_missing_leg_or_anything_else_on_the_platform_is_not_a_platform() {
    let five = case("plate.toml", &plate(&[0, 1, 2, 3, 4], ""));
    assert!(five.asm.platform.is_none(), "five legs");

    let bob = r#"
[[body]]
name = "bob"
mass = 0.1
inertia = [0.001, 0.001, 0.001]
position = [0.05, 0.3, -0.02]

[[joint]]
name = "hang"
type = "spherical"
body1 = "plate"
body2 = "bob"
at = [0.05, 0.6, -0.02]
"#;
    let extra = case("plate.toml", &plate(&[0, 1, 2, 3, 4, 5], bob));
    assert!(
        extra.asm.platform.is_none(),
        "an extra joint on the platform"
    );

    let seven = "\n[[driver]]\nname = \"leg7\"\nbody1 = \"ground\"\npoint1 = [0.0, 0.0, 0.7]\nbody2 = \"plate\"\npoint2 = [0.0, 0.0, 0.0]\nvalue = \"initial\"\n";
    let c = case("plate.toml", &(plate(&[0, 1, 2, 3, 4, 5], "") + seven));
    assert!(c.asm.platform.is_none(), "seven legs");
}

#[test]
fn an_sps_leg_on_its_leg_line_is_a_leg_with_unit_slope() {
    for kind in ["prismatic", "cylindrical"] {
        let c = with_sps(kind, leg_dir(), false);
        let p = c.platform();
        // Legs come in driver order, and the S-P-S leg's driver is the file's first.
        let leg = &p.legs[0];
        assert_eq!(c.model.drivers[leg.driver].name, "act5", "{kind}");
        assert_eq!(c.sys.row_names[leg.row], "act5", "{kind}");
        assert!(close(leg.base, base(5), 1e-15), "{kind}");
        assert!(close(leg.platform, top_local(5), 1e-14), "{kind}");

        // Extend the leg by δ (upper leg body and plate move along it): |leg| − Φ stays.
        let q0 = c.asm.q0.clone();
        let before = c.leg_length(&q0, 0) - c.phi(&q0, 0.3)[leg.row];
        let mut q = q0.clone();
        let delta = 0.04 * leg_dir();
        for name in ["plate", "upper5"] {
            let b = c.model.bodies.iter().find(|b| b.name == name).unwrap();
            for i in 0..3 {
                q[b.offset + i] += delta[i];
            }
        }
        let after = c.leg_length(&q, 0) - c.phi(&q, 0.3)[leg.row];
        assert!((c.leg_length(&q, 0) - c.leg_length(&q0, 0) - 0.04).abs() < 1e-14);
        assert!(
            (after - before).abs() < 1e-14,
            "{kind}: {before} then {after}"
        );
    }
    // The slide measured from the platform-side body: the axis must point down the leg.
    assert!(with_sps("prismatic", -leg_dir(), true)
        .asm
        .platform
        .is_some());
}

#[test]
fn a_slide_off_the_leg_line_or_against_the_leg_length_is_not_a_leg() {
    let d = leg_dir();
    let tilted = (d + 0.1 * d.cross(&V3::y()).normalize()).normalize();
    assert!(with_sps("prismatic", tilted, false).asm.platform.is_none());
    // Parallel but measured the wrong way: Φ would fall as the leg grows.
    assert!(with_sps("prismatic", -d, false).asm.platform.is_none());
    assert!(with_sps("prismatic", d, true).asm.platform.is_none());
    // Slide axis parallel to the leg line but beside it: a prismatic leg keeps its length
    // offset, a cylindrical one would change it by turning about the axis.
    let beside = 0.03 * d.cross(&V3::y()).normalize();
    assert!(with_sps_at("prismatic", d, beside, false)
        .asm
        .platform
        .is_some());
    assert!(with_sps_at("cylindrical", d, beside, false)
        .asm
        .platform
        .is_none());
}
