//! The kinematic path (docs/design.md, decision 23): a driven mechanism followed without time
//! integration — at each output time one position solve, then the least-energy velocity and
//! the saddle-point accelerations and multipliers from one factorization — and the check
//! that tells whether this is exact for a mechanism whose drivers leave free directions.
//!
//! Free directions are exact to follow this way only when they carry no momentum: the
//! velocity of least kinetic energy is then the true velocity at every time. That holds for a
//! Stewart leg's spin about its own axis when the leg is axisymmetric (its spin is a cyclic
//! coordinate whose momentum starts at zero), and [`free_motion`] measures it instead of
//! assuming it.

use nalgebra::DMatrix;

use crate::error::{check_len, Error};
use crate::fk::modes::SplitMix;
use crate::kinematics::{kinetic_energy, mass_times, KinematicSettings, Kinematics};
use crate::kkt::{KktSolver, SchurKkt};
use crate::mechanism::{Mechanism, MechanismInfo};
use crate::watch::{velocity_residual, Residuals};

/// Counters of a kinematic path.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct PathStats {
    /// Output times solved (the start included).
    pub outputs: usize,
    /// Full position Newton iterations (one factorization each) over all outputs.
    pub newton_iterations: usize,
    /// Simplified-Newton corrections with the previous output's factorization.
    pub chord_iterations: usize,
    /// Factorizations of the saddle-point matrix.
    pub factorizations: usize,
}

/// A driven mechanism followed from output time to output time by kinematic analysis.
#[derive(Debug, Clone)]
pub struct KinematicPath<M: Mechanism, K: KktSolver = SchurKkt> {
    mech: M,
    kin: Kinematics<K>,
    t: f64,
    q: Vec<f64>,
    qd: Vec<f64>,
    qdd: Vec<f64>,
    lambda: Vec<f64>,
    /// The steps from each earlier output to the next, latest first (0 before there are
    /// such), and the accelerations at those outputs, for the predictor.
    previous_step: [f64; HISTORY],
    previous_qdd: [Vec<f64>; HISTORY],
    /// The last good position while a new one is sought.
    saved: Vec<f64>,
    /// The predictor's last weights.
    weights: Option<Weights>,
    /// |Φ|∞ (redundant rows included) at `q`, from the position solve's last evaluation.
    position_residual: f64,
    /// Φq q̇ + Φt, for [`Self::residuals`].
    work: Vec<f64>,
    stats: PathStats,
}

impl<M: Mechanism, K: KktSolver> KinematicPath<M, K> {
    /// Starts at time `t0` from the generator's assembled pose `info.q0`, with the velocity
    /// of least kinetic energy (the only one a kinematic path can follow; see the module),
    /// and positions solved to [`PATH_POSITION_TOLERANCE`].
    pub fn new(mech: M, t0: f64) -> Result<Self, Error> {
        let settings = KinematicSettings {
            position_tolerance: PATH_POSITION_TOLERANCE,
            ..KinematicSettings::default()
        };
        Self::with_settings(mech, t0, settings)
    }

    /// As [`KinematicPath::new`], with explicit position-solve settings.
    pub fn with_settings(mech: M, t0: f64, settings: KinematicSettings) -> Result<Self, Error> {
        let q0 = mech.info().q0;
        Self::from_position(mech, t0, q0, settings)
    }

    /// Starts at time `t0` from the position `q` (moved onto Φ = 0 first).
    pub fn from_position(
        mech: M,
        t0: f64,
        q: &[f64],
        settings: KinematicSettings,
    ) -> Result<Self, Error> {
        let kin = Kinematics::with_settings(mech.info(), settings)?;
        Self::with_kinematics(mech, t0, q, kin)
    }

    /// [`Self::from_position`] with the solver's work memory given: one symbolic analysis
    /// serves several paths of a mechanism (a clone of `kin` each).
    fn with_kinematics(mech: M, t0: f64, q: &[f64], kin: Kinematics<K>) -> Result<Self, Error> {
        if !t0.is_finite() {
            return Err(Error::InvalidSetting {
                name: "start time",
                value: t0,
                reason: "must be finite",
            });
        }
        let info = mech.info();
        let (n, m) = (info.n_coords, info.n_constraints);
        check_len("q", n, q.len())?;
        let mut path = KinematicPath {
            kin,
            mech,
            t: t0,
            q: q.to_vec(),
            qd: vec![0.0; n],
            qdd: vec![0.0; n],
            lambda: vec![0.0; m],
            previous_step: [0.0; HISTORY],
            previous_qdd: std::array::from_fn(|_| vec![0.0; n]),
            saved: vec![0.0; n],
            weights: None,
            position_residual: f64::NAN,
            work: vec![0.0; m],
            stats: PathStats::default(),
        };
        path.solve_at(t0)?;
        Ok(path)
    }

    /// Moves to time `t`: a Taylor prediction from the current state ([`Self::predict`]),
    /// Newton onto Φ(q, t) = 0 (corrections smallest in the mass norm, so free directions keep
    /// the predicted motion), then velocity, accelerations and multipliers at `t`. On failure
    /// the state is left at the last good time. Allocates nothing.
    pub fn advance_to(&mut self, t: f64) -> Result<(), Error> {
        if !t.is_finite() {
            return Err(Error::InvalidSetting {
                name: "output time",
                value: t,
                reason: "must be finite",
            });
        }
        let h = t - self.t;
        self.saved.copy_from_slice(&self.q);
        let saved_residual = self.position_residual;
        self.predict(h);
        // The last factorization is at a state one output earlier: close enough for a few
        // simplified-Newton corrections, which cost a residual and a solve each instead of a
        // factorization. Full Newton takes over when they do not converge.
        let chord = self
            .kin
            .position_chord(&self.mech, t, &mut self.q, CHORD_ITERATIONS);
        let result = match chord {
            Ok(Some(report)) => {
                self.stats.chord_iterations += report.iterations;
                self.position_residual = report.residual;
                self.analyse(t)
            }
            Ok(None) | Err(_) => {
                self.q.copy_from_slice(&self.saved);
                self.predict(h);
                self.solve_at(t)
            }
        };
        if result.is_err() {
            self.q.copy_from_slice(&self.saved);
            self.position_residual = saved_residual;
        }
        result
    }

    /// Prediction of q over `h`: q̈ continued by the polynomial through this output's and
    /// the last [`HISTORY`] outputs' accelerations, integrated twice from the current q and
    /// q̇. Eighth order once all are known: at the paper's 0.01 s outputs the predicted |Φ|
    /// is mostly below 1e-14, so most outputs need no correction at all (a fourth-order
    /// prediction needed two simplified-Newton corrections each).
    fn predict(&mut self, h: f64) {
        // Nodes τ₀ = 0 > τ₁ > … at the outputs with known accelerations.
        let mut tau = [0.0; HISTORY + 1];
        let mut nodes = 1;
        while nodes <= HISTORY && self.previous_step[nodes - 1] > 0.0 {
            tau[nodes] = tau[nodes - 1] - self.previous_step[nodes - 1];
            nodes += 1;
        }
        let beta = match self.weights {
            Some(w) if w.serves(h, &tau, nodes) => w.beta,
            _ => {
                let w = Weights::new(h, tau, nodes);
                self.weights = Some(w);
                w.beta
            }
        };
        for ((q, &v), &a) in self.q.iter_mut().zip(&self.qd).zip(&self.qdd) {
            *q += h * v + beta[0] * a;
        }
        for (a, &b) in self.previous_qdd.iter().zip(&beta[1..nodes]) {
            for (q, &a) in self.q.iter_mut().zip(a) {
                *q += b * a;
            }
        }
    }

    fn solve_at(&mut self, t: f64) -> Result<(), Error> {
        let report = self.kin.position(&self.mech, t, &mut self.q)?;
        self.position_residual = report.residual;
        self.stats.newton_iterations += report.iterations;
        self.stats.factorizations += report.iterations;
        self.analyse(t)
    }

    /// Velocity, accelerations and multipliers at the converged position.
    fn analyse(&mut self, t: f64) -> Result<(), Error> {
        if self.stats.outputs > 0 {
            self.previous_step.rotate_right(1);
            self.previous_step[0] = t - self.t;
            self.previous_qdd.rotate_right(1);
            self.previous_qdd[0].copy_from_slice(&self.qdd);
        }
        self.kin.velocity_and_acceleration(
            &self.mech,
            t,
            &self.q,
            &mut self.qd,
            &mut self.qdd,
            &mut self.lambda,
        )?;
        self.t = t;
        self.stats.outputs += 1;
        self.stats.factorizations += 1;
        Ok(())
    }

    /// The state's derivative with respect to one parameter (see
    /// [`crate::sensitivity::kinematic`]), with this output's factorization.
    pub fn sensitivity(
        &mut self,
        neighbours: &crate::sensitivity::Neighbours<'_>,
        out: &mut crate::sensitivity::StateSensitivity,
    ) -> Result<(), Error> {
        crate::sensitivity::kinematic(
            &mut self.kin,
            neighbours,
            self.t,
            (&self.q, &self.qd, &self.qdd, &self.lambda),
            out,
        )
    }

    pub fn mechanism(&self) -> &M {
        &self.mech
    }
    pub fn info(&self) -> &'static MechanismInfo {
        self.mech.info()
    }
    pub fn t(&self) -> f64 {
        self.t
    }
    pub fn q(&self) -> &[f64] {
        &self.q
    }
    pub fn qd(&self) -> &[f64] {
        &self.qd
    }
    pub fn qdd(&self) -> &[f64] {
        &self.qdd
    }
    pub fn lambda(&self) -> &[f64] {
        &self.lambda
    }
    /// Φq nonzeros at the current state.
    pub fn phi_q(&self) -> &[f64] {
        self.kin.phi_q()
    }
    /// Φt at the current state.
    pub fn phi_t(&self) -> &[f64] {
        self.kin.phi_t()
    }
    /// M nonzeros at the current state (the ones `q̈` and λ were solved with).
    pub fn mass(&self) -> &[f64] {
        self.kin.mass()
    }
    /// How well the constraint rows determined λ at the current state.
    pub fn pivots(&self) -> Option<crate::kkt::Pivots> {
        self.kin.pivots()
    }
    pub fn stats(&self) -> PathStats {
        self.stats
    }
    /// Constraint drift at the current state, from the evaluations the path made there: |Φ|∞
    /// of the position solve's last iterate (which is `q`), and |Φq q̇ + Φt|∞ with the Φq and
    /// Φt the velocity was solved with. What a [`ResidualWatch`](crate::ResidualWatch) would
    /// find at this state, without evaluating the equations again.
    pub fn residuals(&mut self) -> Residuals {
        let (phi_q, phi_t) = (self.kin.phi_q(), self.kin.phi_t());
        Residuals {
            position: self.position_residual,
            velocity: velocity_residual(self.mech.info(), phi_q, phi_t, &self.qd, &mut self.work),
        }
    }
    /// |Φ|∞ (redundant rows included) at the current state, from the position solve's last
    /// evaluation: the position part of [`Self::residuals`].
    pub fn position_residual(&self) -> f64 {
        self.position_residual
    }
    /// Kinetic plus potential energy at the current state (J).
    pub fn energy(&self) -> f64 {
        kinetic_energy(self.mech.info(), self.kin.mass(), &self.qd) + self.mech.potential(&self.q)
    }
}

/// What the drivers leave free at one state, and whether following the mechanism kinematically
/// is exact there.
#[derive(Debug, Clone, PartialEq)]
pub struct FreeMotion {
    /// Time of the analysed state (s).
    pub time: f64,
    /// Directions the constraints leave free: coordinates minus the rank of Φq.
    pub dof: usize,
    /// Bodies (indices into `info.bodies`) whose coordinates move along some free direction.
    pub moved_bodies: Vec<usize>,
    /// |a − dv*/dt|_M / |a|_M: how far the accelerations of the equations of motion are from
    /// the rate of change of the least-energy velocity v*(t). Zero (to differencing error,
    /// ≈ 1e-8) when the free directions carry no momentum; the kinematic path is then exact.
    pub acceleration_mismatch: f64,
    /// Largest change of the caller's outputs, relative to their size, when the state is moved
    /// along each free direction and solved again: zero when the free coordinates do not
    /// enter them (a cyclic spin).
    pub output_change: f64,
}

/// Above this [`FreeMotion::acceleration_mismatch`] the free directions carry momentum: the
/// differencing in [`free_motion`] is accurate to ≈ 1e-8 (fourth order in 1e-3 s, position
/// solves to 1e-13).
pub const MAX_ACCELERATION_MISMATCH: f64 = 1e-6;
/// Above this [`FreeMotion::output_change`] a free coordinate enters a requested output.
pub const MAX_OUTPUT_CHANGE: f64 = 1e-8;

impl FreeMotion {
    /// `true` when a kinematic path reproduces the equations of motion at this state: no free
    /// direction, or free directions without momentum that change no requested output and
    /// move none of `bodies`.
    pub fn kinematic_is_exact(&self, bodies: &[usize]) -> bool {
        self.dof == 0
            || (self.acceleration_mismatch <= MAX_ACCELERATION_MISMATCH
                && self.output_change <= MAX_OUTPUT_CHANGE
                && !bodies.iter().any(|b| self.moved_bodies.contains(b)))
    }
}

/// Position tolerance of [`KinematicPath::new`] (|Φ|∞, metres or radians): the pose is an
/// output of the path, not an integration state, so it is solved close to roundoff; the
/// chord corrections converging linearly make the last digits cheap.
pub const PATH_POSITION_TOLERANCE: f64 = 1e-14;

/// The predictor's weights βₖ for the step `h` and the nodes `tau` (see
/// [`KinematicPath::predict`]), kept while the outputs' spacing repeats.
#[derive(Debug, Clone, Copy)]
struct Weights {
    h: f64,
    tau: [f64; HISTORY + 1],
    nodes: usize,
    beta: [f64; HISTORY + 1],
}

impl Weights {
    /// The increment is linear in the accelerations: Σₖ βₖ aₖ with βₖ = ∫₀ʰ (h − τ) Lₖ(τ) dτ
    /// for the Lagrange polynomials Lₖ of the nodes, by four-point Gauss–Legendre (exact
    /// for these polynomials of degree ≤ 7).
    fn new(h: f64, tau: [f64; HISTORY + 1], nodes: usize) -> Self {
        let (inner, outer) = (
            (3.0 / 7.0 - 2.0 / 7.0 * 1.2f64.sqrt()).sqrt(),
            (3.0 / 7.0 + 2.0 / 7.0 * 1.2f64.sqrt()).sqrt(),
        );
        let (w_inner, w_outer) = ((18.0 + 30f64.sqrt()) / 72.0, (18.0 - 30f64.sqrt()) / 72.0);
        let gauss = [
            (0.5 - 0.5 * outer, w_outer),
            (0.5 - 0.5 * inner, w_inner),
            (0.5 + 0.5 * inner, w_inner),
            (0.5 + 0.5 * outer, w_outer),
        ];
        let mut beta = [0.0; HISTORY + 1];
        for (x, w) in gauss {
            let x = x * h;
            for (k, b) in beta.iter_mut().enumerate().take(nodes) {
                let lagrange: f64 = (0..nodes)
                    .filter(|&j| j != k)
                    .map(|j| (x - tau[j]) / (tau[k] - tau[j]))
                    .product();
                *b += w * h * (h - x) * lagrange;
            }
        }
        Weights {
            h,
            tau,
            nodes,
            beta,
        }
    }

    /// Whether these weights serve the step `h` from the nodes `tau`: the same nodes to
    /// 1e-12 of the step. Output times `k·Δt` space their steps equally up to the last bits;
    /// weights that far off move the prediction by ~1e-12 of its acceleration term, far below
    /// the position tolerance, and the position solve corrects it anyway.
    fn serves(&self, h: f64, tau: &[f64; HISTORY + 1], nodes: usize) -> bool {
        let near = |a: f64, b: f64| (a - b).abs() <= 1e-12 * h.abs();
        nodes == self.nodes
            && near(h, self.h)
            && self.tau[..nodes]
                .iter()
                .zip(&tau[..nodes])
                .all(|(&a, &b)| near(a, b))
    }
}

/// Earlier outputs whose accelerations the predictor continues ([`KinematicPath::predict`]).
const HISTORY: usize = 6;

/// Simplified-Newton corrections tried before a full Newton solve: each correction with a
/// Jacobian one output old gains about a factor Δt on the prediction's residual (O(Δt⁹) once
/// seven outputs are known, lower in the first outputs).
const CHORD_ITERATIONS: usize = 4;

/// Step of the differencing in [`free_motion`] (s): fourth-order central differences of the
/// least-energy velocity, truncation ≈ h⁴ ≈ 1e-12 relative, roundoff ≈ 1e-13 / h ≈ 1e-10.
const DIFFERENCE_STEP: f64 = 1e-3;
/// Displacement along each unit free direction for [`FreeMotion::output_change`].
const FREE_DISPLACEMENT: f64 = 0.1;

/// The quantities a run is asked for, from a state: `(q, q̇, λ, Φq nonzeros)` → values.
pub type Outputs<'a> = dyn FnMut(&[f64], &[f64], &[f64], &[f64]) -> Result<Vec<f64>, Error> + 'a;

/// Analyses the free directions at the consistent position `q` (time `t`): their number,
/// the bodies they move, whether they carry momentum (compares the saddle-point
/// accelerations at `t + 2h` with the derivative of the least-energy velocity differenced
/// over `t … t + 4h`), and whether `outputs(q, qd, λ, Φq)` changes when the state is moved
/// along each of them. Allocates; call it once per run, not per step.
pub fn free_motion<M: Mechanism>(
    mech: &M,
    t: f64,
    q: &[f64],
    outputs: &mut Outputs<'_>,
) -> Result<FreeMotion, Error> {
    let info = mech.info();
    let n = info.n_coords;
    check_len("q", n, q.len())?;
    let tight = KinematicSettings {
        position_tolerance: 1e-13,
        ..KinematicSettings::default()
    };
    let mut kin = Kinematics::<SchurKkt>::with_settings(info, tight)?;
    let free = null_space(mech, t, q, &mut kin)?;
    let dof = free.ncols();
    let moved_bodies = moved_by(info, &free);
    let mut result = FreeMotion {
        time: t,
        dof,
        moved_bodies,
        acceleration_mismatch: 0.0,
        output_change: 0.0,
    };
    if dof == 0 {
        return Ok(result);
    }

    // The caller's outputs at q; moved along each free direction below.
    let mut path = KinematicPath::<&M>::with_kinematics(mech, t, q, kin.clone())?;
    let reference = outputs(path.q(), path.qd(), path.lambda(), path.phi_q())?;
    let base = path.q().to_vec();

    // Least-energy velocities at t, t + h, …, t + 4h along one kinematic path.
    let mut v = Vec::with_capacity(5);
    let mut mid = (Vec::new(), Vec::new());
    for k in 0..5 {
        if k > 0 {
            path.advance_to(t + k as f64 * DIFFERENCE_STEP)?;
        }
        v.push(path.qd().to_vec());
        if k == 2 {
            mid = (path.q().to_vec(), path.qdd().to_vec());
        }
    }
    let (q_mid, a) = mid;
    let diff: Vec<f64> = (0..n)
        .map(|i| {
            let dvdt =
                (v[0][i] - 8.0 * v[1][i] + 8.0 * v[3][i] - v[4][i]) / (12.0 * DIFFERENCE_STEP);
            a[i] - dvdt
        })
        .collect();
    let mut mass = vec![0.0; info.mass_nnz()];
    mech.mass(&q_mid, &mut mass);
    let m_norm = |x: &[f64]| {
        let mut mx = vec![0.0; n];
        mass_times(info, &mass, x, &mut mx);
        x.iter()
            .zip(&mx)
            .map(|(a, b)| a * b)
            .sum::<f64>()
            .max(0.0)
            .sqrt()
    };
    result.acceleration_mismatch = m_norm(&diff) / m_norm(&a).max(f64::MIN_POSITIVE);

    let scale = reference.iter().fold(0.0f64, |s, x| s.max(x.abs()));
    let mut change = 0.0f64;
    for k in 0..dof {
        let moved: Vec<f64> = (0..n)
            .map(|i| base[i] + FREE_DISPLACEMENT * free[(i, k)])
            .collect();
        let p = KinematicPath::<&M>::with_kinematics(mech, t, &moved, kin.clone())?;
        let out = outputs(p.q(), p.qd(), p.lambda(), p.phi_q())?;
        for (x, y) in out.iter().zip(&reference) {
            change = change.max((x - y).abs());
        }
    }
    result.output_change = change / scale.max(f64::MIN_POSITIVE);
    Ok(result)
}

/// The bodies (indices into `info.bodies`) that some direction Φq(q, t) leaves free moves:
/// a kinematic path's velocity along such a direction is the least-energy one, so where those
/// bodies are is decided by the path taken, not by the drivers at `t`.
pub fn free_bodies<M: Mechanism>(mech: &M, t: f64, q: &[f64]) -> Result<Vec<usize>, Error> {
    let mut kin = Kinematics::new(mech.info())?;
    Ok(moved_by(mech.info(), &null_space(mech, t, q, &mut kin)?))
}

/// The bodies whose coordinates some column of `free` moves.
fn moved_by(info: &MechanismInfo, free: &DMatrix<f64>) -> Vec<usize> {
    info.bodies
        .iter()
        .enumerate()
        .filter(|(_, b)| free.rows(b.coord_offset, b.n_coords()).amax() > 1e-8)
        .map(|(i, _)| i)
        .collect()
}

/// Orthonormal basis of the null space of Φq(q, t), one direction per column. The saddle-point
/// solve `[M Φqᵀ; Φq 0][y; μ] = [M r; 0]` projects a direction r onto the null space (along
/// M⁻¹Φqᵀ), so the projections of enough directions span it; a pivoted Gram–Schmidt picks an
/// orthonormal basis among them and stops where what is left is roundoff. The directions are
/// pseudo-random (a fixed sequence), [`NULL_SPACE_SPARE`] more than the dimension: the
/// factorization succeeded, so Φq has full row rank but for the declared redundant rows and
/// the null space has `n − m + redundant` dimensions, and directions chosen without regard to
/// Φq span it (the Stewart model: 10 solves instead of one per coordinate, 78). One sparse
/// factorization, no dense SVD of Φq.
fn null_space<M: Mechanism>(
    mech: &M,
    t: f64,
    q: &[f64],
    kin: &mut Kinematics<SchurKkt>,
) -> Result<DMatrix<f64>, Error> {
    let info = mech.info();
    let (n, m) = (info.n_coords, info.n_constraints);
    kin.factor_at(mech, q, t)?;
    let draws = ((n + info.redundant_rows.len()).saturating_sub(m) + NULL_SPACE_SPARE).min(n);
    let mut directions = SplitMix(NULL_SPACE_SEED);
    let (g, mut mu) = (vec![0.0; m], vec![0.0; m]);
    let (mut r, mut f) = (vec![0.0; n], vec![0.0; n]);
    let mut left: Vec<Vec<f64>> = Vec::with_capacity(draws);
    for _ in 0..draws {
        r.iter_mut()
            .for_each(|x| *x = 2.0 * directions.next() - 1.0);
        let size = r.iter().map(|x| x * x).sum::<f64>().sqrt();
        r.iter_mut().for_each(|x| *x /= size);
        mass_times(info, kin.mass(), &r, &mut f);
        let mut y = vec![0.0; n];
        kin.solve(&f, &g, &mut y, &mut mu, t)?;
        left.push(y);
    }
    let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    if !left.iter().flatten().all(|x| x.is_finite()) {
        return Err(Error::NotFinite {
            time: t,
            what: "null space of the constraint Jacobian",
        });
    }
    let mut basis: Vec<Vec<f64>> = Vec::new();
    while let Some((j, size)) = left
        .iter()
        .map(|y| norm(y))
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(&b.1))
    {
        if !(size > NULL_SPACE_TOLERANCE) {
            break;
        }
        let mut b = left.swap_remove(j);
        // Classical Gram–Schmidt loses orthogonality to cancellation; a second pass
        // against the basis restores it.
        for u in &basis {
            let d = dot(u, &b);
            b.iter_mut().zip(u).for_each(|(x, y)| *x -= d * y);
        }
        let size = norm(&b);
        b.iter_mut().for_each(|x| *x /= size);
        for y in left.iter_mut() {
            let d = dot(&b, y);
            y.iter_mut().zip(&b).for_each(|(x, u)| *x -= d * u);
        }
        basis.push(b);
    }
    Ok(DMatrix::from_fn(n, basis.len(), |i, k| basis[k][i]))
}

/// Directions [`null_space`] draws beyond the null space's dimension: a margin for
/// directions that happen to lie close to the span of the others.
const NULL_SPACE_SPARE: usize = 4;

/// Seed of [`null_space`]'s directions: fixed, so a run repeats to the last bit.
const NULL_SPACE_SEED: u64 = 0x2545_f491_4f6c_dd1d;

/// Below this length, what is left of a projected unit direction after removing the basis
/// found so far is roundoff (≈ 1e-16 times the saddle-point matrix's condition), not a free
/// direction. While `k` free directions are left, a unit direction unrelated to them keeps a
/// part of order √(k/n) outside the basis.
const NULL_SPACE_TOLERANCE: f64 = 1e-8;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testmodels::{CircleDriver, Pendulum, TwoBallHinge};

    /// The orthogonal projector onto the null space of the dense Φq at `q`, from nalgebra's
    /// SVD (the reference: singular values below 1e-10 of the largest count as zero).
    fn svd_projector<M: Mechanism>(mech: &M, q: &[f64]) -> DMatrix<f64> {
        let info = mech.info();
        let n = info.n_coords;
        let mut values = vec![0.0; info.phi_q_nnz()];
        mech.phi_q(q, 0.0, &mut values);
        let mut a = DMatrix::<f64>::zeros(info.n_constraints.max(n), n);
        for ((&r, &c), &v) in info.phi_q_rows.iter().zip(info.phi_q_cols).zip(&values) {
            a[(r as usize, c as usize)] = v;
        }
        let svd = a.svd(false, true);
        let v_t = svd.v_t.expect("asked for V");
        let largest = svd.singular_values.max();
        let mut p = DMatrix::zeros(n, n);
        for (k, &s) in svd.singular_values.iter().enumerate() {
            if s <= 1e-10 * largest {
                let v = v_t.row(k).transpose();
                p += &v * v.transpose();
            }
        }
        p
    }

    fn null_space_matches_the_svd<M: Mechanism>(mech: &M, q: &[f64], dof: usize) {
        let mut kin = Kinematics::<SchurKkt>::new(mech.info()).unwrap();
        let basis = null_space(mech, 0.0, q, &mut kin).unwrap();
        assert_eq!(basis.ncols(), dof, "{}", mech.info().name);
        let orthonormal = basis.transpose() * &basis - DMatrix::identity(dof, dof);
        assert!(orthonormal.amax() < 1e-12, "{}", mech.info().name);
        let difference = &basis * basis.transpose() - svd_projector(mech, q);
        assert!(
            difference.amax() < 1e-10,
            "{}: {}",
            mech.info().name,
            difference.amax()
        );
    }

    /// The slider driven along a circle of shrinking radius: Y(t) = √(c(t)² − d²) in closed
    /// form. The path must stay on it, and once seven outputs are known the eighth-order
    /// prediction alone must meet the position tolerance almost everywhere.
    /// Weights kept for steps equal up to the last bits predict what the steps' own weights
    /// do: on a smooth acceleration sampled at the actual nodes, the two increments agree to
    /// 1e-13 of h²·max|a| (the individual weights differ more, ~1e-12 relative: extrapolation
    /// weights alternate, and for smooth data the difference cancels). A different spacing
    /// computes its own.
    #[test]
    fn kept_predictor_weights_predict_as_the_steps_own() {
        let h = 0.01;
        let nodes_of = |steps: &[f64]| {
            let mut tau = [0.0; HISTORY + 1];
            for (k, s) in steps.iter().enumerate() {
                tau[k + 1] = tau[k] - s;
            }
            tau
        };
        let even = Weights::new(h, nodes_of(&[h; HISTORY]), HISTORY + 1);
        // Steps between output times k·Δt: 0.01 up to a few ulps of t ≈ 6.
        let jitter = [h + 1.7e-15, h - 8.9e-16, h, h + 8.9e-16, h - 1.7e-15, h];
        let (step, tau) = (h + 8.9e-16, nodes_of(&jitter));
        assert!(even.serves(step, &tau, HISTORY + 1));
        let own = Weights::new(step, tau, HISTORY + 1);
        let a = |t: f64| 5.0 * (3.0 * t + 0.4).cos();
        let increment =
            |w: &Weights| -> f64 { w.beta.iter().zip(&tau).map(|(b, &t)| b * a(t)).sum() };
        let (kept, exact) = (increment(&even), increment(&own));
        assert!(
            (kept - exact).abs() <= 1e-13 * h * h * 5.0,
            "{kept} vs {exact}"
        );
        // The four-point Lobatto nodes of the tables' path: another spacing.
        let lobatto = nodes_of(&[
            0.276 * h,
            0.447 * h,
            0.276 * h,
            0.276 * h,
            0.447 * h,
            0.276 * h,
        ]);
        assert!(!even.serves(0.276 * h, &lobatto, HISTORY + 1));
        assert!(!even.serves(h, &tau, HISTORY));
    }

    #[test]
    fn prediction_follows_the_circle_driver_without_corrections() {
        use crate::testmodels::{CIRCLE_D, CIRCLE_V};
        let mut path = KinematicPath::<_>::new(CircleDriver, 0.0).unwrap();
        let mut worst = 0.0f64;
        let mut corrections = Vec::new();
        for k in 1..=100 {
            let before = path.stats().chord_iterations;
            path.advance_to(0.01 * k as f64).unwrap();
            corrections.push(path.stats().chord_iterations - before);
            let c = CircleDriver::c(path.t());
            worst = worst.max((path.q()[1] - (c * c - CIRCLE_D * CIRCLE_D).sqrt()).abs());
            let y_dot = -c * CIRCLE_V / path.q()[1];
            worst = worst.max((path.qd()[1] - y_dot).abs());
        }
        assert!(worst < 1e-13, "{worst:e} from the closed form");
        assert_eq!(path.stats().newton_iterations, 0);
        let late: usize = corrections[6..].iter().sum();
        assert!(late <= 2, "{corrections:?}");
    }

    /// A free spherical pendulum (three free directions), a hinge whose redundant row is
    /// declared (one), and a driven slider with none.
    #[test]
    fn null_space_from_the_saddle_point_solves_is_the_svds() {
        for pendulum in [Pendulum::paper(), Pendulum::exact()] {
            let q = [0.3, -0.8, 0.2, 0.4, -0.3, 0.7];
            let mut q = q.to_vec();
            Kinematics::<SchurKkt>::new(pendulum.info())
                .unwrap()
                .position(&pendulum, 0.0, &mut q)
                .unwrap();
            null_space_matches_the_svd(&pendulum, &q, 3);
        }
        let hinge = TwoBallHinge::new(0.0);
        null_space_matches_the_svd(&hinge, hinge.info().q0, 1);
        null_space_matches_the_svd(&CircleDriver, CircleDriver.info().q0, 0);
    }
}
