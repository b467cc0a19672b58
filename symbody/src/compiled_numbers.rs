//! Compiled code at parameters that reach the model's numbers (joint points and axes,
//! lengths, drivers' constants: docs/design.md, decision 36): the mechanism file is loaded at
//! the new values, the numbers the generated code takes at run time are read off it, and the
//! file derived again gives what the generator decides from numbers (the assembled pose, the
//! dependent rows, masses, the platform for `fk`); the compiled code evaluates the equations.
//! Where the new values change a number the code holds as a constant, the file's own
//! equations run interpreted instead, as they did before.

use crate::files::{compiled_entry, with_scoped_entry, Listed};
use crate::scenario::ScenarioError;
use symbody_codegen::interpret;
use symbody_codegen::model::{ForceKind, Model};
use symbody_codegen::slots;
use symbody_runtime::registry::{Built, Formulations, RunTime};
use symbody_runtime::{
    source_hash, Direction, Entry, Formulation, KinematicOutputs, Mechanism, MechanismInfo,
    NewtonOutputs, Origin, Reduction, TangentOutputs,
};

/// Compiled code with the `MechanismInfo` of the file derived at the same values: its
/// patterns are the code's, its pose, dependent rows, bodies, joints and platform the file's.
struct WithInfo {
    code: Box<dyn Mechanism + Sync>,
    info: &'static MechanismInfo,
}

impl Mechanism for WithInfo {
    fn info(&self) -> &'static MechanismInfo {
        self.info
    }
    fn phi(&self, q: &[f64], t: f64, out: &mut [f64]) {
        self.code.phi(q, t, out)
    }
    fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) {
        self.code.phi_q(q, t, out)
    }
    fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) {
        self.code.phi_t(q, t, out)
    }
    fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        self.code.gamma(q, qd, t, out)
    }
    fn mass(&self, q: &[f64], out: &mut [f64]) {
        self.code.mass(q, out)
    }
    fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        self.code.force(q, qd, t, out)
    }
    fn force_jacobian(&self, q: &[f64], qd: &[f64], t: f64, dq: &mut [f64], dqd: &mut [f64]) {
        self.code.force_jacobian(q, qd, t, dq, dqd)
    }
    fn potential(&self, q: &[f64]) -> f64 {
        self.code.potential(q)
    }
    fn power_nc(&self, q: &[f64], qd: &[f64], t: f64) -> f64 {
        self.code.power_nc(q, qd, t)
    }
    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        self.code.eval_newton(q, qd, t, out)
    }
    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
        self.code.eval_kinematics(q, qd, t, out)
    }
    fn run_time_values(&self) -> &[f64] {
        self.code.run_time_values()
    }
    fn tangents(
        &self,
        q: &[f64],
        qd: &[f64],
        t: f64,
        dir: Direction<'_>,
        out: TangentOutputs<'_>,
    ) -> bool {
        self.code.tangents(q, qd, t, dir, out)
    }
}

/// Where the route applies: `entry`'s compiled code takes numbers of its model at run time,
/// some value set is not a parameter it takes by name, and its file is here, unchanged since
/// the code was generated. Its run-time description, file and text.
fn route(
    entry: &Entry,
    parameters: &[(String, f64)],
) -> Option<(&'static RunTime, &'static str, String)> {
    let (Some(rt), Origin::Compiled { file, hash, .. }) = (entry.run_time, entry.origin) else {
        return None;
    };
    let by_name = |(k, _): &(String, f64)| rt.parameters.names.contains(&k.as_str());
    if rt.data.is_empty() || parameters.iter().all(by_name) {
        return None;
    }
    let text = std::fs::read_to_string(file).ok()?;
    (source_hash(&text) == hash).then_some((rt, file, text))
}

/// One formulation of the compiled code at some values, and the info it is to read.
type Combined = Vec<(Formulation, WithInfo, MechanismInfo)>;

/// The compiled code at some values, every info in a box of its own: the mechanisms read
/// their infos (and the reduced infos their initial states) by `'static` references that
/// stay valid as long as this lives (for the program, leaked; or for a scope).
struct Homed {
    full: Vec<(Formulation, WithInfo)>,
    reduced: Option<(Vec<(Formulation, WithInfo)>, &'static Reduction)>,
    // Boxed one by one: references into them are handed out while the list still grows.
    #[allow(clippy::vec_box)]
    _infos: Vec<Box<MechanismInfo>>,
    _states: Vec<Box<[f64]>>,
}

impl Homed {
    /// The formulations, and the reduced model's with its reduction.
    fn lists(&self) -> Lists<'_> {
        fn list(l: &[(Formulation, WithInfo)]) -> Vec<Listed<'_>> {
            l.iter().map(|(f, m)| (*f, m as _)).collect()
        }
        let reduced = self.reduced.as_ref().map(|(r, red)| (list(r), *red));
        (list(&self.full), reduced)
    }
}

type Lists<'a> = (
    Vec<Listed<'a>>,
    Option<(Vec<Listed<'a>>, &'static Reduction)>,
);

/// A place for `v` that outlives the borrow: `'static` while `owner` keeps the box.
fn home<T: ?Sized>(owner: &mut Vec<Box<T>>, v: Box<T>) -> &'static T {
    let r: *const T = &*v;
    owner.push(v);
    // SAFETY: a box's contents do not move when the box does; `Homed` keeps the box as long
    // as anything reads the reference (see `Homed`).
    unsafe { &*r }
}

/// The compiled code at the values (`built`) with the info of the file derived at them
/// (`derived`, [`interpret::describe`]), or `None` where the two do not describe the same
/// equations (other sizes or names).
fn combine(built: Built, derived: &[(Formulation, &'static MechanismInfo)]) -> Option<Combined> {
    built
        .into_iter()
        .map(|(f, code)| {
            let theirs = derived.iter().find(|(g, _)| *g == f)?.1;
            let ours = code.info();
            let same = ours.n_coords == theirs.n_coords
                && ours.n_constraints == theirs.n_constraints
                && ours.coord_names == theirs.coord_names
                && ours.row_names == theirs.row_names;
            let info = MechanismInfo {
                q0: theirs.q0,
                qd0: theirs.qd0,
                redundant_rows: theirs.redundant_rows,
                bodies: theirs.bodies,
                joints: theirs.joints,
                platform: theirs.platform,
                ..*ours
            };
            same.then_some((f, WithInfo { code, info: ours }, info))
        })
        .collect()
}

/// Largest gap, relative to the pose's size, by which the reduced model's substitutions
/// (`q[coord] = weight · q[target] + c(0)`) may miss the full model's new initial pose and
/// still describe it: roundoff of the assembly.
const SUBSTITUTED: f64 = 1e-12;

/// The entry's compiled reduced model at `p`, where it serves these values: its offsets read
/// none of the model's numbers, the new initial pose (`full`'s infos) keeps the coordinates it
/// substitutes where they were, and the full model's dependent rows are the file's.
fn reduced_at(
    entry: &Entry,
    rt: &RunTime,
    p: &[f64],
    full: &Combined,
) -> Result<Option<(Combined, &'static Reduction)>, symbody_runtime::parameters::ParameterError> {
    let Some(r) = &entry.reduced else {
        return Ok(None);
    };
    let red = r.reduction;
    let Some((_, code, info)) = full.first() else {
        return Ok(None);
    };
    if red.offsets_read_parameters || info.redundant_rows != code.info.redundant_rows {
        return Ok(None);
    }
    let mut offsets = vec![0.0; 3 * red.substitutions.len()];
    (red.offsets)(0.0, &mut offsets);
    let q0 = info.q0;
    let size = q0.iter().fold(1.0f64, |m, v| m.max(v.abs()));
    let kept = red.substitutions.iter().enumerate().all(|(k, s)| {
        let follows = s.target.map_or(0.0, |j| s.weight * q0[j as usize]);
        (q0[s.coord as usize] - follows - offsets[3 * k]).abs() <= SUBSTITUTED * size
    });
    if !kept {
        return Ok(None);
    }
    let built: Built = match rt.build_reduced_values {
        Some(build) => build(p)?,
        // A reduced model that reads no run-time values serves any as it is.
        None => r
            .formulations
            .iter()
            .map(|&(f, m)| (f, Box::new(m) as Box<dyn Mechanism + Sync>))
            .collect(),
    };
    let forms = built
        .into_iter()
        .map(|(f, code)| {
            let ours = code.info();
            (f, WithInfo { code, info: ours }, *ours)
        })
        .collect();
    Ok(Some((forms, red)))
}

/// Why the compiled code does not take a set of values (`None`: the file does not load with
/// them, which the file derived again reports), for the note of the run that takes its place.
pub type Declined = Option<String>;

/// The compiled code at `parameters` and the file derived at them, or why the compiled code
/// cannot take these values.
fn at_values(
    entry: &Entry,
    rt: &RunTime,
    file: &str,
    text: &str,
    parameters: &[(String, f64)],
) -> Result<Result<Homed, Declined>, ScenarioError> {
    let (p, model) = match slots::values_at(file, text, parameters, rt.data, rt.p0) {
        Ok(at) => at,
        Err(slots::Refused::Load(_)) => return Ok(Err(None)),
        Err(slots::Refused::OtherSlots) => {
            return Ok(Err(Some(
                "its numbers are not where this generator puts them (regenerate it)".into(),
            )))
        }
        Err(slots::Refused::Structure(what)) => {
            return Ok(Err(Some(format!(
                "these values change what it holds fixed ({what})"
            ))))
        }
    };
    if !same_constants(rt, &p, &model) {
        return Ok(Err(Some(
            "a mass, inertia or spring constant is not what it computes from the parameters (a \
             derived parameter set)"
                .into(),
        )));
    }
    let refused = |e: String| ScenarioError::Options(format!("with {}: {e}", shown(parameters)));
    let built = (rt.build_values)(&p).map_err(|e| refused(e.to_string()))?;
    let Ok(derived) = interpret::describe(file, text, model, parameters) else {
        return Ok(Err(None));
    };
    let Some(full) = combine(built, &derived) else {
        return Ok(Err(Some(
            "its coordinates or rows are not the file's at these values".into(),
        )));
    };
    let reduced = reduced_at(entry, rt, &p, &full).map_err(|e| refused(e.to_string()))?;
    let (mut infos, mut states) = (Vec::new(), Vec::new());
    let mut homed = |forms: Combined, red: Option<&Reduction>| -> Vec<(Formulation, WithInfo)> {
        forms
            .into_iter()
            .map(|(f, mut m, mut info)| {
                if let Some(red) = red {
                    // The reduced model starts where the full one does at these values.
                    let full = full_info(&derived, f);
                    let pick = |v: &[f64]| -> Box<[f64]> {
                        red.coords.iter().map(|&c| v[c as usize]).collect()
                    };
                    if let Some(full) = full {
                        info.q0 = home(&mut states, pick(full.0));
                        info.qd0 = home(&mut states, pick(full.1));
                    }
                }
                m.info = home(&mut infos, Box::new(info));
                (f, m)
            })
            .collect()
    };
    let full_homed = homed(full, None);
    let reduced_homed = reduced.map(|(forms, red)| (homed(forms, Some(red)), red));
    Ok(Ok(Homed {
        full: full_homed,
        reduced: reduced_homed,
        _infos: infos,
        _states: states,
    }))
}

/// Whether the masses, inertias and springs' constants the compiled code computes from `p`
/// (through the file's expressions: decision 35) are `model`'s. A derived parameter set from
/// outside the file stands for its expression, which the compiled code still evaluates.
fn same_constants(rt: &RunTime, p: &[f64], model: &Model) -> bool {
    let params = rt.parameters;
    if p.len() != rt.p0.len() || params.bodies.len() != model.bodies.len() {
        return false;
    }
    let mut props = vec![0.0; 4 * model.bodies.len()];
    (params.mass_properties)(p, &mut props);
    let mut constants = vec![0.0; 2 * model.forces.len()];
    (params.force_constants)(p, &mut constants);
    let bodies = model
        .bodies
        .iter()
        .flat_map(|b| [b.mass, b.inertia[0], b.inertia[1], b.inertia[2]]);
    let forces = model.forces.iter().flat_map(|f| match f.kind {
        ForceKind::Spring {
            stiffness, damping, ..
        }
        | ForceKind::Torsion {
            stiffness, damping, ..
        } => [stiffness, damping],
        _ => [0.0, 0.0],
    });
    let close = |(a, b): (&f64, f64)| (a - b).abs() <= SAME_CONSTANT * a.abs().max(b.abs());
    props.iter().zip(bodies).all(close) && constants.iter().zip(forces).all(close)
}

/// Roundoff between the loader's evaluation of a mass's expression and the generated code's.
const SAME_CONSTANT: f64 = 1e-12;

/// The initial pose and velocities of formulation `f` in the file derived at the values.
fn full_info(
    derived: &[(Formulation, &'static MechanismInfo)],
    f: Formulation,
) -> Option<(&'static [f64], &'static [f64])> {
    let info = derived.iter().find(|(g, _)| *g == f)?.1;
    Some((info.q0, info.qd0))
}

fn shown(parameters: &[(String, f64)]) -> String {
    let set: Vec<String> = parameters
        .iter()
        .map(|(k, v)| format!("{k} = {v}"))
        .collect();
    set.join(", ")
}

/// `entry`'s compiled code at `parameters` (the file's values for the others), living as
/// long as the program, where the route applies ([`route`]) and the values keep the
/// structure; otherwise why not (`Err(None)`: the route does not apply).
pub fn compiled_at(
    entry: &Entry,
    parameters: &[(String, f64)],
) -> Result<Result<&'static Entry, Declined>, ScenarioError> {
    let Some((rt, file, text)) = route(entry, parameters) else {
        return Ok(Err(None));
    };
    let source = crate::files::source_of(entry)?;
    let homed = match at_values(entry, rt, &source, &text, parameters)? {
        Ok(homed) => homed,
        Err(why) => return Ok(Err(why)),
    };
    let homed: &'static Homed = Box::leak(Box::new(homed));
    let (full, reduced) = homed.lists();
    let leaked = |l: Vec<Listed<'static>>| -> Formulations { Box::leak(l.into_boxed_slice()) };
    let lists = (leaked(full), reduced.map(|(r, red)| (leaked(r), red)));
    let set: Vec<(&'static str, f64)> = parameters
        .iter()
        .map(|(k, v)| (&*Box::leak(k.clone().into_boxed_str()), *v))
        .collect();
    let set = Box::leak(set.into_boxed_slice());
    let origin = (file, source_hash(&text));
    Ok(Ok(Box::leak(Box::new(compiled_entry(
        entry, origin, lists, set,
    )))))
}

/// `f` on what [`compiled_at`] builds, freed when `f` returns (a study's row); `None` where
/// the route does not apply or the compiled code cannot take the values.
pub fn with_compiled_at<R>(
    entry: &Entry,
    parameters: &[(String, f64)],
    f: impl FnOnce(&Entry) -> R,
) -> Result<Option<R>, ScenarioError> {
    let Some((rt, file, text)) = route(entry, parameters) else {
        return Ok(None);
    };
    let source = crate::files::source_of(entry)?;
    let build = || at_values(entry, rt, &source, &text, parameters);
    let run = |homed: Result<Result<Homed, Declined>, ScenarioError>| {
        let Ok(homed) = homed? else {
            return Ok(None);
        };
        let (full, reduced) = homed.lists();
        let names: Vec<(&str, f64)> = parameters.iter().map(|(k, v)| (k.as_str(), *v)).collect();
        let reduced = reduced.as_ref().map(|(r, red)| (&r[..], *red));
        let origin = (file, source_hash(&text));
        Ok(Some(with_scoped_entry(
            entry,
            origin,
            (&full, reduced),
            &names,
            f,
        )))
    };
    // SAFETY: nothing `build` built (the derived infos) outlives `run` (as above).
    unsafe { interpret::scoped(build, run) }
}
