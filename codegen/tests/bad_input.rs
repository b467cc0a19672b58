//! Bad mechanism files: each kind of mistake gives an error naming the file, the line,
//! the item, and a fix — never a panic.

use symbody_codegen::{generate, Diagnostic};

/// A small valid mechanism with one item of each kind: a body hung from the ground by a
/// spherical joint, a second body sliding on it (general prismatic joint), an arm hinged
/// to that one (revolute), a driver, and each type of force element. Bodies use the
/// default rotation coordinates (quaternions) except where they say otherwise.
const GOOD: &str = r#"name = "pair"
formulations = ["exact"]

[parameters]
half = 0.1
amp = 0.02

[[body]]
name = "lower"
mass = 1.0
inertia = [0.01, 0.001, 0.01]
position = [0.0, 0.1, 0.0]
quaternion = [1.0, 0.0, 0.0, 0.0]

[[body]]
name = "upper"
mass = 0.5
inertia = [0.005, 0.0005, 0.005]
position = [0.0, 0.3, 0.0]
angles = [0.0, 0.0, 0.0]

[[body]]
name = "arm"
rotation = "quaternion"
mass = 0.2
inertia = [0.0001, 0.002, 0.002]
position = [0.1, 0.4, 0.0]

[[joint]]
name = "base"
type = "spherical"
body1 = "ground"
point1 = [0.0, 0.0, 0.0]
body2 = "lower"
point2 = [0.0, "-half", 0.0]

[[joint]]
name = "slide"
type = "prismatic"
body1 = "lower"
body2 = "upper"
at = [0.0, 0.2, 0.0]
axis = [0.0, 1.0, 0.0]

[[joint]]
name = "hinge"
type = "revolute"
body1 = "upper"
body2 = "arm"
at = [0.0, 0.4, 0.0]
axis = [0.0, 0.0, 1.0]
reference = [1.0, 0.0, 0.0]

[[driver]]
name = "act"
joint = "slide"
value = "initial + amp * sin(t)"

[[force]]
name = "coil"
type = "spring"
body1 = "ground"
body2 = "upper"
at1 = [0.2, 0.3, 0.0]
at2 = [0.0, 0.3, 0.0]
stiffness = 100.0
damping = 1.0

[[force]]
name = "twist"
type = "torsion"
joint = "hinge"
stiffness = 2.0

[[force]]
name = "push"
type = "force"
body = "arm"
point = [0.1, 0.0, 0.0]
value = [0.0, "-sin(t)", 0.0]
axes = "body"

[[force]]
name = "turn"
type = "torque"
body = "lower"
value = [0.0, 0.1, 0.0]
"#;

const FILE: &str = "mechanisms/pair.toml";

/// 1-based line of the first line containing `needle`.
fn line_of(text: &str, needle: &str) -> usize {
    text.lines()
        .position(|l| l.contains(needle))
        .unwrap_or_else(|| panic!("`{needle}` not in the test file"))
        + 1
}

/// 1-based line of the `[[...]]` header of the table whose line contains `needle`
/// (errors about a whole item point there).
fn header_of(text: &str, needle: &str) -> usize {
    let at = line_of(text, needle);
    text.lines()
        .take(at)
        .enumerate()
        .filter(|(_, l)| l.starts_with("[["))
        .last()
        .unwrap_or_else(|| panic!("no table header before `{needle}`"))
        .0
        + 1
}

/// GOOD with each `from` (which must occur exactly once) replaced by its `to`.
fn mutated(edits: &[(&str, &str)]) -> String {
    let mut text = GOOD.to_string();
    for (from, to) in edits {
        assert_eq!(text.matches(from).count(), 1, "`{from}` must occur once");
        text = text.replacen(from, to, 1);
    }
    text
}

/// The first diagnostic of GOOD with `edits` applied; with `single`, it must be the only one.
fn error_of(edits: &[(&str, &str)], single: bool) -> (String, Diagnostic) {
    let text = mutated(edits);
    let errs = generate(FILE, &text).expect_err("the file is invalid");
    assert!(
        !single || errs.0.len() == 1,
        "expected one error, got:\n{errs}"
    );
    (text, errs.0[0].clone())
}

/// Replaces `from` by `to` (exactly once) and returns the first diagnostic; with
/// `single`, it must be the only one.
fn first_error(from: &str, to: &str, single: bool) -> (String, Diagnostic) {
    error_of(&[(from, to)], single)
}

fn single_error(from: &str, to: &str) -> (String, Diagnostic) {
    first_error(from, to, true)
}

fn check(d: &Diagnostic, line: usize, item: &str, message_has: &str, help_has: &str) {
    let shown = d.to_string();
    assert_eq!(d.file, FILE, "{shown}");
    assert_eq!(d.line, line, "{shown}");
    assert_eq!(d.item, item, "{shown}");
    assert!(d.message.contains(message_has), "{shown}");
    assert!(d.help.contains(help_has), "{shown}");
    assert!(shown.contains(&format!("{FILE}:{line}:")), "{shown}");
    assert!(shown.contains(&format!("in {item}")), "{shown}");
}

#[test]
fn the_good_file_generates() {
    let g = generate(FILE, GOOD).unwrap_or_else(|e| panic!("{e}"));
    assert!(g.code.contains("pub struct Exact"));
    assert!(g.report.warnings.is_empty(), "{}", g.report);
    // 3 quaternion bodies; spherical 3 + prismatic 5 + revolute 5 rows, a driver and
    // three normalization rows.
    assert_eq!(g.report.n_coords, 21, "{}", g.report);
    assert_eq!(g.report.n_rows, 17, "{}", g.report);
    assert_eq!(g.report.rank, 17, "{}", g.report);
}

#[test]
fn unknown_body() {
    let (text, d) = single_error(
        "body2 = \"upper\"\nat = [0.0, 0.2, 0.0]",
        "body2 = \"uper\"\nat = [0.0, 0.2, 0.0]",
    );
    check(
        &d,
        line_of(&text, "\"uper\""),
        "joint `slide`",
        "unknown body `uper`",
        "did you mean `upper`?",
    );
}

#[test]
fn unknown_joint() {
    let (text, d) = single_error(r#"joint = "slide""#, r#"joint = "slid""#);
    check(
        &d,
        line_of(&text, "\"slid\""),
        "driver `act`",
        "unknown joint `slid`",
        "did you mean `slide`?",
    );
}

#[test]
fn duplicate_name() {
    // Renaming `upper` also leaves the joints' references to it dangling: a second error.
    let (text, d) = first_error(r#"name = "upper""#, r#"name = "lower""#, false);
    // The second `lower` is the duplicate.
    let line = text
        .lines()
        .enumerate()
        .filter(|(_, l)| l.contains(r#"name = "lower""#))
        .nth(1)
        .unwrap()
        .0
        + 1;
    let first = format!(
        "first `lower` is on line {}",
        line_of(&text, r#"name = "lower""#)
    );
    check(&d, line, "body `lower`", "duplicate name `lower`", &first);
}

#[test]
fn malformed_expression() {
    let (text, d) = single_error("initial + amp * sin(t)", "initial + amp * (sin(t)");
    check(
        &d,
        line_of(&text, "value = \"initial"),
        "driver `act`",
        "malformed expression `initial + amp * (sin(t)`",
        "Rust arithmetic expression",
    );
}

#[test]
fn unsupported_syntax() {
    let (text, d) = single_error("initial + amp * sin(t)", "initial + amp * sin(t) > 0.0");
    check(
        &d,
        line_of(&text, "value = \"initial"),
        "driver `act`",
        "unsupported syntax",
        "only + - * /",
    );
}

#[test]
fn unknown_function() {
    let (text, d) = single_error("amp * sin(t)", "amp * sinn(t)");
    check(
        &d,
        line_of(&text, "sinn"),
        "driver `act`",
        "unknown function `sinn`",
        "known functions: sin",
    );
}

#[test]
fn unknown_name_in_parameter_expression() {
    let (text, d) = single_error(
        r#"point2 = [0.0, "-half", 0.0]"#,
        r#"point2 = [0.0, "-hlf", 0.0]"#,
    );
    check(
        &d,
        line_of(&text, "-hlf"),
        "joint `base`",
        "unknown name `hlf`",
        "did you mean `half`?",
    );
}

#[test]
fn wrong_vector_length() {
    let (text, d) = single_error(
        "inertia = [0.005, 0.0005, 0.005]",
        "inertia = [0.005, 0.0005]",
    );
    check(
        &d,
        line_of(&text, "inertia = [0.005, 0.0005]"),
        "body `upper`",
        "`inertia` has 2 components, expected 3",
        "inertia = [x, y, z]",
    );
}

#[test]
fn impossible_inertias_are_an_error_naming_the_inequality() {
    // Izz = 0.006 exceeds Ixx + Iyy = 0.0055: no distribution of mass has these.
    let (text, d) = single_error(
        "inertia = [0.005, 0.0005, 0.005]",
        "inertia = [0.005, 0.0005, 0.006]",
    );
    check(
        &d,
        line_of(&text, "inertia = [0.005, 0.0005, 0.006]"),
        "body `upper`",
        "impossible principal inertias: Izz = 0.006 > Ixx + Iyy = 0.0055",
        "at most the sum of the other two",
    );
    // Each axis is checked, and the names follow the file's order.
    let (_, d) = single_error(
        "inertia = [0.0001, 0.002, 0.002]",
        "inertia = [0.0001, 0.002, 0.0001]",
    );
    assert_eq!(d.item, "body `arm`", "{d}");
    assert!(
        d.message.contains("Iyy = 0.002 > Ixx + Izz = 0.0002"),
        "{d}"
    );
}

#[test]
fn a_flat_plate_and_roundoff_are_possible_inertias() {
    // Izz = Ixx + Iyy exactly (a thin plate), and a plate whose Izz computed in one
    // expression exceeds the sum of the other two by roundoff (2e-19).
    for inertia in [
        "inertia = [0.005, 0.0005, 0.0055]",
        "inertia = [\"0.3 * 0.1 * 0.1 / 12.0\", \"0.3 * 0.2 * 0.2 / 12.0\", \"0.3 * (0.1 * 0.1 + 0.2 * 0.2) / 12.0\"]",
    ] {
        let text = mutated(&[("inertia = [0.005, 0.0005, 0.005]", inertia)]);
        generate(FILE, &text).unwrap_or_else(|e| panic!("{inertia}: {e}"));
    }
}

#[test]
fn negative_inertia_and_mass_are_errors() {
    let (text, d) = single_error(
        "inertia = [0.005, 0.0005, 0.005]",
        "inertia = [0.005, -0.0005, 0.005]",
    );
    check(
        &d,
        line_of(&text, "inertia = [0.005, -0.0005"),
        "body `upper`",
        "inertias must not be negative",
        "principal inertias",
    );
    for mass in ["mass = 0.0\n", "mass = -0.5\n"] {
        let (text, d) = single_error("mass = 0.5\n", mass);
        check(
            &d,
            line_of(&text, mass.trim()),
            "body `upper`",
            "mass must be positive",
            "mass in kg",
        );
    }
}

#[test]
fn missing_field() {
    let (text, d) = single_error("mass = 0.5\n", "");
    // Reported at the start of the [[body]] table that lacks it.
    check(
        &d,
        header_of(&text, r#"name = "upper""#),
        "body `upper`",
        "missing `mass`",
        "mass = <value in kg>",
    );
}

#[test]
fn misspelt_field() {
    let (text, d) = single_error("mass = 0.5\n", "mas = 0.5\n");
    check(
        &d,
        line_of(&text, "mas = 0.5"),
        "the file",
        "unknown field `mas`",
        "did you mean `mass`?",
    );
}

#[test]
fn misspelt_force_type_and_function_suggest_the_closest() {
    let (text, d) = single_error(r#"type = "spring""#, r#"type = "sprng""#);
    check(
        &d,
        line_of(&text, "sprng"),
        "force `coil`",
        "unknown force type `sprng`",
        "did you mean \"spring\"?",
    );
    let (text, d) = single_error("amp * sin(t)", "amp * sinn(t) + amp2");
    // One cause, one error: the unknown function, not also the unknown name after it.
    check(
        &d,
        line_of(&text, "sinn"),
        "driver `act`",
        "unknown function `sinn`",
        "did you mean `sin`?",
    );
}

#[test]
fn toml_syntax_error() {
    let (text, d) = single_error("amp = 0.02", "amp = = 0.02");
    check(&d, line_of(&text, "amp = ="), "the file", "", "TOML syntax");
}

#[test]
fn driver_on_a_spherical_joint() {
    let (text, d) = single_error(r#"joint = "slide""#, r#"joint = "base""#);
    check(
        &d,
        line_of(&text, r#"joint = "base""#),
        "driver `act`",
        "joint `base` is spherical and has no coordinate to drive",
        "drivers act on revolute (angle), prismatic (distance) and cylindrical joints",
    );
}

#[test]
fn reserved_ground_name() {
    let (text, d) = first_error(r#"name = "upper""#, r#"name = "ground""#, false);
    check(
        &d,
        line_of(&text, r#"name = "ground""#),
        "body `ground`",
        "duplicate name `ground`",
        "reserved",
    );
}

#[test]
fn non_finite_numbers_are_rejected() {
    let (text, d) = single_error("amp = 0.02", "amp = nan");
    check(
        &d,
        line_of(&text, "amp = nan"),
        "parameter `amp`",
        "`amp` is NaN",
        "finite number",
    );
    let (text, d) = single_error(
        "value = \"initial + amp * sin(t)\"",
        "value = \"initial + amp / 0.0 * sin(t)\"",
    );
    check(
        &d,
        line_of(&text, "value = \"initial"),
        "driver `act`",
        "infinite or NaN constant",
        "division by zero",
    );
}

#[test]
fn overflowing_constants_and_huge_powers_are_rejected() {
    let (text, d) = single_error(
        "initial + amp * sin(t)",
        "initial + amp * sin(t) + 1.0 / (t + 1e400)",
    );
    check(
        &d,
        line_of(&text, "value = \"initial"),
        "driver `act`",
        "out of the range of f64",
        "1.8e308",
    );
    let (text, d) = single_error(
        "initial + amp * sin(t)",
        "initial + amp * sin(t) + 1e300 * 1e300 * t",
    );
    check(
        &d,
        line_of(&text, "value = \"initial"),
        "driver `act`",
        "infinite or NaN constant",
        "overflow",
    );
    let (text, d) = single_error(
        "initial + amp * sin(t)",
        "initial + amp * powi(t + 1.0, -2147483647)",
    );
    check(
        &d,
        line_of(&text, "value = \"initial"),
        "driver `act`",
        "within ±64",
        "powi(x, 2)",
    );
}

#[test]
fn duplicate_formulation_is_rejected() {
    let (text, d) = single_error(
        r#"formulations = ["exact"]"#,
        r#"formulations = ["exact", "exact"]"#,
    );
    check(
        &d,
        line_of(&text, "formulations"),
        "`formulations`",
        "listed twice",
        "once",
    );
}

#[test]
fn keyword_mechanism_name_is_rejected() {
    let (text, d) = single_error(r#"name = "pair""#, r#"name = "mod""#);
    check(
        &d,
        line_of(&text, r#"name = "mod""#),
        "the file",
        "Rust keyword",
        "lowercase letters",
    );
}

// ------------------------------------------------------------------ bodies

#[test]
fn unknown_rotation_coordinates() {
    let (text, d) = single_error(r#"rotation = "quaternion""#, r#"rotation = "quaternions""#);
    check(
        &d,
        line_of(&text, "quaternions"),
        "body `arm`",
        "unknown rotation coordinates `quaternions`",
        "use \"quaternion\"",
    );
    // The file-wide default too.
    let (text, d) = single_error(
        "formulations = [\"exact\"]\n",
        "formulations = [\"exact\"]\nrotation = \"eular\"\n",
    );
    check(
        &d,
        line_of(&text, "eular"),
        "the file",
        "unknown rotation coordinates `eular`",
        "or \"euler\"",
    );
}

#[test]
fn quaternion_with_three_components() {
    let (text, d) = single_error(
        "quaternion = [1.0, 0.0, 0.0, 0.0]",
        "quaternion = [1.0, 0.0, 0.0]",
    );
    check(
        &d,
        line_of(&text, "quaternion = [1.0, 0.0, 0.0]"),
        "body `lower`",
        "`quaternion` has 3 components, expected 4",
        "write `quaternion = [w, x, y, z]`",
    );
}

#[test]
fn zero_quaternion() {
    let (text, d) = single_error(
        "quaternion = [1.0, 0.0, 0.0, 0.0]",
        "quaternion = [0.0, 0.0, 0.0, 0.0]",
    );
    check(
        &d,
        line_of(&text, "quaternion = [0.0"),
        "body `lower`",
        "`quaternion` is zero",
        "give a rotation, e.g. [1, 0, 0, 0]",
    );
}

#[test]
fn both_angles_and_quaternion() {
    let (text, d) = single_error(
        "quaternion = [1.0, 0.0, 0.0, 0.0]",
        "angles = [0.0, 0.0, 0.0]\nquaternion = [1.0, 0.0, 0.0, 0.0]",
    );
    check(
        &d,
        line_of(&text, "quaternion = [1.0"),
        "body `lower`",
        "has both `angles` and `quaternion`",
        "give the initial orientation once",
    );
}

// ------------------------------------------------------------------ joints

#[test]
fn unknown_joint_type() {
    let (text, d) = single_error(r#"type = "revolute""#, r#"type = "revolut""#);
    check(
        &d,
        line_of(&text, "revolut\""),
        "joint `hinge`",
        "unknown joint type `revolut`",
        "did you mean \"revolute\"?",
    );
}

#[test]
fn joint_without_a_point() {
    let (text, d) = single_error("at = [0.0, 0.4, 0.0]\n", "");
    check(
        &d,
        header_of(&text, r#"name = "hinge""#),
        "joint `hinge`",
        "has no joint point",
        "give the joint point as `at = [x, y, z]`",
    );
}

#[test]
fn joint_point_given_twice() {
    let (text, d) = single_error(
        "at = [0.0, 0.4, 0.0]",
        "at = [0.0, 0.4, 0.0]\npoint1 = [0.0, 0.1, 0.0]",
    );
    check(
        &d,
        line_of(&text, "at = [0.0, 0.4, 0.0]"),
        "joint `hinge`",
        "the joint point is given in more than one way",
        "give the joint point as `at = [x, y, z]` (global, at the initial pose) or as `point1`, `point2`",
    );
}

#[test]
fn axis_on_a_spherical_joint() {
    let (text, d) = single_error(
        "point1 = [0.0, 0.0, 0.0]",
        "point1 = [0.0, 0.0, 0.0]\naxis = [0.0, 0.0, 1.0]",
    );
    check(
        &d,
        line_of(&text, "point1 = [0.0, 0.0, 0.0]") + 1,
        "joint `base`",
        "a spherical joint has no axis, but `axis` is given",
        "remove the axis",
    );
}

#[test]
fn zero_axis() {
    let (text, d) = single_error("axis = [0.0, 0.0, 1.0]", "axis = [0.0, 0.0, 0.0]");
    check(
        &d,
        line_of(&text, "axis = [0.0, 0.0, 0.0]"),
        "joint `hinge`",
        "`axis` is the zero vector",
        "give `axis` a direction",
    );
}

#[test]
fn revolute_without_an_axis() {
    let (text, d) = single_error("axis = [0.0, 0.0, 1.0]\n", "");
    check(
        &d,
        header_of(&text, r#"name = "hinge""#),
        "joint `hinge`",
        "needs its axis on both bodies",
        "give `axis = [x, y, z]`",
    );
}

#[test]
fn universal_axes_not_perpendicular() {
    let (text, d) = error_of(
        &[
            (r#"type = "revolute""#, r#"type = "universal""#),
            (
                "reference = [1.0, 0.0, 0.0]",
                "cross_axis = [0.0, 1.0, 1.0]",
            ),
        ],
        true,
    );
    check(
        &d,
        line_of(&text, "cross_axis"),
        "joint `hinge`",
        "are not perpendicular at the initial pose",
        "cross axes are perpendicular: fix `cross_axis`",
    );
}

#[test]
fn reference_parallel_to_the_axis() {
    let (text, d) = single_error(
        "reference = [1.0, 0.0, 0.0]",
        "reference = [0.0, 0.0, -2.0]",
    );
    check(
        &d,
        line_of(&text, "reference ="),
        "joint `hinge`",
        "`reference` is parallel to the joint axis",
        "perpendicular to the axis",
    );
}

#[test]
fn local_references_parallel_to_the_axis() {
    // Used to give NaN joint frames (and a panic in assembly) instead of an error.
    let (text, d) = single_error(
        "axis = [0.0, 0.0, 1.0]\nreference = [1.0, 0.0, 0.0]",
        "axis1 = [0.0, 0.0, 1.0]\naxis2 = [0.0, 0.0, 1.0]\nreference1 = [0.0, 0.0, 3.0]",
    );
    check(
        &d,
        line_of(&text, "reference1"),
        "joint `hinge`",
        "`reference1` is parallel to the joint axis",
        "perpendicular to the axis",
    );
    // Used to be replaced silently by an arbitrary perpendicular.
    let (text, d) = single_error(
        "reference = [1.0, 0.0, 0.0]",
        "reference = [1.0, 0.0, 0.0]\nreference2 = [0.0, 0.0, 1.0]",
    );
    check(
        &d,
        line_of(&text, "reference2"),
        "joint `hinge`",
        "`reference2` is parallel to the joint axis",
        "perpendicular to the axis",
    );
}

#[test]
fn euler_prismatic_on_quaternion_bodies() {
    let (text, d) = single_error(r#"type = "prismatic""#, r#"type = "euler_prismatic""#);
    check(
        &d,
        header_of(&text, r#"name = "slide""#),
        "joint `slide`",
        "`euler_prismatic` equates Euler angles, but body `lower` uses quaternions",
        "give both bodies `rotation = \"euler\"`, or use `type = \"prismatic\"`",
    );
}

#[test]
fn paper_formulation_with_quaternion_bodies() {
    let (text, d) = single_error(
        r#"formulations = ["exact"]"#,
        r#"formulations = ["exact", "paper"]"#,
    );
    check(
        &d,
        line_of(&text, "formulations"),
        "`formulations`",
        "the `paper` formulation needs Euler-angle bodies, but body `lower` uses quaternion",
        "use `formulations = [\"exact\"]`, or `rotation = \"euler\"` for every body",
    );
}

#[test]
fn distance_joint_with_coincident_points_and_no_length() {
    // `base` joins the ground's origin to `lower`'s (0, −half, 0), which is the origin too.
    let (text, d) = single_error(r#"type = "spherical""#, r#"type = "distance""#);
    check(
        &d,
        header_of(&text, r#"name = "base""#),
        "joint `base`",
        "the two points of a distance joint coincide at the initial pose",
        "give two distinct points",
    );
}

#[test]
fn distance_joint_with_coincident_points_and_a_length() {
    // |p2 − p1| has no derivative there: used to panic in assembly (NaN Jacobian).
    let (text, d) = single_error(r#"type = "spherical""#, "type = \"distance\"\nlength = 0.5");
    check(
        &d,
        header_of(&text, r#"name = "base""#),
        "joint `base`",
        "the two points of a distance joint coincide at the initial pose",
        "give two distinct points",
    );
}

#[test]
fn placement_with_an_orientation() {
    // The placement orients the body; the file's angles used to be ignored silently.
    let (text, d) = single_error(
        "position = [0.0, 0.3, 0.0]\nangles = [0.0, 0.0, 0.0]",
        "placement = { from = \"slide\", to = \"hinge\", offset_from_end = 0.1 }\nangles = [0.0, 0.0, 0.0]",
    );
    check(
        &d,
        line_of(&text, "angles = [0.0, 0.0, 0.0]"),
        "body `upper`",
        "has both a `placement` and an initial orientation",
        "remove `angles`/`quaternion`",
    );
}

// ------------------------------------------------------------------ drivers

#[test]
fn driver_naming_a_joint_and_a_body() {
    let (text, d) = single_error(r#"joint = "slide""#, "joint = \"slide\"\nbody = \"upper\"");
    check(
        &d,
        header_of(&text, r#"name = "act""#),
        "driver `act`",
        "must name exactly one of `joint`, `body`, or `body1`/`body2`",
        "drive a joint coordinate (`joint`), a body coordinate (`body`, `coordinate`), or a point distance",
    );
}

#[test]
fn cylindrical_driver_without_coordinate() {
    let (text, d) = single_error(r#"type = "prismatic""#, r#"type = "cylindrical""#);
    check(
        &d,
        line_of(&text, r#"joint = "slide""#),
        "driver `act`",
        "joint `slide` is cylindrical: both its angle and its distance can be driven",
        "add `coordinate = \"angle\"` or `coordinate = \"distance\"`",
    );
}

#[test]
fn cylindrical_driver_with_an_unknown_coordinate() {
    let (text, d) = error_of(
        &[
            (r#"type = "prismatic""#, r#"type = "cylindrical""#),
            (
                r#"joint = "slide""#,
                "joint = \"slide\"\ncoordinate = \"sideways\"",
            ),
        ],
        true,
    );
    check(
        &d,
        line_of(&text, "sideways"),
        "driver `act`",
        "joint `slide` (cylindrical) has no coordinate `sideways`",
        // Both of a cylindrical joint's coordinates (the help used to offer the angle only).
        "use `coordinate = \"angle\"` or `coordinate = \"distance\"`",
    );
}

#[test]
fn driver_on_a_quaternion_rotation_coordinate() {
    let (text, d) = single_error(
        r#"joint = "slide""#,
        "body = \"upper\"\ncoordinate = \"theta\"",
    );
    check(
        &d,
        line_of(&text, r#"coordinate = "theta""#),
        "driver `act`",
        "body `upper` has no drivable coordinate `theta`",
        "use one of [\"x\", \"y\", \"z\"]; drive a rotation through a revolute joint's angle instead",
    );
}

#[test]
fn body_coordinate_driver_on_the_ground() {
    let (text, d) = single_error(
        r#"joint = "slide""#,
        "body = \"ground\"\ncoordinate = \"x\"",
    );
    check(
        &d,
        line_of(&text, r#"body = "ground""#),
        "driver `act`",
        "the ground has no coordinates to drive",
        "name a body",
    );
}

#[test]
fn point_distance_driver_with_coincident_points() {
    let (text, d) = single_error(
        r#"joint = "slide""#,
        "body1 = \"ground\"\nbody2 = \"upper\"\nat1 = [0.0, 0.3, 0.0]\nat2 = [0.0, 0.3, 0.0]",
    );
    check(
        &d,
        header_of(&text, r#"name = "act""#),
        "driver `act`",
        "the two points coincide at the initial pose",
        "use two distinct points",
    );
}

// ------------------------------------------------------------------ forces

#[test]
fn unknown_force_type() {
    let (text, d) = single_error(r#"type = "spring""#, r#"type = "sprung""#);
    check(
        &d,
        line_of(&text, "sprung"),
        "force `coil`",
        "unknown force type `sprung`",
        "supported types: \"spring\"",
    );
}

#[test]
fn spring_with_negative_stiffness() {
    let (text, d) = single_error("stiffness = 100.0", "stiffness = -100.0");
    check(
        &d,
        line_of(&text, "stiffness = -100.0"),
        "force `coil`",
        "`stiffness` must not be negative, got -100",
        "give `stiffness` a value ≥ 0",
    );
}

#[test]
fn torsion_on_a_prismatic_joint() {
    let (text, d) = single_error(r#"joint = "hinge""#, r#"joint = "slide""#);
    // The driver names `slide` too: the torsion's is the second.
    let line = text
        .lines()
        .enumerate()
        .filter(|(_, l)| l.contains(r#"joint = "slide""#))
        .nth(1)
        .unwrap()
        .0
        + 1;
    check(
        &d,
        line,
        "force `twist`",
        "joint `slide` is prismatic: it has no angle for a torsion spring",
        "act on a revolute or cylindrical joint",
    );
}

#[test]
fn applied_force_with_two_components() {
    let (text, d) = single_error(
        r#"value = [0.0, "-sin(t)", 0.0]"#,
        r#"value = [0.0, "-sin(t)"]"#,
    );
    check(
        &d,
        line_of(&text, r#"value = [0.0, "-sin(t)"]"#),
        "force `push`",
        "`value` has 2 components, expected 3",
        "write `value = [x, y, z]`",
    );
}

#[test]
fn torque_with_a_point() {
    let (text, d) = single_error(
        "value = [0.0, 0.1, 0.0]",
        "value = [0.0, 0.1, 0.0]\npoint = [0.1, 0.0, 0.0]",
    );
    check(
        &d,
        header_of(&text, r#"name = "turn""#),
        "force `turn`",
        "a torque has no point of application",
        "remove `point`/`at`",
    );
}

#[test]
fn unknown_axes() {
    let (text, d) = single_error(r#"axes = "body""#, r#"axes = "local""#);
    check(
        &d,
        line_of(&text, r#"axes = "local""#),
        "force `push`",
        "unknown axes `local`",
        "use \"global\" or \"body\"",
    );
}

#[test]
fn initial_outside_a_driver() {
    let (text, d) = single_error(r#""-sin(t)""#, r#""-initial * sin(t)""#);
    check(
        &d,
        line_of(&text, "initial * sin"),
        "force `push`",
        "unknown name `initial`",
        "`initial` is only defined for drivers",
    );
    let (text, d) = single_error("damping = 1.0", "damping = 1.0\nactuator = \"initial\"");
    check(
        &d,
        line_of(&text, "actuator"),
        "force `coil`",
        "unknown name `initial`",
        "`initial` is only defined for drivers",
    );
}

/// Generated code must parse, and name every item once per module.
fn assert_valid_module(code: &str, case: usize) {
    let file = syn::parse_file(code).unwrap_or_else(|e| panic!("case {case}: invalid Rust: {e}"));
    fn names(items: &[syn::Item], case: usize) {
        let mut seen = std::collections::HashSet::new();
        for item in items {
            let name = match item {
                syn::Item::Fn(f) => Some(f.sig.ident.to_string()),
                syn::Item::Struct(s) => Some(s.ident.to_string()),
                syn::Item::Static(s) => Some(s.ident.to_string()),
                syn::Item::Const(c) => Some(c.ident.to_string()),
                syn::Item::Type(t) => Some(t.ident.to_string()),
                syn::Item::Mod(m) => {
                    if let Some((_, inner)) = &m.content {
                        names(inner, case);
                    }
                    Some(m.ident.to_string())
                }
                _ => None,
            };
            if let Some(n) = name {
                assert!(seen.insert(n.clone()), "case {case}: `{n}` defined twice");
            }
        }
    }
    names(&file.items, case);
}

/// splitmix64, for reproducible mutations.
fn next(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

#[test]
fn random_mutations_never_panic() {
    // Delete, duplicate or corrupt lines and values; every outcome must be Ok or a
    // diagnostic, never a panic.
    const SNIPPETS: [&str; 12] = [
        "",
        "nan",
        "inf",
        "-1.0",
        "0.0",
        "[]",
        "[1, 2]",
        "\"x\"",
        "\"t * t\"",
        "= =",
        "[[body]]",
        "\"ground\"",
    ];
    let lines: Vec<&str> = GOOD.lines().collect();
    let mut state = 7u64;
    for case in 0..400 {
        let mut ls: Vec<String> = lines.iter().map(|s| s.to_string()).collect();
        for _ in 0..1 + next(&mut state) % 3 {
            let i = (next(&mut state) % ls.len() as u64) as usize;
            match next(&mut state) % 4 {
                0 => {
                    ls.remove(i);
                }
                1 => {
                    let l = ls[i].clone();
                    ls.insert(i, l);
                }
                2 => {
                    if let Some(eq) = ls[i].find('=') {
                        let snip = SNIPPETS[(next(&mut state) % SNIPPETS.len() as u64) as usize];
                        ls[i] = format!("{}= {snip}", &ls[i][..eq]);
                    }
                }
                _ => {
                    let l = &ls[i];
                    let cut = (next(&mut state) % (l.len() as u64 + 1)) as usize;
                    ls[i] = l.chars().take(cut).collect();
                }
            }
        }
        let text = ls.join("\n");
        let result = std::panic::catch_unwind(|| generate(FILE, &text));
        match result {
            Ok(Ok(g)) => assert_valid_module(&g.code, case),
            Ok(Err(e)) => {
                for d in &e.0 {
                    assert!(d.line >= 1 && !d.message.is_empty(), "case {case}: {d}");
                }
            }
            Err(_) => panic!("case {case} panicked on:\n{text}"),
        }
    }
}

#[test]
fn a_parameter_cycle_is_one_error_not_a_cascade() {
    // `half` is used by joint `base`: the cycle must not also surface there as a NaN or an
    // unknown name.
    let (text, d) = single_error(
        "half = 0.1\namp = 0.02",
        "half = \"amp\"\namp = \"2 * half\"",
    );
    assert!(d.message.contains("depends on itself"), "{d}");
    assert!(d.help.contains("break the cycle"), "{d}");
    assert!(
        d.line == line_of(&text, "half = \"amp\"") || d.line == line_of(&text, "amp = \"2"),
        "{d}"
    );
}

#[test]
fn numbers_whose_products_overflow_are_an_error_not_a_panic() {
    // Found by the structured fuzzer: a spring 1e300 long has ½kℓ² = ∞ in its potential, and
    // emitting that constant as a Rust literal panicked.
    let (_, d) = single_error("at2 = [0.0, 0.3, 0.0]", "at2 = [0.0, 1e300, 0.0]");
    assert!(d.message.contains("overflow f64"), "{d}");
    assert!(d.help.contains("1.8e308"), "{d}");
}
