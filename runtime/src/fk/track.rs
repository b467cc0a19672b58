//! Branch-safe continuation of the platform's pose along a leg-length path: each step is a
//! tangent prediction and a Newton correction that may not wander far from it, and the sign of
//! the Jacobian's determinant is watched, so the pose never slides silently onto another
//! assembly mode; where it would, the parallel singularity is reported with its time.

use nalgebra::Vector6;

use super::{Failure, Legs, Pose, Settings, Solution};
use crate::error::Error;

/// Settings of [`track`].
#[derive(Debug, Clone, Copy)]
pub struct TrackSettings {
    pub newton: Settings,
    /// A pose whose Jacobian's condition number exceeds this counts as singular.
    pub max_condition: f64,
    /// Smallest step, as a fraction of the path's span, before giving up.
    pub min_step_fraction: f64,
}

impl Default for TrackSettings {
    fn default() -> Self {
        TrackSettings {
            newton: Settings::default(),
            max_condition: 1e8,
            min_step_fraction: 1e-9,
        }
    }
}

/// The end of a tracked path.
#[derive(Debug, Clone, Copy)]
pub struct Tracked {
    pub solution: Solution,
    /// Accepted continuation steps.
    pub steps: usize,
    /// Largest condition number met along the path.
    pub max_condition: f64,
}

/// Follows the pose from `start` (near a solution at `t0`) along `lengths(t)` to `t1`.
///
/// `t` is whatever parametrizes the path: time along a scenario, or `s ∈ [0, 1]` along a
/// straight line in leg-length space. Returns [`Error::PlatformSingularity`] at the first
/// pose where the Jacobian becomes singular (condition above the limit, or no nearby
/// solution even for tiny steps) or where its determinant changes sign (the tracked pose
/// has passed to another assembly mode).
pub fn track(
    legs: &Legs,
    lengths: impl Fn(f64) -> [f64; 6],
    start: &Pose,
    t0: f64,
    t1: f64,
    settings: TrackSettings,
) -> Result<Tracked, Error> {
    let first = legs.solve(&lengths(t0), start, settings.newton)?;
    let lc = legs.characteristic_length();
    let span = t1 - t0;
    let singular = |pose: &Pose, time: f64, switched: bool| Error::PlatformSingularity {
        time,
        condition: legs.condition(pose),
        legs: dependent_legs(legs, pose),
        switched,
    };
    if first.condition > settings.max_condition {
        return Err(singular(&first.pose, t0, false));
    }
    let mut here = first;
    let mut t = t0;
    let mut h = span / 16.0;
    let mut steps = 0;
    let mut max_condition = first.condition;
    while (t1 - t) * span.signum() > 0.0 {
        if (t + h - t1) * span.signum() > 0.0 {
            h = t1 - t;
        }
        let (l_here, l_next) = (lengths(t), lengths(t + h));
        let dl = Vector6::from_fn(|i, _| l_next[i] - l_here[i]);
        let tangent = legs.jacobian(&here.pose).lu().solve(&dl);
        let predicted = match tangent {
            Some(d) => here.pose.moved(&d),
            None => return Err(singular(&here.pose, t, false)),
        };
        // The tangent prediction errs by O(h²) against a move of O(h): a correction that
        // is not small against the move means the step was too long for the path's
        // curvature, or that Newton is heading for another branch, or for none because
        // the branch folds back here.
        let bound = 1e-9 * lc + 0.1 * here.pose.distance(&predicted, lc);
        match legs.solve_bounded(&l_next, &predicted, settings.newton, bound) {
            Ok(next) if next.iterations <= 5 => {
                if next.det_sign != here.det_sign {
                    return Err(singular(&next.pose, t + h, true));
                }
                if next.condition > settings.max_condition {
                    return Err(singular(&next.pose, t + h, false));
                }
                max_condition = max_condition.max(next.condition);
                let easy = next.iterations <= 3;
                here = next;
                t += h;
                steps += 1;
                if easy {
                    h = (2.0 * h).clamp(-span.abs() / 16.0, span.abs() / 16.0);
                }
            }
            Ok(_) | Err(Failure::Jumped { .. }) | Err(Failure::NoConvergence { .. }) => {
                h /= 2.0;
                if h.abs() < settings.min_step_fraction * span.abs() {
                    return Err(singular(&here.pose, t, false));
                }
            }
            Err(f @ Failure::NotFinite) => return Err(f.into_error()),
        }
    }
    Ok(Tracked {
        solution: here,
        steps,
        max_condition,
    })
}

/// Legs whose lines are (nearly) linearly dependent at `pose`: the nonzero entries of the
/// left singular vector of the Jacobian's smallest singular value, i.e. the leg forces that
/// cancel to no wrench on the platform. One-based, as legs are numbered in reports.
pub fn dependent_legs(legs: &Legs, pose: &Pose) -> Vec<usize> {
    let svd = legs.homogeneous_jacobian(pose).svd(true, false);
    let Some(u) = svd.u else {
        return Vec::new();
    };
    let k = svd.singular_values.imin();
    let w = u.column(k);
    let max = w.amax();
    (0..6)
        .filter(|&i| w[i].abs() > 0.1 * max)
        .map(|i| i + 1)
        .collect()
}
