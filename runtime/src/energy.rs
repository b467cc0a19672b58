//! Energy bookkeeping: kinetic and potential energy at each recorded state and the work of
//! drivers and non-conservative forces since the first record, so that
//! `kinetic + potential − work` is constant along an exact solution and its drift measures
//! an integrator's error.
//!
//! With `M q̈ + Φqᵀλ = Q` and `Φq q̇ = −Φt`, the energy theorem reads
//! `d(T + V)/dt = λᵀΦt + P_nc`: the constraint power `λᵀΦt` is nonzero only on rows that
//! depend on time (drivers), and `P_nc` is [`Mechanism::power_nc`]. The multipliers are
//! recovered at each recorded state from `[M Φqᵀ; Φq 0][q̈; λ] = [Q; γ]` (the reactions of
//! that state, not an integrator's α-shifted ones), and the power is integrated between
//! records by the corrected trapezoid rule of [`crate::quadrature`]. With redundant rows λ is not unique, but `λᵀΦt` is:
//! two valid λ differ by `δλ` with `Φqᵀδλ = 0`, and `Φt = −Φq v` for a consistent `v`.

use crate::error::{check_len, Error};
use crate::kinematics::{kinetic_energy, KinematicSettings, Kinematics};
use crate::kkt::{KktSolver, SchurKkt};
use crate::mechanism::{Mechanism, MechanismInfo};
use crate::quadrature::RunningIntegral;

/// Energies at one recorded state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EnergySample {
    /// `½ q̇ᵀ M(q) q̇` (J).
    pub kinetic: f64,
    /// [`Mechanism::potential`] (J).
    pub potential: f64,
    /// Work of drivers and non-conservative forces since the first record (J).
    pub work: f64,
    /// Their power at this state, `λᵀΦt + P_nc` (W).
    pub power: f64,
}

impl EnergySample {
    /// The energies at the state `(q, q̇)` of time `t` from the nonzeros of M there, with
    /// the work and power integrated to it; an error names `t` when either energy is not
    /// finite.
    pub fn at<M: Mechanism + ?Sized>(
        (info, mech): (&MechanismInfo, &M),
        mass: &[f64],
        (t, q, qd): (f64, &[f64], &[f64]),
        (work, power): (f64, f64),
    ) -> Result<Self, Error> {
        let kinetic = kinetic_energy(info, mass, qd);
        let potential = mech.potential(q);
        if !(kinetic.is_finite() && potential.is_finite()) {
            return Err(Error::NotFinite {
                time: t,
                what: "energy",
            });
        }
        Ok(EnergySample {
            kinetic,
            potential,
            work,
            power,
        })
    }

    /// `kinetic + potential − work`: constant along an exact solution.
    pub fn balance(&self) -> f64 {
        self.kinetic + self.potential - self.work
    }
}

/// Records energies and integrates the work of drivers and non-conservative forces; all
/// memory is taken in [`EnergyMeter::new`], recording allocates nothing.
#[derive(Debug, Clone)]
pub struct EnergyMeter<K: KktSolver = SchurKkt> {
    info: &'static MechanismInfo,
    kin: Kinematics<K>,
    phi_t: Vec<f64>,
    qdd: Vec<f64>,
    lambda: Vec<f64>,
    /// Time of the last record (`None` before the first).
    last: Option<f64>,
    work: RunningIntegral,
    /// Power at the last record.
    power: f64,
    /// `qdd` and `lambda` belong to the last record's state.
    solved: bool,
    /// Some row may depend on time (a driver, or rows no joint describes), so the
    /// constraint power `λᵀΦt` needs λ at every record. Without, `Φt = 0` and records
    /// between outputs ([`EnergyMeter::advance`]) need no saddle-point solve.
    rheonomic: bool,
}

impl<K: KktSolver> EnergyMeter<K> {
    /// A meter for `info`'s mechanism, with no records yet.
    pub fn new(info: &'static MechanismInfo) -> Result<Self, Error> {
        Self::with_settings(info, KinematicSettings::default())
    }

    /// As [`EnergyMeter::new`], with the settings of its saddle-point solves (e.g. to drop
    /// rows that are dependent at a singular position).
    pub fn with_settings(
        info: &'static MechanismInfo,
        settings: KinematicSettings,
    ) -> Result<Self, Error> {
        Ok(EnergyMeter {
            info,
            kin: Kinematics::with_settings(info, settings)?,
            phi_t: vec![0.0; info.n_constraints],
            qdd: vec![0.0; info.n_coords],
            lambda: vec![0.0; info.n_constraints],
            last: None,
            work: RunningIntegral::default(),
            power: 0.0,
            solved: false,
            rheonomic: info.rows_may_depend_on_time(),
        })
    }

    /// Forgets the records: the next one starts the work at zero.
    pub fn reset(&mut self) {
        self.last = None;
        self.work.reset();
    }

    /// Records the state `(q, q̇)` at time `t` (not before the last record's time).
    ///
    /// Solves for `q̈` and λ at the state (borrow them with [`EnergyMeter::lambda`] and
    /// [`EnergyMeter::qdd`], e.g. for [`crate::reactions::joint_wrench`] with
    /// [`EnergyMeter::phi_q`]), then integrates the power up to `t`.
    pub fn record<M: Mechanism>(
        &mut self,
        mech: &M,
        t: f64,
        q: &[f64],
        qd: &[f64],
    ) -> Result<EnergySample, Error> {
        self.advance(mech, t, q, qd)?;
        self.sample(mech, q, qd)
    }

    /// Integrates the power up to the state `(q, q̇)` at time `t` (not before the last
    /// record's time), as [`EnergyMeter::record`] does, without the energies: for the
    /// steps between outputs, where the work must be integrated at the step but nothing is
    /// recorded. Where no row depends on time the constraint power is zero and this solves
    /// nothing; [`EnergyMeter::sample`] then solves at the output's state only.
    pub fn advance<M: Mechanism>(
        &mut self,
        mech: &M,
        t: f64,
        q: &[f64],
        qd: &[f64],
    ) -> Result<(), Error> {
        let info = self.info;
        check_len("mechanism coordinates", info.n_coords, mech.info().n_coords)?;
        check_len("q", info.n_coords, q.len())?;
        check_len("qd", info.n_coords, qd.len())?;
        if !t.is_finite() {
            return Err(Error::InvalidSetting {
                name: "t",
                value: t,
                reason: "must be finite",
            });
        }
        if let Some(t_last) = self.last {
            if !(t >= t_last) {
                return Err(Error::InvalidSetting {
                    name: "t",
                    value: t,
                    reason: "energy records must come in time order",
                });
            }
        }
        self.solved = false;
        let power = if self.rheonomic {
            self.solve(mech, t, q, qd)?;
            power(mech, t, q, qd, &self.lambda, &mut self.phi_t)
        } else {
            // Φt = 0 on every row: λᵀΦt is zero whatever λ is (`power`'s sum would add
            // exact zeros), so the power is the loads' alone.
            mech.power_nc(q, qd, t)
        };
        if !power.is_finite() {
            return Err(Error::NotFinite {
                time: t,
                what: "energy or power",
            });
        }
        self.last = Some(t);
        self.power = power;
        self.work.push(t, power);
        Ok(())
    }

    /// The energies at the last record's state, which `(q, q̇)` must be, and its `q̈` and λ
    /// (solved here unless that record solved them).
    pub fn sample<M: Mechanism>(
        &mut self,
        mech: &M,
        q: &[f64],
        qd: &[f64],
    ) -> Result<EnergySample, Error> {
        let t = self.last.ok_or(Error::InvalidSetting {
            name: "t",
            value: f64::NAN,
            reason: "no state recorded yet: advance or record first",
        })?;
        if !self.solved {
            self.solve(mech, t, q, qd)?;
        }
        EnergySample::at(
            (self.info, mech),
            self.kin.mass(),
            (t, q, qd),
            self.work_and_power(),
        )
    }

    /// Whether `q̈` and λ at the last record's state are solved (where rows move with time
    /// the power needed them), so that [`EnergyMeter::sample`] solves nothing.
    pub fn solved(&self) -> bool {
        self.solved
    }

    /// The work since the first record (J) and the power at the last record's state (W):
    /// what [`EnergyMeter::sample`] adds to the energies, for a caller that solves the state
    /// elsewhere.
    pub fn work_and_power(&self) -> (f64, f64) {
        (self.work.value(), self.power)
    }

    /// `q̈` and λ at the state; checks the mechanism against `info` too.
    fn solve<M: Mechanism>(
        &mut self,
        mech: &M,
        t: f64,
        q: &[f64],
        qd: &[f64],
    ) -> Result<(), Error> {
        self.kin
            .acceleration(mech, t, q, qd, &mut self.qdd, &mut self.lambda)?;
        self.solved = true;
        Ok(())
    }

    /// Multipliers λ at the last recorded state (`M q̈ + Φqᵀλ = Q`).
    pub fn lambda(&self) -> &[f64] {
        &self.lambda
    }

    /// Accelerations at the last recorded state.
    pub fn qdd(&self) -> &[f64] {
        &self.qdd
    }

    /// How well the constraint rows determined λ at the last recorded state.
    pub fn pivots(&self) -> Option<crate::kkt::Pivots> {
        self.kin.pivots()
    }

    /// Φq nonzeros at the last recorded state.
    pub fn phi_q(&self) -> &[f64] {
        self.kin.phi_q()
    }
}

/// The power of drivers and non-conservative loads at the state `(q, q̇)` with multipliers
/// `lambda` (from `[M Φqᵀ; Φq 0][q̈; λ] = [Q; γ]` at that state): `λᵀΦt + P_nc` (W).
/// `phi_t` is scratch of `n_constraints`. For callers that already hold λ of a state
/// between records (a kinematic path's sub-samples).
pub fn power<M: Mechanism>(
    mech: &M,
    t: f64,
    q: &[f64],
    qd: &[f64],
    lambda: &[f64],
    phi_t: &mut [f64],
) -> f64 {
    mech.phi_t(q, t, phi_t);
    let constraint_power: f64 = lambda.iter().zip(phi_t.iter()).map(|(l, p)| l * p).sum();
    constraint_power + mech.power_nc(q, qd, t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hht::HhtBuilder;
    use crate::reactions::driver_effort;
    use crate::testmodels::{
        CircleDriver, Pendulum, CIRCLE_C0, CIRCLE_MASS, CIRCLE_V, G, PENDULUM_LENGTH, PENDULUM_MASS,
    };

    #[test]
    fn circle_driver_energy_change_equals_driver_work() {
        let mech = CircleDriver;
        let info = mech.info();
        let mut hht = HhtBuilder::new().step(1e-3).build(mech).unwrap();
        let mut meter = EnergyMeter::<SchurKkt>::new(info).unwrap();
        let first = meter.record(&mech, hht.t(), hht.q(), hht.qd()).unwrap();
        let scale = CIRCLE_MASS * G * CIRCLE_C0;
        let mut worst = 0.0f64;
        let mut last = first;
        let lift = info.joint_index("lift").unwrap();
        for _ in 0..1000 {
            hht.step().unwrap();
            last = meter.record(&mech, hht.t(), hht.q(), hht.qd()).unwrap();
            worst = worst.max((last.balance() - first.balance()).abs());
            // The constraint power is the driver's: its effort times the rate of its
            // driven distance, dc/dt = −v.
            let effort = driver_effort(info, meter.lambda(), lift).unwrap();
            assert!(
                (last.power - effort * -CIRCLE_V).abs() < 1e-9 * scale,
                "{} vs {}",
                last.power,
                effort * -CIRCLE_V
            );
        }
        let change = last.kinetic + last.potential - first.kinetic - first.potential;
        eprintln!(
            "ΔE = {change:.6} J, W = {:.6} J, max |ΔE − W| = {worst:e} J",
            last.work
        );
        assert!(worst < 1e-7 * scale, "energy balance off by {worst:e} J");
        // The driver's work is what the balance is made of: without it the mismatch would
        // be the whole change of energy (the slider is lowered against gravity).
        assert!(last.work.abs() > 0.2 * scale, "W = {}", last.work);
        assert!((change - last.work).abs() < 1e-6 * last.work.abs());
    }

    #[test]
    fn a_free_pendulum_does_no_work_and_keeps_its_energy() {
        // No driver, no non-conservative force: W = 0 and T + V is conserved by
        // trapezoidal HHT to O(h²).
        let mech = Pendulum::exact();
        let q0 = [0.0, 0.0, 0.0, 0.5, 0.1, -0.4];
        let mut hht = HhtBuilder::new()
            .alpha(0.0)
            .q0(&q0)
            .qd0(&[0.0, 0.0, 0.0, 0.0, 0.5, 0.0])
            .build(mech)
            .unwrap();
        let mut meter = EnergyMeter::<SchurKkt>::new(mech.info()).unwrap();
        let first = meter.record(&mech, hht.t(), hht.q(), hht.qd()).unwrap();
        let mut worst = 0.0f64;
        for _ in 0..500 {
            hht.step().unwrap();
            let s = meter.record(&mech, hht.t(), hht.q(), hht.qd()).unwrap();
            assert!(s.work.abs() < 1e-12 && s.power.abs() < 1e-12, "{s:?}");
            worst = worst.max((s.balance() - first.balance()).abs());
            // The integrator's own bookkeeping agrees.
            assert!((s.kinetic + s.potential - hht.energy()).abs() < 1e-12);
        }
        let scale = PENDULUM_MASS * G * PENDULUM_LENGTH;
        assert!(worst < 1e-6 * scale, "relative drift {}", worst / scale);
    }

    #[test]
    fn records_out_of_order_or_of_the_wrong_size_are_errors() {
        let mech = CircleDriver;
        let mut meter = EnergyMeter::<SchurKkt>::new(mech.info()).unwrap();
        let (q, qd) = (mech.info().q0, [0.0, -0.125, 0.0, 0.0, 0.0, 0.0]);
        meter.record(&mech, 0.5, q, &qd).unwrap();
        assert!(meter.record(&mech, 0.4, q, &qd).is_err());
        assert!(meter.record(&mech, f64::NAN, q, &qd).is_err());
        assert!(meter.record(&mech, 0.6, &q[..5], &qd).is_err());
        meter.reset();
        assert_eq!(meter.record(&mech, 0.0, q, &qd).unwrap().work, 0.0);
    }

    /// Between outputs `advance` integrates the power without solving where no row depends
    /// on time: at the outputs the energies, work, q̈ and λ are those of a meter that records
    /// (and solves) at every step, bit for bit (the skipped constraint power is a sum of
    /// exact zeros). A driven model solves at every step either way.
    #[test]
    fn advancing_between_outputs_records_what_recording_every_step_does() {
        fn compare<M: Mechanism + Copy>(mech: M, q0: &[f64], qd0: &[f64]) {
            let mut hht = HhtBuilder::new()
                .step(1e-3)
                .q0(q0)
                .qd0(qd0)
                .build(mech)
                .unwrap();
            let mut every = EnergyMeter::<SchurKkt>::new(mech.info()).unwrap();
            let mut between = EnergyMeter::<SchurKkt>::new(mech.info()).unwrap();
            let (mut some_work, mut records) = (0.0f64, 0);
            for k in 0..=300 {
                if k > 0 {
                    hht.step().unwrap();
                }
                let (t, q, qd) = (hht.t(), hht.q(), hht.qd());
                let expected = every.record(&mech, t, q, qd).unwrap();
                between.advance(&mech, t, q, qd).unwrap();
                if k % 10 == 0 {
                    assert_eq!(between.sample(&mech, q, qd).unwrap(), expected, "t = {t}");
                    assert_eq!(between.lambda(), every.lambda());
                    assert_eq!(between.qdd(), every.qdd());
                    some_work = some_work.max(expected.work.abs());
                    records += 1;
                }
            }
            assert_eq!(records, 31);
            if mech.info().rows_may_depend_on_time() {
                assert!(some_work > 1e-3, "the driver does work: {some_work}");
            }
        }
        assert!(!Pendulum::exact().info().rows_may_depend_on_time());
        let q0 = [0.0, 0.0, 0.0, 0.5, 0.1, -0.4];
        compare(Pendulum::exact(), &q0, &[0.0, 0.0, 0.0, 0.0, 0.5, 0.0]);
        assert!(CircleDriver.info().rows_may_depend_on_time());
        let q0 = CircleDriver.info().q0;
        compare(CircleDriver, q0, &[0.0, -0.125, 0.0, 0.0, 0.0, 0.0]);
    }

    #[test]
    fn a_sample_needs_a_state_first() {
        let mech = CircleDriver;
        let mut meter = EnergyMeter::<SchurKkt>::new(mech.info()).unwrap();
        let (q, qd) = (mech.info().q0, [0.0, -0.125, 0.0, 0.0, 0.0, 0.0]);
        assert!(meter.sample(&mech, q, &qd).is_err());
    }
}
