//! Symbolic multibody code generator: mechanism file → model → expression DAG →
//! Φ, Φq, Φt, γ, M, Q → straight-line Rust implementing `symbody_runtime::Mechanism`.
//!
//! One module per stage, chained by [`generate`]:
//! [`model`] (parse and validate the TOML) → [`equations`] (build and differentiate on
//! the [`expr`] DAG) → [`emit`] (chunked straight-line functions) → [`rust`] (the module).

pub mod diag;
pub mod emit;
pub mod equations;
pub mod expr;
pub mod files;
pub mod model;
pub mod parse;
pub mod rust;

pub use diag::{Diagnostic, Errors};

/// Generates the Rust module for the mechanism file `text`; `source` names the file in
/// messages and in the generated header (use a path relative to the workspace root).
pub fn generate(source: &str, text: &str) -> Result<String, Errors> {
    let model = model::load(source, text)?;
    let system = equations::build(&model);
    Ok(rust::module(&model, &system, source))
}
