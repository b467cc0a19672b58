//! Developer tasks: `cargo xtask generate [<name>… | --all] [--check]` regenerates (or checks)
//! the committed Rust of the mechanisms under `mechanisms/`.

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
    for n in &names {
        expected.push(files::generated_module(&root, n).map_err(|e| e.to_string())?);
    }
    expected.push(files::generated_index(&every));
    let elapsed = start.elapsed();

    let mut stale = Vec::new();
    for (rel, contents) in &expected {
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
