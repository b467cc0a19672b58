//! Sensitivities of a solution with respect to one parameter of the mechanism file: the
//! implicit part (positions, velocities, accelerations and multipliers defined by the
//! saddle-point systems, or by the HHT step equations) differentiated exactly, by solving
//! with the matrix the solver already factored; the explicit part (how Φ, M, Q, γ and the
//! outputs change at a fixed state when the parameter moves) from the mechanism built at
//! four neighbouring values of the parameter, by the fourth-order central difference.
//!
//! Why the explicit part is differenced: the file's parameters reach the equations through
//! the loader's numeric work (assembled poses, joint frames made local to their bodies), not
//! as symbols of the DAG. A difference of smooth explicit functions at a fixed state has no
//! solver tolerance in it, so with the step [`relative_step`] its error is that of the
//! stencil, (δ⁴ f⁽⁵⁾/30) ≈ 1e-12, plus roundoff ≈ 1e-13 / 1e-3: measured at 1e-10 relative
//! against whole-run differences in `tests/sensitivities.rs`.

use crate::error::{check_len, Error};
use crate::kinematics::{mass_times, phi_q_transpose_times, Kinematics};
use crate::kkt::KktSolver;
use crate::mechanism::{Mechanism, MechanismInfo};

/// Offsets of the stencil in units of the step, and their weights (times 1/step).
const OFFSETS: [f64; 4] = [-2.0, -1.0, 1.0, 2.0];
const WEIGHTS: [f64; 4] = [1.0 / 12.0, -8.0 / 12.0, 8.0 / 12.0, -1.0 / 12.0];

/// The step of the stencil for a parameter of value `p`: 1e-3 relative (1e-6 absolute for a
/// parameter at zero), which balances the stencil's truncation against roundoff.
pub fn relative_step(p: f64) -> f64 {
    if p == 0.0 {
        1e-6
    } else {
        1e-3 * p.abs()
    }
}

/// One parameter's neighbours: the same mechanism built with the parameter at
/// `p − 2δ, p − δ, p + δ, p + 2δ`, every other parameter unchanged.
pub struct Neighbours<'a> {
    step: f64,
    mechs: [&'a dyn Mechanism; 4],
}

impl<'a> Neighbours<'a> {
    /// Checks that the four share `base`'s structure (sizes, patterns, redundant rows): a
    /// parameter change that alters it has no derivative at `p`.
    pub fn new(
        base: &MechanismInfo,
        step: f64,
        mechs: [&'a dyn Mechanism; 4],
    ) -> Result<Self, Error> {
        if !(step.is_finite() && step > 0.0) {
            return Err(Error::InvalidSetting {
                name: "parameter step",
                value: step,
                reason: "must be positive and finite",
            });
        }
        for m in &mechs {
            // Patterns may differ: an entry that cancels exactly at the file's value (a
            // difference of equal numbers, folded away by the generator) is structurally
            // absent there and present beside it, where it is small. Every evaluation here
            // goes through each mechanism's own pattern into dense vectors.
            let i = m.info();
            let same = i.n_coords == base.n_coords
                && i.n_constraints == base.n_constraints
                && i.redundant_rows == base.redundant_rows;
            if !same {
                return Err(Error::InvalidPattern {
                    reason: format!(
                        "the mechanism's structure (coordinates, rows or redundant rows) \
                         changes within ±{:.3e} of the parameter's value: it has no \
                         derivative there",
                        2.0 * step
                    ),
                });
            }
        }
        Ok(Neighbours { step, mechs })
    }

    pub fn step(&self) -> f64 {
        self.step
    }

    /// `out = d/dε f(mechanism at p + ε, ε)` at ε = 0, where `f(mech, ε, tmp)` writes the
    /// value into `tmp` (the caller moves its state by `ε` times its direction inside `f`).
    pub fn derivative(
        &self,
        out: &mut [f64],
        tmp: &mut [f64],
        mut f: impl FnMut(&dyn Mechanism, f64, &mut [f64]) -> Result<(), Error>,
    ) -> Result<(), Error> {
        out.fill(0.0);
        for ((mech, &s), &w) in self.mechs.iter().zip(&OFFSETS).zip(&WEIGHTS) {
            f(*mech, s * self.step, tmp)?;
            for (o, &v) in out.iter_mut().zip(tmp.iter()) {
                *o += w * v / self.step;
            }
        }
        Ok(())
    }
}

/// A state and its derivative with respect to one parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct StateSensitivity {
    pub dq: Vec<f64>,
    pub dqd: Vec<f64>,
    pub dqdd: Vec<f64>,
    pub dlambda: Vec<f64>,
}

impl StateSensitivity {
    pub fn zeros(info: &MechanismInfo) -> Self {
        let (n, m) = (info.n_coords, info.n_constraints);
        StateSensitivity {
            dq: vec![0.0; n],
            dqd: vec![0.0; n],
            dqdd: vec![0.0; n],
            dlambda: vec![0.0; m],
        }
    }
}

/// Scratch of one mechanism's evaluations, sized once.
pub(crate) struct Scratch {
    phi_q: Vec<f64>,
    mass: Vec<f64>,
    vec_n: Vec<f64>,
    vec_m: Vec<f64>,
}

impl Scratch {
    /// Sizes the sparse buffers for `info`'s patterns (neighbours' may differ from the base's).
    fn fit(&mut self, info: &MechanismInfo) {
        self.phi_q.resize(info.phi_q_nnz(), 0.0);
        self.mass.resize(info.mass_nnz(), 0.0);
    }

    pub(crate) fn new(info: &MechanismInfo) -> Self {
        Scratch {
            phi_q: vec![0.0; info.phi_q_nnz()],
            mass: vec![0.0; info.mass_nnz()],
            vec_n: vec![0.0; info.n_coords],
            vec_m: vec![0.0; info.n_constraints],
        }
    }
}

/// `out = Φq v` from the Jacobian nonzeros.
fn phi_q_times(info: &MechanismInfo, phi_q: &[f64], v: &[f64], out: &mut [f64]) {
    out.fill(0.0);
    for ((&r, &c), &a) in info.phi_q_rows.iter().zip(info.phi_q_cols).zip(phi_q) {
        out[r as usize] += a * v[c as usize];
    }
}

/// `x + s·dx`, elementwise, into `out`.
fn moved(x: &[f64], s: f64, dx: &[f64], out: &mut Vec<f64>) {
    out.clear();
    out.extend(x.iter().zip(dx).map(|(a, b)| a + s * b));
}

/// `out = [M x + Φqᵀy; Φq x]` at `q`: the saddle-point matrix of the analyses times `(x, y)`.
fn saddle_product(
    mech: &dyn Mechanism,
    t: f64,
    q: &[f64],
    (x, y): (&[f64], &[f64]),
    s: &mut Scratch,
    out: &mut [f64],
) {
    let info = mech.info();
    s.fit(info);
    mech.phi_q(q, t, &mut s.phi_q);
    mech.mass(q, &mut s.mass);
    let (top, bottom) = out.split_at_mut(info.n_coords);
    mass_times(info, &s.mass, x, top);
    phi_q_transpose_times(info, &s.phi_q, y, &mut s.vec_n);
    for (a, b) in top.iter_mut().zip(&s.vec_n) {
        *a += b;
    }
    phi_q_times(info, &s.phi_q, x, bottom);
}

/// The residuals of the saddle-point systems a kinematic analysis solves, at one state:
/// `[M q̇ + Φqᵀν; Φq q̇ + Φt]` (least-energy velocity) and `[M q̈ + Φqᵀλ − Q; Φq q̈ − γ]`.
pub(crate) fn velocity_residual(
    mech: &dyn Mechanism,
    t: f64,
    (q, qd, nu): (&[f64], &[f64], &[f64]),
    s: &mut Scratch,
    out: &mut [f64],
) {
    saddle_product(mech, t, q, (qd, nu), s, out);
    mech.phi_t(q, t, &mut s.vec_m);
    for (a, b) in out[mech.info().n_coords..].iter_mut().zip(&s.vec_m) {
        *a += b;
    }
}

/// See [`velocity_residual`].
pub(crate) fn acceleration_residual(
    mech: &dyn Mechanism,
    t: f64,
    (q, qd, qdd, lambda): (&[f64], &[f64], &[f64], &[f64]),
    s: &mut Scratch,
    out: &mut [f64],
) {
    saddle_product(mech, t, q, (qdd, lambda), s, out);
    let (top, bottom) = out.split_at_mut(mech.info().n_coords);
    mech.force(q, qd, t, &mut s.vec_n);
    for (a, b) in top.iter_mut().zip(&s.vec_n) {
        *a -= b;
    }
    mech.gamma(q, qd, t, &mut s.vec_m);
    for (a, b) in bottom.iter_mut().zip(&s.vec_m) {
        *a -= b;
    }
}

/// The derivative with respect to the parameter of a kinematic analysis at time `t`: the
/// position on Φ(q, t) = 0 (the correction of least kinetic energy, as the position solve
/// takes it, so free directions the drivers leave get none), the least-energy velocity with
/// its multipliers `nu`, and the accelerations and multipliers. `kin` must hold the
/// factorization of `[M Φqᵀ; Φq 0]` at this state, as [`Kinematics::velocity_and_acceleration`]
/// leaves it.
#[allow(clippy::too_many_arguments)]
pub fn kinematic<K: KktSolver>(
    kin: &mut Kinematics<K>,
    neighbours: &Neighbours<'_>,
    t: f64,
    (q, qd, qdd, lambda): (&[f64], &[f64], &[f64], &[f64]),
    out: &mut StateSensitivity,
) -> Result<(), Error> {
    let info = neighbours.mechs[0].info();
    let (n, m) = (info.n_coords, info.n_constraints);
    check_len("q", n, q.len())?;
    check_len("lambda", m, lambda.len())?;
    let nu = kin.velocity_multipliers().to_vec();
    let mut s = Scratch::new(info);
    let (mut rhs, mut tmp) = (vec![0.0; n + m], vec![0.0; n + m]);
    let zero_n = vec![0.0; n];
    let mut dnu = vec![0.0; m];
    let (mut qa, mut qda) = (Vec::with_capacity(n), Vec::with_capacity(n));

    // Φ(q(p), t; p) = 0  ⇒  Φq dq = −∂Φ/∂p.
    neighbours.derivative(&mut rhs[n..], &mut tmp[n..], |mech, _, v| {
        mech.phi(q, t, v);
        Ok(())
    })?;
    negate(&mut rhs[n..]);
    kin.solve(&zero_n, &rhs[n..], &mut out.dq, &mut dnu, t)?;

    // The velocity system's residual is zero along p: K [dq̇; dν] = −(its change at fixed q̇, ν).
    neighbours.derivative(&mut rhs, &mut tmp, |mech, e, v| {
        moved(q, e, &out.dq, &mut qa);
        velocity_residual(mech, t, (&qa, qd, &nu), &mut s, v);
        Ok(())
    })?;
    negate(&mut rhs);
    let (f, g) = rhs.split_at(n);
    kin.solve(f, g, &mut out.dqd, &mut dnu, t)?;

    // Likewise the acceleration system, whose residual also moves with q̇.
    neighbours.derivative(&mut rhs, &mut tmp, |mech, e, v| {
        moved(q, e, &out.dq, &mut qa);
        moved(qd, e, &out.dqd, &mut qda);
        acceleration_residual(mech, t, (&qa, &qda, qdd, lambda), &mut s, v);
        Ok(())
    })?;
    negate(&mut rhs);
    let (f, g) = rhs.split_at(n);
    kin.solve(f, g, &mut out.dqdd, &mut out.dlambda, t)?;
    let all = [&out.dq, &out.dqd, &out.dqdd, &out.dlambda];
    if all.iter().any(|v| v.iter().any(|x| !x.is_finite())) {
        return Err(Error::NotFinite {
            time: t,
            what: "sensitivity analysis",
        });
    }
    Ok(())
}

fn negate(v: &mut [f64]) {
    for x in v {
        *x = -*x;
    }
}

/// Forward sensitivities of an HHT-α run ([`crate::hht`]) with respect to one parameter:
/// the derivative of the discrete solution, step by step. The step equations are linear in
/// the new accelerations and multipliers, so their derivative solves a linear system with the
/// step's exact Jacobian; it is solved by iterating with `[M/(1+α) Φqᵀ; Φq 0]` (the Newton
/// matrix without the O(βh²) stiffness terms) on the exact residual, which converges as the
/// step's own Newton does. Velocity projection (`HhtBuilder::project_velocities`) is
/// differentiated as the projection of least kinetic energy at the new position.
///
/// Feed it the integrator's state after every accepted step ([`HhtSensitivity::step`]).
pub struct HhtSensitivity<K: KktSolver = crate::kkt::SchurKkt> {
    kin: Kinematics<K>,
    alpha: f64,
    beta: f64,
    gamma: f64,
    project: bool,
    /// The state's derivative at the last accepted step.
    pub state: StateSensitivity,
    /// Derivative of `r = Φqᵀλ − Q` at the last step, which the α-term carries forward.
    dr: Vec<f64>,
    /// The base state at the last accepted step: t, q, q̇, q̈, λ, and q̇ before projection
    /// (what `r` was evaluated with).
    t: f64,
    q: Vec<f64>,
    v: Vec<f64>,
    a: Vec<f64>,
    lambda: Vec<f64>,
    v_tilde: Vec<f64>,
    s: Scratch,
    w: Work,
}

/// Work space of [`HhtSensitivity`], sized once: a step allocates nothing.
struct Work {
    /// Right-hand sides and stencil values, `n + m`.
    rhs: Vec<f64>,
    tmp: Vec<f64>,
    /// Moved states inside the stencils.
    qa: Vec<f64>,
    va: Vec<f64>,
    aa: Vec<f64>,
    la: Vec<f64>,
    /// Solutions `(x, y)` of the saddle-point solves.
    x: Vec<f64>,
    y: Vec<f64>,
    /// The step's previous `r = Φqᵀλ − Q`, and its Newmark velocity and derivatives.
    r0: Vec<f64>,
    v_tilde: Vec<f64>,
    dv_tilde: Vec<f64>,
    da: Vec<f64>,
    dl: Vec<f64>,
    /// `M (v − ṽ)`'s difference, and the projection's multipliers.
    diff: Vec<f64>,
    mu: Vec<f64>,
}

impl Work {
    fn new(n: usize, m: usize) -> Self {
        let z = |k: usize| vec![0.0; k];
        Work {
            rhs: z(n + m),
            tmp: z(n + m),
            qa: z(n),
            va: z(n),
            aa: z(n),
            la: z(m),
            x: z(n),
            y: z(m),
            r0: z(n),
            v_tilde: z(n),
            dv_tilde: z(n),
            da: z(n),
            dl: z(m),
            diff: z(n),
            mu: z(m),
        }
    }
}

/// Sensitivity iterations of one step before giving up; each gains about the factor the
/// step's Newton gains per iteration (O(βh²)·stiffness/mass).
const SENSITIVITY_ITERATIONS: usize = 30;
/// Stop once an iteration changes the derivative by less than this, relative to it.
const SENSITIVITY_TOLERANCE: f64 = 1e-11;
/// Largest relative change at which stagnating iterations are taken as converged.
const STAGNATION_LIMIT: f64 = 1e-4;

impl<K: KktSolver> HhtSensitivity<K> {
    /// At the consistent start `(q, q̇, q̈, λ)` at `t0` that `HhtBuilder::build` made from the
    /// file's pose and velocities (`info.q0`, `info.qd0`, velocities projected): their
    /// derivatives, from the neighbours' assembled poses and given velocities.
    #[allow(clippy::too_many_arguments)]
    pub fn start<M: Mechanism>(
        mech: &M,
        nb: &Neighbours<'_>,
        settings: crate::kinematics::KinematicSettings,
        (alpha, project): (f64, bool),
        t0: f64,
        (q, v, a, lambda): (&[f64], &[f64], &[f64], &[f64]),
    ) -> Result<Self, Error> {
        let info = mech.info();
        let (n, m) = (info.n_coords, info.n_constraints);
        check_len("q", n, q.len())?;
        check_len("lambda", m, lambda.len())?;
        let mut me = HhtSensitivity {
            kin: Kinematics::with_settings(info, settings)?,
            alpha,
            beta: (1.0 - alpha).powi(2) / 4.0,
            gamma: 0.5 - alpha,
            project,
            state: StateSensitivity::zeros(info),
            dr: vec![0.0; n],
            t: t0,
            q: q.to_vec(),
            v: v.to_vec(),
            a: a.to_vec(),
            lambda: lambda.to_vec(),
            v_tilde: v.to_vec(),
            s: Scratch::new(info),
            w: Work::new(n, m),
        };
        me.kin.factor_at(mech, q, t0)?;
        let (mut rhs, mut tmp) = (vec![0.0; n + m], vec![0.0; n + m]);
        let mut y = vec![0.0; m];

        // The assembled pose moves with p; the start's position solve keeps it on Φ = 0
        // with the correction of least kinetic energy.
        let mut dq_given = vec![0.0; n];
        let mut dn = vec![0.0; n];
        nb.derivative(&mut dq_given, &mut dn, |mech, _, out| {
            out.copy_from_slice(mech.info().q0);
            Ok(())
        })?;
        nb.derivative(&mut rhs[n..], &mut tmp[n..], |mech, e, out| {
            let qa: Vec<f64> = q.iter().zip(&dq_given).map(|(a, b)| a + e * b).collect();
            mech.phi(&qa, t0, out);
            Ok(())
        })?;
        negate(&mut rhs[n..]);
        let zero_n = vec![0.0; n];
        let mut dq = vec![0.0; n];
        me.kin.solve(&zero_n, &rhs[n..], &mut dq, &mut y, t0)?;
        for (d, g) in dq.iter_mut().zip(&dq_given) {
            *d += g;
        }
        me.state.dq = dq;

        // The given velocities move with p too, and are projected.
        let mut dv_given = vec![0.0; n];
        nb.derivative(&mut dv_given, &mut dn, |mech, _, out| {
            out.copy_from_slice(mech.info().qd0);
            Ok(())
        })?;
        me.w.v_tilde.copy_from_slice(mech.info().qd0);
        me.w.dv_tilde.copy_from_slice(&dv_given);
        me.project_derivative(mech, nb, t0)?;
        let (mut a, mut l) = (vec![0.0; n], vec![0.0; m]);
        let (mut da, mut dl) = (vec![0.0; n], vec![0.0; m]);
        me.accelerations(mech, nb, t0, [&mut a, &mut l, &mut da, &mut dl])?;
        (me.a, me.lambda, me.state.dqdd, me.state.dlambda) = (a, l, da, dl);
        // `r` at the start is evaluated with the projected velocity.
        me.w.v_tilde.copy_from_slice(&me.v);
        me.w.dv_tilde.copy_from_slice(&me.state.dqd);
        me.store_dr(nb, t0)?;
        Ok(me)
    }

    /// `state.dqd` for `v = ṽ + Δ`, Δ the projection of least kinetic energy of
    /// ṽ = `w.v_tilde` (whose derivative is `w.dv_tilde`) onto the velocity constraints at
    /// `self.q`; `kin` must be factored there. Sets `self.v` to the projected base velocity.
    fn project_derivative<M: Mechanism>(
        &mut self,
        mech: &M,
        nb: &Neighbours<'_>,
        t: f64,
    ) -> Result<(), Error> {
        let info = mech.info();
        let n = info.n_coords;
        let w = &mut self.w;
        // The base projection and its multipliers μ: K [Δ; μ] = [0; −(Φq ṽ + Φt)].
        self.s.fit(info);
        mech.phi_q(&self.q, t, &mut self.s.phi_q);
        phi_q_times(info, &self.s.phi_q, &w.v_tilde, &mut w.rhs[n..]);
        mech.phi_t(&self.q, t, &mut w.tmp[n..]);
        for (r, p) in w.rhs[n..].iter_mut().zip(&w.tmp[n..]) {
            *r = -(*r + p);
        }
        w.tmp[..n].fill(0.0);
        self.kin
            .solve(&w.tmp[..n], &w.rhs[n..], &mut w.x, &mut w.mu, t)?;
        for ((v, a), b) in self.v.iter_mut().zip(&w.v_tilde).zip(&w.x) {
            *v = a + b;
        }
        // The residual [M (v − ṽ) + Φqᵀμ; Φq v + Φt] stays zero along p.
        let (q, dq, v) = (&self.q, &self.state.dq, &self.v);
        let s = &mut self.s;
        let Work {
            rhs,
            tmp,
            qa,
            va,
            diff,
            mu,
            v_tilde,
            dv_tilde,
            y,
            ..
        } = w;
        nb.derivative(rhs, tmp, |mech, e, out| {
            moved(q, e, dq, qa);
            moved(v_tilde, e, dv_tilde, va);
            for ((d, a), b) in diff.iter_mut().zip(v).zip(va.iter()) {
                *d = a - b;
            }
            velocity_residual(mech, t, (qa, diff, mu), s, out);
            // velocity_residual's lower half is Φq·(v − ṽ) + Φt; the projection's is Φq·v + Φt.
            let info = mech.info();
            phi_q_times(info, &s.phi_q, va, &mut s.vec_m);
            for (o, x) in out[n..].iter_mut().zip(&s.vec_m) {
                *o += x;
            }
            Ok(())
        })?;
        negate(rhs);
        let (f, g) = rhs.split_at(n);
        self.kin.solve(f, g, &mut self.state.dqd, y, t)
    }

    /// The saddle-point accelerations and multipliers at `(self.q, self.v)` into `a`, `l`,
    /// and their derivatives (those of the position and velocity being `state.dq`,
    /// `state.dqd`) into `da`, `dl`; `kin` factored at `self.q`.
    fn accelerations<M: Mechanism>(
        &mut self,
        mech: &M,
        nb: &Neighbours<'_>,
        t: f64,
        [a, l, da, dl]: [&mut [f64]; 4],
    ) -> Result<(), Error> {
        let n = self.q.len();
        let w = &mut self.w;
        let (force, gamma) = w.rhs.split_at_mut(n);
        mech.force(&self.q, &self.v, t, force);
        mech.gamma(&self.q, &self.v, t, gamma);
        self.kin.solve(force, gamma, a, l, t)?;
        let (q, v, dq, dv) = (&self.q, &self.v, &self.state.dq, &self.state.dqd);
        let s = &mut self.s;
        let Work {
            rhs, tmp, qa, va, ..
        } = w;
        let (a, l) = (&*a, &*l);
        nb.derivative(rhs, tmp, |mech, e, out| {
            moved(q, e, dq, qa);
            moved(v, e, dv, va);
            acceleration_residual(mech, t, (qa, va, a, l), s, out);
            Ok(())
        })?;
        negate(rhs);
        let (f, g) = rhs.split_at(n);
        self.kin.solve(f, g, da, dl, t)
    }

    /// `dr` = derivative of `Φqᵀλ − Q(q, ṽ)` at the current base state, ṽ = `w.v_tilde`
    /// (the velocity `r` is evaluated with) moving by `w.dv_tilde`; keeps ṽ for the next step.
    fn store_dr(&mut self, nb: &Neighbours<'_>, t: f64) -> Result<(), Error> {
        let n = self.q.len();
        let (q, l) = (&self.q, &self.lambda);
        let (dq, dl) = (&self.state.dq, &self.state.dlambda);
        let s = &mut self.s;
        let Work {
            tmp,
            qa,
            va,
            la,
            v_tilde,
            dv_tilde,
            ..
        } = &mut self.w;
        nb.derivative(&mut self.dr, &mut tmp[..n], |mech, e, out| {
            moved(q, e, dq, qa);
            moved(v_tilde, e, dv_tilde, va);
            moved(l, e, dl, la);
            generalized_reaction(mech, t, (qa, va, la), s, out);
            Ok(())
        })?;
        self.v_tilde.copy_from_slice(v_tilde);
        Ok(())
    }

    /// After the integrator accepted a step to `t1` with the state `(q1, q̇1, q̈1, λ1)`: the
    /// derivative of that state. Allocates nothing.
    pub fn step<M: Mechanism>(
        &mut self,
        mech: &M,
        nb: &Neighbours<'_>,
        t1: f64,
        (q1, v1, a1, l1): (&[f64], &[f64], &[f64], &[f64]),
    ) -> Result<(), Error> {
        let info = mech.info();
        let (n, m) = (info.n_coords, info.n_constraints);
        check_len("q", n, q1.len())?;
        check_len("lambda", m, l1.len())?;
        let h = t1 - self.t;
        let (alpha, beta, gamma) = (self.alpha, self.beta, self.gamma);
        let c = 1.0 / (1.0 + alpha);
        let inv_bh2 = 1.0 / (beta * h * h);
        self.kin.factor_at(mech, q1, t1)?;
        // The step's residual as a function of (q̈1, λ1) and the previous state.
        let (q0, v0, a0) = (&self.q, &self.v, &self.a);
        let w = &mut self.w;
        generalized_reaction(
            mech,
            self.t,
            (q0, &self.v_tilde, &self.lambda),
            &mut self.s,
            &mut w.r0,
        );
        let d = &self.state;
        w.da.copy_from_slice(&d.dqdd);
        w.dl.copy_from_slice(&d.dlambda);
        let Work {
            rhs,
            tmp,
            qa,
            va,
            aa,
            la,
            x,
            y,
            r0,
            da,
            dl,
            ..
        } = w;
        let s = &mut self.s;
        let dr = &self.dr;
        let mut converged = false;
        let mut iterations = 0;
        // The derivative's size, from the first change if the guess was zero.
        // At least the derivative that would change q̈1 (λ1) by its own size over the
        // parameter's value: below it, a derivative is zero for every purpose.
        let natural = |x: &[f64]| x.iter().fold(0.0f64, |s, v| s.max(v.abs())) * 1e-3 / nb.step();
        let (mut scale_a, mut scale_l) = (natural(a1), natural(l1));
        let mut last_rel = f64::INFINITY;
        while iterations < SENSITIVITY_ITERATIONS {
            iterations += 1;
            nb.derivative(rhs, tmp, |mech, e, out| {
                for i in 0..n {
                    let (qi, vi) = (q0[i] + e * d.dq[i], v0[i] + e * d.dqd[i]);
                    let (a0i, a1i) = (a0[i] + e * d.dqdd[i], a1[i] + e * da[i]);
                    qa[i] =
                        qi + h * vi + 0.5 * h * h * ((1.0 - 2.0 * beta) * a0i + 2.0 * beta * a1i);
                    va[i] = vi + h * ((1.0 - gamma) * a0i + gamma * a1i);
                    aa[i] = a1i;
                }
                for (j, l) in la.iter_mut().enumerate() {
                    *l = l1[j] + e * dl[j];
                }
                let info = mech.info();
                let (top, bottom) = out.split_at_mut(n);
                generalized_reaction(mech, t1, (qa, va, la), s, top);
                s.fit(info);
                mech.mass(qa, &mut s.mass);
                mass_times(info, &s.mass, aa, &mut s.vec_n);
                for i in 0..n {
                    let r_prev_i = r0[i] + e * dr[i];
                    top[i] += c * s.vec_n[i] - alpha * c * r_prev_i;
                }
                mech.phi(qa, t1, bottom);
                for b in bottom.iter_mut() {
                    *b *= inv_bh2;
                }
                Ok(())
            })?;
            // [cM Φqᵀ; Φq 0][Δa; Δλ] = −D through [M Φqᵀ; Φq 0][Δa; Δλ/c] = [−D₁/c; −D₂].
            for r in rhs[..n].iter_mut() {
                *r *= -c.recip();
            }
            negate(&mut rhs[n..]);
            let (f, g) = rhs.split_at(n);
            self.kin.solve(f, g, x, y, t1)?;
            let (mut change_a, mut change_l) = (0.0f64, 0.0f64);
            for (a, dx) in da.iter_mut().zip(x.iter()) {
                *a += dx;
                change_a = change_a.max(dx.abs());
            }
            for (l, dy) in dl.iter_mut().zip(y.iter()) {
                *l += c * dy;
                change_l = change_l.max((c * dy).abs());
            }
            if !(change_a.is_finite() && change_l.is_finite()) {
                break;
            }
            scale_a = da.iter().fold(scale_a.max(change_a), |s, v| s.max(v.abs()));
            scale_l = dl.iter().fold(scale_l.max(change_l), |s, v| s.max(v.abs()));
            let rel = (change_a / scale_a.max(f64::MIN_POSITIVE))
                .max(change_l / scale_l.max(f64::MIN_POSITIVE));
            // Done at the tolerance, or once the changes stop shrinking: they have reached
            // the noise of the differenced constraint rows, which the 1/(βh²) scaling lifts
            // to ≈ ε/(δ·βh²) in q̈ (as it lifts the step's own Newton increments; positions
            // get βh² of it back). Stagnation far above that is a failure.
            if rel <= SENSITIVITY_TOLERANCE || (rel > 0.5 * last_rel && rel <= STAGNATION_LIMIT) {
                converged = true;
                break;
            }
            last_rel = rel;
        }
        if !converged {
            return Err(Error::NewtonFailed {
                analysis: "HHT sensitivity",
                time: t1,
                residual: f64::NAN,
                iterations,
                row: None,
            });
        }
        // Newmark for the new (unprojected) velocity, and the derivatives of the new position
        // and velocity.
        let w = &mut self.w;
        let st = &mut self.state;
        // Seven vectors in step: an index reads more plainly than a zip of them.
        #[allow(clippy::needless_range_loop)]
        for i in 0..n {
            w.v_tilde[i] = self.v[i] + h * ((1.0 - gamma) * self.a[i] + gamma * a1[i]);
            st.dq[i] += h * st.dqd[i]
                + 0.5 * h * h * ((1.0 - 2.0 * beta) * st.dqdd[i] + 2.0 * beta * w.da[i]);
            w.dv_tilde[i] = st.dqd[i] + h * ((1.0 - gamma) * st.dqdd[i] + gamma * w.da[i]);
        }
        st.dqdd.copy_from_slice(&w.da);
        st.dlambda.copy_from_slice(&w.dl);
        self.t = t1;
        self.q.copy_from_slice(q1);
        self.a.copy_from_slice(a1);
        self.lambda.copy_from_slice(l1);
        if self.project {
            self.project_derivative(mech, nb, t1)?;
        } else {
            self.state.dqd.copy_from_slice(&self.w.dv_tilde);
        }
        // The integrator's own (projected) velocity is the state; the projection above is
        // the ideal one of the same constraints, equal to it up to the step's tolerance.
        self.v.copy_from_slice(v1);
        self.store_dr(nb, t1)
    }

    /// At the current state (after [`HhtSensitivity::start`] or a step): the saddle-point
    /// accelerations and multipliers recovered at `(q, q̇)`, as a run's outputs are
    /// (`EnergyMeter`), into `qdd`, `lambda`, and their derivatives into `dqdd`, `dlambda`;
    /// `state.dq`, `state.dqd` are the position's and velocity's. The step's own state is
    /// left as it was.
    pub fn recovered<M: Mechanism>(
        &mut self,
        mech: &M,
        nb: &Neighbours<'_>,
        (qdd, lambda): (&mut [f64], &mut [f64]),
        (dqdd, dlambda): (&mut [f64], &mut [f64]),
    ) -> Result<(), Error> {
        self.kin.factor_at(mech, &self.q, self.t)?;
        let t = self.t;
        self.accelerations(mech, nb, t, [qdd, lambda, dqdd, dlambda])
    }
}

/// `out = Φqᵀλ − Q` at `(q, q̇, λ)`.
fn generalized_reaction(
    mech: &dyn Mechanism,
    t: f64,
    (q, v, lambda): (&[f64], &[f64], &[f64]),
    s: &mut Scratch,
    out: &mut [f64],
) {
    let info = mech.info();
    s.fit(info);
    mech.phi_q(q, t, &mut s.phi_q);
    phi_q_transpose_times(info, &s.phi_q, lambda, out);
    mech.force(q, v, t, &mut s.vec_n);
    for (o, f) in out.iter_mut().zip(&s.vec_n) {
        *o -= f;
    }
}
