//! The paper's scenario on the generated Stewart platform: consistent start, HHT-α over the
//! requested span, and the time series the paper plots (pose, joint reactions, actuators).

use crate::path_feed::{self, State, Thread};
use crate::stepper::{reach, Batched, Grid, Outputting};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};
use symbody_runtime::fk::{ModeWatch, Platform, SIMULATION_MAX_CONDITION};
use symbody_runtime::kinematics::kinetic_energy;
use symbody_runtime::{
    actuator_force, velocity_residual, Entry, Error, EulerWarning, ForceOnBody, Formulation,
    FullState, HhtBuilder, Integrator, KinematicPath, Kinematics, Mechanism, MechanismInfo,
    PathStats, Reduction, Registry, ResidualWatch, Residuals, Stats,
};

/// Options of one simulation; `Default` is the paper's scenario over one period.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    pub formulation: Formulation,
    /// End time (s); the motion repeats every 2π s.
    pub t_end: f64,
    /// Nominal HHT step (s); with `tolerances`, the first step the control tries.
    pub step: f64,
    /// Step-size control `(rtol, atol)` (`HhtBuilder::tolerances`); `None`: fixed `step`.
    pub tolerances: Option<(f64, f64)>,
    /// HHT α in [−1/3, 0].
    pub alpha: f64,
    /// Spacing of recorded outputs (s); the integrator lands exactly on each.
    pub output_step: f64,
    /// Where the recorded joint and actuator forces come from.
    pub reactions: Reactions,
    /// Newton's tolerance on q̈ and Φqᵀλ (relative and absolute) and on |Φ| (`None`: the
    /// integrator's defaults), as `generic::Options::newton_tolerance`.
    pub newton_tolerance: Option<f64>,
    /// Keep every output's full coordinates and velocities in [`Run::q`] and [`Run::qd`]
    /// (the HTML viewer draws from them); off, both stay empty. For the Stewart model they
    /// are 1.25 KB an output, three quarters of what a run records, and on this project's
    /// 2-core VM each fresh page costs about 2 µs to fault in: leaving them out took the
    /// kinematic path's printed time to 0.84 of what it was (30 alternated pairs,
    /// 2026-11-29).
    pub states: bool,
}

/// Source of the multipliers λ behind the recorded forces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reactions {
    /// The integrator's own λ. HHT-α satisfies the α-shifted equilibrium, and λ comes out
    /// of constraint rows scaled by 1/(βh²), so it carries an O(h) start-up transient and
    /// roundoff that grows like 1/h² as the step shrinks.
    Integrator,
    /// λ recomputed at each output from the saddle-point system
    /// `[M Φqᵀ; Φq 0][q̈; λ] = [Q; γ]` at the integrator's (q, q̇, t): the multipliers that
    /// belong to that state exactly, at the cost of one factorization per output.
    Recovered,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            formulation: Formulation::Exact,
            t_end: 2.0 * std::f64::consts::PI,
            step: 1e-3,
            tolerances: None,
            alpha: -0.05,
            output_step: 0.01,
            reactions: Reactions::Recovered,
            newton_tolerance: None,
            states: true,
        }
    }
}

/// The integrator settings of `opts`.
fn hht(opts: &Options) -> HhtBuilder {
    crate::generic::hht_builder(
        opts.alpha,
        opts.step,
        opts.tolerances,
        opts.newton_tolerance,
    )
}

/// Number of legs of the platform.
pub const LEGS: usize = 6;

/// Where the scenario's quantities live in the generated model, looked up by name.
#[derive(Debug, Clone, Copy)]
pub struct Layout {
    pub platform: usize,
    pub upper_joints: [usize; LEGS],
    pub lower_joints: [usize; LEGS],
    pub lower_bodies: [usize; LEGS],
    pub drivers: [usize; LEGS],
}

impl Layout {
    /// Finds the paper's names (`platform`, `upper_sph1..6`, `lower_sph1..6`, `lower1..6`,
    /// `act1..6`) in `info`, naming the first one missing.
    pub fn find(info: &MechanismInfo) -> Result<Layout, String> {
        let body = |n: &str| {
            info.body_index(n)
                .ok_or_else(|| format!("mechanism `{}` has no body `{n}`", info.name))
        };
        let joint = |n: &str| {
            info.joint_index(n)
                .ok_or_else(|| format!("mechanism `{}` has no joint `{n}`", info.name))
        };
        let mut l = Layout {
            platform: body("platform")?,
            upper_joints: [0; LEGS],
            lower_joints: [0; LEGS],
            lower_bodies: [0; LEGS],
            drivers: [0; LEGS],
        };
        for i in 0..LEGS {
            l.upper_joints[i] = joint(&format!("upper_sph{}", i + 1))?;
            l.lower_joints[i] = joint(&format!("lower_sph{}", i + 1))?;
            l.lower_bodies[i] = body(&format!("lower{}", i + 1))?;
            l.drivers[i] = joint(&format!("act{}", i + 1))?;
        }
        Ok(l)
    }
}

/// Recorded outputs of one run, one entry per output time.
#[derive(Debug, Clone, Default)]
pub struct Run {
    pub t: Vec<f64>,
    /// All coordinates and velocities at each output time (with [`Options::states`]).
    pub q: Vec<Vec<f64>>,
    pub qd: Vec<Vec<f64>>,
    /// Platform `[X, Y, Z, θ, β, γ]`.
    pub platform: Vec<[f64; 6]>,
    /// Force on the platform at each upper spherical joint (global frame, N).
    pub upper: Vec<[[f64; 3]; LEGS]>,
    /// Force on each lower leg (cylinder) at its base spherical joint (global frame, N);
    /// the force on the base plate is its negative.
    pub lower: Vec<[[f64; 3]; LEGS]>,
    /// Actuator forces (N), positive pushing the platform away from the base.
    pub actuators: Vec<[f64; LEGS]>,
    /// Kinetic plus potential energy (J).
    pub energy: Vec<f64>,
    /// Power of the actuators Σ Fᵢ ċᵢ (W): the only non-conservative input.
    pub actuator_power: Vec<f64>,
    /// Largest |Φ|∞ and |Φq q̇ + Φt|∞ seen at the output times.
    pub max_phi: f64,
    pub max_velocity_residual: f64,
    pub stats: Stats,
    /// The kinematic path's counters when the run was not integrated ([`kinematic`]).
    pub kinematic: Option<PathStats>,
    /// The coordinates followed when the kinematic path ran on the generated reduced model
    /// (recorded on the full one); `None`: the full model.
    pub reduced: Option<usize>,
    pub wall: Duration,
    /// First Euler-angle warning (time, body, β), if any body came near β = ±90°.
    pub euler_warning: Option<(f64, &'static str, f64)>,
}

/// Why a scenario could not run.
#[derive(Debug, Clone, PartialEq)]
pub enum ScenarioError {
    /// A solver failed (with time and residual).
    Runtime(Error),
    /// The mechanism lacks a body or joint the scenario needs.
    Layout(String),
    /// An option is out of range.
    Options(String),
    /// The caller stopped the run (Ctrl-C) at this simulated time.
    Interrupted { time: f64 },
    /// An output could not be written.
    Output(String),
}

impl std::fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ScenarioError::Runtime(e) => write!(f, "{e}"),
            ScenarioError::Layout(s) | ScenarioError::Options(s) | ScenarioError::Output(s) => {
                write!(f, "{s}")
            }
            ScenarioError::Interrupted { time } => write!(f, "interrupted at t = {time:.6} s"),
        }
    }
}

impl std::error::Error for ScenarioError {}

impl From<Error> for ScenarioError {
    fn from(e: Error) -> Self {
        ScenarioError::Runtime(e)
    }
}

/// The registered mechanism the paper's scenario runs on.
pub const MECHANISM: &str = "stewart_6_6";

/// The paper's platform in `registry`.
pub fn platform_entry(registry: &Registry) -> Result<&'static Entry, ScenarioError> {
    crate::generic::find(registry, MECHANISM)
}

/// The generated platform the scenario runs in formulation `f`.
pub fn platform(
    registry: &Registry,
    f: Formulation,
) -> Result<&'static (dyn Mechanism + Sync), ScenarioError> {
    crate::generic::mechanism(platform_entry(registry)?, Some(f))
}

/// The generated platform's sizes and names in formulation `f`.
pub fn mechanism_info(
    registry: &Registry,
    f: Formulation,
) -> Result<&'static MechanismInfo, ScenarioError> {
    Ok(platform(registry, f)?.info())
}

/// Runs the paper's scenario with `opts` on the platform in `registry`.
pub fn simulate(registry: &Registry, opts: &Options) -> Result<Run, ScenarioError> {
    simulate_mechanism(platform(registry, opts.formulation)?, opts)
}

/// The recorded joint forces of a [`Layout`], their Φq entries found once.
#[derive(Debug, Clone)]
struct Forces {
    /// By leg: on the platform at its upper joint, and on the lower leg at its base joint.
    upper: Vec<ForceOnBody>,
    lower: Vec<ForceOnBody>,
}

impl Forces {
    fn new(info: &MechanismInfo, l: &Layout) -> Result<Self, Error> {
        Ok(Forces {
            upper: (0..LEGS)
                .map(|i| ForceOnBody::new(info, l.upper_joints[i], l.platform))
                .collect::<Result<_, _>>()?,
            lower: (0..LEGS)
                .map(|i| ForceOnBody::new(info, l.lower_joints[i], l.lower_bodies[i]))
                .collect::<Result<_, _>>()?,
        })
    }
}

/// Runs any mechanism with the Stewart platform's names (see [`Layout::find`]). Once the
/// run has taken 2 ms, the integration moves to a thread of its own and the outputs are
/// recorded on this one.
pub fn simulate_mechanism<M: Mechanism + Sync>(
    mech: M,
    opts: &Options,
) -> Result<Run, ScenarioError> {
    let info = mech.info();
    let layout = Layout::find(info).map_err(ScenarioError::Layout)?;
    let n_out = output_count(opts.t_end, opts.output_step)?;
    let start = Instant::now();
    let it = hht(opts).build(&mech)?;
    let mut run = Run::with_capacity(n_out + 1, opts.states);
    let mut recorder = Recorder::new(info, layout, opts.states)?;
    // The platform's determinant sign is watched at the outputs: a pose that crossed a
    // parallel singularity between two outputs is on another assembly mode at the next.
    let modes = ModeWatch::new(&Platform::new(&mech)?, it.q(), SIMULATION_MAX_CONDITION)?;
    let integrator_lambda = opts.reactions == Reactions::Integrator;
    let advancing = Advancing {
        it,
        modes,
        integrator_lambda,
        grid: Grid::new(opts.output_step, opts.t_end, n_out),
    };
    let recording = |feed: &mut path_feed::Feed<'_, '_, Batched<Advancing<&M>>>| {
        while let Some(batch) = feed.next() {
            for out in batch.outputs() {
                let lambda = integrator_lambda.then_some(&out.lambda[..]);
                let state = (out.t, &out.q[..], &out.qd[..]);
                recorder.record_state(&mech, state, lambda, out.energy, &mut run)?;
            }
            feed.recycle(batch);
        }
        Ok::<(), ScenarioError>(())
    };
    let thread = Thread::After(crate::generic::INTEGRATION_ALONE);
    let (recorded, (stats, euler_warning, ended)) =
        path_feed::follow(Batched::new(advancing), thread, recording);
    recorded?;
    ended?;
    run.stats = stats;
    run.wall = start.elapsed();
    run.euler_warning = euler_warning.map(|w| (w.time, w.name, w.beta));
    Ok(run)
}

/// The paper scenario's integration, reaching each output in turn with the platform's
/// assembly mode checked there.
struct Advancing<M: Mechanism> {
    it: Integrator<M>,
    modes: ModeWatch,
    /// Whether the outputs carry the integrator's own multipliers (else they are recovered
    /// at each output when it is recorded).
    integrator_lambda: bool,
    grid: Grid,
}

/// One output of [`Advancing`].
#[derive(Default)]
struct Advanced {
    t: f64,
    q: Vec<f64>,
    qd: Vec<f64>,
    /// The integrator's multipliers where the run reports them, else empty.
    lambda: Vec<f64>,
    /// The integrator's kinetic plus potential energy.
    energy: f64,
}

impl<M: Mechanism> Outputting for Advancing<M> {
    type Item = Advanced;
    type End = (Stats, Option<EulerWarning>, Result<(), ScenarioError>);

    fn grid(&self) -> &Grid {
        &self.grid
    }

    fn advance(&mut self, out: &mut Advanced, deadline: Instant) -> Result<bool, ScenarioError> {
        if !reach(&mut self.it, &mut self.grid, deadline, |_| Ok(()))? {
            return Ok(false);
        }
        self.modes.check(self.it.q(), self.it.t())?;
        out.t = self.it.t();
        self.it.q().clone_into(&mut out.q);
        self.it.qd().clone_into(&mut out.qd);
        if self.integrator_lambda {
            self.it.lambda().clone_into(&mut out.lambda);
        }
        out.energy = self.it.energy();
        Ok(true)
    }

    fn reached(&self) -> (f64, usize) {
        (self.it.t(), self.it.stats().steps)
    }

    fn end(self, ended: Result<(), ScenarioError>) -> Self::End {
        (self.it.stats(), self.it.first_euler_warning(), ended)
    }
}

/// The paper's scenario by the kinematic path (docs/design.md, decision 23): no integration;
/// at each output time the pose from the drivers, the velocity of least kinetic energy (the
/// legs' idle spins carry no momentum, see `symbody::scene::choose_path`) and the
/// accelerations and multipliers of the saddle-point system. `opts.step`, `alpha` and
/// `reactions` do not apply: the multipliers are the saddle-point ones.
pub fn kinematic(registry: &Registry, opts: &Options) -> Result<Run, ScenarioError> {
    kinematic_mechanism(platform(registry, opts.formulation)?, opts)
}

/// [`kinematic`] for any mechanism with the Stewart platform's names. The path's solves run
/// on this thread; the outputs' reactions, residuals and assembly-mode watch on a second one
/// ([`path_feed::record_beside`]), a batch of outputs behind, so on two cores the recording
/// takes no wall time. Errors come in time order: a recorded output's before a later
/// solve's.
pub fn kinematic_mechanism<M: Mechanism + Sync>(
    mech: M,
    opts: &Options,
) -> Result<Run, ScenarioError> {
    kinematic_until(mech, None, opts, &AtomicBool::new(false))
}

/// A generated reduced model of a mechanism and the way back to the full one.
pub type Reduced = (&'static (dyn Mechanism + Sync), &'static Reduction);

/// [`kinematic_mechanism`], on `reduced` when given (the path follows the reduced model;
/// the recording thread reads each output in the full model's terms, multipliers of the
/// eliminated rows included, and records it there), given up with
/// [`ScenarioError::Interrupted`] at the first output after `stop` is set: a run started
/// before it is known whether it is wanted.
pub fn kinematic_until<M: Mechanism + Sync>(
    mech: M,
    reduced: Option<Reduced>,
    opts: &Options,
    stop: &AtomicBool,
) -> Result<Run, ScenarioError> {
    kinematic_beside(mech, reduced, opts, stop, || ()).0
}

/// [`kinematic_until`], with `beside` run on the recording thread before it records: work
/// that would otherwise need a third thread beside the path (the scene's choice of path,
/// which may set `stop`). The path starts at once; the recorder, faster than the path,
/// catches up. Returns the run and what `beside` returned.
pub fn kinematic_beside<M: Mechanism + Sync, R: Send>(
    mech: M,
    reduced: Option<Reduced>,
    opts: &Options,
    stop: &AtomicBool,
    beside: impl FnOnce() -> R + Send,
) -> (Result<Run, ScenarioError>, R) {
    let mut beside = Some(beside);
    let mut done = None;
    let run = kinematic_run(mech, reduced, opts, stop, &mut || {
        if let Some(b) = beside.take() {
            done = Some(b());
        }
    });
    // `beside` ran unless the run failed before its recording thread started.
    let done = done.unwrap_or_else(|| (beside.take().expect("beside runs once"))());
    (run, done)
}

fn kinematic_run<M: Mechanism + Sync>(
    mech: M,
    reduced: Option<Reduced>,
    opts: &Options,
    stop: &AtomicBool,
    beside: &mut (dyn FnMut() + Send),
) -> Result<Run, ScenarioError> {
    let info = mech.info();
    let layout = Layout::find(info).map_err(ScenarioError::Layout)?;
    let n_out = output_count(opts.t_end, opts.output_step)?;
    let start = Instant::now();
    let followed: &(dyn Mechanism + Sync) = reduced.map_or(&mech, |(r, _)| r);
    let path = KinematicPath::new(followed, 0.0)?;
    let q0 = match reduced {
        Some((_, reduction)) => {
            let mut q = vec![0.0; info.n_coords];
            reduction.expand(path.q(), path.t(), 0, &mut q)?;
            q
        }
        None => path.q().to_vec(),
    };
    let times = (1..=n_out)
        .map(|k| (k as f64 * opts.output_step).min(opts.t_end))
        .collect();
    let mech = &mech;
    let recording = move |feed: &mut path_feed::Feed<'_, '_, path_feed::Solver<'_, _>>| -> Result<Run, ScenarioError> {
        // Set up while the path starts.
        let mut reading = match reduced {
            Some((_, reduction)) => Some(FullState::new(reduction, info)?),
            None => None,
        };
        let modes = ModeWatch::new(&Platform::new(mech)?, &q0, SIMULATION_MAX_CONDITION)?;
        let forces = Forces::new(info, &layout)?;
        // Φq q̇ + Φt.
        let mut velocity = vec![0.0; info.n_constraints];
        beside();
        let mut run = Run::with_capacity(n_out + 1, opts.states);
        while let Some(batch) = feed.next() {
            for k in 0..batch.len() {
                let state = batch.state(k);
                if stop.load(Ordering::Relaxed) {
                    return Err(ScenarioError::Interrupted { time: state.t });
                }
                let out = match &mut reading {
                    None => Output::solved(&state, mech, &mut velocity),
                    Some(full) => Output::read(&state, mech, full)?,
                };
                modes.check(out.q, out.t)?;
                record((layout, &forces), info, out, opts.states, &mut run)?;
            }
            feed.recycle(batch);
        }
        Ok(run)
    };
    let solver = path_feed::Solver::new(path, times, reduced.is_none(), Some(stop));
    let (run, (stats, followed)) = path_feed::record_beside(solver, recording);
    let mut run = run?;
    followed?;
    // A path stopped before its end.
    if run.t.len() < n_out + 1 {
        return Err(ScenarioError::Interrupted {
            time: run.t.last().copied().unwrap_or(0.0),
        });
    }
    run.kinematic = Some(stats);
    run.reduced = reduced.map(|(r, _)| r.info().n_coords);
    run.wall = start.elapsed();
    Ok(run)
}

impl<'a> Output<'a> {
    /// A state solved on the full model, with its velocity residual (computed into `work`).
    fn solved<M: Mechanism + ?Sized>(state: &State<'a>, mech: &M, work: &mut [f64]) -> Self {
        let (qd, phi_q, phi_t) = (state.qd, state.phi_q, state.phi_t);
        Output {
            t: state.t,
            q: state.q,
            qd,
            lambda: state.lambda,
            phi_q,
            phi_t,
            residuals: Residuals {
                position: state.position_residual,
                velocity: velocity_residual(mech.info(), phi_q, phi_t, qd, work),
            },
            energy: kinetic_energy(mech.info(), state.mass, qd) + mech.potential(state.q),
        }
    }

    /// A state solved on a reduced model, read in `full`'s terms by `reading`.
    fn read<M: Mechanism + ?Sized>(
        state: &State<'_>,
        full: &M,
        reading: &'a mut FullState,
    ) -> Result<Self, Error> {
        let t = state.t;
        reading.read(full, t, state.q, state.qd, state.qdd, state.lambda)?;
        let residuals = reading.residuals(state.position_residual);
        let energy = reading.energy(full);
        let r = &*reading;
        Ok(Output {
            t,
            q: &r.q,
            qd: &r.qd,
            lambda: &r.lambda,
            phi_q: &r.phi_q,
            phi_t: &r.phi_t,
            residuals,
            energy,
        })
    }
}

/// The paper's scenario integrated on the reduced model (`stewart_6_6::reduced`: the 18
/// Euler-angle equalities substituted away, 60 coordinates and 54 rows): HHT on the reduced
/// mechanism, each output expanded to the full state and recorded on the full model, with
/// forces recovered there (`opts.reactions` is ignored).
pub fn simulate_reduced(registry: &Registry, opts: &Options) -> Result<Run, ScenarioError> {
    let entry = platform_entry(registry)?;
    let full = crate::generic::mechanism(entry, Some(opts.formulation))?;
    let (red, reduction) = entry.reduced(opts.formulation).ok_or_else(|| {
        ScenarioError::Options(format!(
            "`{MECHANISM}` has no reduced model in the {} formulation",
            opts.formulation.name()
        ))
    })?;
    let info = full.info();
    let layout = Layout::find(info).map_err(ScenarioError::Layout)?;
    let n_out = output_count(opts.t_end, opts.output_step)?;
    let start = Instant::now();
    let mut it = hht(opts).build(red)?;
    let mut run = Run::with_capacity(n_out + 1, opts.states);
    let mut recorder = Recorder::new(info, layout, opts.states)?;
    let (mut q, mut qd) = (vec![0.0; info.n_coords], vec![0.0; info.n_coords]);
    let mut offsets = vec![0.0; 3 * reduction.substitutions.len()];
    for k in 0..=n_out {
        let t_out = (k as f64 * opts.output_step).min(opts.t_end);
        it.advance_to(t_out)?;
        let reduced_state = (it.q(), it.qd());
        reduction.expand_state(reduced_state, it.t(), &mut offsets, (&mut q, &mut qd))?;
        let state = (it.t(), &q[..], &qd[..]);
        recorder.record_state(&full, state, None, it.energy(), &mut run)?;
    }
    run.stats = it.stats();
    run.wall = start.elapsed();
    Ok(run)
}

/// One output as recorded: the state, its multipliers, Φq's nonzeros and Φt there, the
/// constraint drift and the energy.
struct Output<'a> {
    t: f64,
    q: &'a [f64],
    qd: &'a [f64],
    lambda: &'a [f64],
    phi_q: &'a [f64],
    phi_t: &'a [f64],
    residuals: Residuals,
    /// Kinetic plus potential energy (J).
    energy: f64,
}

/// Number of output intervals of `t_end` at `output_step` (outputs at 0, Δ, …, t_end),
/// after checking both.
pub fn output_count(t_end: f64, output_step: f64) -> Result<usize, ScenarioError> {
    if !(output_step.is_finite() && output_step > 0.0) {
        return Err(ScenarioError::Options(format!(
            "--output-step must be positive and finite, got {output_step}"
        )));
    }
    if !(t_end.is_finite() && t_end >= 0.0) {
        return Err(ScenarioError::Options(format!(
            "--t-end must be finite and zero or positive, got {t_end}"
        )));
    }
    // Every output is kept in memory; beyond this the run would exhaust it, not finish.
    const MAX_OUTPUTS: f64 = 1e7;
    if t_end / output_step > MAX_OUTPUTS {
        return Err(ScenarioError::Options(format!(
            "{t_end} s every {output_step:e} s is more than {MAX_OUTPUTS:e} outputs: raise --output-step"
        )));
    }
    Ok((t_end / output_step - 1e-9).ceil().max(0.0) as usize)
}

/// Work memory for recording integrated outputs, allocated once per run.
struct Recorder {
    layout: Layout,
    forces: Forces,
    /// For states integrated: residuals and Jacobians, and multipliers recovered at the
    /// state (made on first use).
    watch: ResidualWatch,
    kinematics: Option<Kinematics>,
    qdd: Vec<f64>,
    lambda: Vec<f64>,
    /// [`Options::states`].
    states: bool,
}

impl Recorder {
    fn new(info: &'static MechanismInfo, layout: Layout, states: bool) -> Result<Self, Error> {
        Ok(Recorder {
            layout,
            states,
            forces: Forces::new(info, &layout)?,
            watch: ResidualWatch::new(info),
            kinematics: None,
            qdd: vec![0.0; info.n_coords],
            lambda: vec![0.0; info.n_constraints],
        })
    }

    /// Records an integrated state `(t, q, q̇)`: residuals and Jacobians evaluated there, the
    /// integrator's multipliers `lambda` or (`None`) those of the saddle-point system at
    /// the state.
    fn record_state<M: Mechanism>(
        &mut self,
        mech: &M,
        (t, q, qd): (f64, &[f64], &[f64]),
        lambda: Option<&[f64]>,
        energy: f64,
        run: &mut Run,
    ) -> Result<(), Error> {
        let info = mech.info();
        let residuals = self.watch.check(mech, t, q, qd)?;
        let lambda = match lambda {
            Some(l) => l,
            None => {
                let kinematics = match &mut self.kinematics {
                    Some(k) => k,
                    empty => empty.insert(Kinematics::new(info)?),
                };
                kinematics.acceleration(mech, t, q, qd, &mut self.qdd, &mut self.lambda)?;
                &self.lambda
            }
        };
        let out = Output {
            t,
            q,
            qd,
            lambda,
            phi_q: self.watch.phi_q(),
            phi_t: self.watch.phi_t(),
            residuals,
            energy,
        };
        record((self.layout, &self.forces), info, out, self.states, run)
    }
}

/// Appends one output's pose, joint forces, actuator forces and power, energy and drift.
fn record(
    (layout, forces): (Layout, &Forces),
    info: &MechanismInfo,
    out: Output<'_>,
    states: bool,
    run: &mut Run,
) -> Result<(), Error> {
    let Output {
        t,
        q,
        qd,
        lambda,
        phi_q,
        phi_t,
        residuals,
        energy,
    } = out;
    run.max_phi = run.max_phi.max(residuals.position);
    run.max_velocity_residual = run.max_velocity_residual.max(residuals.velocity);
    // Φ_D = d(q) − c(t), so each driver's ċ = −Φt on its row.
    let c_dot: [f64; LEGS] =
        std::array::from_fn(|i| -phi_t[info.joints[layout.drivers[i]].row_start]);
    let o = info.bodies[layout.platform].coord_offset;
    run.platform
        .push([q[o], q[o + 1], q[o + 2], q[o + 3], q[o + 4], q[o + 5]]);
    let mut upper = [[0.0; 3]; LEGS];
    let mut lower = [[0.0; 3]; LEGS];
    let mut act = [0.0; LEGS];
    let mut power = 0.0;
    for i in 0..LEGS {
        upper[i] = forces.upper[i].force(phi_q, lambda)?;
        lower[i] = forces.lower[i].force(phi_q, lambda)?;
        act[i] = actuator_force(info, lambda, layout.drivers[i])?;
        power += act[i] * c_dot[i];
    }
    run.upper.push(upper);
    run.lower.push(lower);
    run.actuators.push(act);
    run.actuator_power.push(power);
    run.energy.push(energy);
    run.t.push(t);
    if states {
        run.q.push(q.to_vec());
        run.qd.push(qd.to_vec());
    }
    Ok(())
}

impl Run {
    /// An empty run with room for `n` outputs (and their states, with `states`), taken at
    /// once instead of by doubling as they come (each doubling copies what was recorded and
    /// touches fresh pages).
    fn with_capacity(n: usize, states: bool) -> Self {
        let room = if states { n } else { 0 };
        Run {
            t: Vec::with_capacity(n),
            q: Vec::with_capacity(room),
            qd: Vec::with_capacity(room),
            platform: Vec::with_capacity(n),
            upper: Vec::with_capacity(n),
            lower: Vec::with_capacity(n),
            actuators: Vec::with_capacity(n),
            energy: Vec::with_capacity(n),
            actuator_power: Vec::with_capacity(n),
            ..Run::default()
        }
    }

    /// Work done by the actuators from the first output to each output (J), by the
    /// trapezoidal rule over the recorded power.
    pub fn actuator_work(&self) -> Vec<f64> {
        let mut w = vec![0.0; self.t.len()];
        for k in 1..self.t.len() {
            let dt = self.t[k] - self.t[k - 1];
            w[k] = w[k - 1] + 0.5 * dt * (self.actuator_power[k] + self.actuator_power[k - 1]);
        }
        w
    }

    /// Largest |self − reference| of the quantity `of` picks at each output, and the time
    /// where it occurs. Both runs must have the same output times.
    pub fn max_difference(
        &self,
        reference: &Run,
        of: impl Fn(&Run, usize) -> &[f64],
    ) -> Result<(f64, f64), String> {
        if self.t.len() != reference.t.len() {
            return Err(format!(
                "{} outputs against the reference's {}",
                self.t.len(),
                reference.t.len()
            ));
        }
        let mut worst = (0.0f64, 0.0);
        for k in 0..self.t.len() {
            if (self.t[k] - reference.t[k]).abs() > 1e-12 {
                return Err(format!(
                    "output {k} at t = {} against {}",
                    self.t[k], reference.t[k]
                ));
            }
            for (a, b) in of(self, k).iter().zip(of(reference, k)) {
                if (a - b).abs() > worst.0 {
                    worst = ((a - b).abs(), self.t[k]);
                }
            }
        }
        Ok(worst)
    }

    /// Range of platform coordinate `k` over the run.
    pub fn platform_range(&self, k: usize) -> (f64, f64) {
        self.platform
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p[k]), hi.max(p[k]))
            })
    }
}

/// The largest |θ|, |β|, |γ| of the platform over the run, with the axis name.
pub fn largest_rotation(run: &Run) -> (&'static str, f64) {
    let names = ["theta (about X)", "beta (about Y)", "gamma (about Z)"];
    (0..3)
        .map(|k| {
            let m = run
                .platform
                .iter()
                .fold(0.0f64, |a, p| a.max(p[3 + k].abs()));
            (names[k], m)
        })
        .fold(("none", 0.0), |best, c| if c.1 > best.1 { c } else { best })
}
