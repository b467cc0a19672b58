//! The generated Stewart platform against independent references: finite differences of
//! the generated Φ, a hand-written kinetic energy (docs/paper-scenario.md's formula, nalgebra),
//! the paper's constants, and the committed file against fresh generation.

use symbody_testkit::common;

use common::{dense_mass, dense_phi_q, random_state, Rng};
use nalgebra::{DMatrix, DVector, Matrix3, Rotation3, Vector3};
use symbody_benchmark_mechanisms::stewart_6_6::{self as st, Exact, Paper};
use symbody_runtime::{KinematicOutputs, Mechanism, NewtonOutputs};

const N: usize = 78;
const M: usize = 72;

fn phi_at(q: &[f64], t: f64) -> Vec<f64> {
    let mut out = vec![0.0; M];
    st::phi(&st::K, q, t, &mut out);
    out
}

#[test]
fn sizes_pattern_and_rank() {
    let info = Exact.info();
    assert_eq!(info.n_coords, N);
    assert_eq!(info.n_constraints, M);
    assert_eq!(info.phi_q_nnz(), 390);
    assert_eq!(info.bodies.len(), 13);
    assert_eq!(info.joints.len(), 24, "18 joints and 6 drivers");
    let mut jac = vec![0.0; 390];
    st::phi_q(&st::K, info.q0, 0.0, &mut jac);
    let dense = dense_phi_q(info, &jac);
    let sv = dense.singular_values();
    let (max, min) = (sv.max(), sv.min());
    assert!(
        min > 1e-6 * max,
        "Φq(q0) is rank-deficient: σ_min {min:e}, σ_max {max:e}"
    );
    // The pattern is strictly row-major with ascending columns.
    for k in 1..390 {
        let a = (info.phi_q_rows[k - 1], info.phi_q_cols[k - 1]);
        let b = (info.phi_q_rows[k], info.phi_q_cols[k]);
        assert!(a < b, "pattern out of order at {k}");
    }
}

#[test]
fn initial_configuration_is_consistent() {
    let phi = phi_at(st::Q0.as_slice(), 0.0);
    let max = phi.iter().fold(0.0f64, |a, b| a.max(b.abs()));
    assert!(max <= 1e-12, "max |Φ(q0, 0)| = {max:e}");
    // docs/paper-scenario.md: the platform starts at Y = 0.3466575, every leg 0.400040 m long,
    // and the drivers start at c_i0 = 0.150040 m.
    assert_eq!(st::Q0[1], 0.3466575);
    let info = Exact.info();
    for leg in 1..=6 {
        let u = info.body_index(&format!("upper{leg}")).unwrap() * 6;
        let l = info.body_index(&format!("lower{leg}")).unwrap() * 6;
        let d: f64 = (0..3)
            .map(|k| (st::Q0[u + k] - st::Q0[l + k]).powi(2))
            .sum::<f64>()
            .sqrt();
        assert!((d - 0.150040).abs() < 1e-6, "leg {leg}: c0 = {d}");
        assert!((d + 0.25 - 0.400040).abs() < 1e-6);
    }
}

#[test]
fn phi_q_matches_central_differences() {
    let info = Exact.info();
    let mut rng = Rng(11);
    let mut worst = 0.0f64;
    for _ in 0..25 {
        let (q, _, t) = random_state(&mut rng, info.q0);
        let mut jac = vec![0.0; 390];
        st::phi_q(&st::K, &q, t, &mut jac);
        let dense = dense_phi_q(info, &jac);
        let h = 1e-6;
        for j in 0..N {
            let (mut qp, mut qm) = (q.clone(), q.clone());
            qp[j] += h;
            qm[j] -= h;
            let (fp, fm) = (phi_at(&qp, t), phi_at(&qm, t));
            for i in 0..M {
                let fd = (fp[i] - fm[i]) / (2.0 * h);
                worst = worst.max((fd - dense[(i, j)]).abs());
            }
        }
        // Φt likewise.
        let mut pt = vec![0.0; M];
        st::phi_t(&st::K, &q, t, &mut pt);
        let (fp, fm) = (phi_at(&q, t + h), phi_at(&q, t - h));
        for i in 0..M {
            worst = worst.max(((fp[i] - fm[i]) / (2.0 * h) - pt[i]).abs());
        }
    }
    eprintln!("max |Φq − FD|, |Φt − FD| over 25 states: {worst:e}");
    assert!(worst <= 1e-7, "max |Φq − FD| = {worst:e}");
}

#[test]
fn gamma_matches_second_difference_along_the_motion() {
    // −γ = D²Φ[(q̇,1),(q̇,1)] = d²/ds² Φ(q + s q̇, t + s) at s = 0; a fourth-order stencil
    // with h = 1e-3 has truncation ~1e-13 and rounding ~1e-10 for |Φ| ~ 1.
    let info = Exact.info();
    let mut rng = Rng(12);
    let mut worst = 0.0f64;
    for _ in 0..25 {
        let (q, qd, t) = random_state(&mut rng, info.q0);
        let mut gamma = vec![0.0; M];
        st::gamma(&st::K, &q, &qd, t, &mut gamma);
        let h = 1e-3;
        let at = |s: f64| {
            let p: Vec<f64> = q.iter().zip(&qd).map(|(a, b)| a + s * b).collect();
            phi_at(&p, t + s)
        };
        let (f2, f1, f0, fm1, fm2) = (at(2.0 * h), at(h), at(0.0), at(-h), at(-2.0 * h));
        for i in 0..M {
            let d2 =
                (-f2[i] + 16.0 * f1[i] - 30.0 * f0[i] + 16.0 * fm1[i] - fm2[i]) / (12.0 * h * h);
            worst = worst.max((d2 + gamma[i]).abs() / (1.0 + gamma[i].abs()));
        }
    }
    eprintln!("max relative |γ + Φ̈| over 25 states: {worst:e}");
    assert!(worst <= 1e-7, "max relative |γ + Φ̈| = {worst:e}");
}

/// Kinetic energy written by hand from docs/paper-scenario.md: ½m|v|² + ½ω_bᵀIω_b with
/// ω_b = Aᵀ(γ̇ e_z + β̇ Rz(γ) e_y + θ̇ Rz(γ)Ry(β) e_x).
fn kinetic_energy(q: &[f64], qd: &[f64]) -> f64 {
    let info = Exact.info();
    let mut t = 0.0;
    for b in info.bodies {
        let o = b.coord_offset;
        let (th, be, ga) = (q[o + 3], q[o + 4], q[o + 5]);
        let rz = Rotation3::from_axis_angle(&Vector3::z_axis(), ga);
        let ry = Rotation3::from_axis_angle(&Vector3::y_axis(), be);
        let rx = Rotation3::from_axis_angle(&Vector3::x_axis(), th);
        let a = rz * ry * rx;
        let w_global = Vector3::z() * qd[o + 5]
            + rz * Vector3::y() * qd[o + 4]
            + rz * ry * Vector3::x() * qd[o + 3];
        let w = a.inverse() * w_global;
        let inertia = Matrix3::from_diagonal(&Vector3::from(b.inertia));
        let v = Vector3::new(qd[o], qd[o + 1], qd[o + 2]);
        t += 0.5 * b.mass * v.norm_squared() + 0.5 * w.dot(&(inertia * w));
    }
    t
}

fn mass_dense(q: &[f64]) -> DMatrix<f64> {
    let info = Exact.info();
    let mut m = vec![0.0; info.mass_nnz()];
    Exact.mass(q, &mut m);
    dense_mass(info, &m)
}

#[test]
fn exact_mass_matrix_is_spd_and_is_the_hessian_of_kinetic_energy() {
    let info = Exact.info();
    let mut rng = Rng(13);
    let mut worst_grad = 0.0f64;
    for _ in 0..25 {
        let (q, qd, _) = random_state(&mut rng, info.q0);
        let m = mass_dense(&q);
        assert!((&m - m.transpose()).amax() <= 1e-15, "M is not symmetric");
        let eig = m.clone().symmetric_eigenvalues();
        assert!(
            eig.min() > 0.0,
            "M not positive definite: λ_min = {}",
            eig.min()
        );
        // M q̇ = ∂T/∂q̇ (T is quadratic in q̇, so central differences are exact up to rounding).
        let mqd = &m * DVector::from_column_slice(&qd);
        let h = 1e-4;
        for i in 0..N {
            let (mut p, mut mm) = (qd.clone(), qd.clone());
            p[i] += h;
            mm[i] -= h;
            let fd = (kinetic_energy(&q, &p) - kinetic_energy(&q, &mm)) / (2.0 * h);
            worst_grad = worst_grad.max((fd - mqd[i]).abs());
        }
    }
    eprintln!("max |M q̇ − ∂T/∂q̇| over 25 states: {worst_grad:e}");
    assert!(worst_grad <= 1e-9, "max |M q̇ − ∂T/∂q̇| = {worst_grad:e}");
}

#[test]
fn exact_forces_are_lagranges_velocity_terms_plus_gravity() {
    // Q = gravity + ∂T/∂q − d/ds[M(q + s q̇) q̇] at s = 0, each term by central differences.
    let info = Exact.info();
    let mut rng = Rng(14);
    let mut worst = 0.0f64;
    for _ in 0..10 {
        let (q, qd, t) = random_state(&mut rng, info.q0);
        let mut force = vec![0.0; N];
        Exact.force(&q, &qd, t, &mut force);
        let h = 1e-5;
        let qdv = DVector::from_column_slice(&qd);
        let shifted = |s: f64| {
            let p: Vec<f64> = q.iter().zip(&qd).map(|(a, b)| a + s * b).collect();
            mass_dense(&p) * &qdv
        };
        let dp = (shifted(h) - shifted(-h)) / (2.0 * h);
        for i in 0..N {
            let (mut p, mut mm) = (q.clone(), q.clone());
            p[i] += h;
            mm[i] -= h;
            let dt_dq = (kinetic_energy(&p, &qd) - kinetic_energy(&mm, &qd)) / (2.0 * h);
            let body = &info.bodies[i / 6];
            let g = if i % 6 < 3 {
                body.mass * info.gravity[i % 6]
            } else {
                0.0
            };
            worst = worst.max((g + dt_dq - dp[i] - force[i]).abs());
        }
    }
    eprintln!("max |Q − (g + ∂T/∂q − ṗ)| over 10 states: {worst:e}");
    assert!(worst <= 1e-7, "max |Q − (g + ∂T/∂q − ṗ)| = {worst:e}");
}

#[test]
fn exact_mass_matrix_degenerates_only_at_the_euler_singularity() {
    let info = Exact.info();
    let mut q = info.q0.to_vec();
    q[4] = std::f64::consts::FRAC_PI_2; // platform β = 90°
    let eig = mass_dense(&q).symmetric_eigenvalues();
    assert!(
        eig.min().abs() < 1e-12,
        "at β = 90° M must be singular, λ_min = {}",
        eig.min()
    );
}

#[test]
fn paper_formulation_is_the_papers_diagonal() {
    let info = Paper.info();
    assert!(info.mass_is_constant);
    let mut m = vec![0.0; info.mass_nnz()];
    Paper.mass(info.q0, &mut m);
    let d = dense_mass(info, &m);
    // paper Table 3 and the leg table of docs/paper-scenario.md
    let platform = [1.79, 1.79, 1.79, 0.0326, 0.065, 0.0326];
    let piston = [0.20, 0.20, 0.20, 1.046667e-3, 1.0e-5, 1.046667e-3];
    let cylinder = [0.30, 0.30, 0.30, 1.579375e-3, 3.375e-5, 1.579375e-3];
    for b in 0..13 {
        let expect = match b {
            0 => platform,
            1..=6 => piston,
            _ => cylinder,
        };
        for (k, e) in expect.iter().enumerate() {
            let i = 6 * b + k;
            assert!((d[(i, i)] - e).abs() <= 1e-9, "M[{i},{i}] = {}", d[(i, i)]);
        }
    }
    assert_eq!(d.iter().filter(|x| **x != 0.0).count(), N, "diagonal only");
    let mut f = vec![0.0; N];
    Paper.force(info.q0, &vec![0.3; N], 0.0, &mut f);
    for (i, v) in f.iter().enumerate() {
        let expect = if i % 6 == 1 {
            -9.81 * info.bodies[i / 6].mass
        } else {
            0.0
        };
        assert!((v - expect).abs() < 1e-12, "Q[{i}] = {v}");
    }
}

#[test]
fn fused_evaluations_equal_the_separate_functions() {
    let mut rng = Rng(15);
    for mech in [&Exact as &dyn Mechanism, &Paper] {
        let info = mech.info();
        let (q, qd, t) = random_state(&mut rng, info.q0);
        let (mut p1, mut j1, mut m1, mut f1) = (
            vec![0.0; M],
            vec![0.0; 390],
            vec![0.0; info.mass_nnz()],
            vec![0.0; N],
        );
        mech.eval_newton(
            &q,
            &qd,
            t,
            NewtonOutputs {
                phi: &mut p1,
                phi_q: &mut j1,
                mass: &mut m1,
                force: &mut f1,
            },
        );
        let (mut p2, mut j2, mut m2, mut f2) = (
            vec![0.0; M],
            vec![0.0; 390],
            vec![0.0; info.mass_nnz()],
            vec![0.0; N],
        );
        mech.phi(&q, t, &mut p2);
        mech.phi_q(&q, t, &mut j2);
        mech.mass(&q, &mut m2);
        mech.force(&q, &qd, t, &mut f2);
        assert_eq!((p1, j1.clone(), m1, f1), (p2, j2, m2, f2));
        let (mut p3, mut j3, mut t3, mut g3) =
            (vec![0.0; M], vec![0.0; 390], vec![0.0; M], vec![0.0; M]);
        mech.eval_kinematics(
            &q,
            &qd,
            t,
            KinematicOutputs {
                phi: &mut p3,
                phi_q: &mut j3,
                phi_t: &mut t3,
                gamma: &mut g3,
            },
        );
        let (mut t4, mut g4) = (vec![0.0; M], vec![0.0; M]);
        mech.phi_t(&q, t, &mut t4);
        mech.gamma(&q, &qd, t, &mut g4);
        assert_eq!((j3, t3, g3), (j1, t4, g4));
    }
}

#[test]
fn potential_energy_is_gravity() {
    let info = Exact.info();
    let expect: f64 = info
        .bodies
        .iter()
        .map(|b| b.mass * 9.81 * info.q0[b.coord_offset + 1])
        .sum();
    assert!((Exact.potential(info.q0) - expect).abs() < 1e-12);
}

#[test]
fn committed_code_is_fresh_and_generation_is_deterministic() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    // The committed files were written by another process: equal to this one's output, the
    // generation does not depend on hash-map seeds (random per map and process) or the run.
    let first = symbody_codegen::files::all_expected(root).unwrap_or_else(|e| panic!("{e}"));
    for (rel, contents) in &first {
        let on_disk = std::fs::read_to_string(root.join(rel)).unwrap_or_default();
        assert!(
            on_disk == *contents,
            "{} is stale: run `cargo xtask generate --all` and commit the result",
            rel.display()
        );
    }
}

#[test]
fn every_angle_has_one_sine_and_one_cosine_per_evaluation() {
    // Hash-consing makes sin(q_i) one node; emission must then compute it once per call of
    // a public function, across all of its chunk helpers.
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let src = std::fs::read_to_string(root.join("mechanisms/generated/stewart_6_6/equations.rs"))
        .unwrap();
    let mut counts: std::collections::HashMap<(String, String), usize> = Default::default();
    let (mut module, mut function) = (String::from("top"), String::new());
    // The reduced system (`pub mod reduced`, the file's last module) has its own functions
    // and formulation modules: they are counted under `reduced::`.
    let mut prefix = "";
    for line in src.lines() {
        let l = line.trim_start();
        if let Some(m) = l.strip_prefix("pub mod ") {
            let m = m.trim_end_matches(" {");
            module = if m == "reduced" {
                prefix = "reduced::";
                "reduced::top".to_string()
            } else {
                format!("{prefix}{m}")
            };
        }
        if let Some(rest) = l.strip_prefix("pub fn ").or_else(|| l.strip_prefix("fn ")) {
            let name: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            let base = name
                .split("_shared_")
                .next()
                .unwrap()
                .split("_part_")
                .next()
                .unwrap();
            function = format!("{module}::{base}");
        }
        // `trig::sin_cos(q[i])` computes both.
        for (call, computes) in [
            ("trig::sin(", &["sin"][..]),
            ("trig::cos(", &["cos"]),
            ("trig::sin_cos(", &["sin", "cos"]),
        ] {
            for (i, _) in line.match_indices(call) {
                let argument = &line[i + call.len()..];
                if !argument.starts_with("q[") {
                    continue;
                }
                let argument = &argument[..=argument.find(']').expect("an index")];
                for f in computes {
                    let call = format!("{argument}.{f}");
                    *counts.entry((function.clone(), call)).or_default() += 1;
                }
            }
        }
    }
    assert!(counts.keys().any(|(f, _)| f == "exact::eval_newton"));
    for ((function, call), n) in &counts {
        assert_eq!(*n, 1, "{function} computes {call} {n} times");
    }
    // Φ alone needs all 39 angles' sine and cosine: 78 calls; the reduced Φ, whose leg parts
    // share their angles, 21 angles: 42.
    assert_eq!(counts.keys().filter(|(f, _)| f == "top::phi").count(), 78);
    assert_eq!(
        counts
            .keys()
            .filter(|(f, _)| f == "reduced::top::phi")
            .count(),
        42
    );
}
