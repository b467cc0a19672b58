//! Times the KKT solvers on a pattern shaped like the 6-6 Stewart platform (13 bodies,
//! 72 rows): `cargo run --release -p symbody-runtime --example kkt_timing`.
use std::time::Instant;
use symbody_runtime::{DenseKkt, KktPattern, KktSolver, SchurKkt};

fn main() {
    let body = |b: usize| (6 * b..6 * b + 6).collect::<Vec<_>>();
    // Bodies: 0 platform, 1..=6 upper legs, 7..=12 lower legs.
    let mut rows: Vec<Vec<usize>> = Vec::new();
    for i in 0..6 {
        for _ in 0..3 {
            rows.push([body(0), body(1 + i)].concat());
        }
    }
    for i in 0..6 {
        for k in 0..5 {
            let mut c = vec![6 * (1 + i) + 3 + k.min(2), 6 * (7 + i) + 3 + k.min(2)];
            if k >= 3 {
                c = [body(1 + i)[..3].to_vec(), body(7 + i)].concat();
            }
            rows.push(c);
        }
    }
    for i in 0..6 {
        for _ in 0..3 {
            rows.push(body(7 + i));
        }
    }
    for i in 0..6 {
        rows.push([body(1 + i)[..3].to_vec(), body(7 + i)].concat());
    }
    let mut seed = 12345u64;
    let mut rnd = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % 1000) as f64 / 500.0 - 1.0
    };
    let (mut pr, mut pc, mut pv) = (vec![], vec![], vec![]);
    for (r, cols) in rows.iter().enumerate() {
        for &c in cols {
            pr.push(r as u32);
            pc.push(c as u32);
            pv.push(rnd() + if c % 6 < 3 { 1.0 } else { 0.0 });
        }
    }
    for exact in [false, true] {
        let (mut mr, mut mc, mut mv) = (vec![], vec![], vec![]);
        for b in 0..13 {
            for i in 0..6 {
                for j in 0..6 {
                    if i == j || (exact && i >= 3 && j >= 3) {
                        mr.push((6 * b + i) as u32);
                        mc.push((6 * b + j) as u32);
                        mv.push(if i == j { 1.0 } else { 0.01 });
                    }
                }
            }
        }
        let pat = KktPattern {
            n: 78,
            m: 72,
            mass_rows: mr,
            mass_cols: mc,
            phi_q_rows: pr.clone(),
            phi_q_cols: pc.clone(),
        };
        let mut s = SchurKkt::new(&pat).unwrap();
        let mut d = DenseKkt::new(&pat).unwrap();
        let f = vec![1.0; 78];
        let g = vec![0.5; 72];
        let (mut x, mut y) = (vec![0.0; 78], vec![0.0; 72]);
        let n = 20000;
        let t = Instant::now();
        for _ in 0..n {
            s.factor(&mv, 1.05, &pv).unwrap();
        }
        let tf = t.elapsed().as_secs_f64() / n as f64;
        let t = Instant::now();
        for _ in 0..n {
            s.solve(&f, &g, &mut x, &mut y).unwrap();
        }
        let ts = t.elapsed().as_secs_f64() / n as f64;
        let t = Instant::now();
        for _ in 0..200 {
            d.factor(&mv, 1.05, &pv).unwrap();
        }
        let td = t.elapsed().as_secs_f64() / 200.0;
        println!(
            "exact={exact}: Φq nnz {}, L nnz {}, blocks {}: Schur factor {:.2} µs, solve {:.2} µs; dense LU factor {:.0} µs",
            pv.len(), s.factor_nnz(), s.block_sizes().len(), tf * 1e6, ts * 1e6, td * 1e6
        );
    }
}
