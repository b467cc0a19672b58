//! Joint reaction wrenches and driver efforts from the Lagrange multipliers, with the sign
//! convention of docs/design.md, decision 7 (`M q̈ + Φqᵀλ = Q`): joint `k` acts on body `i` with the
//! generalized force `−(Φᵏ_{q_i})ᵀλᵏ` on the body's coordinates.
//!
//! A generalized force `g` on a body's coordinates is turned into a force and a torque by
//! virtual work: the translational part is the force `F`; the rotational part satisfies
//! `g_rot = J_ωᵀ τ` with `ω = J_ω q̇_rot` ([`crate::pose::angular_velocity_jacobian`]), so
//! `τ = H⁻ᵀ g_rot` for Euler angles and `τ = E(e) g_rot / (2|e|²)` for a quaternion (the
//! component of `g_rot` along `e`, which the normalization row absorbs, is discarded since
//! `E e = 0`).

use nalgebra::{Matrix3, Matrix3x4, Vector3};

use crate::error::{check_len, Error};
use crate::mechanism::{BodyInfo, JointInfo, JointKind, MechanismInfo, Rotation};
use crate::pose;

/// A force and a moment, global frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wrench {
    /// Force (N).
    pub force: [f64; 3],
    /// Moment about the stated point (N·m).
    pub moment: [f64; 3],
}

/// |cos β| below which an Euler body's torque is not recoverable: the inverse of `Hᵀ`
/// would amplify roundoff in the multipliers by more than 10¹².
const SINGULAR_COS: f64 = 1e-12;

fn joint_info(info: &MechanismInfo, joint: usize) -> Result<&JointInfo, Error> {
    info.joints.get(joint).ok_or(Error::InvalidIndex {
        what: "joint",
        index: joint,
        reason: "no such joint",
    })
}

/// The wrench joint `joint` exerts on its body 1 (global frame), the moment taken about the
/// joint point on the moving body at the current pose: `P = r₁ + A₁·point1` on body 1, or,
/// when body 1 is the ground, `P = r₂ + A₂·point2` on body 2 and the wrench is the one on the
/// ground (minus the wrench on body 2, about that point). The two joint points coincide for
/// joints that hold a point (spherical, revolute, universal, fixed); a sliding joint's
/// (prismatic, cylindrical) do not, and the point that slides with the body is the one that
/// keeps meaning as it travels — the ground's is only where the joint was written.
///
/// `q`, `phi_q` and `lambda` must belong to one state. With redundant rows the multipliers
/// are one valid choice among many, and so are the wrenches of the joints involved.
/// Normalization rows are not joints and are refused.
pub fn joint_wrench(
    info: &MechanismInfo,
    q: &[f64],
    phi_q: &[f64],
    lambda: &[f64],
    joint: usize,
) -> Result<Wrench, Error> {
    check_len("q", info.n_coords, q.len())?;
    check_len("Φq nonzeros", info.phi_q_nnz(), phi_q.len())?;
    check_len("lambda", info.n_constraints, lambda.len())?;
    let end = JointEnd::new(info, joint)?;
    let g = generalized_force(end.entries(info), phi_q, lambda);
    end.wrench(&g, &Frame::new(end.body, q)?)
}

/// Every listed joint's wrench at a state, as [`joint_wrench`] gives each (the same
/// operations in the same order, so the same bits), with each joint's Φq entries on its
/// body found once and each body's frame computed once per state: for a recording that
/// asks at every output (a Stewart platform's 18 joints share 13 bodies).
#[derive(Debug, Clone)]
pub struct JointWrenches {
    info: &'static MechanismInfo,
    joints: Vec<usize>,
    /// Per joint: where its wrench acts, and its Φq entries on that body.
    ends: Vec<(JointEnd<'static>, Entries)>,
    /// Per body, its frame at the state of the current call, made on first use.
    frames: Vec<Option<Result<Frame, Error>>>,
}

/// `(nonzero, row, coordinate of the body)` of a joint's Φq entries on its body, in the
/// pattern's order.
type Entries = Vec<(usize, usize, usize)>;

impl JointWrenches {
    /// For `joints` (indices in `info.joints`), each refused as [`joint_wrench`] refuses it.
    pub fn new(info: &'static MechanismInfo, joints: &[usize]) -> Result<Self, Error> {
        let ends = joints
            .iter()
            .map(|&joint| {
                let end = JointEnd::new(info, joint)?;
                let terms = end.entries(info).collect();
                Ok((end, terms))
            })
            .collect::<Result<_, Error>>()?;
        Ok(JointWrenches {
            info,
            joints: joints.to_vec(),
            ends,
            frames: vec![None; info.bodies.len()],
        })
    }

    /// The joints, in the order of the wrenches.
    pub fn joints(&self) -> &[usize] {
        &self.joints
    }

    /// The wrenches at the state whose `q`, Φq nonzeros and multipliers are given, one per
    /// joint in order, written over `out`.
    pub fn wrenches(
        &mut self,
        q: &[f64],
        phi_q: &[f64],
        lambda: &[f64],
        out: &mut Vec<Wrench>,
    ) -> Result<(), Error> {
        let info = self.info;
        check_len("q", info.n_coords, q.len())?;
        check_len("Φq nonzeros", info.phi_q_nnz(), phi_q.len())?;
        check_len("lambda", info.n_constraints, lambda.len())?;
        self.frames.fill(None);
        out.clear();
        for (end, terms) in &self.ends {
            let g = generalized_force(terms.iter().copied(), phi_q, lambda);
            let frame = self.frames[end.index].get_or_insert_with(|| Frame::new(end.body, q));
            out.push(end.wrench(&g, frame.as_ref().map_err(Clone::clone)?)?);
        }
        Ok(())
    }
}

/// `g = −(Φ^rows_{q_i})ᵀ λ^rows` on a body's coordinates from a joint's Φq `entries`
/// (`(nonzero, row, coordinate of the body)`, summed in their order).
fn generalized_force(
    entries: impl Iterator<Item = (usize, usize, usize)>,
    phi_q: &[f64],
    lambda: &[f64],
) -> [f64; 7] {
    let mut g = [0.0; 7];
    for (k, r, c) in entries {
        g[c] -= phi_q[k] * lambda[r];
    }
    g
}

/// Where joint `joint`'s wrench acts: its body 1, or body 2 when body 1 is the ground (then
/// the wrench is the one on the ground), with the joint's rows, the body's coordinates and
/// the joint point on it.
#[derive(Debug, Clone)]
struct JointEnd<'a> {
    body: &'a BodyInfo,
    /// The body's index in `info.bodies`.
    index: usize,
    on_ground: bool,
    rows: std::ops::Range<usize>,
    cols: std::ops::Range<usize>,
    point: &'a [f64; 3],
}

impl<'a> JointEnd<'a> {
    fn new(info: &'a MechanismInfo, joint: usize) -> Result<Self, Error> {
        let j = joint_info(info, joint)?;
        if j.kind == JointKind::Normalization {
            return Err(Error::InvalidIndex {
                what: "joint",
                index: joint,
                reason: "a normalization row exerts no wrench",
            });
        }
        let (index, on_ground) = match (j.body1, j.body2) {
            (Some(b), _) => (b, false),
            (None, Some(b)) => (b, true),
            (None, None) => {
                return Err(Error::InvalidIndex {
                    what: "joint",
                    index: joint,
                    reason: "the joint connects no body",
                })
            }
        };
        let body = info.bodies.get(index).ok_or(Error::InvalidIndex {
            what: "body",
            index,
            reason: "the joint names a body that does not exist",
        })?;
        let rows = j.row_start..j.row_start + j.rows;
        let cols = body.coord_offset..body.coord_offset + body.n_coords();
        if cols.end > info.n_coords || rows.end > info.n_constraints {
            return Err(Error::InvalidIndex {
                what: "joint",
                index: joint,
                reason: "its rows or its body's coordinates lie outside the mechanism",
            });
        }
        let point = if on_ground { &j.point2 } else { &j.point1 };
        Ok(JointEnd {
            body,
            index,
            on_ground,
            rows,
            cols,
            point,
        })
    }

    /// `(nonzero, row, coordinate of the body)` of the joint's Φq entries on its body, in
    /// the pattern's order.
    fn entries<'i>(
        &'i self,
        info: &'i MechanismInfo,
    ) -> impl Iterator<Item = (usize, usize, usize)> + 'i {
        rows_nonzeros(info, &self.rows).filter_map(move |k| {
            let (r, c) = (info.phi_q_rows[k] as usize, info.phi_q_cols[k] as usize);
            (self.rows.contains(&r) && self.cols.contains(&c)).then_some((
                k,
                r,
                c - self.cols.start,
            ))
        })
    }

    /// The wrench from the generalized force `g` on the body's coordinates.
    fn wrench(&self, g: &[f64; 7], frame: &Frame) -> Result<Wrench, Error> {
        let force = Vector3::new(g[0], g[1], g[2]);
        let torque = match &frame.torque {
            Torque::Euler(ht_inv) => {
                ht_inv.as_ref().map_err(Clone::clone)? * Vector3::new(g[3], g[4], g[5])
            }
            Torque::Quaternion(jw, e2) => {
                jw * nalgebra::Vector4::new(g[3], g[4], g[5], g[6]) / (4.0 * e2)
            }
        };
        let p = frame.r + frame.rotation * Vector3::from(*self.point);
        let moment = torque - (p - frame.r).cross(&force);
        let sign = if self.on_ground { -1.0 } else { 1.0 };
        Ok(Wrench {
            force: (sign * force).into(),
            moment: (sign * moment).into(),
        })
    }
}

/// What a body's wrenches need of its pose: its reference point, its rotation and the map
/// from the generalized force on its rotation coordinates to the torque.
#[derive(Debug, Clone)]
struct Frame {
    r: Vector3<f64>,
    rotation: Matrix3<f64>,
    torque: Torque,
}

#[derive(Debug, Clone)]
enum Torque {
    /// `H⁻ᵀ`, or why the Euler angles do not determine the torque here.
    Euler(Result<Matrix3<f64>, Error>),
    /// `J_ω = 2E` and `|e|²`.
    Quaternion(Matrix3x4<f64>, f64),
}

impl Frame {
    fn new(b: &BodyInfo, q: &[f64]) -> Result<Self, Error> {
        let o = b.coord_offset;
        let jw = pose::angular_velocity_jacobian(b, q)?;
        let torque = match b.rotation {
            Rotation::Euler => {
                let h: Matrix3<f64> = jw.fixed_columns::<3>(0).into_owned();
                let beta = q[o + 4];
                let singular = || Error::EulerSingularity {
                    time: f64::NAN,
                    body: b.name,
                    beta,
                };
                // det H = cos β: at the singularity the Euler-angle forces do not determine
                // τ (one torque component does no work on any angle rate).
                Torque::Euler(if !(beta.cos().abs() > SINGULAR_COS) {
                    Err(singular())
                } else {
                    h.transpose().try_inverse().ok_or_else(singular)
                })
            }
            Rotation::Quaternion => {
                // J_ω = 2E: τ = (2E)ᵀ⁺ g_rot = E g_rot / (2|e|²), since E Eᵀ = |e|² I.
                let e2: f64 = q[o + 3..o + 7].iter().map(|x| x * x).sum();
                Torque::Quaternion(jw, e2)
            }
        };
        Ok(Frame {
            r: Vector3::new(q[o], q[o + 1], q[o + 2]),
            rotation: pose::rotation_matrix(b, q)?,
            torque,
        })
    }
}

/// The effort of driver `joint` along its driven coordinate (force in N or torque in N·m,
/// [`JointInfo::effort_unit`]): `−effort_sign · λ` of its row.
pub fn driver_effort(info: &MechanismInfo, lambda: &[f64], joint: usize) -> Result<f64, Error> {
    check_len("lambda", info.n_constraints, lambda.len())?;
    let j = joint_info(info, joint)?;
    if j.kind != JointKind::Driver || j.rows != 1 {
        return Err(Error::InvalidIndex {
            what: "joint",
            index: joint,
            reason: "not a one-row driver",
        });
    }
    lambda
        .get(j.row_start)
        .map(|l| -j.effort_sign * l)
        .ok_or(Error::InvalidIndex {
            what: "constraint row",
            index: j.row_start,
            reason: "driver row outside λ",
        })
}

/// Force (global X, Y, Z) that joint `joint` exerts on body `body`: `−(Φᵏ_{r_i})ᵀ λᵏ`, where
/// `Φᵏ_{r_i}` are the joint's rows of `Φq` in the body's three translational columns.
///
/// `phi_q` holds the Jacobian's nonzeros at the state the multipliers `lambda` belong to.
/// Allocates nothing; a recording that asks at every output finds the entries once with
/// [`ForceOnBody`].
pub fn joint_force(
    info: &MechanismInfo,
    phi_q: &[f64],
    lambda: &[f64],
    joint: usize,
    body: usize,
) -> Result<[f64; 3], Error> {
    check_len("Φq nonzeros", info.phi_q_nnz(), phi_q.len())?;
    check_len("lambda", info.n_constraints, lambda.len())?;
    let mut f = [0.0; 3];
    for (k, r, c) in force_terms(info, joint, body)? {
        f[c] -= phi_q[k] * lambda[r];
    }
    Ok(f)
}

/// The Φq entries of joint `joint`'s rows in body `body`'s translational columns, as
/// `(nonzero, row, component)` in the pattern's order; the joint must connect the body.
fn force_terms(
    info: &MechanismInfo,
    joint: usize,
    body: usize,
) -> Result<impl Iterator<Item = (usize, usize, usize)> + '_, Error> {
    let j = info.joints.get(joint).ok_or(Error::InvalidIndex {
        what: "joint",
        index: joint,
        reason: "no such joint",
    })?;
    let b = info.bodies.get(body).ok_or(Error::InvalidIndex {
        what: "body",
        index: body,
        reason: "no such body",
    })?;
    if j.body1 != Some(body) && j.body2 != Some(body) {
        return Err(Error::InvalidIndex {
            what: "body",
            index: body,
            reason: "the joint does not connect this body",
        });
    }
    let rows = j.row_start..j.row_start + j.rows;
    let cols = b.coord_offset..b.coord_offset + 3;
    Ok(rows_nonzeros(info, &rows).filter_map(move |k| {
        let (r, c) = (info.phi_q_rows[k] as usize, info.phi_q_cols[k] as usize);
        (rows.contains(&r) && cols.contains(&c)).then_some((k, r, c - cols.start))
    }))
}

/// [`joint_force`] with the joint's Φq entries in the body's columns found once, for a
/// recording that asks at every output.
#[derive(Debug, Clone)]
pub struct ForceOnBody {
    /// The mechanism's sizes, to check the arrays given.
    nnz: usize,
    n_constraints: usize,
    /// `(nonzero, row, component)` of each entry, in the pattern's order.
    terms: Vec<(usize, usize, usize)>,
}

impl ForceOnBody {
    /// The force of joint `joint` on body `body`, which it must connect.
    pub fn new(info: &MechanismInfo, joint: usize, body: usize) -> Result<Self, Error> {
        Ok(ForceOnBody {
            nnz: info.phi_q_nnz(),
            n_constraints: info.n_constraints,
            terms: force_terms(info, joint, body)?.collect(),
        })
    }

    /// The force at the state whose Φq nonzeros and multipliers are given.
    pub fn force(&self, phi_q: &[f64], lambda: &[f64]) -> Result<[f64; 3], Error> {
        check_len("Φq nonzeros", self.nnz, phi_q.len())?;
        check_len("lambda", self.n_constraints, lambda.len())?;
        let mut f = [0.0; 3];
        for &(k, r, c) in &self.terms {
            f[c] -= phi_q[k] * lambda[r];
        }
        Ok(f)
    }
}

/// The nonzeros of Φq that may lie in `rows`: in a row-major pattern (as `MechanismInfo`
/// documents, and every generated one is) one run, found by bisection, so a reaction's sums
/// cost its own entries; all of them otherwise. Checking the order is one pass of integer
/// comparisons, kept so that a hand-written pattern out of order is summed right, not fast;
/// the generator's own pattern (known by its KKT kernels' statics) skips it.
fn rows_nonzeros(info: &MechanismInfo, rows: &std::ops::Range<usize>) -> std::ops::Range<usize> {
    let all = info.phi_q_rows;
    let generated = info
        .kkt
        .first()
        .is_some_and(|k| k.emitted_for(all, info.phi_q_cols));
    match generated || all.is_sorted() {
        true => {
            let at = |row: usize| all.partition_point(|&r| (r as usize) < row);
            at(rows.start)..at(rows.end)
        }
        false => 0..all.len(),
    }
}

/// Force of a driver (a one-row joint of kind [`JointKind::Driver`]): `−λ` of its row.
/// For a driver written as distance minus `c(t)` this is the force along the driven
/// direction, positive pushing the bodies apart.
pub fn actuator_force(info: &MechanismInfo, lambda: &[f64], joint: usize) -> Result<f64, Error> {
    check_len("lambda", info.n_constraints, lambda.len())?;
    let j = info.joints.get(joint).ok_or(Error::InvalidIndex {
        what: "joint",
        index: joint,
        reason: "no such joint",
    })?;
    if j.kind != JointKind::Driver || j.rows != 1 {
        return Err(Error::InvalidIndex {
            what: "joint",
            index: joint,
            reason: "not a one-row driver",
        });
    }
    lambda
        .get(j.row_start)
        .map(|l| -l)
        .ok_or(Error::InvalidIndex {
            what: "constraint row",
            index: j.row_start,
            reason: "driver row outside λ",
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::{InitialVelocity, Kinematics};
    use crate::kkt::tests::Rng;
    use crate::kkt::SchurKkt;
    use crate::mechanism::Mechanism;
    use crate::mechanism::{BodyInfo, Formulation};
    use crate::testmodels::{
        CircleDriver, Pendulum, TwoBallHinge, CIRCLE_C0, CIRCLE_D, CIRCLE_MASS, G, PENDULUM_LENGTH,
        PENDULUM_MASS,
    };

    fn start<M: Mechanism>(mech: &M) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let info = mech.info();
        let mut kin = Kinematics::<SchurKkt>::new(info).unwrap();
        let mut q = info.q0.to_vec();
        let (mut qd, mut qdd) = (vec![0.0; info.n_coords], vec![0.0; info.n_coords]);
        let mut lam = vec![0.0; info.n_constraints];
        kin.consistent_start(
            mech,
            0.0,
            InitialVelocity::LeastKineticEnergy,
            &mut q,
            &mut qd,
            &mut qdd,
            &mut lam,
        )
        .unwrap();
        let mut pq = vec![0.0; info.phi_q_nnz()];
        mech.phi_q(&q, 0.0, &mut pq);
        (q, pq, lam)
    }

    #[test]
    fn hanging_pendulum_is_held_up_by_its_weight() {
        // At rest the pivot must carry the weight: force on the bob = +m g along +Y.
        let mech = Pendulum::paper();
        let (_, pq, lam) = start(&mech);
        let f = joint_force(mech.info(), &pq, &lam, 0, 0).unwrap();
        let w = PENDULUM_MASS * G;
        assert!(f[0].abs() < 1e-12 && f[2].abs() < 1e-12, "{f:?}");
        assert!((f[1] - w).abs() < 1e-12 * w, "{f:?}");
    }

    #[test]
    fn lift_driver_pushes_the_slider_up() {
        // At t = 0 the slider sits at (d, 0.4) with Ÿ = (ċ² − Ẏ²)/Y; the driver pushes
        // along the radius with vertical share Y/c of m(g + Ÿ).
        let mech = CircleDriver;
        let (_, pq, lam) = start(&mech);
        let y = 0.4;
        let cd = -crate::testmodels::CIRCLE_V;
        let yd = CIRCLE_C0 * cd / y;
        let ydd = (cd * cd - yd * yd) / y;
        let expect = CIRCLE_MASS * (G + ydd) * CIRCLE_C0 / y;
        let a = actuator_force(mech.info(), &lam, 1).unwrap();
        assert!((a - expect).abs() < 1e-9 * expect, "{a} vs {expect}");
        // The guide only pushes horizontally against the driver's X share.
        let g = joint_force(mech.info(), &pq, &lam, 0, 0).unwrap();
        assert!((g[0] + expect * CIRCLE_D / CIRCLE_C0).abs() < 1e-9 * expect);
        assert!(g[1].abs() < 1e-12);
    }

    #[test]
    fn bad_indices_are_errors() {
        let mech = CircleDriver;
        let (_, pq, lam) = start(&mech);
        let info = mech.info();
        assert!(actuator_force(info, &lam, 0).is_err());
        assert!(actuator_force(info, &lam, 9).is_err());
        assert!(joint_force(info, &pq, &lam, 0, 3).is_err());
        assert!(joint_force(info, &pq[1..], &lam, 0, 0).is_err());
    }

    fn norm(v: [f64; 3]) -> f64 {
        Vector3::from(v).norm()
    }

    #[test]
    fn hanging_exact_pendulum_has_no_moment_about_its_pivot() {
        let mech = Pendulum::exact();
        let (q, pq, lam) = start(&mech);
        let w = joint_wrench(mech.info(), &q, &pq, &lam, 0).unwrap();
        let mg = PENDULUM_MASS * G;
        assert!(
            (w.force[1] - mg).abs() < 1e-12 * mg && w.force[0].abs() < 1e-12,
            "{w:?}"
        );
        assert!(norm(w.moment) < 1e-12 * mg * PENDULUM_LENGTH, "{w:?}");
    }

    /// A random state on the constraint manifold with a random consistent velocity, and
    /// the accelerations and multipliers there.
    fn moving_state<M: Mechanism>(
        mech: &M,
        rng: &mut Rng,
        q: &mut [f64],
    ) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let info = mech.info();
        let mut kin = Kinematics::<SchurKkt>::new(info).unwrap();
        let mut qd: Vec<f64> = (0..info.n_coords).map(|_| 2.0 * rng.uniform()).collect();
        let mut qdd = vec![0.0; info.n_coords];
        let mut lam = vec![0.0; info.n_constraints];
        kin.consistent_start(
            mech,
            0.0,
            InitialVelocity::ProjectGiven,
            q,
            &mut qd,
            &mut qdd,
            &mut lam,
        )
        .unwrap();
        let mut pq = vec![0.0; info.phi_q_nnz()];
        mech.phi_q(q, 0.0, &mut pq);
        (qdd, pq, lam)
    }

    #[test]
    fn ball_joints_transmit_no_moment_about_their_points_while_moving() {
        // Spinning and swinging: the reaction about the ball's centre must vanish, which
        // tests τ from the rotational multipliers and its transfer to the joint point.
        let mut rng = Rng::new(31);
        let mech = Pendulum::exact();
        for trial in 0..10 {
            let mut q = [
                0.0,
                0.0,
                0.0,
                rng.uniform(),
                rng.uniform(),
                2.0 * rng.uniform(),
            ];
            let (qdd, pq, lam) = moving_state(&mech, &mut rng, &mut q);
            let w = joint_wrench(mech.info(), &q, &pq, &lam, 0).unwrap();
            let scale = norm(w.force) * PENDULUM_LENGTH;
            assert!(norm(w.moment) < 1e-11 * scale, "trial {trial}: {w:?}");
            // Newton for the centre of mass: F + m g = m r̈ (g = −G ŷ).
            let newton = Vector3::from(w.force)
                - PENDULUM_MASS * G * Vector3::y()
                - PENDULUM_MASS * Vector3::new(qdd[0], qdd[1], qdd[2]);
            assert!(newton.norm() < 1e-10 * scale, "trial {trial}: {newton}");
        }
        // The hinge's two balls, each about its own point (the transfer differs by 2a).
        let mech = TwoBallHinge::new(0.0);
        for trial in 0..5 {
            let mut q = mech.info().q0.to_vec();
            q[5] = 2.0 * rng.uniform();
            let (qdd, pq, lam) = moving_state(&mech, &mut rng, &mut q);
            let w1 = joint_wrench(mech.info(), &q, &pq, &lam, 0).unwrap();
            let w2 = joint_wrench(mech.info(), &q, &pq, &lam, 1).unwrap();
            let scale = (norm(w1.force) + norm(w2.force)) * PENDULUM_LENGTH;
            assert!(norm(w1.moment) < 1e-11 * scale, "trial {trial}: {w1:?}");
            assert!(norm(w2.moment) < 1e-11 * scale, "trial {trial}: {w2:?}");
            let total = Vector3::from(w1.force) + Vector3::from(w2.force);
            let expect = PENDULUM_MASS * (Vector3::new(qdd[0], qdd[1], qdd[2]) + G * Vector3::y());
            assert!(
                (total - expect).norm() < 1e-10 * scale,
                "{total} vs {expect}"
            );
        }
    }

    const S_LOCAL: [f64; 3] = [0.3, -0.2, 0.5];
    const P_GLOBAL: [f64; 3] = [1.0, 2.0, -0.5];
    /// The ground joint's point on the body: apart from `S_LOCAL` and from `P_GLOBAL`, as a
    /// slider's point is away from the guide's ground point once it has travelled.
    const T_LOCAL: [f64; 3] = [-0.4, 0.1, 0.25];

    /// One body under an identity "joint" on all its coordinates (`Φq = I`), seen from the
    /// body (`probe`, point `S_LOCAL`) and from the ground (`probe_ground`, ground point
    /// `P_GLOBAL`, body point `T_LOCAL`).
    macro_rules! probe_info {
        ($name:ident, $rotation:expr, $n:literal, $rows:expr) => {
            static $name: MechanismInfo = MechanismInfo {
                name: "probe",
                n_coords: $n,
                n_constraints: $n,
                formulation: Formulation::Exact,
                gravity: [0.0; 3],
                phi_q_rows: &$rows,
                phi_q_cols: &$rows,
                mass_rows: &[],
                mass_cols: &[],
                mass_is_constant: true,
                force_q_rows: &[],
                force_q_cols: &[],
                force_qd_rows: &[],
                force_qd_cols: &[],
                bodies: &[BodyInfo {
                    name: "b",
                    coord_offset: 0,
                    rotation: $rotation,
                    mass: 1.0,
                    inertia: [1.0; 3],
                }],
                joints: &[
                    JointInfo {
                        name: "probe",
                        kind: JointKind::Fixed,
                        body1: Some(0),
                        body2: None,
                        row_start: 0,
                        rows: $n,
                        point1: S_LOCAL,
                        point2: [0.0; 3],
                        effort_sign: 0.0,
                        effort_unit: "",
                    },
                    JointInfo {
                        name: "probe_ground",
                        kind: JointKind::Fixed,
                        body1: None,
                        body2: Some(0),
                        row_start: 0,
                        rows: $n,
                        point1: P_GLOBAL,
                        point2: T_LOCAL,
                        effort_sign: 0.0,
                        effort_unit: "",
                    },
                    JointInfo {
                        name: "norm",
                        kind: JointKind::Normalization,
                        body1: Some(0),
                        body2: None,
                        row_start: $n - 1,
                        rows: 1,
                        point1: [0.0; 3],
                        point2: [0.0; 3],
                        effort_sign: 0.0,
                        effort_unit: "",
                    },
                ],
                coord_names: &[],
                row_names: &[],
                q0: &[],
                qd0: &[],
                redundant_rows: &[],
                platform: None,
                kkt: &[],
            };
        };
    }
    probe_info!(PROBE_EULER, Rotation::Euler, 6, [0, 1, 2, 3, 4, 5]);
    probe_info!(PROBE_QUAT, Rotation::Quaternion, 7, [0, 1, 2, 3, 4, 5, 6]);

    /// Generalized force of force `f` at body point `s` plus couple `c`, by virtual work
    /// with central differences: `g_k = f·∂p/∂q_k + c·δθ_k`, `[δθ_k×] = skew(∂A/∂q_k Aᵀ)`.
    fn generalized_force_fd(
        b: &BodyInfo,
        q: &[f64],
        s: &[f64; 3],
        f: Vector3<f64>,
        c: Vector3<f64>,
    ) -> Vec<f64> {
        let h = 1e-6;
        let a = pose::rotation_matrix(b, q).unwrap();
        (0..q.len())
            .map(|k| {
                let (mut qp, mut qm) = (q.to_vec(), q.to_vec());
                qp[k] += h;
                qm[k] -= h;
                let dp = (pose::point_world(Some(b), &qp, s).unwrap()
                    - pose::point_world(Some(b), &qm, s).unwrap())
                    / (2.0 * h);
                let da = (pose::rotation_matrix(b, &qp).unwrap()
                    - pose::rotation_matrix(b, &qm).unwrap())
                    / (2.0 * h);
                let x = da * a.transpose();
                let x = 0.5 * (x - x.transpose());
                f.dot(&dp) + c.dot(&Vector3::new(x[(2, 1)], x[(0, 2)], x[(1, 0)]))
            })
            .collect()
    }

    #[test]
    fn a_known_wrench_is_recovered_from_its_generalized_force() {
        let mut rng = Rng::new(77);
        for info in [&PROBE_EULER, &PROBE_QUAT] {
            let b = &info.bodies[0];
            for trial in 0..10 {
                let mut q: Vec<f64> = (0..info.n_coords).map(|_| 1.5 * rng.uniform()).collect();
                if b.rotation == Rotation::Quaternion {
                    let n = q[3..].iter().map(|x| x * x).sum::<f64>().sqrt();
                    q[3..].iter_mut().for_each(|x| *x /= n);
                }
                let f = Vector3::new(rng.uniform(), rng.uniform(), rng.uniform()) * 10.0;
                let c = Vector3::new(rng.uniform(), rng.uniform(), rng.uniform()) * 3.0;
                let g = generalized_force_fd(b, &q, &S_LOCAL, f, c);
                // Φq = I and −Φqᵀλ = g.
                let lam: Vec<f64> = g.iter().map(|x| -x).collect();
                let pq = vec![1.0; info.n_coords];
                let tol = 1e-7 * (f.norm() + c.norm());
                let w = joint_wrench(info, &q, &pq, &lam, 0).unwrap();
                assert!(
                    (Vector3::from(w.force) - f).norm() < tol
                        && (Vector3::from(w.moment) - c).norm() < tol,
                    "{:?} trial {trial}: {w:?} vs {f}, {c}",
                    b.rotation
                );
                // From the ground's side: minus the same wrench, about the joint point that
                // moves with the body (M_T = M_S + (S − T) × F), not the ground's P_GLOBAL.
                let s = pose::point_world(Some(b), &q, &S_LOCAL).unwrap();
                let t = pose::point_world(Some(b), &q, &T_LOCAL).unwrap();
                let c_ground = c + (s - t).cross(&f);
                let w = joint_wrench(info, &q, &pq, &lam, 1).unwrap();
                assert!(
                    (Vector3::from(w.force) + f).norm() < tol
                        && (Vector3::from(w.moment) + c_ground).norm() < tol,
                    "{:?} trial {trial}: {w:?}",
                    b.rotation
                );
            }
        }
    }

    #[test]
    fn wrench_and_effort_errors() {
        let info = &PROBE_QUAT;
        let q = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0];
        let (pq, lam) = ([1.0; 7], [0.0; 7]);
        assert!(
            joint_wrench(info, &q, &pq, &lam, 2).is_err(),
            "normalization row"
        );
        assert!(
            joint_wrench(info, &q, &pq, &lam, 3).is_err(),
            "no such joint"
        );
        assert!(joint_wrench(info, &q[..6], &pq, &lam, 0).is_err());
        assert!(joint_wrench(info, &q, &pq[..6], &lam, 0).is_err());
        assert!(driver_effort(info, &lam, 0).is_err(), "not a driver");
        assert!(driver_effort(info, &lam[..3], 0).is_err());
        // An Euler body at β = 90° has no torque from its Euler-angle forces.
        let q = [0.0, 0.0, 0.0, 0.1, std::f64::consts::FRAC_PI_2, 0.2];
        assert!(matches!(
            joint_wrench(&PROBE_EULER, &q, &[1.0; 6], &[1.0; 6], 0),
            Err(Error::EulerSingularity { .. })
        ));
    }

    /// Several joints' wrenches at once are each joint's own [`joint_wrench`], bit for bit:
    /// bodies in Euler angles and in quaternions, seen from the body and from the ground,
    /// two joints sharing one body (its frame made once per state), states that change
    /// between calls; and what one refuses, the other refuses.
    #[test]
    fn joint_wrenches_are_each_joints_wrench() {
        fn check(
            all: &mut JointWrenches,
            info: &MechanismInfo,
            (q, pq, lam): (&[f64], &[f64], &[f64]),
            out: &mut Vec<Wrench>,
        ) {
            all.wrenches(q, pq, lam, out).unwrap();
            let each: Vec<Wrench> = all
                .joints()
                .iter()
                .map(|&j| joint_wrench(info, q, pq, lam, j).unwrap())
                .collect();
            assert_eq!(*out, each);
        }
        let mut rng = Rng::new(7);
        let mut out = Vec::new();
        let mut euler = JointWrenches::new(&PROBE_EULER, &[0, 1]).unwrap();
        let mut quat = JointWrenches::new(&PROBE_QUAT, &[1, 0]).unwrap();
        let hinge = TwoBallHinge::new(0.0);
        let mut balls = JointWrenches::new(hinge.info(), &[0, 1]).unwrap();
        for _ in 0..5 {
            for (all, info) in [(&mut euler, &PROBE_EULER), (&mut quat, &PROBE_QUAT)] {
                let n = info.n_coords;
                let mut random = || (0..n).map(|_| rng.uniform()).collect::<Vec<f64>>();
                let (q, pq, lam) = (random(), random(), random());
                check(all, info, (&q, &pq, &lam), &mut out);
            }
            let mut q = hinge.info().q0.to_vec();
            q[5] = 2.0 * rng.uniform();
            let (_, pq, lam) = moving_state(&hinge, &mut rng, &mut q);
            check(&mut balls, hinge.info(), (&q, &pq, &lam), &mut out);
        }
        assert!(
            JointWrenches::new(&PROBE_QUAT, &[0, 2]).is_err(),
            "normalization row"
        );
        assert!(
            JointWrenches::new(&PROBE_QUAT, &[3]).is_err(),
            "no such joint"
        );
        let q = [0.0, 0.0, 0.0, 0.1, std::f64::consts::FRAC_PI_2, 0.2];
        assert!(matches!(
            euler.wrenches(&q, &[1.0; 6], &[1.0; 6], &mut out),
            Err(Error::EulerSingularity { .. })
        ));
        assert!(euler
            .wrenches(&q[..5], &[1.0; 6], &[1.0; 6], &mut out)
            .is_err());
    }

    #[test]
    fn driver_effort_is_the_pushing_force() {
        let mech = CircleDriver;
        let (_, _, lam) = start(&mech);
        let info = mech.info();
        let e = driver_effort(info, &lam, 1).unwrap();
        assert_eq!(e, actuator_force(info, &lam, 1).unwrap());
        // Pushing up against gravity: positive along increasing distance.
        assert!(e > CIRCLE_MASS * G, "{e}");
    }
}
