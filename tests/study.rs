//! `symbody study`: a scene run once per row of its `[study]`. The rows are the same whatever
//! the number of threads and however the study is cut and resumed; each row's metrics are
//! those of an integrated run of the mechanism with that row's parameters set directly; a parameter set
//! that cannot be built is a failed row, not the end of the study; and mistakes in `[study]`
//! are located in the scene file.

use std::path::{Path, PathBuf};
use std::process::Command;
use symbody::files;
use symbody::generic::{self, Options};
use symbody_mechanisms::REGISTRY;

const BIN: &str = env!("CARGO_BIN_EXE_symbody");

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("symbody-study-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn study(scene: &Path, out: &Path, extra: &[&str]) -> (bool, String, String) {
    let o = Command::new(BIN)
        .args([
            "study".as_ref(),
            scene.as_os_str(),
            "--out".as_ref(),
            out.as_os_str(),
        ])
        .args(extra)
        .output()
        .unwrap();
    let (stdout, stderr) = (
        String::from_utf8_lossy(&o.stdout).to_string(),
        String::from_utf8_lossy(&o.stderr).to_string(),
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
    (o.status.success(), stdout, stderr)
}

/// The rows of a study.csv by run index, without the wall time (the last column).
fn rows(csv: &Path) -> Vec<Vec<String>> {
    let text = std::fs::read_to_string(csv).unwrap();
    let mut rows: Vec<Vec<String>> = text
        .lines()
        .skip(1)
        .map(|l| {
            let mut f: Vec<String> = l.split(',').map(String::from).collect();
            f.pop();
            f
        })
        .collect();
    rows.sort_by_key(|r| r[0].parse::<usize>().unwrap());
    rows
}

const CRANK: &str = "mechanism = \"slider_crank\"\n[time]\nend = 0.5\n[study]\n\
                     parameters = { r = { from = 0.08, to = 0.12, n = 4 }, len = [0.33, 0.36] }\n";

#[test]
fn rows_do_not_depend_on_threads_or_interruptions() {
    let dir = temp_dir("rows");
    let scene = dir.join("crank.toml");
    std::fs::write(&scene, CRANK).unwrap();
    let (ok, stdout, stderr) = study(&scene, &dir.join("one"), &["--jobs", "1"]);
    assert!(ok, "{stdout}{stderr}");
    let (ok, _, _) = study(&scene, &dir.join("two"), &["--jobs", "2"]);
    assert!(ok);
    let one = rows(&dir.join("one/study.csv"));
    assert_eq!(one.len(), 8);
    assert_eq!(one, rows(&dir.join("two/study.csv")));
    assert!(one.iter().all(|r| r[r.len() - 2] == "ok"), "{one:?}");
    assert!(dir.join("one/study.png").is_file(), "the grid's plot");
    // Cut after three rows, the fourth half written, as an interruption leaves it.
    let cut = dir.join("cut");
    std::fs::create_dir_all(&cut).unwrap();
    let text = std::fs::read_to_string(dir.join("one/study.csv")).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let partial = format!("{}\n{}", lines[..4].join("\n"), &lines[4][..10]);
    std::fs::write(cut.join("study.csv"), partial).unwrap();
    let (ok, stdout, _) = study(&scene, &cut, &["--resume"]);
    assert!(ok);
    assert!(stdout.contains("3 already in"), "{stdout}");
    assert_eq!(rows(&cut.join("study.csv")), one);
}

#[test]
fn a_rows_metrics_are_those_of_a_direct_run() {
    let dir = temp_dir("direct");
    let scene = dir.join("crank.toml");
    std::fs::write(&scene, CRANK).unwrap();
    let (ok, _, stderr) = study(&scene, &dir, &[]);
    assert!(ok, "{stderr}");
    let text = std::fs::read_to_string(dir.join("study.csv")).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let motor = header.iter().position(|c| *c == "max|motor|").unwrap();
    let opts = Options {
        t_end: Some(0.5),
        ..Options::default()
    };
    for row in rows(&dir.join("study.csv")) {
        let set = vec![
            ("len".to_string(), row[1].parse::<f64>().unwrap()),
            ("r".to_string(), row[2].parse::<f64>().unwrap()),
        ];
        let entry = files::with_parameters(&REGISTRY, "slider_crank", &set).unwrap();
        let rec = generic::run(entry, &opts).unwrap();
        let peak = rec.efforts.iter().fold(0.0f64, |m, e| m.max(e[0].abs()));
        // The study's scene takes the kinematic path (the crank is driven), the direct run
        // integrates: two routes, both exact to roundoff.
        let got = row[motor].parse::<f64>().unwrap();
        assert!(
            (got - peak).abs() <= 1e-9 * peak,
            "{set:?}: {got} vs {peak}"
        );
    }
}

#[test]
fn a_set_that_cannot_be_built_is_a_failed_row() {
    let dir = temp_dir("failed");
    let scene = dir.join("bar.toml");
    std::fs::write(
        &scene,
        "mechanism = \"four_bar\"\n[time]\nend = 0.1\n[study]\nparameters = { b = [0.1, 0.35] }\n",
    )
    .unwrap();
    let (ok, stdout, stderr) = study(&scene, &dir, &[]);
    assert!(ok, "{stdout}{stderr}");
    assert!(stdout.contains("1 ok, 1 failed"), "{stdout}");
    let text = std::fs::read_to_string(dir.join("study.csv")).unwrap();
    let failed = text.lines().find(|l| l.starts_with("0,")).unwrap();
    assert!(
        failed.contains("failed") && failed.contains("kappa"),
        "{failed}"
    );
}

#[test]
fn mistakes_in_the_study_are_located_in_the_scene() {
    let dir = temp_dir("bad");
    let cases = [
        ("parameters = { rr = [0.1] }", "did you mean `r`?"),
        (
            "parameters = { r = { from = 0.1, to = 0.1, n = 3 } }",
            "empty range",
        ),
        (
            "parameters = { r = { from = 0.1, to = 0.2, n = 0 } }",
            "n = 0",
        ),
        (
            "parameters = { r = { normal = [0.1, -0.01] } }\nsamples = 5",
            "standard deviation",
        ),
        (
            "parameters = { r = { uniform = [0.2, 0.1] } }\nsamples = 5",
            "empty range",
        ),
        (
            "parameters = { r = { uniform = [0.1, 0.2] } }",
            "need `samples`",
        ),
        ("parameters = { r = [] }", "empty list"),
        (
            "parameters = { r = { uniform = [0.1, 0.2] }, len = [0.3] }\nsamples = 5",
            "fixed values among random",
        ),
    ];
    for (k, (study_text, says)) in cases.iter().enumerate() {
        let scene = dir.join(format!("s{k}.toml"));
        std::fs::write(
            &scene,
            format!("mechanism = \"slider_crank\"\n[study]\n{study_text}\n"),
        )
        .unwrap();
        let (ok, _, stderr) = study(&scene, &dir.join(format!("o{k}")), &[]);
        assert!(!ok, "{study_text}");
        assert!(stderr.contains(&format!("s{k}.toml:")), "{stderr}");
        assert!(stderr.contains(says), "{study_text}: {stderr}");
    }
    // A scene without a study says how to write one.
    let scene = dir.join("plain.toml");
    std::fs::write(&scene, "mechanism = \"slider_crank\"\n").unwrap();
    let (ok, _, stderr) = study(&scene, &dir.join("plain"), &[]);
    assert!(!ok && stderr.contains("no [study] table"), "{stderr}");
}
