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
//! CPU shows no switch (and partly counts as the thread's CPU time). Where the kernel lets a
//! program read the processor's counters (`perf_event_open`; a VM must pass its PMU through),
//! each step's user-mode instructions and cycles are read as well: the instructions are the
//! step's work, whatever the machine does, and the cycles its time on the processor, which
//! stop while the hypervisor has the virtual CPU. Prints a Markdown table and writes
//! `bench-results/step_tail.csv`.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::Instant;

use perf_event::events::Hardware;
use perf_event::{Builder, Counter, Group};
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

/// This thread's user-mode instructions and cycles, read together.
struct Counters {
    group: Group,
    instructions: Counter,
    cycles: Counter,
}

impl Counters {
    /// `None` where the kernel refuses the counters (`perf_event_paranoid` above 2, or a VM
    /// without a virtual PMU): the run then goes on with the clocks alone.
    fn new() -> Option<Self> {
        let open = || -> std::io::Result<Self> {
            let mut group = Group::new()?;
            let instructions = group.add(&Builder::new(Hardware::INSTRUCTIONS))?;
            let cycles = group.add(&Builder::new(Hardware::CPU_CYCLES))?;
            group.enable()?;
            Ok(Counters {
                group,
                instructions,
                cycles,
            })
        };
        open()
            .map_err(|e| eprintln!("no hardware counters ({e}): the clocks alone"))
            .ok()
    }

    /// `[instructions, cycles]` so far.
    fn read(&mut self) -> [u64; 2] {
        let data = self
            .group
            .read()
            .unwrap_or_else(|e| fail(&format!("reading the hardware counters: {e}")));
        [data[&self.instructions], data[&self.cycles]]
    }
}

/// `[instructions, cycles]` counted since `start` (`None` without counters).
fn counted_since(counters: &mut Option<Counters>, start: Option<[u64; 2]>) -> Option<[f64; 2]> {
    let (c1, c0) = (counters.as_mut()?.read(), start?);
    Some([(c1[0] - c0[0]) as f64, (c1[1] - c0[1]) as f64])
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
    let mut counters = Counters::new();
    let (mut instructions, mut cycles) = (Vec::new(), Vec::new());
    for _ in 0..steps {
        let before = it.stats();
        // Nested: the CPU clock brackets the wall clock only, the counters both, the switch
        // count all three.
        let switches0 = context_switches();
        let counted0 = counters.as_mut().map(Counters::read);
        let cpu0 = thread_cpu_time();
        let t0 = Instant::now();
        it.step()
            .unwrap_or_else(|e| fail(&format!("at t = {}: {e}", it.t())));
        let dt = t0.elapsed().as_secs_f64();
        let cpu1 = thread_cpu_time();
        if let Some([i, c]) = counted_since(&mut counters, counted0) {
            instructions.push(i);
            cycles.push(c);
        }
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
    let mut fixed_cycles = Vec::with_capacity(steps);
    for _ in 0..steps {
        let counted0 = counters.as_mut().map(Counters::read);
        let t0 = Instant::now();
        for _ in 0..reps {
            eval();
        }
        fixed.push(t0.elapsed().as_secs_f64());
        if let Some([_, c]) = counted_since(&mut counters, counted0) {
            fixed_cycles.push(c);
        }
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
    // Times in µs; counts (the table says which) in thousands, and as counted in the CSV.
    let mut row_in = |name: &str, v: &[f64], time: bool| {
        let qs = QUANTILES.map(|(_, q)| quantile(v, q));
        let cell = |x: f64| match time {
            true => format!("{:.1} µs", us(x)),
            false => format!("{:.1} k", x * 1e-3),
        };
        println!(
            "| {name} | {} | {:.1} |",
            qs.map(cell).join(" | "),
            qs[5] / qs[0]
        );
        csv.push_str(&format!(
            "{name},{},{}\n",
            v.len(),
            qs.map(|x| match time {
                true => format!("{:.3}", us(x)),
                false => format!("{x:.0}"),
            })
            .join(",")
        ));
    };
    row_in("HHT step", &sorted, true);
    let switched = steps - unswitched.len();
    unswitched.sort_by(f64::total_cmp);
    row_in(
        &format!("steps the thread was not switched out of ({switched} were)"),
        &unswitched,
        true,
    );
    cpu.sort_by(f64::total_cmp);
    row_in("HHT step, thread CPU time", &cpu, true);
    row_in(
        &format!("fixed work ({reps} eval_newton at one state)"),
        &fixed,
        true,
    );
    // Whether the counters ran through the slowest step's wall time or stopped with the
    // virtual CPU.
    let slowest_note = (!instructions.is_empty()).then(|| {
        let slowest = (0..steps)
            .max_by(|&a, &b| times[a].total_cmp(&times[b]))
            .unwrap_or(0);
        format!(
            "\nThe slowest step: {:.1} µs wall, {:.1} k cycles, {:.1} k instructions.",
            us(times[slowest]),
            cycles[slowest] * 1e-3,
            instructions[slowest] * 1e-3
        )
    });
    if !instructions.is_empty() {
        for v in [&mut instructions, &mut cycles, &mut fixed_cycles] {
            v.sort_by(f64::total_cmp);
        }
        row_in("HHT step, user-mode instructions", &instructions, false);
        row_in("HHT step, user-mode cycles", &cycles, false);
        row_in("fixed work, user-mode cycles", &fixed_cycles, false);
    }
    for ((iterations, factorizations), mut v) in by_kind {
        v.sort_by(f64::total_cmp);
        row_in(
            &format!("steps with {iterations} Newton iterations, {factorizations} factorizations"),
            &v,
            true,
        );
    }
    if let Some(note) = slowest_note {
        println!("{note}");
    }
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../bench-results");
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| fail(&e.to_string()));
    std::fs::write(dir.join("step_tail.csv"), csv).unwrap_or_else(|e| fail(&e.to_string()));
}
