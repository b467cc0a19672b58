//! `cargo run --release -p symbody-codegen --bin fuzz -- [--inputs N] [--seed S]
//! [--generate-every K]`: N inputs (default 10⁶), three in four mutants of the shipped mechanism
//! files and one in four a random structured file; every input goes through `load`, and one
//! loaded mutant in K (default 1000) and one loaded structured file in 20 through all of
//! `generate`; reports throughput and any panic. Inputs that panic are written to
//! `codegen/tests/fuzz_regressions/`, where `cargo test` replays them.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;
use symbody_codegen::fuzz::{mutate, run_one, structured, Outcome, Rng};

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

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let inputs = arg(&args, "--inputs", 1_000_000) as usize;
    let seed = arg(&args, "--seed", 1);
    let every = arg(&args, "--generate-every", 1000).max(1) as usize;
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let files = corpus(&root.join("../mechanisms"));
    let out = root.join("tests/fuzz_regressions");
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
                let mut rng = Rng(seed.wrapping_mul(0x1000_0000_01b3) ^ i as u64);
                let is_structured = i % 4 == 3;
                let (name, mutant) = if is_structured {
                    ("structured", structured(&mut rng))
                } else {
                    let (name, text) = &files[rng.below(files.len())];
                    (name.as_str(), mutate(text, &mut rng))
                };
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
                if is_structured && outcome != Outcome::Rejected {
                    structured_loaded.fetch_add(1, Ordering::Relaxed);
                }
                if outcome == Outcome::Panicked {
                    std::fs::create_dir_all(&out).ok();
                    let path = out.join(format!("{name}_{seed}_{i}.toml"));
                    std::fs::write(&path, &mutant).ok();
                    eprintln!(
                        "panic on input {i} (from {name}): kept as {}",
                        path.display()
                    );
                }
                if i > 0 && i.is_multiple_of(100_000) {
                    eprintln!("{i} inputs, {:.0} s", start.elapsed().as_secs_f64());
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
    if c(Outcome::Panicked) > 0 {
        std::process::exit(1);
    }
}
