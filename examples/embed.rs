//! Embedding a generated mechanism in your own program: integrate the Stewart platform with
//! HHT-α and read the actuator forces, with nothing but the runtime and the generated crate.
//! Run with `cargo run --release --example embed`.

use symbody_mechanisms::stewart_6_6::Exact;
use symbody_runtime::{actuator_force, Error, HhtBuilder, Kinematics};

fn main() -> Result<(), Error> {
    // Consistent start (positions, least-energy velocities, accelerations, multipliers).
    let mut sim = HhtBuilder::new().alpha(-0.05).step(2e-3).build(Exact)?;
    let info = sim.info();
    let drivers: Vec<usize> = (1..=6)
        .map(|i| {
            info.joint_index(&format!("act{i}"))
                .expect("the model has act1..act6")
        })
        .collect();
    // The reactions of a state, from [M Φqᵀ; Φq 0][q̈; λ] = [Q; γ].
    let mut kinematics: Kinematics = Kinematics::new(info)?;
    let (mut qdd, mut lambda) = (vec![0.0; info.n_coords], vec![0.0; info.n_constraints]);
    for k in 1..=4 {
        let t = 0.5 * k as f64;
        sim.advance_to(t)?;
        kinematics.acceleration(sim.mechanism(), t, sim.q(), sim.qd(), &mut qdd, &mut lambda)?;
        let forces = drivers
            .iter()
            .map(|&j| actuator_force(info, &lambda, j))
            .collect::<Result<Vec<f64>, Error>>()?;
        println!(
            "t = {t:.1} s  platform y = {:.5} m  actuator forces (N): {forces:.3?}",
            sim.q()[1]
        );
    }
    println!("{:?}", sim.stats());
    Ok(())
}
