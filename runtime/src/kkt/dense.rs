//! The reference KKT solver: the whole saddle-point matrix, dense, LU with partial pivoting.
//! Simple enough to trust, so the structured solver is tested against it.
//!
//! A redundant row is removed by leaving its `Φq` entries out and putting a lone pivot on
//! its diagonal with a zero right-hand side: its `y` is 0 and it couples to nothing.

use nalgebra::{DMatrix, DVector};

use super::{check_kkt_len, KktError, KktPattern, KktSolver, DEFAULT_PIVOT_TOLERANCE};
use crate::error::Error;

/// Dense LU of `[c·M Φqᵀ; Φq 0]` (size `n + m`), in place in preallocated storage.
#[derive(Debug, Clone)]
pub struct DenseKkt {
    pattern: KktPattern,
    lu: DMatrix<f64>,
    /// Row interchanges: at elimination step `k`, row `k` was swapped with `perm[k]`.
    perm: Vec<usize>,
    rhs: DVector<f64>,
    /// For each constraint row: declared redundant in the pattern.
    redundant: Vec<bool>,
    factored: bool,
    pivot_tol: f64,
}

impl KktSolver for DenseKkt {
    fn new(pattern: &KktPattern) -> Result<Self, Error> {
        pattern.validate()?;
        let size = pattern.n + pattern.m;
        let mut redundant = vec![false; pattern.m];
        for &r in &pattern.redundant_rows {
            redundant[r as usize] = true;
        }
        Ok(DenseKkt {
            pattern: pattern.clone(),
            lu: DMatrix::zeros(size, size),
            perm: vec![0; size],
            rhs: DVector::zeros(size),
            redundant,
            factored: false,
            pivot_tol: DEFAULT_PIVOT_TOLERANCE,
        })
    }

    fn factor(&mut self, mass: &[f64], mass_scale: f64, phi_q: &[f64]) -> Result<(), KktError> {
        self.factored = false;
        let p = &self.pattern;
        check_kkt_len(p.mass_rows.len(), mass.len())?;
        check_kkt_len(p.phi_q_rows.len(), phi_q.len())?;
        let n = p.n;
        let size = n + p.m;
        let a = &mut self.lu;
        a.fill(0.0);
        for ((&r, &c), &v) in p.mass_rows.iter().zip(&p.mass_cols).zip(mass) {
            a[(r as usize, c as usize)] = mass_scale * v;
        }
        for ((&r, &c), &v) in p.phi_q_rows.iter().zip(&p.phi_q_cols).zip(phi_q) {
            if !v.is_finite() {
                return Err(KktError::NotFinite);
            }
            if !self.redundant[r as usize] {
                a[(n + r as usize, c as usize)] = v;
                a[(c as usize, n + r as usize)] = v;
            }
        }
        let mut scale = 0.0f64;
        for v in a.iter() {
            if !v.is_finite() {
                return Err(KktError::NotFinite);
            }
            scale = scale.max(v.abs());
        }
        if scale == 0.0 && size > 0 {
            return Err(KktError::SingularMatrix { column: 0 });
        }
        // At the matrix's own scale, so the relative pivot tolerance is unchanged.
        for &r in &p.redundant_rows {
            a[(n + r as usize, n + r as usize)] = scale;
        }
        let tiny = self.pivot_tol * scale;
        for k in 0..size {
            let mut piv = k;
            let mut best = a[(k, k)].abs();
            for i in k + 1..size {
                let v = a[(i, k)].abs();
                if v > best {
                    best = v;
                    piv = i;
                }
            }
            // `!(x > tiny)` also catches NaN produced during elimination.
            if !(best > tiny) {
                return Err(if k >= n {
                    KktError::RankDeficient {
                        rows: [k - n, 0, 0, 0],
                        count: 1,
                        pivot: best / scale,
                    }
                } else {
                    KktError::SingularMatrix { column: k }
                });
            }
            self.perm[k] = piv;
            if piv != k {
                a.swap_rows(k, piv);
            }
            let d = a[(k, k)];
            for i in k + 1..size {
                let l = a[(i, k)] / d;
                a[(i, k)] = l;
                if l != 0.0 {
                    for j in k + 1..size {
                        let u = a[(k, j)];
                        a[(i, j)] -= l * u;
                    }
                }
            }
        }
        self.factored = true;
        Ok(())
    }

    fn solve(
        &mut self,
        f: &[f64],
        g: &[f64],
        x: &mut [f64],
        y: &mut [f64],
    ) -> Result<(), KktError> {
        if !self.factored {
            return Err(KktError::NotFactored);
        }
        let (n, m) = (self.pattern.n, self.pattern.m);
        check_kkt_len(n, f.len())?;
        check_kkt_len(m, g.len())?;
        check_kkt_len(n, x.len())?;
        check_kkt_len(m, y.len())?;
        let size = n + m;
        let b = &mut self.rhs;
        b.as_mut_slice()[..n].copy_from_slice(f);
        b.as_mut_slice()[n..].copy_from_slice(g);
        for &r in &self.pattern.redundant_rows {
            b[n + r as usize] = 0.0;
        }
        for k in 0..size {
            b.swap_rows(k, self.perm[k]);
        }
        let a = &self.lu;
        for i in 0..size {
            let mut s = b[i];
            for j in 0..i {
                s -= a[(i, j)] * b[j];
            }
            b[i] = s;
        }
        for i in (0..size).rev() {
            let mut s = b[i];
            for j in i + 1..size {
                s -= a[(i, j)] * b[j];
            }
            b[i] = s / a[(i, i)];
        }
        x.copy_from_slice(&b.as_slice()[..n]);
        y.copy_from_slice(&b.as_slice()[n..]);
        Ok(())
    }
}
