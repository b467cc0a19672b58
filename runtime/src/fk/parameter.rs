//! The parameter homotopy: the 40 solutions of one generic complex platform
//! ([`super::start`]), followed while its coefficients move to the platform asked about.
//!
//! The coefficients move along `(1 − w(s))·P₀ + w(s)·P₁` with `w(s) = s / (s + γ(1 − s))`,
//! `s` from 0 to 1 and `γ` a random unit complex number: the platforms where two solutions
//! meet are finitely many points of the `w` plane, and a random arc from 0 to 1 misses
//! them with probability one (the "γ trick"). So every path is regular before `s = 1`, and
//! the 40 paths end at every isolated solution of the target; those of a special platform
//! that has fewer end on the degenerate set `eᵀe = 0`. Against the linear-product start
//! ([`super::linear_product`]) this tracks 40 paths instead of 84, and none of them goes to
//! the degenerate set on a general platform.
//!
//! Tracking: a cubic Hermite prediction through the last two points and their tangents,
//! Newton correction whose last factorization also gives the new tangent, and a step that
//! follows the size of the first correction (the predictor's error, O(h⁴)).

use super::modes::SplitMix;
use super::study::{degenerate, size, LegVectors, Lu, Study, C, Z};

/// How a path ended.
pub(super) enum End {
    /// At `s = 1`, before refinement.
    Reached(Z),
    /// On (or next to) the degenerate set: no pose (special platforms only).
    Degenerate,
    /// The tracker gave up: the path is not accounted for.
    Failed,
}

/// The start platform, the direction from it to the target, and this attempt's random
/// choices (the arc's γ and the affine patch).
pub(super) struct ParameterHomotopy<'a> {
    start: &'a Study,
    delta: Study,
    gamma: C,
    pub(super) patch: Z,
}

/// First step (in s) of a path: the first prediction is Euler's, O(h²).
const FIRST_STEP: f64 = 0.02;
/// Size of the first Newton correction the step aims for, relative to `1 + |z|∞`.
const PREDICTOR_ERROR: f64 = 3e-3;
/// A first correction larger than this (relative) rejects the step: the prediction may have
/// left its path's basin.
const MAX_FIRST_CORRECTION: f64 = 5e-2;
/// Newton on a path stops when its estimated error (the next increment, from the contraction
/// so far) is below this (relative): enough to predict from; the end is refined to roundoff.
const PATH_TOLERANCE: f64 = 1e-7;
const MAX_CORRECTIONS: usize = 3;
const MAX_STEPS: usize = 5_000;

impl<'a> ParameterHomotopy<'a> {
    pub(super) fn new(start: &'a Study, target: &'a Study, rng: &mut SplitMix) -> Self {
        // An argument of γ away from π keeps |s + γ(1 − s)| ≥ cos(1.25) on the whole arc.
        let angle = 2.5 * (2.0 * rng.next() - 1.0);
        ParameterHomotopy {
            start,
            delta: start.towards(target),
            gamma: C::from_polar(1.0, angle),
            patch: Z::from_fn(|_, _| rng.complex()),
        }
    }

    /// A start solution (homogeneous) scaled onto this attempt's patch.
    pub(super) fn on_patch(&self, z: &Z) -> Z {
        z / self.patch.dot(z)
    }

    /// The platform at `s` on the arc, and `dw/ds`.
    fn at(&self, s: f64) -> (Study, C) {
        let d = C::new(s, 0.0) + self.gamma * (1.0 - s);
        (
            self.start.moved(&self.delta, C::new(s, 0.0) / d),
            self.gamma / (d * d),
        )
    }

    /// `dz/ds` at `z`, with its legs' `u` and the factorization `lu` of `∂H/∂z` there.
    fn tangent(&self, study: &Study, rate: C, z: &Z, us: &LegVectors, lu: &Lu) -> Z {
        -lu.solve(&(study.rate(z, us, &self.delta) * rate))
    }

    /// Follows the path from the start solution `z` (on the patch) to `s = 1`.
    pub(super) fn track(&self, mut z: Z) -> End {
        let (study, rate) = self.at(0.0);
        let us = study.legs(&z);
        let Some(lu) = Lu::new(&study.eval_with(&z, &us, &self.patch).1) else {
            return End::Failed;
        };
        let mut tangent = self.tangent(&study, rate, &z, &us, &lu);
        let mut s = 0.0_f64;
        let mut previous: Option<(f64, Z, Z)> = None;
        let mut h = FIRST_STEP;
        for _ in 0..MAX_STEPS {
            if s >= 1.0 {
                return End::Reached(z);
            }
            let last = h >= 1.0 - s;
            let next = if last { 1.0 } else { s + h };
            let predicted = match &previous {
                Some((s0, z0, t0)) => hermite((*s0, z0, t0), (s, &z, &tangent), next),
                None => z + tangent * C::new(next - s, 0.0),
            };
            match self.correct(predicted, next) {
                Some((zc, tc, first)) => {
                    let order = if previous.is_some() { 4.0 } else { 2.0 };
                    previous = Some((s, z, tangent));
                    let taken = next - s;
                    (s, z, tangent) = (next, zc, tc);
                    let wanted = PREDICTOR_ERROR * (1.0 + size(&z));
                    let ratio = (wanted / first.max(f64::MIN_POSITIVE)).powf(1.0 / order);
                    h = taken * (0.8 * ratio).clamp(0.5, 2.5);
                }
                None => {
                    h = (next - s) / 2.0;
                    if h < 1e-12 {
                        return End::Failed;
                    }
                }
            }
            if s > 0.9 && degenerate(&z) {
                return End::Degenerate;
            }
        }
        End::Failed
    }

    /// Newton at `s` from `z`: the point, its tangent and the first correction's size, or
    /// `None` when the corrections do not contract fast enough.
    fn correct(&self, mut z: Z, s: f64) -> Option<(Z, Z, f64)> {
        let (study, rate) = self.at(s);
        let mut first = 0.0;
        let mut last = f64::INFINITY;
        for it in 0..MAX_CORRECTIONS {
            let us = study.legs(&z);
            let (f, j) = study.eval_with(&z, &us, &self.patch);
            let lu = Lu::new(&j)?;
            let dz = -lu.solve(&f);
            let from = z;
            z += dz;
            let (step, scale) = (size(&dz), 1.0 + size(&z));
            if !step.is_finite() {
                return None;
            }
            if it == 0 {
                first = step;
                if step > MAX_FIRST_CORRECTION * scale {
                    return None;
                }
            } else if step > 0.25 * last {
                return None;
            }
            // Newton's error after this increment is about the next one, |dz|²/|dz_prev| from
            // the contraction seen so far.
            let next = if it == 0 { step } else { step * step / last };
            if next <= PATH_TOLERANCE * scale {
                // The factorization is one increment old: the tangent's error is O(|dz|).
                return Some((z, self.tangent(&study, rate, &from, &us, &lu), first));
            }
            last = step;
        }
        None
    }
}

/// The cubic through `(s₀, z₀)` and `(s₁, z₁)` with tangents `t₀`, `t₁`, at `s`.
fn hermite((s0, z0, t0): (f64, &Z, &Z), (s1, z1, t1): (f64, &Z, &Z), s: f64) -> Z {
    let d = s1 - s0;
    let x = (s - s0) / d;
    let (x2, x3) = (x * x, x * x * x);
    let h00 = 2.0 * x3 - 3.0 * x2 + 1.0;
    let h10 = x3 - 2.0 * x2 + x;
    let h01 = -2.0 * x3 + 3.0 * x2;
    let h11 = x3 - x2;
    let r = |x: f64| C::new(x, 0.0);
    z0 * r(h00) + t0 * r(h10 * d) + z1 * r(h01) + t1 * r(h11 * d)
}
