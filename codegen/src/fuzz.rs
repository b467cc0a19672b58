//! Robustness fuzzing of the generator on stable Rust: mutations of real mechanism files
//! (byte edits, token insertions, line deletions, duplications and swaps, truncations) and
//! random structured files ([`structured`]: bodies, joints, drivers and loads of random kinds,
//! names and values, valid TOML) go through [`crate::model::load`], and those that load through
//! the rest of [`crate::generate`]; any panic is a failure. Used by the `fuzz` binary (10⁶ inputs) and by a seeded test that
//! runs a small share in CI.

use std::panic::{catch_unwind, AssertUnwindSafe};

/// Fragments that stress the parser and the validator: TOML structure, the schema's keys,
/// numbers at the edges of f64, expression syntax, and non-ASCII text.
const TOKENS: &[&str] = &[
    "[[body]]\n",
    "[[joint]]\n",
    "[[driver]]\n",
    "[[force]]\n",
    "[parameters]\n",
    " = ",
    "\"",
    "[",
    "]",
    "{",
    "}",
    ",",
    "\n",
    "#",
    "'''",
    "nan",
    "inf",
    "-inf",
    "1e308",
    "1e-320",
    "-0.0",
    "0",
    "1e999",
    "\"sqrt(-1.0)\"",
    "\"1.0 / 0.0\"",
    "\"x * \"",
    "\"(((\"",
    "\"t\"",
    "\"initial\"",
    "name = \"ground\"\n",
    "body1 = \"ground\"\n",
    "body2 = \"ground\"\n",
    "type = \"revolute\"\n",
    "type = \"distance\"\n",
    "type = \"universal\"\n",
    "rotation = \"euler\"\n",
    "mass = 0.0\n",
    "inertia = [0.0, 0.0, 0.0]\n",
    "axis = [0.0, 0.0, 0.0]\n",
    "at = [0.0, 0.0, 0.0]\n",
    "point1 = [1.0, 2.0]\n",
    "formulations = [\"paper\"]\n",
    "gravity = [0.0, \"g\", 0.0]\n",
    "t_end = -1.0\n",
    "é",
    "😀",
    "\u{0}",
];

/// A small deterministic generator (SplitMix64), so every input can be regenerated from its
/// seed and index.
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    pub fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n.max(1) as u64) as usize
    }
}

/// One to four random edits of `text`, always on character boundaries.
pub fn mutate(text: &str, rng: &mut Rng) -> String {
    let mut s = text.to_string();
    for _ in 0..1 + rng.below(4) {
        let lines: Vec<&str> = s.split_inclusive('\n').collect();
        s = match rng.below(7) {
            0 => {
                let at = boundary(&s, rng);
                let mut t = s.clone();
                t.insert_str(at, TOKENS[rng.below(TOKENS.len())]);
                t
            }
            1 if !lines.is_empty() => {
                let k = rng.below(lines.len());
                lines
                    .iter()
                    .enumerate()
                    .filter(|(i, _)| *i != k)
                    .map(|(_, l)| *l)
                    .collect()
            }
            2 if !lines.is_empty() => {
                let k = rng.below(lines.len());
                let mut v = lines.clone();
                v.insert(k, lines[k]);
                v.concat()
            }
            3 if lines.len() > 1 => {
                let (a, b) = (rng.below(lines.len()), rng.below(lines.len()));
                let mut v = lines.clone();
                v.swap(a, b);
                v.concat()
            }
            4 => s[..boundary(&s, rng)].to_string(),
            5 => {
                // Replace one character by a printable ASCII one.
                let at = boundary(&s, rng);
                let mut t = s.clone();
                if let Some(c) = t[at..].chars().next() {
                    let r = (b' ' + rng.below(95) as u8) as char;
                    t.replace_range(at..at + c.len_utf8(), &r.to_string());
                }
                t
            }
            _ => {
                // A digit changed: numbers stay numbers but the geometry breaks.
                let digits: Vec<usize> = s
                    .char_indices()
                    .filter(|(_, c)| c.is_ascii_digit())
                    .map(|(i, _)| i)
                    .collect();
                if digits.is_empty() {
                    s.clone()
                } else {
                    let at = digits[rng.below(digits.len())];
                    let mut t = s.clone();
                    let d = (b'0' + rng.below(10) as u8) as char;
                    t.replace_range(at..at + 1, &d.to_string());
                    t
                }
            }
        };
    }
    s
}

/// A random mechanism file that is valid TOML with the schema's keys: one to four bodies
/// with either rotation, joints of every type between random bodies (the ground included),
/// drivers and loads on random targets; values mostly sensible, sometimes degenerate (zero
/// mass or axis, coincident points, huge or non-finite numbers, bad expressions, unknown or
/// duplicated names). Most load, so it reaches the validator's and generator's deeper checks
/// that mutations of the shipped files rarely reach.
pub fn structured(rng: &mut Rng) -> String {
    // Each degenerate choice is rare on its own, so that most files load and reach the
    // checks behind the first one.
    let rare = |rng: &mut Rng| rng.below(30) == 0;
    let n_bodies = 1 + rng.below(4);
    let mut names: Vec<String> = (0..n_bodies).map(|i| format!("b{i}")).collect();
    let paper = rare(rng);
    let mut s = format!(
        "name = \"fuzz\"\nformulations = [{}]\nrotation = \"{}\"\nt_end = 1.0\n\n[parameters]\nk = {}\n",
        if paper { "\"exact\", \"paper\"" } else { "\"exact\"" },
        ["quaternion", "euler"][rng.below(2)],
        if rare(rng) { ["\"k\"", "-1.0", "\"1e308 * 10.0\""][rng.below(3)] } else { "0.3" }
    );
    for (i, name) in names.iter().enumerate() {
        let position = format!("[{}.0, {}.0, 0.0]", i + 1, rng.below(2));
        s += &format!(
            "\n[[body]]\nname = \"{name}\"\nmass = {}\ninertia = {}\nposition = {}\n",
            pick(rng, &["1.0", "0.5", "\"k\""], number),
            vector(rng, &["[0.01, 0.02, 0.03]", "[0.1, 0.1, 0.1]"]),
            vector(rng, &[&position]),
        );
        if rng.below(3) == 0 {
            s += &format!("rotation = \"{}\"\n", ["euler", "quaternion"][rng.below(2)]);
        }
        if rng.below(4) == 0 {
            s += &format!(
                "angles = {}\n",
                vector(rng, &["[0.1, 0.2, 0.3]", "[0.1, 1.5707963267948966, 0.0]"])
            );
        }
    }
    names.push("ground".into());
    let kinds = [
        "spherical",
        "revolute",
        "universal",
        "cylindrical",
        "prismatic",
        "fixed",
        "distance",
        "euler_prismatic",
    ];
    let mut joints = Vec::new();
    for j in 0..rng.below(5) {
        // The paper's joint needs Euler bodies on both sides: rare, or most files stop there.
        let usable = kinds.len() - usize::from(!rare(rng));
        let kind = kinds[rng.below(usable)];
        let i1 = rng.below(names.len());
        let i2 = if rare(rng) {
            i1
        } else {
            (i1 + 1 + rng.below(names.len() - 1)) % names.len()
        };
        let name = if rare(rng) {
            "b0".to_string()
        } else {
            format!("j{j}")
        };
        s += &format!(
            "\n[[joint]]\nname = \"{name}\"\ntype = \"{kind}\"\nbody1 = \"{}\"\nbody2 = \"{}\"\n",
            names[i1], names[i2]
        );
        let local = rng.below(3) == 1;
        if local {
            s += &format!(
                "point1 = {}\npoint2 = {}\n",
                vector(rng, &["[0.0, 0.1, 0.0]", "[0.5, 0.0, 0.0]"]),
                vector(rng, &["[0.0, -0.1, 0.0]", "[-0.5, 0.0, 0.0]"])
            );
        } else if kind == "distance" {
            s += &format!(
                "at1 = {}\nat2 = {}\n",
                vector(rng, &["[0.0, 0.0, 0.0]", "[1.0, 0.0, 0.0]"]),
                vector(rng, &["[1.0, 1.0, 0.0]", "[2.0, 0.5, 0.0]"])
            );
        } else {
            s += &format!(
                "at = {}\n",
                vector(rng, &["[0.5, 0.0, 0.0]", "[1.5, 0.5, 0.0]"])
            );
        }
        // Axis joints get their axis (locally when given by local points); others rarely.
        let wants_axis = !matches!(kind, "spherical" | "fixed" | "distance");
        if wants_axis != rare(rng) {
            let keys: &[&str] = if local {
                &["axis1", "axis2"]
            } else {
                &["axis"]
            };
            for key in keys {
                s += &format!(
                    "{key} = {}\n",
                    vector(
                        rng,
                        &["[0.0, 0.0, 1.0]", "[1.0, 0.0, 0.0]", "[0.0, 1.0, 0.0]"]
                    )
                );
            }
        }
        if !local && (kind == "universal" || rare(rng)) {
            let key = "cross_axis";
            s += &format!(
                "{key} = {}\n",
                vector(rng, &["[1.0, 0.0, 0.0]", "[0.0, 1.0, 0.0]"])
            );
        }
        joints.push(name);
    }
    let bodies = &names[..n_bodies];
    for d in 0..rng.below(3) {
        s += &format!("\n[[driver]]\nname = \"d{d}\"\n");
        let value = if rare(rng) {
            ["\"sqrt(t - 1.0)\"", "\"1.0 / t\"", "1.0"][rng.below(3)]
        } else {
            [
                "\"initial + 0.1 * sin(t)\"",
                "\"initial + k * t\"",
                "\"initial\"",
            ][rng.below(3)]
        };
        match rng.below(3) {
            0 if !joints.is_empty() => {
                s += &format!("joint = \"{}\"\n", joints[rng.below(joints.len())]);
                if rng.below(2) == 0 {
                    s += &format!(
                        "coordinate = \"{}\"\n",
                        ["angle", "distance", "x"][rng.below(3)]
                    );
                }
            }
            1 => {
                s += &format!(
                    "body = \"{}\"\ncoordinate = \"{}\"\n",
                    bodies[rng.below(bodies.len())],
                    ["x", "y", "z", "theta", "beta", "gamma", "w"][rng.below(7)]
                )
            }
            _ => {
                s += &format!(
                    "body1 = \"{}\"\nbody2 = \"ground\"\nat1 = [0.0, 0.0, 0.0]\nat2 = [1.0, 2.0, 0.0]\n",
                    bodies[rng.below(bodies.len())]
                )
            }
        }
        s += &format!("value = {value}\n");
    }
    for f in 0..rng.below(3) {
        let kind = ["spring", "torsion", "force", "torque"][rng.below(4)];
        s += &format!("\n[[force]]\nname = \"f{f}\"\ntype = \"{kind}\"\n");
        let body = &bodies[rng.below(bodies.len())];
        match kind {
            "spring" => {
                s += &format!(
                    "body1 = \"{body}\"\nbody2 = \"ground\"\nat1 = [0.0, 0.0, 0.0]\nat2 = {}\nstiffness = {}\ndamping = {}\n",
                    vector(rng, &["[0.0, 3.0, 0.0]", "[2.0, 1.0, 0.0]"]),
                    number(rng),
                    number(rng)
                )
            }
            "torsion" => {
                let j = joints
                    .get(rng.below(joints.len().max(1)))
                    .cloned()
                    .unwrap_or("none".into());
                s += &format!("joint = \"{j}\"\nstiffness = {}\n", number(rng));
            }
            _ => {
                s += &format!(
                    "body = \"{body}\"\nvalue = [0.0, {}, 0.0]\naxes = \"{}\"\n",
                    pick(rng, &["\"-sin(t)\"", "\"k * t\"", "1.0"], number),
                    ["global", "body"][rng.below(2)]
                );
            }
        }
    }
    s
}

/// A number: usually ordinary, one time in 25 at the edges of f64 or a bad expression.
fn number(rng: &mut Rng) -> String {
    if rng.below(25) == 0 {
        [
            "0.0",
            "-2.5",
            "1e-12",
            "1e300",
            "\"1.0 / 0.0\"",
            "\"sqrt(-1.0)\"",
        ][rng.below(6)]
    } else {
        ["1.0", "0.5", "2.0", "\"k\"", "\"2 * k\""][rng.below(5)]
    }
    .to_string()
}

/// One of `choices` most of the time, otherwise `other(rng)`.
fn pick(rng: &mut Rng, choices: &[&str], other: fn(&mut Rng) -> String) -> String {
    if rng.below(10) == 0 {
        other(rng)
    } else {
        choices[rng.below(choices.len())].to_string()
    }
}

/// One of `choices` most of the time, otherwise a vector of random numbers (sometimes of the
/// wrong length).
fn vector(rng: &mut Rng, choices: &[&str]) -> String {
    if rng.below(25) == 0 {
        let n = [3, 3, 3, 2, 4][rng.below(5)];
        let v: Vec<String> = (0..n).map(|_| number(rng)).collect();
        format!("[{}]", v.join(", "))
    } else {
        choices[rng.below(choices.len())].to_string()
    }
}

fn boundary(s: &str, rng: &mut Rng) -> usize {
    let mut at = rng.below(s.len() + 1);
    while !s.is_char_boundary(at) {
        at -= 1;
    }
    at
}

/// What one input did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// `load` reported errors (the normal fate of a broken file).
    Rejected,
    /// It loaded; `generate` was not asked to run (sampling).
    Loaded,
    /// It went through `generate`, which succeeded or reported errors.
    Generated,
    /// Something panicked: a bug.
    Panicked,
}

/// Runs one input through `load`, and through `generate` when `full` and it loaded.
pub fn run_one(text: &str, full: bool) -> Outcome {
    let result = catch_unwind(AssertUnwindSafe(|| {
        match crate::model::load("fuzz.toml", text) {
            Err(_) => Outcome::Rejected,
            Ok(_) if !full => Outcome::Loaded,
            Ok(_) => {
                let _ = crate::generate("fuzz.toml", text);
                Outcome::Generated
            }
        }
    }));
    result.unwrap_or(Outcome::Panicked)
}
