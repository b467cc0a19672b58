//! The IFToMM multibody benchmark problems A01–A05, each run to its published end time:
//! the published error measure against an independent reference, the published tolerance,
//! pass/fail, our CPU time and the CPU times other codes published.
//!
//! `cargo run --release -p symbody-bench --bin mbs_benchmarks [-- --short] [-- --only A01]` writes
//! `bench-results/mbs_benchmarks[_<only>].{csv,md}` and prints the Markdown; it exits with 1 when a
//! problem misses. `--short` runs the shortened lengths the CI test uses
//! (`mbs_benchmarks_short.*`). `--steps 1e-3,5e-4` runs each problem at each of those steps
//! (its own α, or `--alpha A`) instead of its own step: error against CPU time,
//! `mbs_benchmarks_sweep[_<only>].*`, where a miss is a result, not a failure. `--rtols
//! 1e-4,1e-5` runs each problem with step-size control instead, at each rtol (= atol;
//! `mbs_benchmarks_control[_<only>].*`). `--spatial` runs
//! A01 and A02 N = 40 on their spatial models instead of their planar ones
//! (`mbs_benchmarks_spatial.*`). Not run in CI.

use std::fmt::Write as _;
use std::path::PathBuf;

use symbody_bench::iftomm::{problems, Outcome, Settings, Spec};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .map(|i| args.get(i + 1).cloned().unwrap_or_default())
    };
    let short = args.iter().any(|a| a == "--short");
    // The problems that run a planar model (A01, A02 N = 40) on their spatial one instead.
    let spatial = args.iter().any(|a| a == "--spatial");
    let only = value("--only");
    let list = |flag: &str, what: &str, example: &str| -> Option<Vec<f64>> {
        match value(flag).map(|list| {
            list.split(',')
                .map(|v| v.trim().parse::<f64>().ok().filter(|h| *h > 0.0))
                .collect::<Option<Vec<f64>>>()
        }) {
            None => None,
            Some(Some(values)) if !values.is_empty() => Some(values),
            Some(_) => {
                eprintln!("error: {flag} takes positive {what} separated by commas, e.g. {flag} {example}");
                std::process::exit(2);
            }
        }
    };
    let steps = list("--steps", "step sizes", "1e-3,5e-4");
    let rtols = list("--rtols", "tolerances", "1e-4,1e-5");
    if steps.is_some() && rtols.is_some() {
        eprintln!("error: --steps and --rtols are separate sweeps; give one");
        std::process::exit(2);
    }
    let sweep = steps.is_some() || rtols.is_some();
    let alpha: Option<f64> = match value("--alpha").map(|a| a.parse::<f64>()) {
        None => None,
        Some(Ok(a)) if (-1.0 / 3.0..=0.0).contains(&a) => Some(a),
        Some(_) => {
            eprintln!("error: --alpha takes HHT's α in [-1/3, 0], e.g. --alpha -0.05");
            std::process::exit(2);
        }
    };
    let mut csv = String::from(
        "problem,mechanism,t_end_s,measure,error,tolerance,passed,cpu_s,steps,newton_iterations,step_s,alpha,rtol,rejected_steps,smallest_step_s,largest_step_s\n",
    );
    let mut md = String::from(
        "| problem | t_end | error (measure in the notes) | tolerance | result | CPU (symbody) | steps | published CPU (other codes) |\n|---|---|---|---|---|---|---|---|\n",
    );
    let mut notes = String::new();
    let mut failed = false;
    for p in problems() {
        let spec = &p.spec;
        if only.as_deref().is_some_and(|o| !spec.id.starts_with(o)) {
            continue;
        }
        let t_end = if short { spec.short_t_end } else { spec.t_end };
        let own = Settings {
            alpha: alpha.unwrap_or(p.settings.alpha),
            planar: p.settings.planar && !spatial,
            ..p.settings
        };
        let runs: Vec<Settings> = match (&steps, &rtols) {
            (Some(steps), _) => steps
                .iter()
                .map(|&step| Settings {
                    step,
                    tolerances: None,
                    ..own
                })
                .collect(),
            (_, Some(rtols)) => rtols
                .iter()
                .map(|&r| Settings {
                    tolerances: Some((r, r)),
                    ..own
                })
                .collect(),
            _ => vec![own],
        };
        for settings in runs {
            eprintln!(
                "{}: {} to t = {t_end} s, h = {:e} …",
                spec.id, spec.title, settings.step
            );
            match (p.run)(t_end, settings) {
                Ok(o) => {
                    failed |= !o.passed(spec);
                    row(&mut csv, &mut md, spec, &o, &settings);
                }
                Err(e) => {
                    failed = true;
                    let _ = writeln!(
                        md,
                        "| {} | {t_end} s | not run | {:.0e} | **failed**: {e} | | ({}) | {} |",
                        spec.id,
                        spec.tolerance,
                        how(&settings, None),
                        published(spec)
                    );
                    let _ = writeln!(
                        csv,
                        "{},{},{t_end},,,{},false,,,,{:e},{},{}",
                        spec.id,
                        spec.mechanism,
                        spec.tolerance,
                        settings.step,
                        settings.alpha,
                        rtol(&settings)
                    );
                }
            }
        }
        let _ = writeln!(
            notes,
            "- **{}** {}: {}; reference: {}. Source: {}.{}",
            spec.id,
            spec.title,
            spec.measure,
            spec.reference,
            spec.source,
            if spec.caveat.is_empty() {
                String::new()
            } else {
                format!(" Not as published: {}.", spec.caveat)
            }
        );
    }
    md.push('\n');
    md.push_str(&notes);
    let dir = PathBuf::from("bench-results");
    // A run of one problem (`--only A05`) gets its own files, so it neither overwrites the
    // table of all five nor another problem's sweep.
    let only_tag: String = match &only {
        Some(o) => format!("_{}", o.replace(|c: char| !c.is_alphanumeric(), "")),
        None => String::new(),
    };
    let suffix = format!(
        "{}{}{}{}{only_tag}",
        if short { "_short" } else { "" },
        if spatial { "_spatial" } else { "" },
        if steps.is_some() { "_sweep" } else { "" },
        if rtols.is_some() { "_control" } else { "" }
    );
    let written = std::fs::create_dir_all(&dir)
        .and_then(|_| std::fs::write(dir.join(format!("mbs_benchmarks{suffix}.csv")), &csv))
        .and_then(|_| std::fs::write(dir.join(format!("mbs_benchmarks{suffix}.md")), &md));
    if let Err(e) = written {
        eprintln!("error: cannot write bench-results/: {e}");
        std::process::exit(2);
    }
    print!("{md}");
    if failed && !sweep && alpha.is_none() {
        std::process::exit(1);
    }
}

fn row(csv: &mut String, md: &mut String, spec: &Spec, o: &Outcome, settings: &Settings) {
    let passed = o.passed(spec);
    let _ = writeln!(
        csv,
        "{},{},{},\"{}\",{:e},{:e},{},{:.6},{},{},{:e},{},{},{},{:e},{:e}",
        spec.id,
        spec.mechanism,
        o.t_end,
        spec.measure,
        o.error,
        spec.tolerance,
        passed,
        o.cpu.as_secs_f64(),
        o.stats.steps,
        o.stats.newton_iterations,
        o.step,
        o.alpha,
        rtol(settings),
        o.stats.rejected_steps,
        o.stats.smallest_step,
        o.stats.largest_step
    );
    let _ = writeln!(
        md,
        "| {} | {} s | {:.2e} | {:.0e} | {} | {:.3} s | {} ({}) | {} |",
        spec.id,
        o.t_end,
        o.error,
        spec.tolerance,
        if passed { "pass" } else { "**fail**" },
        o.cpu.as_secs_f64(),
        o.stats.steps,
        how(settings, Some(o)),
        published(spec)
    );
}

/// The csv's rtol column: empty for a fixed step.
fn rtol(settings: &Settings) -> String {
    settings
        .tolerances
        .map(|(r, _)| format!("{r:e}"))
        .unwrap_or_default()
}

/// How the steps were chosen: the fixed step, or the tolerance and the range of steps taken
/// (with the rejected attempts).
fn how(settings: &Settings, o: Option<&Outcome>) -> String {
    match (settings.tolerances, o) {
        (None, _) => format!("h = {:e}, α = {}", settings.step, settings.alpha),
        (Some((r, _)), None) => format!("rtol = atol = {r:e}, α = {}", settings.alpha),
        (Some((r, _)), Some(o)) => format!(
            "rtol = atol = {r:e}, h {:.2e}–{:.2e}, {} rejected, α = {}",
            o.stats.smallest_step, o.stats.largest_step, o.stats.rejected_steps, settings.alpha
        ),
    }
}

fn published(spec: &Spec) -> String {
    spec.published
        .iter()
        .map(|p| format!("{}: {} s ({})", p.code, p.cpu_seconds, p.machine))
        .collect::<Vec<_>>()
        .join("; ")
}
