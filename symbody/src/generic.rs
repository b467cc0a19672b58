//! Any registered mechanism, simulated: consistent start, HHT-α with velocity projection,
//! and at every output the body poses, every joint's reaction wrench, the driver efforts and
//! the energy balance. Nothing here knows a particular mechanism.

pub use symbody_codegen::diag::closest;

use crate::path_feed::{self, State, Thread};
use crate::scenario::{output_count, Reduced, ScenarioError};
use crate::stepper::{Batched, OutputSolve, Stepper};
use std::ops::ControlFlow;
use std::time::{Duration, Instant};
use symbody_runtime::fk::{ModeWatch, Platform, SIMULATION_MAX_CONDITION};
use symbody_runtime::kinematics::kinetic_energy;
use symbody_runtime::kkt::DEFAULT_PIVOT_TOLERANCE;
use symbody_runtime::{
    body_pose, driver_effort, velocity_residual, EnergySample, Entry, EulerWarning, Formulation,
    FullState, HhtBuilder, Integrator, JointKind, JointWrenches, KinematicPath, KinematicSettings,
    Mechanism, MechanismInfo, PathStats, Pivots, Registry, Residuals, Rotation, Stats, Wrench,
};
use symbody_runtime::{energy, quadrature};

/// Why a run could not be made: an option out of range or not available for the mechanism
/// (naming it), or a solver failure (with time and residual). The paper scenario's error
/// type, so both paths report alike.
pub type Error = ScenarioError;

/// Options of one run; `None` takes the mechanism's own default.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// Formulation (default: the first the file lists).
    pub formulation: Option<Formulation>,
    /// End time (default: the file's `t_end`).
    pub t_end: Option<f64>,
    /// Nominal HHT step (s); with `tolerances`, the first step the control tries.
    pub step: f64,
    /// Step-size control `(rtol, atol)` on positions and velocities
    /// ([`HhtBuilder::tolerances`]); `None`: the fixed `step`.
    pub tolerances: Option<(f64, f64)>,
    /// HHT α in [−1/3, 0].
    pub alpha: f64,
    /// Spacing of the recorded outputs (s).
    pub output_step: f64,
    /// Let the integrator pass positions where constraint rows are dependent for an
    /// instant (a linkage lying flat, IFToMM A02): a step that lands on one drops the rows
    /// whose pivot vanished instead of failing (`HhtBuilder::drop_dependent_rows`); every
    /// row must still hold. Off by default, so that rank loss is reported.
    pub cross_singular: bool,
    /// Tolerance of each step's Newton solve: on the increments of q̈ and Φqᵀλ (relative and
    /// absolute) and on |Φ|∞ (`None`: the integrator's defaults, 1e-6 and 1e-10). Tighter
    /// makes a run a smooth function of its parameters, as differencing whole runs needs.
    pub newton_tolerance: Option<f64>,
    /// Integrate (or follow by the kinematic path) the mechanism's reduced model where the
    /// generator emitted one (rows qᵢ − qⱼ − c(t) substituted away, docs/design.md decision
    /// 24), read back in the full model's terms at every step or output: the same motion and
    /// forces with fewer coordinates. Without a reduced model the full one is run.
    pub reduce: bool,
    /// The path runs on a thread of its own beside the recording ([`crate::path_feed`]):
    /// an integration once it has run 2 ms, a kinematic path where its model is large
    /// enough to gain from it. Off where the caller already keeps every core busy (a study's
    /// rows), as a second thread per run would only take turns with the others.
    pub path_thread: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            formulation: None,
            t_end: None,
            step: 1e-3,
            tolerances: None,
            // α = 0 with velocity projection (see `run`): measured on the conical quaternion
            // pendulum over 60 s at h = 1 ms, the energy error is 4e-8 J, against 1e-3 J with
            // α = −0.05 (HHT's α-term turns the constraint forces with the bodies and makes
            // the error first order in h) and a blow-up after ~9 s at α = 0 without
            // projection (the velocity residual of eᵀe = 1 grows unchecked).
            alpha: 0.0,
            output_step: 0.01,
            cross_singular: false,
            newton_tolerance: None,
            reduce: false,
            path_thread: true,
        }
    }
}

/// The recorded time series of one run. Every `Vec` indexed by output has one entry per
/// output time `t[k]` (0, Δ, 2Δ, …, t_end).
#[derive(Debug, Clone)]
pub struct Recording {
    /// The simulated mechanism (names of bodies, joints, rows; the formulation run).
    pub info: &'static MechanismInfo,
    /// Output times (s).
    pub t: Vec<f64>,
    /// Per output: all coordinates (`info.coord_names`).
    pub q: Vec<Vec<f64>>,
    /// Per output: all velocities, projected onto the velocity constraints.
    pub qd: Vec<Vec<f64>>,
    /// Bodies (indices in `info.bodies`) written to `bodies.csv`: all unless a scene asks
    /// for fewer.
    pub bodies: Vec<usize>,
    /// Whether `bodies.csv` also has each body's velocities (`.vx,.vy,.vz` of the centre of
    /// mass, `.wx,.wy,.wz` angular, global frame): opt-in, since most uses want poses only.
    pub velocities: bool,
    /// Whether `bodies.csv` also has each body's accelerations (`.ax,.ay,.az` of the centre
    /// of mass, `.alphax,.alphay,.alphaz` angular, global frame); `qdd` is then recorded.
    pub accelerations: bool,
    /// Per output, with `accelerations`: all accelerations, from the saddle-point solve at
    /// the output state (empty otherwise).
    pub qdd: Vec<Vec<f64>>,
    /// Per output, per body (`info.bodies` order, every body): centre of mass (m) and unit quaternion
    /// `[w, x, y, z]` with `w ≥ 0` ([`body_pose`]), whatever the body's coordinates.
    pub poses: Vec<Vec<([f64; 3], [f64; 4])>>,
    /// Indices (in `info.joints`) of the joints whose wrenches are recorded: every joint
    /// except drivers and normalization rows.
    pub joints: Vec<usize>,
    /// Per output, per recorded joint (`joints` order): the wrench the joint exerts on its
    /// first body, global frame, moment about the joint point
    /// ([`symbody_runtime::joint_wrench`]; on the ground when body 1 is the ground), from the
    /// multipliers of the saddle-point solve at that output state.
    pub wrenches: Vec<Vec<Wrench>>,
    /// The wrenches' work memory, made for `joints` at the first output (a scene may
    /// narrow `joints` before).
    reactions: Option<JointWrenches>,
    /// Indices (in `info.joints`) of the drivers.
    pub drivers: Vec<usize>,
    /// Per output, per driver (`drivers` order): its effort ([`driver_effort`]), the force
    /// (N) or torque (N·m, `JointInfo::effort_unit`) on the driven body along the driven
    /// coordinate, positive in the direction the coordinate increases.
    pub efforts: Vec<Vec<f64>>,
    /// Per output: kinetic and potential energy, and the work of drivers and
    /// non-conservative loads since t = 0, integrated by [`EnergyMeter`] from its samples
    /// after every integration step.
    pub energy: Vec<EnergySample>,
    /// Whether `energy.csv` is written (the samples are kept for the summary either way).
    pub energy_table: bool,
    /// Whether the samples' `work` was integrated (NaN where not), and so the energy
    /// balance: always when the run integrates; on the kinematic path only with
    /// `energy_table`, as its quadrature solves the path at two more times per output.
    pub work_integrated: bool,
    /// The integrator's counters over the run (zero on the kinematic path).
    pub stats: Stats,
    /// The kinematic path's counters when the run was not integrated ([`run_kinematic`]).
    pub kinematic: Option<PathStats>,
    /// The coordinates integrated when the run integrated the reduced model
    /// ([`Options::reduce`]); `None`: the full model.
    pub reduced: Option<usize>,
    /// Largest |Φ|∞ at the outputs.
    pub max_phi: f64,
    /// Largest |Φq q̇ + Φt|∞ at the outputs.
    pub max_velocity_residual: f64,
    /// Largest |eᵀe − 1| over quaternion bodies and outputs (0 without quaternion bodies).
    pub max_norm_error: f64,
    /// The first Euler-angle body that came near β = ±90°, if any.
    pub euler_warning: Option<EulerWarning>,
    /// Per output: how well the constraint rows determined the multipliers there (see
    /// [`Recording::ill_conditioned`]).
    pub pivots: Vec<Pivots>,
    /// Wall time of the run (integration and recording, not writing).
    pub wall: Duration,
}

/// Below this smallest relative pivot ([`Pivots::smallest`]) an output's multipliers count
/// as ill-conditioned: the rows are near a singular position, and the errors of the state
/// (the integrator's, not only roundoff) reach λ amplified by about 1/pivot. The pivot does
/// not depend on the rotation coordinates (a quaternion model and its Euler-angle model give
/// the same, `tests/singular_positions.rs`). Measured over 5 s of every shipped mechanism at
/// outputs every 10 ms: regular states stay at or above 1.3e-3, except the flyball
/// governor's, at 1.05e-5 … 1.7e-5 throughout (a margin of 5 % over this bound); the
/// N-four-bar between its flat positions falls to 3e-4, and at outputs within 0.5 ms of a
/// flat position to 4e-7 … 4e-6.
pub const ILL_CONDITIONED_PIVOT: f64 = 1e-5;

/// Above this share of the energy scale, the energy balance of a run says its steps were too
/// long for the motion ([`Recording::energy_warning`]). Measured over 1 s of each shipped
/// mechanism at the defaults: at most 3.7e-6 (the pendulum); A03 (`andrews_squeezer`, time
/// scale ~1e-5 s) at the default 1 ms step is off by 7 % after its 0.05 s.
pub const ENERGY_WARNING: f64 = 1e-2;

/// A run of consecutive outputs whose reactions are ill-conditioned (near a singular
/// position) or not unique (rows dropped at it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IllConditioned {
    /// First and last output time of the window (s).
    pub from: f64,
    pub to: f64,
    /// Outputs in the window.
    pub outputs: usize,
    /// The smallest relative pivot in the window, and where.
    pub smallest: f64,
    pub at: f64,
    /// Outputs at which rows were dropped as dependent.
    pub dropped: usize,
}

impl Recording {
    /// The windows of outputs whose smallest pivot is below [`ILL_CONDITIONED_PIVOT`] or
    /// at which rows were dropped, in time order.
    pub fn ill_conditioned(&self) -> Vec<IllConditioned> {
        let mut windows: Vec<IllConditioned> = Vec::new();
        let mut open = false;
        for (&t, p) in self.t.iter().zip(&self.pivots) {
            if !(p.dropped > 0 || p.smallest < ILL_CONDITIONED_PIVOT) {
                open = false;
                continue;
            }
            match windows.last_mut() {
                Some(w) if open => {
                    w.to = t;
                    w.outputs += 1;
                    w.dropped += usize::from(p.dropped > 0);
                    if p.smallest < w.smallest {
                        (w.smallest, w.at) = (p.smallest, t);
                    }
                }
                _ => windows.push(IllConditioned {
                    from: t,
                    to: t,
                    outputs: 1,
                    smallest: p.smallest,
                    at: t,
                    dropped: usize::from(p.dropped > 0),
                }),
            }
            open = true;
        }
        windows
    }

    /// The warning a summary must give when the energy balance is off by more than
    /// [`ENERGY_WARNING`] of the energy scale (the steps were too long for the motion),
    /// naming the caller's settings for the step and for step-size control.
    pub fn energy_warning(&self, step: &str, rtol: &str) -> Option<String> {
        let (drift, scale) = self.energy_balance()?;
        (scale > 0.0 && drift > ENERGY_WARNING * scale).then(|| {
            format!(
                "the energy balance is off by {:.1}% of the energy scale: the steps are too long for this motion, and the results are not to be trusted; run again with a shorter {step}, or with {rtol} (step-size control)",
                100.0 * drift / scale
            )
        })
    }

    /// Largest |ΔT + ΔV − W| since the start, and the energy scale max(|T| + |V|); `None`
    /// where the work was not integrated ([`Recording::work_integrated`]).
    pub fn energy_balance(&self) -> Option<(f64, f64)> {
        if !self.work_integrated {
            return None;
        }
        let b0 = self.energy.first().map_or(0.0, EnergySample::balance);
        Some(self.energy.iter().fold((0.0f64, 0.0f64), |(d, s), e| {
            (
                d.max((e.balance() - b0).abs()),
                s.max(e.kinetic.abs() + e.potential.abs()),
            )
        }))
    }
}

/// The mechanism `name`: a path to a mechanism file (ending in `.toml`, or with a folder),
/// interpreted ([`crate::files`]); else the entry of `registry` called so (interpreted from
/// its file instead when that changed since its code was generated), or an error listing the
/// known ones (with the closest as a suggestion).
pub fn find(registry: &Registry, name: &str) -> Result<&'static Entry, Error> {
    if crate::files::is_path(name) {
        return crate::files::load(std::path::Path::new(name)).map(|l| l.entry);
    }
    let Some(entry) = registry.find(name) else {
        let known = registry.names();
        let close = closest(name, known.iter().copied())
            .map(|k| format!(" (did you mean `{k}`?)"))
            .unwrap_or_default();
        return Err(ScenarioError::Options(format!(
            "no mechanism `{name}`{close}; known: {}. Or give the path of a mechanism file \
             (e.g. {name}.toml): it runs interpreted, nothing to build",
            known.join(", ")
        )));
    };
    crate::files::fresh(entry)
}

/// The mechanism of `entry` in formulation `f` (or its default), with an error naming the
/// generated ones.
pub fn mechanism(
    entry: &Entry,
    f: Option<Formulation>,
) -> Result<&'static (dyn Mechanism + Sync), Error> {
    match f {
        None => Ok(entry.default_mechanism()),
        Some(f) => entry.mechanism(f).ok_or_else(|| {
            let have: Vec<&str> = entry.formulations.iter().map(|(g, _)| g.name()).collect();
            ScenarioError::Options(format!(
                "`{}` was generated in the {} formulation(s) only, not `{}`; add it to the file's `formulations` and regenerate",
                entry.name,
                have.join(", "),
                f.name()
            ))
        }),
    }
}

/// What a caller sees of a run while it goes: each output as soon as it is recorded (to
/// write it before the run goes on) and the progress as the run goes; either may stop the
/// run. `()` watches nothing. Its calls all come on the caller's thread, even where the
/// path runs on another (so it needs no `Send`).
pub trait Observer {
    /// Once, before the first output, with the empty recording: a caller may narrow what
    /// it records (`bodies`, `joints`, `drivers`, `energy_table`) and open its files.
    fn start(&mut self, rec: &mut Recording) -> Result<(), Error> {
        let _ = rec;
        Ok(())
    }

    /// After each output is recorded (the last entry of every per-output `Vec`).
    fn output(&mut self, rec: &Recording) -> Result<(), Error> {
        let _ = rec;
        Ok(())
    }

    /// As the run goes, after each batch of outputs and at least every few tenths of a
    /// second: the time `t` reached and the `steps` taken (the kinematic path: the states
    /// solved). `Break` stops the run with [`ScenarioError::Interrupted`].
    fn progress(&mut self, t: f64, steps: usize) -> ControlFlow<()> {
        let _ = (t, steps);
        ControlFlow::Continue(())
    }
}

impl Observer for () {}

/// An observer that first narrows or extends what is recorded (`prepare`, on the empty
/// recording at the start), then passes everything on to `inner`.
pub struct Prepared<'a, F: FnMut(&mut Recording)> {
    pub prepare: F,
    pub inner: &'a mut dyn Observer,
}

impl<F: FnMut(&mut Recording)> Observer for Prepared<'_, F> {
    fn start(&mut self, rec: &mut Recording) -> Result<(), Error> {
        (self.prepare)(rec);
        self.inner.start(rec)
    }
    fn output(&mut self, rec: &Recording) -> Result<(), Error> {
        self.inner.output(rec)
    }
    fn progress(&mut self, t: f64, steps: usize) -> ControlFlow<()> {
        self.inner.progress(t, steps)
    }
}

/// A run that stopped before its end: the outputs it recorded up to its last good state
/// (`None` if it stopped before it had a mechanism), and why it stopped.
#[derive(Debug)]
pub struct Stopped {
    pub recording: Option<Box<Recording>>,
    pub error: Error,
}

impl From<Error> for Stopped {
    fn from(error: Error) -> Self {
        Stopped {
            recording: None,
            error,
        }
    }
}

/// Simulates `entry` with `opts`: what `symbody simulate <name>` runs before writing.
///
/// The integrator projects the velocities onto the constraints after every step, and the
/// energy meter integrates the power after every step, so the work of drivers and
/// non-conservative loads is integrated at the integration step (without a saddle-point
/// solve between outputs where no row depends on time: [`EnergyMeter::advance`]).
/// Reactions come from the multipliers of the saddle-point solve at each output state.
pub fn run(entry: &Entry, opts: &Options) -> Result<Recording, Error> {
    run_observed(entry, opts, &mut ()).map_err(|s| s.error)
}

/// [`run`], telling `obs` as it goes; a run that fails or is stopped returns what it
/// recorded.
pub fn run_observed(
    entry: &Entry,
    opts: &Options,
    obs: &mut dyn Observer,
) -> Result<Recording, Stopped> {
    observed(entry, opts, obs, integrate)
}

/// `entry`'s generated reduced model of `mech`'s formulation when `reduce` asks for it and
/// there is one ([`Options::reduce`]).
pub fn reduced_model(
    entry: &Entry,
    mech: &'static (dyn Mechanism + Sync),
    reduce: bool,
) -> Option<Reduced> {
    reduce
        .then(|| entry.reduced(mech.info().formulation))
        .flatten()
}

/// An error unless `entry` has a generated reduced model in formulation `f` (its default):
/// for an explicit request (`--reduced`), where [`Options::reduce`] alone falls back to the
/// full model.
pub fn require_reduced(entry: &Entry, f: Option<Formulation>) -> Result<(), Error> {
    let mech = mechanism(entry, f)?;
    if entry.reduced(mech.info().formulation).is_some() {
        return Ok(());
    }
    Err(ScenarioError::Options(match entry.origin {
        symbody_runtime::Origin::Interpreted { .. } => format!(
            "`{}` runs interpreted, which has no reduced model: generate its code \
             (`cargo xtask generate`) for the planar or substituted model",
            entry.name
        ),
        symbody_runtime::Origin::Compiled { parameters, .. } if !parameters.is_empty() => format!(
            "`{}` with parameters set runs its full model: the reduced model holds the file's \
             values (run it without the reduced model, or at the file's values)",
            entry.name
        ),
        symbody_runtime::Origin::Compiled { .. } => format!(
            "`{}` has no reduced model: its file is not planar (`planar = true`, \
             docs/mechanism-files.md) and has no row a·qᵢ + b·qⱼ + g(t) = 0 to substitute",
            entry.name
        ),
    }))
}

/// The loop of a run: outputs at `k · output_step` (k = 0..=n_out) up to `t_end`.
type Loop = fn(
    (&'static (dyn Mechanism + Sync), Option<Reduced>),
    &Options,
    (f64, usize),
    &mut Recording,
    &mut dyn Observer,
) -> Result<(), Error>;

/// Runs `body` on a fresh recording that `obs` has seen start, timing it.
fn observed(
    entry: &Entry,
    opts: &Options,
    obs: &mut dyn Observer,
    body: Loop,
) -> Result<Recording, Stopped> {
    let mech = mechanism(entry, opts.formulation)?;
    let t_end = opts.t_end.unwrap_or(entry.t_end);
    let n_out = output_count(t_end, opts.output_step)?;
    let mut rec = Recording::new(mech.info());
    let reduced = reduced_model(entry, mech, opts.reduce);
    rec.reduced = reduced.map(|(r, _)| r.info().n_coords);
    obs.start(&mut rec)?;
    let start = Instant::now();
    let result = body((mech, reduced), opts, (t_end, n_out), &mut rec, obs);
    rec.wall = start.elapsed();
    match result {
        Ok(()) => Ok(rec),
        Err(error) => Err(Stopped {
            recording: Some(Box::new(rec)),
            error,
        }),
    }
}

/// How long an integration runs on the recording's thread before it takes a thread of its
/// own (where `Options::path_thread`). Measured (alternated pairs, 2026-11-29), with the
/// thread from the start: runs of 0.5 ms took 0.2–0.3 ms longer (1.4–1.7 times), of
/// 1.9 ms 1.18 times, of 4.2 ms 0.98 times, of 9.6–166 ms 0.82–0.91 times.
pub(crate) const INTEGRATION_ALONE: Duration = Duration::from_millis(2);

/// The integration loop of [`run_observed`]: the integration ([`Stepper`]) on a thread of
/// its own beside this one's recording where `opts.path_thread`, once it has run
/// [`INTEGRATION_ALONE`].
fn integrate(
    model: (&'static (dyn Mechanism + Sync), Option<Reduced>),
    opts: &Options,
    (t_end, n_out): (f64, usize),
    rec: &mut Recording,
    obs: &mut dyn Observer,
) -> Result<(), Error> {
    let stepper = Stepper::new(model, opts, (t_end, n_out))?;
    let mut at_output = OutputSolve::new(model.0.info(), opts)?;
    rec.work_integrated = true;
    let recording = |feed: &mut path_feed::Feed<'_, '_, Batched<Stepper>>| -> Result<(), Error> {
        while let Some(batch) = feed.next() {
            for out in batch.outputs() {
                rec.stats = out.stats;
                rec.euler_warning = out.euler_warning;
                let (solution, residuals, sample) = at_output.read(model.0, out)?;
                let state = (out.t, &out.q[..], &out.qd[..]);
                record(rec, solution, residuals, state, sample)?;
                obs.output(rec)?;
            }
            let (t, steps) = batch.reached;
            if obs.progress(t, steps).is_break() {
                return Err(ScenarioError::Interrupted { time: t });
            }
            feed.recycle(batch);
        }
        Ok(())
    };
    let thread = if opts.path_thread {
        Thread::After(INTEGRATION_ALONE)
    } else {
        Thread::No
    };
    let (recorded, (stats, euler_warning, ended)) =
        path_feed::follow(Batched::new(stepper), thread, recording);
    recorded?;
    // The counters and warnings so far belong to the recording even if a step failed.
    rec.stats = stats;
    rec.euler_warning = euler_warning;
    ended
}

/// The full model's state `(q, q̇)` from the integrator's, expanded when it integrates the
/// reduced model (`offsets`: the reduction's work memory). Runs at every step.
pub(crate) fn full_state(
    it: &Integrator<&'static (dyn Mechanism + Sync)>,
    reduced: Option<Reduced>,
    offsets: &mut [f64],
    (q, qd): (&mut [f64], &mut [f64]),
) -> Result<(), Error> {
    match reduced {
        None => {
            q.copy_from_slice(it.q());
            qd.copy_from_slice(it.qd());
        }
        Some((_, r)) => r.expand_state((it.q(), it.qd()), it.t(), offsets, (q, qd))?,
    }
    Ok(())
}

/// As [`run`], by the kinematic path (docs/design.md, decision 23) instead of integration:
/// at each output time the position from the drivers, the velocity of least kinetic energy,
/// and the saddle-point accelerations and multipliers. Exact only when the drivers leave no
/// free direction with momentum (`symbody::scene::choose_path` checks); `opts.step` and
/// `opts.alpha` do not apply. The work of drivers and loads is integrated by the four-point
/// Gauss–Lobatto rule over each output interval, the path solved at its two interior nodes
/// too: sixth order in the output spacing, as accurate as the integrator's step-by-step sum
/// at the CLI's spacing (the outputs alone gave fourth order: 1.8e-6 of the energy scale on
/// the four-bar's scene, against 1.5e-10 integrated).
pub fn run_kinematic(entry: &Entry, opts: &Options) -> Result<Recording, Error> {
    run_kinematic_observed(entry, opts, &mut ()).map_err(|s| s.error)
}

/// [`run_kinematic`], telling `obs` as it goes (see [`run_observed`]).
pub fn run_kinematic_observed(
    entry: &Entry,
    opts: &Options,
    obs: &mut dyn Observer,
) -> Result<Recording, Stopped> {
    observed(entry, opts, obs, follow_path)
}

/// Each state a kinematic path solved, seen in the full model's terms: the state itself when
/// the path follows the full model, read back through [`FullState`] when it follows the
/// reduced one.
struct Reader {
    full: Option<FullState>,
    /// Φq q̇ + Φt.
    velocity: Vec<f64>,
}

impl Reader {
    fn new(info: &'static MechanismInfo, reduced: Option<Reduced>) -> Result<Self, Error> {
        Ok(Reader {
            full: match reduced {
                Some((_, reduction)) => Some(FullState::new(reduction, info)?),
                None => None,
            },
            velocity: vec![0.0; info.n_constraints],
        })
    }

    /// Reads `s` in `mech`'s terms (the full model's), for the methods below.
    fn read(&mut self, mech: &dyn Mechanism, s: &State<'_>) -> Result<(), Error> {
        match &mut self.full {
            // The runtime's error, as this module's.
            Some(full) => Ok(full.read(mech, s.t, s.q, s.qd, s.qdd, s.lambda)?),
            None => Ok(()),
        }
    }

    fn q<'a>(&'a self, s: &State<'a>) -> &'a [f64] {
        self.full.as_ref().map_or(s.q, |f| &f.q)
    }
    fn qd<'a>(&'a self, s: &State<'a>) -> &'a [f64] {
        self.full.as_ref().map_or(s.qd, |f| &f.qd)
    }
    fn lambda<'a>(&'a self, s: &State<'a>) -> &'a [f64] {
        self.full.as_ref().map_or(s.lambda, |f| &f.lambda)
    }

    /// What the path solved at the state, in the full model's terms: its reactions, without
    /// solving again (the pivots are those of the followed model's factorization).
    fn solution<'a>(&'a self, s: &State<'a>) -> Solution<'a> {
        match &self.full {
            None => Solution {
                qdd: s.qdd,
                lambda: s.lambda,
                phi_q: s.phi_q,
                pivots: s.pivots,
            },
            Some(f) => Solution {
                qdd: &f.qdd,
                lambda: &f.lambda,
                phi_q: &f.phi_q,
                pivots: s.pivots,
            },
        }
    }

    /// The energies and power at the state, what an [`EnergyMeter`] would record, from the M
    /// and λ the path solved with; the work, integrated over the outputs, is the caller's.
    fn energy(
        &self,
        mech: &dyn Mechanism,
        s: &State<'_>,
        phi_t: &mut [f64],
    ) -> Result<EnergySample, Error> {
        let (t, q, qd) = (s.t, self.q(s), self.qd(s));
        let mass = self.full.as_ref().map_or(s.mass, |f| f.mass());
        let kinetic = kinetic_energy(mech.info(), mass, qd);
        let sample = EnergySample {
            kinetic,
            potential: mech.potential(q),
            work: f64::NAN,
            power: energy::power(&mech, t, q, qd, self.lambda(s), phi_t),
        };
        if !(sample.kinetic.is_finite() && sample.potential.is_finite() && sample.power.is_finite())
        {
            return Err(ScenarioError::Runtime(symbody_runtime::Error::NotFinite {
                time: t,
                what: "energy or power",
            }));
        }
        Ok(sample)
    }

    /// The full model's drift at the state (on the reduced model, at the state read back),
    /// from the evaluations the path made there.
    fn residuals(&mut self, info: &MechanismInfo, s: &State<'_>) -> Residuals {
        match &mut self.full {
            None => Residuals {
                position: s.position_residual,
                velocity: velocity_residual(info, s.phi_q, s.phi_t, s.qd, &mut self.velocity),
            },
            Some(f) => f.residuals(s.position_residual),
        }
    }
}

/// The loop of [`run_kinematic_observed`]: the path's solves handed over by a
/// [`path_feed::Feed`] while this thread records each output and hands it to `obs`. With the
/// energy table, the path also solves at the quadrature's two interior times of each
/// interval.
fn follow_path(
    (mech, reduced): (&'static (dyn Mechanism + Sync), Option<Reduced>),
    opts: &Options,
    (t_end, n_out): (f64, usize),
    rec: &mut Recording,
    obs: &mut dyn Observer,
) -> Result<(), Error> {
    let info = mech.info();
    let path = KinematicPath::new(reduced.map_or(mech, |(r, _)| r), 0.0)?;
    let mut reader = Reader::new(info, reduced)?;
    rec.work_integrated = rec.energy_table;
    let nodes: &[f64] = if rec.work_integrated {
        &quadrature::LOBATTO4_NODES
    } else {
        &[]
    };
    // Each interval's interior times, then its end.
    let mut times = Vec::with_capacity(n_out * (nodes.len() + 1));
    let mut start = 0.0;
    for k in 1..=n_out {
        let end = (k as f64 * opts.output_step).min(t_end);
        times.extend(nodes.iter().map(|node| start + node * (end - start)));
        times.push(end);
        start = end;
    }
    let on_thread = opts.path_thread && path_feed::worth_a_thread(path.info());
    let own = reduced.is_none();
    let solver = path_feed::Solver::new(path, times, own, None);
    let mut modes = None;
    let mut phi_t = vec![0.0; info.n_constraints];
    // Without the quadrature the work stays NaN: never integrated, never shown.
    let mut work = if rec.work_integrated { 0.0 } else { f64::NAN };
    let (mut power_before, mut t_before) = (0.0, 0.0);
    let mut inside = [0.0; 2];
    let mut solved = 0;
    let recording =
        |feed: &mut path_feed::Feed<'_, '_, path_feed::Solver<'_, _>>| -> Result<(), Error> {
            while let Some(batch) = feed.next() {
                for k in 0..batch.len() {
                    let s = batch.state(k);
                    // The start, then each interval's interior times and its end.
                    let node = (solved > 0).then(|| (solved - 1) % (nodes.len() + 1));
                    solved += 1;
                    reader.read(mech, &s)?;
                    if let Some(i) = node.filter(|&i| i < nodes.len()) {
                        let (q, qd) = (reader.q(&s), reader.qd(&s));
                        inside[i] = energy::power(&mech, s.t, q, qd, reader.lambda(&s), &mut phi_t);
                        continue;
                    }
                    let watch = match &modes {
                        Some(w) => w,
                        None => modes.insert(mode_watch(mech, reader.q(&s))?),
                    };
                    if let Some(w) = watch {
                        w.check(reader.q(&s), s.t)?;
                    }
                    // The path solved q̈ and λ at this state: the energies and reactions are read
                    // from its solution (an energy meter would solve the same system again).
                    let mut sample = reader.energy(mech, &s, &mut phi_t)?;
                    if node.is_some() {
                        work += quadrature::lobatto4(
                            s.t - t_before,
                            [power_before, inside[0], inside[1], sample.power],
                        );
                    }
                    (power_before, t_before) = (sample.power, s.t);
                    sample.work = work;
                    let residuals = reader.residuals(info, &s);
                    let state = (s.t, reader.q(&s), reader.qd(&s));
                    record(rec, reader.solution(&s), residuals, state, sample)?;
                    obs.output(rec)?;
                    if obs.progress(s.t, solved).is_break() {
                        return Err(ScenarioError::Interrupted { time: s.t });
                    }
                }
                feed.recycle(batch);
            }
            Ok(())
        };
    let thread = if on_thread { Thread::Yes } else { Thread::No };
    let (recorded, (stats, followed)) = path_feed::follow(solver, thread, recording);
    // Whether or not the path got to its end; the quadrature's interior solves count in
    // the iterations and factorizations, not as outputs.
    rec.kinematic = Some(PathStats {
        outputs: rec.t.len(),
        ..stats
    });
    recorded?;
    Ok(followed?)
}

/// A six-leg platform must stay on its assembly mode: a step across a parallel singularity
/// would continue on another one without any solver noticing.
pub(crate) fn mode_watch(
    mech: &(dyn Mechanism + Sync),
    q: &[f64],
) -> Result<Option<ModeWatch>, Error> {
    Ok(match mech.info().platform {
        Some(_) => Some(ModeWatch::new(
            &Platform::new(mech)?,
            q,
            SIMULATION_MAX_CONDITION,
        )?),
        None => None,
    })
}

impl Recording {
    /// An empty recording of every body, joint (drivers and normalization rows aside) and
    /// driver of `info`.
    fn new(info: &'static MechanismInfo) -> Self {
        let of_kind = |want: fn(JointKind) -> bool| -> Vec<usize> {
            (0..info.joints.len())
                .filter(|&j| want(info.joints[j].kind))
                .collect()
        };
        Recording {
            info,
            t: Vec::new(),
            q: Vec::new(),
            qd: Vec::new(),
            bodies: (0..info.bodies.len()).collect(),
            velocities: false,
            accelerations: false,
            qdd: Vec::new(),
            poses: Vec::new(),
            joints: of_kind(|k| !matches!(k, JointKind::Driver | JointKind::Normalization)),
            wrenches: Vec::new(),
            reactions: None,
            drivers: of_kind(|k| k == JointKind::Driver),
            efforts: Vec::new(),
            energy_table: true,
            work_integrated: false,
            energy: Vec::new(),
            stats: Stats::default(),
            kinematic: None,
            reduced: None,
            max_phi: 0.0,
            max_velocity_residual: 0.0,
            max_norm_error: 0.0,
            euler_warning: None,
            pivots: Vec::new(),
            wall: Duration::ZERO,
        }
    }
}

/// The integrator of a generic run, at its consistent start: HHT with `opts.alpha` and
/// velocity projection (see [`Options::default`] for why), from the file's pose and
/// velocities.
pub(crate) fn integrator(
    mech: &'static (dyn Mechanism + Sync),
    opts: &Options,
) -> Result<Integrator<&'static (dyn Mechanism + Sync)>, Error> {
    let builder = hht_builder(
        opts.alpha,
        opts.step,
        opts.tolerances,
        opts.newton_tolerance,
    )
    .qd0(mech.info().qd0)
    .project_velocities(true)
    .kinematic_settings(solve_settings(opts.cross_singular));
    Ok(builder.build(mech)?)
}

/// HHT with `alpha` and the nominal `step` (with `tolerances`, step-size control's
/// `(rtol, atol)`, the first step tried), and Newton's tolerances all at `newton_tolerance`
/// where given: what every run of this library sets before its own settings.
pub(crate) fn hht_builder(
    alpha: f64,
    step: f64,
    tolerances: Option<(f64, f64)>,
    newton_tolerance: Option<f64>,
) -> HhtBuilder {
    let builder = HhtBuilder::new()
        .alpha(alpha)
        .step(step)
        // Allow step cuts well below a step chosen smaller than the default minimum.
        .min_step((step * 1e-4).min(1e-7));
    let builder = match newton_tolerance {
        Some(tol) => builder.newton_tolerance(tol),
        None => builder,
    };
    match tolerances {
        Some((rtol, atol)) => builder.tolerances(rtol, atol),
        None => builder,
    }
}

/// Step-size control's `(rtol, atol)` from the two optional tolerances (either alone sets
/// both; neither: a fixed step), or an error naming the one that is not positive and
/// finite, written as `{prefix}rtol` (`--` on the command line).
pub fn tolerances(
    rtol: Option<f64>,
    atol: Option<f64>,
    prefix: &str,
) -> Result<Option<(f64, f64)>, String> {
    for (name, v) in [("rtol", rtol), ("atol", atol)] {
        if let Some(v) = v {
            if !(v > 0.0 && v.is_finite()) {
                return Err(format!(
                    "{prefix}{name} {v}: a tolerance must be positive and finite (e.g. {prefix}{name} 1e-6)"
                ));
            }
        }
    }
    Ok(match (rtol, atol) {
        (Some(r), Some(a)) => Some((r, a)),
        (Some(t), None) | (None, Some(t)) => Some((t, t)),
        (None, None) => None,
    })
}

/// The settings of every saddle-point solve of a run (the consistent start, the steps, the
/// multipliers at each output and the energy meter's samples): all must cross a singular
/// position where one does.
pub(crate) fn solve_settings(cross_singular: bool) -> KinematicSettings {
    KinematicSettings {
        drop_dependent_rows: cross_singular.then_some(DEFAULT_PIVOT_TOLERANCE),
        ..KinematicSettings::default()
    }
}

/// The solution of `[M Φqᵀ; Φq 0][q̈; λ] = [Q; γ]` at an output's state, and the Φq it was
/// solved with: what the output's reactions are read from.
pub(crate) struct Solution<'a> {
    pub qdd: &'a [f64],
    pub lambda: &'a [f64],
    pub phi_q: &'a [f64],
    pub pivots: Option<Pivots>,
}

/// Appends the output `(t, q, q̇)` with its solution `s`.
fn record(
    rec: &mut Recording,
    s: Solution<'_>,
    r: Residuals,
    (t, q, qd): (f64, &[f64], &[f64]),
    sample: EnergySample,
) -> Result<(), Error> {
    let info = rec.info;
    let (lambda, phi_q) = (s.lambda, s.phi_q);
    rec.pivots.push(s.pivots.unwrap_or_default());
    rec.max_phi = rec.max_phi.max(r.position);
    rec.max_velocity_residual = rec.max_velocity_residual.max(r.velocity);
    for b in info
        .bodies
        .iter()
        .filter(|b| b.rotation == Rotation::Quaternion)
    {
        let e = &q[b.coord_offset + 3..b.coord_offset + 7];
        let n: f64 = e.iter().map(|x| x * x).sum();
        rec.max_norm_error = rec.max_norm_error.max((n - 1.0).abs());
    }
    let at = ScenarioError::Runtime;
    rec.poses.push(
        info.bodies
            .iter()
            .map(|b| body_pose(b, q))
            .collect::<Result<_, _>>()
            .map_err(at)?,
    );
    let reactions = match &mut rec.reactions {
        Some(r) if r.joints() == rec.joints.as_slice() => r,
        stale => stale.insert(JointWrenches::new(info, &rec.joints).map_err(at)?),
    };
    let mut wrenches = Vec::with_capacity(rec.joints.len());
    reactions
        .wrenches(q, phi_q, lambda, &mut wrenches)
        .map_err(at)?;
    rec.wrenches.push(wrenches);
    rec.efforts.push(
        rec.drivers
            .iter()
            .map(|&j| driver_effort(info, lambda, j))
            .collect::<Result<_, _>>()
            .map_err(at)?,
    );
    rec.t.push(t);
    rec.q.push(q.to_vec());
    rec.qd.push(qd.to_vec());
    if rec.accelerations {
        rec.qdd.push(s.qdd.to_vec());
    }
    rec.energy.push(sample);
    Ok(())
}

pub use crate::tables::{tables, write_csvs, Table};

#[cfg(test)]
mod tests {
    use super::*;
    use symbody_mechanisms::REGISTRY;
    use symbody_runtime::EnergyMeter;

    fn four_bar() -> &'static Entry {
        find(&REGISTRY, "four_bar").expect("registered")
    }

    #[test]
    fn unknown_names_list_the_registry_and_suggest_only_near_misses() {
        let msg = |n: &str| find(&REGISTRY, n).expect_err("unknown").to_string();
        assert!(msg("slidercrank").contains("did you mean `slider_crank`"));
        assert!(msg("spherical_pendulm").contains("did you mean `spherical_pendulum`"));
        let far = msg("gearbox");
        assert!(!far.contains("did you mean"), "{far}");
        for e in REGISTRY.iter() {
            assert!(far.contains(e.name), "{far}");
        }
    }

    /// A mechanism whose rows its joints describe, none a driver, has Φt = 0 exactly: what
    /// lets the energy meter skip λ between outputs. Checked on every shipped model at its
    /// start and at a perturbed position, at several times, against the generated Φt.
    #[test]
    fn rows_without_drivers_do_not_depend_on_time() {
        let (mut with, mut without) = (0, 0);
        for entry in REGISTRY.iter() {
            let mech = entry.default_mechanism();
            let info = mech.info();
            let mut phi_t = vec![0.0; info.n_constraints];
            let q: Vec<f64> = info
                .q0
                .iter()
                .enumerate()
                .map(|(i, x)| x + 0.01 * (i % 7) as f64)
                .collect();
            let mut moving = false;
            for t in [0.0, 0.37, 1.3] {
                for q in [info.q0, &q[..]] {
                    mech.phi_t(q, t, &mut phi_t);
                    moving |= phi_t.iter().any(|&v| v != 0.0);
                }
            }
            if info.rows_may_depend_on_time() {
                // A driver may hold a constant (dietmaier_6_6's leg lengths).
                with += usize::from(moving);
            } else {
                without += 1;
                assert!(!moving, "{}: Φt ≠ 0 without a driver", entry.name);
            }
        }
        assert!(
            with > 0 && without > 0,
            "{with} moved by drivers, {without} without"
        );
    }

    /// Without drivers the integration loop's meter solves only at the outputs
    /// (`EnergyMeter::advance` between them): its energies, work and reactions are those
    /// of a meter that solves at every step, recorded beside the same integrator.
    #[test]
    fn energy_without_drivers_is_recorded_as_with_a_solve_at_every_step() {
        let entry = find(&REGISTRY, "oscillators").expect("registered");
        let opts = Options {
            t_end: Some(0.3),
            ..Options::default()
        };
        let rec = run(entry, &opts).unwrap();
        let mech = entry.default_mechanism();
        assert!(!mech.info().rows_may_depend_on_time());
        let mut it = integrator(mech, &opts).unwrap();
        let mut meter: EnergyMeter =
            EnergyMeter::with_settings(mech.info(), solve_settings(opts.cross_singular)).unwrap();
        let mut sample = meter.record(&mech, it.t(), it.q(), it.qd()).unwrap();
        for (k, recorded) in rec.energy.iter().enumerate() {
            while it
                .step_toward(k as f64 * opts.output_step)
                .unwrap()
                .is_some()
            {
                sample = meter.record(&mech, it.t(), it.q(), it.qd()).unwrap();
            }
            assert_eq!(*recorded, sample, "output {k}");
        }
        let work = rec.energy.last().unwrap().work;
        assert!(work.abs() > 1e-3, "the forcing and dampers do work: {work}");
    }

    /// The steps taken one call at a time are the steps `advance_to` takes, with a
    /// step that does not divide the output spacing (0.01 = 3 × 3 ms + 2 × 0.5 ms).
    #[test]
    fn stepping_one_call_at_a_time_takes_advance_tos_steps() {
        let opts = Options {
            step: 3e-3,
            t_end: Some(0.1),
            ..Options::default()
        };
        let rec = run(four_bar(), &opts).unwrap();
        assert_eq!(rec.stats.steps, 10 * 4);
        let mut it = integrator(four_bar().default_mechanism(), &opts).unwrap();
        for (k, (t, q)) in rec.t.iter().zip(&rec.q).enumerate() {
            it.advance_to(k as f64 * opts.output_step).unwrap();
            assert_eq!(it.t(), *t);
            // The same step sizes, up to the rounding of t + h/2 − t against h/2.
            for (a, b) in it.q().iter().zip(q) {
                assert!((a - b).abs() <= 1e-13, "t = {t}: {a} vs {b}");
            }
        }
        assert_eq!(it.stats().steps, rec.stats.steps);
    }

    /// The meter records after every step, not every output: the work integral is the same
    /// whether outputs come every step or every ten. Recorded only at outputs, a trapezoid
    /// over 10 ms would be off by 4e-4 J (of 1.1 J) on this driven four-bar.
    #[test]
    fn work_is_integrated_at_the_step_not_the_output_spacing() {
        let every = |output_step: f64| {
            run(
                four_bar(),
                &Options {
                    t_end: Some(0.5),
                    output_step,
                    ..Options::default()
                },
            )
            .unwrap()
        };
        let (fine, coarse) = (every(1e-3), every(1e-2));
        assert_eq!(fine.stats.steps, coarse.stats.steps);
        let scale = fine.energy.iter().map(|e| e.work.abs()).fold(0.0, f64::max);
        assert!(scale > 0.01, "the driver does work: {scale}");
        // The trapezoid over the outputs' powers: what a meter recording only at outputs
        // would report; the test must be able to tell the two apart.
        let at_outputs: f64 = coarse
            .energy
            .windows(2)
            .zip(coarse.t.windows(2))
            .map(|(e, t)| 0.5 * (e[0].power + e[1].power) * (t[1] - t[0]))
            .sum();
        let end = coarse.energy.last().unwrap().work;
        assert!(
            (at_outputs - end).abs() > 1e-5 * scale,
            "{at_outputs} vs {end}"
        );
        for (k, e) in coarse.energy.iter().enumerate() {
            let f = fine.energy[10 * k];
            assert!((fine.t[10 * k] - coarse.t[k]).abs() < 1e-12);
            assert!(
                (f.work - e.work).abs() <= 1e-9 * scale,
                "t = {}: {} vs {}",
                coarse.t[k],
                f.work,
                e.work
            );
        }
    }
}
