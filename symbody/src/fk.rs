//! `symbody fk`: forward kinematics of any registered six-leg platform — the pose reached by
//! continuation from a known pose, every assembly mode with the current one marked, and how
//! the modes evolve along the mechanism's own driver motion.

use crate::output::write;
use crate::scenario::ScenarioError;
use std::path::Path;
use std::time::{Duration, Instant};
use symbody_runtime::fk::{self, Modes, Platform, Pose, TrackSettings, Tracked};
use symbody_runtime::{Entry, Mechanism};

pub type Error = ScenarioError;

/// The platform of a registry entry, or an error saying why the entry has none.
pub fn platform(entry: &'static Entry) -> Result<Platform<'static, dyn Mechanism + Sync>, Error> {
    Platform::new(entry.default_mechanism()).map_err(|e| {
        // The runtime's "invalid platform index 0" is how the generator's absent
        // `PlatformInfo` reaches it; the user needs the reason in the mechanism's terms.
        let why = match e {
            symbody_runtime::Error::InvalidIndex {
                what: "platform",
                reason,
                ..
            } => reason.to_string(),
            other => other.to_string(),
        };
        ScenarioError::Options(format!(
            "`{}` has no six-leg platform, so forward kinematics does not apply: {why}. \
             `symbody list` marks the mechanisms that have one (FK column)",
            entry.name
        ))
    })
}

/// The names of the entries of `registry` that have a six-leg platform (`symbody fk` takes
/// them).
pub fn platforms(registry: &symbody_runtime::Registry) -> Vec<&'static str> {
    registry
        .iter()
        .filter(|e| e.default_mechanism().info().platform.is_some())
        .map(|e| e.name)
        .collect()
}

/// A forward-kinematics request; `None` takes the mechanism's own value.
#[derive(Debug, Clone, Copy, Default)]
pub struct Request {
    /// Leg lengths (default: what the drivers prescribe at `at`).
    pub lengths: Option<[f64; 6]>,
    /// Pose to continue from (default: the file's initial pose).
    pub from: Option<Pose>,
    /// Time at which the drivers set the default lengths (s).
    pub at: f64,
}

/// The pose reached by continuation.
#[derive(Debug, Clone, Copy)]
pub struct Answer {
    pub lengths: [f64; 6],
    pub start: Pose,
    pub tracked: Tracked,
    pub wall: Duration,
}

/// Leg lengths run from joint centre to joint centre: zero or less would put a platform joint
/// on or through its base joint, which no pose realizes.
fn check_lengths(lengths: &[f64; 6]) -> Result<(), Error> {
    match lengths.iter().find(|l| !l.is_finite() || **l <= 0.0) {
        Some(&l) => Err(ScenarioError::Runtime(
            symbody_runtime::Error::InvalidSetting {
                name: "leg length",
                value: l,
                reason: "must be positive and finite (joint centre to joint centre)",
            },
        )),
        None => Ok(()),
    }
}

/// Continues the pose from the request's start along the straight line in leg-length space
/// to its lengths, so the answer is on the start's assembly mode or an error says where a
/// parallel singularity was in the way (path parameter `t` from 0 to 1).
pub fn solve<M: Mechanism + ?Sized>(p: &Platform<'_, M>, req: &Request) -> Result<Answer, Error> {
    let start = match req.from {
        Some(pose) => pose,
        None => p.pose(p.q0())?,
    };
    let lengths = req.lengths.unwrap_or_else(|| p.lengths_at(req.at));
    check_lengths(&lengths)?;
    let legs = p.legs();
    let l0 = legs.lengths(&start);
    let clock = Instant::now();
    let line = |s: f64| std::array::from_fn(|i| l0[i] + s * (lengths[i] - l0[i]));
    let tracked = match fk::track(legs, line, &start, 0.0, 1.0, TrackSettings::default()) {
        Ok(t) => t,
        Err(e @ symbody_runtime::Error::PlatformSingularity { .. }) => {
            return Err(unreachable_or(p, &lengths, e))
        }
        Err(e) => return Err(e.into()),
    };
    Ok(Answer {
        lengths,
        start,
        tracked,
        wall: clock.elapsed(),
    })
}

/// A singularity met on the way to `lengths` is only the answer when some pose has those
/// lengths: unreachable lengths (longer than the legs can stretch between their joints) also
/// stop the continuation at a singularity, where the branch folds back, and then the
/// singularity's time says nothing useful. Every assembly mode (all complex solutions) tells
/// the two apart.
fn unreachable_or<M: Mechanism + ?Sized>(
    p: &Platform<'_, M>,
    lengths: &[f64; 6],
    singular: symbody_runtime::Error,
) -> Error {
    let at = match singular {
        symbody_runtime::Error::PlatformSingularity { time, .. } => time,
        _ => f64::NAN,
    };
    match fk::assembly_modes(p.legs(), lengths) {
        Ok(modes) if modes.real.is_empty() => ScenarioError::Options(format!(
            "no real pose of the platform has the leg lengths {} m (all {} assembly modes at \
             these lengths are complex), so continuation from the start pose cannot reach \
             them: it stopped at t = {at:.6} of the straight leg-length path, at a parallel \
             singularity where the branch of poses folds back. Give lengths the legs can reach (the \
             drivers' at some time: --at), and check their unit (metres)",
            lengths.map(|l| format!("{l}")).join(", "),
            modes.complex
        )),
        _ => singular.into(),
    }
}

/// Every assembly mode at `lengths`, the index of the one nearest `current` (the same pose
/// to 1e-8 of the platform's size), and the time taken.
pub fn all_modes<M: Mechanism + ?Sized>(
    p: &Platform<'_, M>,
    lengths: &[f64; 6],
    current: Option<&Pose>,
) -> Result<(Modes, Option<usize>, Duration), Error> {
    check_lengths(lengths)?;
    let clock = Instant::now();
    let modes = fk::assembly_modes(p.legs(), lengths)?;
    let wall = clock.elapsed();
    let lc = p.legs().characteristic_length();
    let index = current.and_then(|c| {
        modes
            .real
            .iter()
            .position(|m| m.pose.distance(c, lc) < 1e-8 * lc.max(1.0))
    });
    Ok((modes, index, wall))
}

/// Columns of [`mode_rows`]: the platform frame's origin, its rotation matrix row by row,
/// the condition number, and 1 on the mode nearest the tracked pose (0 elsewhere).
/// `assembly_modes.csv` puts the mode's number first ([`write_modes`]).
pub const MODE_COLUMNS: [&str; 14] = [
    "x", "y", "z", "r11", "r12", "r13", "r21", "r22", "r23", "r31", "r32", "r33", "cond", "current",
];

/// One row per real mode ([`MODE_COLUMNS`]).
pub fn mode_rows(modes: &Modes, current: Option<usize>) -> Vec<Vec<f64>> {
    modes
        .real
        .iter()
        .enumerate()
        .map(|(k, m)| {
            let mut row: Vec<f64> = m.pose.position.iter().copied().collect();
            row.extend((0..9).map(|i| m.pose.rotation[(i / 3, i % 3)]));
            row.push(m.condition);
            row.push(if current == Some(k) { 1.0 } else { 0.0 });
            row
        })
        .collect()
}

/// `assembly_modes.csv`: one row per real mode, its number (from 1, as the summary's
/// "current mode k of n" counts) in the `mode` column, then [`MODE_COLUMNS`].
pub fn write_modes(dir: &Path, modes: &Modes, current: Option<usize>) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let path = dir.join("assembly_modes.csv");
    let rows = mode_rows(modes, current).into_iter().enumerate();
    write(
        &path,
        &format!("mode,{}", MODE_COLUMNS.join(",")),
        rows.map(|(k, row)| std::iter::once((k + 1) as f64).chain(row).collect()),
    )
    .map_err(|e| format!("cannot write {}: {e}", path.display()))
}

/// The assembly modes at one time of the driver motion.
#[derive(Debug, Clone, Copy)]
pub struct Sample {
    pub t: f64,
    pub real: usize,
    pub complex: usize,
    /// Condition number of the tracked (current) mode.
    pub condition: f64,
    /// Distance ([`Pose::distance`] with the platform's radius) to the nearest other real
    /// mode (m), and that mode's condition number.
    pub nearest: f64,
    pub nearest_condition: f64,
}

/// Tracks the pose along the drivers' motion over `[0, t_end]` and finds every assembly mode
/// at `samples + 1` equally spaced times.
pub fn over_time<M: Mechanism + ?Sized>(
    p: &Platform<'_, M>,
    t_end: f64,
    samples: usize,
) -> Result<Vec<Sample>, Error> {
    let legs = p.legs();
    let lc = legs.characteristic_length();
    let mut pose = p.pose(p.q0())?;
    let mut out = Vec::with_capacity(samples + 1);
    for k in 0..=samples {
        let t = t_end * k as f64 / samples as f64;
        if k > 0 {
            let t_prev = t_end * (k - 1) as f64 / samples as f64;
            let lengths = |t: f64| p.lengths_at(t);
            pose = fk::track(legs, lengths, &pose, t_prev, t, TrackSettings::default())?
                .solution
                .pose;
        }
        let (modes, current, _) = all_modes(p, &p.lengths_at(t), Some(&pose))?;
        let Some(c) = current else {
            return Err(ScenarioError::Options(format!(
                "at t = {t:.6} s the tracked pose is not among the {} real assembly modes found",
                modes.real.len()
            )));
        };
        let nearest = modes
            .real
            .iter()
            .enumerate()
            .filter(|(j, _)| *j != c)
            .map(|(_, m)| (m.pose.distance(&pose, lc), m.condition))
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .unwrap_or((f64::INFINITY, f64::NAN));
        out.push(Sample {
            t,
            real: modes.real.len(),
            complex: modes.complex,
            condition: modes.real[c].condition,
            nearest: nearest.0,
            nearest_condition: nearest.1,
        });
    }
    Ok(out)
}

/// `assembly_modes_over_time.csv` (the figure is the command-line tool's).
pub fn write_over_time(dir: &Path, samples: &[Sample]) -> Result<Vec<String>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let csv = dir.join("assembly_modes_over_time.csv");
    write(
        &csv,
        "t,real_modes,complex_modes,cond,nearest_distance,nearest_cond",
        samples.iter().map(|s| {
            vec![
                s.t,
                s.real as f64,
                s.complex as f64,
                s.condition,
                s.nearest,
                s.nearest_condition,
            ]
        }),
    )
    .map_err(|e| format!("cannot write {}: {e}", csv.display()))?;
    Ok(vec!["assembly_modes_over_time.csv".to_string()])
}
