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
        q: &[f64],
        qd: &[f64],
        t: f64,
        dq: &mut [f64],
        dqd: &mut [f64],
    ) {
        let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
        let dq: &mut [f64; 25] = dq.try_into().expect("dq must have 25 entries");
        let dqd: &mut [f64; 25] = dqd.try_into().expect("dqd must have 25 entries");
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
        let x458 = 2.0 * qd[0];
        let x461 = 2.0 * qd[1];
        let x463 = 2.0 * qd[2];
        let x910 = x130 * x361;
        let x930 = x130 * x355;
        let x946 = x131 * x355;
        let x948 = x132 * x361;
        let x962 = x131 * x361;
        let x964 = x132 * x355;
        let x972 = x129 * x361;
        let x985 = x129 * x355;
        let x1248 = 2.0 * x317;
        let x1249 = x302 * x302;
        let x1250 = x1248 * x1249;
        let x1252 = x302 * x458;
        let x1253 = x300 * x1250;
        let x1255 = x1252 - x1253;
        let x1256 = 50.0 * x317;
        let x1257 = 0.8 * x1255;
        let x1260 = x1256 + x1257;
        let x1262 = 2.0 * x302;
        let x1263 = x293 * x1250;
        let x1265 = x1262 - x1263;
        let x1266 = x295 * x1250;
        let x1268 = x297 * x1250;
        let x1270 = x317 * x1260;
        let x1272 = x312 * x1265;
        let x1273 = x1272 - x1270;
        let x1274 = x318 * x1260;
        let x1276 = x312 * x1266;
        let x1278 = x1274 + x1276;
        let x1279 = -x1278;
        let x1280 = x319 * x1260;
        let x1282 = x312 * x1268;
        let x1284 = x1280 + x1282;
        let x1285 = -x1284;
        let x1286 = 2.0 * x318;
        let x1287 = x1249 * x1286;
        let x1289 = x302 * x461;
        let x1290 = x300 * x1287;
        let x1292 = x1289 - x1290;
        let x1293 = 50.0 * x318;
        let x1294 = 0.8 * x1292;
        let x1297 = x1293 + x1294;
        let x1299 = x293 * x1287;
        let x1301 = x295 * x1287;
        let x1303 = x1262 - x1301;
        let x1304 = x297 * x1287;
        let x1306 = x317 * x1297;
        let x1308 = x312 * x1299;
        let x1310 = x1306 + x1308;
        let x1311 = -x1310;
        let x1312 = x318 * x1297;
        let x1314 = x312 * x1303;
        let x1315 = x1314 - x1312;
        let x1316 = x319 * x1297;
        let x1318 = x312 * x1304;
        let x1320 = x1316 + x1318;
        let x1321 = -x1320;
        let x1322 = 2.0 * x319;
        let x1323 = x1249 * x1322;
        let x1325 = x302 * x463;
        let x1326 = x300 * x1323;
        let x1328 = x1325 - x1326;
        let x1329 = 50.0 * x319;
        let x1330 = 0.8 * x1328;
        let x1333 = x1329 + x1330;
        let x1335 = x293 * x1323;
        let x1337 = x295 * x1323;
        let x1339 = x297 * x1323;
        let x1341 = x1262 - x1339;
        let x1342 = x317 * x1333;
        let x1344 = x312 * x1335;
        let x1346 = x1342 + x1344;
        let x1347 = -x1346;
        let x1348 = x318 * x1333;
        let x1350 = x312 * x1337;
        let x1352 = x1348 + x1350;
        let x1353 = -x1352;
        let x1354 = x319 * x1333;
        let x1356 = x312 * x1341;
        let x1357 = x1356 - x1354;
        let x1358 = 2.0 * x220;
        let x1359 = 2.0 * x74;
        let x1360 = x355 * x1359;
        let x1361 = 2.0 * x103;
        let x1362 = x131 * x1361;
        let x1364 = x1360 - x1362;
        let x1365 = x335 * x355;
        let x1366 = x74 * x222;
        let x1368 = x1365 - x1366;
        let x1370 = x131 * x325;
        let x1372 = x103 * x1358;
        let x1373 = x1372 - x1370;
        let x1374 = x1373 - x1368;
        let x1375 = x345 * x345;
        let x1376 = x1364 * x1375;
        let x1378 = x345 * x1374;
        let x1379 = x344 * x1376;
        let x1381 = x1378 - x1379;
        let x1382 = 2.0 * x360;
        let x1383 = 0.1 * x1381;
        let x1386 = x1382 + x1383;
        let x1389 = 4.0 * x103;
        let x1390 = x1389 - x946;
        let x1391 = x946 + x1390;
        let x1392 = x359 * x1376;
        let x1394 = x345 * x1391;
        let x1395 = x1394 - x1392;
        let x1397 = x962 + x964;
        let x1399 = x366 * x1376;
        let x1401 = x345 * x1397;
        let x1403 = x1399 + x1401;
        let x1405 = x985 + x1359;
        let x1406 = x368 * x1376;
        let x1408 = x345 * x1405;
        let x1409 = x1408 - x1406;
        let x1410 = x370 * x1376;
        let x1412 = x345 * x930;
        let x1413 = x1412 - x1410;
        let x1414 = x360 * x1386;
        let x1416 = x352 * x1395;
        let x1417 = x1416 - x1414;
        let x1418 = x367 * x1386;
        let x1420 = x352 * x1403;
        let x1422 = x1418 + x1420;
        let x1423 = -x1422;
        let x1424 = x369 * x1386;
        let x1426 = x352 * x1409;
        let x1427 = x1426 - x1424;
        let x1428 = x372 * x1386;
        let x1430 = x352 * x1413;
        let x1431 = x1430 - x1428;
        let x1432 = x14 * 2.0;
        let x1433 = x1427 + x1432;
        let x1434 = -x1431;
        let x1435 = 2.0 * x221;
        let x1436 = x361 * x1359;
        let x1437 = x132 * x1361;
        let x1438 = x1436 + x1437;
        let x1439 = x335 * x361;
        let x1440 = x74 * x223;
        let x1441 = x1439 + x1440;
        let x1443 = x132 * x325;
        let x1444 = x103 * x1435;
        let x1445 = x1443 + x1444;
        let x1446 = x1445 - x1441;
        let x1447 = x1375 * x1438;
        let x1449 = x345 * x1446;
        let x1450 = x344 * x1447;
        let x1452 = x1449 - x1450;
        let x1453 = 2.0 * x367;
        let x1454 = 0.1 * x1452;
        let x1457 = x1453 + x1454;
        let x1459 = x359 * x1447;
        let x1461 = x1401 - x1459;
        let x1462 = x948 + x1389;
        let x1463 = x1462 - x948;
        let x1464 = x366 * x1447;
        let x1466 = x345 * x1463;
        let x1467 = x1466 - x1464;
        let x1468 = x368 * x1447;
        let x1470 = x345 * x972;
        let x1471 = x1470 - x1468;
        let x1472 = x910 + x1359;
        let x1473 = x370 * x1447;
        let x1475 = x345 * x1472;
        let x1476 = x1475 - x1473;
        let x1477 = x360 * x1457;
        let x1479 = x352 * x1461;
        let x1480 = x1479 - x1477;
        let x1481 = x367 * x1457;
        let x1483 = x352 * x1467;
        let x1484 = x1483 - x1481;
        let x1485 = x369 * x1457;
        let x1487 = x352 * x1471;
        let x1488 = x1487 - x1485;
        let x1489 = x372 * x1457;
        let x1491 = x352 * x1476;
        let x1492 = x1491 - x1489;
        let x1493 = x1432 + x1492;
        let x1494 = -x1493;
        let x1495 = x129 * x1361;
        let x1497 = x74 * x220;
        let x1499 = x129 * x325;
        let x1501 = x1497 - x1499;
        let x1502 = x1375 * x1495;
        let x1504 = x345 * x1501;
        let x1505 = x344 * x1502;
        let x1506 = x1504 + x1505;
        let x1507 = 2.0 * x369;
        let x1508 = 0.1 * x1506;
        let x1511 = x1507 + x1508;
        let x1514 = x1359 - x985;
        let x1515 = x359 * x1502;
        let x1516 = x345 * x1514;
        let x1517 = x1515 + x1516;
        let x1518 = x366 * x1502;
        let x1520 = x1518 - x1470;
        let x1521 = x368 * x1502;
        let x1522 = x370 * x1502;
        let x1523 = x360 * x1511;
        let x1525 = x352 * x1517;
        let x1526 = x1525 - x1523;
        let x1527 = x367 * x1511;
        let x1529 = x352 * x1520;
        let x1530 = x1529 - x1527;
        let x1531 = x369 * x1511;
        let x1533 = x352 * x1521;
        let x1534 = x1533 - x1531;
        let x1535 = x372 * x1511;
        let x1537 = x352 * x1522;
        let x1538 = x1537 - x1535;
        let x1540 = x1526 - x1432;
        let x1541 = -x1538;
        let x1542 = x130 * x1361;
        let x1543 = x74 * x221;
        let x1545 = x130 * x325;
        let x1546 = x1545 - x1543;
        let x1547 = x1375 * x1542;
        let x1549 = x345 * x1546;
        let x1550 = x344 * x1547;
        let x1552 = x1549 - x1550;
        let x1553 = 2.0 * x372;
        let x1555 = 0.1 * x1552;
        let x1557 = x1553 - x1555;
        let x1558 = x359 * x1547;
        let x1560 = x1412 - x1558;
        let x1562 = x910 - x1359;
        let x1563 = x366 * x1547;
        let x1565 = x345 * x1562;
        let x1566 = x1565 - x1563;
        let x1567 = x368 * x1547;
        let x1569 = x370 * x1547;
        let x1571 = x360 * x1557;
        let x1572 = x352 * x1560;
        let x1573 = x1571 + x1572;
        let x1574 = x367 * x1557;
        let x1575 = x352 * x1566;
        let x1576 = x1574 + x1575;
        let x1577 = x369 * x1557;
        let x1578 = x352 * x1567;
        let x1580 = x1577 - x1578;
        let x1581 = x372 * x1557;
        let x1582 = x352 * x1569;
        let x1584 = x1581 - x1582;
        let x1585 = x1432 + x1576;
        let x1586 = -x1584;
        let x1587 = 0.8 * x317;
        let x1589 = x317 * x1587;
        let x1590 = -x1589;
        let x1591 = x318 * x1587;
        let x1592 = -x1591;
        let x1593 = x319 * x1587;
        let x1594 = -x1593;
        let x1595 = 0.8 * x318;
        let x1597 = x317 * x1595;
        let x1598 = -x1597;
        let x1599 = x318 * x1595;
        let x1600 = -x1599;
        let x1601 = x319 * x1595;
        let x1602 = -x1601;
        let x1603 = 0.8 * x319;
        let x1605 = x317 * x1603;
        let x1606 = -x1605;
        let x1607 = x318 * x1603;
        let x1608 = -x1607;
        let x1609 = x319 * x1603;
        let x1610 = -x1609;
        let x1612 = 0.1 * x360;
        let x1614 = x360 * x1612;
        let x1615 = -x1614;
        let x1616 = x367 * x1612;
        let x1617 = -x1616;
        let x1618 = x369 * x1612;
        let x1619 = -x1618;
        let x1620 = x372 * x1612;
        let x1622 = 0.1 * x367;
        let x1624 = x360 * x1622;
        let x1625 = -x1624;
        let x1626 = x367 * x1622;
        let x1627 = -x1626;
        let x1628 = x369 * x1622;
        let x1629 = -x1628;
        let x1630 = x372 * x1622;
        let x1633 = 0.1 * x369;
        let x1635 = x360 * x1633;
        let x1636 = -x1635;
        let x1637 = x367 * x1633;
        let x1638 = -x1637;
        let x1639 = x369 * x1633;
        let x1640 = -x1639;
        let x1641 = x372 * x1633;
        let x1643 = 0.1 * x372;
        let x1645 = x360 * x1643;
        let x1646 = x367 * x1643;
        let x1647 = x369 * x1643;
        let x1648 = x372 * x1643;
        let x1649 = -x1648;
        dq[0] = x1273;
        dq[1] = x1311;
        dq[2] = x1347;
        dq[3] = x1279;
        dq[4] = x1315;
        dq[5] = x1353;
        dq[6] = x1285;
        dq[7] = x1321;
        dq[8] = x1357;
        dq[9] = x1417;
        dq[10] = x1480;
        dq[11] = x1540;
        dq[12] = x1573;
        dq[13] = x1423;
        dq[14] = x1484;
        dq[15] = x1530;
        dq[16] = x1585;
        dq[17] = x1433;
        dq[18] = x1488;
        dq[19] = x1534;
        dq[20] = x1580;
        dq[21] = x1434;
        dq[22] = x1494;
        dq[23] = x1541;
        dq[24] = x1586;
        dqd[0] = x1590;
        dqd[1] = x1598;
        dqd[2] = x1606;
        dqd[3] = x1592;
        dqd[4] = x1600;
        dqd[5] = x1608;
        dqd[6] = x1594;
        dqd[7] = x1602;
        dqd[8] = x1610;
        dqd[9] = x1615;
        dqd[10] = x1625;
        dqd[11] = x1636;
        dqd[12] = x1645;
        dqd[13] = x1617;
        dqd[14] = x1627;
        dqd[15] = x1638;
        dqd[16] = x1646;
        dqd[17] = x1619;
        dqd[18] = x1629;
        dqd[19] = x1640;
        dqd[20] = x1647;
        dqd[21] = x1620;
        dqd[22] = x1630;
        dqd[23] = x1641;
        dqd[24] = x1649;
    }
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
        let x1650 = x288 + x289;
        let x1651 = q[2] * q[3];
        let x1652 = 2.0 * x1651;
        let x1653 = q[1] * q[4];
        let x1654 = 2.0 * x1653;
        let x1655 = q[2] * q[4];
        let x1656 = 2.0 * x1655;
        let x1657 = q[1] * q[3];
        let x1658 = 2.0 * x1657;
        let x1659 = x1652 + x1654;
        let x1660 = q[1] * q[2];
        let x1661 = 2.0 * x1660;
        let x1663 = x1656 - x1658;
        let x1664 = x54 + x1661;
        let x1665 = q[7] * q[7];
        let x1666 = q[8] * q[8];
        let x1667 = x25 + x26;
        let x1668 = q[6] * q[7];
        let x1669 = 2.0 * x1668;
        let x1670 = q[5] * q[8];
        let x1671 = 2.0 * x1670;
        let x1673 = x1669 - x1671;
        let x1674 = q[7] * q[8];
        let x1675 = 2.0 * x1674;
        let x1676 = x51 + x1675;
        let x1677 = -x1676;
        let x1678 = x23 + x1650;
        let x1679 = x24 + x1678;
        let x1680 = x1679 - 1.0;
        let x1681 = x1665 + x1667;
        let x1682 = x1666 + x1681;
        let x1683 = x1682 - 1.0;
        out[0] = x1659;
        out[1] = x1663;
        out[2] = x1664;
        out[3] = x1673;
        out[4] = x1677;
        out[5] = x1680;
        out[6] = x1683;
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
        let x1684 = -x295;
        let x1685 = 2.0 * q[7];
        let x1686 = 2.0 * q[8];
        let x1687 = -x1686;
        let x1688 = -x1685;
        out[0] = x124;
        out[1] = x123;
        out[2] = x297;
        out[3] = x295;
        out[4] = x128;
        out[5] = x124;
        out[6] = x1684;
        out[7] = x297;
        out[8] = x297;
        out[9] = x295;
        out[10] = x124;
        out[11] = x123;
        out[12] = x1687;
        out[13] = x1685;
        out[14] = x126;
        out[15] = x127;
        out[16] = x474;
        out[17] = x127;
        out[18] = x1687;
        out[19] = x1688;
        out[20] = x295;
        out[21] = x297;
        out[22] = x123;
        out[23] = x124;
        out[24] = x125;
        out[25] = x126;
        out[26] = x1685;
        out[27] = x1686;
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
        let x1737 = qd[1] * x461;
        let x1738 = qd[2] * x463;
        let x1739 = x1737 + x1738;
        let x1740 = qd[2] * qd[3];
        let x1741 = x1740 + x1740;
        let x1742 = 2.0 * x1741;
        let x1743 = qd[1] * qd[4];
        let x1744 = x1743 + x1743;
        let x1745 = 2.0 * x1744;
        let x1746 = qd[2] * qd[4];
        let x1747 = x1746 + x1746;
        let x1748 = 2.0 * x1747;
        let x1749 = qd[1] * qd[3];
        let x1750 = x1749 + x1749;
        let x1751 = 2.0 * x1750;
        let x1752 = x1742 + x1745;
        let x1753 = qd[1] * qd[2];
        let x1754 = x1753 + x1753;
        let x1755 = 2.0 * x1754;
        let x1757 = x1748 - x1751;
        let x1758 = x247 + x1755;
        let x1759 = qd[7] * x844;
        let x1760 = qd[8] * x846;
        let x1761 = x226 + x227;
        let x1762 = qd[6] * qd[7];
        let x1763 = x1762 + x1762;
        let x1764 = 2.0 * x1763;
        let x1765 = qd[5] * qd[8];
        let x1766 = x1765 + x1765;
        let x1767 = 2.0 * x1766;
        let x1769 = x1764 - x1767;
        let x1770 = qd[7] * qd[8];
        let x1771 = x1770 + x1770;
        let x1772 = 2.0 * x1771;
        let x1773 = x244 + x1772;
        let x1775 = x224 + x1739;
        let x1776 = x225 + x1775;
        let x1777 = x1759 + x1761;
        let x1778 = x1760 + x1777;
        let x1779 = -x1752;
        let x1780 = -x1757;
        let x1781 = -x1758;
        let x1782 = -x1769;
        let x1783 = -x1776;
        let x1784 = -x1778;
        out[0] = x1779;
        out[1] = x1780;
        out[2] = x1781;
        out[3] = x1782;
        out[4] = x1773;
        out[5] = x1783;
        out[6] = x1784;
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
        let x1650 = x288 + x289;
        let x1651 = q[2] * q[3];
        let x1652 = 2.0 * x1651;
        let x1653 = q[1] * q[4];
        let x1654 = 2.0 * x1653;
        let x1655 = q[2] * q[4];
        let x1656 = 2.0 * x1655;
        let x1657 = q[1] * q[3];
        let x1658 = 2.0 * x1657;
        let x1659 = x1652 + x1654;
        let x1660 = q[1] * q[2];
        let x1661 = 2.0 * x1660;
        let x1663 = x1656 - x1658;
        let x1664 = x54 + x1661;
        let x1665 = q[7] * q[7];
        let x1666 = q[8] * q[8];
        let x1667 = x25 + x26;
        let x1668 = q[6] * q[7];
        let x1669 = 2.0 * x1668;
        let x1670 = q[5] * q[8];
        let x1671 = 2.0 * x1670;
        let x1673 = x1669 - x1671;
        let x1674 = q[7] * q[8];
        let x1675 = 2.0 * x1674;
        let x1676 = x51 + x1675;
        let x1677 = -x1676;
        let x1678 = x23 + x1650;
        let x1679 = x24 + x1678;
        let x1680 = x1679 - 1.0;
        let x1681 = x1665 + x1667;
        let x1682 = x1666 + x1681;
        let x1683 = x1682 - 1.0;
        let x1684 = -x295;
        let x1685 = 2.0 * q[7];
        let x1686 = 2.0 * q[8];
        let x1687 = -x1686;
        let x1688 = -x1685;
        let x1737 = qd[1] * x461;
        let x1738 = qd[2] * x463;
        let x1739 = x1737 + x1738;
        let x1740 = qd[2] * qd[3];
        let x1741 = x1740 + x1740;
        let x1742 = 2.0 * x1741;
        let x1743 = qd[1] * qd[4];
        let x1744 = x1743 + x1743;
        let x1745 = 2.0 * x1744;
        let x1746 = qd[2] * qd[4];
        let x1747 = x1746 + x1746;
        let x1748 = 2.0 * x1747;
        let x1749 = qd[1] * qd[3];
        let x1750 = x1749 + x1749;
        let x1751 = 2.0 * x1750;
        let x1752 = x1742 + x1745;
        let x1753 = qd[1] * qd[2];
        let x1754 = x1753 + x1753;
        let x1755 = 2.0 * x1754;
        let x1757 = x1748 - x1751;
        let x1758 = x247 + x1755;
        let x1759 = qd[7] * x844;
        let x1760 = qd[8] * x846;
        let x1761 = x226 + x227;
        let x1762 = qd[6] * qd[7];
        let x1763 = x1762 + x1762;
        let x1764 = 2.0 * x1763;
        let x1765 = qd[5] * qd[8];
        let x1766 = x1765 + x1765;
        let x1767 = 2.0 * x1766;
        let x1769 = x1764 - x1767;
        let x1770 = qd[7] * qd[8];
        let x1771 = x1770 + x1770;
        let x1772 = 2.0 * x1771;
        let x1773 = x244 + x1772;
        let x1775 = x224 + x1739;
        let x1776 = x225 + x1775;
        let x1777 = x1759 + x1761;
        let x1778 = x1760 + x1777;
        let x1779 = -x1752;
        let x1780 = -x1757;
        let x1781 = -x1758;
        let x1782 = -x1769;
        let x1783 = -x1776;
        let x1784 = -x1778;
        phi[0] = x1659;
        phi_q[0] = x124;
        phi_q[1] = x123;
        phi_q[2] = x297;
        phi_q[3] = x295;
        phi_t[0] = 0.0;
        gamma[0] = x1779;
        phi[1] = x1663;
        phi_q[4] = x128;
        phi_q[5] = x124;
        phi_q[6] = x1684;
        phi_q[7] = x297;
        phi_t[1] = 0.0;
        gamma[1] = x1780;
        phi[2] = x1664;
        phi_q[8] = x297;
        phi_q[9] = x295;
        phi_q[10] = x124;
        phi_q[11] = x123;
        phi_t[2] = 0.0;
        gamma[2] = x1781;
        phi[3] = x1673;
        phi_q[12] = x1687;
        phi_q[13] = x1685;
        phi_q[14] = x126;
        phi_q[15] = x127;
        phi_t[3] = 0.0;
        gamma[3] = x1782;
        phi[4] = x1677;
        phi_q[16] = x474;
        phi_q[17] = x127;
        phi_q[18] = x1687;
        phi_q[19] = x1688;
        phi_t[4] = 0.0;
        gamma[4] = x1773;
        phi[5] = x1680;
        phi_q[20] = x295;
        phi_q[21] = x297;
        phi_q[22] = x123;
        phi_q[23] = x124;
        phi_t[5] = 0.0;
        gamma[5] = x1783;
        phi[6] = x1683;
        phi_q[24] = x125;
        phi_q[25] = x126;
        phi_q[26] = x1685;
        phi_q[27] = x1686;
        phi_t[6] = 0.0;
        gamma[6] = x1784;
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
        let x1667 = x25 + x26;
        let x1785 = 2.0 * x1667;
        let x1786 = x1785 - 1.0;
        let x1787 = q[6] * q[8];
        let x1788 = 2.0 * x1787;
        let x1789 = q[5] * q[7];
        let x1790 = 2.0 * x1789;
        let x1792 = x1788 - x1790;
        let x1793 = x287.sqrt();
        let x1794 = x1793 - 1.0;
        let x1795 = x1794 * x1794;
        let x1796 = 25.0 * x1795;
        let x1797 = -x1792;
        let x1798 = x1797.atan2(x1786);
        let x1799 = x1798 * x1798;
        let x1800 = 9.81 + x1796;
        let x1801 = x1799 + x1800;
        out[0] = x1801;
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
        let x1667 = x25 + x26;
        let x1716 = x153 + x154;
        let x1785 = 2.0 * x1667;
        let x1786 = x1785 - 1.0;
        let x1787 = q[6] * q[8];
        let x1788 = 2.0 * x1787;
        let x1789 = q[5] * q[7];
        let x1790 = 2.0 * x1789;
        let x1792 = x1788 - x1790;
        let x1793 = x287.sqrt();
        let x1802 = 2.0 * x1793;
        let x1803 = 1.0 / x1802;
        let x1804 = x294 * x1803;
        let x1805 = 0.8 * x1804;
        let x1807 = x5 - x1805;
        let x1808 = x1804 * x1807;
        let x1809 = 2.0 * x1716;
        let x1810 = q[8] * qd[6];
        let x1811 = q[6] * qd[8];
        let x1812 = x1810 + x1811;
        let x1813 = 2.0 * x1812;
        let x1814 = q[7] * qd[5];
        let x1815 = q[5] * qd[7];
        let x1816 = x1814 + x1815;
        let x1817 = 2.0 * x1816;
        let x1819 = x1813 - x1817;
        let x1820 = x1786 * x1786;
        let x1821 = x1792 * x1792;
        let x1822 = x1820 + x1821;
        let x1823 = x1786 * x1819;
        let x1825 = x1792 * x1809;
        let x1826 = x1825 - x1823;
        let x1827 = 1.0 / x1822;
        let x1828 = x1826 * x1827;
        let x1829 = 0.1 * x1828;
        let x1831 = x11 - x1829;
        let x1832 = x1828 * x1831;
        let x1835 = x1810 - x1814;
        let x1836 = x1815 + x1835;
        let x1837 = x1836 - x1811;
        let x1838 = 2.0 * x1837;
        let x1839 = x14 * x1838;
        let x1840 = qd[0] + x1808;
        let x1841 = x1832 + x1840;
        let x1842 = x1839 + x1841;
        out[0] = x1842;
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
            q: &[f64],
            qd: &[f64],
            t: f64,
            dq: &mut [f64],
            dqd: &mut [f64],
        ) {
            let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
            let _: &mut [f64; 0] = dq.try_into().expect("dq must have 0 entries");
            let _: &mut [f64; 0] = dqd.try_into().expect("dqd must have 0 entries");
            let _ = q;
            let _ = qd;
            let _ = t;
        }
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
            let x1651 = q[2] * q[3];
            let x1653 = q[1] * q[4];
            let x1655 = q[2] * q[4];
            let x1657 = q[1] * q[3];
            let x1660 = q[1] * q[2];
            let x1665 = q[7] * q[7];
            let x1666 = q[8] * q[8];
            let x1668 = q[6] * q[7];
            let x1670 = q[5] * q[8];
            let x1674 = q[7] * q[8];
            let x1685 = 2.0 * q[7];
            let x1686 = 2.0 * q[8];
            let x1787 = q[6] * q[8];
            let x1789 = q[5] * q[7];
            let x1843 = 2.0 * x297;
            let x1844 = x297 * x1843;
            let x1845 = 0.01 * x1844;
            let x1846 = x607 + x1845;
            let x1847 = x535 + x1846;
            let x1848 = 0.5 * x1847;
            let x1849 = x288 * 0.04;
            let x1850 = x1848 + x1849;
            let x1851 = 2.0 * x295;
            let x1852 = x297 * x1851;
            let x1853 = 0.01 * x1852;
            let x1854 = x1853 - x598;
            let x1855 = x555 + x1854;
            let x1856 = 0.5 * x1855;
            let x1858 = 0.04 * x1660;
            let x1859 = x1858 - x1856;
            let x1860 = x297 * x527;
            let x1861 = 0.01 * x1860;
            let x1862 = x123 * x1851;
            let x1863 = 0.01 * x1862;
            let x1864 = x124 * x1843;
            let x1865 = 0.01 * x1864;
            let x1867 = x1861 + x1863;
            let x1868 = x1867 - x1865;
            let x1869 = 0.5 * x1868;
            let x1871 = 0.04 * x1657;
            let x1872 = x1871 - x1869;
            let x1873 = x297 * x553;
            let x1874 = 0.01 * x1873;
            let x1876 = x123 * x1843;
            let x1877 = 0.01 * x1876;
            let x1878 = x124 * x1851;
            let x1879 = 0.01 * x1878;
            let x1880 = x1877 - x1874;
            let x1881 = x1879 + x1880;
            let x1882 = 0.5 * x1881;
            let x1884 = 0.04 * x1653;
            let x1885 = x1884 - x1882;
            let x1886 = x295 * x1843;
            let x1887 = 0.01 * x1886;
            let x1889 = x555 - x1887;
            let x1890 = x1889 - x598;
            let x1891 = 0.5 * x1890;
            let x1892 = x1858 + x1891;
            let x1893 = x295 * x1851;
            let x1894 = 0.01 * x1893;
            let x1895 = x535 + x1894;
            let x1896 = x607 + x1895;
            let x1897 = 0.5 * x1896;
            let x1898 = x289 * 0.04;
            let x1899 = x1897 + x1898;
            let x1900 = x295 * x527;
            let x1901 = 0.01 * x1900;
            let x1904 = x1901 - x1879;
            let x1905 = x1904 - x1877;
            let x1906 = 0.5 * x1905;
            let x1907 = 0.04 * x1651;
            let x1908 = x1906 + x1907;
            let x1909 = x295 * x553;
            let x1910 = 0.01 * x1909;
            let x1911 = x1865 + x1910;
            let x1913 = x1863 - x1911;
            let x1914 = 0.5 * x1913;
            let x1915 = 0.04 * x1655;
            let x1916 = x1914 + x1915;
            let x1917 = x1861 - x1911;
            let x1918 = 0.5 * x1917;
            let x1919 = x1871 + x1918;
            let x1921 = x1879 - x1901;
            let x1922 = x1921 - x1874;
            let x1923 = 0.5 * x1922;
            let x1924 = x1907 + x1923;
            let x1925 = x1845 + x1895;
            let x1926 = 0.5 * x1925;
            let x1927 = x551 + x1926;
            let x1929 = x1887 - x555;
            let x1930 = x1929 - x1853;
            let x1931 = 0.5 * x1930;
            let x1932 = x566 + x1931;
            let x1933 = x1880 - x1901;
            let x1934 = 0.5 * x1933;
            let x1935 = x1884 + x1934;
            let x1937 = x1910 - x1867;
            let x1938 = 0.5 * x1937;
            let x1939 = x1915 + x1938;
            let x1940 = x1854 - x1887;
            let x1941 = 0.5 * x1940;
            let x1942 = x566 + x1941;
            let x1943 = x1846 + x1894;
            let x1944 = 0.5 * x1943;
            let x1945 = x611 + x1944;
            let x1946 = 2.0 * x1685;
            let x1947 = 2.0 * x1686;
            let x1948 = 0.1 * x541;
            let x1949 = x1685 * x1946;
            let x1950 = 0.2 * x1949;
            let x1951 = x1686 * x1947;
            let x1952 = 0.3 * x1951;
            let x1953 = x1948 + x1950;
            let x1954 = x1952 + x1953;
            let x1955 = 0.5 * x1954;
            let x1956 = x25 * 0.8000000000000002;
            let x1957 = x1955 + x1956;
            let x1958 = 0.1 * x560;
            let x1959 = x1685 * x1947;
            let x1960 = 0.2 * x1959;
            let x1962 = x1686 * x1946;
            let x1963 = 0.3 * x1962;
            let x1964 = x1958 - x1960;
            let x1965 = x1963 + x1964;
            let x1966 = 0.5 * x1965;
            let x1968 = x50 * 0.8000000000000002;
            let x1969 = x1968 - x1966;
            let x1970 = x126 * x1947;
            let x1971 = 0.1 * x1970;
            let x1972 = x529 * x1685;
            let x1973 = 0.2 * x1972;
            let x1974 = x531 * x1686;
            let x1975 = 0.3 * x1974;
            let x1977 = x1971 + x1973;
            let x1978 = x1977 - x1975;
            let x1979 = 0.5 * x1978;
            let x1981 = 0.8000000000000002 * x1789;
            let x1982 = x1981 - x1979;
            let x1983 = x126 * x1946;
            let x1984 = 0.1 * x1983;
            let x1986 = x531 * x1685;
            let x1987 = 0.2 * x1986;
            let x1988 = x529 * x1686;
            let x1989 = 0.3 * x1988;
            let x1990 = x1987 - x1984;
            let x1991 = x1989 + x1990;
            let x1992 = 0.5 * x1991;
            let x1994 = 0.8000000000000002 * x1670;
            let x1995 = x1994 - x1992;
            let x1996 = 0.1 * x556;
            let x1998 = 0.2 * x1962;
            let x1999 = 0.3 * x1959;
            let x2001 = x1998 - x1996;
            let x2002 = x2001 - x1999;
            let x2003 = 0.5 * x2002;
            let x2004 = x1968 + x2003;
            let x2005 = 0.1 * x537;
            let x2006 = 0.2 * x1951;
            let x2007 = 0.3 * x1949;
            let x2008 = x2005 + x2006;
            let x2009 = x2007 + x2008;
            let x2010 = 0.5 * x2009;
            let x2011 = x26 * 0.8000000000000002;
            let x2012 = x2010 + x2011;
            let x2013 = x125 * x1947;
            let x2014 = 0.1 * x2013;
            let x2015 = 0.2 * x1988;
            let x2017 = 0.3 * x1986;
            let x2019 = x2014 - x2015;
            let x2020 = x2019 - x2017;
            let x2021 = 0.5 * x2020;
            let x2022 = 0.8000000000000002 * x1668;
            let x2023 = x2021 + x2022;
            let x2024 = x125 * x1946;
            let x2025 = 0.1 * x2024;
            let x2026 = 0.2 * x1974;
            let x2027 = 0.3 * x1972;
            let x2028 = x2025 + x2026;
            let x2030 = x2027 - x2028;
            let x2031 = 0.5 * x2030;
            let x2032 = 0.8000000000000002 * x1787;
            let x2033 = x2031 + x2032;
            let x2034 = 0.1 * x1974;
            let x2035 = 0.2 * x2024;
            let x2036 = 0.3 * x1970;
            let x2037 = x2034 + x2035;
            let x2039 = x2036 - x2037;
            let x2040 = 0.5 * x2039;
            let x2041 = x1981 + x2040;
            let x2042 = 0.1 * x1988;
            let x2043 = 0.2 * x2013;
            let x2045 = 0.3 * x1983;
            let x2047 = x2042 - x2043;
            let x2048 = x2047 - x2045;
            let x2049 = 0.5 * x2048;
            let x2050 = x2022 + x2049;
            let x2051 = 0.1 * x1951;
            let x2052 = 0.2 * x537;
            let x2053 = x541 * 0.3;
            let x2054 = x2051 + x2052;
            let x2055 = x2053 + x2054;
            let x2056 = 0.5 * x2055;
            let x2057 = 0.8000000000000002 * x1665;
            let x2058 = x2056 + x2057;
            let x2059 = 0.1 * x1962;
            let x2061 = 0.2 * x556;
            let x2062 = x560 * 0.3;
            let x2064 = x2061 - x2059;
            let x2065 = x2064 - x2062;
            let x2066 = 0.5 * x2065;
            let x2067 = 0.8000000000000002 * x1674;
            let x2068 = x2066 + x2067;
            let x2069 = 0.1 * x1986;
            let x2070 = 0.2 * x1983;
            let x2072 = 0.3 * x2013;
            let x2074 = x2069 - x2070;
            let x2075 = x2074 - x2072;
            let x2076 = 0.5 * x2075;
            let x2077 = x1994 + x2076;
            let x2078 = 0.1 * x1972;
            let x2079 = 0.2 * x1970;
            let x2080 = 0.3 * x2024;
            let x2081 = x2078 + x2079;
            let x2083 = x2080 - x2081;
            let x2084 = 0.5 * x2083;
            let x2085 = x2032 + x2084;
            let x2086 = 0.1 * x1959;
            let x2088 = 0.2 * x560;
            let x2089 = x556 * 0.3;
            let x2091 = x2088 - x2086;
            let x2092 = x2091 - x2089;
            let x2093 = 0.5 * x2092;
            let x2094 = x2067 + x2093;
            let x2095 = 0.1 * x1949;
            let x2096 = 0.2 * x541;
            let x2097 = x537 * 0.3;
            let x2098 = x2095 + x2096;
            let x2099 = x2097 + x2098;
            let x2100 = 0.5 * x2099;
            let x2101 = 0.8000000000000002 * x1666;
            let x2102 = x2100 + x2101;
            out[0] = 2.0;
            out[1] = x1850;
            out[2] = x1859;
            out[3] = x1872;
            out[4] = x1885;
            out[5] = x1892;
            out[6] = x1899;
            out[7] = x1908;
            out[8] = x1916;
            out[9] = x1919;
            out[10] = x1924;
            out[11] = x1927;
            out[12] = x1932;
            out[13] = x1935;
            out[14] = x1939;
            out[15] = x1942;
            out[16] = x1945;
            out[17] = x1957;
            out[18] = x1969;
            out[19] = x1982;
            out[20] = x1995;
            out[21] = x2004;
            out[22] = x2012;
            out[23] = x2023;
            out[24] = x2033;
            out[25] = x2041;
            out[26] = x2050;
            out[27] = x2058;
            out[28] = x2068;
            out[29] = x2077;
            out[30] = x2085;
            out[31] = x2094;
            out[32] = x2102;
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
            let x1667 = x25 + x26;
            let x1685 = 2.0 * q[7];
            let x1686 = 2.0 * q[8];
            let x1690 = q[3] * qd[2];
            let x1691 = q[2] * qd[3];
            let x1694 = q[4] * qd[1];
            let x1695 = q[1] * qd[4];
            let x1698 = q[4] * qd[2];
            let x1699 = q[2] * qd[4];
            let x1702 = q[3] * qd[1];
            let x1703 = q[1] * qd[3];
            let x1707 = q[2] * qd[1];
            let x1708 = q[1] * qd[2];
            let x1716 = x153 + x154;
            let x1717 = q[7] * qd[6];
            let x1718 = q[6] * qd[7];
            let x1721 = q[8] * qd[5];
            let x1722 = q[5] * qd[8];
            let x1727 = q[8] * qd[7];
            let x1728 = q[7] * qd[8];
            let x1740 = qd[2] * qd[3];
            let x1743 = qd[1] * qd[4];
            let x1746 = qd[2] * qd[4];
            let x1749 = qd[1] * qd[3];
            let x1762 = qd[6] * qd[7];
            let x1765 = qd[5] * qd[8];
            let x1785 = 2.0 * x1667;
            let x1786 = x1785 - 1.0;
            let x1787 = q[6] * q[8];
            let x1788 = 2.0 * x1787;
            let x1789 = q[5] * q[7];
            let x1790 = 2.0 * x1789;
            let x1792 = x1788 - x1790;
            let x1793 = x287.sqrt();
            let x1794 = x1793 - 1.0;
            let x1797 = -x1792;
            let x1798 = x1797.atan2(x1786);
            let x1802 = 2.0 * x1793;
            let x1803 = 1.0 / x1802;
            let x1804 = x294 * x1803;
            let x1805 = 0.8 * x1804;
            let x1807 = x5 - x1805;
            let x1809 = 2.0 * x1716;
            let x1810 = q[8] * qd[6];
            let x1811 = q[6] * qd[8];
            let x1812 = x1810 + x1811;
            let x1813 = 2.0 * x1812;
            let x1814 = q[7] * qd[5];
            let x1815 = q[5] * qd[7];
            let x1816 = x1814 + x1815;
            let x1817 = 2.0 * x1816;
            let x1819 = x1813 - x1817;
            let x1820 = x1786 * x1786;
            let x1821 = x1792 * x1792;
            let x1822 = x1820 + x1821;
            let x1823 = x1786 * x1819;
            let x1825 = x1792 * x1809;
            let x1826 = x1825 - x1823;
            let x1827 = 1.0 / x1822;
            let x1828 = x1826 * x1827;
            let x1829 = 0.1 * x1828;
            let x1831 = x11 - x1829;
            let x2103 = 50.0 * x1794;
            let x2105 = x1807 - x2103;
            let x2106 = x293 * x1803;
            let x2107 = x2105 * x2106;
            let x2108 = 2.0 * x1798;
            let x2110 = x1831 - x2108;
            let x2111 = x1685 * x1786;
            let x2112 = x529 * x1792;
            let x2113 = x2111 + x2112;
            let x2114 = x1827 * x2113;
            let x2115 = x1686 * x1786;
            let x2117 = x531 * x1792;
            let x2118 = x2117 - x2115;
            let x2119 = x1827 * x2118;
            let x2120 = x125 * x1786;
            let x2121 = x1827 * x2120;
            let x2122 = x126 * x1786;
            let x2123 = x1827 * x2122;
            let x2124 = x2110 * x2114;
            let x2125 = x2110 * x2119;
            let x2126 = x2110 * x2121;
            let x2127 = x2110 * x2123;
            let x2129 = x174 - x173;
            let x2131 = x14 * x1685;
            let x2133 = x14 * x1686;
            let x2134 = x14 * x125;
            let x2135 = x14 * x126;
            let x2136 = 1.0 + x2107;
            let x2137 = x2124 - x2131;
            let x2138 = x2125 + x2133;
            let x2139 = x2126 + x2134;
            let x2140 = x2127 + x2135;
            let x2144 = x1708 - x1707;
            let x2145 = x177 + x2144;
            let x2146 = x2145 - x178;
            let x2147 = 2.0 * x2146;
            let x2148 = x1698 + x1702;
            let x2150 = x1703 - x2148;
            let x2151 = x1699 + x2150;
            let x2152 = 2.0 * x2151;
            let x2155 = x1690 - x1694;
            let x2156 = x2155 - x1691;
            let x2157 = x1695 + x2156;
            let x2158 = 2.0 * x2157;
            let x2159 = 2.0 * x2147;
            let x2160 = 2.0 * x2152;
            let x2161 = 2.0 * x2158;
            let x2162 = x1746 + x1749;
            let x2164 = x1749 - x2162;
            let x2165 = x1746 + x2164;
            let x2166 = 2.0 * x2165;
            let x2169 = x1740 - x1743;
            let x2170 = x2169 - x1740;
            let x2171 = x1743 + x2170;
            let x2172 = 2.0 * x2171;
            let x2173 = 2.0 * x2166;
            let x2174 = 2.0 * x2172;
            let x2175 = x463 * x2159;
            let x2176 = 0.01 * x2175;
            let x2177 = x216 * x2160;
            let x2178 = x123 * x2173;
            let x2179 = x2177 + x2178;
            let x2180 = 0.01 * x2179;
            let x2181 = x217 * x2161;
            let x2182 = x124 * x2174;
            let x2183 = x2181 + x2182;
            let x2184 = 0.01 * x2183;
            let x2185 = x2176 + x2180;
            let x2186 = x2184 + x2185;
            let x2187 = 0.5 * x2186;
            let x2188 = x461 * x2159;
            let x2189 = 0.01 * x2188;
            let x2190 = x217 * x2160;
            let x2191 = x124 * x2173;
            let x2192 = x2190 + x2191;
            let x2193 = 0.01 * x2192;
            let x2195 = x216 * x2161;
            let x2196 = x123 * x2174;
            let x2197 = x2195 + x2196;
            let x2198 = 0.01 * x2197;
            let x2199 = x2189 - x2193;
            let x2200 = x2198 + x2199;
            let x2201 = 0.5 * x2200;
            let x2202 = x217 * x2159;
            let x2203 = 0.01 * x2202;
            let x2204 = x461 * x2160;
            let x2205 = x295 * x2173;
            let x2206 = x2204 + x2205;
            let x2207 = 0.01 * x2206;
            let x2208 = x463 * x2161;
            let x2209 = x297 * x2174;
            let x2210 = x2208 + x2209;
            let x2211 = 0.01 * x2210;
            let x2213 = x2203 + x2207;
            let x2214 = x2213 - x2211;
            let x2215 = 0.5 * x2214;
            let x2216 = x216 * x2159;
            let x2217 = 0.01 * x2216;
            let x2219 = x463 * x2160;
            let x2220 = x297 * x2173;
            let x2221 = x2219 + x2220;
            let x2222 = 0.01 * x2221;
            let x2223 = x461 * x2161;
            let x2224 = x295 * x2174;
            let x2225 = x2223 + x2224;
            let x2226 = 0.01 * x2225;
            let x2227 = x2222 - x2217;
            let x2228 = x2226 + x2227;
            let x2229 = 0.5 * x2228;
            let x2230 = x444 + x448;
            let x2231 = x740 + x2230;
            let x2232 = x741 + x2231;
            let x2233 = 0.01 * x2177;
            let x2234 = 0.01 * x2181;
            let x2235 = x2176 + x2233;
            let x2236 = x2234 + x2235;
            let x2237 = 0.5 * x2236;
            let x2238 = x2187 + x2237;
            let x2239 = q[1] * 0.04;
            let x2240 = x2232 * x2239;
            let x2242 = x2238 - x2240;
            let x2244 = 0.01 * x2190;
            let x2245 = 0.01 * x2195;
            let x2247 = x2244 - x2189;
            let x2248 = x2247 - x2245;
            let x2249 = 0.5 * x2248;
            let x2251 = x2249 - x2201;
            let x2252 = q[2] * 0.04;
            let x2253 = x2232 * x2252;
            let x2255 = x2251 - x2253;
            let x2256 = 0.01 * x2204;
            let x2257 = 0.01 * x2208;
            let x2258 = x2203 + x2256;
            let x2260 = x2257 - x2258;
            let x2261 = 0.5 * x2260;
            let x2263 = x2261 - x2215;
            let x2264 = x754 * x2232;
            let x2266 = x2263 - x2264;
            let x2267 = 0.01 * x2219;
            let x2269 = 0.01 * x2223;
            let x2271 = x2217 - x2267;
            let x2272 = x2271 - x2269;
            let x2273 = 0.5 * x2272;
            let x2275 = x2273 - x2229;
            let x2276 = x773 * x2232;
            let x2278 = x2275 - x2276;
            let x2280 = x1727 + x2129;
            let x2281 = x2280 - x1728;
            let x2282 = 2.0 * x2281;
            let x2283 = x1810 + x1814;
            let x2285 = x1815 - x2283;
            let x2286 = x1811 + x2285;
            let x2287 = 2.0 * x2286;
            let x2289 = x1717 - x1721;
            let x2290 = x2289 - x1718;
            let x2291 = x1722 + x2290;
            let x2292 = 2.0 * x2291;
            let x2293 = 2.0 * x2282;
            let x2294 = 2.0 * x2287;
            let x2295 = 2.0 * x2292;
            let x2296 = qd[6] * qd[8];
            let x2297 = qd[5] * qd[7];
            let x2299 = x2296 + x2297;
            let x2301 = x2297 - x2299;
            let x2302 = x2296 + x2301;
            let x2303 = 2.0 * x2302;
            let x2305 = x1762 - x1765;
            let x2306 = x2305 - x1762;
            let x2307 = x1765 + x2306;
            let x2308 = 2.0 * x2307;
            let x2309 = 2.0 * x2303;
            let x2310 = 2.0 * x2308;
            let x2311 = x219 * x2293;
            let x2312 = 0.1 * x2311;
            let x2313 = x844 * x2294;
            let x2314 = x1685 * x2309;
            let x2315 = x2313 + x2314;
            let x2316 = 0.2 * x2315;
            let x2317 = x846 * x2295;
            let x2318 = x1686 * x2310;
            let x2319 = x2317 + x2318;
            let x2320 = 0.3 * x2319;
            let x2321 = x2312 + x2316;
            let x2322 = x2320 + x2321;
            let x2323 = 0.5 * x2322;
            let x2324 = x218 * x2293;
            let x2325 = 0.1 * x2324;
            let x2326 = x846 * x2294;
            let x2327 = x1686 * x2309;
            let x2328 = x2326 + x2327;
            let x2329 = 0.2 * x2328;
            let x2331 = x844 * x2295;
            let x2332 = x1685 * x2310;
            let x2333 = x2331 + x2332;
            let x2334 = 0.3 * x2333;
            let x2335 = x2325 - x2329;
            let x2336 = x2334 + x2335;
            let x2337 = 0.5 * x2336;
            let x2338 = x846 * x2293;
            let x2339 = 0.1 * x2338;
            let x2340 = x218 * x2294;
            let x2341 = x125 * x2309;
            let x2342 = x2340 + x2341;
            let x2343 = 0.2 * x2342;
            let x2344 = x219 * x2295;
            let x2345 = x126 * x2310;
            let x2346 = x2344 + x2345;
            let x2347 = 0.3 * x2346;
            let x2349 = x2339 + x2343;
            let x2350 = x2349 - x2347;
            let x2351 = 0.5 * x2350;
            let x2352 = x844 * x2293;
            let x2353 = 0.1 * x2352;
            let x2355 = x219 * x2294;
            let x2356 = x126 * x2309;
            let x2357 = x2355 + x2356;
            let x2358 = 0.2 * x2357;
            let x2359 = x218 * x2295;
            let x2360 = x125 * x2310;
            let x2361 = x2359 + x2360;
            let x2362 = 0.3 * x2361;
            let x2363 = x2358 - x2353;
            let x2364 = x2362 + x2363;
            let x2365 = 0.5 * x2364;
            let x2366 = x742 + x743;
            let x2367 = x828 + x2366;
            let x2368 = x831 + x2367;
            let x2369 = 0.2 * x2313;
            let x2370 = 0.3 * x2317;
            let x2371 = x2312 + x2369;
            let x2372 = x2370 + x2371;
            let x2373 = 0.5 * x2372;
            let x2374 = x2323 + x2373;
            let x2375 = q[5] * 0.8000000000000002;
            let x2376 = x2368 * x2375;
            let x2378 = x2374 - x2376;
            let x2380 = 0.2 * x2326;
            let x2381 = 0.3 * x2331;
            let x2383 = x2380 - x2325;
            let x2384 = x2383 - x2381;
            let x2385 = 0.5 * x2384;
            let x2387 = x2385 - x2337;
            let x2388 = q[6] * 0.8000000000000002;
            let x2389 = x2368 * x2388;
            let x2391 = x2387 - x2389;
            let x2392 = 0.2 * x2340;
            let x2393 = 0.3 * x2344;
            let x2394 = x2339 + x2392;
            let x2396 = x2393 - x2394;
            let x2397 = 0.5 * x2396;
            let x2399 = x2397 - x2351;
            let x2400 = q[7] * 0.8000000000000002;
            let x2401 = x2368 * x2400;
            let x2403 = x2399 - x2401;
            let x2404 = 0.2 * x2355;
            let x2406 = 0.3 * x2359;
            let x2408 = x2353 - x2404;
            let x2409 = x2408 - x2406;
            let x2410 = 0.5 * x2409;
            let x2412 = x2410 - x2365;
            let x2413 = q[8] * 0.8000000000000002;
            let x2414 = x2368 * x2413;
            let x2416 = x2412 - x2414;
            let x2417 = x2137 + x2378;
            let x2418 = x2138 + x2391;
            let x2419 = x2139 + x2403;
            let x2420 = x2416 - x2140;
            out[0] = x2136;
            out[1] = x2242;
            out[2] = x2255;
            out[3] = x2266;
            out[4] = x2278;
            out[5] = x2417;
            out[6] = x2418;
            out[7] = x2419;
            out[8] = x2420;
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
            let x1667 = x25 + x26;
            s[21] = x1667;
            let x1685 = 2.0 * q[7];
            s[22] = x1685;
            let x1686 = 2.0 * q[8];
            s[23] = x1686;
            let x1716 = x153 + x154;
            s[24] = x1716;
            let x1717 = q[7] * qd[6];
            s[25] = x1717;
            let x1718 = q[6] * qd[7];
            s[26] = x1718;
            let x1721 = q[8] * qd[5];
            s[27] = x1721;
            let x1722 = q[5] * qd[8];
            s[28] = x1722;
            let x1727 = q[8] * qd[7];
            s[29] = x1727;
            let x1728 = q[7] * qd[8];
            s[30] = x1728;
            let x1762 = qd[6] * qd[7];
            s[31] = x1762;
            let x1765 = qd[5] * qd[8];
            s[32] = x1765;
            let x1785 = 2.0 * x1667;
            s[33] = x1785;
            let x1786 = x1785 - 1.0;
            s[34] = x1786;
            let x1787 = q[6] * q[8];
            s[35] = x1787;
            let x1788 = 2.0 * x1787;
            s[36] = x1788;
            let x1789 = q[5] * q[7];
            s[37] = x1789;
            let x1790 = 2.0 * x1789;
            s[38] = x1790;
            let x1792 = x1788 - x1790;
            s[39] = x1792;
            let x1797 = -x1792;
            s[40] = x1797;
            let x1798 = x1797.atan2(x1786);
            s[41] = x1798;
            let x1809 = 2.0 * x1716;
            s[42] = x1809;
            let x1810 = q[8] * qd[6];
            s[43] = x1810;
            let x1811 = q[6] * qd[8];
            s[44] = x1811;
            let x1812 = x1810 + x1811;
            s[45] = x1812;
            let x1813 = 2.0 * x1812;
            s[46] = x1813;
            let x1814 = q[7] * qd[5];
            s[47] = x1814;
            let x1815 = q[5] * qd[7];
            s[48] = x1815;
            let x1816 = x1814 + x1815;
            s[49] = x1816;
            let x1817 = 2.0 * x1816;
            s[50] = x1817;
            let x1819 = x1813 - x1817;
            s[51] = x1819;
            let x1820 = x1786 * x1786;
            s[52] = x1820;
            let x1821 = x1792 * x1792;
            s[53] = x1821;
            let x1822 = x1820 + x1821;
            s[54] = x1822;
            let x1823 = x1786 * x1819;
            s[55] = x1823;
            let x1825 = x1792 * x1809;
            s[56] = x1825;
            let x1826 = x1825 - x1823;
            s[57] = x1826;
            let x1827 = 1.0 / x1822;
            s[58] = x1827;
            let x1828 = x1826 * x1827;
            s[59] = x1828;
            let x1829 = 0.1 * x1828;
            s[60] = x1829;
            let x1831 = x11 - x1829;
            s[61] = x1831;
            let x2108 = 2.0 * x1798;
            s[62] = x2108;
            let x2110 = x1831 - x2108;
            s[63] = x2110;
            let x2129 = x174 - x173;
            s[64] = x2129;
            let x2280 = x1727 + x2129;
            s[65] = x2280;
            let x2281 = x2280 - x1728;
            s[66] = x2281;
            let x2282 = 2.0 * x2281;
            s[67] = x2282;
            let x2283 = x1810 + x1814;
            s[68] = x2283;
            let x2285 = x1815 - x2283;
            s[69] = x2285;
            let x2286 = x1811 + x2285;
            s[70] = x2286;
            let x2287 = 2.0 * x2286;
            s[71] = x2287;
            let x2289 = x1717 - x1721;
            s[72] = x2289;
            let x2290 = x2289 - x1718;
            s[73] = x2290;
            let x2291 = x1722 + x2290;
            s[74] = x2291;
            let x2292 = 2.0 * x2291;
            s[75] = x2292;
            let x2293 = 2.0 * x2282;
            s[76] = x2293;
            let x2294 = 2.0 * x2287;
            s[77] = x2294;
            let x2295 = 2.0 * x2292;
            s[78] = x2295;
            let x2296 = qd[6] * qd[8];
            s[79] = x2296;
            let x2297 = qd[5] * qd[7];
            s[80] = x2297;
            let x2299 = x2296 + x2297;
            s[81] = x2299;
            let x2301 = x2297 - x2299;
            s[82] = x2301;
            let x2302 = x2296 + x2301;
            s[83] = x2302;
            let x2303 = 2.0 * x2302;
            s[84] = x2303;
            let x2305 = x1762 - x1765;
            s[85] = x2305;
            let x2306 = x2305 - x1762;
            s[86] = x2306;
            let x2307 = x1765 + x2306;
            s[87] = x2307;
            let x2308 = 2.0 * x2307;
            s[88] = x2308;
            let x2309 = 2.0 * x2303;
            s[89] = x2309;
            let x2310 = 2.0 * x2308;
            s[90] = x2310;
            let x2366 = x742 + x743;
            s[91] = x2366;
            let x2367 = x828 + x2366;
            s[92] = x2367;
            let x2368 = x831 + x2367;
            s[93] = x2368;
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
            let x1650 = x288 + x289;
            let x1651 = q[2] * q[3];
            let x1652 = 2.0 * x1651;
            let x1653 = q[1] * q[4];
            let x1654 = 2.0 * x1653;
            let x1655 = q[2] * q[4];
            let x1656 = 2.0 * x1655;
            let x1657 = q[1] * q[3];
            let x1658 = 2.0 * x1657;
            let x1659 = x1652 + x1654;
            let x1660 = q[1] * q[2];
            let x1661 = 2.0 * x1660;
            let x1663 = x1656 - x1658;
            let x1664 = x54 + x1661;
            let x1665 = q[7] * q[7];
            let x1666 = q[8] * q[8];
            let x1668 = q[6] * q[7];
            let x1669 = 2.0 * x1668;
            let x1670 = q[5] * q[8];
            let x1671 = 2.0 * x1670;
            let x1673 = x1669 - x1671;
            let x1674 = q[7] * q[8];
            let x1675 = 2.0 * x1674;
            let x1676 = x51 + x1675;
            let x1677 = -x1676;
            let x1678 = x23 + x1650;
            let x1679 = x24 + x1678;
            let x1680 = x1679 - 1.0;
            let x1681 = x1665 + s[21];
            let x1682 = x1666 + x1681;
            let x1683 = x1682 - 1.0;
            let x1684 = -x295;
            let x1687 = -s[23];
            let x1688 = -s[22];
            let x1690 = q[3] * qd[2];
            let x1691 = q[2] * qd[3];
            let x1694 = q[4] * qd[1];
            let x1695 = q[1] * qd[4];
            let x1698 = q[4] * qd[2];
            let x1699 = q[2] * qd[4];
            let x1702 = q[3] * qd[1];
            let x1703 = q[1] * qd[3];
            let x1707 = q[2] * qd[1];
            let x1708 = q[1] * qd[2];
            let x1740 = qd[2] * qd[3];
            let x1743 = qd[1] * qd[4];
            let x1746 = qd[2] * qd[4];
            let x1749 = qd[1] * qd[3];
            let x1793 = x287.sqrt();
            let x1794 = x1793 - 1.0;
            let x1802 = 2.0 * x1793;
            let x1803 = 1.0 / x1802;
            let x1804 = x294 * x1803;
            let x1805 = 0.8 * x1804;
            let x1807 = x5 - x1805;
            let x1843 = 2.0 * x297;
            let x1844 = x297 * x1843;
            let x1845 = 0.01 * x1844;
            let x1846 = x607 + x1845;
            let x1847 = x535 + x1846;
            let x1848 = 0.5 * x1847;
            let x1849 = x288 * 0.04;
            let x1850 = x1848 + x1849;
            let x1851 = 2.0 * x295;
            let x1852 = x297 * x1851;
            let x1853 = 0.01 * x1852;
            let x1854 = x1853 - x598;
            let x1855 = x555 + x1854;
            let x1856 = 0.5 * x1855;
            let x1858 = 0.04 * x1660;
            let x1859 = x1858 - x1856;
            let x1860 = x297 * x527;
            let x1861 = 0.01 * x1860;
            let x1862 = x123 * x1851;
            let x1863 = 0.01 * x1862;
            let x1864 = x124 * x1843;
            let x1865 = 0.01 * x1864;
            let x1867 = x1861 + x1863;
            let x1868 = x1867 - x1865;
            let x1869 = 0.5 * x1868;
            let x1871 = 0.04 * x1657;
            let x1872 = x1871 - x1869;
            let x1873 = x297 * x553;
            let x1874 = 0.01 * x1873;
            let x1876 = x123 * x1843;
            let x1877 = 0.01 * x1876;
            let x1878 = x124 * x1851;
            let x1879 = 0.01 * x1878;
            let x1880 = x1877 - x1874;
            let x1881 = x1879 + x1880;
            let x1882 = 0.5 * x1881;
            let x1884 = 0.04 * x1653;
            let x1885 = x1884 - x1882;
            let x1886 = x295 * x1843;
            let x1887 = 0.01 * x1886;
            let x1889 = x555 - x1887;
            let x1890 = x1889 - x598;
            let x1891 = 0.5 * x1890;
            let x1892 = x1858 + x1891;
            let x1893 = x295 * x1851;
            let x1894 = 0.01 * x1893;
            let x1895 = x535 + x1894;
            let x1896 = x607 + x1895;
            let x1897 = 0.5 * x1896;
            let x1898 = x289 * 0.04;
            let x1899 = x1897 + x1898;
            let x1900 = x295 * x527;
            let x1901 = 0.01 * x1900;
            let x1904 = x1901 - x1879;
            let x1905 = x1904 - x1877;
            let x1906 = 0.5 * x1905;
            let x1907 = 0.04 * x1651;
            let x1908 = x1906 + x1907;
            let x1909 = x295 * x553;
            let x1910 = 0.01 * x1909;
            let x1911 = x1865 + x1910;
            let x1913 = x1863 - x1911;
            let x1914 = 0.5 * x1913;
            let x1915 = 0.04 * x1655;
            let x1916 = x1914 + x1915;
            let x1917 = x1861 - x1911;
            let x1918 = 0.5 * x1917;
            let x1919 = x1871 + x1918;
            let x1921 = x1879 - x1901;
            let x1922 = x1921 - x1874;
            let x1923 = 0.5 * x1922;
            let x1924 = x1907 + x1923;
            let x1925 = x1845 + x1895;
            let x1926 = 0.5 * x1925;
            let x1927 = x551 + x1926;
            let x1929 = x1887 - x555;
            let x1930 = x1929 - x1853;
            let x1931 = 0.5 * x1930;
            let x1932 = x566 + x1931;
            let x1933 = x1880 - x1901;
            let x1934 = 0.5 * x1933;
            let x1935 = x1884 + x1934;
            let x1937 = x1910 - x1867;
            let x1938 = 0.5 * x1937;
            let x1939 = x1915 + x1938;
            let x1940 = x1854 - x1887;
            let x1941 = 0.5 * x1940;
            let x1942 = x566 + x1941;
            let x1943 = x1846 + x1894;
            let x1944 = 0.5 * x1943;
            let x1945 = x611 + x1944;
            let x1946 = 2.0 * s[22];
            let x1947 = 2.0 * s[23];
            let x1948 = 0.1 * x541;
            let x1949 = s[22] * x1946;
            let x1950 = 0.2 * x1949;
            let x1951 = s[23] * x1947;
            let x1952 = 0.3 * x1951;
            let x1953 = x1948 + x1950;
            let x1954 = x1952 + x1953;
            let x1955 = 0.5 * x1954;
            let x1956 = s[5] * 0.8000000000000002;
            let x1957 = x1955 + x1956;
            let x1958 = 0.1 * x560;
            let x1959 = s[22] * x1947;
            let x1960 = 0.2 * x1959;
            let x1962 = s[23] * x1946;
            let x1963 = 0.3 * x1962;
            let x1964 = x1958 - x1960;
            let x1965 = x1963 + x1964;
            let x1966 = 0.5 * x1965;
            let x1968 = x50 * 0.8000000000000002;
            let x1969 = x1968 - x1966;
            let x1970 = s[8] * x1947;
            let x1971 = 0.1 * x1970;
            let x1972 = x529 * s[22];
            let x1973 = 0.2 * x1972;
            let x1974 = s[14] * s[23];
            let x1975 = 0.3 * x1974;
            let x1977 = x1971 + x1973;
            let x1978 = x1977 - x1975;
            let x1979 = 0.5 * x1978;
            let x1981 = 0.8000000000000002 * s[37];
            let x1982 = x1981 - x1979;
            let x1983 = s[8] * x1946;
            let x1984 = 0.1 * x1983;
            let x1986 = s[14] * s[22];
            let x1987 = 0.2 * x1986;
            let x1988 = x529 * s[23];
            let x1989 = 0.3 * x1988;
            let x1990 = x1987 - x1984;
            let x1991 = x1989 + x1990;
            let x1992 = 0.5 * x1991;
            let x1994 = 0.8000000000000002 * x1670;
            let x1995 = x1994 - x1992;
            let x1996 = 0.1 * x556;
            let x1998 = 0.2 * x1962;
            let x1999 = 0.3 * x1959;
            let x2001 = x1998 - x1996;
            let x2002 = x2001 - x1999;
            let x2003 = 0.5 * x2002;
            let x2004 = x1968 + x2003;
            let x2005 = 0.1 * x537;
            let x2006 = 0.2 * x1951;
            let x2007 = 0.3 * x1949;
            let x2008 = x2005 + x2006;
            let x2009 = x2007 + x2008;
            let x2010 = 0.5 * x2009;
            let x2011 = s[6] * 0.8000000000000002;
            let x2012 = x2010 + x2011;
            let x2013 = s[7] * x1947;
            let x2014 = 0.1 * x2013;
            let x2015 = 0.2 * x1988;
            let x2017 = 0.3 * x1986;
            let x2019 = x2014 - x2015;
            let x2020 = x2019 - x2017;
            let x2021 = 0.5 * x2020;
            let x2022 = 0.8000000000000002 * x1668;
            let x2023 = x2021 + x2022;
            let x2024 = s[7] * x1946;
            let x2025 = 0.1 * x2024;
            let x2026 = 0.2 * x1974;
            let x2027 = 0.3 * x1972;
            let x2028 = x2025 + x2026;
            let x2030 = x2027 - x2028;
            let x2031 = 0.5 * x2030;
            let x2032 = 0.8000000000000002 * s[35];
            let x2033 = x2031 + x2032;
            let x2034 = 0.1 * x1974;
            let x2035 = 0.2 * x2024;
            let x2036 = 0.3 * x1970;
            let x2037 = x2034 + x2035;
            let x2039 = x2036 - x2037;
            let x2040 = 0.5 * x2039;
            let x2041 = x1981 + x2040;
            let x2042 = 0.1 * x1988;
            let x2043 = 0.2 * x2013;
            let x2045 = 0.3 * x1983;
            let x2047 = x2042 - x2043;
            let x2048 = x2047 - x2045;
            let x2049 = 0.5 * x2048;
            let x2050 = x2022 + x2049;
            let x2051 = 0.1 * x1951;
            let x2052 = 0.2 * x537;
            let x2053 = x541 * 0.3;
            let x2054 = x2051 + x2052;
            let x2055 = x2053 + x2054;
            let x2056 = 0.5 * x2055;
            let x2057 = 0.8000000000000002 * x1665;
            let x2058 = x2056 + x2057;
            let x2059 = 0.1 * x1962;
            let x2061 = 0.2 * x556;
            let x2062 = x560 * 0.3;
            let x2064 = x2061 - x2059;
            let x2065 = x2064 - x2062;
            let x2066 = 0.5 * x2065;
            let x2067 = 0.8000000000000002 * x1674;
            let x2068 = x2066 + x2067;
            let x2069 = 0.1 * x1986;
            let x2070 = 0.2 * x1983;
            let x2072 = 0.3 * x2013;
            let x2074 = x2069 - x2070;
            let x2075 = x2074 - x2072;
            let x2076 = 0.5 * x2075;
            let x2077 = x1994 + x2076;
            let x2078 = 0.1 * x1972;
            let x2079 = 0.2 * x1970;
            let x2080 = 0.3 * x2024;
            let x2081 = x2078 + x2079;
            let x2083 = x2080 - x2081;
            let x2084 = 0.5 * x2083;
            let x2085 = x2032 + x2084;
            let x2086 = 0.1 * x1959;
            let x2088 = 0.2 * x560;
            let x2089 = x556 * 0.3;
            let x2091 = x2088 - x2086;
            let x2092 = x2091 - x2089;
            let x2093 = 0.5 * x2092;
            let x2094 = x2067 + x2093;
            let x2095 = 0.1 * x1949;
            let x2096 = 0.2 * x541;
            let x2097 = x537 * 0.3;
            let x2098 = x2095 + x2096;
            let x2099 = x2097 + x2098;
            let x2100 = 0.5 * x2099;
            let x2101 = 0.8000000000000002 * x1666;
            let x2102 = x2100 + x2101;
            let x2103 = 50.0 * x1794;
            let x2105 = x1807 - x2103;
            let x2106 = x293 * x1803;
            let x2107 = x2105 * x2106;
            let x2111 = s[22] * s[34];
            let x2112 = x529 * s[39];
            let x2113 = x2111 + x2112;
            let x2114 = s[58] * x2113;
            let x2124 = s[63] * x2114;
            let x2131 = s[4] * s[22];
            let x2136 = 1.0 + x2107;
            let x2137 = x2124 - x2131;
            let x2144 = x1708 - x1707;
            let x2145 = x177 + x2144;
            let x2146 = x2145 - x178;
            let x2147 = 2.0 * x2146;
            let x2148 = x1698 + x1702;
            let x2150 = x1703 - x2148;
            let x2151 = x1699 + x2150;
            let x2152 = 2.0 * x2151;
            let x2155 = x1690 - x1694;
            let x2156 = x2155 - x1691;
            let x2157 = x1695 + x2156;
            let x2158 = 2.0 * x2157;
            let x2159 = 2.0 * x2147;
            let x2160 = 2.0 * x2152;
            let x2161 = 2.0 * x2158;
            let x2162 = x1746 + x1749;
            let x2164 = x1749 - x2162;
            let x2165 = x1746 + x2164;
            let x2166 = 2.0 * x2165;
            let x2169 = x1740 - x1743;
            let x2170 = x2169 - x1740;
            let x2171 = x1743 + x2170;
            let x2172 = 2.0 * x2171;
            let x2173 = 2.0 * x2166;
            let x2174 = 2.0 * x2172;
            let x2175 = x463 * x2159;
            let x2176 = 0.01 * x2175;
            let x2177 = x216 * x2160;
            let x2178 = x123 * x2173;
            let x2179 = x2177 + x2178;
            let x2180 = 0.01 * x2179;
            let x2181 = x217 * x2161;
            let x2182 = x124 * x2174;
            let x2183 = x2181 + x2182;
            let x2184 = 0.01 * x2183;
            let x2185 = x2176 + x2180;
            let x2186 = x2184 + x2185;
            let x2187 = 0.5 * x2186;
            let x2188 = x461 * x2159;
            let x2189 = 0.01 * x2188;
            let x2190 = x217 * x2160;
            let x2191 = x124 * x2173;
            let x2192 = x2190 + x2191;
            let x2193 = 0.01 * x2192;
            let x2195 = x216 * x2161;
            let x2196 = x123 * x2174;
            let x2197 = x2195 + x2196;
            let x2198 = 0.01 * x2197;
            let x2199 = x2189 - x2193;
            let x2200 = x2198 + x2199;
            let x2201 = 0.5 * x2200;
            let x2202 = x217 * x2159;
            let x2203 = 0.01 * x2202;
            let x2204 = x461 * x2160;
            let x2205 = x295 * x2173;
            let x2206 = x2204 + x2205;
            let x2207 = 0.01 * x2206;
            let x2208 = x463 * x2161;
            let x2209 = x297 * x2174;
            let x2210 = x2208 + x2209;
            let x2211 = 0.01 * x2210;
            let x2213 = x2203 + x2207;
            let x2214 = x2213 - x2211;
            let x2215 = 0.5 * x2214;
            let x2216 = x216 * x2159;
            let x2217 = 0.01 * x2216;
            let x2219 = x463 * x2160;
            let x2220 = x297 * x2173;
            let x2221 = x2219 + x2220;
            let x2222 = 0.01 * x2221;
            let x2223 = x461 * x2161;
            let x2224 = x295 * x2174;
            let x2225 = x2223 + x2224;
            let x2226 = 0.01 * x2225;
            let x2227 = x2222 - x2217;
            let x2228 = x2226 + x2227;
            let x2229 = 0.5 * x2228;
            let x2230 = x444 + x448;
            let x2231 = x740 + x2230;
            let x2232 = x741 + x2231;
            let x2233 = 0.01 * x2177;
            let x2234 = 0.01 * x2181;
            let x2235 = x2176 + x2233;
            let x2236 = x2234 + x2235;
            let x2237 = 0.5 * x2236;
            let x2238 = x2187 + x2237;
            let x2239 = q[1] * 0.04;
            let x2240 = x2232 * x2239;
            let x2242 = x2238 - x2240;
            let x2244 = 0.01 * x2190;
            let x2245 = 0.01 * x2195;
            let x2247 = x2244 - x2189;
            let x2248 = x2247 - x2245;
            let x2249 = 0.5 * x2248;
            let x2251 = x2249 - x2201;
            let x2252 = q[2] * 0.04;
            let x2253 = x2232 * x2252;
            let x2255 = x2251 - x2253;
            let x2256 = 0.01 * x2204;
            let x2257 = 0.01 * x2208;
            let x2258 = x2203 + x2256;
            let x2260 = x2257 - x2258;
            let x2261 = 0.5 * x2260;
            let x2263 = x2261 - x2215;
            let x2264 = x754 * x2232;
            let x2266 = x2263 - x2264;
            let x2267 = 0.01 * x2219;
            let x2269 = 0.01 * x2223;
            let x2271 = x2217 - x2267;
            let x2272 = x2271 - x2269;
            let x2273 = 0.5 * x2272;
            let x2275 = x2273 - x2229;
            let x2276 = x773 * x2232;
            let x2278 = x2275 - x2276;
            let x2311 = s[13] * s[76];
            let x2312 = 0.1 * x2311;
            let x2313 = s[19] * s[77];
            let x2314 = s[22] * s[89];
            let x2315 = x2313 + x2314;
            let x2316 = 0.2 * x2315;
            let x2317 = s[20] * s[78];
            let x2318 = s[23] * s[90];
            let x2319 = x2317 + x2318;
            let x2320 = 0.3 * x2319;
            let x2321 = x2312 + x2316;
            let x2322 = x2320 + x2321;
            let x2323 = 0.5 * x2322;
            let x2369 = 0.2 * x2313;
            let x2370 = 0.3 * x2317;
            let x2371 = x2312 + x2369;
            let x2372 = x2370 + x2371;
            let x2373 = 0.5 * x2372;
            let x2374 = x2323 + x2373;
            let x2375 = q[5] * 0.8000000000000002;
            let x2376 = s[93] * x2375;
            let x2378 = x2374 - x2376;
            let x2417 = x2137 + x2378;
            phi[0] = x1659;
            phi_q[0] = x124;
            phi_q[1] = x123;
            phi_q[2] = x297;
            phi_q[3] = x295;
            phi[1] = x1663;
            phi_q[4] = x128;
            phi_q[5] = x124;
            phi_q[6] = x1684;
            phi_q[7] = x297;
            phi[2] = x1664;
            phi_q[8] = x297;
            phi_q[9] = x295;
            phi_q[10] = x124;
            phi_q[11] = x123;
            phi[3] = x1673;
            phi_q[12] = x1687;
            phi_q[13] = s[22];
            phi_q[14] = s[8];
            phi_q[15] = x127;
            phi[4] = x1677;
            phi_q[16] = x474;
            phi_q[17] = x127;
            phi_q[18] = x1687;
            phi_q[19] = x1688;
            phi[5] = x1680;
            phi_q[20] = x295;
            phi_q[21] = x297;
            phi_q[22] = x123;
            phi_q[23] = x124;
            phi[6] = x1683;
            phi_q[24] = s[7];
            phi_q[25] = s[8];
            phi_q[26] = s[22];
            phi_q[27] = s[23];
            mass[0] = 2.0;
            mass[1] = x1850;
            mass[2] = x1859;
            mass[3] = x1872;
            mass[4] = x1885;
            mass[5] = x1892;
            mass[6] = x1899;
            mass[7] = x1908;
            mass[8] = x1916;
            mass[9] = x1919;
            mass[10] = x1924;
            mass[11] = x1927;
            mass[12] = x1932;
            mass[13] = x1935;
            mass[14] = x1939;
            mass[15] = x1942;
            mass[16] = x1945;
            mass[17] = x1957;
            mass[18] = x1969;
            mass[19] = x1982;
            mass[20] = x1995;
            mass[21] = x2004;
            mass[22] = x2012;
            mass[23] = x2023;
            mass[24] = x2033;
            mass[25] = x2041;
            mass[26] = x2050;
            mass[27] = x2058;
            mass[28] = x2068;
            mass[29] = x2077;
            mass[30] = x2085;
            mass[31] = x2094;
            mass[32] = x2102;
            force[0] = x2136;
            force[1] = x2242;
            force[2] = x2255;
            force[3] = x2266;
            force[4] = x2278;
            force[5] = x2417;
        }
        #[inline(never)]
        fn eval_newton_part_1(
            q: &[f64; 9],
            qd: &[f64; 9],
            s: &[f64; 94],
            force: &mut [f64; 9],
        ) {
            let x218 = 2.0 * qd[5];
            let x2115 = s[23] * s[34];
            let x2117 = s[14] * s[39];
            let x2118 = x2117 - x2115;
            let x2119 = s[58] * x2118;
            let x2120 = s[7] * s[34];
            let x2121 = s[58] * x2120;
            let x2122 = s[8] * s[34];
            let x2123 = s[58] * x2122;
            let x2125 = s[63] * x2119;
            let x2126 = s[63] * x2121;
            let x2127 = s[63] * x2123;
            let x2133 = s[4] * s[23];
            let x2134 = s[4] * s[7];
            let x2135 = s[4] * s[8];
            let x2138 = x2125 + x2133;
            let x2139 = x2126 + x2134;
            let x2140 = x2127 + x2135;
            let x2324 = x218 * s[76];
            let x2325 = 0.1 * x2324;
            let x2326 = s[20] * s[77];
            let x2327 = s[23] * s[89];
            let x2328 = x2326 + x2327;
            let x2329 = 0.2 * x2328;
            let x2331 = s[19] * s[78];
            let x2332 = s[22] * s[90];
            let x2333 = x2331 + x2332;
            let x2334 = 0.3 * x2333;
            let x2335 = x2325 - x2329;
            let x2336 = x2334 + x2335;
            let x2337 = 0.5 * x2336;
            let x2338 = s[20] * s[76];
            let x2339 = 0.1 * x2338;
            let x2340 = x218 * s[77];
            let x2341 = s[7] * s[89];
            let x2342 = x2340 + x2341;
            let x2343 = 0.2 * x2342;
            let x2344 = s[13] * s[78];
            let x2345 = s[8] * s[90];
            let x2346 = x2344 + x2345;
            let x2347 = 0.3 * x2346;
            let x2349 = x2339 + x2343;
            let x2350 = x2349 - x2347;
            let x2351 = 0.5 * x2350;
            let x2352 = s[19] * s[76];
            let x2353 = 0.1 * x2352;
            let x2355 = s[13] * s[77];
            let x2356 = s[8] * s[89];
            let x2357 = x2355 + x2356;
            let x2358 = 0.2 * x2357;
            let x2359 = x218 * s[78];
            let x2360 = s[7] * s[90];
            let x2361 = x2359 + x2360;
            let x2362 = 0.3 * x2361;
            let x2363 = x2358 - x2353;
            let x2364 = x2362 + x2363;
            let x2365 = 0.5 * x2364;
            let x2380 = 0.2 * x2326;
            let x2381 = 0.3 * x2331;
            let x2383 = x2380 - x2325;
            let x2384 = x2383 - x2381;
            let x2385 = 0.5 * x2384;
            let x2387 = x2385 - x2337;
            let x2388 = q[6] * 0.8000000000000002;
            let x2389 = s[93] * x2388;
            let x2391 = x2387 - x2389;
            let x2392 = 0.2 * x2340;
            let x2393 = 0.3 * x2344;
            let x2394 = x2339 + x2392;
            let x2396 = x2393 - x2394;
            let x2397 = 0.5 * x2396;
            let x2399 = x2397 - x2351;
            let x2400 = q[7] * 0.8000000000000002;
            let x2401 = s[93] * x2400;
            let x2403 = x2399 - x2401;
            let x2404 = 0.2 * x2355;
            let x2406 = 0.3 * x2359;
            let x2408 = x2353 - x2404;
            let x2409 = x2408 - x2406;
            let x2410 = 0.5 * x2409;
            let x2412 = x2410 - x2365;
            let x2413 = q[8] * 0.8000000000000002;
            let x2414 = s[93] * x2413;
            let x2416 = x2412 - x2414;
            let x2418 = x2138 + x2391;
            let x2419 = x2139 + x2403;
            let x2420 = x2416 - x2140;
            force[6] = x2418;
            force[7] = x2419;
            force[8] = x2420;
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
    },
};
