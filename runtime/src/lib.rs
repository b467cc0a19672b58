//! Runtime for generated mechanisms: the trait generated code implements, and the solvers
//! (kinematic analysis, HHT-α for index-3 DAEs, reaction forces) that work on any of them.

pub mod error;
pub mod kinematics;
pub mod kkt;
pub mod mechanism;
pub mod reactions;
pub mod testmodels;
pub mod watch;

pub use error::{ConstraintRow, Error};
pub use kkt::{DenseKkt, KktError, KktPattern, KktSolver, SchurKkt};
pub use mechanism::{
    BodyInfo, Formulation, JointInfo, JointKind, KinematicOutputs, Mechanism, MechanismInfo,
    NewtonOutputs,
};
