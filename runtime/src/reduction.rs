//! The way back from a generated reduced mechanism (docs/design.md, decision 24) to its full
//! model: rows `a·qᵢ + b·qⱼ + g(t) = 0` were substituted away by the generator, so the full
//! coordinates follow from the reduced ones, and the eliminated rows' multipliers from the
//! eliminated coordinates' equations of motion of the full model.

use crate::error::{check_len, Error};
use crate::kinematics::{inf_norm, kinetic_energy, mass_times};
use crate::mechanism::{Mechanism, MechanismInfo, NewtonOutputs};
use crate::watch::{velocity_residual, Residuals};

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
        let mut offsets = vec![0.0; 3 * self.substitutions.len()];
        (self.offsets)(t, &mut offsets);
        self.expand_with(reduced, &offsets, order, full)
    }

    /// [`Self::expand`] of a whole state: positions and velocities `(q, q̇)` at `t` into
    /// `full`'s two, with `offsets` (three per substitution) as work memory. Evaluates the
    /// offsets once and allocates nothing: for loops that read every step in full terms.
    pub fn expand_state(
        &self,
        (q, qd): (&[f64], &[f64]),
        t: f64,
        offsets: &mut [f64],
        full: (&mut [f64], &mut [f64]),
    ) -> Result<(), Error> {
        check_len(
            "substitution offsets",
            3 * self.substitutions.len(),
            offsets.len(),
        )?;
        (self.offsets)(t, offsets);
        self.expand_with(q, offsets, 0, full.0)?;
        self.expand_with(qd, offsets, 1, full.1)
    }

    /// [`Self::expand`] with the offsets at `t` already evaluated.
    fn expand_with(
        &self,
        reduced: &[f64],
        offsets: &[f64],
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
        check_len(
            "substitution offsets",
            3 * self.substitutions.len(),
            offsets.len(),
        )?;
        for (&c, &x) in self.coords.iter().zip(reduced) {
            full[c as usize] = x;
        }
        for (s, offset) in self.substitutions.iter().zip(offsets.chunks_exact(3)) {
            let follow = s.target.map_or(0.0, |j| s.weight * full[j as usize]);
            full[s.coord as usize] = offset[order] + follow;
        }
        Ok(())
    }
}

/// A reduced mechanism's kinematic states read in its full model's terms, without allocating
/// after [`FullState::new`]: coordinates, velocities, accelerations and multipliers, and the
/// full model's Φ, Φq and Φt at the state (what recording it on the full model needs).
#[derive(Debug, Clone)]
pub struct FullState {
    reduction: &'static Reduction,
    /// The full model's.
    info: &'static MechanismInfo,
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    pub qdd: Vec<f64>,
    pub lambda: Vec<f64>,
    pub phi: Vec<f64>,
    pub phi_q: Vec<f64>,
    pub phi_t: Vec<f64>,
    mass: Vec<f64>,
    force: Vec<f64>,
    m_qdd: Vec<f64>,
    offsets: Vec<f64>,
    /// Φq q̇ + Φt.
    velocity: Vec<f64>,
    /// For each substitution: the Φq nonzeros in its coordinate's column on other rows.
    coupling: Vec<Vec<usize>>,
}

impl FullState {
    /// The work memory for reading `reduction`'s states in terms of `full`, its full model.
    pub fn new(reduction: &'static Reduction, full: &'static MechanismInfo) -> Result<Self, Error> {
        check_len("full model coordinates", reduction.n_full, full.n_coords)?;
        check_len("full model rows", reduction.m_full, full.n_constraints)?;
        let (n, m) = (full.n_coords, full.n_constraints);
        let coupling = reduction
            .substitutions
            .iter()
            .map(|s| {
                (0..full.phi_q_nnz())
                    .filter(|&k| {
                        full.phi_q_cols[k] == s.coord
                            && s.row.is_none_or(|row| full.phi_q_rows[k] != row)
                    })
                    .collect()
            })
            .collect();
        Ok(FullState {
            reduction,
            info: full,
            q: vec![0.0; n],
            qd: vec![0.0; n],
            qdd: vec![0.0; n],
            lambda: vec![0.0; m],
            phi: vec![0.0; m],
            phi_q: vec![0.0; full.phi_q_nnz()],
            phi_t: vec![0.0; m],
            mass: vec![0.0; full.mass_nnz()],
            force: vec![0.0; n],
            m_qdd: vec![0.0; n],
            offsets: vec![0.0; 3 * reduction.substitutions.len()],
            velocity: vec![0.0; m],
            coupling,
        })
    }

    /// The full model's drift at the last state read: |Φ|∞ (redundant rows included), or
    /// `followed`, the reduced model's own |Φ|∞ there, where that is larger; and
    /// |Φq q̇ + Φt|∞.
    pub fn residuals(&mut self, followed: f64) -> Residuals {
        Residuals {
            position: inf_norm(&self.phi).max(followed),
            velocity: velocity_residual(
                self.info,
                &self.phi_q,
                &self.phi_t,
                &self.qd,
                &mut self.velocity,
            ),
        }
    }

    /// The full model's M nonzeros at the last state read.
    pub fn mass(&self) -> &[f64] {
        &self.mass
    }

    /// Kinetic plus potential energy of `full`, the full model, at the last state read (J).
    pub fn energy<M: Mechanism + ?Sized>(&self, full: &M) -> f64 {
        kinetic_energy(full.info(), &self.mass, &self.qd) + full.potential(&self.q)
    }

    /// Reads the reduced state `(q, q̇, q̈)` at `t` with the reduced rows' multipliers
    /// `lambda`: the kept rows' multipliers are copied, and each eliminated row's follows
    /// from its coordinate's equation of motion in the full model,
    /// `(M q̈)ᵢ + Σₛ Φq[s,i] λₛ = Qᵢ` (no eliminated row touches another eliminated
    /// coordinate, so one pass suffices).
    #[allow(clippy::too_many_arguments)]
    pub fn read<M: Mechanism + ?Sized>(
        &mut self,
        full: &M,
        t: f64,
        q: &[f64],
        qd: &[f64],
        qdd: &[f64],
        lambda: &[f64],
    ) -> Result<(), Error> {
        let (r, info) = (self.reduction, self.info);
        let given = full.info();
        check_len("full model coordinates", info.n_coords, given.n_coords)?;
        check_len("full model rows", info.n_constraints, given.n_constraints)?;
        check_len(
            "full model Φq nonzeros",
            info.phi_q_nnz(),
            given.phi_q_nnz(),
        )?;
        check_len(
            "full model mass nonzeros",
            info.mass_nnz(),
            given.mass_nnz(),
        )?;
        check_len("reduced multipliers", r.rows.len(), lambda.len())?;
        (r.offsets)(t, &mut self.offsets);
        r.expand_with(q, &self.offsets, 0, &mut self.q)?;
        r.expand_with(qd, &self.offsets, 1, &mut self.qd)?;
        r.expand_with(qdd, &self.offsets, 2, &mut self.qdd)?;
        let out = NewtonOutputs {
            phi: &mut self.phi,
            phi_q: &mut self.phi_q,
            mass: &mut self.mass,
            force: &mut self.force,
        };
        full.eval_newton(&self.q, &self.qd, t, out);
        full.phi_t(&self.q, t, &mut self.phi_t);
        mass_times(info, &self.mass, &self.qdd, &mut self.m_qdd);
        self.lambda.fill(0.0);
        for (&row, &l) in r.rows.iter().zip(lambda) {
            self.lambda[row as usize] = l;
        }
        for (s, others) in r.substitutions.iter().zip(&self.coupling) {
            let Some(row) = s.row else { continue };
            let i = s.coord as usize;
            let coupling: f64 = others
                .iter()
                .map(|&k| self.phi_q[k] * self.lambda[info.phi_q_rows[k] as usize])
                .sum();
            self.lambda[row as usize] = (self.force[i] - self.m_qdd[i] - coupling) / s.slope;
        }
        Ok(())
    }
}
