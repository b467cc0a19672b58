//! HHT's first guess of a step's accelerations and multipliers, extrapolated from the last
//! accepted steps (see [`Predictor`]).

use nalgebra::{Matrix4, Vector4};

/// Accepted steps kept besides the current one.
const KEPT: usize = 3;

/// q̈ and λ of the last accepted steps, and the extrapolation of both to the next step.
///
/// Index-3 HHT's accelerations and multipliers carry a parasitic mode that changes by the
/// factor `r = −(1 + α)/(1 − α)` per step whatever the step size (−1 at α = 0: undamped).
/// A polynomial through the last values reads its alternation as motion and amplifies it: on
/// A05's governor at α = 0 a straight line through two steps started Newton ≈ 2·10⁴ times
/// the tolerance away, where this model starts it ≈ 100 times. So the extrapolation fits
/// `a + b·τ + c·τ² + p·rⁿ` (τ the time, n the step's number) through the current and three
/// earlier steps, the smooth part to second order and the parasitic mode exactly; with
/// fewer steps known it drops the terms it cannot fit (`a + b·τ + p·rⁿ` with three, a
/// straight line with two, the current values with one).
#[derive(Debug, Clone)]
pub(crate) struct Predictor {
    /// q̈ and λ one, two and three accepted steps back.
    qdd: [Vec<f64>; KEPT],
    lambda: [Vec<f64>; KEPT],
    /// `steps[k]`: the size of the step that ended `k` steps back (from `qdd[k]` to the
    /// values after it); 0 where not known.
    steps: [f64; KEPT],
    /// The parasitic mode's factor per step.
    ratio: f64,
    /// Weights of the current and earlier values, and the steps and step size they were
    /// fitted for: at a fixed step they serve every step.
    weights: Option<([f64; KEPT], f64, [f64; KEPT + 1])>,
}

impl Predictor {
    pub(crate) fn new(n: usize, m: usize, alpha: f64) -> Self {
        Predictor {
            qdd: std::array::from_fn(|_| vec![0.0; n]),
            lambda: std::array::from_fn(|_| vec![0.0; m]),
            steps: [0.0; KEPT],
            ratio: -(1.0 + alpha) / (1.0 - alpha),
            weights: None,
        }
    }

    /// q̈ one accepted step back (the local error estimate's).
    pub(crate) fn previous_qdd(&self) -> &[f64] {
        &self.qdd[0]
    }

    /// A step of size `h` was accepted: `qdd` and `lambda` (the values it started from)
    /// become the history and take the new values `qdd1`, `lambda1`, which are left holding
    /// scratch. Moves buffers, copies nothing.
    pub(crate) fn push(
        &mut self,
        h: f64,
        (qdd, qdd1): (&mut Vec<f64>, &mut Vec<f64>),
        (lambda, lambda1): (&mut Vec<f64>, &mut Vec<f64>),
    ) {
        self.qdd.rotate_right(1);
        self.lambda.rotate_right(1);
        self.steps.rotate_right(1);
        self.steps[0] = h;
        std::mem::swap(&mut self.qdd[0], qdd);
        std::mem::swap(qdd, qdd1);
        std::mem::swap(&mut self.lambda[0], lambda);
        std::mem::swap(lambda, lambda1);
    }

    /// The guess for a step of size `h` from the current `qdd`, `lambda`, into `qdd1`,
    /// `lambda1`.
    pub(crate) fn predict(
        &mut self,
        h: f64,
        (qdd, qdd1): (&[f64], &mut [f64]),
        (lambda, lambda1): (&[f64], &mut [f64]),
    ) {
        let w = match self.weights {
            Some((steps, for_h, w)) if steps == self.steps && for_h == h => w,
            _ => {
                let w = self.fit(h);
                self.weights = Some((self.steps, h, w));
                w
            }
        };
        extrapolate(&w, qdd, &self.qdd, qdd1);
        extrapolate(&w, lambda, &self.lambda, lambda1);
    }

    /// Weights `w` with `Σ wₖ f(τₖ) = f(τ_next)` for each function f of the model, over the
    /// steps known (times in units of `h` from the current step).
    fn fit(&self, h: f64) -> [f64; KEPT + 1] {
        let known = 1 + self.steps.iter().take_while(|&&s| s > 0.0).count();
        let mut tau = [0.0; KEPT + 1];
        for k in 1..known {
            tau[k] = tau[k - 1] - self.steps[k - 1] / h;
        }
        let mut w = [0.0; KEPT + 1];
        match known {
            1 => w[0] = 1.0,
            2 => {
                w[1] = 1.0 / tau[1];
                w[0] = 1.0 - w[1];
            }
            _ => {
                // Rows: the model's functions 1, τ, r⁻ᵏ (k steps back) and τ² (the last
                // only with four steps known), at the known steps; padded to 4×4 with
                // identity rows.
                let basis = |row: usize, k: usize| match row {
                    0 => 1.0,
                    1 => tau[k],
                    2 => self.ratio.powi(-(k as i32)),
                    _ => tau[k] * tau[k],
                };
                let a = Matrix4::from_fn(|row, k| {
                    if row < known && k < known {
                        basis(row, k)
                    } else if row == k {
                        1.0
                    } else {
                        0.0
                    }
                });
                let target = Vector4::new(1.0, 1.0, self.ratio, if known > 3 { 1.0 } else { 0.0 });
                // Distinct times and a mode that changes sign every step leave no
                // combination of the functions vanishing at all the steps: regular.
                if let Some(x) = a.lu().solve(&target) {
                    w.copy_from_slice(x.as_slice());
                } else {
                    w[0] = 1.0;
                }
            }
        }
        w
    }
}

/// `out = w₀·now + Σₖ wₖ₊₁·back[k]` over the weights given.
fn extrapolate(w: &[f64; KEPT + 1], now: &[f64], back: &[Vec<f64>; KEPT], out: &mut [f64]) {
    for (i, o) in out.iter_mut().enumerate() {
        *o = w[0] * now[i] + w[1] * back[0][i] + w[2] * back[1][i] + w[3] * back[2][i];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A history made of `f` at steps of the given sizes (oldest first), predicted one
    /// step of `h` on.
    fn predicted(alpha: f64, sizes: &[f64], h: f64, f: impl Fn(f64, usize) -> f64) -> (f64, f64) {
        let mut p = Predictor::new(1, 1, alpha);
        let mut t = 0.0;
        let mut k = 0;
        let (mut a, mut a1) = (vec![f(t, k)], vec![0.0]);
        let (mut l, mut l1) = (vec![f(t, k)], vec![0.0]);
        for &s in sizes {
            t += s;
            k += 1;
            a1[0] = f(t, k);
            l1[0] = f(t, k);
            p.push(s, (&mut a, &mut a1), (&mut l, &mut l1));
        }
        p.predict(h, (&a, &mut a1), (&l, &mut l1));
        (a1[0], f(t + h, k + 1))
    }

    #[test]
    fn exact_for_a_quadratic_plus_the_parasitic_mode() {
        // Uneven steps, both α's; the reference is the model evaluated one step further.
        for alpha in [0.0, -0.05, -0.3] {
            let r: f64 = -(1.0 + alpha) / (1.0 - alpha);
            let f = |t: f64, k: usize| 0.3 - 2.0 * t + 5.0 * t * t + 0.7 * r.powi(k as i32);
            let (got, want) = predicted(alpha, &[1e-3, 1.3e-3, 0.8e-3], 1.1e-3, f);
            assert!((got - want).abs() < 1e-12, "α {alpha}: {got} vs {want}");
        }
    }

    #[test]
    fn with_fewer_steps_drops_what_it_cannot_fit() {
        let r = -1.0f64;
        // Three values: a straight line plus the mode, exactly.
        let f = |t: f64, k: usize| 1.0 + 4.0 * t + 0.2 * r.powi(k as i32);
        let (got, want) = predicted(0.0, &[1e-3, 2e-3], 1.5e-3, f);
        assert!((got - want).abs() < 1e-12, "{got} vs {want}");
        // Two: a straight line, exactly.
        let (got, want) = predicted(0.0, &[1e-3], 3e-3, |t, _| 2.0 - 7.0 * t);
        assert!((got - want).abs() < 1e-12, "{got} vs {want}");
        // One: the current value.
        let (got, _) = predicted(0.0, &[], 1e-3, |_, _| 3.0);
        assert_eq!(got, 3.0);
    }
}
