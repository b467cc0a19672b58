//! Saddle-point (KKT) solvers for `[c·M Φqᵀ; Φq 0][x; y] = [f; g]`, the one linear system
//! every runtime analysis reduces to.
//!
//! `M` arrives as its structural nonzeros in the mechanism's mass pattern (both triangles),
//! scaled by a factor `c` (HHT needs `M/(1+α)`); `Φq` as its nonzeros in its pattern. A
//! solver is built once from the patterns ([`KktPattern`]), then [`KktSolver::factor`] and
//! [`KktSolver::solve`] run any number of times without allocating.
//!
//! Rows listed in [`KktPattern::redundant_rows`] are dropped: both solvers solve the system
//! without them and return `y = 0` for them, so consistent redundant constraints (a hinge
//! modelled by two ball joints) run; the remaining multipliers are one valid choice among
//! many.
//!
//! Two implementations: [`DenseKkt`] (LU with partial pivoting on the full matrix; the
//! reference) and [`SchurKkt`] (block Cholesky of `M`, sparse LDLᵀ of the Schur complement
//! `Φq M⁻¹ Φqᵀ` under a minimum-degree ordering; the fast one, which runs the generator's
//! straight-line [`KktKernels`] for a model's own pattern). A mass matrix that is only
//! semi-definite ([`KktPattern::mass_semidefinite`]) has no `M⁻¹`: `SchurKkt` then runs the
//! dense LU.

mod dense;
mod kernels;
mod ordering;
mod schur;

pub use dense::DenseKkt;
pub use kernels::{
    kernels_run_here, length_error, mass_pivot_error, AssembleKernel, FactorKernel,
    KineticEnergyKernel, KktKernels, LoadsKernel, MassTimesKernel, Pivoting, SolveKernel,
    TimesKernel, TransposeKernel,
};
pub use schur::{SchurKkt, SchurPlan};

use std::fmt;

use crate::error::{ConstraintRow, Error};
use crate::mechanism::{JointKind, MechanismInfo};

/// The sizes and sparsity patterns a KKT solver is built for.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct KktPattern {
    /// Number of coordinates (size of `M`).
    pub n: usize,
    /// Number of constraint rows (rows of `Φq`).
    pub m: usize,
    /// Mass nonzeros: rows, both triangles.
    pub mass_rows: Vec<u32>,
    /// Mass nonzeros: columns.
    pub mass_cols: Vec<u32>,
    /// `Φq` nonzeros: rows.
    pub phi_q_rows: Vec<u32>,
    /// `Φq` nonzeros: columns.
    pub phi_q_cols: Vec<u32>,
    /// Rows solved as if absent (their `y` is 0): rows the generator found to be linear
    /// combinations of others ([`MechanismInfo::redundant_rows`]). Ascending.
    pub redundant_rows: Vec<u32>,
    /// Rows that fix a coordinate direction without physical meaning: a quaternion body's
    /// `eᵀe − 1` ([`JointKind::Normalization`]). [`SchurKkt`] eliminates them first, so
    /// that its pivots measure the remaining rows' independence in the kinetic metric on
    /// the configuration space alone, whatever the rotation coordinates. Ascending.
    pub normalization_rows: Vec<u32>,
    /// `M` is only positive semi-definite (a body has a zero principal inertia, e.g. a
    /// slender rod about its own axis): the saddle point is still regular when the
    /// constraints fix the directions without kinetic energy (the generator checks that),
    /// but `M` has no inverse, so [`SchurKkt`] solves it as [`DenseKkt`] does.
    pub mass_semidefinite: bool,
    /// Straight-line factor and solve emitted by the generator for this pattern
    /// ([`MechanismInfo::kkt`]); [`SchurKkt`] runs them when the pattern is still the one
    /// they were emitted for, and its own loops otherwise.
    pub kernels: &'static [KktKernels],
}

impl KktPattern {
    /// The patterns of a mechanism.
    pub fn from_info(info: &MechanismInfo) -> Self {
        KktPattern {
            n: info.n_coords,
            m: info.n_constraints,
            mass_rows: info.mass_rows.to_vec(),
            mass_cols: info.mass_cols.to_vec(),
            phi_q_rows: info.phi_q_rows.to_vec(),
            phi_q_cols: info.phi_q_cols.to_vec(),
            redundant_rows: info.redundant_rows.to_vec(),
            normalization_rows: info
                .joints
                .iter()
                .filter(|j| j.kind == JointKind::Normalization)
                .flat_map(|j| (j.row_start..j.row_start + j.rows).map(|r| r as u32))
                .collect(),
            mass_semidefinite: info.bodies.iter().any(|b| b.inertia.contains(&0.0)),
            kernels: info.kkt,
        }
    }

    /// The pattern HHT factors when the applied loads' stiffness and damping join `M`
    /// (`HhtBuilder::load_stiffness`): the top-left block on the union of the mass pattern
    /// and the symmetrized patterns of `∂Q/∂q` and `∂Q/∂q̇` (rows, columns each); `None`
    /// when both are empty.
    pub fn with_loads(
        &self,
        force_q: (&[u32], &[u32]),
        force_qd: (&[u32], &[u32]),
    ) -> Option<KktPattern> {
        if force_q.0.is_empty() && force_qd.0.is_empty() {
            return None;
        }
        let pairs = |(rows, cols): (&[u32], &[u32])| -> Vec<(u32, u32)> {
            rows.iter().copied().zip(cols.iter().copied()).collect()
        };
        let mass = pairs((&self.mass_rows, &self.mass_cols));
        let union = crate::load_stiffness::union(&mass, &pairs(force_q), &pairs(force_qd));
        Some(KktPattern {
            mass_rows: union.iter().map(|p| p.0).collect(),
            mass_cols: union.iter().map(|p| p.1).collect(),
            ..self.clone()
        })
    }

    /// Checks that every index is in range; solvers call this before trusting the pattern.
    pub fn validate(&self) -> Result<(), Error> {
        let bad = |reason: String| Err(Error::InvalidPattern { reason });
        if self.mass_rows.len() != self.mass_cols.len() {
            return bad("mass_rows and mass_cols differ in length".into());
        }
        if self.phi_q_rows.len() != self.phi_q_cols.len() {
            return bad("phi_q_rows and phi_q_cols differ in length".into());
        }
        for (&r, &c) in self.mass_rows.iter().zip(&self.mass_cols) {
            if r as usize >= self.n || c as usize >= self.n {
                return bad(format!("mass entry ({r}, {c}) outside {0}×{0}", self.n));
            }
        }
        for (&r, &c) in self.phi_q_rows.iter().zip(&self.phi_q_cols) {
            if r as usize >= self.m || c as usize >= self.n {
                return bad(format!("Φq entry ({r}, {c}) outside {}×{}", self.m, self.n));
            }
        }
        for (what, rows) in [
            ("redundant", &self.redundant_rows),
            ("normalization", &self.normalization_rows),
        ] {
            for (i, &r) in rows.iter().enumerate() {
                if r as usize >= self.m {
                    return bad(format!("{what} row {r} outside {} rows", self.m));
                }
                if i > 0 && r <= rows[i - 1] {
                    return bad(format!("{what} rows are not strictly ascending"));
                }
            }
        }
        Ok(())
    }
}

/// Why a factorization failed. `Copy` and allocation-free, because Newton loops recover
/// from it (by cutting the step) before it ever becomes an [`Error`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum KktError {
    /// The scaled mass matrix is not positive definite in the block holding `coord`.
    MassNotPositiveDefinite { coord: usize },
    /// Constraint rows whose pivots vanished: `Φq` lost rank. The first `count` entries
    /// of `rows` are valid (at most four are recorded).
    RankDeficient {
        rows: [usize; 4],
        count: usize,
        /// Smallest pivot relative to its row's scale.
        pivot: f64,
    },
    /// The dense LU met a vanishing pivot in a mass column (no row attribution possible).
    SingularMatrix { column: usize },
    /// An input (or the factorization) holds a NaN or infinity.
    NotFinite,
    /// `solve` was called without a successful `factor`.
    NotFactored,
    /// An input slice has the wrong length.
    Dimension { expected: usize, got: usize },
    /// Generated kernels called on a CPU without what they were compiled for
    /// ([`kernels_run_here`]); `SchurKkt` selects them only where they run.
    KernelsUnsupported,
}

impl KktError {
    /// The runtime error for this failure at time `time`, with row and coordinate names.
    pub fn to_error(self, info: &MechanismInfo, time: f64) -> Error {
        match self {
            KktError::MassNotPositiveDefinite { coord } => Error::MassNotPositiveDefinite {
                time,
                coord,
                name: info.coord_names.get(coord).copied().unwrap_or("?"),
            },
            KktError::RankDeficient { rows, count, .. } => Error::SingularJacobian {
                time,
                rows: rows[..count.min(4)]
                    .iter()
                    .map(|&r| ConstraintRow::new(info, r))
                    .collect(),
            },
            KktError::SingularMatrix { .. } => Error::SingularJacobian {
                time,
                rows: Vec::new(),
            },
            KktError::NotFinite => Error::NotFinite {
                time,
                what: "KKT matrix (mass matrix or constraint Jacobian)",
            },
            KktError::NotFactored => Error::InvalidSetting {
                name: "kkt",
                value: f64::NAN,
                reason: "solve called before a successful factor",
            },
            KktError::Dimension { expected, got } => Error::DimensionMismatch {
                what: "KKT input",
                expected,
                got,
            },
            KktError::KernelsUnsupported => Error::InvalidSetting {
                name: "kkt",
                value: f64::NAN,
                reason: "generated KKT kernels need AVX, which this CPU lacks",
            },
        }
    }
}

impl fmt::Display for KktError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            KktError::MassNotPositiveDefinite { coord } => {
                write!(f, "mass matrix not positive definite (coordinate {coord})")
            }
            KktError::RankDeficient { rows, count, pivot } => write!(
                f,
                "constraint Jacobian rank deficient at rows {:?} (relative pivot {pivot:e})",
                &rows[..(*count).min(4)]
            ),
            KktError::SingularMatrix { column } => {
                write!(f, "singular KKT matrix at column {column}")
            }
            KktError::NotFinite => write!(f, "non-finite KKT matrix"),
            KktError::NotFactored => write!(f, "KKT solve before factor"),
            KktError::Dimension { expected, got } => {
                write!(f, "KKT input has length {got}, expected {expected}")
            }
            KktError::KernelsUnsupported => write!(f, "generated KKT kernels need AVX"),
        }
    }
}

impl std::error::Error for KktError {}

/// A solver for `[c·M Φqᵀ; Φq 0][x; y] = [f; g]`.
///
/// `factor` and `solve` allocate nothing; all memory is taken in `new`.
pub trait KktSolver: Sized {
    /// Builds the solver (ordering, symbolic factorization, work memory) for `pattern`.
    fn new(pattern: &KktPattern) -> Result<Self, Error>;

    /// Factors the matrix with `mass_scale · M` in the top-left block.
    ///
    /// `mass` holds the mass nonzeros in pattern order, `phi_q` the Jacobian's.
    fn factor(&mut self, mass: &[f64], mass_scale: f64, phi_q: &[f64]) -> Result<(), KktError>;

    /// Solves with the last factorization: `x` gets `n` entries, `y` gets `m`.
    fn solve(&mut self, f: &[f64], g: &[f64], x: &mut [f64], y: &mut [f64])
        -> Result<(), KktError>;

    /// From now on, rows whose pivot falls below `tolerance` (relative to the row's diagonal
    /// of `Φq M⁻¹ Φqᵀ`) are dropped for that factorization, as declared redundant rows are,
    /// instead of failing with [`KktError::RankDeficient`]. For mechanisms that pass through
    /// singular positions, where rows are dependent only for an instant; the caller must
    /// still check that the dropped rows hold. Returns `false` if the solver cannot.
    fn drop_dependent_rows(&mut self, tolerance: f64) -> bool {
        let _ = tolerance;
        false
    }

    /// How close the last factorization came to rank loss, if the solver measures it
    /// (`None` before a factorization, or from a solver that does not).
    fn pivots(&self) -> Option<Pivots> {
        None
    }
}

/// The conditioning of the constraint rows in one factorization: how far `Φq` was from
/// losing rank (near a singular position the multipliers, and every reaction built from
/// them, amplify errors in the state by about `1 / smallest`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pivots {
    /// The smallest pivot of `Φq M⁻¹ Φqᵀ` relative to its row's diagonal, over the rows
    /// kept (1 for a row orthogonal to the others, 0 for a dependent one; 1 with no rows).
    /// The diagonal is taken once the normalization rows are eliminated
    /// ([`KktPattern::normalization_rows`]), so the measure is the same in quaternions and
    /// in Euler angles.
    pub smallest: f64,
    /// Rows dropped as dependent ([`KktSolver::drop_dependent_rows`]), declared redundant
    /// rows aside: at such a state the multipliers are one valid choice, with those rows
    /// carrying nothing.
    pub dropped: usize,
}

impl Default for Pivots {
    fn default() -> Self {
        Pivots {
            smallest: 1.0,
            dropped: 0,
        }
    }
}

pub(crate) fn check_kkt_len(expected: usize, got: usize) -> Result<(), KktError> {
    if expected == got {
        Ok(())
    } else {
        Err(KktError::Dimension { expected, got })
    }
}

/// Default relative pivot tolerance: below it the Schur complement has lost about ten
/// digits, so multipliers would carry no information.
pub const DEFAULT_PIVOT_TOLERANCE: f64 = 1e-10;

#[cfg(test)]
pub(crate) mod tests;
