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

/// `study.png`: the largest driver effort of each run against the study's first parameter;
/// one curve per driver when it varies alone, else one curve per value of the second
/// parameter (of the largest over the drivers). Only for grids and lists, with drivers.
fn plot(
    file: &Path,
    st: &study::Study,
    scene: &symbody::scene::Scene,
) -> Result<Option<std::path::PathBuf>, String> {
    let random = st.parameters.iter().any(|(_, a)| a.is_random());
    let drivers = study::driver_metric_names(scene);
    if random || drivers.is_empty() || st.parameters.len() > 2 {
        return Ok(None);
    }
    let (columns, rows) = study::read(file).map_err(|e| e.to_string())?;
    let col = |name: &str| columns.iter().position(|c| c == name);
    let num = |r: &Vec<String>, k: usize| r[k].parse::<f64>().unwrap_or(f64::NAN);
    let x_name = &st.parameters[0].0;
    let xi = col(x_name).expect("the parameter's column");
    let mut xs: Vec<f64> = rows.iter().map(|r| num(r, xi)).collect();
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    let peak = |r: &Vec<String>, names: &[String]| {
        names
            .iter()
            .filter_map(|n| col(n))
            .map(|k| num(r, k))
            .fold(f64::NAN, f64::max)
    };
    // The value of `f` at each x for the rows `keep` selects (NaN where a run failed).
    let series = |keep: &dyn Fn(&Vec<String>) -> bool, f: &dyn Fn(&Vec<String>) -> f64| {
        xs.iter()
            .map(|&x| {
                rows.iter()
                    .find(|r| num(r, xi) == x && keep(r))
                    .map_or(f64::NAN, f)
            })
            .collect::<Vec<f64>>()
    };
    let labels: Vec<String>;
    let mut curves: Vec<Vec<f64>> = Vec::new();
    match st.parameters.get(1) {
        None => {
            labels = drivers.clone();
            for d in &drivers {
                let k = col(d).expect("the metric's column");
                curves.push(series(&|_| true, &|r| num(r, k)));
            }
        }
        Some((y_name, _)) => {
            let yi = col(y_name).expect("the parameter's column");
            let mut ys: Vec<f64> = rows.iter().map(|r| num(r, yi)).collect();
            ys.sort_by(f64::total_cmp);
            ys.dedup();
            // Grid values carry the roundoff of their spacing: shown to 9 digits.
            labels = ys
                .iter()
                .map(|y| {
                    format!(
                        "{y_name} = {}",
                        format!("{y:.9}")
                            .trim_end_matches('0')
                            .trim_end_matches('.')
                    )
                })
                .collect();
            for &y in &ys {
                curves.push(series(&|r| num(r, yi) == y, &|r| peak(r, &drivers)));
            }
        }
    }
    let y_label = match st.parameters.len() {
        1 => "largest |effort| over the run",
        _ => "largest |effort| of any driver",
    };
    let panel = crate::plot::Panel {
        y_label,
        series: labels.iter().map(String::as_str).zip(curves).collect(),
    };
    let png = file.with_file_name("study.png");
    crate::plot::draw_against(
        &png,
        &format!("study of {}", scene.mechanism),
        x_name,
        &xs,
        &[panel],
    )?;
    Ok(Some(png))
}
