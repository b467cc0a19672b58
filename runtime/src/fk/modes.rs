//! Every assembly mode of a six-leg platform: all complex solutions of the forward
//! kinematics by total-degree homotopy continuation, then the real ones polished by Newton.
//!
//! Why this formulation: in Study's kinematic-image coordinates (rotation quaternion `e`,
//! translation part `g = ½ p e`) a leg's equation `|p + R b − a|² = L²` becomes, multiplied
//! by `eᵀe`, the quadric `Fᵢ = N(e b − a e + 2g) − L² N(e) = 0` (`N` the quaternion norm),
//! and the Study condition `e · g = 0` is a quadric too: seven homogeneous quadrics in 8
//! unknowns, solved on a random affine patch. The differences `Fᵢ − F₁` lose the `N(g)` term,
//! so five equations are products of a form in `e` and a form in `(e, g)`, the Study
//! condition a form in `e` times one in `g`, and only `F₁` needs two general forms. A start
//! system of products of random linear forms with exactly that structure has 84 regular
//! solutions (against 2⁷ = 128 for a total-degree start: the 44 it saves would all end on
//! the degenerate set `e = 0`); by the theory of linear-product homotopies its paths reach
//! every isolated solution, here the general platform's 40 poses (Raghavan 1993). The other
//! 44 paths end on `e = 0`, recognised and dropped. An elimination to one degree-40 polynomial
//! is faster but fragile (its coefficients are badly conditioned); continuation needs only
//! 8 × 8 complex solves. The random complex `γ` in `H = γ(1 − t)G + tF` keeps every path
//! regular for `t < 1` with probability one.

use nalgebra::{Complex, Matrix3, Matrix4, SMatrix, SVector, Vector3};

use super::{Legs, Pose, Settings};
use crate::error::Error;

type C = Complex<f64>;
type Z = SVector<C, 8>;
type J = SMatrix<C, 8, 8>;

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
    /// until an attempt adds nothing new (at most 4).
    pub attempts: usize,
}

/// The general platform's number of complex assembly modes (Raghavan 1993; Husty 1996).
pub const GENERIC_COUNT: usize = 40;

/// Finds every assembly mode of `legs` at `lengths`.
pub fn assembly_modes(legs: &Legs, lengths: &[f64; 6]) -> Result<Modes, Error> {
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
    let l_unit = lengths.map(|l| l / scale);
    let mut rng = SplitMix(0x5eed_0f40);
    let mut found: Vec<[C; 12]> = Vec::new();
    let mut real: Vec<Pose> = Vec::new();
    let mut paths = 0;
    let mut attempts = 0;
    // A special geometry has fewer than 40 finite solutions; an attempt with a fresh γ and
    // patch that adds none says the count is complete (a path lost to bad luck in one
    // attempt is found by the next).
    let mut added = usize::MAX;
    while attempts < 4 && found.len() < GENERIC_COUNT && added > 0 {
        attempts += 1;
        let before = found.len();
        let h = Homotopy::new(&unit, &l_unit, &mut rng);
        for start in h.starts() {
            paths += 1;
            let Some(z) = h.track(start) else { continue };
            let Some(z) = h.refine(z) else { continue };
            let Some(pose) = complex_pose(&z) else {
                continue;
            };
            if found.iter().any(|f| close(f, &pose, 1e-6)) {
                continue;
            }
            found.push(pose);
            if pose.iter().all(|c| c.im.abs() < 1e-7) {
                real.push(Pose {
                    position: Vector3::new(pose[9].re, pose[10].re, pose[11].re) * scale,
                    rotation: Matrix3::from_fn(|r, c| pose[3 * r + c].re),
                });
            }
        }
        added = found.len() - before;
    }
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
        complex: found.len(),
        paths,
        attempts,
    })
}

/// The 7 quadrics `F` (5 leg differences, leg 1, Study condition), the start system `G`
/// and the patch.
struct Homotopy {
    /// `e b − a e = M e` for each leg, and `Mᵀ`, both complex once for all evaluations.
    m: [SMatrix<C, 4, 4>; 6],
    mt: [SMatrix<C, 4, 4>; 6],
    l2: [f64; 6],
    /// `G_k = (A_k · z)(B_k · z)`: the two random linear forms of each start equation, with
    /// the supports of `F_k`'s structure.
    forms: [[Z; 2]; 7],
    patch: Z,
    gamma: C,
}

/// Which unknowns a start form may involve.
#[derive(Clone, Copy, PartialEq)]
enum Support {
    E,
    G,
    All,
}

impl Homotopy {
    fn new(legs: &Legs, lengths: &[f64; 6], rng: &mut SplitMix) -> Self {
        let m: [SMatrix<C, 4, 4>; 6] = std::array::from_fn(|i| {
            let (a, b) = (legs.base[i], legs.top[i]);
            let (d, s) = (b - a, b + a);
            // e b − a e = (ε·(a − b), e0 (b − a) + ε × (b + a)) for pure a, b.
            Matrix4::new(
                0.0, -d.x, -d.y, -d.z, //
                d.x, 0.0, s.z, -s.y, //
                d.y, -s.z, 0.0, s.x, //
                d.z, s.y, -s.x, 0.0,
            )
            .map(|x| C::new(x, 0.0))
        });
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
            mt: m.map(|m| m.transpose()),
            m,
            l2: lengths.map(|l| l * l),
            forms,
            patch: Z::from_fn(|_, _| rng.complex()),
            gamma: rng.complex(),
        }
    }

    /// The start points: one factor of each start equation set to zero, with the patch.
    /// Choices that zero four forms in `e` give `e = 0`, a positive-dimensional solution set
    /// of `G`, not a start point: 84 of the 128 choices remain.
    fn starts(&self) -> impl Iterator<Item = Z> + '_ {
        (0..128u32).filter_map(|choice| {
            let pick = |k: usize| (choice >> k) as usize & 1;
            let e_only = (0..5).filter(|&k| pick(k) == 0).count() + usize::from(pick(6) == 0);
            if e_only > 3 {
                return None;
            }
            let mut a = J::zeros();
            for k in 0..7 {
                a.row_mut(k).copy_from(&self.forms[k][pick(k)].transpose());
            }
            a.row_mut(7).copy_from(&self.patch.transpose());
            let mut rhs = Z::zeros();
            rhs[7] = C::new(1.0, 0.0);
            a.lu().solve(&rhs)
        })
    }

    /// `F(z)` and `∂F/∂z`: rows 0..5 `F_{k+1} − F_0`, row 5 `F_0`, row 6 the Study
    /// condition, row 7 the patch.
    fn target(&self, z: &Z) -> (Z, J) {
        let e = z.fixed_rows::<4>(0).into_owned();
        let g = z.fixed_rows::<4>(4).into_owned();
        let ee = e.dot(&e);
        let mut legs = [C::new(0.0, 0.0); 6];
        let mut grads = [Z::zeros(); 6];
        for i in 0..6 {
            let w = self.m[i] * e + g * C::new(2.0, 0.0);
            legs[i] = w.dot(&w) - ee * self.l2[i];
            let de = self.mt[i] * w * C::new(2.0, 0.0) - e * C::new(2.0 * self.l2[i], 0.0);
            let dg = w * C::new(4.0, 0.0);
            grads[i].fixed_rows_mut::<4>(0).copy_from(&de);
            grads[i].fixed_rows_mut::<4>(4).copy_from(&dg);
        }
        let mut f = Z::zeros();
        let mut j = J::zeros();
        for k in 0..5 {
            f[k] = legs[k + 1] - legs[0];
            j.row_mut(k)
                .copy_from(&(grads[k + 1] - grads[0]).transpose());
        }
        f[5] = legs[0];
        j.row_mut(5).copy_from(&grads[0].transpose());
        f[6] = e.dot(&g);
        for k in 0..4 {
            j[(6, k)] = g[k];
            j[(6, 4 + k)] = e[k];
        }
        f[7] = self.patch.dot(z) - C::new(1.0, 0.0);
        j.row_mut(7).copy_from(&self.patch.transpose());
        (f, j)
    }

    /// `H(z, t)`, `∂H/∂z` and `∂H/∂t`.
    fn eval(&self, z: &Z, t: f64) -> (Z, J, Z) {
        let (f, jf) = self.target(z);
        let mut g = Z::zeros();
        let mut jg = J::zeros();
        for k in 0..7 {
            let [a, b] = &self.forms[k];
            let (az, bz) = (a.dot(z), b.dot(z));
            g[k] = az * bz;
            jg.row_mut(k).copy_from(&(a * bz + b * az).transpose());
        }
        let (s, u) = (self.gamma * (1.0 - t), C::new(t, 0.0));
        let mut h = g * s + f * u;
        let mut jh = jg * s + jf * u;
        let mut ht = f - g * self.gamma;
        h[7] = f[7];
        jh.row_mut(7).copy_from(&jf.row(7));
        ht[7] = C::new(0.0, 0.0);
        (h, jh, ht)
    }

    /// `dz/dt = −H_z⁻¹ H_t`.
    fn velocity(&self, z: &Z, t: f64) -> Option<Z> {
        let (_, jh, ht) = self.eval(z, t);
        jh.lu().solve(&(-ht))
    }

    /// Follows one path from `t = 0` to `t = 1`: a fourth-order Runge–Kutta prediction
    /// and at most three Newton corrections per step, the step halved when they do not
    /// settle and doubled after a run of easy steps. `None` for a path that ends on the
    /// degenerate set or cannot be followed.
    fn track(&self, mut z: Z) -> Option<Z> {
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
            let dz = jh.lu().solve(&(-h))?;
            z += dz;
            let (step, size) = (dz.camax(), 1.0 + z.camax());
            if step <= 1e-8 * size {
                return Some(z);
            }
            // A first correction this large means the prediction left the path's basin.
            if it == 0 && step > 0.05 * size {
                return None;
            }
        }
        None
    }

    /// Newton on `F` itself at the path's end.
    fn refine(&self, mut z: Z) -> Option<Z> {
        for _ in 0..12 {
            let (f, j) = self.target(&z);
            let dz = j.lu().solve(&(-f))?;
            z += dz;
            if dz.camax() <= 1e-15 * (1.0 + z.camax()) {
                break;
            }
        }
        let (f, _) = self.target(&z);
        (f.camax() < 1e-8 && !degenerate(&z)).then_some(z)
    }
}

/// On (or next to) the degenerate set where the rotation quaternion's norm `eᵀe` vanishes.
fn degenerate(z: &Z) -> bool {
    let e = z.fixed_rows::<4>(0);
    let size: f64 = z.iter().map(|c| c.norm_sqr()).sum();
    e.dot(&e).norm() < 1e-6 * size
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

fn close(a: &[C; 12], b: &[C; 12], tol: f64) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).norm() < tol)
}

/// A small deterministic generator (SplitMix64), so runs are reproducible without a
/// dependency.
struct SplitMix(u64);

impl SplitMix {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut x = self.0;
        x = (x ^ (x >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        x = (x ^ (x >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        x ^= x >> 31;
        (x >> 11) as f64 / (1u64 << 53) as f64
    }
    /// A random point on the unit circle.
    fn complex(&mut self) -> C {
        C::from_polar(1.0, std::f64::consts::TAU * self.next())
    }
}

#[cfg(test)]
pub(super) fn study_residual(legs: &Legs, lengths: &[f64; 6], pose: &Pose) -> f64 {
    let h = Homotopy::new(legs, lengths, &mut SplitMix(1));
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
    let (f, _) = h.target(&z);
    f.rows(0, 7).camax()
}
