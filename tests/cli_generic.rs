//! The command line on any registered mechanism: `list` shows the registry, `simulate
//! <name>` writes the four CSVs with one column group per body, joint and driver, and bad
//! requests fail with a message naming what exists.

use std::path::PathBuf;
use std::process::Command;
use symbody_mechanisms::REGISTRY;

fn symbody(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_symbody"))
        .args(args)
        .output()
        .expect("the binary runs");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("symbody-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

#[test]
fn list_shows_every_registered_mechanism() {
    let (ok, out, err) = symbody(&["list"]);
    assert!(ok, "{err}");
    for e in REGISTRY.iter() {
        let info = e.default_mechanism().info();
        let line = out
            .lines()
            .find(|l| l.split_whitespace().next() == Some(e.name))
            .unwrap_or_else(|| panic!("{} missing from\n{out}", e.name));
        let cols: Vec<&str> = line.split_whitespace().collect();
        let forms: Vec<&str> = e.formulations.iter().map(|(f, _)| f.name()).collect();
        assert_eq!(cols[1], forms.join(","), "{line}");
        assert_eq!(cols[2], info.bodies.len().to_string(), "{line}");
        assert_eq!(cols[3], info.n_coords.to_string(), "{line}");
        assert_eq!(cols[4], info.n_constraints.to_string(), "{line}");
        assert_eq!(cols[5], info.redundant_rows.len().to_string(), "{line}");
        assert_eq!(cols[6], info.dof().to_string(), "{line}");
        assert_eq!(
            cols[7]
                .parse::<f64>()
                .ok()
                .map(|t| (t - e.t_end).abs() < 1e-3),
            Some(true),
            "{line}"
        );
    }
}

#[test]
fn simulate_writes_the_four_csvs_with_their_columns() {
    let dir = temp_dir("four_bar");
    let d = dir.to_str().unwrap();
    let (ok, out, err) = symbody(&[
        "simulate",
        "four_bar",
        "--t-end",
        "0.2",
        "--out",
        d,
        "--no-plots",
    ]);
    assert!(ok, "{out}\n{err}");
    assert!(out.contains("redundant rows"), "{out}");
    let read = |f: &str| std::fs::read_to_string(dir.join(f)).expect(f);
    let header = |f: &str| read(f).lines().next().unwrap_or("").to_string();
    assert_eq!(
        read("energy.csv").lines().count(),
        22,
        "t = 0, 0.01, …, 0.2 and the header"
    );
    assert_eq!(header("energy.csv"), "t,kinetic,potential,work");
    assert_eq!(header("drivers.csv"), "t,motor");
    let bodies = header("bodies.csv");
    assert!(
        bodies
            .starts_with("t,crank.x,crank.y,crank.z,crank.qw,crank.qx,crank.qy,crank.qz,coupler.x"),
        "{bodies}"
    );
    assert_eq!(bodies.split(',').count(), 1 + 3 * 7);
    let joints = header("joints.csv");
    assert!(
        joints.starts_with("t,a0.fx,a0.fy,a0.fz,a0.mx,a0.my,a0.mz,a1.fx"),
        "{joints}"
    );
    assert_eq!(joints.split(',').count(), 1 + 4 * 6);
    // Every row has as many numbers as the header has names.
    for f in ["bodies.csv", "joints.csv", "drivers.csv", "energy.csv"] {
        let text = read(f);
        let n = text.lines().next().unwrap().split(',').count();
        for l in text.lines().skip(1) {
            assert_eq!(l.split(',').count(), n, "{f}: {l}");
            assert!(
                l.split(',')
                    .all(|x| x.parse::<f64>().is_ok_and(f64::is_finite)),
                "{f}: {l}"
            );
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn simulate_draws_the_drivers_and_each_body_and_prints_the_balance() {
    let dir = temp_dir("four_bar_plots");
    let (ok, out, err) = symbody(&[
        "simulate",
        "four_bar",
        "--t-end",
        "0.05",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert!(ok, "{out}\n{err}");
    for f in [
        "drivers.png",
        "position_crank.png",
        "position_coupler.png",
        "position_rocker.png",
    ] {
        let bytes = std::fs::read(dir.join(f)).expect(f);
        assert!(bytes.starts_with(b"\x89PNG"), "{f}");
    }
    for line in [
        "time span",
        "steps",
        "wall time",
        "max |Phi|",
        "energy balance",
    ] {
        assert!(out.contains(line), "{line} missing from\n{out}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bad_requests_name_what_exists() {
    let (ok, _, err) = symbody(&["simulate", "four_bars", "--no-plots"]);
    assert!(!ok);
    assert!(
        err.contains("no mechanism `four_bars`") && err.contains("did you mean `four_bar`"),
        "{err}"
    );
    for e in REGISTRY.iter() {
        assert!(err.contains(e.name), "{err}");
    }
    let (ok, _, err) = symbody(&[
        "simulate",
        "four_bar",
        "--formulation",
        "paper",
        "--no-plots",
    ]);
    assert!(!ok);
    assert!(err.contains("exact") && err.contains("paper"), "{err}");
    let (ok, _, err) = symbody(&["simulate", "four_bar", "--reactions", "integrator"]);
    assert!(!ok && err.contains("paper scenario only"), "{err}");
    let (ok, _, err) = symbody(&["simulate", "--cross-singular-positions"]);
    assert!(
        !ok && err.contains("applies to a named mechanism or a file"),
        "{err}"
    );
}

/// A mechanism file's path where a mechanism's name belongs (`simulate`, `fk`): the file
/// itself runs, interpreted (not the code generated from it, which may be older), and a path
/// to nothing says so instead of looking for `mechanisms/mechanisms/four_bar.toml.toml`.
#[test]
fn a_mechanism_file_path_runs_the_file() {
    let dir = std::env::temp_dir().join(format!("symbody-path-{}", std::process::id()));
    let out = dir.to_string_lossy().to_string();
    let (ok, stdout, err) = symbody(&[
        "simulate",
        "mechanisms/four_bar.toml",
        "--t-end",
        "0.01",
        "--no-plots",
        "--out",
        &out,
    ]);
    assert!(ok, "{err}");
    assert!(
        stdout.contains("interpreted from mechanisms/four_bar.toml"),
        "{stdout}"
    );
    let (ok, _, err) = symbody(&["simulate", "mechanisms/not_generated.toml"]);
    assert!(!ok);
    assert!(!err.contains("mechanisms/mechanisms"), "{err}");
    assert!(!err.contains(".toml.toml"), "{err}");
    assert!(
        err.contains("mechanisms/not_generated.toml: no such file"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// `run` given a mechanism file instead of a scene: it says what the file is and the commands
/// that take it (the name, and the shipped scene of that mechanism), not a typo suggestion for
/// the mechanism file's `name` field.
#[test]
fn run_on_a_mechanism_file_shows_the_commands_that_take_it() {
    assert!(std::path::Path::new("scenes/four_bar.toml").is_file());
    let (ok, _, err) = symbody(&["run", "mechanisms/four_bar.toml", "--no-plots"]);
    assert!(!ok);
    assert!(!err.contains("did you mean"), "{err}");
    assert!(err.contains("mechanism file"), "{err}");
    assert!(err.contains("mechanisms/four_bar.toml:1:1"), "{err}");
    assert!(
        err.contains("`symbody simulate four_bar`")
            && err.contains("`symbody run scenes/four_bar.toml`"),
        "{err}"
    );
}
