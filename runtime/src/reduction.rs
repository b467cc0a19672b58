//! The way back from a generated reduced mechanism (docs/design.md, decision 24) to its full
//! model: rows `a·qᵢ + b·qⱼ + g(t) = 0` were substituted away by the generator, so the full
//! coordinates follow from the reduced ones, and the eliminated rows' multipliers from the
//! eliminated coordinates' equations of motion of the full model.

use crate::error::{check_len, Error};
use crate::kinematics::mass_times;
use crate::mechanism::Mechanism;

/// One eliminated row: `q[coord] = weight · q[target] + c(t)`, where the row's derivative with
/// respect to `q[coord]` is `slope`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Substitution {
    /// The eliminated row of the full model; `None` for a coordinate pinned by a planar model
    /// (its plane holds it, no row of the spatial model does on its own).
    pub row: Option<u32>,
    pub coord: u32,
    pub target: Option<u32>,
    pub weight: f64,
    pub slope: f64,
}

/// What a generated reduced mechanism needs to be read in its full model's terms.
#[derive(Debug, Clone, Copy)]
pub struct Reduction {
    /// Coordinates and rows of the full model.
    pub n_full: usize,
    pub m_full: usize,
    /// Full index of each reduced coordinate, and of each reduced row.
    pub coords: &'static [u32],
    pub rows: &'static [u32],
    pub substitutions: &'static [Substitution],
    /// `c, ċ, c̈` of each substitution at time `t`, three per substitution.
    pub offsets: fn(f64, &mut [f64]),
    /// Whether the offsets read numbers of the model that parameters reach (a slider's line
    /// at y = e): they hold the file's values, so the reduction serves no other values.
    pub offsets_read_parameters: bool,
}

impl Reduction {
    /// Full coordinates (`order` 0), velocities (1) or accelerations (2) from the reduced
    /// ones at time `t`.
    pub fn expand(
        &self,
        reduced: &[f64],
        t: f64,
        order: usize,
        full: &mut [f64],
    ) -> Result<(), Error> {
        check_len("reduced coordinates", self.coords.len(), reduced.len())?;
        check_len("full coordinates", self.n_full, full.len())?;
        if order > 2 {
            return Err(Error::InvalidIndex {
                what: "derivative order",
                index: order,
                reason: "0 (positions), 1 (velocities) or 2 (accelerations)",
            });
        }
        for (k, &c) in self.coords.iter().enumerate() {
            full[c as usize] = reduced[k];
        }
        let mut offsets = vec![0.0; 3 * self.substitutions.len()];
        (self.offsets)(t, &mut offsets);
        for (k, s) in self.substitutions.iter().enumerate() {
            let follow = s.target.map_or(0.0, |j| s.weight * full[j as usize]);
            full[s.coord as usize] = offsets[3 * k + order] + follow;
        }
        Ok(())
    }

    /// The full model's multipliers at the full state `(q, q̇, q̈)` (expanded) from the
    /// reduced mechanism's `lambda`: kept rows copied, each eliminated row's from
    /// `(M q̈)ᵢ + Σₛ Φq[s,i] λₛ = Qᵢ` of the full model (no eliminated row touches another
    /// eliminated coordinate, so one pass suffices).
    #[allow(clippy::too_many_arguments)]
    pub fn multipliers<M: Mechanism + ?Sized>(
        &self,
        full: &M,
        t: f64,
        q: &[f64],
        qd: &[f64],
        qdd: &[f64],
        lambda: &[f64],
        out: &mut [f64],
    ) -> Result<(), Error> {
        let info = full.info();
        check_len("full model coordinates", self.n_full, info.n_coords)?;
        check_len("full model rows", self.m_full, info.n_constraints)?;
        check_len("reduced multipliers", self.rows.len(), lambda.len())?;
        check_len("full multipliers", self.m_full, out.len())?;
        for v in [q, qd, qdd] {
            check_len("full state", self.n_full, v.len())?;
        }
        out.fill(0.0);
        for (k, &r) in self.rows.iter().enumerate() {
            out[r as usize] = lambda[k];
        }
        let mut phi_q = vec![0.0; info.phi_q_nnz()];
        let mut mass = vec![0.0; info.mass_nnz()];
        let (mut m_qdd, mut force) = (vec![0.0; self.n_full], vec![0.0; self.n_full]);
        full.phi_q(q, t, &mut phi_q);
        full.mass(q, &mut mass);
        full.force(q, qd, t, &mut force);
        mass_times(info, &mass, qdd, &mut m_qdd);
        for s in self.substitutions {
            let Some(row) = s.row else { continue };
            let (i, row) = (s.coord, row as usize);
            let coupling: f64 = (0..phi_q.len())
                .filter(|&k| info.phi_q_cols[k] == i && info.phi_q_rows[k] as usize != row)
                .map(|k| phi_q[k] * out[info.phi_q_rows[k] as usize])
                .sum();
            out[row] = (force[i as usize] - m_qdd[i as usize] - coupling) / s.slope;
        }
        Ok(())
    }
}
