//! The generated solver inside a user's own program, used as a controller would: a 1 kHz loop
//! that steps the paper's Stewart platform once per cycle and reads the six actuator forces
//! and one joint's reaction wrench, without allocating in the loop. Beside it the controller
//! keeps its own model of the platform for feedforward (the forces the commanded motion
//! needs) and retunes it when the payload changes at t = 0.5 s: a run-time parameter of the
//! generated code, set in the loop without allocating and without regenerating anything.
//!
//! Run with `cargo run --release --example embed`. It prints leg 1's force at t = 1 s in the
//! same format as the C example (`examples/c/`) and the Python package, which compute it
//! through `symbody::session`; all three must agree.

use symbody_mechanisms::stewart_6_6::{self, Exact, ExactAt};
use symbody_runtime::{driver_effort, joint_wrench, HhtBuilder, Kinematics, Mechanism};
use symbody_testkit::alloc::CountingAllocator;

// Counts heap allocations, so the example can show its control loop makes none.
#[global_allocator]
static GLOBAL: CountingAllocator = CountingAllocator;

type Error = Box<dyn std::error::Error>;

/// What the loop measured.
struct Report {
    leg1_at_1s: f64,
    /// Leg 1's feedforward force at t = 1 s, with the heavier payload.
    feedforward_leg1_at_1s: f64,
    /// Largest |feedforward − simulated| actuator force before the payload changed.
    feedforward_gap_before: f64,
    allocations_in_loop: usize,
    cycles: usize,
}

/// The payload the platform picks up at t = 0.5 s (kg).
const PAYLOAD: f64 = 0.5;

fn control_loop(print: bool) -> Result<Report, Error> {
    // Consistent start (position, velocity, acceleration, multipliers), then HHT-α with the
    // settings `symbody::session::Settings::default()` uses.
    let mut sim = HhtBuilder::new().alpha(-0.05).step(1e-3).build(Exact)?;
    let info = sim.info();
    // Everything the loop needs, allocated once.
    let mut kinematics: Kinematics = Kinematics::new(info)?;
    let (mut qdd, mut lambda) = (vec![0.0; info.n_coords], vec![0.0; info.n_constraints]);
    let mut phi_q = vec![0.0; info.phi_q_nnz()];
    let mut actuators = [0usize; 6];
    for (i, a) in actuators.iter_mut().enumerate() {
        *a = info
            .joint_index(&format!("act{}", i + 1))
            .expect("the file names act1..6");
    }
    let sphere = info
        .joint_index("upper_sph1")
        .expect("the file names upper_sph1");
    let mut forces = [0.0; 6];
    // The controller's model: the file's platform mass until the payload is picked up.
    let mut model: ExactAt = Exact::with_parameters(&[])?;
    let m_platform = stewart_6_6::PARAMETERS
        .iter()
        .position(|n| *n == "m_platform")
        .map(|i| stewart_6_6::PARAMETER_VALUES[i])
        .expect("the file names m_platform");
    let (mut qdd_model, mut lambda_model) = (qdd.clone(), lambda.clone());
    let mut feedforward = [0.0; 6];
    let mut feedforward_gap_before = 0.0f64;

    let mut cycles = 0;
    let mut run = || -> Result<(), Error> {
        // One accepted 1 ms step per cycle up to t = 1 s (the last one shortened to land on it:
        // the same steps `advance_to(1.0)` takes, so the bindings' single call gives the same
        // numbers).
        while sim.step_toward(1.0)?.is_some() {
            cycles += 1;
            let (t, q, qd) = (sim.t(), sim.q(), sim.qd());
            // The multipliers of this state: [M Φqᵀ; Φq 0][q̈; λ] = [Q; γ].
            kinematics.acceleration(sim.mechanism(), t, q, qd, &mut qdd, &mut lambda)?;
            for (f, &j) in forces.iter_mut().zip(&actuators) {
                *f = driver_effort(info, &lambda, j)?;
            }
            // The gripper closes at cycle 500 (t = 0.5 s): the model carries the payload from
            // now on. Feedforward on the model: the forces the same motion needs with it.
            if cycles == 500 {
                model.0.set(&[("m_platform", m_platform + PAYLOAD)])?;
            }
            kinematics.acceleration(&model, t, q, qd, &mut qdd_model, &mut lambda_model)?;
            for (f, &j) in feedforward.iter_mut().zip(&actuators) {
                *f = driver_effort(info, &lambda_model, j)?;
            }
            if cycles < 500 {
                for (a, b) in feedforward.iter().zip(&forces) {
                    feedforward_gap_before = feedforward_gap_before.max((a - b).abs());
                }
            }
            if cycles % 250 == 0 && print {
                sim.mechanism().phi_q(q, t, &mut phi_q);
                let w = joint_wrench(info, q, &phi_q, &lambda, sphere)?;
                // Printing allocates; the count below comes from a pass that does not print.
                println!(
                    "t = {t:.3} s  actuators [N]: {:8.4} {:8.4} {:8.4} {:8.4} {:8.4} {:8.4}  \
                 upper_sph1 on the platform: ({:.4}, {:.4}, {:.4}) N",
                    forces[0],
                    forces[1],
                    forces[2],
                    forces[3],
                    forces[4],
                    forces[5],
                    w.force[0],
                    w.force[1],
                    w.force[2]
                );
            }
        }
        Ok(())
    };
    let mut result = Ok(());
    let allocations_in_loop = CountingAllocator::count(|| result = run());
    result?;
    Ok(Report {
        leg1_at_1s: forces[0],
        feedforward_leg1_at_1s: feedforward[0],
        feedforward_gap_before,
        allocations_in_loop,
        cycles,
    })
}

fn main() -> Result<(), Error> {
    // One silent pass counts the loop's allocations without the printing.
    let silent = control_loop(false)?;
    let r = control_loop(true)?;
    println!(
        "{} control cycles at 1 kHz, {} heap allocations in the loop",
        silent.cycles, silent.allocations_in_loop
    );
    println!("leg 1 force at t = 1 s: {:.15e} N", r.leg1_at_1s);
    println!(
        "feedforward with the {PAYLOAD} kg payload picked up at t = 0.5 s: leg 1 {:.4} N at \
         t = 1 s (before it: within {:.1e} N of the simulation)",
        r.feedforward_leg1_at_1s, r.feedforward_gap_before
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `cargo test` builds and runs this example (`test = true` in Cargo.toml): the loop
    /// allocates nothing, the payload change included, and its number is the one
    /// `symbody::session` gives (which the C and Python bindings print), bit for bit.
    #[test]
    fn the_control_loop_allocates_nothing_and_matches_the_session() {
        let r = control_loop(false).unwrap();
        assert_eq!(r.allocations_in_loop, 0);
        // Before the payload, the model is the simulated platform: the same forces exactly.
        assert_eq!(r.feedforward_gap_before, 0.0);
        // With it, the forces differ (tests/run_time_parameters.rs checks them against
        // Newton's law for the platform).
        assert!(
            (r.feedforward_leg1_at_1s - r.leg1_at_1s).abs() > 1e-2,
            "{} vs {}",
            r.feedforward_leg1_at_1s,
            r.leg1_at_1s
        );
        let s = symbody::session::paper_leg1_force_at_1s(&symbody_mechanisms::REGISTRY).unwrap();
        assert_eq!(
            r.leg1_at_1s.to_bits(),
            s.to_bits(),
            "{:e} vs {s:e}",
            r.leg1_at_1s
        );
    }
}
