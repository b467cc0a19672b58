//! The generated Stewart platform against a second, hand-written formulation of its
//! constraints (`benches/reference`, from docs/paper-scenario.md) differentiated by num-dual:
//! Φ, Φq (values and sparsity pattern) and γ must agree at random states.

use symbody_testkit::common;
use symbody_testkit::reference;

use common::Rng;
use reference::{rotation, Stewart, M, N};
use symbody_benchmark_mechanisms::stewart_6_6 as st;

const STATES: usize = 25;

/// Random states around Q0, far enough from it that no term of Φ vanishes by accident
/// (positions ±5 cm, angles ±0.6 rad, β kept away from the Euler singularity), with
/// velocities of order 1 and times over more than one period.
fn states() -> Vec<([f64; N], [f64; N], f64)> {
    let mut rng = Rng(0x5eed_57e3_a7f0);
    (0..STATES)
        .map(|_| {
            let q = std::array::from_fn(|k| {
                let x = st::Q0[k];
                match k % 6 {
                    0..=2 => x + rng.uniform(-0.05, 0.05),
                    4 => (x + rng.uniform(-0.6, 0.6)).clamp(-1.3, 1.3),
                    _ => x + rng.uniform(-0.6, 0.6),
                }
            });
            let qd = std::array::from_fn(|_| rng.uniform(-1.0, 1.0));
            (q, qd, rng.uniform(0.0, 7.0))
        })
        .collect()
}

/// The closed-form rotation of the reference is Rz(γ)·Ry(β)·Rx(θ) as a product of
/// elementary rotations: its columns are A·e_x, A·e_y, A·e_z.
#[test]
fn reference_rotation_is_zyx_product() {
    type M3 = [[f64; 3]; 3];
    let mul = |a: &M3, b: &M3| -> M3 {
        std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
    };
    let (th, be, ga) = (0.3f64, -1.1f64, 2.4f64);
    let rx = [
        [1.0, 0.0, 0.0],
        [0.0, th.cos(), -th.sin()],
        [0.0, th.sin(), th.cos()],
    ];
    let ry = [
        [be.cos(), 0.0, be.sin()],
        [0.0, 1.0, 0.0],
        [-be.sin(), 0.0, be.cos()],
    ];
    let rz = [
        [ga.cos(), -ga.sin(), 0.0],
        [ga.sin(), ga.cos(), 0.0],
        [0.0, 0.0, 1.0],
    ];
    let a = mul(&rz, &mul(&ry, &rx));
    let cols = rotation(th, be, ga);
    for (i, row) in a.iter().enumerate() {
        for (j, &v) in row.iter().enumerate() {
            assert!((cols[j][i] - v).abs() < 1e-15, "A[{i}][{j}]");
        }
    }
}

#[test]
fn reference_matches_scenario_constants() {
    let r = Stewart::new(&st::Q0);
    // Every driver starts at 0.400040 m leg length minus the two 0.125 m halves.
    for (i, c) in r.c0.iter().enumerate() {
        assert!((c - 0.150040).abs() < 1e-6, "c0[{i}] = {c}");
    }
    let mut phi = [0.0; M];
    r.phi_f64(&st::Q0, 0.0, &mut phi);
    let max = phi.iter().fold(0.0f64, |a, b| a.max(b.abs()));
    assert!(max < 1e-12, "reference |Φ(Q0, 0)| = {max:e}");
}

#[test]
fn phi_matches_generated() {
    let r = Stewart::new(&st::Q0);
    let (mut mine, mut gen) = ([0.0; M], [0.0; M]);
    let mut worst = 0.0f64;
    for (s, (q, _, t)) in states().iter().enumerate() {
        r.phi_f64(q, *t, &mut mine);
        st::phi(&st::K, q, *t, &mut gen);
        for row in 0..M {
            let e = (mine[row] - gen[row]).abs();
            worst = worst.max(e);
            assert!(
                e <= 1e-13,
                "state {s}, row {row} ({}): reference {:e}, generated {:e}",
                st::ROW_NAMES[row],
                mine[row],
                gen[row]
            );
        }
    }
    eprintln!("max |Φ_ref − Φ_gen| over {STATES} states: {worst:e}");
}

#[test]
fn phi_q_matches_generated_and_pattern() {
    let r = Stewart::new(&st::Q0);
    let mut gen = [0.0; 390];
    let (mut worst, mut worst_outside, mut exact_zero_outside) = (0.0f64, 0.0f64, true);
    // Every pattern entry must be nonzero somewhere: the pattern holds no dead entries.
    let mut ever_nonzero = [false; 390];
    for (s, (q, _, t)) in states().iter().enumerate() {
        st::phi_q(&st::K, q, *t, &mut gen);
        for (seen, v) in ever_nonzero.iter_mut().zip(&gen) {
            *seen |= *v != 0.0;
        }
        let mut dense = vec![[0.0f64; N]; M];
        let mut in_pattern = vec![[false; N]; M];
        for (k, &v) in gen.iter().enumerate() {
            let (row, col) = (st::PHI_Q_ROWS[k] as usize, st::PHI_Q_COLS[k] as usize);
            dense[row][col] = v;
            in_pattern[row][col] = true;
        }
        r.phi_q_columns(q, *t, |col, phi| {
            for row in 0..M {
                let ad = phi[row].eps;
                let e = (ad - dense[row][col]).abs();
                if in_pattern[row][col] {
                    worst = worst.max(e);
                    assert!(
                        e <= 1e-12,
                        "state {s}: ∂{}/∂{}: num-dual {ad:e}, generated {:e}",
                        st::ROW_NAMES[row],
                        st::COORD_NAMES[col],
                        dense[row][col]
                    );
                } else {
                    worst_outside = worst_outside.max(ad.abs());
                    exact_zero_outside &= ad == 0.0;
                    assert!(
                        ad.abs() <= 1e-12,
                        "state {s}: ∂{}/∂{} = {ad:e} is outside the generated pattern",
                        st::ROW_NAMES[row],
                        st::COORD_NAMES[col]
                    );
                }
            }
        });
    }
    eprintln!(
        "max |Φq_AD − Φq_gen| in pattern {worst:e}; max |Φq_AD| outside {worst_outside:e} \
         (exactly zero: {exact_zero_outside})"
    );
    assert!(
        exact_zero_outside,
        "forward AD must give exact zeros off the pattern"
    );
    for (k, seen) in ever_nonzero.iter().enumerate() {
        assert!(
            seen,
            "pattern entry {k} (∂{}/∂{}) is zero at every state",
            st::ROW_NAMES[st::PHI_Q_ROWS[k] as usize],
            st::COORD_NAMES[st::PHI_Q_COLS[k] as usize]
        );
    }
}

/// The 6-wide vector-dual Jacobian (the benchmark's block AD baseline) is the same as the
/// scalar one, bit for bit up to roundoff.
#[test]
fn block_jacobian_matches_scalar() {
    let r = Stewart::new(&st::Q0);
    for (q, _, t) in states().iter().take(3) {
        let mut scalar = vec![[0.0f64; N]; M];
        r.phi_q_columns(q, *t, |col, phi| {
            for row in 0..M {
                scalar[row][col] = phi[row].eps;
            }
        });
        r.phi_q_blocks(q, *t, |body, phi| {
            for (row, p) in phi.iter().enumerate() {
                let eps = p.eps.unwrap_generic(nalgebra::Const::<6>, nalgebra::U1);
                for k in 0..6 {
                    let col = 6 * body + k;
                    assert!(
                        (eps[k] - scalar[row][col]).abs() <= 1e-14,
                        "row {row} col {col}"
                    );
                }
            }
        });
    }
}

#[test]
fn gamma_matches_generated() {
    let r = Stewart::new(&st::Q0);
    let (mut mine, mut gen) = ([0.0; M], [0.0; M]);
    let mut worst = 0.0f64;
    for (s, (q, qd, t)) in states().iter().enumerate() {
        r.gamma(q, qd, *t, &mut mine);
        st::gamma(&st::K, q, qd, *t, &mut gen);
        // Relative to the row's scale; rows whose γ happens to be tiny are measured against
        // the largest |γ| of the state (an absolute floor at that scale).
        let scale = gen.iter().fold(0.0f64, |a, b| a.max(b.abs()));
        for row in 0..M {
            let e = (mine[row] - gen[row]).abs() / gen[row].abs().max(1e-3 * scale);
            worst = worst.max(e);
            assert!(
                e <= 1e-10,
                "state {s}, row {row} ({}): num-dual {:e}, generated {:e}",
                st::ROW_NAMES[row],
                mine[row],
                gen[row]
            );
        }
    }
    eprintln!("max relative |γ_AD − γ_gen| over {STATES} states: {worst:e}");
}
