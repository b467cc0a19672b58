//! Planar models against the spatial models they come from: the driven `four_bar`, the IFToMM
//! A01 pendulum, the A02 chains of 2 and 40 four-bars and A03's squeezing mechanism integrated
//! both ways with the benchmark's settings follow the same motion. The spatial model is the independent
//! reference here: it holds the plane with its joint rows, where the planar model pins it.

use symbody_bench::iftomm::integrate_with;
use symbody_runtime::kkt::DEFAULT_PIVOT_TOLERANCE;
use symbody_runtime::HhtBuilder;

/// Every full coordinate and velocity at `outputs + 1` times, integrated on the planar model
/// (read back on the spatial one) or on the spatial model.
fn run(name: &str, step: f64, t_end: f64, outputs: usize, planar: bool) -> Vec<Vec<f64>> {
    let builder = HhtBuilder::new()
        .step(step)
        .alpha(0.0)
        .project_velocities(true)
        .drop_dependent_rows(DEFAULT_PIVOT_TOLERANCE);
    let mut samples = Vec::new();
    integrate_with(name, builder, planar, t_end, outputs, |_, q, qd| {
        samples.push(q.iter().chain(qd).copied().collect());
        Ok(())
    })
    .unwrap_or_else(|e| panic!("{name} (planar: {planar}): {e}"));
    samples
}

/// The largest difference of any coordinate or velocity between the two runs, and the largest
/// magnitude of any of them in the spatial run.
fn largest_difference(name: &str, step: f64, t_end: f64, outputs: usize) -> (f64, f64) {
    // Two models: the planar one has three coordinates per body where the spatial has six.
    let entry = symbody_bench::REGISTRY.find(name).unwrap();
    let (planar_model, _) = entry.reduced(entry.formulations[0].0).unwrap();
    let (np, ns) = (
        planar_model.info().n_coords,
        entry.default_mechanism().info().n_coords,
    );
    assert_eq!(2 * np, ns, "{name}");
    let planar = run(name, step, t_end, outputs, true);
    let spatial = run(name, step, t_end, outputs, false);
    assert_eq!(planar.len(), spatial.len());
    let worst = planar
        .iter()
        .zip(&spatial)
        .flat_map(|(a, b)| a.iter().zip(b).map(|(x, y)| (x - y).abs()))
        .fold(0.0, f64::max);
    let scale = spatial
        .iter()
        .flatten()
        .fold(0.0_f64, |m, x| m.max(x.abs()));
    eprintln!("{name}: planar against spatial over {t_end} s, largest difference {worst:.2e} (largest value {scale:.2e})");
    (worst, scale)
}

#[test]
fn the_driven_four_bar_turns_alike_in_its_plane_and_in_space() {
    assert!(largest_difference("four_bar", 1e-3, 2.0, 40).0 < 1e-9);
}

#[test]
fn the_pendulum_swings_alike_in_its_plane_and_in_space() {
    // 2 s at A01's step: both integrate the same equations for x, y and γ (the plane's rows
    // have no x, y or γ derivative), so they differ by the Newton tolerance, not by h².
    assert!(largest_difference("simple_pendulum", 1.25e-4, 2.0, 40).0 < 1e-9);
}

#[test]
fn the_squeezer_moves_alike_in_its_plane_and_in_space() {
    // IFToMM A03: seven bodies and ten hinges, the crank spun up from rest against the
    // stiff spring; 0.01 s at 5 µs, the crank reaching 712 rad/s. Unlike the models above
    // the two do not run the same arithmetic here (z and the out-of-plane angles are
    // coordinates held by rows in one and absent from the other, and the spring's length
    // and the motor's work depend on them), so they agree to roundoff carried over 2 000
    // steps, not bitwise: measured 1.27e-8 rad/s, 1.8e-11 of the largest value.
    let (worst, scale) = largest_difference("andrews_squeezer", 5e-6, 0.01, 20);
    assert!(worst < 1e-10 * scale, "{worst:e} of {scale:e}");
}

#[test]
fn two_four_bars_move_alike_through_four_flat_positions() {
    // A02 with N = 2 at its benchmark's step, across its first four flat positions (0.7, 1.2,
    // 2.7 and 3.2 s), where each loop's rows are dependent for an instant.
    assert!(largest_difference("n_four_bar_2", 4e-4, 3.5, 70).0 < 1e-9);
}

#[test]
fn forty_four_bars_move_alike_in_their_plane_and_in_space() {
    assert!(largest_difference("n_four_bar_40", 4e-4, 0.6, 20).0 < 1e-6);
}

/// `symbody simulate --reduced` integrates the planar model and writes the tables the spatial
/// run writes; a mechanism without a reduced model is an error that says why.
#[test]
fn simulate_reduced_writes_the_spatial_runs_tables() {
    let bin = env!("CARGO_BIN_EXE_symbody");
    let dir = std::env::temp_dir().join(format!("symbody-reduced-{}", std::process::id()));
    let simulate = |extra: &[&str], out: &str| {
        let o = std::process::Command::new(bin)
            .args([
                "simulate",
                "four_bar",
                "--t-end",
                "0.5",
                "--no-plots",
                "--out",
            ])
            .arg(dir.join(out))
            .args(extra)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8_lossy(&o.stdout).to_string()
    };
    let summary = simulate(&["--reduced"], "planar");
    assert!(
        summary.contains("reduced model    9 coordinates integrated (of 18)"),
        "{summary}"
    );
    simulate(&[], "spatial");
    for table in ["bodies.csv", "joints.csv", "drivers.csv"] {
        let read = |run: &str| std::fs::read_to_string(dir.join(run).join(table)).unwrap();
        assert_eq!(read("planar"), read("spatial"), "{table}");
    }
    let o = std::process::Command::new(bin)
        .args([
            "simulate",
            "bricard",
            "--reduced",
            "--t-end",
            "0.1",
            "--no-plots",
            "--out",
        ])
        .arg(dir.join("bricard"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && err.contains("`bricard` has no reduced model"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
