//! Applied loads as generalized forces (docs/design.md, decision 20): gravity, spring–damper–
//! actuators, torsion springs, applied forces and torques. Each load is reduced to a
//! scalar `s(q)` with a force along it (Q += f ∂s/∂q), a force at a point (Q += J_pᵀF) or a
//! torque (Q += (∂ω/∂q̇)ᵀτ); conservative parts add to the potential, the others to the
//! non-conservative power.

use crate::equations::{jacobian, BodySym, V3s};
use crate::expr::{Arena, Id, Var};
use crate::model::{ForceKind, Model};
use crate::primitives::{angle_cos_sin, distance, mat_vec, point_world, sym_frame};

/// The generalized load vector, potential energy and non-conservative power.
pub struct Loads {
    pub force: Vec<Id>,
    pub potential: Id,
    pub power_nc: Id,
}

struct Acc<'a> {
    a: &'a mut Arena,
    force: Vec<Vec<Id>>,
    n: usize,
}

impl Acc<'_> {
    /// Q += f · ∂s/∂q.
    fn along(&mut self, s: Id, f: Id) {
        for (_, c, d) in jacobian(self.a, &[s], self.n) {
            let t = self.a.mul(f, d);
            self.force[c as usize].push(t);
        }
    }

    /// Q += J_pᵀ F for a force `f` at the point `p`.
    fn at_point(&mut self, p: V3s, f: V3s) {
        for (k, c, d) in jacobian(self.a, &p, self.n) {
            let t = self.a.mul(f[k as usize], d);
            self.force[c as usize].push(t);
        }
    }

    /// Q += (∂ω/∂q̇)ᵀ τ for a torque on a body with global angular velocity `omega`.
    fn torque(&mut self, body: &BodySym, omega: V3s, tau: V3s) {
        let one = self.a.constant(1.0);
        for k in 0..3 + body.rotation.n_coords() {
            let target = Var::Qd((body.offset + k) as u32);
            let d = self.a.derivative(&omega, &|v| (v == target).then_some(one));
            let p = self.a.dot3(d.try_into().expect("three components"), tau);
            if !self.a.is_zero(p) {
                self.force[body.offset + k].push(p);
            }
        }
    }

    /// Rate of change of `x` along the velocities.
    fn rate(&mut self, x: &[Id]) -> Vec<Id> {
        let qd: Vec<Id> = (0..self.n).map(|i| self.a.var(Var::Qd(i as u32))).collect();
        self.a.derivative(x, &|v| match v {
            Var::Q(i) => Some(qd[i as usize]),
            _ => None,
        })
    }
}

pub fn build(a: &mut Arena, model: &Model, bodies: &[BodySym]) -> Loads {
    let n = model.n_coords();
    let mut potential = Vec::new();
    for (b, body) in model.bodies.iter().enumerate() {
        for k in 0..3 {
            let c = a.constant(-body.mass * model.gravity[k]);
            potential.push(a.mul(c, bodies[b].r[k]));
        }
    }
    let mut power = Vec::new();
    let mut acc = Acc {
        a,
        force: vec![Vec::new(); n],
        n,
    };
    for f in &model.forces {
        match &f.kind {
            ForceKind::Spring {
                f1,
                f2,
                stiffness,
                damping,
                free_length,
                actuator,
            } => {
                let a = &mut *acc.a;
                let s1 = sym_frame(a, bodies, f1);
                let s2 = sym_frame(a, bodies, f2);
                let len = distance(a, &s1, &s2);
                let len_dot = acc.rate(&[len])[0];
                let a = &mut *acc.a;
                let l0 = a.constant(*free_length);
                let stretch = a.sub(len, l0);
                let k = a.constant(*stiffness);
                let c = a.constant(*damping);
                // Force along the separation (pushing apart): −k(ℓ − ℓ0) − c ℓ̇ + f(t).
                let elastic = a.mul(k, stretch);
                let viscous = a.mul(c, len_dot);
                let nc = a.sub(*actuator, viscous);
                let total = a.sub(nc, elastic);
                let half_k = a.constant(0.5 * stiffness);
                let s2 = a.powi(stretch, 2);
                potential.push(a.mul(half_k, s2));
                power.push(a.mul(nc, len_dot));
                acc.along(len, total);
            }
            ForceKind::Torsion {
                joint,
                stiffness,
                damping,
                free_angle,
                torque,
            } => {
                let j = &model.joints[*joint];
                let a = &mut *acc.a;
                let s1 = sym_frame(a, bodies, &j.f1);
                let s2 = sym_frame(a, bodies, &j.f2);
                let (c, s) = angle_cos_sin(a, &s1, &s2);
                // θ − θ0 from the reference turned by θ0, so atan2 only wraps at ±π away from
                // the free angle.
                let (s0, c0) = free_angle.sin_cos();
                let (s0, c0) = (a.constant(s0), a.constant(c0));
                let y = {
                    let p = a.mul(s, c0);
                    let q = a.mul(c, s0);
                    a.sub(p, q)
                };
                let x = {
                    let p = a.mul(c, c0);
                    let q = a.mul(s, s0);
                    a.add(p, q)
                };
                let delta = a.atan2(y, x);
                let delta_dot = acc.rate(&[delta])[0];
                let a = &mut *acc.a;
                let k = a.constant(*stiffness);
                let cd = a.constant(*damping);
                let elastic = a.mul(k, delta);
                let viscous = a.mul(cd, delta_dot);
                let nc = a.sub(*torque, viscous);
                let total = a.sub(nc, elastic);
                let half_k = a.constant(0.5 * stiffness);
                let d2 = a.powi(delta, 2);
                potential.push(a.mul(half_k, d2));
                power.push(a.mul(nc, delta_dot));
                acc.along(delta, total);
            }
            ForceKind::Force {
                at,
                value,
                body_axes,
            } => {
                let b = at.body.expect("applied forces act on bodies");
                let a = &mut *acc.a;
                let p = point_world(a, bodies, at.body, at.point);
                let f = if *body_axes {
                    mat_vec(a, &bodies[b].rot, *value)
                } else {
                    *value
                };
                let v = acc.rate(&p);
                power.push(acc.a.dot3(f, [v[0], v[1], v[2]]));
                acc.at_point(p, f);
            }
            ForceKind::Torque {
                body,
                value,
                body_axes,
            } => {
                let a = &mut *acc.a;
                let tau = if *body_axes {
                    mat_vec(a, &bodies[*body].rot, *value)
                } else {
                    *value
                };
                let omega = bodies[*body].omega_global(a);
                power.push(a.dot3(tau, omega));
                acc.torque(&bodies[*body], omega, tau);
            }
        }
    }
    let Acc { a, force, .. } = acc;
    let force = force.into_iter().map(|terms| a.sum(terms)).collect();
    Loads {
        force,
        potential: a.sum(potential),
        power_nc: a.sum(power),
    }
}
