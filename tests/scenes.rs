//! Scene files: every shipped scene runs on the path pinned here, every mechanism has one, the
//! outputs are restricted to what a scene asks for, and every file in
//! `tests/scene_files/fail/` is refused with the diagnostic its header states.

use std::path::{Path, PathBuf};
use std::process::Command;

use symbody::scene::{self, Outcome, PathChoice};
use symbody_benchmark_mechanisms::REGISTRY;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn load(path: &Path) -> scene::Scene {
    let text = std::fs::read_to_string(path).unwrap();
    let name = path.strip_prefix(root()).unwrap().display().to_string();
    scene::load(&symbody_benchmark_mechanisms::REGISTRY, &name, &text)
        .unwrap_or_else(|e| panic!("{name}:\n{e}"))
}

/// The path each shipped scene must take: kinematic where the drivers fix every requested
/// output (no free DOF, or the Stewart legs' idle spins), integration where free DOFs carry
/// momentum.
const EXPECTED: [(&str, bool); 15] = [
    ("andrews_squeezer", false),
    ("bricard", false),
    ("dietmaier_6_6", true),
    ("flyball_governor", false),
    ("four_bar", true),
    ("hexapod_twist", true),
    ("n_four_bar_2", false),
    ("n_four_bar_40", false),
    ("oscillators", false),
    ("paper", true),
    ("simple_pendulum", false),
    ("slider_crank", true),
    ("spherical_pendulum", false),
    ("stewart_6_6", true),
    ("ups_stewart", true),
];

#[test]
fn every_shipped_scene_runs_on_its_pinned_path() {
    let mut files: Vec<PathBuf> = std::fs::read_dir(root().join("scenes"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    let names: Vec<String> = files
        .iter()
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    assert_eq!(names, EXPECTED.map(|(n, _)| n.to_string()));
    for e in REGISTRY.iter() {
        assert!(names.iter().any(|n| n == e.name), "no scene for {}", e.name);
    }
    for (path, (name, kinematic)) in files.iter().zip(EXPECTED) {
        let s = load(path);
        let entry = symbody_benchmark_mechanisms::find(s.mechanism).unwrap();
        let (choice, outcome) = scene::run(&s, entry).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(
            matches!(choice, PathChoice::Kinematic { .. }),
            kinematic,
            "{name}: {choice:?}"
        );
        let (max_phi, max_vel) = match &outcome {
            Outcome::Paper(r) => (r.max_phi, r.max_velocity_residual),
            Outcome::Tables(r) => (r.max_phi, r.max_velocity_residual),
        };
        assert!(
            max_phi < 1e-12 && max_vel < 1e-10,
            "{name}: {max_phi:e} {max_vel:e}"
        );
    }
}

#[test]
fn a_scene_writes_only_what_it_asks_for() {
    let s = load(&root().join("scenes/four_bar.toml"));
    let entry = symbody_benchmark_mechanisms::find(s.mechanism).unwrap();
    let (_, outcome) = scene::run(&s, entry).unwrap();
    let Outcome::Tables(rec) = outcome else {
        panic!("four_bar writes tables")
    };
    let names: Vec<&str> = rec
        .joints
        .iter()
        .map(|&j| rec.info.joints[j].name)
        .collect();
    assert_eq!(names, ["a0", "b0"]);
    assert!(rec.wrenches.iter().all(|w| w.len() == 2));
    let stems: Vec<&str> = symbody::generic::tables(&rec)
        .iter()
        .map(|t| t.stem)
        .collect();
    assert_eq!(stems, ["bodies", "joints", "drivers", "energy"]);

    let s = load(&root().join("scenes/dietmaier_6_6.toml"));
    let entry = symbody_benchmark_mechanisms::find(s.mechanism).unwrap();
    let (_, outcome) = scene::run(&s, entry).unwrap();
    let Outcome::Tables(rec) = outcome else {
        panic!("dietmaier writes tables")
    };
    let tables = symbody::generic::tables(&rec);
    let stems: Vec<&str> = tables.iter().map(|t| t.stem).collect();
    // reactions = "none", energy = false: only poses and efforts.
    assert_eq!(stems, ["bodies", "drivers"]);
    assert_eq!(tables[0].columns.len(), 1 + 7, "{:?}", tables[0].columns);
}

#[test]
fn asking_for_the_legs_poses_makes_the_paper_platform_integrate() {
    // The legs' spins move the leg bodies; a kinematic path would leave their spin angles
    // at the predictor's values, so their poses need integration.
    let mut s = load(&root().join("scenes/stewart_6_6.toml"));
    s.poses = scene::Selection::All;
    let mech = symbody::generic::mechanism(
        symbody_benchmark_mechanisms::find(s.mechanism).unwrap(),
        None,
    )
    .unwrap();
    let choice = scene::choose_path(&s, mech).unwrap();
    let PathChoice::Integrate {
        reason: Some(reason),
        ..
    } = choice
    else {
        panic!("{choice:?}")
    };
    assert!(reason.contains("move requested bodies"), "{reason}");

    // Forcing the kinematic path is refused with the same reason.
    s.path = scene::PathRequest::Kinematic;
    let err = scene::choose_path(&s, mech).unwrap_err().to_string();
    assert!(
        err.contains("would not be exact") && err.contains("upper1"),
        "{err}"
    );
}

#[test]
fn bad_scene_files_are_refused_with_place_and_help() {
    let dir = root().join("tests/scene_files/fail");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    assert!(files.len() >= 10);
    for path in files {
        let text = std::fs::read_to_string(&path).unwrap();
        let expect = |key: &str| -> String {
            text.lines()
                .find_map(|l| l.strip_prefix(&format!("# {key}: ")))
                .unwrap_or_else(|| panic!("{} has no `# {key}:` line", path.display()))
                .to_string()
        };
        let (place, message) = {
            let e = expect("error");
            let (p, m) = e.split_once(' ').unwrap();
            (p.to_string(), m.to_string())
        };
        let help = expect("help");
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let errors =
            scene::load(&symbody_benchmark_mechanisms::REGISTRY, &name, &text).expect_err(&name);
        let d = &errors.0[0];
        assert_eq!(format!("{}:{}", d.line, d.column), place, "{name}: {d}");
        assert!(d.message.contains(&message), "{name}: {d}");
        assert!(d.help.contains(&help), "{name}: {d}");
        assert_eq!(d.file, name);
        let shown = errors.to_string();
        assert!(shown.contains(&format!("--> {name}:{place}")), "{shown}");
    }
}

fn symbody(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_symbody"))
        .args(args)
        .current_dir(root())
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn run_writes_the_same_files_as_simulate_and_says_how_it_solved() {
    let dir = std::env::temp_dir().join(format!("symbody-scene-{}", std::process::id()));
    let (a, b) = (dir.join("run"), dir.join("simulate"));
    let (ok, stdout, stderr) = symbody(&[
        "run",
        "scenes/paper.toml",
        "--out",
        a.to_str().unwrap(),
        "--no-plots",
    ]);
    assert!(ok, "{stderr}");
    assert!(
        stdout.contains("path             kinematic (no integration)"),
        "{stdout}"
    );
    assert!(stdout.contains("wall time"), "{stdout}");
    let (ok, _, stderr) = symbody(&["simulate", "--out", b.to_str().unwrap(), "--no-plots"]);
    assert!(ok, "{stderr}");
    for f in ["platform.csv", "joint_forces.csv", "actuators.csv"] {
        let x = std::fs::read_to_string(a.join(f)).unwrap();
        let y = std::fs::read_to_string(b.join(f)).unwrap();
        assert_eq!(x.lines().next(), y.lines().next(), "{f} header");
        assert_eq!(x.lines().count(), y.lines().count(), "{f} rows");
    }
    let _ = std::fs::remove_dir_all(&dir);

    let (ok, _, stderr) = symbody(&["run", "scenes/nothing_here.toml"]);
    assert!(
        !ok && stderr.contains("cannot read scene file scenes/nothing_here.toml"),
        "{stderr}"
    );
    let (ok, _, stderr) = symbody(&["run", "tests/scene_files/fail/unknown_body.toml"]);
    assert!(
        !ok && stderr.contains("--> tests/scene_files/fail/unknown_body.toml:6:9"),
        "{stderr}"
    );
}

#[test]
fn tolerances_in_a_scene_or_on_the_command_line_control_the_step() {
    let dir = std::env::temp_dir().join(format!("symbody-stepctl-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("pendulum.toml");
    std::fs::write(
        &scene,
        "mechanism = \"spherical_pendulum\"\n[time]\nend = 2.0\n[solver]\nstep = 1e-4\nrtol = 1e-5\natol = 1e-6\n",
    )
    .unwrap();
    let text = std::fs::read_to_string(&scene).unwrap();
    let loaded = scene::load(
        &symbody_benchmark_mechanisms::REGISTRY,
        "pendulum.toml",
        &text,
    )
    .unwrap();
    assert_eq!(loaded.tolerances, Some((1e-5, 1e-6)));
    assert_eq!(
        loaded.step, 1e-4,
        "a step beside tolerances is the first step"
    );
    let out = dir.join("run");
    let (ok, stdout, stderr) = symbody(&[
        "run",
        scene.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-plots",
    ]);
    assert!(ok, "{stdout}{stderr}");
    assert!(
        stdout.contains("step-size control rtol 1e-5, atol 1e-6"),
        "{stdout}"
    );
    assert!(stdout.contains("step sizes"), "{stdout}");
    let meta = std::fs::read_to_string(out.join("meta.json")).unwrap();
    assert!(meta.contains("\"rtol\": 0.00001"), "{meta}");
    let out = dir.join("simulate");
    let (ok, stdout, stderr) = symbody(&[
        "simulate",
        "spherical_pendulum",
        "--t-end",
        "1",
        "--rtol",
        "1e-6",
        "--out",
        out.to_str().unwrap(),
        "--no-plots",
    ]);
    assert!(ok, "{stdout}{stderr}");
    assert!(stdout.contains("step sizes"), "{stdout}");
    let (ok, _, stderr) = symbody(&["simulate", "spherical_pendulum", "--rtol", "0"]);
    assert!(
        !ok && stderr.contains("--rtol 0: a tolerance must be positive"),
        "{stderr}"
    );
    // Without tolerances the summary is as before: no step-size line.
    let (ok, stdout, _) = symbody(&[
        "simulate",
        "spherical_pendulum",
        "--t-end",
        "0.1",
        "--out",
        dir.join("fixed").to_str().unwrap(),
        "--no-plots",
    ]);
    assert!(ok && !stdout.contains("step sizes"), "{stdout}");
    std::fs::remove_dir_all(&dir).ok();
}

/// A kinematic scene reads each output's reactions and efforts from the path's own solution
/// of the saddle-point system: they must be what that system, solved afresh at the recorded
/// `(q, q̇)` by an energy meter, gives. A scene without energy solves only at its outputs
/// (one factorization each, plus any full Newton iterations) and reports no energy balance;
/// with energy, the path also solves at the quadrature's two interior times and the balance
/// is integrated.
#[test]
fn kinematic_scenes_record_their_states_reactions_and_solve_only_what_they_write() {
    use symbody_runtime::{driver_effort, joint_wrench, EnergyMeter};
    for (file, energy) in [
        ("scenes/four_bar.toml", true),
        ("scenes/slider_crank.toml", false),
    ] {
        let s = load(&root().join(file));
        assert_eq!(s.energy, energy, "{file}");
        let entry = symbody_benchmark_mechanisms::find(s.mechanism).unwrap();
        let (choice, outcome) = scene::run(&s, entry).unwrap();
        assert!(matches!(choice, PathChoice::Kinematic { .. }), "{file}");
        let Outcome::Tables(rec) = outcome else {
            panic!("{file} writes tables")
        };
        let stats = rec.kinematic.unwrap();
        let outputs = rec.t.len();
        let interior = if energy { 2 * (outputs - 1) } else { 0 };
        assert_eq!(
            stats.factorizations,
            outputs + interior + stats.newton_iterations,
            "{file}: {stats:?}"
        );
        assert_eq!(rec.energy_balance().is_some(), energy, "{file}");

        let mech = symbody::generic::mechanism(entry, Some(s.formulation)).unwrap();
        let info = mech.info();
        let mut meter: EnergyMeter = EnergyMeter::new(info).unwrap();
        let mut worst = 0.0f64;
        let mut scale = 0.0f64;
        for k in 0..outputs {
            meter
                .record(&mech, rec.t[k], &rec.q[k], &rec.qd[k])
                .unwrap();
            for (i, &j) in rec.joints.iter().enumerate() {
                let fresh =
                    joint_wrench(info, &rec.q[k], meter.phi_q(), meter.lambda(), j).unwrap();
                let recorded = rec.wrenches[k][i];
                for (a, b) in fresh.force.iter().zip(&recorded.force) {
                    worst = worst.max((a - b).abs());
                    scale = scale.max(a.abs());
                }
            }
            for (i, &j) in rec.drivers.iter().enumerate() {
                let fresh = driver_effort(info, meter.lambda(), j).unwrap();
                worst = worst.max((fresh - rec.efforts[k][i]).abs());
                scale = scale.max(fresh.abs());
            }
        }
        assert!(scale > 0.0, "{file}: nothing to compare");
        assert!(worst <= 1e-12 * scale, "{file}: {worst:e} of {scale:e}");
    }
}
