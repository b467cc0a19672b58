//! Joint reaction forces and actuator forces from the Lagrange multipliers, with the sign
//! convention of DESIGN decision 7 (`M q̈ + Φqᵀλ = Q`).

use crate::error::{check_len, Error};
use crate::mechanism::{JointKind, MechanismInfo};

/// Force (global X, Y, Z) that joint `joint` exerts on body `body`: `−(Φᵏ_{r_i})ᵀ λᵏ`, where
/// `Φᵏ_{r_i}` are the joint's rows of `Φq` in the body's three translational columns.
///
/// `phi_q` holds the Jacobian's nonzeros at the state the multipliers `lambda` belong to.
pub fn joint_force(
    info: &MechanismInfo,
    phi_q: &[f64],
    lambda: &[f64],
    joint: usize,
    body: usize,
) -> Result<[f64; 3], Error> {
    check_len("Φq nonzeros", info.phi_q_nnz(), phi_q.len())?;
    check_len("lambda", info.n_constraints, lambda.len())?;
    let j = info.joints.get(joint).ok_or(Error::InvalidIndex {
        what: "joint",
        index: joint,
        reason: "no such joint",
    })?;
    let b = info.bodies.get(body).ok_or(Error::InvalidIndex {
        what: "body",
        index: body,
        reason: "no such body",
    })?;
    if j.body1 != Some(body) && j.body2 != Some(body) {
        return Err(Error::InvalidIndex {
            what: "body",
            index: body,
            reason: "the joint does not connect this body",
        });
    }
    let rows = j.row_start..j.row_start + j.rows;
    let cols = b.coord_offset..b.coord_offset + 3;
    let mut f = [0.0; 3];
    for ((&r, &c), &v) in info.phi_q_rows.iter().zip(info.phi_q_cols).zip(phi_q) {
        let (r, c) = (r as usize, c as usize);
        if rows.contains(&r) && cols.contains(&c) {
            f[c - cols.start] -= v * lambda[r];
        }
    }
    Ok(f)
}

/// Force of a driver (a one-row joint of kind [`JointKind::Driver`]): `−λ` of its row.
/// For a driver written as distance minus `c(t)` this is the force along the driven
/// direction, positive pushing the bodies apart.
pub fn actuator_force(info: &MechanismInfo, lambda: &[f64], joint: usize) -> Result<f64, Error> {
    check_len("lambda", info.n_constraints, lambda.len())?;
    let j = info.joints.get(joint).ok_or(Error::InvalidIndex {
        what: "joint",
        index: joint,
        reason: "no such joint",
    })?;
    if j.kind != JointKind::Driver || j.rows != 1 {
        return Err(Error::InvalidIndex {
            what: "joint",
            index: joint,
            reason: "not a one-row driver",
        });
    }
    lambda
        .get(j.row_start)
        .map(|l| -l)
        .ok_or(Error::InvalidIndex {
            what: "constraint row",
            index: j.row_start,
            reason: "driver row outside λ",
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::{InitialVelocity, Kinematics};
    use crate::kkt::SchurKkt;
    use crate::mechanism::Mechanism;
    use crate::testmodels::{
        CircleDriver, Pendulum, CIRCLE_C0, CIRCLE_D, CIRCLE_MASS, G, PENDULUM_MASS,
    };

    fn start<M: Mechanism>(mech: &M) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let info = mech.info();
        let mut kin = Kinematics::<SchurKkt>::new(info).unwrap();
        let mut q = info.q0.to_vec();
        let (mut qd, mut qdd) = (vec![0.0; info.n_coords], vec![0.0; info.n_coords]);
        let mut lam = vec![0.0; info.n_constraints];
        kin.consistent_start(
            mech,
            0.0,
            InitialVelocity::LeastKineticEnergy,
            &mut q,
            &mut qd,
            &mut qdd,
            &mut lam,
        )
        .unwrap();
        let mut pq = vec![0.0; info.phi_q_nnz()];
        mech.phi_q(&q, 0.0, &mut pq);
        (q, pq, lam)
    }

    #[test]
    fn hanging_pendulum_is_held_up_by_its_weight() {
        // At rest the pivot must carry the weight: force on the bob = +m g along +Y.
        let mech = Pendulum::paper();
        let (_, pq, lam) = start(&mech);
        let f = joint_force(mech.info(), &pq, &lam, 0, 0).unwrap();
        let w = PENDULUM_MASS * G;
        assert!(f[0].abs() < 1e-12 && f[2].abs() < 1e-12, "{f:?}");
        assert!((f[1] - w).abs() < 1e-12 * w, "{f:?}");
    }

    #[test]
    fn lift_driver_pushes_the_slider_up() {
        // At t = 0 the slider sits at (d, 0.4) with Ÿ = (ċ² − Ẏ²)/Y; the driver pushes
        // along the radius with vertical share Y/c of m(g + Ÿ).
        let mech = CircleDriver;
        let (_, pq, lam) = start(&mech);
        let y = 0.4;
        let cd = -crate::testmodels::CIRCLE_V;
        let yd = CIRCLE_C0 * cd / y;
        let ydd = (cd * cd - yd * yd) / y;
        let expect = CIRCLE_MASS * (G + ydd) * CIRCLE_C0 / y;
        let a = actuator_force(mech.info(), &lam, 1).unwrap();
        assert!((a - expect).abs() < 1e-9 * expect, "{a} vs {expect}");
        // The guide only pushes horizontally against the driver's X share.
        let g = joint_force(mech.info(), &pq, &lam, 0, 0).unwrap();
        assert!((g[0] + expect * CIRCLE_D / CIRCLE_C0).abs() < 1e-9 * expect);
        assert!(g[1].abs() < 1e-12);
    }

    #[test]
    fn bad_indices_are_errors() {
        let mech = CircleDriver;
        let (_, pq, lam) = start(&mech);
        let info = mech.info();
        assert!(actuator_force(info, &lam, 0).is_err());
        assert!(actuator_force(info, &lam, 9).is_err());
        assert!(joint_force(info, &pq, &lam, 0, 3).is_err());
        assert!(joint_force(info, &pq[1..], &lam, 0, 0).is_err());
    }
}
