//! Hand-written reference for the Stewart platform's constraint equations Φ(q, t), written
//! once from `docs/paper-scenario.md` (not from the generator), generic over num-dual's
//! scalars so one formulation yields Φ (`f64`), Φq (`Dual64`, `DualSVec64`) and γ (`Dual2_64`).
//!
//! Shared by `bench/micro/benches/kernels.rs` (the AD baselines) and `tests/reference_model.rs` (the
//! cross-check of the generated code). Coordinate and row order are the scenario's:
//! coordinates platform, upper legs 1..6, lower legs 1..6, six per body `[X, Y, Z, θ, β, γ]`;
//! rows upper spherical (0–17), prismatic (18–47), lower spherical (48–65), drivers (66–71).

// Each includer uses a different subset of the helpers.
#![allow(dead_code)]

use num_dual::DualNum;

/// Coordinates.
pub const N: usize = 78;
/// Constraint rows.
pub const M: usize = 72;

/// Radius of the base joint circle (m).
const R_BASE: f64 = 0.27;
/// Radius of the platform joint circle (m).
const R_PLATFORM: f64 = 0.105;
/// Joint to centre of mass of each leg part, along the part's local y (m).
const HALF: f64 = 0.125;
/// Base joint angles Φi (deg), paper Table 1.
const BASE_DEG: [f64; 6] = [10.5, 109.5, 130.5, 229.5, 250.5, 349.5];
/// Platform joint angles αi (deg), paper Table 1.
const PLATFORM_DEG: [f64; 6] = [49.5, 70.5, 169.5, 190.5, 289.5, 310.5];
/// Driver amplitudes a_i (m), paper Table 2.
pub const AMPLITUDE: [f64; 6] = [0.02, -0.06, 0.02, -0.02, 0.08, -0.02];

/// First coordinate of the platform, of upper leg `i` and of lower leg `i` (i = 0..6).
const fn platform() -> usize {
    0
}
const fn upper(i: usize) -> usize {
    6 * (1 + i)
}
const fn lower(i: usize) -> usize {
    6 * (7 + i)
}

/// The rotation A = Rz(γ)·Ry(β)·Rx(θ) as its three columns (the body's local x, y, z axes
/// in the global frame), multiplied out by hand.
pub fn rotation<T: DualNum<f64> + Copy>(theta: T, beta: T, gamma: T) -> [[T; 3]; 3] {
    let (st, ct) = theta.sin_cos();
    let (sb, cb) = beta.sin_cos();
    let (sg, cg) = gamma.sin_cos();
    [
        [cg * cb, sg * cb, -sb],
        [cg * sb * st - sg * ct, sg * sb * st + cg * ct, cb * st],
        [cg * sb * ct + sg * st, sg * sb * ct - cg * st, cb * ct],
    ]
}

fn dot<T: DualNum<f64> + Copy>(a: &[T; 3], b: &[T; 3]) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The point at radius `r` and angle `deg` counter-clockwise from +X seen from above
/// (a positive rotation about +Y): `(r cos φ, 0, −r sin φ)`.
fn on_circle(r: f64, deg: f64) -> [f64; 3] {
    let (s, c) = deg.to_radians().sin_cos();
    [r * c, 0.0, -r * s]
}

/// The constant data of the scenario; `c0` depends on the initial pose.
#[derive(Debug, Clone)]
pub struct Stewart {
    /// Base joints Bi, global frame.
    pub base: [[f64; 3]; 6],
    /// Platform joints T'i, platform frame.
    pub top: [[f64; 3]; 6],
    /// Driver offsets c_i0: the initial distance between a leg's centres of mass along
    /// the cylinder axis.
    pub c0: [f64; 6],
}

impl Stewart {
    /// The scenario's geometry with the driver offsets read off the initial pose `q0`
    /// ("c_i0 = its initial value").
    pub fn new(q0: &[f64]) -> Self {
        let mut s = Stewart {
            base: std::array::from_fn(|i| on_circle(R_BASE, BASE_DEG[i])),
            top: std::array::from_fn(|i| on_circle(R_PLATFORM, PLATFORM_DEG[i])),
            c0: [0.0; 6],
        };
        let q0: &[f64; N] = q0.try_into().expect("q0 must have 78 entries");
        s.c0 = std::array::from_fn(|i| s.leg_extension(q0, i));
        s
    }

    /// `(A_L · e_y) · (r_U − r_L)` of leg `i`: the distance of the two centres of mass
    /// along the cylinder axis (the driven quantity).
    pub fn leg_extension<T: DualNum<f64> + Copy>(&self, q: &[T; N], i: usize) -> T {
        let (u, l) = (upper(i), lower(i));
        let a_l = rotation(q[l + 3], q[l + 4], q[l + 5]);
        let d = [q[u] - q[l], q[u + 1] - q[l + 1], q[u + 2] - q[l + 2]];
        dot(&a_l[1], &d)
    }

    /// Φ(q, t), all 72 rows in the scenario's order.
    pub fn phi<T: DualNum<f64> + Copy>(&self, q: &[T; N], t: T, out: &mut [T; M]) {
        let p = platform();
        let a_p = rotation(q[p + 3], q[p + 4], q[p + 5]);
        let sin_t = t.sin();
        for i in 0..6 {
            let (u, l) = (upper(i), lower(i));
            let a_u = rotation(q[u + 3], q[u + 4], q[u + 5]);
            let a_l = rotation(q[l + 3], q[l + 4], q[l + 5]);
            let tp = self.top[i];
            let b = self.base[i];
            // r_U − r_L: shared by the no-slide rows and the driver.
            let d = [q[u] - q[l], q[u + 1] - q[l + 1], q[u + 2] - q[l + 2]];
            for k in 0..3 {
                // Upper spherical joint: R_p + A_p·T'_i − R_U − A_U·(0, HALF, 0); T'_i has
                // no local y component.
                out[3 * i + k] =
                    q[p + k] + a_p[0][k] * tp[0] + a_p[2][k] * tp[2] - q[u + k] - a_u[1][k] * HALF;
                // Prismatic joint: equal Euler angles.
                out[18 + 5 * i + k] = q[u + 3 + k] - q[l + 3 + k];
                // Lower spherical joint: B_i − R_L − A_L·(0, −HALF, 0).
                out[48 + 3 * i + k] = T::from(b[k]) - q[l + k] + a_l[1][k] * HALF;
            }
            // No sliding: Rz(90°)·e_y = −e_x and Rx(90°)·e_y = +e_z, in the cylinder frame.
            out[18 + 5 * i + 3] = -dot(&a_l[0], &d);
            out[18 + 5 * i + 4] = dot(&a_l[2], &d);
            // Driver: extension along the cylinder axis minus c_i(t) = c_i0 + a_i sin t.
            out[66 + i] = dot(&a_l[1], &d) - (sin_t * AMPLITUDE[i] + self.c0[i]);
        }
    }

    /// Φ in plain `f64` through the same generic code.
    pub fn phi_f64(&self, q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; N] = q.try_into().expect("q must have 78 entries");
        let out: &mut [f64; M] = out.try_into().expect("out must have 72 entries");
        self.phi(q, t, out);
    }
}

/// Position of each (row, column) of Φq in a sparse pattern, so dense derivative columns
/// can be scattered into the generated code's nonzero order.
pub struct PatternIndex {
    slot: Vec<[u16; N]>,
    /// Per column, its structural nonzeros as (row, slot).
    by_col: Vec<Vec<(u16, u16)>>,
}

impl PatternIndex {
    /// Marks entries outside the pattern.
    pub const NONE: u16 = u16::MAX;

    pub fn new(rows: &[u32], cols: &[u32]) -> Self {
        let mut slot = vec![[Self::NONE; N]; M];
        let mut by_col = vec![Vec::new(); N];
        for (k, (&r, &c)) in rows.iter().zip(cols).enumerate() {
            let k = u16::try_from(k).expect("pattern fits in u16");
            slot[r as usize][c as usize] = k;
            by_col[c as usize].push((r as u16, k));
        }
        PatternIndex { slot, by_col }
    }

    /// Slot of entry (row, col), or [`PatternIndex::NONE`].
    pub fn get(&self, row: usize, col: usize) -> u16 {
        self.slot[row][col]
    }

    /// The structural nonzeros of column `col` as (row, slot).
    pub fn column(&self, col: usize) -> &[(u16, u16)] {
        &self.by_col[col]
    }
}

impl Stewart {
    /// Forward-mode Φq, one `Dual64` pass per coordinate: `sink(j, Φ)` receives the dual
    /// residual whose `eps` parts are column `j`.
    pub fn phi_q_columns(
        &self,
        q: &[f64],
        t: f64,
        mut sink: impl FnMut(usize, &[num_dual::Dual64; M]),
    ) {
        use num_dual::Dual64;
        let mut x: [Dual64; N] = std::array::from_fn(|k| Dual64::from_re(q[k]));
        let t = Dual64::from_re(t);
        let mut out = [Dual64::from_re(0.0); M];
        for j in 0..N {
            x[j].eps = 1.0;
            self.phi(&x, t, &mut out);
            x[j].eps = 0.0;
            sink(j, &out);
        }
    }

    /// Forward-mode Φq in blocks: one pass per body, seeding its six coordinates with a
    /// 6-wide vector dual. `sink(body, Φ)` receives columns `6·body .. 6·body + 6`.
    pub fn phi_q_blocks(
        &self,
        q: &[f64],
        t: f64,
        mut sink: impl FnMut(usize, &[num_dual::DualSVec64<6>; M]),
    ) {
        use num_dual::{Derivative, DualSVec64};
        let re = |v: f64| DualSVec64::<6>::from_re(v);
        let mut x: [DualSVec64<6>; N] = std::array::from_fn(|k| re(q[k]));
        let t = re(t);
        let mut out = [re(0.0); M];
        for body in 0..N / 6 {
            for k in 0..6 {
                x[6 * body + k].eps =
                    Derivative::derivative_generic(nalgebra::Const::<6>, nalgebra::U1, k);
            }
            self.phi(&x, t, &mut out);
            for k in 0..6 {
                x[6 * body + k].eps = Derivative::none();
            }
            sink(body, &out);
        }
    }

    /// γ = −d²Φ/ds² along the line s ↦ (q + s q̇, t + s), i.e. −(q̇ᵀΦqq q̇ + 2Φqt q̇ + Φtt),
    /// from one second-order dual pass.
    pub fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        use num_dual::Dual2_64;
        let x: [Dual2_64; N] = std::array::from_fn(|k| Dual2_64::new(q[k], qd[k], 0.0));
        let mut r = [Dual2_64::from_re(0.0); M];
        self.phi(&x, Dual2_64::new(t, 1.0, 0.0), &mut r);
        for (o, v) in out.iter_mut().zip(&r) {
            *o = -v.v2;
        }
    }
}
