//! Mechanism description files (TOML): the raw serde schema, and its validation into a
//! [`Model`] with every name resolved, every vector checked, and initial poses computed.

use crate::diag::{Diagnostic, Errors, SourceMap};
use crate::expr::{Arena, Id, Var};
use crate::parse::parse_expr;
use serde::Deserialize;
use std::collections::{BTreeMap, HashMap};
use std::ops::Range;
use toml::Spanned;

/// A number, or an expression string evaluated from parameters.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
enum Scalar {
    Int(i64),
    Float(f64),
    Expr(String),
}

type SVec = Spanned<Vec<Spanned<Scalar>>>;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    name: Option<Spanned<String>>,
    description: Option<String>,
    formulations: Option<Spanned<Vec<Spanned<String>>>>,
    gravity: Option<SVec>,
    #[serde(default)]
    parameters: BTreeMap<Spanned<String>, Spanned<Scalar>>,
    #[serde(default)]
    body: Vec<Spanned<RawBody>>,
    #[serde(default)]
    joint: Vec<Spanned<RawJoint>>,
    #[serde(default)]
    driver: Vec<Spanned<RawDriver>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBody {
    name: Option<Spanned<String>>,
    mass: Option<Spanned<Scalar>>,
    inertia: Option<SVec>,
    position: Option<SVec>,
    angles: Option<SVec>,
    placement: Option<Spanned<RawPlacement>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPlacement {
    from: Option<Spanned<String>>,
    to: Option<Spanned<String>>,
    offset_from_start: Option<Spanned<Scalar>>,
    offset_from_end: Option<Spanned<Scalar>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawJoint {
    name: Option<Spanned<String>>,
    #[serde(rename = "type")]
    kind: Option<Spanned<String>>,
    body1: Option<Spanned<String>>,
    body2: Option<Spanned<String>>,
    point1: Option<SVec>,
    point2: Option<SVec>,
    axis: Option<SVec>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDriver {
    name: Option<Spanned<String>>,
    joint: Option<Spanned<String>>,
    value: Option<Spanned<String>>,
}

/// Dynamics formulation (DESIGN.md decision 7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Formulation {
    /// Diagonal `[m, m, m, Ixx, Iyy, Izz]` against Euler-angle accelerations, gravity only.
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

#[derive(Debug, Clone)]
pub struct Body {
    pub name: String,
    pub mass: f64,
    pub inertia: [f64; 3],
    /// Initial `[X, Y, Z, θ, β, γ]`.
    pub q0: [f64; 6],
}

/// A body reference in a joint: `None` is the ground.
pub type BodyRef = Option<usize>;

#[derive(Debug, Clone)]
pub enum JointKind {
    /// `r1 + A1 p1 − r2 − A2 p2 = 0` (points local to their body; global for the ground).
    Spherical {
        body1: BodyRef,
        point1: [f64; 3],
        body2: BodyRef,
        point2: [f64; 3],
    },
    /// Body 2 slides along `axis` (local to body 1): equal Euler angles, and no motion of
    /// body 2's centre of mass across the axis (paper eqs. 4–8).
    Prismatic {
        body1: usize,
        body2: usize,
        axis: [f64; 3],
        /// The two cross-axis directions, local to body 1 (the paper's Rz(90°)v and Rx(90°)v).
        perp: [[f64; 3]; 2],
    },
}

#[derive(Debug, Clone)]
pub struct Joint {
    pub name: String,
    pub kind: JointKind,
}

impl Joint {
    pub fn bodies(&self) -> (BodyRef, BodyRef) {
        match self.kind {
            JointKind::Spherical { body1, body2, .. } => (body1, body2),
            JointKind::Prismatic { body1, body2, .. } => (Some(body1), Some(body2)),
        }
    }
    pub fn rows(&self) -> usize {
        match self.kind {
            JointKind::Spherical { .. } => 3,
            JointKind::Prismatic { .. } => 5,
        }
    }
}

/// A prescribed distance along a prismatic joint's axis: `axis·(r2 − r1) − value(t) = 0`.
#[derive(Debug, Clone)]
pub struct Driver {
    pub name: String,
    pub joint: usize,
    /// The prescribed distance as a function of `t`, in [`Model::arena`].
    pub value: Id,
    /// The source text of the value, for the generated file's header.
    pub source: String,
    /// The measured distance at the initial configuration (`initial` in the expression).
    pub initial: f64,
}

/// A validated mechanism.
#[derive(Debug, Clone)]
pub struct Model {
    pub name: String,
    pub description: String,
    /// Formulations to generate; the first is the default.
    pub formulations: Vec<Formulation>,
    pub gravity: [f64; 3],
    pub bodies: Vec<Body>,
    pub joints: Vec<Joint>,
    pub drivers: Vec<Driver>,
    /// Holds the driver expressions (in `t` only).
    pub arena: Arena,
}

impl Model {
    pub fn n_coords(&self) -> usize {
        6 * self.bodies.len()
    }
    pub fn n_constraints(&self) -> usize {
        self.joints.iter().map(Joint::rows).sum::<usize>() + self.drivers.len()
    }
    pub fn q0(&self) -> Vec<f64> {
        self.bodies.iter().flat_map(|b| b.q0).collect()
    }
}

/// Rotation matrix `Rz(γ)·Ry(β)·Rx(θ)` (local to global), row-major.
pub fn rotation(theta: f64, beta: f64, gamma: f64) -> [[f64; 3]; 3] {
    let (st, ct) = theta.sin_cos();
    let (sb, cb) = beta.sin_cos();
    let (sg, cg) = gamma.sin_cos();
    [
        [cg * cb, cg * sb * st - sg * ct, cg * sb * ct + sg * st],
        [sg * cb, sg * sb * st + cg * ct, sg * sb * ct - cg * st],
        [-sb, cb * st, cb * ct],
    ]
}

fn mat_vec(a: &[[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|i| a[i][0] * v[0] + a[i][1] * v[1] + a[i][2] * v[2])
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

fn scale(a: [f64; 3], k: f64) -> [f64; 3] {
    a.map(|x| x * k)
}

/// Euler angles `(θ, β, γ)` of a rotation matrix `Rz(γ)·Ry(β)·Rx(θ)`.
pub fn euler_angles(a: &[[f64; 3]; 3]) -> [f64; 3] {
    let beta = (-a[2][0]).atan2((a[0][0] * a[0][0] + a[1][0] * a[1][0]).sqrt());
    let theta = a[2][1].atan2(a[2][2]);
    let gamma = a[1][0].atan2(a[0][0]);
    [theta, beta, gamma]
}

/// Reads and validates a mechanism file. `file` is only used in messages.
pub fn load(file: &str, text: &str) -> Result<Model, Errors> {
    let map = SourceMap { file, text };
    let raw: RawFile = toml::from_str(text).map_err(|e| {
        let span = e.span().unwrap_or(0..0);
        let message = e.message().trim().to_string();
        let help = if message.contains("missing field") {
            "add the missing field"
        } else if message.contains("unknown field") {
            "check the spelling against the expected fields listed"
        } else {
            "fix the TOML syntax at this place"
        };
        Errors(vec![map.diag(span, "the file", message, help)])
    })?;
    let mut v = Validator {
        map,
        errors: Vec::new(),
        params: HashMap::new(),
        arena: Arena::new(),
    };
    let model = v.model(raw);
    match model {
        Some(m) if v.errors.is_empty() => Ok(m),
        _ => Err(Errors(v.errors)),
    }
}

struct Validator<'a> {
    map: SourceMap<'a>,
    errors: Vec<Diagnostic>,
    params: HashMap<String, (Range<usize>, Scalar)>,
    arena: Arena,
}

/// State of a parameter during resolution, for cycle detection.
enum ParamState {
    Busy,
    Done(f64),
}

impl Validator<'_> {
    fn err(&mut self, span: Range<usize>, item: &str, message: String, help: &str) {
        let d = self.map.diag(span, item, message, help);
        self.errors.push(d);
    }

    fn model(&mut self, raw: RawFile) -> Option<Model> {
        let name = match raw.name {
            Some(n) if is_identifier(n.get_ref()) && !KEYWORDS.contains(&n.get_ref().as_str()) => {
                n.into_inner()
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
                return None;
            }
            None => {
                self.err(
                    0..0,
                    "the file",
                    "missing top-level `name`".into(),
                    "add `name = \"my_mechanism\"` at the top of the file",
                );
                return None;
            }
        };
        for (k, val) in &raw.parameters {
            self.params
                .insert(k.get_ref().clone(), (k.span(), val.get_ref().clone()));
        }
        // Resolve every parameter up front so errors in unused ones are reported too.
        let mut cache: HashMap<String, ParamState> = HashMap::new();
        for (k, _) in raw.parameters.iter() {
            self.param_value(k.get_ref(), &mut cache);
        }
        let mut cache_values = cache;

        let formulations = self.formulations(raw.formulations);
        let gravity = match &raw.gravity {
            Some(g) => self.vec3(g, "the file", "gravity", &mut cache_values),
            None => Some([0.0, -9.81, 0.0]),
        };

        let mut names: HashMap<String, Range<usize>> = HashMap::new();
        names.insert("ground".into(), 0..0);
        let mut bodies = Vec::new();
        let mut placements = Vec::new();
        for (i, rb) in raw.body.iter().enumerate() {
            let span = rb.span();
            let rb = rb.get_ref();
            let Some(bname) = self.item_name(&rb.name, span.clone(), "body", i, &mut names) else {
                continue;
            };
            let item = format!("body `{bname}`");
            let mass =
                self.required_scalar(&rb.mass, &span, &item, "mass", "kg", &mut cache_values);
            if let Some(m) = mass.filter(|m| *m <= 0.0) {
                self.err(
                    rb.mass.as_ref().map_or(span.clone(), |s| s.span()),
                    &item,
                    format!("mass must be positive, got {m}"),
                    "give the body's mass in kg",
                );
            }
            let inertia = match &rb.inertia {
                Some(v) => self.vec3(v, &item, "inertia", &mut cache_values),
                None => {
                    self.err(
                        span.clone(),
                        &item,
                        format!("{item} is missing `inertia`"),
                        "add `inertia = [Ixx, Iyy, Izz]` (principal, about the centre of mass, kg·m²)",
                    );
                    None
                }
            };
            if let Some(inr) = inertia {
                if inr.iter().any(|x| *x <= 0.0) {
                    self.err(
                        rb.inertia.as_ref().unwrap().span(),
                        &item,
                        format!("inertias must be positive, got {inr:?}"),
                        "give principal inertias in kg·m²",
                    );
                }
            }
            let position = rb
                .position
                .as_ref()
                .and_then(|v| self.vec3(v, &item, "position", &mut cache_values));
            let angles = rb
                .angles
                .as_ref()
                .and_then(|v| self.vec3(v, &item, "angles", &mut cache_values));
            match (&rb.placement, &rb.position) {
                (Some(p), Some(_)) => self.err(
                    p.span(),
                    &item,
                    format!("{item} has both `position` and `placement`"),
                    "give either `position` and `angles`, or a `placement`",
                ),
                (None, None) => self.err(
                    span.clone(),
                    &item,
                    format!("{item} has no initial pose"),
                    "add `position = [x, y, z]` and `angles = [theta, beta, gamma]`, or a `[body.placement]`",
                ),
                _ => {}
            }
            let q0 = match (position, angles) {
                (Some(p), a) => [
                    p[0],
                    p[1],
                    p[2],
                    a.map_or(0.0, |a| a[0]),
                    a.map_or(0.0, |a| a[1]),
                    a.map_or(0.0, |a| a[2]),
                ],
                _ => [0.0; 6],
            };
            placements.push(rb.placement.as_ref());
            bodies.push(Body {
                name: bname,
                mass: mass.unwrap_or(1.0),
                inertia: inertia.unwrap_or([1.0; 3]),
                q0,
            });
        }
        if bodies.is_empty() && self.errors.is_empty() {
            self.err(
                0..0,
                "the file",
                "the mechanism has no bodies".into(),
                "add at least one `[[body]]`",
            );
        }
        let body_index: HashMap<String, usize> = bodies
            .iter()
            .enumerate()
            .map(|(i, b)| (b.name.clone(), i))
            .collect();

        let mut joints = Vec::new();
        let mut joint_spans = Vec::new();
        for (i, rj) in raw.joint.iter().enumerate() {
            let span = rj.span();
            let rj = rj.get_ref();
            let Some(jname) = self.item_name(&rj.name, span.clone(), "joint", i, &mut names) else {
                continue;
            };
            let item = format!("joint `{jname}`");
            if let Some(kind) = self.joint_kind(rj, &span, &item, &body_index, &mut cache_values) {
                joints.push(Joint { name: jname, kind });
                joint_spans.push(span);
            }
        }

        if !self.errors.is_empty() {
            return None;
        }
        let up = match gravity {
            Some(g) if norm(g) > 0.0 => scale(g, -1.0 / norm(g)),
            _ => [0.0, 1.0, 0.0],
        };
        self.place_bodies(&mut bodies, &placements, &joints, up, &mut cache_values);
        if !self.errors.is_empty() {
            return None;
        }

        let mut drivers = Vec::new();
        for (i, rd) in raw.driver.iter().enumerate() {
            let span = rd.span();
            let rd = rd.get_ref();
            let Some(dname) = self.item_name(&rd.name, span.clone(), "driver", i, &mut names)
            else {
                continue;
            };
            let item = format!("driver `{dname}`");
            if let Some(d) =
                self.driver(rd, dname, &span, &item, &joints, &bodies, &mut cache_values)
            {
                drivers.push(d);
            }
        }
        if !self.errors.is_empty() {
            return None;
        }
        Some(Model {
            name,
            description: raw.description.unwrap_or_default(),
            formulations: formulations?,
            gravity: gravity?,
            bodies,
            joints,
            drivers,
            arena: std::mem::take(&mut self.arena),
        })
    }

    fn formulations(
        &mut self,
        raw: Option<Spanned<Vec<Spanned<String>>>>,
    ) -> Option<Vec<Formulation>> {
        let Some(list) = raw else {
            return Some(vec![Formulation::Exact, Formulation::Paper]);
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

    /// Checks the name of the `index`-th item of `kind` and registers it.
    fn item_name(
        &mut self,
        name: &Option<Spanned<String>>,
        span: Range<usize>,
        kind: &str,
        index: usize,
        names: &mut HashMap<String, Range<usize>>,
    ) -> Option<String> {
        let Some(n) = name else {
            self.err(
                span,
                &format!("[[{kind}]] number {}", index + 1),
                format!("{kind} number {} has no `name`", index + 1),
                "add `name = \"...\"`; names are unique across bodies, joints and drivers",
            );
            return None;
        };
        let s = n.get_ref().clone();
        if !is_identifier(&s) {
            self.err(
                n.span(),
                &format!("{kind} `{s}`"),
                format!("{kind} name `{s}` is not a valid identifier"),
                "use letters, digits and underscores, starting with a letter",
            );
            return None;
        }
        if let Some(prev) = names.get(&s) {
            let (line, _) = self.map.position(prev.start);
            let help = if s == "ground" {
                "`ground` is reserved for the fixed frame; rename this item".to_string()
            } else {
                format!(
                    "names must be unique; the first `{s}` is on line {line}: rename one of them"
                )
            };
            self.err(
                n.span(),
                &format!("{kind} `{s}`"),
                format!("duplicate name `{s}`"),
                &help,
            );
            return None;
        }
        names.insert(s.clone(), n.span());
        Some(s)
    }

    fn joint_kind(
        &mut self,
        rj: &RawJoint,
        span: &Range<usize>,
        item: &str,
        body_index: &HashMap<String, usize>,
        cache: &mut HashMap<String, ParamState>,
    ) -> Option<JointKind> {
        let Some(kind) = &rj.kind else {
            self.err(
                span.clone(),
                item,
                format!("{item} is missing `type`"),
                "add `type = \"spherical\"` or `type = \"prismatic\"`",
            );
            return None;
        };
        let b1 = self.body_ref(&rj.body1, span, item, "body1", body_index);
        let b2 = self.body_ref(&rj.body2, span, item, "body2", body_index);
        match kind.get_ref().as_str() {
            "spherical" => {
                let p1 = self.required_vec3(&rj.point1, span, item, "point1", cache);
                let p2 = self.required_vec3(&rj.point2, span, item, "point2", cache);
                let (b1, b2) = (b1?, b2?);
                if b1 == b2 {
                    self.err(
                        span.clone(),
                        item,
                        format!("{item} connects a body to itself"),
                        "body1 and body2 must be different (one may be \"ground\")",
                    );
                    return None;
                }
                Some(JointKind::Spherical {
                    body1: b1,
                    point1: p1?,
                    body2: b2,
                    point2: p2?,
                })
            }
            "prismatic" => {
                let axis = match &rj.axis {
                    Some(v) => self.vec3(v, item, "axis", cache)?,
                    None => [0.0, 1.0, 0.0],
                };
                let (b1, b2) = (b1?, b2?);
                if b1 == b2 {
                    self.err(
                        span.clone(),
                        item,
                        format!("{item} connects a body to itself"),
                        "body1 and body2 must be different",
                    );
                    return None;
                }
                let (Some(b1), Some(b2)) = (b1, b2) else {
                    self.err(
                        span.clone(),
                        item,
                        format!("{item}: a prismatic joint to the ground is not supported yet"),
                        "connect two bodies; fix a body to the ground with other joints",
                    );
                    return None;
                };
                let Some(perp) = perpendiculars(axis) else {
                    self.err(
                        rj.axis.as_ref().map_or(span.clone(), |a| a.span()),
                        item,
                        format!("prismatic axis {axis:?} must be a coordinate axis of body1 (unit vector along x, y or z)"),
                        "set up body1's local frame so the sliding axis is one of its axes, e.g. `axis = [0, 1, 0]`",
                    );
                    return None;
                };
                Some(JointKind::Prismatic {
                    body1: b1,
                    body2: b2,
                    axis,
                    perp,
                })
            }
            other => {
                self.err(
                    kind.span(),
                    item,
                    format!("unknown joint type `{other}`"),
                    "supported types: \"spherical\", \"prismatic\"",
                );
                None
            }
        }
    }

    fn body_ref(
        &mut self,
        name: &Option<Spanned<String>>,
        span: &Range<usize>,
        item: &str,
        field: &str,
        body_index: &HashMap<String, usize>,
    ) -> Option<BodyRef> {
        let Some(n) = name else {
            self.err(
                span.clone(),
                item,
                format!("{item} is missing `{field}`"),
                &format!("add `{field} = \"<body name>\"` (or \"ground\")"),
            );
            return None;
        };
        if n.get_ref() == "ground" {
            return Some(None);
        }
        match body_index.get(n.get_ref()) {
            Some(&i) => Some(Some(i)),
            None => {
                let mut known: Vec<&String> = body_index.keys().collect();
                known.sort();
                let suggestion = closest(n.get_ref(), known.iter().map(|s| s.as_str()));
                let help = match suggestion {
                    Some(s) => format!("did you mean `{s}`? bodies are declared with [[body]]; `ground` is the fixed frame"),
                    None => "declare the body with [[body]], or use `ground`".to_string(),
                };
                self.err(
                    n.span(),
                    item,
                    format!("unknown body `{}` in `{field}`", n.get_ref()),
                    &help,
                );
                None
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn driver(
        &mut self,
        rd: &RawDriver,
        name: String,
        span: &Range<usize>,
        item: &str,
        joints: &[Joint],
        bodies: &[Body],
        cache: &mut HashMap<String, ParamState>,
    ) -> Option<Driver> {
        let Some(jname) = &rd.joint else {
            self.err(
                span.clone(),
                item,
                format!("{item} is missing `joint`"),
                "add `joint = \"<prismatic joint name>\"`",
            );
            return None;
        };
        let Some(ji) = joints.iter().position(|j| &j.name == jname.get_ref()) else {
            let suggestion = closest(jname.get_ref(), joints.iter().map(|j| j.name.as_str()));
            self.err(
                jname.span(),
                item,
                format!("unknown joint `{}`", jname.get_ref()),
                &match suggestion {
                    Some(s) => format!("did you mean `{s}`?"),
                    None => "name a prismatic joint declared with [[joint]]".to_string(),
                },
            );
            return None;
        };
        let JointKind::Prismatic {
            body1, body2, axis, ..
        } = joints[ji].kind
        else {
            self.err(
                jname.span(),
                item,
                format!("joint `{}` is not prismatic", jname.get_ref()),
                "drivers prescribe the distance along a prismatic joint's axis",
            );
            return None;
        };
        let Some(value) = &rd.value else {
            self.err(
                span.clone(),
                item,
                format!("{item} is missing `value`"),
                "add `value = \"initial + 0.02 * sin(t)\"` (a function of t; `initial` is the distance at the initial pose)",
            );
            return None;
        };
        let (b1, b2) = (&bodies[body1], &bodies[body2]);
        let a1 = rotation(b1.q0[3], b1.q0[4], b1.q0[5]);
        let d = sub(
            [b2.q0[0], b2.q0[1], b2.q0[2]],
            [b1.q0[0], b1.q0[1], b1.q0[2]],
        );
        let initial = dot(mat_vec(&a1, axis), d);
        let params: Vec<(String, f64)> = self
            .params
            .keys()
            .cloned()
            .collect::<Vec<_>>()
            .into_iter()
            .filter_map(|k| match cache.get(&k) {
                Some(ParamState::Done(v)) => Some((k, *v)),
                _ => None,
            })
            .collect();
        let mut resolve = |arena: &mut Arena, n: &str| -> Option<Id> {
            match n {
                "t" => Some(arena.var(Var::T)),
                "initial" => Some(arena.constant(initial)),
                _ => params
                    .iter()
                    .find(|(k, _)| k == n)
                    .map(|(_, v)| arena.constant(*v)),
            }
        };
        match parse_expr(&mut self.arena, value.get_ref(), &mut resolve) {
            Ok(id) if self.has_non_finite_constant(id) => {
                self.err(
                    value.span(),
                    item,
                    "`value` folds to an infinite or NaN constant".into(),
                    "check the expression for an overflow or a division by zero",
                );
                None
            }
            Ok(id) if !self.arena.eval(id, &|_| 0.0).is_finite() => {
                self.err(
                    value.span(),
                    item,
                    format!(
                        "`value` is not finite at t = 0 ({})",
                        self.arena.eval(id, &|_| 0.0)
                    ),
                    "check the expression for a division by zero or a domain error",
                );
                None
            }
            Ok(id) => Some(Driver {
                name,
                joint: ji,
                value: id,
                source: value.get_ref().clone(),
                initial,
            }),
            Err(e) => {
                self.err(value.span(), item, e.message, &e.help);
                None
            }
        }
    }

    /// Whether constant folding produced ±∞ or NaN anywhere under `id` (it cannot be emitted).
    fn has_non_finite_constant(&self, id: Id) -> bool {
        self.arena
            .reachable(&[id])
            .iter()
            .enumerate()
            .any(|(i, &m)| {
                m && self
                    .arena
                    .as_const(Id(i as u32))
                    .is_some_and(|c| !c.is_finite())
            })
    }

    /// Computes the poses of bodies given by a `placement`, in dependency order.
    fn place_bodies(
        &mut self,
        bodies: &mut [Body],
        placements: &[Option<&Spanned<RawPlacement>>],
        joints: &[Joint],
        up: [f64; 3],
        cache: &mut HashMap<String, ParamState>,
    ) {
        let mut placed: Vec<bool> = placements.iter().map(|p| p.is_none()).collect();
        loop {
            let mut progress = false;
            for bi in 0..bodies.len() {
                if placed[bi] {
                    continue;
                }
                let p = placements[bi].unwrap();
                let item = format!("body `{}`", bodies[bi].name);
                let (Some(from), Some(to)) = (&p.get_ref().from, &p.get_ref().to) else {
                    self.err(
                        p.span(),
                        &item,
                        format!("{item}: `placement` needs `from` and `to`"),
                        "name the joints at the two ends of the body's axis: `from = \"<joint>\"`, `to = \"<joint>\"`",
                    );
                    placed[bi] = true;
                    continue;
                };
                let mut ends = Vec::new();
                for end in [from, to] {
                    match self.joint_anchor(end, bi, joints, bodies, &placed, &item) {
                        Err(()) => {
                            placed[bi] = true;
                            break;
                        }
                        Ok(e) => ends.push(e),
                    }
                }
                if placed[bi] {
                    continue;
                }
                let (Some(start), Some(end)) = (ends[0], ends[1]) else {
                    continue; // waits for the other body to be placed
                };
                let axis_vec = sub(end, start);
                let len = norm(axis_vec);
                if len < 1e-12 {
                    self.err(
                        p.span(),
                        &item,
                        format!(
                            "{item}: the joints `{}` and `{}` coincide",
                            from.get_ref(),
                            to.get_ref()
                        ),
                        "a placement needs two distinct end points",
                    );
                    placed[bi] = true;
                    continue;
                }
                let y = scale(axis_vec, 1.0 / len);
                let raw = p.get_ref();
                let centre = match (&raw.offset_from_start, &raw.offset_from_end) {
                    (Some(s), None) => self
                        .scalar(s, &item, "offset_from_start", cache)
                        .map(|o| [0, 1, 2].map(|k| start[k] + o * y[k])),
                    (None, Some(s)) => self
                        .scalar(s, &item, "offset_from_end", cache)
                        .map(|o| [0, 1, 2].map(|k| end[k] - o * y[k])),
                    _ => {
                        self.err(
                            p.span(),
                            &item,
                            format!("{item}: `placement` needs exactly one of `offset_from_start`, `offset_from_end`"),
                            "give the distance of the centre of mass from one end along the axis",
                        );
                        None
                    }
                };
                let Some(centre) = centre else {
                    placed[bi] = true;
                    continue;
                };
                // Local x: the horizontal (perpendicular to gravity) outward direction, made
                // perpendicular to the axis, as paper-scenario.md defines the leg frames.
                let mid = scale([0, 1, 2].map(|k| start[k] + end[k]), 0.5);
                let horiz = sub(mid, scale(up, dot(mid, up)));
                let x_raw = sub(horiz, scale(y, dot(horiz, y)));
                let xn = norm(x_raw);
                if xn < 1e-9 {
                    self.err(
                        p.span(),
                        &item,
                        format!("{item}: the body's axis passes through the vertical line of the origin, so `outward` is undefined"),
                        "give the pose explicitly with `position` and `angles`",
                    );
                    placed[bi] = true;
                    continue;
                }
                let x = scale(x_raw, 1.0 / xn);
                let z = cross(x, y);
                let a = [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]];
                let ang = euler_angles(&a);
                bodies[bi].q0 = [centre[0], centre[1], centre[2], ang[0], ang[1], ang[2]];
                placed[bi] = true;
                progress = true;
            }
            if placed.iter().all(|p| *p) {
                return;
            }
            if !progress {
                for bi in (0..bodies.len()).filter(|b| !placed[*b]) {
                    let p = placements[bi].unwrap();
                    self.err(
                        p.span(),
                        &format!("body `{}`", bodies[bi].name),
                        "placement depends on bodies that are themselves placed from it (a cycle)"
                            .into(),
                        "give one body of the cycle an explicit `position` and `angles`",
                    );
                }
                return;
            }
        }
    }

    /// Global position of joint `name`'s point on its body other than `this`;
    /// `Ok(None)` when that body is not placed yet.
    fn joint_anchor(
        &mut self,
        name: &Spanned<String>,
        this: usize,
        joints: &[Joint],
        bodies: &[Body],
        placed: &[bool],
        item: &str,
    ) -> Result<Option<[f64; 3]>, ()> {
        let Some(j) = joints.iter().find(|j| &j.name == name.get_ref()) else {
            let suggestion = closest(name.get_ref(), joints.iter().map(|j| j.name.as_str()));
            self.err(
                name.span(),
                item,
                format!("unknown joint `{}` in `placement`", name.get_ref()),
                &match suggestion {
                    Some(s) => format!("did you mean `{s}`?"),
                    None => "name a spherical joint declared with [[joint]]".into(),
                },
            );
            return Err(());
        };
        let JointKind::Spherical {
            body1,
            point1,
            body2,
            point2,
        } = j.kind
        else {
            self.err(
                name.span(),
                item,
                format!("`placement` joint `{}` is not spherical", j.name),
                "place a body between two spherical joints",
            );
            return Err(());
        };
        // The joint's world position is read off whichever of its bodies (other than this
        // one) is already placed; the ground is always placed.
        for (body, point) in [(body1, point1), (body2, point2)] {
            match body {
                Some(b) if b == this => {}
                None => return Ok(Some(point)),
                Some(o) if placed[o] => {
                    let b = &bodies[o];
                    let a = rotation(b.q0[3], b.q0[4], b.q0[5]);
                    let w = mat_vec(&a, point);
                    return Ok(Some([b.q0[0] + w[0], b.q0[1] + w[1], b.q0[2] + w[2]]));
                }
                Some(_) => {}
            }
        }
        Ok(None)
    }

    fn required_scalar(
        &mut self,
        s: &Option<Spanned<Scalar>>,
        span: &Range<usize>,
        item: &str,
        field: &str,
        unit: &str,
        cache: &mut HashMap<String, ParamState>,
    ) -> Option<f64> {
        match s {
            Some(s) => self.scalar(s, item, field, cache),
            None => {
                self.err(
                    span.clone(),
                    item,
                    format!("{item} is missing `{field}`"),
                    &format!("add `{field} = <value in {unit}>`"),
                );
                None
            }
        }
    }

    fn required_vec3(
        &mut self,
        v: &Option<SVec>,
        span: &Range<usize>,
        item: &str,
        field: &str,
        cache: &mut HashMap<String, ParamState>,
    ) -> Option<[f64; 3]> {
        match v {
            Some(v) => self.vec3(v, item, field, cache),
            None => {
                self.err(
                    span.clone(),
                    item,
                    format!("{item} is missing `{field}`"),
                    &format!("add `{field} = [x, y, z]`"),
                );
                None
            }
        }
    }

    fn vec3(
        &mut self,
        v: &SVec,
        item: &str,
        field: &str,
        cache: &mut HashMap<String, ParamState>,
    ) -> Option<[f64; 3]> {
        let comps = v.get_ref();
        if comps.len() != 3 {
            self.err(
                v.span(),
                item,
                format!(
                    "`{field}` has {} component{}, expected 3",
                    comps.len(),
                    if comps.len() == 1 { "" } else { "s" }
                ),
                &format!("write `{field} = [x, y, z]`"),
            );
            return None;
        }
        let mut out = [0.0; 3];
        for (k, c) in comps.iter().enumerate() {
            out[k] = self.scalar(c, item, field, cache)?;
        }
        Some(out)
    }

    fn scalar(
        &mut self,
        s: &Spanned<Scalar>,
        item: &str,
        field: &str,
        cache: &mut HashMap<String, ParamState>,
    ) -> Option<f64> {
        match s.get_ref() {
            Scalar::Int(i) => Some(*i as f64),
            Scalar::Float(f) => self.finite(*f, s.span(), item, field),
            Scalar::Expr(src) => self.constant_expr(src, s.span(), item, field, cache),
        }
    }

    /// TOML accepts `inf` and `nan`; no physical quantity here may be either.
    fn finite(&mut self, v: f64, span: Range<usize>, item: &str, field: &str) -> Option<f64> {
        if v.is_finite() {
            Some(v)
        } else {
            self.err(
                span,
                item,
                format!("`{field}` is {v}"),
                "give a finite number",
            );
            None
        }
    }

    /// Evaluates an expression of parameters (no `t`) to a number.
    fn constant_expr(
        &mut self,
        src: &str,
        span: Range<usize>,
        item: &str,
        field: &str,
        cache: &mut HashMap<String, ParamState>,
    ) -> Option<f64> {
        let mut arena = Arena::new();
        let mut missing: Vec<String> = Vec::new();
        // Resolve names first (needs &mut self), then build.
        let names = referenced_names(src);
        let mut values: HashMap<String, f64> = HashMap::new();
        for n in names {
            if self.params.contains_key(&n) {
                if let Some(v) = self.param_value(&n, cache) {
                    values.insert(n, v);
                } else {
                    return None;
                }
            } else {
                missing.push(n);
            }
        }
        let mut resolve = |a: &mut Arena, n: &str| values.get(n).map(|v| a.constant(*v));
        match parse_expr(&mut arena, src, &mut resolve) {
            Ok(id) => match arena.as_const(id) {
                Some(v) if v.is_finite() => Some(v),
                Some(v) => {
                    self.err(
                        span,
                        item,
                        format!("`{field}` evaluates to {v}"),
                        "check the expression for a division by zero or a domain error",
                    );
                    None
                }
                None => {
                    self.err(
                        span,
                        item,
                        format!("`{field}` depends on `t`, but must be a constant"),
                        "only driver values may depend on time",
                    );
                    None
                }
            },
            Err(e) => {
                let help = if e.message.starts_with("unknown name") && !self.params.is_empty() {
                    let mut known: Vec<&str> = self.params.keys().map(|s| s.as_str()).collect();
                    known.sort();
                    match missing
                        .first()
                        .and_then(|m| closest(m, known.iter().copied()))
                    {
                        Some(s) => format!("did you mean `{s}`? {}", e.help),
                        None => e.help.clone(),
                    }
                } else {
                    e.help.clone()
                };
                self.err(span, item, format!("in `{field}`: {}", e.message), &help);
                None
            }
        }
    }

    fn param_value(&mut self, name: &str, cache: &mut HashMap<String, ParamState>) -> Option<f64> {
        match cache.get(name) {
            Some(ParamState::Done(v)) => return Some(*v),
            Some(ParamState::Busy) => {
                let span = self.params[name].0.clone();
                self.err(
                    span,
                    &format!("parameter `{name}`"),
                    format!("parameter `{name}` depends on itself"),
                    "break the cycle: give one of the parameters a number",
                );
                return None;
            }
            None => {}
        }
        let (span, value) = self.params.get(name)?.clone();
        cache.insert(name.to_string(), ParamState::Busy);
        let item = format!("parameter `{name}`");
        let v = match value {
            Scalar::Int(i) => Some(i as f64),
            Scalar::Float(f) => self.finite(f, span, &item, name),
            Scalar::Expr(src) => self.constant_expr(&src, span, &item, name, cache),
        };
        match v {
            Some(v) => {
                cache.insert(name.to_string(), ParamState::Done(v));
                Some(v)
            }
            None => {
                // Leave it busy-free but unresolved so later uses do not report a false cycle.
                cache.insert(name.to_string(), ParamState::Done(f64::NAN));
                None
            }
        }
    }
}

/// Identifiers that appear in an expression (syntax errors are reported by the parser later).
fn referenced_names(src: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut prev_dot = false;
    let mut in_number = false;
    for ch in src.chars().chain(std::iter::once(' ')) {
        if ch.is_alphanumeric() || ch == '_' {
            if cur.is_empty() && ch.is_ascii_digit() {
                in_number = true;
            }
            cur.push(ch);
        } else {
            if !cur.is_empty() && !in_number && !prev_dot && ch != '(' {
                out.push(cur.clone());
            }
            if !cur.is_empty() || ch != ' ' {
                prev_dot = ch == '.' && !in_number;
            }
            cur.clear();
            in_number = false;
        }
    }
    out
}

/// Rust keywords cannot name a generated module.
const KEYWORDS: &[&str] = &[
    "as", "async", "await", "break", "const", "continue", "crate", "dyn", "else", "enum", "extern",
    "false", "fn", "for", "gen", "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut",
    "pub", "ref", "return", "self", "static", "struct", "super", "trait", "true", "try", "type",
    "unsafe", "use", "where", "while", "abstract", "become", "box", "do", "final", "macro",
    "override", "priv", "typeof", "unsized", "virtual", "yield",
];

fn is_identifier(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// The closest candidate by edit distance, if it is close enough to be a likely typo.
fn closest<'a>(name: &str, candidates: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    candidates
        .map(|c| (edit_distance(name, c), c))
        .filter(|(d, c)| *d <= 2.max(c.len() / 3))
        .min()
        .map(|(_, c)| c)
}

fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for i in 1..=a.len() {
        let mut cur = vec![i; b.len() + 1];
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            cur[j] = (prev[j] + 1).min(cur[j - 1] + 1).min(prev[j - 1] + cost);
        }
        prev = cur;
    }
    prev[b.len()]
}

/// The two cross-axis directions of a prismatic joint whose axis is a coordinate axis,
/// chosen as the paper does for the y axis: Rz(90°)·v and Rx(90°)·v, exact.
fn perpendiculars(axis: [f64; 3]) -> Option<[[f64; 3]; 2]> {
    let rz90 = |v: [f64; 3]| [-v[1], v[0], v[2]];
    let rx90 = |v: [f64; 3]| [v[0], -v[2], v[1]];
    let ry90 = |v: [f64; 3]| [v[2], v[1], -v[0]];
    let n1 = axis.iter().filter(|x| **x != 0.0).count();
    if n1 != 1 || axis.iter().any(|x| *x != 0.0 && x.abs() != 1.0) {
        return None;
    }
    // Use the two 90° rotations about the axes other than the sliding one.
    let candidates = [rz90(axis), rx90(axis), ry90(axis)];
    let perp: Vec<[f64; 3]> = candidates
        .into_iter()
        .filter(|c| dot(*c, axis) == 0.0)
        .collect();
    Some([perp[0], perp[1]])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn euler_round_trip() {
        for (t, b, g) in [(0.3, -0.7, 1.2), (-1.0, 1.1, -2.5), (0.0, 0.0, 0.0)] {
            let a = rotation(t, b, g);
            let e = euler_angles(&a);
            assert!(
                (e[0] - t).abs() < 1e-12 && (e[1] - b).abs() < 1e-12 && (e[2] - g).abs() < 1e-12
            );
        }
    }

    #[test]
    fn paper_perpendiculars_for_y_axis() {
        // Paper eqs. 7–8: Rz(90°)·(0,1,0) = (−1,0,0), Rx(90°)·(0,1,0) = (0,0,1).
        assert_eq!(
            perpendiculars([0.0, 1.0, 0.0]),
            Some([[-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
        );
        assert_eq!(perpendiculars([0.5, 0.5, 0.0]), None);
    }

    #[test]
    fn names_in_expressions() {
        assert_eq!(referenced_names("c0 + 0.02 * sin(t)"), vec!["c0", "t"]);
        assert_eq!(
            referenced_names("(phi1).to_radians() * r_b"),
            vec!["phi1", "r_b"]
        );
        assert_eq!(referenced_names("1e-3 * x"), vec!["x"]);
    }
}
