//! A path's states (a kinematic path's solves, an integration's outputs) and their
//! recording (reactions, energies, checks, files) on two threads, the states handed over in
//! batches: on two cores the recording costs the run no wall time. For a small model, the
//! same loop on one thread.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::thread::{Scope, ScopedJoinHandle};
use std::time::{Duration, Instant};
use symbody_runtime::kkt::Pivots;
use symbody_runtime::{Error, KinematicPath, Mechanism, MechanismInfo, PathStats};

use crate::apart;

/// Where [`follow`] runs its source.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Thread {
    /// On the recording's thread, as it asks for each batch.
    No,
    /// On a thread of its own from the start.
    Yes,
    /// On the recording's thread until it has run this long, then on its own: a run too
    /// short to repay a thread's start never starts one.
    After(Duration),
}

/// Runs `source` and hands its states to `record` through a [`Feed`], in batches, in time
/// order, the source on the thread `thread` says. The source stops at its own end or when
/// `record` returns (at its next hand-over). Returns what `record` returned and how the
/// source ended.
pub(crate) fn follow<S: Source + Send, R>(
    source: S,
    thread: Thread,
    record: impl FnOnce(&mut Feed<'_, '_, S>) -> R,
) -> (R, S::End)
where
    S::End: Send,
{
    std::thread::scope(|scope| {
        let mut feed = Feed {
            at: At::Here {
                source,
                spare: None,
            },
            thread: None,
            move_at: None,
        };
        match thread {
            Thread::No => {}
            Thread::Yes => feed.move_to(scope),
            Thread::After(run) => feed.move_at = Some((scope, Instant::now() + run)),
        }
        let recorded = record(&mut feed);
        let ended = feed
            .end()
            .expect("a followed source runs on the recording's thread or its own");
        (recorded, ended)
    })
}

/// [`follow`] the other way round: the source on this thread, `record` on a second one. For a
/// run whose path is what it waits for: it starts at once, where a new
/// thread may wait for a core (measured on the paper scene: 0.15–3.3 ms before its first
/// instruction, the printed time 1.16 times this order's, median of 20 alternated pairs).
pub(crate) fn record_beside<S: Source + Send, R: Send>(
    source: S,
    record: impl FnOnce(&mut Feed<'_, '_, S>) -> R + Send,
) -> (R, S::End)
where
    S::End: Send,
{
    let mut recorded = None;
    let ended = std::thread::scope(|scope| {
        let (at, producer) = channel();
        let mut feed = Feed {
            at,
            thread: None,
            move_at: None,
        };
        let slot = &mut recorded;
        let here = apart::current();
        let recording = spawn_named(scope, "symbody-record", move || {
            apart::leave(here);
            *slot = Some(record(&mut feed))
        });
        let ended = producer.run(source);
        // The recording's last batch: waited for awake, as `Feed::next` waits, then the
        // thread is let go rather than joined. Joining waited for its exit (its stack and
        // allocator given back), and asleep: the run ended 0.13–0.5 ms after its last output
        // was recorded, against 0.01–0.02 ms this way (the paper scene, 2026-11-29). The
        // scope still returns only once the recording has.
        let start = Instant::now();
        while !recording.is_finished() && start.elapsed() < POLL {
            std::thread::yield_now();
        }
        drop(recording);
        ended
    });
    let recorded = recorded.expect("a scope returns once its threads have");
    (recorded, ended)
}

/// `scope.spawn(f)` on a thread named `name`, so that profilers and debuggers tell a run's
/// threads apart.
fn spawn_named<'scope, T: Send + 'scope>(
    scope: &'scope Scope<'scope, '_>,
    name: &str,
    f: impl FnOnce() -> T + Send + 'scope,
) -> ScopedJoinHandle<'scope, T> {
    std::thread::Builder::new()
        .name(name.to_string())
        .spawn_scoped(scope, f)
        .expect("failed to spawn thread")
}

/// What a [`Feed`] hands over: states solved in time order, a batch at a time.
pub(crate) trait Source {
    /// The states handed over at once.
    type Batch: Send;
    /// How the source ended: its counters, its first failure.
    type End;

    /// The next states, in `spare` (a batch the recording is done with) where given; `None`
    /// once every state is handed over.
    fn fill(&mut self, spare: Option<Self::Batch>) -> Option<Self::Batch>;

    fn end(self) -> Self::End;
}

/// The two ends of a hand-over between threads.
fn channel<S: Source>() -> (At<S>, Producer<S::Batch>) {
    let (to_caller, solved) = mpsc::sync_channel(QUEUE);
    let (to_path, emptied) = mpsc::channel();
    let at = At::Channel {
        solved,
        emptied: to_path,
    };
    (at, Producer { to_caller, emptied })
}

/// The source's end of a hand-over between threads.
struct Producer<B> {
    to_caller: mpsc::SyncSender<B>,
    emptied: mpsc::Receiver<B>,
}

impl<B: Send> Producer<B> {
    /// Fills and hands over until the source ends or the caller stops taking batches.
    fn run<S: Source<Batch = B>>(self, mut source: S) -> S::End {
        while let Some(batch) = source.fill(self.emptied.try_recv().ok()) {
            // A closed channel: the caller stopped and wants no more.
            if self.to_caller.send(batch).is_err() {
                break;
            }
        }
        source.end()
    }
}

/// A kinematic path and what is left of its times: solves the path at each time in turn,
/// after its current state (handed over first). It stops early when `stop` is set or at
/// its first failure, after handing over every state solved before it. With `own`, each
/// state carries Φq, Φt and M the path solved with (for a caller that records on the
/// followed model itself); without, only the state and the multipliers (a caller that
/// reads each state back on another model evaluates there). Ends with the path's counters
/// and `Ok` when it reached its last time or was stopped, else its first failure.
pub(crate) struct Solver<'a, M: Mechanism> {
    path: KinematicPath<M>,
    times: std::vec::IntoIter<f64>,
    stop: Option<&'a AtomicBool>,
    /// The states solved and not handed over yet.
    batch: Batch,
    /// How the path ended, once it has.
    ended: Option<Result<(), Error>>,
}

impl<'a, M: Mechanism> Solver<'a, M> {
    pub(crate) fn new(
        path: KinematicPath<M>,
        times: Vec<f64>,
        own: bool,
        stop: Option<&'a AtomicBool>,
    ) -> Self {
        let mut batch = Batch::new(path.info(), own);
        batch.push(&path);
        Solver {
            path,
            times: times.into_iter(),
            stop,
            batch,
            ended: None,
        }
    }
}

impl<M: Mechanism + Send> Source for Solver<'_, M> {
    type Batch = Batch;
    type End = (PathStats, Result<(), Error>);

    /// The next [`BATCH`] states solved (fewer at the end).
    fn fill(&mut self, spare: Option<Batch>) -> Option<Batch> {
        while self.ended.is_none() && self.batch.len() < BATCH {
            match self.times.next() {
                Some(_) if self.stop.is_some_and(|s| s.load(Ordering::Relaxed)) => {
                    self.ended = Some(Ok(()))
                }
                Some(t) => match self.path.advance_to(t) {
                    Ok(()) => self.batch.push(&self.path),
                    Err(e) => self.ended = Some(Err(e)),
                },
                None => self.ended = Some(Ok(())),
            }
        }
        if self.batch.len() == 0 {
            return None;
        }
        // The states after these go into the spare batch, or a new one.
        let next = match spare {
            Some(mut b) => {
                b.clear();
                b
            }
            None => Batch::new(self.path.info(), self.batch.own),
        };
        Some(std::mem::replace(&mut self.batch, next))
    }

    fn end(self) -> (PathStats, Result<(), Error>) {
        (self.path.stats(), self.ended.unwrap_or(Ok(())))
    }
}

/// The recording's end of [`follow`] and [`record_beside`].
pub(crate) struct Feed<'scope, 'env, S: Source + 'scope> {
    at: At<S>,
    /// The source's own thread, once it has one ([`follow`]).
    thread: Option<ScopedJoinHandle<'scope, S::End>>,
    /// When to move a source that runs here to a thread of its own ([`Thread::After`]).
    move_at: Option<(&'scope Scope<'scope, 'env>, Instant)>,
}

/// Where a [`Feed`]'s source runs.
enum At<S: Source> {
    /// On the recording's thread, a batch at a time.
    Here {
        source: S,
        /// The last batch recorded, to fill again.
        spare: Option<S::Batch>,
    },
    /// On another thread.
    Channel {
        solved: mpsc::Receiver<S::Batch>,
        emptied: mpsc::Sender<S::Batch>,
    },
}

impl<'scope, S: Source + Send + 'scope> Feed<'scope, '_, S>
where
    S::End: Send + 'scope,
{
    /// Moves a source that runs here to a thread of its own.
    fn move_to(&mut self, scope: &'scope Scope<'scope, '_>) {
        let (channel, producer) = channel();
        let At::Here { source, spare } = std::mem::replace(&mut self.at, channel) else {
            return;
        };
        if let Some(batch) = spare {
            self.recycle(batch);
        }
        let here = apart::current();
        self.thread = Some(spawn_named(scope, "symbody-path", move || {
            apart::leave(here);
            producer.run(source)
        }));
    }

    /// How the source ended: at once when it runs here, else once its thread has stopped
    /// (at its next hand-over); `None` for [`record_beside`]'s recording, whose source
    /// ends on the caller's thread.
    fn end(self) -> Option<S::End> {
        match self.at {
            At::Here { source, .. } => Some(source.end()),
            At::Channel { solved, emptied } => {
                drop((solved, emptied));
                let thread = self.thread?;
                Some(
                    thread
                        .join()
                        .unwrap_or_else(|panic| std::panic::resume_unwind(panic)),
                )
            }
        }
    }

    /// The next solved states in time order; `None` once the source has ended. From another
    /// thread, polls for [`POLL`] before it sleeps: a recording faster than the path would
    /// otherwise sleep before every batch, and Linux then wakes it on the path's core (it
    /// counts the sender's core as warm for it) and often keeps it there for a run of a few
    /// milliseconds, the two threads sharing one core while the other idles (the paper
    /// scene's printed time fell into two groups, about 5 and 8.5 ms; 8 ms is what both
    /// threads pinned to one core take). It polls yielding its core, not spinning: with two
    /// integrated scenes run at once on two cores, spinning made them 1.5–2 times as long,
    /// and alone neither way was slower (alternated runs, 2026-11-29).
    pub(crate) fn next(&mut self) -> Option<S::Batch> {
        if let Some((scope, at)) = self.move_at {
            if Instant::now() >= at {
                self.move_at = None;
                self.move_to(scope);
            }
        }
        let solved = match &mut self.at {
            At::Here { source, spare } => return source.fill(spare.take()),
            At::Channel { solved, .. } => solved,
        };
        let start = Instant::now();
        loop {
            match solved.try_recv() {
                Ok(batch) => return Some(batch),
                Err(mpsc::TryRecvError::Disconnected) => return None,
                Err(mpsc::TryRecvError::Empty) if start.elapsed() < POLL => {
                    std::thread::yield_now()
                }
                Err(mpsc::TryRecvError::Empty) => return solved.recv().ok(),
            }
        }
    }

    /// Hands a recorded batch back for the source to fill again.
    pub(crate) fn recycle(&mut self, batch: S::Batch) {
        match &mut self.at {
            At::Here { spare, .. } => *spare = Some(batch),
            // The source may have finished: then the batch is not needed.
            At::Channel { emptied, .. } => {
                let _ = emptied.send(batch);
            }
        }
    }
}

/// Whether a path on `followed` is worth a thread of its own beside a caller that records
/// every state: its saddle-point system has [`THREAD_SIZE`] rows and columns or more.
pub(crate) fn worth_a_thread(followed: &MechanismInfo) -> bool {
    followed.n_coords + followed.n_constraints >= THREAD_SIZE
}

/// Size of `[M Φqᵀ; Φq 0]` from which the tables' kinematic path runs on its own thread.
/// Measured on the scenes (printed wall time, alternated pairs, 2026-11-29): the Stewart
/// platforms (150 and 182) took 0.65–0.88 of the one-thread time in three sittings, the
/// four-bar (39) and the slider-crank (42) 1.3 and 2.8 times it: their whole runs take
/// 1–4 ms, of which starting the thread alone took 0.13–0.18 ms, and their outputs cost
/// too little for the hand-overs to hide.
const THREAD_SIZE: usize = 100;

/// Batches that may wait for the recording: room for the paper scene's path to go on while
/// its recording makes the choice of path first (≈ 1 ms, 100 outputs); a full queue stops
/// the path.
const QUEUE: usize = 32;

/// States the path hands over at a time: each hand-over costs a wake-up, which 16 outputs'
/// solves hide.
const BATCH: usize = 16;

/// How long [`Feed::next`] polls before it sleeps: several batches' worth of the paper
/// path's solves (≈ 0.1 ms each), so that it sleeps only when the path is slow (a full
/// Newton solve, a failure being reported).
const POLL: Duration = Duration::from_millis(2);

/// Solved states of a kinematic path, one after another in each field.
pub(crate) struct Batch {
    /// The followed model's.
    info: &'static MechanismInfo,
    /// Φq, Φt and M kept ([`follow`]'s `own`).
    own: bool,
    t: Vec<f64>,
    q: Vec<f64>,
    qd: Vec<f64>,
    qdd: Vec<f64>,
    lambda: Vec<f64>,
    phi_q: Vec<f64>,
    phi_t: Vec<f64>,
    mass: Vec<f64>,
    position_residual: Vec<f64>,
    pivots: Vec<Option<Pivots>>,
}

/// One solved state of a [`Batch`], in the followed model's terms.
pub(crate) struct State<'a> {
    pub t: f64,
    pub q: &'a [f64],
    pub qd: &'a [f64],
    pub qdd: &'a [f64],
    pub lambda: &'a [f64],
    /// Φq's nonzeros, Φt and M's nonzeros the state was solved with; empty unless `own`.
    pub phi_q: &'a [f64],
    pub phi_t: &'a [f64],
    pub mass: &'a [f64],
    /// |Φ|∞ at `q` from the position solve's last evaluation.
    pub position_residual: f64,
    pub pivots: Option<Pivots>,
}

impl Batch {
    fn new(info: &'static MechanismInfo, own: bool) -> Self {
        Batch {
            info,
            own,
            t: Vec::new(),
            q: Vec::new(),
            qd: Vec::new(),
            qdd: Vec::new(),
            lambda: Vec::new(),
            phi_q: Vec::new(),
            phi_t: Vec::new(),
            mass: Vec::new(),
            position_residual: Vec::new(),
            pivots: Vec::new(),
        }
    }

    fn push<M: Mechanism>(&mut self, path: &KinematicPath<M>) {
        if self.t.capacity() == 0 {
            self.reserve();
        }
        self.t.push(path.t());
        self.q.extend_from_slice(path.q());
        self.qd.extend_from_slice(path.qd());
        self.qdd.extend_from_slice(path.qdd());
        self.lambda.extend_from_slice(path.lambda());
        self.position_residual.push(path.position_residual());
        self.pivots.push(path.pivots());
        if self.own {
            self.phi_q.extend_from_slice(path.phi_q());
            self.phi_t.extend_from_slice(path.phi_t());
            self.mass.extend_from_slice(path.mass());
        }
    }

    /// Room for [`BATCH`] states at once: grown state by state, a new batch's fields were
    /// reallocated and copied five times each.
    fn reserve(&mut self) {
        let (n, m) = (self.info.n_coords, self.info.n_constraints);
        for (v, size) in [
            (&mut self.t, 1),
            (&mut self.q, n),
            (&mut self.qd, n),
            (&mut self.qdd, n),
            (&mut self.lambda, m),
            (&mut self.position_residual, 1),
        ] {
            v.reserve_exact(BATCH * size);
        }
        if self.own {
            self.phi_q.reserve_exact(BATCH * self.info.phi_q_nnz());
            self.phi_t.reserve_exact(BATCH * m);
            self.mass.reserve_exact(BATCH * self.info.mass_nnz());
        }
        self.pivots.reserve_exact(BATCH);
    }

    pub(crate) fn len(&self) -> usize {
        self.t.len()
    }

    /// State `k` of the batch.
    pub(crate) fn state(&self, k: usize) -> State<'_> {
        let (n, m) = (self.info.n_coords, self.info.n_constraints);
        let (nnz, mass_nnz) = (self.info.phi_q_nnz(), self.info.mass_nnz());
        let (phi_q, phi_t, mass): (&[f64], &[f64], &[f64]) = if self.own {
            (
                &self.phi_q[k * nnz..][..nnz],
                &self.phi_t[k * m..][..m],
                &self.mass[k * mass_nnz..][..mass_nnz],
            )
        } else {
            (&[], &[], &[])
        };
        State {
            t: self.t[k],
            q: &self.q[k * n..][..n],
            qd: &self.qd[k * n..][..n],
            qdd: &self.qdd[k * n..][..n],
            lambda: &self.lambda[k * m..][..m],
            phi_q,
            phi_t,
            mass,
            position_residual: self.position_residual[k],
            pivots: self.pivots[k],
        }
    }

    fn clear(&mut self) {
        for v in [
            &mut self.t,
            &mut self.q,
            &mut self.qd,
            &mut self.qdd,
            &mut self.lambda,
            &mut self.phi_q,
            &mut self.phi_t,
            &mut self.mass,
            &mut self.position_residual,
        ] {
            v.clear();
        }
        self.pivots.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use symbody_testkit::models::{CircleDriver, CIRCLE_C0, CIRCLE_D, CIRCLE_V};

    /// The times of every state `feed` hands over, taking them all.
    fn times_of(feed: &mut Feed<'_, '_, Solver<'_, CircleDriver>>) -> Vec<f64> {
        let mut times = Vec::new();
        while let Some(batch) = feed.next() {
            times.extend((0..batch.len()).map(|k| batch.state(k).t));
            feed.recycle(batch);
        }
        times
    }

    /// The three layouts: on one thread, the path beside, the recording beside.
    fn each_layout<R: Send>(
        times: &[f64],
        stop: Option<&AtomicBool>,
        record: impl Fn(&mut Feed<'_, '_, Solver<'_, CircleDriver>>) -> R + Sync,
    ) -> Vec<(R, PathStats, Result<(), Error>)> {
        let path = || {
            let path = KinematicPath::new(CircleDriver, 0.0).unwrap();
            Solver::new(path, times.to_vec(), true, stop)
        };
        [
            follow(path(), Thread::No, &record),
            follow(path(), Thread::Yes, &record),
            record_beside(path(), &record),
        ]
        .into_iter()
        .map(|(recorded, (stats, ended))| (recorded, stats, ended))
        .collect()
    }

    /// The slider held at x = d on a circle of radius c(t) = c₀ − v t has no position once
    /// c < d (t > 2 s), so the path fails on the way there: every layout hands over the
    /// start and each time solved before the failure, in order, then the failure, with the
    /// same counters.
    #[test]
    fn the_states_before_a_failure_come_first_then_the_failure() {
        let end = (CIRCLE_C0 - CIRCLE_D) / CIRCLE_V;
        assert_eq!(end, 2.0);
        let times: Vec<f64> = (1..=300).map(|k| 0.01 * k as f64).collect();
        let runs = each_layout(&times, None, times_of);
        for (k, (seen, stats, ended)) in runs.iter().enumerate() {
            assert!(ended.is_err(), "layout {k}: {ended:?}");
            assert_eq!(seen[0], 0.0);
            assert_eq!(&seen[1..], &times[..seen.len() - 1], "layout {k}");
            let last = *seen.last().unwrap();
            assert!(last > 1.9 && last < end, "layout {k}: last state at {last}");
            assert_eq!(stats.outputs, seen.len(), "layout {k}");
            assert_eq!((seen, stats), (&runs[0].0, &runs[0].1), "layout {k}");
        }
    }

    /// A path that moves to a thread of its own while it runs ([`Thread::After`]) hands over
    /// the states and ends as on one thread. The recording pauses after its first batch,
    /// past the time the move waits for, so that the move comes mid-run (or at the first
    /// batch on a slow machine: the states are the same either way).
    #[test]
    fn a_path_moved_to_its_own_thread_midway_hands_over_the_same_states() {
        let times: Vec<f64> = (1..=300).map(|k| 0.01 * k as f64).collect();
        let run = |thread| {
            let path = KinematicPath::new(CircleDriver, 0.0).unwrap();
            let solver = Solver::new(path, times.clone(), true, None);
            follow(solver, thread, |feed| {
                let mut seen = Vec::new();
                while let Some(batch) = feed.next() {
                    if seen.is_empty() {
                        std::thread::sleep(Duration::from_millis(3));
                    }
                    seen.extend((0..batch.len()).map(|k| batch.state(k).t));
                    feed.recycle(batch);
                }
                (seen, feed.thread.is_some())
            })
        };
        let ((here, on_thread), (stats, ended)) = run(Thread::No);
        assert!(!on_thread);
        let ((moved, on_thread), (moved_stats, moved_ended)) =
            run(Thread::After(Duration::from_millis(1)));
        assert!(on_thread);
        assert_eq!((moved, moved_stats), (here, stats));
        assert_eq!(
            moved_ended.unwrap_err().to_string(),
            ended.unwrap_err().to_string()
        );
    }

    /// A recording that stops taking states stops the path within the batches queued for it;
    /// `stop` set before the start leaves only the start.
    #[test]
    fn the_path_stops_with_its_recording_or_its_flag() {
        let times: Vec<f64> = (1..=1000).map(|k| 0.001 * k as f64).collect();
        let first =
            |feed: &mut Feed<'_, '_, Solver<'_, CircleDriver>>| feed.next().map(|b| b.len());
        for (k, (taken, stats, ended)) in each_layout(&times, None, first).iter().enumerate() {
            assert_eq!(*taken, Some(BATCH), "layout {k}");
            assert!(ended.is_ok(), "layout {k}: {ended:?}");
            // At most the batch taken, the full queue and the one filled meanwhile.
            assert!(
                stats.outputs <= (QUEUE + 2) * BATCH,
                "layout {k}: {stats:?}"
            );
        }
        let stop = AtomicBool::new(true);
        for (k, (seen, stats, ended)) in each_layout(&times, Some(&stop), times_of)
            .iter()
            .enumerate()
        {
            assert_eq!(seen, &[0.0], "layout {k}");
            assert_eq!(stats.outputs, 1, "layout {k}");
            assert!(ended.is_ok(), "layout {k}: {ended:?}");
        }
    }
}
