//! Generated equations of `simple_pendulum` (IFToMM benchmark A01: planar simple pendulum, point mass on a massless link). Do not edit.
//!
//! Regenerate with `cargo xtask generate simple_pendulum` from `mechanisms/simple_pendulum.toml`.
//!
//! 6 coordinates, 1 constraints, 3 structural nonzeros in Φq.
//! Rank 1 at the initial pose; mobility 5 (Grübler count 5), 5 DOF left with drivers.
//! Each body owns `[X, Y, Z]` (centre of mass), then `[θ, β, γ]` (A = Rz(γ)·Ry(β)·Rx(θ))
//! or Euler parameters `[e0, e1, e2, e3]`. Equations of motion: `M q̈ + Φqᵀλ = Q`, `Φq q̈ = γ`.
//! Sparse outputs hold the pattern's nonzeros in order (row-major, columns ascending).
//!
//! Coordinates:
//! - `0..6` p1 (euler)
//!
//! Constraint rows:
//! - `0..1` link (distance, ground – p1)
#![allow(
    clippy::approx_constant,
    clippy::excessive_precision,
    clippy::too_many_arguments,
    clippy::unreadable_literal
)]
use symbody_runtime::{
    BodyInfo, Entry, Formulation, JointInfo, JointKind, KinematicOutputs, Mechanism,
    MechanismInfo, NewtonOutputs, Origin, PlatformInfo, Reduction, Substitution, Rotation,
};
use symbody_runtime::parameters::{ParameterError, RunTimeParameters};
/// Constraint residual Φ(q, t).
pub fn phi(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = t;
    phi_part_0(q, out);
}
#[inline(never)]
fn phi_part_0(q: &[f64; 6], out: &mut [f64; 1]) {
    let x35 = q[0] * q[0];
    let x36 = q[1] * q[1];
    let x37 = q[2] * q[2];
    let x38 = x35 + x36;
    let x39 = x37 + x38;
    let x40 = x39.sqrt();
    let x42 = x40 - 1.0;
    out[0] = x42;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 3] = out.try_into().expect("out must have 3 entries");
    let _ = t;
    phi_q_part_0(q, out);
}
#[inline(never)]
fn phi_q_part_0(q: &[f64; 6], out: &mut [f64; 3]) {
    let x35 = q[0] * q[0];
    let x36 = q[1] * q[1];
    let x37 = q[2] * q[2];
    let x38 = x35 + x36;
    let x39 = x37 + x38;
    let x40 = x39.sqrt();
    let x44 = q[0] * 2.0;
    let x45 = q[1] * 2.0;
    let x46 = q[2] * 2.0;
    let x47 = x40 * 2.0;
    let x48 = 1.0 / x47;
    let x49 = x44 * x48;
    let x50 = x45 * x48;
    let x51 = x46 * x48;
    out[0] = x49;
    out[1] = x50;
    out[2] = x51;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = q;
    let _ = t;
    phi_t_part_0(out);
}
#[inline(never)]
fn phi_t_part_0(out: &mut [f64; 1]) {
    out[0] = 0.0;
}
/// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
pub fn gamma(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = t;
    gamma_part_0(q, qd, out);
}
#[inline(never)]
fn gamma_part_0(q: &[f64; 6], qd: &[f64; 6], out: &mut [f64; 1]) {
    let x35 = q[0] * q[0];
    let x36 = q[1] * q[1];
    let x37 = q[2] * q[2];
    let x38 = x35 + x36;
    let x39 = x37 + x38;
    let x40 = x39.sqrt();
    let x44 = q[0] * 2.0;
    let x45 = q[1] * 2.0;
    let x46 = q[2] * 2.0;
    let x47 = x40 * 2.0;
    let x48 = 1.0 / x47;
    let x58 = x44 * qd[0];
    let x59 = x45 * qd[1];
    let x60 = x46 * qd[2];
    let x61 = x58 + x59;
    let x62 = x60 + x61;
    let x63 = x48 * x62;
    let x64 = 2.0 * qd[0];
    let x65 = 2.0 * qd[1];
    let x66 = 2.0 * qd[2];
    let x67 = 2.0 * x63;
    let x68 = x48 * x48;
    let x69 = x67 * x68;
    let x71 = qd[0] * x64;
    let x72 = qd[1] * x65;
    let x73 = qd[2] * x66;
    let x74 = x71 + x72;
    let x75 = x73 + x74;
    let x76 = x62 * x69;
    let x78 = x48 * x75;
    let x79 = x78 - x76;
    let x80 = -x79;
    out[0] = x80;
}
/// Φ, Φq, Φt and γ at one state in one pass, sharing every subexpression.
pub fn eval_kinematics(
    q: &[f64],
    qd: &[f64],
    t: f64,
    phi: &mut [f64],
    phi_q: &mut [f64],
    phi_t: &mut [f64],
    gamma: &mut [f64],
) {
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
    let phi: &mut [f64; 1] = phi.try_into().expect("phi must have 1 entries");
    let phi_q: &mut [f64; 3] = phi_q.try_into().expect("phi_q must have 3 entries");
    let phi_t: &mut [f64; 1] = phi_t.try_into().expect("phi_t must have 1 entries");
    let gamma: &mut [f64; 1] = gamma.try_into().expect("gamma must have 1 entries");
    let _ = t;
    eval_kinematics_part_0(q, qd, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_part_0(
    q: &[f64; 6],
    qd: &[f64; 6],
    phi: &mut [f64; 1],
    phi_q: &mut [f64; 3],
    phi_t: &mut [f64; 1],
    gamma: &mut [f64; 1],
) {
    let x35 = q[0] * q[0];
    let x36 = q[1] * q[1];
    let x37 = q[2] * q[2];
    let x38 = x35 + x36;
    let x39 = x37 + x38;
    let x40 = x39.sqrt();
    let x42 = x40 - 1.0;
    let x44 = q[0] * 2.0;
    let x45 = q[1] * 2.0;
    let x46 = q[2] * 2.0;
    let x47 = x40 * 2.0;
    let x48 = 1.0 / x47;
    let x49 = x44 * x48;
    let x50 = x45 * x48;
    let x51 = x46 * x48;
    let x58 = x44 * qd[0];
    let x59 = x45 * qd[1];
    let x60 = x46 * qd[2];
    let x61 = x58 + x59;
    let x62 = x60 + x61;
    let x63 = x48 * x62;
    let x64 = 2.0 * qd[0];
    let x65 = 2.0 * qd[1];
    let x66 = 2.0 * qd[2];
    let x67 = 2.0 * x63;
    let x68 = x48 * x48;
    let x69 = x67 * x68;
    let x71 = qd[0] * x64;
    let x72 = qd[1] * x65;
    let x73 = qd[2] * x66;
    let x74 = x71 + x72;
    let x75 = x73 + x74;
    let x76 = x62 * x69;
    let x78 = x48 * x75;
    let x79 = x78 - x76;
    let x80 = -x79;
    phi[0] = x42;
    phi_q[0] = x49;
    phi_q[1] = x50;
    phi_q[2] = x51;
    phi_t[0] = 0.0;
    gamma[0] = x80;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
    let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    potential_into_part_0(k, q, out);
}
#[inline(never)]
fn potential_into_part_0(k: &[f64; 5], q: &[f64; 6], out: &mut [f64; 1]) {
    let x324 = q[1] * k[1];
    out[0] = x324;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = k;
    let _ = q;
    let _ = qd;
    let _ = t;
    power_nc_into_part_0(out);
}
#[inline(never)]
fn power_nc_into_part_0(out: &mut [f64; 1]) {
    out[0] = 0.0;
}
/// Number of generalized coordinates.
pub const N_COORDS: usize = 6usize;
/// Number of constraint rows.
pub const N_CONSTRAINTS: usize = 1usize;
/// Row of each Φq nonzero.
pub static PHI_Q_ROWS: [u32; 3usize] = [0u32, 0u32, 0u32];
/// Column of each Φq nonzero.
pub static PHI_Q_COLS: [u32; 3usize] = [0u32, 1u32, 2u32];
/// Bodies in coordinate order.
pub static BODIES: [BodyInfo; 1usize] = [
    BodyInfo {
        name: "p1",
        coord_offset: 0usize,
        rotation: Rotation::Euler,
        mass: 1f64,
        inertia: [0.00004f64, 0.00004f64, 0.00004f64],
    },
];
/// Joints in row order, then drivers.
pub static JOINTS: [JointInfo; 1usize] = [
    JointInfo {
        name: "link",
        kind: JointKind::Distance,
        body1: None,
        body2: Some(0usize),
        row_start: 0usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
];
/// Name of each coordinate.
pub static COORD_NAMES: [&str; 6usize] = [
    "p1.x",
    "p1.y",
    "p1.z",
    "p1.theta",
    "p1.beta",
    "p1.gamma",
];
/// Name of each constraint row.
pub static ROW_NAMES: [&str; 1usize] = ["link.distance"];
/// Initial coordinates: the file's pose, assembled.
pub static Q0: [f64; 6usize] = [1f64, 0f64, 0f64, 0f64, 0f64, 0f64];
/// Initial velocities from the file (to be projected onto the constraints).
pub static QD0: [f64; 6usize] = [0f64, 0f64, 0f64, 0f64, 0f64, 0f64];
/// Constraint rows dependent on others at the initial pose (dropped by the solvers).
pub static REDUNDANT_ROWS: [u32; 0usize] = [];
/// Simulation end time suggested by the mechanism file (s).
pub const T_END: f64 = 2000f64;
/// The platform held by six legs of driven length, for forward kinematics (`None`:
/// not such a mechanism).
pub const PLATFORM: Option<PlatformInfo> = None;
/// Potential energy of gravity and springs.
pub fn potential(k: &[f64], q: &[f64]) -> f64 {
    let mut out = [0.0];
    potential_into(k, q, &mut out);
    out[0]
}
/// Power of the non-conservative loads.
pub fn power_nc(k: &[f64], q: &[f64], qd: &[f64], t: f64) -> f64 {
    let mut out = [0.0];
    power_nc_into(k, q, qd, t, &mut out);
    out[0]
}
/// Number of values `setup` computes from the run-time parameters.
pub const N_K: usize = 5;
/// `setup` at the file's parameter values: what the types without parameters read.
pub static K: [f64; 5] = [0.00004f64, 9.81f64, -9.81f64, 1f64, 0.00004f64];
/// The values the per-step functions read (`k`), from the run-time parameters `p`.
pub fn setup(p: &[f64], k: &mut [f64]) {
    let p: &[f64; 1] = p.try_into().expect("p must have 1 entries");
    let k: &mut [f64; 5] = k.try_into().expect("k must have 5 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 1], k: &mut [f64; 5]) {
    let x83 = p[0] * 0.4;
    let x85 = x83 * 0.01;
    let x86 = 0.01 * x85;
    let x89 = p[0] * 9.81;
    let x90 = -x89;
    let x153 = 2.0 * p[0];
    let x154 = 0.5 * x153;
    let x155 = 2.0 * x86;
    let x156 = 0.5 * x155;
    k[0] = x86;
    k[1] = x89;
    k[2] = x90;
    k[3] = x154;
    k[4] = x156;
}
/// The parameters the generated code takes at run time: the file's `[parameters]`
/// entries that reach only masses, inertias and springs' constants (the others are set on
/// the file).
pub static PARAMETERS: [&str; 1] = ["m"];
/// Their values in the file.
pub static PARAMETER_VALUES: [f64; 1] = [1f64];
static OTHER_PARAMETERS: [&str; 2] = ["ball", "l"];
static BODY_NAMES: [&str; 1] = ["p1"];
static FORCE_NAMES: [&str; 0] = [];
/// What a new parameter set is checked with.
pub static RUN_TIME: RunTimeParameters = RunTimeParameters {
    names: &PARAMETERS,
    others: &OTHER_PARAMETERS,
    bodies: &BODY_NAMES,
    mass_properties,
    forces: &FORCE_NAMES,
    force_constants,
};
/// Each body's mass and principal inertias at the run-time parameters `p`.
pub fn mass_properties(p: &[f64], out: &mut [f64]) {
    let p: &[f64; 1] = p.try_into().expect("p must have 1 entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    mass_properties_part_0(p, out);
}
#[inline(never)]
fn mass_properties_part_0(p: &[f64; 1], out: &mut [f64; 4]) {
    let x83 = p[0] * 0.4;
    let x85 = x83 * 0.01;
    let x86 = 0.01 * x85;
    out[0] = p[0];
    out[1] = x86;
    out[2] = x86;
    out[3] = x86;
}
/// Each force's stiffness and damping at the run-time parameters `p`.
pub fn force_constants(p: &[f64], out: &mut [f64]) {
    let p: &[f64; 1] = p.try_into().expect("p must have 1 entries");
    let _: &mut [f64; 0] = out.try_into().expect("out must have 0 entries");
    let _ = p;
}
/// One set of run-time parameter values and the values `setup` computed from it.
#[derive(Debug, Clone)]
pub struct Parameters {
    p: [f64; 1],
    k: [f64; N_K],
}
impl Parameters {
    /// The file's values.
    pub fn file_values() -> Self {
        Parameters {
            p: PARAMETER_VALUES,
            k: K,
        }
    }
    /// The file's values with `set` applied ([`Parameters::set`]).
    pub fn at(set: &[(&str, f64)]) -> Result<Self, ParameterError> {
        let mut p = Self::file_values();
        p.set(set)?;
        Ok(p)
    }
    /// Sets parameters by name. Checked first (known names, finite values, positive
    /// masses, inertias of a rigid body): a refused set changes nothing. Allocates
    /// nothing unless it is refused.
    pub fn set(&mut self, set: &[(&str, f64)]) -> Result<(), ParameterError> {
        let mut p = self.p;
        RUN_TIME.assign(&mut p, set)?;
        let (mut props, mut constants) = ([0.0; 4], [0.0; 0]);
        RUN_TIME.check(&p, set, &mut props, &mut constants)?;
        self.p = p;
        setup(&self.p, &mut self.k);
        Ok(())
    }
    /// The values, in the order of `PARAMETERS`.
    pub fn values(&self) -> &[f64] {
        &self.p
    }
}
fn at_parameters(
    set: &[(&str, f64)],
) -> Result<symbody_runtime::registry::Built, ParameterError> {
    let p = Parameters::at(set)?;
    Ok(
        vec![
            (Formulation::Exact, Box::new(ExactAt(p.clone())) as Box < dyn Mechanism +
            Sync >)
        ],
    )
}
fn at_parameters_reduced(
    set: &[(&str, f64)],
) -> Result<symbody_runtime::registry::Built, ParameterError> {
    let p = Parameters::at(set)?;
    Ok(
        vec![
            (Formulation::Exact, Box::new(reduced::ExactAt::new(& p)) as Box < dyn
            Mechanism + Sync >)
        ],
    )
}
/// This mechanism at other values of its run-time parameters, for the registries.
pub static RUN_TIME_ENTRY: symbody_runtime::registry::RunTime = symbody_runtime::registry::RunTime {
    parameters: &RUN_TIME,
    build: at_parameters,
    build_reduced: Some(at_parameters_reduced),
};
/// The `exact` formulation: mass matrix and forces derived from the exact kinetic energy.
pub mod exact {
    use super::*;
    /// Row of each mass-matrix nonzero (both triangles).
    pub static MASS_ROWS: [u32; 10usize] = [
        0u32, 1u32, 2u32, 3u32, 3u32, 4u32, 4u32, 5u32, 5u32, 5u32,
    ];
    /// Column of each mass-matrix nonzero.
    pub static MASS_COLS: [u32; 10usize] = [
        0u32, 1u32, 2u32, 3u32, 5u32, 4u32, 5u32, 3u32, 4u32, 5u32,
    ];
    /// Row and column of each ∂Q/∂q nonzero.
    pub static FORCE_Q_ROWS: [u32; 0usize] = [];
    pub static FORCE_Q_COLS: [u32; 0usize] = [];
    /// Row and column of each ∂Q/∂q̇ nonzero.
    pub static FORCE_QD_ROWS: [u32; 0usize] = [];
    pub static FORCE_QD_COLS: [u32; 0usize] = [];
    /// Sizes, patterns and names for this formulation.
    pub static INFO: MechanismInfo = MechanismInfo {
        name: "simple_pendulum",
        n_coords: N_COORDS,
        n_constraints: N_CONSTRAINTS,
        formulation: Formulation::Exact,
        gravity: [0f64, -9.81f64, 0f64],
        phi_q_rows: &PHI_Q_ROWS,
        phi_q_cols: &PHI_Q_COLS,
        mass_rows: &MASS_ROWS,
        mass_cols: &MASS_COLS,
        mass_is_constant: false,
        force_q_rows: &FORCE_Q_ROWS,
        force_q_cols: &FORCE_Q_COLS,
        force_qd_rows: &FORCE_QD_ROWS,
        force_qd_cols: &FORCE_QD_COLS,
        bodies: &BODIES,
        joints: &JOINTS,
        coord_names: &COORD_NAMES,
        row_names: &ROW_NAMES,
        q0: &Q0,
        qd0: &QD0,
        redundant_rows: &REDUNDANT_ROWS,
        platform: PLATFORM,
    };
    /// Nonzeros of ∂Q/∂q and ∂Q/∂q̇ in the order of `FORCE_Q_*` and `FORCE_QD_*`.
    pub fn force_jacobian(
        k: &[f64],
        q: &[f64],
        qd: &[f64],
        t: f64,
        dq: &mut [f64],
        dqd: &mut [f64],
    ) {
        let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
        let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
        let _: &mut [f64; 0] = dq.try_into().expect("dq must have 0 entries");
        let _: &mut [f64; 0] = dqd.try_into().expect("dqd must have 0 entries");
        let _ = k;
        let _ = q;
        let _ = qd;
        let _ = t;
    }
    /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
    pub fn mass(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
        let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 10] = out.try_into().expect("out must have 10 entries");
        mass_part_0(k, q, out);
    }
    #[inline(never)]
    fn mass_part_0(k: &[f64; 5], q: &[f64; 6], out: &mut [f64; 10]) {
        let x6 = q[3].sin();
        let x7 = q[3].cos();
        let x8 = q[4].sin();
        let x9 = q[4].cos();
        let x16 = x6 * x9;
        let x17 = x7 * x9;
        let x157 = x8 * 2.0;
        let x163 = x7 * 2.0;
        let x164 = x6 * 2.0;
        let x166 = x7 * x163;
        let x168 = x6 * x164;
        let x174 = x16 * 2.0;
        let x175 = x17 * 2.0;
        let x176 = x7 * x174;
        let x178 = x6 * x175;
        let x183 = x16 * x163;
        let x185 = x17 * x164;
        let x191 = x8 * x157;
        let x195 = x16 * x174;
        let x197 = x17 * x175;
        let x327 = x157 * k[0];
        let x328 = 0.5 * x327;
        let x329 = -x328;
        let x330 = x166 * k[0];
        let x331 = x168 * k[0];
        let x332 = x330 + x331;
        let x333 = 0.5 * x332;
        let x334 = x176 * k[0];
        let x335 = x178 * k[0];
        let x337 = x334 - x335;
        let x338 = 0.5 * x337;
        let x339 = x183 * k[0];
        let x340 = x185 * k[0];
        let x342 = x339 - x340;
        let x343 = 0.5 * x342;
        let x344 = x191 * k[0];
        let x345 = x195 * k[0];
        let x346 = x197 * k[0];
        let x347 = x344 + x345;
        let x348 = x346 + x347;
        let x349 = 0.5 * x348;
        out[0] = k[3];
        out[1] = k[3];
        out[2] = k[3];
        out[3] = k[4];
        out[4] = x329;
        out[5] = x333;
        out[6] = x338;
        out[7] = x329;
        out[8] = x343;
        out[9] = x349;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
        let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 6] = out.try_into().expect("out must have 6 entries");
        let _ = t;
        force_part_0(k, q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(k: &[f64; 5], q: &[f64; 6], qd: &[f64; 6], out: &mut [f64; 6]) {
        let x6 = q[3].sin();
        let x7 = q[3].cos();
        let x8 = q[4].sin();
        let x9 = q[4].cos();
        let x16 = x6 * x9;
        let x17 = x7 * x9;
        let x93 = x8 * qd[5];
        let x95 = x9 * qd[5];
        let x96 = x7 * qd[4];
        let x97 = x6 * x95;
        let x98 = x96 + x97;
        let x99 = x6 * qd[4];
        let x100 = x7 * x95;
        let x102 = x100 - x99;
        let x103 = qd[3] - x93;
        let x123 = 2.0 * x103;
        let x124 = 2.0 * x98;
        let x125 = 2.0 * x102;
        let x202 = x7 * qd[3];
        let x203 = x6 * qd[3];
        let x205 = x9 * qd[4];
        let x206 = x8 * qd[4];
        let x208 = x9 * x202;
        let x209 = x6 * x206;
        let x211 = x208 - x209;
        let x212 = x9 * x203;
        let x214 = x7 * x206;
        let x216 = x212 + x214;
        let x218 = qd[5] * x205;
        let x220 = qd[5] * x206;
        let x222 = qd[4] * x203;
        let x224 = x95 * x202;
        let x225 = x6 * x220;
        let x227 = x224 - x225;
        let x228 = x227 - x222;
        let x229 = qd[4] * x202;
        let x230 = x95 * x203;
        let x232 = x7 * x220;
        let x234 = x230 + x232;
        let x237 = x229 + x234;
        let x239 = 2.0 * x218;
        let x241 = 2.0 * x228;
        let x242 = 2.0 * x237;
        let x248 = x124 * x203;
        let x250 = x7 * x241;
        let x251 = x250 - x248;
        let x253 = x125 * x202;
        let x254 = x6 * x242;
        let x256 = x253 - x254;
        let x261 = x123 * x205;
        let x262 = x8 * x239;
        let x264 = x261 - x262;
        let x267 = x124 * x211;
        let x268 = x16 * x241;
        let x269 = x267 + x268;
        let x271 = x125 * x216;
        let x273 = x17 * x242;
        let x275 = x271 + x273;
        let x285 = x102 * x124;
        let x287 = x98 * x125;
        let x295 = x6 * x93;
        let x297 = x7 * x93;
        let x299 = x95 * x123;
        let x303 = x124 * x295;
        let x307 = x125 * x297;
        let x350 = x239 * k[0];
        let x351 = 0.5 * x350;
        let x352 = x251 * k[0];
        let x353 = x256 * k[0];
        let x355 = x352 - x353;
        let x356 = 0.5 * x355;
        let x357 = x264 * k[0];
        let x359 = x269 * k[0];
        let x360 = x275 * k[0];
        let x362 = x359 - x357;
        let x363 = x362 - x360;
        let x364 = 0.5 * x363;
        let x365 = x285 * k[0];
        let x366 = x287 * k[0];
        let x368 = x365 - x366;
        let x369 = 0.5 * x368;
        let x370 = x351 + x369;
        let x371 = x299 * k[0];
        let x372 = x303 * k[0];
        let x373 = x307 * k[0];
        let x374 = x371 + x372;
        let x375 = x373 + x374;
        let x376 = 0.5 * x375;
        let x377 = x356 + x376;
        let x378 = -x377;
        let x379 = -x364;
        out[0] = 0.0;
        out[1] = k[2];
        out[2] = 0.0;
        out[3] = x370;
        out[4] = x378;
        out[5] = x379;
    }
    /// Φ, Φq, M and Q at one state in one pass: what one Newton iteration needs.
    pub fn eval_newton(
        k: &[f64],
        q: &[f64],
        qd: &[f64],
        t: f64,
        phi: &mut [f64],
        phi_q: &mut [f64],
        mass: &mut [f64],
        force: &mut [f64],
    ) {
        let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
        let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 1] = phi.try_into().expect("phi must have 1 entries");
        let phi_q: &mut [f64; 3] = phi_q.try_into().expect("phi_q must have 3 entries");
        let mass: &mut [f64; 10] = mass.try_into().expect("mass must have 10 entries");
        let force: &mut [f64; 6] = force.try_into().expect("force must have 6 entries");
        let _ = t;
        eval_newton_part_0(k, q, qd, phi, phi_q, mass, force);
    }
    #[inline(never)]
    fn eval_newton_part_0(
        k: &[f64; 5],
        q: &[f64; 6],
        qd: &[f64; 6],
        phi: &mut [f64; 1],
        phi_q: &mut [f64; 3],
        mass: &mut [f64; 10],
        force: &mut [f64; 6],
    ) {
        let x6 = q[3].sin();
        let x7 = q[3].cos();
        let x8 = q[4].sin();
        let x9 = q[4].cos();
        let x16 = x6 * x9;
        let x17 = x7 * x9;
        let x35 = q[0] * q[0];
        let x36 = q[1] * q[1];
        let x37 = q[2] * q[2];
        let x38 = x35 + x36;
        let x39 = x37 + x38;
        let x40 = x39.sqrt();
        let x42 = x40 - 1.0;
        let x44 = q[0] * 2.0;
        let x45 = q[1] * 2.0;
        let x46 = q[2] * 2.0;
        let x47 = x40 * 2.0;
        let x48 = 1.0 / x47;
        let x49 = x44 * x48;
        let x50 = x45 * x48;
        let x51 = x46 * x48;
        let x93 = x8 * qd[5];
        let x95 = x9 * qd[5];
        let x96 = x7 * qd[4];
        let x97 = x6 * x95;
        let x98 = x96 + x97;
        let x99 = x6 * qd[4];
        let x100 = x7 * x95;
        let x102 = x100 - x99;
        let x103 = qd[3] - x93;
        let x123 = 2.0 * x103;
        let x124 = 2.0 * x98;
        let x125 = 2.0 * x102;
        let x157 = x8 * 2.0;
        let x163 = x7 * 2.0;
        let x164 = x6 * 2.0;
        let x166 = x7 * x163;
        let x168 = x6 * x164;
        let x174 = x16 * 2.0;
        let x175 = x17 * 2.0;
        let x176 = x7 * x174;
        let x178 = x6 * x175;
        let x183 = x16 * x163;
        let x185 = x17 * x164;
        let x191 = x8 * x157;
        let x195 = x16 * x174;
        let x197 = x17 * x175;
        let x202 = x7 * qd[3];
        let x203 = x6 * qd[3];
        let x205 = x9 * qd[4];
        let x206 = x8 * qd[4];
        let x208 = x9 * x202;
        let x209 = x6 * x206;
        let x211 = x208 - x209;
        let x212 = x9 * x203;
        let x214 = x7 * x206;
        let x216 = x212 + x214;
        let x218 = qd[5] * x205;
        let x220 = qd[5] * x206;
        let x222 = qd[4] * x203;
        let x224 = x95 * x202;
        let x225 = x6 * x220;
        let x227 = x224 - x225;
        let x228 = x227 - x222;
        let x229 = qd[4] * x202;
        let x230 = x95 * x203;
        let x232 = x7 * x220;
        let x234 = x230 + x232;
        let x237 = x229 + x234;
        let x239 = 2.0 * x218;
        let x241 = 2.0 * x228;
        let x242 = 2.0 * x237;
        let x248 = x124 * x203;
        let x250 = x7 * x241;
        let x251 = x250 - x248;
        let x253 = x125 * x202;
        let x254 = x6 * x242;
        let x256 = x253 - x254;
        let x261 = x123 * x205;
        let x262 = x8 * x239;
        let x264 = x261 - x262;
        let x267 = x124 * x211;
        let x268 = x16 * x241;
        let x269 = x267 + x268;
        let x271 = x125 * x216;
        let x273 = x17 * x242;
        let x275 = x271 + x273;
        let x285 = x102 * x124;
        let x287 = x98 * x125;
        let x295 = x6 * x93;
        let x297 = x7 * x93;
        let x299 = x95 * x123;
        let x303 = x124 * x295;
        let x307 = x125 * x297;
        let x327 = x157 * k[0];
        let x328 = 0.5 * x327;
        let x329 = -x328;
        let x330 = x166 * k[0];
        let x331 = x168 * k[0];
        let x332 = x330 + x331;
        let x333 = 0.5 * x332;
        let x334 = x176 * k[0];
        let x335 = x178 * k[0];
        let x337 = x334 - x335;
        let x338 = 0.5 * x337;
        let x339 = x183 * k[0];
        let x340 = x185 * k[0];
        let x342 = x339 - x340;
        let x343 = 0.5 * x342;
        let x344 = x191 * k[0];
        let x345 = x195 * k[0];
        let x346 = x197 * k[0];
        let x347 = x344 + x345;
        let x348 = x346 + x347;
        let x349 = 0.5 * x348;
        let x350 = x239 * k[0];
        let x351 = 0.5 * x350;
        let x352 = x251 * k[0];
        let x353 = x256 * k[0];
        let x355 = x352 - x353;
        let x356 = 0.5 * x355;
        let x357 = x264 * k[0];
        let x359 = x269 * k[0];
        let x360 = x275 * k[0];
        let x362 = x359 - x357;
        let x363 = x362 - x360;
        let x364 = 0.5 * x363;
        let x365 = x285 * k[0];
        let x366 = x287 * k[0];
        let x368 = x365 - x366;
        let x369 = 0.5 * x368;
        let x370 = x351 + x369;
        let x371 = x299 * k[0];
        let x372 = x303 * k[0];
        let x373 = x307 * k[0];
        let x374 = x371 + x372;
        let x375 = x373 + x374;
        let x376 = 0.5 * x375;
        let x377 = x356 + x376;
        let x378 = -x377;
        let x379 = -x364;
        phi[0] = x42;
        phi_q[0] = x49;
        phi_q[1] = x50;
        phi_q[2] = x51;
        mass[0] = k[3];
        mass[1] = k[3];
        mass[2] = k[3];
        mass[3] = k[4];
        mass[4] = x329;
        mass[5] = x333;
        mass[6] = x338;
        mass[7] = x329;
        mass[8] = x343;
        mass[9] = x349;
        force[0] = 0.0;
        force[1] = k[2];
        force[2] = 0.0;
        force[3] = x370;
        force[4] = x378;
        force[5] = x379;
    }
}
/// The system after substituting rows `a·qᵢ + b·qⱼ + g(t) = 0` away (docs/design.md,
/// decision 24): fewer coordinates and rows, the same motion and multipliers once
/// mapped back with `REDUCTION`.
pub mod reduced {
    use super::*;
    /// Number of reduced coordinates.
    pub const N_COORDS: usize = 3usize;
    /// Number of reduced rows.
    pub const N_CONSTRAINTS: usize = 1usize;
    /// Row of each Φq nonzero.
    pub static PHI_Q_ROWS: [u32; 2usize] = [0u32, 0u32];
    /// Column of each Φq nonzero.
    pub static PHI_Q_COLS: [u32; 2usize] = [0u32, 1u32];
    /// Name of each reduced coordinate (its full model's name).
    pub static COORD_NAMES: [&str; 3usize] = ["p1.x", "p1.y", "p1.gamma"];
    /// Name of each reduced row (its full model's name).
    pub static ROW_NAMES: [&str; 1usize] = ["link.distance"];
    /// Initial coordinates, from the full model's assembled ones.
    pub static Q0: [f64; 3usize] = [1f64, 0f64, 0f64];
    /// Initial velocities from the file.
    pub static QD0: [f64; 3usize] = [0f64, 0f64, 0f64];
    /// Rows dependent on others at the initial pose.
    pub static REDUNDANT_ROWS: [u32; 0usize] = [];
    /// Full index of each reduced coordinate.
    pub static COORDS: [u32; 3usize] = [0u32, 1u32, 5u32];
    /// Full index of each reduced row.
    pub static ROWS: [u32; 1usize] = [0u32];
    /// The eliminated rows.
    pub static SUBSTITUTIONS: [Substitution; 3usize] = [
        Substitution {
            row: None,
            coord: 2u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: None,
            coord: 3u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: None,
            coord: 4u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
    ];
    /// The way back to the full model.
    pub static REDUCTION: Reduction = Reduction {
        n_full: 6usize,
        m_full: 1usize,
        coords: &COORDS,
        rows: &ROWS,
        substitutions: &SUBSTITUTIONS,
        offsets: offsets_into,
    };
    /// `c, ċ, c̈` of each substitution at time `t`, three per substitution.
    pub fn offsets_into(t: f64, out: &mut [f64]) {
        let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
        let _ = t;
        offsets_into_part_0(out);
    }
    #[inline(never)]
    fn offsets_into_part_0(out: &mut [f64; 9]) {
        out[0] = 0.0;
        out[1] = 0.0;
        out[2] = 0.0;
        out[3] = 0.0;
        out[4] = 0.0;
        out[5] = 0.0;
        out[6] = 0.0;
        out[7] = 0.0;
        out[8] = 0.0;
    }
    /// Number of values `setup` computes from the run-time parameters.
    pub const N_K: usize = 4;
    /// `setup` at the file's parameter values: what the types without parameters read.
    pub static K: [f64; 4] = [9.81f64, -9.81f64, 1f64, 0.00004f64];
    /// The values the per-step functions read (`k`), from the run-time parameters `p`.
    pub fn setup(p: &[f64], k: &mut [f64]) {
        let p: &[f64; 1] = p.try_into().expect("p must have 1 entries");
        let k: &mut [f64; 4] = k.try_into().expect("k must have 4 entries");
        setup_part_0(p, k);
    }
    #[inline(never)]
    fn setup_part_0(p: &[f64; 1], k: &mut [f64; 4]) {
        let x83 = p[0] * 0.4;
        let x85 = x83 * 0.01;
        let x86 = 0.01 * x85;
        let x89 = p[0] * 9.81;
        let x90 = -x89;
        let x153 = 2.0 * p[0];
        let x154 = 0.5 * x153;
        let x155 = 2.0 * x86;
        let x156 = 0.5 * x155;
        k[0] = x89;
        k[1] = x90;
        k[2] = x154;
        k[3] = x156;
    }
    /// Constraint residual Φ(q, t).
    pub fn phi(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        let _ = t;
        phi_part_0(q, out);
    }
    #[inline(never)]
    fn phi_part_0(q: &[f64; 3], out: &mut [f64; 1]) {
        let x35 = q[0] * q[0];
        let x36 = q[1] * q[1];
        let x38 = x35 + x36;
        let x321 = x38.sqrt();
        let x322 = x321 - 1.0;
        out[0] = x322;
    }
    /// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
    pub fn phi_q(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 2] = out.try_into().expect("out must have 2 entries");
        let _ = t;
        phi_q_part_0(q, out);
    }
    #[inline(never)]
    fn phi_q_part_0(q: &[f64; 3], out: &mut [f64; 2]) {
        let x35 = q[0] * q[0];
        let x36 = q[1] * q[1];
        let x38 = x35 + x36;
        let x44 = q[0] * 2.0;
        let x45 = q[1] * 2.0;
        let x321 = x38.sqrt();
        let x323 = 2.0 * x321;
        let x324 = 1.0 / x323;
        let x325 = x44 * x324;
        let x326 = x45 * x324;
        out[0] = x325;
        out[1] = x326;
    }
    /// Partial time derivative Φt(q, t).
    pub fn phi_t(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        let _ = q;
        let _ = t;
        phi_t_part_0(out);
    }
    #[inline(never)]
    fn phi_t_part_0(out: &mut [f64; 1]) {
        out[0] = 0.0;
    }
    /// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
    pub fn gamma(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        let _ = t;
        gamma_part_0(q, qd, out);
    }
    #[inline(never)]
    fn gamma_part_0(q: &[f64; 3], qd: &[f64; 3], out: &mut [f64; 1]) {
        let x35 = q[0] * q[0];
        let x36 = q[1] * q[1];
        let x38 = x35 + x36;
        let x44 = q[0] * 2.0;
        let x45 = q[1] * 2.0;
        let x58 = x44 * qd[0];
        let x59 = x45 * qd[1];
        let x61 = x58 + x59;
        let x64 = 2.0 * qd[0];
        let x65 = 2.0 * qd[1];
        let x71 = qd[0] * x64;
        let x72 = qd[1] * x65;
        let x74 = x71 + x72;
        let x321 = x38.sqrt();
        let x323 = 2.0 * x321;
        let x324 = 1.0 / x323;
        let x327 = x61 * x324;
        let x328 = 2.0 * x327;
        let x329 = x324 * x324;
        let x330 = x328 * x329;
        let x332 = x74 * x324;
        let x333 = x61 * x330;
        let x335 = x332 - x333;
        let x336 = -x335;
        out[0] = x336;
    }
    /// Φ, Φq, Φt and γ at one state in one pass, sharing every subexpression.
    pub fn eval_kinematics(
        q: &[f64],
        qd: &[f64],
        t: f64,
        phi: &mut [f64],
        phi_q: &mut [f64],
        phi_t: &mut [f64],
        gamma: &mut [f64],
    ) {
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 1] = phi.try_into().expect("phi must have 1 entries");
        let phi_q: &mut [f64; 2] = phi_q.try_into().expect("phi_q must have 2 entries");
        let phi_t: &mut [f64; 1] = phi_t.try_into().expect("phi_t must have 1 entries");
        let gamma: &mut [f64; 1] = gamma.try_into().expect("gamma must have 1 entries");
        let _ = t;
        eval_kinematics_part_0(q, qd, phi, phi_q, phi_t, gamma);
    }
    #[inline(never)]
    fn eval_kinematics_part_0(
        q: &[f64; 3],
        qd: &[f64; 3],
        phi: &mut [f64; 1],
        phi_q: &mut [f64; 2],
        phi_t: &mut [f64; 1],
        gamma: &mut [f64; 1],
    ) {
        let x35 = q[0] * q[0];
        let x36 = q[1] * q[1];
        let x38 = x35 + x36;
        let x44 = q[0] * 2.0;
        let x45 = q[1] * 2.0;
        let x58 = x44 * qd[0];
        let x59 = x45 * qd[1];
        let x61 = x58 + x59;
        let x64 = 2.0 * qd[0];
        let x65 = 2.0 * qd[1];
        let x71 = qd[0] * x64;
        let x72 = qd[1] * x65;
        let x74 = x71 + x72;
        let x321 = x38.sqrt();
        let x322 = x321 - 1.0;
        let x323 = 2.0 * x321;
        let x324 = 1.0 / x323;
        let x325 = x44 * x324;
        let x326 = x45 * x324;
        let x327 = x61 * x324;
        let x328 = 2.0 * x327;
        let x329 = x324 * x324;
        let x330 = x328 * x329;
        let x332 = x74 * x324;
        let x333 = x61 * x330;
        let x335 = x332 - x333;
        let x336 = -x335;
        phi[0] = x322;
        phi_q[0] = x325;
        phi_q[1] = x326;
        phi_t[0] = 0.0;
        gamma[0] = x336;
    }
    /// Potential energy of gravity and springs, written to `out[0]`.
    pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 4] = k.try_into().expect("k must have 4 entries");
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        potential_into_part_0(k, q, out);
    }
    #[inline(never)]
    fn potential_into_part_0(k: &[f64; 4], q: &[f64; 3], out: &mut [f64; 1]) {
        let x339 = q[1] * k[0];
        out[0] = x339;
    }
    /// Power of the non-conservative loads, written to `out[0]`.
    pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 4] = k.try_into().expect("k must have 4 entries");
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        let _ = k;
        let _ = q;
        let _ = qd;
        let _ = t;
        power_nc_into_part_0(out);
    }
    #[inline(never)]
    fn power_nc_into_part_0(out: &mut [f64; 1]) {
        out[0] = 0.0;
    }
    /// Potential energy of gravity and springs.
    pub fn potential(k: &[f64], q: &[f64]) -> f64 {
        let mut out = [0.0];
        potential_into(k, q, &mut out);
        out[0]
    }
    /// Power of the non-conservative loads.
    pub fn power_nc(k: &[f64], q: &[f64], qd: &[f64], t: f64) -> f64 {
        let mut out = [0.0];
        power_nc_into(k, q, qd, t, &mut out);
        out[0]
    }
    /// The reduced system's mass matrix and forces in this formulation.
    pub mod exact {
        use super::*;
        /// Row of each mass-matrix nonzero (both triangles).
        pub static MASS_ROWS: [u32; 3usize] = [0u32, 1u32, 2u32];
        /// Column of each mass-matrix nonzero.
        pub static MASS_COLS: [u32; 3usize] = [0u32, 1u32, 2u32];
        /// Row and column of each ∂Q/∂q nonzero.
        pub static FORCE_Q_ROWS: [u32; 0usize] = [];
        pub static FORCE_Q_COLS: [u32; 0usize] = [];
        /// Row and column of each ∂Q/∂q̇ nonzero.
        pub static FORCE_QD_ROWS: [u32; 0usize] = [];
        pub static FORCE_QD_COLS: [u32; 0usize] = [];
        /// Sizes, patterns and names for this formulation.
        pub static INFO: MechanismInfo = MechanismInfo {
            name: "simple_pendulum_reduced",
            n_coords: N_COORDS,
            n_constraints: N_CONSTRAINTS,
            formulation: Formulation::Exact,
            gravity: [0f64, -9.81f64, 0f64],
            phi_q_rows: &PHI_Q_ROWS,
            phi_q_cols: &PHI_Q_COLS,
            mass_rows: &MASS_ROWS,
            mass_cols: &MASS_COLS,
            mass_is_constant: false,
            force_q_rows: &FORCE_Q_ROWS,
            force_q_cols: &FORCE_Q_COLS,
            force_qd_rows: &FORCE_QD_ROWS,
            force_qd_cols: &FORCE_QD_COLS,
            bodies: &[],
            joints: &[],
            coord_names: &COORD_NAMES,
            row_names: &ROW_NAMES,
            q0: &Q0,
            qd0: &QD0,
            redundant_rows: &REDUNDANT_ROWS,
            platform: None,
        };
        /// Nonzeros of ∂Q/∂q and ∂Q/∂q̇ in the order of `FORCE_Q_*` and `FORCE_QD_*`.
        pub fn force_jacobian(
            k: &[f64],
            q: &[f64],
            qd: &[f64],
            t: f64,
            dq: &mut [f64],
            dqd: &mut [f64],
        ) {
            let k: &[f64; 4] = k.try_into().expect("k must have 4 entries");
            let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
            let _: &mut [f64; 0] = dq.try_into().expect("dq must have 0 entries");
            let _: &mut [f64; 0] = dqd.try_into().expect("dqd must have 0 entries");
            let _ = k;
            let _ = q;
            let _ = qd;
            let _ = t;
        }
        /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
        pub fn mass(k: &[f64], q: &[f64], out: &mut [f64]) {
            let k: &[f64; 4] = k.try_into().expect("k must have 4 entries");
            let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
            let out: &mut [f64; 3] = out.try_into().expect("out must have 3 entries");
            let _ = q;
            mass_part_0(k, out);
        }
        #[inline(never)]
        fn mass_part_0(k: &[f64; 4], out: &mut [f64; 3]) {
            out[0] = k[2];
            out[1] = k[2];
            out[2] = k[3];
        }
        /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
        pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            let k: &[f64; 4] = k.try_into().expect("k must have 4 entries");
            let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
            let out: &mut [f64; 3] = out.try_into().expect("out must have 3 entries");
            let _ = q;
            let _ = qd;
            let _ = t;
            force_part_0(k, out);
        }
        #[inline(never)]
        fn force_part_0(k: &[f64; 4], out: &mut [f64; 3]) {
            out[0] = 0.0;
            out[1] = k[1];
            out[2] = 0.0;
        }
        /// Φ, Φq, M and Q at one state in one pass: what one Newton iteration needs.
        pub fn eval_newton(
            k: &[f64],
            q: &[f64],
            qd: &[f64],
            t: f64,
            phi: &mut [f64],
            phi_q: &mut [f64],
            mass: &mut [f64],
            force: &mut [f64],
        ) {
            let k: &[f64; 4] = k.try_into().expect("k must have 4 entries");
            let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
            let phi: &mut [f64; 1] = phi.try_into().expect("phi must have 1 entries");
            let phi_q: &mut [f64; 2] = phi_q
                .try_into()
                .expect("phi_q must have 2 entries");
            let mass: &mut [f64; 3] = mass.try_into().expect("mass must have 3 entries");
            let force: &mut [f64; 3] = force
                .try_into()
                .expect("force must have 3 entries");
            let _ = qd;
            let _ = t;
            eval_newton_part_0(k, q, phi, phi_q, mass, force);
        }
        #[inline(never)]
        fn eval_newton_part_0(
            k: &[f64; 4],
            q: &[f64; 3],
            phi: &mut [f64; 1],
            phi_q: &mut [f64; 2],
            mass: &mut [f64; 3],
            force: &mut [f64; 3],
        ) {
            let x35 = q[0] * q[0];
            let x36 = q[1] * q[1];
            let x38 = x35 + x36;
            let x44 = q[0] * 2.0;
            let x45 = q[1] * 2.0;
            let x321 = x38.sqrt();
            let x322 = x321 - 1.0;
            let x323 = 2.0 * x321;
            let x324 = 1.0 / x323;
            let x325 = x44 * x324;
            let x326 = x45 * x324;
            phi[0] = x322;
            phi_q[0] = x325;
            phi_q[1] = x326;
            mass[0] = k[2];
            mass[1] = k[2];
            mass[2] = k[3];
            force[0] = 0.0;
            force[1] = k[1];
            force[2] = 0.0;
        }
    }
    /// `simple_pendulum` reduced by substitution, with the `exact` formulation.
    #[derive(Debug, Clone, Copy, Default)]
    pub struct Exact;
    impl Mechanism for Exact {
        fn info(&self) -> &'static MechanismInfo {
            &exact::INFO
        }
        fn phi(&self, q: &[f64], t: f64, out: &mut [f64]) {
            phi(q, t, out)
        }
        fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) {
            phi_q(q, t, out)
        }
        fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) {
            phi_t(q, t, out)
        }
        fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            gamma(q, qd, t, out)
        }
        fn mass(&self, q: &[f64], out: &mut [f64]) {
            exact::mass(&K, q, out)
        }
        fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            exact::force(&K, q, qd, t, out)
        }
        fn force_jacobian(
            &self,
            q: &[f64],
            qd: &[f64],
            t: f64,
            dq: &mut [f64],
            dqd: &mut [f64],
        ) {
            exact::force_jacobian(&K, q, qd, t, dq, dqd)
        }
        fn potential(&self, q: &[f64]) -> f64 {
            potential(&K, q)
        }
        fn power_nc(&self, q: &[f64], qd: &[f64], t: f64) -> f64 {
            power_nc(&K, q, qd, t)
        }
        fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
            exact::eval_newton(&K, q, qd, t, out.phi, out.phi_q, out.mass, out.force)
        }
        fn eval_kinematics(
            &self,
            q: &[f64],
            qd: &[f64],
            t: f64,
            out: KinematicOutputs<'_>,
        ) {
            eval_kinematics(q, qd, t, out.phi, out.phi_q, out.phi_t, out.gamma)
        }
    }
    /// The reduced model at run-time parameter values.
    #[derive(Debug, Clone)]
    pub struct ExactAt {
        k: [f64; N_K],
    }
    impl ExactAt {
        /// At the parameter values of `p` (checked when they were set).
        pub fn new(p: &Parameters) -> Self {
            let mut k = [0.0; N_K];
            setup(p.values(), &mut k);
            ExactAt { k }
        }
    }
    impl Mechanism for ExactAt {
        fn info(&self) -> &'static MechanismInfo {
            &exact::INFO
        }
        fn phi(&self, q: &[f64], t: f64, out: &mut [f64]) {
            phi(q, t, out)
        }
        fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) {
            phi_q(q, t, out)
        }
        fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) {
            phi_t(q, t, out)
        }
        fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            gamma(q, qd, t, out)
        }
        fn mass(&self, q: &[f64], out: &mut [f64]) {
            exact::mass(&self.k, q, out)
        }
        fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            exact::force(&self.k, q, qd, t, out)
        }
        fn force_jacobian(
            &self,
            q: &[f64],
            qd: &[f64],
            t: f64,
            dq: &mut [f64],
            dqd: &mut [f64],
        ) {
            exact::force_jacobian(&self.k, q, qd, t, dq, dqd)
        }
        fn potential(&self, q: &[f64]) -> f64 {
            potential(&self.k, q)
        }
        fn power_nc(&self, q: &[f64], qd: &[f64], t: f64) -> f64 {
            power_nc(&self.k, q, qd, t)
        }
        fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
            exact::eval_newton(
                &self.k,
                q,
                qd,
                t,
                out.phi,
                out.phi_q,
                out.mass,
                out.force,
            )
        }
        fn eval_kinematics(
            &self,
            q: &[f64],
            qd: &[f64],
            t: f64,
            out: KinematicOutputs<'_>,
        ) {
            eval_kinematics(q, qd, t, out.phi, out.phi_q, out.phi_t, out.gamma)
        }
    }
}
/// `simple_pendulum` with the `exact` formulation.
#[derive(Debug, Clone, Copy, Default)]
pub struct Exact;
impl Mechanism for Exact {
    fn info(&self) -> &'static MechanismInfo {
        &exact::INFO
    }
    fn phi(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi(q, t, out)
    }
    fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi_q(q, t, out)
    }
    fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi_t(q, t, out)
    }
    fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        gamma(q, qd, t, out)
    }
    fn mass(&self, q: &[f64], out: &mut [f64]) {
        exact::mass(&K, q, out)
    }
    fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        exact::force(&K, q, qd, t, out)
    }
    fn force_jacobian(
        &self,
        q: &[f64],
        qd: &[f64],
        t: f64,
        dq: &mut [f64],
        dqd: &mut [f64],
    ) {
        exact::force_jacobian(&K, q, qd, t, dq, dqd)
    }
    fn potential(&self, q: &[f64]) -> f64 {
        potential(&K, q)
    }
    fn power_nc(&self, q: &[f64], qd: &[f64], t: f64) -> f64 {
        power_nc(&K, q, qd, t)
    }
    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        exact::eval_newton(&K, q, qd, t, out.phi, out.phi_q, out.mass, out.force)
    }
    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
        eval_kinematics(q, qd, t, out.phi, out.phi_q, out.phi_t, out.gamma)
    }
}
impl Exact {
    /// This formulation with some run-time parameters (`PARAMETERS`) set, the others
    /// at the file's values; a name or value that is refused changes nothing.
    pub fn with_parameters(set: &[(&str, f64)]) -> Result<ExactAt, ParameterError> {
        Parameters::at(set).map(ExactAt)
    }
}
/// `simple_pendulum` with the `exact` formulation. At run-time parameter values (`Exact::with_parameters`).
#[derive(Debug, Clone)]
pub struct ExactAt(pub Parameters);
impl Mechanism for ExactAt {
    fn info(&self) -> &'static MechanismInfo {
        &exact::INFO
    }
    fn phi(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi(q, t, out)
    }
    fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi_q(q, t, out)
    }
    fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi_t(q, t, out)
    }
    fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        gamma(q, qd, t, out)
    }
    fn mass(&self, q: &[f64], out: &mut [f64]) {
        exact::mass(&self.0.k, q, out)
    }
    fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        exact::force(&self.0.k, q, qd, t, out)
    }
    fn force_jacobian(
        &self,
        q: &[f64],
        qd: &[f64],
        t: f64,
        dq: &mut [f64],
        dqd: &mut [f64],
    ) {
        exact::force_jacobian(&self.0.k, q, qd, t, dq, dqd)
    }
    fn potential(&self, q: &[f64]) -> f64 {
        potential(&self.0.k, q)
    }
    fn power_nc(&self, q: &[f64], qd: &[f64], t: f64) -> f64 {
        power_nc(&self.0.k, q, qd, t)
    }
    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        exact::eval_newton(&self.0.k, q, qd, t, out.phi, out.phi_q, out.mass, out.force)
    }
    fn eval_kinematics(&self, q: &[f64], qd: &[f64], t: f64, out: KinematicOutputs<'_>) {
        eval_kinematics(q, qd, t, out.phi, out.phi_q, out.phi_t, out.gamma)
    }
}
/// The formulation listed first in the mechanism file.
pub type DefaultFormulation = Exact;
/// This mechanism in the registries (`symbody_runtime::Registry`).
pub static ENTRY: Entry = Entry {
    name: "simple_pendulum",
    t_end: T_END,
    formulations: &[(Formulation::Exact, &Exact as &(dyn Mechanism + Sync))],
    reduced: Some(symbody_runtime::registry::Reduced {
        formulations: &[
            (Formulation::Exact, &reduced::Exact as &(dyn Mechanism + Sync)),
        ],
        reduction: &reduced::REDUCTION,
    }),
    origin: Origin::Compiled {
        file: concat!(
            env!("CARGO_MANIFEST_DIR"), "/../../../", "mechanisms/simple_pendulum.toml"
        ),
        hash: 11379041075575716480u64,
        parameters: &[],
    },
    run_time: Some(&RUN_TIME_ENTRY),
};
