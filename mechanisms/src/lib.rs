//! The shipped mechanisms: one generated crate per file in `mechanisms/` (re-exported here
//! under the mechanism's name, e.g. [`stewart_6_6`]), and [`REGISTRY`], which lists them all
//! by name (docs/design.md, decisions 19 and 29). Programs pass the registry to the library
//! (`symbody`) instead of naming mechanisms, so the library never recompiles when a
//! mechanism changes.
//!
//! The crates and the registry are committed; `cargo xtask generate --all` regenerates them.

#[rustfmt::skip]
mod registry;
pub use registry::*;

/// The mechanism called `name`.
pub fn find(name: &str) -> Option<&'static symbody_runtime::Entry> {
    REGISTRY.find(name)
}
