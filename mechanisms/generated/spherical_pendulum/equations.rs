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
use symbody_runtime::parameters::{ParameterError, RunTimeParameters};
/// Constraint residual Φ(q, t).
pub fn phi(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    let _ = t;
    phi_part_0(k, q, out);
}
#[inline(never)]
fn phi_part_0(k: &[f64; 8], q: &[f64; 7], out: &mut [f64; 4]) {
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
    let x65 = x11 + x13;
    let x66 = x12 + x65;
    let x67 = x66 - 1.0;
    let x666 = x16 * k[0];
    let x667 = x29 * k[1];
    let x668 = x666 + x667;
    let x669 = x35 * k[0];
    let x670 = x19 * k[1];
    let x671 = x669 + x670;
    let x672 = x45 * k[0];
    let x673 = x46 * k[1];
    let x674 = x672 + x673;
    let x675 = q[0] + x668;
    let x676 = q[1] + x671;
    let x677 = q[2] + x674;
    let x678 = -x675;
    let x679 = -x676;
    let x680 = -x677;
    out[0] = x678;
    out[1] = x679;
    out[2] = x680;
    out[3] = x67;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
    let _ = t;
    phi_q_part_0(k, q, out);
}
#[inline(never)]
fn phi_q_part_0(k: &[f64; 8], q: &[f64; 7], out: &mut [f64; 19]) {
    let x68 = q[3] * 2.0;
    let x69 = q[4] * 2.0;
    let x70 = q[5] * 2.0;
    let x71 = q[6] * 2.0;
    let x72 = 2.0 * x68;
    let x89 = 2.0 * x69;
    let x97 = 2.0 * x70;
    let x681 = x72 * k[0];
    let x682 = x71 * k[1];
    let x684 = x681 - x682;
    let x685 = x71 * k[0];
    let x686 = x72 * k[1];
    let x687 = x685 + x686;
    let x688 = x70 * k[0];
    let x689 = -x688;
    let x690 = x69 * k[1];
    let x691 = x690 - x688;
    let x692 = -x684;
    let x693 = -x687;
    let x694 = -x691;
    let x695 = x89 * k[0];
    let x696 = x70 * k[1];
    let x697 = x695 + x696;
    let x698 = x68 * k[1];
    let x699 = x685 + x698;
    let x700 = -x697;
    let x701 = -x699;
    let x702 = x69 * k[0];
    let x703 = x97 * k[1];
    let x704 = x702 + x703;
    let x705 = x68 * k[0];
    let x706 = -x705;
    let x707 = x682 - x705;
    let x708 = -x690;
    let x709 = -x704;
    let x710 = -x707;
    let x711 = x696 + x702;
    let x712 = -x711;
    out[0] = -1.0;
    out[1] = x692;
    out[2] = x700;
    out[3] = x708;
    out[4] = x698;
    out[5] = -1.0;
    out[6] = x693;
    out[7] = x689;
    out[8] = x709;
    out[9] = x706;
    out[10] = -1.0;
    out[11] = x694;
    out[12] = x701;
    out[13] = x710;
    out[14] = x712;
    out[15] = x68;
    out[16] = x69;
    out[17] = x70;
    out[18] = x71;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    let _ = k;
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
pub fn gamma(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    let _ = q;
    let _ = t;
    gamma_part_0(k, qd, out);
}
#[inline(never)]
fn gamma_part_0(k: &[f64; 8], qd: &[f64; 7], out: &mut [f64; 4]) {
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
    let x221 = x179 + x181;
    let x222 = x180 + x221;
    let x223 = -x222;
    let x713 = x182 * k[0];
    let x714 = x192 * k[1];
    let x715 = x713 + x714;
    let x716 = x199 * k[0];
    let x717 = x184 * k[1];
    let x718 = x716 + x717;
    let x719 = x207 * k[0];
    let x720 = x208 * k[1];
    let x721 = x719 + x720;
    out[0] = x715;
    out[1] = x718;
    out[2] = x721;
    out[3] = x223;
}
/// Φ, Φq, Φt and γ at one state in one pass, sharing every subexpression.
pub fn eval_kinematics(
    k: &[f64],
    q: &[f64],
    qd: &[f64],
    t: f64,
    phi: &mut [f64],
    phi_q: &mut [f64],
    phi_t: &mut [f64],
    gamma: &mut [f64],
) {
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let phi: &mut [f64; 4] = phi.try_into().expect("phi must have 4 entries");
    let phi_q: &mut [f64; 19] = phi_q.try_into().expect("phi_q must have 19 entries");
    let phi_t: &mut [f64; 4] = phi_t.try_into().expect("phi_t must have 4 entries");
    let gamma: &mut [f64; 4] = gamma.try_into().expect("gamma must have 4 entries");
    let _ = t;
    eval_kinematics_part_0(k, q, qd, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_part_0(
    k: &[f64; 8],
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
    let x65 = x11 + x13;
    let x66 = x12 + x65;
    let x67 = x66 - 1.0;
    let x68 = q[3] * 2.0;
    let x69 = q[4] * 2.0;
    let x70 = q[5] * 2.0;
    let x71 = q[6] * 2.0;
    let x72 = 2.0 * x68;
    let x89 = 2.0 * x69;
    let x97 = 2.0 * x70;
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
    let x221 = x179 + x181;
    let x222 = x180 + x221;
    let x223 = -x222;
    let x666 = x16 * k[0];
    let x667 = x29 * k[1];
    let x668 = x666 + x667;
    let x669 = x35 * k[0];
    let x670 = x19 * k[1];
    let x671 = x669 + x670;
    let x672 = x45 * k[0];
    let x673 = x46 * k[1];
    let x674 = x672 + x673;
    let x675 = q[0] + x668;
    let x676 = q[1] + x671;
    let x677 = q[2] + x674;
    let x678 = -x675;
    let x679 = -x676;
    let x680 = -x677;
    let x681 = x72 * k[0];
    let x682 = x71 * k[1];
    let x684 = x681 - x682;
    let x685 = x71 * k[0];
    let x686 = x72 * k[1];
    let x687 = x685 + x686;
    let x688 = x70 * k[0];
    let x689 = -x688;
    let x690 = x69 * k[1];
    let x691 = x690 - x688;
    let x692 = -x684;
    let x693 = -x687;
    let x694 = -x691;
    let x695 = x89 * k[0];
    let x696 = x70 * k[1];
    let x697 = x695 + x696;
    let x698 = x68 * k[1];
    let x699 = x685 + x698;
    let x700 = -x697;
    let x701 = -x699;
    let x702 = x69 * k[0];
    let x703 = x97 * k[1];
    let x704 = x702 + x703;
    let x705 = x68 * k[0];
    let x706 = -x705;
    let x707 = x682 - x705;
    let x708 = -x690;
    let x709 = -x704;
    let x710 = -x707;
    let x711 = x696 + x702;
    let x712 = -x711;
    let x713 = x182 * k[0];
    let x714 = x192 * k[1];
    let x715 = x713 + x714;
    let x716 = x199 * k[0];
    let x717 = x184 * k[1];
    let x718 = x716 + x717;
    let x719 = x207 * k[0];
    let x720 = x208 * k[1];
    let x721 = x719 + x720;
    phi[0] = x678;
    phi_q[0] = -1.0;
    phi_q[1] = x692;
    phi_q[2] = x700;
    phi_q[3] = x708;
    phi_q[4] = x698;
    phi_t[0] = 0.0;
    gamma[0] = x715;
    phi[1] = x679;
    phi_q[5] = -1.0;
    phi_q[6] = x693;
    phi_q[7] = x689;
    phi_q[8] = x709;
    phi_q[9] = x706;
    phi_t[1] = 0.0;
    gamma[1] = x718;
    phi[2] = x680;
    phi_q[10] = -1.0;
    phi_q[11] = x694;
    phi_q[12] = x701;
    phi_q[13] = x710;
    phi_q[14] = x712;
    phi_t[2] = 0.0;
    gamma[2] = x721;
    phi[3] = x67;
    phi_q[15] = x68;
    phi_q[16] = x69;
    phi_q[17] = x70;
    phi_q[18] = x71;
    phi_t[3] = 0.0;
    gamma[3] = x223;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    potential_into_part_0(k, q, out);
}
#[inline(never)]
fn potential_into_part_0(k: &[f64; 8], q: &[f64; 7], out: &mut [f64; 1]) {
    let x726 = q[1] * k[4];
    out[0] = x726;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
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
pub const N_K: usize = 8;
/// `setup` at the file's parameter values: what the types without parameters read.
pub static K: [f64; 8] = [
    0.00000000000000011102230246251565f64,
    0.9999999999999999f64,
    0.01f64,
    0.05f64,
    9.81f64,
    -9.81f64,
    0.14666666666666667f64,
    1f64,
];
/// The values the per-step functions read (`k`), from the run-time parameters `p`.
pub fn setup(p: &[f64], k: &mut [f64]) {
    let p: &[f64; 10] = p.try_into().expect("p must have 10 entries");
    let k: &mut [f64; 8] = k.try_into().expect("k must have 8 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 10], k: &mut [f64; 8]) {
    let x234 = p[3] * 9.81;
    let x235 = -x234;
    let x342 = p[0] + p[1];
    let x343 = p[1] + x342;
    let x346 = x343 * 4.0;
    let x348 = x346 * 0.3333333333333333;
    let x349 = 2.0 * p[3];
    let x350 = 0.5 * x349;
    k[0] = p[8];
    k[1] = p[9];
    k[2] = p[0];
    k[3] = p[1];
    k[4] = x234;
    k[5] = x235;
    k[6] = x348;
    k[7] = x350;
}
/// The parameters the generated code takes at run time by name: the file's
/// `[parameters]` entries that reach only masses, inertias and springs' constants.
pub static PARAMETERS: [&str; 0] = [];
/// Their values in the file.
pub static PARAMETER_VALUES: [f64; 0] = [];
/// Number of values `p` holds: the parameters by name, then the model's numbers that
/// the other parameters reach (read off the file loaded at their values: `DATA`).
pub const N_P: usize = 10;
/// `p` at the file's values.
pub static P0: [f64; 10] = [
    0.01f64,
    0.05f64,
    1f64,
    1f64,
    1f64,
    0.05f64,
    0.01f64,
    0.05f64,
    0.00000000000000011102230246251565f64,
    0.9999999999999999f64,
];
/// Where the numbers after the named parameters come from in the model (positions in
/// the generator's `slots::numbers`).
pub static DATA: [u32; 10] = [
    3u32, 4u32, 5u32, 6u32, 7u32, 8u32, 9u32, 10u32, 20u32, 21u32,
];
static OTHER_PARAMETERS: [&str; 6] = ["i_a", "i_t", "l", "m", "omega", "phi"];
static BODY_NAMES: [&str; 1] = ["bob"];
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
    let p: &[f64; 10] = p.try_into().expect("p must have 10 entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    mass_properties_part_0(p, out);
}
#[inline(never)]
fn mass_properties_part_0(p: &[f64; 10], out: &mut [f64; 4]) {
    out[0] = p[3];
    out[1] = p[1];
    out[2] = p[0];
    out[3] = p[1];
}
/// Each force's stiffness and damping at the run-time parameters `p`.
pub fn force_constants(p: &[f64], out: &mut [f64]) {
    let p: &[f64; 10] = p.try_into().expect("p must have 10 entries");
    let _: &mut [f64; 0] = out.try_into().expect("out must have 0 entries");
    let _ = p;
}
/// One set of run-time parameter values and the values `setup` computed from it.
#[derive(Debug, Clone)]
pub struct Parameters {
    p: [f64; N_P],
    k: [f64; N_K],
}
impl Parameters {
    /// The file's values.
    pub fn file_values() -> Self {
        Parameters { p: P0, k: K }
    }
    /// All of `p` at once (`N_P` values: the named parameters, then the model's
    /// numbers `DATA` names, as the mechanism file loaded at other values gives them),
    /// checked as [`Parameters::set`] checks.
    pub fn from_values(values: &[f64]) -> Result<Self, ParameterError> {
        let mut p = [0.0; N_P];
        RUN_TIME.assign_all(&mut p, values)?;
        let (mut props, mut constants) = ([0.0; 4], [0.0; 0]);
        RUN_TIME.check(&p, &[], &mut props, &mut constants)?;
        let mut k = [0.0; N_K];
        setup(&p, &mut k);
        Ok(Parameters { p, k })
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
    /// The values: those of `PARAMETERS`, then the numbers `DATA` names.
    pub fn values(&self) -> &[f64] {
        &self.p
    }
}
fn built(p: Parameters) -> symbody_runtime::registry::Built {
    vec![
        (Formulation::Exact, Box::new(ExactAt(p.clone())) as Box < dyn Mechanism + Sync
        >)
    ]
}
fn at_parameters(
    set: &[(&str, f64)],
) -> Result<symbody_runtime::registry::Built, ParameterError> {
    Parameters::at(set).map(built)
}
fn at_values(
    values: &[f64],
) -> Result<symbody_runtime::registry::Built, ParameterError> {
    Parameters::from_values(values).map(built)
}
/// This mechanism at other values of its run-time parameters, for the registries.
pub static RUN_TIME_ENTRY: symbody_runtime::registry::RunTime = symbody_runtime::registry::RunTime {
    parameters: &RUN_TIME,
    build: at_parameters,
    build_reduced: None,
    data: &DATA,
    p0: &P0,
    build_values: at_values,
    build_reduced_values: None,
};
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
        k: &[f64],
        q: &[f64],
        qd: &[f64],
        t: f64,
        dq: &mut [f64],
        dqd: &mut [f64],
    ) {
        let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let _: &mut [f64; 0] = dq.try_into().expect("dq must have 0 entries");
        let _: &mut [f64; 0] = dqd.try_into().expect("dqd must have 0 entries");
        let _ = k;
        let _ = q;
        let _ = qd;
        let _ = t;
    }
    /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
    pub fn mass(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
        mass_part_0(k, q, out);
    }
    #[inline(never)]
    fn mass_part_0(k: &[f64; 8], q: &[f64; 7], out: &mut [f64; 19]) {
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
        let x353 = 2.0 * x71;
        let x355 = x69 * x89;
        let x359 = x70 * x97;
        let x363 = x71 * x353;
        let x375 = x69 * x72;
        let x377 = x70 * x353;
        let x381 = x71 * x97;
        let x389 = x69 * x353;
        let x391 = x70 * x72;
        let x393 = x71 * x89;
        let x403 = x69 * x97;
        let x407 = x70 * x89;
        let x409 = x71 * x72;
        let x417 = x68 * x89;
        let x430 = x68 * x72;
        let x440 = x68 * x353;
        let x452 = x68 * x97;
        let x729 = x355 * k[3];
        let x730 = x359 * k[2];
        let x731 = x363 * k[3];
        let x732 = x729 + x730;
        let x733 = x731 + x732;
        let x734 = 0.5 * x733;
        let x735 = x9 * k[6];
        let x736 = x734 + x735;
        let x737 = x375 * k[3];
        let x738 = x377 * k[2];
        let x740 = x381 * k[3];
        let x741 = x737 - x738;
        let x742 = x740 + x741;
        let x743 = 0.5 * x742;
        let x745 = x38 * k[6];
        let x746 = x745 - x743;
        let x747 = x389 * k[3];
        let x748 = x391 * k[2];
        let x749 = x393 * k[3];
        let x751 = x747 + x748;
        let x752 = x751 - x749;
        let x753 = 0.5 * x752;
        let x755 = x32 * k[6];
        let x756 = x755 - x753;
        let x757 = x403 * k[3];
        let x759 = x407 * k[2];
        let x760 = x409 * k[3];
        let x761 = x759 - x757;
        let x762 = x760 + x761;
        let x763 = 0.5 * x762;
        let x765 = x25 * k[6];
        let x766 = x765 - x763;
        let x767 = x417 * k[3];
        let x769 = x381 * k[2];
        let x770 = x377 * k[3];
        let x772 = x769 - x767;
        let x773 = x772 - x770;
        let x774 = 0.5 * x773;
        let x775 = x745 + x774;
        let x776 = x430 * k[3];
        let x777 = x363 * k[2];
        let x778 = x359 * k[3];
        let x779 = x776 + x777;
        let x780 = x778 + x779;
        let x781 = 0.5 * x780;
        let x782 = x10 * k[6];
        let x783 = x781 + x782;
        let x784 = x440 * k[3];
        let x785 = x409 * k[2];
        let x787 = x407 * k[3];
        let x789 = x784 - x785;
        let x790 = x789 - x787;
        let x791 = 0.5 * x790;
        let x792 = x23 * k[6];
        let x793 = x791 + x792;
        let x794 = x452 * k[3];
        let x795 = x393 * k[2];
        let x796 = x391 * k[3];
        let x797 = x794 + x795;
        let x799 = x796 - x797;
        let x800 = 0.5 * x799;
        let x801 = x30 * k[6];
        let x802 = x800 + x801;
        let x803 = x452 * k[2];
        let x804 = x749 + x803;
        let x806 = x747 - x804;
        let x807 = 0.5 * x806;
        let x808 = x755 + x807;
        let x809 = x440 * k[2];
        let x811 = x760 - x809;
        let x812 = x811 - x757;
        let x813 = 0.5 * x812;
        let x814 = x792 + x813;
        let x815 = x430 * k[2];
        let x816 = x731 + x815;
        let x817 = x729 + x816;
        let x818 = 0.5 * x817;
        let x819 = x11 * k[6];
        let x820 = x818 + x819;
        let x822 = x417 * k[2];
        let x824 = x822 - x740;
        let x825 = x824 - x737;
        let x826 = 0.5 * x825;
        let x827 = x36 * k[6];
        let x828 = x826 + x827;
        let x829 = x403 * k[2];
        let x832 = x787 - x829;
        let x833 = x832 - x784;
        let x834 = 0.5 * x833;
        let x835 = x765 + x834;
        let x836 = x389 * k[2];
        let x837 = x796 + x836;
        let x839 = x794 - x837;
        let x840 = 0.5 * x839;
        let x841 = x801 + x840;
        let x842 = x375 * k[2];
        let x843 = x842 - x770;
        let x844 = x843 - x767;
        let x845 = 0.5 * x844;
        let x846 = x827 + x845;
        let x847 = x355 * k[2];
        let x848 = x778 + x847;
        let x849 = x776 + x848;
        let x850 = 0.5 * x849;
        let x851 = x12 * k[6];
        let x852 = x850 + x851;
        out[0] = k[7];
        out[1] = k[7];
        out[2] = k[7];
        out[3] = x736;
        out[4] = x746;
        out[5] = x756;
        out[6] = x766;
        out[7] = x775;
        out[8] = x783;
        out[9] = x793;
        out[10] = x802;
        out[11] = x808;
        out[12] = x814;
        out[13] = x820;
        out[14] = x828;
        out[15] = x835;
        out[16] = x841;
        out[17] = x846;
        out[18] = x852;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
        let _ = t;
        force_part_0(k, q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(k: &[f64; 8], q: &[f64; 7], qd: &[f64; 7], out: &mut [f64; 7]) {
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
        let x240 = x150 - x149;
        let x241 = x145 + x240;
        let x242 = x241 - x146;
        let x243 = 2.0 * x242;
        let x246 = x136 + x140;
        let x248 = x141 - x246;
        let x249 = x137 + x248;
        let x250 = 2.0 * x249;
        let x253 = x126 - x130;
        let x254 = x253 - x127;
        let x255 = x131 + x254;
        let x256 = 2.0 * x255;
        let x277 = 2.0 * x243;
        let x279 = 2.0 * x250;
        let x281 = 2.0 * x256;
        let x524 = x193 + x196;
        let x526 = x196 - x524;
        let x527 = x193 + x526;
        let x528 = 2.0 * x527;
        let x531 = x185 - x188;
        let x532 = x531 - x185;
        let x533 = x188 + x532;
        let x534 = 2.0 * x533;
        let x535 = 2.0 * x528;
        let x536 = 2.0 * x534;
        let x537 = x174 * x277;
        let x539 = x175 * x279;
        let x540 = x70 * x535;
        let x541 = x539 + x540;
        let x543 = x176 * x281;
        let x544 = x71 * x536;
        let x545 = x543 + x544;
        let x551 = x173 * x277;
        let x553 = x176 * x279;
        let x554 = x71 * x535;
        let x555 = x553 + x554;
        let x558 = x175 * x281;
        let x559 = x70 * x536;
        let x560 = x558 + x559;
        let x565 = x176 * x277;
        let x567 = x173 * x279;
        let x568 = x68 * x535;
        let x569 = x567 + x568;
        let x571 = x174 * x281;
        let x572 = x69 * x536;
        let x573 = x571 + x572;
        let x579 = x175 * x277;
        let x582 = x174 * x279;
        let x583 = x69 * x535;
        let x584 = x582 + x583;
        let x586 = x173 * x281;
        let x587 = x68 * x536;
        let x588 = x586 + x587;
        let x593 = qd[3] * qd[3];
        let x594 = qd[4] * qd[4];
        let x595 = qd[5] * qd[5];
        let x596 = qd[6] * qd[6];
        let x597 = x593 + x594;
        let x598 = x595 + x597;
        let x599 = x596 + x598;
        let x853 = x537 * k[3];
        let x854 = x541 * k[2];
        let x855 = x545 * k[3];
        let x856 = x853 + x854;
        let x857 = x855 + x856;
        let x858 = 0.5 * x857;
        let x859 = x551 * k[3];
        let x860 = x555 * k[2];
        let x862 = x560 * k[3];
        let x863 = x859 - x860;
        let x864 = x862 + x863;
        let x865 = 0.5 * x864;
        let x866 = x565 * k[3];
        let x867 = x569 * k[2];
        let x868 = x573 * k[3];
        let x870 = x866 + x867;
        let x871 = x870 - x868;
        let x872 = 0.5 * x871;
        let x873 = x579 * k[3];
        let x875 = x584 * k[2];
        let x876 = x588 * k[3];
        let x877 = x875 - x873;
        let x878 = x876 + x877;
        let x879 = 0.5 * x878;
        let x880 = x539 * k[2];
        let x881 = x543 * k[3];
        let x882 = x853 + x880;
        let x883 = x881 + x882;
        let x884 = 0.5 * x883;
        let x885 = x858 + x884;
        let x886 = q[3] * k[6];
        let x887 = x599 * x886;
        let x889 = x885 - x887;
        let x891 = x553 * k[2];
        let x892 = x558 * k[3];
        let x894 = x891 - x859;
        let x895 = x894 - x892;
        let x896 = 0.5 * x895;
        let x898 = x896 - x865;
        let x899 = q[4] * k[6];
        let x900 = x599 * x899;
        let x902 = x898 - x900;
        let x903 = x567 * k[2];
        let x904 = x571 * k[3];
        let x905 = x866 + x903;
        let x907 = x904 - x905;
        let x908 = 0.5 * x907;
        let x910 = x908 - x872;
        let x911 = q[5] * k[6];
        let x912 = x599 * x911;
        let x914 = x910 - x912;
        let x915 = x582 * k[2];
        let x917 = x586 * k[3];
        let x919 = x873 - x915;
        let x920 = x919 - x917;
        let x921 = 0.5 * x920;
        let x923 = x921 - x879;
        let x924 = q[6] * k[6];
        let x925 = x599 * x924;
        let x927 = x923 - x925;
        out[0] = 0.0;
        out[1] = k[5];
        out[2] = 0.0;
        out[3] = x889;
        out[4] = x902;
        out[5] = x914;
        out[6] = x927;
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
        let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 4] = phi.try_into().expect("phi must have 4 entries");
        let phi_q: &mut [f64; 19] = phi_q
            .try_into()
            .expect("phi_q must have 19 entries");
        let mass: &mut [f64; 19] = mass.try_into().expect("mass must have 19 entries");
        let force: &mut [f64; 7] = force.try_into().expect("force must have 7 entries");
        let _ = t;
        eval_newton_part_0(k, q, qd, phi, phi_q, mass, force);
    }
    #[inline(never)]
    fn eval_newton_part_0(
        k: &[f64; 8],
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
        let x65 = x11 + x13;
        let x66 = x12 + x65;
        let x67 = x66 - 1.0;
        let x68 = q[3] * 2.0;
        let x69 = q[4] * 2.0;
        let x70 = q[5] * 2.0;
        let x71 = q[6] * 2.0;
        let x72 = 2.0 * x68;
        let x89 = 2.0 * x69;
        let x97 = 2.0 * x70;
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
        let x240 = x150 - x149;
        let x241 = x145 + x240;
        let x242 = x241 - x146;
        let x243 = 2.0 * x242;
        let x246 = x136 + x140;
        let x248 = x141 - x246;
        let x249 = x137 + x248;
        let x250 = 2.0 * x249;
        let x253 = x126 - x130;
        let x254 = x253 - x127;
        let x255 = x131 + x254;
        let x256 = 2.0 * x255;
        let x277 = 2.0 * x243;
        let x279 = 2.0 * x250;
        let x281 = 2.0 * x256;
        let x353 = 2.0 * x71;
        let x355 = x69 * x89;
        let x359 = x70 * x97;
        let x363 = x71 * x353;
        let x375 = x69 * x72;
        let x377 = x70 * x353;
        let x381 = x71 * x97;
        let x389 = x69 * x353;
        let x391 = x70 * x72;
        let x393 = x71 * x89;
        let x403 = x69 * x97;
        let x407 = x70 * x89;
        let x409 = x71 * x72;
        let x417 = x68 * x89;
        let x430 = x68 * x72;
        let x440 = x68 * x353;
        let x452 = x68 * x97;
        let x524 = x193 + x196;
        let x526 = x196 - x524;
        let x527 = x193 + x526;
        let x528 = 2.0 * x527;
        let x531 = x185 - x188;
        let x532 = x531 - x185;
        let x533 = x188 + x532;
        let x534 = 2.0 * x533;
        let x535 = 2.0 * x528;
        let x536 = 2.0 * x534;
        let x537 = x174 * x277;
        let x539 = x175 * x279;
        let x540 = x70 * x535;
        let x541 = x539 + x540;
        let x543 = x176 * x281;
        let x544 = x71 * x536;
        let x545 = x543 + x544;
        let x551 = x173 * x277;
        let x553 = x176 * x279;
        let x554 = x71 * x535;
        let x555 = x553 + x554;
        let x558 = x175 * x281;
        let x559 = x70 * x536;
        let x560 = x558 + x559;
        let x565 = x176 * x277;
        let x567 = x173 * x279;
        let x568 = x68 * x535;
        let x569 = x567 + x568;
        let x571 = x174 * x281;
        let x572 = x69 * x536;
        let x573 = x571 + x572;
        let x579 = x175 * x277;
        let x582 = x174 * x279;
        let x583 = x69 * x535;
        let x584 = x582 + x583;
        let x586 = x173 * x281;
        let x587 = x68 * x536;
        let x588 = x586 + x587;
        let x593 = qd[3] * qd[3];
        let x594 = qd[4] * qd[4];
        let x595 = qd[5] * qd[5];
        let x596 = qd[6] * qd[6];
        let x597 = x593 + x594;
        let x598 = x595 + x597;
        let x599 = x596 + x598;
        let x666 = x16 * k[0];
        let x667 = x29 * k[1];
        let x668 = x666 + x667;
        let x669 = x35 * k[0];
        let x670 = x19 * k[1];
        let x671 = x669 + x670;
        let x672 = x45 * k[0];
        let x673 = x46 * k[1];
        let x674 = x672 + x673;
        let x675 = q[0] + x668;
        let x676 = q[1] + x671;
        let x677 = q[2] + x674;
        let x678 = -x675;
        let x679 = -x676;
        let x680 = -x677;
        let x681 = x72 * k[0];
        let x682 = x71 * k[1];
        let x684 = x681 - x682;
        let x685 = x71 * k[0];
        let x686 = x72 * k[1];
        let x687 = x685 + x686;
        let x688 = x70 * k[0];
        let x689 = -x688;
        let x690 = x69 * k[1];
        let x691 = x690 - x688;
        let x692 = -x684;
        let x693 = -x687;
        let x694 = -x691;
        let x695 = x89 * k[0];
        let x696 = x70 * k[1];
        let x697 = x695 + x696;
        let x698 = x68 * k[1];
        let x699 = x685 + x698;
        let x700 = -x697;
        let x701 = -x699;
        let x702 = x69 * k[0];
        let x703 = x97 * k[1];
        let x704 = x702 + x703;
        let x705 = x68 * k[0];
        let x706 = -x705;
        let x707 = x682 - x705;
        let x708 = -x690;
        let x709 = -x704;
        let x710 = -x707;
        let x711 = x696 + x702;
        let x712 = -x711;
        let x729 = x355 * k[3];
        let x730 = x359 * k[2];
        let x731 = x363 * k[3];
        let x732 = x729 + x730;
        let x733 = x731 + x732;
        let x734 = 0.5 * x733;
        let x735 = x9 * k[6];
        let x736 = x734 + x735;
        let x737 = x375 * k[3];
        let x738 = x377 * k[2];
        let x740 = x381 * k[3];
        let x741 = x737 - x738;
        let x742 = x740 + x741;
        let x743 = 0.5 * x742;
        let x745 = x38 * k[6];
        let x746 = x745 - x743;
        let x747 = x389 * k[3];
        let x748 = x391 * k[2];
        let x749 = x393 * k[3];
        let x751 = x747 + x748;
        let x752 = x751 - x749;
        let x753 = 0.5 * x752;
        let x755 = x32 * k[6];
        let x756 = x755 - x753;
        let x757 = x403 * k[3];
        let x759 = x407 * k[2];
        let x760 = x409 * k[3];
        let x761 = x759 - x757;
        let x762 = x760 + x761;
        let x763 = 0.5 * x762;
        let x765 = x25 * k[6];
        let x766 = x765 - x763;
        let x767 = x417 * k[3];
        let x769 = x381 * k[2];
        let x770 = x377 * k[3];
        let x772 = x769 - x767;
        let x773 = x772 - x770;
        let x774 = 0.5 * x773;
        let x775 = x745 + x774;
        let x776 = x430 * k[3];
        let x777 = x363 * k[2];
        let x778 = x359 * k[3];
        let x779 = x776 + x777;
        let x780 = x778 + x779;
        let x781 = 0.5 * x780;
        let x782 = x10 * k[6];
        let x783 = x781 + x782;
        let x784 = x440 * k[3];
        let x785 = x409 * k[2];
        let x787 = x407 * k[3];
        let x789 = x784 - x785;
        let x790 = x789 - x787;
        let x791 = 0.5 * x790;
        let x792 = x23 * k[6];
        let x793 = x791 + x792;
        let x794 = x452 * k[3];
        let x795 = x393 * k[2];
        let x796 = x391 * k[3];
        let x797 = x794 + x795;
        let x799 = x796 - x797;
        let x800 = 0.5 * x799;
        let x801 = x30 * k[6];
        let x802 = x800 + x801;
        let x803 = x452 * k[2];
        let x804 = x749 + x803;
        let x806 = x747 - x804;
        let x807 = 0.5 * x806;
        let x808 = x755 + x807;
        let x809 = x440 * k[2];
        let x811 = x760 - x809;
        let x812 = x811 - x757;
        let x813 = 0.5 * x812;
        let x814 = x792 + x813;
        let x815 = x430 * k[2];
        let x816 = x731 + x815;
        let x817 = x729 + x816;
        let x818 = 0.5 * x817;
        let x819 = x11 * k[6];
        let x820 = x818 + x819;
        let x822 = x417 * k[2];
        let x824 = x822 - x740;
        let x825 = x824 - x737;
        let x826 = 0.5 * x825;
        let x827 = x36 * k[6];
        let x828 = x826 + x827;
        let x829 = x403 * k[2];
        let x832 = x787 - x829;
        let x833 = x832 - x784;
        let x834 = 0.5 * x833;
        let x835 = x765 + x834;
        let x836 = x389 * k[2];
        let x837 = x796 + x836;
        let x839 = x794 - x837;
        let x840 = 0.5 * x839;
        let x841 = x801 + x840;
        let x842 = x375 * k[2];
        let x843 = x842 - x770;
        let x844 = x843 - x767;
        let x845 = 0.5 * x844;
        let x846 = x827 + x845;
        let x847 = x355 * k[2];
        let x848 = x778 + x847;
        let x849 = x776 + x848;
        let x850 = 0.5 * x849;
        let x851 = x12 * k[6];
        let x852 = x850 + x851;
        let x853 = x537 * k[3];
        let x854 = x541 * k[2];
        let x855 = x545 * k[3];
        let x856 = x853 + x854;
        let x857 = x855 + x856;
        let x858 = 0.5 * x857;
        let x859 = x551 * k[3];
        let x860 = x555 * k[2];
        let x862 = x560 * k[3];
        let x863 = x859 - x860;
        let x864 = x862 + x863;
        let x865 = 0.5 * x864;
        let x866 = x565 * k[3];
        let x867 = x569 * k[2];
        let x868 = x573 * k[3];
        let x870 = x866 + x867;
        let x871 = x870 - x868;
        let x872 = 0.5 * x871;
        let x873 = x579 * k[3];
        let x875 = x584 * k[2];
        let x876 = x588 * k[3];
        let x877 = x875 - x873;
        let x878 = x876 + x877;
        let x879 = 0.5 * x878;
        let x880 = x539 * k[2];
        let x881 = x543 * k[3];
        let x882 = x853 + x880;
        let x883 = x881 + x882;
        let x884 = 0.5 * x883;
        let x885 = x858 + x884;
        let x886 = q[3] * k[6];
        let x887 = x599 * x886;
        let x889 = x885 - x887;
        let x891 = x553 * k[2];
        let x892 = x558 * k[3];
        let x894 = x891 - x859;
        let x895 = x894 - x892;
        let x896 = 0.5 * x895;
        let x898 = x896 - x865;
        let x899 = q[4] * k[6];
        let x900 = x599 * x899;
        let x902 = x898 - x900;
        let x903 = x567 * k[2];
        let x904 = x571 * k[3];
        let x905 = x866 + x903;
        let x907 = x904 - x905;
        let x908 = 0.5 * x907;
        let x910 = x908 - x872;
        let x911 = q[5] * k[6];
        let x912 = x599 * x911;
        let x914 = x910 - x912;
        let x915 = x582 * k[2];
        let x917 = x586 * k[3];
        let x919 = x873 - x915;
        let x920 = x919 - x917;
        let x921 = 0.5 * x920;
        let x923 = x921 - x879;
        let x924 = q[6] * k[6];
        let x925 = x599 * x924;
        let x927 = x923 - x925;
        phi[0] = x678;
        phi_q[0] = -1.0;
        phi_q[1] = x692;
        phi_q[2] = x700;
        phi_q[3] = x708;
        phi_q[4] = x698;
        phi[1] = x679;
        phi_q[5] = -1.0;
        phi_q[6] = x693;
        phi_q[7] = x689;
        phi_q[8] = x709;
        phi_q[9] = x706;
        phi[2] = x680;
        phi_q[10] = -1.0;
        phi_q[11] = x694;
        phi_q[12] = x701;
        phi_q[13] = x710;
        phi_q[14] = x712;
        phi[3] = x67;
        phi_q[15] = x68;
        phi_q[16] = x69;
        phi_q[17] = x70;
        phi_q[18] = x71;
        mass[0] = k[7];
        mass[1] = k[7];
        mass[2] = k[7];
        mass[3] = x736;
        mass[4] = x746;
        mass[5] = x756;
        mass[6] = x766;
        mass[7] = x775;
        mass[8] = x783;
        mass[9] = x793;
        mass[10] = x802;
        mass[11] = x808;
        mass[12] = x814;
        mass[13] = x820;
        mass[14] = x828;
        mass[15] = x835;
        mass[16] = x841;
        mass[17] = x846;
        mass[18] = x852;
        force[0] = 0.0;
        force[1] = k[5];
        force[2] = 0.0;
        force[3] = x889;
        force[4] = x902;
        force[5] = x914;
        force[6] = x927;
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
        phi(&K, q, t, out)
    }
    fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi_q(&K, q, t, out)
    }
    fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi_t(&K, q, t, out)
    }
    fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        gamma(&K, q, qd, t, out)
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
        eval_kinematics(&K, q, qd, t, out.phi, out.phi_q, out.phi_t, out.gamma)
    }
}
impl Exact {
    /// This formulation with some run-time parameters (`PARAMETERS`) set, the others
    /// at the file's values; a name or value that is refused changes nothing.
    pub fn with_parameters(set: &[(&str, f64)]) -> Result<ExactAt, ParameterError> {
        Parameters::at(set).map(ExactAt)
    }
}
/// `spherical_pendulum` with the `exact` formulation. At run-time parameter values (`Exact::with_parameters`).
#[derive(Debug, Clone)]
pub struct ExactAt(pub Parameters);
impl Mechanism for ExactAt {
    fn info(&self) -> &'static MechanismInfo {
        &exact::INFO
    }
    fn phi(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi(&self.0.k, q, t, out)
    }
    fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi_q(&self.0.k, q, t, out)
    }
    fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) {
        phi_t(&self.0.k, q, t, out)
    }
    fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        gamma(&self.0.k, q, qd, t, out)
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
        eval_kinematics(&self.0.k, q, qd, t, out.phi, out.phi_q, out.phi_t, out.gamma)
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
    run_time: Some(&RUN_TIME_ENTRY),
};
