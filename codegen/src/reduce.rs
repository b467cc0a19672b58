//! Reduction pass between "equations" and "emission" (docs/design.md, decision 24): rows of
//! the form `a·qᵢ + b·qⱼ + g(t) = 0` and `a·qᵢ + g(t) = 0` (constant `a ≠ 0`, `b`) are
//! eliminated by substituting `qᵢ = −(b·qⱼ + g(t))/a` into every other equation, so the
//! reduced system has one coordinate and one row fewer for each. Their multipliers are
//! recovered afterwards from the eliminated coordinates' equations of motion
//! ([`Reduced::recover_multipliers`]). The paper's Stewart model loses its 18 Euler-angle
//! equalities θ_U − θ_L = 0: 78 coordinates and 72 rows become 60 and 54.
//!
//! [`planar`] runs the same pass without rows: it pins a planar mechanism's out-of-plane
//! coordinates and drops the rows that vanish in the plane (docs/design.md, decision 34).
//!
//! With `q = T q̃ + c(t)` (T holds the `−b/a` weights), the reduced dynamics are
//! `M̃ = Tᵀ M T` and `Q̃ = Tᵀ (Q − M c̈)` at the substituted state; Φ̃, Φ̃q, Φ̃t and γ̃ are derived
//! from the substituted rows like any others.

use crate::equations::{derivatives, Dynamics, System};
use crate::expr::{Arena, Id, Var};
use crate::symbolic::Entry;

/// One eliminated row: `coord = weight · target + offset(t)`.
#[derive(Debug, Clone)]
pub struct Substitution {
    /// The eliminated row of the full system; `None` for a coordinate a planar model pins
    /// ([`planar`]).
    pub row: Option<usize>,
    /// The eliminated coordinate (full index).
    pub coord: usize,
    /// The coordinate it follows (full index), if any.
    pub target: Option<usize>,
    /// `−b/a`.
    pub weight: f64,
    /// `−g(t)/a`, and its first and second time derivatives (expressions in `t` only).
    pub offset: [Id; 3],
    /// `a`, the row's derivative with respect to `coord`.
    pub slope: f64,
}

/// A system after substitution, and how to go back to the full one.
#[derive(Debug, Clone)]
pub struct Reduced {
    /// The reduced equations (same arena as the full system's, extended). Its `joint_rows`,
    /// `driver_signs` and `normalized_bodies` are left empty: they describe the full model.
    pub system: System,
    pub substitutions: Vec<Substitution>,
    /// Full index of each reduced coordinate.
    pub coords: Vec<usize>,
    /// Full index of each reduced row.
    pub rows: Vec<usize>,
    /// The reduced system's own dependent rows (reduced indices), found by [`planar`]'s
    /// check; `None`: the full model's redundant rows that were kept.
    pub redundant: Option<Vec<usize>>,
}

/// What one elimination takes: the row (if any), the coordinate, the coordinate it follows
/// with its weight `−b/a`, the slope `a`, and the pinned value of a row-less one.
struct Elimination {
    row: Option<usize>,
    coord: usize,
    target: Option<usize>,
    slope: f64,
    b: f64,
    pinned: f64,
}

/// The substitutable rows of `sys`, chosen so that no eliminated coordinate is another
/// substitution's target or appears in two eliminated rows (one pass, no chains).
fn choose(sys: &System) -> Vec<(usize, usize, Option<usize>, f64, f64)> {
    let a = &sys.arena;
    let mut by_row: Vec<Vec<(usize, f64)>> = vec![Vec::new(); sys.n_constraints];
    let mut linear = vec![true; sys.n_constraints];
    for &(r, c, id) in &sys.phi_q {
        match a.as_const(id) {
            Some(v) => by_row[r as usize].push((c as usize, v)),
            None => linear[r as usize] = false,
        }
    }
    let mut eliminated = vec![false; sys.n_coords];
    let mut targeted = vec![false; sys.n_coords];
    let mut chosen = Vec::new();
    for (r, entries) in by_row.iter().enumerate() {
        if !linear[r] || entries.is_empty() || entries.len() > 2 {
            continue;
        }
        // Eliminate the later coordinate: any choice is exact, this one is deterministic.
        let (i, a_i) = entries[entries.len() - 1];
        let other = (entries.len() == 2).then(|| entries[0]);
        let free = |c: usize| !eliminated[c] && !targeted[c];
        if !free(i) || a_i == 0.0 || other.is_some_and(|(j, _)| eliminated[j]) {
            continue;
        }
        eliminated[i] = true;
        if let Some((j, _)) = other {
            targeted[j] = true;
        }
        chosen.push((
            r,
            i,
            other.map(|(j, _)| j),
            a_i,
            other.map_or(0.0, |(_, b)| b),
        ));
    }
    chosen
}

/// Eliminates every substitutable row of `sys`; `None` when there is none.
pub fn substitute(sys: &System) -> Option<Reduced> {
    let chosen: Vec<Elimination> = choose(sys)
        .into_iter()
        .map(|(row, coord, target, slope, b)| Elimination {
            row: Some(row),
            coord,
            target,
            slope,
            b,
            pinned: 0.0,
        })
        .collect();
    if chosen.is_empty() {
        return None;
    }
    Some(eliminate(sys, &chosen, false).expect("rows are only dropped for planar models"))
}

/// The planar model of `sys` (docs/design.md, decision 34): every Euler body's z pinned at
/// its value in `q0`, θ and β at 0, so that each body keeps (x, y, γ), and the rows that the
/// pins make identically zero (a revolute's z row and its two axis rows) dropped. `Err` names a row the pins make a nonzero constant: the bodies cannot all stay
/// in their planes. Whether the planar model keeps the spatial one's mobility is
/// [`crate::assembly::planar_check`]'s to decide.
pub fn planar(sys: &System, bodies: &[crate::model::Body], q0: &[f64]) -> Result<Reduced, String> {
    let pins: Vec<Elimination> = bodies
        .iter()
        .flat_map(|b| {
            [2, 3, 4].map(|k| Elimination {
                row: None,
                coord: b.offset + k,
                target: None,
                slope: 1.0,
                b: 0.0,
                // θ and β are exactly 0 (the model checked); z is the body's own plane.
                pinned: if k == 2 { q0[b.offset + 2] } else { 0.0 },
            })
        })
        .collect();
    eliminate(sys, &pins, true)
}

/// `sys` with the `chosen` eliminations substituted; with `drop_zero_rows`, the rows that
/// become the constant 0 are left out too (`Err`: one became another constant).
fn eliminate(
    sys: &System,
    chosen: &[Elimination],
    drop_zero_rows: bool,
) -> Result<Reduced, String> {
    let mut a = sys.arena.clone();
    let n = sys.n_coords;
    let is_eliminated = |c: usize| chosen.iter().any(|s| s.coord == c);
    let coords: Vec<usize> = (0..n).filter(|&c| !is_eliminated(c)).collect();
    let mut new_index = vec![usize::MAX; n];
    for (k, &c) in coords.iter().enumerate() {
        new_index[c] = k;
    }
    let mut rows: Vec<usize> = (0..sys.n_constraints)
        .filter(|&r| !chosen.iter().any(|s| s.row == Some(r)))
        .collect();

    // g(t) = Φ_r at q = 0, and its time derivatives; the offset is −g/a.
    let zero = a.constant(0.0);
    let one = a.constant(1.0);
    let mut substitutions = Vec::new();
    for e in chosen {
        let &Elimination {
            row,
            coord,
            target,
            slope,
            b,
            pinned,
        } = e;
        let c0 = match row {
            Some(row) => {
                let g =
                    a.substitute(&[sys.phi[row]], &|v| matches!(v, Var::Q(_)).then_some(zero))[0];
                let scale = a.constant(-1.0 / slope);
                a.mul(scale, g)
            }
            None => a.constant(pinned),
        };
        let c1 = a.derivative(&[c0], &|v| (v == Var::T).then_some(one))[0];
        let c2 = a.derivative(&[c1], &|v| (v == Var::T).then_some(one))[0];
        substitutions.push(Substitution {
            row,
            coord,
            target,
            weight: -b / slope,
            offset: [c0, c1, c2],
            slope,
        });
    }

    // The map from full variables to reduced expressions.
    let mut q_of: Vec<Id> = vec![zero; n];
    let mut qd_of: Vec<Id> = vec![zero; n];
    for (k, &c) in coords.iter().enumerate() {
        q_of[c] = a.var(Var::Q(k as u32));
        qd_of[c] = a.var(Var::Qd(k as u32));
    }
    for s in &substitutions {
        let (mut q, mut qd) = (s.offset[0], s.offset[1]);
        if let Some(j) = s.target {
            let w = a.constant(s.weight);
            let wq = a.mul(w, q_of[j]);
            let wqd = a.mul(w, qd_of[j]);
            q = a.add(wq, q);
            qd = a.add(wqd, qd);
        }
        q_of[s.coord] = q;
        qd_of[s.coord] = qd;
    }
    let map = |v: Var| match v {
        Var::Q(i) => Some(q_of[i as usize]),
        Var::Qd(i) => Some(qd_of[i as usize]),
        Var::T | Var::P(_) | Var::K(_) | Var::Dq(_) | Var::Dqd(_) | Var::Dp(_) => None,
    };

    let kept: Vec<Id> = rows.iter().map(|&r| sys.phi[r]).collect();
    let mut phi = a.substitute(&kept, &map);
    if drop_zero_rows {
        // A row held at the initial pose that the pins make constant is that pose's residual
        // (roundoff of the assembly, whose tolerance is 1e-9); anything larger cannot hold.
        for (&r, &p) in rows.iter().zip(&phi) {
            match a.as_const(p) {
                Some(v) if !(v.abs() <= 1e-9) => {
                    return Err(format!(
                        "row `{}` becomes the constant {v:e} in the plane",
                        sys.row_names[r]
                    ))
                }
                _ => {}
            }
        }
        (rows, phi) = rows
            .iter()
            .zip(&phi)
            .filter(|(_, &p)| a.as_const(p).is_none())
            .map(|(&r, &p)| (r, p))
            .unzip();
    }
    let m = coords.len();
    let (phi_q, phi_t, gamma) = derivatives(&mut a, &phi, m);
    let potential = a.substitute(&[sys.potential], &map)[0];
    let power_nc = a.substitute(&[sys.power_nc], &map)[0];

    // T: each full coordinate's reduced column and weight.
    let weight_of = |c: usize| -> Option<(usize, f64)> {
        if new_index[c] != usize::MAX {
            return Some((new_index[c], 1.0));
        }
        let s = substitutions.iter().find(|s| s.coord == c)?;
        Some((new_index[s.target?], s.weight))
    };
    let dynamics = sys
        .dynamics
        .iter()
        .map(|d| reduce_dynamics(&mut a, d, &map, &weight_of, &substitutions, m))
        .collect();
    Ok(Reduced {
        system: System {
            arena: a,
            n_coords: m,
            n_constraints: rows.len(),
            phi,
            phi_q,
            phi_t,
            gamma,
            potential,
            power_nc,
            dynamics,
            tangent: Default::default(),
            mass_props: sys.mass_props.clone(),
            force_constants: sys.force_constants.clone(),
            row_names: rows.iter().map(|&r| sys.row_names[r].clone()).collect(),
            coord_names: coords.iter().map(|&c| sys.coord_names[c].clone()).collect(),
            joint_rows: Vec::new(),
            driver_signs: Vec::new(),
            normalized_bodies: Vec::new(),
        },
        substitutions,
        coords,
        rows,
        redundant: None,
    })
}

/// `M̃ = Tᵀ M T`, `Q̃ = Tᵀ (Q − M c̈)`, both at the substituted state.
fn reduce_dynamics(
    a: &mut Arena,
    d: &Dynamics,
    map: &dyn Fn(Var) -> Option<Id>,
    weight_of: &dyn Fn(usize) -> Option<(usize, f64)>,
    substitutions: &[Substitution],
    m: usize,
) -> Dynamics {
    let mass_vals: Vec<Id> = d.mass.iter().map(|e| e.2).collect();
    let mass_vals = a.substitute(&mass_vals, map);
    let force = a.substitute(&d.force, map);
    // Q − M c̈: only eliminated coordinates with a moving offset contribute.
    let mut force_terms: Vec<Vec<Id>> = force.iter().map(|&f| vec![f]).collect();
    for (&(r, c, _), &v) in d.mass.iter().zip(&mass_vals) {
        if let Some(s) = substitutions.iter().find(|s| s.coord == c as usize) {
            if !a.is_zero(s.offset[2]) {
                let t = a.mul(v, s.offset[2]);
                force_terms[r as usize].push(a.neg(t));
            }
        }
    }
    let mut reduced_force: Vec<Vec<Id>> = vec![Vec::new(); m];
    for (i, terms) in force_terms.into_iter().enumerate() {
        if let Some((k, w)) = weight_of(i) {
            let f = a.sum(terms);
            let wc = a.constant(w);
            reduced_force[k].push(a.mul(wc, f));
        }
    }
    let mut cells: std::collections::BTreeMap<(u32, u32), Vec<Id>> = Default::default();
    for (&(r, c, _), &v) in d.mass.iter().zip(&mass_vals) {
        let (Some((kr, wr)), Some((kc, wc))) = (weight_of(r as usize), weight_of(c as usize))
        else {
            continue;
        };
        let w = a.constant(wr * wc);
        let t = a.mul(w, v);
        cells.entry((kr as u32, kc as u32)).or_default().push(t);
    }
    let mass: Vec<Entry> = cells
        .into_iter()
        .map(|((r, c), terms)| (r, c, a.sum(terms)))
        .collect();
    let force = reduced_force.into_iter().map(|t| a.sum(t)).collect();
    // No force Jacobian: the reduced models serve comparisons, not stiff integration.
    Dynamics::new(a, d.formulation, mass, force, None, d.mass_is_constant)
}

impl Reduced {
    /// The full coordinates (or velocities, or accelerations: `order` 0, 1, 2) from the
    /// reduced ones at time `t`.
    pub fn expand(&self, reduced: &[f64], t: f64, order: usize, n_full: usize) -> Vec<f64> {
        let mut full = vec![0.0; n_full];
        for (k, &c) in self.coords.iter().enumerate() {
            full[c] = reduced[k];
        }
        for s in &self.substitutions {
            let offset = self.system.arena.eval(s.offset[order], &|v| match v {
                Var::T => t,
                _ => 0.0,
            });
            full[s.coord] = offset + s.target.map_or(0.0, |j| s.weight * full[j]);
        }
        full
    }

    /// The full multiplier vector from the reduced one: kept rows copied, each eliminated
    /// row's multiplier from its coordinate's equation of motion
    /// `(M q̈)_i + Σ_s Φq[s,i] λ_s = Q_i` of the full model at the expanded state
    /// (`mass_times_qdd` = (M q̈)_i, `force` = Q_i, `phi_q` the full nonzeros).
    pub fn recover_multipliers(
        &self,
        lambda: &[f64],
        full: &System,
        phi_q: &[f64],
        mass_times_qdd: &[f64],
        force: &[f64],
    ) -> Vec<f64> {
        let mut out = vec![0.0; full.n_constraints];
        for (k, &r) in self.rows.iter().enumerate() {
            out[r] = lambda[k];
        }
        for s in &self.substitutions {
            let Some(row) = s.row else { continue };
            let i = s.coord as u32;
            let coupling: f64 = full
                .phi_q
                .iter()
                .zip(phi_q)
                .filter(|((r, c, _), _)| *c == i && *r as usize != row)
                .map(|((r, _, _), v)| v * out[*r as usize])
                .sum();
            out[row] = (force[s.coord] - mass_times_qdd[s.coord] - coupling) / s.slope;
        }
        out
    }
}
