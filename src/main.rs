//! `symbody list` and `symbody simulate [<mechanism>]`: every generated mechanism by name
//! from the registry; without a name, the paper's Stewart platform scenario and its figures.

use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;
use std::process::ExitCode;
use symbody::generic;
use symbody::scenario::{self, largest_rotation, Options, Reactions};
use symbody_mechanisms::REGISTRY;
use symbody_runtime::Formulation;

/// `println!` that ignores a closed standard output (e.g. piped into `head`) instead of
/// panicking: the run still writes its files.
macro_rules! say {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($arg)*);
    }};
}

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
    /// List every generated mechanism: sizes, redundant rows, degrees of freedom.
    List,
    /// Simulate a generated mechanism; without a name, the paper's 6-6 Stewart platform
    /// scenario (one period, 2π s) with the paper's figures.
    Simulate {
        /// A mechanism from `symbody list` (default: the paper's scenario).
        mechanism: Option<String>,
        /// Dynamics formulation (default: the mechanism's first; the paper scenario: exact).
        #[arg(long, value_enum)]
        formulation: Option<FormulationArg>,
        /// End time (s) (default: the mechanism file's `t_end`; the paper scenario: 2π).
        #[arg(long, allow_hyphen_values = true)]
        t_end: Option<f64>,
        /// HHT step (s).
        #[arg(long, default_value_t = Options::default().step, allow_hyphen_values = true)]
        step: f64,
        /// HHT α in [−1/3, 0] (0: trapezoidal, no numerical damping) (default: 0 for a named
        /// mechanism, with velocity projection; −0.05 for the paper scenario).
        #[arg(long, allow_hyphen_values = true)]
        alpha: Option<f64>,
        /// Spacing of the rows in the CSVs (s).
        #[arg(long, default_value_t = Options::default().output_step, allow_hyphen_values = true)]
        output_step: f64,
        /// Paper scenario only: source of the joint and actuator forces, the saddle-point
        /// solve at each output state (`recovered`) or the integrator's own multipliers
        /// (`integrator`).
        #[arg(long, value_enum)]
        reactions: Option<ReactionsArg>,
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
    let result = match cli.command {
        Command::List => {
            list();
            Ok(())
        }
        Command::Simulate {
            mechanism,
            formulation,
            t_end,
            step,
            alpha,
            output_step,
            reactions,
            out,
            no_plots,
        } => match mechanism {
            Some(_) if reactions.is_some() => Err("--reactions applies to the paper scenario only; a named mechanism always reports the reactions of each output state".to_string()),
            Some(name) => {
                let defaults = generic::Options::default();
                let opts = generic::Options {
                    formulation: formulation.map(FormulationArg::formulation),
                    t_end,
                    step,
                    alpha: alpha.unwrap_or(defaults.alpha),
                    output_step,
                };
                simulate_named(&name, &opts, &out, !no_plots)
            }
            None => {
                let defaults = Options::default();
                let opts = Options {
                    formulation: formulation.map_or(defaults.formulation, FormulationArg::formulation),
                    t_end: t_end.unwrap_or(defaults.t_end),
                    step,
                    alpha: alpha.unwrap_or(defaults.alpha),
                    output_step,
                    reactions: match reactions {
                        Some(ReactionsArg::Integrator) => Reactions::Integrator,
                        Some(ReactionsArg::Recovered) | None => Reactions::Recovered,
                    },
                };
                simulate(&opts, &out, !no_plots)
            }
        },
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

impl FormulationArg {
    fn formulation(self) -> Formulation {
        match self {
            FormulationArg::Paper => Formulation::Paper,
            FormulationArg::Exact => Formulation::Exact,
        }
    }
}

fn list() {
    say!(
        "{:<20} {:<13} {:>6} {:>6} {:>5} {:>9} {:>4} {:>7}",
        "mechanism",
        "formulations",
        "bodies",
        "coords",
        "rows",
        "redundant",
        "DOF",
        "t_end"
    );
    for e in REGISTRY {
        let info = e.default_mechanism().info();
        let forms: Vec<&str> = e.formulations.iter().map(|(f, _)| f.name()).collect();
        say!(
            "{:<20} {:<13} {:>6} {:>6} {:>5} {:>9} {:>4} {:>7.3}",
            e.name,
            forms.join(","),
            info.bodies.len(),
            info.n_coords,
            info.n_constraints,
            info.redundant_rows.len(),
            info.dof(),
            e.t_end
        );
    }
}

fn simulate_named(
    name: &str,
    opts: &generic::Options,
    out: &std::path::Path,
    plots: bool,
) -> Result<(), String> {
    let entry = generic::find(name).map_err(|e| e.to_string())?;
    let rec = generic::run(entry, opts).map_err(|e| format!("{name}: {e}"))?;
    let info = rec.info;
    let s = rec.stats;
    let span = rec.t.last().copied().unwrap_or(0.0);
    say!("{} ({} formulation)", info.name, info.formulation.name());
    say!(
        "  size             {} bod{}, {} coordinates, {} rows, {} DOF",
        info.bodies.len(),
        if info.bodies.len() == 1 { "y" } else { "ies" },
        info.n_coords,
        info.n_constraints,
        info.dof()
    );
    // Every output time is landed on, so no step is longer than the output spacing.
    say!(
        "  time span        0 .. {span:.6} s, step {} s, alpha {}, velocities projected",
        opts.step.min(opts.output_step),
        opts.alpha
    );
    print_work(&s, span, rec.wall);
    let norms = if info
        .bodies
        .iter()
        .any(|b| b.rotation == symbody_runtime::Rotation::Quaternion)
    {
        format!("; quaternion norms |e'e - 1| {:.2e}", rec.max_norm_error)
    } else {
        String::new()
    };
    say!(
        "  max |Phi|        {:.2e} (velocity residual {:.2e}{norms})",
        rec.max_phi,
        rec.max_velocity_residual
    );
    let (drift, scale) = rec.energy_balance();
    say!(
        "  energy balance   max |dT + dV - W| = {drift:.3e} J on a scale of {scale:.4} J ({:.1e})",
        drift / scale.max(f64::MIN_POSITIVE)
    );
    if !info.redundant_rows.is_empty() {
        let names: Vec<&str> = info
            .redundant_rows
            .iter()
            .map(|&r| info.row_names[r as usize])
            .collect();
        say!(
            "  redundant rows   {} (λ = 0: the reactions of their joints are one valid choice, not unique)",
            names.join(", ")
        );
    }
    if let Some(w) = rec.euler_warning {
        say!(
            "  warning: body `{}` reached beta = {:.3} rad at t = {:.3} s (Euler singularity at ±pi/2; use rotation = \"quaternion\")",
            w.name, w.beta, w.time
        );
    }
    let files = generic::write_outputs(&rec, out, plots)?;
    let names: Vec<&str> = files
        .iter()
        .filter_map(|f| f.file_name()?.to_str())
        .collect();
    say!("  wrote {}/: {}", out.display(), names.join(", "));
    Ok(())
}

/// The solver statistics and wall time lines of a run summary.
fn print_work(s: &symbody_runtime::Stats, span: f64, wall: std::time::Duration) {
    say!(
        "  steps            {} accepted, {} rejected; {} Newton iterations ({:.2}/step), {} factorizations",
        s.steps,
        s.rejected_steps,
        s.newton_iterations,
        s.newton_iterations as f64 / s.steps.max(1) as f64,
        s.factorizations
    );
    say!(
        "  wall time        {:.1} ms ({} real time)",
        wall.as_secs_f64() * 1e3,
        speed(span / wall.as_secs_f64())
    );
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
    say!(
        "Stewart 6-6, paper scenario ({} formulation)",
        opts.formulation.name()
    );
    say!(
        "  time span        0 .. {:.6} s, step {} s, alpha {}",
        run.t.last().unwrap_or(&0.0),
        opts.step,
        opts.alpha
    );
    print_work(&s, run.t.last().copied().unwrap_or(0.0), run.wall);
    say!(
        "  max |Phi|        {:.2e} (velocity residual {:.2e})",
        run.max_phi,
        run.max_velocity_residual
    );
    say!("  platform X range [{xlo:.5}, {xhi:.5}] m");
    say!("  largest rotation {rot:.4} rad, {axis}");
    say!(
        "  F on platform at leg 1 upper joint, t=0: ({:.5}, {:.5}, {:.5}) N",
        f0[0],
        f0[1],
        f0[2]
    );
    if let Some((t, body, beta)) = run.euler_warning {
        say!("  warning: body `{body}` reached beta = {beta:.3} rad at t = {t:.3} s (Euler singularity at ±pi/2)");
    }
    symbody::output::write_csvs(&run, out)
        .map_err(|e| format!("cannot write CSVs to {}: {e}", out.display()))?;
    say!(
        "  wrote {}/platform.csv, joint_forces.csv, actuators.csv",
        out.display()
    );
    if plots {
        let files = symbody::plot::paper_figures(&run, out)?;
        say!(
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
