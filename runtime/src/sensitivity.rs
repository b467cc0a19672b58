//! Sensitivities of a solution with respect to one parameter of the mechanism file: the
//! implicit part (positions, velocities, accelerations and multipliers defined by the
//! saddle-point systems, or by the HHT step equations) differentiated exactly, by solving
//! with the matrix the solver already factored; the explicit part (how Φ, Φq, Φt, γ, M and Q
//! change along the state's and the parameter's direction) from the generator's exact
//! directional derivatives of the equations ([`Mechanism::tangents`], decision 37).
//!
//! What is differenced: only what the loader makes of the parameter, once per run and
//! explicitly: the run-time values the equations read (`dp`), the assembled initial pose and
//! the given velocities, and the joint points outputs are taken at, by the fourth-order
//! central difference over the mechanism built at four neighbouring values of the parameter
//! ([`Neighbours`]). Those are smooth functions with no solver tolerance in them, so with the
//! step [`relative_step`] their error is that of the stencil, (δ⁴ f⁽⁵⁾/30) ≈ 1e-12, plus
//! roundoff ≈ 1e-13 / 1e-3.

use crate::error::{check_len, Error};
use crate::kinematics::{mass_times, phi_q_transpose_times, Kinematics};
use crate::kkt::KktSolver;
use crate::mechanism::{Direction, Mechanism, MechanismInfo, TangentOutputs};

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
/// `p − 2δ, p − δ, p + δ, p + 2δ`, every other parameter unchanged; the base mechanism at
/// `p`, whose tangents the analyses take; and the derivative of its run-time values along
/// the parameter, the direction `dp` of those tangents.
pub struct Neighbours<'a> {
    step: f64,
    base: &'a dyn Mechanism,
    mechs: [&'a dyn Mechanism; 4],
    dp: Vec<f64>,
}

impl<'a> Neighbours<'a> {
    /// Checks that the four share `base`'s structure (sizes, redundant rows, the layout of
    /// their run-time values): a parameter change that alters it has no derivative at `p`.
    /// `dp` is the derivative of their run-time values, which are laid out as the base's (the
    /// same compiled code).
    pub fn new(
        base: &'a dyn Mechanism,
        step: f64,
        mechs: [&'a dyn Mechanism; 4],
    ) -> Result<Self, Error> {
        let values = mechs.map(|m| m.run_time_values());
        Self::with_values(base, step, mechs, values)
    }

    /// [`Neighbours::new`] with the base's run-time values at the four neighbouring values
    /// given in the base's layout (`values`): for mechanisms each loaded with a layout of its
    /// own (interpreted files, whose slots each load finds again).
    pub fn with_values(
        base: &'a dyn Mechanism,
        step: f64,
        mechs: [&'a dyn Mechanism; 4],
        values: [&[f64]; 4],
    ) -> Result<Self, Error> {
        if !(step.is_finite() && step > 0.0) {
            return Err(Error::InvalidSetting {
                name: "parameter step",
                value: step,
                reason: "must be positive and finite",
            });
        }
        let (info, n_p) = (base.info(), base.run_time_values().len());
        for (m, v) in mechs.iter().zip(&values) {
            // Patterns may differ: an entry that cancels exactly at the file's value (a
            // difference of equal numbers, folded away by an interpreted load) is
            // structurally absent there and present beside it, where it is small. Every
            // evaluation here goes through each mechanism's own pattern into dense vectors.
            let i = m.info();
            let same = i.n_coords == info.n_coords
                && i.n_constraints == info.n_constraints
                && i.redundant_rows == info.redundant_rows
                && v.len() == n_p;
            if !same {
                return Err(Error::InvalidPattern {
                    reason: format!(
                        "the mechanism's structure (coordinates, rows, redundant rows or \
                         run-time values) changes within ±{:.3e} of the parameter's value: \
                         it has no derivative there",
                        2.0 * step
                    ),
                });
            }
        }
        // The stencil of the given values, in the order of `mechs` (OFFSETS).
        let dp = (0..n_p)
            .map(|i| {
                WEIGHTS
                    .iter()
                    .zip(&values)
                    .map(|(w, v)| w * v[i])
                    .sum::<f64>()
                    / step
            })
            .collect();
        Ok(Neighbours {
            step,
            base,
            mechs,
            dp,
        })
    }

    pub fn step(&self) -> f64 {
        self.step
    }

    /// The mechanism at the parameter's value: the run's equations, with the run-time values
    /// laid out as `dp`. Every evaluation of the analyses here is its.
    pub fn base(&self) -> &'a dyn Mechanism {
        self.base
    }

    /// The derivative of the base mechanism's run-time values along the parameter.
    pub fn dp(&self) -> &[f64] {
        &self.dp
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

/// The directional derivatives of a mechanism's functions at one point along one direction
/// (`d_*`, [`Mechanism::tangents`]), and Φq and M at the point (`phi_q`, `mass`,
/// [`Jet::values`]), which the product rule needs. Sized once.
pub(crate) struct Jet {
    d_phi: Vec<f64>,
    d_phi_q: Vec<f64>,
    d_phi_t: Vec<f64>,
    d_gamma: Vec<f64>,
    d_mass: Vec<f64>,
    d_force: Vec<f64>,
    phi_q: Vec<f64>,
    mass: Vec<f64>,
    vec_n: Vec<f64>,
    vec_m: Vec<f64>,
}

impl Jet {
    pub(crate) fn new(info: &MechanismInfo) -> Self {
        let (n, m) = (info.n_coords, info.n_constraints);
        let z = |k: usize| vec![0.0; k];
        Jet {
            d_phi: z(m),
            d_phi_q: z(info.phi_q_nnz()),
            d_phi_t: z(m),
            d_gamma: z(m),
            d_mass: z(info.mass_nnz()),
            d_force: z(n),
            phi_q: z(info.phi_q_nnz()),
            mass: z(info.mass_nnz()),
            vec_n: z(n),
            vec_m: z(m),
        }
    }

    /// The tangents at `(q, q̇, t)` along `(dq, dq̇)` and `nb`'s parameter, of `nb`'s base
    /// mechanism (the equations of the run's, with run-time values laid out as `dp`).
    fn at(
        &mut self,
        nb: &Neighbours<'_>,
        t: f64,
        (q, dq): (&[f64], &[f64]),
        (qd, dqd): (&[f64], &[f64]),
    ) -> Result<(), Error> {
        let (mech, dp) = (nb.base, nb.dp());
        let out = TangentOutputs {
            phi: &mut self.d_phi,
            phi_q: &mut self.d_phi_q,
            phi_t: &mut self.d_phi_t,
            gamma: &mut self.d_gamma,
            mass: &mut self.d_mass,
            force: &mut self.d_force,
        };
        match mech.tangents(q, qd, t, Direction { dq, dqd, dp }, out) {
            true => Ok(()),
            false => Err(Error::NoTangents {
                mechanism: mech.info().name,
            }),
        }
    }

    /// Φq and M at `q`.
    fn values(&mut self, mech: &dyn Mechanism, q: &[f64], t: f64) {
        mech.phi_q(q, t, &mut self.phi_q);
        mech.mass(q, &mut self.mass);
    }

    /// `out` = the derivative of `[M x + Φqᵀy; Φq x]` with `x` and `y` moving by `dx` and
    /// `dy` (`None`: held), from the tangents and the values at the point.
    fn saddle(
        &mut self,
        info: &MechanismInfo,
        (x, dx): (&[f64], Option<&[f64]>),
        (y, dy): (&[f64], Option<&[f64]>),
        out: &mut [f64],
    ) {
        let (top, bottom) = out.split_at_mut(info.n_coords);
        mass_times(info, &self.d_mass, x, top);
        phi_q_transpose_times(info, &self.d_phi_q, y, &mut self.vec_n);
        add(top, &self.vec_n, 1.0);
        phi_q_times(info, &self.d_phi_q, x, bottom);
        if let Some(dx) = dx {
            mass_times(info, &self.mass, dx, &mut self.vec_n);
            add(top, &self.vec_n, 1.0);
            phi_q_times(info, &self.phi_q, dx, &mut self.vec_m);
            add(bottom, &self.vec_m, 1.0);
        }
        if let Some(dy) = dy {
            phi_q_transpose_times(info, &self.phi_q, dy, &mut self.vec_n);
            add(top, &self.vec_n, 1.0);
        }
    }
}

/// `out += s·v`.
fn add(out: &mut [f64], v: &[f64], s: f64) {
    for (o, x) in out.iter_mut().zip(v) {
        *o += s * x;
    }
}

/// `out = Φq v` from the Jacobian nonzeros.
fn phi_q_times(info: &MechanismInfo, phi_q: &[f64], v: &[f64], out: &mut [f64]) {
    out.fill(0.0);
    for ((&r, &c), &a) in info.phi_q_rows.iter().zip(info.phi_q_cols).zip(phi_q) {
        out[r as usize] += a * v[c as usize];
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

/// The derivative with respect to the parameter of a kinematic analysis at time `t`: the
/// position on Φ(q, t) = 0 (the correction of least kinetic energy, as the position solve
/// takes it, so free directions the drivers leave get none), the least-energy velocity with
/// its multipliers `nu`, and the accelerations and multipliers. `kin` must hold the
/// factorization of `[M Φqᵀ; Φq 0]` at this state, as [`Kinematics::velocity_and_acceleration`]
/// leaves it (its mechanism has the equations of `neighbours`' base).
pub fn kinematic<K: KktSolver>(
    kin: &mut Kinematics<K>,
    neighbours: &Neighbours<'_>,
    t: f64,
    (q, qd, qdd, lambda): (&[f64], &[f64], &[f64], &[f64]),
    out: &mut StateSensitivity,
) -> Result<(), Error> {
    let mech = neighbours.base;
    let info = mech.info();
    let (n, m) = (info.n_coords, info.n_constraints);
    check_len("q", n, q.len())?;
    check_len("lambda", m, lambda.len())?;
    let nu = kin.velocity_multipliers().to_vec();
    let mut jet = Jet::new(info);
    jet.values(mech, q, t);
    let mut rhs = vec![0.0; n + m];
    let zero_n = vec![0.0; n];
    let mut dnu = vec![0.0; m];

    // Φ(q(p), t; p) = 0  ⇒  Φq dq = −∂Φ/∂p.
    jet.at(neighbours, t, (q, &zero_n), (qd, &zero_n))?;
    for (r, d) in rhs[n..].iter_mut().zip(&jet.d_phi) {
        *r = -d;
    }
    kin.solve(&zero_n, &rhs[n..], &mut out.dq, &mut dnu, t)?;

    // The velocity system's residual [M q̇ + Φqᵀν; Φq q̇ + Φt] is zero along p:
    // K [dq̇; dν] = −(its change at fixed q̇, ν).
    jet.at(neighbours, t, (q, &out.dq), (qd, &zero_n))?;
    jet.saddle(info, (qd, None), (&nu, None), &mut rhs);
    add(&mut rhs[n..], &jet.d_phi_t, 1.0);
    negate(&mut rhs);
    let (f, g) = rhs.split_at(n);
    kin.solve(f, g, &mut out.dqd, &mut dnu, t)?;

    // Likewise [M q̈ + Φqᵀλ − Q; Φq q̈ − γ], which also moves with q̇.
    jet.at(neighbours, t, (q, &out.dq), (qd, &out.dqd))?;
    jet.saddle(info, (qdd, None), (lambda, None), &mut rhs);
    add(&mut rhs[..n], &jet.d_force, -1.0);
    add(&mut rhs[n..], &jet.d_gamma, -1.0);
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
    jet: Jet,
    w: Work,
}

/// Work space of [`HhtSensitivity`], sized once: a step allocates nothing.
struct Work {
    /// Right-hand sides, `n + m`.
    rhs: Vec<f64>,
    /// The step's base position and velocity, and their directions.
    qa: Vec<f64>,
    va: Vec<f64>,
    dqa: Vec<f64>,
    dva: Vec<f64>,
    /// Solutions `(x, y)` of the saddle-point solves.
    x: Vec<f64>,
    y: Vec<f64>,
    /// The step's previous `r = Φqᵀλ − Q`, and its Newmark velocity and derivatives.
    r0: Vec<f64>,
    v_tilde: Vec<f64>,
    dv_tilde: Vec<f64>,
    da: Vec<f64>,
    dl: Vec<f64>,
    /// `v − ṽ` and `−dṽ` of the projection, and its multipliers.
    diff: Vec<f64>,
    ddiff: Vec<f64>,
    mu: Vec<f64>,
    vec_n: Vec<f64>,
}

impl Work {
    fn new(n: usize, m: usize) -> Self {
        let z = |k: usize| vec![0.0; k];
        Work {
            rhs: z(n + m),
            qa: z(n),
            va: z(n),
            dqa: z(n),
            dva: z(n),
            x: z(n),
            y: z(m),
            r0: z(n),
            v_tilde: z(n),
            dv_tilde: z(n),
            da: z(n),
            dl: z(m),
            diff: z(n),
            ddiff: z(n),
            mu: z(m),
            vec_n: z(n),
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
    /// derivatives, from the neighbours' assembled poses and given velocities. Every
    /// evaluation is of `nb`'s base, which has the run's equations.
    #[allow(clippy::too_many_arguments)]
    pub fn start(
        nb: &Neighbours<'_>,
        settings: crate::kinematics::KinematicSettings,
        (alpha, project): (f64, bool),
        t0: f64,
        (q, v, a, lambda): (&[f64], &[f64], &[f64], &[f64]),
    ) -> Result<Self, Error> {
        let mech = nb.base;
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
            jet: Jet::new(info),
            w: Work::new(n, m),
        };
        me.kin.factor_at(&mech, q, t0)?;
        let mut y = vec![0.0; m];

        // The assembled pose moves with p; the start's position solve keeps it on Φ = 0
        // with the correction of least kinetic energy.
        let mut dq_given = vec![0.0; n];
        let mut dn = vec![0.0; n];
        nb.derivative(&mut dq_given, &mut dn, |mech, _, out| {
            out.copy_from_slice(mech.info().q0);
            Ok(())
        })?;
        let zero_n = vec![0.0; n];
        me.jet.at(nb, t0, (q, &dq_given), (v, &zero_n))?;
        let rhs: Vec<f64> = me.jet.d_phi.iter().map(|d| -d).collect();
        let mut dq = vec![0.0; n];
        me.kin.solve(&zero_n, &rhs, &mut dq, &mut y, t0)?;
        add(&mut dq, &dq_given, 1.0);
        me.state.dq = dq;

        // The given velocities move with p too, and are projected.
        let mut dv_given = vec![0.0; n];
        nb.derivative(&mut dv_given, &mut dn, |mech, _, out| {
            out.copy_from_slice(mech.info().qd0);
            Ok(())
        })?;
        me.w.v_tilde.copy_from_slice(mech.info().qd0);
        me.w.dv_tilde.copy_from_slice(&dv_given);
        // Φq and M at the start, for the projection, the accelerations and `r` alike.
        me.jet.values(mech, q, t0);
        me.project_derivative(nb, t0)?;
        let (mut a, mut l) = (vec![0.0; n], vec![0.0; m]);
        let (mut da, mut dl) = (vec![0.0; n], vec![0.0; m]);
        me.accelerations(nb, t0, [&mut a, &mut l, &mut da, &mut dl])?;
        (me.a, me.lambda, me.state.dqdd, me.state.dlambda) = (a, l, da, dl);
        // `r` at the start is evaluated with the projected velocity.
        me.w.v_tilde.copy_from_slice(&me.v);
        me.w.dv_tilde.copy_from_slice(&me.state.dqd);
        me.store_dr(nb, t0)?;
        Ok(me)
    }

    /// `state.dqd` for `v = ṽ + Δ`, Δ the projection of least kinetic energy of
    /// ṽ = `w.v_tilde` (whose derivative is `w.dv_tilde`) onto the velocity constraints at
    /// `self.q`; `kin` must be factored there and `jet` hold the values there. Sets `self.v`
    /// to the projected base velocity.
    fn project_derivative(&mut self, nb: &Neighbours<'_>, t: f64) -> Result<(), Error> {
        let mech = nb.base;
        let info = mech.info();
        let n = info.n_coords;
        let (w, jet) = (&mut self.w, &mut self.jet);
        // The base projection and its multipliers μ: K [Δ; μ] = [0; −(Φq ṽ + Φt)].
        phi_q_times(info, &jet.phi_q, &w.v_tilde, &mut w.rhs[n..]);
        mech.phi_t(&self.q, t, &mut jet.vec_m);
        for (r, p) in w.rhs[n..].iter_mut().zip(&jet.vec_m) {
            *r = -(*r + p);
        }
        w.rhs[..n].fill(0.0);
        let (f, g) = w.rhs.split_at(n);
        self.kin.solve(f, g, &mut w.x, &mut w.mu, t)?;
        for ((v, a), b) in self.v.iter_mut().zip(&w.v_tilde).zip(&w.x) {
            *v = a + b;
        }
        // The residual [M (v − ṽ) + Φqᵀμ; Φq v + Φt] stays zero along p, with q moving by
        // dq and ṽ by dṽ.
        jet.at(nb, t, (&self.q, &self.state.dq), (&self.v, &w.dv_tilde))?;
        for i in 0..n {
            w.diff[i] = self.v[i] - w.v_tilde[i];
            w.ddiff[i] = -w.dv_tilde[i];
        }
        jet.saddle(info, (&w.diff, Some(&w.ddiff)), (&w.mu, None), &mut w.rhs);
        // `saddle`'s lower half is the change of Φq·(v − ṽ); the projection's is Φq·v + Φt.
        let bottom = &mut w.rhs[n..];
        phi_q_times(info, &jet.d_phi_q, &self.v, bottom);
        add(bottom, &jet.d_phi_t, 1.0);
        negate(&mut w.rhs);
        let (f, g) = w.rhs.split_at(n);
        self.kin.solve(f, g, &mut self.state.dqd, &mut w.y, t)
    }

    /// The saddle-point accelerations and multipliers at `(self.q, self.v)` into `a`, `l`,
    /// and their derivatives (those of the position and velocity being `state.dq`,
    /// `state.dqd`) into `da`, `dl`; `kin` factored at `self.q`, `jet` holding the values there.
    fn accelerations(
        &mut self,
        nb: &Neighbours<'_>,
        t: f64,
        [a, l, da, dl]: [&mut [f64]; 4],
    ) -> Result<(), Error> {
        let mech = nb.base;
        let info = mech.info();
        let n = info.n_coords;
        let (w, jet) = (&mut self.w, &mut self.jet);
        let (force, gamma) = w.rhs.split_at_mut(n);
        mech.force(&self.q, &self.v, t, force);
        mech.gamma(&self.q, &self.v, t, gamma);
        self.kin.solve(force, gamma, a, l, t)?;
        let (q, v, d) = (&self.q, &self.v, &self.state);
        jet.at(nb, t, (q, &d.dq), (v, &d.dqd))?;
        jet.saddle(info, (a, None), (l, None), &mut w.rhs);
        add(&mut w.rhs[..n], &jet.d_force, -1.0);
        add(&mut w.rhs[n..], &jet.d_gamma, -1.0);
        negate(&mut w.rhs);
        let (f, g) = w.rhs.split_at(n);
        self.kin.solve(f, g, da, dl, t)
    }

    /// `dr` = derivative of `Φqᵀλ − Q(q, ṽ)` at the current base state, ṽ = `w.v_tilde`
    /// (the velocity `r` is evaluated with) moving by `w.dv_tilde`; keeps ṽ for the next step.
    /// `jet` holds the values at `self.q`.
    fn store_dr(&mut self, nb: &Neighbours<'_>, t: f64) -> Result<(), Error> {
        let info = nb.base.info();
        let (w, jet) = (&mut self.w, &mut self.jet);
        let (q, dq) = (&self.q, &self.state.dq);
        jet.at(nb, t, (q, dq), (&w.v_tilde, &w.dv_tilde))?;
        phi_q_transpose_times(info, &jet.d_phi_q, &self.lambda, &mut self.dr);
        phi_q_transpose_times(info, &jet.phi_q, &self.state.dlambda, &mut w.vec_n);
        add(&mut self.dr, &w.vec_n, 1.0);
        add(&mut self.dr, &jet.d_force, -1.0);
        self.v_tilde.copy_from_slice(&w.v_tilde);
        Ok(())
    }

    /// After the integrator accepted a step to `t1` with the state `(q1, q̇1, q̈1, λ1)`: the
    /// derivative of that state. Allocates nothing.
    pub fn step(
        &mut self,
        nb: &Neighbours<'_>,
        t1: f64,
        (q1, v1, a1, l1): (&[f64], &[f64], &[f64], &[f64]),
    ) -> Result<(), Error> {
        let mech = nb.base;
        let info = mech.info();
        let (n, m) = (info.n_coords, info.n_constraints);
        check_len("q", n, q1.len())?;
        check_len("lambda", m, l1.len())?;
        let h = t1 - self.t;
        let (alpha, beta, gamma) = (self.alpha, self.beta, self.gamma);
        let c = 1.0 / (1.0 + alpha);
        let inv_bh2 = 1.0 / (beta * h * h);
        self.kin.factor_at(&mech, q1, t1)?;
        // The step's residual as a function of (q̈1, λ1) and the previous state:
        // [Φqᵀλ1 − Q + c M q̈1 − αc r0; Φ/(βh²)] at the Newmark position and velocity.
        let (q0, v0, a0) = (&self.q, &self.v, &self.a);
        let (w, jet) = (&mut self.w, &mut self.jet);
        generalized_reaction(
            mech,
            self.t,
            (q0, &self.v_tilde, &self.lambda),
            jet,
            &mut w.r0,
        );
        for i in 0..n {
            w.qa[i] =
                q0[i] + h * v0[i] + 0.5 * h * h * ((1.0 - 2.0 * beta) * a0[i] + 2.0 * beta * a1[i]);
            w.va[i] = v0[i] + h * ((1.0 - gamma) * a0[i] + gamma * a1[i]);
        }
        jet.values(mech, &w.qa, t1);
        let d = &self.state;
        w.da.copy_from_slice(&d.dqdd);
        w.dl.copy_from_slice(&d.dlambda);
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
            for i in 0..n {
                w.dqa[i] = d.dq[i]
                    + h * d.dqd[i]
                    + 0.5 * h * h * ((1.0 - 2.0 * beta) * d.dqdd[i] + 2.0 * beta * w.da[i]);
                w.dva[i] = d.dqd[i] + h * ((1.0 - gamma) * d.dqdd[i] + gamma * w.da[i]);
            }
            jet.at(nb, t1, (&w.qa, &w.dqa), (&w.va, &w.dva))?;
            // The residual's derivative D: that of Φqᵀλ1 − Q + c M q̈1 − αc r0, and of Φ/(βh²).
            let (top, bottom) = w.rhs.split_at_mut(n);
            phi_q_transpose_times(info, &jet.d_phi_q, l1, top);
            phi_q_transpose_times(info, &jet.phi_q, &w.dl, &mut w.vec_n);
            add(top, &w.vec_n, 1.0);
            add(top, &jet.d_force, -1.0);
            mass_times(info, &jet.d_mass, a1, &mut w.vec_n);
            add(top, &w.vec_n, c);
            mass_times(info, &jet.mass, &w.da, &mut w.vec_n);
            add(top, &w.vec_n, c);
            add(top, &self.dr, -alpha * c);
            for (b, p) in bottom.iter_mut().zip(&jet.d_phi) {
                *b = p * inv_bh2;
            }
            // [cM Φqᵀ; Φq 0][Δa; Δλ] = −D through [M Φqᵀ; Φq 0][Δa; Δλ/c] = [−D₁/c; −D₂].
            for r in w.rhs[..n].iter_mut() {
                *r *= -c.recip();
            }
            negate(&mut w.rhs[n..]);
            let (f, g) = w.rhs.split_at(n);
            self.kin.solve(f, g, &mut w.x, &mut w.y, t1)?;
            let (mut change_a, mut change_l) = (0.0f64, 0.0f64);
            for (a, dx) in w.da.iter_mut().zip(w.x.iter()) {
                *a += dx;
                change_a = change_a.max(dx.abs());
            }
            for (l, dy) in w.dl.iter_mut().zip(w.y.iter()) {
                *l += c * dy;
                change_l = change_l.max((c * dy).abs());
            }
            if !(change_a.is_finite() && change_l.is_finite()) {
                break;
            }
            scale_a =
                w.da.iter()
                    .fold(scale_a.max(change_a), |s, v| s.max(v.abs()));
            scale_l =
                w.dl.iter()
                    .fold(scale_l.max(change_l), |s, v| s.max(v.abs()));
            let rel = (change_a / scale_a.max(f64::MIN_POSITIVE))
                .max(change_l / scale_l.max(f64::MIN_POSITIVE));
            // Done at the tolerance, or once the changes stop shrinking: they have reached
            // the roundoff of the constraint rows, which the 1/(βh²) scaling lifts to
            // ≈ ε/(βh²) in q̈ (as it lifts the step's own Newton increments; positions get
            // βh² of it back). Stagnation far above that is a failure.
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
        // Φq and M at the new position, for the projection and `r` alike.
        self.jet.values(mech, q1, t1);
        if self.project {
            self.project_derivative(nb, t1)?;
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
    pub fn recovered(
        &mut self,
        nb: &Neighbours<'_>,
        (qdd, lambda): (&mut [f64], &mut [f64]),
        (dqdd, dlambda): (&mut [f64], &mut [f64]),
    ) -> Result<(), Error> {
        let mech = nb.base;
        self.kin.factor_at(&mech, &self.q, self.t)?;
        let t = self.t;
        self.jet.values(mech, &self.q, t);
        self.accelerations(nb, t, [qdd, lambda, dqdd, dlambda])
    }
}

/// `out = Φqᵀλ − Q` at `(q, q̇, λ)`, with `jet`'s buffers as scratch.
fn generalized_reaction(
    mech: &dyn Mechanism,
    t: f64,
    (q, v, lambda): (&[f64], &[f64], &[f64]),
    jet: &mut Jet,
    out: &mut [f64],
) {
    let info = mech.info();
    mech.phi_q(q, t, &mut jet.phi_q);
    phi_q_transpose_times(info, &jet.phi_q, lambda, out);
    mech.force(q, v, t, &mut jet.vec_n);
    add(out, &jet.vec_n, -1.0);
}
