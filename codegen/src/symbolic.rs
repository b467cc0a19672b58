//! The symbolic building blocks the equation stages share: sparse entries, 3-vectors and
//! 3×3 matrices of DAG nodes, one body's coordinates as symbols ([`BodySym`]), and sparse
//! Jacobians of rows. Joint primitives, loads and the equations all import from here, so the
//! generator's modules import in one direction (symbolic → primitives, loads → equations).

use crate::expr::{Arena, Id, Var};
use crate::model::Rotation;

/// A sparse matrix entry: row, column, value.
pub type Entry = (u32, u32, Id);

pub type V3s = [Id; 3];
pub type M3s = [[Id; 3]; 3];

/// Symbolic pieces of one body's coordinates.
pub struct BodySym {
    pub r: V3s,
    /// The rotation coordinates: `[θ, β, γ]` or `[e0, e1, e2, e3]`.
    pub rot_coords: Vec<Id>,
    pub rot: M3s,
    pub rotation: Rotation,
    pub offset: usize,
}

impl BodySym {
    /// The body's velocity variables: `[Ẋ, Ẏ, Ż]`, then the rotation rates.
    pub fn velocities(&self, a: &mut Arena) -> Vec<Id> {
        (0..3 + self.rotation.n_coords())
            .map(|k| a.var(Var::Qd((self.offset + k) as u32)))
            .collect()
    }

    /// Global angular velocity, linear in the rates.
    pub fn omega_global(&self, a: &mut Arena) -> V3s {
        let qd = self.velocities(a);
        match self.rotation {
            Rotation::Euler => {
                // ω = H(β, γ)(θ̇, β̇, γ̇), H columns [cγcβ, sγcβ, −sβ], [−sγ, cγ, 0], e_z.
                let (be, ga) = (self.rot_coords[1], self.rot_coords[2]);
                let (sb, cb) = (a.sin(be), a.cos(be));
                let (sg, cg) = (a.sin(ga), a.cos(ga));
                let (thd, bed, gad) = (qd[3], qd[4], qd[5]);
                let cgcb = a.mul(cg, cb);
                let sgcb = a.mul(sg, cb);
                let w0 = {
                    let p = a.mul(cgcb, thd);
                    let q = a.mul(sg, bed);
                    a.sub(p, q)
                };
                let w1 = {
                    let p = a.mul(sgcb, thd);
                    let q = a.mul(cg, bed);
                    a.add(p, q)
                };
                let w2 = {
                    let p = a.mul(sb, thd);
                    a.sub(gad, p)
                };
                [w0, w1, w2]
            }
            Rotation::Quaternion => {
                // ω = 2E(e)ė, E = [[−e1, e0, −e3, e2], [−e2, e3, e0, −e1], [−e3, −e2, e1, e0]].
                let e = &self.rot_coords;
                let ed = &qd[3..7];
                let rows = [
                    [(1, -1.0), (0, 1.0), (3, -1.0), (2, 1.0)],
                    [(2, -1.0), (3, 1.0), (0, 1.0), (1, -1.0)],
                    [(3, -1.0), (2, -1.0), (1, 1.0), (0, 1.0)],
                ];
                rows.map(|row| quaternion_row(a, e, ed, row))
            }
        }
    }

    /// Body-frame angular velocity, linear in the rates.
    pub fn omega_body(&self, a: &mut Arena) -> V3s {
        let qd = self.velocities(a);
        match self.rotation {
            Rotation::Euler => body_angular_velocity(
                a,
                [self.rot_coords[0], self.rot_coords[1], self.rot_coords[2]],
                [qd[3], qd[4], qd[5]],
            ),
            Rotation::Quaternion => {
                // ω' = 2G(e)ė, G = [[−e1, e0, e3, −e2], [−e2, −e3, e0, e1], [−e3, e2, −e1, e0]].
                let e = &self.rot_coords;
                let ed = &qd[3..7];
                let rows = [
                    [(1, -1.0), (0, 1.0), (3, 1.0), (2, -1.0)],
                    [(2, -1.0), (3, -1.0), (0, 1.0), (1, 1.0)],
                    [(3, -1.0), (2, 1.0), (1, -1.0), (0, 1.0)],
                ];
                rows.map(|row| quaternion_row(a, e, ed, row))
            }
        }
    }
}

/// `2 Σ_k sign_k e[idx_k] ė_k` for one row of E or G.
fn quaternion_row(a: &mut Arena, e: &[Id], ed: &[Id], row: [(usize, f64); 4]) -> Id {
    let terms: Vec<Id> = row
        .iter()
        .zip(ed)
        .map(|(&(i, s), &d)| {
            let p = a.mul(e[i], d);
            if s < 0.0 {
                a.neg(p)
            } else {
                p
            }
        })
        .collect();
    let sum = a.sum(terms);
    let two = a.constant(2.0);
    a.mul(two, sum)
}

/// Structural nonzeros of ∂rows/∂q, row-major. Each coordinate is differentiated once over
/// all rows that mention it, so shared subexpressions are differentiated once.
pub fn jacobian(a: &mut Arena, rows: &[Id], n_coords: usize) -> Vec<Entry> {
    jacobian_in(a, rows, n_coords, Var::Q)
}

/// As [`jacobian`], with respect to the variables `var(0..n)` (`Var::Q` or `Var::Qd`).
pub fn jacobian_in(a: &mut Arena, rows: &[Id], n: usize, var: fn(u32) -> Var) -> Vec<Entry> {
    let mut users: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (r, &row) in rows.iter().enumerate() {
        for v in a.variables(row) {
            let j = match v {
                Var::Q(j) | Var::Qd(j) if var(j) == v => j as usize,
                _ => continue,
            };
            users[j].push(r);
        }
    }
    let one = a.constant(1.0);
    let mut entries = Vec::new();
    for (j, rs) in users.iter().enumerate() {
        if rs.is_empty() {
            continue;
        }
        let roots: Vec<Id> = rs.iter().map(|&r| rows[r]).collect();
        let target = var(j as u32);
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

/// Body-frame angular velocity from Euler-angle rates:
/// ω_b = Aᵀ(γ̇ e_z + β̇ Rz e_y + θ̇ Rz Ry e_x) = θ̇ e_x + Rxᵀ(β̇ e_y + Ryᵀ γ̇ e_z),
/// using RzᵀRz = RyᵀRy = I exactly so the engine need not discover sin² + cos² = 1.
pub fn body_angular_velocity(a: &mut Arena, angles: V3s, rates: V3s) -> V3s {
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
