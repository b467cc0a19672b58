//! Mechanism description files (TOML): the raw serde schema, and its validation into a
//! [`Model`] with every name resolved, every vector checked, every joint frame expressed
//! in its bodies' local coordinates, and the initial poses computed.
//!
//! One submodule per kind of item: [`raw`] (the schema), `values` (numbers, vectors,
//! expressions and names), `bodies` (poses and placements), `joints`, `drivers`, `forces`.

mod bodies;
mod drivers;
mod forces;
mod joints;
pub mod raw;
mod values;

use crate::diag::{closest, Diagnostic, Errors, SourceMap};
use crate::expr::{Arena, Id};
use crate::geometry::{euler_matrix, quaternion_matrix, v3, M3, V3};
use raw::RawFile;
use std::collections::{BTreeSet, HashMap};
use std::ops::Range;

/// Dynamics formulation (docs/design.md, decision 7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Formulation {
    /// Diagonal `[m, m, m, Ixx, Iyy, Izz]` against Euler-angle accelerations (Euler bodies only).
    Paper,
    /// Mass matrix and velocity-dependent forces from the exact kinetic energy.
    Exact,
}

impl Formulation {
    pub fn name(self) -> &'static str {
        match self {
            Formulation::Paper => "paper",
            Formulation::Exact => "exact",
        }
    }
}

/// Rotation coordinates of a body (docs/design.md, decision 15).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rotation {
    /// `[θ, β, γ]` of `Rz(γ)·Ry(β)·Rx(θ)`.
    Euler,
    /// Euler parameters `[e0, e1, e2, e3]` with the row `eᵀe − 1 = 0`.
    Quaternion,
}

impl Rotation {
    pub fn n_coords(self) -> usize {
        match self {
            Rotation::Euler => 3,
            Rotation::Quaternion => 4,
        }
    }
    pub fn name(self) -> &'static str {
        match self {
            Rotation::Euler => "euler",
            Rotation::Quaternion => "quaternion",
        }
    }
    /// Names of the rotation coordinates.
    pub fn coord_names(self) -> &'static [&'static str] {
        match self {
            Rotation::Euler => &["theta", "beta", "gamma"],
            Rotation::Quaternion => &["e0", "e1", "e2", "e3"],
        }
    }
}

#[derive(Debug, Clone)]
pub struct Body {
    pub name: String,
    pub mass: f64,
    /// Principal inertias about the centre of mass, local axes.
    pub inertia: [f64; 3],
    /// The file's expressions for `mass` and each of `inertia` (`None`: a number), which
    /// [`crate::equations::build_parametric`] writes in the run-time parameters.
    pub mass_expr: Option<String>,
    pub inertia_expr: [Option<String>; 3],
    pub rotation: Rotation,
    /// Index of the body's first coordinate.
    pub offset: usize,
    /// Initial coordinates: `[X, Y, Z]` then the rotation coordinates.
    pub q0: Vec<f64>,
    /// Initial velocities (zero unless the file gives `velocity` / `angular_velocity`).
    pub qd0: Vec<f64>,
}

impl Body {
    pub fn n_coords(&self) -> usize {
        3 + self.rotation.n_coords()
    }
    /// Initial centre of mass.
    pub fn position(&self) -> V3 {
        V3::new(self.q0[0], self.q0[1], self.q0[2])
    }
    /// What keeps this body out of a planar model (Euler angles, turned about Z only and
    /// moving in its plane at the start), or `None`.
    pub fn off_plane(&self) -> Option<OffPlane> {
        if self.rotation != Rotation::Euler {
            return Some(OffPlane::NotEuler);
        }
        if self.q0[3] != 0.0 || self.q0[4] != 0.0 {
            return Some(OffPlane::Tilted);
        }
        // ż, θ̇ and β̇: at θ = β = 0 the angle rates are the angular velocity about X and Y.
        let moving = self.qd0[2..5].iter().any(|v| !(v.abs() <= 1e-12));
        moving.then_some(OffPlane::Moving)
    }

    /// Initial rotation matrix (local to global).
    pub fn orientation(&self) -> M3 {
        let c = &self.q0[3..];
        match self.rotation {
            Rotation::Euler => euler_matrix([c[0], c[1], c[2]]),
            Rotation::Quaternion => quaternion_matrix([c[0], c[1], c[2], c[3]]),
        }
    }
}

/// Why a body cannot be part of a planar model ([`Body::off_plane`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OffPlane {
    /// Its rotation coordinates are quaternions.
    NotEuler,
    /// It starts turned about X or Y.
    Tilted,
    /// It starts moving along Z or turning about X or Y.
    Moving,
}

/// A body reference in a joint: `None` is the ground.
pub type BodyRef = Option<usize>;

/// A joint frame fixed on a body: a point and two perpendicular unit axes, local to the
/// body (global for the ground). `z` is the joint axis, `x` the reference from which
/// joint angles are measured.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    pub body: BodyRef,
    pub point: [f64; 3],
    pub x: [f64; 3],
    pub z: [f64; 3],
}

/// Joint types (docs/design.md, decision 16): compositions of the spherical, dot-1, dot-2 and
/// distance primitives on the two frames.
#[derive(Debug, Clone, PartialEq)]
pub enum JointKind {
    Spherical,
    Revolute,
    /// Spherical plus `z1 · z2 = 0` (the two cross axes).
    Universal,
    Cylindrical,
    Prismatic,
    Fixed,
    /// `|p2 − p1| − length = 0`.
    Distance {
        length: f64,
    },
    /// The paper's prismatic: equal Euler angles and no motion of body 2's centre of mass
    /// across `axis` (local to body 1), paper eqs. 4–8.
    EulerPrismatic {
        axis: [f64; 3],
        /// The two cross-axis directions, local to body 1 (the paper's Rz(90°)v and Rx(90°)v).
        perp: [[f64; 3]; 2],
    },
}

impl JointKind {
    pub fn name(&self) -> &'static str {
        match self {
            JointKind::Spherical => "spherical",
            JointKind::Revolute => "revolute",
            JointKind::Universal => "universal",
            JointKind::Cylindrical => "cylindrical",
            JointKind::Prismatic => "prismatic",
            JointKind::Fixed => "fixed",
            JointKind::Distance { .. } => "distance",
            JointKind::EulerPrismatic { .. } => "euler_prismatic",
        }
    }
    pub fn rows(&self) -> usize {
        match self {
            JointKind::Spherical => 3,
            JointKind::Revolute | JointKind::Prismatic | JointKind::EulerPrismatic { .. } => 5,
            JointKind::Universal | JointKind::Cylindrical => 4,
            JointKind::Fixed => 6,
            JointKind::Distance { .. } => 1,
        }
    }
    /// Whether the joint has a relative rotation angle about `z` (drivers, torsion springs).
    pub fn has_angle(&self) -> bool {
        matches!(self, JointKind::Revolute | JointKind::Cylindrical)
    }
    /// Whether the joint has a sliding distance along `z`.
    pub fn has_slide(&self) -> bool {
        matches!(
            self,
            JointKind::Prismatic | JointKind::Cylindrical | JointKind::EulerPrismatic { .. }
        )
    }
}

#[derive(Debug, Clone)]
pub struct Joint {
    pub name: String,
    pub kind: JointKind,
    pub f1: Frame,
    pub f2: Frame,
}

impl Joint {
    pub fn bodies(&self) -> (BodyRef, BodyRef) {
        (self.f1.body, self.f2.body)
    }
    pub fn rows(&self) -> usize {
        self.kind.rows()
    }
}

/// What a driver prescribes (docs/design.md, decision 17).
#[derive(Debug, Clone, PartialEq)]
pub enum DriverTarget {
    /// The angle of joint `0` about its axis, from `x1` to `x2`: row `sin(f − θ)`.
    JointAngle(usize),
    /// The distance `z1 · (p2 − p1)` along joint `0`'s axis (for the paper's prismatic:
    /// `axis · (r2 − r1)` between the centres of mass).
    JointSlide(usize),
    /// Body coordinate `coord` (index within the body's coordinates) of body `body`.
    BodyCoordinate { body: usize, coord: usize },
    /// The distance between two points.
    PointDistance { f1: Frame, f2: Frame },
}

#[derive(Debug, Clone)]
pub struct Driver {
    pub name: String,
    pub target: DriverTarget,
    /// The prescribed value as a function of `t`, in [`Model::arena`].
    pub value: Id,
    /// The source text of the value, for the generated file's header.
    pub source: String,
    /// The measured coordinate at the initial configuration (`initial` in the expression).
    pub initial: f64,
}

impl Driver {
    /// Whether the effort is a torque (or a generalized force on an Euler angle).
    pub fn is_angular(&self) -> bool {
        match self.target {
            DriverTarget::JointAngle(_) => true,
            DriverTarget::BodyCoordinate { coord, .. } => coord >= 3,
            _ => false,
        }
    }
}

/// Applied force elements (docs/design.md, decision 20).
#[derive(Debug, Clone)]
pub enum ForceKind {
    /// Spring–damper–actuator between two points: tension `k(ℓ − ℓ0) + c ℓ̇ − f(t)`.
    Spring {
        f1: Frame,
        f2: Frame,
        stiffness: f64,
        damping: f64,
        free_length: f64,
        /// Actuator force pushing the points apart, in `t`.
        actuator: Id,
    },
    /// Rotational spring–damper–actuator in revolute (or cylindrical) joint `joint`:
    /// torque on body 2 about the axis `−k(θ − θ0) − c θ̇ + τ(t)`.
    Torsion {
        joint: usize,
        stiffness: f64,
        damping: f64,
        free_angle: f64,
        torque: Id,
    },
    /// A force (three expressions in `t`) at a point of a body, global or body axes.
    Force {
        at: Frame,
        value: [Id; 3],
        body_axes: bool,
    },
    /// A torque (three expressions in `t`) on a body, global or body axes.
    Torque {
        body: usize,
        value: [Id; 3],
        body_axes: bool,
    },
}

#[derive(Debug, Clone)]
pub struct Force {
    pub name: String,
    pub kind: ForceKind,
    /// The file's expressions for a spring's or torsion spring's `stiffness` and `damping`
    /// (`None`: a number or absent), which [`crate::equations::build_parametric`] writes in
    /// the run-time parameters.
    pub constants_expr: [Option<String>; 2],
}

/// A validated mechanism.
#[derive(Debug, Clone)]
pub struct Model {
    pub name: String,
    pub description: String,
    /// Formulations to generate; the first is the default.
    pub formulations: Vec<Formulation>,
    pub gravity: [f64; 3],
    /// Suggested simulation end time (s), from the file's `t_end`.
    pub t_end: f64,
    /// The file's `repair_initial_pose`: joints violated by more than a modelling tolerance
    /// are assembled with a warning instead of being an error ([`crate::assembly`]).
    pub repair_initial_pose: bool,
    /// The line of the file's `planar = true`: every body moves in its plane z = const and
    /// turns about Z only, so the generator also emits the model in (x, y, γ) per body
    /// ([`crate::reduce::planar`]).
    pub planar: Option<usize>,
    /// The file leaves `planar` out: the generator emits the planar model anyway when the
    /// mechanism turns out to be planar ([`Model::starts_planar`] and equal mobility).
    pub planar_unstated: bool,
    pub bodies: Vec<Body>,
    pub joints: Vec<Joint>,
    pub drivers: Vec<Driver>,
    pub forces: Vec<Force>,
    /// Holds the expressions in `t` (drivers, actuators, applied loads).
    pub arena: Arena,
    /// Line of each named item (body, joint, driver, force) in the file, for diagnostics
    /// after validation.
    pub lines: HashMap<String, usize>,
    /// The file's `[parameters]`, in name order, with the values used (overrides applied).
    pub parameters: Vec<Parameter>,
    /// The numbers of this model that the other parameters reach, as the equations read them
    /// (`Var::P` after the run-time parameters): set by [`crate::slots::mark`], empty before.
    pub data: Vec<f64>,
    /// Where those numbers are: their positions in [`crate::slots::numbers`].
    pub data_slots: Vec<u32>,
}

/// One entry of a file's `[parameters]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Parameter {
    pub name: String,
    /// The value this model was built with.
    pub value: f64,
    /// The file's expression, for a parameter derived from others (`None`: a number).
    pub expression: Option<String>,
    /// Whether the value was set from outside the file ([`load_with`]).
    pub overridden: bool,
    /// 1-based line in the file.
    pub line: usize,
    /// The items whose values depend on it, directly or through other parameters (e.g.
    /// ``body `crank` ``, ``joint `pin` ``), in name order.
    pub affects: Vec<String>,
    /// A number (not derived) that reaches only bodies' masses and principal inertias (none
    /// of them zero) and springs' stiffness and damping: no decision of the generator
    /// (assembly, rank, reduction, platform) depends on it, so the generated code takes it at
    /// run time (`Var::P`, docs/design.md, decision 35).
    pub run_time: bool,
}

impl Model {
    pub fn n_coords(&self) -> usize {
        self.bodies.iter().map(Body::n_coords).sum()
    }
    pub fn q0(&self) -> Vec<f64> {
        self.bodies.iter().flat_map(|b| b.q0.clone()).collect()
    }
    pub fn qd0(&self) -> Vec<f64> {
        self.bodies.iter().flat_map(|b| b.qd0.clone()).collect()
    }
    /// Every body in Euler angles, turned about Z only and moving in its plane at the start,
    /// and gravity in the XY plane: what `planar = true` requires of the file.
    pub fn starts_planar(&self) -> bool {
        self.gravity[2] == 0.0 && self.bodies.iter().all(|b| b.off_plane().is_none())
    }

    /// The parameters the generated code takes at run time, in order (`Var::P(i)` is the
    /// `i`-th): [`Parameter::run_time`].
    pub fn run_time_parameters(&self) -> Vec<&Parameter> {
        self.parameters.iter().filter(|p| p.run_time).collect()
    }

    /// `p` at this model's values: the run-time parameters' values in their order, then
    /// [`Model::data`].
    pub fn run_time_values(&self) -> Vec<f64> {
        let named = self.run_time_parameters().into_iter().map(|p| p.value);
        named.chain(self.data.iter().copied()).collect()
    }

    pub fn body_name(&self, b: BodyRef) -> &str {
        b.map_or("ground", |i| self.bodies[i].name.as_str())
    }
}

/// Reads and validates a mechanism file. `file` is only used in messages.
pub fn load(file: &str, text: &str) -> Result<Model, Errors> {
    load_with(file, text, &[])
}

/// [`load`] with some of the file's parameters set to other values, as if the file said so:
/// everything that depends on them follows (derived parameters, masses, points, the initial
/// pose, drivers' and loads' constants). An unknown name or a value that is not finite is an
/// error naming the parameter.
pub fn load_with(file: &str, text: &str, overrides: &[(String, f64)]) -> Result<Model, Errors> {
    let map = SourceMap { file, text };
    let raw: RawFile = toml::from_str(text).map_err(|e| {
        let span = e.span().unwrap_or(0..0);
        let message = e.message().trim().to_string();
        let help = crate::diag::toml_error_help(&message);
        Errors(vec![map.diag(span, "the file", message, help)])
    })?;
    let mut v = Validator {
        map,
        errors: Vec::new(),
        params: HashMap::new(),
        values: HashMap::new(),
        uses: HashMap::new(),
        fields: HashMap::new(),
        reads: HashMap::new(),
        error_spans: Vec::new(),
        arena: Arena::new(),
    };
    let model = v.model(raw, overrides);
    match model {
        Some(m) if v.errors.is_empty() => Ok(m),
        _ => {
            // An error at a value that reads a parameter set from outside the file (directly
            // or through derived ones), or in a derived parameter, follows from that setting.
            let set: Vec<(String, f64, Vec<bool>)> = overrides
                .iter()
                .filter(|(k, _)| v.params.contains_key(k))
                .map(|(k, x)| {
                    let reached = v.reached(k);
                    let mut params = vec![k.clone()];
                    params.extend(reached.iter().filter_map(|i| {
                        Some(
                            i.strip_prefix("parameter `")?
                                .strip_suffix('`')?
                                .to_string(),
                        )
                    }));
                    let spans: Vec<&Range<usize>> = params
                        .iter()
                        .flat_map(|p| v.reads.get(p))
                        .flatten()
                        .collect();
                    let hit = v
                        .errors
                        .iter()
                        .zip(&v.error_spans)
                        .map(|(d, e)| {
                            reached.contains(&d.item)
                                && (d.item.starts_with("parameter `")
                                    || spans.iter().any(|r| {
                                        r.start < e.end.max(e.start + 1) && e.start < r.end
                                    }))
                        })
                        .collect();
                    (k.clone(), *x, hit)
                })
                .collect();
            let mut errors = Errors(std::mem::take(&mut v.errors));
            blame(&mut errors, &set);
            Err(errors)
        }
    }
}

/// `x` as a person would write it: plain in the usual range, with an exponent outside it.
pub(crate) fn shown(x: f64) -> String {
    if x == 0.0 || !x.is_finite() || (1e-4..1e6).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Adds to each diagnostic that follows from a parameter set from outside the file (`set`:
/// name, value, and for each diagnostic whether it follows from it) which of them: the error
/// is reported at the file's item, but the value that broke it is not in the file.
pub(crate) fn blame(errors: &mut Errors, set: &[(String, f64, Vec<bool>)]) {
    for (i, d) in errors.0.iter_mut().enumerate() {
        let mut culprits: Vec<String> = Vec::new();
        // The last setting of a name is the one used.
        for (name, value, hit) in set.iter().rev() {
            if hit[i]
                && !culprits
                    .iter()
                    .any(|c| c.starts_with(&format!("`{name}` =")))
            {
                culprits.push(format!("`{name}` = {}", shown(*value)));
            }
        }
        if !culprits.is_empty() {
            culprits.reverse();
            let s = if culprits.len() == 1 { "" } else { "s" };
            let note = format!(
                "this depends on parameter{s} {} as set from outside the file",
                culprits.join(", ")
            );
            d.help = if d.help.is_empty() {
                note
            } else {
                format!("{note}; {}", d.help)
            };
        }
    }
}

/// State of a parameter during resolution, for cycle detection.
enum ParamState {
    Busy,
    Done(f64),
}

struct Validator<'a> {
    map: SourceMap<'a>,
    errors: Vec<Diagnostic>,
    params: HashMap<String, (Range<usize>, raw::Scalar)>,
    values: HashMap<String, ParamState>,
    /// For each parameter, the items whose fields read it directly.
    uses: HashMap<String, BTreeSet<String>>,
    /// For each parameter, the `(item, field)` pairs that read it directly.
    fields: HashMap<String, BTreeSet<(String, String)>>,
    /// For each parameter, where the values that read it directly are in the file.
    reads: HashMap<String, Vec<Range<usize>>>,
    /// Where each of `errors` is in the file.
    error_spans: Vec<Range<usize>>,
    arena: Arena,
}

impl Validator<'_> {
    fn err(&mut self, span: Range<usize>, item: &str, message: String, help: &str) {
        let d = self.map.diag(span.clone(), item, message, help);
        self.errors.push(d);
        self.error_spans.push(span);
    }

    fn model(&mut self, raw: RawFile, overrides: &[(String, f64)]) -> Option<Model> {
        let name = self.mechanism_name(&raw)?;
        for (k, val) in &raw.parameters {
            self.params
                .insert(k.get_ref().clone(), (k.span(), val.get_ref().clone()));
        }
        self.override_parameters(&raw, overrides);
        // Resolve every parameter up front so errors in unused ones are reported too.
        for k in raw.parameters.keys() {
            self.param_value(k.get_ref());
        }
        let formulations = self.formulations(raw.formulations.as_ref());
        let gravity = match &raw.gravity {
            Some(g) => self.vec3(g, "the file", "gravity"),
            None => Some([0.0, -9.81, 0.0]),
        };
        let t_end = match &raw.t_end {
            Some(t) => self
                .scalar(t, "the file", "t_end")
                .filter(|v| self.positive(*v, t.span(), "the file", "t_end")),
            None => Some(2.0),
        };
        let default_rotation = match &raw.rotation {
            Some(r) => self.rotation(r, "the file")?,
            None => Rotation::Quaternion,
        };

        let mut names: HashMap<String, Range<usize>> = HashMap::new();
        names.insert("ground".into(), 0..0);
        let (mut bodies, poses) = self.bodies(&raw.body, default_rotation, &mut names);
        let body_index: HashMap<String, usize> = bodies
            .iter()
            .enumerate()
            .map(|(i, b)| (b.name.clone(), i))
            .collect();
        let specs = self.joint_specs(&raw.joint, &body_index, &mut names);
        if !self.errors.is_empty() {
            return None;
        }
        let up = match gravity {
            Some(g) if v3(g).norm() > 0.0 => -v3(g).normalize(),
            _ => V3::new(0.0, 1.0, 0.0),
        };
        self.place_bodies(&mut bodies, &poses, &specs, up);
        self.initial_velocities(&mut bodies, &poses);
        if !self.errors.is_empty() {
            return None;
        }
        let joints = self.joints(&specs, &bodies);
        if !self.errors.is_empty() {
            return None;
        }
        let drivers = self.drivers(&raw.driver, &joints, &bodies, &body_index, &mut names);
        let forces = self.forces(&raw.force, &joints, &bodies, &body_index, &mut names);
        let formulations = formulations?;
        if formulations.contains(&Formulation::Paper) {
            if let Some(b) = bodies.iter().find(|b| b.rotation != Rotation::Euler) {
                let span = raw.formulations.as_ref().map_or(0..0, |f| f.span());
                self.err(
                    span,
                    "`formulations`",
                    format!(
                        "the `paper` formulation needs Euler-angle bodies, but body `{}` uses {}",
                        b.name,
                        b.rotation.name()
                    ),
                    "use `formulations = [\"exact\"]`, or `rotation = \"euler\"` for every body",
                );
            }
        }
        if let Some(p) = raw.planar.as_ref().filter(|p| *p.get_ref()) {
            self.planar_bodies(&bodies, p.span(), &names);
            if gravity.is_some_and(|g| g[2] != 0.0) {
                let span = raw.gravity.as_ref().map_or(p.span(), |g| g.span());
                self.err(
                    span,
                    "`gravity`",
                    "`planar = true`, but gravity has a component along Z, out of the plane".into(),
                    "a planar mechanism moves in planes z = const: give gravity in the XY plane",
                );
            }
        }
        if !self.errors.is_empty() {
            return None;
        }
        Some(Model {
            name,
            description: raw.description.clone().unwrap_or_default(),
            formulations,
            gravity: gravity?,
            t_end: t_end?,
            repair_initial_pose: raw.repair_initial_pose.unwrap_or(false),
            planar: raw
                .planar
                .as_ref()
                .filter(|p| *p.get_ref())
                .map(|p| self.map.position(p.span().start).0),
            planar_unstated: raw.planar.is_none(),
            bodies,
            lines: names
                .iter()
                .map(|(k, span)| (k.clone(), self.map.position(span.start).0))
                .collect(),
            joints,
            drivers: drivers?,
            forces: forces?,
            arena: std::mem::take(&mut self.arena),
            parameters: self.parameters(&raw, overrides),
            data: Vec::new(),
            data_slots: Vec::new(),
        })
        .map(|mut m| {
            // A zero inertia decides the structure (a semi-definite mass matrix, checked at
            // the assembled pose): the parameters that reach it stay compile-time numbers.
            let zero: Vec<String> = m
                .bodies
                .iter()
                .filter(|b| b.inertia.contains(&0.0))
                .map(|b| format!("body `{}`", b.name))
                .collect();
            for p in &mut m.parameters {
                if p.affects.iter().any(|i| zero.contains(i)) {
                    p.run_time = false;
                }
            }
            m
        })
    }

    /// Replaces the values of overridden parameters (before any is resolved).
    fn override_parameters(&mut self, raw: &RawFile, overrides: &[(String, f64)]) {
        // Errors point at the file's parameters table (or its start, without one).
        let table = raw
            .parameters
            .keys()
            .map(|k| k.span())
            .min_by_key(|s| s.start)
            .unwrap_or(0..0);
        let mut known: Vec<&str> = raw
            .parameters
            .keys()
            .map(|k| k.get_ref().as_str())
            .collect();
        known.sort();
        for (name, value) in overrides {
            let item = format!("parameter `{name}`");
            match self.params.get_mut(name) {
                None => {
                    let close = closest(name, known.iter().copied())
                        .map(|c| format!("did you mean `{c}`? "))
                        .unwrap_or_default();
                    let list = if known.is_empty() {
                        "the file has no [parameters]".to_string()
                    } else {
                        format!("the file's parameters: {}", known.join(", "))
                    };
                    self.err(
                        table.clone(),
                        &item,
                        format!("no parameter `{name}` to set"),
                        &format!("{close}{list}"),
                    );
                }
                Some((span, _)) if !value.is_finite() => {
                    let span = span.clone();
                    self.err(
                        span,
                        &item,
                        format!("parameter `{name}` set to {value}"),
                        "give a finite number",
                    );
                }
                Some((_, v)) => *v = raw::Scalar::Float(*value),
            }
        }
    }

    /// `planar = true` (at `span`): each body in Euler angles, turned about Z only and moving
    /// in its plane at the start, so that pinning z, θ and β at their initial values leaves
    /// the motion unchanged (the generator checks the mobility too).
    fn planar_bodies(
        &mut self,
        bodies: &[Body],
        span: Range<usize>,
        names: &HashMap<String, Range<usize>>,
    ) {
        for b in bodies {
            let Some(off) = b.off_plane() else { continue };
            let at = names.get(&b.name).cloned().unwrap_or_else(|| span.clone());
            let (message, help) = match off {
                OffPlane::NotEuler => (
                    format!(
                        "`planar = true` needs Euler angles, but this body uses {}",
                        b.rotation.name()
                    ),
                    "add `rotation = \"euler\"` at the top of the file (or on the body)",
                ),
                OffPlane::Tilted => (
                    format!(
                        "`planar = true`, but the body starts tilted out of the plane (θ = {}, β = {})",
                        b.q0[3], b.q0[4]
                    ),
                    "a planar body turns about Z only: give its orientation as `angles = [0, 0, γ]`",
                ),
                OffPlane::Moving => (
                    format!(
                        "`planar = true`, but the body starts moving out of the plane (ż = {}, \
                         angular velocity about X or Y {}, {})",
                        b.qd0[2], b.qd0[3], b.qd0[4]
                    ),
                    "give `velocity` with z = 0 and `angular_velocity` along Z only",
                ),
            };
            self.err(at, &format!("body `{}`", b.name), message, help);
        }
    }

    /// The items that read parameter `name`, directly or through any chain of parameters
    /// (those parameters included, as ``parameter `q` ``).
    fn reached(&self, name: &str) -> BTreeSet<String> {
        let mut items = BTreeSet::new();
        let mut todo = vec![name.to_string()];
        let mut seen = BTreeSet::new();
        while let Some(p) = todo.pop() {
            if !seen.insert(p.clone()) {
                continue;
            }
            for item in self.uses.get(&p).into_iter().flatten() {
                if let Some(q) = item
                    .strip_prefix("parameter `")
                    .and_then(|s| s.strip_suffix('`'))
                {
                    todo.push(q.to_string());
                }
                items.insert(item.clone());
            }
        }
        items
    }

    /// Whether every field that reads `name`, directly or through derived parameters, is a
    /// body's `mass` or `inertia` or a force's `stiffness` or `damping` (and one does).
    fn reaches_run_time_fields_only(&self, name: &str) -> bool {
        let mut todo = vec![name.to_string()];
        let mut seen = BTreeSet::new();
        let mut any = false;
        while let Some(p) = todo.pop() {
            if !seen.insert(p.clone()) {
                continue;
            }
            for (item, field) in self.fields.get(&p).into_iter().flatten() {
                if let Some(q) = item
                    .strip_prefix("parameter `")
                    .and_then(|s| s.strip_suffix('`'))
                {
                    todo.push(q.to_string());
                } else if (item.starts_with("body `") && (field == "mass" || field == "inertia"))
                    || (item.starts_with("force `") && (field == "stiffness" || field == "damping"))
                {
                    any = true;
                } else {
                    return false;
                }
            }
        }
        any
    }

    /// The parameters as resolved, each with the items it affects through any chain of
    /// parameters.
    fn parameters(&self, raw: &RawFile, overrides: &[(String, f64)]) -> Vec<Parameter> {
        raw.parameters
            .iter()
            .map(|(k, v)| {
                let name = k.get_ref().clone();
                let items: BTreeSet<String> = self
                    .reached(&name)
                    .into_iter()
                    .filter(|i| !i.starts_with("parameter `"))
                    .collect();
                let value = match self.values.get(&name) {
                    Some(ParamState::Done(x)) => *x,
                    _ => f64::NAN,
                };
                Parameter {
                    expression: match v.get_ref() {
                        raw::Scalar::Expr(e) => Some(e.clone()),
                        _ => None,
                    },
                    overridden: overrides.iter().any(|(o, _)| *o == name),
                    line: self.map.position(k.span().start).0,
                    affects: items.into_iter().collect(),
                    // A derived parameter set from outside is a number like the others
                    // (its value stands, decision 35), so that its derivative is seen.
                    run_time: (matches!(v.get_ref(), raw::Scalar::Int(_) | raw::Scalar::Float(_))
                        || overrides.iter().any(|(o, _)| *o == name))
                        && self.reaches_run_time_fields_only(&name),
                    name,
                    value,
                }
            })
            .collect()
    }

    fn mechanism_name(&mut self, raw: &RawFile) -> Option<String> {
        match &raw.name {
            Some(n) if values::is_identifier(n.get_ref()) && !values::is_keyword(n.get_ref()) => {
                Some(n.get_ref().clone())
            }
            Some(n) => {
                self.err(
                    n.span(),
                    "the file",
                    format!(
                        "mechanism name `{}` is not a valid identifier (or is a Rust keyword)",
                        n.get_ref()
                    ),
                    "use lowercase letters, digits and underscores, e.g. `stewart_6_6`",
                );
                None
            }
            None => {
                self.err(
                    0..0,
                    "the file",
                    "missing top-level `name`".into(),
                    "add `name = \"my_mechanism\"` at the top of the file",
                );
                None
            }
        }
    }

    fn rotation(&mut self, r: &toml::Spanned<String>, item: &str) -> Option<Rotation> {
        match r.get_ref().as_str() {
            "euler" => Some(Rotation::Euler),
            "quaternion" => Some(Rotation::Quaternion),
            other => {
                self.err(
                    r.span(),
                    item,
                    format!("unknown rotation coordinates `{other}`"),
                    "use \"quaternion\" (no singularity) or \"euler\" (Rz·Ry·Rx angles, singular at beta = ±90°)",
                );
                None
            }
        }
    }

    fn formulations(
        &mut self,
        raw: Option<&toml::Spanned<Vec<toml::Spanned<String>>>>,
    ) -> Option<Vec<Formulation>> {
        let Some(list) = raw else {
            return Some(vec![Formulation::Exact]);
        };
        let mut out = Vec::new();
        for f in list.get_ref() {
            let parsed = match f.get_ref().as_str() {
                "paper" => Formulation::Paper,
                "exact" => Formulation::Exact,
                other => {
                    self.err(
                        f.span(),
                        "`formulations`",
                        format!("unknown formulation `{other}`"),
                        "use \"paper\" or \"exact\"",
                    );
                    return None;
                }
            };
            if out.contains(&parsed) {
                self.err(
                    f.span(),
                    "`formulations`",
                    format!("formulation `{}` is listed twice", f.get_ref()),
                    "list each formulation once",
                );
                return None;
            }
            out.push(parsed);
        }
        if out.is_empty() {
            self.err(
                list.span(),
                "`formulations`",
                "`formulations` is empty".into(),
                "list at least one of \"exact\", \"paper\"",
            );
            return None;
        }
        Some(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const PENDULUM: &str = include_str!("../../mechanisms/simple_pendulum.toml");

    fn refused(set: &[(&str, f64)]) -> Errors {
        let set: Vec<(String, f64)> = set.iter().map(|(k, v)| (k.to_string(), *v)).collect();
        load_with("pendulum.toml", PENDULUM, &set).expect_err("refused")
    }

    /// A value set from outside the file that breaks an item is reported at the item, with
    /// the parameter it follows from (directly or through a derived parameter) named.
    #[test]
    fn a_bad_value_set_from_outside_names_its_parameter() {
        let e = refused(&[("m", -1.0)]);
        let d =
            e.0.iter()
                .find(|d| d.message.contains("mass must be positive"));
        let d = d.unwrap_or_else(|| panic!("{e}"));
        assert_eq!(d.item, "body `p1`");
        assert!(d.help.contains("parameter `m` = -1"), "{e}");
        // `ball` is derived from `m`: the inertia error names `m` as well.
        let e = refused(&[("l", 2.0), ("m", 1e-320), ("ball", -1.0)]);
        let d = e.0.iter().find(|d| d.message.contains("inertias"));
        let d = d.unwrap_or_else(|| panic!("{e}"));
        assert!(d.help.contains("parameter `ball` = -1"), "{e}");
        assert!(
            !d.help.contains("`l`"),
            "`l` does not reach the inertia: {e}"
        );
        // Through the derived `ball`, a negative `m` breaks the inertias too.
        let e = refused(&[("m", -1.0)]);
        let d = e.0.iter().find(|d| d.message.contains("inertias"));
        let d = d.unwrap_or_else(|| panic!("{e}"));
        assert!(d.help.contains("parameter `m` = -1 "), "{e}");
        // Extreme values are shown with an exponent.
        let e = refused(&[("m", -1e-320)]);
        assert!(e.0[0].message.ends_with("got -1e-320"), "{e}");
    }

    #[test]
    fn non_finite_and_unknown_values_are_refused_naming_the_parameter() {
        for v in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let e = refused(&[("l", v)]);
            assert!(
                e.0.iter().any(|d| d.item == "parameter `l`"
                    && d.message == format!("parameter `l` set to {v}")),
                "{e}"
            );
        }
        let e = refused(&[("bal", 1.0)]);
        assert!(
            e.0[0].message == "no parameter `bal` to set"
                && e.0[0].help.starts_with("did you mean `ball`?"),
            "{e}"
        );
        // Accepted values are used as given, the derived ones follow.
        let set = [("m".to_string(), 2.0)];
        let m = load_with("pendulum.toml", PENDULUM, &set).unwrap();
        assert_eq!(m.bodies[0].mass, 2.0);
        let ball = m.parameters.iter().find(|p| p.name == "ball").unwrap();
        assert_eq!(ball.value, 0.4 * 2.0 * 0.01 * 0.01);
        assert!(m.parameters.iter().any(|p| p.name == "m" && p.overridden));
    }
}
