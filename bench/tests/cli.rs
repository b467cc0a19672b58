//! The command-line tool on the benchmark problems (`symbody-bench`, the same code as
//! `symbody` over a registry that also holds the benchmark mechanisms).

use std::path::PathBuf;
use std::process::Command;

fn symbody(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_symbody-bench"))
        .args(args)
        .output()
        .expect("the tool runs");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn temp_dir(tag: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("bench-cli-{tag}-{}", std::process::id()))
}

/// A long list of redundant rows (the 40-bar chain's 120) is cut to the first nine and a
/// count, so the summary stays readable.
#[test]
fn a_long_redundant_row_list_is_cut_with_a_count() {
    let out_dir = temp_dir("redundant");
    let dir = out_dir.to_str().unwrap();
    let (ok, out, err) = symbody(&[
        "simulate",
        "n_four_bar_40",
        "--t-end",
        "0.01",
        "--no-plots",
        "--out",
        dir,
    ]);
    assert!(ok, "{err}");
    let line = out
        .lines()
        .find(|l| l.contains("redundant rows"))
        .unwrap_or_else(|| panic!("{out}"));
    let list = line.split(" (λ").next().unwrap();
    assert_eq!(list.matches(", ").count(), 9, "{line}");
    assert!(line.contains("right3.dot1(y1,z2), and 111 more"), "{line}");
    let _ = std::fs::remove_dir_all(&out_dir);
}
