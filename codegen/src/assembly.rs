//! Assembly at generation time: brings the file's initial pose onto the constraints
//! (warning when a joint was violated by more than a tolerance, an error naming the rows
//! when it cannot be done, and an error naming the joint when the violation is a modelling
//! error rather than imprecise numbers, unless the file sets `repair_initial_pose`), checks
//! there that the joints fix every rotation about an axis of zero inertia, then counts
//! degrees of freedom and finds redundant rows with a rank-revealing elimination of Φq at
//! the assembled pose, and recognizes a six-leg platform there ([`crate::legs`]).

use crate::diag::{Diagnostic, Errors};
use crate::equations::System;
use crate::expr::{Id, Var};
use crate::geometry::{
    euler_matrix, euler_rate_matrix, quaternion_matrix, quaternion_rates, v3, V3,
};
use crate::legs::{self, Platform};
use crate::model::{Body, DriverTarget, Formulation, Frame, Model, Rotation};
use crate::primitives::{driver_row_is_length, joint_row_is_length};
use nalgebra::{DMatrix, DVector};
use std::fmt;

/// Residual below which the file's pose is taken as it is (its numbers reach the
/// generated code unchanged).
const CONSISTENT: f64 = 1e-10;
/// Largest correction of the file's pose accepted without a warning.
pub const WARN_CORRECTION: f64 = 1e-6;
/// Largest violation of a joint or driver at the file's pose that is assembled without
/// `repair_initial_pose`, as a fraction of the mechanism's [`size`]. Numbers typed with a
/// few digits, or rounded placements, are off by far less; a joint point on the wrong side
/// of a body or a wrong length is off by far more, and moving the bodies would hide it. A
/// misaligned axis counts as the gap it opens across the mechanism's size.
pub const MODELLING_TOLERANCE: f64 = 1e-3;
/// A row is dependent when the part of it independent of the rows before it is smaller
/// than this fraction of its norm.
const RANK_TOL: f64 = 1e-9;

/// What the generator found out about the mechanism at its initial pose.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    pub name: String,
    pub n_bodies: usize,
    pub n_coords: usize,
    pub n_rows: usize,
    pub n_drivers: usize,
    /// Rank of Φq at the assembled pose.
    pub rank: usize,
    /// Grübler–Kutzbach count `6·bodies − Σ joint rows` (without drivers).
    pub grubler: i64,
    /// Mobility without drivers: coordinates minus the rank of the joint (and
    /// normalization) rows.
    pub mobility: usize,
    /// Degrees of freedom left with the drivers: coordinates minus rank.
    pub dof: usize,
    /// Rows found dependent on earlier rows (index, name).
    pub redundant: Vec<(usize, String)>,
    /// A six-leg platform: its body's name and the leg drivers' names.
    pub platform: Option<(String, Vec<String>)>,
    /// The planar model's coordinates, rows and dependent rows' names.
    pub planar: Option<(usize, usize, Vec<String>)>,
    /// The planar model was recognised (the file does not say `planar`).
    pub planar_recognised: bool,
    /// Warnings (e.g. a corrected initial pose).
    pub warnings: Vec<String>,
}

impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "{}: {} bodies, {} coordinates, {} constraint rows ({} driver{}), rank {} at the initial pose",
            self.name,
            self.n_bodies,
            self.n_coords,
            self.n_rows,
            self.n_drivers,
            if self.n_drivers == 1 { "" } else { "s" },
            self.rank
        )?;
        writeln!(
            f,
            "  mobility: Grübler count {}, actual {} (without drivers); {} DOF left with drivers",
            self.grubler, self.mobility, self.dof
        )?;
        if self.redundant.is_empty() {
            write!(f, "  no redundant rows")?;
        } else {
            let names: Vec<&str> = self.redundant.iter().map(|(_, n)| n.as_str()).collect();
            write!(
                f,
                "  {} redundant row(s), dropped by the solvers (their joints' reactions are not unique): {}",
                names.len(),
                names.join(", ")
            )?;
        }
        if let Some((body, legs)) = &self.platform {
            write!(
                f,
                "\n  platform: body \"{body}\" held by {} driven legs ({}): forward kinematics available",
                legs.len(),
                legs.join(", ")
            )?;
        }
        if let Some((n, m, redundant)) = &self.planar {
            write!(
                f,
                "\n  planar model: {n} coordinates (x, y, γ per body), {m} rows, {}{}",
                match redundant.len() {
                    0 => "no redundant rows".to_string(),
                    _ => format!("redundant: {}", redundant.join(", ")),
                },
                match self.planar_recognised {
                    true => " (recognised: every body moves in its plane; `planar = false` turns it off)",
                    false => "",
                }
            )?;
        }
        for w in &self.warnings {
            write!(f, "\n  warning: {w}")?;
        }
        Ok(())
    }
}

/// The assembled initial pose and the report.
pub struct Assembly {
    pub q0: Vec<f64>,
    pub redundant_rows: Vec<u32>,
    /// The planar model (`planar = true`, or recognised), with its own dependent rows.
    pub planar: Option<crate::reduce::Reduced>,
    /// The six-leg platform, when the mechanism is one.
    pub platform: Option<Platform>,
    pub report: Report,
}

struct Eval<'a> {
    sys: &'a System,
    /// The run-time values (`Var::P`), [`Model::run_time_values`].
    p: Vec<f64>,
}

impl Eval<'_> {
    fn phi(&self, q: &[f64]) -> DVector<f64> {
        let env = |v: Var| match v {
            Var::Q(i) => q[i as usize],
            Var::P(i) => self.p[i as usize],
            _ => 0.0,
        };
        DVector::from_vec(self.sys.arena.eval_many(&self.sys.phi, &env))
    }

    fn phi_q(&self, q: &[f64]) -> DMatrix<f64> {
        let env = |v: Var| match v {
            Var::Q(i) => q[i as usize],
            Var::P(i) => self.p[i as usize],
            _ => 0.0,
        };
        let ids: Vec<_> = self.sys.phi_q.iter().map(|e| e.2).collect();
        let vals = self.sys.arena.eval_many(&ids, &env);
        let mut m = DMatrix::zeros(self.sys.n_constraints, self.sys.n_coords);
        for (&(r, c, _), v) in self.sys.phi_q.iter().zip(vals) {
            m[(r as usize, c as usize)] = v;
        }
        m
    }
}

/// The joint (or driver, or body) that owns row `row`: its name, and the item as
/// diagnostics name it (``joint `a0` ``, ``driver `motor` ``, ``body `rod` ``).
fn owner(model: &Model, sys: &System, row: usize) -> (String, String) {
    let k = sys.joint_rows.iter().rposition(|&s| s <= row).unwrap_or(0);
    let nj = model.joints.len();
    let nd = model.drivers.len();
    let (kind, name) = if k < nj {
        ("joint", &model.joints[k].name)
    } else if k < nj + nd {
        ("driver", &model.drivers[k - nj].name)
    } else {
        (
            "body",
            &model.bodies[sys.normalized_bodies[k - nj - nd]].name,
        )
    };
    (name.clone(), format!("{kind} `{name}`"))
}

/// A row as a message names it: `` `joint.primitive` `` for joints and drivers, whose names
/// the file wrote; a quaternion body's generated `eᵀe = 1` row by its body instead of its
/// internal name `<body>.norm`.
fn row_label(model: &Model, sys: &System, row: usize) -> String {
    let norm_start = sys
        .joint_rows
        .get(model.joints.len() + model.drivers.len())
        .copied()
        .unwrap_or(sys.n_constraints);
    match row
        .checked_sub(norm_start)
        .and_then(|k| sys.normalized_bodies.get(k))
    {
        Some(&b) => format!(
            "the unit-quaternion condition of body `{}`",
            model.bodies[b].name
        ),
        None => format!("`{}`", sys.row_names[row]),
    }
}

fn diagnostic(
    model: &Model,
    file: &str,
    row: (String, String),
    message: String,
    help: &str,
) -> Diagnostic {
    let (name, item) = row;
    Diagnostic {
        file: file.to_string(),
        line: model.lines.get(&name).copied().unwrap_or(1),
        column: 1,
        item,
        message,
        help: help.to_string(),
    }
}

/// An error when Φ or Φq is not finite at `q` (a frame or a distance undefined there).
fn non_finite(
    model: &Model,
    sys: &System,
    eval: &Eval,
    q: &[f64],
    file: &str,
) -> Result<(), Errors> {
    let phi = eval.phi(q);
    let jac = eval.phi_q(q);
    let Some(r) =
        (0..phi.len()).find(|&r| !phi[r].is_finite() || jac.row(r).iter().any(|x| !x.is_finite()))
    else {
        return Ok(());
    };
    Err(Errors(vec![diagnostic(
        model,
        file,
        owner(model, sys, r),
        format!("row {} or its derivative is not a finite number at the initial pose", row_label(model, sys, r)),
        "check this item's points and axes: a distance between coincident points or a direction of zero length is undefined",
    )]))
}

/// Emission writes every constant of the equations as a Rust literal, and a literal cannot be
/// infinite or NaN: such a constant comes from numbers whose products overflow f64 (a spring
/// of length 1e300 has ½kℓ² = ∞), and is reported here instead of failing in emission.
pub fn non_finite_constants(sys: &System, file: &str) -> Result<(), Errors> {
    let mut roots: Vec<Id> = [sys.phi.as_slice(), &sys.phi_t, &sys.gamma].concat();
    roots.extend(sys.phi_q.iter().map(|e| e.2));
    roots.extend([sys.potential, sys.power_nc]);
    for d in &sys.dynamics {
        roots.extend(d.mass.iter().map(|e| e.2));
        roots.extend(&d.force);
    }
    let mut seen = vec![false; sys.arena.len()];
    while let Some(id) = roots.pop() {
        if std::mem::replace(&mut seen[id.index()], true) {
            continue;
        }
        if let Some(c) = sys.arena.as_const(id) {
            if !c.is_finite() {
                return Err(Errors(vec![Diagnostic {
                    file: file.to_string(),
                    line: 1,
                    column: 1,
                    item: "the file".to_string(),
                    message: format!(
                        "a constant of the equations is {c}: the mechanism's numbers overflow f64 \
                         when multiplied (for example ½·stiffness·length² of a spring)"
                    ),
                    help: "check the magnitudes of points, lengths, masses, stiffnesses and \
                           parameters: their products must stay below 1.8e308"
                        .to_string(),
                }]));
            }
        }
        roots.extend(sys.arena.node(id).children());
    }
    Ok(())
}

/// The mechanism's size (m): the diagonal of the box around the bodies' centres of mass and
/// the points of its joints and point-distance drivers at the file's pose; 1 m when these
/// all coincide (then no joint has points apart, and only axes can be violated).
pub fn size(model: &Model) -> f64 {
    let world = |f: &Frame| match f.body {
        Some(b) => {
            let body = &model.bodies[b];
            body.position() + body.orientation() * v3(f.point)
        }
        None => v3(f.point),
    };
    let mut points: Vec<V3> = model.bodies.iter().map(Body::position).collect();
    for j in &model.joints {
        points.extend([world(&j.f1), world(&j.f2)]);
    }
    for d in &model.drivers {
        if let DriverTarget::PointDistance { f1, f2 } = &d.target {
            points.extend([world(f1), world(f2)]);
        }
    }
    let lo = points
        .iter()
        .fold(V3::repeat(f64::INFINITY), |m, p| m.inf(p));
    let hi = points
        .iter()
        .fold(V3::repeat(f64::NEG_INFINITY), |m, p| m.sup(p));
    let d = (hi - lo).norm();
    if d > 0.0 && d.is_finite() {
        d
    } else {
        1.0
    }
}

/// A length in metres with four significant digits.
fn metres(x: f64) -> String {
    let digits = if x > 0.0 && x.is_finite() {
        (3.0 - x.log10().floor()).clamp(0.0, 15.0) as usize
    } else {
        3
    };
    format!("{x:.digits$} m")
}

/// One diagnostic per joint or driver that the file's pose violates by more than
/// [`MODELLING_TOLERANCE`] of the mechanism's size, the worst first. `phi` is Φ at the
/// file's pose. A joint's gap is the norm of its rows in metres (for a spherical joint, the
/// distance between its two points), or its axes' misalignment (the norm of its cosine
/// rows, about the angle in radians) times the size, whichever is larger.
fn modelling_errors(
    model: &Model,
    sys: &System,
    phi: &DVector<f64>,
    file: &str,
) -> Vec<Diagnostic> {
    let size = size(model);
    let limit = MODELLING_TOLERANCE * size;
    let nj = model.joints.len();
    let nd = model.drivers.len();
    let end = |k: usize| sys.joint_rows.get(k + 1).copied().unwrap_or(phi.len());
    let mut found = Vec::new();
    for k in 0..nj + nd {
        let (mut length, mut angle) = (0.0f64, 0.0f64);
        let (mut worst, mut worst_gap) = (sys.joint_rows[k], -1.0);
        for r in sys.joint_rows[k]..end(k) {
            let is_length = if k < nj {
                let prefix = format!("{}.", model.joints[k].name);
                joint_row_is_length(sys.row_names[r].strip_prefix(&prefix).unwrap_or(""))
            } else {
                driver_row_is_length(&model.drivers[k - nj].target)
            };
            let v = phi[r].abs();
            let gap = if is_length { v } else { v * size };
            if gap > worst_gap {
                (worst, worst_gap) = (r, gap);
            }
            if is_length {
                length = length.hypot(v);
            } else {
                angle = angle.hypot(v);
            }
        }
        let gap = length.max(angle * size);
        // `!(gap <= limit)`: a NaN residual is not a small one.
        if !(gap <= limit) {
            found.push((gap, k, length, angle, worst));
        }
    }
    found.sort_by(|a, b| b.0.total_cmp(&a.0));
    found
        .into_iter()
        .map(|(gap, _, length, angle, row)| {
            let what = if length >= angle * size {
                format!("by {}", metres(length))
            } else {
                format!(
                    "by {angle:.3e} rad of its axes (a gap of {} across the mechanism)",
                    metres(gap)
                )
            };
            let owner = owner(model, sys, row);
            let item = owner.1.clone();
            diagnostic(
                model,
                file,
                owner,
                format!(
                    "the initial pose violates {item} {what} (row `{}`): more than the modelling \
                     tolerance of {} ({MODELLING_TOLERANCE:e} of the mechanism's size, {}); the \
                     generator would have to move bodies that far to assemble it",
                    sys.row_names[row],
                    metres(limit),
                    metres(size)
                ),
                "check this item's points, axes and lengths against the bodies' positions and \
                 orientations; if the pose is only a rough guess, add `repair_initial_pose = \
                 true` at the top of the file to let the generator move the bodies onto the \
                 joints (with a warning)",
            )
        })
        .collect()
}

/// The directions of `body`'s coordinates at `q` that carry no kinetic energy under
/// `formulation`, one per zero principal inertia (with its local axis), plus, for a
/// quaternion body without any inertia, `ė ∥ e` (axis index 3).
fn zero_energy_directions(
    body: &Body,
    formulation: Formulation,
    q: &[f64],
    n: usize,
) -> Vec<(usize, DVector<f64>)> {
    let off = body.offset;
    let c = &q[off + 3..off + body.n_coords()];
    let mut out = Vec::new();
    for k in (0..3).filter(|&k| body.inertia[k] == 0.0) {
        let mut d = DVector::zeros(n);
        match (formulation, body.rotation) {
            // The paper's M is diag(m, m, m, Ixx, Iyy, Izz) against the Euler angles' rates.
            (Formulation::Paper, _) => d[off + 3 + k] = 1.0,
            // Exact: ½ωᵀJω, so the spin about the body's local axis k.
            (Formulation::Exact, Rotation::Euler) => {
                let angles = [c[0], c[1], c[2]];
                let w = euler_matrix(angles).column(k).into_owned();
                // Singular only at β = ±90°, where the runtime refuses to run anyway.
                let Some(h) = euler_rate_matrix(angles).try_inverse() else {
                    continue;
                };
                let rates = h * w;
                for i in 0..3 {
                    d[off + 3 + i] = rates[i];
                }
            }
            (Formulation::Exact, Rotation::Quaternion) => {
                let e = [c[0], c[1], c[2], c[3]];
                let w = quaternion_matrix(e).column(k).into_owned();
                for (i, r) in quaternion_rates(e, &w).into_iter().enumerate() {
                    d[off + 3 + i] = r;
                }
            }
        }
        out.push((k, d));
    }
    // The regularization k·eeᵀ (k = 4·mean inertia) vanishes with every inertia; the
    // normalization row always fixes this direction, but it belongs to the null space.
    if formulation == Formulation::Exact
        && body.rotation == Rotation::Quaternion
        && body.inertia == [0.0; 3]
    {
        let mut d = DVector::zeros(n);
        for i in 0..4 {
            d[off + 3 + i] = c[i];
        }
        out.push((3, d));
    }
    out
}

/// With zero principal inertias M is only positive semi-definite, and the equations of
/// motion are regular exactly when M is positive definite on the null space of Φq: when
/// the constraints fix every direction without kinetic energy, i.e. Φq times those
/// directions has full column rank. Checked at the assembled pose `q` for each formulation;
/// the direction that adds no rank names the body and the axis left free.
fn zero_inertias_fixed(
    model: &Model,
    jac: &DMatrix<f64>,
    q: &[f64],
    file: &str,
) -> Result<(), Errors> {
    const AXES: [&str; 3] = ["x", "y", "z"];
    let scale = jac.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    for &formulation in &model.formulations {
        let mut basis: Vec<DVector<f64>> = Vec::new();
        for body in &model.bodies {
            for (k, d) in zero_energy_directions(body, formulation, q, jac.ncols()) {
                let mut v = jac * &d;
                for _ in 0..2 {
                    for b in &basis {
                        let c = b.dot(&v);
                        v -= b * c;
                    }
                }
                if v.norm() > RANK_TOL * scale * d.norm() {
                    basis.push(v.normalize());
                    continue;
                }
                let what = match AXES.get(k) {
                    Some(axis) => format!(
                        "zero inertia about its local {axis} axis, and no joint fixes its \
                         rotation about that axis at the initial pose"
                    ),
                    None => "no inertia at all, and the joints leave a rotation free".to_string(),
                };
                return Err(Errors(vec![diagnostic(
                    model,
                    file,
                    (body.name.clone(), format!("body `{}`", body.name)),
                    format!(
                        "{what}: the mass matrix ({} formulation) is singular on the motions \
                         the constraints allow, so the accelerations are undetermined",
                        formulation.name()
                    ),
                    "give the body a small inertia about that axis, or a joint that fixes the \
                     rotation (e.g. a revolute joint along that axis instead of a spherical one)",
                )]));
            }
        }
    }
    Ok(())
}

/// Assembles the initial pose at t = 0 and analyses Φq there.
/// Adds row `r` of `jac` to the orthonormal `basis` when it is independent of it (twice
/// orthogonalized, relative tolerance [`RANK_TOL`]); `false`: dependent.
fn extend_basis(basis: &mut Vec<DVector<f64>>, jac: &DMatrix<f64>, r: usize) -> bool {
    let row = jac.row(r).transpose();
    let norm = row.norm();
    let mut v = row.clone();
    for _ in 0..2 {
        for b in basis.iter() {
            let c = b.dot(&v);
            v -= b * c;
        }
    }
    if v.norm() <= RANK_TOL * norm.max(1e-300) || norm == 0.0 {
        return false;
    }
    basis.push(v.normalize());
    true
}

/// The planar model of a `planar = true` file (declared at `line`), with its own dependent
/// rows; an error when a row cannot hold in the plane, a warning (in `warnings`) when it has
/// fewer degrees of freedom than the spatial model's `dof`.
#[allow(clippy::too_many_arguments)]
fn planar_check(
    model: &Model,
    sys: &System,
    q: &[f64],
    driver_rows: &[usize],
    dof: usize,
    line: usize,
    file: &str,
    warnings: &mut Vec<String>,
) -> Result<crate::reduce::Reduced, Errors> {
    let fail = |message: String| {
        Errors(vec![Diagnostic {
            file: file.to_string(),
            line,
            column: 1,
            item: "`planar`".to_string(),
            message,
            help: "a planar mechanism turns about Z only: revolute axes along Z, prismatic axes \
                   and loads in the plane; or `planar = false` for the spatial model alone"
                .to_string(),
        }])
    };
    let mut red = crate::reduce::planar(sys, &model.bodies, q)
        .map_err(|e| fail(format!("`planar = true`, but {e}")))?;
    let qr: Vec<f64> = red.coords.iter().map(|&c| q[c]).collect();
    let jac = Eval {
        sys: &red.system,
        p: model.run_time_values(),
    }
    .phi_q(&qr);
    let is_driver = |k: &usize| driver_rows.contains(&red.rows[*k]);
    let m = red.system.n_constraints;
    let order = (0..m)
        .filter(|k| !is_driver(k))
        .chain((0..m).filter(is_driver));
    let mut basis = Vec::new();
    let mut dependent: Vec<usize> = order
        .filter(|&k| !extend_basis(&mut basis, &jac, k))
        .collect();
    dependent.sort_unstable();
    let planar_dof = red.system.n_coords - basis.len();
    if planar_dof < dof {
        // Out-of-plane freedoms of the spatial model (a pendulum on a distance joint can
        // swing out of its plane): they stay at rest when nothing excites them, which the
        // file's gravity and initial velocities in the plane ensure for symmetric loads.
        warnings.push(format!(
            "the planar model holds {} out-of-plane degree(s) of freedom of the spatial model \
             fixed ({planar_dof} DOF in the plane, {dof} in space): both move alike only while \
             no load pushes out of the plane",
            dof - planar_dof
        ));
    }
    red.redundant = Some(dependent);
    Ok(red)
}

pub fn assemble(model: &Model, sys: &System, file: &str) -> Result<Assembly, Errors> {
    let eval = Eval {
        sys,
        p: model.run_time_values(),
    };
    let q_file = model.q0();
    let mut q = q_file.clone();
    non_finite(model, sys, &eval, &q, file)?;
    non_finite_constants(sys, file)?;
    let mut phi = eval.phi(&q);
    let mut warnings = Vec::new();
    if phi.amax() > CONSISTENT {
        // Gauss–Newton with the minimum-norm step (SVD): the smallest move onto Φ = 0.
        let first = phi.clone();
        for _ in 0..60 {
            let jac = eval.phi_q(&q);
            if !jac.iter().all(|x| x.is_finite()) {
                break;
            }
            let svd = jac.svd(true, true);
            let step = match svd.solve(&phi, 1e-12 * svd.singular_values.max()) {
                Ok(s) => s,
                Err(_) => break,
            };
            for (qi, s) in q.iter_mut().zip(step.iter()) {
                *qi -= s;
            }
            phi = eval.phi(&q);
            if phi.amax() < 1e-14 || step.amax() < 1e-15 || !phi.iter().all(|x| x.is_finite()) {
                break;
            }
        }
        if !phi.iter().all(|x| x.abs() <= 1e-9) {
            let mut rows: Vec<usize> = (0..phi.len())
                .filter(|&r| !(phi[r].abs() <= 1e-9))
                .collect();
            rows.sort_by(|&a, &b| phi[b].abs().total_cmp(&phi[a].abs()));
            // Blame the worst joint or driver row: a normalization row is only off because
            // the least-squares compromise shrank the quaternion.
            let norm_start = sys
                .joint_rows
                .get(model.joints.len() + model.drivers.len())
                .copied()
                .unwrap_or(phi.len());
            let worst = owner(
                model,
                sys,
                rows.iter()
                    .copied()
                    .find(|&r| r < norm_start)
                    .unwrap_or(rows[0]),
            );
            rows.truncate(5);
            let list: Vec<String> = rows
                .iter()
                .map(|&r| format!("{} ({:.3e})", row_label(model, sys, r), phi[r]))
                .collect();
            return Err(Errors(vec![diagnostic(
                model,
                file,
                worst,
                format!(
                    "the mechanism cannot be assembled at t = 0: rows {} keep a residual after the closest pose was sought",
                    list.join(", ")
                ),
                "the joints contradict each other: check these joints' points, axes and lengths, and the drivers' values at t = 0",
            )]));
        }
        if !model.repair_initial_pose {
            let errors = modelling_errors(model, sys, &first, file);
            if !errors.is_empty() {
                return Err(Errors(errors));
            }
        }
        let moved = q
            .iter()
            .zip(&q_file)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        if moved > WARN_CORRECTION {
            let worst = first.iamax();
            warnings.push(format!(
                "the initial pose violates {} by {:.3e} (row {}); the generator moved the coordinates by up to {:.3e} to assemble it",
                owner(model, sys, worst).1,
                first[worst].abs(),
                row_label(model, sys, worst),
                moved
            ));
        }
    } else {
        q = q_file;
    }
    non_finite(model, sys, &eval, &q, file)?;

    let jac = eval.phi_q(&q);
    zero_inertias_fixed(model, &jac, &q, file)?;
    let m = sys.n_constraints;
    let nj = model.joints.len();
    let nd = model.drivers.len();
    let driver_rows: Vec<usize> = (0..nd).map(|k| sys.joint_rows[nj + k]).collect();
    let norm_start = sys.joint_rows.get(nj + nd).copied().unwrap_or(m);
    // Normalization rows first (never the redundant ones), then joints, then drivers.
    let order: Vec<usize> = (norm_start..m)
        .chain((0..m).filter(|r| *r < norm_start && !driver_rows.contains(r)))
        .chain(driver_rows.iter().copied())
        .collect();
    let mut basis: Vec<DVector<f64>> = Vec::new();
    let mut redundant = Vec::new();
    let mut rank_joints = 0;
    for &r in &order {
        if !extend_basis(&mut basis, &jac, r) {
            redundant.push(r);
        }
        if !driver_rows.contains(&r) {
            rank_joints = basis.len();
        }
    }
    redundant.sort_unstable();
    let rank = basis.len();
    let dof = sys.n_coords - rank;
    let planar = match model.planar {
        Some(line) => Some(planar_check(
            model,
            sys,
            &q,
            &driver_rows,
            dof,
            line,
            file,
            &mut warnings,
        )?),
        // Recognised only when nothing about it would need a word: no error, no warning.
        None if model.planar_unstated && model.starts_planar() => {
            let mut notes = Vec::new();
            planar_check(model, sys, &q, &driver_rows, dof, 0, file, &mut notes)
                .ok()
                .filter(|_| notes.is_empty())
        }
        None => None,
    };
    let planar_recognised = planar.is_some() && model.planar.is_none();
    let joint_rows: i64 = model.joints.iter().map(|j| j.rows() as i64).sum();
    let platform = legs::detect(model, &q);
    let report = Report {
        name: model.name.clone(),
        n_bodies: model.bodies.len(),
        n_coords: sys.n_coords,
        n_rows: m,
        n_drivers: nd,
        rank,
        grubler: 6 * model.bodies.len() as i64 - joint_rows,
        mobility: sys.n_coords - rank_joints,
        dof: sys.n_coords - rank,
        redundant: redundant
            .iter()
            .map(|&r| (r, sys.row_names[r].clone()))
            .collect(),
        platform: platform.as_ref().map(|p| {
            let legs = p.legs.iter().map(|l| model.drivers[l.driver].name.clone());
            (model.bodies[p.body].name.clone(), legs.collect())
        }),
        planar: planar.as_ref().map(|p| {
            let r = &p.system;
            let dependent = p.redundant.iter().flatten();
            (
                r.n_coords,
                r.n_constraints,
                dependent.map(|&k| r.row_names[k].clone()).collect(),
            )
        }),
        planar_recognised,
        warnings,
    };
    Ok(Assembly {
        q0: q,
        redundant_rows: redundant.iter().map(|&r| r as u32).collect(),
        planar,
        platform,
        report,
    })
}
