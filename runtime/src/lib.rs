//! Runtime for generated mechanisms: the trait generated code implements, and the solvers
//! (kinematic analysis, HHT-α for index-3 DAEs, reaction forces) that work on any of them.

// `!(x > tol)` is used on purpose throughout: unlike `x <= tol` it also rejects NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod error;
pub mod hht;
pub mod kinematics;
pub mod kkt;
pub mod mechanism;
pub mod reactions;
pub mod testmodels;
pub mod watch;

pub use error::{ConstraintRow, Error};
pub use hht::{HhtBuilder, Integrator, Stats, StepReport};
pub use kinematics::{InitialVelocity, KinematicSettings, Kinematics, PositionReport};
pub use kkt::{DenseKkt, KktError, KktPattern, KktSolver, SchurKkt};
pub use mechanism::{
    BodyInfo, Formulation, JointInfo, JointKind, KinematicOutputs, Mechanism, MechanismInfo,
    NewtonOutputs,
};
pub use reactions::{actuator_force, joint_force};
pub use watch::{EulerLimits, EulerWarning, ResidualWatch, Residuals};
