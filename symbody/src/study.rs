//! Studies (decision 32): one scene run many times with its mechanism file's parameters
//! varied (a grid, a list, or seeded random samples), each run reduced to a row of metrics;
//! the runs spread over worker threads, each row handed over as soon as it is done.
//!
//! Each run derives its mechanism from the file with its parameter values and frees it when
//! the row is done (`interpret::load_scoped_with`), so a study of any length holds one
//! mechanism per worker.

use crate::generic::Recording;
use crate::scenario::ScenarioError;
use crate::scene::{self, Files, Outcome, Scene};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Instant;
use symbody_runtime::{Entry, JointKind};

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

/// The metric columns of a study of `scene`: for each driver the largest |effort|, for each
/// joint the largest |force| and |moment|, the relative energy balance and the largest |Φ|.
pub fn metric_names(scene: &Scene) -> Vec<String> {
    let info = scene.entry.default_mechanism().info();
    let mut names = driver_metric_names(scene);
    // The joints a table run records, in the recording's (ascending) order.
    let mut tables = scene.clone();
    tables.files = Files::Tables;
    let mut joints = scene::requested_joints(&tables, info);
    joints.sort_unstable();
    for k in joints {
        let j = &info.joints[k];
        names.push(format!("max|F {}|", j.name));
        names.push(format!("max|M {}|", j.name));
    }
    names.push("energy_balance".to_string());
    names.push("max|Phi|".to_string());
    names
}

/// The drivers' metric columns (`max|<driver>|`), the first of [`metric_names`]; none when
/// the scene asks for no efforts.
pub fn driver_metric_names(scene: &Scene) -> Vec<String> {
    let info = scene.entry.default_mechanism().info();
    match scene.efforts {
        false => Vec::new(),
        true => info
            .joints
            .iter()
            .filter(|j| j.kind == JointKind::Driver)
            .map(|j| format!("max|{}|", j.name))
            .collect(),
    }
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

fn metrics_of(rec: &Recording) -> Vec<f64> {
    let max = |it: &mut dyn Iterator<Item = f64>| it.fold(0.0f64, |m, x| m.max(x.abs()));
    let mut out = Vec::new();
    for d in 0..rec.drivers.len() {
        out.push(max(&mut rec.efforts.iter().map(|e| e[d])));
    }
    for j in 0..rec.joints.len() {
        let norm = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        out.push(max(&mut rec.wrenches.iter().map(|w| norm(w[j].force))));
        out.push(max(&mut rec.wrenches.iter().map(|w| norm(w[j].moment))));
    }
    let (drift, scale) = rec.energy_balance();
    out.push(if scale > 0.0 { drift / scale } else { drift });
    out.push(rec.max_phi);
    out
}

/// Runs `scene` with `parameters` (on top of its own) on a mechanism derived for them and
/// freed afterwards.
pub fn run_row(
    scene: &Scene,
    text: &str,
    source: &str,
    parameters: &[(String, f64)],
) -> Result<Vec<f64>, String> {
    let merged = crate::files::merged(&scene.parameters, parameters);
    // Tables, whatever the scene writes: the metrics are read from the generic recording.
    let mut tables = scene.clone();
    tables.files = Files::Tables;
    let run = |loaded: &symbody_codegen::interpret::Loaded| -> Result<Vec<f64>, String> {
        let entry: &Entry = loaded.entry;
        match scene::run_observed(&tables, entry, &mut ()) {
            Err(e) => Err(e.to_string()),
            Ok((_, Err(stopped))) => Err(stopped.error.to_string()),
            Ok((_, Ok(Outcome::Tables(rec)))) => Ok(metrics_of(&rec)),
            Ok((_, Ok(Outcome::Paper(_)))) => unreachable!("the study runs tables"),
        }
    };
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

/// Runs the rows of `rows` whose index is not in `done` on `jobs` threads, calling `sink`
/// (on this thread) with each as it finishes; stops taking new rows once `stop` is set.
pub fn run(
    scene: &Scene,
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
                let metrics = run_row(scene, text, source, &rows[index]);
                let row = RowResult {
                    index,
                    parameters: rows[index].clone(),
                    metrics,
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
        };
        let mut strata: Vec<usize> = latin.rows().iter().map(|r| r[0].1 as usize).collect();
        strata.sort_unstable();
        assert_eq!(strata, (0..10).collect::<Vec<_>>());
        assert_eq!(latin.rows(), latin.rows(), "seeded");
    }
}
