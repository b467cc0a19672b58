//! A02, the N-four-bar mechanism (N = 2 and the published N = 40), measured against its
//! one-coordinate equation of motion.
//!
//! On the parallelogram branch every crank turns by the same angle φ and every coupler
//! translates with the cranks' tips, so T = ½·((N+1)·mL²/3 + N·mL²)·φ̇² and
//! V = ((N+1)·mgL/2 + N·mgL)·sin φ: one ordinary differential equation, integrated here
//! with classical RK4, independent of the generated constraint equations. The published
//! difficulty is that the mechanism crosses positions where it could leave that branch.

use super::Error;
use super::{
    integrate_with, point, point_velocity, rk4_step, Outcome, Problem, Published, Settings, Spec,
};
use symbody_runtime::kkt::DEFAULT_PIVOT_TOLERANCE;

const G: f64 = 9.81;
const L: f64 = 1.0;
const M: f64 = 1.0;
/// Published: 400 outputs over 20 s.
const OUTPUT_STEP: f64 = 20.0 / 400.0;
/// Local position of B0, the tip of the first crank (local x runs along the crank).
const B0: [f64; 3] = [0.5 * L, 0.0, 0.0];

const SOURCE: &str = "http://lim.ii.udc.es/mbsbenchmark/dist/A02/A02_specification.xml";
const MEASURE: &str = "largest |Δ| of B0's x, y (m) and ẋ, ẏ (m/s) over 400 outputs";

pub static PROBLEM_2: Problem = Problem {
    spec: Spec {
        id: "A02 (N = 2)",
        title: "two four-bar mechanism (Bayo & Avello's original)",
        mechanism: "n_four_bar_2",
        t_end: 20.0,
        // All of it: about a second, across all 20 flat positions.
        short_t_end: 20.0,
        measure: MEASURE,
        tolerance: 1e-3,
        caveat: "the library publishes N = 40; same length and measure here. The formula behind \"400 output steps and a threshold of 1e-3\" was not found; the largest absolute difference is used",
        reference: "one-coordinate equation of motion of the parallelogram branch, RK4",
        source: SOURCE,
        published: &[Published {
            code: "OpenSim 3.2 (10 s of the 20 s)",
            cpu_seconds: 0.455,
            machine: "Intel Core i5-4570 3.2 GHz",
            source: "rehabenggroup.github.io/MBSbenchmarksInOpenSim, A02",
        }],
    },
    settings: SETTINGS_PLANAR,
    run: run_2,
};

pub static PROBLEM_40: Problem = Problem {
    spec: Spec {
        id: "A02 (N = 40)",
        title: "N-four-bar mechanism, as published",
        mechanism: "n_four_bar_40",
        t_end: 20.0,
        // Across the first two flat positions (0.72 s and 1.24 s).
        short_t_end: 1.5,
        measure: MEASURE,
        tolerance: 1e-3,
        caveat: "the formula behind \"400 output steps and a threshold of 1e-3\" was not found; the largest absolute difference is used",
        reference: "one-coordinate equation of motion of the parallelogram branch, RK4",
        source: SOURCE,
        published: &[],
    },
    settings: SETTINGS_PLANAR,
    run: run_40,
};

/// α = 0 (the trapezoidal rule): numerical damping (α < 0) shortens the swings and costs
/// more than the tolerance over 20 s (3.9e-1 at α = −0.05). The error is the trapezoidal
/// rule's phase error and falls as h² (BENCHMARKS.md: 3.8e-3 at h = 1e-3, 8.2e-4 at 5e-4,
/// 5.2e-4 at 4e-4 for N = 2); 4e-4 leaves half the tolerance as margin.
const SETTINGS: Settings = Settings {
    step: 4e-4,
    alpha: 0.0,
    tolerances: None,
    reuse_factorization: false,
    planar: false,
};

/// Both run their planar models (the files say `planar = true`): 243 coordinates and 242
/// rows instead of 486 and 605 for N = 40, 15 and 14 instead of 30 and 35 for N = 2, the same
/// motion (tests/planar_models.rs).
const SETTINGS_PLANAR: Settings = Settings {
    planar: true,
    ..SETTINGS
};

fn run_2(t_end: f64, settings: Settings) -> Result<Outcome, Error> {
    run(2, t_end, settings)
}

fn run_40(t_end: f64, settings: Settings) -> Result<Outcome, Error> {
    run(40, t_end, settings)
}

fn run(n: usize, t_end: f64, settings: Settings) -> Result<Outcome, Error> {
    let name = format!("n_four_bar_{n}");
    let outputs = (t_end / OUTPUT_STEP).round().max(1.0) as usize;
    let mut samples = Vec::with_capacity(outputs + 1);
    let builder = settings
        .builder()
        // At a flat position the rows of each loop are dependent for an instant; a step that
        // lands there drops the rows whose pivot is below the rank-loss threshold (they must
        // still hold). Steps near it are accepted at the roundoff floor (`Stats::noise_limited`).
        .drop_dependent_rows(DEFAULT_PIVOT_TOLERANCE);
    let (cpu, stats) = integrate_with(
        &name,
        builder,
        settings.planar,
        t_end,
        outputs,
        |t, q, qd| {
            let p = point(&name, "crank0", B0, q)?;
            let v = point_velocity(&name, "crank0", B0, q, qd)?;
            samples.push((t, [p[0], p[1], v[0], v[1]]));
            Ok(())
        },
    )?;
    let times: Vec<f64> = samples.iter().map(|s| s.0).collect();
    let reference = reference(n, &times);
    let error = samples
        .iter()
        .zip(&reference)
        .flat_map(|((_, s), r)| s.iter().zip(r).map(|(a, b)| (a - b).abs()))
        .fold(0.0, f64::max);
    Ok(Outcome {
        t_end,
        error,
        cpu,
        stats,
        step: settings.step,
        alpha: settings.alpha,
    })
}

/// B0's `[x, y, ẋ, ẏ]` at each of `times` (ascending, from 0) on the parallelogram branch,
/// from φ(0) = π/2 (cranks vertical) and φ̇(0) = −1/L (B0 at +1 m/s along x).
pub fn reference(n: usize, times: &[f64]) -> Vec<[f64; 4]> {
    // RK4's error at this step is below 1e-8 over 20 s (checked by halving in the tests).
    reference_with_step(n, times, 1e-4)
}

fn reference_with_step(n: usize, times: &[f64], h_max: f64) -> Vec<[f64; 4]> {
    let nf = n as f64;
    let inertia = (nf + 1.0) * M * L * L / 3.0 + nf * M * L * L;
    let moment = ((nf + 1.0) * M * G * L / 2.0 + nf * M * G * L) / inertia;
    let f = |phi: f64| -moment * phi.cos();
    let (mut phi, mut w, mut t) = (std::f64::consts::FRAC_PI_2, -1.0 / L, 0.0);
    let mut out = Vec::with_capacity(times.len());
    for &t_out in times {
        while t < t_out {
            let h = h_max.min(t_out - t);
            rk4_step(&mut phi, &mut w, h, f);
            t += h;
        }
        let (s, c) = phi.sin_cos();
        out.push([L * c, L * s, -L * s * w, L * c * w]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The reference conserves its energy, and its first turn matches the published motion:
    /// B0 starts at (0, 1) moving at +1 m/s along x.
    #[test]
    fn reference_starts_as_published_and_conserves_energy() {
        let times: Vec<f64> = (0..=400).map(|k| k as f64 * OUTPUT_STEP).collect();
        let r = reference(40, &times);
        let start = [0.0, L, 1.0, 0.0];
        assert!(
            r[0].iter().zip(start).all(|(a, b)| (a - b).abs() < 1e-15),
            "{:?}",
            r[0]
        );
        let nf = 40.0;
        let inertia = (nf + 1.0) * M * L * L / 3.0 + nf * M * L * L;
        let weight = (nf + 1.0) * M * G * L / 2.0 + nf * M * G * L;
        let energy = |b: &[f64; 4]| {
            let w2 = (b[2] * b[2] + b[3] * b[3]) / (L * L);
            0.5 * inertia * w2 + weight * b[1] / L
        };
        let e0 = energy(&r[0]);
        let drift = r.iter().map(|b| (energy(b) - e0).abs()).fold(0.0, f64::max);
        assert!(drift < 1e-9 * e0.abs().max(1.0), "energy drift {drift:e} J");
    }

    /// Halving RK4's step changes the reference by less than 1e-8 (measured 4.4e-9): it is
    /// converged far below the published tolerance of 1e-3.
    #[test]
    fn reference_is_converged() {
        let times: Vec<f64> = (0..=400).map(|k| k as f64 * OUTPUT_STEP).collect();
        let coarse = reference(2, &times);
        let fine = reference_with_step(2, &times, 0.5e-4);
        let diff = coarse
            .iter()
            .zip(&fine)
            .flat_map(|(a, b)| a.iter().zip(b).map(|(x, y)| (x - y).abs()))
            .fold(0.0, f64::max);
        assert!(diff < 1e-8, "{diff:e}");
    }
}
