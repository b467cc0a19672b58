//! The benchmark problems' mechanisms (`mechanisms/benchmarks/*.toml`: the IFToMM problems
//! A01–A05), each a generated crate compiled only where the benchmarks and their tests need
//! it, and [`REGISTRY`]: them and the shipped mechanisms (re-exported from
//! `symbody-mechanisms`) by name.
//!
//! The crates and the registry are committed; `cargo xtask generate --all` regenerates them.

#[rustfmt::skip]
mod registry;
pub use registry::*;

/// The mechanism called `name`, shipped or benchmark.
pub fn find(name: &str) -> Option<&'static symbody_runtime::Entry> {
    REGISTRY.find(name)
}
