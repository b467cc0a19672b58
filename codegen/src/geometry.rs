//! Numeric rigid-body geometry at the initial pose (nalgebra): rotation matrices from Euler
//! angles and Euler parameters and back, and the rate maps that turn an angular velocity
//! into coordinate rates. The symbolic counterparts live in [`crate::equations`].

use nalgebra::{Matrix3, Vector3, Vector4};

pub type V3 = Vector3<f64>;
pub type M3 = Matrix3<f64>;

pub fn v3(a: [f64; 3]) -> V3 {
    V3::new(a[0], a[1], a[2])
}

pub fn arr(v: &V3) -> [f64; 3] {
    [v.x, v.y, v.z]
}

/// `A = Rz(γ)·Ry(β)·Rx(θ)` (local to global).
pub fn euler_matrix([theta, beta, gamma]: [f64; 3]) -> M3 {
    let (st, ct) = theta.sin_cos();
    let (sb, cb) = beta.sin_cos();
    let (sg, cg) = gamma.sin_cos();
    M3::new(
        cg * cb,
        cg * sb * st - sg * ct,
        cg * sb * ct + sg * st,
        sg * cb,
        sg * sb * st + cg * ct,
        sg * sb * ct - cg * st,
        -sb,
        cb * st,
        cb * ct,
    )
}

/// Euler angles `[θ, β, γ]` of a rotation matrix `Rz(γ)·Ry(β)·Rx(θ)`.
pub fn euler_angles(a: &M3) -> [f64; 3] {
    let beta = (-a[(2, 0)]).atan2((a[(0, 0)] * a[(0, 0)] + a[(1, 0)] * a[(1, 0)]).sqrt());
    let theta = a[(2, 1)].atan2(a[(2, 2)]);
    let gamma = a[(1, 0)].atan2(a[(0, 0)]);
    [theta, beta, gamma]
}

/// `A(e) = (2e0² − 1)I + 2(ēēᵀ + e0[ē×])`, the formula the generated code uses.
pub fn quaternion_matrix(e: [f64; 4]) -> M3 {
    let [e0, e1, e2, e3] = e;
    M3::new(
        2.0 * (e0 * e0 + e1 * e1) - 1.0,
        2.0 * (e1 * e2 - e0 * e3),
        2.0 * (e1 * e3 + e0 * e2),
        2.0 * (e1 * e2 + e0 * e3),
        2.0 * (e0 * e0 + e2 * e2) - 1.0,
        2.0 * (e2 * e3 - e0 * e1),
        2.0 * (e1 * e3 - e0 * e2),
        2.0 * (e2 * e3 + e0 * e1),
        2.0 * (e0 * e0 + e3 * e3) - 1.0,
    )
}

/// Unit Euler parameters (scalar first, e0 ≥ 0) of a rotation matrix.
pub fn matrix_quaternion(a: &M3) -> [f64; 4] {
    let r = nalgebra::Rotation3::from_matrix_unchecked(*a);
    let q = nalgebra::UnitQuaternion::from_rotation_matrix(&r);
    let s = if q.w < 0.0 { -1.0 } else { 1.0 };
    [s * q.w, s * q.i, s * q.j, s * q.k]
}

/// `H(β, γ)` in `ω_global = H·(θ̇, β̇, γ̇)`.
pub fn euler_rate_matrix([_, beta, gamma]: [f64; 3]) -> M3 {
    let (sb, cb) = beta.sin_cos();
    let (sg, cg) = gamma.sin_cos();
    M3::new(cg * cb, -sg, 0.0, sg * cb, cg, 0.0, -sb, 0.0, 1.0)
}

/// Euler parameter rates `ė = ½ Eᵀ ω` of a global angular velocity.
pub fn quaternion_rates(e: [f64; 4], w: &V3) -> [f64; 4] {
    let [e0, e1, e2, e3] = e;
    let d = Vector4::new(
        -e1 * w.x - e2 * w.y - e3 * w.z,
        e0 * w.x + e3 * w.y - e2 * w.z,
        -e3 * w.x + e0 * w.y + e1 * w.z,
        e2 * w.x - e1 * w.y + e0 * w.z,
    ) * 0.5;
    [d[0], d[1], d[2], d[3]]
}

/// A unit vector perpendicular to the unit vector `z`, chosen deterministically: the
/// coordinate axis least aligned with `z`, made perpendicular.
pub fn perpendicular(z: &V3) -> V3 {
    let k = (0..3)
        .min_by(|&a, &b| z[a].abs().total_cmp(&z[b].abs()))
        .unwrap_or(0);
    let mut e = V3::zeros();
    e[k] = 1.0;
    (e - z * z.dot(&e)).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn euler_round_trip() {
        for a in [[0.3, -0.7, 1.2], [-1.0, 1.1, -2.5], [0.0, 0.0, 0.0]] {
            let e = euler_angles(&euler_matrix(a));
            assert!(
                (0..3).all(|k| (e[k] - a[k]).abs() < 1e-12),
                "{e:?} vs {a:?}"
            );
        }
    }

    #[test]
    fn quaternion_matches_euler() {
        let a = euler_matrix([0.3, -0.7, 1.2]);
        let e = matrix_quaternion(&a);
        assert!((quaternion_matrix(e) - a).norm() < 1e-14);
    }

    #[test]
    fn rates_reproduce_the_angular_velocity() {
        // ω from finite differences of A along the rates: skew(ω) = Ȧ Aᵀ.
        let w = V3::new(0.3, -1.1, 0.7);
        let ang = [0.4, 0.5, -0.9];
        let rates = euler_rate_matrix(ang).try_inverse().unwrap() * w;
        let e = matrix_quaternion(&euler_matrix(ang));
        let ed = quaternion_rates(e, &w);
        let h = 1e-6;
        let step_e = |s: f64| quaternion_matrix([0, 1, 2, 3].map(|k| e[k] + s * ed[k]));
        let step_a = |s: f64| euler_matrix([0, 1, 2].map(|k| ang[k] + s * rates[k]));
        for (plus, minus, a) in [
            (step_e(h), step_e(-h), quaternion_matrix(e)),
            (step_a(h), step_a(-h), euler_matrix(ang)),
        ] {
            let s = (plus - minus) / (2.0 * h) * a.transpose();
            let got = V3::new(s[(2, 1)], s[(0, 2)], s[(1, 0)]);
            assert!((got - w).norm() < 1e-8, "{got} vs {w}");
        }
    }
}
