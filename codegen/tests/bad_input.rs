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
        line_of(&text, "value ="),
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
        line_of(&text, "value ="),
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
        line_of(&text, "value ="),
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
        line_of(&text, "value ="),
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
        let result = std::panic::catch_unwind(|| generate("mechanisms/pair.toml", &text));
        match result {
            Ok(Ok(code)) => assert_valid_module(&code, case),
            Ok(Err(e)) => {
                for d in &e.0 {
                    assert!(d.line >= 1 && !d.message.is_empty(), "case {case}: {d}");
                }
            }
            Err(_) => panic!("case {case} panicked on:\n{text}"),
        }
    }
}
