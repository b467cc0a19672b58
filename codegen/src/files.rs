//! The generated files of a workspace: which mechanism files exist, and what the Rust
//! generated from them must contain. Shared by `cargo xtask generate` and the freshness test.

use crate::model::Formulation;
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

/// Path of mechanism `name`'s generated module, relative to the root.
pub fn module_path(name: &str) -> PathBuf {
    PathBuf::from(GENERATED_DIR).join(format!("{name}.rs"))
}

/// The generated module of mechanism `name`: (path relative to root, contents and report).
pub fn generated_module(
    root: &Path,
    name: &str,
) -> Result<(PathBuf, crate::Generated), FilesError> {
    let rel = format!("{MECHANISMS_DIR}/{name}.toml");
    let path = root.join(&rel);
    if !path.exists() {
        return Err(FilesError::UnknownMechanism {
            name: name.to_string(),
            known: mechanism_names(root)?,
        });
    }
    let text = std::fs::read_to_string(&path).map_err(|e| FilesError::Io(path.clone(), e))?;
    let generated = crate::generate(&rel, &text).map_err(FilesError::Invalid)?;
    Ok((module_path(name), generated))
}

/// The `mod.rs` listing every generated module and the registry of mechanisms
/// (docs/design.md, decision 19): name, formulations and a constructor for each.
pub fn generated_index(mechanisms: &[(String, Vec<Formulation>)]) -> (PathBuf, String) {
    let mut s = String::from(
        "//! Generated mechanisms, one module each, and their registry. Regenerate with\n//! `cargo xtask generate --all`.\n\n",
    );
    for (n, _) in mechanisms {
        // prettyplease, not rustfmt, owns the layout of generated code.
        s.push_str(&format!("#[rustfmt::skip]\npub mod {n};\n"));
    }
    s.push_str("\nuse symbody_runtime::{Formulation, Mechanism};\n\n");
    s.push_str("/// Every generated mechanism: name, formulations (the first is the default), the\n/// mechanism in each, and the simulation end time its file suggests.\n");
    s.push_str("#[rustfmt::skip]\npub static REGISTRY: &[crate::Entry] = &[\n");
    for (n, forms) in mechanisms {
        s.push_str(&format!("    crate::Entry {{\n        name: \"{n}\",\n        t_end: {n}::T_END,\n        formulations: &[\n"));
        for f in forms {
            let (variant, ty) = match f {
                Formulation::Exact => ("Exact", "Exact"),
                Formulation::Paper => ("Paper", "Paper"),
            };
            s.push_str(&format!(
                "            (Formulation::{variant}, &{n}::{ty} as &(dyn Mechanism + Sync)),\n"
            ));
        }
        s.push_str("        ],\n    },\n");
    }
    s.push_str("];\n");
    (PathBuf::from(GENERATED_DIR).join("mod.rs"), s)
}

/// What the module index lists after a generation run, and what it leaves out.
#[derive(Debug, Clone, PartialEq)]
pub struct IndexEntries {
    /// Mechanisms in the index, in name order, with their formulations.
    pub entries: Vec<(String, Vec<Formulation>)>,
    /// Mechanisms not attempted in this run whose module exists but whose file no longer
    /// generates: they stay out of the index.
    pub left_out: Vec<String>,
}

/// The mechanisms the module index lists after `cargo xtask generate` attempted the names
/// in `attempted` and succeeded for those in `regenerated` (name, formulations): each
/// regenerated mechanism, and each other mechanism file whose module already exists and
/// that still generates. A mechanism attempted in this run that failed, or a file that no
/// longer generates, stays out: a broken file never enters the index.
pub fn index_entries(
    root: &Path,
    attempted: &[String],
    regenerated: &[(String, Vec<Formulation>)],
) -> Result<IndexEntries, FilesError> {
    let mut entries = Vec::new();
    let mut left_out = Vec::new();
    for n in &mechanism_names(root)? {
        if let Some((_, forms)) = regenerated.iter().find(|(r, _)| r == n) {
            entries.push((n.clone(), forms.clone()));
        } else if !attempted.contains(n) && root.join(module_path(n)).exists() {
            // Reading the file is enough to list it (generating it again would cost the full
            // derivation of every mechanism each time one is regenerated).
            let rel = format!("{MECHANISMS_DIR}/{n}.toml");
            let path = root.join(&rel);
            let text = std::fs::read_to_string(&path).map_err(|e| FilesError::Io(path, e))?;
            match crate::model::load(&rel, &text) {
                Ok(m) => entries.push((n.clone(), m.formulations)),
                Err(_) => left_out.push(n.clone()),
            }
        }
    }
    Ok(IndexEntries { entries, left_out })
}

/// Every generated file of the workspace with its expected contents.
pub fn all_expected(root: &Path) -> Result<Vec<(PathBuf, String)>, FilesError> {
    let names = mechanism_names(root)?;
    let mut out = Vec::new();
    let mut index = Vec::new();
    for n in &names {
        let (path, g) = generated_module(root, n)?;
        index.push((n.clone(), g.formulations.clone()));
        out.push((path, g.code));
    }
    out.push(generated_index(&index));
    Ok(out)
}
