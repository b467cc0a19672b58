//! The `symbody` command-line tool: its code is `symbody-cli`; this program links it with the
//! shipped mechanisms' registry, so changing a mechanism recompiles only that mechanism's
//! crate, the registry and this file.

fn main() -> std::process::ExitCode {
    symbody_cli::main(&symbody_mechanisms::REGISTRY)
}
