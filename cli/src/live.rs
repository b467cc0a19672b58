//! What a run shows and writes while it goes: its tables as CSV output by output (so a run
//! that fails or is interrupted keeps everything up to its last good state), a progress bar
//! on a terminal, and Ctrl-C as a request to stop after the current step.

use indicatif::{ProgressBar, ProgressStyle};
use std::ops::ControlFlow;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::OnceLock;
use std::time::{Duration, Instant};
use symbody::generic::{Observer, Recording};
use symbody::scenario::ScenarioError;
use symbody::tables::CsvTables;

use crate::meta::Meta;

/// Set by Ctrl-C while a [`Live`] run listens.
static INTERRUPTED: AtomicBool = AtomicBool::new(false);
/// Whether a [`Live`] run is going (and will stop at its next step when interrupted).
static LISTENING: AtomicBool = AtomicBool::new(false);

/// Makes Ctrl-C stop a [`Live`] run after its current step, keeping its outputs; with no
/// such run going (or at a second Ctrl-C) it ends the process as usual. Once per process.
pub fn catch_interrupts() {
    static ONCE: OnceLock<()> = OnceLock::new();
    ONCE.get_or_init(|| {
        // Without a handler (e.g. where signals cannot be caught) Ctrl-C keeps its default.
        let _ = ctrlc::set_handler(|| {
            if !LISTENING.load(Ordering::SeqCst) || INTERRUPTED.swap(true, Ordering::SeqCst) {
                std::process::exit(130);
            }
        });
    });
}

/// The Ctrl-C flag, for work that is not a [`Live`] run (a study): while `listen(true)`,
/// Ctrl-C sets it instead of ending the process.
pub fn interrupt_flag() -> &'static AtomicBool {
    &INTERRUPTED
}

/// Whether Ctrl-C sets [`interrupt_flag`] (true) or ends the process (false).
pub fn listen(on: bool) {
    LISTENING.store(on, Ordering::SeqCst);
}

fn interrupted() -> bool {
    INTERRUPTED.load(Ordering::Relaxed)
}

/// Fails with a message naming `dir` unless it can be created and written: checked before a
/// run, not after it.
pub fn check_folder(dir: &Path) -> Result<(), String> {
    let probe = dir.join(".symbody-write-check");
    std::fs::create_dir_all(dir)
        .and_then(|()| std::fs::write(&probe, b""))
        .and_then(|()| std::fs::remove_file(&probe))
        .map_err(|e| cannot_write(dir, &e))
}

fn cannot_write(dir: &Path, e: &std::io::Error) -> String {
    format!(
        "cannot write to {}: {e}; choose another folder with --out",
        dir.display()
    )
}

/// The observer of a run whose tables go to `dir`.
pub struct Live {
    dir: PathBuf,
    tables: Option<CsvTables>,
    meta: Meta,
    /// What `meta.json` describes once the run has started: mechanism, formulation, files.
    described: Option<Described>,
    bar: ProgressBar,
    t_end: f64,
    steps: usize,
    /// When the message was last set (`None`: not yet, so the first step sets it).
    drawn: Option<Instant>,
}

type Described = (String, String, Vec<(String, Vec<(String, &'static str)>)>);

/// Between redraws of the progress message.
const REDRAW: Duration = Duration::from_millis(100);

impl Live {
    /// For a run to `t_end` (s) writing into `dir`, described in its `meta.json` by `meta`.
    /// The bar draws only on a terminal (stderr), so piped or captured output stays clean.
    pub fn new(dir: &Path, t_end: f64, meta: Meta) -> Self {
        LISTENING.store(true, Ordering::SeqCst);
        let bar = ProgressBar::new(1000);
        bar.set_style(
            ProgressStyle::with_template("{bar:24} {msg}, {eta} left").expect("a valid template"),
        );
        Live {
            dir: dir.to_path_buf(),
            tables: None,
            meta,
            described: None,
            bar,
            t_end,
            steps: 0,
            drawn: None,
        }
    }

    /// Adds a setting known only once the run is under way (a scene's chosen path) to
    /// `meta.json`, rewriting it if the run has started.
    pub fn note(&mut self, key: &str, value: serde_json::Value) -> Result<(), String> {
        self.meta.settings.insert(key.to_string(), value);
        match &self.described {
            Some((mechanism, formulation, files)) => self
                .meta
                .write(&self.dir, mechanism, formulation, files)
                .map(drop),
            None => Ok(()),
        }
    }

    /// Clears the bar and closes the files; returns them.
    pub fn finish(self) -> Result<Vec<PathBuf>, String> {
        LISTENING.store(false, Ordering::SeqCst);
        self.bar.finish_and_clear();
        match self.tables {
            Some(t) => t.finish().map_err(|e| cannot_write(&self.dir, &e)),
            None => Ok(Vec::new()),
        }
    }
}

impl Observer for Live {
    fn start(&mut self, rec: &mut Recording) -> Result<(), ScenarioError> {
        let tables = CsvTables::create(rec, &self.dir)
            .map_err(|e| ScenarioError::Output(cannot_write(&self.dir, &e)))?;
        self.tables = Some(tables);
        let files: Vec<(String, Vec<(String, &'static str)>)> = symbody::tables::columns(rec)
            .into_iter()
            .map(|(stem, columns)| {
                let units = columns
                    .into_iter()
                    .map(|c| {
                        let unit = symbody::tables::unit(rec, stem, &c);
                        (c, unit)
                    })
                    .collect();
                (format!("{stem}.csv"), units)
            })
            .collect();
        let described = (
            rec.info.name.to_string(),
            rec.info.formulation.name().to_string(),
            files,
        );
        self.meta
            .write(&self.dir, &described.0, &described.1, &described.2)
            .map_err(ScenarioError::Output)?;
        self.described = Some(described);
        Ok(())
    }

    fn output(&mut self, rec: &Recording) -> Result<(), ScenarioError> {
        if let Some(t) = &mut self.tables {
            t.append(rec, rec.t.len() - 1)
                .map_err(|e| ScenarioError::Output(cannot_write(&self.dir, &e)))?;
        }
        Ok(())
    }

    fn progress(&mut self, t: f64, steps: usize) -> ControlFlow<()> {
        self.steps = steps;
        if self.drawn.is_none_or(|d| d.elapsed() >= REDRAW) {
            self.drawn = Some(Instant::now());
            let elapsed = self.bar.elapsed().as_secs_f64().max(1e-9);
            self.bar
                .set_position((1000.0 * t / self.t_end).clamp(0.0, 1000.0) as u64);
            self.bar.set_message(format!(
                "t = {t:.3}/{} s, {} steps, {:.0}/s",
                self.t_end,
                self.steps,
                self.steps as f64 / elapsed
            ));
        }
        if interrupted() {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    }
}
