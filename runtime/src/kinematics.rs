//! Kinematic analysis and the consistent start: positions by Newton with mass-weighted
//! minimum-norm corrections, velocities of least kinetic energy, accelerations and
//! multipliers from the saddle-point system — all through one KKT solver.
//!
//! Every correction solves `[M Φqᵀ; Φq 0][Δ; μ] = [f; g]`, so directions the constraints
//! leave free (a Stewart leg's spin about its own axis) are not moved by position
//! corrections and get no velocity of their own unless asked for.

use crate::error::{check_len, ConstraintRow, Error};
use crate::kkt::{KktKernels, KktPattern, KktSolver, SchurKkt, TimesKernel};
use crate::mechanism::{Mechanism, MechanismInfo};

/// Settings of the position Newton iteration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KinematicSettings {
    /// Converged when the unscaled residual |Φ|∞ is at or below this (default 1e-11, in the
    /// units of the constraints: metres or radians, a few hundred roundoffs at unit scale).
    pub position_tolerance: f64,
    /// Maximum Newton iterations (default 30; Newton from a nearby point needs 3–5).
    pub max_iterations: usize,
    /// Drop rows whose relative pivot falls below this instead of failing with rank loss
    /// ([`KktSolver::drop_dependent_rows`]; default `None`): for mechanisms that pass
    /// singular positions, where the multipliers are then one valid choice.
    pub drop_dependent_rows: Option<f64>,
}

impl Default for KinematicSettings {
    fn default() -> Self {
        KinematicSettings {
            position_tolerance: 1e-11,
            max_iterations: 30,
            drop_dependent_rows: None,
        }
    }
}

/// How [`Kinematics::consistent_start`] chooses the initial velocity.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum InitialVelocity {
    /// The consistent velocity of least kinetic energy: `[M Φqᵀ; Φq 0][q̇; μ] = [0; −Φt]`
    /// (docs/paper-scenario.md, "Initial velocities"). The given `qd` is ignored.
    #[default]
    LeastKineticEnergy,
    /// The consistent velocity closest to the given `qd` in the kinetic-energy norm.
    ProjectGiven,
}

/// Result of a converged position analysis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PositionReport {
    /// Newton iterations taken (0 when the start already satisfied the tolerance).
    pub iterations: usize,
    /// Final |Φ|∞ over all rows, redundant ones included.
    pub residual: f64,
}

/// Newton iterations allowed past convergence of the independent rows while a redundant
/// row is still above the tolerance: a consistent redundant row is a combination of the
/// others, so one more (quadratically convergent) step brings it down to roundoff; one that
/// stays up contradicts them.
const POLISH_ITERATIONS: usize = 2;

/// Work memory and settings for kinematic analyses of one mechanism.
#[derive(Debug, Clone)]
pub struct Kinematics<K: KktSolver = SchurKkt> {
    info: &'static MechanismInfo,
    settings: KinematicSettings,
    kkt: K,
    phi: Vec<f64>,
    phi_q: Vec<f64>,
    phi_t: Vec<f64>,
    gamma: Vec<f64>,
    mass: Vec<f64>,
    force: Vec<f64>,
    f: Vec<f64>,
    g: Vec<f64>,
    dq: Vec<f64>,
    mu: Vec<f64>,
}

pub(crate) fn inf_norm(v: &[f64]) -> f64 {
    // NaN must not hide behind `max`, so it is propagated explicitly. The loop stays
    // branch-free (it runs on every Newton iteration): `x * 0` is NaN exactly when `x` is
    // NaN or infinite, and only then is the slow path taken. Four independent maxima, each
    // a plain comparison (`f64::max` orders NaN, which keeps it out of vector registers),
    // so the loop is not one chain of dependent maxima.
    let (mut m, mut poison) = ([0.0f64; 4], [0.0f64; 4]);
    let chunks = v.chunks_exact(4);
    let rest = chunks.remainder();
    for c in chunks {
        for i in 0..4 {
            let a = c[i].abs();
            m[i] = if a > m[i] { a } else { m[i] };
            poison[i] += c[i] * 0.0;
        }
    }
    for (i, &x) in rest.iter().enumerate() {
        let a = x.abs();
        m[i] = if a > m[i] { a } else { m[i] };
        poison[i] += x * 0.0;
    }
    let poison = (poison[0] + poison[1]) + (poison[2] + poison[3]);
    if poison.is_nan() && v.iter().any(|x| x.is_nan()) {
        f64::NAN
    } else {
        m[0].max(m[1]).max(m[2].max(m[3]))
    }
}

/// Index of the entry of largest magnitude (0 for an empty slice).
pub(crate) fn largest_row(v: &[f64]) -> usize {
    (0..v.len())
        .max_by(|&a, &b| v[a].abs().total_cmp(&v[b].abs()))
        .unwrap_or(0)
}

/// `½ q̇ᵀ M q̇` from the mass nonzeros.
pub fn kinetic_energy(info: &MechanismInfo, mass: &[f64], qd: &[f64]) -> f64 {
    if let Some(Ok(t)) = mass_kernels(info).map(|k| (k.kinetic_energy)(mass, qd)) {
        return t;
    }
    let mut t = 0.0;
    for ((&r, &c), &m) in info.mass_rows.iter().zip(info.mass_cols).zip(mass) {
        t += qd[r as usize] * m * qd[c as usize];
    }
    0.5 * t
}

/// `out = Φqᵀ y` from the Jacobian nonzeros.
pub(crate) fn phi_q_transpose_times(
    info: &MechanismInfo,
    phi_q: &[f64],
    y: &[f64],
    out: &mut [f64],
) {
    if let Some(Ok(())) = phi_q_kernel(info, |k| k.transpose_times).map(|t| t(phi_q, y, out)) {
        return;
    }
    out.fill(0.0);
    for ((&r, &c), &v) in info.phi_q_rows.iter().zip(info.phi_q_cols).zip(phi_q) {
        out[c as usize] += v * y[r as usize];
    }
}

/// `out += Φq x` from the Jacobian nonzeros, each row's products added in their order.
pub(crate) fn phi_q_times_add(info: &MechanismInfo, phi_q: &[f64], x: &[f64], out: &mut [f64]) {
    if let Some(Ok(())) = phi_q_kernel(info, |k| k.times_add).map(|t| t(phi_q, x, out)) {
        return;
    }
    for ((&r, &c), &v) in info.phi_q_rows.iter().zip(info.phi_q_cols).zip(phi_q) {
        out[r as usize] += v * x[c as usize];
    }
}

/// The model's generated Φq kernel `pick` chooses, where `info`'s pattern is the one it was
/// emitted for.
fn phi_q_kernel(info: &MechanismInfo, pick: fn(&KktKernels) -> TimesKernel) -> Option<TimesKernel> {
    let kernels = info.kkt.first()?;
    kernels
        .emitted_for(info.phi_q_rows, info.phi_q_cols)
        .then(|| pick(kernels))
}

/// The model's generated kernels, where `info`'s mass pattern is the one they were emitted
/// for.
fn mass_kernels(info: &MechanismInfo) -> Option<&KktKernels> {
    let kernels = info.kkt.first()?;
    kernels
        .mass_emitted_for(info.mass_rows, info.mass_cols)
        .then_some(kernels)
}

/// `out = M v` from the mass nonzeros.
pub(crate) fn mass_times(info: &MechanismInfo, mass: &[f64], v: &[f64], out: &mut [f64]) {
    if let Some(Ok(())) = mass_kernels(info).map(|k| (k.mass_times)(mass, v, out)) {
        return;
    }
    out.fill(0.0);
    for ((&r, &c), &m) in info.mass_rows.iter().zip(info.mass_cols).zip(mass) {
        out[r as usize] += m * v[c as usize];
    }
}

impl<K: KktSolver> Kinematics<K> {
    /// Allocates all work memory for `info`'s mechanism, with default settings.
    pub fn new(info: &'static MechanismInfo) -> Result<Self, Error> {
        Self::with_settings(info, KinematicSettings::default())
    }

    /// As [`Kinematics::new`] with explicit settings.
    pub fn with_settings(
        info: &'static MechanismInfo,
        settings: KinematicSettings,
    ) -> Result<Self, Error> {
        if !(settings.position_tolerance > 0.0) || !settings.position_tolerance.is_finite() {
            return Err(Error::InvalidSetting {
                name: "position_tolerance",
                value: settings.position_tolerance,
                reason: "must be positive and finite",
            });
        }
        let (n, m) = (info.n_coords, info.n_constraints);
        check_len("coord_names", n, info.coord_names.len())?;
        check_len("row_names", m, info.row_names.len())?;
        let mut kkt = K::new(&KktPattern::from_info(info))?;
        if let Some(tolerance) = settings.drop_dependent_rows {
            if !(tolerance > 0.0 && tolerance < 1.0 && kkt.drop_dependent_rows(tolerance)) {
                return Err(Error::InvalidSetting {
                    name: "drop_dependent_rows",
                    value: tolerance,
                    reason: "must lie in (0, 1), with a KKT solver that can drop rows (SchurKkt, unless a zero principal inertia makes it solve densely)",
                });
            }
        }
        Ok(Kinematics {
            info,
            settings,
            kkt,
            phi: vec![0.0; m],
            phi_q: vec![0.0; info.phi_q_nnz()],
            phi_t: vec![0.0; m],
            gamma: vec![0.0; m],
            mass: vec![0.0; info.mass_nnz()],
            force: vec![0.0; n],
            f: vec![0.0; n],
            g: vec![0.0; m],
            dq: vec![0.0; n],
            mu: vec![0.0; m],
        })
    }

    /// The settings in use.
    pub fn settings(&self) -> KinematicSettings {
        self.settings
    }

    /// The conditioning of the last factorization (see [`crate::kkt::Pivots`]).
    pub fn pivots(&self) -> Option<crate::kkt::Pivots> {
        self.kkt.pivots()
    }

    /// Φq nonzeros of the last velocity or acceleration analysis, at its state (after a
    /// position analysis: at the last Newton iterate before the converged one).
    pub fn phi_q(&self) -> &[f64] {
        &self.phi_q
    }

    /// Mass-matrix nonzeros of the last velocity or acceleration analysis, at its state.
    pub fn mass(&self) -> &[f64] {
        &self.mass
    }

    /// Φt of the last velocity analysis, at its state.
    pub fn phi_t(&self) -> &[f64] {
        &self.phi_t
    }

    fn check_mech<M: Mechanism>(&self, mech: &M) -> Result<(), Error> {
        let info = mech.info();
        check_len("mechanism coordinates", self.info.n_coords, info.n_coords)?;
        check_len(
            "mechanism constraints",
            self.info.n_constraints,
            info.n_constraints,
        )?;
        check_len("Φq nonzeros", self.info.phi_q_nnz(), info.phi_q_nnz())?;
        check_len("mass nonzeros", self.info.mass_nnz(), info.mass_nnz())
    }

    /// Solves Φ(q, t) = 0 by Newton from the given `q`, each correction the smallest in
    /// the mass norm. `q` is updated in place only on success; on failure it is left at the
    /// last iterate, and the error names the time, residual and iterations.
    ///
    /// Newton converges on the independent rows (the KKT solver drops the redundant ones);
    /// the redundant rows must then hold too, or the result is
    /// [`Error::InconsistentConstraints`] naming them.
    pub fn position<M: Mechanism>(
        &mut self,
        mech: &M,
        t: f64,
        q: &mut [f64],
    ) -> Result<PositionReport, Error> {
        self.check_mech(mech)?;
        check_len("q", self.info.n_coords, q.len())?;
        let info = self.info;
        let tol = self.settings.position_tolerance;
        // A NaN or infinite coordinate that no constraint row holds would leave Φ finite
        // and "converge" with it still in q.
        if !inf_norm(q).is_finite() {
            return Err(Error::NotFinite {
                time: t,
                what: "coordinates q given to position analysis",
            });
        }
        self.f.fill(0.0);
        // The iterate closest to Φ = 0 and its worst row: what to report if Newton fails (a
        // diverged last iterate would name an arbitrary row).
        let mut best = (f64::INFINITY, 0usize);
        let mut polish = 0;
        for it in 0..=self.settings.max_iterations {
            mech.phi(q, t, &mut self.phi);
            // The redundant rows are judged separately, then zeroed: the solver ignores
            // their right-hand side, and the independent rows decide convergence.
            let mut redundant = 0.0f64;
            let mut nan = false;
            for &r in info.redundant_rows {
                let v = self.phi[r as usize];
                nan |= v.is_nan();
                redundant = redundant.max(v.abs());
                self.phi[r as usize] = 0.0;
            }
            let residual = inf_norm(&self.phi);
            if residual.is_nan() || nan {
                return Err(Error::NotFinite {
                    time: t,
                    what: "constraint residual Φ in position analysis",
                });
            }
            if residual < best.0 {
                best = (residual, largest_row(&self.phi));
            }
            if residual <= tol {
                if redundant <= tol {
                    // Φ can hold while a correction of a coordinate outside it overflowed.
                    if !inf_norm(q).is_finite() {
                        return Err(Error::NotFinite {
                            time: t,
                            what: "coordinates q in position analysis",
                        });
                    }
                    return Ok(PositionReport {
                        iterations: it,
                        residual: residual.max(redundant),
                    });
                }
                if polish == POLISH_ITERATIONS || it == self.settings.max_iterations {
                    return Err(self.inconsistent(mech, t, q, redundant));
                }
                polish += 1;
            }
            if it == self.settings.max_iterations {
                break;
            }
            mech.phi_q(q, t, &mut self.phi_q);
            if it == 0 || !info.mass_is_constant {
                mech.mass(q, &mut self.mass);
            }
            self.kkt
                .factor(&self.mass, 1.0, &self.phi_q)
                .map_err(|e| e.to_error(info, t))?;
            for (g, &p) in self.g.iter_mut().zip(&self.phi) {
                *g = -p;
            }
            self.kkt
                .solve(&self.f, &self.g, &mut self.dq, &mut self.mu)
                .map_err(|e| e.to_error(info, t))?;
            for (qi, d) in q.iter_mut().zip(&self.dq) {
                *qi += d;
            }
        }
        Err(Error::NewtonFailed {
            analysis: "position analysis",
            time: t,
            residual: best.0,
            iterations: self.settings.max_iterations,
            row: Some(ConstraintRow::new(info, best.1)),
        })
    }

    /// Simplified Newton on Φ(q, t) = 0 with the factorization left by the last velocity or
    /// acceleration analysis (a nearby state), at most `max_iterations` corrections. Returns
    /// the iterations taken when it converged; `None` when it did not (q is then somewhere
    /// near and a full [`Kinematics::position`] should follow). Only valid right after an
    /// analysis of this mechanism: the caller guarantees that.
    pub(crate) fn position_chord<M: Mechanism>(
        &mut self,
        mech: &M,
        t: f64,
        q: &mut [f64],
        max_iterations: usize,
    ) -> Result<Option<PositionReport>, Error> {
        let info = self.info;
        let tol = self.settings.position_tolerance;
        self.f.fill(0.0);
        for it in 0..=max_iterations {
            mech.phi(q, t, &mut self.phi);
            // A NaN redundant row must stop convergence (`max` would drop it).
            let (mut redundant, mut converged) = (0.0f64, true);
            for &r in info.redundant_rows {
                let v = self.phi[r as usize].abs();
                converged &= v <= tol;
                redundant = redundant.max(v);
                self.phi[r as usize] = 0.0;
            }
            let residual = inf_norm(&self.phi);
            if residual.is_nan() {
                return Err(Error::NotFinite {
                    time: t,
                    what: "constraint residual Φ in position analysis",
                });
            }
            if residual <= tol && converged {
                return Ok(Some(PositionReport {
                    iterations: it,
                    residual: residual.max(redundant),
                }));
            }
            if it == max_iterations {
                break;
            }
            for (g, &p) in self.g.iter_mut().zip(&self.phi) {
                *g = -p;
            }
            self.kkt
                .solve(&self.f, &self.g, &mut self.dq, &mut self.mu)
                .map_err(|e| e.to_error(info, t))?;
            for (qi, d) in q.iter_mut().zip(&self.dq) {
                *qi += d;
            }
        }
        Ok(None)
    }

    /// The error for redundant rows left unsatisfied at `q` (error path: allocates).
    fn inconsistent<M: Mechanism>(&mut self, mech: &M, t: f64, q: &[f64], residual: f64) -> Error {
        let info = self.info;
        mech.phi(q, t, &mut self.phi);
        let tol = self.settings.position_tolerance;
        Error::InconsistentConstraints {
            time: t,
            rows: info
                .redundant_rows
                .iter()
                .map(|&r| r as usize)
                .filter(|&r| !(self.phi[r].abs() <= tol))
                .map(|r| ConstraintRow::new(info, r))
                .collect(),
            residual,
        }
    }

    /// The consistent velocity (Φq q̇ = −Φt) of least kinetic energy, written to `qd`.
    pub fn velocity<M: Mechanism>(
        &mut self,
        mech: &M,
        t: f64,
        q: &[f64],
        qd: &mut [f64],
    ) -> Result<(), Error> {
        self.velocity_impl(mech, t, q, qd, false)
    }

    /// Replaces `qd` by the consistent velocity closest to it in the kinetic-energy norm.
    pub fn project_velocity<M: Mechanism>(
        &mut self,
        mech: &M,
        t: f64,
        q: &[f64],
        qd: &mut [f64],
    ) -> Result<(), Error> {
        self.velocity_impl(mech, t, q, qd, true)
    }

    fn velocity_impl<M: Mechanism>(
        &mut self,
        mech: &M,
        t: f64,
        q: &[f64],
        qd: &mut [f64],
        project: bool,
    ) -> Result<(), Error> {
        self.check_mech(mech)?;
        check_len("q", self.info.n_coords, q.len())?;
        check_len("qd", self.info.n_coords, qd.len())?;
        let info = self.info;
        mech.phi_q(q, t, &mut self.phi_q);
        mech.phi_t(q, t, &mut self.phi_t);
        mech.mass(q, &mut self.mass);
        if project {
            // min ½(v − v*)ᵀM(v − v*) s.t. Φq v = −Φt  ⇒  M v + Φqᵀμ = M v*.
            mass_times(info, &self.mass, qd, &mut self.f);
        } else {
            self.f.fill(0.0);
        }
        for (g, &p) in self.g.iter_mut().zip(&self.phi_t) {
            *g = -p;
        }
        self.kkt
            .factor(&self.mass, 1.0, &self.phi_q)
            .map_err(|e| e.to_error(info, t))?;
        self.kkt
            .solve(&self.f, &self.g, qd, &mut self.mu)
            .map_err(|e| e.to_error(info, t))?;
        if !inf_norm(qd).is_finite() {
            return Err(Error::NotFinite {
                time: t,
                what: "velocity analysis",
            });
        }
        Ok(())
    }

    /// Accelerations and multipliers from `[M Φqᵀ; Φq 0][q̈; λ] = [Q; γ]`.
    pub fn acceleration<M: Mechanism>(
        &mut self,
        mech: &M,
        t: f64,
        q: &[f64],
        qd: &[f64],
        qdd: &mut [f64],
        lambda: &mut [f64],
    ) -> Result<(), Error> {
        self.check_state(mech, q, qd, qdd, lambda)?;
        mech.phi_q(q, t, &mut self.phi_q);
        mech.mass(q, &mut self.mass);
        self.factor(t)?;
        self.solve_acceleration(mech, t, q, qd, qdd, lambda)
    }

    /// The velocity of least kinetic energy, then accelerations and multipliers, at one
    /// position: both saddle-point systems share the matrix `[M Φqᵀ; Φq 0]` at `q`, so it is
    /// factored once (what a kinematically driven run needs at every output time).
    #[allow(clippy::too_many_arguments)]
    pub fn velocity_and_acceleration<M: Mechanism>(
        &mut self,
        mech: &M,
        t: f64,
        q: &[f64],
        qd: &mut [f64],
        qdd: &mut [f64],
        lambda: &mut [f64],
    ) -> Result<(), Error> {
        self.check_state(mech, q, qd, qdd, lambda)?;
        mech.phi_q(q, t, &mut self.phi_q);
        mech.phi_t(q, t, &mut self.phi_t);
        mech.mass(q, &mut self.mass);
        self.factor(t)?;
        self.f.fill(0.0);
        for (g, &p) in self.g.iter_mut().zip(&self.phi_t) {
            *g = -p;
        }
        let info = self.info;
        self.kkt
            .solve(&self.f, &self.g, qd, &mut self.mu)
            .map_err(|e| e.to_error(info, t))?;
        if !inf_norm(qd).is_finite() {
            return Err(Error::NotFinite {
                time: t,
                what: "velocity analysis",
            });
        }
        self.solve_acceleration(mech, t, q, qd, qdd, lambda)
    }

    fn check_state<M: Mechanism>(
        &self,
        mech: &M,
        q: &[f64],
        qd: &[f64],
        qdd: &[f64],
        lambda: &[f64],
    ) -> Result<(), Error> {
        self.check_mech(mech)?;
        let (n, m) = (self.info.n_coords, self.info.n_constraints);
        check_len("q", n, q.len())?;
        check_len("qd", n, qd.len())?;
        check_len("qdd", n, qdd.len())?;
        check_len("lambda", m, lambda.len())
    }

    /// Factors `[M Φqᵀ; Φq 0]` at `q` (time `t`), for [`Kinematics::solve`].
    pub fn factor_at<M: Mechanism>(&mut self, mech: &M, q: &[f64], t: f64) -> Result<(), Error> {
        self.check_mech(mech)?;
        check_len("q", self.info.n_coords, q.len())?;
        mech.phi_q(q, t, &mut self.phi_q);
        mech.mass(q, &mut self.mass);
        self.factor(t)
    }

    /// Solves `[M Φqᵀ; Φq 0][x; y] = [f; g]` with the last factorization (at the state of
    /// the last analysis), for derivatives of that analysis; `t` names the time in errors.
    pub fn solve(
        &mut self,
        f: &[f64],
        g: &[f64],
        x: &mut [f64],
        y: &mut [f64],
        t: f64,
    ) -> Result<(), Error> {
        let info = self.info;
        check_len("f", info.n_coords, f.len())?;
        check_len("g", info.n_constraints, g.len())?;
        self.kkt.solve(f, g, x, y).map_err(|e| e.to_error(info, t))
    }

    /// The multipliers ν of the last least-energy velocity, `M q̇ + Φqᵀν = 0`.
    pub fn velocity_multipliers(&self) -> &[f64] {
        &self.mu
    }

    /// Factors `[M Φqᵀ; Φq 0]` from the stored M and Φq.
    fn factor(&mut self, t: f64) -> Result<(), Error> {
        let info = self.info;
        self.kkt
            .factor(&self.mass, 1.0, &self.phi_q)
            .map_err(|e| e.to_error(info, t))
    }

    /// `[Q; γ]` at the state, solved with the current factorization.
    fn solve_acceleration<M: Mechanism>(
        &mut self,
        mech: &M,
        t: f64,
        q: &[f64],
        qd: &[f64],
        qdd: &mut [f64],
        lambda: &mut [f64],
    ) -> Result<(), Error> {
        let info = self.info;
        mech.gamma(q, qd, t, &mut self.gamma);
        mech.force(q, qd, t, &mut self.force);
        self.kkt
            .solve(&self.force, &self.gamma, qdd, lambda)
            .map_err(|e| e.to_error(info, t))?;
        if !inf_norm(qdd).is_finite() || !inf_norm(lambda).is_finite() {
            return Err(Error::NotFinite {
                time: t,
                what: "acceleration analysis",
            });
        }
        Ok(())
    }

    /// The consistent start (docs/design.md, decision 9): position Newton on `q`, then the velocity
    /// chosen by `velocity`, then accelerations and multipliers.
    #[allow(clippy::too_many_arguments)]
    pub fn consistent_start<M: Mechanism>(
        &mut self,
        mech: &M,
        t: f64,
        velocity: InitialVelocity,
        q: &mut [f64],
        qd: &mut [f64],
        qdd: &mut [f64],
        lambda: &mut [f64],
    ) -> Result<PositionReport, Error> {
        let report = self.position(mech, t, q)?;
        match velocity {
            InitialVelocity::LeastKineticEnergy => self.velocity(mech, t, q, qd)?,
            InitialVelocity::ProjectGiven => self.project_velocity(mech, t, q, qd)?,
        }
        self.acceleration(mech, t, q, qd, qdd, lambda)?;
        Ok(report)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kkt::DenseKkt;
    use crate::testmodels::{
        CircleDriver, Pendulum, TwoBallHinge, CIRCLE_C0, CIRCLE_D, CIRCLE_MASS, CIRCLE_V, G,
        HINGE_HALF_WIDTH, PENDULUM_LENGTH,
    };

    #[test]
    fn inf_norm_is_the_largest_magnitude_and_propagates_nan() {
        // Reference: a plain fold over |x|; every length around the four-wide loop.
        for n in 0..14 {
            let v: Vec<f64> = (0..n).map(|i| ((i * 7919) % 13) as f64 - 6.5).collect();
            let want = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            assert_eq!(inf_norm(&v), want, "{v:?}");
            for k in 0..n {
                let mut w = v.clone();
                w[k] = f64::NAN;
                assert!(inf_norm(&w).is_nan(), "{w:?}");
                w[k] = f64::NEG_INFINITY;
                assert_eq!(inf_norm(&w), f64::INFINITY, "{w:?}");
            }
        }
    }

    #[test]
    fn position_newton_leaves_free_directions_alone() {
        // The pendulum has three free directions; a displaced start must be pulled back
        // onto the sphere without turning the body about the pivot-to-centre axis, since
        // that rotation costs kinetic energy and is not needed to satisfy Φ.
        let mech = Pendulum::paper();
        let mut kin = Kinematics::<SchurKkt>::new(mech.info()).unwrap();
        let mut q = [0.05, -0.45, 0.02, 0.0, 0.0, 0.0];
        let rep = kin.position(&mech, 0.0, &mut q).unwrap();
        let mut phi = [0.0; 3];
        mech.phi(&q, 0.0, &mut phi);
        assert!(inf_norm(&phi) <= 1e-11, "{phi:?}");
        assert!(rep.iterations >= 1 && rep.iterations < 10);
        // β is the spin about the arm (local y ∥ global y here): Φq has a zero column for
        // it at the start, so a minimum-norm correction leaves it (nearly) where it was,
        // whereas the translation error is taken up by X, Z, θ, γ.
        assert!(q[4].abs() < 1e-4, "spin β = {}", q[4]);
        assert!(q[3].abs() > 1e-3 && q[5].abs() > 1e-3);
        assert!((q[1] + PENDULUM_LENGTH).abs() < 0.05);
    }

    #[test]
    fn position_rejects_non_finite_coordinates() {
        // A coordinate no row holds (a free body's, found by the interpreter fuzzer) would
        // leave Φ finite and come back `Ok` still NaN: every start is checked.
        let mech = Pendulum::paper();
        let mut kin = Kinematics::<SchurKkt>::new(mech.info()).unwrap();
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            for k in 0..6 {
                let mut q = [0.05, -0.45, 0.02, 0.0, 0.0, 0.0];
                q[k] = bad;
                let e = kin.position(&mech, 0.0, &mut q).unwrap_err();
                assert!(matches!(e, Error::NotFinite { .. }), "{e:?}");
            }
        }
    }

    #[test]
    fn circle_driver_kinematics_match_the_analytic_solution() {
        let mech = CircleDriver;
        for t in [0.0, 0.7, 1.5] {
            let mut kin = Kinematics::<SchurKkt>::new(mech.info()).unwrap();
            let mut q = [CIRCLE_D + 0.01, 0.35, 0.01, 0.02, -0.01, 0.03];
            let (mut qd, mut qdd, mut lam) = ([0.0; 6], [0.0; 6], [0.0; 6]);
            kin.consistent_start(
                &mech,
                t,
                InitialVelocity::LeastKineticEnergy,
                &mut q,
                &mut qd,
                &mut qdd,
                &mut lam,
            )
            .unwrap();
            // Y² = c² − d²:  Ẏ = c ċ / Y,  Ÿ = (ċ² − Ẏ²)/Y  (c̈ = 0).
            let c = CIRCLE_C0 - CIRCLE_V * t;
            let cd = -CIRCLE_V;
            let y = (c * c - CIRCLE_D * CIRCLE_D).sqrt();
            let yd = c * cd / y;
            let ydd = (cd * cd - yd * yd) / y;
            // Newton stops at |Φ|∞ ≤ 1e-11, which bounds the position error by ~1e-11·c/Y.
            assert!(
                (q[1] - y).abs() < 1e-10 && (q[0] - CIRCLE_D).abs() < 1e-10,
                "{q:?}"
            );
            assert!(q[2..].iter().all(|v| v.abs() < 1e-10));
            assert!((qd[1] - yd).abs() < 1e-10 && qd[0].abs() < 1e-10);
            assert!((qdd[1] - ydd).abs() < 1e-10 && qdd[0].abs() < 1e-10);
            // m Ÿ + (Y/c) λ5 = −m g,  λ0 + (d/c) λ5 = 0.
            let l5 = -CIRCLE_MASS * (G + ydd) * c / y;
            assert!((lam[5] - l5).abs() < 1e-9 * l5.abs(), "{} vs {l5}", lam[5]);
            assert!((lam[0] + CIRCLE_D / c * l5).abs() < 1e-9 * l5.abs());
        }
    }

    #[test]
    fn impossible_driver_is_a_newton_failure() {
        // c(3) = 0.2 < d = 0.3: no real position exists.
        let mech = CircleDriver;
        let mut kin = Kinematics::<DenseKkt>::new(mech.info()).unwrap();
        let mut q = mech.info().q0.to_vec();
        match kin.position(&mech, 3.0, &mut q) {
            Err(Error::NewtonFailed { time, residual, .. }) => {
                assert_eq!(time, 3.0);
                assert!(residual > 1e-3);
            }
            Err(Error::SingularJacobian { time, rows }) => {
                assert_eq!(time, 3.0);
                assert!(!rows.is_empty());
            }
            other => panic!("expected a failure, got {other:?}"),
        }
    }

    #[test]
    fn projected_velocity_keeps_the_admissible_part() {
        // A pendulum hanging at rest: a velocity along X is admissible only with the
        // matching rotation; projecting a consistent velocity must return it unchanged.
        let mech = Pendulum::exact();
        let mut kin = Kinematics::<SchurKkt>::new(mech.info()).unwrap();
        let q = mech.info().q0.to_vec();
        // Swinging about Z through the pivot: v = ω × (r − pivot), ω = (0, 0, w).
        let w = 0.7;
        let consistent = [w * PENDULUM_LENGTH, 0.0, 0.0, 0.0, 0.0, w];
        let mut qd = consistent;
        kin.project_velocity(&mech, 0.0, &q, &mut qd).unwrap();
        for (a, b) in qd.iter().zip(&consistent) {
            assert!((a - b).abs() < 1e-12);
        }
        let mut qd0 = [1.0; 6];
        kin.velocity(&mech, 0.0, &q, &mut qd0).unwrap();
        assert!(qd0.iter().all(|v| v.abs() < 1e-14), "no driver: rest");
    }

    #[test]
    fn wrong_lengths_are_errors() {
        let mech = Pendulum::paper();
        let mut kin = Kinematics::<SchurKkt>::new(mech.info()).unwrap();
        let mut q = [0.0; 5];
        assert!(matches!(
            kin.position(&mech, 0.0, &mut q),
            Err(Error::DimensionMismatch { .. })
        ));
        let other = CircleDriver;
        let mut q6 = [0.0; 6];
        assert!(matches!(
            kin.position(&other, 0.0, &mut q6),
            Err(Error::DimensionMismatch { .. })
        ));
    }

    /// Full |Φ|∞ of the hinge, redundant row included.
    fn hinge_residual(mech: &TwoBallHinge, q: &[f64]) -> f64 {
        let mut phi = [0.0; 6];
        mech.phi(q, 0.0, &mut phi);
        inf_norm(&phi)
    }

    #[test]
    fn consistent_redundant_rows_are_satisfied_by_the_position_solve() {
        // Displaced off the hinge in every direction: Newton on the five independent rows
        // must also bring the redundant row (ball2.z) to the tolerance.
        for kkt_dense in [false, true] {
            let mech = TwoBallHinge::new(0.0);
            let mut q = [0.03, -0.47, 0.02, 0.05, -0.04, 0.3];
            let rep = if kkt_dense {
                Kinematics::<DenseKkt>::new(mech.info())
                    .unwrap()
                    .position(&mech, 0.0, &mut q)
            } else {
                Kinematics::<SchurKkt>::new(mech.info())
                    .unwrap()
                    .position(&mech, 0.0, &mut q)
            }
            .unwrap();
            let full = hinge_residual(&mech, &q);
            assert!(full <= 1e-11, "dense {kkt_dense}: |Φ| = {full}");
            assert!(rep.residual >= full, "the report covers the redundant row");
            // A hinge about Z: the body may only have swung about Z.
            assert!(q[3].abs() < 1e-10 && q[4].abs() < 1e-10, "{q:?}");
            // The multipliers exist and the redundant row's is zero.
            let mut kin = Kinematics::<SchurKkt>::new(mech.info()).unwrap();
            let (mut qd, mut qdd, mut lam) = ([0.0; 6], [0.0; 6], [1.0; 6]);
            kin.consistent_start(
                &mech,
                0.0,
                InitialVelocity::LeastKineticEnergy,
                &mut q,
                &mut qd,
                &mut qdd,
                &mut lam,
            )
            .unwrap();
            assert_eq!(lam[5], 0.0);
        }
    }

    #[test]
    fn contradicting_redundant_rows_are_an_inconsistency_error() {
        // Ground points 0.01 m apart in X more than the body points allow: the five
        // independent rows are solved with the axis tilted, leaving ball2.z off by
        // 2a − √(4a² − δ²) ≈ δ²/(4a).
        let delta = 0.01;
        let mech = TwoBallHinge::new(delta);
        let mut kin = Kinematics::<SchurKkt>::new(mech.info()).unwrap();
        let mut q = mech.info().q0.to_vec();
        let err = kin.position(&mech, 0.25, &mut q).unwrap_err();
        let a = HINGE_HALF_WIDTH;
        let expect = 2.0 * a - (4.0 * a * a - delta * delta).sqrt();
        match &err {
            Error::InconsistentConstraints {
                time,
                rows,
                residual,
            } => {
                assert_eq!(*time, 0.25);
                assert_eq!(rows.len(), 1);
                assert_eq!(
                    (rows[0].row, rows[0].name, rows[0].joint),
                    (5, "ball2.z", "ball2")
                );
                assert!(
                    (residual - expect).abs() < 1e-3 * expect,
                    "{residual} vs {expect}"
                );
            }
            other => panic!("expected an inconsistency, got {other:?}"),
        }
        let msg = err.to_string();
        assert!(
            msg.contains("ball2.z") && msg.contains("contradict") && msg.contains("geometry"),
            "{msg}"
        );
        // Without the declaration the same hinge is a rank-deficient Jacobian, as before.
        let undeclared = TwoBallHinge {
            declared: false,
            ..TwoBallHinge::new(0.0)
        };
        let mut kin = Kinematics::<SchurKkt>::new(undeclared.info()).unwrap();
        let mut q = [0.03, -0.47, 0.02, 0.05, -0.04, 0.3];
        match kin.position(&undeclared, 0.0, &mut q) {
            Err(Error::SingularJacobian { rows, .. }) => {
                assert!(rows.iter().any(|r| r.row == 2 || r.row == 5), "{rows:?}")
            }
            other => panic!("expected a singular Jacobian, got {other:?}"),
        }
    }
}
