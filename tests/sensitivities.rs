//! Sensitivities of whole runs with respect to the file's parameters
//! (`symbody::sensitivity`) against their independent reference: differences of whole runs,
//! the mechanism rebuilt at p ± δ and p ± 2δ (δ = 1e-3·|p|) and every solve done again, the
//! central differences at δ and 2δ combined by Richardson extrapolation (fourth order).
//! Plain central differences were not accurate enough to judge 1e-6: at δ = 1e-3·|p| their
//! truncation reached 3.7e-5 on the paper scene (δ = 1e-4: 3.9e-7), at δ = 1e-5·|p| the
//! solves' tolerance over δ reached 7e-6.

use symbody::files;
use symbody::generic::{self, Options, Recording};
use symbody::sensitivity::{self, Sensitivities, Span};
use symbody_mechanisms::REGISTRY;
use symbody_runtime::{Entry, Formulation};

/// A whole run with some of the file's parameters set.
type Runs<'a> = dyn Fn(&[(String, f64)]) -> Recording + 'a;

/// Relative step of the reference differences.
const DELTA: f64 = 1e-3;

fn entry(name: &str) -> &'static Entry {
    generic::find(&REGISTRY, name).unwrap()
}

/// The value of parameter `name` in `entry`'s file.
fn value(entry: &Entry, name: &str) -> f64 {
    files::derive(entry, &[])
        .unwrap()
        .parameters
        .iter()
        .find(|p| p.name == name)
        .unwrap()
        .value
}

/// Each output's series from a recording, by the names `Sensitivities::outputs` uses.
fn series(rec: &Recording, output: &str) -> Vec<f64> {
    let info = rec.info;
    if let Some(d) = rec
        .drivers
        .iter()
        .position(|&j| info.joints[j].name == output)
    {
        return rec.efforts.iter().map(|e| e[d]).collect();
    }
    let (item, part) = output.rsplit_once('.').unwrap();
    if let Some(b) = info.bodies.iter().position(|b| b.name == item) {
        let k = ["x", "y", "z", "qw", "qx", "qy", "qz"]
            .iter()
            .position(|p| *p == part)
            .unwrap();
        return rec
            .poses
            .iter()
            .map(|p| if k < 3 { p[b].0[k] } else { p[b].1[k - 3] })
            .collect();
    }
    let j = rec
        .joints
        .iter()
        .position(|&j| info.joints[j].name == item)
        .unwrap();
    let k = ["fx", "fy", "fz", "mx", "my", "mz"]
        .iter()
        .position(|p| *p == part)
        .unwrap();
    rec.wrenches
        .iter()
        .map(|w| {
            if k < 3 {
                w[j].force[k]
            } else {
                w[j].moment[k - 3]
            }
        })
        .collect()
}

/// Per differentiated output: the largest error of its series against the extrapolated
/// differences of whole runs, relative to the largest |derivative| of the series (a
/// derivative crossing zero has no relative error of its own), or, if larger, to 1e-4 of the
/// output's size over the parameter's: differences of whole runs cannot resolve a
/// derivative below that (the solves' roundoff over δ; on the spherical pendulum the pivot's
/// vertical force, 9.81 N, moves by 1.6e-6 N per metre of length, differenced to 6e-10 N).
/// Quaternion components are not compared at outputs where a run's `qw` is within 0.05 of
/// zero: the recorded quaternion is the one with `qw ≥ 0`, which changes sign there, so
/// runs on either side of the flip do not difference.
fn errors(s: &Sensitivities, parameter: &str, run: &Runs<'_>, p: f64) -> Vec<(String, f64)> {
    let d = DELTA * p.abs();
    let at = |k: f64| run(&[(parameter.to_string(), p + k * d)]);
    let runs = [at(-2.0), at(-1.0), at(1.0), at(2.0)];
    assert_eq!(runs[0].t, s.t, "the same output times");
    let mut out = Vec::new();
    for o in &s.outputs {
        let f: Vec<Vec<f64>> = runs.iter().map(|r| series(r, o)).collect();
        let flips: Vec<bool> = match o.rsplit_once('.') {
            Some((body, part)) if part.starts_with('q') => {
                let w: Vec<Vec<f64>> = runs
                    .iter()
                    .map(|r| series(r, &format!("{body}.qw")))
                    .collect();
                (0..s.t.len())
                    .map(|k| w.iter().any(|w| w[k].abs() < 0.05))
                    .collect()
            }
            _ => vec![false; s.t.len()],
        };
        let fd: Vec<f64> = (0..s.t.len())
            .map(|k| {
                let c1 = (f[2][k] - f[1][k]) / (2.0 * d);
                let c2 = (f[3][k] - f[0][k]) / (4.0 * d);
                (4.0 * c1 - c2) / 3.0
            })
            .collect();
        let ours = s.series(o, parameter).unwrap();
        let size = f[1].iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let slope = fd.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        if slope < 1e-9 {
            assert!(
                ours.iter().all(|v| v.abs() < 1e-7),
                "{o}/{parameter}: differences ≈ 0, ours {:e}",
                ours.iter().fold(0.0f64, |m, v| m.max(v.abs()))
            );
            continue;
        }
        let scale = slope.max(1e-4 * size / p.abs());
        let err = (0..s.t.len())
            .filter(|&k| !flips[k])
            .fold(0.0f64, |m, k| m.max((ours[k] - fd[k]).abs()));
        out.push((o.clone(), err / scale));
    }
    out
}

fn worst<'a>(errors: impl Iterator<Item = &'a (String, f64)>) -> f64 {
    errors.fold(0.0f64, |m, (_, e)| m.max(*e))
}

/// The paper's scene on its kinematic path: the six actuator efforts (and the platform's
/// pose and every joint's wrench) with respect to platform radius, leg mass and payload.
#[test]
fn paper_scene_kinematic_path_against_whole_run_differences() {
    let e = entry("stewart_6_6");
    let t_end = std::f64::consts::TAU;
    let span = Span {
        formulation: Formulation::Exact,
        t_end,
        output_step: 0.01,
    };
    let names: Vec<String> = ["r_platform", "m_cyl", "m_platform"]
        .map(String::from)
        .into();
    let s = sensitivity::kinematic(e, span, &[], &names).unwrap();
    assert_eq!(s.t.len(), 630);
    let run = |set: &[(String, f64)]| {
        let derived = files::reparametrized(e, set).unwrap();
        let opts = Options {
            formulation: Some(Formulation::Exact),
            t_end: Some(t_end),
            output_step: 0.01,
            ..Options::default()
        };
        generic::run_kinematic(derived, &opts).unwrap()
    };
    for p in &names {
        let errs = errors(&s, p, &run, value(e, p));
        let efforts: Vec<_> = errs.iter().filter(|(o, _)| o.starts_with("act")).collect();
        let (all, acts) = (worst(errs.iter()), worst(efforts.iter().copied()));
        println!(
            "{p}: {} series, worst {all:.2e}; efforts {acts:.2e}",
            errs.len()
        );
        assert_eq!(efforts.len(), 6, "{p}: all six efforts move");
        assert!(all <= 1e-6, "{p}: {all:e}");
    }
}

/// An integrated run's sensitivities against the extrapolated differences of whole runs.
fn integrated(e: &Entry, parameters: &[&str], t_end: f64) -> Vec<(String, f64)> {
    // Newton to roundoff, so the runs the reference differences are smooth in p: at the
    // default tolerances (|Φ| ≤ 1e-10) their differences over δ are noise of 1e-4.
    let opts = Options {
        t_end: Some(t_end),
        newton_tolerance: Some(1e-13),
        ..Options::default()
    };
    let names: Vec<String> = parameters.iter().map(|p| p.to_string()).collect();
    let s = sensitivity::integrated(e, &opts, &[], &names).unwrap();
    let run = |set: &[(String, f64)]| {
        generic::run(files::reparametrized(e, set).unwrap(), &opts).unwrap()
    };
    names
        .iter()
        .map(|p| {
            let errs = errors(&s, p, &run, value(e, p));
            for (o, err) in &errs {
                if *err > 1e-7 {
                    println!("  {o}/{p}: {err:.2e}");
                }
            }
            (p.clone(), worst(errs.iter()))
        })
        .collect()
}

#[test]
fn spherical_pendulum_over_five_seconds_against_whole_run_differences() {
    for (p, err) in integrated(entry("spherical_pendulum"), &["l", "m", "i_t"], 5.0) {
        println!("spherical_pendulum {p}: worst {err:.2e}");
        assert!(err <= 1e-6, "{p}: {err:e}");
    }
}

#[test]
fn bricard_over_two_seconds_against_whole_run_differences() {
    for (p, err) in integrated(entry("bricard"), &["m", "i_cross"], 2.0) {
        println!("bricard {p}: worst {err:.2e}");
        assert!(err <= 1e-6, "{p}: {err:e}");
    }
}

/// A file no code was generated for, interpreted: each load of it finds its slots again
/// (and roundoff may list a few others), so the neighbours' run-time values are read in the
/// base's layout. Geometry: the base and platform joint radii and the platform's height.
#[test]
fn an_interpreted_file_against_whole_run_differences() {
    let e = files::load(std::path::Path::new("examples/mechanisms/three_rps.toml"))
        .unwrap()
        .entry;
    for (p, err) in integrated(e, &["r_b", "r_p", "height"], 1.0) {
        println!("three_rps {p}: worst {err:.2e}");
        assert!(err <= 1e-6, "{p}: {err:e}");
    }
}

/// `--sensitivities` on the command line: the table's columns, the values of the library's
/// pass, and an unknown name refused before anything runs.
#[test]
fn command_line_writes_sensitivities_csv_and_refuses_unknown_names() {
    const BIN: &str = env!("CARGO_BIN_EXE_symbody");
    let dir = std::env::temp_dir().join(format!("symbody-sens-cli-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = std::process::Command::new(BIN)
        .args([
            "simulate",
            "spherical_pendulum",
            "--t-end",
            "0.2",
            "--no-plots",
        ])
        .args(["--sensitivities", "l,m", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(dir.join("sensitivities.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(&header[..3], ["t", "bob.x/l", "bob.x/m"]);
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 21);
    let opts = Options {
        t_end: Some(0.2),
        ..Options::default()
    };
    let names = ["l", "m"].map(String::from);
    let s = sensitivity::integrated(entry("spherical_pendulum"), &opts, &[], &names).unwrap();
    for (row, (t, ours)) in rows.iter().zip(s.t.iter().zip(&s.rows)) {
        assert_eq!(row[0], *t);
        for (a, b) in row[1..].iter().zip(ours) {
            assert!((a - b).abs() <= 1e-12 * b.abs().max(1.0), "{a} vs {b}");
        }
    }

    let _ = std::fs::remove_dir_all(&dir);
    let out = std::process::Command::new(BIN)
        .args([
            "simulate",
            "spherical_pendulum",
            "--no-plots",
            "--sensitivities",
            "ll",
        ])
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("no parameter `ll` (did you mean `l`?)"),
        "{err}"
    );
    assert!(!dir.join("bodies.csv").exists(), "refused before the run");
}
