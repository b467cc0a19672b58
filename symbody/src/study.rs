//! Studies (decision 32): one scene run many times with its mechanism file's parameters
//! varied (a grid, a list, or seeded random samples), each run reduced to a row of metrics;
//! the runs spread over worker threads, each row handed over as soon as it is done.
//!
//! Each run derives its mechanism from the file with its parameter values and frees it when
//! the row is done (`interpret::load_scoped_with`), so a study of any length holds one
//! mechanism per worker.

use crate::generic::Recording;
use crate::scenario::ScenarioError;
use crate::scene::{self, Files, Outcome, Scene, Selection};
use nalgebra::Vector3;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Instant;
use symbody_runtime::fk::{Legs, Pose};
use symbody_runtime::{Entry, JointKind, MechanismInfo};

/// How one parameter varies.
#[derive(Debug, Clone, PartialEq)]
pub enum Axis {
    /// `n` values from `from` to `to`, equally spaced (both ends included).
    Grid { from: f64, to: f64, n: usize },
    /// These values.
    List(Vec<f64>),
    /// Uniform on `[lo, hi)`.
    Uniform { lo: f64, hi: f64 },
    /// Normal with this mean and standard deviation.
    Normal { mean: f64, sd: f64 },
}

impl Axis {
    /// A distribution (sampled) rather than fixed values.
    pub fn is_random(&self) -> bool {
        matches!(self, Axis::Uniform { .. } | Axis::Normal { .. })
    }
}

/// A scene's `[study]`: the parameters varied and how the rows are drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct Study {
    /// In name order.
    pub parameters: Vec<(String, Axis)>,
    /// Random parameters: the number of rows.
    pub samples: usize,
    pub seed: u64,
    /// Random parameters: a Latin hypercube (each parameter's range cut into `samples`
    /// equally likely strata, each stratum used once) instead of independent draws.
    pub latin: bool,
    /// The metrics the scene asks for, in its order; `None`: the default set
    /// ([`default_metrics`]).
    pub metrics: Option<Vec<Metric>>,
}

/// One number each run is reduced to (a column of `study.csv`).
#[derive(Debug, Clone, PartialEq)]
pub enum Metric {
    /// `max|<driver>|`: the driver's largest |effort|.
    Driver(String),
    /// `max|F <joint>|`: the largest |force| of the joint's reaction.
    Force(String),
    /// `max|M <joint>|`: the largest |moment| of the joint's reaction.
    Moment(String),
    /// `energy_balance`: the energy drift relative to its scale.
    EnergyBalance,
    /// `max|Phi|`: the largest constraint violation at the outputs.
    MaxPhi,
    /// `min <coordinate>` or `max <coordinate>` (a name of `MechanismInfo::coord_names`, e.g.
    /// `platform.z`) over the outputs.
    Coordinate { name: String, max: bool },
    /// `min fk_condition` or `max fk_condition`: the 2-norm condition number of the six-leg
    /// platform's forward-kinematics Jacobian (pose → leg lengths, its rotation columns
    /// divided by the platform's radius so every column is in metres:
    /// `fk::Legs::condition`), smallest or largest over the outputs. The largest is the
    /// worst: how near the run comes to a parallel singularity.
    FkCondition { max: bool },
}

impl Metric {
    /// The metric's column name.
    pub fn name(&self) -> String {
        let extreme = |max: bool| if max { "max" } else { "min" };
        match self {
            Metric::Driver(d) => format!("max|{d}|"),
            Metric::Force(j) => format!("max|F {j}|"),
            Metric::Moment(j) => format!("max|M {j}|"),
            Metric::EnergyBalance => "energy_balance".to_string(),
            Metric::MaxPhi => "max|Phi|".to_string(),
            Metric::Coordinate { name, max } => format!("{} {name}", extreme(*max)),
            Metric::FkCondition { max } => format!("{} fk_condition", extreme(*max)),
        }
    }

    /// The metric called `name` for the mechanism of `info`; else the message and the help
    /// (the closest name) of a diagnostic.
    pub fn parse(name: &str, info: &MechanismInfo) -> Result<Metric, (String, String)> {
        let catalogue = catalogue(info);
        if let Some(m) = catalogue.iter().find(|m| m.name() == name) {
            return Ok(m.clone());
        }
        if info.platform.is_none() && matches!(name, "min fk_condition" | "max fk_condition") {
            return Err((
                format!(
                    "`{name}`: `{}` has no six-leg platform, so it has no forward-kinematics \
                     condition",
                    info.name
                ),
                "`symbody list` marks the mechanisms that have one (FK column)".to_string(),
            ));
        }
        let names: Vec<String> = catalogue.iter().map(Metric::name).collect();
        // A coordinate of a known body with a name too far from any: list that body's.
        let body = name
            .strip_prefix("min ")
            .or_else(|| name.strip_prefix("max "))
            .and_then(|c| c.split_once('.'))
            .and_then(|(b, _)| info.bodies.iter().find(|x| x.name == b));
        let help = match (
            crate::generic::closest(name, names.iter().map(String::as_str)),
            body,
        ) {
            (Some(c), _) => format!("did you mean `{c}`?"),
            (None, Some(b)) => format!(
                "the coordinates of `{}`: {}",
                b.name,
                info.coord_names
                    .get(b.coord_offset..b.coord_offset + b.n_coords())
                    .unwrap_or_default()
                    .join(", ")
            ),
            (None, None) => "the metrics: max|<driver>|, max|F <joint>|, max|M <joint>|, \
                             energy_balance, max|Phi|, min <body>.<coordinate> and max \
                             <body>.<coordinate> (e.g. `max platform.z`), min fk_condition \
                             and max fk_condition (six-leg platforms)"
                .to_string(),
        };
        Err((format!("no metric `{name}` for `{}`", info.name), help))
    }
}

/// Every metric the mechanism of `info` offers: the drivers' efforts, the reacting joints'
/// forces and moments, the energy balance, |Φ|, each coordinate's extremes and, for a
/// six-leg platform, the FK condition's.
pub fn catalogue(info: &MechanismInfo) -> Vec<Metric> {
    let mut all: Vec<Metric> = info
        .joints
        .iter()
        .filter(|j| j.kind == JointKind::Driver)
        .map(|j| Metric::Driver(j.name.to_string()))
        .collect();
    for j in info.joints {
        if !matches!(j.kind, JointKind::Driver | JointKind::Normalization) {
            all.push(Metric::Force(j.name.to_string()));
            all.push(Metric::Moment(j.name.to_string()));
        }
    }
    all.extend([Metric::EnergyBalance, Metric::MaxPhi]);
    for c in info.coord_names {
        for max in [false, true] {
            all.push(Metric::Coordinate {
                name: c.to_string(),
                max,
            });
        }
    }
    if info.platform.is_some() {
        all.extend([false, true].map(|max| Metric::FkCondition { max }));
    }
    all
}

/// A small, seeded generator (SplitMix64): the same seed gives the same rows everywhere.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform on (0, 1): never 0, so the inverse normal CDF stays finite.
    fn open01(&mut self) -> f64 {
        ((self.next() >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
}

/// The standard normal quantile by P. J. Acklam's published rational approximation
/// (relative error below 1.2e-9: far below any sampling question a study asks).
fn normal_quantile(p: f64) -> f64 {
    const A: [f64; 6] = [
        -3.969683028665376e1,
        2.209460984245205e2,
        -2.759285104469687e2,
        1.383_577_518_672_69e2,
        -3.066479806614716e1,
        2.506628277459239,
    ];
    const B: [f64; 5] = [
        -5.447609879822406e1,
        1.615858368580409e2,
        -1.556989798598866e2,
        6.680131188771972e1,
        -1.328068155288572e1,
    ];
    const C: [f64; 6] = [
        -7.784894002430293e-3,
        -3.223964580411365e-1,
        -2.400758277161838,
        -2.549732539343734,
        4.374664141464968,
        2.938163982698783,
    ];
    const D: [f64; 4] = [
        7.784695709041462e-3,
        3.224671290700398e-1,
        2.445134137142996,
        3.754408661907416,
    ];
    let tail = |q: f64| {
        (((((C[0] * q + C[1]) * q + C[2]) * q + C[3]) * q + C[4]) * q + C[5])
            / ((((D[0] * q + D[1]) * q + D[2]) * q + D[3]) * q + 1.0)
    };
    if p < 0.02425 {
        tail((-2.0 * p.ln()).sqrt())
    } else if p > 1.0 - 0.02425 {
        -tail((-2.0 * (1.0 - p).ln()).sqrt())
    } else {
        let q = p - 0.5;
        let r = q * q;
        (((((A[0] * r + A[1]) * r + A[2]) * r + A[3]) * r + A[4]) * r + A[5]) * q
            / (((((B[0] * r + B[1]) * r + B[2]) * r + B[3]) * r + B[4]) * r + 1.0)
    }
}

impl Study {
    /// Every row of parameter values, in a fixed order: the Cartesian product of the grids
    /// and lists (the first parameter varying slowest), or `samples` random rows (then every
    /// parameter is random).
    pub fn rows(&self) -> Vec<Vec<(String, f64)>> {
        let random = self.parameters.iter().any(|(_, a)| a.is_random());
        if !random {
            let mut rows: Vec<Vec<(String, f64)>> = vec![Vec::new()];
            for (name, axis) in &self.parameters {
                let values: Vec<f64> = match axis {
                    Axis::Grid { from, to, n } => (0..*n)
                        .map(|k| match n {
                            1 => *from,
                            _ => from + (to - from) * k as f64 / (*n - 1) as f64,
                        })
                        .collect(),
                    Axis::List(v) => v.clone(),
                    _ => unreachable!("no random parameter here"),
                };
                rows = rows
                    .into_iter()
                    .flat_map(|row| {
                        values.iter().map(move |&v| {
                            let mut r = row.clone();
                            r.push((name.clone(), v));
                            r
                        })
                    })
                    .collect();
            }
            return rows;
        }
        let mut rng = Rng(self.seed);
        let n = self.samples;
        // One column per parameter: probabilities in (0, 1), stratified for a Latin hypercube.
        let columns: Vec<Vec<f64>> = self
            .parameters
            .iter()
            .map(|_| {
                if self.latin {
                    let mut strata: Vec<usize> = (0..n).collect();
                    for i in (1..n).rev() {
                        strata.swap(i, (rng.next() % (i as u64 + 1)) as usize);
                    }
                    strata
                        .into_iter()
                        .map(|s| (s as f64 + rng.open01()) / n as f64)
                        .collect()
                } else {
                    (0..n).map(|_| rng.open01()).collect()
                }
            })
            .collect();
        (0..n)
            .map(|k| {
                self.parameters
                    .iter()
                    .zip(&columns)
                    .map(|((name, axis), col)| {
                        let p = col[k];
                        let v = match axis {
                            Axis::Uniform { lo, hi } => lo + (hi - lo) * p,
                            Axis::Normal { mean, sd } => mean + sd * normal_quantile(p),
                            Axis::List(_) | Axis::Grid { .. } => {
                                unreachable!(
                                    "the scene parser refuses fixed values among random ones"
                                )
                            }
                        };
                        (name.clone(), v)
                    })
                    .collect()
            })
            .collect()
    }
}

/// The metrics of a study of `scene` when its `[study]` names none: for each driver the
/// largest |effort| (when the scene asks for efforts), for each joint it asks reactions of
/// the largest |force| and |moment|, the relative energy balance and the largest |Φ|.
pub fn default_metrics(scene: &Scene) -> Vec<Metric> {
    let info = scene.entry.default_mechanism().info();
    let mut metrics: Vec<Metric> = match scene.efforts {
        false => Vec::new(),
        true => info
            .joints
            .iter()
            .filter(|j| j.kind == JointKind::Driver)
            .map(|j| Metric::Driver(j.name.to_string()))
            .collect(),
    };
    // The joints a table run records, in the recording's (ascending) order.
    let mut tables = scene.clone();
    tables.files = Files::Tables;
    let mut joints = scene::requested_joints(&tables, info);
    joints.sort_unstable();
    for k in joints {
        let name = info.joints[k].name.to_string();
        metrics.push(Metric::Force(name.clone()));
        metrics.push(Metric::Moment(name));
    }
    metrics.extend([Metric::EnergyBalance, Metric::MaxPhi]);
    metrics
}

/// The metrics of a study of `scene`: those its `[study]` names, else [`default_metrics`].
pub fn metrics(scene: &Scene) -> Vec<Metric> {
    match scene.study.as_ref().and_then(|s| s.metrics.clone()) {
        Some(m) => m,
        None => default_metrics(scene),
    }
}

/// The metric columns of a study of `scene`, in [`metrics`] order.
pub fn metric_names(scene: &Scene) -> Vec<String> {
    metrics(scene).iter().map(Metric::name).collect()
}

/// The drivers' metric columns (`max|<driver>|`) among [`metric_names`].
pub fn driver_metric_names(scene: &Scene) -> Vec<String> {
    metrics(scene)
        .iter()
        .filter(|m| matches!(m, Metric::Driver(_)))
        .map(Metric::name)
        .collect()
}

/// `scene` as a study runs it: tables, with the outputs it asks for plus those `metrics`
/// are read from (a driver's efforts, a joint's reaction, the body owning a coordinate or
/// the platform), so the path is chosen exact for them too.
fn recorded(scene: &Scene, metrics: &[Metric]) -> Scene {
    let info = scene.entry.default_mechanism().info();
    let mut tables = scene.clone();
    tables.files = Files::Tables;
    // The rows run on every core already.
    tables.path_thread = false;
    let mut bodies = Vec::new();
    let mut joints = Vec::new();
    for m in metrics {
        match m {
            Metric::Driver(_) => tables.efforts = true,
            Metric::Force(j) | Metric::Moment(j) => joints.extend(info.joint_index(j)),
            Metric::Coordinate { name, .. } => {
                let k = info.coord_names.iter().position(|c| c == name);
                bodies.extend(k.and_then(|k| {
                    info.bodies
                        .iter()
                        .position(|b| (b.coord_offset..b.coord_offset + b.n_coords()).contains(&k))
                }));
            }
            Metric::FkCondition { .. } => bodies.extend(info.platform.map(|p| p.body)),
            Metric::EnergyBalance | Metric::MaxPhi => {}
        }
    }
    let widen = |selection: &Selection, extra: &[usize]| match selection {
        Selection::All => Selection::All,
        _ if extra.is_empty() => selection.clone(),
        Selection::None => Selection::Only(sorted(extra.to_vec())),
        Selection::Only(v) => Selection::Only(sorted(v.iter().chain(extra).copied().collect())),
    };
    tables.poses = widen(&tables.poses, &bodies);
    tables.reactions = widen(&tables.reactions, &joints);
    tables
}

fn sorted(mut v: Vec<usize>) -> Vec<usize> {
    v.sort_unstable();
    v.dedup();
    v
}

/// One finished run: its row index, its metrics (in [`metric_names`] order) or why it failed,
/// and its wall time.
#[derive(Debug, Clone)]
pub struct RowResult {
    pub index: usize,
    pub parameters: Vec<(String, f64)>,
    pub metrics: Result<Vec<f64>, String>,
    pub wall: f64,
}

/// `metrics` of a recording, in their order; an error when the recording lacks what one is
/// read from (its run's mechanism, derived for the row's parameters, has other names).
fn metrics_of(rec: &Recording, metrics: &[Metric]) -> Result<Vec<f64>, String> {
    let info = rec.info;
    let max_abs = |it: &mut dyn Iterator<Item = f64>| it.fold(0.0f64, |m, x| m.max(x.abs()));
    let extreme = |it: &mut dyn Iterator<Item = f64>, max: bool| match max {
        true => it.fold(f64::NEG_INFINITY, f64::max),
        false => it.fold(f64::INFINITY, f64::min),
    };
    let norm = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let joint = |name: &str| {
        rec.joints
            .iter()
            .position(|&j| info.joints[j].name == name)
            .ok_or_else(|| format!("no reaction of `{name}` recorded"))
    };
    let mut out = Vec::with_capacity(metrics.len());
    for m in metrics {
        out.push(match m {
            Metric::Driver(name) => {
                let d = rec
                    .drivers
                    .iter()
                    .position(|&j| info.joints[j].name == name)
                    .ok_or_else(|| format!("no effort of `{name}` recorded"))?;
                max_abs(&mut rec.efforts.iter().map(|e| e[d]))
            }
            Metric::Force(name) => {
                let j = joint(name)?;
                max_abs(&mut rec.wrenches.iter().map(|w| norm(w[j].force)))
            }
            Metric::Moment(name) => {
                let j = joint(name)?;
                max_abs(&mut rec.wrenches.iter().map(|w| norm(w[j].moment)))
            }
            Metric::EnergyBalance => {
                let (drift, scale) = rec.energy_balance().ok_or(
                    "the energy balance is not computed when the scene sets energy = false \
                     (the kinematic path then integrates no work): set energy = true",
                )?;
                if scale > 0.0 {
                    drift / scale
                } else {
                    drift
                }
            }
            Metric::MaxPhi => rec.max_phi,
            Metric::Coordinate { name, max } => {
                let k = info
                    .coord_names
                    .iter()
                    .position(|c| c == name)
                    .ok_or_else(|| format!("no coordinate `{name}`"))?;
                extreme(&mut rec.q.iter().map(|q| q[k]), *max)
            }
            Metric::FkCondition { max } => {
                let conditions = fk_conditions(info, &rec.q)?;
                extreme(&mut conditions.into_iter(), *max)
            }
        });
    }
    Ok(out)
}

/// The condition number of the six-leg platform's forward-kinematics Jacobian
/// (`fk::Legs::condition`) at each of the coordinates `qs`.
pub fn fk_conditions(info: &MechanismInfo, qs: &[Vec<f64>]) -> Result<Vec<f64>, String> {
    let platform = info
        .platform
        .filter(|p| p.legs.len() == 6 && p.body < info.bodies.len())
        .ok_or_else(|| format!("`{}` has no six-leg platform", info.name))?;
    let legs = Legs {
        base: std::array::from_fn(|i| Vector3::from(platform.legs[i].base)),
        top: std::array::from_fn(|i| Vector3::from(platform.legs[i].platform)),
    };
    let body = &info.bodies[platform.body];
    qs.iter()
        .map(|q| {
            let r = q
                .get(body.coord_offset..body.coord_offset + 3)
                .ok_or_else(|| "the platform's coordinates lie outside q".to_string())?;
            let rotation = symbody_runtime::rotation_matrix(body, q).map_err(|e| e.to_string())?;
            let pose = Pose {
                position: Vector3::new(r[0], r[1], r[2]),
                rotation,
            };
            Ok(legs.condition(&pose))
        })
        .collect()
}

/// Runs `scene` with `parameters` (on top of its own) on a mechanism derived for them and
/// freed afterwards, and reduces the run to `metrics`.
pub fn run_row(
    scene: &Scene,
    metrics: &[Metric],
    text: &str,
    source: &str,
    parameters: &[(String, f64)],
) -> Result<Vec<f64>, String> {
    let merged = crate::files::merged(&scene.parameters, parameters);
    // Tables, whatever the scene writes: the metrics are read from the generic recording.
    let tables = recorded(scene, metrics);
    let run_entry = |entry: &Entry| -> Result<Vec<f64>, String> {
        match scene::run_observed(&tables, entry, &mut ()) {
            Err(e) => Err(e.to_string()),
            Ok((_, Err(stopped))) => Err(stopped.error.to_string()),
            Ok((_, Ok(Outcome::Tables(rec)))) => metrics_of(&rec, metrics),
            Ok((_, Ok(Outcome::Paper(_)))) => unreachable!("the study runs tables"),
        }
    };
    // Rows that set only run-time parameters of the compiled code run it: nothing derived.
    if let Some(result) = crate::files::with_compiled_at(scene.entry, &merged, run_entry)
        .map_err(|e| e.to_string())?
    {
        return result;
    }
    let run = |loaded: &symbody_codegen::interpret::Loaded| run_entry(loaded.entry);
    // SAFETY: nothing from the entry outlives `run`: the recording is reduced to numbers in it.
    unsafe {
        symbody_codegen::interpret::load_scoped_with(source, text, &merged, false, run).map_err(
            |e| {
                let shown = e.to_string();
                shown.strip_prefix("error: ").unwrap_or(&shown).to_string()
            },
        )?
    }
}

/// Runs the rows of `rows` whose index is not in `done` on `jobs` threads, each reduced to
/// `metrics`, calling `sink` (on this thread) with each as it finishes; stops taking new
/// rows once `stop` is set.
pub fn run(
    scene: &Scene,
    metrics: &[Metric],
    rows: &[Vec<(String, f64)>],
    done: &std::collections::HashSet<usize>,
    jobs: usize,
    stop: &AtomicBool,
    mut sink: impl FnMut(RowResult) -> Result<(), ScenarioError>,
) -> Result<(), ScenarioError> {
    let source = crate::files::source_of(scene.entry)?;
    let text = crate::files::read(std::path::Path::new(&source))?;
    let pending: Vec<usize> = (0..rows.len()).filter(|i| !done.contains(i)).collect();
    let next = AtomicUsize::new(0);
    let (send, receive) = std::sync::mpsc::channel::<RowResult>();
    std::thread::scope(|s| {
        for _ in 0..jobs.max(1) {
            let send = send.clone();
            let (next, pending, text, source) = (&next, &pending, &text, &source);
            s.spawn(move || loop {
                if stop.load(Ordering::Relaxed) {
                    break;
                }
                let k = next.fetch_add(1, Ordering::Relaxed);
                let Some(&index) = pending.get(k) else { break };
                let clock = Instant::now();
                let values = run_row(scene, metrics, text, source, &rows[index]);
                let row = RowResult {
                    index,
                    parameters: rows[index].clone(),
                    metrics: values,
                    wall: clock.elapsed().as_secs_f64(),
                };
                if send.send(row).is_err() {
                    break;
                }
            });
        }
        drop(send);
        for row in receive {
            if let Err(e) = sink(row) {
                stop.store(true, Ordering::Relaxed);
                return Err(e);
            }
        }
        Ok(())
    })
}

/// The columns of `study.csv`: `run` (the row's index), the parameters, the metrics, then
/// `status` (`ok` or `failed`), `error` and `wall_s`.
pub fn columns(study: &Study, scene: &Scene) -> Vec<String> {
    std::iter::once("run".to_string())
        .chain(study.parameters.iter().map(|(n, _)| n.clone()))
        .chain(metric_names(scene))
        .chain(["status", "error", "wall_s"].map(String::from))
        .collect()
}

/// `study.csv`, written row by row (each row flushed whole, so an interrupted study leaves a
/// valid table).
pub struct Table {
    writer: csv::Writer<std::fs::File>,
    width: usize,
}

impl Table {
    /// Creates `path` with `columns`; with `resume`, keeps the complete rows of an existing
    /// file with the same columns (a row cut short by an interruption is dropped) and returns
    /// their run indices.
    pub fn open(
        path: &std::path::Path,
        columns: &[String],
        resume: bool,
    ) -> Result<(Self, std::collections::HashSet<usize>), ScenarioError> {
        let fail =
            |e: &dyn std::fmt::Display| ScenarioError::Output(format!("{}: {e}", path.display()));
        let mut kept: Vec<csv::StringRecord> = Vec::new();
        if resume && path.exists() {
            let mut reader = csv::ReaderBuilder::new()
                .flexible(true)
                .from_path(path)
                .map_err(|e| fail(&e))?;
            let header: Vec<String> = reader
                .headers()
                .map_err(|e| fail(&e))?
                .iter()
                .map(String::from)
                .collect();
            if header != columns {
                return Err(ScenarioError::Options(format!(
                    "--resume: {} has other columns than this study ({}); remove it or give \
                     another --out",
                    path.display(),
                    header.join(",")
                )));
            }
            for record in reader.records() {
                match record {
                    Ok(r) if r.len() == columns.len() && r[0].parse::<usize>().is_ok() => {
                        kept.push(r)
                    }
                    _ => {}
                }
            }
        }
        let mut writer = csv::Writer::from_path(path).map_err(|e| fail(&e))?;
        writer.write_record(columns).map_err(|e| fail(&e))?;
        let mut done = std::collections::HashSet::new();
        for r in &kept {
            writer.write_record(r).map_err(|e| fail(&e))?;
            done.insert(r[0].parse::<usize>().expect("checked above"));
        }
        writer.flush().map_err(|e| fail(&e))?;
        let width = columns.len();
        Ok((Table { writer, width }, done))
    }

    /// Appends one finished run.
    pub fn write(&mut self, row: &RowResult, n_metrics: usize) -> Result<(), ScenarioError> {
        let mut record: Vec<String> = vec![row.index.to_string()];
        record.extend(row.parameters.iter().map(|(_, v)| format!("{v:?}")));
        match &row.metrics {
            Ok(m) => {
                record.extend(m.iter().map(|v| format!("{v:?}")));
                record.extend(["ok".to_string(), String::new()]);
            }
            Err(e) => {
                record.extend((0..n_metrics).map(|_| String::new()));
                record.extend(["failed".to_string(), e.clone()]);
            }
        }
        record.push(format!("{:.6}", row.wall));
        assert_eq!(record.len(), self.width, "a row has every column");
        let fail = |e: &dyn std::fmt::Display| ScenarioError::Output(e.to_string());
        self.writer.write_record(&record).map_err(|e| fail(&e))?;
        self.writer.flush().map_err(|e| fail(&e))
    }
}

/// The columns and rows of a `study.csv`, as text, in file order.
pub fn read(path: &std::path::Path) -> Result<(Vec<String>, Vec<Vec<String>>), ScenarioError> {
    let fail =
        |e: &dyn std::fmt::Display| ScenarioError::Output(format!("{}: {e}", path.display()));
    let mut reader = csv::Reader::from_path(path).map_err(|e| fail(&e))?;
    let columns = reader
        .headers()
        .map_err(|e| fail(&e))?
        .iter()
        .map(String::from)
        .collect();
    let rows = reader
        .records()
        .map(|r| r.map(|r| r.iter().map(String::from).collect()))
        .collect::<Result<_, _>>()
        .map_err(|e| fail(&e))?;
    Ok((columns, rows))
}

#[cfg(test)]
mod tests {
    use super::*;
    use symbody_mechanisms::REGISTRY;

    fn info(name: &str) -> &'static MechanismInfo {
        REGISTRY.find(name).unwrap().default_mechanism().info()
    }

    #[test]
    fn every_metric_name_reads_back_as_its_metric() {
        for mechanism in ["slider_crank", "stewart_6_6"] {
            let info = info(mechanism);
            let all = catalogue(info);
            assert!(all.contains(&Metric::Coordinate {
                name: info.coord_names[0].to_string(),
                max: true
            }));
            assert_eq!(
                all.contains(&Metric::FkCondition { max: true }),
                mechanism == "stewart_6_6"
            );
            for m in all {
                assert_eq!(
                    Metric::parse(&m.name(), info),
                    Ok(m.clone()),
                    "{}",
                    m.name()
                );
            }
        }
        let parsed = Metric::parse("max platform.z", info("stewart_6_6"));
        assert_eq!(
            parsed,
            Ok(Metric::Coordinate {
                name: "platform.z".into(),
                max: true
            })
        );
    }

    #[test]
    fn unknown_metrics_say_what_is_close_or_what_there_is() {
        let crank = info("slider_crank");
        let (message, help) = Metric::parse("max|motr|", crank).unwrap_err();
        assert!(message.contains("no metric `max|motr|`"), "{message}");
        assert_eq!(help, "did you mean `max|motor|`?");
        let (message, _) = Metric::parse("max fk_condition", crank).unwrap_err();
        assert!(message.contains("no six-leg platform"), "{message}");
        let body = crank.bodies[0];
        let (_, help) =
            Metric::parse(&format!("min {}.nothing_like_it", body.name), crank).unwrap_err();
        assert!(
            help.contains(crank.coord_names[body.coord_offset]),
            "{help}"
        );
        let (_, help) = Metric::parse("largest of all", crank).unwrap_err();
        assert!(help.contains("fk_condition"), "{help}");
    }

    /// A study's rows already run on every core: each row's kinematic path stays on its
    /// worker's thread (with a thread of its own per row, the example study took 1.5–1.9
    /// times as long on two cores).
    #[test]
    fn a_row_runs_its_path_on_its_workers_thread() {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../examples/studies/paper_platform.toml"
        );
        let text = std::fs::read_to_string(path).unwrap();
        let scene = crate::scene::load(&REGISTRY, path, &text).unwrap();
        assert!(scene.path_thread);
        let row = recorded(&scene, &metrics(&scene));
        assert_eq!(row.files, Files::Tables);
        assert!(!row.path_thread);
        assert!(!scene::options(&row).path_thread);
    }

    /// The coordinate extremes are those of the recorded coordinates; the FK condition at the
    /// platform's symmetric home pose is that of the legs' Jacobian, differentiated here by
    /// central differences of the leg lengths.
    #[test]
    fn coordinate_and_fk_metrics_of_a_recording() {
        let entry = REGISTRY.find("stewart_6_6").unwrap();
        let opts = crate::generic::Options {
            t_end: Some(0.3),
            ..Default::default()
        };
        let rec = crate::generic::run_kinematic(entry, &opts).unwrap();
        let info = rec.info;
        let z = info
            .coord_names
            .iter()
            .position(|c| *c == "platform.z")
            .unwrap();
        let metrics = [
            Metric::Coordinate {
                name: "platform.z".into(),
                max: false,
            },
            Metric::Coordinate {
                name: "platform.z".into(),
                max: true,
            },
            Metric::FkCondition { max: true },
        ];
        let got = metrics_of(&rec, &metrics).unwrap();
        let zs: Vec<f64> = rec.q.iter().map(|q| q[z]).collect();
        assert!(zs.contains(&got[0]) && zs.iter().all(|&v| v >= got[0]));
        assert!(zs.contains(&got[1]) && zs.iter().all(|&v| v <= got[1]));
        assert!(got[1] > got[0], "the platform moves: {got:?}");
        let conditions = fk_conditions(info, &rec.q).unwrap();
        assert_eq!(got[2], conditions.iter().copied().fold(0.0, f64::max));
        // At the first output (the home pose), by differences of the lengths |p + R b − a|
        // for small moves of the platform (symbody_testkit::platform).
        let platform = info.platform.unwrap();
        let body = &info.bodies[platform.body];
        let q0 = &rec.q[0][..];
        let p0 = Vector3::from_column_slice(&q0[body.coord_offset..body.coord_offset + 3]);
        let r0 = symbody_runtime::rotation_matrix(body, q0).unwrap();
        let want = symbody_testkit::platform::fk_condition(platform.legs, p0, r0);
        assert!(
            (conditions[0] - want).abs() < 1e-7 * want,
            "{} vs {want}",
            conditions[0]
        );
    }

    #[test]
    fn the_normal_quantile_inverts_the_cdf() {
        // Published quantiles of the standard normal.
        for (p, x) in [
            (0.5, 0.0),
            (0.975, 1.959963984540054),
            (0.001, -3.090232306167813),
        ] {
            assert!(
                (normal_quantile(p) - x).abs() < 1e-8,
                "{p}: {}",
                normal_quantile(p)
            );
        }
    }

    #[test]
    fn grids_are_products_and_latin_rows_use_each_stratum_once() {
        let grid = Study {
            parameters: vec![
                (
                    "a".into(),
                    Axis::Grid {
                        from: 0.0,
                        to: 1.0,
                        n: 3,
                    },
                ),
                ("b".into(), Axis::List(vec![5.0, 6.0])),
            ],
            samples: 0,
            seed: 1,
            latin: false,
            metrics: None,
        };
        let rows = grid.rows();
        assert_eq!(rows.len(), 6);
        assert_eq!(rows[0], vec![("a".into(), 0.0), ("b".into(), 5.0)]);
        assert_eq!(rows[5], vec![("a".into(), 1.0), ("b".into(), 6.0)]);
        let latin = Study {
            parameters: vec![("u".into(), Axis::Uniform { lo: 0.0, hi: 10.0 })],
            samples: 10,
            seed: 7,
            latin: true,
            metrics: None,
        };
        let mut strata: Vec<usize> = latin.rows().iter().map(|r| r[0].1 as usize).collect();
        strata.sort_unstable();
        assert_eq!(strata, (0..10).collect::<Vec<_>>());
        assert_eq!(latin.rows(), latin.rows(), "seeded");
    }
}
