//! Joints: type and bodies first (placements need them), then, once every body has its
//! initial pose, the two joint frames in the bodies' local coordinates.

use super::drivers::pose;
use super::raw::{RawJoint, SVec};
use super::{Body, BodyRef, Frame, Joint, JointKind, Rotation, Validator};
use crate::geometry::{arr, perpendicular, v3, M3, V3};
use std::collections::HashMap;
use std::ops::Range;
use toml::Spanned;

const JOINT_TYPES: &str = "\"spherical\", \"revolute\", \"universal\", \"cylindrical\", \"prismatic\", \"fixed\", \"distance\", \"euler_prismatic\"";

/// A joint after the first pass: its name, type and bodies, with the raw fields kept for
/// the frames.
pub(super) struct JointSpec<'r> {
    pub name: String,
    pub span: Range<usize>,
    pub kind: String,
    pub b1: BodyRef,
    pub b2: BodyRef,
    pub raw: &'r RawJoint,
}

impl Validator<'_> {
    pub(super) fn joint_specs<'r>(
        &mut self,
        raw: &'r [Spanned<RawJoint>],
        body_index: &HashMap<String, usize>,
        names: &mut HashMap<String, Range<usize>>,
    ) -> Vec<JointSpec<'r>> {
        let mut out = Vec::new();
        for (i, rj) in raw.iter().enumerate() {
            let span = rj.span();
            let rj = rj.get_ref();
            let Some(name) = self.item_name(&rj.name, span.clone(), "joint", i, names) else {
                continue;
            };
            let item = format!("joint `{name}`");
            let Some(kind) = &rj.kind else {
                self.err(
                    span.clone(),
                    &item,
                    format!("{item} is missing `type`"),
                    &format!("add `type = ...`, one of {JOINT_TYPES}"),
                );
                continue;
            };
            let known = [
                "spherical",
                "revolute",
                "universal",
                "cylindrical",
                "prismatic",
                "fixed",
                "distance",
                "euler_prismatic",
            ];
            if !known.contains(&kind.get_ref().as_str()) {
                let help = match super::values::closest(kind.get_ref(), known.iter().copied()) {
                    Some(s) => format!("did you mean \"{s}\"? supported types: {JOINT_TYPES}"),
                    None => format!("supported types: {JOINT_TYPES}"),
                };
                self.err(
                    kind.span(),
                    &item,
                    format!("unknown joint type `{}`", kind.get_ref()),
                    &help,
                );
                continue;
            }
            let b1 = self.body_ref(&rj.body1, &span, &item, "body1", body_index);
            let b2 = self.body_ref(&rj.body2, &span, &item, "body2", body_index);
            let (Some(b1), Some(b2)) = (b1, b2) else {
                continue;
            };
            if b1 == b2 {
                self.err(
                    span.clone(),
                    &item,
                    format!(
                        "{item} connects {} to itself",
                        if b1.is_none() { "the ground" } else { "a body" }
                    ),
                    "body1 and body2 must be different (one of them may be \"ground\")",
                );
                continue;
            }
            out.push(JointSpec {
                name,
                span,
                kind: kind.get_ref().clone(),
                b1,
                b2,
                raw: rj,
            });
        }
        out
    }

    pub(super) fn joints(&mut self, specs: &[JointSpec<'_>], bodies: &[Body]) -> Vec<Joint> {
        specs
            .iter()
            .filter_map(|s| {
                let item = format!("joint `{}`", s.name);
                let (kind, f1, f2) = self.joint(s, &item, bodies)?;
                Some(Joint {
                    name: s.name.clone(),
                    kind,
                    f1,
                    f2,
                })
            })
            .collect()
    }

    fn joint(
        &mut self,
        s: &JointSpec<'_>,
        item: &str,
        bodies: &[Body],
    ) -> Option<(JointKind, Frame, Frame)> {
        let r = s.raw;
        if s.kind == "euler_prismatic" {
            return self.euler_prismatic(s, item, bodies);
        }
        let has_axes = !matches!(s.kind.as_str(), "spherical" | "distance");
        if !has_axes {
            for (field, v) in [("axis", &r.axis), ("axis1", &r.axis1), ("axis2", &r.axis2)] {
                if let Some(v) = v {
                    self.err(
                        v.span(),
                        item,
                        format!("a {} joint has no axis, but `{field}` is given", s.kind),
                        "remove the axis, or choose a joint type with an axis (revolute, universal, …)",
                    );
                    return None;
                }
            }
        }
        let (p1, p2) = self.joint_points(s, item, bodies)?;
        let (z1, z2, x1, x2) = if has_axes {
            self.joint_axes(s, item, bodies)?
        } else {
            let (z, x) = ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0]);
            (z, z, x, x)
        };
        let kind = match s.kind.as_str() {
            "spherical" => JointKind::Spherical,
            "revolute" => JointKind::Revolute,
            "universal" => JointKind::Universal,
            "cylindrical" => JointKind::Cylindrical,
            "prismatic" => JointKind::Prismatic,
            "fixed" => JointKind::Fixed,
            _ => {
                let (r1, a1) = pose(bodies, s.b1);
                let (r2, a2) = pose(bodies, s.b2);
                let d = (r2 + a2 * v3(p2) - r1 - a1 * v3(p1)).norm();
                // |p2 − p1| has no derivative where the points coincide, so assembly could
                // not start from there even with a `length`.
                if !(d > 1e-9) {
                    self.err(
                        s.span.clone(),
                        item,
                        "the two points of a distance joint coincide at the initial pose".into(),
                        "give two distinct points (their distance at the initial pose is the length, unless `length = <m>` is given)",
                    );
                    return None;
                }
                let length = match &r.length {
                    Some(l) => {
                        let v = self.scalar(l, item, "length")?;
                        self.positive(v, l.span(), item, "length").then_some(v)?
                    }
                    None => d,
                };
                JointKind::Distance { length }
            }
        };
        let frame = |body, point, x, z| Frame { body, point, x, z };
        Some((kind, frame(s.b1, p1, x1, z1), frame(s.b2, p2, x2, z2)))
    }

    /// The joint point on each body (local): `at` (one global point), `at1`/`at2` (two
    /// global points) or `point1`/`point2` (local).
    fn joint_points(
        &mut self,
        s: &JointSpec<'_>,
        item: &str,
        bodies: &[Body],
    ) -> Option<([f64; 3], [f64; 3])> {
        let r = s.raw;
        let two_points = s.kind == "distance";
        let help = if two_points {
            "give the two points as `at1`, `at2` (global, at the initial pose) or as `point1`, `point2` (local to each body; global for the ground)"
        } else {
            "give the joint point as `at = [x, y, z]` (global, at the initial pose) or as `point1`, `point2` (local to each body; global for the ground)"
        };
        let local = |b: BodyRef, p: [f64; 3]| {
            let (rb, ab) = pose(bodies, b);
            arr(&(ab.transpose() * (v3(p) - rb)))
        };
        match (&r.at, &r.at1, &r.at2, &r.point1, &r.point2) {
            (Some(at), None, None, None, None) if !two_points => {
                let p = self.vec3(at, item, "at")?;
                Some((local(s.b1, p), local(s.b2, p)))
            }
            (None, Some(a1), Some(a2), None, None) => {
                let p1 = self.vec3(a1, item, "at1")?;
                let p2 = self.vec3(a2, item, "at2")?;
                Some((local(s.b1, p1), local(s.b2, p2)))
            }
            (None, None, None, Some(p1), Some(p2)) => {
                let p1 = self.vec3(p1, item, "point1")?;
                let p2 = self.vec3(p2, item, "point2")?;
                Some((p1, p2))
            }
            (None, None, None, None, None) => {
                self.err(
                    s.span.clone(),
                    item,
                    format!("{item} has no joint point"),
                    help,
                );
                None
            }
            _ => {
                let span = [&r.at, &r.at1, &r.at2, &r.point1, &r.point2]
                    .into_iter()
                    .flatten()
                    .next()
                    .map_or(s.span.clone(), |v| v.span());
                self.err(
                    span,
                    item,
                    format!("{item}: the joint point is given in more than one way, or only half of a pair"),
                    help,
                );
                None
            }
        }
    }

    /// The axis `z` and reference `x` on each body (local).
    #[allow(clippy::type_complexity)]
    fn joint_axes(
        &mut self,
        s: &JointSpec<'_>,
        item: &str,
        bodies: &[Body],
    ) -> Option<([f64; 3], [f64; 3], [f64; 3], [f64; 3])> {
        let r = s.raw;
        let (_, a1) = pose(bodies, s.b1);
        let (_, a2) = pose(bodies, s.b2);
        let universal = s.kind == "universal";
        // Global directions at the initial pose of body 1's axis and body 2's axis.
        let world = |this: &mut Self,
                     g: &Option<SVec>,
                     l: &Option<SVec>,
                     a: &M3,
                     f: &str,
                     lf: &str| {
            match (g, l) {
                (Some(g), None) => this.direction(g, item, f).map(v3),
                (None, Some(l)) => this.direction(l, item, lf).map(|d| a * v3(d)),
                (Some(g), Some(_)) => {
                    this.err(
                        g.span(),
                        item,
                        format!("{item} gives both `{f}` (global) and `{lf}` (local)"),
                        "give the axis once",
                    );
                    None
                }
                (None, None) => None,
            }
        };
        let z1w = world(self, &r.axis, &r.axis1, &a1, "axis", "axis1");
        let z2w = if universal {
            world(self, &r.cross_axis, &r.axis2, &a2, "cross_axis", "axis2")
        } else {
            match (&r.axis, &r.axis2) {
                (None, Some(l)) => self.direction(l, item, "axis2").map(|d| a2 * v3(d)),
                _ => z1w,
            }
        };
        let (z1w, z2w) = match (z1w, z2w, s.kind.as_str()) {
            (Some(a), Some(b), _) => (a, b),
            (None, None, "fixed") => (V3::z(), V3::z()),
            _ => {
                let help = if universal {
                    "give `axis` (fixed in body1) and `cross_axis` (fixed in body2), global at the initial pose, or `axis1` and `axis2` local"
                } else {
                    "give `axis = [x, y, z]` (global, at the initial pose), or `axis1` and `axis2` (local to each body)"
                };
                if self.errors.is_empty() || !self.errors.iter().any(|d| d.item == item) {
                    self.err(
                        s.span.clone(),
                        item,
                        format!("{item} needs its axis on both bodies"),
                        help,
                    );
                }
                return None;
            }
        };
        if universal && z1w.dot(&z2w).abs() > 1e-9 {
            self.err(
                r.cross_axis
                    .as_ref()
                    .or(r.axis2.as_ref())
                    .map_or(s.span.clone(), |v| v.span()),
                item,
                format!(
                    "the two axes of universal joint `{}` are not perpendicular at the initial pose (cosine {:.3e})",
                    s.name,
                    z1w.dot(&z2w)
                ),
                "a universal joint's cross axes are perpendicular: fix `cross_axis`/`axis2`",
            );
            return None;
        }
        // The part of a given reference direction `d` (global) across the axis `z`.
        let across = |this: &mut Self, v: &SVec, field: &str, d: V3, z: &V3| {
            let x = d - z * z.dot(&d);
            if x.norm() < 1e-6 {
                this.err(
                    v.span(),
                    item,
                    format!("`{field}` is parallel to the joint axis"),
                    "give a reference direction perpendicular to the axis (angle zero)",
                );
                return None;
            }
            Some(x.normalize())
        };
        let x1w = match (&r.reference, &r.reference1) {
            (Some(g), None) => {
                let d = v3(self.direction(g, item, "reference")?);
                across(self, g, "reference", d, &z1w)?
            }
            (None, Some(l)) => {
                let d = a1 * v3(self.direction(l, item, "reference1")?);
                across(self, l, "reference1", d, &z1w)?
            }
            (None, None) => perpendicular(&z1w),
            (Some(g), Some(_)) => {
                self.err(
                    g.span(),
                    item,
                    format!("{item} gives both `reference` and `reference1`"),
                    "give the reference direction once",
                );
                return None;
            }
        };
        let x2w = match &r.reference2 {
            Some(l) => {
                let d = a2 * v3(self.direction(l, item, "reference2")?);
                across(self, l, "reference2", d, &z2w)?
            }
            // Body 1's reference, made perpendicular to body 2's axis (any perpendicular
            // when it is along that axis, as it can be for a universal joint).
            None => {
                let x = x1w - z2w * z2w.dot(&x1w);
                if x.norm() < 1e-6 {
                    perpendicular(&z2w)
                } else {
                    x.normalize()
                }
            }
        };
        let loc = |a: &M3, v: V3| arr(&(a.transpose() * v));
        Some((loc(&a1, z1w), loc(&a2, z2w), loc(&a1, x1w), loc(&a2, x2w)))
    }

    fn euler_prismatic(
        &mut self,
        s: &JointSpec<'_>,
        item: &str,
        bodies: &[Body],
    ) -> Option<(JointKind, Frame, Frame)> {
        let (Some(b1), Some(b2)) = (s.b1, s.b2) else {
            self.err(
                s.span.clone(),
                item,
                format!("{item}: the paper's `euler_prismatic` joint connects two bodies"),
                "use `type = \"prismatic\"` for a slider on the ground",
            );
            return None;
        };
        for b in [b1, b2] {
            if bodies[b].rotation != Rotation::Euler {
                self.err(
                    s.span.clone(),
                    item,
                    format!(
                        "`euler_prismatic` equates Euler angles, but body `{}` uses quaternions",
                        bodies[b].name
                    ),
                    "give both bodies `rotation = \"euler\"`, or use `type = \"prismatic\"`",
                );
                return None;
            }
        }
        let axis = match &s.raw.axis {
            Some(v) => self.vec3(v, item, "axis")?,
            None => [0.0, 1.0, 0.0],
        };
        let Some(perp) = perpendiculars(axis) else {
            self.err(
                s.raw.axis.as_ref().map_or(s.span.clone(), |a| a.span()),
                item,
                format!("euler_prismatic axis {axis:?} must be a coordinate axis of body1 (unit vector along x, y or z)"),
                "set up body1's local frame so the sliding axis is one of its axes, e.g. `axis = [0, 1, 0]`",
            );
            return None;
        };
        let f = |body| Frame {
            body: Some(body),
            point: [0.0; 3],
            x: perp[0],
            z: axis,
        };
        Some((JointKind::EulerPrismatic { axis, perp }, f(b1), f(b2)))
    }
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
    let candidates = [rz90(axis), rx90(axis), ry90(axis)];
    let perp: Vec<[f64; 3]> = candidates
        .into_iter()
        .filter(|c| c[0] * axis[0] + c[1] * axis[1] + c[2] * axis[2] == 0.0)
        .collect();
    Some([perp[0], perp[1]])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_perpendiculars_for_y_axis() {
        // Paper eqs. 7–8: Rz(90°)·(0,1,0) = (−1,0,0), Rx(90°)·(0,1,0) = (0,0,1).
        assert_eq!(
            perpendiculars([0.0, 1.0, 0.0]),
            Some([[-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
        );
        assert_eq!(perpendiculars([0.5, 0.5, 0.0]), None);
    }
}
