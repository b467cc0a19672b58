//! One simulation of any registered mechanism behind a small surface a controller loop can
//! drive: build, step or advance, read the state, the reaction wrenches and the driver
//! efforts. The C ABI (`capi/`) and the Python package (`python/`) wrap exactly this, so the
//! three languages compute the same numbers by the same code.

use crate::scenario::ScenarioError;
use symbody_runtime::{
    driver_effort, joint_wrench, Formulation, HhtBuilder, Integrator, Kinematics, Mechanism,
    MechanismInfo, Registry, Wrench,
};

pub type Error = ScenarioError;

/// The generated mechanism as a trait object from the registry.
pub type Dyn = &'static (dyn Mechanism + Sync);

/// Settings of a [`Session`]; the defaults are the paper scenario's integrator.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// `None`: the mechanism's first formulation.
    pub formulation: Option<Formulation>,
    /// HHT α in [−1/3, 0].
    pub alpha: f64,
    /// HHT step (s).
    pub step: f64,
    /// Project velocities onto the constraints after each step (see `generic::Options`).
    pub project_velocities: bool,
    /// Pass singular positions (`generic::Options::cross_singular`): the step and the
    /// multipliers drop rows that are dependent at the state.
    pub cross_singular_positions: bool,
    /// Step-size control's `(rtol, atol)` (`HhtBuilder::tolerances`; `step` is then the
    /// first step tried); `None`: the fixed `step`.
    pub tolerances: Option<(f64, f64)>,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            formulation: None,
            alpha: -0.05,
            step: 1e-3,
            project_velocities: false,
            cross_singular_positions: false,
            tolerances: None,
        }
    }
}

/// A running simulation. Stepping allocates nothing; the multipliers of the current state
/// come from one saddle-point solve `[M Φqᵀ; Φq 0][q̈; λ] = [Q; γ]`, done on demand and
/// cached until the state changes.
pub struct Session {
    it: Integrator<Dyn>,
    kinematics: Kinematics,
    qdd: Vec<f64>,
    lambda: Vec<f64>,
    phi_q: Vec<f64>,
    /// Whether `lambda` and `phi_q` belong to the current state.
    fresh: bool,
}

impl Session {
    /// A consistent start of the mechanism `name` of `registry`.
    pub fn new(registry: &Registry, name: &str, s: Settings) -> Result<Session, Error> {
        let entry = crate::generic::find(registry, name)?;
        let mech = match s.formulation {
            None => entry.default_mechanism(),
            Some(f) => entry.mechanism(f).ok_or_else(|| {
                ScenarioError::Options(format!(
                    "`{name}` was not generated in the {} formulation",
                    f.name()
                ))
            })?,
        };
        Session::with_mechanism(mech, s)
    }

    /// A consistent start of `mech` (e.g. of an entry from [`crate::files::load`]);
    /// `s.formulation` is not consulted: `mech` is already one formulation.
    pub fn with_mechanism(mech: Dyn, s: Settings) -> Result<Session, Error> {
        let info = mech.info();
        let solves = crate::generic::solve_settings(s.cross_singular_positions);
        let mut builder = HhtBuilder::new()
            .alpha(s.alpha)
            .step(s.step)
            .qd0(info.qd0)
            .project_velocities(s.project_velocities)
            .kinematic_settings(solves);
        if let Some((rtol, atol)) = s.tolerances {
            builder = builder.tolerances(rtol, atol);
        }
        let it = builder.build(mech)?;
        Ok(Session {
            it,
            kinematics: Kinematics::with_settings(info, solves)?,
            qdd: vec![0.0; info.n_coords],
            lambda: vec![0.0; info.n_constraints],
            phi_q: vec![0.0; info.phi_q_nnz()],
            fresh: false,
        })
    }

    pub fn info(&self) -> &'static MechanismInfo {
        self.it.info()
    }
    pub fn mechanism(&self) -> Dyn {
        *self.it.mechanism()
    }
    pub fn t(&self) -> f64 {
        self.it.t()
    }
    pub fn q(&self) -> &[f64] {
        self.it.q()
    }
    pub fn qd(&self) -> &[f64] {
        self.it.qd()
    }

    /// One HHT step of the nominal size.
    pub fn step(&mut self) -> Result<(), Error> {
        self.fresh = false;
        self.it.step()?;
        Ok(())
    }

    /// Steps until exactly `t` (the last step shortened to land on it).
    pub fn advance_to(&mut self, t: f64) -> Result<(), Error> {
        self.fresh = false;
        self.it.advance_to(t)?;
        Ok(())
    }

    fn refresh(&mut self) -> Result<(), Error> {
        if !self.fresh {
            let (t, q, qd) = (self.it.t(), self.it.q(), self.it.qd());
            self.kinematics.acceleration(
                self.it.mechanism(),
                t,
                q,
                qd,
                &mut self.qdd,
                &mut self.lambda,
            )?;
            self.it.mechanism().phi_q(q, t, &mut self.phi_q);
            self.fresh = true;
        }
        Ok(())
    }

    /// The Lagrange multipliers of the current state (one per constraint row).
    pub fn multipliers(&mut self) -> Result<&[f64], Error> {
        self.refresh()?;
        Ok(&self.lambda)
    }

    /// The effort of every driver, in joint order (`info().joints` filtered to drivers):
    /// force (N) or torque (N·m) on the driven body along the driven coordinate.
    pub fn driver_efforts(&mut self, out: &mut [f64]) -> Result<usize, Error> {
        self.refresh()?;
        let info = self.info();
        let mut n = 0;
        for (j, joint) in info.joints.iter().enumerate() {
            if joint.kind == symbody_runtime::JointKind::Driver {
                if let Some(slot) = out.get_mut(n) {
                    *slot = driver_effort(info, &self.lambda, j)?;
                }
                n += 1;
            }
        }
        Ok(n)
    }

    /// The effort of the driver called `name`.
    pub fn driver_effort(&mut self, name: &str) -> Result<f64, Error> {
        let j = self.joint(name)?;
        self.refresh()?;
        Ok(driver_effort(self.info(), &self.lambda, j)?)
    }

    /// The wrench joint `name` exerts on its first body (global frame, moment about the
    /// joint point).
    pub fn joint_wrench(&mut self, name: &str) -> Result<Wrench, Error> {
        let j = self.joint(name)?;
        self.refresh()?;
        Ok(joint_wrench(
            self.info(),
            self.it.q(),
            &self.phi_q,
            &self.lambda,
            j,
        )?)
    }

    fn joint(&self, name: &str) -> Result<usize, Error> {
        let info = self.info();
        info.joint_index(name).ok_or_else(|| {
            let known: Vec<&str> = info.joints.iter().map(|j| j.name).collect();
            ScenarioError::Options(format!(
                "`{}` has no joint or driver `{name}`; it has: {}",
                info.name,
                known.join(", ")
            ))
        })
    }
}

/// The number the Rust example, the C example and the Python package all print: the paper
/// platform's actuator 1 force (N) at t = 1 s with the default [`Settings`].
pub fn paper_leg1_force_at_1s(registry: &Registry) -> Result<f64, Error> {
    let mut s = Session::new(registry, crate::scenario::MECHANISM, Settings::default())?;
    s.advance_to(1.0)?;
    s.driver_effort("act1")
}

#[cfg(test)]
mod tests {
    use super::*;
    use symbody_mechanisms::REGISTRY;

    /// Against the paper scenario's recorder, which computes the actuator forces its own way
    /// (recovered reactions, same integrator settings).
    #[test]
    fn session_matches_the_paper_scenario() {
        let f = paper_leg1_force_at_1s(&REGISTRY).unwrap();
        let opts = crate::scenario::Options {
            t_end: 1.0,
            output_step: 0.5,
            ..Default::default()
        };
        let run = crate::scenario::simulate(&REGISTRY, &opts).unwrap();
        let k = run.t.iter().position(|&t| t == 1.0).unwrap();
        assert!(
            (run.actuators[k][0] - f).abs() <= 1e-9 * f.abs(),
            "{} vs {f}",
            run.actuators[k][0]
        );
    }

    #[test]
    fn unknown_names_are_errors_that_list_the_known_ones() {
        let e = Session::new(&REGISTRY, "stewart", Settings::default())
            .err()
            .unwrap();
        assert!(e.to_string().contains("stewart_6_6"), "{e}");
        let mut s = Session::new(&REGISTRY, "four_bar", Settings::default()).unwrap();
        let e = s.driver_effort("act9").unwrap_err().to_string();
        assert!(
            e.contains("act9") && e.contains("a0, a1, b1, b0, motor"),
            "{e}"
        );
    }
}
