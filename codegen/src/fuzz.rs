//! Robustness fuzzing of the generator on stable Rust: mutations of real mechanism files
//! (byte edits, token insertions, line deletions, duplications and swaps, truncations) and
//! random structured files ([`structured`]: bodies, joints, drivers and loads of random kinds,
//! names and values, valid TOML) go through [`crate::model::load`], and those that load through
//! the rest of [`crate::generate`]; any panic is a failure. Those that load also run in the
//! interpreter ([`interpret_one`]): every [`Mechanism`] function at the file's state and at
//! NaN, infinite and huge ones, a few HHT steps and position solves, where a panic or a
//! solver `Ok` holding a non-finite state is a failure and everything else must come back as
//! a typed [`symbody_runtime::Error`]. [`parameter_case`] sets the parameters of files that
//! load to random and degenerate values through [`crate::model::load_with`] and the
//! interpreter: each set is refused with errors naming what is wrong or gives a finite
//! mechanism. Used by the `fuzz` binary (10⁶ inputs) and by a seeded test that runs a small
//! share in CI.

use std::panic::{catch_unwind, AssertUnwindSafe};
use symbody_runtime::{KinematicOutputs, Mechanism, NewtonOutputs};

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

/// What one input did in the interpreter ([`interpret_one`]).
#[derive(Debug, Default, Clone)]
pub struct Interpretation {
    /// [`crate::interpret::load`] built its entry (otherwise it reported errors).
    pub built: bool,
    /// Formulations whose every [`Mechanism`] function was evaluated.
    pub formulations: usize,
    /// HHT integrators asked to start (from the file's state and from a perturbed one).
    pub solver_runs: usize,
    /// HHT steps that returned `Ok`.
    pub steps: usize,
    /// Kinematic position solves run.
    pub position_solves: usize,
    /// Typed runtime errors returned, by variant name (`NewtonFailed`, `NotFinite`, …).
    pub errors: Vec<String>,
    /// Solver results that came back `Ok` with a NaN or infinite state: bugs.
    pub findings: Vec<String>,
}

/// The variant name of a runtime error (`NewtonFailed`, `NotFinite`, …).
fn variant(e: &symbody_runtime::Error) -> String {
    format!("{e:?}")
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric())
        .collect()
}

/// `base` with a random perturbation: small noise, or one entry NaN, infinite or huge, or
/// all entries huge.
fn perturb(base: &[f64], rng: &mut Rng) -> Vec<f64> {
    let mut v = base.to_vec();
    if v.is_empty() {
        return v;
    }
    let k = rng.below(v.len());
    match rng.below(6) {
        0 => v[k] = f64::NAN,
        1 => v[k] = [f64::INFINITY, f64::NEG_INFINITY][rng.below(2)],
        2 => v[k] = [1e300, -1e300, 1e18, f64::MAX][rng.below(4)],
        3 => v.iter_mut().for_each(|x| *x = *x * 1e200 + 1e200),
        _ => {
            for x in &mut v {
                *x += (rng.below(2001) as f64 - 1000.0) * 1e-4;
            }
        }
    }
    v
}

/// Evaluates every [`Mechanism`] function of `mech` at `(q, qd, t)`, as a solver would (the
/// outputs are allowed to be NaN: only a panic is wrong here).
fn evaluate_all(mech: &dyn Mechanism, q: &[f64], qd: &[f64], t: f64) {
    let info = mech.info();
    let (n, m) = (info.n_coords, info.n_constraints);
    let (mut phi, mut phi_q) = (vec![0.0; m], vec![0.0; info.phi_q_nnz()]);
    let (mut phi_t, mut gamma) = (vec![0.0; m], vec![0.0; m]);
    let (mut mass, mut force) = (vec![0.0; info.mass_nnz()], vec![0.0; n]);
    let mut dq = vec![0.0; info.force_q_rows.len()];
    let mut dqd = vec![0.0; info.force_qd_rows.len()];
    mech.phi(q, t, &mut phi);
    mech.phi_q(q, t, &mut phi_q);
    mech.phi_t(q, t, &mut phi_t);
    mech.gamma(q, qd, t, &mut gamma);
    mech.mass(q, &mut mass);
    mech.force(q, qd, t, &mut force);
    mech.force_jacobian(q, qd, t, &mut dq, &mut dqd);
    let _ = mech.potential(q);
    let _ = mech.power_nc(q, qd, t);
    mech.eval_newton(
        q,
        qd,
        t,
        NewtonOutputs {
            phi: &mut phi,
            phi_q: &mut phi_q,
            mass: &mut mass,
            force: &mut force,
        },
    );
    mech.eval_kinematics(
        q,
        qd,
        t,
        KinematicOutputs {
            phi: &mut phi,
            phi_q: &mut phi_q,
            phi_t: &mut phi_t,
            gamma: &mut gamma,
        },
    );
}

fn finite(v: &[f64]) -> bool {
    v.iter().all(|x| x.is_finite())
}

/// Starts HHT on `mech` (from the file's state, or from `start` when given) and takes up to
/// `steps` steps; every `Ok` must leave a finite state.
fn run_hht(
    mech: &'static (dyn Mechanism + Sync),
    start: Option<(&[f64], &[f64])>,
    steps: usize,
    what: &str,
    out: &mut Interpretation,
) {
    out.solver_runs += 1;
    let mut builder = symbody_runtime::HhtBuilder::new().project_velocities(true);
    builder = match start {
        Some((q, qd)) => builder.q0(q).qd0(qd),
        None => builder.qd0(mech.info().qd0),
    };
    let mut it = match builder.build(mech) {
        Ok(it) => it,
        Err(e) => return out.errors.push(variant(&e)),
    };
    let check = |it: &symbody_runtime::Integrator<_>, when: &str, out: &mut Interpretation| {
        let ok = finite(it.q()) && finite(it.qd()) && it.t().is_finite();
        if !ok {
            out.findings.push(format!(
                "{what}: Ok with a non-finite state {when} (t = {}, q = {:?}, qd = {:?})",
                it.t(),
                it.q(),
                it.qd()
            ));
        }
        ok
    };
    if !check(&it, "after the consistent start", out) {
        return;
    }
    for k in 0..steps {
        match it.step() {
            Ok(_) => {
                out.steps += 1;
                if !check(&it, &format!("after step {}", k + 1), out) {
                    return;
                }
            }
            Err(e) => return out.errors.push(variant(&e)),
        }
    }
}

/// A kinematic position solve of `mech` at `t` from `q`; an `Ok` must leave `q` finite.
fn run_position(mech: &(dyn Mechanism + Sync), t: f64, q: &[f64], out: &mut Interpretation) {
    out.position_solves += 1;
    let mut q = q.to_vec();
    let result = symbody_runtime::Kinematics::<symbody_runtime::SchurKkt>::new(mech.info())
        .and_then(|mut kin| kin.position(&mech, t, &mut q));
    match result {
        Err(e) => out.errors.push(variant(&e)),
        Ok(_) if !finite(&q) => out.findings.push(format!(
            "position solve at t = {t}: Ok with a non-finite q = {q:?}"
        )),
        Ok(_) => {}
    }
}

/// Runs one input through the interpreter: [`crate::interpret::load`], then for every
/// formulation every [`Mechanism`] function at `q0`/`qd0` and at `states` random perturbed
/// states (NaN, infinite and huge entries among them, and such times), and when `solve`, a
/// few HHT steps from the file's state and from a perturbed one and kinematic position
/// solves. `None` when anything panicked; findings (an `Ok` with a non-finite state) are
/// in the result.
pub fn interpret_one(
    text: &str,
    rng: &mut Rng,
    states: usize,
    solve: bool,
) -> Option<Interpretation> {
    let mut out = Interpretation::default();
    catch_unwind(AssertUnwindSafe(|| {
        // SAFETY: the solvers are built and dropped inside the closure, and nothing taken
        // from the entry leaves it.
        let _ = unsafe {
            crate::interpret::load_scoped("fuzz.toml", text, false, |loaded| {
                exercise(loaded, rng, states, solve, &mut out)
            })
        };
    }))
    .ok()?;
    Some(out)
}

/// What [`interpret_one`] does with an entry that loaded.
fn exercise(
    loaded: &crate::interpret::Loaded,
    rng: &mut Rng,
    states: usize,
    solve: bool,
    out: &mut Interpretation,
) {
    out.built = true;
    for &(_, mech) in loaded.entry.formulations {
        let info = mech.info();
        evaluate_all(mech, info.q0, info.qd0, 0.0);
        for _ in 0..states {
            let q = perturb(info.q0, rng);
            let qd = perturb(info.qd0, rng);
            let t = [0.0, 0.37, 1e300, f64::NAN, f64::INFINITY][rng.below(5)];
            evaluate_all(mech, &q, &qd, t);
        }
        out.formulations += 1;
        if solve {
            run_hht(mech, None, 5, "HHT from the file's state", out);
            let (q, qd) = (perturb(info.q0, rng), perturb(info.qd0, rng));
            run_hht(mech, Some((&q, &qd)), 2, "HHT from a perturbed state", out);
            run_position(mech, 0.25, info.q0, out);
            run_position(mech, 0.0, &perturb(info.q0, rng), out);
        }
    }
}

/// What [`parameter_case`] did with one file's parameter sets.
#[derive(Debug, Default, Clone)]
pub struct ParameterCase {
    /// The file's parameters (none: no sets were tried).
    pub parameters: usize,
    /// Override sets tried.
    pub sets: usize,
    /// Sets [`crate::model::load_with`] accepted.
    pub loaded: usize,
    /// Sets refused, by kind: the stage (`load`, `assembly`) and the first diagnostic's
    /// message with names and numbers blanked out.
    pub rejected: Vec<String>,
    /// Refused sets whose diagnostics name one of the set's parameters (the others are
    /// reported at the file's item only).
    pub rejected_naming: usize,
    /// Sets whose interpreted entry was built (the assembly succeeded too).
    pub built: usize,
    /// What the interpreter and the solvers did with the built entries, summed.
    pub interpretation: Interpretation,
    /// Sets that panicked, each as `name = value, …`: bugs.
    pub panics: Vec<String>,
    /// Sets accepted with a non-finite or inconsistent value in what the model or the entry
    /// reports, accepted although they should be refused (an unknown name, a non-finite
    /// value), or refused without naming the culprit: bugs.
    pub findings: Vec<String>,
}

/// A uniform number in [0, 1).
fn unit(rng: &mut Rng) -> f64 {
    (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64
}

/// A value for a parameter whose file value is `default` (`others`: every parameter's file
/// value): half the time the default scaled by a random factor over many decades, sometimes
/// negated; otherwise a degenerate value (zero of either sign, a negation, NaN, ±∞, the
/// largest and a subnormal number, another parameter's value).
fn parameter_value(rng: &mut Rng, default: f64, others: &[f64]) -> f64 {
    match rng.below(20) {
        0 => 0.0,
        1 => -0.0,
        2 => -default,
        3 => -1.0,
        4 => f64::NAN,
        5 => f64::INFINITY,
        6 => f64::NEG_INFINITY,
        7 => 1e308,
        8 => 1e-320,
        9 => others[rng.below(others.len())],
        k => {
            // Mostly near the default (so that many sets still assemble and run), sometimes
            // decades away from it.
            let decades = if k < 16 { 0.2 } else { 30.0 };
            let factor = 10f64.powf(decades * (2.0 * unit(rng) - 1.0));
            let sign = if rng.below(6) == 0 { -1.0 } else { 1.0 };
            sign * default * factor
        }
    }
}

/// Levenshtein distance, to check the loader's suggestion for an unknown name on its own
/// terms rather than with the loader's own function.
fn distance(a: &str, b: &str) -> usize {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for i in 1..=a.len() {
        let mut cur = vec![i; b.len() + 1];
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            cur[j] = (prev[j] + 1).min(cur[j - 1] + 1).min(prev[j - 1] + cost);
        }
        prev = cur;
    }
    prev[b.len()]
}

/// A name one edit away from `name` that no parameter has (a typo), or a name far from
/// every one.
fn unknown_name(rng: &mut Rng, name: &str, names: &[String]) -> String {
    let mut chars: Vec<char> = name.chars().collect();
    let c = (b'a' + rng.below(26) as u8) as char;
    let at = rng.below(chars.len() + 1);
    match rng.below(4) {
        0 => chars.insert(at, c),
        1 if chars.len() > 1 => {
            chars.remove(at.min(chars.len() - 1));
        }
        2 if at < chars.len() => chars[at] = c,
        _ => return "zz_no_such_parameter".to_string(),
    }
    let typo: String = chars.into_iter().collect();
    if names.contains(&typo) {
        "zz_no_such_parameter".to_string()
    } else {
        typo
    }
}

/// A diagnostic's message reduced to its kind: its first clause (up to a `: ` after the
/// start), names in backticks and numbers (a sign kept) blanked out.
fn error_kind(stage: &str, message: &str) -> String {
    let clause = match message.find(": ") {
        Some(at) if at > 12 => &message[..at],
        _ => message,
    };
    let mut out = format!("{stage}: ");
    let mut quoted = false;
    let mut number = false;
    for c in clause.chars() {
        if c == '`' {
            quoted = !quoted;
            if quoted {
                out.push('·');
            }
            continue;
        }
        if quoted {
            continue;
        }
        // Digits, and a number's point, exponent and exponent sign, are one `#`.
        let part = c.is_ascii_digit() || number && matches!(c, '.' | 'e' | '-' | '+');
        if part && !number {
            out.push('#');
        } else if !part {
            out.push(c);
        }
        number = part;
    }
    out.chars().take(72).collect()
}

/// The problems of an accepted model: a non-finite or impossible value anywhere it reports,
/// or an override not applied.
fn model_problems(m: &crate::model::Model, set: &[(String, f64)]) -> Vec<String> {
    let mut out = Vec::new();
    for p in &m.parameters {
        if !p.value.is_finite() {
            out.push(format!("parameter `{}` = {}", p.name, p.value));
        }
        // The last setting of a name wins, as in a file read top to bottom.
        if let Some((_, v)) = set.iter().rev().find(|(k, _)| *k == p.name) {
            if p.value != *v || !p.overridden {
                out.push(format!(
                    "parameter `{}` set to {v} but used {}",
                    p.name, p.value
                ));
            }
        }
    }
    for b in &m.bodies {
        if !(b.mass.is_finite() && b.mass > 0.0) {
            out.push(format!("body `{}` has mass {}", b.name, b.mass));
        }
        if !b.inertia.iter().all(|x| x.is_finite() && *x >= 0.0) {
            out.push(format!("body `{}` has inertia {:?}", b.name, b.inertia));
        }
        if !finite(&b.q0) || !finite(&b.qd0) {
            out.push(format!(
                "body `{}` starts at {:?}, {:?}",
                b.name, b.q0, b.qd0
            ));
        }
    }
    if !(finite(&m.gravity) && m.t_end.is_finite() && m.t_end > 0.0) {
        out.push(format!("gravity {:?}, t_end {}", m.gravity, m.t_end));
    }
    out
}

/// The problems of a built entry: a non-finite value in what it reports.
fn entry_problems(loaded: &crate::interpret::Loaded) -> Vec<String> {
    let mut out = Vec::new();
    let entry = loaded.entry;
    if !entry.t_end.is_finite() {
        out.push(format!("t_end {}", entry.t_end));
    }
    for p in &loaded.parameters {
        if !p.value.is_finite() {
            out.push(format!("parameter `{}` = {}", p.name, p.value));
        }
    }
    for &(_, mech) in entry.formulations {
        let info = mech.info();
        if !finite(info.q0) || !finite(info.qd0) || !finite(&info.gravity) {
            out.push(format!("q0 {:?}, qd0 {:?}", info.q0, info.qd0));
        }
        for b in info.bodies {
            if !(b.mass.is_finite() && b.mass > 0.0 && finite(&b.inertia)) {
                out.push(format!("body `{}`: {} kg, {:?}", b.name, b.mass, b.inertia));
            }
        }
        for j in info.joints {
            if !finite(&j.point1) || !finite(&j.point2) || !j.effort_sign.is_finite() {
                out.push(format!(
                    "joint `{}`: {:?}, {:?}",
                    j.name, j.point1, j.point2
                ));
            }
        }
        for l in info.platform.iter().flat_map(|p| p.legs) {
            if !finite(&l.base) || !finite(&l.platform) {
                out.push(format!(
                    "leg `{}`: {:?}, {:?}",
                    l.driver, l.base, l.platform
                ));
            }
        }
    }
    out
}

/// Parameter-value fuzzing of one file: when `text` loads and has parameters, `sets`
/// override sets of one to all of them, with random values (the file's scaled over many
/// decades, sign flips) and degenerate ones (±0, negatives, NaN, ±∞, 1e308, a subnormal,
/// another parameter's value), and now and then a name the file does not have. Each goes
/// through [`crate::model::load_with`]; a set it accepts must give a finite model with the
/// values asked for, and then goes through [`crate::interpret::load_scoped_with`] (whose
/// entry must report finite values) and [`exercise`] (every mechanism function at `states`
/// perturbed states; with `solve`, HHT steps and position solves). A refusal of an unknown
/// name must name it and suggest a closest parameter; of a non-finite value, name the
/// parameter. A panic anywhere is recorded with its set.
pub fn parameter_case(
    text: &str,
    rng: &mut Rng,
    sets: usize,
    states: usize,
    solve: bool,
) -> ParameterCase {
    let mut out = ParameterCase::default();
    let listed = match catch_unwind(|| crate::model::load("fuzz.toml", text)) {
        Ok(Ok(m)) => m.parameters,
        // The plain file's fate is `run_one`'s business.
        _ => return out,
    };
    let names: Vec<String> = listed.iter().map(|p| p.name.clone()).collect();
    let defaults: Vec<f64> = listed.iter().map(|p| p.value).collect();
    out.parameters = names.len();
    if names.is_empty() {
        return out;
    }
    for _ in 0..sets {
        // One parameter half the time, otherwise any number of them up to all.
        let k = if rng.below(2) == 0 {
            1
        } else {
            1 + rng.below(names.len())
        };
        let mut set: Vec<(String, f64)> = (0..k)
            .map(|_| {
                let i = rng.below(names.len());
                let v = parameter_value(rng, defaults[i], &defaults);
                (names[i].clone(), v)
            })
            .collect();
        let unknown = (rng.below(8) == 0).then(|| {
            let of = rng.below(names.len());
            let name = unknown_name(rng, &names[of], &names);
            let at = rng.below(set.len() + 1);
            set.insert(at, (name.clone(), 1.0));
            name
        });
        out.sets += 1;
        let shown = || {
            set.iter()
                .map(|(k, v)| format!("{k} = {v:e}"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        let mut interpretation = Interpretation::default();
        let result = catch_unwind(AssertUnwindSafe(|| {
            let mut findings = Vec::new();
            match crate::model::load_with("fuzz.toml", text, &set) {
                Err(e) => {
                    findings.extend(refusal_problems(&e, &set, &names, unknown.as_deref()));
                    let kind = error_kind("load", &e.0[0].message);
                    return (Some((kind, names_one(&e, &set))), false, findings);
                }
                Ok(m) => {
                    if let Some(u) = &unknown {
                        findings.push(format!("unknown parameter `{u}` accepted"));
                    }
                    if let Some((k, v)) = set.iter().find(|(_, v)| !v.is_finite()) {
                        findings.push(format!("parameter `{k}` = {v} accepted"));
                    }
                    findings.extend(model_problems(&m, &set));
                }
            }
            // SAFETY: the solvers are built and dropped inside the closure, and nothing
            // taken from the entry leaves it.
            let built = unsafe {
                crate::interpret::load_scoped_with("fuzz.toml", text, &set, false, |loaded| {
                    findings.extend(entry_problems(loaded));
                    exercise(loaded, rng, states, solve, &mut interpretation);
                })
            };
            match built {
                Ok(()) => (None, true, findings),
                Err(e) => {
                    let kind = error_kind("assembly", &e.0[0].message);
                    (Some((kind, names_one(&e, &set))), false, findings)
                }
            }
        }));
        match result {
            Err(_) => out.panics.push(shown()),
            Ok((rejected, built, findings)) => {
                out.loaded += usize::from(
                    rejected
                        .as_ref()
                        .is_none_or(|(k, _)| k.starts_with("assembly")),
                );
                if let Some((kind, named)) = rejected {
                    out.rejected.push(kind);
                    out.rejected_naming += usize::from(named);
                }
                out.built += usize::from(built);
                out.findings
                    .extend(findings.into_iter().map(|f| format!("{}: {f}", shown())));
                for f in &interpretation.findings {
                    out.findings.push(format!("{}: {f}", shown()));
                }
                let sum = &mut out.interpretation;
                sum.built |= interpretation.built;
                sum.formulations += interpretation.formulations;
                sum.solver_runs += interpretation.solver_runs;
                sum.steps += interpretation.steps;
                sum.position_solves += interpretation.position_solves;
                sum.errors.extend(interpretation.errors);
            }
        }
    }
    out
}

/// Whether a diagnostic of `e` names a parameter of `set`.
fn names_one(e: &crate::Errors, set: &[(String, f64)]) -> bool {
    e.0.iter().any(|d| {
        set.iter().any(|(k, _)| {
            let k = format!("`{k}`");
            d.message.contains(&k) || d.help.contains(&k) || d.item.contains(&k)
        })
    })
}

/// What is wrong with a refusal of `set`: an unknown name not named, or without the
/// closest parameter suggested; a non-finite value whose parameter is not named.
fn refusal_problems(
    e: &crate::Errors,
    set: &[(String, f64)],
    names: &[String],
    unknown: Option<&str>,
) -> Vec<String> {
    let mut out = Vec::new();
    if let Some(u) = unknown {
        let named = format!("no parameter `{u}`");
        match e.0.iter().find(|d| d.message.contains(&named)) {
            None => out.push(format!("unknown parameter `{u}` not named: {e}")),
            Some(d) => {
                let best = names.iter().map(|n| distance(u, n)).min().unwrap_or(0);
                // The loader suggests only close names: one edit away always qualifies.
                let suggested = d
                    .help
                    .split_once("did you mean `")
                    .and_then(|(_, rest)| rest.split_once('`'))
                    .map(|(s, _)| s);
                match suggested {
                    Some(s) if names.iter().any(|n| n == s) && distance(u, s) == best => {}
                    None if best > 2 => {}
                    _ => out.push(format!(
                        "unknown parameter `{u}`: suggested {suggested:?}, a closest is {best} edits away: {}",
                        d.help
                    )),
                }
            }
        }
    }
    for (k, v) in set {
        if !v.is_finite() && names.contains(k) {
            let named = format!("parameter `{k}` set to");
            if !e.0.iter().any(|d| d.message.contains(&named)) {
                out.push(format!(
                    "non-finite `{k}` = {v} refused without naming it: {e}"
                ));
            }
        }
    }
    out
}
