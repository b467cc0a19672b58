//! Nothing lost, nothing silent, on the command line: a run writes its tables as it goes, so
//! one that fails or is interrupted keeps every output up to its last good state and says
//! where and why it stopped; an unwritable output folder is reported before any work; long
//! runs show progress on a terminal and print nothing extra when not on one.

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_symbody");

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("symbody-runs-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// The complete data rows of a CSV (header aside), each as numbers: a file read while its
/// run still writes it may end in part of a line, which is left out.
fn rows(path: &Path) -> Vec<Vec<f64>> {
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let complete = text.rfind('\n').map_or("", |end| &text[..end]);
    complete
        .lines()
        .skip(1)
        .filter(|l| !l.is_empty())
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect()
}

/// Sends Ctrl-C (SIGINT) to `child` and waits for it to end, at most `limit`: a run that
/// ignores it is killed and fails the test instead of hanging it.
fn interrupt(mut child: Child, limit: Duration) -> Output {
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    let clock = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if clock.elapsed() > limit {
            let _ = child.kill();
            panic!("still running {limit:?} after Ctrl-C");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

#[test]
fn a_run_that_fails_keeps_its_outputs_and_says_where_and_why_it_stopped() {
    // hexapod_twist drives its platform into a parallel singularity at t = 1.797 s, by design.
    let dir = temp_dir("hexapod");
    let out = Command::new(BIN)
        .args(["simulate", "hexapod_twist", "--no-plots", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert!(!out.status.success());
    assert!(
        stderr.contains("parallel singularity at t = 1.797"),
        "{stderr}"
    );
    assert!(
        stdout.contains("stopped          after the output at t = 1.790000 s"),
        "{stdout}"
    );
    for stem in ["bodies", "drivers", "energy"] {
        let r = rows(&dir.join(format!("{stem}.csv")));
        // Outputs every 10 ms from 0 to the last before the singularity.
        assert_eq!(r.len(), 180, "{stem}");
        assert_eq!(r.last().unwrap()[0], 1.79, "{stem}");
        assert!(r.iter().all(|row| row.iter().all(|v| v.is_finite())));
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn an_unwritable_output_folder_is_reported_before_the_run() {
    // At its speed, 1e5 s of the four-bar would take minutes: the error must come first.
    let clock = Instant::now();
    for args in [
        &["simulate", "four_bar", "--t-end", "1e5"][..],
        &["simulate", "--t-end", "1e5"][..],
        &["run", "scenes/four_bar.toml"][..],
    ] {
        let out = Command::new(BIN)
            .args(args)
            .args(["--out", "/proc/forbidden"])
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?}");
        assert!(
            stderr.contains("cannot write to /proc/forbidden") && stderr.contains("--out"),
            "{args:?}: {stderr}"
        );
    }
    assert!(clock.elapsed() < Duration::from_secs(60));
}

#[test]
fn ctrl_c_stops_the_run_and_keeps_what_it_computed() {
    let dir = temp_dir("interrupt");
    let child = Command::new(BIN)
        .args(["simulate", "n_four_bar_2", "--cross-singular-positions"])
        .args(["--t-end", "1e4", "--no-plots", "--out"])
        .arg(&dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Waits for outputs on disk (they are flushed every 200 ms), then interrupts.
    let bodies = dir.join("bodies.csv");
    let clock = Instant::now();
    while rows(&bodies).len() < 5 {
        assert!(
            clock.elapsed() < Duration::from_secs(120),
            "no output written"
        );
        std::thread::sleep(Duration::from_millis(50));
    }
    let seen = rows(&bodies).len();
    let out = interrupt(child, Duration::from_secs(30));
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert!(!out.status.success());
    assert!(stderr.contains("interrupted at t = "), "{stderr}");
    assert!(stdout.contains("stopped "), "{stdout}");
    let kept = rows(&bodies);
    assert!(
        kept.len() >= seen,
        "{} rows after, {seen} before",
        kept.len()
    );
    // The summary's last output is the files' last row.
    let last = kept.last().unwrap()[0];
    assert!(
        stdout.contains(&format!("after the output at t = {last:.6} s")),
        "{last}: {stdout}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn progress_shows_on_a_terminal_only() {
    let dir = temp_dir("progress");
    let args = [
        "simulate",
        "n_four_bar_2",
        "--cross-singular-positions",
        "--t-end",
        "20",
        "--no-plots",
        "--out",
        dir.to_str().unwrap(),
    ];
    // Not a terminal: stderr stays empty.
    let out = Command::new(BIN).args(args).output().unwrap();
    assert!(out.status.success());
    assert_eq!(String::from_utf8_lossy(&out.stderr), "");
    // A terminal (util-linux `script` gives the run a pseudo-terminal): the bar shows the
    // simulated time, the steps and their rate, and the time left.
    let line = std::iter::once(BIN)
        .chain(args)
        .collect::<Vec<_>>()
        .join(" ");
    let out = Command::new("script")
        .args(["-qec", &line, "/dev/null"])
        .output()
        .expect("util-linux `script` runs");
    assert!(out.status.success());
    let screen = String::from_utf8_lossy(&out.stdout);
    assert!(
        screen.contains("/20 s,") && screen.contains(" steps, "),
        "{screen}"
    );
    assert!(screen.contains(" left"), "{screen}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn ctrl_c_ends_a_run_that_does_not_stream_at_once() {
    // The paper scenario records in memory; Ctrl-C must still end it at once (not wait for
    // a second one).
    let child = Command::new(BIN)
        .args([
            "simulate",
            "--t-end",
            "1e4",
            "--output-step",
            "1",
            "--no-plots",
            "--out",
        ])
        .arg(temp_dir("paper-interrupt"))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Time to install the handler and start; a signal before then ends it just the same.
    std::thread::sleep(Duration::from_millis(500));
    let out = interrupt(child, Duration::from_secs(30));
    // 130: the handler's exit; `None`: the default action, if the signal came first.
    assert!(
        matches!(out.status.code(), Some(130) | None),
        "{:?}",
        out.status
    );
}

#[test]
fn the_readmes_singular_position_example_needs_its_flag() {
    // README: `simulate n_four_bar_2 --step 2.5e-4 --cross-singular-positions`, and without
    // the flag the run stops at a flat position in its 13th second.
    let dir = temp_dir("flat");
    let run = |flag: &[&str]| {
        Command::new(BIN)
            .args([
                "simulate",
                "n_four_bar_2",
                "--step",
                "2.5e-4",
                "--no-plots",
                "--out",
            ])
            .arg(&dir)
            .args(flag)
            .output()
            .unwrap()
    };
    let without = run(&[]);
    let stderr = String::from_utf8_lossy(&without.stderr);
    assert!(!without.status.success());
    assert!(stderr.contains("lost rank at t = 12."), "{stderr}");
    assert!(run(&["--cross-singular-positions"]).status.success());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_run_whose_steps_are_too_long_for_its_motion_says_so() {
    // A03 (Andrews' squeezer) moves on a time scale of ~1e-5 s: at the default 1 ms step its
    // energy balance is off by 7 % of the energy scale (the reference: the energy theorem,
    // which the balance checks), and the summary must warn; with step-size control at rtol
    // 1e-5 the balance holds to 4.4e-6 and no warning is given.
    let dir = temp_dir("too-long");
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/mechanisms/benchmarks/andrews_squeezer.toml"
    );
    let run = |extra: &[&str]| {
        let out = Command::new(BIN)
            .args(["simulate", file, "--no-plots", "--out"])
            .arg(&dir)
            .args(extra)
            .output()
            .unwrap();
        assert!(out.status.success(), "{out:?}");
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let coarse = run(&[]);
    assert!(
        coarse.contains("warning: the energy balance is off by")
            && coarse.contains("--rtol (step-size control)"),
        "{coarse}"
    );
    let controlled = run(&["--rtol", "1e-5"]);
    assert!(!controlled.contains("warning"), "{controlled}");
    let _ = std::fs::remove_dir_all(&dir);
}
