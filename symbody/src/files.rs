//! Mechanisms given as files: any mechanism file runs at once, interpreted (decision 31), and
//! a compiled mechanism whose file changed after its code was generated runs interpreted from
//! the file, with a note, never as the stale code.
//!
//! Interpreted entries live as long as the program (the solvers take `&'static` mechanisms,
//! as for compiled ones); each distinct file text is loaded once and then reused.

use crate::scenario::ScenarioError;
use std::collections::HashMap;
use std::path::Path;
use std::sync::{Mutex, OnceLock};
use symbody_codegen::model::Parameter;
use symbody_runtime::registry::{Built, Formulations, Reduced, RunTime};
use symbody_runtime::{source_hash, Entry, Formulation, Mechanism, Origin, Reduction, Registry};

/// Largest mechanism file read: far above any real one (the 13-body Stewart file is 9 KB),
/// and small enough that a wrong path (a log, a binary) is refused before it is parsed.
pub const MAX_FILE_BYTES: u64 = 1 << 20;

/// Whether `name` names a file rather than a registered mechanism.
pub fn is_path(name: &str) -> bool {
    name.ends_with(".toml") || Path::new(name).components().count() > 1
}

/// A loaded file: its entry and what the generator's front end reported.
#[derive(Clone, Copy)]
pub struct Loaded {
    pub entry: &'static Entry,
    /// Sizes, rank, mobility, redundant rows, platform and warnings, as `cargo xtask
    /// generate` prints them.
    pub report: &'static str,
    /// The file's parameters, with the values used.
    pub parameters: &'static [Parameter],
}

/// Parameter values set from outside a mechanism file: `(name, value)`.
pub type Overrides = [(String, f64)];

/// Loaded entries by (file as shown, text, (stale, with tangents), overrides as text).
type Cache = Mutex<HashMap<(String, String, (bool, bool), String), Loaded>>;

fn cache() -> &'static Cache {
    static CACHE: OnceLock<Cache> = OnceLock::new();
    CACHE.get_or_init(Default::default)
}

/// Reads a mechanism file's text: a clear error for a missing file, a directory, a file too
/// large to be one, or text that is not UTF-8 (with the line and column where it stops).
pub fn read(path: &Path) -> Result<String, ScenarioError> {
    let shown = path.display();
    let fail = |what: String| ScenarioError::Options(format!("mechanism file {shown}: {what}"));
    let meta = std::fs::metadata(path).map_err(|e| {
        fail(match e.kind() {
            std::io::ErrorKind::NotFound => {
                "no such file (give a path to a .toml mechanism file, or a name from `symbody list`)"
                    .to_string()
            }
            _ => format!("cannot read it: {e}"),
        })
    })?;
    if meta.is_dir() {
        return Err(fail(
            "is a folder; give one mechanism file in it (a .toml file)".to_string(),
        ));
    }
    if meta.len() > MAX_FILE_BYTES {
        return Err(fail(format!(
            "{} bytes, more than the {MAX_FILE_BYTES} a mechanism file may have; is this the \
             right file?",
            meta.len()
        )));
    }
    let bytes = std::fs::read(path).map_err(|e| fail(format!("cannot read it: {e}")))?;
    String::from_utf8(bytes).map_err(|e| {
        let good = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        let line = good.iter().filter(|&&b| b == b'\n').count() + 1;
        let column = good.iter().rev().take_while(|&&b| b != b'\n').count() + 1;
        fail(format!(
            "not UTF-8 text: the bytes at line {line}, column {column} are no character; save \
             the file as UTF-8"
        ))
    })
}

/// The mechanism file at `path`, interpreted (loaded once per distinct text).
pub fn load(path: &Path) -> Result<Loaded, ScenarioError> {
    load_with(path, &[])
}

/// [`load`] with some of the file's parameters set to other values.
pub fn load_with(path: &Path, parameters: &Overrides) -> Result<Loaded, ScenarioError> {
    let text = read(path)?;
    load_text(
        &path.display().to_string(),
        &text,
        (false, false),
        parameters,
    )
}

/// The mechanism `name` (a registered name or a file path) with `parameters` set: the
/// registered mechanism's file is interpreted with the new values (its compiled code has the
/// file's). No parameters: [`crate::generic::find`].
pub fn with_parameters(
    registry: &Registry,
    name: &str,
    parameters: &Overrides,
) -> Result<&'static Entry, ScenarioError> {
    if parameters.is_empty() {
        return crate::generic::find(registry, name);
    }
    if is_path(name) {
        return load_with(Path::new(name), parameters).map(|l| l.entry);
    }
    reparametrized(crate::generic::find(registry, name)?, parameters)
}

/// The file `entry` comes from with `parameters` set (the file's values for the others,
/// whatever `entry` was built with): its compiled code where every one is a run-time
/// parameter of it by name ([`compiled_at`]), or where the code takes the numbers the file
/// gives at these values ([`crate::compiled_numbers::compiled_at`]), else the file derived
/// again and interpreted.
pub fn reparametrized(
    entry: &Entry,
    parameters: &Overrides,
) -> Result<&'static Entry, ScenarioError> {
    if let Some(e) = compiled_at(entry, parameters)? {
        return Ok(e);
    }
    match crate::compiled_numbers::compiled_at(entry, parameters)? {
        Ok(e) => Ok(e),
        Err(why) => {
            let derived = derive(entry, parameters)?.entry;
            if let Some(why) = why {
                declined()
                    .lock()
                    .unwrap_or_else(|e| e.into_inner())
                    .insert(derived as *const Entry as usize, why);
            }
            Ok(derived)
        }
    }
}

/// Why the compiled code did not take the values an interpreted entry was derived with, by
/// the entry's address (entries live as long as the program), for [`note`].
fn declined() -> &'static Mutex<HashMap<usize, String>> {
    static DECLINED: OnceLock<Mutex<HashMap<usize, String>>> = OnceLock::new();
    DECLINED.get_or_init(Default::default)
}

/// `f` on `entry`'s compiled code at `parameters`, as [`compiled_at`] (or
/// [`crate::compiled_numbers::compiled_at`]) builds it but freed when `f` returns (a study's
/// row); `None` where neither applies.
pub fn with_compiled_at<R>(
    entry: &Entry,
    parameters: &Overrides,
    f: impl FnOnce(&Entry) -> R,
) -> Result<Option<R>, ScenarioError> {
    let Some((rt, file, hash)) = run_time_route(entry, parameters) else {
        return crate::compiled_numbers::with_compiled_at(entry, parameters, f);
    };
    let set = static_names(rt, parameters);
    let (built, built_reduced) = build(entry, rt, &set)?;
    fn refs(b: &[(Formulation, Box<dyn Mechanism + Sync>)]) -> Vec<Listed<'_>> {
        b.iter().map(|(f, m)| (*f, &**m)).collect()
    }
    let (full, reduced_built) = (refs(&built), built_reduced.as_deref().map(refs));
    let reduced = entry.reduced.as_ref().map(|r| {
        let list: &[Listed<'_>] = reduced_built.as_deref().unwrap_or(r.formulations);
        (list, r.reduction)
    });
    Ok(Some(with_scoped_entry(
        entry,
        (file, hash),
        (&full, reduced),
        &set,
        f,
    )))
}

/// One formulation's mechanism, as an entry lists them.
pub(crate) type Listed<'a> = (Formulation, &'a (dyn Mechanism + Sync));

/// `entry` over other mechanisms (`full`, and `reduced` with its reduction), its origin the
/// compiled code of `file` (source hash `hash`) at `parameters`.
pub(crate) fn compiled_entry(
    entry: &Entry,
    (file, hash): (&'static str, u64),
    (full, reduced): (Formulations, Option<(Formulations, &'static Reduction)>),
    parameters: &'static [(&'static str, f64)],
) -> Entry {
    Entry {
        name: entry.name,
        t_end: entry.t_end,
        formulations: full,
        reduced: reduced.map(|(formulations, reduction)| Reduced {
            formulations,
            reduction,
        }),
        origin: Origin::Compiled {
            file,
            hash,
            parameters,
        },
        run_time: entry.run_time,
    }
}

/// `f` on [`compiled_entry`] over borrowed mechanisms and names, which outlive the call.
pub(crate) fn with_scoped_entry<R>(
    entry: &Entry,
    origin: (&'static str, u64),
    (full, reduced): (&[Listed<'_>], Option<(&[Listed<'_>], &'static Reduction)>),
    parameters: &[(&str, f64)],
    f: impl FnOnce(&Entry) -> R,
) -> R {
    // SAFETY: the entry and every reference in it are dropped when `f` returns, while the
    // borrowed lists and names still live; `f` gets the entry by reference only, and the
    // runs reduce what they record to numbers (the contract of `interpret::load_scoped`).
    let forever =
        |l: &[Listed<'_>]| unsafe { std::mem::transmute::<&[Listed<'_>], Formulations>(l) };
    let set = unsafe {
        std::mem::transmute::<&[(&str, f64)], &'static [(&'static str, f64)]>(parameters)
    };
    let lists = (forever(full), reduced.map(|(r, red)| (forever(r), red)));
    f(&compiled_entry(entry, origin, lists, set))
}

/// Every formulation of `entry`'s compiled code at `set`, and of its reduced model where it
/// has one that takes run-time parameters (a reduced model that reads none of them, as the
/// planar four-bar's with the inertia about the links' own axes, serves any values as it is).
fn build(
    entry: &Entry,
    rt: &RunTime,
    set: &[(&'static str, f64)],
) -> Result<(Built, Option<Built>), ScenarioError> {
    let refused = |e: symbody_runtime::parameters::ParameterError| {
        ScenarioError::Options(format!("`{}`: {e}", entry.name))
    };
    let full = (rt.build)(set).map_err(refused)?;
    let reduced = match (&entry.reduced, rt.build_reduced) {
        (Some(_), Some(b)) => Some(b(set).map_err(refused)?),
        _ => None,
    };
    Ok((full, reduced))
}

/// The run-time parameters of `entry`'s compiled code, its file and hash, when `parameters`
/// is not empty, sets only those, and the file has not changed since the code was generated.
fn run_time_route(
    entry: &Entry,
    parameters: &Overrides,
) -> Option<(&'static RunTime, &'static str, u64)> {
    let (Some(rt), Origin::Compiled { file, hash, .. }) = (entry.run_time, entry.origin) else {
        return None;
    };
    let run_time = |k: &String| rt.parameters.names.contains(&k.as_str());
    if parameters.is_empty() || !parameters.iter().all(|(k, _)| run_time(k)) {
        return None;
    }
    // A file changed since its code was generated is derived again, as `fresh` does.
    if std::fs::read_to_string(file).is_ok_and(|t| source_hash(&t) != hash) {
        return None;
    }
    Some((rt, file, hash))
}

/// `parameters` named by the compiled code's own strings (every name is one of them: see
/// [`run_time_route`]).
fn static_names(rt: &RunTime, parameters: &Overrides) -> Vec<(&'static str, f64)> {
    parameters
        .iter()
        .filter_map(|(k, v)| Some((*rt.parameters.names.iter().find(|n| **n == k)?, *v)))
        .collect()
}

/// `entry`'s compiled code at `parameters` (the file's values for the others), when its file
/// is unchanged and every one of them is a run-time parameter of that code (they reach only
/// masses, inertias and springs' constants: decision 35); `None` otherwise. Lives as long as
/// the program, as interpreted entries do.
pub fn compiled_at(
    entry: &Entry,
    parameters: &Overrides,
) -> Result<Option<&'static Entry>, ScenarioError> {
    let Some((rt, file, hash)) = run_time_route(entry, parameters) else {
        return Ok(None);
    };
    let set = static_names(rt, parameters);
    let (built, built_reduced) = build(entry, rt, &set)?;
    let leaked = |b: Built| -> Formulations {
        let l: Vec<_> = b.into_iter().map(|(f, m)| (f, &*Box::leak(m))).collect();
        Box::leak(l.into_boxed_slice())
    };
    let reduced = entry
        .reduced
        .as_ref()
        .map(|r| (built_reduced.map_or(r.formulations, leaked), r.reduction));
    let lists = (leaked(built), reduced);
    let set = Box::leak(set.into_boxed_slice());
    Ok(Some(Box::leak(Box::new(compiled_entry(
        entry,
        (file, hash),
        lists,
        set,
    )))))
}

/// The file `entry` comes from, loaded with `parameters` set.
pub fn derive(entry: &Entry, parameters: &Overrides) -> Result<Loaded, ScenarioError> {
    let (file, text) = file_text(entry)?;
    load_text(&file, &text, (false, false), parameters)
}

/// [`derive`], the mechanisms also giving the equations' directional derivatives
/// (`Mechanism::tangents`), as sensitivities need of an interpreted base.
pub fn derive_with_tangents(
    entry: &Entry,
    parameters: &Overrides,
) -> Result<Loaded, ScenarioError> {
    let (file, text) = file_text(entry)?;
    load_text(&file, &text, (false, true), parameters)
}

/// The path and text of the file `entry` comes from.
fn file_text(entry: &Entry) -> Result<(String, String), ScenarioError> {
    let file = source_of(entry)?;
    let text = read(Path::new(&file))?;
    Ok((file, text))
}

/// The file `entry` comes from, loaded with `parameters` set as far as its parameters'
/// values (nothing derived): what listing or checking parameter names needs.
pub fn model_parameters(
    entry: &Entry,
    parameters: &Overrides,
) -> Result<Vec<symbody_codegen::model::Parameter>, ScenarioError> {
    let (file, text) = file_text(entry)?;
    symbody_codegen::model::load_with(&file, &text, parameters)
        .map(|m| m.parameters)
        .map_err(|e| {
            // `main` and the bindings add their own `error:` before the first message.
            let shown = e.to_string();
            ScenarioError::Options(shown.strip_prefix("error: ").unwrap_or(&shown).to_string())
        })
}

/// `base` with the values of `over` set on top (replacing those of the same name).
pub fn merged(base: &Overrides, over: &Overrides) -> Vec<(String, f64)> {
    let mut all = base.to_vec();
    for (k, v) in over {
        all.retain(|(p, _)| p != k);
        all.push((k.clone(), *v));
    }
    all
}

/// The file `entry` was generated or interpreted from, as it can be opened now.
pub fn source_of(entry: &Entry) -> Result<String, ScenarioError> {
    let file = match entry.origin {
        Origin::Compiled { file, .. } | Origin::Interpreted { file, .. } => file,
    };
    match Path::new(file).canonicalize() {
        Ok(p) => Ok(p.display().to_string()),
        Err(_) => Err(ScenarioError::Options(format!(
            "`{}`: its mechanism file {file} is not here (this program was installed without \
             its source tree); parameters are set on the file, so give the file's path instead",
            entry.name
        ))),
    }
}

/// The parameters of mechanism `name` (a registered name or a file path): names, values,
/// derived ones' expressions and the items each affects.
pub fn parameters(registry: &Registry, name: &str) -> Result<Loaded, ScenarioError> {
    if is_path(name) {
        return load(Path::new(name));
    }
    derive(crate::generic::find(registry, name)?, &[])
}

/// The names of the parameters of the file `entry` comes from.
pub fn parameter_names(entry: &Entry) -> Result<Vec<String>, ScenarioError> {
    Ok(model_parameters(entry, &[])?
        .into_iter()
        .map(|p| p.name)
        .collect())
}

fn load_text(
    source: &str,
    text: &str,
    (stale, tangents): (bool, bool),
    parameters: &Overrides,
) -> Result<Loaded, ScenarioError> {
    let key = (
        source.to_string(),
        text.to_string(),
        (stale, tangents),
        format!("{parameters:?}"),
    );
    if let Some(&l) = cache().lock().unwrap_or_else(|e| e.into_inner()).get(&key) {
        return Ok(l);
    }
    let load = match tangents {
        true => symbody_codegen::interpret::load_with_tangents,
        false => symbody_codegen::interpret::load_with,
    };
    let loaded = load(source, text, parameters, stale).map_err(|e| {
        let shown = e.to_string();
        // `main` and the bindings add their own `error:` before the first message.
        let shown = shown.strip_prefix("error: ").unwrap_or(&shown).to_string();
        ScenarioError::Options(match parameters.is_empty() {
            true => shown,
            false => {
                let set: Vec<String> = parameters
                    .iter()
                    .map(|(k, v)| format!("{k} = {v}"))
                    .collect();
                format!("with {} set: {shown}", set.join(", "))
            }
        })
    })?;
    let report = Box::leak(loaded.report.to_string().into_boxed_str());
    let l = Loaded {
        entry: loaded.entry,
        report,
        parameters: Box::leak(loaded.parameters.into_boxed_slice()),
    };
    cache()
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .insert(key, l);
    Ok(l)
}

/// `entry` itself, or, when it is compiled and its file (still where it was when the program
/// was built) has changed since its code was generated, the file interpreted. A changed file
/// that no longer loads is an error with its diagnostics, not a silent run of the old code.
pub fn fresh(entry: &'static Entry) -> Result<&'static Entry, ScenarioError> {
    let Origin::Compiled {
        file,
        hash,
        parameters,
    } = entry.origin
    else {
        return Ok(entry);
    };
    // Installed without its source tree (a wheel, a copied binary): nothing to compare.
    let Ok(text) = std::fs::read_to_string(file) else {
        return Ok(entry);
    };
    if source_hash(&text) == hash {
        return Ok(entry);
    }
    let shown = Path::new(file)
        .canonicalize()
        .map_or_else(|_| file.to_string(), |p| p.display().to_string());
    let set: Vec<(String, f64)> = parameters
        .iter()
        .map(|(k, v)| (k.to_string(), *v))
        .collect();
    load_text(&shown, &text, (true, false), &set)
        .map(|l| l.entry)
        .map_err(|e| {
            ScenarioError::Options(format!(
                "{e}\n(`{}` changed since its code was generated, and the compiled code is not \
                 run in its place; fix the file, or restore it)",
                entry.name
            ))
        })
}

/// What a summary says about where `entry`'s equations come from, when they are not the
/// compiled code of its current file.
pub fn note(entry: &Entry) -> Option<String> {
    match entry.origin {
        Origin::Compiled { parameters, .. } if !parameters.is_empty() => {
            let set: Vec<String> = parameters
                .iter()
                .map(|(k, v)| format!("{k} = {v}"))
                .collect();
            let by_name = |k: &str| {
                entry
                    .run_time
                    .is_some_and(|rt| rt.parameters.names.contains(&k))
            };
            if parameters.iter().all(|(k, _)| by_name(k)) {
                return Some(format!(
                    "compiled, with run-time parameters {} (nothing re-derived)",
                    set.join(", ")
                ));
            }
            // The structure the generator found for the file's values is the compiled code's.
            let file_values = entry.run_time.and_then(|rt| (rt.build)(&[]).ok());
            let changed = file_values
                .and_then(|b| {
                    let (_, m) = b.first()?;
                    structure_change(m.info(), entry.default_mechanism().info())
                })
                .map(|c| format!("; with these values {c}"))
                .unwrap_or_default();
            Some(format!(
                "compiled, with {} (the code takes the numbers the file gives at these values; \
                 the file derived again for its pose and dependent rows){changed}",
                set.join(", ")
            ))
        }
        Origin::Compiled { .. } => None,
        Origin::Interpreted {
            file, parameters, ..
        } if !parameters.is_empty() => {
            let set: Vec<String> = parameters
                .iter()
                .map(|(k, v)| format!("{k} = {v}"))
                .collect();
            let default = read(Path::new(file))
                .and_then(|text| load_text(file, &text, (false, false), &[]))
                .ok();
            let mut changed = default
                .and_then(|d| {
                    let info = |e: &Entry| e.default_mechanism().info();
                    structure_change(info(d.entry), info(entry))
                })
                .map(|c| format!("; with these values {c}"))
                .unwrap_or_default();
            let key = entry as *const Entry as usize;
            if let Some(why) = declined()
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .get(&key)
            {
                changed += &format!("; the compiled code does not take them: {why}");
            }
            Some(format!(
                "interpreted from {file} with {} (the file's equations re-derived for these \
                 values; compiled code keeps the file's){changed}",
                set.join(", ")
            ))
        }
        Origin::Interpreted {
            file, stale: false, ..
        } => Some(format!(
            "interpreted from {file} (nothing compiled); the compiled route evaluates faster \
             (BENCHMARKS.md, \"Interpreted and compiled\"): put the file in mechanisms/ and run \
             `cargo xtask generate {}`",
            entry.name
        )),
        Origin::Interpreted {
            file, stale: true, ..
        } => Some(format!(
            "interpreted from {file}: the compiled `{0}` is stale (the file changed after `cargo \
             xtask generate {0}`); regenerate it to run compiled again",
            entry.name
        )),
    }
}

/// How the structure the generator found (dependent rows, degrees of freedom, a platform for
/// forward kinematics) differs from `a` (the file's own values) to `b`.
fn structure_change(
    a: &symbody_runtime::MechanismInfo,
    b: &symbody_runtime::MechanismInfo,
) -> Option<String> {
    let rows = |i: &symbody_runtime::MechanismInfo| -> Vec<&str> {
        i.redundant_rows
            .iter()
            .map(|&r| i.row_names[r as usize])
            .collect()
    };
    let mut changes = Vec::new();
    if rows(a) != rows(b) {
        let list = |r: Vec<&str>| match r.is_empty() {
            true => "none".to_string(),
            false => r.join(", "),
        };
        changes.push(format!(
            "the dependent rows change from {} to {}",
            list(rows(a)),
            list(rows(b))
        ));
    }
    if a.dof() != b.dof() {
        changes.push(format!("the DOF change from {} to {}", a.dof(), b.dof()));
    }
    if a.platform.is_some() != b.platform.is_some() {
        changes.push(match b.platform {
            Some(_) => "it becomes a six-leg platform (fk applies)".to_string(),
            None => "it is no longer a six-leg platform (fk does not apply)".to_string(),
        });
    }
    (!changes.is_empty()).then(|| changes.join("; "))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;
    use symbody_mechanisms::REGISTRY;

    /// A compiled entry whose file is a copy in a temporary folder, so the test may edit it.
    fn entry_with_file(dir: &Path) -> (&'static Entry, PathBuf, String) {
        let shipped = REGISTRY.find("slider_crank").unwrap();
        let Origin::Compiled { file, hash, .. } = shipped.origin else {
            panic!("compiled")
        };
        let text = std::fs::read_to_string(file).unwrap();
        let copy = dir.join("slider_crank.toml");
        std::fs::write(&copy, &text).unwrap();
        let leaked: &'static str = Box::leak(copy.display().to_string().into_boxed_str());
        let entry = Box::leak(Box::new(Entry {
            name: shipped.name,
            t_end: shipped.t_end,
            formulations: shipped.formulations,
            reduced: None,
            origin: Origin::Compiled {
                file: leaked,
                hash,
                parameters: &[],
            },
            run_time: None,
        }));
        (entry, copy, text)
    }

    #[test]
    fn a_changed_file_runs_interpreted_and_a_broken_one_is_an_error() {
        let dir = std::env::temp_dir().join(format!("symbody-stale-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let (entry, copy, text) = entry_with_file(&dir);
        // Unchanged: the compiled code itself.
        assert!(std::ptr::eq(fresh(entry).unwrap(), entry));
        // The crank made longer: the file's equations, flagged as replacing stale code.
        let edited = text.replacen("r = 0.1 ", "r = 0.12 ", 1);
        assert_ne!(edited, text, "the test edits the crank radius");
        std::fs::write(&copy, &edited).unwrap();
        let now = fresh(entry).unwrap();
        assert!(matches!(
            now.origin,
            Origin::Interpreted { stale: true, .. }
        ));
        let crank = |e: &Entry| e.default_mechanism().info().q0.to_vec();
        assert_ne!(
            crank(now),
            crank(entry),
            "the edited pose, not the compiled one"
        );
        assert!(note(now).unwrap().contains("stale"));
        // Broken: an error with the file's diagnostics, never the old code.
        std::fs::write(&copy, "name = \"slider_crank\"\n[[body]]\n").unwrap();
        let e = fresh(entry).unwrap_err().to_string();
        assert!(e.contains("changed since its code was generated"), "{e}");
        assert!(e.contains("slider_crank.toml"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
