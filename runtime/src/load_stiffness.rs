//! The applied loads' stiffness and damping in HHT's Newton matrix: the top-left block
//! `c·M − βh²·sym(∂Q/∂q) − γh·sym(∂Q/∂q̇)` on the union of the mass pattern and the
//! (symmetrized) patterns the generator emits for the loads' Jacobians.
//!
//! Without them a spring of stiffness k or a damper of rate c/m limits Newton, not the
//! motion: modified Newton contracts only while `βh²k/m` and `γh·c/m` stay below about one,
//! so the step follows the load's time scale instead of the motion's (IFToMM A05's governor
//! needed h ≤ 1.25e-4 s). The block is symmetrized so the structured KKT solver's Cholesky
//! applies; the antisymmetric part (a damper's dependence on position, a follower load) is
//! left to the iteration, like every other term outside the matrix.

use crate::kkt::{AssembleKernel, KktPattern};
use crate::mechanism::MechanismInfo;

/// Where each contribution goes in the union pattern, and the work memory of one assembly.
#[derive(Debug, Clone)]
pub(crate) struct LoadStiffness {
    rows: Vec<u32>,
    cols: Vec<u32>,
    mass_slot: Vec<usize>,
    /// Per ∂Q/∂q nonzero `(r, c)`: its slots `(r, c)` and `(c, r)`.
    dq_slot: Vec<(usize, usize)>,
    dqd_slot: Vec<(usize, usize)>,
    pub(crate) dq: Vec<f64>,
    pub(crate) dqd: Vec<f64>,
    values: Vec<f64>,
    /// The generated assembly, where it was emitted for these patterns.
    kernel: Option<AssembleKernel>,
}

/// The union of the mass pattern and the symmetrized load Jacobians' patterns, sorted.
pub(crate) fn union(mass: &[(u32, u32)], dq: &[(u32, u32)], dqd: &[(u32, u32)]) -> Vec<(u32, u32)> {
    let mut union: Vec<(u32, u32)> = mass.to_vec();
    for &(r, c) in dq.iter().chain(dqd) {
        union.push((r, c));
        union.push((c, r));
    }
    union.sort_unstable();
    union.dedup();
    union
}

impl LoadStiffness {
    /// `None` when the mechanism has no load Jacobian (nothing to add).
    pub(crate) fn new(info: &MechanismInfo) -> Option<Self> {
        if info.force_q_rows.is_empty() && info.force_qd_rows.is_empty() {
            return None;
        }
        let pairs = |rows: &[u32], cols: &[u32]| -> Vec<(u32, u32)> {
            rows.iter().copied().zip(cols.iter().copied()).collect()
        };
        let mass = pairs(info.mass_rows, info.mass_cols);
        let dq = pairs(info.force_q_rows, info.force_q_cols);
        let dqd = pairs(info.force_qd_rows, info.force_qd_cols);
        let union = union(&mass, &dq, &dqd);
        let slot = |p: (u32, u32)| union.binary_search(&p).expect("in the union");
        let both = |&(r, c): &(u32, u32)| (slot((r, c)), slot((c, r)));
        Some(LoadStiffness {
            mass_slot: mass.iter().map(|&p| slot(p)).collect(),
            dq_slot: dq.iter().map(both).collect(),
            dqd_slot: dqd.iter().map(both).collect(),
            dq: vec![0.0; dq.len()],
            dqd: vec![0.0; dqd.len()],
            values: vec![0.0; union.len()],
            rows: union.iter().map(|p| p.0).collect(),
            cols: union.iter().map(|p| p.1).collect(),
            kernel: info
                .kkt
                .iter()
                .find_map(|k| k.loads_for(info))
                .map(|l| l.assemble),
        })
    }

    /// The KKT pattern with the union as its top-left block.
    pub(crate) fn pattern(&self, info: &MechanismInfo) -> KktPattern {
        KktPattern {
            mass_rows: self.rows.clone(),
            mass_cols: self.cols.clone(),
            ..KktPattern::from_info(info)
        }
    }

    /// `c·M − kq·sym(dq) − kqd·sym(dqd)` in the union pattern, from the mass nonzeros and
    /// the Jacobians last written to `self.dq`, `self.dqd` (`kq = βh²`, `kqd = γh`; both 0
    /// give `c·M` alone).
    pub(crate) fn assemble(&mut self, mass: &[f64], c: f64, kq: f64, kqd: f64) -> &[f64] {
        let (dq, dqd) = (&self.dq, &self.dqd);
        if let Some(Ok(())) = self
            .kernel
            .map(|k| k(mass, c, dq, kq, dqd, kqd, &mut self.values))
        {
            return &self.values;
        }
        self.values.fill(0.0);
        for (&s, &m) in self.mass_slot.iter().zip(mass) {
            self.values[s] = c * m;
        }
        for (slots, vals, k) in [
            (&self.dq_slot, &self.dq, kq),
            (&self.dqd_slot, &self.dqd, kqd),
        ] {
            for (&(a, b), &v) in slots.iter().zip(vals.iter()) {
                let half = 0.5 * k * v;
                self.values[a] -= half;
                self.values[b] -= half;
            }
        }
        &self.values
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two coordinates, a diagonal mass and one spring-like coupling: the assembled block is
    /// `cM − βh²·(K + Kᵀ)/2 − γh·(C + Cᵀ)/2`, written out by hand.
    #[test]
    fn assembles_the_symmetric_part_on_the_union_pattern() {
        static INFO: MechanismInfo = MechanismInfo {
            name: "two",
            n_coords: 2,
            n_constraints: 0,
            formulation: crate::Formulation::Exact,
            gravity: [0.0; 3],
            phi_q_rows: &[],
            phi_q_cols: &[],
            mass_rows: &[0, 1],
            mass_cols: &[0, 1],
            mass_is_constant: true,
            force_q_rows: &[0, 0, 1],
            force_q_cols: &[0, 1, 1],
            force_qd_rows: &[1],
            force_qd_cols: &[0],
            bodies: &[],
            joints: &[],
            coord_names: &["a", "b"],
            row_names: &[],
            q0: &[0.0; 2],
            qd0: &[0.0; 2],
            redundant_rows: &[],
            platform: None,
            kkt: &[],
        };
        let mut s = LoadStiffness::new(&INFO).unwrap();
        assert_eq!(s.rows, [0, 0, 1, 1]);
        assert_eq!(s.cols, [0, 1, 0, 1]);
        s.dq.copy_from_slice(&[-4.0, 2.0, -6.0]);
        s.dqd.copy_from_slice(&[-8.0]);
        let (c, kq, kqd) = (2.0, 0.5, 0.25);
        let got = s.assemble(&[3.0, 5.0], c, kq, kqd).to_vec();
        // K = [[-4, 2], [0, -6]], C = [[0, 0], [-8, 0]].
        let k_sym = [[-4.0, 1.0], [1.0, -6.0]];
        let c_sym = [[0.0, -4.0], [-4.0, 0.0]];
        let m = [[3.0, 0.0], [0.0, 5.0]];
        let want: Vec<f64> = [(0, 0), (0, 1), (1, 0), (1, 1)]
            .iter()
            .map(|&(i, j)| c * m[i][j] - kq * k_sym[i][j] - kqd * c_sym[i][j])
            .collect();
        assert_eq!(got, want);
        use crate::Mechanism;
        let pendulum = crate::testmodels::Pendulum::exact();
        assert!(LoadStiffness::new(pendulum.info()).is_none());
    }
}
