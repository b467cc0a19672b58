//! Mechanisms generated from the files in `mechanisms/`: each module implements
//! `symbody_runtime::Mechanism` once per formulation (`Exact`, `Paper`), and [`REGISTRY`]
//! lists them all by name (docs/design.md, decision 19), so programs dispatch on a name instead
//! of naming modules.
//!
//! The modules and the registry are committed; `cargo xtask generate --all` regenerates them.

mod generated;
pub use generated::*;

use symbody_runtime::{Formulation, Mechanism};

/// One generated mechanism in the registry.
pub struct Entry {
    pub name: &'static str,
    /// Simulation end time suggested by the mechanism file (s).
    pub t_end: f64,
    /// The mechanism in each generated formulation; the first is the default.
    pub formulations: &'static [(Formulation, &'static (dyn Mechanism + Sync))],
}

impl Entry {
    /// The mechanism in formulation `f`, if it was generated.
    pub fn mechanism(&self, f: Formulation) -> Option<&'static (dyn Mechanism + Sync)> {
        self.formulations
            .iter()
            .find(|(g, _)| *g == f)
            .map(|(_, m)| *m)
    }
    /// The mechanism in its default (first) formulation.
    pub fn default_mechanism(&self) -> &'static (dyn Mechanism + Sync) {
        self.formulations[0].1
    }
}

/// The registry entry called `name`.
pub fn find(name: &str) -> Option<&'static Entry> {
    REGISTRY.iter().find(|e| e.name == name)
}
