//! Every assembly mode of a six-leg platform: all complex solutions of the forward
//! kinematics (the Study-form quadrics of [`super::study`]) by homotopy continuation, then
//! the real ones polished by Newton.
//!
//! First the parameter homotopy ([`super::parameter`]): 40 paths from a generic complex
//! platform whose solutions are shipped ([`super::start`]). When its paths do not all end
//! on distinct solutions, or a special platform has fewer than 40 and a second attempt with
//! fresh random choices does not confirm the count, the linear-product homotopy
//! ([`super::linear_product`]), which needs nothing precomputed, is run as before.
//! Continuation rather than an elimination to one degree-40 polynomial: the elimination is
//! faster but fragile (its coefficients are badly conditioned), continuation needs only
//! 8 × 8 complex solves and every answer is polished by Newton on the leg lengths.

use nalgebra::{Matrix3, SMatrix, SVector, Vector3};

use super::linear_product::Homotopy;
use super::parameter::{End, ParameterHomotopy};
use super::study::{degenerate, refine, Study, C, Z};
use super::{start, Legs, Pose, Settings};
use crate::error::Error;

/// One real assembly mode.
#[derive(Debug, Clone, Copy)]
pub struct Mode {
    pub pose: Pose,
    /// Largest leg-length error after Newton polishing (m).
    pub residual: f64,
    /// Condition number of the homogeneous Jacobian ([`Legs::condition`]).
    pub condition: f64,
    /// Sign of the Jacobian's determinant.
    pub det_sign: f64,
}

/// All assembly modes found.
#[derive(Debug, Clone)]
pub struct Modes {
    /// The real poses, sorted by the platform origin's `z`, then `y`, then `x`, so the order
    /// is reproducible.
    pub real: Vec<Mode>,
    /// Distinct finite complex solutions found, real ones included (40 for a general
    /// platform; fewer for special geometries).
    pub complex: usize,
    /// Paths tracked over all attempts.
    pub paths: usize,
    /// Attempts, each with a fresh random `γ` and patch: one when all 40 are found, else
    /// until the count is confirmed.
    pub attempts: usize,
    /// `true` when the parameter homotopy left paths unaccounted for (or could not confirm
    /// a special platform's count) and the linear-product homotopy was run as well.
    pub fallback: bool,
}

/// The general platform's number of complex assembly modes (Raghavan 1993; Husty 1996).
pub const GENERIC_COUNT: usize = 40;

/// The seed of [`assembly_modes`]' random choices, so its answers are reproducible.
pub const DEFAULT_SEED: u64 = 0x5eed_0f40;

/// Finds every assembly mode of `legs` at `lengths`.
pub fn assembly_modes(legs: &Legs, lengths: &[f64; 6]) -> Result<Modes, Error> {
    assembly_modes_seeded(legs, lengths, DEFAULT_SEED)
}

/// [`assembly_modes`] with the random choices (the homotopies' `γ` and patches) drawn from
/// `seed`: the answer does not depend on them, only the work does.
pub fn assembly_modes_seeded(legs: &Legs, lengths: &[f64; 6], seed: u64) -> Result<Modes, Error> {
    modes(legs, lengths, seed, true)
}

/// [`assembly_modes_seeded`], from the shipped generic platform (`parameter`) or by the
/// linear-product homotopy alone (the method before it, kept to compare with in tests).
pub(super) fn modes(
    legs: &Legs,
    lengths: &[f64; 6],
    seed: u64,
    parameter: bool,
) -> Result<Modes, Error> {
    if !lengths.iter().all(|l| l.is_finite() && *l > 0.0) {
        return Err(Error::InvalidSetting {
            name: "leg length",
            value: lengths
                .iter()
                .copied()
                .find(|l| !(*l > 0.0))
                .unwrap_or(f64::NAN),
            reason: "leg lengths must be positive and finite",
        });
    }
    // Unit scale keeps the homotopy's tolerances meaningful for any size of platform.
    let scale = legs
        .base
        .iter()
        .chain(legs.top.iter())
        .map(|v| v.norm())
        .chain(lengths.iter().copied())
        .fold(0.0, f64::max);
    let unit = Legs {
        base: legs.base.map(|v| v / scale),
        top: legs.top.map(|v| v / scale),
    };
    let target = Study::real(&unit, &lengths.map(|l| l / scale));
    let mut rng = SplitMix(seed);
    let mut found = Found::default();
    let (mut attempts, mut confirmed) = (0, false);
    if parameter {
        (attempts, confirmed) = from_generic_start(&target, &mut rng, &mut found);
    }
    let fallback = found.poses.len() < GENERIC_COUNT && !confirmed;
    if fallback {
        attempts += from_linear_product(&target, &mut rng, &mut found);
    }
    let real = found
        .poses
        .iter()
        .filter(|pose| pose.iter().all(|c| c.im.abs() < 1e-7))
        .map(|pose| Pose {
            position: Vector3::new(pose[9].re, pose[10].re, pose[11].re) * scale,
            rotation: Matrix3::from_fn(|r, c| pose[3 * r + c].re),
        });
    let settings = Settings {
        tolerance: 1e-14 * scale,
        max_iterations: 20,
    };
    let lc = legs.characteristic_length();
    let mut modes: Vec<Mode> = Vec::new();
    for guess in real {
        // Polishing must stay on the mode it started from: a pose that moved is dropped
        // rather than counted twice.
        let Ok(s) = legs.solve(lengths, &guess, settings).or_else(|_| {
            legs.solve(
                lengths,
                &guess,
                Settings {
                    tolerance: 1e-11 * scale,
                    ..settings
                },
            )
        }) else {
            continue;
        };
        if s.pose.distance(&guess, lc) > 1e-6 * scale
            || modes
                .iter()
                .any(|m| m.pose.distance(&s.pose, lc) < 1e-9 * scale)
        {
            continue;
        }
        modes.push(Mode {
            pose: s.pose,
            residual: s.residual,
            condition: s.condition,
            det_sign: s.det_sign,
        });
    }
    modes.sort_by(|a, b| {
        let (p, q) = (a.pose.position, b.pose.position);
        (p.z, p.y, p.x).partial_cmp(&(q.z, q.y, q.x)).unwrap()
    });
    Ok(Modes {
        real: modes,
        complex: found.poses.len(),
        paths: found.paths,
        attempts,
        fallback,
    })
}

/// Rotation (row-major, 9) and position (3) of a solution, complex in general; `None` on
/// the degenerate set.
fn complex_pose(z: &Z) -> Option<[C; 12]> {
    let mut e = z.fixed_rows::<4>(0).into_owned();
    let mut g = z.fixed_rows::<4>(4).into_owned();
    let n = e.dot(&e);
    if n.norm() < 1e-12 {
        return None;
    }
    // Scale the homogeneous solution to eᵀe = 1: a real pose then has a real (e, g).
    let lambda = C::new(1.0, 0.0) / n.sqrt();
    e *= lambda;
    g *= lambda;
    let (e0, v) = (e[0], SVector::<C, 3>::new(e[1], e[2], e[3]));
    let gv = SVector::<C, 3>::new(g[1], g[2], g[3]);
    let two = C::new(2.0, 0.0);
    let r = SMatrix::<C, 3, 3>::identity() * (e0 * e0 - v.dot(&v))
        + v * v.transpose() * two
        + v.cross_matrix() * (e0 * two);
    // p = 2 g ẽ (vector part) for eᵀe = 1.
    let p = (gv * e0 - v * g[0] - gv.cross(&v)) * two;
    let mut out = [C::new(0.0, 0.0); 12];
    for k in 0..9 {
        out[k] = r[(k / 3, k % 3)];
    }
    out[9..].copy_from_slice(p.as_slice());
    out.iter()
        .all(|c| c.re.is_finite() && c.im.is_finite())
        .then_some(out)
}

/// The parameter homotopy from the shipped generic platform, into `found`: one attempt when
/// it ends on 40 distinct solutions, else a second with fresh random choices. Returns the
/// attempts and whether the count is confirmed: a special platform has fewer than 40 finite
/// solutions, and a second attempt that adds nothing, with every path of both ending
/// somewhere known (a solution, or the degenerate set), confirms it.
fn from_generic_start(target: &Study, rng: &mut SplitMix, found: &mut Found) -> (usize, bool) {
    let generic = start::generic();
    let (mut attempts, mut unaccounted) = (0, 0);
    while attempts < 2 && found.poses.len() < GENERIC_COUNT {
        attempts += 1;
        let before = found.poses.len();
        let h = ParameterHomotopy::new(&generic.study, target, rng);
        let mut this_attempt = Found::default();
        for z in &generic.solutions {
            found.paths += 1;
            let ended = match h.track(h.on_patch(z)) {
                End::Reached(z) => match refine(target, &h.patch, z) {
                    Some(z) => Some(Some(z)),
                    None => degenerate(&z).then_some(None),
                },
                End::Degenerate => Some(None),
                End::Failed => None,
            };
            match ended {
                Some(Some(z)) if this_attempt.add(&z) => {
                    found.add(&z);
                }
                Some(None) => {}
                // A failed path, or two paths of one attempt at one solution (one jumped).
                _ => unaccounted += 1,
            }
        }
        if attempts == 2 {
            return (2, unaccounted == 0 && found.poses.len() == before);
        }
    }
    (attempts, false)
}

/// The linear-product homotopy into `found`, repeated with fresh random choices until an
/// attempt adds nothing (a path lost to bad luck in one attempt is found by the next) or
/// all 40 are there, at most four times. Returns the attempts.
fn from_linear_product(target: &Study, rng: &mut SplitMix, found: &mut Found) -> usize {
    let mut attempts = 0;
    let mut added = usize::MAX;
    while attempts < 4 && found.poses.len() < GENERIC_COUNT && added > 0 {
        attempts += 1;
        let before = found.poses.len();
        let h = Homotopy::new(target, rng);
        for start in h.starts() {
            found.paths += 1;
            if let Some(z) = h.track(start).and_then(|z| refine(target, &h.patch, z)) {
                found.add(&z);
            }
        }
        added = found.poses.len() - before;
    }
    attempts
}

/// Distinct finite solutions, as complex poses, and the paths that led to them.
#[derive(Default)]
struct Found {
    poses: Vec<[C; 12]>,
    paths: usize,
}

impl Found {
    /// Adds the pose of the solution `z`; `false` when it is not a pose or already there.
    fn add(&mut self, z: &Z) -> bool {
        let Some(pose) = complex_pose(z) else {
            return false;
        };
        let close = |f: &[C; 12]| f.iter().zip(&pose).all(|(x, y)| (x - y).norm() < 1e-6);
        if self.poses.iter().any(close) {
            return false;
        }
        self.poses.push(pose);
        true
    }
}

/// A small deterministic generator (SplitMix64), so runs are reproducible without a
/// dependency: numbers in [0, 1).
pub(crate) struct SplitMix(pub(crate) u64);

impl SplitMix {
    pub(crate) fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut x = self.0;
        x = (x ^ (x >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        x = (x ^ (x >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        x ^= x >> 31;
        (x >> 11) as f64 / (1u64 << 53) as f64
    }
    /// A random point on the unit circle.
    pub(super) fn complex(&mut self) -> C {
        C::from_polar(1.0, std::f64::consts::TAU * self.next())
    }
}

#[cfg(test)]
pub(super) fn study_residual(legs: &Legs, lengths: &[f64; 6], pose: &Pose) -> f64 {
    let study = Study::real(legs, lengths);
    let q = nalgebra::UnitQuaternion::from_matrix(&pose.rotation);
    let e = nalgebra::Vector4::new(q.w, q.i, q.j, q.k);
    let pq = nalgebra::Quaternion::from_imag(pose.position);
    let gq = pq * nalgebra::Quaternion::new(e[0], e[1], e[2], e[3]) * 0.5;
    let z = Z::from_fn(|k, _| {
        C::new(
            if k < 4 {
                e[k]
            } else {
                [gq.w, gq.i, gq.j, gq.k][k - 4]
            },
            0.0,
        )
    });
    let (f, _) = study.eval(&z, &Z::zeros());
    f.rows(0, 7).camax()
}
