//! Body poses from the coordinates, for either rotation parametrization: the rotation
//! matrix, a unit quaternion for output, the angular-velocity Jacobian and world points,
//! with exactly the conventions the generator emits equations with.
//!
//! - Euler body `[θ, β, γ]`: `A = Rz(γ)·Ry(β)·Rx(θ)` (local → global), global
//!   `ω = H(β, γ)·(θ̇, β̇, γ̇)` with `H` columns `[cγcβ, sγcβ, −sβ]`, `[−sγ, cγ, 0]`,
//!   `[0, 0, 1]`.
//! - Quaternion body `e = (e0, e1, e2, e3)`: `A(e) = (2e0² − 1)I + 2(ēēᵀ + e0[ē×])`, not
//!   normalized inside (as in the generated equations; the body's normalization row keeps
//!   `|e| = 1`), and global `ω = 2E(e)ė` with
//!   `E = [[−e1, e0, −e3, e2], [−e2, e3, e0, −e1], [−e3, −e2, e1, e0]]`.

use nalgebra::{Matrix3, Matrix3x4, Quaternion, UnitQuaternion, Vector3};

use crate::error::Error;
use crate::mechanism::{BodyInfo, Rotation};

/// The body's coordinates `[X, Y, Z, rotation…]` in `q`, or an error if they lie outside.
fn coords<'a>(body: &BodyInfo, q: &'a [f64]) -> Result<&'a [f64], Error> {
    q.get(body.coord_offset..body.coord_offset + body.n_coords())
        .ok_or(Error::InvalidIndex {
            what: "body coordinate",
            index: body.coord_offset,
            reason: "the body's coordinates lie outside q",
        })
}

/// `[v×]`, the cross-product matrix.
fn skew(v: &Vector3<f64>) -> Matrix3<f64> {
    v.cross_matrix()
}

/// `E(e)` of the quaternion convention: global `ω = 2E(e)ė`.
fn e_matrix(e: &[f64]) -> Matrix3x4<f64> {
    Matrix3x4::new(
        -e[1], e[0], -e[3], e[2], //
        -e[2], e[3], e[0], -e[1], //
        -e[3], -e[2], e[1], e[0],
    )
}

/// Rotation matrix `A` (local → global) of the body at `q`; for a quaternion body the
/// generator's formula, which is a rotation only for a unit quaternion.
pub fn rotation_matrix(body: &BodyInfo, q: &[f64]) -> Result<Matrix3<f64>, Error> {
    let c = coords(body, q)?;
    Ok(match body.rotation {
        Rotation::Euler => {
            let (st, ct) = c[3].sin_cos();
            let (sb, cb) = c[4].sin_cos();
            let (sg, cg) = c[5].sin_cos();
            let rz = Matrix3::new(cg, -sg, 0.0, sg, cg, 0.0, 0.0, 0.0, 1.0);
            let ry = Matrix3::new(cb, 0.0, sb, 0.0, 1.0, 0.0, -sb, 0.0, cb);
            let rx = Matrix3::new(1.0, 0.0, 0.0, 0.0, ct, -st, 0.0, st, ct);
            rz * ry * rx
        }
        Rotation::Quaternion => {
            let e0 = c[3];
            let ev = Vector3::new(c[4], c[5], c[6]);
            Matrix3::identity() * (2.0 * e0 * e0 - 1.0)
                + 2.0 * (ev * ev.transpose() + skew(&ev) * e0)
        }
    })
}

/// Centre of mass `[X, Y, Z]` and orientation as a unit quaternion `[w, x, y, z]` with
/// `w ≥ 0`, from either parametrization (quaternion coordinates are normalized here).
///
/// A quaternion of zero or non-finite length is an [`Error::NotFinite`] (with time NaN:
/// the pose functions do not know the time).
pub fn body_pose(body: &BodyInfo, q: &[f64]) -> Result<([f64; 3], [f64; 4]), Error> {
    let c = coords(body, q)?;
    let quat = match body.rotation {
        Rotation::Euler => {
            UnitQuaternion::from_axis_angle(&Vector3::z_axis(), c[5])
                * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), c[4])
                * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), c[3])
        }
        Rotation::Quaternion => {
            let raw = Quaternion::new(c[3], c[4], c[5], c[6]);
            let norm = raw.norm();
            if !(norm > 0.0 && norm.is_finite()) {
                return Err(Error::NotFinite {
                    time: f64::NAN,
                    what: "body quaternion (zero or non-finite length)",
                });
            }
            UnitQuaternion::new_unchecked(raw / norm)
        }
    };
    let sign = if quat.w < 0.0 { -1.0 } else { 1.0 };
    Ok((
        [c[0], c[1], c[2]],
        [sign * quat.w, sign * quat.i, sign * quat.j, sign * quat.k],
    ))
}

/// `J` in the global angular velocity `ω = J·q̇_rot`, `q̇_rot` the body's rotation
/// velocities: `[H | 0]` for Euler angles (the fourth column unused), `2E(e)` for a
/// quaternion.
pub fn angular_velocity_jacobian(body: &BodyInfo, q: &[f64]) -> Result<Matrix3x4<f64>, Error> {
    let c = coords(body, q)?;
    Ok(match body.rotation {
        Rotation::Euler => {
            let (sb, cb) = c[4].sin_cos();
            let (sg, cg) = c[5].sin_cos();
            Matrix3x4::new(
                cg * cb,
                -sg,
                0.0,
                0.0, //
                sg * cb,
                cg,
                0.0,
                0.0, //
                -sb,
                0.0,
                1.0,
                0.0,
            )
        }
        Rotation::Quaternion => 2.0 * e_matrix(&c[3..7]),
    })
}

/// Global angular velocity of the body at `(q, q̇)`.
pub fn angular_velocity(body: &BodyInfo, q: &[f64], qd: &[f64]) -> Result<Vector3<f64>, Error> {
    let j = angular_velocity_jacobian(body, q)?;
    let v = coords(body, qd)?;
    let k = body.rotation.n_coords();
    Ok(j.columns(0, k) * nalgebra::DVectorView::from_slice(&v[3..3 + k], k))
}

/// Global angular acceleration of the body at `(q, q̇, q̈)`: `J·q̈_rot + J̇·q̇_rot`. For a
/// quaternion `J̇·ė = 2E(ė)ė` vanishes identically; for Euler angles `J̇` follows from `H`'s
/// dependence on β and γ.
pub fn angular_acceleration(
    body: &BodyInfo,
    q: &[f64],
    qd: &[f64],
    qdd: &[f64],
) -> Result<Vector3<f64>, Error> {
    let along = angular_velocity(body, q, qdd)?;
    Ok(match body.rotation {
        Rotation::Quaternion => along,
        Rotation::Euler => {
            let (c, v) = (coords(body, q)?, coords(body, qd)?);
            let (sb, cb) = c[4].sin_cos();
            let (sg, cg) = c[5].sin_cos();
            let (rate_x, rate_b, rate_g) = (v[3], v[4], v[5]);
            along
                + Vector3::new(
                    (-cg * sb * rate_b - sg * cb * rate_g) * rate_x - cg * rate_g * rate_b,
                    (-sg * sb * rate_b + cg * cb * rate_g) * rate_x - sg * rate_g * rate_b,
                    -cb * rate_b * rate_x,
                )
        }
    })
}

/// Global position of a point: `r + A·local` on `body`, or `local` itself on the ground
/// (`None`).
pub fn point_world(
    body: Option<&BodyInfo>,
    q: &[f64],
    local: &[f64; 3],
) -> Result<Vector3<f64>, Error> {
    let s = Vector3::from(*local);
    match body {
        None => Ok(s),
        Some(b) => {
            let c = coords(b, q)?;
            Ok(Vector3::new(c[0], c[1], c[2]) + rotation_matrix(b, q)? * s)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kkt::tests::Rng;
    use crate::testmodels;

    fn body(rotation: Rotation, coord_offset: usize) -> BodyInfo {
        BodyInfo {
            name: "b",
            coord_offset,
            rotation,
            mass: 1.0,
            inertia: [1.0; 3],
        }
    }

    /// A random state of `body` in a `q` with two leading unrelated coordinates: unit
    /// quaternions, and for them a tangent velocity (`eᵀė = 0`, as the normalization
    /// row's velocity equation demands).
    fn random_state(rng: &mut Rng, b: &BodyInfo) -> (Vec<f64>, Vec<f64>) {
        let n = b.coord_offset + b.n_coords();
        let mut q: Vec<f64> = (0..n).map(|_| 2.0 * rng.uniform()).collect();
        let mut qd: Vec<f64> = (0..n).map(|_| 2.0 * rng.uniform()).collect();
        if b.rotation == Rotation::Quaternion {
            let e = &mut q[b.coord_offset + 3..];
            let norm = e.iter().map(|x| x * x).sum::<f64>().sqrt();
            e.iter_mut().for_each(|x| *x /= norm);
            let e = e.to_vec();
            let ed = &mut qd[b.coord_offset + 3..];
            let along: f64 = e.iter().zip(ed.iter()).map(|(a, b)| a * b).sum();
            ed.iter_mut().zip(&e).for_each(|(d, a)| *d -= along * a);
        }
        (q, qd)
    }

    #[test]
    fn angular_velocity_is_the_rotation_rate_by_finite_differences() {
        // skew(ω) = Ȧ Aᵀ, with Ȧ by central differences along q̇.
        let mut rng = Rng::new(17);
        for rotation in [Rotation::Euler, Rotation::Quaternion] {
            let b = body(rotation, 2);
            for trial in 0..20 {
                let (q, qd) = random_state(&mut rng, &b);
                let h = 1e-6;
                let at = |s: f64| {
                    let qs: Vec<f64> = q.iter().zip(&qd).map(|(a, v)| a + s * v).collect();
                    rotation_matrix(&b, &qs).unwrap()
                };
                let adot = (at(h) - at(-h)) / (2.0 * h);
                let w_fd = adot * at(0.0).transpose();
                let w = angular_velocity(&b, &q, &qd).unwrap();
                let expect = skew(&w);
                assert!(
                    (w_fd - expect).abs().max() < 1e-8 * (1.0 + w.norm()),
                    "{rotation:?} trial {trial}: {w_fd} vs {expect}"
                );
                // J has the same meaning column by column (ω is linear in q̇).
                let j = angular_velocity_jacobian(&b, &q).unwrap();
                let k = rotation.n_coords();
                let mut w2 = Vector3::zeros();
                for c in 0..k {
                    w2 += j.column(c) * qd[b.coord_offset + 3 + c];
                }
                assert!((w2 - w).norm() < 1e-14 * (1.0 + w.norm()));
                if rotation == Rotation::Euler {
                    assert_eq!(j.column(3).norm(), 0.0);
                }
            }
        }
    }

    #[test]
    fn rotation_matrices_match_independent_formulas() {
        let mut rng = Rng::new(5);
        for _ in 0..20 {
            let b = body(Rotation::Euler, 0);
            let (q, _) = random_state(&mut rng, &b);
            let a = rotation_matrix(&b, &q).unwrap();
            let r = testmodels::rotation(q[3], q[4], q[5]);
            for i in 0..3 {
                for j in 0..3 {
                    assert!((a[(i, j)] - r[i][j]).abs() < 1e-15);
                }
            }
            let b = body(Rotation::Quaternion, 0);
            let (q, _) = random_state(&mut rng, &b);
            let a = rotation_matrix(&b, &q).unwrap();
            let r = UnitQuaternion::from_quaternion(Quaternion::new(q[3], q[4], q[5], q[6]))
                .to_rotation_matrix();
            assert!((a - r.matrix()).abs().max() < 1e-14, "{a} vs {r}");
        }
    }

    #[test]
    fn body_pose_reproduces_the_rotation_matrix() {
        let mut rng = Rng::new(9);
        for rotation in [Rotation::Euler, Rotation::Quaternion] {
            let b = body(rotation, 1);
            for _ in 0..20 {
                let (mut q, _) = random_state(&mut rng, &b);
                if rotation == Rotation::Quaternion {
                    // Unnormalized and with a negative scalar: normalized and sign-flipped.
                    q[4] = -q[4].abs() - 0.1;
                    q[4..8].iter_mut().for_each(|x| *x *= 3.0);
                }
                let (r, e) = body_pose(&b, &q).unwrap();
                assert_eq!(r, [q[1], q[2], q[3]]);
                assert!(e[0] >= 0.0);
                let norm = e.iter().map(|x| x * x).sum::<f64>().sqrt();
                assert!((norm - 1.0).abs() < 1e-15);
                let from_pose =
                    UnitQuaternion::from_quaternion(Quaternion::new(e[0], e[1], e[2], e[3]))
                        .to_rotation_matrix();
                let mut qn = q.clone();
                if rotation == Rotation::Quaternion {
                    let s = q[4..8].iter().map(|x| x * x).sum::<f64>().sqrt();
                    qn[4..8].iter_mut().for_each(|x| *x /= s);
                }
                let a = rotation_matrix(&b, &qn).unwrap();
                assert!((a - from_pose.matrix()).abs().max() < 1e-14);
            }
        }
    }

    #[test]
    fn world_points_and_bad_input() {
        let b = body(Rotation::Euler, 0);
        // Turned 90° about Z: local x points along global y.
        let q = [1.0, 2.0, 3.0, 0.0, 0.0, std::f64::consts::FRAC_PI_2];
        let p = point_world(Some(&b), &q, &[1.0, 0.0, 0.0]).unwrap();
        assert!((p - Vector3::new(1.0, 3.0, 3.0)).norm() < 1e-15);
        assert_eq!(
            point_world(None, &q, &[4.0, 5.0, 6.0]).unwrap(),
            Vector3::new(4.0, 5.0, 6.0)
        );
        let far = body(Rotation::Quaternion, 3);
        assert!(matches!(
            rotation_matrix(&far, &q),
            Err(Error::InvalidIndex { .. })
        ));
        assert!(body_pose(&far, &[0.0; 10]).is_err());
        assert!(angular_velocity(&b, &q, &q[..5]).is_err());
    }
}
