//! The generated files of a workspace: which mechanism files exist, the crate generated from
//! each, and the registry crates that link them. Shared by `cargo xtask generate` and the
//! freshness test.
//!
//! Every mechanism is its own crate (`mechanisms/generated/<name>/`), so changing one file
//! recompiles one crate. Its file says which registry lists it: `mechanisms/<name>.toml` is
//! shipped (`symbody-mechanisms`, what the command-line tool, the C library and the Python
//! package link); `mechanisms/benchmarks/<name>.toml` is a benchmark problem, compiled only
//! where the benchmarks need it (`symbody-benchmark-mechanisms`, which lists both groups).

use crate::Errors;
use std::path::{Path, PathBuf};

/// Folder of generated crates, one per mechanism, relative to the workspace root.
pub const GENERATED_DIR: &str = "mechanisms/generated";

/// Which registry lists a mechanism.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Group {
    /// `mechanisms/<name>.toml`: in every program's registry.
    Shipped,
    /// `mechanisms/benchmarks/<name>.toml`: only in the benchmarks' registry.
    Benchmarks,
}

impl Group {
    pub const ALL: [Group; 2] = [Group::Shipped, Group::Benchmarks];

    /// Folder of this group's mechanism files (and of its registry crate's manifest).
    pub fn dir(self) -> &'static str {
        match self {
            Group::Shipped => "mechanisms",
            Group::Benchmarks => "mechanisms/benchmarks",
        }
    }

    fn package(self) -> &'static str {
        match self {
            Group::Shipped => "symbody-mechanisms",
            Group::Benchmarks => "symbody-benchmark-mechanisms",
        }
    }
}

/// One mechanism file of the workspace.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MechanismFile {
    pub name: String,
    pub group: Group,
}

impl MechanismFile {
    /// Path of the file, relative to the root.
    pub fn path(&self) -> String {
        format!("{}/{}.toml", self.group.dir(), self.name)
    }
}

/// Why the expected files could not be produced.
#[derive(Debug)]
pub enum FilesError {
    Io(PathBuf, std::io::Error),
    Invalid(Errors),
    UnknownMechanism {
        name: String,
        known: Vec<String>,
    },
    /// The same name in both groups: one crate name, two files.
    Duplicate(String),
    /// A file name that is not a Rust identifier cannot name a crate or a module.
    BadName(String),
}

impl std::fmt::Display for FilesError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FilesError::Io(p, e) => write!(f, "cannot read {}: {e}", p.display()),
            FilesError::Invalid(e) => write!(f, "{e}"),
            FilesError::UnknownMechanism { name, known } => write!(
                f,
                "no mechanism file `mechanisms/{name}.toml` or `mechanisms/benchmarks/{name}.toml`; known mechanisms: {}",
                known.join(", ")
            ),
            FilesError::Duplicate(n) => write!(
                f,
                "`{n}` is both mechanisms/{n}.toml and mechanisms/benchmarks/{n}.toml: rename one"
            ),
            FilesError::BadName(n) => write!(
                f,
                "mechanism file `{n}.toml`: the name must be a lowercase Rust identifier \
                 (letters, digits, `_`; not starting with a digit), since it names a crate"
            ),
        }
    }
}

impl std::error::Error for FilesError {}

fn valid_name(n: &str) -> bool {
    let mut chars = n.chars();
    chars
        .next()
        .is_some_and(|c| c.is_ascii_lowercase() || c == '_')
        && chars.all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
}

/// The `.toml` files of `dir` except `Cargo.toml`, by stem.
fn stems(dir: &Path) -> Result<Vec<String>, FilesError> {
    let entries = std::fs::read_dir(dir).map_err(|e| FilesError::Io(dir.to_path_buf(), e))?;
    Ok(entries
        .filter_map(|e| e.ok())
        .filter_map(|e| {
            let p = e.path();
            // The registry crate's own manifest lives in the same folder.
            (p.is_file() && p.extension()? == "toml" && p.file_name()? != "Cargo.toml")
                .then(|| p.file_stem()?.to_str().map(str::to_string))
                .flatten()
        })
        .collect())
}

/// Every mechanism file of both groups, sorted by name.
pub fn mechanism_files(root: &Path) -> Result<Vec<MechanismFile>, FilesError> {
    let mut files = Vec::new();
    for group in Group::ALL {
        let dir = root.join(group.dir());
        if group == Group::Benchmarks && !dir.exists() {
            continue;
        }
        for name in stems(&dir)? {
            if !valid_name(&name) {
                return Err(FilesError::BadName(name));
            }
            files.push(MechanismFile { name, group });
        }
    }
    files.sort_by(|a, b| a.name.cmp(&b.name));
    if let Some(w) = files.windows(2).find(|w| w[0].name == w[1].name) {
        return Err(FilesError::Duplicate(w[0].name.clone()));
    }
    Ok(files)
}

/// Names of all mechanism files, sorted.
pub fn mechanism_names(root: &Path) -> Result<Vec<String>, FilesError> {
    Ok(mechanism_files(root)?.into_iter().map(|f| f.name).collect())
}

/// The file of mechanism `name`.
pub fn find(root: &Path, name: &str) -> Result<MechanismFile, FilesError> {
    let files = mechanism_files(root)?;
    files
        .iter()
        .find(|f| f.name == name)
        .cloned()
        .ok_or_else(|| FilesError::UnknownMechanism {
            name: name.to_string(),
            known: files.into_iter().map(|f| f.name).collect(),
        })
}

/// Folder of mechanism `name`'s crate, relative to the root.
pub fn crate_dir(name: &str) -> PathBuf {
    PathBuf::from(GENERATED_DIR).join(name)
}

/// Path of mechanism `name`'s generated equations, relative to the root.
pub fn module_path(name: &str) -> PathBuf {
    crate_dir(name).join("equations.rs")
}

/// The crate name of mechanism `name`'s generated crate (as written in Rust code).
fn crate_ident(name: &str) -> String {
    format!("symbody_mechanism_{name}")
}

fn package_name(name: &str) -> String {
    format!("symbody-mechanism-{name}")
}

const GENERATED_NOTE: &str = "Generated by `cargo xtask generate`; do not edit.";

/// A generated crate's manifest: `about` as comments, the package (`lib_path`: its root when
/// not `src/lib.rs`) with no test harness (generated code has no tests of its own; the
/// workspace's tests check it), and its dependencies besides the runtime (`deps`, TOML lines).
fn manifest(about: &str, package: &str, lib_path: Option<&str>, deps: &str) -> String {
    let about: String = about.lines().map(|l| format!("# {l}\n")).collect();
    let path = lib_path.map_or(String::new(), |p| format!("path = \"{p}\"\n"));
    format!(
        "# {GENERATED_NOTE}\n{about}[package]\nname = \"{package}\"\nversion = \"0.1.0\"\nedition = \"2021\"\npublish = false\n\n[lib]\n{path}test = false\ndoctest = false\n\n[dependencies]\nsymbody-runtime.workspace = true\n{deps}"
    )
}

/// The crate of one mechanism: its manifest, a root that re-exports the generated module,
/// and the module (files relative to the root), with what the generator found out.
pub fn generated_crate(
    root: &Path,
    file: &MechanismFile,
) -> Result<(Vec<(PathBuf, String)>, crate::Generated), FilesError> {
    let rel = file.path();
    let path = root.join(&rel);
    let text = std::fs::read_to_string(&path).map_err(|e| FilesError::Io(path.clone(), e))?;
    let generated = crate::generate(&rel, &text).map_err(FilesError::Invalid)?;
    let name = &file.name;
    let dir = crate_dir(name);
    let manifest = manifest(
        &format!("From {rel}: the mechanism's equations as their own crate, so that changing\nthe file recompiles only this crate and the programs that link it."),
        &package_name(name),
        Some("lib.rs"),
        "",
    );
    let lib = format!(
        "//! The generated equations of `{name}`, from `{rel}`; their documentation\n//! (coordinates, rows, sizes) is in `equations.rs`. {GENERATED_NOTE}\n\n// prettyplease, not rustfmt, owns the layout of generated code.\n#[rustfmt::skip]\nmod equations;\npub use equations::*;\n"
    );
    let files = vec![
        (dir.join("Cargo.toml"), manifest),
        (dir.join("lib.rs"), lib),
        (module_path(name), generated.code.clone()),
    ];
    Ok((files, generated))
}

/// The registry crates' generated files: for each group its manifest (a dependency on each
/// listed crate) and its list of entries. `listed` are the mechanisms whose crate exists;
/// the benchmarks' registry lists both groups.
pub fn registries(listed: &[MechanismFile]) -> Vec<(PathBuf, String)> {
    let deps = |files: &[&MechanismFile], path_to_generated: &str| -> String {
        files
            .iter()
            .map(|f| {
                format!(
                    "{} = {{ path = \"{path_to_generated}/{}\" }}\n",
                    package_name(&f.name),
                    f.name
                )
            })
            .collect()
    };
    let uses = |files: &[&MechanismFile]| -> String {
        files
            .iter()
            .map(|f| format!("pub use {} as {};\n", crate_ident(&f.name), f.name))
            .collect()
    };
    let list = |files: &[&MechanismFile]| -> String {
        files
            .iter()
            .map(|f| format!("    &{}::ENTRY,\n", f.name))
            .collect()
    };
    let shipped: Vec<&MechanismFile> = listed
        .iter()
        .filter(|f| f.group == Group::Shipped)
        .collect();
    let all: Vec<&MechanismFile> = listed.iter().collect();
    let bench_only: Vec<&MechanismFile> = listed
        .iter()
        .filter(|f| f.group == Group::Benchmarks)
        .collect();

    let shipped_manifest = manifest(
        "The shipped mechanisms (files in this folder) and their registry.",
        Group::Shipped.package(),
        None,
        &deps(&shipped, "generated"),
    );
    let shipped_list = format!(
        "//! {GENERATED_NOTE}\n\n{}\n/// Every shipped mechanism, in name order.\npub static REGISTRY: symbody_runtime::Registry = symbody_runtime::Registry(&[\n{}]);\n",
        uses(&shipped),
        list(&shipped)
    );
    let bench_manifest = manifest(
        "The benchmark problems' mechanisms (files in this folder) and a registry of them\nwith the shipped ones.",
        Group::Benchmarks.package(),
        Some("lib.rs"),
        &format!("symbody-mechanisms.workspace = true\n{}", deps(&bench_only, "../generated")),
    );
    let shipped_uses: String = shipped
        .iter()
        .map(|f| format!("pub use symbody_mechanisms::{};\n", f.name))
        .collect();
    let bench_list = format!(
        "//! {GENERATED_NOTE}\n\n{}{}\n/// The shipped mechanisms and the benchmark problems, in name order.\npub static REGISTRY: symbody_runtime::Registry = symbody_runtime::Registry(&[\n{}]);\n",
        uses(&bench_only),
        shipped_uses,
        list(&all)
    );
    let dir = |g: Group| PathBuf::from(g.dir());
    vec![
        (dir(Group::Shipped).join("Cargo.toml"), shipped_manifest),
        (dir(Group::Shipped).join("src/registry.rs"), shipped_list),
        (dir(Group::Benchmarks).join("Cargo.toml"), bench_manifest),
        (dir(Group::Benchmarks).join("registry.rs"), bench_list),
    ]
}

/// What one `cargo xtask generate` run writes, and what it could not generate.
#[derive(Debug, Default)]
pub struct Plan {
    /// Every file to write (relative to the root) with its contents.
    pub outputs: Vec<(PathBuf, String)>,
    /// Mechanisms whose file did not generate: nothing of theirs is written, and their
    /// previous crate (if any) stays as it was, listed in the registry.
    pub failures: Vec<(String, FilesError)>,
    /// Generated crates whose mechanism file no longer exists (folders relative to the root).
    pub orphans: Vec<PathBuf>,
    /// What the generator found out about each mechanism generated.
    pub reports: Vec<(String, crate::Generated)>,
}

/// The files a generation run of `names` produces in the workspace at `root`. The registries
/// list every mechanism file whose crate exists after the run, whether or not it was asked
/// for: a failed generation writes nothing and takes nothing out.
pub fn plan(root: &Path, names: &[String]) -> Result<Plan, FilesError> {
    let files = mechanism_files(root)?;
    let mut plan = Plan::default();
    let mut generated = Vec::new();
    for name in names {
        let file = match files.iter().find(|f| &f.name == name) {
            Some(f) => f,
            None => {
                let known = files.iter().map(|f| f.name.clone()).collect();
                let name = name.clone();
                plan.failures
                    .push((name.clone(), FilesError::UnknownMechanism { name, known }));
                continue;
            }
        };
        match generated_crate(root, file) {
            Ok((out, g)) => {
                plan.outputs.extend(out);
                plan.reports.push((name.clone(), g));
                generated.push(name.clone());
            }
            Err(e) => plan.failures.push((name.clone(), e)),
        }
    }
    let listed: Vec<MechanismFile> = files
        .iter()
        .filter(|f| generated.contains(&f.name) || root.join(module_path(&f.name)).exists())
        .cloned()
        .collect();
    plan.outputs.extend(registries(&listed));
    if let Ok(dirs) = std::fs::read_dir(root.join(GENERATED_DIR)) {
        let mut orphans: Vec<PathBuf> = dirs
            .filter_map(|d| d.ok())
            .filter_map(|d| d.file_name().to_str().map(str::to_string))
            .filter(|n| !files.iter().any(|f| &f.name == n))
            .map(|n| crate_dir(&n))
            .collect();
        orphans.sort();
        plan.orphans = orphans;
    }
    Ok(plan)
}

/// Every generated file of the workspace with its expected contents (all mechanisms).
pub fn all_expected(root: &Path) -> Result<Vec<(PathBuf, String)>, FilesError> {
    let names = mechanism_names(root)?;
    let mut plan = plan(root, &names)?;
    match plan.failures.pop() {
        Some((_, e)) => Err(e),
        None => Ok(plan.outputs),
    }
}
