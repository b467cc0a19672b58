//! Fixtures for tests and benchmarks, kept out of every library's public API: hand-written
//! mechanisms ([`models`]), a counting allocator ([`alloc`]), a reproducible random generator
//! and dense views of sparse outputs ([`common`]), the Newton–Euler reference of the paper's
//! scenario ([`newton_euler`]), a hand-written Stewart Φ for AD ([`reference`]) and a
//! six-leg platform's leg-length Jacobian by differences ([`platform`]).
//!
//! Only ever a dev-dependency. `models.rs` is also compiled into the runtime's own unit tests
//! (`#[cfg(test)]`, through `#[path]`): those tests reach private items, and a dev-dependency
//! on this crate would give them a second, incompatible copy of the runtime's types. The
//! `use` below lets its `crate::mechanism`/`crate::pose` paths resolve here as there.

// `pose` is only used by the fixtures' own tests.
#[allow(unused_imports)]
use symbody_runtime::{mechanism, pose};

pub mod alloc;
pub mod common;
pub mod models;
pub mod newton_euler;
pub mod platform;
pub mod reference;
