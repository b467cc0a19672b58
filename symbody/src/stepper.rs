//! An integration's outputs as a [`Source`] for [`path_feed`]: the integrator, the energy
//! meter and the checks that see every step run where the source runs; each output goes to
//! the recording, which solves it for its reactions and energies ([`OutputSolve`]) unless
//! the meter already has.

use crate::generic::{
    full_state, integrator, mode_watch, solve_settings, Error, Options, Solution,
};
use crate::path_feed::Source;
use crate::scenario::Reduced;
use std::time::{Duration, Instant};
use symbody_runtime::fk::ModeWatch;
use symbody_runtime::{
    EnergyMeter, EnergySample, EulerWarning, Integrator, Kinematics, Mechanism, MechanismInfo,
    Pivots, ResidualWatch, Residuals, Stats,
};

/// Outputs handed over at a time, at most.
const BATCH: usize = 16;

/// How long a batch may take before it is handed over with fewer outputs (none at all in a
/// long output interval): the recording tells its observer the time reached (a live
/// progress bar, an interrupt) at least this often.
const TICK: Duration = Duration::from_millis(50);

/// Accepted steps between two looks at the clock for [`TICK`]: a look every step cost
/// 3 % of a small model's run.
const CLOCK_EVERY: u32 = 64;

/// Output times `k · step`, the last one at `t_end` (k = 0..=`last`), and the next one due.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Grid {
    step: f64,
    t_end: f64,
    last: usize,
    next: usize,
}

impl Grid {
    pub(crate) fn new(step: f64, t_end: f64, last: usize) -> Self {
        Grid {
            step,
            t_end,
            last,
            next: 0,
        }
    }

    pub(crate) fn more(&self) -> bool {
        self.next <= self.last
    }

    fn due(&self) -> f64 {
        (self.next as f64 * self.step).min(self.t_end)
    }
}

/// Steps `it` toward `grid`'s next output, calling `each` after every accepted step: `true`
/// once there (the output after it then due), `false` when `deadline` passed first (looked
/// at every [`CLOCK_EVERY`] steps).
pub(crate) fn reach<M: Mechanism>(
    it: &mut Integrator<M>,
    grid: &mut Grid,
    deadline: Instant,
    mut each: impl FnMut(&Integrator<M>) -> Result<(), Error>,
) -> Result<bool, Error> {
    let t_out = grid.due();
    let mut steps = 0;
    while it.step_toward(t_out)?.is_some() {
        each(it)?;
        steps += 1;
        if steps % CLOCK_EVERY == 0 && Instant::now() >= deadline {
            return Ok(false);
        }
    }
    grid.next += 1;
    Ok(true)
}

/// One output of an integration in the full model's terms: the state, the work and power
/// the energy meter integrated to it, what the meter solved there if it did (where rows
/// move with time), and the integrator's counters once it got there.
#[derive(Default)]
pub(crate) struct Integrated {
    pub t: f64,
    pub q: Vec<f64>,
    pub qd: Vec<f64>,
    pub work_and_power: (f64, f64),
    /// The energies, with `qdd`, `lambda`, `phi_q` and `pivots`, where the meter solved.
    pub solved: Option<EnergySample>,
    pub qdd: Vec<f64>,
    pub lambda: Vec<f64>,
    pub phi_q: Vec<f64>,
    pub pivots: Option<Pivots>,
    pub stats: Stats,
    pub euler_warning: Option<EulerWarning>,
}

/// The solve at each output that the integration did not need, `[M Φqᵀ; Φq 0][q̈; λ] =
/// [Q; γ]`, and the drift there: on the recording's thread, off the integration's.
pub(crate) struct OutputSolve {
    info: &'static MechanismInfo,
    kin: Kinematics,
    qdd: Vec<f64>,
    lambda: Vec<f64>,
    watch: ResidualWatch,
}

impl OutputSolve {
    /// For outputs in the terms of `info`, the full model, solved as the energy meter would.
    pub(crate) fn new(info: &'static MechanismInfo, opts: &Options) -> Result<Self, Error> {
        Ok(OutputSolve {
            info,
            kin: Kinematics::with_settings(info, solve_settings(opts.cross_singular))?,
            qdd: vec![0.0; info.n_coords],
            lambda: vec![0.0; info.n_constraints],
            watch: ResidualWatch::new(info),
        })
    }

    /// The output's solution, drift and energies: solved here unless the meter solved them.
    pub(crate) fn read<'a>(
        &'a mut self,
        mech: &(dyn Mechanism + Sync),
        out: &'a Integrated,
    ) -> Result<(Solution<'a>, Residuals, EnergySample), Error> {
        let (t, q, qd) = (out.t, &out.q[..], &out.qd[..]);
        let residuals = self.watch.check(&mech, t, q, qd)?;
        if let Some(sample) = out.solved {
            let solution = Solution {
                qdd: &out.qdd,
                lambda: &out.lambda,
                phi_q: &out.phi_q,
                pivots: out.pivots,
            };
            return Ok((solution, residuals, sample));
        }
        self.kin
            .acceleration(&mech, t, q, qd, &mut self.qdd, &mut self.lambda)?;
        let sample = EnergySample::at(
            (self.info, mech),
            self.kin.mass(),
            (t, q, qd),
            out.work_and_power,
        )?;
        let solution = Solution {
            qdd: &self.qdd,
            lambda: &self.lambda,
            phi_q: self.kin.phi_q(),
            pivots: self.kin.pivots(),
        };
        Ok((solution, residuals, sample))
    }
}

/// Outputs of an integration, and how far it had got when they were handed over.
pub(crate) struct Outputs<T> {
    /// Reused from batch to batch: only the first `len` are this batch's.
    items: Vec<T>,
    len: usize,
    /// The time reached and the steps taken.
    pub reached: (f64, usize),
}

impl<T> Outputs<T> {
    pub(crate) fn outputs(&self) -> &[T] {
        &self.items[..self.len]
    }
}

/// An integration that reaches its outputs one at a time, handed over in batches by
/// [`Batched`].
pub(crate) trait Outputting {
    /// One output, as handed over (its room reused).
    type Item: Default + Send;
    /// What the integration tells once it ends.
    type End;

    /// The outputs' times and the next one due.
    fn grid(&self) -> &Grid;

    /// Steps toward the next output until it is reached (then written to `out`: `true`) or
    /// until `deadline`, looked at every [`CLOCK_EVERY`] steps (`false`).
    fn advance(&mut self, out: &mut Self::Item, deadline: Instant) -> Result<bool, Error>;

    /// The time reached and the steps taken.
    fn reached(&self) -> (f64, usize);

    /// The end, given how it ended: `Ok` at the last output or when the recording stopped
    /// taking outputs, else the first failure.
    fn end(self, ended: Result<(), Error>) -> Self::End;
}

/// An [`Outputting`] integration as a [`Source`]: [`BATCH`] outputs at a time, fewer at
/// the end or after [`TICK`].
pub(crate) struct Batched<O> {
    outputs: O,
    ended: Option<Result<(), Error>>,
}

impl<O> Batched<O> {
    pub(crate) fn new(outputs: O) -> Self {
        Batched {
            outputs,
            ended: None,
        }
    }
}

impl<O: Outputting> Source for Batched<O> {
    type Batch = Outputs<O::Item>;
    type End = O::End;

    fn fill(&mut self, spare: Option<Self::Batch>) -> Option<Self::Batch> {
        if self.ended.is_some() {
            return None;
        }
        let mut batch = spare.unwrap_or(Outputs {
            items: Vec::new(),
            len: 0,
            reached: (0.0, 0),
        });
        batch.len = 0;
        let deadline = Instant::now() + TICK;
        while batch.len < BATCH && self.ended.is_none() {
            if !self.outputs.grid().more() {
                self.ended = Some(Ok(()));
                break;
            }
            if batch.items.len() == batch.len {
                batch.items.push(O::Item::default());
            }
            match self.outputs.advance(&mut batch.items[batch.len], deadline) {
                Ok(true) => batch.len += 1,
                Ok(false) => break,
                Err(e) => self.ended = Some(Err(e)),
            }
            if Instant::now() >= deadline {
                break;
            }
        }
        batch.reached = self.outputs.reached();
        Some(batch)
    }

    fn end(self) -> O::End {
        self.outputs.end(self.ended.unwrap_or(Ok(())))
    }
}

/// The integration of [`crate::generic::run`]: steps to each output time in turn (the
/// first output at the start), one accepted step at a time so that the energy meter and the
/// assembly-mode watch see every step. Ends with the integrator's counters, its first
/// Euler warning, and `Ok` at the last output, else the first failure.
pub(crate) struct Stepper {
    mech: &'static (dyn Mechanism + Sync),
    reduced: Option<Reduced>,
    it: Integrator<&'static (dyn Mechanism + Sync)>,
    meter: EnergyMeter,
    modes: Option<ModeWatch>,
    /// The full model's state, which every output and the meter see.
    q: Vec<f64>,
    qd: Vec<f64>,
    /// The reduction's work memory.
    offsets: Vec<f64>,
    grid: Grid,
}

impl Stepper {
    pub(crate) fn new(
        (mech, reduced): (&'static (dyn Mechanism + Sync), Option<Reduced>),
        opts: &Options,
        (t_end, n_out): (f64, usize),
    ) -> Result<Self, Error> {
        let info = mech.info();
        let it = integrator(reduced.map_or(mech, |(r, _)| r), opts)?;
        let mut stepper = Stepper {
            mech,
            reduced,
            it,
            meter: EnergyMeter::with_settings(info, solve_settings(opts.cross_singular))?,
            modes: None,
            q: vec![0.0; info.n_coords],
            qd: vec![0.0; info.n_coords],
            offsets: vec![0.0; reduced.map_or(0, |(_, r)| 3 * r.substitutions.len())],
            grid: Grid::new(opts.output_step, t_end, n_out),
        };
        let s = &mut stepper;
        full_state(&s.it, reduced, &mut s.offsets, (&mut s.q, &mut s.qd))?;
        s.modes = mode_watch(mech, &s.q)?;
        s.meter.advance(&mech, s.it.t(), &s.q, &s.qd)?;
        Ok(stepper)
    }
}

impl Outputting for Stepper {
    type Item = Integrated;
    type End = (Stats, Option<EulerWarning>, Result<(), Error>);

    fn grid(&self) -> &Grid {
        &self.grid
    }

    fn advance(&mut self, out: &mut Integrated, deadline: Instant) -> Result<bool, Error> {
        let Stepper {
            mech,
            reduced,
            it,
            meter,
            modes,
            q,
            qd,
            offsets,
            grid,
        } = self;
        let reached = reach(it, grid, deadline, |it| {
            full_state(it, *reduced, offsets, (q, qd))?;
            if let Some(w) = modes {
                w.check(q, it.t())?;
            }
            meter.advance(mech, it.t(), q, qd)?;
            Ok(())
        })?;
        if !reached {
            return Ok(false);
        }
        out.t = it.t();
        q.clone_into(&mut out.q);
        qd.clone_into(&mut out.qd);
        out.work_and_power = meter.work_and_power();
        out.solved = None;
        if meter.solved() {
            // The meter solved at this state already: its energies cost no solve.
            out.solved = Some(meter.sample(mech, q, qd)?);
            meter.qdd().clone_into(&mut out.qdd);
            meter.lambda().clone_into(&mut out.lambda);
            meter.phi_q().clone_into(&mut out.phi_q);
            out.pivots = meter.pivots();
        }
        out.stats = it.stats();
        out.euler_warning = it.first_euler_warning();
        Ok(true)
    }

    fn reached(&self) -> (f64, usize) {
        (self.it.t(), self.it.stats().steps)
    }

    fn end(self, ended: Result<(), Error>) -> Self::End {
        (self.it.stats(), self.it.first_euler_warning(), ended)
    }
}

#[cfg(test)]
mod tests {
    use super::{Batched, Stepper};
    use crate::generic::{find, run_observed, Observer, Options, Recording, Stopped};
    use crate::path_feed::{self, Thread};
    use crate::scenario::ScenarioError;
    use std::ops::ControlFlow;
    use symbody_mechanisms::REGISTRY;
    use symbody_testkit::models::{CircleDriver, CIRCLE_C0, CIRCLE_D, CIRCLE_V};

    /// Runs `name` with the integration on a thread of its own and on the recording's;
    /// `obs` sees each.
    fn both_layouts(
        name: &str,
        opts: Options,
        mut obs: impl Observer,
    ) -> [Result<Recording, Stopped>; 2] {
        let entry = find(&REGISTRY, name).unwrap();
        [true, false].map(|path_thread| {
            let opts = Options {
                path_thread,
                ..opts
            };
            run_observed(entry, &opts, &mut obs)
        })
    }

    /// A recording's every number, the wall time aside (`{:?}` writes each f64 so that it
    /// reads back to the same bits).
    fn numbers(rec: &Recording) -> String {
        let mut rec = rec.clone();
        rec.wall = std::time::Duration::ZERO;
        format!("{rec:?}")
    }

    /// The two layouts record the same outputs, bit for bit, with the same counters.
    #[test]
    fn an_integration_records_alike_on_its_own_thread_and_on_the_recordings() {
        let opts = Options {
            t_end: Some(0.5),
            ..Options::default()
        };
        let [beside, here] = both_layouts("spherical_pendulum", opts, ());
        let (beside, here) = (beside.unwrap(), here.unwrap());
        assert_eq!(beside.t.len(), 51);
        assert!(beside.stats.steps > 50, "{:?}", beside.stats);
        assert_eq!(numbers(&beside), numbers(&here));
    }

    /// The slider held at x = d on a circle of radius c(t) = c₀ − v t has no position once
    /// c < d (t > 2 s), so the integration fails on the way there. Both layouts hand over
    /// every output before the failure, in order, then the failure, with the same counters.
    #[test]
    fn the_outputs_before_a_failure_come_first_then_the_failure() {
        static CIRCLE: CircleDriver = CircleDriver;
        let end = (CIRCLE_C0 - CIRCLE_D) / CIRCLE_V;
        assert_eq!(end, 2.0);
        let opts = Options::default();
        let n_out = 300;
        let t_end = n_out as f64 * opts.output_step;
        let runs = [Thread::Yes, Thread::No].map(|thread| {
            let stepper = Stepper::new((&CIRCLE, None), &opts, (t_end, n_out)).unwrap();
            let stepper = Batched::new(stepper);
            path_feed::follow(stepper, thread, |feed| {
                let mut times = Vec::new();
                while let Some(batch) = feed.next() {
                    times.extend(batch.outputs().iter().map(|out| out.t));
                    feed.recycle(batch);
                }
                times
            })
        });
        for (k, (times, (stats, _, ended))) in runs.iter().enumerate() {
            assert!(ended.is_err(), "layout {k}: {ended:?}");
            let last = *times.last().unwrap();
            assert!(
                last > 1.9 && last < end,
                "layout {k}: last output at {last}"
            );
            for (i, t) in times.iter().enumerate() {
                assert_eq!(*t, (i as f64 * opts.output_step).min(t_end), "layout {k}");
            }
            assert!(stats.rejected_steps > 0, "layout {k}: {stats:?}");
            let first = &runs[0];
            assert_eq!((times, stats), (&first.0, &first.1 .0), "layout {k}");
            assert_eq!(
                ended.as_ref().unwrap_err().to_string(),
                first.1 .2.as_ref().unwrap_err().to_string()
            );
        }
    }

    /// Stops the run once it has seen time `after`, counting the calls.
    struct StopAfter {
        after: f64,
        seen: Vec<f64>,
    }

    impl Observer for StopAfter {
        fn progress(&mut self, t: f64, _steps: usize) -> ControlFlow<()> {
            self.seen.push(t);
            if t >= self.after {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        }
    }

    /// An observer that asks to stop stops the integration in either layout: the outputs
    /// recorded so far, in order, then `Interrupted` at the time the observer was last told.
    #[test]
    fn an_integration_stops_when_its_observer_asks() {
        let opts = Options {
            t_end: Some(2.0),
            ..Options::default()
        };
        for (k, run) in both_layouts(
            "spherical_pendulum",
            opts,
            StopAfter {
                after: 0.3,
                seen: Vec::new(),
            },
        )
        .into_iter()
        .enumerate()
        {
            let stopped = run.unwrap_err();
            let ScenarioError::Interrupted { time } = stopped.error else {
                panic!("layout {k}: {}", stopped.error);
            };
            assert!((0.3..2.0).contains(&time), "layout {k}: stopped at {time}");
            let rec = stopped.recording.unwrap();
            assert!(rec.t.windows(2).all(|w| w[0] < w[1]), "layout {k}");
            assert!(*rec.t.last().unwrap() <= time, "layout {k}");
        }
    }
}
