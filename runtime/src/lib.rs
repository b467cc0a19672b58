//! Runtime for generated mechanisms: the trait generated code implements, and the solvers
//! (kinematic analysis, HHT-α for index-3 DAEs, reaction forces) that work on any of them.

pub mod mechanism;

pub use mechanism::{
    BodyInfo, Formulation, JointInfo, JointKind, KinematicOutputs, Mechanism, MechanismInfo,
    NewtonOutputs,
};
