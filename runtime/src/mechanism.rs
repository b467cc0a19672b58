//! The contract between generated mechanism code and the solvers: sizes, sparsity patterns,
//! names, and the evaluation functions the generator emits.
//!
//! Conventions shared by every implementation:
//! - `q`, `qd` have `n_coords` entries; each body owns six consecutive coordinates
//!   `[X, Y, Z, θ, β, γ]` (centre of mass, then Rz(γ)·Ry(β)·Rx(θ) Euler angles).
//! - Equations of motion are `M q̈ + Φqᵀ λ = Q` and `Φq q̈ = γ`.
//! - Sparse matrices are written as their structural nonzeros only, in the order of the
//!   pattern arrays in [`MechanismInfo`]; zeros outside the pattern are never written.

/// How a joint constrains its bodies; the runtime uses it for reports and reaction forces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JointKind {
    /// Three rows: point on body 1 minus point on body 2 (or a ground point).
    Spherical,
    /// Five rows: three Euler-angle equalities, then two no-slide rows (paper eqs. 4–8).
    Prismatic,
    /// One row: distance along the prismatic axis minus a function of time.
    Driver,
}

/// One rigid body of the mechanism.
#[derive(Debug, Clone, Copy)]
pub struct BodyInfo {
    pub name: &'static str,
    /// Index of the body's `X` coordinate; `θ, β, γ` follow at `+3, +4, +5`.
    pub coord_offset: usize,
    pub mass: f64,
    /// Principal inertias about the centre of mass, local axes.
    pub inertia: [f64; 3],
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
    pub bodies: &'static [BodyInfo],
    pub joints: &'static [JointInfo],
    /// Human-readable name of each coordinate, e.g. `platform.beta`.
    pub coord_names: &'static [&'static str],
    /// Human-readable name of each constraint row, e.g. `upper_sph1.y`.
    pub row_names: &'static [&'static str],
    /// Initial coordinates written in the mechanism file (consistent or close to it).
    pub q0: &'static [f64],
}

impl MechanismInfo {
    pub fn phi_q_nnz(&self) -> usize {
        self.phi_q_rows.len()
    }
    pub fn mass_nnz(&self) -> usize {
        self.mass_rows.len()
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
    /// Potential energy of the applied (conservative) forces.
    fn potential(&self, q: &[f64]) -> f64;
    /// Φ, Φq, M, Q at one state, sharing trigonometry: what one Newton iteration needs.
    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>);
    /// Φ, Φq, Φt, γ at one state, sharing trigonometry: what kinematic analysis needs.
    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>);
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
    fn potential(&self, q: &[f64]) -> f64 {
        (**self).potential(q)
    }
    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        (**self).eval_newton(q, qd, t, out)
    }
    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
        (**self).eval_kinematics(q, qd, t, out)
    }
}
