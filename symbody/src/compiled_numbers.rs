//! Compiled code at parameters that reach the model's numbers (joint points and axes,
//! lengths, drivers' constants: docs/design.md, decision 36): the mechanism file is loaded at
//! the new values, the numbers the generated code takes at run time are read off it, and the
//! file derived again gives what the generator decides from numbers (the assembled pose, the
//! dependent rows, masses, the platform for `fk`); the compiled code evaluates the equations.
//! Where the new values change a number the code holds as a constant, the file's own
//! equations run interpreted instead, as they did before.

use crate::scenario::ScenarioError;
use symbody_codegen::interpret;
use symbody_codegen::slots;
use symbody_runtime::registry::{Built, Formulations, RunTime};
use symbody_runtime::{
    source_hash, Entry, Formulation, KinematicOutputs, Mechanism, MechanismInfo, NewtonOutputs,
    Origin,
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

/// Each formulation of the compiled code at some values, and the info it is to read (which
/// takes its place once it has a home: leaked, or kept for a scope).
type Combined = Vec<(Formulation, WithInfo, MechanismInfo)>;

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

/// The compiled code at `parameters` and the file derived at them, or `None` where the
/// compiled code cannot take these values: they change a number the code holds as a constant,
/// or the file does not load with them (which the file derived again then reports).
fn at_values(
    rt: &RunTime,
    file: &str,
    text: &str,
    parameters: &[(String, f64)],
) -> Result<Option<Combined>, ScenarioError> {
    let Ok((p, model)) = slots::values_at(file, text, parameters, rt.data, rt.p0) else {
        return Ok(None);
    };
    let refused = |e: String| ScenarioError::Options(format!("with {}: {e}", shown(parameters)));
    let built = (rt.build_values)(&p).map_err(|e| refused(e.to_string()))?;
    let Ok(derived) = interpret::describe(file, text, model, parameters) else {
        return Ok(None);
    };
    Ok(combine(built, &derived))
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
/// structure; `None` otherwise.
pub fn compiled_at(
    entry: &Entry,
    parameters: &[(String, f64)],
) -> Result<Option<&'static Entry>, ScenarioError> {
    let Some((rt, file, text)) = route(entry, parameters) else {
        return Ok(None);
    };
    let source = crate::files::source_of(entry)?;
    let Some(forms) = at_values(rt, &source, &text, parameters)? else {
        return Ok(None);
    };
    let list: Vec<(Formulation, &'static (dyn Mechanism + Sync))> = forms
        .into_iter()
        .map(|(f, mut m, info)| {
            m.info = Box::leak(Box::new(info));
            (
                f,
                &*Box::leak(Box::new(m)) as &'static (dyn Mechanism + Sync),
            )
        })
        .collect();
    let set: Vec<(&'static str, f64)> = parameters
        .iter()
        .map(|(k, v)| (&*Box::leak(k.clone().into_boxed_str()), *v))
        .collect();
    Ok(Some(Box::leak(Box::new(Entry {
        name: entry.name,
        t_end: entry.t_end,
        formulations: Box::leak(list.into_boxed_slice()),
        reduced: None,
        origin: Origin::Compiled {
            file,
            hash: source_hash(&text),
            parameters: Box::leak(set.into_boxed_slice()),
        },
        run_time: entry.run_time,
    }))))
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
    let build = || at_values(rt, &source, &text, parameters);
    let run = |forms: Result<Option<Combined>, ScenarioError>| {
        let Some(forms) = forms? else {
            return Ok(None);
        };
        let infos: Vec<MechanismInfo> = forms.iter().map(|(_, _, i)| *i).collect();
        let mechanisms: Vec<(Formulation, WithInfo)> = forms
            .into_iter()
            .zip(&infos)
            .map(|((form, mut m, _), info)| {
                // SAFETY: `infos` outlives every use of the mechanisms, which are dropped
                // before it, after `f` returns.
                m.info =
                    unsafe { std::mem::transmute::<&MechanismInfo, &'static MechanismInfo>(info) };
                (form, m)
            })
            .collect();
        let refs: Vec<(Formulation, &(dyn Mechanism + Sync))> =
            mechanisms.iter().map(|(form, m)| (*form, m as _)).collect();
        let names: Vec<(&str, f64)> = parameters.iter().map(|(k, v)| (k.as_str(), *v)).collect();
        // SAFETY: the entry and every reference in it are dropped when `f` returns, before
        // `refs`, `mechanisms`, `infos` and `names`; `f` gets the entry by reference only and
        // reduces what it records to numbers (the contract of `interpret::load_scoped`).
        let (formulations, set) = unsafe {
            (
                std::mem::transmute::<&[(Formulation, &(dyn Mechanism + Sync))], Formulations>(
                    &refs,
                ),
                std::mem::transmute::<&[(&str, f64)], &'static [(&'static str, f64)]>(&names),
            )
        };
        let scoped = Entry {
            name: entry.name,
            t_end: entry.t_end,
            formulations,
            reduced: None,
            origin: Origin::Compiled {
                file,
                hash: source_hash(&text),
                parameters: set,
            },
            run_time: entry.run_time,
        };
        Ok(Some(f(&scoped)))
    };
    // SAFETY: nothing `build` built (the derived infos) outlives `run` (as above).
    unsafe { interpret::scoped(build, run) }
}
