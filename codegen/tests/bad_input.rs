//! Bad mechanism files: each kind of mistake gives an error naming the file, the line,
//! the item, and a fix — never a panic.

use symbody_codegen::{generate, Diagnostic};

/// A small valid mechanism: a slider-crank-like pair of bodies on a prismatic joint,
/// hung from the ground by a spherical joint, with one driver.
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
angles = [0.0, 0.0, 0.0]

[[body]]
name = "upper"
mass = 0.5
inertia = [0.005, 0.0005, 0.005]
position = [0.0, 0.3, 0.0]
angles = [0.0, 0.0, 0.0]

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
axis = [0.0, 1.0, 0.0]

[[driver]]
name = "act"
joint = "slide"
value = "initial + amp * sin(t)"
"#;

fn line_of(text: &str, needle: &str) -> usize {
    text.lines()
        .position(|l| l.contains(needle))
        .unwrap_or_else(|| panic!("`{needle}` not in the test file"))
        + 1
}

/// Replaces `from` by `to` (exactly once) and returns the first diagnostic; with
/// `single`, it must be the only one.
fn first_error(from: &str, to: &str, single: bool) -> (String, Diagnostic) {
    assert_eq!(GOOD.matches(from).count(), 1, "`{from}` must occur once");
    let text = GOOD.replacen(from, to, 1);
    let errs = generate("mechanisms/pair.toml", &text).expect_err("the file is invalid");
    assert!(
        !single || errs.0.len() == 1,
        "expected one error, got:\n{errs}"
    );
    (text, errs.0[0].clone())
}

fn single_error(from: &str, to: &str) -> (String, Diagnostic) {
    first_error(from, to, true)
}

fn check(d: &Diagnostic, line: usize, item: &str, message_has: &str, help_has: &str) {
    let shown = d.to_string();
    assert_eq!(d.file, "mechanisms/pair.toml", "{shown}");
    assert_eq!(d.line, line, "{shown}");
    assert_eq!(d.item, item, "{shown}");
    assert!(d.message.contains(message_has), "{shown}");
    assert!(d.help.contains(help_has), "{shown}");
    assert!(
        shown.contains(&format!("mechanisms/pair.toml:{line}:")),
        "{shown}"
    );
}

#[test]
fn the_good_file_generates() {
    let code = generate("mechanisms/pair.toml", GOOD).unwrap_or_else(|e| panic!("{e}"));
    assert!(code.contains("pub struct Exact"));
}

#[test]
fn unknown_body() {
    let (text, d) = single_error(r#"body2 = "upper""#, r#"body2 = "uper""#);
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
        line_of(&text, "value ="),
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
        line_of(&text, "value ="),
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
fn missing_field() {
    let (text, d) = single_error("mass = 0.5\n", "");
    // Reported at the start of the [[body]] table that lacks it.
    let line = text
        .lines()
        .enumerate()
        .filter(|(_, l)| l.contains("[[body]]"))
        .nth(1)
        .unwrap()
        .0
        + 1;
    assert!(d.line == line || d.line == line + 1, "{d}");
    assert_eq!(d.item, "body `upper`", "{d}");
    assert!(d.message.contains("missing `mass`"), "{d}");
    assert!(d.help.contains("mass = <value in kg>"), "{d}");
}

#[test]
fn misspelt_field() {
    let (text, d) = single_error("mass = 0.5\n", "mas = 0.5\n");
    check(
        &d,
        line_of(&text, "mas = 0.5"),
        "the file",
        "unknown field `mas`",
        "check the spelling",
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
        "not prismatic",
        "prismatic joint's axis",
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
