//! The two KKT solvers against each other and against the residual of the system itself.

use super::*;

/// xorshift64*: deterministic, dependency-free randomness for test matrices.
pub(crate) struct Rng(u64);

impl Rng {
    pub(crate) fn new(seed: u64) -> Self {
        Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }
    pub(crate) fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    /// Uniform in [-1, 1).
    pub(crate) fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
    pub(crate) fn below(&mut self, k: usize) -> usize {
        (self.next_u64() % k as u64) as usize
    }
}

/// A random problem: block-diagonal SPD `M` (blocks of 1–6, as bodies), sparse full-rank `Φq`.
struct Problem {
    pattern: KktPattern,
    mass: Vec<f64>,
    phi_q: Vec<f64>,
}

/// `m` rows if given (capped below `n`), else a random count below `n`.
fn random_problem(rng: &mut Rng, n_blocks: usize, m: Option<usize>) -> Problem {
    let mut mass_rows = Vec::new();
    let mut mass_cols = Vec::new();
    let mut mass = Vec::new();
    let mut start = 0;
    let mut blocks = Vec::new();
    for _ in 0..n_blocks {
        let s = 1 + rng.below(6);
        // SPD block B Bᵀ + s·I with entries scaled like masses and inertias.
        let b: Vec<f64> = (0..s * s).map(|_| rng.uniform()).collect();
        let scale = 10f64.powf(2.0 * rng.uniform());
        for i in 0..s {
            for j in 0..s {
                let mut v: f64 = (0..s).map(|k| b[i * s + k] * b[j * s + k]).sum();
                if i == j {
                    v += s as f64;
                }
                mass_rows.push((start + i) as u32);
                mass_cols.push((start + j) as u32);
                mass.push(scale * v);
            }
        }
        blocks.push((start, s));
        start += s;
    }
    let n = start;
    let m = match m {
        Some(m) => m.min(n - 1),
        None => rng.below(n),
    };
    let mut phi_q_rows = Vec::new();
    let mut phi_q_cols = Vec::new();
    let mut phi_q = Vec::new();
    for r in 0..m {
        // A guaranteed distinct column per row keeps Φq generically of full rank.
        let mut cols = vec![r * n / m];
        for _ in 0..1 + rng.below(6) {
            cols.push(rng.below(n));
        }
        cols.sort_unstable();
        cols.dedup();
        for c in cols {
            phi_q_rows.push(r as u32);
            phi_q_cols.push(c as u32);
            phi_q.push(rng.uniform() + if c == r * n / m { 2.0 } else { 0.0 });
        }
    }
    Problem {
        pattern: KktPattern {
            n,
            m,
            mass_rows,
            mass_cols,
            phi_q_rows,
            phi_q_cols,
            redundant_rows: Vec::new(),
            normalization_rows: Vec::new(),
            mass_semidefinite: false,
            kernels: &[],
        },
        mass,
        phi_q,
    }
}

/// `‖K [x; y] − [f; g]‖∞ / (‖[f; g]‖∞ + ‖K‖·‖[x;y]‖)` evaluated straight from the nonzeros.
fn relative_residual(p: &Problem, c: f64, x: &[f64], y: &[f64], f: &[f64], g: &[f64]) -> f64 {
    let pat = &p.pattern;
    let mut r1: Vec<f64> = f.iter().map(|v| -v).collect();
    let mut r2: Vec<f64> = g.iter().map(|v| -v).collect();
    for ((&i, &j), &v) in pat.mass_rows.iter().zip(&pat.mass_cols).zip(&p.mass) {
        r1[i as usize] += c * v * x[j as usize];
    }
    for ((&i, &j), &v) in pat.phi_q_rows.iter().zip(&pat.phi_q_cols).zip(&p.phi_q) {
        r1[j as usize] += v * y[i as usize];
        r2[i as usize] += v * x[j as usize];
    }
    let inf = |v: &[f64]| v.iter().fold(0.0f64, |a, b| a.max(b.abs()));
    let num = inf(&r1).max(inf(&r2));
    let kmax = inf(&p.mass).abs() * c.abs() + inf(&p.phi_q);
    num / (inf(f).max(inf(g)) + kmax * inf(x).max(inf(y)))
}

fn solve_with<K: KktSolver>(p: &Problem, c: f64, f: &[f64], g: &[f64]) -> (Vec<f64>, Vec<f64>) {
    let mut s = K::new(&p.pattern).unwrap();
    s.factor(&p.mass, c, &p.phi_q).unwrap();
    let mut x = vec![0.0; p.pattern.n];
    let mut y = vec![0.0; p.pattern.m];
    s.solve(f, g, &mut x, &mut y).unwrap();
    (x, y)
}

#[test]
fn dense_and_schur_agree_and_solve_the_system() {
    let mut rng = Rng::new(7);
    for trial in 0..40 {
        let nb = 1 + rng.below(14);
        let p = random_problem(&mut rng, nb, None);
        let c = 0.5 + rng.uniform().abs();
        let f: Vec<f64> = (0..p.pattern.n).map(|_| rng.uniform()).collect();
        let g: Vec<f64> = (0..p.pattern.m).map(|_| rng.uniform()).collect();
        let (xd, yd) = solve_with::<DenseKkt>(&p, c, &f, &g);
        let (xs, ys) = solve_with::<SchurKkt>(&p, c, &f, &g);
        assert!(
            relative_residual(&p, c, &xd, &yd, &f, &g) < 1e-12,
            "dense, trial {trial}"
        );
        assert!(
            relative_residual(&p, c, &xs, &ys, &f, &g) < 1e-12,
            "schur, trial {trial}"
        );
        let scale = xd.iter().chain(&yd).fold(1e-300f64, |a, b| a.max(b.abs()));
        for (a, b) in xd.iter().chain(&yd).zip(xs.iter().chain(&ys)) {
            assert!((a - b).abs() <= 1e-8 * scale, "trial {trial}: {a} vs {b}");
        }
    }
}

#[test]
fn schur_detects_blocks_of_the_mass_pattern() {
    let mut rng = Rng::new(3);
    let p = random_problem(&mut rng, 5, Some(4));
    let s = SchurKkt::new(&p.pattern).unwrap();
    let sizes = s.block_sizes();
    assert_eq!(sizes.len(), 5);
    assert_eq!(sizes.iter().sum::<usize>(), p.pattern.n);
}

#[test]
fn dependent_rows_are_named() {
    let mut rng = Rng::new(11);
    let mut p = random_problem(&mut rng, 10, Some(8));
    // Make row 5 a copy of row 2: Φq loses rank, and one of the two must be named.
    let row2: Vec<(u32, f64)> = p
        .pattern
        .phi_q_rows
        .iter()
        .zip(&p.pattern.phi_q_cols)
        .zip(&p.phi_q)
        .filter(|((&r, _), _)| r == 2)
        .map(|((_, &c), &v)| (c, v))
        .collect();
    let keep: Vec<usize> = (0..p.phi_q.len())
        .filter(|&e| p.pattern.phi_q_rows[e] != 5)
        .collect();
    let mut rows: Vec<u32> = keep.iter().map(|&e| p.pattern.phi_q_rows[e]).collect();
    let mut cols: Vec<u32> = keep.iter().map(|&e| p.pattern.phi_q_cols[e]).collect();
    let mut vals: Vec<f64> = keep.iter().map(|&e| p.phi_q[e]).collect();
    for (c, v) in row2 {
        rows.push(5);
        cols.push(c);
        vals.push(v);
    }
    p.pattern.phi_q_rows = rows;
    p.pattern.phi_q_cols = cols;
    p.phi_q = vals;

    let mut s = SchurKkt::new(&p.pattern).unwrap();
    match s.factor(&p.mass, 1.0, &p.phi_q) {
        Err(KktError::RankDeficient { rows, count, .. }) => {
            assert_eq!(count, 1);
            assert!(rows[0] == 2 || rows[0] == 5, "named row {}", rows[0]);
        }
        other => panic!("expected rank deficiency, got {other:?}"),
    }
    let mut d = DenseKkt::new(&p.pattern).unwrap();
    assert!(matches!(
        d.factor(&p.mass, 1.0, &p.phi_q),
        Err(KktError::RankDeficient { .. })
    ));
    // A failed factorization must not leave a usable one behind.
    let (mut x, mut y) = (vec![0.0; p.pattern.n], vec![0.0; p.pattern.m]);
    let (f, g) = (vec![1.0; p.pattern.n], vec![1.0; p.pattern.m]);
    assert_eq!(s.solve(&f, &g, &mut x, &mut y), Err(KktError::NotFactored));
}

#[test]
fn indefinite_mass_and_nan_are_errors_not_panics() {
    let mut rng = Rng::new(5);
    let p = random_problem(&mut rng, 3, Some(2));
    let mut s = SchurKkt::new(&p.pattern).unwrap();
    assert!(matches!(
        s.factor(&p.mass, -1.0, &p.phi_q),
        Err(KktError::MassNotPositiveDefinite { .. })
    ));
    let mut bad = p.phi_q.clone();
    bad[0] = f64::NAN;
    assert_eq!(s.factor(&p.mass, 1.0, &bad), Err(KktError::NotFinite));
    assert!(matches!(
        s.factor(&p.mass[1..], 1.0, &p.phi_q),
        Err(KktError::Dimension { .. })
    ));
}

#[test]
fn pattern_errors_are_reported() {
    let pat = KktPattern {
        n: 2,
        m: 1,
        mass_rows: vec![0],
        mass_cols: vec![0],
        phi_q_rows: vec![0],
        phi_q_cols: vec![1],
        redundant_rows: Vec::new(),
        normalization_rows: Vec::new(),
        mass_semidefinite: false,
        kernels: &[],
    };
    assert!(matches!(
        SchurKkt::new(&pat),
        Err(Error::InvalidPattern { .. })
    ));
    let pat = KktPattern {
        phi_q_cols: vec![7],
        ..pat
    };
    assert!(matches!(
        DenseKkt::new(&pat),
        Err(Error::InvalidPattern { .. })
    ));
}

/// `p` with extra rows inserted: each `(at, combination)` puts, at final row index `at`, the
/// combination `Σ c·row_k` of original rows. Returns the problem and the map from final
/// rows to original rows (`None` for inserted ones). `at` must be ascending.
fn with_combination_rows(
    p: &Problem,
    extra: &[(usize, Vec<(usize, f64)>)],
) -> (Problem, Vec<Option<usize>>) {
    let (n, m) = (p.pattern.n, p.pattern.m);
    let mut dense = vec![vec![0.0; n]; m];
    let mut structural = vec![vec![false; n]; m];
    for ((&r, &c), &v) in p
        .pattern
        .phi_q_rows
        .iter()
        .zip(&p.pattern.phi_q_cols)
        .zip(&p.phi_q)
    {
        dense[r as usize][c as usize] = v;
        structural[r as usize][c as usize] = true;
    }
    let total = m + extra.len();
    let mut origin = Vec::with_capacity(total);
    let mut next = 0;
    for row in 0..total {
        if extra.iter().any(|(at, _)| *at == row) {
            origin.push(None);
        } else {
            origin.push(Some(next));
            next += 1;
        }
    }
    let (mut rows, mut cols, mut vals) = (Vec::new(), Vec::new(), Vec::new());
    for (row, o) in origin.iter().enumerate() {
        let (vals_row, pat_row): (Vec<f64>, Vec<bool>) = match o {
            Some(k) => (dense[*k].clone(), structural[*k].clone()),
            None => {
                let comb = &extra.iter().find(|(at, _)| *at == row).unwrap().1;
                let v = (0..n)
                    .map(|c| comb.iter().map(|&(k, a)| a * dense[k][c]).sum())
                    .collect();
                let s = (0..n)
                    .map(|c| comb.iter().any(|&(k, _)| structural[k][c]))
                    .collect();
                (v, s)
            }
        };
        for c in 0..n {
            if pat_row[c] {
                rows.push(row as u32);
                cols.push(c as u32);
                vals.push(vals_row[c]);
            }
        }
    }
    let pattern = KktPattern {
        m: total,
        phi_q_rows: rows,
        phi_q_cols: cols,
        redundant_rows: extra.iter().map(|(at, _)| *at as u32).collect(),
        normalization_rows: Vec::new(),
        mass_semidefinite: false,
        ..p.pattern.clone()
    };
    (
        Problem {
            pattern,
            mass: p.mass.clone(),
            phi_q: vals,
        },
        origin,
    )
}

#[test]
fn redundant_rows_are_solved_as_absent_with_zero_multipliers() {
    let mut rng = Rng::new(23);
    for trial in 0..10 {
        let p = random_problem(&mut rng, 8, Some(7));
        let m = p.pattern.m;
        let c = 0.7;
        let f: Vec<f64> = (0..p.pattern.n).map(|_| rng.uniform()).collect();
        let g: Vec<f64> = (0..m).map(|_| rng.uniform()).collect();
        let (x0, y0) = solve_with::<DenseKkt>(&p, c, &f, &g);
        // A duplicate of row 2 first, and a combination of rows 1 and 5 in the middle.
        let extra = vec![(0, vec![(2, 1.0)]), (4, vec![(1, 0.5), (5, -2.0)])];
        let (r, origin) = with_combination_rows(&p, &extra);
        // Consistent right-hand sides on the inserted rows (the solvers must ignore them).
        let g1: Vec<f64> = origin
            .iter()
            .enumerate()
            .map(|(row, o)| match o {
                Some(k) => g[*k],
                None => {
                    let comb = &extra.iter().find(|(at, _)| *at == row).unwrap().1;
                    comb.iter().map(|&(k, a)| a * g[k]).sum()
                }
            })
            .collect();
        let scale = x0.iter().chain(&y0).fold(1e-300f64, |a, b| a.max(b.abs()));
        let results = [
            ("dense", solve_with::<DenseKkt>(&r, c, &f, &g1)),
            ("schur", solve_with::<SchurKkt>(&r, c, &f, &g1)),
        ];
        for (name, (x, y)) in results {
            for (a, b) in x.iter().zip(&x0) {
                assert!(
                    (a - b).abs() <= 1e-10 * scale,
                    "{name} {trial}: x {a} vs {b}"
                );
            }
            for (row, o) in origin.iter().enumerate() {
                match o {
                    Some(k) => assert!(
                        (y[row] - y0[*k]).abs() <= 1e-10 * scale,
                        "{name} {trial}: y[{row}] {} vs {}",
                        y[row],
                        y0[*k]
                    ),
                    None => assert_eq!(y[row], 0.0, "{name} {trial}: dropped row {row}"),
                }
            }
            // The full system, dropped rows included, holds (their λ is one valid choice).
            assert!(
                relative_residual(&r, c, &x, &y, &f, &g1) < 1e-12,
                "{name} {trial}"
            );
        }

        // Undeclared, the same rows make Φq rank deficient, as before.
        let undeclared = Problem {
            pattern: KktPattern {
                redundant_rows: Vec::new(),
                normalization_rows: Vec::new(),
                mass_semidefinite: false,
                ..r.pattern.clone()
            },
            mass: r.mass.clone(),
            phi_q: r.phi_q.clone(),
        };
        let mut s = SchurKkt::new(&undeclared.pattern).unwrap();
        match s.factor(&undeclared.mass, c, &undeclared.phi_q) {
            Err(KktError::RankDeficient { count, .. }) => assert_eq!(count, 2, "{trial}"),
            other => panic!("schur {trial}: expected rank deficiency, got {other:?}"),
        }
        let mut d = DenseKkt::new(&undeclared.pattern).unwrap();
        assert!(matches!(
            d.factor(&undeclared.mass, c, &undeclared.phi_q),
            Err(KktError::RankDeficient { .. })
        ));
    }
}

#[test]
fn redundant_rows_must_be_in_range_and_ascending() {
    let mut rng = Rng::new(2);
    let p = random_problem(&mut rng, 3, Some(3));
    for bad in [vec![3], vec![1, 1], vec![2, 0]] {
        let pat = KktPattern {
            redundant_rows: bad.clone(),
            mass_semidefinite: false,
            ..p.pattern.clone()
        };
        assert!(
            matches!(SchurKkt::new(&pat), Err(Error::InvalidPattern { .. })),
            "{bad:?}"
        );
        assert!(matches!(
            DenseKkt::new(&pat),
            Err(Error::InvalidPattern { .. })
        ));
    }
}

#[test]
fn a_semidefinite_mass_is_solved_when_the_constraints_fix_its_null_direction() {
    // Two coordinates, M = diag(2, 0) (a spin with no inertia) and one row fixing the second
    // coordinate: [2c 0 0; 0 0 1; 0 1 0][x; y] = [f; g] is regular, with x = (f₀/2c, g),
    // y = f₁. The block inverse of M does not exist.
    let pattern = KktPattern {
        n: 2,
        m: 1,
        mass_rows: vec![0, 1],
        mass_cols: vec![0, 1],
        phi_q_rows: vec![0],
        phi_q_cols: vec![1],
        redundant_rows: Vec::new(),
        normalization_rows: Vec::new(),
        mass_semidefinite: true,
        kernels: &[],
    };
    let (mass, c, phi_q) = ([2.0, 0.0], 0.5, [1.0]);
    let (f, g) = ([3.0, -4.0], [0.25]);
    let mut s = SchurKkt::new(&pattern).unwrap();
    assert!(s.is_dense());
    s.factor(&mass, c, &phi_q).unwrap();
    let (mut x, mut y) = ([0.0; 2], [0.0; 1]);
    s.solve(&f, &g, &mut x, &mut y).unwrap();
    assert_eq!(x, [3.0, 0.25]);
    assert_eq!(y, [-4.0]);

    // Without the flag the structured path fails on the singular block, as before.
    let mut s = SchurKkt::new(&KktPattern {
        mass_semidefinite: false,
        ..pattern
    })
    .unwrap();
    assert!(!s.is_dense());
    assert!(matches!(
        s.factor(&mass, c, &phi_q),
        Err(KktError::MassNotPositiveDefinite { coord: 1 })
    ));
}
