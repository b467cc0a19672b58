//! The tail of the HHT step time of the exact Stewart model (the paper's motion, α = −0.05,
//! h = 1 ms) over many steps: what a real-time controller has to budget for, against the
//! median, and what makes the slow steps slow.
//!
//! `cargo run --release -p symbody-bench --bin step_tail [-- --steps N]` (default 10⁶ steps,
//! about a minute) times every step on its own, with the Newton iterations and factorizations
//! it took, and, as the machine's own noise, the same number of repetitions of a fixed piece
//! of work of about a step's length (evaluations at one state: no branch depends on data).
//! Each step's thread CPU time and the context switches during it are read too. A switch
//! marks a step the guest's own scheduler interrupted; a hypervisor's pause of the virtual
//! CPU shows no switch (and partly counts as the thread's CPU time), so on a VM the slow
//! steps without one are told from the step's own work only by the fixed work's tail.
//! Prints a Markdown table and writes `bench-results/step_tail.csv`.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::Instant;

use symbody_bench::{fail, NewtonBuffers};
use symbody_benchmark_mechanisms::stewart_6_6::Exact;
use symbody_runtime::{HhtBuilder, Mechanism};

/// CPU time of the calling thread (s).
fn thread_cpu_time() -> f64 {
    let mut ts = libc::timespec {
        tv_sec: 0,
        tv_nsec: 0,
    };
    // SAFETY: writes only `ts`, which lives on this stack.
    if unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) } != 0 {
        fail("the thread's CPU time cannot be read");
    }
    ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9
}

/// The calling thread's context switches so far, voluntary and involuntary.
fn context_switches() -> i64 {
    // SAFETY: writes only `ru`, which lives on this stack (all-zero is a valid `rusage`).
    let mut ru: libc::rusage = unsafe { std::mem::zeroed() };
    if unsafe { libc::getrusage(libc::RUSAGE_THREAD, &mut ru) } != 0 {
        fail("the thread's context switches cannot be read");
    }
    ru.ru_nvcsw + ru.ru_nivcsw
}

/// The `q`-quantile of sorted `v` (nearest rank).
fn quantile(v: &[f64], q: f64) -> f64 {
    let k = ((v.len() as f64 * q).ceil() as usize).clamp(1, v.len()) - 1;
    v[k]
}

const QUANTILES: [(&str, f64); 6] = [
    ("p50", 0.5),
    ("p90", 0.9),
    ("p99", 0.99),
    ("p99.9", 0.999),
    ("p99.99", 0.9999),
    ("max", 1.0),
];

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let steps: usize = match args.as_slice() {
        [] => 1_000_000,
        [flag, n] if flag == "--steps" => n
            .parse()
            .unwrap_or_else(|_| fail("--steps needs an integer")),
        _ => fail("expected --steps N or no arguments"),
    };
    let mut it = HhtBuilder::new()
        .alpha(-0.05)
        .step(1e-3)
        .build(Exact)
        .unwrap_or_else(|e| fail(&e.to_string()));
    // Past the start-up, so that every step timed is a steady one.
    it.advance_to(1.0).unwrap_or_else(|e| fail(&e.to_string()));

    let mut times = Vec::with_capacity(steps);
    let mut cpu = Vec::with_capacity(steps);
    let mut unswitched = Vec::with_capacity(steps);
    let mut kinds = Vec::with_capacity(steps);
    for _ in 0..steps {
        let before = it.stats();
        // Nested: the CPU clock brackets the wall clock only, the switch count both.
        let switches0 = context_switches();
        let cpu0 = thread_cpu_time();
        let t0 = Instant::now();
        it.step()
            .unwrap_or_else(|e| fail(&format!("at t = {}: {e}", it.t())));
        let dt = t0.elapsed().as_secs_f64();
        let cpu1 = thread_cpu_time();
        let switches1 = context_switches();
        let after = it.stats();
        times.push(dt);
        cpu.push(cpu1 - cpu0);
        if switches1 == switches0 {
            unswitched.push(dt);
        }
        kinds.push((
            after.newton_iterations - before.newton_iterations,
            after.factorizations - before.factorizations,
        ));
    }

    // The machine's noise: a fixed amount of work of about the median step's length.
    let info = Exact.info();
    let (q, qd, t) = (it.q().to_vec(), it.qd().to_vec(), it.t());
    let mut buffers = NewtonBuffers::new(info);
    let mut eval = || buffers.eval(&Exact, &q, &qd, t);
    let mut sorted = times.clone();
    sorted.sort_by(f64::total_cmp);
    let median = quantile(&sorted, 0.5);
    let t0 = Instant::now();
    for _ in 0..1000 {
        eval();
    }
    let per_eval = t0.elapsed().as_secs_f64() / 1000.0;
    let reps = ((median / per_eval).round() as usize).max(1);
    let mut fixed = Vec::with_capacity(steps);
    for _ in 0..steps {
        let t0 = Instant::now();
        for _ in 0..reps {
            eval();
        }
        fixed.push(t0.elapsed().as_secs_f64());
    }
    fixed.sort_by(f64::total_cmp);

    // By the work a step did: how many, their median, their slowest.
    let mut by_kind: BTreeMap<(usize, usize), Vec<f64>> = BTreeMap::new();
    for (&dt, &k) in times.iter().zip(&kinds) {
        by_kind.entry(k).or_default().push(dt);
    }

    let us = |s: f64| s * 1e6;
    println!("{steps} HHT steps of the exact Stewart model (α = −0.05, h = 1 ms), each timed\n");
    println!(
        "| | {} | max / p50 |",
        QUANTILES.map(|(n, _)| n).join(" | ")
    );
    println!("|---|{}---|", "---|".repeat(QUANTILES.len()));
    let mut csv = String::from("series,count,p50,p90,p99,p99.9,p99.99,max\n");
    let mut row = |name: &str, v: &[f64]| {
        let qs = QUANTILES.map(|(_, q)| quantile(v, q));
        println!(
            "| {name} | {} | {:.1} |",
            qs.map(|x| format!("{:.1} µs", us(x))).join(" | "),
            qs[5] / qs[0]
        );
        csv.push_str(&format!(
            "{name},{},{}\n",
            v.len(),
            qs.map(|x| format!("{:.3}", us(x))).join(",")
        ));
    };
    row("HHT step", &sorted);
    let switched = steps - unswitched.len();
    unswitched.sort_by(f64::total_cmp);
    row(
        &format!("steps the thread was not switched out of ({switched} were)"),
        &unswitched,
    );
    cpu.sort_by(f64::total_cmp);
    row("HHT step, thread CPU time", &cpu);
    row(
        &format!("fixed work ({reps} eval_newton at one state)"),
        &fixed,
    );
    for ((iterations, factorizations), mut v) in by_kind {
        v.sort_by(f64::total_cmp);
        row(
            &format!("steps with {iterations} Newton iterations, {factorizations} factorizations"),
            &v,
        );
    }
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../bench-results");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| fail(&e.to_string()));
    std::fs::write(dir.join("step_tail.csv"), csv).unwrap_or_else(|e| fail(&e.to_string()));
}
