//! Drivers (docs/design.md, decision 17): a joint coordinate (revolute angle, sliding distance),
//! a body coordinate, or the distance between two points, prescribed as a function of `t`.

use super::raw::{RawDriver, SStr, SVec};
use super::{Body, BodyRef, Driver, DriverTarget, Frame, Joint, JointKind, Rotation, Validator};
use crate::geometry::{arr, v3, M3, V3};
use std::collections::HashMap;
use std::ops::Range;
use toml::Spanned;

/// Pose of a body (or of the ground) at the initial configuration.
pub(super) fn pose(bodies: &[Body], b: BodyRef) -> (V3, M3) {
    match b {
        None => (V3::zeros(), M3::identity()),
        Some(i) => (bodies[i].position(), bodies[i].orientation()),
    }
}

/// Global position at the initial pose of a frame's point.
pub(super) fn frame_point(bodies: &[Body], f: &Frame) -> V3 {
    let (r, a) = pose(bodies, f.body);
    r + a * v3(f.point)
}

/// The angle of joint `j` about its axis at the initial pose, from `x1` to `x2`.
pub(super) fn joint_angle(bodies: &[Body], j: &Joint) -> f64 {
    let (_, a1) = pose(bodies, j.f1.body);
    let (_, a2) = pose(bodies, j.f2.body);
    let x1 = a1 * v3(j.f1.x);
    let y1 = a1 * v3(j.f1.z).cross(&v3(j.f1.x));
    let x2 = a2 * v3(j.f2.x);
    y1.dot(&x2).atan2(x1.dot(&x2))
}

/// The sliding distance of joint `j` at the initial pose.
fn joint_slide(bodies: &[Body], j: &Joint) -> f64 {
    let (r1, a1) = pose(bodies, j.f1.body);
    match j.kind {
        JointKind::EulerPrismatic { axis, .. } => {
            let (r2, _) = pose(bodies, j.f2.body);
            (a1 * v3(axis)).dot(&(r2 - r1))
        }
        _ => (a1 * v3(j.f1.z)).dot(&(frame_point(bodies, &j.f2) - frame_point(bodies, &j.f1))),
    }
}

/// Fields naming two points on two bodies.
pub(super) struct TwoPoints<'r> {
    pub body1: &'r Option<SStr>,
    pub body2: &'r Option<SStr>,
    pub at1: &'r Option<SVec>,
    pub at2: &'r Option<SVec>,
    pub point1: &'r Option<SVec>,
    pub point2: &'r Option<SVec>,
}

impl Validator<'_> {
    /// Two frames (points only) from `body1`/`body2` and `at1`/`at2` (global) or
    /// `point1`/`point2` (local).
    pub(super) fn two_points(
        &mut self,
        f: TwoPoints<'_>,
        span: &Range<usize>,
        item: &str,
        bodies: &[Body],
        body_index: &HashMap<String, usize>,
    ) -> Option<(Frame, Frame)> {
        let b1 = self.body_ref(f.body1, span, item, "body1", body_index);
        let b2 = self.body_ref(f.body2, span, item, "body2", body_index);
        let (b1, b2) = (b1?, b2?);
        if b1 == b2 {
            self.err(
                span.clone(),
                item,
                format!("{item} connects a body to itself"),
                "body1 and body2 must be different (one of them may be \"ground\")",
            );
            return None;
        }
        let local = |b: BodyRef, p: [f64; 3]| {
            let (r, a) = pose(bodies, b);
            arr(&(a.transpose() * (v3(p) - r)))
        };
        let (p1, p2) = match (f.at1, f.at2, f.point1, f.point2) {
            (Some(a1), Some(a2), None, None) => {
                let (a1, a2) = (self.vec3(a1, item, "at1"), self.vec3(a2, item, "at2"));
                (local(b1, a1?), local(b2, a2?))
            }
            (None, None, Some(p1), Some(p2)) => {
                let (p1, p2) = (self.vec3(p1, item, "point1"), self.vec3(p2, item, "point2"));
                (p1?, p2?)
            }
            _ => {
                self.err(
                    span.clone(),
                    item,
                    format!("{item} needs its two points"),
                    "give `at1`, `at2` (global, at the initial pose) or `point1`, `point2` (local to each body; global for the ground)",
                );
                return None;
            }
        };
        let frame = |body, point| Frame {
            body,
            point,
            x: [1.0, 0.0, 0.0],
            z: [0.0, 0.0, 1.0],
        };
        let (f1, f2) = (frame(b1, p1), frame(b2, p2));
        if (frame_point(bodies, &f2) - frame_point(bodies, &f1)).norm() < 1e-9 {
            self.err(
                span.clone(),
                item,
                format!("{item}: the two points coincide at the initial pose"),
                "a distance is not differentiable at zero: use two distinct points",
            );
            return None;
        }
        Some((f1, f2))
    }

    pub(super) fn drivers(
        &mut self,
        raw: &[Spanned<RawDriver>],
        joints: &[Joint],
        bodies: &[Body],
        body_index: &HashMap<String, usize>,
        names: &mut HashMap<String, Range<usize>>,
    ) -> Option<Vec<Driver>> {
        let mut out = Vec::new();
        for (i, rd) in raw.iter().enumerate() {
            let span = rd.span();
            let rd = rd.get_ref();
            let Some(name) = self.item_name(&rd.name, span.clone(), "driver", i, names) else {
                continue;
            };
            let item = format!("driver `{name}`");
            let Some((target, initial)) =
                self.driver_target(rd, &span, &item, joints, bodies, body_index)
            else {
                continue;
            };
            let Some(value) = &rd.value else {
                self.err(
                    span.clone(),
                    &item,
                    format!("{item} is missing `value`"),
                    "add `value = \"initial + 0.02 * sin(t)\"` (a function of t; `initial` is the coordinate at the initial pose)",
                );
                continue;
            };
            if let Some(v) = self.time_expr(value, &item, "value", Some(initial)) {
                out.push(Driver {
                    name,
                    target,
                    value: v,
                    source: value.get_ref().clone(),
                    initial,
                });
            }
        }
        Some(out)
    }

    fn driver_target(
        &mut self,
        rd: &RawDriver,
        span: &Range<usize>,
        item: &str,
        joints: &[Joint],
        bodies: &[Body],
        body_index: &HashMap<String, usize>,
    ) -> Option<(DriverTarget, f64)> {
        let forms = [
            rd.joint.is_some(),
            rd.body.is_some(),
            rd.body1.is_some() || rd.body2.is_some(),
        ];
        if forms.iter().filter(|f| **f).count() != 1 {
            self.err(
                span.clone(),
                item,
                format!("{item} must name exactly one of `joint`, `body`, or `body1`/`body2`"),
                "drive a joint coordinate (`joint`), a body coordinate (`body`, `coordinate`), or a point distance (`body1`, `body2`, with points)",
            );
            return None;
        }
        if let Some(jname) = &rd.joint {
            return self.joint_driver(rd, jname, item, joints, bodies);
        }
        if let Some(bname) = &rd.body {
            let b = self.body_ref(&rd.body, span, item, "body", body_index)?;
            let Some(b) = b else {
                self.err(
                    bname.span(),
                    item,
                    "the ground has no coordinates to drive".into(),
                    "name a body",
                );
                return None;
            };
            let body = &bodies[b];
            let allowed: &[&str] = match body.rotation {
                Rotation::Euler => &["x", "y", "z", "theta", "beta", "gamma"],
                Rotation::Quaternion => &["x", "y", "z"],
            };
            let Some(c) = &rd.coordinate else {
                self.err(
                    span.clone(),
                    item,
                    format!("{item} is missing `coordinate`"),
                    &format!("add `coordinate = ...`, one of {allowed:?}"),
                );
                return None;
            };
            let Some(coord) = allowed.iter().position(|a| a == c.get_ref()) else {
                let extra = if body.rotation == Rotation::Quaternion {
                    "; drive a rotation through a revolute joint's angle instead"
                } else {
                    ""
                };
                self.err(
                    c.span(),
                    item,
                    format!(
                        "body `{}` has no drivable coordinate `{}`",
                        body.name,
                        c.get_ref()
                    ),
                    &format!("use one of {allowed:?}{extra}"),
                );
                return None;
            };
            return Some((
                DriverTarget::BodyCoordinate { body: b, coord },
                body.q0[coord],
            ));
        }
        let (f1, f2) = self.two_points(
            TwoPoints {
                body1: &rd.body1,
                body2: &rd.body2,
                at1: &rd.at1,
                at2: &rd.at2,
                point1: &rd.point1,
                point2: &rd.point2,
            },
            span,
            item,
            bodies,
            body_index,
        )?;
        let initial = (frame_point(bodies, &f2) - frame_point(bodies, &f1)).norm();
        Some((DriverTarget::PointDistance { f1, f2 }, initial))
    }

    fn joint_driver(
        &mut self,
        rd: &RawDriver,
        jname: &SStr,
        item: &str,
        joints: &[Joint],
        bodies: &[Body],
    ) -> Option<(DriverTarget, f64)> {
        let Some(ji) = joints.iter().position(|j| &j.name == jname.get_ref()) else {
            let suggestion =
                super::values::closest(jname.get_ref(), joints.iter().map(|j| j.name.as_str()));
            self.err(
                jname.span(),
                item,
                format!("unknown joint `{}`", jname.get_ref()),
                &match suggestion {
                    Some(s) => format!("did you mean `{s}`?"),
                    None => {
                        "name a revolute, prismatic or cylindrical joint declared with [[joint]]"
                            .to_string()
                    }
                },
            );
            return None;
        };
        let j = &joints[ji];
        let coordinate = rd.coordinate.as_ref().map(|c| c.get_ref().as_str());
        let angle = match (coordinate, j.kind.has_angle(), j.kind.has_slide()) {
            (None, true, false) | (Some("angle"), true, _) => true,
            (None, false, true) | (Some("distance"), _, true) => false,
            (None, true, true) => {
                self.err(
                    jname.span(),
                    item,
                    format!(
                        "joint `{}` is cylindrical: both its angle and its distance can be driven",
                        j.name
                    ),
                    "add `coordinate = \"angle\"` or `coordinate = \"distance\"`",
                );
                return None;
            }
            (Some(c), a, s) if a || s => {
                let span = rd.coordinate.as_ref().map_or(jname.span(), |c| c.span());
                self.err(
                    span,
                    item,
                    format!(
                        "joint `{}` ({}) has no coordinate `{c}`",
                        j.name,
                        j.kind.name()
                    ),
                    match (a, s) {
                        (true, true) => {
                            "use `coordinate = \"angle\"` or `coordinate = \"distance\"`"
                        }
                        (true, false) => "use `coordinate = \"angle\"`",
                        _ => "use `coordinate = \"distance\"`",
                    },
                );
                return None;
            }
            _ => {
                self.err(
                    jname.span(),
                    item,
                    format!("joint `{}` is {} and has no coordinate to drive", j.name, j.kind.name()),
                    "drivers act on revolute (angle), prismatic (distance) and cylindrical joints, on a body coordinate (`body`, `coordinate`) or on a point distance (`body1`, `body2`)",
                );
                return None;
            }
        };
        Some(if angle {
            (DriverTarget::JointAngle(ji), joint_angle(bodies, j))
        } else {
            (DriverTarget::JointSlide(ji), joint_slide(bodies, j))
        })
    }
}
