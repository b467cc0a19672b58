//! Runtime for generated mechanisms: the trait generated code implements, and the solvers
//! (kinematic analysis, HHT-α for index-3 DAEs, reaction forces) that work on any of them.
//!
//! - [`mechanism`]: the [`Mechanism`] trait generated code implements.
//! - [`kkt`]: solvers for the saddle-point system `[c·M Φqᵀ; Φq 0]` ([`SchurKkt`], the
//!   structured default, and [`DenseKkt`], the reference).
//! - [`kinematics`]: position/velocity/acceleration analysis and the consistent start.
//! - [`kinematic_path`]: a driven mechanism followed without integration, and the check
//!   that this is exact ([`free_motion`]).
//! - [`hht`]: the HHT-α integrator ([`HhtBuilder`] → [`Integrator`]), whose Newton matrix
//!   takes the applied loads' stiffness and damping (`load_stiffness`).
//! - [`reactions`]: joint wrenches and driver efforts from the multipliers.
//! - [`registry`]: compiled mechanisms by name ([`Registry`] of [`Entry`]).
//! - [`tape`] and [`interpreted`]: instruction tapes and the interpreter that runs a mechanism
//!   file never compiled ([`Interpreted`]).
//! - [`reduction`]: reduced generated mechanisms read back in their full model's terms.
//! - [`pose`]: rotation matrices, poses, angular velocities and world points of Euler-angle
//!   and quaternion bodies.
//! - [`energy`]: kinetic and potential energy and the work of drivers and non-conservative
//!   forces ([`EnergyMeter`]), for energy-balance checks.
//! - [`watch`]: constraint-drift and Euler-singularity watchdogs.
//! - [`trig`]: the sine and cosine of generated code and of the interpreter.
//! - [`error`]: the one [`Error`] type.
//!
//! All solvers allocate their work memory when built; stepping and solving allocate nothing.

// `!(x > tol)` is used on purpose throughout: unlike `x <= tol` it also rejects NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod energy;
pub mod error;
pub mod fk;
pub mod hht;
mod hht_predictor;
pub mod interpreted;
pub mod kinematic_path;
pub mod kinematics;
pub mod kkt;
mod load_stiffness;
pub mod mechanism;
pub mod parameters;
pub mod pose;
pub mod quadrature;
pub mod reactions;
pub mod reduction;
pub mod registry;
pub mod sensitivity;
pub mod tape;
pub mod trig;
// Hand-written fixtures for this crate's unit tests; other crates reach them through the
// dev-only `symbody-testkit`, where the file lives.
#[cfg(test)]
#[path = "../../testkit/src/models.rs"]
mod testmodels;
pub mod watch;

pub use energy::{EnergyMeter, EnergySample};
pub use error::{ConstraintRow, Error, NewtonIncrement, RowOwner};
pub use hht::{HhtBuilder, Integrator, Stats, StepReport};
pub use interpreted::Interpreted;
pub use kinematic_path::{
    free_bodies, free_motion, FreeMotion, KinematicPath, PathStats, MAX_ACCELERATION_MISMATCH,
    MAX_OUTPUT_CHANGE,
};
pub use kinematics::{InitialVelocity, KinematicSettings, Kinematics, PositionReport};
pub use kkt::{DenseKkt, KktError, KktPattern, KktSolver, Pivots, SchurKkt};
pub use mechanism::{
    BodyInfo, Direction, Formulation, JointInfo, JointKind, KinematicOutputs, LegInfo, Mechanism,
    MechanismInfo, NewtonOutputs, PlatformInfo, Rotation, TangentOutputs,
};
pub use pose::{
    angular_velocity, angular_velocity_jacobian, body_pose, point_world, rotation_matrix,
};
pub use reactions::{
    actuator_force, driver_effort, joint_force, joint_wrench, ForceOnBody, JointWrenches, Wrench,
};
pub use reduction::{FullState, Reduction, Substitution};
pub use registry::{source_hash, Entry, Origin, Registry};
pub use watch::{velocity_residual, EulerLimits, EulerWarning, ResidualWatch, Residuals};
