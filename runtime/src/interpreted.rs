//! A mechanism evaluated by the tape interpreter instead of compiled code: the same
//! functions, behind the same [`Mechanism`] trait, so every solver runs it unchanged.

use crate::mechanism::{
    Direction, KinematicOutputs, Mechanism, MechanismInfo, NewtonOutputs, TangentOutputs,
};
use crate::tape::Tape;
use std::sync::Arc;

/// The tapes that do not depend on the formulation.
#[derive(Debug)]
pub struct KinematicTapes {
    pub phi: Tape,
    pub phi_q: Tape,
    pub phi_t: Tape,
    pub gamma: Tape,
    /// Outputs Φ, Φq, Φt, γ.
    pub eval_kinematics: Tape,
    pub potential: Tape,
    pub power_nc: Tape,
}

/// The tapes of one formulation.
#[derive(Debug)]
pub struct DynamicTapes {
    /// Outputs ∂Q/∂q and ∂Q/∂q̇ nonzeros.
    pub force_jacobian: Tape,
    pub mass: Tape,
    pub force: Tape,
    /// Outputs Φ, Φq, M, Q.
    pub eval_newton: Tape,
    /// Outputs the directional derivatives of Φ, Φq, Φt, γ, M, Q; its inputs are
    /// `q` = `[q, dq, dp]` and `qd` = `[qd, dqd]` ([`Mechanism::tangents`]). Built only
    /// for a load that asked for it.
    pub tangents: Option<Tape>,
}

/// One formulation of an interpreted mechanism.
#[derive(Debug, Clone)]
pub struct Interpreted {
    info: &'static MechanismInfo,
    kinematic: Arc<KinematicTapes>,
    dynamic: Arc<DynamicTapes>,
    /// The run-time values the tapes were bound with ([`Mechanism::run_time_values`]).
    values: Arc<[f64]>,
}

impl Interpreted {
    /// Panics when a tape's outputs do not have the sizes `info` gives: the generator built
    /// both from one model, so a mismatch is a bug, not bad input.
    pub fn new(
        info: &'static MechanismInfo,
        kinematic: Arc<KinematicTapes>,
        dynamic: Arc<DynamicTapes>,
        values: Arc<[f64]>,
    ) -> Self {
        let (n, m) = (info.n_coords, info.n_constraints);
        let sizes = |t: &Tape| t.output_lens().collect::<Vec<_>>();
        let k = &kinematic;
        assert_eq!(sizes(&k.eval_kinematics), [m, info.phi_q_nnz(), m, m]);
        assert_eq!(sizes(&k.phi), [m]);
        let d = &dynamic;
        assert_eq!(
            sizes(&d.eval_newton),
            [m, info.phi_q_nnz(), info.mass_nnz(), n]
        );
        assert_eq!(
            sizes(&d.force_jacobian),
            [info.force_q_rows.len(), info.force_qd_rows.len()]
        );
        if let Some(t) = &d.tangents {
            assert_eq!(sizes(t), [m, info.phi_q_nnz(), m, m, info.mass_nnz(), n]);
        }
        Interpreted {
            info,
            kinematic,
            dynamic,
            values,
        }
    }
}

impl Mechanism for Interpreted {
    fn info(&self) -> &'static MechanismInfo {
        self.info
    }
    fn phi(&self, q: &[f64], t: f64, out: &mut [f64]) {
        self.kinematic.phi.eval(q, &[], t, &mut [out]);
    }
    fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) {
        self.kinematic.phi_q.eval(q, &[], t, &mut [out]);
    }
    fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) {
        self.kinematic.phi_t.eval(q, &[], t, &mut [out]);
    }
    fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        self.kinematic.gamma.eval(q, qd, t, &mut [out]);
    }
    fn mass(&self, q: &[f64], out: &mut [f64]) {
        self.dynamic.mass.eval(q, &[], 0.0, &mut [out]);
    }
    fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        self.dynamic.force.eval(q, qd, t, &mut [out]);
    }
    fn force_jacobian(&self, q: &[f64], qd: &[f64], t: f64, dq: &mut [f64], dqd: &mut [f64]) {
        self.dynamic.force_jacobian.eval(q, qd, t, &mut [dq, dqd]);
    }
    fn potential(&self, q: &[f64]) -> f64 {
        let mut out = [0.0];
        self.kinematic.potential.eval(q, &[], 0.0, &mut [&mut out]);
        out[0]
    }
    fn power_nc(&self, q: &[f64], qd: &[f64], t: f64) -> f64 {
        let mut out = [0.0];
        self.kinematic.power_nc.eval(q, qd, t, &mut [&mut out]);
        out[0]
    }
    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        self.dynamic
            .eval_newton
            .eval(q, qd, t, &mut [out.phi, out.phi_q, out.mass, out.force]);
    }
    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
        self.kinematic.eval_kinematics.eval(
            q,
            qd,
            t,
            &mut [out.phi, out.phi_q, out.phi_t, out.gamma],
        );
    }
    fn run_time_values(&self) -> &[f64] {
        &self.values
    }
    fn tangents(
        &self,
        q: &[f64],
        qd: &[f64],
        t: f64,
        dir: Direction<'_>,
        out: TangentOutputs<'_>,
    ) -> bool {
        let Some(tape) = &self.dynamic.tangents else {
            return false;
        };
        assert_eq!(dir.dp.len(), self.values.len(), "dp has the wrong length");
        tape.eval_joined(
            &[q, dir.dq, dir.dp],
            &[qd, dir.dqd],
            t,
            &mut [
                out.phi, out.phi_q, out.phi_t, out.gamma, out.mass, out.force,
            ],
        );
        true
    }
}
