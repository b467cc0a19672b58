//! Directional derivatives of the equations (docs/design.md, decision 37): Φ, Φq, Φt, γ, M
//! and Q differentiated forward along one direction `(dq, dq̇, dp)` of the coordinates, the
//! velocities and the run-time values, on the same DAG. The generated `tangents` evaluate
//! them; the sensitivity analyses need nothing else from the equations.

use crate::equations::System;
use crate::expr::{Id, Var};

/// The directional derivatives of the kinematic functions: Φ, Φq's nonzeros (in the order of
/// `System::phi_q`), Φt and γ.
#[derive(Debug, Clone, Default)]
pub struct Kinematic {
    pub phi: Vec<Id>,
    pub phi_q: Vec<Id>,
    pub phi_t: Vec<Id>,
    pub gamma: Vec<Id>,
}

/// The directional derivatives of one formulation's M (its nonzeros, in order) and Q.
#[derive(Debug, Clone, Default)]
pub struct Dynamic {
    pub mass: Vec<Id>,
    pub force: Vec<Id>,
}

/// Fills `sys.tangent` and each formulation's `tangent`: every root differentiated in one
/// forward pass, with `q[i] ↦ dq[i]`, `qd[i] ↦ dqd[i]`, `p[i] ↦ dp[i]` (time held fixed).
/// Call it on the parametric system, before hoisting: what depends on `p` alone in a
/// derivative is then hoisted like the rest.
pub fn add(sys: &mut System) {
    let a = &mut sys.arena;
    let n = sys.n_coords as u32;
    let dq: Vec<Id> = (0..n).map(|i| a.var(Var::Dq(i))).collect();
    let dqd: Vec<Id> = (0..n).map(|i| a.var(Var::Dqd(i))).collect();
    let n_p = sys.value_lengths().0 as u32;
    let a = &mut sys.arena;
    let dp: Vec<Id> = (0..n_p).map(|i| a.var(Var::Dp(i))).collect();
    let mut roots: Vec<Id> = Vec::new();
    roots.extend(&sys.phi);
    roots.extend(sys.phi_q.iter().map(|e| e.2));
    roots.extend(&sys.phi_t);
    roots.extend(&sys.gamma);
    for d in &sys.dynamics {
        roots.extend(d.mass.iter().map(|e| e.2));
        roots.extend(&d.force);
    }
    let seed = |v: Var| match v {
        Var::Q(i) => Some(dq[i as usize]),
        Var::Qd(i) => Some(dqd[i as usize]),
        Var::P(i) => Some(dp[i as usize]),
        _ => None,
    };
    let d = sys.arena.derivative(&roots, &seed);
    let mut it = d.into_iter();
    let mut take = |k: usize| -> Vec<Id> { it.by_ref().take(k).collect() };
    let m = sys.n_constraints;
    sys.tangent = Some(Kinematic {
        phi: take(m),
        phi_q: take(sys.phi_q.len()),
        phi_t: take(m),
        gamma: take(m),
    });
    for dy in &mut sys.dynamics {
        dy.tangent = Dynamic {
            mass: take(dy.mass.len()),
            force: take(dy.force.len()),
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::Arena;

    /// The forward pass along a direction against the partial derivatives it sums:
    /// d(p·sin q0·q̇1) = p·cos q0·q̇1·dq0 + p·sin q0·dq̇1 + sin q0·q̇1·dp.
    #[test]
    fn a_tangent_is_the_sum_of_the_partials_along_the_direction() {
        let mut a = Arena::new();
        let (q0, qd1, p) = (a.var(Var::Q(0)), a.var(Var::Qd(1)), a.var(Var::P(0)));
        let s = a.sin(q0);
        let sq = a.mul(s, qd1);
        let f = a.mul(p, sq);
        let d = {
            let (dq0, dqd1, dp) = (a.var(Var::Dq(0)), a.var(Var::Dqd(1)), a.var(Var::Dp(0)));
            let seed = move |v: Var| match v {
                Var::Q(0) => Some(dq0),
                Var::Qd(1) => Some(dqd1),
                Var::P(0) => Some(dp),
                _ => None,
            };
            a.derivative(&[f], &seed)[0]
        };
        let (x, v, pv, dx, dv, dpv) = (0.3, -1.2, 2.5, 0.7, 0.4, -0.9);
        let env = |var: Var| match var {
            Var::Q(_) => x,
            Var::Qd(_) => v,
            Var::P(_) => pv,
            Var::Dq(_) => dx,
            Var::Dqd(_) => dv,
            Var::Dp(_) => dpv,
            _ => f64::NAN,
        };
        let by_hand: f64 =
            pv * f64::cos(x) * v * dx + pv * f64::sin(x) * dv + f64::sin(x) * v * dpv;
        assert!((a.eval(d, &env) - by_hand).abs() <= 1e-15 * by_hand.abs());
    }
}
