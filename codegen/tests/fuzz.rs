//! A seeded share of the generator fuzzer (`cargo run --release -p symbody-codegen --bin
//! fuzz` runs 10⁶ inputs): mutants of every shipped mechanism file must be rejected with
//! errors or generated, never panic; random structured files that load must run in the
//! interpreter (every mechanism function at the file's and at NaN, infinite and huge states,
//! HHT steps, position solves) without a panic and without a solver `Ok` holding a NaN or
//! infinite state; random and degenerate values of the parameters of shipped files and of
//! structured ones are refused with errors naming them or give finite mechanisms that run;
//! every input the fuzzer ever kept (`tests/fuzz_regressions/`) is replayed.

use std::path::Path;
use symbody_codegen::fuzz::{
    interpret_one, mutate, parameter_case, run_one, structured, Outcome, Rng,
};

#[test]
fn mutated_mechanism_files_never_panic() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../mechanisms");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml") && !p.ends_with("Cargo.toml"))
        .collect();
    files.sort();
    let texts: Vec<String> = files
        .iter()
        .map(|p| std::fs::read_to_string(p).unwrap())
        .collect();
    let mut outcomes = [0usize; 4];
    let mut generated_small = 0;
    for i in 0..3000u64 {
        let mut rng = Rng(0x5eed ^ i);
        let text = &texts[rng.below(texts.len())];
        let mutant = mutate(text, &mut rng);
        // Full generation of the large files takes ~0.5 s: only the small ones here.
        let full = mutant.len() < 4000 && generated_small < 60;
        let o = run_one(&mutant, full);
        if o == Outcome::Generated {
            generated_small += 1;
        }
        assert_ne!(o, Outcome::Panicked, "input {i} panicked:\n{mutant}");
        outcomes[o as usize] += 1;
    }
    // The share exercises both fates: rejected files and files that load.
    assert!(outcomes[Outcome::Rejected as usize] > 1000, "{outcomes:?}");
    assert!(
        outcomes[Outcome::Loaded as usize] + outcomes[Outcome::Generated as usize] > 100,
        "{outcomes:?}"
    );
}

#[test]
fn random_structured_files_never_panic() {
    let mut outcomes = [0usize; 4];
    for i in 0..600u64 {
        let mut rng = Rng(0x57a7 ^ i);
        let text = structured(&mut rng);
        let o = run_one(&text, true);
        assert_ne!(o, Outcome::Panicked, "input {i} panicked:\n{text}");
        outcomes[o as usize] += 1;
    }
    // Both fates again: degenerate files rejected, the others generated.
    assert!(outcomes[Outcome::Rejected as usize] > 50, "{outcomes:?}");
    assert!(outcomes[Outcome::Generated as usize] > 50, "{outcomes:?}");
}

#[test]
fn random_structured_files_run_in_the_interpreter() {
    let (mut built, mut steps, mut errors) = (0, 0, 0);
    for i in 0..1500u64 {
        let mut rng = Rng(0x1a7e ^ i);
        let text = structured(&mut rng);
        let r = interpret_one(&text, &mut rng, 4, true)
            .unwrap_or_else(|| panic!("input {i} panicked in the interpreter:\n{text}"));
        assert!(r.findings.is_empty(), "input {i}: {:?}\n{text}", r.findings);
        built += usize::from(r.built);
        steps += r.steps;
        errors += r.errors.len();
    }
    // Both fates: files that run (and steps taken), and typed errors from degenerate ones
    // and from the NaN, infinite and huge starts.
    assert!(built > 250, "{built} built");
    assert!(steps > 1000, "{steps} steps");
    assert!(errors > 400, "{errors} errors");
}

#[test]
fn random_and_degenerate_parameter_values_never_panic() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../mechanisms");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml") && !p.ends_with("Cargo.toml"))
        .collect();
    files.sort();
    let mut texts: Vec<(String, String)> = files
        .iter()
        .map(|p| (p.display().to_string(), std::fs::read_to_string(p).unwrap()))
        .collect();
    // The shipped files as they are, then structured ones (small: many sets each).
    for i in 0..500u64 {
        texts.push((format!("structured {i}"), structured(&mut Rng(0x9a7a ^ i))));
    }
    let (mut sets, mut loaded, mut built, mut steps, mut refused) = (0, 0, 0, 0, 0);
    for (i, (name, text)) in texts.iter().enumerate() {
        let mut rng = Rng(0x9a7a_5eed ^ i as u64);
        // The shipped files are large: fewer sets, and the solvers on them.
        let n = if name.starts_with("structured") {
            8
        } else {
            12
        };
        let r = parameter_case(text, &mut rng, n, 1, true);
        assert!(r.panics.is_empty(), "{name}: {:?} panicked", r.panics);
        assert!(r.findings.is_empty(), "{name}: {:?}", r.findings);
        sets += r.sets;
        loaded += r.loaded;
        built += r.built;
        steps += r.interpretation.steps;
        refused += r.rejected.len();
    }
    // Every fate is exercised: refused by the loader and by the assembly, built and run.
    eprintln!("{sets} sets: {loaded} loaded, {built} built, {steps} steps, {refused} refused");
    assert!(
        sets > 1000 && built > 300 && steps > 1200,
        "{sets} {built} {steps}"
    );
    assert!(
        refused > 400 && loaded > built,
        "{refused} {loaded} {built}"
    );
}

#[test]
fn kept_fuzz_inputs_never_panic_again() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fuzz_regressions");
    for entry in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let path = entry.path();
        if path.extension().is_some_and(|x| x == "toml") {
            let text = std::fs::read_to_string(&path).unwrap();
            assert_ne!(
                run_one(&text, true),
                Outcome::Panicked,
                "{}",
                path.display()
            );
            // Through the interpreter too, from several random states.
            for seed in 0..16 {
                let r = interpret_one(&text, &mut Rng(seed), 4, true)
                    .unwrap_or_else(|| panic!("{} panicked in the interpreter", path.display()));
                assert!(
                    r.findings.is_empty(),
                    "{}: {:?}",
                    path.display(),
                    r.findings
                );
            }
        }
    }
}
