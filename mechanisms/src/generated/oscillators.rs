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
    BodyInfo, Formulation, JointInfo, JointKind, KinematicOutputs, Mechanism,
    MechanismInfo, NewtonOutputs, PlatformInfo, Reduction, Substitution, Rotation,
};
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
pub fn potential_into(q: &[f64], out: &mut [f64]) {
    let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    potential_into_part_0(q, out);
}
#[inline(never)]
fn potential_into_part_0(q: &[f64; 14], out: &mut [f64; 1]) {
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
    let x283 = q[1] * 19.62;
    let x285 = q[8] * 9.81;
    let x286 = 1.0 + q[0];
    let x287 = x286 * x286;
    let x288 = q[1] * q[1];
    let x289 = q[2] * q[2];
    let x290 = x287 + x288;
    let x291 = x289 + x290;
    let x292 = x291.sqrt();
    let x304 = x292 - 1.0;
    let x314 = x304 * x304;
    let x315 = 25.0 * x314;
    let x323 = -x103;
    let x324 = x323.atan2(x74);
    let x353 = x324 * x324;
    let x414 = x283 + x285;
    let x415 = x315 + x414;
    let x416 = x353 + x415;
    out[0] = x416;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
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
    let x286 = 1.0 + q[0];
    let x287 = x286 * x286;
    let x288 = q[1] * q[1];
    let x289 = q[2] * q[2];
    let x290 = x287 + x288;
    let x291 = x289 + x290;
    let x292 = x291.sqrt();
    let x293 = 2.0 * x286;
    let x294 = qd[0] * x293;
    let x295 = q[1] * 2.0;
    let x296 = qd[1] * x295;
    let x297 = q[2] * 2.0;
    let x298 = qd[2] * x297;
    let x299 = x294 + x296;
    let x300 = x298 + x299;
    let x301 = 2.0 * x292;
    let x302 = 1.0 / x301;
    let x303 = x300 * x302;
    let x308 = x303 * 0.8;
    let x310 = x5 - x308;
    let x316 = x303 * x310;
    let x325 = 2.0 * x188;
    let x326 = q[13] * qd[11];
    let x327 = q[11] * qd[13];
    let x328 = x326 + x327;
    let x329 = 2.0 * x328;
    let x330 = q[12] * qd[10];
    let x331 = q[10] * qd[12];
    let x332 = x330 + x331;
    let x333 = 2.0 * x332;
    let x335 = x329 - x333;
    let x337 = x74 * x74;
    let x338 = x103 * x103;
    let x339 = x337 + x338;
    let x340 = x74 * x335;
    let x342 = x103 * x325;
    let x344 = x342 - x340;
    let x345 = 1.0 / x339;
    let x346 = x344 * x345;
    let x348 = 0.1 * x346;
    let x350 = x11 - x348;
    let x354 = x346 * x350;
    let x387 = x326 - x330;
    let x388 = x331 + x387;
    let x389 = x388 - x327;
    let x390 = 2.0 * x389;
    let x398 = x14 * x390;
    let x417 = qd[0] + x316;
    let x418 = x354 + x417;
    let x419 = x398 + x418;
    out[0] = x419;
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
        bodies: &BODIES,
        joints: &JOINTS,
        coord_names: &COORD_NAMES,
        row_names: &ROW_NAMES,
        q0: &Q0,
        qd0: &QD0,
        redundant_rows: &REDUNDANT_ROWS,
        platform: PLATFORM,
    };
    /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
    pub fn mass(q: &[f64], out: &mut [f64]) {
        let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 38] = out.try_into().expect("out must have 38 entries");
        mass_part_0(q, out);
    }
    #[inline(never)]
    fn mass_part_0(q: &[f64; 14], out: &mut [f64; 38]) {
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
        let x355 = 2.0 * x129;
        let x361 = 2.0 * x130;
        let x527 = 2.0 * x124;
        let x529 = 2.0 * x125;
        let x531 = 2.0 * x126;
        let x533 = x124 * x527;
        let x535 = 0.01 * x533;
        let x537 = x125 * x529;
        let x539 = 0.01 * x537;
        let x541 = x126 * x531;
        let x543 = 0.01 * x541;
        let x545 = x535 + x539;
        let x547 = x543 + x545;
        let x549 = 0.5 * x547;
        let x551 = x23 * 0.04;
        let x552 = x549 + x551;
        let x553 = 2.0 * x123;
        let x554 = x124 * x553;
        let x555 = 0.01 * x554;
        let x556 = x125 * x531;
        let x558 = 0.01 * x556;
        let x560 = x126 * x529;
        let x561 = 0.01 * x560;
        let x562 = x555 - x558;
        let x563 = x561 + x562;
        let x564 = 0.5 * x563;
        let x566 = x52 * 0.04;
        let x567 = x566 - x564;
        let x568 = x124 * x531;
        let x569 = 0.01 * x568;
        let x570 = x125 * x553;
        let x571 = 0.01 * x570;
        let x572 = x126 * x527;
        let x574 = 0.01 * x572;
        let x576 = x569 + x571;
        let x577 = x576 - x574;
        let x578 = 0.5 * x577;
        let x580 = x46 * 0.04;
        let x581 = x580 - x578;
        let x582 = x124 * x529;
        let x584 = 0.01 * x582;
        let x586 = x125 * x527;
        let x587 = 0.01 * x586;
        let x588 = x126 * x553;
        let x589 = 0.01 * x588;
        let x590 = x587 - x584;
        let x591 = x589 + x590;
        let x592 = 0.5 * x591;
        let x594 = x39 * 0.04;
        let x595 = x594 - x592;
        let x596 = x123 * x527;
        let x598 = 0.01 * x596;
        let x602 = x561 - x598;
        let x603 = x602 - x558;
        let x604 = 0.5 * x603;
        let x605 = x566 + x604;
        let x606 = x123 * x553;
        let x607 = 0.01 * x606;
        let x608 = x543 + x607;
        let x609 = x539 + x608;
        let x610 = 0.5 * x609;
        let x611 = x24 * 0.04;
        let x612 = x610 + x611;
        let x613 = x123 * x531;
        let x614 = 0.01 * x613;
        let x618 = x614 - x589;
        let x619 = x618 - x587;
        let x620 = 0.5 * x619;
        let x621 = x37 * 0.04;
        let x622 = x620 + x621;
        let x623 = x123 * x529;
        let x625 = 0.01 * x623;
        let x627 = x574 + x625;
        let x629 = x571 - x627;
        let x630 = 0.5 * x629;
        let x631 = x44 * 0.04;
        let x632 = x630 + x631;
        let x635 = x569 - x627;
        let x636 = 0.5 * x635;
        let x637 = x580 + x636;
        let x640 = x589 - x614;
        let x641 = x640 - x584;
        let x642 = 0.5 * x641;
        let x643 = x621 + x642;
        let x644 = x535 + x608;
        let x645 = 0.5 * x644;
        let x646 = x25 * 0.04;
        let x647 = x645 + x646;
        let x649 = x598 - x561;
        let x650 = x649 - x555;
        let x651 = 0.5 * x650;
        let x652 = x50 * 0.04;
        let x653 = x651 + x652;
        let x654 = x590 - x614;
        let x655 = 0.5 * x654;
        let x656 = x594 + x655;
        let x659 = x625 - x576;
        let x660 = 0.5 * x659;
        let x661 = x631 + x660;
        let x662 = x562 - x598;
        let x663 = 0.5 * x662;
        let x664 = x652 + x663;
        let x665 = x545 + x607;
        let x666 = 0.5 * x665;
        let x667 = x26 * 0.04;
        let x668 = x666 + x667;
        let x906 = 2.0 * x131;
        let x908 = 2.0 * x132;
        let x910 = x130 * x361;
        let x912 = 0.1 * x910;
        let x914 = x131 * x906;
        let x916 = 0.2 * x914;
        let x918 = x132 * x908;
        let x920 = 0.3 * x918;
        let x922 = x912 + x916;
        let x924 = x920 + x922;
        let x926 = 0.5 * x924;
        let x928 = x68 * 0.8000000000000002;
        let x929 = x926 + x928;
        let x930 = x130 * x355;
        let x931 = 0.1 * x930;
        let x932 = x131 * x908;
        let x934 = 0.2 * x932;
        let x936 = x132 * x906;
        let x937 = 0.3 * x936;
        let x938 = x931 - x934;
        let x939 = x937 + x938;
        let x940 = 0.5 * x939;
        let x942 = x96 * 0.8000000000000002;
        let x943 = x942 - x940;
        let x944 = x130 * x908;
        let x945 = 0.1 * x944;
        let x946 = x131 * x355;
        let x947 = 0.2 * x946;
        let x948 = x132 * x361;
        let x950 = 0.3 * x948;
        let x952 = x945 + x947;
        let x953 = x952 - x950;
        let x954 = 0.5 * x953;
        let x956 = x90 * 0.8000000000000002;
        let x957 = x956 - x954;
        let x958 = x130 * x906;
        let x960 = 0.1 * x958;
        let x962 = x131 * x361;
        let x963 = 0.2 * x962;
        let x964 = x132 * x355;
        let x965 = 0.3 * x964;
        let x966 = x963 - x960;
        let x967 = x965 + x966;
        let x968 = 0.5 * x967;
        let x970 = x83 * 0.8000000000000002;
        let x971 = x970 - x968;
        let x972 = x129 * x361;
        let x974 = 0.1 * x972;
        let x977 = 0.2 * x936;
        let x979 = 0.3 * x932;
        let x981 = x977 - x974;
        let x982 = x981 - x979;
        let x983 = 0.5 * x982;
        let x984 = x942 + x983;
        let x985 = x129 * x355;
        let x986 = 0.1 * x985;
        let x987 = 0.2 * x918;
        let x989 = 0.3 * x914;
        let x990 = x986 + x987;
        let x991 = x989 + x990;
        let x992 = 0.5 * x991;
        let x993 = x69 * 0.8000000000000002;
        let x994 = x992 + x993;
        let x995 = x129 * x908;
        let x996 = 0.1 * x995;
        let x997 = 0.2 * x964;
        let x1000 = 0.3 * x962;
        let x1002 = x996 - x997;
        let x1003 = x1002 - x1000;
        let x1004 = 0.5 * x1003;
        let x1005 = x81 * 0.8000000000000002;
        let x1006 = x1004 + x1005;
        let x1007 = x129 * x906;
        let x1009 = 0.1 * x1007;
        let x1011 = 0.2 * x948;
        let x1013 = 0.3 * x946;
        let x1014 = x1009 + x1011;
        let x1016 = x1013 - x1014;
        let x1017 = 0.5 * x1016;
        let x1018 = x88 * 0.8000000000000002;
        let x1019 = x1017 + x1018;
        let x1020 = 0.1 * x948;
        let x1022 = 0.2 * x1007;
        let x1025 = 0.3 * x944;
        let x1027 = x1020 + x1022;
        let x1029 = x1025 - x1027;
        let x1030 = 0.5 * x1029;
        let x1031 = x956 + x1030;
        let x1032 = 0.1 * x964;
        let x1034 = 0.2 * x995;
        let x1036 = 0.3 * x958;
        let x1038 = x1032 - x1034;
        let x1039 = x1038 - x1036;
        let x1040 = 0.5 * x1039;
        let x1041 = x1005 + x1040;
        let x1042 = 0.1 * x918;
        let x1043 = 0.2 * x985;
        let x1044 = 0.3 * x910;
        let x1046 = x1042 + x1043;
        let x1047 = x1044 + x1046;
        let x1048 = 0.5 * x1047;
        let x1049 = x70 * 0.8000000000000002;
        let x1050 = x1048 + x1049;
        let x1051 = 0.1 * x936;
        let x1053 = 0.2 * x972;
        let x1054 = 0.3 * x930;
        let x1056 = x1053 - x1051;
        let x1057 = x1056 - x1054;
        let x1058 = 0.5 * x1057;
        let x1059 = x94 * 0.8000000000000002;
        let x1060 = x1058 + x1059;
        let x1061 = 0.1 * x962;
        let x1063 = 0.2 * x958;
        let x1065 = 0.3 * x995;
        let x1067 = x1061 - x1063;
        let x1068 = x1067 - x1065;
        let x1069 = 0.5 * x1068;
        let x1070 = x970 + x1069;
        let x1071 = 0.1 * x946;
        let x1073 = 0.2 * x944;
        let x1075 = 0.3 * x1007;
        let x1076 = x1071 + x1073;
        let x1078 = x1075 - x1076;
        let x1079 = 0.5 * x1078;
        let x1080 = x1018 + x1079;
        let x1081 = 0.1 * x932;
        let x1083 = 0.2 * x930;
        let x1084 = 0.3 * x972;
        let x1086 = x1083 - x1081;
        let x1087 = x1086 - x1084;
        let x1088 = 0.5 * x1087;
        let x1089 = x1059 + x1088;
        let x1090 = 0.1 * x914;
        let x1092 = 0.2 * x910;
        let x1093 = 0.3 * x985;
        let x1094 = x1090 + x1092;
        let x1095 = x1093 + x1094;
        let x1096 = 0.5 * x1095;
        let x1097 = x71 * 0.8000000000000002;
        let x1098 = x1096 + x1097;
        out[0] = 2.0;
        out[1] = 2.0;
        out[2] = 2.0;
        out[3] = x552;
        out[4] = x567;
        out[5] = x581;
        out[6] = x595;
        out[7] = x605;
        out[8] = x612;
        out[9] = x622;
        out[10] = x632;
        out[11] = x637;
        out[12] = x643;
        out[13] = x647;
        out[14] = x653;
        out[15] = x656;
        out[16] = x661;
        out[17] = x664;
        out[18] = x668;
        out[19] = 1.0;
        out[20] = 1.0;
        out[21] = 1.0;
        out[22] = x929;
        out[23] = x943;
        out[24] = x957;
        out[25] = x971;
        out[26] = x984;
        out[27] = x994;
        out[28] = x1006;
        out[29] = x1019;
        out[30] = x1031;
        out[31] = x1041;
        out[32] = x1050;
        out[33] = x1060;
        out[34] = x1070;
        out[35] = x1080;
        out[36] = x1089;
        out[37] = x1098;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 14] = out.try_into().expect("out must have 14 entries");
        force_part_0(q, qd, t, out);
    }
    #[inline(never)]
    fn force_part_0(q: &[f64; 14], qd: &[f64; 14], t: f64, out: &mut [f64; 14]) {
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
        let x286 = 1.0 + q[0];
        let x287 = x286 * x286;
        let x288 = q[1] * q[1];
        let x289 = q[2] * q[2];
        let x290 = x287 + x288;
        let x291 = x289 + x290;
        let x292 = x291.sqrt();
        let x293 = 2.0 * x286;
        let x294 = qd[0] * x293;
        let x295 = q[1] * 2.0;
        let x296 = qd[1] * x295;
        let x297 = q[2] * 2.0;
        let x298 = qd[2] * x297;
        let x299 = x294 + x296;
        let x300 = x298 + x299;
        let x301 = 2.0 * x292;
        let x302 = 1.0 / x301;
        let x303 = x300 * x302;
        let x304 = x292 - 1.0;
        let x307 = x304 * 50.0;
        let x308 = x303 * 0.8;
        let x310 = x5 - x308;
        let x312 = x310 - x307;
        let x317 = x293 * x302;
        let x318 = x295 * x302;
        let x319 = x297 * x302;
        let x320 = x312 * x317;
        let x321 = x312 * x318;
        let x322 = x312 * x319;
        let x323 = -x103;
        let x324 = x323.atan2(x74);
        let x325 = 2.0 * x188;
        let x326 = q[13] * qd[11];
        let x327 = q[11] * qd[13];
        let x328 = x326 + x327;
        let x329 = 2.0 * x328;
        let x330 = q[12] * qd[10];
        let x331 = q[10] * qd[12];
        let x332 = x330 + x331;
        let x333 = 2.0 * x332;
        let x335 = x329 - x333;
        let x337 = x74 * x74;
        let x338 = x103 * x103;
        let x339 = x337 + x338;
        let x340 = x74 * x335;
        let x342 = x103 * x325;
        let x344 = x342 - x340;
        let x345 = 1.0 / x339;
        let x346 = x344 * x345;
        let x347 = 2.0 * x324;
        let x348 = 0.1 * x346;
        let x350 = x11 - x348;
        let x352 = x350 - x347;
        let x355 = 2.0 * x129;
        let x356 = x74 * x131;
        let x357 = x103 * x355;
        let x359 = x356 + x357;
        let x360 = x345 * x359;
        let x361 = 2.0 * x130;
        let x362 = x74 * x132;
        let x364 = x103 * x361;
        let x366 = x364 - x362;
        let x367 = x345 * x366;
        let x368 = x74 * x129;
        let x369 = x345 * x368;
        let x370 = x74 * x130;
        let x372 = x345 * x370;
        let x374 = x352 * x360;
        let x375 = x352 * x367;
        let x376 = x352 * x369;
        let x377 = x352 * x372;
        let x381 = x204 - x203;
        let x402 = x14 * x131;
        let x404 = x14 * x132;
        let x405 = x14 * x129;
        let x406 = x14 * x130;
        let x408 = 1.0 + x320;
        let x409 = x374 - x402;
        let x410 = x375 + x404;
        let x411 = x376 + x405;
        let x412 = x377 + x406;
        let x422 = x178 - x177;
        let x423 = x173 + x422;
        let x424 = x423 - x174;
        let x425 = 2.0 * x424;
        let x428 = x164 + x168;
        let x430 = x169 - x428;
        let x431 = x165 + x430;
        let x432 = 2.0 * x431;
        let x435 = x156 - x160;
        let x436 = x435 - x157;
        let x437 = x161 + x436;
        let x438 = 2.0 * x437;
        let x460 = 2.0 * x425;
        let x462 = 2.0 * x432;
        let x464 = 2.0 * x438;
        let x671 = x235 + x238;
        let x673 = x238 - x671;
        let x674 = x235 + x673;
        let x675 = 2.0 * x674;
        let x678 = x229 - x232;
        let x679 = x678 - x229;
        let x680 = x232 + x679;
        let x681 = 2.0 * x680;
        let x682 = 2.0 * x675;
        let x683 = 2.0 * x681;
        let x684 = x217 * x460;
        let x685 = 0.01 * x684;
        let x686 = x218 * x462;
        let x687 = x125 * x682;
        let x688 = x686 + x687;
        let x689 = 0.01 * x688;
        let x690 = x219 * x464;
        let x691 = x126 * x683;
        let x692 = x690 + x691;
        let x693 = 0.01 * x692;
        let x694 = x685 + x689;
        let x695 = x693 + x694;
        let x696 = 0.5 * x695;
        let x698 = x216 * x460;
        let x699 = 0.01 * x698;
        let x700 = x219 * x462;
        let x701 = x126 * x682;
        let x702 = x700 + x701;
        let x703 = 0.01 * x702;
        let x705 = x218 * x464;
        let x706 = x125 * x683;
        let x707 = x705 + x706;
        let x708 = 0.01 * x707;
        let x709 = x699 - x703;
        let x710 = x708 + x709;
        let x711 = 0.5 * x710;
        let x712 = x219 * x460;
        let x713 = 0.01 * x712;
        let x714 = x216 * x462;
        let x715 = x123 * x682;
        let x716 = x714 + x715;
        let x717 = 0.01 * x716;
        let x718 = x217 * x464;
        let x719 = x124 * x683;
        let x720 = x718 + x719;
        let x721 = 0.01 * x720;
        let x723 = x713 + x717;
        let x724 = x723 - x721;
        let x725 = 0.5 * x724;
        let x726 = x218 * x460;
        let x727 = 0.01 * x726;
        let x729 = x217 * x462;
        let x730 = x124 * x682;
        let x731 = x729 + x730;
        let x732 = 0.01 * x731;
        let x733 = x216 * x464;
        let x734 = x123 * x683;
        let x735 = x733 + x734;
        let x736 = 0.01 * x735;
        let x737 = x732 - x727;
        let x738 = x736 + x737;
        let x739 = 0.5 * x738;
        let x740 = qd[3] * qd[3];
        let x741 = qd[4] * qd[4];
        let x742 = qd[5] * qd[5];
        let x743 = qd[6] * qd[6];
        let x744 = x740 + x741;
        let x745 = x742 + x744;
        let x746 = x743 + x745;
        let x748 = 0.01 * x686;
        let x749 = 0.01 * x690;
        let x750 = x685 + x748;
        let x751 = x749 + x750;
        let x752 = 0.5 * x751;
        let x753 = x696 + x752;
        let x754 = q[3] * 0.04;
        let x755 = x746 * x754;
        let x757 = x753 - x755;
        let x764 = 0.01 * x700;
        let x766 = 0.01 * x705;
        let x768 = x764 - x699;
        let x769 = x768 - x766;
        let x770 = 0.5 * x769;
        let x772 = x770 - x711;
        let x773 = q[4] * 0.04;
        let x774 = x746 * x773;
        let x776 = x772 - x774;
        let x782 = 0.01 * x714;
        let x784 = 0.01 * x718;
        let x785 = x713 + x782;
        let x787 = x784 - x785;
        let x788 = 0.5 * x787;
        let x790 = x788 - x725;
        let x791 = q[5] * 0.04;
        let x792 = x746 * x791;
        let x794 = x790 - x792;
        let x798 = 0.01 * x729;
        let x801 = 0.01 * x733;
        let x803 = x727 - x798;
        let x804 = x803 - x801;
        let x805 = 0.5 * x804;
        let x807 = x805 - x739;
        let x808 = q[6] * 0.04;
        let x809 = x746 * x808;
        let x811 = x807 - x809;
        let x812 = x321 - 19.62;
        let x814 = x199 + x381;
        let x815 = x814 - x200;
        let x816 = 2.0 * x815;
        let x818 = x326 + x330;
        let x820 = x331 - x818;
        let x821 = x327 + x820;
        let x822 = 2.0 * x821;
        let x824 = x189 - x193;
        let x825 = x824 - x190;
        let x826 = x194 + x825;
        let x827 = 2.0 * x826;
        let x845 = 2.0 * x816;
        let x847 = 2.0 * x822;
        let x849 = 2.0 * x827;
        let x1099 = qd[11] * qd[13];
        let x1100 = qd[10] * qd[12];
        let x1104 = x1099 + x1100;
        let x1106 = x1100 - x1104;
        let x1107 = x1099 + x1106;
        let x1108 = 2.0 * x1107;
        let x1110 = x256 - x259;
        let x1111 = x1110 - x256;
        let x1112 = x259 + x1111;
        let x1113 = 2.0 * x1112;
        let x1114 = 2.0 * x1108;
        let x1115 = 2.0 * x1113;
        let x1116 = x221 * x845;
        let x1117 = 0.1 * x1116;
        let x1118 = x222 * x847;
        let x1119 = x131 * x1114;
        let x1120 = x1118 + x1119;
        let x1121 = 0.2 * x1120;
        let x1122 = x223 * x849;
        let x1123 = x132 * x1115;
        let x1124 = x1122 + x1123;
        let x1125 = 0.3 * x1124;
        let x1126 = x1117 + x1121;
        let x1127 = x1125 + x1126;
        let x1128 = 0.5 * x1127;
        let x1130 = x220 * x845;
        let x1131 = 0.1 * x1130;
        let x1132 = x223 * x847;
        let x1133 = x132 * x1114;
        let x1134 = x1132 + x1133;
        let x1135 = 0.2 * x1134;
        let x1137 = x222 * x849;
        let x1138 = x131 * x1115;
        let x1139 = x1137 + x1138;
        let x1140 = 0.3 * x1139;
        let x1141 = x1131 - x1135;
        let x1142 = x1140 + x1141;
        let x1143 = 0.5 * x1142;
        let x1144 = x223 * x845;
        let x1145 = 0.1 * x1144;
        let x1146 = x220 * x847;
        let x1147 = x129 * x1114;
        let x1148 = x1146 + x1147;
        let x1149 = 0.2 * x1148;
        let x1150 = x221 * x849;
        let x1151 = x130 * x1115;
        let x1152 = x1150 + x1151;
        let x1153 = 0.3 * x1152;
        let x1155 = x1145 + x1149;
        let x1156 = x1155 - x1153;
        let x1157 = 0.5 * x1156;
        let x1158 = x222 * x845;
        let x1159 = 0.1 * x1158;
        let x1161 = x221 * x847;
        let x1162 = x130 * x1114;
        let x1163 = x1161 + x1162;
        let x1164 = 0.2 * x1163;
        let x1165 = x220 * x849;
        let x1166 = x129 * x1115;
        let x1167 = x1165 + x1166;
        let x1168 = 0.3 * x1167;
        let x1169 = x1164 - x1159;
        let x1170 = x1168 + x1169;
        let x1171 = 0.5 * x1170;
        let x1172 = qd[10] * qd[10];
        let x1173 = qd[11] * qd[11];
        let x1174 = qd[12] * qd[12];
        let x1175 = qd[13] * qd[13];
        let x1176 = x1172 + x1173;
        let x1177 = x1174 + x1176;
        let x1178 = x1175 + x1177;
        let x1180 = 0.2 * x1118;
        let x1181 = 0.3 * x1122;
        let x1182 = x1117 + x1180;
        let x1183 = x1181 + x1182;
        let x1184 = 0.5 * x1183;
        let x1185 = x1128 + x1184;
        let x1186 = q[10] * 0.8000000000000002;
        let x1187 = x1178 * x1186;
        let x1189 = x1185 - x1187;
        let x1196 = 0.2 * x1132;
        let x1198 = 0.3 * x1137;
        let x1200 = x1196 - x1131;
        let x1201 = x1200 - x1198;
        let x1202 = 0.5 * x1201;
        let x1204 = x1202 - x1143;
        let x1205 = q[11] * 0.8000000000000002;
        let x1206 = x1178 * x1205;
        let x1208 = x1204 - x1206;
        let x1214 = 0.2 * x1146;
        let x1216 = 0.3 * x1150;
        let x1217 = x1145 + x1214;
        let x1219 = x1216 - x1217;
        let x1220 = 0.5 * x1219;
        let x1222 = x1220 - x1157;
        let x1223 = q[12] * 0.8000000000000002;
        let x1224 = x1178 * x1223;
        let x1226 = x1222 - x1224;
        let x1230 = 0.2 * x1161;
        let x1233 = 0.3 * x1165;
        let x1235 = x1159 - x1230;
        let x1236 = x1235 - x1233;
        let x1237 = 0.5 * x1236;
        let x1239 = x1237 - x1171;
        let x1240 = q[13] * 0.8000000000000002;
        let x1241 = x1178 * x1240;
        let x1243 = x1239 - x1241;
        let x1244 = x409 + x1189;
        let x1245 = x410 + x1208;
        let x1246 = x411 + x1226;
        let x1247 = x1243 - x412;
        out[0] = x408;
        out[1] = x812;
        out[2] = x322;
        out[3] = x757;
        out[4] = x776;
        out[5] = x794;
        out[6] = x811;
        out[7] = 0.0;
        out[8] = -9.81;
        out[9] = 0.0;
        out[10] = x1244;
        out[11] = x1245;
        out[12] = x1246;
        out[13] = x1247;
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
        eval_newton_shared_0(q, qd, t, &mut s);
        eval_newton_part_0(q, qd, t, &s, phi, phi_q, mass, force);
        eval_newton_part_1(q, qd, &s, force);
    }
    #[inline(never)]
    fn eval_newton_shared_0(q: &[f64; 14], qd: &[f64; 14], t: f64, s: &mut [f64; 94]) {
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
        let x323 = -x103;
        s[35] = x323;
        let x324 = x323.atan2(x74);
        s[36] = x324;
        let x325 = 2.0 * x188;
        s[37] = x325;
        let x326 = q[13] * qd[11];
        s[38] = x326;
        let x327 = q[11] * qd[13];
        s[39] = x327;
        let x328 = x326 + x327;
        s[40] = x328;
        let x329 = 2.0 * x328;
        s[41] = x329;
        let x330 = q[12] * qd[10];
        s[42] = x330;
        let x331 = q[10] * qd[12];
        s[43] = x331;
        let x332 = x330 + x331;
        s[44] = x332;
        let x333 = 2.0 * x332;
        s[45] = x333;
        let x335 = x329 - x333;
        s[46] = x335;
        let x337 = x74 * x74;
        s[47] = x337;
        let x338 = x103 * x103;
        s[48] = x338;
        let x339 = x337 + x338;
        s[49] = x339;
        let x340 = x74 * x335;
        s[50] = x340;
        let x342 = x103 * x325;
        s[51] = x342;
        let x344 = x342 - x340;
        s[52] = x344;
        let x345 = 1.0 / x339;
        s[53] = x345;
        let x346 = x344 * x345;
        s[54] = x346;
        let x347 = 2.0 * x324;
        s[55] = x347;
        let x348 = 0.1 * x346;
        s[56] = x348;
        let x350 = x11 - x348;
        s[57] = x350;
        let x352 = x350 - x347;
        s[58] = x352;
        let x361 = 2.0 * x130;
        s[59] = x361;
        let x381 = x204 - x203;
        s[60] = x381;
        let x814 = x199 + x381;
        s[61] = x814;
        let x815 = x814 - x200;
        s[62] = x815;
        let x816 = 2.0 * x815;
        s[63] = x816;
        let x818 = x326 + x330;
        s[64] = x818;
        let x820 = x331 - x818;
        s[65] = x820;
        let x821 = x327 + x820;
        s[66] = x821;
        let x822 = 2.0 * x821;
        s[67] = x822;
        let x824 = x189 - x193;
        s[68] = x824;
        let x825 = x824 - x190;
        s[69] = x825;
        let x826 = x194 + x825;
        s[70] = x826;
        let x827 = 2.0 * x826;
        s[71] = x827;
        let x845 = 2.0 * x816;
        s[72] = x845;
        let x847 = 2.0 * x822;
        s[73] = x847;
        let x849 = 2.0 * x827;
        s[74] = x849;
        let x1099 = qd[11] * qd[13];
        s[75] = x1099;
        let x1100 = qd[10] * qd[12];
        s[76] = x1100;
        let x1104 = x1099 + x1100;
        s[77] = x1104;
        let x1106 = x1100 - x1104;
        s[78] = x1106;
        let x1107 = x1099 + x1106;
        s[79] = x1107;
        let x1108 = 2.0 * x1107;
        s[80] = x1108;
        let x1110 = x256 - x259;
        s[81] = x1110;
        let x1111 = x1110 - x256;
        s[82] = x1111;
        let x1112 = x259 + x1111;
        s[83] = x1112;
        let x1113 = 2.0 * x1112;
        s[84] = x1113;
        let x1114 = 2.0 * x1108;
        s[85] = x1114;
        let x1115 = 2.0 * x1113;
        s[86] = x1115;
        let x1172 = qd[10] * qd[10];
        s[87] = x1172;
        let x1173 = qd[11] * qd[11];
        s[88] = x1173;
        let x1174 = qd[12] * qd[12];
        s[89] = x1174;
        let x1175 = qd[13] * qd[13];
        s[90] = x1175;
        let x1176 = x1172 + x1173;
        s[91] = x1176;
        let x1177 = x1174 + x1176;
        s[92] = x1177;
        let x1178 = x1175 + x1177;
        s[93] = x1178;
    }
    #[inline(never)]
    fn eval_newton_part_0(
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
        let x286 = 1.0 + q[0];
        let x287 = x286 * x286;
        let x288 = q[1] * q[1];
        let x289 = q[2] * q[2];
        let x290 = x287 + x288;
        let x291 = x289 + x290;
        let x292 = x291.sqrt();
        let x293 = 2.0 * x286;
        let x294 = qd[0] * x293;
        let x295 = q[1] * 2.0;
        let x296 = qd[1] * x295;
        let x297 = q[2] * 2.0;
        let x298 = qd[2] * x297;
        let x299 = x294 + x296;
        let x300 = x298 + x299;
        let x301 = 2.0 * x292;
        let x302 = 1.0 / x301;
        let x303 = x300 * x302;
        let x304 = x292 - 1.0;
        let x307 = x304 * 50.0;
        let x308 = x303 * 0.8;
        let x310 = x5 - x308;
        let x312 = x310 - x307;
        let x317 = x293 * x302;
        let x318 = x295 * x302;
        let x319 = x297 * x302;
        let x320 = x312 * x317;
        let x321 = x312 * x318;
        let x322 = x312 * x319;
        let x355 = 2.0 * s[15];
        let x356 = s[9] * s[17];
        let x357 = s[14] * x355;
        let x359 = x356 + x357;
        let x360 = s[53] * x359;
        let x374 = s[58] * x360;
        let x402 = s[4] * s[17];
        let x408 = 1.0 + x320;
        let x409 = x374 - x402;
        let x422 = x178 - x177;
        let x423 = x173 + x422;
        let x424 = x423 - x174;
        let x425 = 2.0 * x424;
        let x428 = x164 + x168;
        let x430 = x169 - x428;
        let x431 = x165 + x430;
        let x432 = 2.0 * x431;
        let x435 = x156 - x160;
        let x436 = x435 - x157;
        let x437 = x161 + x436;
        let x438 = 2.0 * x437;
        let x460 = 2.0 * x425;
        let x462 = 2.0 * x432;
        let x464 = 2.0 * x438;
        let x527 = 2.0 * x124;
        let x529 = 2.0 * x125;
        let x531 = 2.0 * x126;
        let x533 = x124 * x527;
        let x535 = 0.01 * x533;
        let x537 = x125 * x529;
        let x539 = 0.01 * x537;
        let x541 = x126 * x531;
        let x543 = 0.01 * x541;
        let x545 = x535 + x539;
        let x547 = x543 + x545;
        let x549 = 0.5 * x547;
        let x551 = x23 * 0.04;
        let x552 = x549 + x551;
        let x553 = 2.0 * x123;
        let x554 = x124 * x553;
        let x555 = 0.01 * x554;
        let x556 = x125 * x531;
        let x558 = 0.01 * x556;
        let x560 = x126 * x529;
        let x561 = 0.01 * x560;
        let x562 = x555 - x558;
        let x563 = x561 + x562;
        let x564 = 0.5 * x563;
        let x566 = x52 * 0.04;
        let x567 = x566 - x564;
        let x568 = x124 * x531;
        let x569 = 0.01 * x568;
        let x570 = x125 * x553;
        let x571 = 0.01 * x570;
        let x572 = x126 * x527;
        let x574 = 0.01 * x572;
        let x576 = x569 + x571;
        let x577 = x576 - x574;
        let x578 = 0.5 * x577;
        let x580 = x46 * 0.04;
        let x581 = x580 - x578;
        let x582 = x124 * x529;
        let x584 = 0.01 * x582;
        let x586 = x125 * x527;
        let x587 = 0.01 * x586;
        let x588 = x126 * x553;
        let x589 = 0.01 * x588;
        let x590 = x587 - x584;
        let x591 = x589 + x590;
        let x592 = 0.5 * x591;
        let x594 = x39 * 0.04;
        let x595 = x594 - x592;
        let x596 = x123 * x527;
        let x598 = 0.01 * x596;
        let x602 = x561 - x598;
        let x603 = x602 - x558;
        let x604 = 0.5 * x603;
        let x605 = x566 + x604;
        let x606 = x123 * x553;
        let x607 = 0.01 * x606;
        let x608 = x543 + x607;
        let x609 = x539 + x608;
        let x610 = 0.5 * x609;
        let x611 = x24 * 0.04;
        let x612 = x610 + x611;
        let x613 = x123 * x531;
        let x614 = 0.01 * x613;
        let x618 = x614 - x589;
        let x619 = x618 - x587;
        let x620 = 0.5 * x619;
        let x621 = x37 * 0.04;
        let x622 = x620 + x621;
        let x623 = x123 * x529;
        let x625 = 0.01 * x623;
        let x627 = x574 + x625;
        let x629 = x571 - x627;
        let x630 = 0.5 * x629;
        let x631 = x44 * 0.04;
        let x632 = x630 + x631;
        let x635 = x569 - x627;
        let x636 = 0.5 * x635;
        let x637 = x580 + x636;
        let x640 = x589 - x614;
        let x641 = x640 - x584;
        let x642 = 0.5 * x641;
        let x643 = x621 + x642;
        let x644 = x535 + x608;
        let x645 = 0.5 * x644;
        let x646 = x25 * 0.04;
        let x647 = x645 + x646;
        let x649 = x598 - x561;
        let x650 = x649 - x555;
        let x651 = 0.5 * x650;
        let x652 = x50 * 0.04;
        let x653 = x651 + x652;
        let x654 = x590 - x614;
        let x655 = 0.5 * x654;
        let x656 = x594 + x655;
        let x659 = x625 - x576;
        let x660 = 0.5 * x659;
        let x661 = x631 + x660;
        let x662 = x562 - x598;
        let x663 = 0.5 * x662;
        let x664 = x652 + x663;
        let x665 = x545 + x607;
        let x666 = 0.5 * x665;
        let x667 = x26 * 0.04;
        let x668 = x666 + x667;
        let x671 = x235 + x238;
        let x673 = x238 - x671;
        let x674 = x235 + x673;
        let x675 = 2.0 * x674;
        let x678 = x229 - x232;
        let x679 = x678 - x229;
        let x680 = x232 + x679;
        let x681 = 2.0 * x680;
        let x682 = 2.0 * x675;
        let x683 = 2.0 * x681;
        let x684 = x217 * x460;
        let x685 = 0.01 * x684;
        let x686 = x218 * x462;
        let x687 = x125 * x682;
        let x688 = x686 + x687;
        let x689 = 0.01 * x688;
        let x690 = x219 * x464;
        let x691 = x126 * x683;
        let x692 = x690 + x691;
        let x693 = 0.01 * x692;
        let x694 = x685 + x689;
        let x695 = x693 + x694;
        let x696 = 0.5 * x695;
        let x698 = x216 * x460;
        let x699 = 0.01 * x698;
        let x700 = x219 * x462;
        let x701 = x126 * x682;
        let x702 = x700 + x701;
        let x703 = 0.01 * x702;
        let x705 = x218 * x464;
        let x706 = x125 * x683;
        let x707 = x705 + x706;
        let x708 = 0.01 * x707;
        let x709 = x699 - x703;
        let x710 = x708 + x709;
        let x711 = 0.5 * x710;
        let x712 = x219 * x460;
        let x713 = 0.01 * x712;
        let x714 = x216 * x462;
        let x715 = x123 * x682;
        let x716 = x714 + x715;
        let x717 = 0.01 * x716;
        let x718 = x217 * x464;
        let x719 = x124 * x683;
        let x720 = x718 + x719;
        let x721 = 0.01 * x720;
        let x723 = x713 + x717;
        let x724 = x723 - x721;
        let x725 = 0.5 * x724;
        let x726 = x218 * x460;
        let x727 = 0.01 * x726;
        let x729 = x217 * x462;
        let x730 = x124 * x682;
        let x731 = x729 + x730;
        let x732 = 0.01 * x731;
        let x733 = x216 * x464;
        let x734 = x123 * x683;
        let x735 = x733 + x734;
        let x736 = 0.01 * x735;
        let x737 = x732 - x727;
        let x738 = x736 + x737;
        let x739 = 0.5 * x738;
        let x740 = qd[3] * qd[3];
        let x741 = qd[4] * qd[4];
        let x742 = qd[5] * qd[5];
        let x743 = qd[6] * qd[6];
        let x744 = x740 + x741;
        let x745 = x742 + x744;
        let x746 = x743 + x745;
        let x748 = 0.01 * x686;
        let x749 = 0.01 * x690;
        let x750 = x685 + x748;
        let x751 = x749 + x750;
        let x752 = 0.5 * x751;
        let x753 = x696 + x752;
        let x754 = q[3] * 0.04;
        let x755 = x746 * x754;
        let x757 = x753 - x755;
        let x764 = 0.01 * x700;
        let x766 = 0.01 * x705;
        let x768 = x764 - x699;
        let x769 = x768 - x766;
        let x770 = 0.5 * x769;
        let x772 = x770 - x711;
        let x773 = q[4] * 0.04;
        let x774 = x746 * x773;
        let x776 = x772 - x774;
        let x782 = 0.01 * x714;
        let x784 = 0.01 * x718;
        let x785 = x713 + x782;
        let x787 = x784 - x785;
        let x788 = 0.5 * x787;
        let x790 = x788 - x725;
        let x791 = q[5] * 0.04;
        let x792 = x746 * x791;
        let x794 = x790 - x792;
        let x798 = 0.01 * x729;
        let x801 = 0.01 * x733;
        let x803 = x727 - x798;
        let x804 = x803 - x801;
        let x805 = 0.5 * x804;
        let x807 = x805 - x739;
        let x808 = q[6] * 0.04;
        let x809 = x746 * x808;
        let x811 = x807 - x809;
        let x812 = x321 - 19.62;
        let x906 = 2.0 * s[17];
        let x908 = 2.0 * s[18];
        let x910 = s[16] * s[59];
        let x912 = 0.1 * x910;
        let x914 = s[17] * x906;
        let x916 = 0.2 * x914;
        let x918 = s[18] * x908;
        let x920 = 0.3 * x918;
        let x922 = x912 + x916;
        let x924 = x920 + x922;
        let x926 = 0.5 * x924;
        let x928 = s[5] * 0.8000000000000002;
        let x929 = x926 + x928;
        let x930 = s[16] * x355;
        let x931 = 0.1 * x930;
        let x932 = s[17] * x908;
        let x934 = 0.2 * x932;
        let x936 = s[18] * x906;
        let x937 = 0.3 * x936;
        let x938 = x931 - x934;
        let x939 = x937 + x938;
        let x940 = 0.5 * x939;
        let x942 = x96 * 0.8000000000000002;
        let x943 = x942 - x940;
        let x944 = s[16] * x908;
        let x945 = 0.1 * x944;
        let x946 = s[17] * x355;
        let x947 = 0.2 * x946;
        let x948 = s[18] * s[59];
        let x950 = 0.3 * x948;
        let x952 = x945 + x947;
        let x953 = x952 - x950;
        let x954 = 0.5 * x953;
        let x956 = s[12] * 0.8000000000000002;
        let x957 = x956 - x954;
        let x958 = s[16] * x906;
        let x960 = 0.1 * x958;
        let x962 = s[17] * s[59];
        let x963 = 0.2 * x962;
        let x964 = s[18] * x355;
        let x965 = 0.3 * x964;
        let x966 = x963 - x960;
        let x967 = x965 + x966;
        let x968 = 0.5 * x967;
        let x970 = x83 * 0.8000000000000002;
        let x971 = x970 - x968;
        let x972 = s[15] * s[59];
        let x974 = 0.1 * x972;
        let x977 = 0.2 * x936;
        let x979 = 0.3 * x932;
        let x981 = x977 - x974;
        let x982 = x981 - x979;
        let x983 = 0.5 * x982;
        let x984 = x942 + x983;
        let x985 = s[15] * x355;
        let x986 = 0.1 * x985;
        let x987 = 0.2 * x918;
        let x989 = 0.3 * x914;
        let x990 = x986 + x987;
        let x991 = x989 + x990;
        let x992 = 0.5 * x991;
        let x993 = s[6] * 0.8000000000000002;
        let x994 = x992 + x993;
        let x995 = s[15] * x908;
        let x996 = 0.1 * x995;
        let x997 = 0.2 * x964;
        let x1000 = 0.3 * x962;
        let x1002 = x996 - x997;
        let x1003 = x1002 - x1000;
        let x1004 = 0.5 * x1003;
        let x1005 = x81 * 0.8000000000000002;
        let x1006 = x1004 + x1005;
        let x1007 = s[15] * x906;
        let x1009 = 0.1 * x1007;
        let x1011 = 0.2 * x948;
        let x1013 = 0.3 * x946;
        let x1014 = x1009 + x1011;
        let x1016 = x1013 - x1014;
        let x1017 = 0.5 * x1016;
        let x1018 = s[10] * 0.8000000000000002;
        let x1019 = x1017 + x1018;
        let x1020 = 0.1 * x948;
        let x1022 = 0.2 * x1007;
        let x1025 = 0.3 * x944;
        let x1027 = x1020 + x1022;
        let x1029 = x1025 - x1027;
        let x1030 = 0.5 * x1029;
        let x1031 = x956 + x1030;
        let x1032 = 0.1 * x964;
        let x1034 = 0.2 * x995;
        let x1036 = 0.3 * x958;
        let x1038 = x1032 - x1034;
        let x1039 = x1038 - x1036;
        let x1040 = 0.5 * x1039;
        let x1041 = x1005 + x1040;
        let x1042 = 0.1 * x918;
        let x1043 = 0.2 * x985;
        let x1044 = 0.3 * x910;
        let x1046 = x1042 + x1043;
        let x1047 = x1044 + x1046;
        let x1048 = 0.5 * x1047;
        let x1049 = x70 * 0.8000000000000002;
        let x1050 = x1048 + x1049;
        let x1051 = 0.1 * x936;
        let x1053 = 0.2 * x972;
        let x1054 = 0.3 * x930;
        let x1056 = x1053 - x1051;
        let x1057 = x1056 - x1054;
        let x1058 = 0.5 * x1057;
        let x1059 = x94 * 0.8000000000000002;
        let x1060 = x1058 + x1059;
        let x1061 = 0.1 * x962;
        let x1063 = 0.2 * x958;
        let x1065 = 0.3 * x995;
        let x1067 = x1061 - x1063;
        let x1068 = x1067 - x1065;
        let x1069 = 0.5 * x1068;
        let x1070 = x970 + x1069;
        let x1071 = 0.1 * x946;
        let x1073 = 0.2 * x944;
        let x1075 = 0.3 * x1007;
        let x1076 = x1071 + x1073;
        let x1078 = x1075 - x1076;
        let x1079 = 0.5 * x1078;
        let x1080 = x1018 + x1079;
        let x1081 = 0.1 * x932;
        let x1083 = 0.2 * x930;
        let x1084 = 0.3 * x972;
        let x1086 = x1083 - x1081;
        let x1087 = x1086 - x1084;
        let x1088 = 0.5 * x1087;
        let x1089 = x1059 + x1088;
        let x1090 = 0.1 * x914;
        let x1092 = 0.2 * x910;
        let x1093 = 0.3 * x985;
        let x1094 = x1090 + x1092;
        let x1095 = x1093 + x1094;
        let x1096 = 0.5 * x1095;
        let x1097 = x71 * 0.8000000000000002;
        let x1098 = x1096 + x1097;
        let x1116 = s[30] * s[72];
        let x1117 = 0.1 * x1116;
        let x1118 = s[31] * s[73];
        let x1119 = s[17] * s[85];
        let x1120 = x1118 + x1119;
        let x1121 = 0.2 * x1120;
        let x1122 = s[32] * s[74];
        let x1123 = s[18] * s[86];
        let x1124 = x1122 + x1123;
        let x1125 = 0.3 * x1124;
        let x1126 = x1117 + x1121;
        let x1127 = x1125 + x1126;
        let x1128 = 0.5 * x1127;
        let x1180 = 0.2 * x1118;
        let x1181 = 0.3 * x1122;
        let x1182 = x1117 + x1180;
        let x1183 = x1181 + x1182;
        let x1184 = 0.5 * x1183;
        let x1185 = x1128 + x1184;
        let x1186 = q[10] * 0.8000000000000002;
        let x1187 = s[93] * x1186;
        let x1189 = x1185 - x1187;
        let x1244 = x409 + x1189;
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
        mass[0] = 2.0;
        mass[1] = 2.0;
        mass[2] = 2.0;
        mass[3] = x552;
        mass[4] = x567;
        mass[5] = x581;
        mass[6] = x595;
        mass[7] = x605;
        mass[8] = x612;
        mass[9] = x622;
        mass[10] = x632;
        mass[11] = x637;
        mass[12] = x643;
        mass[13] = x647;
        mass[14] = x653;
        mass[15] = x656;
        mass[16] = x661;
        mass[17] = x664;
        mass[18] = x668;
        mass[19] = 1.0;
        mass[20] = 1.0;
        mass[21] = 1.0;
        mass[22] = x929;
        mass[23] = x943;
        mass[24] = x957;
        mass[25] = x971;
        mass[26] = x984;
        mass[27] = x994;
        mass[28] = x1006;
        mass[29] = x1019;
        mass[30] = x1031;
        mass[31] = x1041;
        mass[32] = x1050;
        mass[33] = x1060;
        mass[34] = x1070;
        mass[35] = x1080;
        mass[36] = x1089;
        mass[37] = x1098;
        force[0] = x408;
        force[1] = x812;
        force[2] = x322;
        force[3] = x757;
        force[4] = x776;
        force[5] = x794;
        force[6] = x811;
        force[7] = 0.0;
        force[8] = -9.81;
        force[9] = 0.0;
        force[10] = x1244;
    }
    #[inline(never)]
    fn eval_newton_part_1(
        q: &[f64; 14],
        qd: &[f64; 14],
        s: &[f64; 94],
        force: &mut [f64; 14],
    ) {
        let x220 = 2.0 * qd[10];
        let x362 = s[9] * s[18];
        let x364 = s[14] * s[59];
        let x366 = x364 - x362;
        let x367 = s[53] * x366;
        let x368 = s[9] * s[15];
        let x369 = s[53] * x368;
        let x370 = s[9] * s[16];
        let x372 = s[53] * x370;
        let x375 = s[58] * x367;
        let x376 = s[58] * x369;
        let x377 = s[58] * x372;
        let x404 = s[4] * s[18];
        let x405 = s[4] * s[15];
        let x406 = s[4] * s[16];
        let x410 = x375 + x404;
        let x411 = x376 + x405;
        let x412 = x377 + x406;
        let x1130 = x220 * s[72];
        let x1131 = 0.1 * x1130;
        let x1132 = s[32] * s[73];
        let x1133 = s[18] * s[85];
        let x1134 = x1132 + x1133;
        let x1135 = 0.2 * x1134;
        let x1137 = s[31] * s[74];
        let x1138 = s[17] * s[86];
        let x1139 = x1137 + x1138;
        let x1140 = 0.3 * x1139;
        let x1141 = x1131 - x1135;
        let x1142 = x1140 + x1141;
        let x1143 = 0.5 * x1142;
        let x1144 = s[32] * s[72];
        let x1145 = 0.1 * x1144;
        let x1146 = x220 * s[73];
        let x1147 = s[15] * s[85];
        let x1148 = x1146 + x1147;
        let x1149 = 0.2 * x1148;
        let x1150 = s[30] * s[74];
        let x1151 = s[16] * s[86];
        let x1152 = x1150 + x1151;
        let x1153 = 0.3 * x1152;
        let x1155 = x1145 + x1149;
        let x1156 = x1155 - x1153;
        let x1157 = 0.5 * x1156;
        let x1158 = s[31] * s[72];
        let x1159 = 0.1 * x1158;
        let x1161 = s[30] * s[73];
        let x1162 = s[16] * s[85];
        let x1163 = x1161 + x1162;
        let x1164 = 0.2 * x1163;
        let x1165 = x220 * s[74];
        let x1166 = s[15] * s[86];
        let x1167 = x1165 + x1166;
        let x1168 = 0.3 * x1167;
        let x1169 = x1164 - x1159;
        let x1170 = x1168 + x1169;
        let x1171 = 0.5 * x1170;
        let x1196 = 0.2 * x1132;
        let x1198 = 0.3 * x1137;
        let x1200 = x1196 - x1131;
        let x1201 = x1200 - x1198;
        let x1202 = 0.5 * x1201;
        let x1204 = x1202 - x1143;
        let x1205 = q[11] * 0.8000000000000002;
        let x1206 = s[93] * x1205;
        let x1208 = x1204 - x1206;
        let x1214 = 0.2 * x1146;
        let x1216 = 0.3 * x1150;
        let x1217 = x1145 + x1214;
        let x1219 = x1216 - x1217;
        let x1220 = 0.5 * x1219;
        let x1222 = x1220 - x1157;
        let x1223 = q[12] * 0.8000000000000002;
        let x1224 = s[93] * x1223;
        let x1226 = x1222 - x1224;
        let x1230 = 0.2 * x1161;
        let x1233 = 0.3 * x1165;
        let x1235 = x1159 - x1230;
        let x1236 = x1235 - x1233;
        let x1237 = 0.5 * x1236;
        let x1239 = x1237 - x1171;
        let x1240 = q[13] * 0.8000000000000002;
        let x1241 = s[93] * x1240;
        let x1243 = x1239 - x1241;
        let x1245 = x410 + x1208;
        let x1246 = x411 + x1226;
        let x1247 = x1243 - x412;
        force[11] = x1245;
        force[12] = x1246;
        force[13] = x1247;
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
            row: 2u32,
            coord: 1u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: 3u32,
            coord: 2u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: 5u32,
            coord: 7u32,
            target: None,
            weight: 0f64,
            slope: -1f64,
        },
        Substitution {
            row: 6u32,
            coord: 8u32,
            target: None,
            weight: 0f64,
            slope: -1f64,
        },
        Substitution {
            row: 7u32,
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
        let x288 = q[1] * q[1];
        let x289 = q[2] * q[2];
        let x1248 = x288 + x289;
        let x1249 = q[2] * q[3];
        let x1250 = 2.0 * x1249;
        let x1251 = q[1] * q[4];
        let x1252 = 2.0 * x1251;
        let x1253 = q[2] * q[4];
        let x1254 = 2.0 * x1253;
        let x1255 = q[1] * q[3];
        let x1256 = 2.0 * x1255;
        let x1257 = x1250 + x1252;
        let x1258 = q[1] * q[2];
        let x1259 = 2.0 * x1258;
        let x1261 = x1254 - x1256;
        let x1262 = x54 + x1259;
        let x1263 = q[7] * q[7];
        let x1264 = q[8] * q[8];
        let x1265 = x25 + x26;
        let x1266 = q[6] * q[7];
        let x1267 = 2.0 * x1266;
        let x1268 = q[5] * q[8];
        let x1269 = 2.0 * x1268;
        let x1271 = x1267 - x1269;
        let x1272 = q[7] * q[8];
        let x1273 = 2.0 * x1272;
        let x1274 = x51 + x1273;
        let x1275 = -x1274;
        let x1276 = x23 + x1248;
        let x1277 = x24 + x1276;
        let x1278 = x1277 - 1.0;
        let x1279 = x1263 + x1265;
        let x1280 = x1264 + x1279;
        let x1281 = x1280 - 1.0;
        out[0] = x1257;
        out[1] = x1261;
        out[2] = x1262;
        out[3] = x1271;
        out[4] = x1275;
        out[5] = x1278;
        out[6] = x1281;
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
        let x295 = q[1] * 2.0;
        let x297 = q[2] * 2.0;
        let x474 = -x126;
        let x1282 = -x295;
        let x1283 = 2.0 * q[7];
        let x1284 = 2.0 * q[8];
        let x1285 = -x1284;
        let x1286 = -x1283;
        out[0] = x124;
        out[1] = x123;
        out[2] = x297;
        out[3] = x295;
        out[4] = x128;
        out[5] = x124;
        out[6] = x1282;
        out[7] = x297;
        out[8] = x297;
        out[9] = x295;
        out[10] = x124;
        out[11] = x123;
        out[12] = x1285;
        out[13] = x1283;
        out[14] = x126;
        out[15] = x127;
        out[16] = x474;
        out[17] = x127;
        out[18] = x1285;
        out[19] = x1286;
        out[20] = x295;
        out[21] = x297;
        out[22] = x123;
        out[23] = x124;
        out[24] = x125;
        out[25] = x126;
        out[26] = x1283;
        out[27] = x1284;
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
        let x461 = 2.0 * qd[1];
        let x463 = 2.0 * qd[2];
        let x844 = 2.0 * qd[7];
        let x846 = 2.0 * qd[8];
        let x1335 = qd[1] * x461;
        let x1336 = qd[2] * x463;
        let x1337 = x1335 + x1336;
        let x1338 = qd[2] * qd[3];
        let x1339 = x1338 + x1338;
        let x1340 = 2.0 * x1339;
        let x1341 = qd[1] * qd[4];
        let x1342 = x1341 + x1341;
        let x1343 = 2.0 * x1342;
        let x1344 = qd[2] * qd[4];
        let x1345 = x1344 + x1344;
        let x1346 = 2.0 * x1345;
        let x1347 = qd[1] * qd[3];
        let x1348 = x1347 + x1347;
        let x1349 = 2.0 * x1348;
        let x1350 = x1340 + x1343;
        let x1351 = qd[1] * qd[2];
        let x1352 = x1351 + x1351;
        let x1353 = 2.0 * x1352;
        let x1355 = x1346 - x1349;
        let x1356 = x247 + x1353;
        let x1357 = qd[7] * x844;
        let x1358 = qd[8] * x846;
        let x1359 = x226 + x227;
        let x1360 = qd[6] * qd[7];
        let x1361 = x1360 + x1360;
        let x1362 = 2.0 * x1361;
        let x1363 = qd[5] * qd[8];
        let x1364 = x1363 + x1363;
        let x1365 = 2.0 * x1364;
        let x1367 = x1362 - x1365;
        let x1368 = qd[7] * qd[8];
        let x1369 = x1368 + x1368;
        let x1370 = 2.0 * x1369;
        let x1371 = x244 + x1370;
        let x1373 = x224 + x1337;
        let x1374 = x225 + x1373;
        let x1375 = x1357 + x1359;
        let x1376 = x1358 + x1375;
        let x1377 = -x1350;
        let x1378 = -x1355;
        let x1379 = -x1356;
        let x1380 = -x1367;
        let x1381 = -x1374;
        let x1382 = -x1376;
        out[0] = x1377;
        out[1] = x1378;
        out[2] = x1379;
        out[3] = x1380;
        out[4] = x1371;
        out[5] = x1381;
        out[6] = x1382;
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
        let x288 = q[1] * q[1];
        let x289 = q[2] * q[2];
        let x295 = q[1] * 2.0;
        let x297 = q[2] * 2.0;
        let x461 = 2.0 * qd[1];
        let x463 = 2.0 * qd[2];
        let x474 = -x126;
        let x844 = 2.0 * qd[7];
        let x846 = 2.0 * qd[8];
        let x1248 = x288 + x289;
        let x1249 = q[2] * q[3];
        let x1250 = 2.0 * x1249;
        let x1251 = q[1] * q[4];
        let x1252 = 2.0 * x1251;
        let x1253 = q[2] * q[4];
        let x1254 = 2.0 * x1253;
        let x1255 = q[1] * q[3];
        let x1256 = 2.0 * x1255;
        let x1257 = x1250 + x1252;
        let x1258 = q[1] * q[2];
        let x1259 = 2.0 * x1258;
        let x1261 = x1254 - x1256;
        let x1262 = x54 + x1259;
        let x1263 = q[7] * q[7];
        let x1264 = q[8] * q[8];
        let x1265 = x25 + x26;
        let x1266 = q[6] * q[7];
        let x1267 = 2.0 * x1266;
        let x1268 = q[5] * q[8];
        let x1269 = 2.0 * x1268;
        let x1271 = x1267 - x1269;
        let x1272 = q[7] * q[8];
        let x1273 = 2.0 * x1272;
        let x1274 = x51 + x1273;
        let x1275 = -x1274;
        let x1276 = x23 + x1248;
        let x1277 = x24 + x1276;
        let x1278 = x1277 - 1.0;
        let x1279 = x1263 + x1265;
        let x1280 = x1264 + x1279;
        let x1281 = x1280 - 1.0;
        let x1282 = -x295;
        let x1283 = 2.0 * q[7];
        let x1284 = 2.0 * q[8];
        let x1285 = -x1284;
        let x1286 = -x1283;
        let x1335 = qd[1] * x461;
        let x1336 = qd[2] * x463;
        let x1337 = x1335 + x1336;
        let x1338 = qd[2] * qd[3];
        let x1339 = x1338 + x1338;
        let x1340 = 2.0 * x1339;
        let x1341 = qd[1] * qd[4];
        let x1342 = x1341 + x1341;
        let x1343 = 2.0 * x1342;
        let x1344 = qd[2] * qd[4];
        let x1345 = x1344 + x1344;
        let x1346 = 2.0 * x1345;
        let x1347 = qd[1] * qd[3];
        let x1348 = x1347 + x1347;
        let x1349 = 2.0 * x1348;
        let x1350 = x1340 + x1343;
        let x1351 = qd[1] * qd[2];
        let x1352 = x1351 + x1351;
        let x1353 = 2.0 * x1352;
        let x1355 = x1346 - x1349;
        let x1356 = x247 + x1353;
        let x1357 = qd[7] * x844;
        let x1358 = qd[8] * x846;
        let x1359 = x226 + x227;
        let x1360 = qd[6] * qd[7];
        let x1361 = x1360 + x1360;
        let x1362 = 2.0 * x1361;
        let x1363 = qd[5] * qd[8];
        let x1364 = x1363 + x1363;
        let x1365 = 2.0 * x1364;
        let x1367 = x1362 - x1365;
        let x1368 = qd[7] * qd[8];
        let x1369 = x1368 + x1368;
        let x1370 = 2.0 * x1369;
        let x1371 = x244 + x1370;
        let x1373 = x224 + x1337;
        let x1374 = x225 + x1373;
        let x1375 = x1357 + x1359;
        let x1376 = x1358 + x1375;
        let x1377 = -x1350;
        let x1378 = -x1355;
        let x1379 = -x1356;
        let x1380 = -x1367;
        let x1381 = -x1374;
        let x1382 = -x1376;
        phi[0] = x1257;
        phi_q[0] = x124;
        phi_q[1] = x123;
        phi_q[2] = x297;
        phi_q[3] = x295;
        phi_t[0] = 0.0;
        gamma[0] = x1377;
        phi[1] = x1261;
        phi_q[4] = x128;
        phi_q[5] = x124;
        phi_q[6] = x1282;
        phi_q[7] = x297;
        phi_t[1] = 0.0;
        gamma[1] = x1378;
        phi[2] = x1262;
        phi_q[8] = x297;
        phi_q[9] = x295;
        phi_q[10] = x124;
        phi_q[11] = x123;
        phi_t[2] = 0.0;
        gamma[2] = x1379;
        phi[3] = x1271;
        phi_q[12] = x1285;
        phi_q[13] = x1283;
        phi_q[14] = x126;
        phi_q[15] = x127;
        phi_t[3] = 0.0;
        gamma[3] = x1380;
        phi[4] = x1275;
        phi_q[16] = x474;
        phi_q[17] = x127;
        phi_q[18] = x1285;
        phi_q[19] = x1286;
        phi_t[4] = 0.0;
        gamma[4] = x1371;
        phi[5] = x1278;
        phi_q[20] = x295;
        phi_q[21] = x297;
        phi_q[22] = x123;
        phi_q[23] = x124;
        phi_t[5] = 0.0;
        gamma[5] = x1381;
        phi[6] = x1281;
        phi_q[24] = x125;
        phi_q[25] = x126;
        phi_q[26] = x1283;
        phi_q[27] = x1284;
        phi_t[6] = 0.0;
        gamma[6] = x1382;
    }
    /// Potential energy of gravity and springs, written to `out[0]`.
    pub fn potential_into(q: &[f64], out: &mut [f64]) {
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        potential_into_part_0(q, out);
    }
    #[inline(never)]
    fn potential_into_part_0(q: &[f64; 9], out: &mut [f64; 1]) {
        let x25 = q[5] * q[5];
        let x26 = q[6] * q[6];
        let x286 = 1.0 + q[0];
        let x287 = x286 * x286;
        let x1265 = x25 + x26;
        let x1383 = 2.0 * x1265;
        let x1384 = x1383 - 1.0;
        let x1385 = q[6] * q[8];
        let x1386 = 2.0 * x1385;
        let x1387 = q[5] * q[7];
        let x1388 = 2.0 * x1387;
        let x1390 = x1386 - x1388;
        let x1391 = x287.sqrt();
        let x1392 = x1391 - 1.0;
        let x1393 = x1392 * x1392;
        let x1394 = 25.0 * x1393;
        let x1395 = -x1390;
        let x1396 = x1395.atan2(x1384);
        let x1397 = x1396 * x1396;
        let x1398 = 9.81 + x1394;
        let x1399 = x1397 + x1398;
        out[0] = x1399;
    }
    /// Power of the non-conservative loads, written to `out[0]`.
    pub fn power_nc_into(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
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
        let x286 = 1.0 + q[0];
        let x287 = x286 * x286;
        let x293 = 2.0 * x286;
        let x294 = qd[0] * x293;
        let x1265 = x25 + x26;
        let x1314 = x153 + x154;
        let x1383 = 2.0 * x1265;
        let x1384 = x1383 - 1.0;
        let x1385 = q[6] * q[8];
        let x1386 = 2.0 * x1385;
        let x1387 = q[5] * q[7];
        let x1388 = 2.0 * x1387;
        let x1390 = x1386 - x1388;
        let x1391 = x287.sqrt();
        let x1400 = 2.0 * x1391;
        let x1401 = 1.0 / x1400;
        let x1402 = x294 * x1401;
        let x1403 = 0.8 * x1402;
        let x1405 = x5 - x1403;
        let x1406 = x1402 * x1405;
        let x1407 = 2.0 * x1314;
        let x1408 = q[8] * qd[6];
        let x1409 = q[6] * qd[8];
        let x1410 = x1408 + x1409;
        let x1411 = 2.0 * x1410;
        let x1412 = q[7] * qd[5];
        let x1413 = q[5] * qd[7];
        let x1414 = x1412 + x1413;
        let x1415 = 2.0 * x1414;
        let x1417 = x1411 - x1415;
        let x1418 = x1384 * x1384;
        let x1419 = x1390 * x1390;
        let x1420 = x1418 + x1419;
        let x1421 = x1384 * x1417;
        let x1423 = x1390 * x1407;
        let x1424 = x1423 - x1421;
        let x1425 = 1.0 / x1420;
        let x1426 = x1424 * x1425;
        let x1427 = 0.1 * x1426;
        let x1429 = x11 - x1427;
        let x1430 = x1426 * x1429;
        let x1433 = x1408 - x1412;
        let x1434 = x1413 + x1433;
        let x1435 = x1434 - x1409;
        let x1436 = 2.0 * x1435;
        let x1437 = x14 * x1436;
        let x1438 = qd[0] + x1406;
        let x1439 = x1430 + x1438;
        let x1440 = x1437 + x1439;
        out[0] = x1440;
    }
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
            bodies: &[],
            joints: &[],
            coord_names: &COORD_NAMES,
            row_names: &ROW_NAMES,
            q0: &Q0,
            qd0: &QD0,
            redundant_rows: &REDUNDANT_ROWS,
            platform: None,
        };
        /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
        pub fn mass(q: &[f64], out: &mut [f64]) {
            let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
            let out: &mut [f64; 33] = out.try_into().expect("out must have 33 entries");
            mass_part_0(q, out);
        }
        #[inline(never)]
        fn mass_part_0(q: &[f64; 9], out: &mut [f64; 33]) {
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
            let x288 = q[1] * q[1];
            let x289 = q[2] * q[2];
            let x295 = q[1] * 2.0;
            let x297 = q[2] * 2.0;
            let x527 = 2.0 * x124;
            let x529 = 2.0 * x125;
            let x531 = 2.0 * x126;
            let x533 = x124 * x527;
            let x535 = 0.01 * x533;
            let x537 = x125 * x529;
            let x541 = x126 * x531;
            let x551 = x23 * 0.04;
            let x553 = 2.0 * x123;
            let x554 = x124 * x553;
            let x555 = 0.01 * x554;
            let x556 = x125 * x531;
            let x560 = x126 * x529;
            let x566 = x52 * 0.04;
            let x596 = x123 * x527;
            let x598 = 0.01 * x596;
            let x606 = x123 * x553;
            let x607 = 0.01 * x606;
            let x611 = x24 * 0.04;
            let x1249 = q[2] * q[3];
            let x1251 = q[1] * q[4];
            let x1253 = q[2] * q[4];
            let x1255 = q[1] * q[3];
            let x1258 = q[1] * q[2];
            let x1263 = q[7] * q[7];
            let x1264 = q[8] * q[8];
            let x1266 = q[6] * q[7];
            let x1268 = q[5] * q[8];
            let x1272 = q[7] * q[8];
            let x1283 = 2.0 * q[7];
            let x1284 = 2.0 * q[8];
            let x1385 = q[6] * q[8];
            let x1387 = q[5] * q[7];
            let x1441 = 2.0 * x297;
            let x1442 = x297 * x1441;
            let x1443 = 0.01 * x1442;
            let x1444 = x607 + x1443;
            let x1445 = x535 + x1444;
            let x1446 = 0.5 * x1445;
            let x1447 = x288 * 0.04;
            let x1448 = x1446 + x1447;
            let x1449 = 2.0 * x295;
            let x1450 = x297 * x1449;
            let x1451 = 0.01 * x1450;
            let x1452 = x1451 - x598;
            let x1453 = x555 + x1452;
            let x1454 = 0.5 * x1453;
            let x1456 = 0.04 * x1258;
            let x1457 = x1456 - x1454;
            let x1458 = x297 * x527;
            let x1459 = 0.01 * x1458;
            let x1460 = x123 * x1449;
            let x1461 = 0.01 * x1460;
            let x1462 = x124 * x1441;
            let x1463 = 0.01 * x1462;
            let x1465 = x1459 + x1461;
            let x1466 = x1465 - x1463;
            let x1467 = 0.5 * x1466;
            let x1469 = 0.04 * x1255;
            let x1470 = x1469 - x1467;
            let x1471 = x297 * x553;
            let x1472 = 0.01 * x1471;
            let x1474 = x123 * x1441;
            let x1475 = 0.01 * x1474;
            let x1476 = x124 * x1449;
            let x1477 = 0.01 * x1476;
            let x1478 = x1475 - x1472;
            let x1479 = x1477 + x1478;
            let x1480 = 0.5 * x1479;
            let x1482 = 0.04 * x1251;
            let x1483 = x1482 - x1480;
            let x1484 = x295 * x1441;
            let x1485 = 0.01 * x1484;
            let x1487 = x555 - x1485;
            let x1488 = x1487 - x598;
            let x1489 = 0.5 * x1488;
            let x1490 = x1456 + x1489;
            let x1491 = x295 * x1449;
            let x1492 = 0.01 * x1491;
            let x1493 = x535 + x1492;
            let x1494 = x607 + x1493;
            let x1495 = 0.5 * x1494;
            let x1496 = x289 * 0.04;
            let x1497 = x1495 + x1496;
            let x1498 = x295 * x527;
            let x1499 = 0.01 * x1498;
            let x1502 = x1499 - x1477;
            let x1503 = x1502 - x1475;
            let x1504 = 0.5 * x1503;
            let x1505 = 0.04 * x1249;
            let x1506 = x1504 + x1505;
            let x1507 = x295 * x553;
            let x1508 = 0.01 * x1507;
            let x1509 = x1463 + x1508;
            let x1511 = x1461 - x1509;
            let x1512 = 0.5 * x1511;
            let x1513 = 0.04 * x1253;
            let x1514 = x1512 + x1513;
            let x1515 = x1459 - x1509;
            let x1516 = 0.5 * x1515;
            let x1517 = x1469 + x1516;
            let x1519 = x1477 - x1499;
            let x1520 = x1519 - x1472;
            let x1521 = 0.5 * x1520;
            let x1522 = x1505 + x1521;
            let x1523 = x1443 + x1493;
            let x1524 = 0.5 * x1523;
            let x1525 = x551 + x1524;
            let x1527 = x1485 - x555;
            let x1528 = x1527 - x1451;
            let x1529 = 0.5 * x1528;
            let x1530 = x566 + x1529;
            let x1531 = x1478 - x1499;
            let x1532 = 0.5 * x1531;
            let x1533 = x1482 + x1532;
            let x1535 = x1508 - x1465;
            let x1536 = 0.5 * x1535;
            let x1537 = x1513 + x1536;
            let x1538 = x1452 - x1485;
            let x1539 = 0.5 * x1538;
            let x1540 = x566 + x1539;
            let x1541 = x1444 + x1492;
            let x1542 = 0.5 * x1541;
            let x1543 = x611 + x1542;
            let x1544 = 2.0 * x1283;
            let x1545 = 2.0 * x1284;
            let x1546 = 0.1 * x541;
            let x1547 = x1283 * x1544;
            let x1548 = 0.2 * x1547;
            let x1549 = x1284 * x1545;
            let x1550 = 0.3 * x1549;
            let x1551 = x1546 + x1548;
            let x1552 = x1550 + x1551;
            let x1553 = 0.5 * x1552;
            let x1554 = x25 * 0.8000000000000002;
            let x1555 = x1553 + x1554;
            let x1556 = 0.1 * x560;
            let x1557 = x1283 * x1545;
            let x1558 = 0.2 * x1557;
            let x1560 = x1284 * x1544;
            let x1561 = 0.3 * x1560;
            let x1562 = x1556 - x1558;
            let x1563 = x1561 + x1562;
            let x1564 = 0.5 * x1563;
            let x1566 = x50 * 0.8000000000000002;
            let x1567 = x1566 - x1564;
            let x1568 = x126 * x1545;
            let x1569 = 0.1 * x1568;
            let x1570 = x529 * x1283;
            let x1571 = 0.2 * x1570;
            let x1572 = x531 * x1284;
            let x1573 = 0.3 * x1572;
            let x1575 = x1569 + x1571;
            let x1576 = x1575 - x1573;
            let x1577 = 0.5 * x1576;
            let x1579 = 0.8000000000000002 * x1387;
            let x1580 = x1579 - x1577;
            let x1581 = x126 * x1544;
            let x1582 = 0.1 * x1581;
            let x1584 = x531 * x1283;
            let x1585 = 0.2 * x1584;
            let x1586 = x529 * x1284;
            let x1587 = 0.3 * x1586;
            let x1588 = x1585 - x1582;
            let x1589 = x1587 + x1588;
            let x1590 = 0.5 * x1589;
            let x1592 = 0.8000000000000002 * x1268;
            let x1593 = x1592 - x1590;
            let x1594 = 0.1 * x556;
            let x1596 = 0.2 * x1560;
            let x1597 = 0.3 * x1557;
            let x1599 = x1596 - x1594;
            let x1600 = x1599 - x1597;
            let x1601 = 0.5 * x1600;
            let x1602 = x1566 + x1601;
            let x1603 = 0.1 * x537;
            let x1604 = 0.2 * x1549;
            let x1605 = 0.3 * x1547;
            let x1606 = x1603 + x1604;
            let x1607 = x1605 + x1606;
            let x1608 = 0.5 * x1607;
            let x1609 = x26 * 0.8000000000000002;
            let x1610 = x1608 + x1609;
            let x1611 = x125 * x1545;
            let x1612 = 0.1 * x1611;
            let x1613 = 0.2 * x1586;
            let x1615 = 0.3 * x1584;
            let x1617 = x1612 - x1613;
            let x1618 = x1617 - x1615;
            let x1619 = 0.5 * x1618;
            let x1620 = 0.8000000000000002 * x1266;
            let x1621 = x1619 + x1620;
            let x1622 = x125 * x1544;
            let x1623 = 0.1 * x1622;
            let x1624 = 0.2 * x1572;
            let x1625 = 0.3 * x1570;
            let x1626 = x1623 + x1624;
            let x1628 = x1625 - x1626;
            let x1629 = 0.5 * x1628;
            let x1630 = 0.8000000000000002 * x1385;
            let x1631 = x1629 + x1630;
            let x1632 = 0.1 * x1572;
            let x1633 = 0.2 * x1622;
            let x1634 = 0.3 * x1568;
            let x1635 = x1632 + x1633;
            let x1637 = x1634 - x1635;
            let x1638 = 0.5 * x1637;
            let x1639 = x1579 + x1638;
            let x1640 = 0.1 * x1586;
            let x1641 = 0.2 * x1611;
            let x1643 = 0.3 * x1581;
            let x1645 = x1640 - x1641;
            let x1646 = x1645 - x1643;
            let x1647 = 0.5 * x1646;
            let x1648 = x1620 + x1647;
            let x1649 = 0.1 * x1549;
            let x1650 = 0.2 * x537;
            let x1651 = x541 * 0.3;
            let x1652 = x1649 + x1650;
            let x1653 = x1651 + x1652;
            let x1654 = 0.5 * x1653;
            let x1655 = 0.8000000000000002 * x1263;
            let x1656 = x1654 + x1655;
            let x1657 = 0.1 * x1560;
            let x1659 = 0.2 * x556;
            let x1660 = x560 * 0.3;
            let x1662 = x1659 - x1657;
            let x1663 = x1662 - x1660;
            let x1664 = 0.5 * x1663;
            let x1665 = 0.8000000000000002 * x1272;
            let x1666 = x1664 + x1665;
            let x1667 = 0.1 * x1584;
            let x1668 = 0.2 * x1581;
            let x1670 = 0.3 * x1611;
            let x1672 = x1667 - x1668;
            let x1673 = x1672 - x1670;
            let x1674 = 0.5 * x1673;
            let x1675 = x1592 + x1674;
            let x1676 = 0.1 * x1570;
            let x1677 = 0.2 * x1568;
            let x1678 = 0.3 * x1622;
            let x1679 = x1676 + x1677;
            let x1681 = x1678 - x1679;
            let x1682 = 0.5 * x1681;
            let x1683 = x1630 + x1682;
            let x1684 = 0.1 * x1557;
            let x1686 = 0.2 * x560;
            let x1687 = x556 * 0.3;
            let x1689 = x1686 - x1684;
            let x1690 = x1689 - x1687;
            let x1691 = 0.5 * x1690;
            let x1692 = x1665 + x1691;
            let x1693 = 0.1 * x1547;
            let x1694 = 0.2 * x541;
            let x1695 = x537 * 0.3;
            let x1696 = x1693 + x1694;
            let x1697 = x1695 + x1696;
            let x1698 = 0.5 * x1697;
            let x1699 = 0.8000000000000002 * x1264;
            let x1700 = x1698 + x1699;
            out[0] = 2.0;
            out[1] = x1448;
            out[2] = x1457;
            out[3] = x1470;
            out[4] = x1483;
            out[5] = x1490;
            out[6] = x1497;
            out[7] = x1506;
            out[8] = x1514;
            out[9] = x1517;
            out[10] = x1522;
            out[11] = x1525;
            out[12] = x1530;
            out[13] = x1533;
            out[14] = x1537;
            out[15] = x1540;
            out[16] = x1543;
            out[17] = x1555;
            out[18] = x1567;
            out[19] = x1580;
            out[20] = x1593;
            out[21] = x1602;
            out[22] = x1610;
            out[23] = x1621;
            out[24] = x1631;
            out[25] = x1639;
            out[26] = x1648;
            out[27] = x1656;
            out[28] = x1666;
            out[29] = x1675;
            out[30] = x1683;
            out[31] = x1692;
            out[32] = x1700;
        }
        /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
        pub fn force(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
            let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
            force_part_0(q, qd, t, out);
        }
        #[inline(never)]
        fn force_part_0(q: &[f64; 9], qd: &[f64; 9], t: f64, out: &mut [f64; 9]) {
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
            let x286 = 1.0 + q[0];
            let x287 = x286 * x286;
            let x293 = 2.0 * x286;
            let x294 = qd[0] * x293;
            let x295 = q[1] * 2.0;
            let x297 = q[2] * 2.0;
            let x444 = qd[1] * qd[1];
            let x448 = qd[2] * qd[2];
            let x461 = 2.0 * qd[1];
            let x463 = 2.0 * qd[2];
            let x529 = 2.0 * x125;
            let x531 = 2.0 * x126;
            let x740 = qd[3] * qd[3];
            let x741 = qd[4] * qd[4];
            let x742 = qd[5] * qd[5];
            let x743 = qd[6] * qd[6];
            let x754 = q[3] * 0.04;
            let x773 = q[4] * 0.04;
            let x828 = qd[7] * qd[7];
            let x831 = qd[8] * qd[8];
            let x844 = 2.0 * qd[7];
            let x846 = 2.0 * qd[8];
            let x1265 = x25 + x26;
            let x1283 = 2.0 * q[7];
            let x1284 = 2.0 * q[8];
            let x1288 = q[3] * qd[2];
            let x1289 = q[2] * qd[3];
            let x1292 = q[4] * qd[1];
            let x1293 = q[1] * qd[4];
            let x1296 = q[4] * qd[2];
            let x1297 = q[2] * qd[4];
            let x1300 = q[3] * qd[1];
            let x1301 = q[1] * qd[3];
            let x1305 = q[2] * qd[1];
            let x1306 = q[1] * qd[2];
            let x1314 = x153 + x154;
            let x1315 = q[7] * qd[6];
            let x1316 = q[6] * qd[7];
            let x1319 = q[8] * qd[5];
            let x1320 = q[5] * qd[8];
            let x1325 = q[8] * qd[7];
            let x1326 = q[7] * qd[8];
            let x1338 = qd[2] * qd[3];
            let x1341 = qd[1] * qd[4];
            let x1344 = qd[2] * qd[4];
            let x1347 = qd[1] * qd[3];
            let x1360 = qd[6] * qd[7];
            let x1363 = qd[5] * qd[8];
            let x1383 = 2.0 * x1265;
            let x1384 = x1383 - 1.0;
            let x1385 = q[6] * q[8];
            let x1386 = 2.0 * x1385;
            let x1387 = q[5] * q[7];
            let x1388 = 2.0 * x1387;
            let x1390 = x1386 - x1388;
            let x1391 = x287.sqrt();
            let x1392 = x1391 - 1.0;
            let x1395 = -x1390;
            let x1396 = x1395.atan2(x1384);
            let x1400 = 2.0 * x1391;
            let x1401 = 1.0 / x1400;
            let x1402 = x294 * x1401;
            let x1403 = 0.8 * x1402;
            let x1405 = x5 - x1403;
            let x1407 = 2.0 * x1314;
            let x1408 = q[8] * qd[6];
            let x1409 = q[6] * qd[8];
            let x1410 = x1408 + x1409;
            let x1411 = 2.0 * x1410;
            let x1412 = q[7] * qd[5];
            let x1413 = q[5] * qd[7];
            let x1414 = x1412 + x1413;
            let x1415 = 2.0 * x1414;
            let x1417 = x1411 - x1415;
            let x1418 = x1384 * x1384;
            let x1419 = x1390 * x1390;
            let x1420 = x1418 + x1419;
            let x1421 = x1384 * x1417;
            let x1423 = x1390 * x1407;
            let x1424 = x1423 - x1421;
            let x1425 = 1.0 / x1420;
            let x1426 = x1424 * x1425;
            let x1427 = 0.1 * x1426;
            let x1429 = x11 - x1427;
            let x1701 = 50.0 * x1392;
            let x1703 = x1405 - x1701;
            let x1704 = x293 * x1401;
            let x1705 = x1703 * x1704;
            let x1706 = 2.0 * x1396;
            let x1708 = x1429 - x1706;
            let x1709 = x1283 * x1384;
            let x1710 = x529 * x1390;
            let x1711 = x1709 + x1710;
            let x1712 = x1425 * x1711;
            let x1713 = x1284 * x1384;
            let x1715 = x531 * x1390;
            let x1716 = x1715 - x1713;
            let x1717 = x1425 * x1716;
            let x1718 = x125 * x1384;
            let x1719 = x1425 * x1718;
            let x1720 = x126 * x1384;
            let x1721 = x1425 * x1720;
            let x1722 = x1708 * x1712;
            let x1723 = x1708 * x1717;
            let x1724 = x1708 * x1719;
            let x1725 = x1708 * x1721;
            let x1727 = x174 - x173;
            let x1729 = x14 * x1283;
            let x1731 = x14 * x1284;
            let x1732 = x14 * x125;
            let x1733 = x14 * x126;
            let x1734 = 1.0 + x1705;
            let x1735 = x1722 - x1729;
            let x1736 = x1723 + x1731;
            let x1737 = x1724 + x1732;
            let x1738 = x1725 + x1733;
            let x1742 = x1306 - x1305;
            let x1743 = x177 + x1742;
            let x1744 = x1743 - x178;
            let x1745 = 2.0 * x1744;
            let x1746 = x1296 + x1300;
            let x1748 = x1301 - x1746;
            let x1749 = x1297 + x1748;
            let x1750 = 2.0 * x1749;
            let x1753 = x1288 - x1292;
            let x1754 = x1753 - x1289;
            let x1755 = x1293 + x1754;
            let x1756 = 2.0 * x1755;
            let x1757 = 2.0 * x1745;
            let x1758 = 2.0 * x1750;
            let x1759 = 2.0 * x1756;
            let x1760 = x1344 + x1347;
            let x1762 = x1347 - x1760;
            let x1763 = x1344 + x1762;
            let x1764 = 2.0 * x1763;
            let x1767 = x1338 - x1341;
            let x1768 = x1767 - x1338;
            let x1769 = x1341 + x1768;
            let x1770 = 2.0 * x1769;
            let x1771 = 2.0 * x1764;
            let x1772 = 2.0 * x1770;
            let x1773 = x463 * x1757;
            let x1774 = 0.01 * x1773;
            let x1775 = x216 * x1758;
            let x1776 = x123 * x1771;
            let x1777 = x1775 + x1776;
            let x1778 = 0.01 * x1777;
            let x1779 = x217 * x1759;
            let x1780 = x124 * x1772;
            let x1781 = x1779 + x1780;
            let x1782 = 0.01 * x1781;
            let x1783 = x1774 + x1778;
            let x1784 = x1782 + x1783;
            let x1785 = 0.5 * x1784;
            let x1786 = x461 * x1757;
            let x1787 = 0.01 * x1786;
            let x1788 = x217 * x1758;
            let x1789 = x124 * x1771;
            let x1790 = x1788 + x1789;
            let x1791 = 0.01 * x1790;
            let x1793 = x216 * x1759;
            let x1794 = x123 * x1772;
            let x1795 = x1793 + x1794;
            let x1796 = 0.01 * x1795;
            let x1797 = x1787 - x1791;
            let x1798 = x1796 + x1797;
            let x1799 = 0.5 * x1798;
            let x1800 = x217 * x1757;
            let x1801 = 0.01 * x1800;
            let x1802 = x461 * x1758;
            let x1803 = x295 * x1771;
            let x1804 = x1802 + x1803;
            let x1805 = 0.01 * x1804;
            let x1806 = x463 * x1759;
            let x1807 = x297 * x1772;
            let x1808 = x1806 + x1807;
            let x1809 = 0.01 * x1808;
            let x1811 = x1801 + x1805;
            let x1812 = x1811 - x1809;
            let x1813 = 0.5 * x1812;
            let x1814 = x216 * x1757;
            let x1815 = 0.01 * x1814;
            let x1817 = x463 * x1758;
            let x1818 = x297 * x1771;
            let x1819 = x1817 + x1818;
            let x1820 = 0.01 * x1819;
            let x1821 = x461 * x1759;
            let x1822 = x295 * x1772;
            let x1823 = x1821 + x1822;
            let x1824 = 0.01 * x1823;
            let x1825 = x1820 - x1815;
            let x1826 = x1824 + x1825;
            let x1827 = 0.5 * x1826;
            let x1828 = x444 + x448;
            let x1829 = x740 + x1828;
            let x1830 = x741 + x1829;
            let x1831 = 0.01 * x1775;
            let x1832 = 0.01 * x1779;
            let x1833 = x1774 + x1831;
            let x1834 = x1832 + x1833;
            let x1835 = 0.5 * x1834;
            let x1836 = x1785 + x1835;
            let x1837 = q[1] * 0.04;
            let x1838 = x1830 * x1837;
            let x1840 = x1836 - x1838;
            let x1842 = 0.01 * x1788;
            let x1843 = 0.01 * x1793;
            let x1845 = x1842 - x1787;
            let x1846 = x1845 - x1843;
            let x1847 = 0.5 * x1846;
            let x1849 = x1847 - x1799;
            let x1850 = q[2] * 0.04;
            let x1851 = x1830 * x1850;
            let x1853 = x1849 - x1851;
            let x1854 = 0.01 * x1802;
            let x1855 = 0.01 * x1806;
            let x1856 = x1801 + x1854;
            let x1858 = x1855 - x1856;
            let x1859 = 0.5 * x1858;
            let x1861 = x1859 - x1813;
            let x1862 = x754 * x1830;
            let x1864 = x1861 - x1862;
            let x1865 = 0.01 * x1817;
            let x1867 = 0.01 * x1821;
            let x1869 = x1815 - x1865;
            let x1870 = x1869 - x1867;
            let x1871 = 0.5 * x1870;
            let x1873 = x1871 - x1827;
            let x1874 = x773 * x1830;
            let x1876 = x1873 - x1874;
            let x1878 = x1325 + x1727;
            let x1879 = x1878 - x1326;
            let x1880 = 2.0 * x1879;
            let x1881 = x1408 + x1412;
            let x1883 = x1413 - x1881;
            let x1884 = x1409 + x1883;
            let x1885 = 2.0 * x1884;
            let x1887 = x1315 - x1319;
            let x1888 = x1887 - x1316;
            let x1889 = x1320 + x1888;
            let x1890 = 2.0 * x1889;
            let x1891 = 2.0 * x1880;
            let x1892 = 2.0 * x1885;
            let x1893 = 2.0 * x1890;
            let x1894 = qd[6] * qd[8];
            let x1895 = qd[5] * qd[7];
            let x1897 = x1894 + x1895;
            let x1899 = x1895 - x1897;
            let x1900 = x1894 + x1899;
            let x1901 = 2.0 * x1900;
            let x1903 = x1360 - x1363;
            let x1904 = x1903 - x1360;
            let x1905 = x1363 + x1904;
            let x1906 = 2.0 * x1905;
            let x1907 = 2.0 * x1901;
            let x1908 = 2.0 * x1906;
            let x1909 = x219 * x1891;
            let x1910 = 0.1 * x1909;
            let x1911 = x844 * x1892;
            let x1912 = x1283 * x1907;
            let x1913 = x1911 + x1912;
            let x1914 = 0.2 * x1913;
            let x1915 = x846 * x1893;
            let x1916 = x1284 * x1908;
            let x1917 = x1915 + x1916;
            let x1918 = 0.3 * x1917;
            let x1919 = x1910 + x1914;
            let x1920 = x1918 + x1919;
            let x1921 = 0.5 * x1920;
            let x1922 = x218 * x1891;
            let x1923 = 0.1 * x1922;
            let x1924 = x846 * x1892;
            let x1925 = x1284 * x1907;
            let x1926 = x1924 + x1925;
            let x1927 = 0.2 * x1926;
            let x1929 = x844 * x1893;
            let x1930 = x1283 * x1908;
            let x1931 = x1929 + x1930;
            let x1932 = 0.3 * x1931;
            let x1933 = x1923 - x1927;
            let x1934 = x1932 + x1933;
            let x1935 = 0.5 * x1934;
            let x1936 = x846 * x1891;
            let x1937 = 0.1 * x1936;
            let x1938 = x218 * x1892;
            let x1939 = x125 * x1907;
            let x1940 = x1938 + x1939;
            let x1941 = 0.2 * x1940;
            let x1942 = x219 * x1893;
            let x1943 = x126 * x1908;
            let x1944 = x1942 + x1943;
            let x1945 = 0.3 * x1944;
            let x1947 = x1937 + x1941;
            let x1948 = x1947 - x1945;
            let x1949 = 0.5 * x1948;
            let x1950 = x844 * x1891;
            let x1951 = 0.1 * x1950;
            let x1953 = x219 * x1892;
            let x1954 = x126 * x1907;
            let x1955 = x1953 + x1954;
            let x1956 = 0.2 * x1955;
            let x1957 = x218 * x1893;
            let x1958 = x125 * x1908;
            let x1959 = x1957 + x1958;
            let x1960 = 0.3 * x1959;
            let x1961 = x1956 - x1951;
            let x1962 = x1960 + x1961;
            let x1963 = 0.5 * x1962;
            let x1964 = x742 + x743;
            let x1965 = x828 + x1964;
            let x1966 = x831 + x1965;
            let x1967 = 0.2 * x1911;
            let x1968 = 0.3 * x1915;
            let x1969 = x1910 + x1967;
            let x1970 = x1968 + x1969;
            let x1971 = 0.5 * x1970;
            let x1972 = x1921 + x1971;
            let x1973 = q[5] * 0.8000000000000002;
            let x1974 = x1966 * x1973;
            let x1976 = x1972 - x1974;
            let x1978 = 0.2 * x1924;
            let x1979 = 0.3 * x1929;
            let x1981 = x1978 - x1923;
            let x1982 = x1981 - x1979;
            let x1983 = 0.5 * x1982;
            let x1985 = x1983 - x1935;
            let x1986 = q[6] * 0.8000000000000002;
            let x1987 = x1966 * x1986;
            let x1989 = x1985 - x1987;
            let x1990 = 0.2 * x1938;
            let x1991 = 0.3 * x1942;
            let x1992 = x1937 + x1990;
            let x1994 = x1991 - x1992;
            let x1995 = 0.5 * x1994;
            let x1997 = x1995 - x1949;
            let x1998 = q[7] * 0.8000000000000002;
            let x1999 = x1966 * x1998;
            let x2001 = x1997 - x1999;
            let x2002 = 0.2 * x1953;
            let x2004 = 0.3 * x1957;
            let x2006 = x1951 - x2002;
            let x2007 = x2006 - x2004;
            let x2008 = 0.5 * x2007;
            let x2010 = x2008 - x1963;
            let x2011 = q[8] * 0.8000000000000002;
            let x2012 = x1966 * x2011;
            let x2014 = x2010 - x2012;
            let x2015 = x1735 + x1976;
            let x2016 = x1736 + x1989;
            let x2017 = x1737 + x2001;
            let x2018 = x2014 - x1738;
            out[0] = x1734;
            out[1] = x1840;
            out[2] = x1853;
            out[3] = x1864;
            out[4] = x1876;
            out[5] = x2015;
            out[6] = x2016;
            out[7] = x2017;
            out[8] = x2018;
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
            eval_newton_shared_0(q, qd, t, &mut s);
            eval_newton_part_0(q, qd, t, &s, phi, phi_q, mass, force);
            eval_newton_part_1(q, qd, &s, force);
        }
        #[inline(never)]
        fn eval_newton_shared_0(q: &[f64; 9], qd: &[f64; 9], t: f64, s: &mut [f64; 94]) {
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
            let x531 = 2.0 * x126;
            s[14] = x531;
            let x742 = qd[5] * qd[5];
            s[15] = x742;
            let x743 = qd[6] * qd[6];
            s[16] = x743;
            let x828 = qd[7] * qd[7];
            s[17] = x828;
            let x831 = qd[8] * qd[8];
            s[18] = x831;
            let x844 = 2.0 * qd[7];
            s[19] = x844;
            let x846 = 2.0 * qd[8];
            s[20] = x846;
            let x1265 = x25 + x26;
            s[21] = x1265;
            let x1283 = 2.0 * q[7];
            s[22] = x1283;
            let x1284 = 2.0 * q[8];
            s[23] = x1284;
            let x1314 = x153 + x154;
            s[24] = x1314;
            let x1315 = q[7] * qd[6];
            s[25] = x1315;
            let x1316 = q[6] * qd[7];
            s[26] = x1316;
            let x1319 = q[8] * qd[5];
            s[27] = x1319;
            let x1320 = q[5] * qd[8];
            s[28] = x1320;
            let x1325 = q[8] * qd[7];
            s[29] = x1325;
            let x1326 = q[7] * qd[8];
            s[30] = x1326;
            let x1360 = qd[6] * qd[7];
            s[31] = x1360;
            let x1363 = qd[5] * qd[8];
            s[32] = x1363;
            let x1383 = 2.0 * x1265;
            s[33] = x1383;
            let x1384 = x1383 - 1.0;
            s[34] = x1384;
            let x1385 = q[6] * q[8];
            s[35] = x1385;
            let x1386 = 2.0 * x1385;
            s[36] = x1386;
            let x1387 = q[5] * q[7];
            s[37] = x1387;
            let x1388 = 2.0 * x1387;
            s[38] = x1388;
            let x1390 = x1386 - x1388;
            s[39] = x1390;
            let x1395 = -x1390;
            s[40] = x1395;
            let x1396 = x1395.atan2(x1384);
            s[41] = x1396;
            let x1407 = 2.0 * x1314;
            s[42] = x1407;
            let x1408 = q[8] * qd[6];
            s[43] = x1408;
            let x1409 = q[6] * qd[8];
            s[44] = x1409;
            let x1410 = x1408 + x1409;
            s[45] = x1410;
            let x1411 = 2.0 * x1410;
            s[46] = x1411;
            let x1412 = q[7] * qd[5];
            s[47] = x1412;
            let x1413 = q[5] * qd[7];
            s[48] = x1413;
            let x1414 = x1412 + x1413;
            s[49] = x1414;
            let x1415 = 2.0 * x1414;
            s[50] = x1415;
            let x1417 = x1411 - x1415;
            s[51] = x1417;
            let x1418 = x1384 * x1384;
            s[52] = x1418;
            let x1419 = x1390 * x1390;
            s[53] = x1419;
            let x1420 = x1418 + x1419;
            s[54] = x1420;
            let x1421 = x1384 * x1417;
            s[55] = x1421;
            let x1423 = x1390 * x1407;
            s[56] = x1423;
            let x1424 = x1423 - x1421;
            s[57] = x1424;
            let x1425 = 1.0 / x1420;
            s[58] = x1425;
            let x1426 = x1424 * x1425;
            s[59] = x1426;
            let x1427 = 0.1 * x1426;
            s[60] = x1427;
            let x1429 = x11 - x1427;
            s[61] = x1429;
            let x1706 = 2.0 * x1396;
            s[62] = x1706;
            let x1708 = x1429 - x1706;
            s[63] = x1708;
            let x1727 = x174 - x173;
            s[64] = x1727;
            let x1878 = x1325 + x1727;
            s[65] = x1878;
            let x1879 = x1878 - x1326;
            s[66] = x1879;
            let x1880 = 2.0 * x1879;
            s[67] = x1880;
            let x1881 = x1408 + x1412;
            s[68] = x1881;
            let x1883 = x1413 - x1881;
            s[69] = x1883;
            let x1884 = x1409 + x1883;
            s[70] = x1884;
            let x1885 = 2.0 * x1884;
            s[71] = x1885;
            let x1887 = x1315 - x1319;
            s[72] = x1887;
            let x1888 = x1887 - x1316;
            s[73] = x1888;
            let x1889 = x1320 + x1888;
            s[74] = x1889;
            let x1890 = 2.0 * x1889;
            s[75] = x1890;
            let x1891 = 2.0 * x1880;
            s[76] = x1891;
            let x1892 = 2.0 * x1885;
            s[77] = x1892;
            let x1893 = 2.0 * x1890;
            s[78] = x1893;
            let x1894 = qd[6] * qd[8];
            s[79] = x1894;
            let x1895 = qd[5] * qd[7];
            s[80] = x1895;
            let x1897 = x1894 + x1895;
            s[81] = x1897;
            let x1899 = x1895 - x1897;
            s[82] = x1899;
            let x1900 = x1894 + x1899;
            s[83] = x1900;
            let x1901 = 2.0 * x1900;
            s[84] = x1901;
            let x1903 = x1360 - x1363;
            s[85] = x1903;
            let x1904 = x1903 - x1360;
            s[86] = x1904;
            let x1905 = x1363 + x1904;
            s[87] = x1905;
            let x1906 = 2.0 * x1905;
            s[88] = x1906;
            let x1907 = 2.0 * x1901;
            s[89] = x1907;
            let x1908 = 2.0 * x1906;
            s[90] = x1908;
            let x1964 = x742 + x743;
            s[91] = x1964;
            let x1965 = x828 + x1964;
            s[92] = x1965;
            let x1966 = x831 + x1965;
            s[93] = x1966;
        }
        #[inline(never)]
        fn eval_newton_part_0(
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
            let x286 = 1.0 + q[0];
            let x287 = x286 * x286;
            let x288 = q[1] * q[1];
            let x289 = q[2] * q[2];
            let x293 = 2.0 * x286;
            let x294 = qd[0] * x293;
            let x295 = q[1] * 2.0;
            let x297 = q[2] * 2.0;
            let x444 = qd[1] * qd[1];
            let x448 = qd[2] * qd[2];
            let x461 = 2.0 * qd[1];
            let x463 = 2.0 * qd[2];
            let x474 = -s[8];
            let x527 = 2.0 * x124;
            let x529 = 2.0 * s[7];
            let x533 = x124 * x527;
            let x535 = 0.01 * x533;
            let x537 = s[7] * x529;
            let x541 = s[8] * s[14];
            let x551 = x23 * 0.04;
            let x553 = 2.0 * x123;
            let x554 = x124 * x553;
            let x555 = 0.01 * x554;
            let x556 = s[7] * s[14];
            let x560 = s[8] * x529;
            let x566 = x52 * 0.04;
            let x596 = x123 * x527;
            let x598 = 0.01 * x596;
            let x606 = x123 * x553;
            let x607 = 0.01 * x606;
            let x611 = x24 * 0.04;
            let x740 = qd[3] * qd[3];
            let x741 = qd[4] * qd[4];
            let x754 = q[3] * 0.04;
            let x773 = q[4] * 0.04;
            let x1248 = x288 + x289;
            let x1249 = q[2] * q[3];
            let x1250 = 2.0 * x1249;
            let x1251 = q[1] * q[4];
            let x1252 = 2.0 * x1251;
            let x1253 = q[2] * q[4];
            let x1254 = 2.0 * x1253;
            let x1255 = q[1] * q[3];
            let x1256 = 2.0 * x1255;
            let x1257 = x1250 + x1252;
            let x1258 = q[1] * q[2];
            let x1259 = 2.0 * x1258;
            let x1261 = x1254 - x1256;
            let x1262 = x54 + x1259;
            let x1263 = q[7] * q[7];
            let x1264 = q[8] * q[8];
            let x1266 = q[6] * q[7];
            let x1267 = 2.0 * x1266;
            let x1268 = q[5] * q[8];
            let x1269 = 2.0 * x1268;
            let x1271 = x1267 - x1269;
            let x1272 = q[7] * q[8];
            let x1273 = 2.0 * x1272;
            let x1274 = x51 + x1273;
            let x1275 = -x1274;
            let x1276 = x23 + x1248;
            let x1277 = x24 + x1276;
            let x1278 = x1277 - 1.0;
            let x1279 = x1263 + s[21];
            let x1280 = x1264 + x1279;
            let x1281 = x1280 - 1.0;
            let x1282 = -x295;
            let x1285 = -s[23];
            let x1286 = -s[22];
            let x1288 = q[3] * qd[2];
            let x1289 = q[2] * qd[3];
            let x1292 = q[4] * qd[1];
            let x1293 = q[1] * qd[4];
            let x1296 = q[4] * qd[2];
            let x1297 = q[2] * qd[4];
            let x1300 = q[3] * qd[1];
            let x1301 = q[1] * qd[3];
            let x1305 = q[2] * qd[1];
            let x1306 = q[1] * qd[2];
            let x1338 = qd[2] * qd[3];
            let x1341 = qd[1] * qd[4];
            let x1344 = qd[2] * qd[4];
            let x1347 = qd[1] * qd[3];
            let x1391 = x287.sqrt();
            let x1392 = x1391 - 1.0;
            let x1400 = 2.0 * x1391;
            let x1401 = 1.0 / x1400;
            let x1402 = x294 * x1401;
            let x1403 = 0.8 * x1402;
            let x1405 = x5 - x1403;
            let x1441 = 2.0 * x297;
            let x1442 = x297 * x1441;
            let x1443 = 0.01 * x1442;
            let x1444 = x607 + x1443;
            let x1445 = x535 + x1444;
            let x1446 = 0.5 * x1445;
            let x1447 = x288 * 0.04;
            let x1448 = x1446 + x1447;
            let x1449 = 2.0 * x295;
            let x1450 = x297 * x1449;
            let x1451 = 0.01 * x1450;
            let x1452 = x1451 - x598;
            let x1453 = x555 + x1452;
            let x1454 = 0.5 * x1453;
            let x1456 = 0.04 * x1258;
            let x1457 = x1456 - x1454;
            let x1458 = x297 * x527;
            let x1459 = 0.01 * x1458;
            let x1460 = x123 * x1449;
            let x1461 = 0.01 * x1460;
            let x1462 = x124 * x1441;
            let x1463 = 0.01 * x1462;
            let x1465 = x1459 + x1461;
            let x1466 = x1465 - x1463;
            let x1467 = 0.5 * x1466;
            let x1469 = 0.04 * x1255;
            let x1470 = x1469 - x1467;
            let x1471 = x297 * x553;
            let x1472 = 0.01 * x1471;
            let x1474 = x123 * x1441;
            let x1475 = 0.01 * x1474;
            let x1476 = x124 * x1449;
            let x1477 = 0.01 * x1476;
            let x1478 = x1475 - x1472;
            let x1479 = x1477 + x1478;
            let x1480 = 0.5 * x1479;
            let x1482 = 0.04 * x1251;
            let x1483 = x1482 - x1480;
            let x1484 = x295 * x1441;
            let x1485 = 0.01 * x1484;
            let x1487 = x555 - x1485;
            let x1488 = x1487 - x598;
            let x1489 = 0.5 * x1488;
            let x1490 = x1456 + x1489;
            let x1491 = x295 * x1449;
            let x1492 = 0.01 * x1491;
            let x1493 = x535 + x1492;
            let x1494 = x607 + x1493;
            let x1495 = 0.5 * x1494;
            let x1496 = x289 * 0.04;
            let x1497 = x1495 + x1496;
            let x1498 = x295 * x527;
            let x1499 = 0.01 * x1498;
            let x1502 = x1499 - x1477;
            let x1503 = x1502 - x1475;
            let x1504 = 0.5 * x1503;
            let x1505 = 0.04 * x1249;
            let x1506 = x1504 + x1505;
            let x1507 = x295 * x553;
            let x1508 = 0.01 * x1507;
            let x1509 = x1463 + x1508;
            let x1511 = x1461 - x1509;
            let x1512 = 0.5 * x1511;
            let x1513 = 0.04 * x1253;
            let x1514 = x1512 + x1513;
            let x1515 = x1459 - x1509;
            let x1516 = 0.5 * x1515;
            let x1517 = x1469 + x1516;
            let x1519 = x1477 - x1499;
            let x1520 = x1519 - x1472;
            let x1521 = 0.5 * x1520;
            let x1522 = x1505 + x1521;
            let x1523 = x1443 + x1493;
            let x1524 = 0.5 * x1523;
            let x1525 = x551 + x1524;
            let x1527 = x1485 - x555;
            let x1528 = x1527 - x1451;
            let x1529 = 0.5 * x1528;
            let x1530 = x566 + x1529;
            let x1531 = x1478 - x1499;
            let x1532 = 0.5 * x1531;
            let x1533 = x1482 + x1532;
            let x1535 = x1508 - x1465;
            let x1536 = 0.5 * x1535;
            let x1537 = x1513 + x1536;
            let x1538 = x1452 - x1485;
            let x1539 = 0.5 * x1538;
            let x1540 = x566 + x1539;
            let x1541 = x1444 + x1492;
            let x1542 = 0.5 * x1541;
            let x1543 = x611 + x1542;
            let x1544 = 2.0 * s[22];
            let x1545 = 2.0 * s[23];
            let x1546 = 0.1 * x541;
            let x1547 = s[22] * x1544;
            let x1548 = 0.2 * x1547;
            let x1549 = s[23] * x1545;
            let x1550 = 0.3 * x1549;
            let x1551 = x1546 + x1548;
            let x1552 = x1550 + x1551;
            let x1553 = 0.5 * x1552;
            let x1554 = s[5] * 0.8000000000000002;
            let x1555 = x1553 + x1554;
            let x1556 = 0.1 * x560;
            let x1557 = s[22] * x1545;
            let x1558 = 0.2 * x1557;
            let x1560 = s[23] * x1544;
            let x1561 = 0.3 * x1560;
            let x1562 = x1556 - x1558;
            let x1563 = x1561 + x1562;
            let x1564 = 0.5 * x1563;
            let x1566 = x50 * 0.8000000000000002;
            let x1567 = x1566 - x1564;
            let x1568 = s[8] * x1545;
            let x1569 = 0.1 * x1568;
            let x1570 = x529 * s[22];
            let x1571 = 0.2 * x1570;
            let x1572 = s[14] * s[23];
            let x1573 = 0.3 * x1572;
            let x1575 = x1569 + x1571;
            let x1576 = x1575 - x1573;
            let x1577 = 0.5 * x1576;
            let x1579 = 0.8000000000000002 * s[37];
            let x1580 = x1579 - x1577;
            let x1581 = s[8] * x1544;
            let x1582 = 0.1 * x1581;
            let x1584 = s[14] * s[22];
            let x1585 = 0.2 * x1584;
            let x1586 = x529 * s[23];
            let x1587 = 0.3 * x1586;
            let x1588 = x1585 - x1582;
            let x1589 = x1587 + x1588;
            let x1590 = 0.5 * x1589;
            let x1592 = 0.8000000000000002 * x1268;
            let x1593 = x1592 - x1590;
            let x1594 = 0.1 * x556;
            let x1596 = 0.2 * x1560;
            let x1597 = 0.3 * x1557;
            let x1599 = x1596 - x1594;
            let x1600 = x1599 - x1597;
            let x1601 = 0.5 * x1600;
            let x1602 = x1566 + x1601;
            let x1603 = 0.1 * x537;
            let x1604 = 0.2 * x1549;
            let x1605 = 0.3 * x1547;
            let x1606 = x1603 + x1604;
            let x1607 = x1605 + x1606;
            let x1608 = 0.5 * x1607;
            let x1609 = s[6] * 0.8000000000000002;
            let x1610 = x1608 + x1609;
            let x1611 = s[7] * x1545;
            let x1612 = 0.1 * x1611;
            let x1613 = 0.2 * x1586;
            let x1615 = 0.3 * x1584;
            let x1617 = x1612 - x1613;
            let x1618 = x1617 - x1615;
            let x1619 = 0.5 * x1618;
            let x1620 = 0.8000000000000002 * x1266;
            let x1621 = x1619 + x1620;
            let x1622 = s[7] * x1544;
            let x1623 = 0.1 * x1622;
            let x1624 = 0.2 * x1572;
            let x1625 = 0.3 * x1570;
            let x1626 = x1623 + x1624;
            let x1628 = x1625 - x1626;
            let x1629 = 0.5 * x1628;
            let x1630 = 0.8000000000000002 * s[35];
            let x1631 = x1629 + x1630;
            let x1632 = 0.1 * x1572;
            let x1633 = 0.2 * x1622;
            let x1634 = 0.3 * x1568;
            let x1635 = x1632 + x1633;
            let x1637 = x1634 - x1635;
            let x1638 = 0.5 * x1637;
            let x1639 = x1579 + x1638;
            let x1640 = 0.1 * x1586;
            let x1641 = 0.2 * x1611;
            let x1643 = 0.3 * x1581;
            let x1645 = x1640 - x1641;
            let x1646 = x1645 - x1643;
            let x1647 = 0.5 * x1646;
            let x1648 = x1620 + x1647;
            let x1649 = 0.1 * x1549;
            let x1650 = 0.2 * x537;
            let x1651 = x541 * 0.3;
            let x1652 = x1649 + x1650;
            let x1653 = x1651 + x1652;
            let x1654 = 0.5 * x1653;
            let x1655 = 0.8000000000000002 * x1263;
            let x1656 = x1654 + x1655;
            let x1657 = 0.1 * x1560;
            let x1659 = 0.2 * x556;
            let x1660 = x560 * 0.3;
            let x1662 = x1659 - x1657;
            let x1663 = x1662 - x1660;
            let x1664 = 0.5 * x1663;
            let x1665 = 0.8000000000000002 * x1272;
            let x1666 = x1664 + x1665;
            let x1667 = 0.1 * x1584;
            let x1668 = 0.2 * x1581;
            let x1670 = 0.3 * x1611;
            let x1672 = x1667 - x1668;
            let x1673 = x1672 - x1670;
            let x1674 = 0.5 * x1673;
            let x1675 = x1592 + x1674;
            let x1676 = 0.1 * x1570;
            let x1677 = 0.2 * x1568;
            let x1678 = 0.3 * x1622;
            let x1679 = x1676 + x1677;
            let x1681 = x1678 - x1679;
            let x1682 = 0.5 * x1681;
            let x1683 = x1630 + x1682;
            let x1684 = 0.1 * x1557;
            let x1686 = 0.2 * x560;
            let x1687 = x556 * 0.3;
            let x1689 = x1686 - x1684;
            let x1690 = x1689 - x1687;
            let x1691 = 0.5 * x1690;
            let x1692 = x1665 + x1691;
            let x1693 = 0.1 * x1547;
            let x1694 = 0.2 * x541;
            let x1695 = x537 * 0.3;
            let x1696 = x1693 + x1694;
            let x1697 = x1695 + x1696;
            let x1698 = 0.5 * x1697;
            let x1699 = 0.8000000000000002 * x1264;
            let x1700 = x1698 + x1699;
            let x1701 = 50.0 * x1392;
            let x1703 = x1405 - x1701;
            let x1704 = x293 * x1401;
            let x1705 = x1703 * x1704;
            let x1709 = s[22] * s[34];
            let x1710 = x529 * s[39];
            let x1711 = x1709 + x1710;
            let x1712 = s[58] * x1711;
            let x1722 = s[63] * x1712;
            let x1729 = s[4] * s[22];
            let x1734 = 1.0 + x1705;
            let x1735 = x1722 - x1729;
            let x1742 = x1306 - x1305;
            let x1743 = x177 + x1742;
            let x1744 = x1743 - x178;
            let x1745 = 2.0 * x1744;
            let x1746 = x1296 + x1300;
            let x1748 = x1301 - x1746;
            let x1749 = x1297 + x1748;
            let x1750 = 2.0 * x1749;
            let x1753 = x1288 - x1292;
            let x1754 = x1753 - x1289;
            let x1755 = x1293 + x1754;
            let x1756 = 2.0 * x1755;
            let x1757 = 2.0 * x1745;
            let x1758 = 2.0 * x1750;
            let x1759 = 2.0 * x1756;
            let x1760 = x1344 + x1347;
            let x1762 = x1347 - x1760;
            let x1763 = x1344 + x1762;
            let x1764 = 2.0 * x1763;
            let x1767 = x1338 - x1341;
            let x1768 = x1767 - x1338;
            let x1769 = x1341 + x1768;
            let x1770 = 2.0 * x1769;
            let x1771 = 2.0 * x1764;
            let x1772 = 2.0 * x1770;
            let x1773 = x463 * x1757;
            let x1774 = 0.01 * x1773;
            let x1775 = x216 * x1758;
            let x1776 = x123 * x1771;
            let x1777 = x1775 + x1776;
            let x1778 = 0.01 * x1777;
            let x1779 = x217 * x1759;
            let x1780 = x124 * x1772;
            let x1781 = x1779 + x1780;
            let x1782 = 0.01 * x1781;
            let x1783 = x1774 + x1778;
            let x1784 = x1782 + x1783;
            let x1785 = 0.5 * x1784;
            let x1786 = x461 * x1757;
            let x1787 = 0.01 * x1786;
            let x1788 = x217 * x1758;
            let x1789 = x124 * x1771;
            let x1790 = x1788 + x1789;
            let x1791 = 0.01 * x1790;
            let x1793 = x216 * x1759;
            let x1794 = x123 * x1772;
            let x1795 = x1793 + x1794;
            let x1796 = 0.01 * x1795;
            let x1797 = x1787 - x1791;
            let x1798 = x1796 + x1797;
            let x1799 = 0.5 * x1798;
            let x1800 = x217 * x1757;
            let x1801 = 0.01 * x1800;
            let x1802 = x461 * x1758;
            let x1803 = x295 * x1771;
            let x1804 = x1802 + x1803;
            let x1805 = 0.01 * x1804;
            let x1806 = x463 * x1759;
            let x1807 = x297 * x1772;
            let x1808 = x1806 + x1807;
            let x1809 = 0.01 * x1808;
            let x1811 = x1801 + x1805;
            let x1812 = x1811 - x1809;
            let x1813 = 0.5 * x1812;
            let x1814 = x216 * x1757;
            let x1815 = 0.01 * x1814;
            let x1817 = x463 * x1758;
            let x1818 = x297 * x1771;
            let x1819 = x1817 + x1818;
            let x1820 = 0.01 * x1819;
            let x1821 = x461 * x1759;
            let x1822 = x295 * x1772;
            let x1823 = x1821 + x1822;
            let x1824 = 0.01 * x1823;
            let x1825 = x1820 - x1815;
            let x1826 = x1824 + x1825;
            let x1827 = 0.5 * x1826;
            let x1828 = x444 + x448;
            let x1829 = x740 + x1828;
            let x1830 = x741 + x1829;
            let x1831 = 0.01 * x1775;
            let x1832 = 0.01 * x1779;
            let x1833 = x1774 + x1831;
            let x1834 = x1832 + x1833;
            let x1835 = 0.5 * x1834;
            let x1836 = x1785 + x1835;
            let x1837 = q[1] * 0.04;
            let x1838 = x1830 * x1837;
            let x1840 = x1836 - x1838;
            let x1842 = 0.01 * x1788;
            let x1843 = 0.01 * x1793;
            let x1845 = x1842 - x1787;
            let x1846 = x1845 - x1843;
            let x1847 = 0.5 * x1846;
            let x1849 = x1847 - x1799;
            let x1850 = q[2] * 0.04;
            let x1851 = x1830 * x1850;
            let x1853 = x1849 - x1851;
            let x1854 = 0.01 * x1802;
            let x1855 = 0.01 * x1806;
            let x1856 = x1801 + x1854;
            let x1858 = x1855 - x1856;
            let x1859 = 0.5 * x1858;
            let x1861 = x1859 - x1813;
            let x1862 = x754 * x1830;
            let x1864 = x1861 - x1862;
            let x1865 = 0.01 * x1817;
            let x1867 = 0.01 * x1821;
            let x1869 = x1815 - x1865;
            let x1870 = x1869 - x1867;
            let x1871 = 0.5 * x1870;
            let x1873 = x1871 - x1827;
            let x1874 = x773 * x1830;
            let x1876 = x1873 - x1874;
            let x1909 = s[13] * s[76];
            let x1910 = 0.1 * x1909;
            let x1911 = s[19] * s[77];
            let x1912 = s[22] * s[89];
            let x1913 = x1911 + x1912;
            let x1914 = 0.2 * x1913;
            let x1915 = s[20] * s[78];
            let x1916 = s[23] * s[90];
            let x1917 = x1915 + x1916;
            let x1918 = 0.3 * x1917;
            let x1919 = x1910 + x1914;
            let x1920 = x1918 + x1919;
            let x1921 = 0.5 * x1920;
            let x1967 = 0.2 * x1911;
            let x1968 = 0.3 * x1915;
            let x1969 = x1910 + x1967;
            let x1970 = x1968 + x1969;
            let x1971 = 0.5 * x1970;
            let x1972 = x1921 + x1971;
            let x1973 = q[5] * 0.8000000000000002;
            let x1974 = s[93] * x1973;
            let x1976 = x1972 - x1974;
            let x2015 = x1735 + x1976;
            phi[0] = x1257;
            phi_q[0] = x124;
            phi_q[1] = x123;
            phi_q[2] = x297;
            phi_q[3] = x295;
            phi[1] = x1261;
            phi_q[4] = x128;
            phi_q[5] = x124;
            phi_q[6] = x1282;
            phi_q[7] = x297;
            phi[2] = x1262;
            phi_q[8] = x297;
            phi_q[9] = x295;
            phi_q[10] = x124;
            phi_q[11] = x123;
            phi[3] = x1271;
            phi_q[12] = x1285;
            phi_q[13] = s[22];
            phi_q[14] = s[8];
            phi_q[15] = x127;
            phi[4] = x1275;
            phi_q[16] = x474;
            phi_q[17] = x127;
            phi_q[18] = x1285;
            phi_q[19] = x1286;
            phi[5] = x1278;
            phi_q[20] = x295;
            phi_q[21] = x297;
            phi_q[22] = x123;
            phi_q[23] = x124;
            phi[6] = x1281;
            phi_q[24] = s[7];
            phi_q[25] = s[8];
            phi_q[26] = s[22];
            phi_q[27] = s[23];
            mass[0] = 2.0;
            mass[1] = x1448;
            mass[2] = x1457;
            mass[3] = x1470;
            mass[4] = x1483;
            mass[5] = x1490;
            mass[6] = x1497;
            mass[7] = x1506;
            mass[8] = x1514;
            mass[9] = x1517;
            mass[10] = x1522;
            mass[11] = x1525;
            mass[12] = x1530;
            mass[13] = x1533;
            mass[14] = x1537;
            mass[15] = x1540;
            mass[16] = x1543;
            mass[17] = x1555;
            mass[18] = x1567;
            mass[19] = x1580;
            mass[20] = x1593;
            mass[21] = x1602;
            mass[22] = x1610;
            mass[23] = x1621;
            mass[24] = x1631;
            mass[25] = x1639;
            mass[26] = x1648;
            mass[27] = x1656;
            mass[28] = x1666;
            mass[29] = x1675;
            mass[30] = x1683;
            mass[31] = x1692;
            mass[32] = x1700;
            force[0] = x1734;
            force[1] = x1840;
            force[2] = x1853;
            force[3] = x1864;
            force[4] = x1876;
            force[5] = x2015;
        }
        #[inline(never)]
        fn eval_newton_part_1(
            q: &[f64; 9],
            qd: &[f64; 9],
            s: &[f64; 94],
            force: &mut [f64; 9],
        ) {
            let x218 = 2.0 * qd[5];
            let x1713 = s[23] * s[34];
            let x1715 = s[14] * s[39];
            let x1716 = x1715 - x1713;
            let x1717 = s[58] * x1716;
            let x1718 = s[7] * s[34];
            let x1719 = s[58] * x1718;
            let x1720 = s[8] * s[34];
            let x1721 = s[58] * x1720;
            let x1723 = s[63] * x1717;
            let x1724 = s[63] * x1719;
            let x1725 = s[63] * x1721;
            let x1731 = s[4] * s[23];
            let x1732 = s[4] * s[7];
            let x1733 = s[4] * s[8];
            let x1736 = x1723 + x1731;
            let x1737 = x1724 + x1732;
            let x1738 = x1725 + x1733;
            let x1922 = x218 * s[76];
            let x1923 = 0.1 * x1922;
            let x1924 = s[20] * s[77];
            let x1925 = s[23] * s[89];
            let x1926 = x1924 + x1925;
            let x1927 = 0.2 * x1926;
            let x1929 = s[19] * s[78];
            let x1930 = s[22] * s[90];
            let x1931 = x1929 + x1930;
            let x1932 = 0.3 * x1931;
            let x1933 = x1923 - x1927;
            let x1934 = x1932 + x1933;
            let x1935 = 0.5 * x1934;
            let x1936 = s[20] * s[76];
            let x1937 = 0.1 * x1936;
            let x1938 = x218 * s[77];
            let x1939 = s[7] * s[89];
            let x1940 = x1938 + x1939;
            let x1941 = 0.2 * x1940;
            let x1942 = s[13] * s[78];
            let x1943 = s[8] * s[90];
            let x1944 = x1942 + x1943;
            let x1945 = 0.3 * x1944;
            let x1947 = x1937 + x1941;
            let x1948 = x1947 - x1945;
            let x1949 = 0.5 * x1948;
            let x1950 = s[19] * s[76];
            let x1951 = 0.1 * x1950;
            let x1953 = s[13] * s[77];
            let x1954 = s[8] * s[89];
            let x1955 = x1953 + x1954;
            let x1956 = 0.2 * x1955;
            let x1957 = x218 * s[78];
            let x1958 = s[7] * s[90];
            let x1959 = x1957 + x1958;
            let x1960 = 0.3 * x1959;
            let x1961 = x1956 - x1951;
            let x1962 = x1960 + x1961;
            let x1963 = 0.5 * x1962;
            let x1978 = 0.2 * x1924;
            let x1979 = 0.3 * x1929;
            let x1981 = x1978 - x1923;
            let x1982 = x1981 - x1979;
            let x1983 = 0.5 * x1982;
            let x1985 = x1983 - x1935;
            let x1986 = q[6] * 0.8000000000000002;
            let x1987 = s[93] * x1986;
            let x1989 = x1985 - x1987;
            let x1990 = 0.2 * x1938;
            let x1991 = 0.3 * x1942;
            let x1992 = x1937 + x1990;
            let x1994 = x1991 - x1992;
            let x1995 = 0.5 * x1994;
            let x1997 = x1995 - x1949;
            let x1998 = q[7] * 0.8000000000000002;
            let x1999 = s[93] * x1998;
            let x2001 = x1997 - x1999;
            let x2002 = 0.2 * x1953;
            let x2004 = 0.3 * x1957;
            let x2006 = x1951 - x2002;
            let x2007 = x2006 - x2004;
            let x2008 = 0.5 * x2007;
            let x2010 = x2008 - x1963;
            let x2011 = q[8] * 0.8000000000000002;
            let x2012 = s[93] * x2011;
            let x2014 = x2010 - x2012;
            let x2016 = x1736 + x1989;
            let x2017 = x1737 + x2001;
            let x2018 = x2014 - x1738;
            force[6] = x2016;
            force[7] = x2017;
            force[8] = x2018;
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
            exact::mass(q, out)
        }
        fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            exact::force(q, qd, t, out)
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
        exact::mass(q, out)
    }
    fn force(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        exact::force(q, qd, t, out)
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
