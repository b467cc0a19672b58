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
            let i = m.info();
            let same = i.n_coords == base.n_coords
                && i.n_constraints == base.n_constraints
                && i.phi_q_rows == base.phi_q_rows
                && i.phi_q_cols == base.phi_q_cols
                && i.mass_rows == base.mass_rows
                && i.mass_cols == base.mass_cols
                && i.redundant_rows == base.redundant_rows;
            if !same {
                return Err(Error::InvalidPattern {
                    reason: format!(
                        "the mechanism's structure (coordinates, rows, patterns or redundant \
                         rows) changes within ±{:.3e} of the parameter's value: it has no \
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

/// The residuals of the saddle-point systems a kinematic analysis solves, at one state:
/// `[M q̇ + Φqᵀν; Φq q̇ + Φt]` (least-energy velocity) and `[M q̈ + Φqᵀλ − Q; Φq q̈ − γ]`.
pub(crate) fn velocity_residual(
    mech: &dyn Mechanism,
    t: f64,
    (q, qd, nu): (&[f64], &[f64], &[f64]),
    s: &mut Scratch,
    out: &mut [f64],
) {
    let info = mech.info();
    let n = info.n_coords;
    mech.phi_q(q, t, &mut s.phi_q);
    mech.mass(q, &mut s.mass);
    let (top, bottom) = out.split_at_mut(n);
    mass_times(info, &s.mass, qd, top);
    phi_q_transpose_times(info, &s.phi_q, nu, &mut s.vec_n);
    for (a, b) in top.iter_mut().zip(&s.vec_n) {
        *a += b;
    }
    phi_q_times(info, &s.phi_q, qd, bottom);
    mech.phi_t(q, t, &mut s.vec_m);
    for (a, b) in bottom.iter_mut().zip(&s.vec_m) {
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
    let info = mech.info();
    let n = info.n_coords;
    mech.phi_q(q, t, &mut s.phi_q);
    mech.mass(q, &mut s.mass);
    let (top, bottom) = out.split_at_mut(n);
    mass_times(info, &s.mass, qdd, top);
    phi_q_transpose_times(info, &s.phi_q, lambda, &mut s.vec_n);
    for (a, b) in top.iter_mut().zip(&s.vec_n) {
        *a += b;
    }
    mech.force(q, qd, t, &mut s.vec_n);
    for (a, b) in top.iter_mut().zip(&s.vec_n) {
        *a -= b;
    }
    phi_q_times(info, &s.phi_q, qdd, bottom);
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
