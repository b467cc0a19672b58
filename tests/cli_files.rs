//! Mechanism files given to the command-line tool where a name goes: run interpreted at once,
//! checked without a run, named from scenes relative to the scene file; and every way a path
//! can be wrong gives a clear error naming it, never a panic.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const BIN: &str = env!("CARGO_BIN_EXE_symbody");

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("symbody-files-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// `mechanisms/<name>.toml` copied into `dir` as `new_name`: a file the tool never compiled.
fn copy_of(name: &str, dir: &Path, new_name: &str) -> PathBuf {
    let to = dir.join(new_name);
    std::fs::copy(root().join(format!("mechanisms/{name}.toml")), &to).unwrap();
    to
}

fn run(args: &[&std::ffi::OsStr]) -> (Output, String, String) {
    let out = Command::new(BIN).args(args).output().unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert!(!stderr.contains("panicked"), "{stderr}");
    (out, stdout, stderr)
}

/// The CSV data rows of `file`.
fn data(file: &Path) -> Vec<String> {
    std::fs::read_to_string(file)
        .unwrap()
        .lines()
        .skip(1)
        .map(str::to_string)
        .collect()
}

#[test]
fn a_file_never_compiled_simulates_and_matches_the_compiled_mechanism() {
    let dir = temp_dir("simulate");
    let file = copy_of("ups_stewart", &dir, "my_platform.toml");
    let (a, b) = (dir.join("a"), dir.join("b"));
    let (out, stdout, stderr) = run(&[
        "simulate".as_ref(),
        file.as_os_str(),
        "--t-end".as_ref(),
        "0.2".as_ref(),
        "--no-plots".as_ref(),
        "--out".as_ref(),
        a.as_os_str(),
    ]);
    assert!(out.status.success(), "{stdout}{stderr}");
    assert!(stdout.contains("interpreted from"), "{stdout}");
    assert!(stdout.contains("cargo xtask generate"), "{stdout}");
    let (out, stdout, _) = run(&[
        "simulate".as_ref(),
        "ups_stewart".as_ref(),
        "--t-end".as_ref(),
        "0.2".as_ref(),
        "--no-plots".as_ref(),
        "--out".as_ref(),
        b.as_os_str(),
    ]);
    assert!(out.status.success());
    assert!(!stdout.contains("interpreted"), "{stdout}");
    // Same operations in the same order: the tables agree to the digit.
    for table in ["bodies.csv", "joints.csv", "drivers.csv"] {
        assert_eq!(data(&a.join(table)), data(&b.join(table)), "{table}");
    }
}

#[test]
fn check_reports_what_the_generator_finds_without_running() {
    let dir = temp_dir("check");
    let file = copy_of("four_bar", &dir, "linkage.toml");
    let (out, stdout, stderr) = run(&["check".as_ref(), file.as_os_str()]);
    assert!(out.status.success(), "{stdout}{stderr}");
    // A planar four-bar has mobility 3·3 − 2·4 = 1 and its crank driver takes it; written
    // with spatial revolutes (5 rows each) the count is 6·3 − 5·4 = −2, so 1 − (−2) = 3 rows
    // are dependent: rank 18 of 21 rows on 18 Euler-angle coordinates. Its planar model has
    // 3·3 coordinates and 2·4 + 1 rows, none dependent.
    assert!(stdout.contains("rank 18"), "{stdout}");
    assert!(
        stdout
            .contains("planar model: 9 coordinates (x, y, γ per body), 9 rows, no redundant rows"),
        "{stdout}"
    );
    assert!(
        stdout.contains("actual 1 (without drivers); 0 DOF left with drivers"),
        "{stdout}"
    );
    assert!(stdout.contains("3 redundant row(s)"), "{stdout}");
    assert!(stdout.contains("valid"), "{stdout}");
    assert!(!dir.join("out").exists(), "check writes nothing");
}

#[test]
fn a_scene_names_a_file_relative_to_itself() {
    let dir = temp_dir("scene");
    std::fs::create_dir_all(dir.join("models")).unwrap();
    copy_of("slider_crank", &dir.join("models"), "crank.toml");
    let scene = dir.join("crank_scene.toml");
    std::fs::write(
        &scene,
        "mechanism = \"models/crank.toml\"\n[time]\nend = 0.1\n",
    )
    .unwrap();
    let out_dir = dir.join("out");
    let (out, stdout, stderr) = run(&[
        "run".as_ref(),
        scene.as_os_str(),
        "--no-plots".as_ref(),
        "--out".as_ref(),
        out_dir.as_os_str(),
    ]);
    assert!(out.status.success(), "{stdout}{stderr}");
    assert!(stdout.contains("interpreted from"), "{stdout}");
    assert!(out_dir.join("joints.csv").is_file());
    // A missing file is located in the scene.
    std::fs::write(&scene, "mechanism = \"models/nothing.toml\"\n").unwrap();
    let (out, _, stderr) = run(&["run".as_ref(), scene.as_os_str()]);
    assert!(!out.status.success());
    assert!(stderr.contains("crank_scene.toml:1:"), "{stderr}");
    assert!(stderr.contains("nothing.toml"), "{stderr}");
}

#[test]
fn bad_paths_and_bad_files_are_clear_errors() {
    let dir = temp_dir("bad");
    let missing = dir.join("missing.toml");
    let folder = dir.join("folder.toml");
    std::fs::create_dir_all(&folder).unwrap();
    let binary = dir.join("binary.toml");
    std::fs::write(&binary, b"name = \"x\"\n\xff\xfe\x00oops").unwrap();
    let huge = dir.join("huge.toml");
    std::fs::write(&huge, vec![b'#'; 2 << 20]).unwrap();
    let broken = dir.join("broken.toml");
    std::fs::write(&broken, "name = \"broken\"\n[[body]]\nname = \n").unwrap();
    let cases: [(&Path, &str); 5] = [
        (&missing, "no such file"),
        (&folder, "is a folder"),
        (&binary, "line 2, column 1"),
        (&huge, "bytes, more than"),
        (&broken, "broken.toml:3:"),
    ];
    for (path, says) in cases {
        for command in ["simulate", "check", "fk"] {
            let (out, stdout, stderr) = run(&[command.as_ref(), path.as_os_str()]);
            assert!(
                !out.status.success(),
                "{command} {}: {stdout}",
                path.display()
            );
            assert!(
                stderr.contains(&*path.file_name().unwrap().to_string_lossy()),
                "{command}: the message names the file: {stderr}"
            );
            assert!(
                stderr.contains(says),
                "{command} {}: {stderr}",
                path.display()
            );
        }
    }
}

#[test]
fn set_and_params_change_a_parameter_without_a_build() {
    let dir = temp_dir("set");
    let out_dir = dir.join("out");
    let (out, stdout, stderr) = run(&[
        "simulate".as_ref(),
        "slider_crank".as_ref(),
        "--set".as_ref(),
        "r=0.12".as_ref(),
        "--t-end".as_ref(),
        "0.2".as_ref(),
        "--no-plots".as_ref(),
        "--out".as_ref(),
        out_dir.as_os_str(),
    ]);
    assert!(out.status.success(), "{stdout}{stderr}");
    assert!(stdout.contains("with r = 0.12"), "{stdout}");
    let meta = std::fs::read_to_string(out_dir.join("meta.json")).unwrap();
    assert!(meta.contains("\"r\": 0.12"), "{meta}");
    // The scene route, on top of the scene's own parameters.
    let (out, stdout, stderr) = run(&[
        "run".as_ref(),
        root().join("scenes/slider_crank.toml").as_os_str(),
        "--set".as_ref(),
        "r=0.12".as_ref(),
        "--no-plots".as_ref(),
        "--out".as_ref(),
        dir.join("scene").as_os_str(),
    ]);
    assert!(out.status.success(), "{stdout}{stderr}");
    assert!(stdout.contains("with r = 0.12"), "{stdout}");
    // Listed with what each affects.
    let (out, stdout, _) = run(&["params".as_ref(), "slider_crank".as_ref()]);
    assert!(out.status.success());
    let r = stdout
        .lines()
        .find(|l| l.trim_start().starts_with("r "))
        .unwrap();
    assert!(r.contains("0.1") && r.contains("body `crank`"), "{r}");
    // Wrong names and values.
    for (set, says) in [
        ("rr=0.12", "did you mean `r`?"),
        ("r=abc", "is not a number"),
        ("r", "give NAME=VALUE"),
        ("r=nan", "set to NaN"),
    ] {
        let (out, _, stderr) = run(&[
            "simulate".as_ref(),
            "slider_crank".as_ref(),
            "--set".as_ref(),
            set.as_ref(),
        ]);
        assert!(!out.status.success(), "{set}");
        assert!(stderr.contains(says), "{set}: {stderr}");
    }
}
