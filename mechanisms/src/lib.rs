//! Mechanisms generated from the files in `mechanisms/`: each module implements
//! `symbody_runtime::Mechanism` once per formulation (`Exact`, `Paper`).
//!
//! The modules are committed; `cargo xtask generate --all` regenerates them.

mod generated;
pub use generated::*;
