//! Every generated mechanism in `symbody_benchmark_mechanisms::REGISTRY`, in every formulation it was
//! generated for, against independent references at random states (a new mechanism is
//! covered as soon as it is registered):
//!
//! - Φq and Φt: central differences of the generated Φ;
//! - γ: a fourth-order second difference of the generated Φ along the motion (q̇, 1);
//! - M: the Hessian ∂²T/∂q̇² of a kinetic energy written here with nalgebra rotation
//!   matrices (`kinetic_energy`), plus the design's quaternion regularization k·e eᵀ;
//! - Q: gravity plus Lagrange's velocity terms ∂T/∂q − (∂p/∂q)q̇ of that same T, plus the
//!   regularization's −k·e(ėᵀė);
//! - the sparsity patterns: row-major, columns ascending, the mass pattern symmetric.
//!
//! The tolerances are those of `tests/generated_stewart.rs`, the same for every mechanism.
//!
//! **The quaternion regularization** (docs/design.md, decision 15). A quaternion body's
//! kinetic energy ½ω'ᵀJω' with ω' = 2G(e)ė does not see ė ∥ e, so its Hessian 4GᵀJG has
//! rank 3. The generator adds k·e eᵀ to that block of M and −k·e(ėᵀė) to Q, with
//! k = 4·mean(J); under the normalization row (eᵀë = −ėᵀė) the two cancel on the motion.
//! This is a design choice, not physics, so it is added to the reference here explicitly and
//! checked on its own: M e = k e for unit e (`quaternion_regularization_has_eigenvector_e`).
//!
//! **The paper formulation** (stewart_6_6 `Paper`) is by definition the paper's constant
//! diagonal `[m, m, m, Jx, Jy, Jz]` against Euler-angle accelerations, with gravity as the
//! only force (docs/design.md, decision 7); it is checked against that definition, not
//! against T.

use symbody_testkit::common;

use common::{d1, dense, dense_mass, dense_phi_q, random_state_for, rotation, Rng};
use nalgebra::{DMatrix, Vector3};
use symbody_benchmark_mechanisms::REGISTRY;
use symbody_runtime::{BodyInfo, Formulation, Mechanism, MechanismInfo, Rotation};

/// Random states per mechanism and formulation.
const STATES: usize = 20;

/// Every registered mechanism in every formulation, with a label for messages.
fn mechanisms() -> Vec<(String, &'static (dyn Mechanism + Sync))> {
    REGISTRY
        .iter()
        .flat_map(|e| {
            e.formulations
                .iter()
                .map(move |(f, m)| (format!("{} ({})", e.name, f.name()), *m))
        })
        .collect()
}

fn phi_at(mech: &dyn Mechanism, q: &[f64], t: f64) -> Vec<f64> {
    let mut out = vec![0.0; mech.info().n_constraints];
    mech.phi(q, t, &mut out);
    out
}

fn mass_dense(mech: &dyn Mechanism, q: &[f64]) -> DMatrix<f64> {
    let info = mech.info();
    let mut m = vec![0.0; info.mass_nnz()];
    mech.mass(q, &mut m);
    dense_mass(info, &m)
}

/// Body-frame angular velocity ω' from skew(ω') = AᵀȦ, with Ȧ = dA(q + s q̇)/ds at s = 0 by
/// the fourth-order central stencil (h = 1e-3: truncation ~1e-12, rounding ~1e-13).
///
/// For a quaternion body A is the rotation of e/|e|, so ω' is the physical angular velocity
/// of the normalized attitude; it is then multiplied by |e|², which is 1 at every state the
/// tests evaluate M and Q at. The factor only matters for ∂T/∂e off the unit sphere: it
/// extends T there the way the generator does (ω' = 2G(e)ė is homogeneous of degree one in
/// e, and 2G(e)ė = |e|²·2G(ê)ê̇ with ê = e/|e|), on which Lagrange's ∂T/∂q depends.
fn omega_body(body: &BodyInfo, q: &[f64], qd: &[f64]) -> Vector3<f64> {
    let at = |s: f64| {
        let p: Vec<f64> = q.iter().zip(qd).map(|(a, b)| a + s * b).collect();
        rotation(body, &p)
    };
    let a = at(0.0);
    let w = a.transpose() * d1(at, 1e-3);
    let omega = Vector3::new(
        w[(2, 1)] - w[(1, 2)],
        w[(0, 2)] - w[(2, 0)],
        w[(1, 0)] - w[(0, 1)],
    ) * 0.5;
    match body.rotation {
        Rotation::Euler => omega,
        Rotation::Quaternion => {
            let e = &q[body.coord_offset + 3..body.coord_offset + 7];
            omega * e.iter().map(|x| x * x).sum::<f64>()
        }
    }
}

/// ½ m|ṙ|² + ½ ω'ᵀJω' of one body (J: the principal inertias of `BodyInfo`, local axes).
fn body_kinetic_energy(body: &BodyInfo, q: &[f64], qd: &[f64]) -> f64 {
    let o = body.coord_offset;
    let v = Vector3::new(qd[o], qd[o + 1], qd[o + 2]);
    let w = omega_body(body, q, qd);
    let j = Vector3::from(body.inertia);
    0.5 * body.mass * v.norm_squared() + 0.5 * w.component_mul(&w).dot(&j)
}

/// k = 4·mean(J) of a quaternion body's regularization k·e eᵀ (docs/design.md, decision 15).
fn regularization(body: &BodyInfo) -> f64 {
    4.0 * (body.inertia[0] + body.inertia[1] + body.inertia[2]) / 3.0
}

/// Gravity's potential −Σ m g·r, written from `info.gravity` and the bodies' masses.
fn gravity_potential(info: &MechanismInfo, q: &[f64]) -> f64 {
    info.bodies
        .iter()
        .map(|b| {
            -b.mass
                * (0..3)
                    .map(|k| info.gravity[k] * q[b.coord_offset + k])
                    .sum::<f64>()
        })
        .sum()
}

#[test]
fn patterns_are_row_major_ascending_and_the_mass_pattern_is_symmetric() {
    for (name, mech) in mechanisms() {
        let info = mech.info();
        let check = |what: &str, rows: &[u32], cols: &[u32], n_rows: usize, n_cols: usize| {
            assert_eq!(rows.len(), cols.len(), "{name}: {what} pattern lengths");
            for k in 0..rows.len() {
                assert!(
                    (rows[k] as usize) < n_rows && (cols[k] as usize) < n_cols,
                    "{name}: {what} entry {k} = ({}, {}) outside {n_rows}×{n_cols}",
                    rows[k],
                    cols[k]
                );
                if k > 0 {
                    assert!(
                        (rows[k - 1], cols[k - 1]) < (rows[k], cols[k]),
                        "{name}: {what} pattern not row-major ascending at entry {k}: ({}, {}) then ({}, {})",
                        rows[k - 1],
                        cols[k - 1],
                        rows[k],
                        cols[k]
                    );
                }
            }
        };
        let (nc, n) = (info.n_constraints, info.n_coords);
        check("Φq", info.phi_q_rows, info.phi_q_cols, nc, n);
        check("mass", info.mass_rows, info.mass_cols, n, n);
        let entries: std::collections::HashSet<(u32, u32)> = info
            .mass_rows
            .iter()
            .zip(info.mass_cols)
            .map(|(&r, &c)| (r, c))
            .collect();
        for &(r, c) in &entries {
            assert!(
                entries.contains(&(c, r)),
                "{name}: mass pattern has ({r}, {c}) but not ({c}, {r})"
            );
        }
        assert!(
            info.redundant_rows.windows(2).all(|w| w[0] < w[1])
                && info.redundant_rows.iter().all(|&r| (r as usize) < nc),
            "{name}: redundant rows {:?} not ascending inside 0..{nc}",
            info.redundant_rows
        );
    }
}

#[test]
fn phi_q_and_phi_t_match_central_differences() {
    let mut rng = Rng(0x0d1f_f5ea_11a1);
    for (name, mech) in mechanisms() {
        let info = mech.info();
        let (n, nc) = (info.n_coords, info.n_constraints);
        let mut worst = 0.0f64;
        for _ in 0..STATES {
            let (q, _, t) = random_state_for(&mut rng, info);
            let mut jac = vec![0.0; info.phi_q_nnz()];
            mech.phi_q(&q, t, &mut jac);
            let dense = dense_phi_q(info, &jac);
            let h = 1e-6;
            for j in 0..n {
                let (mut qp, mut qm) = (q.clone(), q.clone());
                qp[j] += h;
                qm[j] -= h;
                let (fp, fm) = (phi_at(mech, &qp, t), phi_at(mech, &qm, t));
                for i in 0..nc {
                    let fd = (fp[i] - fm[i]) / (2.0 * h);
                    worst = worst.max((fd - dense[(i, j)]).abs());
                }
            }
            let mut pt = vec![0.0; nc];
            mech.phi_t(&q, t, &mut pt);
            let (fp, fm) = (phi_at(mech, &q, t + h), phi_at(mech, &q, t - h));
            for i in 0..nc {
                worst = worst.max(((fp[i] - fm[i]) / (2.0 * h) - pt[i]).abs());
            }
        }
        eprintln!("{name}: max |Φq − FD|, |Φt − FD| over {STATES} states: {worst:e}");
        assert!(
            worst <= 1e-7,
            "{name}: max |Φq − FD|, |Φt − FD| = {worst:e}"
        );
    }
}

#[test]
fn gamma_matches_a_fourth_order_second_difference_along_the_motion() {
    // −γ = d²/ds² Φ(q + s q̇, t + s) at s = 0; h = 1e-3: truncation ~1e-13, rounding ~1e-10.
    let mut rng = Rng(0x6a33_a5ec_0bd0);
    for (name, mech) in mechanisms() {
        let info = mech.info();
        let mut worst = 0.0f64;
        for _ in 0..STATES {
            let (q, qd, t) = random_state_for(&mut rng, info);
            let mut gamma = vec![0.0; info.n_constraints];
            mech.gamma(&q, &qd, t, &mut gamma);
            let h = 1e-3;
            let at = |s: f64| {
                let p: Vec<f64> = q.iter().zip(&qd).map(|(a, b)| a + s * b).collect();
                phi_at(mech, &p, t + s)
            };
            let (f2, f1, f0, fm1, fm2) = (at(2.0 * h), at(h), at(0.0), at(-h), at(-2.0 * h));
            for i in 0..info.n_constraints {
                let d2 = (-f2[i] + 16.0 * f1[i] - 30.0 * f0[i] + 16.0 * fm1[i] - fm2[i])
                    / (12.0 * h * h);
                worst = worst.max((d2 + gamma[i]).abs() / (1.0 + gamma[i].abs()));
            }
        }
        eprintln!("{name}: max relative |γ + Φ̈| over {STATES} states: {worst:e}");
        assert!(worst <= 1e-7, "{name}: max relative |γ + Φ̈| = {worst:e}");
    }
}

/// The reference mass matrix at `q`: for `Exact`, the Hessian ∂²T/∂q̇² of
/// [`kinetic_energy`] (block diagonal, one block per body since T is a sum over bodies),
/// each block by polarization — T is quadratic in q̇, so T(eᵢ + eⱼ) − T(eᵢ) − T(eⱼ) is exact
/// up to rounding — plus k·e eᵀ on quaternion blocks; for `Paper`, the constant diagonal
/// `[m, m, m, Jx, Jy, Jz]` per body.
fn reference_mass(info: &MechanismInfo, q: &[f64]) -> DMatrix<f64> {
    let n = info.n_coords;
    let mut m = DMatrix::zeros(n, n);
    for b in info.bodies {
        let (o, nb) = (b.coord_offset, b.n_coords());
        match info.formulation {
            Formulation::Paper => {
                for k in 0..3 {
                    m[(o + k, o + k)] = b.mass;
                    m[(o + 3 + k, o + 3 + k)] = b.inertia[k];
                }
            }
            Formulation::Exact => {
                let t = |dirs: &[usize]| {
                    let mut qd = vec![0.0; n];
                    for &d in dirs {
                        qd[o + d] += 1.0;
                    }
                    body_kinetic_energy(b, q, &qd)
                };
                for i in 0..nb {
                    m[(o + i, o + i)] = 2.0 * t(&[i]);
                    for j in 0..i {
                        let h = t(&[i, j]) - t(&[i]) - t(&[j]);
                        m[(o + i, o + j)] = h;
                        m[(o + j, o + i)] = h;
                    }
                }
                if b.rotation == Rotation::Quaternion {
                    let k = regularization(b);
                    for i in 0..4 {
                        for j in 0..4 {
                            m[(o + 3 + i, o + 3 + j)] += k * q[o + 3 + i] * q[o + 3 + j];
                        }
                    }
                }
            }
        }
    }
    m
}

#[test]
fn mass_matrix_is_the_hessian_of_a_hand_written_kinetic_energy() {
    let mut rng = Rng(0x3a55_e55e_7117);
    for (name, mech) in mechanisms() {
        let info = mech.info();
        let mut worst = 0.0f64;
        for _ in 0..STATES {
            let (q, _, _) = random_state_for(&mut rng, info);
            let m = mass_dense(mech, &q);
            assert!(
                (&m - m.transpose()).amax() <= 1e-15,
                "{name}: M is not symmetric"
            );
            worst = worst.max((&m - reference_mass(info, &q)).amax());
        }
        if info.mass_is_constant {
            let (q, _, _) = random_state_for(&mut rng, info);
            assert_eq!(
                mass_dense(mech, &q),
                mass_dense(mech, info.q0),
                "{name}: mass_is_constant, but M(q) ≠ M(q0)"
            );
        }
        eprintln!("{name}: max |M − ∂²T/∂q̇² (+ k e eᵀ)| over {STATES} states: {worst:e}");
        assert!(worst <= 1e-9, "{name}: max |M − reference| = {worst:e}");
    }
}

#[test]
fn quaternion_regularization_has_eigenvector_e() {
    // 4GᵀJG e = 0 because G(e) e = 0, so at unit e the rotational block maps e to k e.
    let mut rng = Rng(0x4e9e_0001);
    let mut seen = 0;
    for (name, mech) in mechanisms() {
        let info = mech.info();
        for _ in 0..STATES {
            let (q, _, _) = random_state_for(&mut rng, info);
            let m = mass_dense(mech, &q);
            for b in info.bodies.iter() {
                if b.rotation != Rotation::Quaternion {
                    continue;
                }
                seen += 1;
                let (o, k) = (b.coord_offset + 3, regularization(b));
                for i in 0..4 {
                    let me: f64 = (0..4).map(|j| m[(o + i, o + j)] * q[o + j]).sum();
                    let err = (me - k * q[o + i]).abs();
                    assert!(
                        err <= 1e-12 * k,
                        "{name}, body {}: (M e)[{i}] = {me}, k e[{i}] = {} (k = {k})",
                        b.name,
                        k * q[o + i]
                    );
                }
            }
        }
    }
    assert!(seen > 0, "no quaternion body in the registry");
}

#[test]
fn forces_are_gravity_plus_lagranges_velocity_terms_of_the_hand_written_kinetic_energy() {
    // Exact: Q = m g + ∂T/∂q − (∂p/∂q) q̇ − k e (ėᵀė) on quaternion rows, with p = ∂T/∂q̇ by a
    // central difference in q̇ (exact for quadratic T at any step; δ = 0.5), and ∂T/∂q and
    // (∂p/∂q) q̇ = dp(q + s q̇)/ds by fourth-order stencils (h = 1e-3).
    // Paper: Q = m g (no velocity terms).
    // Applied loads other than gravity (springs, dampers, actuators, applied forces) are
    // outside this reference: where the generated potential is gravity's and power_nc
    // vanishes, the remainder must be zero row by row; otherwise only its power is checked,
    // Q_rest·q̇ = −d(V − V_gravity)/ds + power_nc (the loads themselves are tested elsewhere).
    let mut rng = Rng(0x1a9a_a9e7_0f0c);
    for (name, mech) in mechanisms() {
        let info = mech.info();
        let n = info.n_coords;
        let owner: Vec<&BodyInfo> = (0..n)
            .map(|i| {
                info.bodies
                    .iter()
                    .find(|b| (b.coord_offset..b.coord_offset + b.n_coords()).contains(&i))
                    .expect("every coordinate belongs to a body")
            })
            .collect();
        let mut worst = 0.0f64;
        for _ in 0..STATES {
            let (q, qd, t) = random_state_for(&mut rng, info);
            let mut force = vec![0.0; n];
            mech.force(&q, &qd, t, &mut force);
            // Fourth-order truncation dominates at h = 1e-3 for millimetre-sized links (Andrews'
            // squeezer: 3.4e-4 at 1e-3, 3.5e-8 at 1e-4), rounding at h = 1e-4 for stiff springs
            // (the flyball governor: 3.6e-7 at 1e-4): each state takes the better step.
            // Relative to the loads' size (forces, or their power): differences of a stiff
            // spring's 1e5 N terms round off far above an absolute 1e-7.
            let load = force.iter().fold(0.0f64, |a, f| a.max(f.abs()));
            let discrepancy = |h: f64| -> f64 {
                let shifted = |i: usize, s: f64| {
                    let mut p = q.clone();
                    p[i] += s;
                    p
                };
                // Coordinate i enters only its own body's kinetic energy, so the differences
                // take that body's term alone: the same derivative as of the whole sum, without
                // the other bodies' terms cancelling (an O(n²) reference becomes O(n); the
                // 567-coordinate chain took 50 s).
                let momentum = |q: &[f64]| -> DMatrix<f64> {
                    let delta = 0.5;
                    DMatrix::from_fn(n, 1, |i, _| {
                        let (mut up, mut down) = (qd.clone(), qd.clone());
                        up[i] += delta;
                        down[i] -= delta;
                        let b = owner[i];
                        (body_kinetic_energy(b, q, &up) - body_kinetic_energy(b, q, &down))
                            / (2.0 * delta)
                    })
                };
                let pdot = d1(
                    |s| {
                        let p: Vec<f64> = q.iter().zip(&qd).map(|(a, b)| a + s * b).collect();
                        momentum(&p)
                    },
                    h,
                );
                let mut rest = force.clone();
                for b in info.bodies {
                    let o = b.coord_offset;
                    for k in 0..3 {
                        rest[o + k] -= b.mass * info.gravity[k];
                    }
                    if info.formulation == Formulation::Paper {
                        continue;
                    }
                    for i in o..o + b.n_coords() {
                        let dt_dq = d1(|s| body_kinetic_energy(b, &shifted(i, s), &qd), h);
                        rest[i] -= dt_dq - pdot[i];
                    }
                    if b.rotation == Rotation::Quaternion {
                        let ed2: f64 = qd[o + 3..o + 7].iter().map(|x| x * x).sum();
                        for i in o + 3..o + 7 {
                            rest[i] += regularization(b) * q[i] * ed2;
                        }
                    }
                }
                let dv = mech.potential(&q) - mech.potential(info.q0);
                let dvg = gravity_potential(info, &q) - gravity_potential(info, info.q0);
                let pnc = mech.power_nc(&q, &qd, t);
                if (dv - dvg).abs() <= 1e-12 * (1.0 + dvg.abs()) && pnc == 0.0 {
                    rest.iter().fold(0.0f64, |a, r| a.max(r.abs())) / (1.0 + load)
                } else {
                    let v_rest = |s: f64| {
                        let p: Vec<f64> = q.iter().zip(&qd).map(|(a, b)| a + s * b).collect();
                        mech.potential(&p) - gravity_potential(info, &p)
                    };
                    let power: f64 = rest.iter().zip(&qd).map(|(r, v)| r * v).sum();
                    let load_power: f64 = force.iter().zip(&qd).map(|(f, v)| (f * v).abs()).sum();
                    (power + d1(v_rest, h) - pnc).abs() / (1.0 + load_power)
                }
            };
            worst = worst.max(discrepancy(1e-3).min(discrepancy(1e-4)));
        }
        eprintln!("{name}: max |Q − (m g + ∂T/∂q − ṗ − k e ėᵀė)| / (1 + |Q|) over {STATES} states: {worst:e}");
        assert!(
            worst <= 1e-7,
            "{name}: max |Q − reference| / (1 + |Q|) = {worst:e}"
        );
    }
}

/// The applied loads' Jacobians (`force_jacobian`, what HHT's Newton matrix takes) against
/// central differences of the generated Q at rest (q̇ = 0). There Q is gravity (constant) plus
/// the loads: the inertial terms and the quaternion regularization are quadratic in q̇, so
/// they and their derivatives vanish, and the differences see the loads alone. Covered:
/// every spring's, actuator's and applied load's ∂Q/∂q and every damper's ∂Q/∂q̇; a
/// damper's ∂Q/∂q at nonzero velocity is not (it vanishes at rest). Also checked: a
/// mechanism without such loads has empty patterns, and the patterns are row-major.
#[test]
fn load_jacobians_match_central_differences_at_rest() {
    let mut rng = Rng(0x0005_71ff_4e55);
    let mut with_loads = 0;
    for (name, mech) in mechanisms() {
        let info = mech.info();
        let n = info.n_coords;
        for (rows, cols) in [
            (info.force_q_rows, info.force_q_cols),
            (info.force_qd_rows, info.force_qd_cols),
        ] {
            let keys: Vec<(u32, u32)> = rows.iter().copied().zip(cols.iter().copied()).collect();
            assert!(
                keys.windows(2).all(|w| w[0] < w[1]),
                "{name}: not row-major"
            );
        }
        if info.force_q_rows.is_empty() && info.force_qd_rows.is_empty() {
            continue;
        }
        with_loads += 1;
        let mut worst = 0.0f64;
        for _ in 0..STATES {
            let (q, _, t) = random_state_for(&mut rng, info);
            let rest = vec![0.0; n];
            let mut dq = vec![0.0; info.force_q_rows.len()];
            let mut dqd = vec![0.0; info.force_qd_rows.len()];
            mech.force_jacobian(&q, &rest, t, &mut dq, &mut dqd);
            let (gq, gqd) = (
                dense((n, n), info.force_q_rows, info.force_q_cols, &dq),
                dense((n, n), info.force_qd_rows, info.force_qd_cols, &dqd),
            );
            let force = |q: &[f64], qd: &[f64]| {
                let mut f = vec![0.0; n];
                mech.force(q, qd, t, &mut f);
                f
            };
            let scale = 1.0 + gq.amax().max(gqd.amax());
            for j in 0..n {
                // Fourth-order stencils: relative to the largest entry, truncation and
                // rounding both stay near 1e-9 for the flyball's 8e5 N/m spring and for
                // Andrews' millimetre links at this step.
                let h = 1e-4;
                let shifted = |v: &[f64], s: f64| {
                    let mut p = v.to_vec();
                    p[j] += s;
                    p
                };
                let fd_q = d1(
                    |s| DMatrix::from_vec(n, 1, force(&shifted(&q, s), &rest)),
                    h,
                );
                let fd_qd = d1(
                    |s| DMatrix::from_vec(n, 1, force(&q, &shifted(&rest, s))),
                    h,
                );
                for i in 0..n {
                    worst = worst.max((fd_q[i] - gq[(i, j)]).abs() / scale);
                    worst = worst.max((fd_qd[i] - gqd[(i, j)]).abs() / scale);
                }
            }
        }
        eprintln!("{name}: max |∂Q/∂q, ∂Q/∂q̇ − FD| / (1 + max entry) at rest over {STATES} states: {worst:e}");
        assert!(worst <= 1e-7, "{name}: {worst:e}");
    }
    assert!(with_loads >= 3, "only {with_loads} mechanisms with loads");
}
