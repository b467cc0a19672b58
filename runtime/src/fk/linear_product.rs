//! Every solution of the Study-form equations ([`super::study`]) from a start system of
//! products of random linear forms: the method that needs nothing precomputed, used to make
//! the generic start system shipped in [`super::start`] and as the fallback of the parameter
//! homotopy.
//!
//! The differences `Fᵢ − F₁` lose the `N(g)` term, so five equations are products of a form
//! in `e` and a form in `(e, g)`, the Study condition a form in `e` times one in `g`, and
//! only `F₁` needs two general forms. A start system of products of random linear forms with
//! exactly that structure has 84 regular solutions (against 2⁷ = 128 for a total-degree
//! start: the 44 it saves would all end on the degenerate set `e = 0`); by the theory of
//! linear-product homotopies its paths reach every isolated solution, a general platform's
//! 40 poses (Raghavan 1993). The other 44 paths end on `e = 0`, recognised and dropped. The
//! random complex `γ` in `H = γ(1 − t)G + tF` keeps every path regular for `t < 1` with
//! probability one.

use super::modes::SplitMix;
use super::study::{degenerate, size, Lu, Study, C, J, Z};

/// The target equations `F`, the start system `G` and the patch.
pub(super) struct Homotopy<'a> {
    target: &'a Study,
    /// `G_k = (A_k · z)(B_k · z)`: the two random linear forms of each start equation, with
    /// the supports of `F_k`'s structure.
    forms: [[Z; 2]; 7],
    pub(super) patch: Z,
    gamma: C,
}

/// Which unknowns a start form may involve.
#[derive(Clone, Copy, PartialEq)]
enum Support {
    E,
    G,
    All,
}

impl<'a> Homotopy<'a> {
    pub(super) fn new(target: &'a Study, rng: &mut SplitMix) -> Self {
        let mut form = |support: Support| {
            Z::from_fn(|k, _| match (support, k < 4) {
                (Support::E, false) | (Support::G, true) => C::new(0.0, 0.0),
                _ => rng.complex(),
            })
        };
        let forms = std::array::from_fn(|k| match k {
            0..=4 => [form(Support::E), form(Support::All)],
            5 => [form(Support::All), form(Support::All)],
            _ => [form(Support::E), form(Support::G)],
        });
        Homotopy {
            target,
            forms,
            patch: Z::from_fn(|_, _| rng.complex()),
            gamma: rng.complex(),
        }
    }

    /// The start points: one factor of each start equation set to zero, with the patch.
    /// Choices that zero four forms in `e` give `e = 0`, a positive-dimensional solution set
    /// of `G`, not a start point: 84 of the 128 choices remain.
    pub(super) fn starts(&self) -> impl Iterator<Item = Z> + '_ {
        (0..128u32).filter_map(|choice| {
            let pick = |k: usize| (choice >> k) as usize & 1;
            let e_only = (0..5).filter(|&k| pick(k) == 0).count() + usize::from(pick(6) == 0);
            if e_only > 3 {
                return None;
            }
            let mut a: J = [[C::new(0.0, 0.0); 8]; 8];
            for (c, column) in a.iter_mut().enumerate() {
                for (k, entry) in column.iter_mut().take(7).enumerate() {
                    *entry = self.forms[k][pick(k)][c];
                }
                column[7] = self.patch[c];
            }
            let mut rhs = Z::zeros();
            rhs[7] = C::new(1.0, 0.0);
            Lu::new(&a).map(|lu| lu.solve(&rhs))
        })
    }

    /// `H(z, t)`, `∂H/∂z` and `∂H/∂t`; row 7 is the patch in all three.
    fn eval(&self, z: &Z, t: f64) -> (Z, J, Z) {
        let (f, mut j) = self.target.eval(z, &self.patch);
        let (s, u) = (self.gamma * (1.0 - t), C::new(t, 0.0));
        let mut h = f;
        let mut ht = Z::zeros();
        for k in 0..7 {
            let [a, b] = &self.forms[k];
            let (az, bz) = (a.dot(z), b.dot(z));
            h[k] = az * bz * s + f[k] * u;
            ht[k] = f[k] - az * bz * self.gamma;
            for (c, column) in j.iter_mut().enumerate() {
                column[k] = (a[c] * bz + b[c] * az) * s + column[k] * u;
            }
        }
        (h, j, ht)
    }

    /// `dz/dt = −H_z⁻¹ H_t`.
    fn velocity(&self, z: &Z, t: f64) -> Option<Z> {
        let (_, jh, ht) = self.eval(z, t);
        Lu::new(&jh).map(|lu| -lu.solve(&ht))
    }

    /// Follows one path from `t = 0` to `t = 1`: a fourth-order Runge–Kutta prediction
    /// and at most three Newton corrections per step, the step halved when they do not
    /// settle and doubled after a run of easy steps. `None` for a path that ends on the
    /// degenerate set or cannot be followed.
    pub(super) fn track(&self, mut z: Z) -> Option<Z> {
        let (mut t, mut h, mut easy) = (0.0_f64, 0.02_f64, 0);
        for _ in 0..20_000 {
            if t >= 1.0 {
                return Some(z);
            }
            h = h.min(1.0 - t);
            let Some(predicted) = self.rk4(&z, t, h) else {
                h /= 2.0;
                if h < 1e-14 {
                    return None;
                }
                continue;
            };
            match self.correct(predicted, t + h) {
                Some(next) => {
                    z = next;
                    t = if h == 1.0 - t { 1.0 } else { t + h };
                    easy += 1;
                    if easy >= 3 {
                        h = (2.0 * h).min(0.1);
                        easy = 0;
                    }
                }
                None => {
                    h /= 2.0;
                    easy = 0;
                    if h < 1e-14 {
                        return None;
                    }
                }
            }
            if t > 0.9 && degenerate(&z) {
                return None;
            }
        }
        None
    }

    fn rk4(&self, z: &Z, t: f64, h: f64) -> Option<Z> {
        let half = C::new(h / 2.0, 0.0);
        let k1 = self.velocity(z, t)?;
        let k2 = self.velocity(&(z + k1 * half), t + h / 2.0)?;
        let k3 = self.velocity(&(z + k2 * half), t + h / 2.0)?;
        let k4 = self.velocity(&(z + k3 * C::new(h, 0.0)), t + h)?;
        Some(z + (k1 + (k2 + k3) * C::new(2.0, 0.0) + k4) * C::new(h / 6.0, 0.0))
    }

    fn correct(&self, mut z: Z, t: f64) -> Option<Z> {
        for it in 0..3 {
            let (h, jh, _) = self.eval(&z, t);
            let dz = -Lu::new(&jh)?.solve(&h);
            z += dz;
            let (step, scale) = (size(&dz), 1.0 + size(&z));
            if step <= 1e-8 * scale {
                return Some(z);
            }
            // A first correction this large means the prediction left the path's basin.
            if it == 0 && step > 0.05 * scale {
                return None;
            }
        }
        None
    }
}
