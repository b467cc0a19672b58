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
    BodyInfo, Direction, Entry, Formulation, JointInfo, JointKind, KinematicOutputs,
    Mechanism, MechanismInfo, NewtonOutputs, Origin, PlatformInfo, Reduction,
    Substitution, Rotation, TangentOutputs,
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
    let x3046 = q[1] * k[11];
    let x3054 = x356 * k[13];
    let x3067 = x397 * k[14];
    let x3085 = x329 + x3046;
    let x3086 = x3054 + x3085;
    let x3087 = x3067 + x3086;
    out[0] = x3087;
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
    let x13 = symbody_runtime::trig::sin(t);
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
    let x3028 = t * k[1];
    let x3029 = symbody_runtime::trig::sin(x3028);
    let x3030 = k[0] * x3029;
    let x3034 = t * k[4];
    let x3035 = symbody_runtime::trig::cos(x3034);
    let x3036 = k[3] * x3035;
    let x3038 = x13 * k[5];
    let x3048 = x347 * k[6];
    let x3050 = x3030 - x3048;
    let x3055 = x347 * x3050;
    let x3059 = qd[0] * k[2];
    let x3061 = x389 * k[7];
    let x3063 = x3036 - x3061;
    let x3068 = x389 * x3063;
    let x3073 = x435 * x3038;
    let x3088 = x3055 + x3059;
    let x3089 = x3068 + x3088;
    let x3090 = x3073 + x3089;
    out[0] = x3090;
}
/// Directional derivatives of Φ, Φq's nonzeros, Φt and γ along `(dq, dqd, dp)`.
pub fn kinematic_tangents(
    k: &[f64],
    q: &[f64],
    qd: &[f64],
    t: f64,
    dq: &[f64],
    dqd: &[f64],
    dp: &[f64],
    phi: &mut [f64],
    phi_q: &mut [f64],
    phi_t: &mut [f64],
    gamma: &mut [f64],
) {
    let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
    let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
    let dq: &[f64; 14] = dq.try_into().expect("dq must have n_coords entries");
    let dqd: &[f64; 14] = dqd.try_into().expect("dqd must have n_coords entries");
    let dp: &[f64; 33] = dp.try_into().expect("dp must have 33 entries");
    let phi: &mut [f64; 12] = phi.try_into().expect("phi must have 12 entries");
    let phi_q: &mut [f64; 33] = phi_q.try_into().expect("phi_q must have 33 entries");
    let phi_t: &mut [f64; 12] = phi_t.try_into().expect("phi_t must have 12 entries");
    let gamma: &mut [f64; 12] = gamma.try_into().expect("gamma must have 12 entries");
    let _ = k;
    let _ = t;
    let _ = dp;
    kinematic_tangents_part_0(q, qd, dq, dqd, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn kinematic_tangents_part_0(
    q: &[f64; 14],
    qd: &[f64; 14],
    dq: &[f64; 14],
    dqd: &[f64; 14],
    phi: &mut [f64; 12],
    phi_q: &mut [f64; 33],
    phi_t: &mut [f64; 12],
    gamma: &mut [f64; 12],
) {
    let x136 = q[3] * 2.0;
    let x137 = q[4] * 2.0;
    let x138 = q[5] * 2.0;
    let x139 = q[6] * 2.0;
    let x142 = 2.0 * q[10];
    let x143 = 2.0 * q[11];
    let x144 = 2.0 * q[12];
    let x145 = 2.0 * q[13];
    let x229 = 2.0 * qd[3];
    let x230 = 2.0 * qd[4];
    let x231 = 2.0 * qd[5];
    let x232 = 2.0 * qd[6];
    let x233 = 2.0 * qd[10];
    let x234 = 2.0 * qd[11];
    let x235 = 2.0 * qd[12];
    let x236 = 2.0 * qd[13];
    let x1777 = x136 * dq[3];
    let x1778 = x137 * dq[4];
    let x1779 = x138 * dq[5];
    let x1780 = x139 * dq[6];
    let x1781 = x1777 + x1778;
    let x1782 = q[5] * dq[4];
    let x1783 = q[4] * dq[5];
    let x1784 = x1782 + x1783;
    let x1785 = 2.0 * x1784;
    let x1786 = q[6] * dq[3];
    let x1787 = q[3] * dq[6];
    let x1788 = x1786 + x1787;
    let x1789 = 2.0 * x1788;
    let x1790 = q[6] * dq[4];
    let x1791 = q[4] * dq[6];
    let x1792 = x1790 + x1791;
    let x1793 = 2.0 * x1792;
    let x1794 = q[5] * dq[3];
    let x1795 = q[3] * dq[5];
    let x1796 = x1794 + x1795;
    let x1797 = 2.0 * x1796;
    let x1798 = x1785 + x1789;
    let x1799 = q[6] * dq[5];
    let x1800 = q[5] * dq[6];
    let x1801 = x1799 + x1800;
    let x1802 = 2.0 * x1801;
    let x1803 = q[4] * dq[3];
    let x1804 = q[3] * dq[4];
    let x1805 = x1803 + x1804;
    let x1806 = 2.0 * x1805;
    let x1808 = x1793 - x1797;
    let x1809 = x1802 + x1806;
    let x1810 = x142 * dq[10];
    let x1811 = x143 * dq[11];
    let x1812 = x144 * dq[12];
    let x1813 = x145 * dq[13];
    let x1814 = x1810 + x1811;
    let x1816 = q[12] * dq[11];
    let x1817 = q[11] * dq[12];
    let x1818 = x1816 + x1817;
    let x1819 = 2.0 * x1818;
    let x1820 = q[13] * dq[10];
    let x1821 = q[10] * dq[13];
    let x1822 = x1820 + x1821;
    let x1823 = 2.0 * x1822;
    let x1825 = x1819 - x1823;
    let x1834 = q[13] * dq[12];
    let x1835 = q[12] * dq[13];
    let x1836 = x1834 + x1835;
    let x1837 = 2.0 * x1836;
    let x1838 = q[11] * dq[10];
    let x1839 = q[10] * dq[11];
    let x1840 = x1838 + x1839;
    let x1841 = 2.0 * x1840;
    let x1844 = x1837 + x1841;
    let x1845 = -dq[7];
    let x1846 = -dq[8];
    let x1847 = -dq[9];
    let x1848 = -x1844;
    let x1849 = x1779 + x1781;
    let x1850 = x1780 + x1849;
    let x1851 = x1812 + x1814;
    let x1852 = x1813 + x1851;
    let x1853 = 2.0 * dq[3];
    let x1854 = 2.0 * dq[4];
    let x1855 = 2.0 * dq[5];
    let x1856 = 2.0 * dq[6];
    let x1857 = -x1855;
    let x1858 = -x1853;
    let x1859 = 2.0 * dq[10];
    let x1860 = 2.0 * dq[11];
    let x1861 = 2.0 * dq[12];
    let x1862 = 2.0 * dq[13];
    let x1863 = -x1862;
    let x1864 = -x1860;
    let x1865 = -x1859;
    let x1866 = -x1861;
    let x1934 = 2.0 * dqd[3];
    let x1935 = 2.0 * dqd[4];
    let x1936 = 2.0 * dqd[5];
    let x1937 = 2.0 * dqd[6];
    let x1938 = 2.0 * dqd[10];
    let x1939 = 2.0 * dqd[11];
    let x1940 = 2.0 * dqd[12];
    let x1941 = 2.0 * dqd[13];
    let x1942 = x229 * dqd[3];
    let x1943 = qd[3] * x1934;
    let x1944 = x1942 + x1943;
    let x1945 = x230 * dqd[4];
    let x1946 = qd[4] * x1935;
    let x1947 = x1945 + x1946;
    let x1948 = x231 * dqd[5];
    let x1949 = qd[5] * x1936;
    let x1950 = x1948 + x1949;
    let x1951 = x232 * dqd[6];
    let x1952 = qd[6] * x1937;
    let x1953 = x1951 + x1952;
    let x1954 = x1944 + x1947;
    let x1955 = qd[5] * dqd[4];
    let x1956 = qd[4] * dqd[5];
    let x1957 = x1955 + x1956;
    let x1958 = x1957 + x1957;
    let x1959 = 2.0 * x1958;
    let x1960 = qd[6] * dqd[3];
    let x1961 = qd[3] * dqd[6];
    let x1962 = x1960 + x1961;
    let x1963 = x1962 + x1962;
    let x1964 = 2.0 * x1963;
    let x1965 = qd[6] * dqd[4];
    let x1966 = qd[4] * dqd[6];
    let x1967 = x1965 + x1966;
    let x1968 = x1967 + x1967;
    let x1969 = 2.0 * x1968;
    let x1970 = qd[5] * dqd[3];
    let x1971 = qd[3] * dqd[5];
    let x1972 = x1970 + x1971;
    let x1973 = x1972 + x1972;
    let x1974 = 2.0 * x1973;
    let x1975 = x1959 + x1964;
    let x1976 = qd[6] * dqd[5];
    let x1977 = qd[5] * dqd[6];
    let x1978 = x1976 + x1977;
    let x1979 = x1978 + x1978;
    let x1980 = 2.0 * x1979;
    let x1981 = qd[4] * dqd[3];
    let x1982 = qd[3] * dqd[4];
    let x1983 = x1981 + x1982;
    let x1984 = x1983 + x1983;
    let x1985 = 2.0 * x1984;
    let x1987 = x1969 - x1974;
    let x1988 = x1980 + x1985;
    let x1989 = x233 * dqd[10];
    let x1990 = qd[10] * x1938;
    let x1991 = x1989 + x1990;
    let x1992 = x234 * dqd[11];
    let x1993 = qd[11] * x1939;
    let x1994 = x1992 + x1993;
    let x1995 = x235 * dqd[12];
    let x1996 = qd[12] * x1940;
    let x1997 = x1995 + x1996;
    let x1998 = x236 * dqd[13];
    let x1999 = qd[13] * x1941;
    let x2000 = x1998 + x1999;
    let x2001 = x1991 + x1994;
    let x2002 = qd[12] * dqd[11];
    let x2003 = qd[11] * dqd[12];
    let x2004 = x2002 + x2003;
    let x2005 = x2004 + x2004;
    let x2006 = 2.0 * x2005;
    let x2007 = qd[13] * dqd[10];
    let x2008 = qd[10] * dqd[13];
    let x2009 = x2007 + x2008;
    let x2010 = x2009 + x2009;
    let x2011 = 2.0 * x2010;
    let x2013 = x2006 - x2011;
    let x2014 = qd[13] * dqd[12];
    let x2015 = qd[12] * dqd[13];
    let x2016 = x2014 + x2015;
    let x2017 = x2016 + x2016;
    let x2018 = 2.0 * x2017;
    let x2019 = qd[11] * dqd[10];
    let x2020 = qd[10] * dqd[11];
    let x2021 = x2019 + x2020;
    let x2022 = x2021 + x2021;
    let x2023 = 2.0 * x2022;
    let x2024 = x2018 + x2023;
    let x2025 = x1950 + x1954;
    let x2026 = x1953 + x2025;
    let x2027 = x1997 + x2001;
    let x2028 = x2000 + x2027;
    let x2029 = -x1975;
    let x2030 = -x1987;
    let x2031 = -x1988;
    let x2032 = -x2013;
    let x2033 = -x2026;
    let x2034 = -x2028;
    phi[0] = x1798;
    phi_q[0] = x1856;
    phi_q[1] = x1855;
    phi_q[2] = x1854;
    phi_q[3] = x1853;
    phi_t[0] = 0.0;
    gamma[0] = x2029;
    phi[1] = x1808;
    phi_q[4] = x1857;
    phi_q[5] = x1856;
    phi_q[6] = x1858;
    phi_q[7] = x1854;
    phi_t[1] = 0.0;
    gamma[1] = x2030;
    phi[2] = dq[1];
    phi_q[8] = 0.0;
    phi_t[2] = 0.0;
    gamma[2] = 0.0;
    phi[3] = dq[2];
    phi_q[9] = 0.0;
    phi_t[3] = 0.0;
    gamma[3] = 0.0;
    phi[4] = x1809;
    phi_q[10] = x1854;
    phi_q[11] = x1853;
    phi_q[12] = x1856;
    phi_q[13] = x1855;
    phi_t[4] = 0.0;
    gamma[4] = x2031;
    phi[5] = x1845;
    phi_q[14] = 0.0;
    phi_t[5] = 0.0;
    gamma[5] = 0.0;
    phi[6] = x1846;
    phi_q[15] = 0.0;
    phi_t[6] = 0.0;
    gamma[6] = 0.0;
    phi[7] = x1847;
    phi_q[16] = 0.0;
    phi_t[7] = 0.0;
    gamma[7] = 0.0;
    phi[8] = x1825;
    phi_q[17] = x1863;
    phi_q[18] = x1861;
    phi_q[19] = x1860;
    phi_q[20] = x1865;
    phi_t[8] = 0.0;
    gamma[8] = x2032;
    phi[9] = x1848;
    phi_q[21] = x1864;
    phi_q[22] = x1865;
    phi_q[23] = x1863;
    phi_q[24] = x1866;
    phi_t[9] = 0.0;
    gamma[9] = x2024;
    phi[10] = x1850;
    phi_q[25] = x1853;
    phi_q[26] = x1854;
    phi_q[27] = x1855;
    phi_q[28] = x1856;
    phi_t[10] = 0.0;
    gamma[10] = x2033;
    phi[11] = x1852;
    phi_q[29] = x1859;
    phi_q[30] = x1860;
    phi_q[31] = x1861;
    phi_q[32] = x1862;
    phi_t[11] = 0.0;
    gamma[11] = x2034;
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
        kkt: &KKT,
    };
    use symbody_runtime::kkt::{
        length_error, mass_pivot_error, KktError, KktKernels, Pivoting,
    };
    /// The KKT factor and solve for this model's patterns, straight-line (`KktKernels`).
    pub static KKT: [KktKernels; 2] = [
        KktKernels {
            pattern: 0xf12494a443116ee4,
            storage: 80,
            factor: kkt_factor_0,
            solve: kkt_solve_0,
            phi_q_rows: &PHI_Q_ROWS,
            phi_q_cols: &PHI_Q_COLS,
            transpose_times: kkt_transpose_times,
            times_add: kkt_times_add,
            mass_rows: &MASS_ROWS,
            mass_cols: &MASS_COLS,
            mass_times: kkt_mass_times,
            kinetic_energy: kkt_kinetic_energy,
            loads: None,
        },
        KktKernels {
            pattern: 0xc64715c39133be24,
            storage: 85,
            factor: kkt_factor_1,
            solve: kkt_solve_1,
            phi_q_rows: &PHI_Q_ROWS,
            phi_q_cols: &PHI_Q_COLS,
            transpose_times: kkt_transpose_times,
            times_add: kkt_times_add,
            mass_rows: &MASS_ROWS,
            mass_cols: &MASS_COLS,
            mass_times: kkt_mass_times,
            kinetic_energy: kkt_kinetic_energy,
            loads: Some(symbody_runtime::kkt::LoadsKernel {
                force_q_rows: &FORCE_Q_ROWS,
                force_q_cols: &FORCE_Q_COLS,
                force_qd_rows: &FORCE_QD_ROWS,
                force_qd_cols: &FORCE_QD_COLS,
                assemble: kkt_assemble_loads,
            }),
        },
    ];
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    fn kkt_factor_0_avx(
        mass: &[f64],
        c: f64,
        phi_q: &[f64],
        st: &mut [f64],
        piv: &mut Pivoting,
    ) -> Result<(), KktError> {
        kkt_factor_0_any(mass, c, phi_q, st, piv)
    }
    fn kkt_factor_0(
        mass: &[f64],
        c: f64,
        phi_q: &[f64],
        st: &mut [f64],
        piv: &mut Pivoting,
    ) -> Result<(), KktError> {
        #[cfg(target_arch = "x86_64")]
        {
            if !symbody_runtime::kkt::kernels_run_here() {
                return Err(KktError::KernelsUnsupported);
            }
            unsafe { kkt_factor_0_avx(mass, c, phi_q, st, piv) }
        }
        #[cfg(not(target_arch = "x86_64"))] kkt_factor_0_any(mass, c, phi_q, st, piv)
    }
    #[allow(
        unused_variables,
        unused_parens,
        clippy::neg_cmp_op_on_partial_ord,
        clippy::nonminimal_bool
    )]
    #[inline(always)]
    fn kkt_factor_0_any(
        mass: &[f64],
        c: f64,
        phi_q: &[f64],
        st: &mut [f64],
        piv: &mut Pivoting,
    ) -> Result<(), KktError> {
        let mass: &[f64; 38] = mass
            .try_into()
            .map_err(|_| length_error(38, mass.len()))?;
        let phi_q: &[f64; 33] = phi_q
            .try_into()
            .map_err(|_| length_error(33, phi_q.len()))?;
        let st_len = st.len();
        let st: &mut [f64; 80] = st.try_into().map_err(|_| length_error(80, st_len))?;
        if !((c * mass[0]) > 0.0 && (c * mass[0]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[0]), 0));
        }
        let v0: f64 = (c * mass[0]).sqrt();
        let v1: f64 = 1.0 / v0;
        st[12] = v1;
        if !((c * mass[1]) > 0.0 && (c * mass[1]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[1]), 1));
        }
        let v2: f64 = (c * mass[1]).sqrt();
        let v3: f64 = 1.0 / v2;
        st[13] = v3;
        let v4: f64 = phi_q[8] * v3;
        st[26] = v4;
        let v5: f64 = v4 * v4;
        if !((c * mass[2]) > 0.0 && (c * mass[2]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[2]), 2));
        }
        let v6: f64 = (c * mass[2]).sqrt();
        let v7: f64 = 1.0 / v6;
        st[14] = v7;
        let v8: f64 = phi_q[9] * v7;
        st[27] = v8;
        let v9: f64 = v8 * v8;
        if !((c * mass[3]) > 0.0 && (c * mass[3]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[3]), 3));
        }
        let v10: f64 = (c * mass[3]).sqrt();
        let v11: f64 = 1.0 / v10;
        st[15] = v11;
        let v12: f64 = (c * mass[7]) * v11;
        st[0] = v12;
        let v13: f64 = (c * mass[11]) * v11;
        st[1] = v13;
        let v14: f64 = (c * mass[15]) * v11;
        st[3] = v14;
        let v15: f64 = (c * mass[8]) - v12 * v12;
        if !(v15 > 0.0 && v15 <= f64::MAX) {
            return Err(mass_pivot_error(v15, 4));
        }
        let v16: f64 = v15.sqrt();
        let v17: f64 = 1.0 / v16;
        st[16] = v17;
        let v18: f64 = (c * mass[12]) - v13 * v12;
        let v19: f64 = v18 * v17;
        st[2] = v19;
        let v20: f64 = (c * mass[16]) - v14 * v12;
        let v21: f64 = v20 * v17;
        st[4] = v21;
        let v22: f64 = (c * mass[13]) - v13 * v13;
        let v23: f64 = v22 - v19 * v19;
        if !(v23 > 0.0 && v23 <= f64::MAX) {
            return Err(mass_pivot_error(v23, 5));
        }
        let v24: f64 = v23.sqrt();
        let v25: f64 = 1.0 / v24;
        st[17] = v25;
        let v26: f64 = (c * mass[17]) - v14 * v13;
        let v27: f64 = v26 - v21 * v19;
        let v28: f64 = v27 * v25;
        st[5] = v28;
        let v29: f64 = (c * mass[18]) - v14 * v14;
        let v30: f64 = v29 - v21 * v21;
        let v31: f64 = v30 - v28 * v28;
        if !(v31 > 0.0 && v31 <= f64::MAX) {
            return Err(mass_pivot_error(v31, 6));
        }
        let v32: f64 = v31.sqrt();
        let v33: f64 = 1.0 / v32;
        st[18] = v33;
        let v34: f64 = phi_q[0] * v11;
        st[28] = v34;
        let v35: f64 = phi_q[1] - v12 * v34;
        let v36: f64 = v35 * v17;
        st[29] = v36;
        let v37: f64 = phi_q[2] - v13 * v34;
        let v38: f64 = v37 - v19 * v36;
        let v39: f64 = v38 * v25;
        st[30] = v39;
        let v40: f64 = phi_q[3] - v14 * v34;
        let v41: f64 = v40 - v21 * v36;
        let v42: f64 = v41 - v28 * v39;
        let v43: f64 = v42 * v33;
        st[31] = v43;
        let v44: f64 = phi_q[4] * v11;
        st[32] = v44;
        let v45: f64 = phi_q[5] - v12 * v44;
        let v46: f64 = v45 * v17;
        st[33] = v46;
        let v47: f64 = phi_q[6] - v13 * v44;
        let v48: f64 = v47 - v19 * v46;
        let v49: f64 = v48 * v25;
        st[34] = v49;
        let v50: f64 = phi_q[7] - v14 * v44;
        let v51: f64 = v50 - v21 * v46;
        let v52: f64 = v51 - v28 * v49;
        let v53: f64 = v52 * v33;
        st[35] = v53;
        let v54: f64 = phi_q[10] * v11;
        st[36] = v54;
        let v55: f64 = phi_q[11] - v12 * v54;
        let v56: f64 = v55 * v17;
        st[37] = v56;
        let v57: f64 = phi_q[12] - v13 * v54;
        let v58: f64 = v57 - v19 * v56;
        let v59: f64 = v58 * v25;
        st[38] = v59;
        let v60: f64 = phi_q[13] - v14 * v54;
        let v61: f64 = v60 - v21 * v56;
        let v62: f64 = v61 - v28 * v59;
        let v63: f64 = v62 * v33;
        st[39] = v63;
        let v64: f64 = phi_q[25] * v11;
        st[40] = v64;
        let v65: f64 = phi_q[26] - v12 * v64;
        let v66: f64 = v65 * v17;
        st[41] = v66;
        let v67: f64 = phi_q[27] - v13 * v64;
        let v68: f64 = v67 - v19 * v66;
        let v69: f64 = v68 * v25;
        st[42] = v69;
        let v70: f64 = phi_q[28] - v14 * v64;
        let v71: f64 = v70 - v21 * v66;
        let v72: f64 = v71 - v28 * v69;
        let v73: f64 = v72 * v33;
        st[43] = v73;
        let v74: f64 = v34 * v34;
        let v75: f64 = v36 * v36;
        let v76: f64 = v74 + v75;
        let v77: f64 = v39 * v39;
        let v78: f64 = v76 + v77;
        let v79: f64 = v43 * v43;
        let v80: f64 = v78 + v79;
        let v81: f64 = v44 * v34;
        let v82: f64 = v46 * v36;
        let v83: f64 = v81 + v82;
        let v84: f64 = v49 * v39;
        let v85: f64 = v83 + v84;
        let v86: f64 = v53 * v43;
        let v87: f64 = v85 + v86;
        let v88: f64 = v44 * v44;
        let v89: f64 = v46 * v46;
        let v90: f64 = v88 + v89;
        let v91: f64 = v49 * v49;
        let v92: f64 = v90 + v91;
        let v93: f64 = v53 * v53;
        let v94: f64 = v92 + v93;
        let v95: f64 = v54 * v34;
        let v96: f64 = v56 * v36;
        let v97: f64 = v95 + v96;
        let v98: f64 = v59 * v39;
        let v99: f64 = v97 + v98;
        let v100: f64 = v63 * v43;
        let v101: f64 = v99 + v100;
        let v102: f64 = v54 * v44;
        let v103: f64 = v56 * v46;
        let v104: f64 = v102 + v103;
        let v105: f64 = v59 * v49;
        let v106: f64 = v104 + v105;
        let v107: f64 = v63 * v53;
        let v108: f64 = v106 + v107;
        let v109: f64 = v54 * v54;
        let v110: f64 = v56 * v56;
        let v111: f64 = v109 + v110;
        let v112: f64 = v59 * v59;
        let v113: f64 = v111 + v112;
        let v114: f64 = v63 * v63;
        let v115: f64 = v113 + v114;
        let v116: f64 = v64 * v34;
        let v117: f64 = v66 * v36;
        let v118: f64 = v116 + v117;
        let v119: f64 = v69 * v39;
        let v120: f64 = v118 + v119;
        let v121: f64 = v73 * v43;
        let v122: f64 = v120 + v121;
        let v123: f64 = v64 * v44;
        let v124: f64 = v66 * v46;
        let v125: f64 = v123 + v124;
        let v126: f64 = v69 * v49;
        let v127: f64 = v125 + v126;
        let v128: f64 = v73 * v53;
        let v129: f64 = v127 + v128;
        let v130: f64 = v64 * v54;
        let v131: f64 = v66 * v56;
        let v132: f64 = v130 + v131;
        let v133: f64 = v69 * v59;
        let v134: f64 = v132 + v133;
        let v135: f64 = v73 * v63;
        let v136: f64 = v134 + v135;
        let v137: f64 = v64 * v64;
        let v138: f64 = v66 * v66;
        let v139: f64 = v137 + v138;
        let v140: f64 = v69 * v69;
        let v141: f64 = v139 + v140;
        let v142: f64 = v73 * v73;
        let v143: f64 = v141 + v142;
        if !((c * mass[19]) > 0.0 && (c * mass[19]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[19]), 7));
        }
        let v144: f64 = (c * mass[19]).sqrt();
        let v145: f64 = 1.0 / v144;
        st[19] = v145;
        let v146: f64 = phi_q[14] * v145;
        st[44] = v146;
        let v147: f64 = v146 * v146;
        if !((c * mass[20]) > 0.0 && (c * mass[20]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[20]), 8));
        }
        let v148: f64 = (c * mass[20]).sqrt();
        let v149: f64 = 1.0 / v148;
        st[20] = v149;
        let v150: f64 = phi_q[15] * v149;
        st[45] = v150;
        let v151: f64 = v150 * v150;
        if !((c * mass[21]) > 0.0 && (c * mass[21]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[21]), 9));
        }
        let v152: f64 = (c * mass[21]).sqrt();
        let v153: f64 = 1.0 / v152;
        st[21] = v153;
        let v154: f64 = phi_q[16] * v153;
        st[46] = v154;
        let v155: f64 = v154 * v154;
        if !((c * mass[22]) > 0.0 && (c * mass[22]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[22]), 10));
        }
        let v156: f64 = (c * mass[22]).sqrt();
        let v157: f64 = 1.0 / v156;
        st[22] = v157;
        let v158: f64 = (c * mass[26]) * v157;
        st[6] = v158;
        let v159: f64 = (c * mass[30]) * v157;
        st[7] = v159;
        let v160: f64 = (c * mass[34]) * v157;
        st[9] = v160;
        let v161: f64 = (c * mass[27]) - v158 * v158;
        if !(v161 > 0.0 && v161 <= f64::MAX) {
            return Err(mass_pivot_error(v161, 11));
        }
        let v162: f64 = v161.sqrt();
        let v163: f64 = 1.0 / v162;
        st[23] = v163;
        let v164: f64 = (c * mass[31]) - v159 * v158;
        let v165: f64 = v164 * v163;
        st[8] = v165;
        let v166: f64 = (c * mass[35]) - v160 * v158;
        let v167: f64 = v166 * v163;
        st[10] = v167;
        let v168: f64 = (c * mass[32]) - v159 * v159;
        let v169: f64 = v168 - v165 * v165;
        if !(v169 > 0.0 && v169 <= f64::MAX) {
            return Err(mass_pivot_error(v169, 12));
        }
        let v170: f64 = v169.sqrt();
        let v171: f64 = 1.0 / v170;
        st[24] = v171;
        let v172: f64 = (c * mass[36]) - v160 * v159;
        let v173: f64 = v172 - v167 * v165;
        let v174: f64 = v173 * v171;
        st[11] = v174;
        let v175: f64 = (c * mass[37]) - v160 * v160;
        let v176: f64 = v175 - v167 * v167;
        let v177: f64 = v176 - v174 * v174;
        if !(v177 > 0.0 && v177 <= f64::MAX) {
            return Err(mass_pivot_error(v177, 13));
        }
        let v178: f64 = v177.sqrt();
        let v179: f64 = 1.0 / v178;
        st[25] = v179;
        let v180: f64 = phi_q[17] * v157;
        st[47] = v180;
        let v181: f64 = phi_q[18] - v158 * v180;
        let v182: f64 = v181 * v163;
        st[48] = v182;
        let v183: f64 = phi_q[19] - v159 * v180;
        let v184: f64 = v183 - v165 * v182;
        let v185: f64 = v184 * v171;
        st[49] = v185;
        let v186: f64 = phi_q[20] - v160 * v180;
        let v187: f64 = v186 - v167 * v182;
        let v188: f64 = v187 - v174 * v185;
        let v189: f64 = v188 * v179;
        st[50] = v189;
        let v190: f64 = phi_q[21] * v157;
        st[51] = v190;
        let v191: f64 = phi_q[22] - v158 * v190;
        let v192: f64 = v191 * v163;
        st[52] = v192;
        let v193: f64 = phi_q[23] - v159 * v190;
        let v194: f64 = v193 - v165 * v192;
        let v195: f64 = v194 * v171;
        st[53] = v195;
        let v196: f64 = phi_q[24] - v160 * v190;
        let v197: f64 = v196 - v167 * v192;
        let v198: f64 = v197 - v174 * v195;
        let v199: f64 = v198 * v179;
        st[54] = v199;
        let v200: f64 = phi_q[29] * v157;
        st[55] = v200;
        let v201: f64 = phi_q[30] - v158 * v200;
        let v202: f64 = v201 * v163;
        st[56] = v202;
        let v203: f64 = phi_q[31] - v159 * v200;
        let v204: f64 = v203 - v165 * v202;
        let v205: f64 = v204 * v171;
        st[57] = v205;
        let v206: f64 = phi_q[32] - v160 * v200;
        let v207: f64 = v206 - v167 * v202;
        let v208: f64 = v207 - v174 * v205;
        let v209: f64 = v208 * v179;
        st[58] = v209;
        let v210: f64 = v180 * v180;
        let v211: f64 = v182 * v182;
        let v212: f64 = v210 + v211;
        let v213: f64 = v185 * v185;
        let v214: f64 = v212 + v213;
        let v215: f64 = v189 * v189;
        let v216: f64 = v214 + v215;
        let v217: f64 = v190 * v180;
        let v218: f64 = v192 * v182;
        let v219: f64 = v217 + v218;
        let v220: f64 = v195 * v185;
        let v221: f64 = v219 + v220;
        let v222: f64 = v199 * v189;
        let v223: f64 = v221 + v222;
        let v224: f64 = v190 * v190;
        let v225: f64 = v192 * v192;
        let v226: f64 = v224 + v225;
        let v227: f64 = v195 * v195;
        let v228: f64 = v226 + v227;
        let v229: f64 = v199 * v199;
        let v230: f64 = v228 + v229;
        let v231: f64 = v200 * v180;
        let v232: f64 = v202 * v182;
        let v233: f64 = v231 + v232;
        let v234: f64 = v205 * v185;
        let v235: f64 = v233 + v234;
        let v236: f64 = v209 * v189;
        let v237: f64 = v235 + v236;
        let v238: f64 = v200 * v190;
        let v239: f64 = v202 * v192;
        let v240: f64 = v238 + v239;
        let v241: f64 = v205 * v195;
        let v242: f64 = v240 + v241;
        let v243: f64 = v209 * v199;
        let v244: f64 = v242 + v243;
        let v245: f64 = v200 * v200;
        let v246: f64 = v202 * v202;
        let v247: f64 = v245 + v246;
        let v248: f64 = v205 * v205;
        let v249: f64 = v247 + v248;
        let v250: f64 = v209 * v209;
        let v251: f64 = v249 + v250;
        let (v252, v253) = piv.pivot(v143, v143, 10, false)?;
        st[68] = v252;
        let v254: f64 = v122 * v252;
        st[59] = v254;
        let v255: f64 = v80 - v254 * v253 * v254;
        let v256: f64 = v129 * v252;
        st[60] = v256;
        let v257: f64 = v94 - v256 * v253 * v256;
        let v258: f64 = v136 * v252;
        st[61] = v258;
        let v259: f64 = v115 - v258 * v253 * v258;
        let v260: f64 = v87 - v256 * v253 * v254;
        let v261: f64 = v101 - v258 * v253 * v254;
        let v262: f64 = v108 - v258 * v253 * v256;
        let (v263, v264) = piv.pivot(v251, v251, 11, false)?;
        st[69] = v263;
        let v265: f64 = v237 * v263;
        st[62] = v265;
        let v266: f64 = v216 - v265 * v264 * v265;
        let v267: f64 = v244 * v263;
        st[63] = v267;
        let v268: f64 = v230 - v267 * v264 * v267;
        let v269: f64 = v223 - v267 * v264 * v265;
        let (v270, v271) = piv.pivot(v5, v5, 2, false)?;
        st[70] = v270;
        let (v272, v273) = piv.pivot(v9, v9, 3, false)?;
        st[71] = v272;
        let (v274, v275) = piv.pivot(v147, v147, 5, false)?;
        st[72] = v274;
        let (v276, v277) = piv.pivot(v151, v151, 6, false)?;
        st[73] = v276;
        let (v278, v279) = piv.pivot(v155, v155, 7, false)?;
        st[74] = v278;
        let (v280, v281) = piv.pivot(v266, v266, 8, false)?;
        st[75] = v280;
        let v282: f64 = v269 * v280;
        st[64] = v282;
        let v283: f64 = v268 - v282 * v281 * v282;
        let (v284, v285) = piv.pivot(v283, v268, 9, false)?;
        st[76] = v284;
        let (v286, v287) = piv.pivot(v255, v255, 0, false)?;
        st[77] = v286;
        let v288: f64 = v260 * v286;
        st[65] = v288;
        let v289: f64 = v257 - v288 * v287 * v288;
        let v290: f64 = v261 * v286;
        st[66] = v290;
        let v291: f64 = v259 - v290 * v287 * v290;
        let v292: f64 = v262 - v290 * v287 * v288;
        let (v293, v294) = piv.pivot(v289, v257, 1, false)?;
        st[78] = v293;
        let v295: f64 = v292 * v293;
        st[67] = v295;
        let v296: f64 = v291 - v295 * v294 * v295;
        let (v297, v298) = piv.pivot(v296, v259, 4, false)?;
        st[79] = v297;
        Ok(())
    }
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    fn kkt_solve_0_avx(
        f: &[f64],
        g: &[f64],
        x: &mut [f64],
        y: &mut [f64],
        st: &[f64],
    ) -> Result<(), KktError> {
        kkt_solve_0_any(f, g, x, y, st)
    }
    fn kkt_solve_0(
        f: &[f64],
        g: &[f64],
        x: &mut [f64],
        y: &mut [f64],
        st: &[f64],
    ) -> Result<(), KktError> {
        #[cfg(target_arch = "x86_64")]
        {
            if !symbody_runtime::kkt::kernels_run_here() {
                return Err(KktError::KernelsUnsupported);
            }
            unsafe { kkt_solve_0_avx(f, g, x, y, st) }
        }
        #[cfg(not(target_arch = "x86_64"))] kkt_solve_0_any(f, g, x, y, st)
    }
    #[allow(
        unused_variables,
        clippy::neg_cmp_op_on_partial_ord,
        clippy::nonminimal_bool
    )]
    #[inline(always)]
    fn kkt_solve_0_any(
        f: &[f64],
        g: &[f64],
        x: &mut [f64],
        y: &mut [f64],
        st: &[f64],
    ) -> Result<(), KktError> {
        let f: &[f64; 14] = f.try_into().map_err(|_| length_error(14, f.len()))?;
        let g: &[f64; 12] = g.try_into().map_err(|_| length_error(12, g.len()))?;
        let x_len = x.len();
        let x: &mut [f64; 14] = x.try_into().map_err(|_| length_error(14, x_len))?;
        let y_len = y.len();
        let y: &mut [f64; 12] = y.try_into().map_err(|_| length_error(12, y_len))?;
        let st: &[f64; 80] = st.try_into().map_err(|_| length_error(80, st.len()))?;
        x.fill(0.0);
        y[0] = -g[0];
        y[1] = -g[1];
        y[2] = -g[2];
        y[3] = -g[3];
        y[4] = -g[4];
        y[5] = -g[5];
        y[6] = -g[6];
        y[7] = -g[7];
        y[8] = -g[8];
        y[9] = -g[9];
        y[10] = -g[10];
        y[11] = -g[11];
        if f.iter().any(|&v| v != 0.0) {
            let v0: f64 = f[0];
            let v1: f64 = f[1];
            let v2: f64 = v0 * st[12];
            let v3: f64 = v1 * st[13];
            let v4: f64 = st[26] * v3;
            y[2] += v4;
            x[0] = v2;
            x[1] = v3;
            let v5: f64 = f[2];
            let v6: f64 = v5 * st[14];
            let v7: f64 = st[27] * v6;
            y[3] += v7;
            x[2] = v6;
            let v8: f64 = f[3];
            let v9: f64 = f[4];
            let v10: f64 = f[5];
            let v11: f64 = f[6];
            let v12: f64 = v8 * st[15];
            let v13: f64 = v9 - st[0] * v12;
            let v14: f64 = v13 * st[16];
            let v15: f64 = v10 - st[1] * v12;
            let v16: f64 = v15 - st[2] * v14;
            let v17: f64 = v16 * st[17];
            let v18: f64 = v11 - st[3] * v12;
            let v19: f64 = v18 - st[4] * v14;
            let v20: f64 = v19 - st[5] * v17;
            let v21: f64 = v20 * st[18];
            let v22: f64 = st[28] * v12;
            let v23: f64 = st[29] * v14;
            let v24: f64 = v22 + v23;
            let v25: f64 = st[30] * v17;
            let v26: f64 = v24 + v25;
            let v27: f64 = st[31] * v21;
            let v28: f64 = v26 + v27;
            y[0] += v28;
            let v29: f64 = st[32] * v12;
            let v30: f64 = st[33] * v14;
            let v31: f64 = v29 + v30;
            let v32: f64 = st[34] * v17;
            let v33: f64 = v31 + v32;
            let v34: f64 = st[35] * v21;
            let v35: f64 = v33 + v34;
            y[1] += v35;
            let v36: f64 = st[36] * v12;
            let v37: f64 = st[37] * v14;
            let v38: f64 = v36 + v37;
            let v39: f64 = st[38] * v17;
            let v40: f64 = v38 + v39;
            let v41: f64 = st[39] * v21;
            let v42: f64 = v40 + v41;
            y[4] += v42;
            let v43: f64 = st[40] * v12;
            let v44: f64 = st[41] * v14;
            let v45: f64 = v43 + v44;
            let v46: f64 = st[42] * v17;
            let v47: f64 = v45 + v46;
            let v48: f64 = st[43] * v21;
            let v49: f64 = v47 + v48;
            y[10] += v49;
            x[3] = v12;
            x[4] = v14;
            x[5] = v17;
            x[6] = v21;
            let v50: f64 = f[7];
            let v51: f64 = v50 * st[19];
            let v52: f64 = st[44] * v51;
            y[5] += v52;
            x[7] = v51;
            let v53: f64 = f[8];
            let v54: f64 = v53 * st[20];
            let v55: f64 = st[45] * v54;
            y[6] += v55;
            x[8] = v54;
            let v56: f64 = f[9];
            let v57: f64 = v56 * st[21];
            let v58: f64 = st[46] * v57;
            y[7] += v58;
            x[9] = v57;
            let v59: f64 = f[10];
            let v60: f64 = f[11];
            let v61: f64 = f[12];
            let v62: f64 = f[13];
            let v63: f64 = v59 * st[22];
            let v64: f64 = v60 - st[6] * v63;
            let v65: f64 = v64 * st[23];
            let v66: f64 = v61 - st[7] * v63;
            let v67: f64 = v66 - st[8] * v65;
            let v68: f64 = v67 * st[24];
            let v69: f64 = v62 - st[9] * v63;
            let v70: f64 = v69 - st[10] * v65;
            let v71: f64 = v70 - st[11] * v68;
            let v72: f64 = v71 * st[25];
            let v73: f64 = st[47] * v63;
            let v74: f64 = st[48] * v65;
            let v75: f64 = v73 + v74;
            let v76: f64 = st[49] * v68;
            let v77: f64 = v75 + v76;
            let v78: f64 = st[50] * v72;
            let v79: f64 = v77 + v78;
            y[8] += v79;
            let v80: f64 = st[51] * v63;
            let v81: f64 = st[52] * v65;
            let v82: f64 = v80 + v81;
            let v83: f64 = st[53] * v68;
            let v84: f64 = v82 + v83;
            let v85: f64 = st[54] * v72;
            let v86: f64 = v84 + v85;
            y[9] += v86;
            let v87: f64 = st[55] * v63;
            let v88: f64 = st[56] * v65;
            let v89: f64 = v87 + v88;
            let v90: f64 = st[57] * v68;
            let v91: f64 = v89 + v90;
            let v92: f64 = st[58] * v72;
            let v93: f64 = v91 + v92;
            y[11] += v93;
            x[10] = v63;
            x[11] = v65;
            x[12] = v68;
            x[13] = v72;
        }
        let v94: f64 = y[0] - st[59] * y[10];
        let v95: f64 = y[1] - st[60] * y[10];
        let v96: f64 = y[4] - st[61] * y[10];
        let v97: f64 = y[8] - st[62] * y[11];
        let v98: f64 = y[9] - st[63] * y[11];
        let v99: f64 = v98 - st[64] * v97;
        let v100: f64 = v95 - st[65] * v94;
        let v101: f64 = v96 - st[66] * v94;
        let v102: f64 = v101 - st[67] * v100;
        let v103: f64 = y[10] * st[68];
        let v104: f64 = y[11] * st[69];
        let v105: f64 = y[2] * st[70];
        let v106: f64 = y[3] * st[71];
        let v107: f64 = y[5] * st[72];
        let v108: f64 = y[6] * st[73];
        let v109: f64 = y[7] * st[74];
        let v110: f64 = v97 * st[75];
        let v111: f64 = v99 * st[76];
        let v112: f64 = v94 * st[77];
        let v113: f64 = v100 * st[78];
        let v114: f64 = v102 * st[79];
        let v115: f64 = v113 - st[67] * v114;
        let v116: f64 = v112 - st[65] * v115;
        let v117: f64 = v116 - st[66] * v114;
        let v118: f64 = v110 - st[64] * v111;
        let v119: f64 = v104 - st[62] * v118;
        let v120: f64 = v119 - st[63] * v111;
        let v121: f64 = v103 - st[59] * v117;
        let v122: f64 = v121 - st[60] * v115;
        let v123: f64 = v122 - st[61] * v114;
        y[10] = v123;
        y[11] = v120;
        y[2] = v105;
        y[3] = v106;
        y[5] = v107;
        y[6] = v108;
        y[7] = v109;
        y[8] = v118;
        y[9] = v111;
        y[0] = v117;
        y[1] = v115;
        y[4] = v114;
        let v124: f64 = x[1] - st[26] * v105;
        let v125: f64 = v124 * st[13];
        let v126: f64 = x[0] * st[12];
        x[0] = v126;
        x[1] = v125;
        let v127: f64 = x[2] - st[27] * v106;
        let v128: f64 = v127 * st[14];
        x[2] = v128;
        let v129: f64 = x[3] - st[28] * v117;
        let v130: f64 = x[4] - st[29] * v117;
        let v131: f64 = x[5] - st[30] * v117;
        let v132: f64 = x[6] - st[31] * v117;
        let v133: f64 = v129 - st[32] * v115;
        let v134: f64 = v130 - st[33] * v115;
        let v135: f64 = v131 - st[34] * v115;
        let v136: f64 = v132 - st[35] * v115;
        let v137: f64 = v133 - st[36] * v114;
        let v138: f64 = v134 - st[37] * v114;
        let v139: f64 = v135 - st[38] * v114;
        let v140: f64 = v136 - st[39] * v114;
        let v141: f64 = v137 - st[40] * v123;
        let v142: f64 = v138 - st[41] * v123;
        let v143: f64 = v139 - st[42] * v123;
        let v144: f64 = v140 - st[43] * v123;
        let v145: f64 = v144 * st[18];
        let v146: f64 = v143 - st[5] * v145;
        let v147: f64 = v146 * st[17];
        let v148: f64 = v142 - st[2] * v147;
        let v149: f64 = v148 - st[4] * v145;
        let v150: f64 = v149 * st[16];
        let v151: f64 = v141 - st[0] * v150;
        let v152: f64 = v151 - st[1] * v147;
        let v153: f64 = v152 - st[3] * v145;
        let v154: f64 = v153 * st[15];
        x[3] = v154;
        x[4] = v150;
        x[5] = v147;
        x[6] = v145;
        let v155: f64 = x[7] - st[44] * v107;
        let v156: f64 = v155 * st[19];
        x[7] = v156;
        let v157: f64 = x[8] - st[45] * v108;
        let v158: f64 = v157 * st[20];
        x[8] = v158;
        let v159: f64 = x[9] - st[46] * v109;
        let v160: f64 = v159 * st[21];
        x[9] = v160;
        let v161: f64 = x[10] - st[47] * v118;
        let v162: f64 = x[11] - st[48] * v118;
        let v163: f64 = x[12] - st[49] * v118;
        let v164: f64 = x[13] - st[50] * v118;
        let v165: f64 = v161 - st[51] * v111;
        let v166: f64 = v162 - st[52] * v111;
        let v167: f64 = v163 - st[53] * v111;
        let v168: f64 = v164 - st[54] * v111;
        let v169: f64 = v165 - st[55] * v120;
        let v170: f64 = v166 - st[56] * v120;
        let v171: f64 = v167 - st[57] * v120;
        let v172: f64 = v168 - st[58] * v120;
        let v173: f64 = v172 * st[25];
        let v174: f64 = v171 - st[11] * v173;
        let v175: f64 = v174 * st[24];
        let v176: f64 = v170 - st[8] * v175;
        let v177: f64 = v176 - st[10] * v173;
        let v178: f64 = v177 * st[23];
        let v179: f64 = v169 - st[6] * v178;
        let v180: f64 = v179 - st[7] * v175;
        let v181: f64 = v180 - st[9] * v173;
        let v182: f64 = v181 * st[22];
        x[10] = v182;
        x[11] = v178;
        x[12] = v175;
        x[13] = v173;
        Ok(())
    }
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    fn kkt_factor_1_avx(
        mass: &[f64],
        c: f64,
        phi_q: &[f64],
        st: &mut [f64],
        piv: &mut Pivoting,
    ) -> Result<(), KktError> {
        kkt_factor_1_any(mass, c, phi_q, st, piv)
    }
    fn kkt_factor_1(
        mass: &[f64],
        c: f64,
        phi_q: &[f64],
        st: &mut [f64],
        piv: &mut Pivoting,
    ) -> Result<(), KktError> {
        #[cfg(target_arch = "x86_64")]
        {
            if !symbody_runtime::kkt::kernels_run_here() {
                return Err(KktError::KernelsUnsupported);
            }
            unsafe { kkt_factor_1_avx(mass, c, phi_q, st, piv) }
        }
        #[cfg(not(target_arch = "x86_64"))] kkt_factor_1_any(mass, c, phi_q, st, piv)
    }
    #[allow(
        unused_variables,
        unused_parens,
        clippy::neg_cmp_op_on_partial_ord,
        clippy::nonminimal_bool
    )]
    #[inline(always)]
    fn kkt_factor_1_any(
        mass: &[f64],
        c: f64,
        phi_q: &[f64],
        st: &mut [f64],
        piv: &mut Pivoting,
    ) -> Result<(), KktError> {
        let mass: &[f64; 44] = mass
            .try_into()
            .map_err(|_| length_error(44, mass.len()))?;
        let phi_q: &[f64; 33] = phi_q
            .try_into()
            .map_err(|_| length_error(33, phi_q.len()))?;
        let st_len = st.len();
        let st: &mut [f64; 85] = st.try_into().map_err(|_| length_error(85, st_len))?;
        if !((c * mass[0]) > 0.0 && (c * mass[0]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[0]), 0));
        }
        let v0: f64 = (c * mass[0]).sqrt();
        let v1: f64 = 1.0 / v0;
        st[15] = v1;
        let v2: f64 = (c * mass[3]) * v1;
        st[0] = v2;
        let v3: f64 = (c * mass[6]) * v1;
        st[1] = v3;
        let v4: f64 = (c * mass[4]) - v2 * v2;
        if !(v4 > 0.0 && v4 <= f64::MAX) {
            return Err(mass_pivot_error(v4, 1));
        }
        let v5: f64 = v4.sqrt();
        let v6: f64 = 1.0 / v5;
        st[16] = v6;
        let v7: f64 = (c * mass[7]) - v3 * v2;
        let v8: f64 = v7 * v6;
        st[2] = v8;
        let v9: f64 = (c * mass[8]) - v3 * v3;
        let v10: f64 = v9 - v8 * v8;
        if !(v10 > 0.0 && v10 <= f64::MAX) {
            return Err(mass_pivot_error(v10, 2));
        }
        let v11: f64 = v10.sqrt();
        let v12: f64 = 1.0 / v11;
        st[17] = v12;
        let v13: f64 = phi_q[8] * v6;
        st[29] = v13;
        let v14: f64 = -(v8 * v13);
        let v15: f64 = v14 * v12;
        st[30] = v15;
        let v16: f64 = phi_q[9] * v12;
        st[31] = v16;
        let v17: f64 = v13 * v13;
        let v18: f64 = v15 * v15;
        let v19: f64 = v17 + v18;
        let v20: f64 = v16 * v15;
        let v21: f64 = v16 * v16;
        if !((c * mass[9]) > 0.0 && (c * mass[9]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[9]), 3));
        }
        let v22: f64 = (c * mass[9]).sqrt();
        let v23: f64 = 1.0 / v22;
        st[18] = v23;
        let v24: f64 = (c * mass[13]) * v23;
        st[3] = v24;
        let v25: f64 = (c * mass[17]) * v23;
        st[4] = v25;
        let v26: f64 = (c * mass[21]) * v23;
        st[6] = v26;
        let v27: f64 = (c * mass[14]) - v24 * v24;
        if !(v27 > 0.0 && v27 <= f64::MAX) {
            return Err(mass_pivot_error(v27, 4));
        }
        let v28: f64 = v27.sqrt();
        let v29: f64 = 1.0 / v28;
        st[19] = v29;
        let v30: f64 = (c * mass[18]) - v25 * v24;
        let v31: f64 = v30 * v29;
        st[5] = v31;
        let v32: f64 = (c * mass[22]) - v26 * v24;
        let v33: f64 = v32 * v29;
        st[7] = v33;
        let v34: f64 = (c * mass[19]) - v25 * v25;
        let v35: f64 = v34 - v31 * v31;
        if !(v35 > 0.0 && v35 <= f64::MAX) {
            return Err(mass_pivot_error(v35, 5));
        }
        let v36: f64 = v35.sqrt();
        let v37: f64 = 1.0 / v36;
        st[20] = v37;
        let v38: f64 = (c * mass[23]) - v26 * v25;
        let v39: f64 = v38 - v33 * v31;
        let v40: f64 = v39 * v37;
        st[8] = v40;
        let v41: f64 = (c * mass[24]) - v26 * v26;
        let v42: f64 = v41 - v33 * v33;
        let v43: f64 = v42 - v40 * v40;
        if !(v43 > 0.0 && v43 <= f64::MAX) {
            return Err(mass_pivot_error(v43, 6));
        }
        let v44: f64 = v43.sqrt();
        let v45: f64 = 1.0 / v44;
        st[21] = v45;
        let v46: f64 = phi_q[0] * v23;
        st[32] = v46;
        let v47: f64 = phi_q[1] - v24 * v46;
        let v48: f64 = v47 * v29;
        st[33] = v48;
        let v49: f64 = phi_q[2] - v25 * v46;
        let v50: f64 = v49 - v31 * v48;
        let v51: f64 = v50 * v37;
        st[34] = v51;
        let v52: f64 = phi_q[3] - v26 * v46;
        let v53: f64 = v52 - v33 * v48;
        let v54: f64 = v53 - v40 * v51;
        let v55: f64 = v54 * v45;
        st[35] = v55;
        let v56: f64 = phi_q[4] * v23;
        st[36] = v56;
        let v57: f64 = phi_q[5] - v24 * v56;
        let v58: f64 = v57 * v29;
        st[37] = v58;
        let v59: f64 = phi_q[6] - v25 * v56;
        let v60: f64 = v59 - v31 * v58;
        let v61: f64 = v60 * v37;
        st[38] = v61;
        let v62: f64 = phi_q[7] - v26 * v56;
        let v63: f64 = v62 - v33 * v58;
        let v64: f64 = v63 - v40 * v61;
        let v65: f64 = v64 * v45;
        st[39] = v65;
        let v66: f64 = phi_q[10] * v23;
        st[40] = v66;
        let v67: f64 = phi_q[11] - v24 * v66;
        let v68: f64 = v67 * v29;
        st[41] = v68;
        let v69: f64 = phi_q[12] - v25 * v66;
        let v70: f64 = v69 - v31 * v68;
        let v71: f64 = v70 * v37;
        st[42] = v71;
        let v72: f64 = phi_q[13] - v26 * v66;
        let v73: f64 = v72 - v33 * v68;
        let v74: f64 = v73 - v40 * v71;
        let v75: f64 = v74 * v45;
        st[43] = v75;
        let v76: f64 = phi_q[25] * v23;
        st[44] = v76;
        let v77: f64 = phi_q[26] - v24 * v76;
        let v78: f64 = v77 * v29;
        st[45] = v78;
        let v79: f64 = phi_q[27] - v25 * v76;
        let v80: f64 = v79 - v31 * v78;
        let v81: f64 = v80 * v37;
        st[46] = v81;
        let v82: f64 = phi_q[28] - v26 * v76;
        let v83: f64 = v82 - v33 * v78;
        let v84: f64 = v83 - v40 * v81;
        let v85: f64 = v84 * v45;
        st[47] = v85;
        let v86: f64 = v46 * v46;
        let v87: f64 = v48 * v48;
        let v88: f64 = v86 + v87;
        let v89: f64 = v51 * v51;
        let v90: f64 = v88 + v89;
        let v91: f64 = v55 * v55;
        let v92: f64 = v90 + v91;
        let v93: f64 = v56 * v46;
        let v94: f64 = v58 * v48;
        let v95: f64 = v93 + v94;
        let v96: f64 = v61 * v51;
        let v97: f64 = v95 + v96;
        let v98: f64 = v65 * v55;
        let v99: f64 = v97 + v98;
        let v100: f64 = v56 * v56;
        let v101: f64 = v58 * v58;
        let v102: f64 = v100 + v101;
        let v103: f64 = v61 * v61;
        let v104: f64 = v102 + v103;
        let v105: f64 = v65 * v65;
        let v106: f64 = v104 + v105;
        let v107: f64 = v66 * v46;
        let v108: f64 = v68 * v48;
        let v109: f64 = v107 + v108;
        let v110: f64 = v71 * v51;
        let v111: f64 = v109 + v110;
        let v112: f64 = v75 * v55;
        let v113: f64 = v111 + v112;
        let v114: f64 = v66 * v56;
        let v115: f64 = v68 * v58;
        let v116: f64 = v114 + v115;
        let v117: f64 = v71 * v61;
        let v118: f64 = v116 + v117;
        let v119: f64 = v75 * v65;
        let v120: f64 = v118 + v119;
        let v121: f64 = v66 * v66;
        let v122: f64 = v68 * v68;
        let v123: f64 = v121 + v122;
        let v124: f64 = v71 * v71;
        let v125: f64 = v123 + v124;
        let v126: f64 = v75 * v75;
        let v127: f64 = v125 + v126;
        let v128: f64 = v76 * v46;
        let v129: f64 = v78 * v48;
        let v130: f64 = v128 + v129;
        let v131: f64 = v81 * v51;
        let v132: f64 = v130 + v131;
        let v133: f64 = v85 * v55;
        let v134: f64 = v132 + v133;
        let v135: f64 = v76 * v56;
        let v136: f64 = v78 * v58;
        let v137: f64 = v135 + v136;
        let v138: f64 = v81 * v61;
        let v139: f64 = v137 + v138;
        let v140: f64 = v85 * v65;
        let v141: f64 = v139 + v140;
        let v142: f64 = v76 * v66;
        let v143: f64 = v78 * v68;
        let v144: f64 = v142 + v143;
        let v145: f64 = v81 * v71;
        let v146: f64 = v144 + v145;
        let v147: f64 = v85 * v75;
        let v148: f64 = v146 + v147;
        let v149: f64 = v76 * v76;
        let v150: f64 = v78 * v78;
        let v151: f64 = v149 + v150;
        let v152: f64 = v81 * v81;
        let v153: f64 = v151 + v152;
        let v154: f64 = v85 * v85;
        let v155: f64 = v153 + v154;
        if !((c * mass[25]) > 0.0 && (c * mass[25]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[25]), 7));
        }
        let v156: f64 = (c * mass[25]).sqrt();
        let v157: f64 = 1.0 / v156;
        st[22] = v157;
        let v158: f64 = phi_q[14] * v157;
        st[48] = v158;
        let v159: f64 = v158 * v158;
        if !((c * mass[26]) > 0.0 && (c * mass[26]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[26]), 8));
        }
        let v160: f64 = (c * mass[26]).sqrt();
        let v161: f64 = 1.0 / v160;
        st[23] = v161;
        let v162: f64 = phi_q[15] * v161;
        st[49] = v162;
        let v163: f64 = v162 * v162;
        if !((c * mass[27]) > 0.0 && (c * mass[27]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[27]), 9));
        }
        let v164: f64 = (c * mass[27]).sqrt();
        let v165: f64 = 1.0 / v164;
        st[24] = v165;
        let v166: f64 = phi_q[16] * v165;
        st[50] = v166;
        let v167: f64 = v166 * v166;
        if !((c * mass[28]) > 0.0 && (c * mass[28]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[28]), 10));
        }
        let v168: f64 = (c * mass[28]).sqrt();
        let v169: f64 = 1.0 / v168;
        st[25] = v169;
        let v170: f64 = (c * mass[32]) * v169;
        st[9] = v170;
        let v171: f64 = (c * mass[36]) * v169;
        st[10] = v171;
        let v172: f64 = (c * mass[40]) * v169;
        st[12] = v172;
        let v173: f64 = (c * mass[33]) - v170 * v170;
        if !(v173 > 0.0 && v173 <= f64::MAX) {
            return Err(mass_pivot_error(v173, 11));
        }
        let v174: f64 = v173.sqrt();
        let v175: f64 = 1.0 / v174;
        st[26] = v175;
        let v176: f64 = (c * mass[37]) - v171 * v170;
        let v177: f64 = v176 * v175;
        st[11] = v177;
        let v178: f64 = (c * mass[41]) - v172 * v170;
        let v179: f64 = v178 * v175;
        st[13] = v179;
        let v180: f64 = (c * mass[38]) - v171 * v171;
        let v181: f64 = v180 - v177 * v177;
        if !(v181 > 0.0 && v181 <= f64::MAX) {
            return Err(mass_pivot_error(v181, 12));
        }
        let v182: f64 = v181.sqrt();
        let v183: f64 = 1.0 / v182;
        st[27] = v183;
        let v184: f64 = (c * mass[42]) - v172 * v171;
        let v185: f64 = v184 - v179 * v177;
        let v186: f64 = v185 * v183;
        st[14] = v186;
        let v187: f64 = (c * mass[43]) - v172 * v172;
        let v188: f64 = v187 - v179 * v179;
        let v189: f64 = v188 - v186 * v186;
        if !(v189 > 0.0 && v189 <= f64::MAX) {
            return Err(mass_pivot_error(v189, 13));
        }
        let v190: f64 = v189.sqrt();
        let v191: f64 = 1.0 / v190;
        st[28] = v191;
        let v192: f64 = phi_q[17] * v169;
        st[51] = v192;
        let v193: f64 = phi_q[18] - v170 * v192;
        let v194: f64 = v193 * v175;
        st[52] = v194;
        let v195: f64 = phi_q[19] - v171 * v192;
        let v196: f64 = v195 - v177 * v194;
        let v197: f64 = v196 * v183;
        st[53] = v197;
        let v198: f64 = phi_q[20] - v172 * v192;
        let v199: f64 = v198 - v179 * v194;
        let v200: f64 = v199 - v186 * v197;
        let v201: f64 = v200 * v191;
        st[54] = v201;
        let v202: f64 = phi_q[21] * v169;
        st[55] = v202;
        let v203: f64 = phi_q[22] - v170 * v202;
        let v204: f64 = v203 * v175;
        st[56] = v204;
        let v205: f64 = phi_q[23] - v171 * v202;
        let v206: f64 = v205 - v177 * v204;
        let v207: f64 = v206 * v183;
        st[57] = v207;
        let v208: f64 = phi_q[24] - v172 * v202;
        let v209: f64 = v208 - v179 * v204;
        let v210: f64 = v209 - v186 * v207;
        let v211: f64 = v210 * v191;
        st[58] = v211;
        let v212: f64 = phi_q[29] * v169;
        st[59] = v212;
        let v213: f64 = phi_q[30] - v170 * v212;
        let v214: f64 = v213 * v175;
        st[60] = v214;
        let v215: f64 = phi_q[31] - v171 * v212;
        let v216: f64 = v215 - v177 * v214;
        let v217: f64 = v216 * v183;
        st[61] = v217;
        let v218: f64 = phi_q[32] - v172 * v212;
        let v219: f64 = v218 - v179 * v214;
        let v220: f64 = v219 - v186 * v217;
        let v221: f64 = v220 * v191;
        st[62] = v221;
        let v222: f64 = v192 * v192;
        let v223: f64 = v194 * v194;
        let v224: f64 = v222 + v223;
        let v225: f64 = v197 * v197;
        let v226: f64 = v224 + v225;
        let v227: f64 = v201 * v201;
        let v228: f64 = v226 + v227;
        let v229: f64 = v202 * v192;
        let v230: f64 = v204 * v194;
        let v231: f64 = v229 + v230;
        let v232: f64 = v207 * v197;
        let v233: f64 = v231 + v232;
        let v234: f64 = v211 * v201;
        let v235: f64 = v233 + v234;
        let v236: f64 = v202 * v202;
        let v237: f64 = v204 * v204;
        let v238: f64 = v236 + v237;
        let v239: f64 = v207 * v207;
        let v240: f64 = v238 + v239;
        let v241: f64 = v211 * v211;
        let v242: f64 = v240 + v241;
        let v243: f64 = v212 * v192;
        let v244: f64 = v214 * v194;
        let v245: f64 = v243 + v244;
        let v246: f64 = v217 * v197;
        let v247: f64 = v245 + v246;
        let v248: f64 = v221 * v201;
        let v249: f64 = v247 + v248;
        let v250: f64 = v212 * v202;
        let v251: f64 = v214 * v204;
        let v252: f64 = v250 + v251;
        let v253: f64 = v217 * v207;
        let v254: f64 = v252 + v253;
        let v255: f64 = v221 * v211;
        let v256: f64 = v254 + v255;
        let v257: f64 = v212 * v212;
        let v258: f64 = v214 * v214;
        let v259: f64 = v257 + v258;
        let v260: f64 = v217 * v217;
        let v261: f64 = v259 + v260;
        let v262: f64 = v221 * v221;
        let v263: f64 = v261 + v262;
        let (v264, v265) = piv.pivot(v155, v155, 10, false)?;
        st[73] = v264;
        let v266: f64 = v134 * v264;
        st[63] = v266;
        let v267: f64 = v92 - v266 * v265 * v266;
        let v268: f64 = v141 * v264;
        st[64] = v268;
        let v269: f64 = v106 - v268 * v265 * v268;
        let v270: f64 = v148 * v264;
        st[65] = v270;
        let v271: f64 = v127 - v270 * v265 * v270;
        let v272: f64 = v99 - v268 * v265 * v266;
        let v273: f64 = v113 - v270 * v265 * v266;
        let v274: f64 = v120 - v270 * v265 * v268;
        let (v275, v276) = piv.pivot(v263, v263, 11, false)?;
        st[74] = v275;
        let v277: f64 = v249 * v275;
        st[66] = v277;
        let v278: f64 = v228 - v277 * v276 * v277;
        let v279: f64 = v256 * v275;
        st[67] = v279;
        let v280: f64 = v242 - v279 * v276 * v279;
        let v281: f64 = v235 - v279 * v276 * v277;
        let (v282, v283) = piv.pivot(v159, v159, 5, false)?;
        st[75] = v282;
        let (v284, v285) = piv.pivot(v163, v163, 6, false)?;
        st[76] = v284;
        let (v286, v287) = piv.pivot(v167, v167, 7, false)?;
        st[77] = v286;
        let (v288, v289) = piv.pivot(v19, v19, 2, false)?;
        st[78] = v288;
        let v290: f64 = v20 * v288;
        st[68] = v290;
        let v291: f64 = v21 - v290 * v289 * v290;
        let (v292, v293) = piv.pivot(v291, v21, 3, false)?;
        st[79] = v292;
        let (v294, v295) = piv.pivot(v278, v278, 8, false)?;
        st[80] = v294;
        let v296: f64 = v281 * v294;
        st[69] = v296;
        let v297: f64 = v280 - v296 * v295 * v296;
        let (v298, v299) = piv.pivot(v297, v280, 9, false)?;
        st[81] = v298;
        let (v300, v301) = piv.pivot(v267, v267, 0, false)?;
        st[82] = v300;
        let v302: f64 = v272 * v300;
        st[70] = v302;
        let v303: f64 = v269 - v302 * v301 * v302;
        let v304: f64 = v273 * v300;
        st[71] = v304;
        let v305: f64 = v271 - v304 * v301 * v304;
        let v306: f64 = v274 - v304 * v301 * v302;
        let (v307, v308) = piv.pivot(v303, v269, 1, false)?;
        st[83] = v307;
        let v309: f64 = v306 * v307;
        st[72] = v309;
        let v310: f64 = v305 - v309 * v308 * v309;
        let (v311, v312) = piv.pivot(v310, v271, 4, false)?;
        st[84] = v311;
        Ok(())
    }
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx")]
    fn kkt_solve_1_avx(
        f: &[f64],
        g: &[f64],
        x: &mut [f64],
        y: &mut [f64],
        st: &[f64],
    ) -> Result<(), KktError> {
        kkt_solve_1_any(f, g, x, y, st)
    }
    fn kkt_solve_1(
        f: &[f64],
        g: &[f64],
        x: &mut [f64],
        y: &mut [f64],
        st: &[f64],
    ) -> Result<(), KktError> {
        #[cfg(target_arch = "x86_64")]
        {
            if !symbody_runtime::kkt::kernels_run_here() {
                return Err(KktError::KernelsUnsupported);
            }
            unsafe { kkt_solve_1_avx(f, g, x, y, st) }
        }
        #[cfg(not(target_arch = "x86_64"))] kkt_solve_1_any(f, g, x, y, st)
    }
    #[allow(
        unused_variables,
        clippy::neg_cmp_op_on_partial_ord,
        clippy::nonminimal_bool
    )]
    #[inline(always)]
    fn kkt_solve_1_any(
        f: &[f64],
        g: &[f64],
        x: &mut [f64],
        y: &mut [f64],
        st: &[f64],
    ) -> Result<(), KktError> {
        let f: &[f64; 14] = f.try_into().map_err(|_| length_error(14, f.len()))?;
        let g: &[f64; 12] = g.try_into().map_err(|_| length_error(12, g.len()))?;
        let x_len = x.len();
        let x: &mut [f64; 14] = x.try_into().map_err(|_| length_error(14, x_len))?;
        let y_len = y.len();
        let y: &mut [f64; 12] = y.try_into().map_err(|_| length_error(12, y_len))?;
        let st: &[f64; 85] = st.try_into().map_err(|_| length_error(85, st.len()))?;
        x.fill(0.0);
        y[0] = -g[0];
        y[1] = -g[1];
        y[2] = -g[2];
        y[3] = -g[3];
        y[4] = -g[4];
        y[5] = -g[5];
        y[6] = -g[6];
        y[7] = -g[7];
        y[8] = -g[8];
        y[9] = -g[9];
        y[10] = -g[10];
        y[11] = -g[11];
        if f.iter().any(|&v| v != 0.0) {
            let v0: f64 = f[0];
            let v1: f64 = f[1];
            let v2: f64 = f[2];
            let v3: f64 = v0 * st[15];
            let v4: f64 = v1 - st[0] * v3;
            let v5: f64 = v4 * st[16];
            let v6: f64 = v2 - st[1] * v3;
            let v7: f64 = v6 - st[2] * v5;
            let v8: f64 = v7 * st[17];
            let v9: f64 = st[29] * v5;
            let v10: f64 = st[30] * v8;
            let v11: f64 = v9 + v10;
            y[2] += v11;
            let v12: f64 = st[31] * v8;
            y[3] += v12;
            x[0] = v3;
            x[1] = v5;
            x[2] = v8;
            let v13: f64 = f[3];
            let v14: f64 = f[4];
            let v15: f64 = f[5];
            let v16: f64 = f[6];
            let v17: f64 = v13 * st[18];
            let v18: f64 = v14 - st[3] * v17;
            let v19: f64 = v18 * st[19];
            let v20: f64 = v15 - st[4] * v17;
            let v21: f64 = v20 - st[5] * v19;
            let v22: f64 = v21 * st[20];
            let v23: f64 = v16 - st[6] * v17;
            let v24: f64 = v23 - st[7] * v19;
            let v25: f64 = v24 - st[8] * v22;
            let v26: f64 = v25 * st[21];
            let v27: f64 = st[32] * v17;
            let v28: f64 = st[33] * v19;
            let v29: f64 = v27 + v28;
            let v30: f64 = st[34] * v22;
            let v31: f64 = v29 + v30;
            let v32: f64 = st[35] * v26;
            let v33: f64 = v31 + v32;
            y[0] += v33;
            let v34: f64 = st[36] * v17;
            let v35: f64 = st[37] * v19;
            let v36: f64 = v34 + v35;
            let v37: f64 = st[38] * v22;
            let v38: f64 = v36 + v37;
            let v39: f64 = st[39] * v26;
            let v40: f64 = v38 + v39;
            y[1] += v40;
            let v41: f64 = st[40] * v17;
            let v42: f64 = st[41] * v19;
            let v43: f64 = v41 + v42;
            let v44: f64 = st[42] * v22;
            let v45: f64 = v43 + v44;
            let v46: f64 = st[43] * v26;
            let v47: f64 = v45 + v46;
            y[4] += v47;
            let v48: f64 = st[44] * v17;
            let v49: f64 = st[45] * v19;
            let v50: f64 = v48 + v49;
            let v51: f64 = st[46] * v22;
            let v52: f64 = v50 + v51;
            let v53: f64 = st[47] * v26;
            let v54: f64 = v52 + v53;
            y[10] += v54;
            x[3] = v17;
            x[4] = v19;
            x[5] = v22;
            x[6] = v26;
            let v55: f64 = f[7];
            let v56: f64 = v55 * st[22];
            let v57: f64 = st[48] * v56;
            y[5] += v57;
            x[7] = v56;
            let v58: f64 = f[8];
            let v59: f64 = v58 * st[23];
            let v60: f64 = st[49] * v59;
            y[6] += v60;
            x[8] = v59;
            let v61: f64 = f[9];
            let v62: f64 = v61 * st[24];
            let v63: f64 = st[50] * v62;
            y[7] += v63;
            x[9] = v62;
            let v64: f64 = f[10];
            let v65: f64 = f[11];
            let v66: f64 = f[12];
            let v67: f64 = f[13];
            let v68: f64 = v64 * st[25];
            let v69: f64 = v65 - st[9] * v68;
            let v70: f64 = v69 * st[26];
            let v71: f64 = v66 - st[10] * v68;
            let v72: f64 = v71 - st[11] * v70;
            let v73: f64 = v72 * st[27];
            let v74: f64 = v67 - st[12] * v68;
            let v75: f64 = v74 - st[13] * v70;
            let v76: f64 = v75 - st[14] * v73;
            let v77: f64 = v76 * st[28];
            let v78: f64 = st[51] * v68;
            let v79: f64 = st[52] * v70;
            let v80: f64 = v78 + v79;
            let v81: f64 = st[53] * v73;
            let v82: f64 = v80 + v81;
            let v83: f64 = st[54] * v77;
            let v84: f64 = v82 + v83;
            y[8] += v84;
            let v85: f64 = st[55] * v68;
            let v86: f64 = st[56] * v70;
            let v87: f64 = v85 + v86;
            let v88: f64 = st[57] * v73;
            let v89: f64 = v87 + v88;
            let v90: f64 = st[58] * v77;
            let v91: f64 = v89 + v90;
            y[9] += v91;
            let v92: f64 = st[59] * v68;
            let v93: f64 = st[60] * v70;
            let v94: f64 = v92 + v93;
            let v95: f64 = st[61] * v73;
            let v96: f64 = v94 + v95;
            let v97: f64 = st[62] * v77;
            let v98: f64 = v96 + v97;
            y[11] += v98;
            x[10] = v68;
            x[11] = v70;
            x[12] = v73;
            x[13] = v77;
        }
        let v99: f64 = y[0] - st[63] * y[10];
        let v100: f64 = y[1] - st[64] * y[10];
        let v101: f64 = y[4] - st[65] * y[10];
        let v102: f64 = y[8] - st[66] * y[11];
        let v103: f64 = y[9] - st[67] * y[11];
        let v104: f64 = y[3] - st[68] * y[2];
        let v105: f64 = v103 - st[69] * v102;
        let v106: f64 = v100 - st[70] * v99;
        let v107: f64 = v101 - st[71] * v99;
        let v108: f64 = v107 - st[72] * v106;
        let v109: f64 = y[10] * st[73];
        let v110: f64 = y[11] * st[74];
        let v111: f64 = y[5] * st[75];
        let v112: f64 = y[6] * st[76];
        let v113: f64 = y[7] * st[77];
        let v114: f64 = y[2] * st[78];
        let v115: f64 = v104 * st[79];
        let v116: f64 = v102 * st[80];
        let v117: f64 = v105 * st[81];
        let v118: f64 = v99 * st[82];
        let v119: f64 = v106 * st[83];
        let v120: f64 = v108 * st[84];
        let v121: f64 = v119 - st[72] * v120;
        let v122: f64 = v118 - st[70] * v121;
        let v123: f64 = v122 - st[71] * v120;
        let v124: f64 = v116 - st[69] * v117;
        let v125: f64 = v114 - st[68] * v115;
        let v126: f64 = v110 - st[66] * v124;
        let v127: f64 = v126 - st[67] * v117;
        let v128: f64 = v109 - st[63] * v123;
        let v129: f64 = v128 - st[64] * v121;
        let v130: f64 = v129 - st[65] * v120;
        y[10] = v130;
        y[11] = v127;
        y[5] = v111;
        y[6] = v112;
        y[7] = v113;
        y[2] = v125;
        y[3] = v115;
        y[8] = v124;
        y[9] = v117;
        y[0] = v123;
        y[1] = v121;
        y[4] = v120;
        let v131: f64 = x[1] - st[29] * v125;
        let v132: f64 = x[2] - st[30] * v125;
        let v133: f64 = v132 - st[31] * v115;
        let v134: f64 = v133 * st[17];
        let v135: f64 = v131 - st[2] * v134;
        let v136: f64 = v135 * st[16];
        let v137: f64 = x[0] - st[0] * v136;
        let v138: f64 = v137 - st[1] * v134;
        let v139: f64 = v138 * st[15];
        x[0] = v139;
        x[1] = v136;
        x[2] = v134;
        let v140: f64 = x[3] - st[32] * v123;
        let v141: f64 = x[4] - st[33] * v123;
        let v142: f64 = x[5] - st[34] * v123;
        let v143: f64 = x[6] - st[35] * v123;
        let v144: f64 = v140 - st[36] * v121;
        let v145: f64 = v141 - st[37] * v121;
        let v146: f64 = v142 - st[38] * v121;
        let v147: f64 = v143 - st[39] * v121;
        let v148: f64 = v144 - st[40] * v120;
        let v149: f64 = v145 - st[41] * v120;
        let v150: f64 = v146 - st[42] * v120;
        let v151: f64 = v147 - st[43] * v120;
        let v152: f64 = v148 - st[44] * v130;
        let v153: f64 = v149 - st[45] * v130;
        let v154: f64 = v150 - st[46] * v130;
        let v155: f64 = v151 - st[47] * v130;
        let v156: f64 = v155 * st[21];
        let v157: f64 = v154 - st[8] * v156;
        let v158: f64 = v157 * st[20];
        let v159: f64 = v153 - st[5] * v158;
        let v160: f64 = v159 - st[7] * v156;
        let v161: f64 = v160 * st[19];
        let v162: f64 = v152 - st[3] * v161;
        let v163: f64 = v162 - st[4] * v158;
        let v164: f64 = v163 - st[6] * v156;
        let v165: f64 = v164 * st[18];
        x[3] = v165;
        x[4] = v161;
        x[5] = v158;
        x[6] = v156;
        let v166: f64 = x[7] - st[48] * v111;
        let v167: f64 = v166 * st[22];
        x[7] = v167;
        let v168: f64 = x[8] - st[49] * v112;
        let v169: f64 = v168 * st[23];
        x[8] = v169;
        let v170: f64 = x[9] - st[50] * v113;
        let v171: f64 = v170 * st[24];
        x[9] = v171;
        let v172: f64 = x[10] - st[51] * v124;
        let v173: f64 = x[11] - st[52] * v124;
        let v174: f64 = x[12] - st[53] * v124;
        let v175: f64 = x[13] - st[54] * v124;
        let v176: f64 = v172 - st[55] * v117;
        let v177: f64 = v173 - st[56] * v117;
        let v178: f64 = v174 - st[57] * v117;
        let v179: f64 = v175 - st[58] * v117;
        let v180: f64 = v176 - st[59] * v127;
        let v181: f64 = v177 - st[60] * v127;
        let v182: f64 = v178 - st[61] * v127;
        let v183: f64 = v179 - st[62] * v127;
        let v184: f64 = v183 * st[28];
        let v185: f64 = v182 - st[14] * v184;
        let v186: f64 = v185 * st[27];
        let v187: f64 = v181 - st[11] * v186;
        let v188: f64 = v187 - st[13] * v184;
        let v189: f64 = v188 * st[26];
        let v190: f64 = v180 - st[9] * v189;
        let v191: f64 = v190 - st[10] * v186;
        let v192: f64 = v191 - st[12] * v184;
        let v193: f64 = v192 * st[25];
        x[10] = v193;
        x[11] = v189;
        x[12] = v186;
        x[13] = v184;
        Ok(())
    }
    #[allow(unused_variables, clippy::too_many_arguments)]
    fn kkt_assemble_loads(
        mass: &[f64],
        c: f64,
        dq: &[f64],
        kq: f64,
        dqd: &[f64],
        kqd: f64,
        out: &mut [f64],
    ) -> Result<(), KktError> {
        let mass: &[f64; 38] = mass
            .try_into()
            .map_err(|_| length_error(38, mass.len()))?;
        let dq: &[f64; 25] = dq.try_into().map_err(|_| length_error(25, dq.len()))?;
        let dqd: &[f64; 25] = dqd.try_into().map_err(|_| length_error(25, dqd.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 44] = out.try_into().map_err(|_| length_error(44, out_len))?;
        let hq0 = 0.5 * kq * dq[0];
        let hq1 = 0.5 * kq * dq[1];
        let hq2 = 0.5 * kq * dq[2];
        let hq3 = 0.5 * kq * dq[3];
        let hq4 = 0.5 * kq * dq[4];
        let hq5 = 0.5 * kq * dq[5];
        let hq6 = 0.5 * kq * dq[6];
        let hq7 = 0.5 * kq * dq[7];
        let hq8 = 0.5 * kq * dq[8];
        let hq9 = 0.5 * kq * dq[9];
        let hq10 = 0.5 * kq * dq[10];
        let hq11 = 0.5 * kq * dq[11];
        let hq12 = 0.5 * kq * dq[12];
        let hq13 = 0.5 * kq * dq[13];
        let hq14 = 0.5 * kq * dq[14];
        let hq15 = 0.5 * kq * dq[15];
        let hq16 = 0.5 * kq * dq[16];
        let hq17 = 0.5 * kq * dq[17];
        let hq18 = 0.5 * kq * dq[18];
        let hq19 = 0.5 * kq * dq[19];
        let hq20 = 0.5 * kq * dq[20];
        let hq21 = 0.5 * kq * dq[21];
        let hq22 = 0.5 * kq * dq[22];
        let hq23 = 0.5 * kq * dq[23];
        let hq24 = 0.5 * kq * dq[24];
        let hd0 = 0.5 * kqd * dqd[0];
        let hd1 = 0.5 * kqd * dqd[1];
        let hd2 = 0.5 * kqd * dqd[2];
        let hd3 = 0.5 * kqd * dqd[3];
        let hd4 = 0.5 * kqd * dqd[4];
        let hd5 = 0.5 * kqd * dqd[5];
        let hd6 = 0.5 * kqd * dqd[6];
        let hd7 = 0.5 * kqd * dqd[7];
        let hd8 = 0.5 * kqd * dqd[8];
        let hd9 = 0.5 * kqd * dqd[9];
        let hd10 = 0.5 * kqd * dqd[10];
        let hd11 = 0.5 * kqd * dqd[11];
        let hd12 = 0.5 * kqd * dqd[12];
        let hd13 = 0.5 * kqd * dqd[13];
        let hd14 = 0.5 * kqd * dqd[14];
        let hd15 = 0.5 * kqd * dqd[15];
        let hd16 = 0.5 * kqd * dqd[16];
        let hd17 = 0.5 * kqd * dqd[17];
        let hd18 = 0.5 * kqd * dqd[18];
        let hd19 = 0.5 * kqd * dqd[19];
        let hd20 = 0.5 * kqd * dqd[20];
        let hd21 = 0.5 * kqd * dqd[21];
        let hd22 = 0.5 * kqd * dqd[22];
        let hd23 = 0.5 * kqd * dqd[23];
        let hd24 = 0.5 * kqd * dqd[24];
        out[0] = c * mass[0] - hq0 - hq0 - hd0 - hd0;
        out[1] = 0.0 - hq1 - hq3 - hd1 - hd3;
        out[2] = 0.0 - hq2 - hq6 - hd2 - hd6;
        out[3] = 0.0 - hq1 - hq3 - hd1 - hd3;
        out[4] = c * mass[1] - hq4 - hq4 - hd4 - hd4;
        out[5] = 0.0 - hq5 - hq7 - hd5 - hd7;
        out[6] = 0.0 - hq2 - hq6 - hd2 - hd6;
        out[7] = 0.0 - hq5 - hq7 - hd5 - hd7;
        out[8] = c * mass[2] - hq8 - hq8 - hd8 - hd8;
        out[9] = c * mass[3];
        out[10] = c * mass[4];
        out[11] = c * mass[5];
        out[12] = c * mass[6];
        out[13] = c * mass[7];
        out[14] = c * mass[8];
        out[15] = c * mass[9];
        out[16] = c * mass[10];
        out[17] = c * mass[11];
        out[18] = c * mass[12];
        out[19] = c * mass[13];
        out[20] = c * mass[14];
        out[21] = c * mass[15];
        out[22] = c * mass[16];
        out[23] = c * mass[17];
        out[24] = c * mass[18];
        out[25] = c * mass[19];
        out[26] = c * mass[20];
        out[27] = c * mass[21];
        out[28] = c * mass[22] - hq9 - hq9 - hd9 - hd9;
        out[29] = c * mass[23] - hq10 - hq13 - hd10 - hd13;
        out[30] = c * mass[24] - hq11 - hq17 - hd11 - hd17;
        out[31] = c * mass[25] - hq12 - hq21 - hd12 - hd21;
        out[32] = c * mass[26] - hq10 - hq13 - hd10 - hd13;
        out[33] = c * mass[27] - hq14 - hq14 - hd14 - hd14;
        out[34] = c * mass[28] - hq15 - hq18 - hd15 - hd18;
        out[35] = c * mass[29] - hq16 - hq22 - hd16 - hd22;
        out[36] = c * mass[30] - hq11 - hq17 - hd11 - hd17;
        out[37] = c * mass[31] - hq15 - hq18 - hd15 - hd18;
        out[38] = c * mass[32] - hq19 - hq19 - hd19 - hd19;
        out[39] = c * mass[33] - hq20 - hq23 - hd20 - hd23;
        out[40] = c * mass[34] - hq12 - hq21 - hd12 - hd21;
        out[41] = c * mass[35] - hq16 - hq22 - hd16 - hd22;
        out[42] = c * mass[36] - hq20 - hq23 - hd20 - hd23;
        out[43] = c * mass[37] - hq24 - hq24 - hd24 - hd24;
        Ok(())
    }
    fn kkt_transpose_times(
        phi_q: &[f64],
        y: &[f64],
        out: &mut [f64],
    ) -> Result<(), KktError> {
        let phi_q: &[f64; 33] = phi_q
            .try_into()
            .map_err(|_| length_error(33, phi_q.len()))?;
        let y: &[f64; 12] = y.try_into().map_err(|_| length_error(12, y.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 14] = out.try_into().map_err(|_| length_error(14, out_len))?;
        out[0] = 0.0;
        out[1] = phi_q[8] * y[2];
        out[2] = phi_q[9] * y[3];
        out[3] = phi_q[0] * y[0] + phi_q[4] * y[1] + phi_q[10] * y[4]
            + phi_q[25] * y[10];
        out[4] = phi_q[1] * y[0] + phi_q[5] * y[1] + phi_q[11] * y[4]
            + phi_q[26] * y[10];
        out[5] = phi_q[2] * y[0] + phi_q[6] * y[1] + phi_q[12] * y[4]
            + phi_q[27] * y[10];
        out[6] = phi_q[3] * y[0] + phi_q[7] * y[1] + phi_q[13] * y[4]
            + phi_q[28] * y[10];
        out[7] = phi_q[14] * y[5];
        out[8] = phi_q[15] * y[6];
        out[9] = phi_q[16] * y[7];
        out[10] = phi_q[17] * y[8] + phi_q[21] * y[9] + phi_q[29] * y[11];
        out[11] = phi_q[18] * y[8] + phi_q[22] * y[9] + phi_q[30] * y[11];
        out[12] = phi_q[19] * y[8] + phi_q[23] * y[9] + phi_q[31] * y[11];
        out[13] = phi_q[20] * y[8] + phi_q[24] * y[9] + phi_q[32] * y[11];
        Ok(())
    }
    #[allow(clippy::assign_op_pattern)]
    fn kkt_times_add(phi_q: &[f64], x: &[f64], out: &mut [f64]) -> Result<(), KktError> {
        let phi_q: &[f64; 33] = phi_q
            .try_into()
            .map_err(|_| length_error(33, phi_q.len()))?;
        let x: &[f64; 14] = x.try_into().map_err(|_| length_error(14, x.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 12] = out.try_into().map_err(|_| length_error(12, out_len))?;
        out[0] = out[0] + phi_q[0] * x[3] + phi_q[1] * x[4] + phi_q[2] * x[5]
            + phi_q[3] * x[6];
        out[1] = out[1] + phi_q[4] * x[3] + phi_q[5] * x[4] + phi_q[6] * x[5]
            + phi_q[7] * x[6];
        out[2] = out[2] + phi_q[8] * x[1];
        out[3] = out[3] + phi_q[9] * x[2];
        out[4] = out[4] + phi_q[10] * x[3] + phi_q[11] * x[4] + phi_q[12] * x[5]
            + phi_q[13] * x[6];
        out[5] = out[5] + phi_q[14] * x[7];
        out[6] = out[6] + phi_q[15] * x[8];
        out[7] = out[7] + phi_q[16] * x[9];
        out[8] = out[8] + phi_q[17] * x[10] + phi_q[18] * x[11] + phi_q[19] * x[12]
            + phi_q[20] * x[13];
        out[9] = out[9] + phi_q[21] * x[10] + phi_q[22] * x[11] + phi_q[23] * x[12]
            + phi_q[24] * x[13];
        out[10] = out[10] + phi_q[25] * x[3] + phi_q[26] * x[4] + phi_q[27] * x[5]
            + phi_q[28] * x[6];
        out[11] = out[11] + phi_q[29] * x[10] + phi_q[30] * x[11] + phi_q[31] * x[12]
            + phi_q[32] * x[13];
        Ok(())
    }
    fn kkt_mass_times(mass: &[f64], v: &[f64], out: &mut [f64]) -> Result<(), KktError> {
        let mass: &[f64; 38] = mass
            .try_into()
            .map_err(|_| length_error(38, mass.len()))?;
        let v: &[f64; 14] = v.try_into().map_err(|_| length_error(14, v.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 14] = out.try_into().map_err(|_| length_error(14, out_len))?;
        out[0] = 0.0 + mass[0] * v[0];
        out[1] = 0.0 + mass[1] * v[1];
        out[2] = 0.0 + mass[2] * v[2];
        out[3] = 0.0 + mass[3] * v[3] + mass[4] * v[4] + mass[5] * v[5] + mass[6] * v[6];
        out[4] = 0.0 + mass[7] * v[3] + mass[8] * v[4] + mass[9] * v[5]
            + mass[10] * v[6];
        out[5] = 0.0 + mass[11] * v[3] + mass[12] * v[4] + mass[13] * v[5]
            + mass[14] * v[6];
        out[6] = 0.0 + mass[15] * v[3] + mass[16] * v[4] + mass[17] * v[5]
            + mass[18] * v[6];
        out[7] = 0.0 + mass[19] * v[7];
        out[8] = 0.0 + mass[20] * v[8];
        out[9] = 0.0 + mass[21] * v[9];
        out[10] = 0.0 + mass[22] * v[10] + mass[23] * v[11] + mass[24] * v[12]
            + mass[25] * v[13];
        out[11] = 0.0 + mass[26] * v[10] + mass[27] * v[11] + mass[28] * v[12]
            + mass[29] * v[13];
        out[12] = 0.0 + mass[30] * v[10] + mass[31] * v[11] + mass[32] * v[12]
            + mass[33] * v[13];
        out[13] = 0.0 + mass[34] * v[10] + mass[35] * v[11] + mass[36] * v[12]
            + mass[37] * v[13];
        Ok(())
    }
    fn kkt_kinetic_energy(mass: &[f64], qd: &[f64]) -> Result<f64, KktError> {
        let mass: &[f64; 38] = mass
            .try_into()
            .map_err(|_| length_error(38, mass.len()))?;
        let qd: &[f64; 14] = qd.try_into().map_err(|_| length_error(14, qd.len()))?;
        let mut t = 0.0;
        t += qd[0] * mass[0] * qd[0];
        t += qd[1] * mass[1] * qd[1];
        t += qd[2] * mass[2] * qd[2];
        t += qd[3] * mass[3] * qd[3];
        t += qd[3] * mass[4] * qd[4];
        t += qd[3] * mass[5] * qd[5];
        t += qd[3] * mass[6] * qd[6];
        t += qd[4] * mass[7] * qd[3];
        t += qd[4] * mass[8] * qd[4];
        t += qd[4] * mass[9] * qd[5];
        t += qd[4] * mass[10] * qd[6];
        t += qd[5] * mass[11] * qd[3];
        t += qd[5] * mass[12] * qd[4];
        t += qd[5] * mass[13] * qd[5];
        t += qd[5] * mass[14] * qd[6];
        t += qd[6] * mass[15] * qd[3];
        t += qd[6] * mass[16] * qd[4];
        t += qd[6] * mass[17] * qd[5];
        t += qd[6] * mass[18] * qd[6];
        t += qd[7] * mass[19] * qd[7];
        t += qd[8] * mass[20] * qd[8];
        t += qd[9] * mass[21] * qd[9];
        t += qd[10] * mass[22] * qd[10];
        t += qd[10] * mass[23] * qd[11];
        t += qd[10] * mass[24] * qd[12];
        t += qd[10] * mass[25] * qd[13];
        t += qd[11] * mass[26] * qd[10];
        t += qd[11] * mass[27] * qd[11];
        t += qd[11] * mass[28] * qd[12];
        t += qd[11] * mass[29] * qd[13];
        t += qd[12] * mass[30] * qd[10];
        t += qd[12] * mass[31] * qd[11];
        t += qd[12] * mass[32] * qd[12];
        t += qd[12] * mass[33] * qd[13];
        t += qd[13] * mass[34] * qd[10];
        t += qd[13] * mass[35] * qd[11];
        t += qd[13] * mass[36] * qd[12];
        t += qd[13] * mass[37] * qd[13];
        Ok(0.5 * t)
    }
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
        let x13 = symbody_runtime::trig::sin(t);
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
        let x3028 = t * k[1];
        let x3029 = symbody_runtime::trig::sin(x3028);
        let x3030 = k[0] * x3029;
        let x3034 = t * k[4];
        let x3035 = symbody_runtime::trig::cos(x3034);
        let x3036 = k[3] * x3035;
        let x3038 = x13 * k[5];
        let x3047 = x348 * k[9];
        let x3048 = x347 * k[6];
        let x3050 = x3030 - x3048;
        let x3052 = x3050 - x3047;
        let x3060 = x367 * k[10];
        let x3061 = x389 * k[7];
        let x3063 = x3036 - x3061;
        let x3065 = x3063 - x3060;
        let x3256 = x359 * k[9];
        let x3257 = x1305 * k[6];
        let x3258 = x3256 + x3257;
        let x3259 = x359 * x3258;
        let x3261 = x1315 * x3052;
        let x3262 = x3261 - x3259;
        let x3263 = x360 * x3258;
        let x3264 = x1316 * x3052;
        let x3265 = x3263 + x3264;
        let x3266 = -x3265;
        let x3267 = x361 * x3258;
        let x3268 = x1318 * x3052;
        let x3269 = x3267 + x3268;
        let x3270 = -x3269;
        let x3271 = x360 * k[9];
        let x3272 = x1342 * k[6];
        let x3273 = x3271 + x3272;
        let x3274 = x359 * x3273;
        let x3275 = x1349 * x3052;
        let x3276 = x3274 + x3275;
        let x3277 = -x3276;
        let x3278 = x360 * x3273;
        let x3280 = x1353 * x3052;
        let x3281 = x3280 - x3278;
        let x3282 = x361 * x3273;
        let x3283 = x1354 * x3052;
        let x3284 = x3282 + x3283;
        let x3285 = -x3284;
        let x3286 = x361 * k[9];
        let x3287 = x1378 * k[6];
        let x3288 = x3286 + x3287;
        let x3289 = x359 * x3288;
        let x3290 = x1385 * x3052;
        let x3291 = x3289 + x3290;
        let x3292 = -x3291;
        let x3293 = x360 * x3288;
        let x3294 = x1387 * x3052;
        let x3295 = x3293 + x3294;
        let x3296 = -x3295;
        let x3297 = x361 * x3288;
        let x3299 = x1391 * x3052;
        let x3300 = x3299 - x3297;
        let x3301 = x405 * k[10];
        let x3302 = x1431 * k[7];
        let x3303 = x3301 + x3302;
        let x3304 = x405 * x3303;
        let x3306 = x1445 * x3065;
        let x3307 = x3306 - x3304;
        let x3308 = x412 * x3303;
        let x3309 = x1453 * x3065;
        let x3310 = x3308 + x3309;
        let x3311 = -x3310;
        let x3312 = x414 * x3303;
        let x3314 = x1459 * x3065;
        let x3315 = x3314 - x3312;
        let x3316 = x417 * x3303;
        let x3318 = x1463 * x3065;
        let x3319 = x3318 - x3316;
        let x3320 = 2.0 * x3038;
        let x3321 = x3315 + x3320;
        let x3322 = -x3319;
        let x3323 = x412 * k[10];
        let x3324 = x1502 * k[7];
        let x3325 = x3323 + x3324;
        let x3326 = x405 * x3325;
        let x3328 = x1511 * x3065;
        let x3329 = x3328 - x3326;
        let x3330 = x412 * x3325;
        let x3332 = x1517 * x3065;
        let x3333 = x3332 - x3330;
        let x3334 = x414 * x3325;
        let x3336 = x1521 * x3065;
        let x3337 = x3336 - x3334;
        let x3338 = x417 * x3325;
        let x3340 = x1526 * x3065;
        let x3341 = x3340 - x3338;
        let x3342 = x3320 + x3341;
        let x3343 = -x3342;
        let x3344 = x414 * k[10];
        let x3345 = x1556 * k[7];
        let x3346 = x3344 + x3345;
        let x3347 = x405 * x3346;
        let x3349 = x1567 * x3065;
        let x3350 = x3349 - x3347;
        let x3351 = x412 * x3346;
        let x3353 = x1570 * x3065;
        let x3354 = x3353 - x3351;
        let x3355 = x414 * x3346;
        let x3357 = x1571 * x3065;
        let x3358 = x3357 - x3355;
        let x3359 = x417 * x3346;
        let x3361 = x1572 * x3065;
        let x3362 = x3361 - x3359;
        let x3364 = x3350 - x3320;
        let x3365 = -x3362;
        let x3366 = x417 * k[10];
        let x3367 = x1602 * k[7];
        let x3369 = x3366 - x3367;
        let x3370 = x405 * x3369;
        let x3371 = x1610 * x3065;
        let x3372 = x3370 + x3371;
        let x3373 = x412 * x3369;
        let x3374 = x1616 * x3065;
        let x3375 = x3373 + x3374;
        let x3376 = x414 * x3369;
        let x3377 = x1617 * x3065;
        let x3379 = x3376 - x3377;
        let x3380 = x417 * x3369;
        let x3381 = x1619 * x3065;
        let x3383 = x3380 - x3381;
        let x3384 = x3320 + x3375;
        let x3385 = -x3383;
        let x3386 = x359 * k[6];
        let x3387 = x359 * x3386;
        let x3388 = -x3387;
        let x3389 = x360 * x3386;
        let x3390 = -x3389;
        let x3391 = x361 * x3386;
        let x3392 = -x3391;
        let x3393 = x360 * k[6];
        let x3394 = x359 * x3393;
        let x3395 = -x3394;
        let x3396 = x360 * x3393;
        let x3397 = -x3396;
        let x3398 = x361 * x3393;
        let x3399 = -x3398;
        let x3400 = x361 * k[6];
        let x3401 = x359 * x3400;
        let x3402 = -x3401;
        let x3403 = x360 * x3400;
        let x3404 = -x3403;
        let x3405 = x361 * x3400;
        let x3406 = -x3405;
        let x3407 = x405 * k[7];
        let x3408 = x405 * x3407;
        let x3409 = -x3408;
        let x3410 = x412 * x3407;
        let x3411 = -x3410;
        let x3412 = x414 * x3407;
        let x3413 = -x3412;
        let x3414 = x417 * x3407;
        let x3415 = x412 * k[7];
        let x3416 = x405 * x3415;
        let x3417 = -x3416;
        let x3418 = x412 * x3415;
        let x3419 = -x3418;
        let x3420 = x414 * x3415;
        let x3421 = -x3420;
        let x3422 = x417 * x3415;
        let x3423 = x414 * k[7];
        let x3424 = x405 * x3423;
        let x3425 = -x3424;
        let x3426 = x412 * x3423;
        let x3427 = -x3426;
        let x3428 = x414 * x3423;
        let x3429 = -x3428;
        let x3430 = x417 * x3423;
        let x3431 = x417 * k[7];
        let x3432 = x405 * x3431;
        let x3433 = x412 * x3431;
        let x3434 = x414 * x3431;
        let x3435 = x417 * x3431;
        let x3436 = -x3435;
        dq[0] = x3262;
        dq[1] = x3277;
        dq[2] = x3292;
        dq[3] = x3266;
        dq[4] = x3281;
        dq[5] = x3296;
        dq[6] = x3270;
        dq[7] = x3285;
        dq[8] = x3300;
        dq[9] = x3307;
        dq[10] = x3329;
        dq[11] = x3364;
        dq[12] = x3372;
        dq[13] = x3311;
        dq[14] = x3333;
        dq[15] = x3354;
        dq[16] = x3384;
        dq[17] = x3321;
        dq[18] = x3337;
        dq[19] = x3358;
        dq[20] = x3379;
        dq[21] = x3322;
        dq[22] = x3343;
        dq[23] = x3365;
        dq[24] = x3385;
        dqd[0] = x3388;
        dqd[1] = x3395;
        dqd[2] = x3402;
        dqd[3] = x3390;
        dqd[4] = x3397;
        dqd[5] = x3404;
        dqd[6] = x3392;
        dqd[7] = x3399;
        dqd[8] = x3406;
        dqd[9] = x3409;
        dqd[10] = x3417;
        dqd[11] = x3425;
        dqd[12] = x3432;
        dqd[13] = x3411;
        dqd[14] = x3419;
        dqd[15] = x3427;
        dqd[16] = x3433;
        dqd[17] = x3413;
        dqd[18] = x3421;
        dqd[19] = x3429;
        dqd[20] = x3434;
        dqd[21] = x3414;
        dqd[22] = x3422;
        dqd[23] = x3430;
        dqd[24] = x3436;
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
        let x3094 = x965 * k[8];
        let x3095 = x963 + x3094;
        let x3096 = x971 + x3095;
        let x3097 = 0.5 * x3096;
        let x3098 = x81 * k[16];
        let x3099 = x3097 + x3098;
        let x3100 = x983 * k[8];
        let x3102 = x982 - x3100;
        let x3103 = x988 + x3102;
        let x3104 = 0.5 * x3103;
        let x3106 = x109 * k[16];
        let x3107 = x3106 - x3104;
        let x3108 = x997 * k[8];
        let x3109 = x996 + x3108;
        let x3110 = x3109 - x1001;
        let x3111 = 0.5 * x3110;
        let x3113 = x103 * k[16];
        let x3114 = x3113 - x3111;
        let x3115 = x1013 * k[8];
        let x3116 = x3115 - x1011;
        let x3117 = x1016 + x3116;
        let x3118 = 0.5 * x3117;
        let x3120 = x96 * k[16];
        let x3121 = x3120 - x3118;
        let x3122 = x987 * k[8];
        let x3123 = x3122 - x1025;
        let x3124 = x3123 - x1030;
        let x3125 = 0.5 * x3124;
        let x3126 = x3106 + x3125;
        let x3127 = x969 * k[8];
        let x3128 = x1037 + x3127;
        let x3129 = x1040 + x3128;
        let x3130 = 0.5 * x3129;
        let x3131 = x82 * k[16];
        let x3132 = x3130 + x3131;
        let x3133 = x1015 * k[8];
        let x3135 = x1047 - x3133;
        let x3136 = x3135 - x1051;
        let x3137 = 0.5 * x3136;
        let x3138 = x94 * k[16];
        let x3139 = x3137 + x3138;
        let x3140 = x999 * k[8];
        let x3141 = x1060 + x3140;
        let x3143 = x1064 - x3141;
        let x3144 = 0.5 * x3143;
        let x3145 = x101 * k[16];
        let x3146 = x3144 + x3145;
        let x3147 = x1058 * k[8];
        let x3148 = x1071 + x3147;
        let x3150 = x1076 - x3148;
        let x3151 = 0.5 * x3150;
        let x3152 = x3113 + x3151;
        let x3153 = x1046 * k[8];
        let x3155 = x1083 - x3153;
        let x3156 = x3155 - x1087;
        let x3157 = 0.5 * x3156;
        let x3158 = x3138 + x3157;
        let x3159 = x1036 * k[8];
        let x3160 = x1093 + x3159;
        let x3161 = x1095 + x3160;
        let x3162 = 0.5 * x3161;
        let x3163 = x83 * k[16];
        let x3164 = x3162 + x3163;
        let x3165 = x1023 * k[8];
        let x3166 = x3165 - x1102;
        let x3167 = x3166 - x1105;
        let x3168 = 0.5 * x3167;
        let x3169 = x107 * k[16];
        let x3170 = x3168 + x3169;
        let x3171 = x1009 * k[8];
        let x3173 = x1112 - x3171;
        let x3174 = x3173 - x1116;
        let x3175 = 0.5 * x3174;
        let x3176 = x3120 + x3175;
        let x3177 = x995 * k[8];
        let x3178 = x1122 + x3177;
        let x3180 = x1126 - x3178;
        let x3181 = 0.5 * x3180;
        let x3182 = x3145 + x3181;
        let x3183 = x981 * k[8];
        let x3184 = x3183 - x1132;
        let x3185 = x3184 - x1135;
        let x3186 = 0.5 * x3185;
        let x3187 = x3169 + x3186;
        let x3188 = x961 * k[8];
        let x3189 = x1141 + x3188;
        let x3190 = x1144 + x3189;
        let x3191 = 0.5 * x3190;
        let x3192 = x84 * k[16];
        let x3193 = x3191 + x3192;
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
        out[22] = x3099;
        out[23] = x3107;
        out[24] = x3114;
        out[25] = x3121;
        out[26] = x3126;
        out[27] = x3132;
        out[28] = x3139;
        out[29] = x3146;
        out[30] = x3152;
        out[31] = x3158;
        out[32] = x3164;
        out[33] = x3170;
        out[34] = x3176;
        out[35] = x3182;
        out[36] = x3187;
        out[37] = x3193;
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
        let x13 = symbody_runtime::trig::sin(t);
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
        let x3028 = t * k[1];
        let x3029 = symbody_runtime::trig::sin(x3028);
        let x3030 = k[0] * x3029;
        let x3034 = t * k[4];
        let x3035 = symbody_runtime::trig::cos(x3034);
        let x3036 = k[3] * x3035;
        let x3038 = x13 * k[5];
        let x3047 = x348 * k[9];
        let x3048 = x347 * k[6];
        let x3050 = x3030 - x3048;
        let x3052 = x3050 - x3047;
        let x3056 = x359 * x3052;
        let x3057 = x360 * x3052;
        let x3058 = x361 * x3052;
        let x3060 = x367 * k[10];
        let x3061 = x389 * k[7];
        let x3063 = x3036 - x3061;
        let x3065 = x3063 - x3060;
        let x3069 = x405 * x3065;
        let x3070 = x412 * x3065;
        let x3071 = x414 * x3065;
        let x3072 = x417 * x3065;
        let x3074 = x144 * x3038;
        let x3076 = x145 * x3038;
        let x3077 = x142 * x3038;
        let x3078 = x143 * x3038;
        let x3079 = k[2] + x3056;
        let x3080 = x3069 - x3074;
        let x3081 = x3070 + x3076;
        let x3082 = x3071 + x3077;
        let x3083 = x3072 + x3078;
        let x3092 = k[12] + x3057;
        let x3194 = x1171 * k[8];
        let x3195 = x1168 + x3194;
        let x3196 = x1176 + x3195;
        let x3197 = 0.5 * x3196;
        let x3198 = x1185 * k[8];
        let x3200 = x1182 - x3198;
        let x3201 = x1191 + x3200;
        let x3202 = 0.5 * x3201;
        let x3203 = x1199 * k[8];
        let x3204 = x1196 + x3203;
        let x3205 = x3204 - x1204;
        let x3206 = 0.5 * x3205;
        let x3207 = x1214 * k[8];
        let x3208 = x3207 - x1210;
        let x3209 = x1219 + x3208;
        let x3210 = 0.5 * x3209;
        let x3211 = x1169 * k[8];
        let x3212 = x1168 + x3211;
        let x3213 = x1231 + x3212;
        let x3214 = 0.5 * x3213;
        let x3215 = x3197 + x3214;
        let x3216 = q[10] * k[16];
        let x3217 = x1229 * x3216;
        let x3219 = x3215 - x3217;
        let x3220 = x1183 * k[8];
        let x3221 = x3220 - x1182;
        let x3222 = x3221 - x1248;
        let x3223 = 0.5 * x3222;
        let x3225 = x3223 - x3202;
        let x3226 = q[11] * k[16];
        let x3227 = x1229 * x3226;
        let x3229 = x3225 - x3227;
        let x3230 = x1197 * k[8];
        let x3231 = x1196 + x3230;
        let x3233 = x1266 - x3231;
        let x3234 = 0.5 * x3233;
        let x3236 = x3234 - x3206;
        let x3237 = q[12] * k[16];
        let x3238 = x1229 * x3237;
        let x3240 = x3236 - x3238;
        let x3241 = x1212 * k[8];
        let x3243 = x1210 - x3241;
        let x3244 = x3243 - x1283;
        let x3245 = 0.5 * x3244;
        let x3247 = x3245 - x3210;
        let x3248 = q[13] * k[16];
        let x3249 = x1229 * x3248;
        let x3251 = x3247 - x3249;
        let x3252 = x3080 + x3219;
        let x3253 = x3081 + x3229;
        let x3254 = x3082 + x3240;
        let x3255 = x3251 - x3083;
        out[0] = x3079;
        out[1] = x3092;
        out[2] = x3058;
        out[3] = x805;
        out[4] = x824;
        out[5] = x842;
        out[6] = x859;
        out[7] = 0.0;
        out[8] = -9.81;
        out[9] = 0.0;
        out[10] = x3252;
        out[11] = x3253;
        out[12] = x3254;
        out[13] = x3255;
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
        let x13 = symbody_runtime::trig::sin(t);
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
        let x3034 = t * k[4];
        s[86] = x3034;
        let x3035 = symbody_runtime::trig::cos(x3034);
        s[87] = x3035;
        let x3036 = k[3] * x3035;
        s[88] = x3036;
        let x3038 = x13 * k[5];
        s[89] = x3038;
        let x3060 = x367 * k[10];
        s[90] = x3060;
        let x3061 = x389 * k[7];
        s[91] = x3061;
        let x3063 = x3036 - x3061;
        s[92] = x3063;
        let x3065 = x3063 - x3060;
        s[93] = x3065;
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
        let x3028 = t * k[1];
        let x3029 = symbody_runtime::trig::sin(x3028);
        let x3030 = k[0] * x3029;
        let x3047 = x348 * k[9];
        let x3048 = x347 * k[6];
        let x3050 = x3030 - x3048;
        let x3052 = x3050 - x3047;
        let x3056 = x359 * x3052;
        let x3057 = x360 * x3052;
        let x3058 = x361 * x3052;
        let x3069 = x405 * s[93];
        let x3074 = s[13] * s[89];
        let x3079 = k[2] + x3056;
        let x3080 = x3069 - x3074;
        let x3092 = k[12] + x3057;
        let x3094 = x965 * k[8];
        let x3095 = x963 + x3094;
        let x3096 = x971 + x3095;
        let x3097 = 0.5 * x3096;
        let x3098 = s[1] * k[16];
        let x3099 = x3097 + x3098;
        let x3100 = x983 * k[8];
        let x3102 = x982 - x3100;
        let x3103 = x988 + x3102;
        let x3104 = 0.5 * x3103;
        let x3106 = x109 * k[16];
        let x3107 = x3106 - x3104;
        let x3108 = x997 * k[8];
        let x3109 = x996 + x3108;
        let x3110 = x3109 - x1001;
        let x3111 = 0.5 * x3110;
        let x3113 = s[8] * k[16];
        let x3114 = x3113 - x3111;
        let x3115 = x1013 * k[8];
        let x3116 = x3115 - x1011;
        let x3117 = x1016 + x3116;
        let x3118 = 0.5 * x3117;
        let x3120 = x96 * k[16];
        let x3121 = x3120 - x3118;
        let x3122 = x987 * k[8];
        let x3123 = x3122 - x1025;
        let x3124 = x3123 - x1030;
        let x3125 = 0.5 * x3124;
        let x3126 = x3106 + x3125;
        let x3127 = x969 * k[8];
        let x3128 = x1037 + x3127;
        let x3129 = x1040 + x3128;
        let x3130 = 0.5 * x3129;
        let x3131 = s[2] * k[16];
        let x3132 = x3130 + x3131;
        let x3133 = x1015 * k[8];
        let x3135 = x1047 - x3133;
        let x3136 = x3135 - x1051;
        let x3137 = 0.5 * x3136;
        let x3138 = x94 * k[16];
        let x3139 = x3137 + x3138;
        let x3140 = x999 * k[8];
        let x3141 = x1060 + x3140;
        let x3143 = x1064 - x3141;
        let x3144 = 0.5 * x3143;
        let x3145 = s[6] * k[16];
        let x3146 = x3144 + x3145;
        let x3147 = x1058 * k[8];
        let x3148 = x1071 + x3147;
        let x3150 = x1076 - x3148;
        let x3151 = 0.5 * x3150;
        let x3152 = x3113 + x3151;
        let x3153 = x1046 * k[8];
        let x3155 = x1083 - x3153;
        let x3156 = x3155 - x1087;
        let x3157 = 0.5 * x3156;
        let x3158 = x3138 + x3157;
        let x3159 = x1036 * k[8];
        let x3160 = x1093 + x3159;
        let x3161 = x1095 + x3160;
        let x3162 = 0.5 * x3161;
        let x3163 = x83 * k[16];
        let x3164 = x3162 + x3163;
        let x3165 = x1023 * k[8];
        let x3166 = x3165 - x1102;
        let x3167 = x3166 - x1105;
        let x3168 = 0.5 * x3167;
        let x3169 = x107 * k[16];
        let x3170 = x3168 + x3169;
        let x3171 = x1009 * k[8];
        let x3173 = x1112 - x3171;
        let x3174 = x3173 - x1116;
        let x3175 = 0.5 * x3174;
        let x3176 = x3120 + x3175;
        let x3177 = x995 * k[8];
        let x3178 = x1122 + x3177;
        let x3180 = x1126 - x3178;
        let x3181 = 0.5 * x3180;
        let x3182 = x3145 + x3181;
        let x3183 = x981 * k[8];
        let x3184 = x3183 - x1132;
        let x3185 = x3184 - x1135;
        let x3186 = 0.5 * x3185;
        let x3187 = x3169 + x3186;
        let x3188 = x961 * k[8];
        let x3189 = x1141 + x3188;
        let x3190 = x1144 + x3189;
        let x3191 = 0.5 * x3190;
        let x3192 = x84 * k[16];
        let x3193 = x3191 + x3192;
        let x3194 = x1171 * k[8];
        let x3195 = x1168 + x3194;
        let x3196 = x1176 + x3195;
        let x3197 = 0.5 * x3196;
        let x3211 = x1169 * k[8];
        let x3212 = x1168 + x3211;
        let x3213 = x1231 + x3212;
        let x3214 = 0.5 * x3213;
        let x3215 = x3197 + x3214;
        let x3216 = q[10] * k[16];
        let x3217 = s[85] * x3216;
        let x3219 = x3215 - x3217;
        let x3252 = x3080 + x3219;
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
        mass[22] = x3099;
        mass[23] = x3107;
        mass[24] = x3114;
        mass[25] = x3121;
        mass[26] = x3126;
        mass[27] = x3132;
        mass[28] = x3139;
        mass[29] = x3146;
        mass[30] = x3152;
        mass[31] = x3158;
        mass[32] = x3164;
        mass[33] = x3170;
        mass[34] = x3176;
        mass[35] = x3182;
        mass[36] = x3187;
        mass[37] = x3193;
        force[0] = x3079;
        force[1] = x3092;
        force[2] = x3058;
        force[3] = x805;
        force[4] = x824;
        force[5] = x842;
        force[6] = x859;
        force[7] = 0.0;
        force[8] = -9.81;
        force[9] = 0.0;
        force[10] = x3252;
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
        let x3070 = x412 * s[93];
        let x3071 = x414 * s[93];
        let x3072 = x417 * s[93];
        let x3076 = s[14] * s[89];
        let x3077 = s[11] * s[89];
        let x3078 = s[12] * s[89];
        let x3081 = x3070 + x3076;
        let x3082 = x3071 + x3077;
        let x3083 = x3072 + x3078;
        let x3198 = x1185 * k[8];
        let x3200 = x1182 - x3198;
        let x3201 = x1191 + x3200;
        let x3202 = 0.5 * x3201;
        let x3203 = x1199 * k[8];
        let x3204 = x1196 + x3203;
        let x3205 = x3204 - x1204;
        let x3206 = 0.5 * x3205;
        let x3207 = x1214 * k[8];
        let x3208 = x3207 - x1210;
        let x3209 = x1219 + x3208;
        let x3210 = 0.5 * x3209;
        let x3220 = x1183 * k[8];
        let x3221 = x3220 - x1182;
        let x3222 = x3221 - x1248;
        let x3223 = 0.5 * x3222;
        let x3225 = x3223 - x3202;
        let x3226 = q[11] * k[16];
        let x3227 = s[85] * x3226;
        let x3229 = x3225 - x3227;
        let x3230 = x1197 * k[8];
        let x3231 = x1196 + x3230;
        let x3233 = x1266 - x3231;
        let x3234 = 0.5 * x3233;
        let x3236 = x3234 - x3206;
        let x3237 = q[12] * k[16];
        let x3238 = s[85] * x3237;
        let x3240 = x3236 - x3238;
        let x3241 = x1212 * k[8];
        let x3243 = x1210 - x3241;
        let x3244 = x3243 - x1283;
        let x3245 = 0.5 * x3244;
        let x3247 = x3245 - x3210;
        let x3248 = q[13] * k[16];
        let x3249 = s[85] * x3248;
        let x3251 = x3247 - x3249;
        let x3253 = x3081 + x3229;
        let x3254 = x3082 + x3240;
        let x3255 = x3251 - x3083;
        force[11] = x3253;
        force[12] = x3254;
        force[13] = x3255;
    }
    /// Directional derivatives of M's nonzeros and Q along `(dq, dqd, dp)`.
    pub fn tangents(
        k: &[f64],
        q: &[f64],
        qd: &[f64],
        t: f64,
        dq: &[f64],
        dqd: &[f64],
        dp: &[f64],
        mass: &mut [f64],
        force: &mut [f64],
    ) {
        let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
        let q: &[f64; 14] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 14] = qd.try_into().expect("qd must have n_coords entries");
        let dq: &[f64; 14] = dq.try_into().expect("dq must have n_coords entries");
        let dqd: &[f64; 14] = dqd.try_into().expect("dqd must have n_coords entries");
        let dp: &[f64; 33] = dp.try_into().expect("dp must have 33 entries");
        let mass: &mut [f64; 38] = mass.try_into().expect("mass must have 38 entries");
        let force: &mut [f64; 14] = force
            .try_into()
            .expect("force must have 14 entries");
        let mut s = [0.0f64; 257];
        tangents_shared_0(k, q, qd, t, dq, dqd, dp, &mut s);
        tangents_part_0(k, q, qd, t, dq, dqd, dp, &s, mass, force);
        tangents_part_1(k, q, qd, dq, dqd, dp, &s, force);
        tangents_part_2(k, q, dq, dqd, dp, &s, force);
    }
    #[inline(never)]
    fn tangents_shared_0(
        k: &[f64; 17],
        q: &[f64; 14],
        qd: &[f64; 14],
        t: f64,
        dq: &[f64; 14],
        dqd: &[f64; 14],
        dp: &[f64; 33],
        s: &mut [f64; 257],
    ) {
        let x13 = symbody_runtime::trig::sin(t);
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
        let x136 = q[3] * 2.0;
        s[11] = x136;
        let x137 = q[4] * 2.0;
        s[12] = x137;
        let x138 = q[5] * 2.0;
        s[13] = x138;
        let x139 = q[6] * 2.0;
        s[14] = x139;
        let x142 = 2.0 * q[10];
        s[15] = x142;
        let x143 = 2.0 * q[11];
        s[16] = x143;
        let x144 = 2.0 * q[12];
        s[17] = x144;
        let x145 = 2.0 * q[13];
        s[18] = x145;
        let x197 = x142 * qd[10];
        s[19] = x197;
        let x198 = x143 * qd[11];
        s[20] = x198;
        let x201 = x197 + x198;
        s[21] = x201;
        let x202 = q[12] * qd[11];
        s[22] = x202;
        let x203 = q[11] * qd[12];
        s[23] = x203;
        let x206 = q[13] * qd[10];
        s[24] = x206;
        let x207 = q[10] * qd[13];
        s[25] = x207;
        let x212 = q[13] * qd[12];
        s[26] = x212;
        let x213 = q[12] * qd[13];
        s[27] = x213;
        let x216 = q[11] * qd[10];
        s[28] = x216;
        let x217 = q[10] * qd[11];
        s[29] = x217;
        let x233 = 2.0 * qd[10];
        s[30] = x233;
        let x234 = 2.0 * qd[11];
        s[31] = x234;
        let x235 = 2.0 * qd[12];
        s[32] = x235;
        let x236 = 2.0 * qd[13];
        s[33] = x236;
        let x269 = qd[11] * qd[12];
        s[34] = x269;
        let x272 = qd[10] * qd[13];
        s[35] = x272;
        let x366 = -x116;
        s[36] = x366;
        let x367 = x366.atan2(x87);
        s[37] = x367;
        let x368 = 2.0 * x201;
        s[38] = x368;
        let x369 = q[13] * qd[11];
        s[39] = x369;
        let x370 = q[11] * qd[13];
        s[40] = x370;
        let x371 = x369 + x370;
        s[41] = x371;
        let x372 = 2.0 * x371;
        s[42] = x372;
        let x373 = q[12] * qd[10];
        s[43] = x373;
        let x374 = q[10] * qd[12];
        s[44] = x374;
        let x375 = x373 + x374;
        s[45] = x375;
        let x376 = 2.0 * x375;
        s[46] = x376;
        let x378 = x372 - x376;
        s[47] = x378;
        let x380 = x87 * x87;
        s[48] = x380;
        let x381 = x116 * x116;
        s[49] = x381;
        let x382 = x380 + x381;
        s[50] = x382;
        let x383 = x87 * x378;
        s[51] = x383;
        let x385 = x116 * x368;
        s[52] = x385;
        let x387 = x385 - x383;
        s[53] = x387;
        let x388 = 1.0 / x382;
        s[54] = x388;
        let x389 = x387 * x388;
        s[55] = x389;
        let x400 = 2.0 * x142;
        s[56] = x400;
        let x406 = 2.0 * x143;
        s[57] = x406;
        let x426 = x217 - x216;
        s[58] = x426;
        let x862 = x212 + x426;
        s[59] = x862;
        let x863 = x862 - x213;
        s[60] = x863;
        let x864 = 2.0 * x863;
        s[61] = x864;
        let x866 = x369 + x373;
        s[62] = x866;
        let x868 = x374 - x866;
        s[63] = x868;
        let x869 = x370 + x868;
        s[64] = x869;
        let x870 = 2.0 * x869;
        s[65] = x870;
        let x872 = x202 - x206;
        s[66] = x872;
        let x873 = x872 - x203;
        s[67] = x873;
        let x874 = x207 + x873;
        s[68] = x874;
        let x875 = 2.0 * x874;
        s[69] = x875;
        let x892 = 2.0 * x864;
        s[70] = x892;
        let x894 = 2.0 * x870;
        s[71] = x894;
        let x896 = 2.0 * x875;
        s[72] = x896;
        let x1150 = qd[11] * qd[13];
        s[73] = x1150;
        let x1151 = qd[10] * qd[12];
        s[74] = x1151;
        let x1155 = x1150 + x1151;
        s[75] = x1155;
        let x1157 = x1151 - x1155;
        s[76] = x1157;
        let x1158 = x1150 + x1157;
        s[77] = x1158;
        let x1159 = 2.0 * x1158;
        s[78] = x1159;
        let x1161 = x269 - x272;
        s[79] = x1161;
        let x1162 = x1161 - x269;
        s[80] = x1162;
        let x1163 = x272 + x1162;
        s[81] = x1163;
        let x1164 = 2.0 * x1163;
        s[82] = x1164;
        let x1165 = 2.0 * x1159;
        s[83] = x1165;
        let x1166 = 2.0 * x1164;
        s[84] = x1166;
        let x1223 = qd[10] * qd[10];
        s[85] = x1223;
        let x1224 = qd[11] * qd[11];
        s[86] = x1224;
        let x1225 = qd[12] * qd[12];
        s[87] = x1225;
        let x1226 = qd[13] * qd[13];
        s[88] = x1226;
        let x1227 = x1223 + x1224;
        s[89] = x1227;
        let x1228 = x1225 + x1227;
        s[90] = x1228;
        let x1229 = x1226 + x1228;
        s[91] = x1229;
        let x1409 = 2.0 * x87;
        s[92] = x1409;
        let x1411 = 2.0 * x116;
        s[93] = x1411;
        let x1425 = x388 * x388;
        s[94] = x1425;
        let x1767 = t * dp[31];
        s[95] = x1767;
        let x1776 = x13 * dp[32];
        s[96] = x1776;
        let x1810 = x142 * dq[10];
        s[97] = x1810;
        let x1811 = x143 * dq[11];
        s[98] = x1811;
        let x1814 = x1810 + x1811;
        s[99] = x1814;
        let x1815 = 2.0 * x1814;
        s[100] = x1815;
        let x1826 = q[13] * dq[11];
        s[101] = x1826;
        let x1827 = q[11] * dq[13];
        s[102] = x1827;
        let x1828 = x1826 + x1827;
        s[103] = x1828;
        let x1829 = 2.0 * x1828;
        s[104] = x1829;
        let x1830 = q[12] * dq[10];
        s[105] = x1830;
        let x1831 = q[10] * dq[12];
        s[106] = x1831;
        let x1832 = x1830 + x1831;
        s[107] = x1832;
        let x1833 = 2.0 * x1832;
        s[108] = x1833;
        let x1843 = x1829 - x1833;
        s[109] = x1843;
        let x1853 = 2.0 * dq[3];
        s[110] = x1853;
        let x1854 = 2.0 * dq[4];
        s[111] = x1854;
        let x1855 = 2.0 * dq[5];
        s[112] = x1855;
        let x1856 = 2.0 * dq[6];
        s[113] = x1856;
        let x1859 = 2.0 * dq[10];
        s[114] = x1859;
        let x1860 = 2.0 * dq[11];
        s[115] = x1860;
        let x1861 = 2.0 * dq[12];
        s[116] = x1861;
        let x1862 = 2.0 * dq[13];
        s[117] = x1862;
        let x1903 = qd[10] * x1859;
        s[118] = x1903;
        let x1904 = x142 * dqd[10];
        s[119] = x1904;
        let x1905 = x1903 + x1904;
        s[120] = x1905;
        let x1906 = qd[11] * x1860;
        s[121] = x1906;
        let x1907 = x143 * dqd[11];
        s[122] = x1907;
        let x1908 = x1906 + x1907;
        s[123] = x1908;
        let x1909 = x1905 + x1908;
        s[124] = x1909;
        let x1910 = qd[11] * dq[12];
        s[125] = x1910;
        let x1911 = q[12] * dqd[11];
        s[126] = x1911;
        let x1912 = x1910 + x1911;
        s[127] = x1912;
        let x1913 = qd[12] * dq[11];
        s[128] = x1913;
        let x1914 = q[11] * dqd[12];
        s[129] = x1914;
        let x1915 = x1913 + x1914;
        s[130] = x1915;
        let x1916 = qd[10] * dq[13];
        s[131] = x1916;
        let x1917 = q[13] * dqd[10];
        s[132] = x1917;
        let x1918 = x1916 + x1917;
        s[133] = x1918;
        let x1919 = qd[13] * dq[10];
        s[134] = x1919;
        let x1920 = q[10] * dqd[13];
        s[135] = x1920;
        let x1921 = x1919 + x1920;
        s[136] = x1921;
        let x1922 = qd[12] * dq[13];
        s[137] = x1922;
        let x1923 = q[13] * dqd[12];
        s[138] = x1923;
        let x1924 = x1922 + x1923;
        s[139] = x1924;
        let x1925 = qd[13] * dq[12];
        s[140] = x1925;
        let x1926 = q[12] * dqd[13];
        s[141] = x1926;
        let x1927 = x1925 + x1926;
        s[142] = x1927;
        let x1928 = qd[10] * dq[11];
        s[143] = x1928;
        let x1929 = q[11] * dqd[10];
        s[144] = x1929;
        let x1930 = x1928 + x1929;
        s[145] = x1930;
        let x1931 = qd[11] * dq[10];
        s[146] = x1931;
        let x1932 = q[10] * dqd[11];
        s[147] = x1932;
        let x1933 = x1931 + x1932;
        s[148] = x1933;
        let x1939 = 2.0 * dqd[11];
        s[149] = x1939;
        let x1940 = 2.0 * dqd[12];
        s[150] = x1940;
        let x1941 = 2.0 * dqd[13];
        s[151] = x1941;
        let x1989 = x233 * dqd[10];
        s[152] = x1989;
        let x1992 = x234 * dqd[11];
        s[153] = x1992;
        let x1995 = x235 * dqd[12];
        s[154] = x1995;
        let x1998 = x236 * dqd[13];
        s[155] = x1998;
        let x2002 = qd[12] * dqd[11];
        s[156] = x2002;
        let x2003 = qd[11] * dqd[12];
        s[157] = x2003;
        let x2004 = x2002 + x2003;
        s[158] = x2004;
        let x2007 = qd[13] * dqd[10];
        s[159] = x2007;
        let x2008 = qd[10] * dqd[13];
        s[160] = x2008;
        let x2009 = x2007 + x2008;
        s[161] = x2009;
        let x2096 = x87 * x1843;
        s[162] = x2096;
        let x2098 = x116 * x1815;
        s[163] = x2098;
        let x2100 = x2098 - x2096;
        s[164] = x2100;
        let x2101 = x388 * x2100;
        s[165] = x2101;
        let x2102 = 2.0 * x1909;
        s[166] = x2102;
        let x2103 = qd[11] * dq[13];
        s[167] = x2103;
        let x2104 = q[13] * dqd[11];
        s[168] = x2104;
        let x2105 = x2103 + x2104;
        s[169] = x2105;
        let x2106 = qd[13] * dq[11];
        s[170] = x2106;
        let x2107 = q[11] * dqd[13];
        s[171] = x2107;
        let x2108 = x2106 + x2107;
        s[172] = x2108;
        let x2109 = x2105 + x2108;
        s[173] = x2109;
        let x2110 = 2.0 * x2109;
        s[174] = x2110;
        let x2111 = qd[10] * dq[12];
        s[175] = x2111;
        let x2112 = q[12] * dqd[10];
        s[176] = x2112;
        let x2113 = x2111 + x2112;
        s[177] = x2113;
        let x2114 = qd[12] * dq[10];
        s[178] = x2114;
        let x2115 = q[10] * dqd[12];
        s[179] = x2115;
        let x2116 = x2114 + x2115;
        s[180] = x2116;
        let x2117 = x2113 + x2116;
        s[181] = x2117;
        let x2118 = 2.0 * x2117;
        s[182] = x2118;
        let x2120 = x2110 - x2118;
        s[183] = x2120;
        let x2121 = x1409 * x1815;
        s[184] = x2121;
        let x2122 = x1411 * x1843;
        s[185] = x2122;
        let x2123 = x2121 + x2122;
        s[186] = x2123;
        let x2124 = x378 * x1815;
        s[187] = x2124;
        let x2125 = x87 * x2120;
        s[188] = x2125;
        let x2126 = x2124 + x2125;
        s[189] = x2126;
        let x2128 = x368 * x1843;
        s[190] = x2128;
        let x2129 = x116 * x2102;
        s[191] = x2129;
        let x2130 = x2128 + x2129;
        s[192] = x2130;
        let x2131 = x2130 - x2126;
        s[193] = x2131;
        let x2132 = x1425 * x2123;
        s[194] = x2132;
        let x2134 = x388 * x2131;
        s[195] = x2134;
        let x2135 = x387 * x2132;
        s[196] = x2135;
        let x2137 = x2134 - x2135;
        s[197] = x2137;
        let x2138 = x367 * dp[4];
        s[198] = x2138;
        let x2141 = x389 * dp[1];
        s[199] = x2141;
        let x2148 = 2.0 * x1859;
        s[200] = x2148;
        let x2160 = 2.0 * x1860;
        s[201] = x2160;
        let x2200 = x1933 - x1930;
        s[202] = x2200;
        let x2562 = x1924 + x2200;
        s[203] = x2562;
        let x2563 = x2562 - x1927;
        s[204] = x2563;
        let x2564 = 2.0 * x2563;
        s[205] = x2564;
        let x2565 = x2105 + x2113;
        s[206] = x2565;
        let x2567 = x2116 - x2565;
        s[207] = x2567;
        let x2568 = x2108 + x2567;
        s[208] = x2568;
        let x2569 = 2.0 * x2568;
        s[209] = x2569;
        let x2571 = x1912 - x1918;
        s[210] = x2571;
        let x2572 = x2571 - x1915;
        s[211] = x2572;
        let x2573 = x1921 + x2572;
        s[212] = x2573;
        let x2574 = 2.0 * x2573;
        s[213] = x2574;
        let x2575 = 2.0 * x2564;
        s[214] = x2575;
        let x2576 = 2.0 * x2569;
        s[215] = x2576;
        let x2577 = 2.0 * x2574;
        s[216] = x2577;
        let x2578 = 4.0 * dp[2];
        s[217] = x2578;
        let x2579 = 0.3333333333333333 * x2578;
        s[218] = x2579;
        let x2825 = qd[13] * dqd[11];
        s[219] = x2825;
        let x2826 = qd[11] * dqd[13];
        s[220] = x2826;
        let x2827 = x2825 + x2826;
        s[221] = x2827;
        let x2828 = qd[12] * dqd[10];
        s[222] = x2828;
        let x2829 = qd[10] * dqd[12];
        s[223] = x2829;
        let x2830 = x2828 + x2829;
        s[224] = x2830;
        let x2832 = x2827 + x2830;
        s[225] = x2832;
        let x2834 = x2830 - x2832;
        s[226] = x2834;
        let x2835 = x2827 + x2834;
        s[227] = x2835;
        let x2836 = 2.0 * x2835;
        s[228] = x2836;
        let x2838 = x2004 - x2009;
        s[229] = x2838;
        let x2839 = x2838 - x2004;
        s[230] = x2839;
        let x2840 = x2009 + x2839;
        s[231] = x2840;
        let x2841 = 2.0 * x2840;
        s[232] = x2841;
        let x2842 = 2.0 * x2836;
        s[233] = x2842;
        let x2843 = 2.0 * x2841;
        s[234] = x2843;
        let x2947 = x1989 + x1992;
        s[235] = x2947;
        let x2948 = x1995 + x2947;
        s[236] = x2948;
        let x2949 = x1998 + x2948;
        s[237] = x2949;
        let x3034 = t * k[4];
        s[238] = x3034;
        let (x3442, x3035) = symbody_runtime::trig::sin_cos(x3034);
        s[246] = x3442;
        s[239] = x3035;
        let x3036 = k[3] * x3035;
        s[240] = x3036;
        let x3038 = x13 * k[5];
        s[241] = x3038;
        let x3060 = x367 * k[10];
        s[242] = x3060;
        let x3061 = x389 * k[7];
        s[243] = x3061;
        let x3063 = x3036 - x3061;
        s[244] = x3063;
        let x3065 = x3063 - x3060;
        s[245] = x3065;
        let x3443 = x1767 * x3442;
        s[247] = x3443;
        let x3444 = dp[30] * x3035;
        s[248] = x3444;
        let x3445 = k[3] * x3443;
        s[249] = x3445;
        let x3447 = x3444 - x3445;
        s[250] = x3447;
        let x3465 = x2101 * k[10];
        s[251] = x3465;
        let x3466 = x2138 + x3465;
        s[252] = x3466;
        let x3467 = x2137 * k[7];
        s[253] = x3467;
        let x3468 = x2141 + x3467;
        s[254] = x3468;
        let x3470 = x3447 - x3468;
        s[255] = x3470;
        let x3472 = x3470 - x3466;
        s[256] = x3472;
    }
    #[inline(never)]
    fn tangents_part_0(
        k: &[f64; 17],
        q: &[f64; 14],
        qd: &[f64; 14],
        t: f64,
        dq: &[f64; 14],
        dqd: &[f64; 14],
        dp: &[f64; 33],
        s: &[f64; 257],
        mass: &mut [f64; 38],
        force: &mut [f64; 14],
    ) {
        let x83 = q[12] * q[12];
        let x84 = q[13] * q[13];
        let x94 = q[11] * q[12];
        let x96 = q[10] * q[13];
        let x107 = q[12] * q[13];
        let x109 = q[10] * q[11];
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
        let x576 = 2.0 * s[12];
        let x578 = 2.0 * s[13];
        let x580 = 2.0 * s[14];
        let x602 = 2.0 * s[11];
        let x957 = 2.0 * s[17];
        let x959 = 2.0 * s[18];
        let x961 = s[16] * s[57];
        let x965 = s[17] * x957;
        let x969 = s[18] * x959;
        let x981 = s[16] * s[56];
        let x983 = s[17] * x959;
        let x987 = s[18] * x957;
        let x995 = s[16] * x959;
        let x997 = s[17] * s[56];
        let x999 = s[18] * s[57];
        let x1009 = s[16] * x957;
        let x1013 = s[17] * s[57];
        let x1015 = s[18] * s[56];
        let x1023 = s[15] * s[57];
        let x1036 = s[15] * s[56];
        let x1046 = s[15] * x959;
        let x1058 = s[15] * x957;
        let x1299 = x346 * x346;
        let x1761 = t * dp[28];
        let x1777 = s[11] * dq[3];
        let x1778 = s[12] * dq[4];
        let x1779 = s[13] * dq[5];
        let x1780 = s[14] * dq[6];
        let x1782 = q[5] * dq[4];
        let x1783 = q[4] * dq[5];
        let x1784 = x1782 + x1783;
        let x1786 = q[6] * dq[3];
        let x1787 = q[3] * dq[6];
        let x1788 = x1786 + x1787;
        let x1790 = q[6] * dq[4];
        let x1791 = q[4] * dq[6];
        let x1792 = x1790 + x1791;
        let x1794 = q[5] * dq[3];
        let x1795 = q[3] * dq[5];
        let x1796 = x1794 + x1795;
        let x1799 = q[6] * dq[5];
        let x1800 = q[5] * dq[6];
        let x1801 = x1799 + x1800;
        let x1803 = q[4] * dq[3];
        let x1804 = q[3] * dq[4];
        let x1805 = x1803 + x1804;
        let x1812 = s[17] * dq[12];
        let x1813 = s[18] * dq[13];
        let x1816 = q[12] * dq[11];
        let x1817 = q[11] * dq[12];
        let x1818 = x1816 + x1817;
        let x1820 = q[13] * dq[10];
        let x1821 = q[10] * dq[13];
        let x1822 = x1820 + x1821;
        let x1834 = q[13] * dq[12];
        let x1835 = q[12] * dq[13];
        let x1836 = x1834 + x1835;
        let x1838 = q[11] * dq[10];
        let x1839 = q[10] * dq[11];
        let x1840 = x1838 + x1839;
        let x2035 = 9.81 * dp[5];
        let x2037 = x337 * dq[0];
        let x2038 = x339 * dq[1];
        let x2039 = x341 * dq[2];
        let x2040 = x2037 + x2038;
        let x2041 = x2039 + x2040;
        let x2042 = x346 * x2041;
        let x2043 = 2.0 * dq[0];
        let x2044 = x337 * dqd[0];
        let x2045 = qd[0] * x2043;
        let x2046 = x2044 + x2045;
        let x2047 = 2.0 * dq[1];
        let x2048 = x339 * dqd[1];
        let x2049 = qd[1] * x2047;
        let x2050 = x2048 + x2049;
        let x2051 = 2.0 * dq[2];
        let x2052 = x341 * dqd[2];
        let x2053 = qd[2] * x2051;
        let x2054 = x2052 + x2053;
        let x2055 = x2046 + x2050;
        let x2056 = x2054 + x2055;
        let x2057 = 2.0 * x2042;
        let x2058 = x1299 * x2057;
        let x2060 = x346 * x2056;
        let x2061 = x344 * x2058;
        let x2063 = x2060 - x2061;
        let x2064 = x348 * dp[3];
        let x2067 = x347 * dp[0];
        let x2074 = x346 * x2043;
        let x2075 = x337 * x2058;
        let x2077 = x2074 - x2075;
        let x2078 = x346 * x2047;
        let x2079 = x339 * x2058;
        let x2081 = x2078 - x2079;
        let x2082 = x346 * x2051;
        let x2083 = x341 * x2058;
        let x2085 = x2082 - x2083;
        let x2241 = 2.0 * dp[5];
        let x2242 = 0.5 * x2241;
        let x2243 = 2.0 * s[111];
        let x2244 = 2.0 * s[112];
        let x2245 = 2.0 * s[113];
        let x2246 = x576 * s[111];
        let x2247 = s[12] * x2243;
        let x2248 = x2246 + x2247;
        let x2249 = 0.01 * x2248;
        let x2250 = x578 * s[112];
        let x2251 = s[13] * x2244;
        let x2252 = x2250 + x2251;
        let x2253 = 0.01 * x2252;
        let x2254 = x580 * s[113];
        let x2255 = s[14] * x2245;
        let x2256 = x2254 + x2255;
        let x2257 = 0.01 * x2256;
        let x2258 = x2249 + x2253;
        let x2259 = x2257 + x2258;
        let x2260 = 0.5 * x2259;
        let x2261 = 0.04 * x1777;
        let x2262 = x2260 + x2261;
        let x2263 = 2.0 * s[110];
        let x2264 = x602 * s[111];
        let x2265 = s[12] * x2263;
        let x2266 = x2264 + x2265;
        let x2267 = 0.01 * x2266;
        let x2268 = x580 * s[112];
        let x2269 = s[13] * x2245;
        let x2270 = x2268 + x2269;
        let x2271 = 0.01 * x2270;
        let x2273 = x578 * s[113];
        let x2274 = s[14] * x2244;
        let x2275 = x2273 + x2274;
        let x2276 = 0.01 * x2275;
        let x2277 = x2267 - x2271;
        let x2278 = x2276 + x2277;
        let x2279 = 0.5 * x2278;
        let x2281 = 0.04 * x1805;
        let x2282 = x2281 - x2279;
        let x2283 = x580 * s[111];
        let x2284 = s[12] * x2245;
        let x2285 = x2283 + x2284;
        let x2286 = 0.01 * x2285;
        let x2287 = x602 * s[112];
        let x2288 = s[13] * x2263;
        let x2289 = x2287 + x2288;
        let x2290 = 0.01 * x2289;
        let x2291 = x576 * s[113];
        let x2292 = s[14] * x2243;
        let x2293 = x2291 + x2292;
        let x2294 = 0.01 * x2293;
        let x2296 = x2286 + x2290;
        let x2297 = x2296 - x2294;
        let x2298 = 0.5 * x2297;
        let x2300 = 0.04 * x1796;
        let x2301 = x2300 - x2298;
        let x2302 = x578 * s[111];
        let x2303 = s[12] * x2244;
        let x2304 = x2302 + x2303;
        let x2305 = 0.01 * x2304;
        let x2307 = x576 * s[112];
        let x2308 = s[13] * x2243;
        let x2309 = x2307 + x2308;
        let x2310 = 0.01 * x2309;
        let x2311 = x602 * s[113];
        let x2312 = s[14] * x2263;
        let x2313 = x2311 + x2312;
        let x2314 = 0.01 * x2313;
        let x2315 = x2310 - x2305;
        let x2316 = x2314 + x2315;
        let x2317 = 0.5 * x2316;
        let x2319 = 0.04 * x1788;
        let x2320 = x2319 - x2317;
        let x2321 = x576 * s[110];
        let x2322 = s[11] * x2243;
        let x2323 = x2321 + x2322;
        let x2324 = 0.01 * x2323;
        let x2327 = x2276 - x2324;
        let x2328 = x2327 - x2271;
        let x2329 = 0.5 * x2328;
        let x2330 = x2281 + x2329;
        let x2331 = x602 * s[110];
        let x2332 = s[11] * x2263;
        let x2333 = x2331 + x2332;
        let x2334 = 0.01 * x2333;
        let x2335 = x2257 + x2334;
        let x2336 = x2253 + x2335;
        let x2337 = 0.5 * x2336;
        let x2338 = 0.04 * x1778;
        let x2339 = x2337 + x2338;
        let x2340 = x580 * s[110];
        let x2341 = s[11] * x2245;
        let x2342 = x2340 + x2341;
        let x2343 = 0.01 * x2342;
        let x2346 = x2343 - x2314;
        let x2347 = x2346 - x2310;
        let x2348 = 0.5 * x2347;
        let x2349 = 0.04 * x1784;
        let x2350 = x2348 + x2349;
        let x2351 = x578 * s[110];
        let x2352 = s[11] * x2244;
        let x2353 = x2351 + x2352;
        let x2354 = 0.01 * x2353;
        let x2355 = x2294 + x2354;
        let x2357 = x2290 - x2355;
        let x2358 = 0.5 * x2357;
        let x2359 = 0.04 * x1792;
        let x2360 = x2358 + x2359;
        let x2361 = x2286 - x2355;
        let x2362 = 0.5 * x2361;
        let x2363 = x2300 + x2362;
        let x2365 = x2314 - x2343;
        let x2366 = x2365 - x2305;
        let x2367 = 0.5 * x2366;
        let x2368 = x2349 + x2367;
        let x2369 = x2249 + x2335;
        let x2370 = 0.5 * x2369;
        let x2371 = 0.04 * x1779;
        let x2372 = x2370 + x2371;
        let x2374 = x2324 - x2276;
        let x2375 = x2374 - x2267;
        let x2376 = 0.5 * x2375;
        let x2377 = 0.04 * x1801;
        let x2378 = x2376 + x2377;
        let x2379 = x2315 - x2343;
        let x2380 = 0.5 * x2379;
        let x2381 = x2319 + x2380;
        let x2383 = x2354 - x2296;
        let x2384 = 0.5 * x2383;
        let x2385 = x2359 + x2384;
        let x2386 = x2277 - x2324;
        let x2387 = 0.5 * x2386;
        let x2388 = x2377 + x2387;
        let x2389 = x2258 + x2334;
        let x2390 = 0.5 * x2389;
        let x2391 = 0.04 * x1780;
        let x2392 = x2390 + x2391;
        let x2580 = 2.0 * s[116];
        let x2581 = 2.0 * s[117];
        let x2582 = s[57] * s[115];
        let x2583 = s[16] * s[201];
        let x2584 = x2582 + x2583;
        let x2585 = 0.1 * x2584;
        let x2586 = x957 * s[116];
        let x2587 = s[17] * x2580;
        let x2588 = x2586 + x2587;
        let x2589 = x965 * dp[2];
        let x2592 = x959 * s[117];
        let x2593 = s[18] * x2581;
        let x2594 = x2592 + x2593;
        let x2595 = 0.3 * x2594;
        let x2600 = s[1] * s[218];
        let x2603 = s[56] * s[115];
        let x2604 = s[16] * s[200];
        let x2605 = x2603 + x2604;
        let x2606 = 0.1 * x2605;
        let x2607 = x959 * s[116];
        let x2608 = s[17] * x2581;
        let x2609 = x2607 + x2608;
        let x2610 = x983 * dp[2];
        let x2614 = x957 * s[117];
        let x2615 = s[18] * x2580;
        let x2616 = x2614 + x2615;
        let x2617 = 0.3 * x2616;
        let x2623 = x109 * s[218];
        let x2626 = x959 * s[115];
        let x2627 = s[16] * x2581;
        let x2628 = x2626 + x2627;
        let x2629 = 0.1 * x2628;
        let x2630 = s[56] * s[116];
        let x2631 = s[17] * s[200];
        let x2632 = x2630 + x2631;
        let x2633 = x997 * dp[2];
        let x2636 = s[57] * s[117];
        let x2637 = s[18] * s[201];
        let x2638 = x2636 + x2637;
        let x2639 = 0.3 * x2638;
        let x2646 = s[8] * s[218];
        let x2649 = x957 * s[115];
        let x2650 = s[16] * x2580;
        let x2651 = x2649 + x2650;
        let x2652 = 0.1 * x2651;
        let x2654 = s[57] * s[116];
        let x2655 = s[17] * s[201];
        let x2656 = x2654 + x2655;
        let x2657 = x1013 * dp[2];
        let x2660 = s[56] * s[117];
        let x2661 = s[18] * s[200];
        let x2662 = x2660 + x2661;
        let x2663 = 0.3 * x2662;
        let x2669 = x96 * s[218];
        let x2672 = s[57] * s[114];
        let x2673 = s[15] * s[201];
        let x2674 = x2672 + x2673;
        let x2675 = 0.1 * x2674;
        let x2677 = x987 * dp[2];
        let x2680 = 0.3 * x2609;
        let x2686 = s[56] * s[114];
        let x2687 = s[15] * s[200];
        let x2688 = x2686 + x2687;
        let x2689 = 0.1 * x2688;
        let x2690 = x969 * dp[2];
        let x2693 = 0.3 * x2588;
        let x2698 = s[2] * s[218];
        let x2701 = x959 * s[114];
        let x2702 = s[15] * x2581;
        let x2703 = x2701 + x2702;
        let x2704 = 0.1 * x2703;
        let x2705 = x1015 * dp[2];
        let x2709 = 0.3 * x2656;
        let x2715 = x94 * s[218];
        let x2718 = x957 * s[114];
        let x2719 = s[15] * x2580;
        let x2720 = x2718 + x2719;
        let x2721 = 0.1 * x2720;
        let x2722 = x999 * dp[2];
        let x2725 = 0.3 * x2632;
        let x2731 = s[6] * s[218];
        let x2734 = 0.1 * x2638;
        let x2735 = x1058 * dp[2];
        let x2738 = 0.3 * x2628;
        let x2744 = 0.1 * x2662;
        let x2745 = x1046 * dp[2];
        let x2749 = 0.3 * x2651;
        let x2755 = 0.1 * x2594;
        let x2756 = x1036 * dp[2];
        let x2759 = 0.3 * x2584;
        let x2764 = x83 * s[218];
        let x2767 = 0.1 * x2616;
        let x2769 = x1023 * dp[2];
        let x2772 = 0.3 * x2605;
        let x2778 = x107 * s[218];
        let x2781 = 0.1 * x2656;
        let x2782 = x1009 * dp[2];
        let x2786 = 0.3 * x2703;
        let x2792 = 0.1 * x2632;
        let x2793 = x995 * dp[2];
        let x2796 = 0.3 * x2720;
        let x2802 = 0.1 * x2609;
        let x2804 = x981 * dp[2];
        let x2807 = 0.3 * x2674;
        let x2813 = 0.1 * x2588;
        let x2814 = x961 * dp[2];
        let x2817 = 0.3 * x2688;
        let x2822 = x84 * s[218];
        let x3028 = t * k[1];
        let (x3029, x3437) = symbody_runtime::trig::sin_cos(x3028);
        let x3030 = k[0] * x3029;
        let x3047 = x348 * k[9];
        let x3048 = x347 * k[6];
        let x3050 = x3030 - x3048;
        let x3052 = x3050 - x3047;
        let x3438 = x1761 * x3437;
        let x3439 = dp[27] * x3029;
        let x3440 = k[0] * x3438;
        let x3441 = x3439 + x3440;
        let x3448 = x2042 * k[9];
        let x3449 = x2064 + x3448;
        let x3450 = x2063 * k[6];
        let x3451 = x2067 + x3450;
        let x3453 = x3441 - x3451;
        let x3455 = x3453 - x3449;
        let x3456 = x359 * x3455;
        let x3457 = x2077 * x3052;
        let x3458 = x3456 + x3457;
        let x3459 = x360 * x3455;
        let x3460 = x2081 * x3052;
        let x3461 = x3459 + x3460;
        let x3462 = x361 * x3455;
        let x3463 = x2085 * x3052;
        let x3464 = x3462 + x3463;
        let x3494 = dp[29] + x3458;
        let x3500 = x3461 - x2035;
        let x3501 = x2588 * k[8];
        let x3502 = x2589 + x3501;
        let x3503 = x2585 + x3502;
        let x3504 = x2595 + x3503;
        let x3505 = 0.5 * x3504;
        let x3506 = s[97] * k[16];
        let x3507 = x2600 + x3506;
        let x3508 = x3505 + x3507;
        let x3509 = x2609 * k[8];
        let x3510 = x2610 + x3509;
        let x3512 = x2606 - x3510;
        let x3513 = x2617 + x3512;
        let x3514 = 0.5 * x3513;
        let x3516 = x1840 * k[16];
        let x3517 = x2623 + x3516;
        let x3518 = x3517 - x3514;
        let x3519 = x2632 * k[8];
        let x3520 = x2633 + x3519;
        let x3521 = x2629 + x3520;
        let x3522 = x3521 - x2639;
        let x3523 = 0.5 * x3522;
        let x3525 = s[107] * k[16];
        let x3526 = x2646 + x3525;
        let x3527 = x3526 - x3523;
        let x3528 = x2656 * k[8];
        let x3529 = x2657 + x3528;
        let x3530 = x3529 - x2652;
        let x3531 = x2663 + x3530;
        let x3532 = 0.5 * x3531;
        let x3534 = x1822 * k[16];
        let x3535 = x2669 + x3534;
        let x3536 = x3535 - x3532;
        let x3537 = x2616 * k[8];
        let x3538 = x2677 + x3537;
        let x3539 = x3538 - x2675;
        let x3540 = x3539 - x2680;
        let x3541 = 0.5 * x3540;
        let x3542 = x3517 + x3541;
        let x3543 = x2594 * k[8];
        let x3544 = x2690 + x3543;
        let x3545 = x2689 + x3544;
        let x3546 = x2693 + x3545;
        let x3547 = 0.5 * x3546;
        let x3548 = s[98] * k[16];
        let x3549 = x2698 + x3548;
        let x3550 = x3547 + x3549;
        let x3551 = x2662 * k[8];
        let x3552 = x2705 + x3551;
        let x3554 = x2704 - x3552;
        let x3555 = x3554 - x2709;
        let x3556 = 0.5 * x3555;
        let x3557 = x1818 * k[16];
        let x3558 = x2715 + x3557;
        let x3559 = x3556 + x3558;
        let x3560 = x2638 * k[8];
        let x3561 = x2722 + x3560;
        let x3562 = x2721 + x3561;
        let x3564 = x2725 - x3562;
        let x3565 = 0.5 * x3564;
        let x3566 = s[103] * k[16];
        let x3567 = x2731 + x3566;
        let x3568 = x3565 + x3567;
        let x3569 = x2720 * k[8];
        let x3570 = x2735 + x3569;
        let x3571 = x2734 + x3570;
        let x3573 = x2738 - x3571;
        let x3574 = 0.5 * x3573;
        let x3575 = x3526 + x3574;
        let x3576 = x2703 * k[8];
        let x3577 = x2745 + x3576;
        let x3579 = x2744 - x3577;
        let x3580 = x3579 - x2749;
        let x3581 = 0.5 * x3580;
        let x3582 = x3558 + x3581;
        let x3583 = x2688 * k[8];
        let x3584 = x2756 + x3583;
        let x3585 = x2755 + x3584;
        let x3586 = x2759 + x3585;
        let x3587 = 0.5 * x3586;
        let x3588 = x1812 * k[16];
        let x3589 = x2764 + x3588;
        let x3590 = x3587 + x3589;
        let x3591 = x2674 * k[8];
        let x3592 = x2769 + x3591;
        let x3593 = x3592 - x2767;
        let x3594 = x3593 - x2772;
        let x3595 = 0.5 * x3594;
        let x3596 = x1836 * k[16];
        let x3597 = x2778 + x3596;
        let x3598 = x3595 + x3597;
        let x3599 = x2651 * k[8];
        let x3600 = x2782 + x3599;
        let x3602 = x2781 - x3600;
        let x3603 = x3602 - x2786;
        let x3604 = 0.5 * x3603;
        let x3605 = x3535 + x3604;
        let x3606 = x2628 * k[8];
        let x3607 = x2793 + x3606;
        let x3608 = x2792 + x3607;
        let x3610 = x2796 - x3608;
        let x3611 = 0.5 * x3610;
        let x3612 = x3567 + x3611;
        let x3613 = x2605 * k[8];
        let x3614 = x2804 + x3613;
        let x3615 = x3614 - x2802;
        let x3616 = x3615 - x2807;
        let x3617 = 0.5 * x3616;
        let x3618 = x3597 + x3617;
        let x3619 = x2584 * k[8];
        let x3620 = x2814 + x3619;
        let x3621 = x2813 + x3620;
        let x3622 = x2817 + x3621;
        let x3623 = 0.5 * x3622;
        let x3624 = x1813 * k[16];
        let x3625 = x2822 + x3624;
        let x3626 = x3623 + x3625;
        mass[0] = x2242;
        mass[1] = x2242;
        mass[2] = x2242;
        mass[3] = x2262;
        mass[4] = x2282;
        mass[5] = x2301;
        mass[6] = x2320;
        mass[7] = x2330;
        mass[8] = x2339;
        mass[9] = x2350;
        mass[10] = x2360;
        mass[11] = x2363;
        mass[12] = x2368;
        mass[13] = x2372;
        mass[14] = x2378;
        mass[15] = x2381;
        mass[16] = x2385;
        mass[17] = x2388;
        mass[18] = x2392;
        mass[19] = 0.0;
        mass[20] = 0.0;
        mass[21] = 0.0;
        mass[22] = x3508;
        mass[23] = x3518;
        mass[24] = x3527;
        mass[25] = x3536;
        mass[26] = x3542;
        mass[27] = x3550;
        mass[28] = x3559;
        mass[29] = x3568;
        mass[30] = x3575;
        mass[31] = x3582;
        mass[32] = x3590;
        mass[33] = x3598;
        mass[34] = x3605;
        mass[35] = x3612;
        mass[36] = x3618;
        mass[37] = x3626;
        force[0] = x3494;
        force[1] = x3500;
        force[2] = x3464;
    }
    #[inline(never)]
    fn tangents_part_1(
        k: &[f64; 17],
        q: &[f64; 14],
        qd: &[f64; 14],
        dq: &[f64; 14],
        dqd: &[f64; 14],
        dp: &[f64; 33],
        s: &[f64; 257],
        force: &mut [f64; 14],
    ) {
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
        let x401 = s[5] * s[17];
        let x402 = s[10] * s[56];
        let x404 = x401 + x402;
        let x405 = s[54] * x404;
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
        let x789 = qd[3] * qd[3];
        let x790 = qd[4] * qd[4];
        let x791 = qd[5] * qd[5];
        let x792 = qd[6] * qd[6];
        let x793 = x789 + x790;
        let x794 = x791 + x793;
        let x795 = x792 + x794;
        let x802 = q[3] * 0.04;
        let x821 = q[4] * 0.04;
        let x839 = q[5] * 0.04;
        let x856 = q[6] * 0.04;
        let x1169 = s[32] * s[71];
        let x1170 = s[17] * s[83];
        let x1171 = x1169 + x1170;
        let x1867 = qd[4] * dq[5];
        let x1868 = q[5] * dqd[4];
        let x1869 = x1867 + x1868;
        let x1870 = qd[5] * dq[4];
        let x1871 = q[4] * dqd[5];
        let x1872 = x1870 + x1871;
        let x1873 = qd[3] * dq[6];
        let x1874 = q[6] * dqd[3];
        let x1875 = x1873 + x1874;
        let x1876 = qd[6] * dq[3];
        let x1877 = q[3] * dqd[6];
        let x1878 = x1876 + x1877;
        let x1879 = qd[4] * dq[6];
        let x1880 = q[6] * dqd[4];
        let x1881 = x1879 + x1880;
        let x1882 = qd[6] * dq[4];
        let x1883 = q[4] * dqd[6];
        let x1884 = x1882 + x1883;
        let x1885 = qd[3] * dq[5];
        let x1886 = q[5] * dqd[3];
        let x1887 = x1885 + x1886;
        let x1888 = qd[5] * dq[3];
        let x1889 = q[3] * dqd[5];
        let x1890 = x1888 + x1889;
        let x1891 = qd[5] * dq[6];
        let x1892 = q[6] * dqd[5];
        let x1893 = x1891 + x1892;
        let x1894 = qd[6] * dq[5];
        let x1895 = q[5] * dqd[6];
        let x1896 = x1894 + x1895;
        let x1897 = qd[3] * dq[4];
        let x1898 = q[4] * dqd[3];
        let x1899 = x1897 + x1898;
        let x1900 = qd[4] * dq[3];
        let x1901 = q[3] * dqd[4];
        let x1902 = x1900 + x1901;
        let x1934 = 2.0 * dqd[3];
        let x1935 = 2.0 * dqd[4];
        let x1936 = 2.0 * dqd[5];
        let x1937 = 2.0 * dqd[6];
        let x1942 = x229 * dqd[3];
        let x1945 = x230 * dqd[4];
        let x1948 = x231 * dqd[5];
        let x1951 = x232 * dqd[6];
        let x1955 = qd[5] * dqd[4];
        let x1956 = qd[4] * dqd[5];
        let x1957 = x1955 + x1956;
        let x1960 = qd[6] * dqd[3];
        let x1961 = qd[3] * dqd[6];
        let x1962 = x1960 + x1961;
        let x1965 = qd[6] * dqd[4];
        let x1966 = qd[4] * dqd[6];
        let x1967 = x1965 + x1966;
        let x1970 = qd[5] * dqd[3];
        let x1971 = qd[3] * dqd[5];
        let x1972 = x1970 + x1971;
        let x2149 = s[17] * s[100];
        let x2150 = s[5] * s[116];
        let x2151 = x2149 + x2150;
        let x2152 = s[56] * s[109];
        let x2153 = s[10] * s[200];
        let x2154 = x2152 + x2153;
        let x2155 = x2151 + x2154;
        let x2156 = x404 * s[194];
        let x2158 = s[54] * x2155;
        let x2159 = x2158 - x2156;
        let x2202 = s[17] * s[96];
        let x2223 = x1902 - x1899;
        let x2224 = x1893 + x2223;
        let x2225 = x2224 - x1896;
        let x2226 = 2.0 * x2225;
        let x2227 = x1881 + x1887;
        let x2229 = x1890 - x2227;
        let x2230 = x1884 + x2229;
        let x2231 = 2.0 * x2230;
        let x2234 = x1869 - x1875;
        let x2235 = x2234 - x1872;
        let x2236 = x1878 + x2235;
        let x2237 = 2.0 * x2236;
        let x2238 = 2.0 * x2226;
        let x2239 = 2.0 * x2231;
        let x2240 = 2.0 * x2237;
        let x2393 = x1967 + x1972;
        let x2395 = x1972 - x2393;
        let x2396 = x1967 + x2395;
        let x2397 = 2.0 * x2396;
        let x2400 = x1957 - x1962;
        let x2401 = x2400 - x1957;
        let x2402 = x1962 + x2401;
        let x2403 = 2.0 * x2402;
        let x2404 = 2.0 * x2397;
        let x2405 = 2.0 * x2403;
        let x2406 = x504 * x1935;
        let x2407 = x230 * x2238;
        let x2408 = x2406 + x2407;
        let x2409 = 0.01 * x2408;
        let x2410 = x506 * x1936;
        let x2411 = x231 * x2239;
        let x2412 = x2410 + x2411;
        let x2413 = x731 * s[112];
        let x2414 = s[13] * x2404;
        let x2415 = x2413 + x2414;
        let x2416 = x2412 + x2415;
        let x2417 = 0.01 * x2416;
        let x2418 = x508 * x1937;
        let x2419 = x232 * x2240;
        let x2420 = x2418 + x2419;
        let x2421 = x732 * s[113];
        let x2422 = s[14] * x2405;
        let x2423 = x2421 + x2422;
        let x2424 = x2420 + x2423;
        let x2425 = 0.01 * x2424;
        let x2426 = x2409 + x2417;
        let x2427 = x2425 + x2426;
        let x2428 = 0.5 * x2427;
        let x2429 = x504 * x1934;
        let x2430 = x229 * x2238;
        let x2431 = x2429 + x2430;
        let x2432 = 0.01 * x2431;
        let x2433 = x506 * x1937;
        let x2434 = x232 * x2239;
        let x2435 = x2433 + x2434;
        let x2436 = x731 * s[113];
        let x2437 = s[14] * x2404;
        let x2438 = x2436 + x2437;
        let x2439 = x2435 + x2438;
        let x2440 = 0.01 * x2439;
        let x2442 = x508 * x1936;
        let x2443 = x231 * x2240;
        let x2444 = x2442 + x2443;
        let x2445 = x732 * s[112];
        let x2446 = s[13] * x2405;
        let x2447 = x2445 + x2446;
        let x2448 = x2444 + x2447;
        let x2449 = 0.01 * x2448;
        let x2450 = x2432 - x2440;
        let x2451 = x2449 + x2450;
        let x2452 = 0.5 * x2451;
        let x2453 = x504 * x1937;
        let x2454 = x232 * x2238;
        let x2455 = x2453 + x2454;
        let x2456 = 0.01 * x2455;
        let x2457 = x506 * x1934;
        let x2458 = x229 * x2239;
        let x2459 = x2457 + x2458;
        let x2460 = x731 * s[110];
        let x2461 = s[11] * x2404;
        let x2462 = x2460 + x2461;
        let x2463 = x2459 + x2462;
        let x2464 = 0.01 * x2463;
        let x2465 = x508 * x1935;
        let x2466 = x230 * x2240;
        let x2467 = x2465 + x2466;
        let x2468 = x732 * s[111];
        let x2469 = s[12] * x2405;
        let x2470 = x2468 + x2469;
        let x2471 = x2467 + x2470;
        let x2472 = 0.01 * x2471;
        let x2474 = x2456 + x2464;
        let x2475 = x2474 - x2472;
        let x2476 = 0.5 * x2475;
        let x2477 = x504 * x1936;
        let x2478 = x231 * x2238;
        let x2479 = x2477 + x2478;
        let x2480 = 0.01 * x2479;
        let x2482 = x506 * x1935;
        let x2483 = x230 * x2239;
        let x2484 = x2482 + x2483;
        let x2485 = x731 * s[111];
        let x2486 = s[12] * x2404;
        let x2487 = x2485 + x2486;
        let x2488 = x2484 + x2487;
        let x2489 = 0.01 * x2488;
        let x2490 = x508 * x1934;
        let x2491 = x229 * x2240;
        let x2492 = x2490 + x2491;
        let x2493 = x732 * s[110];
        let x2494 = s[11] * x2405;
        let x2495 = x2493 + x2494;
        let x2496 = x2492 + x2495;
        let x2497 = 0.01 * x2496;
        let x2498 = x2489 - x2480;
        let x2499 = x2497 + x2498;
        let x2500 = 0.5 * x2499;
        let x2501 = x1942 + x1945;
        let x2502 = x1948 + x2501;
        let x2503 = x1951 + x2502;
        let x2504 = 0.01 * x2412;
        let x2505 = 0.01 * x2420;
        let x2506 = x2409 + x2504;
        let x2507 = x2505 + x2506;
        let x2508 = 0.5 * x2507;
        let x2509 = x2428 + x2508;
        let x2510 = 0.04 * dq[3];
        let x2511 = x802 * x2503;
        let x2512 = x795 * x2510;
        let x2513 = x2511 + x2512;
        let x2515 = x2509 - x2513;
        let x2517 = 0.01 * x2435;
        let x2518 = 0.01 * x2444;
        let x2520 = x2517 - x2432;
        let x2521 = x2520 - x2518;
        let x2522 = 0.5 * x2521;
        let x2524 = x2522 - x2452;
        let x2525 = 0.04 * dq[4];
        let x2526 = x821 * x2503;
        let x2527 = x795 * x2525;
        let x2528 = x2526 + x2527;
        let x2530 = x2524 - x2528;
        let x2531 = 0.01 * x2459;
        let x2532 = 0.01 * x2467;
        let x2533 = x2456 + x2531;
        let x2535 = x2532 - x2533;
        let x2536 = 0.5 * x2535;
        let x2538 = x2536 - x2476;
        let x2539 = 0.04 * dq[5];
        let x2540 = x839 * x2503;
        let x2541 = x795 * x2539;
        let x2542 = x2540 + x2541;
        let x2544 = x2538 - x2542;
        let x2545 = 0.01 * x2484;
        let x2547 = 0.01 * x2492;
        let x2549 = x2480 - x2545;
        let x2550 = x2549 - x2547;
        let x2551 = 0.5 * x2550;
        let x2553 = x2551 - x2500;
        let x2554 = 0.04 * dq[6];
        let x2555 = x856 * x2503;
        let x2556 = x795 * x2554;
        let x2557 = x2555 + x2556;
        let x2559 = x2553 - x2557;
        let x2844 = s[70] * s[149];
        let x2845 = s[31] * s[214];
        let x2846 = x2844 + x2845;
        let x2847 = 0.1 * x2846;
        let x2848 = s[71] * s[150];
        let x2849 = s[32] * s[215];
        let x2850 = x2848 + x2849;
        let x2851 = s[83] * s[116];
        let x2852 = s[17] * s[233];
        let x2853 = x2851 + x2852;
        let x2854 = x2850 + x2853;
        let x2855 = x1171 * dp[2];
        let x2858 = s[72] * s[151];
        let x2859 = s[33] * s[216];
        let x2860 = x2858 + x2859;
        let x2861 = s[84] * s[117];
        let x2862 = s[18] * s[234];
        let x2863 = x2861 + x2862;
        let x2864 = x2860 + x2863;
        let x2865 = 0.3 * x2864;
        let x2950 = x1169 * dp[2];
        let x2953 = 0.3 * x2860;
        let x2959 = q[10] * s[218];
        let x3216 = q[10] * k[16];
        let x3473 = x405 * s[256];
        let x3474 = x2159 * s[245];
        let x3475 = x3473 + x3474;
        let x3485 = s[116] * s[241];
        let x3486 = x2202 + x3485;
        let x3495 = x3475 - x3486;
        let x3627 = x2854 * k[8];
        let x3628 = x2855 + x3627;
        let x3629 = x2847 + x3628;
        let x3630 = x2865 + x3629;
        let x3631 = 0.5 * x3630;
        let x3648 = x2850 * k[8];
        let x3649 = x2950 + x3648;
        let x3650 = x2847 + x3649;
        let x3651 = x2953 + x3650;
        let x3652 = 0.5 * x3651;
        let x3653 = x3631 + x3652;
        let x3654 = dq[10] * k[16];
        let x3655 = x2959 + x3654;
        let x3656 = s[237] * x3216;
        let x3657 = s[91] * x3655;
        let x3658 = x3656 + x3657;
        let x3660 = x3653 - x3658;
        let x3705 = x3495 + x3660;
        force[3] = x2515;
        force[4] = x2530;
        force[5] = x2544;
        force[6] = x2559;
        force[7] = 0.0;
        force[8] = 0.0;
        force[9] = 0.0;
        force[10] = x3705;
    }
    #[inline(never)]
    fn tangents_part_2(
        k: &[f64; 17],
        q: &[f64; 14],
        dq: &[f64; 14],
        dqd: &[f64; 14],
        dp: &[f64; 33],
        s: &[f64; 257],
        force: &mut [f64; 14],
    ) {
        let x407 = s[5] * s[18];
        let x409 = s[10] * s[57];
        let x411 = x409 - x407;
        let x412 = s[54] * x411;
        let x413 = s[5] * s[15];
        let x414 = s[54] * x413;
        let x415 = s[5] * s[16];
        let x417 = s[54] * x415;
        let x1183 = s[33] * s[71];
        let x1184 = s[18] * s[83];
        let x1185 = x1183 + x1184;
        let x1197 = s[30] * s[71];
        let x1198 = s[15] * s[83];
        let x1199 = x1197 + x1198;
        let x1212 = s[31] * s[71];
        let x1213 = s[16] * s[83];
        let x1214 = x1212 + x1213;
        let x1938 = 2.0 * dqd[10];
        let x2161 = s[18] * s[100];
        let x2162 = s[5] * s[117];
        let x2163 = x2161 + x2162;
        let x2165 = s[57] * s[109];
        let x2166 = s[10] * s[201];
        let x2167 = x2165 + x2166;
        let x2168 = x2167 - x2163;
        let x2169 = x411 * s[194];
        let x2171 = s[54] * x2168;
        let x2172 = x2171 - x2169;
        let x2173 = s[15] * s[100];
        let x2174 = s[5] * s[114];
        let x2175 = x2173 + x2174;
        let x2176 = x413 * s[194];
        let x2178 = s[54] * x2175;
        let x2179 = x2178 - x2176;
        let x2180 = s[16] * s[100];
        let x2181 = s[5] * s[115];
        let x2182 = x2180 + x2181;
        let x2183 = x415 * s[194];
        let x2185 = s[54] * x2182;
        let x2186 = x2185 - x2183;
        let x2206 = s[18] * s[96];
        let x2209 = s[15] * s[96];
        let x2212 = s[16] * s[96];
        let x2869 = s[70] * x1938;
        let x2870 = s[30] * s[214];
        let x2871 = x2869 + x2870;
        let x2872 = 0.1 * x2871;
        let x2873 = s[71] * s[151];
        let x2874 = s[33] * s[215];
        let x2875 = x2873 + x2874;
        let x2876 = s[83] * s[117];
        let x2877 = s[18] * s[233];
        let x2878 = x2876 + x2877;
        let x2879 = x2875 + x2878;
        let x2880 = x1185 * dp[2];
        let x2884 = s[72] * s[150];
        let x2885 = s[32] * s[216];
        let x2886 = x2884 + x2885;
        let x2887 = s[84] * s[116];
        let x2888 = s[17] * s[234];
        let x2889 = x2887 + x2888;
        let x2890 = x2886 + x2889;
        let x2891 = 0.3 * x2890;
        let x2895 = s[70] * s[151];
        let x2896 = s[33] * s[214];
        let x2897 = x2895 + x2896;
        let x2898 = 0.1 * x2897;
        let x2899 = s[71] * x1938;
        let x2900 = s[30] * s[215];
        let x2901 = x2899 + x2900;
        let x2902 = s[83] * s[114];
        let x2903 = s[15] * s[233];
        let x2904 = x2902 + x2903;
        let x2905 = x2901 + x2904;
        let x2906 = x1199 * dp[2];
        let x2909 = s[72] * s[149];
        let x2910 = s[31] * s[216];
        let x2911 = x2909 + x2910;
        let x2912 = s[84] * s[115];
        let x2913 = s[16] * s[234];
        let x2914 = x2912 + x2913;
        let x2915 = x2911 + x2914;
        let x2916 = 0.3 * x2915;
        let x2921 = s[70] * s[150];
        let x2922 = s[32] * s[214];
        let x2923 = x2921 + x2922;
        let x2924 = 0.1 * x2923;
        let x2926 = s[71] * s[149];
        let x2927 = s[31] * s[215];
        let x2928 = x2926 + x2927;
        let x2929 = s[83] * s[115];
        let x2930 = s[16] * s[233];
        let x2931 = x2929 + x2930;
        let x2932 = x2928 + x2931;
        let x2933 = x1214 * dp[2];
        let x2936 = s[72] * x1938;
        let x2937 = s[30] * s[216];
        let x2938 = x2936 + x2937;
        let x2939 = s[84] * s[114];
        let x2940 = s[15] * s[234];
        let x2941 = x2939 + x2940;
        let x2942 = x2938 + x2941;
        let x2943 = 0.3 * x2942;
        let x2967 = x1183 * dp[2];
        let x2970 = 0.3 * x2886;
        let x2978 = q[11] * s[218];
        let x2985 = x1197 * dp[2];
        let x2988 = 0.3 * x2911;
        let x2996 = q[12] * s[218];
        let x3003 = x1212 * dp[2];
        let x3007 = 0.3 * x2938;
        let x3015 = q[13] * s[218];
        let x3226 = q[11] * k[16];
        let x3237 = q[12] * k[16];
        let x3248 = q[13] * k[16];
        let x3476 = x412 * s[256];
        let x3477 = x2172 * s[245];
        let x3478 = x3476 + x3477;
        let x3479 = x414 * s[256];
        let x3480 = x2179 * s[245];
        let x3481 = x3479 + x3480;
        let x3482 = x417 * s[256];
        let x3483 = x2186 * s[245];
        let x3484 = x3482 + x3483;
        let x3488 = s[117] * s[241];
        let x3489 = x2206 + x3488;
        let x3490 = s[114] * s[241];
        let x3491 = x2209 + x3490;
        let x3492 = s[115] * s[241];
        let x3493 = x2212 + x3492;
        let x3496 = x3478 + x3489;
        let x3497 = x3481 + x3491;
        let x3498 = x3484 + x3493;
        let x3632 = x2879 * k[8];
        let x3633 = x2880 + x3632;
        let x3635 = x2872 - x3633;
        let x3636 = x2891 + x3635;
        let x3637 = 0.5 * x3636;
        let x3638 = x2905 * k[8];
        let x3639 = x2906 + x3638;
        let x3640 = x2898 + x3639;
        let x3641 = x3640 - x2916;
        let x3642 = 0.5 * x3641;
        let x3643 = x2932 * k[8];
        let x3644 = x2933 + x3643;
        let x3645 = x3644 - x2924;
        let x3646 = x2943 + x3645;
        let x3647 = 0.5 * x3646;
        let x3661 = x2875 * k[8];
        let x3662 = x2967 + x3661;
        let x3663 = x3662 - x2872;
        let x3664 = x3663 - x2970;
        let x3665 = 0.5 * x3664;
        let x3667 = x3665 - x3637;
        let x3668 = dq[11] * k[16];
        let x3669 = x2978 + x3668;
        let x3670 = s[237] * x3226;
        let x3671 = s[91] * x3669;
        let x3672 = x3670 + x3671;
        let x3674 = x3667 - x3672;
        let x3675 = x2901 * k[8];
        let x3676 = x2985 + x3675;
        let x3677 = x2898 + x3676;
        let x3679 = x2988 - x3677;
        let x3680 = 0.5 * x3679;
        let x3682 = x3680 - x3642;
        let x3683 = dq[12] * k[16];
        let x3684 = x2996 + x3683;
        let x3685 = s[237] * x3237;
        let x3686 = s[91] * x3684;
        let x3687 = x3685 + x3686;
        let x3689 = x3682 - x3687;
        let x3690 = x2928 * k[8];
        let x3691 = x3003 + x3690;
        let x3693 = x2924 - x3691;
        let x3694 = x3693 - x3007;
        let x3695 = 0.5 * x3694;
        let x3697 = x3695 - x3647;
        let x3698 = dq[13] * k[16];
        let x3699 = x3015 + x3698;
        let x3700 = s[237] * x3248;
        let x3701 = s[91] * x3699;
        let x3702 = x3700 + x3701;
        let x3704 = x3697 - x3702;
        let x3706 = x3496 + x3674;
        let x3707 = x3497 + x3689;
        let x3708 = x3704 - x3498;
        force[11] = x3706;
        force[12] = x3707;
        force[13] = x3708;
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
        let x3026 = x332 + x333;
        let x3027 = q[2] * q[3];
        let x3028 = 2.0 * x3027;
        let x3029 = q[1] * q[4];
        let x3030 = 2.0 * x3029;
        let x3031 = q[2] * q[4];
        let x3032 = 2.0 * x3031;
        let x3033 = q[1] * q[3];
        let x3034 = 2.0 * x3033;
        let x3035 = x3028 + x3030;
        let x3036 = q[1] * q[2];
        let x3037 = 2.0 * x3036;
        let x3039 = x3032 - x3034;
        let x3040 = x67 + x3037;
        let x3041 = q[7] * q[7];
        let x3042 = q[8] * q[8];
        let x3043 = x38 + x39;
        let x3044 = q[6] * q[7];
        let x3045 = 2.0 * x3044;
        let x3046 = q[5] * q[8];
        let x3047 = 2.0 * x3046;
        let x3049 = x3045 - x3047;
        let x3050 = q[7] * q[8];
        let x3051 = 2.0 * x3050;
        let x3052 = x64 + x3051;
        let x3053 = -x3052;
        let x3054 = x36 + x3026;
        let x3055 = x37 + x3054;
        let x3056 = x3055 - 1.0;
        let x3057 = x3041 + x3043;
        let x3058 = x3042 + x3057;
        let x3059 = x3058 - 1.0;
        out[0] = x3035;
        out[1] = x3039;
        out[2] = x3040;
        out[3] = x3049;
        out[4] = x3053;
        out[5] = x3056;
        out[6] = x3059;
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
        let x3060 = -x339;
        let x3061 = 2.0 * q[7];
        let x3062 = 2.0 * q[8];
        let x3063 = -x3062;
        let x3064 = -x3061;
        out[0] = x137;
        out[1] = x136;
        out[2] = x341;
        out[3] = x339;
        out[4] = x141;
        out[5] = x137;
        out[6] = x3060;
        out[7] = x341;
        out[8] = x341;
        out[9] = x339;
        out[10] = x137;
        out[11] = x136;
        out[12] = x3063;
        out[13] = x3061;
        out[14] = x139;
        out[15] = x140;
        out[16] = x518;
        out[17] = x140;
        out[18] = x3063;
        out[19] = x3064;
        out[20] = x339;
        out[21] = x341;
        out[22] = x136;
        out[23] = x137;
        out[24] = x138;
        out[25] = x139;
        out[26] = x3061;
        out[27] = x3062;
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
        let x3113 = qd[1] * x505;
        let x3114 = qd[2] * x507;
        let x3115 = x3113 + x3114;
        let x3116 = qd[2] * qd[3];
        let x3117 = x3116 + x3116;
        let x3118 = 2.0 * x3117;
        let x3119 = qd[1] * qd[4];
        let x3120 = x3119 + x3119;
        let x3121 = 2.0 * x3120;
        let x3122 = qd[2] * qd[4];
        let x3123 = x3122 + x3122;
        let x3124 = 2.0 * x3123;
        let x3125 = qd[1] * qd[3];
        let x3126 = x3125 + x3125;
        let x3127 = 2.0 * x3126;
        let x3128 = x3118 + x3121;
        let x3129 = qd[1] * qd[2];
        let x3130 = x3129 + x3129;
        let x3131 = 2.0 * x3130;
        let x3133 = x3124 - x3127;
        let x3134 = x260 + x3131;
        let x3135 = qd[7] * x891;
        let x3136 = qd[8] * x893;
        let x3137 = x239 + x240;
        let x3138 = qd[6] * qd[7];
        let x3139 = x3138 + x3138;
        let x3140 = 2.0 * x3139;
        let x3141 = qd[5] * qd[8];
        let x3142 = x3141 + x3141;
        let x3143 = 2.0 * x3142;
        let x3145 = x3140 - x3143;
        let x3146 = qd[7] * qd[8];
        let x3147 = x3146 + x3146;
        let x3148 = 2.0 * x3147;
        let x3149 = x257 + x3148;
        let x3151 = x237 + x3115;
        let x3152 = x238 + x3151;
        let x3153 = x3135 + x3137;
        let x3154 = x3136 + x3153;
        let x3155 = -x3128;
        let x3156 = -x3133;
        let x3157 = -x3134;
        let x3158 = -x3145;
        let x3159 = -x3152;
        let x3160 = -x3154;
        out[0] = x3155;
        out[1] = x3156;
        out[2] = x3157;
        out[3] = x3158;
        out[4] = x3149;
        out[5] = x3159;
        out[6] = x3160;
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
        let x3026 = x332 + x333;
        let x3027 = q[2] * q[3];
        let x3028 = 2.0 * x3027;
        let x3029 = q[1] * q[4];
        let x3030 = 2.0 * x3029;
        let x3031 = q[2] * q[4];
        let x3032 = 2.0 * x3031;
        let x3033 = q[1] * q[3];
        let x3034 = 2.0 * x3033;
        let x3035 = x3028 + x3030;
        let x3036 = q[1] * q[2];
        let x3037 = 2.0 * x3036;
        let x3039 = x3032 - x3034;
        let x3040 = x67 + x3037;
        let x3041 = q[7] * q[7];
        let x3042 = q[8] * q[8];
        let x3043 = x38 + x39;
        let x3044 = q[6] * q[7];
        let x3045 = 2.0 * x3044;
        let x3046 = q[5] * q[8];
        let x3047 = 2.0 * x3046;
        let x3049 = x3045 - x3047;
        let x3050 = q[7] * q[8];
        let x3051 = 2.0 * x3050;
        let x3052 = x64 + x3051;
        let x3053 = -x3052;
        let x3054 = x36 + x3026;
        let x3055 = x37 + x3054;
        let x3056 = x3055 - 1.0;
        let x3057 = x3041 + x3043;
        let x3058 = x3042 + x3057;
        let x3059 = x3058 - 1.0;
        let x3060 = -x339;
        let x3061 = 2.0 * q[7];
        let x3062 = 2.0 * q[8];
        let x3063 = -x3062;
        let x3064 = -x3061;
        let x3113 = qd[1] * x505;
        let x3114 = qd[2] * x507;
        let x3115 = x3113 + x3114;
        let x3116 = qd[2] * qd[3];
        let x3117 = x3116 + x3116;
        let x3118 = 2.0 * x3117;
        let x3119 = qd[1] * qd[4];
        let x3120 = x3119 + x3119;
        let x3121 = 2.0 * x3120;
        let x3122 = qd[2] * qd[4];
        let x3123 = x3122 + x3122;
        let x3124 = 2.0 * x3123;
        let x3125 = qd[1] * qd[3];
        let x3126 = x3125 + x3125;
        let x3127 = 2.0 * x3126;
        let x3128 = x3118 + x3121;
        let x3129 = qd[1] * qd[2];
        let x3130 = x3129 + x3129;
        let x3131 = 2.0 * x3130;
        let x3133 = x3124 - x3127;
        let x3134 = x260 + x3131;
        let x3135 = qd[7] * x891;
        let x3136 = qd[8] * x893;
        let x3137 = x239 + x240;
        let x3138 = qd[6] * qd[7];
        let x3139 = x3138 + x3138;
        let x3140 = 2.0 * x3139;
        let x3141 = qd[5] * qd[8];
        let x3142 = x3141 + x3141;
        let x3143 = 2.0 * x3142;
        let x3145 = x3140 - x3143;
        let x3146 = qd[7] * qd[8];
        let x3147 = x3146 + x3146;
        let x3148 = 2.0 * x3147;
        let x3149 = x257 + x3148;
        let x3151 = x237 + x3115;
        let x3152 = x238 + x3151;
        let x3153 = x3135 + x3137;
        let x3154 = x3136 + x3153;
        let x3155 = -x3128;
        let x3156 = -x3133;
        let x3157 = -x3134;
        let x3158 = -x3145;
        let x3159 = -x3152;
        let x3160 = -x3154;
        phi[0] = x3035;
        phi_q[0] = x137;
        phi_q[1] = x136;
        phi_q[2] = x341;
        phi_q[3] = x339;
        phi_t[0] = 0.0;
        gamma[0] = x3155;
        phi[1] = x3039;
        phi_q[4] = x141;
        phi_q[5] = x137;
        phi_q[6] = x3060;
        phi_q[7] = x341;
        phi_t[1] = 0.0;
        gamma[1] = x3156;
        phi[2] = x3040;
        phi_q[8] = x341;
        phi_q[9] = x339;
        phi_q[10] = x137;
        phi_q[11] = x136;
        phi_t[2] = 0.0;
        gamma[2] = x3157;
        phi[3] = x3049;
        phi_q[12] = x3063;
        phi_q[13] = x3061;
        phi_q[14] = x139;
        phi_q[15] = x140;
        phi_t[3] = 0.0;
        gamma[3] = x3158;
        phi[4] = x3053;
        phi_q[16] = x518;
        phi_q[17] = x140;
        phi_q[18] = x3063;
        phi_q[19] = x3064;
        phi_t[4] = 0.0;
        gamma[4] = x3149;
        phi[5] = x3056;
        phi_q[20] = x339;
        phi_q[21] = x341;
        phi_q[22] = x136;
        phi_q[23] = x137;
        phi_t[5] = 0.0;
        gamma[5] = x3159;
        phi[6] = x3059;
        phi_q[24] = x138;
        phi_q[25] = x139;
        phi_q[26] = x3061;
        phi_q[27] = x3062;
        phi_t[6] = 0.0;
        gamma[6] = x3160;
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
        let x3043 = x38 + x39;
        let x3161 = 2.0 * x3043;
        let x3162 = x3161 - 1.0;
        let x3163 = q[6] * q[8];
        let x3164 = 2.0 * x3163;
        let x3165 = q[5] * q[7];
        let x3166 = 2.0 * x3165;
        let x3168 = x3164 - x3166;
        let x3169 = x331.sqrt();
        let x3170 = x3169 - 1.0;
        let x3171 = x3170 * x3170;
        let x3173 = -x3168;
        let x3174 = x3173.atan2(x3162);
        let x3175 = x3174 * x3174;
        let x3821 = x3171 * k[11];
        let x3822 = x3175 * k[12];
        let x3823 = 9.81 + x3821;
        let x3824 = x3822 + x3823;
        out[0] = x3824;
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
        let x13 = symbody_runtime::trig::sin(t);
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
        let x3043 = x38 + x39;
        let x3092 = x166 + x167;
        let x3161 = 2.0 * x3043;
        let x3162 = x3161 - 1.0;
        let x3163 = q[6] * q[8];
        let x3164 = 2.0 * x3163;
        let x3165 = q[5] * q[7];
        let x3166 = 2.0 * x3165;
        let x3168 = x3164 - x3166;
        let x3169 = x331.sqrt();
        let x3179 = 2.0 * x3169;
        let x3180 = 1.0 / x3179;
        let x3181 = x338 * x3180;
        let x3186 = 2.0 * x3092;
        let x3187 = q[8] * qd[6];
        let x3188 = q[6] * qd[8];
        let x3189 = x3187 + x3188;
        let x3190 = 2.0 * x3189;
        let x3191 = q[7] * qd[5];
        let x3192 = q[5] * qd[7];
        let x3193 = x3191 + x3192;
        let x3194 = 2.0 * x3193;
        let x3196 = x3190 - x3194;
        let x3197 = x3162 * x3162;
        let x3198 = x3168 * x3168;
        let x3199 = x3197 + x3198;
        let x3200 = x3162 * x3196;
        let x3202 = x3168 * x3186;
        let x3203 = x3202 - x3200;
        let x3204 = 1.0 / x3199;
        let x3205 = x3203 * x3204;
        let x3212 = x3187 - x3191;
        let x3213 = x3192 + x3212;
        let x3214 = x3213 - x3188;
        let x3215 = 2.0 * x3214;
        let x3800 = t * k[1];
        let x3801 = symbody_runtime::trig::sin(x3800);
        let x3802 = k[0] * x3801;
        let x3806 = t * k[4];
        let x3807 = symbody_runtime::trig::cos(x3806);
        let x3808 = k[3] * x3807;
        let x3810 = x13 * k[5];
        let x3817 = qd[0] * k[2];
        let x3825 = x3181 * k[6];
        let x3827 = x3802 - x3825;
        let x3828 = x3181 * x3827;
        let x3829 = x3205 * k[7];
        let x3831 = x3808 - x3829;
        let x3832 = x3205 * x3831;
        let x3833 = x3215 * x3810;
        let x3834 = x3817 + x3828;
        let x3835 = x3832 + x3834;
        let x3836 = x3833 + x3835;
        out[0] = x3836;
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
            kkt: &KKT,
        };
        use symbody_runtime::kkt::{
            length_error, mass_pivot_error, KktError, KktKernels, Pivoting,
        };
        /// The KKT factor and solve for this model's patterns, straight-line (`KktKernels`).
        pub static KKT: [KktKernels; 1] = [
            KktKernels {
                pattern: 0x431b064dad0c7067,
                storage: 65,
                factor: kkt_factor_0,
                solve: kkt_solve_0,
                phi_q_rows: &PHI_Q_ROWS,
                phi_q_cols: &PHI_Q_COLS,
                transpose_times: kkt_transpose_times,
                times_add: kkt_times_add,
                mass_rows: &MASS_ROWS,
                mass_cols: &MASS_COLS,
                mass_times: kkt_mass_times,
                kinetic_energy: kkt_kinetic_energy,
                loads: None,
            },
        ];
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx")]
        fn kkt_factor_0_avx(
            mass: &[f64],
            c: f64,
            phi_q: &[f64],
            st: &mut [f64],
            piv: &mut Pivoting,
        ) -> Result<(), KktError> {
            kkt_factor_0_any(mass, c, phi_q, st, piv)
        }
        fn kkt_factor_0(
            mass: &[f64],
            c: f64,
            phi_q: &[f64],
            st: &mut [f64],
            piv: &mut Pivoting,
        ) -> Result<(), KktError> {
            #[cfg(target_arch = "x86_64")]
            {
                if !symbody_runtime::kkt::kernels_run_here() {
                    return Err(KktError::KernelsUnsupported);
                }
                unsafe { kkt_factor_0_avx(mass, c, phi_q, st, piv) }
            }
            #[cfg(not(target_arch = "x86_64"))] kkt_factor_0_any(mass, c, phi_q, st, piv)
        }
        #[allow(
            unused_variables,
            unused_parens,
            clippy::neg_cmp_op_on_partial_ord,
            clippy::nonminimal_bool
        )]
        #[inline(always)]
        fn kkt_factor_0_any(
            mass: &[f64],
            c: f64,
            phi_q: &[f64],
            st: &mut [f64],
            piv: &mut Pivoting,
        ) -> Result<(), KktError> {
            let mass: &[f64; 33] = mass
                .try_into()
                .map_err(|_| length_error(33, mass.len()))?;
            let phi_q: &[f64; 28] = phi_q
                .try_into()
                .map_err(|_| length_error(28, phi_q.len()))?;
            let st_len = st.len();
            let st: &mut [f64; 65] = st
                .try_into()
                .map_err(|_| length_error(65, st_len))?;
            if !((c * mass[0]) > 0.0 && (c * mass[0]) <= f64::MAX) {
                return Err(mass_pivot_error((c * mass[0]), 0));
            }
            let v0: f64 = (c * mass[0]).sqrt();
            let v1: f64 = 1.0 / v0;
            st[12] = v1;
            if !((c * mass[1]) > 0.0 && (c * mass[1]) <= f64::MAX) {
                return Err(mass_pivot_error((c * mass[1]), 1));
            }
            let v2: f64 = (c * mass[1]).sqrt();
            let v3: f64 = 1.0 / v2;
            st[13] = v3;
            let v4: f64 = (c * mass[5]) * v3;
            st[0] = v4;
            let v5: f64 = (c * mass[9]) * v3;
            st[1] = v5;
            let v6: f64 = (c * mass[13]) * v3;
            st[3] = v6;
            let v7: f64 = (c * mass[6]) - v4 * v4;
            if !(v7 > 0.0 && v7 <= f64::MAX) {
                return Err(mass_pivot_error(v7, 2));
            }
            let v8: f64 = v7.sqrt();
            let v9: f64 = 1.0 / v8;
            st[14] = v9;
            let v10: f64 = (c * mass[10]) - v5 * v4;
            let v11: f64 = v10 * v9;
            st[2] = v11;
            let v12: f64 = (c * mass[14]) - v6 * v4;
            let v13: f64 = v12 * v9;
            st[4] = v13;
            let v14: f64 = (c * mass[11]) - v5 * v5;
            let v15: f64 = v14 - v11 * v11;
            if !(v15 > 0.0 && v15 <= f64::MAX) {
                return Err(mass_pivot_error(v15, 3));
            }
            let v16: f64 = v15.sqrt();
            let v17: f64 = 1.0 / v16;
            st[15] = v17;
            let v18: f64 = (c * mass[15]) - v6 * v5;
            let v19: f64 = v18 - v13 * v11;
            let v20: f64 = v19 * v17;
            st[5] = v20;
            let v21: f64 = (c * mass[16]) - v6 * v6;
            let v22: f64 = v21 - v13 * v13;
            let v23: f64 = v22 - v20 * v20;
            if !(v23 > 0.0 && v23 <= f64::MAX) {
                return Err(mass_pivot_error(v23, 4));
            }
            let v24: f64 = v23.sqrt();
            let v25: f64 = 1.0 / v24;
            st[16] = v25;
            let v26: f64 = phi_q[0] * v3;
            st[21] = v26;
            let v27: f64 = phi_q[1] - v4 * v26;
            let v28: f64 = v27 * v9;
            st[22] = v28;
            let v29: f64 = phi_q[2] - v5 * v26;
            let v30: f64 = v29 - v11 * v28;
            let v31: f64 = v30 * v17;
            st[23] = v31;
            let v32: f64 = phi_q[3] - v6 * v26;
            let v33: f64 = v32 - v13 * v28;
            let v34: f64 = v33 - v20 * v31;
            let v35: f64 = v34 * v25;
            st[24] = v35;
            let v36: f64 = phi_q[4] * v3;
            st[25] = v36;
            let v37: f64 = phi_q[5] - v4 * v36;
            let v38: f64 = v37 * v9;
            st[26] = v38;
            let v39: f64 = phi_q[6] - v5 * v36;
            let v40: f64 = v39 - v11 * v38;
            let v41: f64 = v40 * v17;
            st[27] = v41;
            let v42: f64 = phi_q[7] - v6 * v36;
            let v43: f64 = v42 - v13 * v38;
            let v44: f64 = v43 - v20 * v41;
            let v45: f64 = v44 * v25;
            st[28] = v45;
            let v46: f64 = phi_q[8] * v3;
            st[29] = v46;
            let v47: f64 = phi_q[9] - v4 * v46;
            let v48: f64 = v47 * v9;
            st[30] = v48;
            let v49: f64 = phi_q[10] - v5 * v46;
            let v50: f64 = v49 - v11 * v48;
            let v51: f64 = v50 * v17;
            st[31] = v51;
            let v52: f64 = phi_q[11] - v6 * v46;
            let v53: f64 = v52 - v13 * v48;
            let v54: f64 = v53 - v20 * v51;
            let v55: f64 = v54 * v25;
            st[32] = v55;
            let v56: f64 = phi_q[20] * v3;
            st[33] = v56;
            let v57: f64 = phi_q[21] - v4 * v56;
            let v58: f64 = v57 * v9;
            st[34] = v58;
            let v59: f64 = phi_q[22] - v5 * v56;
            let v60: f64 = v59 - v11 * v58;
            let v61: f64 = v60 * v17;
            st[35] = v61;
            let v62: f64 = phi_q[23] - v6 * v56;
            let v63: f64 = v62 - v13 * v58;
            let v64: f64 = v63 - v20 * v61;
            let v65: f64 = v64 * v25;
            st[36] = v65;
            let v66: f64 = v26 * v26;
            let v67: f64 = v28 * v28;
            let v68: f64 = v66 + v67;
            let v69: f64 = v31 * v31;
            let v70: f64 = v68 + v69;
            let v71: f64 = v35 * v35;
            let v72: f64 = v70 + v71;
            let v73: f64 = v36 * v26;
            let v74: f64 = v38 * v28;
            let v75: f64 = v73 + v74;
            let v76: f64 = v41 * v31;
            let v77: f64 = v75 + v76;
            let v78: f64 = v45 * v35;
            let v79: f64 = v77 + v78;
            let v80: f64 = v36 * v36;
            let v81: f64 = v38 * v38;
            let v82: f64 = v80 + v81;
            let v83: f64 = v41 * v41;
            let v84: f64 = v82 + v83;
            let v85: f64 = v45 * v45;
            let v86: f64 = v84 + v85;
            let v87: f64 = v46 * v26;
            let v88: f64 = v48 * v28;
            let v89: f64 = v87 + v88;
            let v90: f64 = v51 * v31;
            let v91: f64 = v89 + v90;
            let v92: f64 = v55 * v35;
            let v93: f64 = v91 + v92;
            let v94: f64 = v46 * v36;
            let v95: f64 = v48 * v38;
            let v96: f64 = v94 + v95;
            let v97: f64 = v51 * v41;
            let v98: f64 = v96 + v97;
            let v99: f64 = v55 * v45;
            let v100: f64 = v98 + v99;
            let v101: f64 = v46 * v46;
            let v102: f64 = v48 * v48;
            let v103: f64 = v101 + v102;
            let v104: f64 = v51 * v51;
            let v105: f64 = v103 + v104;
            let v106: f64 = v55 * v55;
            let v107: f64 = v105 + v106;
            let v108: f64 = v56 * v26;
            let v109: f64 = v58 * v28;
            let v110: f64 = v108 + v109;
            let v111: f64 = v61 * v31;
            let v112: f64 = v110 + v111;
            let v113: f64 = v65 * v35;
            let v114: f64 = v112 + v113;
            let v115: f64 = v56 * v36;
            let v116: f64 = v58 * v38;
            let v117: f64 = v115 + v116;
            let v118: f64 = v61 * v41;
            let v119: f64 = v117 + v118;
            let v120: f64 = v65 * v45;
            let v121: f64 = v119 + v120;
            let v122: f64 = v56 * v46;
            let v123: f64 = v58 * v48;
            let v124: f64 = v122 + v123;
            let v125: f64 = v61 * v51;
            let v126: f64 = v124 + v125;
            let v127: f64 = v65 * v55;
            let v128: f64 = v126 + v127;
            let v129: f64 = v56 * v56;
            let v130: f64 = v58 * v58;
            let v131: f64 = v129 + v130;
            let v132: f64 = v61 * v61;
            let v133: f64 = v131 + v132;
            let v134: f64 = v65 * v65;
            let v135: f64 = v133 + v134;
            if !((c * mass[17]) > 0.0 && (c * mass[17]) <= f64::MAX) {
                return Err(mass_pivot_error((c * mass[17]), 5));
            }
            let v136: f64 = (c * mass[17]).sqrt();
            let v137: f64 = 1.0 / v136;
            st[17] = v137;
            let v138: f64 = (c * mass[21]) * v137;
            st[6] = v138;
            let v139: f64 = (c * mass[25]) * v137;
            st[7] = v139;
            let v140: f64 = (c * mass[29]) * v137;
            st[9] = v140;
            let v141: f64 = (c * mass[22]) - v138 * v138;
            if !(v141 > 0.0 && v141 <= f64::MAX) {
                return Err(mass_pivot_error(v141, 6));
            }
            let v142: f64 = v141.sqrt();
            let v143: f64 = 1.0 / v142;
            st[18] = v143;
            let v144: f64 = (c * mass[26]) - v139 * v138;
            let v145: f64 = v144 * v143;
            st[8] = v145;
            let v146: f64 = (c * mass[30]) - v140 * v138;
            let v147: f64 = v146 * v143;
            st[10] = v147;
            let v148: f64 = (c * mass[27]) - v139 * v139;
            let v149: f64 = v148 - v145 * v145;
            if !(v149 > 0.0 && v149 <= f64::MAX) {
                return Err(mass_pivot_error(v149, 7));
            }
            let v150: f64 = v149.sqrt();
            let v151: f64 = 1.0 / v150;
            st[19] = v151;
            let v152: f64 = (c * mass[31]) - v140 * v139;
            let v153: f64 = v152 - v147 * v145;
            let v154: f64 = v153 * v151;
            st[11] = v154;
            let v155: f64 = (c * mass[32]) - v140 * v140;
            let v156: f64 = v155 - v147 * v147;
            let v157: f64 = v156 - v154 * v154;
            if !(v157 > 0.0 && v157 <= f64::MAX) {
                return Err(mass_pivot_error(v157, 8));
            }
            let v158: f64 = v157.sqrt();
            let v159: f64 = 1.0 / v158;
            st[20] = v159;
            let v160: f64 = phi_q[12] * v137;
            st[37] = v160;
            let v161: f64 = phi_q[13] - v138 * v160;
            let v162: f64 = v161 * v143;
            st[38] = v162;
            let v163: f64 = phi_q[14] - v139 * v160;
            let v164: f64 = v163 - v145 * v162;
            let v165: f64 = v164 * v151;
            st[39] = v165;
            let v166: f64 = phi_q[15] - v140 * v160;
            let v167: f64 = v166 - v147 * v162;
            let v168: f64 = v167 - v154 * v165;
            let v169: f64 = v168 * v159;
            st[40] = v169;
            let v170: f64 = phi_q[16] * v137;
            st[41] = v170;
            let v171: f64 = phi_q[17] - v138 * v170;
            let v172: f64 = v171 * v143;
            st[42] = v172;
            let v173: f64 = phi_q[18] - v139 * v170;
            let v174: f64 = v173 - v145 * v172;
            let v175: f64 = v174 * v151;
            st[43] = v175;
            let v176: f64 = phi_q[19] - v140 * v170;
            let v177: f64 = v176 - v147 * v172;
            let v178: f64 = v177 - v154 * v175;
            let v179: f64 = v178 * v159;
            st[44] = v179;
            let v180: f64 = phi_q[24] * v137;
            st[45] = v180;
            let v181: f64 = phi_q[25] - v138 * v180;
            let v182: f64 = v181 * v143;
            st[46] = v182;
            let v183: f64 = phi_q[26] - v139 * v180;
            let v184: f64 = v183 - v145 * v182;
            let v185: f64 = v184 * v151;
            st[47] = v185;
            let v186: f64 = phi_q[27] - v140 * v180;
            let v187: f64 = v186 - v147 * v182;
            let v188: f64 = v187 - v154 * v185;
            let v189: f64 = v188 * v159;
            st[48] = v189;
            let v190: f64 = v160 * v160;
            let v191: f64 = v162 * v162;
            let v192: f64 = v190 + v191;
            let v193: f64 = v165 * v165;
            let v194: f64 = v192 + v193;
            let v195: f64 = v169 * v169;
            let v196: f64 = v194 + v195;
            let v197: f64 = v170 * v160;
            let v198: f64 = v172 * v162;
            let v199: f64 = v197 + v198;
            let v200: f64 = v175 * v165;
            let v201: f64 = v199 + v200;
            let v202: f64 = v179 * v169;
            let v203: f64 = v201 + v202;
            let v204: f64 = v170 * v170;
            let v205: f64 = v172 * v172;
            let v206: f64 = v204 + v205;
            let v207: f64 = v175 * v175;
            let v208: f64 = v206 + v207;
            let v209: f64 = v179 * v179;
            let v210: f64 = v208 + v209;
            let v211: f64 = v180 * v160;
            let v212: f64 = v182 * v162;
            let v213: f64 = v211 + v212;
            let v214: f64 = v185 * v165;
            let v215: f64 = v213 + v214;
            let v216: f64 = v189 * v169;
            let v217: f64 = v215 + v216;
            let v218: f64 = v180 * v170;
            let v219: f64 = v182 * v172;
            let v220: f64 = v218 + v219;
            let v221: f64 = v185 * v175;
            let v222: f64 = v220 + v221;
            let v223: f64 = v189 * v179;
            let v224: f64 = v222 + v223;
            let v225: f64 = v180 * v180;
            let v226: f64 = v182 * v182;
            let v227: f64 = v225 + v226;
            let v228: f64 = v185 * v185;
            let v229: f64 = v227 + v228;
            let v230: f64 = v189 * v189;
            let v231: f64 = v229 + v230;
            let (v232, v233) = piv.pivot(v196, v196, 3, false)?;
            st[58] = v232;
            let v234: f64 = v203 * v232;
            st[49] = v234;
            let v235: f64 = v210 - v234 * v233 * v234;
            let v236: f64 = v217 * v232;
            st[50] = v236;
            let v237: f64 = v231 - v236 * v233 * v236;
            let v238: f64 = v224 - v236 * v233 * v234;
            let (v239, v240) = piv.pivot(v235, v210, 4, false)?;
            st[59] = v239;
            let v241: f64 = v238 * v239;
            st[51] = v241;
            let v242: f64 = v237 - v241 * v240 * v241;
            let (v243, v244) = piv.pivot(v242, v231, 6, false)?;
            st[60] = v243;
            let (v245, v246) = piv.pivot(v72, v72, 0, false)?;
            st[61] = v245;
            let v247: f64 = v79 * v245;
            st[52] = v247;
            let v248: f64 = v86 - v247 * v246 * v247;
            let v249: f64 = v93 * v245;
            st[53] = v249;
            let v250: f64 = v107 - v249 * v246 * v249;
            let v251: f64 = v114 * v245;
            st[54] = v251;
            let v252: f64 = v135 - v251 * v246 * v251;
            let v253: f64 = v100 - v249 * v246 * v247;
            let v254: f64 = v121 - v251 * v246 * v247;
            let v255: f64 = v128 - v251 * v246 * v249;
            let (v256, v257) = piv.pivot(v248, v86, 1, false)?;
            st[62] = v256;
            let v258: f64 = v253 * v256;
            st[55] = v258;
            let v259: f64 = v250 - v258 * v257 * v258;
            let v260: f64 = v254 * v256;
            st[56] = v260;
            let v261: f64 = v252 - v260 * v257 * v260;
            let v262: f64 = v255 - v260 * v257 * v258;
            let (v263, v264) = piv.pivot(v259, v107, 2, false)?;
            st[63] = v263;
            let v265: f64 = v262 * v263;
            st[57] = v265;
            let v266: f64 = v261 - v265 * v264 * v265;
            let (v267, v268) = piv.pivot(v266, v135, 5, false)?;
            st[64] = v267;
            Ok(())
        }
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx")]
        fn kkt_solve_0_avx(
            f: &[f64],
            g: &[f64],
            x: &mut [f64],
            y: &mut [f64],
            st: &[f64],
        ) -> Result<(), KktError> {
            kkt_solve_0_any(f, g, x, y, st)
        }
        fn kkt_solve_0(
            f: &[f64],
            g: &[f64],
            x: &mut [f64],
            y: &mut [f64],
            st: &[f64],
        ) -> Result<(), KktError> {
            #[cfg(target_arch = "x86_64")]
            {
                if !symbody_runtime::kkt::kernels_run_here() {
                    return Err(KktError::KernelsUnsupported);
                }
                unsafe { kkt_solve_0_avx(f, g, x, y, st) }
            }
            #[cfg(not(target_arch = "x86_64"))] kkt_solve_0_any(f, g, x, y, st)
        }
        #[allow(
            unused_variables,
            clippy::neg_cmp_op_on_partial_ord,
            clippy::nonminimal_bool
        )]
        #[inline(always)]
        fn kkt_solve_0_any(
            f: &[f64],
            g: &[f64],
            x: &mut [f64],
            y: &mut [f64],
            st: &[f64],
        ) -> Result<(), KktError> {
            let f: &[f64; 9] = f.try_into().map_err(|_| length_error(9, f.len()))?;
            let g: &[f64; 7] = g.try_into().map_err(|_| length_error(7, g.len()))?;
            let x_len = x.len();
            let x: &mut [f64; 9] = x.try_into().map_err(|_| length_error(9, x_len))?;
            let y_len = y.len();
            let y: &mut [f64; 7] = y.try_into().map_err(|_| length_error(7, y_len))?;
            let st: &[f64; 65] = st.try_into().map_err(|_| length_error(65, st.len()))?;
            x.fill(0.0);
            y[0] = -g[0];
            y[1] = -g[1];
            y[2] = -g[2];
            y[3] = -g[3];
            y[4] = -g[4];
            y[5] = -g[5];
            y[6] = -g[6];
            if f.iter().any(|&v| v != 0.0) {
                let v0: f64 = f[0];
                let v1: f64 = f[1];
                let v2: f64 = f[2];
                let v3: f64 = f[3];
                let v4: f64 = f[4];
                let v5: f64 = v0 * st[12];
                let v6: f64 = v1 * st[13];
                let v7: f64 = v2 - st[0] * v6;
                let v8: f64 = v7 * st[14];
                let v9: f64 = v3 - st[1] * v6;
                let v10: f64 = v9 - st[2] * v8;
                let v11: f64 = v10 * st[15];
                let v12: f64 = v4 - st[3] * v6;
                let v13: f64 = v12 - st[4] * v8;
                let v14: f64 = v13 - st[5] * v11;
                let v15: f64 = v14 * st[16];
                let v16: f64 = st[21] * v6;
                let v17: f64 = st[22] * v8;
                let v18: f64 = v16 + v17;
                let v19: f64 = st[23] * v11;
                let v20: f64 = v18 + v19;
                let v21: f64 = st[24] * v15;
                let v22: f64 = v20 + v21;
                y[0] += v22;
                let v23: f64 = st[25] * v6;
                let v24: f64 = st[26] * v8;
                let v25: f64 = v23 + v24;
                let v26: f64 = st[27] * v11;
                let v27: f64 = v25 + v26;
                let v28: f64 = st[28] * v15;
                let v29: f64 = v27 + v28;
                y[1] += v29;
                let v30: f64 = st[29] * v6;
                let v31: f64 = st[30] * v8;
                let v32: f64 = v30 + v31;
                let v33: f64 = st[31] * v11;
                let v34: f64 = v32 + v33;
                let v35: f64 = st[32] * v15;
                let v36: f64 = v34 + v35;
                y[2] += v36;
                let v37: f64 = st[33] * v6;
                let v38: f64 = st[34] * v8;
                let v39: f64 = v37 + v38;
                let v40: f64 = st[35] * v11;
                let v41: f64 = v39 + v40;
                let v42: f64 = st[36] * v15;
                let v43: f64 = v41 + v42;
                y[5] += v43;
                x[0] = v5;
                x[1] = v6;
                x[2] = v8;
                x[3] = v11;
                x[4] = v15;
                let v44: f64 = f[5];
                let v45: f64 = f[6];
                let v46: f64 = f[7];
                let v47: f64 = f[8];
                let v48: f64 = v44 * st[17];
                let v49: f64 = v45 - st[6] * v48;
                let v50: f64 = v49 * st[18];
                let v51: f64 = v46 - st[7] * v48;
                let v52: f64 = v51 - st[8] * v50;
                let v53: f64 = v52 * st[19];
                let v54: f64 = v47 - st[9] * v48;
                let v55: f64 = v54 - st[10] * v50;
                let v56: f64 = v55 - st[11] * v53;
                let v57: f64 = v56 * st[20];
                let v58: f64 = st[37] * v48;
                let v59: f64 = st[38] * v50;
                let v60: f64 = v58 + v59;
                let v61: f64 = st[39] * v53;
                let v62: f64 = v60 + v61;
                let v63: f64 = st[40] * v57;
                let v64: f64 = v62 + v63;
                y[3] += v64;
                let v65: f64 = st[41] * v48;
                let v66: f64 = st[42] * v50;
                let v67: f64 = v65 + v66;
                let v68: f64 = st[43] * v53;
                let v69: f64 = v67 + v68;
                let v70: f64 = st[44] * v57;
                let v71: f64 = v69 + v70;
                y[4] += v71;
                let v72: f64 = st[45] * v48;
                let v73: f64 = st[46] * v50;
                let v74: f64 = v72 + v73;
                let v75: f64 = st[47] * v53;
                let v76: f64 = v74 + v75;
                let v77: f64 = st[48] * v57;
                let v78: f64 = v76 + v77;
                y[6] += v78;
                x[5] = v48;
                x[6] = v50;
                x[7] = v53;
                x[8] = v57;
            }
            let v79: f64 = y[4] - st[49] * y[3];
            let v80: f64 = y[6] - st[50] * y[3];
            let v81: f64 = v80 - st[51] * v79;
            let v82: f64 = y[1] - st[52] * y[0];
            let v83: f64 = y[2] - st[53] * y[0];
            let v84: f64 = y[5] - st[54] * y[0];
            let v85: f64 = v83 - st[55] * v82;
            let v86: f64 = v84 - st[56] * v82;
            let v87: f64 = v86 - st[57] * v85;
            let v88: f64 = y[3] * st[58];
            let v89: f64 = v79 * st[59];
            let v90: f64 = v81 * st[60];
            let v91: f64 = y[0] * st[61];
            let v92: f64 = v82 * st[62];
            let v93: f64 = v85 * st[63];
            let v94: f64 = v87 * st[64];
            let v95: f64 = v93 - st[57] * v94;
            let v96: f64 = v92 - st[55] * v95;
            let v97: f64 = v96 - st[56] * v94;
            let v98: f64 = v91 - st[52] * v97;
            let v99: f64 = v98 - st[53] * v95;
            let v100: f64 = v99 - st[54] * v94;
            let v101: f64 = v89 - st[51] * v90;
            let v102: f64 = v88 - st[49] * v101;
            let v103: f64 = v102 - st[50] * v90;
            y[3] = v103;
            y[4] = v101;
            y[6] = v90;
            y[0] = v100;
            y[1] = v97;
            y[2] = v95;
            y[5] = v94;
            let v104: f64 = x[1] - st[21] * v100;
            let v105: f64 = x[2] - st[22] * v100;
            let v106: f64 = x[3] - st[23] * v100;
            let v107: f64 = x[4] - st[24] * v100;
            let v108: f64 = v104 - st[25] * v97;
            let v109: f64 = v105 - st[26] * v97;
            let v110: f64 = v106 - st[27] * v97;
            let v111: f64 = v107 - st[28] * v97;
            let v112: f64 = v108 - st[29] * v95;
            let v113: f64 = v109 - st[30] * v95;
            let v114: f64 = v110 - st[31] * v95;
            let v115: f64 = v111 - st[32] * v95;
            let v116: f64 = v112 - st[33] * v94;
            let v117: f64 = v113 - st[34] * v94;
            let v118: f64 = v114 - st[35] * v94;
            let v119: f64 = v115 - st[36] * v94;
            let v120: f64 = v119 * st[16];
            let v121: f64 = v118 - st[5] * v120;
            let v122: f64 = v121 * st[15];
            let v123: f64 = v117 - st[2] * v122;
            let v124: f64 = v123 - st[4] * v120;
            let v125: f64 = v124 * st[14];
            let v126: f64 = v116 - st[0] * v125;
            let v127: f64 = v126 - st[1] * v122;
            let v128: f64 = v127 - st[3] * v120;
            let v129: f64 = v128 * st[13];
            let v130: f64 = x[0] * st[12];
            x[0] = v130;
            x[1] = v129;
            x[2] = v125;
            x[3] = v122;
            x[4] = v120;
            let v131: f64 = x[5] - st[37] * v103;
            let v132: f64 = x[6] - st[38] * v103;
            let v133: f64 = x[7] - st[39] * v103;
            let v134: f64 = x[8] - st[40] * v103;
            let v135: f64 = v131 - st[41] * v101;
            let v136: f64 = v132 - st[42] * v101;
            let v137: f64 = v133 - st[43] * v101;
            let v138: f64 = v134 - st[44] * v101;
            let v139: f64 = v135 - st[45] * v90;
            let v140: f64 = v136 - st[46] * v90;
            let v141: f64 = v137 - st[47] * v90;
            let v142: f64 = v138 - st[48] * v90;
            let v143: f64 = v142 * st[20];
            let v144: f64 = v141 - st[11] * v143;
            let v145: f64 = v144 * st[19];
            let v146: f64 = v140 - st[8] * v145;
            let v147: f64 = v146 - st[10] * v143;
            let v148: f64 = v147 * st[18];
            let v149: f64 = v139 - st[6] * v148;
            let v150: f64 = v149 - st[7] * v145;
            let v151: f64 = v150 - st[9] * v143;
            let v152: f64 = v151 * st[17];
            x[5] = v152;
            x[6] = v148;
            x[7] = v145;
            x[8] = v143;
            Ok(())
        }
        fn kkt_transpose_times(
            phi_q: &[f64],
            y: &[f64],
            out: &mut [f64],
        ) -> Result<(), KktError> {
            let phi_q: &[f64; 28] = phi_q
                .try_into()
                .map_err(|_| length_error(28, phi_q.len()))?;
            let y: &[f64; 7] = y.try_into().map_err(|_| length_error(7, y.len()))?;
            let out_len = out.len();
            let out: &mut [f64; 9] = out
                .try_into()
                .map_err(|_| length_error(9, out_len))?;
            out[0] = 0.0;
            out[1] = phi_q[0] * y[0] + phi_q[4] * y[1] + phi_q[8] * y[2]
                + phi_q[20] * y[5];
            out[2] = phi_q[1] * y[0] + phi_q[5] * y[1] + phi_q[9] * y[2]
                + phi_q[21] * y[5];
            out[3] = phi_q[2] * y[0] + phi_q[6] * y[1] + phi_q[10] * y[2]
                + phi_q[22] * y[5];
            out[4] = phi_q[3] * y[0] + phi_q[7] * y[1] + phi_q[11] * y[2]
                + phi_q[23] * y[5];
            out[5] = phi_q[12] * y[3] + phi_q[16] * y[4] + phi_q[24] * y[6];
            out[6] = phi_q[13] * y[3] + phi_q[17] * y[4] + phi_q[25] * y[6];
            out[7] = phi_q[14] * y[3] + phi_q[18] * y[4] + phi_q[26] * y[6];
            out[8] = phi_q[15] * y[3] + phi_q[19] * y[4] + phi_q[27] * y[6];
            Ok(())
        }
        #[allow(clippy::assign_op_pattern)]
        fn kkt_times_add(
            phi_q: &[f64],
            x: &[f64],
            out: &mut [f64],
        ) -> Result<(), KktError> {
            let phi_q: &[f64; 28] = phi_q
                .try_into()
                .map_err(|_| length_error(28, phi_q.len()))?;
            let x: &[f64; 9] = x.try_into().map_err(|_| length_error(9, x.len()))?;
            let out_len = out.len();
            let out: &mut [f64; 7] = out
                .try_into()
                .map_err(|_| length_error(7, out_len))?;
            out[0] = out[0] + phi_q[0] * x[1] + phi_q[1] * x[2] + phi_q[2] * x[3]
                + phi_q[3] * x[4];
            out[1] = out[1] + phi_q[4] * x[1] + phi_q[5] * x[2] + phi_q[6] * x[3]
                + phi_q[7] * x[4];
            out[2] = out[2] + phi_q[8] * x[1] + phi_q[9] * x[2] + phi_q[10] * x[3]
                + phi_q[11] * x[4];
            out[3] = out[3] + phi_q[12] * x[5] + phi_q[13] * x[6] + phi_q[14] * x[7]
                + phi_q[15] * x[8];
            out[4] = out[4] + phi_q[16] * x[5] + phi_q[17] * x[6] + phi_q[18] * x[7]
                + phi_q[19] * x[8];
            out[5] = out[5] + phi_q[20] * x[1] + phi_q[21] * x[2] + phi_q[22] * x[3]
                + phi_q[23] * x[4];
            out[6] = out[6] + phi_q[24] * x[5] + phi_q[25] * x[6] + phi_q[26] * x[7]
                + phi_q[27] * x[8];
            Ok(())
        }
        fn kkt_mass_times(
            mass: &[f64],
            v: &[f64],
            out: &mut [f64],
        ) -> Result<(), KktError> {
            let mass: &[f64; 33] = mass
                .try_into()
                .map_err(|_| length_error(33, mass.len()))?;
            let v: &[f64; 9] = v.try_into().map_err(|_| length_error(9, v.len()))?;
            let out_len = out.len();
            let out: &mut [f64; 9] = out
                .try_into()
                .map_err(|_| length_error(9, out_len))?;
            out[0] = 0.0 + mass[0] * v[0];
            out[1] = 0.0 + mass[1] * v[1] + mass[2] * v[2] + mass[3] * v[3]
                + mass[4] * v[4];
            out[2] = 0.0 + mass[5] * v[1] + mass[6] * v[2] + mass[7] * v[3]
                + mass[8] * v[4];
            out[3] = 0.0 + mass[9] * v[1] + mass[10] * v[2] + mass[11] * v[3]
                + mass[12] * v[4];
            out[4] = 0.0 + mass[13] * v[1] + mass[14] * v[2] + mass[15] * v[3]
                + mass[16] * v[4];
            out[5] = 0.0 + mass[17] * v[5] + mass[18] * v[6] + mass[19] * v[7]
                + mass[20] * v[8];
            out[6] = 0.0 + mass[21] * v[5] + mass[22] * v[6] + mass[23] * v[7]
                + mass[24] * v[8];
            out[7] = 0.0 + mass[25] * v[5] + mass[26] * v[6] + mass[27] * v[7]
                + mass[28] * v[8];
            out[8] = 0.0 + mass[29] * v[5] + mass[30] * v[6] + mass[31] * v[7]
                + mass[32] * v[8];
            Ok(())
        }
        fn kkt_kinetic_energy(mass: &[f64], qd: &[f64]) -> Result<f64, KktError> {
            let mass: &[f64; 33] = mass
                .try_into()
                .map_err(|_| length_error(33, mass.len()))?;
            let qd: &[f64; 9] = qd.try_into().map_err(|_| length_error(9, qd.len()))?;
            let mut t = 0.0;
            t += qd[0] * mass[0] * qd[0];
            t += qd[1] * mass[1] * qd[1];
            t += qd[1] * mass[2] * qd[2];
            t += qd[1] * mass[3] * qd[3];
            t += qd[1] * mass[4] * qd[4];
            t += qd[2] * mass[5] * qd[1];
            t += qd[2] * mass[6] * qd[2];
            t += qd[2] * mass[7] * qd[3];
            t += qd[2] * mass[8] * qd[4];
            t += qd[3] * mass[9] * qd[1];
            t += qd[3] * mass[10] * qd[2];
            t += qd[3] * mass[11] * qd[3];
            t += qd[3] * mass[12] * qd[4];
            t += qd[4] * mass[13] * qd[1];
            t += qd[4] * mass[14] * qd[2];
            t += qd[4] * mass[15] * qd[3];
            t += qd[4] * mass[16] * qd[4];
            t += qd[5] * mass[17] * qd[5];
            t += qd[5] * mass[18] * qd[6];
            t += qd[5] * mass[19] * qd[7];
            t += qd[5] * mass[20] * qd[8];
            t += qd[6] * mass[21] * qd[5];
            t += qd[6] * mass[22] * qd[6];
            t += qd[6] * mass[23] * qd[7];
            t += qd[6] * mass[24] * qd[8];
            t += qd[7] * mass[25] * qd[5];
            t += qd[7] * mass[26] * qd[6];
            t += qd[7] * mass[27] * qd[7];
            t += qd[7] * mass[28] * qd[8];
            t += qd[8] * mass[29] * qd[5];
            t += qd[8] * mass[30] * qd[6];
            t += qd[8] * mass[31] * qd[7];
            t += qd[8] * mass[32] * qd[8];
            Ok(0.5 * t)
        }
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
            let x3027 = q[2] * q[3];
            let x3029 = q[1] * q[4];
            let x3031 = q[2] * q[4];
            let x3033 = q[1] * q[3];
            let x3036 = q[1] * q[2];
            let x3041 = q[7] * q[7];
            let x3042 = q[8] * q[8];
            let x3044 = q[6] * q[7];
            let x3046 = q[5] * q[8];
            let x3050 = q[7] * q[8];
            let x3061 = 2.0 * q[7];
            let x3062 = 2.0 * q[8];
            let x3163 = q[6] * q[8];
            let x3165 = q[5] * q[7];
            let x3220 = 2.0 * x341;
            let x3221 = x341 * x3220;
            let x3222 = 0.01 * x3221;
            let x3223 = x656 + x3222;
            let x3224 = x584 + x3223;
            let x3225 = 0.5 * x3224;
            let x3226 = x332 * 0.04;
            let x3227 = x3225 + x3226;
            let x3228 = 2.0 * x339;
            let x3229 = x341 * x3228;
            let x3230 = 0.01 * x3229;
            let x3231 = x3230 - x647;
            let x3232 = x604 + x3231;
            let x3233 = 0.5 * x3232;
            let x3235 = 0.04 * x3036;
            let x3236 = x3235 - x3233;
            let x3237 = x341 * x576;
            let x3238 = 0.01 * x3237;
            let x3239 = x136 * x3228;
            let x3240 = 0.01 * x3239;
            let x3241 = x137 * x3220;
            let x3242 = 0.01 * x3241;
            let x3244 = x3238 + x3240;
            let x3245 = x3244 - x3242;
            let x3246 = 0.5 * x3245;
            let x3248 = 0.04 * x3033;
            let x3249 = x3248 - x3246;
            let x3250 = x341 * x602;
            let x3251 = 0.01 * x3250;
            let x3253 = x136 * x3220;
            let x3254 = 0.01 * x3253;
            let x3255 = x137 * x3228;
            let x3256 = 0.01 * x3255;
            let x3257 = x3254 - x3251;
            let x3258 = x3256 + x3257;
            let x3259 = 0.5 * x3258;
            let x3261 = 0.04 * x3029;
            let x3262 = x3261 - x3259;
            let x3263 = x339 * x3220;
            let x3264 = 0.01 * x3263;
            let x3266 = x604 - x3264;
            let x3267 = x3266 - x647;
            let x3268 = 0.5 * x3267;
            let x3269 = x3235 + x3268;
            let x3270 = x339 * x3228;
            let x3271 = 0.01 * x3270;
            let x3272 = x584 + x3271;
            let x3273 = x656 + x3272;
            let x3274 = 0.5 * x3273;
            let x3275 = x333 * 0.04;
            let x3276 = x3274 + x3275;
            let x3277 = x339 * x576;
            let x3278 = 0.01 * x3277;
            let x3281 = x3278 - x3256;
            let x3282 = x3281 - x3254;
            let x3283 = 0.5 * x3282;
            let x3284 = 0.04 * x3027;
            let x3285 = x3283 + x3284;
            let x3286 = x339 * x602;
            let x3287 = 0.01 * x3286;
            let x3288 = x3242 + x3287;
            let x3290 = x3240 - x3288;
            let x3291 = 0.5 * x3290;
            let x3292 = 0.04 * x3031;
            let x3293 = x3291 + x3292;
            let x3294 = x3238 - x3288;
            let x3295 = 0.5 * x3294;
            let x3296 = x3248 + x3295;
            let x3298 = x3256 - x3278;
            let x3299 = x3298 - x3251;
            let x3300 = 0.5 * x3299;
            let x3301 = x3284 + x3300;
            let x3302 = x3222 + x3272;
            let x3303 = 0.5 * x3302;
            let x3304 = x600 + x3303;
            let x3306 = x3264 - x604;
            let x3307 = x3306 - x3230;
            let x3308 = 0.5 * x3307;
            let x3309 = x615 + x3308;
            let x3310 = x3257 - x3278;
            let x3311 = 0.5 * x3310;
            let x3312 = x3261 + x3311;
            let x3314 = x3287 - x3244;
            let x3315 = 0.5 * x3314;
            let x3316 = x3292 + x3315;
            let x3317 = x3231 - x3264;
            let x3318 = 0.5 * x3317;
            let x3319 = x615 + x3318;
            let x3320 = x3223 + x3271;
            let x3321 = 0.5 * x3320;
            let x3322 = x660 + x3321;
            let x3323 = 2.0 * x3061;
            let x3324 = 2.0 * x3062;
            let x3325 = 0.1 * x590;
            let x3326 = x3061 * x3323;
            let x3328 = x3062 * x3324;
            let x3329 = 0.3 * x3328;
            let x3335 = 0.1 * x609;
            let x3336 = x3061 * x3324;
            let x3339 = x3062 * x3323;
            let x3340 = 0.3 * x3339;
            let x3347 = x139 * x3324;
            let x3348 = 0.1 * x3347;
            let x3349 = x578 * x3061;
            let x3351 = x580 * x3062;
            let x3352 = 0.3 * x3351;
            let x3360 = x139 * x3323;
            let x3361 = 0.1 * x3360;
            let x3363 = x580 * x3061;
            let x3365 = x578 * x3062;
            let x3366 = 0.3 * x3365;
            let x3373 = 0.1 * x605;
            let x3376 = 0.3 * x3336;
            let x3382 = 0.1 * x586;
            let x3384 = 0.3 * x3326;
            let x3390 = x138 * x3324;
            let x3391 = 0.1 * x3390;
            let x3394 = 0.3 * x3363;
            let x3401 = x138 * x3323;
            let x3402 = 0.1 * x3401;
            let x3404 = 0.3 * x3349;
            let x3411 = 0.1 * x3351;
            let x3413 = 0.3 * x3347;
            let x3419 = 0.1 * x3365;
            let x3422 = 0.3 * x3360;
            let x3428 = 0.1 * x3328;
            let x3430 = 0.3 * x590;
            let x3436 = 0.1 * x3339;
            let x3439 = 0.3 * x609;
            let x3446 = 0.1 * x3363;
            let x3449 = 0.3 * x3390;
            let x3455 = 0.1 * x3349;
            let x3457 = 0.3 * x3401;
            let x3463 = 0.1 * x3336;
            let x3466 = 0.3 * x605;
            let x3472 = 0.1 * x3326;
            let x3474 = 0.3 * x586;
            let x3837 = x3326 * k[8];
            let x3838 = x3325 + x3837;
            let x3839 = x3329 + x3838;
            let x3840 = 0.5 * x3839;
            let x3841 = x38 * k[14];
            let x3842 = x3840 + x3841;
            let x3843 = x3336 * k[8];
            let x3845 = x3335 - x3843;
            let x3846 = x3340 + x3845;
            let x3847 = 0.5 * x3846;
            let x3849 = x63 * k[14];
            let x3850 = x3849 - x3847;
            let x3851 = x3349 * k[8];
            let x3852 = x3348 + x3851;
            let x3853 = x3852 - x3352;
            let x3854 = 0.5 * x3853;
            let x3856 = x3165 * k[14];
            let x3857 = x3856 - x3854;
            let x3858 = x3363 * k[8];
            let x3859 = x3858 - x3361;
            let x3860 = x3366 + x3859;
            let x3861 = 0.5 * x3860;
            let x3863 = x3046 * k[14];
            let x3864 = x3863 - x3861;
            let x3865 = x3339 * k[8];
            let x3866 = x3865 - x3373;
            let x3867 = x3866 - x3376;
            let x3868 = 0.5 * x3867;
            let x3869 = x3849 + x3868;
            let x3870 = x3328 * k[8];
            let x3871 = x3382 + x3870;
            let x3872 = x3384 + x3871;
            let x3873 = 0.5 * x3872;
            let x3874 = x39 * k[14];
            let x3875 = x3873 + x3874;
            let x3876 = x3365 * k[8];
            let x3878 = x3391 - x3876;
            let x3879 = x3878 - x3394;
            let x3880 = 0.5 * x3879;
            let x3881 = x3044 * k[14];
            let x3882 = x3880 + x3881;
            let x3883 = x3351 * k[8];
            let x3884 = x3402 + x3883;
            let x3886 = x3404 - x3884;
            let x3887 = 0.5 * x3886;
            let x3888 = x3163 * k[14];
            let x3889 = x3887 + x3888;
            let x3890 = x3401 * k[8];
            let x3891 = x3411 + x3890;
            let x3893 = x3413 - x3891;
            let x3894 = 0.5 * x3893;
            let x3895 = x3856 + x3894;
            let x3896 = x3390 * k[8];
            let x3898 = x3419 - x3896;
            let x3899 = x3898 - x3422;
            let x3900 = 0.5 * x3899;
            let x3901 = x3881 + x3900;
            let x3902 = x586 * k[8];
            let x3903 = x3428 + x3902;
            let x3904 = x3430 + x3903;
            let x3905 = 0.5 * x3904;
            let x3906 = x3041 * k[14];
            let x3907 = x3905 + x3906;
            let x3908 = x605 * k[8];
            let x3909 = x3908 - x3436;
            let x3910 = x3909 - x3439;
            let x3911 = 0.5 * x3910;
            let x3912 = x3050 * k[14];
            let x3913 = x3911 + x3912;
            let x3914 = x3360 * k[8];
            let x3916 = x3446 - x3914;
            let x3917 = x3916 - x3449;
            let x3918 = 0.5 * x3917;
            let x3919 = x3863 + x3918;
            let x3920 = x3347 * k[8];
            let x3921 = x3455 + x3920;
            let x3923 = x3457 - x3921;
            let x3924 = 0.5 * x3923;
            let x3925 = x3888 + x3924;
            let x3926 = x609 * k[8];
            let x3927 = x3926 - x3463;
            let x3928 = x3927 - x3466;
            let x3929 = 0.5 * x3928;
            let x3930 = x3912 + x3929;
            let x3931 = x590 * k[8];
            let x3932 = x3472 + x3931;
            let x3933 = x3474 + x3932;
            let x3934 = 0.5 * x3933;
            let x3935 = x3042 * k[14];
            let x3936 = x3934 + x3935;
            out[0] = k[13];
            out[1] = x3227;
            out[2] = x3236;
            out[3] = x3249;
            out[4] = x3262;
            out[5] = x3269;
            out[6] = x3276;
            out[7] = x3285;
            out[8] = x3293;
            out[9] = x3296;
            out[10] = x3301;
            out[11] = x3304;
            out[12] = x3309;
            out[13] = x3312;
            out[14] = x3316;
            out[15] = x3319;
            out[16] = x3322;
            out[17] = x3842;
            out[18] = x3850;
            out[19] = x3857;
            out[20] = x3864;
            out[21] = x3869;
            out[22] = x3875;
            out[23] = x3882;
            out[24] = x3889;
            out[25] = x3895;
            out[26] = x3901;
            out[27] = x3907;
            out[28] = x3913;
            out[29] = x3919;
            out[30] = x3925;
            out[31] = x3930;
            out[32] = x3936;
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
            let x13 = symbody_runtime::trig::sin(t);
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
            let x3043 = x38 + x39;
            let x3061 = 2.0 * q[7];
            let x3062 = 2.0 * q[8];
            let x3066 = q[3] * qd[2];
            let x3067 = q[2] * qd[3];
            let x3070 = q[4] * qd[1];
            let x3071 = q[1] * qd[4];
            let x3074 = q[4] * qd[2];
            let x3075 = q[2] * qd[4];
            let x3078 = q[3] * qd[1];
            let x3079 = q[1] * qd[3];
            let x3083 = q[2] * qd[1];
            let x3084 = q[1] * qd[2];
            let x3092 = x166 + x167;
            let x3093 = q[7] * qd[6];
            let x3094 = q[6] * qd[7];
            let x3097 = q[8] * qd[5];
            let x3098 = q[5] * qd[8];
            let x3103 = q[8] * qd[7];
            let x3104 = q[7] * qd[8];
            let x3116 = qd[2] * qd[3];
            let x3119 = qd[1] * qd[4];
            let x3122 = qd[2] * qd[4];
            let x3125 = qd[1] * qd[3];
            let x3138 = qd[6] * qd[7];
            let x3141 = qd[5] * qd[8];
            let x3161 = 2.0 * x3043;
            let x3162 = x3161 - 1.0;
            let x3163 = q[6] * q[8];
            let x3164 = 2.0 * x3163;
            let x3165 = q[5] * q[7];
            let x3166 = 2.0 * x3165;
            let x3168 = x3164 - x3166;
            let x3169 = x331.sqrt();
            let x3170 = x3169 - 1.0;
            let x3173 = -x3168;
            let x3174 = x3173.atan2(x3162);
            let x3179 = 2.0 * x3169;
            let x3180 = 1.0 / x3179;
            let x3181 = x338 * x3180;
            let x3186 = 2.0 * x3092;
            let x3187 = q[8] * qd[6];
            let x3188 = q[6] * qd[8];
            let x3189 = x3187 + x3188;
            let x3190 = 2.0 * x3189;
            let x3191 = q[7] * qd[5];
            let x3192 = q[5] * qd[7];
            let x3193 = x3191 + x3192;
            let x3194 = 2.0 * x3193;
            let x3196 = x3190 - x3194;
            let x3197 = x3162 * x3162;
            let x3198 = x3168 * x3168;
            let x3199 = x3197 + x3198;
            let x3200 = x3162 * x3196;
            let x3202 = x3168 * x3186;
            let x3203 = x3202 - x3200;
            let x3204 = 1.0 / x3199;
            let x3205 = x3203 * x3204;
            let x3483 = x337 * x3180;
            let x3488 = x3061 * x3162;
            let x3489 = x578 * x3168;
            let x3490 = x3488 + x3489;
            let x3491 = x3204 * x3490;
            let x3492 = x3062 * x3162;
            let x3494 = x580 * x3168;
            let x3495 = x3494 - x3492;
            let x3496 = x3204 * x3495;
            let x3497 = x138 * x3162;
            let x3498 = x3204 * x3497;
            let x3499 = x139 * x3162;
            let x3500 = x3204 * x3499;
            let x3506 = x187 - x186;
            let x3521 = x3084 - x3083;
            let x3522 = x190 + x3521;
            let x3523 = x3522 - x191;
            let x3524 = 2.0 * x3523;
            let x3525 = x3074 + x3078;
            let x3527 = x3079 - x3525;
            let x3528 = x3075 + x3527;
            let x3529 = 2.0 * x3528;
            let x3532 = x3066 - x3070;
            let x3533 = x3532 - x3067;
            let x3534 = x3071 + x3533;
            let x3535 = 2.0 * x3534;
            let x3536 = 2.0 * x3524;
            let x3537 = 2.0 * x3529;
            let x3538 = 2.0 * x3535;
            let x3539 = x3122 + x3125;
            let x3541 = x3125 - x3539;
            let x3542 = x3122 + x3541;
            let x3543 = 2.0 * x3542;
            let x3546 = x3116 - x3119;
            let x3547 = x3546 - x3116;
            let x3548 = x3119 + x3547;
            let x3549 = 2.0 * x3548;
            let x3550 = 2.0 * x3543;
            let x3551 = 2.0 * x3549;
            let x3552 = x507 * x3536;
            let x3553 = 0.01 * x3552;
            let x3554 = x229 * x3537;
            let x3555 = x136 * x3550;
            let x3556 = x3554 + x3555;
            let x3557 = 0.01 * x3556;
            let x3558 = x230 * x3538;
            let x3559 = x137 * x3551;
            let x3560 = x3558 + x3559;
            let x3561 = 0.01 * x3560;
            let x3562 = x3553 + x3557;
            let x3563 = x3561 + x3562;
            let x3564 = 0.5 * x3563;
            let x3565 = x505 * x3536;
            let x3566 = 0.01 * x3565;
            let x3567 = x230 * x3537;
            let x3568 = x137 * x3550;
            let x3569 = x3567 + x3568;
            let x3570 = 0.01 * x3569;
            let x3572 = x229 * x3538;
            let x3573 = x136 * x3551;
            let x3574 = x3572 + x3573;
            let x3575 = 0.01 * x3574;
            let x3576 = x3566 - x3570;
            let x3577 = x3575 + x3576;
            let x3578 = 0.5 * x3577;
            let x3579 = x230 * x3536;
            let x3580 = 0.01 * x3579;
            let x3581 = x505 * x3537;
            let x3582 = x339 * x3550;
            let x3583 = x3581 + x3582;
            let x3584 = 0.01 * x3583;
            let x3585 = x507 * x3538;
            let x3586 = x341 * x3551;
            let x3587 = x3585 + x3586;
            let x3588 = 0.01 * x3587;
            let x3590 = x3580 + x3584;
            let x3591 = x3590 - x3588;
            let x3592 = 0.5 * x3591;
            let x3593 = x229 * x3536;
            let x3594 = 0.01 * x3593;
            let x3596 = x507 * x3537;
            let x3597 = x341 * x3550;
            let x3598 = x3596 + x3597;
            let x3599 = 0.01 * x3598;
            let x3600 = x505 * x3538;
            let x3601 = x339 * x3551;
            let x3602 = x3600 + x3601;
            let x3603 = 0.01 * x3602;
            let x3604 = x3599 - x3594;
            let x3605 = x3603 + x3604;
            let x3606 = 0.5 * x3605;
            let x3607 = x488 + x492;
            let x3608 = x789 + x3607;
            let x3609 = x790 + x3608;
            let x3610 = 0.01 * x3554;
            let x3611 = 0.01 * x3558;
            let x3612 = x3553 + x3610;
            let x3613 = x3611 + x3612;
            let x3614 = 0.5 * x3613;
            let x3615 = x3564 + x3614;
            let x3616 = q[1] * 0.04;
            let x3617 = x3609 * x3616;
            let x3619 = x3615 - x3617;
            let x3621 = 0.01 * x3567;
            let x3622 = 0.01 * x3572;
            let x3624 = x3621 - x3566;
            let x3625 = x3624 - x3622;
            let x3626 = 0.5 * x3625;
            let x3628 = x3626 - x3578;
            let x3629 = q[2] * 0.04;
            let x3630 = x3609 * x3629;
            let x3632 = x3628 - x3630;
            let x3633 = 0.01 * x3581;
            let x3634 = 0.01 * x3585;
            let x3635 = x3580 + x3633;
            let x3637 = x3634 - x3635;
            let x3638 = 0.5 * x3637;
            let x3640 = x3638 - x3592;
            let x3641 = x802 * x3609;
            let x3643 = x3640 - x3641;
            let x3644 = 0.01 * x3596;
            let x3646 = 0.01 * x3600;
            let x3648 = x3594 - x3644;
            let x3649 = x3648 - x3646;
            let x3650 = 0.5 * x3649;
            let x3652 = x3650 - x3606;
            let x3653 = x821 * x3609;
            let x3655 = x3652 - x3653;
            let x3657 = x3103 + x3506;
            let x3658 = x3657 - x3104;
            let x3659 = 2.0 * x3658;
            let x3660 = x3187 + x3191;
            let x3662 = x3192 - x3660;
            let x3663 = x3188 + x3662;
            let x3664 = 2.0 * x3663;
            let x3666 = x3093 - x3097;
            let x3667 = x3666 - x3094;
            let x3668 = x3098 + x3667;
            let x3669 = 2.0 * x3668;
            let x3670 = 2.0 * x3659;
            let x3671 = 2.0 * x3664;
            let x3672 = 2.0 * x3669;
            let x3673 = qd[6] * qd[8];
            let x3674 = qd[5] * qd[7];
            let x3676 = x3673 + x3674;
            let x3678 = x3674 - x3676;
            let x3679 = x3673 + x3678;
            let x3680 = 2.0 * x3679;
            let x3682 = x3138 - x3141;
            let x3683 = x3682 - x3138;
            let x3684 = x3141 + x3683;
            let x3685 = 2.0 * x3684;
            let x3686 = 2.0 * x3680;
            let x3687 = 2.0 * x3685;
            let x3688 = x232 * x3670;
            let x3689 = 0.1 * x3688;
            let x3690 = x891 * x3671;
            let x3691 = x3061 * x3686;
            let x3692 = x3690 + x3691;
            let x3694 = x893 * x3672;
            let x3695 = x3062 * x3687;
            let x3696 = x3694 + x3695;
            let x3697 = 0.3 * x3696;
            let x3701 = x231 * x3670;
            let x3702 = 0.1 * x3701;
            let x3703 = x893 * x3671;
            let x3704 = x3062 * x3686;
            let x3705 = x3703 + x3704;
            let x3708 = x891 * x3672;
            let x3709 = x3061 * x3687;
            let x3710 = x3708 + x3709;
            let x3711 = 0.3 * x3710;
            let x3715 = x893 * x3670;
            let x3716 = 0.1 * x3715;
            let x3717 = x231 * x3671;
            let x3718 = x138 * x3686;
            let x3719 = x3717 + x3718;
            let x3721 = x232 * x3672;
            let x3722 = x139 * x3687;
            let x3723 = x3721 + x3722;
            let x3724 = 0.3 * x3723;
            let x3729 = x891 * x3670;
            let x3730 = 0.1 * x3729;
            let x3732 = x232 * x3671;
            let x3733 = x139 * x3686;
            let x3734 = x3732 + x3733;
            let x3736 = x231 * x3672;
            let x3737 = x138 * x3687;
            let x3738 = x3736 + x3737;
            let x3739 = 0.3 * x3738;
            let x3743 = x791 + x792;
            let x3744 = x876 + x3743;
            let x3745 = x879 + x3744;
            let x3747 = 0.3 * x3694;
            let x3758 = 0.3 * x3708;
            let x3770 = 0.3 * x3721;
            let x3783 = 0.3 * x3736;
            let x3800 = t * k[1];
            let x3801 = symbody_runtime::trig::sin(x3800);
            let x3802 = k[0] * x3801;
            let x3806 = t * k[4];
            let x3807 = symbody_runtime::trig::cos(x3806);
            let x3808 = k[3] * x3807;
            let x3810 = x13 * k[5];
            let x3825 = x3181 * k[6];
            let x3827 = x3802 - x3825;
            let x3829 = x3205 * k[7];
            let x3831 = x3808 - x3829;
            let x3937 = x3170 * k[9];
            let x3939 = x3827 - x3937;
            let x3940 = x3483 * x3939;
            let x3941 = x3174 * k[10];
            let x3943 = x3831 - x3941;
            let x3944 = x3491 * x3943;
            let x3945 = x3496 * x3943;
            let x3946 = x3498 * x3943;
            let x3947 = x3500 * x3943;
            let x3948 = x3061 * x3810;
            let x3950 = x3062 * x3810;
            let x3951 = x138 * x3810;
            let x3952 = x139 * x3810;
            let x3953 = k[2] + x3940;
            let x3954 = x3944 - x3948;
            let x3955 = x3945 + x3950;
            let x3956 = x3946 + x3951;
            let x3957 = x3947 + x3952;
            let x3959 = x3692 * k[8];
            let x3960 = x3689 + x3959;
            let x3961 = x3697 + x3960;
            let x3962 = 0.5 * x3961;
            let x3963 = x3705 * k[8];
            let x3965 = x3702 - x3963;
            let x3966 = x3711 + x3965;
            let x3967 = 0.5 * x3966;
            let x3968 = x3719 * k[8];
            let x3969 = x3716 + x3968;
            let x3970 = x3969 - x3724;
            let x3971 = 0.5 * x3970;
            let x3972 = x3734 * k[8];
            let x3973 = x3972 - x3730;
            let x3974 = x3739 + x3973;
            let x3975 = 0.5 * x3974;
            let x3976 = x3690 * k[8];
            let x3977 = x3689 + x3976;
            let x3978 = x3747 + x3977;
            let x3979 = 0.5 * x3978;
            let x3980 = x3962 + x3979;
            let x3981 = q[5] * k[14];
            let x3982 = x3745 * x3981;
            let x3984 = x3980 - x3982;
            let x3985 = x3703 * k[8];
            let x3986 = x3985 - x3702;
            let x3987 = x3986 - x3758;
            let x3988 = 0.5 * x3987;
            let x3990 = x3988 - x3967;
            let x3991 = q[6] * k[14];
            let x3992 = x3745 * x3991;
            let x3994 = x3990 - x3992;
            let x3995 = x3717 * k[8];
            let x3996 = x3716 + x3995;
            let x3998 = x3770 - x3996;
            let x3999 = 0.5 * x3998;
            let x4001 = x3999 - x3971;
            let x4002 = q[7] * k[14];
            let x4003 = x3745 * x4002;
            let x4005 = x4001 - x4003;
            let x4006 = x3732 * k[8];
            let x4008 = x3730 - x4006;
            let x4009 = x4008 - x3783;
            let x4010 = 0.5 * x4009;
            let x4012 = x4010 - x3975;
            let x4013 = q[8] * k[14];
            let x4014 = x3745 * x4013;
            let x4016 = x4012 - x4014;
            let x4017 = x3954 + x3984;
            let x4018 = x3955 + x3994;
            let x4019 = x3956 + x4005;
            let x4020 = x4016 - x3957;
            out[0] = x3953;
            out[1] = x3619;
            out[2] = x3632;
            out[3] = x3643;
            out[4] = x3655;
            out[5] = x4017;
            out[6] = x4018;
            out[7] = x4019;
            out[8] = x4020;
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
            let x13 = symbody_runtime::trig::sin(t);
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
            let x3043 = x38 + x39;
            s[17] = x3043;
            let x3061 = 2.0 * q[7];
            s[18] = x3061;
            let x3062 = 2.0 * q[8];
            s[19] = x3062;
            let x3092 = x166 + x167;
            s[20] = x3092;
            let x3093 = q[7] * qd[6];
            s[21] = x3093;
            let x3094 = q[6] * qd[7];
            s[22] = x3094;
            let x3097 = q[8] * qd[5];
            s[23] = x3097;
            let x3098 = q[5] * qd[8];
            s[24] = x3098;
            let x3103 = q[8] * qd[7];
            s[25] = x3103;
            let x3104 = q[7] * qd[8];
            s[26] = x3104;
            let x3138 = qd[6] * qd[7];
            s[27] = x3138;
            let x3141 = qd[5] * qd[8];
            s[28] = x3141;
            let x3161 = 2.0 * x3043;
            s[29] = x3161;
            let x3162 = x3161 - 1.0;
            s[30] = x3162;
            let x3163 = q[6] * q[8];
            s[31] = x3163;
            let x3164 = 2.0 * x3163;
            s[32] = x3164;
            let x3165 = q[5] * q[7];
            s[33] = x3165;
            let x3166 = 2.0 * x3165;
            s[34] = x3166;
            let x3168 = x3164 - x3166;
            s[35] = x3168;
            let x3173 = -x3168;
            s[36] = x3173;
            let x3174 = x3173.atan2(x3162);
            s[37] = x3174;
            let x3186 = 2.0 * x3092;
            s[38] = x3186;
            let x3187 = q[8] * qd[6];
            s[39] = x3187;
            let x3188 = q[6] * qd[8];
            s[40] = x3188;
            let x3189 = x3187 + x3188;
            s[41] = x3189;
            let x3190 = 2.0 * x3189;
            s[42] = x3190;
            let x3191 = q[7] * qd[5];
            s[43] = x3191;
            let x3192 = q[5] * qd[7];
            s[44] = x3192;
            let x3193 = x3191 + x3192;
            s[45] = x3193;
            let x3194 = 2.0 * x3193;
            s[46] = x3194;
            let x3196 = x3190 - x3194;
            s[47] = x3196;
            let x3197 = x3162 * x3162;
            s[48] = x3197;
            let x3198 = x3168 * x3168;
            s[49] = x3198;
            let x3199 = x3197 + x3198;
            s[50] = x3199;
            let x3200 = x3162 * x3196;
            s[51] = x3200;
            let x3202 = x3168 * x3186;
            s[52] = x3202;
            let x3203 = x3202 - x3200;
            s[53] = x3203;
            let x3204 = 1.0 / x3199;
            s[54] = x3204;
            let x3205 = x3203 * x3204;
            s[55] = x3205;
            let x3506 = x187 - x186;
            s[56] = x3506;
            let x3657 = x3103 + x3506;
            s[57] = x3657;
            let x3658 = x3657 - x3104;
            s[58] = x3658;
            let x3659 = 2.0 * x3658;
            s[59] = x3659;
            let x3660 = x3187 + x3191;
            s[60] = x3660;
            let x3662 = x3192 - x3660;
            s[61] = x3662;
            let x3663 = x3188 + x3662;
            s[62] = x3663;
            let x3664 = 2.0 * x3663;
            s[63] = x3664;
            let x3666 = x3093 - x3097;
            s[64] = x3666;
            let x3667 = x3666 - x3094;
            s[65] = x3667;
            let x3668 = x3098 + x3667;
            s[66] = x3668;
            let x3669 = 2.0 * x3668;
            s[67] = x3669;
            let x3670 = 2.0 * x3659;
            s[68] = x3670;
            let x3671 = 2.0 * x3664;
            s[69] = x3671;
            let x3672 = 2.0 * x3669;
            s[70] = x3672;
            let x3673 = qd[6] * qd[8];
            s[71] = x3673;
            let x3674 = qd[5] * qd[7];
            s[72] = x3674;
            let x3676 = x3673 + x3674;
            s[73] = x3676;
            let x3678 = x3674 - x3676;
            s[74] = x3678;
            let x3679 = x3673 + x3678;
            s[75] = x3679;
            let x3680 = 2.0 * x3679;
            s[76] = x3680;
            let x3682 = x3138 - x3141;
            s[77] = x3682;
            let x3683 = x3682 - x3138;
            s[78] = x3683;
            let x3684 = x3141 + x3683;
            s[79] = x3684;
            let x3685 = 2.0 * x3684;
            s[80] = x3685;
            let x3686 = 2.0 * x3680;
            s[81] = x3686;
            let x3687 = 2.0 * x3685;
            s[82] = x3687;
            let x3743 = x791 + x792;
            s[83] = x3743;
            let x3744 = x876 + x3743;
            s[84] = x3744;
            let x3745 = x879 + x3744;
            s[85] = x3745;
            let x3806 = t * k[4];
            s[86] = x3806;
            let x3807 = symbody_runtime::trig::cos(x3806);
            s[87] = x3807;
            let x3808 = k[3] * x3807;
            s[88] = x3808;
            let x3810 = x13 * k[5];
            s[89] = x3810;
            let x3829 = x3205 * k[7];
            s[90] = x3829;
            let x3831 = x3808 - x3829;
            s[91] = x3831;
            let x3941 = x3174 * k[10];
            s[92] = x3941;
            let x3943 = x3831 - x3941;
            s[93] = x3943;
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
            let x3026 = x332 + x333;
            let x3027 = q[2] * q[3];
            let x3028 = 2.0 * x3027;
            let x3029 = q[1] * q[4];
            let x3030 = 2.0 * x3029;
            let x3031 = q[2] * q[4];
            let x3032 = 2.0 * x3031;
            let x3033 = q[1] * q[3];
            let x3034 = 2.0 * x3033;
            let x3035 = x3028 + x3030;
            let x3036 = q[1] * q[2];
            let x3037 = 2.0 * x3036;
            let x3039 = x3032 - x3034;
            let x3040 = x67 + x3037;
            let x3041 = q[7] * q[7];
            let x3042 = q[8] * q[8];
            let x3044 = q[6] * q[7];
            let x3045 = 2.0 * x3044;
            let x3046 = q[5] * q[8];
            let x3047 = 2.0 * x3046;
            let x3049 = x3045 - x3047;
            let x3050 = q[7] * q[8];
            let x3051 = 2.0 * x3050;
            let x3052 = x64 + x3051;
            let x3053 = -x3052;
            let x3054 = x36 + x3026;
            let x3055 = x37 + x3054;
            let x3056 = x3055 - 1.0;
            let x3057 = x3041 + s[17];
            let x3058 = x3042 + x3057;
            let x3059 = x3058 - 1.0;
            let x3060 = -x339;
            let x3063 = -s[19];
            let x3064 = -s[18];
            let x3066 = q[3] * qd[2];
            let x3067 = q[2] * qd[3];
            let x3070 = q[4] * qd[1];
            let x3071 = q[1] * qd[4];
            let x3074 = q[4] * qd[2];
            let x3075 = q[2] * qd[4];
            let x3078 = q[3] * qd[1];
            let x3079 = q[1] * qd[3];
            let x3083 = q[2] * qd[1];
            let x3084 = q[1] * qd[2];
            let x3116 = qd[2] * qd[3];
            let x3119 = qd[1] * qd[4];
            let x3122 = qd[2] * qd[4];
            let x3125 = qd[1] * qd[3];
            let x3169 = x331.sqrt();
            let x3170 = x3169 - 1.0;
            let x3179 = 2.0 * x3169;
            let x3180 = 1.0 / x3179;
            let x3181 = x338 * x3180;
            let x3220 = 2.0 * x341;
            let x3221 = x341 * x3220;
            let x3222 = 0.01 * x3221;
            let x3223 = x656 + x3222;
            let x3224 = x584 + x3223;
            let x3225 = 0.5 * x3224;
            let x3226 = x332 * 0.04;
            let x3227 = x3225 + x3226;
            let x3228 = 2.0 * x339;
            let x3229 = x341 * x3228;
            let x3230 = 0.01 * x3229;
            let x3231 = x3230 - x647;
            let x3232 = x604 + x3231;
            let x3233 = 0.5 * x3232;
            let x3235 = 0.04 * x3036;
            let x3236 = x3235 - x3233;
            let x3237 = x341 * x576;
            let x3238 = 0.01 * x3237;
            let x3239 = x136 * x3228;
            let x3240 = 0.01 * x3239;
            let x3241 = x137 * x3220;
            let x3242 = 0.01 * x3241;
            let x3244 = x3238 + x3240;
            let x3245 = x3244 - x3242;
            let x3246 = 0.5 * x3245;
            let x3248 = 0.04 * x3033;
            let x3249 = x3248 - x3246;
            let x3250 = x341 * x602;
            let x3251 = 0.01 * x3250;
            let x3253 = x136 * x3220;
            let x3254 = 0.01 * x3253;
            let x3255 = x137 * x3228;
            let x3256 = 0.01 * x3255;
            let x3257 = x3254 - x3251;
            let x3258 = x3256 + x3257;
            let x3259 = 0.5 * x3258;
            let x3261 = 0.04 * x3029;
            let x3262 = x3261 - x3259;
            let x3263 = x339 * x3220;
            let x3264 = 0.01 * x3263;
            let x3266 = x604 - x3264;
            let x3267 = x3266 - x647;
            let x3268 = 0.5 * x3267;
            let x3269 = x3235 + x3268;
            let x3270 = x339 * x3228;
            let x3271 = 0.01 * x3270;
            let x3272 = x584 + x3271;
            let x3273 = x656 + x3272;
            let x3274 = 0.5 * x3273;
            let x3275 = x333 * 0.04;
            let x3276 = x3274 + x3275;
            let x3277 = x339 * x576;
            let x3278 = 0.01 * x3277;
            let x3281 = x3278 - x3256;
            let x3282 = x3281 - x3254;
            let x3283 = 0.5 * x3282;
            let x3284 = 0.04 * x3027;
            let x3285 = x3283 + x3284;
            let x3286 = x339 * x602;
            let x3287 = 0.01 * x3286;
            let x3288 = x3242 + x3287;
            let x3290 = x3240 - x3288;
            let x3291 = 0.5 * x3290;
            let x3292 = 0.04 * x3031;
            let x3293 = x3291 + x3292;
            let x3294 = x3238 - x3288;
            let x3295 = 0.5 * x3294;
            let x3296 = x3248 + x3295;
            let x3298 = x3256 - x3278;
            let x3299 = x3298 - x3251;
            let x3300 = 0.5 * x3299;
            let x3301 = x3284 + x3300;
            let x3302 = x3222 + x3272;
            let x3303 = 0.5 * x3302;
            let x3304 = x600 + x3303;
            let x3306 = x3264 - x604;
            let x3307 = x3306 - x3230;
            let x3308 = 0.5 * x3307;
            let x3309 = x615 + x3308;
            let x3310 = x3257 - x3278;
            let x3311 = 0.5 * x3310;
            let x3312 = x3261 + x3311;
            let x3314 = x3287 - x3244;
            let x3315 = 0.5 * x3314;
            let x3316 = x3292 + x3315;
            let x3317 = x3231 - x3264;
            let x3318 = 0.5 * x3317;
            let x3319 = x615 + x3318;
            let x3320 = x3223 + x3271;
            let x3321 = 0.5 * x3320;
            let x3322 = x660 + x3321;
            let x3323 = 2.0 * s[18];
            let x3324 = 2.0 * s[19];
            let x3325 = 0.1 * x590;
            let x3326 = s[18] * x3323;
            let x3328 = s[19] * x3324;
            let x3329 = 0.3 * x3328;
            let x3335 = 0.1 * x609;
            let x3336 = s[18] * x3324;
            let x3339 = s[19] * x3323;
            let x3340 = 0.3 * x3339;
            let x3347 = s[4] * x3324;
            let x3348 = 0.1 * x3347;
            let x3349 = x578 * s[18];
            let x3351 = s[10] * s[19];
            let x3352 = 0.3 * x3351;
            let x3360 = s[4] * x3323;
            let x3361 = 0.1 * x3360;
            let x3363 = s[10] * s[18];
            let x3365 = x578 * s[19];
            let x3366 = 0.3 * x3365;
            let x3373 = 0.1 * x605;
            let x3376 = 0.3 * x3336;
            let x3382 = 0.1 * x586;
            let x3384 = 0.3 * x3326;
            let x3390 = s[3] * x3324;
            let x3391 = 0.1 * x3390;
            let x3394 = 0.3 * x3363;
            let x3401 = s[3] * x3323;
            let x3402 = 0.1 * x3401;
            let x3404 = 0.3 * x3349;
            let x3411 = 0.1 * x3351;
            let x3413 = 0.3 * x3347;
            let x3419 = 0.1 * x3365;
            let x3422 = 0.3 * x3360;
            let x3428 = 0.1 * x3328;
            let x3430 = 0.3 * x590;
            let x3436 = 0.1 * x3339;
            let x3439 = 0.3 * x609;
            let x3446 = 0.1 * x3363;
            let x3449 = 0.3 * x3390;
            let x3455 = 0.1 * x3349;
            let x3457 = 0.3 * x3401;
            let x3463 = 0.1 * x3336;
            let x3466 = 0.3 * x605;
            let x3472 = 0.1 * x3326;
            let x3474 = 0.3 * x586;
            let x3483 = x337 * x3180;
            let x3488 = s[18] * s[30];
            let x3489 = x578 * s[35];
            let x3490 = x3488 + x3489;
            let x3491 = s[54] * x3490;
            let x3521 = x3084 - x3083;
            let x3522 = x190 + x3521;
            let x3523 = x3522 - x191;
            let x3524 = 2.0 * x3523;
            let x3525 = x3074 + x3078;
            let x3527 = x3079 - x3525;
            let x3528 = x3075 + x3527;
            let x3529 = 2.0 * x3528;
            let x3532 = x3066 - x3070;
            let x3533 = x3532 - x3067;
            let x3534 = x3071 + x3533;
            let x3535 = 2.0 * x3534;
            let x3536 = 2.0 * x3524;
            let x3537 = 2.0 * x3529;
            let x3538 = 2.0 * x3535;
            let x3539 = x3122 + x3125;
            let x3541 = x3125 - x3539;
            let x3542 = x3122 + x3541;
            let x3543 = 2.0 * x3542;
            let x3546 = x3116 - x3119;
            let x3547 = x3546 - x3116;
            let x3548 = x3119 + x3547;
            let x3549 = 2.0 * x3548;
            let x3550 = 2.0 * x3543;
            let x3551 = 2.0 * x3549;
            let x3552 = x507 * x3536;
            let x3553 = 0.01 * x3552;
            let x3554 = x229 * x3537;
            let x3555 = x136 * x3550;
            let x3556 = x3554 + x3555;
            let x3557 = 0.01 * x3556;
            let x3558 = x230 * x3538;
            let x3559 = x137 * x3551;
            let x3560 = x3558 + x3559;
            let x3561 = 0.01 * x3560;
            let x3562 = x3553 + x3557;
            let x3563 = x3561 + x3562;
            let x3564 = 0.5 * x3563;
            let x3565 = x505 * x3536;
            let x3566 = 0.01 * x3565;
            let x3567 = x230 * x3537;
            let x3568 = x137 * x3550;
            let x3569 = x3567 + x3568;
            let x3570 = 0.01 * x3569;
            let x3572 = x229 * x3538;
            let x3573 = x136 * x3551;
            let x3574 = x3572 + x3573;
            let x3575 = 0.01 * x3574;
            let x3576 = x3566 - x3570;
            let x3577 = x3575 + x3576;
            let x3578 = 0.5 * x3577;
            let x3579 = x230 * x3536;
            let x3580 = 0.01 * x3579;
            let x3581 = x505 * x3537;
            let x3582 = x339 * x3550;
            let x3583 = x3581 + x3582;
            let x3584 = 0.01 * x3583;
            let x3585 = x507 * x3538;
            let x3586 = x341 * x3551;
            let x3587 = x3585 + x3586;
            let x3588 = 0.01 * x3587;
            let x3590 = x3580 + x3584;
            let x3591 = x3590 - x3588;
            let x3592 = 0.5 * x3591;
            let x3593 = x229 * x3536;
            let x3594 = 0.01 * x3593;
            let x3596 = x507 * x3537;
            let x3597 = x341 * x3550;
            let x3598 = x3596 + x3597;
            let x3599 = 0.01 * x3598;
            let x3600 = x505 * x3538;
            let x3601 = x339 * x3551;
            let x3602 = x3600 + x3601;
            let x3603 = 0.01 * x3602;
            let x3604 = x3599 - x3594;
            let x3605 = x3603 + x3604;
            let x3606 = 0.5 * x3605;
            let x3607 = x488 + x492;
            let x3608 = x789 + x3607;
            let x3609 = x790 + x3608;
            let x3610 = 0.01 * x3554;
            let x3611 = 0.01 * x3558;
            let x3612 = x3553 + x3610;
            let x3613 = x3611 + x3612;
            let x3614 = 0.5 * x3613;
            let x3615 = x3564 + x3614;
            let x3616 = q[1] * 0.04;
            let x3617 = x3609 * x3616;
            let x3619 = x3615 - x3617;
            let x3621 = 0.01 * x3567;
            let x3622 = 0.01 * x3572;
            let x3624 = x3621 - x3566;
            let x3625 = x3624 - x3622;
            let x3626 = 0.5 * x3625;
            let x3628 = x3626 - x3578;
            let x3629 = q[2] * 0.04;
            let x3630 = x3609 * x3629;
            let x3632 = x3628 - x3630;
            let x3633 = 0.01 * x3581;
            let x3634 = 0.01 * x3585;
            let x3635 = x3580 + x3633;
            let x3637 = x3634 - x3635;
            let x3638 = 0.5 * x3637;
            let x3640 = x3638 - x3592;
            let x3641 = x802 * x3609;
            let x3643 = x3640 - x3641;
            let x3644 = 0.01 * x3596;
            let x3646 = 0.01 * x3600;
            let x3648 = x3594 - x3644;
            let x3649 = x3648 - x3646;
            let x3650 = 0.5 * x3649;
            let x3652 = x3650 - x3606;
            let x3653 = x821 * x3609;
            let x3655 = x3652 - x3653;
            let x3688 = s[9] * s[68];
            let x3689 = 0.1 * x3688;
            let x3690 = s[15] * s[69];
            let x3691 = s[18] * s[81];
            let x3692 = x3690 + x3691;
            let x3694 = s[16] * s[70];
            let x3695 = s[19] * s[82];
            let x3696 = x3694 + x3695;
            let x3697 = 0.3 * x3696;
            let x3747 = 0.3 * x3694;
            let x3800 = t * k[1];
            let x3801 = symbody_runtime::trig::sin(x3800);
            let x3802 = k[0] * x3801;
            let x3825 = x3181 * k[6];
            let x3827 = x3802 - x3825;
            let x3837 = x3326 * k[8];
            let x3838 = x3325 + x3837;
            let x3839 = x3329 + x3838;
            let x3840 = 0.5 * x3839;
            let x3841 = s[1] * k[14];
            let x3842 = x3840 + x3841;
            let x3843 = x3336 * k[8];
            let x3845 = x3335 - x3843;
            let x3846 = x3340 + x3845;
            let x3847 = 0.5 * x3846;
            let x3849 = x63 * k[14];
            let x3850 = x3849 - x3847;
            let x3851 = x3349 * k[8];
            let x3852 = x3348 + x3851;
            let x3853 = x3852 - x3352;
            let x3854 = 0.5 * x3853;
            let x3856 = s[33] * k[14];
            let x3857 = x3856 - x3854;
            let x3858 = x3363 * k[8];
            let x3859 = x3858 - x3361;
            let x3860 = x3366 + x3859;
            let x3861 = 0.5 * x3860;
            let x3863 = x3046 * k[14];
            let x3864 = x3863 - x3861;
            let x3865 = x3339 * k[8];
            let x3866 = x3865 - x3373;
            let x3867 = x3866 - x3376;
            let x3868 = 0.5 * x3867;
            let x3869 = x3849 + x3868;
            let x3870 = x3328 * k[8];
            let x3871 = x3382 + x3870;
            let x3872 = x3384 + x3871;
            let x3873 = 0.5 * x3872;
            let x3874 = s[2] * k[14];
            let x3875 = x3873 + x3874;
            let x3876 = x3365 * k[8];
            let x3878 = x3391 - x3876;
            let x3879 = x3878 - x3394;
            let x3880 = 0.5 * x3879;
            let x3881 = x3044 * k[14];
            let x3882 = x3880 + x3881;
            let x3883 = x3351 * k[8];
            let x3884 = x3402 + x3883;
            let x3886 = x3404 - x3884;
            let x3887 = 0.5 * x3886;
            let x3888 = s[31] * k[14];
            let x3889 = x3887 + x3888;
            let x3890 = x3401 * k[8];
            let x3891 = x3411 + x3890;
            let x3893 = x3413 - x3891;
            let x3894 = 0.5 * x3893;
            let x3895 = x3856 + x3894;
            let x3896 = x3390 * k[8];
            let x3898 = x3419 - x3896;
            let x3899 = x3898 - x3422;
            let x3900 = 0.5 * x3899;
            let x3901 = x3881 + x3900;
            let x3902 = x586 * k[8];
            let x3903 = x3428 + x3902;
            let x3904 = x3430 + x3903;
            let x3905 = 0.5 * x3904;
            let x3906 = x3041 * k[14];
            let x3907 = x3905 + x3906;
            let x3908 = x605 * k[8];
            let x3909 = x3908 - x3436;
            let x3910 = x3909 - x3439;
            let x3911 = 0.5 * x3910;
            let x3912 = x3050 * k[14];
            let x3913 = x3911 + x3912;
            let x3914 = x3360 * k[8];
            let x3916 = x3446 - x3914;
            let x3917 = x3916 - x3449;
            let x3918 = 0.5 * x3917;
            let x3919 = x3863 + x3918;
            let x3920 = x3347 * k[8];
            let x3921 = x3455 + x3920;
            let x3923 = x3457 - x3921;
            let x3924 = 0.5 * x3923;
            let x3925 = x3888 + x3924;
            let x3926 = x609 * k[8];
            let x3927 = x3926 - x3463;
            let x3928 = x3927 - x3466;
            let x3929 = 0.5 * x3928;
            let x3930 = x3912 + x3929;
            let x3931 = x590 * k[8];
            let x3932 = x3472 + x3931;
            let x3933 = x3474 + x3932;
            let x3934 = 0.5 * x3933;
            let x3935 = x3042 * k[14];
            let x3936 = x3934 + x3935;
            let x3937 = x3170 * k[9];
            let x3939 = x3827 - x3937;
            let x3940 = x3483 * x3939;
            let x3944 = x3491 * s[93];
            let x3948 = s[18] * s[89];
            let x3953 = k[2] + x3940;
            let x3954 = x3944 - x3948;
            let x3959 = x3692 * k[8];
            let x3960 = x3689 + x3959;
            let x3961 = x3697 + x3960;
            let x3962 = 0.5 * x3961;
            let x3976 = x3690 * k[8];
            let x3977 = x3689 + x3976;
            let x3978 = x3747 + x3977;
            let x3979 = 0.5 * x3978;
            let x3980 = x3962 + x3979;
            let x3981 = q[5] * k[14];
            let x3982 = s[85] * x3981;
            let x3984 = x3980 - x3982;
            let x4017 = x3954 + x3984;
            phi[0] = x3035;
            phi_q[0] = x137;
            phi_q[1] = x136;
            phi_q[2] = x341;
            phi_q[3] = x339;
            phi[1] = x3039;
            phi_q[4] = x141;
            phi_q[5] = x137;
            phi_q[6] = x3060;
            phi_q[7] = x341;
            phi[2] = x3040;
            phi_q[8] = x341;
            phi_q[9] = x339;
            phi_q[10] = x137;
            phi_q[11] = x136;
            phi[3] = x3049;
            phi_q[12] = x3063;
            phi_q[13] = s[18];
            phi_q[14] = s[4];
            phi_q[15] = x140;
            phi[4] = x3053;
            phi_q[16] = x518;
            phi_q[17] = x140;
            phi_q[18] = x3063;
            phi_q[19] = x3064;
            phi[5] = x3056;
            phi_q[20] = x339;
            phi_q[21] = x341;
            phi_q[22] = x136;
            phi_q[23] = x137;
            phi[6] = x3059;
            phi_q[24] = s[3];
            phi_q[25] = s[4];
            phi_q[26] = s[18];
            phi_q[27] = s[19];
            mass[0] = k[13];
            mass[1] = x3227;
            mass[2] = x3236;
            mass[3] = x3249;
            mass[4] = x3262;
            mass[5] = x3269;
            mass[6] = x3276;
            mass[7] = x3285;
            mass[8] = x3293;
            mass[9] = x3296;
            mass[10] = x3301;
            mass[11] = x3304;
            mass[12] = x3309;
            mass[13] = x3312;
            mass[14] = x3316;
            mass[15] = x3319;
            mass[16] = x3322;
            mass[17] = x3842;
            mass[18] = x3850;
            mass[19] = x3857;
            mass[20] = x3864;
            mass[21] = x3869;
            mass[22] = x3875;
            mass[23] = x3882;
            mass[24] = x3889;
            mass[25] = x3895;
            mass[26] = x3901;
            mass[27] = x3907;
            mass[28] = x3913;
            mass[29] = x3919;
            mass[30] = x3925;
            mass[31] = x3930;
            mass[32] = x3936;
            force[0] = x3953;
            force[1] = x3619;
            force[2] = x3632;
            force[3] = x3643;
            force[4] = x3655;
            force[5] = x4017;
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
            let x3492 = s[19] * s[30];
            let x3494 = s[10] * s[35];
            let x3495 = x3494 - x3492;
            let x3496 = s[54] * x3495;
            let x3497 = s[3] * s[30];
            let x3498 = s[54] * x3497;
            let x3499 = s[4] * s[30];
            let x3500 = s[54] * x3499;
            let x3701 = x231 * s[68];
            let x3702 = 0.1 * x3701;
            let x3703 = s[16] * s[69];
            let x3704 = s[19] * s[81];
            let x3705 = x3703 + x3704;
            let x3708 = s[15] * s[70];
            let x3709 = s[18] * s[82];
            let x3710 = x3708 + x3709;
            let x3711 = 0.3 * x3710;
            let x3715 = s[16] * s[68];
            let x3716 = 0.1 * x3715;
            let x3717 = x231 * s[69];
            let x3718 = s[3] * s[81];
            let x3719 = x3717 + x3718;
            let x3721 = s[9] * s[70];
            let x3722 = s[4] * s[82];
            let x3723 = x3721 + x3722;
            let x3724 = 0.3 * x3723;
            let x3729 = s[15] * s[68];
            let x3730 = 0.1 * x3729;
            let x3732 = s[9] * s[69];
            let x3733 = s[4] * s[81];
            let x3734 = x3732 + x3733;
            let x3736 = x231 * s[70];
            let x3737 = s[3] * s[82];
            let x3738 = x3736 + x3737;
            let x3739 = 0.3 * x3738;
            let x3758 = 0.3 * x3708;
            let x3770 = 0.3 * x3721;
            let x3783 = 0.3 * x3736;
            let x3945 = x3496 * s[93];
            let x3946 = x3498 * s[93];
            let x3947 = x3500 * s[93];
            let x3950 = s[19] * s[89];
            let x3951 = s[3] * s[89];
            let x3952 = s[4] * s[89];
            let x3955 = x3945 + x3950;
            let x3956 = x3946 + x3951;
            let x3957 = x3947 + x3952;
            let x3963 = x3705 * k[8];
            let x3965 = x3702 - x3963;
            let x3966 = x3711 + x3965;
            let x3967 = 0.5 * x3966;
            let x3968 = x3719 * k[8];
            let x3969 = x3716 + x3968;
            let x3970 = x3969 - x3724;
            let x3971 = 0.5 * x3970;
            let x3972 = x3734 * k[8];
            let x3973 = x3972 - x3730;
            let x3974 = x3739 + x3973;
            let x3975 = 0.5 * x3974;
            let x3985 = x3703 * k[8];
            let x3986 = x3985 - x3702;
            let x3987 = x3986 - x3758;
            let x3988 = 0.5 * x3987;
            let x3990 = x3988 - x3967;
            let x3991 = q[6] * k[14];
            let x3992 = s[85] * x3991;
            let x3994 = x3990 - x3992;
            let x3995 = x3717 * k[8];
            let x3996 = x3716 + x3995;
            let x3998 = x3770 - x3996;
            let x3999 = 0.5 * x3998;
            let x4001 = x3999 - x3971;
            let x4002 = q[7] * k[14];
            let x4003 = s[85] * x4002;
            let x4005 = x4001 - x4003;
            let x4006 = x3732 * k[8];
            let x4008 = x3730 - x4006;
            let x4009 = x4008 - x3783;
            let x4010 = 0.5 * x4009;
            let x4012 = x4010 - x3975;
            let x4013 = q[8] * k[14];
            let x4014 = s[85] * x4013;
            let x4016 = x4012 - x4014;
            let x4018 = x3955 + x3994;
            let x4019 = x3956 + x4005;
            let x4020 = x4016 - x3957;
            force[6] = x4018;
            force[7] = x4019;
            force[8] = x4020;
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
    fn run_time_values(&self) -> &[f64] {
        &P0
    }
    fn tangents(
        &self,
        q: &[f64],
        qd: &[f64],
        t: f64,
        dir: Direction<'_>,
        out: TangentOutputs<'_>,
    ) -> bool {
        kinematic_tangents(
            &K,
            q,
            qd,
            t,
            dir.dq,
            dir.dqd,
            dir.dp,
            out.phi,
            out.phi_q,
            out.phi_t,
            out.gamma,
        );
        exact::tangents(&K, q, qd, t, dir.dq, dir.dqd, dir.dp, out.mass, out.force);
        true
    }
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
    fn run_time_values(&self) -> &[f64] {
        self.0.values()
    }
    fn tangents(
        &self,
        q: &[f64],
        qd: &[f64],
        t: f64,
        dir: Direction<'_>,
        out: TangentOutputs<'_>,
    ) -> bool {
        kinematic_tangents(
            &self.0.k,
            q,
            qd,
            t,
            dir.dq,
            dir.dqd,
            dir.dp,
            out.phi,
            out.phi_q,
            out.phi_t,
            out.gamma,
        );
        exact::tangents(
            &self.0.k,
            q,
            qd,
            t,
            dir.dq,
            dir.dqd,
            dir.dp,
            out.mass,
            out.force,
        );
        true
    }
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
