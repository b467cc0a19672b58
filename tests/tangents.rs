//! The generated directional derivatives (`Mechanism::tangents`, decision 37) of every
//! shipped and benchmark mechanism, in every formulation, against their independent
//! reference: the fourth-order central difference of the generated Φ, Φq, Φt, γ, M and Q
//! along the same direction, the state moved by ε·(dq, dq̇) and the mechanism rebuilt at its
//! run-time values moved by ε·dp (`RunTime::build_values`), at random states and directions.
//! And the interpreter's tangents (tapes lowered from the same roots) against the compiled
//! ones.

use nalgebra::DVector;
use symbody_runtime::{Direction, Entry, Mechanism, Origin, TangentOutputs};
use symbody_testkit::common::{d1, random_state_for, Rng};

/// Random states and directions per mechanism and formulation.
const STATES: usize = 6;
/// Step of the reference stencil, in units of the direction: its truncation falls as H⁴
/// (andrews_squeezer's stiff springs: 3.3e-7 at 1e-3, 2.1e-8 at 5e-4, 5.3e-10 at 2e-4 at one
/// state; at its stiffest sampled state, forces of 1.4e4 N, 8.2e-8 at 2e-4 and 5.1e-9 at
/// 1e-4), its roundoff ≈ 1e-16/H stays below 1e-11.
const H: f64 = 1e-4;

fn entries() -> impl Iterator<Item = &'static Entry> {
    symbody_mechanisms::REGISTRY
        .iter()
        .chain(symbody_benchmark_mechanisms::REGISTRY.iter())
}

/// Φ, Φq, Φt, γ, M, Q at one state, one after the other.
fn functions(m: &dyn Mechanism, q: &[f64], qd: &[f64], t: f64) -> DVector<f64> {
    let info = m.info();
    let (n, r) = (info.n_coords, info.n_constraints);
    let mut v = Vec::new();
    let mut part = |len: usize, f: &dyn Fn(&mut [f64])| {
        let mut out = vec![0.0; len];
        f(&mut out);
        v.extend(out);
    };
    part(r, &|o| m.phi(q, t, o));
    part(info.phi_q_nnz(), &|o| m.phi_q(q, t, o));
    part(r, &|o| m.phi_t(q, t, o));
    part(r, &|o| m.gamma(q, qd, t, o));
    part(info.mass_nnz(), &|o| m.mass(q, o));
    part(n, &|o| m.force(q, qd, t, o));
    DVector::from_vec(v)
}

/// `m`'s tangents at `(q, q̇, t)` along `dir`, in the order of [`functions`].
fn tangents(m: &dyn Mechanism, q: &[f64], qd: &[f64], t: f64, dir: Direction<'_>) -> DVector<f64> {
    let info = m.info();
    let (n, r) = (info.n_coords, info.n_constraints);
    let (mut phi, mut phi_q, mut phi_t) = (vec![0.0; r], vec![0.0; info.phi_q_nnz()], vec![0.0; r]);
    let (mut gamma, mut mass, mut force) = (vec![0.0; r], vec![0.0; info.mass_nnz()], vec![0.0; n]);
    let out = TangentOutputs {
        phi: &mut phi,
        phi_q: &mut phi_q,
        phi_t: &mut phi_t,
        gamma: &mut gamma,
        mass: &mut mass,
        force: &mut force,
    };
    assert!(m.tangents(q, qd, t, dir, out), "{} has tangents", info.name);
    DVector::from_vec([phi, phi_q, phi_t, gamma, mass, force].concat())
}

/// `x + s·dx`.
fn moved(x: &[f64], s: f64, dx: &[f64]) -> Vec<f64> {
    x.iter().zip(dx).map(|(a, b)| a + s * b).collect()
}

/// Largest difference relative to the largest entry of either (1 at least: the functions'
/// entries are O(1) at these states, and a tangent of O(1e-9) is exact at 1e-9).
fn rel(a: &DVector<f64>, b: &DVector<f64>) -> f64 {
    let scale = a.amax().max(b.amax()).max(1.0);
    (a - b).amax() / scale
}

#[test]
fn tangents_match_central_differences_along_state_and_run_time_values() {
    let mut rng = Rng(0x7a9e_2b1d);
    let mut worst = (0.0f64, String::new());
    let (mut values, mut held) = (0, 0);
    for entry in entries() {
        for &(f, mech) in entry.formulations {
            let info = mech.info();
            let p = mech.run_time_values().to_vec();
            for _ in 0..STATES {
                let (q, qd, t) = random_state_for(&mut rng, info);
                let dq: Vec<f64> = q.iter().map(|_| rng.uniform(-1.0, 1.0)).collect();
                let dqd: Vec<f64> = q.iter().map(|_| rng.uniform(-1.0, 1.0)).collect();
                // Each value moved by up to its own size (at zero by up to 0.1), except one
                // that a move leaves the valid set on either side within the stencil (an
                // inertia on the rigid-body bound): it has no central difference.
                let mut dp: Vec<f64> = p
                    .iter()
                    .map(|&v| rng.uniform(-1.0, 1.0) * if v == 0.0 { 0.1 } else { v.abs() })
                    .collect();
                let valid = |dp: &[f64]| {
                    entry.run_time.is_none_or(|rt| {
                        [-2.0, 2.0]
                            .iter()
                            .all(|&s| (rt.build_values)(&moved(&p, s * H, dp)).is_ok())
                    })
                };
                for i in 0..dp.len() {
                    let mut alone = vec![0.0; dp.len()];
                    alone[i] = dp[i];
                    if !valid(&alone) {
                        dp[i] = 0.0;
                        held += 1;
                    }
                }
                assert!(valid(&dp), "{}", entry.name);
                values += dp.len();
                let at = |s: f64| -> DVector<f64> {
                    let (qs, qds) = (moved(&q, s, &dq), moved(&qd, s, &dqd));
                    match entry.run_time {
                        Some(rt) if !p.is_empty() => {
                            let built = (rt.build_values)(&moved(&p, s, &dp))
                                .unwrap_or_else(|e| panic!("{}: {e}", entry.name));
                            let m = &built.iter().find(|(g, _)| *g == f).unwrap().1;
                            functions(m.as_ref(), &qs, &qds, t)
                        }
                        _ => functions(mech, &qs, &qds, t),
                    }
                };
                let reference = d1(at, H);
                let dir = Direction {
                    dq: &dq,
                    dqd: &dqd,
                    dp: &dp,
                };
                let exact = tangents(mech, &q, &qd, t, dir);
                let err = rel(&exact, &reference);
                assert!(
                    err <= 1e-8,
                    "{} ({}): tangents off the central difference by {err:e}",
                    entry.name,
                    f.name()
                );
                if err > worst.0 {
                    worst = (err, format!("{} ({})", entry.name, f.name()));
                }
            }
        }
    }
    println!(
        "worst {:.2e} ({}); {held} of {values} run-time values held (on a bound)",
        worst.0, worst.1
    );
    assert!(100 * held <= values, "nearly every value moves");
}

#[test]
fn interpreted_tangents_are_the_compiled_ones() {
    let mut rng = Rng(0x51_7e3c);
    let mut worst = 0.0f64;
    for entry in entries() {
        let Origin::Compiled { file, .. } = entry.origin else {
            continue;
        };
        let text = std::fs::read_to_string(file).unwrap();
        let loaded =
            symbody_codegen::interpret::load_with_tangents(file, &text, &[], false).unwrap();
        for &(f, mech) in entry.formulations {
            let interpreted = loaded.entry.mechanism(f).unwrap();
            assert_eq!(interpreted.run_time_values(), mech.run_time_values());
            let (q, qd, t) = random_state_for(&mut rng, mech.info());
            let dq: Vec<f64> = q.iter().map(|_| rng.uniform(-1.0, 1.0)).collect();
            let dqd: Vec<f64> = q.iter().map(|_| rng.uniform(-1.0, 1.0)).collect();
            let dp: Vec<f64> = mech
                .run_time_values()
                .iter()
                .map(|_| rng.uniform(-1.0, 1.0))
                .collect();
            let dir = Direction {
                dq: &dq,
                dqd: &dqd,
                dp: &dp,
            };
            let a = tangents(mech, &q, &qd, t, dir);
            let b = tangents(interpreted, &q, &qd, t, dir);
            let err = rel(&a, &b);
            assert!(err <= 1e-13, "{} ({}): {err:e}", entry.name, f.name());
            worst = worst.max(err);
        }
    }
    println!("worst {worst:.2e}");
}
