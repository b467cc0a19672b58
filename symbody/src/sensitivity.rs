//! Derivatives of a run's outputs (body poses, joint wrenches, driver efforts) with respect
//! to parameters of the mechanism file, at every output time: `sensitivities.csv`.
//!
//! Each parameter's derivative is carried along the run by [`symbody_runtime::sensitivity`]
//! with the equations' exact directional derivatives, and what the loader makes of the
//! parameter from the mechanism built at four neighbouring values of it (see there for what
//! is exact and what is differenced). The run itself is the base mechanism's, unchanged.

use std::path::Path;

use symbody_runtime::sensitivity::{self, HhtSensitivity, Neighbours, StateSensitivity};
use symbody_runtime::{
    body_pose, driver_effort, free_bodies, joint_wrench, Entry, Formulation, JointKind,
    KinematicPath, Mechanism, Origin,
};

use crate::files::{self, Overrides};
use crate::scenario::{output_count, ScenarioError};
use symbody_codegen::{model, slots};

/// The derivatives of a run's outputs, one row per output time.
#[derive(Debug, Clone, PartialEq)]
pub struct Sensitivities {
    /// The parameters, in the order asked.
    pub parameters: Vec<String>,
    /// The outputs differentiated, named as in the run's tables (`<body>.x`, `<joint>.fx`,
    /// `<driver>`).
    pub outputs: Vec<String>,
    /// Output times (s).
    pub t: Vec<f64>,
    /// Per output time: d(output)/d(parameter), outputs major (`outputs[i]`, then every
    /// parameter).
    pub rows: Vec<Vec<f64>>,
}

impl Sensitivities {
    /// `t`, then `<output>/<parameter>` for every output and parameter.
    pub fn columns(&self) -> Vec<String> {
        std::iter::once("t".to_string())
            .chain(
                self.outputs
                    .iter()
                    .flat_map(|o| self.parameters.iter().map(move |p| format!("{o}/{p}"))),
            )
            .collect()
    }

    /// The column of d(`output`)/d(`parameter`) over the run, if both were asked for.
    pub fn series(&self, output: &str, parameter: &str) -> Option<Vec<f64>> {
        let i = self.outputs.iter().position(|o| o == output)?;
        let j = self.parameters.iter().position(|p| p == parameter)?;
        let k = i * self.parameters.len() + j;
        Some(self.rows.iter().map(|r| r[k]).collect())
    }

    /// As a table (`sensitivities`): `t`, then the [`Sensitivities::columns`].
    pub fn table(&self) -> crate::tables::Table {
        crate::tables::Table {
            stem: "sensitivities",
            columns: self.columns(),
            rows: self
                .t
                .iter()
                .zip(&self.rows)
                .map(|(t, r)| std::iter::once(*t).chain(r.iter().copied()).collect())
                .collect(),
        }
    }

    /// Writes `sensitivities.csv` into `dir` (quoted where CSV needs it, as the run's
    /// tables; shortest round-trip numbers).
    pub fn write(&self, dir: &Path) -> std::io::Result<std::path::PathBuf> {
        let path = dir.join("sensitivities.csv");
        let mut w = std::io::BufWriter::new(std::fs::File::create(&path)?);
        let table = self.table();
        crate::number::write_header(&mut w, &table.columns)?;
        let mut num = crate::number::Shortest::default();
        for row in &table.rows {
            crate::number::write_record(&mut w, row.iter().copied(), &mut num)?;
        }
        std::io::Write::flush(&mut w)?;
        Ok(path)
    }
}

/// What is differentiated: the poses of `bodies`, the wrenches of `joints`, the efforts of
/// `drivers` (indices into the mechanism's info).
struct Outputs {
    bodies: Vec<usize>,
    joints: Vec<usize>,
    drivers: Vec<usize>,
}

const POSE: [&str; 7] = ["x", "y", "z", "qw", "qx", "qy", "qz"];
const WRENCH: [&str; 6] = ["fx", "fy", "fz", "mx", "my", "mz"];

impl Outputs {
    /// Every body but those in `free`, every joint (drivers and normalization rows aside),
    /// every driver.
    fn new(mech: &dyn Mechanism, free: &[usize]) -> Self {
        let info = mech.info();
        let of_kind = |want: fn(JointKind) -> bool| -> Vec<usize> {
            (0..info.joints.len())
                .filter(|&j| want(info.joints[j].kind))
                .collect()
        };
        Outputs {
            bodies: (0..info.bodies.len())
                .filter(|b| !free.contains(b))
                .collect(),
            joints: of_kind(|k| !matches!(k, JointKind::Driver | JointKind::Normalization)),
            drivers: of_kind(|k| k == JointKind::Driver),
        }
    }

    fn names(&self, mech: &dyn Mechanism) -> Vec<String> {
        let info = mech.info();
        let group = |items: &[usize], name: &dyn Fn(usize) -> &'static str, parts: &[&str]| {
            items
                .iter()
                .flat_map(|&i| parts.iter().map(move |p| format!("{}.{p}", name(i))))
                .collect::<Vec<_>>()
        };
        let mut names = group(&self.bodies, &|b| info.bodies[b].name, &POSE);
        names.extend(group(&self.joints, &|j| info.joints[j].name, &WRENCH));
        names.extend(
            self.drivers
                .iter()
                .map(|&j| info.joints[j].name.to_string()),
        );
        names
    }

    /// The outputs of `mech` at `(q, λ)` at time `t`, into `out`.
    fn values(
        &self,
        mech: &dyn Mechanism,
        t: f64,
        (q, lambda): (&[f64], &[f64]),
        phi_q: &mut Vec<f64>,
        out: &mut [f64],
    ) -> Result<(), symbody_runtime::Error> {
        let info = mech.info();
        phi_q.resize(info.phi_q_nnz(), 0.0);
        mech.phi_q(q, t, phi_q);
        let mut k = 0;
        let mut push = |v: f64| {
            out[k] = v;
            k += 1;
        };
        for &b in &self.bodies {
            let (r, e) = body_pose(&info.bodies[b], q)?;
            r.iter().chain(&e).for_each(|&v| push(v));
        }
        for &j in &self.joints {
            let w = joint_wrench(info, q, phi_q, lambda, j)?;
            w.force.iter().chain(&w.moment).for_each(|&v| push(v));
        }
        for &j in &self.drivers {
            push(driver_effort(info, lambda, j)?);
        }
        Ok(())
    }
}

/// Work space of the outputs' derivatives at one output time.
struct OutputRow {
    d: Vec<f64>,
    tmp: Vec<f64>,
    q: Vec<f64>,
    lambda: Vec<f64>,
    phi_q: Vec<f64>,
}

impl OutputRow {
    fn new(n_outputs: usize) -> Self {
        OutputRow {
            d: vec![0.0; n_outputs],
            tmp: vec![0.0; n_outputs],
            q: Vec::new(),
            lambda: Vec::new(),
            phi_q: Vec::new(),
        }
    }

    /// The derivatives of `outputs` at `(q, λ)` moving by `(dq, dλ)` with the parameter of
    /// `nb`, into `row` at every `stride`-th place from `first` (outputs major).
    #[allow(clippy::too_many_arguments)]
    fn fill(
        &mut self,
        outputs: &Outputs,
        nb: &Neighbours<'_>,
        t: f64,
        (q, dq): (&[f64], &[f64]),
        (lambda, dlambda): (&[f64], &[f64]),
        row: &mut [f64],
        (first, stride): (usize, usize),
    ) -> Result<(), ScenarioError> {
        let OutputRow {
            d,
            tmp,
            q: qa,
            lambda: la,
            phi_q,
        } = self;
        nb.derivative(d, tmp, |m, e, v| {
            qa.clear();
            qa.extend(q.iter().zip(dq).map(|(a, b)| a + e * b));
            la.clear();
            la.extend(lambda.iter().zip(dlambda).map(|(a, b)| a + e * b));
            outputs.values(m, t, (qa, la), phi_q, v)
        })?;
        for (i, v) in d.iter().enumerate() {
            row[i * stride + first] = *v;
        }
        Ok(())
    }
}

/// The value of each of `names` among `entry`'s parameters (as set by `base`), or an error
/// naming the first unknown one with the closest known name: to check before a run.
pub fn values(
    entry: &Entry,
    base: &Overrides,
    names: &[String],
) -> Result<Vec<f64>, ScenarioError> {
    if names.is_empty() {
        return Ok(Vec::new());
    }
    // The file's parameters as loaded, nothing derived (a derivation of the 13-body
    // platform costs as much as its run).
    let parameters = files::model_parameters(entry, base)?;
    names
        .iter()
        .map(|name| match parameters.iter().find(|p| &p.name == name) {
            Some(p) => Ok(p.value),
            None => {
                let known: Vec<&str> = parameters.iter().map(|p| p.name.as_str()).collect();
                let hint = symbody_codegen::diag::closest(name, known.iter().copied())
                    .map_or(String::new(), |c| format!(" (did you mean `{c}`?)"));
                Err(ScenarioError::Options(format!(
                    "--sensitivities: `{}` has no parameter `{name}`{hint}; its parameters: {}",
                    entry.name,
                    if known.is_empty() {
                        "none".to_string()
                    } else {
                        known.join(", ")
                    }
                )))
            }
        })
        .collect()
}

/// The mechanism (formulation `f`) built with parameter `name` at its four neighbouring
/// values around `value`, every other parameter as in `base` (`entry` is the run's, built
/// with `base`); re-derived on as many threads (each is a whole load of the file). The base
/// and the four are all compiled code or all interpreted: a direction `dp` is laid out by the
/// code, or by the base's load of the file.
fn neighbours(
    entry: &Entry,
    f: Formulation,
    base: &Overrides,
    (name, value): (&str, f64),
) -> Result<Neighbours<'static>, ScenarioError> {
    let step = sensitivity::relative_step(value);
    let at = |k: f64| files::merged(base, &[(name.to_string(), value + k * step)]);
    let failed = |k: f64, e: ScenarioError| {
        ScenarioError::Options(format!(
            "--sensitivities: `{name}` = {} (a neighbour of {value} used to differentiate): {e}",
            value + k * step,
        ))
    };
    let offsets = [-2.0, -1.0, 1.0, 2.0];
    let loaded: Vec<Result<&'static Entry, ScenarioError>> = std::thread::scope(|s| {
        let handles: Vec<_> = offsets
            .map(|k| {
                let (at, failed) = (&at, &failed);
                s.spawn(move || files::reparametrized(entry, &at(k)).map_err(|e| failed(k, e)))
            })
            .into();
        handles
            .into_iter()
            .map(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p)))
            .collect()
    });
    let mut entries = loaded.into_iter().collect::<Result<Vec<_>, _>>()?;
    let interpreted = |e: &Entry| matches!(e.origin, Origin::Interpreted { .. });
    let mechanism = |e: &Entry| crate::generic::mechanism(e, Some(f));
    let named = |e: String| ScenarioError::Options(format!("--sensitivities: `{name}`: {e}"));
    // One compiled code lays its run-time values out alike at every value; interpreted, the
    // base is loaded again with its tangents and the neighbours' values read in its layout.
    let (base_entry, values) = match !interpreted(entry) && !entries.iter().any(|e| interpreted(e))
    {
        true => (entry, None),
        false => {
            for (e, &k) in entries.iter_mut().zip(&offsets) {
                if !interpreted(e) {
                    *e = files::derive(entry, &at(k))
                        .map_err(|e| failed(k, e))?
                        .entry;
                }
            }
            let base_entry = files::derive_with_tangents(entry, &at(0.0))
                .map_err(|e| failed(0.0, e))?
                .entry;
            let ats: Vec<_> = offsets.iter().map(|&k| at(k)).collect();
            let values = values_in_base_layout(entry, &at(0.0), &ats).map_err(&named)?;
            (base_entry, Some(values))
        }
    };
    let mechs = entries
        .iter()
        .map(|&e| mechanism(e))
        .collect::<Result<Vec<_>, _>>()?;
    let around: [&'static dyn Mechanism; 4] = [mechs[0], mechs[1], mechs[2], mechs[3]];
    let base_mech = mechanism(base_entry)?;
    match &values {
        None => Neighbours::new(base_mech, step, around),
        Some(v) => Neighbours::with_values(base_mech, step, around, [&v[0], &v[1], &v[2], &v[3]]),
    }
    .map_err(|e| named(e.to_string()))
}

/// The run-time values of `entry`'s file loaded with `base` set, as the file loaded with each
/// of `ats` set gives them, in the layout of the first (`slots::values_like`).
fn values_in_base_layout(
    entry: &Entry,
    base: &Overrides,
    ats: &[Vec<(String, f64)>],
) -> Result<Vec<Vec<f64>>, String> {
    let file = files::source_of(entry).map_err(|e| e.to_string())?;
    let text = files::read(std::path::Path::new(&file)).map_err(|e| e.to_string())?;
    let mut base_model = model::load_with(&file, &text, base).map_err(|e| e.to_string())?;
    slots::mark(&file, &text, &mut base_model);
    let refused = |e: slots::Refused| match e {
        slots::Refused::Load(e) => e.to_string(),
        slots::Refused::Structure(what) => format!(
            "a number the file holds constant at the value ({what}) moves beside it: it has no \
             derivative there"
        ),
        slots::Refused::OtherSlots => "the file's numbers moved between loads".to_string(),
    };
    ats.iter()
        .map(|at| slots::values_like(&base_model, &file, &text, at).map_err(refused))
        .collect()
}

/// Every parameter's [`neighbours`].
fn all_neighbours(
    entry: &Entry,
    f: Formulation,
    base: &Overrides,
    parameters: &[String],
) -> Result<Vec<Neighbours<'static>>, ScenarioError> {
    let vals = values(entry, base, parameters)?;
    parameters
        .iter()
        .zip(vals)
        .map(|(p, v)| neighbours(entry, f, base, (p, v)))
        .collect()
}

/// The run's settings a sensitivity pass needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Span {
    pub formulation: Formulation,
    pub t_end: f64,
    pub output_step: f64,
}

/// The derivatives of the outputs of a kinematic path (`generic::run_kinematic`) with
/// respect to `parameters`, the file's other parameters as in `base`. Bodies that the
/// drivers leave free to move (a Stewart leg's spin) are left out: where they are is
/// decided by the path, not by the parameters.
pub fn kinematic(
    entry: &Entry,
    span: Span,
    base: &Overrides,
    parameters: &[String],
) -> Result<Sensitivities, ScenarioError> {
    let mech = crate::generic::mechanism(entry, Some(span.formulation))?;
    let info = mech.info();
    let all = all_neighbours(entry, span.formulation, base, parameters)?;
    let n_out = output_count(span.t_end, span.output_step)?;
    let mut path = KinematicPath::<_>::new(mech, 0.0)?;
    let outputs = Outputs::new(mech, &free_bodies(&mech, 0.0, path.q())?);
    let names = outputs.names(mech);
    let mut result = Sensitivities {
        parameters: parameters.to_vec(),
        outputs: names.clone(),
        t: Vec::with_capacity(n_out + 1),
        rows: Vec::with_capacity(n_out + 1),
    };
    let mut ds = StateSensitivity::zeros(info);
    let mut work = OutputRow::new(names.len());
    for k in 0..=n_out {
        if k > 0 {
            path.advance_to((k as f64 * span.output_step).min(span.t_end))?;
        }
        let t = path.t();
        let mut row = vec![0.0; names.len() * all.len()];
        for (j, nb) in all.iter().enumerate() {
            path.sensitivity(nb, &mut ds)?;
            work.fill(
                &outputs,
                nb,
                t,
                (path.q(), &ds.dq),
                (path.lambda(), &ds.dlambda),
                &mut row,
                (j, all.len()),
            )?;
        }
        result.t.push(t);
        result.rows.push(row);
    }
    Ok(result)
}

/// The derivatives of the outputs of an integrated run (`generic::run` with `opts`) with
/// respect to `parameters`, the file's other parameters as in `base`: forward sensitivities
/// of the HHT steps ([`HhtSensitivity`]), then of the saddle-point multipliers recovered at
/// each output state, from which the run's efforts and wrenches are computed.
pub fn integrated(
    entry: &Entry,
    opts: &crate::generic::Options,
    base: &Overrides,
    parameters: &[String],
) -> Result<Sensitivities, ScenarioError> {
    let mech = crate::generic::mechanism(entry, opts.formulation)?;
    let info = mech.info();
    let f = info.formulation;
    let all = all_neighbours(entry, f, base, parameters)?;
    let t_end = opts.t_end.unwrap_or(entry.t_end);
    let n_out = output_count(t_end, opts.output_step)?;
    let mut it = crate::generic::integrator(mech, opts)?;
    let settings = crate::generic::solve_settings(opts.cross_singular);
    let project = it.settings().projects_velocities();
    let mut sens: Vec<HhtSensitivity> = all
        .iter()
        .map(|nb| {
            HhtSensitivity::start(
                nb,
                settings,
                (opts.alpha, project),
                it.t(),
                (it.q(), it.qd(), it.qdd(), it.lambda()),
            )
        })
        .collect::<Result<_, _>>()?;
    let outputs = Outputs::new(mech, &[]);
    let names = outputs.names(mech);
    let mut result = Sensitivities {
        parameters: parameters.to_vec(),
        outputs: names.clone(),
        t: Vec::with_capacity(n_out + 1),
        rows: Vec::with_capacity(n_out + 1),
    };
    let (n, m) = (info.n_coords, info.n_constraints);
    let (mut qdd, mut lambda, mut dqdd, mut dlambda) =
        (vec![0.0; n], vec![0.0; m], vec![0.0; n], vec![0.0; m]);
    let mut work = OutputRow::new(names.len());
    for k in 0..=n_out {
        let t_out = (k as f64 * opts.output_step).min(t_end);
        while it.step_toward(t_out)?.is_some() {
            for (s, nb) in sens.iter_mut().zip(&all) {
                s.step(nb, it.t(), (it.q(), it.qd(), it.qdd(), it.lambda()))?;
            }
        }
        let (t, q) = (it.t(), it.q());
        let mut row = vec![0.0; names.len() * all.len()];
        for (j, (s, nb)) in sens.iter_mut().zip(&all).enumerate() {
            s.recovered(nb, (&mut qdd, &mut lambda), (&mut dqdd, &mut dlambda))?;
            work.fill(
                &outputs,
                nb,
                t,
                (q, &s.state.dq),
                (&lambda, &dlambda),
                &mut row,
                (j, all.len()),
            )?;
        }
        result.t.push(t);
        result.rows.push(row);
    }
    Ok(result)
}

/// The sensitivities of a run of `scene` on `entry` (the scene's mechanism with the
/// parameters `base`), on the path the run took (`kinematic` or integrated).
pub fn of_scene(
    scene: &crate::scene::Scene,
    entry: &Entry,
    kinematic: bool,
    base: &Overrides,
    parameters: &[String],
) -> Result<Sensitivities, ScenarioError> {
    match kinematic {
        true => self::kinematic(
            entry,
            Span {
                formulation: scene.formulation,
                t_end: scene.t_end,
                output_step: scene.output_step,
            },
            base,
            parameters,
        ),
        false => integrated(entry, &crate::scene::options(scene), base, parameters),
    }
}
