//! The workspace's generated files: an invalid mechanism file never enters the module index
//! (whatever `cargo xtask generate` was asked to regenerate) and its diagnostic is what the
//! run reports; and generating every mechanism file twice gives the same module.

use std::path::{Path, PathBuf};
use symbody_codegen::files::{self, FilesError, GENERATED_DIR, MECHANISMS_DIR};
use symbody_codegen::generate;
use symbody_codegen::model::Formulation;

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

/// A copy of the workspace's mechanism files and committed generated modules in a fresh
/// folder laid out like the workspace, plus `mechanisms/broken.toml`.
struct Tree {
    root: PathBuf,
}

impl Tree {
    fn new(tag: &str) -> Tree {
        let root = Path::new(env!("CARGO_TARGET_TMPDIR"))
            .join(format!("files-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        let ws = workspace_root();
        for (dir, ext) in [(MECHANISMS_DIR, "toml"), (GENERATED_DIR, "rs")] {
            std::fs::create_dir_all(root.join(dir)).unwrap();
            for entry in std::fs::read_dir(ws.join(dir)).unwrap() {
                let path = entry.unwrap().path();
                if path.extension().is_some_and(|e| e == ext) {
                    std::fs::copy(&path, root.join(dir).join(path.file_name().unwrap())).unwrap();
                }
            }
        }
        std::fs::write(root.join(MECHANISMS_DIR).join("broken.toml"), BROKEN).unwrap();
        Tree { root }
    }

    /// What `cargo xtask generate <names>` does before writing: regenerate each name,
    /// collect the failures, and build the index.
    fn run(&self, names: &[&str]) -> (Vec<(String, FilesError)>, files::IndexEntries, String) {
        let names: Vec<String> = names.iter().map(|s| s.to_string()).collect();
        let mut regenerated = Vec::new();
        let mut failures = Vec::new();
        for n in &names {
            match files::generated_module(&self.root, n) {
                Ok((_, g)) => regenerated.push((n.clone(), g.formulations)),
                Err(e) => failures.push((n.clone(), e)),
            }
        }
        let index = files::index_entries(&self.root, &names, &regenerated).unwrap();
        let (path, code) = files::generated_index(&index.entries);
        assert_eq!(path, Path::new(GENERATED_DIR).join("mod.rs"));
        (failures, index, code)
    }
}

impl Drop for Tree {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.root);
    }
}

/// The valid mechanisms of the workspace (every file there is valid).
fn workspace_mechanisms() -> Vec<String> {
    files::mechanism_names(&workspace_root()).unwrap()
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

fn check_index(index: &files::IndexEntries, code: &str) {
    let listed: Vec<&str> = index.entries.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(listed, workspace_mechanisms(), "{code}");
    assert!(!code.contains("broken"), "{code}");
    for n in workspace_mechanisms() {
        assert!(code.contains(&format!("pub mod {n};")), "{n}: {code}");
    }
    // The workspace's formulations, e.g. Stewart's paper formulation after the exact one.
    let stewart = index
        .entries
        .iter()
        .find(|(n, _)| n == "stewart_6_6")
        .unwrap();
    assert_eq!(stewart.1, vec![Formulation::Exact, Formulation::Paper]);
}

#[test]
fn generate_all_leaves_a_broken_file_out_of_the_index() {
    let tree = Tree::new("all");
    let names = files::mechanism_names(&tree.root).unwrap();
    assert!(names.contains(&"broken".to_string()));
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    let (failures, index, code) = tree.run(&names);
    check_broken_failure(&failures);
    check_index(&index, &code);
    assert!(index.left_out.is_empty(), "{:?}", index.left_out);
    // Without the broken file, the index is the committed one.
    let committed =
        std::fs::read_to_string(workspace_root().join(GENERATED_DIR).join("mod.rs")).unwrap();
    assert_eq!(code, committed);
    // The freshness check's view of the tree fails on the same diagnostic.
    let err = files::all_expected(&tree.root).expect_err("broken.toml is invalid");
    assert!(
        err.to_string().contains("mechanisms/broken.toml:14:8"),
        "{err}"
    );
}

#[test]
fn generate_one_leaves_a_stale_module_of_a_broken_file_out() {
    // broken.rs was generated when the file was still valid; regenerating another
    // mechanism must not put it back in the index.
    let tree = Tree::new("one");
    let stale = tree.root.join(files::module_path("broken"));
    std::fs::write(&stale, "// generated from an older, valid broken.toml\n").unwrap();
    let (failures, index, code) = tree.run(&["four_bar"]);
    assert!(failures.is_empty());
    check_index(&index, &code);
    assert_eq!(index.left_out, vec!["broken".to_string()]);

    // Asking for the broken file itself: it fails, and the others stay in the index.
    let (failures, index, code) = tree.run(&["broken"]);
    check_broken_failure(&failures);
    check_index(&index, &code);
    assert!(index.left_out.is_empty(), "{:?}", index.left_out);
}

#[test]
fn a_mechanism_without_a_module_is_not_indexed_until_generated() {
    let tree = Tree::new("new");
    std::fs::remove_file(tree.root.join(files::module_path("bricard"))).unwrap();
    let (_, index, code) = tree.run(&["four_bar"]);
    assert!(index.entries.iter().all(|(n, _)| n != "bricard"));
    assert!(!code.contains("bricard"));
    let (_, index, _) = tree.run(&["bricard"]);
    assert!(index.entries.iter().any(|(n, _)| n == "bricard"));
}

#[test]
fn generation_is_deterministic_for_every_mechanism_file() {
    let root = workspace_root();
    let names = workspace_mechanisms();
    assert!(names.len() >= 6, "{names:?}");
    for n in &names {
        let rel = format!("{MECHANISMS_DIR}/{n}.toml");
        let text = std::fs::read_to_string(root.join(&rel)).unwrap();
        let first = generate(&rel, &text).unwrap_or_else(|e| panic!("{e}"));
        let second = generate(&rel, &text).unwrap_or_else(|e| panic!("{e}"));
        assert!(first.code == second.code, "{n}: the generated code differs");
        assert_eq!(first.report, second.report, "{n}");
        assert_eq!(first.formulations, second.formulations, "{n}");
        // Through the files layer too (what xtask writes).
        let (path, third) = files::generated_module(&root, n).unwrap();
        assert_eq!(path, files::module_path(n));
        assert!(
            third.code == first.code,
            "{n}: files::generated_module differs"
        );
    }
}
