//! Symbolic multibody code generator: mechanism file → model → expression DAG →
//! Φ, Φq, Φt, γ, M, Q → straight-line Rust implementing `symbody_runtime::Mechanism`.
//!
//! One module per stage, chained by [`generate`]:
//! [`model`] (parse and validate the TOML) → [`equations`] (joint rows from
//! [`primitives`], loads from [`loads`], built and differentiated on the [`expr`] DAG) →
//! [`assembly`] (initial pose, rank, redundant rows, and [`legs`]: a six-leg platform for
//! forward kinematics) → [`emit`] (chunked straight-line functions) → [`rust`] (the module).
//! [`symbolic`] holds the pieces the equation stages share (no stage imports a later one).
//! [`reduce`] is a pass between equations and emission: substitution of rows qᵢ − qⱼ − c(t).

// `!(x > tol)` is used on purpose: unlike `x <= tol` it also rejects NaN.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod assembly;
pub mod diag;
pub mod emit;
pub mod equations;
pub mod expr;
pub mod files;
pub mod fuzz;
pub mod geometry;
pub mod hoist;
pub mod info;
pub mod interpret;
pub mod kkt;
pub mod legs;
pub mod loads;
pub mod model;
pub mod parse;
pub mod primitives;
pub mod reduce;
pub mod rust;
pub mod slots;
pub mod symbolic;
pub mod tangent;
pub mod tape;

pub use assembly::Report;
pub use diag::{Diagnostic, Errors};

/// A generated module and what the generator found out about the mechanism.
#[derive(Debug, Clone)]
pub struct Generated {
    pub code: String,
    pub report: Report,
    /// Formulations generated, the default first.
    pub formulations: Vec<model::Formulation>,
}

/// Generates the Rust module for the mechanism file `text`; `source` names the file in
/// messages and in the generated header (use a path relative to the workspace root).
pub fn generate(source: &str, text: &str) -> Result<Generated, Errors> {
    let mut model = model::load(source, text)?;
    let mut system = equations::build_parametric(&slots::mark(source, text, &mut model));
    tangent::add(&mut system);
    // What the run-time parameters make of the equations at the file's values must be finite,
    // as every literal must (the interpreter folds the same values in, and is checked alike).
    let mut bound = system.clone();
    hoist::bound(&mut bound, &model.run_time_values());
    assembly::non_finite_constants(&bound, source)?;
    let assembly = assembly::assemble(&model, &system, source)?;
    Ok(Generated {
        code: rust::module(
            &model,
            &system,
            &assembly,
            source,
            symbody_runtime::source_hash(text),
        ),
        report: assembly.report,
        formulations: model.formulations.clone(),
    })
}
