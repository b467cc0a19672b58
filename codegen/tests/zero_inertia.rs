//! Zero principal inertias (a slender rod about its own axis, as the IFToMM benchmark
//! problems define rods): accepted when the joints fix the rotation about that axis, and
//! then run by the solvers to the same motion as with a nonzero axial inertia (which the
//! revolute joints keep unexcited); refused, naming the body and the axis, when a joint
//! leaves that rotation free.
//!
//! The equations are run by interpreting the generator's expression DAG (the generated
//! Rust is a straight-line transcription of the same DAG).

use symbody_codegen::assembly::assemble;
use symbody_codegen::equations::{build, System};
use symbody_codegen::expr::{Id, Var};
use symbody_codegen::generate;
use symbody_codegen::model::{load, Rotation as CgRotation};
use symbody_runtime::kkt::{KktPattern, KktSolver, SchurKkt};
use symbody_runtime::mechanism::{
    BodyInfo, Formulation, KinematicOutputs, Mechanism, MechanismInfo, NewtonOutputs, Rotation,
};
use symbody_runtime::{DenseKkt, HhtBuilder};

const FILE: &str = "mechanisms/rods.toml";

/// A planar double pendulum of two 1 m rods along their local x, hinged about global z to
/// the ground and to each other (the elbow is a `joint2`: "revolute" or "spherical");
/// `axial` is both rods' inertia about their own axis; `top` adds top-level keys.
fn double_pendulum(axial: &str, joint2: &str, top: &str) -> String {
    let axis = if joint2 == "revolute" {
        "axis = [0.0, 0.0, 1.0]\n"
    } else {
        ""
    };
    let (a, b) = (-0.4f64, 0.9f64);
    let (ca, sa) = (a.cos(), a.sin());
    let (cb, sb) = (b.cos(), b.sin());
    format!(
        r#"name = "rods"
{top}

[[body]]
name = "upper"
mass = 1.0
inertia = [{axial}, "1.0 / 12.0", "1.0 / 12.0"]
position = [{}, {}, 0.0]
angles = [0.0, 0.0, {a}]

[[body]]
name = "lower"
mass = 0.5
inertia = [{axial}, "0.5 / 12.0", "0.5 / 12.0"]
position = [{}, {}, 0.0]
angles = [0.0, 0.0, {b}]

[[joint]]
name = "shoulder"
type = "revolute"
body1 = "ground"
body2 = "upper"
at = [0.0, 0.0, 0.0]
axis = [0.0, 0.0, 1.0]

[[joint]]
name = "elbow"
type = "{joint2}"
body1 = "upper"
body2 = "lower"
at = [{ca}, {sa}, 0.0]
{axis}"#,
        0.5 * ca,
        0.5 * sa,
        ca + 0.5 * cb,
        sa + 0.5 * sb,
    )
}

/// The generator's equations of one mechanism file, evaluated by walking the DAG.
struct Interpreted {
    sys: System,
    info: &'static MechanismInfo,
}

fn leak<T>(v: Vec<T>) -> &'static [T] {
    Box::leak(v.into_boxed_slice())
}

impl Interpreted {
    fn new(text: &str) -> Self {
        let model = load(FILE, text).unwrap_or_else(|e| panic!("{e}"));
        let sys = build(&model);
        let asm = assemble(&model, &sys, FILE).unwrap_or_else(|e| panic!("{e}"));
        let dy = &sys.dynamics[0];
        let names = |v: &[String]| leak(v.iter().map(|s| &*s.clone().leak()).collect());
        let bodies = model
            .bodies
            .iter()
            .map(|b| BodyInfo {
                name: b.name.clone().leak(),
                coord_offset: b.offset,
                rotation: match b.rotation {
                    CgRotation::Euler => Rotation::Euler,
                    CgRotation::Quaternion => Rotation::Quaternion,
                },
                mass: b.mass,
                inertia: b.inertia,
            })
            .collect();
        let info = Box::leak(Box::new(MechanismInfo {
            name: "rods",
            n_coords: sys.n_coords,
            n_constraints: sys.n_constraints,
            formulation: Formulation::Exact,
            gravity: model.gravity,
            phi_q_rows: leak(sys.phi_q.iter().map(|e| e.0).collect()),
            phi_q_cols: leak(sys.phi_q.iter().map(|e| e.1).collect()),
            mass_rows: leak(dy.mass.iter().map(|e| e.0).collect()),
            mass_cols: leak(dy.mass.iter().map(|e| e.1).collect()),
            mass_is_constant: dy.mass_is_constant,
            force_q_rows: &[],
            force_q_cols: &[],
            force_qd_rows: &[],
            force_qd_cols: &[],
            bodies: leak(bodies),
            joints: &[],
            coord_names: names(&sys.coord_names),
            row_names: names(&sys.row_names),
            q0: leak(asm.q0.clone()),
            qd0: leak(model.qd0()),
            redundant_rows: leak(asm.redundant_rows.clone()),
            platform: None,
            kkt: &[],
        }));
        Interpreted { sys, info }
    }

    fn eval(&self, roots: &[Id], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let env = |v: Var| match v {
            Var::Q(i) => q[i as usize],
            Var::Qd(i) => qd[i as usize],
            Var::T => t,
            Var::P(_) | Var::K(_) => unreachable!("built with the parameters' values"),
            Var::Dq(_) | Var::Dqd(_) | Var::Dp(_) => unreachable!("built without tangents"),
        };
        out.copy_from_slice(&self.sys.arena.eval_many(roots, &env));
    }

    fn ids(entries: &[(u32, u32, Id)]) -> Vec<Id> {
        entries.iter().map(|e| e.2).collect()
    }
}

impl Mechanism for Interpreted {
    fn info(&self) -> &'static MechanismInfo {
        self.info
    }
    fn phi(&self, q: &[f64], t: f64, out: &mut [f64]) {
        self.eval(&self.sys.phi, q, q, t, out);
    }
    fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) {
        self.eval(&Self::ids(&self.sys.phi_q), q, q, t, out);
    }
    fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) {
        self.eval(&self.sys.phi_t, q, q, t, out);
    }
    fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        self.eval(&self.sys.gamma, q, qd, t, out);
    }
    fn mass(&self, q: &[f64], out: &mut [f64]) {
        self.eval(&Self::ids(&self.sys.dynamics[0].mass), q, q, 0.0, out);
    }
    fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        self.eval(&self.sys.dynamics[0].force, q, qd, t, out);
    }
    fn potential(&self, q: &[f64]) -> f64 {
        let mut v = [0.0];
        self.eval(&[self.sys.potential], q, q, 0.0, &mut v);
        v[0]
    }
    fn power_nc(&self, q: &[f64], qd: &[f64], t: f64) -> f64 {
        let mut v = [0.0];
        self.eval(&[self.sys.power_nc], q, qd, t, &mut v);
        v[0]
    }
    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        self.phi(q, t, out.phi);
        self.phi_q(q, t, out.phi_q);
        self.mass(q, out.mass);
        self.force(q, qd, t, out.force);
    }
    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
        self.phi(q, t, out.phi);
        self.phi_q(q, t, out.phi_q);
        self.phi_t(q, t, out.phi_t);
        self.gamma(q, qd, t, out.gamma);
    }
}

/// The centres of mass (x, y of both rods) every 0.01 s up to 1.5 s, with steps of `h` and
/// tight Newton tolerances so that the solution, not the iteration, is compared.
fn swing<K: KktSolver>(mech: Interpreted, h: f64) -> Vec<[f64; 4]> {
    let lower = mech.info.bodies[1].coord_offset;
    let mut hht = HhtBuilder::new()
        .step(h)
        .rel_tol(1e-12)
        .abs_tol_acceleration(1e-10)
        .abs_tol_lambda(1e-10)
        .build_with_solver::<_, K>(mech)
        .unwrap_or_else(|e| panic!("{e}"));
    (1..=150)
        .map(|k| {
            hht.advance_to(k as f64 * 0.01)
                .unwrap_or_else(|e| panic!("{e}"));
            let q = hht.q();
            [q[0], q[1], q[lower], q[lower + 1]]
        })
        .collect()
}

fn largest_difference(a: &[[f64; 4]], b: &[[f64; 4]]) -> f64 {
    a.iter()
        .zip(b)
        .flat_map(|(x, y)| x.iter().zip(y).map(|(u, v)| (u - v).abs()))
        .fold(0.0, f64::max)
}

#[test]
fn euler_rods_without_axial_inertia_swing_exactly_as_with_it() {
    // Euler-angle rods: M about the axial spin is Ixx alone, and the hinges keep θ and β at
    // exactly 0, so the axial inertia never enters the discrete equations either: the same
    // motion with 1e-3 kg·m² (run by the block-Cholesky path) is the reference to roundoff.
    let top = "rotation = \"euler\"";
    let text = double_pendulum("0.0", "revolute", top);
    let g = generate(FILE, &text).unwrap_or_else(|e| panic!("{e}"));
    assert!(g.report.warnings.is_empty(), "{}", g.report);

    let zero = Interpreted::new(&text);
    let pattern = KktPattern::from_info(zero.info);
    assert!(pattern.mass_semidefinite);
    assert!(SchurKkt::new(&pattern).unwrap().is_dense());
    let with = Interpreted::new(&double_pendulum("1e-3", "revolute", top));
    let pattern = KktPattern::from_info(with.info);
    assert!(!pattern.mass_semidefinite);
    assert!(!SchurKkt::new(&pattern).unwrap().is_dense());

    let reference = swing::<SchurKkt>(with, 1e-3);
    let moved = largest_difference(&reference[..1], &reference[reference.len() - 1..]);
    assert!(moved > 0.3, "the pendulum barely moved: {moved}");
    let structured = swing::<SchurKkt>(zero, 1e-3);
    let diff = largest_difference(&structured, &reference);
    assert!(
        diff < 1e-10,
        "zero axial inertia changed the motion by {diff:e} m"
    );
    let dense = swing::<DenseKkt>(Interpreted::new(&text), 1e-3);
    let diff = largest_difference(&dense, &reference);
    assert!(
        diff < 1e-10,
        "dense solver: the motion differs by {diff:e} m"
    );
}

#[test]
fn quaternion_rods_without_axial_inertia_converge_to_the_motion_with_it() {
    // Quaternion rods: the normalization term k·eeᵀ of M (k = 4·mean inertia) changes with
    // the axial inertia, and only the continuous equations are blind to it (eᵀë = −ėᵀė holds
    // exactly there, not between HHT's discrete states). So the discrete motions differ by
    // an integration error, which must vanish with the step: measured first order, halving
    // with each halved step (1.5e-6, 7.5e-7, 3.7e-7 m).
    let text = double_pendulum("0.0", "revolute", "");
    let g = generate(FILE, &text).unwrap_or_else(|e| panic!("{e}"));
    assert!(g.report.warnings.is_empty(), "{}", g.report);
    let with = double_pendulum("1e-3", "revolute", "");
    let diffs: Vec<f64> = [2e-3, 1e-3, 5e-4]
        .iter()
        .map(|&h| {
            let zero = swing::<SchurKkt>(Interpreted::new(&text), h);
            let reference = swing::<SchurKkt>(Interpreted::new(&with), h);
            largest_difference(&zero, &reference)
        })
        .collect();
    assert!(diffs[0] < 3e-6, "{diffs:?}");
    for w in diffs.windows(2) {
        assert!(w[0] / w[1] > 1.8, "not converging with the step: {diffs:?}");
    }
}

#[test]
fn a_rod_without_axial_inertia_on_a_spherical_joint_is_an_error() {
    // The elbow as a ball joint leaves the lower rod free to spin about its own axis, which
    // then carries no kinetic energy: the accelerations are undetermined.
    let text = double_pendulum("0.0", "spherical", "");
    let errs = generate(FILE, &text).expect_err("the lower rod's spin is free");
    assert_eq!(errs.0.len(), 1, "{errs}");
    let d = &errs.0[0];
    let shown = d.to_string();
    assert_eq!(d.item, "body `lower`", "{shown}");
    let line = text
        .lines()
        .position(|l| l.contains("name = \"lower\""))
        .unwrap()
        + 1;
    assert_eq!(d.line, line, "{shown}");
    assert!(
        d.message.contains("zero inertia about its local x axis"),
        "{shown}"
    );
    assert!(d.message.contains("no joint fixes its rotation"), "{shown}");
    assert!(d.help.contains("small inertia"), "{shown}");

    // With the axial inertia back, the same mechanism is fine.
    generate(FILE, &double_pendulum("1e-3", "spherical", "")).unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn zero_inertia_about_an_axis_a_joint_fixes_is_accepted_in_each_formulation() {
    // Euler-angle rods in both formulations (the paper's M lacks Ixx against θ̇ instead).
    let top = "rotation = \"euler\"\nformulations = [\"exact\", \"paper\"]";
    generate(FILE, &double_pendulum("0.0", "revolute", top)).unwrap_or_else(|e| panic!("{e}"));
    for top in [top, "rotation = \"euler\"\nformulations = [\"paper\"]"] {
        let errs = generate(FILE, &double_pendulum("0.0", "spherical", top))
            .expect_err("the lower rod's spin is free");
        assert_eq!(errs.0[0].item, "body `lower`", "{errs}");
        assert!(errs.0[0].message.contains("local x axis"), "{errs}");
    }
}
