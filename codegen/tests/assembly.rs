//! Assembly at generation time: a violated initial pose is corrected with a warning naming
//! the joint and the size of the correction (and the generated Q0 satisfies Φ), a pose off
//! by rounding is corrected silently, an impossible one is an error naming the rows and the
//! joint with file:line; and the reports of the workspace's four-bar, Bricard and Stewart
//! mechanisms (Grübler count, mobility, redundant rows, rank).

use quote::ToTokens;
use symbody_codegen::assembly::{assemble, Assembly};
use symbody_codegen::equations::{build, System};
use symbody_codegen::expr::Var;
use symbody_codegen::model::load;
use symbody_codegen::{generate, Diagnostic, Generated};

const FILE: &str = "mechanisms/pendulum.toml";

/// A quaternion rod hinged to the ground at the origin, its hinge point at local
/// (−0.5, 0, 0); `position` is where the file puts its centre of mass (0.5 m from the
/// hinge along x assembles exactly).
fn pendulum(position: &str) -> String {
    format!(
        r#"name = "pendulum"

[[body]]
name = "rod"
mass = 1.0
inertia = [0.001, 0.1, 0.1]
position = {position}
angles = [0.0, 0.0, 0.3]

[[joint]]
name = "hinge"
type = "revolute"
body1 = "ground"
body2 = "rod"
point1 = [0.0, 0.0, 0.0]
point2 = [-0.5, 0.0, 0.0]
axis = [0.0, 0.0, 1.0]
"#
    )
}

/// The file's pose, the assembly and the equations, through the generator's own stages.
fn stages(text: &str) -> (Vec<f64>, Assembly, System) {
    let model = load(FILE, text).unwrap_or_else(|e| panic!("{e}"));
    let sys = build(&model);
    let asm = assemble(&model, &sys, FILE).unwrap_or_else(|e| panic!("{e}"));
    (model.q0(), asm, sys)
}

/// Largest |Φ(q, t = 0)|.
fn residual(sys: &System, q: &[f64]) -> f64 {
    let env = |v: Var| match v {
        Var::Q(i) => q[i as usize],
        _ => 0.0,
    };
    sys.arena
        .eval_many(&sys.phi, &env)
        .iter()
        .fold(0.0, |m, x| f64::max(m, x.abs()))
}

/// The generated module's `Q0` array, read back from its text.
fn generated_q0(code: &str) -> Vec<f64> {
    let file = syn::parse_file(code).expect("the generated module parses");
    let q0 = file
        .items
        .iter()
        .find_map(|item| match item {
            syn::Item::Static(s) if s.ident == "Q0" => Some(&*s.expr),
            _ => None,
        })
        .expect("the module defines Q0");
    let syn::Expr::Array(array) = q0 else {
        panic!("Q0 is not an array literal");
    };
    array
        .elems
        .iter()
        .map(|e| {
            // `0.5f64`, `0f64` or `-0.5f64`.
            let lit = e.to_token_stream().to_string().replace(' ', "");
            lit.trim_end_matches("f64")
                .parse::<f64>()
                .unwrap_or_else(|_| panic!("unexpected Q0 element `{lit}`"))
        })
        .collect()
}

fn generated(text: &str) -> Generated {
    generate(FILE, text).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn an_assembled_pose_is_taken_as_written() {
    // The hinge at the origin, the rod turned by 0.3 rad about z.
    let position = format!("[{}, {}, 0.0]", 0.5 * 0.3f64.cos(), 0.5 * 0.3f64.sin());
    let text = pendulum(&position);
    let g = generated(&text);
    assert!(g.report.warnings.is_empty(), "{}", g.report);
    let (q_file, asm, sys) = stages(&text);
    assert!(residual(&sys, &asm.q0) <= 1e-12);
    assert_eq!(generated_q0(&g.code), asm.q0);
    let moved = q_file
        .iter()
        .zip(&asm.q0)
        .fold(0.0, |m, (a, b)| f64::max(m, (a - b).abs()));
    assert!(moved <= 1e-15, "moved by {moved:e}");
}

/// `text` with `repair_initial_pose = true` at the top level.
fn repairing(text: &str) -> String {
    text.replacen('\n', "\nrepair_initial_pose = true\n", 1)
}

#[test]
fn a_violated_joint_is_corrected_with_a_warning_when_the_file_allows_it() {
    // 0.3 m too far out along the rod: the hinge is violated by 0.3 m.
    let (c, s) = (0.3f64.cos(), 0.3f64.sin());
    let position = format!("[{}, {}, 0.0]", 0.8 * c, 0.8 * s);
    let text = repairing(&pendulum(&position));
    let g = generated(&text);
    let (q_file, asm, sys) = stages(&text);
    assert_eq!(g.report, asm.report);

    assert_eq!(g.report.warnings.len(), 1, "{}", g.report);
    let w = &g.report.warnings[0];
    // The joint, the size of the violation, and the correction actually made.
    let violation = (0.3 * c).abs().max((0.3 * s).abs());
    let moved = q_file
        .iter()
        .zip(&asm.q0)
        .fold(0.0, |m, (a, b)| f64::max(m, (a - b).abs()));
    assert!(w.contains("joint `hinge`"), "{w}");
    assert!(w.contains(&format!("by {violation:.3e}")), "{w}");
    assert!(w.contains(&format!("by up to {moved:.3e}")), "{w}");
    assert!(moved > 0.1 && moved < 0.4, "moved by {moved}");
    assert!(g.report.to_string().contains(&format!("warning: {w}")));

    // The assembled pose satisfies every row (the hinge and the quaternion norm), and it
    // is what the generated module starts from.
    assert!(residual(&sys, &q_file) > 0.2);
    assert!(
        residual(&sys, &asm.q0) <= 1e-12,
        "{:e}",
        residual(&sys, &asm.q0)
    );
    let q0 = generated_q0(&g.code);
    assert_eq!(q0, asm.q0);
    assert!(residual(&sys, &q0) <= 1e-12);
}

/// The single error of a pose violated beyond the modelling tolerance, checked to name
/// `item` with the line of its name, the gap `gap` and the way out.
fn modelling_error(text: &str, item: &str, name: &str, gap: &str) -> Diagnostic {
    let errs = generate(FILE, text).expect_err("the violation is a modelling error");
    assert_eq!(errs.0.len(), 1, "{errs}");
    let d = errs.0[0].clone();
    let shown = d.to_string();
    assert_eq!(d.item, item, "{shown}");
    assert_eq!(
        d.line,
        line_of(text, &format!("name = \"{name}\"")),
        "{shown}"
    );
    assert!(
        d.message.contains(&format!("violates {item} by {gap}")),
        "{shown}"
    );
    assert!(d.message.contains("modelling tolerance"), "{shown}");
    assert!(d.help.contains("repair_initial_pose = true"), "{shown}");
    d
}

/// A rod hung from the ground by a spherical joint at its end, whose point on the rod is
/// `gap` metres further along the rod (x) than the ground point the file puts it at.
fn ball_pendulum(gap: f64) -> String {
    format!(
        r#"name = "ball_pendulum"

[[body]]
name = "rod"
mass = 1.0
inertia = [0.001, 0.1, 0.1]
position = [0.5, 0.0, 0.0]

[[joint]]
name = "ball"
type = "spherical"
body1 = "ground"
body2 = "rod"
point1 = [0.0, 0.0, 0.0]
point2 = [{}, 0.0, 0.0]
"#,
        -0.5 + gap
    )
}

#[test]
fn a_joint_one_metre_apart_is_an_error_not_a_repair() {
    // The ball's two points are 1 m apart on a mechanism 1 m across (the ground point at 0,
    // the rod's centre at 0.5, its ball point at 1.0 m): a modelling error, which the
    // generator used to hide by moving the rod 1 m with a warning.
    let text = ball_pendulum(1.0);
    let d = modelling_error(&text, "joint `ball`", "ball", "1.000 m");
    assert!(d.message.contains("(row `ball.x`)"), "{d}");
    // 1e-3 of the size, 1 m across the points' box.
    assert!(d.message.contains("tolerance of 0.001000 m"), "{d}");
    assert!(d.message.contains("size, 1.000 m"), "{d}");

    // Allowed by the file: assembled with the warning, the rod moved by about 1 m.
    let g = generated(&repairing(&text));
    assert_eq!(g.report.warnings.len(), 1, "{}", g.report);
    let w = &g.report.warnings[0];
    assert!(w.contains("joint `ball` by 1.000e0"), "{w}");
    let (q_file, asm, sys) = stages(&repairing(&text));
    assert!(residual(&sys, &asm.q0) <= 1e-12);
    let moved = q_file
        .iter()
        .zip(&asm.q0)
        .fold(0.0, |m, (a, b)| f64::max(m, (a - b).abs()));
    assert!(moved > 0.5, "moved by {moved}");
}

#[test]
fn a_violation_below_the_modelling_tolerance_stays_a_warning() {
    // 0.5 mm on a mechanism 0.5 m across (tolerance 0.5 mm) is just under; 0.6 mm is over.
    let g = generated(&ball_pendulum(0.00049));
    assert_eq!(g.report.warnings.len(), 1, "{}", g.report);
    assert!(
        g.report.warnings[0].contains("joint `ball`"),
        "{}",
        g.report
    );
    modelling_error(
        &ball_pendulum(0.0006),
        "joint `ball`",
        "ball",
        "0.0006000 m",
    );
}

#[test]
fn a_misaligned_axis_is_an_error_giving_the_angle() {
    // The hinge's axis on the rod is tilted by 0.1 rad from the ground's: the joint's points
    // coincide but the axes do not: sin 0.1 across the mechanism's 0.5 m.
    let text = pendulum("[0.5, 0.0, 0.0]").replace(
        "axis = [0.0, 0.0, 1.0]",
        &format!(
            "axis1 = [0.0, 0.0, 1.0]\naxis2 = [0.0, {}, {}]",
            0.1f64.sin(),
            0.1f64.cos()
        ),
    );
    let text = text.replace("angles = [0.0, 0.0, 0.3]", "angles = [0.0, 0.0, 0.0]");
    let d = modelling_error(&text, "joint `hinge`", "hinge", "9.983e-2 rad of its axes");
    assert!(d.message.contains("a gap of 0.04992 m"), "{d}");
}

#[test]
fn a_pose_off_by_rounding_is_corrected_silently() {
    let (c, s) = (0.3f64.cos(), 0.3f64.sin());
    let position = format!("[{}, {}, 0.0]", (0.5 + 1e-9) * c, (0.5 + 1e-9) * s);
    let text = pendulum(&position);
    let g = generated(&text);
    assert!(g.report.warnings.is_empty(), "{}", g.report);
    let (q_file, asm, sys) = stages(&text);
    assert!(residual(&sys, &q_file) > 5e-10);
    assert!(
        residual(&sys, &asm.q0) <= 1e-12,
        "{:e}",
        residual(&sys, &asm.q0)
    );
    let moved = q_file
        .iter()
        .zip(&asm.q0)
        .fold(0.0, |m, (a, b)| f64::max(m, (a - b).abs()));
    assert!(moved < 1e-8, "moved by {moved:e}");
    assert_eq!(generated_q0(&g.code), asm.q0);
}

fn line_of(text: &str, needle: &str) -> usize {
    text.lines()
        .position(|l| l.contains(needle))
        .unwrap_or_else(|| panic!("`{needle}` not in the test file"))
        + 1
}

/// The single error of an impossible assembly, checked to name the rows in `rows` and one
/// of `joints` (with the line of its name).
fn assembly_error(text: &str, rows: &[&str], joints: &[&str]) -> Diagnostic {
    let errs = generate(FILE, text).expect_err("the mechanism cannot be assembled");
    assert_eq!(errs.0.len(), 1, "{errs}");
    let d = errs.0[0].clone();
    let shown = d.to_string();
    assert_eq!(d.file, FILE, "{shown}");
    assert!(d.message.contains("cannot be assembled"), "{shown}");
    for r in rows {
        assert!(d.message.contains(&format!("`{r}`")), "row {r}: {shown}");
    }
    let joint = joints
        .iter()
        .find(|j| d.item == format!("joint `{j}`"))
        .unwrap_or_else(|| panic!("expected one of the joints {joints:?}: {shown}"));
    let line = line_of(text, &format!("name = \"{joint}\""));
    assert_eq!(d.line, line, "{shown}");
    assert!(shown.contains(&format!("{FILE}:{line}:")), "{shown}");
    assert!(d.help.contains("check these joints' points"), "{shown}");
    d
}

#[test]
fn a_body_pinned_at_two_points_too_far_apart_is_an_error() {
    // The rod's ends are 1 m apart; the ground points they are pinned to are 2 m apart.
    let text = r#"name = "stretched"

[[body]]
name = "rod"
mass = 1.0
inertia = [0.001, 0.1, 0.1]
position = [0.0, 0.0, 0.0]

[[joint]]
name = "left"
type = "spherical"
body1 = "ground"
body2 = "rod"
point1 = [-1.0, 0.0, 0.0]
point2 = [-0.5, 0.0, 0.0]

[[joint]]
name = "right"
type = "spherical"
body1 = "ground"
body2 = "rod"
point1 = [1.0, 0.0, 0.0]
point2 = [0.5, 0.0, 0.0]
"#;
    // The quaternion's norm row is off too (the least-squares compromise stretches the
    // rod), but a joint is blamed; the row is named by its body, not by the generated
    // `rod.norm` no file contains.
    let d = assembly_error(text, &["left.x", "right.x"], &["left", "right"]);
    assert!(
        d.message
            .contains("the unit-quaternion condition of body `rod`")
            && !d.message.contains("rod.norm"),
        "{d}"
    );
}

#[test]
fn a_distance_joint_longer_than_the_fixed_points_is_an_error() {
    let text = r#"name = "too_long"

[[body]]
name = "block"
mass = 1.0
inertia = [0.1, 0.1, 0.1]
position = [0.0, 0.0, 0.0]

[[joint]]
name = "weld"
type = "fixed"
body1 = "ground"
body2 = "block"
at = [0.0, 0.0, 0.0]

[[joint]]
name = "tie"
type = "distance"
body1 = "ground"
body2 = "block"
at1 = [1.0, 0.0, 0.0]
at2 = [0.0, 0.0, 0.0]
length = 2.0
"#;
    assembly_error(text, &["tie.distance"], &["weld", "tie"]);
}

#[test]
fn a_driver_value_out_of_reach_is_an_error_naming_the_driver() {
    // The rod's free end is 1 m from the hinge; the driver asks for 3 m.
    let (c, s) = (0.3f64.cos(), 0.3f64.sin());
    let text = format!(
        "{}\n[[driver]]\nname = \"reach\"\nbody1 = \"ground\"\nbody2 = \"rod\"\nat1 = [0.0, 0.0, 0.0]\nat2 = [{c}, {s}, 0.0]\nvalue = \"3.0\"\n",
        pendulum(&format!("[{}, {}, 0.0]", 0.5 * c, 0.5 * s))
    );
    let errs = generate(FILE, &text).expect_err("the driver cannot be met");
    assert_eq!(errs.0.len(), 1, "{errs}");
    let d = &errs.0[0];
    assert_eq!(d.item, "driver `reach`", "{d}");
    assert_eq!(d.line, line_of(&text, "name = \"reach\""), "{d}");
    assert!(d.message.contains("`reach`"), "{d}");
}

fn workspace_file(name: &str) -> (String, String) {
    let rel = format!("mechanisms/{name}.toml");
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join(&rel);
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    (rel, text)
}

#[test]
fn four_bar_report() {
    let (rel, text) = workspace_file("four_bar");
    let r = generate(&rel, &text)
        .unwrap_or_else(|e| panic!("{e}"))
        .report;
    // 3 moving bodies, 4 revolute joints of 5 rows: 18 − 20.
    assert_eq!(r.grubler, -2, "{r}");
    assert_eq!(r.mobility, 1, "{r}");
    // A planar loop of spatial revolute joints: three rows depend on the others.
    assert_eq!(r.redundant.len(), 3, "{r}");
    assert!(r.redundant.iter().all(|(_, n)| n != "motor"), "{r}");
    assert_eq!(r.dof, 0, "{r}");
    assert!(r.warnings.is_empty(), "{r}");
}

#[test]
fn bricard_report() {
    let (rel, text) = workspace_file("bricard");
    let r = generate(&rel, &text)
        .unwrap_or_else(|e| panic!("{e}"))
        .report;
    // 5 bodies, 6 revolute joints: 30 − 30, yet the loop moves.
    assert_eq!(r.grubler, 0, "{r}");
    assert_eq!(r.mobility, 1, "{r}");
    assert_eq!(r.redundant.len(), 1, "{r}");
    assert_eq!(r.dof, 1, "{r}");
    assert!(r.warnings.is_empty(), "{r}");
}

#[test]
fn stewart_report() {
    let (rel, text) = workspace_file("stewart_6_6");
    let r = generate(&rel, &text)
        .unwrap_or_else(|e| panic!("{e}"))
        .report;
    assert_eq!(r.n_bodies, 13, "{r}");
    assert_eq!(r.n_coords, 78, "{r}");
    assert_eq!(r.n_rows, 72, "{r}");
    assert_eq!(r.rank, 72, "{r}");
    assert!(r.redundant.is_empty(), "{r}");
    assert!(r.warnings.is_empty(), "{r}");
}
