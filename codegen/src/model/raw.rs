//! The serde schema of a mechanism file: every field optional, so that validation (not the
//! TOML reader) reports what is missing, with the item's name and a fix.

use serde::Deserialize;
use std::collections::BTreeMap;
use toml::Spanned;

/// A number, or an expression string evaluated from parameters.
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
pub enum Scalar {
    Int(i64),
    Float(f64),
    Expr(String),
}

pub type SScalar = Spanned<Scalar>;
pub type SVec = Spanned<Vec<SScalar>>;
pub type SStr = Spanned<String>;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawFile {
    pub name: Option<SStr>,
    pub description: Option<String>,
    pub formulations: Option<Spanned<Vec<SStr>>>,
    pub gravity: Option<SVec>,
    /// Default rotation coordinates of the bodies: "quaternion" (default) or "euler".
    pub rotation: Option<SStr>,
    /// Suggested simulation end time (s).
    pub t_end: Option<SScalar>,
    /// Lets the generator move bodies by more than a modelling tolerance to assemble the
    /// initial pose (otherwise such a violation is an error).
    pub repair_initial_pose: Option<bool>,
    /// The mechanism moves in the plane z = const: emit a planar model in (x, y, γ) per body
    /// beside the spatial one.
    pub planar: Option<Spanned<bool>>,
    #[serde(default)]
    pub parameters: BTreeMap<SStr, SScalar>,
    #[serde(default)]
    pub body: Vec<Spanned<RawBody>>,
    #[serde(default)]
    pub joint: Vec<Spanned<RawJoint>>,
    #[serde(default)]
    pub driver: Vec<Spanned<RawDriver>>,
    #[serde(default)]
    pub force: Vec<Spanned<RawForce>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBody {
    pub name: Option<SStr>,
    pub mass: Option<SScalar>,
    pub inertia: Option<SVec>,
    pub rotation: Option<SStr>,
    pub position: Option<SVec>,
    pub angles: Option<SVec>,
    pub quaternion: Option<SVec>,
    pub placement: Option<Spanned<RawPlacement>>,
    pub velocity: Option<SVec>,
    pub angular_velocity: Option<SVec>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPlacement {
    pub from: Option<SStr>,
    pub to: Option<SStr>,
    pub offset_from_start: Option<SScalar>,
    pub offset_from_end: Option<SScalar>,
}

/// Points and axes are given either in the bodies' local coordinates (`point1`, `point2`,
/// `axis1`, `axis2`, `reference1`, `reference2`) or globally at the file's initial pose
/// (`at` for a shared point, `at1`/`at2` for two points, `axis`, `cross_axis`, `reference`).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawJoint {
    pub name: Option<SStr>,
    #[serde(rename = "type")]
    pub kind: Option<SStr>,
    pub body1: Option<SStr>,
    pub body2: Option<SStr>,
    pub point1: Option<SVec>,
    pub point2: Option<SVec>,
    pub at: Option<SVec>,
    pub at1: Option<SVec>,
    pub at2: Option<SVec>,
    pub axis: Option<SVec>,
    pub axis1: Option<SVec>,
    pub axis2: Option<SVec>,
    pub cross_axis: Option<SVec>,
    pub reference: Option<SVec>,
    pub reference1: Option<SVec>,
    pub reference2: Option<SVec>,
    pub length: Option<SScalar>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawDriver {
    pub name: Option<SStr>,
    pub joint: Option<SStr>,
    pub coordinate: Option<SStr>,
    pub body: Option<SStr>,
    pub body1: Option<SStr>,
    pub body2: Option<SStr>,
    pub point1: Option<SVec>,
    pub point2: Option<SVec>,
    pub at1: Option<SVec>,
    pub at2: Option<SVec>,
    pub value: Option<SStr>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawForce {
    pub name: Option<SStr>,
    #[serde(rename = "type")]
    pub kind: Option<SStr>,
    pub body: Option<SStr>,
    pub body1: Option<SStr>,
    pub body2: Option<SStr>,
    pub joint: Option<SStr>,
    pub point: Option<SVec>,
    pub point1: Option<SVec>,
    pub point2: Option<SVec>,
    pub at: Option<SVec>,
    pub at1: Option<SVec>,
    pub at2: Option<SVec>,
    pub stiffness: Option<SScalar>,
    pub damping: Option<SScalar>,
    pub free_length: Option<SScalar>,
    pub free_angle: Option<SScalar>,
    /// Spring: actuator force (pushing apart); torsion: actuator torque. Expressions in `t`.
    pub actuator: Option<SStr>,
    /// Applied force or torque: three expressions in `t`.
    pub value: Option<Spanned<Vec<SScalar>>>,
    /// "global" (default) or "body".
    pub axes: Option<SStr>,
}
