//! The generated solver inside a user's own program: integrate the paper's Stewart platform
//! for half a second and print its actuator forces and one joint's reaction wrench.
//!
//! Run with `cargo run --release --example embed`.

use symbody_mechanisms::stewart_6_6::Exact;
use symbody_runtime::{driver_effort, joint_wrench, Error, HhtBuilder, Kinematics, Mechanism};

fn main() -> Result<(), Error> {
    // Consistent start (position, velocity, acceleration and multipliers), then HHT-α.
    let mut sim = HhtBuilder::new().alpha(-0.05).step(2e-3).build(Exact)?;
    let info = sim.info();
    let mut kinematics: Kinematics = Kinematics::new(info)?;
    let (mut qdd, mut lambda) = (vec![0.0; info.n_coords], vec![0.0; info.n_constraints]);
    let mut phi_q = vec![0.0; info.phi_q_nnz()];
    for k in 1..=5 {
        let t = 0.1 * k as f64;
        sim.advance_to(t)?; // lands exactly on t
                            // The multipliers of this state: [M Φqᵀ; Φq 0][q̈; λ] = [Q; γ].
        kinematics.acceleration(sim.mechanism(), t, sim.q(), sim.qd(), &mut qdd, &mut lambda)?;
        sim.mechanism().phi_q(sim.q(), t, &mut phi_q);
        let forces: Vec<String> = (1..=6)
            .map(|i| {
                let j = info
                    .joint_index(&format!("act{i}"))
                    .expect("the file names act1..6");
                driver_effort(info, &lambda, j).map(|f| format!("{f:8.4}"))
            })
            .collect::<Result<_, _>>()?;
        let sph = info
            .joint_index("upper_sph1")
            .expect("the file names upper_sph1");
        let w = joint_wrench(info, sim.q(), &phi_q, &lambda, sph)?;
        println!(
            "t = {t:.1} s  actuators [N]: {}  upper_sph1 on the platform: F = ({:.4}, {:.4}, {:.4}) N",
            forces.join(" "),
            w.force[0],
            w.force[1],
            w.force[2]
        );
    }
    Ok(())
}
