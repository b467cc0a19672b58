//! From a validated model to symbolic equations on one DAG: Φ(q, t), structurally sparse
//! Φq, Φt, γ (a second directional derivative), and per formulation the mass matrix M(q),
//! the generalized forces Q(q, q̇, t) and the potential energy.

use crate::expr::{Arena, Id, Var};
use crate::model::{Formulation, JointKind, Model};

/// A sparse matrix entry: row, column, value.
pub type Entry = (u32, u32, Id);

/// Mass matrix and forces of one formulation.
#[derive(Debug, Clone)]
pub struct Dynamics {
    pub formulation: Formulation,
    /// Structural nonzeros, both triangles, row-major.
    pub mass: Vec<Entry>,
    pub force: Vec<Id>,
    pub mass_is_constant: bool,
}

/// The equations of a mechanism, all on one arena.
#[derive(Debug, Clone)]
pub struct System {
    pub arena: Arena,
    pub n_coords: usize,
    pub n_constraints: usize,
    pub phi: Vec<Id>,
    /// Structural nonzeros of Φq, row-major, columns ascending.
    pub phi_q: Vec<Entry>,
    pub phi_t: Vec<Id>,
    pub gamma: Vec<Id>,
    pub potential: Id,
    pub dynamics: Vec<Dynamics>,
    pub row_names: Vec<String>,
    pub coord_names: Vec<String>,
    /// First row of each joint, then of each driver (drivers have one row each).
    pub joint_rows: Vec<usize>,
}

type V3 = [Id; 3];
type M3 = [[Id; 3]; 3];

/// Symbolic pieces of one body's coordinates.
struct BodySym {
    r: V3,
    angles: V3,
    rot: M3,
}

fn body_sym(a: &mut Arena, b: usize) -> BodySym {
    let q = |a: &mut Arena, k: usize| a.var(Var::Q((6 * b + k) as u32));
    let r = [q(a, 0), q(a, 1), q(a, 2)];
    let angles = [q(a, 3), q(a, 4), q(a, 5)];
    let rot = rotation(a, angles);
    BodySym { r, angles, rot }
}

/// `Rz(γ)·Ry(β)·Rx(θ)` written out, as in paper eq. 1.
fn rotation(a: &mut Arena, [th, be, ga]: V3) -> M3 {
    let (st, ct) = (a.sin(th), a.cos(th));
    let (sb, cb) = (a.sin(be), a.cos(be));
    let (sg, cg) = (a.sin(ga), a.cos(ga));
    let mut m = |x: Id, y: Id| a.mul(x, y);
    let cgcb = m(cg, cb);
    let sgcb = m(sg, cb);
    let cgsb = m(cg, sb);
    let sgsb = m(sg, sb);
    let cbst = m(cb, st);
    let cbct = m(cb, ct);
    let t1 = m(cgsb, st);
    let t2 = m(sg, ct);
    let t3 = m(cgsb, ct);
    let t4 = m(sg, st);
    let t5 = m(sgsb, st);
    let t6 = m(cg, ct);
    let t7 = m(sgsb, ct);
    let t8 = m(cg, st);
    let a01 = a.sub(t1, t2);
    let a02 = a.add(t3, t4);
    let a11 = a.add(t5, t6);
    let a12 = a.sub(t7, t8);
    let a20 = a.neg(sb);
    [[cgcb, a01, a02], [sgcb, a11, a12], [a20, cbst, cbct]]
}

fn consts(a: &mut Arena, v: [f64; 3]) -> V3 {
    v.map(|x| a.constant(x))
}

fn mat_vec(a: &mut Arena, m: &M3, v: V3) -> V3 {
    [0, 1, 2].map(|i| a.dot3(m[i], v))
}

fn add3(a: &mut Arena, x: V3, y: V3) -> V3 {
    [0, 1, 2].map(|i| a.add(x[i], y[i]))
}

fn sub3(a: &mut Arena, x: V3, y: V3) -> V3 {
    [0, 1, 2].map(|i| a.sub(x[i], y[i]))
}

/// World position of a point fixed on a body (or a ground point).
fn point_world(a: &mut Arena, bodies: &[BodySym], body: Option<usize>, p: [f64; 3]) -> V3 {
    let pc = consts(a, p);
    match body {
        None => pc,
        Some(b) => {
            let w = mat_vec(a, &bodies[b].rot, pc);
            add3(a, bodies[b].r, w)
        }
    }
}

/// Builds every equation of `model`.
pub fn build(model: &Model) -> System {
    let mut a = model.arena.clone();
    let nb = model.bodies.len();
    let bodies: Vec<BodySym> = (0..nb).map(|b| body_sym(&mut a, b)).collect();
    let mut phi = Vec::new();
    let mut row_names = Vec::new();
    let mut joint_rows = Vec::new();
    for j in &model.joints {
        joint_rows.push(phi.len());
        match j.kind {
            JointKind::Spherical {
                body1,
                point1,
                body2,
                point2,
            } => {
                let p1 = point_world(&mut a, &bodies, body1, point1);
                let p2 = point_world(&mut a, &bodies, body2, point2);
                let d = sub3(&mut a, p1, p2);
                for (k, axis) in ["x", "y", "z"].iter().enumerate() {
                    phi.push(d[k]);
                    row_names.push(format!("{}.{axis}", j.name));
                }
            }
            JointKind::Prismatic {
                body1, body2, perp, ..
            } => {
                for (k, ang) in ["theta", "beta", "gamma"].iter().enumerate() {
                    let e = a.sub(bodies[body2].angles[k], bodies[body1].angles[k]);
                    phi.push(e);
                    row_names.push(format!("{}.{ang}", j.name));
                }
                let d = sub3(&mut a, bodies[body2].r, bodies[body1].r);
                for (k, p) in perp.iter().enumerate() {
                    let pc = consts(&mut a, *p);
                    let u = mat_vec(&mut a, &bodies[body1].rot, pc);
                    phi.push(a.dot3(u, d));
                    row_names.push(format!("{}.slide{}", j.name, k + 1));
                }
            }
        }
    }
    for d in &model.drivers {
        joint_rows.push(phi.len());
        let JointKind::Prismatic {
            body1, body2, axis, ..
        } = model.joints[d.joint].kind
        else {
            unreachable!("the model validated that drivers act on prismatic joints");
        };
        let ac = consts(&mut a, axis);
        let u = mat_vec(&mut a, &bodies[body1].rot, ac);
        let dr = sub3(&mut a, bodies[body2].r, bodies[body1].r);
        let dist = a.dot3(u, dr);
        phi.push(a.sub(dist, d.value));
        row_names.push(d.name.clone());
    }

    let n_coords = 6 * nb;
    let phi_q = jacobian(&mut a, &phi, n_coords);
    let one = a.constant(1.0);
    let phi_t = a.derivative(&phi, &|v| (v == Var::T).then_some(one));
    let gamma = {
        let qd: Vec<Id> = (0..n_coords).map(|i| a.var(Var::Qd(i as u32))).collect();
        let seed = |v: Var| match v {
            Var::Q(i) => Some(qd[i as usize]),
            Var::T => Some(one),
            Var::Qd(_) => None,
        };
        let phi_dot = a.derivative(&phi, &seed);
        let phi_ddot = a.derivative(&phi_dot, &seed);
        phi_ddot.into_iter().map(|x| a.neg(x)).collect()
    };
    let potential = {
        let terms: Vec<Id> = (0..nb)
            .flat_map(|b| (0..3).map(move |k| (b, k)))
            .map(|(b, k)| {
                let c = a.constant(-model.bodies[b].mass * model.gravity[k]);
                a.mul(c, bodies[b].r[k])
            })
            .collect();
        a.sum(terms)
    };
    let dynamics = model
        .formulations
        .iter()
        .map(|f| match f {
            Formulation::Paper => paper_dynamics(&mut a, model),
            Formulation::Exact => exact_dynamics(&mut a, model, &bodies),
        })
        .collect();
    let coord_names = model
        .bodies
        .iter()
        .flat_map(|b| {
            ["x", "y", "z", "theta", "beta", "gamma"]
                .iter()
                .map(move |c| format!("{}.{c}", b.name))
        })
        .collect();
    System {
        arena: a,
        n_coords,
        n_constraints: phi.len(),
        phi,
        phi_q,
        phi_t,
        gamma,
        potential,
        dynamics,
        row_names,
        coord_names,
        joint_rows,
    }
}

/// Structural nonzeros of ∂rows/∂q, row-major. Each coordinate is differentiated once over
/// all rows that mention it, so shared subexpressions are differentiated once.
pub fn jacobian(a: &mut Arena, rows: &[Id], n_coords: usize) -> Vec<Entry> {
    let mut users: Vec<Vec<usize>> = vec![Vec::new(); n_coords];
    for (r, &row) in rows.iter().enumerate() {
        for v in a.variables(row) {
            if let Var::Q(j) = v {
                users[j as usize].push(r);
            }
        }
    }
    let one = a.constant(1.0);
    let mut entries = Vec::new();
    for (j, rs) in users.iter().enumerate() {
        if rs.is_empty() {
            continue;
        }
        let roots: Vec<Id> = rs.iter().map(|&r| rows[r]).collect();
        let target = Var::Q(j as u32);
        let d = a.derivative(&roots, &|v| (v == target).then_some(one));
        for (&r, &id) in rs.iter().zip(&d) {
            if !a.is_zero(id) {
                entries.push((r as u32, j as u32, id));
            }
        }
    }
    entries.sort_by_key(|&(r, c, _)| (r, c));
    entries
}

fn paper_dynamics(a: &mut Arena, model: &Model) -> Dynamics {
    let mut mass = Vec::new();
    let mut force = Vec::new();
    for (b, body) in model.bodies.iter().enumerate() {
        let diag = [
            body.mass,
            body.mass,
            body.mass,
            body.inertia[0],
            body.inertia[1],
            body.inertia[2],
        ];
        for (k, m) in diag.iter().enumerate() {
            let i = (6 * b + k) as u32;
            mass.push((i, i, a.constant(*m)));
            let f = if k < 3 {
                body.mass * model.gravity[k]
            } else {
                0.0
            };
            force.push(a.constant(f));
        }
    }
    Dynamics {
        formulation: Formulation::Paper,
        mass,
        force,
        mass_is_constant: true,
    }
}

/// Body-frame angular velocity from Euler-angle rates:
/// ω_b = Aᵀ(γ̇ e_z + β̇ Rz e_y + θ̇ Rz Ry e_x) = θ̇ e_x + Rxᵀ(β̇ e_y + Ryᵀ γ̇ e_z),
/// using RzᵀRz = RyᵀRy = I exactly so the engine need not discover sin² + cos² = 1.
pub fn body_angular_velocity(a: &mut Arena, angles: V3, rates: V3) -> V3 {
    let [th, be, _] = angles;
    let [thd, bed, gad] = rates;
    let (st, ct) = (a.sin(th), a.cos(th));
    let (sb, cb) = (a.sin(be), a.cos(be));
    // Ryᵀ (0, 0, γ̇) = (−sβ γ̇, 0, cβ γ̇)
    let v0 = {
        let p = a.mul(sb, gad);
        a.neg(p)
    };
    let v2 = a.mul(cb, gad);
    // add β̇ e_y, then Rxᵀ (x, y, z) = (x, cθ y + sθ z, −sθ y + cθ z)
    let y = bed;
    let w1 = {
        let p = a.mul(ct, y);
        let q = a.mul(st, v2);
        a.add(p, q)
    };
    let w2 = {
        let p = a.mul(st, y);
        let q = a.mul(ct, v2);
        a.sub(q, p)
    };
    let w0 = a.add(v0, thd);
    [w0, w1, w2]
}

fn exact_dynamics(a: &mut Arena, model: &Model, bodies: &[BodySym]) -> Dynamics {
    let n = 6 * model.bodies.len();
    let half = a.constant(0.5);
    let one = a.constant(1.0);
    let mut mass = Vec::new();
    let mut force = vec![a.constant(0.0); n];
    for (b, body) in model.bodies.iter().enumerate() {
        let off = 6 * b;
        let qd: Vec<Id> = (0..6).map(|k| a.var(Var::Qd((off + k) as u32))).collect();
        let omega = body_angular_velocity(a, bodies[b].angles, [qd[3], qd[4], qd[5]]);
        let mut terms = Vec::new();
        for k in 0..3 {
            let v2 = a.powi(qd[k], 2);
            let c = a.constant(body.mass);
            terms.push(a.mul(c, v2));
            let w2 = a.powi(omega[k], 2);
            let c = a.constant(body.inertia[k]);
            terms.push(a.mul(c, w2));
        }
        let twice_t = a.sum(terms);
        let t_kin = a.mul(half, twice_t);
        // p_i = ∂T/∂q̇_i, M_ij = ∂p_i/∂q̇_j
        let p: Vec<Id> = (0..6)
            .map(|i| {
                let target = Var::Qd((off + i) as u32);
                a.derivative(&[t_kin], &|v| (v == target).then_some(one))[0]
            })
            .collect();
        for (i, &pi) in p.iter().enumerate() {
            for j in 0..6 {
                let target = Var::Qd((off + j) as u32);
                let m = a.derivative(&[pi], &|v| (v == target).then_some(one))[0];
                if !a.is_zero(m) {
                    mass.push(((off + i) as u32, (off + j) as u32, m));
                }
            }
        }
        // Q_i = gravity + ∂T/∂q_i − (∂p_i/∂q) q̇
        let seed_q = |v: Var| match v {
            Var::Q(k) if (k as usize) >= off && (k as usize) < off + 6 => {
                Some(qd[k as usize - off])
            }
            _ => None,
        };
        let pdot = a.derivative(&p, &seed_q);
        for i in 0..6 {
            let target = Var::Q((off + i) as u32);
            let dt_dq = a.derivative(&[t_kin], &|v| (v == target).then_some(one))[0];
            let g = if i < 3 {
                body.mass * model.gravity[i]
            } else {
                0.0
            };
            let gc = a.constant(g);
            let s = a.add(gc, dt_dq);
            force[off + i] = a.sub(s, pdot[i]);
        }
    }
    mass.sort_by_key(|&(r, c, _)| (r, c));
    let mass_is_constant = mass.iter().all(|&(_, _, id)| a.as_const(id).is_some());
    Dynamics {
        formulation: Formulation::Exact,
        mass,
        force,
        mass_is_constant,
    }
}
