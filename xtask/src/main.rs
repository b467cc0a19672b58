//! Developer tasks: `cargo xtask generate [<name>… | --all] [--check]` regenerates (or checks)
//! the committed Rust of the mechanisms under `mechanisms/` (a crate each, and the registries),
//! and prints what the generator found out about each (sizes, rank, degrees of freedom,
//! redundant rows, warnings).

use clap::{Parser, Subcommand};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;
use symbody_codegen::files;

/// `cargo xtask`: developer tasks.
#[derive(Parser)]
#[command(
    name = "cargo xtask",
    bin_name = "cargo xtask",
    about = "Developer tasks of the symbody workspace"
)]
struct Cli {
    #[command(subcommand)]
    command: Task,
}

#[derive(Subcommand)]
enum Task {
    /// Regenerate the crate mechanisms/generated/<name>/ from mechanisms/<name>.toml (or
    /// mechanisms/benchmarks/<name>.toml) for each name, and the registries; every mechanism
    /// when no name is given.
    Generate {
        /// Mechanisms to regenerate.
        names: Vec<String>,
        /// Regenerate every mechanism (the default when no name is given).
        #[arg(long)]
        all: bool,
        /// Write nothing; fail if any generated file differs from what generation produces.
        #[arg(long)]
        check: bool,
    },
}

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("xtask lives one level below the workspace root")
        .to_path_buf()
}

fn main() -> ExitCode {
    let Task::Generate { names, all, check } = Cli::parse().command;
    match generate(names, all, check) {
        Ok(()) => ExitCode::SUCCESS,
        Err(msg) => {
            eprintln!("{msg}");
            ExitCode::FAILURE
        }
    }
}

fn generate(mut names: Vec<String>, all: bool, check: bool) -> Result<(), String> {
    let root = workspace_root();
    let every = files::mechanism_names(&root).map_err(|e| e.to_string())?;
    if all || names.is_empty() {
        names = every.clone();
    }
    let start = Instant::now();
    let plan = files::plan(&root, &names).map_err(|e| e.to_string())?;
    for (_, g) in &plan.reports {
        eprintln!("{}", g.report);
    }
    let failures: Vec<String> = plan
        .failures
        .iter()
        .map(|(n, e)| format!("{n}: {e}"))
        .collect();
    let elapsed = start.elapsed();

    // A failed generation writes nothing at all: the registries would still list its old
    // crate, but a half-written run is harder to reason about than none.
    let write = !check && failures.is_empty();
    let mut stale = Vec::new();
    for (rel, contents) in &plan.outputs {
        let path = root.join(rel);
        let current = std::fs::read_to_string(&path).ok();
        if current.as_deref() == Some(contents.as_str()) {
            continue;
        }
        if !write {
            stale.push(rel.display().to_string());
        } else {
            if let Some(dir) = path.parent() {
                std::fs::create_dir_all(dir)
                    .map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
            }
            std::fs::write(&path, contents)
                .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
            eprintln!("wrote {}", rel.display());
        }
    }
    for dir in &plan.orphans {
        if !write {
            stale.push(format!("{} (its mechanism file is gone)", dir.display()));
        } else {
            std::fs::remove_dir_all(root.join(dir))
                .map_err(|e| format!("cannot remove {}: {e}", dir.display()))?;
            eprintln!("removed {} (its mechanism file is gone)", dir.display());
        }
    }
    if !failures.is_empty() {
        return Err(format!(
            "{}\n\n{} mechanism file(s) failed; nothing was written, every generated file is as it was",
            failures.join("\n\n"),
            failures.len()
        ));
    }
    if !stale.is_empty() {
        let cmd = if names.len() == every.len() {
            "cargo xtask generate --all".to_string()
        } else {
            format!("cargo xtask generate {}", names.join(" "))
        };
        return Err(format!(
            "generated files are stale:\n  {}\nrun `{cmd}` and commit the result",
            stale.join("\n  ")
        ));
    }
    eprintln!(
        "{} {} mechanism(s) in {:.0} ms",
        if check { "checked" } else { "generated" },
        names.len(),
        elapsed.as_secs_f64() * 1e3
    );
    Ok(())
}
