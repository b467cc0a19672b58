//! Helpers shared by the integration tests: a reproducible random generator and small
//! dense-matrix utilities over the generated sparse outputs.

use nalgebra::{DMatrix, Matrix3, Quaternion, Rotation3, UnitQuaternion, Vector3};
use symbody_runtime::{BodyInfo, HhtBuilder, Mechanism, MechanismInfo, Rotation};

/// splitmix64: deterministic, so a failing configuration reproduces.
pub struct Rng(pub u64);

impl Rng {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The positions after `t_end` of HHT (α = −0.05, h = 1 ms, the file's velocities projected)
/// from the file's pose: one whole run to compare two routes by.
pub fn hht_positions(m: impl Mechanism, t_end: f64) -> Vec<f64> {
    let qd0 = m.info().qd0;
    let mut it = HhtBuilder::new()
        .alpha(-0.05)
        .step(1e-3)
        .qd0(qd0)
        .project_velocities(true)
        .build(m)
        .unwrap();
    it.advance_to(t_end).unwrap();
    it.q().to_vec()
}

/// Largest |a − b| relative to the largest |b|: how far a result is from its reference.
pub fn max_rel(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs() / scale))
}

/// A dense `shape` matrix from nonzeros `nnz` at `(rows[k], cols[k])`.
pub fn dense(shape: (usize, usize), rows: &[u32], cols: &[u32], nnz: &[f64]) -> DMatrix<f64> {
    let mut m = DMatrix::zeros(shape.0, shape.1);
    for ((&r, &c), &v) in rows.iter().zip(cols).zip(nnz) {
        m[(r as usize, c as usize)] = v;
    }
    m
}

/// Dense Φq from its nonzeros.
pub fn dense_phi_q(info: &MechanismInfo, nnz: &[f64]) -> DMatrix<f64> {
    let shape = (info.n_constraints, info.n_coords);
    dense(shape, info.phi_q_rows, info.phi_q_cols, nnz)
}

/// Dense mass matrix from its nonzeros.
pub fn dense_mass(info: &MechanismInfo, nnz: &[f64]) -> DMatrix<f64> {
    let shape = (info.n_coords, info.n_coords);
    dense(shape, info.mass_rows, info.mass_cols, nnz)
}

/// A random configuration near q0: positions within ±5 cm, angles within ±0.5 rad, but
/// every β kept inside ±1.3 rad (away from the Euler singularity).
pub fn random_state(rng: &mut Rng, q0: &[f64]) -> (Vec<f64>, Vec<f64>, f64) {
    let q: Vec<f64> = q0
        .iter()
        .enumerate()
        .map(|(i, &x)| {
            let k = i % 6;
            let v = if k < 3 {
                x + rng.uniform(-0.05, 0.05)
            } else {
                x + rng.uniform(-0.5, 0.5)
            };
            if k == 4 {
                v.clamp(-1.3, 1.3)
            } else {
                v
            }
        })
        .collect();
    let qd: Vec<f64> = (0..q0.len()).map(|_| rng.uniform(-1.0, 1.0)).collect();
    let t = rng.uniform(0.0, 7.0);
    (q, qd, t)
}

/// A random state of any mechanism around its `q0`, body by body (`info.bodies`): centres
/// of mass within ±5 cm; Euler angles within ±0.5 rad with β kept inside ±1.3 rad (away
/// from the Euler singularity); Euler parameters perturbed by ±0.3 each and normalized to
/// |e| = 1. Velocities uniform in ±1 (quaternion rates included, so ė is not tangent to the
/// unit sphere), time uniform in [0, 7].
pub fn random_state_for(rng: &mut Rng, info: &MechanismInfo) -> (Vec<f64>, Vec<f64>, f64) {
    let mut q = info.q0.to_vec();
    for b in info.bodies {
        let o = b.coord_offset;
        for x in &mut q[o..o + 3] {
            *x += rng.uniform(-0.05, 0.05);
        }
        match b.rotation {
            Rotation::Euler => {
                for k in 3..6 {
                    q[o + k] += rng.uniform(-0.5, 0.5);
                }
                q[o + 4] = q[o + 4].clamp(-1.3, 1.3);
            }
            Rotation::Quaternion => {
                for k in 3..7 {
                    q[o + k] += rng.uniform(-0.3, 0.3);
                }
                let norm = q[o + 3..o + 7].iter().map(|e| e * e).sum::<f64>().sqrt();
                for e in &mut q[o + 3..o + 7] {
                    *e /= norm;
                }
            }
        }
    }
    let qd: Vec<f64> = (0..q.len()).map(|_| rng.uniform(-1.0, 1.0)).collect();
    let t = rng.uniform(0.0, 7.0);
    (q, qd, t)
}

/// First derivative of `f` at 0 by the fourth-order central stencil
/// (f(−2h) − 8f(−h) + 8f(h) − f(2h)) / 12h.
pub fn d1<T>(f: impl Fn(f64) -> T, h: f64) -> T
where
    T: std::ops::Add<Output = T> + std::ops::Sub<Output = T> + std::ops::Mul<f64, Output = T>,
{
    (f(-2.0 * h) - f(2.0 * h) + (f(h) - f(-h)) * 8.0) * (1.0 / (12.0 * h))
}

/// The body's rotation matrix (local → global) from nalgebra: Rz(γ)·Ry(β)·Rx(θ) for Euler
/// angles, the unit quaternion e/|e| (scalar first) for Euler parameters.
pub fn rotation(body: &BodyInfo, q: &[f64]) -> Matrix3<f64> {
    let r = &q[body.coord_offset + 3..];
    match body.rotation {
        Rotation::Euler => {
            let rz = Rotation3::from_axis_angle(&Vector3::z_axis(), r[2]);
            let ry = Rotation3::from_axis_angle(&Vector3::y_axis(), r[1]);
            let rx = Rotation3::from_axis_angle(&Vector3::x_axis(), r[0]);
            (rz * ry * rx).into_inner()
        }
        Rotation::Quaternion => {
            UnitQuaternion::from_quaternion(Quaternion::new(r[0], r[1], r[2], r[3]))
                .to_rotation_matrix()
                .into_inner()
        }
    }
}
