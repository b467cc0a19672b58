//! Generated equations of `spherical_pendulum` (rigid spherical pendulum released into a steady cone, Y up). Do not edit.
//!
//! Regenerate with `cargo xtask generate spherical_pendulum` from `mechanisms/spherical_pendulum.toml`.
//!
//! 7 coordinates, 4 constraints, 19 structural nonzeros in Φq.
//! Rank 4 at the initial pose; mobility 3 (Grübler count 3), 3 DOF left with drivers.
//! Each body owns `[X, Y, Z]` (centre of mass), then `[θ, β, γ]` (A = Rz(γ)·Ry(β)·Rx(θ))
//! or Euler parameters `[e0, e1, e2, e3]`. Equations of motion: `M q̈ + Φqᵀλ = Q`, `Φq q̈ = γ`.
//! Sparse outputs hold the pattern's nonzeros in order (row-major, columns ascending).
//!
//! Coordinates:
//! - `0..7` bob (quaternion)
//!
//! Constraint rows:
//! - `0..3` pivot (spherical, ground – bob)
//! - `3` bob.norm: eᵀe − 1
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
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    let _ = t;
    phi_part_0(q, out);
}
#[inline(never)]
fn phi_part_0(q: &[f64; 7], out: &mut [f64; 4]) {
    let x9 = q[3] * q[3];
    let x10 = q[4] * q[4];
    let x11 = q[5] * q[5];
    let x12 = q[6] * q[6];
    let x13 = x9 + x10;
    let x14 = 2.0 * x13;
    let x16 = x14 - 1.0;
    let x17 = x9 + x11;
    let x18 = 2.0 * x17;
    let x19 = x18 - 1.0;
    let x23 = q[4] * q[5];
    let x24 = 2.0 * x23;
    let x25 = q[3] * q[6];
    let x27 = 2.0 * x25;
    let x29 = x24 - x27;
    let x30 = q[4] * q[6];
    let x31 = 2.0 * x30;
    let x32 = q[3] * q[5];
    let x33 = 2.0 * x32;
    let x35 = x24 + x27;
    let x36 = q[5] * q[6];
    let x37 = 2.0 * x36;
    let x38 = q[3] * q[4];
    let x40 = 2.0 * x38;
    let x45 = x31 - x33;
    let x46 = x37 + x40;
    let x50 = x16 * 0.00000000000000011102230246251565;
    let x51 = x29 * 0.9999999999999999;
    let x52 = x50 + x51;
    let x53 = x35 * 0.00000000000000011102230246251565;
    let x54 = x19 * 0.9999999999999999;
    let x55 = x53 + x54;
    let x56 = x45 * 0.00000000000000011102230246251565;
    let x57 = x46 * 0.9999999999999999;
    let x58 = x56 + x57;
    let x59 = q[0] + x52;
    let x60 = q[1] + x55;
    let x61 = q[2] + x58;
    let x62 = -x59;
    let x63 = -x60;
    let x64 = -x61;
    let x65 = x11 + x13;
    let x66 = x12 + x65;
    let x67 = x66 - 1.0;
    out[0] = x62;
    out[1] = x63;
    out[2] = x64;
    out[3] = x67;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
    let _ = t;
    phi_q_part_0(q, out);
}
#[inline(never)]
fn phi_q_part_0(q: &[f64; 7], out: &mut [f64; 19]) {
    let x68 = q[3] * 2.0;
    let x69 = q[4] * 2.0;
    let x70 = q[5] * 2.0;
    let x71 = q[6] * 2.0;
    let x72 = 2.0 * x68;
    let x75 = 0.00000000000000011102230246251565 * x72;
    let x76 = 0.9999999999999999 * x71;
    let x78 = x75 - x76;
    let x79 = 0.00000000000000011102230246251565 * x71;
    let x80 = 0.9999999999999999 * x72;
    let x81 = x79 + x80;
    let x82 = 0.00000000000000011102230246251565 * x70;
    let x83 = -x82;
    let x84 = 0.9999999999999999 * x69;
    let x85 = x84 - x82;
    let x86 = -x78;
    let x87 = -x81;
    let x88 = -x85;
    let x89 = 2.0 * x69;
    let x90 = 0.00000000000000011102230246251565 * x89;
    let x91 = 0.9999999999999999 * x70;
    let x92 = x90 + x91;
    let x93 = 0.9999999999999999 * x68;
    let x94 = x79 + x93;
    let x95 = -x92;
    let x96 = -x94;
    let x97 = 2.0 * x70;
    let x99 = 0.00000000000000011102230246251565 * x69;
    let x100 = 0.9999999999999999 * x97;
    let x101 = x99 + x100;
    let x102 = 0.00000000000000011102230246251565 * x68;
    let x103 = -x102;
    let x104 = x76 - x102;
    let x105 = -x84;
    let x106 = -x101;
    let x107 = -x104;
    let x109 = x91 + x99;
    let x110 = -x109;
    out[0] = -1.0;
    out[1] = x86;
    out[2] = x95;
    out[3] = x105;
    out[4] = x93;
    out[5] = -1.0;
    out[6] = x87;
    out[7] = x83;
    out[8] = x106;
    out[9] = x103;
    out[10] = -1.0;
    out[11] = x88;
    out[12] = x96;
    out[13] = x107;
    out[14] = x110;
    out[15] = x68;
    out[16] = x69;
    out[17] = x70;
    out[18] = x71;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    let _ = q;
    let _ = t;
    phi_t_part_0(out);
}
#[inline(never)]
fn phi_t_part_0(out: &mut [f64; 4]) {
    out[0] = 0.0;
    out[1] = 0.0;
    out[2] = 0.0;
    out[3] = 0.0;
}
/// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
pub fn gamma(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    let _ = q;
    let _ = t;
    gamma_part_0(qd, out);
}
#[inline(never)]
fn gamma_part_0(qd: &[f64; 7], out: &mut [f64; 4]) {
    let x173 = 2.0 * qd[3];
    let x174 = 2.0 * qd[4];
    let x175 = 2.0 * qd[5];
    let x176 = 2.0 * qd[6];
    let x177 = qd[3] * x173;
    let x178 = qd[4] * x174;
    let x179 = qd[5] * x175;
    let x180 = qd[6] * x176;
    let x181 = x177 + x178;
    let x182 = 2.0 * x181;
    let x183 = x177 + x179;
    let x184 = 2.0 * x183;
    let x185 = qd[4] * qd[5];
    let x186 = x185 + x185;
    let x187 = 2.0 * x186;
    let x188 = qd[3] * qd[6];
    let x189 = x188 + x188;
    let x190 = 2.0 * x189;
    let x192 = x187 - x190;
    let x193 = qd[4] * qd[6];
    let x194 = x193 + x193;
    let x195 = 2.0 * x194;
    let x196 = qd[3] * qd[5];
    let x197 = x196 + x196;
    let x198 = 2.0 * x197;
    let x199 = x187 + x190;
    let x200 = qd[5] * qd[6];
    let x201 = x200 + x200;
    let x202 = 2.0 * x201;
    let x203 = qd[3] * qd[4];
    let x204 = x203 + x203;
    let x205 = 2.0 * x204;
    let x207 = x195 - x198;
    let x208 = x202 + x205;
    let x209 = 0.00000000000000011102230246251565 * x182;
    let x210 = 0.9999999999999999 * x192;
    let x211 = x209 + x210;
    let x212 = 0.00000000000000011102230246251565 * x199;
    let x213 = 0.9999999999999999 * x184;
    let x214 = x212 + x213;
    let x215 = 0.00000000000000011102230246251565 * x207;
    let x216 = 0.9999999999999999 * x208;
    let x217 = x215 + x216;
    let x221 = x179 + x181;
    let x222 = x180 + x221;
    let x223 = -x222;
    out[0] = x211;
    out[1] = x214;
    out[2] = x217;
    out[3] = x223;
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
    let phi: &mut [f64; 4] = phi.try_into().expect("phi must have 4 entries");
    let phi_q: &mut [f64; 19] = phi_q.try_into().expect("phi_q must have 19 entries");
    let phi_t: &mut [f64; 4] = phi_t.try_into().expect("phi_t must have 4 entries");
    let gamma: &mut [f64; 4] = gamma.try_into().expect("gamma must have 4 entries");
    let _ = t;
    eval_kinematics_part_0(q, qd, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_part_0(
    q: &[f64; 7],
    qd: &[f64; 7],
    phi: &mut [f64; 4],
    phi_q: &mut [f64; 19],
    phi_t: &mut [f64; 4],
    gamma: &mut [f64; 4],
) {
    let x9 = q[3] * q[3];
    let x10 = q[4] * q[4];
    let x11 = q[5] * q[5];
    let x12 = q[6] * q[6];
    let x13 = x9 + x10;
    let x14 = 2.0 * x13;
    let x16 = x14 - 1.0;
    let x17 = x9 + x11;
    let x18 = 2.0 * x17;
    let x19 = x18 - 1.0;
    let x23 = q[4] * q[5];
    let x24 = 2.0 * x23;
    let x25 = q[3] * q[6];
    let x27 = 2.0 * x25;
    let x29 = x24 - x27;
    let x30 = q[4] * q[6];
    let x31 = 2.0 * x30;
    let x32 = q[3] * q[5];
    let x33 = 2.0 * x32;
    let x35 = x24 + x27;
    let x36 = q[5] * q[6];
    let x37 = 2.0 * x36;
    let x38 = q[3] * q[4];
    let x40 = 2.0 * x38;
    let x45 = x31 - x33;
    let x46 = x37 + x40;
    let x50 = x16 * 0.00000000000000011102230246251565;
    let x51 = x29 * 0.9999999999999999;
    let x52 = x50 + x51;
    let x53 = x35 * 0.00000000000000011102230246251565;
    let x54 = x19 * 0.9999999999999999;
    let x55 = x53 + x54;
    let x56 = x45 * 0.00000000000000011102230246251565;
    let x57 = x46 * 0.9999999999999999;
    let x58 = x56 + x57;
    let x59 = q[0] + x52;
    let x60 = q[1] + x55;
    let x61 = q[2] + x58;
    let x62 = -x59;
    let x63 = -x60;
    let x64 = -x61;
    let x65 = x11 + x13;
    let x66 = x12 + x65;
    let x67 = x66 - 1.0;
    let x68 = q[3] * 2.0;
    let x69 = q[4] * 2.0;
    let x70 = q[5] * 2.0;
    let x71 = q[6] * 2.0;
    let x72 = 2.0 * x68;
    let x75 = 0.00000000000000011102230246251565 * x72;
    let x76 = 0.9999999999999999 * x71;
    let x78 = x75 - x76;
    let x79 = 0.00000000000000011102230246251565 * x71;
    let x80 = 0.9999999999999999 * x72;
    let x81 = x79 + x80;
    let x82 = 0.00000000000000011102230246251565 * x70;
    let x83 = -x82;
    let x84 = 0.9999999999999999 * x69;
    let x85 = x84 - x82;
    let x86 = -x78;
    let x87 = -x81;
    let x88 = -x85;
    let x89 = 2.0 * x69;
    let x90 = 0.00000000000000011102230246251565 * x89;
    let x91 = 0.9999999999999999 * x70;
    let x92 = x90 + x91;
    let x93 = 0.9999999999999999 * x68;
    let x94 = x79 + x93;
    let x95 = -x92;
    let x96 = -x94;
    let x97 = 2.0 * x70;
    let x99 = 0.00000000000000011102230246251565 * x69;
    let x100 = 0.9999999999999999 * x97;
    let x101 = x99 + x100;
    let x102 = 0.00000000000000011102230246251565 * x68;
    let x103 = -x102;
    let x104 = x76 - x102;
    let x105 = -x84;
    let x106 = -x101;
    let x107 = -x104;
    let x109 = x91 + x99;
    let x110 = -x109;
    let x173 = 2.0 * qd[3];
    let x174 = 2.0 * qd[4];
    let x175 = 2.0 * qd[5];
    let x176 = 2.0 * qd[6];
    let x177 = qd[3] * x173;
    let x178 = qd[4] * x174;
    let x179 = qd[5] * x175;
    let x180 = qd[6] * x176;
    let x181 = x177 + x178;
    let x182 = 2.0 * x181;
    let x183 = x177 + x179;
    let x184 = 2.0 * x183;
    let x185 = qd[4] * qd[5];
    let x186 = x185 + x185;
    let x187 = 2.0 * x186;
    let x188 = qd[3] * qd[6];
    let x189 = x188 + x188;
    let x190 = 2.0 * x189;
    let x192 = x187 - x190;
    let x193 = qd[4] * qd[6];
    let x194 = x193 + x193;
    let x195 = 2.0 * x194;
    let x196 = qd[3] * qd[5];
    let x197 = x196 + x196;
    let x198 = 2.0 * x197;
    let x199 = x187 + x190;
    let x200 = qd[5] * qd[6];
    let x201 = x200 + x200;
    let x202 = 2.0 * x201;
    let x203 = qd[3] * qd[4];
    let x204 = x203 + x203;
    let x205 = 2.0 * x204;
    let x207 = x195 - x198;
    let x208 = x202 + x205;
    let x209 = 0.00000000000000011102230246251565 * x182;
    let x210 = 0.9999999999999999 * x192;
    let x211 = x209 + x210;
    let x212 = 0.00000000000000011102230246251565 * x199;
    let x213 = 0.9999999999999999 * x184;
    let x214 = x212 + x213;
    let x215 = 0.00000000000000011102230246251565 * x207;
    let x216 = 0.9999999999999999 * x208;
    let x217 = x215 + x216;
    let x221 = x179 + x181;
    let x222 = x180 + x221;
    let x223 = -x222;
    phi[0] = x62;
    phi_q[0] = -1.0;
    phi_q[1] = x86;
    phi_q[2] = x95;
    phi_q[3] = x105;
    phi_q[4] = x93;
    phi_t[0] = 0.0;
    gamma[0] = x211;
    phi[1] = x63;
    phi_q[5] = -1.0;
    phi_q[6] = x87;
    phi_q[7] = x83;
    phi_q[8] = x106;
    phi_q[9] = x103;
    phi_t[1] = 0.0;
    gamma[1] = x214;
    phi[2] = x64;
    phi_q[10] = -1.0;
    phi_q[11] = x88;
    phi_q[12] = x96;
    phi_q[13] = x107;
    phi_q[14] = x110;
    phi_t[2] = 0.0;
    gamma[2] = x217;
    phi[3] = x67;
    phi_q[15] = x68;
    phi_q[16] = x69;
    phi_q[17] = x70;
    phi_q[18] = x71;
    phi_t[3] = 0.0;
    gamma[3] = x223;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(q: &[f64], out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    potential_into_part_0(q, out);
}
#[inline(never)]
fn potential_into_part_0(q: &[f64; 7], out: &mut [f64; 1]) {
    let x228 = q[1] * 9.81;
    out[0] = x228;
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
pub const N_CONSTRAINTS: usize = 4usize;
/// Row of each Φq nonzero.
pub static PHI_Q_ROWS: [u32; 19usize] = [
    0u32, 0u32, 0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 1u32, 1u32, 2u32, 2u32, 2u32, 2u32,
    2u32, 3u32, 3u32, 3u32, 3u32,
];
/// Column of each Φq nonzero.
pub static PHI_Q_COLS: [u32; 19usize] = [
    0u32, 3u32, 4u32, 5u32, 6u32, 1u32, 3u32, 4u32, 5u32, 6u32, 2u32, 3u32, 4u32, 5u32,
    6u32, 3u32, 4u32, 5u32, 6u32,
];
/// Bodies in coordinate order.
pub static BODIES: [BodyInfo; 1usize] = [
    BodyInfo {
        name: "bob",
        coord_offset: 0usize,
        rotation: Rotation::Quaternion,
        mass: 1f64,
        inertia: [0.05f64, 0.01f64, 0.05f64],
    },
];
/// Joints in row order, then drivers.
pub static JOINTS: [JointInfo; 2usize] = [
    JointInfo {
        name: "pivot",
        kind: JointKind::Spherical,
        body1: None,
        body2: Some(0usize),
        row_start: 0usize,
        rows: 3usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0.00000000000000011102230246251565f64, 0.9999999999999999f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
    JointInfo {
        name: "bob.norm",
        kind: JointKind::Normalization,
        body1: Some(0usize),
        body2: None,
        row_start: 3usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
];
/// Name of each coordinate.
pub static COORD_NAMES: [&str; 7usize] = [
    "bob.x",
    "bob.y",
    "bob.z",
    "bob.e0",
    "bob.e1",
    "bob.e2",
    "bob.e3",
];
/// Name of each constraint row.
pub static ROW_NAMES: [&str; 4usize] = ["pivot.x", "pivot.y", "pivot.z", "bob.norm"];
/// Initial coordinates: the file's pose, assembled.
pub static Q0: [f64; 7usize] = [
    0.7071067811865475f64,
    -0.7071067811865476f64,
    0f64,
    0.9238795325112867f64,
    0f64,
    0f64,
    0.3826834323650897f64,
];
/// Initial velocities from the file (to be projected onto the constraints).
pub static QD0: [f64; 7usize] = [
    0f64,
    0f64,
    -2.582618960593183f64,
    -0f64,
    0.6988516548183277f64,
    1.6871771431492877f64,
    0f64,
];
/// Constraint rows dependent on others at the initial pose (dropped by the solvers).
pub static REDUNDANT_ROWS: [u32; 0usize] = [];
/// Simulation end time suggested by the mechanism file (s).
pub const T_END: f64 = 60f64;
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
        name: "spherical_pendulum",
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
        let x68 = q[3] * 2.0;
        let x69 = q[4] * 2.0;
        let x70 = q[5] * 2.0;
        let x71 = q[6] * 2.0;
        let x72 = 2.0 * x68;
        let x89 = 2.0 * x69;
        let x97 = 2.0 * x70;
        let x336 = 2.0 * x71;
        let x338 = x69 * x89;
        let x340 = 0.05 * x338;
        let x342 = x70 * x97;
        let x344 = 0.01 * x342;
        let x346 = x71 * x336;
        let x348 = 0.05 * x346;
        let x350 = x340 + x344;
        let x352 = x348 + x350;
        let x354 = 0.5 * x352;
        let x356 = x9 * 0.1466666666666667;
        let x357 = x354 + x356;
        let x358 = x69 * x72;
        let x359 = 0.05 * x358;
        let x360 = x70 * x336;
        let x362 = 0.01 * x360;
        let x364 = x71 * x97;
        let x365 = 0.05 * x364;
        let x366 = x359 - x362;
        let x367 = x365 + x366;
        let x368 = 0.5 * x367;
        let x370 = x38 * 0.1466666666666667;
        let x371 = x370 - x368;
        let x372 = x69 * x336;
        let x373 = 0.05 * x372;
        let x374 = x70 * x72;
        let x375 = 0.01 * x374;
        let x376 = x71 * x89;
        let x378 = 0.05 * x376;
        let x380 = x373 + x375;
        let x381 = x380 - x378;
        let x382 = 0.5 * x381;
        let x384 = x32 * 0.1466666666666667;
        let x385 = x384 - x382;
        let x386 = x69 * x97;
        let x388 = 0.05 * x386;
        let x390 = x70 * x89;
        let x391 = 0.01 * x390;
        let x392 = x71 * x72;
        let x393 = 0.05 * x392;
        let x394 = x391 - x388;
        let x395 = x393 + x394;
        let x396 = 0.5 * x395;
        let x398 = x25 * 0.1466666666666667;
        let x399 = x398 - x396;
        let x400 = x68 * x89;
        let x402 = 0.05 * x400;
        let x405 = 0.01 * x364;
        let x407 = 0.05 * x360;
        let x409 = x405 - x402;
        let x410 = x409 - x407;
        let x411 = 0.5 * x410;
        let x412 = x370 + x411;
        let x413 = x68 * x72;
        let x414 = 0.05 * x413;
        let x415 = 0.01 * x346;
        let x417 = 0.05 * x342;
        let x418 = x414 + x415;
        let x419 = x417 + x418;
        let x420 = 0.5 * x419;
        let x421 = x10 * 0.1466666666666667;
        let x422 = x420 + x421;
        let x423 = x68 * x336;
        let x424 = 0.05 * x423;
        let x425 = 0.01 * x392;
        let x428 = 0.05 * x390;
        let x430 = x424 - x425;
        let x431 = x430 - x428;
        let x432 = 0.5 * x431;
        let x433 = x23 * 0.1466666666666667;
        let x434 = x432 + x433;
        let x435 = x68 * x97;
        let x437 = 0.05 * x435;
        let x439 = 0.01 * x376;
        let x441 = 0.05 * x374;
        let x442 = x437 + x439;
        let x444 = x441 - x442;
        let x445 = 0.5 * x444;
        let x446 = x30 * 0.1466666666666667;
        let x447 = x445 + x446;
        let x448 = 0.01 * x435;
        let x452 = x378 + x448;
        let x454 = x373 - x452;
        let x455 = 0.5 * x454;
        let x456 = x384 + x455;
        let x458 = 0.01 * x423;
        let x460 = x393 - x458;
        let x461 = x460 - x388;
        let x462 = 0.5 * x461;
        let x463 = x433 + x462;
        let x464 = 0.01 * x413;
        let x465 = x348 + x464;
        let x466 = x340 + x465;
        let x467 = 0.5 * x466;
        let x468 = x11 * 0.1466666666666667;
        let x469 = x467 + x468;
        let x471 = 0.01 * x400;
        let x473 = x471 - x365;
        let x474 = x473 - x359;
        let x475 = 0.5 * x474;
        let x476 = x36 * 0.1466666666666667;
        let x477 = x475 + x476;
        let x478 = 0.01 * x386;
        let x481 = x428 - x478;
        let x482 = x481 - x424;
        let x483 = 0.5 * x482;
        let x484 = x398 + x483;
        let x486 = 0.01 * x372;
        let x488 = x441 + x486;
        let x490 = x437 - x488;
        let x491 = 0.5 * x490;
        let x492 = x446 + x491;
        let x493 = 0.01 * x358;
        let x494 = x493 - x407;
        let x495 = x494 - x402;
        let x496 = 0.5 * x495;
        let x497 = x476 + x496;
        let x499 = 0.01 * x338;
        let x500 = x417 + x499;
        let x501 = x414 + x500;
        let x502 = 0.5 * x501;
        let x503 = x12 * 0.1466666666666667;
        let x504 = x502 + x503;
        out[0] = 1.0;
        out[1] = 1.0;
        out[2] = 1.0;
        out[3] = x357;
        out[4] = x371;
        out[5] = x385;
        out[6] = x399;
        out[7] = x412;
        out[8] = x422;
        out[9] = x434;
        out[10] = x447;
        out[11] = x456;
        out[12] = x463;
        out[13] = x469;
        out[14] = x477;
        out[15] = x484;
        out[16] = x492;
        out[17] = x497;
        out[18] = x504;
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
        let x68 = q[3] * 2.0;
        let x69 = q[4] * 2.0;
        let x70 = q[5] * 2.0;
        let x71 = q[6] * 2.0;
        let x126 = q[5] * qd[4];
        let x127 = q[4] * qd[5];
        let x130 = q[6] * qd[3];
        let x131 = q[3] * qd[6];
        let x136 = q[6] * qd[4];
        let x137 = q[4] * qd[6];
        let x140 = q[5] * qd[3];
        let x141 = q[3] * qd[5];
        let x145 = q[6] * qd[5];
        let x146 = q[5] * qd[6];
        let x149 = q[4] * qd[3];
        let x150 = q[3] * qd[4];
        let x173 = 2.0 * qd[3];
        let x174 = 2.0 * qd[4];
        let x175 = 2.0 * qd[5];
        let x176 = 2.0 * qd[6];
        let x185 = qd[4] * qd[5];
        let x188 = qd[3] * qd[6];
        let x193 = qd[4] * qd[6];
        let x196 = qd[3] * qd[5];
        let x232 = x150 - x149;
        let x233 = x145 + x232;
        let x234 = x233 - x146;
        let x235 = 2.0 * x234;
        let x238 = x136 + x140;
        let x240 = x141 - x238;
        let x241 = x137 + x240;
        let x242 = 2.0 * x241;
        let x245 = x126 - x130;
        let x246 = x245 - x127;
        let x247 = x131 + x246;
        let x248 = 2.0 * x247;
        let x265 = 2.0 * x235;
        let x267 = 2.0 * x242;
        let x269 = 2.0 * x248;
        let x507 = x193 + x196;
        let x509 = x196 - x507;
        let x510 = x193 + x509;
        let x511 = 2.0 * x510;
        let x514 = x185 - x188;
        let x515 = x514 - x185;
        let x516 = x188 + x515;
        let x517 = 2.0 * x516;
        let x518 = 2.0 * x511;
        let x519 = 2.0 * x517;
        let x520 = x174 * x265;
        let x521 = 0.05 * x520;
        let x522 = x175 * x267;
        let x523 = x70 * x518;
        let x524 = x522 + x523;
        let x525 = 0.01 * x524;
        let x526 = x176 * x269;
        let x527 = x71 * x519;
        let x528 = x526 + x527;
        let x529 = 0.05 * x528;
        let x530 = x521 + x525;
        let x531 = x529 + x530;
        let x532 = 0.5 * x531;
        let x534 = x173 * x265;
        let x535 = 0.05 * x534;
        let x536 = x176 * x267;
        let x537 = x71 * x518;
        let x538 = x536 + x537;
        let x539 = 0.01 * x538;
        let x541 = x175 * x269;
        let x542 = x70 * x519;
        let x543 = x541 + x542;
        let x544 = 0.05 * x543;
        let x545 = x535 - x539;
        let x546 = x544 + x545;
        let x547 = 0.5 * x546;
        let x548 = x176 * x265;
        let x549 = 0.05 * x548;
        let x550 = x173 * x267;
        let x551 = x68 * x518;
        let x552 = x550 + x551;
        let x553 = 0.01 * x552;
        let x554 = x174 * x269;
        let x555 = x69 * x519;
        let x556 = x554 + x555;
        let x557 = 0.05 * x556;
        let x559 = x549 + x553;
        let x560 = x559 - x557;
        let x561 = 0.5 * x560;
        let x562 = x175 * x265;
        let x563 = 0.05 * x562;
        let x565 = x174 * x267;
        let x566 = x69 * x518;
        let x567 = x565 + x566;
        let x568 = 0.01 * x567;
        let x569 = x173 * x269;
        let x570 = x68 * x519;
        let x571 = x569 + x570;
        let x572 = 0.05 * x571;
        let x573 = x568 - x563;
        let x574 = x572 + x573;
        let x575 = 0.5 * x574;
        let x576 = qd[3] * qd[3];
        let x577 = qd[4] * qd[4];
        let x578 = qd[5] * qd[5];
        let x579 = qd[6] * qd[6];
        let x580 = x576 + x577;
        let x581 = x578 + x580;
        let x582 = x579 + x581;
        let x583 = 0.01 * x522;
        let x584 = 0.05 * x526;
        let x585 = x521 + x583;
        let x586 = x584 + x585;
        let x587 = 0.5 * x586;
        let x588 = x532 + x587;
        let x589 = q[3] * 0.1466666666666667;
        let x590 = x582 * x589;
        let x592 = x588 - x590;
        let x599 = 0.01 * x536;
        let x601 = 0.05 * x541;
        let x603 = x599 - x535;
        let x604 = x603 - x601;
        let x605 = 0.5 * x604;
        let x607 = x605 - x547;
        let x608 = q[4] * 0.1466666666666667;
        let x609 = x582 * x608;
        let x611 = x607 - x609;
        let x617 = 0.01 * x550;
        let x619 = 0.05 * x554;
        let x620 = x549 + x617;
        let x622 = x619 - x620;
        let x623 = 0.5 * x622;
        let x625 = x623 - x561;
        let x626 = q[5] * 0.1466666666666667;
        let x627 = x582 * x626;
        let x629 = x625 - x627;
        let x633 = 0.01 * x565;
        let x636 = 0.05 * x569;
        let x638 = x563 - x633;
        let x639 = x638 - x636;
        let x640 = 0.5 * x639;
        let x642 = x640 - x575;
        let x643 = q[6] * 0.1466666666666667;
        let x644 = x582 * x643;
        let x646 = x642 - x644;
        out[0] = 0.0;
        out[1] = -9.81;
        out[2] = 0.0;
        out[3] = x592;
        out[4] = x611;
        out[5] = x629;
        out[6] = x646;
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
        let phi: &mut [f64; 4] = phi.try_into().expect("phi must have 4 entries");
        let phi_q: &mut [f64; 19] = phi_q
            .try_into()
            .expect("phi_q must have 19 entries");
        let mass: &mut [f64; 19] = mass.try_into().expect("mass must have 19 entries");
        let force: &mut [f64; 7] = force.try_into().expect("force must have 7 entries");
        let _ = t;
        eval_newton_part_0(q, qd, phi, phi_q, mass, force);
    }
    #[inline(never)]
    fn eval_newton_part_0(
        q: &[f64; 7],
        qd: &[f64; 7],
        phi: &mut [f64; 4],
        phi_q: &mut [f64; 19],
        mass: &mut [f64; 19],
        force: &mut [f64; 7],
    ) {
        let x9 = q[3] * q[3];
        let x10 = q[4] * q[4];
        let x11 = q[5] * q[5];
        let x12 = q[6] * q[6];
        let x13 = x9 + x10;
        let x14 = 2.0 * x13;
        let x16 = x14 - 1.0;
        let x17 = x9 + x11;
        let x18 = 2.0 * x17;
        let x19 = x18 - 1.0;
        let x23 = q[4] * q[5];
        let x24 = 2.0 * x23;
        let x25 = q[3] * q[6];
        let x27 = 2.0 * x25;
        let x29 = x24 - x27;
        let x30 = q[4] * q[6];
        let x31 = 2.0 * x30;
        let x32 = q[3] * q[5];
        let x33 = 2.0 * x32;
        let x35 = x24 + x27;
        let x36 = q[5] * q[6];
        let x37 = 2.0 * x36;
        let x38 = q[3] * q[4];
        let x40 = 2.0 * x38;
        let x45 = x31 - x33;
        let x46 = x37 + x40;
        let x50 = x16 * 0.00000000000000011102230246251565;
        let x51 = x29 * 0.9999999999999999;
        let x52 = x50 + x51;
        let x53 = x35 * 0.00000000000000011102230246251565;
        let x54 = x19 * 0.9999999999999999;
        let x55 = x53 + x54;
        let x56 = x45 * 0.00000000000000011102230246251565;
        let x57 = x46 * 0.9999999999999999;
        let x58 = x56 + x57;
        let x59 = q[0] + x52;
        let x60 = q[1] + x55;
        let x61 = q[2] + x58;
        let x62 = -x59;
        let x63 = -x60;
        let x64 = -x61;
        let x65 = x11 + x13;
        let x66 = x12 + x65;
        let x67 = x66 - 1.0;
        let x68 = q[3] * 2.0;
        let x69 = q[4] * 2.0;
        let x70 = q[5] * 2.0;
        let x71 = q[6] * 2.0;
        let x72 = 2.0 * x68;
        let x75 = 0.00000000000000011102230246251565 * x72;
        let x76 = 0.9999999999999999 * x71;
        let x78 = x75 - x76;
        let x79 = 0.00000000000000011102230246251565 * x71;
        let x80 = 0.9999999999999999 * x72;
        let x81 = x79 + x80;
        let x82 = 0.00000000000000011102230246251565 * x70;
        let x83 = -x82;
        let x84 = 0.9999999999999999 * x69;
        let x85 = x84 - x82;
        let x86 = -x78;
        let x87 = -x81;
        let x88 = -x85;
        let x89 = 2.0 * x69;
        let x90 = 0.00000000000000011102230246251565 * x89;
        let x91 = 0.9999999999999999 * x70;
        let x92 = x90 + x91;
        let x93 = 0.9999999999999999 * x68;
        let x94 = x79 + x93;
        let x95 = -x92;
        let x96 = -x94;
        let x97 = 2.0 * x70;
        let x99 = 0.00000000000000011102230246251565 * x69;
        let x100 = 0.9999999999999999 * x97;
        let x101 = x99 + x100;
        let x102 = 0.00000000000000011102230246251565 * x68;
        let x103 = -x102;
        let x104 = x76 - x102;
        let x105 = -x84;
        let x106 = -x101;
        let x107 = -x104;
        let x109 = x91 + x99;
        let x110 = -x109;
        let x126 = q[5] * qd[4];
        let x127 = q[4] * qd[5];
        let x130 = q[6] * qd[3];
        let x131 = q[3] * qd[6];
        let x136 = q[6] * qd[4];
        let x137 = q[4] * qd[6];
        let x140 = q[5] * qd[3];
        let x141 = q[3] * qd[5];
        let x145 = q[6] * qd[5];
        let x146 = q[5] * qd[6];
        let x149 = q[4] * qd[3];
        let x150 = q[3] * qd[4];
        let x173 = 2.0 * qd[3];
        let x174 = 2.0 * qd[4];
        let x175 = 2.0 * qd[5];
        let x176 = 2.0 * qd[6];
        let x185 = qd[4] * qd[5];
        let x188 = qd[3] * qd[6];
        let x193 = qd[4] * qd[6];
        let x196 = qd[3] * qd[5];
        let x232 = x150 - x149;
        let x233 = x145 + x232;
        let x234 = x233 - x146;
        let x235 = 2.0 * x234;
        let x238 = x136 + x140;
        let x240 = x141 - x238;
        let x241 = x137 + x240;
        let x242 = 2.0 * x241;
        let x245 = x126 - x130;
        let x246 = x245 - x127;
        let x247 = x131 + x246;
        let x248 = 2.0 * x247;
        let x265 = 2.0 * x235;
        let x267 = 2.0 * x242;
        let x269 = 2.0 * x248;
        let x336 = 2.0 * x71;
        let x338 = x69 * x89;
        let x340 = 0.05 * x338;
        let x342 = x70 * x97;
        let x344 = 0.01 * x342;
        let x346 = x71 * x336;
        let x348 = 0.05 * x346;
        let x350 = x340 + x344;
        let x352 = x348 + x350;
        let x354 = 0.5 * x352;
        let x356 = x9 * 0.1466666666666667;
        let x357 = x354 + x356;
        let x358 = x69 * x72;
        let x359 = 0.05 * x358;
        let x360 = x70 * x336;
        let x362 = 0.01 * x360;
        let x364 = x71 * x97;
        let x365 = 0.05 * x364;
        let x366 = x359 - x362;
        let x367 = x365 + x366;
        let x368 = 0.5 * x367;
        let x370 = x38 * 0.1466666666666667;
        let x371 = x370 - x368;
        let x372 = x69 * x336;
        let x373 = 0.05 * x372;
        let x374 = x70 * x72;
        let x375 = 0.01 * x374;
        let x376 = x71 * x89;
        let x378 = 0.05 * x376;
        let x380 = x373 + x375;
        let x381 = x380 - x378;
        let x382 = 0.5 * x381;
        let x384 = x32 * 0.1466666666666667;
        let x385 = x384 - x382;
        let x386 = x69 * x97;
        let x388 = 0.05 * x386;
        let x390 = x70 * x89;
        let x391 = 0.01 * x390;
        let x392 = x71 * x72;
        let x393 = 0.05 * x392;
        let x394 = x391 - x388;
        let x395 = x393 + x394;
        let x396 = 0.5 * x395;
        let x398 = x25 * 0.1466666666666667;
        let x399 = x398 - x396;
        let x400 = x68 * x89;
        let x402 = 0.05 * x400;
        let x405 = 0.01 * x364;
        let x407 = 0.05 * x360;
        let x409 = x405 - x402;
        let x410 = x409 - x407;
        let x411 = 0.5 * x410;
        let x412 = x370 + x411;
        let x413 = x68 * x72;
        let x414 = 0.05 * x413;
        let x415 = 0.01 * x346;
        let x417 = 0.05 * x342;
        let x418 = x414 + x415;
        let x419 = x417 + x418;
        let x420 = 0.5 * x419;
        let x421 = x10 * 0.1466666666666667;
        let x422 = x420 + x421;
        let x423 = x68 * x336;
        let x424 = 0.05 * x423;
        let x425 = 0.01 * x392;
        let x428 = 0.05 * x390;
        let x430 = x424 - x425;
        let x431 = x430 - x428;
        let x432 = 0.5 * x431;
        let x433 = x23 * 0.1466666666666667;
        let x434 = x432 + x433;
        let x435 = x68 * x97;
        let x437 = 0.05 * x435;
        let x439 = 0.01 * x376;
        let x441 = 0.05 * x374;
        let x442 = x437 + x439;
        let x444 = x441 - x442;
        let x445 = 0.5 * x444;
        let x446 = x30 * 0.1466666666666667;
        let x447 = x445 + x446;
        let x448 = 0.01 * x435;
        let x452 = x378 + x448;
        let x454 = x373 - x452;
        let x455 = 0.5 * x454;
        let x456 = x384 + x455;
        let x458 = 0.01 * x423;
        let x460 = x393 - x458;
        let x461 = x460 - x388;
        let x462 = 0.5 * x461;
        let x463 = x433 + x462;
        let x464 = 0.01 * x413;
        let x465 = x348 + x464;
        let x466 = x340 + x465;
        let x467 = 0.5 * x466;
        let x468 = x11 * 0.1466666666666667;
        let x469 = x467 + x468;
        let x471 = 0.01 * x400;
        let x473 = x471 - x365;
        let x474 = x473 - x359;
        let x475 = 0.5 * x474;
        let x476 = x36 * 0.1466666666666667;
        let x477 = x475 + x476;
        let x478 = 0.01 * x386;
        let x481 = x428 - x478;
        let x482 = x481 - x424;
        let x483 = 0.5 * x482;
        let x484 = x398 + x483;
        let x486 = 0.01 * x372;
        let x488 = x441 + x486;
        let x490 = x437 - x488;
        let x491 = 0.5 * x490;
        let x492 = x446 + x491;
        let x493 = 0.01 * x358;
        let x494 = x493 - x407;
        let x495 = x494 - x402;
        let x496 = 0.5 * x495;
        let x497 = x476 + x496;
        let x499 = 0.01 * x338;
        let x500 = x417 + x499;
        let x501 = x414 + x500;
        let x502 = 0.5 * x501;
        let x503 = x12 * 0.1466666666666667;
        let x504 = x502 + x503;
        let x507 = x193 + x196;
        let x509 = x196 - x507;
        let x510 = x193 + x509;
        let x511 = 2.0 * x510;
        let x514 = x185 - x188;
        let x515 = x514 - x185;
        let x516 = x188 + x515;
        let x517 = 2.0 * x516;
        let x518 = 2.0 * x511;
        let x519 = 2.0 * x517;
        let x520 = x174 * x265;
        let x521 = 0.05 * x520;
        let x522 = x175 * x267;
        let x523 = x70 * x518;
        let x524 = x522 + x523;
        let x525 = 0.01 * x524;
        let x526 = x176 * x269;
        let x527 = x71 * x519;
        let x528 = x526 + x527;
        let x529 = 0.05 * x528;
        let x530 = x521 + x525;
        let x531 = x529 + x530;
        let x532 = 0.5 * x531;
        let x534 = x173 * x265;
        let x535 = 0.05 * x534;
        let x536 = x176 * x267;
        let x537 = x71 * x518;
        let x538 = x536 + x537;
        let x539 = 0.01 * x538;
        let x541 = x175 * x269;
        let x542 = x70 * x519;
        let x543 = x541 + x542;
        let x544 = 0.05 * x543;
        let x545 = x535 - x539;
        let x546 = x544 + x545;
        let x547 = 0.5 * x546;
        let x548 = x176 * x265;
        let x549 = 0.05 * x548;
        let x550 = x173 * x267;
        let x551 = x68 * x518;
        let x552 = x550 + x551;
        let x553 = 0.01 * x552;
        let x554 = x174 * x269;
        let x555 = x69 * x519;
        let x556 = x554 + x555;
        let x557 = 0.05 * x556;
        let x559 = x549 + x553;
        let x560 = x559 - x557;
        let x561 = 0.5 * x560;
        let x562 = x175 * x265;
        let x563 = 0.05 * x562;
        let x565 = x174 * x267;
        let x566 = x69 * x518;
        let x567 = x565 + x566;
        let x568 = 0.01 * x567;
        let x569 = x173 * x269;
        let x570 = x68 * x519;
        let x571 = x569 + x570;
        let x572 = 0.05 * x571;
        let x573 = x568 - x563;
        let x574 = x572 + x573;
        let x575 = 0.5 * x574;
        let x576 = qd[3] * qd[3];
        let x577 = qd[4] * qd[4];
        let x578 = qd[5] * qd[5];
        let x579 = qd[6] * qd[6];
        let x580 = x576 + x577;
        let x581 = x578 + x580;
        let x582 = x579 + x581;
        let x583 = 0.01 * x522;
        let x584 = 0.05 * x526;
        let x585 = x521 + x583;
        let x586 = x584 + x585;
        let x587 = 0.5 * x586;
        let x588 = x532 + x587;
        let x589 = q[3] * 0.1466666666666667;
        let x590 = x582 * x589;
        let x592 = x588 - x590;
        let x599 = 0.01 * x536;
        let x601 = 0.05 * x541;
        let x603 = x599 - x535;
        let x604 = x603 - x601;
        let x605 = 0.5 * x604;
        let x607 = x605 - x547;
        let x608 = q[4] * 0.1466666666666667;
        let x609 = x582 * x608;
        let x611 = x607 - x609;
        let x617 = 0.01 * x550;
        let x619 = 0.05 * x554;
        let x620 = x549 + x617;
        let x622 = x619 - x620;
        let x623 = 0.5 * x622;
        let x625 = x623 - x561;
        let x626 = q[5] * 0.1466666666666667;
        let x627 = x582 * x626;
        let x629 = x625 - x627;
        let x633 = 0.01 * x565;
        let x636 = 0.05 * x569;
        let x638 = x563 - x633;
        let x639 = x638 - x636;
        let x640 = 0.5 * x639;
        let x642 = x640 - x575;
        let x643 = q[6] * 0.1466666666666667;
        let x644 = x582 * x643;
        let x646 = x642 - x644;
        phi[0] = x62;
        phi_q[0] = -1.0;
        phi_q[1] = x86;
        phi_q[2] = x95;
        phi_q[3] = x105;
        phi_q[4] = x93;
        phi[1] = x63;
        phi_q[5] = -1.0;
        phi_q[6] = x87;
        phi_q[7] = x83;
        phi_q[8] = x106;
        phi_q[9] = x103;
        phi[2] = x64;
        phi_q[10] = -1.0;
        phi_q[11] = x88;
        phi_q[12] = x96;
        phi_q[13] = x107;
        phi_q[14] = x110;
        phi[3] = x67;
        phi_q[15] = x68;
        phi_q[16] = x69;
        phi_q[17] = x70;
        phi_q[18] = x71;
        mass[0] = 1.0;
        mass[1] = 1.0;
        mass[2] = 1.0;
        mass[3] = x357;
        mass[4] = x371;
        mass[5] = x385;
        mass[6] = x399;
        mass[7] = x412;
        mass[8] = x422;
        mass[9] = x434;
        mass[10] = x447;
        mass[11] = x456;
        mass[12] = x463;
        mass[13] = x469;
        mass[14] = x477;
        mass[15] = x484;
        mass[16] = x492;
        mass[17] = x497;
        mass[18] = x504;
        force[0] = 0.0;
        force[1] = -9.81;
        force[2] = 0.0;
        force[3] = x592;
        force[4] = x611;
        force[5] = x629;
        force[6] = x646;
    }
}
/// `spherical_pendulum` with the `exact` formulation.
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
    name: "spherical_pendulum",
    t_end: T_END,
    formulations: &[(Formulation::Exact, &Exact as &(dyn Mechanism + Sync))],
    reduced: None,
    origin: Origin::Compiled {
        file: concat!(
            env!("CARGO_MANIFEST_DIR"), "/../../../",
            "mechanisms/spherical_pendulum.toml"
        ),
        hash: 11312270152100685384u64,
        parameters: &[],
    },
    run_time: None,
};
