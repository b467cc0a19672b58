//! Hand-written test fixtures: small mechanisms implementing [`Mechanism`] with the same
//! conventions as generated code (bodies `[X, Y, Z, θ, β, γ]`, `A = Rz(γ)Ry(β)Rx(θ)`,
//! Y up, gravity −Y), so the solvers can be tested against analytic results without the
//! generator. Not meant for production use.
//!
//! - [`Pendulum`]: one rigid body hanging from a spherical joint at a ground point, in the
//!   paper (diagonal, constant mass) or exact (configuration-dependent mass) formulation.
//! - [`CircleDriver`]: one body whose centre is held at `X = d` and driven to distance
//!   `c(t) = c0 − v·t` from the origin; the driver becomes impossible at `t = (c0 − d)/v`.
//! - [`QuaternionPendulum`]: the exact pendulum with Euler parameters and its
//!   normalization row.
//! - [`TwoBallHinge`]: the exact pendulum on a hinge made of two ball joints, a redundant
//!   constraint row (consistent, or contradicting the other joint by a misalignment).

use crate::mechanism::{
    BodyInfo, Formulation, JointInfo, JointKind, KinematicOutputs, Mechanism, MechanismInfo,
    NewtonOutputs, Rotation,
};

/// Standard gravity used by the fixtures (m/s²).
pub const G: f64 = 9.81;

/// `A = Rz(γ)·Ry(β)·Rx(θ)`, row-major.
pub fn rotation(theta: f64, beta: f64, gamma: f64) -> [[f64; 3]; 3] {
    let (st, ct) = theta.sin_cos();
    let (sb, cb) = beta.sin_cos();
    let (sg, cg) = gamma.sin_cos();
    [
        [cg * cb, cg * sb * st - sg * ct, cg * sb * ct + sg * st],
        [sg * cb, sg * sb * st + cg * ct, sg * sb * ct - cg * st],
        [-sb, cb * st, cb * ct],
    ]
}

fn mat_vec(a: &[[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    [
        a[0][0] * v[0] + a[0][1] * v[1] + a[0][2] * v[2],
        a[1][0] * v[0] + a[1][1] * v[1] + a[1][2] * v[2],
        a[2][0] * v[0] + a[2][1] * v[1] + a[2][2] * v[2],
    ]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Columns of `H` in `ω_global = H·(θ̇, β̇, γ̇)` for `Rz·Ry·Rx` angles.
fn h_columns(beta: f64, gamma: f64) -> [[f64; 3]; 3] {
    let (sb, cb) = beta.sin_cos();
    let (sg, cg) = gamma.sin_cos();
    [[cg * cb, sg * cb, -sb], [-sg, cg, 0.0], [0.0, 0.0, 1.0]]
}

/// Global arm `u = A s` of the local point `s` of the body at `q`.
fn arm_of(q: &[f64], s: [f64; 3]) -> [f64; 3] {
    mat_vec(&rotation(q[3], q[4], q[5]), s)
}

/// Columns `∂(A s)/∂(θ, β, γ) = h_k × u` of a body point whose arm is `u = A s`.
fn arm_angle_columns(q: &[f64], u: [f64; 3]) -> [[f64; 3]; 3] {
    let h = h_columns(q[4], q[5]);
    [cross(h[0], u), cross(h[1], u), cross(h[2], u)]
}

/// γ of a point row `r + A s − g`: `d²(A s)/dt² = α × u + ω × (ω × u)` with
/// `α = H p̈ + Ḣ ṗ`; γ keeps the `p̈`-free part, negated.
fn point_gamma(q: &[f64], qd: &[f64], u: [f64; 3]) -> [f64; 3] {
    let h = h_columns(q[4], q[5]);
    let (td, bd, gd) = (qd[3], qd[4], qd[5]);
    let w = [
        h[0][0] * td + h[1][0] * bd + h[2][0] * gd,
        h[0][1] * td + h[1][1] * bd + h[2][1] * gd,
        h[0][2] * td + h[1][2] * bd + h[2][2] * gd,
    ];
    let (sb, cb) = q[4].sin_cos();
    let (sg, cg) = q[5].sin_cos();
    let hdot_pd = [
        td * (-sg * cb * gd - cg * sb * bd) + bd * (-cg * gd),
        td * (cg * cb * gd - sg * sb * bd) + bd * (-sg * gd),
        td * (-cb * bd),
    ];
    let a = cross(hdot_pd, u);
    let b = cross(w, cross(w, u));
    [-(a[0] + b[0]), -(a[1] + b[1]), -(a[2] + b[2])]
}

/// `B` in the body-frame angular velocity `ω_b = B·(θ̇, β̇, γ̇)`, row-major.
fn body_rate_matrix(theta: f64, beta: f64) -> [[f64; 3]; 3] {
    let (st, ct) = theta.sin_cos();
    let (sb, cb) = beta.sin_cos();
    [[1.0, 0.0, -sb], [0.0, ct, st * cb], [0.0, -st, ct * cb]]
}

// ---------------------------------------------------------------------------------------
// Pendulum

/// Pendulum mass (kg).
pub const PENDULUM_MASS: f64 = 2.0;
/// Principal inertias about the centre of mass (kg·m²).
pub const PENDULUM_INERTIA: [f64; 3] = [0.03, 0.02, 0.04];
/// Distance from the centre of mass up to the pivot, along local +y (m).
pub const PENDULUM_LENGTH: f64 = 0.5;

const PENDULUM_PHIQ_ROWS: [u32; 11] = [0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2];
const PENDULUM_PHIQ_COLS: [u32; 11] = [0, 3, 4, 5, 1, 3, 4, 5, 2, 3, 4];
const COORD_NAMES: [&str; 6] = [
    "bob.x",
    "bob.y",
    "bob.z",
    "bob.theta",
    "bob.beta",
    "bob.gamma",
];
const PENDULUM_BODIES: [BodyInfo; 1] = [BodyInfo {
    name: "bob",
    coord_offset: 0,
    rotation: Rotation::Euler,
    mass: PENDULUM_MASS,
    inertia: PENDULUM_INERTIA,
}];
const PENDULUM_JOINTS: [JointInfo; 1] = [JointInfo {
    name: "pivot",
    kind: JointKind::Spherical,
    body1: Some(0),
    body2: None,
    row_start: 0,
    rows: 3,
    point1: [0.0, PENDULUM_LENGTH, 0.0],
    point2: [0.0; 3],
    effort_sign: 0.0,
    effort_unit: "",
}];
const PENDULUM_ROWS: [&str; 3] = ["pivot.x", "pivot.y", "pivot.z"];
const PENDULUM_Q0: [f64; 6] = [0.0, -PENDULUM_LENGTH, 0.0, 0.0, 0.0, 0.0];

static PENDULUM_PAPER: MechanismInfo = MechanismInfo {
    name: "pendulum_paper",
    n_coords: 6,
    n_constraints: 3,
    formulation: Formulation::Paper,
    gravity: [0.0, -G, 0.0],
    phi_q_rows: &PENDULUM_PHIQ_ROWS,
    phi_q_cols: &PENDULUM_PHIQ_COLS,
    mass_rows: &[0, 1, 2, 3, 4, 5],
    mass_cols: &[0, 1, 2, 3, 4, 5],
    mass_is_constant: true,
    force_q_rows: &[],
    force_q_cols: &[],
    force_qd_rows: &[],
    force_qd_cols: &[],
    bodies: &PENDULUM_BODIES,
    joints: &PENDULUM_JOINTS,
    coord_names: &COORD_NAMES,
    row_names: &PENDULUM_ROWS,
    q0: &PENDULUM_Q0,
    qd0: &[0.0; 6],
    redundant_rows: &[],
    platform: None,
    kkt: &[],
};

static PENDULUM_EXACT: MechanismInfo = MechanismInfo {
    name: "pendulum_exact",
    formulation: Formulation::Exact,
    mass_rows: &[0, 1, 2, 3, 3, 3, 4, 4, 4, 5, 5, 5],
    mass_cols: &[0, 1, 2, 3, 4, 5, 3, 4, 5, 3, 4, 5],
    mass_is_constant: false,
    force_q_rows: &[],
    force_q_cols: &[],
    force_qd_rows: &[],
    force_qd_cols: &[],
    ..PENDULUM_PAPER
};

/// A rigid body hanging from a spherical joint: the body point at local `(0, L, 0)` is
/// held at the global origin (rows: body point minus ground point).
#[derive(Debug, Clone, Copy)]
pub struct Pendulum {
    pub formulation: Formulation,
}

impl Pendulum {
    /// Diagonal constant mass against Euler-angle accelerations, as the paper.
    pub fn paper() -> Self {
        Pendulum {
            formulation: Formulation::Paper,
        }
    }
    /// Mass matrix and velocity forces from the exact kinetic energy.
    pub fn exact() -> Self {
        Pendulum {
            formulation: Formulation::Exact,
        }
    }
    /// Pivot point relative to the centre of mass, global frame: `u = A·(0, L, 0)`.
    fn arm(q: &[f64]) -> [f64; 3] {
        arm_of(q, [0.0, PENDULUM_LENGTH, 0.0])
    }
    /// Kinetic energy ½ q̇ᵀ M q̇ evaluated from first principles (body-frame ω), for tests.
    pub fn kinetic_energy_exact(q: &[f64], qd: &[f64]) -> f64 {
        let b = body_rate_matrix(q[3], q[4]);
        let w = mat_vec(&b, [qd[3], qd[4], qd[5]]);
        let i = PENDULUM_INERTIA;
        0.5 * PENDULUM_MASS * (qd[0] * qd[0] + qd[1] * qd[1] + qd[2] * qd[2])
            + 0.5 * (i[0] * w[0] * w[0] + i[1] * w[1] * w[1] + i[2] * w[2] * w[2])
    }
}

impl Mechanism for Pendulum {
    fn info(&self) -> &'static MechanismInfo {
        match self.formulation {
            Formulation::Paper => &PENDULUM_PAPER,
            Formulation::Exact => &PENDULUM_EXACT,
        }
    }

    fn phi(&self, q: &[f64], _t: f64, out: &mut [f64]) {
        let u = Self::arm(q);
        for k in 0..3 {
            out[k] = q[k] + u[k];
        }
    }

    fn phi_q(&self, q: &[f64], _t: f64, out: &mut [f64]) {
        let c = arm_angle_columns(q, Self::arm(q));
        out.copy_from_slice(&[
            1.0, c[0][0], c[1][0], c[2][0], //
            1.0, c[0][1], c[1][1], c[2][1], //
            1.0, c[0][2], c[1][2],
        ]);
    }

    fn phi_t(&self, _q: &[f64], _t: f64, out: &mut [f64]) {
        out.fill(0.0);
    }

    fn gamma(&self, q: &[f64], qd: &[f64], _t: f64, out: &mut [f64]) {
        out.copy_from_slice(&point_gamma(q, qd, Self::arm(q)));
    }

    fn mass(&self, q: &[f64], out: &mut [f64]) {
        let m = PENDULUM_MASS;
        let i = PENDULUM_INERTIA;
        match self.formulation {
            Formulation::Paper => out.copy_from_slice(&[m, m, m, i[0], i[1], i[2]]),
            Formulation::Exact => {
                let b = body_rate_matrix(q[3], q[4]);
                out[..3].copy_from_slice(&[m, m, m]);
                for r in 0..3 {
                    for c in 0..3 {
                        out[3 + 3 * r + c] = (0..3).map(|k| b[k][r] * i[k] * b[k][c]).sum();
                    }
                }
            }
        }
    }

    fn force(&self, q: &[f64], qd: &[f64], _t: f64, out: &mut [f64]) {
        out.fill(0.0);
        out[1] = -PENDULUM_MASS * G;
        if self.formulation == Formulation::Paper {
            return;
        }
        // Lagrange with T = ½ ṗᵀBᵀIBṗ: Q_v = ∂T/∂p − (ḂᵀIω + BᵀIḂṗ), ω = Bṗ.
        let (st, ct) = q[3].sin_cos();
        let (sb, cb) = q[4].sin_cos();
        let pd = [qd[3], qd[4], qd[5]];
        let b = body_rate_matrix(q[3], q[4]);
        let b_th = [[0.0, 0.0, 0.0], [0.0, -st, ct * cb], [0.0, -ct, -st * cb]];
        let b_be = [[0.0, 0.0, -cb], [0.0, 0.0, -st * sb], [0.0, 0.0, -ct * sb]];
        let i = PENDULUM_INERTIA;
        let w = mat_vec(&b, pd);
        let iw = [i[0] * w[0], i[1] * w[1], i[2] * w[2]];
        let mut bdot = [[0.0; 3]; 3];
        for r in 0..3 {
            for c in 0..3 {
                bdot[r][c] = pd[0] * b_th[r][c] + pd[1] * b_be[r][c];
            }
        }
        let bdot_pd = mat_vec(&bdot, pd);
        let dtheta = mat_vec(&b_th, pd);
        let dbeta = mat_vec(&b_be, pd);
        let dot = |a: [f64; 3], c: [f64; 3]| a[0] * c[0] + a[1] * c[1] + a[2] * c[2];
        let dtdp = [dot(iw, dtheta), dot(iw, dbeta), 0.0];
        for k in 0..3 {
            let bdot_t_iw: f64 = (0..3).map(|r| bdot[r][k] * iw[r]).sum();
            let bt_i_bdot: f64 = (0..3).map(|r| b[r][k] * i[r] * bdot_pd[r]).sum();
            out[3 + k] = dtdp[k] - bdot_t_iw - bt_i_bdot;
        }
    }

    fn potential(&self, q: &[f64]) -> f64 {
        PENDULUM_MASS * G * q[1]
    }

    fn power_nc(&self, _q: &[f64], _qd: &[f64], _t: f64) -> f64 {
        // Gravity is the only applied force, and it is conservative.
        0.0
    }

    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        self.phi(q, t, out.phi);
        self.phi_q(q, t, out.phi_q);
        self.mass(q, out.mass);
        self.force(q, qd, t, out.force);
    }

    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
        self.phi(q, t, out.phi);
        self.phi_q(q, t, out.phi_q);
        self.phi_t(q, t, out.phi_t);
        self.gamma(q, qd, t, out.gamma);
    }
}

// ---------------------------------------------------------------------------------------
// Circle driver

/// Mass of the driven body (kg).
pub const CIRCLE_MASS: f64 = 1.5;
/// Fixed X of the body's centre (m).
pub const CIRCLE_D: f64 = 0.3;
/// Initial driven distance from the origin (m).
pub const CIRCLE_C0: f64 = 0.5;
/// Rate at which the driven distance shrinks (m/s).
pub const CIRCLE_V: f64 = 0.1;

const CIRCLE_Q0: [f64; 6] = [CIRCLE_D, 0.4, 0.0, 0.0, 0.0, 0.0];

static CIRCLE: MechanismInfo = MechanismInfo {
    name: "circle_driver",
    n_coords: 6,
    n_constraints: 6,
    formulation: Formulation::Paper,
    gravity: [0.0, -G, 0.0],
    phi_q_rows: &[0, 1, 2, 3, 4, 5, 5],
    phi_q_cols: &[0, 2, 3, 4, 5, 0, 1],
    mass_rows: &[0, 1, 2, 3, 4, 5],
    mass_cols: &[0, 1, 2, 3, 4, 5],
    mass_is_constant: true,
    force_q_rows: &[],
    force_q_cols: &[],
    force_qd_rows: &[],
    force_qd_cols: &[],
    bodies: &[BodyInfo {
        name: "slider",
        coord_offset: 0,
        rotation: Rotation::Euler,
        mass: CIRCLE_MASS,
        inertia: [0.01, 0.02, 0.03],
    }],
    joints: &[
        JointInfo {
            name: "guide",
            kind: JointKind::EulerPrismatic,
            body1: Some(0),
            body2: None,
            row_start: 0,
            rows: 5,
            point1: [0.0; 3],
            point2: [0.0; 3],
            effort_sign: 0.0,
            effort_unit: "",
        },
        JointInfo {
            name: "lift",
            kind: JointKind::Driver,
            body1: Some(0),
            body2: None,
            row_start: 5,
            rows: 1,
            point1: [0.0; 3],
            point2: [0.0; 3],
            // Φ = s − c(t) with s = √(X² + Y²): ∂Φ/∂s = 1.
            effort_sign: 1.0,
            effort_unit: "N",
        },
    ],
    coord_names: &[
        "slider.x",
        "slider.y",
        "slider.z",
        "slider.theta",
        "slider.beta",
        "slider.gamma",
    ],
    row_names: &[
        "guide.x",
        "guide.z",
        "guide.theta",
        "guide.beta",
        "guide.gamma",
        "lift",
    ],
    q0: &CIRCLE_Q0,
    qd0: &[0.0; 6],
    redundant_rows: &[],
    platform: None,
    kkt: &[],
};

/// Rows: `X − d`, `Z`, `θ`, `β`, `γ` (the guide), then `√(X² + Y²) − c(t)` (the driver),
/// with `c(t) = c0 − v·t`. Exactly determined: `Y = √(c² − d²)`, singular when `c = d`.
#[derive(Debug, Clone, Copy, Default)]
pub struct CircleDriver;

impl CircleDriver {
    /// Driven distance `c(t)`.
    pub fn c(t: f64) -> f64 {
        CIRCLE_C0 - CIRCLE_V * t
    }
}

impl Mechanism for CircleDriver {
    fn info(&self) -> &'static MechanismInfo {
        &CIRCLE
    }

    fn phi(&self, q: &[f64], t: f64, out: &mut [f64]) {
        out[0] = q[0] - CIRCLE_D;
        out[1] = q[2];
        out[2] = q[3];
        out[3] = q[4];
        out[4] = q[5];
        out[5] = q[0].hypot(q[1]) - Self::c(t);
    }

    fn phi_q(&self, q: &[f64], _t: f64, out: &mut [f64]) {
        let r = q[0].hypot(q[1]);
        out.copy_from_slice(&[1.0, 1.0, 1.0, 1.0, 1.0, q[0] / r, q[1] / r]);
    }

    fn phi_t(&self, _q: &[f64], _t: f64, out: &mut [f64]) {
        out.fill(0.0);
        out[5] = CIRCLE_V;
    }

    fn gamma(&self, q: &[f64], qd: &[f64], _t: f64, out: &mut [f64]) {
        out.fill(0.0);
        let r = q[0].hypot(q[1]);
        let rd = (q[0] * qd[0] + q[1] * qd[1]) / r;
        out[5] = -((qd[0] * qd[0] + qd[1] * qd[1]) / r - rd * rd / r);
    }

    fn mass(&self, _q: &[f64], out: &mut [f64]) {
        let m = CIRCLE_MASS;
        out.copy_from_slice(&[m, m, m, 0.01, 0.02, 0.03]);
    }

    fn force(&self, _q: &[f64], _qd: &[f64], _t: f64, out: &mut [f64]) {
        out.fill(0.0);
        out[1] = -CIRCLE_MASS * G;
    }

    fn potential(&self, q: &[f64]) -> f64 {
        CIRCLE_MASS * G * q[1]
    }

    fn power_nc(&self, _q: &[f64], _qd: &[f64], _t: f64) -> f64 {
        // Gravity is the only applied force; the driver's power is a constraint power.
        0.0
    }

    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        self.phi(q, t, out.phi);
        self.phi_q(q, t, out.phi_q);
        self.mass(q, out.mass);
        self.force(q, qd, t, out.force);
    }

    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
        self.phi(q, t, out.phi);
        self.phi_q(q, t, out.phi_q);
        self.phi_t(q, t, out.phi_t);
        self.gamma(q, qd, t, out.gamma);
    }
}

// ---------------------------------------------------------------------------------------
// Two-ball hinge

/// Half the distance between the hinge's two ball joints, along global Z (m).
pub const HINGE_HALF_WIDTH: f64 = 0.2;
/// The ball joints' points on the body: `(0, L, ±a)` in local coordinates.
pub const HINGE_POINTS: [[f64; 3]; 2] = [
    [0.0, PENDULUM_LENGTH, HINGE_HALF_WIDTH],
    [0.0, PENDULUM_LENGTH, -HINGE_HALF_WIDTH],
];

const HINGE_PHIQ_ROWS: [u32; 22] = [
    0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, //
    3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5,
];
const HINGE_PHIQ_COLS: [u32; 22] = [
    0, 3, 4, 5, 1, 3, 4, 5, 2, 3, 4, //
    0, 3, 4, 5, 1, 3, 4, 5, 2, 3, 4,
];
const HINGE_JOINTS: [JointInfo; 2] = [
    JointInfo {
        name: "ball1",
        kind: JointKind::Spherical,
        body1: Some(0),
        body2: None,
        row_start: 0,
        rows: 3,
        point1: HINGE_POINTS[0],
        point2: [0.0; 3],
        effort_sign: 0.0,
        effort_unit: "",
    },
    JointInfo {
        name: "ball2",
        kind: JointKind::Spherical,
        body1: Some(0),
        body2: None,
        row_start: 3,
        rows: 3,
        point1: HINGE_POINTS[1],
        point2: [0.0; 3],
        effort_sign: 0.0,
        effort_unit: "",
    },
];
const HINGE_ROWS: [&str; 6] = [
    "ball1.x", "ball1.y", "ball1.z", "ball2.x", "ball2.y", "ball2.z",
];

static HINGE: MechanismInfo = MechanismInfo {
    name: "two_ball_hinge",
    n_constraints: 6,
    phi_q_rows: &HINGE_PHIQ_ROWS,
    phi_q_cols: &HINGE_PHIQ_COLS,
    joints: &HINGE_JOINTS,
    row_names: &HINGE_ROWS,
    // Both z rows read `Z + (A s)_z ∓ a`; their gradients differ by `2a·(h_k × A e_z)_z`,
    // which vanishes while the body turns about Z: row 5 is row 2's copy.
    redundant_rows: &[5],
    ..PENDULUM_EXACT
};

static HINGE_UNDECLARED: MechanismInfo = MechanismInfo {
    name: "two_ball_hinge_undeclared",
    redundant_rows: &[],
    ..HINGE
};

/// The exact pendulum hung from a door hinge made of two ball joints on the global Z axis:
/// body points `(0, L, ±a)` held at ground points `(0, 0, a)` and `(δ, 0, −a)`. Six rows of
/// rank five (row 5, `ball2.z`, is redundant); with `δ ≠ 0` the two joints contradict each
/// other (the ground points are farther apart than the body points).
#[derive(Debug, Clone, Copy)]
pub struct TwoBallHinge {
    /// `δ`, the X offset of the second ground point (m); 0 for a consistent hinge.
    pub misalignment: f64,
    /// Whether the info declares row 5 redundant (the generator would).
    pub declared: bool,
}

impl TwoBallHinge {
    /// A hinge with its redundant row declared.
    pub fn new(misalignment: f64) -> Self {
        TwoBallHinge {
            misalignment,
            declared: true,
        }
    }

    fn ground(&self, k: usize) -> [f64; 3] {
        [
            if k == 0 { 0.0 } else { self.misalignment },
            0.0,
            HINGE_POINTS[k][2],
        ]
    }
}

impl Mechanism for TwoBallHinge {
    fn info(&self) -> &'static MechanismInfo {
        if self.declared {
            &HINGE
        } else {
            &HINGE_UNDECLARED
        }
    }

    fn phi(&self, q: &[f64], _t: f64, out: &mut [f64]) {
        for k in 0..2 {
            let (u, g) = (arm_of(q, HINGE_POINTS[k]), self.ground(k));
            for i in 0..3 {
                out[3 * k + i] = q[i] + u[i] - g[i];
            }
        }
    }

    fn phi_q(&self, q: &[f64], _t: f64, out: &mut [f64]) {
        for k in 0..2 {
            let c = arm_angle_columns(q, arm_of(q, HINGE_POINTS[k]));
            out[11 * k..11 * k + 11].copy_from_slice(&[
                1.0, c[0][0], c[1][0], c[2][0], //
                1.0, c[0][1], c[1][1], c[2][1], //
                1.0, c[0][2], c[1][2],
            ]);
        }
    }

    fn phi_t(&self, _q: &[f64], _t: f64, out: &mut [f64]) {
        out.fill(0.0);
    }

    fn gamma(&self, q: &[f64], qd: &[f64], _t: f64, out: &mut [f64]) {
        for k in 0..2 {
            out[3 * k..3 * k + 3].copy_from_slice(&point_gamma(q, qd, arm_of(q, HINGE_POINTS[k])));
        }
    }

    fn mass(&self, q: &[f64], out: &mut [f64]) {
        Pendulum::exact().mass(q, out)
    }

    fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        Pendulum::exact().force(q, qd, t, out)
    }

    fn potential(&self, q: &[f64]) -> f64 {
        Pendulum::exact().potential(q)
    }

    fn power_nc(&self, _q: &[f64], _qd: &[f64], _t: f64) -> f64 {
        0.0
    }

    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        self.phi(q, t, out.phi);
        self.phi_q(q, t, out.phi_q);
        self.mass(q, out.mass);
        self.force(q, qd, t, out.force);
    }

    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
        self.phi(q, t, out.phi);
        self.phi_q(q, t, out.phi_q);
        self.phi_t(q, t, out.phi_t);
        self.gamma(q, qd, t, out.gamma);
    }
}

// ---------------------------------------------------------------------------------------
// Quaternion pendulum

/// The augmentation `c` of the quaternion mass block `4GᵀJG + c·e eᵀ` (kg·m²): `4GᵀJG` is
/// singular (`G e = 0`), and the block Cholesky needs a positive definite block. Adding
/// `c·e(eᵀë + ėᵀė)`, which vanishes on the unit sphere, moves only the normalization
/// multiplier; `c = 4·mean(J)` keeps the block's eigenvalues (`4J_i` and `c`) alike.
pub const QUAT_AUGMENT: f64 =
    4.0 * (PENDULUM_INERTIA[0] + PENDULUM_INERTIA[1] + PENDULUM_INERTIA[2]) / 3.0;

const QUAT_PHIQ_ROWS: [u32; 19] = [0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 3, 3, 3, 3];
const QUAT_PHIQ_COLS: [u32; 19] = [0, 3, 4, 5, 6, 1, 3, 4, 5, 6, 2, 3, 4, 5, 6, 3, 4, 5, 6];
const QUAT_MASS_ROWS: [u32; 19] = [0, 1, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 6, 6, 6, 6];
const QUAT_MASS_COLS: [u32; 19] = [0, 1, 2, 3, 4, 5, 6, 3, 4, 5, 6, 3, 4, 5, 6, 3, 4, 5, 6];

static QUAT_PENDULUM: MechanismInfo = MechanismInfo {
    name: "pendulum_quaternion",
    n_coords: 7,
    n_constraints: 4,
    formulation: Formulation::Exact,
    gravity: [0.0, -G, 0.0],
    phi_q_rows: &QUAT_PHIQ_ROWS,
    phi_q_cols: &QUAT_PHIQ_COLS,
    mass_rows: &QUAT_MASS_ROWS,
    mass_cols: &QUAT_MASS_COLS,
    mass_is_constant: false,
    force_q_rows: &[],
    force_q_cols: &[],
    force_qd_rows: &[],
    force_qd_cols: &[],
    bodies: &[BodyInfo {
        name: "bob",
        coord_offset: 0,
        rotation: Rotation::Quaternion,
        mass: PENDULUM_MASS,
        inertia: PENDULUM_INERTIA,
    }],
    joints: &[
        JointInfo {
            name: "pivot",
            kind: JointKind::Spherical,
            body1: Some(0),
            body2: None,
            row_start: 0,
            rows: 3,
            point1: [0.0, PENDULUM_LENGTH, 0.0],
            point2: [0.0; 3],
            effort_sign: 0.0,
            effort_unit: "",
        },
        JointInfo {
            name: "bob.norm",
            kind: JointKind::Normalization,
            body1: Some(0),
            body2: None,
            row_start: 3,
            rows: 1,
            point1: [0.0; 3],
            point2: [0.0; 3],
            effort_sign: 0.0,
            effort_unit: "",
        },
    ],
    coord_names: &[
        "bob.x", "bob.y", "bob.z", "bob.e0", "bob.e1", "bob.e2", "bob.e3",
    ],
    row_names: &["pivot.x", "pivot.y", "pivot.z", "bob.norm"],
    q0: &[0.0, -PENDULUM_LENGTH, 0.0, 1.0, 0.0, 0.0, 0.0],
    qd0: &[0.0; 7],
    redundant_rows: &[],
    platform: None,
    kkt: &[],
};

/// The exact pendulum with Euler parameters: body point `(0, L, 0)` held at the origin,
/// rows `r + A(e)s` and the normalization row `eᵀe − 1`; mass and forces from
/// `T = ½m|ṙ|² + ½ω'ᵀJω' + ½c(eᵀė)²`, `ω' = 2G(e)ė` ([`QUAT_AUGMENT`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct QuaternionPendulum;

/// `G(e)` of the body-frame angular velocity `ω' = 2G(e)ė`, row-major.
pub fn quaternion_g(e: &[f64]) -> [[f64; 4]; 3] {
    [
        [-e[1], e[0], e[3], -e[2]],
        [-e[2], -e[3], e[0], e[1]],
        [-e[3], e[2], -e[1], e[0]],
    ]
}

/// `(2e0² − 1)s + 2ē(ēᵀs) + 2e0(ē × s)` with the constant term scaled by `one` (1 for
/// `A(e)s`; 0 for its quadratic part).
fn quaternion_arm(e: &[f64], s: [f64; 3], one: f64) -> [f64; 3] {
    let ev = [e[1], e[2], e[3]];
    let es = ev[0] * s[0] + ev[1] * s[1] + ev[2] * s[2];
    let c = cross(ev, s);
    let k = 2.0 * e[0] * e[0] - one;
    [
        k * s[0] + 2.0 * ev[0] * es + 2.0 * e[0] * c[0],
        k * s[1] + 2.0 * ev[1] * es + 2.0 * e[0] * c[1],
        k * s[2] + 2.0 * ev[2] * es + 2.0 * e[0] * c[2],
    ]
}

impl QuaternionPendulum {
    /// Kinetic energy `T` from its definition (with `ω' = 2G(e)ė`), for tests.
    pub fn kinetic_energy(q: &[f64], qd: &[f64]) -> f64 {
        let g = quaternion_g(&q[3..7]);
        let ed = &qd[3..7];
        let w: Vec<f64> = g
            .iter()
            .map(|row| 2.0 * row.iter().zip(ed).map(|(a, b)| a * b).sum::<f64>())
            .collect();
        let i = PENDULUM_INERTIA;
        let ee: f64 = q[3..7].iter().zip(ed).map(|(a, b)| a * b).sum();
        0.5 * PENDULUM_MASS * (qd[0] * qd[0] + qd[1] * qd[1] + qd[2] * qd[2])
            + 0.5 * (i[0] * w[0] * w[0] + i[1] * w[1] * w[1] + i[2] * w[2] * w[2])
            + 0.5 * QUAT_AUGMENT * ee * ee
    }
}

impl Mechanism for QuaternionPendulum {
    fn info(&self) -> &'static MechanismInfo {
        &QUAT_PENDULUM
    }

    fn phi(&self, q: &[f64], _t: f64, out: &mut [f64]) {
        let u = quaternion_arm(&q[3..7], [0.0, PENDULUM_LENGTH, 0.0], 1.0);
        for k in 0..3 {
            out[k] = q[k] + u[k];
        }
        out[3] = q[3..7].iter().map(|x| x * x).sum::<f64>() - 1.0;
    }

    fn phi_q(&self, q: &[f64], _t: f64, out: &mut [f64]) {
        // ∂(A s)/∂e0 = 4e0 s + 2 ē × s;  ∂(A s)/∂ē = 2((ēᵀs)I + ē sᵀ) − 2e0 [s×].
        let e = &q[3..7];
        let s = [0.0, PENDULUM_LENGTH, 0.0];
        let ev = [e[1], e[2], e[3]];
        let es = ev[0] * s[0] + ev[1] * s[1] + ev[2] * s[2];
        let c = cross(ev, s);
        let mut d = [[0.0; 4]; 3];
        for i in 0..3 {
            d[i][0] = 4.0 * e[0] * s[i] + 2.0 * c[i];
            for k in 0..3 {
                let ident = if i == k { es } else { 0.0 };
                // [s×][i][k]: the i-th component of s × e_k.
                let mut unit = [0.0; 3];
                unit[k] = 1.0;
                let sx = cross(s, unit)[i];
                d[i][1 + k] = 2.0 * (ident + ev[i] * s[k]) - 2.0 * e[0] * sx;
            }
        }
        for i in 0..3 {
            out[5 * i] = 1.0;
            out[5 * i + 1..5 * i + 5].copy_from_slice(&d[i]);
        }
        for k in 0..4 {
            out[15 + k] = 2.0 * e[k];
        }
    }

    fn phi_t(&self, _q: &[f64], _t: f64, out: &mut [f64]) {
        out.fill(0.0);
    }

    fn gamma(&self, _q: &[f64], qd: &[f64], _t: f64, out: &mut [f64]) {
        // A(e)s is quadratic in e: at ë = 0 its second derivative is twice its quadratic
        // part at ė.
        let u = quaternion_arm(&qd[3..7], [0.0, PENDULUM_LENGTH, 0.0], 0.0);
        for k in 0..3 {
            out[k] = -2.0 * u[k];
        }
        out[3] = -2.0 * qd[3..7].iter().map(|x| x * x).sum::<f64>();
    }

    fn mass(&self, q: &[f64], out: &mut [f64]) {
        let m = PENDULUM_MASS;
        let i = PENDULUM_INERTIA;
        let e = &q[3..7];
        let g = quaternion_g(e);
        out[..3].copy_from_slice(&[m, m, m]);
        for r in 0..4 {
            for c in 0..4 {
                let rot: f64 = (0..3).map(|k| 4.0 * g[k][r] * i[k] * g[k][c]).sum();
                out[3 + 4 * r + c] = rot + QUAT_AUGMENT * e[r] * e[c];
            }
        }
    }

    fn force(&self, q: &[f64], qd: &[f64], _t: f64, out: &mut [f64]) {
        // Lagrange: Q_v = 8 G(ė)ᵀ J G(ė) e − c e (ėᵀė).
        out.fill(0.0);
        out[1] = -PENDULUM_MASS * G;
        let (e, ed) = (&q[3..7], &qd[3..7]);
        let gd = quaternion_g(ed);
        let i = PENDULUM_INERTIA;
        let gde: Vec<f64> = gd
            .iter()
            .map(|row| row.iter().zip(e).map(|(a, b)| a * b).sum())
            .collect();
        let edd: f64 = ed.iter().map(|x| x * x).sum();
        for r in 0..4 {
            let v: f64 = (0..3).map(|k| 8.0 * gd[k][r] * i[k] * gde[k]).sum();
            out[3 + r] = v - QUAT_AUGMENT * e[r] * edd;
        }
    }

    fn potential(&self, q: &[f64]) -> f64 {
        PENDULUM_MASS * G * q[1]
    }

    fn power_nc(&self, _q: &[f64], _qd: &[f64], _t: f64) -> f64 {
        0.0
    }

    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        self.phi(q, t, out.phi);
        self.phi_q(q, t, out.phi_q);
        self.mass(q, out.mass);
        self.force(q, qd, t, out.force);
    }

    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
        self.phi(q, t, out.phi);
        self.phi_q(q, t, out.phi_q);
        self.phi_t(q, t, out.phi_t);
        self.gamma(q, qd, t, out.gamma);
    }
}

#[cfg(test)]
mod tests {
    //! The fixtures' hand-written derivatives against finite differences of their own Φ.
    use super::*;

    fn dense_phi_q<M: Mechanism>(mech: &M, q: &[f64], t: f64) -> Vec<Vec<f64>> {
        let info = mech.info();
        let mut vals = vec![0.0; info.phi_q_nnz()];
        mech.phi_q(q, t, &mut vals);
        let mut d = vec![vec![0.0; info.n_coords]; info.n_constraints];
        for e in 0..vals.len() {
            d[info.phi_q_rows[e] as usize][info.phi_q_cols[e] as usize] = vals[e];
        }
        d
    }

    fn check_derivatives<M: Mechanism>(mech: &M, q: &[f64], qd: &[f64], t: f64) {
        let info = mech.info();
        let (n, m) = (info.n_coords, info.n_constraints);
        let phi_at = |q: &[f64], t: f64| {
            let mut o = vec![0.0; m];
            mech.phi(q, t, &mut o);
            o
        };
        let jac = dense_phi_q(mech, q, t);
        let h = 1e-6;
        for j in 0..n {
            let (mut qp, mut qm) = (q.to_vec(), q.to_vec());
            qp[j] += h;
            qm[j] -= h;
            let (fp, fm) = (phi_at(&qp, t), phi_at(&qm, t));
            for i in 0..m {
                let fd = (fp[i] - fm[i]) / (2.0 * h);
                assert!(
                    (fd - jac[i][j]).abs() < 1e-8,
                    "Φq[{i}][{j}] {} vs {fd}",
                    jac[i][j]
                );
            }
        }
        let mut pt = vec![0.0; m];
        mech.phi_t(q, t, &mut pt);
        let (fp, fm) = (phi_at(q, t + h), phi_at(q, t - h));
        for i in 0..m {
            assert!((pt[i] - (fp[i] - fm[i]) / (2.0 * h)).abs() < 1e-8);
        }
        // Along q(s) = q + s q̇, t(s) = t + s: d²Φ/ds² = −γ (q̈ = 0 on this path).
        let h = 1e-4;
        let path = |s: f64| {
            let qs: Vec<f64> = q.iter().zip(qd).map(|(a, b)| a + s * b).collect();
            phi_at(&qs, t + s)
        };
        let (fp, f0, fm) = (path(h), path(0.0), path(-h));
        let mut g = vec![0.0; m];
        mech.gamma(q, qd, t, &mut g);
        for i in 0..m {
            let d2 = (fp[i] - 2.0 * f0[i] + fm[i]) / (h * h);
            assert!((d2 + g[i]).abs() < 1e-5, "γ[{i}] {} vs {}", g[i], -d2);
        }
    }

    const Q: [f64; 6] = [0.1, -0.3, 0.2, 0.4, -0.7, 1.1];
    const QD: [f64; 6] = [0.3, -0.2, 0.5, 1.3, -0.8, 0.6];

    #[test]
    fn pendulum_derivatives_match_finite_differences() {
        check_derivatives(&Pendulum::paper(), &Q, &QD, 0.3);
        check_derivatives(&Pendulum::exact(), &Q, &QD, 0.3);
    }

    #[test]
    fn circle_driver_derivatives_match_finite_differences() {
        check_derivatives(&CircleDriver, &Q, &QD, 0.3);
    }

    #[test]
    fn two_ball_hinge_derivatives_match_finite_differences() {
        check_derivatives(&TwoBallHinge::new(0.01), &Q, &QD, 0.3);
    }

    #[test]
    fn exact_mass_is_the_kinetic_energy_hessian_and_omega_matches_rotation() {
        // ω̃_b = Aᵀ Ȧ from finite differences of A must agree with B ṗ.
        let p = [0.4, -0.7, 1.1];
        let pd = [1.3, -0.8, 0.6];
        let h = 1e-6;
        let ap = rotation(p[0] + h * pd[0], p[1] + h * pd[1], p[2] + h * pd[2]);
        let am = rotation(p[0] - h * pd[0], p[1] - h * pd[1], p[2] - h * pd[2]);
        let a = rotation(p[0], p[1], p[2]);
        let mut wt = [[0.0; 3]; 3];
        for r in 0..3 {
            for c in 0..3 {
                wt[r][c] = (0..3)
                    .map(|k| a[k][r] * (ap[k][c] - am[k][c]) / (2.0 * h))
                    .sum();
            }
        }
        let w = mat_vec(&body_rate_matrix(p[0], p[1]), pd);
        assert!((wt[2][1] - w[0]).abs() < 1e-8);
        assert!((wt[0][2] - w[1]).abs() < 1e-8);
        assert!((wt[1][0] - w[2]).abs() < 1e-8);
        // ½ q̇ᵀ M q̇ equals the kinetic energy computed from ω.
        let mech = Pendulum::exact();
        let mut mass = vec![0.0; 12];
        mech.mass(&Q, &mut mass);
        let info = mech.info();
        let mut t2 = 0.0;
        for e in 0..12 {
            t2 += mass[e] * QD[info.mass_rows[e] as usize] * QD[info.mass_cols[e] as usize];
        }
        assert!((0.5 * t2 - Pendulum::kinetic_energy_exact(&Q, &QD)).abs() < 1e-12);
    }

    #[test]
    fn exact_velocity_forces_follow_from_lagrange() {
        // Q_v = ∂T/∂q − d/dt(∂T/∂q̇) + M q̈ at q̈ = 0, with both terms from finite
        // differences of the kinetic energy.
        let mech = Pendulum::exact();
        let t_of = |q: &[f64], qd: &[f64]| Pendulum::kinetic_energy_exact(q, qd);
        let h = 1e-5;
        let mut qv = [0.0; 6];
        mech.force(&Q, &QD, 0.0, &mut qv);
        qv[1] += PENDULUM_MASS * G;
        for k in 3..6 {
            let (mut qp, mut qm) = (Q, Q);
            qp[k] += h;
            qm[k] -= h;
            let dtdq = (t_of(&qp, &QD) - t_of(&qm, &QD)) / (2.0 * h);
            // d/dt ∂T/∂q̇_k along q(s) = q + s q̇, q̇ fixed.
            let p_at = |s: f64| {
                let qs: Vec<f64> = Q.iter().zip(&QD).map(|(a, b)| a + s * b).collect();
                let (mut vp, mut vm) = (QD, QD);
                vp[k] += h;
                vm[k] -= h;
                (t_of(&qs, &vp) - t_of(&qs, &vm)) / (2.0 * h)
            };
            let ddt = (p_at(h) - p_at(-h)) / (2.0 * h);
            assert!(
                (qv[k] - (dtdq - ddt)).abs() < 1e-5,
                "Q_v[{k}] {} vs {}",
                qv[k],
                dtdq - ddt
            );
        }
    }

    const Q7: [f64; 7] = [0.1, -0.3, 0.2, 0.7, -0.4, 0.5, 0.3];
    const QD7: [f64; 7] = [0.3, -0.2, 0.5, 1.3, -0.8, 0.6, -0.4];

    #[test]
    fn quaternion_pendulum_derivatives_match_finite_differences() {
        check_derivatives(&QuaternionPendulum, &Q7, &QD7, 0.3);
    }

    #[test]
    fn quaternion_mass_and_forces_follow_from_the_kinetic_energy() {
        // Off the unit sphere on purpose: the formulas must hold for any e.
        let mech = QuaternionPendulum;
        let info = mech.info();
        let t_of = |q: &[f64], qd: &[f64]| QuaternionPendulum::kinetic_energy(q, qd);
        let mut mass = vec![0.0; info.mass_nnz()];
        mech.mass(&Q7, &mut mass);
        let mut t2 = 0.0;
        for e in 0..mass.len() {
            t2 += mass[e] * QD7[info.mass_rows[e] as usize] * QD7[info.mass_cols[e] as usize];
        }
        assert!((0.5 * t2 - t_of(&Q7, &QD7)).abs() < 1e-12);
        let mut qv = [0.0; 7];
        mech.force(&Q7, &QD7, 0.0, &mut qv);
        qv[1] += PENDULUM_MASS * G;
        let h = 1e-5;
        for k in 0..7 {
            let (mut qp, mut qm) = (Q7, Q7);
            qp[k] += h;
            qm[k] -= h;
            let dtdq = (t_of(&qp, &QD7) - t_of(&qm, &QD7)) / (2.0 * h);
            let p_at = |s: f64| {
                let qs: Vec<f64> = Q7.iter().zip(&QD7).map(|(a, b)| a + s * b).collect();
                let (mut vp, mut vm) = (QD7, QD7);
                vp[k] += h;
                vm[k] -= h;
                (t_of(&qs, &vp) - t_of(&qs, &vm)) / (2.0 * h)
            };
            let ddt = (p_at(h) - p_at(-h)) / (2.0 * h);
            assert!(
                (qv[k] - (dtdq - ddt)).abs() < 1e-5,
                "Q_v[{k}] {} vs {}",
                qv[k],
                dtdq - ddt
            );
        }
    }

    #[test]
    fn quaternion_body_rate_is_the_rotated_global_rate() {
        // On the unit sphere with eᵀė = 0: ω' = 2Gė must equal Aᵀω, ω = 2Eė from `pose`.
        let info = QuaternionPendulum.info();
        let b = &info.bodies[0];
        let mut q = Q7;
        let n = q[3..].iter().map(|x| x * x).sum::<f64>().sqrt();
        q[3..].iter_mut().for_each(|x| *x /= n);
        let mut qd = QD7;
        let along: f64 = q[3..].iter().zip(&qd[3..]).map(|(a, b)| a * b).sum();
        for k in 3..7 {
            qd[k] -= along * q[k];
        }
        let a = crate::pose::rotation_matrix(b, &q).unwrap();
        let w_body = a.transpose() * crate::pose::angular_velocity(b, &q, &qd).unwrap();
        let g = quaternion_g(&q[3..]);
        for k in 0..3 {
            let w: f64 = 2.0 * (0..4).map(|c| g[k][c] * qd[3 + c]).sum::<f64>();
            assert!((w - w_body[k]).abs() < 1e-14, "{w} vs {}", w_body[k]);
        }
    }
}
