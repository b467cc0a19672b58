//! A04, Bricard's overconstrained mechanism, measured by its energy balance.
//!
//! Nothing dissipates or drives it, so T + V is constant in the exact motion: its drift is
//! an error measure that needs no reference solution. The published reference trajectory
//! of P3 (the joint at (1, −1, 0) at t = 0) is not reproduced here.

use super::Error;
use super::{energy, integrate, Outcome, Problem, Published, Settings, Spec};

const MECHANISM: &str = "bricard";
/// Outputs at which the energy is compared (every 10 ms).
const OUTPUT_STEP: f64 = 0.01;

pub static PROBLEM: Problem = Problem {
    spec: Spec {
        id: "A04",
        title: "Bricard's mechanism (redundant constraints)",
        mechanism: MECHANISM,
        t_end: 10.0,
        short_t_end: 2.0,
        measure: "largest |T + V − E₀| over outputs every 10 ms (J)",
        tolerance: 1e-3,
        caveat: "the UDC page's length, tolerance and reference trajectory (point P3) were not found: 10 s is the ports' length, the measure (energy drift) and tolerance are ours",
        reference: "conservation of energy (no dissipation, no drive)",
        source: "http://lim.ii.udc.es/mbsbenchmark/dist/A04/A04_specification.xml",
        published: &[Published {
            code: "OpenSim 3.2",
            cpu_seconds: 0.258,
            machine: "Intel Core i5-4570 3.2 GHz",
            source: "rehabenggroup.github.io/MBSbenchmarksInOpenSim, A04",
        }],
    },
    settings: SETTINGS,
    run,
};

/// α = 0 conserves energy (velocities projected after each step keep it stable); α < 0
/// would damp it by design and so fail a measure of drift.
const SETTINGS: Settings = Settings {
    step: 1e-3,
    alpha: 0.0,
    tolerances: None,
    reuse_factorization: false,
    planar: false,
};

fn run(t_end: f64, settings: Settings) -> Result<Outcome, Error> {
    let outputs = (t_end / OUTPUT_STEP).round().max(1.0) as usize;
    let mut e0 = None;
    let mut error = 0.0_f64;
    let (cpu, stats) = integrate(MECHANISM, settings, t_end, outputs, |_, q, qd| {
        let e = energy(MECHANISM, q, qd)?;
        error = error.max((e - *e0.get_or_insert(e)).abs());
        Ok(())
    })?;
    Ok(Outcome {
        t_end,
        error,
        cpu,
        stats,
        step: settings.step,
        alpha: settings.alpha,
    })
}
