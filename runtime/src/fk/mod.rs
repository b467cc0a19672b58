//! Forward kinematics of a platform held to the ground by six legs of given length (the
//! Stewart–Gough structure): the pose reached by Newton from a nearby pose ([`Legs::solve`]),
//! the conditioning of the platform's Jacobian, branch-safe continuation along a leg-length
//! path ([`track`]) and every assembly mode ([`modes`]).
//!
//! Conventions: the platform's pose is its frame's origin `p` (global) and rotation `R`
//! (platform → global); leg `i` joins the base point `aᵢ` (global) to the platform point `bᵢ`
//! (platform frame), so its length is `|p + R bᵢ − aᵢ|`.

mod linear_product;
pub mod modes;
mod parameter;
pub mod platform;
mod start;
mod study;
pub mod track;

use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

use crate::error::Error;

pub use modes::{assembly_modes, assembly_modes_seeded, Mode, Modes};
pub use platform::{ModeWatch, Platform, SIMULATION_MAX_CONDITION};
pub use start::start_table_source;
pub use track::{track, TrackSettings, Tracked};

/// The six legs' attachment points.
#[derive(Debug, Clone, PartialEq)]
pub struct Legs {
    /// Base joint centres, global frame.
    pub base: [Vector3<f64>; 6],
    /// Platform joint centres, platform frame.
    pub top: [Vector3<f64>; 6],
}

/// A pose of the platform frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// Origin of the platform frame, global.
    pub position: Vector3<f64>,
    /// Rotation platform → global.
    pub rotation: Matrix3<f64>,
}

impl Pose {
    /// The pose `(x, y, z)` with `R = Rz(γ)·Ry(β)·Rx(θ)`, the Euler-angle convention of the
    /// mechanism files.
    pub fn from_euler(position: [f64; 3], [theta, beta, gamma]: [f64; 3]) -> Pose {
        let r = nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), gamma)
            * nalgebra::Rotation3::from_axis_angle(&Vector3::y_axis(), beta)
            * nalgebra::Rotation3::from_axis_angle(&Vector3::x_axis(), theta);
        Pose {
            position: Vector3::from(position),
            rotation: *r.matrix(),
        }
    }

    /// `[θ, β, γ]` of `R = Rz(γ)·Ry(β)·Rx(θ)`, β in [−90°, 90°].
    pub fn euler_angles(&self) -> [f64; 3] {
        let r = &self.rotation;
        let beta = (-r[(2, 0)]).clamp(-1.0, 1.0).asin();
        [r[(2, 1)].atan2(r[(2, 2)]), beta, r[(1, 0)].atan2(r[(0, 0)])]
    }

    /// The pose moved by `δp` and turned by the small global rotation vector `δθ`; the
    /// rotation stays orthonormal to roundoff because the increment is an exact rotation.
    fn moved(&self, d: &Vector6<f64>) -> Pose {
        let dtheta = Vector3::new(d[3], d[4], d[5]);
        Pose {
            position: self.position + Vector3::new(d[0], d[1], d[2]),
            rotation: nalgebra::Rotation3::new(dtheta).matrix() * self.rotation,
        }
    }

    /// Distance to another pose: position difference plus `length` × rotation angle between
    /// them, so both parts are in metres.
    pub fn distance(&self, other: &Pose, length: f64) -> f64 {
        // |R₁ − R₂|_F = 2√2 sin(angle/2): unlike acos of the trace, exact near zero.
        let chord = (self.rotation - other.rotation).norm() / (2.0 * std::f64::consts::SQRT_2);
        let angle = 2.0 * chord.min(1.0).asin();
        (self.position - other.position).norm() + length * angle
    }
}

/// Settings of the Newton solve.
#[derive(Debug, Clone, Copy)]
pub struct Settings {
    /// Converged when every leg-length error is below this (m).
    pub tolerance: f64,
    pub max_iterations: usize,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            tolerance: 1e-13,
            max_iterations: 30,
        }
    }
}

/// A pose found by Newton, with what it took and how well it is determined.
#[derive(Debug, Clone, Copy)]
pub struct Solution {
    pub pose: Pose,
    /// Largest leg-length error |ℓᵢ(pose) − Lᵢ| (m).
    pub residual: f64,
    pub iterations: usize,
    /// Condition number of the dimensionally homogeneous Jacobian ([`Legs::condition`]).
    pub condition: f64,
    /// Sign of the Jacobian's determinant: the assembly mode's side of the singularity
    /// surface. Continuation cannot change it without passing a singular pose.
    pub det_sign: f64,
}

impl Legs {
    /// The legs' lengths at `pose` (inverse kinematics).
    pub fn lengths(&self, pose: &Pose) -> [f64; 6] {
        std::array::from_fn(|i| self.leg(pose, i).norm())
    }

    fn leg(&self, pose: &Pose, i: usize) -> Vector3<f64> {
        pose.position + pose.rotation * self.top[i] - self.base[i]
    }

    /// The characteristic length that makes the Jacobian dimensionally homogeneous: the RMS
    /// distance of the platform points from their centroid (the platform's radius).
    pub fn characteristic_length(&self) -> f64 {
        let c = self.top.iter().sum::<Vector3<f64>>() / 6.0;
        let r = (self.top.iter().map(|b| (b - c).norm_squared()).sum::<f64>() / 6.0).sqrt();
        if r > 0.0 {
            r
        } else {
            1.0
        }
    }

    /// `∂ℓ/∂(δp, δθ)`: row `i` is `[uᵢᵀ, (R bᵢ × uᵢ)ᵀ]` with `uᵢ` the unit leg vector and `δθ`
    /// a global rotation vector: the legs' lines in Plücker coordinates. Singular where the
    /// six lines are linearly dependent (a parallel singularity).
    pub fn jacobian(&self, pose: &Pose) -> Matrix6<f64> {
        let mut j = Matrix6::zeros();
        for i in 0..6 {
            let u = self.leg(pose, i).normalize();
            let m = (pose.rotation * self.top[i]).cross(&u);
            for k in 0..3 {
                j[(i, k)] = u[k];
                j[(i, k + 3)] = m[k];
            }
        }
        j
    }

    /// The Jacobian with its rotation columns divided by [`Self::characteristic_length`], so
    /// all columns are in the same unit and its condition number means something.
    pub fn homogeneous_jacobian(&self, pose: &Pose) -> Matrix6<f64> {
        let mut j = self.jacobian(pose);
        let lc = self.characteristic_length();
        for k in 3..6 {
            j.column_mut(k).unscale_mut(lc);
        }
        j
    }

    /// 2-norm condition number of [`Self::homogeneous_jacobian`] (∞ at a singularity).
    pub fn condition(&self, pose: &Pose) -> f64 {
        let s = self.homogeneous_jacobian(pose).singular_values();
        let (max, min) = (s.max(), s.min());
        if min > 0.0 {
            max / min
        } else {
            f64::INFINITY
        }
    }

    /// Newton's method on the six leg lengths from `start`. Fails with
    /// [`Error::NewtonFailed`] (time NaN: no time is involved) when it does not converge,
    /// and with [`Error::NotFinite`] on non-finite input.
    pub fn solve(&self, lengths: &[f64; 6], start: &Pose, s: Settings) -> Result<Solution, Error> {
        self.solve_bounded(lengths, start, s, f64::INFINITY)
            .map_err(|e| e.into_error())
    }

    /// [`Self::solve`] that also gives up when the iterates move farther than `max_move`
    /// ([`Pose::distance`]) from `start`: continuation uses it to refuse a jump.
    pub(crate) fn solve_bounded(
        &self,
        lengths: &[f64; 6],
        start: &Pose,
        s: Settings,
        max_move: f64,
    ) -> Result<Solution, Failure> {
        let finite = lengths.iter().all(|l| l.is_finite())
            && start.position.iter().all(|x| x.is_finite())
            && start.rotation.iter().all(|x| x.is_finite());
        if !finite {
            return Err(Failure::NotFinite);
        }
        let lc = self.characteristic_length();
        let mut pose = *start;
        let mut residual = f64::INFINITY;
        for it in 0..=s.max_iterations {
            let current = self.lengths(&pose);
            let r = Vector6::from_fn(|i, _| current[i] - lengths[i]);
            residual = r.amax();
            if residual <= s.tolerance {
                return Ok(self.solution(pose, residual, it));
            }
            if it == s.max_iterations || !residual.is_finite() {
                break;
            }
            let Some(d) = self.jacobian(&pose).lu().solve(&(-r)) else {
                break;
            };
            pose = pose.moved(&d);
            if start.distance(&pose, lc) > max_move {
                return Err(Failure::Jumped { residual });
            }
        }
        Err(Failure::NoConvergence {
            residual,
            iterations: s.max_iterations,
        })
    }

    fn solution(&self, pose: Pose, residual: f64, iterations: usize) -> Solution {
        Solution {
            pose,
            residual,
            iterations,
            condition: self.condition(&pose),
            det_sign: self.jacobian(&pose).determinant().signum(),
        }
    }
}

/// Why a bounded Newton solve gave up.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Failure {
    NotFinite,
    NoConvergence { residual: f64, iterations: usize },
    Jumped { residual: f64 },
}

impl Failure {
    fn into_error(self) -> Error {
        match self {
            Failure::NotFinite => Error::NotFinite {
                time: f64::NAN,
                what: "forward kinematics input (lengths or start pose)",
            },
            Failure::NoConvergence {
                residual,
                iterations,
            } => Error::NewtonFailed {
                analysis: "forward kinematics",
                time: f64::NAN,
                residual,
                iterations,
                row: None,
            },
            Failure::Jumped { residual } => Error::NewtonFailed {
                analysis: "forward kinematics",
                time: f64::NAN,
                residual,
                iterations: 0,
                row: None,
            },
        }
    }
}

#[cfg(test)]
mod tests;
