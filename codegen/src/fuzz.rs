//! Robustness fuzzing of the generator on stable Rust: mutations of real mechanism files
//! (byte edits, token insertions, line deletions, duplications and swaps, truncations) go
//! through [`crate::model::load`], and those that load through the rest of [`crate::generate`];
//! any panic is a failure. Used by the `fuzz` binary (10⁶ inputs) and by a seeded test that
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
