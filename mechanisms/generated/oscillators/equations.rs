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
    let x36 = q[3] * q[3];
    let x37 = q[4] * q[4];
    let x38 = q[5] * q[5];
    let x39 = q[6] * q[6];
    let x40 = x36 + x37;
    let x50 = q[4] * q[5];
    let x51 = 2.0 * x50;
    let x52 = q[3] * q[6];
    let x54 = 2.0 * x52;
    let x57 = q[4] * q[6];
    let x58 = 2.0 * x57;
    let x59 = q[3] * q[5];
    let x60 = 2.0 * x59;
    let x62 = x51 + x54;
    let x63 = q[5] * q[6];
    let x64 = 2.0 * x63;
    let x65 = q[3] * q[4];
    let x67 = 2.0 * x65;
    let x72 = x58 - x60;
    let x73 = x64 + x67;
    let x81 = q[10] * q[10];
    let x82 = q[11] * q[11];
    let x83 = q[12] * q[12];
    let x84 = q[13] * q[13];
    let x85 = x81 + x82;
    let x94 = q[11] * q[12];
    let x95 = 2.0 * x94;
    let x96 = q[10] * q[13];
    let x98 = 2.0 * x96;
    let x100 = x95 - x98;
    let x107 = q[12] * q[13];
    let x108 = 2.0 * x107;
    let x109 = q[10] * q[11];
    let x111 = 2.0 * x109;
    let x117 = x108 + x111;
    let x124 = -q[7];
    let x126 = 1.0 - q[8];
    let x128 = 2.0 - q[9];
    let x129 = -x117;
    let x130 = x38 + x40;
    let x131 = x39 + x130;
    let x132 = x131 - 1.0;
    let x133 = x83 + x85;
    let x134 = x84 + x133;
    let x135 = x134 - 1.0;
    out[0] = x62;
    out[1] = x72;
    out[2] = q[1];
    out[3] = q[2];
    out[4] = x73;
    out[5] = x124;
    out[6] = x126;
    out[7] = x128;
    out[8] = x100;
    out[9] = x129;
    out[10] = x132;
    out[11] = x135;
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
    let x136 = q[3] * 2.0;
    let x137 = q[4] * 2.0;
    let x138 = q[5] * 2.0;
    let x139 = q[6] * 2.0;
    let x140 = -x138;
    let x141 = -x136;
    let x142 = 2.0 * q[10];
    let x143 = 2.0 * q[11];
    let x144 = 2.0 * q[12];
    let x145 = 2.0 * q[13];
    let x146 = -x145;
    let x147 = -x143;
    let x148 = -x142;
    let x149 = -x144;
    out[0] = x139;
    out[1] = x138;
    out[2] = x137;
    out[3] = x136;
    out[4] = x140;
    out[5] = x139;
    out[6] = x141;
    out[7] = x137;
    out[8] = 1.0;
    out[9] = 1.0;
    out[10] = x137;
    out[11] = x136;
    out[12] = x139;
    out[13] = x138;
    out[14] = -1.0;
    out[15] = -1.0;
    out[16] = -1.0;
    out[17] = x146;
    out[18] = x144;
    out[19] = x143;
    out[20] = x148;
    out[21] = x147;
    out[22] = x148;
    out[23] = x146;
    out[24] = x149;
    out[25] = x136;
    out[26] = x137;
    out[27] = x138;
    out[28] = x139;
    out[29] = x142;
    out[30] = x143;
    out[31] = x144;
    out[32] = x145;
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
    let x229 = 2.0 * qd[3];
    let x230 = 2.0 * qd[4];
    let x231 = 2.0 * qd[5];
    let x232 = 2.0 * qd[6];
    let x233 = 2.0 * qd[10];
    let x234 = 2.0 * qd[11];
    let x235 = 2.0 * qd[12];
    let x236 = 2.0 * qd[13];
    let x237 = qd[3] * x229;
    let x238 = qd[4] * x230;
    let x239 = qd[5] * x231;
    let x240 = qd[6] * x232;
    let x241 = x237 + x238;
    let x242 = qd[4] * qd[5];
    let x243 = x242 + x242;
    let x244 = 2.0 * x243;
    let x245 = qd[3] * qd[6];
    let x246 = x245 + x245;
    let x247 = 2.0 * x246;
    let x248 = qd[4] * qd[6];
    let x249 = x248 + x248;
    let x250 = 2.0 * x249;
    let x251 = qd[3] * qd[5];
    let x252 = x251 + x251;
    let x253 = 2.0 * x252;
    let x254 = x244 + x247;
    let x255 = qd[5] * qd[6];
    let x256 = x255 + x255;
    let x257 = 2.0 * x256;
    let x258 = qd[3] * qd[4];
    let x259 = x258 + x258;
    let x260 = 2.0 * x259;
    let x262 = x250 - x253;
    let x263 = x257 + x260;
    let x264 = qd[10] * x233;
    let x265 = qd[11] * x234;
    let x266 = qd[12] * x235;
    let x267 = qd[13] * x236;
    let x268 = x264 + x265;
    let x269 = qd[11] * qd[12];
    let x270 = x269 + x269;
    let x271 = 2.0 * x270;
    let x272 = qd[10] * qd[13];
    let x273 = x272 + x272;
    let x274 = 2.0 * x273;
    let x276 = x271 - x274;
    let x277 = qd[12] * qd[13];
    let x278 = x277 + x277;
    let x279 = 2.0 * x278;
    let x280 = qd[10] * qd[11];
    let x281 = x280 + x280;
    let x282 = 2.0 * x281;
    let x283 = x279 + x282;
    let x285 = x239 + x241;
    let x286 = x240 + x285;
    let x287 = x266 + x268;
    let x288 = x267 + x287;
    let x289 = -x254;
    let x290 = -x262;
    let x291 = -x263;
    let x292 = -x276;
    let x293 = -x286;
    let x294 = -x288;
    out[0] = x289;
    out[1] = x290;
    out[2] = 0.0;
    out[3] = 0.0;
    out[4] = x291;
    out[5] = 0.0;
    out[6] = 0.0;
    out[7] = 0.0;
    out[8] = x292;
    out[9] = x283;
    out[10] = x293;
    out[11] = x294;
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
    let x36 = q[3] * q[3];
    let x37 = q[4] * q[4];
    let x38 = q[5] * q[5];
    let x39 = q[6] * q[6];
    let x40 = x36 + x37;
    let x50 = q[4] * q[5];
    let x51 = 2.0 * x50;
    let x52 = q[3] * q[6];
    let x54 = 2.0 * x52;
    let x57 = q[4] * q[6];
    let x58 = 2.0 * x57;
    let x59 = q[3] * q[5];
    let x60 = 2.0 * x59;
    let x62 = x51 + x54;
    let x63 = q[5] * q[6];
    let x64 = 2.0 * x63;
    let x65 = q[3] * q[4];
    let x67 = 2.0 * x65;
    let x72 = x58 - x60;
    let x73 = x64 + x67;
    let x81 = q[10] * q[10];
    let x82 = q[11] * q[11];
    let x83 = q[12] * q[12];
    let x84 = q[13] * q[13];
    let x85 = x81 + x82;
    let x94 = q[11] * q[12];
    let x95 = 2.0 * x94;
    let x96 = q[10] * q[13];
    let x98 = 2.0 * x96;
    let x100 = x95 - x98;
    let x107 = q[12] * q[13];
    let x108 = 2.0 * x107;
    let x109 = q[10] * q[11];
    let x111 = 2.0 * x109;
    let x117 = x108 + x111;
    let x124 = -q[7];
    let x126 = 1.0 - q[8];
    let x128 = 2.0 - q[9];
    let x129 = -x117;
    let x130 = x38 + x40;
    let x131 = x39 + x130;
    let x132 = x131 - 1.0;
    let x133 = x83 + x85;
    let x134 = x84 + x133;
    let x135 = x134 - 1.0;
    let x136 = q[3] * 2.0;
    let x137 = q[4] * 2.0;
    let x138 = q[5] * 2.0;
    let x139 = q[6] * 2.0;
    let x140 = -x138;
    let x141 = -x136;
    let x142 = 2.0 * q[10];
    let x143 = 2.0 * q[11];
    let x144 = 2.0 * q[12];
    let x145 = 2.0 * q[13];
    let x146 = -x145;
    let x147 = -x143;
    let x148 = -x142;
    let x149 = -x144;
    let x229 = 2.0 * qd[3];
    let x230 = 2.0 * qd[4];
    let x231 = 2.0 * qd[5];
    let x232 = 2.0 * qd[6];
    let x233 = 2.0 * qd[10];
    let x234 = 2.0 * qd[11];
    let x235 = 2.0 * qd[12];
    let x236 = 2.0 * qd[13];
    let x237 = qd[3] * x229;
    let x238 = qd[4] * x230;
    let x239 = qd[5] * x231;
    let x240 = qd[6] * x232;
    let x241 = x237 + x238;
    let x242 = qd[4] * qd[5];
    let x243 = x242 + x242;
    let x244 = 2.0 * x243;
    let x245 = qd[3] * qd[6];
    let x246 = x245 + x245;
    let x247 = 2.0 * x246;
    let x248 = qd[4] * qd[6];
    let x249 = x248 + x248;
    let x250 = 2.0 * x249;
    let x251 = qd[3] * qd[5];
    let x252 = x251 + x251;
    let x253 = 2.0 * x252;
    let x254 = x244 + x247;
    let x255 = qd[5] * qd[6];
    let x256 = x255 + x255;
    let x257 = 2.0 * x256;
    let x258 = qd[3] * qd[4];
    let x259 = x258 + x258;
    let x260 = 2.0 * x259;
    let x262 = x250 - x253;
    let x263 = x257 + x260;
    let x264 = qd[10] * x233;
    let x265 = qd[11] * x234;
    let x266 = qd[12] * x235;
    let x267 = qd[13] * x236;
    let x268 = x264 + x265;
    let x269 = qd[11] * qd[12];
    let x270 = x269 + x269;
    let x271 = 2.0 * x270;
    let x272 = qd[10] * qd[13];
    let x273 = x272 + x272;
    let x274 = 2.0 * x273;
    let x276 = x271 - x274;
    let x277 = qd[12] * qd[13];
    let x278 = x277 + x277;
    let x279 = 2.0 * x278;
    let x280 = qd[10] * qd[11];
    let x281 = x280 + x280;
    let x282 = 2.0 * x281;
    let x283 = x279 + x282;
    let x285 = x239 + x241;
    let x286 = x240 + x285;
    let x287 = x266 + x268;
    let x288 = x267 + x287;
    let x289 = -x254;
    let x290 = -x262;
    let x291 = -x263;
    let x292 = -x276;
    let x293 = -x286;
    let x294 = -x288;
    phi[0] = x62;
    phi_q[0] = x139;
    phi_q[1] = x138;
    phi_q[2] = x137;
    phi_q[3] = x136;
    phi_t[0] = 0.0;
    gamma[0] = x289;
    phi[1] = x72;
    phi_q[4] = x140;
    phi_q[5] = x139;
    phi_q[6] = x141;
    phi_q[7] = x137;
    phi_t[1] = 0.0;
    gamma[1] = x290;
    phi[2] = q[1];
    phi_q[8] = 1.0;
    phi_t[2] = 0.0;
    gamma[2] = 0.0;
    phi[3] = q[2];
    phi_q[9] = 1.0;
    phi_t[3] = 0.0;
    gamma[3] = 0.0;
    phi[4] = x73;
    phi_q[10] = x137;
    phi_q[11] = x136;
    phi_q[12] = x139;
    phi_q[13] = x138;
    phi_t[4] = 0.0;
    gamma[4] = x291;
    phi[5] = x124;
    phi_q[14] = -1.0;
    phi_t[5] = 0.0;
    gamma[5] = 0.0;
    phi[6] = x126;
    phi_q[15] = -1.0;
    phi_t[6] = 0.0;
    gamma[6] = 0.0;
    phi[7] = x128;
    phi_q[16] = -1.0;
    phi_t[7] = 0.0;
    gamma[7] = 0.0;
    phi[8] = x100;
    phi_q[17] = x146;
    phi_q[18] = x144;
    phi_q[19] = x143;
    phi_q[20] = x148;
    phi_t[8] = 0.0;
    gamma[8] = x292;
    phi[9] = x129;
    phi_q[21] = x147;
    phi_q[22] = x148;
    phi_q[23] = x146;
    phi_q[24] = x149;
    phi_t[9] = 0.0;
    gamma[9] = x283;
    phi[10] = x132;
    phi_q[25] = x136;
    phi_q[26] = x137;
    phi_q[27] = x138;
    phi_q[28] = x139;
    phi_t[10] = 0.0;
    gamma[10] = x293;
    phi[11] = x135;
    phi_q[29] = x142;
    phi_q[30] = x143;
    phi_q[31] = x144;
    phi_q[32] = x145;
    phi_t[11] = 0.0;
    gamma[11] = x294;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
    let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
    let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    potential_into_part_0(k, q, out);
}
#[inline(never)]
fn potential_into_part_0(k: &[f64; 17], q: &[f64; 14], out: &mut [f64; 1]) {
    let x81 = q[10] * q[10];
    let x82 = q[11] * q[11];
    let x85 = x81 + x82;
    let x86 = 2.0 * x85;
    let x87 = x86 - 1.0;
    let x101 = q[11] * q[13];
    let x102 = 2.0 * x101;
    let x103 = q[10] * q[12];
    let x104 = 2.0 * x103;
    let x116 = x102 - x104;
    let x329 = q[8] * 9.81;
    let x330 = 1.0 + q[0];
    let x331 = x330 * x330;
    let x332 = q[1] * q[1];
    let x333 = q[2] * q[2];
    let x334 = x331 + x332;
    let x335 = x333 + x334;
    let x336 = x335.sqrt();
    let x348 = x336 - 1.0;
    let x356 = x348 * x348;
    let x366 = -x116;
    let x367 = x366.atan2(x87);
    let x397 = x367 * x367;
    let x1720 = q[1] * k[11];
    let x1728 = x356 * k[13];
    let x1741 = x397 * k[14];
    let x1759 = x329 + x1720;
    let x1760 = x1728 + x1759;
    let x1761 = x1741 + x1760;
    out[0] = x1761;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
    let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    power_nc_into_part_0(k, q, qd, t, out);
}
#[inline(never)]
fn power_nc_into_part_0(
    k: &[f64; 17],
    q: &[f64; 14],
    qd: &[f64; 14],
    t: f64,
    out: &mut [f64; 1],
) {
    let x13 = t.sin();
    let x81 = q[10] * q[10];
    let x82 = q[11] * q[11];
    let x85 = x81 + x82;
    let x86 = 2.0 * x85;
    let x87 = x86 - 1.0;
    let x101 = q[11] * q[13];
    let x102 = 2.0 * x101;
    let x103 = q[10] * q[12];
    let x104 = 2.0 * x103;
    let x116 = x102 - x104;
    let x142 = 2.0 * q[10];
    let x143 = 2.0 * q[11];
    let x197 = x142 * qd[10];
    let x198 = x143 * qd[11];
    let x201 = x197 + x198;
    let x330 = 1.0 + q[0];
    let x331 = x330 * x330;
    let x332 = q[1] * q[1];
    let x333 = q[2] * q[2];
    let x334 = x331 + x332;
    let x335 = x333 + x334;
    let x336 = x335.sqrt();
    let x337 = 2.0 * x330;
    let x338 = qd[0] * x337;
    let x339 = q[1] * 2.0;
    let x340 = qd[1] * x339;
    let x341 = q[2] * 2.0;
    let x342 = qd[2] * x341;
    let x343 = x338 + x340;
    let x344 = x342 + x343;
    let x345 = 2.0 * x336;
    let x346 = 1.0 / x345;
    let x347 = x344 * x346;
    let x368 = 2.0 * x201;
    let x369 = q[13] * qd[11];
    let x370 = q[11] * qd[13];
    let x371 = x369 + x370;
    let x372 = 2.0 * x371;
    let x373 = q[12] * qd[10];
    let x374 = q[10] * qd[12];
    let x375 = x373 + x374;
    let x376 = 2.0 * x375;
    let x378 = x372 - x376;
    let x380 = x87 * x87;
    let x381 = x116 * x116;
    let x382 = x380 + x381;
    let x383 = x87 * x378;
    let x385 = x116 * x368;
    let x387 = x385 - x383;
    let x388 = 1.0 / x382;
    let x389 = x387 * x388;
    let x432 = x369 - x373;
    let x433 = x374 + x432;
    let x434 = x433 - x370;
    let x435 = 2.0 * x434;
    let x1702 = t * k[1];
    let x1703 = x1702.sin();
    let x1704 = k[0] * x1703;
    let x1708 = t * k[4];
    let x1709 = x1708.cos();
    let x1710 = k[3] * x1709;
    let x1712 = x13 * k[5];
    let x1722 = x347 * k[6];
    let x1724 = x1704 - x1722;
    let x1729 = x347 * x1724;
    let x1733 = qd[0] * k[2];
    let x1735 = x389 * k[7];
    let x1737 = x1710 - x1735;
    let x1742 = x389 * x1737;
    let x1747 = x435 * x1712;
    let x1762 = x1729 + x1733;
    let x1763 = x1742 + x1762;
    let x1764 = x1747 + x1763;
    out[0] = x1764;
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
pub const N_K: usize = 17;
/// `setup` at the file's parameter values: what the types without parameters read.
pub static K: [f64; 17] = [
    3f64,
    4f64,
    1f64,
    0.5f64,
    3f64,
    0.2f64,
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
    let p: &[f64; 33] = p.try_into().expect("p must have 33 entries");
    let k: &mut [f64; 17] = k.try_into().expect("k must have 17 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 33], k: &mut [f64; 17]) {
    let x326 = p[5] * 9.81;
    let x327 = -x326;
    let x355 = 0.5 * p[3];
    let x396 = 0.5 * p[4];
    let x574 = 2.0 * p[5];
    let x575 = 0.5 * x574;
    let x951 = p[2] + 0.1;
    let x952 = 0.3 + x951;
    let x953 = 4.0 * x952;
    let x955 = x953 * 0.3333333333333333;
    k[0] = p[27];
    k[1] = p[28];
    k[2] = p[29];
    k[3] = p[30];
    k[4] = p[31];
    k[5] = p[32];
    k[6] = p[0];
    k[7] = p[1];
    k[8] = p[2];
    k[9] = p[3];
    k[10] = p[4];
    k[11] = x326;
    k[12] = x327;
    k[13] = x355;
    k[14] = x396;
    k[15] = x575;
    k[16] = x955;
}
/// The parameters the generated code takes at run time by name: the file's
/// `[parameters]` entries that reach only masses, inertias and springs' constants.
pub static PARAMETERS: [&str; 6] = ["c", "ct", "j", "k", "kt", "m"];
/// Their values in the file.
pub static PARAMETER_VALUES: [f64; 6] = [0.8f64, 0.1f64, 0.2f64, 50f64, 2f64, 2f64];
/// Number of values `p` holds: the parameters by name, then the model's numbers that
/// the other parameters reach (read off the file loaded at their values: `DATA`).
pub const N_P: usize = 33;
/// `p` at the file's values.
pub static P0: [f64; 33] = [
    0.8f64,
    0.1f64,
    0.2f64,
    50f64,
    2f64,
    2f64,
    0.8f64,
    0.1f64,
    3f64,
    1f64,
    0.2f64,
    50f64,
    2f64,
    2f64,
    3f64,
    1f64,
    0.5f64,
    0.2f64,
    4f64,
    0.1f64,
    2f64,
    0.2f64,
    0.1f64,
    50f64,
    0.8f64,
    2f64,
    0.1f64,
    3f64,
    4f64,
    1f64,
    0.5f64,
    3f64,
    0.2f64,
];
/// Where the numbers after the named parameters come from in the model (positions in
/// the generator's `slots::numbers`).
pub static DATA: [u32; 27] = [
    3u32, 4u32, 5u32, 6u32, 7u32, 8u32, 9u32, 10u32, 11u32, 12u32, 13u32, 14u32, 15u32,
    16u32, 17u32, 23u32, 25u32, 79u32, 80u32, 91u32, 92u32, 94u32, 95u32, 96u32, 99u32,
    100u32, 102u32,
];
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
    let p: &[f64; 33] = p.try_into().expect("p must have 33 entries");
    let out: &mut [f64; 8] = out.try_into().expect("out must have 8 entries");
    mass_properties_part_0(p, out);
}
#[inline(never)]
fn mass_properties_part_0(p: &[f64; 33], out: &mut [f64; 8]) {
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
    let p: &[f64; 33] = p.try_into().expect("p must have 33 entries");
    let out: &mut [f64; 8] = out.try_into().expect("out must have 8 entries");
    force_constants_part_0(p, out);
}
#[inline(never)]
fn force_constants_part_0(p: &[f64; 33], out: &mut [f64; 8]) {
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
        let (mut props, mut constants) = ([0.0; 8], [0.0; 8]);
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
        let (mut props, mut constants) = ([0.0; 8], [0.0; 8]);
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
fn built_reduced(p: Parameters) -> symbody_runtime::registry::Built {
    vec![
        (Formulation::Exact, Box::new(reduced::ExactAt::new(& p)) as Box < dyn Mechanism
        + Sync >)
    ]
}
fn at_parameters_reduced(
    set: &[(&str, f64)],
) -> Result<symbody_runtime::registry::Built, ParameterError> {
    Parameters::at(set).map(built_reduced)
}
fn at_values_reduced(
    values: &[f64],
) -> Result<symbody_runtime::registry::Built, ParameterError> {
    Parameters::from_values(values).map(built_reduced)
}
/// This mechanism at other values of its run-time parameters, for the registries.
pub static RUN_TIME_ENTRY: symbody_runtime::registry::RunTime = symbody_runtime::registry::RunTime {
    parameters: &RUN_TIME,
    build: at_parameters,
    build_reduced: Some(at_parameters_reduced),
    data: &DATA,
    p0: &P0,
    build_values: at_values,
    build_reduced_values: Some(at_values_reduced),
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
        let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
        let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
        let dq: &mut [f64; 25] = dq.try_into().expect("dq must have 25 entries");
        let dqd: &mut [f64; 25] = dqd.try_into().expect("dqd must have 25 entries");
        force_jacobian_part_0(k, q, qd, t, dq, dqd);
    }
    #[inline(never)]
    fn force_jacobian_part_0(
        k: &[f64; 17],
        q: &[f64; 14],
        qd: &[f64; 14],
        t: f64,
        dq: &mut [f64; 25],
        dqd: &mut [f64; 25],
    ) {
        let x13 = t.sin();
        let x81 = q[10] * q[10];
        let x82 = q[11] * q[11];
        let x85 = x81 + x82;
        let x86 = 2.0 * x85;
        let x87 = x86 - 1.0;
        let x101 = q[11] * q[13];
        let x102 = 2.0 * x101;
        let x103 = q[10] * q[12];
        let x104 = 2.0 * x103;
        let x116 = x102 - x104;
        let x142 = 2.0 * q[10];
        let x143 = 2.0 * q[11];
        let x144 = 2.0 * q[12];
        let x145 = 2.0 * q[13];
        let x197 = x142 * qd[10];
        let x198 = x143 * qd[11];
        let x201 = x197 + x198;
        let x233 = 2.0 * qd[10];
        let x234 = 2.0 * qd[11];
        let x235 = 2.0 * qd[12];
        let x236 = 2.0 * qd[13];
        let x330 = 1.0 + q[0];
        let x331 = x330 * x330;
        let x332 = q[1] * q[1];
        let x333 = q[2] * q[2];
        let x334 = x331 + x332;
        let x335 = x333 + x334;
        let x336 = x335.sqrt();
        let x337 = 2.0 * x330;
        let x338 = qd[0] * x337;
        let x339 = q[1] * 2.0;
        let x340 = qd[1] * x339;
        let x341 = q[2] * 2.0;
        let x342 = qd[2] * x341;
        let x343 = x338 + x340;
        let x344 = x342 + x343;
        let x345 = 2.0 * x336;
        let x346 = 1.0 / x345;
        let x347 = x344 * x346;
        let x348 = x336 - 1.0;
        let x359 = x337 * x346;
        let x360 = x339 * x346;
        let x361 = x341 * x346;
        let x366 = -x116;
        let x367 = x366.atan2(x87);
        let x368 = 2.0 * x201;
        let x369 = q[13] * qd[11];
        let x370 = q[11] * qd[13];
        let x371 = x369 + x370;
        let x372 = 2.0 * x371;
        let x373 = q[12] * qd[10];
        let x374 = q[10] * qd[12];
        let x375 = x373 + x374;
        let x376 = 2.0 * x375;
        let x378 = x372 - x376;
        let x380 = x87 * x87;
        let x381 = x116 * x116;
        let x382 = x380 + x381;
        let x383 = x87 * x378;
        let x385 = x116 * x368;
        let x387 = x385 - x383;
        let x388 = 1.0 / x382;
        let x389 = x387 * x388;
        let x400 = 2.0 * x142;
        let x401 = x87 * x144;
        let x402 = x116 * x400;
        let x404 = x401 + x402;
        let x405 = x388 * x404;
        let x406 = 2.0 * x143;
        let x407 = x87 * x145;
        let x409 = x116 * x406;
        let x411 = x409 - x407;
        let x412 = x388 * x411;
        let x413 = x87 * x142;
        let x414 = x388 * x413;
        let x415 = x87 * x143;
        let x417 = x388 * x415;
        let x502 = 2.0 * qd[0];
        let x505 = 2.0 * qd[1];
        let x507 = 2.0 * qd[2];
        let x961 = x143 * x406;
        let x981 = x143 * x400;
        let x997 = x144 * x400;
        let x999 = x145 * x406;
        let x1013 = x144 * x406;
        let x1015 = x145 * x400;
        let x1023 = x142 * x406;
        let x1036 = x142 * x400;
        let x1298 = 2.0 * x359;
        let x1299 = x346 * x346;
        let x1300 = x1298 * x1299;
        let x1302 = x346 * x502;
        let x1303 = x344 * x1300;
        let x1305 = x1302 - x1303;
        let x1312 = 2.0 * x346;
        let x1313 = x337 * x1300;
        let x1315 = x1312 - x1313;
        let x1316 = x339 * x1300;
        let x1318 = x341 * x1300;
        let x1336 = 2.0 * x360;
        let x1337 = x1299 * x1336;
        let x1339 = x346 * x505;
        let x1340 = x344 * x1337;
        let x1342 = x1339 - x1340;
        let x1349 = x337 * x1337;
        let x1351 = x339 * x1337;
        let x1353 = x1312 - x1351;
        let x1354 = x341 * x1337;
        let x1372 = 2.0 * x361;
        let x1373 = x1299 * x1372;
        let x1375 = x346 * x507;
        let x1376 = x344 * x1373;
        let x1378 = x1375 - x1376;
        let x1385 = x337 * x1373;
        let x1387 = x339 * x1373;
        let x1389 = x341 * x1373;
        let x1391 = x1312 - x1389;
        let x1408 = 2.0 * x233;
        let x1409 = 2.0 * x87;
        let x1410 = x400 * x1409;
        let x1411 = 2.0 * x116;
        let x1412 = x144 * x1411;
        let x1414 = x1410 - x1412;
        let x1415 = x378 * x400;
        let x1416 = x87 * x235;
        let x1418 = x1415 - x1416;
        let x1420 = x144 * x368;
        let x1422 = x116 * x1408;
        let x1423 = x1422 - x1420;
        let x1424 = x1423 - x1418;
        let x1425 = x388 * x388;
        let x1426 = x1414 * x1425;
        let x1428 = x388 * x1424;
        let x1429 = x387 * x1426;
        let x1431 = x1428 - x1429;
        let x1439 = 4.0 * x116;
        let x1440 = x1439 - x997;
        let x1441 = x997 + x1440;
        let x1442 = x404 * x1426;
        let x1444 = x388 * x1441;
        let x1445 = x1444 - x1442;
        let x1447 = x1013 + x1015;
        let x1449 = x411 * x1426;
        let x1451 = x388 * x1447;
        let x1453 = x1449 + x1451;
        let x1455 = x1036 + x1409;
        let x1456 = x413 * x1426;
        let x1458 = x388 * x1455;
        let x1459 = x1458 - x1456;
        let x1460 = x415 * x1426;
        let x1462 = x388 * x981;
        let x1463 = x1462 - x1460;
        let x1485 = 2.0 * x234;
        let x1486 = x406 * x1409;
        let x1487 = x145 * x1411;
        let x1488 = x1486 + x1487;
        let x1489 = x378 * x406;
        let x1490 = x87 * x236;
        let x1491 = x1489 + x1490;
        let x1493 = x145 * x368;
        let x1494 = x116 * x1485;
        let x1495 = x1493 + x1494;
        let x1496 = x1495 - x1491;
        let x1497 = x1425 * x1488;
        let x1499 = x388 * x1496;
        let x1500 = x387 * x1497;
        let x1502 = x1499 - x1500;
        let x1509 = x404 * x1497;
        let x1511 = x1451 - x1509;
        let x1512 = x999 + x1439;
        let x1513 = x1512 - x999;
        let x1514 = x411 * x1497;
        let x1516 = x388 * x1513;
        let x1517 = x1516 - x1514;
        let x1518 = x413 * x1497;
        let x1520 = x388 * x1023;
        let x1521 = x1520 - x1518;
        let x1522 = x961 + x1409;
        let x1523 = x415 * x1497;
        let x1525 = x388 * x1522;
        let x1526 = x1525 - x1523;
        let x1545 = x142 * x1411;
        let x1547 = x87 * x233;
        let x1549 = x142 * x368;
        let x1551 = x1547 - x1549;
        let x1552 = x1425 * x1545;
        let x1554 = x388 * x1551;
        let x1555 = x387 * x1552;
        let x1556 = x1554 + x1555;
        let x1564 = x1409 - x1036;
        let x1565 = x404 * x1552;
        let x1566 = x388 * x1564;
        let x1567 = x1565 + x1566;
        let x1568 = x411 * x1552;
        let x1570 = x1568 - x1520;
        let x1571 = x413 * x1552;
        let x1572 = x415 * x1552;
        let x1592 = x143 * x1411;
        let x1593 = x87 * x234;
        let x1595 = x143 * x368;
        let x1596 = x1595 - x1593;
        let x1597 = x1425 * x1592;
        let x1599 = x388 * x1596;
        let x1600 = x387 * x1597;
        let x1602 = x1599 - x1600;
        let x1608 = x404 * x1597;
        let x1610 = x1462 - x1608;
        let x1612 = x961 - x1409;
        let x1613 = x411 * x1597;
        let x1615 = x388 * x1612;
        let x1616 = x1615 - x1613;
        let x1617 = x413 * x1597;
        let x1619 = x415 * x1597;
        let x1702 = t * k[1];
        let x1703 = x1702.sin();
        let x1704 = k[0] * x1703;
        let x1708 = t * k[4];
        let x1709 = x1708.cos();
        let x1710 = k[3] * x1709;
        let x1712 = x13 * k[5];
        let x1721 = x348 * k[9];
        let x1722 = x347 * k[6];
        let x1724 = x1704 - x1722;
        let x1726 = x1724 - x1721;
        let x1734 = x367 * k[10];
        let x1735 = x389 * k[7];
        let x1737 = x1710 - x1735;
        let x1739 = x1737 - x1734;
        let x1930 = x359 * k[9];
        let x1931 = x1305 * k[6];
        let x1932 = x1930 + x1931;
        let x1933 = x359 * x1932;
        let x1935 = x1315 * x1726;
        let x1936 = x1935 - x1933;
        let x1937 = x360 * x1932;
        let x1938 = x1316 * x1726;
        let x1939 = x1937 + x1938;
        let x1940 = -x1939;
        let x1941 = x361 * x1932;
        let x1942 = x1318 * x1726;
        let x1943 = x1941 + x1942;
        let x1944 = -x1943;
        let x1945 = x360 * k[9];
        let x1946 = x1342 * k[6];
        let x1947 = x1945 + x1946;
        let x1948 = x359 * x1947;
        let x1949 = x1349 * x1726;
        let x1950 = x1948 + x1949;
        let x1951 = -x1950;
        let x1952 = x360 * x1947;
        let x1954 = x1353 * x1726;
        let x1955 = x1954 - x1952;
        let x1956 = x361 * x1947;
        let x1957 = x1354 * x1726;
        let x1958 = x1956 + x1957;
        let x1959 = -x1958;
        let x1960 = x361 * k[9];
        let x1961 = x1378 * k[6];
        let x1962 = x1960 + x1961;
        let x1963 = x359 * x1962;
        let x1964 = x1385 * x1726;
        let x1965 = x1963 + x1964;
        let x1966 = -x1965;
        let x1967 = x360 * x1962;
        let x1968 = x1387 * x1726;
        let x1969 = x1967 + x1968;
        let x1970 = -x1969;
        let x1971 = x361 * x1962;
        let x1973 = x1391 * x1726;
        let x1974 = x1973 - x1971;
        let x1975 = x405 * k[10];
        let x1976 = x1431 * k[7];
        let x1977 = x1975 + x1976;
        let x1978 = x405 * x1977;
        let x1980 = x1445 * x1739;
        let x1981 = x1980 - x1978;
        let x1982 = x412 * x1977;
        let x1983 = x1453 * x1739;
        let x1984 = x1982 + x1983;
        let x1985 = -x1984;
        let x1986 = x414 * x1977;
        let x1988 = x1459 * x1739;
        let x1989 = x1988 - x1986;
        let x1990 = x417 * x1977;
        let x1992 = x1463 * x1739;
        let x1993 = x1992 - x1990;
        let x1994 = 2.0 * x1712;
        let x1995 = x1989 + x1994;
        let x1996 = -x1993;
        let x1997 = x412 * k[10];
        let x1998 = x1502 * k[7];
        let x1999 = x1997 + x1998;
        let x2000 = x405 * x1999;
        let x2002 = x1511 * x1739;
        let x2003 = x2002 - x2000;
        let x2004 = x412 * x1999;
        let x2006 = x1517 * x1739;
        let x2007 = x2006 - x2004;
        let x2008 = x414 * x1999;
        let x2010 = x1521 * x1739;
        let x2011 = x2010 - x2008;
        let x2012 = x417 * x1999;
        let x2014 = x1526 * x1739;
        let x2015 = x2014 - x2012;
        let x2016 = x1994 + x2015;
        let x2017 = -x2016;
        let x2018 = x414 * k[10];
        let x2019 = x1556 * k[7];
        let x2020 = x2018 + x2019;
        let x2021 = x405 * x2020;
        let x2023 = x1567 * x1739;
        let x2024 = x2023 - x2021;
        let x2025 = x412 * x2020;
        let x2027 = x1570 * x1739;
        let x2028 = x2027 - x2025;
        let x2029 = x414 * x2020;
        let x2031 = x1571 * x1739;
        let x2032 = x2031 - x2029;
        let x2033 = x417 * x2020;
        let x2035 = x1572 * x1739;
        let x2036 = x2035 - x2033;
        let x2038 = x2024 - x1994;
        let x2039 = -x2036;
        let x2040 = x417 * k[10];
        let x2041 = x1602 * k[7];
        let x2043 = x2040 - x2041;
        let x2044 = x405 * x2043;
        let x2045 = x1610 * x1739;
        let x2046 = x2044 + x2045;
        let x2047 = x412 * x2043;
        let x2048 = x1616 * x1739;
        let x2049 = x2047 + x2048;
        let x2050 = x414 * x2043;
        let x2051 = x1617 * x1739;
        let x2053 = x2050 - x2051;
        let x2054 = x417 * x2043;
        let x2055 = x1619 * x1739;
        let x2057 = x2054 - x2055;
        let x2058 = x1994 + x2049;
        let x2059 = -x2057;
        let x2060 = x359 * k[6];
        let x2061 = x359 * x2060;
        let x2062 = -x2061;
        let x2063 = x360 * x2060;
        let x2064 = -x2063;
        let x2065 = x361 * x2060;
        let x2066 = -x2065;
        let x2067 = x360 * k[6];
        let x2068 = x359 * x2067;
        let x2069 = -x2068;
        let x2070 = x360 * x2067;
        let x2071 = -x2070;
        let x2072 = x361 * x2067;
        let x2073 = -x2072;
        let x2074 = x361 * k[6];
        let x2075 = x359 * x2074;
        let x2076 = -x2075;
        let x2077 = x360 * x2074;
        let x2078 = -x2077;
        let x2079 = x361 * x2074;
        let x2080 = -x2079;
        let x2081 = x405 * k[7];
        let x2082 = x405 * x2081;
        let x2083 = -x2082;
        let x2084 = x412 * x2081;
        let x2085 = -x2084;
        let x2086 = x414 * x2081;
        let x2087 = -x2086;
        let x2088 = x417 * x2081;
        let x2089 = x412 * k[7];
        let x2090 = x405 * x2089;
        let x2091 = -x2090;
        let x2092 = x412 * x2089;
        let x2093 = -x2092;
        let x2094 = x414 * x2089;
        let x2095 = -x2094;
        let x2096 = x417 * x2089;
        let x2097 = x414 * k[7];
        let x2098 = x405 * x2097;
        let x2099 = -x2098;
        let x2100 = x412 * x2097;
        let x2101 = -x2100;
        let x2102 = x414 * x2097;
        let x2103 = -x2102;
        let x2104 = x417 * x2097;
        let x2105 = x417 * k[7];
        let x2106 = x405 * x2105;
        let x2107 = x412 * x2105;
        let x2108 = x414 * x2105;
        let x2109 = x417 * x2105;
        let x2110 = -x2109;
        dq[0] = x1936;
        dq[1] = x1951;
        dq[2] = x1966;
        dq[3] = x1940;
        dq[4] = x1955;
        dq[5] = x1970;
        dq[6] = x1944;
        dq[7] = x1959;
        dq[8] = x1974;
        dq[9] = x1981;
        dq[10] = x2003;
        dq[11] = x2038;
        dq[12] = x2046;
        dq[13] = x1985;
        dq[14] = x2007;
        dq[15] = x2028;
        dq[16] = x2058;
        dq[17] = x1995;
        dq[18] = x2011;
        dq[19] = x2032;
        dq[20] = x2053;
        dq[21] = x1996;
        dq[22] = x2017;
        dq[23] = x2039;
        dq[24] = x2059;
        dqd[0] = x2062;
        dqd[1] = x2069;
        dqd[2] = x2076;
        dqd[3] = x2064;
        dqd[4] = x2071;
        dqd[5] = x2078;
        dqd[6] = x2066;
        dqd[7] = x2073;
        dqd[8] = x2080;
        dqd[9] = x2083;
        dqd[10] = x2091;
        dqd[11] = x2099;
        dqd[12] = x2106;
        dqd[13] = x2085;
        dqd[14] = x2093;
        dqd[15] = x2101;
        dqd[16] = x2107;
        dqd[17] = x2087;
        dqd[18] = x2095;
        dqd[19] = x2103;
        dqd[20] = x2108;
        dqd[21] = x2088;
        dqd[22] = x2096;
        dqd[23] = x2104;
        dqd[24] = x2110;
    }
    /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
    pub fn mass(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
        let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 38] = out.try_into().expect("out must have 38 entries");
        mass_part_0(k, q, out);
    }
    #[inline(never)]
    fn mass_part_0(k: &[f64; 17], q: &[f64; 14], out: &mut [f64; 38]) {
        let x36 = q[3] * q[3];
        let x37 = q[4] * q[4];
        let x38 = q[5] * q[5];
        let x39 = q[6] * q[6];
        let x50 = q[4] * q[5];
        let x52 = q[3] * q[6];
        let x57 = q[4] * q[6];
        let x59 = q[3] * q[5];
        let x63 = q[5] * q[6];
        let x65 = q[3] * q[4];
        let x81 = q[10] * q[10];
        let x82 = q[11] * q[11];
        let x83 = q[12] * q[12];
        let x84 = q[13] * q[13];
        let x94 = q[11] * q[12];
        let x96 = q[10] * q[13];
        let x101 = q[11] * q[13];
        let x103 = q[10] * q[12];
        let x107 = q[12] * q[13];
        let x109 = q[10] * q[11];
        let x136 = q[3] * 2.0;
        let x137 = q[4] * 2.0;
        let x138 = q[5] * 2.0;
        let x139 = q[6] * 2.0;
        let x142 = 2.0 * q[10];
        let x143 = 2.0 * q[11];
        let x144 = 2.0 * q[12];
        let x145 = 2.0 * q[13];
        let x400 = 2.0 * x142;
        let x406 = 2.0 * x143;
        let x576 = 2.0 * x137;
        let x578 = 2.0 * x138;
        let x580 = 2.0 * x139;
        let x582 = x137 * x576;
        let x584 = 0.01 * x582;
        let x586 = x138 * x578;
        let x588 = 0.01 * x586;
        let x590 = x139 * x580;
        let x592 = 0.01 * x590;
        let x594 = x584 + x588;
        let x596 = x592 + x594;
        let x598 = 0.5 * x596;
        let x600 = x36 * 0.04;
        let x601 = x598 + x600;
        let x602 = 2.0 * x136;
        let x603 = x137 * x602;
        let x604 = 0.01 * x603;
        let x605 = x138 * x580;
        let x607 = 0.01 * x605;
        let x609 = x139 * x578;
        let x610 = 0.01 * x609;
        let x611 = x604 - x607;
        let x612 = x610 + x611;
        let x613 = 0.5 * x612;
        let x615 = x65 * 0.04;
        let x616 = x615 - x613;
        let x617 = x137 * x580;
        let x618 = 0.01 * x617;
        let x619 = x138 * x602;
        let x620 = 0.01 * x619;
        let x621 = x139 * x576;
        let x623 = 0.01 * x621;
        let x625 = x618 + x620;
        let x626 = x625 - x623;
        let x627 = 0.5 * x626;
        let x629 = x59 * 0.04;
        let x630 = x629 - x627;
        let x631 = x137 * x578;
        let x633 = 0.01 * x631;
        let x635 = x138 * x576;
        let x636 = 0.01 * x635;
        let x637 = x139 * x602;
        let x638 = 0.01 * x637;
        let x639 = x636 - x633;
        let x640 = x638 + x639;
        let x641 = 0.5 * x640;
        let x643 = x52 * 0.04;
        let x644 = x643 - x641;
        let x645 = x136 * x576;
        let x647 = 0.01 * x645;
        let x651 = x610 - x647;
        let x652 = x651 - x607;
        let x653 = 0.5 * x652;
        let x654 = x615 + x653;
        let x655 = x136 * x602;
        let x656 = 0.01 * x655;
        let x657 = x592 + x656;
        let x658 = x588 + x657;
        let x659 = 0.5 * x658;
        let x660 = x37 * 0.04;
        let x661 = x659 + x660;
        let x662 = x136 * x580;
        let x663 = 0.01 * x662;
        let x667 = x663 - x638;
        let x668 = x667 - x636;
        let x669 = 0.5 * x668;
        let x670 = x50 * 0.04;
        let x671 = x669 + x670;
        let x672 = x136 * x578;
        let x674 = 0.01 * x672;
        let x676 = x623 + x674;
        let x678 = x620 - x676;
        let x679 = 0.5 * x678;
        let x680 = x57 * 0.04;
        let x681 = x679 + x680;
        let x684 = x618 - x676;
        let x685 = 0.5 * x684;
        let x686 = x629 + x685;
        let x689 = x638 - x663;
        let x690 = x689 - x633;
        let x691 = 0.5 * x690;
        let x692 = x670 + x691;
        let x693 = x584 + x657;
        let x694 = 0.5 * x693;
        let x695 = x38 * 0.04;
        let x696 = x694 + x695;
        let x698 = x647 - x610;
        let x699 = x698 - x604;
        let x700 = 0.5 * x699;
        let x701 = x63 * 0.04;
        let x702 = x700 + x701;
        let x703 = x639 - x663;
        let x704 = 0.5 * x703;
        let x705 = x643 + x704;
        let x708 = x674 - x625;
        let x709 = 0.5 * x708;
        let x710 = x680 + x709;
        let x711 = x611 - x647;
        let x712 = 0.5 * x711;
        let x713 = x701 + x712;
        let x714 = x594 + x656;
        let x715 = 0.5 * x714;
        let x716 = x39 * 0.04;
        let x717 = x715 + x716;
        let x957 = 2.0 * x144;
        let x959 = 2.0 * x145;
        let x961 = x143 * x406;
        let x963 = 0.1 * x961;
        let x965 = x144 * x957;
        let x969 = x145 * x959;
        let x971 = 0.3 * x969;
        let x981 = x143 * x400;
        let x982 = 0.1 * x981;
        let x983 = x144 * x959;
        let x987 = x145 * x957;
        let x988 = 0.3 * x987;
        let x995 = x143 * x959;
        let x996 = 0.1 * x995;
        let x997 = x144 * x400;
        let x999 = x145 * x406;
        let x1001 = 0.3 * x999;
        let x1009 = x143 * x957;
        let x1011 = 0.1 * x1009;
        let x1013 = x144 * x406;
        let x1015 = x145 * x400;
        let x1016 = 0.3 * x1015;
        let x1023 = x142 * x406;
        let x1025 = 0.1 * x1023;
        let x1030 = 0.3 * x983;
        let x1036 = x142 * x400;
        let x1037 = 0.1 * x1036;
        let x1040 = 0.3 * x965;
        let x1046 = x142 * x959;
        let x1047 = 0.1 * x1046;
        let x1051 = 0.3 * x1013;
        let x1058 = x142 * x957;
        let x1060 = 0.1 * x1058;
        let x1064 = 0.3 * x997;
        let x1071 = 0.1 * x999;
        let x1076 = 0.3 * x995;
        let x1083 = 0.1 * x1015;
        let x1087 = 0.3 * x1009;
        let x1093 = 0.1 * x969;
        let x1095 = 0.3 * x961;
        let x1102 = 0.1 * x987;
        let x1105 = 0.3 * x981;
        let x1112 = 0.1 * x1013;
        let x1116 = 0.3 * x1046;
        let x1122 = 0.1 * x997;
        let x1126 = 0.3 * x1058;
        let x1132 = 0.1 * x983;
        let x1135 = 0.3 * x1023;
        let x1141 = 0.1 * x965;
        let x1144 = 0.3 * x1036;
        let x1768 = x965 * k[8];
        let x1769 = x963 + x1768;
        let x1770 = x971 + x1769;
        let x1771 = 0.5 * x1770;
        let x1772 = x81 * k[16];
        let x1773 = x1771 + x1772;
        let x1774 = x983 * k[8];
        let x1776 = x982 - x1774;
        let x1777 = x988 + x1776;
        let x1778 = 0.5 * x1777;
        let x1780 = x109 * k[16];
        let x1781 = x1780 - x1778;
        let x1782 = x997 * k[8];
        let x1783 = x996 + x1782;
        let x1784 = x1783 - x1001;
        let x1785 = 0.5 * x1784;
        let x1787 = x103 * k[16];
        let x1788 = x1787 - x1785;
        let x1789 = x1013 * k[8];
        let x1790 = x1789 - x1011;
        let x1791 = x1016 + x1790;
        let x1792 = 0.5 * x1791;
        let x1794 = x96 * k[16];
        let x1795 = x1794 - x1792;
        let x1796 = x987 * k[8];
        let x1797 = x1796 - x1025;
        let x1798 = x1797 - x1030;
        let x1799 = 0.5 * x1798;
        let x1800 = x1780 + x1799;
        let x1801 = x969 * k[8];
        let x1802 = x1037 + x1801;
        let x1803 = x1040 + x1802;
        let x1804 = 0.5 * x1803;
        let x1805 = x82 * k[16];
        let x1806 = x1804 + x1805;
        let x1807 = x1015 * k[8];
        let x1809 = x1047 - x1807;
        let x1810 = x1809 - x1051;
        let x1811 = 0.5 * x1810;
        let x1812 = x94 * k[16];
        let x1813 = x1811 + x1812;
        let x1814 = x999 * k[8];
        let x1815 = x1060 + x1814;
        let x1817 = x1064 - x1815;
        let x1818 = 0.5 * x1817;
        let x1819 = x101 * k[16];
        let x1820 = x1818 + x1819;
        let x1821 = x1058 * k[8];
        let x1822 = x1071 + x1821;
        let x1824 = x1076 - x1822;
        let x1825 = 0.5 * x1824;
        let x1826 = x1787 + x1825;
        let x1827 = x1046 * k[8];
        let x1829 = x1083 - x1827;
        let x1830 = x1829 - x1087;
        let x1831 = 0.5 * x1830;
        let x1832 = x1812 + x1831;
        let x1833 = x1036 * k[8];
        let x1834 = x1093 + x1833;
        let x1835 = x1095 + x1834;
        let x1836 = 0.5 * x1835;
        let x1837 = x83 * k[16];
        let x1838 = x1836 + x1837;
        let x1839 = x1023 * k[8];
        let x1840 = x1839 - x1102;
        let x1841 = x1840 - x1105;
        let x1842 = 0.5 * x1841;
        let x1843 = x107 * k[16];
        let x1844 = x1842 + x1843;
        let x1845 = x1009 * k[8];
        let x1847 = x1112 - x1845;
        let x1848 = x1847 - x1116;
        let x1849 = 0.5 * x1848;
        let x1850 = x1794 + x1849;
        let x1851 = x995 * k[8];
        let x1852 = x1122 + x1851;
        let x1854 = x1126 - x1852;
        let x1855 = 0.5 * x1854;
        let x1856 = x1819 + x1855;
        let x1857 = x981 * k[8];
        let x1858 = x1857 - x1132;
        let x1859 = x1858 - x1135;
        let x1860 = 0.5 * x1859;
        let x1861 = x1843 + x1860;
        let x1862 = x961 * k[8];
        let x1863 = x1141 + x1862;
        let x1864 = x1144 + x1863;
        let x1865 = 0.5 * x1864;
        let x1866 = x84 * k[16];
        let x1867 = x1865 + x1866;
        out[0] = k[15];
        out[1] = k[15];
        out[2] = k[15];
        out[3] = x601;
        out[4] = x616;
        out[5] = x630;
        out[6] = x644;
        out[7] = x654;
        out[8] = x661;
        out[9] = x671;
        out[10] = x681;
        out[11] = x686;
        out[12] = x692;
        out[13] = x696;
        out[14] = x702;
        out[15] = x705;
        out[16] = x710;
        out[17] = x713;
        out[18] = x717;
        out[19] = 1.0;
        out[20] = 1.0;
        out[21] = 1.0;
        out[22] = x1773;
        out[23] = x1781;
        out[24] = x1788;
        out[25] = x1795;
        out[26] = x1800;
        out[27] = x1806;
        out[28] = x1813;
        out[29] = x1820;
        out[30] = x1826;
        out[31] = x1832;
        out[32] = x1838;
        out[33] = x1844;
        out[34] = x1850;
        out[35] = x1856;
        out[36] = x1861;
        out[37] = x1867;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
        let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 14] = out.try_into().expect("out must have 14 entries");
        force_part_0(k, q, qd, t, out);
    }
    #[inline(never)]
    fn force_part_0(
        k: &[f64; 17],
        q: &[f64; 14],
        qd: &[f64; 14],
        t: f64,
        out: &mut [f64; 14],
    ) {
        let x13 = t.sin();
        let x81 = q[10] * q[10];
        let x82 = q[11] * q[11];
        let x85 = x81 + x82;
        let x86 = 2.0 * x85;
        let x87 = x86 - 1.0;
        let x101 = q[11] * q[13];
        let x102 = 2.0 * x101;
        let x103 = q[10] * q[12];
        let x104 = 2.0 * x103;
        let x116 = x102 - x104;
        let x136 = q[3] * 2.0;
        let x137 = q[4] * 2.0;
        let x138 = q[5] * 2.0;
        let x139 = q[6] * 2.0;
        let x142 = 2.0 * q[10];
        let x143 = 2.0 * q[11];
        let x144 = 2.0 * q[12];
        let x145 = 2.0 * q[13];
        let x169 = q[5] * qd[4];
        let x170 = q[4] * qd[5];
        let x173 = q[6] * qd[3];
        let x174 = q[3] * qd[6];
        let x177 = q[6] * qd[4];
        let x178 = q[4] * qd[6];
        let x181 = q[5] * qd[3];
        let x182 = q[3] * qd[5];
        let x186 = q[6] * qd[5];
        let x187 = q[5] * qd[6];
        let x190 = q[4] * qd[3];
        let x191 = q[3] * qd[4];
        let x197 = x142 * qd[10];
        let x198 = x143 * qd[11];
        let x201 = x197 + x198;
        let x202 = q[12] * qd[11];
        let x203 = q[11] * qd[12];
        let x206 = q[13] * qd[10];
        let x207 = q[10] * qd[13];
        let x212 = q[13] * qd[12];
        let x213 = q[12] * qd[13];
        let x216 = q[11] * qd[10];
        let x217 = q[10] * qd[11];
        let x229 = 2.0 * qd[3];
        let x230 = 2.0 * qd[4];
        let x231 = 2.0 * qd[5];
        let x232 = 2.0 * qd[6];
        let x233 = 2.0 * qd[10];
        let x234 = 2.0 * qd[11];
        let x235 = 2.0 * qd[12];
        let x236 = 2.0 * qd[13];
        let x242 = qd[4] * qd[5];
        let x245 = qd[3] * qd[6];
        let x248 = qd[4] * qd[6];
        let x251 = qd[3] * qd[5];
        let x269 = qd[11] * qd[12];
        let x272 = qd[10] * qd[13];
        let x330 = 1.0 + q[0];
        let x331 = x330 * x330;
        let x332 = q[1] * q[1];
        let x333 = q[2] * q[2];
        let x334 = x331 + x332;
        let x335 = x333 + x334;
        let x336 = x335.sqrt();
        let x337 = 2.0 * x330;
        let x338 = qd[0] * x337;
        let x339 = q[1] * 2.0;
        let x340 = qd[1] * x339;
        let x341 = q[2] * 2.0;
        let x342 = qd[2] * x341;
        let x343 = x338 + x340;
        let x344 = x342 + x343;
        let x345 = 2.0 * x336;
        let x346 = 1.0 / x345;
        let x347 = x344 * x346;
        let x348 = x336 - 1.0;
        let x359 = x337 * x346;
        let x360 = x339 * x346;
        let x361 = x341 * x346;
        let x366 = -x116;
        let x367 = x366.atan2(x87);
        let x368 = 2.0 * x201;
        let x369 = q[13] * qd[11];
        let x370 = q[11] * qd[13];
        let x371 = x369 + x370;
        let x372 = 2.0 * x371;
        let x373 = q[12] * qd[10];
        let x374 = q[10] * qd[12];
        let x375 = x373 + x374;
        let x376 = 2.0 * x375;
        let x378 = x372 - x376;
        let x380 = x87 * x87;
        let x381 = x116 * x116;
        let x382 = x380 + x381;
        let x383 = x87 * x378;
        let x385 = x116 * x368;
        let x387 = x385 - x383;
        let x388 = 1.0 / x382;
        let x389 = x387 * x388;
        let x400 = 2.0 * x142;
        let x401 = x87 * x144;
        let x402 = x116 * x400;
        let x404 = x401 + x402;
        let x405 = x388 * x404;
        let x406 = 2.0 * x143;
        let x407 = x87 * x145;
        let x409 = x116 * x406;
        let x411 = x409 - x407;
        let x412 = x388 * x411;
        let x413 = x87 * x142;
        let x414 = x388 * x413;
        let x415 = x87 * x143;
        let x417 = x388 * x415;
        let x426 = x217 - x216;
        let x467 = x191 - x190;
        let x468 = x186 + x467;
        let x469 = x468 - x187;
        let x470 = 2.0 * x469;
        let x473 = x177 + x181;
        let x475 = x182 - x473;
        let x476 = x178 + x475;
        let x477 = 2.0 * x476;
        let x480 = x169 - x173;
        let x481 = x480 - x170;
        let x482 = x174 + x481;
        let x483 = 2.0 * x482;
        let x504 = 2.0 * x470;
        let x506 = 2.0 * x477;
        let x508 = 2.0 * x483;
        let x720 = x248 + x251;
        let x722 = x251 - x720;
        let x723 = x248 + x722;
        let x724 = 2.0 * x723;
        let x727 = x242 - x245;
        let x728 = x727 - x242;
        let x729 = x245 + x728;
        let x730 = 2.0 * x729;
        let x731 = 2.0 * x724;
        let x732 = 2.0 * x730;
        let x733 = x230 * x504;
        let x734 = 0.01 * x733;
        let x735 = x231 * x506;
        let x736 = x138 * x731;
        let x737 = x735 + x736;
        let x738 = 0.01 * x737;
        let x739 = x232 * x508;
        let x740 = x139 * x732;
        let x741 = x739 + x740;
        let x742 = 0.01 * x741;
        let x743 = x734 + x738;
        let x744 = x742 + x743;
        let x745 = 0.5 * x744;
        let x747 = x229 * x504;
        let x748 = 0.01 * x747;
        let x749 = x232 * x506;
        let x750 = x139 * x731;
        let x751 = x749 + x750;
        let x752 = 0.01 * x751;
        let x754 = x231 * x508;
        let x755 = x138 * x732;
        let x756 = x754 + x755;
        let x757 = 0.01 * x756;
        let x758 = x748 - x752;
        let x759 = x757 + x758;
        let x760 = 0.5 * x759;
        let x761 = x232 * x504;
        let x762 = 0.01 * x761;
        let x763 = x229 * x506;
        let x764 = x136 * x731;
        let x765 = x763 + x764;
        let x766 = 0.01 * x765;
        let x767 = x230 * x508;
        let x768 = x137 * x732;
        let x769 = x767 + x768;
        let x770 = 0.01 * x769;
        let x772 = x762 + x766;
        let x773 = x772 - x770;
        let x774 = 0.5 * x773;
        let x775 = x231 * x504;
        let x776 = 0.01 * x775;
        let x778 = x230 * x506;
        let x779 = x137 * x731;
        let x780 = x778 + x779;
        let x781 = 0.01 * x780;
        let x782 = x229 * x508;
        let x783 = x136 * x732;
        let x784 = x782 + x783;
        let x785 = 0.01 * x784;
        let x786 = x781 - x776;
        let x787 = x785 + x786;
        let x788 = 0.5 * x787;
        let x789 = qd[3] * qd[3];
        let x790 = qd[4] * qd[4];
        let x791 = qd[5] * qd[5];
        let x792 = qd[6] * qd[6];
        let x793 = x789 + x790;
        let x794 = x791 + x793;
        let x795 = x792 + x794;
        let x796 = 0.01 * x735;
        let x797 = 0.01 * x739;
        let x798 = x734 + x796;
        let x799 = x797 + x798;
        let x800 = 0.5 * x799;
        let x801 = x745 + x800;
        let x802 = q[3] * 0.04;
        let x803 = x795 * x802;
        let x805 = x801 - x803;
        let x812 = 0.01 * x749;
        let x814 = 0.01 * x754;
        let x816 = x812 - x748;
        let x817 = x816 - x814;
        let x818 = 0.5 * x817;
        let x820 = x818 - x760;
        let x821 = q[4] * 0.04;
        let x822 = x795 * x821;
        let x824 = x820 - x822;
        let x830 = 0.01 * x763;
        let x832 = 0.01 * x767;
        let x833 = x762 + x830;
        let x835 = x832 - x833;
        let x836 = 0.5 * x835;
        let x838 = x836 - x774;
        let x839 = q[5] * 0.04;
        let x840 = x795 * x839;
        let x842 = x838 - x840;
        let x846 = 0.01 * x778;
        let x849 = 0.01 * x782;
        let x851 = x776 - x846;
        let x852 = x851 - x849;
        let x853 = 0.5 * x852;
        let x855 = x853 - x788;
        let x856 = q[6] * 0.04;
        let x857 = x795 * x856;
        let x859 = x855 - x857;
        let x862 = x212 + x426;
        let x863 = x862 - x213;
        let x864 = 2.0 * x863;
        let x866 = x369 + x373;
        let x868 = x374 - x866;
        let x869 = x370 + x868;
        let x870 = 2.0 * x869;
        let x872 = x202 - x206;
        let x873 = x872 - x203;
        let x874 = x207 + x873;
        let x875 = 2.0 * x874;
        let x892 = 2.0 * x864;
        let x894 = 2.0 * x870;
        let x896 = 2.0 * x875;
        let x1150 = qd[11] * qd[13];
        let x1151 = qd[10] * qd[12];
        let x1155 = x1150 + x1151;
        let x1157 = x1151 - x1155;
        let x1158 = x1150 + x1157;
        let x1159 = 2.0 * x1158;
        let x1161 = x269 - x272;
        let x1162 = x1161 - x269;
        let x1163 = x272 + x1162;
        let x1164 = 2.0 * x1163;
        let x1165 = 2.0 * x1159;
        let x1166 = 2.0 * x1164;
        let x1167 = x234 * x892;
        let x1168 = 0.1 * x1167;
        let x1169 = x235 * x894;
        let x1170 = x144 * x1165;
        let x1171 = x1169 + x1170;
        let x1173 = x236 * x896;
        let x1174 = x145 * x1166;
        let x1175 = x1173 + x1174;
        let x1176 = 0.3 * x1175;
        let x1181 = x233 * x892;
        let x1182 = 0.1 * x1181;
        let x1183 = x236 * x894;
        let x1184 = x145 * x1165;
        let x1185 = x1183 + x1184;
        let x1188 = x235 * x896;
        let x1189 = x144 * x1166;
        let x1190 = x1188 + x1189;
        let x1191 = 0.3 * x1190;
        let x1195 = x236 * x892;
        let x1196 = 0.1 * x1195;
        let x1197 = x233 * x894;
        let x1198 = x142 * x1165;
        let x1199 = x1197 + x1198;
        let x1201 = x234 * x896;
        let x1202 = x143 * x1166;
        let x1203 = x1201 + x1202;
        let x1204 = 0.3 * x1203;
        let x1209 = x235 * x892;
        let x1210 = 0.1 * x1209;
        let x1212 = x234 * x894;
        let x1213 = x143 * x1165;
        let x1214 = x1212 + x1213;
        let x1216 = x233 * x896;
        let x1217 = x142 * x1166;
        let x1218 = x1216 + x1217;
        let x1219 = 0.3 * x1218;
        let x1223 = qd[10] * qd[10];
        let x1224 = qd[11] * qd[11];
        let x1225 = qd[12] * qd[12];
        let x1226 = qd[13] * qd[13];
        let x1227 = x1223 + x1224;
        let x1228 = x1225 + x1227;
        let x1229 = x1226 + x1228;
        let x1231 = 0.3 * x1173;
        let x1248 = 0.3 * x1188;
        let x1266 = 0.3 * x1201;
        let x1283 = 0.3 * x1216;
        let x1702 = t * k[1];
        let x1703 = x1702.sin();
        let x1704 = k[0] * x1703;
        let x1708 = t * k[4];
        let x1709 = x1708.cos();
        let x1710 = k[3] * x1709;
        let x1712 = x13 * k[5];
        let x1721 = x348 * k[9];
        let x1722 = x347 * k[6];
        let x1724 = x1704 - x1722;
        let x1726 = x1724 - x1721;
        let x1730 = x359 * x1726;
        let x1731 = x360 * x1726;
        let x1732 = x361 * x1726;
        let x1734 = x367 * k[10];
        let x1735 = x389 * k[7];
        let x1737 = x1710 - x1735;
        let x1739 = x1737 - x1734;
        let x1743 = x405 * x1739;
        let x1744 = x412 * x1739;
        let x1745 = x414 * x1739;
        let x1746 = x417 * x1739;
        let x1748 = x144 * x1712;
        let x1750 = x145 * x1712;
        let x1751 = x142 * x1712;
        let x1752 = x143 * x1712;
        let x1753 = k[2] + x1730;
        let x1754 = x1743 - x1748;
        let x1755 = x1744 + x1750;
        let x1756 = x1745 + x1751;
        let x1757 = x1746 + x1752;
        let x1766 = k[12] + x1731;
        let x1868 = x1171 * k[8];
        let x1869 = x1168 + x1868;
        let x1870 = x1176 + x1869;
        let x1871 = 0.5 * x1870;
        let x1872 = x1185 * k[8];
        let x1874 = x1182 - x1872;
        let x1875 = x1191 + x1874;
        let x1876 = 0.5 * x1875;
        let x1877 = x1199 * k[8];
        let x1878 = x1196 + x1877;
        let x1879 = x1878 - x1204;
        let x1880 = 0.5 * x1879;
        let x1881 = x1214 * k[8];
        let x1882 = x1881 - x1210;
        let x1883 = x1219 + x1882;
        let x1884 = 0.5 * x1883;
        let x1885 = x1169 * k[8];
        let x1886 = x1168 + x1885;
        let x1887 = x1231 + x1886;
        let x1888 = 0.5 * x1887;
        let x1889 = x1871 + x1888;
        let x1890 = q[10] * k[16];
        let x1891 = x1229 * x1890;
        let x1893 = x1889 - x1891;
        let x1894 = x1183 * k[8];
        let x1895 = x1894 - x1182;
        let x1896 = x1895 - x1248;
        let x1897 = 0.5 * x1896;
        let x1899 = x1897 - x1876;
        let x1900 = q[11] * k[16];
        let x1901 = x1229 * x1900;
        let x1903 = x1899 - x1901;
        let x1904 = x1197 * k[8];
        let x1905 = x1196 + x1904;
        let x1907 = x1266 - x1905;
        let x1908 = 0.5 * x1907;
        let x1910 = x1908 - x1880;
        let x1911 = q[12] * k[16];
        let x1912 = x1229 * x1911;
        let x1914 = x1910 - x1912;
        let x1915 = x1212 * k[8];
        let x1917 = x1210 - x1915;
        let x1918 = x1917 - x1283;
        let x1919 = 0.5 * x1918;
        let x1921 = x1919 - x1884;
        let x1922 = q[13] * k[16];
        let x1923 = x1229 * x1922;
        let x1925 = x1921 - x1923;
        let x1926 = x1754 + x1893;
        let x1927 = x1755 + x1903;
        let x1928 = x1756 + x1914;
        let x1929 = x1925 - x1757;
        out[0] = x1753;
        out[1] = x1766;
        out[2] = x1732;
        out[3] = x805;
        out[4] = x824;
        out[5] = x842;
        out[6] = x859;
        out[7] = 0.0;
        out[8] = -9.81;
        out[9] = 0.0;
        out[10] = x1926;
        out[11] = x1927;
        out[12] = x1928;
        out[13] = x1929;
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
        let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
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
        k: &[f64; 17],
        q: &[f64; 14],
        qd: &[f64; 14],
        t: f64,
        s: &mut [f64; 94],
    ) {
        let x13 = t.sin();
        s[0] = x13;
        let x81 = q[10] * q[10];
        s[1] = x81;
        let x82 = q[11] * q[11];
        s[2] = x82;
        let x85 = x81 + x82;
        s[3] = x85;
        let x86 = 2.0 * x85;
        s[4] = x86;
        let x87 = x86 - 1.0;
        s[5] = x87;
        let x101 = q[11] * q[13];
        s[6] = x101;
        let x102 = 2.0 * x101;
        s[7] = x102;
        let x103 = q[10] * q[12];
        s[8] = x103;
        let x104 = 2.0 * x103;
        s[9] = x104;
        let x116 = x102 - x104;
        s[10] = x116;
        let x142 = 2.0 * q[10];
        s[11] = x142;
        let x143 = 2.0 * q[11];
        s[12] = x143;
        let x144 = 2.0 * q[12];
        s[13] = x144;
        let x145 = 2.0 * q[13];
        s[14] = x145;
        let x197 = x142 * qd[10];
        s[15] = x197;
        let x198 = x143 * qd[11];
        s[16] = x198;
        let x201 = x197 + x198;
        s[17] = x201;
        let x202 = q[12] * qd[11];
        s[18] = x202;
        let x203 = q[11] * qd[12];
        s[19] = x203;
        let x206 = q[13] * qd[10];
        s[20] = x206;
        let x207 = q[10] * qd[13];
        s[21] = x207;
        let x212 = q[13] * qd[12];
        s[22] = x212;
        let x213 = q[12] * qd[13];
        s[23] = x213;
        let x216 = q[11] * qd[10];
        s[24] = x216;
        let x217 = q[10] * qd[11];
        s[25] = x217;
        let x234 = 2.0 * qd[11];
        s[26] = x234;
        let x235 = 2.0 * qd[12];
        s[27] = x235;
        let x236 = 2.0 * qd[13];
        s[28] = x236;
        let x269 = qd[11] * qd[12];
        s[29] = x269;
        let x272 = qd[10] * qd[13];
        s[30] = x272;
        let x366 = -x116;
        s[31] = x366;
        let x367 = x366.atan2(x87);
        s[32] = x367;
        let x368 = 2.0 * x201;
        s[33] = x368;
        let x369 = q[13] * qd[11];
        s[34] = x369;
        let x370 = q[11] * qd[13];
        s[35] = x370;
        let x371 = x369 + x370;
        s[36] = x371;
        let x372 = 2.0 * x371;
        s[37] = x372;
        let x373 = q[12] * qd[10];
        s[38] = x373;
        let x374 = q[10] * qd[12];
        s[39] = x374;
        let x375 = x373 + x374;
        s[40] = x375;
        let x376 = 2.0 * x375;
        s[41] = x376;
        let x378 = x372 - x376;
        s[42] = x378;
        let x380 = x87 * x87;
        s[43] = x380;
        let x381 = x116 * x116;
        s[44] = x381;
        let x382 = x380 + x381;
        s[45] = x382;
        let x383 = x87 * x378;
        s[46] = x383;
        let x385 = x116 * x368;
        s[47] = x385;
        let x387 = x385 - x383;
        s[48] = x387;
        let x388 = 1.0 / x382;
        s[49] = x388;
        let x389 = x387 * x388;
        s[50] = x389;
        let x406 = 2.0 * x143;
        s[51] = x406;
        let x426 = x217 - x216;
        s[52] = x426;
        let x862 = x212 + x426;
        s[53] = x862;
        let x863 = x862 - x213;
        s[54] = x863;
        let x864 = 2.0 * x863;
        s[55] = x864;
        let x866 = x369 + x373;
        s[56] = x866;
        let x868 = x374 - x866;
        s[57] = x868;
        let x869 = x370 + x868;
        s[58] = x869;
        let x870 = 2.0 * x869;
        s[59] = x870;
        let x872 = x202 - x206;
        s[60] = x872;
        let x873 = x872 - x203;
        s[61] = x873;
        let x874 = x207 + x873;
        s[62] = x874;
        let x875 = 2.0 * x874;
        s[63] = x875;
        let x892 = 2.0 * x864;
        s[64] = x892;
        let x894 = 2.0 * x870;
        s[65] = x894;
        let x896 = 2.0 * x875;
        s[66] = x896;
        let x1150 = qd[11] * qd[13];
        s[67] = x1150;
        let x1151 = qd[10] * qd[12];
        s[68] = x1151;
        let x1155 = x1150 + x1151;
        s[69] = x1155;
        let x1157 = x1151 - x1155;
        s[70] = x1157;
        let x1158 = x1150 + x1157;
        s[71] = x1158;
        let x1159 = 2.0 * x1158;
        s[72] = x1159;
        let x1161 = x269 - x272;
        s[73] = x1161;
        let x1162 = x1161 - x269;
        s[74] = x1162;
        let x1163 = x272 + x1162;
        s[75] = x1163;
        let x1164 = 2.0 * x1163;
        s[76] = x1164;
        let x1165 = 2.0 * x1159;
        s[77] = x1165;
        let x1166 = 2.0 * x1164;
        s[78] = x1166;
        let x1223 = qd[10] * qd[10];
        s[79] = x1223;
        let x1224 = qd[11] * qd[11];
        s[80] = x1224;
        let x1225 = qd[12] * qd[12];
        s[81] = x1225;
        let x1226 = qd[13] * qd[13];
        s[82] = x1226;
        let x1227 = x1223 + x1224;
        s[83] = x1227;
        let x1228 = x1225 + x1227;
        s[84] = x1228;
        let x1229 = x1226 + x1228;
        s[85] = x1229;
        let x1708 = t * k[4];
        s[86] = x1708;
        let x1709 = x1708.cos();
        s[87] = x1709;
        let x1710 = k[3] * x1709;
        s[88] = x1710;
        let x1712 = x13 * k[5];
        s[89] = x1712;
        let x1734 = x367 * k[10];
        s[90] = x1734;
        let x1735 = x389 * k[7];
        s[91] = x1735;
        let x1737 = x1710 - x1735;
        s[92] = x1737;
        let x1739 = x1737 - x1734;
        s[93] = x1739;
    }
    #[inline(never)]
    fn eval_newton_part_0(
        k: &[f64; 17],
        q: &[f64; 14],
        qd: &[f64; 14],
        t: f64,
        s: &[f64; 94],
        phi: &mut [f64; 12],
        phi_q: &mut [f64; 33],
        mass: &mut [f64; 38],
        force: &mut [f64; 14],
    ) {
        let x36 = q[3] * q[3];
        let x37 = q[4] * q[4];
        let x38 = q[5] * q[5];
        let x39 = q[6] * q[6];
        let x40 = x36 + x37;
        let x50 = q[4] * q[5];
        let x51 = 2.0 * x50;
        let x52 = q[3] * q[6];
        let x54 = 2.0 * x52;
        let x57 = q[4] * q[6];
        let x58 = 2.0 * x57;
        let x59 = q[3] * q[5];
        let x60 = 2.0 * x59;
        let x62 = x51 + x54;
        let x63 = q[5] * q[6];
        let x64 = 2.0 * x63;
        let x65 = q[3] * q[4];
        let x67 = 2.0 * x65;
        let x72 = x58 - x60;
        let x73 = x64 + x67;
        let x83 = q[12] * q[12];
        let x84 = q[13] * q[13];
        let x94 = q[11] * q[12];
        let x95 = 2.0 * x94;
        let x96 = q[10] * q[13];
        let x98 = 2.0 * x96;
        let x100 = x95 - x98;
        let x107 = q[12] * q[13];
        let x108 = 2.0 * x107;
        let x109 = q[10] * q[11];
        let x111 = 2.0 * x109;
        let x117 = x108 + x111;
        let x124 = -q[7];
        let x126 = 1.0 - q[8];
        let x128 = 2.0 - q[9];
        let x129 = -x117;
        let x130 = x38 + x40;
        let x131 = x39 + x130;
        let x132 = x131 - 1.0;
        let x133 = x83 + s[3];
        let x134 = x84 + x133;
        let x135 = x134 - 1.0;
        let x136 = q[3] * 2.0;
        let x137 = q[4] * 2.0;
        let x138 = q[5] * 2.0;
        let x139 = q[6] * 2.0;
        let x140 = -x138;
        let x141 = -x136;
        let x146 = -s[14];
        let x147 = -s[12];
        let x148 = -s[11];
        let x149 = -s[13];
        let x169 = q[5] * qd[4];
        let x170 = q[4] * qd[5];
        let x173 = q[6] * qd[3];
        let x174 = q[3] * qd[6];
        let x177 = q[6] * qd[4];
        let x178 = q[4] * qd[6];
        let x181 = q[5] * qd[3];
        let x182 = q[3] * qd[5];
        let x186 = q[6] * qd[5];
        let x187 = q[5] * qd[6];
        let x190 = q[4] * qd[3];
        let x191 = q[3] * qd[4];
        let x229 = 2.0 * qd[3];
        let x230 = 2.0 * qd[4];
        let x231 = 2.0 * qd[5];
        let x232 = 2.0 * qd[6];
        let x242 = qd[4] * qd[5];
        let x245 = qd[3] * qd[6];
        let x248 = qd[4] * qd[6];
        let x251 = qd[3] * qd[5];
        let x330 = 1.0 + q[0];
        let x331 = x330 * x330;
        let x332 = q[1] * q[1];
        let x333 = q[2] * q[2];
        let x334 = x331 + x332;
        let x335 = x333 + x334;
        let x336 = x335.sqrt();
        let x337 = 2.0 * x330;
        let x338 = qd[0] * x337;
        let x339 = q[1] * 2.0;
        let x340 = qd[1] * x339;
        let x341 = q[2] * 2.0;
        let x342 = qd[2] * x341;
        let x343 = x338 + x340;
        let x344 = x342 + x343;
        let x345 = 2.0 * x336;
        let x346 = 1.0 / x345;
        let x347 = x344 * x346;
        let x348 = x336 - 1.0;
        let x359 = x337 * x346;
        let x360 = x339 * x346;
        let x361 = x341 * x346;
        let x400 = 2.0 * s[11];
        let x401 = s[5] * s[13];
        let x402 = s[10] * x400;
        let x404 = x401 + x402;
        let x405 = s[49] * x404;
        let x467 = x191 - x190;
        let x468 = x186 + x467;
        let x469 = x468 - x187;
        let x470 = 2.0 * x469;
        let x473 = x177 + x181;
        let x475 = x182 - x473;
        let x476 = x178 + x475;
        let x477 = 2.0 * x476;
        let x480 = x169 - x173;
        let x481 = x480 - x170;
        let x482 = x174 + x481;
        let x483 = 2.0 * x482;
        let x504 = 2.0 * x470;
        let x506 = 2.0 * x477;
        let x508 = 2.0 * x483;
        let x576 = 2.0 * x137;
        let x578 = 2.0 * x138;
        let x580 = 2.0 * x139;
        let x582 = x137 * x576;
        let x584 = 0.01 * x582;
        let x586 = x138 * x578;
        let x588 = 0.01 * x586;
        let x590 = x139 * x580;
        let x592 = 0.01 * x590;
        let x594 = x584 + x588;
        let x596 = x592 + x594;
        let x598 = 0.5 * x596;
        let x600 = x36 * 0.04;
        let x601 = x598 + x600;
        let x602 = 2.0 * x136;
        let x603 = x137 * x602;
        let x604 = 0.01 * x603;
        let x605 = x138 * x580;
        let x607 = 0.01 * x605;
        let x609 = x139 * x578;
        let x610 = 0.01 * x609;
        let x611 = x604 - x607;
        let x612 = x610 + x611;
        let x613 = 0.5 * x612;
        let x615 = x65 * 0.04;
        let x616 = x615 - x613;
        let x617 = x137 * x580;
        let x618 = 0.01 * x617;
        let x619 = x138 * x602;
        let x620 = 0.01 * x619;
        let x621 = x139 * x576;
        let x623 = 0.01 * x621;
        let x625 = x618 + x620;
        let x626 = x625 - x623;
        let x627 = 0.5 * x626;
        let x629 = x59 * 0.04;
        let x630 = x629 - x627;
        let x631 = x137 * x578;
        let x633 = 0.01 * x631;
        let x635 = x138 * x576;
        let x636 = 0.01 * x635;
        let x637 = x139 * x602;
        let x638 = 0.01 * x637;
        let x639 = x636 - x633;
        let x640 = x638 + x639;
        let x641 = 0.5 * x640;
        let x643 = x52 * 0.04;
        let x644 = x643 - x641;
        let x645 = x136 * x576;
        let x647 = 0.01 * x645;
        let x651 = x610 - x647;
        let x652 = x651 - x607;
        let x653 = 0.5 * x652;
        let x654 = x615 + x653;
        let x655 = x136 * x602;
        let x656 = 0.01 * x655;
        let x657 = x592 + x656;
        let x658 = x588 + x657;
        let x659 = 0.5 * x658;
        let x660 = x37 * 0.04;
        let x661 = x659 + x660;
        let x662 = x136 * x580;
        let x663 = 0.01 * x662;
        let x667 = x663 - x638;
        let x668 = x667 - x636;
        let x669 = 0.5 * x668;
        let x670 = x50 * 0.04;
        let x671 = x669 + x670;
        let x672 = x136 * x578;
        let x674 = 0.01 * x672;
        let x676 = x623 + x674;
        let x678 = x620 - x676;
        let x679 = 0.5 * x678;
        let x680 = x57 * 0.04;
        let x681 = x679 + x680;
        let x684 = x618 - x676;
        let x685 = 0.5 * x684;
        let x686 = x629 + x685;
        let x689 = x638 - x663;
        let x690 = x689 - x633;
        let x691 = 0.5 * x690;
        let x692 = x670 + x691;
        let x693 = x584 + x657;
        let x694 = 0.5 * x693;
        let x695 = x38 * 0.04;
        let x696 = x694 + x695;
        let x698 = x647 - x610;
        let x699 = x698 - x604;
        let x700 = 0.5 * x699;
        let x701 = x63 * 0.04;
        let x702 = x700 + x701;
        let x703 = x639 - x663;
        let x704 = 0.5 * x703;
        let x705 = x643 + x704;
        let x708 = x674 - x625;
        let x709 = 0.5 * x708;
        let x710 = x680 + x709;
        let x711 = x611 - x647;
        let x712 = 0.5 * x711;
        let x713 = x701 + x712;
        let x714 = x594 + x656;
        let x715 = 0.5 * x714;
        let x716 = x39 * 0.04;
        let x717 = x715 + x716;
        let x720 = x248 + x251;
        let x722 = x251 - x720;
        let x723 = x248 + x722;
        let x724 = 2.0 * x723;
        let x727 = x242 - x245;
        let x728 = x727 - x242;
        let x729 = x245 + x728;
        let x730 = 2.0 * x729;
        let x731 = 2.0 * x724;
        let x732 = 2.0 * x730;
        let x733 = x230 * x504;
        let x734 = 0.01 * x733;
        let x735 = x231 * x506;
        let x736 = x138 * x731;
        let x737 = x735 + x736;
        let x738 = 0.01 * x737;
        let x739 = x232 * x508;
        let x740 = x139 * x732;
        let x741 = x739 + x740;
        let x742 = 0.01 * x741;
        let x743 = x734 + x738;
        let x744 = x742 + x743;
        let x745 = 0.5 * x744;
        let x747 = x229 * x504;
        let x748 = 0.01 * x747;
        let x749 = x232 * x506;
        let x750 = x139 * x731;
        let x751 = x749 + x750;
        let x752 = 0.01 * x751;
        let x754 = x231 * x508;
        let x755 = x138 * x732;
        let x756 = x754 + x755;
        let x757 = 0.01 * x756;
        let x758 = x748 - x752;
        let x759 = x757 + x758;
        let x760 = 0.5 * x759;
        let x761 = x232 * x504;
        let x762 = 0.01 * x761;
        let x763 = x229 * x506;
        let x764 = x136 * x731;
        let x765 = x763 + x764;
        let x766 = 0.01 * x765;
        let x767 = x230 * x508;
        let x768 = x137 * x732;
        let x769 = x767 + x768;
        let x770 = 0.01 * x769;
        let x772 = x762 + x766;
        let x773 = x772 - x770;
        let x774 = 0.5 * x773;
        let x775 = x231 * x504;
        let x776 = 0.01 * x775;
        let x778 = x230 * x506;
        let x779 = x137 * x731;
        let x780 = x778 + x779;
        let x781 = 0.01 * x780;
        let x782 = x229 * x508;
        let x783 = x136 * x732;
        let x784 = x782 + x783;
        let x785 = 0.01 * x784;
        let x786 = x781 - x776;
        let x787 = x785 + x786;
        let x788 = 0.5 * x787;
        let x789 = qd[3] * qd[3];
        let x790 = qd[4] * qd[4];
        let x791 = qd[5] * qd[5];
        let x792 = qd[6] * qd[6];
        let x793 = x789 + x790;
        let x794 = x791 + x793;
        let x795 = x792 + x794;
        let x796 = 0.01 * x735;
        let x797 = 0.01 * x739;
        let x798 = x734 + x796;
        let x799 = x797 + x798;
        let x800 = 0.5 * x799;
        let x801 = x745 + x800;
        let x802 = q[3] * 0.04;
        let x803 = x795 * x802;
        let x805 = x801 - x803;
        let x812 = 0.01 * x749;
        let x814 = 0.01 * x754;
        let x816 = x812 - x748;
        let x817 = x816 - x814;
        let x818 = 0.5 * x817;
        let x820 = x818 - x760;
        let x821 = q[4] * 0.04;
        let x822 = x795 * x821;
        let x824 = x820 - x822;
        let x830 = 0.01 * x763;
        let x832 = 0.01 * x767;
        let x833 = x762 + x830;
        let x835 = x832 - x833;
        let x836 = 0.5 * x835;
        let x838 = x836 - x774;
        let x839 = q[5] * 0.04;
        let x840 = x795 * x839;
        let x842 = x838 - x840;
        let x846 = 0.01 * x778;
        let x849 = 0.01 * x782;
        let x851 = x776 - x846;
        let x852 = x851 - x849;
        let x853 = 0.5 * x852;
        let x855 = x853 - x788;
        let x856 = q[6] * 0.04;
        let x857 = x795 * x856;
        let x859 = x855 - x857;
        let x957 = 2.0 * s[13];
        let x959 = 2.0 * s[14];
        let x961 = s[12] * s[51];
        let x963 = 0.1 * x961;
        let x965 = s[13] * x957;
        let x969 = s[14] * x959;
        let x971 = 0.3 * x969;
        let x981 = s[12] * x400;
        let x982 = 0.1 * x981;
        let x983 = s[13] * x959;
        let x987 = s[14] * x957;
        let x988 = 0.3 * x987;
        let x995 = s[12] * x959;
        let x996 = 0.1 * x995;
        let x997 = s[13] * x400;
        let x999 = s[14] * s[51];
        let x1001 = 0.3 * x999;
        let x1009 = s[12] * x957;
        let x1011 = 0.1 * x1009;
        let x1013 = s[13] * s[51];
        let x1015 = s[14] * x400;
        let x1016 = 0.3 * x1015;
        let x1023 = s[11] * s[51];
        let x1025 = 0.1 * x1023;
        let x1030 = 0.3 * x983;
        let x1036 = s[11] * x400;
        let x1037 = 0.1 * x1036;
        let x1040 = 0.3 * x965;
        let x1046 = s[11] * x959;
        let x1047 = 0.1 * x1046;
        let x1051 = 0.3 * x1013;
        let x1058 = s[11] * x957;
        let x1060 = 0.1 * x1058;
        let x1064 = 0.3 * x997;
        let x1071 = 0.1 * x999;
        let x1076 = 0.3 * x995;
        let x1083 = 0.1 * x1015;
        let x1087 = 0.3 * x1009;
        let x1093 = 0.1 * x969;
        let x1095 = 0.3 * x961;
        let x1102 = 0.1 * x987;
        let x1105 = 0.3 * x981;
        let x1112 = 0.1 * x1013;
        let x1116 = 0.3 * x1046;
        let x1122 = 0.1 * x997;
        let x1126 = 0.3 * x1058;
        let x1132 = 0.1 * x983;
        let x1135 = 0.3 * x1023;
        let x1141 = 0.1 * x965;
        let x1144 = 0.3 * x1036;
        let x1167 = s[26] * s[64];
        let x1168 = 0.1 * x1167;
        let x1169 = s[27] * s[65];
        let x1170 = s[13] * s[77];
        let x1171 = x1169 + x1170;
        let x1173 = s[28] * s[66];
        let x1174 = s[14] * s[78];
        let x1175 = x1173 + x1174;
        let x1176 = 0.3 * x1175;
        let x1231 = 0.3 * x1173;
        let x1702 = t * k[1];
        let x1703 = x1702.sin();
        let x1704 = k[0] * x1703;
        let x1721 = x348 * k[9];
        let x1722 = x347 * k[6];
        let x1724 = x1704 - x1722;
        let x1726 = x1724 - x1721;
        let x1730 = x359 * x1726;
        let x1731 = x360 * x1726;
        let x1732 = x361 * x1726;
        let x1743 = x405 * s[93];
        let x1748 = s[13] * s[89];
        let x1753 = k[2] + x1730;
        let x1754 = x1743 - x1748;
        let x1766 = k[12] + x1731;
        let x1768 = x965 * k[8];
        let x1769 = x963 + x1768;
        let x1770 = x971 + x1769;
        let x1771 = 0.5 * x1770;
        let x1772 = s[1] * k[16];
        let x1773 = x1771 + x1772;
        let x1774 = x983 * k[8];
        let x1776 = x982 - x1774;
        let x1777 = x988 + x1776;
        let x1778 = 0.5 * x1777;
        let x1780 = x109 * k[16];
        let x1781 = x1780 - x1778;
        let x1782 = x997 * k[8];
        let x1783 = x996 + x1782;
        let x1784 = x1783 - x1001;
        let x1785 = 0.5 * x1784;
        let x1787 = s[8] * k[16];
        let x1788 = x1787 - x1785;
        let x1789 = x1013 * k[8];
        let x1790 = x1789 - x1011;
        let x1791 = x1016 + x1790;
        let x1792 = 0.5 * x1791;
        let x1794 = x96 * k[16];
        let x1795 = x1794 - x1792;
        let x1796 = x987 * k[8];
        let x1797 = x1796 - x1025;
        let x1798 = x1797 - x1030;
        let x1799 = 0.5 * x1798;
        let x1800 = x1780 + x1799;
        let x1801 = x969 * k[8];
        let x1802 = x1037 + x1801;
        let x1803 = x1040 + x1802;
        let x1804 = 0.5 * x1803;
        let x1805 = s[2] * k[16];
        let x1806 = x1804 + x1805;
        let x1807 = x1015 * k[8];
        let x1809 = x1047 - x1807;
        let x1810 = x1809 - x1051;
        let x1811 = 0.5 * x1810;
        let x1812 = x94 * k[16];
        let x1813 = x1811 + x1812;
        let x1814 = x999 * k[8];
        let x1815 = x1060 + x1814;
        let x1817 = x1064 - x1815;
        let x1818 = 0.5 * x1817;
        let x1819 = s[6] * k[16];
        let x1820 = x1818 + x1819;
        let x1821 = x1058 * k[8];
        let x1822 = x1071 + x1821;
        let x1824 = x1076 - x1822;
        let x1825 = 0.5 * x1824;
        let x1826 = x1787 + x1825;
        let x1827 = x1046 * k[8];
        let x1829 = x1083 - x1827;
        let x1830 = x1829 - x1087;
        let x1831 = 0.5 * x1830;
        let x1832 = x1812 + x1831;
        let x1833 = x1036 * k[8];
        let x1834 = x1093 + x1833;
        let x1835 = x1095 + x1834;
        let x1836 = 0.5 * x1835;
        let x1837 = x83 * k[16];
        let x1838 = x1836 + x1837;
        let x1839 = x1023 * k[8];
        let x1840 = x1839 - x1102;
        let x1841 = x1840 - x1105;
        let x1842 = 0.5 * x1841;
        let x1843 = x107 * k[16];
        let x1844 = x1842 + x1843;
        let x1845 = x1009 * k[8];
        let x1847 = x1112 - x1845;
        let x1848 = x1847 - x1116;
        let x1849 = 0.5 * x1848;
        let x1850 = x1794 + x1849;
        let x1851 = x995 * k[8];
        let x1852 = x1122 + x1851;
        let x1854 = x1126 - x1852;
        let x1855 = 0.5 * x1854;
        let x1856 = x1819 + x1855;
        let x1857 = x981 * k[8];
        let x1858 = x1857 - x1132;
        let x1859 = x1858 - x1135;
        let x1860 = 0.5 * x1859;
        let x1861 = x1843 + x1860;
        let x1862 = x961 * k[8];
        let x1863 = x1141 + x1862;
        let x1864 = x1144 + x1863;
        let x1865 = 0.5 * x1864;
        let x1866 = x84 * k[16];
        let x1867 = x1865 + x1866;
        let x1868 = x1171 * k[8];
        let x1869 = x1168 + x1868;
        let x1870 = x1176 + x1869;
        let x1871 = 0.5 * x1870;
        let x1885 = x1169 * k[8];
        let x1886 = x1168 + x1885;
        let x1887 = x1231 + x1886;
        let x1888 = 0.5 * x1887;
        let x1889 = x1871 + x1888;
        let x1890 = q[10] * k[16];
        let x1891 = s[85] * x1890;
        let x1893 = x1889 - x1891;
        let x1926 = x1754 + x1893;
        phi[0] = x62;
        phi_q[0] = x139;
        phi_q[1] = x138;
        phi_q[2] = x137;
        phi_q[3] = x136;
        phi[1] = x72;
        phi_q[4] = x140;
        phi_q[5] = x139;
        phi_q[6] = x141;
        phi_q[7] = x137;
        phi[2] = q[1];
        phi_q[8] = 1.0;
        phi[3] = q[2];
        phi_q[9] = 1.0;
        phi[4] = x73;
        phi_q[10] = x137;
        phi_q[11] = x136;
        phi_q[12] = x139;
        phi_q[13] = x138;
        phi[5] = x124;
        phi_q[14] = -1.0;
        phi[6] = x126;
        phi_q[15] = -1.0;
        phi[7] = x128;
        phi_q[16] = -1.0;
        phi[8] = x100;
        phi_q[17] = x146;
        phi_q[18] = s[13];
        phi_q[19] = s[12];
        phi_q[20] = x148;
        phi[9] = x129;
        phi_q[21] = x147;
        phi_q[22] = x148;
        phi_q[23] = x146;
        phi_q[24] = x149;
        phi[10] = x132;
        phi_q[25] = x136;
        phi_q[26] = x137;
        phi_q[27] = x138;
        phi_q[28] = x139;
        phi[11] = x135;
        phi_q[29] = s[11];
        phi_q[30] = s[12];
        phi_q[31] = s[13];
        phi_q[32] = s[14];
        mass[0] = k[15];
        mass[1] = k[15];
        mass[2] = k[15];
        mass[3] = x601;
        mass[4] = x616;
        mass[5] = x630;
        mass[6] = x644;
        mass[7] = x654;
        mass[8] = x661;
        mass[9] = x671;
        mass[10] = x681;
        mass[11] = x686;
        mass[12] = x692;
        mass[13] = x696;
        mass[14] = x702;
        mass[15] = x705;
        mass[16] = x710;
        mass[17] = x713;
        mass[18] = x717;
        mass[19] = 1.0;
        mass[20] = 1.0;
        mass[21] = 1.0;
        mass[22] = x1773;
        mass[23] = x1781;
        mass[24] = x1788;
        mass[25] = x1795;
        mass[26] = x1800;
        mass[27] = x1806;
        mass[28] = x1813;
        mass[29] = x1820;
        mass[30] = x1826;
        mass[31] = x1832;
        mass[32] = x1838;
        mass[33] = x1844;
        mass[34] = x1850;
        mass[35] = x1856;
        mass[36] = x1861;
        mass[37] = x1867;
        force[0] = x1753;
        force[1] = x1766;
        force[2] = x1732;
        force[3] = x805;
        force[4] = x824;
        force[5] = x842;
        force[6] = x859;
        force[7] = 0.0;
        force[8] = -9.81;
        force[9] = 0.0;
        force[10] = x1926;
    }
    #[inline(never)]
    fn eval_newton_part_1(
        k: &[f64; 17],
        q: &[f64; 14],
        qd: &[f64; 14],
        s: &[f64; 94],
        force: &mut [f64; 14],
    ) {
        let x233 = 2.0 * qd[10];
        let x407 = s[5] * s[14];
        let x409 = s[10] * s[51];
        let x411 = x409 - x407;
        let x412 = s[49] * x411;
        let x413 = s[5] * s[11];
        let x414 = s[49] * x413;
        let x415 = s[5] * s[12];
        let x417 = s[49] * x415;
        let x1181 = x233 * s[64];
        let x1182 = 0.1 * x1181;
        let x1183 = s[28] * s[65];
        let x1184 = s[14] * s[77];
        let x1185 = x1183 + x1184;
        let x1188 = s[27] * s[66];
        let x1189 = s[13] * s[78];
        let x1190 = x1188 + x1189;
        let x1191 = 0.3 * x1190;
        let x1195 = s[28] * s[64];
        let x1196 = 0.1 * x1195;
        let x1197 = x233 * s[65];
        let x1198 = s[11] * s[77];
        let x1199 = x1197 + x1198;
        let x1201 = s[26] * s[66];
        let x1202 = s[12] * s[78];
        let x1203 = x1201 + x1202;
        let x1204 = 0.3 * x1203;
        let x1209 = s[27] * s[64];
        let x1210 = 0.1 * x1209;
        let x1212 = s[26] * s[65];
        let x1213 = s[12] * s[77];
        let x1214 = x1212 + x1213;
        let x1216 = x233 * s[66];
        let x1217 = s[11] * s[78];
        let x1218 = x1216 + x1217;
        let x1219 = 0.3 * x1218;
        let x1248 = 0.3 * x1188;
        let x1266 = 0.3 * x1201;
        let x1283 = 0.3 * x1216;
        let x1744 = x412 * s[93];
        let x1745 = x414 * s[93];
        let x1746 = x417 * s[93];
        let x1750 = s[14] * s[89];
        let x1751 = s[11] * s[89];
        let x1752 = s[12] * s[89];
        let x1755 = x1744 + x1750;
        let x1756 = x1745 + x1751;
        let x1757 = x1746 + x1752;
        let x1872 = x1185 * k[8];
        let x1874 = x1182 - x1872;
        let x1875 = x1191 + x1874;
        let x1876 = 0.5 * x1875;
        let x1877 = x1199 * k[8];
        let x1878 = x1196 + x1877;
        let x1879 = x1878 - x1204;
        let x1880 = 0.5 * x1879;
        let x1881 = x1214 * k[8];
        let x1882 = x1881 - x1210;
        let x1883 = x1219 + x1882;
        let x1884 = 0.5 * x1883;
        let x1894 = x1183 * k[8];
        let x1895 = x1894 - x1182;
        let x1896 = x1895 - x1248;
        let x1897 = 0.5 * x1896;
        let x1899 = x1897 - x1876;
        let x1900 = q[11] * k[16];
        let x1901 = s[85] * x1900;
        let x1903 = x1899 - x1901;
        let x1904 = x1197 * k[8];
        let x1905 = x1196 + x1904;
        let x1907 = x1266 - x1905;
        let x1908 = 0.5 * x1907;
        let x1910 = x1908 - x1880;
        let x1911 = q[12] * k[16];
        let x1912 = s[85] * x1911;
        let x1914 = x1910 - x1912;
        let x1915 = x1212 * k[8];
        let x1917 = x1210 - x1915;
        let x1918 = x1917 - x1283;
        let x1919 = 0.5 * x1918;
        let x1921 = x1919 - x1884;
        let x1922 = q[13] * k[16];
        let x1923 = s[85] * x1922;
        let x1925 = x1921 - x1923;
        let x1927 = x1755 + x1903;
        let x1928 = x1756 + x1914;
        let x1929 = x1925 - x1757;
        force[11] = x1927;
        force[12] = x1928;
        force[13] = x1929;
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
        offsets_read_parameters: false,
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
    pub const N_K: usize = 15;
    /// `setup` at the file's parameter values: what the types without parameters read.
    pub static K: [f64; 15] = [
        3f64,
        4f64,
        1f64,
        0.5f64,
        3f64,
        0.2f64,
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
        let p: &[f64; 33] = p.try_into().expect("p must have 33 entries");
        let k: &mut [f64; 15] = k.try_into().expect("k must have 15 entries");
        setup_part_0(p, k);
    }
    #[inline(never)]
    fn setup_part_0(p: &[f64; 33], k: &mut [f64; 15]) {
        let x355 = 0.5 * p[3];
        let x396 = 0.5 * p[4];
        let x574 = 2.0 * p[5];
        let x575 = 0.5 * x574;
        let x951 = p[2] + 0.1;
        let x952 = 0.3 + x951;
        let x953 = 4.0 * x952;
        let x955 = x953 * 0.3333333333333333;
        k[0] = p[27];
        k[1] = p[28];
        k[2] = p[29];
        k[3] = p[30];
        k[4] = p[31];
        k[5] = p[32];
        k[6] = p[0];
        k[7] = p[1];
        k[8] = p[2];
        k[9] = p[3];
        k[10] = p[4];
        k[11] = x355;
        k[12] = x396;
        k[13] = x575;
        k[14] = x955;
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
        let x36 = q[3] * q[3];
        let x37 = q[4] * q[4];
        let x38 = q[5] * q[5];
        let x39 = q[6] * q[6];
        let x63 = q[5] * q[6];
        let x64 = 2.0 * x63;
        let x65 = q[3] * q[4];
        let x67 = 2.0 * x65;
        let x332 = q[1] * q[1];
        let x333 = q[2] * q[2];
        let x1700 = x332 + x333;
        let x1701 = q[2] * q[3];
        let x1702 = 2.0 * x1701;
        let x1703 = q[1] * q[4];
        let x1704 = 2.0 * x1703;
        let x1705 = q[2] * q[4];
        let x1706 = 2.0 * x1705;
        let x1707 = q[1] * q[3];
        let x1708 = 2.0 * x1707;
        let x1709 = x1702 + x1704;
        let x1710 = q[1] * q[2];
        let x1711 = 2.0 * x1710;
        let x1713 = x1706 - x1708;
        let x1714 = x67 + x1711;
        let x1715 = q[7] * q[7];
        let x1716 = q[8] * q[8];
        let x1717 = x38 + x39;
        let x1718 = q[6] * q[7];
        let x1719 = 2.0 * x1718;
        let x1720 = q[5] * q[8];
        let x1721 = 2.0 * x1720;
        let x1723 = x1719 - x1721;
        let x1724 = q[7] * q[8];
        let x1725 = 2.0 * x1724;
        let x1726 = x64 + x1725;
        let x1727 = -x1726;
        let x1728 = x36 + x1700;
        let x1729 = x37 + x1728;
        let x1730 = x1729 - 1.0;
        let x1731 = x1715 + x1717;
        let x1732 = x1716 + x1731;
        let x1733 = x1732 - 1.0;
        out[0] = x1709;
        out[1] = x1713;
        out[2] = x1714;
        out[3] = x1723;
        out[4] = x1727;
        out[5] = x1730;
        out[6] = x1733;
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
        let x136 = q[3] * 2.0;
        let x137 = q[4] * 2.0;
        let x138 = q[5] * 2.0;
        let x139 = q[6] * 2.0;
        let x140 = -x138;
        let x141 = -x136;
        let x339 = q[1] * 2.0;
        let x341 = q[2] * 2.0;
        let x518 = -x139;
        let x1734 = -x339;
        let x1735 = 2.0 * q[7];
        let x1736 = 2.0 * q[8];
        let x1737 = -x1736;
        let x1738 = -x1735;
        out[0] = x137;
        out[1] = x136;
        out[2] = x341;
        out[3] = x339;
        out[4] = x141;
        out[5] = x137;
        out[6] = x1734;
        out[7] = x341;
        out[8] = x341;
        out[9] = x339;
        out[10] = x137;
        out[11] = x136;
        out[12] = x1737;
        out[13] = x1735;
        out[14] = x139;
        out[15] = x140;
        out[16] = x518;
        out[17] = x140;
        out[18] = x1737;
        out[19] = x1738;
        out[20] = x339;
        out[21] = x341;
        out[22] = x136;
        out[23] = x137;
        out[24] = x138;
        out[25] = x139;
        out[26] = x1735;
        out[27] = x1736;
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
        let x229 = 2.0 * qd[3];
        let x230 = 2.0 * qd[4];
        let x231 = 2.0 * qd[5];
        let x232 = 2.0 * qd[6];
        let x237 = qd[3] * x229;
        let x238 = qd[4] * x230;
        let x239 = qd[5] * x231;
        let x240 = qd[6] * x232;
        let x255 = qd[5] * qd[6];
        let x256 = x255 + x255;
        let x257 = 2.0 * x256;
        let x258 = qd[3] * qd[4];
        let x259 = x258 + x258;
        let x260 = 2.0 * x259;
        let x505 = 2.0 * qd[1];
        let x507 = 2.0 * qd[2];
        let x891 = 2.0 * qd[7];
        let x893 = 2.0 * qd[8];
        let x1787 = qd[1] * x505;
        let x1788 = qd[2] * x507;
        let x1789 = x1787 + x1788;
        let x1790 = qd[2] * qd[3];
        let x1791 = x1790 + x1790;
        let x1792 = 2.0 * x1791;
        let x1793 = qd[1] * qd[4];
        let x1794 = x1793 + x1793;
        let x1795 = 2.0 * x1794;
        let x1796 = qd[2] * qd[4];
        let x1797 = x1796 + x1796;
        let x1798 = 2.0 * x1797;
        let x1799 = qd[1] * qd[3];
        let x1800 = x1799 + x1799;
        let x1801 = 2.0 * x1800;
        let x1802 = x1792 + x1795;
        let x1803 = qd[1] * qd[2];
        let x1804 = x1803 + x1803;
        let x1805 = 2.0 * x1804;
        let x1807 = x1798 - x1801;
        let x1808 = x260 + x1805;
        let x1809 = qd[7] * x891;
        let x1810 = qd[8] * x893;
        let x1811 = x239 + x240;
        let x1812 = qd[6] * qd[7];
        let x1813 = x1812 + x1812;
        let x1814 = 2.0 * x1813;
        let x1815 = qd[5] * qd[8];
        let x1816 = x1815 + x1815;
        let x1817 = 2.0 * x1816;
        let x1819 = x1814 - x1817;
        let x1820 = qd[7] * qd[8];
        let x1821 = x1820 + x1820;
        let x1822 = 2.0 * x1821;
        let x1823 = x257 + x1822;
        let x1825 = x237 + x1789;
        let x1826 = x238 + x1825;
        let x1827 = x1809 + x1811;
        let x1828 = x1810 + x1827;
        let x1829 = -x1802;
        let x1830 = -x1807;
        let x1831 = -x1808;
        let x1832 = -x1819;
        let x1833 = -x1826;
        let x1834 = -x1828;
        out[0] = x1829;
        out[1] = x1830;
        out[2] = x1831;
        out[3] = x1832;
        out[4] = x1823;
        out[5] = x1833;
        out[6] = x1834;
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
        let x36 = q[3] * q[3];
        let x37 = q[4] * q[4];
        let x38 = q[5] * q[5];
        let x39 = q[6] * q[6];
        let x63 = q[5] * q[6];
        let x64 = 2.0 * x63;
        let x65 = q[3] * q[4];
        let x67 = 2.0 * x65;
        let x136 = q[3] * 2.0;
        let x137 = q[4] * 2.0;
        let x138 = q[5] * 2.0;
        let x139 = q[6] * 2.0;
        let x140 = -x138;
        let x141 = -x136;
        let x229 = 2.0 * qd[3];
        let x230 = 2.0 * qd[4];
        let x231 = 2.0 * qd[5];
        let x232 = 2.0 * qd[6];
        let x237 = qd[3] * x229;
        let x238 = qd[4] * x230;
        let x239 = qd[5] * x231;
        let x240 = qd[6] * x232;
        let x255 = qd[5] * qd[6];
        let x256 = x255 + x255;
        let x257 = 2.0 * x256;
        let x258 = qd[3] * qd[4];
        let x259 = x258 + x258;
        let x260 = 2.0 * x259;
        let x332 = q[1] * q[1];
        let x333 = q[2] * q[2];
        let x339 = q[1] * 2.0;
        let x341 = q[2] * 2.0;
        let x505 = 2.0 * qd[1];
        let x507 = 2.0 * qd[2];
        let x518 = -x139;
        let x891 = 2.0 * qd[7];
        let x893 = 2.0 * qd[8];
        let x1700 = x332 + x333;
        let x1701 = q[2] * q[3];
        let x1702 = 2.0 * x1701;
        let x1703 = q[1] * q[4];
        let x1704 = 2.0 * x1703;
        let x1705 = q[2] * q[4];
        let x1706 = 2.0 * x1705;
        let x1707 = q[1] * q[3];
        let x1708 = 2.0 * x1707;
        let x1709 = x1702 + x1704;
        let x1710 = q[1] * q[2];
        let x1711 = 2.0 * x1710;
        let x1713 = x1706 - x1708;
        let x1714 = x67 + x1711;
        let x1715 = q[7] * q[7];
        let x1716 = q[8] * q[8];
        let x1717 = x38 + x39;
        let x1718 = q[6] * q[7];
        let x1719 = 2.0 * x1718;
        let x1720 = q[5] * q[8];
        let x1721 = 2.0 * x1720;
        let x1723 = x1719 - x1721;
        let x1724 = q[7] * q[8];
        let x1725 = 2.0 * x1724;
        let x1726 = x64 + x1725;
        let x1727 = -x1726;
        let x1728 = x36 + x1700;
        let x1729 = x37 + x1728;
        let x1730 = x1729 - 1.0;
        let x1731 = x1715 + x1717;
        let x1732 = x1716 + x1731;
        let x1733 = x1732 - 1.0;
        let x1734 = -x339;
        let x1735 = 2.0 * q[7];
        let x1736 = 2.0 * q[8];
        let x1737 = -x1736;
        let x1738 = -x1735;
        let x1787 = qd[1] * x505;
        let x1788 = qd[2] * x507;
        let x1789 = x1787 + x1788;
        let x1790 = qd[2] * qd[3];
        let x1791 = x1790 + x1790;
        let x1792 = 2.0 * x1791;
        let x1793 = qd[1] * qd[4];
        let x1794 = x1793 + x1793;
        let x1795 = 2.0 * x1794;
        let x1796 = qd[2] * qd[4];
        let x1797 = x1796 + x1796;
        let x1798 = 2.0 * x1797;
        let x1799 = qd[1] * qd[3];
        let x1800 = x1799 + x1799;
        let x1801 = 2.0 * x1800;
        let x1802 = x1792 + x1795;
        let x1803 = qd[1] * qd[2];
        let x1804 = x1803 + x1803;
        let x1805 = 2.0 * x1804;
        let x1807 = x1798 - x1801;
        let x1808 = x260 + x1805;
        let x1809 = qd[7] * x891;
        let x1810 = qd[8] * x893;
        let x1811 = x239 + x240;
        let x1812 = qd[6] * qd[7];
        let x1813 = x1812 + x1812;
        let x1814 = 2.0 * x1813;
        let x1815 = qd[5] * qd[8];
        let x1816 = x1815 + x1815;
        let x1817 = 2.0 * x1816;
        let x1819 = x1814 - x1817;
        let x1820 = qd[7] * qd[8];
        let x1821 = x1820 + x1820;
        let x1822 = 2.0 * x1821;
        let x1823 = x257 + x1822;
        let x1825 = x237 + x1789;
        let x1826 = x238 + x1825;
        let x1827 = x1809 + x1811;
        let x1828 = x1810 + x1827;
        let x1829 = -x1802;
        let x1830 = -x1807;
        let x1831 = -x1808;
        let x1832 = -x1819;
        let x1833 = -x1826;
        let x1834 = -x1828;
        phi[0] = x1709;
        phi_q[0] = x137;
        phi_q[1] = x136;
        phi_q[2] = x341;
        phi_q[3] = x339;
        phi_t[0] = 0.0;
        gamma[0] = x1829;
        phi[1] = x1713;
        phi_q[4] = x141;
        phi_q[5] = x137;
        phi_q[6] = x1734;
        phi_q[7] = x341;
        phi_t[1] = 0.0;
        gamma[1] = x1830;
        phi[2] = x1714;
        phi_q[8] = x341;
        phi_q[9] = x339;
        phi_q[10] = x137;
        phi_q[11] = x136;
        phi_t[2] = 0.0;
        gamma[2] = x1831;
        phi[3] = x1723;
        phi_q[12] = x1737;
        phi_q[13] = x1735;
        phi_q[14] = x139;
        phi_q[15] = x140;
        phi_t[3] = 0.0;
        gamma[3] = x1832;
        phi[4] = x1727;
        phi_q[16] = x518;
        phi_q[17] = x140;
        phi_q[18] = x1737;
        phi_q[19] = x1738;
        phi_t[4] = 0.0;
        gamma[4] = x1823;
        phi[5] = x1730;
        phi_q[20] = x339;
        phi_q[21] = x341;
        phi_q[22] = x136;
        phi_q[23] = x137;
        phi_t[5] = 0.0;
        gamma[5] = x1833;
        phi[6] = x1733;
        phi_q[24] = x138;
        phi_q[25] = x139;
        phi_q[26] = x1735;
        phi_q[27] = x1736;
        phi_t[6] = 0.0;
        gamma[6] = x1834;
    }
    /// Potential energy of gravity and springs, written to `out[0]`.
    pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 15] = k.try_into().expect("k must have 15 entries");
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        potential_into_part_0(k, q, out);
    }
    #[inline(never)]
    fn potential_into_part_0(k: &[f64; 15], q: &[f64; 9], out: &mut [f64; 1]) {
        let x38 = q[5] * q[5];
        let x39 = q[6] * q[6];
        let x330 = 1.0 + q[0];
        let x331 = x330 * x330;
        let x1717 = x38 + x39;
        let x1835 = 2.0 * x1717;
        let x1836 = x1835 - 1.0;
        let x1837 = q[6] * q[8];
        let x1838 = 2.0 * x1837;
        let x1839 = q[5] * q[7];
        let x1840 = 2.0 * x1839;
        let x1842 = x1838 - x1840;
        let x1843 = x331.sqrt();
        let x1844 = x1843 - 1.0;
        let x1845 = x1844 * x1844;
        let x1847 = -x1842;
        let x1848 = x1847.atan2(x1836);
        let x1849 = x1848 * x1848;
        let x2495 = x1845 * k[11];
        let x2496 = x1849 * k[12];
        let x2497 = 9.81 + x2495;
        let x2498 = x2496 + x2497;
        out[0] = x2498;
    }
    /// Power of the non-conservative loads, written to `out[0]`.
    pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 15] = k.try_into().expect("k must have 15 entries");
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        power_nc_into_part_0(k, q, qd, t, out);
    }
    #[inline(never)]
    fn power_nc_into_part_0(
        k: &[f64; 15],
        q: &[f64; 9],
        qd: &[f64; 9],
        t: f64,
        out: &mut [f64; 1],
    ) {
        let x13 = t.sin();
        let x38 = q[5] * q[5];
        let x39 = q[6] * q[6];
        let x138 = q[5] * 2.0;
        let x139 = q[6] * 2.0;
        let x166 = x138 * qd[5];
        let x167 = x139 * qd[6];
        let x330 = 1.0 + q[0];
        let x331 = x330 * x330;
        let x337 = 2.0 * x330;
        let x338 = qd[0] * x337;
        let x1717 = x38 + x39;
        let x1766 = x166 + x167;
        let x1835 = 2.0 * x1717;
        let x1836 = x1835 - 1.0;
        let x1837 = q[6] * q[8];
        let x1838 = 2.0 * x1837;
        let x1839 = q[5] * q[7];
        let x1840 = 2.0 * x1839;
        let x1842 = x1838 - x1840;
        let x1843 = x331.sqrt();
        let x1853 = 2.0 * x1843;
        let x1854 = 1.0 / x1853;
        let x1855 = x338 * x1854;
        let x1860 = 2.0 * x1766;
        let x1861 = q[8] * qd[6];
        let x1862 = q[6] * qd[8];
        let x1863 = x1861 + x1862;
        let x1864 = 2.0 * x1863;
        let x1865 = q[7] * qd[5];
        let x1866 = q[5] * qd[7];
        let x1867 = x1865 + x1866;
        let x1868 = 2.0 * x1867;
        let x1870 = x1864 - x1868;
        let x1871 = x1836 * x1836;
        let x1872 = x1842 * x1842;
        let x1873 = x1871 + x1872;
        let x1874 = x1836 * x1870;
        let x1876 = x1842 * x1860;
        let x1877 = x1876 - x1874;
        let x1878 = 1.0 / x1873;
        let x1879 = x1877 * x1878;
        let x1886 = x1861 - x1865;
        let x1887 = x1866 + x1886;
        let x1888 = x1887 - x1862;
        let x1889 = 2.0 * x1888;
        let x2474 = t * k[1];
        let x2475 = x2474.sin();
        let x2476 = k[0] * x2475;
        let x2480 = t * k[4];
        let x2481 = x2480.cos();
        let x2482 = k[3] * x2481;
        let x2484 = x13 * k[5];
        let x2491 = qd[0] * k[2];
        let x2499 = x1855 * k[6];
        let x2501 = x2476 - x2499;
        let x2502 = x1855 * x2501;
        let x2503 = x1879 * k[7];
        let x2505 = x2482 - x2503;
        let x2506 = x1879 * x2505;
        let x2507 = x1889 * x2484;
        let x2508 = x2491 + x2502;
        let x2509 = x2506 + x2508;
        let x2510 = x2507 + x2509;
        out[0] = x2510;
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
            let k: &[f64; 15] = k.try_into().expect("k must have 15 entries");
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
            let k: &[f64; 15] = k.try_into().expect("k must have 15 entries");
            let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
            let out: &mut [f64; 33] = out.try_into().expect("out must have 33 entries");
            mass_part_0(k, q, out);
        }
        #[inline(never)]
        fn mass_part_0(k: &[f64; 15], q: &[f64; 9], out: &mut [f64; 33]) {
            let x36 = q[3] * q[3];
            let x37 = q[4] * q[4];
            let x38 = q[5] * q[5];
            let x39 = q[6] * q[6];
            let x63 = q[5] * q[6];
            let x65 = q[3] * q[4];
            let x136 = q[3] * 2.0;
            let x137 = q[4] * 2.0;
            let x138 = q[5] * 2.0;
            let x139 = q[6] * 2.0;
            let x332 = q[1] * q[1];
            let x333 = q[2] * q[2];
            let x339 = q[1] * 2.0;
            let x341 = q[2] * 2.0;
            let x576 = 2.0 * x137;
            let x578 = 2.0 * x138;
            let x580 = 2.0 * x139;
            let x582 = x137 * x576;
            let x584 = 0.01 * x582;
            let x586 = x138 * x578;
            let x590 = x139 * x580;
            let x600 = x36 * 0.04;
            let x602 = 2.0 * x136;
            let x603 = x137 * x602;
            let x604 = 0.01 * x603;
            let x605 = x138 * x580;
            let x609 = x139 * x578;
            let x615 = x65 * 0.04;
            let x645 = x136 * x576;
            let x647 = 0.01 * x645;
            let x655 = x136 * x602;
            let x656 = 0.01 * x655;
            let x660 = x37 * 0.04;
            let x1701 = q[2] * q[3];
            let x1703 = q[1] * q[4];
            let x1705 = q[2] * q[4];
            let x1707 = q[1] * q[3];
            let x1710 = q[1] * q[2];
            let x1715 = q[7] * q[7];
            let x1716 = q[8] * q[8];
            let x1718 = q[6] * q[7];
            let x1720 = q[5] * q[8];
            let x1724 = q[7] * q[8];
            let x1735 = 2.0 * q[7];
            let x1736 = 2.0 * q[8];
            let x1837 = q[6] * q[8];
            let x1839 = q[5] * q[7];
            let x1894 = 2.0 * x341;
            let x1895 = x341 * x1894;
            let x1896 = 0.01 * x1895;
            let x1897 = x656 + x1896;
            let x1898 = x584 + x1897;
            let x1899 = 0.5 * x1898;
            let x1900 = x332 * 0.04;
            let x1901 = x1899 + x1900;
            let x1902 = 2.0 * x339;
            let x1903 = x341 * x1902;
            let x1904 = 0.01 * x1903;
            let x1905 = x1904 - x647;
            let x1906 = x604 + x1905;
            let x1907 = 0.5 * x1906;
            let x1909 = 0.04 * x1710;
            let x1910 = x1909 - x1907;
            let x1911 = x341 * x576;
            let x1912 = 0.01 * x1911;
            let x1913 = x136 * x1902;
            let x1914 = 0.01 * x1913;
            let x1915 = x137 * x1894;
            let x1916 = 0.01 * x1915;
            let x1918 = x1912 + x1914;
            let x1919 = x1918 - x1916;
            let x1920 = 0.5 * x1919;
            let x1922 = 0.04 * x1707;
            let x1923 = x1922 - x1920;
            let x1924 = x341 * x602;
            let x1925 = 0.01 * x1924;
            let x1927 = x136 * x1894;
            let x1928 = 0.01 * x1927;
            let x1929 = x137 * x1902;
            let x1930 = 0.01 * x1929;
            let x1931 = x1928 - x1925;
            let x1932 = x1930 + x1931;
            let x1933 = 0.5 * x1932;
            let x1935 = 0.04 * x1703;
            let x1936 = x1935 - x1933;
            let x1937 = x339 * x1894;
            let x1938 = 0.01 * x1937;
            let x1940 = x604 - x1938;
            let x1941 = x1940 - x647;
            let x1942 = 0.5 * x1941;
            let x1943 = x1909 + x1942;
            let x1944 = x339 * x1902;
            let x1945 = 0.01 * x1944;
            let x1946 = x584 + x1945;
            let x1947 = x656 + x1946;
            let x1948 = 0.5 * x1947;
            let x1949 = x333 * 0.04;
            let x1950 = x1948 + x1949;
            let x1951 = x339 * x576;
            let x1952 = 0.01 * x1951;
            let x1955 = x1952 - x1930;
            let x1956 = x1955 - x1928;
            let x1957 = 0.5 * x1956;
            let x1958 = 0.04 * x1701;
            let x1959 = x1957 + x1958;
            let x1960 = x339 * x602;
            let x1961 = 0.01 * x1960;
            let x1962 = x1916 + x1961;
            let x1964 = x1914 - x1962;
            let x1965 = 0.5 * x1964;
            let x1966 = 0.04 * x1705;
            let x1967 = x1965 + x1966;
            let x1968 = x1912 - x1962;
            let x1969 = 0.5 * x1968;
            let x1970 = x1922 + x1969;
            let x1972 = x1930 - x1952;
            let x1973 = x1972 - x1925;
            let x1974 = 0.5 * x1973;
            let x1975 = x1958 + x1974;
            let x1976 = x1896 + x1946;
            let x1977 = 0.5 * x1976;
            let x1978 = x600 + x1977;
            let x1980 = x1938 - x604;
            let x1981 = x1980 - x1904;
            let x1982 = 0.5 * x1981;
            let x1983 = x615 + x1982;
            let x1984 = x1931 - x1952;
            let x1985 = 0.5 * x1984;
            let x1986 = x1935 + x1985;
            let x1988 = x1961 - x1918;
            let x1989 = 0.5 * x1988;
            let x1990 = x1966 + x1989;
            let x1991 = x1905 - x1938;
            let x1992 = 0.5 * x1991;
            let x1993 = x615 + x1992;
            let x1994 = x1897 + x1945;
            let x1995 = 0.5 * x1994;
            let x1996 = x660 + x1995;
            let x1997 = 2.0 * x1735;
            let x1998 = 2.0 * x1736;
            let x1999 = 0.1 * x590;
            let x2000 = x1735 * x1997;
            let x2002 = x1736 * x1998;
            let x2003 = 0.3 * x2002;
            let x2009 = 0.1 * x609;
            let x2010 = x1735 * x1998;
            let x2013 = x1736 * x1997;
            let x2014 = 0.3 * x2013;
            let x2021 = x139 * x1998;
            let x2022 = 0.1 * x2021;
            let x2023 = x578 * x1735;
            let x2025 = x580 * x1736;
            let x2026 = 0.3 * x2025;
            let x2034 = x139 * x1997;
            let x2035 = 0.1 * x2034;
            let x2037 = x580 * x1735;
            let x2039 = x578 * x1736;
            let x2040 = 0.3 * x2039;
            let x2047 = 0.1 * x605;
            let x2050 = 0.3 * x2010;
            let x2056 = 0.1 * x586;
            let x2058 = 0.3 * x2000;
            let x2064 = x138 * x1998;
            let x2065 = 0.1 * x2064;
            let x2068 = 0.3 * x2037;
            let x2075 = x138 * x1997;
            let x2076 = 0.1 * x2075;
            let x2078 = 0.3 * x2023;
            let x2085 = 0.1 * x2025;
            let x2087 = 0.3 * x2021;
            let x2093 = 0.1 * x2039;
            let x2096 = 0.3 * x2034;
            let x2102 = 0.1 * x2002;
            let x2104 = 0.3 * x590;
            let x2110 = 0.1 * x2013;
            let x2113 = 0.3 * x609;
            let x2120 = 0.1 * x2037;
            let x2123 = 0.3 * x2064;
            let x2129 = 0.1 * x2023;
            let x2131 = 0.3 * x2075;
            let x2137 = 0.1 * x2010;
            let x2140 = 0.3 * x605;
            let x2146 = 0.1 * x2000;
            let x2148 = 0.3 * x586;
            let x2511 = x2000 * k[8];
            let x2512 = x1999 + x2511;
            let x2513 = x2003 + x2512;
            let x2514 = 0.5 * x2513;
            let x2515 = x38 * k[14];
            let x2516 = x2514 + x2515;
            let x2517 = x2010 * k[8];
            let x2519 = x2009 - x2517;
            let x2520 = x2014 + x2519;
            let x2521 = 0.5 * x2520;
            let x2523 = x63 * k[14];
            let x2524 = x2523 - x2521;
            let x2525 = x2023 * k[8];
            let x2526 = x2022 + x2525;
            let x2527 = x2526 - x2026;
            let x2528 = 0.5 * x2527;
            let x2530 = x1839 * k[14];
            let x2531 = x2530 - x2528;
            let x2532 = x2037 * k[8];
            let x2533 = x2532 - x2035;
            let x2534 = x2040 + x2533;
            let x2535 = 0.5 * x2534;
            let x2537 = x1720 * k[14];
            let x2538 = x2537 - x2535;
            let x2539 = x2013 * k[8];
            let x2540 = x2539 - x2047;
            let x2541 = x2540 - x2050;
            let x2542 = 0.5 * x2541;
            let x2543 = x2523 + x2542;
            let x2544 = x2002 * k[8];
            let x2545 = x2056 + x2544;
            let x2546 = x2058 + x2545;
            let x2547 = 0.5 * x2546;
            let x2548 = x39 * k[14];
            let x2549 = x2547 + x2548;
            let x2550 = x2039 * k[8];
            let x2552 = x2065 - x2550;
            let x2553 = x2552 - x2068;
            let x2554 = 0.5 * x2553;
            let x2555 = x1718 * k[14];
            let x2556 = x2554 + x2555;
            let x2557 = x2025 * k[8];
            let x2558 = x2076 + x2557;
            let x2560 = x2078 - x2558;
            let x2561 = 0.5 * x2560;
            let x2562 = x1837 * k[14];
            let x2563 = x2561 + x2562;
            let x2564 = x2075 * k[8];
            let x2565 = x2085 + x2564;
            let x2567 = x2087 - x2565;
            let x2568 = 0.5 * x2567;
            let x2569 = x2530 + x2568;
            let x2570 = x2064 * k[8];
            let x2572 = x2093 - x2570;
            let x2573 = x2572 - x2096;
            let x2574 = 0.5 * x2573;
            let x2575 = x2555 + x2574;
            let x2576 = x586 * k[8];
            let x2577 = x2102 + x2576;
            let x2578 = x2104 + x2577;
            let x2579 = 0.5 * x2578;
            let x2580 = x1715 * k[14];
            let x2581 = x2579 + x2580;
            let x2582 = x605 * k[8];
            let x2583 = x2582 - x2110;
            let x2584 = x2583 - x2113;
            let x2585 = 0.5 * x2584;
            let x2586 = x1724 * k[14];
            let x2587 = x2585 + x2586;
            let x2588 = x2034 * k[8];
            let x2590 = x2120 - x2588;
            let x2591 = x2590 - x2123;
            let x2592 = 0.5 * x2591;
            let x2593 = x2537 + x2592;
            let x2594 = x2021 * k[8];
            let x2595 = x2129 + x2594;
            let x2597 = x2131 - x2595;
            let x2598 = 0.5 * x2597;
            let x2599 = x2562 + x2598;
            let x2600 = x609 * k[8];
            let x2601 = x2600 - x2137;
            let x2602 = x2601 - x2140;
            let x2603 = 0.5 * x2602;
            let x2604 = x2586 + x2603;
            let x2605 = x590 * k[8];
            let x2606 = x2146 + x2605;
            let x2607 = x2148 + x2606;
            let x2608 = 0.5 * x2607;
            let x2609 = x1716 * k[14];
            let x2610 = x2608 + x2609;
            out[0] = k[13];
            out[1] = x1901;
            out[2] = x1910;
            out[3] = x1923;
            out[4] = x1936;
            out[5] = x1943;
            out[6] = x1950;
            out[7] = x1959;
            out[8] = x1967;
            out[9] = x1970;
            out[10] = x1975;
            out[11] = x1978;
            out[12] = x1983;
            out[13] = x1986;
            out[14] = x1990;
            out[15] = x1993;
            out[16] = x1996;
            out[17] = x2516;
            out[18] = x2524;
            out[19] = x2531;
            out[20] = x2538;
            out[21] = x2543;
            out[22] = x2549;
            out[23] = x2556;
            out[24] = x2563;
            out[25] = x2569;
            out[26] = x2575;
            out[27] = x2581;
            out[28] = x2587;
            out[29] = x2593;
            out[30] = x2599;
            out[31] = x2604;
            out[32] = x2610;
        }
        /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
        pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            let k: &[f64; 15] = k.try_into().expect("k must have 15 entries");
            let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
            let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
            force_part_0(k, q, qd, t, out);
        }
        #[inline(never)]
        fn force_part_0(
            k: &[f64; 15],
            q: &[f64; 9],
            qd: &[f64; 9],
            t: f64,
            out: &mut [f64; 9],
        ) {
            let x13 = t.sin();
            let x38 = q[5] * q[5];
            let x39 = q[6] * q[6];
            let x136 = q[3] * 2.0;
            let x137 = q[4] * 2.0;
            let x138 = q[5] * 2.0;
            let x139 = q[6] * 2.0;
            let x166 = x138 * qd[5];
            let x167 = x139 * qd[6];
            let x186 = q[6] * qd[5];
            let x187 = q[5] * qd[6];
            let x190 = q[4] * qd[3];
            let x191 = q[3] * qd[4];
            let x229 = 2.0 * qd[3];
            let x230 = 2.0 * qd[4];
            let x231 = 2.0 * qd[5];
            let x232 = 2.0 * qd[6];
            let x330 = 1.0 + q[0];
            let x331 = x330 * x330;
            let x337 = 2.0 * x330;
            let x338 = qd[0] * x337;
            let x339 = q[1] * 2.0;
            let x341 = q[2] * 2.0;
            let x488 = qd[1] * qd[1];
            let x492 = qd[2] * qd[2];
            let x505 = 2.0 * qd[1];
            let x507 = 2.0 * qd[2];
            let x578 = 2.0 * x138;
            let x580 = 2.0 * x139;
            let x789 = qd[3] * qd[3];
            let x790 = qd[4] * qd[4];
            let x791 = qd[5] * qd[5];
            let x792 = qd[6] * qd[6];
            let x802 = q[3] * 0.04;
            let x821 = q[4] * 0.04;
            let x876 = qd[7] * qd[7];
            let x879 = qd[8] * qd[8];
            let x891 = 2.0 * qd[7];
            let x893 = 2.0 * qd[8];
            let x1717 = x38 + x39;
            let x1735 = 2.0 * q[7];
            let x1736 = 2.0 * q[8];
            let x1740 = q[3] * qd[2];
            let x1741 = q[2] * qd[3];
            let x1744 = q[4] * qd[1];
            let x1745 = q[1] * qd[4];
            let x1748 = q[4] * qd[2];
            let x1749 = q[2] * qd[4];
            let x1752 = q[3] * qd[1];
            let x1753 = q[1] * qd[3];
            let x1757 = q[2] * qd[1];
            let x1758 = q[1] * qd[2];
            let x1766 = x166 + x167;
            let x1767 = q[7] * qd[6];
            let x1768 = q[6] * qd[7];
            let x1771 = q[8] * qd[5];
            let x1772 = q[5] * qd[8];
            let x1777 = q[8] * qd[7];
            let x1778 = q[7] * qd[8];
            let x1790 = qd[2] * qd[3];
            let x1793 = qd[1] * qd[4];
            let x1796 = qd[2] * qd[4];
            let x1799 = qd[1] * qd[3];
            let x1812 = qd[6] * qd[7];
            let x1815 = qd[5] * qd[8];
            let x1835 = 2.0 * x1717;
            let x1836 = x1835 - 1.0;
            let x1837 = q[6] * q[8];
            let x1838 = 2.0 * x1837;
            let x1839 = q[5] * q[7];
            let x1840 = 2.0 * x1839;
            let x1842 = x1838 - x1840;
            let x1843 = x331.sqrt();
            let x1844 = x1843 - 1.0;
            let x1847 = -x1842;
            let x1848 = x1847.atan2(x1836);
            let x1853 = 2.0 * x1843;
            let x1854 = 1.0 / x1853;
            let x1855 = x338 * x1854;
            let x1860 = 2.0 * x1766;
            let x1861 = q[8] * qd[6];
            let x1862 = q[6] * qd[8];
            let x1863 = x1861 + x1862;
            let x1864 = 2.0 * x1863;
            let x1865 = q[7] * qd[5];
            let x1866 = q[5] * qd[7];
            let x1867 = x1865 + x1866;
            let x1868 = 2.0 * x1867;
            let x1870 = x1864 - x1868;
            let x1871 = x1836 * x1836;
            let x1872 = x1842 * x1842;
            let x1873 = x1871 + x1872;
            let x1874 = x1836 * x1870;
            let x1876 = x1842 * x1860;
            let x1877 = x1876 - x1874;
            let x1878 = 1.0 / x1873;
            let x1879 = x1877 * x1878;
            let x2157 = x337 * x1854;
            let x2162 = x1735 * x1836;
            let x2163 = x578 * x1842;
            let x2164 = x2162 + x2163;
            let x2165 = x1878 * x2164;
            let x2166 = x1736 * x1836;
            let x2168 = x580 * x1842;
            let x2169 = x2168 - x2166;
            let x2170 = x1878 * x2169;
            let x2171 = x138 * x1836;
            let x2172 = x1878 * x2171;
            let x2173 = x139 * x1836;
            let x2174 = x1878 * x2173;
            let x2180 = x187 - x186;
            let x2195 = x1758 - x1757;
            let x2196 = x190 + x2195;
            let x2197 = x2196 - x191;
            let x2198 = 2.0 * x2197;
            let x2199 = x1748 + x1752;
            let x2201 = x1753 - x2199;
            let x2202 = x1749 + x2201;
            let x2203 = 2.0 * x2202;
            let x2206 = x1740 - x1744;
            let x2207 = x2206 - x1741;
            let x2208 = x1745 + x2207;
            let x2209 = 2.0 * x2208;
            let x2210 = 2.0 * x2198;
            let x2211 = 2.0 * x2203;
            let x2212 = 2.0 * x2209;
            let x2213 = x1796 + x1799;
            let x2215 = x1799 - x2213;
            let x2216 = x1796 + x2215;
            let x2217 = 2.0 * x2216;
            let x2220 = x1790 - x1793;
            let x2221 = x2220 - x1790;
            let x2222 = x1793 + x2221;
            let x2223 = 2.0 * x2222;
            let x2224 = 2.0 * x2217;
            let x2225 = 2.0 * x2223;
            let x2226 = x507 * x2210;
            let x2227 = 0.01 * x2226;
            let x2228 = x229 * x2211;
            let x2229 = x136 * x2224;
            let x2230 = x2228 + x2229;
            let x2231 = 0.01 * x2230;
            let x2232 = x230 * x2212;
            let x2233 = x137 * x2225;
            let x2234 = x2232 + x2233;
            let x2235 = 0.01 * x2234;
            let x2236 = x2227 + x2231;
            let x2237 = x2235 + x2236;
            let x2238 = 0.5 * x2237;
            let x2239 = x505 * x2210;
            let x2240 = 0.01 * x2239;
            let x2241 = x230 * x2211;
            let x2242 = x137 * x2224;
            let x2243 = x2241 + x2242;
            let x2244 = 0.01 * x2243;
            let x2246 = x229 * x2212;
            let x2247 = x136 * x2225;
            let x2248 = x2246 + x2247;
            let x2249 = 0.01 * x2248;
            let x2250 = x2240 - x2244;
            let x2251 = x2249 + x2250;
            let x2252 = 0.5 * x2251;
            let x2253 = x230 * x2210;
            let x2254 = 0.01 * x2253;
            let x2255 = x505 * x2211;
            let x2256 = x339 * x2224;
            let x2257 = x2255 + x2256;
            let x2258 = 0.01 * x2257;
            let x2259 = x507 * x2212;
            let x2260 = x341 * x2225;
            let x2261 = x2259 + x2260;
            let x2262 = 0.01 * x2261;
            let x2264 = x2254 + x2258;
            let x2265 = x2264 - x2262;
            let x2266 = 0.5 * x2265;
            let x2267 = x229 * x2210;
            let x2268 = 0.01 * x2267;
            let x2270 = x507 * x2211;
            let x2271 = x341 * x2224;
            let x2272 = x2270 + x2271;
            let x2273 = 0.01 * x2272;
            let x2274 = x505 * x2212;
            let x2275 = x339 * x2225;
            let x2276 = x2274 + x2275;
            let x2277 = 0.01 * x2276;
            let x2278 = x2273 - x2268;
            let x2279 = x2277 + x2278;
            let x2280 = 0.5 * x2279;
            let x2281 = x488 + x492;
            let x2282 = x789 + x2281;
            let x2283 = x790 + x2282;
            let x2284 = 0.01 * x2228;
            let x2285 = 0.01 * x2232;
            let x2286 = x2227 + x2284;
            let x2287 = x2285 + x2286;
            let x2288 = 0.5 * x2287;
            let x2289 = x2238 + x2288;
            let x2290 = q[1] * 0.04;
            let x2291 = x2283 * x2290;
            let x2293 = x2289 - x2291;
            let x2295 = 0.01 * x2241;
            let x2296 = 0.01 * x2246;
            let x2298 = x2295 - x2240;
            let x2299 = x2298 - x2296;
            let x2300 = 0.5 * x2299;
            let x2302 = x2300 - x2252;
            let x2303 = q[2] * 0.04;
            let x2304 = x2283 * x2303;
            let x2306 = x2302 - x2304;
            let x2307 = 0.01 * x2255;
            let x2308 = 0.01 * x2259;
            let x2309 = x2254 + x2307;
            let x2311 = x2308 - x2309;
            let x2312 = 0.5 * x2311;
            let x2314 = x2312 - x2266;
            let x2315 = x802 * x2283;
            let x2317 = x2314 - x2315;
            let x2318 = 0.01 * x2270;
            let x2320 = 0.01 * x2274;
            let x2322 = x2268 - x2318;
            let x2323 = x2322 - x2320;
            let x2324 = 0.5 * x2323;
            let x2326 = x2324 - x2280;
            let x2327 = x821 * x2283;
            let x2329 = x2326 - x2327;
            let x2331 = x1777 + x2180;
            let x2332 = x2331 - x1778;
            let x2333 = 2.0 * x2332;
            let x2334 = x1861 + x1865;
            let x2336 = x1866 - x2334;
            let x2337 = x1862 + x2336;
            let x2338 = 2.0 * x2337;
            let x2340 = x1767 - x1771;
            let x2341 = x2340 - x1768;
            let x2342 = x1772 + x2341;
            let x2343 = 2.0 * x2342;
            let x2344 = 2.0 * x2333;
            let x2345 = 2.0 * x2338;
            let x2346 = 2.0 * x2343;
            let x2347 = qd[6] * qd[8];
            let x2348 = qd[5] * qd[7];
            let x2350 = x2347 + x2348;
            let x2352 = x2348 - x2350;
            let x2353 = x2347 + x2352;
            let x2354 = 2.0 * x2353;
            let x2356 = x1812 - x1815;
            let x2357 = x2356 - x1812;
            let x2358 = x1815 + x2357;
            let x2359 = 2.0 * x2358;
            let x2360 = 2.0 * x2354;
            let x2361 = 2.0 * x2359;
            let x2362 = x232 * x2344;
            let x2363 = 0.1 * x2362;
            let x2364 = x891 * x2345;
            let x2365 = x1735 * x2360;
            let x2366 = x2364 + x2365;
            let x2368 = x893 * x2346;
            let x2369 = x1736 * x2361;
            let x2370 = x2368 + x2369;
            let x2371 = 0.3 * x2370;
            let x2375 = x231 * x2344;
            let x2376 = 0.1 * x2375;
            let x2377 = x893 * x2345;
            let x2378 = x1736 * x2360;
            let x2379 = x2377 + x2378;
            let x2382 = x891 * x2346;
            let x2383 = x1735 * x2361;
            let x2384 = x2382 + x2383;
            let x2385 = 0.3 * x2384;
            let x2389 = x893 * x2344;
            let x2390 = 0.1 * x2389;
            let x2391 = x231 * x2345;
            let x2392 = x138 * x2360;
            let x2393 = x2391 + x2392;
            let x2395 = x232 * x2346;
            let x2396 = x139 * x2361;
            let x2397 = x2395 + x2396;
            let x2398 = 0.3 * x2397;
            let x2403 = x891 * x2344;
            let x2404 = 0.1 * x2403;
            let x2406 = x232 * x2345;
            let x2407 = x139 * x2360;
            let x2408 = x2406 + x2407;
            let x2410 = x231 * x2346;
            let x2411 = x138 * x2361;
            let x2412 = x2410 + x2411;
            let x2413 = 0.3 * x2412;
            let x2417 = x791 + x792;
            let x2418 = x876 + x2417;
            let x2419 = x879 + x2418;
            let x2421 = 0.3 * x2368;
            let x2432 = 0.3 * x2382;
            let x2444 = 0.3 * x2395;
            let x2457 = 0.3 * x2410;
            let x2474 = t * k[1];
            let x2475 = x2474.sin();
            let x2476 = k[0] * x2475;
            let x2480 = t * k[4];
            let x2481 = x2480.cos();
            let x2482 = k[3] * x2481;
            let x2484 = x13 * k[5];
            let x2499 = x1855 * k[6];
            let x2501 = x2476 - x2499;
            let x2503 = x1879 * k[7];
            let x2505 = x2482 - x2503;
            let x2611 = x1844 * k[9];
            let x2613 = x2501 - x2611;
            let x2614 = x2157 * x2613;
            let x2615 = x1848 * k[10];
            let x2617 = x2505 - x2615;
            let x2618 = x2165 * x2617;
            let x2619 = x2170 * x2617;
            let x2620 = x2172 * x2617;
            let x2621 = x2174 * x2617;
            let x2622 = x1735 * x2484;
            let x2624 = x1736 * x2484;
            let x2625 = x138 * x2484;
            let x2626 = x139 * x2484;
            let x2627 = k[2] + x2614;
            let x2628 = x2618 - x2622;
            let x2629 = x2619 + x2624;
            let x2630 = x2620 + x2625;
            let x2631 = x2621 + x2626;
            let x2633 = x2366 * k[8];
            let x2634 = x2363 + x2633;
            let x2635 = x2371 + x2634;
            let x2636 = 0.5 * x2635;
            let x2637 = x2379 * k[8];
            let x2639 = x2376 - x2637;
            let x2640 = x2385 + x2639;
            let x2641 = 0.5 * x2640;
            let x2642 = x2393 * k[8];
            let x2643 = x2390 + x2642;
            let x2644 = x2643 - x2398;
            let x2645 = 0.5 * x2644;
            let x2646 = x2408 * k[8];
            let x2647 = x2646 - x2404;
            let x2648 = x2413 + x2647;
            let x2649 = 0.5 * x2648;
            let x2650 = x2364 * k[8];
            let x2651 = x2363 + x2650;
            let x2652 = x2421 + x2651;
            let x2653 = 0.5 * x2652;
            let x2654 = x2636 + x2653;
            let x2655 = q[5] * k[14];
            let x2656 = x2419 * x2655;
            let x2658 = x2654 - x2656;
            let x2659 = x2377 * k[8];
            let x2660 = x2659 - x2376;
            let x2661 = x2660 - x2432;
            let x2662 = 0.5 * x2661;
            let x2664 = x2662 - x2641;
            let x2665 = q[6] * k[14];
            let x2666 = x2419 * x2665;
            let x2668 = x2664 - x2666;
            let x2669 = x2391 * k[8];
            let x2670 = x2390 + x2669;
            let x2672 = x2444 - x2670;
            let x2673 = 0.5 * x2672;
            let x2675 = x2673 - x2645;
            let x2676 = q[7] * k[14];
            let x2677 = x2419 * x2676;
            let x2679 = x2675 - x2677;
            let x2680 = x2406 * k[8];
            let x2682 = x2404 - x2680;
            let x2683 = x2682 - x2457;
            let x2684 = 0.5 * x2683;
            let x2686 = x2684 - x2649;
            let x2687 = q[8] * k[14];
            let x2688 = x2419 * x2687;
            let x2690 = x2686 - x2688;
            let x2691 = x2628 + x2658;
            let x2692 = x2629 + x2668;
            let x2693 = x2630 + x2679;
            let x2694 = x2690 - x2631;
            out[0] = x2627;
            out[1] = x2293;
            out[2] = x2306;
            out[3] = x2317;
            out[4] = x2329;
            out[5] = x2691;
            out[6] = x2692;
            out[7] = x2693;
            out[8] = x2694;
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
            let k: &[f64; 15] = k.try_into().expect("k must have 15 entries");
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
            k: &[f64; 15],
            q: &[f64; 9],
            qd: &[f64; 9],
            t: f64,
            s: &mut [f64; 94],
        ) {
            let x13 = t.sin();
            s[0] = x13;
            let x38 = q[5] * q[5];
            s[1] = x38;
            let x39 = q[6] * q[6];
            s[2] = x39;
            let x138 = q[5] * 2.0;
            s[3] = x138;
            let x139 = q[6] * 2.0;
            s[4] = x139;
            let x166 = x138 * qd[5];
            s[5] = x166;
            let x167 = x139 * qd[6];
            s[6] = x167;
            let x186 = q[6] * qd[5];
            s[7] = x186;
            let x187 = q[5] * qd[6];
            s[8] = x187;
            let x232 = 2.0 * qd[6];
            s[9] = x232;
            let x580 = 2.0 * x139;
            s[10] = x580;
            let x791 = qd[5] * qd[5];
            s[11] = x791;
            let x792 = qd[6] * qd[6];
            s[12] = x792;
            let x876 = qd[7] * qd[7];
            s[13] = x876;
            let x879 = qd[8] * qd[8];
            s[14] = x879;
            let x891 = 2.0 * qd[7];
            s[15] = x891;
            let x893 = 2.0 * qd[8];
            s[16] = x893;
            let x1717 = x38 + x39;
            s[17] = x1717;
            let x1735 = 2.0 * q[7];
            s[18] = x1735;
            let x1736 = 2.0 * q[8];
            s[19] = x1736;
            let x1766 = x166 + x167;
            s[20] = x1766;
            let x1767 = q[7] * qd[6];
            s[21] = x1767;
            let x1768 = q[6] * qd[7];
            s[22] = x1768;
            let x1771 = q[8] * qd[5];
            s[23] = x1771;
            let x1772 = q[5] * qd[8];
            s[24] = x1772;
            let x1777 = q[8] * qd[7];
            s[25] = x1777;
            let x1778 = q[7] * qd[8];
            s[26] = x1778;
            let x1812 = qd[6] * qd[7];
            s[27] = x1812;
            let x1815 = qd[5] * qd[8];
            s[28] = x1815;
            let x1835 = 2.0 * x1717;
            s[29] = x1835;
            let x1836 = x1835 - 1.0;
            s[30] = x1836;
            let x1837 = q[6] * q[8];
            s[31] = x1837;
            let x1838 = 2.0 * x1837;
            s[32] = x1838;
            let x1839 = q[5] * q[7];
            s[33] = x1839;
            let x1840 = 2.0 * x1839;
            s[34] = x1840;
            let x1842 = x1838 - x1840;
            s[35] = x1842;
            let x1847 = -x1842;
            s[36] = x1847;
            let x1848 = x1847.atan2(x1836);
            s[37] = x1848;
            let x1860 = 2.0 * x1766;
            s[38] = x1860;
            let x1861 = q[8] * qd[6];
            s[39] = x1861;
            let x1862 = q[6] * qd[8];
            s[40] = x1862;
            let x1863 = x1861 + x1862;
            s[41] = x1863;
            let x1864 = 2.0 * x1863;
            s[42] = x1864;
            let x1865 = q[7] * qd[5];
            s[43] = x1865;
            let x1866 = q[5] * qd[7];
            s[44] = x1866;
            let x1867 = x1865 + x1866;
            s[45] = x1867;
            let x1868 = 2.0 * x1867;
            s[46] = x1868;
            let x1870 = x1864 - x1868;
            s[47] = x1870;
            let x1871 = x1836 * x1836;
            s[48] = x1871;
            let x1872 = x1842 * x1842;
            s[49] = x1872;
            let x1873 = x1871 + x1872;
            s[50] = x1873;
            let x1874 = x1836 * x1870;
            s[51] = x1874;
            let x1876 = x1842 * x1860;
            s[52] = x1876;
            let x1877 = x1876 - x1874;
            s[53] = x1877;
            let x1878 = 1.0 / x1873;
            s[54] = x1878;
            let x1879 = x1877 * x1878;
            s[55] = x1879;
            let x2180 = x187 - x186;
            s[56] = x2180;
            let x2331 = x1777 + x2180;
            s[57] = x2331;
            let x2332 = x2331 - x1778;
            s[58] = x2332;
            let x2333 = 2.0 * x2332;
            s[59] = x2333;
            let x2334 = x1861 + x1865;
            s[60] = x2334;
            let x2336 = x1866 - x2334;
            s[61] = x2336;
            let x2337 = x1862 + x2336;
            s[62] = x2337;
            let x2338 = 2.0 * x2337;
            s[63] = x2338;
            let x2340 = x1767 - x1771;
            s[64] = x2340;
            let x2341 = x2340 - x1768;
            s[65] = x2341;
            let x2342 = x1772 + x2341;
            s[66] = x2342;
            let x2343 = 2.0 * x2342;
            s[67] = x2343;
            let x2344 = 2.0 * x2333;
            s[68] = x2344;
            let x2345 = 2.0 * x2338;
            s[69] = x2345;
            let x2346 = 2.0 * x2343;
            s[70] = x2346;
            let x2347 = qd[6] * qd[8];
            s[71] = x2347;
            let x2348 = qd[5] * qd[7];
            s[72] = x2348;
            let x2350 = x2347 + x2348;
            s[73] = x2350;
            let x2352 = x2348 - x2350;
            s[74] = x2352;
            let x2353 = x2347 + x2352;
            s[75] = x2353;
            let x2354 = 2.0 * x2353;
            s[76] = x2354;
            let x2356 = x1812 - x1815;
            s[77] = x2356;
            let x2357 = x2356 - x1812;
            s[78] = x2357;
            let x2358 = x1815 + x2357;
            s[79] = x2358;
            let x2359 = 2.0 * x2358;
            s[80] = x2359;
            let x2360 = 2.0 * x2354;
            s[81] = x2360;
            let x2361 = 2.0 * x2359;
            s[82] = x2361;
            let x2417 = x791 + x792;
            s[83] = x2417;
            let x2418 = x876 + x2417;
            s[84] = x2418;
            let x2419 = x879 + x2418;
            s[85] = x2419;
            let x2480 = t * k[4];
            s[86] = x2480;
            let x2481 = x2480.cos();
            s[87] = x2481;
            let x2482 = k[3] * x2481;
            s[88] = x2482;
            let x2484 = x13 * k[5];
            s[89] = x2484;
            let x2503 = x1879 * k[7];
            s[90] = x2503;
            let x2505 = x2482 - x2503;
            s[91] = x2505;
            let x2615 = x1848 * k[10];
            s[92] = x2615;
            let x2617 = x2505 - x2615;
            s[93] = x2617;
        }
        #[inline(never)]
        fn eval_newton_part_0(
            k: &[f64; 15],
            q: &[f64; 9],
            qd: &[f64; 9],
            t: f64,
            s: &[f64; 94],
            phi: &mut [f64; 7],
            phi_q: &mut [f64; 28],
            mass: &mut [f64; 33],
            force: &mut [f64; 9],
        ) {
            let x36 = q[3] * q[3];
            let x37 = q[4] * q[4];
            let x63 = q[5] * q[6];
            let x64 = 2.0 * x63;
            let x65 = q[3] * q[4];
            let x67 = 2.0 * x65;
            let x136 = q[3] * 2.0;
            let x137 = q[4] * 2.0;
            let x140 = -s[3];
            let x141 = -x136;
            let x190 = q[4] * qd[3];
            let x191 = q[3] * qd[4];
            let x229 = 2.0 * qd[3];
            let x230 = 2.0 * qd[4];
            let x330 = 1.0 + q[0];
            let x331 = x330 * x330;
            let x332 = q[1] * q[1];
            let x333 = q[2] * q[2];
            let x337 = 2.0 * x330;
            let x338 = qd[0] * x337;
            let x339 = q[1] * 2.0;
            let x341 = q[2] * 2.0;
            let x488 = qd[1] * qd[1];
            let x492 = qd[2] * qd[2];
            let x505 = 2.0 * qd[1];
            let x507 = 2.0 * qd[2];
            let x518 = -s[4];
            let x576 = 2.0 * x137;
            let x578 = 2.0 * s[3];
            let x582 = x137 * x576;
            let x584 = 0.01 * x582;
            let x586 = s[3] * x578;
            let x590 = s[4] * s[10];
            let x600 = x36 * 0.04;
            let x602 = 2.0 * x136;
            let x603 = x137 * x602;
            let x604 = 0.01 * x603;
            let x605 = s[3] * s[10];
            let x609 = s[4] * x578;
            let x615 = x65 * 0.04;
            let x645 = x136 * x576;
            let x647 = 0.01 * x645;
            let x655 = x136 * x602;
            let x656 = 0.01 * x655;
            let x660 = x37 * 0.04;
            let x789 = qd[3] * qd[3];
            let x790 = qd[4] * qd[4];
            let x802 = q[3] * 0.04;
            let x821 = q[4] * 0.04;
            let x1700 = x332 + x333;
            let x1701 = q[2] * q[3];
            let x1702 = 2.0 * x1701;
            let x1703 = q[1] * q[4];
            let x1704 = 2.0 * x1703;
            let x1705 = q[2] * q[4];
            let x1706 = 2.0 * x1705;
            let x1707 = q[1] * q[3];
            let x1708 = 2.0 * x1707;
            let x1709 = x1702 + x1704;
            let x1710 = q[1] * q[2];
            let x1711 = 2.0 * x1710;
            let x1713 = x1706 - x1708;
            let x1714 = x67 + x1711;
            let x1715 = q[7] * q[7];
            let x1716 = q[8] * q[8];
            let x1718 = q[6] * q[7];
            let x1719 = 2.0 * x1718;
            let x1720 = q[5] * q[8];
            let x1721 = 2.0 * x1720;
            let x1723 = x1719 - x1721;
            let x1724 = q[7] * q[8];
            let x1725 = 2.0 * x1724;
            let x1726 = x64 + x1725;
            let x1727 = -x1726;
            let x1728 = x36 + x1700;
            let x1729 = x37 + x1728;
            let x1730 = x1729 - 1.0;
            let x1731 = x1715 + s[17];
            let x1732 = x1716 + x1731;
            let x1733 = x1732 - 1.0;
            let x1734 = -x339;
            let x1737 = -s[19];
            let x1738 = -s[18];
            let x1740 = q[3] * qd[2];
            let x1741 = q[2] * qd[3];
            let x1744 = q[4] * qd[1];
            let x1745 = q[1] * qd[4];
            let x1748 = q[4] * qd[2];
            let x1749 = q[2] * qd[4];
            let x1752 = q[3] * qd[1];
            let x1753 = q[1] * qd[3];
            let x1757 = q[2] * qd[1];
            let x1758 = q[1] * qd[2];
            let x1790 = qd[2] * qd[3];
            let x1793 = qd[1] * qd[4];
            let x1796 = qd[2] * qd[4];
            let x1799 = qd[1] * qd[3];
            let x1843 = x331.sqrt();
            let x1844 = x1843 - 1.0;
            let x1853 = 2.0 * x1843;
            let x1854 = 1.0 / x1853;
            let x1855 = x338 * x1854;
            let x1894 = 2.0 * x341;
            let x1895 = x341 * x1894;
            let x1896 = 0.01 * x1895;
            let x1897 = x656 + x1896;
            let x1898 = x584 + x1897;
            let x1899 = 0.5 * x1898;
            let x1900 = x332 * 0.04;
            let x1901 = x1899 + x1900;
            let x1902 = 2.0 * x339;
            let x1903 = x341 * x1902;
            let x1904 = 0.01 * x1903;
            let x1905 = x1904 - x647;
            let x1906 = x604 + x1905;
            let x1907 = 0.5 * x1906;
            let x1909 = 0.04 * x1710;
            let x1910 = x1909 - x1907;
            let x1911 = x341 * x576;
            let x1912 = 0.01 * x1911;
            let x1913 = x136 * x1902;
            let x1914 = 0.01 * x1913;
            let x1915 = x137 * x1894;
            let x1916 = 0.01 * x1915;
            let x1918 = x1912 + x1914;
            let x1919 = x1918 - x1916;
            let x1920 = 0.5 * x1919;
            let x1922 = 0.04 * x1707;
            let x1923 = x1922 - x1920;
            let x1924 = x341 * x602;
            let x1925 = 0.01 * x1924;
            let x1927 = x136 * x1894;
            let x1928 = 0.01 * x1927;
            let x1929 = x137 * x1902;
            let x1930 = 0.01 * x1929;
            let x1931 = x1928 - x1925;
            let x1932 = x1930 + x1931;
            let x1933 = 0.5 * x1932;
            let x1935 = 0.04 * x1703;
            let x1936 = x1935 - x1933;
            let x1937 = x339 * x1894;
            let x1938 = 0.01 * x1937;
            let x1940 = x604 - x1938;
            let x1941 = x1940 - x647;
            let x1942 = 0.5 * x1941;
            let x1943 = x1909 + x1942;
            let x1944 = x339 * x1902;
            let x1945 = 0.01 * x1944;
            let x1946 = x584 + x1945;
            let x1947 = x656 + x1946;
            let x1948 = 0.5 * x1947;
            let x1949 = x333 * 0.04;
            let x1950 = x1948 + x1949;
            let x1951 = x339 * x576;
            let x1952 = 0.01 * x1951;
            let x1955 = x1952 - x1930;
            let x1956 = x1955 - x1928;
            let x1957 = 0.5 * x1956;
            let x1958 = 0.04 * x1701;
            let x1959 = x1957 + x1958;
            let x1960 = x339 * x602;
            let x1961 = 0.01 * x1960;
            let x1962 = x1916 + x1961;
            let x1964 = x1914 - x1962;
            let x1965 = 0.5 * x1964;
            let x1966 = 0.04 * x1705;
            let x1967 = x1965 + x1966;
            let x1968 = x1912 - x1962;
            let x1969 = 0.5 * x1968;
            let x1970 = x1922 + x1969;
            let x1972 = x1930 - x1952;
            let x1973 = x1972 - x1925;
            let x1974 = 0.5 * x1973;
            let x1975 = x1958 + x1974;
            let x1976 = x1896 + x1946;
            let x1977 = 0.5 * x1976;
            let x1978 = x600 + x1977;
            let x1980 = x1938 - x604;
            let x1981 = x1980 - x1904;
            let x1982 = 0.5 * x1981;
            let x1983 = x615 + x1982;
            let x1984 = x1931 - x1952;
            let x1985 = 0.5 * x1984;
            let x1986 = x1935 + x1985;
            let x1988 = x1961 - x1918;
            let x1989 = 0.5 * x1988;
            let x1990 = x1966 + x1989;
            let x1991 = x1905 - x1938;
            let x1992 = 0.5 * x1991;
            let x1993 = x615 + x1992;
            let x1994 = x1897 + x1945;
            let x1995 = 0.5 * x1994;
            let x1996 = x660 + x1995;
            let x1997 = 2.0 * s[18];
            let x1998 = 2.0 * s[19];
            let x1999 = 0.1 * x590;
            let x2000 = s[18] * x1997;
            let x2002 = s[19] * x1998;
            let x2003 = 0.3 * x2002;
            let x2009 = 0.1 * x609;
            let x2010 = s[18] * x1998;
            let x2013 = s[19] * x1997;
            let x2014 = 0.3 * x2013;
            let x2021 = s[4] * x1998;
            let x2022 = 0.1 * x2021;
            let x2023 = x578 * s[18];
            let x2025 = s[10] * s[19];
            let x2026 = 0.3 * x2025;
            let x2034 = s[4] * x1997;
            let x2035 = 0.1 * x2034;
            let x2037 = s[10] * s[18];
            let x2039 = x578 * s[19];
            let x2040 = 0.3 * x2039;
            let x2047 = 0.1 * x605;
            let x2050 = 0.3 * x2010;
            let x2056 = 0.1 * x586;
            let x2058 = 0.3 * x2000;
            let x2064 = s[3] * x1998;
            let x2065 = 0.1 * x2064;
            let x2068 = 0.3 * x2037;
            let x2075 = s[3] * x1997;
            let x2076 = 0.1 * x2075;
            let x2078 = 0.3 * x2023;
            let x2085 = 0.1 * x2025;
            let x2087 = 0.3 * x2021;
            let x2093 = 0.1 * x2039;
            let x2096 = 0.3 * x2034;
            let x2102 = 0.1 * x2002;
            let x2104 = 0.3 * x590;
            let x2110 = 0.1 * x2013;
            let x2113 = 0.3 * x609;
            let x2120 = 0.1 * x2037;
            let x2123 = 0.3 * x2064;
            let x2129 = 0.1 * x2023;
            let x2131 = 0.3 * x2075;
            let x2137 = 0.1 * x2010;
            let x2140 = 0.3 * x605;
            let x2146 = 0.1 * x2000;
            let x2148 = 0.3 * x586;
            let x2157 = x337 * x1854;
            let x2162 = s[18] * s[30];
            let x2163 = x578 * s[35];
            let x2164 = x2162 + x2163;
            let x2165 = s[54] * x2164;
            let x2195 = x1758 - x1757;
            let x2196 = x190 + x2195;
            let x2197 = x2196 - x191;
            let x2198 = 2.0 * x2197;
            let x2199 = x1748 + x1752;
            let x2201 = x1753 - x2199;
            let x2202 = x1749 + x2201;
            let x2203 = 2.0 * x2202;
            let x2206 = x1740 - x1744;
            let x2207 = x2206 - x1741;
            let x2208 = x1745 + x2207;
            let x2209 = 2.0 * x2208;
            let x2210 = 2.0 * x2198;
            let x2211 = 2.0 * x2203;
            let x2212 = 2.0 * x2209;
            let x2213 = x1796 + x1799;
            let x2215 = x1799 - x2213;
            let x2216 = x1796 + x2215;
            let x2217 = 2.0 * x2216;
            let x2220 = x1790 - x1793;
            let x2221 = x2220 - x1790;
            let x2222 = x1793 + x2221;
            let x2223 = 2.0 * x2222;
            let x2224 = 2.0 * x2217;
            let x2225 = 2.0 * x2223;
            let x2226 = x507 * x2210;
            let x2227 = 0.01 * x2226;
            let x2228 = x229 * x2211;
            let x2229 = x136 * x2224;
            let x2230 = x2228 + x2229;
            let x2231 = 0.01 * x2230;
            let x2232 = x230 * x2212;
            let x2233 = x137 * x2225;
            let x2234 = x2232 + x2233;
            let x2235 = 0.01 * x2234;
            let x2236 = x2227 + x2231;
            let x2237 = x2235 + x2236;
            let x2238 = 0.5 * x2237;
            let x2239 = x505 * x2210;
            let x2240 = 0.01 * x2239;
            let x2241 = x230 * x2211;
            let x2242 = x137 * x2224;
            let x2243 = x2241 + x2242;
            let x2244 = 0.01 * x2243;
            let x2246 = x229 * x2212;
            let x2247 = x136 * x2225;
            let x2248 = x2246 + x2247;
            let x2249 = 0.01 * x2248;
            let x2250 = x2240 - x2244;
            let x2251 = x2249 + x2250;
            let x2252 = 0.5 * x2251;
            let x2253 = x230 * x2210;
            let x2254 = 0.01 * x2253;
            let x2255 = x505 * x2211;
            let x2256 = x339 * x2224;
            let x2257 = x2255 + x2256;
            let x2258 = 0.01 * x2257;
            let x2259 = x507 * x2212;
            let x2260 = x341 * x2225;
            let x2261 = x2259 + x2260;
            let x2262 = 0.01 * x2261;
            let x2264 = x2254 + x2258;
            let x2265 = x2264 - x2262;
            let x2266 = 0.5 * x2265;
            let x2267 = x229 * x2210;
            let x2268 = 0.01 * x2267;
            let x2270 = x507 * x2211;
            let x2271 = x341 * x2224;
            let x2272 = x2270 + x2271;
            let x2273 = 0.01 * x2272;
            let x2274 = x505 * x2212;
            let x2275 = x339 * x2225;
            let x2276 = x2274 + x2275;
            let x2277 = 0.01 * x2276;
            let x2278 = x2273 - x2268;
            let x2279 = x2277 + x2278;
            let x2280 = 0.5 * x2279;
            let x2281 = x488 + x492;
            let x2282 = x789 + x2281;
            let x2283 = x790 + x2282;
            let x2284 = 0.01 * x2228;
            let x2285 = 0.01 * x2232;
            let x2286 = x2227 + x2284;
            let x2287 = x2285 + x2286;
            let x2288 = 0.5 * x2287;
            let x2289 = x2238 + x2288;
            let x2290 = q[1] * 0.04;
            let x2291 = x2283 * x2290;
            let x2293 = x2289 - x2291;
            let x2295 = 0.01 * x2241;
            let x2296 = 0.01 * x2246;
            let x2298 = x2295 - x2240;
            let x2299 = x2298 - x2296;
            let x2300 = 0.5 * x2299;
            let x2302 = x2300 - x2252;
            let x2303 = q[2] * 0.04;
            let x2304 = x2283 * x2303;
            let x2306 = x2302 - x2304;
            let x2307 = 0.01 * x2255;
            let x2308 = 0.01 * x2259;
            let x2309 = x2254 + x2307;
            let x2311 = x2308 - x2309;
            let x2312 = 0.5 * x2311;
            let x2314 = x2312 - x2266;
            let x2315 = x802 * x2283;
            let x2317 = x2314 - x2315;
            let x2318 = 0.01 * x2270;
            let x2320 = 0.01 * x2274;
            let x2322 = x2268 - x2318;
            let x2323 = x2322 - x2320;
            let x2324 = 0.5 * x2323;
            let x2326 = x2324 - x2280;
            let x2327 = x821 * x2283;
            let x2329 = x2326 - x2327;
            let x2362 = s[9] * s[68];
            let x2363 = 0.1 * x2362;
            let x2364 = s[15] * s[69];
            let x2365 = s[18] * s[81];
            let x2366 = x2364 + x2365;
            let x2368 = s[16] * s[70];
            let x2369 = s[19] * s[82];
            let x2370 = x2368 + x2369;
            let x2371 = 0.3 * x2370;
            let x2421 = 0.3 * x2368;
            let x2474 = t * k[1];
            let x2475 = x2474.sin();
            let x2476 = k[0] * x2475;
            let x2499 = x1855 * k[6];
            let x2501 = x2476 - x2499;
            let x2511 = x2000 * k[8];
            let x2512 = x1999 + x2511;
            let x2513 = x2003 + x2512;
            let x2514 = 0.5 * x2513;
            let x2515 = s[1] * k[14];
            let x2516 = x2514 + x2515;
            let x2517 = x2010 * k[8];
            let x2519 = x2009 - x2517;
            let x2520 = x2014 + x2519;
            let x2521 = 0.5 * x2520;
            let x2523 = x63 * k[14];
            let x2524 = x2523 - x2521;
            let x2525 = x2023 * k[8];
            let x2526 = x2022 + x2525;
            let x2527 = x2526 - x2026;
            let x2528 = 0.5 * x2527;
            let x2530 = s[33] * k[14];
            let x2531 = x2530 - x2528;
            let x2532 = x2037 * k[8];
            let x2533 = x2532 - x2035;
            let x2534 = x2040 + x2533;
            let x2535 = 0.5 * x2534;
            let x2537 = x1720 * k[14];
            let x2538 = x2537 - x2535;
            let x2539 = x2013 * k[8];
            let x2540 = x2539 - x2047;
            let x2541 = x2540 - x2050;
            let x2542 = 0.5 * x2541;
            let x2543 = x2523 + x2542;
            let x2544 = x2002 * k[8];
            let x2545 = x2056 + x2544;
            let x2546 = x2058 + x2545;
            let x2547 = 0.5 * x2546;
            let x2548 = s[2] * k[14];
            let x2549 = x2547 + x2548;
            let x2550 = x2039 * k[8];
            let x2552 = x2065 - x2550;
            let x2553 = x2552 - x2068;
            let x2554 = 0.5 * x2553;
            let x2555 = x1718 * k[14];
            let x2556 = x2554 + x2555;
            let x2557 = x2025 * k[8];
            let x2558 = x2076 + x2557;
            let x2560 = x2078 - x2558;
            let x2561 = 0.5 * x2560;
            let x2562 = s[31] * k[14];
            let x2563 = x2561 + x2562;
            let x2564 = x2075 * k[8];
            let x2565 = x2085 + x2564;
            let x2567 = x2087 - x2565;
            let x2568 = 0.5 * x2567;
            let x2569 = x2530 + x2568;
            let x2570 = x2064 * k[8];
            let x2572 = x2093 - x2570;
            let x2573 = x2572 - x2096;
            let x2574 = 0.5 * x2573;
            let x2575 = x2555 + x2574;
            let x2576 = x586 * k[8];
            let x2577 = x2102 + x2576;
            let x2578 = x2104 + x2577;
            let x2579 = 0.5 * x2578;
            let x2580 = x1715 * k[14];
            let x2581 = x2579 + x2580;
            let x2582 = x605 * k[8];
            let x2583 = x2582 - x2110;
            let x2584 = x2583 - x2113;
            let x2585 = 0.5 * x2584;
            let x2586 = x1724 * k[14];
            let x2587 = x2585 + x2586;
            let x2588 = x2034 * k[8];
            let x2590 = x2120 - x2588;
            let x2591 = x2590 - x2123;
            let x2592 = 0.5 * x2591;
            let x2593 = x2537 + x2592;
            let x2594 = x2021 * k[8];
            let x2595 = x2129 + x2594;
            let x2597 = x2131 - x2595;
            let x2598 = 0.5 * x2597;
            let x2599 = x2562 + x2598;
            let x2600 = x609 * k[8];
            let x2601 = x2600 - x2137;
            let x2602 = x2601 - x2140;
            let x2603 = 0.5 * x2602;
            let x2604 = x2586 + x2603;
            let x2605 = x590 * k[8];
            let x2606 = x2146 + x2605;
            let x2607 = x2148 + x2606;
            let x2608 = 0.5 * x2607;
            let x2609 = x1716 * k[14];
            let x2610 = x2608 + x2609;
            let x2611 = x1844 * k[9];
            let x2613 = x2501 - x2611;
            let x2614 = x2157 * x2613;
            let x2618 = x2165 * s[93];
            let x2622 = s[18] * s[89];
            let x2627 = k[2] + x2614;
            let x2628 = x2618 - x2622;
            let x2633 = x2366 * k[8];
            let x2634 = x2363 + x2633;
            let x2635 = x2371 + x2634;
            let x2636 = 0.5 * x2635;
            let x2650 = x2364 * k[8];
            let x2651 = x2363 + x2650;
            let x2652 = x2421 + x2651;
            let x2653 = 0.5 * x2652;
            let x2654 = x2636 + x2653;
            let x2655 = q[5] * k[14];
            let x2656 = s[85] * x2655;
            let x2658 = x2654 - x2656;
            let x2691 = x2628 + x2658;
            phi[0] = x1709;
            phi_q[0] = x137;
            phi_q[1] = x136;
            phi_q[2] = x341;
            phi_q[3] = x339;
            phi[1] = x1713;
            phi_q[4] = x141;
            phi_q[5] = x137;
            phi_q[6] = x1734;
            phi_q[7] = x341;
            phi[2] = x1714;
            phi_q[8] = x341;
            phi_q[9] = x339;
            phi_q[10] = x137;
            phi_q[11] = x136;
            phi[3] = x1723;
            phi_q[12] = x1737;
            phi_q[13] = s[18];
            phi_q[14] = s[4];
            phi_q[15] = x140;
            phi[4] = x1727;
            phi_q[16] = x518;
            phi_q[17] = x140;
            phi_q[18] = x1737;
            phi_q[19] = x1738;
            phi[5] = x1730;
            phi_q[20] = x339;
            phi_q[21] = x341;
            phi_q[22] = x136;
            phi_q[23] = x137;
            phi[6] = x1733;
            phi_q[24] = s[3];
            phi_q[25] = s[4];
            phi_q[26] = s[18];
            phi_q[27] = s[19];
            mass[0] = k[13];
            mass[1] = x1901;
            mass[2] = x1910;
            mass[3] = x1923;
            mass[4] = x1936;
            mass[5] = x1943;
            mass[6] = x1950;
            mass[7] = x1959;
            mass[8] = x1967;
            mass[9] = x1970;
            mass[10] = x1975;
            mass[11] = x1978;
            mass[12] = x1983;
            mass[13] = x1986;
            mass[14] = x1990;
            mass[15] = x1993;
            mass[16] = x1996;
            mass[17] = x2516;
            mass[18] = x2524;
            mass[19] = x2531;
            mass[20] = x2538;
            mass[21] = x2543;
            mass[22] = x2549;
            mass[23] = x2556;
            mass[24] = x2563;
            mass[25] = x2569;
            mass[26] = x2575;
            mass[27] = x2581;
            mass[28] = x2587;
            mass[29] = x2593;
            mass[30] = x2599;
            mass[31] = x2604;
            mass[32] = x2610;
            force[0] = x2627;
            force[1] = x2293;
            force[2] = x2306;
            force[3] = x2317;
            force[4] = x2329;
            force[5] = x2691;
        }
        #[inline(never)]
        fn eval_newton_part_1(
            k: &[f64; 15],
            q: &[f64; 9],
            qd: &[f64; 9],
            s: &[f64; 94],
            force: &mut [f64; 9],
        ) {
            let x231 = 2.0 * qd[5];
            let x2166 = s[19] * s[30];
            let x2168 = s[10] * s[35];
            let x2169 = x2168 - x2166;
            let x2170 = s[54] * x2169;
            let x2171 = s[3] * s[30];
            let x2172 = s[54] * x2171;
            let x2173 = s[4] * s[30];
            let x2174 = s[54] * x2173;
            let x2375 = x231 * s[68];
            let x2376 = 0.1 * x2375;
            let x2377 = s[16] * s[69];
            let x2378 = s[19] * s[81];
            let x2379 = x2377 + x2378;
            let x2382 = s[15] * s[70];
            let x2383 = s[18] * s[82];
            let x2384 = x2382 + x2383;
            let x2385 = 0.3 * x2384;
            let x2389 = s[16] * s[68];
            let x2390 = 0.1 * x2389;
            let x2391 = x231 * s[69];
            let x2392 = s[3] * s[81];
            let x2393 = x2391 + x2392;
            let x2395 = s[9] * s[70];
            let x2396 = s[4] * s[82];
            let x2397 = x2395 + x2396;
            let x2398 = 0.3 * x2397;
            let x2403 = s[15] * s[68];
            let x2404 = 0.1 * x2403;
            let x2406 = s[9] * s[69];
            let x2407 = s[4] * s[81];
            let x2408 = x2406 + x2407;
            let x2410 = x231 * s[70];
            let x2411 = s[3] * s[82];
            let x2412 = x2410 + x2411;
            let x2413 = 0.3 * x2412;
            let x2432 = 0.3 * x2382;
            let x2444 = 0.3 * x2395;
            let x2457 = 0.3 * x2410;
            let x2619 = x2170 * s[93];
            let x2620 = x2172 * s[93];
            let x2621 = x2174 * s[93];
            let x2624 = s[19] * s[89];
            let x2625 = s[3] * s[89];
            let x2626 = s[4] * s[89];
            let x2629 = x2619 + x2624;
            let x2630 = x2620 + x2625;
            let x2631 = x2621 + x2626;
            let x2637 = x2379 * k[8];
            let x2639 = x2376 - x2637;
            let x2640 = x2385 + x2639;
            let x2641 = 0.5 * x2640;
            let x2642 = x2393 * k[8];
            let x2643 = x2390 + x2642;
            let x2644 = x2643 - x2398;
            let x2645 = 0.5 * x2644;
            let x2646 = x2408 * k[8];
            let x2647 = x2646 - x2404;
            let x2648 = x2413 + x2647;
            let x2649 = 0.5 * x2648;
            let x2659 = x2377 * k[8];
            let x2660 = x2659 - x2376;
            let x2661 = x2660 - x2432;
            let x2662 = 0.5 * x2661;
            let x2664 = x2662 - x2641;
            let x2665 = q[6] * k[14];
            let x2666 = s[85] * x2665;
            let x2668 = x2664 - x2666;
            let x2669 = x2391 * k[8];
            let x2670 = x2390 + x2669;
            let x2672 = x2444 - x2670;
            let x2673 = 0.5 * x2672;
            let x2675 = x2673 - x2645;
            let x2676 = q[7] * k[14];
            let x2677 = s[85] * x2676;
            let x2679 = x2675 - x2677;
            let x2680 = x2406 * k[8];
            let x2682 = x2404 - x2680;
            let x2683 = x2682 - x2457;
            let x2684 = 0.5 * x2683;
            let x2686 = x2684 - x2649;
            let x2687 = q[8] * k[14];
            let x2688 = s[85] * x2687;
            let x2690 = x2686 - x2688;
            let x2692 = x2629 + x2668;
            let x2693 = x2630 + x2679;
            let x2694 = x2690 - x2631;
            force[6] = x2692;
            force[7] = x2693;
            force[8] = x2694;
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
