//! The `symbody` command-line tool as a library: `symbody list`, `symbody simulate
//! [<mechanism>]`, `symbody run <scene>` and `symbody fk <mechanism>`: every generated
//! mechanism by name from the registry; without a name, the paper's Stewart platform
//! scenario and its figures; scene files solved by the cheapest exact path; forward
//! kinematics of the six-leg platforms. [`main`] takes the
//! registry of mechanisms the program links (the `symbody` executable passes the shipped
//! ones), and the summaries, CSVs, figures ([`plot`]) and the HTML viewer ([`viewer`]) are
//! written here.

mod live;
mod meta;
pub mod plot;
pub mod viewer;

use clap::{Parser, Subcommand, ValueEnum};
use serde_json::json;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use symbody::scenario::{self, largest_rotation, Options, Reactions};
use symbody::{fk, generic, scene};
use symbody_runtime::fk::Pose;
use symbody_runtime::{body_pose, Formulation, Registry};

/// `println!` that ignores a closed standard output (e.g. piped into `head`) instead of
/// panicking: the run still writes its files.
macro_rules! say {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stdout(), $($arg)*);
    }};
}

// After `say!`, which it uses.
mod study;

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

/// Where a run writes, and what besides the CSVs.
#[derive(clap::Args)]
struct Files {
    /// Output folder (default: out/<mechanism>/ for `simulate <mechanism>`, out/paper/ for
    /// the paper scenario, out/<scene file stem>/ for `run <scene>`).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Skip the PNG figures.
    #[arg(long)]
    no_plots: bool,
    /// Also write <out>/view.html: a self-contained 3D animation of the run.
    #[arg(long)]
    html: bool,
}

/// Parameters of the mechanism file set to other values.
#[derive(clap::Args)]
struct SetParameters {
    /// Set a parameter of the mechanism file (`[parameters]`, see `symbody params
    /// <mechanism>`), as if the file said so; repeat for several. Nothing to build: the
    /// compiled code takes the numbers the file gives at these values (or the file runs
    /// interpreted where they change its structure).
    #[arg(long = "set", value_name = "NAME=VALUE")]
    set: Vec<String>,
}

impl SetParameters {
    /// The `NAME=VALUE` pairs, or an error naming the one that is not.
    fn parse(&self) -> Result<Vec<(String, f64)>, String> {
        self.set
            .iter()
            .map(|s| {
                let (k, v) = s
                    .split_once('=')
                    .ok_or_else(|| format!("--set {s}: give NAME=VALUE, e.g. --set r=0.12"))?;
                let v: f64 = v
                    .trim()
                    .parse()
                    .map_err(|_| format!("--set {s}: `{}` is not a number", v.trim()))?;
                Ok((k.trim().to_string(), v))
            })
            .collect()
    }
}

/// Parameters to differentiate the run's outputs with respect to.
#[derive(clap::Args)]
struct Sensitivities {
    /// Also write sensitivities.csv: the derivative of every output (body poses, joint
    /// wrenches, driver efforts) with respect to each of these parameters of the mechanism
    /// file, at every output time (`t`, then `<output>/<parameter>` columns).
    #[arg(long, value_delimiter = ',', value_name = "NAME,...")]
    sensitivities: Vec<String>,
}

#[derive(Subcommand)]
enum Command {
    /// List every generated mechanism: sizes, redundant rows, degrees of freedom.
    List,
    /// Check a mechanism file without running it: its diagnostics, the assembly of its
    /// initial pose, rank, mobility, redundant rows and platform detection.
    Check {
        /// The mechanism file, e.g. robot.toml.
        file: PathBuf,
    },
    /// Run a scene once per row of its `[study]` (its mechanism file's parameters on a grid,
    /// a list or random samples), on every core: study.csv gets one row of metrics per run
    /// (those `[study] metrics` names, e.g. largest driver efforts and joint forces, a
    /// coordinate's extremes, a platform's FK condition; by default the efforts, forces,
    /// moments and energy balance), status and wall time as each ends.
    Study {
        /// The scene file, with a [study] table.
        scene: PathBuf,
        /// Runs at a time (default: the number of cores).
        #[arg(long)]
        jobs: Option<usize>,
        /// Output folder (default: out/<scene file stem>/).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Keep the finished rows of an earlier study.csv with the same columns and run only
        /// the others.
        #[arg(long)]
        resume: bool,
        /// Skip study.png (the metrics against one parameter, or heat maps over two).
        #[arg(long)]
        no_plots: bool,
    },
    /// The parameters of a mechanism's file: names, values, the expressions of derived ones,
    /// and the items (bodies, joints, drivers, forces) each one affects.
    Params {
        /// A mechanism from `symbody list`, or a mechanism file.
        mechanism: String,
    },
    /// Simulate a mechanism (compiled, or a file run interpreted); without one, the paper's
    /// 6-6 Stewart platform scenario (one period, 2π s) with the paper's figures.
    Simulate {
        /// A mechanism from `symbody list`, or a mechanism file (robot.toml: interpreted, no
        /// build) (default: the paper's scenario).
        mechanism: Option<String>,
        /// Dynamics formulation (default: the mechanism's first; the paper scenario: exact).
        #[arg(long, value_enum)]
        formulation: Option<FormulationArg>,
        /// End time (s) (default: the mechanism file's `t_end`; the paper scenario: 2π).
        #[arg(long, allow_hyphen_values = true)]
        t_end: Option<f64>,
        /// HHT step (s); with --rtol/--atol, the first step the control tries.
        #[arg(long, default_value_t = Options::default().step, allow_hyphen_values = true)]
        step: f64,
        /// Step-size control: relative tolerance on the local error of positions and
        /// velocities (default: off, the fixed --step). Either of --rtol/--atol alone sets
        /// both.
        #[arg(long, allow_hyphen_values = true)]
        rtol: Option<f64>,
        /// Step-size control: absolute tolerance (m, rad, m/s, rad/s as the coordinates).
        #[arg(long, allow_hyphen_values = true)]
        atol: Option<f64>,
        /// HHT α in [−1/3, 0] (0: trapezoidal, no numerical damping) (default: 0 for a named
        /// mechanism, with velocity projection; −0.05 for the paper scenario).
        #[arg(long, allow_hyphen_values = true)]
        alpha: Option<f64>,
        /// Spacing of the rows in the CSVs (s).
        #[arg(long, default_value_t = Options::default().output_step, allow_hyphen_values = true)]
        output_step: f64,
        /// Let the integrator pass positions where constraint rows are dependent for an
        /// instant (a linkage lying flat, as the IFToMM A02 N-four-bar): a step landing on one
        /// drops the rows whose pivot vanished, and every row must still hold (not the paper
        /// scenario; default: stop with the dependent rows named).
        #[arg(long)]
        cross_singular_positions: bool,
        /// Integrate the mechanism's generated reduced model (its planar model where the
        /// file is planar) and read every step back on the full model: the same tables; the
        /// summary says how many coordinates were integrated (not the paper scenario).
        #[arg(long)]
        reduced: bool,
        /// Add each body's velocities to bodies.csv: <body>.vx,.vy,.vz (centre of mass, m/s)
        /// and .wx,.wy,.wz (angular velocity, rad/s), global frame (not the paper scenario).
        #[arg(long)]
        velocities: bool,
        /// Add each body's accelerations to bodies.csv: <body>.ax,.ay,.az (centre of mass,
        /// m/s²) and .alphax,.alphay,.alphaz (angular, rad/s²), global frame (not the paper
        /// scenario).
        #[arg(long)]
        accelerations: bool,
        /// Paper scenario only: source of the joint and actuator forces, the saddle-point
        /// solve at each output state (`recovered`) or the integrator's own multipliers
        /// (`integrator`).
        #[arg(long, value_enum)]
        reactions: Option<ReactionsArg>,
        #[command(flatten)]
        files: Files,
        #[command(flatten)]
        parameters: SetParameters,
        #[command(flatten)]
        sensitivities: Sensitivities,
    },
    /// Run a scene file (scenes/<name>.toml): the mechanism, time span and outputs it names,
    /// solved by the cheapest exact path — kinematic (no integration) when the drivers fix
    /// everything the scene asks for, HHT-α integration otherwise — with the same summary and
    /// files as `simulate`.
    Run {
        /// The scene file, e.g. scenes/paper.toml.
        scene: PathBuf,
        #[command(flatten)]
        files: Files,
        // Set on top of the scene's own `[parameters]`.
        #[command(flatten)]
        parameters: SetParameters,
        #[command(flatten)]
        sensitivities: Sensitivities,
    },
    /// Forward kinematics of a platform held by six legs of driven length: the pose reached
    /// by continuation from a known pose, with its leg-length residual and the condition
    /// number of the platform's Jacobian; with --all every assembly mode.
    Fk {
        /// A mechanism from `symbody list` whose FK column says yes, or a mechanism file.
        mechanism: String,
        /// Six leg lengths l1,…,l6 (m), joint centre to joint centre (default: what the
        /// drivers prescribe at --at).
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        lengths: Option<Vec<f64>>,
        /// Pose to continue from: x,y,z (m) of the platform frame and its Euler angles θ,β,γ
        /// (rad) of Rz(γ)·Ry(β)·Rx(θ) (default: the mechanism file's initial pose).
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        from: Option<Vec<f64>>,
        /// Time at which the drivers give the default lengths (s).
        #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
        at: f64,
        /// Every assembly mode (all complex solutions by homotopy continuation; the real
        /// ones written to <out>/assembly_modes.csv, numbered from 1 in its `mode` column,
        /// the tracked one marked `current`); an error when none is real.
        #[arg(long)]
        all: bool,
        /// Follow the drivers' motion over the file's t_end and find every assembly mode at
        /// this many equally spaced times: <out>/assembly_modes_over_time.{csv,png}.
        #[arg(long)]
        over_time: Option<usize>,
        /// Output folder.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Skip the PNG figure.
        #[arg(long)]
        no_plots: bool,
        #[command(flatten)]
        parameters: SetParameters,
    },
}

/// The command-line tool over the mechanisms of `registry`: parses the process's arguments,
/// runs the command, prints its summary or error, and gives the exit code.
pub fn main(registry: &Registry) -> ExitCode {
    let cli = Cli::parse();
    live::catch_interrupts();
    let result = match cli.command {
        Command::List => {
            list(registry);
            Ok(())
        }
        Command::Check { file } => check(&file),
        Command::Simulate {
            mechanism,
            formulation,
            t_end,
            step,
            rtol,
            atol,
            alpha,
            output_step,
            cross_singular_positions,
            reduced,
            velocities,
            accelerations,
            reactions,
            files,
            parameters,
            sensitivities,
        } => match (mechanism, generic::tolerances(rtol, atol, "--")) {
            (_, Err(e)) => Err(e),
            (mechanism, Ok(tolerances)) => match mechanism {
            None if !sensitivities.sensitivities.is_empty() => Err("--sensitivities applies to a named mechanism or a file; for the paper's scenario, run scenes/paper.toml with it (e.g. `symbody run scenes/paper.toml --sensitivities r_platform,m_platform`)".to_string()),
            None if !parameters.set.is_empty() => Err("--set applies to a named mechanism or a file; for the paper's scenario with other parameters, run scenes/paper.toml with --set (e.g. `symbody run scenes/paper.toml --set r_platform=0.11`)".to_string()),
            None if velocities || accelerations => Err(format!("--{} applies to a named mechanism or a file (it adds columns to bodies.csv); the paper scenario writes platform.csv", if velocities { "velocities" } else { "accelerations" })),
            None if cross_singular_positions => Err("--cross-singular-positions applies to a named mechanism or a file; the paper scenario has no singular position to cross".to_string()),
            None if reduced => Err("--reduced applies to a named mechanism; for the paper's scenario on its reduced model, run `symbody simulate stewart_6_6 --reduced` or a scene with `[solver] reduce = \"auto\"`".to_string()),
            Some(_) if reactions.is_some() => Err("--reactions applies to the paper scenario only; a named mechanism always reports the reactions of each output state".to_string()),
            Some(name) => {
                let defaults = generic::Options::default();
                let opts = generic::Options {
                    formulation: formulation.map(FormulationArg::formulation),
                    t_end,
                    step,
                    tolerances,
                    alpha: alpha.unwrap_or(defaults.alpha),
                    output_step,
                    cross_singular: cross_singular_positions,
                    newton_tolerance: None,
                    reduce: reduced,
                    path_thread: true,
                };
                parameters.parse().and_then(|p| {
                    simulate_named(registry, &name, &p, &opts, [velocities, accelerations], &files, &sensitivities.sensitivities)
                })
            }
            None => {
                let defaults = Options::default();
                let opts = Options {
                    formulation: formulation.map_or(defaults.formulation, FormulationArg::formulation),
                    t_end: t_end.unwrap_or(defaults.t_end),
                    step,
                    tolerances,
                    alpha: alpha.unwrap_or(defaults.alpha),
                    output_step,
                    reactions: match reactions {
                        Some(ReactionsArg::Integrator) => Reactions::Integrator,
                        Some(ReactionsArg::Recovered) | None => Reactions::Recovered,
                    },
                    newton_tolerance: defaults.newton_tolerance,
                    // The viewer draws every body from them; the paper's files need none.
                    states: files.html,
                };
                let out = files.out.clone().unwrap_or_else(|| default_out("paper"));
                simulate(registry, &opts, &out, !files.no_plots, files.html)
            }
            },
        },
        Command::Run {
            scene,
            files,
            parameters,
            sensitivities,
        } => parameters.parse().and_then(|p| {
            run_scene(registry, &scene, &files, &p, &sensitivities.sensitivities)
        }),
        Command::Params { mechanism } => list_parameters(registry, &mechanism),
        Command::Study {
            scene,
            jobs,
            out,
            resume,
            no_plots,
        } => {
            let jobs = jobs.unwrap_or_else(|| {
                std::thread::available_parallelism().map_or(1, |n| n.get())
            });
            let out = out.unwrap_or_else(|| {
                default_out(&scene.file_stem().map_or("study".into(), |s| s.to_string_lossy()))
            });
            if jobs == 0 {
                Err("--jobs 0: give at least 1".to_string())
            } else {
                study::run(registry, &scene, &out, jobs, (resume, !no_plots))
            }
        }
        Command::Fk {
            mechanism,
            lengths,
            from,
            at,
            all,
            over_time,
            out,
            no_plots,
            parameters,
        } => {
            parameters.parse().and_then(|set| {
            six("--lengths", lengths.as_deref())
                .and_then(|l| {
                    if let Some((i, x)) = l.iter().flatten().enumerate().find(|(_, x)| x.is_nan() || **x <= 0.0) {
                        return Err(format!(
                            "--lengths: leg {} is {x} m long; a leg's length runs from joint centre to joint centre and must be positive",
                            i + 1
                        ));
                    }
                    let from = six("--from", from.as_deref())?;
                    Ok(fk::Request {
                        lengths: l,
                        from: from.map(|p| Pose::from_euler([p[0], p[1], p[2]], [p[3], p[4], p[5]])),
                        at,
                    })
                })
                .and_then(|req| {
                    let entry = symbody::files::with_parameters(registry, &mechanism, &set)
                        .map_err(|e| e.to_string())?;
                    forward_kinematics(registry, entry, &mechanism, &req, (all, over_time), &out, !no_plots)
                })
            })
        }
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

fn list(registry: &Registry) {
    for line in list_lines(registry) {
        say!("{line}");
    }
}

/// The lines `symbody list` prints for `registry`: a header, then one line per mechanism,
/// in columns as wide as their widest entry.
pub fn list_lines(registry: &Registry) -> Vec<String> {
    const HEADER: [&str; 9] = [
        "mechanism",
        "formulations",
        "bodies",
        "coords",
        "rows",
        "redundant",
        "DOF",
        "t_end",
        "FK",
    ];
    let rows: Vec<[String; 9]> = registry
        .iter()
        .map(|e| {
            let info = e.default_mechanism().info();
            let forms: Vec<&str> = e.formulations.iter().map(|(f, _)| f.name()).collect();
            [
                e.name.to_string(),
                forms.join(","),
                info.bodies.len().to_string(),
                info.n_coords.to_string(),
                info.n_constraints.to_string(),
                info.redundant_rows.len().to_string(),
                info.dof().to_string(),
                format!("{:.3}", e.t_end),
                if info.platform.is_some() { "yes" } else { "-" }.to_string(),
            ]
        })
        .collect();
    // Widths from the content: a registry may hold names of any length (the benchmarks'
    // `n_four_bar_40`, a user's `stewart_platform_with_flexible_legs`).
    let widths: [usize; 9] = std::array::from_fn(|c| {
        rows.iter()
            .map(|r| r[c].chars().count())
            .chain([HEADER[c].chars().count()])
            .max()
            .unwrap_or(0)
    });
    let line = |cells: [&str; 9]| -> String {
        let mut s = String::new();
        for (c, (cell, w)) in cells.iter().zip(widths).enumerate() {
            let pad = " ".repeat(w - cell.chars().count());
            match c {
                0 => s.push_str(&format!("{cell}{pad}")),
                1 => s.push_str(&format!(" {cell}{pad}")),
                _ => s.push_str(&format!(" {pad}{cell}")),
            }
        }
        s.trim_end().to_string()
    };
    std::iter::once(line(HEADER))
        .chain(
            rows.iter()
                .map(|r| line(std::array::from_fn(|c| r[c].as_str()))),
        )
        .collect()
}

/// `v` in at most 10 significant digits, without trailing zeros.
fn short(v: f64) -> String {
    if v == 0.0 || (1e-4..1e6).contains(&v.abs()) {
        let s = format!(
            "{:.*}",
            (9 - v.abs().log10().floor().max(-4.0) as i64).max(0) as usize,
            v
        );
        let s = if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.')
        } else {
            &s
        };
        s.to_string()
    } else {
        format!("{v:.9e}")
    }
}

/// The parameters set from outside the file, for meta.json.
fn parameters_json(parameters: &[(String, f64)]) -> serde_json::Value {
    parameters
        .iter()
        .map(|(k, v)| (k.clone(), json!(v)))
        .collect::<serde_json::Map<_, _>>()
        .into()
}

/// `symbody params`: a mechanism file's parameters and what each affects.
fn list_parameters(registry: &Registry, name: &str) -> Result<(), String> {
    let loaded = symbody::files::parameters(registry, name).map_err(|e| e.to_string())?;
    let ps = loaded.parameters;
    if ps.is_empty() {
        say!("{}: its file has no [parameters]", loaded.entry.name);
        return Ok(());
    }
    say!(
        "{}: {} parameters (set with --set NAME=VALUE on simulate, run and fk)",
        loaded.entry.name,
        ps.len()
    );
    // Run-time parameters of the compiled code: setting only those derives nothing.
    let run_time = |p: &str| {
        symbody::generic::find(registry, name)
            .ok()
            .and_then(|e| e.run_time)
            .is_some_and(|rt| rt.parameters.names.contains(&p))
    };
    let width = ps.iter().map(|p| p.name.chars().count()).max().unwrap_or(0);
    for p in ps {
        let how = match &p.expression {
            Some(e) => format!(" = {e}"),
            None => String::new(),
        };
        let affects = match p.affects.is_empty() {
            true => "nothing (unused)".to_string(),
            false => p.affects.join(", "),
        };
        let compiled = match run_time(&p.name) {
            true => ", by name in the compiled code",
            false => "",
        };
        say!(
            "  {:width$} {:>14}{how}  (line {}) affects: {affects}{compiled}",
            p.name,
            short(p.value),
            p.line
        );
    }
    Ok(())
}

/// `symbody check`: what the generator finds out about a file, without running it.
fn check(file: &Path) -> Result<(), String> {
    let loaded = symbody::files::load(file).map_err(|e| e.to_string())?;
    say!("{}", loaded.report.trim_end());
    let forms: Vec<&str> = loaded
        .entry
        .formulations
        .iter()
        .map(|(f, _)| f.name())
        .collect();
    say!(
        "{}: valid; formulations {}; run it with `symbody simulate {}`",
        file.display(),
        forms.join(", "),
        file.display()
    );
    Ok(())
}

/// Where a run writes without `--out`: its own folder under `out/`, so that runs of
/// different mechanisms, scenes and the paper scenario keep each other's files.
fn default_out(name: &str) -> PathBuf {
    Path::new("out").join(name)
}

fn simulate_named(
    registry: &Registry,
    name: &str,
    parameters: &[(String, f64)],
    opts: &generic::Options,
    [velocities, accelerations]: [bool; 2],
    files: &Files,
    sensitivities: &[String],
) -> Result<(), String> {
    let entry =
        symbody::files::with_parameters(registry, name, parameters).map_err(|e| e.to_string())?;
    symbody::sensitivity::values(entry, parameters, sensitivities).map_err(|e| e.to_string())?;
    if opts.reduce {
        generic::require_reduced(entry, opts.formulation).map_err(|e| format!("--reduced: {e}"))?;
    }
    let out = files.out.clone().unwrap_or_else(|| default_out(entry.name));
    let (out, plots, html) = (out.as_path(), !files.no_plots, files.html);
    let t_end = opts.t_end.unwrap_or(entry.t_end);
    let meta = meta::Meta::new(json!({
        "t_end": t_end,
        "step": opts.step,
        "rtol": opts.tolerances.map(|t| t.0),
        "atol": opts.tolerances.map(|t| t.1),
        "alpha": opts.alpha,
        "output_step": opts.output_step,
        "velocities_projected": true,
        "cross_singular_positions": opts.cross_singular,
        "reduced": opts.reduce,
        "velocities": velocities,
        "accelerations": accelerations,
        "parameters": parameters_json(parameters),
    }));
    let mut live = live::Live::new(out, t_end, meta);
    let mut obs = generic::Prepared {
        prepare: |rec: &mut generic::Recording| {
            rec.velocities = velocities;
            rec.accelerations = accelerations;
        },
        inner: &mut live,
    };
    let run = generic::run_observed(entry, opts, &mut obs);
    let method = format!(
        "{}, alpha {}, velocities projected",
        stepping(opts.step, opts.tolerances, opts.output_step),
        opts.alpha
    );
    let note = symbody::files::note(entry);
    report_run(run, live, (&method, note.as_deref()), out, plots, html)
        .map_err(|e| format!("{name}: {e}"))?;
    differentiate(sensitivities, out, || {
        symbody::sensitivity::integrated(entry, opts, parameters, sensitivities)
    })
    .map_err(|e| format!("{name}: {e}"))
}

/// With parameters to differentiate with respect to: `sensitivities.csv` in `out` from
/// `compute`, and its line of the summary.
fn differentiate(
    names: &[String],
    out: &std::path::Path,
    compute: impl FnOnce() -> Result<
        symbody::sensitivity::Sensitivities,
        symbody::scenario::ScenarioError,
    >,
) -> Result<(), String> {
    if names.is_empty() {
        return Ok(());
    }
    let start = std::time::Instant::now();
    let s = compute().map_err(|e| e.to_string())?;
    let wall = start.elapsed().as_secs_f64();
    let path = s.write(out).map_err(|e| {
        format!(
            "cannot write {}: {e}",
            out.join("sensitivities.csv").display()
        )
    })?;
    say!(
        "  sensitivities    {} outputs × {} parameter{} ({}) at {} times in {:.3} s → {}",
        s.outputs.len(),
        s.parameters.len(),
        if s.parameters.len() == 1 { "" } else { "s" },
        s.parameters.join(", "),
        s.t.len(),
        wall,
        path.display()
    );
    Ok(())
}

/// The summary and files of a generic run that went to its end, or of the part a stopped
/// one recorded, with where and why it stopped (then the error).
fn report_run(
    run: Result<generic::Recording, generic::Stopped>,
    live: live::Live,
    method: (&str, Option<&str>),
    out: &std::path::Path,
    plots: bool,
    html: bool,
) -> Result<(), String> {
    let csvs = live.finish()?;
    match run {
        Ok(rec) => report_named(&rec, csvs, method, out, plots, html),
        Err(generic::Stopped {
            recording: Some(rec),
            error,
        }) if !rec.t.is_empty() => {
            report_named(&rec, csvs, method, out, plots, html)?;
            say!(
                "  stopped          after the output at t = {:.6} s: {error}",
                rec.t.last().copied().unwrap_or(0.0)
            );
            Err(error.to_string())
        }
        Err(stopped) => Err(stopped.error.to_string()),
    }
}

/// The summary and files of a generic run (`simulate <name>` or a scene with tables);
/// `method` says how it was solved.
fn report_named(
    rec: &generic::Recording,
    csvs: Vec<std::path::PathBuf>,
    (method, origin): (&str, Option<&str>),
    out: &std::path::Path,
    plots: bool,
    html: bool,
) -> Result<(), String> {
    let info = rec.info;
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
    if let Some(origin) = origin {
        say!("  equations        {origin}");
    }
    if let Some(n) = rec.reduced {
        let (verb, when) = match rec.kinematic {
            Some(_) => ("followed", "output"),
            None => ("integrated", "step"),
        };
        say!(
            "  reduced model    {n} coordinates {verb} (of {}), read back in full at every {when}",
            info.n_coords
        );
    }
    say!("  time span        0 .. {span:.6} s, {method}");
    print_work(&rec.stats, rec.kinematic, span, rec.wall);
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
    match rec.energy_balance() {
        Some((drift, scale)) if scale > 0.0 => say!(
            "  energy balance   max |dT + dV - W| = {drift:.3e} J on a scale of {scale:.4} J ({:.1e})",
            drift / scale
        ),
        Some((drift, _)) => say!(
            "  energy balance   no energy anywhere in the run (max |dT + dV - W| = {drift:.1e} J)"
        ),
        None => say!(
            "  energy balance   not computed: the scene asks for no energy (energy = false), and the kinematic path integrates the work only for it"
        ),
    }
    if let Some(w) = rec.energy_warning("--step", "--rtol") {
        say!("  warning: {w}");
    }
    if !info.redundant_rows.is_empty() {
        // A long list (the 40-bar chain has 120) would bury the summary: the first few, then
        // how many more (`symbody list` counts them; the generated module lists them all).
        const SHOWN: usize = 9;
        let rows = &info.redundant_rows;
        let mut names: Vec<&str> = rows
            .iter()
            .take(SHOWN)
            .map(|&r| info.row_names[r as usize])
            .collect();
        let more = format!("and {} more", rows.len().saturating_sub(SHOWN));
        if rows.len() > SHOWN {
            names.push(&more);
        }
        say!(
            "  redundant rows   {} (λ = 0: the reactions of their joints are one valid choice, not unique)",
            names.join(", ")
        );
    }
    let windows = rec.ill_conditioned();
    if let Some(worst) = windows
        .iter()
        .min_by(|a, b| a.smallest.total_cmp(&b.smallest))
    {
        let outputs: usize = windows.iter().map(|w| w.outputs).sum();
        let dropped: usize = windows.iter().map(|w| w.dropped).sum();
        let first = windows[0];
        say!(
            "  reactions        ill-conditioned near singular positions at {outputs} output(s) in {} window(s), the first t = {:.4} .. {:.4} s; smallest relative pivot {:.1e} at t = {:.4} s (regular positions: typically 1e-3 or more){}: there the reactions amplify the motion's error by about 1/pivot (README: singular positions)",
            windows.len(),
            first.from,
            first.to,
            worst.smallest,
            worst.at,
            if dropped > 0 {
                format!("; at {dropped} output(s) rows were dependent and dropped: their joints carry none of the load there")
            } else {
                String::new()
            },
        );
    }
    if let Some(w) = rec.euler_warning {
        say!(
            "  warning: body `{}` reached beta = {:.3} rad at t = {:.3} s (Euler singularity at ±pi/2; use rotation = \"quaternion\")",
            w.name, w.beta, w.time
        );
    }
    let mut files = csvs;
    files.push(out.join(meta::FILE));
    if plots {
        files.extend(plot::write_plots(rec, out)?);
    }
    let names: Vec<&str> = files
        .iter()
        .filter_map(|f| f.file_name()?.to_str())
        .collect();
    say!("  wrote {}/: {}", out.display(), names.join(", "));
    if html {
        let forces: Vec<viewer::Force<'_>> = rec
            .drivers
            .iter()
            .enumerate()
            .map(|(i, &j)| viewer::Force {
                name: info.joints[j].name,
                unit: info.joints[j].effort_unit,
                values: rec.efforts.iter().map(|e| e[i]).collect(),
            })
            .collect();
        let path = out.join("view.html");
        let title = format!("{} ({} formulation)", info.name, info.formulation.name());
        viewer::write(&path, &title, info, &rec.t, &rec.poses, &forces)?;
        say!("  wrote {}", path.display());
    }
    Ok(())
}

/// The solver statistics and wall time lines of a run summary: the integrator's, or the
/// kinematic path's when the run was not integrated.
fn print_work(
    s: &symbody_runtime::Stats,
    kinematic: Option<symbody_runtime::PathStats>,
    span: f64,
    wall: std::time::Duration,
) {
    match kinematic {
        Some(k) => say!(
            "  solves           {} output times; {} simplified-Newton corrections, {} Newton iterations, {} factorizations",
            k.outputs,
            k.chord_iterations,
            k.newton_iterations,
            k.factorizations
        ),
        None => print_steps(s),
    }
    say!(
        "  wall time        {:.1} ms ({} real time)",
        wall.as_secs_f64() * 1e3,
        speed(span / wall.as_secs_f64())
    );
}

/// How the steps were chosen, for a summary's time-span line. Every output time is landed
/// on, so a fixed step is never longer than the output spacing.
fn stepping(step: f64, tolerances: Option<(f64, f64)>, output_step: f64) -> String {
    match tolerances {
        Some((rtol, atol)) => format!("step-size control rtol {rtol:e}, atol {atol:e}"),
        None => format!("step {} s", step.min(output_step)),
    }
}

fn print_steps(s: &symbody_runtime::Stats) {
    say!(
        "  steps            {} accepted, {} rejected; {} Newton iterations ({:.2}/step), {} factorizations",
        s.steps,
        s.rejected_steps,
        s.newton_iterations,
        s.newton_iterations as f64 / s.steps.max(1) as f64,
        s.factorizations
    );
    if s.controlled {
        say!(
            "  step sizes       {:.3e} .. {:.3e} s (step-size control; {} steps rejected by the error test)",
            s.smallest_step,
            s.largest_step,
            s.error_test_failures
        );
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

fn simulate(
    registry: &Registry,
    opts: &Options,
    out: &std::path::Path,
    plots: bool,
    html: bool,
) -> Result<(), String> {
    live::check_folder(out)?;
    meta::Meta::new(json!({
        "t_end": opts.t_end,
        "step": opts.step,
        "rtol": opts.tolerances.map(|t| t.0),
        "atol": opts.tolerances.map(|t| t.1),
        "alpha": opts.alpha,
        "output_step": opts.output_step,
        "reactions": match opts.reactions {
            Reactions::Recovered => "recovered",
            Reactions::Integrator => "integrator",
        },
    }))
    .write(
        out,
        scenario::MECHANISM,
        opts.formulation.name(),
        &symbody::output::columns(),
    )?;
    let run = scenario::simulate(registry, opts).map_err(|e| match e {
        scenario::ScenarioError::Runtime(symbody_runtime::Error::EulerSingularity {
            time, ..
        }) => {
            format!(
                "{e}\nhint: the exact formulation's mass matrix is singular at β = ±90° (Euler \
                 rates); nothing was written. Simulate up to before t = {time:.3} s with --t-end, \
                 or give that body quaternion coordinates (rotation = \"quaternion\")"
            )
        }
        other => other.to_string(),
    })?;
    let method = format!(
        "{}, alpha {}",
        stepping(opts.step, opts.tolerances, f64::INFINITY),
        opts.alpha
    );
    report_paper(registry, &run, opts.formulation, &method, out, plots, html)
}

/// The summary and files of the paper scenario (`simulate` or a scene with the paper's
/// files); `method` says how it was solved.
fn report_paper(
    registry: &Registry,
    run: &scenario::Run,
    formulation: Formulation,
    method: &str,
    out: &std::path::Path,
    plots: bool,
    html: bool,
) -> Result<(), String> {
    let (xlo, xhi) = run.platform_range(0);
    let (axis, rot) = largest_rotation(run);
    let f0 = run.upper[0][0];
    say!(
        "Stewart 6-6, paper scenario ({} formulation)",
        formulation.name()
    );
    if let Some(n) = run.reduced {
        say!("  reduced model    {n} coordinates followed, read back in full at every output");
    }
    say!(
        "  time span        0 .. {:.6} s, {method}",
        run.t.last().unwrap_or(&0.0)
    );
    print_work(
        &run.stats,
        run.kinematic,
        run.t.last().copied().unwrap_or(0.0),
        run.wall,
    );
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
        if formulation == Formulation::Paper {
            say!("           the constant mass matrix keeps the run regular; the leg's spin is the paper model's flaw (README, Formulations)");
        }
    }
    symbody::output::write_csvs(run, out)
        .map_err(|e| format!("cannot write CSVs to {}: {e}", out.display()))?;
    say!(
        "  wrote {}/: platform.csv, joint_forces.csv, actuators.csv, {}",
        out.display(),
        meta::FILE
    );
    if plots {
        let files = plot::paper_figures(run, out)?;
        say!(
            "  wrote {} figures to {}/: {}",
            files.len(),
            out.display(),
            files
                .iter()
                .filter_map(|f| f.file_name()?.to_str())
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    if html {
        if run.q.len() != run.t.len() {
            return Err(
                "the run kept no states to draw: run it with `Options::states` for --html"
                    .to_string(),
            );
        }
        let info = scenario::mechanism_info(registry, formulation).map_err(|e| e.to_string())?;
        let poses = run
            .q
            .iter()
            .map(|q| {
                info.bodies
                    .iter()
                    .map(|b| body_pose(b, q))
                    .collect::<Result<Vec<_>, _>>()
            })
            .collect::<Result<Vec<_>, _>>()
            .map_err(|e| e.to_string())?;
        let forces: Vec<viewer::Force<'_>> = (0..6)
            .map(|i| viewer::Force {
                name: ["act1", "act2", "act3", "act4", "act5", "act6"][i],
                unit: "N",
                values: run.actuators.iter().map(|a| a[i]).collect(),
            })
            .collect();
        let path = out.join("view.html");
        let title = format!(
            "Stewart 6-6, paper scenario ({} formulation)",
            formulation.name()
        );
        viewer::write(&path, &title, info, &run.t, &poses, &forces)?;
        say!("  wrote {}", path.display());
    }
    Ok(())
}

/// `symbody run <scene>`: load and check the scene, choose the path, run, report.
fn run_scene(
    registry: &Registry,
    path: &Path,
    files: &Files,
    set: &[(String, f64)],
    sensitivities: &[String],
) -> Result<(), String> {
    let (plots, html) = (!files.no_plots, files.html);
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read scene file {}: {e}", path.display()))?;
    // The diagnostics carry their own `error:` prefix; `main` adds the first one.
    let mut scene = scene::load(registry, &path.display().to_string(), &text).map_err(|e| {
        let shown = e.to_string();
        shown.strip_prefix("error: ").unwrap_or(&shown).to_string()
    })?;
    scene.states = html;
    // `--set` on top of the scene's own parameters.
    let parameters = symbody::files::merged(&scene.parameters, set);
    let entry = match set.is_empty() {
        true => scene.entry,
        false => symbody::files::reparametrized(scene.entry, &parameters)
            .map_err(|e| format!("{}: --set: {e}", path.display()))?,
    };
    symbody::sensitivity::values(entry, &parameters, sensitivities)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let out = files.out.clone().unwrap_or_else(|| {
        default_out(
            &path
                .file_stem()
                .map_or_else(|| scene.mechanism.into(), |s| s.to_string_lossy()),
        )
    });
    let out = out.as_path();
    live::check_folder(out)?;
    let meta = meta::Meta::new(json!({
        "scene": path.display().to_string(),
        "t_end": scene.t_end,
        "step": scene.step,
        "rtol": scene.tolerances.map(|t| t.0),
        "atol": scene.tolerances.map(|t| t.1),
        "alpha": scene.alpha,
        "output_step": scene.output_step,
        "path": match scene.path {
            scene::PathRequest::Auto => "auto",
            scene::PathRequest::Kinematic => "kinematic",
            scene::PathRequest::Integrate => "integrate",
        },
        "cross_singular_positions": scene.cross_singular,
        "velocities": scene.velocities,
        "accelerations": scene.accelerations,
        "parameters": parameters_json(&parameters),
    }));
    if scene.files == scene::Files::Paper {
        // The paper scenario's run does not report its start: described before it, as
        // `simulate` does.
        meta.write(
            out,
            scene.mechanism,
            scene.formulation.name(),
            &symbody::output::columns(),
        )?;
    }
    let mut live = live::Live::new(out, scene.t_end, meta.clone());
    let (choice, outcome) = scene::run_observed(&scene, entry, &mut live)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let taken = match choice {
        scene::PathChoice::Kinematic { .. } => "kinematic",
        scene::PathChoice::Integrate { .. } => "integrate",
    };
    live.note("path_taken", json!(taken))?;
    if scene.files == scene::Files::Paper {
        let mut meta = meta;
        meta.settings.insert("path_taken".into(), json!(taken));
        meta.write(
            out,
            scene.mechanism,
            scene.formulation.name(),
            &symbody::output::columns(),
        )?;
    }
    let info = generic::mechanism(entry, Some(scene.formulation))
        .map_err(|e| e.to_string())?
        .info();
    say!("scene {}", path.display());
    say!("  path             {}", choice.describe(info));
    let method = match choice {
        scene::PathChoice::Kinematic { .. } => {
            format!("outputs every {} s, no integration", scene.output_step)
        }
        scene::PathChoice::Integrate { .. } => format!(
            "{}, alpha {}",
            stepping(scene.step, scene.tolerances, scene.output_step),
            scene.alpha
        ),
    };
    let at = |e: String| format!("{}: {e}", path.display());
    let note = symbody::files::note(entry);
    match outcome {
        Ok(scene::Outcome::Paper(run)) => {
            live.finish()?;
            report_paper(registry, &run, scene.formulation, &method, out, plots, html)?
        }
        Ok(scene::Outcome::Tables(rec)) => {
            report_run(Ok(rec), live, (&method, note.as_deref()), out, plots, html).map_err(at)?
        }
        Err(stopped) => {
            return report_run(
                Err(stopped),
                live,
                (&method, note.as_deref()),
                out,
                plots,
                html,
            )
            .map_err(at)
        }
    }
    let kinematic = matches!(choice, scene::PathChoice::Kinematic { .. });
    differentiate(sensitivities, out, || {
        symbody::sensitivity::of_scene(&scene, entry, kinematic, &parameters, sensitivities)
    })
    .map_err(at)
}

/// Six comma-separated numbers, or an error naming the option.
fn six(option: &str, v: Option<&[f64]>) -> Result<Option<[f64; 6]>, String> {
    match v {
        None => Ok(None),
        Some(v) if v.len() == 6 && v.iter().all(|x| x.is_finite()) => {
            Ok(Some(std::array::from_fn(|i| v[i])))
        }
        Some(v) => Err(format!(
            "{option} needs six finite comma-separated numbers, got {}: {v:?}",
            v.len()
        )),
    }
}

fn forward_kinematics(
    registry: &Registry,
    entry: &'static symbody_runtime::Entry,
    name: &str,
    req: &fk::Request,
    (all, over_time): (bool, Option<usize>),
    out: &std::path::Path,
    plots: bool,
) -> Result<(), String> {
    let p = fk::platform(entry)
        .map_err(|e| format!("{e}; here: {}", fk::platforms(registry).join(", ")))?;
    let names = p.leg_names();
    say!(
        "{name}: platform `{}` on legs {}",
        p.body().name,
        names.join(", ")
    );
    if let Some(note) = symbody::files::note(entry) {
        say!("  equations: {note}");
    }
    let answer = fk::solve(&p, req).map_err(|e| match e {
        symbody::scenario::ScenarioError::Runtime(_) => format!(
            "{name}: continuing the pose along the straight leg-length path from the start \
             pose (t = 0) to the requested lengths (t = 1): {e}"
        ),
        // Already says where and why (lengths no pose has).
        other => format!("{name}: {other}"),
    });
    match &answer {
        Ok(a) => {
            let s = a.tracked.solution;
            let [x, y, z] = [s.pose.position.x, s.pose.position.y, s.pose.position.z];
            let [th, be, ga] = s.pose.euler_angles();
            say!("  lengths          {}", join(&a.lengths, 9));
            say!("  position         {x:.12} {y:.12} {z:.12} m");
            say!("  euler angles     {th:.12} {be:.12} {ga:.12} rad (theta, beta, gamma)");
            for r in 0..3 {
                say!(
                    "  rotation row {}   {}",
                    r + 1,
                    join(&[0, 1, 2].map(|c| s.pose.rotation[(r, c)]), 12)
                );
            }
            say!(
                "  residual         {:.2e} m (largest leg-length error)",
                s.residual
            );
            say!(
                "  continuation     {} steps from the start pose; {} Newton iterations in the last",
                a.tracked.steps,
                s.iterations
            );
            say!(
                "  condition        {:.4e} (Jacobian, rotation columns scaled by the platform radius {:.4} m); det sign {:+}",
                s.condition,
                p.legs().characteristic_length(),
                s.det_sign
            );
            say!("  wall time        {:.3} ms", a.wall.as_secs_f64() * 1e3);
        }
        Err(e) if all => say!("  no tracked pose: {e}"),
        Err(e) => return Err(e.clone()),
    }
    if all {
        let lengths = answer
            .as_ref()
            .map(|a| a.lengths)
            .unwrap_or_else(|_| req.lengths.unwrap_or_else(|| p.lengths_at(req.at)));
        let current = answer.as_ref().ok().map(|a| a.tracked.solution.pose);
        let (modes, index, wall) =
            fk::all_modes(&p, &lengths, current.as_ref()).map_err(|e| e.to_string())?;
        say!(
            "  assembly modes   {} real of {} complex (general platform: 40); {} paths in {} attempt{}{}, {:.1} ms",
            modes.real.len(),
            modes.complex,
            modes.paths,
            modes.attempts,
            if modes.attempts == 1 { "" } else { "s" },
            if modes.fallback {
                " (the 40 from the shipped generic platform, then the linear-product start)"
            } else {
                " from the shipped generic platform"
            },
            wall.as_secs_f64() * 1e3
        );
        if modes.real.is_empty() {
            return Err(format!(
                "{name}: no real assembly mode at the leg lengths {} m (all {} are complex): no \
                 pose of the platform has them, and nothing was written; give lengths the legs can reach (the drivers' \
                 at some time: --at)",
                lengths.map(|l| l.to_string()).join(", "),
                modes.complex
            ));
        }
        let worst = modes.real.iter().map(|m| m.residual).fold(0.0, f64::max);
        say!("  worst residual   {worst:.2e} m over the real modes");
        match index {
            Some(k) => say!(
                "  current          mode {} of {} (column `mode` of assembly_modes.csv)",
                k + 1,
                modes.real.len()
            ),
            None => say!("  current          none: no tracked pose to compare with"),
        }
        fk::write_modes(out, &modes, index)?;
        say!("  wrote {}/assembly_modes.csv", out.display());
    }
    if let Some(n) = over_time {
        if n == 0 {
            return Err("--over-time needs at least 1 interval".to_string());
        }
        let clock = std::time::Instant::now();
        let samples = fk::over_time(&p, entry.t_end, n).map_err(|e| format!("{name}: {e}"))?;
        let lo = samples.iter().map(|s| s.real).min().unwrap_or(0);
        let hi = samples.iter().map(|s| s.real).max().unwrap_or(0);
        let near = samples
            .iter()
            .map(|s| s.nearest)
            .fold(f64::INFINITY, f64::min);
        let cond = samples.iter().map(|s| s.condition).fold(0.0, f64::max);
        say!(
            "  over time        0 .. {:.4} s, {} samples: {lo}..{hi} real modes; nearest other mode at least {near:.4} m away; condition at most {cond:.3e}; {:.0} ms",
            entry.t_end,
            samples.len(),
            clock.elapsed().as_secs_f64() * 1e3
        );
        let mut files = fk::write_over_time(out, &samples)?;
        if plots {
            files.push(plot::modes_over_time(out, &samples)?);
        }
        say!("  wrote {}/: {}", out.display(), files.join(", "));
    }
    Ok(())
}

fn join(v: &[f64], digits: usize) -> String {
    v.iter()
        .map(|x| format!("{x:.digits$}"))
        .collect::<Vec<_>>()
        .join(" ")
}
