//! The workspace's generated files: a mechanism file that does not generate changes no
//! generated file (its previous crate stays, listed in the registries), a new invalid file
//! never enters a registry, and its diagnostic is what the run reports. (That generation is
//! deterministic and the committed files fresh: tests/generated_stewart.rs.)

use std::path::{Path, PathBuf};
use symbody_codegen::files::{self, FilesError, Group, GENERATED_DIR};

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("codegen lives one level below the workspace root")
        .to_path_buf()
}

/// An invalid mechanism file: the joint type is misspelt on line 14.
const BROKEN: &str = r#"name = "broken"

[[body]]
name = "bob"
mass = 1.0
inertia = [0.1, 0.1, 0.1]
position = [0.0, -1.0, 0.0]

[[joint]]
name = "pivot"
body1 = "ground"
body2 = "bob"
at = [0.0, 0.0, 0.0]
type = "sperical"
"#;

/// A copy of the workspace's mechanism files and committed generated crates in a fresh
/// folder laid out like the workspace, plus `mechanisms/broken.toml`.
struct Tree {
    root: PathBuf,
}

fn copy_dir(from: &Path, to: &Path, keep: impl Fn(&Path) -> bool) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let path = entry.unwrap().path();
        if path.is_file() && keep(&path) {
            std::fs::copy(&path, to.join(path.file_name().unwrap())).unwrap();
        }
    }
}

impl Tree {
    fn new(tag: &str) -> Tree {
        let root = Path::new(env!("CARGO_TARGET_TMPDIR"))
            .join(format!("files-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        let ws = workspace_root();
        let toml = |p: &Path| p.extension().is_some_and(|e| e == "toml");
        for g in Group::ALL {
            copy_dir(&ws.join(g.dir()), &root.join(g.dir()), toml);
        }
        for n in files::mechanism_names(&ws).unwrap() {
            let dir = files::crate_dir(&n);
            copy_dir(&ws.join(&dir), &root.join(&dir), |_| true);
        }
        std::fs::write(root.join("mechanisms/broken.toml"), BROKEN).unwrap();
        Tree { root }
    }

    /// What `cargo xtask generate <names>` would write.
    fn plan(&self, names: &[&str]) -> files::Plan {
        let names: Vec<String> = names.iter().map(|s| s.to_string()).collect();
        files::plan(&self.root, &names).unwrap()
    }
}

impl Drop for Tree {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.root);
    }
}

/// The registry files a plan writes, by path.
fn registry_files(plan: &files::Plan) -> Vec<(PathBuf, String)> {
    plan.outputs
        .iter()
        .filter(|(p, _)| !p.starts_with(GENERATED_DIR))
        .cloned()
        .collect()
}

/// The committed registry files.
fn committed_registries() -> Vec<(PathBuf, String)> {
    let ws = workspace_root();
    files::plan(&ws, &[])
        .unwrap()
        .outputs
        .into_iter()
        .map(|(p, _)| {
            let text = std::fs::read_to_string(ws.join(&p)).unwrap();
            (p, text)
        })
        .collect()
}

/// The broken file's diagnostic is what a failed run reports for it.
fn check_broken_failure(failures: &[(String, FilesError)]) {
    assert_eq!(failures.len(), 1, "{failures:?}");
    let (name, e) = &failures[0];
    assert_eq!(name, "broken");
    let FilesError::Invalid(errs) = e else {
        panic!("expected diagnostics, got {e}");
    };
    assert_eq!(errs.0.len(), 1, "{e}");
    let d = &errs.0[0];
    assert_eq!(d.file, "mechanisms/broken.toml", "{d}");
    assert_eq!(d.line, 14, "{d}");
    assert_eq!(d.item, "joint `pivot`", "{d}");
    assert!(d.message.contains("unknown joint type `sperical`"), "{d}");
    assert!(d.help.contains("did you mean \"spherical\"?"), "{d}");
    // xtask prints `<name>: <error>`.
    let shown = format!("{name}: {e}");
    assert!(
        shown.contains("mechanisms/broken.toml:14:8") && shown.contains("did you mean"),
        "{shown}"
    );
}

#[test]
fn the_committed_registries_list_every_mechanism_in_its_group() {
    let committed = committed_registries();
    let text = |path: &str| {
        &committed
            .iter()
            .find(|(p, _)| p == Path::new(path))
            .unwrap_or_else(|| panic!("{path}"))
            .1
    };
    let ws = workspace_root();
    for f in files::mechanism_files(&ws).unwrap() {
        let entry = format!("&{}::ENTRY,", f.name);
        let shipped = text("mechanisms/src/registry.rs");
        assert_eq!(
            shipped.contains(&entry),
            f.group == Group::Shipped,
            "{}",
            f.name
        );
        assert!(
            text("mechanisms/benchmarks/registry.rs").contains(&entry),
            "{}",
            f.name
        );
    }
}

#[test]
fn a_failed_generation_changes_no_generated_file() {
    // The slip a user makes: a typo in a shipped file that has a crate, then
    // `cargo xtask generate <it>` (issue: the registry used to be rewritten without it).
    let tree = Tree::new("typo");
    let path = tree.root.join("mechanisms/slider_crank.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    std::fs::write(&path, text.replacen("revolute", "revolut", 1)).unwrap();
    let plan = tree.plan(&["slider_crank"]);
    assert_eq!(plan.failures.len(), 1, "{:?}", plan.failures);
    assert!(
        plan.failures[0]
            .1
            .to_string()
            .contains("mechanisms/slider_crank.toml:"),
        "{}",
        plan.failures[0].1
    );
    assert!(plan
        .outputs
        .iter()
        .all(|(p, _)| !p.starts_with(files::crate_dir("slider_crank"))));
    // The registries it would write are the committed ones: slider_crank stays listed.
    assert_eq!(registry_files(&plan), committed_registries());
}

#[test]
fn a_new_invalid_file_is_reported_and_never_listed() {
    let tree = Tree::new("new");
    assert!(files::mechanism_names(&tree.root)
        .unwrap()
        .contains(&"broken".to_string()));
    // With another name, as `generate --all` would (every mechanism would take 7 s here).
    let plan = tree.plan(&["broken", "slider_crank"]);
    check_broken_failure(&plan.failures);
    assert_eq!(registry_files(&plan), committed_registries());
    // Regenerating another mechanism does not list it either.
    let plan = tree.plan(&["four_bar"]);
    assert!(plan.failures.is_empty());
    assert_eq!(registry_files(&plan), committed_registries());
    // The freshness check's view of the tree fails on the same diagnostic.
    let err = files::all_expected(&tree.root).expect_err("broken.toml is invalid");
    assert!(
        err.to_string().contains("mechanisms/broken.toml:14:8"),
        "{err}"
    );
}

#[test]
fn a_mechanism_without_a_crate_is_listed_once_generated() {
    let tree = Tree::new("gen");
    std::fs::remove_dir_all(tree.root.join(files::crate_dir("bricard"))).unwrap();
    let plan = tree.plan(&["four_bar"]);
    assert!(registry_files(&plan)
        .iter()
        .all(|(_, t)| !t.contains("bricard")));
    let plan = tree.plan(&["bricard"]);
    assert_eq!(registry_files(&plan), committed_registries());
}

#[test]
fn a_crate_whose_file_is_gone_is_an_orphan() {
    let tree = Tree::new("orphan");
    std::fs::remove_file(tree.root.join("mechanisms/four_bar.toml")).unwrap();
    let plan = tree.plan(&[]);
    assert_eq!(plan.orphans, vec![files::crate_dir("four_bar")]);
    let listed =
        |t: &str| t.contains("&four_bar::ENTRY") || t.contains("symbody-mechanism-four_bar ");
    assert!(registry_files(&plan).iter().all(|(_, t)| !listed(t)));
}

/// Renaming a file (and its `name`) and generating the new name lists it under that name,
/// drops the old one from the registries and removes its crate: what docs/mechanism-files.md
/// tells a user to do.
#[test]
fn a_renamed_file_is_listed_under_its_new_name_and_its_old_crate_removed() {
    let tree = Tree::new("rename");
    let old = tree.root.join("mechanisms/four_bar.toml");
    let text = std::fs::read_to_string(&old).unwrap();
    assert!(text.contains("name = \"four_bar\""));
    std::fs::remove_file(&old).unwrap();
    std::fs::write(
        tree.root.join("mechanisms/crank_rocker.toml"),
        text.replacen("name = \"four_bar\"", "name = \"crank_rocker\"", 1),
    )
    .unwrap();
    let plan = tree.plan(&["crank_rocker"]);
    assert!(plan.failures.is_empty(), "{:?}", plan.failures);
    assert_eq!(plan.orphans, vec![files::crate_dir("four_bar")]);
    let module = plan
        .outputs
        .iter()
        .find(|(p, _)| *p == files::module_path("crank_rocker"))
        .map(|(_, t)| t)
        .expect("the renamed crate is generated");
    assert!(module.contains("name: \"crank_rocker\""));
    let registries = registry_files(&plan);
    assert!(registries
        .iter()
        .any(|(_, t)| t.contains("&crank_rocker::ENTRY")));
    assert!(registries
        .iter()
        .all(|(_, t)| !t.contains("&four_bar::ENTRY") && !t.contains("mechanism-four_bar ")));
}
