//! From a validated model to symbolic equations on one DAG: Φ(q, t), structurally sparse
//! Φq, Φt, γ (a second directional derivative), and per formulation the mass matrix M(q),
//! the generalized forces Q(q, q̇, t), the potential energy and the power of the
//! non-conservative loads. Joint rows come from [`crate::primitives`], applied loads from
//! [`crate::loads`].

use crate::expr::{Arena, Id, Node, Var};
use crate::model::{ForceKind, Formulation, Model, Rotation};
use crate::primitives::{driver_row, joint_rows};
use crate::symbolic::{jacobian, jacobian_in, BodySym, Entry, M3s, V3s};

/// Mass matrix and forces of one formulation.
#[derive(Debug, Clone)]
pub struct Dynamics {
    pub formulation: Formulation,
    /// Structural nonzeros, both triangles, row-major.
    pub mass: Vec<Entry>,
    pub force: Vec<Id>,
    /// Structural nonzeros of ∂Q/∂q and ∂Q/∂q̇ of the applied loads (springs, dampers,
    /// actuators, applied forces), row-major: the stiffness and damping an implicit
    /// integrator's Newton matrix takes. Gravity is constant and the inertial velocity terms
    /// are not stiff, so they are left out (and the code stays small for mechanisms without
    /// such loads).
    pub force_q: Vec<Entry>,
    pub force_qd: Vec<Entry>,
    pub mass_is_constant: bool,
    /// Directional derivatives of `mass` and `force` ([`crate::tangent::add`]).
    pub tangent: crate::tangent::Dynamic,
}

impl Dynamics {
    /// M and Q of one formulation, with the applied `loads` (part of Q) differentiated once
    /// per coordinate and per velocity over the loads that mention it; `None`: no Jacobian.
    pub fn new(
        a: &mut Arena,
        formulation: Formulation,
        mass: Vec<Entry>,
        force: Vec<Id>,
        loads: Option<&[Id]>,
        mass_is_constant: bool,
    ) -> Self {
        let n = force.len();
        let (force_q, force_qd) = match loads {
            Some(l) => (jacobian_in(a, l, n, Var::Q), jacobian_in(a, l, n, Var::Qd)),
            None => (Vec::new(), Vec::new()),
        };
        Dynamics {
            formulation,
            mass,
            force,
            force_q,
            force_qd,
            mass_is_constant,
            tangent: Default::default(),
        }
    }
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
    /// Power of the non-conservative loads (dampers, actuators, applied loads in `t`).
    pub power_nc: Id,
    pub dynamics: Vec<Dynamics>,
    /// Directional derivatives of Φ, Φq, Φt, γ ([`crate::tangent::add`]; `None` before, and
    /// then no formulation has any either).
    pub tangent: Option<crate::tangent::Kinematic>,
    /// Each body's mass and principal inertias, as they enter the equations (written in the
    /// run-time parameters by [`build_parametric`]).
    pub mass_props: Vec<[Id; 4]>,
    /// Each force's stiffness and damping (0 for applied forces and torques), likewise.
    pub force_constants: Vec<[Id; 2]>,
    pub row_names: Vec<String>,
    pub coord_names: Vec<String>,
    /// First row of each joint, then of each driver (one row each), then of each
    /// quaternion body's normalization row.
    pub joint_rows: Vec<usize>,
    /// `∂Φ/∂s` of each driver's row at Φ = 0 (see `JointInfo::effort_sign`).
    pub driver_signs: Vec<f64>,
    /// Bodies owning a normalization row, in row order.
    pub normalized_bodies: Vec<usize>,
}

impl System {
    /// Lengths of `p` and `k`: one past the largest `Var::P` and `Var::K` index in the arena.
    pub fn value_lengths(&self) -> (usize, usize) {
        let (mut np, mut nk) = (0, 0);
        for i in 0..self.arena.len() {
            match self.arena.node(Id(i as u32)) {
                Node::Var(Var::P(j)) => np = np.max(j as usize + 1),
                Node::Var(Var::K(j)) => nk = nk.max(j as usize + 1),
                _ => {}
            }
        }
        (np, nk)
    }
}

fn body_sym(a: &mut Arena, offset: usize, rotation: Rotation) -> BodySym {
    let q = |a: &mut Arena, k: usize| a.var(Var::Q((offset + k) as u32));
    let r = [q(a, 0), q(a, 1), q(a, 2)];
    let rot_coords: Vec<Id> = (0..rotation.n_coords()).map(|k| q(a, 3 + k)).collect();
    let rot = match rotation {
        Rotation::Euler => euler_rotation(a, [rot_coords[0], rot_coords[1], rot_coords[2]]),
        Rotation::Quaternion => quaternion_rotation(
            a,
            [rot_coords[0], rot_coords[1], rot_coords[2], rot_coords[3]],
        ),
    };
    BodySym {
        r,
        rot_coords,
        rot,
        rotation,
        offset,
    }
}

/// `Rz(γ)·Ry(β)·Rx(θ)` written out, as in paper eq. 1.
fn euler_rotation(a: &mut Arena, [th, be, ga]: V3s) -> M3s {
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

/// `A(e) = (2e0² − 1)I + 2(ēēᵀ + e0[ē×])`: a rotation on the unit sphere, which the body's
/// normalization row enforces.
fn quaternion_rotation(a: &mut Arena, [e0, e1, e2, e3]: [Id; 4]) -> M3s {
    let two = a.constant(2.0);
    let one = a.constant(1.0);
    let twice = |a: &mut Arena, x: Id, y: Id, sign: f64| {
        let p = a.mul(x, y);
        let p = if sign < 0.0 { a.neg(p) } else { p };
        a.mul(two, p)
    };
    let sq = [e0, e1, e2, e3].map(|e| a.powi(e, 2));
    let diag = |a: &mut Arena, k: usize| {
        let s = a.add(sq[0], sq[k]);
        let t = a.mul(two, s);
        a.sub(t, one)
    };
    let d0 = diag(a, 1);
    let d1 = diag(a, 2);
    let d2 = diag(a, 3);
    let off = |a: &mut Arena, x: (Id, Id), y: (Id, Id), sign: f64| {
        let p = twice(a, x.0, x.1, 1.0);
        let q = twice(a, y.0, y.1, sign);
        a.add(p, q)
    };
    let a01 = off(a, (e1, e2), (e0, e3), -1.0);
    let a02 = off(a, (e1, e3), (e0, e2), 1.0);
    let a10 = off(a, (e1, e2), (e0, e3), 1.0);
    let a12 = off(a, (e2, e3), (e0, e1), -1.0);
    let a20 = off(a, (e1, e3), (e0, e2), -1.0);
    let a21 = off(a, (e2, e3), (e0, e1), 1.0);
    [[d0, a01, a02], [a10, d1, a12], [a20, a21, d2]]
}

/// Builds every equation of `model`, every number a constant.
pub fn build(model: &Model) -> System {
    build_with(model, false)
}

/// [`build`] with the run-time values as `Var::P`, for the generated code: masses, inertias
/// and springs' constants written in the run-time parameters
/// ([`Model::run_time_parameters`]), and the numbers [`crate::slots::mark`] marked.
pub fn build_parametric(model: &Model) -> System {
    build_with(model, true)
}

/// The numbers the run-time parameters can reach, as they enter the equations: the bodies'
/// masses and principal inertias, each force's stiffness and damping (0 where it has none).
struct MassProps {
    mass: Vec<Id>,
    inertia: Vec<[Id; 3]>,
    force_constants: Vec<[Id; 2]>,
}

impl MassProps {
    fn new(a: &mut Arena, model: &Model, parametric: bool) -> Self {
        if parametric {
            // Every run-time value is a variable of the arena, read or not, so that the
            // generated code's `p` has one entry per name and per slot.
            for i in 0..model.run_time_values().len() {
                a.var(Var::P(i as u32));
            }
        }
        let value = |a: &mut Arena, src: &Option<String>, v: f64| match src {
            Some(e) if parametric => parameter_expr(a, model, e).unwrap_or_else(|| a.constant(v)),
            _ => a.constant(v),
        };
        let mut mass = Vec::new();
        let mut inertia = Vec::new();
        for b in &model.bodies {
            mass.push(value(a, &b.mass_expr, b.mass));
            inertia.push([0, 1, 2].map(|k| value(a, &b.inertia_expr[k], b.inertia[k])));
        }
        let force_constants = model
            .forces
            .iter()
            .map(|f| {
                let (k, c) = match f.kind {
                    ForceKind::Spring {
                        stiffness, damping, ..
                    }
                    | ForceKind::Torsion {
                        stiffness, damping, ..
                    } => (stiffness, damping),
                    _ => (0.0, 0.0),
                };
                [
                    value(a, &f.constants_expr[0], k),
                    value(a, &f.constants_expr[1], c),
                ]
            })
            .collect();
        MassProps {
            mass,
            inertia,
            force_constants,
        }
    }
}

/// The file's expression `src` with run-time parameters as `Var::P`, derived parameters
/// expanded (unless set from outside the file: then their value stands), and the other
/// parameters' values as constants (`None`: it does not parse, which the validator would
/// have reported).
fn parameter_expr(a: &mut Arena, model: &Model, src: &str) -> Option<Id> {
    let run_time = model.run_time_parameters();
    let mut resolve = |a: &mut Arena, name: &str| -> Option<Id> {
        let p = model.parameters.iter().find(|p| p.name == name)?;
        Some(
            match (run_time.iter().position(|q| q.name == name), &p.expression) {
                (Some(i), _) => a.var(Var::P(i as u32)),
                (None, Some(e)) if !p.overridden => parameter_expr(a, model, e)?,
                (None, _) => a.constant(p.value),
            },
        )
    };
    crate::parse::parse_expr(a, src, &mut resolve).ok()
}

fn build_with(model: &Model, parametric: bool) -> System {
    let mut a = model.arena.clone();
    let bodies: Vec<BodySym> = model
        .bodies
        .iter()
        .map(|b| body_sym(&mut a, b.offset, b.rotation))
        .collect();
    let mut phi = Vec::new();
    let mut row_names = Vec::new();
    let mut joint_rows_start = Vec::new();
    for j in &model.joints {
        joint_rows_start.push(phi.len());
        for (name, row) in joint_rows(&mut a, &bodies, j) {
            phi.push(row);
            row_names.push(name);
        }
    }
    let mut driver_signs = Vec::new();
    for d in &model.drivers {
        joint_rows_start.push(phi.len());
        let (row, sign) = driver_row(&mut a, &bodies, model, &d.target, d.value);
        phi.push(row);
        driver_signs.push(sign);
        row_names.push(d.name.clone());
    }
    let mut normalized_bodies = Vec::new();
    for (b, body) in model.bodies.iter().enumerate() {
        if body.rotation == Rotation::Quaternion {
            joint_rows_start.push(phi.len());
            let e = bodies[b].rot_coords.clone();
            let sq: Vec<Id> = e.iter().map(|&x| a.powi(x, 2)).collect();
            let s = a.sum(sq);
            let one = a.constant(1.0);
            phi.push(a.sub(s, one));
            row_names.push(format!("{}.norm", body.name));
            normalized_bodies.push(b);
        }
    }

    let n_coords = model.n_coords();
    let (phi_q, phi_t, gamma) = derivatives(&mut a, &phi, n_coords);
    let props = MassProps::new(&mut a, model, parametric);
    let loads = crate::loads::build(&mut a, model, &bodies, &props.mass, &props.force_constants);
    let dynamics = model
        .formulations
        .iter()
        .map(|f| match f {
            Formulation::Paper => paper_dynamics(&mut a, model, &props, &loads.force),
            Formulation::Exact => exact_dynamics(&mut a, model, &props, &bodies, &loads.force),
        })
        .collect();
    let coord_names = model
        .bodies
        .iter()
        .flat_map(|b| {
            ["x", "y", "z"]
                .iter()
                .chain(b.rotation.coord_names())
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
        potential: loads.potential,
        power_nc: loads.power_nc,
        dynamics,
        tangent: Default::default(),
        mass_props: props
            .mass
            .iter()
            .zip(&props.inertia)
            .map(|(&m, &[a, b, c])| [m, a, b, c])
            .collect(),
        force_constants: props.force_constants,
        row_names,
        coord_names,
        joint_rows: joint_rows_start,
        driver_signs,
        normalized_bodies,
    }
}

/// Φq, Φt and γ = −D²Φ[(q̇,1),(q̇,1)] of the rows `phi` in `n_coords` coordinates (decision 3).
pub fn derivatives(a: &mut Arena, phi: &[Id], n_coords: usize) -> (Vec<Entry>, Vec<Id>, Vec<Id>) {
    let phi_q = jacobian(a, phi, n_coords);
    let one = a.constant(1.0);
    let phi_t = a.derivative(phi, &|v| (v == Var::T).then_some(one));
    let qd: Vec<Id> = (0..n_coords).map(|i| a.var(Var::Qd(i as u32))).collect();
    let seed = |v: Var| match v {
        Var::Q(i) => Some(qd[i as usize]),
        Var::T => Some(one),
        Var::Qd(_) | Var::P(_) | Var::K(_) | Var::Dq(_) | Var::Dqd(_) | Var::Dp(_) => None,
    };
    let phi_dot = a.derivative(phi, &seed);
    let phi_ddot = a.derivative(&phi_dot, &seed);
    let gamma = phi_ddot.into_iter().map(|x| a.neg(x)).collect();
    (phi_q, phi_t, gamma)
}

fn paper_dynamics(a: &mut Arena, model: &Model, props: &MassProps, loads: &[Id]) -> Dynamics {
    let mut mass = Vec::new();
    let mut force = Vec::new();
    for (b, body) in model.bodies.iter().enumerate() {
        let m = props.mass[b];
        let [ix, iy, iz] = props.inertia[b];
        for (k, &mk) in [m, m, m, ix, iy, iz].iter().enumerate() {
            let i = body.offset + k;
            mass.push((i as u32, i as u32, mk));
            let g = if k < 3 {
                let g = a.constant(model.gravity[k]);
                a.mul(m, g)
            } else {
                a.constant(0.0)
            };
            force.push(a.add(g, loads[i]));
        }
    }
    Dynamics::new(a, Formulation::Paper, mass, force, Some(loads), true)
}

fn exact_dynamics(
    a: &mut Arena,
    model: &Model,
    props: &MassProps,
    bodies: &[BodySym],
    loads: &[Id],
) -> Dynamics {
    let n = model.n_coords();
    let half = a.constant(0.5);
    let one = a.constant(1.0);
    let mut mass = Vec::new();
    let mut force = vec![a.constant(0.0); n];
    for (b, body) in model.bodies.iter().enumerate() {
        let off = body.offset;
        let nb = body.n_coords();
        let qd = bodies[b].velocities(a);
        let omega = bodies[b].omega_body(a);
        let mut terms = Vec::new();
        for k in 0..3 {
            let v2 = a.powi(qd[k], 2);
            terms.push(a.mul(props.mass[b], v2));
            let w2 = a.powi(omega[k], 2);
            terms.push(a.mul(props.inertia[b][k], w2));
        }
        let twice_t = a.sum(terms);
        let t_kin = a.mul(half, twice_t);
        // p_i = ∂T/∂q̇_i, M_ij = ∂p_i/∂q̇_j
        let p: Vec<Id> = (0..nb)
            .map(|i| {
                let target = Var::Qd((off + i) as u32);
                a.derivative(&[t_kin], &|v| (v == target).then_some(one))[0]
            })
            .collect();
        // A quaternion body's 4GᵀJG has no kinetic energy along ė ∥ e (rank 3). Adding
        // k·e eᵀ to M and −k·e(ėᵀė) to Q changes nothing on the motion, because the
        // normalization row gives eᵀë = −ėᵀė, and makes the block positive definite
        // (docs/design.md, decision 15). k = 4·mean(J) matches the other eigenvalues 4·J_i.
        let reg = (body.rotation == Rotation::Quaternion).then(|| {
            let sum = a.sum(props.inertia[b]);
            let four = a.constant(4.0);
            let three = a.constant(3.0);
            let k = a.mul(four, sum);
            (a.div(k, three), bodies[b].rot_coords.clone())
        });
        for (i, &pi) in p.iter().enumerate() {
            for j in 0..nb {
                let target = Var::Qd((off + j) as u32);
                let mut m = a.derivative(&[pi], &|v| (v == target).then_some(one))[0];
                if let (Some((k, e)), true) = (&reg, i >= 3 && j >= 3) {
                    let ee = a.mul(e[i - 3], e[j - 3]);
                    let kee = a.mul(*k, ee);
                    m = a.add(m, kee);
                }
                if !a.is_zero(m) {
                    mass.push(((off + i) as u32, (off + j) as u32, m));
                }
            }
        }
        // Q_i = gravity + loads + ∂T/∂q_i − (∂p_i/∂q) q̇
        let seed_q = |v: Var| match v {
            Var::Q(k) if (k as usize) >= off && (k as usize) < off + nb => {
                Some(qd[k as usize - off])
            }
            _ => None,
        };
        let pdot = a.derivative(&p, &seed_q);
        let edot_sq = reg.as_ref().map(|_| {
            let sq: Vec<Id> = qd[3..].iter().map(|&x| a.powi(x, 2)).collect();
            a.sum(sq)
        });
        for i in 0..nb {
            let target = Var::Q((off + i) as u32);
            let dt_dq = a.derivative(&[t_kin], &|v| (v == target).then_some(one))[0];
            let gc = if i < 3 {
                let g = a.constant(model.gravity[i]);
                a.mul(props.mass[b], g)
            } else {
                a.constant(0.0)
            };
            let s = a.add(gc, dt_dq);
            let mut f = a.sub(s, pdot[i]);
            if let (Some((k, e)), Some(ed2), true) = (&reg, edot_sq, i >= 3) {
                let ke = a.mul(*k, e[i - 3]);
                let t = a.mul(ke, ed2);
                f = a.sub(f, t);
            }
            force[off + i] = f;
        }
        for i in 0..nb {
            force[off + i] = a.add(force[off + i], loads[off + i]);
        }
    }
    mass.sort_by_key(|&(r, c, _)| (r, c));
    // Constant within a run: run-time parameters do not change during one.
    let mass_is_constant = mass.iter().all(|&(_, _, id)| {
        a.variables(id)
            .iter()
            .all(|v| matches!(v, Var::P(_) | Var::K(_)))
    });
    Dynamics::new(
        a,
        Formulation::Exact,
        mass,
        force,
        Some(loads),
        mass_is_constant,
    )
}
