//! The structure-exploiting KKT solver: `M` is block diagonal (one block per body), so
//! `M⁻¹` is cheap and the saddle point reduces to the Schur complement `S = Φq M⁻¹ Φqᵀ`,
//! which is symmetric positive definite exactly when `Φq` has full row rank. `S` is factored
//! as `LDLᵀ` with a minimum-degree ordering whose pattern is computed once.
//!
//! Redundant rows cost nothing on the numeric path: their `Φq` nonzeros are scattered into
//! one dummy slot of the work matrix that no block reads, so their rows of `S` stay empty
//! (isolated in the ordering, no fill), and their zero pivot is recognised as dropped only
//! in the rank-loss branch, where it gets `D = 1`, `1/D = 0` and hence `y = 0`.
//!
//! A mass matrix that is only semi-definite ([`KktPattern::mass_semidefinite`]: a zero
//! principal inertia) has no block inverses; the saddle point is still regular, and is then
//! solved by a [`DenseKkt`] inside, so callers keep one solver type.
//!
//! The generator replays this factorization and solve as straight-line code for each model's
//! fixed pattern ([`KktKernels`], decision 41); `SchurKkt` runs them in place of its loops
//! when the pattern carries kernels emitted for it, with the same pivot test ([`Pivoting`]).

use super::ordering::{minimum_degree, Symbolic};
use super::{
    check_kkt_len, kernels_run_here, DenseKkt, KktError, KktKernels, KktPattern, KktSolver,
    Pivoting, Pivots, DEFAULT_PIVOT_TOLERANCE,
};
use crate::error::Error;

/// Largest group of mass-matrix blocks factored together as one dense block: a quaternion
/// body's seven coordinates.
const GROUP_MAX: usize = 7;

/// Block-Cholesky + sparse-`LDLᵀ` Schur-complement solver. See the module docs.
#[derive(Debug, Clone)]
pub struct SchurKkt {
    n: usize,
    m: usize,
    component_sizes: Vec<usize>,
    // Diagonal blocks of M: coordinates of block b are `block_coords[block_ptr[b]..block_ptr[b+1]]`.
    block_ptr: Vec<usize>,
    block_coords: Vec<usize>,
    /// Offset of block b's dense (row-major, lower triangle used) Cholesky factor in `chol`.
    chol_off: Vec<usize>,
    chol: Vec<f64>,
    /// For each mass nonzero: its slot in `chol` (always the lower triangle).
    mass_dest: Vec<usize>,
    // Rows of Φq touching block b: `brows[brow_ptr[b]..brow_ptr[b+1]]`, ascending.
    brow_ptr: Vec<usize>,
    brows: Vec<usize>,
    /// Offset of block b's dense `rows × block size` slice of Φq in `wmat`.
    p_off: Vec<usize>,
    /// Φq_b (rows touching block b, row by row), overwritten by `W_b = L_b⁻¹ Φq_bᵀ`.
    wmat: Vec<f64>,
    /// Reciprocals of the diagonal of the block Cholesky factors, by position in `block_coords`.
    inv_diag: Vec<f64>,
    /// `L_b⁻¹ f_b` between the two halves of a solve, by position in `block_coords`.
    ustore: Vec<f64>,
    phi_q_dest: Vec<usize>,
    /// For each block, the destinations of `S[a, b]` (local rows `a ≥ b`, row-major order):
    /// slots of `lval`, and for `a = b` of `diag`.
    pair_ptr: Vec<usize>,
    pair_dest: Vec<usize>,
    sym: Symbolic,
    /// Strictly-lower entries of L, column by column as in `sym`.
    lval: Vec<f64>,
    /// D of `LDLᵀ` (permuted order); before factorization it holds diag(S).
    diag: Vec<f64>,
    /// 1/D, or 0 for a dropped (rank-deficient or redundant) pivot.
    dinv: Vec<f64>,
    /// By permuted position: the row is redundant (declared in the pattern) and dropped.
    redundant: Vec<bool>,
    /// Column k's updates of the later columns, `updates[update_ptr[k]..update_ptr[k + 1]]`:
    /// `(a, b, dest)` means `lval[dest] -= L[a]·D[k]·L[b]` for two entries `a`, `b` of
    /// column k (rows r_a > r_b) and `dest` the slot of `L[r_a, r_b]`. Listed once when the
    /// solver is built, so the numeric factorization is one flat loop per column instead of
    /// short, variable-length loops whose exits the branch predictor misses (12 bytes per
    /// multiply-add of the factorization: 160 kB for the 40-bar chain of IFToMM A02).
    update_ptr: Vec<usize>,
    updates: Vec<[u32; 3]>,
    /// The scale of each pivot's rank-loss test: diag(S) once the normalization rows are
    /// eliminated (the row's own squared length in the kinetic metric on the configuration
    /// space, so the relative pivots do not depend on the rotation coordinates).
    scale: Vec<f64>,
    /// Normalization rows, eliminated first ([`KktPattern::normalization_rows`]).
    n_first: usize,
    work: Vec<f64>,
    rvec: Vec<f64>,
    factored: bool,
    pivot_tol: f64,
    /// Rows with a pivot below `pivot_tol` are dropped instead of reported
    /// ([`KktSolver::drop_dependent_rows`]).
    drop_dependent: bool,
    /// Of the last factorization ([`KktSolver::pivots`]).
    pivots: Pivots,
    /// The solver for a semi-definite `M`; every other field is then empty.
    dense: Option<Box<DenseKkt>>,
    /// The generator's straight-line factor and solve for this pattern, when it emitted them,
    /// and the state they keep between the two ([`KktKernels`]).
    kernels: Option<&'static KktKernels>,
    state: Vec<f64>,
}

/// The symbolic analysis of a [`SchurKkt`]: what the generator needs to emit its numeric
/// factorization and solve as straight-line code ([`KktKernels`]). Slots index the solver's
/// work arrays as `SchurKkt::factor` uses them.
#[derive(Debug, Clone, Copy)]
pub struct SchurPlan<'a> {
    /// Group `b` holds the coordinates `block_coords[block_ptr[b]..block_ptr[b + 1]]`.
    pub block_ptr: &'a [usize],
    pub block_coords: &'a [usize],
    /// Offset of group `b`'s dense `s × s` block (row-major) in the Cholesky array.
    pub chol_off: &'a [usize],
    /// Length of the Cholesky array.
    pub chol_len: usize,
    /// For each mass nonzero, its slot in the Cholesky array (lower triangle).
    pub mass_dest: &'a [usize],
    /// Rows of Φq touching group `b`: `brows[brow_ptr[b]..brow_ptr[b + 1]]`.
    pub brow_ptr: &'a [usize],
    pub brows: &'a [usize],
    /// Offset of group `b`'s `rows × s` slice of `W` in the `W` array.
    pub p_off: &'a [usize],
    /// Length of the `W` array; its last slot is the dummy that takes redundant rows' entries.
    pub w_len: usize,
    /// For each Φq nonzero, its slot in the `W` array.
    pub phi_q_dest: &'a [usize],
    /// Destinations of group `b`'s products `W_aᵀ W_b` (see `SchurKkt::factor`).
    pub pair_ptr: &'a [usize],
    pub pair_dest: &'a [usize],
    /// Pivot order: position `k` eliminates row `perm[k]`.
    pub perm: &'a [usize],
    /// Strictly-lower pattern of L, column by column, in pivot positions.
    pub col_ptr: &'a [usize],
    pub row_idx: &'a [usize],
    /// Column `k`'s updates `updates[update_ptr[k]..update_ptr[k + 1]]`: `(a, b, dest)`,
    /// `L[dest] −= L[a]·D[k]·L[b]` (slots of `row_idx`).
    pub update_ptr: &'a [usize],
    pub updates: &'a [[u32; 3]],
    /// By pivot position: a declared redundant row.
    pub redundant: &'a [bool],
    /// Number of normalization rows, eliminated first.
    pub n_first: usize,
}

impl SchurKkt {
    /// Number of structural nonzeros of the factor `L` (strict lower triangle); 0 when a
    /// semi-definite `M` is solved densely or the generated kernels run.
    pub fn factor_nnz(&self) -> usize {
        self.lval.len()
    }

    /// Sizes of the detected diagonal blocks of `M` (connected components of its pattern),
    /// in order of their first coordinate; empty when a semi-definite `M` is solved densely or
    /// the generated kernels run (no analysis is made then).
    pub fn block_sizes(&self) -> Vec<usize> {
        self.component_sizes.clone()
    }

    /// Whether this solver runs the dense LU because `M` is only semi-definite.
    pub fn is_dense(&self) -> bool {
        self.dense.is_some()
    }

    /// Whether factor and solve run the generator's straight-line kernels for this pattern.
    pub fn runs_kernels(&self) -> bool {
        self.kernels.is_some()
    }

    /// The symbolic analysis, for the generator; `None` when `M` is solved densely or the
    /// generated kernels run.
    pub fn plan(&self) -> Option<SchurPlan<'_>> {
        (self.dense.is_none() && self.kernels.is_none()).then_some(SchurPlan {
            block_ptr: &self.block_ptr,
            block_coords: &self.block_coords,
            chol_off: &self.chol_off,
            chol_len: self.chol.len(),
            mass_dest: &self.mass_dest,
            brow_ptr: &self.brow_ptr,
            brows: &self.brows,
            p_off: &self.p_off,
            w_len: self.wmat.len(),
            phi_q_dest: &self.phi_q_dest,
            pair_ptr: &self.pair_ptr,
            pair_dest: &self.pair_dest,
            perm: &self.sym.perm,
            col_ptr: &self.sym.col_ptr,
            row_idx: &self.sym.row_idx,
            update_ptr: &self.update_ptr,
            updates: &self.updates,
            redundant: &self.redundant,
            n_first: self.n_first,
        })
    }

    /// A solver without the symbolic analysis: the dense LU for a semi-definite `M`, or the
    /// generator's kernels for this pattern, which carry their own.
    fn without_analysis(
        pattern: &KktPattern,
        dense: Option<Box<DenseKkt>>,
        kernels: Option<&'static KktKernels>,
    ) -> Self {
        SchurKkt {
            n: pattern.n,
            m: pattern.m,
            component_sizes: Vec::new(),
            block_ptr: vec![0],
            block_coords: Vec::new(),
            chol_off: Vec::new(),
            chol: Vec::new(),
            mass_dest: Vec::new(),
            brow_ptr: vec![0],
            brows: Vec::new(),
            p_off: Vec::new(),
            wmat: Vec::new(),
            inv_diag: Vec::new(),
            ustore: Vec::new(),
            phi_q_dest: Vec::new(),
            pair_ptr: vec![0],
            pair_dest: Vec::new(),
            sym: minimum_degree(0, &[], &[]),
            lval: Vec::new(),
            diag: Vec::new(),
            dinv: Vec::new(),
            redundant: Vec::new(),
            update_ptr: vec![0],
            updates: Vec::new(),
            scale: Vec::new(),
            n_first: 0,
            work: Vec::new(),
            rvec: Vec::new(),
            factored: false,
            pivot_tol: DEFAULT_PIVOT_TOLERANCE,
            drop_dependent: false,
            pivots: Pivots::default(),
            dense,
            kernels,
            state: vec![0.0; kernels.map_or(0, |k| k.storage)],
        }
    }
}

// The block kernels take the block size `s` as an argument and are always inlined: every
// call site goes through `sized!`, which passes a literal 3, 6 or 7 when the group has a
// body's three (planar), six (Euler) or seven (quaternion) coordinates, so the compiler sees a
// constant size, unrolls the loops and drops bounds checks; other sizes run the same code
// with a variable.

/// Evaluates `$body` with `$n` bound to the literal group size for 3, 6 and 7, else to `$s`.
macro_rules! sized {
    ($s:expr, |$n:ident| $body:expr) => {
        match $s {
            3 => {
                let $n = 3;
                $body
            }
            6 => {
                let $n = 6;
                $body
            }
            7 => {
                let $n = 7;
                $body
            }
            _ => {
                let $n = $s;
                $body
            }
        }
    };
}

/// `v ← L⁻¹ v` for the row-major lower-triangular `l` (`s × s`) with reciprocal diagonal `inv`.
#[inline(always)]
fn forward(l: &[f64], inv: &[f64], s: usize, v: &mut [f64]) {
    let (l, inv, v) = (&l[..s * s], &inv[..s], &mut v[..s]);
    for i in 0..s {
        let mut t = v[i];
        for j in 0..i {
            t -= l[i * s + j] * v[j];
        }
        v[i] = t * inv[i];
    }
}

/// [`forward`] on four vectors at once (`v` holds them one after another, each `s` long):
/// four independent sums per step keep the multiply-add pipeline full where one vector
/// waits on each addition; each vector's sum runs in the same order, so the result is
/// bitwise that of four calls. It is for a large group (bodies coupled through a load's
/// stiffness: 21 coordinates in IFToMM A05), whose long chains the processor cannot overlap
/// as it does a small group's (measured on A05 with the Cholesky below: the factorization's
/// instructions −12 %, wall time −7 %, within the machine's noise).
#[inline(always)]
fn forward4(l: &[f64], inv: &[f64], s: usize, v: &mut [f64]) {
    let (l, inv, v) = (&l[..s * s], &inv[..s], &mut v[..4 * s]);
    for i in 0..s {
        let mut t = [v[i], v[s + i], v[2 * s + i], v[3 * s + i]];
        for j in 0..i {
            let a = l[i * s + j];
            t[0] -= a * v[j];
            t[1] -= a * v[s + j];
            t[2] -= a * v[2 * s + j];
            t[3] -= a * v[3 * s + j];
        }
        for (r, t) in t.into_iter().enumerate() {
            v[r * s + i] = t * inv[i];
        }
    }
}

/// `v ← L⁻ᵀ v`.
#[inline(always)]
fn backward(l: &[f64], inv: &[f64], s: usize, v: &mut [f64]) {
    let (l, inv, v) = (&l[..s * s], &inv[..s], &mut v[..s]);
    for i in (0..s).rev() {
        let mut t = v[i];
        for j in i + 1..s {
            t -= l[j * s + i] * v[j];
        }
        v[i] = t * inv[i];
    }
}

/// `v ← v − Σ_k y[rows[k]] · w_k` for the rows `w_k` (each `s` long) of `w`.
#[inline(always)]
fn subtract_rows(w: &[f64], rows: &[usize], y: &[f64], s: usize, v: &mut [f64]) {
    let (w, v) = (&w[..rows.len() * s], &mut v[..s]);
    for (k, &r) in rows.iter().enumerate() {
        let yr = y[r];
        let wk = &w[k * s..k * s + s];
        for i in 0..s {
            v[i] -= wk[i] * yr;
        }
    }
}

#[inline(always)]
fn dot(a: &[f64], b: &[f64], s: usize) -> f64 {
    let (a, b) = (&a[..s], &b[..s]);
    let mut t = 0.0;
    for i in 0..s {
        t += a[i] * b[i];
    }
    t
}

/// Cholesky of the `s × s` block `a` in place (lower triangle, row-major); `inv` gets the
/// reciprocal diagonal. On failure returns the local index of the bad pivot and whether it
/// was NaN.
#[inline(always)]
fn cholesky(a: &mut [f64], inv: &mut [f64], s: usize) -> Result<(), (usize, bool)> {
    let (a, inv) = (&mut a[..s * s], &mut inv[..s]);
    for j in 0..s {
        let mut d = a[j * s + j];
        for k in 0..j {
            d -= a[j * s + k] * a[j * s + k];
        }
        // Positive and finite, tested as the generated kernels do (`codegen/src/kkt.rs`).
        if !(d > 0.0 && d <= f64::MAX) {
            return Err((j, d.is_nan()));
        }
        let d = d.sqrt();
        a[j * s + j] = d;
        let r = 1.0 / d;
        inv[j] = r;
        // Four rows at a time, each summed in the same order (as `forward4`).
        let mut i = j + 1;
        while i + 4 <= s {
            let mut t = [
                a[i * s + j],
                a[(i + 1) * s + j],
                a[(i + 2) * s + j],
                a[(i + 3) * s + j],
            ];
            for k in 0..j {
                let b = a[j * s + k];
                t[0] -= a[i * s + k] * b;
                t[1] -= a[(i + 1) * s + k] * b;
                t[2] -= a[(i + 2) * s + k] * b;
                t[3] -= a[(i + 3) * s + k] * b;
            }
            for (q, t) in t.into_iter().enumerate() {
                a[(i + q) * s + j] = t * r;
            }
            i += 4;
        }
        for i in i..s {
            let mut t = a[i * s + j];
            for k in 0..j {
                t -= a[i * s + k] * a[j * s + k];
            }
            a[i * s + j] = t * r;
        }
    }
    Ok(())
}

/// One group's share of the factorization: Cholesky of its mass block, `W = L⁻¹ Φq_bᵀ` row
/// by row, and `S += WᵀW` scattered through the precomputed destinations.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn factor_group(
    s: usize,
    a: &mut [f64],
    inv: &mut [f64],
    w: &mut [f64],
    dest: &[usize],
    diag: &mut [f64],
    lval: &mut [f64],
) -> Result<(), (usize, bool)> {
    cholesky(a, inv, s)?;
    let k = w.len() / s;
    let mut rows = w.chunks_exact_mut(4 * s);
    for four in &mut rows {
        forward4(a, inv, s, four);
    }
    for row in rows.into_remainder().chunks_exact_mut(s) {
        forward(a, inv, s, row);
    }
    // Row i's destinations: its i products with the rows before it (slots of L), then its
    // own square (a slot of D): the stream holds i + 1 entries per row.
    let mut at = 0;
    for i in 0..k {
        let wi = &w[i * s..i * s + s];
        let (off, d) = (&dest[at..at + i], dest[at + i]);
        at += i + 1;
        // Four rows at a time: four independent sums keep the multiply-add pipeline full,
        // where one dot product at a time waits on each addition (each sum is still added
        // in the same order, so the result is unchanged).
        let mut j = 0;
        while j + 4 <= i {
            for (v, &d) in dot4(wi, &w[j * s..(j + 4) * s], s)
                .into_iter()
                .zip(&off[j..j + 4])
            {
                lval[d] += v;
            }
            j += 4;
        }
        for j in j..i {
            lval[off[j]] += dot(wi, &w[j * s..j * s + s], s);
        }
        diag[d] += dot(wi, wi, s);
    }
    Ok(())
}

/// The dot products of `a` with the four consecutive rows of `b` (each `s` long).
#[inline(always)]
fn dot4(a: &[f64], b: &[f64], s: usize) -> [f64; 4] {
    let (a, b) = (&a[..s], &b[..4 * s]);
    let mut t = [0.0; 4];
    for c in 0..s {
        let x = a[c];
        t[0] += x * b[c];
        t[1] += x * b[s + c];
        t[2] += x * b[2 * s + c];
        t[3] += x * b[3 * s + c];
    }
    t
}

fn find(parent: &mut [usize], mut i: usize) -> usize {
    while parent[i] != i {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    i
}

impl KktSolver for SchurKkt {
    fn drop_dependent_rows(&mut self, tolerance: f64) -> bool {
        if let Some(d) = &mut self.dense {
            return d.drop_dependent_rows(tolerance);
        }
        self.pivot_tol = tolerance;
        self.drop_dependent = true;
        true
    }

    fn new(pattern: &KktPattern) -> Result<Self, Error> {
        pattern.validate()?;
        if pattern.mass_semidefinite {
            let dense = Box::new(DenseKkt::new(pattern)?);
            return Ok(Self::without_analysis(pattern, Some(dense), None));
        }
        // Generated kernels were emitted for this pattern's own analysis: the ordering and
        // slot tables below would go unused (1.3 M instructions for the Stewart model).
        let fingerprint = pattern.fingerprint();
        let kernels = pattern.kernels.iter().find(|k| k.pattern == fingerprint);
        if let Some(kernels) = kernels.filter(|_| kernels_run_here()) {
            return Ok(Self::without_analysis(pattern, None, Some(kernels)));
        }
        let (n, m) = (pattern.n, pattern.m);

        // Blocks of M = connected components of its pattern graph.
        let mut parent: Vec<usize> = (0..n).collect();
        let mut has_diag = vec![false; n];
        for (&r, &c) in pattern.mass_rows.iter().zip(&pattern.mass_cols) {
            let (r, c) = (r as usize, c as usize);
            if r == c {
                has_diag[r] = true;
            }
            let (a, b) = (find(&mut parent, r), find(&mut parent, c));
            if a != b {
                parent[a.max(b)] = a.min(b);
            }
        }
        if let Some(c) = has_diag.iter().position(|&d| !d) {
            return Err(Error::InvalidPattern {
                reason: format!("mass pattern has no diagonal entry for coordinate {c}"),
            });
        }
        let mut root_block = vec![usize::MAX; n];
        let mut members: Vec<Vec<usize>> = Vec::new();
        for c in 0..n {
            let r = find(&mut parent, c);
            if root_block[r] == usize::MAX {
                root_block[r] = members.len();
                members.push(Vec::new());
            }
            members[root_block[r]].push(c);
        }
        let component_sizes = members.iter().map(Vec::len).collect();
        // Consecutive components are merged into groups of up to GROUP_MAX coordinates, as
        // long as one of them touches every constraint row the others touch: a body's
        // coordinates (exact formulation: three 1×1 translation blocks and a 3×3 or 4×4
        // rotation block touching all of the body's rows; the paper's six 1×1 blocks; a
        // planar body's x, y and γ) and no further. Per-block overhead (slicing, the scatter
        // of `S += WᵀW` pairs, once per block over the same rows) costs more than the
        // structural zeros of a dense group (Cholesky keeps them exactly zero); a group
        // spanning two bodies would instead couple their rows in S and add fill.
        let mut is_redundant = vec![false; m];
        for &r in &pattern.redundant_rows {
            is_redundant[r as usize] = true;
        }
        let mut component_of = vec![0; n];
        for (k, mem) in members.iter().enumerate() {
            for &c in mem {
                component_of[c] = k;
            }
        }
        let mut component_rows: Vec<Vec<usize>> = vec![Vec::new(); members.len()];
        for (&r, &c) in pattern.phi_q_rows.iter().zip(&pattern.phi_q_cols) {
            if !is_redundant[r as usize] {
                component_rows[component_of[c as usize]].push(r as usize);
            }
        }
        for rows in &mut component_rows {
            rows.sort_unstable();
            rows.dedup();
        }
        let mut groups: Vec<Vec<usize>> = Vec::new();
        let mut first = 0;
        while first < members.len() {
            let mut end = first;
            let (mut size, mut union) = (members[first].len(), component_rows[first].clone());
            for next in first + 1..members.len() {
                size += members[next].len();
                if size > GROUP_MAX {
                    break;
                }
                union.extend_from_slice(&component_rows[next]);
                union.sort_unstable();
                union.dedup();
                // Each member's rows lie in the union: equal sizes mean equal sets.
                if (first..=next).any(|k| component_rows[k].len() == union.len()) {
                    end = next;
                }
            }
            groups.push(members[first..=end].concat());
            first = end + 1;
        }
        let members = groups;
        let nb = members.len();
        let mut coord_block = vec![0; n];
        let mut coord_local = vec![0; n];
        let mut block_ptr = vec![0];
        let mut block_coords = Vec::with_capacity(n);
        let mut chol_off = Vec::with_capacity(nb);
        let mut chol_len = 0;
        for (b, mem) in members.iter().enumerate() {
            for (l, &c) in mem.iter().enumerate() {
                coord_block[c] = b;
                coord_local[c] = l;
            }
            block_coords.extend_from_slice(mem);
            block_ptr.push(block_coords.len());
            chol_off.push(chol_len);
            chol_len += mem.len() * mem.len();
        }
        let mass_dest = pattern
            .mass_rows
            .iter()
            .zip(&pattern.mass_cols)
            .map(|(&r, &c)| {
                let b = coord_block[r as usize];
                let s = members[b].len();
                let (lr, lc) = (coord_local[r as usize], coord_local[c as usize]);
                chol_off[b] + lr.max(lc) * s + lr.min(lc)
            })
            .collect();

        // Rows of Φq touching each block; redundant rows touch none.
        let mut touch: Vec<Vec<usize>> = vec![Vec::new(); nb];
        for (&r, &c) in pattern.phi_q_rows.iter().zip(&pattern.phi_q_cols) {
            if !is_redundant[r as usize] {
                touch[coord_block[c as usize]].push(r as usize);
            }
        }
        for t in &mut touch {
            t.sort_unstable();
            t.dedup();
        }
        let mut brow_ptr = vec![0];
        let mut brows = Vec::new();
        let mut p_off = Vec::with_capacity(nb);
        let mut p_len = 0;
        for (b, t) in touch.iter().enumerate() {
            brows.extend_from_slice(t);
            brow_ptr.push(brows.len());
            p_off.push(p_len);
            p_len += t.len() * members[b].len();
        }
        // The dummy slot past every block's slice takes the redundant rows' nonzeros.
        let dummy = p_len;
        let phi_q_dest = pattern
            .phi_q_rows
            .iter()
            .zip(&pattern.phi_q_cols)
            .map(|(&r, &c)| {
                if is_redundant[r as usize] {
                    return dummy;
                }
                let b = coord_block[c as usize];
                let a = touch[b].binary_search(&(r as usize)).expect("row recorded");
                p_off[b] + a * members[b].len() + coord_local[c as usize]
            })
            .collect();

        // Pattern of S: rows sharing a block are coupled.
        let mut edges = Vec::new();
        for t in &touch {
            for (i, &a) in t.iter().enumerate() {
                for &b in &t[..i] {
                    edges.push((a, b));
                }
            }
        }
        // The normalization rows go first: each couples only rows of its own body, which S
        // couples already, so eliminating them adds no fill, and the rows after them keep
        // the order they would have in the same model without them (Euler angles).
        let normalization: Vec<usize> = pattern
            .normalization_rows
            .iter()
            .map(|&r| r as usize)
            .collect();
        let sym = minimum_degree(m, &edges, &normalization);
        let slot = |i: usize, j: usize| -> usize {
            // Position of S[i, j] (original indices) in `lval`, or in `diag` for i = j.
            let (pi, pj) = (sym.iperm[i], sym.iperm[j]);
            if pi == pj {
                return pi;
            }
            let (row, col) = (pi.max(pj), pi.min(pj));
            let range = sym.col_ptr[col]..sym.col_ptr[col + 1];
            let off = sym.row_idx[range.clone()]
                .binary_search(&row)
                .expect("S pattern lies inside the symbolic factor");
            range.start + off
        };
        let mut pair_ptr = vec![0];
        let mut pair_dest = Vec::new();
        for t in &touch {
            for (a, &ra) in t.iter().enumerate() {
                for &rb in &t[..=a] {
                    pair_dest.push(slot(ra, rb));
                }
            }
            pair_ptr.push(pair_dest.len());
        }

        let index = |i: usize| {
            u32::try_from(i).map_err(|_| Error::InvalidPattern {
                reason: format!("factor too large: {i} nonzeros"),
            })
        };
        let mut update_ptr = vec![0];
        let mut updates = Vec::new();
        for k in 0..m {
            let col = sym.col_ptr[k]..sym.col_ptr[k + 1];
            for a in col.clone() {
                for b in col.start..a {
                    let (ra, rb) = (sym.row_idx[a], sym.row_idx[b]);
                    let target = sym.col_ptr[rb]..sym.col_ptr[rb + 1];
                    let off = sym.row_idx[target.clone()]
                        .binary_search(&ra)
                        .expect("fill lies inside the symbolic factor");
                    updates.push([index(a)?, index(b)?, index(target.start + off)?]);
                }
            }
            update_ptr.push(updates.len());
        }

        let lnnz = sym.row_idx.len();
        assert!(
            updates.iter().flatten().all(|&i| (i as usize) < lnnz),
            "update slots lie in the factor"
        );
        let redundant = sym.perm.iter().map(|&r| is_redundant[r]).collect();
        Ok(SchurKkt {
            n,
            m,
            component_sizes,
            block_ptr,
            block_coords,
            chol_off,
            chol: vec![0.0; chol_len],
            mass_dest,
            brow_ptr,
            brows,
            p_off,
            wmat: vec![0.0; p_len + 1],
            inv_diag: vec![0.0; n],
            ustore: vec![0.0; n],
            phi_q_dest,
            pair_ptr,
            pair_dest,
            sym,
            lval: vec![0.0; lnnz],
            diag: vec![0.0; m],
            dinv: vec![0.0; m],
            redundant,
            update_ptr,
            updates,
            scale: vec![0.0; m],
            n_first: normalization.len(),
            work: vec![0.0; m],
            rvec: vec![0.0; m],
            factored: false,
            pivot_tol: DEFAULT_PIVOT_TOLERANCE,
            drop_dependent: false,
            pivots: Pivots::default(),
            dense: None,
            kernels: None,
            state: Vec::new(),
        })
    }

    fn factor(&mut self, mass: &[f64], mass_scale: f64, phi_q: &[f64]) -> Result<(), KktError> {
        if let Some(d) = &mut self.dense {
            return d.factor(mass, mass_scale, phi_q);
        }
        self.factored = false;
        if let Some(kernels) = self.kernels {
            // The kernels check the lengths themselves.
            let mut pivoting = Pivoting::new(self.pivot_tol, self.drop_dependent);
            (kernels.factor)(mass, mass_scale, phi_q, &mut self.state, &mut pivoting)?;
            self.pivots = pivoting.finish()?;
            self.factored = true;
            return Ok(());
        }
        check_kkt_len(self.mass_dest.len(), mass.len())?;
        check_kkt_len(self.phi_q_dest.len(), phi_q.len())?;

        // Per group: Cholesky of c·M_b (lower triangle, row-major), W_b = L_b⁻¹ Φq_bᵀ and
        // S += W_bᵀ W_b.
        self.chol.fill(0.0);
        for (&d, &v) in self.mass_dest.iter().zip(mass) {
            self.chol[d] = mass_scale * v;
        }
        self.wmat.fill(0.0);
        for (&d, &v) in self.phi_q_dest.iter().zip(phi_q) {
            if !v.is_finite() {
                return Err(KktError::NotFinite);
            }
            self.wmat[d] = v;
        }
        self.diag.fill(0.0);
        self.lval.fill(0.0);
        let nb = self.chol_off.len();
        for b in 0..nb {
            let (c0, c1) = (self.block_ptr[b], self.block_ptr[b + 1]);
            let s = c1 - c0;
            let k = self.brow_ptr[b + 1] - self.brow_ptr[b];
            let a = &mut self.chol[self.chol_off[b]..self.chol_off[b] + s * s];
            let inv = &mut self.inv_diag[c0..c1];
            let w = &mut self.wmat[self.p_off[b]..self.p_off[b] + k * s];
            let dest = &self.pair_dest[self.pair_ptr[b]..self.pair_ptr[b + 1]];
            let (diag, lval) = (&mut self.diag[..], &mut self.lval[..]);
            let done = sized!(s, |n| factor_group(n, a, inv, w, dest, diag, lval));
            if let Err((j, nan)) = done {
                return Err(if nan {
                    KktError::NotFinite
                } else {
                    KktError::MassNotPositiveDefinite {
                        coord: self.block_coords[c0 + j],
                    }
                });
            }
        }

        // Right-looking LDLᵀ of S in place: column k, once final, updates the later columns
        // through its precomputed list. Rank loss shows as a pivot that is tiny relative to
        // the row's own diag(S).
        let mut pivoting = Pivoting::new(self.pivot_tol, self.drop_dependent);
        let sym = &self.sym;
        self.scale.copy_from_slice(&self.diag);
        for k in 0..self.m {
            if k == self.n_first {
                self.scale[k..].copy_from_slice(&self.diag[k..]);
            }
            let col = sym.col_ptr[k]..sym.col_ptr[k + 1];
            let (inv, dk) =
                pivoting.pivot(self.diag[k], self.scale[k], sym.perm[k], self.redundant[k])?;
            self.dinv[k] = inv;
            if inv == 0.0 {
                // Dropped: solved as absent (y = 0), as a redundant row. (Clamping the pivot
                // instead keeps the row corrected, but Newton then converges too slowly along
                // the nearly dependent direction to finish a step.)
                self.lval[col].fill(0.0);
                continue;
            }
            let lcol = &mut self.lval[col.clone()];
            for (l, &r) in lcol.iter_mut().zip(&sym.row_idx[col]) {
                *l *= inv;
                self.diag[r] -= *l * dk * *l;
            }
            let lval = &mut self.lval[..];
            for &[a, b, dest] in &self.updates[self.update_ptr[k]..self.update_ptr[k + 1]] {
                // SAFETY: `new` asserted every index of `updates` below `lval.len()`, which
                // never changes. (The three bounds checks were 9 % of the factorization's
                // instructions, on the Stewart model and on A02's 40 four-bars alike.)
                unsafe {
                    *lval.get_unchecked_mut(dest as usize) -=
                        *lval.get_unchecked(a as usize) * dk * *lval.get_unchecked(b as usize);
                }
            }
        }
        self.pivots = pivoting.finish()?;
        self.factored = true;
        Ok(())
    }

    fn pivots(&self) -> Option<Pivots> {
        self.factored.then_some(self.pivots)
    }

    fn solve(
        &mut self,
        f: &[f64],
        g: &[f64],
        x: &mut [f64],
        y: &mut [f64],
    ) -> Result<(), KktError> {
        if let Some(d) = &mut self.dense {
            return d.solve(f, g, x, y);
        }
        if !self.factored {
            return Err(KktError::NotFactored);
        }
        check_kkt_len(self.n, f.len())?;
        check_kkt_len(self.m, g.len())?;
        check_kkt_len(self.n, x.len())?;
        check_kkt_len(self.m, y.len())?;
        if let Some(kernels) = self.kernels {
            return (kernels.solve)(f, g, x, y, &self.state);
        }
        let nb = self.chol_off.len();

        // With u_b = L_b⁻¹ f_b: Φq M⁻¹ f = Σ_b W_bᵀ u_b, so r = Φq M⁻¹ f − g needs only
        // forward substitutions, and u is kept for x below.
        for (r, &gi) in self.rvec.iter_mut().zip(g) {
            *r = -gi;
        }
        // f = 0 (a position correction, the least-energy velocity): u = 0 adds nothing to r.
        let f_nonzero = f.iter().any(|&v| v != 0.0);
        if !f_nonzero {
            self.ustore.fill(0.0);
        }
        for b in (0..nb).filter(|_| f_nonzero) {
            let (c0, c1) = (self.block_ptr[b], self.block_ptr[b + 1]);
            let s = c1 - c0;
            let u = &mut self.ustore[c0..c1];
            for (l, &c) in u.iter_mut().zip(&self.block_coords[c0..c1]) {
                *l = f[c];
            }
            let l = &self.chol[self.chol_off[b]..self.chol_off[b] + s * s];
            let inv = &self.inv_diag[c0..c1];
            let rows = &self.brows[self.brow_ptr[b]..self.brow_ptr[b + 1]];
            let w = &self.wmat[self.p_off[b]..self.p_off[b] + rows.len() * s];
            sized!(s, |n| {
                forward(l, inv, n, u);
                for (&r, wrow) in rows.iter().zip(w.chunks_exact(n)) {
                    self.rvec[r] += dot(wrow, u, n);
                }
            });
        }
        let sym = &self.sym;
        let z = &mut self.work;
        for (k, zk) in z.iter_mut().enumerate() {
            *zk = self.rvec[sym.perm[k]];
        }
        for j in 0..self.m {
            let zj = z[j];
            let col = sym.col_ptr[j]..sym.col_ptr[j + 1];
            for (&r, &l) in sym.row_idx[col.clone()].iter().zip(&self.lval[col]) {
                z[r] -= l * zj;
            }
        }
        for (zj, &d) in z.iter_mut().zip(&self.dinv) {
            *zj *= d;
        }
        for j in (0..self.m).rev() {
            let col = sym.col_ptr[j]..sym.col_ptr[j + 1];
            let mut t = z[j];
            for (&r, &l) in sym.row_idx[col.clone()].iter().zip(&self.lval[col]) {
                t -= l * z[r];
            }
            z[j] = t;
        }
        for (k, &zk) in z.iter().enumerate() {
            y[sym.perm[k]] = zk;
        }

        // x = M⁻¹ (f − Φqᵀ y) = L⁻ᵀ (u − W y), group by group.
        for b in 0..nb {
            let (c0, c1) = (self.block_ptr[b], self.block_ptr[b + 1]);
            let s = c1 - c0;
            let v = &mut self.ustore[c0..c1];
            let l = &self.chol[self.chol_off[b]..self.chol_off[b] + s * s];
            let inv = &self.inv_diag[c0..c1];
            let rows = &self.brows[self.brow_ptr[b]..self.brow_ptr[b + 1]];
            let w = &self.wmat[self.p_off[b]..self.p_off[b] + rows.len() * s];
            sized!(s, |n| {
                subtract_rows(w, rows, y, n, v);
                backward(l, inv, n, v);
            });
            for (&vi, &c) in v.iter().zip(&self.block_coords[c0..c1]) {
                x[c] = vi;
            }
        }
        Ok(())
    }
}
