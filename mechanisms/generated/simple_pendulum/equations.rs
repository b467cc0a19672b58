//! Generated equations of `simple_pendulum` (IFToMM benchmark A01: planar simple pendulum, point mass on a massless link). Do not edit.
//!
//! Regenerate with `cargo xtask generate simple_pendulum` from `mechanisms/simple_pendulum.toml`.
//!
//! 7 coordinates, 2 constraints, 7 structural nonzeros in Φq.
//! Rank 2 at the initial pose; mobility 5 (Grübler count 5), 5 DOF left with drivers.
//! Each body owns `[X, Y, Z]` (centre of mass), then `[θ, β, γ]` (A = Rz(γ)·Ry(β)·Rx(θ))
//! or Euler parameters `[e0, e1, e2, e3]`. Equations of motion: `M q̈ + Φqᵀλ = Q`, `Φq q̈ = γ`.
//! Sparse outputs hold the pattern's nonzeros in order (row-major, columns ascending).
//!
//! Coordinates:
//! - `0..7` p1 (quaternion)
//!
//! Constraint rows:
//! - `0..1` link (distance, ground – p1)
//! - `1` p1.norm: eᵀe − 1
#![allow(
    clippy::approx_constant,
    clippy::excessive_precision,
    clippy::too_many_arguments,
    clippy::unreadable_literal
)]
use symbody_runtime::{
    BodyInfo, Entry, Formulation, JointInfo, JointKind, KinematicOutputs, Mechanism,
    MechanismInfo, NewtonOutputs, Origin, PlatformInfo, Rotation,
};
/// Constraint residual Φ(q, t).
pub fn phi(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 2] = out.try_into().expect("out must have 2 entries");
    let _ = t;
    phi_part_0(q, out);
}
#[inline(never)]
fn phi_part_0(q: &[f64; 7], out: &mut [f64; 2]) {
    let x9 = q[3] * q[3];
    let x10 = q[4] * q[4];
    let x11 = q[5] * q[5];
    let x12 = q[6] * q[6];
    let x13 = x9 + x10;
    let x48 = q[0] * q[0];
    let x49 = q[1] * q[1];
    let x50 = q[2] * q[2];
    let x51 = x48 + x49;
    let x52 = x50 + x51;
    let x53 = x52.sqrt();
    let x54 = x53 - 1.0;
    let x55 = x11 + x13;
    let x56 = x12 + x55;
    let x57 = x56 - 1.0;
    out[0] = x54;
    out[1] = x57;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
    let _ = t;
    phi_q_part_0(q, out);
}
#[inline(never)]
fn phi_q_part_0(q: &[f64; 7], out: &mut [f64; 7]) {
    let x48 = q[0] * q[0];
    let x49 = q[1] * q[1];
    let x50 = q[2] * q[2];
    let x51 = x48 + x49;
    let x52 = x50 + x51;
    let x53 = x52.sqrt();
    let x58 = q[0] * 2.0;
    let x59 = q[1] * 2.0;
    let x60 = q[2] * 2.0;
    let x61 = 2.0 * x53;
    let x62 = 1.0 / x61;
    let x63 = x58 * x62;
    let x64 = x59 * x62;
    let x65 = x60 * x62;
    let x66 = q[3] * 2.0;
    let x67 = q[4] * 2.0;
    let x68 = q[5] * 2.0;
    let x69 = q[6] * 2.0;
    out[0] = x63;
    out[1] = x64;
    out[2] = x65;
    out[3] = x66;
    out[4] = x67;
    out[5] = x68;
    out[6] = x69;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 2] = out.try_into().expect("out must have 2 entries");
    let _ = q;
    let _ = t;
    phi_t_part_0(out);
}
#[inline(never)]
fn phi_t_part_0(out: &mut [f64; 2]) {
    out[0] = 0.0;
    out[1] = 0.0;
}
/// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
pub fn gamma(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 2] = out.try_into().expect("out must have 2 entries");
    let _ = t;
    gamma_part_0(q, qd, out);
}
#[inline(never)]
fn gamma_part_0(q: &[f64; 7], qd: &[f64; 7], out: &mut [f64; 2]) {
    let x48 = q[0] * q[0];
    let x49 = q[1] * q[1];
    let x50 = q[2] * q[2];
    let x51 = x48 + x49;
    let x52 = x50 + x51;
    let x53 = x52.sqrt();
    let x58 = q[0] * 2.0;
    let x59 = q[1] * 2.0;
    let x60 = q[2] * 2.0;
    let x61 = 2.0 * x53;
    let x62 = 1.0 / x61;
    let x82 = x58 * qd[0];
    let x83 = x59 * qd[1];
    let x84 = x60 * qd[2];
    let x85 = x82 + x83;
    let x86 = x84 + x85;
    let x87 = x62 * x86;
    let x90 = 2.0 * qd[0];
    let x91 = 2.0 * qd[1];
    let x92 = 2.0 * qd[2];
    let x93 = 2.0 * x87;
    let x94 = x62 * x62;
    let x95 = x93 * x94;
    let x97 = 2.0 * qd[3];
    let x98 = 2.0 * qd[4];
    let x99 = 2.0 * qd[5];
    let x100 = 2.0 * qd[6];
    let x101 = qd[3] * x97;
    let x102 = qd[4] * x98;
    let x103 = qd[5] * x99;
    let x104 = qd[6] * x100;
    let x105 = x101 + x102;
    let x106 = qd[0] * x90;
    let x107 = qd[1] * x91;
    let x108 = qd[2] * x92;
    let x109 = x106 + x107;
    let x110 = x108 + x109;
    let x111 = x86 * x95;
    let x113 = x62 * x110;
    let x114 = x113 - x111;
    let x115 = x103 + x105;
    let x116 = x104 + x115;
    let x117 = -x114;
    let x118 = -x116;
    out[0] = x117;
    out[1] = x118;
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
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let phi: &mut [f64; 2] = phi.try_into().expect("phi must have 2 entries");
    let phi_q: &mut [f64; 7] = phi_q.try_into().expect("phi_q must have 7 entries");
    let phi_t: &mut [f64; 2] = phi_t.try_into().expect("phi_t must have 2 entries");
    let gamma: &mut [f64; 2] = gamma.try_into().expect("gamma must have 2 entries");
    let _ = t;
    eval_kinematics_part_0(q, qd, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_part_0(
    q: &[f64; 7],
    qd: &[f64; 7],
    phi: &mut [f64; 2],
    phi_q: &mut [f64; 7],
    phi_t: &mut [f64; 2],
    gamma: &mut [f64; 2],
) {
    let x9 = q[3] * q[3];
    let x10 = q[4] * q[4];
    let x11 = q[5] * q[5];
    let x12 = q[6] * q[6];
    let x13 = x9 + x10;
    let x48 = q[0] * q[0];
    let x49 = q[1] * q[1];
    let x50 = q[2] * q[2];
    let x51 = x48 + x49;
    let x52 = x50 + x51;
    let x53 = x52.sqrt();
    let x54 = x53 - 1.0;
    let x55 = x11 + x13;
    let x56 = x12 + x55;
    let x57 = x56 - 1.0;
    let x58 = q[0] * 2.0;
    let x59 = q[1] * 2.0;
    let x60 = q[2] * 2.0;
    let x61 = 2.0 * x53;
    let x62 = 1.0 / x61;
    let x63 = x58 * x62;
    let x64 = x59 * x62;
    let x65 = x60 * x62;
    let x66 = q[3] * 2.0;
    let x67 = q[4] * 2.0;
    let x68 = q[5] * 2.0;
    let x69 = q[6] * 2.0;
    let x82 = x58 * qd[0];
    let x83 = x59 * qd[1];
    let x84 = x60 * qd[2];
    let x85 = x82 + x83;
    let x86 = x84 + x85;
    let x87 = x62 * x86;
    let x90 = 2.0 * qd[0];
    let x91 = 2.0 * qd[1];
    let x92 = 2.0 * qd[2];
    let x93 = 2.0 * x87;
    let x94 = x62 * x62;
    let x95 = x93 * x94;
    let x97 = 2.0 * qd[3];
    let x98 = 2.0 * qd[4];
    let x99 = 2.0 * qd[5];
    let x100 = 2.0 * qd[6];
    let x101 = qd[3] * x97;
    let x102 = qd[4] * x98;
    let x103 = qd[5] * x99;
    let x104 = qd[6] * x100;
    let x105 = x101 + x102;
    let x106 = qd[0] * x90;
    let x107 = qd[1] * x91;
    let x108 = qd[2] * x92;
    let x109 = x106 + x107;
    let x110 = x108 + x109;
    let x111 = x86 * x95;
    let x113 = x62 * x110;
    let x114 = x113 - x111;
    let x115 = x103 + x105;
    let x116 = x104 + x115;
    let x117 = -x114;
    let x118 = -x116;
    phi[0] = x54;
    phi_q[0] = x63;
    phi_q[1] = x64;
    phi_q[2] = x65;
    phi_t[0] = 0.0;
    gamma[0] = x117;
    phi[1] = x57;
    phi_q[3] = x66;
    phi_q[4] = x67;
    phi_q[5] = x68;
    phi_q[6] = x69;
    phi_t[1] = 0.0;
    gamma[1] = x118;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(q: &[f64], out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    potential_into_part_0(q, out);
}
#[inline(never)]
fn potential_into_part_0(q: &[f64; 7], out: &mut [f64; 1]) {
    let x120 = q[1] * 9.81;
    out[0] = x120;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
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
pub const N_COORDS: usize = 7usize;
/// Number of constraint rows.
pub const N_CONSTRAINTS: usize = 2usize;
/// Row of each Φq nonzero.
pub static PHI_Q_ROWS: [u32; 7usize] = [0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 1u32];
/// Column of each Φq nonzero.
pub static PHI_Q_COLS: [u32; 7usize] = [0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32];
/// Bodies in coordinate order.
pub static BODIES: [BodyInfo; 1usize] = [
    BodyInfo {
        name: "p1",
        coord_offset: 0usize,
        rotation: Rotation::Quaternion,
        mass: 1f64,
        inertia: [0.00004f64, 0.00004f64, 0.00004f64],
    },
];
/// Joints in row order, then drivers.
pub static JOINTS: [JointInfo; 2usize] = [
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
    JointInfo {
        name: "p1.norm",
        kind: JointKind::Normalization,
        body1: Some(0usize),
        body2: None,
        row_start: 1usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
];
/// Name of each coordinate.
pub static COORD_NAMES: [&str; 7usize] = [
    "p1.x",
    "p1.y",
    "p1.z",
    "p1.e0",
    "p1.e1",
    "p1.e2",
    "p1.e3",
];
/// Name of each constraint row.
pub static ROW_NAMES: [&str; 2usize] = ["link.distance", "p1.norm"];
/// Initial coordinates: the file's pose, assembled.
pub static Q0: [f64; 7usize] = [1f64, 0f64, 0f64, 1f64, 0f64, 0f64, 0f64];
/// Initial velocities from the file (to be projected onto the constraints).
pub static QD0: [f64; 7usize] = [0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64];
/// Constraint rows dependent on others at the initial pose (dropped by the solvers).
pub static REDUNDANT_ROWS: [u32; 0usize] = [];
/// Simulation end time suggested by the mechanism file (s).
pub const T_END: f64 = 2000f64;
/// The platform held by six legs of driven length, for forward kinematics (`None`:
/// not such a mechanism).
pub const PLATFORM: Option<PlatformInfo> = None;
/// Potential energy of gravity and springs.
pub fn potential(q: &[f64]) -> f64 {
    let mut out = [0.0];
    potential_into(q, &mut out);
    out[0]
}
/// Power of the non-conservative loads.
pub fn power_nc(q: &[f64], qd: &[f64], t: f64) -> f64 {
    let mut out = [0.0];
    power_nc_into(q, qd, t, &mut out);
    out[0]
}
/// The `exact` formulation: mass matrix and forces derived from the exact kinetic energy.
pub mod exact {
    use super::*;
    /// Row of each mass-matrix nonzero (both triangles).
    pub static MASS_ROWS: [u32; 19usize] = [
        0u32, 1u32, 2u32, 3u32, 3u32, 3u32, 3u32, 4u32, 4u32, 4u32, 4u32, 5u32, 5u32,
        5u32, 5u32, 6u32, 6u32, 6u32, 6u32,
    ];
    /// Column of each mass-matrix nonzero.
    pub static MASS_COLS: [u32; 19usize] = [
        0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32,
        5u32, 6u32, 3u32, 4u32, 5u32, 6u32,
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
        q: &[f64],
        qd: &[f64],
        t: f64,
        dq: &mut [f64],
        dqd: &mut [f64],
    ) {
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let _: &mut [f64; 0] = dq.try_into().expect("dq must have 0 entries");
        let _: &mut [f64; 0] = dqd.try_into().expect("dqd must have 0 entries");
        let _ = q;
        let _ = qd;
        let _ = t;
    }
    /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
    pub fn mass(q: &[f64], out: &mut [f64]) {
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
        mass_part_0(q, out);
    }
    #[inline(never)]
    fn mass_part_0(q: &[f64; 7], out: &mut [f64; 19]) {
        let x9 = q[3] * q[3];
        let x10 = q[4] * q[4];
        let x11 = q[5] * q[5];
        let x12 = q[6] * q[6];
        let x23 = q[4] * q[5];
        let x25 = q[3] * q[6];
        let x30 = q[4] * q[6];
        let x32 = q[3] * q[5];
        let x36 = q[5] * q[6];
        let x38 = q[3] * q[4];
        let x66 = q[3] * 2.0;
        let x67 = q[4] * 2.0;
        let x68 = q[5] * 2.0;
        let x69 = q[6] * 2.0;
        let x233 = 2.0 * x67;
        let x235 = 2.0 * x68;
        let x237 = 2.0 * x69;
        let x239 = x67 * x233;
        let x241 = 0.00004 * x239;
        let x243 = x68 * x235;
        let x245 = 0.00004 * x243;
        let x247 = x69 * x237;
        let x249 = 0.00004 * x247;
        let x251 = x241 + x245;
        let x253 = x249 + x251;
        let x255 = 0.5 * x253;
        let x257 = x9 * 0.00016;
        let x258 = x255 + x257;
        let x259 = 2.0 * x66;
        let x260 = x67 * x259;
        let x261 = 0.00004 * x260;
        let x262 = x68 * x237;
        let x264 = 0.00004 * x262;
        let x266 = x69 * x235;
        let x267 = 0.00004 * x266;
        let x268 = x261 - x264;
        let x269 = x267 + x268;
        let x270 = 0.5 * x269;
        let x272 = x38 * 0.00016;
        let x273 = x272 - x270;
        let x274 = x67 * x237;
        let x275 = 0.00004 * x274;
        let x276 = x68 * x259;
        let x277 = 0.00004 * x276;
        let x278 = x69 * x233;
        let x280 = 0.00004 * x278;
        let x282 = x275 + x277;
        let x283 = x282 - x280;
        let x284 = 0.5 * x283;
        let x286 = x32 * 0.00016;
        let x287 = x286 - x284;
        let x288 = x67 * x235;
        let x290 = 0.00004 * x288;
        let x292 = x68 * x233;
        let x293 = 0.00004 * x292;
        let x294 = x69 * x259;
        let x295 = 0.00004 * x294;
        let x296 = x293 - x290;
        let x297 = x295 + x296;
        let x298 = 0.5 * x297;
        let x300 = x25 * 0.00016;
        let x301 = x300 - x298;
        let x302 = x66 * x233;
        let x304 = 0.00004 * x302;
        let x308 = x267 - x304;
        let x309 = x308 - x264;
        let x310 = 0.5 * x309;
        let x311 = x272 + x310;
        let x312 = x66 * x259;
        let x313 = 0.00004 * x312;
        let x314 = x249 + x313;
        let x315 = x245 + x314;
        let x316 = 0.5 * x315;
        let x317 = x10 * 0.00016;
        let x318 = x316 + x317;
        let x319 = x66 * x237;
        let x320 = 0.00004 * x319;
        let x324 = x320 - x295;
        let x325 = x324 - x293;
        let x326 = 0.5 * x325;
        let x327 = x23 * 0.00016;
        let x328 = x326 + x327;
        let x329 = x66 * x235;
        let x331 = 0.00004 * x329;
        let x333 = x280 + x331;
        let x335 = x277 - x333;
        let x336 = 0.5 * x335;
        let x337 = x30 * 0.00016;
        let x338 = x336 + x337;
        let x341 = x275 - x333;
        let x342 = 0.5 * x341;
        let x343 = x286 + x342;
        let x346 = x295 - x320;
        let x347 = x346 - x290;
        let x348 = 0.5 * x347;
        let x349 = x327 + x348;
        let x350 = x241 + x314;
        let x351 = 0.5 * x350;
        let x352 = x11 * 0.00016;
        let x353 = x351 + x352;
        let x355 = x304 - x267;
        let x356 = x355 - x261;
        let x357 = 0.5 * x356;
        let x358 = x36 * 0.00016;
        let x359 = x357 + x358;
        let x360 = x296 - x320;
        let x361 = 0.5 * x360;
        let x362 = x300 + x361;
        let x365 = x331 - x282;
        let x366 = 0.5 * x365;
        let x367 = x337 + x366;
        let x368 = x268 - x304;
        let x369 = 0.5 * x368;
        let x370 = x358 + x369;
        let x371 = x251 + x313;
        let x372 = 0.5 * x371;
        let x373 = x12 * 0.00016;
        let x374 = x372 + x373;
        out[0] = 1.0;
        out[1] = 1.0;
        out[2] = 1.0;
        out[3] = x258;
        out[4] = x273;
        out[5] = x287;
        out[6] = x301;
        out[7] = x311;
        out[8] = x318;
        out[9] = x328;
        out[10] = x338;
        out[11] = x343;
        out[12] = x349;
        out[13] = x353;
        out[14] = x359;
        out[15] = x362;
        out[16] = x367;
        out[17] = x370;
        out[18] = x374;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
        let _ = t;
        force_part_0(q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(q: &[f64; 7], qd: &[f64; 7], out: &mut [f64; 7]) {
        let x66 = q[3] * 2.0;
        let x67 = q[4] * 2.0;
        let x68 = q[5] * 2.0;
        let x69 = q[6] * 2.0;
        let x97 = 2.0 * qd[3];
        let x98 = 2.0 * qd[4];
        let x99 = 2.0 * qd[5];
        let x100 = 2.0 * qd[6];
        let x122 = q[4] * qd[3];
        let x124 = q[3] * qd[4];
        let x125 = q[6] * qd[5];
        let x126 = q[5] * qd[6];
        let x128 = x124 - x122;
        let x129 = x125 + x128;
        let x130 = x129 - x126;
        let x131 = 2.0 * x130;
        let x132 = q[5] * qd[3];
        let x134 = q[6] * qd[4];
        let x136 = q[3] * qd[5];
        let x137 = q[4] * qd[6];
        let x138 = x132 + x134;
        let x140 = x136 - x138;
        let x141 = x137 + x140;
        let x142 = 2.0 * x141;
        let x143 = q[6] * qd[3];
        let x145 = q[5] * qd[4];
        let x146 = q[4] * qd[5];
        let x148 = q[3] * qd[6];
        let x149 = x145 - x143;
        let x150 = x149 - x146;
        let x151 = x148 + x150;
        let x152 = 2.0 * x151;
        let x169 = 2.0 * x131;
        let x170 = 2.0 * x142;
        let x171 = 2.0 * x152;
        let x379 = qd[3] * qd[5];
        let x380 = qd[4] * qd[6];
        let x381 = x379 + x380;
        let x383 = x379 - x381;
        let x384 = x380 + x383;
        let x385 = 2.0 * x384;
        let x386 = qd[3] * qd[6];
        let x388 = qd[4] * qd[5];
        let x390 = x388 - x386;
        let x391 = x390 - x388;
        let x392 = x386 + x391;
        let x393 = 2.0 * x392;
        let x394 = 2.0 * x385;
        let x395 = 2.0 * x393;
        let x396 = x98 * x169;
        let x397 = 0.00004 * x396;
        let x398 = x99 * x170;
        let x399 = x68 * x394;
        let x400 = x398 + x399;
        let x401 = 0.00004 * x400;
        let x402 = x100 * x171;
        let x403 = x69 * x395;
        let x404 = x402 + x403;
        let x405 = 0.00004 * x404;
        let x406 = x397 + x401;
        let x407 = x405 + x406;
        let x408 = 0.5 * x407;
        let x410 = x97 * x169;
        let x411 = 0.00004 * x410;
        let x412 = x100 * x170;
        let x413 = x69 * x394;
        let x414 = x412 + x413;
        let x415 = 0.00004 * x414;
        let x417 = x99 * x171;
        let x418 = x68 * x395;
        let x419 = x417 + x418;
        let x420 = 0.00004 * x419;
        let x421 = x411 - x415;
        let x422 = x420 + x421;
        let x423 = 0.5 * x422;
        let x424 = x100 * x169;
        let x425 = 0.00004 * x424;
        let x426 = x97 * x170;
        let x427 = x66 * x394;
        let x428 = x426 + x427;
        let x429 = 0.00004 * x428;
        let x430 = x98 * x171;
        let x431 = x67 * x395;
        let x432 = x430 + x431;
        let x433 = 0.00004 * x432;
        let x435 = x425 + x429;
        let x436 = x435 - x433;
        let x437 = 0.5 * x436;
        let x438 = x99 * x169;
        let x439 = 0.00004 * x438;
        let x441 = x98 * x170;
        let x442 = x67 * x394;
        let x443 = x441 + x442;
        let x444 = 0.00004 * x443;
        let x445 = x97 * x171;
        let x446 = x66 * x395;
        let x447 = x445 + x446;
        let x448 = 0.00004 * x447;
        let x449 = x444 - x439;
        let x450 = x448 + x449;
        let x451 = 0.5 * x450;
        let x452 = qd[3] * qd[3];
        let x453 = qd[4] * qd[4];
        let x454 = qd[5] * qd[5];
        let x455 = qd[6] * qd[6];
        let x456 = x452 + x453;
        let x457 = x454 + x456;
        let x458 = x455 + x457;
        let x460 = 0.00004 * x398;
        let x461 = 0.00004 * x402;
        let x462 = x397 + x460;
        let x463 = x461 + x462;
        let x464 = 0.5 * x463;
        let x465 = x408 + x464;
        let x466 = q[3] * 0.00016;
        let x467 = x458 * x466;
        let x469 = x465 - x467;
        let x476 = 0.00004 * x412;
        let x478 = 0.00004 * x417;
        let x480 = x476 - x411;
        let x481 = x480 - x478;
        let x482 = 0.5 * x481;
        let x484 = x482 - x423;
        let x485 = q[4] * 0.00016;
        let x486 = x458 * x485;
        let x488 = x484 - x486;
        let x494 = 0.00004 * x426;
        let x496 = 0.00004 * x430;
        let x497 = x425 + x494;
        let x499 = x496 - x497;
        let x500 = 0.5 * x499;
        let x502 = x500 - x437;
        let x503 = q[5] * 0.00016;
        let x504 = x458 * x503;
        let x506 = x502 - x504;
        let x510 = 0.00004 * x441;
        let x513 = 0.00004 * x445;
        let x515 = x439 - x510;
        let x516 = x515 - x513;
        let x517 = 0.5 * x516;
        let x519 = x517 - x451;
        let x520 = q[6] * 0.00016;
        let x521 = x458 * x520;
        let x523 = x519 - x521;
        out[0] = 0.0;
        out[1] = -9.81;
        out[2] = 0.0;
        out[3] = x469;
        out[4] = x488;
        out[5] = x506;
        out[6] = x523;
    }
    /// Φ, Φq, M and Q at one state in one pass: what one Newton iteration needs.
    pub fn eval_newton(
        q: &[f64],
        qd: &[f64],
        t: f64,
        phi: &mut [f64],
        phi_q: &mut [f64],
        mass: &mut [f64],
        force: &mut [f64],
    ) {
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 2] = phi.try_into().expect("phi must have 2 entries");
        let phi_q: &mut [f64; 7] = phi_q.try_into().expect("phi_q must have 7 entries");
        let mass: &mut [f64; 19] = mass.try_into().expect("mass must have 19 entries");
        let force: &mut [f64; 7] = force.try_into().expect("force must have 7 entries");
        let _ = t;
        eval_newton_part_0(q, qd, phi, phi_q, mass, force);
    }
    #[inline(never)]
    fn eval_newton_part_0(
        q: &[f64; 7],
        qd: &[f64; 7],
        phi: &mut [f64; 2],
        phi_q: &mut [f64; 7],
        mass: &mut [f64; 19],
        force: &mut [f64; 7],
    ) {
        let x9 = q[3] * q[3];
        let x10 = q[4] * q[4];
        let x11 = q[5] * q[5];
        let x12 = q[6] * q[6];
        let x13 = x9 + x10;
        let x23 = q[4] * q[5];
        let x25 = q[3] * q[6];
        let x30 = q[4] * q[6];
        let x32 = q[3] * q[5];
        let x36 = q[5] * q[6];
        let x38 = q[3] * q[4];
        let x48 = q[0] * q[0];
        let x49 = q[1] * q[1];
        let x50 = q[2] * q[2];
        let x51 = x48 + x49;
        let x52 = x50 + x51;
        let x53 = x52.sqrt();
        let x54 = x53 - 1.0;
        let x55 = x11 + x13;
        let x56 = x12 + x55;
        let x57 = x56 - 1.0;
        let x58 = q[0] * 2.0;
        let x59 = q[1] * 2.0;
        let x60 = q[2] * 2.0;
        let x61 = 2.0 * x53;
        let x62 = 1.0 / x61;
        let x63 = x58 * x62;
        let x64 = x59 * x62;
        let x65 = x60 * x62;
        let x66 = q[3] * 2.0;
        let x67 = q[4] * 2.0;
        let x68 = q[5] * 2.0;
        let x69 = q[6] * 2.0;
        let x97 = 2.0 * qd[3];
        let x98 = 2.0 * qd[4];
        let x99 = 2.0 * qd[5];
        let x100 = 2.0 * qd[6];
        let x122 = q[4] * qd[3];
        let x124 = q[3] * qd[4];
        let x125 = q[6] * qd[5];
        let x126 = q[5] * qd[6];
        let x128 = x124 - x122;
        let x129 = x125 + x128;
        let x130 = x129 - x126;
        let x131 = 2.0 * x130;
        let x132 = q[5] * qd[3];
        let x134 = q[6] * qd[4];
        let x136 = q[3] * qd[5];
        let x137 = q[4] * qd[6];
        let x138 = x132 + x134;
        let x140 = x136 - x138;
        let x141 = x137 + x140;
        let x142 = 2.0 * x141;
        let x143 = q[6] * qd[3];
        let x145 = q[5] * qd[4];
        let x146 = q[4] * qd[5];
        let x148 = q[3] * qd[6];
        let x149 = x145 - x143;
        let x150 = x149 - x146;
        let x151 = x148 + x150;
        let x152 = 2.0 * x151;
        let x169 = 2.0 * x131;
        let x170 = 2.0 * x142;
        let x171 = 2.0 * x152;
        let x233 = 2.0 * x67;
        let x235 = 2.0 * x68;
        let x237 = 2.0 * x69;
        let x239 = x67 * x233;
        let x241 = 0.00004 * x239;
        let x243 = x68 * x235;
        let x245 = 0.00004 * x243;
        let x247 = x69 * x237;
        let x249 = 0.00004 * x247;
        let x251 = x241 + x245;
        let x253 = x249 + x251;
        let x255 = 0.5 * x253;
        let x257 = x9 * 0.00016;
        let x258 = x255 + x257;
        let x259 = 2.0 * x66;
        let x260 = x67 * x259;
        let x261 = 0.00004 * x260;
        let x262 = x68 * x237;
        let x264 = 0.00004 * x262;
        let x266 = x69 * x235;
        let x267 = 0.00004 * x266;
        let x268 = x261 - x264;
        let x269 = x267 + x268;
        let x270 = 0.5 * x269;
        let x272 = x38 * 0.00016;
        let x273 = x272 - x270;
        let x274 = x67 * x237;
        let x275 = 0.00004 * x274;
        let x276 = x68 * x259;
        let x277 = 0.00004 * x276;
        let x278 = x69 * x233;
        let x280 = 0.00004 * x278;
        let x282 = x275 + x277;
        let x283 = x282 - x280;
        let x284 = 0.5 * x283;
        let x286 = x32 * 0.00016;
        let x287 = x286 - x284;
        let x288 = x67 * x235;
        let x290 = 0.00004 * x288;
        let x292 = x68 * x233;
        let x293 = 0.00004 * x292;
        let x294 = x69 * x259;
        let x295 = 0.00004 * x294;
        let x296 = x293 - x290;
        let x297 = x295 + x296;
        let x298 = 0.5 * x297;
        let x300 = x25 * 0.00016;
        let x301 = x300 - x298;
        let x302 = x66 * x233;
        let x304 = 0.00004 * x302;
        let x308 = x267 - x304;
        let x309 = x308 - x264;
        let x310 = 0.5 * x309;
        let x311 = x272 + x310;
        let x312 = x66 * x259;
        let x313 = 0.00004 * x312;
        let x314 = x249 + x313;
        let x315 = x245 + x314;
        let x316 = 0.5 * x315;
        let x317 = x10 * 0.00016;
        let x318 = x316 + x317;
        let x319 = x66 * x237;
        let x320 = 0.00004 * x319;
        let x324 = x320 - x295;
        let x325 = x324 - x293;
        let x326 = 0.5 * x325;
        let x327 = x23 * 0.00016;
        let x328 = x326 + x327;
        let x329 = x66 * x235;
        let x331 = 0.00004 * x329;
        let x333 = x280 + x331;
        let x335 = x277 - x333;
        let x336 = 0.5 * x335;
        let x337 = x30 * 0.00016;
        let x338 = x336 + x337;
        let x341 = x275 - x333;
        let x342 = 0.5 * x341;
        let x343 = x286 + x342;
        let x346 = x295 - x320;
        let x347 = x346 - x290;
        let x348 = 0.5 * x347;
        let x349 = x327 + x348;
        let x350 = x241 + x314;
        let x351 = 0.5 * x350;
        let x352 = x11 * 0.00016;
        let x353 = x351 + x352;
        let x355 = x304 - x267;
        let x356 = x355 - x261;
        let x357 = 0.5 * x356;
        let x358 = x36 * 0.00016;
        let x359 = x357 + x358;
        let x360 = x296 - x320;
        let x361 = 0.5 * x360;
        let x362 = x300 + x361;
        let x365 = x331 - x282;
        let x366 = 0.5 * x365;
        let x367 = x337 + x366;
        let x368 = x268 - x304;
        let x369 = 0.5 * x368;
        let x370 = x358 + x369;
        let x371 = x251 + x313;
        let x372 = 0.5 * x371;
        let x373 = x12 * 0.00016;
        let x374 = x372 + x373;
        let x379 = qd[3] * qd[5];
        let x380 = qd[4] * qd[6];
        let x381 = x379 + x380;
        let x383 = x379 - x381;
        let x384 = x380 + x383;
        let x385 = 2.0 * x384;
        let x386 = qd[3] * qd[6];
        let x388 = qd[4] * qd[5];
        let x390 = x388 - x386;
        let x391 = x390 - x388;
        let x392 = x386 + x391;
        let x393 = 2.0 * x392;
        let x394 = 2.0 * x385;
        let x395 = 2.0 * x393;
        let x396 = x98 * x169;
        let x397 = 0.00004 * x396;
        let x398 = x99 * x170;
        let x399 = x68 * x394;
        let x400 = x398 + x399;
        let x401 = 0.00004 * x400;
        let x402 = x100 * x171;
        let x403 = x69 * x395;
        let x404 = x402 + x403;
        let x405 = 0.00004 * x404;
        let x406 = x397 + x401;
        let x407 = x405 + x406;
        let x408 = 0.5 * x407;
        let x410 = x97 * x169;
        let x411 = 0.00004 * x410;
        let x412 = x100 * x170;
        let x413 = x69 * x394;
        let x414 = x412 + x413;
        let x415 = 0.00004 * x414;
        let x417 = x99 * x171;
        let x418 = x68 * x395;
        let x419 = x417 + x418;
        let x420 = 0.00004 * x419;
        let x421 = x411 - x415;
        let x422 = x420 + x421;
        let x423 = 0.5 * x422;
        let x424 = x100 * x169;
        let x425 = 0.00004 * x424;
        let x426 = x97 * x170;
        let x427 = x66 * x394;
        let x428 = x426 + x427;
        let x429 = 0.00004 * x428;
        let x430 = x98 * x171;
        let x431 = x67 * x395;
        let x432 = x430 + x431;
        let x433 = 0.00004 * x432;
        let x435 = x425 + x429;
        let x436 = x435 - x433;
        let x437 = 0.5 * x436;
        let x438 = x99 * x169;
        let x439 = 0.00004 * x438;
        let x441 = x98 * x170;
        let x442 = x67 * x394;
        let x443 = x441 + x442;
        let x444 = 0.00004 * x443;
        let x445 = x97 * x171;
        let x446 = x66 * x395;
        let x447 = x445 + x446;
        let x448 = 0.00004 * x447;
        let x449 = x444 - x439;
        let x450 = x448 + x449;
        let x451 = 0.5 * x450;
        let x452 = qd[3] * qd[3];
        let x453 = qd[4] * qd[4];
        let x454 = qd[5] * qd[5];
        let x455 = qd[6] * qd[6];
        let x456 = x452 + x453;
        let x457 = x454 + x456;
        let x458 = x455 + x457;
        let x460 = 0.00004 * x398;
        let x461 = 0.00004 * x402;
        let x462 = x397 + x460;
        let x463 = x461 + x462;
        let x464 = 0.5 * x463;
        let x465 = x408 + x464;
        let x466 = q[3] * 0.00016;
        let x467 = x458 * x466;
        let x469 = x465 - x467;
        let x476 = 0.00004 * x412;
        let x478 = 0.00004 * x417;
        let x480 = x476 - x411;
        let x481 = x480 - x478;
        let x482 = 0.5 * x481;
        let x484 = x482 - x423;
        let x485 = q[4] * 0.00016;
        let x486 = x458 * x485;
        let x488 = x484 - x486;
        let x494 = 0.00004 * x426;
        let x496 = 0.00004 * x430;
        let x497 = x425 + x494;
        let x499 = x496 - x497;
        let x500 = 0.5 * x499;
        let x502 = x500 - x437;
        let x503 = q[5] * 0.00016;
        let x504 = x458 * x503;
        let x506 = x502 - x504;
        let x510 = 0.00004 * x441;
        let x513 = 0.00004 * x445;
        let x515 = x439 - x510;
        let x516 = x515 - x513;
        let x517 = 0.5 * x516;
        let x519 = x517 - x451;
        let x520 = q[6] * 0.00016;
        let x521 = x458 * x520;
        let x523 = x519 - x521;
        phi[0] = x54;
        phi_q[0] = x63;
        phi_q[1] = x64;
        phi_q[2] = x65;
        phi[1] = x57;
        phi_q[3] = x66;
        phi_q[4] = x67;
        phi_q[5] = x68;
        phi_q[6] = x69;
        mass[0] = 1.0;
        mass[1] = 1.0;
        mass[2] = 1.0;
        mass[3] = x258;
        mass[4] = x273;
        mass[5] = x287;
        mass[6] = x301;
        mass[7] = x311;
        mass[8] = x318;
        mass[9] = x328;
        mass[10] = x338;
        mass[11] = x343;
        mass[12] = x349;
        mass[13] = x353;
        mass[14] = x359;
        mass[15] = x362;
        mass[16] = x367;
        mass[17] = x370;
        mass[18] = x374;
        force[0] = 0.0;
        force[1] = -9.81;
        force[2] = 0.0;
        force[3] = x469;
        force[4] = x488;
        force[5] = x506;
        force[6] = x523;
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
        exact::mass(q, out)
    }
    fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        exact::force(q, qd, t, out)
    }
    fn force_jacobian(
        &self,
        q: &[f64],
        qd: &[f64],
        t: f64,
        dq: &mut [f64],
        dqd: &mut [f64],
    ) {
        exact::force_jacobian(q, qd, t, dq, dqd)
    }
    fn potential(&self, q: &[f64]) -> f64 {
        potential(q)
    }
    fn power_nc(&self, q: &[f64], qd: &[f64], t: f64) -> f64 {
        power_nc(q, qd, t)
    }
    fn eval_newton(&self, q: &[f64], qd: &[f64], t: f64, out: NewtonOutputs<'_>) {
        exact::eval_newton(q, qd, t, out.phi, out.phi_q, out.mass, out.force)
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
    reduced: None,
    origin: Origin::Compiled {
        file: concat!(
            env!("CARGO_MANIFEST_DIR"), "/../../../", "mechanisms/simple_pendulum.toml"
        ),
        hash: 18052815997623647509u64,
    },
};
