//! `symbody simulate`: runs the paper's Stewart platform scenario with the generated
//! equations and writes CSVs and the paper's figures.

use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;
use std::process::ExitCode;
use symbody::scenario::{self, largest_rotation, Options, Reactions};
use symbody_runtime::Formulation;

#[derive(Parser)]
#[command(
    name = "symbody",
    version,
    about = "Generated multibody equations, simulated"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Clone, Copy, ValueEnum)]
enum FormulationArg {
    /// Diagonal mass matrix against Euler-angle accelerations, as the paper.
    Paper,
    /// Mass matrix and forces from the exact kinetic energy.
    Exact,
}

#[derive(Clone, Copy, ValueEnum)]
enum ReactionsArg {
    /// λ from [M Φqᵀ; Φq 0][q̈; λ] = [Q; γ] at each output state.
    Recovered,
    /// The HHT integrator's λ.
    Integrator,
}

#[derive(Subcommand)]
enum Command {
    /// Simulate the paper's 6-6 Stewart platform scenario (one period, 2π s, by default).
    Simulate {
        /// Dynamics formulation.
        #[arg(long, value_enum, default_value = "exact")]
        formulation: FormulationArg,
        /// End time (s).
        #[arg(long, default_value_t = 2.0 * std::f64::consts::PI, allow_hyphen_values = true)]
        t_end: f64,
        /// HHT step (s).
        #[arg(long, default_value_t = Options::default().step, allow_hyphen_values = true)]
        step: f64,
        /// HHT α in [−1/3, 0] (0: trapezoidal, no numerical damping).
        #[arg(long, default_value_t = Options::default().alpha, allow_hyphen_values = true)]
        alpha: f64,
        /// Spacing of the rows in the CSVs (s).
        #[arg(long, default_value_t = Options::default().output_step, allow_hyphen_values = true)]
        output_step: f64,
        /// Source of the joint and actuator forces: the saddle-point solve at each output
        /// state (`recovered`), or the integrator's own multipliers (`integrator`).
        #[arg(long, value_enum, default_value = "recovered")]
        reactions: ReactionsArg,
        /// Output folder.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Skip the PNG figures.
        #[arg(long)]
        no_plots: bool,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Simulate {
            formulation,
            t_end,
            step,
            alpha,
            output_step,
            reactions,
            out,
            no_plots,
        } => {
            let opts = Options {
                formulation: match formulation {
                    FormulationArg::Paper => Formulation::Paper,
                    FormulationArg::Exact => Formulation::Exact,
                },
                t_end,
                step,
                alpha,
                output_step,
                reactions: match reactions {
                    ReactionsArg::Recovered => Reactions::Recovered,
                    ReactionsArg::Integrator => Reactions::Integrator,
                },
            };
            match simulate(&opts, &out, !no_plots) {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!("error: {e}");
                    ExitCode::FAILURE
                }
            }
        }
    }
}

/// "123x faster than" or "0.06x", readable at any ratio.
fn speed(ratio: f64) -> String {
    if ratio >= 10.0 {
        format!("{ratio:.0}x faster than")
    } else {
        format!("{ratio:.2}x")
    }
}

fn simulate(opts: &Options, out: &std::path::Path, plots: bool) -> Result<(), String> {
    let run = scenario::simulate(opts).map_err(|e| match e {
        scenario::ScenarioError::Runtime(symbody_runtime::Error::EulerSingularity {
            time, ..
        }) => {
            format!(
                "{e}\nhint: Euler angles cannot represent this orientation; nothing was written. \
                 Simulate up to before t = {time:.3} s with --t-end, or use --formulation exact \
                 (the paper formulation lacks the gyroscopic coupling and spins the legs)"
            )
        }
        other => other.to_string(),
    })?;
    let s = run.stats;
    let (xlo, xhi) = run.platform_range(0);
    let (axis, rot) = largest_rotation(&run);
    let f0 = run.upper[0][0];
    println!(
        "Stewart 6-6, paper scenario ({} formulation)",
        opts.formulation.name()
    );
    println!(
        "  time span        0 .. {:.6} s, step {} s, alpha {}",
        run.t.last().unwrap_or(&0.0),
        opts.step,
        opts.alpha
    );
    println!(
        "  steps            {} accepted, {} rejected; {} Newton iterations ({:.2}/step), {} factorizations",
        s.steps,
        s.rejected_steps,
        s.newton_iterations,
        s.newton_iterations as f64 / s.steps.max(1) as f64,
        s.factorizations
    );
    println!(
        "  wall time        {:.1} ms ({} real time)",
        run.wall.as_secs_f64() * 1e3,
        speed(run.t.last().copied().unwrap_or(0.0) / run.wall.as_secs_f64())
    );
    println!(
        "  max |Phi|        {:.2e} (velocity residual {:.2e})",
        run.max_phi, run.max_velocity_residual
    );
    println!("  platform X range [{xlo:.5}, {xhi:.5}] m");
    println!("  largest rotation {rot:.4} rad, {axis}");
    println!(
        "  F on platform at leg 1 upper joint, t=0: ({:.5}, {:.5}, {:.5}) N",
        f0[0], f0[1], f0[2]
    );
    if let Some((t, body, beta)) = run.euler_warning {
        println!("  warning: body `{body}` reached beta = {beta:.3} rad at t = {t:.3} s (Euler singularity at ±pi/2)");
    }
    symbody::output::write_csvs(&run, out)
        .map_err(|e| format!("cannot write CSVs to {}: {e}", out.display()))?;
    println!(
        "  wrote {}/platform.csv, joint_forces.csv, actuators.csv",
        out.display()
    );
    if plots {
        let files = symbody::plot::paper_figures(&run, out)?;
        println!(
            "  wrote {} figures: {}",
            files.len(),
            files
                .iter()
                .filter_map(|f| f.file_name()?.to_str())
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    Ok(())
}
