//! Scene files (`scenes/<name>.toml`, docs/design.md decision 23): which mechanism, over what
//! time, which outputs, and how to solve it — read and checked here ([`load`]), run by
//! [`run`].
//!
//! ```toml
//! mechanism = "stewart_6_6"     # a name from `symbody list`, or a mechanism file
//!                               # ("robot.toml", relative to the scene; interpreted)
//! formulation = "exact"         # optional: the mechanism's default
//!
//! [time]
//! end = 6.283185307179586       # s (default: the mechanism file's t_end)
//! output_step = 0.01            # s (default 0.01)
//!
//! [outputs]
//! poses = ["platform"]          # body names, or "all" (default) or "none"
//! velocities = false            # also the bodies' velocities in bodies.csv (default false)
//! accelerations = false         # and their accelerations (default false)
//! reactions = "all"             # joint names, or "all" (default) or "none"
//! efforts = true                # driver efforts (default true)
//! energy = true                 # energy table (default true)
//! files = "tables"              # "tables" (default) or "paper" (the paper scenario's files)
//!
//! [solver]
//! path = "auto"                 # "auto" (default), "kinematic" or "integrate"
//! step = 1e-3                   # HHT step when integrating (s); with rtol/atol the first
//!                               # step tried
//! rtol = 1e-6                   # step-size control (default off: the fixed step):
//! atol = 1e-6                   # relative and absolute local error on q and q̇; either
//!                               # alone sets both
//! alpha = 0.0                   # HHT α (default: as `symbody simulate`)
//! cross_singular_positions = false  # pass positions where rows are dependent for an instant
//!
//! [parameters]                  # optional: the mechanism file's parameters, other values
//! r_platform = 0.11             # (nothing to build: the compiled code takes the file's numbers)
//! ```

mod parse;
pub mod run;

pub use parse::load;
pub(crate) use run::requested_joints;
pub use run::{choose_path, options, run, run_observed, Outcome, PathChoice};

use symbody_runtime::{Entry, Formulation};

/// Whether `text` is a scene (TOML with a top-level `mechanism`) rather than a mechanism file.
pub fn is_scene(text: &str) -> bool {
    text.parse::<toml::Table>()
        .is_ok_and(|t| t.contains_key("mechanism"))
}

/// Which outputs a scene asks for: every one, none, or the named ones (indices into the
/// mechanism's bodies or joints, checked by [`load`]).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Selection {
    All,
    None,
    Only(Vec<usize>),
}

impl Selection {
    /// The selected indices out of `0..n`, ascending.
    pub fn indices(&self, n: usize) -> Vec<usize> {
        match self {
            Selection::All => (0..n).collect(),
            Selection::None => Vec::new(),
            Selection::Only(v) => v.clone(),
        }
    }
}

/// The files a scene writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Files {
    /// `bodies.csv`, `joints.csv`, `drivers.csv`, `energy.csv` (as `symbody simulate <name>`),
    /// restricted to the selected outputs.
    Tables,
    /// The paper scenario's `platform.csv`, `joint_forces.csv`, `actuators.csv` and figures
    /// (as `symbody simulate`); needs the paper's body and joint names.
    Paper,
}

/// How the scene is solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PathRequest {
    /// Kinematic when that is exact for the requested outputs, integration otherwise.
    Auto,
    /// Kinematic, or an error saying why it would not be exact.
    Kinematic,
    /// HHT-α integration.
    Integrate,
}

/// A checked scene.
#[derive(Debug, Clone)]
pub struct Scene {
    /// The file it was read from, for messages.
    pub file: String,
    /// Name of the mechanism.
    pub mechanism: &'static str,
    /// The mechanism: registered, or interpreted from the file the scene names (with the
    /// scene's parameters, if it sets any).
    pub entry: &'static Entry,
    /// The scene's `[parameters]`: the mechanism file's parameters it sets.
    pub parameters: Vec<(String, f64)>,
    /// The scene's `[study]`: the parameters `symbody study` varies.
    pub study: Option<crate::study::Study>,
    pub formulation: Formulation,
    pub t_end: f64,
    pub output_step: f64,
    /// Bodies whose poses are wanted (indices into `info.bodies`).
    pub poses: Selection,
    /// Whether `bodies.csv` has the selected bodies' velocities too.
    pub velocities: bool,
    /// Whether `bodies.csv` has the selected bodies' accelerations too.
    pub accelerations: bool,
    /// Joints whose reactions are wanted (indices into `info.joints`; never drivers or
    /// normalization rows).
    pub reactions: Selection,
    pub efforts: bool,
    pub energy: bool,
    pub files: Files,
    pub path: PathRequest,
    /// HHT step when integrating (s); with `tolerances`, the first step tried.
    pub step: f64,
    /// Step-size control `(rtol, atol)` when integrating (`[solver] rtol`, `atol`; either
    /// alone sets both); `None`: the fixed `step`.
    pub tolerances: Option<(f64, f64)>,
    /// HHT α when integrating.
    pub alpha: f64,
    /// Let the integrator pass singular positions ([`crate::generic::Options::cross_singular`]).
    pub cross_singular: bool,
    /// Integrate, or follow by the kinematic path, the generated reduced model where there
    /// is one ([`crate::generic::Options::reduce`]; `[solver] reduce = "auto"`).
    pub reduce: bool,
    /// Not from the file: [`crate::generic::Options::path_thread`] (on; a study turns it
    /// off for its rows).
    pub path_thread: bool,
    /// Not from the file: [`crate::scenario::Options::states`] for `files = "paper"` (off:
    /// the paper's files need none; `symbody run --html` turns it on for the viewer).
    pub states: bool,
}
