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
    let k: &[f64; 11] = k.try_into().expect("k must have 11 entries");
    let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    potential_into_part_0(k, q, out);
}
#[inline(never)]
fn potential_into_part_0(k: &[f64; 11], q: &[f64; 14], out: &mut [f64; 1]) {
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
    let x295 = q[8] * 9.81;
    let x296 = 1.0 + q[0];
    let x297 = x296 * x296;
    let x298 = q[1] * q[1];
    let x299 = q[2] * q[2];
    let x300 = x297 + x298;
    let x301 = x299 + x300;
    let x302 = x301.sqrt();
    let x314 = x302 - 1.0;
    let x322 = x314 * x314;
    let x331 = -x103;
    let x332 = x331.atan2(x74);
    let x362 = x332 * x332;
    let x1672 = q[1] * k[5];
    let x1680 = x322 * k[7];
    let x1692 = x362 * k[8];
    let x1704 = x295 + x1672;
    let x1705 = x1680 + x1704;
    let x1706 = x1692 + x1705;
    out[0] = x1706;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 11] = k.try_into().expect("k must have 11 entries");
    let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    power_nc_into_part_0(k, q, qd, t, out);
}
#[inline(never)]
fn power_nc_into_part_0(
    k: &[f64; 11],
    q: &[f64; 14],
    qd: &[f64; 14],
    t: f64,
    out: &mut [f64; 1],
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
    let x184 = x129 * qd[10];
    let x185 = x130 * qd[11];
    let x188 = x184 + x185;
    let x296 = 1.0 + q[0];
    let x297 = x296 * x296;
    let x298 = q[1] * q[1];
    let x299 = q[2] * q[2];
    let x300 = x297 + x298;
    let x301 = x299 + x300;
    let x302 = x301.sqrt();
    let x303 = 2.0 * x296;
    let x304 = qd[0] * x303;
    let x305 = q[1] * 2.0;
    let x306 = qd[1] * x305;
    let x307 = q[2] * 2.0;
    let x308 = qd[2] * x307;
    let x309 = x304 + x306;
    let x310 = x308 + x309;
    let x311 = 2.0 * x302;
    let x312 = 1.0 / x311;
    let x313 = x310 * x312;
    let x333 = 2.0 * x188;
    let x334 = q[13] * qd[11];
    let x335 = q[11] * qd[13];
    let x336 = x334 + x335;
    let x337 = 2.0 * x336;
    let x338 = q[12] * qd[10];
    let x339 = q[10] * qd[12];
    let x340 = x338 + x339;
    let x341 = 2.0 * x340;
    let x343 = x337 - x341;
    let x345 = x74 * x74;
    let x346 = x103 * x103;
    let x347 = x345 + x346;
    let x348 = x74 * x343;
    let x350 = x103 * x333;
    let x352 = x350 - x348;
    let x353 = 1.0 / x347;
    let x354 = x352 * x353;
    let x397 = x334 - x338;
    let x398 = x339 + x397;
    let x399 = x398 - x335;
    let x400 = 2.0 * x399;
    let x408 = x14 * x400;
    let x1674 = x313 * k[0];
    let x1676 = x5 - x1674;
    let x1681 = x313 * x1676;
    let x1686 = x354 * k[1];
    let x1688 = x11 - x1686;
    let x1693 = x354 * x1688;
    let x1707 = qd[0] + x1681;
    let x1708 = x1693 + x1707;
    let x1709 = x408 + x1708;
    out[0] = x1709;
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
pub const N_K: usize = 11;
/// `setup` at the file's parameter values: what the types without parameters read.
pub static K: [f64; 11] = [
    0.8f64,
    0.1f64,
    0.2f64,
    50f64,
    2f64,
    19.62f64,
    -19.62f64,
    25f64,
    1f64,
    2f64,
    0.8f64,
];
/// The values the per-step functions read (`k`), from the run-time parameters `p`.
pub fn setup(p: &[f64], k: &mut [f64]) {
    let p: &[f64; 6] = p.try_into().expect("p must have 6 entries");
    let k: &mut [f64; 11] = k.try_into().expect("k must have 11 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 6], k: &mut [f64; 11]) {
    let x292 = p[5] * 9.81;
    let x293 = -x292;
    let x321 = 0.5 * p[3];
    let x361 = 0.5 * p[4];
    let x539 = 2.0 * p[5];
    let x540 = 0.5 * x539;
    let x916 = 0.1 + p[2];
    let x917 = 0.3 + x916;
    let x918 = 4.0 * x917;
    let x920 = x918 * 0.3333333333333333;
    k[0] = p[0];
    k[1] = p[1];
    k[2] = p[2];
    k[3] = p[3];
    k[4] = p[4];
    k[5] = x292;
    k[6] = x293;
    k[7] = x321;
    k[8] = x361;
    k[9] = x540;
    k[10] = x920;
}
/// The parameters the generated code takes at run time: the file's `[parameters]`
/// entries that reach only masses, inertias and springs' constants (the others are set on
/// the file).
pub static PARAMETERS: [&str; 6] = ["c", "ct", "j", "k", "kt", "m"];
/// Their values in the file.
pub static PARAMETER_VALUES: [f64; 6] = [0.8f64, 0.1f64, 0.2f64, 50f64, 2f64, 2f64];
static OTHER_PARAMETERS: [&str; 8] = [
    "f0",
    "fc",
    "nu",
    "omega0",
    "tau1",
    "tau2",
    "w",
    "x0",
];
static BODY_NAMES: [&str; 2] = ["slider", "rotor"];
static FORCE_NAMES: [&str; 4] = ["spring", "push", "coil", "twist"];
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
    let p: &[f64; 6] = p.try_into().expect("p must have 6 entries");
    let out: &mut [f64; 8] = out.try_into().expect("out must have 8 entries");
    mass_properties_part_0(p, out);
}
#[inline(never)]
fn mass_properties_part_0(p: &[f64; 6], out: &mut [f64; 8]) {
    out[0] = p[5];
    out[1] = 0.01;
    out[2] = 0.01;
    out[3] = 0.01;
    out[4] = 1.0;
    out[5] = 0.1;
    out[6] = p[2];
    out[7] = 0.3;
}
/// Each force's stiffness and damping at the run-time parameters `p`.
pub fn force_constants(p: &[f64], out: &mut [f64]) {
    let p: &[f64; 6] = p.try_into().expect("p must have 6 entries");
    let out: &mut [f64; 8] = out.try_into().expect("out must have 8 entries");
    force_constants_part_0(p, out);
}
#[inline(never)]
fn force_constants_part_0(p: &[f64; 6], out: &mut [f64; 8]) {
    out[0] = p[3];
    out[1] = p[0];
    out[2] = 0.0;
    out[3] = 0.0;
    out[4] = p[4];
    out[5] = p[1];
    out[6] = 0.0;
    out[7] = 0.0;
}
/// One set of run-time parameter values and the values `setup` computed from it.
#[derive(Debug, Clone)]
pub struct Parameters {
    p: [f64; 6],
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
        let (mut props, mut constants) = ([0.0; 8], [0.0; 8]);
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
        let k: &[f64; 11] = k.try_into().expect("k must have 11 entries");
        let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
        let dq: &mut [f64; 25] = dq.try_into().expect("dq must have 25 entries");
        let dqd: &mut [f64; 25] = dqd.try_into().expect("dqd must have 25 entries");
        force_jacobian_part_0(k, q, qd, t, dq, dqd);
    }
    #[inline(never)]
    fn force_jacobian_part_0(
        k: &[f64; 11],
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
        let x296 = 1.0 + q[0];
        let x297 = x296 * x296;
        let x298 = q[1] * q[1];
        let x299 = q[2] * q[2];
        let x300 = x297 + x298;
        let x301 = x299 + x300;
        let x302 = x301.sqrt();
        let x303 = 2.0 * x296;
        let x304 = qd[0] * x303;
        let x305 = q[1] * 2.0;
        let x306 = qd[1] * x305;
        let x307 = q[2] * 2.0;
        let x308 = qd[2] * x307;
        let x309 = x304 + x306;
        let x310 = x308 + x309;
        let x311 = 2.0 * x302;
        let x312 = 1.0 / x311;
        let x313 = x310 * x312;
        let x314 = x302 - 1.0;
        let x325 = x303 * x312;
        let x326 = x305 * x312;
        let x327 = x307 * x312;
        let x331 = -x103;
        let x332 = x331.atan2(x74);
        let x333 = 2.0 * x188;
        let x334 = q[13] * qd[11];
        let x335 = q[11] * qd[13];
        let x336 = x334 + x335;
        let x337 = 2.0 * x336;
        let x338 = q[12] * qd[10];
        let x339 = q[10] * qd[12];
        let x340 = x338 + x339;
        let x341 = 2.0 * x340;
        let x343 = x337 - x341;
        let x345 = x74 * x74;
        let x346 = x103 * x103;
        let x347 = x345 + x346;
        let x348 = x74 * x343;
        let x350 = x103 * x333;
        let x352 = x350 - x348;
        let x353 = 1.0 / x347;
        let x354 = x352 * x353;
        let x365 = 2.0 * x129;
        let x366 = x74 * x131;
        let x367 = x103 * x365;
        let x369 = x366 + x367;
        let x370 = x353 * x369;
        let x371 = 2.0 * x130;
        let x372 = x74 * x132;
        let x374 = x103 * x371;
        let x376 = x374 - x372;
        let x377 = x353 * x376;
        let x378 = x74 * x129;
        let x379 = x353 * x378;
        let x380 = x74 * x130;
        let x382 = x353 * x380;
        let x467 = 2.0 * qd[0];
        let x470 = 2.0 * qd[1];
        let x472 = 2.0 * qd[2];
        let x926 = x130 * x371;
        let x946 = x130 * x365;
        let x962 = x131 * x365;
        let x964 = x132 * x371;
        let x978 = x131 * x371;
        let x980 = x132 * x365;
        let x988 = x129 * x371;
        let x1001 = x129 * x365;
        let x1263 = 2.0 * x325;
        let x1264 = x312 * x312;
        let x1265 = x1263 * x1264;
        let x1267 = x312 * x467;
        let x1268 = x310 * x1265;
        let x1270 = x1267 - x1268;
        let x1277 = 2.0 * x312;
        let x1278 = x303 * x1265;
        let x1280 = x1277 - x1278;
        let x1281 = x305 * x1265;
        let x1283 = x307 * x1265;
        let x1301 = 2.0 * x326;
        let x1302 = x1264 * x1301;
        let x1304 = x312 * x470;
        let x1305 = x310 * x1302;
        let x1307 = x1304 - x1305;
        let x1314 = x303 * x1302;
        let x1316 = x305 * x1302;
        let x1318 = x1277 - x1316;
        let x1319 = x307 * x1302;
        let x1337 = 2.0 * x327;
        let x1338 = x1264 * x1337;
        let x1340 = x312 * x472;
        let x1341 = x310 * x1338;
        let x1343 = x1340 - x1341;
        let x1350 = x303 * x1338;
        let x1352 = x305 * x1338;
        let x1354 = x307 * x1338;
        let x1356 = x1277 - x1354;
        let x1373 = 2.0 * x220;
        let x1374 = 2.0 * x74;
        let x1375 = x365 * x1374;
        let x1376 = 2.0 * x103;
        let x1377 = x131 * x1376;
        let x1379 = x1375 - x1377;
        let x1380 = x343 * x365;
        let x1381 = x74 * x222;
        let x1383 = x1380 - x1381;
        let x1385 = x131 * x333;
        let x1387 = x103 * x1373;
        let x1388 = x1387 - x1385;
        let x1389 = x1388 - x1383;
        let x1390 = x353 * x353;
        let x1391 = x1379 * x1390;
        let x1393 = x353 * x1389;
        let x1394 = x352 * x1391;
        let x1396 = x1393 - x1394;
        let x1404 = 4.0 * x103;
        let x1405 = x1404 - x962;
        let x1406 = x962 + x1405;
        let x1407 = x369 * x1391;
        let x1409 = x353 * x1406;
        let x1410 = x1409 - x1407;
        let x1412 = x978 + x980;
        let x1414 = x376 * x1391;
        let x1416 = x353 * x1412;
        let x1418 = x1414 + x1416;
        let x1420 = x1001 + x1374;
        let x1421 = x378 * x1391;
        let x1423 = x353 * x1420;
        let x1424 = x1423 - x1421;
        let x1425 = x380 * x1391;
        let x1427 = x353 * x946;
        let x1428 = x1427 - x1425;
        let x1447 = x14 * 2.0;
        let x1450 = 2.0 * x221;
        let x1451 = x371 * x1374;
        let x1452 = x132 * x1376;
        let x1453 = x1451 + x1452;
        let x1454 = x343 * x371;
        let x1455 = x74 * x223;
        let x1456 = x1454 + x1455;
        let x1458 = x132 * x333;
        let x1459 = x103 * x1450;
        let x1460 = x1458 + x1459;
        let x1461 = x1460 - x1456;
        let x1462 = x1390 * x1453;
        let x1464 = x353 * x1461;
        let x1465 = x352 * x1462;
        let x1467 = x1464 - x1465;
        let x1474 = x369 * x1462;
        let x1476 = x1416 - x1474;
        let x1477 = x964 + x1404;
        let x1478 = x1477 - x964;
        let x1479 = x376 * x1462;
        let x1481 = x353 * x1478;
        let x1482 = x1481 - x1479;
        let x1483 = x378 * x1462;
        let x1485 = x353 * x988;
        let x1486 = x1485 - x1483;
        let x1487 = x926 + x1374;
        let x1488 = x380 * x1462;
        let x1490 = x353 * x1487;
        let x1491 = x1490 - x1488;
        let x1510 = x129 * x1376;
        let x1512 = x74 * x220;
        let x1514 = x129 * x333;
        let x1516 = x1512 - x1514;
        let x1517 = x1390 * x1510;
        let x1519 = x353 * x1516;
        let x1520 = x352 * x1517;
        let x1521 = x1519 + x1520;
        let x1529 = x1374 - x1001;
        let x1530 = x369 * x1517;
        let x1531 = x353 * x1529;
        let x1532 = x1530 + x1531;
        let x1533 = x376 * x1517;
        let x1535 = x1533 - x1485;
        let x1536 = x378 * x1517;
        let x1537 = x380 * x1517;
        let x1557 = x130 * x1376;
        let x1558 = x74 * x221;
        let x1560 = x130 * x333;
        let x1561 = x1560 - x1558;
        let x1562 = x1390 * x1557;
        let x1564 = x353 * x1561;
        let x1565 = x352 * x1562;
        let x1567 = x1564 - x1565;
        let x1573 = x369 * x1562;
        let x1575 = x1427 - x1573;
        let x1577 = x926 - x1374;
        let x1578 = x376 * x1562;
        let x1580 = x353 * x1577;
        let x1581 = x1580 - x1578;
        let x1582 = x378 * x1562;
        let x1584 = x380 * x1562;
        let x1673 = x314 * k[3];
        let x1674 = x313 * k[0];
        let x1676 = x5 - x1674;
        let x1678 = x1676 - x1673;
        let x1685 = x332 * k[4];
        let x1686 = x354 * k[1];
        let x1688 = x11 - x1686;
        let x1690 = x1688 - x1685;
        let x1875 = x325 * k[3];
        let x1876 = x1270 * k[0];
        let x1877 = x1875 + x1876;
        let x1878 = x325 * x1877;
        let x1880 = x1280 * x1678;
        let x1881 = x1880 - x1878;
        let x1882 = x326 * x1877;
        let x1883 = x1281 * x1678;
        let x1884 = x1882 + x1883;
        let x1885 = -x1884;
        let x1886 = x327 * x1877;
        let x1887 = x1283 * x1678;
        let x1888 = x1886 + x1887;
        let x1889 = -x1888;
        let x1890 = x326 * k[3];
        let x1891 = x1307 * k[0];
        let x1892 = x1890 + x1891;
        let x1893 = x325 * x1892;
        let x1894 = x1314 * x1678;
        let x1895 = x1893 + x1894;
        let x1896 = -x1895;
        let x1897 = x326 * x1892;
        let x1899 = x1318 * x1678;
        let x1900 = x1899 - x1897;
        let x1901 = x327 * x1892;
        let x1902 = x1319 * x1678;
        let x1903 = x1901 + x1902;
        let x1904 = -x1903;
        let x1905 = x327 * k[3];
        let x1906 = x1343 * k[0];
        let x1907 = x1905 + x1906;
        let x1908 = x325 * x1907;
        let x1909 = x1350 * x1678;
        let x1910 = x1908 + x1909;
        let x1911 = -x1910;
        let x1912 = x326 * x1907;
        let x1913 = x1352 * x1678;
        let x1914 = x1912 + x1913;
        let x1915 = -x1914;
        let x1916 = x327 * x1907;
        let x1918 = x1356 * x1678;
        let x1919 = x1918 - x1916;
        let x1920 = x370 * k[4];
        let x1921 = x1396 * k[1];
        let x1922 = x1920 + x1921;
        let x1923 = x370 * x1922;
        let x1925 = x1410 * x1690;
        let x1926 = x1925 - x1923;
        let x1927 = x377 * x1922;
        let x1928 = x1418 * x1690;
        let x1929 = x1927 + x1928;
        let x1930 = -x1929;
        let x1931 = x379 * x1922;
        let x1933 = x1424 * x1690;
        let x1934 = x1933 - x1931;
        let x1935 = x382 * x1922;
        let x1937 = x1428 * x1690;
        let x1938 = x1937 - x1935;
        let x1939 = x1447 + x1934;
        let x1940 = -x1938;
        let x1941 = x377 * k[4];
        let x1942 = x1467 * k[1];
        let x1943 = x1941 + x1942;
        let x1944 = x370 * x1943;
        let x1946 = x1476 * x1690;
        let x1947 = x1946 - x1944;
        let x1948 = x377 * x1943;
        let x1950 = x1482 * x1690;
        let x1951 = x1950 - x1948;
        let x1952 = x379 * x1943;
        let x1954 = x1486 * x1690;
        let x1955 = x1954 - x1952;
        let x1956 = x382 * x1943;
        let x1958 = x1491 * x1690;
        let x1959 = x1958 - x1956;
        let x1960 = x1447 + x1959;
        let x1961 = -x1960;
        let x1962 = x379 * k[4];
        let x1963 = x1521 * k[1];
        let x1964 = x1962 + x1963;
        let x1965 = x370 * x1964;
        let x1967 = x1532 * x1690;
        let x1968 = x1967 - x1965;
        let x1969 = x377 * x1964;
        let x1971 = x1535 * x1690;
        let x1972 = x1971 - x1969;
        let x1973 = x379 * x1964;
        let x1975 = x1536 * x1690;
        let x1976 = x1975 - x1973;
        let x1977 = x382 * x1964;
        let x1979 = x1537 * x1690;
        let x1980 = x1979 - x1977;
        let x1981 = x1968 - x1447;
        let x1982 = -x1980;
        let x1983 = x382 * k[4];
        let x1984 = x1567 * k[1];
        let x1986 = x1983 - x1984;
        let x1987 = x370 * x1986;
        let x1988 = x1575 * x1690;
        let x1989 = x1987 + x1988;
        let x1990 = x377 * x1986;
        let x1991 = x1581 * x1690;
        let x1992 = x1990 + x1991;
        let x1993 = x379 * x1986;
        let x1994 = x1582 * x1690;
        let x1996 = x1993 - x1994;
        let x1997 = x382 * x1986;
        let x1998 = x1584 * x1690;
        let x2000 = x1997 - x1998;
        let x2001 = x1447 + x1992;
        let x2002 = -x2000;
        let x2003 = x325 * k[0];
        let x2004 = x325 * x2003;
        let x2005 = -x2004;
        let x2006 = x326 * x2003;
        let x2007 = -x2006;
        let x2008 = x327 * x2003;
        let x2009 = -x2008;
        let x2010 = x326 * k[0];
        let x2011 = x325 * x2010;
        let x2012 = -x2011;
        let x2013 = x326 * x2010;
        let x2014 = -x2013;
        let x2015 = x327 * x2010;
        let x2016 = -x2015;
        let x2017 = x327 * k[0];
        let x2018 = x325 * x2017;
        let x2019 = -x2018;
        let x2020 = x326 * x2017;
        let x2021 = -x2020;
        let x2022 = x327 * x2017;
        let x2023 = -x2022;
        let x2024 = x370 * k[1];
        let x2025 = x370 * x2024;
        let x2026 = -x2025;
        let x2027 = x377 * x2024;
        let x2028 = -x2027;
        let x2029 = x379 * x2024;
        let x2030 = -x2029;
        let x2031 = x382 * x2024;
        let x2032 = x377 * k[1];
        let x2033 = x370 * x2032;
        let x2034 = -x2033;
        let x2035 = x377 * x2032;
        let x2036 = -x2035;
        let x2037 = x379 * x2032;
        let x2038 = -x2037;
        let x2039 = x382 * x2032;
        let x2040 = x379 * k[1];
        let x2041 = x370 * x2040;
        let x2042 = -x2041;
        let x2043 = x377 * x2040;
        let x2044 = -x2043;
        let x2045 = x379 * x2040;
        let x2046 = -x2045;
        let x2047 = x382 * x2040;
        let x2048 = x382 * k[1];
        let x2049 = x370 * x2048;
        let x2050 = x377 * x2048;
        let x2051 = x379 * x2048;
        let x2052 = x382 * x2048;
        let x2053 = -x2052;
        dq[0] = x1881;
        dq[1] = x1896;
        dq[2] = x1911;
        dq[3] = x1885;
        dq[4] = x1900;
        dq[5] = x1915;
        dq[6] = x1889;
        dq[7] = x1904;
        dq[8] = x1919;
        dq[9] = x1926;
        dq[10] = x1947;
        dq[11] = x1981;
        dq[12] = x1989;
        dq[13] = x1930;
        dq[14] = x1951;
        dq[15] = x1972;
        dq[16] = x2001;
        dq[17] = x1939;
        dq[18] = x1955;
        dq[19] = x1976;
        dq[20] = x1996;
        dq[21] = x1940;
        dq[22] = x1961;
        dq[23] = x1982;
        dq[24] = x2002;
        dqd[0] = x2005;
        dqd[1] = x2012;
        dqd[2] = x2019;
        dqd[3] = x2007;
        dqd[4] = x2014;
        dqd[5] = x2021;
        dqd[6] = x2009;
        dqd[7] = x2016;
        dqd[8] = x2023;
        dqd[9] = x2026;
        dqd[10] = x2034;
        dqd[11] = x2042;
        dqd[12] = x2049;
        dqd[13] = x2028;
        dqd[14] = x2036;
        dqd[15] = x2044;
        dqd[16] = x2050;
        dqd[17] = x2030;
        dqd[18] = x2038;
        dqd[19] = x2046;
        dqd[20] = x2051;
        dqd[21] = x2031;
        dqd[22] = x2039;
        dqd[23] = x2047;
        dqd[24] = x2053;
    }
    /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
    pub fn mass(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 11] = k.try_into().expect("k must have 11 entries");
        let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 38] = out.try_into().expect("out must have 38 entries");
        mass_part_0(k, q, out);
    }
    #[inline(never)]
    fn mass_part_0(k: &[f64; 11], q: &[f64; 14], out: &mut [f64; 38]) {
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
        let x365 = 2.0 * x129;
        let x371 = 2.0 * x130;
        let x541 = 2.0 * x124;
        let x543 = 2.0 * x125;
        let x545 = 2.0 * x126;
        let x547 = x124 * x541;
        let x549 = 0.01 * x547;
        let x551 = x125 * x543;
        let x553 = 0.01 * x551;
        let x555 = x126 * x545;
        let x557 = 0.01 * x555;
        let x559 = x549 + x553;
        let x561 = x557 + x559;
        let x563 = 0.5 * x561;
        let x565 = x23 * 0.04;
        let x566 = x563 + x565;
        let x567 = 2.0 * x123;
        let x568 = x124 * x567;
        let x569 = 0.01 * x568;
        let x570 = x125 * x545;
        let x572 = 0.01 * x570;
        let x574 = x126 * x543;
        let x575 = 0.01 * x574;
        let x576 = x569 - x572;
        let x577 = x575 + x576;
        let x578 = 0.5 * x577;
        let x580 = x52 * 0.04;
        let x581 = x580 - x578;
        let x582 = x124 * x545;
        let x583 = 0.01 * x582;
        let x584 = x125 * x567;
        let x585 = 0.01 * x584;
        let x586 = x126 * x541;
        let x588 = 0.01 * x586;
        let x590 = x583 + x585;
        let x591 = x590 - x588;
        let x592 = 0.5 * x591;
        let x594 = x46 * 0.04;
        let x595 = x594 - x592;
        let x596 = x124 * x543;
        let x598 = 0.01 * x596;
        let x600 = x125 * x541;
        let x601 = 0.01 * x600;
        let x602 = x126 * x567;
        let x603 = 0.01 * x602;
        let x604 = x601 - x598;
        let x605 = x603 + x604;
        let x606 = 0.5 * x605;
        let x608 = x39 * 0.04;
        let x609 = x608 - x606;
        let x610 = x123 * x541;
        let x612 = 0.01 * x610;
        let x616 = x575 - x612;
        let x617 = x616 - x572;
        let x618 = 0.5 * x617;
        let x619 = x580 + x618;
        let x620 = x123 * x567;
        let x621 = 0.01 * x620;
        let x622 = x557 + x621;
        let x623 = x553 + x622;
        let x624 = 0.5 * x623;
        let x625 = x24 * 0.04;
        let x626 = x624 + x625;
        let x627 = x123 * x545;
        let x628 = 0.01 * x627;
        let x632 = x628 - x603;
        let x633 = x632 - x601;
        let x634 = 0.5 * x633;
        let x635 = x37 * 0.04;
        let x636 = x634 + x635;
        let x637 = x123 * x543;
        let x639 = 0.01 * x637;
        let x641 = x588 + x639;
        let x643 = x585 - x641;
        let x644 = 0.5 * x643;
        let x645 = x44 * 0.04;
        let x646 = x644 + x645;
        let x649 = x583 - x641;
        let x650 = 0.5 * x649;
        let x651 = x594 + x650;
        let x654 = x603 - x628;
        let x655 = x654 - x598;
        let x656 = 0.5 * x655;
        let x657 = x635 + x656;
        let x658 = x549 + x622;
        let x659 = 0.5 * x658;
        let x660 = x25 * 0.04;
        let x661 = x659 + x660;
        let x663 = x612 - x575;
        let x664 = x663 - x569;
        let x665 = 0.5 * x664;
        let x666 = x50 * 0.04;
        let x667 = x665 + x666;
        let x668 = x604 - x628;
        let x669 = 0.5 * x668;
        let x670 = x608 + x669;
        let x673 = x639 - x590;
        let x674 = 0.5 * x673;
        let x675 = x645 + x674;
        let x676 = x576 - x612;
        let x677 = 0.5 * x676;
        let x678 = x666 + x677;
        let x679 = x559 + x621;
        let x680 = 0.5 * x679;
        let x681 = x26 * 0.04;
        let x682 = x680 + x681;
        let x922 = 2.0 * x131;
        let x924 = 2.0 * x132;
        let x926 = x130 * x371;
        let x928 = 0.1 * x926;
        let x930 = x131 * x922;
        let x934 = x132 * x924;
        let x936 = 0.3 * x934;
        let x946 = x130 * x365;
        let x947 = 0.1 * x946;
        let x948 = x131 * x924;
        let x952 = x132 * x922;
        let x953 = 0.3 * x952;
        let x960 = x130 * x924;
        let x961 = 0.1 * x960;
        let x962 = x131 * x365;
        let x964 = x132 * x371;
        let x966 = 0.3 * x964;
        let x974 = x130 * x922;
        let x976 = 0.1 * x974;
        let x978 = x131 * x371;
        let x980 = x132 * x365;
        let x981 = 0.3 * x980;
        let x988 = x129 * x371;
        let x990 = 0.1 * x988;
        let x995 = 0.3 * x948;
        let x1001 = x129 * x365;
        let x1002 = 0.1 * x1001;
        let x1005 = 0.3 * x930;
        let x1011 = x129 * x924;
        let x1012 = 0.1 * x1011;
        let x1016 = 0.3 * x978;
        let x1023 = x129 * x922;
        let x1025 = 0.1 * x1023;
        let x1029 = 0.3 * x962;
        let x1036 = 0.1 * x964;
        let x1041 = 0.3 * x960;
        let x1048 = 0.1 * x980;
        let x1052 = 0.3 * x974;
        let x1058 = 0.1 * x934;
        let x1060 = 0.3 * x926;
        let x1067 = 0.1 * x952;
        let x1070 = 0.3 * x946;
        let x1077 = 0.1 * x978;
        let x1081 = 0.3 * x1011;
        let x1087 = 0.1 * x962;
        let x1091 = 0.3 * x1023;
        let x1097 = 0.1 * x948;
        let x1100 = 0.3 * x988;
        let x1106 = 0.1 * x930;
        let x1109 = 0.3 * x1001;
        let x1713 = x930 * k[2];
        let x1714 = x928 + x1713;
        let x1715 = x936 + x1714;
        let x1716 = 0.5 * x1715;
        let x1717 = x68 * k[10];
        let x1718 = x1716 + x1717;
        let x1719 = x948 * k[2];
        let x1721 = x947 - x1719;
        let x1722 = x953 + x1721;
        let x1723 = 0.5 * x1722;
        let x1725 = x96 * k[10];
        let x1726 = x1725 - x1723;
        let x1727 = x962 * k[2];
        let x1728 = x961 + x1727;
        let x1729 = x1728 - x966;
        let x1730 = 0.5 * x1729;
        let x1732 = x90 * k[10];
        let x1733 = x1732 - x1730;
        let x1734 = x978 * k[2];
        let x1735 = x1734 - x976;
        let x1736 = x981 + x1735;
        let x1737 = 0.5 * x1736;
        let x1739 = x83 * k[10];
        let x1740 = x1739 - x1737;
        let x1741 = x952 * k[2];
        let x1742 = x1741 - x990;
        let x1743 = x1742 - x995;
        let x1744 = 0.5 * x1743;
        let x1745 = x1725 + x1744;
        let x1746 = x934 * k[2];
        let x1747 = x1002 + x1746;
        let x1748 = x1005 + x1747;
        let x1749 = 0.5 * x1748;
        let x1750 = x69 * k[10];
        let x1751 = x1749 + x1750;
        let x1752 = x980 * k[2];
        let x1754 = x1012 - x1752;
        let x1755 = x1754 - x1016;
        let x1756 = 0.5 * x1755;
        let x1757 = x81 * k[10];
        let x1758 = x1756 + x1757;
        let x1759 = x964 * k[2];
        let x1760 = x1025 + x1759;
        let x1762 = x1029 - x1760;
        let x1763 = 0.5 * x1762;
        let x1764 = x88 * k[10];
        let x1765 = x1763 + x1764;
        let x1766 = x1023 * k[2];
        let x1767 = x1036 + x1766;
        let x1769 = x1041 - x1767;
        let x1770 = 0.5 * x1769;
        let x1771 = x1732 + x1770;
        let x1772 = x1011 * k[2];
        let x1774 = x1048 - x1772;
        let x1775 = x1774 - x1052;
        let x1776 = 0.5 * x1775;
        let x1777 = x1757 + x1776;
        let x1778 = x1001 * k[2];
        let x1779 = x1058 + x1778;
        let x1780 = x1060 + x1779;
        let x1781 = 0.5 * x1780;
        let x1782 = x70 * k[10];
        let x1783 = x1781 + x1782;
        let x1784 = x988 * k[2];
        let x1785 = x1784 - x1067;
        let x1786 = x1785 - x1070;
        let x1787 = 0.5 * x1786;
        let x1788 = x94 * k[10];
        let x1789 = x1787 + x1788;
        let x1790 = x974 * k[2];
        let x1792 = x1077 - x1790;
        let x1793 = x1792 - x1081;
        let x1794 = 0.5 * x1793;
        let x1795 = x1739 + x1794;
        let x1796 = x960 * k[2];
        let x1797 = x1087 + x1796;
        let x1799 = x1091 - x1797;
        let x1800 = 0.5 * x1799;
        let x1801 = x1764 + x1800;
        let x1802 = x946 * k[2];
        let x1803 = x1802 - x1097;
        let x1804 = x1803 - x1100;
        let x1805 = 0.5 * x1804;
        let x1806 = x1788 + x1805;
        let x1807 = x926 * k[2];
        let x1808 = x1106 + x1807;
        let x1809 = x1109 + x1808;
        let x1810 = 0.5 * x1809;
        let x1811 = x71 * k[10];
        let x1812 = x1810 + x1811;
        out[0] = k[9];
        out[1] = k[9];
        out[2] = k[9];
        out[3] = x566;
        out[4] = x581;
        out[5] = x595;
        out[6] = x609;
        out[7] = x619;
        out[8] = x626;
        out[9] = x636;
        out[10] = x646;
        out[11] = x651;
        out[12] = x657;
        out[13] = x661;
        out[14] = x667;
        out[15] = x670;
        out[16] = x675;
        out[17] = x678;
        out[18] = x682;
        out[19] = 1.0;
        out[20] = 1.0;
        out[21] = 1.0;
        out[22] = x1718;
        out[23] = x1726;
        out[24] = x1733;
        out[25] = x1740;
        out[26] = x1745;
        out[27] = x1751;
        out[28] = x1758;
        out[29] = x1765;
        out[30] = x1771;
        out[31] = x1777;
        out[32] = x1783;
        out[33] = x1789;
        out[34] = x1795;
        out[35] = x1801;
        out[36] = x1806;
        out[37] = x1812;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 11] = k.try_into().expect("k must have 11 entries");
        let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 14] = out.try_into().expect("out must have 14 entries");
        force_part_0(k, q, qd, t, out);
    }
    #[inline(never)]
    fn force_part_0(
        k: &[f64; 11],
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
        let x296 = 1.0 + q[0];
        let x297 = x296 * x296;
        let x298 = q[1] * q[1];
        let x299 = q[2] * q[2];
        let x300 = x297 + x298;
        let x301 = x299 + x300;
        let x302 = x301.sqrt();
        let x303 = 2.0 * x296;
        let x304 = qd[0] * x303;
        let x305 = q[1] * 2.0;
        let x306 = qd[1] * x305;
        let x307 = q[2] * 2.0;
        let x308 = qd[2] * x307;
        let x309 = x304 + x306;
        let x310 = x308 + x309;
        let x311 = 2.0 * x302;
        let x312 = 1.0 / x311;
        let x313 = x310 * x312;
        let x314 = x302 - 1.0;
        let x325 = x303 * x312;
        let x326 = x305 * x312;
        let x327 = x307 * x312;
        let x331 = -x103;
        let x332 = x331.atan2(x74);
        let x333 = 2.0 * x188;
        let x334 = q[13] * qd[11];
        let x335 = q[11] * qd[13];
        let x336 = x334 + x335;
        let x337 = 2.0 * x336;
        let x338 = q[12] * qd[10];
        let x339 = q[10] * qd[12];
        let x340 = x338 + x339;
        let x341 = 2.0 * x340;
        let x343 = x337 - x341;
        let x345 = x74 * x74;
        let x346 = x103 * x103;
        let x347 = x345 + x346;
        let x348 = x74 * x343;
        let x350 = x103 * x333;
        let x352 = x350 - x348;
        let x353 = 1.0 / x347;
        let x354 = x352 * x353;
        let x365 = 2.0 * x129;
        let x366 = x74 * x131;
        let x367 = x103 * x365;
        let x369 = x366 + x367;
        let x370 = x353 * x369;
        let x371 = 2.0 * x130;
        let x372 = x74 * x132;
        let x374 = x103 * x371;
        let x376 = x374 - x372;
        let x377 = x353 * x376;
        let x378 = x74 * x129;
        let x379 = x353 * x378;
        let x380 = x74 * x130;
        let x382 = x353 * x380;
        let x391 = x204 - x203;
        let x412 = x14 * x131;
        let x414 = x14 * x132;
        let x415 = x14 * x129;
        let x416 = x14 * x130;
        let x432 = x178 - x177;
        let x433 = x173 + x432;
        let x434 = x433 - x174;
        let x435 = 2.0 * x434;
        let x438 = x164 + x168;
        let x440 = x169 - x438;
        let x441 = x165 + x440;
        let x442 = 2.0 * x441;
        let x445 = x156 - x160;
        let x446 = x445 - x157;
        let x447 = x161 + x446;
        let x448 = 2.0 * x447;
        let x469 = 2.0 * x435;
        let x471 = 2.0 * x442;
        let x473 = 2.0 * x448;
        let x685 = x235 + x238;
        let x687 = x238 - x685;
        let x688 = x235 + x687;
        let x689 = 2.0 * x688;
        let x692 = x229 - x232;
        let x693 = x692 - x229;
        let x694 = x232 + x693;
        let x695 = 2.0 * x694;
        let x696 = 2.0 * x689;
        let x697 = 2.0 * x695;
        let x698 = x217 * x469;
        let x699 = 0.01 * x698;
        let x700 = x218 * x471;
        let x701 = x125 * x696;
        let x702 = x700 + x701;
        let x703 = 0.01 * x702;
        let x704 = x219 * x473;
        let x705 = x126 * x697;
        let x706 = x704 + x705;
        let x707 = 0.01 * x706;
        let x708 = x699 + x703;
        let x709 = x707 + x708;
        let x710 = 0.5 * x709;
        let x712 = x216 * x469;
        let x713 = 0.01 * x712;
        let x714 = x219 * x471;
        let x715 = x126 * x696;
        let x716 = x714 + x715;
        let x717 = 0.01 * x716;
        let x719 = x218 * x473;
        let x720 = x125 * x697;
        let x721 = x719 + x720;
        let x722 = 0.01 * x721;
        let x723 = x713 - x717;
        let x724 = x722 + x723;
        let x725 = 0.5 * x724;
        let x726 = x219 * x469;
        let x727 = 0.01 * x726;
        let x728 = x216 * x471;
        let x729 = x123 * x696;
        let x730 = x728 + x729;
        let x731 = 0.01 * x730;
        let x732 = x217 * x473;
        let x733 = x124 * x697;
        let x734 = x732 + x733;
        let x735 = 0.01 * x734;
        let x737 = x727 + x731;
        let x738 = x737 - x735;
        let x739 = 0.5 * x738;
        let x740 = x218 * x469;
        let x741 = 0.01 * x740;
        let x743 = x217 * x471;
        let x744 = x124 * x696;
        let x745 = x743 + x744;
        let x746 = 0.01 * x745;
        let x747 = x216 * x473;
        let x748 = x123 * x697;
        let x749 = x747 + x748;
        let x750 = 0.01 * x749;
        let x751 = x746 - x741;
        let x752 = x750 + x751;
        let x753 = 0.5 * x752;
        let x754 = qd[3] * qd[3];
        let x755 = qd[4] * qd[4];
        let x756 = qd[5] * qd[5];
        let x757 = qd[6] * qd[6];
        let x758 = x754 + x755;
        let x759 = x756 + x758;
        let x760 = x757 + x759;
        let x761 = 0.01 * x700;
        let x762 = 0.01 * x704;
        let x763 = x699 + x761;
        let x764 = x762 + x763;
        let x765 = 0.5 * x764;
        let x766 = x710 + x765;
        let x767 = q[3] * 0.04;
        let x768 = x760 * x767;
        let x770 = x766 - x768;
        let x777 = 0.01 * x714;
        let x779 = 0.01 * x719;
        let x781 = x777 - x713;
        let x782 = x781 - x779;
        let x783 = 0.5 * x782;
        let x785 = x783 - x725;
        let x786 = q[4] * 0.04;
        let x787 = x760 * x786;
        let x789 = x785 - x787;
        let x795 = 0.01 * x728;
        let x797 = 0.01 * x732;
        let x798 = x727 + x795;
        let x800 = x797 - x798;
        let x801 = 0.5 * x800;
        let x803 = x801 - x739;
        let x804 = q[5] * 0.04;
        let x805 = x760 * x804;
        let x807 = x803 - x805;
        let x811 = 0.01 * x743;
        let x814 = 0.01 * x747;
        let x816 = x741 - x811;
        let x817 = x816 - x814;
        let x818 = 0.5 * x817;
        let x820 = x818 - x753;
        let x821 = q[6] * 0.04;
        let x822 = x760 * x821;
        let x824 = x820 - x822;
        let x827 = x199 + x391;
        let x828 = x827 - x200;
        let x829 = 2.0 * x828;
        let x831 = x334 + x338;
        let x833 = x339 - x831;
        let x834 = x335 + x833;
        let x835 = 2.0 * x834;
        let x837 = x189 - x193;
        let x838 = x837 - x190;
        let x839 = x194 + x838;
        let x840 = 2.0 * x839;
        let x857 = 2.0 * x829;
        let x859 = 2.0 * x835;
        let x861 = 2.0 * x840;
        let x1115 = qd[11] * qd[13];
        let x1116 = qd[10] * qd[12];
        let x1120 = x1115 + x1116;
        let x1122 = x1116 - x1120;
        let x1123 = x1115 + x1122;
        let x1124 = 2.0 * x1123;
        let x1126 = x256 - x259;
        let x1127 = x1126 - x256;
        let x1128 = x259 + x1127;
        let x1129 = 2.0 * x1128;
        let x1130 = 2.0 * x1124;
        let x1131 = 2.0 * x1129;
        let x1132 = x221 * x857;
        let x1133 = 0.1 * x1132;
        let x1134 = x222 * x859;
        let x1135 = x131 * x1130;
        let x1136 = x1134 + x1135;
        let x1138 = x223 * x861;
        let x1139 = x132 * x1131;
        let x1140 = x1138 + x1139;
        let x1141 = 0.3 * x1140;
        let x1146 = x220 * x857;
        let x1147 = 0.1 * x1146;
        let x1148 = x223 * x859;
        let x1149 = x132 * x1130;
        let x1150 = x1148 + x1149;
        let x1153 = x222 * x861;
        let x1154 = x131 * x1131;
        let x1155 = x1153 + x1154;
        let x1156 = 0.3 * x1155;
        let x1160 = x223 * x857;
        let x1161 = 0.1 * x1160;
        let x1162 = x220 * x859;
        let x1163 = x129 * x1130;
        let x1164 = x1162 + x1163;
        let x1166 = x221 * x861;
        let x1167 = x130 * x1131;
        let x1168 = x1166 + x1167;
        let x1169 = 0.3 * x1168;
        let x1174 = x222 * x857;
        let x1175 = 0.1 * x1174;
        let x1177 = x221 * x859;
        let x1178 = x130 * x1130;
        let x1179 = x1177 + x1178;
        let x1181 = x220 * x861;
        let x1182 = x129 * x1131;
        let x1183 = x1181 + x1182;
        let x1184 = 0.3 * x1183;
        let x1188 = qd[10] * qd[10];
        let x1189 = qd[11] * qd[11];
        let x1190 = qd[12] * qd[12];
        let x1191 = qd[13] * qd[13];
        let x1192 = x1188 + x1189;
        let x1193 = x1190 + x1192;
        let x1194 = x1191 + x1193;
        let x1196 = 0.3 * x1138;
        let x1213 = 0.3 * x1153;
        let x1231 = 0.3 * x1166;
        let x1248 = 0.3 * x1181;
        let x1673 = x314 * k[3];
        let x1674 = x313 * k[0];
        let x1676 = x5 - x1674;
        let x1678 = x1676 - x1673;
        let x1682 = x325 * x1678;
        let x1683 = x326 * x1678;
        let x1684 = x327 * x1678;
        let x1685 = x332 * k[4];
        let x1686 = x354 * k[1];
        let x1688 = x11 - x1686;
        let x1690 = x1688 - x1685;
        let x1694 = x370 * x1690;
        let x1695 = x377 * x1690;
        let x1696 = x379 * x1690;
        let x1697 = x382 * x1690;
        let x1698 = 1.0 + x1682;
        let x1699 = x1694 - x412;
        let x1700 = x414 + x1695;
        let x1701 = x415 + x1696;
        let x1702 = x416 + x1697;
        let x1711 = k[6] + x1683;
        let x1813 = x1136 * k[2];
        let x1814 = x1133 + x1813;
        let x1815 = x1141 + x1814;
        let x1816 = 0.5 * x1815;
        let x1817 = x1150 * k[2];
        let x1819 = x1147 - x1817;
        let x1820 = x1156 + x1819;
        let x1821 = 0.5 * x1820;
        let x1822 = x1164 * k[2];
        let x1823 = x1161 + x1822;
        let x1824 = x1823 - x1169;
        let x1825 = 0.5 * x1824;
        let x1826 = x1179 * k[2];
        let x1827 = x1826 - x1175;
        let x1828 = x1184 + x1827;
        let x1829 = 0.5 * x1828;
        let x1830 = x1134 * k[2];
        let x1831 = x1133 + x1830;
        let x1832 = x1196 + x1831;
        let x1833 = 0.5 * x1832;
        let x1834 = x1816 + x1833;
        let x1835 = q[10] * k[10];
        let x1836 = x1194 * x1835;
        let x1838 = x1834 - x1836;
        let x1839 = x1148 * k[2];
        let x1840 = x1839 - x1147;
        let x1841 = x1840 - x1213;
        let x1842 = 0.5 * x1841;
        let x1844 = x1842 - x1821;
        let x1845 = q[11] * k[10];
        let x1846 = x1194 * x1845;
        let x1848 = x1844 - x1846;
        let x1849 = x1162 * k[2];
        let x1850 = x1161 + x1849;
        let x1852 = x1231 - x1850;
        let x1853 = 0.5 * x1852;
        let x1855 = x1853 - x1825;
        let x1856 = q[12] * k[10];
        let x1857 = x1194 * x1856;
        let x1859 = x1855 - x1857;
        let x1860 = x1177 * k[2];
        let x1862 = x1175 - x1860;
        let x1863 = x1862 - x1248;
        let x1864 = 0.5 * x1863;
        let x1866 = x1864 - x1829;
        let x1867 = q[13] * k[10];
        let x1868 = x1194 * x1867;
        let x1870 = x1866 - x1868;
        let x1871 = x1699 + x1838;
        let x1872 = x1700 + x1848;
        let x1873 = x1701 + x1859;
        let x1874 = x1870 - x1702;
        out[0] = x1698;
        out[1] = x1711;
        out[2] = x1684;
        out[3] = x770;
        out[4] = x789;
        out[5] = x807;
        out[6] = x824;
        out[7] = 0.0;
        out[8] = -9.81;
        out[9] = 0.0;
        out[10] = x1871;
        out[11] = x1872;
        out[12] = x1873;
        out[13] = x1874;
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
        let k: &[f64; 11] = k.try_into().expect("k must have 11 entries");
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
        k: &[f64; 11],
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
        let x331 = -x103;
        s[35] = x331;
        let x332 = x331.atan2(x74);
        s[36] = x332;
        let x333 = 2.0 * x188;
        s[37] = x333;
        let x334 = q[13] * qd[11];
        s[38] = x334;
        let x335 = q[11] * qd[13];
        s[39] = x335;
        let x336 = x334 + x335;
        s[40] = x336;
        let x337 = 2.0 * x336;
        s[41] = x337;
        let x338 = q[12] * qd[10];
        s[42] = x338;
        let x339 = q[10] * qd[12];
        s[43] = x339;
        let x340 = x338 + x339;
        s[44] = x340;
        let x341 = 2.0 * x340;
        s[45] = x341;
        let x343 = x337 - x341;
        s[46] = x343;
        let x345 = x74 * x74;
        s[47] = x345;
        let x346 = x103 * x103;
        s[48] = x346;
        let x347 = x345 + x346;
        s[49] = x347;
        let x348 = x74 * x343;
        s[50] = x348;
        let x350 = x103 * x333;
        s[51] = x350;
        let x352 = x350 - x348;
        s[52] = x352;
        let x353 = 1.0 / x347;
        s[53] = x353;
        let x354 = x352 * x353;
        s[54] = x354;
        let x371 = 2.0 * x130;
        s[55] = x371;
        let x391 = x204 - x203;
        s[56] = x391;
        let x827 = x199 + x391;
        s[57] = x827;
        let x828 = x827 - x200;
        s[58] = x828;
        let x829 = 2.0 * x828;
        s[59] = x829;
        let x831 = x334 + x338;
        s[60] = x831;
        let x833 = x339 - x831;
        s[61] = x833;
        let x834 = x335 + x833;
        s[62] = x834;
        let x835 = 2.0 * x834;
        s[63] = x835;
        let x837 = x189 - x193;
        s[64] = x837;
        let x838 = x837 - x190;
        s[65] = x838;
        let x839 = x194 + x838;
        s[66] = x839;
        let x840 = 2.0 * x839;
        s[67] = x840;
        let x857 = 2.0 * x829;
        s[68] = x857;
        let x859 = 2.0 * x835;
        s[69] = x859;
        let x861 = 2.0 * x840;
        s[70] = x861;
        let x1115 = qd[11] * qd[13];
        s[71] = x1115;
        let x1116 = qd[10] * qd[12];
        s[72] = x1116;
        let x1120 = x1115 + x1116;
        s[73] = x1120;
        let x1122 = x1116 - x1120;
        s[74] = x1122;
        let x1123 = x1115 + x1122;
        s[75] = x1123;
        let x1124 = 2.0 * x1123;
        s[76] = x1124;
        let x1126 = x256 - x259;
        s[77] = x1126;
        let x1127 = x1126 - x256;
        s[78] = x1127;
        let x1128 = x259 + x1127;
        s[79] = x1128;
        let x1129 = 2.0 * x1128;
        s[80] = x1129;
        let x1130 = 2.0 * x1124;
        s[81] = x1130;
        let x1131 = 2.0 * x1129;
        s[82] = x1131;
        let x1188 = qd[10] * qd[10];
        s[83] = x1188;
        let x1189 = qd[11] * qd[11];
        s[84] = x1189;
        let x1190 = qd[12] * qd[12];
        s[85] = x1190;
        let x1191 = qd[13] * qd[13];
        s[86] = x1191;
        let x1192 = x1188 + x1189;
        s[87] = x1192;
        let x1193 = x1190 + x1192;
        s[88] = x1193;
        let x1194 = x1191 + x1193;
        s[89] = x1194;
        let x1685 = x332 * k[4];
        s[90] = x1685;
        let x1686 = x354 * k[1];
        s[91] = x1686;
        let x1688 = x11 - x1686;
        s[92] = x1688;
        let x1690 = x1688 - x1685;
        s[93] = x1690;
    }
    #[inline(never)]
    fn eval_newton_part_0(
        k: &[f64; 11],
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
        let x296 = 1.0 + q[0];
        let x297 = x296 * x296;
        let x298 = q[1] * q[1];
        let x299 = q[2] * q[2];
        let x300 = x297 + x298;
        let x301 = x299 + x300;
        let x302 = x301.sqrt();
        let x303 = 2.0 * x296;
        let x304 = qd[0] * x303;
        let x305 = q[1] * 2.0;
        let x306 = qd[1] * x305;
        let x307 = q[2] * 2.0;
        let x308 = qd[2] * x307;
        let x309 = x304 + x306;
        let x310 = x308 + x309;
        let x311 = 2.0 * x302;
        let x312 = 1.0 / x311;
        let x313 = x310 * x312;
        let x314 = x302 - 1.0;
        let x325 = x303 * x312;
        let x326 = x305 * x312;
        let x327 = x307 * x312;
        let x365 = 2.0 * s[15];
        let x366 = s[9] * s[17];
        let x367 = s[14] * x365;
        let x369 = x366 + x367;
        let x370 = s[53] * x369;
        let x412 = s[4] * s[17];
        let x432 = x178 - x177;
        let x433 = x173 + x432;
        let x434 = x433 - x174;
        let x435 = 2.0 * x434;
        let x438 = x164 + x168;
        let x440 = x169 - x438;
        let x441 = x165 + x440;
        let x442 = 2.0 * x441;
        let x445 = x156 - x160;
        let x446 = x445 - x157;
        let x447 = x161 + x446;
        let x448 = 2.0 * x447;
        let x469 = 2.0 * x435;
        let x471 = 2.0 * x442;
        let x473 = 2.0 * x448;
        let x541 = 2.0 * x124;
        let x543 = 2.0 * x125;
        let x545 = 2.0 * x126;
        let x547 = x124 * x541;
        let x549 = 0.01 * x547;
        let x551 = x125 * x543;
        let x553 = 0.01 * x551;
        let x555 = x126 * x545;
        let x557 = 0.01 * x555;
        let x559 = x549 + x553;
        let x561 = x557 + x559;
        let x563 = 0.5 * x561;
        let x565 = x23 * 0.04;
        let x566 = x563 + x565;
        let x567 = 2.0 * x123;
        let x568 = x124 * x567;
        let x569 = 0.01 * x568;
        let x570 = x125 * x545;
        let x572 = 0.01 * x570;
        let x574 = x126 * x543;
        let x575 = 0.01 * x574;
        let x576 = x569 - x572;
        let x577 = x575 + x576;
        let x578 = 0.5 * x577;
        let x580 = x52 * 0.04;
        let x581 = x580 - x578;
        let x582 = x124 * x545;
        let x583 = 0.01 * x582;
        let x584 = x125 * x567;
        let x585 = 0.01 * x584;
        let x586 = x126 * x541;
        let x588 = 0.01 * x586;
        let x590 = x583 + x585;
        let x591 = x590 - x588;
        let x592 = 0.5 * x591;
        let x594 = x46 * 0.04;
        let x595 = x594 - x592;
        let x596 = x124 * x543;
        let x598 = 0.01 * x596;
        let x600 = x125 * x541;
        let x601 = 0.01 * x600;
        let x602 = x126 * x567;
        let x603 = 0.01 * x602;
        let x604 = x601 - x598;
        let x605 = x603 + x604;
        let x606 = 0.5 * x605;
        let x608 = x39 * 0.04;
        let x609 = x608 - x606;
        let x610 = x123 * x541;
        let x612 = 0.01 * x610;
        let x616 = x575 - x612;
        let x617 = x616 - x572;
        let x618 = 0.5 * x617;
        let x619 = x580 + x618;
        let x620 = x123 * x567;
        let x621 = 0.01 * x620;
        let x622 = x557 + x621;
        let x623 = x553 + x622;
        let x624 = 0.5 * x623;
        let x625 = x24 * 0.04;
        let x626 = x624 + x625;
        let x627 = x123 * x545;
        let x628 = 0.01 * x627;
        let x632 = x628 - x603;
        let x633 = x632 - x601;
        let x634 = 0.5 * x633;
        let x635 = x37 * 0.04;
        let x636 = x634 + x635;
        let x637 = x123 * x543;
        let x639 = 0.01 * x637;
        let x641 = x588 + x639;
        let x643 = x585 - x641;
        let x644 = 0.5 * x643;
        let x645 = x44 * 0.04;
        let x646 = x644 + x645;
        let x649 = x583 - x641;
        let x650 = 0.5 * x649;
        let x651 = x594 + x650;
        let x654 = x603 - x628;
        let x655 = x654 - x598;
        let x656 = 0.5 * x655;
        let x657 = x635 + x656;
        let x658 = x549 + x622;
        let x659 = 0.5 * x658;
        let x660 = x25 * 0.04;
        let x661 = x659 + x660;
        let x663 = x612 - x575;
        let x664 = x663 - x569;
        let x665 = 0.5 * x664;
        let x666 = x50 * 0.04;
        let x667 = x665 + x666;
        let x668 = x604 - x628;
        let x669 = 0.5 * x668;
        let x670 = x608 + x669;
        let x673 = x639 - x590;
        let x674 = 0.5 * x673;
        let x675 = x645 + x674;
        let x676 = x576 - x612;
        let x677 = 0.5 * x676;
        let x678 = x666 + x677;
        let x679 = x559 + x621;
        let x680 = 0.5 * x679;
        let x681 = x26 * 0.04;
        let x682 = x680 + x681;
        let x685 = x235 + x238;
        let x687 = x238 - x685;
        let x688 = x235 + x687;
        let x689 = 2.0 * x688;
        let x692 = x229 - x232;
        let x693 = x692 - x229;
        let x694 = x232 + x693;
        let x695 = 2.0 * x694;
        let x696 = 2.0 * x689;
        let x697 = 2.0 * x695;
        let x698 = x217 * x469;
        let x699 = 0.01 * x698;
        let x700 = x218 * x471;
        let x701 = x125 * x696;
        let x702 = x700 + x701;
        let x703 = 0.01 * x702;
        let x704 = x219 * x473;
        let x705 = x126 * x697;
        let x706 = x704 + x705;
        let x707 = 0.01 * x706;
        let x708 = x699 + x703;
        let x709 = x707 + x708;
        let x710 = 0.5 * x709;
        let x712 = x216 * x469;
        let x713 = 0.01 * x712;
        let x714 = x219 * x471;
        let x715 = x126 * x696;
        let x716 = x714 + x715;
        let x717 = 0.01 * x716;
        let x719 = x218 * x473;
        let x720 = x125 * x697;
        let x721 = x719 + x720;
        let x722 = 0.01 * x721;
        let x723 = x713 - x717;
        let x724 = x722 + x723;
        let x725 = 0.5 * x724;
        let x726 = x219 * x469;
        let x727 = 0.01 * x726;
        let x728 = x216 * x471;
        let x729 = x123 * x696;
        let x730 = x728 + x729;
        let x731 = 0.01 * x730;
        let x732 = x217 * x473;
        let x733 = x124 * x697;
        let x734 = x732 + x733;
        let x735 = 0.01 * x734;
        let x737 = x727 + x731;
        let x738 = x737 - x735;
        let x739 = 0.5 * x738;
        let x740 = x218 * x469;
        let x741 = 0.01 * x740;
        let x743 = x217 * x471;
        let x744 = x124 * x696;
        let x745 = x743 + x744;
        let x746 = 0.01 * x745;
        let x747 = x216 * x473;
        let x748 = x123 * x697;
        let x749 = x747 + x748;
        let x750 = 0.01 * x749;
        let x751 = x746 - x741;
        let x752 = x750 + x751;
        let x753 = 0.5 * x752;
        let x754 = qd[3] * qd[3];
        let x755 = qd[4] * qd[4];
        let x756 = qd[5] * qd[5];
        let x757 = qd[6] * qd[6];
        let x758 = x754 + x755;
        let x759 = x756 + x758;
        let x760 = x757 + x759;
        let x761 = 0.01 * x700;
        let x762 = 0.01 * x704;
        let x763 = x699 + x761;
        let x764 = x762 + x763;
        let x765 = 0.5 * x764;
        let x766 = x710 + x765;
        let x767 = q[3] * 0.04;
        let x768 = x760 * x767;
        let x770 = x766 - x768;
        let x777 = 0.01 * x714;
        let x779 = 0.01 * x719;
        let x781 = x777 - x713;
        let x782 = x781 - x779;
        let x783 = 0.5 * x782;
        let x785 = x783 - x725;
        let x786 = q[4] * 0.04;
        let x787 = x760 * x786;
        let x789 = x785 - x787;
        let x795 = 0.01 * x728;
        let x797 = 0.01 * x732;
        let x798 = x727 + x795;
        let x800 = x797 - x798;
        let x801 = 0.5 * x800;
        let x803 = x801 - x739;
        let x804 = q[5] * 0.04;
        let x805 = x760 * x804;
        let x807 = x803 - x805;
        let x811 = 0.01 * x743;
        let x814 = 0.01 * x747;
        let x816 = x741 - x811;
        let x817 = x816 - x814;
        let x818 = 0.5 * x817;
        let x820 = x818 - x753;
        let x821 = q[6] * 0.04;
        let x822 = x760 * x821;
        let x824 = x820 - x822;
        let x922 = 2.0 * s[17];
        let x924 = 2.0 * s[18];
        let x926 = s[16] * s[55];
        let x928 = 0.1 * x926;
        let x930 = s[17] * x922;
        let x934 = s[18] * x924;
        let x936 = 0.3 * x934;
        let x946 = s[16] * x365;
        let x947 = 0.1 * x946;
        let x948 = s[17] * x924;
        let x952 = s[18] * x922;
        let x953 = 0.3 * x952;
        let x960 = s[16] * x924;
        let x961 = 0.1 * x960;
        let x962 = s[17] * x365;
        let x964 = s[18] * s[55];
        let x966 = 0.3 * x964;
        let x974 = s[16] * x922;
        let x976 = 0.1 * x974;
        let x978 = s[17] * s[55];
        let x980 = s[18] * x365;
        let x981 = 0.3 * x980;
        let x988 = s[15] * s[55];
        let x990 = 0.1 * x988;
        let x995 = 0.3 * x948;
        let x1001 = s[15] * x365;
        let x1002 = 0.1 * x1001;
        let x1005 = 0.3 * x930;
        let x1011 = s[15] * x924;
        let x1012 = 0.1 * x1011;
        let x1016 = 0.3 * x978;
        let x1023 = s[15] * x922;
        let x1025 = 0.1 * x1023;
        let x1029 = 0.3 * x962;
        let x1036 = 0.1 * x964;
        let x1041 = 0.3 * x960;
        let x1048 = 0.1 * x980;
        let x1052 = 0.3 * x974;
        let x1058 = 0.1 * x934;
        let x1060 = 0.3 * x926;
        let x1067 = 0.1 * x952;
        let x1070 = 0.3 * x946;
        let x1077 = 0.1 * x978;
        let x1081 = 0.3 * x1011;
        let x1087 = 0.1 * x962;
        let x1091 = 0.3 * x1023;
        let x1097 = 0.1 * x948;
        let x1100 = 0.3 * x988;
        let x1106 = 0.1 * x930;
        let x1109 = 0.3 * x1001;
        let x1132 = s[30] * s[68];
        let x1133 = 0.1 * x1132;
        let x1134 = s[31] * s[69];
        let x1135 = s[17] * s[81];
        let x1136 = x1134 + x1135;
        let x1138 = s[32] * s[70];
        let x1139 = s[18] * s[82];
        let x1140 = x1138 + x1139;
        let x1141 = 0.3 * x1140;
        let x1196 = 0.3 * x1138;
        let x1673 = x314 * k[3];
        let x1674 = x313 * k[0];
        let x1676 = x5 - x1674;
        let x1678 = x1676 - x1673;
        let x1682 = x325 * x1678;
        let x1683 = x326 * x1678;
        let x1684 = x327 * x1678;
        let x1694 = x370 * s[93];
        let x1698 = 1.0 + x1682;
        let x1699 = x1694 - x412;
        let x1711 = k[6] + x1683;
        let x1713 = x930 * k[2];
        let x1714 = x928 + x1713;
        let x1715 = x936 + x1714;
        let x1716 = 0.5 * x1715;
        let x1717 = s[5] * k[10];
        let x1718 = x1716 + x1717;
        let x1719 = x948 * k[2];
        let x1721 = x947 - x1719;
        let x1722 = x953 + x1721;
        let x1723 = 0.5 * x1722;
        let x1725 = x96 * k[10];
        let x1726 = x1725 - x1723;
        let x1727 = x962 * k[2];
        let x1728 = x961 + x1727;
        let x1729 = x1728 - x966;
        let x1730 = 0.5 * x1729;
        let x1732 = s[12] * k[10];
        let x1733 = x1732 - x1730;
        let x1734 = x978 * k[2];
        let x1735 = x1734 - x976;
        let x1736 = x981 + x1735;
        let x1737 = 0.5 * x1736;
        let x1739 = x83 * k[10];
        let x1740 = x1739 - x1737;
        let x1741 = x952 * k[2];
        let x1742 = x1741 - x990;
        let x1743 = x1742 - x995;
        let x1744 = 0.5 * x1743;
        let x1745 = x1725 + x1744;
        let x1746 = x934 * k[2];
        let x1747 = x1002 + x1746;
        let x1748 = x1005 + x1747;
        let x1749 = 0.5 * x1748;
        let x1750 = s[6] * k[10];
        let x1751 = x1749 + x1750;
        let x1752 = x980 * k[2];
        let x1754 = x1012 - x1752;
        let x1755 = x1754 - x1016;
        let x1756 = 0.5 * x1755;
        let x1757 = x81 * k[10];
        let x1758 = x1756 + x1757;
        let x1759 = x964 * k[2];
        let x1760 = x1025 + x1759;
        let x1762 = x1029 - x1760;
        let x1763 = 0.5 * x1762;
        let x1764 = s[10] * k[10];
        let x1765 = x1763 + x1764;
        let x1766 = x1023 * k[2];
        let x1767 = x1036 + x1766;
        let x1769 = x1041 - x1767;
        let x1770 = 0.5 * x1769;
        let x1771 = x1732 + x1770;
        let x1772 = x1011 * k[2];
        let x1774 = x1048 - x1772;
        let x1775 = x1774 - x1052;
        let x1776 = 0.5 * x1775;
        let x1777 = x1757 + x1776;
        let x1778 = x1001 * k[2];
        let x1779 = x1058 + x1778;
        let x1780 = x1060 + x1779;
        let x1781 = 0.5 * x1780;
        let x1782 = x70 * k[10];
        let x1783 = x1781 + x1782;
        let x1784 = x988 * k[2];
        let x1785 = x1784 - x1067;
        let x1786 = x1785 - x1070;
        let x1787 = 0.5 * x1786;
        let x1788 = x94 * k[10];
        let x1789 = x1787 + x1788;
        let x1790 = x974 * k[2];
        let x1792 = x1077 - x1790;
        let x1793 = x1792 - x1081;
        let x1794 = 0.5 * x1793;
        let x1795 = x1739 + x1794;
        let x1796 = x960 * k[2];
        let x1797 = x1087 + x1796;
        let x1799 = x1091 - x1797;
        let x1800 = 0.5 * x1799;
        let x1801 = x1764 + x1800;
        let x1802 = x946 * k[2];
        let x1803 = x1802 - x1097;
        let x1804 = x1803 - x1100;
        let x1805 = 0.5 * x1804;
        let x1806 = x1788 + x1805;
        let x1807 = x926 * k[2];
        let x1808 = x1106 + x1807;
        let x1809 = x1109 + x1808;
        let x1810 = 0.5 * x1809;
        let x1811 = x71 * k[10];
        let x1812 = x1810 + x1811;
        let x1813 = x1136 * k[2];
        let x1814 = x1133 + x1813;
        let x1815 = x1141 + x1814;
        let x1816 = 0.5 * x1815;
        let x1830 = x1134 * k[2];
        let x1831 = x1133 + x1830;
        let x1832 = x1196 + x1831;
        let x1833 = 0.5 * x1832;
        let x1834 = x1816 + x1833;
        let x1835 = q[10] * k[10];
        let x1836 = s[89] * x1835;
        let x1838 = x1834 - x1836;
        let x1871 = x1699 + x1838;
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
        mass[0] = k[9];
        mass[1] = k[9];
        mass[2] = k[9];
        mass[3] = x566;
        mass[4] = x581;
        mass[5] = x595;
        mass[6] = x609;
        mass[7] = x619;
        mass[8] = x626;
        mass[9] = x636;
        mass[10] = x646;
        mass[11] = x651;
        mass[12] = x657;
        mass[13] = x661;
        mass[14] = x667;
        mass[15] = x670;
        mass[16] = x675;
        mass[17] = x678;
        mass[18] = x682;
        mass[19] = 1.0;
        mass[20] = 1.0;
        mass[21] = 1.0;
        mass[22] = x1718;
        mass[23] = x1726;
        mass[24] = x1733;
        mass[25] = x1740;
        mass[26] = x1745;
        mass[27] = x1751;
        mass[28] = x1758;
        mass[29] = x1765;
        mass[30] = x1771;
        mass[31] = x1777;
        mass[32] = x1783;
        mass[33] = x1789;
        mass[34] = x1795;
        mass[35] = x1801;
        mass[36] = x1806;
        mass[37] = x1812;
        force[0] = x1698;
        force[1] = x1711;
        force[2] = x1684;
        force[3] = x770;
        force[4] = x789;
        force[5] = x807;
        force[6] = x824;
        force[7] = 0.0;
        force[8] = -9.81;
        force[9] = 0.0;
        force[10] = x1871;
    }
    #[inline(never)]
    fn eval_newton_part_1(
        k: &[f64; 11],
        q: &[f64; 14],
        qd: &[f64; 14],
        s: &[f64; 94],
        force: &mut [f64; 14],
    ) {
        let x220 = 2.0 * qd[10];
        let x372 = s[9] * s[18];
        let x374 = s[14] * s[55];
        let x376 = x374 - x372;
        let x377 = s[53] * x376;
        let x378 = s[9] * s[15];
        let x379 = s[53] * x378;
        let x380 = s[9] * s[16];
        let x382 = s[53] * x380;
        let x414 = s[4] * s[18];
        let x415 = s[4] * s[15];
        let x416 = s[4] * s[16];
        let x1146 = x220 * s[68];
        let x1147 = 0.1 * x1146;
        let x1148 = s[32] * s[69];
        let x1149 = s[18] * s[81];
        let x1150 = x1148 + x1149;
        let x1153 = s[31] * s[70];
        let x1154 = s[17] * s[82];
        let x1155 = x1153 + x1154;
        let x1156 = 0.3 * x1155;
        let x1160 = s[32] * s[68];
        let x1161 = 0.1 * x1160;
        let x1162 = x220 * s[69];
        let x1163 = s[15] * s[81];
        let x1164 = x1162 + x1163;
        let x1166 = s[30] * s[70];
        let x1167 = s[16] * s[82];
        let x1168 = x1166 + x1167;
        let x1169 = 0.3 * x1168;
        let x1174 = s[31] * s[68];
        let x1175 = 0.1 * x1174;
        let x1177 = s[30] * s[69];
        let x1178 = s[16] * s[81];
        let x1179 = x1177 + x1178;
        let x1181 = x220 * s[70];
        let x1182 = s[15] * s[82];
        let x1183 = x1181 + x1182;
        let x1184 = 0.3 * x1183;
        let x1213 = 0.3 * x1153;
        let x1231 = 0.3 * x1166;
        let x1248 = 0.3 * x1181;
        let x1695 = x377 * s[93];
        let x1696 = x379 * s[93];
        let x1697 = x382 * s[93];
        let x1700 = x414 + x1695;
        let x1701 = x415 + x1696;
        let x1702 = x416 + x1697;
        let x1817 = x1150 * k[2];
        let x1819 = x1147 - x1817;
        let x1820 = x1156 + x1819;
        let x1821 = 0.5 * x1820;
        let x1822 = x1164 * k[2];
        let x1823 = x1161 + x1822;
        let x1824 = x1823 - x1169;
        let x1825 = 0.5 * x1824;
        let x1826 = x1179 * k[2];
        let x1827 = x1826 - x1175;
        let x1828 = x1184 + x1827;
        let x1829 = 0.5 * x1828;
        let x1839 = x1148 * k[2];
        let x1840 = x1839 - x1147;
        let x1841 = x1840 - x1213;
        let x1842 = 0.5 * x1841;
        let x1844 = x1842 - x1821;
        let x1845 = q[11] * k[10];
        let x1846 = s[89] * x1845;
        let x1848 = x1844 - x1846;
        let x1849 = x1162 * k[2];
        let x1850 = x1161 + x1849;
        let x1852 = x1231 - x1850;
        let x1853 = 0.5 * x1852;
        let x1855 = x1853 - x1825;
        let x1856 = q[12] * k[10];
        let x1857 = s[89] * x1856;
        let x1859 = x1855 - x1857;
        let x1860 = x1177 * k[2];
        let x1862 = x1175 - x1860;
        let x1863 = x1862 - x1248;
        let x1864 = 0.5 * x1863;
        let x1866 = x1864 - x1829;
        let x1867 = q[13] * k[10];
        let x1868 = s[89] * x1867;
        let x1870 = x1866 - x1868;
        let x1872 = x1700 + x1848;
        let x1873 = x1701 + x1859;
        let x1874 = x1870 - x1702;
        force[11] = x1872;
        force[12] = x1873;
        force[13] = x1874;
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
    pub const N_K: usize = 9;
    /// `setup` at the file's parameter values: what the types without parameters read.
    pub static K: [f64; 9] = [
        0.8f64,
        0.1f64,
        0.2f64,
        50f64,
        2f64,
        25f64,
        1f64,
        2f64,
        0.8f64,
    ];
    /// The values the per-step functions read (`k`), from the run-time parameters `p`.
    pub fn setup(p: &[f64], k: &mut [f64]) {
        let p: &[f64; 6] = p.try_into().expect("p must have 6 entries");
        let k: &mut [f64; 9] = k.try_into().expect("k must have 9 entries");
        setup_part_0(p, k);
    }
    #[inline(never)]
    fn setup_part_0(p: &[f64; 6], k: &mut [f64; 9]) {
        let x321 = 0.5 * p[3];
        let x361 = 0.5 * p[4];
        let x539 = 2.0 * p[5];
        let x540 = 0.5 * x539;
        let x916 = 0.1 + p[2];
        let x917 = 0.3 + x916;
        let x918 = 4.0 * x917;
        let x920 = x918 * 0.3333333333333333;
        k[0] = p[0];
        k[1] = p[1];
        k[2] = p[2];
        k[3] = p[3];
        k[4] = p[4];
        k[5] = x321;
        k[6] = x361;
        k[7] = x540;
        k[8] = x920;
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
        let x298 = q[1] * q[1];
        let x299 = q[2] * q[2];
        let x1665 = x298 + x299;
        let x1666 = q[2] * q[3];
        let x1667 = 2.0 * x1666;
        let x1668 = q[1] * q[4];
        let x1669 = 2.0 * x1668;
        let x1670 = q[2] * q[4];
        let x1671 = 2.0 * x1670;
        let x1672 = q[1] * q[3];
        let x1673 = 2.0 * x1672;
        let x1674 = x1667 + x1669;
        let x1675 = q[1] * q[2];
        let x1676 = 2.0 * x1675;
        let x1678 = x1671 - x1673;
        let x1679 = x54 + x1676;
        let x1680 = q[7] * q[7];
        let x1681 = q[8] * q[8];
        let x1682 = x25 + x26;
        let x1683 = q[6] * q[7];
        let x1684 = 2.0 * x1683;
        let x1685 = q[5] * q[8];
        let x1686 = 2.0 * x1685;
        let x1688 = x1684 - x1686;
        let x1689 = q[7] * q[8];
        let x1690 = 2.0 * x1689;
        let x1691 = x51 + x1690;
        let x1692 = -x1691;
        let x1693 = x23 + x1665;
        let x1694 = x24 + x1693;
        let x1695 = x1694 - 1.0;
        let x1696 = x1680 + x1682;
        let x1697 = x1681 + x1696;
        let x1698 = x1697 - 1.0;
        out[0] = x1674;
        out[1] = x1678;
        out[2] = x1679;
        out[3] = x1688;
        out[4] = x1692;
        out[5] = x1695;
        out[6] = x1698;
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
        let x305 = q[1] * 2.0;
        let x307 = q[2] * 2.0;
        let x483 = -x126;
        let x1699 = -x305;
        let x1700 = 2.0 * q[7];
        let x1701 = 2.0 * q[8];
        let x1702 = -x1701;
        let x1703 = -x1700;
        out[0] = x124;
        out[1] = x123;
        out[2] = x307;
        out[3] = x305;
        out[4] = x128;
        out[5] = x124;
        out[6] = x1699;
        out[7] = x307;
        out[8] = x307;
        out[9] = x305;
        out[10] = x124;
        out[11] = x123;
        out[12] = x1702;
        out[13] = x1700;
        out[14] = x126;
        out[15] = x127;
        out[16] = x483;
        out[17] = x127;
        out[18] = x1702;
        out[19] = x1703;
        out[20] = x305;
        out[21] = x307;
        out[22] = x123;
        out[23] = x124;
        out[24] = x125;
        out[25] = x126;
        out[26] = x1700;
        out[27] = x1701;
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
        let x470 = 2.0 * qd[1];
        let x472 = 2.0 * qd[2];
        let x856 = 2.0 * qd[7];
        let x858 = 2.0 * qd[8];
        let x1752 = qd[1] * x470;
        let x1753 = qd[2] * x472;
        let x1754 = x1752 + x1753;
        let x1755 = qd[2] * qd[3];
        let x1756 = x1755 + x1755;
        let x1757 = 2.0 * x1756;
        let x1758 = qd[1] * qd[4];
        let x1759 = x1758 + x1758;
        let x1760 = 2.0 * x1759;
        let x1761 = qd[2] * qd[4];
        let x1762 = x1761 + x1761;
        let x1763 = 2.0 * x1762;
        let x1764 = qd[1] * qd[3];
        let x1765 = x1764 + x1764;
        let x1766 = 2.0 * x1765;
        let x1767 = x1757 + x1760;
        let x1768 = qd[1] * qd[2];
        let x1769 = x1768 + x1768;
        let x1770 = 2.0 * x1769;
        let x1772 = x1763 - x1766;
        let x1773 = x247 + x1770;
        let x1774 = qd[7] * x856;
        let x1775 = qd[8] * x858;
        let x1776 = x226 + x227;
        let x1777 = qd[6] * qd[7];
        let x1778 = x1777 + x1777;
        let x1779 = 2.0 * x1778;
        let x1780 = qd[5] * qd[8];
        let x1781 = x1780 + x1780;
        let x1782 = 2.0 * x1781;
        let x1784 = x1779 - x1782;
        let x1785 = qd[7] * qd[8];
        let x1786 = x1785 + x1785;
        let x1787 = 2.0 * x1786;
        let x1788 = x244 + x1787;
        let x1790 = x224 + x1754;
        let x1791 = x225 + x1790;
        let x1792 = x1774 + x1776;
        let x1793 = x1775 + x1792;
        let x1794 = -x1767;
        let x1795 = -x1772;
        let x1796 = -x1773;
        let x1797 = -x1784;
        let x1798 = -x1791;
        let x1799 = -x1793;
        out[0] = x1794;
        out[1] = x1795;
        out[2] = x1796;
        out[3] = x1797;
        out[4] = x1788;
        out[5] = x1798;
        out[6] = x1799;
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
        let x298 = q[1] * q[1];
        let x299 = q[2] * q[2];
        let x305 = q[1] * 2.0;
        let x307 = q[2] * 2.0;
        let x470 = 2.0 * qd[1];
        let x472 = 2.0 * qd[2];
        let x483 = -x126;
        let x856 = 2.0 * qd[7];
        let x858 = 2.0 * qd[8];
        let x1665 = x298 + x299;
        let x1666 = q[2] * q[3];
        let x1667 = 2.0 * x1666;
        let x1668 = q[1] * q[4];
        let x1669 = 2.0 * x1668;
        let x1670 = q[2] * q[4];
        let x1671 = 2.0 * x1670;
        let x1672 = q[1] * q[3];
        let x1673 = 2.0 * x1672;
        let x1674 = x1667 + x1669;
        let x1675 = q[1] * q[2];
        let x1676 = 2.0 * x1675;
        let x1678 = x1671 - x1673;
        let x1679 = x54 + x1676;
        let x1680 = q[7] * q[7];
        let x1681 = q[8] * q[8];
        let x1682 = x25 + x26;
        let x1683 = q[6] * q[7];
        let x1684 = 2.0 * x1683;
        let x1685 = q[5] * q[8];
        let x1686 = 2.0 * x1685;
        let x1688 = x1684 - x1686;
        let x1689 = q[7] * q[8];
        let x1690 = 2.0 * x1689;
        let x1691 = x51 + x1690;
        let x1692 = -x1691;
        let x1693 = x23 + x1665;
        let x1694 = x24 + x1693;
        let x1695 = x1694 - 1.0;
        let x1696 = x1680 + x1682;
        let x1697 = x1681 + x1696;
        let x1698 = x1697 - 1.0;
        let x1699 = -x305;
        let x1700 = 2.0 * q[7];
        let x1701 = 2.0 * q[8];
        let x1702 = -x1701;
        let x1703 = -x1700;
        let x1752 = qd[1] * x470;
        let x1753 = qd[2] * x472;
        let x1754 = x1752 + x1753;
        let x1755 = qd[2] * qd[3];
        let x1756 = x1755 + x1755;
        let x1757 = 2.0 * x1756;
        let x1758 = qd[1] * qd[4];
        let x1759 = x1758 + x1758;
        let x1760 = 2.0 * x1759;
        let x1761 = qd[2] * qd[4];
        let x1762 = x1761 + x1761;
        let x1763 = 2.0 * x1762;
        let x1764 = qd[1] * qd[3];
        let x1765 = x1764 + x1764;
        let x1766 = 2.0 * x1765;
        let x1767 = x1757 + x1760;
        let x1768 = qd[1] * qd[2];
        let x1769 = x1768 + x1768;
        let x1770 = 2.0 * x1769;
        let x1772 = x1763 - x1766;
        let x1773 = x247 + x1770;
        let x1774 = qd[7] * x856;
        let x1775 = qd[8] * x858;
        let x1776 = x226 + x227;
        let x1777 = qd[6] * qd[7];
        let x1778 = x1777 + x1777;
        let x1779 = 2.0 * x1778;
        let x1780 = qd[5] * qd[8];
        let x1781 = x1780 + x1780;
        let x1782 = 2.0 * x1781;
        let x1784 = x1779 - x1782;
        let x1785 = qd[7] * qd[8];
        let x1786 = x1785 + x1785;
        let x1787 = 2.0 * x1786;
        let x1788 = x244 + x1787;
        let x1790 = x224 + x1754;
        let x1791 = x225 + x1790;
        let x1792 = x1774 + x1776;
        let x1793 = x1775 + x1792;
        let x1794 = -x1767;
        let x1795 = -x1772;
        let x1796 = -x1773;
        let x1797 = -x1784;
        let x1798 = -x1791;
        let x1799 = -x1793;
        phi[0] = x1674;
        phi_q[0] = x124;
        phi_q[1] = x123;
        phi_q[2] = x307;
        phi_q[3] = x305;
        phi_t[0] = 0.0;
        gamma[0] = x1794;
        phi[1] = x1678;
        phi_q[4] = x128;
        phi_q[5] = x124;
        phi_q[6] = x1699;
        phi_q[7] = x307;
        phi_t[1] = 0.0;
        gamma[1] = x1795;
        phi[2] = x1679;
        phi_q[8] = x307;
        phi_q[9] = x305;
        phi_q[10] = x124;
        phi_q[11] = x123;
        phi_t[2] = 0.0;
        gamma[2] = x1796;
        phi[3] = x1688;
        phi_q[12] = x1702;
        phi_q[13] = x1700;
        phi_q[14] = x126;
        phi_q[15] = x127;
        phi_t[3] = 0.0;
        gamma[3] = x1797;
        phi[4] = x1692;
        phi_q[16] = x483;
        phi_q[17] = x127;
        phi_q[18] = x1702;
        phi_q[19] = x1703;
        phi_t[4] = 0.0;
        gamma[4] = x1788;
        phi[5] = x1695;
        phi_q[20] = x305;
        phi_q[21] = x307;
        phi_q[22] = x123;
        phi_q[23] = x124;
        phi_t[5] = 0.0;
        gamma[5] = x1798;
        phi[6] = x1698;
        phi_q[24] = x125;
        phi_q[25] = x126;
        phi_q[26] = x1700;
        phi_q[27] = x1701;
        phi_t[6] = 0.0;
        gamma[6] = x1799;
    }
    /// Potential energy of gravity and springs, written to `out[0]`.
    pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 9] = k.try_into().expect("k must have 9 entries");
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        potential_into_part_0(k, q, out);
    }
    #[inline(never)]
    fn potential_into_part_0(k: &[f64; 9], q: &[f64; 9], out: &mut [f64; 1]) {
        let x25 = q[5] * q[5];
        let x26 = q[6] * q[6];
        let x296 = 1.0 + q[0];
        let x297 = x296 * x296;
        let x1682 = x25 + x26;
        let x1800 = 2.0 * x1682;
        let x1801 = x1800 - 1.0;
        let x1802 = q[6] * q[8];
        let x1803 = 2.0 * x1802;
        let x1804 = q[5] * q[7];
        let x1805 = 2.0 * x1804;
        let x1807 = x1803 - x1805;
        let x1808 = x297.sqrt();
        let x1809 = x1808 - 1.0;
        let x1810 = x1809 * x1809;
        let x1812 = -x1807;
        let x1813 = x1812.atan2(x1801);
        let x1814 = x1813 * x1813;
        let x2446 = x1810 * k[5];
        let x2447 = x1814 * k[6];
        let x2448 = 9.81 + x2446;
        let x2449 = x2447 + x2448;
        out[0] = x2449;
    }
    /// Power of the non-conservative loads, written to `out[0]`.
    pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 9] = k.try_into().expect("k must have 9 entries");
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        power_nc_into_part_0(k, q, qd, t, out);
    }
    #[inline(never)]
    fn power_nc_into_part_0(
        k: &[f64; 9],
        q: &[f64; 9],
        qd: &[f64; 9],
        t: f64,
        out: &mut [f64; 1],
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
        let x125 = q[5] * 2.0;
        let x126 = q[6] * 2.0;
        let x153 = x125 * qd[5];
        let x154 = x126 * qd[6];
        let x296 = 1.0 + q[0];
        let x297 = x296 * x296;
        let x303 = 2.0 * x296;
        let x304 = qd[0] * x303;
        let x1682 = x25 + x26;
        let x1731 = x153 + x154;
        let x1800 = 2.0 * x1682;
        let x1801 = x1800 - 1.0;
        let x1802 = q[6] * q[8];
        let x1803 = 2.0 * x1802;
        let x1804 = q[5] * q[7];
        let x1805 = 2.0 * x1804;
        let x1807 = x1803 - x1805;
        let x1808 = x297.sqrt();
        let x1818 = 2.0 * x1808;
        let x1819 = 1.0 / x1818;
        let x1820 = x304 * x1819;
        let x1825 = 2.0 * x1731;
        let x1826 = q[8] * qd[6];
        let x1827 = q[6] * qd[8];
        let x1828 = x1826 + x1827;
        let x1829 = 2.0 * x1828;
        let x1830 = q[7] * qd[5];
        let x1831 = q[5] * qd[7];
        let x1832 = x1830 + x1831;
        let x1833 = 2.0 * x1832;
        let x1835 = x1829 - x1833;
        let x1836 = x1801 * x1801;
        let x1837 = x1807 * x1807;
        let x1838 = x1836 + x1837;
        let x1839 = x1801 * x1835;
        let x1841 = x1807 * x1825;
        let x1842 = x1841 - x1839;
        let x1843 = 1.0 / x1838;
        let x1844 = x1842 * x1843;
        let x1851 = x1826 - x1830;
        let x1852 = x1831 + x1851;
        let x1853 = x1852 - x1827;
        let x1854 = 2.0 * x1853;
        let x1855 = x14 * x1854;
        let x2450 = x1820 * k[0];
        let x2452 = x5 - x2450;
        let x2453 = x1820 * x2452;
        let x2454 = x1844 * k[1];
        let x2456 = x11 - x2454;
        let x2457 = x1844 * x2456;
        let x2458 = qd[0] + x2453;
        let x2459 = x2457 + x2458;
        let x2460 = x1855 + x2459;
        out[0] = x2460;
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
            let k: &[f64; 9] = k.try_into().expect("k must have 9 entries");
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
            let k: &[f64; 9] = k.try_into().expect("k must have 9 entries");
            let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
            let out: &mut [f64; 33] = out.try_into().expect("out must have 33 entries");
            mass_part_0(k, q, out);
        }
        #[inline(never)]
        fn mass_part_0(k: &[f64; 9], q: &[f64; 9], out: &mut [f64; 33]) {
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
            let x298 = q[1] * q[1];
            let x299 = q[2] * q[2];
            let x305 = q[1] * 2.0;
            let x307 = q[2] * 2.0;
            let x541 = 2.0 * x124;
            let x543 = 2.0 * x125;
            let x545 = 2.0 * x126;
            let x547 = x124 * x541;
            let x549 = 0.01 * x547;
            let x551 = x125 * x543;
            let x555 = x126 * x545;
            let x565 = x23 * 0.04;
            let x567 = 2.0 * x123;
            let x568 = x124 * x567;
            let x569 = 0.01 * x568;
            let x570 = x125 * x545;
            let x574 = x126 * x543;
            let x580 = x52 * 0.04;
            let x610 = x123 * x541;
            let x612 = 0.01 * x610;
            let x620 = x123 * x567;
            let x621 = 0.01 * x620;
            let x625 = x24 * 0.04;
            let x1666 = q[2] * q[3];
            let x1668 = q[1] * q[4];
            let x1670 = q[2] * q[4];
            let x1672 = q[1] * q[3];
            let x1675 = q[1] * q[2];
            let x1680 = q[7] * q[7];
            let x1681 = q[8] * q[8];
            let x1683 = q[6] * q[7];
            let x1685 = q[5] * q[8];
            let x1689 = q[7] * q[8];
            let x1700 = 2.0 * q[7];
            let x1701 = 2.0 * q[8];
            let x1802 = q[6] * q[8];
            let x1804 = q[5] * q[7];
            let x1859 = 2.0 * x307;
            let x1860 = x307 * x1859;
            let x1861 = 0.01 * x1860;
            let x1862 = x621 + x1861;
            let x1863 = x549 + x1862;
            let x1864 = 0.5 * x1863;
            let x1865 = x298 * 0.04;
            let x1866 = x1864 + x1865;
            let x1867 = 2.0 * x305;
            let x1868 = x307 * x1867;
            let x1869 = 0.01 * x1868;
            let x1870 = x1869 - x612;
            let x1871 = x569 + x1870;
            let x1872 = 0.5 * x1871;
            let x1874 = 0.04 * x1675;
            let x1875 = x1874 - x1872;
            let x1876 = x307 * x541;
            let x1877 = 0.01 * x1876;
            let x1878 = x123 * x1867;
            let x1879 = 0.01 * x1878;
            let x1880 = x124 * x1859;
            let x1881 = 0.01 * x1880;
            let x1883 = x1877 + x1879;
            let x1884 = x1883 - x1881;
            let x1885 = 0.5 * x1884;
            let x1887 = 0.04 * x1672;
            let x1888 = x1887 - x1885;
            let x1889 = x307 * x567;
            let x1890 = 0.01 * x1889;
            let x1892 = x123 * x1859;
            let x1893 = 0.01 * x1892;
            let x1894 = x124 * x1867;
            let x1895 = 0.01 * x1894;
            let x1896 = x1893 - x1890;
            let x1897 = x1895 + x1896;
            let x1898 = 0.5 * x1897;
            let x1900 = 0.04 * x1668;
            let x1901 = x1900 - x1898;
            let x1902 = x305 * x1859;
            let x1903 = 0.01 * x1902;
            let x1905 = x569 - x1903;
            let x1906 = x1905 - x612;
            let x1907 = 0.5 * x1906;
            let x1908 = x1874 + x1907;
            let x1909 = x305 * x1867;
            let x1910 = 0.01 * x1909;
            let x1911 = x549 + x1910;
            let x1912 = x621 + x1911;
            let x1913 = 0.5 * x1912;
            let x1914 = x299 * 0.04;
            let x1915 = x1913 + x1914;
            let x1916 = x305 * x541;
            let x1917 = 0.01 * x1916;
            let x1920 = x1917 - x1895;
            let x1921 = x1920 - x1893;
            let x1922 = 0.5 * x1921;
            let x1923 = 0.04 * x1666;
            let x1924 = x1922 + x1923;
            let x1925 = x305 * x567;
            let x1926 = 0.01 * x1925;
            let x1927 = x1881 + x1926;
            let x1929 = x1879 - x1927;
            let x1930 = 0.5 * x1929;
            let x1931 = 0.04 * x1670;
            let x1932 = x1930 + x1931;
            let x1933 = x1877 - x1927;
            let x1934 = 0.5 * x1933;
            let x1935 = x1887 + x1934;
            let x1937 = x1895 - x1917;
            let x1938 = x1937 - x1890;
            let x1939 = 0.5 * x1938;
            let x1940 = x1923 + x1939;
            let x1941 = x1861 + x1911;
            let x1942 = 0.5 * x1941;
            let x1943 = x565 + x1942;
            let x1945 = x1903 - x569;
            let x1946 = x1945 - x1869;
            let x1947 = 0.5 * x1946;
            let x1948 = x580 + x1947;
            let x1949 = x1896 - x1917;
            let x1950 = 0.5 * x1949;
            let x1951 = x1900 + x1950;
            let x1953 = x1926 - x1883;
            let x1954 = 0.5 * x1953;
            let x1955 = x1931 + x1954;
            let x1956 = x1870 - x1903;
            let x1957 = 0.5 * x1956;
            let x1958 = x580 + x1957;
            let x1959 = x1862 + x1910;
            let x1960 = 0.5 * x1959;
            let x1961 = x625 + x1960;
            let x1962 = 2.0 * x1700;
            let x1963 = 2.0 * x1701;
            let x1964 = 0.1 * x555;
            let x1965 = x1700 * x1962;
            let x1967 = x1701 * x1963;
            let x1968 = 0.3 * x1967;
            let x1974 = 0.1 * x574;
            let x1975 = x1700 * x1963;
            let x1978 = x1701 * x1962;
            let x1979 = 0.3 * x1978;
            let x1986 = x126 * x1963;
            let x1987 = 0.1 * x1986;
            let x1988 = x543 * x1700;
            let x1990 = x545 * x1701;
            let x1991 = 0.3 * x1990;
            let x1999 = x126 * x1962;
            let x2000 = 0.1 * x1999;
            let x2002 = x545 * x1700;
            let x2004 = x543 * x1701;
            let x2005 = 0.3 * x2004;
            let x2012 = 0.1 * x570;
            let x2015 = 0.3 * x1975;
            let x2021 = 0.1 * x551;
            let x2023 = 0.3 * x1965;
            let x2029 = x125 * x1963;
            let x2030 = 0.1 * x2029;
            let x2033 = 0.3 * x2002;
            let x2040 = x125 * x1962;
            let x2041 = 0.1 * x2040;
            let x2043 = 0.3 * x1988;
            let x2050 = 0.1 * x1990;
            let x2052 = 0.3 * x1986;
            let x2058 = 0.1 * x2004;
            let x2061 = 0.3 * x1999;
            let x2067 = 0.1 * x1967;
            let x2069 = 0.3 * x555;
            let x2075 = 0.1 * x1978;
            let x2078 = 0.3 * x574;
            let x2085 = 0.1 * x2002;
            let x2088 = 0.3 * x2029;
            let x2094 = 0.1 * x1988;
            let x2096 = 0.3 * x2040;
            let x2102 = 0.1 * x1975;
            let x2105 = 0.3 * x570;
            let x2111 = 0.1 * x1965;
            let x2113 = 0.3 * x551;
            let x2461 = x1965 * k[2];
            let x2462 = x1964 + x2461;
            let x2463 = x1968 + x2462;
            let x2464 = 0.5 * x2463;
            let x2465 = x25 * k[8];
            let x2466 = x2464 + x2465;
            let x2467 = x1975 * k[2];
            let x2469 = x1974 - x2467;
            let x2470 = x1979 + x2469;
            let x2471 = 0.5 * x2470;
            let x2473 = x50 * k[8];
            let x2474 = x2473 - x2471;
            let x2475 = x1988 * k[2];
            let x2476 = x1987 + x2475;
            let x2477 = x2476 - x1991;
            let x2478 = 0.5 * x2477;
            let x2480 = x1804 * k[8];
            let x2481 = x2480 - x2478;
            let x2482 = x2002 * k[2];
            let x2483 = x2482 - x2000;
            let x2484 = x2005 + x2483;
            let x2485 = 0.5 * x2484;
            let x2487 = x1685 * k[8];
            let x2488 = x2487 - x2485;
            let x2489 = x1978 * k[2];
            let x2490 = x2489 - x2012;
            let x2491 = x2490 - x2015;
            let x2492 = 0.5 * x2491;
            let x2493 = x2473 + x2492;
            let x2494 = x1967 * k[2];
            let x2495 = x2021 + x2494;
            let x2496 = x2023 + x2495;
            let x2497 = 0.5 * x2496;
            let x2498 = x26 * k[8];
            let x2499 = x2497 + x2498;
            let x2500 = x2004 * k[2];
            let x2502 = x2030 - x2500;
            let x2503 = x2502 - x2033;
            let x2504 = 0.5 * x2503;
            let x2505 = x1683 * k[8];
            let x2506 = x2504 + x2505;
            let x2507 = x1990 * k[2];
            let x2508 = x2041 + x2507;
            let x2510 = x2043 - x2508;
            let x2511 = 0.5 * x2510;
            let x2512 = x1802 * k[8];
            let x2513 = x2511 + x2512;
            let x2514 = x2040 * k[2];
            let x2515 = x2050 + x2514;
            let x2517 = x2052 - x2515;
            let x2518 = 0.5 * x2517;
            let x2519 = x2480 + x2518;
            let x2520 = x2029 * k[2];
            let x2522 = x2058 - x2520;
            let x2523 = x2522 - x2061;
            let x2524 = 0.5 * x2523;
            let x2525 = x2505 + x2524;
            let x2526 = x551 * k[2];
            let x2527 = x2067 + x2526;
            let x2528 = x2069 + x2527;
            let x2529 = 0.5 * x2528;
            let x2530 = x1680 * k[8];
            let x2531 = x2529 + x2530;
            let x2532 = x570 * k[2];
            let x2533 = x2532 - x2075;
            let x2534 = x2533 - x2078;
            let x2535 = 0.5 * x2534;
            let x2536 = x1689 * k[8];
            let x2537 = x2535 + x2536;
            let x2538 = x1999 * k[2];
            let x2540 = x2085 - x2538;
            let x2541 = x2540 - x2088;
            let x2542 = 0.5 * x2541;
            let x2543 = x2487 + x2542;
            let x2544 = x1986 * k[2];
            let x2545 = x2094 + x2544;
            let x2547 = x2096 - x2545;
            let x2548 = 0.5 * x2547;
            let x2549 = x2512 + x2548;
            let x2550 = x574 * k[2];
            let x2551 = x2550 - x2102;
            let x2552 = x2551 - x2105;
            let x2553 = 0.5 * x2552;
            let x2554 = x2536 + x2553;
            let x2555 = x555 * k[2];
            let x2556 = x2111 + x2555;
            let x2557 = x2113 + x2556;
            let x2558 = 0.5 * x2557;
            let x2559 = x1681 * k[8];
            let x2560 = x2558 + x2559;
            out[0] = k[7];
            out[1] = x1866;
            out[2] = x1875;
            out[3] = x1888;
            out[4] = x1901;
            out[5] = x1908;
            out[6] = x1915;
            out[7] = x1924;
            out[8] = x1932;
            out[9] = x1935;
            out[10] = x1940;
            out[11] = x1943;
            out[12] = x1948;
            out[13] = x1951;
            out[14] = x1955;
            out[15] = x1958;
            out[16] = x1961;
            out[17] = x2466;
            out[18] = x2474;
            out[19] = x2481;
            out[20] = x2488;
            out[21] = x2493;
            out[22] = x2499;
            out[23] = x2506;
            out[24] = x2513;
            out[25] = x2519;
            out[26] = x2525;
            out[27] = x2531;
            out[28] = x2537;
            out[29] = x2543;
            out[30] = x2549;
            out[31] = x2554;
            out[32] = x2560;
        }
        /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
        pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            let k: &[f64; 9] = k.try_into().expect("k must have 9 entries");
            let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
            let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
            force_part_0(k, q, qd, t, out);
        }
        #[inline(never)]
        fn force_part_0(
            k: &[f64; 9],
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
            let x296 = 1.0 + q[0];
            let x297 = x296 * x296;
            let x303 = 2.0 * x296;
            let x304 = qd[0] * x303;
            let x305 = q[1] * 2.0;
            let x307 = q[2] * 2.0;
            let x453 = qd[1] * qd[1];
            let x457 = qd[2] * qd[2];
            let x470 = 2.0 * qd[1];
            let x472 = 2.0 * qd[2];
            let x543 = 2.0 * x125;
            let x545 = 2.0 * x126;
            let x754 = qd[3] * qd[3];
            let x755 = qd[4] * qd[4];
            let x756 = qd[5] * qd[5];
            let x757 = qd[6] * qd[6];
            let x767 = q[3] * 0.04;
            let x786 = q[4] * 0.04;
            let x841 = qd[7] * qd[7];
            let x844 = qd[8] * qd[8];
            let x856 = 2.0 * qd[7];
            let x858 = 2.0 * qd[8];
            let x1682 = x25 + x26;
            let x1700 = 2.0 * q[7];
            let x1701 = 2.0 * q[8];
            let x1705 = q[3] * qd[2];
            let x1706 = q[2] * qd[3];
            let x1709 = q[4] * qd[1];
            let x1710 = q[1] * qd[4];
            let x1713 = q[4] * qd[2];
            let x1714 = q[2] * qd[4];
            let x1717 = q[3] * qd[1];
            let x1718 = q[1] * qd[3];
            let x1722 = q[2] * qd[1];
            let x1723 = q[1] * qd[2];
            let x1731 = x153 + x154;
            let x1732 = q[7] * qd[6];
            let x1733 = q[6] * qd[7];
            let x1736 = q[8] * qd[5];
            let x1737 = q[5] * qd[8];
            let x1742 = q[8] * qd[7];
            let x1743 = q[7] * qd[8];
            let x1755 = qd[2] * qd[3];
            let x1758 = qd[1] * qd[4];
            let x1761 = qd[2] * qd[4];
            let x1764 = qd[1] * qd[3];
            let x1777 = qd[6] * qd[7];
            let x1780 = qd[5] * qd[8];
            let x1800 = 2.0 * x1682;
            let x1801 = x1800 - 1.0;
            let x1802 = q[6] * q[8];
            let x1803 = 2.0 * x1802;
            let x1804 = q[5] * q[7];
            let x1805 = 2.0 * x1804;
            let x1807 = x1803 - x1805;
            let x1808 = x297.sqrt();
            let x1809 = x1808 - 1.0;
            let x1812 = -x1807;
            let x1813 = x1812.atan2(x1801);
            let x1818 = 2.0 * x1808;
            let x1819 = 1.0 / x1818;
            let x1820 = x304 * x1819;
            let x1825 = 2.0 * x1731;
            let x1826 = q[8] * qd[6];
            let x1827 = q[6] * qd[8];
            let x1828 = x1826 + x1827;
            let x1829 = 2.0 * x1828;
            let x1830 = q[7] * qd[5];
            let x1831 = q[5] * qd[7];
            let x1832 = x1830 + x1831;
            let x1833 = 2.0 * x1832;
            let x1835 = x1829 - x1833;
            let x1836 = x1801 * x1801;
            let x1837 = x1807 * x1807;
            let x1838 = x1836 + x1837;
            let x1839 = x1801 * x1835;
            let x1841 = x1807 * x1825;
            let x1842 = x1841 - x1839;
            let x1843 = 1.0 / x1838;
            let x1844 = x1842 * x1843;
            let x2122 = x303 * x1819;
            let x2127 = x1700 * x1801;
            let x2128 = x543 * x1807;
            let x2129 = x2127 + x2128;
            let x2130 = x1843 * x2129;
            let x2131 = x1701 * x1801;
            let x2133 = x545 * x1807;
            let x2134 = x2133 - x2131;
            let x2135 = x1843 * x2134;
            let x2136 = x125 * x1801;
            let x2137 = x1843 * x2136;
            let x2138 = x126 * x1801;
            let x2139 = x1843 * x2138;
            let x2145 = x174 - x173;
            let x2147 = x14 * x1700;
            let x2149 = x14 * x1701;
            let x2150 = x14 * x125;
            let x2151 = x14 * x126;
            let x2160 = x1723 - x1722;
            let x2161 = x177 + x2160;
            let x2162 = x2161 - x178;
            let x2163 = 2.0 * x2162;
            let x2164 = x1713 + x1717;
            let x2166 = x1718 - x2164;
            let x2167 = x1714 + x2166;
            let x2168 = 2.0 * x2167;
            let x2171 = x1705 - x1709;
            let x2172 = x2171 - x1706;
            let x2173 = x1710 + x2172;
            let x2174 = 2.0 * x2173;
            let x2175 = 2.0 * x2163;
            let x2176 = 2.0 * x2168;
            let x2177 = 2.0 * x2174;
            let x2178 = x1761 + x1764;
            let x2180 = x1764 - x2178;
            let x2181 = x1761 + x2180;
            let x2182 = 2.0 * x2181;
            let x2185 = x1755 - x1758;
            let x2186 = x2185 - x1755;
            let x2187 = x1758 + x2186;
            let x2188 = 2.0 * x2187;
            let x2189 = 2.0 * x2182;
            let x2190 = 2.0 * x2188;
            let x2191 = x472 * x2175;
            let x2192 = 0.01 * x2191;
            let x2193 = x216 * x2176;
            let x2194 = x123 * x2189;
            let x2195 = x2193 + x2194;
            let x2196 = 0.01 * x2195;
            let x2197 = x217 * x2177;
            let x2198 = x124 * x2190;
            let x2199 = x2197 + x2198;
            let x2200 = 0.01 * x2199;
            let x2201 = x2192 + x2196;
            let x2202 = x2200 + x2201;
            let x2203 = 0.5 * x2202;
            let x2204 = x470 * x2175;
            let x2205 = 0.01 * x2204;
            let x2206 = x217 * x2176;
            let x2207 = x124 * x2189;
            let x2208 = x2206 + x2207;
            let x2209 = 0.01 * x2208;
            let x2211 = x216 * x2177;
            let x2212 = x123 * x2190;
            let x2213 = x2211 + x2212;
            let x2214 = 0.01 * x2213;
            let x2215 = x2205 - x2209;
            let x2216 = x2214 + x2215;
            let x2217 = 0.5 * x2216;
            let x2218 = x217 * x2175;
            let x2219 = 0.01 * x2218;
            let x2220 = x470 * x2176;
            let x2221 = x305 * x2189;
            let x2222 = x2220 + x2221;
            let x2223 = 0.01 * x2222;
            let x2224 = x472 * x2177;
            let x2225 = x307 * x2190;
            let x2226 = x2224 + x2225;
            let x2227 = 0.01 * x2226;
            let x2229 = x2219 + x2223;
            let x2230 = x2229 - x2227;
            let x2231 = 0.5 * x2230;
            let x2232 = x216 * x2175;
            let x2233 = 0.01 * x2232;
            let x2235 = x472 * x2176;
            let x2236 = x307 * x2189;
            let x2237 = x2235 + x2236;
            let x2238 = 0.01 * x2237;
            let x2239 = x470 * x2177;
            let x2240 = x305 * x2190;
            let x2241 = x2239 + x2240;
            let x2242 = 0.01 * x2241;
            let x2243 = x2238 - x2233;
            let x2244 = x2242 + x2243;
            let x2245 = 0.5 * x2244;
            let x2246 = x453 + x457;
            let x2247 = x754 + x2246;
            let x2248 = x755 + x2247;
            let x2249 = 0.01 * x2193;
            let x2250 = 0.01 * x2197;
            let x2251 = x2192 + x2249;
            let x2252 = x2250 + x2251;
            let x2253 = 0.5 * x2252;
            let x2254 = x2203 + x2253;
            let x2255 = q[1] * 0.04;
            let x2256 = x2248 * x2255;
            let x2258 = x2254 - x2256;
            let x2260 = 0.01 * x2206;
            let x2261 = 0.01 * x2211;
            let x2263 = x2260 - x2205;
            let x2264 = x2263 - x2261;
            let x2265 = 0.5 * x2264;
            let x2267 = x2265 - x2217;
            let x2268 = q[2] * 0.04;
            let x2269 = x2248 * x2268;
            let x2271 = x2267 - x2269;
            let x2272 = 0.01 * x2220;
            let x2273 = 0.01 * x2224;
            let x2274 = x2219 + x2272;
            let x2276 = x2273 - x2274;
            let x2277 = 0.5 * x2276;
            let x2279 = x2277 - x2231;
            let x2280 = x767 * x2248;
            let x2282 = x2279 - x2280;
            let x2283 = 0.01 * x2235;
            let x2285 = 0.01 * x2239;
            let x2287 = x2233 - x2283;
            let x2288 = x2287 - x2285;
            let x2289 = 0.5 * x2288;
            let x2291 = x2289 - x2245;
            let x2292 = x786 * x2248;
            let x2294 = x2291 - x2292;
            let x2296 = x1742 + x2145;
            let x2297 = x2296 - x1743;
            let x2298 = 2.0 * x2297;
            let x2299 = x1826 + x1830;
            let x2301 = x1831 - x2299;
            let x2302 = x1827 + x2301;
            let x2303 = 2.0 * x2302;
            let x2305 = x1732 - x1736;
            let x2306 = x2305 - x1733;
            let x2307 = x1737 + x2306;
            let x2308 = 2.0 * x2307;
            let x2309 = 2.0 * x2298;
            let x2310 = 2.0 * x2303;
            let x2311 = 2.0 * x2308;
            let x2312 = qd[6] * qd[8];
            let x2313 = qd[5] * qd[7];
            let x2315 = x2312 + x2313;
            let x2317 = x2313 - x2315;
            let x2318 = x2312 + x2317;
            let x2319 = 2.0 * x2318;
            let x2321 = x1777 - x1780;
            let x2322 = x2321 - x1777;
            let x2323 = x1780 + x2322;
            let x2324 = 2.0 * x2323;
            let x2325 = 2.0 * x2319;
            let x2326 = 2.0 * x2324;
            let x2327 = x219 * x2309;
            let x2328 = 0.1 * x2327;
            let x2329 = x856 * x2310;
            let x2330 = x1700 * x2325;
            let x2331 = x2329 + x2330;
            let x2333 = x858 * x2311;
            let x2334 = x1701 * x2326;
            let x2335 = x2333 + x2334;
            let x2336 = 0.3 * x2335;
            let x2340 = x218 * x2309;
            let x2341 = 0.1 * x2340;
            let x2342 = x858 * x2310;
            let x2343 = x1701 * x2325;
            let x2344 = x2342 + x2343;
            let x2347 = x856 * x2311;
            let x2348 = x1700 * x2326;
            let x2349 = x2347 + x2348;
            let x2350 = 0.3 * x2349;
            let x2354 = x858 * x2309;
            let x2355 = 0.1 * x2354;
            let x2356 = x218 * x2310;
            let x2357 = x125 * x2325;
            let x2358 = x2356 + x2357;
            let x2360 = x219 * x2311;
            let x2361 = x126 * x2326;
            let x2362 = x2360 + x2361;
            let x2363 = 0.3 * x2362;
            let x2368 = x856 * x2309;
            let x2369 = 0.1 * x2368;
            let x2371 = x219 * x2310;
            let x2372 = x126 * x2325;
            let x2373 = x2371 + x2372;
            let x2375 = x218 * x2311;
            let x2376 = x125 * x2326;
            let x2377 = x2375 + x2376;
            let x2378 = 0.3 * x2377;
            let x2382 = x756 + x757;
            let x2383 = x841 + x2382;
            let x2384 = x844 + x2383;
            let x2386 = 0.3 * x2333;
            let x2397 = 0.3 * x2347;
            let x2409 = 0.3 * x2360;
            let x2422 = 0.3 * x2375;
            let x2450 = x1820 * k[0];
            let x2452 = x5 - x2450;
            let x2454 = x1844 * k[1];
            let x2456 = x11 - x2454;
            let x2561 = x1809 * k[3];
            let x2563 = x2452 - x2561;
            let x2564 = x2122 * x2563;
            let x2565 = x1813 * k[4];
            let x2567 = x2456 - x2565;
            let x2568 = x2130 * x2567;
            let x2569 = x2135 * x2567;
            let x2570 = x2137 * x2567;
            let x2571 = x2139 * x2567;
            let x2572 = 1.0 + x2564;
            let x2573 = x2568 - x2147;
            let x2574 = x2149 + x2569;
            let x2575 = x2150 + x2570;
            let x2576 = x2151 + x2571;
            let x2578 = x2331 * k[2];
            let x2579 = x2328 + x2578;
            let x2580 = x2336 + x2579;
            let x2581 = 0.5 * x2580;
            let x2582 = x2344 * k[2];
            let x2584 = x2341 - x2582;
            let x2585 = x2350 + x2584;
            let x2586 = 0.5 * x2585;
            let x2587 = x2358 * k[2];
            let x2588 = x2355 + x2587;
            let x2589 = x2588 - x2363;
            let x2590 = 0.5 * x2589;
            let x2591 = x2373 * k[2];
            let x2592 = x2591 - x2369;
            let x2593 = x2378 + x2592;
            let x2594 = 0.5 * x2593;
            let x2595 = x2329 * k[2];
            let x2596 = x2328 + x2595;
            let x2597 = x2386 + x2596;
            let x2598 = 0.5 * x2597;
            let x2599 = x2581 + x2598;
            let x2600 = q[5] * k[8];
            let x2601 = x2384 * x2600;
            let x2603 = x2599 - x2601;
            let x2604 = x2342 * k[2];
            let x2605 = x2604 - x2341;
            let x2606 = x2605 - x2397;
            let x2607 = 0.5 * x2606;
            let x2609 = x2607 - x2586;
            let x2610 = q[6] * k[8];
            let x2611 = x2384 * x2610;
            let x2613 = x2609 - x2611;
            let x2614 = x2356 * k[2];
            let x2615 = x2355 + x2614;
            let x2617 = x2409 - x2615;
            let x2618 = 0.5 * x2617;
            let x2620 = x2618 - x2590;
            let x2621 = q[7] * k[8];
            let x2622 = x2384 * x2621;
            let x2624 = x2620 - x2622;
            let x2625 = x2371 * k[2];
            let x2627 = x2369 - x2625;
            let x2628 = x2627 - x2422;
            let x2629 = 0.5 * x2628;
            let x2631 = x2629 - x2594;
            let x2632 = q[8] * k[8];
            let x2633 = x2384 * x2632;
            let x2635 = x2631 - x2633;
            let x2636 = x2573 + x2603;
            let x2637 = x2574 + x2613;
            let x2638 = x2575 + x2624;
            let x2639 = x2635 - x2576;
            out[0] = x2572;
            out[1] = x2258;
            out[2] = x2271;
            out[3] = x2282;
            out[4] = x2294;
            out[5] = x2636;
            out[6] = x2637;
            out[7] = x2638;
            out[8] = x2639;
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
            let k: &[f64; 9] = k.try_into().expect("k must have 9 entries");
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
            k: &[f64; 9],
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
            let x545 = 2.0 * x126;
            s[14] = x545;
            let x756 = qd[5] * qd[5];
            s[15] = x756;
            let x757 = qd[6] * qd[6];
            s[16] = x757;
            let x841 = qd[7] * qd[7];
            s[17] = x841;
            let x844 = qd[8] * qd[8];
            s[18] = x844;
            let x856 = 2.0 * qd[7];
            s[19] = x856;
            let x858 = 2.0 * qd[8];
            s[20] = x858;
            let x1682 = x25 + x26;
            s[21] = x1682;
            let x1700 = 2.0 * q[7];
            s[22] = x1700;
            let x1701 = 2.0 * q[8];
            s[23] = x1701;
            let x1731 = x153 + x154;
            s[24] = x1731;
            let x1732 = q[7] * qd[6];
            s[25] = x1732;
            let x1733 = q[6] * qd[7];
            s[26] = x1733;
            let x1736 = q[8] * qd[5];
            s[27] = x1736;
            let x1737 = q[5] * qd[8];
            s[28] = x1737;
            let x1742 = q[8] * qd[7];
            s[29] = x1742;
            let x1743 = q[7] * qd[8];
            s[30] = x1743;
            let x1777 = qd[6] * qd[7];
            s[31] = x1777;
            let x1780 = qd[5] * qd[8];
            s[32] = x1780;
            let x1800 = 2.0 * x1682;
            s[33] = x1800;
            let x1801 = x1800 - 1.0;
            s[34] = x1801;
            let x1802 = q[6] * q[8];
            s[35] = x1802;
            let x1803 = 2.0 * x1802;
            s[36] = x1803;
            let x1804 = q[5] * q[7];
            s[37] = x1804;
            let x1805 = 2.0 * x1804;
            s[38] = x1805;
            let x1807 = x1803 - x1805;
            s[39] = x1807;
            let x1812 = -x1807;
            s[40] = x1812;
            let x1813 = x1812.atan2(x1801);
            s[41] = x1813;
            let x1825 = 2.0 * x1731;
            s[42] = x1825;
            let x1826 = q[8] * qd[6];
            s[43] = x1826;
            let x1827 = q[6] * qd[8];
            s[44] = x1827;
            let x1828 = x1826 + x1827;
            s[45] = x1828;
            let x1829 = 2.0 * x1828;
            s[46] = x1829;
            let x1830 = q[7] * qd[5];
            s[47] = x1830;
            let x1831 = q[5] * qd[7];
            s[48] = x1831;
            let x1832 = x1830 + x1831;
            s[49] = x1832;
            let x1833 = 2.0 * x1832;
            s[50] = x1833;
            let x1835 = x1829 - x1833;
            s[51] = x1835;
            let x1836 = x1801 * x1801;
            s[52] = x1836;
            let x1837 = x1807 * x1807;
            s[53] = x1837;
            let x1838 = x1836 + x1837;
            s[54] = x1838;
            let x1839 = x1801 * x1835;
            s[55] = x1839;
            let x1841 = x1807 * x1825;
            s[56] = x1841;
            let x1842 = x1841 - x1839;
            s[57] = x1842;
            let x1843 = 1.0 / x1838;
            s[58] = x1843;
            let x1844 = x1842 * x1843;
            s[59] = x1844;
            let x2145 = x174 - x173;
            s[60] = x2145;
            let x2296 = x1742 + x2145;
            s[61] = x2296;
            let x2297 = x2296 - x1743;
            s[62] = x2297;
            let x2298 = 2.0 * x2297;
            s[63] = x2298;
            let x2299 = x1826 + x1830;
            s[64] = x2299;
            let x2301 = x1831 - x2299;
            s[65] = x2301;
            let x2302 = x1827 + x2301;
            s[66] = x2302;
            let x2303 = 2.0 * x2302;
            s[67] = x2303;
            let x2305 = x1732 - x1736;
            s[68] = x2305;
            let x2306 = x2305 - x1733;
            s[69] = x2306;
            let x2307 = x1737 + x2306;
            s[70] = x2307;
            let x2308 = 2.0 * x2307;
            s[71] = x2308;
            let x2309 = 2.0 * x2298;
            s[72] = x2309;
            let x2310 = 2.0 * x2303;
            s[73] = x2310;
            let x2311 = 2.0 * x2308;
            s[74] = x2311;
            let x2312 = qd[6] * qd[8];
            s[75] = x2312;
            let x2313 = qd[5] * qd[7];
            s[76] = x2313;
            let x2315 = x2312 + x2313;
            s[77] = x2315;
            let x2317 = x2313 - x2315;
            s[78] = x2317;
            let x2318 = x2312 + x2317;
            s[79] = x2318;
            let x2319 = 2.0 * x2318;
            s[80] = x2319;
            let x2321 = x1777 - x1780;
            s[81] = x2321;
            let x2322 = x2321 - x1777;
            s[82] = x2322;
            let x2323 = x1780 + x2322;
            s[83] = x2323;
            let x2324 = 2.0 * x2323;
            s[84] = x2324;
            let x2325 = 2.0 * x2319;
            s[85] = x2325;
            let x2326 = 2.0 * x2324;
            s[86] = x2326;
            let x2382 = x756 + x757;
            s[87] = x2382;
            let x2383 = x841 + x2382;
            s[88] = x2383;
            let x2384 = x844 + x2383;
            s[89] = x2384;
            let x2454 = x1844 * k[1];
            s[90] = x2454;
            let x2456 = x11 - x2454;
            s[91] = x2456;
            let x2565 = x1813 * k[4];
            s[92] = x2565;
            let x2567 = x2456 - x2565;
            s[93] = x2567;
        }
        #[inline(never)]
        fn eval_newton_part_0(
            k: &[f64; 9],
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
            let x296 = 1.0 + q[0];
            let x297 = x296 * x296;
            let x298 = q[1] * q[1];
            let x299 = q[2] * q[2];
            let x303 = 2.0 * x296;
            let x304 = qd[0] * x303;
            let x305 = q[1] * 2.0;
            let x307 = q[2] * 2.0;
            let x453 = qd[1] * qd[1];
            let x457 = qd[2] * qd[2];
            let x470 = 2.0 * qd[1];
            let x472 = 2.0 * qd[2];
            let x483 = -s[8];
            let x541 = 2.0 * x124;
            let x543 = 2.0 * s[7];
            let x547 = x124 * x541;
            let x549 = 0.01 * x547;
            let x551 = s[7] * x543;
            let x555 = s[8] * s[14];
            let x565 = x23 * 0.04;
            let x567 = 2.0 * x123;
            let x568 = x124 * x567;
            let x569 = 0.01 * x568;
            let x570 = s[7] * s[14];
            let x574 = s[8] * x543;
            let x580 = x52 * 0.04;
            let x610 = x123 * x541;
            let x612 = 0.01 * x610;
            let x620 = x123 * x567;
            let x621 = 0.01 * x620;
            let x625 = x24 * 0.04;
            let x754 = qd[3] * qd[3];
            let x755 = qd[4] * qd[4];
            let x767 = q[3] * 0.04;
            let x786 = q[4] * 0.04;
            let x1665 = x298 + x299;
            let x1666 = q[2] * q[3];
            let x1667 = 2.0 * x1666;
            let x1668 = q[1] * q[4];
            let x1669 = 2.0 * x1668;
            let x1670 = q[2] * q[4];
            let x1671 = 2.0 * x1670;
            let x1672 = q[1] * q[3];
            let x1673 = 2.0 * x1672;
            let x1674 = x1667 + x1669;
            let x1675 = q[1] * q[2];
            let x1676 = 2.0 * x1675;
            let x1678 = x1671 - x1673;
            let x1679 = x54 + x1676;
            let x1680 = q[7] * q[7];
            let x1681 = q[8] * q[8];
            let x1683 = q[6] * q[7];
            let x1684 = 2.0 * x1683;
            let x1685 = q[5] * q[8];
            let x1686 = 2.0 * x1685;
            let x1688 = x1684 - x1686;
            let x1689 = q[7] * q[8];
            let x1690 = 2.0 * x1689;
            let x1691 = x51 + x1690;
            let x1692 = -x1691;
            let x1693 = x23 + x1665;
            let x1694 = x24 + x1693;
            let x1695 = x1694 - 1.0;
            let x1696 = x1680 + s[21];
            let x1697 = x1681 + x1696;
            let x1698 = x1697 - 1.0;
            let x1699 = -x305;
            let x1702 = -s[23];
            let x1703 = -s[22];
            let x1705 = q[3] * qd[2];
            let x1706 = q[2] * qd[3];
            let x1709 = q[4] * qd[1];
            let x1710 = q[1] * qd[4];
            let x1713 = q[4] * qd[2];
            let x1714 = q[2] * qd[4];
            let x1717 = q[3] * qd[1];
            let x1718 = q[1] * qd[3];
            let x1722 = q[2] * qd[1];
            let x1723 = q[1] * qd[2];
            let x1755 = qd[2] * qd[3];
            let x1758 = qd[1] * qd[4];
            let x1761 = qd[2] * qd[4];
            let x1764 = qd[1] * qd[3];
            let x1808 = x297.sqrt();
            let x1809 = x1808 - 1.0;
            let x1818 = 2.0 * x1808;
            let x1819 = 1.0 / x1818;
            let x1820 = x304 * x1819;
            let x1859 = 2.0 * x307;
            let x1860 = x307 * x1859;
            let x1861 = 0.01 * x1860;
            let x1862 = x621 + x1861;
            let x1863 = x549 + x1862;
            let x1864 = 0.5 * x1863;
            let x1865 = x298 * 0.04;
            let x1866 = x1864 + x1865;
            let x1867 = 2.0 * x305;
            let x1868 = x307 * x1867;
            let x1869 = 0.01 * x1868;
            let x1870 = x1869 - x612;
            let x1871 = x569 + x1870;
            let x1872 = 0.5 * x1871;
            let x1874 = 0.04 * x1675;
            let x1875 = x1874 - x1872;
            let x1876 = x307 * x541;
            let x1877 = 0.01 * x1876;
            let x1878 = x123 * x1867;
            let x1879 = 0.01 * x1878;
            let x1880 = x124 * x1859;
            let x1881 = 0.01 * x1880;
            let x1883 = x1877 + x1879;
            let x1884 = x1883 - x1881;
            let x1885 = 0.5 * x1884;
            let x1887 = 0.04 * x1672;
            let x1888 = x1887 - x1885;
            let x1889 = x307 * x567;
            let x1890 = 0.01 * x1889;
            let x1892 = x123 * x1859;
            let x1893 = 0.01 * x1892;
            let x1894 = x124 * x1867;
            let x1895 = 0.01 * x1894;
            let x1896 = x1893 - x1890;
            let x1897 = x1895 + x1896;
            let x1898 = 0.5 * x1897;
            let x1900 = 0.04 * x1668;
            let x1901 = x1900 - x1898;
            let x1902 = x305 * x1859;
            let x1903 = 0.01 * x1902;
            let x1905 = x569 - x1903;
            let x1906 = x1905 - x612;
            let x1907 = 0.5 * x1906;
            let x1908 = x1874 + x1907;
            let x1909 = x305 * x1867;
            let x1910 = 0.01 * x1909;
            let x1911 = x549 + x1910;
            let x1912 = x621 + x1911;
            let x1913 = 0.5 * x1912;
            let x1914 = x299 * 0.04;
            let x1915 = x1913 + x1914;
            let x1916 = x305 * x541;
            let x1917 = 0.01 * x1916;
            let x1920 = x1917 - x1895;
            let x1921 = x1920 - x1893;
            let x1922 = 0.5 * x1921;
            let x1923 = 0.04 * x1666;
            let x1924 = x1922 + x1923;
            let x1925 = x305 * x567;
            let x1926 = 0.01 * x1925;
            let x1927 = x1881 + x1926;
            let x1929 = x1879 - x1927;
            let x1930 = 0.5 * x1929;
            let x1931 = 0.04 * x1670;
            let x1932 = x1930 + x1931;
            let x1933 = x1877 - x1927;
            let x1934 = 0.5 * x1933;
            let x1935 = x1887 + x1934;
            let x1937 = x1895 - x1917;
            let x1938 = x1937 - x1890;
            let x1939 = 0.5 * x1938;
            let x1940 = x1923 + x1939;
            let x1941 = x1861 + x1911;
            let x1942 = 0.5 * x1941;
            let x1943 = x565 + x1942;
            let x1945 = x1903 - x569;
            let x1946 = x1945 - x1869;
            let x1947 = 0.5 * x1946;
            let x1948 = x580 + x1947;
            let x1949 = x1896 - x1917;
            let x1950 = 0.5 * x1949;
            let x1951 = x1900 + x1950;
            let x1953 = x1926 - x1883;
            let x1954 = 0.5 * x1953;
            let x1955 = x1931 + x1954;
            let x1956 = x1870 - x1903;
            let x1957 = 0.5 * x1956;
            let x1958 = x580 + x1957;
            let x1959 = x1862 + x1910;
            let x1960 = 0.5 * x1959;
            let x1961 = x625 + x1960;
            let x1962 = 2.0 * s[22];
            let x1963 = 2.0 * s[23];
            let x1964 = 0.1 * x555;
            let x1965 = s[22] * x1962;
            let x1967 = s[23] * x1963;
            let x1968 = 0.3 * x1967;
            let x1974 = 0.1 * x574;
            let x1975 = s[22] * x1963;
            let x1978 = s[23] * x1962;
            let x1979 = 0.3 * x1978;
            let x1986 = s[8] * x1963;
            let x1987 = 0.1 * x1986;
            let x1988 = x543 * s[22];
            let x1990 = s[14] * s[23];
            let x1991 = 0.3 * x1990;
            let x1999 = s[8] * x1962;
            let x2000 = 0.1 * x1999;
            let x2002 = s[14] * s[22];
            let x2004 = x543 * s[23];
            let x2005 = 0.3 * x2004;
            let x2012 = 0.1 * x570;
            let x2015 = 0.3 * x1975;
            let x2021 = 0.1 * x551;
            let x2023 = 0.3 * x1965;
            let x2029 = s[7] * x1963;
            let x2030 = 0.1 * x2029;
            let x2033 = 0.3 * x2002;
            let x2040 = s[7] * x1962;
            let x2041 = 0.1 * x2040;
            let x2043 = 0.3 * x1988;
            let x2050 = 0.1 * x1990;
            let x2052 = 0.3 * x1986;
            let x2058 = 0.1 * x2004;
            let x2061 = 0.3 * x1999;
            let x2067 = 0.1 * x1967;
            let x2069 = 0.3 * x555;
            let x2075 = 0.1 * x1978;
            let x2078 = 0.3 * x574;
            let x2085 = 0.1 * x2002;
            let x2088 = 0.3 * x2029;
            let x2094 = 0.1 * x1988;
            let x2096 = 0.3 * x2040;
            let x2102 = 0.1 * x1975;
            let x2105 = 0.3 * x570;
            let x2111 = 0.1 * x1965;
            let x2113 = 0.3 * x551;
            let x2122 = x303 * x1819;
            let x2127 = s[22] * s[34];
            let x2128 = x543 * s[39];
            let x2129 = x2127 + x2128;
            let x2130 = s[58] * x2129;
            let x2147 = s[4] * s[22];
            let x2160 = x1723 - x1722;
            let x2161 = x177 + x2160;
            let x2162 = x2161 - x178;
            let x2163 = 2.0 * x2162;
            let x2164 = x1713 + x1717;
            let x2166 = x1718 - x2164;
            let x2167 = x1714 + x2166;
            let x2168 = 2.0 * x2167;
            let x2171 = x1705 - x1709;
            let x2172 = x2171 - x1706;
            let x2173 = x1710 + x2172;
            let x2174 = 2.0 * x2173;
            let x2175 = 2.0 * x2163;
            let x2176 = 2.0 * x2168;
            let x2177 = 2.0 * x2174;
            let x2178 = x1761 + x1764;
            let x2180 = x1764 - x2178;
            let x2181 = x1761 + x2180;
            let x2182 = 2.0 * x2181;
            let x2185 = x1755 - x1758;
            let x2186 = x2185 - x1755;
            let x2187 = x1758 + x2186;
            let x2188 = 2.0 * x2187;
            let x2189 = 2.0 * x2182;
            let x2190 = 2.0 * x2188;
            let x2191 = x472 * x2175;
            let x2192 = 0.01 * x2191;
            let x2193 = x216 * x2176;
            let x2194 = x123 * x2189;
            let x2195 = x2193 + x2194;
            let x2196 = 0.01 * x2195;
            let x2197 = x217 * x2177;
            let x2198 = x124 * x2190;
            let x2199 = x2197 + x2198;
            let x2200 = 0.01 * x2199;
            let x2201 = x2192 + x2196;
            let x2202 = x2200 + x2201;
            let x2203 = 0.5 * x2202;
            let x2204 = x470 * x2175;
            let x2205 = 0.01 * x2204;
            let x2206 = x217 * x2176;
            let x2207 = x124 * x2189;
            let x2208 = x2206 + x2207;
            let x2209 = 0.01 * x2208;
            let x2211 = x216 * x2177;
            let x2212 = x123 * x2190;
            let x2213 = x2211 + x2212;
            let x2214 = 0.01 * x2213;
            let x2215 = x2205 - x2209;
            let x2216 = x2214 + x2215;
            let x2217 = 0.5 * x2216;
            let x2218 = x217 * x2175;
            let x2219 = 0.01 * x2218;
            let x2220 = x470 * x2176;
            let x2221 = x305 * x2189;
            let x2222 = x2220 + x2221;
            let x2223 = 0.01 * x2222;
            let x2224 = x472 * x2177;
            let x2225 = x307 * x2190;
            let x2226 = x2224 + x2225;
            let x2227 = 0.01 * x2226;
            let x2229 = x2219 + x2223;
            let x2230 = x2229 - x2227;
            let x2231 = 0.5 * x2230;
            let x2232 = x216 * x2175;
            let x2233 = 0.01 * x2232;
            let x2235 = x472 * x2176;
            let x2236 = x307 * x2189;
            let x2237 = x2235 + x2236;
            let x2238 = 0.01 * x2237;
            let x2239 = x470 * x2177;
            let x2240 = x305 * x2190;
            let x2241 = x2239 + x2240;
            let x2242 = 0.01 * x2241;
            let x2243 = x2238 - x2233;
            let x2244 = x2242 + x2243;
            let x2245 = 0.5 * x2244;
            let x2246 = x453 + x457;
            let x2247 = x754 + x2246;
            let x2248 = x755 + x2247;
            let x2249 = 0.01 * x2193;
            let x2250 = 0.01 * x2197;
            let x2251 = x2192 + x2249;
            let x2252 = x2250 + x2251;
            let x2253 = 0.5 * x2252;
            let x2254 = x2203 + x2253;
            let x2255 = q[1] * 0.04;
            let x2256 = x2248 * x2255;
            let x2258 = x2254 - x2256;
            let x2260 = 0.01 * x2206;
            let x2261 = 0.01 * x2211;
            let x2263 = x2260 - x2205;
            let x2264 = x2263 - x2261;
            let x2265 = 0.5 * x2264;
            let x2267 = x2265 - x2217;
            let x2268 = q[2] * 0.04;
            let x2269 = x2248 * x2268;
            let x2271 = x2267 - x2269;
            let x2272 = 0.01 * x2220;
            let x2273 = 0.01 * x2224;
            let x2274 = x2219 + x2272;
            let x2276 = x2273 - x2274;
            let x2277 = 0.5 * x2276;
            let x2279 = x2277 - x2231;
            let x2280 = x767 * x2248;
            let x2282 = x2279 - x2280;
            let x2283 = 0.01 * x2235;
            let x2285 = 0.01 * x2239;
            let x2287 = x2233 - x2283;
            let x2288 = x2287 - x2285;
            let x2289 = 0.5 * x2288;
            let x2291 = x2289 - x2245;
            let x2292 = x786 * x2248;
            let x2294 = x2291 - x2292;
            let x2327 = s[13] * s[72];
            let x2328 = 0.1 * x2327;
            let x2329 = s[19] * s[73];
            let x2330 = s[22] * s[85];
            let x2331 = x2329 + x2330;
            let x2333 = s[20] * s[74];
            let x2334 = s[23] * s[86];
            let x2335 = x2333 + x2334;
            let x2336 = 0.3 * x2335;
            let x2386 = 0.3 * x2333;
            let x2450 = x1820 * k[0];
            let x2452 = x5 - x2450;
            let x2461 = x1965 * k[2];
            let x2462 = x1964 + x2461;
            let x2463 = x1968 + x2462;
            let x2464 = 0.5 * x2463;
            let x2465 = s[5] * k[8];
            let x2466 = x2464 + x2465;
            let x2467 = x1975 * k[2];
            let x2469 = x1974 - x2467;
            let x2470 = x1979 + x2469;
            let x2471 = 0.5 * x2470;
            let x2473 = x50 * k[8];
            let x2474 = x2473 - x2471;
            let x2475 = x1988 * k[2];
            let x2476 = x1987 + x2475;
            let x2477 = x2476 - x1991;
            let x2478 = 0.5 * x2477;
            let x2480 = s[37] * k[8];
            let x2481 = x2480 - x2478;
            let x2482 = x2002 * k[2];
            let x2483 = x2482 - x2000;
            let x2484 = x2005 + x2483;
            let x2485 = 0.5 * x2484;
            let x2487 = x1685 * k[8];
            let x2488 = x2487 - x2485;
            let x2489 = x1978 * k[2];
            let x2490 = x2489 - x2012;
            let x2491 = x2490 - x2015;
            let x2492 = 0.5 * x2491;
            let x2493 = x2473 + x2492;
            let x2494 = x1967 * k[2];
            let x2495 = x2021 + x2494;
            let x2496 = x2023 + x2495;
            let x2497 = 0.5 * x2496;
            let x2498 = s[6] * k[8];
            let x2499 = x2497 + x2498;
            let x2500 = x2004 * k[2];
            let x2502 = x2030 - x2500;
            let x2503 = x2502 - x2033;
            let x2504 = 0.5 * x2503;
            let x2505 = x1683 * k[8];
            let x2506 = x2504 + x2505;
            let x2507 = x1990 * k[2];
            let x2508 = x2041 + x2507;
            let x2510 = x2043 - x2508;
            let x2511 = 0.5 * x2510;
            let x2512 = s[35] * k[8];
            let x2513 = x2511 + x2512;
            let x2514 = x2040 * k[2];
            let x2515 = x2050 + x2514;
            let x2517 = x2052 - x2515;
            let x2518 = 0.5 * x2517;
            let x2519 = x2480 + x2518;
            let x2520 = x2029 * k[2];
            let x2522 = x2058 - x2520;
            let x2523 = x2522 - x2061;
            let x2524 = 0.5 * x2523;
            let x2525 = x2505 + x2524;
            let x2526 = x551 * k[2];
            let x2527 = x2067 + x2526;
            let x2528 = x2069 + x2527;
            let x2529 = 0.5 * x2528;
            let x2530 = x1680 * k[8];
            let x2531 = x2529 + x2530;
            let x2532 = x570 * k[2];
            let x2533 = x2532 - x2075;
            let x2534 = x2533 - x2078;
            let x2535 = 0.5 * x2534;
            let x2536 = x1689 * k[8];
            let x2537 = x2535 + x2536;
            let x2538 = x1999 * k[2];
            let x2540 = x2085 - x2538;
            let x2541 = x2540 - x2088;
            let x2542 = 0.5 * x2541;
            let x2543 = x2487 + x2542;
            let x2544 = x1986 * k[2];
            let x2545 = x2094 + x2544;
            let x2547 = x2096 - x2545;
            let x2548 = 0.5 * x2547;
            let x2549 = x2512 + x2548;
            let x2550 = x574 * k[2];
            let x2551 = x2550 - x2102;
            let x2552 = x2551 - x2105;
            let x2553 = 0.5 * x2552;
            let x2554 = x2536 + x2553;
            let x2555 = x555 * k[2];
            let x2556 = x2111 + x2555;
            let x2557 = x2113 + x2556;
            let x2558 = 0.5 * x2557;
            let x2559 = x1681 * k[8];
            let x2560 = x2558 + x2559;
            let x2561 = x1809 * k[3];
            let x2563 = x2452 - x2561;
            let x2564 = x2122 * x2563;
            let x2568 = x2130 * s[93];
            let x2572 = 1.0 + x2564;
            let x2573 = x2568 - x2147;
            let x2578 = x2331 * k[2];
            let x2579 = x2328 + x2578;
            let x2580 = x2336 + x2579;
            let x2581 = 0.5 * x2580;
            let x2595 = x2329 * k[2];
            let x2596 = x2328 + x2595;
            let x2597 = x2386 + x2596;
            let x2598 = 0.5 * x2597;
            let x2599 = x2581 + x2598;
            let x2600 = q[5] * k[8];
            let x2601 = s[89] * x2600;
            let x2603 = x2599 - x2601;
            let x2636 = x2573 + x2603;
            phi[0] = x1674;
            phi_q[0] = x124;
            phi_q[1] = x123;
            phi_q[2] = x307;
            phi_q[3] = x305;
            phi[1] = x1678;
            phi_q[4] = x128;
            phi_q[5] = x124;
            phi_q[6] = x1699;
            phi_q[7] = x307;
            phi[2] = x1679;
            phi_q[8] = x307;
            phi_q[9] = x305;
            phi_q[10] = x124;
            phi_q[11] = x123;
            phi[3] = x1688;
            phi_q[12] = x1702;
            phi_q[13] = s[22];
            phi_q[14] = s[8];
            phi_q[15] = x127;
            phi[4] = x1692;
            phi_q[16] = x483;
            phi_q[17] = x127;
            phi_q[18] = x1702;
            phi_q[19] = x1703;
            phi[5] = x1695;
            phi_q[20] = x305;
            phi_q[21] = x307;
            phi_q[22] = x123;
            phi_q[23] = x124;
            phi[6] = x1698;
            phi_q[24] = s[7];
            phi_q[25] = s[8];
            phi_q[26] = s[22];
            phi_q[27] = s[23];
            mass[0] = k[7];
            mass[1] = x1866;
            mass[2] = x1875;
            mass[3] = x1888;
            mass[4] = x1901;
            mass[5] = x1908;
            mass[6] = x1915;
            mass[7] = x1924;
            mass[8] = x1932;
            mass[9] = x1935;
            mass[10] = x1940;
            mass[11] = x1943;
            mass[12] = x1948;
            mass[13] = x1951;
            mass[14] = x1955;
            mass[15] = x1958;
            mass[16] = x1961;
            mass[17] = x2466;
            mass[18] = x2474;
            mass[19] = x2481;
            mass[20] = x2488;
            mass[21] = x2493;
            mass[22] = x2499;
            mass[23] = x2506;
            mass[24] = x2513;
            mass[25] = x2519;
            mass[26] = x2525;
            mass[27] = x2531;
            mass[28] = x2537;
            mass[29] = x2543;
            mass[30] = x2549;
            mass[31] = x2554;
            mass[32] = x2560;
            force[0] = x2572;
            force[1] = x2258;
            force[2] = x2271;
            force[3] = x2282;
            force[4] = x2294;
            force[5] = x2636;
        }
        #[inline(never)]
        fn eval_newton_part_1(
            k: &[f64; 9],
            q: &[f64; 9],
            qd: &[f64; 9],
            s: &[f64; 94],
            force: &mut [f64; 9],
        ) {
            let x218 = 2.0 * qd[5];
            let x2131 = s[23] * s[34];
            let x2133 = s[14] * s[39];
            let x2134 = x2133 - x2131;
            let x2135 = s[58] * x2134;
            let x2136 = s[7] * s[34];
            let x2137 = s[58] * x2136;
            let x2138 = s[8] * s[34];
            let x2139 = s[58] * x2138;
            let x2149 = s[4] * s[23];
            let x2150 = s[4] * s[7];
            let x2151 = s[4] * s[8];
            let x2340 = x218 * s[72];
            let x2341 = 0.1 * x2340;
            let x2342 = s[20] * s[73];
            let x2343 = s[23] * s[85];
            let x2344 = x2342 + x2343;
            let x2347 = s[19] * s[74];
            let x2348 = s[22] * s[86];
            let x2349 = x2347 + x2348;
            let x2350 = 0.3 * x2349;
            let x2354 = s[20] * s[72];
            let x2355 = 0.1 * x2354;
            let x2356 = x218 * s[73];
            let x2357 = s[7] * s[85];
            let x2358 = x2356 + x2357;
            let x2360 = s[13] * s[74];
            let x2361 = s[8] * s[86];
            let x2362 = x2360 + x2361;
            let x2363 = 0.3 * x2362;
            let x2368 = s[19] * s[72];
            let x2369 = 0.1 * x2368;
            let x2371 = s[13] * s[73];
            let x2372 = s[8] * s[85];
            let x2373 = x2371 + x2372;
            let x2375 = x218 * s[74];
            let x2376 = s[7] * s[86];
            let x2377 = x2375 + x2376;
            let x2378 = 0.3 * x2377;
            let x2397 = 0.3 * x2347;
            let x2409 = 0.3 * x2360;
            let x2422 = 0.3 * x2375;
            let x2569 = x2135 * s[93];
            let x2570 = x2137 * s[93];
            let x2571 = x2139 * s[93];
            let x2574 = x2149 + x2569;
            let x2575 = x2150 + x2570;
            let x2576 = x2151 + x2571;
            let x2582 = x2344 * k[2];
            let x2584 = x2341 - x2582;
            let x2585 = x2350 + x2584;
            let x2586 = 0.5 * x2585;
            let x2587 = x2358 * k[2];
            let x2588 = x2355 + x2587;
            let x2589 = x2588 - x2363;
            let x2590 = 0.5 * x2589;
            let x2591 = x2373 * k[2];
            let x2592 = x2591 - x2369;
            let x2593 = x2378 + x2592;
            let x2594 = 0.5 * x2593;
            let x2604 = x2342 * k[2];
            let x2605 = x2604 - x2341;
            let x2606 = x2605 - x2397;
            let x2607 = 0.5 * x2606;
            let x2609 = x2607 - x2586;
            let x2610 = q[6] * k[8];
            let x2611 = s[89] * x2610;
            let x2613 = x2609 - x2611;
            let x2614 = x2356 * k[2];
            let x2615 = x2355 + x2614;
            let x2617 = x2409 - x2615;
            let x2618 = 0.5 * x2617;
            let x2620 = x2618 - x2590;
            let x2621 = q[7] * k[8];
            let x2622 = s[89] * x2621;
            let x2624 = x2620 - x2622;
            let x2625 = x2371 * k[2];
            let x2627 = x2369 - x2625;
            let x2628 = x2627 - x2422;
            let x2629 = 0.5 * x2628;
            let x2631 = x2629 - x2594;
            let x2632 = q[8] * k[8];
            let x2633 = s[89] * x2632;
            let x2635 = x2631 - x2633;
            let x2637 = x2574 + x2613;
            let x2638 = x2575 + x2624;
            let x2639 = x2635 - x2576;
            force[6] = x2637;
            force[7] = x2638;
            force[8] = x2639;
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
        Parameters::at(set).map(ExactAt)
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
