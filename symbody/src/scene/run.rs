//! Running a scene: the cheapest exact path is chosen from what the scene asks for
//! (docs/design.md, decision 23), then the run is made by the paper scenario's or the generic
//! recorder and restricted to the requested outputs.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;
use symbody_runtime::{
    driver_effort, free_motion, joint_wrench, Entry, FreeMotion, JointKind, Mechanism,
    MAX_ACCELERATION_MISMATCH, MAX_OUTPUT_CHANGE,
};

use super::{Files, PathRequest, Scene};
use crate::generic::{self, Observer, Prepared, Recording, Stopped};
use crate::scenario::{self, Reactions, Run, ScenarioError};

/// How a scene is solved, and why.
#[derive(Debug, Clone, PartialEq)]
pub enum PathChoice {
    /// No integration: kinematic analysis at each output time.
    Kinematic { free: FreeMotion },
    /// HHT-α integration.
    Integrate {
        /// Why the kinematic path was not taken (`None`: the scene asked for integration).
        reason: Option<String>,
        free: Option<FreeMotion>,
    },
}

impl PathChoice {
    /// One line for the run summary.
    pub fn describe(&self, info: &symbody_runtime::MechanismInfo) -> String {
        match self {
            PathChoice::Kinematic { free } if free.dof == 0 => {
                "kinematic (no integration): the drivers leave no free degree of freedom".into()
            }
            PathChoice::Kinematic { free } => format!(
                "kinematic (no integration): {} free DOF move only {} and carry no momentum \
                 (acceleration mismatch {:.1e}, output change {:.1e} when moved)",
                free.dof,
                body_list(info, &free.moved_bodies),
                free.acceleration_mismatch,
                free.output_change
            ),
            PathChoice::Integrate { reason: None, .. } => {
                "integrate (the scene asks for it)".into()
            }
            PathChoice::Integrate {
                reason: Some(r), ..
            } => format!("integrate: {r}"),
        }
    }
}

fn body_list(info: &symbody_runtime::MechanismInfo, bodies: &[usize]) -> String {
    let names: Vec<&str> = bodies.iter().map(|&b| info.bodies[b].name).collect();
    if names.len() > 4 {
        format!("{} bodies ({}, …)", names.len(), names[..3].join(", "))
    } else {
        names.join(", ")
    }
}

/// What a scene run produced.
#[derive(Debug, Clone)]
pub enum Outcome {
    /// The paper scenario's series (`files = "paper"`).
    Paper(Run),
    /// The generic tables, restricted to the requested outputs.
    Tables(Recording),
}

/// Decides how `scene` is solved: the kinematic path when the drivers leave no free
/// direction, or when every free direction moves no requested body, changes no requested
/// reaction or effort, and carries no momentum (measured by [`free_motion`] at the start).
pub fn choose_path(
    scene: &Scene,
    mech: &(dyn Mechanism + Sync),
) -> Result<PathChoice, ScenarioError> {
    if scene.path == PathRequest::Integrate {
        return Ok(PathChoice::Integrate {
            reason: None,
            free: None,
        });
    }
    let info = mech.info();
    let joints = requested_joints(scene, info);
    let drivers: Vec<usize> = if scene.efforts {
        (0..info.joints.len())
            .filter(|&j| info.joints[j].kind == JointKind::Driver)
            .collect()
    } else {
        Vec::new()
    };
    let mut outputs = |q: &[f64], _qd: &[f64], lambda: &[f64], phi_q: &[f64]| {
        let mut out = Vec::new();
        for &j in &joints {
            let w = joint_wrench(info, q, phi_q, lambda, j)?;
            out.extend(w.force.iter().chain(&w.moment));
        }
        for &j in &drivers {
            out.push(driver_effort(info, lambda, j)?);
        }
        Ok(out)
    };
    let free = free_motion(&mech, 0.0, info.q0, &mut outputs)?;
    let bodies = scene.poses.indices(info.bodies.len());
    if free.kinematic_is_exact(&bodies) {
        return Ok(PathChoice::Kinematic { free });
    }
    let reason = if free.acceleration_mismatch > MAX_ACCELERATION_MISMATCH {
        format!(
            "{} free DOF carry momentum (accelerations differ from the least-energy velocity's rate by {:.1e} > {:.0e})",
            free.dof, free.acceleration_mismatch, MAX_ACCELERATION_MISMATCH
        )
    } else if free.output_change > MAX_OUTPUT_CHANGE {
        format!(
            "moving along the {} free DOF changes the requested reactions by {:.1e} (relative) > {:.0e}",
            free.dof, free.output_change, MAX_OUTPUT_CHANGE
        )
    } else {
        let moved: Vec<usize> = bodies
            .iter()
            .copied()
            .filter(|b| free.moved_bodies.contains(b))
            .collect();
        format!(
            "the {} free DOF move requested bodies ({}); ask for fewer poses to skip integration",
            free.dof,
            body_list(info, &moved)
        )
    };
    if scene.path == PathRequest::Kinematic {
        return Err(ScenarioError::Options(format!(
            "{}: [solver] path = \"kinematic\" would not be exact: {reason}; use path = \"auto\" or \"integrate\"",
            scene.file
        )));
    }
    Ok(PathChoice::Integrate {
        reason: Some(reason),
        free: Some(free),
    })
}

/// Joints whose reactions the scene wants; the paper's files always need the legs' joints.
pub(crate) fn requested_joints(scene: &Scene, info: &symbody_runtime::MechanismInfo) -> Vec<usize> {
    let reacting: Vec<usize> = (0..info.joints.len())
        .filter(|&j| {
            !matches!(
                info.joints[j].kind,
                JointKind::Driver | JointKind::Normalization
            )
        })
        .collect();
    let mut joints: Vec<usize> = match &scene.reactions {
        super::Selection::All => reacting,
        other => other.indices(info.joints.len()),
    };
    if scene.files == Files::Paper {
        if let Ok(l) = scenario::Layout::find(info) {
            joints.extend(l.upper_joints.iter().chain(&l.lower_joints));
            joints.sort_unstable();
            joints.dedup();
        }
    }
    joints
}

/// Runs `scene`: chooses the path, runs it, and restricts the recording to the requested
/// outputs. The recorded wall time includes the choice.
pub fn run(scene: &Scene, entry: &Entry) -> Result<(PathChoice, Outcome), ScenarioError> {
    let (choice, outcome) = run_observed(scene, entry, &mut ())?;
    Ok((choice, outcome.map_err(|s| s.error)?))
}

/// [`run`], telling `obs` as it goes when the scene writes tables (`files = "paper"` runs
/// the paper scenario, which it does not see); the outcome of a run that stopped is what it
/// recorded, and why. The outer error: no path could be chosen.
pub fn run_observed(
    scene: &Scene,
    entry: &Entry,
    obs: &mut dyn Observer,
) -> Result<(PathChoice, Result<Outcome, Stopped>), ScenarioError> {
    let mech = generic::mechanism(entry, Some(scene.formulation))?;
    if scene.files == Files::Paper {
        return run_paper(scene, entry, mech);
    }
    // The choice is part of the run's cost: its wall time is added to the run's.
    let clock = Instant::now();
    let choice = choose_path(scene, mech)?;
    let choice_wall = clock.elapsed();
    let opts = options(scene);
    let mut obs = Prepared {
        prepare: |rec: &mut Recording| restrict(rec, scene),
        inner: obs,
    };
    let rec = match choice {
        PathChoice::Kinematic { .. } => generic::run_kinematic_observed(entry, &opts, &mut obs),
        PathChoice::Integrate { .. } => generic::run_observed(entry, &opts, &mut obs),
    };
    let outcome = rec.map(|mut rec| {
        rec.wall += choice_wall;
        Outcome::Tables(rec)
    });
    Ok((choice, outcome))
}

/// [`run_observed`] for `files = "paper"` (the paper scenario, which takes no observer). The
/// kinematic path starts on its own thread while this one makes the choice, which usually picks
/// it, and is given up when the choice is integration (two threads, not three: on two
/// cores a third took turns with the path); the wall time spans both. With `reduce`, the
/// path follows the generated reduced model where there is one.
fn run_paper(
    scene: &Scene,
    entry: &Entry,
    mech: &'static (dyn Mechanism + Sync),
) -> Result<(PathChoice, Result<Outcome, Stopped>), ScenarioError> {
    let clock = Instant::now();
    let opts = scenario::Options {
        formulation: scene.formulation,
        t_end: scene.t_end,
        step: scene.step,
        tolerances: scene.tolerances,
        alpha: scene.alpha,
        output_step: scene.output_step,
        reactions: Reactions::Recovered,
        newton_tolerance: None,
        states: scene.states,
    };
    let integrate = AtomicBool::new(scene.path == PathRequest::Integrate);
    let reduced = generic::reduced_model(entry, mech, scene.reduce);
    let (kinematic, choice) = scenario::kinematic_beside(mech, reduced, &opts, &integrate, || {
        let choice = choose_path(scene, mech);
        if !matches!(choice, Ok(PathChoice::Kinematic { .. })) {
            integrate.store(true, Ordering::Relaxed);
        }
        choice
    });
    let choice = choice?;
    let run = match choice {
        PathChoice::Kinematic { .. } => kinematic,
        PathChoice::Integrate { .. } => scenario::simulate_mechanism(mech, &opts),
    };
    let run = run.map(|mut run| {
        run.wall = clock.elapsed();
        Outcome::Paper(run)
    });
    Ok((choice, run.map_err(Stopped::from)))
}

/// Records only the outputs `scene` asks for (before the first output: nothing is
/// computed for the others).
fn restrict(rec: &mut Recording, scene: &Scene) {
    let info = rec.info;
    rec.bodies = scene.poses.indices(info.bodies.len());
    rec.velocities = scene.velocities;
    rec.accelerations = scene.accelerations;
    let keep = requested_joints(scene, info);
    rec.joints.retain(|j| keep.contains(j));
    if !scene.efforts {
        rec.drivers.clear();
    }
    rec.energy_table = scene.energy;
}

/// The options of a generic run of `scene`.
pub fn options(scene: &Scene) -> generic::Options {
    generic::Options {
        formulation: Some(scene.formulation),
        t_end: Some(scene.t_end),
        step: scene.step,
        tolerances: scene.tolerances,
        alpha: scene.alpha,
        output_step: scene.output_step,
        cross_singular: scene.cross_singular,
        newton_tolerance: None,
        reduce: scene.reduce,
        path_thread: scene.path_thread,
    }
}
