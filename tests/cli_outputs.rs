//! What a run leaves behind can be read on its own: each route writes into a folder of its
//! own under `out/` and says which, `meta.json` beside the tables gives every column's unit
//! and what made the files, `list` stays in columns whatever the names, and bodies.csv can
//! carry the bodies' velocities.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;
use symbody_runtime::{Entry, Registry};

const BIN: &str = env!("CARGO_BIN_EXE_symbody");

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("symbody-outputs-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// Runs the tool in `cwd` with `args`: success, stdout, stderr.
fn symbody_in(cwd: &Path, args: &[&str]) -> (bool, String, String) {
    std::fs::create_dir_all(cwd).unwrap();
    let out = Command::new(BIN)
        .current_dir(cwd)
        .args(args)
        .output()
        .expect("the binary runs");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn meta(dir: &Path) -> Value {
    let text = std::fs::read_to_string(dir.join("meta.json"))
        .unwrap_or_else(|e| panic!("{}/meta.json: {e}", dir.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("meta.json is not JSON: {e}\n{text}"))
}

/// Every CSV in `dir` is described in `meta`'s `files`, with the header's columns in order
/// and a unit for each from the known set.
fn every_column_has_a_unit(dir: &Path, meta: &Value) {
    let files = meta["files"].as_object().expect("files");
    let mut csvs: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|f| f.ends_with(".csv"))
        .collect();
    csvs.sort();
    let mut described: Vec<String> = files.keys().cloned().collect();
    described.sort();
    assert_eq!(csvs, described, "{meta:#}");
    for (file, desc) in files {
        let text = std::fs::read_to_string(dir.join(file)).unwrap();
        let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
        let columns: Vec<&str> = desc["columns"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| c.as_str().unwrap())
            .collect();
        assert_eq!(header, columns, "{file}");
        for c in columns {
            let unit = desc["units"][c].as_str().unwrap_or("");
            assert!(
                ["s", "m", "rad", "1", "N", "N·m", "J", "m/s", "rad/s"].contains(&unit),
                "{file}: column {c} has unit {unit:?}"
            );
        }
    }
}

#[test]
fn simulate_writes_meta_json_with_units_settings_version_and_command_line() {
    let base = temp_dir("meta");
    // Quotes and `</` in an argument must come out as valid JSON, not break it.
    let dir = base.join("odd \"name\" </script>");
    let d = dir.to_str().unwrap();
    let args = [
        "simulate",
        "four_bar",
        "--t-end",
        "0.05",
        "--step",
        "5e-4",
        "--out",
        d,
        "--no-plots",
    ];
    let (ok, out, err) = symbody_in(&base, &args);
    assert!(ok, "{out}\n{err}");
    assert!(out.contains("meta.json"), "{out}");
    let m = meta(&dir);
    every_column_has_a_unit(&dir, &m);
    assert_eq!(m["mechanism"], "four_bar");
    assert_eq!(m["formulation"], "exact");
    assert_eq!(m["version"], env!("CARGO_PKG_VERSION"));
    assert_eq!(m["settings"]["step"], 5e-4);
    assert_eq!(m["settings"]["t_end"], 0.05);
    assert_eq!(m["settings"]["output_step"], 0.01);
    assert_eq!(m["settings"]["alpha"], 0.0);
    let line: Vec<&str> = m["command_line"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| a.as_str().unwrap())
        .collect();
    assert_eq!(&line[1..], &args[..]);
    let units = &m["files"]["joints.csv"]["units"];
    assert_eq!(units["a0.fx"], "N");
    assert_eq!(units["a0.mz"], "N·m");
    assert_eq!(m["files"]["drivers.csv"]["units"]["motor"], "N·m");
    assert_eq!(m["files"]["bodies.csv"]["units"]["crank.qw"], "1");
    assert_eq!(m["files"]["energy.csv"]["units"]["work"], "J");
}

#[test]
fn a_driver_pushing_a_slide_reports_newtons_and_a_stopped_run_keeps_its_meta() {
    // hexapod_twist stops at its singularity (t = 1.797 s) by design; its legs are slides.
    let dir = temp_dir("meta-stopped");
    let d = dir.to_str().unwrap();
    let (ok, out, err) = symbody_in(
        &std::env::temp_dir(),
        &["simulate", "hexapod_twist", "--no-plots", "--out", d],
    );
    assert!(!ok, "{out}\n{err}");
    let m = meta(&dir);
    every_column_has_a_unit(&dir, &m);
    let units = m["files"]["drivers.csv"]["units"].as_object().unwrap();
    assert!(!units.is_empty());
    assert!(units.iter().all(|(c, u)| c == "t" || u == "N"), "{units:?}");
}

#[test]
fn the_paper_scenario_and_scenes_write_meta_json_too() {
    let dir = temp_dir("meta-paper");
    let d = dir.to_str().unwrap();
    let (ok, out, err) = symbody_in(
        &std::env::temp_dir(),
        &["simulate", "--t-end", "0.05", "--no-plots", "--out", d],
    );
    assert!(ok, "{out}\n{err}");
    let m = meta(&dir);
    every_column_has_a_unit(&dir, &m);
    assert_eq!(m["mechanism"], "stewart_6_6");
    assert_eq!(m["settings"]["alpha"], -0.05);
    assert_eq!(m["files"]["platform.csv"]["units"]["beta"], "rad");
    assert_eq!(m["files"]["actuators.csv"]["units"]["act1"], "N");

    let dir = temp_dir("meta-scene");
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("short_four_bar.toml");
    std::fs::write(
        &scene,
        "mechanism = \"four_bar\"\n[time]\nend = 0.05\n[outputs]\nvelocities = true\n",
    )
    .unwrap();
    let out_dir = dir.join("o");
    let (ok, out, err) = symbody_in(
        &dir,
        &[
            "run",
            scene.to_str().unwrap(),
            "--no-plots",
            "--out",
            out_dir.to_str().unwrap(),
        ],
    );
    assert!(ok, "{out}\n{err}");
    let m = meta(&out_dir);
    every_column_has_a_unit(&out_dir, &m);
    assert_eq!(m["settings"]["scene"], scene.to_str().unwrap());
    assert_eq!(m["settings"]["path"], "auto");
    assert_eq!(m["settings"]["path_taken"], "kinematic");
    assert_eq!(m["files"]["bodies.csv"]["units"]["crank.wz"], "rad/s");
    assert_eq!(m["files"]["bodies.csv"]["units"]["crank.vx"], "m/s");
}

#[test]
fn each_route_writes_to_a_folder_of_its_own_and_says_which() {
    let cwd = temp_dir("routes");
    let (ok, out, err) = symbody_in(
        &cwd,
        &["simulate", "four_bar", "--t-end", "0.02", "--no-plots"],
    );
    assert!(ok, "{out}\n{err}");
    assert!(cwd.join("out/four_bar/bodies.csv").is_file());
    assert!(out.contains("wrote out/four_bar/: "), "{out}");

    let (ok, out, err) = symbody_in(&cwd, &["simulate", "--t-end", "0.02", "--no-plots"]);
    assert!(ok, "{out}\n{err}");
    assert!(cwd.join("out/paper/platform.csv").is_file());
    assert!(out.contains("wrote out/paper/: "), "{out}");

    std::fs::write(
        cwd.join("quick.toml"),
        "mechanism = \"slider_crank\"\n[time]\nend = 0.02\n",
    )
    .unwrap();
    let (ok, out, err) = symbody_in(&cwd, &["run", "quick.toml", "--no-plots"]);
    assert!(ok, "{out}\n{err}");
    assert!(cwd.join("out/quick/bodies.csv").is_file());
    assert!(out.contains("wrote out/quick/: "), "{out}");
    // Nothing landed in out/ itself, so no run overwrote another's files.
    let loose: Vec<_> = std::fs::read_dir(cwd.join("out"))
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.path().is_file())
        .map(|e| e.file_name())
        .collect();
    assert!(loose.is_empty(), "{loose:?}");
}

/// Every line's columns end (right-aligned) or start (left-aligned) at the same place: the
/// header's words and each row's values line up.
#[test]
fn list_keeps_its_columns_aligned_for_long_names() {
    let shipped = symbody_mechanisms::REGISTRY.find("four_bar").unwrap();
    let long: &'static Entry = Box::leak(Box::new(Entry {
        name: "a_user_mechanism_with_a_rather_long_name",
        t_end: shipped.t_end,
        formulations: shipped.formulations,
        reduced: None,
        origin: shipped.origin,
        run_time: None,
    }));
    let mut entries: Vec<&'static Entry> = symbody_benchmark_mechanisms::REGISTRY.iter().collect();
    entries.push(long);
    let registry = Registry(Box::leak(entries.into_boxed_slice()));
    let lines = symbody_cli::list_lines(&registry);
    assert_eq!(lines.len(), registry.len() + 1);
    // Where each of the 9 fields ends on a line (fields hold no spaces).
    let ends = |l: &str| -> Vec<usize> {
        let mut ends = Vec::new();
        let chars: Vec<char> = l.chars().collect();
        for (i, c) in chars.iter().enumerate() {
            if *c != ' ' && chars.get(i + 1).is_none_or(|n| *n == ' ') {
                ends.push(i + 1);
            }
        }
        ends
    };
    let starts = |l: &str| -> Vec<usize> {
        let chars: Vec<char> = l.chars().collect();
        (0..chars.len())
            .filter(|&i| chars[i] != ' ' && (i == 0 || chars[i - 1] == ' '))
            .collect()
    };
    let header = &lines[0];
    for l in &lines {
        assert_eq!(ends(l).len(), 9, "{l}");
        // The formulations column starts at the same place, the numbers end at the same.
        assert_eq!(starts(l)[1], starts(header)[1], "\n{header}\n{l}");
        assert_eq!(ends(l)[2..], ends(header)[2..], "\n{header}\n{l}");
    }
    assert!(lines.iter().any(|l| l.starts_with(long.name)));
    assert!(lines.iter().any(|l| l.starts_with("n_four_bar_40 ")));
}

/// Runs `mechanism` for 0.3 s with outputs every millisecond and its bodies' velocities,
/// and checks them against central differences of the recorded poses (their O(h²) error);
/// returns the largest speed and angular speed seen.
fn velocities_match_the_rates_of_the_poses(mechanism: &str) -> [f64; 2] {
    let dir = temp_dir(&format!("velocities-{mechanism}"));
    let d = dir.to_str().unwrap();
    let (ok, out, err) = symbody_in(
        &std::env::temp_dir(),
        &[
            "simulate",
            mechanism,
            "--velocities",
            "--t-end",
            "0.3",
            "--output-step",
            "1e-3",
            "--step",
            "1e-3",
            "--no-plots",
            "--out",
            d,
        ],
    );
    assert!(ok, "{out}\n{err}");
    let text = std::fs::read_to_string(dir.join("bodies.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    let col = |name: &str| {
        header
            .iter()
            .position(|c| *c == name)
            .unwrap_or_else(|| panic!("no column {name} in {header:?}"))
    };
    let bodies: Vec<&str> = header.iter().filter_map(|c| c.strip_suffix(".x")).collect();
    assert!(!bodies.is_empty());
    let mut largest = [0.0f64; 2];
    for body in bodies {
        let c = |part: &str| col(&format!("{body}.{part}"));
        let (x, qw, vx, wx) = (c("x"), c("qw"), c("vx"), c("wx"));
        for k in 1..rows.len() - 1 {
            let h = rows[k + 1][0] - rows[k - 1][0];
            let (r, prev, next) = (&rows[k], &rows[k - 1], &rows[k + 1]);
            for i in 0..3 {
                let fd = (next[x + i] - prev[x + i]) / h;
                assert!(
                    (fd - r[vx + i]).abs() < 1e-4,
                    "{mechanism} {body}, t = {}: v{i} {} vs {fd}",
                    r[0],
                    r[vx + i]
                );
                largest[0] = largest[0].max(r[vx + i].abs());
            }
            // ω = 2 ė ē (global frame), ė by central differences.
            let e = [r[qw], r[qw + 1], r[qw + 2], r[qw + 3]];
            let ed: Vec<f64> = (0..4).map(|i| (next[qw + i] - prev[qw + i]) / h).collect();
            let w = [
                2.0 * (-ed[0] * e[1] + ed[1] * e[0] - ed[2] * e[3] + ed[3] * e[2]),
                2.0 * (-ed[0] * e[2] + ed[2] * e[0] - ed[3] * e[1] + ed[1] * e[3]),
                2.0 * (-ed[0] * e[3] + ed[3] * e[0] - ed[1] * e[2] + ed[2] * e[1]),
            ];
            for i in 0..3 {
                assert!(
                    (w[i] - r[wx + i]).abs() < 1e-4,
                    "{mechanism} {body}, t = {}: w{i} {} vs {}",
                    r[0],
                    r[wx + i],
                    w[i]
                );
                largest[1] = largest[1].max(r[wx + i].abs());
            }
        }
    }
    largest
}

/// Quaternion bodies (the conical pendulum) and Euler-angle bodies (the paper's platform and
/// legs) alike: the columns are the rates of the poses beside them.
#[test]
fn velocities_in_bodies_csv_are_the_rates_of_the_poses() {
    let pendulum = velocities_match_the_rates_of_the_poses("spherical_pendulum");
    // The pendulum moves, so the comparison means something.
    assert!(pendulum[0] > 0.1 && pendulum[1] > 0.1, "{pendulum:?}");
    let platform = velocities_match_the_rates_of_the_poses("stewart_6_6");
    assert!(platform[0] > 1e-3 && platform[1] > 1e-3, "{platform:?}");
}

/// `--velocities` and a scene's `velocities` add to bodies.csv, which the paper scenario's
/// files do not have: both say so instead of ignoring the request.
#[test]
fn velocities_without_a_bodies_table_are_refused() {
    let dir = temp_dir("velocities-refused");
    let (ok, _, err) = symbody_in(&dir, &["simulate", "--velocities", "--no-plots"]);
    assert!(!ok);
    assert!(
        err.contains("--velocities applies to a named mechanism or a file"),
        "{err}"
    );
    std::fs::write(
        dir.join("p.toml"),
        "mechanism = \"stewart_6_6\"\n[outputs]\nfiles = \"paper\"\nvelocities = true\n",
    )
    .unwrap();
    let (ok, _, err) = symbody_in(&dir, &["run", "p.toml", "--no-plots"]);
    assert!(!ok);
    assert!(
        err.contains("[outputs] `velocities`") && err.contains("p.toml:4"),
        "{err}"
    );
    assert!(
        !dir.join("out").exists(),
        "nothing is written for a refused scene"
    );
}

/// What docs/mechanism-files.md says of a driven joint: its wrench in joints.csv is its own
/// rows' reaction, without the driver's torque, which drivers.csv reports on its own (the
/// four-bar's motor drives the revolute `a0` about Z).
#[test]
fn a_driven_joints_moment_leaves_out_its_drivers_torque() {
    let dir = temp_dir("driven");
    let d = dir.to_str().unwrap();
    let (ok, out, err) = symbody_in(
        &std::env::temp_dir(),
        &[
            "simulate",
            "four_bar",
            "--t-end",
            "0.5",
            "--no-plots",
            "--out",
            d,
        ],
    );
    assert!(ok, "{out}\n{err}");
    let column = |file: &str, name: &str| -> Vec<f64> {
        let text = std::fs::read_to_string(dir.join(file)).unwrap();
        let mut lines = text.lines();
        let c = lines
            .next()
            .unwrap()
            .split(',')
            .position(|c| c == name)
            .unwrap();
        lines
            .map(|l| l.split(',').nth(c).unwrap().parse().unwrap())
            .collect()
    };
    let largest = |v: Vec<f64>| v.iter().map(|x| x.abs()).fold(0.0, f64::max);
    let motor = largest(column("drivers.csv", "motor"));
    let about_axis = largest(column("joints.csv", "a0.mz"));
    assert!(motor > 0.1, "{motor}");
    assert!(
        about_axis < 1e-9 * motor,
        "{about_axis} N·m about a0's axis"
    );
}

/// Runs `mechanism` for 0.3 s with outputs every millisecond and its bodies' velocities and
/// accelerations, and checks the accelerations against central differences of the velocity
/// columns (themselves checked against the poses above); returns the largest linear and
/// angular acceleration seen and the largest mismatch relative to them.
fn accelerations_match_the_rates_of_the_velocities(mechanism: &str) -> [f64; 3] {
    let dir = temp_dir(&format!("accelerations-{mechanism}"));
    let d = dir.to_str().unwrap();
    let (ok, out, err) = symbody_in(
        &std::env::temp_dir(),
        &[
            "simulate",
            mechanism,
            "--velocities",
            "--accelerations",
            "--t-end",
            "0.3",
            "--output-step",
            "1e-3",
            "--no-plots",
            "--out",
            d,
        ],
    );
    assert!(ok, "{out}\n{err}");
    let text = std::fs::read_to_string(dir.join("bodies.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    let col = |name: &str| header.iter().position(|c| *c == name).unwrap();
    let meta = std::fs::read_to_string(dir.join("meta.json")).unwrap();
    assert!(meta.contains("m/s²") && meta.contains("rad/s²"), "{meta}");
    let bodies: Vec<&str> = header.iter().filter_map(|c| c.strip_suffix(".x")).collect();
    let (mut largest, mut mismatch) = ([0.0f64; 2], 0.0f64);
    for body in bodies {
        let c = |part: &str| col(&format!("{body}.{part}"));
        for (kind, rate, of) in [(0, c("ax"), c("vx")), (1, c("alphax"), c("wx"))] {
            for k in 1..rows.len() - 1 {
                let h = rows[k + 1][0] - rows[k - 1][0];
                for i in 0..3 {
                    let fd = (rows[k + 1][of + i] - rows[k - 1][of + i]) / h;
                    let got = rows[k][rate + i];
                    largest[kind] = largest[kind].max(got.abs());
                    mismatch = mismatch.max((fd - got).abs());
                }
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    [largest[0], largest[1], mismatch]
}

/// Quaternion bodies (the N-four-bar's swinging links; the conical pendulum's ω is constant)
/// and Euler-angle bodies (the paper's platform and legs): the accelerations are the rates of
/// the velocities beside them, to the central difference's O(h²) at h = 1 ms.
#[test]
fn accelerations_in_bodies_csv_are_the_rates_of_the_velocities() {
    for mechanism in ["n_four_bar_2", "stewart_6_6"] {
        let [linear, angular, mismatch] =
            accelerations_match_the_rates_of_the_velocities(mechanism);
        eprintln!("{mechanism}: |a| ≤ {linear}, |α| ≤ {angular}, mismatch {mismatch:e}");
        // The bodies accelerate, so the comparison means something.
        assert!(
            linear > 0.01 && angular > 0.1,
            "{mechanism}: {linear}, {angular}"
        );
        assert!(
            mismatch < 1e-4 * linear.max(angular),
            "{mechanism}: {mismatch:e}"
        );
    }
}
