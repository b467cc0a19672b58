//! A new user's mechanism files run without building: the four files in examples/mechanisms/,
//! written from published definitions, pass `symbody check` with the rank and mobility their
//! theory gives, and `symbody simulate <file>` runs them to the end with the constraints held
//! and, for the undriven ones, energy conserved.

use std::path::PathBuf;
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_symbody");

fn file(stem: &str) -> String {
    format!(
        "{}/examples/mechanisms/{stem}.toml",
        env!("CARGO_MANIFEST_DIR")
    )
}

/// `symbody check <file>`: its stdout, after asserting success.
fn check(stem: &str) -> String {
    let out = Command::new(BIN)
        .args(["check", &file(stem)])
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    stdout
}

/// Asserts that `text` has a line equal to `line` once trimmed.
fn has_line(text: &str, line: &str) {
    assert!(
        text.lines().any(|l| l.trim() == line),
        "no line `{line}` in:\n{text}"
    );
}

/// The run's summary and output folder after `symbody simulate <file> --t-end 1 --no-plots`,
/// asserting success and a run to t = 1.
fn simulate(stem: &str) -> (String, PathBuf) {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("user_files-{stem}"));
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(BIN)
        .args([
            "simulate",
            &file(stem),
            "--t-end",
            "1",
            "--no-plots",
            "--out",
        ])
        .arg(&dir)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.contains("0 .. 1.000000 s"), "{stdout}");
    (stdout, dir)
}

/// The first number after `key` on the summary line that starts with `key`.
fn number_after(summary: &str, key: &str) -> f64 {
    let line = summary
        .lines()
        .map(str::trim)
        .find(|l| l.starts_with(key))
        .unwrap_or_else(|| panic!("no `{key}` line in:\n{summary}"));
    line[key.len()..]
        .split_whitespace()
        .next()
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("no number after `{key}` in `{line}`"))
}

/// max |Phi| from the summary.
fn max_phi(summary: &str) -> f64 {
    number_after(summary, "max |Phi|")
}

/// The ratio in `energy balance   max |dT + dV - W| = <J> J on a scale of <J> J (<ratio>)`.
fn energy_ratio(summary: &str) -> f64 {
    let line = summary
        .lines()
        .find(|l| l.trim().starts_with("energy balance"))
        .unwrap_or_else(|| panic!("no energy balance line in:\n{summary}"));
    let ratio = line
        .rsplit_once('(')
        .and_then(|(_, r)| r.strip_suffix(')'))
        .unwrap_or_else(|| panic!("no (ratio) in `{line}`"));
    ratio.parse().unwrap()
}

/// One column of a CSV by its header name.
fn column(path: &PathBuf, name: &str) -> Vec<f64> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let at = lines
        .next()
        .unwrap()
        .split(',')
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {}", path.display()));
    lines
        .filter(|l| !l.is_empty())
        .map(|l| l.split(',').nth(at).unwrap().parse().unwrap())
        .collect()
}

#[test]
fn three_rps_has_three_dof_and_none_with_its_three_leg_drivers() {
    // Bodies: platform + 3 legs of 2 parts = 7; quaternions: 7 * 7 = 49 coordinates.
    // Rows: 3 revolutes (5) + 3 prismatics (5) + 3 sphericals (3) = 39, + 3 drivers + 7 unit
    // quaternions = 49. Grübler: 6 * 7 - 39 = 3 (heave and two tilts of a 3-RPS), no
    // redundancy, so rank 49 and 0 DOF once the three leg lengths are driven.
    let report = check("three_rps");
    has_line(
        &report,
        "three_rps: 7 bodies, 49 coordinates, 49 constraint rows (3 drivers), rank 49 at the \
         initial pose",
    );
    has_line(
        &report,
        "mobility: Grübler count 3, actual 3 (without drivers); 0 DOF left with drivers",
    );
    has_line(&report, "no redundant rows");

    let (summary, dir) = simulate("three_rps");
    assert!(summary.contains("49 rows, 0 DOF"), "{summary}");
    assert!(max_phi(&summary) < 1e-8, "{summary}");
    // The platform moves: the legs change length by up to 6 cm, so its height changes.
    let z = column(&dir.join("bodies.csv"), "platform.z");
    let span =
        z.iter().cloned().fold(f64::MIN, f64::max) - z.iter().cloned().fold(f64::MAX, f64::min);
    assert!(span > 1e-3, "platform height span {span}");
}

#[test]
fn rsup_slider_crank_has_one_dof_and_its_slider_follows_the_closed_form() {
    // Bodies: crank, rod, slider = 3 (21 coordinates). Rows: R 5 + S 3 + U 4 + P 5 = 17, + 1
    // driver + 3 unit quaternions = 21. Grübler: 6 * 3 - 17 = 1, no redundancy: rank 21, 0 DOF
    // with the crank driven.
    let report = check("rsup_slider_crank");
    has_line(
        &report,
        "rsup_slider_crank: 3 bodies, 21 coordinates, 21 constraint rows (1 driver), rank 21 \
         at the initial pose",
    );
    has_line(
        &report,
        "mobility: Grübler count 1, actual 1 (without drivers); 0 DOF left with drivers",
    );
    has_line(&report, "no redundant rows");

    let (summary, dir) = simulate("rsup_slider_crank");
    assert!(max_phi(&summary) < 1e-8, "{summary}");
    // The file's header: s = r cos θ + sqrt(len² − e_x² − (r sin θ − e_z)²), θ = 2π t.
    let (r, len, e_x, e_z) = (0.08_f64, 0.3_f64, 0.06_f64, 0.04_f64);
    let bodies = dir.join("bodies.csv");
    let (t, s) = (column(&bodies, "t"), column(&bodies, "slider.y"));
    assert_eq!(t.len(), 101);
    for (t, s) in t.iter().zip(&s) {
        let th = 2.0 * std::f64::consts::PI * t;
        let want = r * th.cos() + (len * len - e_x * e_x - (r * th.sin() - e_z).powi(2)).sqrt();
        assert!(
            (s - want).abs() < 1e-9,
            "t = {t}: slider at {s}, closed form {want}"
        );
    }
}

#[test]
fn parallelogram_four_bar_has_three_redundant_rows_and_conserves_energy() {
    // Bodies: crank, coupler, rocker = 3 (21 coordinates). Rows: 4 revolutes (5) = 20 + 3
    // unit quaternions = 23. Grübler: 6 * 3 - 20 = -2; a planar loop has 3 rows too many in
    // space (the out-of-plane ones), so the rank is 23 - 3 = 20 and the mobility 21 - 20 = 1.
    let report = check("parallelogram_four_bar");
    has_line(
        &report,
        "parallelogram_four_bar: 3 bodies, 21 coordinates, 23 constraint rows (0 drivers), \
         rank 20 at the initial pose",
    );
    has_line(
        &report,
        "mobility: Grübler count -2, actual 1 (without drivers); 1 DOF left with drivers",
    );
    assert!(report.contains("3 redundant row(s)"), "{report}");

    let (summary, dir) = simulate("parallelogram_four_bar");
    assert!(max_phi(&summary) < 1e-8, "{summary}");
    assert!(energy_ratio(&summary) < 1e-6, "{summary}");
    // A parallelogram's coupler translates: it stays horizontal (quaternion z part 0).
    let qz = column(&dir.join("bodies.csv"), "coupler.qz");
    assert!(qz.iter().all(|q| q.abs() < 1e-9), "coupler turned: {qz:?}");
    // And it swings: the crank is no longer hanging straight down at t = 0.25 s.
    let x = column(&dir.join("bodies.csv"), "crank.x");
    assert!(x[25] > 0.03, "crank centre x at 0.25 s: {}", x[25]);
}

#[test]
fn bricard_loop_moves_with_mobility_one_despite_a_grubler_count_of_zero() {
    // Bodies: 5 bars (35 coordinates); the ground is the sixth link. Rows: 6 revolutes (5) =
    // 30 + 5 unit quaternions = 35. Grübler: 6 * 5 - 30 = 0, but a line-symmetric Bricard loop
    // moves with 1 DOF: exactly one row is redundant, rank 34.
    let report = check("bricard_loop");
    has_line(
        &report,
        "bricard_loop: 5 bodies, 35 coordinates, 35 constraint rows (0 drivers), rank 34 at the \
         initial pose",
    );
    has_line(
        &report,
        "mobility: Grübler count 0, actual 1 (without drivers); 1 DOF left with drivers",
    );
    assert!(report.contains("1 redundant row(s)"), "{report}");

    let (summary, dir) = simulate("bricard_loop");
    assert!(summary.contains("35 rows, 1 DOF"), "{summary}");
    assert!(max_phi(&summary) < 1e-8, "{summary}");
    assert!(energy_ratio(&summary) < 1e-6, "{summary}");
    // It does move from rest: kinetic energy well above roundoff within the first second.
    let kinetic = column(&dir.join("energy.csv"), "kinetic");
    assert!(kinetic.iter().cloned().fold(0.0, f64::max) > 0.05);
}
