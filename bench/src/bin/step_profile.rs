//! Where one HHT step of the exact Stewart model spends its time, and the structured KKT
//! solver against dense LU on the real KKT matrix.
//!
//! `cargo run --release -p symbody-bench --bin step_profile` times, at a state of the paper's scenario
//! (t = 1 s, α = −0.05, h = 1 ms): a whole step, `eval_newton`, and factor/solve of both KKT
//! solvers; prints a Markdown table and writes `bench-results/step_profile.md`.
//! `-- --steps N` only takes N steps (for `valgrind --tool=callgrind`, which is deterministic
//! where wall clocks on a shared machine are not).

use std::fmt::Write as _;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Instant;

use symbody_bench::{best_time, fail, NewtonBuffers};
use symbody_benchmark_mechanisms::stewart_6_6::Exact;
use symbody_runtime::{DenseKkt, HhtBuilder, KktPattern, KktSolver, Mechanism, SchurKkt};

const ALPHA: f64 = -0.05;
const STEP: f64 = 1e-3;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut it = HhtBuilder::new()
        .alpha(ALPHA)
        .step(STEP)
        .build(Exact)
        .unwrap_or_else(|e| fail(&e.to_string()));
    if let [flag, n] = args.as_slice() {
        if flag != "--steps" {
            fail("expected --steps N or no arguments");
        }
        let n: usize = n
            .parse()
            .unwrap_or_else(|_| fail("--steps needs an integer"));
        for _ in 0..n {
            it.step().unwrap_or_else(|e| fail(&e.to_string()));
        }
        println!("{:?}", it.stats());
        return;
    } else if !args.is_empty() {
        fail("expected --steps N or no arguments");
    }
    it.advance_to(1.0).unwrap_or_else(|e| fail(&e.to_string()));

    // A whole step, averaged over 1 s of the scenario (1000 steps) per round; the best of
    // seven rounds, as a shared machine only ever adds time.
    let before = it.stats();
    let mut step_times = Vec::new();
    for _ in 0..7 {
        let t0 = Instant::now();
        for _ in 0..1000 {
            it.step().unwrap_or_else(|e| fail(&e.to_string()));
        }
        step_times.push(t0.elapsed().as_secs_f64() / 1000.0);
    }
    let step = step_times.iter().copied().fold(f64::INFINITY, f64::min);
    let after = it.stats();
    let steps = (after.steps - before.steps) as f64;
    let per_step = |a: usize, b: usize| (a - b) as f64 / steps;
    let evals = per_step(after.evaluations, before.evaluations);
    let factors = per_step(after.factorizations, before.factorizations);
    let solves = per_step(after.newton_iterations, before.newton_iterations);

    // The pieces, at the current state.
    let info = Exact.info();
    let (q, qd, t) = (it.q().to_vec(), it.qd().to_vec(), it.t());
    let mut b = NewtonBuffers::new(info);
    let eval = best_time(5, 20_000, || b.eval(&Exact, &q, &qd, t));
    let c = 1.0 / (1.0 + ALPHA);
    let pattern = KktPattern::from_info(info);
    let f: Vec<f64> = b.force.iter().map(|v| -v).collect();
    let g: Vec<f64> = b.phi.iter().map(|v| v * 1e3).collect();
    let (mut x, mut y) = (vec![0.0; info.n_coords], vec![0.0; info.n_constraints]);
    let mut schur = SchurKkt::new(&pattern).unwrap_or_else(|e| fail(&e.to_string()));
    let mut dense = DenseKkt::new(&pattern).unwrap_or_else(|e| fail(&e.to_string()));
    let s_factor = best_time(5, 20_000, || {
        schur
            .factor(black_box(&b.mass), c, black_box(&b.phi_q))
            .unwrap()
    });
    let s_solve = best_time(5, 20_000, || {
        schur
            .solve(black_box(&f), black_box(&g), &mut x, &mut y)
            .unwrap()
    });
    let (xs, ys) = (x.clone(), y.clone());
    // The same solver without the generated kernels: its own loops over index lists.
    let mut loops = SchurKkt::new(&KktPattern {
        kernels: &[],
        ..pattern.clone()
    })
    .unwrap_or_else(|e| fail(&e.to_string()));
    let l_factor = best_time(5, 20_000, || {
        loops
            .factor(black_box(&b.mass), c, black_box(&b.phi_q))
            .unwrap()
    });
    let l_solve = best_time(5, 20_000, || {
        loops
            .solve(black_box(&f), black_box(&g), &mut x, &mut y)
            .unwrap()
    });
    let d_factor = best_time(5, 200, || {
        dense
            .factor(black_box(&b.mass), c, black_box(&b.phi_q))
            .unwrap()
    });
    let d_solve = best_time(5, 2_000, || {
        dense
            .solve(black_box(&f), black_box(&g), &mut x, &mut y)
            .unwrap()
    });
    // nalgebra's own LU (column-oriented, partial pivoting) on the same assembled matrix, in
    // case the hand-written DenseKkt loop order is what makes dense slow.
    let size = info.n_coords + info.n_constraints;
    let mut kkt = nalgebra::DMatrix::<f64>::zeros(size, size);
    for ((&r, &cc), &v) in info.mass_rows.iter().zip(info.mass_cols).zip(&b.mass) {
        kkt[(r as usize, cc as usize)] = c * v;
    }
    for ((&r, &cc), &v) in info.phi_q_rows.iter().zip(info.phi_q_cols).zip(&b.phi_q) {
        kkt[(info.n_coords + r as usize, cc as usize)] = v;
        kkt[(cc as usize, info.n_coords + r as usize)] = v;
    }
    let na_factor = best_time(5, 200, || {
        black_box(black_box(kkt.clone()).lu());
    });
    let agree = xs
        .iter()
        .zip(&x)
        .chain(ys.iter().zip(&y))
        .map(|(a, b)| (a - b).abs() / (1.0 + b.abs()))
        .fold(0.0f64, f64::max);

    let us = 1e6;
    let in_step = evals * eval + factors * s_factor + solves * s_solve;
    let mut md = String::new();
    let _ = writeln!(
        md,
        "One HHT step of `stewart_6_6::Exact` at t = 1 s of the paper's scenario (α = {ALPHA}, \
         h = {STEP} s); best of 3–5 rounds of thousands of calls.\n"
    );
    let _ = writeln!(
        md,
        "| part | µs per call | calls per step | µs per step | share |"
    );
    let _ = writeln!(md, "|---|---|---|---|---|");
    let mut line = |name: &str, per_call: f64, calls: f64| {
        let _ = writeln!(
            md,
            "| {name} | {:.2} | {calls:.2} | {:.2} | {:.0} % |",
            per_call * us,
            per_call * calls * us,
            100.0 * per_call * calls / step
        );
    };
    line("`eval_newton` (Φ, Φq, M, Q)", eval, evals);
    line("SchurKkt factor (generated kernels)", s_factor, factors);
    line("SchurKkt solve (generated kernels)", s_solve, solves);
    line(
        "rest (predictor, residual, norms, commit)",
        step - in_step,
        1.0,
    );
    let _ = writeln!(md, "| **whole step** | | | **{:.2}** | 100 % |", step * us);
    let _ = writeln!(
        md,
        "\nKKT matrix {}×{} (78 coordinates + 72 constraints), {} nonzeros in Φq, {} in M; \
         Schur LDLᵀ factor {} off-diagonal nonzeros.\n",
        info.n_coords + info.n_constraints,
        info.n_coords + info.n_constraints,
        info.phi_q_nnz(),
        info.mass_nnz(),
        loops.factor_nnz()
    );
    let _ = writeln!(md, "| solver | factor (µs) | solve (µs) |");
    let _ = writeln!(md, "|---|---|---|");
    let _ = writeln!(
        md,
        "| SchurKkt (block Cholesky of M + sparse LDLᵀ of Φq M⁻¹ Φqᵀ), generated kernels{} | {:.2} | {:.2} |",
        if schur.runs_kernels() { "" } else { " (**not running**)" },
        s_factor * us,
        s_solve * us
    );
    let _ = writeln!(
        md,
        "| SchurKkt, its own loops (no kernels) | {:.2} | {:.2} |",
        l_factor * us,
        l_solve * us
    );
    let _ = writeln!(
        md,
        "| DenseKkt (LU with partial pivoting, nalgebra) | {:.1} | {:.2} |",
        d_factor * us,
        d_solve * us
    );
    let _ = writeln!(
        md,
        "| nalgebra `DMatrix::lu` (same matrix, includes a copy) | {:.1} | |",
        na_factor * us
    );
    let _ = writeln!(
        md,
        "| ratio DenseKkt / structured | {:.0}× | {:.0}× |",
        d_factor / s_factor,
        d_solve / s_solve
    );
    let _ = writeln!(
        md,
        "| ratio nalgebra LU / structured | {:.0}× | |",
        na_factor / s_factor
    );
    let _ = writeln!(
        md,
        "\nBoth solutions agree to {agree:.1e} (relative). Per step (1 factor + 2 solves): \
         structured {:.1} µs, dense {:.1} µs. The whole step is **1/{:.1}** of the dense \
         LU's factor and two solves.",
        (s_factor + 2.0 * s_solve) * us,
        (d_factor + 2.0 * d_solve) * us,
        (d_factor + 2.0 * d_solve) / step
    );
    print!("{md}");
    let dir = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../bench-results"));
    std::fs::create_dir_all(&dir)
        .and_then(|_| std::fs::write(dir.join("step_profile.md"), &md))
        .unwrap_or_else(|e| fail(&format!("cannot write step_profile.md: {e}")));
}
