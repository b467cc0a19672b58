//! Compiled mechanisms by name: each generated crate exports one [`Entry`], and the crates
//! that link a set of them (the shipped mechanisms, the benchmark problems) list those
//! entries in a [`Registry`]. Programs and libraries take a `&Registry` instead of naming
//! generated crates, so a library built once serves any set of mechanisms, and changing one
//! mechanism rebuilds only its crate and the programs that link it.

use crate::mechanism::{Formulation, Mechanism};
use crate::parameters::{ParameterError, RunTimeParameters};
use crate::reduction::Reduction;

/// A mechanism in each formulation it was generated in; the first is the default.
pub type Formulations = &'static [(Formulation, &'static (dyn Mechanism + Sync))];

/// One generated mechanism.
pub struct Entry {
    pub name: &'static str,
    /// Simulation end time suggested by the mechanism file (s).
    pub t_end: f64,
    pub formulations: Formulations,
    /// The model after the substitution pass, where the generator found rows to substitute.
    pub reduced: Option<Reduced>,
    pub origin: Origin,
    /// The compiled code's run-time parameters, where it has any (decision 30).
    pub run_time: Option<&'static RunTime>,
}

/// What a compiled entry offers at other values of its run-time parameters.
pub struct RunTime {
    pub parameters: &'static RunTimeParameters,
    /// Every formulation of the entry, in its order, at the file's values with `set`
    /// applied (checked first: an error changes nothing).
    pub build: Build,
    /// The same for the entry's reduced model, where it has one.
    pub build_reduced: Option<Build>,
    /// Where the values of `p` after the named parameters come from: the model's numbers
    /// that the other parameters reach (points, axes, lengths, drivers' constants), read off
    /// the mechanism file loaded at new values (the generator's `slots::values_at`).
    pub data: &'static [u32],
    /// The whole `p` at the file's values.
    pub p0: &'static [f64],
    /// Every formulation at a whole `p` (named parameters, then `data`'s numbers).
    pub build_values: BuildValues,
    /// The same for the entry's reduced model, where it reads run-time values.
    pub build_reduced_values: Option<BuildValues>,
}

/// Builds every formulation at the file's values with `set` applied.
pub type Build = fn(set: &[(&str, f64)]) -> Result<Built, ParameterError>;

/// Builds every formulation at a whole `p`, checked first.
pub type BuildValues = fn(p: &[f64]) -> Result<Built, ParameterError>;

/// Mechanisms built at run-time parameter values, one per formulation.
pub type Built = Vec<(Formulation, Box<dyn Mechanism + Sync>)>;

/// Where an entry's equations come from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Origin {
    /// Rust generated from `file` (its path when this program was built) whose text had
    /// [`source_hash`] `hash`, compiled into this program; `parameters`: run-time
    /// parameters given other values than the file's ([`RunTime`]).
    Compiled {
        file: &'static str,
        hash: u64,
        parameters: &'static [(&'static str, f64)],
    },
    /// Equations interpreted from `file` ([`crate::Interpreted`]), derived when this
    /// program ran; `stale`: in place of a compiled entry whose file changed since its code
    /// was generated; `parameters`: the file's parameters given other values than the file's.
    Interpreted {
        file: &'static str,
        stale: bool,
        parameters: &'static [(&'static str, f64)],
    },
}

/// 64-bit FNV-1a of a mechanism file's text: written into generated code so a program can
/// tell whether the file changed after its code was generated. (Not `DefaultHasher`, whose
/// output may change between Rust releases.)
pub fn source_hash(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// A mechanism reduced by substitution, and the way back to its full model.
pub struct Reduced {
    /// One per formulation of the full model, in the same order.
    pub formulations: Formulations,
    pub reduction: &'static Reduction,
}

impl std::fmt::Debug for Entry {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Entry")
            .field("name", &self.name)
            .field("t_end", &self.t_end)
            .field("origin", &self.origin)
            .finish_non_exhaustive()
    }
}

impl Entry {
    /// The mechanism in formulation `f`, if it was generated.
    pub fn mechanism(&self, f: Formulation) -> Option<&'static (dyn Mechanism + Sync)> {
        find_formulation(self.formulations, f)
    }
    /// The mechanism in its default (first) formulation.
    pub fn default_mechanism(&self) -> &'static (dyn Mechanism + Sync) {
        self.formulations[0].1
    }
    /// The reduced mechanism in formulation `f` and its reduction, if both exist.
    pub fn reduced(
        &self,
        f: Formulation,
    ) -> Option<(&'static (dyn Mechanism + Sync), &'static Reduction)> {
        let r = self.reduced.as_ref()?;
        Some((find_formulation(r.formulations, f)?, r.reduction))
    }
}

fn find_formulation(list: Formulations, f: Formulation) -> Option<&'static (dyn Mechanism + Sync)> {
    list.iter().find(|(g, _)| *g == f).map(|(_, m)| *m)
}

/// A set of compiled mechanisms, in name order.
#[derive(Clone, Copy)]
pub struct Registry(pub &'static [&'static Entry]);

impl Registry {
    /// The entry called `name`.
    pub fn find(&self, name: &str) -> Option<&'static Entry> {
        self.0.iter().copied().find(|e| e.name == name)
    }
    /// Every entry, in name order.
    pub fn iter(&self) -> impl Iterator<Item = &'static Entry> + '_ {
        self.0.iter().copied()
    }
    /// Every mechanism's name, in order.
    pub fn names(&self) -> Vec<&'static str> {
        self.iter().map(|e| e.name).collect()
    }
    pub fn len(&self) -> usize {
        self.0.len()
    }
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

impl std::fmt::Debug for Registry {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.names()).finish()
    }
}
