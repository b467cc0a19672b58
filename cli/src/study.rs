//! `symbody study <scene>`: the scene run once per row of its `[study]`, on every core, each
//! row of metrics written to `study.csv` as soon as its run ends; Ctrl-C stops taking new
//! rows and leaves a valid table that `--resume` completes.

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::path::Path;
use std::sync::atomic::Ordering;
use std::time::Instant;
use symbody::study::{self, Table};
use symbody_runtime::Registry;

use crate::live;

/// Runs the study of the scene at `path` into `out` on `jobs` threads.
pub fn run(
    registry: &Registry,
    path: &Path,
    out: &Path,
    jobs: usize,
    (resume, plots): (bool, bool),
) -> Result<(), String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read scene file {}: {e}", path.display()))?;
    let scene =
        symbody::scene::load(registry, &path.display().to_string(), &text).map_err(|e| {
            let shown = e.to_string();
            shown.strip_prefix("error: ").unwrap_or(&shown).to_string()
        })?;
    let Some(st) = scene.study.clone() else {
        return Err(format!(
            "{}: no [study] table: say which parameters to vary, e.g.\n  [study]\n  \
             parameters = {{ r = {{ from = 0.08, to = 0.12, n = 5 }} }}",
            path.display()
        ));
    };
    live::check_folder(out)?;
    let rows = st.rows();
    let columns = study::columns(&st, &scene);
    let metrics = study::metrics(&scene);
    let n_metrics = metrics.len();
    let file = out.join("study.csv");
    let (mut table, done) = Table::open(&file, &columns, resume).map_err(|e| e.to_string())?;
    let left = rows.len() - done.len().min(rows.len());
    say!(
        "study {}: {} runs of `{}` ({} already in {}), {} at a time",
        path.display(),
        rows.len(),
        scene.mechanism,
        done.len(),
        file.display(),
        jobs
    );
    let bar = if std::io::stderr().is_terminal() {
        let bar = ProgressBar::new(left as u64);
        bar.set_style(
            ProgressStyle::with_template("{bar:30} {pos}/{len} runs, {msg} [{elapsed} < {eta}]")
                .expect("a valid template"),
        );
        bar
    } else {
        ProgressBar::hidden()
    };
    let (mut ok, mut failed) = (0usize, 0usize);
    let clock = Instant::now();
    live::listen(true);
    let result = study::run(
        &scene,
        &metrics,
        &rows,
        &done,
        jobs,
        live::interrupt_flag(),
        |row| {
            match row.metrics {
                Ok(_) => ok += 1,
                Err(_) => failed += 1,
            }
            bar.inc(1);
            bar.set_message(format!("{failed} failed"));
            table.write(&row, n_metrics)
        },
    );
    live::listen(false);
    bar.finish_and_clear();
    result.map_err(|e| e.to_string())?;
    let wall = clock.elapsed().as_secs_f64();
    say!(
        "  runs             {ok} ok, {failed} failed in {wall:.2} s ({:.1} runs/s)",
        (ok + failed) as f64 / wall.max(1e-9)
    );
    say!("  wrote {}", file.display());
    if plots && !live::interrupt_flag().load(Ordering::SeqCst) {
        if let Some(png) = plot(&file, &st, &scene)? {
            say!("  wrote {}", png.display());
        }
    }
    if live::interrupt_flag().load(Ordering::SeqCst) {
        let total = done.len() + ok + failed;
        return Err(format!(
            "interrupted: {total} of {} rows in {}; `symbody study {} --out {} --resume` runs the rest",
            rows.len(),
            file.display(),
            path.display(),
            out.display()
        ));
    }
    Ok(())
}

/// `study.png`, for grids and lists of one or two parameters: the largest driver effort
/// (the study's main quantity, when it has drivers) and each other metric the scene's
/// `metrics` names (without drivers or named metrics: the first metric), at most four
/// panels. Against one parameter, curves (one per driver for the efforts); over two, a heat
/// map of each with its colour bar.
fn plot(
    file: &Path,
    st: &study::Study,
    scene: &symbody::scene::Scene,
) -> Result<Option<std::path::PathBuf>, String> {
    const MOST: usize = 4;
    let random = st.parameters.iter().any(|(_, a)| a.is_random());
    if random || st.parameters.is_empty() || st.parameters.len() > 2 {
        return Ok(None);
    }
    let drivers = study::driver_metric_names(scene);
    let names = study::metric_names(scene);
    let others: Vec<String> = match (&st.metrics, drivers.is_empty()) {
        (Some(_), _) => names
            .iter()
            .filter(|n| !drivers.contains(n))
            .cloned()
            .collect(),
        (None, true) => names.first().cloned().into_iter().collect(),
        (None, false) => Vec::new(),
    };
    let others = &others[..others.len().min(MOST - usize::from(!drivers.is_empty()))];
    let (columns, rows) = study::read(file).map_err(|e| e.to_string())?;
    let col = |name: &str| columns.iter().position(|c| c == name);
    let num = |r: &Vec<String>, k: usize| r[k].parse::<f64>().unwrap_or(f64::NAN);
    // The ascending distinct values of a parameter's column.
    let values = |k: usize| {
        let mut v: Vec<f64> = rows.iter().map(|r| num(r, k)).collect();
        v.sort_by(f64::total_cmp);
        v.dedup();
        v
    };
    let peak = |r: &Vec<String>| {
        drivers
            .iter()
            .filter_map(|n| col(n))
            .map(|k| num(r, k))
            .fold(f64::NAN, f64::max)
    };
    let metric = |name: &str| {
        let k = col(name);
        move |r: &Vec<String>| k.map_or(f64::NAN, |k| num(r, k))
    };
    let x_name = &st.parameters[0].0;
    let xi = col(x_name).ok_or_else(|| format!("{}: no column `{x_name}`", file.display()))?;
    let xs = values(xi);
    let png = file.with_file_name("study.png");
    let title = format!("study of {}", scene.mechanism);
    match st.parameters.get(1) {
        None => {
            // The value of `f` at each x (NaN where a run failed).
            let series = |f: &dyn Fn(&Vec<String>) -> f64| {
                xs.iter()
                    .map(|&x| rows.iter().find(|r| num(r, xi) == x).map_or(f64::NAN, f))
                    .collect::<Vec<f64>>()
            };
            let mut panels = Vec::new();
            if !drivers.is_empty() {
                panels.push(crate::plot::Panel {
                    y_label: "largest |effort| over the run".into(),
                    series: drivers
                        .iter()
                        .map(|d| (d.as_str(), series(&metric(d))))
                        .collect(),
                });
            }
            for o in others {
                panels.push(crate::plot::Panel {
                    y_label: o.as_str().into(),
                    series: vec![(o.as_str(), series(&metric(o)))],
                });
            }
            crate::plot::draw_against(&png, &title, x_name, &xs, &panels)?;
        }
        Some((y_name, _)) => {
            let yi =
                col(y_name).ok_or_else(|| format!("{}: no column `{y_name}`", file.display()))?;
            let ys = values(yi);
            // The value of `f` at each grid point, rows of y (NaN where a run failed).
            let grid = |f: &dyn Fn(&Vec<String>) -> f64| {
                ys.iter()
                    .map(|&y| {
                        xs.iter()
                            .map(|&x| {
                                rows.iter()
                                    .find(|r| num(r, xi) == x && num(r, yi) == y)
                                    .map_or(f64::NAN, f)
                            })
                            .collect()
                    })
                    .collect::<Vec<Vec<f64>>>()
            };
            let mut maps = Vec::new();
            if !drivers.is_empty() {
                maps.push(crate::plot::HeatMap {
                    label: "largest |effort| of any driver",
                    values: grid(&peak),
                });
            }
            for o in others {
                maps.push(crate::plot::HeatMap {
                    label: o,
                    values: grid(&metric(o)),
                });
            }
            crate::plot::draw_heat_maps(&png, &title, (x_name, &xs), (y_name, &ys), &maps)?;
        }
    }
    Ok(Some(png))
}
