//! Generated mechanisms, one module each. Regenerate with `cargo xtask generate --all`.

#[rustfmt::skip]
pub mod stewart_6_6;
