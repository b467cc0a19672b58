//! Keeps `capi/include/symbody.h` equal to what cbindgen generates from `capi/src`: exits with
//! an error naming the command that regenerates it when they differ; with `--write`, writes it.
//!
//! `cargo run --release --manifest-path capi/header/Cargo.toml [-- --write]` (.ci/run runs the
//! check). A separate package so that neither the tool nor `cargo test` compiles cbindgen.

use std::path::Path;
use std::process::ExitCode;

fn main() -> ExitCode {
    let write = match std::env::args().nth(1).as_deref() {
        None => false,
        Some("--write") => true,
        Some(other) => {
            eprintln!("unknown argument `{other}`; usage: [--write]");
            return ExitCode::FAILURE;
        }
    };
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("capi/header lives in capi/");
    let config = match cbindgen::Config::from_file(dir.join("cbindgen.toml")) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("capi/cbindgen.toml: {e}");
            return ExitCode::FAILURE;
        }
    };
    let mut generated = Vec::new();
    match cbindgen::Builder::new()
        .with_config(config)
        .with_src(dir.join("src/lib.rs"))
        .generate()
    {
        Ok(bindings) => bindings.write(&mut generated),
        Err(e) => {
            eprintln!("cbindgen cannot read capi/src: {e}");
            return ExitCode::FAILURE;
        }
    }
    let path = dir.join("include/symbody.h");
    if write {
        if let Err(e) = std::fs::write(&path, &generated) {
            eprintln!("cannot write {}: {e}", path.display());
            return ExitCode::FAILURE;
        }
        eprintln!("wrote capi/include/symbody.h");
        return ExitCode::SUCCESS;
    }
    let committed = std::fs::read(&path).unwrap_or_default();
    if committed != generated {
        eprintln!(
            "capi/include/symbody.h is not what cbindgen generates from capi/src; regenerate it \
             with\n    cargo run --release --manifest-path capi/header/Cargo.toml -- --write\nand commit it"
        );
        return ExitCode::FAILURE;
    }
    eprintln!("capi/include/symbody.h is current");
    ExitCode::SUCCESS
}
