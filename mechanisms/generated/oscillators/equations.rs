//! Generated equations of `oscillators` (a spring-damper slider and a torsion-spring rotor, forced: closed-form motions). Do not edit.
//!
//! Regenerate with `cargo xtask generate oscillators` from `mechanisms/oscillators.toml`.
//!
//! 14 coordinates, 12 constraints, 33 structural nonzeros in Φq.
//! Rank 12 at the initial pose; mobility 2 (Grübler count 2), 2 DOF left with drivers.
//! Each body owns `[X, Y, Z]` (centre of mass), then `[θ, β, γ]` (A = Rz(γ)·Ry(β)·Rx(θ))
//! or Euler parameters `[e0, e1, e2, e3]`. Equations of motion: `M q̈ + Φqᵀλ = Q`, `Φq q̈ = γ`.
//! Sparse outputs hold the pattern's nonzeros in order (row-major, columns ascending).
//!
//! Coordinates:
//! - `0..7` slider (quaternion)
//! - `7..14` rotor (quaternion)
//!
//! Constraint rows:
//! - `0..5` rail (prismatic, ground – slider)
//! - `5..10` spindle (revolute, ground – rotor)
//! - `10` slider.norm: eᵀe − 1
//! - `11` rotor.norm: eᵀe − 1
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
    let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 12] = out.try_into().expect("out must have 12 entries");
    let _ = t;
    phi_part_0(q, out);
}
#[inline(never)]
fn phi_part_0(q: &[f64; 14], out: &mut [f64; 12]) {
    let x23 = q[3] * q[3];
    let x24 = q[4] * q[4];
    let x25 = q[5] * q[5];
    let x26 = q[6] * q[6];
    let x27 = x23 + x24;
    let x37 = q[4] * q[5];
    let x38 = 2.0 * x37;
    let x39 = q[3] * q[6];
    let x41 = 2.0 * x39;
    let x44 = q[4] * q[6];
    let x45 = 2.0 * x44;
    let x46 = q[3] * q[5];
    let x47 = 2.0 * x46;
    let x49 = x38 + x41;
    let x50 = q[5] * q[6];
    let x51 = 2.0 * x50;
    let x52 = q[3] * q[4];
    let x54 = 2.0 * x52;
    let x59 = x45 - x47;
    let x60 = x51 + x54;
    let x68 = q[10] * q[10];
    let x69 = q[11] * q[11];
    let x70 = q[12] * q[12];
    let x71 = q[13] * q[13];
    let x72 = x68 + x69;
    let x81 = q[11] * q[12];
    let x82 = 2.0 * x81;
    let x83 = q[10] * q[13];
    let x85 = 2.0 * x83;
    let x87 = x82 - x85;
    let x94 = q[12] * q[13];
    let x95 = 2.0 * x94;
    let x96 = q[10] * q[11];
    let x98 = 2.0 * x96;
    let x104 = x95 + x98;
    let x111 = -q[7];
    let x113 = 1.0 - q[8];
    let x115 = 2.0 - q[9];
    let x116 = -x104;
    let x117 = x25 + x27;
    let x118 = x26 + x117;
    let x119 = x118 - 1.0;
    let x120 = x70 + x72;
    let x121 = x71 + x120;
    let x122 = x121 - 1.0;
    out[0] = x49;
    out[1] = x59;
    out[2] = q[1];
    out[3] = q[2];
    out[4] = x60;
    out[5] = x111;
    out[6] = x113;
    out[7] = x115;
    out[8] = x87;
    out[9] = x116;
    out[10] = x119;
    out[11] = x122;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 33] = out.try_into().expect("out must have 33 entries");
    let _ = t;
    phi_q_part_0(q, out);
}
#[inline(never)]
fn phi_q_part_0(q: &[f64; 14], out: &mut [f64; 33]) {
    let x123 = q[3] * 2.0;
    let x124 = q[4] * 2.0;
    let x125 = q[5] * 2.0;
    let x126 = q[6] * 2.0;
    let x127 = -x125;
    let x128 = -x123;
    let x129 = 2.0 * q[10];
    let x130 = 2.0 * q[11];
    let x131 = 2.0 * q[12];
    let x132 = 2.0 * q[13];
    let x133 = -x132;
    let x134 = -x130;
    let x135 = -x129;
    let x136 = -x131;
    out[0] = x126;
    out[1] = x125;
    out[2] = x124;
    out[3] = x123;
    out[4] = x127;
    out[5] = x126;
    out[6] = x128;
    out[7] = x124;
    out[8] = 1.0;
    out[9] = 1.0;
    out[10] = x124;
    out[11] = x123;
    out[12] = x126;
    out[13] = x125;
    out[14] = -1.0;
    out[15] = -1.0;
    out[16] = -1.0;
    out[17] = x133;
    out[18] = x131;
    out[19] = x130;
    out[20] = x135;
    out[21] = x134;
    out[22] = x135;
    out[23] = x133;
    out[24] = x136;
    out[25] = x123;
    out[26] = x124;
    out[27] = x125;
    out[28] = x126;
    out[29] = x129;
    out[30] = x130;
    out[31] = x131;
    out[32] = x132;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 12] = out.try_into().expect("out must have 12 entries");
    let _ = q;
    let _ = t;
    phi_t_part_0(out);
}
#[inline(never)]
fn phi_t_part_0(out: &mut [f64; 12]) {
    out[0] = 0.0;
    out[1] = 0.0;
    out[2] = 0.0;
    out[3] = 0.0;
    out[4] = 0.0;
    out[5] = 0.0;
    out[6] = 0.0;
    out[7] = 0.0;
    out[8] = 0.0;
    out[9] = 0.0;
    out[10] = 0.0;
    out[11] = 0.0;
}
/// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
pub fn gamma(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 12] = out.try_into().expect("out must have 12 entries");
    let _ = q;
    let _ = t;
    gamma_part_0(qd, out);
}
#[inline(never)]
fn gamma_part_0(qd: &[f64; 14], out: &mut [f64; 12]) {
    let x216 = 2.0 * qd[3];
    let x217 = 2.0 * qd[4];
    let x218 = 2.0 * qd[5];
    let x219 = 2.0 * qd[6];
    let x220 = 2.0 * qd[10];
    let x221 = 2.0 * qd[11];
    let x222 = 2.0 * qd[12];
    let x223 = 2.0 * qd[13];
    let x224 = qd[3] * x216;
    let x225 = qd[4] * x217;
    let x226 = qd[5] * x218;
    let x227 = qd[6] * x219;
    let x228 = x224 + x225;
    let x229 = qd[4] * qd[5];
    let x230 = x229 + x229;
    let x231 = 2.0 * x230;
    let x232 = qd[3] * qd[6];
    let x233 = x232 + x232;
    let x234 = 2.0 * x233;
    let x235 = qd[4] * qd[6];
    let x236 = x235 + x235;
    let x237 = 2.0 * x236;
    let x238 = qd[3] * qd[5];
    let x239 = x238 + x238;
    let x240 = 2.0 * x239;
    let x241 = x231 + x234;
    let x242 = qd[5] * qd[6];
    let x243 = x242 + x242;
    let x244 = 2.0 * x243;
    let x245 = qd[3] * qd[4];
    let x246 = x245 + x245;
    let x247 = 2.0 * x246;
    let x249 = x237 - x240;
    let x250 = x244 + x247;
    let x251 = qd[10] * x220;
    let x252 = qd[11] * x221;
    let x253 = qd[12] * x222;
    let x254 = qd[13] * x223;
    let x255 = x251 + x252;
    let x256 = qd[11] * qd[12];
    let x257 = x256 + x256;
    let x258 = 2.0 * x257;
    let x259 = qd[10] * qd[13];
    let x260 = x259 + x259;
    let x261 = 2.0 * x260;
    let x263 = x258 - x261;
    let x264 = qd[12] * qd[13];
    let x265 = x264 + x264;
    let x266 = 2.0 * x265;
    let x267 = qd[10] * qd[11];
    let x268 = x267 + x267;
    let x269 = 2.0 * x268;
    let x270 = x266 + x269;
    let x272 = x226 + x228;
    let x273 = x227 + x272;
    let x274 = x253 + x255;
    let x275 = x254 + x274;
    let x276 = -x241;
    let x277 = -x249;
    let x278 = -x250;
    let x279 = -x263;
    let x280 = -x273;
    let x281 = -x275;
    out[0] = x276;
    out[1] = x277;
    out[2] = 0.0;
    out[3] = 0.0;
    out[4] = x278;
    out[5] = 0.0;
    out[6] = 0.0;
    out[7] = 0.0;
    out[8] = x279;
    out[9] = x270;
    out[10] = x280;
    out[11] = x281;
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
    let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
    let phi: &mut [f64; 12] = phi.try_into().expect("phi must have 12 entries");
    let phi_q: &mut [f64; 33] = phi_q.try_into().expect("phi_q must have 33 entries");
    let phi_t: &mut [f64; 12] = phi_t.try_into().expect("phi_t must have 12 entries");
    let gamma: &mut [f64; 12] = gamma.try_into().expect("gamma must have 12 entries");
    let _ = t;
    eval_kinematics_part_0(q, qd, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_part_0(
    q: &[f64; 14],
    qd: &[f64; 14],
    phi: &mut [f64; 12],
    phi_q: &mut [f64; 33],
    phi_t: &mut [f64; 12],
    gamma: &mut [f64; 12],
) {
    let x23 = q[3] * q[3];
    let x24 = q[4] * q[4];
    let x25 = q[5] * q[5];
    let x26 = q[6] * q[6];
    let x27 = x23 + x24;
    let x37 = q[4] * q[5];
    let x38 = 2.0 * x37;
    let x39 = q[3] * q[6];
    let x41 = 2.0 * x39;
    let x44 = q[4] * q[6];
    let x45 = 2.0 * x44;
    let x46 = q[3] * q[5];
    let x47 = 2.0 * x46;
    let x49 = x38 + x41;
    let x50 = q[5] * q[6];
    let x51 = 2.0 * x50;
    let x52 = q[3] * q[4];
    let x54 = 2.0 * x52;
    let x59 = x45 - x47;
    let x60 = x51 + x54;
    let x68 = q[10] * q[10];
    let x69 = q[11] * q[11];
    let x70 = q[12] * q[12];
    let x71 = q[13] * q[13];
    let x72 = x68 + x69;
    let x81 = q[11] * q[12];
    let x82 = 2.0 * x81;
    let x83 = q[10] * q[13];
    let x85 = 2.0 * x83;
    let x87 = x82 - x85;
    let x94 = q[12] * q[13];
    let x95 = 2.0 * x94;
    let x96 = q[10] * q[11];
    let x98 = 2.0 * x96;
    let x104 = x95 + x98;
    let x111 = -q[7];
    let x113 = 1.0 - q[8];
    let x115 = 2.0 - q[9];
    let x116 = -x104;
    let x117 = x25 + x27;
    let x118 = x26 + x117;
    let x119 = x118 - 1.0;
    let x120 = x70 + x72;
    let x121 = x71 + x120;
    let x122 = x121 - 1.0;
    let x123 = q[3] * 2.0;
    let x124 = q[4] * 2.0;
    let x125 = q[5] * 2.0;
    let x126 = q[6] * 2.0;
    let x127 = -x125;
    let x128 = -x123;
    let x129 = 2.0 * q[10];
    let x130 = 2.0 * q[11];
    let x131 = 2.0 * q[12];
    let x132 = 2.0 * q[13];
    let x133 = -x132;
    let x134 = -x130;
    let x135 = -x129;
    let x136 = -x131;
    let x216 = 2.0 * qd[3];
    let x217 = 2.0 * qd[4];
    let x218 = 2.0 * qd[5];
    let x219 = 2.0 * qd[6];
    let x220 = 2.0 * qd[10];
    let x221 = 2.0 * qd[11];
    let x222 = 2.0 * qd[12];
    let x223 = 2.0 * qd[13];
    let x224 = qd[3] * x216;
    let x225 = qd[4] * x217;
    let x226 = qd[5] * x218;
    let x227 = qd[6] * x219;
    let x228 = x224 + x225;
    let x229 = qd[4] * qd[5];
    let x230 = x229 + x229;
    let x231 = 2.0 * x230;
    let x232 = qd[3] * qd[6];
    let x233 = x232 + x232;
    let x234 = 2.0 * x233;
    let x235 = qd[4] * qd[6];
    let x236 = x235 + x235;
    let x237 = 2.0 * x236;
    let x238 = qd[3] * qd[5];
    let x239 = x238 + x238;
    let x240 = 2.0 * x239;
    let x241 = x231 + x234;
    let x242 = qd[5] * qd[6];
    let x243 = x242 + x242;
    let x244 = 2.0 * x243;
    let x245 = qd[3] * qd[4];
    let x246 = x245 + x245;
    let x247 = 2.0 * x246;
    let x249 = x237 - x240;
    let x250 = x244 + x247;
    let x251 = qd[10] * x220;
    let x252 = qd[11] * x221;
    let x253 = qd[12] * x222;
    let x254 = qd[13] * x223;
    let x255 = x251 + x252;
    let x256 = qd[11] * qd[12];
    let x257 = x256 + x256;
    let x258 = 2.0 * x257;
    let x259 = qd[10] * qd[13];
    let x260 = x259 + x259;
    let x261 = 2.0 * x260;
    let x263 = x258 - x261;
    let x264 = qd[12] * qd[13];
    let x265 = x264 + x264;
    let x266 = 2.0 * x265;
    let x267 = qd[10] * qd[11];
    let x268 = x267 + x267;
    let x269 = 2.0 * x268;
    let x270 = x266 + x269;
    let x272 = x226 + x228;
    let x273 = x227 + x272;
    let x274 = x253 + x255;
    let x275 = x254 + x274;
    let x276 = -x241;
    let x277 = -x249;
    let x278 = -x250;
    let x279 = -x263;
    let x280 = -x273;
    let x281 = -x275;
    phi[0] = x49;
    phi_q[0] = x126;
    phi_q[1] = x125;
    phi_q[2] = x124;
    phi_q[3] = x123;
    phi_t[0] = 0.0;
    gamma[0] = x276;
    phi[1] = x59;
    phi_q[4] = x127;
    phi_q[5] = x126;
    phi_q[6] = x128;
    phi_q[7] = x124;
    phi_t[1] = 0.0;
    gamma[1] = x277;
    phi[2] = q[1];
    phi_q[8] = 1.0;
    phi_t[2] = 0.0;
    gamma[2] = 0.0;
    phi[3] = q[2];
    phi_q[9] = 1.0;
    phi_t[3] = 0.0;
    gamma[3] = 0.0;
    phi[4] = x60;
    phi_q[10] = x124;
    phi_q[11] = x123;
    phi_q[12] = x126;
    phi_q[13] = x125;
    phi_t[4] = 0.0;
    gamma[4] = x278;
    phi[5] = x111;
    phi_q[14] = -1.0;
    phi_t[5] = 0.0;
    gamma[5] = 0.0;
    phi[6] = x113;
    phi_q[15] = -1.0;
    phi_t[6] = 0.0;
    gamma[6] = 0.0;
    phi[7] = x115;
    phi_q[16] = -1.0;
    phi_t[7] = 0.0;
    gamma[7] = 0.0;
    phi[8] = x87;
    phi_q[17] = x133;
    phi_q[18] = x131;
    phi_q[19] = x130;
    phi_q[20] = x135;
    phi_t[8] = 0.0;
    gamma[8] = x279;
    phi[9] = x116;
    phi_q[21] = x134;
    phi_q[22] = x135;
    phi_q[23] = x133;
    phi_q[24] = x136;
    phi_t[9] = 0.0;
    gamma[9] = x270;
    phi[10] = x119;
    phi_q[25] = x123;
    phi_q[26] = x124;
    phi_q[27] = x125;
    phi_q[28] = x126;
    phi_t[10] = 0.0;
    gamma[10] = x280;
    phi[11] = x122;
    phi_q[29] = x129;
    phi_q[30] = x130;
    phi_q[31] = x131;
    phi_q[32] = x132;
    phi_t[11] = 0.0;
    gamma[11] = x281;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
    let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
    let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    potential_into_part_0(k, q, out);
}
#[inline(never)]
fn potential_into_part_0(k: &[f64; 5], q: &[f64; 14], out: &mut [f64; 1]) {
    let x68 = q[10] * q[10];
    let x69 = q[11] * q[11];
    let x72 = x68 + x69;
    let x73 = 2.0 * x72;
    let x74 = x73 - 1.0;
    let x88 = q[11] * q[13];
    let x89 = 2.0 * x88;
    let x90 = q[10] * q[12];
    let x91 = 2.0 * x90;
    let x103 = x89 - x91;
    let x291 = q[8] * 9.81;
    let x292 = 1.0 + q[0];
    let x293 = x292 * x292;
    let x294 = q[1] * q[1];
    let x295 = q[2] * q[2];
    let x296 = x293 + x294;
    let x297 = x295 + x296;
    let x298 = x297.sqrt();
    let x310 = x298 - 1.0;
    let x320 = x310 * x310;
    let x321 = 25.0 * x320;
    let x329 = -x103;
    let x330 = x329.atan2(x74);
    let x359 = x330 * x330;
    let x1664 = q[1] * k[1];
    let x1665 = x291 + x1664;
    let x1666 = x321 + x1665;
    let x1667 = x359 + x1666;
    out[0] = x1667;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
    let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = k;
    power_nc_into_part_0(q, qd, t, out);
}
#[inline(never)]
fn power_nc_into_part_0(q: &[f64; 14], qd: &[f64; 14], t: f64, out: &mut [f64; 1]) {
    let x3 = 4.0 * t;
    let x4 = x3.sin();
    let x5 = 3.0 * x4;
    let x9 = 3.0 * t;
    let x10 = x9.cos();
    let x11 = 0.5 * x10;
    let x13 = t.sin();
    let x14 = 0.2 * x13;
    let x68 = q[10] * q[10];
    let x69 = q[11] * q[11];
    let x72 = x68 + x69;
    let x73 = 2.0 * x72;
    let x74 = x73 - 1.0;
    let x88 = q[11] * q[13];
    let x89 = 2.0 * x88;
    let x90 = q[10] * q[12];
    let x91 = 2.0 * x90;
    let x103 = x89 - x91;
    let x129 = 2.0 * q[10];
    let x130 = 2.0 * q[11];
    let x184 = x129 * qd[10];
    let x185 = x130 * qd[11];
    let x188 = x184 + x185;
    let x292 = 1.0 + q[0];
    let x293 = x292 * x292;
    let x294 = q[1] * q[1];
    let x295 = q[2] * q[2];
    let x296 = x293 + x294;
    let x297 = x295 + x296;
    let x298 = x297.sqrt();
    let x299 = 2.0 * x292;
    let x300 = qd[0] * x299;
    let x301 = q[1] * 2.0;
    let x302 = qd[1] * x301;
    let x303 = q[2] * 2.0;
    let x304 = qd[2] * x303;
    let x305 = x300 + x302;
    let x306 = x304 + x305;
    let x307 = 2.0 * x298;
    let x308 = 1.0 / x307;
    let x309 = x306 * x308;
    let x314 = x309 * 0.8;
    let x316 = x5 - x314;
    let x322 = x309 * x316;
    let x331 = 2.0 * x188;
    let x332 = q[13] * qd[11];
    let x333 = q[11] * qd[13];
    let x334 = x332 + x333;
    let x335 = 2.0 * x334;
    let x336 = q[12] * qd[10];
    let x337 = q[10] * qd[12];
    let x338 = x336 + x337;
    let x339 = 2.0 * x338;
    let x341 = x335 - x339;
    let x343 = x74 * x74;
    let x344 = x103 * x103;
    let x345 = x343 + x344;
    let x346 = x74 * x341;
    let x348 = x103 * x331;
    let x350 = x348 - x346;
    let x351 = 1.0 / x345;
    let x352 = x350 * x351;
    let x354 = 0.1 * x352;
    let x356 = x11 - x354;
    let x360 = x352 * x356;
    let x393 = x332 - x336;
    let x394 = x337 + x393;
    let x395 = x394 - x333;
    let x396 = 2.0 * x395;
    let x404 = x14 * x396;
    let x423 = qd[0] + x322;
    let x424 = x360 + x423;
    let x425 = x404 + x424;
    out[0] = x425;
}
/// Number of generalized coordinates.
pub const N_COORDS: usize = 14usize;
/// Number of constraint rows.
pub const N_CONSTRAINTS: usize = 12usize;
/// Row of each Φq nonzero.
pub static PHI_Q_ROWS: [u32; 33usize] = [
    0u32, 0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 1u32, 2u32, 3u32, 4u32, 4u32, 4u32, 4u32,
    5u32, 6u32, 7u32, 8u32, 8u32, 8u32, 8u32, 9u32, 9u32, 9u32, 9u32, 10u32, 10u32,
    10u32, 10u32, 11u32, 11u32, 11u32, 11u32,
];
/// Column of each Φq nonzero.
pub static PHI_Q_COLS: [u32; 33usize] = [
    3u32, 4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32,
    7u32, 8u32, 9u32, 10u32, 11u32, 12u32, 13u32, 10u32, 11u32, 12u32, 13u32, 3u32, 4u32,
    5u32, 6u32, 10u32, 11u32, 12u32, 13u32,
];
/// Bodies in coordinate order.
pub static BODIES: [BodyInfo; 2usize] = [
    BodyInfo {
        name: "slider",
        coord_offset: 0usize,
        rotation: Rotation::Quaternion,
        mass: 2f64,
        inertia: [0.01f64, 0.01f64, 0.01f64],
    },
    BodyInfo {
        name: "rotor",
        coord_offset: 7usize,
        rotation: Rotation::Quaternion,
        mass: 1f64,
        inertia: [0.1f64, 0.2f64, 0.3f64],
    },
];
/// Joints in row order, then drivers.
pub static JOINTS: [JointInfo; 4usize] = [
    JointInfo {
        name: "rail",
        kind: JointKind::Prismatic,
        body1: None,
        body2: Some(0usize),
        row_start: 0usize,
        rows: 5usize,
        point1: [0.1f64, 0f64, 0f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
    JointInfo {
        name: "spindle",
        kind: JointKind::Revolute,
        body1: None,
        body2: Some(1usize),
        row_start: 5usize,
        rows: 5usize,
        point1: [0f64, 1f64, 2f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
    JointInfo {
        name: "slider.norm",
        kind: JointKind::Normalization,
        body1: Some(0usize),
        body2: None,
        row_start: 10usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
    JointInfo {
        name: "rotor.norm",
        kind: JointKind::Normalization,
        body1: Some(1usize),
        body2: None,
        row_start: 11usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
];
/// Name of each coordinate.
pub static COORD_NAMES: [&str; 14usize] = [
    "slider.x",
    "slider.y",
    "slider.z",
    "slider.e0",
    "slider.e1",
    "slider.e2",
    "slider.e3",
    "rotor.x",
    "rotor.y",
    "rotor.z",
    "rotor.e0",
    "rotor.e1",
    "rotor.e2",
    "rotor.e3",
];
/// Name of each constraint row.
pub static ROW_NAMES: [&str; 12usize] = [
    "rail.dot1(x1,z2)",
    "rail.dot1(y1,z2)",
    "rail.dot2(x1,d)",
    "rail.dot2(y1,d)",
    "rail.dot1(y1,x2)",
    "spindle.x",
    "spindle.y",
    "spindle.z",
    "spindle.dot1(x1,z2)",
    "spindle.dot1(y1,z2)",
    "slider.norm",
    "rotor.norm",
];
/// Initial coordinates: the file's pose, assembled.
pub static Q0: [f64; 14usize] = [
    0.1f64,
    0f64,
    0f64,
    1f64,
    0f64,
    0f64,
    0f64,
    0f64,
    1f64,
    2f64,
    1f64,
    0f64,
    0f64,
    0f64,
];
/// Initial velocities from the file (to be projected onto the constraints).
pub static QD0: [f64; 14usize] = [
    0f64,
    0f64,
    0f64,
    0f64,
    0f64,
    0f64,
    0f64,
    0f64,
    0f64,
    0f64,
    -0f64,
    0f64,
    0.5f64,
    0f64,
];
/// Constraint rows dependent on others at the initial pose (dropped by the solvers).
pub static REDUNDANT_ROWS: [u32; 0usize] = [];
/// Simulation end time suggested by the mechanism file (s).
pub const T_END: f64 = 5f64;
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
pub static K: [f64; 5] = [0.2f64, 19.62f64, -19.62f64, 2f64, 0.8f64];
/// The values the per-step functions read (`k`), from the run-time parameters `p`.
pub fn setup(p: &[f64], k: &mut [f64]) {
    let p: &[f64; 2] = p.try_into().expect("p must have 2 entries");
    let k: &mut [f64; 5] = k.try_into().expect("k must have 5 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 2], k: &mut [f64; 5]) {
    let x288 = p[1] * 9.81;
    let x289 = -x288;
    let x535 = 2.0 * p[1];
    let x536 = 0.5 * x535;
    let x912 = 0.1 + p[0];
    let x913 = 0.3 + x912;
    let x914 = 4.0 * x913;
    let x916 = x914 * 0.3333333333333333;
    k[0] = p[0];
    k[1] = x288;
    k[2] = x289;
    k[3] = x536;
    k[4] = x916;
}
/// The parameters the generated code takes at run time: the file's `[parameters]`
/// entries that reach only masses and inertias (the others are set on the file).
pub static PARAMETERS: [&str; 2] = ["j", "m"];
/// Their values in the file.
pub static PARAMETER_VALUES: [f64; 2] = [0.2f64, 2f64];
static OTHER_PARAMETERS: [&str; 12] = [
    "c",
    "ct",
    "f0",
    "fc",
    "k",
    "kt",
    "nu",
    "omega0",
    "tau1",
    "tau2",
    "w",
    "x0",
];
static BODY_NAMES: [&str; 2] = ["slider", "rotor"];
/// What a new parameter set is checked with.
pub static RUN_TIME: RunTimeParameters = RunTimeParameters {
    names: &PARAMETERS,
    others: &OTHER_PARAMETERS,
    bodies: &BODY_NAMES,
    mass_properties,
};
/// Each body's mass and principal inertias at the run-time parameters `p`.
pub fn mass_properties(p: &[f64], out: &mut [f64]) {
    let p: &[f64; 2] = p.try_into().expect("p must have 2 entries");
    let out: &mut [f64; 8] = out.try_into().expect("out must have 8 entries");
    mass_properties_part_0(p, out);
}
#[inline(never)]
fn mass_properties_part_0(p: &[f64; 2], out: &mut [f64; 8]) {
    out[0] = p[1];
    out[1] = 0.01;
    out[2] = 0.01;
    out[3] = 0.01;
    out[4] = 1.0;
    out[5] = 0.1;
    out[6] = p[0];
    out[7] = 0.3;
}
/// One set of run-time parameter values and the values `setup` computed from it.
#[derive(Debug, Clone)]
pub struct Parameters {
    p: [f64; 2],
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
    /// Sets parameters by name. Checked first (known names, finite values, positive
    /// masses, inertias of a rigid body): a refused set changes nothing. Allocates
    /// nothing unless it is refused.
    pub fn set(&mut self, set: &[(&str, f64)]) -> Result<(), ParameterError> {
        let mut p = self.p;
        RUN_TIME.assign(&mut p, set)?;
        let mut props = [0.0; 8];
        RUN_TIME.check(&p, set, &mut props)?;
        self.p = p;
        setup(&self.p, &mut self.k);
        Ok(())
    }
    /// The values, in the order of `PARAMETERS`.
    pub fn values(&self) -> &[f64] {
        &self.p
    }
}
#[allow(clippy::type_complexity)]
fn at_parameters(
    set: &[(&str, f64)],
) -> Result<Vec<(Formulation, Box<dyn Mechanism + Sync>)>, ParameterError> {
    let mut p = Parameters::file_values();
    p.set(set)?;
    Ok(
        vec![
            (Formulation::Exact, Box::new(ExactAt(p.clone())) as Box < dyn Mechanism +
            Sync >)
        ],
    )
}
/// This mechanism at other values of its run-time parameters, for the registries.
pub static RUN_TIME_ENTRY: symbody_runtime::registry::RunTime = symbody_runtime::registry::RunTime {
    parameters: &RUN_TIME,
    build: at_parameters,
};
/// The `exact` formulation: mass matrix and forces derived from the exact kinetic energy.
pub mod exact {
    use super::*;
    /// Row of each mass-matrix nonzero (both triangles).
    pub static MASS_ROWS: [u32; 38usize] = [
        0u32, 1u32, 2u32, 3u32, 3u32, 3u32, 3u32, 4u32, 4u32, 4u32, 4u32, 5u32, 5u32,
        5u32, 5u32, 6u32, 6u32, 6u32, 6u32, 7u32, 8u32, 9u32, 10u32, 10u32, 10u32, 10u32,
        11u32, 11u32, 11u32, 11u32, 12u32, 12u32, 12u32, 12u32, 13u32, 13u32, 13u32,
        13u32,
    ];
    /// Column of each mass-matrix nonzero.
    pub static MASS_COLS: [u32; 38usize] = [
        0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32,
        5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 7u32, 8u32, 9u32, 10u32, 11u32, 12u32, 13u32,
        10u32, 11u32, 12u32, 13u32, 10u32, 11u32, 12u32, 13u32, 10u32, 11u32, 12u32,
        13u32,
    ];
    /// Row and column of each ∂Q/∂q nonzero.
    pub static FORCE_Q_ROWS: [u32; 25usize] = [
        0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 2u32, 2u32, 2u32, 10u32, 10u32, 10u32, 10u32,
        11u32, 11u32, 11u32, 11u32, 12u32, 12u32, 12u32, 12u32, 13u32, 13u32, 13u32,
        13u32,
    ];
    pub static FORCE_Q_COLS: [u32; 25usize] = [
        0u32, 1u32, 2u32, 0u32, 1u32, 2u32, 0u32, 1u32, 2u32, 10u32, 11u32, 12u32, 13u32,
        10u32, 11u32, 12u32, 13u32, 10u32, 11u32, 12u32, 13u32, 10u32, 11u32, 12u32,
        13u32,
    ];
    /// Row and column of each ∂Q/∂q̇ nonzero.
    pub static FORCE_QD_ROWS: [u32; 25usize] = [
        0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 2u32, 2u32, 2u32, 10u32, 10u32, 10u32, 10u32,
        11u32, 11u32, 11u32, 11u32, 12u32, 12u32, 12u32, 12u32, 13u32, 13u32, 13u32,
        13u32,
    ];
    pub static FORCE_QD_COLS: [u32; 25usize] = [
        0u32, 1u32, 2u32, 0u32, 1u32, 2u32, 0u32, 1u32, 2u32, 10u32, 11u32, 12u32, 13u32,
        10u32, 11u32, 12u32, 13u32, 10u32, 11u32, 12u32, 13u32, 10u32, 11u32, 12u32,
        13u32,
    ];
    /// Sizes, patterns and names for this formulation.
    pub static INFO: MechanismInfo = MechanismInfo {
        name: "oscillators",
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
        let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
        let dq: &mut [f64; 25] = dq.try_into().expect("dq must have 25 entries");
        let dqd: &mut [f64; 25] = dqd.try_into().expect("dqd must have 25 entries");
        let _ = k;
        force_jacobian_part_0(q, qd, t, dq, dqd);
    }
    #[inline(never)]
    fn force_jacobian_part_0(
        q: &[f64; 14],
        qd: &[f64; 14],
        t: f64,
        dq: &mut [f64; 25],
        dqd: &mut [f64; 25],
    ) {
        let x3 = 4.0 * t;
        let x4 = x3.sin();
        let x5 = 3.0 * x4;
        let x9 = 3.0 * t;
        let x10 = x9.cos();
        let x11 = 0.5 * x10;
        let x13 = t.sin();
        let x14 = 0.2 * x13;
        let x68 = q[10] * q[10];
        let x69 = q[11] * q[11];
        let x72 = x68 + x69;
        let x73 = 2.0 * x72;
        let x74 = x73 - 1.0;
        let x88 = q[11] * q[13];
        let x89 = 2.0 * x88;
        let x90 = q[10] * q[12];
        let x91 = 2.0 * x90;
        let x103 = x89 - x91;
        let x129 = 2.0 * q[10];
        let x130 = 2.0 * q[11];
        let x131 = 2.0 * q[12];
        let x132 = 2.0 * q[13];
        let x184 = x129 * qd[10];
        let x185 = x130 * qd[11];
        let x188 = x184 + x185;
        let x220 = 2.0 * qd[10];
        let x221 = 2.0 * qd[11];
        let x222 = 2.0 * qd[12];
        let x223 = 2.0 * qd[13];
        let x292 = 1.0 + q[0];
        let x293 = x292 * x292;
        let x294 = q[1] * q[1];
        let x295 = q[2] * q[2];
        let x296 = x293 + x294;
        let x297 = x295 + x296;
        let x298 = x297.sqrt();
        let x299 = 2.0 * x292;
        let x300 = qd[0] * x299;
        let x301 = q[1] * 2.0;
        let x302 = qd[1] * x301;
        let x303 = q[2] * 2.0;
        let x304 = qd[2] * x303;
        let x305 = x300 + x302;
        let x306 = x304 + x305;
        let x307 = 2.0 * x298;
        let x308 = 1.0 / x307;
        let x309 = x306 * x308;
        let x310 = x298 - 1.0;
        let x313 = x310 * 50.0;
        let x314 = x309 * 0.8;
        let x316 = x5 - x314;
        let x318 = x316 - x313;
        let x323 = x299 * x308;
        let x324 = x301 * x308;
        let x325 = x303 * x308;
        let x329 = -x103;
        let x330 = x329.atan2(x74);
        let x331 = 2.0 * x188;
        let x332 = q[13] * qd[11];
        let x333 = q[11] * qd[13];
        let x334 = x332 + x333;
        let x335 = 2.0 * x334;
        let x336 = q[12] * qd[10];
        let x337 = q[10] * qd[12];
        let x338 = x336 + x337;
        let x339 = 2.0 * x338;
        let x341 = x335 - x339;
        let x343 = x74 * x74;
        let x344 = x103 * x103;
        let x345 = x343 + x344;
        let x346 = x74 * x341;
        let x348 = x103 * x331;
        let x350 = x348 - x346;
        let x351 = 1.0 / x345;
        let x352 = x350 * x351;
        let x353 = 2.0 * x330;
        let x354 = 0.1 * x352;
        let x356 = x11 - x354;
        let x358 = x356 - x353;
        let x361 = 2.0 * x129;
        let x362 = x74 * x131;
        let x363 = x103 * x361;
        let x365 = x362 + x363;
        let x366 = x351 * x365;
        let x367 = 2.0 * x130;
        let x368 = x74 * x132;
        let x370 = x103 * x367;
        let x372 = x370 - x368;
        let x373 = x351 * x372;
        let x374 = x74 * x129;
        let x375 = x351 * x374;
        let x376 = x74 * x130;
        let x378 = x351 * x376;
        let x463 = 2.0 * qd[0];
        let x466 = 2.0 * qd[1];
        let x468 = 2.0 * qd[2];
        let x922 = x130 * x367;
        let x942 = x130 * x361;
        let x958 = x131 * x361;
        let x960 = x132 * x367;
        let x974 = x131 * x367;
        let x976 = x132 * x361;
        let x984 = x129 * x367;
        let x997 = x129 * x361;
        let x1259 = 2.0 * x323;
        let x1260 = x308 * x308;
        let x1261 = x1259 * x1260;
        let x1263 = x308 * x463;
        let x1264 = x306 * x1261;
        let x1266 = x1263 - x1264;
        let x1267 = 50.0 * x323;
        let x1268 = 0.8 * x1266;
        let x1271 = x1267 + x1268;
        let x1273 = 2.0 * x308;
        let x1274 = x299 * x1261;
        let x1276 = x1273 - x1274;
        let x1277 = x301 * x1261;
        let x1279 = x303 * x1261;
        let x1281 = x323 * x1271;
        let x1283 = x318 * x1276;
        let x1284 = x1283 - x1281;
        let x1285 = x324 * x1271;
        let x1287 = x318 * x1277;
        let x1289 = x1285 + x1287;
        let x1290 = -x1289;
        let x1291 = x325 * x1271;
        let x1293 = x318 * x1279;
        let x1295 = x1291 + x1293;
        let x1296 = -x1295;
        let x1297 = 2.0 * x324;
        let x1298 = x1260 * x1297;
        let x1300 = x308 * x466;
        let x1301 = x306 * x1298;
        let x1303 = x1300 - x1301;
        let x1304 = 50.0 * x324;
        let x1305 = 0.8 * x1303;
        let x1308 = x1304 + x1305;
        let x1310 = x299 * x1298;
        let x1312 = x301 * x1298;
        let x1314 = x1273 - x1312;
        let x1315 = x303 * x1298;
        let x1317 = x323 * x1308;
        let x1319 = x318 * x1310;
        let x1321 = x1317 + x1319;
        let x1322 = -x1321;
        let x1323 = x324 * x1308;
        let x1325 = x318 * x1314;
        let x1326 = x1325 - x1323;
        let x1327 = x325 * x1308;
        let x1329 = x318 * x1315;
        let x1331 = x1327 + x1329;
        let x1332 = -x1331;
        let x1333 = 2.0 * x325;
        let x1334 = x1260 * x1333;
        let x1336 = x308 * x468;
        let x1337 = x306 * x1334;
        let x1339 = x1336 - x1337;
        let x1340 = 50.0 * x325;
        let x1341 = 0.8 * x1339;
        let x1344 = x1340 + x1341;
        let x1346 = x299 * x1334;
        let x1348 = x301 * x1334;
        let x1350 = x303 * x1334;
        let x1352 = x1273 - x1350;
        let x1353 = x323 * x1344;
        let x1355 = x318 * x1346;
        let x1357 = x1353 + x1355;
        let x1358 = -x1357;
        let x1359 = x324 * x1344;
        let x1361 = x318 * x1348;
        let x1363 = x1359 + x1361;
        let x1364 = -x1363;
        let x1365 = x325 * x1344;
        let x1367 = x318 * x1352;
        let x1368 = x1367 - x1365;
        let x1369 = 2.0 * x220;
        let x1370 = 2.0 * x74;
        let x1371 = x361 * x1370;
        let x1372 = 2.0 * x103;
        let x1373 = x131 * x1372;
        let x1375 = x1371 - x1373;
        let x1376 = x341 * x361;
        let x1377 = x74 * x222;
        let x1379 = x1376 - x1377;
        let x1381 = x131 * x331;
        let x1383 = x103 * x1369;
        let x1384 = x1383 - x1381;
        let x1385 = x1384 - x1379;
        let x1386 = x351 * x351;
        let x1387 = x1375 * x1386;
        let x1389 = x351 * x1385;
        let x1390 = x350 * x1387;
        let x1392 = x1389 - x1390;
        let x1393 = 2.0 * x366;
        let x1394 = 0.1 * x1392;
        let x1397 = x1393 + x1394;
        let x1400 = 4.0 * x103;
        let x1401 = x1400 - x958;
        let x1402 = x958 + x1401;
        let x1403 = x365 * x1387;
        let x1405 = x351 * x1402;
        let x1406 = x1405 - x1403;
        let x1408 = x974 + x976;
        let x1410 = x372 * x1387;
        let x1412 = x351 * x1408;
        let x1414 = x1410 + x1412;
        let x1416 = x997 + x1370;
        let x1417 = x374 * x1387;
        let x1419 = x351 * x1416;
        let x1420 = x1419 - x1417;
        let x1421 = x376 * x1387;
        let x1423 = x351 * x942;
        let x1424 = x1423 - x1421;
        let x1425 = x366 * x1397;
        let x1427 = x358 * x1406;
        let x1428 = x1427 - x1425;
        let x1429 = x373 * x1397;
        let x1431 = x358 * x1414;
        let x1433 = x1429 + x1431;
        let x1434 = -x1433;
        let x1435 = x375 * x1397;
        let x1437 = x358 * x1420;
        let x1438 = x1437 - x1435;
        let x1439 = x378 * x1397;
        let x1441 = x358 * x1424;
        let x1442 = x1441 - x1439;
        let x1443 = x14 * 2.0;
        let x1444 = x1438 + x1443;
        let x1445 = -x1442;
        let x1446 = 2.0 * x221;
        let x1447 = x367 * x1370;
        let x1448 = x132 * x1372;
        let x1449 = x1447 + x1448;
        let x1450 = x341 * x367;
        let x1451 = x74 * x223;
        let x1452 = x1450 + x1451;
        let x1454 = x132 * x331;
        let x1455 = x103 * x1446;
        let x1456 = x1454 + x1455;
        let x1457 = x1456 - x1452;
        let x1458 = x1386 * x1449;
        let x1460 = x351 * x1457;
        let x1461 = x350 * x1458;
        let x1463 = x1460 - x1461;
        let x1464 = 2.0 * x373;
        let x1465 = 0.1 * x1463;
        let x1468 = x1464 + x1465;
        let x1470 = x365 * x1458;
        let x1472 = x1412 - x1470;
        let x1473 = x960 + x1400;
        let x1474 = x1473 - x960;
        let x1475 = x372 * x1458;
        let x1477 = x351 * x1474;
        let x1478 = x1477 - x1475;
        let x1479 = x374 * x1458;
        let x1481 = x351 * x984;
        let x1482 = x1481 - x1479;
        let x1483 = x922 + x1370;
        let x1484 = x376 * x1458;
        let x1486 = x351 * x1483;
        let x1487 = x1486 - x1484;
        let x1488 = x366 * x1468;
        let x1490 = x358 * x1472;
        let x1491 = x1490 - x1488;
        let x1492 = x373 * x1468;
        let x1494 = x358 * x1478;
        let x1495 = x1494 - x1492;
        let x1496 = x375 * x1468;
        let x1498 = x358 * x1482;
        let x1499 = x1498 - x1496;
        let x1500 = x378 * x1468;
        let x1502 = x358 * x1487;
        let x1503 = x1502 - x1500;
        let x1504 = x1443 + x1503;
        let x1505 = -x1504;
        let x1506 = x129 * x1372;
        let x1508 = x74 * x220;
        let x1510 = x129 * x331;
        let x1512 = x1508 - x1510;
        let x1513 = x1386 * x1506;
        let x1515 = x351 * x1512;
        let x1516 = x350 * x1513;
        let x1517 = x1515 + x1516;
        let x1518 = 2.0 * x375;
        let x1519 = 0.1 * x1517;
        let x1522 = x1518 + x1519;
        let x1525 = x1370 - x997;
        let x1526 = x365 * x1513;
        let x1527 = x351 * x1525;
        let x1528 = x1526 + x1527;
        let x1529 = x372 * x1513;
        let x1531 = x1529 - x1481;
        let x1532 = x374 * x1513;
        let x1533 = x376 * x1513;
        let x1534 = x366 * x1522;
        let x1536 = x358 * x1528;
        let x1537 = x1536 - x1534;
        let x1538 = x373 * x1522;
        let x1540 = x358 * x1531;
        let x1541 = x1540 - x1538;
        let x1542 = x375 * x1522;
        let x1544 = x358 * x1532;
        let x1545 = x1544 - x1542;
        let x1546 = x378 * x1522;
        let x1548 = x358 * x1533;
        let x1549 = x1548 - x1546;
        let x1551 = x1537 - x1443;
        let x1552 = -x1549;
        let x1553 = x130 * x1372;
        let x1554 = x74 * x221;
        let x1556 = x130 * x331;
        let x1557 = x1556 - x1554;
        let x1558 = x1386 * x1553;
        let x1560 = x351 * x1557;
        let x1561 = x350 * x1558;
        let x1563 = x1560 - x1561;
        let x1564 = 2.0 * x378;
        let x1566 = 0.1 * x1563;
        let x1568 = x1564 - x1566;
        let x1569 = x365 * x1558;
        let x1571 = x1423 - x1569;
        let x1573 = x922 - x1370;
        let x1574 = x372 * x1558;
        let x1576 = x351 * x1573;
        let x1577 = x1576 - x1574;
        let x1578 = x374 * x1558;
        let x1580 = x376 * x1558;
        let x1582 = x366 * x1568;
        let x1583 = x358 * x1571;
        let x1584 = x1582 + x1583;
        let x1585 = x373 * x1568;
        let x1586 = x358 * x1577;
        let x1587 = x1585 + x1586;
        let x1588 = x375 * x1568;
        let x1589 = x358 * x1578;
        let x1591 = x1588 - x1589;
        let x1592 = x378 * x1568;
        let x1593 = x358 * x1580;
        let x1595 = x1592 - x1593;
        let x1596 = x1443 + x1587;
        let x1597 = -x1595;
        let x1598 = 0.8 * x323;
        let x1600 = x323 * x1598;
        let x1601 = -x1600;
        let x1602 = x324 * x1598;
        let x1603 = -x1602;
        let x1604 = x325 * x1598;
        let x1605 = -x1604;
        let x1606 = 0.8 * x324;
        let x1608 = x323 * x1606;
        let x1609 = -x1608;
        let x1610 = x324 * x1606;
        let x1611 = -x1610;
        let x1612 = x325 * x1606;
        let x1613 = -x1612;
        let x1614 = 0.8 * x325;
        let x1616 = x323 * x1614;
        let x1617 = -x1616;
        let x1618 = x324 * x1614;
        let x1619 = -x1618;
        let x1620 = x325 * x1614;
        let x1621 = -x1620;
        let x1623 = 0.1 * x366;
        let x1625 = x366 * x1623;
        let x1626 = -x1625;
        let x1627 = x373 * x1623;
        let x1628 = -x1627;
        let x1629 = x375 * x1623;
        let x1630 = -x1629;
        let x1631 = x378 * x1623;
        let x1633 = 0.1 * x373;
        let x1635 = x366 * x1633;
        let x1636 = -x1635;
        let x1637 = x373 * x1633;
        let x1638 = -x1637;
        let x1639 = x375 * x1633;
        let x1640 = -x1639;
        let x1641 = x378 * x1633;
        let x1644 = 0.1 * x375;
        let x1646 = x366 * x1644;
        let x1647 = -x1646;
        let x1648 = x373 * x1644;
        let x1649 = -x1648;
        let x1650 = x375 * x1644;
        let x1651 = -x1650;
        let x1652 = x378 * x1644;
        let x1654 = 0.1 * x378;
        let x1656 = x366 * x1654;
        let x1657 = x373 * x1654;
        let x1658 = x375 * x1654;
        let x1659 = x378 * x1654;
        let x1660 = -x1659;
        dq[0] = x1284;
        dq[1] = x1322;
        dq[2] = x1358;
        dq[3] = x1290;
        dq[4] = x1326;
        dq[5] = x1364;
        dq[6] = x1296;
        dq[7] = x1332;
        dq[8] = x1368;
        dq[9] = x1428;
        dq[10] = x1491;
        dq[11] = x1551;
        dq[12] = x1584;
        dq[13] = x1434;
        dq[14] = x1495;
        dq[15] = x1541;
        dq[16] = x1596;
        dq[17] = x1444;
        dq[18] = x1499;
        dq[19] = x1545;
        dq[20] = x1591;
        dq[21] = x1445;
        dq[22] = x1505;
        dq[23] = x1552;
        dq[24] = x1597;
        dqd[0] = x1601;
        dqd[1] = x1609;
        dqd[2] = x1617;
        dqd[3] = x1603;
        dqd[4] = x1611;
        dqd[5] = x1619;
        dqd[6] = x1605;
        dqd[7] = x1613;
        dqd[8] = x1621;
        dqd[9] = x1626;
        dqd[10] = x1636;
        dqd[11] = x1647;
        dqd[12] = x1656;
        dqd[13] = x1628;
        dqd[14] = x1638;
        dqd[15] = x1649;
        dqd[16] = x1657;
        dqd[17] = x1630;
        dqd[18] = x1640;
        dqd[19] = x1651;
        dqd[20] = x1658;
        dqd[21] = x1631;
        dqd[22] = x1641;
        dqd[23] = x1652;
        dqd[24] = x1660;
    }
    /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
    pub fn mass(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
        let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 38] = out.try_into().expect("out must have 38 entries");
        mass_part_0(k, q, out);
    }
    #[inline(never)]
    fn mass_part_0(k: &[f64; 5], q: &[f64; 14], out: &mut [f64; 38]) {
        let x23 = q[3] * q[3];
        let x24 = q[4] * q[4];
        let x25 = q[5] * q[5];
        let x26 = q[6] * q[6];
        let x37 = q[4] * q[5];
        let x39 = q[3] * q[6];
        let x44 = q[4] * q[6];
        let x46 = q[3] * q[5];
        let x50 = q[5] * q[6];
        let x52 = q[3] * q[4];
        let x68 = q[10] * q[10];
        let x69 = q[11] * q[11];
        let x70 = q[12] * q[12];
        let x71 = q[13] * q[13];
        let x81 = q[11] * q[12];
        let x83 = q[10] * q[13];
        let x88 = q[11] * q[13];
        let x90 = q[10] * q[12];
        let x94 = q[12] * q[13];
        let x96 = q[10] * q[11];
        let x123 = q[3] * 2.0;
        let x124 = q[4] * 2.0;
        let x125 = q[5] * 2.0;
        let x126 = q[6] * 2.0;
        let x129 = 2.0 * q[10];
        let x130 = 2.0 * q[11];
        let x131 = 2.0 * q[12];
        let x132 = 2.0 * q[13];
        let x361 = 2.0 * x129;
        let x367 = 2.0 * x130;
        let x537 = 2.0 * x124;
        let x539 = 2.0 * x125;
        let x541 = 2.0 * x126;
        let x543 = x124 * x537;
        let x545 = 0.01 * x543;
        let x547 = x125 * x539;
        let x549 = 0.01 * x547;
        let x551 = x126 * x541;
        let x553 = 0.01 * x551;
        let x555 = x545 + x549;
        let x557 = x553 + x555;
        let x559 = 0.5 * x557;
        let x561 = x23 * 0.04;
        let x562 = x559 + x561;
        let x563 = 2.0 * x123;
        let x564 = x124 * x563;
        let x565 = 0.01 * x564;
        let x566 = x125 * x541;
        let x568 = 0.01 * x566;
        let x570 = x126 * x539;
        let x571 = 0.01 * x570;
        let x572 = x565 - x568;
        let x573 = x571 + x572;
        let x574 = 0.5 * x573;
        let x576 = x52 * 0.04;
        let x577 = x576 - x574;
        let x578 = x124 * x541;
        let x579 = 0.01 * x578;
        let x580 = x125 * x563;
        let x581 = 0.01 * x580;
        let x582 = x126 * x537;
        let x584 = 0.01 * x582;
        let x586 = x579 + x581;
        let x587 = x586 - x584;
        let x588 = 0.5 * x587;
        let x590 = x46 * 0.04;
        let x591 = x590 - x588;
        let x592 = x124 * x539;
        let x594 = 0.01 * x592;
        let x596 = x125 * x537;
        let x597 = 0.01 * x596;
        let x598 = x126 * x563;
        let x599 = 0.01 * x598;
        let x600 = x597 - x594;
        let x601 = x599 + x600;
        let x602 = 0.5 * x601;
        let x604 = x39 * 0.04;
        let x605 = x604 - x602;
        let x606 = x123 * x537;
        let x608 = 0.01 * x606;
        let x612 = x571 - x608;
        let x613 = x612 - x568;
        let x614 = 0.5 * x613;
        let x615 = x576 + x614;
        let x616 = x123 * x563;
        let x617 = 0.01 * x616;
        let x618 = x553 + x617;
        let x619 = x549 + x618;
        let x620 = 0.5 * x619;
        let x621 = x24 * 0.04;
        let x622 = x620 + x621;
        let x623 = x123 * x541;
        let x624 = 0.01 * x623;
        let x628 = x624 - x599;
        let x629 = x628 - x597;
        let x630 = 0.5 * x629;
        let x631 = x37 * 0.04;
        let x632 = x630 + x631;
        let x633 = x123 * x539;
        let x635 = 0.01 * x633;
        let x637 = x584 + x635;
        let x639 = x581 - x637;
        let x640 = 0.5 * x639;
        let x641 = x44 * 0.04;
        let x642 = x640 + x641;
        let x645 = x579 - x637;
        let x646 = 0.5 * x645;
        let x647 = x590 + x646;
        let x650 = x599 - x624;
        let x651 = x650 - x594;
        let x652 = 0.5 * x651;
        let x653 = x631 + x652;
        let x654 = x545 + x618;
        let x655 = 0.5 * x654;
        let x656 = x25 * 0.04;
        let x657 = x655 + x656;
        let x659 = x608 - x571;
        let x660 = x659 - x565;
        let x661 = 0.5 * x660;
        let x662 = x50 * 0.04;
        let x663 = x661 + x662;
        let x664 = x600 - x624;
        let x665 = 0.5 * x664;
        let x666 = x604 + x665;
        let x669 = x635 - x586;
        let x670 = 0.5 * x669;
        let x671 = x641 + x670;
        let x672 = x572 - x608;
        let x673 = 0.5 * x672;
        let x674 = x662 + x673;
        let x675 = x555 + x617;
        let x676 = 0.5 * x675;
        let x677 = x26 * 0.04;
        let x678 = x676 + x677;
        let x918 = 2.0 * x131;
        let x920 = 2.0 * x132;
        let x922 = x130 * x367;
        let x924 = 0.1 * x922;
        let x926 = x131 * x918;
        let x930 = x132 * x920;
        let x932 = 0.3 * x930;
        let x942 = x130 * x361;
        let x943 = 0.1 * x942;
        let x944 = x131 * x920;
        let x948 = x132 * x918;
        let x949 = 0.3 * x948;
        let x956 = x130 * x920;
        let x957 = 0.1 * x956;
        let x958 = x131 * x361;
        let x960 = x132 * x367;
        let x962 = 0.3 * x960;
        let x970 = x130 * x918;
        let x972 = 0.1 * x970;
        let x974 = x131 * x367;
        let x976 = x132 * x361;
        let x977 = 0.3 * x976;
        let x984 = x129 * x367;
        let x986 = 0.1 * x984;
        let x991 = 0.3 * x944;
        let x997 = x129 * x361;
        let x998 = 0.1 * x997;
        let x1001 = 0.3 * x926;
        let x1007 = x129 * x920;
        let x1008 = 0.1 * x1007;
        let x1012 = 0.3 * x974;
        let x1019 = x129 * x918;
        let x1021 = 0.1 * x1019;
        let x1025 = 0.3 * x958;
        let x1032 = 0.1 * x960;
        let x1037 = 0.3 * x956;
        let x1044 = 0.1 * x976;
        let x1048 = 0.3 * x970;
        let x1054 = 0.1 * x930;
        let x1056 = 0.3 * x922;
        let x1063 = 0.1 * x948;
        let x1066 = 0.3 * x942;
        let x1073 = 0.1 * x974;
        let x1077 = 0.3 * x1007;
        let x1083 = 0.1 * x958;
        let x1087 = 0.3 * x1019;
        let x1093 = 0.1 * x944;
        let x1096 = 0.3 * x984;
        let x1102 = 0.1 * x926;
        let x1105 = 0.3 * x997;
        let x1671 = x926 * k[0];
        let x1672 = x924 + x1671;
        let x1673 = x932 + x1672;
        let x1674 = 0.5 * x1673;
        let x1675 = x68 * k[4];
        let x1676 = x1674 + x1675;
        let x1677 = x944 * k[0];
        let x1679 = x943 - x1677;
        let x1680 = x949 + x1679;
        let x1681 = 0.5 * x1680;
        let x1683 = x96 * k[4];
        let x1684 = x1683 - x1681;
        let x1685 = x958 * k[0];
        let x1686 = x957 + x1685;
        let x1687 = x1686 - x962;
        let x1688 = 0.5 * x1687;
        let x1690 = x90 * k[4];
        let x1691 = x1690 - x1688;
        let x1692 = x974 * k[0];
        let x1693 = x1692 - x972;
        let x1694 = x977 + x1693;
        let x1695 = 0.5 * x1694;
        let x1697 = x83 * k[4];
        let x1698 = x1697 - x1695;
        let x1699 = x948 * k[0];
        let x1700 = x1699 - x986;
        let x1701 = x1700 - x991;
        let x1702 = 0.5 * x1701;
        let x1703 = x1683 + x1702;
        let x1704 = x930 * k[0];
        let x1705 = x998 + x1704;
        let x1706 = x1001 + x1705;
        let x1707 = 0.5 * x1706;
        let x1708 = x69 * k[4];
        let x1709 = x1707 + x1708;
        let x1710 = x976 * k[0];
        let x1712 = x1008 - x1710;
        let x1713 = x1712 - x1012;
        let x1714 = 0.5 * x1713;
        let x1715 = x81 * k[4];
        let x1716 = x1714 + x1715;
        let x1717 = x960 * k[0];
        let x1718 = x1021 + x1717;
        let x1720 = x1025 - x1718;
        let x1721 = 0.5 * x1720;
        let x1722 = x88 * k[4];
        let x1723 = x1721 + x1722;
        let x1724 = x1019 * k[0];
        let x1725 = x1032 + x1724;
        let x1727 = x1037 - x1725;
        let x1728 = 0.5 * x1727;
        let x1729 = x1690 + x1728;
        let x1730 = x1007 * k[0];
        let x1732 = x1044 - x1730;
        let x1733 = x1732 - x1048;
        let x1734 = 0.5 * x1733;
        let x1735 = x1715 + x1734;
        let x1736 = x997 * k[0];
        let x1737 = x1054 + x1736;
        let x1738 = x1056 + x1737;
        let x1739 = 0.5 * x1738;
        let x1740 = x70 * k[4];
        let x1741 = x1739 + x1740;
        let x1742 = x984 * k[0];
        let x1743 = x1742 - x1063;
        let x1744 = x1743 - x1066;
        let x1745 = 0.5 * x1744;
        let x1746 = x94 * k[4];
        let x1747 = x1745 + x1746;
        let x1748 = x970 * k[0];
        let x1750 = x1073 - x1748;
        let x1751 = x1750 - x1077;
        let x1752 = 0.5 * x1751;
        let x1753 = x1697 + x1752;
        let x1754 = x956 * k[0];
        let x1755 = x1083 + x1754;
        let x1757 = x1087 - x1755;
        let x1758 = 0.5 * x1757;
        let x1759 = x1722 + x1758;
        let x1760 = x942 * k[0];
        let x1761 = x1760 - x1093;
        let x1762 = x1761 - x1096;
        let x1763 = 0.5 * x1762;
        let x1764 = x1746 + x1763;
        let x1765 = x922 * k[0];
        let x1766 = x1102 + x1765;
        let x1767 = x1105 + x1766;
        let x1768 = 0.5 * x1767;
        let x1769 = x71 * k[4];
        let x1770 = x1768 + x1769;
        out[0] = k[3];
        out[1] = k[3];
        out[2] = k[3];
        out[3] = x562;
        out[4] = x577;
        out[5] = x591;
        out[6] = x605;
        out[7] = x615;
        out[8] = x622;
        out[9] = x632;
        out[10] = x642;
        out[11] = x647;
        out[12] = x653;
        out[13] = x657;
        out[14] = x663;
        out[15] = x666;
        out[16] = x671;
        out[17] = x674;
        out[18] = x678;
        out[19] = 1.0;
        out[20] = 1.0;
        out[21] = 1.0;
        out[22] = x1676;
        out[23] = x1684;
        out[24] = x1691;
        out[25] = x1698;
        out[26] = x1703;
        out[27] = x1709;
        out[28] = x1716;
        out[29] = x1723;
        out[30] = x1729;
        out[31] = x1735;
        out[32] = x1741;
        out[33] = x1747;
        out[34] = x1753;
        out[35] = x1759;
        out[36] = x1764;
        out[37] = x1770;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
        let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 14] = out.try_into().expect("out must have 14 entries");
        force_part_0(k, q, qd, t, out);
    }
    #[inline(never)]
    fn force_part_0(
        k: &[f64; 5],
        q: &[f64; 14],
        qd: &[f64; 14],
        t: f64,
        out: &mut [f64; 14],
    ) {
        let x3 = 4.0 * t;
        let x4 = x3.sin();
        let x5 = 3.0 * x4;
        let x9 = 3.0 * t;
        let x10 = x9.cos();
        let x11 = 0.5 * x10;
        let x13 = t.sin();
        let x14 = 0.2 * x13;
        let x68 = q[10] * q[10];
        let x69 = q[11] * q[11];
        let x72 = x68 + x69;
        let x73 = 2.0 * x72;
        let x74 = x73 - 1.0;
        let x88 = q[11] * q[13];
        let x89 = 2.0 * x88;
        let x90 = q[10] * q[12];
        let x91 = 2.0 * x90;
        let x103 = x89 - x91;
        let x123 = q[3] * 2.0;
        let x124 = q[4] * 2.0;
        let x125 = q[5] * 2.0;
        let x126 = q[6] * 2.0;
        let x129 = 2.0 * q[10];
        let x130 = 2.0 * q[11];
        let x131 = 2.0 * q[12];
        let x132 = 2.0 * q[13];
        let x156 = q[5] * qd[4];
        let x157 = q[4] * qd[5];
        let x160 = q[6] * qd[3];
        let x161 = q[3] * qd[6];
        let x164 = q[6] * qd[4];
        let x165 = q[4] * qd[6];
        let x168 = q[5] * qd[3];
        let x169 = q[3] * qd[5];
        let x173 = q[6] * qd[5];
        let x174 = q[5] * qd[6];
        let x177 = q[4] * qd[3];
        let x178 = q[3] * qd[4];
        let x184 = x129 * qd[10];
        let x185 = x130 * qd[11];
        let x188 = x184 + x185;
        let x189 = q[12] * qd[11];
        let x190 = q[11] * qd[12];
        let x193 = q[13] * qd[10];
        let x194 = q[10] * qd[13];
        let x199 = q[13] * qd[12];
        let x200 = q[12] * qd[13];
        let x203 = q[11] * qd[10];
        let x204 = q[10] * qd[11];
        let x216 = 2.0 * qd[3];
        let x217 = 2.0 * qd[4];
        let x218 = 2.0 * qd[5];
        let x219 = 2.0 * qd[6];
        let x220 = 2.0 * qd[10];
        let x221 = 2.0 * qd[11];
        let x222 = 2.0 * qd[12];
        let x223 = 2.0 * qd[13];
        let x229 = qd[4] * qd[5];
        let x232 = qd[3] * qd[6];
        let x235 = qd[4] * qd[6];
        let x238 = qd[3] * qd[5];
        let x256 = qd[11] * qd[12];
        let x259 = qd[10] * qd[13];
        let x292 = 1.0 + q[0];
        let x293 = x292 * x292;
        let x294 = q[1] * q[1];
        let x295 = q[2] * q[2];
        let x296 = x293 + x294;
        let x297 = x295 + x296;
        let x298 = x297.sqrt();
        let x299 = 2.0 * x292;
        let x300 = qd[0] * x299;
        let x301 = q[1] * 2.0;
        let x302 = qd[1] * x301;
        let x303 = q[2] * 2.0;
        let x304 = qd[2] * x303;
        let x305 = x300 + x302;
        let x306 = x304 + x305;
        let x307 = 2.0 * x298;
        let x308 = 1.0 / x307;
        let x309 = x306 * x308;
        let x310 = x298 - 1.0;
        let x313 = x310 * 50.0;
        let x314 = x309 * 0.8;
        let x316 = x5 - x314;
        let x318 = x316 - x313;
        let x323 = x299 * x308;
        let x324 = x301 * x308;
        let x325 = x303 * x308;
        let x326 = x318 * x323;
        let x327 = x318 * x324;
        let x328 = x318 * x325;
        let x329 = -x103;
        let x330 = x329.atan2(x74);
        let x331 = 2.0 * x188;
        let x332 = q[13] * qd[11];
        let x333 = q[11] * qd[13];
        let x334 = x332 + x333;
        let x335 = 2.0 * x334;
        let x336 = q[12] * qd[10];
        let x337 = q[10] * qd[12];
        let x338 = x336 + x337;
        let x339 = 2.0 * x338;
        let x341 = x335 - x339;
        let x343 = x74 * x74;
        let x344 = x103 * x103;
        let x345 = x343 + x344;
        let x346 = x74 * x341;
        let x348 = x103 * x331;
        let x350 = x348 - x346;
        let x351 = 1.0 / x345;
        let x352 = x350 * x351;
        let x353 = 2.0 * x330;
        let x354 = 0.1 * x352;
        let x356 = x11 - x354;
        let x358 = x356 - x353;
        let x361 = 2.0 * x129;
        let x362 = x74 * x131;
        let x363 = x103 * x361;
        let x365 = x362 + x363;
        let x366 = x351 * x365;
        let x367 = 2.0 * x130;
        let x368 = x74 * x132;
        let x370 = x103 * x367;
        let x372 = x370 - x368;
        let x373 = x351 * x372;
        let x374 = x74 * x129;
        let x375 = x351 * x374;
        let x376 = x74 * x130;
        let x378 = x351 * x376;
        let x380 = x358 * x366;
        let x381 = x358 * x373;
        let x382 = x358 * x375;
        let x383 = x358 * x378;
        let x387 = x204 - x203;
        let x408 = x14 * x131;
        let x410 = x14 * x132;
        let x411 = x14 * x129;
        let x412 = x14 * x130;
        let x414 = 1.0 + x326;
        let x415 = x380 - x408;
        let x416 = x381 + x410;
        let x417 = x382 + x411;
        let x418 = x383 + x412;
        let x428 = x178 - x177;
        let x429 = x173 + x428;
        let x430 = x429 - x174;
        let x431 = 2.0 * x430;
        let x434 = x164 + x168;
        let x436 = x169 - x434;
        let x437 = x165 + x436;
        let x438 = 2.0 * x437;
        let x441 = x156 - x160;
        let x442 = x441 - x157;
        let x443 = x161 + x442;
        let x444 = 2.0 * x443;
        let x465 = 2.0 * x431;
        let x467 = 2.0 * x438;
        let x469 = 2.0 * x444;
        let x681 = x235 + x238;
        let x683 = x238 - x681;
        let x684 = x235 + x683;
        let x685 = 2.0 * x684;
        let x688 = x229 - x232;
        let x689 = x688 - x229;
        let x690 = x232 + x689;
        let x691 = 2.0 * x690;
        let x692 = 2.0 * x685;
        let x693 = 2.0 * x691;
        let x694 = x217 * x465;
        let x695 = 0.01 * x694;
        let x696 = x218 * x467;
        let x697 = x125 * x692;
        let x698 = x696 + x697;
        let x699 = 0.01 * x698;
        let x700 = x219 * x469;
        let x701 = x126 * x693;
        let x702 = x700 + x701;
        let x703 = 0.01 * x702;
        let x704 = x695 + x699;
        let x705 = x703 + x704;
        let x706 = 0.5 * x705;
        let x708 = x216 * x465;
        let x709 = 0.01 * x708;
        let x710 = x219 * x467;
        let x711 = x126 * x692;
        let x712 = x710 + x711;
        let x713 = 0.01 * x712;
        let x715 = x218 * x469;
        let x716 = x125 * x693;
        let x717 = x715 + x716;
        let x718 = 0.01 * x717;
        let x719 = x709 - x713;
        let x720 = x718 + x719;
        let x721 = 0.5 * x720;
        let x722 = x219 * x465;
        let x723 = 0.01 * x722;
        let x724 = x216 * x467;
        let x725 = x123 * x692;
        let x726 = x724 + x725;
        let x727 = 0.01 * x726;
        let x728 = x217 * x469;
        let x729 = x124 * x693;
        let x730 = x728 + x729;
        let x731 = 0.01 * x730;
        let x733 = x723 + x727;
        let x734 = x733 - x731;
        let x735 = 0.5 * x734;
        let x736 = x218 * x465;
        let x737 = 0.01 * x736;
        let x739 = x217 * x467;
        let x740 = x124 * x692;
        let x741 = x739 + x740;
        let x742 = 0.01 * x741;
        let x743 = x216 * x469;
        let x744 = x123 * x693;
        let x745 = x743 + x744;
        let x746 = 0.01 * x745;
        let x747 = x742 - x737;
        let x748 = x746 + x747;
        let x749 = 0.5 * x748;
        let x750 = qd[3] * qd[3];
        let x751 = qd[4] * qd[4];
        let x752 = qd[5] * qd[5];
        let x753 = qd[6] * qd[6];
        let x754 = x750 + x751;
        let x755 = x752 + x754;
        let x756 = x753 + x755;
        let x757 = 0.01 * x696;
        let x758 = 0.01 * x700;
        let x759 = x695 + x757;
        let x760 = x758 + x759;
        let x761 = 0.5 * x760;
        let x762 = x706 + x761;
        let x763 = q[3] * 0.04;
        let x764 = x756 * x763;
        let x766 = x762 - x764;
        let x773 = 0.01 * x710;
        let x775 = 0.01 * x715;
        let x777 = x773 - x709;
        let x778 = x777 - x775;
        let x779 = 0.5 * x778;
        let x781 = x779 - x721;
        let x782 = q[4] * 0.04;
        let x783 = x756 * x782;
        let x785 = x781 - x783;
        let x791 = 0.01 * x724;
        let x793 = 0.01 * x728;
        let x794 = x723 + x791;
        let x796 = x793 - x794;
        let x797 = 0.5 * x796;
        let x799 = x797 - x735;
        let x800 = q[5] * 0.04;
        let x801 = x756 * x800;
        let x803 = x799 - x801;
        let x807 = 0.01 * x739;
        let x810 = 0.01 * x743;
        let x812 = x737 - x807;
        let x813 = x812 - x810;
        let x814 = 0.5 * x813;
        let x816 = x814 - x749;
        let x817 = q[6] * 0.04;
        let x818 = x756 * x817;
        let x820 = x816 - x818;
        let x823 = x199 + x387;
        let x824 = x823 - x200;
        let x825 = 2.0 * x824;
        let x827 = x332 + x336;
        let x829 = x337 - x827;
        let x830 = x333 + x829;
        let x831 = 2.0 * x830;
        let x833 = x189 - x193;
        let x834 = x833 - x190;
        let x835 = x194 + x834;
        let x836 = 2.0 * x835;
        let x853 = 2.0 * x825;
        let x855 = 2.0 * x831;
        let x857 = 2.0 * x836;
        let x1111 = qd[11] * qd[13];
        let x1112 = qd[10] * qd[12];
        let x1116 = x1111 + x1112;
        let x1118 = x1112 - x1116;
        let x1119 = x1111 + x1118;
        let x1120 = 2.0 * x1119;
        let x1122 = x256 - x259;
        let x1123 = x1122 - x256;
        let x1124 = x259 + x1123;
        let x1125 = 2.0 * x1124;
        let x1126 = 2.0 * x1120;
        let x1127 = 2.0 * x1125;
        let x1128 = x221 * x853;
        let x1129 = 0.1 * x1128;
        let x1130 = x222 * x855;
        let x1131 = x131 * x1126;
        let x1132 = x1130 + x1131;
        let x1134 = x223 * x857;
        let x1135 = x132 * x1127;
        let x1136 = x1134 + x1135;
        let x1137 = 0.3 * x1136;
        let x1142 = x220 * x853;
        let x1143 = 0.1 * x1142;
        let x1144 = x223 * x855;
        let x1145 = x132 * x1126;
        let x1146 = x1144 + x1145;
        let x1149 = x222 * x857;
        let x1150 = x131 * x1127;
        let x1151 = x1149 + x1150;
        let x1152 = 0.3 * x1151;
        let x1156 = x223 * x853;
        let x1157 = 0.1 * x1156;
        let x1158 = x220 * x855;
        let x1159 = x129 * x1126;
        let x1160 = x1158 + x1159;
        let x1162 = x221 * x857;
        let x1163 = x130 * x1127;
        let x1164 = x1162 + x1163;
        let x1165 = 0.3 * x1164;
        let x1170 = x222 * x853;
        let x1171 = 0.1 * x1170;
        let x1173 = x221 * x855;
        let x1174 = x130 * x1126;
        let x1175 = x1173 + x1174;
        let x1177 = x220 * x857;
        let x1178 = x129 * x1127;
        let x1179 = x1177 + x1178;
        let x1180 = 0.3 * x1179;
        let x1184 = qd[10] * qd[10];
        let x1185 = qd[11] * qd[11];
        let x1186 = qd[12] * qd[12];
        let x1187 = qd[13] * qd[13];
        let x1188 = x1184 + x1185;
        let x1189 = x1186 + x1188;
        let x1190 = x1187 + x1189;
        let x1192 = 0.3 * x1134;
        let x1209 = 0.3 * x1149;
        let x1227 = 0.3 * x1162;
        let x1244 = 0.3 * x1177;
        let x1669 = x327 + k[2];
        let x1771 = x1132 * k[0];
        let x1772 = x1129 + x1771;
        let x1773 = x1137 + x1772;
        let x1774 = 0.5 * x1773;
        let x1775 = x1146 * k[0];
        let x1777 = x1143 - x1775;
        let x1778 = x1152 + x1777;
        let x1779 = 0.5 * x1778;
        let x1780 = x1160 * k[0];
        let x1781 = x1157 + x1780;
        let x1782 = x1781 - x1165;
        let x1783 = 0.5 * x1782;
        let x1784 = x1175 * k[0];
        let x1785 = x1784 - x1171;
        let x1786 = x1180 + x1785;
        let x1787 = 0.5 * x1786;
        let x1788 = x1130 * k[0];
        let x1789 = x1129 + x1788;
        let x1790 = x1192 + x1789;
        let x1791 = 0.5 * x1790;
        let x1792 = x1774 + x1791;
        let x1793 = q[10] * k[4];
        let x1794 = x1190 * x1793;
        let x1796 = x1792 - x1794;
        let x1797 = x1144 * k[0];
        let x1798 = x1797 - x1143;
        let x1799 = x1798 - x1209;
        let x1800 = 0.5 * x1799;
        let x1802 = x1800 - x1779;
        let x1803 = q[11] * k[4];
        let x1804 = x1190 * x1803;
        let x1806 = x1802 - x1804;
        let x1807 = x1158 * k[0];
        let x1808 = x1157 + x1807;
        let x1810 = x1227 - x1808;
        let x1811 = 0.5 * x1810;
        let x1813 = x1811 - x1783;
        let x1814 = q[12] * k[4];
        let x1815 = x1190 * x1814;
        let x1817 = x1813 - x1815;
        let x1818 = x1173 * k[0];
        let x1820 = x1171 - x1818;
        let x1821 = x1820 - x1244;
        let x1822 = 0.5 * x1821;
        let x1824 = x1822 - x1787;
        let x1825 = q[13] * k[4];
        let x1826 = x1190 * x1825;
        let x1828 = x1824 - x1826;
        let x1829 = x415 + x1796;
        let x1830 = x416 + x1806;
        let x1831 = x417 + x1817;
        let x1832 = x1828 - x418;
        out[0] = x414;
        out[1] = x1669;
        out[2] = x328;
        out[3] = x766;
        out[4] = x785;
        out[5] = x803;
        out[6] = x820;
        out[7] = 0.0;
        out[8] = -9.81;
        out[9] = 0.0;
        out[10] = x1829;
        out[11] = x1830;
        out[12] = x1831;
        out[13] = x1832;
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
        let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 12] = phi.try_into().expect("phi must have 12 entries");
        let phi_q: &mut [f64; 33] = phi_q
            .try_into()
            .expect("phi_q must have 33 entries");
        let mass: &mut [f64; 38] = mass.try_into().expect("mass must have 38 entries");
        let force: &mut [f64; 14] = force
            .try_into()
            .expect("force must have 14 entries");
        let mut s = [0.0f64; 94];
        eval_newton_shared_0(k, q, qd, t, &mut s);
        eval_newton_part_0(k, q, qd, t, &s, phi, phi_q, mass, force);
        eval_newton_part_1(k, q, qd, &s, force);
    }
    #[inline(never)]
    fn eval_newton_shared_0(
        _k: &[f64; 5],
        q: &[f64; 14],
        qd: &[f64; 14],
        t: f64,
        s: &mut [f64; 94],
    ) {
        let x9 = 3.0 * t;
        s[0] = x9;
        let x10 = x9.cos();
        s[1] = x10;
        let x11 = 0.5 * x10;
        s[2] = x11;
        let x13 = t.sin();
        s[3] = x13;
        let x14 = 0.2 * x13;
        s[4] = x14;
        let x68 = q[10] * q[10];
        s[5] = x68;
        let x69 = q[11] * q[11];
        s[6] = x69;
        let x72 = x68 + x69;
        s[7] = x72;
        let x73 = 2.0 * x72;
        s[8] = x73;
        let x74 = x73 - 1.0;
        s[9] = x74;
        let x88 = q[11] * q[13];
        s[10] = x88;
        let x89 = 2.0 * x88;
        s[11] = x89;
        let x90 = q[10] * q[12];
        s[12] = x90;
        let x91 = 2.0 * x90;
        s[13] = x91;
        let x103 = x89 - x91;
        s[14] = x103;
        let x129 = 2.0 * q[10];
        s[15] = x129;
        let x130 = 2.0 * q[11];
        s[16] = x130;
        let x131 = 2.0 * q[12];
        s[17] = x131;
        let x132 = 2.0 * q[13];
        s[18] = x132;
        let x184 = x129 * qd[10];
        s[19] = x184;
        let x185 = x130 * qd[11];
        s[20] = x185;
        let x188 = x184 + x185;
        s[21] = x188;
        let x189 = q[12] * qd[11];
        s[22] = x189;
        let x190 = q[11] * qd[12];
        s[23] = x190;
        let x193 = q[13] * qd[10];
        s[24] = x193;
        let x194 = q[10] * qd[13];
        s[25] = x194;
        let x199 = q[13] * qd[12];
        s[26] = x199;
        let x200 = q[12] * qd[13];
        s[27] = x200;
        let x203 = q[11] * qd[10];
        s[28] = x203;
        let x204 = q[10] * qd[11];
        s[29] = x204;
        let x221 = 2.0 * qd[11];
        s[30] = x221;
        let x222 = 2.0 * qd[12];
        s[31] = x222;
        let x223 = 2.0 * qd[13];
        s[32] = x223;
        let x256 = qd[11] * qd[12];
        s[33] = x256;
        let x259 = qd[10] * qd[13];
        s[34] = x259;
        let x329 = -x103;
        s[35] = x329;
        let x330 = x329.atan2(x74);
        s[36] = x330;
        let x331 = 2.0 * x188;
        s[37] = x331;
        let x332 = q[13] * qd[11];
        s[38] = x332;
        let x333 = q[11] * qd[13];
        s[39] = x333;
        let x334 = x332 + x333;
        s[40] = x334;
        let x335 = 2.0 * x334;
        s[41] = x335;
        let x336 = q[12] * qd[10];
        s[42] = x336;
        let x337 = q[10] * qd[12];
        s[43] = x337;
        let x338 = x336 + x337;
        s[44] = x338;
        let x339 = 2.0 * x338;
        s[45] = x339;
        let x341 = x335 - x339;
        s[46] = x341;
        let x343 = x74 * x74;
        s[47] = x343;
        let x344 = x103 * x103;
        s[48] = x344;
        let x345 = x343 + x344;
        s[49] = x345;
        let x346 = x74 * x341;
        s[50] = x346;
        let x348 = x103 * x331;
        s[51] = x348;
        let x350 = x348 - x346;
        s[52] = x350;
        let x351 = 1.0 / x345;
        s[53] = x351;
        let x352 = x350 * x351;
        s[54] = x352;
        let x353 = 2.0 * x330;
        s[55] = x353;
        let x354 = 0.1 * x352;
        s[56] = x354;
        let x356 = x11 - x354;
        s[57] = x356;
        let x358 = x356 - x353;
        s[58] = x358;
        let x367 = 2.0 * x130;
        s[59] = x367;
        let x387 = x204 - x203;
        s[60] = x387;
        let x823 = x199 + x387;
        s[61] = x823;
        let x824 = x823 - x200;
        s[62] = x824;
        let x825 = 2.0 * x824;
        s[63] = x825;
        let x827 = x332 + x336;
        s[64] = x827;
        let x829 = x337 - x827;
        s[65] = x829;
        let x830 = x333 + x829;
        s[66] = x830;
        let x831 = 2.0 * x830;
        s[67] = x831;
        let x833 = x189 - x193;
        s[68] = x833;
        let x834 = x833 - x190;
        s[69] = x834;
        let x835 = x194 + x834;
        s[70] = x835;
        let x836 = 2.0 * x835;
        s[71] = x836;
        let x853 = 2.0 * x825;
        s[72] = x853;
        let x855 = 2.0 * x831;
        s[73] = x855;
        let x857 = 2.0 * x836;
        s[74] = x857;
        let x1111 = qd[11] * qd[13];
        s[75] = x1111;
        let x1112 = qd[10] * qd[12];
        s[76] = x1112;
        let x1116 = x1111 + x1112;
        s[77] = x1116;
        let x1118 = x1112 - x1116;
        s[78] = x1118;
        let x1119 = x1111 + x1118;
        s[79] = x1119;
        let x1120 = 2.0 * x1119;
        s[80] = x1120;
        let x1122 = x256 - x259;
        s[81] = x1122;
        let x1123 = x1122 - x256;
        s[82] = x1123;
        let x1124 = x259 + x1123;
        s[83] = x1124;
        let x1125 = 2.0 * x1124;
        s[84] = x1125;
        let x1126 = 2.0 * x1120;
        s[85] = x1126;
        let x1127 = 2.0 * x1125;
        s[86] = x1127;
        let x1184 = qd[10] * qd[10];
        s[87] = x1184;
        let x1185 = qd[11] * qd[11];
        s[88] = x1185;
        let x1186 = qd[12] * qd[12];
        s[89] = x1186;
        let x1187 = qd[13] * qd[13];
        s[90] = x1187;
        let x1188 = x1184 + x1185;
        s[91] = x1188;
        let x1189 = x1186 + x1188;
        s[92] = x1189;
        let x1190 = x1187 + x1189;
        s[93] = x1190;
    }
    #[inline(never)]
    fn eval_newton_part_0(
        k: &[f64; 5],
        q: &[f64; 14],
        qd: &[f64; 14],
        t: f64,
        s: &[f64; 94],
        phi: &mut [f64; 12],
        phi_q: &mut [f64; 33],
        mass: &mut [f64; 38],
        force: &mut [f64; 14],
    ) {
        let x3 = 4.0 * t;
        let x4 = x3.sin();
        let x5 = 3.0 * x4;
        let x23 = q[3] * q[3];
        let x24 = q[4] * q[4];
        let x25 = q[5] * q[5];
        let x26 = q[6] * q[6];
        let x27 = x23 + x24;
        let x37 = q[4] * q[5];
        let x38 = 2.0 * x37;
        let x39 = q[3] * q[6];
        let x41 = 2.0 * x39;
        let x44 = q[4] * q[6];
        let x45 = 2.0 * x44;
        let x46 = q[3] * q[5];
        let x47 = 2.0 * x46;
        let x49 = x38 + x41;
        let x50 = q[5] * q[6];
        let x51 = 2.0 * x50;
        let x52 = q[3] * q[4];
        let x54 = 2.0 * x52;
        let x59 = x45 - x47;
        let x60 = x51 + x54;
        let x70 = q[12] * q[12];
        let x71 = q[13] * q[13];
        let x81 = q[11] * q[12];
        let x82 = 2.0 * x81;
        let x83 = q[10] * q[13];
        let x85 = 2.0 * x83;
        let x87 = x82 - x85;
        let x94 = q[12] * q[13];
        let x95 = 2.0 * x94;
        let x96 = q[10] * q[11];
        let x98 = 2.0 * x96;
        let x104 = x95 + x98;
        let x111 = -q[7];
        let x113 = 1.0 - q[8];
        let x115 = 2.0 - q[9];
        let x116 = -x104;
        let x117 = x25 + x27;
        let x118 = x26 + x117;
        let x119 = x118 - 1.0;
        let x120 = x70 + s[7];
        let x121 = x71 + x120;
        let x122 = x121 - 1.0;
        let x123 = q[3] * 2.0;
        let x124 = q[4] * 2.0;
        let x125 = q[5] * 2.0;
        let x126 = q[6] * 2.0;
        let x127 = -x125;
        let x128 = -x123;
        let x133 = -s[18];
        let x134 = -s[16];
        let x135 = -s[15];
        let x136 = -s[17];
        let x156 = q[5] * qd[4];
        let x157 = q[4] * qd[5];
        let x160 = q[6] * qd[3];
        let x161 = q[3] * qd[6];
        let x164 = q[6] * qd[4];
        let x165 = q[4] * qd[6];
        let x168 = q[5] * qd[3];
        let x169 = q[3] * qd[5];
        let x173 = q[6] * qd[5];
        let x174 = q[5] * qd[6];
        let x177 = q[4] * qd[3];
        let x178 = q[3] * qd[4];
        let x216 = 2.0 * qd[3];
        let x217 = 2.0 * qd[4];
        let x218 = 2.0 * qd[5];
        let x219 = 2.0 * qd[6];
        let x229 = qd[4] * qd[5];
        let x232 = qd[3] * qd[6];
        let x235 = qd[4] * qd[6];
        let x238 = qd[3] * qd[5];
        let x292 = 1.0 + q[0];
        let x293 = x292 * x292;
        let x294 = q[1] * q[1];
        let x295 = q[2] * q[2];
        let x296 = x293 + x294;
        let x297 = x295 + x296;
        let x298 = x297.sqrt();
        let x299 = 2.0 * x292;
        let x300 = qd[0] * x299;
        let x301 = q[1] * 2.0;
        let x302 = qd[1] * x301;
        let x303 = q[2] * 2.0;
        let x304 = qd[2] * x303;
        let x305 = x300 + x302;
        let x306 = x304 + x305;
        let x307 = 2.0 * x298;
        let x308 = 1.0 / x307;
        let x309 = x306 * x308;
        let x310 = x298 - 1.0;
        let x313 = x310 * 50.0;
        let x314 = x309 * 0.8;
        let x316 = x5 - x314;
        let x318 = x316 - x313;
        let x323 = x299 * x308;
        let x324 = x301 * x308;
        let x325 = x303 * x308;
        let x326 = x318 * x323;
        let x327 = x318 * x324;
        let x328 = x318 * x325;
        let x361 = 2.0 * s[15];
        let x362 = s[9] * s[17];
        let x363 = s[14] * x361;
        let x365 = x362 + x363;
        let x366 = s[53] * x365;
        let x380 = s[58] * x366;
        let x408 = s[4] * s[17];
        let x414 = 1.0 + x326;
        let x415 = x380 - x408;
        let x428 = x178 - x177;
        let x429 = x173 + x428;
        let x430 = x429 - x174;
        let x431 = 2.0 * x430;
        let x434 = x164 + x168;
        let x436 = x169 - x434;
        let x437 = x165 + x436;
        let x438 = 2.0 * x437;
        let x441 = x156 - x160;
        let x442 = x441 - x157;
        let x443 = x161 + x442;
        let x444 = 2.0 * x443;
        let x465 = 2.0 * x431;
        let x467 = 2.0 * x438;
        let x469 = 2.0 * x444;
        let x537 = 2.0 * x124;
        let x539 = 2.0 * x125;
        let x541 = 2.0 * x126;
        let x543 = x124 * x537;
        let x545 = 0.01 * x543;
        let x547 = x125 * x539;
        let x549 = 0.01 * x547;
        let x551 = x126 * x541;
        let x553 = 0.01 * x551;
        let x555 = x545 + x549;
        let x557 = x553 + x555;
        let x559 = 0.5 * x557;
        let x561 = x23 * 0.04;
        let x562 = x559 + x561;
        let x563 = 2.0 * x123;
        let x564 = x124 * x563;
        let x565 = 0.01 * x564;
        let x566 = x125 * x541;
        let x568 = 0.01 * x566;
        let x570 = x126 * x539;
        let x571 = 0.01 * x570;
        let x572 = x565 - x568;
        let x573 = x571 + x572;
        let x574 = 0.5 * x573;
        let x576 = x52 * 0.04;
        let x577 = x576 - x574;
        let x578 = x124 * x541;
        let x579 = 0.01 * x578;
        let x580 = x125 * x563;
        let x581 = 0.01 * x580;
        let x582 = x126 * x537;
        let x584 = 0.01 * x582;
        let x586 = x579 + x581;
        let x587 = x586 - x584;
        let x588 = 0.5 * x587;
        let x590 = x46 * 0.04;
        let x591 = x590 - x588;
        let x592 = x124 * x539;
        let x594 = 0.01 * x592;
        let x596 = x125 * x537;
        let x597 = 0.01 * x596;
        let x598 = x126 * x563;
        let x599 = 0.01 * x598;
        let x600 = x597 - x594;
        let x601 = x599 + x600;
        let x602 = 0.5 * x601;
        let x604 = x39 * 0.04;
        let x605 = x604 - x602;
        let x606 = x123 * x537;
        let x608 = 0.01 * x606;
        let x612 = x571 - x608;
        let x613 = x612 - x568;
        let x614 = 0.5 * x613;
        let x615 = x576 + x614;
        let x616 = x123 * x563;
        let x617 = 0.01 * x616;
        let x618 = x553 + x617;
        let x619 = x549 + x618;
        let x620 = 0.5 * x619;
        let x621 = x24 * 0.04;
        let x622 = x620 + x621;
        let x623 = x123 * x541;
        let x624 = 0.01 * x623;
        let x628 = x624 - x599;
        let x629 = x628 - x597;
        let x630 = 0.5 * x629;
        let x631 = x37 * 0.04;
        let x632 = x630 + x631;
        let x633 = x123 * x539;
        let x635 = 0.01 * x633;
        let x637 = x584 + x635;
        let x639 = x581 - x637;
        let x640 = 0.5 * x639;
        let x641 = x44 * 0.04;
        let x642 = x640 + x641;
        let x645 = x579 - x637;
        let x646 = 0.5 * x645;
        let x647 = x590 + x646;
        let x650 = x599 - x624;
        let x651 = x650 - x594;
        let x652 = 0.5 * x651;
        let x653 = x631 + x652;
        let x654 = x545 + x618;
        let x655 = 0.5 * x654;
        let x656 = x25 * 0.04;
        let x657 = x655 + x656;
        let x659 = x608 - x571;
        let x660 = x659 - x565;
        let x661 = 0.5 * x660;
        let x662 = x50 * 0.04;
        let x663 = x661 + x662;
        let x664 = x600 - x624;
        let x665 = 0.5 * x664;
        let x666 = x604 + x665;
        let x669 = x635 - x586;
        let x670 = 0.5 * x669;
        let x671 = x641 + x670;
        let x672 = x572 - x608;
        let x673 = 0.5 * x672;
        let x674 = x662 + x673;
        let x675 = x555 + x617;
        let x676 = 0.5 * x675;
        let x677 = x26 * 0.04;
        let x678 = x676 + x677;
        let x681 = x235 + x238;
        let x683 = x238 - x681;
        let x684 = x235 + x683;
        let x685 = 2.0 * x684;
        let x688 = x229 - x232;
        let x689 = x688 - x229;
        let x690 = x232 + x689;
        let x691 = 2.0 * x690;
        let x692 = 2.0 * x685;
        let x693 = 2.0 * x691;
        let x694 = x217 * x465;
        let x695 = 0.01 * x694;
        let x696 = x218 * x467;
        let x697 = x125 * x692;
        let x698 = x696 + x697;
        let x699 = 0.01 * x698;
        let x700 = x219 * x469;
        let x701 = x126 * x693;
        let x702 = x700 + x701;
        let x703 = 0.01 * x702;
        let x704 = x695 + x699;
        let x705 = x703 + x704;
        let x706 = 0.5 * x705;
        let x708 = x216 * x465;
        let x709 = 0.01 * x708;
        let x710 = x219 * x467;
        let x711 = x126 * x692;
        let x712 = x710 + x711;
        let x713 = 0.01 * x712;
        let x715 = x218 * x469;
        let x716 = x125 * x693;
        let x717 = x715 + x716;
        let x718 = 0.01 * x717;
        let x719 = x709 - x713;
        let x720 = x718 + x719;
        let x721 = 0.5 * x720;
        let x722 = x219 * x465;
        let x723 = 0.01 * x722;
        let x724 = x216 * x467;
        let x725 = x123 * x692;
        let x726 = x724 + x725;
        let x727 = 0.01 * x726;
        let x728 = x217 * x469;
        let x729 = x124 * x693;
        let x730 = x728 + x729;
        let x731 = 0.01 * x730;
        let x733 = x723 + x727;
        let x734 = x733 - x731;
        let x735 = 0.5 * x734;
        let x736 = x218 * x465;
        let x737 = 0.01 * x736;
        let x739 = x217 * x467;
        let x740 = x124 * x692;
        let x741 = x739 + x740;
        let x742 = 0.01 * x741;
        let x743 = x216 * x469;
        let x744 = x123 * x693;
        let x745 = x743 + x744;
        let x746 = 0.01 * x745;
        let x747 = x742 - x737;
        let x748 = x746 + x747;
        let x749 = 0.5 * x748;
        let x750 = qd[3] * qd[3];
        let x751 = qd[4] * qd[4];
        let x752 = qd[5] * qd[5];
        let x753 = qd[6] * qd[6];
        let x754 = x750 + x751;
        let x755 = x752 + x754;
        let x756 = x753 + x755;
        let x757 = 0.01 * x696;
        let x758 = 0.01 * x700;
        let x759 = x695 + x757;
        let x760 = x758 + x759;
        let x761 = 0.5 * x760;
        let x762 = x706 + x761;
        let x763 = q[3] * 0.04;
        let x764 = x756 * x763;
        let x766 = x762 - x764;
        let x773 = 0.01 * x710;
        let x775 = 0.01 * x715;
        let x777 = x773 - x709;
        let x778 = x777 - x775;
        let x779 = 0.5 * x778;
        let x781 = x779 - x721;
        let x782 = q[4] * 0.04;
        let x783 = x756 * x782;
        let x785 = x781 - x783;
        let x791 = 0.01 * x724;
        let x793 = 0.01 * x728;
        let x794 = x723 + x791;
        let x796 = x793 - x794;
        let x797 = 0.5 * x796;
        let x799 = x797 - x735;
        let x800 = q[5] * 0.04;
        let x801 = x756 * x800;
        let x803 = x799 - x801;
        let x807 = 0.01 * x739;
        let x810 = 0.01 * x743;
        let x812 = x737 - x807;
        let x813 = x812 - x810;
        let x814 = 0.5 * x813;
        let x816 = x814 - x749;
        let x817 = q[6] * 0.04;
        let x818 = x756 * x817;
        let x820 = x816 - x818;
        let x918 = 2.0 * s[17];
        let x920 = 2.0 * s[18];
        let x922 = s[16] * s[59];
        let x924 = 0.1 * x922;
        let x926 = s[17] * x918;
        let x930 = s[18] * x920;
        let x932 = 0.3 * x930;
        let x942 = s[16] * x361;
        let x943 = 0.1 * x942;
        let x944 = s[17] * x920;
        let x948 = s[18] * x918;
        let x949 = 0.3 * x948;
        let x956 = s[16] * x920;
        let x957 = 0.1 * x956;
        let x958 = s[17] * x361;
        let x960 = s[18] * s[59];
        let x962 = 0.3 * x960;
        let x970 = s[16] * x918;
        let x972 = 0.1 * x970;
        let x974 = s[17] * s[59];
        let x976 = s[18] * x361;
        let x977 = 0.3 * x976;
        let x984 = s[15] * s[59];
        let x986 = 0.1 * x984;
        let x991 = 0.3 * x944;
        let x997 = s[15] * x361;
        let x998 = 0.1 * x997;
        let x1001 = 0.3 * x926;
        let x1007 = s[15] * x920;
        let x1008 = 0.1 * x1007;
        let x1012 = 0.3 * x974;
        let x1019 = s[15] * x918;
        let x1021 = 0.1 * x1019;
        let x1025 = 0.3 * x958;
        let x1032 = 0.1 * x960;
        let x1037 = 0.3 * x956;
        let x1044 = 0.1 * x976;
        let x1048 = 0.3 * x970;
        let x1054 = 0.1 * x930;
        let x1056 = 0.3 * x922;
        let x1063 = 0.1 * x948;
        let x1066 = 0.3 * x942;
        let x1073 = 0.1 * x974;
        let x1077 = 0.3 * x1007;
        let x1083 = 0.1 * x958;
        let x1087 = 0.3 * x1019;
        let x1093 = 0.1 * x944;
        let x1096 = 0.3 * x984;
        let x1102 = 0.1 * x926;
        let x1105 = 0.3 * x997;
        let x1128 = s[30] * s[72];
        let x1129 = 0.1 * x1128;
        let x1130 = s[31] * s[73];
        let x1131 = s[17] * s[85];
        let x1132 = x1130 + x1131;
        let x1134 = s[32] * s[74];
        let x1135 = s[18] * s[86];
        let x1136 = x1134 + x1135;
        let x1137 = 0.3 * x1136;
        let x1192 = 0.3 * x1134;
        let x1669 = x327 + k[2];
        let x1671 = x926 * k[0];
        let x1672 = x924 + x1671;
        let x1673 = x932 + x1672;
        let x1674 = 0.5 * x1673;
        let x1675 = s[5] * k[4];
        let x1676 = x1674 + x1675;
        let x1677 = x944 * k[0];
        let x1679 = x943 - x1677;
        let x1680 = x949 + x1679;
        let x1681 = 0.5 * x1680;
        let x1683 = x96 * k[4];
        let x1684 = x1683 - x1681;
        let x1685 = x958 * k[0];
        let x1686 = x957 + x1685;
        let x1687 = x1686 - x962;
        let x1688 = 0.5 * x1687;
        let x1690 = s[12] * k[4];
        let x1691 = x1690 - x1688;
        let x1692 = x974 * k[0];
        let x1693 = x1692 - x972;
        let x1694 = x977 + x1693;
        let x1695 = 0.5 * x1694;
        let x1697 = x83 * k[4];
        let x1698 = x1697 - x1695;
        let x1699 = x948 * k[0];
        let x1700 = x1699 - x986;
        let x1701 = x1700 - x991;
        let x1702 = 0.5 * x1701;
        let x1703 = x1683 + x1702;
        let x1704 = x930 * k[0];
        let x1705 = x998 + x1704;
        let x1706 = x1001 + x1705;
        let x1707 = 0.5 * x1706;
        let x1708 = s[6] * k[4];
        let x1709 = x1707 + x1708;
        let x1710 = x976 * k[0];
        let x1712 = x1008 - x1710;
        let x1713 = x1712 - x1012;
        let x1714 = 0.5 * x1713;
        let x1715 = x81 * k[4];
        let x1716 = x1714 + x1715;
        let x1717 = x960 * k[0];
        let x1718 = x1021 + x1717;
        let x1720 = x1025 - x1718;
        let x1721 = 0.5 * x1720;
        let x1722 = s[10] * k[4];
        let x1723 = x1721 + x1722;
        let x1724 = x1019 * k[0];
        let x1725 = x1032 + x1724;
        let x1727 = x1037 - x1725;
        let x1728 = 0.5 * x1727;
        let x1729 = x1690 + x1728;
        let x1730 = x1007 * k[0];
        let x1732 = x1044 - x1730;
        let x1733 = x1732 - x1048;
        let x1734 = 0.5 * x1733;
        let x1735 = x1715 + x1734;
        let x1736 = x997 * k[0];
        let x1737 = x1054 + x1736;
        let x1738 = x1056 + x1737;
        let x1739 = 0.5 * x1738;
        let x1740 = x70 * k[4];
        let x1741 = x1739 + x1740;
        let x1742 = x984 * k[0];
        let x1743 = x1742 - x1063;
        let x1744 = x1743 - x1066;
        let x1745 = 0.5 * x1744;
        let x1746 = x94 * k[4];
        let x1747 = x1745 + x1746;
        let x1748 = x970 * k[0];
        let x1750 = x1073 - x1748;
        let x1751 = x1750 - x1077;
        let x1752 = 0.5 * x1751;
        let x1753 = x1697 + x1752;
        let x1754 = x956 * k[0];
        let x1755 = x1083 + x1754;
        let x1757 = x1087 - x1755;
        let x1758 = 0.5 * x1757;
        let x1759 = x1722 + x1758;
        let x1760 = x942 * k[0];
        let x1761 = x1760 - x1093;
        let x1762 = x1761 - x1096;
        let x1763 = 0.5 * x1762;
        let x1764 = x1746 + x1763;
        let x1765 = x922 * k[0];
        let x1766 = x1102 + x1765;
        let x1767 = x1105 + x1766;
        let x1768 = 0.5 * x1767;
        let x1769 = x71 * k[4];
        let x1770 = x1768 + x1769;
        let x1771 = x1132 * k[0];
        let x1772 = x1129 + x1771;
        let x1773 = x1137 + x1772;
        let x1774 = 0.5 * x1773;
        let x1788 = x1130 * k[0];
        let x1789 = x1129 + x1788;
        let x1790 = x1192 + x1789;
        let x1791 = 0.5 * x1790;
        let x1792 = x1774 + x1791;
        let x1793 = q[10] * k[4];
        let x1794 = s[93] * x1793;
        let x1796 = x1792 - x1794;
        let x1829 = x415 + x1796;
        phi[0] = x49;
        phi_q[0] = x126;
        phi_q[1] = x125;
        phi_q[2] = x124;
        phi_q[3] = x123;
        phi[1] = x59;
        phi_q[4] = x127;
        phi_q[5] = x126;
        phi_q[6] = x128;
        phi_q[7] = x124;
        phi[2] = q[1];
        phi_q[8] = 1.0;
        phi[3] = q[2];
        phi_q[9] = 1.0;
        phi[4] = x60;
        phi_q[10] = x124;
        phi_q[11] = x123;
        phi_q[12] = x126;
        phi_q[13] = x125;
        phi[5] = x111;
        phi_q[14] = -1.0;
        phi[6] = x113;
        phi_q[15] = -1.0;
        phi[7] = x115;
        phi_q[16] = -1.0;
        phi[8] = x87;
        phi_q[17] = x133;
        phi_q[18] = s[17];
        phi_q[19] = s[16];
        phi_q[20] = x135;
        phi[9] = x116;
        phi_q[21] = x134;
        phi_q[22] = x135;
        phi_q[23] = x133;
        phi_q[24] = x136;
        phi[10] = x119;
        phi_q[25] = x123;
        phi_q[26] = x124;
        phi_q[27] = x125;
        phi_q[28] = x126;
        phi[11] = x122;
        phi_q[29] = s[15];
        phi_q[30] = s[16];
        phi_q[31] = s[17];
        phi_q[32] = s[18];
        mass[0] = k[3];
        mass[1] = k[3];
        mass[2] = k[3];
        mass[3] = x562;
        mass[4] = x577;
        mass[5] = x591;
        mass[6] = x605;
        mass[7] = x615;
        mass[8] = x622;
        mass[9] = x632;
        mass[10] = x642;
        mass[11] = x647;
        mass[12] = x653;
        mass[13] = x657;
        mass[14] = x663;
        mass[15] = x666;
        mass[16] = x671;
        mass[17] = x674;
        mass[18] = x678;
        mass[19] = 1.0;
        mass[20] = 1.0;
        mass[21] = 1.0;
        mass[22] = x1676;
        mass[23] = x1684;
        mass[24] = x1691;
        mass[25] = x1698;
        mass[26] = x1703;
        mass[27] = x1709;
        mass[28] = x1716;
        mass[29] = x1723;
        mass[30] = x1729;
        mass[31] = x1735;
        mass[32] = x1741;
        mass[33] = x1747;
        mass[34] = x1753;
        mass[35] = x1759;
        mass[36] = x1764;
        mass[37] = x1770;
        force[0] = x414;
        force[1] = x1669;
        force[2] = x328;
        force[3] = x766;
        force[4] = x785;
        force[5] = x803;
        force[6] = x820;
        force[7] = 0.0;
        force[8] = -9.81;
        force[9] = 0.0;
        force[10] = x1829;
    }
    #[inline(never)]
    fn eval_newton_part_1(
        k: &[f64; 5],
        q: &[f64; 14],
        qd: &[f64; 14],
        s: &[f64; 94],
        force: &mut [f64; 14],
    ) {
        let x220 = 2.0 * qd[10];
        let x368 = s[9] * s[18];
        let x370 = s[14] * s[59];
        let x372 = x370 - x368;
        let x373 = s[53] * x372;
        let x374 = s[9] * s[15];
        let x375 = s[53] * x374;
        let x376 = s[9] * s[16];
        let x378 = s[53] * x376;
        let x381 = s[58] * x373;
        let x382 = s[58] * x375;
        let x383 = s[58] * x378;
        let x410 = s[4] * s[18];
        let x411 = s[4] * s[15];
        let x412 = s[4] * s[16];
        let x416 = x381 + x410;
        let x417 = x382 + x411;
        let x418 = x383 + x412;
        let x1142 = x220 * s[72];
        let x1143 = 0.1 * x1142;
        let x1144 = s[32] * s[73];
        let x1145 = s[18] * s[85];
        let x1146 = x1144 + x1145;
        let x1149 = s[31] * s[74];
        let x1150 = s[17] * s[86];
        let x1151 = x1149 + x1150;
        let x1152 = 0.3 * x1151;
        let x1156 = s[32] * s[72];
        let x1157 = 0.1 * x1156;
        let x1158 = x220 * s[73];
        let x1159 = s[15] * s[85];
        let x1160 = x1158 + x1159;
        let x1162 = s[30] * s[74];
        let x1163 = s[16] * s[86];
        let x1164 = x1162 + x1163;
        let x1165 = 0.3 * x1164;
        let x1170 = s[31] * s[72];
        let x1171 = 0.1 * x1170;
        let x1173 = s[30] * s[73];
        let x1174 = s[16] * s[85];
        let x1175 = x1173 + x1174;
        let x1177 = x220 * s[74];
        let x1178 = s[15] * s[86];
        let x1179 = x1177 + x1178;
        let x1180 = 0.3 * x1179;
        let x1209 = 0.3 * x1149;
        let x1227 = 0.3 * x1162;
        let x1244 = 0.3 * x1177;
        let x1775 = x1146 * k[0];
        let x1777 = x1143 - x1775;
        let x1778 = x1152 + x1777;
        let x1779 = 0.5 * x1778;
        let x1780 = x1160 * k[0];
        let x1781 = x1157 + x1780;
        let x1782 = x1781 - x1165;
        let x1783 = 0.5 * x1782;
        let x1784 = x1175 * k[0];
        let x1785 = x1784 - x1171;
        let x1786 = x1180 + x1785;
        let x1787 = 0.5 * x1786;
        let x1797 = x1144 * k[0];
        let x1798 = x1797 - x1143;
        let x1799 = x1798 - x1209;
        let x1800 = 0.5 * x1799;
        let x1802 = x1800 - x1779;
        let x1803 = q[11] * k[4];
        let x1804 = s[93] * x1803;
        let x1806 = x1802 - x1804;
        let x1807 = x1158 * k[0];
        let x1808 = x1157 + x1807;
        let x1810 = x1227 - x1808;
        let x1811 = 0.5 * x1810;
        let x1813 = x1811 - x1783;
        let x1814 = q[12] * k[4];
        let x1815 = s[93] * x1814;
        let x1817 = x1813 - x1815;
        let x1818 = x1173 * k[0];
        let x1820 = x1171 - x1818;
        let x1821 = x1820 - x1244;
        let x1822 = 0.5 * x1821;
        let x1824 = x1822 - x1787;
        let x1825 = q[13] * k[4];
        let x1826 = s[93] * x1825;
        let x1828 = x1824 - x1826;
        let x1830 = x416 + x1806;
        let x1831 = x417 + x1817;
        let x1832 = x1828 - x418;
        force[11] = x1830;
        force[12] = x1831;
        force[13] = x1832;
    }
}
/// The system after substituting rows `a·qᵢ + b·qⱼ + g(t) = 0` away (docs/design.md,
/// decision 24): fewer coordinates and rows, the same motion and multipliers once
/// mapped back with `REDUCTION`.
pub mod reduced {
    use super::*;
    /// Number of reduced coordinates.
    pub const N_COORDS: usize = 9usize;
    /// Number of reduced rows.
    pub const N_CONSTRAINTS: usize = 7usize;
    /// Row of each Φq nonzero.
    pub static PHI_Q_ROWS: [u32; 28usize] = [
        0u32, 0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 1u32, 2u32, 2u32, 2u32, 2u32, 3u32,
        3u32, 3u32, 3u32, 4u32, 4u32, 4u32, 4u32, 5u32, 5u32, 5u32, 5u32, 6u32, 6u32,
        6u32, 6u32,
    ];
    /// Column of each Φq nonzero.
    pub static PHI_Q_COLS: [u32; 28usize] = [
        1u32, 2u32, 3u32, 4u32, 1u32, 2u32, 3u32, 4u32, 1u32, 2u32, 3u32, 4u32, 5u32,
        6u32, 7u32, 8u32, 5u32, 6u32, 7u32, 8u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32,
        7u32, 8u32,
    ];
    /// Name of each reduced coordinate (its full model's name).
    pub static COORD_NAMES: [&str; 9usize] = [
        "slider.x",
        "slider.e0",
        "slider.e1",
        "slider.e2",
        "slider.e3",
        "rotor.e0",
        "rotor.e1",
        "rotor.e2",
        "rotor.e3",
    ];
    /// Name of each reduced row (its full model's name).
    pub static ROW_NAMES: [&str; 7usize] = [
        "rail.dot1(x1,z2)",
        "rail.dot1(y1,z2)",
        "rail.dot1(y1,x2)",
        "spindle.dot1(x1,z2)",
        "spindle.dot1(y1,z2)",
        "slider.norm",
        "rotor.norm",
    ];
    /// Initial coordinates, from the full model's assembled ones.
    pub static Q0: [f64; 9usize] = [
        0.1f64,
        1f64,
        0f64,
        0f64,
        0f64,
        1f64,
        0f64,
        0f64,
        0f64,
    ];
    /// Initial velocities from the file.
    pub static QD0: [f64; 9usize] = [
        0f64,
        0f64,
        0f64,
        0f64,
        0f64,
        -0f64,
        0f64,
        0.5f64,
        0f64,
    ];
    /// Rows dependent on others at the initial pose.
    pub static REDUNDANT_ROWS: [u32; 0usize] = [];
    /// Full index of each reduced coordinate.
    pub static COORDS: [u32; 9usize] = [
        0u32, 3u32, 4u32, 5u32, 6u32, 10u32, 11u32, 12u32, 13u32,
    ];
    /// Full index of each reduced row.
    pub static ROWS: [u32; 7usize] = [0u32, 1u32, 4u32, 8u32, 9u32, 10u32, 11u32];
    /// The eliminated rows.
    pub static SUBSTITUTIONS: [Substitution; 5usize] = [
        Substitution {
            row: Some(2u32),
            coord: 1u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: Some(3u32),
            coord: 2u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: Some(5u32),
            coord: 7u32,
            target: None,
            weight: 0f64,
            slope: -1f64,
        },
        Substitution {
            row: Some(6u32),
            coord: 8u32,
            target: None,
            weight: 0f64,
            slope: -1f64,
        },
        Substitution {
            row: Some(7u32),
            coord: 9u32,
            target: None,
            weight: 0f64,
            slope: -1f64,
        },
    ];
    /// The way back to the full model.
    pub static REDUCTION: Reduction = Reduction {
        n_full: 14usize,
        m_full: 12usize,
        coords: &COORDS,
        rows: &ROWS,
        substitutions: &SUBSTITUTIONS,
        offsets: offsets_into,
    };
    /// `c, ċ, c̈` of each substitution at time `t`, three per substitution.
    pub fn offsets_into(t: f64, out: &mut [f64]) {
        let out: &mut [f64; 15] = out.try_into().expect("out must have 15 entries");
        let _ = t;
        offsets_into_part_0(out);
    }
    #[inline(never)]
    fn offsets_into_part_0(out: &mut [f64; 15]) {
        out[0] = 0.0;
        out[1] = 0.0;
        out[2] = 0.0;
        out[3] = 0.0;
        out[4] = 0.0;
        out[5] = 0.0;
        out[6] = 0.0;
        out[7] = 0.0;
        out[8] = 0.0;
        out[9] = 1.0;
        out[10] = 0.0;
        out[11] = 0.0;
        out[12] = 2.0;
        out[13] = 0.0;
        out[14] = 0.0;
    }
    /// Number of values `setup` computes from the run-time parameters.
    pub const N_K: usize = 3;
    /// `setup` at the file's parameter values: what the types without parameters read.
    pub static K: [f64; 3] = [0.2f64, 2f64, 0.8f64];
    /// The values the per-step functions read (`k`), from the run-time parameters `p`.
    pub fn setup(p: &[f64], k: &mut [f64]) {
        let p: &[f64; 2] = p.try_into().expect("p must have 2 entries");
        let k: &mut [f64; 3] = k.try_into().expect("k must have 3 entries");
        setup_part_0(p, k);
    }
    #[inline(never)]
    fn setup_part_0(p: &[f64; 2], k: &mut [f64; 3]) {
        let x535 = 2.0 * p[1];
        let x536 = 0.5 * x535;
        let x912 = 0.1 + p[0];
        let x913 = 0.3 + x912;
        let x914 = 4.0 * x913;
        let x916 = x914 * 0.3333333333333333;
        k[0] = p[0];
        k[1] = x536;
        k[2] = x916;
    }
    /// Constraint residual Φ(q, t).
    pub fn phi(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
        let _ = t;
        phi_part_0(q, out);
    }
    #[inline(never)]
    fn phi_part_0(q: &[f64; 9], out: &mut [f64; 7]) {
        let x23 = q[3] * q[3];
        let x24 = q[4] * q[4];
        let x25 = q[5] * q[5];
        let x26 = q[6] * q[6];
        let x50 = q[5] * q[6];
        let x51 = 2.0 * x50;
        let x52 = q[3] * q[4];
        let x54 = 2.0 * x52;
        let x294 = q[1] * q[1];
        let x295 = q[2] * q[2];
        let x1661 = x294 + x295;
        let x1662 = q[2] * q[3];
        let x1663 = 2.0 * x1662;
        let x1664 = q[1] * q[4];
        let x1665 = 2.0 * x1664;
        let x1666 = q[2] * q[4];
        let x1667 = 2.0 * x1666;
        let x1668 = q[1] * q[3];
        let x1669 = 2.0 * x1668;
        let x1670 = x1663 + x1665;
        let x1671 = q[1] * q[2];
        let x1672 = 2.0 * x1671;
        let x1674 = x1667 - x1669;
        let x1675 = x54 + x1672;
        let x1676 = q[7] * q[7];
        let x1677 = q[8] * q[8];
        let x1678 = x25 + x26;
        let x1679 = q[6] * q[7];
        let x1680 = 2.0 * x1679;
        let x1681 = q[5] * q[8];
        let x1682 = 2.0 * x1681;
        let x1684 = x1680 - x1682;
        let x1685 = q[7] * q[8];
        let x1686 = 2.0 * x1685;
        let x1687 = x51 + x1686;
        let x1688 = -x1687;
        let x1689 = x23 + x1661;
        let x1690 = x24 + x1689;
        let x1691 = x1690 - 1.0;
        let x1692 = x1676 + x1678;
        let x1693 = x1677 + x1692;
        let x1694 = x1693 - 1.0;
        out[0] = x1670;
        out[1] = x1674;
        out[2] = x1675;
        out[3] = x1684;
        out[4] = x1688;
        out[5] = x1691;
        out[6] = x1694;
    }
    /// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
    pub fn phi_q(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 28] = out.try_into().expect("out must have 28 entries");
        let _ = t;
        phi_q_part_0(q, out);
    }
    #[inline(never)]
    fn phi_q_part_0(q: &[f64; 9], out: &mut [f64; 28]) {
        let x123 = q[3] * 2.0;
        let x124 = q[4] * 2.0;
        let x125 = q[5] * 2.0;
        let x126 = q[6] * 2.0;
        let x127 = -x125;
        let x128 = -x123;
        let x301 = q[1] * 2.0;
        let x303 = q[2] * 2.0;
        let x479 = -x126;
        let x1695 = -x301;
        let x1696 = 2.0 * q[7];
        let x1697 = 2.0 * q[8];
        let x1698 = -x1697;
        let x1699 = -x1696;
        out[0] = x124;
        out[1] = x123;
        out[2] = x303;
        out[3] = x301;
        out[4] = x128;
        out[5] = x124;
        out[6] = x1695;
        out[7] = x303;
        out[8] = x303;
        out[9] = x301;
        out[10] = x124;
        out[11] = x123;
        out[12] = x1698;
        out[13] = x1696;
        out[14] = x126;
        out[15] = x127;
        out[16] = x479;
        out[17] = x127;
        out[18] = x1698;
        out[19] = x1699;
        out[20] = x301;
        out[21] = x303;
        out[22] = x123;
        out[23] = x124;
        out[24] = x125;
        out[25] = x126;
        out[26] = x1696;
        out[27] = x1697;
    }
    /// Partial time derivative Φt(q, t).
    pub fn phi_t(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
        let _ = q;
        let _ = t;
        phi_t_part_0(out);
    }
    #[inline(never)]
    fn phi_t_part_0(out: &mut [f64; 7]) {
        out[0] = 0.0;
        out[1] = 0.0;
        out[2] = 0.0;
        out[3] = 0.0;
        out[4] = 0.0;
        out[5] = 0.0;
        out[6] = 0.0;
    }
    /// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
    pub fn gamma(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
        let _ = q;
        let _ = t;
        gamma_part_0(qd, out);
    }
    #[inline(never)]
    fn gamma_part_0(qd: &[f64; 9], out: &mut [f64; 7]) {
        let x216 = 2.0 * qd[3];
        let x217 = 2.0 * qd[4];
        let x218 = 2.0 * qd[5];
        let x219 = 2.0 * qd[6];
        let x224 = qd[3] * x216;
        let x225 = qd[4] * x217;
        let x226 = qd[5] * x218;
        let x227 = qd[6] * x219;
        let x242 = qd[5] * qd[6];
        let x243 = x242 + x242;
        let x244 = 2.0 * x243;
        let x245 = qd[3] * qd[4];
        let x246 = x245 + x245;
        let x247 = 2.0 * x246;
        let x466 = 2.0 * qd[1];
        let x468 = 2.0 * qd[2];
        let x852 = 2.0 * qd[7];
        let x854 = 2.0 * qd[8];
        let x1748 = qd[1] * x466;
        let x1749 = qd[2] * x468;
        let x1750 = x1748 + x1749;
        let x1751 = qd[2] * qd[3];
        let x1752 = x1751 + x1751;
        let x1753 = 2.0 * x1752;
        let x1754 = qd[1] * qd[4];
        let x1755 = x1754 + x1754;
        let x1756 = 2.0 * x1755;
        let x1757 = qd[2] * qd[4];
        let x1758 = x1757 + x1757;
        let x1759 = 2.0 * x1758;
        let x1760 = qd[1] * qd[3];
        let x1761 = x1760 + x1760;
        let x1762 = 2.0 * x1761;
        let x1763 = x1753 + x1756;
        let x1764 = qd[1] * qd[2];
        let x1765 = x1764 + x1764;
        let x1766 = 2.0 * x1765;
        let x1768 = x1759 - x1762;
        let x1769 = x247 + x1766;
        let x1770 = qd[7] * x852;
        let x1771 = qd[8] * x854;
        let x1772 = x226 + x227;
        let x1773 = qd[6] * qd[7];
        let x1774 = x1773 + x1773;
        let x1775 = 2.0 * x1774;
        let x1776 = qd[5] * qd[8];
        let x1777 = x1776 + x1776;
        let x1778 = 2.0 * x1777;
        let x1780 = x1775 - x1778;
        let x1781 = qd[7] * qd[8];
        let x1782 = x1781 + x1781;
        let x1783 = 2.0 * x1782;
        let x1784 = x244 + x1783;
        let x1786 = x224 + x1750;
        let x1787 = x225 + x1786;
        let x1788 = x1770 + x1772;
        let x1789 = x1771 + x1788;
        let x1790 = -x1763;
        let x1791 = -x1768;
        let x1792 = -x1769;
        let x1793 = -x1780;
        let x1794 = -x1787;
        let x1795 = -x1789;
        out[0] = x1790;
        out[1] = x1791;
        out[2] = x1792;
        out[3] = x1793;
        out[4] = x1784;
        out[5] = x1794;
        out[6] = x1795;
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
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 7] = phi.try_into().expect("phi must have 7 entries");
        let phi_q: &mut [f64; 28] = phi_q
            .try_into()
            .expect("phi_q must have 28 entries");
        let phi_t: &mut [f64; 7] = phi_t.try_into().expect("phi_t must have 7 entries");
        let gamma: &mut [f64; 7] = gamma.try_into().expect("gamma must have 7 entries");
        let _ = t;
        eval_kinematics_part_0(q, qd, phi, phi_q, phi_t, gamma);
    }
    #[inline(never)]
    fn eval_kinematics_part_0(
        q: &[f64; 9],
        qd: &[f64; 9],
        phi: &mut [f64; 7],
        phi_q: &mut [f64; 28],
        phi_t: &mut [f64; 7],
        gamma: &mut [f64; 7],
    ) {
        let x23 = q[3] * q[3];
        let x24 = q[4] * q[4];
        let x25 = q[5] * q[5];
        let x26 = q[6] * q[6];
        let x50 = q[5] * q[6];
        let x51 = 2.0 * x50;
        let x52 = q[3] * q[4];
        let x54 = 2.0 * x52;
        let x123 = q[3] * 2.0;
        let x124 = q[4] * 2.0;
        let x125 = q[5] * 2.0;
        let x126 = q[6] * 2.0;
        let x127 = -x125;
        let x128 = -x123;
        let x216 = 2.0 * qd[3];
        let x217 = 2.0 * qd[4];
        let x218 = 2.0 * qd[5];
        let x219 = 2.0 * qd[6];
        let x224 = qd[3] * x216;
        let x225 = qd[4] * x217;
        let x226 = qd[5] * x218;
        let x227 = qd[6] * x219;
        let x242 = qd[5] * qd[6];
        let x243 = x242 + x242;
        let x244 = 2.0 * x243;
        let x245 = qd[3] * qd[4];
        let x246 = x245 + x245;
        let x247 = 2.0 * x246;
        let x294 = q[1] * q[1];
        let x295 = q[2] * q[2];
        let x301 = q[1] * 2.0;
        let x303 = q[2] * 2.0;
        let x466 = 2.0 * qd[1];
        let x468 = 2.0 * qd[2];
        let x479 = -x126;
        let x852 = 2.0 * qd[7];
        let x854 = 2.0 * qd[8];
        let x1661 = x294 + x295;
        let x1662 = q[2] * q[3];
        let x1663 = 2.0 * x1662;
        let x1664 = q[1] * q[4];
        let x1665 = 2.0 * x1664;
        let x1666 = q[2] * q[4];
        let x1667 = 2.0 * x1666;
        let x1668 = q[1] * q[3];
        let x1669 = 2.0 * x1668;
        let x1670 = x1663 + x1665;
        let x1671 = q[1] * q[2];
        let x1672 = 2.0 * x1671;
        let x1674 = x1667 - x1669;
        let x1675 = x54 + x1672;
        let x1676 = q[7] * q[7];
        let x1677 = q[8] * q[8];
        let x1678 = x25 + x26;
        let x1679 = q[6] * q[7];
        let x1680 = 2.0 * x1679;
        let x1681 = q[5] * q[8];
        let x1682 = 2.0 * x1681;
        let x1684 = x1680 - x1682;
        let x1685 = q[7] * q[8];
        let x1686 = 2.0 * x1685;
        let x1687 = x51 + x1686;
        let x1688 = -x1687;
        let x1689 = x23 + x1661;
        let x1690 = x24 + x1689;
        let x1691 = x1690 - 1.0;
        let x1692 = x1676 + x1678;
        let x1693 = x1677 + x1692;
        let x1694 = x1693 - 1.0;
        let x1695 = -x301;
        let x1696 = 2.0 * q[7];
        let x1697 = 2.0 * q[8];
        let x1698 = -x1697;
        let x1699 = -x1696;
        let x1748 = qd[1] * x466;
        let x1749 = qd[2] * x468;
        let x1750 = x1748 + x1749;
        let x1751 = qd[2] * qd[3];
        let x1752 = x1751 + x1751;
        let x1753 = 2.0 * x1752;
        let x1754 = qd[1] * qd[4];
        let x1755 = x1754 + x1754;
        let x1756 = 2.0 * x1755;
        let x1757 = qd[2] * qd[4];
        let x1758 = x1757 + x1757;
        let x1759 = 2.0 * x1758;
        let x1760 = qd[1] * qd[3];
        let x1761 = x1760 + x1760;
        let x1762 = 2.0 * x1761;
        let x1763 = x1753 + x1756;
        let x1764 = qd[1] * qd[2];
        let x1765 = x1764 + x1764;
        let x1766 = 2.0 * x1765;
        let x1768 = x1759 - x1762;
        let x1769 = x247 + x1766;
        let x1770 = qd[7] * x852;
        let x1771 = qd[8] * x854;
        let x1772 = x226 + x227;
        let x1773 = qd[6] * qd[7];
        let x1774 = x1773 + x1773;
        let x1775 = 2.0 * x1774;
        let x1776 = qd[5] * qd[8];
        let x1777 = x1776 + x1776;
        let x1778 = 2.0 * x1777;
        let x1780 = x1775 - x1778;
        let x1781 = qd[7] * qd[8];
        let x1782 = x1781 + x1781;
        let x1783 = 2.0 * x1782;
        let x1784 = x244 + x1783;
        let x1786 = x224 + x1750;
        let x1787 = x225 + x1786;
        let x1788 = x1770 + x1772;
        let x1789 = x1771 + x1788;
        let x1790 = -x1763;
        let x1791 = -x1768;
        let x1792 = -x1769;
        let x1793 = -x1780;
        let x1794 = -x1787;
        let x1795 = -x1789;
        phi[0] = x1670;
        phi_q[0] = x124;
        phi_q[1] = x123;
        phi_q[2] = x303;
        phi_q[3] = x301;
        phi_t[0] = 0.0;
        gamma[0] = x1790;
        phi[1] = x1674;
        phi_q[4] = x128;
        phi_q[5] = x124;
        phi_q[6] = x1695;
        phi_q[7] = x303;
        phi_t[1] = 0.0;
        gamma[1] = x1791;
        phi[2] = x1675;
        phi_q[8] = x303;
        phi_q[9] = x301;
        phi_q[10] = x124;
        phi_q[11] = x123;
        phi_t[2] = 0.0;
        gamma[2] = x1792;
        phi[3] = x1684;
        phi_q[12] = x1698;
        phi_q[13] = x1696;
        phi_q[14] = x126;
        phi_q[15] = x127;
        phi_t[3] = 0.0;
        gamma[3] = x1793;
        phi[4] = x1688;
        phi_q[16] = x479;
        phi_q[17] = x127;
        phi_q[18] = x1698;
        phi_q[19] = x1699;
        phi_t[4] = 0.0;
        gamma[4] = x1784;
        phi[5] = x1691;
        phi_q[20] = x301;
        phi_q[21] = x303;
        phi_q[22] = x123;
        phi_q[23] = x124;
        phi_t[5] = 0.0;
        gamma[5] = x1794;
        phi[6] = x1694;
        phi_q[24] = x125;
        phi_q[25] = x126;
        phi_q[26] = x1696;
        phi_q[27] = x1697;
        phi_t[6] = 0.0;
        gamma[6] = x1795;
    }
    /// Potential energy of gravity and springs, written to `out[0]`.
    pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        let _ = k;
        potential_into_part_0(q, out);
    }
    #[inline(never)]
    fn potential_into_part_0(q: &[f64; 9], out: &mut [f64; 1]) {
        let x25 = q[5] * q[5];
        let x26 = q[6] * q[6];
        let x292 = 1.0 + q[0];
        let x293 = x292 * x292;
        let x1678 = x25 + x26;
        let x1796 = 2.0 * x1678;
        let x1797 = x1796 - 1.0;
        let x1798 = q[6] * q[8];
        let x1799 = 2.0 * x1798;
        let x1800 = q[5] * q[7];
        let x1801 = 2.0 * x1800;
        let x1803 = x1799 - x1801;
        let x1804 = x293.sqrt();
        let x1805 = x1804 - 1.0;
        let x1806 = x1805 * x1805;
        let x1807 = 25.0 * x1806;
        let x1808 = -x1803;
        let x1809 = x1808.atan2(x1797);
        let x1810 = x1809 * x1809;
        let x1811 = 9.81 + x1807;
        let x1812 = x1810 + x1811;
        out[0] = x1812;
    }
    /// Power of the non-conservative loads, written to `out[0]`.
    pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        let _ = k;
        power_nc_into_part_0(q, qd, t, out);
    }
    #[inline(never)]
    fn power_nc_into_part_0(q: &[f64; 9], qd: &[f64; 9], t: f64, out: &mut [f64; 1]) {
        let x3 = 4.0 * t;
        let x4 = x3.sin();
        let x5 = 3.0 * x4;
        let x9 = 3.0 * t;
        let x10 = x9.cos();
        let x11 = 0.5 * x10;
        let x13 = t.sin();
        let x14 = 0.2 * x13;
        let x25 = q[5] * q[5];
        let x26 = q[6] * q[6];
        let x125 = q[5] * 2.0;
        let x126 = q[6] * 2.0;
        let x153 = x125 * qd[5];
        let x154 = x126 * qd[6];
        let x292 = 1.0 + q[0];
        let x293 = x292 * x292;
        let x299 = 2.0 * x292;
        let x300 = qd[0] * x299;
        let x1678 = x25 + x26;
        let x1727 = x153 + x154;
        let x1796 = 2.0 * x1678;
        let x1797 = x1796 - 1.0;
        let x1798 = q[6] * q[8];
        let x1799 = 2.0 * x1798;
        let x1800 = q[5] * q[7];
        let x1801 = 2.0 * x1800;
        let x1803 = x1799 - x1801;
        let x1804 = x293.sqrt();
        let x1813 = 2.0 * x1804;
        let x1814 = 1.0 / x1813;
        let x1815 = x300 * x1814;
        let x1816 = 0.8 * x1815;
        let x1818 = x5 - x1816;
        let x1819 = x1815 * x1818;
        let x1820 = 2.0 * x1727;
        let x1821 = q[8] * qd[6];
        let x1822 = q[6] * qd[8];
        let x1823 = x1821 + x1822;
        let x1824 = 2.0 * x1823;
        let x1825 = q[7] * qd[5];
        let x1826 = q[5] * qd[7];
        let x1827 = x1825 + x1826;
        let x1828 = 2.0 * x1827;
        let x1830 = x1824 - x1828;
        let x1831 = x1797 * x1797;
        let x1832 = x1803 * x1803;
        let x1833 = x1831 + x1832;
        let x1834 = x1797 * x1830;
        let x1836 = x1803 * x1820;
        let x1837 = x1836 - x1834;
        let x1838 = 1.0 / x1833;
        let x1839 = x1837 * x1838;
        let x1840 = 0.1 * x1839;
        let x1842 = x11 - x1840;
        let x1843 = x1839 * x1842;
        let x1846 = x1821 - x1825;
        let x1847 = x1826 + x1846;
        let x1848 = x1847 - x1822;
        let x1849 = 2.0 * x1848;
        let x1850 = x14 * x1849;
        let x1851 = qd[0] + x1819;
        let x1852 = x1843 + x1851;
        let x1853 = x1850 + x1852;
        out[0] = x1853;
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
        pub static MASS_ROWS: [u32; 33usize] = [
            0u32, 1u32, 1u32, 1u32, 1u32, 2u32, 2u32, 2u32, 2u32, 3u32, 3u32, 3u32, 3u32,
            4u32, 4u32, 4u32, 4u32, 5u32, 5u32, 5u32, 5u32, 6u32, 6u32, 6u32, 6u32, 7u32,
            7u32, 7u32, 7u32, 8u32, 8u32, 8u32, 8u32,
        ];
        /// Column of each mass-matrix nonzero.
        pub static MASS_COLS: [u32; 33usize] = [
            0u32, 1u32, 2u32, 3u32, 4u32, 1u32, 2u32, 3u32, 4u32, 1u32, 2u32, 3u32, 4u32,
            1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 7u32, 8u32, 5u32, 6u32, 7u32, 8u32, 5u32,
            6u32, 7u32, 8u32, 5u32, 6u32, 7u32, 8u32,
        ];
        /// Row and column of each ∂Q/∂q nonzero.
        pub static FORCE_Q_ROWS: [u32; 0usize] = [];
        pub static FORCE_Q_COLS: [u32; 0usize] = [];
        /// Row and column of each ∂Q/∂q̇ nonzero.
        pub static FORCE_QD_ROWS: [u32; 0usize] = [];
        pub static FORCE_QD_COLS: [u32; 0usize] = [];
        /// Sizes, patterns and names for this formulation.
        pub static INFO: MechanismInfo = MechanismInfo {
            name: "oscillators_reduced",
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
            let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
            let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
            let _: &mut [f64; 0] = dq.try_into().expect("dq must have 0 entries");
            let _: &mut [f64; 0] = dqd.try_into().expect("dqd must have 0 entries");
            let _ = k;
            let _ = q;
            let _ = qd;
            let _ = t;
        }
        /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
        pub fn mass(k: &[f64], q: &[f64], out: &mut [f64]) {
            let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
            let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
            let out: &mut [f64; 33] = out.try_into().expect("out must have 33 entries");
            mass_part_0(k, q, out);
        }
        #[inline(never)]
        fn mass_part_0(k: &[f64; 3], q: &[f64; 9], out: &mut [f64; 33]) {
            let x23 = q[3] * q[3];
            let x24 = q[4] * q[4];
            let x25 = q[5] * q[5];
            let x26 = q[6] * q[6];
            let x50 = q[5] * q[6];
            let x52 = q[3] * q[4];
            let x123 = q[3] * 2.0;
            let x124 = q[4] * 2.0;
            let x125 = q[5] * 2.0;
            let x126 = q[6] * 2.0;
            let x294 = q[1] * q[1];
            let x295 = q[2] * q[2];
            let x301 = q[1] * 2.0;
            let x303 = q[2] * 2.0;
            let x537 = 2.0 * x124;
            let x539 = 2.0 * x125;
            let x541 = 2.0 * x126;
            let x543 = x124 * x537;
            let x545 = 0.01 * x543;
            let x547 = x125 * x539;
            let x551 = x126 * x541;
            let x561 = x23 * 0.04;
            let x563 = 2.0 * x123;
            let x564 = x124 * x563;
            let x565 = 0.01 * x564;
            let x566 = x125 * x541;
            let x570 = x126 * x539;
            let x576 = x52 * 0.04;
            let x606 = x123 * x537;
            let x608 = 0.01 * x606;
            let x616 = x123 * x563;
            let x617 = 0.01 * x616;
            let x621 = x24 * 0.04;
            let x1662 = q[2] * q[3];
            let x1664 = q[1] * q[4];
            let x1666 = q[2] * q[4];
            let x1668 = q[1] * q[3];
            let x1671 = q[1] * q[2];
            let x1676 = q[7] * q[7];
            let x1677 = q[8] * q[8];
            let x1679 = q[6] * q[7];
            let x1681 = q[5] * q[8];
            let x1685 = q[7] * q[8];
            let x1696 = 2.0 * q[7];
            let x1697 = 2.0 * q[8];
            let x1798 = q[6] * q[8];
            let x1800 = q[5] * q[7];
            let x1854 = 2.0 * x303;
            let x1855 = x303 * x1854;
            let x1856 = 0.01 * x1855;
            let x1857 = x617 + x1856;
            let x1858 = x545 + x1857;
            let x1859 = 0.5 * x1858;
            let x1860 = x294 * 0.04;
            let x1861 = x1859 + x1860;
            let x1862 = 2.0 * x301;
            let x1863 = x303 * x1862;
            let x1864 = 0.01 * x1863;
            let x1865 = x1864 - x608;
            let x1866 = x565 + x1865;
            let x1867 = 0.5 * x1866;
            let x1869 = 0.04 * x1671;
            let x1870 = x1869 - x1867;
            let x1871 = x303 * x537;
            let x1872 = 0.01 * x1871;
            let x1873 = x123 * x1862;
            let x1874 = 0.01 * x1873;
            let x1875 = x124 * x1854;
            let x1876 = 0.01 * x1875;
            let x1878 = x1872 + x1874;
            let x1879 = x1878 - x1876;
            let x1880 = 0.5 * x1879;
            let x1882 = 0.04 * x1668;
            let x1883 = x1882 - x1880;
            let x1884 = x303 * x563;
            let x1885 = 0.01 * x1884;
            let x1887 = x123 * x1854;
            let x1888 = 0.01 * x1887;
            let x1889 = x124 * x1862;
            let x1890 = 0.01 * x1889;
            let x1891 = x1888 - x1885;
            let x1892 = x1890 + x1891;
            let x1893 = 0.5 * x1892;
            let x1895 = 0.04 * x1664;
            let x1896 = x1895 - x1893;
            let x1897 = x301 * x1854;
            let x1898 = 0.01 * x1897;
            let x1900 = x565 - x1898;
            let x1901 = x1900 - x608;
            let x1902 = 0.5 * x1901;
            let x1903 = x1869 + x1902;
            let x1904 = x301 * x1862;
            let x1905 = 0.01 * x1904;
            let x1906 = x545 + x1905;
            let x1907 = x617 + x1906;
            let x1908 = 0.5 * x1907;
            let x1909 = x295 * 0.04;
            let x1910 = x1908 + x1909;
            let x1911 = x301 * x537;
            let x1912 = 0.01 * x1911;
            let x1915 = x1912 - x1890;
            let x1916 = x1915 - x1888;
            let x1917 = 0.5 * x1916;
            let x1918 = 0.04 * x1662;
            let x1919 = x1917 + x1918;
            let x1920 = x301 * x563;
            let x1921 = 0.01 * x1920;
            let x1922 = x1876 + x1921;
            let x1924 = x1874 - x1922;
            let x1925 = 0.5 * x1924;
            let x1926 = 0.04 * x1666;
            let x1927 = x1925 + x1926;
            let x1928 = x1872 - x1922;
            let x1929 = 0.5 * x1928;
            let x1930 = x1882 + x1929;
            let x1932 = x1890 - x1912;
            let x1933 = x1932 - x1885;
            let x1934 = 0.5 * x1933;
            let x1935 = x1918 + x1934;
            let x1936 = x1856 + x1906;
            let x1937 = 0.5 * x1936;
            let x1938 = x561 + x1937;
            let x1940 = x1898 - x565;
            let x1941 = x1940 - x1864;
            let x1942 = 0.5 * x1941;
            let x1943 = x576 + x1942;
            let x1944 = x1891 - x1912;
            let x1945 = 0.5 * x1944;
            let x1946 = x1895 + x1945;
            let x1948 = x1921 - x1878;
            let x1949 = 0.5 * x1948;
            let x1950 = x1926 + x1949;
            let x1951 = x1865 - x1898;
            let x1952 = 0.5 * x1951;
            let x1953 = x576 + x1952;
            let x1954 = x1857 + x1905;
            let x1955 = 0.5 * x1954;
            let x1956 = x621 + x1955;
            let x1957 = 2.0 * x1696;
            let x1958 = 2.0 * x1697;
            let x1959 = 0.1 * x551;
            let x1960 = x1696 * x1957;
            let x1962 = x1697 * x1958;
            let x1963 = 0.3 * x1962;
            let x1969 = 0.1 * x570;
            let x1970 = x1696 * x1958;
            let x1973 = x1697 * x1957;
            let x1974 = 0.3 * x1973;
            let x1981 = x126 * x1958;
            let x1982 = 0.1 * x1981;
            let x1983 = x539 * x1696;
            let x1985 = x541 * x1697;
            let x1986 = 0.3 * x1985;
            let x1994 = x126 * x1957;
            let x1995 = 0.1 * x1994;
            let x1997 = x541 * x1696;
            let x1999 = x539 * x1697;
            let x2000 = 0.3 * x1999;
            let x2007 = 0.1 * x566;
            let x2010 = 0.3 * x1970;
            let x2016 = 0.1 * x547;
            let x2018 = 0.3 * x1960;
            let x2024 = x125 * x1958;
            let x2025 = 0.1 * x2024;
            let x2028 = 0.3 * x1997;
            let x2035 = x125 * x1957;
            let x2036 = 0.1 * x2035;
            let x2038 = 0.3 * x1983;
            let x2045 = 0.1 * x1985;
            let x2047 = 0.3 * x1981;
            let x2053 = 0.1 * x1999;
            let x2056 = 0.3 * x1994;
            let x2062 = 0.1 * x1962;
            let x2064 = 0.3 * x551;
            let x2070 = 0.1 * x1973;
            let x2073 = 0.3 * x570;
            let x2080 = 0.1 * x1997;
            let x2083 = 0.3 * x2024;
            let x2089 = 0.1 * x1983;
            let x2091 = 0.3 * x2035;
            let x2097 = 0.1 * x1970;
            let x2100 = 0.3 * x566;
            let x2106 = 0.1 * x1960;
            let x2108 = 0.3 * x547;
            let x2435 = x1960 * k[0];
            let x2436 = x1959 + x2435;
            let x2437 = x1963 + x2436;
            let x2438 = 0.5 * x2437;
            let x2439 = x25 * k[2];
            let x2440 = x2438 + x2439;
            let x2441 = x1970 * k[0];
            let x2443 = x1969 - x2441;
            let x2444 = x1974 + x2443;
            let x2445 = 0.5 * x2444;
            let x2447 = x50 * k[2];
            let x2448 = x2447 - x2445;
            let x2449 = x1983 * k[0];
            let x2450 = x1982 + x2449;
            let x2451 = x2450 - x1986;
            let x2452 = 0.5 * x2451;
            let x2454 = x1800 * k[2];
            let x2455 = x2454 - x2452;
            let x2456 = x1997 * k[0];
            let x2457 = x2456 - x1995;
            let x2458 = x2000 + x2457;
            let x2459 = 0.5 * x2458;
            let x2461 = x1681 * k[2];
            let x2462 = x2461 - x2459;
            let x2463 = x1973 * k[0];
            let x2464 = x2463 - x2007;
            let x2465 = x2464 - x2010;
            let x2466 = 0.5 * x2465;
            let x2467 = x2447 + x2466;
            let x2468 = x1962 * k[0];
            let x2469 = x2016 + x2468;
            let x2470 = x2018 + x2469;
            let x2471 = 0.5 * x2470;
            let x2472 = x26 * k[2];
            let x2473 = x2471 + x2472;
            let x2474 = x1999 * k[0];
            let x2476 = x2025 - x2474;
            let x2477 = x2476 - x2028;
            let x2478 = 0.5 * x2477;
            let x2479 = x1679 * k[2];
            let x2480 = x2478 + x2479;
            let x2481 = x1985 * k[0];
            let x2482 = x2036 + x2481;
            let x2484 = x2038 - x2482;
            let x2485 = 0.5 * x2484;
            let x2486 = x1798 * k[2];
            let x2487 = x2485 + x2486;
            let x2488 = x2035 * k[0];
            let x2489 = x2045 + x2488;
            let x2491 = x2047 - x2489;
            let x2492 = 0.5 * x2491;
            let x2493 = x2454 + x2492;
            let x2494 = x2024 * k[0];
            let x2496 = x2053 - x2494;
            let x2497 = x2496 - x2056;
            let x2498 = 0.5 * x2497;
            let x2499 = x2479 + x2498;
            let x2500 = x547 * k[0];
            let x2501 = x2062 + x2500;
            let x2502 = x2064 + x2501;
            let x2503 = 0.5 * x2502;
            let x2504 = x1676 * k[2];
            let x2505 = x2503 + x2504;
            let x2506 = x566 * k[0];
            let x2507 = x2506 - x2070;
            let x2508 = x2507 - x2073;
            let x2509 = 0.5 * x2508;
            let x2510 = x1685 * k[2];
            let x2511 = x2509 + x2510;
            let x2512 = x1994 * k[0];
            let x2514 = x2080 - x2512;
            let x2515 = x2514 - x2083;
            let x2516 = 0.5 * x2515;
            let x2517 = x2461 + x2516;
            let x2518 = x1981 * k[0];
            let x2519 = x2089 + x2518;
            let x2521 = x2091 - x2519;
            let x2522 = 0.5 * x2521;
            let x2523 = x2486 + x2522;
            let x2524 = x570 * k[0];
            let x2525 = x2524 - x2097;
            let x2526 = x2525 - x2100;
            let x2527 = 0.5 * x2526;
            let x2528 = x2510 + x2527;
            let x2529 = x551 * k[0];
            let x2530 = x2106 + x2529;
            let x2531 = x2108 + x2530;
            let x2532 = 0.5 * x2531;
            let x2533 = x1677 * k[2];
            let x2534 = x2532 + x2533;
            out[0] = k[1];
            out[1] = x1861;
            out[2] = x1870;
            out[3] = x1883;
            out[4] = x1896;
            out[5] = x1903;
            out[6] = x1910;
            out[7] = x1919;
            out[8] = x1927;
            out[9] = x1930;
            out[10] = x1935;
            out[11] = x1938;
            out[12] = x1943;
            out[13] = x1946;
            out[14] = x1950;
            out[15] = x1953;
            out[16] = x1956;
            out[17] = x2440;
            out[18] = x2448;
            out[19] = x2455;
            out[20] = x2462;
            out[21] = x2467;
            out[22] = x2473;
            out[23] = x2480;
            out[24] = x2487;
            out[25] = x2493;
            out[26] = x2499;
            out[27] = x2505;
            out[28] = x2511;
            out[29] = x2517;
            out[30] = x2523;
            out[31] = x2528;
            out[32] = x2534;
        }
        /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
        pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
            let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
            let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
            force_part_0(k, q, qd, t, out);
        }
        #[inline(never)]
        fn force_part_0(
            k: &[f64; 3],
            q: &[f64; 9],
            qd: &[f64; 9],
            t: f64,
            out: &mut [f64; 9],
        ) {
            let x3 = 4.0 * t;
            let x4 = x3.sin();
            let x5 = 3.0 * x4;
            let x9 = 3.0 * t;
            let x10 = x9.cos();
            let x11 = 0.5 * x10;
            let x13 = t.sin();
            let x14 = 0.2 * x13;
            let x25 = q[5] * q[5];
            let x26 = q[6] * q[6];
            let x123 = q[3] * 2.0;
            let x124 = q[4] * 2.0;
            let x125 = q[5] * 2.0;
            let x126 = q[6] * 2.0;
            let x153 = x125 * qd[5];
            let x154 = x126 * qd[6];
            let x173 = q[6] * qd[5];
            let x174 = q[5] * qd[6];
            let x177 = q[4] * qd[3];
            let x178 = q[3] * qd[4];
            let x216 = 2.0 * qd[3];
            let x217 = 2.0 * qd[4];
            let x218 = 2.0 * qd[5];
            let x219 = 2.0 * qd[6];
            let x292 = 1.0 + q[0];
            let x293 = x292 * x292;
            let x299 = 2.0 * x292;
            let x300 = qd[0] * x299;
            let x301 = q[1] * 2.0;
            let x303 = q[2] * 2.0;
            let x449 = qd[1] * qd[1];
            let x453 = qd[2] * qd[2];
            let x466 = 2.0 * qd[1];
            let x468 = 2.0 * qd[2];
            let x539 = 2.0 * x125;
            let x541 = 2.0 * x126;
            let x750 = qd[3] * qd[3];
            let x751 = qd[4] * qd[4];
            let x752 = qd[5] * qd[5];
            let x753 = qd[6] * qd[6];
            let x763 = q[3] * 0.04;
            let x782 = q[4] * 0.04;
            let x837 = qd[7] * qd[7];
            let x840 = qd[8] * qd[8];
            let x852 = 2.0 * qd[7];
            let x854 = 2.0 * qd[8];
            let x1678 = x25 + x26;
            let x1696 = 2.0 * q[7];
            let x1697 = 2.0 * q[8];
            let x1701 = q[3] * qd[2];
            let x1702 = q[2] * qd[3];
            let x1705 = q[4] * qd[1];
            let x1706 = q[1] * qd[4];
            let x1709 = q[4] * qd[2];
            let x1710 = q[2] * qd[4];
            let x1713 = q[3] * qd[1];
            let x1714 = q[1] * qd[3];
            let x1718 = q[2] * qd[1];
            let x1719 = q[1] * qd[2];
            let x1727 = x153 + x154;
            let x1728 = q[7] * qd[6];
            let x1729 = q[6] * qd[7];
            let x1732 = q[8] * qd[5];
            let x1733 = q[5] * qd[8];
            let x1738 = q[8] * qd[7];
            let x1739 = q[7] * qd[8];
            let x1751 = qd[2] * qd[3];
            let x1754 = qd[1] * qd[4];
            let x1757 = qd[2] * qd[4];
            let x1760 = qd[1] * qd[3];
            let x1773 = qd[6] * qd[7];
            let x1776 = qd[5] * qd[8];
            let x1796 = 2.0 * x1678;
            let x1797 = x1796 - 1.0;
            let x1798 = q[6] * q[8];
            let x1799 = 2.0 * x1798;
            let x1800 = q[5] * q[7];
            let x1801 = 2.0 * x1800;
            let x1803 = x1799 - x1801;
            let x1804 = x293.sqrt();
            let x1805 = x1804 - 1.0;
            let x1808 = -x1803;
            let x1809 = x1808.atan2(x1797);
            let x1813 = 2.0 * x1804;
            let x1814 = 1.0 / x1813;
            let x1815 = x300 * x1814;
            let x1816 = 0.8 * x1815;
            let x1818 = x5 - x1816;
            let x1820 = 2.0 * x1727;
            let x1821 = q[8] * qd[6];
            let x1822 = q[6] * qd[8];
            let x1823 = x1821 + x1822;
            let x1824 = 2.0 * x1823;
            let x1825 = q[7] * qd[5];
            let x1826 = q[5] * qd[7];
            let x1827 = x1825 + x1826;
            let x1828 = 2.0 * x1827;
            let x1830 = x1824 - x1828;
            let x1831 = x1797 * x1797;
            let x1832 = x1803 * x1803;
            let x1833 = x1831 + x1832;
            let x1834 = x1797 * x1830;
            let x1836 = x1803 * x1820;
            let x1837 = x1836 - x1834;
            let x1838 = 1.0 / x1833;
            let x1839 = x1837 * x1838;
            let x1840 = 0.1 * x1839;
            let x1842 = x11 - x1840;
            let x2114 = 50.0 * x1805;
            let x2116 = x1818 - x2114;
            let x2117 = x299 * x1814;
            let x2118 = x2116 * x2117;
            let x2119 = 2.0 * x1809;
            let x2121 = x1842 - x2119;
            let x2122 = x1696 * x1797;
            let x2123 = x539 * x1803;
            let x2124 = x2122 + x2123;
            let x2125 = x1838 * x2124;
            let x2126 = x1697 * x1797;
            let x2128 = x541 * x1803;
            let x2129 = x2128 - x2126;
            let x2130 = x1838 * x2129;
            let x2131 = x125 * x1797;
            let x2132 = x1838 * x2131;
            let x2133 = x126 * x1797;
            let x2134 = x1838 * x2133;
            let x2135 = x2121 * x2125;
            let x2136 = x2121 * x2130;
            let x2137 = x2121 * x2132;
            let x2138 = x2121 * x2134;
            let x2140 = x174 - x173;
            let x2142 = x14 * x1696;
            let x2144 = x14 * x1697;
            let x2145 = x14 * x125;
            let x2146 = x14 * x126;
            let x2147 = 1.0 + x2118;
            let x2148 = x2135 - x2142;
            let x2149 = x2136 + x2144;
            let x2150 = x2137 + x2145;
            let x2151 = x2138 + x2146;
            let x2155 = x1719 - x1718;
            let x2156 = x177 + x2155;
            let x2157 = x2156 - x178;
            let x2158 = 2.0 * x2157;
            let x2159 = x1709 + x1713;
            let x2161 = x1714 - x2159;
            let x2162 = x1710 + x2161;
            let x2163 = 2.0 * x2162;
            let x2166 = x1701 - x1705;
            let x2167 = x2166 - x1702;
            let x2168 = x1706 + x2167;
            let x2169 = 2.0 * x2168;
            let x2170 = 2.0 * x2158;
            let x2171 = 2.0 * x2163;
            let x2172 = 2.0 * x2169;
            let x2173 = x1757 + x1760;
            let x2175 = x1760 - x2173;
            let x2176 = x1757 + x2175;
            let x2177 = 2.0 * x2176;
            let x2180 = x1751 - x1754;
            let x2181 = x2180 - x1751;
            let x2182 = x1754 + x2181;
            let x2183 = 2.0 * x2182;
            let x2184 = 2.0 * x2177;
            let x2185 = 2.0 * x2183;
            let x2186 = x468 * x2170;
            let x2187 = 0.01 * x2186;
            let x2188 = x216 * x2171;
            let x2189 = x123 * x2184;
            let x2190 = x2188 + x2189;
            let x2191 = 0.01 * x2190;
            let x2192 = x217 * x2172;
            let x2193 = x124 * x2185;
            let x2194 = x2192 + x2193;
            let x2195 = 0.01 * x2194;
            let x2196 = x2187 + x2191;
            let x2197 = x2195 + x2196;
            let x2198 = 0.5 * x2197;
            let x2199 = x466 * x2170;
            let x2200 = 0.01 * x2199;
            let x2201 = x217 * x2171;
            let x2202 = x124 * x2184;
            let x2203 = x2201 + x2202;
            let x2204 = 0.01 * x2203;
            let x2206 = x216 * x2172;
            let x2207 = x123 * x2185;
            let x2208 = x2206 + x2207;
            let x2209 = 0.01 * x2208;
            let x2210 = x2200 - x2204;
            let x2211 = x2209 + x2210;
            let x2212 = 0.5 * x2211;
            let x2213 = x217 * x2170;
            let x2214 = 0.01 * x2213;
            let x2215 = x466 * x2171;
            let x2216 = x301 * x2184;
            let x2217 = x2215 + x2216;
            let x2218 = 0.01 * x2217;
            let x2219 = x468 * x2172;
            let x2220 = x303 * x2185;
            let x2221 = x2219 + x2220;
            let x2222 = 0.01 * x2221;
            let x2224 = x2214 + x2218;
            let x2225 = x2224 - x2222;
            let x2226 = 0.5 * x2225;
            let x2227 = x216 * x2170;
            let x2228 = 0.01 * x2227;
            let x2230 = x468 * x2171;
            let x2231 = x303 * x2184;
            let x2232 = x2230 + x2231;
            let x2233 = 0.01 * x2232;
            let x2234 = x466 * x2172;
            let x2235 = x301 * x2185;
            let x2236 = x2234 + x2235;
            let x2237 = 0.01 * x2236;
            let x2238 = x2233 - x2228;
            let x2239 = x2237 + x2238;
            let x2240 = 0.5 * x2239;
            let x2241 = x449 + x453;
            let x2242 = x750 + x2241;
            let x2243 = x751 + x2242;
            let x2244 = 0.01 * x2188;
            let x2245 = 0.01 * x2192;
            let x2246 = x2187 + x2244;
            let x2247 = x2245 + x2246;
            let x2248 = 0.5 * x2247;
            let x2249 = x2198 + x2248;
            let x2250 = q[1] * 0.04;
            let x2251 = x2243 * x2250;
            let x2253 = x2249 - x2251;
            let x2255 = 0.01 * x2201;
            let x2256 = 0.01 * x2206;
            let x2258 = x2255 - x2200;
            let x2259 = x2258 - x2256;
            let x2260 = 0.5 * x2259;
            let x2262 = x2260 - x2212;
            let x2263 = q[2] * 0.04;
            let x2264 = x2243 * x2263;
            let x2266 = x2262 - x2264;
            let x2267 = 0.01 * x2215;
            let x2268 = 0.01 * x2219;
            let x2269 = x2214 + x2267;
            let x2271 = x2268 - x2269;
            let x2272 = 0.5 * x2271;
            let x2274 = x2272 - x2226;
            let x2275 = x763 * x2243;
            let x2277 = x2274 - x2275;
            let x2278 = 0.01 * x2230;
            let x2280 = 0.01 * x2234;
            let x2282 = x2228 - x2278;
            let x2283 = x2282 - x2280;
            let x2284 = 0.5 * x2283;
            let x2286 = x2284 - x2240;
            let x2287 = x782 * x2243;
            let x2289 = x2286 - x2287;
            let x2291 = x1738 + x2140;
            let x2292 = x2291 - x1739;
            let x2293 = 2.0 * x2292;
            let x2294 = x1821 + x1825;
            let x2296 = x1826 - x2294;
            let x2297 = x1822 + x2296;
            let x2298 = 2.0 * x2297;
            let x2300 = x1728 - x1732;
            let x2301 = x2300 - x1729;
            let x2302 = x1733 + x2301;
            let x2303 = 2.0 * x2302;
            let x2304 = 2.0 * x2293;
            let x2305 = 2.0 * x2298;
            let x2306 = 2.0 * x2303;
            let x2307 = qd[6] * qd[8];
            let x2308 = qd[5] * qd[7];
            let x2310 = x2307 + x2308;
            let x2312 = x2308 - x2310;
            let x2313 = x2307 + x2312;
            let x2314 = 2.0 * x2313;
            let x2316 = x1773 - x1776;
            let x2317 = x2316 - x1773;
            let x2318 = x1776 + x2317;
            let x2319 = 2.0 * x2318;
            let x2320 = 2.0 * x2314;
            let x2321 = 2.0 * x2319;
            let x2322 = x219 * x2304;
            let x2323 = 0.1 * x2322;
            let x2324 = x852 * x2305;
            let x2325 = x1696 * x2320;
            let x2326 = x2324 + x2325;
            let x2328 = x854 * x2306;
            let x2329 = x1697 * x2321;
            let x2330 = x2328 + x2329;
            let x2331 = 0.3 * x2330;
            let x2335 = x218 * x2304;
            let x2336 = 0.1 * x2335;
            let x2337 = x854 * x2305;
            let x2338 = x1697 * x2320;
            let x2339 = x2337 + x2338;
            let x2342 = x852 * x2306;
            let x2343 = x1696 * x2321;
            let x2344 = x2342 + x2343;
            let x2345 = 0.3 * x2344;
            let x2349 = x854 * x2304;
            let x2350 = 0.1 * x2349;
            let x2351 = x218 * x2305;
            let x2352 = x125 * x2320;
            let x2353 = x2351 + x2352;
            let x2355 = x219 * x2306;
            let x2356 = x126 * x2321;
            let x2357 = x2355 + x2356;
            let x2358 = 0.3 * x2357;
            let x2363 = x852 * x2304;
            let x2364 = 0.1 * x2363;
            let x2366 = x219 * x2305;
            let x2367 = x126 * x2320;
            let x2368 = x2366 + x2367;
            let x2370 = x218 * x2306;
            let x2371 = x125 * x2321;
            let x2372 = x2370 + x2371;
            let x2373 = 0.3 * x2372;
            let x2377 = x752 + x753;
            let x2378 = x837 + x2377;
            let x2379 = x840 + x2378;
            let x2381 = 0.3 * x2328;
            let x2392 = 0.3 * x2342;
            let x2404 = 0.3 * x2355;
            let x2417 = 0.3 * x2370;
            let x2535 = x2326 * k[0];
            let x2536 = x2323 + x2535;
            let x2537 = x2331 + x2536;
            let x2538 = 0.5 * x2537;
            let x2539 = x2339 * k[0];
            let x2541 = x2336 - x2539;
            let x2542 = x2345 + x2541;
            let x2543 = 0.5 * x2542;
            let x2544 = x2353 * k[0];
            let x2545 = x2350 + x2544;
            let x2546 = x2545 - x2358;
            let x2547 = 0.5 * x2546;
            let x2548 = x2368 * k[0];
            let x2549 = x2548 - x2364;
            let x2550 = x2373 + x2549;
            let x2551 = 0.5 * x2550;
            let x2552 = x2324 * k[0];
            let x2553 = x2323 + x2552;
            let x2554 = x2381 + x2553;
            let x2555 = 0.5 * x2554;
            let x2556 = x2538 + x2555;
            let x2557 = q[5] * k[2];
            let x2558 = x2379 * x2557;
            let x2560 = x2556 - x2558;
            let x2561 = x2337 * k[0];
            let x2562 = x2561 - x2336;
            let x2563 = x2562 - x2392;
            let x2564 = 0.5 * x2563;
            let x2566 = x2564 - x2543;
            let x2567 = q[6] * k[2];
            let x2568 = x2379 * x2567;
            let x2570 = x2566 - x2568;
            let x2571 = x2351 * k[0];
            let x2572 = x2350 + x2571;
            let x2574 = x2404 - x2572;
            let x2575 = 0.5 * x2574;
            let x2577 = x2575 - x2547;
            let x2578 = q[7] * k[2];
            let x2579 = x2379 * x2578;
            let x2581 = x2577 - x2579;
            let x2582 = x2366 * k[0];
            let x2584 = x2364 - x2582;
            let x2585 = x2584 - x2417;
            let x2586 = 0.5 * x2585;
            let x2588 = x2586 - x2551;
            let x2589 = q[8] * k[2];
            let x2590 = x2379 * x2589;
            let x2592 = x2588 - x2590;
            let x2593 = x2148 + x2560;
            let x2594 = x2149 + x2570;
            let x2595 = x2150 + x2581;
            let x2596 = x2592 - x2151;
            out[0] = x2147;
            out[1] = x2253;
            out[2] = x2266;
            out[3] = x2277;
            out[4] = x2289;
            out[5] = x2593;
            out[6] = x2594;
            out[7] = x2595;
            out[8] = x2596;
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
            let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
            let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
            let phi: &mut [f64; 7] = phi.try_into().expect("phi must have 7 entries");
            let phi_q: &mut [f64; 28] = phi_q
                .try_into()
                .expect("phi_q must have 28 entries");
            let mass: &mut [f64; 33] = mass
                .try_into()
                .expect("mass must have 33 entries");
            let force: &mut [f64; 9] = force
                .try_into()
                .expect("force must have 9 entries");
            let mut s = [0.0f64; 94];
            eval_newton_shared_0(k, q, qd, t, &mut s);
            eval_newton_part_0(k, q, qd, t, &s, phi, phi_q, mass, force);
            eval_newton_part_1(k, q, qd, &s, force);
        }
        #[inline(never)]
        fn eval_newton_shared_0(
            _k: &[f64; 3],
            q: &[f64; 9],
            qd: &[f64; 9],
            t: f64,
            s: &mut [f64; 94],
        ) {
            let x9 = 3.0 * t;
            s[0] = x9;
            let x10 = x9.cos();
            s[1] = x10;
            let x11 = 0.5 * x10;
            s[2] = x11;
            let x13 = t.sin();
            s[3] = x13;
            let x14 = 0.2 * x13;
            s[4] = x14;
            let x25 = q[5] * q[5];
            s[5] = x25;
            let x26 = q[6] * q[6];
            s[6] = x26;
            let x125 = q[5] * 2.0;
            s[7] = x125;
            let x126 = q[6] * 2.0;
            s[8] = x126;
            let x153 = x125 * qd[5];
            s[9] = x153;
            let x154 = x126 * qd[6];
            s[10] = x154;
            let x173 = q[6] * qd[5];
            s[11] = x173;
            let x174 = q[5] * qd[6];
            s[12] = x174;
            let x219 = 2.0 * qd[6];
            s[13] = x219;
            let x541 = 2.0 * x126;
            s[14] = x541;
            let x752 = qd[5] * qd[5];
            s[15] = x752;
            let x753 = qd[6] * qd[6];
            s[16] = x753;
            let x837 = qd[7] * qd[7];
            s[17] = x837;
            let x840 = qd[8] * qd[8];
            s[18] = x840;
            let x852 = 2.0 * qd[7];
            s[19] = x852;
            let x854 = 2.0 * qd[8];
            s[20] = x854;
            let x1678 = x25 + x26;
            s[21] = x1678;
            let x1696 = 2.0 * q[7];
            s[22] = x1696;
            let x1697 = 2.0 * q[8];
            s[23] = x1697;
            let x1727 = x153 + x154;
            s[24] = x1727;
            let x1728 = q[7] * qd[6];
            s[25] = x1728;
            let x1729 = q[6] * qd[7];
            s[26] = x1729;
            let x1732 = q[8] * qd[5];
            s[27] = x1732;
            let x1733 = q[5] * qd[8];
            s[28] = x1733;
            let x1738 = q[8] * qd[7];
            s[29] = x1738;
            let x1739 = q[7] * qd[8];
            s[30] = x1739;
            let x1773 = qd[6] * qd[7];
            s[31] = x1773;
            let x1776 = qd[5] * qd[8];
            s[32] = x1776;
            let x1796 = 2.0 * x1678;
            s[33] = x1796;
            let x1797 = x1796 - 1.0;
            s[34] = x1797;
            let x1798 = q[6] * q[8];
            s[35] = x1798;
            let x1799 = 2.0 * x1798;
            s[36] = x1799;
            let x1800 = q[5] * q[7];
            s[37] = x1800;
            let x1801 = 2.0 * x1800;
            s[38] = x1801;
            let x1803 = x1799 - x1801;
            s[39] = x1803;
            let x1808 = -x1803;
            s[40] = x1808;
            let x1809 = x1808.atan2(x1797);
            s[41] = x1809;
            let x1820 = 2.0 * x1727;
            s[42] = x1820;
            let x1821 = q[8] * qd[6];
            s[43] = x1821;
            let x1822 = q[6] * qd[8];
            s[44] = x1822;
            let x1823 = x1821 + x1822;
            s[45] = x1823;
            let x1824 = 2.0 * x1823;
            s[46] = x1824;
            let x1825 = q[7] * qd[5];
            s[47] = x1825;
            let x1826 = q[5] * qd[7];
            s[48] = x1826;
            let x1827 = x1825 + x1826;
            s[49] = x1827;
            let x1828 = 2.0 * x1827;
            s[50] = x1828;
            let x1830 = x1824 - x1828;
            s[51] = x1830;
            let x1831 = x1797 * x1797;
            s[52] = x1831;
            let x1832 = x1803 * x1803;
            s[53] = x1832;
            let x1833 = x1831 + x1832;
            s[54] = x1833;
            let x1834 = x1797 * x1830;
            s[55] = x1834;
            let x1836 = x1803 * x1820;
            s[56] = x1836;
            let x1837 = x1836 - x1834;
            s[57] = x1837;
            let x1838 = 1.0 / x1833;
            s[58] = x1838;
            let x1839 = x1837 * x1838;
            s[59] = x1839;
            let x1840 = 0.1 * x1839;
            s[60] = x1840;
            let x1842 = x11 - x1840;
            s[61] = x1842;
            let x2119 = 2.0 * x1809;
            s[62] = x2119;
            let x2121 = x1842 - x2119;
            s[63] = x2121;
            let x2140 = x174 - x173;
            s[64] = x2140;
            let x2291 = x1738 + x2140;
            s[65] = x2291;
            let x2292 = x2291 - x1739;
            s[66] = x2292;
            let x2293 = 2.0 * x2292;
            s[67] = x2293;
            let x2294 = x1821 + x1825;
            s[68] = x2294;
            let x2296 = x1826 - x2294;
            s[69] = x2296;
            let x2297 = x1822 + x2296;
            s[70] = x2297;
            let x2298 = 2.0 * x2297;
            s[71] = x2298;
            let x2300 = x1728 - x1732;
            s[72] = x2300;
            let x2301 = x2300 - x1729;
            s[73] = x2301;
            let x2302 = x1733 + x2301;
            s[74] = x2302;
            let x2303 = 2.0 * x2302;
            s[75] = x2303;
            let x2304 = 2.0 * x2293;
            s[76] = x2304;
            let x2305 = 2.0 * x2298;
            s[77] = x2305;
            let x2306 = 2.0 * x2303;
            s[78] = x2306;
            let x2307 = qd[6] * qd[8];
            s[79] = x2307;
            let x2308 = qd[5] * qd[7];
            s[80] = x2308;
            let x2310 = x2307 + x2308;
            s[81] = x2310;
            let x2312 = x2308 - x2310;
            s[82] = x2312;
            let x2313 = x2307 + x2312;
            s[83] = x2313;
            let x2314 = 2.0 * x2313;
            s[84] = x2314;
            let x2316 = x1773 - x1776;
            s[85] = x2316;
            let x2317 = x2316 - x1773;
            s[86] = x2317;
            let x2318 = x1776 + x2317;
            s[87] = x2318;
            let x2319 = 2.0 * x2318;
            s[88] = x2319;
            let x2320 = 2.0 * x2314;
            s[89] = x2320;
            let x2321 = 2.0 * x2319;
            s[90] = x2321;
            let x2377 = x752 + x753;
            s[91] = x2377;
            let x2378 = x837 + x2377;
            s[92] = x2378;
            let x2379 = x840 + x2378;
            s[93] = x2379;
        }
        #[inline(never)]
        fn eval_newton_part_0(
            k: &[f64; 3],
            q: &[f64; 9],
            qd: &[f64; 9],
            t: f64,
            s: &[f64; 94],
            phi: &mut [f64; 7],
            phi_q: &mut [f64; 28],
            mass: &mut [f64; 33],
            force: &mut [f64; 9],
        ) {
            let x3 = 4.0 * t;
            let x4 = x3.sin();
            let x5 = 3.0 * x4;
            let x23 = q[3] * q[3];
            let x24 = q[4] * q[4];
            let x50 = q[5] * q[6];
            let x51 = 2.0 * x50;
            let x52 = q[3] * q[4];
            let x54 = 2.0 * x52;
            let x123 = q[3] * 2.0;
            let x124 = q[4] * 2.0;
            let x127 = -s[7];
            let x128 = -x123;
            let x177 = q[4] * qd[3];
            let x178 = q[3] * qd[4];
            let x216 = 2.0 * qd[3];
            let x217 = 2.0 * qd[4];
            let x292 = 1.0 + q[0];
            let x293 = x292 * x292;
            let x294 = q[1] * q[1];
            let x295 = q[2] * q[2];
            let x299 = 2.0 * x292;
            let x300 = qd[0] * x299;
            let x301 = q[1] * 2.0;
            let x303 = q[2] * 2.0;
            let x449 = qd[1] * qd[1];
            let x453 = qd[2] * qd[2];
            let x466 = 2.0 * qd[1];
            let x468 = 2.0 * qd[2];
            let x479 = -s[8];
            let x537 = 2.0 * x124;
            let x539 = 2.0 * s[7];
            let x543 = x124 * x537;
            let x545 = 0.01 * x543;
            let x547 = s[7] * x539;
            let x551 = s[8] * s[14];
            let x561 = x23 * 0.04;
            let x563 = 2.0 * x123;
            let x564 = x124 * x563;
            let x565 = 0.01 * x564;
            let x566 = s[7] * s[14];
            let x570 = s[8] * x539;
            let x576 = x52 * 0.04;
            let x606 = x123 * x537;
            let x608 = 0.01 * x606;
            let x616 = x123 * x563;
            let x617 = 0.01 * x616;
            let x621 = x24 * 0.04;
            let x750 = qd[3] * qd[3];
            let x751 = qd[4] * qd[4];
            let x763 = q[3] * 0.04;
            let x782 = q[4] * 0.04;
            let x1661 = x294 + x295;
            let x1662 = q[2] * q[3];
            let x1663 = 2.0 * x1662;
            let x1664 = q[1] * q[4];
            let x1665 = 2.0 * x1664;
            let x1666 = q[2] * q[4];
            let x1667 = 2.0 * x1666;
            let x1668 = q[1] * q[3];
            let x1669 = 2.0 * x1668;
            let x1670 = x1663 + x1665;
            let x1671 = q[1] * q[2];
            let x1672 = 2.0 * x1671;
            let x1674 = x1667 - x1669;
            let x1675 = x54 + x1672;
            let x1676 = q[7] * q[7];
            let x1677 = q[8] * q[8];
            let x1679 = q[6] * q[7];
            let x1680 = 2.0 * x1679;
            let x1681 = q[5] * q[8];
            let x1682 = 2.0 * x1681;
            let x1684 = x1680 - x1682;
            let x1685 = q[7] * q[8];
            let x1686 = 2.0 * x1685;
            let x1687 = x51 + x1686;
            let x1688 = -x1687;
            let x1689 = x23 + x1661;
            let x1690 = x24 + x1689;
            let x1691 = x1690 - 1.0;
            let x1692 = x1676 + s[21];
            let x1693 = x1677 + x1692;
            let x1694 = x1693 - 1.0;
            let x1695 = -x301;
            let x1698 = -s[23];
            let x1699 = -s[22];
            let x1701 = q[3] * qd[2];
            let x1702 = q[2] * qd[3];
            let x1705 = q[4] * qd[1];
            let x1706 = q[1] * qd[4];
            let x1709 = q[4] * qd[2];
            let x1710 = q[2] * qd[4];
            let x1713 = q[3] * qd[1];
            let x1714 = q[1] * qd[3];
            let x1718 = q[2] * qd[1];
            let x1719 = q[1] * qd[2];
            let x1751 = qd[2] * qd[3];
            let x1754 = qd[1] * qd[4];
            let x1757 = qd[2] * qd[4];
            let x1760 = qd[1] * qd[3];
            let x1804 = x293.sqrt();
            let x1805 = x1804 - 1.0;
            let x1813 = 2.0 * x1804;
            let x1814 = 1.0 / x1813;
            let x1815 = x300 * x1814;
            let x1816 = 0.8 * x1815;
            let x1818 = x5 - x1816;
            let x1854 = 2.0 * x303;
            let x1855 = x303 * x1854;
            let x1856 = 0.01 * x1855;
            let x1857 = x617 + x1856;
            let x1858 = x545 + x1857;
            let x1859 = 0.5 * x1858;
            let x1860 = x294 * 0.04;
            let x1861 = x1859 + x1860;
            let x1862 = 2.0 * x301;
            let x1863 = x303 * x1862;
            let x1864 = 0.01 * x1863;
            let x1865 = x1864 - x608;
            let x1866 = x565 + x1865;
            let x1867 = 0.5 * x1866;
            let x1869 = 0.04 * x1671;
            let x1870 = x1869 - x1867;
            let x1871 = x303 * x537;
            let x1872 = 0.01 * x1871;
            let x1873 = x123 * x1862;
            let x1874 = 0.01 * x1873;
            let x1875 = x124 * x1854;
            let x1876 = 0.01 * x1875;
            let x1878 = x1872 + x1874;
            let x1879 = x1878 - x1876;
            let x1880 = 0.5 * x1879;
            let x1882 = 0.04 * x1668;
            let x1883 = x1882 - x1880;
            let x1884 = x303 * x563;
            let x1885 = 0.01 * x1884;
            let x1887 = x123 * x1854;
            let x1888 = 0.01 * x1887;
            let x1889 = x124 * x1862;
            let x1890 = 0.01 * x1889;
            let x1891 = x1888 - x1885;
            let x1892 = x1890 + x1891;
            let x1893 = 0.5 * x1892;
            let x1895 = 0.04 * x1664;
            let x1896 = x1895 - x1893;
            let x1897 = x301 * x1854;
            let x1898 = 0.01 * x1897;
            let x1900 = x565 - x1898;
            let x1901 = x1900 - x608;
            let x1902 = 0.5 * x1901;
            let x1903 = x1869 + x1902;
            let x1904 = x301 * x1862;
            let x1905 = 0.01 * x1904;
            let x1906 = x545 + x1905;
            let x1907 = x617 + x1906;
            let x1908 = 0.5 * x1907;
            let x1909 = x295 * 0.04;
            let x1910 = x1908 + x1909;
            let x1911 = x301 * x537;
            let x1912 = 0.01 * x1911;
            let x1915 = x1912 - x1890;
            let x1916 = x1915 - x1888;
            let x1917 = 0.5 * x1916;
            let x1918 = 0.04 * x1662;
            let x1919 = x1917 + x1918;
            let x1920 = x301 * x563;
            let x1921 = 0.01 * x1920;
            let x1922 = x1876 + x1921;
            let x1924 = x1874 - x1922;
            let x1925 = 0.5 * x1924;
            let x1926 = 0.04 * x1666;
            let x1927 = x1925 + x1926;
            let x1928 = x1872 - x1922;
            let x1929 = 0.5 * x1928;
            let x1930 = x1882 + x1929;
            let x1932 = x1890 - x1912;
            let x1933 = x1932 - x1885;
            let x1934 = 0.5 * x1933;
            let x1935 = x1918 + x1934;
            let x1936 = x1856 + x1906;
            let x1937 = 0.5 * x1936;
            let x1938 = x561 + x1937;
            let x1940 = x1898 - x565;
            let x1941 = x1940 - x1864;
            let x1942 = 0.5 * x1941;
            let x1943 = x576 + x1942;
            let x1944 = x1891 - x1912;
            let x1945 = 0.5 * x1944;
            let x1946 = x1895 + x1945;
            let x1948 = x1921 - x1878;
            let x1949 = 0.5 * x1948;
            let x1950 = x1926 + x1949;
            let x1951 = x1865 - x1898;
            let x1952 = 0.5 * x1951;
            let x1953 = x576 + x1952;
            let x1954 = x1857 + x1905;
            let x1955 = 0.5 * x1954;
            let x1956 = x621 + x1955;
            let x1957 = 2.0 * s[22];
            let x1958 = 2.0 * s[23];
            let x1959 = 0.1 * x551;
            let x1960 = s[22] * x1957;
            let x1962 = s[23] * x1958;
            let x1963 = 0.3 * x1962;
            let x1969 = 0.1 * x570;
            let x1970 = s[22] * x1958;
            let x1973 = s[23] * x1957;
            let x1974 = 0.3 * x1973;
            let x1981 = s[8] * x1958;
            let x1982 = 0.1 * x1981;
            let x1983 = x539 * s[22];
            let x1985 = s[14] * s[23];
            let x1986 = 0.3 * x1985;
            let x1994 = s[8] * x1957;
            let x1995 = 0.1 * x1994;
            let x1997 = s[14] * s[22];
            let x1999 = x539 * s[23];
            let x2000 = 0.3 * x1999;
            let x2007 = 0.1 * x566;
            let x2010 = 0.3 * x1970;
            let x2016 = 0.1 * x547;
            let x2018 = 0.3 * x1960;
            let x2024 = s[7] * x1958;
            let x2025 = 0.1 * x2024;
            let x2028 = 0.3 * x1997;
            let x2035 = s[7] * x1957;
            let x2036 = 0.1 * x2035;
            let x2038 = 0.3 * x1983;
            let x2045 = 0.1 * x1985;
            let x2047 = 0.3 * x1981;
            let x2053 = 0.1 * x1999;
            let x2056 = 0.3 * x1994;
            let x2062 = 0.1 * x1962;
            let x2064 = 0.3 * x551;
            let x2070 = 0.1 * x1973;
            let x2073 = 0.3 * x570;
            let x2080 = 0.1 * x1997;
            let x2083 = 0.3 * x2024;
            let x2089 = 0.1 * x1983;
            let x2091 = 0.3 * x2035;
            let x2097 = 0.1 * x1970;
            let x2100 = 0.3 * x566;
            let x2106 = 0.1 * x1960;
            let x2108 = 0.3 * x547;
            let x2114 = 50.0 * x1805;
            let x2116 = x1818 - x2114;
            let x2117 = x299 * x1814;
            let x2118 = x2116 * x2117;
            let x2122 = s[22] * s[34];
            let x2123 = x539 * s[39];
            let x2124 = x2122 + x2123;
            let x2125 = s[58] * x2124;
            let x2135 = s[63] * x2125;
            let x2142 = s[4] * s[22];
            let x2147 = 1.0 + x2118;
            let x2148 = x2135 - x2142;
            let x2155 = x1719 - x1718;
            let x2156 = x177 + x2155;
            let x2157 = x2156 - x178;
            let x2158 = 2.0 * x2157;
            let x2159 = x1709 + x1713;
            let x2161 = x1714 - x2159;
            let x2162 = x1710 + x2161;
            let x2163 = 2.0 * x2162;
            let x2166 = x1701 - x1705;
            let x2167 = x2166 - x1702;
            let x2168 = x1706 + x2167;
            let x2169 = 2.0 * x2168;
            let x2170 = 2.0 * x2158;
            let x2171 = 2.0 * x2163;
            let x2172 = 2.0 * x2169;
            let x2173 = x1757 + x1760;
            let x2175 = x1760 - x2173;
            let x2176 = x1757 + x2175;
            let x2177 = 2.0 * x2176;
            let x2180 = x1751 - x1754;
            let x2181 = x2180 - x1751;
            let x2182 = x1754 + x2181;
            let x2183 = 2.0 * x2182;
            let x2184 = 2.0 * x2177;
            let x2185 = 2.0 * x2183;
            let x2186 = x468 * x2170;
            let x2187 = 0.01 * x2186;
            let x2188 = x216 * x2171;
            let x2189 = x123 * x2184;
            let x2190 = x2188 + x2189;
            let x2191 = 0.01 * x2190;
            let x2192 = x217 * x2172;
            let x2193 = x124 * x2185;
            let x2194 = x2192 + x2193;
            let x2195 = 0.01 * x2194;
            let x2196 = x2187 + x2191;
            let x2197 = x2195 + x2196;
            let x2198 = 0.5 * x2197;
            let x2199 = x466 * x2170;
            let x2200 = 0.01 * x2199;
            let x2201 = x217 * x2171;
            let x2202 = x124 * x2184;
            let x2203 = x2201 + x2202;
            let x2204 = 0.01 * x2203;
            let x2206 = x216 * x2172;
            let x2207 = x123 * x2185;
            let x2208 = x2206 + x2207;
            let x2209 = 0.01 * x2208;
            let x2210 = x2200 - x2204;
            let x2211 = x2209 + x2210;
            let x2212 = 0.5 * x2211;
            let x2213 = x217 * x2170;
            let x2214 = 0.01 * x2213;
            let x2215 = x466 * x2171;
            let x2216 = x301 * x2184;
            let x2217 = x2215 + x2216;
            let x2218 = 0.01 * x2217;
            let x2219 = x468 * x2172;
            let x2220 = x303 * x2185;
            let x2221 = x2219 + x2220;
            let x2222 = 0.01 * x2221;
            let x2224 = x2214 + x2218;
            let x2225 = x2224 - x2222;
            let x2226 = 0.5 * x2225;
            let x2227 = x216 * x2170;
            let x2228 = 0.01 * x2227;
            let x2230 = x468 * x2171;
            let x2231 = x303 * x2184;
            let x2232 = x2230 + x2231;
            let x2233 = 0.01 * x2232;
            let x2234 = x466 * x2172;
            let x2235 = x301 * x2185;
            let x2236 = x2234 + x2235;
            let x2237 = 0.01 * x2236;
            let x2238 = x2233 - x2228;
            let x2239 = x2237 + x2238;
            let x2240 = 0.5 * x2239;
            let x2241 = x449 + x453;
            let x2242 = x750 + x2241;
            let x2243 = x751 + x2242;
            let x2244 = 0.01 * x2188;
            let x2245 = 0.01 * x2192;
            let x2246 = x2187 + x2244;
            let x2247 = x2245 + x2246;
            let x2248 = 0.5 * x2247;
            let x2249 = x2198 + x2248;
            let x2250 = q[1] * 0.04;
            let x2251 = x2243 * x2250;
            let x2253 = x2249 - x2251;
            let x2255 = 0.01 * x2201;
            let x2256 = 0.01 * x2206;
            let x2258 = x2255 - x2200;
            let x2259 = x2258 - x2256;
            let x2260 = 0.5 * x2259;
            let x2262 = x2260 - x2212;
            let x2263 = q[2] * 0.04;
            let x2264 = x2243 * x2263;
            let x2266 = x2262 - x2264;
            let x2267 = 0.01 * x2215;
            let x2268 = 0.01 * x2219;
            let x2269 = x2214 + x2267;
            let x2271 = x2268 - x2269;
            let x2272 = 0.5 * x2271;
            let x2274 = x2272 - x2226;
            let x2275 = x763 * x2243;
            let x2277 = x2274 - x2275;
            let x2278 = 0.01 * x2230;
            let x2280 = 0.01 * x2234;
            let x2282 = x2228 - x2278;
            let x2283 = x2282 - x2280;
            let x2284 = 0.5 * x2283;
            let x2286 = x2284 - x2240;
            let x2287 = x782 * x2243;
            let x2289 = x2286 - x2287;
            let x2322 = s[13] * s[76];
            let x2323 = 0.1 * x2322;
            let x2324 = s[19] * s[77];
            let x2325 = s[22] * s[89];
            let x2326 = x2324 + x2325;
            let x2328 = s[20] * s[78];
            let x2329 = s[23] * s[90];
            let x2330 = x2328 + x2329;
            let x2331 = 0.3 * x2330;
            let x2381 = 0.3 * x2328;
            let x2435 = x1960 * k[0];
            let x2436 = x1959 + x2435;
            let x2437 = x1963 + x2436;
            let x2438 = 0.5 * x2437;
            let x2439 = s[5] * k[2];
            let x2440 = x2438 + x2439;
            let x2441 = x1970 * k[0];
            let x2443 = x1969 - x2441;
            let x2444 = x1974 + x2443;
            let x2445 = 0.5 * x2444;
            let x2447 = x50 * k[2];
            let x2448 = x2447 - x2445;
            let x2449 = x1983 * k[0];
            let x2450 = x1982 + x2449;
            let x2451 = x2450 - x1986;
            let x2452 = 0.5 * x2451;
            let x2454 = s[37] * k[2];
            let x2455 = x2454 - x2452;
            let x2456 = x1997 * k[0];
            let x2457 = x2456 - x1995;
            let x2458 = x2000 + x2457;
            let x2459 = 0.5 * x2458;
            let x2461 = x1681 * k[2];
            let x2462 = x2461 - x2459;
            let x2463 = x1973 * k[0];
            let x2464 = x2463 - x2007;
            let x2465 = x2464 - x2010;
            let x2466 = 0.5 * x2465;
            let x2467 = x2447 + x2466;
            let x2468 = x1962 * k[0];
            let x2469 = x2016 + x2468;
            let x2470 = x2018 + x2469;
            let x2471 = 0.5 * x2470;
            let x2472 = s[6] * k[2];
            let x2473 = x2471 + x2472;
            let x2474 = x1999 * k[0];
            let x2476 = x2025 - x2474;
            let x2477 = x2476 - x2028;
            let x2478 = 0.5 * x2477;
            let x2479 = x1679 * k[2];
            let x2480 = x2478 + x2479;
            let x2481 = x1985 * k[0];
            let x2482 = x2036 + x2481;
            let x2484 = x2038 - x2482;
            let x2485 = 0.5 * x2484;
            let x2486 = s[35] * k[2];
            let x2487 = x2485 + x2486;
            let x2488 = x2035 * k[0];
            let x2489 = x2045 + x2488;
            let x2491 = x2047 - x2489;
            let x2492 = 0.5 * x2491;
            let x2493 = x2454 + x2492;
            let x2494 = x2024 * k[0];
            let x2496 = x2053 - x2494;
            let x2497 = x2496 - x2056;
            let x2498 = 0.5 * x2497;
            let x2499 = x2479 + x2498;
            let x2500 = x547 * k[0];
            let x2501 = x2062 + x2500;
            let x2502 = x2064 + x2501;
            let x2503 = 0.5 * x2502;
            let x2504 = x1676 * k[2];
            let x2505 = x2503 + x2504;
            let x2506 = x566 * k[0];
            let x2507 = x2506 - x2070;
            let x2508 = x2507 - x2073;
            let x2509 = 0.5 * x2508;
            let x2510 = x1685 * k[2];
            let x2511 = x2509 + x2510;
            let x2512 = x1994 * k[0];
            let x2514 = x2080 - x2512;
            let x2515 = x2514 - x2083;
            let x2516 = 0.5 * x2515;
            let x2517 = x2461 + x2516;
            let x2518 = x1981 * k[0];
            let x2519 = x2089 + x2518;
            let x2521 = x2091 - x2519;
            let x2522 = 0.5 * x2521;
            let x2523 = x2486 + x2522;
            let x2524 = x570 * k[0];
            let x2525 = x2524 - x2097;
            let x2526 = x2525 - x2100;
            let x2527 = 0.5 * x2526;
            let x2528 = x2510 + x2527;
            let x2529 = x551 * k[0];
            let x2530 = x2106 + x2529;
            let x2531 = x2108 + x2530;
            let x2532 = 0.5 * x2531;
            let x2533 = x1677 * k[2];
            let x2534 = x2532 + x2533;
            let x2535 = x2326 * k[0];
            let x2536 = x2323 + x2535;
            let x2537 = x2331 + x2536;
            let x2538 = 0.5 * x2537;
            let x2552 = x2324 * k[0];
            let x2553 = x2323 + x2552;
            let x2554 = x2381 + x2553;
            let x2555 = 0.5 * x2554;
            let x2556 = x2538 + x2555;
            let x2557 = q[5] * k[2];
            let x2558 = s[93] * x2557;
            let x2560 = x2556 - x2558;
            let x2593 = x2148 + x2560;
            phi[0] = x1670;
            phi_q[0] = x124;
            phi_q[1] = x123;
            phi_q[2] = x303;
            phi_q[3] = x301;
            phi[1] = x1674;
            phi_q[4] = x128;
            phi_q[5] = x124;
            phi_q[6] = x1695;
            phi_q[7] = x303;
            phi[2] = x1675;
            phi_q[8] = x303;
            phi_q[9] = x301;
            phi_q[10] = x124;
            phi_q[11] = x123;
            phi[3] = x1684;
            phi_q[12] = x1698;
            phi_q[13] = s[22];
            phi_q[14] = s[8];
            phi_q[15] = x127;
            phi[4] = x1688;
            phi_q[16] = x479;
            phi_q[17] = x127;
            phi_q[18] = x1698;
            phi_q[19] = x1699;
            phi[5] = x1691;
            phi_q[20] = x301;
            phi_q[21] = x303;
            phi_q[22] = x123;
            phi_q[23] = x124;
            phi[6] = x1694;
            phi_q[24] = s[7];
            phi_q[25] = s[8];
            phi_q[26] = s[22];
            phi_q[27] = s[23];
            mass[0] = k[1];
            mass[1] = x1861;
            mass[2] = x1870;
            mass[3] = x1883;
            mass[4] = x1896;
            mass[5] = x1903;
            mass[6] = x1910;
            mass[7] = x1919;
            mass[8] = x1927;
            mass[9] = x1930;
            mass[10] = x1935;
            mass[11] = x1938;
            mass[12] = x1943;
            mass[13] = x1946;
            mass[14] = x1950;
            mass[15] = x1953;
            mass[16] = x1956;
            mass[17] = x2440;
            mass[18] = x2448;
            mass[19] = x2455;
            mass[20] = x2462;
            mass[21] = x2467;
            mass[22] = x2473;
            mass[23] = x2480;
            mass[24] = x2487;
            mass[25] = x2493;
            mass[26] = x2499;
            mass[27] = x2505;
            mass[28] = x2511;
            mass[29] = x2517;
            mass[30] = x2523;
            mass[31] = x2528;
            mass[32] = x2534;
            force[0] = x2147;
            force[1] = x2253;
            force[2] = x2266;
            force[3] = x2277;
            force[4] = x2289;
            force[5] = x2593;
        }
        #[inline(never)]
        fn eval_newton_part_1(
            k: &[f64; 3],
            q: &[f64; 9],
            qd: &[f64; 9],
            s: &[f64; 94],
            force: &mut [f64; 9],
        ) {
            let x218 = 2.0 * qd[5];
            let x2126 = s[23] * s[34];
            let x2128 = s[14] * s[39];
            let x2129 = x2128 - x2126;
            let x2130 = s[58] * x2129;
            let x2131 = s[7] * s[34];
            let x2132 = s[58] * x2131;
            let x2133 = s[8] * s[34];
            let x2134 = s[58] * x2133;
            let x2136 = s[63] * x2130;
            let x2137 = s[63] * x2132;
            let x2138 = s[63] * x2134;
            let x2144 = s[4] * s[23];
            let x2145 = s[4] * s[7];
            let x2146 = s[4] * s[8];
            let x2149 = x2136 + x2144;
            let x2150 = x2137 + x2145;
            let x2151 = x2138 + x2146;
            let x2335 = x218 * s[76];
            let x2336 = 0.1 * x2335;
            let x2337 = s[20] * s[77];
            let x2338 = s[23] * s[89];
            let x2339 = x2337 + x2338;
            let x2342 = s[19] * s[78];
            let x2343 = s[22] * s[90];
            let x2344 = x2342 + x2343;
            let x2345 = 0.3 * x2344;
            let x2349 = s[20] * s[76];
            let x2350 = 0.1 * x2349;
            let x2351 = x218 * s[77];
            let x2352 = s[7] * s[89];
            let x2353 = x2351 + x2352;
            let x2355 = s[13] * s[78];
            let x2356 = s[8] * s[90];
            let x2357 = x2355 + x2356;
            let x2358 = 0.3 * x2357;
            let x2363 = s[19] * s[76];
            let x2364 = 0.1 * x2363;
            let x2366 = s[13] * s[77];
            let x2367 = s[8] * s[89];
            let x2368 = x2366 + x2367;
            let x2370 = x218 * s[78];
            let x2371 = s[7] * s[90];
            let x2372 = x2370 + x2371;
            let x2373 = 0.3 * x2372;
            let x2392 = 0.3 * x2342;
            let x2404 = 0.3 * x2355;
            let x2417 = 0.3 * x2370;
            let x2539 = x2339 * k[0];
            let x2541 = x2336 - x2539;
            let x2542 = x2345 + x2541;
            let x2543 = 0.5 * x2542;
            let x2544 = x2353 * k[0];
            let x2545 = x2350 + x2544;
            let x2546 = x2545 - x2358;
            let x2547 = 0.5 * x2546;
            let x2548 = x2368 * k[0];
            let x2549 = x2548 - x2364;
            let x2550 = x2373 + x2549;
            let x2551 = 0.5 * x2550;
            let x2561 = x2337 * k[0];
            let x2562 = x2561 - x2336;
            let x2563 = x2562 - x2392;
            let x2564 = 0.5 * x2563;
            let x2566 = x2564 - x2543;
            let x2567 = q[6] * k[2];
            let x2568 = s[93] * x2567;
            let x2570 = x2566 - x2568;
            let x2571 = x2351 * k[0];
            let x2572 = x2350 + x2571;
            let x2574 = x2404 - x2572;
            let x2575 = 0.5 * x2574;
            let x2577 = x2575 - x2547;
            let x2578 = q[7] * k[2];
            let x2579 = s[93] * x2578;
            let x2581 = x2577 - x2579;
            let x2582 = x2366 * k[0];
            let x2584 = x2364 - x2582;
            let x2585 = x2584 - x2417;
            let x2586 = 0.5 * x2585;
            let x2588 = x2586 - x2551;
            let x2589 = q[8] * k[2];
            let x2590 = s[93] * x2589;
            let x2592 = x2588 - x2590;
            let x2594 = x2149 + x2570;
            let x2595 = x2150 + x2581;
            let x2596 = x2592 - x2151;
            force[6] = x2594;
            force[7] = x2595;
            force[8] = x2596;
        }
    }
    /// `oscillators` reduced by substitution, with the `exact` formulation.
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
}
/// `oscillators` with the `exact` formulation.
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
        let mut p = Parameters::file_values();
        p.set(set)?;
        Ok(ExactAt(p))
    }
}
/// `oscillators` with the `exact` formulation. At run-time parameter values (`Exact::with_parameters`).
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
    name: "oscillators",
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
            env!("CARGO_MANIFEST_DIR"), "/../../../", "mechanisms/oscillators.toml"
        ),
        hash: 4635265543466163833u64,
        parameters: &[],
    },
    run_time: Some(&RUN_TIME_ENTRY),
};
