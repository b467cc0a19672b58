//! Reading a scene file: TOML into a [`Scene`], every mistake reported with file, line,
//! column, the item and what to do (the mechanism files' diagnostics, `symbody_codegen::diag`).

use serde::Deserialize;
use std::path::Path;
use symbody_codegen::diag::{Diagnostic, Errors, SourceMap};
use symbody_runtime::{Entry, Formulation, JointKind, Registry};
use toml::Spanned;

use super::{Files, PathRequest, Scene, Selection};
use crate::generic::{closest, mechanism};
use crate::study::{Axis, Metric, Study};

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawScene {
    mechanism: Spanned<String>,
    formulation: Option<Spanned<String>>,
    time: Option<RawTime>,
    outputs: Option<RawOutputs>,
    solver: Option<RawSolver>,
    /// The mechanism file's parameters set to other values (name = number).
    parameters: Option<Spanned<std::collections::BTreeMap<String, f64>>>,
    study: Option<Spanned<RawStudy>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawStudy {
    parameters: Spanned<std::collections::BTreeMap<Spanned<String>, Spanned<toml::Value>>>,
    samples: Option<Spanned<i64>>,
    seed: Option<Spanned<i64>>,
    latin: Option<bool>,
    metrics: Option<Spanned<Vec<Spanned<String>>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTime {
    end: Option<Spanned<f64>>,
    output_step: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawOutputs {
    poses: Option<Spanned<toml::Value>>,
    velocities: Option<Spanned<bool>>,
    accelerations: Option<Spanned<bool>>,
    reactions: Option<Spanned<toml::Value>>,
    efforts: Option<bool>,
    energy: Option<bool>,
    files: Option<Spanned<String>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSolver {
    path: Option<Spanned<String>>,
    step: Option<Spanned<f64>>,
    rtol: Option<Spanned<f64>>,
    atol: Option<Spanned<f64>>,
    alpha: Option<Spanned<f64>>,
    cross_singular_positions: Option<Spanned<bool>>,
    reduce: Option<Spanned<String>>,
}

/// Reads and checks the scene in `text`; `file` names it in messages.
pub fn load(registry: &Registry, file: &str, text: &str) -> Result<Scene, Errors> {
    let map = SourceMap { file, text };
    if let Some(d) = mechanism_file(registry, &map) {
        return Err(Errors(vec![d]));
    }
    let raw: RawScene = toml::from_str(text).map_err(|e| {
        let span = e.span().unwrap_or(0..0);
        let message = e.message().trim().to_string();
        let help = symbody_codegen::diag::toml_error_help(&message).replace(
            "the TOML syntax at this place",
            "the TOML at this place (docs/scenes.md lists every field)",
        );
        Errors(vec![map.diag(span, "the scene", &message, help)])
    })?;
    let mut errors = Vec::new();
    let scene = check(registry, &map, raw, &mut errors);
    match scene {
        Some(s) if errors.is_empty() => Ok(s),
        _ => Err(Errors(errors)),
    }
}

/// A mechanism file (bodies and joints, no `mechanism` key) given where a scene belongs: the
/// scene parser alone would only see unknown fields (`name`, with a typo's "did you mean
/// `time`?"), so say what the file is and which command takes it.
fn mechanism_file(registry: &Registry, map: &SourceMap<'_>) -> Option<Diagnostic> {
    let table: toml::Table = toml::from_str(map.text).ok()?;
    if table.contains_key("mechanism")
        || !(table.contains_key("body") || table.contains_key("joint"))
    {
        return None;
    }
    let name = table.get("name").and_then(|n| n.as_str());
    let help = match name {
        Some(n) if registry.find(n).is_some() => {
            let scene = std::path::Path::new(map.file)
                .parent()
                .and_then(|d| d.parent())
                .map(|root| root.join("scenes").join(format!("{n}.toml")))
                .filter(|p| p.is_file())
                .map(|p| format!(", or run its scene: `symbody run {}`", p.display()))
                .unwrap_or_default();
            format!("simulate it by name: `symbody simulate {n}`{scene}")
        }
        Some(n) => format!(
            "generate it first (`cargo xtask generate {n}`), then `symbody simulate {n}`, or \
             write a scene with `mechanism = \"{n}\"` (docs/scenes.md)"
        ),
        None => "give `run` a scene file (scenes/<name>.toml, docs/scenes.md)".to_string(),
    };
    Some(map.diag(
        0..0,
        "the file",
        "this is a mechanism file (bodies and joints), not a scene: `symbody run` takes a \
         scene, which names a mechanism and says what to compute",
        help,
    ))
}

fn check(
    registry: &Registry,
    map: &SourceMap<'_>,
    raw: RawScene,
    errors: &mut Vec<Diagnostic>,
) -> Option<Scene> {
    let name = raw.mechanism.get_ref();
    let parameters: Vec<(String, f64)> = raw
        .parameters
        .as_ref()
        .map(|p| p.get_ref().iter().map(|(k, v)| (k.clone(), *v)).collect())
        .unwrap_or_default();
    let found = if crate::files::is_path(name) {
        // Relative to the scene file, so a scene and its mechanism move together.
        let dir = Path::new(map.file).parent().unwrap_or(Path::new(""));
        Some(crate::files::load_with(&dir.join(name), &parameters).map(|l| l.entry))
    } else {
        registry.find(name).map(|e| match parameters.is_empty() {
            true => crate::files::fresh(e),
            false => crate::files::reparametrized(e, &parameters),
        })
    };
    let entry = match found {
        Some(Ok(entry)) => entry,
        Some(Err(e)) => {
            let (span, item, help) = match &raw.parameters {
                Some(p) => (
                    p.span(),
                    "`[parameters]`",
                    "the mechanism with these parameter values could not be built (a path is read relative to the scene file)",
                ),
                None => (
                    raw.mechanism.span(),
                    "`mechanism`",
                    "a path is read relative to the scene file",
                ),
            };
            errors.push(map.diag(span, item, e.to_string(), help));
            return None;
        }
        None => {
            let known = registry.names();
            let help = match closest(name, known.iter().copied()) {
                Some(s) => format!("did you mean `{s}`? Or give the path of a mechanism file"),
                None => format!(
                    "known mechanisms: {}; or give the path of a mechanism file (e.g. \"{name}.toml\", relative to the scene)",
                    known.join(", ")
                ),
            };
            errors.push(map.diag(
                raw.mechanism.span(),
                "`mechanism`",
                format!("no mechanism `{name}`"),
                help,
            ));
            return None;
        }
    };
    let formulation = match &raw.formulation {
        None => None,
        Some(f) => match f.get_ref().as_str() {
            "exact" => Some(Formulation::Exact),
            "paper" => Some(Formulation::Paper),
            other => {
                errors.push(map.diag(
                    f.span(),
                    "`formulation`",
                    format!("unknown formulation `{other}`"),
                    "use \"exact\" or \"paper\"",
                ));
                return None;
            }
        },
    };
    let mech = match mechanism(entry, formulation) {
        Ok(m) => m,
        Err(e) => {
            let span = raw.formulation.as_ref().map_or(0..0, |f| f.span());
            errors.push(map.diag(
                span,
                "`formulation`",
                e.to_string(),
                "pick a generated formulation",
            ));
            return None;
        }
    };
    let info = mech.info();

    let time = raw.time.unwrap_or(RawTime {
        end: None,
        output_step: None,
    });
    let t_end =
        positive(map, errors, time.end.as_ref(), "[time] `end`", true).unwrap_or(entry.t_end);
    let output_step = positive(
        map,
        errors,
        time.output_step.as_ref(),
        "[time] `output_step`",
        false,
    )
    .unwrap_or(0.01);

    let outputs = raw.outputs.unwrap_or(RawOutputs {
        poses: None,
        velocities: None,
        accelerations: None,
        reactions: None,
        efforts: None,
        energy: None,
        files: None,
    });
    let bodies: Vec<&str> = info.bodies.iter().map(|b| b.name).collect();
    let poses = selection(
        map,
        errors,
        outputs.poses.as_ref(),
        "[outputs] `poses`",
        "body",
        &bodies,
        |_| true,
    );
    let joints: Vec<&str> = info.joints.iter().map(|j| j.name).collect();
    let reactions = selection(
        map,
        errors,
        outputs.reactions.as_ref(),
        "[outputs] `reactions`",
        "joint",
        &joints,
        |j| {
            !matches!(
                info.joints[j].kind,
                JointKind::Driver | JointKind::Normalization
            )
        },
    );
    let files = match &outputs.files {
        None => Files::Tables,
        Some(f) => match f.get_ref().as_str() {
            "tables" => Files::Tables,
            "paper" => {
                if let Err(e) = crate::scenario::Layout::find(info) {
                    errors.push(map.diag(
                        f.span(),
                        "[outputs] `files`",
                        format!("the paper scenario's files need its names: {e}"),
                        "use files = \"tables\" for this mechanism",
                    ));
                }
                Files::Paper
            }
            other => {
                errors.push(map.diag(
                    f.span(),
                    "[outputs] `files`",
                    format!("unknown files `{other}`"),
                    "use \"tables\" (bodies, joints, drivers, energy CSVs) or \"paper\" (the paper scenario's CSVs and figures)",
                ));
                Files::Tables
            }
        },
    };

    // Columns of bodies.csv, which the paper scenario's files do not have.
    let mut bodies_column =
        |key: &Option<Spanned<bool>>, name: &str, columns: &str| match (key, files) {
            (Some(v), Files::Paper) if *v.get_ref() => {
                errors.push(map.diag(
                    v.span(),
                    format!("[outputs] `{name}`"),
                    format!("the paper scenario's files have no bodies table to add {name} to"),
                    format!("remove it, or use files = \"tables\" (bodies.csv gets {columns})"),
                ));
                false
            }
            (v, _) => v.as_ref().is_some_and(|v| *v.get_ref()),
        };
    let velocities = bodies_column(&outputs.velocities, "velocities", "<body>.vx … .wz");
    let accelerations = bodies_column(
        &outputs.accelerations,
        "accelerations",
        "<body>.ax … .alphaz",
    );

    let solver = raw.solver.unwrap_or(RawSolver {
        path: None,
        step: None,
        rtol: None,
        atol: None,
        alpha: None,
        cross_singular_positions: None,
        reduce: None,
    });
    let path = match &solver.path {
        None => PathRequest::Auto,
        Some(p) => match p.get_ref().as_str() {
            "auto" => PathRequest::Auto,
            "kinematic" => PathRequest::Kinematic,
            "integrate" => PathRequest::Integrate,
            other => {
                errors.push(map.diag(
                    p.span(),
                    "[solver] `path`",
                    format!("unknown path `{other}`"),
                    "use \"auto\" (kinematic when exact, else integrate), \"kinematic\" or \"integrate\"",
                ));
                PathRequest::Auto
            }
        },
    };
    let reduce = match &solver.reduce {
        None => false,
        Some(r) => match r.get_ref().as_str() {
            "auto" => true,
            "off" => false,
            other => {
                errors.push(map.diag(
                    r.span(),
                    "[solver] `reduce`",
                    format!("unknown reduce `{other}`"),
                    "use \"auto\" (run the generated reduced model where there is one) or \"off\"",
                ));
                false
            }
        },
    };
    let step =
        positive(map, errors, solver.step.as_ref(), "[solver] `step`", false).unwrap_or(1e-3);
    // Either tolerance turns step-size control on, the other then taking its value; a
    // `step` beside them is the first step tried (not ambiguous, so not refused).
    let rtol = tolerance(map, errors, solver.rtol.as_ref(), "[solver] `rtol`");
    let atol = tolerance(map, errors, solver.atol.as_ref(), "[solver] `atol`");
    let tolerances = match (rtol, atol) {
        (Some(r), Some(a)) => Some((r, a)),
        (Some(t), None) | (None, Some(t)) => Some((t, t)),
        (None, None) => None,
    };
    let alpha = match &solver.alpha {
        None => match files {
            Files::Paper => crate::scenario::Options::default().alpha,
            Files::Tables => crate::generic::Options::default().alpha,
        },
        Some(a) => {
            let v = *a.get_ref();
            if !(-1.0 / 3.0..=0.0).contains(&v) {
                errors.push(map.diag(
                    a.span(),
                    "[solver] `alpha`",
                    format!("HHT α must lie in [−1/3, 0], got {v}"),
                    "0 adds no numerical damping; −0.05 damps the highest frequencies a little",
                ));
            }
            v
        }
    };
    let cross_singular = match (&solver.cross_singular_positions, files) {
        (Some(c), Files::Paper) if *c.get_ref() => {
            errors.push(map.diag(
                c.span(),
                "[solver] `cross_singular_positions`",
                "the paper's files run the paper scenario, which has no singular position to cross",
                "remove it, or use files = \"tables\"",
            ));
            false
        }
        (c, _) => c.as_ref().is_some_and(|c| *c.get_ref()),
    };
    let study = raw
        .study
        .as_ref()
        .and_then(|st| study(map, errors, st, entry));
    Some(Scene {
        study,
        file: map.file.to_string(),
        mechanism: entry.name,
        entry,
        parameters,
        formulation: info.formulation,
        t_end,
        output_step,
        poses,
        velocities,
        accelerations,
        reactions,
        efforts: outputs.efforts.unwrap_or(true),
        energy: outputs.energy.unwrap_or(true),
        files,
        path,
        step,
        tolerances,
        alpha,
        cross_singular,
        reduce,
        path_thread: true,
        states: false,
    })
}

/// A scene's `[study]`, checked against the mechanism file's parameters.
fn study(
    map: &SourceMap<'_>,
    errors: &mut Vec<Diagnostic>,
    raw: &Spanned<RawStudy>,
    entry: &Entry,
) -> Option<Study> {
    let st = raw.get_ref();
    let known: Vec<String> = match crate::files::parameter_names(entry) {
        Ok(k) => k,
        Err(e) => {
            errors.push(map.diag(
                raw.span(),
                "`[study]`",
                e.to_string(),
                "a study varies the parameters of the mechanism file",
            ));
            return None;
        }
    };
    let before = errors.len();
    let mut axes = Vec::new();
    if st.parameters.get_ref().is_empty() {
        errors.push(map.diag(
            st.parameters.span(),
            "[study] `parameters`",
            "no parameter to vary",
            "e.g. parameters = { r = { from = 0.08, to = 0.12, n = 5 } }",
        ));
    }
    for (name, value) in st.parameters.get_ref() {
        let item = format!("[study.parameters] `{}`", name.get_ref());
        if !known.iter().any(|k| k == name.get_ref()) {
            let help = match closest(name.get_ref(), known.iter().map(String::as_str)) {
                Some(c) => format!("did you mean `{c}`? (`symbody params` lists them)"),
                None => format!("the file's parameters: {}", known.join(", ")),
            };
            errors.push(map.diag(
                name.span(),
                &item,
                format!("no parameter `{}` in the mechanism file", name.get_ref()),
                help,
            ));
            continue;
        }
        match axis(value.get_ref()) {
            Ok(a) => axes.push((name.get_ref().clone(), a)),
            Err((message, help)) => errors.push(map.diag(value.span(), &item, message, help)),
        }
    }
    let random = axes.iter().any(|(_, a)| a.is_random());
    if random {
        for (name, a) in &axes {
            if !a.is_random() {
                errors.push(map.diag(
                    st.parameters.span(),
                    "[study] `parameters`",
                    format!("`{name}` takes fixed values among random parameters"),
                    "make every parameter random ({ uniform = [lo, hi] } or { normal = [mean, sd] }), or none; run one study per fixed value",
                ));
            }
        }
    }
    let samples = match (&st.samples, random) {
        (Some(n), _) if *n.get_ref() < 1 => {
            errors.push(map.diag(
                n.span(),
                "[study] `samples`",
                format!("samples = {}: no row to run", n.get_ref()),
                "give at least 1",
            ));
            0
        }
        (Some(n), _) => *n.get_ref() as usize,
        (None, true) => {
            errors.push(map.diag(
                raw.span(),
                "`[study]`",
                "random parameters need `samples`",
                "e.g. samples = 100 (and seed = 1)",
            ));
            0
        }
        (None, false) => 0,
    };
    let seed = st.seed.as_ref().map_or(1, |s| *s.get_ref() as u64);
    let metrics = st
        .metrics
        .as_ref()
        .map(|list| metrics(map, errors, list, entry));
    if errors.len() > before {
        return None;
    }
    Some(Study {
        parameters: axes,
        samples,
        seed,
        latin: st.latin.unwrap_or(false),
        metrics,
    })
}

/// A `[study]`'s `metrics`, each checked against the mechanism (unknown or repeated names
/// are located at the name).
fn metrics(
    map: &SourceMap<'_>,
    errors: &mut Vec<Diagnostic>,
    list: &Spanned<Vec<Spanned<String>>>,
    entry: &Entry,
) -> Vec<Metric> {
    let item = "[study] `metrics`";
    if list.get_ref().is_empty() {
        errors.push(map.diag(
            list.span(),
            item,
            "no metric to report",
            "name some, e.g. metrics = [\"max|act1|\", \"max platform.z\"], or remove the key for \
             the default set",
        ));
    }
    let info = entry.default_mechanism().info();
    let mut metrics: Vec<Metric> = Vec::new();
    for name in list.get_ref() {
        match Metric::parse(name.get_ref(), info) {
            Ok(m) if metrics.contains(&m) => errors.push(map.diag(
                name.span(),
                item,
                format!("`{}` is listed twice", name.get_ref()),
                "each metric is one column: list it once",
            )),
            Ok(m) => metrics.push(m),
            Err((message, help)) => errors.push(map.diag(name.span(), item, message, help)),
        }
    }
    metrics
}

/// One parameter's variation: `[values…]`, `{ from, to, n }`, `{ uniform = [lo, hi] }` or
/// `{ normal = [mean, sd] }`; or the message and help of what is wrong with it.
fn axis(v: &toml::Value) -> Result<Axis, (String, String)> {
    let num = |v: &toml::Value| v.as_float().or_else(|| v.as_integer().map(|i| i as f64));
    let finite = |x: Option<f64>, what: &str| -> Result<f64, (String, String)> {
        match x {
            Some(x) if x.is_finite() => Ok(x),
            _ => Err((format!("`{what}` must be a finite number"), String::new())),
        }
    };
    let pair = |v: Option<&toml::Value>, what: &str| -> Result<(f64, f64), (String, String)> {
        match v.and_then(|v| v.as_array()) {
            Some(a) if a.len() == 2 => Ok((finite(num(&a[0]), what)?, finite(num(&a[1]), what)?)),
            _ => Err((
                format!("`{what}` takes two numbers"),
                format!("e.g. {what} = [0.5, 1.5]"),
            )),
        }
    };
    let forms = "a list [a, b, …], { from = a, to = b, n = 5 }, { uniform = [lo, hi] } or { normal = [mean, sd] }".to_string();
    match v {
        toml::Value::Array(a) if a.is_empty() => Err((
            "an empty list of values".into(),
            "give at least one value".into(),
        )),
        toml::Value::Array(a) => a
            .iter()
            .map(|x| finite(num(x), "values"))
            .collect::<Result<Vec<_>, _>>()
            .map(Axis::List),
        toml::Value::Table(t) if t.contains_key("uniform") => {
            let (lo, hi) = pair(t.get("uniform"), "uniform")?;
            if lo >= hi {
                return Err((
                    format!("uniform = [{lo}, {hi}] is an empty range"),
                    "give lo < hi".into(),
                ));
            }
            Ok(Axis::Uniform { lo, hi })
        }
        toml::Value::Table(t) if t.contains_key("normal") => {
            let (mean, sd) = pair(t.get("normal"), "normal")?;
            if sd <= 0.0 {
                return Err((
                    format!("normal = [{mean}, {sd}]: the standard deviation must be positive"),
                    "give [mean, sd] with sd > 0".into(),
                ));
            }
            Ok(Axis::Normal { mean, sd })
        }
        toml::Value::Table(t)
            if t.contains_key("from") || t.contains_key("to") || t.contains_key("n") =>
        {
            let from = finite(t.get("from").and_then(num), "from")?;
            let to = finite(t.get("to").and_then(num), "to")?;
            let n = t.get("n").and_then(|n| n.as_integer()).ok_or_else(|| {
                (
                    "`n` (the number of values) is missing".to_string(),
                    "e.g. { from = 0.1, to = 0.2, n = 5 }".to_string(),
                )
            })?;
            if n < 1 {
                return Err((format!("n = {n}: no value to run"), "give n ≥ 1".into()));
            }
            if n > 1 && from == to {
                return Err((
                    format!("from = to = {from} with n = {n} is an empty range"),
                    "give different ends, or a list".into(),
                ));
            }
            Ok(Axis::Grid {
                from,
                to,
                n: n as usize,
            })
        }
        _ => Err(("not a way to vary a parameter".into(), forms)),
    }
}

/// A finite time that is positive (or, with `zero_ok`, zero), or a diagnostic.
fn positive(
    map: &SourceMap<'_>,
    errors: &mut Vec<Diagnostic>,
    v: Option<&Spanned<f64>>,
    item: &str,
    zero_ok: bool,
) -> Option<f64> {
    let v = v?;
    let x = *v.get_ref();
    if x.is_finite() && (x > 0.0 || (zero_ok && x == 0.0)) {
        Some(x)
    } else {
        errors.push(map.diag(
            v.span(),
            item,
            format!(
                "must be a finite {} time in seconds, got {x}",
                if zero_ok { "non-negative" } else { "positive" }
            ),
            "give the time in seconds, e.g. 0.01",
        ));
        None
    }
}

/// A step-size control tolerance: positive and finite.
fn tolerance(
    map: &SourceMap<'_>,
    errors: &mut Vec<Diagnostic>,
    v: Option<&Spanned<f64>>,
    item: &str,
) -> Option<f64> {
    let v = v?;
    let x = *v.get_ref();
    if x.is_finite() && x > 0.0 {
        Some(x)
    } else {
        errors.push(map.diag(
            v.span(),
            item,
            format!("a tolerance must be positive and finite, got {x}"),
            "e.g. rtol = 1e-6 (relative) and atol = 1e-6 (absolute, in the coordinates' units: m, rad, m/s, rad/s)",
        ));
        None
    }
}

/// `"all"`, `"none"` or a list of names out of `known` (`allowed` filters which indices may
/// be named).
#[allow(clippy::too_many_arguments)]
fn selection(
    map: &SourceMap<'_>,
    errors: &mut Vec<Diagnostic>,
    v: Option<&Spanned<toml::Value>>,
    item: &str,
    what: &str,
    known: &[&str],
    allowed: impl Fn(usize) -> bool,
) -> Selection {
    let Some(v) = v else {
        return Selection::All;
    };
    let help_all = format!("write \"all\", \"none\" or a list of {what} names");
    match v.get_ref() {
        toml::Value::String(s) if s == "all" => Selection::All,
        toml::Value::String(s) if s == "none" => Selection::None,
        toml::Value::Array(items) => {
            let mut picked = Vec::new();
            for it in items {
                let Some(name) = it.as_str() else {
                    errors.push(map.diag(
                        v.span(),
                        item,
                        format!("expected {what} names, found `{it}`"),
                        &help_all,
                    ));
                    continue;
                };
                match known.iter().position(|k| *k == name) {
                    Some(i) if allowed(i) => {
                        if !picked.contains(&i) {
                            picked.push(i);
                        }
                    }
                    Some(_) => errors.push(map.diag(
                        v.span(),
                        item,
                        format!("`{name}` is a driver or a normalization row, not a joint with a reaction"),
                        "its effort is in the drivers' output (`efforts = true`)",
                    )),
                    None => errors.push(map.diag(
                        v.span(),
                        item,
                        format!("no {what} `{name}` in this mechanism"),
                        match closest(name, known.iter().copied()) {
                            Some(s) => format!("did you mean `{s}`?"),
                            None => format!("its {what}s: {}", known.join(", ")),
                        },
                    )),
                }
            }
            picked.sort_unstable();
            Selection::Only(picked)
        }
        other => {
            errors.push(map.diag(
                v.span(),
                item,
                format!("expected \"all\", \"none\" or a list, found `{other}`"),
                help_all,
            ));
            Selection::All
        }
    }
}
