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
        (
            "parameters = { r = [0.1] }\nmetrics = [\"energy_balance\", \"max|motr|\"]",
            "did you mean `max|motor|`?",
        ),
        (
            "parameters = { r = [0.1] }\nmetrics = [\"max fk_condition\"]",
            "no six-leg platform",
        ),
        (
            "parameters = { r = [0.1] }\nmetrics = [\"max crank.z\", \"max crank.z\"]",
            "listed twice",
        ),
        ("parameters = { r = [0.1] }\nmetrics = []", "no metric"),
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
    // A metric's mistake is located at its name: line 4, the second string from column 30.
    let scene = dir.join("s8.toml");
    let (_, _, stderr) = study(&scene, &dir.join("o8"), &[]);
    assert!(stderr.contains("s8.toml:4:30"), "{stderr}");
    // A scene without a study says how to write one.
    let scene = dir.join("plain.toml");
    std::fs::write(&scene, "mechanism = \"slider_crank\"\n").unwrap();
    let (ok, _, stderr) = study(&scene, &dir.join("plain"), &[]);
    assert!(!ok && stderr.contains("no [study] table"), "{stderr}");
}

/// The size of `png` and, among its pixels, the share and the number of distinct colours
/// that are saturated (a heat map's cells and colour bar; curves and text are thin).
fn colours(png: &Path) -> ((u32, u32), f64, usize) {
    let decoder = png::Decoder::new(std::fs::File::open(png).unwrap());
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let frame = reader.next_frame(&mut buf).unwrap();
    assert_eq!(frame.color_type, png::ColorType::Rgb);
    let pixels: Vec<[u8; 3]> = buf[..frame.buffer_size()]
        .chunks(3)
        .map(|c| [c[0], c[1], c[2]])
        .collect();
    let saturated: Vec<[u8; 3]> = pixels
        .iter()
        .copied()
        .filter(|p| p.iter().max().unwrap() - p.iter().min().unwrap() > 40)
        .collect();
    let share = saturated.len() as f64 / pixels.len() as f64;
    let mut distinct = saturated;
    distinct.sort_unstable();
    distinct.dedup();
    ((frame.width, frame.height), share, distinct.len())
}

#[test]
fn two_parameters_draw_heat_maps_one_draws_curves() {
    let dir = temp_dir("heat");
    let scene = dir.join("crank.toml");
    std::fs::write(&scene, CRANK).unwrap();
    let (ok, _, stderr) = study(&scene, &dir.join("two"), &[]);
    assert!(ok, "{stderr}");
    // One map (the largest driver effort, the default metrics name no other) of the
    // 4 × 2 grid: its cells and colour bar cover a good part of the picture in many colours.
    let (size, share, distinct) = colours(&dir.join("two/study.png"));
    assert_eq!(size, (900, 360 + 60));
    assert!(share > 0.25 && distinct >= 50, "{share} {distinct}");
    let one = dir.join("one.toml");
    std::fs::write(
        &one,
        "mechanism = \"slider_crank\"\n[time]\nend = 0.5\n[study]\n\
         parameters = { r = [0.08, 0.1, 0.12] }\n",
    )
    .unwrap();
    let (ok, _, stderr) = study(&one, &dir.join("one"), &[]);
    assert!(ok, "{stderr}");
    let (_, share, _) = colours(&dir.join("one/study.png"));
    assert!(share < 0.05, "curves, not cells: {share}");
}

#[test]
fn named_metrics_are_those_of_the_scenes_own_run() {
    let dir = temp_dir("named");
    let head = "mechanism = \"stewart_6_6\"\nformulation = \"exact\"\n[time]\nend = 0.6\n\
                output_step = 0.05\n[outputs]\nposes = \"none\"\nreactions = \"none\"\n";
    let metrics = [
        "max fk_condition",
        "max platform.z",
        "min platform.x",
        "max|act2|",
        "min fk_condition",
    ];
    let scene = dir.join("platform.toml");
    std::fs::write(
        &scene,
        format!(
            "{head}[study]\nparameters = {{ r_platform = [0.1, 0.11], m_cyl = [0.2, 0.4] }}\n\
             metrics = {metrics:?}\n"
        ),
    )
    .unwrap();
    let (ok, _, stderr) = study(&scene, &dir, &[]);
    assert!(ok, "{stderr}");
    let text = std::fs::read_to_string(dir.join("study.csv")).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    assert_eq!(header[..3], ["run", "m_cyl", "r_platform"]);
    assert_eq!(header[3..8], metrics, "the scene's order");
    assert_eq!(header[8..], ["status", "error", "wall_s"]);
    // Four maps, the most a picture takes: the largest actuator force, then the named metrics
    // other than the drivers' in their order.
    let (size, share, _) = colours(&dir.join("study.png"));
    assert_eq!(size, (900, 4 * 360 + 60));
    assert!(share > 0.25, "{share}");
    for row in rows(&dir.join("study.csv")) {
        assert_eq!(row[8], "ok", "{row:?}");
        let value = |k: usize| row[k].parse::<f64>().unwrap();
        // The scene's own run with the row's parameters, asking for the platform's pose and
        // the efforts: its bodies.csv columns and drivers.csv, recomputed here.
        let own = format!(
            "{head}[parameters]\nm_cyl = {}\nr_platform = {}\n",
            row[1], row[2]
        )
        .replace("poses = \"none\"", "poses = [\"platform\"]");
        let parsed = symbody::scene::load(&REGISTRY, "own.toml", &own).unwrap();
        let rec = match symbody::scene::run(&parsed, parsed.entry).unwrap().1 {
            symbody::scene::Outcome::Tables(rec) => rec,
            _ => unreachable!("tables"),
        };
        let info = rec.info;
        let platform = info.platform.expect("a six-leg platform");
        let b = platform.body;
        let z = rec.poses.iter().map(|p| p[b].0[2]).fold(f64::MIN, f64::max);
        let x = rec.poses.iter().map(|p| p[b].0[0]).fold(f64::MAX, f64::min);
        let act2 = rec.efforts.iter().fold(0.0f64, |m, e| m.max(e[1].abs()));
        assert_eq!(info.joints[rec.drivers[1]].name, "act2");
        let conditions: Vec<f64> = rec
            .poses
            .iter()
            .map(|p| {
                let (c, [w, i, j, k]) = p[b];
                let turn = nalgebra::UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(
                    w, i, j, k,
                ));
                symbody_testkit::platform::fk_condition(
                    platform.legs,
                    nalgebra::Vector3::from(c),
                    *turn.to_rotation_matrix().matrix(),
                )
            })
            .collect();
        let worst = conditions.iter().copied().fold(0.0, f64::max);
        let best = conditions.iter().copied().fold(f64::INFINITY, f64::min);
        let close = |got: f64, want: f64, tol: f64, what: &str| {
            assert!(
                (got - want).abs() <= tol * want.abs().max(1e-3),
                "{row:?} {what}: {got} vs {want}"
            )
        };
        close(value(3), worst, 1e-6, "max fk_condition");
        close(value(7), best, 1e-6, "min fk_condition");
        assert!(
            worst > best,
            "the platform's conditioning changes over the run"
        );
        // Two mechanisms derived alike (the study's and the scene's), both exact to roundoff.
        close(value(4), z, 1e-9, "max platform.z");
        close(value(5), x, 1e-9, "min platform.x");
        close(value(6), act2, 1e-9, "max|act2|");
    }
}
