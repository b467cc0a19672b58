//! The forward-kinematics view of a generated mechanism whose generator found a six-leg
//! platform ([`crate::PlatformInfo`]): its legs, the leg lengths its drivers prescribe at a
//! time, the platform's pose in the coordinates, and a watch that stops a simulation before
//! its tracked pose can pass to another assembly mode.

use nalgebra::Vector3;

use super::{Legs, Pose};
use crate::error::Error;
use crate::mechanism::{BodyInfo, Mechanism, MechanismInfo, PlatformInfo};
use crate::pose::rotation_matrix;

/// A generated six-leg platform seen as a forward-kinematics problem.
pub struct Platform<'m, M: Mechanism + ?Sized> {
    mechanism: &'m M,
    info: &'static MechanismInfo,
    platform: PlatformInfo,
    legs: Legs,
    /// `|leg(q0)|`: with the driver rows at `q0`, the prescribed length at any time.
    lengths_q0: [f64; 6],
}

impl<'m, M: Mechanism + ?Sized> Platform<'m, M> {
    /// The platform of `mechanism`; [`Error::InvalidIndex`] when its generator found none.
    pub fn new(mechanism: &'m M) -> Result<Self, Error> {
        let info = mechanism.info();
        let not_one = Error::InvalidIndex {
            what: "platform",
            index: 0,
            reason: "the mechanism is not a platform held to the ground by six legs of \
                     driven length (S-P-S or U-P-S legs, or point-distance drivers)",
        };
        let platform = info.platform.ok_or(not_one.clone())?;
        if platform.legs.len() != 6 || platform.body >= info.bodies.len() {
            return Err(not_one);
        }
        let legs = Legs {
            base: std::array::from_fn(|i| Vector3::from(platform.legs[i].base)),
            top: std::array::from_fn(|i| Vector3::from(platform.legs[i].platform)),
        };
        let mut p = Platform {
            mechanism,
            info,
            platform,
            legs,
            lengths_q0: [0.0; 6],
        };
        let home = p.pose(info.q0)?;
        p.lengths_q0 = p.legs.lengths(&home);
        Ok(p)
    }

    /// The file's initial coordinates, on the assembly mode the mechanism starts in.
    pub fn q0(&self) -> &'static [f64] {
        self.info.q0
    }

    pub fn legs(&self) -> &Legs {
        &self.legs
    }

    /// The platform body.
    pub fn body(&self) -> &'static BodyInfo {
        &self.info.bodies[self.platform.body]
    }

    /// The drivers setting the legs' lengths, in leg order.
    pub fn leg_names(&self) -> [&'static str; 6] {
        std::array::from_fn(|i| self.platform.legs[i].driver)
    }

    /// The leg lengths the drivers prescribe at time `t`.
    pub fn lengths_at(&self, t: f64) -> [f64; 6] {
        let mut phi = vec![0.0; self.info.n_constraints];
        self.mechanism.phi(self.info.q0, t, &mut phi);
        std::array::from_fn(|i| self.lengths_q0[i] - phi[self.platform.legs[i].row])
    }

    /// The platform's pose at coordinates `q`.
    pub fn pose(&self, q: &[f64]) -> Result<Pose, Error> {
        pose_of(self.body(), q)
    }
}

/// The pose of `body` at coordinates `q`; an error, not a panic, when `q` is too short.
fn pose_of(body: &BodyInfo, q: &[f64]) -> Result<Pose, Error> {
    let r = q
        .get(body.coord_offset..body.coord_offset + 3)
        .ok_or(Error::InvalidIndex {
            what: "body coordinate",
            index: body.coord_offset,
            reason: "the platform's coordinates lie outside q",
        })?;
    Ok(Pose {
        position: Vector3::new(r[0], r[1], r[2]),
        rotation: rotation_matrix(body, q)?,
    })
}

/// The condition number at which simulations stop a six-leg platform: there the legs
/// amplify load and length errors a thousandfold, and a few milliseconds later (on the
/// hexapod_twist mechanism) the integrator can no longer converge at all.
pub const SIMULATION_MAX_CONDITION: f64 = 1e3;

/// Watches a simulated platform's pose for a parallel singularity: the sign of the legs'
/// Jacobian's determinant must not change between checks, and its condition must stay below
/// a limit. Allocates nothing per check.
#[derive(Debug, Clone)]
pub struct ModeWatch {
    legs: Legs,
    body: BodyInfo,
    det_sign: f64,
    max_condition: f64,
}

impl ModeWatch {
    /// Starts watching at `q`, the platform's pose on its initial assembly mode.
    pub fn new<M: Mechanism + ?Sized>(
        platform: &Platform<'_, M>,
        q: &[f64],
        max_condition: f64,
    ) -> Result<Self, Error> {
        let pose = platform.pose(q)?;
        Ok(ModeWatch {
            legs: platform.legs.clone(),
            body: *platform.body(),
            det_sign: platform.legs.jacobian(&pose).determinant().signum(),
            max_condition,
        })
    }

    /// [`Error::PlatformSingularity`] (at time `t`) once the pose at `q` is singular or on
    /// the other side of a singularity.
    pub fn check(&self, q: &[f64], t: f64) -> Result<(), Error> {
        let pose = pose_of(&self.body, q)?;
        // Column scaling keeps the determinant's sign, so the homogeneous Jacobian serves both
        // checks. The SVD runs once per step of a simulation, so it is skipped while a cheap
        // bound already keeps the condition under the limit: cond₂(J) ≤ 2 (‖J‖_F/√n)ⁿ / |det J|
        // (Guggenheimer, Edelman and Johnson, 1995).
        let j = self.legs.homogeneous_jacobian(&pose);
        let det = j.determinant();
        let switched = det.signum() != self.det_sign;
        let bound = 2.0 * (j.norm() / 6f64.sqrt()).powi(6) / det.abs();
        if !switched && bound <= self.max_condition {
            return Ok(());
        }
        let condition = self.legs.condition(&pose);
        if switched || condition > self.max_condition {
            return Err(Error::PlatformSingularity {
                time: t,
                condition,
                legs: super::track::dependent_legs(&self.legs, &pose),
                switched,
            });
        }
        Ok(())
    }
}
