//! symbody's high-level API, what Rust programs, the C library (`capi/`), the Python package
//! (`python/`) and the command-line tool (`cli/`) link: any mechanism of a registry by name,
//! simulated ([`generic`]) or driven step by step ([`session`]); the paper's scenario on the
//! generated Stewart platform ([`scenario`]); scene files ([`scene`]); forward kinematics
//! ([`fk`]); and the results as tables and CSV files ([`output`], [`generic::tables`]).
//!
//! Mechanisms come from a [`symbody_runtime::Registry`] the caller passes
//! (`symbody_mechanisms::REGISTRY` for the shipped ones), so this library is compiled once
//! whatever mechanisms a program links. Plots and the viewer belong to the command-line tool.

mod apart;
pub mod compiled_numbers;
pub mod files;
pub mod fk;
pub mod generic;
pub mod number;
pub mod output;
mod path_feed;
pub mod scenario;
pub mod scene;
pub mod sensitivity;
pub mod session;
mod stepper;
pub mod study;
pub mod tables;
