//! The forward kinematics of a six-leg platform as seven quadrics in Study's kinematic-image
//! coordinates, for real or complex geometry, with the 8 × 8 complex LU both homotopies
//! solve with.
//!
//! Unknowns `z = (e, g)`: the rotation quaternion `e` and `g = ½ p e` (`p` the position).
//! Leg `i`'s equation `|p + R bᵢ − aᵢ|² = Lᵢ²`, multiplied by `eᵀe`, is the quadric
//! `Fᵢ = N(Mᵢ e + 2g) − Lᵢ² N(e)` with `Mᵢ e = e bᵢ − aᵢ e` linear in the geometry
//! (`N` the bilinear quaternion norm `xᵀx`), and the Study condition is `e · g = 0`.
//! Because `Mᵢ` and `Lᵢ²` enter linearly, a platform on the segment between two others has
//! the same blend of their [`Study`] coefficients, which is what the parameter homotopy
//! follows.

use nalgebra::{Complex, SVector, Vector3};

use super::Legs;

pub(super) type C = Complex<f64>;
pub(super) type Z = SVector<C, 8>;
/// An 8 × 8 complex matrix as its columns (`j[c][r]`).
pub(super) type J = [[C; 8]; 8];
type V3 = [C; 3];
/// Each leg's `u = M e + 2g` ([`Study::legs`]).
pub(super) type LegVectors = [[C; 4]; 6];

/// One platform's coefficients: for each leg `dᵢ = bᵢ − aᵢ` and `sᵢ = bᵢ + aᵢ`, which make
/// `Mᵢ e = (−dᵢ·ε, e₀ dᵢ + ε × sᵢ)` for `e = (e₀, ε)`, and the squared lengths.
#[derive(Debug, Clone)]
pub(super) struct Study {
    d: [V3; 6],
    s: [V3; 6],
    l2: [C; 6],
}

fn dot3(a: &V3, b: &V3) -> C {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross3(a: &V3, b: &V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `M e` for the leg of `d`, `s`.
fn m_times(d: &V3, s: &V3, e0: C, ev: &V3) -> [C; 4] {
    let x = cross3(ev, s);
    [
        -dot3(d, ev),
        e0 * d[0] + x[0],
        e0 * d[1] + x[1],
        e0 * d[2] + x[2],
    ]
}

impl Study {
    /// A real platform.
    pub(super) fn real(legs: &Legs, lengths: &[f64; 6]) -> Study {
        let re = |v: Vector3<f64>| v.map(|x| C::new(x, 0.0));
        Study::complex(
            legs.base.map(re),
            legs.top.map(re),
            lengths.map(|l| C::new(l * l, 0.0)),
        )
    }

    /// A platform of complex base points `a`, platform points `b` and squared lengths `l2`.
    pub(super) fn complex(a: [Vector3<C>; 6], b: [Vector3<C>; 6], l2: [C; 6]) -> Study {
        Study {
            d: std::array::from_fn(|i| (b[i] - a[i]).into()),
            s: std::array::from_fn(|i| (b[i] + a[i]).into()),
            l2,
        }
    }

    /// `self + w·delta`: the platform at `w` on a segment whose direction is `delta`.
    pub(super) fn moved(&self, delta: &Study, w: C) -> Study {
        let v3 = |a: &[V3; 6], b: &[V3; 6]| {
            std::array::from_fn(|i| std::array::from_fn(|k| a[i][k] + w * b[i][k]))
        };
        Study {
            d: v3(&self.d, &delta.d),
            s: v3(&self.s, &delta.s),
            l2: std::array::from_fn(|i| self.l2[i] + w * delta.l2[i]),
        }
    }

    /// `other − self`, the direction from this platform to `other`.
    pub(super) fn towards(&self, other: &Study) -> Study {
        Study {
            d: std::array::from_fn(|i| std::array::from_fn(|k| other.d[i][k] - self.d[i][k])),
            s: std::array::from_fn(|i| std::array::from_fn(|k| other.s[i][k] - self.s[i][k])),
            l2: std::array::from_fn(|i| other.l2[i] - self.l2[i]),
        }
    }

    /// `u = M e + 2g` for each leg at `z`: what [`Study::eval_with`] and [`Study::rate`]
    /// share at one point.
    pub(super) fn legs(&self, z: &Z) -> LegVectors {
        let (e0, ev) = (z[0], [z[1], z[2], z[3]]);
        std::array::from_fn(|i| {
            let me = m_times(&self.d[i], &self.s[i], e0, &ev);
            std::array::from_fn(|k| me[k] + 2.0 * z[4 + k])
        })
    }

    /// The equations at `z` and their Jacobian: rows 0..5 `F_{k+1} − F_0`, row 5 `F_0`,
    /// row 6 the Study condition, row 7 the affine patch `patch · z = 1`.
    pub(super) fn eval(&self, z: &Z, patch: &Z) -> (Z, J) {
        self.eval_with(z, &self.legs(z), patch)
    }

    /// [`Study::eval`] with the legs' `u` at `z` ([`Study::legs`]) already known.
    pub(super) fn eval_with(&self, z: &Z, us: &LegVectors, patch: &Z) -> (Z, J) {
        let (e0, ev) = (z[0], [z[1], z[2], z[3]]);
        let gv = [z[5], z[6], z[7]];
        let ee = e0 * e0 + dot3(&ev, &ev);
        let mut legs = [C::new(0.0, 0.0); 6];
        // Row i of the leg equations' gradient: ∂/∂e = 2Mᵀu − 2L²e, ∂/∂g = 4u.
        let mut grads = [[C::new(0.0, 0.0); 8]; 6];
        for (i, u) in us.iter().enumerate() {
            let (d, s) = (&self.d[i], &self.s[i]);
            let uv = [u[1], u[2], u[3]];
            legs[i] = u[0] * u[0] + dot3(&uv, &uv) - ee * self.l2[i];
            // Mᵀu = (d·u_v, −u₀ d + s × u_v).
            let x = cross3(s, &uv);
            let l2 = 2.0 * self.l2[i];
            grads[i] = [
                2.0 * dot3(d, &uv) - l2 * e0,
                2.0 * (x[0] - u[0] * d[0]) - l2 * ev[0],
                2.0 * (x[1] - u[0] * d[1]) - l2 * ev[1],
                2.0 * (x[2] - u[0] * d[2]) - l2 * ev[2],
                4.0 * u[0],
                4.0 * u[1],
                4.0 * u[2],
                4.0 * u[3],
            ];
        }
        let mut f = Z::zeros();
        let mut j = [[C::new(0.0, 0.0); 8]; 8];
        for k in 0..5 {
            f[k] = legs[k + 1] - legs[0];
            for c in 0..8 {
                j[c][k] = grads[k + 1][c] - grads[0][c];
            }
        }
        f[5] = legs[0];
        f[6] = e0 * z[4] + dot3(&ev, &gv);
        f[7] = patch.dot(z) - C::new(1.0, 0.0);
        for c in 0..8 {
            j[c][5] = grads[0][c];
            j[c][6] = z[(c + 4) % 8];
            j[c][7] = patch[c];
        }
        (f, j)
    }

    /// The rows of [`Study::eval`] differentiated as the coefficients move along `along`
    /// (the Study condition and the patch do not move), with the legs' `u` at `z`.
    pub(super) fn rate(&self, z: &Z, us: &LegVectors, along: &Study) -> Z {
        let (e0, ev) = (z[0], [z[1], z[2], z[3]]);
        let ee = e0 * e0 + dot3(&ev, &ev);
        let rates: [C; 6] = std::array::from_fn(|i| {
            let (u, de) = (&us[i], m_times(&along.d[i], &along.s[i], e0, &ev));
            2.0 * (u[0] * de[0] + u[1] * de[1] + u[2] * de[2] + u[3] * de[3]) - ee * along.l2[i]
        });
        let mut ft = Z::zeros();
        for k in 0..5 {
            ft[k] = rates[k + 1] - rates[0];
        }
        ft[5] = rates[0];
        ft
    }
}

/// Largest component, each measured by `max(|re|, |im|)` (within √2 of its modulus, and
/// no square root): the size the trackers' tolerances are relative to.
pub(super) fn size(z: &Z) -> f64 {
    z.iter().fold(0.0, |m, c| m.max(c.re.abs()).max(c.im.abs()))
}

/// On (or next to) the degenerate set where the rotation quaternion's norm `eᵀe` vanishes:
/// no pose, only where paths of special platforms end.
pub(super) fn degenerate(z: &Z) -> bool {
    let e = z.fixed_rows::<4>(0);
    let size: f64 = z.iter().map(|c| c.norm_sqr()).sum();
    e.dot(&e).norm() < 1e-6 * size
}

/// LU factors with partial pivoting of an 8 × 8 complex matrix. Written out because it is
/// the inner loop of every path: real and imaginary parts in separate arrays of fixed size,
/// and every column update over all eight rows (the multipliers zero above the pivot), so
/// the loops have constant bounds the compiler unrolls and vectorises. nalgebra's generic LU
/// is several times slower on this size.
pub(super) struct Lu {
    /// Columns of `L` (below the diagonal, unit diagonal implied) and `U`.
    re: [[f64; 8]; 8],
    im: [[f64; 8]; 8],
    perm: [usize; 8],
}

impl Lu {
    /// `None` when a pivot is zero or not finite.
    pub(super) fn new(j: &J) -> Option<Lu> {
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU running this has just been found to have AVX2.
            return unsafe { Lu::factor_avx2(j) };
        }
        Lu::factor(j)
    }

    /// [`Lu::factor`] compiled for four-wide vectors.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn factor_avx2(j: &J) -> Option<Lu> {
        Lu::factor(j)
    }

    #[inline(always)]
    fn factor(j: &J) -> Option<Lu> {
        let mut re = j.map(|c| c.map(|x| x.re));
        let mut im = j.map(|c| c.map(|x| x.im));
        let mut perm = [0, 1, 2, 3, 4, 5, 6, 7];
        for k in 0..8 {
            let (mut p, mut best) = (k, 0.0);
            for r in k..8 {
                let v = re[k][r].abs() + im[k][r].abs();
                if v > best {
                    (p, best) = (r, v);
                }
            }
            if !(best > 0.0 && best.is_finite()) {
                return None;
            }
            if p != k {
                perm.swap(p, k);
                for c in 0..8 {
                    re[c].swap(k, p);
                    im[c].swap(k, p);
                }
            }
            let (pr, pi) = (re[k][k], im[k][k]);
            let n = pr * pr + pi * pi;
            let (ir, ii) = (pr / n, -pi / n);
            let (mut lr, mut li) = ([0.0; 8], [0.0; 8]);
            for r in k + 1..8 {
                let (a, b) = (re[k][r], im[k][r]);
                (lr[r], li[r]) = (a * ir - b * ii, a * ii + b * ir);
            }
            for r in k + 1..8 {
                (re[k][r], im[k][r]) = (lr[r], li[r]);
            }
            for c in k + 1..8 {
                let (ur, ui) = (re[c][k], im[c][k]);
                for r in 0..8 {
                    re[c][r] -= lr[r] * ur - li[r] * ui;
                    im[c][r] -= lr[r] * ui + li[r] * ur;
                }
            }
        }
        Some(Lu { re, im, perm })
    }

    pub(super) fn solve(&self, b: &Z) -> Z {
        let (re, im) = (&self.re, &self.im);
        let mut xr: [f64; 8] = std::array::from_fn(|r| b[self.perm[r]].re);
        let mut xi: [f64; 8] = std::array::from_fn(|r| b[self.perm[r]].im);
        for c in 0..8 {
            let (ur, ui) = (xr[c], xi[c]);
            for r in c + 1..8 {
                xr[r] -= re[c][r] * ur - im[c][r] * ui;
                xi[r] -= re[c][r] * ui + im[c][r] * ur;
            }
        }
        for c in (0..8).rev() {
            let (pr, pi) = (re[c][c], im[c][c]);
            let n = pr * pr + pi * pi;
            let (a, b) = (xr[c], xi[c]);
            let (ur, ui) = ((a * pr + b * pi) / n, (b * pr - a * pi) / n);
            (xr[c], xi[c]) = (ur, ui);
            for r in 0..c {
                xr[r] -= re[c][r] * ur - im[c][r] * ui;
                xi[r] -= re[c][r] * ui + im[c][r] * ur;
            }
        }
        Z::from_fn(|r, _| C::new(xr[r], xi[r]))
    }
}

/// Newton on the equations themselves from a path's end `z`: the solution to roundoff, or
/// `None` when it does not settle there or lies on the degenerate set.
pub(super) fn refine(study: &Study, patch: &Z, mut z: Z) -> Option<Z> {
    for _ in 0..12 {
        let (f, j) = study.eval(&z, patch);
        let dz = -Lu::new(&j)?.solve(&f);
        z += dz;
        if size(&dz) <= 1e-15 * (1.0 + size(&z)) {
            break;
        }
    }
    let (f, _) = study.eval(&z, patch);
    (size(&f) < 1e-8 && !degenerate(&z)).then_some(z)
}
