//! Applied loads as generalized forces (docs/design.md, decision 20): gravity, spring–damper–
//! actuators, torsion springs, applied forces and torques. Each load is reduced to a
//! scalar `s(q)` with a force along it (Q += f ∂s/∂q), a force at a point (Q += J_pᵀF) or a
//! torque (Q += (∂ω/∂q̇)ᵀτ); conservative parts add to the potential, the others to the
//! non-conservative power.

use crate::expr::{Arena, Id, Var};
use crate::model::{ForceKind, Model};
use crate::primitives::{angle_cos_sin, distance, mat_vec, point_world, sym_frame};
use crate::symbolic::{jacobian, BodySym, V3s};

/// The generalized load vector, potential energy and non-conservative power.
pub struct Loads {
    pub force: Vec<Id>,
    pub potential: Id,
    pub power_nc: Id,
}

struct Acc<'a> {
    a: &'a mut Arena,
    /// Terms of each generalized force, of the potential, and of the non-conservative power.
    force: Vec<Vec<Id>>,
    potential: Vec<Id>,
    power: Vec<Id>,
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

    /// A spring–damper–actuator along the scalar `coord`: generalized force
    /// `−k·stretch − c·rate + f(t)` along it, potential `½k·stretch²`, non-conservative
    /// power `(f(t) − c·rate)·rate`.
    fn spring_damper(&mut self, coord: Id, stretch: Id, rate: Id, [kc, cc, f]: [Id; 3]) {
        let a = &mut *self.a;
        let elastic = a.mul(kc, stretch);
        let viscous = a.mul(cc, rate);
        let nc = a.sub(f, viscous);
        let total = a.sub(nc, elastic);
        let half = a.constant(0.5);
        let half_k = a.mul(half, kc);
        let s2 = a.powi(stretch, 2);
        self.potential.push(a.mul(half_k, s2));
        self.power.push(a.mul(nc, rate));
        self.along(coord, total);
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

/// The loads of `model`; `masses` are the bodies' masses and `constants` each force's
/// stiffness and damping (springs and torsion springs; unused for the others), as they enter
/// the equations.
pub fn build(
    a: &mut Arena,
    model: &Model,
    bodies: &[BodySym],
    masses: &[Id],
    constants: &[[Id; 2]],
) -> Loads {
    let n = model.n_coords();
    let mut acc = Acc {
        a,
        force: vec![Vec::new(); n],
        potential: Vec::new(),
        power: Vec::new(),
        n,
    };
    for (b, &mass) in masses.iter().enumerate() {
        for k in 0..3 {
            let g = acc.a.constant(model.gravity[k]);
            let mg = acc.a.mul(mass, g);
            let c = acc.a.neg(mg);
            let v = acc.a.mul(c, bodies[b].r[k]);
            acc.potential.push(v);
        }
    }
    for (f, &[stiffness, damping]) in model.forces.iter().zip(constants) {
        match &f.kind {
            ForceKind::Spring {
                f1,
                f2,
                free_length,
                actuator,
                ..
            } => {
                let a = &mut *acc.a;
                let s1 = sym_frame(a, bodies, f1);
                let s2 = sym_frame(a, bodies, f2);
                let len = distance(a, &s1, &s2);
                let len_dot = acc.rate(&[len])[0];
                let l0 = acc.a.constant(*free_length);
                let stretch = acc.a.sub(len, l0);
                acc.spring_damper(len, stretch, len_dot, [stiffness, damping, *actuator]);
            }
            ForceKind::Torsion {
                joint,
                free_angle,
                torque,
                ..
            } => {
                let j = &model.joints[*joint];
                let a = &mut *acc.a;
                let s1 = sym_frame(a, bodies, &j.f1);
                let s2 = sym_frame(a, bodies, &j.f2);
                let (c, s) = angle_cos_sin(a, &s1, &s2);
                // θ − θ0 from the reference turned by θ0, so atan2 only wraps at ±π away from
                // the free angle.
                let angle0 = a.constant(*free_angle);
                let (s0, c0) = (a.sin(angle0), a.cos(angle0));
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
                acc.spring_damper(delta, delta, delta_dot, [stiffness, damping, *torque]);
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
                let power = acc.a.dot3(f, [v[0], v[1], v[2]]);
                acc.power.push(power);
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
                let p = a.dot3(tau, omega);
                acc.power.push(p);
                acc.torque(&bodies[*body], omega, tau);
            }
        }
    }
    let Acc {
        a,
        force,
        potential,
        power,
        ..
    } = acc;
    let force = force.into_iter().map(|terms| a.sum(terms)).collect();
    Loads {
        force,
        potential: a.sum(potential),
        power_nc: a.sum(power),
    }
}
