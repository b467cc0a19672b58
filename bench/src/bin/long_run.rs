//! Long-run stability of the paper's scene: 10⁶ HHT steps (h = 1 ms, α = −0.05, exact
//! formulation, 1000 s ≈ 159 periods of the actuator law), with constraint drift, velocity
//! residual and energy balance sampled every 10 s, and the final state compared with the
//! kinematic path at the same time (exact to roundoff, no integration error to accumulate).
//!
//! `cargo run --release -p symbody-bench --bin long_run [-- --steps N]` writes `bench-results/long_run.{csv,md}`
//! and prints the Markdown. Not run in CI (≈ 1 min).

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Instant;

use symbody_bench::fail;
use symbody_benchmark_mechanisms::stewart_6_6::Exact;
use symbody_runtime::{
    actuator_force, EnergyMeter, HhtBuilder, KinematicPath, Kinematics, Mechanism, ResidualWatch,
};

const STEP: f64 = 1e-3;
const ALPHA: f64 = -0.05;
/// Spacing of the samples written to the CSV (steps).
const SAMPLE_EVERY: usize = 10_000;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let steps: usize = match args.as_slice() {
        [] => 1_000_000,
        [flag, n] if flag == "--steps" => n
            .parse()
            .ok()
            .filter(|&n: &usize| n >= SAMPLE_EVERY)
            .unwrap_or_else(|| fail("--steps needs an integer ≥ 10000")),
        _ => fail("usage: long_run [--steps N]"),
    };
    let info = Exact.info();
    let mut it = HhtBuilder::new()
        .alpha(ALPHA)
        .step(STEP)
        .build(Exact)
        .unwrap_or_else(|e| fail(&e.to_string()));
    let mut meter: EnergyMeter = EnergyMeter::new(info).unwrap_or_else(|e| fail(&e.to_string()));
    let mut watch = ResidualWatch::new(info);
    let first = meter
        .record(&Exact, it.t(), it.q(), it.qd())
        .unwrap_or_else(|e| fail(&e.to_string()));
    let (b0, scale) = (first.balance(), first.kinetic.abs() + first.potential.abs());
    let mut csv =
        String::from("t,steps,max_abs_phi,velocity_residual,energy_balance_J,energy_balance_rel\n");
    let (mut worst_phi, mut worst_vel, mut worst_balance) = (0.0f64, 0.0f64, 0.0f64);
    let clock = Instant::now();
    for k in 1..=steps {
        // Every step lands on k·h, so the meter integrates the actuators' power at the step.
        it.advance_to(k as f64 * STEP)
            .unwrap_or_else(|e| fail(&format!("step {k}: {e}")));
        let sample = meter
            .record(&Exact, it.t(), it.q(), it.qd())
            .unwrap_or_else(|e| fail(&format!("energy at step {k}: {e}")));
        let balance = sample.balance() - b0;
        worst_balance = worst_balance.max(balance.abs());
        if k % SAMPLE_EVERY == 0 {
            let r = watch
                .check(&Exact, it.t(), it.q(), it.qd())
                .unwrap_or_else(|e| fail(&e.to_string()));
            worst_phi = worst_phi.max(r.position);
            worst_vel = worst_vel.max(r.velocity);
            let _ = writeln!(
                csv,
                "{},{k},{:.3e},{:.3e},{:.6e},{:.3e}",
                it.t(),
                r.position,
                r.velocity,
                balance,
                balance / scale
            );
        }
    }
    let wall = clock.elapsed().as_secs_f64();
    let t_end = it.t();

    // The same time on the kinematic path, and the actuator forces of both states.
    let clock = Instant::now();
    let mut path = KinematicPath::<_>::new(Exact, 0.0).unwrap_or_else(|e| fail(&e.to_string()));
    let outputs = (t_end / 0.01).round() as usize;
    for k in 1..=outputs {
        path.advance_to((k as f64 * 0.01).min(t_end))
            .unwrap_or_else(|e| fail(&format!("kinematic path: {e}")));
    }
    let path_wall = clock.elapsed().as_secs_f64();
    let mut kin: Kinematics = Kinematics::new(info).unwrap_or_else(|e| fail(&e.to_string()));
    let (mut qdd, mut lambda) = (vec![0.0; info.n_coords], vec![0.0; info.n_constraints]);
    kin.acceleration(&Exact, t_end, it.q(), it.qd(), &mut qdd, &mut lambda)
        .unwrap_or_else(|e| fail(&e.to_string()));
    let force_error = (1..=6)
        .map(|i| {
            let j = info.joint_index(&format!("act{i}")).unwrap();
            let a = actuator_force(info, &lambda, j).unwrap();
            let b = actuator_force(info, path.lambda(), j).unwrap();
            (a - b).abs()
        })
        .fold(0.0, f64::max);
    let p = info.bodies[info.body_index("platform").unwrap()].coord_offset;
    let pose_error = (0..3)
        .map(|c| (it.q()[p + c] - path.q()[p + c]).abs())
        .fold(0.0, f64::max);

    let stats = it.stats();
    let mut md = String::new();
    let _ = writeln!(
        md,
        "Paper scene, exact formulation, HHT α = {ALPHA}, h = {STEP} s: {} steps to t = {t_end:.1} s \
         ({:.0} periods) in {wall:.1} s wall ({:.2} µs per step with an energy record each step); \
         {} Newton iterations, {} rejected steps.\n",
        stats.steps,
        t_end / (2.0 * std::f64::consts::PI),
        wall / stats.steps as f64 * 1e6,
        stats.newton_iterations,
        stats.rejected_steps
    );
    let _ = writeln!(md, "| measure | worst over the run | at the end |");
    let _ = writeln!(md, "|---|---|---|");
    let last = |col: usize| {
        csv.lines()
            .last()
            .and_then(|l| l.split(',').nth(col))
            .unwrap_or("")
            .to_string()
    };
    let _ = writeln!(
        md,
        "| max \\|Φ\\| (m, rad) | {worst_phi:.2e} | {} |",
        last(2)
    );
    let _ = writeln!(
        md,
        "| \\|Φq q̇ + Φt\\| (m/s, rad/s) | {worst_vel:.2e} | {} |",
        last(3)
    );
    let _ = writeln!(
        md,
        "| \\|ΔT + ΔV − W\\| (J), energy scale {scale:.3} J | {worst_balance:.2e} ({:.1e} of the scale) | {} |",
        worst_balance / scale,
        last(4)
    );
    let _ = writeln!(
        md,
        "| actuator forces vs the kinematic path (N) | | {force_error:.2e} |"
    );
    let _ = writeln!(
        md,
        "| platform position vs the kinematic path (m) | | {pose_error:.2e} |"
    );
    let _ = writeln!(
        md,
        "\nThe kinematic path reached t = {t_end:.1} s through {outputs} output times in {path_wall:.2} s."
    );
    let dir = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../bench-results"));
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| fail(&e.to_string()));
    for (file, text) in [("long_run.csv", &csv), ("long_run.md", &md)] {
        let p = dir.join(file);
        std::fs::write(&p, text).unwrap_or_else(|e| fail(&format!("{}: {e}", p.display())));
        eprintln!("wrote {}", p.display());
    }
    print!("{md}");
}
