//! The C ABI of symbody: every registered mechanism's generated equations
//! ([`mechanism`]) and a running simulation of one ([`session`]) behind opaque handles,
//! with integer statuses and a thread-local error message ([`status`]). The header
//! `include/symbody.h` is generated from this crate by cbindgen (`header/`, a separate package).
//!
//! Rust callers use the same functions through the rlib; they are `unsafe` because they
//! take raw pointers, and each one's `# Safety` section (copied into the header) says what
//! the caller must guarantee beyond what is checked: pointers that are null, misaligned or
//! paired with a too-short length are reported as errors, never dereferenced.

#![deny(unsafe_op_in_unsafe_fn)]

pub mod mechanism;
pub mod session;
pub mod status;

pub use mechanism::*;
pub use session::*;
pub use status::*;
