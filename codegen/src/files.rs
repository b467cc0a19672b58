//! The generated files of a workspace: which mechanism files exist, and what the Rust
//! generated from them must contain. Shared by `cargo xtask generate` and the freshness test.

use crate::Errors;
use std::path::{Path, PathBuf};

/// Folder of mechanism files, relative to the workspace root.
pub const MECHANISMS_DIR: &str = "mechanisms";
/// Folder of generated modules, relative to the workspace root.
pub const GENERATED_DIR: &str = "mechanisms/src/generated";

/// Why the expected files could not be produced.
#[derive(Debug)]
pub enum FilesError {
    Io(PathBuf, std::io::Error),
    Invalid(Errors),
    UnknownMechanism { name: String, known: Vec<String> },
}

impl std::fmt::Display for FilesError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FilesError::Io(p, e) => write!(f, "cannot read {}: {e}", p.display()),
            FilesError::Invalid(e) => write!(f, "{e}"),
            FilesError::UnknownMechanism { name, known } => write!(
                f,
                "no mechanism file `{MECHANISMS_DIR}/{name}.toml`; known mechanisms: {}",
                known.join(", ")
            ),
        }
    }
}

impl std::error::Error for FilesError {}

/// Names of all mechanism files (`mechanisms/<name>.toml` except `Cargo.toml`), sorted.
pub fn mechanism_names(root: &Path) -> Result<Vec<String>, FilesError> {
    let dir = root.join(MECHANISMS_DIR);
    let entries = std::fs::read_dir(&dir).map_err(|e| FilesError::Io(dir.clone(), e))?;
    let mut names: Vec<String> = entries
        .filter_map(|e| e.ok())
        .filter_map(|e| {
            let p = e.path();
            // The crate's own manifest lives in the same folder.
            (p.extension()? == "toml" && p.file_name()? != "Cargo.toml")
                .then(|| p.file_stem()?.to_str().map(str::to_string))
                .flatten()
        })
        .collect();
    names.sort();
    Ok(names)
}

/// The generated module of mechanism `name`: (path relative to root, contents).
pub fn generated_module(root: &Path, name: &str) -> Result<(PathBuf, String), FilesError> {
    let rel = format!("{MECHANISMS_DIR}/{name}.toml");
    let path = root.join(&rel);
    if !path.exists() {
        return Err(FilesError::UnknownMechanism {
            name: name.to_string(),
            known: mechanism_names(root)?,
        });
    }
    let text = std::fs::read_to_string(&path).map_err(|e| FilesError::Io(path.clone(), e))?;
    let code = crate::generate(&rel, &text).map_err(FilesError::Invalid)?;
    Ok((
        PathBuf::from(GENERATED_DIR).join(format!("{name}.rs")),
        code,
    ))
}

/// The `mod.rs` listing every generated module.
pub fn generated_index(names: &[String]) -> (PathBuf, String) {
    let mut s = String::from(
        "//! Generated mechanisms, one module each. Regenerate with `cargo xtask generate --all`.\n\n",
    );
    for n in names {
        // prettyplease, not rustfmt, owns the layout of generated code.
        s.push_str(&format!("#[rustfmt::skip]\npub mod {n};\n"));
    }
    (PathBuf::from(GENERATED_DIR).join("mod.rs"), s)
}

/// Every generated file of the workspace with its expected contents.
pub fn all_expected(root: &Path) -> Result<Vec<(PathBuf, String)>, FilesError> {
    let names = mechanism_names(root)?;
    let mut out = Vec::new();
    for n in &names {
        out.push(generated_module(root, n)?);
    }
    out.push(generated_index(&names));
    Ok(out)
}
