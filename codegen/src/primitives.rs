//! Constraint primitives on joint frames (docs/design.md, decision 16), one derivation each, and
//! the joints and drivers composed from them. Every joint's rows are built here.

use crate::expr::{Arena, Id};
use crate::model::{DriverTarget, Frame, Joint, JointKind, Model};
use crate::symbolic::{BodySym, M3s, V3s};

/// A joint frame in global coordinates: point and axes as expressions in `q`.
pub struct SymFrame {
    pub p: V3s,
    pub x: V3s,
    pub y: V3s,
    pub z: V3s,
}

pub fn consts(a: &mut Arena, v: [f64; 3]) -> V3s {
    v.map(|x| a.constant(x))
}

pub fn mat_vec(a: &mut Arena, m: &M3s, v: V3s) -> V3s {
    [0, 1, 2].map(|i| a.dot3(m[i], v))
}

pub fn add3(a: &mut Arena, x: V3s, y: V3s) -> V3s {
    [0, 1, 2].map(|i| a.add(x[i], y[i]))
}

pub fn sub3(a: &mut Arena, x: V3s, y: V3s) -> V3s {
    [0, 1, 2].map(|i| a.sub(x[i], y[i]))
}

/// `v × w` of constant vectors, on the arena (so that a run-time value in them stays one).
fn cross3(a: &mut Arena, v: [f64; 3], w: [f64; 3]) -> V3s {
    let (v, w) = (consts(a, v), consts(a, w));
    [(1, 2), (2, 0), (0, 1)].map(|(i, j)| {
        let p = a.mul(v[i], w[j]);
        let q = a.mul(v[j], w[i]);
        a.sub(p, q)
    })
}

/// Global position of a point fixed on a body (or a ground point).
pub fn point_world(a: &mut Arena, bodies: &[BodySym], body: Option<usize>, p: [f64; 3]) -> V3s {
    let pc = consts(a, p);
    match body {
        None => pc,
        Some(b) => {
            let w = mat_vec(a, &bodies[b].rot, pc);
            add3(a, bodies[b].r, w)
        }
    }
}

/// Global direction of a vector fixed on a body (or a ground direction).
fn direction_world(a: &mut Arena, bodies: &[BodySym], body: Option<usize>, v: [f64; 3]) -> V3s {
    let vc = consts(a, v);
    direction_world_sym(a, bodies, body, vc)
}

fn direction_world_sym(a: &mut Arena, bodies: &[BodySym], body: Option<usize>, vc: V3s) -> V3s {
    match body {
        None => vc,
        Some(b) => mat_vec(a, &bodies[b].rot, vc),
    }
}

pub fn sym_frame(a: &mut Arena, bodies: &[BodySym], f: &Frame) -> SymFrame {
    SymFrame {
        p: point_world(a, bodies, f.body, f.point),
        x: direction_world(a, bodies, f.body, f.x),
        y: {
            let y = cross3(a, f.z, f.x);
            direction_world_sym(a, bodies, f.body, y)
        },
        z: direction_world(a, bodies, f.body, f.z),
    }
}

/// Spherical: `p1 − p2 = 0` (3 rows).
pub fn spherical(a: &mut Arena, f1: &SymFrame, f2: &SymFrame) -> V3s {
    sub3(a, f1.p, f2.p)
}

/// Dot-1: two body-fixed directions stay perpendicular, `u · v = 0`.
pub fn dot1(a: &mut Arena, u: V3s, v: V3s) -> Id {
    a.dot3(u, v)
}

/// Dot-2: a body-fixed direction stays perpendicular to the line between the points,
/// `u · (p2 − p1) = 0`.
pub fn dot2(a: &mut Arena, u: V3s, f1: &SymFrame, f2: &SymFrame) -> Id {
    let d = sub3(a, f2.p, f1.p);
    a.dot3(u, d)
}

/// Distance between the two points, `|p2 − p1|`.
pub fn distance(a: &mut Arena, f1: &SymFrame, f2: &SymFrame) -> Id {
    let d = sub3(a, f2.p, f1.p);
    let d2 = a.dot3(d, d);
    a.call(crate::expr::Func::Sqrt, d2)
}

/// `(cos θ, sin θ)` of the joint angle about `z1` from `x1` to `x2`: `(x1·x2, y1·x2)`.
pub fn angle_cos_sin(a: &mut Arena, f1: &SymFrame, f2: &SymFrame) -> (Id, Id) {
    (a.dot3(f1.x, f2.x), a.dot3(f1.y, f2.x))
}

/// The rows of joint `j`, named `<joint>.<primitive>`.
pub fn joint_rows(a: &mut Arena, bodies: &[BodySym], j: &Joint) -> Vec<(String, Id)> {
    let n = |s: &str| format!("{}.{s}", j.name);
    if let JointKind::EulerPrismatic { perp, .. } = j.kind {
        return euler_prismatic(a, bodies, j, perp);
    }
    let f1 = sym_frame(a, bodies, &j.f1);
    let f2 = sym_frame(a, bodies, &j.f2);
    let mut rows = Vec::new();
    let sph = |a: &mut Arena, rows: &mut Vec<(String, Id)>| {
        let d = spherical(a, &f1, &f2);
        for (k, axis) in ["x", "y", "z"].iter().enumerate() {
            rows.push((n(axis), d[k]));
        }
    };
    let parallel = |a: &mut Arena, rows: &mut Vec<(String, Id)>| {
        rows.push((n("dot1(x1,z2)"), dot1(a, f1.x, f2.z)));
        rows.push((n("dot1(y1,z2)"), dot1(a, f1.y, f2.z)));
    };
    match j.kind {
        JointKind::Spherical => sph(a, &mut rows),
        JointKind::Revolute => {
            sph(a, &mut rows);
            parallel(a, &mut rows);
        }
        JointKind::Universal => {
            sph(a, &mut rows);
            rows.push((n("dot1(z1,z2)"), dot1(a, f1.z, f2.z)));
        }
        JointKind::Cylindrical | JointKind::Prismatic => {
            parallel(a, &mut rows);
            rows.push((n("dot2(x1,d)"), dot2(a, f1.x, &f1, &f2)));
            rows.push((n("dot2(y1,d)"), dot2(a, f1.y, &f1, &f2)));
            if j.kind == JointKind::Prismatic {
                rows.push((n("dot1(y1,x2)"), dot1(a, f1.y, f2.x)));
            }
        }
        JointKind::Fixed => {
            sph(a, &mut rows);
            parallel(a, &mut rows);
            rows.push((n("dot1(y1,x2)"), dot1(a, f1.y, f2.x)));
        }
        JointKind::Distance { length } => {
            let d = distance(a, &f1, &f2);
            let l = a.constant(length);
            rows.push((n("distance"), a.sub(d, l)));
        }
        JointKind::EulerPrismatic { .. } => unreachable!("handled above"),
    }
    rows
}

/// Whether the joint row `<joint>.<primitive>` of [`joint_rows`] measures how far apart
/// points are (metres), rather than how far axes are from their directions (cosines, or
/// the paper's Euler-angle differences: dimensionless).
pub fn joint_row_is_length(primitive: &str) -> bool {
    matches!(
        primitive,
        "x" | "y" | "z" | "distance" | "slide1" | "slide2"
    ) || primitive.starts_with("dot2")
}

/// Whether a driver's row of [`driver_row`] is in metres (else dimensionless: the sine of
/// an angle error, or an Euler angle).
pub fn driver_row_is_length(target: &DriverTarget) -> bool {
    match target {
        DriverTarget::JointAngle(_) => false,
        DriverTarget::JointSlide(_) | DriverTarget::PointDistance { .. } => true,
        DriverTarget::BodyCoordinate { coord, .. } => *coord < 3,
    }
}

/// The paper's prismatic joint (eqs. 4–8): equal Euler angles, and no motion of body 2's
/// centre of mass across the axis.
fn euler_prismatic(
    a: &mut Arena,
    bodies: &[BodySym],
    j: &Joint,
    perp: [[f64; 3]; 2],
) -> Vec<(String, Id)> {
    let (b1, b2) = (j.f1.body.unwrap_or(0), j.f2.body.unwrap_or(0));
    let mut rows = Vec::new();
    for (k, ang) in ["theta", "beta", "gamma"].iter().enumerate() {
        let e = a.sub(bodies[b2].rot_coords[k], bodies[b1].rot_coords[k]);
        rows.push((format!("{}.{ang}", j.name), e));
    }
    let d = sub3(a, bodies[b2].r, bodies[b1].r);
    for (k, p) in perp.iter().enumerate() {
        let pc = consts(a, *p);
        let u = mat_vec(a, &bodies[b1].rot, pc);
        rows.push((format!("{}.slide{}", j.name, k + 1), a.dot3(u, d)));
    }
    rows
}

/// The prescribed coordinate `s(q)` of a driver, and `∂Φ/∂s` of its row at Φ = 0.
pub fn driver_row(
    a: &mut Arena,
    bodies: &[BodySym],
    model: &Model,
    target: &DriverTarget,
    value: Id,
) -> (Id, f64) {
    match target {
        DriverTarget::JointAngle(ji) => {
            let j = &model.joints[*ji];
            let f1 = sym_frame(a, bodies, &j.f1);
            let f2 = sym_frame(a, bodies, &j.f2);
            let (c, s) = angle_cos_sin(a, &f1, &f2);
            // sin(f − θ) = sin f cos θ − cos f sin θ: smooth over any number of turns, no
            // atan2 branch; ∂/∂θ = −1 at the solution.
            let (sf, cf) = (a.sin(value), a.cos(value));
            let p = a.mul(sf, c);
            let q = a.mul(cf, s);
            (a.sub(p, q), -1.0)
        }
        DriverTarget::JointSlide(ji) => {
            let j = &model.joints[*ji];
            let dist = match j.kind {
                JointKind::EulerPrismatic { axis, .. } => {
                    let b1 = j.f1.body.unwrap_or(0);
                    let b2 = j.f2.body.unwrap_or(0);
                    let ac = consts(a, axis);
                    let u = mat_vec(a, &bodies[b1].rot, ac);
                    let dr = sub3(a, bodies[b2].r, bodies[b1].r);
                    a.dot3(u, dr)
                }
                _ => {
                    let f1 = sym_frame(a, bodies, &j.f1);
                    let f2 = sym_frame(a, bodies, &j.f2);
                    dot2(a, f1.z, &f1, &f2)
                }
            };
            (a.sub(dist, value), 1.0)
        }
        DriverTarget::BodyCoordinate { body, coord } => {
            let b = &bodies[*body];
            let q = if *coord < 3 {
                b.r[*coord]
            } else {
                b.rot_coords[*coord - 3]
            };
            (a.sub(q, value), 1.0)
        }
        DriverTarget::PointDistance { f1, f2 } => {
            let f1 = sym_frame(a, bodies, f1);
            let f2 = sym_frame(a, bodies, f2);
            let d = distance(a, &f1, &f2);
            (a.sub(d, value), 1.0)
        }
    }
}
