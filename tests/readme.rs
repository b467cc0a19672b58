//! The README's counts are the code's: the `symbody list` block is the command's output, the
//! number of shipped and benchmark-only mechanisms and the paper model's sizes are the
//! registry's. (Timings live in BENCHMARKS.md, where they are measured.)

use std::process::Command;

fn readme() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap()
}

const WORDS: [&str; 16] = [
    "zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten",
    "eleven", "twelve", "thirteen", "fourteen", "fifteen",
];

/// The number written as a word just before `after` in `text`, e.g. "Eleven ship".
fn word_before(text: &str, after: &str) -> usize {
    let at = text
        .find(after)
        .unwrap_or_else(|| panic!("README lost `{after}`"));
    let word = text[..at].split_whitespace().last().unwrap().to_lowercase();
    WORDS
        .iter()
        .position(|w| *w == word)
        .unwrap_or_else(|| panic!("`{word} {after}` is not a count"))
}

#[test]
fn the_list_block_is_what_list_prints() {
    let out = Command::new(env!("CARGO_BIN_EXE_symbody"))
        .arg("list")
        .output()
        .unwrap();
    assert!(out.status.success());
    let printed = String::from_utf8(out.stdout).unwrap();
    let text = readme();
    let block = text
        .split("```text\n")
        .map(|b| b.split("```").next().unwrap())
        .find(|b| b.starts_with("mechanism "))
        .expect("the README shows `symbody list`");
    assert_eq!(block, printed);
}

#[test]
fn the_mechanism_counts_are_the_registries() {
    let text = readme();
    let shipped = symbody_mechanisms::REGISTRY.len();
    let all = symbody_benchmark_mechanisms::REGISTRY.len();
    assert_eq!(word_before(&text, "ship with the repository"), shipped);
    assert_eq!(
        word_before(&text, "larger\nIFToMM benchmark problems"),
        all - shipped
    );
}

#[test]
fn the_paper_models_sizes_are_the_generated_ones() {
    let info = symbody_mechanisms::REGISTRY
        .find(symbody::scenario::MECHANISM)
        .unwrap()
        .default_mechanism()
        .info();
    let sizes = format!(
        "({} rigid\nbodies, {} coordinates, {} constraints, {} nonzeros in Φq)",
        info.bodies.len(),
        info.n_coords,
        info.n_constraints,
        info.phi_q_nnz()
    );
    assert!(readme().contains(&sizes), "README lacks {sizes}");
}
