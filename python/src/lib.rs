//! `symbody._native`: the compiled half of the Python package `symbody` (PyO3, stable ABI).
//!
//! Every entry point calls the same Rust the command line and the C ABI call — the registry
//! ([`symbody::generic::find`]), a run and its tables ([`symbody::generic::run`],
//! [`symbody::generic::tables`]), a [`symbody::session::Session`], forward kinematics
//! ([`symbody::fk`]) and the generated [`symbody_runtime::Mechanism`] functions — so the
//! three languages print the same numbers. A mechanism is a registered name or a mechanism
//! file ([`Target`]), the file's equations interpreted ([`symbody::files`]). Vectors and matrices cross as NumPy arrays; Rust
//! errors become `ValueError` (a bad name, option or argument) or `RuntimeError` (a solver
//! failure), with the Rust message. `python/symbody/__init__.py` wraps the tables and the
//! forward-kinematics answers in small Python classes.

use nalgebra::{Matrix3, Vector3};
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2, PyReadonlyArray1, PyReadonlyArray2};
use pyo3::exceptions::{
    PyFileNotFoundError, PyIsADirectoryError, PyOSError, PyRuntimeError, PyValueError,
};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Duration;
use symbody::generic::{self, Recording};
use symbody::scenario::ScenarioError;
use symbody::scene::{Outcome, PathChoice};
use symbody::session::{self, Dyn};
use symbody::tables::Table;
use symbody_mechanisms::REGISTRY;
use symbody_runtime::fk::Pose;
use symbody_runtime::{
    Entry, Error as RuntimeError, Formulation, JointKind, MechanismInfo, Origin, PathStats, Stats,
};

/// A Rust error as the Python exception of its kind, with the Rust message in Python's
/// words.
fn py_err(e: ScenarioError) -> PyErr {
    py_err_in("", e)
}

/// [`py_err`], the message after `context`.
fn py_err_in(context: &str, e: ScenarioError) -> PyErr {
    let bad_input = match &e {
        ScenarioError::Options(_) | ScenarioError::Layout(_) => true,
        ScenarioError::Interrupted { .. } | ScenarioError::Output(_) => false,
        ScenarioError::Runtime(r) => matches!(
            r,
            RuntimeError::InvalidSetting { .. }
                | RuntimeError::DimensionMismatch { .. }
                | RuntimeError::InvalidIndex { .. }
        ),
    };
    let message = format!("{context}{}", python_words(&e.to_string()));
    if bad_input {
        PyValueError::new_err(message)
    } else {
        PyRuntimeError::new_err(message)
    }
}

/// `message` with the command line's flags (`--t-end`) as the Python arguments that set the
/// same thing (`t_end`): the library's messages are written for the command line, and a
/// Python caller never typed a flag.
fn python_words(message: &str) -> String {
    let mut out = String::with_capacity(message.len());
    let mut rest = message;
    while let Some(k) = rest.find("--") {
        out.push_str(&rest[..k]);
        let after = &rest[k + 2..];
        let len = after
            .find(|c: char| !(c.is_ascii_lowercase() || c == '-'))
            .unwrap_or(after.len());
        let name = after[..len].trim_end_matches('-');
        let at_word_start = !out.ends_with(|c: char| c.is_alphanumeric() || c == '-');
        if at_word_start && name.starts_with(|c: char| c.is_ascii_lowercase()) {
            match name {
                "from" => out.push_str("start"),
                _ => out.push_str(&name.replace('-', "_")),
            }
            rest = &after[name.len()..];
        } else {
            out.push_str("--");
            rest = after;
        }
    }
    out.push_str(rest);
    out
}

fn formulation(name: Option<&str>) -> PyResult<Option<Formulation>> {
    match name {
        None => Ok(None),
        Some("paper") => Ok(Some(Formulation::Paper)),
        Some("exact") => Ok(Some(Formulation::Exact)),
        Some(other) => Err(PyValueError::new_err(format!(
            "formulation must be \"paper\" or \"exact\" \
             (or None for the mechanism's first), got {other:?}"
        ))),
    }
}

/// What a `name` argument names: a `str` is a registered mechanism's name, or a mechanism
/// file's path when it ends in `.toml` or has a folder (as on the command line); any other
/// `os.PathLike` (`pathlib.Path`) is always a file's path.
enum Target {
    Name(String),
    File(PathBuf),
}

impl<'py> FromPyObject<'_, 'py> for Target {
    type Error = PyErr;

    fn extract(ob: Borrowed<'_, 'py, PyAny>) -> PyResult<Self> {
        if ob.is_instance_of::<PyString>() {
            return ob.extract::<String>().map(Target::Name);
        }
        ob.extract::<PathBuf>().map(Target::File).map_err(|_| {
            pyo3::exceptions::PyTypeError::new_err(format!(
                "a mechanism is a name (str) or a mechanism file's path (str or os.PathLike), \
                 not {}",
                ob.get_type()
                    .name()
                    .map_or_else(|_| "this".to_string(), |n| n.to_string())
            ))
        })
    }
}

/// The mechanism file at `path`, interpreted: `FileNotFoundError` when nothing is there,
/// `IsADirectoryError` for a folder, `OSError` when it cannot be opened, `ValueError` when it
/// is no mechanism (not UTF-8, a TOML or modelling error: the diagnostics with line:column);
/// each message names the file.
fn load_file(path: &Path) -> PyResult<&'static Entry> {
    symbody::files::load(path).map(|l| l.entry).map_err(|e| {
        let message = python_words(&e.to_string());
        match std::fs::metadata(path) {
            Err(io) if io.kind() == std::io::ErrorKind::NotFound => {
                PyFileNotFoundError::new_err(message)
            }
            Err(_) => PyOSError::new_err(message),
            Ok(m) if m.is_dir() => PyIsADirectoryError::new_err(message),
            Ok(_) => PyValueError::new_err(message),
        }
    })
}

/// The registry entry `target` names, or its file interpreted; with `params`, at those
/// parameter values (`symbody --set`: `files::with_parameters`).
fn find(target: &Target, params: Option<BTreeMap<String, f64>>) -> PyResult<&'static Entry> {
    let entry = match target {
        Target::Name(name) if symbody::files::is_path(name) => load_file(Path::new(name)),
        Target::Name(name) => generic::find(&REGISTRY, name).map_err(py_err),
        Target::File(path) => load_file(path),
    }?;
    match params {
        Some(p) if !p.is_empty() => {
            let p: Vec<(String, f64)> = p.into_iter().collect();
            symbody::files::reparametrized(entry, &p).map_err(py_err)
        }
        _ => Ok(entry),
    }
}

/// The file `origin`'s equations are interpreted from; `None` for compiled code.
fn source(origin: Origin) -> Option<&'static str> {
    match origin {
        Origin::Compiled { .. } => None,
        Origin::Interpreted { file, .. } => Some(file),
    }
}

/// A float vector of length `n` from a NumPy array or any sequence of numbers.
fn vector(x: &Bound<'_, PyAny>, n: usize, what: &str) -> PyResult<Vec<f64>> {
    let v: Vec<f64> = match x.extract::<PyReadonlyArray1<'_, f64>>() {
        Ok(a) => a.as_array().to_vec(),
        Err(_) => x.extract().map_err(|_| {
            PyValueError::new_err(format!("{what} must be a sequence of {n} numbers"))
        })?,
    };
    if v.len() != n {
        return Err(PyValueError::new_err(format!(
            "{what} must have {n} entries, got {}",
            v.len()
        )));
    }
    Ok(v)
}

/// A NumPy float vector.
type Vector<'py> = Bound<'py, PyArray1<f64>>;
/// A NumPy float matrix.
type Matrix<'py> = Bound<'py, PyArray2<f64>>;

fn array1<'py>(py: Python<'py>, v: &[f64]) -> Vector<'py> {
    PyArray1::from_slice(py, v)
}

/// A `rows × cols` array from row-major values.
fn array2(py: Python<'_>, rows: usize, cols: usize, values: Vec<f64>) -> Matrix<'_> {
    Array2::from_shape_vec((rows, cols), values)
        .expect("rows × cols values")
        .into_pyarray(py)
}

/// `(data, (rows, cols))`: a sparse matrix in SciPy's COO form.
fn coo<'py>(
    py: Python<'py>,
    data: &[f64],
    rows: &[u32],
    cols: &[u32],
) -> PyResult<Bound<'py, PyTuple>> {
    let index = |v: &[u32]| PyArray1::from_iter(py, v.iter().map(|&i| i64::from(i)));
    let pattern = PyTuple::new(py, [index(rows), index(cols)])?;
    PyTuple::new(py, [array1(py, data).into_any(), pattern.into_any()])
}

/// Names of every registered mechanism, in registry order.
#[pyfunction]
fn mechanisms() -> Vec<&'static str> {
    REGISTRY.names()
}

/// The defaults of a run (`symbody simulate <name>`'s, [`generic::Options::default`]):
/// `simulate` and `Session` take theirs from here, so the two cannot drift apart.
#[pyfunction]
fn defaults(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let d = generic::Options::default();
    let out = PyDict::new(py);
    out.set_item("step", d.step)?;
    out.set_item("alpha", d.alpha)?;
    out.set_item("output_step", d.output_step)?;
    // `generic::run` always projects the velocities (see `generic::Options::alpha`).
    out.set_item("project_velocities", true)?;
    Ok(out)
}

/// Tables as `[(stem, columns, data)]`, `data` an outputs × columns array.
type PyTables<'py> = Vec<(&'static str, Vec<String>, Matrix<'py>)>;

/// A run's answer: its tables, its summary and the files written.
type Answer<'py> = (PyTables<'py>, Bound<'py, PyDict>, Vec<PathBuf>);

fn py_tables(py: Python<'_>, tables: Vec<Table>) -> PyTables<'_> {
    tables
        .into_iter()
        .map(|t| {
            let (n, m) = (t.rows.len(), t.columns.len());
            let data = array2(py, n, m, t.rows.into_iter().flatten().collect());
            (t.stem, t.columns, data)
        })
        .collect()
}

/// The folder `out` made before the run, so that one that cannot be written fails before the
/// work rather than after it.
fn out_folder(out: Option<&Path>) -> PyResult<()> {
    match out {
        Some(dir) => std::fs::create_dir_all(dir).map_err(|e| written(dir, e)),
        None => Ok(()),
    }
}

fn written(dir: &Path, e: std::io::Error) -> PyErr {
    PyOSError::new_err(format!(
        "out: cannot write the CSV files to {}: {e}",
        dir.display()
    ))
}

/// The summary every run shares: the solver's work, wall time and constraint residuals.
fn work_summary<'py>(
    py: Python<'py>,
    path: &str,
    stats: &Stats,
    kinematic: Option<PathStats>,
    wall: Duration,
    max_phi: f64,
    max_velocity_residual: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("path", path)?;
    d.set_item("steps", stats.steps)?;
    d.set_item("rejected_steps", stats.rejected_steps)?;
    // With step-size control (`rtol`, `atol`), the range of the steps it took.
    let (smallest, largest) = match stats.controlled {
        true => (Some(stats.smallest_step), Some(stats.largest_step)),
        false => (None, None),
    };
    d.set_item("smallest_step", smallest)?;
    d.set_item("largest_step", largest)?;
    // On the kinematic path the solves are per output, not per step: its Newton iterations
    // and factorizations, and the simplified-Newton corrections that stand in for most.
    let k = kinematic.unwrap_or_default();
    d.set_item(
        "newton_iterations",
        stats.newton_iterations + k.newton_iterations,
    )?;
    d.set_item("chord_iterations", k.chord_iterations)?;
    d.set_item("factorizations", stats.factorizations + k.factorizations)?;
    d.set_item("wall_time", wall.as_secs_f64())?;
    d.set_item("max_phi", max_phi)?;
    d.set_item("max_velocity_residual", max_velocity_residual)?;
    Ok(d)
}

fn recording_summary<'py>(
    py: Python<'py>,
    rec: &Recording,
    path: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let d = work_summary(
        py,
        path,
        &rec.stats,
        rec.kinematic,
        rec.wall,
        rec.max_phi,
        rec.max_velocity_residual,
    )?;
    // None where the work was not integrated (a kinematic scene with energy = false).
    let balance = rec.energy_balance();
    d.set_item("energy_drift", balance.map(|b| b.0))?;
    d.set_item("energy_scale", balance.map(|b| b.1))?;
    let windows = PyList::empty(py);
    for w in rec.ill_conditioned() {
        let item = PyDict::new(py);
        item.set_item("from", w.from)?;
        item.set_item("to", w.to)?;
        item.set_item("outputs", w.outputs)?;
        item.set_item("smallest", w.smallest)?;
        item.set_item("at", w.at)?;
        item.set_item("dropped", w.dropped)?;
        windows.append(item)?;
    }
    d.set_item("ill_conditioned", windows)?;
    let warnings: Vec<String> = rec.energy_warning("step=", "rtol=").into_iter().collect();
    d.set_item("warnings", warnings)?;
    Ok(d)
}

/// A generic run's answer, its CSV files written into `out` if given.
fn recording_answer<'py>(
    py: Python<'py>,
    rec: &Recording,
    path: &str,
    out: Option<&Path>,
) -> PyResult<Answer<'py>> {
    let files = match out {
        Some(dir) => symbody::tables::write_csvs(rec, dir).map_err(|e| written(dir, e))?,
        None => Vec::new(),
    };
    Ok((
        py_tables(py, symbody::tables::tables(rec)),
        recording_summary(py, rec, path)?,
        files,
    ))
}

/// One run of `symbody simulate <name>`: its tables `bodies`, `joints`, `drivers` and
/// `energy`, its summary, and the CSV files written into `out` if given.
#[pyfunction]
#[pyo3(signature = (name, t_end, step, alpha, output_step, formulation, cross_singular_positions, out, params, sensitivities, rtol, atol, reduced))]
#[allow(clippy::too_many_arguments)]
fn simulate<'py>(
    py: Python<'py>,
    name: Target,
    t_end: Option<f64>,
    step: f64,
    alpha: f64,
    output_step: f64,
    formulation: Option<&str>,
    cross_singular_positions: bool,
    out: Option<PathBuf>,
    params: Option<BTreeMap<String, f64>>,
    sensitivities: Vec<String>,
    rtol: Option<f64>,
    atol: Option<f64>,
    reduced: bool,
) -> PyResult<Answer<'py>> {
    let tolerances = generic::tolerances(rtol, atol, "").map_err(PyValueError::new_err)?;
    let base: Vec<(String, f64)> = params.clone().unwrap_or_default().into_iter().collect();
    let entry = find(&name, params)?;
    symbody::sensitivity::values(entry, &base, &sensitivities).map_err(py_err)?;
    let formulation = self::formulation(formulation)?;
    if reduced {
        generic::require_reduced(entry, formulation)
            .map_err(|e| PyValueError::new_err(format!("reduced: {e}")))?;
    }
    let opts = generic::Options {
        formulation,
        t_end,
        step,
        alpha,
        output_step,
        cross_singular: cross_singular_positions,
        newton_tolerance: None,
        tolerances,
        reduce: reduced,
        path_thread: true,
    };
    out_folder(out.as_deref())?;
    let rec = py.detach(|| generic::run(entry, &opts)).map_err(py_err)?;
    let mut answer = recording_answer(py, &rec, "integrated", out.as_deref())?;
    answer.1.set_item("source", source(entry.origin))?;
    answer.1.set_item("note", symbody::files::note(entry))?;
    with_sensitivities(py, &mut answer, out.as_deref(), &sensitivities, || {
        symbody::sensitivity::integrated(entry, &opts, &base, &sensitivities)
    })?;
    Ok(answer)
}

/// With parameters to differentiate with respect to: the `sensitivities` table added to
/// `answer` (and its CSV written into `out`, if given).
fn with_sensitivities<'py>(
    py: Python<'py>,
    answer: &mut Answer<'py>,
    out: Option<&Path>,
    names: &[String],
    compute: impl FnOnce() -> Result<symbody::sensitivity::Sensitivities, ScenarioError> + Send,
) -> PyResult<()> {
    if names.is_empty() {
        return Ok(());
    }
    let s = py.detach(compute).map_err(py_err)?;
    if let Some(dir) = out {
        answer.2.push(s.write(dir).map_err(|e| written(dir, e))?);
    }
    answer.0.extend(py_tables(py, vec![s.table()]));
    Ok(())
}

/// `symbody run <scene>`: the scene file read, checked and run on the path it chooses; the
/// tables it asks for (the paper scenario's with `files = "paper"`), a summary with the path
/// and why, and the CSV files written into `out` if given.
#[pyfunction]
#[pyo3(signature = (scene, out, sensitivities, params))]
fn run<'py>(
    py: Python<'py>,
    scene: PathBuf,
    out: Option<PathBuf>,
    sensitivities: Vec<String>,
    params: Option<BTreeMap<String, f64>>,
) -> PyResult<Answer<'py>> {
    let file = scene.display().to_string();
    let text = std::fs::read_to_string(&scene).map_err(|e| {
        let message = format!("cannot read scene file {file}: {e}");
        match e.kind() {
            std::io::ErrorKind::NotFound => PyFileNotFoundError::new_err(message),
            _ => PyOSError::new_err(message),
        }
    })?;
    let parsed = symbody::scene::load(&REGISTRY, &file, &text).map_err(|e| {
        // Diagnostics begin with `error: `; the exception's type says as much.
        let shown = e.to_string();
        PyValueError::new_err(shown.strip_prefix("error: ").unwrap_or(&shown).to_string())
    })?;
    // `params` on top of the scene's own parameters, as `symbody run --set` does.
    let set: Vec<(String, f64)> = params.unwrap_or_default().into_iter().collect();
    let base = symbody::files::merged(&parsed.parameters, &set);
    let entry = match set.is_empty() {
        true => parsed.entry,
        false => symbody::files::reparametrized(parsed.entry, &base)
            .map_err(|e| py_err_in(&format!("{file}: "), e))?,
    };
    symbody::sensitivity::values(entry, &base, &sensitivities).map_err(py_err)?;
    out_folder(out.as_deref())?;
    let (choice, outcome) = py
        .detach(|| symbody::scene::run(&parsed, entry))
        .map_err(|e| py_err_in(&format!("{file}: "), e))?;
    let info = generic::mechanism(entry, Some(parsed.formulation))
        .map_err(py_err)?
        .info();
    let path = match choice {
        PathChoice::Kinematic { .. } => "kinematic",
        PathChoice::Integrate { .. } => "integrated",
    };
    let (tables, summary, files) = match outcome {
        Outcome::Tables(rec) => recording_answer(py, &rec, path, out.as_deref())?,
        Outcome::Paper(run) => {
            let tables = symbody::output::tables(&run);
            let files = match out.as_deref() {
                Some(dir) => {
                    symbody::output::write_csvs(&run, dir).map_err(|e| written(dir, e))?;
                    tables
                        .iter()
                        .map(|t| dir.join(format!("{}.csv", t.stem)))
                        .collect()
                }
                None => Vec::new(),
            };
            let summary = work_summary(
                py,
                path,
                &run.stats,
                run.kinematic,
                run.wall,
                run.max_phi,
                run.max_velocity_residual,
            )?;
            // The paper's run records T + V and the actuators' power at the outputs, not an
            // energy meter over the steps, nor the pivots that flag singular positions.
            summary.set_item("energy_drift", py.None())?;
            summary.set_item("energy_scale", py.None())?;
            summary.set_item("warnings", PyList::empty(py))?;
            summary.set_item("ill_conditioned", py.None())?;
            (py_tables(py, tables), summary, files)
        }
    };
    summary.set_item("path_reason", choice.describe(info))?;
    let mut answer = (tables, summary, files);
    let kinematic = matches!(choice, PathChoice::Kinematic { .. });
    with_sensitivities(py, &mut answer, out.as_deref(), &sensitivities, || {
        symbody::sensitivity::of_scene(&parsed, entry, kinematic, &base, &sensitivities)
    })?;
    Ok(answer)
}

/// The pose to continue from: six numbers `x, y, z, θ, β, γ` (as `symbody fk --from`), or a
/// pair `(position (3,), rotation (3, 3))`.
fn start_pose(x: &Bound<'_, PyAny>) -> PyResult<Pose> {
    if let Ok((p, r)) = x.extract::<(Bound<'_, PyAny>, Bound<'_, PyAny>)>() {
        let p = vector(&p, 3, "start position")?;
        let r: PyReadonlyArray2<'_, f64> = r
            .extract()
            .map_err(|_| PyValueError::new_err("start rotation must be a (3, 3) float64 array"))?;
        let r = r.as_array();
        if r.shape() != [3, 3] {
            return Err(PyValueError::new_err(format!(
                "start rotation must be (3, 3), got {:?}",
                r.shape()
            )));
        }
        return Ok(Pose {
            position: Vector3::new(p[0], p[1], p[2]),
            rotation: Matrix3::from_fn(|i, j| r[[i, j]]),
        });
    }
    let v = vector(x, 6, "start (x, y, z, theta, beta, gamma)")?;
    Ok(Pose::from_euler([v[0], v[1], v[2]], [v[3], v[4], v[5]]))
}

/// A study (`symbody study`): the scene file `target` (one with a top-level `mechanism`), or
/// a default scene of the mechanism `target` (a name or a file) over `t_end`, run once per
/// row of `columns` (one list per parameter in `names`, all as long) on `jobs` threads with
/// the GIL released, each run reduced to `metrics` (names as in a scene's `[study]`; `None`:
/// the scene's own, else the default set). A dict of columns: `run`, the parameters, the
/// metrics, `status`, `error`, `wall_s`, in row order.
#[pyfunction]
#[pyo3(signature = (target, names, columns, t_end, metrics, jobs))]
fn study<'py>(
    py: Python<'py>,
    target: Target,
    names: Vec<String>,
    columns: Vec<Vec<f64>>,
    t_end: Option<f64>,
    metrics: Option<Vec<String>>,
    jobs: Option<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let scene_text = |mechanism: &str| -> PyResult<String> {
        if mechanism.contains('\'') {
            return Err(PyValueError::new_err(format!(
                "{mechanism}: a path with a single quote cannot be named in a scene"
            )));
        }
        let mut text = format!("mechanism = '{mechanism}'\n");
        if let Some(t) = t_end {
            text.push_str(&format!("[time]\nend = {t:?}\n"));
        }
        Ok(text)
    };
    // A scene file names its mechanism at the top level; anything else is a mechanism.
    let (file, text) = match (scene_file(&target), &target) {
        (Some((p, text)), _) => (p.display().to_string(), text),
        (None, Target::File(p)) => {
            let abs = std::path::absolute(p).unwrap_or_else(|_| p.clone());
            (
                "<study>".to_string(),
                scene_text(&abs.display().to_string())?,
            )
        }
        (None, Target::Name(n)) => ("<study>".to_string(), scene_text(n)?),
    };
    let scene = symbody::scene::load(&REGISTRY, &file, &text).map_err(|e| {
        let shown = e.to_string();
        PyValueError::new_err(shown.strip_prefix("error: ").unwrap_or(&shown).to_string())
    })?;
    if names.len() != columns.len() {
        return Err(PyValueError::new_err(
            "one column of values per parameter name",
        ));
    }
    let n_rows = columns.first().map_or(0, Vec::len);
    if columns.iter().any(|c| c.len() != n_rows) {
        return Err(PyValueError::new_err(
            "params: every parameter needs as many values",
        ));
    }
    let known = symbody::files::parameter_names(scene.entry).map_err(py_err)?;
    for n in &names {
        if !known.contains(n) {
            let close = symbody::generic::closest(n, known.iter().map(String::as_str))
                .map(|c| format!(" (did you mean `{c}`?)"))
                .unwrap_or_default();
            return Err(PyValueError::new_err(format!(
                "params: no parameter `{n}` in the mechanism file{close}; its parameters: {}",
                known.join(", ")
            )));
        }
    }
    let rows: Vec<Vec<(String, f64)>> = (0..n_rows)
        .map(|k| {
            names
                .iter()
                .cloned()
                .zip(columns.iter().map(|c| c[k]))
                .collect()
        })
        .collect();
    let metrics = match metrics {
        None => symbody::study::metrics(&scene),
        Some(list) => {
            let info = scene.entry.default_mechanism().info();
            let mut chosen: Vec<symbody::study::Metric> = Vec::new();
            for name in &list {
                let m = symbody::study::Metric::parse(name, info).map_err(|(message, help)| {
                    PyValueError::new_err(format!("metrics: {message}; {help}"))
                })?;
                if chosen.contains(&m) {
                    return Err(PyValueError::new_err(format!(
                        "metrics: `{name}` is listed twice"
                    )));
                }
                chosen.push(m);
            }
            if chosen.is_empty() {
                return Err(PyValueError::new_err(
                    "metrics: none given; name some, or pass None for the default set",
                ));
            }
            chosen
        }
    };
    let metric_names: Vec<String> = metrics.iter().map(|m| m.name()).collect();
    let jobs = jobs.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    let stop = std::sync::atomic::AtomicBool::new(false);
    let mut results: Vec<Option<symbody::study::RowResult>> = vec![None; n_rows];
    py.detach(|| {
        symbody::study::run(
            &scene,
            &metrics,
            &rows,
            &Default::default(),
            jobs,
            &stop,
            |row| {
                let index = row.index;
                results[index] = Some(row);
                Ok(())
            },
        )
    })
    .map_err(py_err)?;
    let d = PyDict::new(py);
    let results: Vec<symbody::study::RowResult> = results.into_iter().flatten().collect();
    d.set_item("run", results.iter().map(|r| r.index).collect::<Vec<_>>())?;
    for (k, n) in names.iter().enumerate() {
        d.set_item(
            n,
            results
                .iter()
                .map(|r| r.parameters[k].1)
                .collect::<Vec<_>>(),
        )?;
    }
    for (k, n) in metric_names.iter().enumerate() {
        let col: Vec<f64> = results
            .iter()
            .map(|r| r.metrics.as_ref().map_or(f64::NAN, |m| m[k]))
            .collect();
        d.set_item(n, col)?;
    }
    let status: Vec<&str> = results
        .iter()
        .map(|r| if r.metrics.is_ok() { "ok" } else { "failed" })
        .collect();
    d.set_item("status", status)?;
    let errors: Vec<String> = results
        .iter()
        .map(|r| r.metrics.as_ref().err().cloned().unwrap_or_default())
        .collect();
    d.set_item("error", errors)?;
    d.set_item("wall_s", results.iter().map(|r| r.wall).collect::<Vec<_>>())?;
    Ok(d)
}

/// The path and text of `target` when it is a scene file (TOML with a top-level
/// `mechanism`); `None` for a mechanism (name or file).
fn scene_file(target: &Target) -> Option<(PathBuf, String)> {
    let path = match target {
        Target::File(p) => p.clone(),
        Target::Name(n) if symbody::files::is_path(n) => PathBuf::from(n),
        Target::Name(_) => return None,
    };
    let text = std::fs::read_to_string(&path).ok()?;
    symbody::scene::is_scene(&text).then_some((path, text))
}

/// Forward kinematics of a six-leg platform (`symbody fk`): a dict of the pose reached by
/// continuation and, with `all`, every real assembly mode.
#[pyfunction]
#[pyo3(signature = (name, lengths, start, at, all, params))]
fn fk<'py>(
    py: Python<'py>,
    name: Target,
    lengths: Option<Bound<'py, PyAny>>,
    start: Option<Bound<'py, PyAny>>,
    at: f64,
    all: bool,
    params: Option<BTreeMap<String, f64>>,
) -> PyResult<Bound<'py, PyDict>> {
    let entry = find(&name, params)?;
    let p = symbody::fk::platform(entry).map_err(py_err)?;
    let req = symbody::fk::Request {
        lengths: match lengths {
            None => None,
            Some(l) => {
                let v = vector(&l, 6, "lengths")?;
                Some(std::array::from_fn(|i| v[i]))
            }
        },
        from: start.as_ref().map(start_pose).transpose()?,
        at,
    };
    let out = PyDict::new(py);
    out.set_item("legs", p.leg_names().to_vec())?;
    let answer = match py.detach(|| symbody::fk::solve(&p, &req)) {
        Ok(a) => Some(a),
        // As `symbody fk --all`: the modes are found without a tracked pose to mark.
        Err(e) if all => {
            out.set_item("error", e.to_string())?;
            None
        }
        Err(e) => return Err(py_err(e)),
    };
    let lengths = match &answer {
        Some(a) => a.lengths,
        None => req.lengths.unwrap_or_else(|| p.lengths_at(req.at)),
    };
    out.set_item("lengths", array1(py, &lengths))?;
    if let Some(a) = &answer {
        let s = a.tracked.solution;
        out.set_item("position", array1(py, s.pose.position.as_slice()))?;
        let r = (0..9).map(|i| s.pose.rotation[(i / 3, i % 3)]).collect();
        out.set_item("rotation", array2(py, 3, 3, r))?;
        out.set_item("euler", array1(py, &s.pose.euler_angles()))?;
        out.set_item("residual", s.residual)?;
        out.set_item("iterations", s.iterations)?;
        out.set_item("condition", s.condition)?;
        out.set_item("det_sign", s.det_sign)?;
        out.set_item("steps", a.tracked.steps)?;
    }
    if all {
        let current = answer.as_ref().map(|a| a.tracked.solution.pose);
        let (modes, index, _) = py
            .detach(|| symbody::fk::all_modes(&p, &lengths, current.as_ref()))
            .map_err(py_err)?;
        let rows: Vec<f64> = symbody::fk::mode_rows(&modes, index)
            .into_iter()
            .flatten()
            .collect();
        let cols = symbody::fk::MODE_COLUMNS.len();
        out.set_item("modes", array2(py, modes.real.len(), cols, rows))?;
        out.set_item("mode_columns", symbody::fk::MODE_COLUMNS.to_vec())?;
        out.set_item("complex", modes.complex)?;
        out.set_item("current", index)?;
        let worst = modes.real.iter().map(|m| m.residual).fold(0.0, f64::max);
        out.set_item("modes_residual", worst)?;
    }
    Ok(out)
}

/// Names of the drivers of `info`, in joint order.
fn driver_names(info: &MechanismInfo) -> Vec<&'static str> {
    info.joints
        .iter()
        .filter(|j| j.kind == JointKind::Driver)
        .map(|j| j.name)
        .collect()
}

/// One simulation to drive step by step, as `symbody::session::Session`: HHT-α from the
/// mechanism's consistent start. `symbody.Session` subclasses it with the defaults.
#[pyclass(module = "symbody._native", subclass)]
struct Session {
    inner: session::Session,
    origin: Origin,
}

#[pymethods]
impl Session {
    #[new]
    // No defaults here: `symbody.Session` gives `simulate`'s (`defaults()`).
    #[pyo3(signature = (name, formulation, alpha, step, project_velocities, cross_singular_positions, params, rtol, atol))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        name: Target,
        formulation: Option<&str>,
        alpha: f64,
        step: f64,
        project_velocities: bool,
        cross_singular_positions: bool,
        params: Option<BTreeMap<String, f64>>,
        rtol: Option<f64>,
        atol: Option<f64>,
    ) -> PyResult<Self> {
        let tolerances = generic::tolerances(rtol, atol, "").map_err(PyValueError::new_err)?;
        let entry = find(&name, params)?;
        let mech = generic::mechanism(entry, self::formulation(formulation)?).map_err(py_err)?;
        let settings = session::Settings {
            formulation: Some(mech.info().formulation),
            alpha,
            step,
            project_velocities,
            cross_singular_positions,
            tolerances,
        };
        Ok(Session {
            inner: session::Session::with_mechanism(mech, settings).map_err(py_err)?,
            origin: entry.origin,
        })
    }

    /// Whether the equations are interpreted from a mechanism file rather than compiled.
    #[getter]
    fn interpreted(&self) -> bool {
        source(self.origin).is_some()
    }
    /// The mechanism file the equations are interpreted from; `None` for compiled code.
    #[getter]
    fn source(&self) -> Option<&'static str> {
        source(self.origin)
    }

    /// The mechanism's name.
    #[getter]
    fn name(&self) -> &'static str {
        self.inner.info().name
    }
    /// `"paper"` or `"exact"`.
    #[getter]
    fn formulation(&self) -> &'static str {
        self.inner.info().formulation.name()
    }
    /// Current time (s).
    #[getter]
    fn t(&self) -> f64 {
        self.inner.t()
    }
    /// Coordinates (a copy).
    #[getter]
    fn q<'py>(&self, py: Python<'py>) -> Vector<'py> {
        array1(py, self.inner.q())
    }
    /// Velocities (a copy).
    #[getter]
    fn qd<'py>(&self, py: Python<'py>) -> Vector<'py> {
        array1(py, self.inner.qd())
    }
    /// Name of each coordinate, `q` order.
    #[getter]
    fn coord_names(&self) -> Vec<&'static str> {
        self.inner.info().coord_names.to_vec()
    }
    /// Name of every joint and driver, as `joint_wrench` and `driver_effort` take them.
    #[getter]
    fn joint_names(&self) -> Vec<&'static str> {
        self.inner.info().joints.iter().map(|j| j.name).collect()
    }
    /// Name of each driver, `driver_efforts()` order.
    #[getter]
    fn driver_names(&self) -> Vec<&'static str> {
        driver_names(self.inner.info())
    }

    /// One HHT step of the nominal size.
    fn step(&mut self, py: Python<'_>) -> PyResult<()> {
        let s = &mut self.inner;
        py.detach(|| s.step()).map_err(py_err)
    }

    /// Steps until exactly `t` (the last step shortened to land on it).
    fn advance_to(&mut self, py: Python<'_>, t: f64) -> PyResult<()> {
        let s = &mut self.inner;
        let now = s.t();
        py.detach(|| s.advance_to(t)).map_err(|e| match e {
            // The integrator's name for the target is not the caller's.
            ScenarioError::Runtime(RuntimeError::InvalidSetting {
                name: "t_out",
                reason,
                ..
            }) => PyValueError::new_err(format!(
                "advance_to(t): t = {t} {reason} (the session is at t = {now} s)"
            )),
            other => py_err(other),
        })
    }

    /// Lagrange multipliers of the current state, one per constraint row.
    fn multipliers<'py>(&mut self, py: Python<'py>) -> PyResult<Vector<'py>> {
        Ok(array1(py, self.inner.multipliers().map_err(py_err)?))
    }

    /// Effort of the driver `name`: force (N) or torque (N·m) along the driven coordinate.
    fn driver_effort(&mut self, name: &str) -> PyResult<f64> {
        self.inner.driver_effort(name).map_err(py_err)
    }

    /// Effort of every driver, `driver_names` order.
    fn driver_efforts<'py>(&mut self, py: Python<'py>) -> PyResult<Vector<'py>> {
        let mut out = vec![0.0; driver_names(self.inner.info()).len()];
        self.inner.driver_efforts(&mut out).map_err(py_err)?;
        Ok(array1(py, &out))
    }

    /// `(force, moment)` joint `name` exerts on its first body: global frame, moment about
    /// the joint point.
    fn joint_wrench<'py>(
        &mut self,
        py: Python<'py>,
        name: &str,
    ) -> PyResult<(Vector<'py>, Vector<'py>)> {
        let w = self.inner.joint_wrench(name).map_err(py_err)?;
        Ok((array1(py, &w.force), array1(py, &w.moment)))
    }

    fn __repr__(&self) -> String {
        format!(
            "Session({:?}, formulation={:?}, t={})",
            self.inner.info().name,
            self.inner.info().formulation.name(),
            self.inner.t()
        )
    }
}

/// The generated functions of one mechanism, evaluated at any state: constraints, their
/// Jacobian (sparse), γ, mass matrix (sparse) and generalized forces.
/// `symbody.Mechanism` subclasses it to return the sparse matrices as `symbody.Coo`.
#[pyclass(module = "symbody._native", frozen, subclass)]
struct Mechanism {
    mech: Dyn,
    origin: Origin,
}

impl Mechanism {
    fn info(&self) -> &'static MechanismInfo {
        self.mech.info()
    }
    fn q(&self, q: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
        vector(q, self.info().n_coords, "q")
    }
    fn qd(&self, qd: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
        vector(qd, self.info().n_coords, "qd")
    }
}

#[pymethods]
impl Mechanism {
    #[new]
    #[pyo3(signature = (name, formulation=None, params=None))]
    fn new(
        name: Target,
        formulation: Option<&str>,
        params: Option<BTreeMap<String, f64>>,
    ) -> PyResult<Self> {
        let entry = find(&name, params)?;
        let mech = generic::mechanism(entry, self::formulation(formulation)?).map_err(py_err)?;
        Ok(Mechanism {
            mech,
            origin: entry.origin,
        })
    }

    /// Whether the equations are interpreted from a mechanism file rather than compiled.
    #[getter]
    fn interpreted(&self) -> bool {
        source(self.origin).is_some()
    }
    /// The mechanism file the equations are interpreted from; `None` for compiled code.
    #[getter]
    fn source(&self) -> Option<&'static str> {
        source(self.origin)
    }

    /// The mechanism's name.
    #[getter]
    fn name(&self) -> &'static str {
        self.info().name
    }
    /// `"paper"` or `"exact"`.
    #[getter]
    fn formulation(&self) -> &'static str {
        self.info().formulation.name()
    }
    /// Number of coordinates (the length of `q`).
    #[getter]
    fn n_coords(&self) -> usize {
        self.info().n_coords
    }
    /// Number of constraint rows (the length of `phi(q)`).
    #[getter]
    fn n_constraints(&self) -> usize {
        self.info().n_constraints
    }
    /// The file's assembled initial coordinates.
    #[getter]
    fn q0<'py>(&self, py: Python<'py>) -> Vector<'py> {
        array1(py, self.info().q0)
    }
    /// The file's initial velocities (not projected onto the constraints).
    #[getter]
    fn qd0<'py>(&self, py: Python<'py>) -> Vector<'py> {
        array1(py, self.info().qd0)
    }
    /// Name of each coordinate, `q` order.
    #[getter]
    fn coord_names(&self) -> Vec<&'static str> {
        self.info().coord_names.to_vec()
    }
    /// Name of each constraint row, `phi` order.
    #[getter]
    fn row_names(&self) -> Vec<&'static str> {
        self.info().row_names.to_vec()
    }
    /// Constraint rows the generator found redundant at the initial pose.
    #[getter]
    fn redundant_rows(&self) -> Vec<u32> {
        self.info().redundant_rows.to_vec()
    }

    /// Φ(q, t), one entry per constraint row.
    #[pyo3(signature = (q, t=0.0))]
    fn phi<'py>(&self, py: Python<'py>, q: &Bound<'py, PyAny>, t: f64) -> PyResult<Vector<'py>> {
        let mut out = vec![0.0; self.info().n_constraints];
        self.mech.phi(&self.q(q)?, t, &mut out);
        Ok(array1(py, &out))
    }

    /// Φq(q, t) as `(data, (rows, cols))`, shape `(n_constraints, n_coords)`.
    #[pyo3(signature = (q, t=0.0))]
    fn phi_q<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        t: f64,
    ) -> PyResult<Bound<'py, PyTuple>> {
        let info = self.info();
        let mut out = vec![0.0; info.phi_q_nnz()];
        self.mech.phi_q(&self.q(q)?, t, &mut out);
        coo(py, &out, info.phi_q_rows, info.phi_q_cols)
    }

    /// ∂Φ/∂t(q, t).
    #[pyo3(signature = (q, t=0.0))]
    fn phi_t<'py>(&self, py: Python<'py>, q: &Bound<'py, PyAny>, t: f64) -> PyResult<Vector<'py>> {
        let mut out = vec![0.0; self.info().n_constraints];
        self.mech.phi_t(&self.q(q)?, t, &mut out);
        Ok(array1(py, &out))
    }

    /// γ(q, q̇, t), the right-hand side of the acceleration constraints Φq q̈ = γ.
    #[pyo3(signature = (q, qd, t=0.0))]
    fn gamma<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        qd: &Bound<'py, PyAny>,
        t: f64,
    ) -> PyResult<Vector<'py>> {
        let mut out = vec![0.0; self.info().n_constraints];
        self.mech.gamma(&self.q(q)?, &self.qd(qd)?, t, &mut out);
        Ok(array1(py, &out))
    }

    /// M(q) as `(data, (rows, cols))` (both triangles), shape `(n_coords, n_coords)`.
    fn mass<'py>(&self, py: Python<'py>, q: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyTuple>> {
        let info = self.info();
        let mut out = vec![0.0; info.mass_nnz()];
        self.mech.mass(&self.q(q)?, &mut out);
        coo(py, &out, info.mass_rows, info.mass_cols)
    }

    /// Generalized forces Q(q, q̇, t): applied loads and velocity-dependent terms.
    #[pyo3(signature = (q, qd, t=0.0))]
    fn force<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        qd: &Bound<'py, PyAny>,
        t: f64,
    ) -> PyResult<Vector<'py>> {
        let mut out = vec![0.0; self.info().n_coords];
        self.mech.force(&self.q(q)?, &self.qd(qd)?, t, &mut out);
        Ok(array1(py, &out))
    }

    /// The applied loads' ∂Q/∂q and ∂Q/∂q̇ (springs, dampers, actuators) at `(q, q̇, t)`, each
    /// as `(data, (rows, cols))`, shape `(n_coords, n_coords)`; empty without such loads.
    #[pyo3(signature = (q, qd, t=0.0))]
    fn force_jacobian<'py>(
        &self,
        py: Python<'py>,
        q: &Bound<'py, PyAny>,
        qd: &Bound<'py, PyAny>,
        t: f64,
    ) -> PyResult<(Bound<'py, PyTuple>, Bound<'py, PyTuple>)> {
        let info = self.info();
        let mut dq = vec![0.0; info.force_q_rows.len()];
        let mut dqd = vec![0.0; info.force_qd_rows.len()];
        self.mech
            .force_jacobian(&self.q(q)?, &self.qd(qd)?, t, &mut dq, &mut dqd);
        Ok((
            coo(py, &dq, info.force_q_rows, info.force_q_cols)?,
            coo(py, &dqd, info.force_qd_rows, info.force_qd_cols)?,
        ))
    }

    /// Potential energy V(q) (J).
    fn potential(&self, q: &Bound<'_, PyAny>) -> PyResult<f64> {
        Ok(self.mech.potential(&self.q(q)?))
    }

    fn __repr__(&self) -> String {
        format!(
            "Mechanism({:?}, formulation={:?})",
            self.info().name,
            self.info().formulation.name()
        )
    }
}

/// The value the Rust example, the C example and this package print: the paper platform's
/// actuator 1 force (N) at t = 1 s with the paper scenario's integrator settings.
#[pyfunction]
fn paper_leg1_force_at_1s(py: Python<'_>) -> PyResult<f64> {
    py.detach(|| session::paper_leg1_force_at_1s(&REGISTRY))
        .map_err(py_err)
}

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(mechanisms, m)?)?;
    m.add_function(wrap_pyfunction!(defaults, m)?)?;
    m.add_function(wrap_pyfunction!(simulate, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(fk, m)?)?;
    m.add_function(wrap_pyfunction!(study, m)?)?;
    m.add_function(wrap_pyfunction!(paper_leg1_force_at_1s, m)?)?;
    m.add_class::<Session>()?;
    m.add_class::<Mechanism>()?;
    // The wheel's version is this crate's (maturin), so Python reports the same number.
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
