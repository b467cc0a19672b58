//! Straight-line KKT kernels emitted by the generator for one mechanism's fixed pattern, and
//! the pivot logic they share with [`SchurKkt`](super::SchurKkt)'s loops.
//!
//! The generator runs `SchurKkt`'s symbolic analysis (groups, ordering, fill) on the
//! pattern of each model it emits, and writes its numeric factorization and solve out as
//! straight-line code: constant offsets instead of index lists, no loop exits, and no
//! multiply-add with an operand that is structurally zero (a translation coordinate's
//! diagonal mass, a row that touches only some of a body's coordinates). `SchurKkt` takes
//! the kernels when its pattern is the one they were emitted for
//! ([`KktPattern::fingerprint`]), and runs its own loops otherwise (a pattern widened by a
//! load's stiffness, an interpreted model): the kernels are an exact copy of those loops'
//! arithmetic with the zero terms left out.

use super::{KktError, KktPattern, Pivots};

/// Whether generated kernels run on this CPU. On x86-64 the generator compiles them for AVX
/// (`codegen/src/kkt.rs`, `dispatch`), whose three-operand forms spare the register copy
/// that SSE2's two-operand forms need before most products; without AVX, `SchurKkt` runs
/// its loops, which compute the same bits.
pub fn kernels_run_here() -> bool {
    #[cfg(target_arch = "x86_64")]
    return std::arch::is_x86_feature_detected!("avx");
    #[cfg(not(target_arch = "x86_64"))]
    return true;
}

/// A generated factorization: `(mass, mass_scale, phi_q, state, pivoting)`, as
/// [`KktSolver::factor`](super::KktSolver::factor), leaving in `state` what the solves read.
pub type FactorKernel = fn(&[f64], f64, &[f64], &mut [f64], &mut Pivoting) -> Result<(), KktError>;

/// A generated solve: `(f, g, x, y, state)`, as [`KktSolver::solve`](super::KktSolver::solve).
pub type SolveKernel = fn(&[f64], &[f64], &mut [f64], &mut [f64], &[f64]) -> Result<(), KktError>;

/// A generated `out = Φqᵀ y` from Φq's nonzeros: `(phi_q, y, out)`.
pub type TransposeKernel = fn(&[f64], &[f64], &mut [f64]) -> Result<(), KktError>;

/// A generated `out += Φq x`: `(phi_q, x, out)`.
pub type TimesKernel = fn(&[f64], &[f64], &mut [f64]) -> Result<(), KktError>;

/// A generated `out = M v` from M's nonzeros: `(mass, v, out)`.
pub type MassTimesKernel = fn(&[f64], &[f64], &mut [f64]) -> Result<(), KktError>;

/// A generated `½ q̇ᵀ M q̇` from M's nonzeros: `(mass, qd)`.
pub type KineticEnergyKernel = fn(&[f64], &[f64]) -> Result<f64, KktError>;

/// A generated `c·M − kq·sym(∂Q/∂q) − kqd·sym(∂Q/∂q̇)` on the union pattern:
/// `(mass, c, dq, kq, dqd, kqd, out)`.
pub type AssembleKernel =
    fn(&[f64], f64, &[f64], f64, &[f64], f64, &mut [f64]) -> Result<(), KktError>;

/// The generated assembly of the HHT iteration matrix's top-left block with the loads'
/// stiffness and damping, and the load patterns it was emitted for: the model's own
/// statics, compared by address. The slot each nonzero lands in depends on the mass
/// pattern too, which its [`KktKernels`] entry holds ([`KktKernels::loads_for`]).
#[derive(Clone, Copy)]
pub struct LoadsKernel {
    pub force_q_rows: &'static [u32],
    pub force_q_cols: &'static [u32],
    pub force_qd_rows: &'static [u32],
    pub force_qd_cols: &'static [u32],
    /// Each slot's value from `c·mᵢ` (or zero) less the halves of the load Jacobians'
    /// entries that land there, in the order of the entries (as `LoadStiffness::assemble`'s
    /// loop subtracts them).
    pub assemble: AssembleKernel,
}

impl LoadsKernel {
    /// Whether `info`'s load patterns are the statics the kernel was emitted for.
    fn emitted_for(&self, info: &crate::MechanismInfo) -> bool {
        let same = |a: &[u32], b: &[u32]| std::ptr::eq(a, b);
        same(self.force_q_rows, info.force_q_rows)
            && same(self.force_q_cols, info.force_q_cols)
            && same(self.force_qd_rows, info.force_qd_rows)
            && same(self.force_qd_cols, info.force_qd_cols)
    }
}

/// Factor and solve for one pattern, as the generator emits them. Not built by hand: the
/// generated module of a mechanism fills [`MechanismInfo::kkt`](crate::MechanismInfo::kkt).
#[derive(Clone, Copy)]
pub struct KktKernels {
    /// [`KktPattern::fingerprint`] of the pattern the kernels were emitted for.
    pub pattern: u64,
    /// Length of the state the factorization leaves for the solves.
    pub storage: usize,
    pub factor: FactorKernel,
    pub solve: SolveKernel,
    /// The Φq pattern `transpose_times` was emitted for: the model's own statics, so that
    /// a caller can tell by address that an info's pattern is theirs.
    pub phi_q_rows: &'static [u32],
    pub phi_q_cols: &'static [u32],
    /// `Φqᵀ y`, summed column by column in the order of the nonzeros (as
    /// `phi_q_transpose_times`'s loop does).
    pub transpose_times: TransposeKernel,
    /// `out += Φq x`, each row's products added to `out` in the order of the nonzeros (as
    /// a loop over them does).
    pub times_add: TimesKernel,
    /// The model's own mass pattern (`MechanismInfo::mass_rows`/`mass_cols`, by address)
    /// that `mass_times` and `kinetic_energy` were emitted for.
    pub mass_rows: &'static [u32],
    pub mass_cols: &'static [u32],
    /// `out = M v`, each row's products added from zero in the order of the nonzeros (as
    /// `mass_times`'s loop does).
    pub mass_times: MassTimesKernel,
    /// `½ q̇ᵀ M q̇`, the terms `q̇ᵣ·m·q̇꜀` summed in the order of the nonzeros (as
    /// `kinetic_energy`'s loop does).
    pub kinetic_energy: KineticEnergyKernel,
    /// The loads' stiffness assembled into this pattern (the one with the loads' stiffness),
    /// where the generator emitted it.
    pub loads: Option<LoadsKernel>,
}

impl KktKernels {
    /// The generated `Φqᵀ y` when `rows` and `cols` are the pattern it was emitted for
    /// (the same statics, compared by address: no scan).
    pub fn transpose_for(&self, rows: &[u32], cols: &[u32]) -> Option<TransposeKernel> {
        self.emitted_for(rows, cols).then_some(self.transpose_times)
    }

    /// Whether `rows` and `cols` are the Φq pattern statics the kernels were emitted with
    /// (by address): then the pattern is the generator's, row-major as it always emits it.
    pub fn emitted_for(&self, rows: &[u32], cols: &[u32]) -> bool {
        std::ptr::eq(self.phi_q_rows, rows) && std::ptr::eq(self.phi_q_cols, cols)
    }

    /// Whether `rows` and `cols` are the mass pattern statics `mass_times` and
    /// `kinetic_energy` were emitted with (by address).
    pub fn mass_emitted_for(&self, rows: &[u32], cols: &[u32]) -> bool {
        std::ptr::eq(self.mass_rows, rows) && std::ptr::eq(self.mass_cols, cols)
    }

    /// The loads' assembly, where this entry has one emitted for `info`'s mass and load
    /// patterns.
    pub fn loads_for(&self, info: &crate::MechanismInfo) -> Option<&LoadsKernel> {
        let loads = self.loads.as_ref()?;
        (self.mass_emitted_for(info.mass_rows, info.mass_cols) && loads.emitted_for(info))
            .then_some(loads)
    }
}

impl std::fmt::Debug for KktKernels {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("KktKernels")
            .field("pattern", &format_args!("{:#018x}", self.pattern))
            .field("storage", &self.storage)
            .finish_non_exhaustive()
    }
}

/// Kernels are equal when emitted for the same pattern with the same storage: the
/// generator's output is a function of the pattern alone.
impl PartialEq for KktKernels {
    fn eq(&self, other: &Self) -> bool {
        (self.pattern, self.storage) == (other.pattern, other.storage)
    }
}

impl Eq for KktKernels {}

impl KktPattern {
    /// A hash of every field but [`KktPattern::kernels`] (FNV-1a): kernels run only on the
    /// pattern they were emitted for.
    pub fn fingerprint(&self) -> u64 {
        let mut h: u64 = 0xcbf2_9ce4_8422_2325;
        let mut word = |w: u64| {
            for b in w.to_le_bytes() {
                h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
            }
        };
        word(self.n as u64);
        word(self.m as u64);
        word(u64::from(self.mass_semidefinite));
        for list in [
            &self.mass_rows,
            &self.mass_cols,
            &self.phi_q_rows,
            &self.phi_q_cols,
            &self.redundant_rows,
            &self.normalization_rows,
        ] {
            word(list.len() as u64);
            for &i in list {
                word(u64::from(i));
            }
        }
        h
    }
}

/// The pivot test of the Schur complement's `LDLᵀ`, one column at a time, and what it
/// found: shared by `SchurKkt`'s loop and the generated kernels so that both drop, report
/// and measure rows alike.
#[derive(Debug, Clone)]
pub struct Pivoting {
    tolerance: f64,
    drop_dependent: bool,
    bad: [usize; 4],
    count: usize,
    worst: f64,
    // The smallest kept pivot relative to its row's scale, as the pair (D, scale) so the
    // test multiplies instead of dividing every row.
    small_d: f64,
    small_scale: f64,
    dropped: usize,
}

impl Pivoting {
    pub(crate) fn new(tolerance: f64, drop_dependent: bool) -> Self {
        Pivoting {
            tolerance,
            drop_dependent,
            bad: [0; 4],
            count: 0,
            worst: f64::INFINITY,
            small_d: 1.0,
            small_scale: 1.0,
            dropped: 0,
        }
    }

    /// Tests the pivot `d` of constraint row `row` against its `scale` (its diagonal of
    /// `Φq M⁻¹ Φqᵀ` once the normalization rows are eliminated). Returns `(1/d, d)` for a
    /// kept pivot and `(0, 0)` for a dropped one (a declared redundant row, or a dependent
    /// one): its column of `L` is then zero and it updates nothing.
    #[inline(always)]
    pub fn pivot(
        &mut self,
        d: f64,
        scale: f64,
        row: usize,
        redundant: bool,
    ) -> Result<(f64, f64), KktError> {
        if !d.is_finite() {
            return Err(KktError::NotFinite);
        }
        if !(d > self.tolerance * scale) {
            self.drop(d, scale, row, redundant);
            return Ok((0.0, 0.0));
        }
        if d * self.small_scale < self.small_d * scale {
            (self.small_d, self.small_scale) = (d, scale);
        }
        Ok((1.0 / d, d))
    }

    #[cold]
    fn drop(&mut self, d: f64, scale: f64, row: usize, redundant: bool) {
        if redundant {
            return;
        }
        if self.drop_dependent {
            self.dropped += 1;
            return;
        }
        self.worst = self.worst.min(if scale > 0.0 { d / scale } else { 0.0 });
        if self.count < self.bad.len() {
            self.bad[self.count] = row;
        }
        self.count += 1;
    }

    /// The factorization's outcome once every column is tested.
    pub fn finish(&self) -> Result<Pivots, KktError> {
        if self.count > 0 {
            return Err(KktError::RankDeficient {
                rows: self.bad,
                count: self.count.min(self.bad.len()),
                pivot: self.worst,
            });
        }
        Ok(Pivots {
            smallest: self.small_d / self.small_scale,
            dropped: self.dropped,
        })
    }
}

/// The error of a block Cholesky pivot `d` at coordinate `coord` (generated kernels).
#[cold]
pub fn mass_pivot_error(d: f64, coord: usize) -> KktError {
    if d.is_nan() {
        KktError::NotFinite
    } else {
        KktError::MassNotPositiveDefinite { coord }
    }
}

/// The error of an input of the wrong length (generated kernels).
#[cold]
pub fn length_error(expected: usize, got: usize) -> KktError {
    KktError::Dimension { expected, got }
}
