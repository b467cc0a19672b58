//! The contract between generated mechanism code and the solvers: sizes, sparsity patterns,
//! names, and the evaluation functions the generator emits.
//!
//! Conventions shared by every implementation:
//! - `q`, `qd` have `n_coords` entries; each body owns consecutive coordinates: its centre
//!   of mass `[X, Y, Z]`, then its rotation coordinates ([`Rotation`]): `[θ, β, γ]`
//!   (A = Rz(γ)·Ry(β)·Rx(θ)) or Euler parameters `[e0, e1, e2, e3]`.
//! - Equations of motion are `M q̈ + Φqᵀ λ = Q` and `Φq q̈ = γ`.
//! - Sparse matrices are written as their structural nonzeros only, in the order of the
//!   pattern arrays in [`MechanismInfo`]; zeros outside the pattern are never written.

/// How a joint constrains its bodies; the runtime uses it for reports and reaction forces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JointKind {
    /// Three rows: point on body 1 minus point on body 2 (or a ground point).
    Spherical,
    /// Spherical plus two rows keeping the axes parallel (5 rows).
    Revolute,
    /// Spherical plus one row keeping the two cross axes perpendicular (4 rows).
    Universal,
    /// Axes parallel and the points on one line (4 rows).
    Cylindrical,
    /// Cylindrical plus one row stopping rotation about the axis (5 rows).
    Prismatic,
    /// Spherical plus three rows fixing the relative orientation (6 rows).
    Fixed,
    /// One row: distance between the two points minus a constant.
    Distance,
    /// The paper's prismatic (eqs. 4–8): three Euler-angle equalities, then two no-slide rows.
    EulerPrismatic,
    /// One row prescribing a joint coordinate, a body coordinate or a point distance as a
    /// function of time; see [`JointInfo::effort_sign`].
    Driver,
    /// One row `eᵀe − 1 = 0` owned by quaternion body `body1`.
    Normalization,
}

/// How a body's orientation is parametrized.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rotation {
    /// `[θ, β, γ]` of A = Rz(γ)·Ry(β)·Rx(θ): three coordinates, singular at β = ±90°.
    Euler,
    /// Euler parameters `[e0, e1, e2, e3]` (unit quaternion, scalar first) and the body's
    /// normalization row; no singularity.
    Quaternion,
}

impl Rotation {
    /// Number of rotation coordinates: 3 or 4.
    pub fn n_coords(self) -> usize {
        match self {
            Rotation::Euler => 3,
            Rotation::Quaternion => 4,
        }
    }
    /// The name used in mechanism files: `euler` or `quaternion`.
    pub fn name(self) -> &'static str {
        match self {
            Rotation::Euler => "euler",
            Rotation::Quaternion => "quaternion",
        }
    }
}

/// One rigid body of the mechanism.
#[derive(Debug, Clone, Copy)]
pub struct BodyInfo {
    pub name: &'static str,
    /// Index of the body's `X` coordinate; `Y, Z` follow, then the rotation coordinates
    /// from `+3`.
    pub coord_offset: usize,
    pub rotation: Rotation,
    pub mass: f64,
    /// Principal inertias about the centre of mass, local axes.
    pub inertia: [f64; 3],
}

impl BodyInfo {
    /// Number of coordinates the body owns: 6 (Euler) or 7 (quaternion).
    pub fn n_coords(&self) -> usize {
        3 + self.rotation.n_coords()
    }
}

/// One joint (or driver) and the constraint rows it owns.
#[derive(Debug, Clone, Copy)]
pub struct JointInfo {
    pub name: &'static str,
    pub kind: JointKind,
    /// First body (the one whose point comes first in the equation); `None` is ground.
    pub body1: Option<usize>,
    /// Second body; `None` is ground.
    pub body2: Option<usize>,
    /// First constraint row of this joint.
    pub row_start: usize,
    /// Number of constraint rows.
    pub rows: usize,
    /// The joint point on body 1 (local coordinates; global if body 1 is the ground):
    /// reaction moments are taken about it, unless body 1 is the ground.
    pub point1: [f64; 3],
    /// The joint point on body 2 (local; global if body 2 is the ground). For drivers of a
    /// joint coordinate, the driven joint's; for body-coordinate drivers and normalization
    /// rows, zero. When body 1 is the ground, reaction moments are taken about this point as
    /// it moves with body 2 ([`crate::reactions::joint_wrench`]).
    pub point2: [f64; 3],
    /// Drivers only (0 otherwise): ∂Φ/∂s of the driver's row with respect to the driven
    /// coordinate `s` where Φ = 0, so the driver's effort along `s` (force or torque, on
    /// body 2, positive in the direction of increasing `s`) is `−effort_sign · λ`.
    pub effort_sign: f64,
    /// Drivers only: unit of the effort, `"N"` or `"N·m"` (`""` for other joints).
    pub effort_unit: &'static str,
}

/// Which dynamics formulation the mass matrix and forces were generated for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Formulation {
    /// Constant diagonal `[m, m, m, Ixx, Iyy, Izz]` per body against Euler-angle accelerations.
    Paper,
    /// Mass matrix and velocity-dependent forces from the exact kinetic energy.
    Exact,
}

impl Formulation {
    /// The name used in mechanism files and on the command line: `paper` or `exact`.
    pub fn name(self) -> &'static str {
        match self {
            Formulation::Paper => "paper",
            Formulation::Exact => "exact",
        }
    }
}

/// Everything about a mechanism that does not depend on the state.
#[derive(Debug, Clone, Copy)]
pub struct MechanismInfo {
    pub name: &'static str,
    pub n_coords: usize,
    pub n_constraints: usize,
    pub formulation: Formulation,
    /// Gravity vector, global frame (m/s²).
    pub gravity: [f64; 3],
    /// Row of each structural nonzero of Φq, in output order (row-major, columns ascending).
    pub phi_q_rows: &'static [u32],
    /// Column of each structural nonzero of Φq, in output order.
    pub phi_q_cols: &'static [u32],
    /// Row of each structural nonzero of the (symmetric) mass matrix, both triangles.
    pub mass_rows: &'static [u32],
    /// Column of each structural nonzero of the mass matrix, both triangles.
    pub mass_cols: &'static [u32],
    /// `true` when the mass matrix does not depend on `q` (it may then be evaluated once).
    pub mass_is_constant: bool,
    /// Row and column of each structural nonzero of ∂Q/∂q of the applied loads (springs,
    /// dampers, actuators; not gravity or the inertial terms), in output order (row-major).
    /// Empty when there are none, or the implementation does not provide
    /// [`Mechanism::force_jacobian`].
    pub force_q_rows: &'static [u32],
    pub force_q_cols: &'static [u32],
    /// Row and column of each structural nonzero of ∂Q/∂q̇, in output order (row-major).
    pub force_qd_rows: &'static [u32],
    pub force_qd_cols: &'static [u32],
    pub bodies: &'static [BodyInfo],
    pub joints: &'static [JointInfo],
    /// Human-readable name of each coordinate, e.g. `platform.beta`.
    pub coord_names: &'static [&'static str],
    /// Human-readable name of each constraint row, e.g. `upper_sph1.y`.
    pub row_names: &'static [&'static str],
    /// Initial coordinates: the file's pose, assembled by the generator (consistent to
    /// roundoff).
    pub q0: &'static [f64],
    /// Initial velocities from the file (zero where none was given); not necessarily
    /// consistent: project them (`InitialVelocity::ProjectGiven`).
    pub qd0: &'static [f64],
    /// Rows that are linear combinations of other rows at the initial pose (found by the
    /// generator with a rank-revealing elimination): solvers drop them (λ = 0), so the
    /// reactions of the joints they belong to, and of the rows they depend on, are not
    /// unique. Ascending.
    pub redundant_rows: &'static [u32],
    /// Detected by the generator: the body held to the ground by six legs of driven length,
    /// for forward kinematics. `None` when the mechanism is not such a platform.
    pub platform: Option<PlatformInfo>,
    /// The KKT factor and solve the generator emitted for this model's patterns: the mass
    /// matrix's, then (with loads that have Jacobians) the one with the loads' stiffness
    /// ([`KktPattern::with_loads`](crate::kkt::KktPattern::with_loads)). Empty when none
    /// were, e.g. an interpreted model or one too large for straight-line code; see
    /// [`KktKernels`](crate::kkt::KktKernels).
    pub kkt: &'static [crate::kkt::KktKernels],
}

/// One leg of a platform held to the ground by legs of driven length (forward kinematics).
#[derive(Debug, Clone, Copy)]
pub struct LegInfo {
    /// Name of the driver that sets the leg's length.
    pub driver: &'static str,
    /// Base joint centre, global frame.
    pub base: [f64; 3],
    /// Platform joint centre, local to the platform body (relative to its centre of mass,
    /// like every body point).
    pub platform: [f64; 3],
    /// The driver's constraint row. Its row has unit slope in the leg length, so the length
    /// the driver prescribes at time `t` is `|leg(q)| − Φ_row(q, t)` for any `q` at which the
    /// legs' own joints hold (use `q0`).
    pub row: usize,
}

/// A body held to the ground by six legs of driven length (S-P-S, U-P-S or distance
/// drivers): what forward kinematics needs.
#[derive(Debug, Clone, Copy)]
pub struct PlatformInfo {
    /// Index of the platform body.
    pub body: usize,
    /// The legs, in driver order.
    pub legs: &'static [LegInfo],
}

impl MechanismInfo {
    pub fn phi_q_nnz(&self) -> usize {
        self.phi_q_rows.len()
    }
    pub fn mass_nnz(&self) -> usize {
        self.mass_rows.len()
    }
    /// Whether a row of Φ may depend on time, so that Φt may be nonzero: a driver (the only
    /// joint kind that does), or rows its joints do not all describe (a hand-written model),
    /// where nothing is known.
    pub fn rows_may_depend_on_time(&self) -> bool {
        let described: usize = self.joints.iter().map(|j| j.rows).sum();
        described != self.n_constraints || self.joints.iter().any(|j| j.kind == JointKind::Driver)
    }
    /// The joint owning constraint row `row`.
    pub fn joint_of_row(&self, row: usize) -> Option<&JointInfo> {
        self.joints
            .iter()
            .find(|j| row >= j.row_start && row < j.row_start + j.rows)
    }
    /// Index of the body called `name`.
    pub fn body_index(&self, name: &str) -> Option<usize> {
        self.bodies.iter().position(|b| b.name == name)
    }
    /// Index of the joint called `name`.
    pub fn joint_index(&self, name: &str) -> Option<usize> {
        self.joints.iter().position(|j| j.name == name)
    }
    /// Degrees of freedom left at the initial pose: coordinates minus independent rows.
    pub fn dof(&self) -> usize {
        self.n_coords - (self.n_constraints - self.redundant_rows.len())
    }
}

/// Output slices of the fused Newton-iteration evaluation.
pub struct NewtonOutputs<'a> {
    /// Φ(q, t), `n_constraints`.
    pub phi: &'a mut [f64],
    /// Φq nonzeros, `phi_q_nnz`.
    pub phi_q: &'a mut [f64],
    /// M(q) nonzeros, `mass_nnz`.
    pub mass: &'a mut [f64],
    /// Q(q, q̇, t), `n_coords`.
    pub force: &'a mut [f64],
}

/// Output slices of the fused kinematic evaluation.
pub struct KinematicOutputs<'a> {
    /// Φ(q, t), `n_constraints`.
    pub phi: &'a mut [f64],
    /// Φq nonzeros, `phi_q_nnz`.
    pub phi_q: &'a mut [f64],
    /// Φt(q, t), `n_constraints`.
    pub phi_t: &'a mut [f64],
    /// γ(q, q̇, t), `n_constraints`.
    pub gamma: &'a mut [f64],
}

/// A direction in (q, q̇, p) along which [`Mechanism::tangents`] differentiates: `dq` and
/// `dqd` have `n_coords` entries, `dp` as many as [`Mechanism::run_time_values`].
#[derive(Debug, Clone, Copy)]
pub struct Direction<'a> {
    pub dq: &'a [f64],
    pub dqd: &'a [f64],
    pub dp: &'a [f64],
}

/// Output slices of [`Mechanism::tangents`]: the directional derivatives of Φ
/// (`n_constraints`), Φq's nonzeros (`phi_q_nnz`), Φt, γ, M's nonzeros (`mass_nnz`) and Q
/// (`n_coords`).
pub struct TangentOutputs<'a> {
    pub phi: &'a mut [f64],
    pub phi_q: &'a mut [f64],
    pub phi_t: &'a mut [f64],
    pub gamma: &'a mut [f64],
    pub mass: &'a mut [f64],
    pub force: &'a mut [f64],
}

/// A mechanism's equations, implemented by generated code.
///
/// Every method takes plain slices, allocates nothing and writes every entry of its output.
/// Slices of the wrong length are a programming error and panic.
pub trait Mechanism {
    /// Sizes, patterns and names.
    fn info(&self) -> &'static MechanismInfo;
    /// Constraint residual Φ(q, t).
    fn phi(&self, q: &[f64], t: f64, out: &mut [f64]);
    /// Constraint Jacobian Φq nonzeros in pattern order.
    fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]);
    /// Partial time derivative Φt.
    fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]);
    /// Acceleration right-hand side γ = −(Φq q̇)q q̇ − 2Φqt q̇ − Φtt.
    fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]);
    /// Mass matrix nonzeros in pattern order.
    fn mass(&self, q: &[f64], out: &mut [f64]);
    /// Generalized applied and velocity-dependent forces Q(q, q̇, t).
    fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]);
    /// Nonzeros of the applied loads' ∂Q/∂q (`dq`, pattern `force_q_*`) and ∂Q/∂q̇ (`dqd`,
    /// pattern `force_qd_*`): their stiffness and damping, for an implicit integrator's
    /// Newton matrix. The default writes nothing and goes with empty patterns.
    fn force_jacobian(&self, q: &[f64], qd: &[f64], t: f64, dq: &mut [f64], dqd: &mut [f64]) {
        let _ = (q, qd, t, dq, dqd);
    }
    /// Potential energy of the conservative applied forces (gravity, springs).
    fn potential(&self, q: &[f64]) -> f64;
    /// Power of the non-conservative applied forces (dampers, actuator forces, applied
    /// forces and torques given as functions of time) at `(q, q̇, t)`.
    fn power_nc(&self, q: &[f64], qd: &[f64], t: f64) -> f64;
    /// Φ, Φq, M, Q at one state, sharing trigonometry: what one Newton iteration needs.
    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>);
    /// Φ, Φq, Φt, γ at one state, sharing trigonometry: what kinematic analysis needs.
    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>);
    /// The run-time values the equations read (the generated code's `p`: named parameters,
    /// then the model's numbers that other parameters reach), the coordinates of
    /// [`Direction::dp`]. The default has none.
    fn run_time_values(&self) -> &[f64] {
        &[]
    }
    /// The exact directional derivatives at `(q, q̇, t)` of Φ, Φq, Φt, γ, M and Q along `dir`
    /// (time held fixed), from the generator's forward-mode derivatives of the equations.
    /// `false` (writing nothing): this mechanism has none (the default).
    fn tangents(
        &self,
        q: &[f64],
        qd: &[f64],
        t: f64,
        dir: Direction<'_>,
        out: TangentOutputs<'_>,
    ) -> bool {
        let _ = (q, qd, t, dir, out);
        false
    }
}

/// A borrowed mechanism is a mechanism, so solvers that own theirs can also borrow one.
impl<T: Mechanism + ?Sized> Mechanism for &T {
    fn info(&self) -> &'static MechanismInfo {
        (**self).info()
    }
    fn phi(&self, q: &[f64], t: f64, out: &mut [f64]) {
        (**self).phi(q, t, out)
    }
    fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) {
        (**self).phi_q(q, t, out)
    }
    fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) {
        (**self).phi_t(q, t, out)
    }
    fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        (**self).gamma(q, qd, t, out)
    }
    fn mass(&self, q: &[f64], out: &mut [f64]) {
        (**self).mass(q, out)
    }
    fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        (**self).force(q, qd, t, out)
    }
    fn force_jacobian(&self, q: &[f64], qd: &[f64], t: f64, dq: &mut [f64], dqd: &mut [f64]) {
        (**self).force_jacobian(q, qd, t, dq, dqd)
    }
    fn potential(&self, q: &[f64]) -> f64 {
        (**self).potential(q)
    }
    fn power_nc(&self, q: &[f64], qd: &[f64], t: f64) -> f64 {
        (**self).power_nc(q, qd, t)
    }
    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        (**self).eval_newton(q, qd, t, out)
    }
    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
        (**self).eval_kinematics(q, qd, t, out)
    }
    fn run_time_values(&self) -> &[f64] {
        (**self).run_time_values()
    }
    fn tangents(
        &self,
        q: &[f64],
        qd: &[f64],
        t: f64,
        dir: Direction<'_>,
        out: TangentOutputs<'_>,
    ) -> bool {
        (**self).tangents(q, qd, t, dir, out)
    }
}
