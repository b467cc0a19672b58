//! The IFToMM multibody benchmark problems A01–A05, each run to its published end time:
//! the published error measure against an independent reference, the published tolerance,
//! pass/fail, our CPU time and the CPU times other codes published.
//!
//! `cargo run --release --bin mbs_benchmarks [-- --short] [-- --only A01]` writes
//! `bench-results/mbs_benchmarks.{csv,md}` and prints the Markdown. `--short` runs the
//! shortened lengths the CI test uses. Not run in CI.

use std::fmt::Write as _;
use std::path::PathBuf;

use symbody::iftomm::{problems, Outcome, Spec};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let short = args.iter().any(|a| a == "--short");
    let only = args
        .iter()
        .position(|a| a == "--only")
        .map(|i| args.get(i + 1).cloned().unwrap_or_default());
    let mut csv = String::from(
        "problem,mechanism,t_end_s,measure,error,tolerance,passed,cpu_s,steps,newton_iterations,step_s,alpha\n",
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
        eprintln!("{}: {} to t = {t_end} s …", spec.id, spec.title);
        match (p.run)(t_end) {
            Ok(o) => {
                failed |= !o.passed(spec);
                row(&mut csv, &mut md, spec, &o);
            }
            Err(e) => {
                failed = true;
                let _ = writeln!(
                    md,
                    "| {} | {t_end} s | not run | {:.0e} | **failed**: {e} | | | {} |",
                    spec.id,
                    spec.tolerance,
                    published(spec)
                );
                let _ = writeln!(
                    csv,
                    "{},{},{t_end},,,{},false,,,,,",
                    spec.id, spec.mechanism, spec.tolerance
                );
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
    let suffix = if short { "_short" } else { "" };
    let written = std::fs::create_dir_all(&dir)
        .and_then(|_| std::fs::write(dir.join(format!("mbs_benchmarks{suffix}.csv")), &csv))
        .and_then(|_| std::fs::write(dir.join(format!("mbs_benchmarks{suffix}.md")), &md));
    if let Err(e) = written {
        eprintln!("error: cannot write bench-results/: {e}");
        std::process::exit(2);
    }
    print!("{md}");
    if failed {
        std::process::exit(1);
    }
}

fn row(csv: &mut String, md: &mut String, spec: &Spec, o: &Outcome) {
    let passed = o.passed(spec);
    let _ = writeln!(
        csv,
        "{},{},{},\"{}\",{:e},{:e},{},{:.6},{},{},{:e},{}",
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
        o.alpha
    );
    let _ = writeln!(
        md,
        "| {} | {} s | {:.2e} | {:.0e} | {} | {:.3} s | {} (h = {:e}, α = {}) | {} |",
        spec.id,
        o.t_end,
        o.error,
        spec.tolerance,
        if passed { "pass" } else { "**fail**" },
        o.cpu.as_secs_f64(),
        o.stats.steps,
        o.step,
        o.alpha,
        published(spec)
    );
}

fn published(spec: &Spec) -> String {
    spec.published
        .iter()
        .map(|p| format!("{}: {} s ({})", p.code, p.cpu_seconds, p.machine))
        .collect::<Vec<_>>()
        .join("; ")
}
