//! Applied force elements (docs/design.md, decision 20): translational spring–damper–actuators
//! between two points, rotational spring–damper–actuators in joints, and applied forces and
//! torques given as functions of `t`.

use super::drivers::{frame_point, joint_angle, TwoPoints};
use super::raw::{RawForce, SScalar, Scalar};
use super::{Body, Force, ForceKind, Frame, Joint, Validator};
use crate::expr::Id;
use crate::geometry::{arr, v3};
use std::collections::HashMap;
use std::ops::Range;
use toml::Spanned;

const FORCE_TYPES: &str = "\"spring\" (spring–damper–actuator between two points), \"torsion\" (in a revolute or cylindrical joint), \"force\", \"torque\"";

impl Validator<'_> {
    pub(super) fn forces(
        &mut self,
        raw: &[Spanned<RawForce>],
        joints: &[Joint],
        bodies: &[Body],
        body_index: &HashMap<String, usize>,
        names: &mut HashMap<String, Range<usize>>,
    ) -> Option<Vec<Force>> {
        let mut out = Vec::new();
        for (i, rf) in raw.iter().enumerate() {
            let span = rf.span();
            let rf = rf.get_ref();
            let Some(name) = self.item_name(&rf.name, span.clone(), "force", i, names) else {
                continue;
            };
            let item = format!("force `{name}`");
            let Some(kind) = &rf.kind else {
                self.err(
                    span.clone(),
                    &item,
                    format!("{item} is missing `type`"),
                    &format!("add `type = ...`, one of {FORCE_TYPES}"),
                );
                continue;
            };
            let built = match kind.get_ref().as_str() {
                "spring" => self.spring(rf, &span, &item, bodies, body_index),
                "torsion" => self.torsion(rf, &span, &item, joints, bodies),
                "force" | "torque" => self.applied(
                    rf,
                    &span,
                    &item,
                    kind.get_ref() == "force",
                    bodies,
                    body_index,
                ),
                other => {
                    self.err(
                        kind.span(),
                        &item,
                        format!("unknown force type `{other}`"),
                        &match super::values::closest(
                            other,
                            ["spring", "torsion", "force", "torque"].into_iter(),
                        ) {
                            Some(s) => {
                                format!("did you mean \"{s}\"? supported types: {FORCE_TYPES}")
                            }
                            None => format!("supported types: {FORCE_TYPES}"),
                        },
                    );
                    None
                }
            };
            if let Some(kind) = built {
                let expr = |s: &Option<SScalar>| match s.as_ref().map(|s| s.get_ref()) {
                    Some(Scalar::Expr(e)) => Some(e.clone()),
                    _ => None,
                };
                let constants_expr = match kind {
                    ForceKind::Spring { .. } | ForceKind::Torsion { .. } => {
                        [expr(&rf.stiffness), expr(&rf.damping)]
                    }
                    _ => [None, None],
                };
                out.push(Force {
                    name,
                    kind,
                    constants_expr,
                });
            }
        }
        Some(out)
    }

    /// An optional expression in `t` (zero when absent).
    fn optional_time_expr(
        &mut self,
        s: &Option<super::raw::SStr>,
        item: &str,
        field: &str,
    ) -> Option<Id> {
        match s {
            Some(s) => self.time_expr(s, item, field, None),
            None => Some(self.arena.constant(0.0)),
        }
    }

    fn spring(
        &mut self,
        rf: &RawForce,
        span: &Range<usize>,
        item: &str,
        bodies: &[Body],
        body_index: &HashMap<String, usize>,
    ) -> Option<ForceKind> {
        let points = self.two_points(
            TwoPoints {
                body1: &rf.body1,
                body2: &rf.body2,
                at1: &rf.at1,
                at2: &rf.at2,
                point1: &rf.point1,
                point2: &rf.point2,
            },
            span,
            item,
            bodies,
            body_index,
        );
        let stiffness = self.non_negative(&rf.stiffness, item, "stiffness");
        let damping = self.non_negative(&rf.damping, item, "damping");
        let actuator = self.optional_time_expr(&rf.actuator, item, "actuator");
        let (f1, f2) = points?;
        let initial = (frame_point(bodies, &f2) - frame_point(bodies, &f1)).norm();
        let free_length = match &rf.free_length {
            Some(l) => {
                let v = self.scalar(l, item, "free_length")?;
                if v < 0.0 {
                    self.err(
                        l.span(),
                        item,
                        format!("`free_length` must not be negative, got {v}"),
                        "give the spring's unstretched length in m",
                    );
                    return None;
                }
                v
            }
            None => initial,
        };
        Some(ForceKind::Spring {
            f1,
            f2,
            stiffness: stiffness?,
            damping: damping?,
            free_length,
            actuator: actuator?,
        })
    }

    fn torsion(
        &mut self,
        rf: &RawForce,
        span: &Range<usize>,
        item: &str,
        joints: &[Joint],
        bodies: &[Body],
    ) -> Option<ForceKind> {
        let Some(jname) = &rf.joint else {
            self.err(
                span.clone(),
                item,
                format!("{item} is missing `joint`"),
                "add `joint = \"<revolute joint>\"`: a torsion spring acts in a joint",
            );
            return None;
        };
        let Some(ji) = joints.iter().position(|j| &j.name == jname.get_ref()) else {
            let s = super::values::closest(jname.get_ref(), joints.iter().map(|j| j.name.as_str()));
            self.err(
                jname.span(),
                item,
                format!("unknown joint `{}`", jname.get_ref()),
                &s.map_or("name a revolute or cylindrical joint".into(), |s| {
                    format!("did you mean `{s}`?")
                }),
            );
            return None;
        };
        if !joints[ji].kind.has_angle() {
            self.err(
                jname.span(),
                item,
                format!(
                    "joint `{}` is {}: it has no angle for a torsion spring",
                    joints[ji].name,
                    joints[ji].kind.name()
                ),
                "act on a revolute or cylindrical joint",
            );
            return None;
        }
        let stiffness = self.non_negative(&rf.stiffness, item, "stiffness");
        let damping = self.non_negative(&rf.damping, item, "damping");
        let torque = self.optional_time_expr(&rf.actuator, item, "actuator");
        let free_angle = match &rf.free_angle {
            Some(a) => self.scalar(a, item, "free_angle")?,
            None => joint_angle(bodies, &joints[ji]),
        };
        Some(ForceKind::Torsion {
            joint: ji,
            stiffness: stiffness?,
            damping: damping?,
            free_angle,
            torque: torque?,
        })
    }

    fn applied(
        &mut self,
        rf: &RawForce,
        span: &Range<usize>,
        item: &str,
        is_force: bool,
        bodies: &[Body],
        body_index: &HashMap<String, usize>,
    ) -> Option<ForceKind> {
        let b = self.body_ref(&rf.body, span, item, "body", body_index)?;
        let Some(b) = b else {
            self.err(
                rf.body.as_ref().map_or(span.clone(), |s| s.span()),
                item,
                "a load on the ground does nothing".into(),
                "name a body",
            );
            return None;
        };
        let body_axes = match rf.axes.as_ref().map(|a| (a.span(), a.get_ref().as_str())) {
            None | Some((_, "global")) => false,
            Some((_, "body")) => true,
            Some((s, other)) => {
                self.err(
                    s,
                    item,
                    format!("unknown axes `{other}`"),
                    "use \"global\" or \"body\"",
                );
                return None;
            }
        };
        let Some(value) = &rf.value else {
            self.err(
                span.clone(),
                item,
                format!("{item} is missing `value`"),
                "add `value = [fx, fy, fz]`: numbers or expressions in t",
            );
            return None;
        };
        if value.get_ref().len() != 3 {
            self.err(
                value.span(),
                item,
                format!(
                    "`value` has {} components, expected 3",
                    value.get_ref().len()
                ),
                "write `value = [x, y, z]`",
            );
            return None;
        }
        let mut v = [Id(0); 3];
        for (k, c) in value.get_ref().iter().enumerate() {
            v[k] = self.time_scalar(c, item, "value")?;
        }
        if !is_force {
            if rf.point.is_some() || rf.at.is_some() {
                self.err(
                    span.clone(),
                    item,
                    "a torque has no point of application".into(),
                    "remove `point`/`at`",
                );
                return None;
            }
            return Some(ForceKind::Torque {
                body: b,
                value: v,
                body_axes,
            });
        }
        let point = match (&rf.point, &rf.at) {
            (Some(p), None) => self.vec3(p, item, "point")?,
            (None, Some(a)) => {
                let p = v3(self.vec3(a, item, "at")?);
                let body = &bodies[b];
                arr(&(body.orientation().transpose() * (p - body.position())))
            }
            (None, None) => [0.0; 3],
            (Some(p), Some(_)) => {
                self.err(
                    p.span(),
                    item,
                    format!("{item} gives both `point` (local) and `at` (global)"),
                    "give the point of application once",
                );
                return None;
            }
        };
        Some(ForceKind::Force {
            at: Frame {
                body: Some(b),
                point,
                x: [1.0, 0.0, 0.0],
                z: [0.0, 0.0, 1.0],
            },
            value: v,
            body_axes,
        })
    }
}
