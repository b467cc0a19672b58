//! The per-step cost of a long chain against its length: IFToMM A02's N-four-bar mechanism for
//! N = 2 … 40, each HHT step split into evaluations, KKT factorization and solves.
//!
//! `cargo run --release -p symbody-bench --bin chain_cost` cuts the shipped N = 40 file down to
//! N four-bars (the first N + 1 cranks, N couplers and their joints; nothing else changes),
//! runs each interpreted (N = 40 also compiled, spatial and planar) at A02's settings (α = 0,
//! h = 4e-4 s) from t = 0.3 s, and writes `bench-results/chain_cost.{csv,md,png}`: cost per
//! step and per body against the number of bodies (2N + 1 links).

use std::fmt::Write as _;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Instant;

use symbody_bench::{best_time, fail, NewtonBuffers};
use symbody_cli::plot::{draw_log_log, LogSeries};
use symbody_runtime::kkt::DEFAULT_PIVOT_TOLERANCE;
use symbody_runtime::{HhtBuilder, KktPattern, KktSolver, Mechanism, SchurKkt};

const LENGTHS: [usize; 7] = [2, 4, 8, 16, 24, 32, 40];
const STEP: f64 = 4e-4;
/// Away from the flat positions (the first is near t = 1.2 s), where Newton takes its usual
/// iterations.
const T_START: f64 = 0.3;
const STEPS: usize = 300;

/// The N = 40 file cut to `n` four-bars: its header, then the `[[body]]` and `[[joint]]`
/// blocks of cranks 0…n, couplers 1…n, ground joints a0…an and tip joints left/right 1…n.
fn chain_file(full: &str, n: usize) -> String {
    let keep = |name: &str| {
        let index = |prefix: &str| {
            name.strip_prefix(prefix)
                .and_then(|k| k.parse::<usize>().ok())
        };
        match (index("crank"), index("coupler"), index("a")) {
            (Some(k), _, _) | (_, _, Some(k)) => k <= n,
            (_, Some(k), _) => (1..=n).contains(&k),
            _ => index("left")
                .or_else(|| index("right"))
                .is_some_and(|k| (1..=n).contains(&k)),
        }
    };
    let first = full
        .find("[[body]]")
        .unwrap_or_else(|| fail("no [[body]] in the file"));
    let mut out = full[..first].replace(
        "name = \"n_four_bar_40\"",
        &format!("name = \"n_four_bar_{n}\""),
    );
    for block in full[first..].split("\n\n") {
        let name = block
            .lines()
            .find_map(|l| l.strip_prefix("name = \""))
            .and_then(|l| l.strip_suffix('"'))
            .unwrap_or_else(|| fail("a block without a name"));
        if keep(name) {
            out.push_str(block.trim_end());
            out.push_str("\n\n");
        }
    }
    out
}

struct Row {
    n: usize,
    route: &'static str,
    coords: usize,
    rows: usize,
    step: f64,
    eval: f64,
    factor: f64,
    solve: f64,
    evals: f64,
    factors: f64,
    solves: f64,
}

fn measure(n: usize, route: &'static str, mech: &'static (dyn Mechanism + Sync)) -> Row {
    let mut it = HhtBuilder::new()
        .alpha(0.0)
        .step(STEP)
        .drop_dependent_rows(DEFAULT_PIVOT_TOLERANCE)
        .build(mech)
        .unwrap_or_else(|e| fail(&format!("N = {n}: {e}")));
    it.advance_to(T_START)
        .unwrap_or_else(|e| fail(&format!("N = {n}: {e}")));
    let before = it.stats();
    let mut best = f64::INFINITY;
    for _ in 0..3 {
        let t0 = Instant::now();
        for _ in 0..STEPS / 3 {
            it.step().unwrap_or_else(|e| fail(&format!("N = {n}: {e}")));
        }
        best = best.min(t0.elapsed().as_secs_f64() / (STEPS / 3) as f64);
    }
    let after = it.stats();
    let per_step = |a: usize, b: usize| (a - b) as f64 / (after.steps - before.steps) as f64;

    let info = mech.info();
    let (q, qd, t) = (it.q().to_vec(), it.qd().to_vec(), it.t());
    let mut b = NewtonBuffers::new(info);
    let reps = (20_000 / info.n_coords).max(10);
    let eval = best_time(5, reps, || b.eval(mech, &q, &qd, t));
    let mut kkt = SchurKkt::new(&KktPattern::from_info(info))
        .unwrap_or_else(|e| fail(&format!("N = {n}: {e}")));
    kkt.drop_dependent_rows(DEFAULT_PIVOT_TOLERANCE);
    let factor = best_time(5, reps, || {
        kkt.factor(black_box(&b.mass), 1.0, black_box(&b.phi_q))
            .unwrap_or_else(|e| fail(&format!("N = {n}: {e:?}")))
    });
    let f: Vec<f64> = b.force.iter().map(|v| -v).collect();
    let (mut x, mut y) = (vec![0.0; info.n_coords], vec![0.0; info.n_constraints]);
    let solve = best_time(5, reps, || {
        kkt.solve(black_box(&f), black_box(&b.phi), &mut x, &mut y)
            .unwrap_or_else(|e| fail(&format!("N = {n}: {e:?}")))
    });
    Row {
        n,
        route,
        coords: info.n_coords,
        rows: info.n_constraints,
        step: best,
        eval,
        factor,
        solve,
        evals: per_step(after.evaluations, before.evaluations),
        factors: per_step(after.factorizations, before.factorizations),
        solves: per_step(after.newton_iterations, before.newton_iterations),
    }
}

fn main() {
    let root = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    let full = std::fs::read_to_string(root.join("mechanisms/benchmarks/n_four_bar_40.toml"))
        .unwrap_or_else(|e| fail(&format!("cannot read n_four_bar_40.toml: {e}")));
    let files = std::env::temp_dir().join(format!("symbody-chain-{}", std::process::id()));
    std::fs::create_dir_all(&files).unwrap_or_else(|e| fail(&e.to_string()));
    let mut rows = Vec::new();
    for n in LENGTHS {
        let path = files.join(format!("n_four_bar_{n}.toml"));
        std::fs::write(&path, chain_file(&full, n)).unwrap_or_else(|e| fail(&e.to_string()));
        let loaded = symbody::files::load(&path).unwrap_or_else(|e| fail(&e.to_string()));
        let interpreted = measure(n, "interpreted", loaded.entry.default_mechanism());
        // The file the others are cut from, compiled: its spatial and its planar model.
        if let Some(entry) = symbody_bench::REGISTRY
            .find("n_four_bar_40")
            .filter(|_| n == 40)
        {
            let compiled = measure(n, "compiled", entry.default_mechanism());
            if let Some((planar, _)) = entry.reduced(entry.formulations[0].0) {
                rows.push(measure(n, "planar", planar));
            }
            // The cut file is the shipped one: same sizes as the compiled code of its file.
            if (compiled.coords, compiled.rows) != (interpreted.coords, interpreted.rows) {
                fail(&format!(
                    "N = {n}: the cut file differs from the shipped one"
                ));
            }
            rows.push(compiled);
        }
        rows.push(interpreted);
    }
    let _ = std::fs::remove_dir_all(&files);

    let us = 1e6;
    let mut csv = String::from(
        "n,route,bodies,coordinates,rows,step_us,step_per_body_us,eval_newton_us,factor_us,solve_us,evaluations_per_step,factorizations_per_step,solves_per_step\n",
    );
    let mut md = String::from(
        "| N | bodies | coordinates × rows | route | step (µs) | per body (µs) | `eval_newton` (µs) × per step | factor (µs) × per step | solve (µs) × per step |\n|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in &rows {
        let bodies = 2 * r.n + 1;
        let _ = writeln!(
            csv,
            "{},{},{bodies},{},{},{:.3},{:.4},{:.3},{:.3},{:.3},{:.3},{:.3},{:.3}",
            r.n,
            r.route,
            r.coords,
            r.rows,
            r.step * us,
            r.step * us / bodies as f64,
            r.eval * us,
            r.factor * us,
            r.solve * us,
            r.evals,
            r.factors,
            r.solves
        );
        let _ = writeln!(
            md,
            "| {} | {bodies} | {} × {} | {} | {:.1} | {:.2} | {:.2} × {:.2} | {:.1} × {:.2} | {:.1} × {:.2} |",
            r.n,
            r.coords,
            r.rows,
            r.route,
            r.step * us,
            r.step * us / bodies as f64,
            r.eval * us,
            r.evals,
            r.factor * us,
            r.factors,
            r.solve * us,
            r.solves
        );
    }
    let series = |name: &str, route: &str, secondary: bool, f: fn(&Row) -> f64| LogSeries {
        name: name.to_string(),
        points: rows
            .iter()
            .filter(|r| r.route == route)
            .map(|r| ((2 * r.n + 1) as f64, f(r) * us))
            .collect(),
        secondary,
    };
    let dir = root.join("bench-results");
    let write = |name: &str, text: &str| {
        std::fs::write(dir.join(name), text)
            .unwrap_or_else(|e| fail(&format!("cannot write {name}: {e}")))
    };
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| fail(&e.to_string()));
    write("chain_cost.csv", &csv);
    write("chain_cost.md", &md);
    draw_log_log(
        &dir.join("chain_cost.png"),
        "IFToMM A02 N-four-bar: cost per HHT step against chain length",
        "bodies (2N + 1 links)",
        "µs",
        &[
            series("whole step (interpreted)", "interpreted", false, |r| r.step),
            series("whole step (compiled)", "compiled", true, |r| r.step),
            series("whole step (planar model, compiled)", "planar", true, |r| {
                r.step
            }),
            series("KKT factor", "interpreted", false, |r| r.factor),
            series("KKT solve", "interpreted", false, |r| r.solve),
            series("eval_newton (interpreted)", "interpreted", false, |r| {
                r.eval
            }),
            series("eval_newton (compiled)", "compiled", true, |r| r.eval),
        ],
    )
    .unwrap_or_else(|e| fail(&e));
    print!("{md}");
}
