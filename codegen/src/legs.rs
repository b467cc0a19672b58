//! Recognizes a six-leg platform (the Stewart–Gough structure: one body held to the ground by
//! six legs whose lengths drivers set), so that the runtime can solve its forward kinematics
//! from the six lengths instead of from the whole chain of leg bodies.
//!
//! A leg is either a point-distance driver between the ground and the platform, or two leg
//! bodies — one on the ground through a spherical or universal joint, the other on the
//! platform through a spherical joint — sliding on a prismatic, cylindrical or paper
//! prismatic joint whose slide a driver sets, with the slide axis on the line between the
//! two joint centres.
//!
//! Why the slide is the leg length plus a constant: the driver's row is `s(q) − f(t)`
//! ([`crate::primitives::driver_row`] gives ∂Φ/∂s = 1 for slide and distance drivers). The two
//! leg bodies keep their relative orientation (or, for a cylindrical joint, turn about the
//! axis), so the leg vector is `s·u + c` with `u` the slide axis and `c` fixed in the base-side
//! body; when `c` lies along `u` (checked at `q0`, the joint centres on the axis for a
//! cylindrical joint) the leg length is `s + k` with `k` constant as long as the leg's own
//! joints hold. Hence the prescribed length is `|leg(q)| − Φ_row(q, t)` for any such `q`, which
//! the runtime relies on (`symbody_runtime::LegInfo::row`).
//! A slide measured from the platform side towards the base would have slope −1 in the
//! length; such a leg is not recognized.

use crate::geometry::{euler_matrix, quaternion_matrix, v3, M3, V3};
use crate::model::{BodyRef, DriverTarget, Frame, Joint, JointKind, Model, Rotation};

/// Relative tolerance for "the slide axis lies on the leg line" at `q0`.
const ALIGNED: f64 = 1e-9;

/// One leg of a detected platform.
#[derive(Debug, Clone, PartialEq)]
pub struct Leg {
    /// Index of the driver setting the leg's length.
    pub driver: usize,
    /// Base joint centre, global.
    pub base: [f64; 3],
    /// Platform joint centre, local to the platform body.
    pub platform: [f64; 3],
    /// The driver's row in Φ.
    pub row: usize,
}

/// A body held to the ground by six legs of driven length.
#[derive(Debug, Clone, PartialEq)]
pub struct Platform {
    pub body: usize,
    /// The legs in driver order.
    pub legs: Vec<Leg>,
}

/// A leg candidate: the platform body, the leg, and the platform-side joint (if any).
struct Candidate {
    body: usize,
    leg: Leg,
    platform_joint: Option<usize>,
}

/// Pose of a body (or the ground) at coordinates `q`.
fn pose(model: &Model, q: &[f64], b: BodyRef) -> (V3, M3) {
    let Some(i) = b else {
        return (V3::zeros(), M3::identity());
    };
    let body = &model.bodies[i];
    let c = &q[body.offset..body.offset + body.n_coords()];
    let rot = match body.rotation {
        Rotation::Euler => euler_matrix([c[3], c[4], c[5]]),
        Rotation::Quaternion => quaternion_matrix([c[3], c[4], c[5], c[6]]),
    };
    (V3::new(c[0], c[1], c[2]), rot)
}

fn world(model: &Model, q: &[f64], f: &Frame) -> V3 {
    let (r, a) = pose(model, q, f.body);
    r + a * v3(f.point)
}

fn touches(j: &Joint, b: usize) -> bool {
    j.f1.body == Some(b) || j.f2.body == Some(b)
}

/// The frame of `j` on `body` and the other frame, when `j` has a frame on `body`.
fn split(j: &Joint, body: BodyRef) -> Option<(&Frame, &Frame)> {
    if j.f1.body == body {
        Some((&j.f1, &j.f2))
    } else if j.f2.body == body {
        Some((&j.f2, &j.f1))
    } else {
        None
    }
}

/// Whether driver `k` acts on body `b` (through its joint, its coordinate or its points).
fn drives(model: &Model, k: usize, b: usize) -> bool {
    match &model.drivers[k].target {
        DriverTarget::JointAngle(j) | DriverTarget::JointSlide(j) => touches(&model.joints[*j], b),
        DriverTarget::BodyCoordinate { body, .. } => *body == b,
        DriverTarget::PointDistance { f1, f2 } => f1.body == Some(b) || f2.body == Some(b),
    }
}

/// `u` and `d` are parallel within [`ALIGNED`].
fn parallel(u: &V3, d: &V3) -> bool {
    u.cross(d).norm() <= ALIGNED * u.norm() * d.norm()
}

/// Driver `k` as a leg, if it is one.
fn leg(model: &Model, q0: &[f64], k: usize, row: usize) -> Option<Candidate> {
    match &model.drivers[k].target {
        DriverTarget::PointDistance { f1, f2 } => {
            let (base, top) = match (f1.body, f2.body) {
                (None, Some(_)) => (f1, f2),
                (Some(_), None) => (f2, f1),
                _ => return None,
            };
            Some(Candidate {
                body: top.body?,
                leg: Leg {
                    driver: k,
                    base: base.point,
                    platform: top.point,
                    row,
                },
                platform_joint: None,
            })
        }
        DriverTarget::JointSlide(ji) => slide_leg(model, q0, k, *ji, row),
        _ => None,
    }
}

/// An S-P-S or U-P-S leg whose slide joint `ji` driver `k` sets.
fn slide_leg(model: &Model, q0: &[f64], k: usize, ji: usize, row: usize) -> Option<Candidate> {
    let slide = &model.joints[ji];
    if !slide.kind.has_slide() {
        return None;
    }
    let (Some(a), Some(b)) = slide.bodies() else {
        return None;
    };
    // The leg bodies carry nothing but the leg: anything else would make the length alone
    // not determine the platform, or the leg bodies not follow from it.
    let others: Vec<usize> = (0..model.joints.len())
        .filter(|&i| i != ji && (touches(&model.joints[i], a) || touches(&model.joints[i], b)))
        .collect();
    let extra_driver =
        (0..model.drivers.len()).any(|d| d != k && (drives(model, d, a) || drives(model, d, b)));
    if others.len() != 2 || extra_driver {
        return None;
    }
    let is_base = |i: usize| {
        let j = &model.joints[i];
        matches!(j.kind, JointKind::Spherical | JointKind::Universal)
            && (j.f1.body.is_none() || j.f2.body.is_none())
    };
    let (gi, si) = match (is_base(others[0]), is_base(others[1])) {
        (true, false) => (others[0], others[1]),
        (false, true) => (others[1], others[0]),
        _ => return None,
    };
    let (ground_joint, top_joint) = (&model.joints[gi], &model.joints[si]);
    let (base_frame, lower_frame) = split(ground_joint, None)?;
    let lower = lower_frame.body?;
    let upper = if lower == a { b } else { a };
    if top_joint.kind != JointKind::Spherical {
        return None;
    }
    let (_, top_frame) = split(top_joint, Some(upper))?;
    let body = top_frame.body?;
    if body == a || body == b {
        return None;
    }

    let base = v3(base_frame.point);
    let top = world(model, q0, top_frame);
    let (_, rot1) = pose(model, q0, slide.f1.body);
    let u = match slide.kind {
        JointKind::EulerPrismatic { axis, .. } => rot1 * v3(axis),
        _ => rot1 * v3(slide.f1.z),
    };
    let d = top - base;
    // s grows along u from body 1 to body 2: the length grows with s only when u points
    // from the base towards the platform and body 1 is the base side, or the reverse.
    let along = u.dot(&d) > 0.0;
    if !parallel(&u, &d) || along != (slide.f1.body == Some(lower)) {
        return None;
    }
    // A cylindrical joint lets the upper body turn about the axis: its joint centre must
    // then lie on the axis, or the leg length would change with that turn.
    if slide.kind == JointKind::Cylindrical && !parallel(&u, &(top - world(model, q0, &slide.f1))) {
        return None;
    }
    Some(Candidate {
        body,
        leg: Leg {
            driver: k,
            base: base_frame.point,
            platform: top_frame.point,
            row,
        },
        platform_joint: Some(si),
    })
}

/// The six-leg platform of `model`, if it is one; `q0` are the assembled initial coordinates.
pub fn detect(model: &Model, q0: &[f64]) -> Option<Platform> {
    // Drivers' rows follow every joint row, one each, in driver order (equations::build).
    let first_driver_row: usize = model.joints.iter().map(Joint::rows).sum();
    let legs: Vec<Candidate> = (0..model.drivers.len())
        .filter_map(|k| leg(model, q0, k, first_driver_row + k))
        .collect();
    if legs.len() != 6 {
        return None;
    }
    let body = legs[0].body;
    if legs.iter().any(|c| c.body != body) {
        return None;
    }
    // Anything else on the platform would constrain it beyond the six lengths.
    let leg_joints: Vec<usize> = legs.iter().filter_map(|c| c.platform_joint).collect();
    let foreign_joint = (0..model.joints.len())
        .any(|i| touches(&model.joints[i], body) && !leg_joints.contains(&i));
    let foreign_driver = (0..model.drivers.len())
        .any(|d| drives(model, d, body) && !legs.iter().any(|c| c.leg.driver == d));
    if foreign_joint || foreign_driver {
        return None;
    }
    Some(Platform {
        body,
        legs: legs.into_iter().map(|c| c.leg).collect(),
    })
}
