//! The KKT factor and solve of one model as straight-line Rust: `SchurKkt`'s numeric
//! factorization and solve, replayed on the model's fixed pattern with every index a
//! constant and every multiply-add by a structural zero left out
//! (`symbody_runtime::kkt::KktKernels`).
//!
//! The replay follows `SchurKkt::factor` and `SchurKkt::solve` operation by operation (the
//! same sums in the same order), on values that are either a structural zero or a named
//! local: a term with a zero factor is skipped, which changes no result but the sign of a
//! zero. What the factorization leaves for the solves (the block factors, `W`, `L`, `1/D`)
//! is stored once, in a state array whose slots the solve reads.

use std::fmt::Write;

use proc_macro2::TokenStream;
use symbody_runtime::kkt::{KktPattern, KktSolver, SchurKkt, SchurPlan};

/// Above this many emitted operations the kernels are not emitted: the model runs
/// `SchurKkt`'s loops, whose per-entry overhead matters least on long chains, and the
/// generated crate stays quick to compile.
const MAX_OPS: usize = 30_000;

/// A value of the replay: a structural zero, a local `v{n}`, or a slot `st[n]` of the
/// state the factorization left.
#[derive(Debug, Clone, Copy, PartialEq)]
enum V {
    Zero,
    Var(u32),
    Slot(u32),
    /// `c · mass[i]` and `phi_q[i]`, written where they are used: bound at the top they
    /// lived through the whole factorization, and LLVM spilled and reloaded every one.
    Mass(u32),
    PhiQ(u32),
    /// An entry of the solve's `x` or `y`, which hold `u` and `r` in between.
    In(&'static str, u32),
}

impl std::fmt::Display for V {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            V::Zero => write!(f, "0.0"),
            V::Var(i) => write!(f, "v{i}"),
            V::Slot(i) => write!(f, "st[{i}]"),
            V::Mass(i) => write!(f, "(c * mass[{i}])"),
            V::PhiQ(i) => write!(f, "phi_q[{i}]"),
            V::In(a, i) => write!(f, "{a}[{i}]"),
        }
    }
}

/// Straight-line code under construction.
#[derive(Default)]
struct Code {
    lines: Vec<String>,
    /// The line defining each local `v{n}`.
    defined_at: Vec<usize>,
    /// Stores of locals into the state, each to be written right after its local's
    /// definition (`(line, store)`): a value stored at once need not stay live (spilled)
    /// until the end. The state is read only by the solves, after a successful factor.
    stores: Vec<(usize, String)>,
    next: u32,
    ops: usize,
}

impl Code {
    fn line(&mut self, s: &str) {
        self.lines.push(s.to_owned());
    }

    /// Names the next `count` locals, defined by the line emitted next.
    fn locals(&mut self, count: u32) -> u32 {
        let first = self.next;
        self.next += count;
        let at = self.lines.len();
        self.defined_at.resize(self.next as usize, at);
        first
    }

    fn bind(&mut self, expr: std::fmt::Arguments<'_>) -> V {
        let id = self.locals(1);
        self.ops += 1;
        self.lines.push(format!("let v{id}: f64 = {expr};"));
        V::Var(id)
    }

    /// `st[slot] = v`, next to `v`'s definition when it is a local.
    fn store(&mut self, slot: usize, v: V) {
        let line = format!("st[{slot}] = {v};");
        match v {
            V::Var(id) => self.stores.push((self.defined_at[id as usize], line)),
            _ => self.lines.push(line),
        }
    }

    /// The code, each store after its local's definition.
    fn text(mut self) -> String {
        self.stores.sort_by_key(|&(at, _)| at);
        let mut stores = self.stores.into_iter().peekable();
        let mut text = String::new();
        for (i, l) in self.lines.iter().enumerate() {
            text.push_str(l);
            text.push('\n');
            while let Some((_, s)) = stores.next_if(|(at, _)| *at == i) {
                text.push_str(&s);
                text.push('\n');
            }
        }
        text
    }

    /// `acc − a·b` (`acc −= a * b` in the loops).
    fn sub_mul(&mut self, acc: V, a: V, b: V) -> V {
        match (acc, a, b) {
            (_, V::Zero, _) | (_, _, V::Zero) => acc,
            (V::Zero, ..) => self.bind(format_args!("-({a} * {b})")),
            _ => self.bind(format_args!("{acc} - {a} * {b}")),
        }
    }

    /// `acc − a·d·b` (the `LDLᵀ` updates).
    fn sub_mul3(&mut self, acc: V, a: V, d: V, b: V) -> V {
        match (acc, a, b) {
            (_, V::Zero, _) | (_, _, V::Zero) => acc,
            (V::Zero, ..) => self.bind(format_args!("-({a} * {d} * {b})")),
            _ => self.bind(format_args!("{acc} - {a} * {d} * {b}")),
        }
    }

    fn add(&mut self, acc: V, a: V) -> V {
        match (acc, a) {
            (_, V::Zero) => acc,
            (V::Zero, _) => a,
            _ => self.bind(format_args!("{acc} + {a}")),
        }
    }

    fn mul(&mut self, a: V, b: V) -> V {
        match (a, b) {
            (V::Zero, _) | (_, V::Zero) => V::Zero,
            _ => self.bind(format_args!("{a} * {b}")),
        }
    }

    /// `Σ a[i]·b[i]` summed in order from zero, as the loops' dot products.
    fn dot(&mut self, a: &[V], b: &[V]) -> V {
        let mut t = V::Zero;
        for (&x, &y) in a.iter().zip(b) {
            let p = self.mul(x, y);
            t = self.add(t, p);
        }
        t
    }
}

/// The emitted kernels: items for the model's module (`KKT`, one `KktKernels` per pattern
/// in `patterns` that is not solved densely and not too long, with `kkt_factor_{i}`,
/// `kkt_solve_{i}`, and one each of `kkt_transpose_times`, `kkt_times_add`, `kkt_mass_times`
/// and `kkt_kinetic_energy`), or `None` when there is none. The patterns (the model's, then
/// the one with its loads' stiffness) share `Φq`; the first's mass pattern is `INFO`'s.
pub fn kernels(patterns: &[KktPattern], loads: [(&[u32], &[u32]); 2]) -> Option<TokenStream> {
    let mut items = String::new();
    let mut entries = Vec::new();
    for (i, pattern) in patterns.iter().enumerate() {
        // The second pattern, where there is one, is the first's with the loads' stiffness.
        let assembly = (i == 1).then(|| assemble_loads(&patterns[0], pattern, loads));
        let loads_field = match &assembly {
            Some(_) => "Some(symbody_runtime::kkt::LoadsKernel { force_q_rows: &FORCE_Q_ROWS, force_q_cols: &FORCE_Q_COLS, force_qd_rows: &FORCE_QD_ROWS, force_qd_cols: &FORCE_QD_COLS, assemble: kkt_assemble_loads })",
            None => "None",
        };
        if let Some((text, entry)) = one(pattern, i, loads_field) {
            items.push_str(&text);
            items.push_str(assembly.as_deref().unwrap_or_default());
            entries.push(entry);
        }
    }
    let pattern = patterns.first()?;
    if entries.is_empty() {
        return None;
    }
    let (n, m, np) = (pattern.n, pattern.m, pattern.phi_q_rows.len());
    let nm = pattern.mass_rows.len();
    let k = entries.len();
    let text = format!(
        "use symbody_runtime::kkt::{{length_error, mass_pivot_error, KktError, KktKernels, Pivoting}};
/// The KKT factor and solve for this model's patterns, straight-line (`KktKernels`).
pub static KKT: [KktKernels; {k}] = [{}];
{items}
fn kkt_transpose_times(phi_q: &[f64], y: &[f64], out: &mut [f64]) -> Result<(), KktError> {{
let phi_q: &[f64; {np}] = phi_q.try_into().map_err(|_| length_error({np}, phi_q.len()))?;
let y: &[f64; {m}] = y.try_into().map_err(|_| length_error({m}, y.len()))?;
let out_len = out.len();
let out: &mut [f64; {n}] = out.try_into().map_err(|_| length_error({n}, out_len))?;
{}
Ok(())
}}
#[allow(clippy::assign_op_pattern)]
fn kkt_times_add(phi_q: &[f64], x: &[f64], out: &mut [f64]) -> Result<(), KktError> {{
let phi_q: &[f64; {np}] = phi_q.try_into().map_err(|_| length_error({np}, phi_q.len()))?;
let x: &[f64; {n}] = x.try_into().map_err(|_| length_error({n}, x.len()))?;
let out_len = out.len();
let out: &mut [f64; {m}] = out.try_into().map_err(|_| length_error({m}, out_len))?;
{}
Ok(())
}}
fn kkt_mass_times(mass: &[f64], v: &[f64], out: &mut [f64]) -> Result<(), KktError> {{
let mass: &[f64; {nm}] = mass.try_into().map_err(|_| length_error({nm}, mass.len()))?;
let v: &[f64; {n}] = v.try_into().map_err(|_| length_error({n}, v.len()))?;
let out_len = out.len();
let out: &mut [f64; {n}] = out.try_into().map_err(|_| length_error({n}, out_len))?;
{}
Ok(())
}}
fn kkt_kinetic_energy(mass: &[f64], qd: &[f64]) -> Result<f64, KktError> {{
let mass: &[f64; {nm}] = mass.try_into().map_err(|_| length_error({nm}, mass.len()))?;
let qd: &[f64; {n}] = qd.try_into().map_err(|_| length_error({n}, qd.len()))?;
let mut t = 0.0;
{}
Ok(0.5 * t)
}}
",
        entries.join(", "),
        transpose(pattern),
        times_add(pattern),
        mass_times(pattern),
        kinetic_energy(pattern)
    );
    Some(text.parse().expect("emitted kernels are Rust tokens"))
}

/// Factor and solve for one pattern, named with suffix `i`, and its `KktKernels` value.
fn one(pattern: &KktPattern, i: usize, loads: &str) -> Option<(String, String)> {
    let pattern = KktPattern {
        kernels: &[],
        ..pattern.clone()
    };
    let solver = SchurKkt::new(&pattern).ok()?;
    let plan = solver.plan()?;
    let mut factor = Code::default();
    let stored = replay_factor(&plan, &pattern, &mut factor);
    let mut solve = Code::default();
    replay_solve(&plan, &pattern, &stored, &mut solve);
    if factor.ops + solve.ops > MAX_OPS {
        return None;
    }
    let (n, m) = (pattern.n, pattern.m);
    let (nm, np) = (pattern.mass_rows.len(), pattern.phi_q_rows.len());
    let ns = stored.slots;
    let fingerprint = pattern.fingerprint();
    let entry = format!(
        "KktKernels {{ pattern: {fingerprint:#x}, storage: {ns}, factor: kkt_factor_{i}, solve: kkt_solve_{i}, phi_q_rows: &PHI_Q_ROWS, phi_q_cols: &PHI_Q_COLS, transpose_times: kkt_transpose_times, times_add: kkt_times_add, mass_rows: &MASS_ROWS, mass_cols: &MASS_COLS, mass_times: kkt_mass_times, kinetic_energy: kkt_kinetic_energy, loads: {loads} }}"
    );
    let text = format!(
        "{}
#[allow(unused_variables, unused_parens, clippy::neg_cmp_op_on_partial_ord, clippy::nonminimal_bool)]
#[inline(always)]
fn kkt_factor_{i}_any(mass: &[f64], c: f64, phi_q: &[f64], st: &mut [f64], piv: &mut Pivoting) -> Result<(), KktError> {{
let mass: &[f64; {nm}] = mass.try_into().map_err(|_| length_error({nm}, mass.len()))?;
let phi_q: &[f64; {np}] = phi_q.try_into().map_err(|_| length_error({np}, phi_q.len()))?;
let st_len = st.len();
let st: &mut [f64; {ns}] = st.try_into().map_err(|_| length_error({ns}, st_len))?;
{}
Ok(())
}}
{}
#[allow(unused_variables, clippy::neg_cmp_op_on_partial_ord, clippy::nonminimal_bool)]
#[inline(always)]
fn kkt_solve_{i}_any(f: &[f64], g: &[f64], x: &mut [f64], y: &mut [f64], st: &[f64]) -> Result<(), KktError> {{
let f: &[f64; {n}] = f.try_into().map_err(|_| length_error({n}, f.len()))?;
let g: &[f64; {m}] = g.try_into().map_err(|_| length_error({m}, g.len()))?;
let x_len = x.len();
let x: &mut [f64; {n}] = x.try_into().map_err(|_| length_error({n}, x_len))?;
let y_len = y.len();
let y: &mut [f64; {m}] = y.try_into().map_err(|_| length_error({m}, y_len))?;
let st: &[f64; {ns}] = st.try_into().map_err(|_| length_error({ns}, st.len()))?;
{}
Ok(())
}}
",
        dispatch(
            &format!("kkt_factor_{i}"),
            "mass: &[f64], c: f64, phi_q: &[f64], st: &mut [f64], piv: &mut Pivoting",
            "mass, c, phi_q, st, piv"
        ),
        factor.text(),
        dispatch(
            &format!("kkt_solve_{i}"),
            "f: &[f64], g: &[f64], x: &mut [f64], y: &mut [f64], st: &[f64]",
            "f, g, x, y, st"
        ),
        solve.text()
    );
    Some((text, entry))
}

/// `name`, which runs `name_any` (the straight-line body, inlined into one caller only, so
/// compiled once). On x86-64 that caller is compiled for AVX: the kernels are tens of
/// kilobytes of scalar arithmetic run once per call, and SSE2's two-operand forms need a
/// register copy before most products (13 % of the Stewart factorization's instructions),
/// AVX's three-operand forms do not. Same operations in the same order (nothing is fused
/// into an FMA), so the same bits. `SchurKkt` takes the kernels only where
/// `kernels_run_here()`, and runs its loops on a CPU without AVX.
fn dispatch(name: &str, params: &str, args: &str) -> String {
    format!(
        "#[cfg(target_arch = \"x86_64\")]
#[target_feature(enable = \"avx\")]
fn {name}_avx({params}) -> Result<(), KktError> {{
{name}_any({args})
}}
fn {name}({params}) -> Result<(), KktError> {{
#[cfg(target_arch = \"x86_64\")]
{{
if !symbody_runtime::kkt::kernels_run_here() {{
return Err(KktError::KernelsUnsupported);
}}
// SAFETY: the CPU has AVX (`kernels_run_here`), checked just above.
unsafe {{ {name}_avx({args}) }}
}}
#[cfg(not(target_arch = \"x86_64\"))]
{name}_any({args})
}}"
    )
}

/// `out[c] = Σ phi_q[k]·y[row k]` over column `c`'s nonzeros in their order, as
/// `phi_q_transpose_times`'s loop adds them (from zero).
fn transpose(pattern: &KktPattern) -> String {
    let mut text = String::new();
    for (c, t) in products(pattern, false).iter().enumerate() {
        let sum = if t.is_empty() {
            "0.0".to_string()
        } else {
            t.join(" + ")
        };
        let _ = writeln!(text, "out[{c}] = {sum};");
    }
    text
}

/// `out[r] += Σ phi_q[k]·x[c]` over row `r`'s nonzeros in their order, as a loop over the
/// nonzeros adds them to what `out` holds: written `out[r] = out[r] + a + b`, since
/// `out[r] += a + b` would add the products to each other first.
fn times_add(pattern: &KktPattern) -> String {
    let mut text = String::new();
    for (r, t) in products(pattern, true).iter().enumerate() {
        if !t.is_empty() {
            let _ = writeln!(text, "out[{r}] = out[{r}] + {};", t.join(" + "));
        }
    }
    text
}

/// `out[r] = Σ mass[k]·v[c]` over row `r`'s nonzeros in their order, as `mass_times`'s loop
/// adds them from zero (the leading `0.0 +` keeps the sign of a zero sum the loop's).
fn mass_times(pattern: &KktPattern) -> String {
    let mut terms = vec![Vec::new(); pattern.n];
    for (k, (&r, &c)) in pattern.mass_rows.iter().zip(&pattern.mass_cols).enumerate() {
        terms[r as usize].push(format!("mass[{k}] * v[{c}]"));
    }
    let mut text = String::new();
    for (r, t) in terms.iter().enumerate() {
        let sum: String = t.iter().map(|p| format!(" + {p}")).collect();
        let _ = writeln!(text, "out[{r}] = 0.0{sum};");
    }
    text
}

/// `kkt_assemble_loads`: `c·M − kq·sym(∂Q/∂q) − kqd·sym(∂Q/∂q̇)` on `union`'s mass
/// pattern (the model's `model` with the loads' patterns `loads`), each slot from `c·mᵢ`
/// (or zero) less the halves of the entries that land there, in the entries' order, as
/// `LoadStiffness::assemble`'s loop subtracts them.
fn assemble_loads(model: &KktPattern, union: &KktPattern, loads: [(&[u32], &[u32]); 2]) -> String {
    let pairs: Vec<(u32, u32)> = union
        .mass_rows
        .iter()
        .copied()
        .zip(union.mass_cols.iter().copied())
        .collect();
    let slot = |p: (u32, u32)| {
        pairs
            .binary_search(&p)
            .expect("the union holds every nonzero")
    };
    let mut value: Vec<String> = vec!["0.0".into(); pairs.len()];
    for (k, (&r, &c)) in model.mass_rows.iter().zip(&model.mass_cols).enumerate() {
        value[slot((r, c))] = format!("c * mass[{k}]");
    }
    let mut halves = String::new();
    let names = [("dq", "kq", "hq"), ("dqd", "kqd", "hd")];
    for ((rows, cols), (v, k, h)) in loads.iter().zip(names) {
        for (i, (&r, &c)) in rows.iter().zip(cols.iter()).enumerate() {
            let _ = writeln!(halves, "let {h}{i} = 0.5 * {k} * {v}[{i}];");
            for at in [slot((r, c)), slot((c, r))] {
                let _ = write!(value[at], " - {h}{i}");
            }
        }
    }
    let mut text = String::new();
    for (s, v) in value.iter().enumerate() {
        let _ = writeln!(text, "out[{s}] = {v};");
    }
    let (nm, nu) = (model.mass_rows.len(), pairs.len());
    let (nq, nqd) = (loads[0].0.len(), loads[1].0.len());
    format!(
        "#[allow(unused_variables, clippy::too_many_arguments)]
fn kkt_assemble_loads(mass: &[f64], c: f64, dq: &[f64], kq: f64, dqd: &[f64], kqd: f64, out: &mut [f64]) -> Result<(), KktError> {{
let mass: &[f64; {nm}] = mass.try_into().map_err(|_| length_error({nm}, mass.len()))?;
let dq: &[f64; {nq}] = dq.try_into().map_err(|_| length_error({nq}, dq.len()))?;
let dqd: &[f64; {nqd}] = dqd.try_into().map_err(|_| length_error({nqd}, dqd.len()))?;
let out_len = out.len();
let out: &mut [f64; {nu}] = out.try_into().map_err(|_| length_error({nu}, out_len))?;
{halves}{text}Ok(())
}}
"
    )
}

/// `t += qd[r]·mass[k]·qd[c]` over M's nonzeros in their order, as `kinetic_energy`'s loop
/// sums them: one statement each (a sum of hundreds of terms in one expression nests as
/// deep).
fn kinetic_energy(pattern: &KktPattern) -> String {
    let mut text = String::new();
    for (k, (&r, &c)) in pattern.mass_rows.iter().zip(&pattern.mass_cols).enumerate() {
        let _ = writeln!(text, "t += qd[{r}] * mass[{k}] * qd[{c}];");
    }
    text
}

/// The products of Φq's nonzeros, in their order, grouped by row (`phi_q[k] * x[col]`) or
/// by column (`phi_q[k] * y[row]`).
fn products(pattern: &KktPattern, by_row: bool) -> Vec<Vec<String>> {
    let mut terms = vec![Vec::new(); if by_row { pattern.m } else { pattern.n }];
    for (k, (&r, &c)) in pattern
        .phi_q_rows
        .iter()
        .zip(&pattern.phi_q_cols)
        .enumerate()
    {
        let (at, term) = match by_row {
            true => (r, format!("phi_q[{k}] * x[{c}]")),
            false => (c, format!("phi_q[{k}] * y[{r}]")),
        };
        terms[at as usize].push(term);
    }
    terms
}

/// What the factorization stores for the solves: the value of each block-factor entry
/// (strict lower triangle), reciprocal block diagonal, `W`, `L` and `1/D` entry, as a slot
/// of the state or a structural zero.
struct Stored {
    chol: Vec<V>,
    inv_diag: Vec<V>,
    wmat: Vec<V>,
    lval: Vec<V>,
    dinv: Vec<V>,
    slots: usize,
}

fn replay_factor(plan: &SchurPlan<'_>, pattern: &KktPattern, code: &mut Code) -> Stored {
    let mut chol = vec![V::Zero; plan.chol_len];
    for (i, &d) in plan.mass_dest.iter().enumerate() {
        // Both triangles land on the same slot; the later write wins, as in the loop.
        chol[d] = V::Mass(i as u32);
    }
    // Counted as the bindings they were, so the same patterns stay under `MAX_OPS`.
    code.ops += plan.mass_dest.len();
    let dummy = plan.w_len - 1;
    let mut wmat = vec![V::Zero; plan.w_len];
    for (i, &d) in plan.phi_q_dest.iter().enumerate() {
        if d == dummy {
            // A redundant row's entry: read by nothing else, so tested for finiteness here
            // (every other entry reaches a pivot, which is tested).
            code.line(&format!(
                "if !phi_q[{i}].is_finite() {{ return Err(KktError::NotFinite); }}"
            ));
        } else {
            wmat[d] = V::PhiQ(i as u32);
            code.ops += 1;
        }
    }
    let n_rows = pattern.m;
    let mut diag = vec![V::Zero; n_rows];
    let mut lval = vec![V::Zero; plan.row_idx.len()];
    let mut inv_diag = vec![V::Zero; plan.block_coords.len()];
    let nb = plan.chol_off.len();
    for b in 0..nb {
        let (c0, c1) = (plan.block_ptr[b], plan.block_ptr[b + 1]);
        let s = c1 - c0;
        let off = plan.chol_off[b];
        // Cholesky of the block (lower, row-major).
        for j in 0..s {
            let mut d = chol[off + j * s + j];
            assert!(d != V::Zero, "the mass pattern holds its diagonal");
            for k in 0..j {
                let a = chol[off + j * s + k];
                d = code.sub_mul(d, a, a);
            }
            let coord = plan.block_coords[c0 + j];
            // Positive and finite as two comparisons: LLVM turns `!(d > 0.0) ||
            // !d.is_finite()` into a floating-point class test that x86 evaluates in ~25
            // integer instructions (measured on the Stewart factorization: one per
            // coordinate), `d <= f64::MAX` into one comparison.
            code.line(&format!(
                "if !({d} > 0.0 && {d} <= f64::MAX) {{ return Err(mass_pivot_error({d}, {coord})); }}"
            ));
            let root = code.bind(format_args!("{d}.sqrt()"));
            chol[off + j * s + j] = root;
            let r = code.bind(format_args!("1.0 / {root}"));
            inv_diag[c0 + j] = r;
            for i in j + 1..s {
                let mut t = chol[off + i * s + j];
                for k in 0..j {
                    t = code.sub_mul(t, chol[off + i * s + k], chol[off + j * s + k]);
                }
                chol[off + i * s + j] = code.mul(t, r);
            }
        }
        // W = L⁻¹ Φq_bᵀ, row by row.
        let rows = plan.brow_ptr[b + 1] - plan.brow_ptr[b];
        let w0 = plan.p_off[b];
        for row in wmat[w0..w0 + rows * s].chunks_exact_mut(s) {
            forward(code, &chol[off..off + s * s], &inv_diag[c0..c1], row);
        }
        // S += WᵀW through the pair destinations: row i's products with the rows before
        // it go to L, its square to D.
        let dest = &plan.pair_dest[plan.pair_ptr[b]..plan.pair_ptr[b + 1]];
        let mut at = 0;
        for i in 0..rows {
            let wi: Vec<V> = wmat[w0 + i * s..w0 + i * s + s].to_vec();
            for j in 0..i {
                let p = code.dot(&wi, &wmat[w0 + j * s..w0 + j * s + s]);
                lval[dest[at + j]] = code.add(lval[dest[at + j]], p);
            }
            let p = code.dot(&wi, &wi);
            diag[dest[at + i]] = code.add(diag[dest[at + i]], p);
            at += i + 1;
        }
    }

    // LDLᵀ of S, right-looking, with the pivot test of the loops.
    let mut scale = diag.clone();
    let mut dinv = vec![V::Zero; n_rows];
    for k in 0..n_rows {
        if k == plan.n_first {
            scale[k..].copy_from_slice(&diag[k..]);
        }
        let inv = code.locals(2);
        let dk = inv + 1;
        code.ops += 1;
        code.line(&format!(
            "let (v{inv}, v{dk}) = piv.pivot({}, {}, {}, {})?;",
            diag[k], scale[k], plan.perm[k], plan.redundant[k]
        ));
        let (inv, dk) = (V::Var(inv), V::Var(dk));
        dinv[k] = inv;
        let col = plan.col_ptr[k]..plan.col_ptr[k + 1];
        for a in col {
            lval[a] = code.mul(lval[a], inv);
            let r = plan.row_idx[a];
            diag[r] = code.sub_mul3(diag[r], lval[a], dk, lval[a]);
        }
        for &[a, b, dest] in &plan.updates[plan.update_ptr[k]..plan.update_ptr[k + 1]] {
            let (a, b, dest) = (a as usize, b as usize, dest as usize);
            lval[dest] = code.sub_mul3(lval[dest], lval[a], dk, lval[b]);
        }
    }

    // Store what the solves read.
    let mut slots = 0;
    let mut store = |code: &mut Code, v: &mut V| {
        if *v != V::Zero {
            code.store(slots, *v);
            *v = V::Slot(slots as u32);
            slots += 1;
        }
    };
    for b in 0..nb {
        let s = plan.block_ptr[b + 1] - plan.block_ptr[b];
        let off = plan.chol_off[b];
        for i in 0..s {
            for j in 0..i {
                store(code, &mut chol[off + i * s + j]);
            }
        }
    }
    for v in inv_diag
        .iter_mut()
        .chain(&mut wmat[..dummy])
        .chain(&mut lval)
        .chain(&mut dinv)
    {
        store(code, v);
    }
    Stored {
        chol,
        inv_diag,
        wmat,
        lval,
        dinv,
        slots,
    }
}

/// The solve. Its first part, `r = Φq M⁻¹ f − g` with `u = L⁻¹ f` per group, runs only for
/// `f ≠ 0` (the loop skips it for position corrections) and leaves `r` in `y` and `u` in `x`
/// (by coordinate, so that each group's `x` overwrites only its own `u`), so that the rest is
/// emitted once for both cases. (Local arrays instead took LLVM minutes on the 40-bar chain.)
fn replay_solve(plan: &SchurPlan<'_>, pattern: &KktPattern, st: &Stored, code: &mut Code) {
    let (n, m) = (pattern.n, pattern.m);
    let nb = plan.chol_off.len();
    code.line("x.fill(0.0);");
    for r in 0..m {
        code.line(&format!("y[{r}] = -g[{r}];"));
    }
    code.line("if f.iter().any(|&v| v != 0.0) {");
    let mut ustore = vec![V::Zero; n];
    for b in 0..nb {
        let (c0, c1) = (plan.block_ptr[b], plan.block_ptr[b + 1]);
        let s = c1 - c0;
        let off = plan.chol_off[b];
        for l in 0..s {
            ustore[c0 + l] = code.bind(format_args!("f[{}]", plan.block_coords[c0 + l]));
        }
        forward(
            code,
            &st.chol[off..off + s * s],
            &st.inv_diag[c0..c1],
            &mut ustore[c0..c1],
        );
        let rows = &plan.brows[plan.brow_ptr[b]..plan.brow_ptr[b + 1]];
        let w0 = plan.p_off[b];
        for (k, &r) in rows.iter().enumerate() {
            let p = code.dot(&st.wmat[w0 + k * s..w0 + k * s + s], &ustore[c0..c1]);
            if p != V::Zero {
                code.line(&format!("y[{r}] += {p};"));
            }
        }
        for (l, &v) in ustore[c0..c1].iter().enumerate() {
            if v != V::Zero {
                code.line(&format!("x[{}] = {v};", plan.block_coords[c0 + l]));
            }
        }
    }
    code.line("}");
    let mut ustore: Vec<V> = plan
        .block_coords
        .iter()
        .map(|&c| V::In("x", c as u32))
        .collect();
    let mut z: Vec<V> = plan.perm.iter().map(|&r| V::In("y", r as u32)).collect();
    for j in 0..m {
        let zj = z[j];
        for a in plan.col_ptr[j]..plan.col_ptr[j + 1] {
            let r = plan.row_idx[a];
            z[r] = code.sub_mul(z[r], st.lval[a], zj);
        }
    }
    for (zj, &d) in z.iter_mut().zip(&st.dinv) {
        *zj = code.mul(*zj, d);
    }
    for j in (0..m).rev() {
        let mut t = z[j];
        for a in plan.col_ptr[j]..plan.col_ptr[j + 1] {
            t = code.sub_mul(t, st.lval[a], z[plan.row_idx[a]]);
        }
        z[j] = t;
    }
    let mut y = vec![V::Zero; m];
    for (k, &zk) in z.iter().enumerate() {
        y[plan.perm[k]] = zk;
        code.line(&format!("y[{}] = {zk};", plan.perm[k]));
    }
    for b in 0..nb {
        let (c0, c1) = (plan.block_ptr[b], plan.block_ptr[b + 1]);
        let s = c1 - c0;
        let off = plan.chol_off[b];
        let rows = &plan.brows[plan.brow_ptr[b]..plan.brow_ptr[b + 1]];
        let w0 = plan.p_off[b];
        let v = &mut ustore[c0..c1];
        for (k, &r) in rows.iter().enumerate() {
            for (vi, &w) in v.iter_mut().zip(&st.wmat[w0 + k * s..w0 + k * s + s]) {
                *vi = code.sub_mul(*vi, w, y[r]);
            }
        }
        let (l, inv) = (&st.chol[off..off + s * s], &st.inv_diag[c0..c1]);
        for i in (0..s).rev() {
            let mut t = v[i];
            for j in i + 1..s {
                t = code.sub_mul(t, l[j * s + i], v[j]);
            }
            v[i] = code.mul(t, inv[i]);
        }
        for (l, &vi) in v.iter().enumerate() {
            code.line(&format!("x[{}] = {vi};", plan.block_coords[c0 + l]));
        }
    }
}

/// `v ← L⁻¹ v` for one block (`forward` in the loops).
fn forward(code: &mut Code, l: &[V], inv: &[V], v: &mut [V]) {
    let s = v.len();
    for i in 0..s {
        let mut t = v[i];
        for j in 0..i {
            t = code.sub_mul(t, l[i * s + j], v[j]);
        }
        v[i] = code.mul(t, inv[i]);
    }
}
