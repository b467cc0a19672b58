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
    resume: bool,
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
    let n_metrics = study::metric_names(&scene).len();
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
    let result = study::run(&scene, &rows, &done, jobs, live::interrupt_flag(), |row| {
        match row.metrics {
            Ok(_) => ok += 1,
            Err(_) => failed += 1,
        }
        bar.inc(1);
        bar.set_message(format!("{failed} failed"));
        table.write(&row, n_metrics)
    });
    live::listen(false);
    bar.finish_and_clear();
    result.map_err(|e| e.to_string())?;
    let wall = clock.elapsed().as_secs_f64();
    say!(
        "  runs             {ok} ok, {failed} failed in {wall:.2} s ({:.1} runs/s)",
        (ok + failed) as f64 / wall.max(1e-9)
    );
    say!("  wrote {}", file.display());
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
