//! Bodies: mass properties, rotation coordinates, the initial pose (explicit, or a
//! placement between two joints) and the initial velocity.

use super::joints::JointSpec;
use super::raw::{RawBody, RawPlacement, SScalar, Scalar};
use super::{Body, Rotation, Validator};
use crate::geometry::{
    euler_angles, euler_matrix, euler_rate_matrix, matrix_quaternion, quaternion_rates, v3, M3, V3,
};
use std::collections::HashMap;
use std::ops::Range;
use toml::Spanned;

/// What a body still needs after the first pass: its placement and initial velocity.
pub(super) struct PoseSpec<'r> {
    placement: Option<&'r Spanned<RawPlacement>>,
    velocity: Option<[f64; 3]>,
    angular_velocity: Option<(Range<usize>, [f64; 3])>,
}

/// Principal inertias are sums `Σ m (other two coordinates)²`, so each is at most the sum of
/// the other two. Allowed beyond that: roundoff of inertias computed in expressions.
const TRIANGLE_SLACK: f64 = 1e-9;

/// The first principal inertia larger than the sum of the other two (beyond roundoff),
/// described for a diagnostic.
fn triangle_violation(i: [f64; 3]) -> Option<String> {
    const AXES: [&str; 3] = ["Ixx", "Iyy", "Izz"];
    let trace = i[0] + i[1] + i[2];
    (0..3).find_map(|k| {
        let (a, b) = ((k + 1) % 3, (k + 2) % 3);
        let (a, b) = (a.min(b), a.max(b));
        let others = i[a] + i[b];
        (i[k] - others > TRIANGLE_SLACK * trace).then(|| {
            format!(
                "impossible principal inertias: {} = {} > {} + {} = {}",
                AXES[k], i[k], AXES[a], AXES[b], others
            )
        })
    })
}

impl Validator<'_> {
    pub(super) fn bodies<'r>(
        &mut self,
        raw: &'r [Spanned<RawBody>],
        default_rotation: Rotation,
        names: &mut HashMap<String, Range<usize>>,
    ) -> (Vec<Body>, Vec<PoseSpec<'r>>) {
        let mut bodies = Vec::new();
        let mut poses = Vec::new();
        let mut offset = 0;
        for (i, rb) in raw.iter().enumerate() {
            let span = rb.span();
            let rb = rb.get_ref();
            let Some(bname) = self.item_name(&rb.name, span.clone(), "body", i, names) else {
                continue;
            };
            let item = format!("body `{bname}`");
            let mass = self.required_scalar(&rb.mass, &span, &item, "mass", "kg");
            if let Some(m) = mass.filter(|m| *m <= 0.0) {
                self.err(
                    rb.mass.as_ref().map_or(span.clone(), |s| s.span()),
                    &item,
                    format!("mass must be positive, got {}", super::shown(m)),
                    "give the body's mass in kg",
                );
            }
            let inertia = match &rb.inertia {
                Some(v) => self.vec3(v, &item, "inertia"),
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
                let at = rb.inertia.as_ref().map_or(span.clone(), |s| s.span());
                // Zero is allowed (a slender rod about its own axis): whether the equations
                // stay regular depends on the joints, checked at the assembled pose.
                if inr.iter().any(|x| *x < 0.0) {
                    self.err(
                        at,
                        &item,
                        format!("inertias must not be negative, got {inr:?}"),
                        "give principal inertias in kg·m² (zero only about an axis a joint \
                         fixes, e.g. a slender rod's own axis)",
                    );
                } else if let Some(message) = triangle_violation(inr) {
                    self.err(
                        at,
                        &item,
                        message,
                        "no rigid body has these inertias: each principal inertia is at most \
                         the sum of the other two (equal for a flat plate); check the values \
                         and their order [Ixx, Iyy, Izz]",
                    );
                }
            }
            let rotation = match &rb.rotation {
                Some(r) => self.rotation(r, &item).unwrap_or(default_rotation),
                None => default_rotation,
            };
            let q0 = self.explicit_pose(rb, &span, &item, rotation);
            let velocity = rb
                .velocity
                .as_ref()
                .and_then(|v| self.vec3(v, &item, "velocity"));
            let angular_velocity = rb.angular_velocity.as_ref().and_then(|v| {
                self.vec3(v, &item, "angular_velocity")
                    .map(|w| (v.span(), w))
            });
            poses.push(PoseSpec {
                placement: rb.placement.as_ref(),
                velocity,
                angular_velocity,
            });
            let n = 3 + rotation.n_coords();
            let expr = |s: Option<&SScalar>| match s.map(|s| s.get_ref()) {
                Some(Scalar::Expr(e)) => Some(e.clone()),
                _ => None,
            };
            let inertia_expr = match rb.inertia.as_ref().map(|v| v.get_ref()) {
                Some(c) if c.len() == 3 => {
                    [expr(Some(&c[0])), expr(Some(&c[1])), expr(Some(&c[2]))]
                }
                _ => [None, None, None],
            };
            bodies.push(Body {
                name: bname,
                mass: mass.unwrap_or(1.0),
                inertia: inertia.unwrap_or([1.0; 3]),
                mass_expr: expr(rb.mass.as_ref()),
                inertia_expr,
                rotation,
                offset,
                q0,
                qd0: vec![0.0; n],
            });
            offset += n;
        }
        if bodies.is_empty() && self.errors.is_empty() {
            self.err(
                0..0,
                "the file",
                "the mechanism has no bodies".into(),
                "add at least one `[[body]]`",
            );
        }
        (bodies, poses)
    }

    /// The initial coordinates from `position` and `angles` or `quaternion` (identity
    /// orientation when neither is given); zeros when the body is placed later.
    fn explicit_pose(
        &mut self,
        rb: &RawBody,
        span: &Range<usize>,
        item: &str,
        rotation: Rotation,
    ) -> Vec<f64> {
        let position = rb
            .position
            .as_ref()
            .and_then(|v| self.vec3(v, item, "position"));
        match (&rb.placement, &rb.position) {
            (Some(p), Some(_)) => self.err(
                p.span(),
                item,
                format!("{item} has both `position` and `placement`"),
                "give either `position` (and `angles` or `quaternion`), or a `placement`",
            ),
            (None, None) => self.err(
                span.clone(),
                item,
                format!("{item} has no initial pose"),
                "add `position = [x, y, z]` (and `angles = [theta, beta, gamma]` or `quaternion = [w, x, y, z]`), or a `placement`",
            ),
            _ => {}
        }
        if let (Some(_), Some(o)) = (&rb.placement, rb.angles.as_ref().or(rb.quaternion.as_ref())) {
            // The placement sets the orientation too; the file's would be ignored.
            self.err(
                o.span(),
                item,
                format!("{item} has both a `placement` and an initial orientation"),
                "a placement orients the body (local y along the line between its joints): remove `angles`/`quaternion`, or give `position` instead of the placement",
            );
        }
        if let (Some(a), Some(q)) = (&rb.angles, &rb.quaternion) {
            let _ = a;
            self.err(
                q.span(),
                item,
                format!("{item} has both `angles` and `quaternion`"),
                "give the initial orientation once",
            );
        }
        let angles = rb
            .angles
            .as_ref()
            .and_then(|v| self.vec3(v, item, "angles"));
        let quaternion = rb
            .quaternion
            .as_ref()
            .and_then(|v| self.quaternion(v, item));
        let p = position.unwrap_or([0.0; 3]);
        let mut q0 = p.to_vec();
        match (rotation, angles, quaternion) {
            // Euler angles as written, so the file's numbers reach the generated code unchanged.
            (Rotation::Euler, Some(a), _) => q0.extend(a),
            (Rotation::Euler, None, Some(e)) => {
                q0.extend(euler_angles(&crate::geometry::quaternion_matrix(e)))
            }
            (Rotation::Euler, None, None) => q0.extend([0.0; 3]),
            (Rotation::Quaternion, Some(a), _) => q0.extend(matrix_quaternion(&euler_matrix(a))),
            (Rotation::Quaternion, None, Some(e)) => q0.extend(e),
            (Rotation::Quaternion, None, None) => q0.extend([1.0, 0.0, 0.0, 0.0]),
        }
        q0
    }

    fn quaternion(&mut self, v: &super::raw::SVec, item: &str) -> Option<[f64; 4]> {
        let comps = v.get_ref();
        if comps.len() != 4 {
            self.err(
                v.span(),
                item,
                format!("`quaternion` has {} components, expected 4", comps.len()),
                "write `quaternion = [w, x, y, z]` (scalar first)",
            );
            return None;
        }
        let mut e = [0.0; 4];
        for (k, c) in comps.iter().enumerate() {
            e[k] = self.scalar(c, item, "quaternion")?;
        }
        let n = e.iter().map(|x| x * x).sum::<f64>().sqrt();
        if !(n > 1e-12) {
            self.err(
                v.span(),
                item,
                "`quaternion` is zero".into(),
                "give a rotation, e.g. [1, 0, 0, 0] for none",
            );
            return None;
        }
        Some(e.map(|x| x / n))
    }

    /// Turns the file's `velocity` and `angular_velocity` (global) into coordinate rates.
    pub(super) fn initial_velocities(&mut self, bodies: &mut [Body], poses: &[PoseSpec<'_>]) {
        for (b, pose) in bodies.iter_mut().zip(poses) {
            if let Some(v) = pose.velocity {
                b.qd0[..3].copy_from_slice(&v);
            }
            let Some((span, w)) = &pose.angular_velocity else {
                continue;
            };
            let w = v3(*w);
            let c = b.q0[3..].to_vec();
            match b.rotation {
                Rotation::Euler => {
                    let h = euler_rate_matrix([c[0], c[1], c[2]]);
                    match h.try_inverse() {
                        Some(hi) if c[1].cos().abs() > 1e-6 => {
                            let r = hi * w;
                            b.qd0[3..].copy_from_slice(&[r.x, r.y, r.z]);
                        }
                        _ => self.err(
                            span.clone(),
                            &format!("body `{}`", b.name),
                            "the body's Euler angles are singular (beta = ±90°): no angle rates give this angular velocity".into(),
                            "use `rotation = \"quaternion\"` for this body",
                        ),
                    }
                }
                Rotation::Quaternion => {
                    let e = quaternion_rates([c[0], c[1], c[2], c[3]], &w);
                    b.qd0[3..].copy_from_slice(&e);
                }
            }
        }
    }

    /// Computes the poses of bodies given by a `placement`, in dependency order.
    pub(super) fn place_bodies(
        &mut self,
        bodies: &mut [Body],
        poses: &[PoseSpec<'_>],
        joints: &[JointSpec<'_>],
        up: V3,
    ) {
        let mut placed: Vec<bool> = poses.iter().map(|p| p.placement.is_none()).collect();
        loop {
            let mut progress = false;
            for bi in 0..bodies.len() {
                if placed[bi] {
                    continue;
                }
                let Some(p) = poses[bi].placement else {
                    continue;
                };
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
                let axis_vec = end - start;
                if axis_vec.norm() < 1e-12 {
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
                let y = axis_vec.normalize();
                let raw = p.get_ref();
                let centre = match (&raw.offset_from_start, &raw.offset_from_end) {
                    (Some(s), None) => self
                        .scalar(s, &item, "offset_from_start")
                        .map(|o| start + y * o),
                    (None, Some(s)) => self
                        .scalar(s, &item, "offset_from_end")
                        .map(|o| end - y * o),
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
                placed[bi] = true;
                let Some(centre) = centre else {
                    continue;
                };
                // Local x: the horizontal (perpendicular to gravity) outward direction, made
                // perpendicular to the axis, as the paper's leg frames are defined.
                let mid = (start + end) * 0.5;
                let horiz = mid - up * mid.dot(&up);
                let x_raw = horiz - y * horiz.dot(&y);
                if x_raw.norm() < 1e-9 {
                    self.err(
                        p.span(),
                        &item,
                        format!("{item}: the body's axis passes through the vertical line of the origin, so `outward` is undefined"),
                        "give the pose explicitly with `position` and `angles`",
                    );
                    continue;
                }
                let x = x_raw.normalize();
                let z = x.cross(&y);
                let a = M3::from_columns(&[x, y, z]);
                let b = &mut bodies[bi];
                b.q0 = vec![centre.x, centre.y, centre.z];
                match b.rotation {
                    Rotation::Euler => b.q0.extend(euler_angles(&a)),
                    Rotation::Quaternion => b.q0.extend(matrix_quaternion(&a)),
                }
                progress = true;
            }
            if placed.iter().all(|p| *p) {
                return;
            }
            if !progress {
                for bi in (0..bodies.len()).filter(|b| !placed[*b]) {
                    if let Some(p) = poses[bi].placement {
                        self.err(
                            p.span(),
                            &format!("body `{}`", bodies[bi].name),
                            "placement depends on bodies that are themselves placed from it (a cycle)"
                                .into(),
                            "give one body of the cycle an explicit `position` and `angles`",
                        );
                    }
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
        joints: &[JointSpec<'_>],
        bodies: &[Body],
        placed: &[bool],
        item: &str,
    ) -> Result<Option<V3>, ()> {
        let Some(j) = joints.iter().find(|j| &j.name == name.get_ref()) else {
            let suggestion =
                super::values::closest(name.get_ref(), joints.iter().map(|j| j.name.as_str()));
            self.err(
                name.span(),
                item,
                format!("unknown joint `{}` in `placement`", name.get_ref()),
                &match suggestion {
                    Some(s) => format!("did you mean `{s}`?"),
                    None => "name a joint with a point, declared with [[joint]]".into(),
                },
            );
            return Err(());
        };
        if let Some(at) = &j.raw.at {
            return self.vec3(at, item, "at").map(|p| Some(v3(p))).ok_or(());
        }
        let points = (&j.raw.point1, &j.raw.point2);
        let (Some(p1), Some(p2)) = points else {
            self.err(
                name.span(),
                item,
                format!("`placement` joint `{}` has no joint point", j.name),
                "place a body between joints that give `at`, or `point1` and `point2`",
            );
            return Err(());
        };
        // The joint's world position is read off whichever of its bodies (other than this
        // one) is already placed; the ground is always placed.
        for (body, point) in [(j.b1, p1), (j.b2, p2)] {
            match body {
                Some(b) if b == this => {}
                None => {
                    return self
                        .vec3(point, item, "point")
                        .map(|p| Some(v3(p)))
                        .ok_or(())
                }
                Some(o) if placed[o] => {
                    let p = self.vec3(point, item, "point").ok_or(())?;
                    let b = &bodies[o];
                    return Ok(Some(b.position() + b.orientation() * v3(p)));
                }
                Some(_) => {}
            }
        }
        Ok(None)
    }
}
