//! `symbody fk` and the forward-kinematics library against independent references: the
//! paper's scenario (its actuator law typed in from docs/paper-scenario.md, its pose tracked
//! by the 78-coordinate dynamics), Dietmaier's published geometry (lengths recomputed from
//! each reported pose), and a leg-length path that must cross a parallel singularity.

use nalgebra::{Rotation3, Vector3};
use std::process::Command;
use symbody::fk::{self, Request};
use symbody::scenario::{simulate, Options};
use symbody_benchmark_mechanisms::find;
use symbody_runtime::fk::{Legs, Pose};
use symbody_runtime::Error;

// docs/paper-scenario.md, Tables 1 and 2, typed in independently of the mechanism file.
const BASE_DEG: [f64; 6] = [10.5, 109.5, 130.5, 229.5, 250.5, 349.5];
const PLATFORM_DEG: [f64; 6] = [49.5, 70.5, 169.5, 190.5, 289.5, 310.5];
const AMPLITUDE: [f64; 6] = [0.02, -0.06, 0.02, -0.02, 0.08, -0.02];
const Y0: f64 = 0.3466575;

fn point(r: f64, deg: f64) -> Vector3<f64> {
    let a = deg.to_radians();
    Vector3::new(r * a.cos(), 0.0, -r * a.sin())
}

fn paper_legs() -> Legs {
    Legs {
        base: BASE_DEG.map(|d| point(0.27, d)),
        top: PLATFORM_DEG.map(|d| point(0.105, d)),
    }
}

fn home() -> Pose {
    Pose::from_euler([0.0, Y0, 0.0], [0.0, 0.0, 0.0])
}

/// The paper's actuator law: each leg grows by aᵢ sin t from its length at the home pose.
fn paper_lengths(t: f64) -> [f64; 6] {
    let l0 = paper_legs().lengths(&home());
    std::array::from_fn(|i| l0[i] + AMPLITUDE[i] * t.sin())
}

fn symbody(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_symbody"))
        .args(args)
        .output()
        .expect("the symbody binary runs")
}

#[test]
fn the_generator_finds_the_paper_platform_legs() {
    let p = fk::platform(find("stewart_6_6").unwrap()).unwrap();
    let reference = paper_legs();
    for i in 0..6 {
        assert!((p.legs().base[i] - reference.base[i]).norm() < 1e-15);
        assert!((p.legs().top[i] - reference.top[i]).norm() < 1e-15);
    }
    for t in [0.0, 0.7, 2.0, 4.5] {
        let (a, b) = (p.lengths_at(t), paper_lengths(t));
        for i in 0..6 {
            assert!(
                (a[i] - b[i]).abs() < 1e-14,
                "t = {t}, leg {i}: {} vs {}",
                a[i],
                b[i]
            );
        }
    }
    assert!(fk::platform(find("four_bar").unwrap()).is_err());
}

/// The dynamics track the pose with 78 coordinates and 72 rows; `fk` solves six equations
/// from the home pose. Both must give the same pose.
#[test]
fn fk_agrees_with_the_pose_tracked_by_the_paper_scenario() {
    let run = simulate(&symbody_benchmark_mechanisms::REGISTRY, &Options::default()).unwrap();
    let p = fk::platform(find("stewart_6_6").unwrap()).unwrap();
    let n = run.t.len() - 1;
    let mut worst = 0.0_f64;
    for k in 1..=10 {
        let i = k * n / 10;
        let t = run.t[i];
        let req = Request {
            lengths: Some(paper_lengths(t)),
            from: Some(home()),
            at: 0.0,
        };
        let a = fk::solve(&p, &req).unwrap();
        let [x, y, z, th, be, ga] = run.platform[i];
        let r = Rotation3::from_axis_angle(&Vector3::z_axis(), ga)
            * Rotation3::from_axis_angle(&Vector3::y_axis(), be)
            * Rotation3::from_axis_angle(&Vector3::x_axis(), th);
        let s = a.tracked.solution;
        let dp = (s.pose.position - Vector3::new(x, y, z)).amax();
        let dr = (s.pose.rotation - r.matrix()).amax();
        worst = worst.max(dp).max(dr);
        assert!(s.residual <= 1e-13, "t = {t}: residual {}", s.residual);
    }
    assert!(worst <= 1e-12, "largest pose difference {worst:e}");
}

#[test]
fn fk_all_finds_dietmaiers_forty_real_poses() {
    let out = std::env::temp_dir().join(format!("symbody-fk-{}", std::process::id()));
    let o = symbody(&[
        "fk",
        "dietmaier_6_6",
        "--all",
        "--out",
        out.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(stdout.contains("40 real of 40 complex"), "{stdout}");
    let csv = std::fs::read_to_string(out.join("assembly_modes.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "mode,x,y,z,r11,r12,r13,r21,r22,r23,r31,r32,r33,cond,current"
    );
    // Dietmaier's data, typed in from the mechanism file's source.
    let v = Vector3::new;
    let base = [
        v(0.0, 0.0, 0.0),
        v(1.107915, 0.0, 0.0),
        v(0.549094, 0.756063, 0.0),
        v(0.735077, -0.223935, 0.525991),
        v(0.514188, -0.526063, -0.368418),
        v(0.590473, 0.094733, -0.205018),
    ];
    let top = [
        v(0.0, 0.0, 0.0),
        v(0.542805, 0.0, 0.0),
        v(0.956919, -0.528915, 0.0),
        v(0.665885, -0.353482, 1.402538),
        v(0.478359, 1.158742, 0.107672),
        v(-0.137087, -0.235121, 0.353913),
    ];
    let lengths = [1.0, 0.645275, 1.086284, 1.503439, 1.281933, 0.771071];
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 40);
    // Numbered from 1 in the CSV, and the summary names the current mode by that number.
    for (k, r) in rows.iter().enumerate() {
        assert_eq!(r[0], (k + 1) as f64, "row {k}");
    }
    let current: Vec<&Vec<f64>> = rows.iter().filter(|r| r[14] == 1.0).collect();
    assert_eq!(current.len(), 1);
    let said = format!("current          mode {} of 40 ", current[0][0]);
    assert!(stdout.contains(&said), "`{said}` not in\n{stdout}");
    for r in &rows {
        let p = v(r[1], r[2], r[3]);
        let rot = nalgebra::Matrix3::from_row_slice(&r[4..13]);
        for i in 0..6 {
            // The CSV's 17 significant digits carry the pose to roundoff.
            let l = (p + rot * top[i] - base[i]).norm();
            assert!(
                (l - lengths[i]).abs() <= 1e-10,
                "leg {i}: {l} vs {}",
                lengths[i]
            );
        }
    }
    std::fs::remove_dir_all(&out).ok();
}

/// Shortening every leg of the paper's platform to 0.1 m lowers it into the base plane, where
/// the legs' lines become coplanar (a parallel singularity) and the branch folds back: no
/// pose at all has these lengths. `fk` must say so, with where along the path continuation
/// stopped, instead of answering with a pose of another mode.
#[test]
fn fk_reports_the_singularity_between_the_start_and_the_requested_lengths() {
    let o = symbody(&["fk", "stewart_6_6", "--lengths", "0.1,0.1,0.1,0.1,0.1,0.1"]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(stderr.contains("parallel singularity"), "{stderr}");
    // No mode at all has these lengths (every one of the 28 is complex), so that is the
    // answer, with where the continuation stopped.
    assert!(stderr.contains("no real pose"), "{stderr}");

    let p = fk::platform(find("stewart_6_6").unwrap()).unwrap();
    let start = p.pose(p.q0()).unwrap();
    let l0 = p.legs().lengths(&start);
    let line = |s: f64| std::array::from_fn(|i| l0[i] + s * (0.1 - l0[i]));
    match symbody_runtime::fk::track(p.legs(), line, &start, 0.0, 1.0, Default::default()) {
        Err(Error::PlatformSingularity {
            time,
            condition,
            switched,
            ..
        }) => {
            assert!(time > 0.0 && time < 1.0, "path parameter {time}");
            assert!(condition > 1e3, "condition {condition}");
            assert!(!switched, "stopped before passing it");
            assert!(stderr.contains(&format!("t = {time:.6}")), "{stderr}");
        }
        other => panic!("expected a platform singularity, got {other:?}"),
    }
}

/// Continuation keeps the start's assembly mode. The paper's platform twisted by 100° about
/// the vertical is past the 90° singularity, on another mode; by the geometry's symmetry the
/// 80° twist at another height has the same lengths (checked here from the poses alone), and
/// that is the pose continuation from the home pose must reach.
#[test]
fn fk_continuation_stays_on_the_start_mode() {
    let legs = paper_legs();
    let twisted = Pose::from_euler([0.0, Y0, 0.0], [0.0, 100f64.to_radians(), 0.0]);
    let l = legs.lengths(&twisted);
    let p = fk::platform(find("stewart_6_6").unwrap()).unwrap();
    let req = Request {
        lengths: Some(l),
        ..Request::default()
    };
    let s = fk::solve(&p, &req).unwrap().tracked.solution;
    let [_, beta, _] = s.pose.euler_angles();
    assert!((beta - 80f64.to_radians()).abs() < 1e-12, "beta {beta}");
    let reached = legs.lengths(&s.pose);
    assert!((0..6).all(|i| (reached[i] - l[i]).abs() < 1e-13));
    let det = |pose: &Pose| legs.jacobian(pose).determinant();
    assert!(det(&s.pose) * det(&home()) > 0.0 && det(&twisted) * det(&home()) < 0.0);
    // Started on the twisted pose's own side, the same lengths give the twisted pose.
    let past = Pose::from_euler([0.0, Y0, 0.0], [0.0, 95f64.to_radians(), 0.0]);
    let a = fk::solve(
        &p,
        &Request {
            lengths: Some(l),
            from: Some(past),
            at: 0.0,
        },
    )
    .unwrap();
    assert!(a.tracked.solution.pose.distance(&twisted, 0.1) < 1e-12);
}

/// The dynamics' watch: a platform state past the twist singularity (another assembly mode)
/// is refused with the time, and the start state is accepted.
#[test]
fn simulations_refuse_a_platform_state_on_another_assembly_mode() {
    use symbody_runtime::fk::ModeWatch;
    let mech = find("stewart_6_6").unwrap().default_mechanism();
    let p = fk::platform(find("stewart_6_6").unwrap()).unwrap();
    let info = mech.info();
    let watch = ModeWatch::new(&p, info.q0, 1e8).unwrap();
    assert!(watch.check(info.q0, 0.0).is_ok());
    let mut q = info.q0.to_vec();
    // The paper platform's Euler angles θ, β, γ follow its position; β turns about the vertical.
    let beta = p.body().coord_offset + 4;
    q[beta] = 100f64.to_radians();
    match watch.check(&q, 1.25) {
        Err(Error::PlatformSingularity { time, switched, .. }) => {
            assert_eq!(time, 1.25);
            assert!(switched);
        }
        other => panic!("expected a platform singularity, got {other:?}"),
    }
    q[beta] = 90f64.to_radians();
    let r = watch.check(&q, 1.0);
    assert!(matches!(r, Err(Error::PlatformSingularity { .. })), "{r:?}");
}

#[test]
fn fk_over_time_follows_the_paper_period_and_bad_options_are_named() {
    let out = std::env::temp_dir().join(format!("symbody-fk-ot-{}", std::process::id()));
    let o = symbody(&[
        "fk",
        "stewart_6_6",
        "--over-time",
        "2",
        "--no-plots",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let csv = std::fs::read_to_string(out.join("assembly_modes_over_time.csv")).unwrap();
    let rows: Vec<Vec<f64>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 3);
    for r in &rows {
        // Every sample has the tracked mode among an even number of real modes (the planar
        // base and platform pair each pose with its mirror image through the base plane).
        assert!(r[1] >= 2.0 && r[1] % 2.0 == 0.0, "{r:?}");
        assert!(r[3] > 1.0 && r[3] < 10.0, "condition {}", r[3]);
    }
    std::fs::remove_dir_all(&out).ok();

    let o = symbody(&["fk", "stewart_6_6", "--lengths", "0.4,0.4"]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && stderr.contains("--lengths needs six"),
        "{stderr}"
    );
    let o = symbody(&["fk", "four_bar"]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && stderr.contains("no six-leg platform"),
        "{stderr}"
    );
}

/// `hexapod_twist` drives the paper's platform geometry into its 90° twist singularity at
/// t = 1.8 s (the twist rate is 50°/s; that the 90° twist is singular for this geometry is
/// checked here from the legs' Jacobian alone). The simulation must stop just before, with the
/// time, a condition number past the limit and all six legs, while the forces it recorded up
/// to then stay finite.
#[test]
fn a_driver_path_into_a_parallel_singularity_stops_the_simulation_first() {
    let legs = paper_legs();
    let twist = |deg: f64| Pose::from_euler([0.0, Y0, 0.0], [0.0, deg.to_radians(), 0.0]);
    let det = |deg: f64| legs.jacobian(&twist(deg)).determinant();
    assert!(
        det(89.9) * det(90.1) < 0.0,
        "90° twist is where the determinant changes sign"
    );

    let entry = find("hexapod_twist").unwrap();
    let err = symbody::generic::run(entry, &symbody::generic::Options::default()).unwrap_err();
    match err {
        symbody::scenario::ScenarioError::Runtime(Error::PlatformSingularity {
            time,
            condition,
            legs,
            switched,
        }) => {
            assert!((1.78..1.8).contains(&time), "stopped at t = {time}");
            assert!(condition >= symbody_runtime::fk::SIMULATION_MAX_CONDITION);
            assert_eq!(legs, vec![1, 2, 3, 4, 5, 6]);
            assert!(!switched);
        }
        other => panic!("expected a platform singularity, got {other}"),
    }
    // Up to 1.7 s the run is regular and its leg forces finite.
    let rec = symbody::generic::run(
        entry,
        &symbody::generic::Options {
            t_end: Some(1.7),
            ..Default::default()
        },
    )
    .unwrap();
    assert!(rec.efforts.iter().flatten().all(|f| f.is_finite()));
}

/// Leg lengths of 100 m on Dietmaier's platform (legs about 1 m): no pose has them.
/// Reference: every assembly mode at these lengths from the homotopy of
/// `symbody_runtime::fk::assembly_modes` (checked against Dietmaier's 40 real poses above),
/// all complex. `fk` must say no pose has these lengths, not blame a parallel singularity at
/// t = 0.001461 as if another leg-length path could get there; `--all` must fail instead of
/// writing an empty table.
#[test]
fn fk_says_no_pose_has_unreachable_lengths() {
    let p = fk::platform(find("dietmaier_6_6").unwrap()).unwrap();
    let far = [100.0; 6];
    let modes = symbody_runtime::fk::assembly_modes(p.legs(), &far).unwrap();
    assert!(
        modes.real.is_empty() && modes.complex > 0,
        "{} real",
        modes.real.len()
    );

    let o = symbody(&[
        "fk",
        "dietmaier_6_6",
        "--lengths",
        "100,100,100,100,100,100",
    ]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(
        stderr.contains("no real pose of the platform has the leg lengths")
            && stderr.contains("cannot reach"),
        "{stderr}"
    );
    assert!(!stderr.contains("change the leg-length path"), "{stderr}");

    let out = std::env::temp_dir().join(format!("symbody-fk-far-{}", std::process::id()));
    let o = symbody(&[
        "fk",
        "dietmaier_6_6",
        "--lengths",
        "100,100,100,100,100,100",
        "--all",
        "--out",
        out.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success(), "--all with 0 real modes must fail");
    assert!(stderr.contains("no real assembly mode"), "{stderr}");
    assert!(!out.join("assembly_modes.csv").exists());
    std::fs::remove_dir_all(&out).ok();
}

/// `fk` on a mechanism without a six-leg platform says so in the mechanism's terms and names
/// the ones that have one (from `symbody list`'s FK column, read here), not the runtime's
/// "invalid platform index 0".
#[test]
fn fk_on_a_mechanism_without_a_platform_names_the_ones_with_one() {
    let o = symbody(&["fk", "four_bar"]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(!stderr.contains("index"), "{stderr}");
    assert!(
        stderr.contains("`four_bar` has no six-leg platform"),
        "{stderr}"
    );
    let list = String::from_utf8_lossy(&symbody(&["list"]).stdout).into_owned();
    let with: Vec<&str> = list
        .lines()
        .skip(1)
        .filter(|l| l.split_whitespace().last() == Some("yes"))
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    assert!(with.contains(&"stewart_6_6"), "{list}");
    for name in with {
        assert!(stderr.contains(name), "{name} missing: {stderr}");
    }
}
