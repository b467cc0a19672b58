//! HHT-α for index-3 DAEs, as Negrut, Rampalli, Ottarsson and Sajdak (2007) and Project
//! Chrono's `ChTimestepperHHT` formulate it (docs/design.md, decision 8).
//!
//! Per step `tₙ → tₙ₊₁ = tₙ + h` the unknowns are `q̈ₙ₊₁` and `λₙ₊₁`; positions and
//! velocities follow from the Newmark formulas
//! ```text
//! qₙ₊₁ = qₙ + h q̇ₙ + h²/2 [(1 − 2β) q̈ₙ + 2β q̈ₙ₊₁],   q̇ₙ₊₁ = q̇ₙ + h [(1 − γ) q̈ₙ + γ q̈ₙ₊₁],
//! ```
//! with `β = (1 − α)²/4`, `γ = 1/2 − α`, and the equations
//! ```text
//! (1/(1+α)) (M q̈)ₙ₊₁ + (Φqᵀλ − Q)ₙ₊₁ − (α/(1+α)) (Φqᵀλ − Q)ₙ = 0,    Φ(qₙ₊₁)/(βh²) = 0
//! ```
//! are solved by Newton on the increments of `q̈` and `λ` with the iteration matrix
//! `[M/(1+α) Φqᵀ; Φq 0]`. Scaling the constraint rows by `1/(βh²)` makes that matrix
//! independent of `h`, so its conditioning does not degrade with small steps, and one
//! factorization serves any step size. Where the generator emitted the applied loads'
//! Jacobians (springs, dampers), their symmetric parts join the top-left block as
//! `−βh²·∂Q/∂q − γh·∂Q/∂q̇` ([`HhtBuilder::load_stiffness`]), so a stiff load does not
//! limit the step.
//!
//! Newton policy (modified Newton): the matrix is factored at the first iteration of each
//! step (or kept across steps when [`HhtBuilder::reuse_factorization`] is on) and refactored
//! whenever an iteration reduces the weighted increment by less than half. The other
//! stiffness terms (`∂(Φqᵀλ)/∂q`, the inertial terms' dependence on the state) are left out
//! of the matrix: they are `O(βh²)` relative to `M`, so they only slow the (still fast)
//! convergence, never change the converged answer, which is
//! always that of the full residual.
//!
//! A step is accepted only when the last weighted increment is at most 1 **and** the
//! unscaled `|Φ|∞` evaluated at the accepted positions is below its tolerance. The
//! increments are weighted per entry by `abs_tol + rel_tol·|value|` (max norm, stricter than
//! Chrono's WRMS), with the absolute tolerance raised to the roundoff floor `~ε/(βh²)` that
//! the scaled constraint rows impose on very small steps. On failure the
//! step is retried with a fresh factorization at every iteration, then halved; below the
//! minimum step the integrator returns an error and keeps the last accepted state.

use crate::error::{check_len, ConstraintRow, Error, NewtonIncrement};
use crate::hht_predictor::Predictor;
use crate::kinematics::{
    inf_norm, largest_row, mass_times, phi_q_times_add, phi_q_transpose_times, InitialVelocity,
    KinematicSettings, Kinematics,
};
use crate::kkt::{KktError, KktPattern, KktSolver, SchurKkt};
use crate::load_stiffness::LoadStiffness;
use crate::mechanism::{Mechanism, MechanismInfo, NewtonOutputs};
use crate::reactions;
use crate::watch::{EulerLimits, EulerWarning};

/// Settings of the HHT-α integrator; every field has a documented default.
#[derive(Debug, Clone, PartialEq)]
pub struct HhtBuilder {
    alpha: f64,
    step: f64,
    min_step: f64,
    max_iterations: usize,
    rel_tol: f64,
    abs_tol_acc: f64,
    abs_tol_lambda: f64,
    phi_tol: f64,
    reuse_factorization: bool,
    rate_test: bool,
    /// `(rtol, atol)` of the step-size control; `None`: fixed step.
    tolerances: Option<(f64, f64)>,
    max_step: f64,
    project_velocities: bool,
    load_stiffness: bool,
    t0: f64,
    q0: Option<Vec<f64>>,
    qd0: Option<Vec<f64>>,
    kinematics: KinematicSettings,
    euler: EulerLimits,
}

impl Default for HhtBuilder {
    fn default() -> Self {
        HhtBuilder {
            alpha: -0.05,
            step: 1e-3,
            min_step: 1e-7,
            max_iterations: 8,
            rel_tol: 1e-6,
            abs_tol_acc: 1e-6,
            abs_tol_lambda: 1e-6,
            phi_tol: 1e-10,
            reuse_factorization: false,
            rate_test: true,
            tolerances: None,
            max_step: f64::INFINITY,
            project_velocities: false,
            load_stiffness: true,
            t0: 0.0,
            q0: None,
            qd0: None,
            kinematics: KinematicSettings::default(),
            euler: EulerLimits::default(),
        }
    }
}

impl HhtBuilder {
    /// Default settings; see each setter for its default.
    pub fn new() -> Self {
        Self::default()
    }

    /// Numerical damping α ∈ [−1/3, 0] (default −0.05: damps only components near the
    /// step's Nyquist frequency; the mechanism's own motion keeps second-order accuracy).
    /// α = 0 is the trapezoidal rule and conserves energy for linear problems.
    pub fn alpha(mut self, alpha: f64) -> Self {
        self.alpha = alpha;
        self
    }

    /// Nominal step (default 1e-3 s). Steps are halved on Newton failure and grow back.
    /// With [`HhtBuilder::tolerances`] it is the first step the control tries.
    pub fn step(mut self, h: f64) -> Self {
        self.step = h;
        self
    }

    /// Step-size control (default off: the fixed [`HhtBuilder::step`]): each step's local
    /// error in positions and velocities is estimated from the change of the accelerations
    /// over it (see `Integrator::local_error`) and kept, in the weighted RMS norm with
    /// weights `atol + rtol·max(|xₙ|, |xₙ₊₁|)`, at most 1; a step above it is rejected and
    /// retried smaller, and every step proposes the next. Multipliers are not judged (in an
    /// index-3 formulation they carry no error of their own that a step could control).
    /// Both must be positive and finite. These are not [`HhtBuilder::rel_tol`], the Newton
    /// tolerance on each step's equations. Velocities are then always projected
    /// ([`HhtBuilder::project_velocities`]).
    pub fn tolerances(mut self, rtol: f64, atol: f64) -> Self {
        self.tolerances = Some((rtol, atol));
        self
    }

    /// Largest step the control may take (default unbounded; with a fixed step it only has
    /// to be at least the step).
    pub fn max_step(mut self, h: f64) -> Self {
        self.max_step = h;
        self
    }

    /// Smallest step before giving up with [`Error::StepSizeTooSmall`] (default 1e-7 s).
    pub fn min_step(mut self, h: f64) -> Self {
        self.min_step = h;
        self
    }

    /// Newton iterations allowed per attempt (default 8; a healthy step needs 1 or 2).
    pub fn max_iterations(mut self, n: usize) -> Self {
        self.max_iterations = n;
        self
    }

    /// Relative tolerance on the increments of `q̈` and `λ` (default 1e-6).
    pub fn rel_tol(mut self, tol: f64) -> Self {
        self.rel_tol = tol;
        self
    }

    /// Absolute tolerance on acceleration increments (default 1e-6, m/s² or rad/s²).
    pub fn abs_tol_acceleration(mut self, tol: f64) -> Self {
        self.abs_tol_acc = tol;
        self
    }

    /// Absolute tolerance on the increments of the generalized constraint forces Φqᵀλ
    /// (default 1e-6, N or N·m). Judged through Φqᵀ because at a singular configuration λ is
    /// not unique and only Φqᵀλ is: an N-four-bar crossing its flat position (IFToMM A02)
    /// would otherwise never converge.
    pub fn abs_tol_lambda(mut self, tol: f64) -> Self {
        self.abs_tol_lambda = tol;
        self
    }

    /// Tolerance on the unscaled constraint residual |Φ|∞ of an accepted step
    /// (default 1e-10, metres or radians).
    pub fn constraint_tol(mut self, tol: f64) -> Self {
        self.phi_tol = tol;
        self
    }

    /// All of Newton's tolerances at once: [`Self::rel_tol`], [`Self::abs_tol_acceleration`],
    /// [`Self::abs_tol_lambda`] and [`Self::constraint_tol`] set to `tol` (what a run asked
    /// to solve each step to a given accuracy wants).
    pub fn newton_tolerance(self, tol: f64) -> Self {
        self.rel_tol(tol)
            .abs_tol_acceleration(tol)
            .abs_tol_lambda(tol)
            .constraint_tol(tol)
    }

    /// Keep one factorization across steps while convergence stays fast (default off:
    /// factor once per step). The matrix depends on `q` and, through the loads' stiffness
    /// and damping, on `h`; a kept one is refreshed as soon as convergence slows. Projected
    /// velocities (`project_velocities`, and step control, which always projects) need a
    /// factorization of the step they end: a step that solved with a kept one refactors at
    /// its accepted state, which the next step then keeps.
    pub fn reuse_factorization(mut self, reuse: bool) -> Self {
        self.reuse_factorization = reuse;
        self
    }

    /// Accept a Newton iterate by its convergence rate (default on), as DASSL and IDA do:
    /// once an increment `δ` was applied, the error left is about `ρ/(1 − ρ)·‖δ‖` for the
    /// contraction rate ρ of the iteration, so the iterate passes when that is below a third
    /// of the tolerances (`rel_tol`, `abs_tol_*`) without taking (and evaluating) one more
    /// increment. ρ is measured whenever a step takes two increments through one
    /// factorization, and a step's first increment is judged by the rate of an earlier step
    /// for at most a few steps before it is measured again. Off: an iterate passes only after
    /// an increment within the tolerances was applied, one more increment per step.
    pub fn rate_test(mut self, on: bool) -> Self {
        self.rate_test = on;
        self
    }

    /// Lets the step pass singular positions (a linkage crossing a flat or dead-centre
    /// configuration, where its rows are dependent for an instant, as in the IFToMM A02
    /// N-four-bar): rows whose Schur pivot falls below `tolerance` (relative; the rank-loss
    /// threshold [`crate::kkt::DEFAULT_PIVOT_TOLERANCE`] drops only what would fail) are
    /// dropped for that factorization instead of failing the step. A step is still accepted
    /// only when every row, dropped or not, satisfies the constraint tolerance, so an
    /// unreachable pose still fails. The consistent start drops them too. Off by default (0):
    /// rank loss is reported. The same setting as [`KinematicSettings::drop_dependent_rows`].
    pub fn drop_dependent_rows(mut self, tolerance: f64) -> Self {
        self.kinematics.drop_dependent_rows = (tolerance > 0.0).then_some(tolerance);
        self
    }

    /// Put the applied loads' stiffness and damping, `−βh²·∂Q/∂q − γh·∂Q/∂q̇` (symmetric
    /// parts, as the generator emits them: springs, dampers, actuators), into the Newton
    /// matrix (default on; mechanisms without such loads are unaffected). Off, Newton sees
    /// only `M` and a stiff spring or damper limits the step instead of the motion.
    pub fn load_stiffness(mut self, on: bool) -> Self {
        self.load_stiffness = on;
        self
    }

    /// Project the velocities onto Φq q̇ + Φt = 0 after every accepted step (a mass-weighted
    /// correction through the step's own factorization; default off). Index-3 HHT holds
    /// Φ = 0 but lets the velocity residual drift; on a fast-turning quaternion body at
    /// α = 0 that drift feeds back into the motion and grows until the step fails.
    pub fn project_velocities(mut self, on: bool) -> Self {
        self.project_velocities = on;
        self
    }

    /// Whether velocities are projected after every step ([`HhtBuilder::project_velocities`]).
    pub fn projects_velocities(&self) -> bool {
        self.project_velocities
    }

    /// Initial time (default 0).
    pub fn t0(mut self, t0: f64) -> Self {
        self.t0 = t0;
        self
    }

    /// Initial positions (default: the mechanism's `info.q0`); made consistent by Newton.
    pub fn q0(mut self, q0: &[f64]) -> Self {
        self.q0 = Some(q0.to_vec());
        self
    }

    /// Initial velocities, projected onto the consistent ones in the kinetic-energy norm.
    /// Default: the mechanism's `info.qd0` (the file's velocities, zero where none was
    /// given), projected the same way; projecting zeros gives the consistent velocity of
    /// least kinetic energy.
    pub fn qd0(mut self, qd0: &[f64]) -> Self {
        self.qd0 = Some(qd0.to_vec());
        self
    }

    /// Settings of the position analysis of the consistent start; their
    /// `drop_dependent_rows` applies to the steps too (it is
    /// [`HhtBuilder::drop_dependent_rows`]'s setting, which a later call replaces).
    pub fn kinematic_settings(mut self, s: KinematicSettings) -> Self {
        self.kinematics = s;
        self
    }

    /// Euler-singularity thresholds (default [`EulerLimits::default`]).
    pub fn euler_limits(mut self, limits: EulerLimits) -> Self {
        self.euler = limits;
        self
    }

    fn validate(&self) -> Result<(), Error> {
        let bad = |name, value, reason| {
            Err(Error::InvalidSetting {
                name,
                value,
                reason,
            })
        };
        if !(-1.0 / 3.0 - 1e-15..=0.0).contains(&self.alpha) {
            return bad("alpha", self.alpha, "must lie in [-1/3, 0]");
        }
        if !(self.step > 0.0 && self.step.is_finite()) {
            return bad("step", self.step, "must be positive and finite");
        }
        if !(self.min_step > 0.0 && self.min_step <= self.step) {
            return bad(
                "min_step",
                self.min_step,
                "must be positive and at most step",
            );
        }
        if !(self.max_step >= self.step) {
            return bad("max_step", self.max_step, "must be at least step");
        }
        if let Some((rtol, atol)) = self.tolerances {
            for (name, v) in [("rtol", rtol), ("atol", atol)] {
                if !(v > 0.0 && v.is_finite()) {
                    return bad(name, v, "must be positive and finite");
                }
            }
        }
        if self.max_iterations < 1 {
            return bad("max_iterations", 0.0, "must be at least 1");
        }
        for (name, v) in [
            ("rel_tol", self.rel_tol),
            ("abs_tol_acceleration", self.abs_tol_acc),
            ("abs_tol_lambda", self.abs_tol_lambda),
        ] {
            if !(v >= 0.0 && v.is_finite()) {
                return bad(name, v, "must be non-negative and finite");
            }
        }
        if !(self.abs_tol_acc > 0.0 || self.rel_tol > 0.0) {
            return bad("abs_tol_acceleration", 0.0, "tolerances cannot all be zero");
        }
        if !(self.abs_tol_lambda > 0.0 || self.rel_tol > 0.0) {
            return bad("abs_tol_lambda", 0.0, "tolerances cannot all be zero");
        }
        if !(self.phi_tol > 0.0 && self.phi_tol.is_finite()) {
            return bad(
                "constraint_tol",
                self.phi_tol,
                "must be positive and finite",
            );
        }
        if !self.t0.is_finite() {
            return bad("t0", self.t0, "must be finite");
        }
        self.euler.validate()
    }

    /// Builds the integrator with the structured KKT solver and starts it consistently.
    pub fn build<M: Mechanism>(self, mech: M) -> Result<Integrator<M, SchurKkt>, Error> {
        self.build_with_solver(mech)
    }

    /// As [`HhtBuilder::build`] with a chosen KKT solver (e.g. [`crate::DenseKkt`]).
    ///
    /// Allocates all work memory, then runs the consistent start (docs/design.md, decision 9):
    /// position Newton, initial velocity, initial accelerations and multipliers.
    pub fn build_with_solver<M: Mechanism, K: KktSolver>(
        self,
        mech: M,
    ) -> Result<Integrator<M, K>, Error> {
        self.validate()?;
        let info = mech.info();
        let (n, m) = (info.n_coords, info.n_constraints);
        check_len("info.q0", n, info.q0.len())?;
        check_len("Φq column pattern", info.phi_q_nnz(), info.phi_q_cols.len())?;
        check_len("mass column pattern", info.mass_nnz(), info.mass_cols.len())?;
        let mut q = match &self.q0 {
            Some(q0) => {
                check_len("q0", n, q0.len())?;
                q0.clone()
            }
            None => info.q0.to_vec(),
        };
        let qd0 = match &self.qd0 {
            Some(v) => {
                check_len("qd0", n, v.len())?;
                v.as_slice()
            }
            None => {
                check_len("info.qd0", n, info.qd0.len())?;
                info.qd0
            }
        };
        let mut qd = qd0.to_vec();
        // Given velocities are projected; for all-zero ones that is the same solve as
        // least kinetic energy (the right-hand side M·0 is 0).
        let velocity = InitialVelocity::ProjectGiven;
        let mut qdd = vec![0.0; n];
        let mut lambda = vec![0.0; m];
        // A start at a singular position is as legitimate as a step onto one.
        let mut kin = Kinematics::<K>::with_settings(info, self.kinematics)?;
        kin.consistent_start(
            &mech,
            self.t0,
            velocity,
            &mut q,
            &mut qd,
            &mut qdd,
            &mut lambda,
        )?;
        let first_warning = self.euler.check(info, self.t0, &q)?;
        let stiffness = if self.load_stiffness {
            LoadStiffness::new(info)
        } else {
            None
        };
        let mut it = Integrator {
            info,
            kkt: {
                let pattern = match &stiffness {
                    Some(s) => s.pattern(info),
                    None => KktPattern::from_info(info),
                };
                let mut kkt = K::new(&pattern)?;
                if let Some(tolerance) = self.kinematics.drop_dependent_rows {
                    // The start's solver took the same tolerance, so only the solver type
                    // can refuse it here.
                    if !kkt.drop_dependent_rows(tolerance) {
                        return Err(Error::InvalidSetting {
                        name: "drop_dependent_rows",
                        value: tolerance,
                        reason: "the KKT solver cannot drop dependent rows (SchurKkt can, unless a zero principal inertia makes it solve densely: give that body a small inertia)",
                    });
                    }
                }
                kkt
            },
            beta: (1.0 - self.alpha).powi(2) / 4.0,
            gamma: 0.5 - self.alpha,
            h_nominal: self.step,
            h: self.step,
            successes_since_cut: 0,
            need_factor: true,
            factored_at: 0,
            rate: f64::NAN,
            rate_age: 0,
            t: self.t0,
            q,
            qd,
            qdd,
            lambda,
            r_prev: vec![0.0; n],
            predictor: Predictor::new(n, m, self.alpha),
            h_prev: 0.0,
            ratio_prev: 0.0,
            phi_q_state: vec![0.0; info.phi_q_nnz()],
            mass_state: vec![0.0; info.mass_nnz()],
            q1: vec![0.0; n],
            qd1: vec![0.0; n],
            qdd1: vec![0.0; n],
            lambda1: vec![0.0; m],
            phi: vec![0.0; m],
            phi_q: vec![0.0; info.phi_q_nnz()],
            mass: vec![0.0; info.mass_nnz()],
            force: vec![0.0; n],
            res1: vec![0.0; n],
            res2: vec![0.0; m],
            da: vec![0.0; n],
            dl: vec![0.0; m],
            reaction1: vec![0.0; n],
            noise: NoiseProbe::new(n, m),
            noise_measured: false,
            stiffness,
            stats: Stats::default(),
            first_warning,
            settings: self,
            mech,
        };
        it.stats.euler_warnings = usize::from(first_warning.is_some());
        it.stats.controlled = it.settings.tolerances.is_some();
        // (Φqᵀλ − Q)ₙ at the start, evaluated rather than inferred from the start's solve.
        it.evaluate_current();
        it.phi_q_state.copy_from_slice(&it.phi_q);
        it.mass_state.copy_from_slice(&it.mass);
        it.store_generalized_reaction();
        Ok(it)
    }
}

/// Solver counters, reported so tests and benchmarks can pin the work done.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Stats {
    /// Accepted steps.
    pub steps: usize,
    /// Newton iterations (linear solves).
    pub newton_iterations: usize,
    /// Factorizations of the iteration matrix.
    pub factorizations: usize,
    /// Failed step attempts (each followed by a retry with fresh Jacobian or a smaller
    /// step), those the error test rejected included.
    pub rejected_steps: usize,
    /// Attempts that converged but that the step-size control's error test rejected (a
    /// part of `rejected_steps`; 0 with a fixed step).
    pub error_test_failures: usize,
    /// Whether step-size control chose the steps ([`HhtBuilder::tolerances`]), so that a
    /// report can say so beside the step sizes.
    pub controlled: bool,
    /// Smallest and largest accepted step (s; 0 before the first). Steps shortened to land
    /// on an output time count too.
    pub smallest_step: f64,
    pub largest_step: f64,
    /// Calls of `eval_newton`.
    pub evaluations: usize,
    /// Accepted states at which some body was past the Euler warning threshold.
    pub euler_warnings: usize,
    /// Newton iterations that stalled above the tolerance but at the noise floor that
    /// roundoff sets through the factorization, and were accepted as converged (near
    /// singular positions; see `NoiseProbe`).
    pub noise_limited: usize,
}

/// What one accepted step did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepReport {
    /// Step size taken (s).
    pub h: f64,
    /// Newton iterations of the accepted attempt.
    pub iterations: usize,
    /// |Φ|∞ at the accepted positions.
    pub residual: f64,
}

/// Why one attempt failed; the caller decides whether to retry.
#[derive(Debug, Clone, Copy)]
enum Failure {
    /// `row`: the constraint row with the largest |Φ| at the last iterate; `increment`: the
    /// last weighted increment, the coordinate where it is largest and whether in Φqᵀλ.
    NotConverged {
        residual: f64,
        row: usize,
        increment: Option<(f64, usize, bool)>,
    },
    Kkt(KktError),
    NotFinite,
}

/// The HHT-α integrator for one mechanism, with all work memory owned.
#[derive(Debug)]
pub struct Integrator<M: Mechanism, K: KktSolver = SchurKkt> {
    mech: M,
    info: &'static MechanismInfo,
    settings: HhtBuilder,
    kkt: K,
    beta: f64,
    gamma: f64,
    h_nominal: f64,
    h: f64,
    successes_since_cut: usize,
    need_factor: bool,
    /// `stats.steps` when the factorization was made: the projection of a step's velocities
    /// needs one made in that step (see [`Integrator::project_velocity`]).
    factored_at: usize,
    /// Newton's contraction rate as last measured (NaN: none to go by, `rate_test`), and
    /// the steps accepted on it since.
    rate: f64,
    rate_age: usize,
    // Accepted state.
    t: f64,
    q: Vec<f64>,
    qd: Vec<f64>,
    qdd: Vec<f64>,
    lambda: Vec<f64>,
    /// (Φqᵀλ − Q) at the accepted state: the αterm of the next step.
    r_prev: Vec<f64>,
    /// q̈ and λ of earlier steps, for the next step's first guess.
    predictor: Predictor,
    /// The last accepted step's size (0 before the first step).
    h_prev: f64,
    /// `LocalError::ratio` of the last accepted step (0: none yet), for the predictive
    /// controller.
    ratio_prev: f64,
    phi_q_state: Vec<f64>,
    mass_state: Vec<f64>,
    // Iterates and evaluations of the step in progress.
    q1: Vec<f64>,
    qd1: Vec<f64>,
    qdd1: Vec<f64>,
    lambda1: Vec<f64>,
    phi: Vec<f64>,
    phi_q: Vec<f64>,
    mass: Vec<f64>,
    force: Vec<f64>,
    res1: Vec<f64>,
    res2: Vec<f64>,
    da: Vec<f64>,
    dl: Vec<f64>,
    /// Φqᵀλ of the current iterate: in the residual and in the convergence test.
    reaction1: Vec<f64>,
    noise: NoiseProbe,
    /// Whether the probe measured the roundoff of q̈ coordinate by coordinate in the last
    /// attempt (`NoiseProbe::accel`): the local error estimate, built on differences of q̈,
    /// then does not ask for less than it.
    noise_measured: bool,
    /// The loads' stiffness and damping in the Newton matrix (`None`: M alone).
    stiffness: Option<LoadStiffness>,
    stats: Stats,
    first_warning: Option<EulerWarning>,
}

/// Where [`Integrator::factor`] evaluates the loads' Jacobians.
#[derive(Debug, Clone, Copy)]
enum Iterate {
    /// The step's iterate `q1, qd1`.
    Step,
    /// The accepted state `q, qd`.
    Accepted,
}

/// The weighted local errors of one step (`Integrator::local_error`).
#[derive(Debug, Clone, Copy, Default)]
struct LocalError {
    /// Weighted RMS norms over the positions and the velocities: 1 is the tolerance.
    position: f64,
    velocity: f64,
    /// The coordinate with the largest weighted entry, and whether in its velocity.
    worst: usize,
    worst_is_velocity: bool,
}

impl LocalError {
    /// The larger norm: the step is accepted when it is at most 1 (NaN is not).
    fn norm(&self) -> f64 {
        if self.position.is_nan() || self.velocity.is_nan() {
            f64::NAN
        } else {
            self.position.max(self.velocity)
        }
    }

    /// The error as the step factor it asks for: each estimate to the power 1/its order
    /// in h (positions 3, velocities 2), the larger; the step would be right at 1.
    fn ratio(&self) -> f64 {
        self.position.powf(1.0 / 3.0).max(self.velocity.sqrt())
    }

    /// Step factor that brings each estimate to `SAFETY` times the tolerance.
    fn factor(&self) -> f64 {
        let r = self.ratio();
        if r > 0.0 {
            SAFETY / r
        } else {
            FAC_MAX
        }
    }
}

/// Step-size control: the error aimed at (relative to the tolerance), as a factor on the
/// step (0.9 ≈ 0.73 of the tolerance for an O(h³) estimate, so most proposals pass), and
/// the bounds on the change of the step from one step to the next. Growth is bounded by 2
/// as in DAE codes (IDA, DASSL): the velocity estimate divides by the previous step and
/// would amplify the Newton tolerance's noise if consecutive steps differed much more.
const SAFETY: f64 = 0.9;
const FAC_MIN: f64 = 0.2;
const FAC_MAX: f64 = 2.0;

/// Steps that must succeed at a reduced size before it is doubled again.
const GROWTH_DELAY: usize = 3;
/// An iteration that shrinks the weighted increment by less than this factor asks for a
/// fresh factorization.
const SLOW_RATE: f64 = 0.5;
/// The rate test's bound on the estimated error left in an iterate, relative to Newton's
/// tolerances (IDA's 0.33: the test is an estimate, and a rate carried over from an earlier
/// step can be optimistic).
const RATE_TOL: f64 = 0.33;
/// Steps that may accept their first increment on a rate measured in an earlier step; the
/// next one takes a second increment and so measures the rate again.
const RATE_AGE_MAX: usize = 10;
/// Multiple of machine epsilon (times the coordinate scale) taken as the roundoff of Φ.
const NOISE_FACTOR: f64 = 100.0;

impl<M: Mechanism, K: KktSolver> Integrator<M, K> {
    /// Current time.
    pub fn t(&self) -> f64 {
        self.t
    }
    /// Positions at [`Integrator::t`].
    pub fn q(&self) -> &[f64] {
        &self.q
    }
    /// Velocities.
    pub fn qd(&self) -> &[f64] {
        &self.qd
    }
    /// Accelerations.
    pub fn qdd(&self) -> &[f64] {
        &self.qdd
    }
    /// Lagrange multipliers (`M q̈ + Φqᵀλ = Q`).
    pub fn lambda(&self) -> &[f64] {
        &self.lambda
    }
    /// Nonzeros of Φq at the current state (for reactions).
    // The `phi_q` field is the step's work buffer; the accepted state's copy is returned.
    #[allow(clippy::misnamed_getters)]
    pub fn phi_q(&self) -> &[f64] {
        &self.phi_q_state
    }
    /// The step size the next step will try.
    pub fn step_size(&self) -> f64 {
        self.h
    }
    /// Counters since construction.
    pub fn stats(&self) -> Stats {
        self.stats
    }
    /// The first Euler warning seen (the watchdog keeps counting in [`Stats`]).
    pub fn first_euler_warning(&self) -> Option<EulerWarning> {
        self.first_warning
    }
    /// The mechanism.
    pub fn mechanism(&self) -> &M {
        &self.mech
    }
    /// The mechanism's info.
    pub fn info(&self) -> &'static MechanismInfo {
        self.info
    }
    /// The settings the integrator was built with.
    pub fn settings(&self) -> &HhtBuilder {
        &self.settings
    }

    /// Force joint `joint` exerts on body `body` at the current state (global frame).
    pub fn joint_force(&self, joint: usize, body: usize) -> Result<[f64; 3], Error> {
        reactions::joint_force(self.info, &self.phi_q_state, &self.lambda, joint, body)
    }

    /// Force of driver `joint` at the current state (`−λ` of its row).
    pub fn actuator_force(&self, joint: usize) -> Result<f64, Error> {
        reactions::actuator_force(self.info, &self.lambda, joint)
    }

    /// Wrench joint `joint` exerts on its body 1 at the current state, about the joint
    /// point ([`reactions::joint_wrench`]), from the integrator's own multipliers.
    pub fn joint_wrench(&self, joint: usize) -> Result<reactions::Wrench, Error> {
        reactions::joint_wrench(self.info, &self.q, &self.phi_q_state, &self.lambda, joint)
    }

    /// Effort of driver `joint` along its driven coordinate at the current state
    /// ([`reactions::driver_effort`]).
    pub fn driver_effort(&self, joint: usize) -> Result<f64, Error> {
        reactions::driver_effort(self.info, &self.lambda, joint)
    }

    /// Nonzeros of the mass matrix at the current state.
    #[allow(clippy::misnamed_getters)]
    pub fn mass(&self) -> &[f64] {
        &self.mass_state
    }

    /// Kinetic energy ½ q̇ᵀ M(q) q̇ at the current state.
    pub fn kinetic_energy(&self) -> f64 {
        crate::kinematics::kinetic_energy(self.info, &self.mass_state, &self.qd)
    }

    /// Kinetic plus potential energy at the current state.
    pub fn energy(&self) -> f64 {
        self.kinetic_energy() + self.mech.potential(&self.q)
    }

    fn evaluate_current(&mut self) {
        self.mech.eval_newton(
            &self.q,
            &self.qd,
            self.t,
            NewtonOutputs {
                phi: &mut self.phi,
                phi_q: &mut self.phi_q,
                mass: &mut self.mass,
                force: &mut self.force,
            },
        );
        self.stats.evaluations += 1;
    }

    /// `q̇ ← q̇ + Δ` with `[W Φqᵀ; Φq 0][Δ; μ] = [0; −(Φq q̇ + Φt)]`, through Newton's matrix
    /// of this step (W = cM, less the loads' stiffness and damping when they are in it), at
    /// the accepted state or a Newton iteration from it. The projection's metric is W: one
    /// kept from an earlier step ([`HhtBuilder::reuse_factorization`]) is refactored at the
    /// accepted state first, because W's damping rotates with the bodies (A05's governor: a
    /// metric kept over many steps moved the slider 5e-4 m off, 55 times the tolerance).
    fn project_velocity(&mut self, t: f64) -> Result<(), Error> {
        if self.factored_at != self.stats.steps {
            self.factor(self.h_prev, t, Iterate::Accepted)
                .map_err(|e| e.to_error(self.info, t))?;
        }
        self.mech.phi_t(&self.q, t, &mut self.res2);
        phi_q_times_add(self.info, &self.phi_q, &self.qd, &mut self.res2);
        for r in self.res2.iter_mut() {
            *r = -*r;
        }
        self.res1.fill(0.0);
        self.kkt
            .solve(&self.res1, &self.res2, &mut self.da, &mut self.dl)
            .map_err(|e| e.to_error(self.info, t))?;
        for (v, d) in self.qd.iter_mut().zip(&self.da) {
            *v += d;
        }
        Ok(())
    }

    /// `r_prev = Φqᵀλ − Q` from the evaluation buffers and `self.lambda`.
    fn store_generalized_reaction(&mut self) {
        phi_q_transpose_times(self.info, &self.phi_q, &self.lambda, &mut self.r_prev);
        for (r, &f) in self.r_prev.iter_mut().zip(&self.force) {
            *r -= f;
        }
    }

    /// Takes one step of the current step size (halving it internally on failure).
    pub fn step(&mut self) -> Result<StepReport, Error> {
        let h = self.h;
        self.step_to(self.t + h, h)
    }

    /// Integrates up to exactly `t_out` (the last step is shortened to land on it, and the
    /// one before evened out so no sliver of a step remains).
    pub fn advance_to(&mut self, t_out: f64) -> Result<(), Error> {
        while self.step_toward(t_out)?.is_some() {}
        Ok(())
    }

    /// One accepted step towards `t_out`, the steps [`Integrator::advance_to`] takes one
    /// call at a time (for callers that look at every step, e.g. an energy meter): the
    /// nominal step while two or more fit, then the remainder evened out over two steps, the
    /// last landing on `t_out` exactly. `Ok(None)` once `t_out` is reached (a floating-point
    /// sliver short of it is absorbed rather than stepped over).
    pub fn step_toward(&mut self, t_out: f64) -> Result<Option<StepReport>, Error> {
        if !(t_out >= self.t) || !t_out.is_finite() {
            return Err(Error::InvalidSetting {
                name: "t_out",
                value: t_out,
                reason: "must be finite and not before the current time",
            });
        }
        let remaining = t_out - self.t;
        if remaining == 0.0 {
            return Ok(None);
        }
        // A step of ~1e-16 s would divide roundoff by βh².
        if remaining <= 16.0 * f64::EPSILON * t_out.abs().max(1.0) {
            self.t = t_out;
            return Ok(None);
        }
        if remaining < self.settings.min_step {
            // Stepping over less than the minimum step would divide roundoff by βh²
            // beyond what the convergence test can judge.
            return Err(Error::InvalidSetting {
                name: "t_out",
                value: t_out,
                reason: "closer to the current time than the minimum step; \
                         request output times at least min_step apart",
            });
        }
        // Evening out must not leave a step below the minimum, which the next call would
        // refuse as an output time too close (a controlled step can be near the minimum).
        let report =
            if remaining <= self.h * (1.0 + 1e-9) || remaining < 2.0 * self.settings.min_step {
                self.step_to(t_out, remaining)?
            } else if remaining < 2.0 * self.h {
                let h = 0.5 * remaining;
                self.step_to(self.t + h, h)?
            } else {
                let h = self.h;
                self.step_to(self.t + h, h)?
            };
        Ok(Some(report))
    }

    /// One accepted step towards `t1 = t + h` (exactly `t1` when no cut is needed).
    fn step_to(&mut self, t1: f64, h: f64) -> Result<StepReport, Error> {
        if t1 <= self.t {
            // h is below the rounding step of t: no step can make progress.
            return Err(Error::InvalidSetting {
                name: "step",
                value: h,
                reason: "too small to advance the current time in floating point",
            });
        }
        let h_before = self.h;
        // A step shorter than the one proposed was shortened by the caller to land on an
        // output time: its error says nothing about the step the motion allows, so it
        // must not shrink the next one (`shortened` lasts until a rejection cuts it).
        let mut shortened = h < h_before;
        let mut cut = false;
        let mut h = h;
        let mut t1 = t1;
        let mut fresh_every_iteration = false;
        loop {
            let failure = match self.attempt(h, t1, fresh_every_iteration) {
                Ok(report) => {
                    let Some(tol) = self.settings.tolerances else {
                        return self.commit(report, h, t1);
                    };
                    let mut e = self.local_error(h, tol);
                    // Near a singular position the q̈ Newton reached carries roundoff amplified
                    // by about 1/σ, which Newton's own test need not have measured: measured
                    // here, the estimate does not count it as error.
                    if e.norm() > 1.0 && !self.noise_measured && self.measure_noise(h).is_ok() {
                        e = self.local_error(h, tol);
                    }
                    if e.norm() <= 1.0 {
                        let next = self.next_step(h, e, shortened, cut, h_before);
                        let accepted = self.commit(report, h, t1)?;
                        self.h = next;
                        self.ratio_prev = e.ratio();
                        return Ok(accepted);
                    }
                    self.stats.rejected_steps += 1;
                    self.stats.error_test_failures += 1;
                    self.need_factor = true;
                    self.rate = f64::NAN;
                    fresh_every_iteration = false;
                    (shortened, cut) = (false, true);
                    h *= e.factor().max(FAC_MIN);
                    t1 = self.t + h;
                    self.h = h;
                    if h < self.settings.min_step || t1 <= self.t {
                        self.h = h_before;
                        return Err(Error::ToleranceNotMet {
                            time: self.t,
                            step: h,
                            error: e.norm(),
                            coord: self.info.coord_names.get(e.worst).copied().unwrap_or("?"),
                            velocity: e.worst_is_velocity,
                            residual: report.residual,
                        });
                    }
                    continue;
                }
                Err(f) => f,
            };
            self.stats.rejected_steps += 1;
            self.need_factor = true;
            self.rate = f64::NAN;
            if !fresh_every_iteration {
                fresh_every_iteration = true;
                continue;
            }
            fresh_every_iteration = false;
            (shortened, cut) = (false, true);
            h *= 0.5;
            t1 = self.t + h;
            self.h = self.h.min(h);
            self.successes_since_cut = 0;
            if h < self.settings.min_step {
                // The next call starts from the step size this one was asked to take.
                self.h = h_before;
                return Err(match failure {
                    Failure::Kkt(e @ KktError::RankDeficient { .. })
                    | Failure::Kkt(e @ KktError::MassNotPositiveDefinite { .. }) => {
                        e.to_error(self.info, self.t)
                    }
                    Failure::NotConverged {
                        residual,
                        row,
                        increment,
                    } => Error::StepSizeTooSmall {
                        time: self.t,
                        step: h,
                        residual,
                        row: Some(ConstraintRow::new(self.info, row)),
                        increment: increment.map(|(size, c, constraint_force)| {
                            Box::new(NewtonIncrement {
                                size,
                                coord: self.info.coord_names.get(c).copied().unwrap_or("?"),
                                constraint_force,
                            })
                        }),
                    },
                    Failure::Kkt(_) | Failure::NotFinite => Error::StepSizeTooSmall {
                        time: self.t,
                        step: h,
                        residual: f64::NAN,
                        row: None,
                        increment: None,
                    },
                });
            }
        }
    }

    fn commit(&mut self, report: StepReport, h: f64, t1: f64) -> Result<StepReport, Error> {
        // A converged step into the singular region is still unusable: stop before it.
        let warning = self.settings.euler.check(self.info, t1, &self.q1)?;
        if let Some(w) = warning {
            self.stats.euler_warnings += 1;
            self.first_warning.get_or_insert(w);
        }
        self.t = t1;
        self.h_prev = h;
        std::mem::swap(&mut self.q, &mut self.q1);
        std::mem::swap(&mut self.qd, &mut self.qd1);
        // Step-size control always projects: index-3 HHT leaves a velocity-constraint
        // residual that a change of step turns into a jump of q̈ of about residual/(βh),
        // which the error test reads as error (measured on the pendulum: the steps fell
        // to the minimum at t ≈ 0.3 s without it).
        if self.settings.project_velocities || self.settings.tolerances.is_some() {
            self.project_velocity(t1)?;
        }
        // The accepted values become current, the current ones the predictor's history.
        self.predictor.push(
            h,
            (&mut self.qdd, &mut self.qdd1),
            (&mut self.lambda, &mut self.lambda1),
        );
        // The last evaluation was at the accepted state (see `attempt`).
        self.phi_q_state.copy_from_slice(&self.phi_q);
        self.mass_state.copy_from_slice(&self.mass);
        self.store_generalized_reaction();
        self.stats.steps += 1;
        if self.stats.steps == 1 {
            (self.stats.smallest_step, self.stats.largest_step) = (h, h);
        } else {
            self.stats.smallest_step = self.stats.smallest_step.min(h);
            self.stats.largest_step = self.stats.largest_step.max(h);
        }
        // With step-size control the error estimate proposes the next step (`step_to`).
        if self.settings.tolerances.is_none() && h < self.h_nominal {
            self.successes_since_cut += 1;
            if self.successes_since_cut >= GROWTH_DELAY {
                self.h = (2.0 * self.h).min(self.h_nominal);
                self.successes_since_cut = 0;
            }
        }
        Ok(StepReport { h, ..report })
    }

    /// One Newton solve of the step equations; on success `q1, qd1, qdd1, lambda1` hold the
    /// accepted state and the evaluation buffers were filled at it.
    fn attempt(
        &mut self,
        h: f64,
        t1: f64,
        fresh_every_iteration: bool,
    ) -> Result<StepReport, Failure> {
        let (max_iterations, phi_tol) = (self.settings.max_iterations, self.settings.phi_tol);
        let (alpha, beta, gamma) = (self.settings.alpha, self.beta, self.gamma);
        let c = 1.0 / (1.0 + alpha);
        let inv_bh2 = 1.0 / (beta * h * h);
        self.predictor.predict(
            h,
            (&self.qdd, &mut self.qdd1),
            (&self.lambda, &mut self.lambda1),
        );
        let mut last_err = f64::INFINITY;
        // The rate test's estimate of the error left in the current iterate (`rate_test`).
        let mut left = f64::INFINITY;
        let carried_rate = if self.settings.rate_test && self.rate_age < RATE_AGE_MAX {
            self.rate
        } else {
            f64::NAN
        };
        let mut residual = f64::NAN;
        // The last iteration's floors of the increments, for a report when Newton fails.
        let mut floors = None;
        self.noise_measured = false;
        let q_scale = inf_norm(&self.q).max(1.0);
        if !self.settings.reuse_factorization {
            self.need_factor = true;
        }
        for iter in 0..=max_iterations {
            let (hq, hv) = (0.5 * h * h, h);
            for i in 0..self.q.len() {
                let (a0, a1) = (self.qdd[i], self.qdd1[i]);
                self.q1[i] =
                    self.q[i] + h * self.qd[i] + hq * ((1.0 - 2.0 * beta) * a0 + 2.0 * beta * a1);
                self.qd1[i] = self.qd[i] + hv * ((1.0 - gamma) * a0 + gamma * a1);
            }
            self.mech.eval_newton(
                &self.q1,
                &self.qd1,
                t1,
                NewtonOutputs {
                    phi: &mut self.phi,
                    phi_q: &mut self.phi_q,
                    mass: &mut self.mass,
                    force: &mut self.force,
                },
            );
            self.stats.evaluations += 1;
            residual = inf_norm(&self.phi);
            if residual.is_nan() {
                return Err(Failure::NotFinite);
            }
            if iter > 0 && (last_err <= 1.0 || left <= RATE_TOL) && residual <= phi_tol {
                // Φ and the increments can be finite while a coordinate no row holds is not.
                if !inf_norm(&self.q1).is_finite() || !inf_norm(&self.qd1).is_finite() {
                    return Err(Failure::NotFinite);
                }
                if iter == 1 && last_err > 1.0 {
                    self.rate_age += 1;
                }
                return Ok(StepReport {
                    h,
                    iterations: iter,
                    residual,
                });
            }
            if iter == max_iterations {
                break;
            }
            // res1 = M q̈/(1+α) + Φqᵀλ − Q − α/(1+α) r_prev, negated for the solve.
            // Φqᵀλ is kept: the convergence test below judges the multipliers by it.
            mass_times(self.info, &self.mass, &self.qdd1, &mut self.res1);
            phi_q_transpose_times(self.info, &self.phi_q, &self.lambda1, &mut self.reaction1);
            let ac = alpha * c;
            for i in 0..self.res1.len() {
                self.res1[i] =
                    -(c * self.res1[i] + self.reaction1[i] - self.force[i] - ac * self.r_prev[i]);
            }
            for (r, &p) in self.res2.iter_mut().zip(&self.phi) {
                *r = -p * inv_bh2;
            }
            let fresh = self.need_factor || fresh_every_iteration;
            if fresh {
                self.factor(h, t1, Iterate::Step).map_err(Failure::Kkt)?;
            }
            self.kkt
                .solve(&self.res1, &self.res2, &mut self.da, &mut self.dl)
                .map_err(Failure::Kkt)?;
            self.stats.newton_iterations += 1;
            // Roundoff δ in Φ reaches the increments as δ/(βh²): below that floor an
            // increment is noise, so the weights never ask for more than it (at h = 1e-3 the
            // floor is ~1e-7, below the default tolerances; it matters only for tiny steps).
            let floor_a = NOISE_FACTOR * f64::EPSILON * q_scale * inv_bh2;
            let floor_l = floor_a * inf_norm(&self.mass);
            floors = Some((floor_a, floor_l));
            // The multipliers are judged by the forces they apply, Φqᵀλ (see
            // `abs_tol_lambda`); the right-hand side is consumed, so res1 takes Φqᵀ·Δλ.
            phi_q_transpose_times(self.info, &self.phi_q, &self.dl, &mut self.res1);
            let mut err = self.weighted_increment((floor_a, floor_l)).0;
            if !err.is_finite() {
                return Err(Failure::NotFinite);
            }
            let mut stalled = iter >= 1 && err > SLOW_RATE * last_err;
            let mut noise_limited = false;
            if stalled && err > 1.0 {
                // Stalled above the tolerance: if what is left is what roundoff alone makes
                // of an increment through this factorization, Newton is done.
                let (noise_a, noise_l) = self.measure_noise(h).map_err(Failure::Kkt)?;
                let at_noise = self
                    .weighted_increment((floor_a.max(noise_a), floor_l.max(noise_l)))
                    .0;
                if at_noise <= 1.0 {
                    err = at_noise;
                    stalled = false;
                    noise_limited = true;
                    self.stats.noise_limited += 1;
                }
            }
            // ρ from two increments through one factorization (across a refactorization it
            // measures the change of matrix); after the first increment, an earlier step's.
            let rate = if iter >= 1 && !fresh && !noise_limited {
                let rho = err / last_err;
                self.rate = rho;
                self.rate_age = 0;
                rho
            } else if iter == 0 {
                carried_rate
            } else {
                f64::NAN
            };
            left = if !self.settings.rate_test || noise_limited || !(rate < 1.0) {
                f64::INFINITY
            } else {
                rate / (1.0 - rate) * err
            };
            if stalled {
                if err > 4.0 * last_err && iter >= 2 {
                    return Err(Failure::NotConverged {
                        residual,
                        row: largest_row(&self.phi),
                        increment: floors.map(|f| self.weighted_increment(f)),
                    });
                }
                self.need_factor = true;
            }
            for (a, d) in self.qdd1.iter_mut().zip(&self.da) {
                *a += d;
            }
            for (l, d) in self.lambda1.iter_mut().zip(&self.dl) {
                *l += d;
            }
            last_err = err;
        }
        Err(Failure::NotConverged {
            residual,
            row: largest_row(&self.phi),
            increment: floors.map(|f| self.weighted_increment(f)),
        })
    }
}

impl<M: Mechanism, K: KktSolver> Integrator<M, K> {
    /// Factors Newton's matrix with the evaluation buffers (Φq, M) and, with the loads'
    /// stiffness, their Jacobians at `at` (time `t`) for a step of size `h`.
    fn factor(&mut self, h: f64, t: f64, at: Iterate) -> Result<(), KktError> {
        let (beta, gamma) = (self.beta, self.gamma);
        let c = 1.0 / (1.0 + self.settings.alpha);
        let factored = match &mut self.stiffness {
            None => self.kkt.factor(&self.mass, c, &self.phi_q),
            Some(st) => {
                let (q, qd) = match at {
                    Iterate::Step => (&self.q1, &self.qd1),
                    Iterate::Accepted => (&self.q, &self.qd),
                };
                self.mech.force_jacobian(q, qd, t, &mut st.dq, &mut st.dqd);
                // A load whose symmetric stiffness has a negative part (a spring's
                // geometric term) can outweigh M in some direction: A05's governor beyond
                // h ≈ 1e-3 s, whose rods have 5e-6 kg·m² about their own axis. The damping
                // part of a passive load is positive semi-definite, and it is the one that
                // limits Newton (γh·c/m ≫ βh²·k/m), so it is kept when the stiffness has to
                // go; M alone is the last resort.
                let mut result = Err(KktError::NotFactored);
                for (kq, kqd) in [(beta * h * h, gamma * h), (0.0, gamma * h), (0.0, 0.0)] {
                    let a = st.assemble(&self.mass, c, kq, kqd);
                    result = self.kkt.factor(a, 1.0, &self.phi_q);
                    if !matches!(result, Err(KktError::MassNotPositiveDefinite { .. })) {
                        break;
                    }
                }
                result
            }
        };
        self.need_factor = factored.is_err();
        factored?;
        self.stats.factorizations += 1;
        self.factored_at = self.stats.steps;
        Ok(())
    }

    /// The roundoff floors of the increments of q̈ and of Φqᵀλ through the current
    /// factorization of a step of size `h`, at the last iterate (`NoiseProbe`; it keeps them
    /// coordinate by coordinate for the local error estimate, `noise_measured`).
    fn measure_noise(&mut self, h: f64) -> Result<(f64, f64), KktError> {
        let c = 1.0 / (1.0 + self.settings.alpha);
        // |q|/(βh²): the right-hand side of a unit error in Φ.
        let scale = inf_norm(&self.q).max(1.0) * (1.0 / (self.beta * h * h));
        let parts = ResidualParts {
            mass: &self.mass,
            c,
            qdd: &self.qdd1,
            reaction: &self.reaction1,
            force: &self.force,
            previous: &self.r_prev,
            previous_weight: self.settings.alpha * c,
        };
        self.noise
            .measure(&mut self.kkt, self.info, &self.phi_q, &parts, scale)?;
        self.noise_measured = true;
        Ok(self.noise.floor)
    }

    /// Weighted RMS norms of the local error estimates of the step of size `h` just
    /// converged (`q1, qd1, qdd1` from the accepted `q, qd, qdd`; the predictor's q̈ one
    /// step further back, over `h_prev`), positions and velocities apart, with the weights
    /// `atol + rtol·max(|xₙ|, |xₙ₊₁|)` of `tol = (rtol, atol)`. Multipliers are not judged.
    ///
    /// Both are built on the change of the step's mean acceleration `ā = (q̇ₙ₊₁ − q̇ₙ)/h =
    /// (1 − γ) q̈ₙ + γ q̈ₙ₊₁` rather than of `q̈` itself: index-3 HHT's accelerations carry
    /// the parasitic mode of ratio `−(1 + α)/(1 − α)`, undamped at α = 0, which a step
    /// change excites and which a difference of `q̈` would read as error (measured on the
    /// pendulum: at rtol 1e-8 and α = 0 the steps fell to 7e-7 s); the mean cancels it at
    /// α = 0 and reduces it to O(α) otherwise. `Δā ≈ ½(h + hₚ) q⃛`.
    ///
    /// Velocities: `½ h·Δā`, the difference between the corrected velocity and its
    /// predictor `q̇ₙ + h āₙ`, O(h²). It overestimates HHT's velocity error (O(h³): the
    /// α-shift of the accelerations cancels the `h²` term) by ~6/(hω), which is what makes
    /// it useful: kept at the tolerance per step, it holds the global error near the
    /// tolerance (error per unit step), where a sharp O(h³) estimate lets the error of an
    /// oscillation's phase grow with the number of steps (measured on the pendulum: 30–1000×
    /// the tolerance, no fewer steps than a fixed step of the same error).
    ///
    /// Positions: HHT's accelerations are those of the exact motion at `t + αh`, so the
    /// Newmark position formula leaves `−(1/12 + α²/4) h³ q⃛` (Zienkiewicz–Xie's
    /// `(β − 1/6) h² Δq̈` with HHT's shift αh/2 added), O(h³), from `h q⃛ ≈ 2h Δā/(h + hₚ)`.
    /// It is the predictor–corrector difference `qₙ₊₁ − (qₙ + h q̇ₙ + h²/2 q̈ₙ) = βh² Δq̈`
    /// rescaled to the error it measures. On the first step (no history) `Δā` is `Δq̈`.
    ///
    /// Where the probe measured it (`NoiseProbe::accel`), the weights take the roundoff of q̈
    /// through the factorization, coordinate by coordinate, as the Newton test takes its
    /// floor (decision 27). Near a singular position it grows like 1/(σh²) along the
    /// direction Φq loses, so an estimate that counted it as error would grow as the step
    /// shrinks and never pass (A02 at rtol 1e-6 stopped at a flat position).
    fn local_error(&self, h: f64, (rtol, atol): (f64, f64)) -> LocalError {
        let (alpha, gamma) = (self.settings.alpha, self.gamma);
        let hp = self.h_prev;
        // h q⃛ from the mean's change (over ½(h + hₚ)), or from Δq̈ itself on the first step.
        let h_dddq = if hp > 0.0 { 2.0 * h / (h + hp) } else { 1.0 };
        let cq = (1.0 / 12.0 + 0.25 * alpha * alpha) * h * h * h_dddq;
        let cv = 0.5 * h;
        let (mut sq, mut sv) = (0.0, 0.0);
        let mut largest = (0.0, 0, false);
        for i in 0..self.q.len() {
            let d1 = self.qdd1[i] - self.qdd[i];
            let dmean = if hp > 0.0 {
                (1.0 - gamma) * (self.qdd[i] - self.predictor.previous_qdd()[i]) + gamma * d1
            } else {
                d1
            };
            let noise = if self.noise_measured {
                self.noise.accel[i]
            } else {
                0.0
            };
            let wq = atol + rtol * self.q[i].abs().max(self.q1[i].abs()) + cq * noise;
            let wv = atol + rtol * self.qd[i].abs().max(self.qd1[i].abs()) + cv * noise;
            let (eq, ev) = (cq * dmean.abs() / wq, cv * dmean.abs() / wv);
            sq += eq * eq;
            sv += ev * ev;
            for (e, velocity) in [(eq, false), (ev, true)] {
                // `!(e <= …)` so that a NaN is the one reported.
                if !(e <= largest.0) {
                    largest = (e, i, velocity);
                }
            }
        }
        let n = self.q.len().max(1) as f64;
        LocalError {
            position: (sq / n).sqrt(),
            velocity: (sv / n).sqrt(),
            worst: largest.1,
            worst_is_velocity: largest.2,
        }
    }

    /// The step the control proposes after accepting one of size `h` whose error gave
    /// `factor`: growth at most `FAC_MAX`, none right after a rejection (`cut`); a step the
    /// caller `shortened` (from `proposed`) for an output never lowers the proposal.
    ///
    /// The factor is the smaller of the error's own and Gustafsson's predictive one (as
    /// RADAU5), which also follows the error's trend over the last two steps: where the
    /// estimate does not shrink like h^order (stiff components far beyond their time scale,
    /// A05's damper) the plain factor alternates growth and rejection (measured on A05 at
    /// rtol 1e-4: 1 071 rejections in 1 085 steps).
    fn next_step(&self, h: f64, e: LocalError, shortened: bool, cut: bool, proposed: f64) -> f64 {
        let mut factor = e.factor();
        if self.ratio_prev > 0.0 && self.h_prev > 0.0 && e.ratio() > 0.0 {
            let r = e.ratio();
            factor = factor.min(SAFETY * (h / self.h_prev) * (self.ratio_prev / (r * r)));
        }
        let next = if cut {
            (h * factor).clamp(FAC_MIN * h, h)
        } else if shortened {
            (h * factor).clamp(proposed, FAC_MAX * proposed)
        } else {
            (h * factor).clamp(FAC_MIN * h, FAC_MAX * h)
        };
        next.min(self.settings.max_step).max(self.settings.min_step)
    }

    /// The largest increment of `q̈` (`self.da`) and of Φqᵀλ (`self.res1`), each relative to
    /// its tolerance, with the absolute tolerances raised to the noise floors `(floor_a,
    /// floor_l)`; with it, the coordinate where it is largest and whether in Φqᵀλ (for the
    /// error of a failed step).
    fn weighted_increment(&self, (floor_a, floor_l): (f64, f64)) -> (f64, usize, bool) {
        let s = &self.settings;
        let mut worst = (0.0, 0, false);
        for i in 0..self.da.len() {
            let acc =
                self.da[i].abs() / (s.abs_tol_acc.max(floor_a) + s.rel_tol * self.qdd1[i].abs());
            let force = self.res1[i].abs()
                / (s.abs_tol_lambda.max(floor_l) + s.rel_tol * self.reaction1[i].abs());
            if acc > worst.0 {
                worst = (acc, i, false);
            }
            if force > worst.0 {
                worst = (force, i, true);
            }
        }
        worst
    }
}

/// What roundoff alone makes of a Newton increment through the current factorization:
/// the convergence test never asks Newton to go below it.
///
/// Roundoff δ in Φ reaches the right-hand side as δ/(βh²), about ε·|q|/(βh²); the residual's
/// own roundoff is ε times the magnitudes it is summed from. Solving with both, under a few
/// fixed sign patterns ([`probe_sign`]), measures what the factorization makes of them (the
/// largest of the patterns' answers): about themselves for
/// a regular mechanism, but 1/σ times more where Φq is nearly singular (a linkage crossing a
/// flat position), where a fixed floor would leave Newton chasing noise until the step fails.
#[derive(Debug)]
struct NoiseProbe {
    /// The roundoff of the residual's entries, unsigned: the same for every sign pattern.
    size: Vec<f64>,
    /// The signed right-hand side: roundoff of the residual's entries, and of Φ's.
    f: Vec<f64>,
    g: Vec<f64>,
    x: Vec<f64>,
    y: Vec<f64>,
    /// Floors of the acceleration and Φqᵀλ increments.
    floor: (f64, f64),
    /// The roundoff's largest answer in each acceleration, without the floor's base: near
    /// a singular position it grows along the direction Φq loses, not in every coordinate.
    accel: Vec<f64>,
}

impl NoiseProbe {
    fn new(n: usize, m: usize) -> Self {
        NoiseProbe {
            size: vec![0.0; n],
            f: vec![0.0; n],
            g: vec![0.0; m],
            x: vec![0.0; n],
            y: vec![0.0; m],
            floor: (0.0, 0.0),
            accel: vec![0.0; n],
        }
    }

    /// `scale`: |q|/(βh²), the right-hand side of a unit error in Φ.
    fn measure<K: KktSolver>(
        &mut self,
        kkt: &mut K,
        info: &MechanismInfo,
        phi_q: &[f64],
        r: &ResidualParts<'_>,
        scale: f64,
    ) -> Result<(), KktError> {
        let g0 = NOISE_FACTOR * f64::EPSILON * scale;
        let m = self.g.len();
        let (mut floor_a, mut floor_l) = (g0, g0 * inf_norm(r.mass));
        self.accel.fill(0.0);
        mass_times(info, r.mass, r.qdd, &mut self.size);
        for (i, size) in self.size.iter_mut().enumerate() {
            *size = NOISE_FACTOR
                * f64::EPSILON
                * ((r.c * *size).abs()
                    + r.reaction[i].abs()
                    + r.force[i].abs()
                    + (r.previous_weight * r.previous[i]).abs());
        }
        for pattern in 0..probe_patterns(m + self.f.len()) {
            for (i, g) in self.g.iter_mut().enumerate() {
                *g = probe_sign(pattern, i) * g0;
            }
            for (i, (f, &size)) in self.f.iter_mut().zip(&self.size).enumerate() {
                *f = probe_sign(pattern, m + i) * size;
            }
            kkt.solve(&self.f, &self.g, &mut self.x, &mut self.y)?;
            floor_a = floor_a.max(inf_norm(&self.x));
            for (a, x) in self.accel.iter_mut().zip(&self.x) {
                *a = a.max(x.abs());
            }
            phi_q_transpose_times(info, phi_q, &self.y, &mut self.x);
            floor_l = floor_l.max(inf_norm(&self.x));
        }
        self.floor = (floor_a, floor_l);
        Ok(())
    }
}

/// What HHT's force residual `c·M q̈ + Φqᵀλ − Q − αc·r_prev` is summed from, at one iterate.
struct ResidualParts<'a> {
    mass: &'a [f64],
    c: f64,
    qdd: &'a [f64],
    reaction: &'a [f64],
    force: &'a [f64],
    previous: &'a [f64],
    previous_weight: f64,
}

/// How many sign patterns [`probe_sign`] has for `rows` rows: pseudo-random, all equal, and
/// one per bit of a row's index.
fn probe_patterns(rows: usize) -> usize {
    2 + (usize::BITS - rows.saturating_sub(1).leading_zeros()) as usize
}

/// The sign of row `i` in probe pattern `pattern`. One sign vector can be orthogonal to the
/// direction Φq nearly loses, and then the probe sees no amplification at all: at a flat
/// position of a linkage that direction lives on a few rows of one loop, and two rows with
/// the same pseudo-random sign and opposite weights cancel (the Euler-angle A02 with N = 2
/// stalled so at t = 0.714 s, its floor underestimated 70–300×). Among pseudo-random signs,
/// equal signs and one pattern per bit of the index, any two rows have equal signs in one
/// pattern and opposite signs in another, so no direction on two rows hides from all.
fn probe_sign(pattern: usize, i: usize) -> f64 {
    let negative = match pattern {
        0 => (i as u64 + 1).wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 63 == 1,
        1 => false,
        bit => (i >> (bit - 2)) & 1 == 1,
    };
    if negative {
        -1.0
    } else {
        1.0
    }
}

#[cfg(test)]
#[path = "hht_tests.rs"]
mod tests;
