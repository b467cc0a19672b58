//! The command-line tool over the shipped mechanisms and the benchmark problems (whose
//! mechanisms the `symbody` executable does not link): `cargo run --release -p symbody-bench
//! --bin symbody-bench -- simulate n_four_bar_40`.

fn main() -> std::process::ExitCode {
    symbody_cli::main(&symbody_bench::REGISTRY)
}
