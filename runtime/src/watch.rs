//! Watchdogs: constraint drift at position and velocity level, and every Euler-angle body's
//! distance from the singularity at β = ±90° (docs/design.md, decision 11), so a simulation reports
//! trouble by body name instead of producing garbage. Quaternion bodies have no singularity
//! and are not watched.

use crate::error::{check_len, Error};
use crate::kinematics::{inf_norm, phi_q_times_add};
use crate::mechanism::{BodyInfo, Mechanism, MechanismInfo, Rotation};

/// Thresholds on |cos β|: below `warn_cos` a warning is reported, below `error_cos` an
/// error when the mass matrix depends on the coordinates (it becomes singular at cos β = 0;
/// a constant mass matrix gets the warning only). Defaults: warn at |β| ≳ 80° (cos β = 0.17), fail at |β| ≳ 88° (cos β = 0.035),
/// where Euler rates are ~30 times the angular velocity and their accuracy is gone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EulerLimits {
    pub warn_cos: f64,
    pub error_cos: f64,
}

impl Default for EulerLimits {
    fn default() -> Self {
        EulerLimits {
            warn_cos: 0.17,
            error_cos: 0.035,
        }
    }
}

/// A body whose β came close to ±90°.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EulerWarning {
    pub time: f64,
    pub body: usize,
    pub name: &'static str,
    /// β in radians.
    pub beta: f64,
}

/// β of an Euler-angle body (`None` for a quaternion body, or if `q` is too short).
fn euler_beta(body: &BodyInfo, q: &[f64]) -> Option<f64> {
    match body.rotation {
        Rotation::Euler => q.get(body.coord_offset + 4).copied(),
        Rotation::Quaternion => None,
    }
}

/// The Euler-angle body with the smallest |cos β| and that value (`None` for a mechanism
/// without Euler-angle bodies).
pub fn min_cos_beta(info: &MechanismInfo, q: &[f64]) -> Option<(usize, f64)> {
    info.bodies
        .iter()
        .enumerate()
        .filter_map(|(i, b)| euler_beta(b, q).map(|beta| (i, beta.cos().abs())))
        .min_by(|a, b| a.1.total_cmp(&b.1))
}

impl EulerLimits {
    /// Checks the limits are ordered and in (0, 1].
    pub fn validate(&self) -> Result<(), Error> {
        if !(self.error_cos >= 0.0 && self.error_cos <= self.warn_cos && self.warn_cos <= 1.0) {
            return Err(Error::InvalidSetting {
                name: "euler limits",
                value: self.error_cos,
                reason: "need 0 ≤ error_cos ≤ warn_cos ≤ 1",
            });
        }
        Ok(())
    }

    /// `Err(EulerSingularity)` past the error threshold, `Ok(Some(warning))` past the
    /// warning threshold, `Ok(None)` otherwise. A NaN angle is an error too.
    pub fn check(
        &self,
        info: &MechanismInfo,
        time: f64,
        q: &[f64],
    ) -> Result<Option<EulerWarning>, Error> {
        check_len("q", info.n_coords, q.len())?;
        for (i, b) in info.bodies.iter().enumerate() {
            if b.coord_offset + b.n_coords() > q.len() {
                return Err(Error::InvalidIndex {
                    what: "body",
                    index: i,
                    reason: "its coordinates lie outside q",
                });
            }
            let Some(beta) = euler_beta(b, q) else {
                continue;
            };
            // With M(q) from the kinetic energy, the Euler-rate map H(β) makes M singular at
            // cos β = 0: the step fails there. A constant mass matrix (the paper's
            // formulation) keeps the saddle-point system regular as long as Φq keeps full
            // row rank (which the solvers check), so there the angle only warrants a warning.
            let singular_mass = !info.mass_is_constant;
            if beta.is_nan() || (singular_mass && !(beta.cos().abs() >= self.error_cos)) {
                return Err(Error::EulerSingularity {
                    time,
                    body: b.name,
                    beta,
                });
            }
        }
        Ok(match min_cos_beta(info, q) {
            Some((i, c)) if c < self.warn_cos => {
                let b = &info.bodies[i];
                Some(EulerWarning {
                    time,
                    body: i,
                    name: b.name,
                    beta: q[b.coord_offset + 4],
                })
            }
            _ => None,
        })
    }
}

/// Constraint drift at one state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Residuals {
    /// |Φ(q, t)|∞.
    pub position: f64,
    /// |Φq q̇ + Φt|∞.
    pub velocity: f64,
}

/// |Φq q̇ + Φt|∞ from Φq's nonzeros and Φt at a state; `work` (`n_constraints` long) holds
/// Φq q̇ + Φt afterwards.
pub fn velocity_residual(
    info: &MechanismInfo,
    phi_q: &[f64],
    phi_t: &[f64],
    qd: &[f64],
    work: &mut [f64],
) -> f64 {
    work.copy_from_slice(phi_t);
    phi_q_times_add(info, phi_q, qd, work);
    inf_norm(work)
}

/// Work memory for evaluating [`Residuals`] without allocating.
#[derive(Debug, Clone)]
pub struct ResidualWatch {
    info: &'static MechanismInfo,
    phi: Vec<f64>,
    phi_q: Vec<f64>,
    phi_t: Vec<f64>,
    gamma: Vec<f64>,
    /// Φq q̇ + Φt.
    velocity: Vec<f64>,
}

impl ResidualWatch {
    pub fn new(info: &'static MechanismInfo) -> Self {
        let m = info.n_constraints;
        ResidualWatch {
            info,
            phi: vec![0.0; m],
            phi_q: vec![0.0; info.phi_q_nnz()],
            phi_t: vec![0.0; m],
            gamma: vec![0.0; m],
            velocity: vec![0.0; m],
        }
    }

    /// Position and velocity residuals of `mech` at `(q, q̇, t)`.
    pub fn check<M: Mechanism>(
        &mut self,
        mech: &M,
        t: f64,
        q: &[f64],
        qd: &[f64],
    ) -> Result<Residuals, Error> {
        let info = self.info;
        check_len(
            "mechanism constraints",
            info.n_constraints,
            mech.info().n_constraints,
        )?;
        check_len("Φq nonzeros", info.phi_q_nnz(), mech.info().phi_q_nnz())?;
        check_len("q", info.n_coords, q.len())?;
        check_len("qd", info.n_coords, qd.len())?;
        mech.eval_kinematics(
            q,
            qd,
            t,
            crate::mechanism::KinematicOutputs {
                phi: &mut self.phi,
                phi_q: &mut self.phi_q,
                phi_t: &mut self.phi_t,
                gamma: &mut self.gamma,
            },
        );
        Ok(Residuals {
            position: inf_norm(&self.phi),
            velocity: velocity_residual(info, &self.phi_q, &self.phi_t, qd, &mut self.velocity),
        })
    }

    /// Φq's nonzeros at the state of the last [`ResidualWatch::check`].
    pub fn phi_q(&self) -> &[f64] {
        &self.phi_q
    }

    /// Φt at the state of the last [`ResidualWatch::check`].
    pub fn phi_t(&self) -> &[f64] {
        &self.phi_t
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testmodels::Pendulum;

    #[test]
    fn euler_limits_name_the_body() {
        let info = Pendulum::exact().info();
        let lim = EulerLimits::default();
        let mut q = info.q0.to_vec();
        assert_eq!(lim.check(info, 1.0, &q), Ok(None));
        q[4] = 81f64.to_radians();
        let w = lim.check(info, 1.0, &q).unwrap().unwrap();
        assert_eq!((w.name, w.time), ("bob", 1.0));
        q[4] = -89f64.to_radians();
        match lim.check(info, 2.5, &q) {
            Err(e @ Error::EulerSingularity { time, body, .. }) => {
                assert_eq!((time, body), (2.5, "bob"));
                let msg = e.to_string();
                assert!(msg.contains("bob") && msg.contains("2.5"), "{msg}");
            }
            other => panic!("{other:?}"),
        }
        q[4] = f64::NAN;
        assert!(lim.check(info, 0.0, &q).is_err());
        // A constant mass matrix stays regular there: a warning, not an error.
        let paper = Pendulum::paper().info();
        q[4] = -89f64.to_radians();
        assert!(lim.check(paper, 2.5, &q).unwrap().is_some());
        q[4] = f64::NAN;
        assert!(lim.check(paper, 0.0, &q).is_err());
    }

    #[test]
    fn residuals_see_drift() {
        let mech = Pendulum::paper();
        let mut w = ResidualWatch::new(mech.info());
        let q = [0.0, -0.5, 0.0, 0.0, 0.0, 0.0];
        let r = w.check(&mech, 0.0, &q, &[0.0; 6]).unwrap();
        assert_eq!((r.position, r.velocity), (0.0, 0.0));
        // Moving straight down breaks the rod at velocity level by exactly the speed.
        let q2 = [0.0, -0.6, 0.0, 0.0, 0.0, 0.0];
        let r = w
            .check(&mech, 0.0, &q2, &[0.0, -2.0, 0.0, 0.0, 0.0, 0.0])
            .unwrap();
        assert!((r.position - 0.1).abs() < 1e-15 && (r.velocity - 2.0).abs() < 1e-15);
    }

    /// A quaternion body (coordinates 0..7) and an Euler body (7..13).
    static MIXED: MechanismInfo = MechanismInfo {
        name: "mixed",
        n_coords: 13,
        n_constraints: 0,
        phi_q_rows: &[],
        phi_q_cols: &[],
        mass_rows: &[],
        mass_cols: &[],
        bodies: &[
            BodyInfo {
                name: "ball",
                coord_offset: 0,
                rotation: Rotation::Quaternion,
                mass: 1.0,
                inertia: [1.0; 3],
            },
            BodyInfo {
                name: "bob",
                coord_offset: 7,
                rotation: Rotation::Euler,
                mass: 1.0,
                inertia: [1.0; 3],
            },
        ],
        joints: &[],
        coord_names: &[],
        row_names: &[],
        q0: &[],
        qd0: &[],
        redundant_rows: &[],
        platform: None,
        formulation: crate::mechanism::Formulation::Exact,
        gravity: [0.0; 3],
        mass_is_constant: false,
        force_q_rows: &[],
        force_q_cols: &[],
        force_qd_rows: &[],
        force_qd_cols: &[],
        kkt: &[],
    };

    #[test]
    fn quaternion_bodies_are_never_singular() {
        let lim = EulerLimits::default();
        let mut q = [0.0; 13];
        // The quaternion body's coordinate +4 (e1) at π/2 would read as β = 90°.
        q[4] = std::f64::consts::FRAC_PI_2;
        assert_eq!(lim.check(&MIXED, 0.0, &q), Ok(None));
        assert_eq!(min_cos_beta(&MIXED, &q), Some((1, 1.0)));
        // The Euler body is still watched, by name.
        q[7 + 4] = 81f64.to_radians();
        let w = lim.check(&MIXED, 0.5, &q).unwrap().unwrap();
        assert_eq!((w.body, w.name), (1, "bob"));
        q[7 + 4] = 89f64.to_radians();
        match lim.check(&MIXED, 0.5, &q) {
            Err(Error::EulerSingularity { body, .. }) => assert_eq!(body, "bob"),
            other => panic!("{other:?}"),
        }
        // Only quaternion bodies: nothing to watch.
        let only_quaternion = MechanismInfo {
            n_coords: 7,
            bodies: &MIXED.bodies[..1],
            ..MIXED
        };
        assert_eq!(min_cos_beta(&only_quaternion, &q[..7]), None);
        assert_eq!(lim.check(&only_quaternion, 0.0, &q[..7]), Ok(None));
        // A body whose coordinates run past q is an error, not a panic.
        let short = MechanismInfo {
            n_coords: 10,
            ..MIXED
        };
        assert!(matches!(
            lim.check(&short, 0.0, &q[..10]),
            Err(Error::InvalidIndex { .. })
        ));
    }
}
