//! Developer tasks: `cargo xtask generate [<name>… | --all] [--check]` regenerates (or checks)
//! the committed Rust of the mechanisms under `mechanisms/`, and prints what the generator
//! found out about each (sizes, rank, degrees of freedom, redundant rows, warnings).

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;
use symbody_codegen::files;

const USAGE: &str = "usage: cargo xtask generate [<name>... | --all] [--check]

  generate <name>    regenerate mechanisms/src/generated/<name>.rs from mechanisms/<name>.toml
  generate --all     regenerate every mechanism (the default when no name is given)
  generate --check   fail if any generated file differs from what generation produces";

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("xtask lives one level below the workspace root")
        .to_path_buf()
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("generate") => match generate(&args[1..]) {
            Ok(()) => ExitCode::SUCCESS,
            Err(msg) => {
                eprintln!("{msg}");
                ExitCode::FAILURE
            }
        },
        _ => {
            eprintln!("{USAGE}");
            ExitCode::FAILURE
        }
    }
}

fn generate(args: &[String]) -> Result<(), String> {
    let root = workspace_root();
    let check = args.iter().any(|a| a == "--check");
    let all = args.iter().any(|a| a == "--all");
    if let Some(bad) = args
        .iter()
        .find(|a| a.starts_with("--") && *a != "--check" && *a != "--all")
    {
        return Err(format!("unknown option `{bad}`\n\n{USAGE}"));
    }
    let mut names: Vec<String> = args
        .iter()
        .filter(|a| !a.starts_with("--"))
        .cloned()
        .collect();
    let every = files::mechanism_names(&root).map_err(|e| e.to_string())?;
    if all || names.is_empty() {
        names = every.clone();
    }
    let start = Instant::now();
    let mut expected = Vec::new();
    let mut failures = Vec::new();
    for n in &names {
        match files::generated_module(&root, n) {
            Ok((path, g)) => {
                eprintln!("{}", g.report);
                expected.push((n.clone(), path, g.code, g.formulations));
            }
            Err(e) => failures.push(format!("{n}: {e}")),
        }
    }
    // The registry lists what generates now, plus mechanisms not regenerated in this run
    // whose module already exists: a broken file never enters the module index.
    let regenerated: Vec<_> = expected
        .iter()
        .map(|(n, _, _, forms)| (n.clone(), forms.clone()))
        .collect();
    let index = files::index_entries(&root, &names, &regenerated).map_err(|e| e.to_string())?;
    for n in &index.left_out {
        eprintln!("note: `{n}` is not valid and stays out of the module index");
    }
    let (index_path, index_code) = files::generated_index(&index.entries);
    let elapsed = start.elapsed();

    let mut outputs: Vec<(PathBuf, String)> =
        expected.into_iter().map(|(_, p, c, _)| (p, c)).collect();
    outputs.push((index_path, index_code));
    let mut stale = Vec::new();
    for (rel, contents) in &outputs {
        let path = root.join(rel);
        let current = std::fs::read_to_string(&path).ok();
        if current.as_deref() == Some(contents.as_str()) {
            continue;
        }
        if check {
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
    if !failures.is_empty() {
        return Err(format!(
            "{}\n\n{} mechanism file(s) failed; nothing was written for them",
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
