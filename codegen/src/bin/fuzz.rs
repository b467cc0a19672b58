//! `cargo run --release -p symbody-codegen --bin fuzz -- [--inputs N] [--seed S]
//! [--generate-every K] [--interpret-every J] [--solve-every L] [--parameters-every P]
//! [--parameter-sets S] [--dump I]`: N inputs (default 10⁶), three
//! in four mutants of the shipped mechanism files and one in four a random structured file;
//! every input goes through `load`, and one loaded mutant in K (default 1000) and one loaded
//! structured file in 20 through all of `generate`. Every loaded structured file and one
//! loaded mutant in J (default 100) also goes through the interpreter
//! ([`symbody_codegen::fuzz::interpret_one`]: every mechanism function at the file's state and
//! at perturbed ones with NaN, infinite and huge entries), one in L of those (default 1) through
//! a few HHT steps and kinematic position solves too. Every loaded structured file and one
//! loaded mutant in P (default 10; 0: none) also get S (default 4) random and degenerate
//! override sets of their parameters ([`symbody_codegen::fuzz::parameter_case`]), each
//! through `model::load_with` and, when accepted, the interpreter and the solvers. Reports
//! throughput, the runtime's typed errors by kind, the refused parameter sets by kind, any
//! panic and any finding (a solver `Ok` with a non-finite state, a non-finite mechanism
//! accepted, a bad value accepted or refused without naming it). Inputs
//! that panic or give a finding are written to `codegen/tests/fuzz_regressions/`, where
//! `cargo test` replays them.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;
use symbody_codegen::fuzz::{
    interpret_one, mutate, parameter_case, run_one, structured, Outcome, Rng,
};

/// What the interpreter share did, summed over the inputs.
#[derive(Default)]
struct Interpreted {
    inputs: usize,
    built: usize,
    formulations: usize,
    solved: usize,
    solver_runs: usize,
    steps: usize,
    position_solves: usize,
    errors: BTreeMap<String, usize>,
    findings: usize,
    panics: usize,
}

/// What the parameter share did, summed over the inputs.
#[derive(Default)]
struct Parametrized {
    inputs: usize,
    sets: usize,
    loaded: usize,
    built: usize,
    formulations: usize,
    solver_runs: usize,
    steps: usize,
    position_solves: usize,
    rejected: BTreeMap<String, usize>,
    rejected_naming: usize,
    errors: BTreeMap<String, usize>,
    findings: usize,
    panics: usize,
}

/// Resident memory of this process in MiB (Linux), to see what the leaked entries cost.
fn resident_mib() -> f64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmRSS:"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse::<f64>().ok())
        })
        .map_or(f64::NAN, |kib| kib / 1024.0)
}

fn arg(args: &[String], name: &str, default: u64) -> u64 {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .map(|v| {
            v.parse()
                .unwrap_or_else(|_| panic!("{name} needs a number, got {v}"))
        })
        .unwrap_or(default)
}

fn corpus(dir: &Path) -> Vec<(String, String)> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml") && !p.ends_with("Cargo.toml"))
        .collect();
    files.sort();
    files
        .iter()
        .map(|p| {
            let name = p.file_stem().unwrap().to_string_lossy().into_owned();
            (name, std::fs::read_to_string(p).unwrap())
        })
        .collect()
}

/// Input `i` of `seed`: its origin, its text, the generator that made it (to go on
/// drawing from) and whether it is a structured file.
fn input(seed: u64, i: usize, files: &[(String, String)]) -> (&str, String, Rng, bool) {
    let mut rng = Rng(seed.wrapping_mul(0x1000_0000_01b3) ^ i as u64);
    let is_structured = i % 4 == 3;
    if is_structured {
        let text = structured(&mut rng);
        ("structured", text, rng, true)
    } else {
        let (name, text) = &files[rng.below(files.len())];
        (name.as_str(), mutate(text, &mut rng), rng, false)
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let inputs = arg(&args, "--inputs", 1_000_000) as usize;
    let seed = arg(&args, "--seed", 1);
    let every = arg(&args, "--generate-every", 1000).max(1) as usize;
    // 0 turns the interpreter off.
    let interpret_every = arg(&args, "--interpret-every", 100) as usize;
    let solve_every = arg(&args, "--solve-every", 1).max(1) as usize;
    // 0 turns parameter fuzzing off.
    let parameters_every = arg(&args, "--parameters-every", 10) as usize;
    let parameter_sets = arg(&args, "--parameter-sets", 4) as usize;
    let parametrized = Mutex::new(Parametrized::default());
    let parameter_mutants = AtomicUsize::new(0);
    let interpreted = Mutex::new(Interpreted::default());
    let interpret_seen = AtomicUsize::new(0);
    let loaded_mutants = AtomicUsize::new(0);
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let files = corpus(&root.join("../mechanisms"));
    let out = root.join("tests/fuzz_regressions");
    // `--dump I`: print input I of the seed and stop (to look at a reported one).
    if args.iter().any(|a| a == "--dump") {
        print!(
            "{}",
            input(seed, arg(&args, "--dump", 0) as usize, &files).1
        );
        return;
    }
    // A panic is recorded as a failing input; its message would only flood the terminal.
    std::panic::set_hook(Box::new(|_| {}));
    let counts: [AtomicUsize; 4] = Default::default();
    let loaded_seen = AtomicUsize::new(0);
    let structured_seen = AtomicUsize::new(0);
    let structured_loaded = AtomicUsize::new(0);
    let next = AtomicUsize::new(0);
    let start = Instant::now();
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    std::thread::scope(|s| {
        for _ in 0..threads {
            s.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                if i >= inputs {
                    break;
                }
                let (name, mutant, mut rng, is_structured) = input(seed, i, &files);
                let mut outcome = run_one(&mutant, false);
                // Structured files are small and reach generation's checks: generate more.
                let full = if is_structured {
                    structured_seen
                        .fetch_add(1, Ordering::Relaxed)
                        .is_multiple_of(20)
                } else {
                    loaded_seen
                        .fetch_add(1, Ordering::Relaxed)
                        .is_multiple_of(every)
                };
                if outcome == Outcome::Loaded && full {
                    outcome = run_one(&mutant, true);
                }
                counts[outcome as usize].fetch_add(1, Ordering::Relaxed);
                // The interpreter: every loaded structured file, one loaded mutant in J.
                let interpret = interpret_every > 0
                    && outcome != Outcome::Rejected
                    && outcome != Outcome::Panicked
                    && (is_structured
                        || loaded_mutants
                            .fetch_add(1, Ordering::Relaxed)
                            .is_multiple_of(interpret_every));
                let mut finding = false;
                if interpret {
                    let solve = interpret_seen
                        .fetch_add(1, Ordering::Relaxed)
                        .is_multiple_of(solve_every);
                    let result = interpret_one(&mutant, &mut rng, 4, solve);
                    let mut s = interpreted.lock().unwrap();
                    s.inputs += 1;
                    match result {
                        None => {
                            s.panics += 1;
                            outcome = Outcome::Panicked;
                        }
                        Some(r) => {
                            s.built += usize::from(r.built);
                            s.formulations += r.formulations;
                            s.solved += usize::from(solve && r.built);
                            s.solver_runs += r.solver_runs;
                            s.steps += r.steps;
                            s.position_solves += r.position_solves;
                            for e in r.errors {
                                *s.errors.entry(e).or_default() += 1;
                            }
                            if !r.findings.is_empty() {
                                s.findings += 1;
                                finding = true;
                                eprintln!("finding on input {i} (from {name}): {}", r.findings[0]);
                            }
                        }
                    }
                }
                // Parameter values: every loaded structured file, one loaded mutant in P.
                let parameters = parameters_every > 0
                    && outcome != Outcome::Rejected
                    && outcome != Outcome::Panicked
                    && (is_structured
                        || parameter_mutants
                            .fetch_add(1, Ordering::Relaxed)
                            .is_multiple_of(parameters_every));
                if parameters {
                    let r = parameter_case(&mutant, &mut rng, parameter_sets, 1, true);
                    let mut s = parametrized.lock().unwrap();
                    s.inputs += usize::from(r.parameters > 0);
                    s.sets += r.sets;
                    s.loaded += r.loaded;
                    s.built += r.built;
                    s.formulations += r.interpretation.formulations;
                    s.solver_runs += r.interpretation.solver_runs;
                    s.steps += r.interpretation.steps;
                    s.position_solves += r.interpretation.position_solves;
                    s.rejected_naming += r.rejected_naming;
                    for e in r.rejected {
                        *s.rejected.entry(e).or_default() += 1;
                    }
                    for e in r.interpretation.errors {
                        *s.errors.entry(e).or_default() += 1;
                    }
                    if let Some(p) = r.panics.first() {
                        s.panics += r.panics.len();
                        outcome = Outcome::Panicked;
                        eprintln!("parameter set panicked on input {i} (from {name}): {p}");
                    }
                    if let Some(f) = r.findings.first() {
                        s.findings += r.findings.len();
                        finding = true;
                        eprintln!("parameter finding on input {i} (from {name}): {f}");
                    }
                }
                if is_structured && outcome != Outcome::Rejected {
                    structured_loaded.fetch_add(1, Ordering::Relaxed);
                }
                if outcome == Outcome::Panicked || finding {
                    std::fs::create_dir_all(&out).ok();
                    let path = out.join(format!("{name}_{seed}_{i}.toml"));
                    std::fs::write(&path, &mutant).ok();
                    eprintln!(
                        "panic or finding on input {i} (from {name}): kept as {}",
                        path.display()
                    );
                }
                if i > 0 && i.is_multiple_of(100_000) {
                    eprintln!(
                        "{i} inputs, {:.0} s, {:.0} MiB resident",
                        start.elapsed().as_secs_f64(),
                        resident_mib()
                    );
                }
            });
        }
    });
    let secs = start.elapsed().as_secs_f64();
    let c = |o: Outcome| counts[o as usize].load(Ordering::Relaxed);
    println!(
        "{inputs} inputs from {} files (seed {seed}, {threads} threads) in {secs:.1} s: {:.0} inputs/s",
        files.len(),
        inputs as f64 / secs
    );
    println!(
        "  rejected by load {}, loaded {}, also generated {}, panicked {}",
        c(Outcome::Rejected),
        c(Outcome::Loaded) + c(Outcome::Generated),
        c(Outcome::Generated),
        c(Outcome::Panicked)
    );
    println!(
        "  structured files {}: {} loaded",
        inputs / 4,
        structured_loaded.load(Ordering::Relaxed)
    );
    let s = interpreted.into_inner().unwrap();
    println!(
        "  interpreted {} (every loaded structured file, one loaded mutant in {interpret_every}): \
         {} built, {} formulations evaluated at 5 states each; {} ran the solvers \
         (one in {solve_every}): {} HHT starts, {} HHT steps Ok, {} position solves",
        s.inputs, s.built, s.formulations, s.solved, s.solver_runs, s.steps, s.position_solves
    );
    let errors: Vec<String> = s.errors.iter().map(|(k, v)| format!("{k} {v}")).collect();
    println!("  runtime errors: {}", errors.join(", "));
    println!(
        "  interpreter panics {}, findings (Ok with a non-finite state) {}; {:.0} MiB resident at the end",
        s.panics,
        s.findings,
        resident_mib()
    );
    let p = parametrized.into_inner().unwrap();
    println!(
        "  parameter values (every loaded structured file, one loaded mutant in \
         {parameters_every}, {parameter_sets} sets each): {} files with parameters, {} sets, \
         {} accepted by load_with, {} built in the interpreter, {} formulations evaluated; \
         {} HHT starts, {} HHT steps Ok, {} position solves",
        p.inputs,
        p.sets,
        p.loaded,
        p.built,
        p.formulations,
        p.solver_runs,
        p.steps,
        p.position_solves
    );
    let refused: usize = p.rejected.values().sum();
    println!(
        "  parameter sets refused {refused} ({} with a diagnostic naming a parameter of the set), \
         by kind of the first diagnostic:",
        p.rejected_naming
    );
    let mut kinds: Vec<(&String, &usize)> = p.rejected.iter().collect();
    kinds.sort_by(|a, b| b.1.cmp(a.1).then(a.0.cmp(b.0)));
    for (k, v) in kinds.iter().take(15) {
        println!("    {v:>7}  {k}");
    }
    let rest: usize = kinds.iter().skip(15).map(|(_, v)| **v).sum();
    if rest > 0 {
        println!("    {rest:>7}  {} other kinds", kinds.len() - 15);
    }
    let errors: Vec<String> = p.errors.iter().map(|(k, v)| format!("{k} {v}")).collect();
    println!(
        "  runtime errors with parameter sets: {}",
        errors.join(", ")
    );
    println!(
        "  parameter-set panics {}, findings {}",
        p.panics, p.findings
    );
    if c(Outcome::Panicked) > 0 || s.findings > 0 || p.panics > 0 || p.findings > 0 {
        std::process::exit(1);
    }
}
