//! Generated equations of `dietmaier_6_6` (Dietmaier's general 6-6 Stewart-Gough platform (40 real assembly modes)). Do not edit.
//!
//! Regenerate with `cargo xtask generate dietmaier_6_6` from `mechanisms/dietmaier_6_6.toml`.
//!
//! 7 coordinates, 7 constraints, 42 structural nonzeros in Φq.
//! Rank 7 at the initial pose; mobility 6 (Grübler count 6), 0 DOF left with drivers.
//! Each body owns `[X, Y, Z]` (centre of mass), then `[θ, β, γ]` (A = Rz(γ)·Ry(β)·Rx(θ))
//! or Euler parameters `[e0, e1, e2, e3]`. Equations of motion: `M q̈ + Φqᵀλ = Q`, `Φq q̈ = γ`.
//! Sparse outputs hold the pattern's nonzeros in order (row-major, columns ascending).
//!
//! Coordinates:
//! - `0..7` platform (quaternion)
//!
//! Constraint rows:
//! - `0` leg1 (driver): point distance − f, f = l1, initial = 1.000000000
//! - `1` leg2 (driver): point distance − f, f = l2, initial = 0.645275000
//! - `2` leg3 (driver): point distance − f, f = l3, initial = 1.086284000
//! - `3` leg4 (driver): point distance − f, f = l4, initial = 1.503439000
//! - `4` leg5 (driver): point distance − f, f = l5, initial = 1.281933000
//! - `5` leg6 (driver): point distance − f, f = l6, initial = 0.771071000
//! - `6` platform.norm: eᵀe − 1
#![allow(
    clippy::approx_constant,
    clippy::excessive_precision,
    clippy::too_many_arguments,
    clippy::unreadable_literal
)]
use symbody_runtime::{
    BodyInfo, Direction, Entry, Formulation, JointInfo, JointKind, KinematicOutputs,
    LegInfo, Mechanism, MechanismInfo, NewtonOutputs, Origin, PlatformInfo, Rotation,
    TangentOutputs,
};
use symbody_runtime::parameters::{ParameterError, RunTimeParameters};
/// Constraint residual Φ(q, t).
pub fn phi(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
    let _ = t;
    phi_part_0(k, q, out);
}
#[inline(never)]
fn phi_part_0(k: &[f64; 6], q: &[f64; 7], out: &mut [f64; 7]) {
    let x20 = q[3] * q[3];
    let x21 = q[4] * q[4];
    let x22 = q[5] * q[5];
    let x23 = q[6] * q[6];
    let x24 = x20 + x21;
    let x25 = 2.0 * x24;
    let x27 = x25 - 1.0;
    let x28 = x20 + x22;
    let x29 = 2.0 * x28;
    let x30 = x29 - 1.0;
    let x31 = x20 + x23;
    let x32 = 2.0 * x31;
    let x33 = x32 - 1.0;
    let x34 = q[4] * q[5];
    let x35 = 2.0 * x34;
    let x36 = q[3] * q[6];
    let x38 = 2.0 * x36;
    let x40 = x35 - x38;
    let x41 = q[4] * q[6];
    let x42 = 2.0 * x41;
    let x43 = q[3] * q[5];
    let x44 = 2.0 * x43;
    let x45 = x42 + x44;
    let x46 = x35 + x38;
    let x47 = q[5] * q[6];
    let x48 = 2.0 * x47;
    let x49 = q[3] * q[4];
    let x51 = 2.0 * x49;
    let x53 = x48 - x51;
    let x56 = x42 - x44;
    let x57 = x48 + x51;
    let x59 = q[0] * q[0];
    let x60 = q[1] * q[1];
    let x61 = q[2] * q[2];
    let x62 = x59 + x60;
    let x63 = x61 + x62;
    let x64 = x63.sqrt();
    let x69 = x27 * 0.542805;
    let x70 = x46 * 0.542805;
    let x71 = x56 * 0.542805;
    let x72 = q[0] + x69;
    let x73 = q[1] + x70;
    let x74 = q[2] + x71;
    let x76 = x72 - 1.107915;
    let x77 = x76 * x76;
    let x78 = x73 * x73;
    let x79 = x74 * x74;
    let x80 = x77 + x78;
    let x81 = x79 + x80;
    let x82 = x81.sqrt();
    let x89 = x27 * 0.956919;
    let x91 = x40 * 0.528915;
    let x93 = x89 - x91;
    let x94 = x46 * 0.956919;
    let x95 = x30 * 0.528915;
    let x97 = x94 - x95;
    let x98 = x56 * 0.956919;
    let x99 = x57 * 0.528915;
    let x101 = x98 - x99;
    let x102 = q[0] + x93;
    let x103 = q[1] + x97;
    let x104 = q[2] + x101;
    let x106 = x102 - 0.549094;
    let x108 = x103 - 0.756063;
    let x109 = x106 * x106;
    let x110 = x108 * x108;
    let x111 = x104 * x104;
    let x112 = x109 + x110;
    let x113 = x111 + x112;
    let x114 = x113.sqrt();
    let x123 = x27 * 0.665885;
    let x125 = x40 * 0.353482;
    let x127 = x45 * 1.402538;
    let x128 = x123 - x125;
    let x129 = x127 + x128;
    let x130 = x46 * 0.665885;
    let x131 = x30 * 0.353482;
    let x133 = x53 * 1.402538;
    let x134 = x130 - x131;
    let x135 = x133 + x134;
    let x136 = x56 * 0.665885;
    let x137 = x57 * 0.353482;
    let x139 = x33 * 1.402538;
    let x140 = x136 - x137;
    let x141 = x139 + x140;
    let x142 = q[0] + x129;
    let x143 = q[1] + x135;
    let x144 = q[2] + x141;
    let x146 = x142 - 0.735077;
    let x148 = x143 + 0.223935;
    let x150 = x144 - 0.525991;
    let x151 = x146 * x146;
    let x152 = x148 * x148;
    let x153 = x150 * x150;
    let x154 = x151 + x152;
    let x155 = x153 + x154;
    let x156 = x155.sqrt();
    let x165 = x27 * 0.478359;
    let x166 = x40 * 1.158742;
    let x167 = x45 * 0.107672;
    let x168 = x165 + x166;
    let x169 = x167 + x168;
    let x170 = x46 * 0.478359;
    let x171 = x30 * 1.158742;
    let x172 = x53 * 0.107672;
    let x173 = x170 + x171;
    let x174 = x172 + x173;
    let x175 = x56 * 0.478359;
    let x176 = x57 * 1.158742;
    let x177 = x33 * 0.107672;
    let x178 = x175 + x176;
    let x179 = x177 + x178;
    let x180 = q[0] + x169;
    let x181 = q[1] + x174;
    let x182 = q[2] + x179;
    let x184 = x180 - 0.514188;
    let x186 = x181 + 0.526063;
    let x188 = x182 + 0.368418;
    let x189 = x184 * x184;
    let x190 = x186 * x186;
    let x191 = x188 * x188;
    let x192 = x189 + x190;
    let x193 = x191 + x192;
    let x194 = x193.sqrt();
    let x204 = x27 * 0.137087;
    let x207 = x40 * 0.235121;
    let x209 = x45 * 0.353913;
    let x210 = x204 + x207;
    let x212 = x209 - x210;
    let x213 = x46 * 0.137087;
    let x215 = x30 * 0.235121;
    let x217 = x53 * 0.353913;
    let x218 = x213 + x215;
    let x220 = x217 - x218;
    let x221 = x56 * 0.137087;
    let x223 = x57 * 0.235121;
    let x225 = x33 * 0.353913;
    let x226 = x221 + x223;
    let x228 = x225 - x226;
    let x229 = q[0] + x212;
    let x230 = q[1] + x220;
    let x231 = q[2] + x228;
    let x233 = x229 - 0.590473;
    let x235 = x230 - 0.094733;
    let x237 = x231 + 0.205018;
    let x238 = x233 * x233;
    let x239 = x235 * x235;
    let x240 = x237 * x237;
    let x241 = x238 + x239;
    let x242 = x240 + x241;
    let x243 = x242.sqrt();
    let x246 = x22 + x24;
    let x247 = x23 + x246;
    let x248 = x247 - 1.0;
    let x3041 = x64 + k[0];
    let x3043 = x82 + k[1];
    let x3045 = x114 + k[2];
    let x3047 = x156 + k[3];
    let x3049 = x194 + k[4];
    let x3051 = x243 + k[5];
    out[0] = x3041;
    out[1] = x3043;
    out[2] = x3045;
    out[3] = x3047;
    out[4] = x3049;
    out[5] = x3051;
    out[6] = x248;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 42] = out.try_into().expect("out must have 42 entries");
    let _ = k;
    let _ = t;
    phi_q_part_0(q, out);
}
#[inline(never)]
fn phi_q_part_0(q: &[f64; 7], out: &mut [f64; 42]) {
    let x20 = q[3] * q[3];
    let x21 = q[4] * q[4];
    let x22 = q[5] * q[5];
    let x23 = q[6] * q[6];
    let x24 = x20 + x21;
    let x25 = 2.0 * x24;
    let x27 = x25 - 1.0;
    let x28 = x20 + x22;
    let x29 = 2.0 * x28;
    let x30 = x29 - 1.0;
    let x31 = x20 + x23;
    let x32 = 2.0 * x31;
    let x33 = x32 - 1.0;
    let x34 = q[4] * q[5];
    let x35 = 2.0 * x34;
    let x36 = q[3] * q[6];
    let x38 = 2.0 * x36;
    let x40 = x35 - x38;
    let x41 = q[4] * q[6];
    let x42 = 2.0 * x41;
    let x43 = q[3] * q[5];
    let x44 = 2.0 * x43;
    let x45 = x42 + x44;
    let x46 = x35 + x38;
    let x47 = q[5] * q[6];
    let x48 = 2.0 * x47;
    let x49 = q[3] * q[4];
    let x51 = 2.0 * x49;
    let x53 = x48 - x51;
    let x56 = x42 - x44;
    let x57 = x48 + x51;
    let x59 = q[0] * q[0];
    let x60 = q[1] * q[1];
    let x61 = q[2] * q[2];
    let x62 = x59 + x60;
    let x63 = x61 + x62;
    let x64 = x63.sqrt();
    let x69 = x27 * 0.542805;
    let x70 = x46 * 0.542805;
    let x71 = x56 * 0.542805;
    let x72 = q[0] + x69;
    let x73 = q[1] + x70;
    let x74 = q[2] + x71;
    let x76 = x72 - 1.107915;
    let x77 = x76 * x76;
    let x78 = x73 * x73;
    let x79 = x74 * x74;
    let x80 = x77 + x78;
    let x81 = x79 + x80;
    let x82 = x81.sqrt();
    let x89 = x27 * 0.956919;
    let x91 = x40 * 0.528915;
    let x93 = x89 - x91;
    let x94 = x46 * 0.956919;
    let x95 = x30 * 0.528915;
    let x97 = x94 - x95;
    let x98 = x56 * 0.956919;
    let x99 = x57 * 0.528915;
    let x101 = x98 - x99;
    let x102 = q[0] + x93;
    let x103 = q[1] + x97;
    let x104 = q[2] + x101;
    let x106 = x102 - 0.549094;
    let x108 = x103 - 0.756063;
    let x109 = x106 * x106;
    let x110 = x108 * x108;
    let x111 = x104 * x104;
    let x112 = x109 + x110;
    let x113 = x111 + x112;
    let x114 = x113.sqrt();
    let x123 = x27 * 0.665885;
    let x125 = x40 * 0.353482;
    let x127 = x45 * 1.402538;
    let x128 = x123 - x125;
    let x129 = x127 + x128;
    let x130 = x46 * 0.665885;
    let x131 = x30 * 0.353482;
    let x133 = x53 * 1.402538;
    let x134 = x130 - x131;
    let x135 = x133 + x134;
    let x136 = x56 * 0.665885;
    let x137 = x57 * 0.353482;
    let x139 = x33 * 1.402538;
    let x140 = x136 - x137;
    let x141 = x139 + x140;
    let x142 = q[0] + x129;
    let x143 = q[1] + x135;
    let x144 = q[2] + x141;
    let x146 = x142 - 0.735077;
    let x148 = x143 + 0.223935;
    let x150 = x144 - 0.525991;
    let x151 = x146 * x146;
    let x152 = x148 * x148;
    let x153 = x150 * x150;
    let x154 = x151 + x152;
    let x155 = x153 + x154;
    let x156 = x155.sqrt();
    let x165 = x27 * 0.478359;
    let x166 = x40 * 1.158742;
    let x167 = x45 * 0.107672;
    let x168 = x165 + x166;
    let x169 = x167 + x168;
    let x170 = x46 * 0.478359;
    let x171 = x30 * 1.158742;
    let x172 = x53 * 0.107672;
    let x173 = x170 + x171;
    let x174 = x172 + x173;
    let x175 = x56 * 0.478359;
    let x176 = x57 * 1.158742;
    let x177 = x33 * 0.107672;
    let x178 = x175 + x176;
    let x179 = x177 + x178;
    let x180 = q[0] + x169;
    let x181 = q[1] + x174;
    let x182 = q[2] + x179;
    let x184 = x180 - 0.514188;
    let x186 = x181 + 0.526063;
    let x188 = x182 + 0.368418;
    let x189 = x184 * x184;
    let x190 = x186 * x186;
    let x191 = x188 * x188;
    let x192 = x189 + x190;
    let x193 = x191 + x192;
    let x194 = x193.sqrt();
    let x204 = x27 * 0.137087;
    let x207 = x40 * 0.235121;
    let x209 = x45 * 0.353913;
    let x210 = x204 + x207;
    let x212 = x209 - x210;
    let x213 = x46 * 0.137087;
    let x215 = x30 * 0.235121;
    let x217 = x53 * 0.353913;
    let x218 = x213 + x215;
    let x220 = x217 - x218;
    let x221 = x56 * 0.137087;
    let x223 = x57 * 0.235121;
    let x225 = x33 * 0.353913;
    let x226 = x221 + x223;
    let x228 = x225 - x226;
    let x229 = q[0] + x212;
    let x230 = q[1] + x220;
    let x231 = q[2] + x228;
    let x233 = x229 - 0.590473;
    let x235 = x230 - 0.094733;
    let x237 = x231 + 0.205018;
    let x238 = x233 * x233;
    let x239 = x235 * x235;
    let x240 = x237 * x237;
    let x241 = x238 + x239;
    let x242 = x240 + x241;
    let x243 = x242.sqrt();
    let x249 = q[3] * 2.0;
    let x250 = q[4] * 2.0;
    let x251 = q[5] * 2.0;
    let x252 = q[6] * 2.0;
    let x253 = q[0] * 2.0;
    let x254 = q[1] * 2.0;
    let x255 = q[2] * 2.0;
    let x256 = 2.0 * x64;
    let x257 = 1.0 / x256;
    let x258 = x253 * x257;
    let x259 = 2.0 * x76;
    let x260 = 2.0 * x73;
    let x261 = 2.0 * x74;
    let x262 = 2.0 * x82;
    let x263 = 1.0 / x262;
    let x264 = x259 * x263;
    let x265 = 2.0 * x106;
    let x266 = 2.0 * x108;
    let x267 = 2.0 * x104;
    let x268 = 2.0 * x114;
    let x269 = 1.0 / x268;
    let x270 = x265 * x269;
    let x271 = 2.0 * x146;
    let x272 = 2.0 * x148;
    let x273 = 2.0 * x150;
    let x274 = 2.0 * x156;
    let x275 = 1.0 / x274;
    let x276 = x271 * x275;
    let x277 = 2.0 * x184;
    let x278 = 2.0 * x186;
    let x279 = 2.0 * x188;
    let x280 = 2.0 * x194;
    let x281 = 1.0 / x280;
    let x282 = x277 * x281;
    let x283 = 2.0 * x233;
    let x284 = 2.0 * x235;
    let x285 = 2.0 * x237;
    let x286 = 2.0 * x243;
    let x287 = 1.0 / x286;
    let x288 = x283 * x287;
    let x289 = x254 * x257;
    let x290 = x260 * x263;
    let x291 = x266 * x269;
    let x292 = x272 * x275;
    let x293 = x278 * x281;
    let x294 = x284 * x287;
    let x295 = x255 * x257;
    let x296 = x261 * x263;
    let x297 = x267 * x269;
    let x298 = x273 * x275;
    let x299 = x279 * x281;
    let x300 = x285 * x287;
    let x301 = 2.0 * x249;
    let x305 = 0.542805 * x301;
    let x306 = 0.542805 * x252;
    let x307 = 0.542805 * x251;
    let x309 = x259 * x305;
    let x310 = x260 * x306;
    let x311 = x261 * x307;
    let x313 = x309 + x310;
    let x314 = x313 - x311;
    let x315 = x263 * x314;
    let x316 = 0.956919 * x301;
    let x317 = 0.528915 * x252;
    let x319 = x316 + x317;
    let x320 = 0.956919 * x252;
    let x321 = 0.528915 * x301;
    let x323 = x320 - x321;
    let x324 = 0.956919 * x251;
    let x326 = 0.528915 * x250;
    let x328 = x324 + x326;
    let x330 = x265 * x319;
    let x331 = x266 * x323;
    let x332 = x267 * x328;
    let x334 = x330 + x331;
    let x335 = x334 - x332;
    let x336 = x269 * x335;
    let x337 = 0.665885 * x301;
    let x338 = 0.353482 * x252;
    let x340 = 1.402538 * x251;
    let x341 = x337 + x338;
    let x342 = x340 + x341;
    let x343 = 0.665885 * x252;
    let x344 = 0.353482 * x301;
    let x346 = 1.402538 * x250;
    let x348 = x343 - x344;
    let x349 = x348 - x346;
    let x350 = 0.665885 * x251;
    let x352 = 0.353482 * x250;
    let x354 = 1.402538 * x301;
    let x355 = x350 + x352;
    let x357 = x354 - x355;
    let x358 = x271 * x342;
    let x359 = x272 * x349;
    let x360 = x273 * x357;
    let x361 = x358 + x359;
    let x362 = x360 + x361;
    let x363 = x275 * x362;
    let x364 = 0.478359 * x301;
    let x365 = 1.158742 * x252;
    let x367 = 0.107672 * x251;
    let x368 = x364 - x365;
    let x369 = x367 + x368;
    let x370 = 0.478359 * x252;
    let x371 = 1.158742 * x301;
    let x372 = 0.107672 * x250;
    let x374 = x370 + x371;
    let x375 = x374 - x372;
    let x376 = 0.478359 * x251;
    let x378 = 1.158742 * x250;
    let x379 = 0.107672 * x301;
    let x380 = x378 - x376;
    let x381 = x379 + x380;
    let x382 = x277 * x369;
    let x383 = x278 * x375;
    let x384 = x279 * x381;
    let x385 = x382 + x383;
    let x386 = x384 + x385;
    let x387 = x281 * x386;
    let x388 = 0.137087 * x301;
    let x389 = 0.235121 * x252;
    let x391 = 0.353913 * x251;
    let x392 = x388 - x389;
    let x394 = x391 - x392;
    let x395 = 0.137087 * x252;
    let x396 = 0.235121 * x301;
    let x397 = 0.353913 * x250;
    let x399 = x395 + x396;
    let x401 = x397 + x399;
    let x403 = 0.137087 * x251;
    let x405 = 0.235121 * x250;
    let x406 = 0.353913 * x301;
    let x407 = x405 - x403;
    let x409 = x406 - x407;
    let x410 = x283 * x394;
    let x411 = x284 * x401;
    let x413 = x285 * x409;
    let x414 = x410 - x411;
    let x415 = x413 + x414;
    let x416 = x287 * x415;
    let x417 = 2.0 * x250;
    let x419 = 0.542805 * x417;
    let x420 = x259 * x419;
    let x421 = x260 * x307;
    let x422 = x261 * x306;
    let x423 = x420 + x421;
    let x424 = x422 + x423;
    let x425 = x263 * x424;
    let x426 = 0.956919 * x417;
    let x427 = 0.528915 * x251;
    let x429 = x426 - x427;
    let x430 = 0.528915 * x249;
    let x432 = x320 - x430;
    let x433 = x265 * x429;
    let x434 = x266 * x324;
    let x435 = x267 * x432;
    let x436 = x433 + x434;
    let x437 = x435 + x436;
    let x438 = x269 * x437;
    let x439 = 0.665885 * x417;
    let x440 = 0.353482 * x251;
    let x442 = 1.402538 * x252;
    let x443 = x439 - x440;
    let x444 = x442 + x443;
    let x445 = 1.402538 * x249;
    let x447 = x350 - x445;
    let x448 = 0.353482 * x249;
    let x450 = x343 - x448;
    let x451 = x271 * x444;
    let x452 = x272 * x447;
    let x453 = x273 * x450;
    let x454 = x451 + x452;
    let x455 = x453 + x454;
    let x456 = x275 * x455;
    let x457 = 0.478359 * x417;
    let x458 = 1.158742 * x251;
    let x459 = 0.107672 * x252;
    let x460 = x457 + x458;
    let x461 = x459 + x460;
    let x462 = 0.107672 * x249;
    let x464 = x376 - x462;
    let x465 = 1.158742 * x249;
    let x466 = x370 + x465;
    let x467 = x277 * x461;
    let x468 = x278 * x464;
    let x469 = x279 * x466;
    let x470 = x467 + x468;
    let x471 = x469 + x470;
    let x472 = x281 * x471;
    let x473 = 0.137087 * x417;
    let x474 = 0.235121 * x251;
    let x475 = 0.353913 * x252;
    let x476 = x473 + x474;
    let x478 = x475 - x476;
    let x479 = 0.353913 * x249;
    let x481 = x403 + x479;
    let x483 = 0.235121 * x249;
    let x484 = x395 + x483;
    let x486 = x283 * x478;
    let x487 = x284 * x481;
    let x489 = x285 * x484;
    let x491 = x486 - x487;
    let x492 = x491 - x489;
    let x493 = x287 * x492;
    let x494 = 2.0 * x251;
    let x495 = 0.542805 * x250;
    let x496 = 0.542805 * x249;
    let x498 = x260 * x495;
    let x499 = x261 * x496;
    let x501 = x498 - x499;
    let x502 = x263 * x501;
    let x503 = 0.956919 * x250;
    let x504 = 0.528915 * x494;
    let x506 = x503 - x504;
    let x507 = 0.956919 * x249;
    let x509 = x317 + x507;
    let x511 = x265 * x326;
    let x513 = x266 * x506;
    let x514 = x267 * x509;
    let x516 = x513 - x511;
    let x517 = x516 - x514;
    let x518 = x269 * x517;
    let x519 = x445 - x352;
    let x520 = 0.665885 * x250;
    let x521 = 0.353482 * x494;
    let x523 = x520 - x521;
    let x524 = x442 + x523;
    let x525 = 0.665885 * x249;
    let x527 = x338 + x525;
    let x529 = x271 * x519;
    let x530 = x272 * x524;
    let x531 = x273 * x527;
    let x533 = x529 + x530;
    let x534 = x533 - x531;
    let x535 = x275 * x534;
    let x536 = x378 + x462;
    let x537 = 0.478359 * x250;
    let x538 = 1.158742 * x494;
    let x539 = x537 + x538;
    let x540 = x459 + x539;
    let x541 = 0.478359 * x249;
    let x543 = x365 - x541;
    let x544 = x277 * x536;
    let x545 = x278 * x540;
    let x546 = x279 * x543;
    let x547 = x544 + x545;
    let x548 = x546 + x547;
    let x549 = x281 * x548;
    let x551 = x479 - x405;
    let x552 = 0.137087 * x250;
    let x553 = 0.235121 * x494;
    let x554 = x552 + x553;
    let x556 = x475 - x554;
    let x557 = 0.137087 * x249;
    let x559 = x389 - x557;
    let x561 = x283 * x551;
    let x562 = x284 * x556;
    let x563 = x285 * x559;
    let x565 = x561 + x562;
    let x566 = x565 - x563;
    let x567 = x287 * x566;
    let x568 = 2.0 * x252;
    let x569 = x260 * x496;
    let x570 = x261 * x495;
    let x571 = x569 + x570;
    let x572 = x263 * x571;
    let x573 = x503 - x427;
    let x574 = x265 * x430;
    let x575 = x266 * x507;
    let x576 = x267 * x573;
    let x577 = x574 + x575;
    let x578 = x576 + x577;
    let x579 = x269 * x578;
    let x580 = x346 + x448;
    let x581 = x340 + x525;
    let x582 = 1.402538 * x568;
    let x583 = x520 - x440;
    let x584 = x582 + x583;
    let x585 = x271 * x580;
    let x586 = x272 * x581;
    let x587 = x273 * x584;
    let x588 = x585 + x586;
    let x589 = x587 + x588;
    let x590 = x275 * x589;
    let x592 = x372 - x465;
    let x593 = x367 + x541;
    let x594 = 0.107672 * x568;
    let x595 = x458 + x537;
    let x596 = x594 + x595;
    let x597 = x277 * x592;
    let x598 = x278 * x593;
    let x599 = x279 * x596;
    let x600 = x597 + x598;
    let x601 = x599 + x600;
    let x602 = x281 * x601;
    let x604 = x397 + x483;
    let x605 = x391 - x557;
    let x606 = 0.353913 * x568;
    let x607 = x474 + x552;
    let x609 = x606 - x607;
    let x610 = x283 * x604;
    let x611 = x284 * x605;
    let x612 = x285 * x609;
    let x613 = x610 + x611;
    let x614 = x612 + x613;
    let x615 = x287 * x614;
    out[0] = x258;
    out[1] = x289;
    out[2] = x295;
    out[3] = x264;
    out[4] = x290;
    out[5] = x296;
    out[6] = x315;
    out[7] = x425;
    out[8] = x502;
    out[9] = x572;
    out[10] = x270;
    out[11] = x291;
    out[12] = x297;
    out[13] = x336;
    out[14] = x438;
    out[15] = x518;
    out[16] = x579;
    out[17] = x276;
    out[18] = x292;
    out[19] = x298;
    out[20] = x363;
    out[21] = x456;
    out[22] = x535;
    out[23] = x590;
    out[24] = x282;
    out[25] = x293;
    out[26] = x299;
    out[27] = x387;
    out[28] = x472;
    out[29] = x549;
    out[30] = x602;
    out[31] = x288;
    out[32] = x294;
    out[33] = x300;
    out[34] = x416;
    out[35] = x493;
    out[36] = x567;
    out[37] = x615;
    out[38] = x249;
    out[39] = x250;
    out[40] = x251;
    out[41] = x252;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
    let _ = k;
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
pub fn gamma(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
    let _ = k;
    let _ = t;
    gamma_part_0(q, qd, out);
}
#[inline(never)]
fn gamma_part_0(q: &[f64; 7], qd: &[f64; 7], out: &mut [f64; 7]) {
    let x20 = q[3] * q[3];
    let x21 = q[4] * q[4];
    let x22 = q[5] * q[5];
    let x23 = q[6] * q[6];
    let x24 = x20 + x21;
    let x25 = 2.0 * x24;
    let x27 = x25 - 1.0;
    let x28 = x20 + x22;
    let x29 = 2.0 * x28;
    let x30 = x29 - 1.0;
    let x31 = x20 + x23;
    let x32 = 2.0 * x31;
    let x33 = x32 - 1.0;
    let x34 = q[4] * q[5];
    let x35 = 2.0 * x34;
    let x36 = q[3] * q[6];
    let x38 = 2.0 * x36;
    let x40 = x35 - x38;
    let x41 = q[4] * q[6];
    let x42 = 2.0 * x41;
    let x43 = q[3] * q[5];
    let x44 = 2.0 * x43;
    let x45 = x42 + x44;
    let x46 = x35 + x38;
    let x47 = q[5] * q[6];
    let x48 = 2.0 * x47;
    let x49 = q[3] * q[4];
    let x51 = 2.0 * x49;
    let x53 = x48 - x51;
    let x56 = x42 - x44;
    let x57 = x48 + x51;
    let x59 = q[0] * q[0];
    let x60 = q[1] * q[1];
    let x61 = q[2] * q[2];
    let x62 = x59 + x60;
    let x63 = x61 + x62;
    let x64 = x63.sqrt();
    let x69 = x27 * 0.542805;
    let x70 = x46 * 0.542805;
    let x71 = x56 * 0.542805;
    let x72 = q[0] + x69;
    let x73 = q[1] + x70;
    let x74 = q[2] + x71;
    let x76 = x72 - 1.107915;
    let x77 = x76 * x76;
    let x78 = x73 * x73;
    let x79 = x74 * x74;
    let x80 = x77 + x78;
    let x81 = x79 + x80;
    let x82 = x81.sqrt();
    let x89 = x27 * 0.956919;
    let x91 = x40 * 0.528915;
    let x93 = x89 - x91;
    let x94 = x46 * 0.956919;
    let x95 = x30 * 0.528915;
    let x97 = x94 - x95;
    let x98 = x56 * 0.956919;
    let x99 = x57 * 0.528915;
    let x101 = x98 - x99;
    let x102 = q[0] + x93;
    let x103 = q[1] + x97;
    let x104 = q[2] + x101;
    let x106 = x102 - 0.549094;
    let x108 = x103 - 0.756063;
    let x109 = x106 * x106;
    let x110 = x108 * x108;
    let x111 = x104 * x104;
    let x112 = x109 + x110;
    let x113 = x111 + x112;
    let x114 = x113.sqrt();
    let x123 = x27 * 0.665885;
    let x125 = x40 * 0.353482;
    let x127 = x45 * 1.402538;
    let x128 = x123 - x125;
    let x129 = x127 + x128;
    let x130 = x46 * 0.665885;
    let x131 = x30 * 0.353482;
    let x133 = x53 * 1.402538;
    let x134 = x130 - x131;
    let x135 = x133 + x134;
    let x136 = x56 * 0.665885;
    let x137 = x57 * 0.353482;
    let x139 = x33 * 1.402538;
    let x140 = x136 - x137;
    let x141 = x139 + x140;
    let x142 = q[0] + x129;
    let x143 = q[1] + x135;
    let x144 = q[2] + x141;
    let x146 = x142 - 0.735077;
    let x148 = x143 + 0.223935;
    let x150 = x144 - 0.525991;
    let x151 = x146 * x146;
    let x152 = x148 * x148;
    let x153 = x150 * x150;
    let x154 = x151 + x152;
    let x155 = x153 + x154;
    let x156 = x155.sqrt();
    let x165 = x27 * 0.478359;
    let x166 = x40 * 1.158742;
    let x167 = x45 * 0.107672;
    let x168 = x165 + x166;
    let x169 = x167 + x168;
    let x170 = x46 * 0.478359;
    let x171 = x30 * 1.158742;
    let x172 = x53 * 0.107672;
    let x173 = x170 + x171;
    let x174 = x172 + x173;
    let x175 = x56 * 0.478359;
    let x176 = x57 * 1.158742;
    let x177 = x33 * 0.107672;
    let x178 = x175 + x176;
    let x179 = x177 + x178;
    let x180 = q[0] + x169;
    let x181 = q[1] + x174;
    let x182 = q[2] + x179;
    let x184 = x180 - 0.514188;
    let x186 = x181 + 0.526063;
    let x188 = x182 + 0.368418;
    let x189 = x184 * x184;
    let x190 = x186 * x186;
    let x191 = x188 * x188;
    let x192 = x189 + x190;
    let x193 = x191 + x192;
    let x194 = x193.sqrt();
    let x204 = x27 * 0.137087;
    let x207 = x40 * 0.235121;
    let x209 = x45 * 0.353913;
    let x210 = x204 + x207;
    let x212 = x209 - x210;
    let x213 = x46 * 0.137087;
    let x215 = x30 * 0.235121;
    let x217 = x53 * 0.353913;
    let x218 = x213 + x215;
    let x220 = x217 - x218;
    let x221 = x56 * 0.137087;
    let x223 = x57 * 0.235121;
    let x225 = x33 * 0.353913;
    let x226 = x221 + x223;
    let x228 = x225 - x226;
    let x229 = q[0] + x212;
    let x230 = q[1] + x220;
    let x231 = q[2] + x228;
    let x233 = x229 - 0.590473;
    let x235 = x230 - 0.094733;
    let x237 = x231 + 0.205018;
    let x238 = x233 * x233;
    let x239 = x235 * x235;
    let x240 = x237 * x237;
    let x241 = x238 + x239;
    let x242 = x240 + x241;
    let x243 = x242.sqrt();
    let x249 = q[3] * 2.0;
    let x250 = q[4] * 2.0;
    let x251 = q[5] * 2.0;
    let x252 = q[6] * 2.0;
    let x253 = q[0] * 2.0;
    let x254 = q[1] * 2.0;
    let x255 = q[2] * 2.0;
    let x256 = 2.0 * x64;
    let x257 = 1.0 / x256;
    let x259 = 2.0 * x76;
    let x260 = 2.0 * x73;
    let x261 = 2.0 * x74;
    let x262 = 2.0 * x82;
    let x263 = 1.0 / x262;
    let x265 = 2.0 * x106;
    let x266 = 2.0 * x108;
    let x267 = 2.0 * x104;
    let x268 = 2.0 * x114;
    let x269 = 1.0 / x268;
    let x271 = 2.0 * x146;
    let x272 = 2.0 * x148;
    let x273 = 2.0 * x150;
    let x274 = 2.0 * x156;
    let x275 = 1.0 / x274;
    let x277 = 2.0 * x184;
    let x278 = 2.0 * x186;
    let x279 = 2.0 * x188;
    let x280 = 2.0 * x194;
    let x281 = 1.0 / x280;
    let x283 = 2.0 * x233;
    let x284 = 2.0 * x235;
    let x285 = 2.0 * x237;
    let x286 = 2.0 * x243;
    let x287 = 1.0 / x286;
    let x623 = x249 * qd[3];
    let x624 = x250 * qd[4];
    let x625 = x251 * qd[5];
    let x626 = x252 * qd[6];
    let x627 = x623 + x624;
    let x628 = 2.0 * x627;
    let x629 = x623 + x625;
    let x630 = 2.0 * x629;
    let x631 = x623 + x626;
    let x632 = 2.0 * x631;
    let x633 = q[5] * qd[4];
    let x634 = q[4] * qd[5];
    let x635 = x633 + x634;
    let x636 = 2.0 * x635;
    let x637 = q[6] * qd[3];
    let x638 = q[3] * qd[6];
    let x639 = x637 + x638;
    let x640 = 2.0 * x639;
    let x642 = x636 - x640;
    let x643 = q[6] * qd[4];
    let x644 = q[4] * qd[6];
    let x645 = x643 + x644;
    let x646 = 2.0 * x645;
    let x647 = q[5] * qd[3];
    let x648 = q[3] * qd[5];
    let x649 = x647 + x648;
    let x650 = 2.0 * x649;
    let x651 = x646 + x650;
    let x652 = x636 + x640;
    let x653 = q[6] * qd[5];
    let x654 = q[5] * qd[6];
    let x655 = x653 + x654;
    let x656 = 2.0 * x655;
    let x657 = q[4] * qd[3];
    let x658 = q[3] * qd[4];
    let x659 = x657 + x658;
    let x660 = 2.0 * x659;
    let x662 = x656 - x660;
    let x664 = x646 - x650;
    let x665 = x656 + x660;
    let x666 = x253 * qd[0];
    let x667 = x254 * qd[1];
    let x668 = x255 * qd[2];
    let x669 = x666 + x667;
    let x670 = x668 + x669;
    let x671 = x257 * x670;
    let x672 = 0.542805 * x628;
    let x673 = 0.542805 * x652;
    let x674 = 0.542805 * x664;
    let x675 = qd[0] + x672;
    let x676 = qd[1] + x673;
    let x677 = qd[2] + x674;
    let x678 = x259 * x675;
    let x679 = x260 * x676;
    let x680 = x261 * x677;
    let x681 = x678 + x679;
    let x682 = x680 + x681;
    let x683 = x263 * x682;
    let x684 = 0.956919 * x628;
    let x685 = 0.528915 * x642;
    let x687 = x684 - x685;
    let x688 = 0.956919 * x652;
    let x689 = 0.528915 * x630;
    let x691 = x688 - x689;
    let x692 = 0.956919 * x664;
    let x693 = 0.528915 * x665;
    let x695 = x692 - x693;
    let x696 = qd[0] + x687;
    let x697 = qd[1] + x691;
    let x698 = qd[2] + x695;
    let x699 = x265 * x696;
    let x700 = x266 * x697;
    let x701 = x267 * x698;
    let x702 = x699 + x700;
    let x703 = x701 + x702;
    let x704 = x269 * x703;
    let x705 = 0.665885 * x628;
    let x706 = 0.353482 * x642;
    let x708 = 1.402538 * x651;
    let x709 = x705 - x706;
    let x710 = x708 + x709;
    let x711 = 0.665885 * x652;
    let x712 = 0.353482 * x630;
    let x714 = 1.402538 * x662;
    let x715 = x711 - x712;
    let x716 = x714 + x715;
    let x717 = 0.665885 * x664;
    let x718 = 0.353482 * x665;
    let x720 = 1.402538 * x632;
    let x721 = x717 - x718;
    let x722 = x720 + x721;
    let x723 = qd[0] + x710;
    let x724 = qd[1] + x716;
    let x725 = qd[2] + x722;
    let x726 = x271 * x723;
    let x727 = x272 * x724;
    let x728 = x273 * x725;
    let x729 = x726 + x727;
    let x730 = x728 + x729;
    let x731 = x275 * x730;
    let x732 = 0.478359 * x628;
    let x733 = 1.158742 * x642;
    let x734 = 0.107672 * x651;
    let x735 = x732 + x733;
    let x736 = x734 + x735;
    let x737 = 0.478359 * x652;
    let x738 = 1.158742 * x630;
    let x739 = 0.107672 * x662;
    let x740 = x737 + x738;
    let x741 = x739 + x740;
    let x742 = 0.478359 * x664;
    let x743 = 1.158742 * x665;
    let x744 = 0.107672 * x632;
    let x745 = x742 + x743;
    let x746 = x744 + x745;
    let x747 = qd[0] + x736;
    let x748 = qd[1] + x741;
    let x749 = qd[2] + x746;
    let x750 = x277 * x747;
    let x751 = x278 * x748;
    let x752 = x279 * x749;
    let x753 = x750 + x751;
    let x754 = x752 + x753;
    let x755 = x281 * x754;
    let x756 = 0.137087 * x628;
    let x757 = 0.235121 * x642;
    let x758 = 0.353913 * x651;
    let x759 = x756 + x757;
    let x761 = x758 - x759;
    let x762 = 0.137087 * x652;
    let x763 = 0.235121 * x630;
    let x764 = 0.353913 * x662;
    let x765 = x762 + x763;
    let x767 = x764 - x765;
    let x768 = 0.137087 * x664;
    let x769 = 0.235121 * x665;
    let x770 = 0.353913 * x632;
    let x771 = x768 + x769;
    let x773 = x770 - x771;
    let x774 = qd[0] + x761;
    let x775 = qd[1] + x767;
    let x776 = qd[2] + x773;
    let x777 = x283 * x774;
    let x778 = x284 * x775;
    let x779 = x285 * x776;
    let x780 = x777 + x778;
    let x781 = x779 + x780;
    let x782 = x287 * x781;
    let x785 = 2.0 * qd[3];
    let x786 = 2.0 * qd[4];
    let x787 = 2.0 * qd[5];
    let x788 = 2.0 * qd[6];
    let x789 = 2.0 * qd[0];
    let x790 = 2.0 * qd[1];
    let x791 = 2.0 * qd[2];
    let x792 = 2.0 * x671;
    let x793 = x257 * x257;
    let x794 = x792 * x793;
    let x796 = 2.0 * x675;
    let x797 = 2.0 * x676;
    let x798 = 2.0 * x677;
    let x799 = 2.0 * x683;
    let x800 = x263 * x263;
    let x801 = x799 * x800;
    let x803 = 2.0 * x696;
    let x804 = 2.0 * x697;
    let x805 = 2.0 * x698;
    let x806 = 2.0 * x704;
    let x807 = x269 * x269;
    let x808 = x806 * x807;
    let x810 = 2.0 * x723;
    let x811 = 2.0 * x724;
    let x812 = 2.0 * x725;
    let x813 = 2.0 * x731;
    let x814 = x275 * x275;
    let x815 = x813 * x814;
    let x817 = 2.0 * x747;
    let x818 = 2.0 * x748;
    let x819 = 2.0 * x749;
    let x820 = 2.0 * x755;
    let x821 = x281 * x281;
    let x822 = x820 * x821;
    let x824 = 2.0 * x774;
    let x825 = 2.0 * x775;
    let x826 = 2.0 * x776;
    let x827 = 2.0 * x782;
    let x828 = x287 * x287;
    let x829 = x827 * x828;
    let x831 = qd[3] * x785;
    let x832 = qd[4] * x786;
    let x833 = qd[5] * x787;
    let x834 = qd[6] * x788;
    let x835 = x831 + x832;
    let x836 = 2.0 * x835;
    let x837 = x831 + x833;
    let x838 = 2.0 * x837;
    let x839 = x831 + x834;
    let x840 = 2.0 * x839;
    let x841 = qd[4] * qd[5];
    let x842 = x841 + x841;
    let x843 = 2.0 * x842;
    let x844 = qd[3] * qd[6];
    let x845 = x844 + x844;
    let x846 = 2.0 * x845;
    let x848 = x843 - x846;
    let x849 = qd[4] * qd[6];
    let x850 = x849 + x849;
    let x851 = 2.0 * x850;
    let x852 = qd[3] * qd[5];
    let x853 = x852 + x852;
    let x854 = 2.0 * x853;
    let x855 = x851 + x854;
    let x856 = x843 + x846;
    let x857 = qd[5] * qd[6];
    let x858 = x857 + x857;
    let x859 = 2.0 * x858;
    let x860 = qd[3] * qd[4];
    let x861 = x860 + x860;
    let x862 = 2.0 * x861;
    let x864 = x859 - x862;
    let x866 = x851 - x854;
    let x867 = x859 + x862;
    let x868 = qd[0] * x789;
    let x869 = qd[1] * x790;
    let x870 = qd[2] * x791;
    let x871 = x868 + x869;
    let x872 = x870 + x871;
    let x873 = x670 * x794;
    let x875 = x257 * x872;
    let x876 = x875 - x873;
    let x877 = 0.542805 * x836;
    let x878 = 0.542805 * x856;
    let x879 = 0.542805 * x866;
    let x880 = x675 * x796;
    let x881 = x259 * x877;
    let x882 = x880 + x881;
    let x883 = x676 * x797;
    let x884 = x260 * x878;
    let x885 = x883 + x884;
    let x886 = x677 * x798;
    let x887 = x261 * x879;
    let x888 = x886 + x887;
    let x889 = x882 + x885;
    let x890 = x888 + x889;
    let x891 = x682 * x801;
    let x893 = x263 * x890;
    let x894 = x893 - x891;
    let x895 = 0.956919 * x836;
    let x896 = 0.528915 * x848;
    let x898 = x895 - x896;
    let x899 = 0.956919 * x856;
    let x900 = 0.528915 * x838;
    let x902 = x899 - x900;
    let x903 = 0.956919 * x866;
    let x904 = 0.528915 * x867;
    let x906 = x903 - x904;
    let x907 = x696 * x803;
    let x908 = x265 * x898;
    let x909 = x907 + x908;
    let x910 = x697 * x804;
    let x911 = x266 * x902;
    let x912 = x910 + x911;
    let x913 = x698 * x805;
    let x914 = x267 * x906;
    let x915 = x913 + x914;
    let x916 = x909 + x912;
    let x917 = x915 + x916;
    let x918 = x703 * x808;
    let x920 = x269 * x917;
    let x921 = x920 - x918;
    let x922 = 0.665885 * x836;
    let x923 = 0.353482 * x848;
    let x925 = 1.402538 * x855;
    let x926 = x922 - x923;
    let x927 = x925 + x926;
    let x928 = 0.665885 * x856;
    let x929 = 0.353482 * x838;
    let x931 = 1.402538 * x864;
    let x932 = x928 - x929;
    let x933 = x931 + x932;
    let x934 = 0.665885 * x866;
    let x935 = 0.353482 * x867;
    let x937 = 1.402538 * x840;
    let x938 = x934 - x935;
    let x939 = x937 + x938;
    let x940 = x723 * x810;
    let x941 = x271 * x927;
    let x942 = x940 + x941;
    let x943 = x724 * x811;
    let x944 = x272 * x933;
    let x945 = x943 + x944;
    let x946 = x725 * x812;
    let x947 = x273 * x939;
    let x948 = x946 + x947;
    let x949 = x942 + x945;
    let x950 = x948 + x949;
    let x951 = x730 * x815;
    let x953 = x275 * x950;
    let x954 = x953 - x951;
    let x955 = 0.478359 * x836;
    let x956 = 1.158742 * x848;
    let x957 = 0.107672 * x855;
    let x958 = x955 + x956;
    let x959 = x957 + x958;
    let x960 = 0.478359 * x856;
    let x961 = 1.158742 * x838;
    let x962 = 0.107672 * x864;
    let x963 = x960 + x961;
    let x964 = x962 + x963;
    let x965 = 0.478359 * x866;
    let x966 = 1.158742 * x867;
    let x967 = 0.107672 * x840;
    let x968 = x965 + x966;
    let x969 = x967 + x968;
    let x970 = x747 * x817;
    let x971 = x277 * x959;
    let x972 = x970 + x971;
    let x973 = x748 * x818;
    let x974 = x278 * x964;
    let x975 = x973 + x974;
    let x976 = x749 * x819;
    let x977 = x279 * x969;
    let x978 = x976 + x977;
    let x979 = x972 + x975;
    let x980 = x978 + x979;
    let x981 = x754 * x822;
    let x983 = x281 * x980;
    let x984 = x983 - x981;
    let x985 = 0.137087 * x836;
    let x986 = 0.235121 * x848;
    let x987 = 0.353913 * x855;
    let x988 = x985 + x986;
    let x990 = x987 - x988;
    let x991 = 0.137087 * x856;
    let x992 = 0.235121 * x838;
    let x993 = 0.353913 * x864;
    let x994 = x991 + x992;
    let x996 = x993 - x994;
    let x997 = 0.137087 * x866;
    let x998 = 0.235121 * x867;
    let x999 = 0.353913 * x840;
    let x1000 = x997 + x998;
    let x1002 = x999 - x1000;
    let x1003 = x774 * x824;
    let x1004 = x283 * x990;
    let x1005 = x1003 + x1004;
    let x1006 = x775 * x825;
    let x1007 = x284 * x996;
    let x1008 = x1006 + x1007;
    let x1009 = x776 * x826;
    let x1010 = x285 * x1002;
    let x1011 = x1009 + x1010;
    let x1012 = x1005 + x1008;
    let x1013 = x1011 + x1012;
    let x1014 = x781 * x829;
    let x1016 = x287 * x1013;
    let x1017 = x1016 - x1014;
    let x1018 = x833 + x835;
    let x1019 = x834 + x1018;
    let x1020 = -x876;
    let x1021 = -x894;
    let x1022 = -x921;
    let x1023 = -x954;
    let x1024 = -x984;
    let x1025 = -x1017;
    let x1026 = -x1019;
    out[0] = x1020;
    out[1] = x1021;
    out[2] = x1022;
    out[3] = x1023;
    out[4] = x1024;
    out[5] = x1025;
    out[6] = x1026;
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
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let phi: &mut [f64; 7] = phi.try_into().expect("phi must have 7 entries");
    let phi_q: &mut [f64; 42] = phi_q.try_into().expect("phi_q must have 42 entries");
    let phi_t: &mut [f64; 7] = phi_t.try_into().expect("phi_t must have 7 entries");
    let gamma: &mut [f64; 7] = gamma.try_into().expect("gamma must have 7 entries");
    let _ = t;
    let mut s = [0.0f64; 155];
    eval_kinematics_shared_0(k, q, qd, t, &mut s);
    eval_kinematics_part_0(k, q, qd, &s, phi, phi_q, phi_t, gamma);
    eval_kinematics_part_1(k, q, qd, &s, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_shared_0(
    _k: &[f64; 6],
    q: &[f64; 7],
    qd: &[f64; 7],
    _t: f64,
    s: &mut [f64; 155],
) {
    let x20 = q[3] * q[3];
    s[0] = x20;
    let x21 = q[4] * q[4];
    s[1] = x21;
    let x22 = q[5] * q[5];
    s[2] = x22;
    let x23 = q[6] * q[6];
    s[3] = x23;
    let x24 = x20 + x21;
    s[4] = x24;
    let x25 = 2.0 * x24;
    s[5] = x25;
    let x27 = x25 - 1.0;
    s[6] = x27;
    let x28 = x20 + x22;
    s[7] = x28;
    let x29 = 2.0 * x28;
    s[8] = x29;
    let x30 = x29 - 1.0;
    s[9] = x30;
    let x31 = x20 + x23;
    s[10] = x31;
    let x32 = 2.0 * x31;
    s[11] = x32;
    let x33 = x32 - 1.0;
    s[12] = x33;
    let x34 = q[4] * q[5];
    s[13] = x34;
    let x35 = 2.0 * x34;
    s[14] = x35;
    let x36 = q[3] * q[6];
    s[15] = x36;
    let x38 = 2.0 * x36;
    s[16] = x38;
    let x40 = x35 - x38;
    s[17] = x40;
    let x41 = q[4] * q[6];
    s[18] = x41;
    let x42 = 2.0 * x41;
    s[19] = x42;
    let x43 = q[3] * q[5];
    s[20] = x43;
    let x44 = 2.0 * x43;
    s[21] = x44;
    let x45 = x42 + x44;
    s[22] = x45;
    let x46 = x35 + x38;
    s[23] = x46;
    let x47 = q[5] * q[6];
    s[24] = x47;
    let x48 = 2.0 * x47;
    s[25] = x48;
    let x49 = q[3] * q[4];
    s[26] = x49;
    let x51 = 2.0 * x49;
    s[27] = x51;
    let x53 = x48 - x51;
    s[28] = x53;
    let x56 = x42 - x44;
    s[29] = x56;
    let x57 = x48 + x51;
    s[30] = x57;
    let x165 = x27 * 0.478359;
    s[31] = x165;
    let x166 = x40 * 1.158742;
    s[32] = x166;
    let x167 = x45 * 0.107672;
    s[33] = x167;
    let x168 = x165 + x166;
    s[34] = x168;
    let x169 = x167 + x168;
    s[35] = x169;
    let x170 = x46 * 0.478359;
    s[36] = x170;
    let x171 = x30 * 1.158742;
    s[37] = x171;
    let x172 = x53 * 0.107672;
    s[38] = x172;
    let x173 = x170 + x171;
    s[39] = x173;
    let x174 = x172 + x173;
    s[40] = x174;
    let x175 = x56 * 0.478359;
    s[41] = x175;
    let x176 = x57 * 1.158742;
    s[42] = x176;
    let x177 = x33 * 0.107672;
    s[43] = x177;
    let x178 = x175 + x176;
    s[44] = x178;
    let x179 = x177 + x178;
    s[45] = x179;
    let x180 = q[0] + x169;
    s[46] = x180;
    let x181 = q[1] + x174;
    s[47] = x181;
    let x182 = q[2] + x179;
    s[48] = x182;
    let x184 = x180 - 0.514188;
    s[49] = x184;
    let x186 = x181 + 0.526063;
    s[50] = x186;
    let x188 = x182 + 0.368418;
    s[51] = x188;
    let x189 = x184 * x184;
    s[52] = x189;
    let x190 = x186 * x186;
    s[53] = x190;
    let x191 = x188 * x188;
    s[54] = x191;
    let x192 = x189 + x190;
    s[55] = x192;
    let x193 = x191 + x192;
    s[56] = x193;
    let x194 = x193.sqrt();
    s[57] = x194;
    let x249 = q[3] * 2.0;
    s[58] = x249;
    let x250 = q[4] * 2.0;
    s[59] = x250;
    let x251 = q[5] * 2.0;
    s[60] = x251;
    let x252 = q[6] * 2.0;
    s[61] = x252;
    let x277 = 2.0 * x184;
    s[62] = x277;
    let x278 = 2.0 * x186;
    s[63] = x278;
    let x279 = 2.0 * x188;
    s[64] = x279;
    let x280 = 2.0 * x194;
    s[65] = x280;
    let x281 = 1.0 / x280;
    s[66] = x281;
    let x301 = 2.0 * x249;
    s[67] = x301;
    let x367 = 0.107672 * x251;
    s[68] = x367;
    let x372 = 0.107672 * x250;
    s[69] = x372;
    let x417 = 2.0 * x250;
    s[70] = x417;
    let x458 = 1.158742 * x251;
    s[71] = x458;
    let x465 = 1.158742 * x249;
    s[72] = x465;
    let x494 = 2.0 * x251;
    s[73] = x494;
    let x537 = 0.478359 * x250;
    s[74] = x537;
    let x541 = 0.478359 * x249;
    s[75] = x541;
    let x568 = 2.0 * x252;
    s[76] = x568;
    let x623 = x249 * qd[3];
    s[77] = x623;
    let x624 = x250 * qd[4];
    s[78] = x624;
    let x625 = x251 * qd[5];
    s[79] = x625;
    let x626 = x252 * qd[6];
    s[80] = x626;
    let x627 = x623 + x624;
    s[81] = x627;
    let x628 = 2.0 * x627;
    s[82] = x628;
    let x629 = x623 + x625;
    s[83] = x629;
    let x630 = 2.0 * x629;
    s[84] = x630;
    let x631 = x623 + x626;
    s[85] = x631;
    let x632 = 2.0 * x631;
    s[86] = x632;
    let x633 = q[5] * qd[4];
    s[87] = x633;
    let x634 = q[4] * qd[5];
    s[88] = x634;
    let x635 = x633 + x634;
    s[89] = x635;
    let x636 = 2.0 * x635;
    s[90] = x636;
    let x637 = q[6] * qd[3];
    s[91] = x637;
    let x638 = q[3] * qd[6];
    s[92] = x638;
    let x639 = x637 + x638;
    s[93] = x639;
    let x640 = 2.0 * x639;
    s[94] = x640;
    let x642 = x636 - x640;
    s[95] = x642;
    let x643 = q[6] * qd[4];
    s[96] = x643;
    let x644 = q[4] * qd[6];
    s[97] = x644;
    let x645 = x643 + x644;
    s[98] = x645;
    let x646 = 2.0 * x645;
    s[99] = x646;
    let x647 = q[5] * qd[3];
    s[100] = x647;
    let x648 = q[3] * qd[5];
    s[101] = x648;
    let x649 = x647 + x648;
    s[102] = x649;
    let x650 = 2.0 * x649;
    s[103] = x650;
    let x651 = x646 + x650;
    s[104] = x651;
    let x652 = x636 + x640;
    s[105] = x652;
    let x653 = q[6] * qd[5];
    s[106] = x653;
    let x654 = q[5] * qd[6];
    s[107] = x654;
    let x655 = x653 + x654;
    s[108] = x655;
    let x656 = 2.0 * x655;
    s[109] = x656;
    let x657 = q[4] * qd[3];
    s[110] = x657;
    let x658 = q[3] * qd[4];
    s[111] = x658;
    let x659 = x657 + x658;
    s[112] = x659;
    let x660 = 2.0 * x659;
    s[113] = x660;
    let x662 = x656 - x660;
    s[114] = x662;
    let x664 = x646 - x650;
    s[115] = x664;
    let x665 = x656 + x660;
    s[116] = x665;
    let x785 = 2.0 * qd[3];
    s[117] = x785;
    let x786 = 2.0 * qd[4];
    s[118] = x786;
    let x787 = 2.0 * qd[5];
    s[119] = x787;
    let x788 = 2.0 * qd[6];
    s[120] = x788;
    let x831 = qd[3] * x785;
    s[121] = x831;
    let x832 = qd[4] * x786;
    s[122] = x832;
    let x833 = qd[5] * x787;
    s[123] = x833;
    let x834 = qd[6] * x788;
    s[124] = x834;
    let x835 = x831 + x832;
    s[125] = x835;
    let x836 = 2.0 * x835;
    s[126] = x836;
    let x837 = x831 + x833;
    s[127] = x837;
    let x838 = 2.0 * x837;
    s[128] = x838;
    let x839 = x831 + x834;
    s[129] = x839;
    let x840 = 2.0 * x839;
    s[130] = x840;
    let x841 = qd[4] * qd[5];
    s[131] = x841;
    let x842 = x841 + x841;
    s[132] = x842;
    let x843 = 2.0 * x842;
    s[133] = x843;
    let x844 = qd[3] * qd[6];
    s[134] = x844;
    let x845 = x844 + x844;
    s[135] = x845;
    let x846 = 2.0 * x845;
    s[136] = x846;
    let x848 = x843 - x846;
    s[137] = x848;
    let x849 = qd[4] * qd[6];
    s[138] = x849;
    let x850 = x849 + x849;
    s[139] = x850;
    let x851 = 2.0 * x850;
    s[140] = x851;
    let x852 = qd[3] * qd[5];
    s[141] = x852;
    let x853 = x852 + x852;
    s[142] = x853;
    let x854 = 2.0 * x853;
    s[143] = x854;
    let x855 = x851 + x854;
    s[144] = x855;
    let x856 = x843 + x846;
    s[145] = x856;
    let x857 = qd[5] * qd[6];
    s[146] = x857;
    let x858 = x857 + x857;
    s[147] = x858;
    let x859 = 2.0 * x858;
    s[148] = x859;
    let x860 = qd[3] * qd[4];
    s[149] = x860;
    let x861 = x860 + x860;
    s[150] = x861;
    let x862 = 2.0 * x861;
    s[151] = x862;
    let x864 = x859 - x862;
    s[152] = x864;
    let x866 = x851 - x854;
    s[153] = x866;
    let x867 = x859 + x862;
    s[154] = x867;
}
#[inline(never)]
fn eval_kinematics_part_0(
    k: &[f64; 6],
    q: &[f64; 7],
    qd: &[f64; 7],
    s: &[f64; 155],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 42],
    phi_t: &mut [f64; 7],
    gamma: &mut [f64; 7],
) {
    let x59 = q[0] * q[0];
    let x60 = q[1] * q[1];
    let x61 = q[2] * q[2];
    let x62 = x59 + x60;
    let x63 = x61 + x62;
    let x64 = x63.sqrt();
    let x69 = s[6] * 0.542805;
    let x70 = s[23] * 0.542805;
    let x71 = s[29] * 0.542805;
    let x72 = q[0] + x69;
    let x73 = q[1] + x70;
    let x74 = q[2] + x71;
    let x76 = x72 - 1.107915;
    let x77 = x76 * x76;
    let x78 = x73 * x73;
    let x79 = x74 * x74;
    let x80 = x77 + x78;
    let x81 = x79 + x80;
    let x82 = x81.sqrt();
    let x89 = s[6] * 0.956919;
    let x91 = s[17] * 0.528915;
    let x93 = x89 - x91;
    let x94 = s[23] * 0.956919;
    let x95 = s[9] * 0.528915;
    let x97 = x94 - x95;
    let x98 = s[29] * 0.956919;
    let x99 = s[30] * 0.528915;
    let x101 = x98 - x99;
    let x102 = q[0] + x93;
    let x103 = q[1] + x97;
    let x104 = q[2] + x101;
    let x106 = x102 - 0.549094;
    let x108 = x103 - 0.756063;
    let x109 = x106 * x106;
    let x110 = x108 * x108;
    let x111 = x104 * x104;
    let x112 = x109 + x110;
    let x113 = x111 + x112;
    let x114 = x113.sqrt();
    let x123 = s[6] * 0.665885;
    let x125 = s[17] * 0.353482;
    let x127 = s[22] * 1.402538;
    let x128 = x123 - x125;
    let x129 = x127 + x128;
    let x130 = s[23] * 0.665885;
    let x131 = s[9] * 0.353482;
    let x133 = s[28] * 1.402538;
    let x134 = x130 - x131;
    let x135 = x133 + x134;
    let x136 = s[29] * 0.665885;
    let x137 = s[30] * 0.353482;
    let x139 = s[12] * 1.402538;
    let x140 = x136 - x137;
    let x141 = x139 + x140;
    let x142 = q[0] + x129;
    let x143 = q[1] + x135;
    let x144 = q[2] + x141;
    let x146 = x142 - 0.735077;
    let x148 = x143 + 0.223935;
    let x150 = x144 - 0.525991;
    let x151 = x146 * x146;
    let x152 = x148 * x148;
    let x153 = x150 * x150;
    let x154 = x151 + x152;
    let x155 = x153 + x154;
    let x156 = x155.sqrt();
    let x253 = q[0] * 2.0;
    let x254 = q[1] * 2.0;
    let x255 = q[2] * 2.0;
    let x256 = 2.0 * x64;
    let x257 = 1.0 / x256;
    let x258 = x253 * x257;
    let x259 = 2.0 * x76;
    let x260 = 2.0 * x73;
    let x261 = 2.0 * x74;
    let x262 = 2.0 * x82;
    let x263 = 1.0 / x262;
    let x264 = x259 * x263;
    let x265 = 2.0 * x106;
    let x266 = 2.0 * x108;
    let x267 = 2.0 * x104;
    let x268 = 2.0 * x114;
    let x269 = 1.0 / x268;
    let x270 = x265 * x269;
    let x271 = 2.0 * x146;
    let x272 = 2.0 * x148;
    let x273 = 2.0 * x150;
    let x274 = 2.0 * x156;
    let x275 = 1.0 / x274;
    let x276 = x271 * x275;
    let x282 = s[62] * s[66];
    let x289 = x254 * x257;
    let x290 = x260 * x263;
    let x291 = x266 * x269;
    let x292 = x272 * x275;
    let x293 = s[63] * s[66];
    let x295 = x255 * x257;
    let x296 = x261 * x263;
    let x297 = x267 * x269;
    let x298 = x273 * x275;
    let x299 = s[64] * s[66];
    let x305 = 0.542805 * s[67];
    let x306 = 0.542805 * s[61];
    let x307 = 0.542805 * s[60];
    let x309 = x259 * x305;
    let x310 = x260 * x306;
    let x311 = x261 * x307;
    let x313 = x309 + x310;
    let x314 = x313 - x311;
    let x315 = x263 * x314;
    let x316 = 0.956919 * s[67];
    let x317 = 0.528915 * s[61];
    let x319 = x316 + x317;
    let x320 = 0.956919 * s[61];
    let x321 = 0.528915 * s[67];
    let x323 = x320 - x321;
    let x324 = 0.956919 * s[60];
    let x326 = 0.528915 * s[59];
    let x328 = x324 + x326;
    let x330 = x265 * x319;
    let x331 = x266 * x323;
    let x332 = x267 * x328;
    let x334 = x330 + x331;
    let x335 = x334 - x332;
    let x336 = x269 * x335;
    let x337 = 0.665885 * s[67];
    let x338 = 0.353482 * s[61];
    let x340 = 1.402538 * s[60];
    let x341 = x337 + x338;
    let x342 = x340 + x341;
    let x343 = 0.665885 * s[61];
    let x344 = 0.353482 * s[67];
    let x346 = 1.402538 * s[59];
    let x348 = x343 - x344;
    let x349 = x348 - x346;
    let x350 = 0.665885 * s[60];
    let x352 = 0.353482 * s[59];
    let x354 = 1.402538 * s[67];
    let x355 = x350 + x352;
    let x357 = x354 - x355;
    let x358 = x271 * x342;
    let x359 = x272 * x349;
    let x360 = x273 * x357;
    let x361 = x358 + x359;
    let x362 = x360 + x361;
    let x363 = x275 * x362;
    let x364 = 0.478359 * s[67];
    let x365 = 1.158742 * s[61];
    let x368 = x364 - x365;
    let x369 = s[68] + x368;
    let x370 = 0.478359 * s[61];
    let x371 = 1.158742 * s[67];
    let x374 = x370 + x371;
    let x375 = x374 - s[69];
    let x376 = 0.478359 * s[60];
    let x378 = 1.158742 * s[59];
    let x379 = 0.107672 * s[67];
    let x380 = x378 - x376;
    let x381 = x379 + x380;
    let x382 = s[62] * x369;
    let x383 = s[63] * x375;
    let x384 = s[64] * x381;
    let x385 = x382 + x383;
    let x386 = x384 + x385;
    let x387 = s[66] * x386;
    let x419 = 0.542805 * s[70];
    let x420 = x259 * x419;
    let x421 = x260 * x307;
    let x422 = x261 * x306;
    let x423 = x420 + x421;
    let x424 = x422 + x423;
    let x425 = x263 * x424;
    let x426 = 0.956919 * s[70];
    let x427 = 0.528915 * s[60];
    let x429 = x426 - x427;
    let x430 = 0.528915 * s[58];
    let x432 = x320 - x430;
    let x433 = x265 * x429;
    let x434 = x266 * x324;
    let x435 = x267 * x432;
    let x436 = x433 + x434;
    let x437 = x435 + x436;
    let x438 = x269 * x437;
    let x439 = 0.665885 * s[70];
    let x440 = 0.353482 * s[60];
    let x442 = 1.402538 * s[61];
    let x443 = x439 - x440;
    let x444 = x442 + x443;
    let x445 = 1.402538 * s[58];
    let x447 = x350 - x445;
    let x448 = 0.353482 * s[58];
    let x450 = x343 - x448;
    let x451 = x271 * x444;
    let x452 = x272 * x447;
    let x453 = x273 * x450;
    let x454 = x451 + x452;
    let x455 = x453 + x454;
    let x456 = x275 * x455;
    let x457 = 0.478359 * s[70];
    let x459 = 0.107672 * s[61];
    let x460 = x457 + s[71];
    let x461 = x459 + x460;
    let x462 = 0.107672 * s[58];
    let x464 = x376 - x462;
    let x466 = x370 + s[72];
    let x467 = s[62] * x461;
    let x468 = s[63] * x464;
    let x469 = s[64] * x466;
    let x470 = x467 + x468;
    let x471 = x469 + x470;
    let x472 = s[66] * x471;
    let x495 = 0.542805 * s[59];
    let x496 = 0.542805 * s[58];
    let x498 = x260 * x495;
    let x499 = x261 * x496;
    let x501 = x498 - x499;
    let x502 = x263 * x501;
    let x503 = 0.956919 * s[59];
    let x504 = 0.528915 * s[73];
    let x506 = x503 - x504;
    let x507 = 0.956919 * s[58];
    let x509 = x317 + x507;
    let x511 = x265 * x326;
    let x513 = x266 * x506;
    let x514 = x267 * x509;
    let x516 = x513 - x511;
    let x517 = x516 - x514;
    let x518 = x269 * x517;
    let x519 = x445 - x352;
    let x520 = 0.665885 * s[59];
    let x521 = 0.353482 * s[73];
    let x523 = x520 - x521;
    let x524 = x442 + x523;
    let x525 = 0.665885 * s[58];
    let x527 = x338 + x525;
    let x529 = x271 * x519;
    let x530 = x272 * x524;
    let x531 = x273 * x527;
    let x533 = x529 + x530;
    let x534 = x533 - x531;
    let x535 = x275 * x534;
    let x536 = x378 + x462;
    let x538 = 1.158742 * s[73];
    let x539 = s[74] + x538;
    let x540 = x459 + x539;
    let x543 = x365 - s[75];
    let x544 = s[62] * x536;
    let x545 = s[63] * x540;
    let x546 = s[64] * x543;
    let x547 = x544 + x545;
    let x548 = x546 + x547;
    let x549 = s[66] * x548;
    let x569 = x260 * x496;
    let x570 = x261 * x495;
    let x571 = x569 + x570;
    let x572 = x263 * x571;
    let x573 = x503 - x427;
    let x574 = x265 * x430;
    let x575 = x266 * x507;
    let x576 = x267 * x573;
    let x577 = x574 + x575;
    let x578 = x576 + x577;
    let x579 = x269 * x578;
    let x580 = x346 + x448;
    let x581 = x340 + x525;
    let x582 = 1.402538 * s[76];
    let x583 = x520 - x440;
    let x584 = x582 + x583;
    let x585 = x271 * x580;
    let x586 = x272 * x581;
    let x587 = x273 * x584;
    let x588 = x585 + x586;
    let x589 = x587 + x588;
    let x590 = x275 * x589;
    let x666 = x253 * qd[0];
    let x667 = x254 * qd[1];
    let x668 = x255 * qd[2];
    let x669 = x666 + x667;
    let x670 = x668 + x669;
    let x671 = x257 * x670;
    let x672 = 0.542805 * s[82];
    let x673 = 0.542805 * s[105];
    let x674 = 0.542805 * s[115];
    let x675 = qd[0] + x672;
    let x676 = qd[1] + x673;
    let x677 = qd[2] + x674;
    let x678 = x259 * x675;
    let x679 = x260 * x676;
    let x680 = x261 * x677;
    let x681 = x678 + x679;
    let x682 = x680 + x681;
    let x683 = x263 * x682;
    let x684 = 0.956919 * s[82];
    let x685 = 0.528915 * s[95];
    let x687 = x684 - x685;
    let x688 = 0.956919 * s[105];
    let x689 = 0.528915 * s[84];
    let x691 = x688 - x689;
    let x692 = 0.956919 * s[115];
    let x693 = 0.528915 * s[116];
    let x695 = x692 - x693;
    let x696 = qd[0] + x687;
    let x697 = qd[1] + x691;
    let x698 = qd[2] + x695;
    let x699 = x265 * x696;
    let x700 = x266 * x697;
    let x701 = x267 * x698;
    let x702 = x699 + x700;
    let x703 = x701 + x702;
    let x704 = x269 * x703;
    let x705 = 0.665885 * s[82];
    let x706 = 0.353482 * s[95];
    let x708 = 1.402538 * s[104];
    let x709 = x705 - x706;
    let x710 = x708 + x709;
    let x711 = 0.665885 * s[105];
    let x712 = 0.353482 * s[84];
    let x714 = 1.402538 * s[114];
    let x715 = x711 - x712;
    let x716 = x714 + x715;
    let x717 = 0.665885 * s[115];
    let x718 = 0.353482 * s[116];
    let x720 = 1.402538 * s[86];
    let x721 = x717 - x718;
    let x722 = x720 + x721;
    let x723 = qd[0] + x710;
    let x724 = qd[1] + x716;
    let x725 = qd[2] + x722;
    let x726 = x271 * x723;
    let x727 = x272 * x724;
    let x728 = x273 * x725;
    let x729 = x726 + x727;
    let x730 = x728 + x729;
    let x731 = x275 * x730;
    let x789 = 2.0 * qd[0];
    let x790 = 2.0 * qd[1];
    let x791 = 2.0 * qd[2];
    let x792 = 2.0 * x671;
    let x793 = x257 * x257;
    let x794 = x792 * x793;
    let x796 = 2.0 * x675;
    let x797 = 2.0 * x676;
    let x798 = 2.0 * x677;
    let x799 = 2.0 * x683;
    let x800 = x263 * x263;
    let x801 = x799 * x800;
    let x803 = 2.0 * x696;
    let x804 = 2.0 * x697;
    let x805 = 2.0 * x698;
    let x806 = 2.0 * x704;
    let x807 = x269 * x269;
    let x808 = x806 * x807;
    let x810 = 2.0 * x723;
    let x811 = 2.0 * x724;
    let x812 = 2.0 * x725;
    let x813 = 2.0 * x731;
    let x814 = x275 * x275;
    let x815 = x813 * x814;
    let x868 = qd[0] * x789;
    let x869 = qd[1] * x790;
    let x870 = qd[2] * x791;
    let x871 = x868 + x869;
    let x872 = x870 + x871;
    let x873 = x670 * x794;
    let x875 = x257 * x872;
    let x876 = x875 - x873;
    let x877 = 0.542805 * s[126];
    let x878 = 0.542805 * s[145];
    let x879 = 0.542805 * s[153];
    let x880 = x675 * x796;
    let x881 = x259 * x877;
    let x882 = x880 + x881;
    let x883 = x676 * x797;
    let x884 = x260 * x878;
    let x885 = x883 + x884;
    let x886 = x677 * x798;
    let x887 = x261 * x879;
    let x888 = x886 + x887;
    let x889 = x882 + x885;
    let x890 = x888 + x889;
    let x891 = x682 * x801;
    let x893 = x263 * x890;
    let x894 = x893 - x891;
    let x895 = 0.956919 * s[126];
    let x896 = 0.528915 * s[137];
    let x898 = x895 - x896;
    let x899 = 0.956919 * s[145];
    let x900 = 0.528915 * s[128];
    let x902 = x899 - x900;
    let x903 = 0.956919 * s[153];
    let x904 = 0.528915 * s[154];
    let x906 = x903 - x904;
    let x907 = x696 * x803;
    let x908 = x265 * x898;
    let x909 = x907 + x908;
    let x910 = x697 * x804;
    let x911 = x266 * x902;
    let x912 = x910 + x911;
    let x913 = x698 * x805;
    let x914 = x267 * x906;
    let x915 = x913 + x914;
    let x916 = x909 + x912;
    let x917 = x915 + x916;
    let x918 = x703 * x808;
    let x920 = x269 * x917;
    let x921 = x920 - x918;
    let x922 = 0.665885 * s[126];
    let x923 = 0.353482 * s[137];
    let x925 = 1.402538 * s[144];
    let x926 = x922 - x923;
    let x927 = x925 + x926;
    let x928 = 0.665885 * s[145];
    let x929 = 0.353482 * s[128];
    let x931 = 1.402538 * s[152];
    let x932 = x928 - x929;
    let x933 = x931 + x932;
    let x934 = 0.665885 * s[153];
    let x935 = 0.353482 * s[154];
    let x937 = 1.402538 * s[130];
    let x938 = x934 - x935;
    let x939 = x937 + x938;
    let x940 = x723 * x810;
    let x941 = x271 * x927;
    let x942 = x940 + x941;
    let x943 = x724 * x811;
    let x944 = x272 * x933;
    let x945 = x943 + x944;
    let x946 = x725 * x812;
    let x947 = x273 * x939;
    let x948 = x946 + x947;
    let x949 = x942 + x945;
    let x950 = x948 + x949;
    let x951 = x730 * x815;
    let x953 = x275 * x950;
    let x954 = x953 - x951;
    let x1020 = -x876;
    let x1021 = -x894;
    let x1022 = -x921;
    let x1023 = -x954;
    let x3041 = x64 + k[0];
    let x3043 = x82 + k[1];
    let x3045 = x114 + k[2];
    let x3047 = x156 + k[3];
    let x3049 = s[57] + k[4];
    phi[0] = x3041;
    phi_q[0] = x258;
    phi_q[1] = x289;
    phi_q[2] = x295;
    phi_t[0] = 0.0;
    gamma[0] = x1020;
    phi[1] = x3043;
    phi_q[3] = x264;
    phi_q[4] = x290;
    phi_q[5] = x296;
    phi_q[6] = x315;
    phi_q[7] = x425;
    phi_q[8] = x502;
    phi_q[9] = x572;
    phi_t[1] = 0.0;
    gamma[1] = x1021;
    phi[2] = x3045;
    phi_q[10] = x270;
    phi_q[11] = x291;
    phi_q[12] = x297;
    phi_q[13] = x336;
    phi_q[14] = x438;
    phi_q[15] = x518;
    phi_q[16] = x579;
    phi_t[2] = 0.0;
    gamma[2] = x1022;
    phi[3] = x3047;
    phi_q[17] = x276;
    phi_q[18] = x292;
    phi_q[19] = x298;
    phi_q[20] = x363;
    phi_q[21] = x456;
    phi_q[22] = x535;
    phi_q[23] = x590;
    phi_t[3] = 0.0;
    gamma[3] = x1023;
    phi[4] = x3049;
    phi_q[24] = x282;
    phi_q[25] = x293;
    phi_q[26] = x299;
    phi_q[27] = x387;
    phi_q[28] = x472;
    phi_q[29] = x549;
}
#[inline(never)]
fn eval_kinematics_part_1(
    k: &[f64; 6],
    q: &[f64; 7],
    qd: &[f64; 7],
    s: &[f64; 155],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 42],
    phi_t: &mut [f64; 7],
    gamma: &mut [f64; 7],
) {
    let x204 = s[6] * 0.137087;
    let x207 = s[17] * 0.235121;
    let x209 = s[22] * 0.353913;
    let x210 = x204 + x207;
    let x212 = x209 - x210;
    let x213 = s[23] * 0.137087;
    let x215 = s[9] * 0.235121;
    let x217 = s[28] * 0.353913;
    let x218 = x213 + x215;
    let x220 = x217 - x218;
    let x221 = s[29] * 0.137087;
    let x223 = s[30] * 0.235121;
    let x225 = s[12] * 0.353913;
    let x226 = x221 + x223;
    let x228 = x225 - x226;
    let x229 = q[0] + x212;
    let x230 = q[1] + x220;
    let x231 = q[2] + x228;
    let x233 = x229 - 0.590473;
    let x235 = x230 - 0.094733;
    let x237 = x231 + 0.205018;
    let x238 = x233 * x233;
    let x239 = x235 * x235;
    let x240 = x237 * x237;
    let x241 = x238 + x239;
    let x242 = x240 + x241;
    let x243 = x242.sqrt();
    let x246 = s[2] + s[4];
    let x247 = s[3] + x246;
    let x248 = x247 - 1.0;
    let x283 = 2.0 * x233;
    let x284 = 2.0 * x235;
    let x285 = 2.0 * x237;
    let x286 = 2.0 * x243;
    let x287 = 1.0 / x286;
    let x288 = x283 * x287;
    let x294 = x284 * x287;
    let x300 = x285 * x287;
    let x388 = 0.137087 * s[67];
    let x389 = 0.235121 * s[61];
    let x391 = 0.353913 * s[60];
    let x392 = x388 - x389;
    let x394 = x391 - x392;
    let x395 = 0.137087 * s[61];
    let x396 = 0.235121 * s[67];
    let x397 = 0.353913 * s[59];
    let x399 = x395 + x396;
    let x401 = x397 + x399;
    let x403 = 0.137087 * s[60];
    let x405 = 0.235121 * s[59];
    let x406 = 0.353913 * s[67];
    let x407 = x405 - x403;
    let x409 = x406 - x407;
    let x410 = x283 * x394;
    let x411 = x284 * x401;
    let x413 = x285 * x409;
    let x414 = x410 - x411;
    let x415 = x413 + x414;
    let x416 = x287 * x415;
    let x473 = 0.137087 * s[70];
    let x474 = 0.235121 * s[60];
    let x475 = 0.353913 * s[61];
    let x476 = x473 + x474;
    let x478 = x475 - x476;
    let x479 = 0.353913 * s[58];
    let x481 = x403 + x479;
    let x483 = 0.235121 * s[58];
    let x484 = x395 + x483;
    let x486 = x283 * x478;
    let x487 = x284 * x481;
    let x489 = x285 * x484;
    let x491 = x486 - x487;
    let x492 = x491 - x489;
    let x493 = x287 * x492;
    let x551 = x479 - x405;
    let x552 = 0.137087 * s[59];
    let x553 = 0.235121 * s[73];
    let x554 = x552 + x553;
    let x556 = x475 - x554;
    let x557 = 0.137087 * s[58];
    let x559 = x389 - x557;
    let x561 = x283 * x551;
    let x562 = x284 * x556;
    let x563 = x285 * x559;
    let x565 = x561 + x562;
    let x566 = x565 - x563;
    let x567 = x287 * x566;
    let x592 = s[69] - s[72];
    let x593 = s[68] + s[75];
    let x594 = 0.107672 * s[76];
    let x595 = s[71] + s[74];
    let x596 = x594 + x595;
    let x597 = s[62] * x592;
    let x598 = s[63] * x593;
    let x599 = s[64] * x596;
    let x600 = x597 + x598;
    let x601 = x599 + x600;
    let x602 = s[66] * x601;
    let x604 = x397 + x483;
    let x605 = x391 - x557;
    let x606 = 0.353913 * s[76];
    let x607 = x474 + x552;
    let x609 = x606 - x607;
    let x610 = x283 * x604;
    let x611 = x284 * x605;
    let x612 = x285 * x609;
    let x613 = x610 + x611;
    let x614 = x612 + x613;
    let x615 = x287 * x614;
    let x732 = 0.478359 * s[82];
    let x733 = 1.158742 * s[95];
    let x734 = 0.107672 * s[104];
    let x735 = x732 + x733;
    let x736 = x734 + x735;
    let x737 = 0.478359 * s[105];
    let x738 = 1.158742 * s[84];
    let x739 = 0.107672 * s[114];
    let x740 = x737 + x738;
    let x741 = x739 + x740;
    let x742 = 0.478359 * s[115];
    let x743 = 1.158742 * s[116];
    let x744 = 0.107672 * s[86];
    let x745 = x742 + x743;
    let x746 = x744 + x745;
    let x747 = qd[0] + x736;
    let x748 = qd[1] + x741;
    let x749 = qd[2] + x746;
    let x750 = s[62] * x747;
    let x751 = s[63] * x748;
    let x752 = s[64] * x749;
    let x753 = x750 + x751;
    let x754 = x752 + x753;
    let x755 = s[66] * x754;
    let x756 = 0.137087 * s[82];
    let x757 = 0.235121 * s[95];
    let x758 = 0.353913 * s[104];
    let x759 = x756 + x757;
    let x761 = x758 - x759;
    let x762 = 0.137087 * s[105];
    let x763 = 0.235121 * s[84];
    let x764 = 0.353913 * s[114];
    let x765 = x762 + x763;
    let x767 = x764 - x765;
    let x768 = 0.137087 * s[115];
    let x769 = 0.235121 * s[116];
    let x770 = 0.353913 * s[86];
    let x771 = x768 + x769;
    let x773 = x770 - x771;
    let x774 = qd[0] + x761;
    let x775 = qd[1] + x767;
    let x776 = qd[2] + x773;
    let x777 = x283 * x774;
    let x778 = x284 * x775;
    let x779 = x285 * x776;
    let x780 = x777 + x778;
    let x781 = x779 + x780;
    let x782 = x287 * x781;
    let x817 = 2.0 * x747;
    let x818 = 2.0 * x748;
    let x819 = 2.0 * x749;
    let x820 = 2.0 * x755;
    let x821 = s[66] * s[66];
    let x822 = x820 * x821;
    let x824 = 2.0 * x774;
    let x825 = 2.0 * x775;
    let x826 = 2.0 * x776;
    let x827 = 2.0 * x782;
    let x828 = x287 * x287;
    let x829 = x827 * x828;
    let x955 = 0.478359 * s[126];
    let x956 = 1.158742 * s[137];
    let x957 = 0.107672 * s[144];
    let x958 = x955 + x956;
    let x959 = x957 + x958;
    let x960 = 0.478359 * s[145];
    let x961 = 1.158742 * s[128];
    let x962 = 0.107672 * s[152];
    let x963 = x960 + x961;
    let x964 = x962 + x963;
    let x965 = 0.478359 * s[153];
    let x966 = 1.158742 * s[154];
    let x967 = 0.107672 * s[130];
    let x968 = x965 + x966;
    let x969 = x967 + x968;
    let x970 = x747 * x817;
    let x971 = s[62] * x959;
    let x972 = x970 + x971;
    let x973 = x748 * x818;
    let x974 = s[63] * x964;
    let x975 = x973 + x974;
    let x976 = x749 * x819;
    let x977 = s[64] * x969;
    let x978 = x976 + x977;
    let x979 = x972 + x975;
    let x980 = x978 + x979;
    let x981 = x754 * x822;
    let x983 = s[66] * x980;
    let x984 = x983 - x981;
    let x985 = 0.137087 * s[126];
    let x986 = 0.235121 * s[137];
    let x987 = 0.353913 * s[144];
    let x988 = x985 + x986;
    let x990 = x987 - x988;
    let x991 = 0.137087 * s[145];
    let x992 = 0.235121 * s[128];
    let x993 = 0.353913 * s[152];
    let x994 = x991 + x992;
    let x996 = x993 - x994;
    let x997 = 0.137087 * s[153];
    let x998 = 0.235121 * s[154];
    let x999 = 0.353913 * s[130];
    let x1000 = x997 + x998;
    let x1002 = x999 - x1000;
    let x1003 = x774 * x824;
    let x1004 = x283 * x990;
    let x1005 = x1003 + x1004;
    let x1006 = x775 * x825;
    let x1007 = x284 * x996;
    let x1008 = x1006 + x1007;
    let x1009 = x776 * x826;
    let x1010 = x285 * x1002;
    let x1011 = x1009 + x1010;
    let x1012 = x1005 + x1008;
    let x1013 = x1011 + x1012;
    let x1014 = x781 * x829;
    let x1016 = x287 * x1013;
    let x1017 = x1016 - x1014;
    let x1018 = s[123] + s[125];
    let x1019 = s[124] + x1018;
    let x1024 = -x984;
    let x1025 = -x1017;
    let x1026 = -x1019;
    let x3051 = x243 + k[5];
    phi_q[30] = x602;
    phi_t[4] = 0.0;
    gamma[4] = x1024;
    phi[5] = x3051;
    phi_q[31] = x288;
    phi_q[32] = x294;
    phi_q[33] = x300;
    phi_q[34] = x416;
    phi_q[35] = x493;
    phi_q[36] = x567;
    phi_q[37] = x615;
    phi_t[5] = 0.0;
    gamma[5] = x1025;
    phi[6] = x248;
    phi_q[38] = s[58];
    phi_q[39] = s[59];
    phi_q[40] = s[60];
    phi_q[41] = s[61];
    phi_t[6] = 0.0;
    gamma[6] = x1026;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = k;
    let _ = q;
    potential_into_part_0(out);
}
#[inline(never)]
fn potential_into_part_0(out: &mut [f64; 1]) {
    out[0] = 0.0;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
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
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let dq: &[f64; 7] = dq.try_into().expect("dq must have n_coords entries");
    let dqd: &[f64; 7] = dqd.try_into().expect("dqd must have n_coords entries");
    let dp: &[f64; 12] = dp.try_into().expect("dp must have 12 entries");
    let phi: &mut [f64; 7] = phi.try_into().expect("phi must have 7 entries");
    let phi_q: &mut [f64; 42] = phi_q.try_into().expect("phi_q must have 42 entries");
    let phi_t: &mut [f64; 7] = phi_t.try_into().expect("phi_t must have 7 entries");
    let gamma: &mut [f64; 7] = gamma.try_into().expect("gamma must have 7 entries");
    let _ = k;
    let _ = t;
    let mut s = [0.0f64; 538];
    kinematic_tangents_shared_0(k, q, qd, t, dq, dqd, dp, &mut s);
    kinematic_tangents_part_0(q, qd, dq, dqd, dp, &s, phi, phi_q, phi_t, gamma);
    kinematic_tangents_part_1(qd, dqd, dp, &s, phi, phi_q, phi_t, gamma);
    kinematic_tangents_part_2(&s, phi_q, phi_t);
    kinematic_tangents_part_3(qd, dqd, dp, &s, phi, phi_q, gamma);
    kinematic_tangents_part_4(&s, phi_q, phi_t);
    kinematic_tangents_part_5(qd, dqd, dp, &s, phi, phi_q, gamma);
    kinematic_tangents_part_6(&s, phi_q, phi_t);
    kinematic_tangents_part_7(qd, dqd, &s, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn kinematic_tangents_shared_0(
    _k: &[f64; 6],
    q: &[f64; 7],
    qd: &[f64; 7],
    _t: f64,
    dq: &[f64; 7],
    dqd: &[f64; 7],
    _dp: &[f64; 12],
    s: &mut [f64; 538],
) {
    let x20 = q[3] * q[3];
    s[0] = x20;
    let x21 = q[4] * q[4];
    s[1] = x21;
    let x22 = q[5] * q[5];
    s[2] = x22;
    let x23 = q[6] * q[6];
    s[3] = x23;
    let x24 = x20 + x21;
    s[4] = x24;
    let x25 = 2.0 * x24;
    s[5] = x25;
    let x27 = x25 - 1.0;
    s[6] = x27;
    let x28 = x20 + x22;
    s[7] = x28;
    let x29 = 2.0 * x28;
    s[8] = x29;
    let x30 = x29 - 1.0;
    s[9] = x30;
    let x31 = x20 + x23;
    s[10] = x31;
    let x32 = 2.0 * x31;
    s[11] = x32;
    let x33 = x32 - 1.0;
    s[12] = x33;
    let x34 = q[4] * q[5];
    s[13] = x34;
    let x35 = 2.0 * x34;
    s[14] = x35;
    let x36 = q[3] * q[6];
    s[15] = x36;
    let x38 = 2.0 * x36;
    s[16] = x38;
    let x40 = x35 - x38;
    s[17] = x40;
    let x41 = q[4] * q[6];
    s[18] = x41;
    let x42 = 2.0 * x41;
    s[19] = x42;
    let x43 = q[3] * q[5];
    s[20] = x43;
    let x44 = 2.0 * x43;
    s[21] = x44;
    let x45 = x42 + x44;
    s[22] = x45;
    let x46 = x35 + x38;
    s[23] = x46;
    let x47 = q[5] * q[6];
    s[24] = x47;
    let x48 = 2.0 * x47;
    s[25] = x48;
    let x49 = q[3] * q[4];
    s[26] = x49;
    let x51 = 2.0 * x49;
    s[27] = x51;
    let x53 = x48 - x51;
    s[28] = x53;
    let x56 = x42 - x44;
    s[29] = x56;
    let x57 = x48 + x51;
    s[30] = x57;
    let x89 = x27 * 0.956919;
    s[31] = x89;
    let x91 = x40 * 0.528915;
    s[32] = x91;
    let x93 = x89 - x91;
    s[33] = x93;
    let x94 = x46 * 0.956919;
    s[34] = x94;
    let x95 = x30 * 0.528915;
    s[35] = x95;
    let x97 = x94 - x95;
    s[36] = x97;
    let x98 = x56 * 0.956919;
    s[37] = x98;
    let x99 = x57 * 0.528915;
    s[38] = x99;
    let x101 = x98 - x99;
    s[39] = x101;
    let x102 = q[0] + x93;
    s[40] = x102;
    let x103 = q[1] + x97;
    s[41] = x103;
    let x104 = q[2] + x101;
    s[42] = x104;
    let x106 = x102 - 0.549094;
    s[43] = x106;
    let x108 = x103 - 0.756063;
    s[44] = x108;
    let x109 = x106 * x106;
    s[45] = x109;
    let x110 = x108 * x108;
    s[46] = x110;
    let x111 = x104 * x104;
    s[47] = x111;
    let x112 = x109 + x110;
    s[48] = x112;
    let x113 = x111 + x112;
    s[49] = x113;
    let x114 = x113.sqrt();
    s[50] = x114;
    let x123 = x27 * 0.665885;
    s[51] = x123;
    let x125 = x40 * 0.353482;
    s[52] = x125;
    let x127 = x45 * 1.402538;
    s[53] = x127;
    let x128 = x123 - x125;
    s[54] = x128;
    let x129 = x127 + x128;
    s[55] = x129;
    let x130 = x46 * 0.665885;
    s[56] = x130;
    let x131 = x30 * 0.353482;
    s[57] = x131;
    let x133 = x53 * 1.402538;
    s[58] = x133;
    let x134 = x130 - x131;
    s[59] = x134;
    let x135 = x133 + x134;
    s[60] = x135;
    let x136 = x56 * 0.665885;
    s[61] = x136;
    let x137 = x57 * 0.353482;
    s[62] = x137;
    let x139 = x33 * 1.402538;
    s[63] = x139;
    let x140 = x136 - x137;
    s[64] = x140;
    let x141 = x139 + x140;
    s[65] = x141;
    let x142 = q[0] + x129;
    s[66] = x142;
    let x143 = q[1] + x135;
    s[67] = x143;
    let x144 = q[2] + x141;
    s[68] = x144;
    let x146 = x142 - 0.735077;
    s[69] = x146;
    let x148 = x143 + 0.223935;
    s[70] = x148;
    let x150 = x144 - 0.525991;
    s[71] = x150;
    let x151 = x146 * x146;
    s[72] = x151;
    let x152 = x148 * x148;
    s[73] = x152;
    let x153 = x150 * x150;
    s[74] = x153;
    let x154 = x151 + x152;
    s[75] = x154;
    let x155 = x153 + x154;
    s[76] = x155;
    let x156 = x155.sqrt();
    s[77] = x156;
    let x165 = x27 * 0.478359;
    s[78] = x165;
    let x166 = x40 * 1.158742;
    s[79] = x166;
    let x167 = x45 * 0.107672;
    s[80] = x167;
    let x168 = x165 + x166;
    s[81] = x168;
    let x169 = x167 + x168;
    s[82] = x169;
    let x170 = x46 * 0.478359;
    s[83] = x170;
    let x171 = x30 * 1.158742;
    s[84] = x171;
    let x172 = x53 * 0.107672;
    s[85] = x172;
    let x173 = x170 + x171;
    s[86] = x173;
    let x174 = x172 + x173;
    s[87] = x174;
    let x175 = x56 * 0.478359;
    s[88] = x175;
    let x176 = x57 * 1.158742;
    s[89] = x176;
    let x177 = x33 * 0.107672;
    s[90] = x177;
    let x178 = x175 + x176;
    s[91] = x178;
    let x179 = x177 + x178;
    s[92] = x179;
    let x180 = q[0] + x169;
    s[93] = x180;
    let x181 = q[1] + x174;
    s[94] = x181;
    let x182 = q[2] + x179;
    s[95] = x182;
    let x184 = x180 - 0.514188;
    s[96] = x184;
    let x186 = x181 + 0.526063;
    s[97] = x186;
    let x188 = x182 + 0.368418;
    s[98] = x188;
    let x189 = x184 * x184;
    s[99] = x189;
    let x190 = x186 * x186;
    s[100] = x190;
    let x191 = x188 * x188;
    s[101] = x191;
    let x192 = x189 + x190;
    s[102] = x192;
    let x193 = x191 + x192;
    s[103] = x193;
    let x194 = x193.sqrt();
    s[104] = x194;
    let x204 = x27 * 0.137087;
    s[105] = x204;
    let x207 = x40 * 0.235121;
    s[106] = x207;
    let x209 = x45 * 0.353913;
    s[107] = x209;
    let x210 = x204 + x207;
    s[108] = x210;
    let x212 = x209 - x210;
    s[109] = x212;
    let x213 = x46 * 0.137087;
    s[110] = x213;
    let x215 = x30 * 0.235121;
    s[111] = x215;
    let x217 = x53 * 0.353913;
    s[112] = x217;
    let x218 = x213 + x215;
    s[113] = x218;
    let x220 = x217 - x218;
    s[114] = x220;
    let x221 = x56 * 0.137087;
    s[115] = x221;
    let x223 = x57 * 0.235121;
    s[116] = x223;
    let x225 = x33 * 0.353913;
    s[117] = x225;
    let x226 = x221 + x223;
    s[118] = x226;
    let x228 = x225 - x226;
    s[119] = x228;
    let x229 = q[0] + x212;
    s[120] = x229;
    let x230 = q[1] + x220;
    s[121] = x230;
    let x231 = q[2] + x228;
    s[122] = x231;
    let x233 = x229 - 0.590473;
    s[123] = x233;
    let x235 = x230 - 0.094733;
    s[124] = x235;
    let x237 = x231 + 0.205018;
    s[125] = x237;
    let x238 = x233 * x233;
    s[126] = x238;
    let x239 = x235 * x235;
    s[127] = x239;
    let x240 = x237 * x237;
    s[128] = x240;
    let x241 = x238 + x239;
    s[129] = x241;
    let x242 = x240 + x241;
    s[130] = x242;
    let x243 = x242.sqrt();
    s[131] = x243;
    let x249 = q[3] * 2.0;
    s[132] = x249;
    let x250 = q[4] * 2.0;
    s[133] = x250;
    let x251 = q[5] * 2.0;
    s[134] = x251;
    let x252 = q[6] * 2.0;
    s[135] = x252;
    let x265 = 2.0 * x106;
    s[136] = x265;
    let x266 = 2.0 * x108;
    s[137] = x266;
    let x267 = 2.0 * x104;
    s[138] = x267;
    let x268 = 2.0 * x114;
    s[139] = x268;
    let x269 = 1.0 / x268;
    s[140] = x269;
    let x271 = 2.0 * x146;
    s[141] = x271;
    let x272 = 2.0 * x148;
    s[142] = x272;
    let x273 = 2.0 * x150;
    s[143] = x273;
    let x274 = 2.0 * x156;
    s[144] = x274;
    let x275 = 1.0 / x274;
    s[145] = x275;
    let x277 = 2.0 * x184;
    s[146] = x277;
    let x278 = 2.0 * x186;
    s[147] = x278;
    let x279 = 2.0 * x188;
    s[148] = x279;
    let x280 = 2.0 * x194;
    s[149] = x280;
    let x281 = 1.0 / x280;
    s[150] = x281;
    let x283 = 2.0 * x233;
    s[151] = x283;
    let x284 = 2.0 * x235;
    s[152] = x284;
    let x285 = 2.0 * x237;
    s[153] = x285;
    let x286 = 2.0 * x243;
    s[154] = x286;
    let x287 = 1.0 / x286;
    s[155] = x287;
    let x301 = 2.0 * x249;
    s[156] = x301;
    let x317 = 0.528915 * x252;
    s[157] = x317;
    let x320 = 0.956919 * x252;
    s[158] = x320;
    let x324 = 0.956919 * x251;
    s[159] = x324;
    let x326 = 0.528915 * x250;
    s[160] = x326;
    let x417 = 2.0 * x250;
    s[161] = x417;
    let x494 = 2.0 * x251;
    s[162] = x494;
    let x568 = 2.0 * x252;
    s[163] = x568;
    let x623 = x249 * qd[3];
    s[164] = x623;
    let x624 = x250 * qd[4];
    s[165] = x624;
    let x625 = x251 * qd[5];
    s[166] = x625;
    let x626 = x252 * qd[6];
    s[167] = x626;
    let x627 = x623 + x624;
    s[168] = x627;
    let x628 = 2.0 * x627;
    s[169] = x628;
    let x629 = x623 + x625;
    s[170] = x629;
    let x630 = 2.0 * x629;
    s[171] = x630;
    let x631 = x623 + x626;
    s[172] = x631;
    let x632 = 2.0 * x631;
    s[173] = x632;
    let x633 = q[5] * qd[4];
    s[174] = x633;
    let x634 = q[4] * qd[5];
    s[175] = x634;
    let x635 = x633 + x634;
    s[176] = x635;
    let x636 = 2.0 * x635;
    s[177] = x636;
    let x637 = q[6] * qd[3];
    s[178] = x637;
    let x638 = q[3] * qd[6];
    s[179] = x638;
    let x639 = x637 + x638;
    s[180] = x639;
    let x640 = 2.0 * x639;
    s[181] = x640;
    let x642 = x636 - x640;
    s[182] = x642;
    let x643 = q[6] * qd[4];
    s[183] = x643;
    let x644 = q[4] * qd[6];
    s[184] = x644;
    let x645 = x643 + x644;
    s[185] = x645;
    let x646 = 2.0 * x645;
    s[186] = x646;
    let x647 = q[5] * qd[3];
    s[187] = x647;
    let x648 = q[3] * qd[5];
    s[188] = x648;
    let x649 = x647 + x648;
    s[189] = x649;
    let x650 = 2.0 * x649;
    s[190] = x650;
    let x651 = x646 + x650;
    s[191] = x651;
    let x652 = x636 + x640;
    s[192] = x652;
    let x653 = q[6] * qd[5];
    s[193] = x653;
    let x654 = q[5] * qd[6];
    s[194] = x654;
    let x655 = x653 + x654;
    s[195] = x655;
    let x656 = 2.0 * x655;
    s[196] = x656;
    let x657 = q[4] * qd[3];
    s[197] = x657;
    let x658 = q[3] * qd[4];
    s[198] = x658;
    let x659 = x657 + x658;
    s[199] = x659;
    let x660 = 2.0 * x659;
    s[200] = x660;
    let x662 = x656 - x660;
    s[201] = x662;
    let x664 = x646 - x650;
    s[202] = x664;
    let x665 = x656 + x660;
    s[203] = x665;
    let x785 = 2.0 * qd[3];
    s[204] = x785;
    let x786 = 2.0 * qd[4];
    s[205] = x786;
    let x787 = 2.0 * qd[5];
    s[206] = x787;
    let x788 = 2.0 * qd[6];
    s[207] = x788;
    let x807 = x269 * x269;
    s[208] = x807;
    let x814 = x275 * x275;
    s[209] = x814;
    let x821 = x281 * x281;
    s[210] = x821;
    let x828 = x287 * x287;
    s[211] = x828;
    let x831 = qd[3] * x785;
    s[212] = x831;
    let x832 = qd[4] * x786;
    s[213] = x832;
    let x833 = qd[5] * x787;
    s[214] = x833;
    let x834 = qd[6] * x788;
    s[215] = x834;
    let x835 = x831 + x832;
    s[216] = x835;
    let x836 = 2.0 * x835;
    s[217] = x836;
    let x837 = x831 + x833;
    s[218] = x837;
    let x838 = 2.0 * x837;
    s[219] = x838;
    let x839 = x831 + x834;
    s[220] = x839;
    let x840 = 2.0 * x839;
    s[221] = x840;
    let x841 = qd[4] * qd[5];
    s[222] = x841;
    let x842 = x841 + x841;
    s[223] = x842;
    let x843 = 2.0 * x842;
    s[224] = x843;
    let x844 = qd[3] * qd[6];
    s[225] = x844;
    let x845 = x844 + x844;
    s[226] = x845;
    let x846 = 2.0 * x845;
    s[227] = x846;
    let x848 = x843 - x846;
    s[228] = x848;
    let x849 = qd[4] * qd[6];
    s[229] = x849;
    let x850 = x849 + x849;
    s[230] = x850;
    let x851 = 2.0 * x850;
    s[231] = x851;
    let x852 = qd[3] * qd[5];
    s[232] = x852;
    let x853 = x852 + x852;
    s[233] = x853;
    let x854 = 2.0 * x853;
    s[234] = x854;
    let x855 = x851 + x854;
    s[235] = x855;
    let x856 = x843 + x846;
    s[236] = x856;
    let x857 = qd[5] * qd[6];
    s[237] = x857;
    let x858 = x857 + x857;
    s[238] = x858;
    let x859 = 2.0 * x858;
    s[239] = x859;
    let x860 = qd[3] * qd[4];
    s[240] = x860;
    let x861 = x860 + x860;
    s[241] = x861;
    let x862 = 2.0 * x861;
    s[242] = x862;
    let x864 = x859 - x862;
    s[243] = x864;
    let x866 = x851 - x854;
    s[244] = x866;
    let x867 = x859 + x862;
    s[245] = x867;
    let x1362 = x249 * dq[3];
    s[246] = x1362;
    let x1363 = x250 * dq[4];
    s[247] = x1363;
    let x1364 = x251 * dq[5];
    s[248] = x1364;
    let x1365 = x252 * dq[6];
    s[249] = x1365;
    let x1366 = x1362 + x1363;
    s[250] = x1366;
    let x1367 = 2.0 * x1366;
    s[251] = x1367;
    let x1368 = x1362 + x1364;
    s[252] = x1368;
    let x1369 = 2.0 * x1368;
    s[253] = x1369;
    let x1370 = x1362 + x1365;
    s[254] = x1370;
    let x1371 = 2.0 * x1370;
    s[255] = x1371;
    let x1372 = q[5] * dq[4];
    s[256] = x1372;
    let x1373 = q[4] * dq[5];
    s[257] = x1373;
    let x1374 = x1372 + x1373;
    s[258] = x1374;
    let x1375 = 2.0 * x1374;
    s[259] = x1375;
    let x1376 = q[6] * dq[3];
    s[260] = x1376;
    let x1377 = q[3] * dq[6];
    s[261] = x1377;
    let x1378 = x1376 + x1377;
    s[262] = x1378;
    let x1379 = 2.0 * x1378;
    s[263] = x1379;
    let x1381 = x1375 - x1379;
    s[264] = x1381;
    let x1382 = q[6] * dq[4];
    s[265] = x1382;
    let x1383 = q[4] * dq[6];
    s[266] = x1383;
    let x1384 = x1382 + x1383;
    s[267] = x1384;
    let x1385 = 2.0 * x1384;
    s[268] = x1385;
    let x1386 = q[5] * dq[3];
    s[269] = x1386;
    let x1387 = q[3] * dq[5];
    s[270] = x1387;
    let x1388 = x1386 + x1387;
    s[271] = x1388;
    let x1389 = 2.0 * x1388;
    s[272] = x1389;
    let x1390 = x1385 + x1389;
    s[273] = x1390;
    let x1391 = x1375 + x1379;
    s[274] = x1391;
    let x1392 = q[6] * dq[5];
    s[275] = x1392;
    let x1393 = q[5] * dq[6];
    s[276] = x1393;
    let x1394 = x1392 + x1393;
    s[277] = x1394;
    let x1395 = 2.0 * x1394;
    s[278] = x1395;
    let x1396 = q[4] * dq[3];
    s[279] = x1396;
    let x1397 = q[3] * dq[4];
    s[280] = x1397;
    let x1398 = x1396 + x1397;
    s[281] = x1398;
    let x1399 = 2.0 * x1398;
    s[282] = x1399;
    let x1401 = x1395 - x1399;
    s[283] = x1401;
    let x1403 = x1385 - x1389;
    s[284] = x1403;
    let x1404 = x1395 + x1399;
    s[285] = x1404;
    let x1427 = 0.956919 * x1367;
    s[286] = x1427;
    let x1428 = 0.528915 * x1381;
    s[287] = x1428;
    let x1430 = x1427 - x1428;
    s[288] = x1430;
    let x1431 = 0.956919 * x1391;
    s[289] = x1431;
    let x1432 = 0.528915 * x1369;
    s[290] = x1432;
    let x1434 = x1431 - x1432;
    s[291] = x1434;
    let x1435 = 0.956919 * x1403;
    s[292] = x1435;
    let x1436 = 0.528915 * x1404;
    s[293] = x1436;
    let x1438 = x1435 - x1436;
    s[294] = x1438;
    let x1439 = dq[0] + x1430;
    s[295] = x1439;
    let x1440 = dq[1] + x1434;
    s[296] = x1440;
    let x1441 = dq[2] + x1438;
    s[297] = x1441;
    let x1442 = x265 * x1439;
    s[298] = x1442;
    let x1443 = x266 * x1440;
    s[299] = x1443;
    let x1444 = x267 * x1441;
    s[300] = x1444;
    let x1445 = x1442 + x1443;
    s[301] = x1445;
    let x1446 = x1444 + x1445;
    s[302] = x1446;
    let x1447 = x269 * x1446;
    s[303] = x1447;
    let x1450 = 0.665885 * x1367;
    s[304] = x1450;
    let x1451 = 0.353482 * x1381;
    s[305] = x1451;
    let x1453 = 1.402538 * x1390;
    s[306] = x1453;
    let x1454 = x1450 - x1451;
    s[307] = x1454;
    let x1455 = x1453 + x1454;
    s[308] = x1455;
    let x1456 = 0.665885 * x1391;
    s[309] = x1456;
    let x1457 = 0.353482 * x1369;
    s[310] = x1457;
    let x1459 = 1.402538 * x1401;
    s[311] = x1459;
    let x1460 = x1456 - x1457;
    s[312] = x1460;
    let x1461 = x1459 + x1460;
    s[313] = x1461;
    let x1462 = 0.665885 * x1403;
    s[314] = x1462;
    let x1463 = 0.353482 * x1404;
    s[315] = x1463;
    let x1465 = 1.402538 * x1371;
    s[316] = x1465;
    let x1466 = x1462 - x1463;
    s[317] = x1466;
    let x1467 = x1465 + x1466;
    s[318] = x1467;
    let x1468 = dq[0] + x1455;
    s[319] = x1468;
    let x1469 = dq[1] + x1461;
    s[320] = x1469;
    let x1470 = dq[2] + x1467;
    s[321] = x1470;
    let x1471 = x271 * x1468;
    s[322] = x1471;
    let x1472 = x272 * x1469;
    s[323] = x1472;
    let x1473 = x273 * x1470;
    s[324] = x1473;
    let x1474 = x1471 + x1472;
    s[325] = x1474;
    let x1475 = x1473 + x1474;
    s[326] = x1475;
    let x1476 = x275 * x1475;
    s[327] = x1476;
    let x1479 = 0.478359 * x1367;
    s[328] = x1479;
    let x1480 = 1.158742 * x1381;
    s[329] = x1480;
    let x1481 = 0.107672 * x1390;
    s[330] = x1481;
    let x1482 = x1479 + x1480;
    s[331] = x1482;
    let x1483 = x1481 + x1482;
    s[332] = x1483;
    let x1484 = 0.478359 * x1391;
    s[333] = x1484;
    let x1485 = 1.158742 * x1369;
    s[334] = x1485;
    let x1486 = 0.107672 * x1401;
    s[335] = x1486;
    let x1487 = x1484 + x1485;
    s[336] = x1487;
    let x1488 = x1486 + x1487;
    s[337] = x1488;
    let x1489 = 0.478359 * x1403;
    s[338] = x1489;
    let x1490 = 1.158742 * x1404;
    s[339] = x1490;
    let x1491 = 0.107672 * x1371;
    s[340] = x1491;
    let x1492 = x1489 + x1490;
    s[341] = x1492;
    let x1493 = x1491 + x1492;
    s[342] = x1493;
    let x1494 = dq[0] + x1483;
    s[343] = x1494;
    let x1495 = dq[1] + x1488;
    s[344] = x1495;
    let x1496 = dq[2] + x1493;
    s[345] = x1496;
    let x1497 = x277 * x1494;
    s[346] = x1497;
    let x1498 = x278 * x1495;
    s[347] = x1498;
    let x1499 = x279 * x1496;
    s[348] = x1499;
    let x1500 = x1497 + x1498;
    s[349] = x1500;
    let x1501 = x1499 + x1500;
    s[350] = x1501;
    let x1502 = x281 * x1501;
    s[351] = x1502;
    let x1505 = 0.137087 * x1367;
    s[352] = x1505;
    let x1506 = 0.235121 * x1381;
    s[353] = x1506;
    let x1507 = 0.353913 * x1390;
    s[354] = x1507;
    let x1508 = x1505 + x1506;
    s[355] = x1508;
    let x1510 = x1507 - x1508;
    s[356] = x1510;
    let x1511 = 0.137087 * x1391;
    s[357] = x1511;
    let x1512 = 0.235121 * x1369;
    s[358] = x1512;
    let x1513 = 0.353913 * x1401;
    s[359] = x1513;
    let x1514 = x1511 + x1512;
    s[360] = x1514;
    let x1516 = x1513 - x1514;
    s[361] = x1516;
    let x1517 = 0.137087 * x1403;
    s[362] = x1517;
    let x1518 = 0.235121 * x1404;
    s[363] = x1518;
    let x1519 = 0.353913 * x1371;
    s[364] = x1519;
    let x1520 = x1517 + x1518;
    s[365] = x1520;
    let x1522 = x1519 - x1520;
    s[366] = x1522;
    let x1523 = dq[0] + x1510;
    s[367] = x1523;
    let x1524 = dq[1] + x1516;
    s[368] = x1524;
    let x1525 = dq[2] + x1522;
    s[369] = x1525;
    let x1526 = x283 * x1523;
    s[370] = x1526;
    let x1527 = x284 * x1524;
    s[371] = x1527;
    let x1528 = x285 * x1525;
    s[372] = x1528;
    let x1529 = x1526 + x1527;
    s[373] = x1529;
    let x1530 = x1528 + x1529;
    s[374] = x1530;
    let x1531 = x287 * x1530;
    s[375] = x1531;
    let x1536 = 2.0 * dq[3];
    s[376] = x1536;
    let x1537 = 2.0 * dq[4];
    s[377] = x1537;
    let x1538 = 2.0 * dq[5];
    s[378] = x1538;
    let x1539 = 2.0 * dq[6];
    s[379] = x1539;
    let x1560 = 2.0 * x1439;
    s[380] = x1560;
    let x1561 = 2.0 * x1440;
    s[381] = x1561;
    let x1562 = 2.0 * x1441;
    s[382] = x1562;
    let x1563 = 2.0 * x1447;
    s[383] = x1563;
    let x1564 = x807 * x1563;
    s[384] = x1564;
    let x1570 = 2.0 * x1468;
    s[385] = x1570;
    let x1571 = 2.0 * x1469;
    s[386] = x1571;
    let x1572 = 2.0 * x1470;
    s[387] = x1572;
    let x1573 = 2.0 * x1476;
    s[388] = x1573;
    let x1574 = x814 * x1573;
    s[389] = x1574;
    let x1580 = 2.0 * x1494;
    s[390] = x1580;
    let x1581 = 2.0 * x1495;
    s[391] = x1581;
    let x1582 = 2.0 * x1496;
    s[392] = x1582;
    let x1583 = 2.0 * x1502;
    s[393] = x1583;
    let x1584 = x821 * x1583;
    s[394] = x1584;
    let x1590 = 2.0 * x1523;
    s[395] = x1590;
    let x1591 = 2.0 * x1524;
    s[396] = x1591;
    let x1592 = 2.0 * x1525;
    s[397] = x1592;
    let x1593 = 2.0 * x1531;
    s[398] = x1593;
    let x1594 = x828 * x1593;
    s[399] = x1594;
    let x1648 = 2.0 * x1536;
    s[400] = x1648;
    let x1669 = 0.528915 * x1539;
    s[401] = x1669;
    let x1671 = 0.956919 * x1539;
    s[402] = x1671;
    let x1675 = 0.956919 * x1538;
    s[403] = x1675;
    let x1676 = 0.528915 * x1537;
    s[404] = x1676;
    let x1796 = 2.0 * x1537;
    s[405] = x1796;
    let x1914 = 2.0 * x1538;
    s[406] = x1914;
    let x2025 = 2.0 * x1539;
    s[407] = x2025;
    let x2115 = qd[3] * x1536;
    s[408] = x2115;
    let x2116 = x249 * dqd[3];
    s[409] = x2116;
    let x2117 = x2115 + x2116;
    s[410] = x2117;
    let x2118 = qd[4] * x1537;
    s[411] = x2118;
    let x2119 = x250 * dqd[4];
    s[412] = x2119;
    let x2120 = x2118 + x2119;
    s[413] = x2120;
    let x2121 = qd[5] * x1538;
    s[414] = x2121;
    let x2122 = x251 * dqd[5];
    s[415] = x2122;
    let x2123 = x2121 + x2122;
    s[416] = x2123;
    let x2124 = qd[6] * x1539;
    s[417] = x2124;
    let x2125 = x252 * dqd[6];
    s[418] = x2125;
    let x2126 = x2124 + x2125;
    s[419] = x2126;
    let x2127 = x2117 + x2120;
    s[420] = x2127;
    let x2128 = 2.0 * x2127;
    s[421] = x2128;
    let x2129 = x2117 + x2123;
    s[422] = x2129;
    let x2130 = 2.0 * x2129;
    s[423] = x2130;
    let x2131 = x2117 + x2126;
    s[424] = x2131;
    let x2132 = 2.0 * x2131;
    s[425] = x2132;
    let x2133 = qd[4] * dq[5];
    s[426] = x2133;
    let x2134 = q[5] * dqd[4];
    s[427] = x2134;
    let x2135 = x2133 + x2134;
    s[428] = x2135;
    let x2136 = qd[5] * dq[4];
    s[429] = x2136;
    let x2137 = q[4] * dqd[5];
    s[430] = x2137;
    let x2138 = x2136 + x2137;
    s[431] = x2138;
    let x2139 = x2135 + x2138;
    s[432] = x2139;
    let x2140 = 2.0 * x2139;
    s[433] = x2140;
    let x2141 = qd[3] * dq[6];
    s[434] = x2141;
    let x2142 = q[6] * dqd[3];
    s[435] = x2142;
    let x2143 = x2141 + x2142;
    s[436] = x2143;
    let x2144 = qd[6] * dq[3];
    s[437] = x2144;
    let x2145 = q[3] * dqd[6];
    s[438] = x2145;
    let x2146 = x2144 + x2145;
    s[439] = x2146;
    let x2147 = x2143 + x2146;
    s[440] = x2147;
    let x2148 = 2.0 * x2147;
    s[441] = x2148;
    let x2150 = x2140 - x2148;
    s[442] = x2150;
    let x2151 = qd[4] * dq[6];
    s[443] = x2151;
    let x2152 = q[6] * dqd[4];
    s[444] = x2152;
    let x2153 = x2151 + x2152;
    s[445] = x2153;
    let x2154 = qd[6] * dq[4];
    s[446] = x2154;
    let x2155 = q[4] * dqd[6];
    s[447] = x2155;
    let x2156 = x2154 + x2155;
    s[448] = x2156;
    let x2157 = x2153 + x2156;
    s[449] = x2157;
    let x2158 = 2.0 * x2157;
    s[450] = x2158;
    let x2159 = qd[3] * dq[5];
    s[451] = x2159;
    let x2160 = q[5] * dqd[3];
    s[452] = x2160;
    let x2161 = x2159 + x2160;
    s[453] = x2161;
    let x2162 = qd[5] * dq[3];
    s[454] = x2162;
    let x2163 = q[3] * dqd[5];
    s[455] = x2163;
    let x2164 = x2162 + x2163;
    s[456] = x2164;
    let x2165 = x2161 + x2164;
    s[457] = x2165;
    let x2166 = 2.0 * x2165;
    s[458] = x2166;
    let x2167 = x2158 + x2166;
    s[459] = x2167;
    let x2168 = x2140 + x2148;
    s[460] = x2168;
    let x2169 = qd[5] * dq[6];
    s[461] = x2169;
    let x2170 = q[6] * dqd[5];
    s[462] = x2170;
    let x2171 = x2169 + x2170;
    s[463] = x2171;
    let x2172 = qd[6] * dq[5];
    s[464] = x2172;
    let x2173 = q[5] * dqd[6];
    s[465] = x2173;
    let x2174 = x2172 + x2173;
    s[466] = x2174;
    let x2175 = x2171 + x2174;
    s[467] = x2175;
    let x2176 = 2.0 * x2175;
    s[468] = x2176;
    let x2177 = qd[3] * dq[4];
    s[469] = x2177;
    let x2178 = q[4] * dqd[3];
    s[470] = x2178;
    let x2179 = x2177 + x2178;
    s[471] = x2179;
    let x2180 = qd[4] * dq[3];
    s[472] = x2180;
    let x2181 = q[3] * dqd[4];
    s[473] = x2181;
    let x2182 = x2180 + x2181;
    s[474] = x2182;
    let x2183 = x2179 + x2182;
    s[475] = x2183;
    let x2184 = 2.0 * x2183;
    s[476] = x2184;
    let x2186 = x2176 - x2184;
    s[477] = x2186;
    let x2188 = x2158 - x2166;
    s[478] = x2188;
    let x2189 = x2176 + x2184;
    s[479] = x2189;
    let x2361 = 2.0 * dqd[3];
    s[480] = x2361;
    let x2362 = 2.0 * dqd[4];
    s[481] = x2362;
    let x2363 = 2.0 * dqd[5];
    s[482] = x2363;
    let x2364 = 2.0 * dqd[6];
    s[483] = x2364;
    let x2431 = x785 * dqd[3];
    s[484] = x2431;
    let x2432 = qd[3] * x2361;
    s[485] = x2432;
    let x2433 = x2431 + x2432;
    s[486] = x2433;
    let x2434 = x786 * dqd[4];
    s[487] = x2434;
    let x2435 = qd[4] * x2362;
    s[488] = x2435;
    let x2436 = x2434 + x2435;
    s[489] = x2436;
    let x2437 = x787 * dqd[5];
    s[490] = x2437;
    let x2438 = qd[5] * x2363;
    s[491] = x2438;
    let x2439 = x2437 + x2438;
    s[492] = x2439;
    let x2440 = x788 * dqd[6];
    s[493] = x2440;
    let x2441 = qd[6] * x2364;
    s[494] = x2441;
    let x2442 = x2440 + x2441;
    s[495] = x2442;
    let x2443 = x2433 + x2436;
    s[496] = x2443;
    let x2444 = 2.0 * x2443;
    s[497] = x2444;
    let x2445 = x2433 + x2439;
    s[498] = x2445;
    let x2446 = 2.0 * x2445;
    s[499] = x2446;
    let x2447 = x2433 + x2442;
    s[500] = x2447;
    let x2448 = 2.0 * x2447;
    s[501] = x2448;
    let x2449 = qd[5] * dqd[4];
    s[502] = x2449;
    let x2450 = qd[4] * dqd[5];
    s[503] = x2450;
    let x2451 = x2449 + x2450;
    s[504] = x2451;
    let x2452 = x2451 + x2451;
    s[505] = x2452;
    let x2453 = 2.0 * x2452;
    s[506] = x2453;
    let x2454 = qd[6] * dqd[3];
    s[507] = x2454;
    let x2455 = qd[3] * dqd[6];
    s[508] = x2455;
    let x2456 = x2454 + x2455;
    s[509] = x2456;
    let x2457 = x2456 + x2456;
    s[510] = x2457;
    let x2458 = 2.0 * x2457;
    s[511] = x2458;
    let x2460 = x2453 - x2458;
    s[512] = x2460;
    let x2461 = qd[6] * dqd[4];
    s[513] = x2461;
    let x2462 = qd[4] * dqd[6];
    s[514] = x2462;
    let x2463 = x2461 + x2462;
    s[515] = x2463;
    let x2464 = x2463 + x2463;
    s[516] = x2464;
    let x2465 = 2.0 * x2464;
    s[517] = x2465;
    let x2466 = qd[5] * dqd[3];
    s[518] = x2466;
    let x2467 = qd[3] * dqd[5];
    s[519] = x2467;
    let x2468 = x2466 + x2467;
    s[520] = x2468;
    let x2469 = x2468 + x2468;
    s[521] = x2469;
    let x2470 = 2.0 * x2469;
    s[522] = x2470;
    let x2471 = x2465 + x2470;
    s[523] = x2471;
    let x2472 = x2453 + x2458;
    s[524] = x2472;
    let x2473 = qd[6] * dqd[5];
    s[525] = x2473;
    let x2474 = qd[5] * dqd[6];
    s[526] = x2474;
    let x2475 = x2473 + x2474;
    s[527] = x2475;
    let x2476 = x2475 + x2475;
    s[528] = x2476;
    let x2477 = 2.0 * x2476;
    s[529] = x2477;
    let x2478 = qd[4] * dqd[3];
    s[530] = x2478;
    let x2479 = qd[3] * dqd[4];
    s[531] = x2479;
    let x2480 = x2478 + x2479;
    s[532] = x2480;
    let x2481 = x2480 + x2480;
    s[533] = x2481;
    let x2482 = 2.0 * x2481;
    s[534] = x2482;
    let x2484 = x2477 - x2482;
    s[535] = x2484;
    let x2486 = x2465 - x2470;
    s[536] = x2486;
    let x2487 = x2477 + x2482;
    s[537] = x2487;
}
#[inline(never)]
fn kinematic_tangents_part_0(
    q: &[f64; 7],
    qd: &[f64; 7],
    dq: &[f64; 7],
    dqd: &[f64; 7],
    dp: &[f64; 12],
    s: &[f64; 538],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 42],
    phi_t: &mut [f64; 7],
    gamma: &mut [f64; 7],
) {
    let x59 = q[0] * q[0];
    let x60 = q[1] * q[1];
    let x61 = q[2] * q[2];
    let x62 = x59 + x60;
    let x63 = x61 + x62;
    let x64 = x63.sqrt();
    let x69 = s[6] * 0.542805;
    let x70 = s[23] * 0.542805;
    let x71 = s[29] * 0.542805;
    let x72 = q[0] + x69;
    let x73 = q[1] + x70;
    let x74 = q[2] + x71;
    let x76 = x72 - 1.107915;
    let x77 = x76 * x76;
    let x78 = x73 * x73;
    let x79 = x74 * x74;
    let x80 = x77 + x78;
    let x81 = x79 + x80;
    let x82 = x81.sqrt();
    let x253 = q[0] * 2.0;
    let x254 = q[1] * 2.0;
    let x255 = q[2] * 2.0;
    let x256 = 2.0 * x64;
    let x257 = 1.0 / x256;
    let x259 = 2.0 * x76;
    let x260 = 2.0 * x73;
    let x261 = 2.0 * x74;
    let x262 = 2.0 * x82;
    let x263 = 1.0 / x262;
    let x305 = 0.542805 * s[156];
    let x306 = 0.542805 * s[135];
    let x307 = 0.542805 * s[134];
    let x309 = x259 * x305;
    let x310 = x260 * x306;
    let x311 = x261 * x307;
    let x313 = x309 + x310;
    let x314 = x313 - x311;
    let x316 = 0.956919 * s[156];
    let x319 = x316 + s[157];
    let x321 = 0.528915 * s[156];
    let x323 = s[158] - x321;
    let x328 = s[159] + s[160];
    let x330 = s[136] * x319;
    let x331 = s[137] * x323;
    let x332 = s[138] * x328;
    let x334 = x330 + x331;
    let x335 = x334 - x332;
    let x419 = 0.542805 * s[161];
    let x420 = x259 * x419;
    let x421 = x260 * x307;
    let x422 = x261 * x306;
    let x423 = x420 + x421;
    let x424 = x422 + x423;
    let x495 = 0.542805 * s[133];
    let x496 = 0.542805 * s[132];
    let x498 = x260 * x495;
    let x499 = x261 * x496;
    let x501 = x498 - x499;
    let x569 = x260 * x496;
    let x570 = x261 * x495;
    let x571 = x569 + x570;
    let x666 = x253 * qd[0];
    let x667 = x254 * qd[1];
    let x668 = x255 * qd[2];
    let x669 = x666 + x667;
    let x670 = x668 + x669;
    let x671 = x257 * x670;
    let x672 = 0.542805 * s[169];
    let x673 = 0.542805 * s[192];
    let x674 = 0.542805 * s[202];
    let x675 = qd[0] + x672;
    let x676 = qd[1] + x673;
    let x677 = qd[2] + x674;
    let x678 = x259 * x675;
    let x679 = x260 * x676;
    let x680 = x261 * x677;
    let x681 = x678 + x679;
    let x682 = x680 + x681;
    let x683 = x263 * x682;
    let x789 = 2.0 * qd[0];
    let x790 = 2.0 * qd[1];
    let x791 = 2.0 * qd[2];
    let x792 = 2.0 * x671;
    let x793 = x257 * x257;
    let x794 = x792 * x793;
    let x796 = 2.0 * x675;
    let x797 = 2.0 * x676;
    let x798 = 2.0 * x677;
    let x799 = 2.0 * x683;
    let x800 = x263 * x263;
    let x801 = x799 * x800;
    let x868 = qd[0] * x789;
    let x869 = qd[1] * x790;
    let x870 = qd[2] * x791;
    let x871 = x868 + x869;
    let x872 = x870 + x871;
    let x877 = 0.542805 * s[217];
    let x878 = 0.542805 * s[236];
    let x879 = 0.542805 * s[244];
    let x880 = x675 * x796;
    let x881 = x259 * x877;
    let x882 = x880 + x881;
    let x883 = x676 * x797;
    let x884 = x260 * x878;
    let x885 = x883 + x884;
    let x886 = x677 * x798;
    let x887 = x261 * x879;
    let x888 = x886 + x887;
    let x889 = x882 + x885;
    let x890 = x888 + x889;
    let x1405 = x253 * dq[0];
    let x1406 = x254 * dq[1];
    let x1407 = x255 * dq[2];
    let x1408 = x1405 + x1406;
    let x1409 = x1407 + x1408;
    let x1410 = x257 * x1409;
    let x1412 = x1410 - dp[6];
    let x1413 = 0.542805 * s[251];
    let x1414 = 0.542805 * s[274];
    let x1415 = 0.542805 * s[284];
    let x1416 = dq[0] + x1413;
    let x1417 = dq[1] + x1414;
    let x1418 = dq[2] + x1415;
    let x1419 = x259 * x1416;
    let x1420 = x260 * x1417;
    let x1421 = x261 * x1418;
    let x1422 = x1419 + x1420;
    let x1423 = x1421 + x1422;
    let x1424 = x263 * x1423;
    let x1426 = x1424 - dp[7];
    let x1449 = s[303] - dp[8];
    let x1540 = 2.0 * dq[0];
    let x1541 = 2.0 * dq[1];
    let x1542 = 2.0 * dq[2];
    let x1543 = 2.0 * x1410;
    let x1544 = x793 * x1543;
    let x1546 = x257 * x1540;
    let x1547 = x253 * x1544;
    let x1549 = x1546 - x1547;
    let x1550 = 2.0 * x1416;
    let x1551 = 2.0 * x1417;
    let x1552 = 2.0 * x1418;
    let x1553 = 2.0 * x1424;
    let x1554 = x800 * x1553;
    let x1556 = x263 * x1550;
    let x1557 = x259 * x1554;
    let x1559 = x1556 - x1557;
    let x1566 = s[140] * s[380];
    let x1567 = s[136] * s[384];
    let x1569 = x1566 - x1567;
    let x1600 = x257 * x1541;
    let x1601 = x254 * x1544;
    let x1603 = x1600 - x1601;
    let x1604 = x263 * x1551;
    let x1605 = x260 * x1554;
    let x1607 = x1604 - x1605;
    let x1608 = s[140] * s[381];
    let x1609 = s[137] * s[384];
    let x1611 = x1608 - x1609;
    let x1624 = x257 * x1542;
    let x1625 = x255 * x1544;
    let x1627 = x1624 - x1625;
    let x1628 = x263 * x1552;
    let x1629 = x261 * x1554;
    let x1631 = x1628 - x1629;
    let x1632 = s[140] * s[382];
    let x1633 = s[138] * s[384];
    let x1635 = x1632 - x1633;
    let x1649 = 0.542805 * s[400];
    let x1650 = 0.542805 * s[379];
    let x1651 = 0.542805 * s[378];
    let x1652 = x305 * x1550;
    let x1653 = x259 * x1649;
    let x1654 = x1652 + x1653;
    let x1655 = x306 * x1551;
    let x1656 = x260 * x1650;
    let x1657 = x1655 + x1656;
    let x1658 = x307 * x1552;
    let x1659 = x261 * x1651;
    let x1660 = x1658 + x1659;
    let x1662 = x1654 + x1657;
    let x1663 = x1662 - x1660;
    let x1664 = x314 * x1554;
    let x1666 = x263 * x1663;
    let x1667 = x1666 - x1664;
    let x1668 = 0.956919 * s[400];
    let x1670 = x1668 + s[401];
    let x1672 = 0.528915 * s[400];
    let x1674 = s[402] - x1672;
    let x1677 = s[403] + s[404];
    let x1678 = x319 * s[380];
    let x1679 = s[136] * x1670;
    let x1680 = x1678 + x1679;
    let x1681 = x323 * s[381];
    let x1682 = s[137] * x1674;
    let x1683 = x1681 + x1682;
    let x1684 = x328 * s[382];
    let x1685 = s[138] * x1677;
    let x1686 = x1684 + x1685;
    let x1688 = x1680 + x1683;
    let x1689 = x1688 - x1686;
    let x1690 = x335 * s[384];
    let x1692 = s[140] * x1689;
    let x1693 = x1692 - x1690;
    let x1797 = 0.542805 * s[405];
    let x1798 = x419 * x1550;
    let x1799 = x259 * x1797;
    let x1800 = x1798 + x1799;
    let x1801 = x307 * x1551;
    let x1802 = x260 * x1651;
    let x1803 = x1801 + x1802;
    let x1804 = x306 * x1552;
    let x1805 = x261 * x1650;
    let x1806 = x1804 + x1805;
    let x1807 = x1800 + x1803;
    let x1808 = x1806 + x1807;
    let x1809 = x424 * x1554;
    let x1811 = x263 * x1808;
    let x1812 = x1811 - x1809;
    let x1915 = 0.542805 * s[377];
    let x1916 = 0.542805 * s[376];
    let x1917 = x495 * x1551;
    let x1918 = x260 * x1915;
    let x1919 = x1917 + x1918;
    let x1920 = x496 * x1552;
    let x1921 = x261 * x1916;
    let x1922 = x1920 + x1921;
    let x1924 = x1919 - x1922;
    let x1925 = x501 * x1554;
    let x1927 = x263 * x1924;
    let x1928 = x1927 - x1925;
    let x2026 = x496 * x1551;
    let x2027 = x260 * x1916;
    let x2028 = x2026 + x2027;
    let x2029 = x495 * x1552;
    let x2030 = x261 * x1915;
    let x2031 = x2029 + x2030;
    let x2032 = x2028 + x2031;
    let x2033 = x571 * x1554;
    let x2035 = x263 * x2032;
    let x2036 = x2035 - x2033;
    let x2190 = qd[0] * x1540;
    let x2191 = x253 * dqd[0];
    let x2192 = x2190 + x2191;
    let x2193 = qd[1] * x1541;
    let x2194 = x254 * dqd[1];
    let x2195 = x2193 + x2194;
    let x2196 = qd[2] * x1542;
    let x2197 = x255 * dqd[2];
    let x2198 = x2196 + x2197;
    let x2199 = x2192 + x2195;
    let x2200 = x2198 + x2199;
    let x2201 = x670 * x1544;
    let x2203 = x257 * x2200;
    let x2204 = x2203 - x2201;
    let x2205 = 0.542805 * s[421];
    let x2206 = 0.542805 * s[460];
    let x2207 = 0.542805 * s[478];
    let x2208 = dqd[0] + x2205;
    let x2209 = dqd[1] + x2206;
    let x2210 = dqd[2] + x2207;
    let x2211 = x675 * x1550;
    let x2212 = x259 * x2208;
    let x2213 = x2211 + x2212;
    let x2214 = x676 * x1551;
    let x2215 = x260 * x2209;
    let x2216 = x2214 + x2215;
    let x2217 = x677 * x1552;
    let x2218 = x261 * x2210;
    let x2219 = x2217 + x2218;
    let x2220 = x2213 + x2216;
    let x2221 = x2219 + x2220;
    let x2222 = x682 * x1554;
    let x2224 = x263 * x2221;
    let x2225 = x2224 - x2222;
    let x2365 = 2.0 * dqd[0];
    let x2366 = 2.0 * dqd[1];
    let x2367 = 2.0 * dqd[2];
    let x2368 = 2.0 * x2204;
    let x2369 = 2.0 * x257;
    let x2370 = x1544 * x2369;
    let x2372 = x793 * x2368;
    let x2373 = x792 * x2370;
    let x2375 = x2372 - x2373;
    let x2376 = 2.0 * x2208;
    let x2377 = 2.0 * x2209;
    let x2378 = 2.0 * x2210;
    let x2379 = 2.0 * x2225;
    let x2380 = 2.0 * x263;
    let x2381 = x1554 * x2380;
    let x2383 = x800 * x2379;
    let x2384 = x799 * x2381;
    let x2386 = x2383 - x2384;
    let x2488 = x789 * dqd[0];
    let x2489 = qd[0] * x2365;
    let x2490 = x2488 + x2489;
    let x2491 = x790 * dqd[1];
    let x2492 = qd[1] * x2366;
    let x2493 = x2491 + x2492;
    let x2494 = x791 * dqd[2];
    let x2495 = qd[2] * x2367;
    let x2496 = x2494 + x2495;
    let x2497 = x2490 + x2493;
    let x2498 = x2496 + x2497;
    let x2499 = x794 * x2200;
    let x2500 = x670 * x2375;
    let x2501 = x2499 + x2500;
    let x2503 = x872 * x1544;
    let x2505 = x257 * x2498;
    let x2506 = x2505 - x2503;
    let x2507 = x2506 - x2501;
    let x2508 = 0.542805 * s[497];
    let x2509 = 0.542805 * s[524];
    let x2510 = 0.542805 * s[536];
    let x2511 = x796 * x2208;
    let x2512 = x675 * x2376;
    let x2513 = x2511 + x2512;
    let x2514 = x877 * x1550;
    let x2515 = x259 * x2508;
    let x2516 = x2514 + x2515;
    let x2517 = x2513 + x2516;
    let x2518 = x797 * x2209;
    let x2519 = x676 * x2377;
    let x2520 = x2518 + x2519;
    let x2521 = x878 * x1551;
    let x2522 = x260 * x2509;
    let x2523 = x2521 + x2522;
    let x2524 = x2520 + x2523;
    let x2525 = x798 * x2210;
    let x2526 = x677 * x2378;
    let x2527 = x2525 + x2526;
    let x2528 = x879 * x1552;
    let x2529 = x261 * x2510;
    let x2530 = x2528 + x2529;
    let x2531 = x2527 + x2530;
    let x2532 = x2517 + x2524;
    let x2533 = x2531 + x2532;
    let x2534 = x801 * x2221;
    let x2535 = x682 * x2386;
    let x2536 = x2534 + x2535;
    let x2538 = x890 * x1554;
    let x2540 = x263 * x2533;
    let x2541 = x2540 - x2538;
    let x2542 = x2541 - x2536;
    let x2736 = -x2507;
    let x2737 = -x2542;
    phi[0] = x1412;
    phi_q[0] = x1549;
    phi_q[1] = x1603;
    phi_q[2] = x1627;
    phi_t[0] = 0.0;
    gamma[0] = x2736;
    phi[1] = x1426;
    phi_q[3] = x1559;
    phi_q[4] = x1607;
    phi_q[5] = x1631;
    phi_q[6] = x1667;
    phi_q[7] = x1812;
    phi_q[8] = x1928;
    phi_q[9] = x2036;
    phi_t[1] = 0.0;
    gamma[1] = x2737;
    phi[2] = x1449;
    phi_q[10] = x1569;
    phi_q[11] = x1611;
    phi_q[12] = x1635;
    phi_q[13] = x1693;
}
#[inline(never)]
fn kinematic_tangents_part_1(
    qd: &[f64; 7],
    dqd: &[f64; 7],
    dp: &[f64; 12],
    s: &[f64; 538],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 42],
    phi_t: &mut [f64; 7],
    gamma: &mut [f64; 7],
) {
    let x426 = 0.956919 * s[161];
    let x427 = 0.528915 * s[134];
    let x429 = x426 - x427;
    let x430 = 0.528915 * s[132];
    let x432 = s[158] - x430;
    let x433 = s[136] * x429;
    let x434 = s[137] * s[159];
    let x435 = s[138] * x432;
    let x436 = x433 + x434;
    let x437 = x435 + x436;
    let x503 = 0.956919 * s[133];
    let x504 = 0.528915 * s[162];
    let x506 = x503 - x504;
    let x507 = 0.956919 * s[132];
    let x509 = s[157] + x507;
    let x511 = s[136] * s[160];
    let x513 = s[137] * x506;
    let x514 = s[138] * x509;
    let x516 = x513 - x511;
    let x517 = x516 - x514;
    let x573 = x503 - x427;
    let x574 = s[136] * x430;
    let x575 = s[137] * x507;
    let x576 = s[138] * x573;
    let x577 = x574 + x575;
    let x578 = x576 + x577;
    let x684 = 0.956919 * s[169];
    let x685 = 0.528915 * s[182];
    let x687 = x684 - x685;
    let x688 = 0.956919 * s[192];
    let x689 = 0.528915 * s[171];
    let x691 = x688 - x689;
    let x692 = 0.956919 * s[202];
    let x693 = 0.528915 * s[203];
    let x695 = x692 - x693;
    let x696 = qd[0] + x687;
    let x697 = qd[1] + x691;
    let x698 = qd[2] + x695;
    let x699 = s[136] * x696;
    let x700 = s[137] * x697;
    let x701 = s[138] * x698;
    let x702 = x699 + x700;
    let x703 = x701 + x702;
    let x704 = s[140] * x703;
    let x803 = 2.0 * x696;
    let x804 = 2.0 * x697;
    let x805 = 2.0 * x698;
    let x806 = 2.0 * x704;
    let x808 = x806 * s[208];
    let x895 = 0.956919 * s[217];
    let x896 = 0.528915 * s[228];
    let x898 = x895 - x896;
    let x899 = 0.956919 * s[236];
    let x900 = 0.528915 * s[219];
    let x902 = x899 - x900;
    let x903 = 0.956919 * s[244];
    let x904 = 0.528915 * s[245];
    let x906 = x903 - x904;
    let x907 = x696 * x803;
    let x908 = s[136] * x898;
    let x909 = x907 + x908;
    let x910 = x697 * x804;
    let x911 = s[137] * x902;
    let x912 = x910 + x911;
    let x913 = x698 * x805;
    let x914 = s[138] * x906;
    let x915 = x913 + x914;
    let x916 = x909 + x912;
    let x917 = x915 + x916;
    let x1478 = s[327] - dp[9];
    let x1576 = s[145] * s[385];
    let x1577 = s[141] * s[389];
    let x1579 = x1576 - x1577;
    let x1612 = s[145] * s[386];
    let x1613 = s[142] * s[389];
    let x1615 = x1612 - x1613;
    let x1636 = s[145] * s[387];
    let x1637 = s[143] * s[389];
    let x1639 = x1636 - x1637;
    let x1813 = 0.956919 * s[405];
    let x1814 = 0.528915 * s[378];
    let x1816 = x1813 - x1814;
    let x1817 = 0.528915 * s[376];
    let x1819 = s[402] - x1817;
    let x1820 = x429 * s[380];
    let x1821 = s[136] * x1816;
    let x1822 = x1820 + x1821;
    let x1823 = s[159] * s[381];
    let x1824 = s[137] * s[403];
    let x1825 = x1823 + x1824;
    let x1826 = x432 * s[382];
    let x1827 = s[138] * x1819;
    let x1828 = x1826 + x1827;
    let x1829 = x1822 + x1825;
    let x1830 = x1828 + x1829;
    let x1831 = x437 * s[384];
    let x1833 = s[140] * x1830;
    let x1834 = x1833 - x1831;
    let x1929 = 0.956919 * s[377];
    let x1930 = 0.528915 * s[406];
    let x1932 = x1929 - x1930;
    let x1933 = 0.956919 * s[376];
    let x1934 = s[401] + x1933;
    let x1935 = s[160] * s[380];
    let x1936 = s[136] * s[404];
    let x1937 = x1935 + x1936;
    let x1939 = x506 * s[381];
    let x1940 = s[137] * x1932;
    let x1941 = x1939 + x1940;
    let x1942 = x509 * s[382];
    let x1943 = s[138] * x1934;
    let x1944 = x1942 + x1943;
    let x1946 = x1941 - x1937;
    let x1947 = x1946 - x1944;
    let x1948 = x517 * s[384];
    let x1950 = s[140] * x1947;
    let x1951 = x1950 - x1948;
    let x2037 = x1929 - x1814;
    let x2038 = x430 * s[380];
    let x2039 = s[136] * x1817;
    let x2040 = x2038 + x2039;
    let x2041 = x507 * s[381];
    let x2042 = s[137] * x1933;
    let x2043 = x2041 + x2042;
    let x2044 = x573 * s[382];
    let x2045 = s[138] * x2037;
    let x2046 = x2044 + x2045;
    let x2047 = x2040 + x2043;
    let x2048 = x2046 + x2047;
    let x2049 = x578 * s[384];
    let x2051 = s[140] * x2048;
    let x2052 = x2051 - x2049;
    let x2226 = 0.956919 * s[421];
    let x2227 = 0.528915 * s[442];
    let x2229 = x2226 - x2227;
    let x2230 = 0.956919 * s[460];
    let x2231 = 0.528915 * s[423];
    let x2233 = x2230 - x2231;
    let x2234 = 0.956919 * s[478];
    let x2235 = 0.528915 * s[479];
    let x2237 = x2234 - x2235;
    let x2238 = dqd[0] + x2229;
    let x2239 = dqd[1] + x2233;
    let x2240 = dqd[2] + x2237;
    let x2241 = x696 * s[380];
    let x2242 = s[136] * x2238;
    let x2243 = x2241 + x2242;
    let x2244 = x697 * s[381];
    let x2245 = s[137] * x2239;
    let x2246 = x2244 + x2245;
    let x2247 = x698 * s[382];
    let x2248 = s[138] * x2240;
    let x2249 = x2247 + x2248;
    let x2250 = x2243 + x2246;
    let x2251 = x2249 + x2250;
    let x2252 = x703 * s[384];
    let x2254 = s[140] * x2251;
    let x2255 = x2254 - x2252;
    let x2387 = 2.0 * x2238;
    let x2388 = 2.0 * x2239;
    let x2389 = 2.0 * x2240;
    let x2390 = 2.0 * x2255;
    let x2391 = 2.0 * s[140];
    let x2392 = s[384] * x2391;
    let x2394 = s[208] * x2390;
    let x2395 = x806 * x2392;
    let x2397 = x2394 - x2395;
    let x2543 = 0.956919 * s[497];
    let x2544 = 0.528915 * s[512];
    let x2546 = x2543 - x2544;
    let x2547 = 0.956919 * s[524];
    let x2548 = 0.528915 * s[499];
    let x2550 = x2547 - x2548;
    let x2551 = 0.956919 * s[536];
    let x2552 = 0.528915 * s[537];
    let x2554 = x2551 - x2552;
    let x2555 = x803 * x2238;
    let x2556 = x696 * x2387;
    let x2557 = x2555 + x2556;
    let x2558 = x898 * s[380];
    let x2559 = s[136] * x2546;
    let x2560 = x2558 + x2559;
    let x2561 = x2557 + x2560;
    let x2562 = x804 * x2239;
    let x2563 = x697 * x2388;
    let x2564 = x2562 + x2563;
    let x2565 = x902 * s[381];
    let x2566 = s[137] * x2550;
    let x2567 = x2565 + x2566;
    let x2568 = x2564 + x2567;
    let x2569 = x805 * x2240;
    let x2570 = x698 * x2389;
    let x2571 = x2569 + x2570;
    let x2572 = x906 * s[382];
    let x2573 = s[138] * x2554;
    let x2574 = x2572 + x2573;
    let x2575 = x2571 + x2574;
    let x2576 = x2561 + x2568;
    let x2577 = x2575 + x2576;
    let x2578 = x808 * x2251;
    let x2579 = x703 * x2397;
    let x2580 = x2578 + x2579;
    let x2582 = x917 * s[384];
    let x2584 = s[140] * x2577;
    let x2585 = x2584 - x2582;
    let x2586 = x2585 - x2580;
    let x2738 = -x2586;
    phi_q[14] = x1834;
    phi_q[15] = x1951;
    phi_q[16] = x2052;
    phi_t[2] = 0.0;
    gamma[2] = x2738;
    phi[3] = x1478;
    phi_q[17] = x1579;
    phi_q[18] = x1615;
    phi_q[19] = x1639;
}
#[inline(never)]
fn kinematic_tangents_part_2(
    s: &[f64; 538],
    phi_q: &mut [f64; 42],
    phi_t: &mut [f64; 7],
) {
    let x337 = 0.665885 * s[156];
    let x338 = 0.353482 * s[135];
    let x340 = 1.402538 * s[134];
    let x341 = x337 + x338;
    let x342 = x340 + x341;
    let x343 = 0.665885 * s[135];
    let x344 = 0.353482 * s[156];
    let x346 = 1.402538 * s[133];
    let x348 = x343 - x344;
    let x349 = x348 - x346;
    let x350 = 0.665885 * s[134];
    let x352 = 0.353482 * s[133];
    let x354 = 1.402538 * s[156];
    let x355 = x350 + x352;
    let x357 = x354 - x355;
    let x358 = s[141] * x342;
    let x359 = s[142] * x349;
    let x360 = s[143] * x357;
    let x361 = x358 + x359;
    let x362 = x360 + x361;
    let x439 = 0.665885 * s[161];
    let x440 = 0.353482 * s[134];
    let x442 = 1.402538 * s[135];
    let x443 = x439 - x440;
    let x444 = x442 + x443;
    let x445 = 1.402538 * s[132];
    let x447 = x350 - x445;
    let x448 = 0.353482 * s[132];
    let x450 = x343 - x448;
    let x451 = s[141] * x444;
    let x452 = s[142] * x447;
    let x453 = s[143] * x450;
    let x454 = x451 + x452;
    let x455 = x453 + x454;
    let x519 = x445 - x352;
    let x520 = 0.665885 * s[133];
    let x521 = 0.353482 * s[162];
    let x523 = x520 - x521;
    let x524 = x442 + x523;
    let x525 = 0.665885 * s[132];
    let x527 = x338 + x525;
    let x529 = s[141] * x519;
    let x530 = s[142] * x524;
    let x531 = s[143] * x527;
    let x533 = x529 + x530;
    let x534 = x533 - x531;
    let x580 = x346 + x448;
    let x581 = x340 + x525;
    let x582 = 1.402538 * s[163];
    let x583 = x520 - x440;
    let x584 = x582 + x583;
    let x585 = s[141] * x580;
    let x586 = s[142] * x581;
    let x587 = s[143] * x584;
    let x588 = x585 + x586;
    let x589 = x587 + x588;
    let x1694 = 0.665885 * s[400];
    let x1695 = 0.353482 * s[379];
    let x1696 = 1.402538 * s[378];
    let x1697 = x1694 + x1695;
    let x1698 = x1696 + x1697;
    let x1699 = 0.665885 * s[379];
    let x1700 = 0.353482 * s[400];
    let x1702 = 1.402538 * s[377];
    let x1704 = x1699 - x1700;
    let x1705 = x1704 - x1702;
    let x1706 = 0.665885 * s[378];
    let x1707 = 0.353482 * s[377];
    let x1709 = 1.402538 * s[400];
    let x1710 = x1706 + x1707;
    let x1712 = x1709 - x1710;
    let x1713 = x342 * s[385];
    let x1714 = s[141] * x1698;
    let x1715 = x1713 + x1714;
    let x1716 = x349 * s[386];
    let x1717 = s[142] * x1705;
    let x1718 = x1716 + x1717;
    let x1719 = x357 * s[387];
    let x1720 = s[143] * x1712;
    let x1721 = x1719 + x1720;
    let x1722 = x1715 + x1718;
    let x1723 = x1721 + x1722;
    let x1724 = x362 * s[389];
    let x1726 = s[145] * x1723;
    let x1727 = x1726 - x1724;
    let x1835 = 0.665885 * s[405];
    let x1836 = 0.353482 * s[378];
    let x1838 = 1.402538 * s[379];
    let x1839 = x1835 - x1836;
    let x1840 = x1838 + x1839;
    let x1841 = 1.402538 * s[376];
    let x1843 = x1706 - x1841;
    let x1844 = 0.353482 * s[376];
    let x1846 = x1699 - x1844;
    let x1847 = x444 * s[385];
    let x1848 = s[141] * x1840;
    let x1849 = x1847 + x1848;
    let x1850 = x447 * s[386];
    let x1851 = s[142] * x1843;
    let x1852 = x1850 + x1851;
    let x1853 = x450 * s[387];
    let x1854 = s[143] * x1846;
    let x1855 = x1853 + x1854;
    let x1856 = x1849 + x1852;
    let x1857 = x1855 + x1856;
    let x1858 = x455 * s[389];
    let x1860 = s[145] * x1857;
    let x1861 = x1860 - x1858;
    let x1952 = x1841 - x1707;
    let x1953 = 0.665885 * s[377];
    let x1954 = 0.353482 * s[406];
    let x1956 = x1953 - x1954;
    let x1957 = x1838 + x1956;
    let x1958 = 0.665885 * s[376];
    let x1959 = x1695 + x1958;
    let x1960 = x519 * s[385];
    let x1961 = s[141] * x1952;
    let x1962 = x1960 + x1961;
    let x1963 = x524 * s[386];
    let x1964 = s[142] * x1957;
    let x1965 = x1963 + x1964;
    let x1966 = x527 * s[387];
    let x1967 = s[143] * x1959;
    let x1968 = x1966 + x1967;
    let x1970 = x1962 + x1965;
    let x1971 = x1970 - x1968;
    let x1972 = x534 * s[389];
    let x1974 = s[145] * x1971;
    let x1975 = x1974 - x1972;
    let x2053 = x1702 + x1844;
    let x2054 = x1696 + x1958;
    let x2055 = 1.402538 * s[407];
    let x2056 = x1953 - x1836;
    let x2057 = x2055 + x2056;
    let x2058 = x580 * s[385];
    let x2059 = s[141] * x2053;
    let x2060 = x2058 + x2059;
    let x2061 = x581 * s[386];
    let x2062 = s[142] * x2054;
    let x2063 = x2061 + x2062;
    let x2064 = x584 * s[387];
    let x2065 = s[143] * x2057;
    let x2066 = x2064 + x2065;
    let x2067 = x2060 + x2063;
    let x2068 = x2066 + x2067;
    let x2069 = x589 * s[389];
    let x2071 = s[145] * x2068;
    let x2072 = x2071 - x2069;
    phi_q[20] = x1727;
    phi_q[21] = x1861;
    phi_q[22] = x1975;
    phi_q[23] = x2072;
    phi_t[3] = 0.0;
}
#[inline(never)]
fn kinematic_tangents_part_3(
    qd: &[f64; 7],
    dqd: &[f64; 7],
    dp: &[f64; 12],
    s: &[f64; 538],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 42],
    gamma: &mut [f64; 7],
) {
    let x705 = 0.665885 * s[169];
    let x706 = 0.353482 * s[182];
    let x708 = 1.402538 * s[191];
    let x709 = x705 - x706;
    let x710 = x708 + x709;
    let x711 = 0.665885 * s[192];
    let x712 = 0.353482 * s[171];
    let x714 = 1.402538 * s[201];
    let x715 = x711 - x712;
    let x716 = x714 + x715;
    let x717 = 0.665885 * s[202];
    let x718 = 0.353482 * s[203];
    let x720 = 1.402538 * s[173];
    let x721 = x717 - x718;
    let x722 = x720 + x721;
    let x723 = qd[0] + x710;
    let x724 = qd[1] + x716;
    let x725 = qd[2] + x722;
    let x726 = s[141] * x723;
    let x727 = s[142] * x724;
    let x728 = s[143] * x725;
    let x729 = x726 + x727;
    let x730 = x728 + x729;
    let x731 = s[145] * x730;
    let x810 = 2.0 * x723;
    let x811 = 2.0 * x724;
    let x812 = 2.0 * x725;
    let x813 = 2.0 * x731;
    let x815 = x813 * s[209];
    let x922 = 0.665885 * s[217];
    let x923 = 0.353482 * s[228];
    let x925 = 1.402538 * s[235];
    let x926 = x922 - x923;
    let x927 = x925 + x926;
    let x928 = 0.665885 * s[236];
    let x929 = 0.353482 * s[219];
    let x931 = 1.402538 * s[243];
    let x932 = x928 - x929;
    let x933 = x931 + x932;
    let x934 = 0.665885 * s[244];
    let x935 = 0.353482 * s[245];
    let x937 = 1.402538 * s[221];
    let x938 = x934 - x935;
    let x939 = x937 + x938;
    let x940 = x723 * x810;
    let x941 = s[141] * x927;
    let x942 = x940 + x941;
    let x943 = x724 * x811;
    let x944 = s[142] * x933;
    let x945 = x943 + x944;
    let x946 = x725 * x812;
    let x947 = s[143] * x939;
    let x948 = x946 + x947;
    let x949 = x942 + x945;
    let x950 = x948 + x949;
    let x1504 = s[351] - dp[10];
    let x1586 = s[150] * s[390];
    let x1587 = s[146] * s[394];
    let x1589 = x1586 - x1587;
    let x1616 = s[150] * s[391];
    let x1617 = s[147] * s[394];
    let x1619 = x1616 - x1617;
    let x1640 = s[150] * s[392];
    let x1641 = s[148] * s[394];
    let x1643 = x1640 - x1641;
    let x2256 = 0.665885 * s[421];
    let x2257 = 0.353482 * s[442];
    let x2259 = 1.402538 * s[459];
    let x2260 = x2256 - x2257;
    let x2261 = x2259 + x2260;
    let x2262 = 0.665885 * s[460];
    let x2263 = 0.353482 * s[423];
    let x2265 = 1.402538 * s[477];
    let x2266 = x2262 - x2263;
    let x2267 = x2265 + x2266;
    let x2268 = 0.665885 * s[478];
    let x2269 = 0.353482 * s[479];
    let x2271 = 1.402538 * s[425];
    let x2272 = x2268 - x2269;
    let x2273 = x2271 + x2272;
    let x2274 = dqd[0] + x2261;
    let x2275 = dqd[1] + x2267;
    let x2276 = dqd[2] + x2273;
    let x2277 = x723 * s[385];
    let x2278 = s[141] * x2274;
    let x2279 = x2277 + x2278;
    let x2280 = x724 * s[386];
    let x2281 = s[142] * x2275;
    let x2282 = x2280 + x2281;
    let x2283 = x725 * s[387];
    let x2284 = s[143] * x2276;
    let x2285 = x2283 + x2284;
    let x2286 = x2279 + x2282;
    let x2287 = x2285 + x2286;
    let x2288 = x730 * s[389];
    let x2290 = s[145] * x2287;
    let x2291 = x2290 - x2288;
    let x2398 = 2.0 * x2274;
    let x2399 = 2.0 * x2275;
    let x2400 = 2.0 * x2276;
    let x2401 = 2.0 * x2291;
    let x2402 = 2.0 * s[145];
    let x2403 = s[389] * x2402;
    let x2405 = s[209] * x2401;
    let x2406 = x813 * x2403;
    let x2408 = x2405 - x2406;
    let x2587 = 0.665885 * s[497];
    let x2588 = 0.353482 * s[512];
    let x2590 = 1.402538 * s[523];
    let x2591 = x2587 - x2588;
    let x2592 = x2590 + x2591;
    let x2593 = 0.665885 * s[524];
    let x2594 = 0.353482 * s[499];
    let x2596 = 1.402538 * s[535];
    let x2597 = x2593 - x2594;
    let x2598 = x2596 + x2597;
    let x2599 = 0.665885 * s[536];
    let x2600 = 0.353482 * s[537];
    let x2602 = 1.402538 * s[501];
    let x2603 = x2599 - x2600;
    let x2604 = x2602 + x2603;
    let x2605 = x810 * x2274;
    let x2606 = x723 * x2398;
    let x2607 = x2605 + x2606;
    let x2608 = x927 * s[385];
    let x2609 = s[141] * x2592;
    let x2610 = x2608 + x2609;
    let x2611 = x2607 + x2610;
    let x2612 = x811 * x2275;
    let x2613 = x724 * x2399;
    let x2614 = x2612 + x2613;
    let x2615 = x933 * s[386];
    let x2616 = s[142] * x2598;
    let x2617 = x2615 + x2616;
    let x2618 = x2614 + x2617;
    let x2619 = x812 * x2276;
    let x2620 = x725 * x2400;
    let x2621 = x2619 + x2620;
    let x2622 = x939 * s[387];
    let x2623 = s[143] * x2604;
    let x2624 = x2622 + x2623;
    let x2625 = x2621 + x2624;
    let x2626 = x2611 + x2618;
    let x2627 = x2625 + x2626;
    let x2628 = x815 * x2287;
    let x2629 = x730 * x2408;
    let x2630 = x2628 + x2629;
    let x2632 = x950 * s[389];
    let x2634 = s[145] * x2627;
    let x2635 = x2634 - x2632;
    let x2636 = x2635 - x2630;
    let x2739 = -x2636;
    gamma[3] = x2739;
    phi[4] = x1504;
    phi_q[24] = x1589;
    phi_q[25] = x1619;
    phi_q[26] = x1643;
}
#[inline(never)]
fn kinematic_tangents_part_4(
    s: &[f64; 538],
    phi_q: &mut [f64; 42],
    phi_t: &mut [f64; 7],
) {
    let x364 = 0.478359 * s[156];
    let x365 = 1.158742 * s[135];
    let x367 = 0.107672 * s[134];
    let x368 = x364 - x365;
    let x369 = x367 + x368;
    let x370 = 0.478359 * s[135];
    let x371 = 1.158742 * s[156];
    let x372 = 0.107672 * s[133];
    let x374 = x370 + x371;
    let x375 = x374 - x372;
    let x376 = 0.478359 * s[134];
    let x378 = 1.158742 * s[133];
    let x379 = 0.107672 * s[156];
    let x380 = x378 - x376;
    let x381 = x379 + x380;
    let x382 = s[146] * x369;
    let x383 = s[147] * x375;
    let x384 = s[148] * x381;
    let x385 = x382 + x383;
    let x386 = x384 + x385;
    let x457 = 0.478359 * s[161];
    let x458 = 1.158742 * s[134];
    let x459 = 0.107672 * s[135];
    let x460 = x457 + x458;
    let x461 = x459 + x460;
    let x462 = 0.107672 * s[132];
    let x464 = x376 - x462;
    let x465 = 1.158742 * s[132];
    let x466 = x370 + x465;
    let x467 = s[146] * x461;
    let x468 = s[147] * x464;
    let x469 = s[148] * x466;
    let x470 = x467 + x468;
    let x471 = x469 + x470;
    let x536 = x378 + x462;
    let x537 = 0.478359 * s[133];
    let x538 = 1.158742 * s[162];
    let x539 = x537 + x538;
    let x540 = x459 + x539;
    let x541 = 0.478359 * s[132];
    let x543 = x365 - x541;
    let x544 = s[146] * x536;
    let x545 = s[147] * x540;
    let x546 = s[148] * x543;
    let x547 = x544 + x545;
    let x548 = x546 + x547;
    let x592 = x372 - x465;
    let x593 = x367 + x541;
    let x594 = 0.107672 * s[163];
    let x595 = x458 + x537;
    let x596 = x594 + x595;
    let x597 = s[146] * x592;
    let x598 = s[147] * x593;
    let x599 = s[148] * x596;
    let x600 = x597 + x598;
    let x601 = x599 + x600;
    let x1728 = 0.478359 * s[400];
    let x1729 = 1.158742 * s[379];
    let x1731 = 0.107672 * s[378];
    let x1732 = x1728 - x1729;
    let x1733 = x1731 + x1732;
    let x1734 = 0.478359 * s[379];
    let x1735 = 1.158742 * s[400];
    let x1736 = 0.107672 * s[377];
    let x1738 = x1734 + x1735;
    let x1739 = x1738 - x1736;
    let x1740 = 0.478359 * s[378];
    let x1742 = 1.158742 * s[377];
    let x1743 = 0.107672 * s[400];
    let x1744 = x1742 - x1740;
    let x1745 = x1743 + x1744;
    let x1746 = x369 * s[390];
    let x1747 = s[146] * x1733;
    let x1748 = x1746 + x1747;
    let x1749 = x375 * s[391];
    let x1750 = s[147] * x1739;
    let x1751 = x1749 + x1750;
    let x1752 = x381 * s[392];
    let x1753 = s[148] * x1745;
    let x1754 = x1752 + x1753;
    let x1755 = x1748 + x1751;
    let x1756 = x1754 + x1755;
    let x1757 = x386 * s[394];
    let x1759 = s[150] * x1756;
    let x1760 = x1759 - x1757;
    let x1862 = 0.478359 * s[405];
    let x1863 = 1.158742 * s[378];
    let x1864 = 0.107672 * s[379];
    let x1865 = x1862 + x1863;
    let x1866 = x1864 + x1865;
    let x1867 = 0.107672 * s[376];
    let x1869 = x1740 - x1867;
    let x1870 = 1.158742 * s[376];
    let x1871 = x1734 + x1870;
    let x1872 = x461 * s[390];
    let x1873 = s[146] * x1866;
    let x1874 = x1872 + x1873;
    let x1875 = x464 * s[391];
    let x1876 = s[147] * x1869;
    let x1877 = x1875 + x1876;
    let x1878 = x466 * s[392];
    let x1879 = s[148] * x1871;
    let x1880 = x1878 + x1879;
    let x1881 = x1874 + x1877;
    let x1882 = x1880 + x1881;
    let x1883 = x471 * s[394];
    let x1885 = s[150] * x1882;
    let x1886 = x1885 - x1883;
    let x1976 = x1742 + x1867;
    let x1977 = 0.478359 * s[377];
    let x1978 = 1.158742 * s[406];
    let x1979 = x1977 + x1978;
    let x1980 = x1864 + x1979;
    let x1981 = 0.478359 * s[376];
    let x1983 = x1729 - x1981;
    let x1984 = x536 * s[390];
    let x1985 = s[146] * x1976;
    let x1986 = x1984 + x1985;
    let x1987 = x540 * s[391];
    let x1988 = s[147] * x1980;
    let x1989 = x1987 + x1988;
    let x1990 = x543 * s[392];
    let x1991 = s[148] * x1983;
    let x1992 = x1990 + x1991;
    let x1993 = x1986 + x1989;
    let x1994 = x1992 + x1993;
    let x1995 = x548 * s[394];
    let x1997 = s[150] * x1994;
    let x1998 = x1997 - x1995;
    let x2074 = x1736 - x1870;
    let x2075 = x1731 + x1981;
    let x2076 = 0.107672 * s[407];
    let x2077 = x1863 + x1977;
    let x2078 = x2076 + x2077;
    let x2079 = x592 * s[390];
    let x2080 = s[146] * x2074;
    let x2081 = x2079 + x2080;
    let x2082 = x593 * s[391];
    let x2083 = s[147] * x2075;
    let x2084 = x2082 + x2083;
    let x2085 = x596 * s[392];
    let x2086 = s[148] * x2078;
    let x2087 = x2085 + x2086;
    let x2088 = x2081 + x2084;
    let x2089 = x2087 + x2088;
    let x2090 = x601 * s[394];
    let x2092 = s[150] * x2089;
    let x2093 = x2092 - x2090;
    phi_q[27] = x1760;
    phi_q[28] = x1886;
    phi_q[29] = x1998;
    phi_q[30] = x2093;
    phi_t[4] = 0.0;
}
#[inline(never)]
fn kinematic_tangents_part_5(
    qd: &[f64; 7],
    dqd: &[f64; 7],
    dp: &[f64; 12],
    s: &[f64; 538],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 42],
    gamma: &mut [f64; 7],
) {
    let x732 = 0.478359 * s[169];
    let x733 = 1.158742 * s[182];
    let x734 = 0.107672 * s[191];
    let x735 = x732 + x733;
    let x736 = x734 + x735;
    let x737 = 0.478359 * s[192];
    let x738 = 1.158742 * s[171];
    let x739 = 0.107672 * s[201];
    let x740 = x737 + x738;
    let x741 = x739 + x740;
    let x742 = 0.478359 * s[202];
    let x743 = 1.158742 * s[203];
    let x744 = 0.107672 * s[173];
    let x745 = x742 + x743;
    let x746 = x744 + x745;
    let x747 = qd[0] + x736;
    let x748 = qd[1] + x741;
    let x749 = qd[2] + x746;
    let x750 = s[146] * x747;
    let x751 = s[147] * x748;
    let x752 = s[148] * x749;
    let x753 = x750 + x751;
    let x754 = x752 + x753;
    let x755 = s[150] * x754;
    let x817 = 2.0 * x747;
    let x818 = 2.0 * x748;
    let x819 = 2.0 * x749;
    let x820 = 2.0 * x755;
    let x822 = x820 * s[210];
    let x955 = 0.478359 * s[217];
    let x956 = 1.158742 * s[228];
    let x957 = 0.107672 * s[235];
    let x958 = x955 + x956;
    let x959 = x957 + x958;
    let x960 = 0.478359 * s[236];
    let x961 = 1.158742 * s[219];
    let x962 = 0.107672 * s[243];
    let x963 = x960 + x961;
    let x964 = x962 + x963;
    let x965 = 0.478359 * s[244];
    let x966 = 1.158742 * s[245];
    let x967 = 0.107672 * s[221];
    let x968 = x965 + x966;
    let x969 = x967 + x968;
    let x970 = x747 * x817;
    let x971 = s[146] * x959;
    let x972 = x970 + x971;
    let x973 = x748 * x818;
    let x974 = s[147] * x964;
    let x975 = x973 + x974;
    let x976 = x749 * x819;
    let x977 = s[148] * x969;
    let x978 = x976 + x977;
    let x979 = x972 + x975;
    let x980 = x978 + x979;
    let x1533 = s[375] - dp[11];
    let x1596 = s[155] * s[395];
    let x1597 = s[151] * s[399];
    let x1599 = x1596 - x1597;
    let x1620 = s[155] * s[396];
    let x1621 = s[152] * s[399];
    let x1623 = x1620 - x1621;
    let x1644 = s[155] * s[397];
    let x1645 = s[153] * s[399];
    let x1647 = x1644 - x1645;
    let x2292 = 0.478359 * s[421];
    let x2293 = 1.158742 * s[442];
    let x2294 = 0.107672 * s[459];
    let x2295 = x2292 + x2293;
    let x2296 = x2294 + x2295;
    let x2297 = 0.478359 * s[460];
    let x2298 = 1.158742 * s[423];
    let x2299 = 0.107672 * s[477];
    let x2300 = x2297 + x2298;
    let x2301 = x2299 + x2300;
    let x2302 = 0.478359 * s[478];
    let x2303 = 1.158742 * s[479];
    let x2304 = 0.107672 * s[425];
    let x2305 = x2302 + x2303;
    let x2306 = x2304 + x2305;
    let x2307 = dqd[0] + x2296;
    let x2308 = dqd[1] + x2301;
    let x2309 = dqd[2] + x2306;
    let x2310 = x747 * s[390];
    let x2311 = s[146] * x2307;
    let x2312 = x2310 + x2311;
    let x2313 = x748 * s[391];
    let x2314 = s[147] * x2308;
    let x2315 = x2313 + x2314;
    let x2316 = x749 * s[392];
    let x2317 = s[148] * x2309;
    let x2318 = x2316 + x2317;
    let x2319 = x2312 + x2315;
    let x2320 = x2318 + x2319;
    let x2321 = x754 * s[394];
    let x2323 = s[150] * x2320;
    let x2324 = x2323 - x2321;
    let x2409 = 2.0 * x2307;
    let x2410 = 2.0 * x2308;
    let x2411 = 2.0 * x2309;
    let x2412 = 2.0 * x2324;
    let x2413 = 2.0 * s[150];
    let x2414 = s[394] * x2413;
    let x2416 = s[210] * x2412;
    let x2417 = x820 * x2414;
    let x2419 = x2416 - x2417;
    let x2637 = 0.478359 * s[497];
    let x2638 = 1.158742 * s[512];
    let x2639 = 0.107672 * s[523];
    let x2640 = x2637 + x2638;
    let x2641 = x2639 + x2640;
    let x2642 = 0.478359 * s[524];
    let x2643 = 1.158742 * s[499];
    let x2644 = 0.107672 * s[535];
    let x2645 = x2642 + x2643;
    let x2646 = x2644 + x2645;
    let x2647 = 0.478359 * s[536];
    let x2648 = 1.158742 * s[537];
    let x2649 = 0.107672 * s[501];
    let x2650 = x2647 + x2648;
    let x2651 = x2649 + x2650;
    let x2652 = x817 * x2307;
    let x2653 = x747 * x2409;
    let x2654 = x2652 + x2653;
    let x2655 = x959 * s[390];
    let x2656 = s[146] * x2641;
    let x2657 = x2655 + x2656;
    let x2658 = x2654 + x2657;
    let x2659 = x818 * x2308;
    let x2660 = x748 * x2410;
    let x2661 = x2659 + x2660;
    let x2662 = x964 * s[391];
    let x2663 = s[147] * x2646;
    let x2664 = x2662 + x2663;
    let x2665 = x2661 + x2664;
    let x2666 = x819 * x2309;
    let x2667 = x749 * x2411;
    let x2668 = x2666 + x2667;
    let x2669 = x969 * s[392];
    let x2670 = s[148] * x2651;
    let x2671 = x2669 + x2670;
    let x2672 = x2668 + x2671;
    let x2673 = x2658 + x2665;
    let x2674 = x2672 + x2673;
    let x2675 = x822 * x2320;
    let x2676 = x754 * x2419;
    let x2677 = x2675 + x2676;
    let x2679 = x980 * s[394];
    let x2681 = s[150] * x2674;
    let x2682 = x2681 - x2679;
    let x2683 = x2682 - x2677;
    let x2740 = -x2683;
    gamma[4] = x2740;
    phi[5] = x1533;
    phi_q[31] = x1599;
    phi_q[32] = x1623;
    phi_q[33] = x1647;
}
#[inline(never)]
fn kinematic_tangents_part_6(
    s: &[f64; 538],
    phi_q: &mut [f64; 42],
    phi_t: &mut [f64; 7],
) {
    let x388 = 0.137087 * s[156];
    let x389 = 0.235121 * s[135];
    let x391 = 0.353913 * s[134];
    let x392 = x388 - x389;
    let x394 = x391 - x392;
    let x395 = 0.137087 * s[135];
    let x396 = 0.235121 * s[156];
    let x397 = 0.353913 * s[133];
    let x399 = x395 + x396;
    let x401 = x397 + x399;
    let x403 = 0.137087 * s[134];
    let x405 = 0.235121 * s[133];
    let x406 = 0.353913 * s[156];
    let x407 = x405 - x403;
    let x409 = x406 - x407;
    let x410 = s[151] * x394;
    let x411 = s[152] * x401;
    let x413 = s[153] * x409;
    let x414 = x410 - x411;
    let x415 = x413 + x414;
    let x473 = 0.137087 * s[161];
    let x474 = 0.235121 * s[134];
    let x475 = 0.353913 * s[135];
    let x476 = x473 + x474;
    let x478 = x475 - x476;
    let x479 = 0.353913 * s[132];
    let x481 = x403 + x479;
    let x483 = 0.235121 * s[132];
    let x484 = x395 + x483;
    let x486 = s[151] * x478;
    let x487 = s[152] * x481;
    let x489 = s[153] * x484;
    let x491 = x486 - x487;
    let x492 = x491 - x489;
    let x551 = x479 - x405;
    let x552 = 0.137087 * s[133];
    let x553 = 0.235121 * s[162];
    let x554 = x552 + x553;
    let x556 = x475 - x554;
    let x557 = 0.137087 * s[132];
    let x559 = x389 - x557;
    let x561 = s[151] * x551;
    let x562 = s[152] * x556;
    let x563 = s[153] * x559;
    let x565 = x561 + x562;
    let x566 = x565 - x563;
    let x604 = x397 + x483;
    let x605 = x391 - x557;
    let x606 = 0.353913 * s[163];
    let x607 = x474 + x552;
    let x609 = x606 - x607;
    let x610 = s[151] * x604;
    let x611 = s[152] * x605;
    let x612 = s[153] * x609;
    let x613 = x610 + x611;
    let x614 = x612 + x613;
    let x1761 = 0.137087 * s[400];
    let x1762 = 0.235121 * s[379];
    let x1764 = 0.353913 * s[378];
    let x1765 = x1761 - x1762;
    let x1767 = x1764 - x1765;
    let x1768 = 0.137087 * s[379];
    let x1769 = 0.235121 * s[400];
    let x1770 = 0.353913 * s[377];
    let x1771 = x1768 + x1769;
    let x1772 = x1770 + x1771;
    let x1773 = 0.137087 * s[378];
    let x1775 = 0.235121 * s[377];
    let x1776 = 0.353913 * s[400];
    let x1777 = x1775 - x1773;
    let x1779 = x1776 - x1777;
    let x1780 = x394 * s[395];
    let x1781 = s[151] * x1767;
    let x1782 = x1780 + x1781;
    let x1783 = x401 * s[396];
    let x1784 = s[152] * x1772;
    let x1785 = x1783 + x1784;
    let x1787 = x409 * s[397];
    let x1788 = s[153] * x1779;
    let x1789 = x1787 + x1788;
    let x1790 = x1782 - x1785;
    let x1791 = x1789 + x1790;
    let x1792 = x415 * s[399];
    let x1794 = s[155] * x1791;
    let x1795 = x1794 - x1792;
    let x1887 = 0.137087 * s[405];
    let x1888 = 0.235121 * s[378];
    let x1889 = 0.353913 * s[379];
    let x1890 = x1887 + x1888;
    let x1892 = x1889 - x1890;
    let x1893 = 0.353913 * s[376];
    let x1894 = x1773 + x1893;
    let x1895 = 0.235121 * s[376];
    let x1896 = x1768 + x1895;
    let x1897 = x478 * s[395];
    let x1898 = s[151] * x1892;
    let x1899 = x1897 + x1898;
    let x1900 = x481 * s[396];
    let x1901 = s[152] * x1894;
    let x1902 = x1900 + x1901;
    let x1904 = x484 * s[397];
    let x1905 = s[153] * x1896;
    let x1906 = x1904 + x1905;
    let x1908 = x1899 - x1902;
    let x1909 = x1908 - x1906;
    let x1910 = x492 * s[399];
    let x1912 = s[155] * x1909;
    let x1913 = x1912 - x1910;
    let x2000 = x1893 - x1775;
    let x2001 = 0.137087 * s[377];
    let x2002 = 0.235121 * s[406];
    let x2003 = x2001 + x2002;
    let x2005 = x1889 - x2003;
    let x2006 = 0.137087 * s[376];
    let x2008 = x1762 - x2006;
    let x2009 = x551 * s[395];
    let x2010 = s[151] * x2000;
    let x2011 = x2009 + x2010;
    let x2012 = x556 * s[396];
    let x2013 = s[152] * x2005;
    let x2014 = x2012 + x2013;
    let x2015 = x559 * s[397];
    let x2016 = s[153] * x2008;
    let x2017 = x2015 + x2016;
    let x2019 = x2011 + x2014;
    let x2020 = x2019 - x2017;
    let x2021 = x566 * s[399];
    let x2023 = s[155] * x2020;
    let x2024 = x2023 - x2021;
    let x2094 = x1770 + x1895;
    let x2095 = x1764 - x2006;
    let x2096 = 0.353913 * s[407];
    let x2097 = x1888 + x2001;
    let x2099 = x2096 - x2097;
    let x2100 = x604 * s[395];
    let x2101 = s[151] * x2094;
    let x2102 = x2100 + x2101;
    let x2103 = x605 * s[396];
    let x2104 = s[152] * x2095;
    let x2105 = x2103 + x2104;
    let x2106 = x609 * s[397];
    let x2107 = s[153] * x2099;
    let x2108 = x2106 + x2107;
    let x2109 = x2102 + x2105;
    let x2110 = x2108 + x2109;
    let x2111 = x614 * s[399];
    let x2113 = s[155] * x2110;
    let x2114 = x2113 - x2111;
    phi_q[34] = x1795;
    phi_q[35] = x1913;
    phi_q[36] = x2024;
    phi_q[37] = x2114;
    phi_t[5] = 0.0;
}
#[inline(never)]
fn kinematic_tangents_part_7(
    qd: &[f64; 7],
    dqd: &[f64; 7],
    s: &[f64; 538],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 42],
    phi_t: &mut [f64; 7],
    gamma: &mut [f64; 7],
) {
    let x756 = 0.137087 * s[169];
    let x757 = 0.235121 * s[182];
    let x758 = 0.353913 * s[191];
    let x759 = x756 + x757;
    let x761 = x758 - x759;
    let x762 = 0.137087 * s[192];
    let x763 = 0.235121 * s[171];
    let x764 = 0.353913 * s[201];
    let x765 = x762 + x763;
    let x767 = x764 - x765;
    let x768 = 0.137087 * s[202];
    let x769 = 0.235121 * s[203];
    let x770 = 0.353913 * s[173];
    let x771 = x768 + x769;
    let x773 = x770 - x771;
    let x774 = qd[0] + x761;
    let x775 = qd[1] + x767;
    let x776 = qd[2] + x773;
    let x777 = s[151] * x774;
    let x778 = s[152] * x775;
    let x779 = s[153] * x776;
    let x780 = x777 + x778;
    let x781 = x779 + x780;
    let x782 = s[155] * x781;
    let x824 = 2.0 * x774;
    let x825 = 2.0 * x775;
    let x826 = 2.0 * x776;
    let x827 = 2.0 * x782;
    let x829 = x827 * s[211];
    let x985 = 0.137087 * s[217];
    let x986 = 0.235121 * s[228];
    let x987 = 0.353913 * s[235];
    let x988 = x985 + x986;
    let x990 = x987 - x988;
    let x991 = 0.137087 * s[236];
    let x992 = 0.235121 * s[219];
    let x993 = 0.353913 * s[243];
    let x994 = x991 + x992;
    let x996 = x993 - x994;
    let x997 = 0.137087 * s[244];
    let x998 = 0.235121 * s[245];
    let x999 = 0.353913 * s[221];
    let x1000 = x997 + x998;
    let x1002 = x999 - x1000;
    let x1003 = x774 * x824;
    let x1004 = s[151] * x990;
    let x1005 = x1003 + x1004;
    let x1006 = x775 * x825;
    let x1007 = s[152] * x996;
    let x1008 = x1006 + x1007;
    let x1009 = x776 * x826;
    let x1010 = s[153] * x1002;
    let x1011 = x1009 + x1010;
    let x1012 = x1005 + x1008;
    let x1013 = x1011 + x1012;
    let x1534 = s[248] + s[250];
    let x1535 = s[249] + x1534;
    let x2325 = 0.137087 * s[421];
    let x2326 = 0.235121 * s[442];
    let x2327 = 0.353913 * s[459];
    let x2328 = x2325 + x2326;
    let x2330 = x2327 - x2328;
    let x2331 = 0.137087 * s[460];
    let x2332 = 0.235121 * s[423];
    let x2333 = 0.353913 * s[477];
    let x2334 = x2331 + x2332;
    let x2336 = x2333 - x2334;
    let x2337 = 0.137087 * s[478];
    let x2338 = 0.235121 * s[479];
    let x2339 = 0.353913 * s[425];
    let x2340 = x2337 + x2338;
    let x2342 = x2339 - x2340;
    let x2343 = dqd[0] + x2330;
    let x2344 = dqd[1] + x2336;
    let x2345 = dqd[2] + x2342;
    let x2346 = x774 * s[395];
    let x2347 = s[151] * x2343;
    let x2348 = x2346 + x2347;
    let x2349 = x775 * s[396];
    let x2350 = s[152] * x2344;
    let x2351 = x2349 + x2350;
    let x2352 = x776 * s[397];
    let x2353 = s[153] * x2345;
    let x2354 = x2352 + x2353;
    let x2355 = x2348 + x2351;
    let x2356 = x2354 + x2355;
    let x2357 = x781 * s[399];
    let x2359 = s[155] * x2356;
    let x2360 = x2359 - x2357;
    let x2420 = 2.0 * x2343;
    let x2421 = 2.0 * x2344;
    let x2422 = 2.0 * x2345;
    let x2423 = 2.0 * x2360;
    let x2424 = 2.0 * s[155];
    let x2425 = s[399] * x2424;
    let x2427 = s[211] * x2423;
    let x2428 = x827 * x2425;
    let x2430 = x2427 - x2428;
    let x2684 = 0.137087 * s[497];
    let x2685 = 0.235121 * s[512];
    let x2686 = 0.353913 * s[523];
    let x2687 = x2684 + x2685;
    let x2689 = x2686 - x2687;
    let x2690 = 0.137087 * s[524];
    let x2691 = 0.235121 * s[499];
    let x2692 = 0.353913 * s[535];
    let x2693 = x2690 + x2691;
    let x2695 = x2692 - x2693;
    let x2696 = 0.137087 * s[536];
    let x2697 = 0.235121 * s[537];
    let x2698 = 0.353913 * s[501];
    let x2699 = x2696 + x2697;
    let x2701 = x2698 - x2699;
    let x2702 = x824 * x2343;
    let x2703 = x774 * x2420;
    let x2704 = x2702 + x2703;
    let x2705 = x990 * s[395];
    let x2706 = s[151] * x2689;
    let x2707 = x2705 + x2706;
    let x2708 = x2704 + x2707;
    let x2709 = x825 * x2344;
    let x2710 = x775 * x2421;
    let x2711 = x2709 + x2710;
    let x2712 = x996 * s[396];
    let x2713 = s[152] * x2695;
    let x2714 = x2712 + x2713;
    let x2715 = x2711 + x2714;
    let x2716 = x826 * x2345;
    let x2717 = x776 * x2422;
    let x2718 = x2716 + x2717;
    let x2719 = x1002 * s[397];
    let x2720 = s[153] * x2701;
    let x2721 = x2719 + x2720;
    let x2722 = x2718 + x2721;
    let x2723 = x2708 + x2715;
    let x2724 = x2722 + x2723;
    let x2725 = x829 * x2356;
    let x2726 = x781 * x2430;
    let x2727 = x2725 + x2726;
    let x2729 = x1013 * s[399];
    let x2731 = s[155] * x2724;
    let x2732 = x2731 - x2729;
    let x2733 = x2732 - x2727;
    let x2734 = s[492] + s[496];
    let x2735 = s[495] + x2734;
    let x2741 = -x2733;
    let x2742 = -x2735;
    gamma[5] = x2741;
    phi[6] = x1535;
    phi_q[38] = s[376];
    phi_q[39] = s[377];
    phi_q[40] = s[378];
    phi_q[41] = s[379];
    phi_t[6] = 0.0;
    gamma[6] = x2742;
}
/// Number of generalized coordinates.
pub const N_COORDS: usize = 7usize;
/// Number of constraint rows.
pub const N_CONSTRAINTS: usize = 7usize;
/// Row of each Φq nonzero.
pub static PHI_Q_ROWS: [u32; 42usize] = [
    0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 1u32, 1u32, 1u32, 1u32, 2u32, 2u32, 2u32, 2u32,
    2u32, 2u32, 2u32, 3u32, 3u32, 3u32, 3u32, 3u32, 3u32, 3u32, 4u32, 4u32, 4u32, 4u32,
    4u32, 4u32, 4u32, 5u32, 5u32, 5u32, 5u32, 5u32, 5u32, 5u32, 6u32, 6u32, 6u32, 6u32,
];
/// Column of each Φq nonzero.
pub static PHI_Q_COLS: [u32; 42usize] = [
    0u32, 1u32, 2u32, 0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 0u32, 1u32, 2u32, 3u32,
    4u32, 5u32, 6u32, 0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 0u32, 1u32, 2u32, 3u32,
    4u32, 5u32, 6u32, 0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32,
];
/// Bodies in coordinate order.
pub static BODIES: [BodyInfo; 1usize] = [
    BodyInfo {
        name: "platform",
        coord_offset: 0usize,
        rotation: Rotation::Quaternion,
        mass: 1f64,
        inertia: [1f64, 1f64, 1f64],
    },
];
/// Joints in row order, then drivers.
pub static JOINTS: [JointInfo; 7usize] = [
    JointInfo {
        name: "leg1",
        kind: JointKind::Driver,
        body1: None,
        body2: Some(0usize),
        row_start: 0usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 1f64,
        effort_unit: "N",
    },
    JointInfo {
        name: "leg2",
        kind: JointKind::Driver,
        body1: None,
        body2: Some(0usize),
        row_start: 1usize,
        rows: 1usize,
        point1: [1.107915f64, 0f64, 0f64],
        point2: [0.542805f64, 0f64, 0f64],
        effort_sign: 1f64,
        effort_unit: "N",
    },
    JointInfo {
        name: "leg3",
        kind: JointKind::Driver,
        body1: None,
        body2: Some(0usize),
        row_start: 2usize,
        rows: 1usize,
        point1: [0.549094f64, 0.756063f64, 0f64],
        point2: [0.956919f64, -0.528915f64, 0f64],
        effort_sign: 1f64,
        effort_unit: "N",
    },
    JointInfo {
        name: "leg4",
        kind: JointKind::Driver,
        body1: None,
        body2: Some(0usize),
        row_start: 3usize,
        rows: 1usize,
        point1: [0.735077f64, -0.223935f64, 0.525991f64],
        point2: [0.665885f64, -0.353482f64, 1.402538f64],
        effort_sign: 1f64,
        effort_unit: "N",
    },
    JointInfo {
        name: "leg5",
        kind: JointKind::Driver,
        body1: None,
        body2: Some(0usize),
        row_start: 4usize,
        rows: 1usize,
        point1: [0.514188f64, -0.526063f64, -0.368418f64],
        point2: [0.478359f64, 1.158742f64, 0.107672f64],
        effort_sign: 1f64,
        effort_unit: "N",
    },
    JointInfo {
        name: "leg6",
        kind: JointKind::Driver,
        body1: None,
        body2: Some(0usize),
        row_start: 5usize,
        rows: 1usize,
        point1: [0.590473f64, 0.094733f64, -0.205018f64],
        point2: [-0.137087f64, -0.235121f64, 0.353913f64],
        effort_sign: 1f64,
        effort_unit: "N",
    },
    JointInfo {
        name: "platform.norm",
        kind: JointKind::Normalization,
        body1: Some(0usize),
        body2: None,
        row_start: 6usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
];
/// Name of each coordinate.
pub static COORD_NAMES: [&str; 7usize] = [
    "platform.x",
    "platform.y",
    "platform.z",
    "platform.e0",
    "platform.e1",
    "platform.e2",
    "platform.e3",
];
/// Name of each constraint row.
pub static ROW_NAMES: [&str; 7usize] = [
    "leg1",
    "leg2",
    "leg3",
    "leg4",
    "leg5",
    "leg6",
    "platform.norm",
];
/// Initial coordinates: the file's pose, assembled.
pub static Q0: [f64; 7usize] = [
    0.6361117806578849f64,
    0.7714519603665412f64,
    0.014955779982200337f64,
    0.5116908851624842f64,
    0.663453083168387f64,
    -0.008880171196940189f64,
    -0.5458237692108212f64,
];
/// Initial velocities from the file (to be projected onto the constraints).
pub static QD0: [f64; 7usize] = [0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64];
/// Constraint rows dependent on others at the initial pose (dropped by the solvers).
pub static REDUNDANT_ROWS: [u32; 0usize] = [];
/// Simulation end time suggested by the mechanism file (s).
pub const T_END: f64 = 1f64;
/// The platform held by six legs of driven length, for forward kinematics (`None`:
/// not such a mechanism).
pub const PLATFORM: Option<PlatformInfo> = Some(PlatformInfo {
    body: 0usize,
    legs: &[
        LegInfo {
            driver: "leg1",
            base: [0f64, 0f64, 0f64],
            platform: [0f64, 0f64, 0f64],
            row: 0usize,
        },
        LegInfo {
            driver: "leg2",
            base: [1.107915f64, 0f64, 0f64],
            platform: [0.542805f64, 0f64, 0f64],
            row: 1usize,
        },
        LegInfo {
            driver: "leg3",
            base: [0.549094f64, 0.756063f64, 0f64],
            platform: [0.956919f64, -0.528915f64, 0f64],
            row: 2usize,
        },
        LegInfo {
            driver: "leg4",
            base: [0.735077f64, -0.223935f64, 0.525991f64],
            platform: [0.665885f64, -0.353482f64, 1.402538f64],
            row: 3usize,
        },
        LegInfo {
            driver: "leg5",
            base: [0.514188f64, -0.526063f64, -0.368418f64],
            platform: [0.478359f64, 1.158742f64, 0.107672f64],
            row: 4usize,
        },
        LegInfo {
            driver: "leg6",
            base: [0.590473f64, 0.094733f64, -0.205018f64],
            platform: [-0.137087f64, -0.235121f64, 0.353913f64],
            row: 5usize,
        },
    ],
});
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
pub const N_K: usize = 6;
/// `setup` at the file's parameter values: what the types without parameters read.
pub static K: [f64; 6] = [
    -1f64,
    -0.645275f64,
    -1.086284f64,
    -1.503439f64,
    -1.281933f64,
    -0.771071f64,
];
/// The values the per-step functions read (`k`), from the run-time parameters `p`.
pub fn setup(p: &[f64], k: &mut [f64]) {
    let p: &[f64; 12] = p.try_into().expect("p must have 12 entries");
    let k: &mut [f64; 6] = k.try_into().expect("k must have 6 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 12], k: &mut [f64; 6]) {
    let x65 = -p[6];
    let x83 = -p[7];
    let x115 = -p[8];
    let x157 = -p[9];
    let x195 = -p[10];
    let x244 = -p[11];
    k[0] = x65;
    k[1] = x83;
    k[2] = x115;
    k[3] = x157;
    k[4] = x195;
    k[5] = x244;
}
/// The parameters the generated code takes at run time by name: the file's
/// `[parameters]` entries that reach only masses, inertias and springs' constants.
pub static PARAMETERS: [&str; 0] = [];
/// Their values in the file.
pub static PARAMETER_VALUES: [f64; 0] = [];
/// Number of values `p` holds: the parameters by name, then the model's numbers that
/// the other parameters reach (read off the file loaded at their values: `DATA`).
pub const N_P: usize = 12;
/// `p` at the file's values.
pub static P0: [f64; 12] = [
    1f64,
    0.645275f64,
    1.086284f64,
    1.503439f64,
    1.281933f64,
    0.771071f64,
    1f64,
    0.645275f64,
    1.086284f64,
    1.503439f64,
    1.281933f64,
    0.771071f64,
];
/// Where the numbers after the named parameters come from in the model (positions in
/// the generator's `slots::numbers`).
pub static DATA: [u32; 12] = [
    3u32, 4u32, 5u32, 6u32, 7u32, 8u32, 121u32, 122u32, 123u32, 124u32, 125u32, 126u32,
];
static OTHER_PARAMETERS: [&str; 6] = ["l1", "l2", "l3", "l4", "l5", "l6"];
static BODY_NAMES: [&str; 1] = ["platform"];
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
    let p: &[f64; 12] = p.try_into().expect("p must have 12 entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    let _ = p;
    mass_properties_part_0(out);
}
#[inline(never)]
fn mass_properties_part_0(out: &mut [f64; 4]) {
    out[0] = 1.0;
    out[1] = 1.0;
    out[2] = 1.0;
    out[3] = 1.0;
}
/// Each force's stiffness and damping at the run-time parameters `p`.
pub fn force_constants(p: &[f64], out: &mut [f64]) {
    let p: &[f64; 12] = p.try_into().expect("p must have 12 entries");
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
        name: "dietmaier_6_6",
        n_coords: N_COORDS,
        n_constraints: N_CONSTRAINTS,
        formulation: Formulation::Exact,
        gravity: [0f64, 0f64, 0f64],
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
    pub static KKT: [KktKernels; 1] = [
        KktKernels {
            pattern: 0x90e5a013a012db63,
            storage: 82,
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
        let mass: &[f64; 19] = mass
            .try_into()
            .map_err(|_| length_error(19, mass.len()))?;
        let phi_q: &[f64; 42] = phi_q
            .try_into()
            .map_err(|_| length_error(42, phi_q.len()))?;
        let st_len = st.len();
        let st: &mut [f64; 82] = st.try_into().map_err(|_| length_error(82, st_len))?;
        if !((c * mass[0]) > 0.0 && (c * mass[0]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[0]), 0));
        }
        let v0: f64 = (c * mass[0]).sqrt();
        let v1: f64 = 1.0 / v0;
        st[6] = v1;
        if !((c * mass[1]) > 0.0 && (c * mass[1]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[1]), 1));
        }
        let v2: f64 = (c * mass[1]).sqrt();
        let v3: f64 = 1.0 / v2;
        st[7] = v3;
        if !((c * mass[2]) > 0.0 && (c * mass[2]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[2]), 2));
        }
        let v4: f64 = (c * mass[2]).sqrt();
        let v5: f64 = 1.0 / v4;
        st[8] = v5;
        let v6: f64 = phi_q[0] * v1;
        st[13] = v6;
        let v7: f64 = phi_q[1] * v3;
        st[14] = v7;
        let v8: f64 = phi_q[2] * v5;
        st[15] = v8;
        let v9: f64 = phi_q[3] * v1;
        st[16] = v9;
        let v10: f64 = phi_q[4] * v3;
        st[17] = v10;
        let v11: f64 = phi_q[5] * v5;
        st[18] = v11;
        let v12: f64 = phi_q[10] * v1;
        st[19] = v12;
        let v13: f64 = phi_q[11] * v3;
        st[20] = v13;
        let v14: f64 = phi_q[12] * v5;
        st[21] = v14;
        let v15: f64 = phi_q[17] * v1;
        st[22] = v15;
        let v16: f64 = phi_q[18] * v3;
        st[23] = v16;
        let v17: f64 = phi_q[19] * v5;
        st[24] = v17;
        let v18: f64 = phi_q[24] * v1;
        st[25] = v18;
        let v19: f64 = phi_q[25] * v3;
        st[26] = v19;
        let v20: f64 = phi_q[26] * v5;
        st[27] = v20;
        let v21: f64 = phi_q[31] * v1;
        st[28] = v21;
        let v22: f64 = phi_q[32] * v3;
        st[29] = v22;
        let v23: f64 = phi_q[33] * v5;
        st[30] = v23;
        let v24: f64 = v6 * v6;
        let v25: f64 = v7 * v7;
        let v26: f64 = v24 + v25;
        let v27: f64 = v8 * v8;
        let v28: f64 = v26 + v27;
        let v29: f64 = v9 * v6;
        let v30: f64 = v10 * v7;
        let v31: f64 = v29 + v30;
        let v32: f64 = v11 * v8;
        let v33: f64 = v31 + v32;
        let v34: f64 = v9 * v9;
        let v35: f64 = v10 * v10;
        let v36: f64 = v34 + v35;
        let v37: f64 = v11 * v11;
        let v38: f64 = v36 + v37;
        let v39: f64 = v12 * v6;
        let v40: f64 = v13 * v7;
        let v41: f64 = v39 + v40;
        let v42: f64 = v14 * v8;
        let v43: f64 = v41 + v42;
        let v44: f64 = v12 * v9;
        let v45: f64 = v13 * v10;
        let v46: f64 = v44 + v45;
        let v47: f64 = v14 * v11;
        let v48: f64 = v46 + v47;
        let v49: f64 = v12 * v12;
        let v50: f64 = v13 * v13;
        let v51: f64 = v49 + v50;
        let v52: f64 = v14 * v14;
        let v53: f64 = v51 + v52;
        let v54: f64 = v15 * v6;
        let v55: f64 = v16 * v7;
        let v56: f64 = v54 + v55;
        let v57: f64 = v17 * v8;
        let v58: f64 = v56 + v57;
        let v59: f64 = v15 * v9;
        let v60: f64 = v16 * v10;
        let v61: f64 = v59 + v60;
        let v62: f64 = v17 * v11;
        let v63: f64 = v61 + v62;
        let v64: f64 = v15 * v12;
        let v65: f64 = v16 * v13;
        let v66: f64 = v64 + v65;
        let v67: f64 = v17 * v14;
        let v68: f64 = v66 + v67;
        let v69: f64 = v15 * v15;
        let v70: f64 = v16 * v16;
        let v71: f64 = v69 + v70;
        let v72: f64 = v17 * v17;
        let v73: f64 = v71 + v72;
        let v74: f64 = v18 * v6;
        let v75: f64 = v19 * v7;
        let v76: f64 = v74 + v75;
        let v77: f64 = v20 * v8;
        let v78: f64 = v76 + v77;
        let v79: f64 = v18 * v9;
        let v80: f64 = v19 * v10;
        let v81: f64 = v79 + v80;
        let v82: f64 = v20 * v11;
        let v83: f64 = v81 + v82;
        let v84: f64 = v18 * v12;
        let v85: f64 = v19 * v13;
        let v86: f64 = v84 + v85;
        let v87: f64 = v20 * v14;
        let v88: f64 = v86 + v87;
        let v89: f64 = v18 * v15;
        let v90: f64 = v19 * v16;
        let v91: f64 = v89 + v90;
        let v92: f64 = v20 * v17;
        let v93: f64 = v91 + v92;
        let v94: f64 = v18 * v18;
        let v95: f64 = v19 * v19;
        let v96: f64 = v94 + v95;
        let v97: f64 = v20 * v20;
        let v98: f64 = v96 + v97;
        let v99: f64 = v21 * v6;
        let v100: f64 = v22 * v7;
        let v101: f64 = v99 + v100;
        let v102: f64 = v23 * v8;
        let v103: f64 = v101 + v102;
        let v104: f64 = v21 * v9;
        let v105: f64 = v22 * v10;
        let v106: f64 = v104 + v105;
        let v107: f64 = v23 * v11;
        let v108: f64 = v106 + v107;
        let v109: f64 = v21 * v12;
        let v110: f64 = v22 * v13;
        let v111: f64 = v109 + v110;
        let v112: f64 = v23 * v14;
        let v113: f64 = v111 + v112;
        let v114: f64 = v21 * v15;
        let v115: f64 = v22 * v16;
        let v116: f64 = v114 + v115;
        let v117: f64 = v23 * v17;
        let v118: f64 = v116 + v117;
        let v119: f64 = v21 * v18;
        let v120: f64 = v22 * v19;
        let v121: f64 = v119 + v120;
        let v122: f64 = v23 * v20;
        let v123: f64 = v121 + v122;
        let v124: f64 = v21 * v21;
        let v125: f64 = v22 * v22;
        let v126: f64 = v124 + v125;
        let v127: f64 = v23 * v23;
        let v128: f64 = v126 + v127;
        if !((c * mass[3]) > 0.0 && (c * mass[3]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[3]), 3));
        }
        let v129: f64 = (c * mass[3]).sqrt();
        let v130: f64 = 1.0 / v129;
        st[9] = v130;
        let v131: f64 = (c * mass[7]) * v130;
        st[0] = v131;
        let v132: f64 = (c * mass[11]) * v130;
        st[1] = v132;
        let v133: f64 = (c * mass[15]) * v130;
        st[3] = v133;
        let v134: f64 = (c * mass[8]) - v131 * v131;
        if !(v134 > 0.0 && v134 <= f64::MAX) {
            return Err(mass_pivot_error(v134, 4));
        }
        let v135: f64 = v134.sqrt();
        let v136: f64 = 1.0 / v135;
        st[10] = v136;
        let v137: f64 = (c * mass[12]) - v132 * v131;
        let v138: f64 = v137 * v136;
        st[2] = v138;
        let v139: f64 = (c * mass[16]) - v133 * v131;
        let v140: f64 = v139 * v136;
        st[4] = v140;
        let v141: f64 = (c * mass[13]) - v132 * v132;
        let v142: f64 = v141 - v138 * v138;
        if !(v142 > 0.0 && v142 <= f64::MAX) {
            return Err(mass_pivot_error(v142, 5));
        }
        let v143: f64 = v142.sqrt();
        let v144: f64 = 1.0 / v143;
        st[11] = v144;
        let v145: f64 = (c * mass[17]) - v133 * v132;
        let v146: f64 = v145 - v140 * v138;
        let v147: f64 = v146 * v144;
        st[5] = v147;
        let v148: f64 = (c * mass[18]) - v133 * v133;
        let v149: f64 = v148 - v140 * v140;
        let v150: f64 = v149 - v147 * v147;
        if !(v150 > 0.0 && v150 <= f64::MAX) {
            return Err(mass_pivot_error(v150, 6));
        }
        let v151: f64 = v150.sqrt();
        let v152: f64 = 1.0 / v151;
        st[12] = v152;
        let v153: f64 = phi_q[6] * v130;
        st[31] = v153;
        let v154: f64 = phi_q[7] - v131 * v153;
        let v155: f64 = v154 * v136;
        st[32] = v155;
        let v156: f64 = phi_q[8] - v132 * v153;
        let v157: f64 = v156 - v138 * v155;
        let v158: f64 = v157 * v144;
        st[33] = v158;
        let v159: f64 = phi_q[9] - v133 * v153;
        let v160: f64 = v159 - v140 * v155;
        let v161: f64 = v160 - v147 * v158;
        let v162: f64 = v161 * v152;
        st[34] = v162;
        let v163: f64 = phi_q[13] * v130;
        st[35] = v163;
        let v164: f64 = phi_q[14] - v131 * v163;
        let v165: f64 = v164 * v136;
        st[36] = v165;
        let v166: f64 = phi_q[15] - v132 * v163;
        let v167: f64 = v166 - v138 * v165;
        let v168: f64 = v167 * v144;
        st[37] = v168;
        let v169: f64 = phi_q[16] - v133 * v163;
        let v170: f64 = v169 - v140 * v165;
        let v171: f64 = v170 - v147 * v168;
        let v172: f64 = v171 * v152;
        st[38] = v172;
        let v173: f64 = phi_q[20] * v130;
        st[39] = v173;
        let v174: f64 = phi_q[21] - v131 * v173;
        let v175: f64 = v174 * v136;
        st[40] = v175;
        let v176: f64 = phi_q[22] - v132 * v173;
        let v177: f64 = v176 - v138 * v175;
        let v178: f64 = v177 * v144;
        st[41] = v178;
        let v179: f64 = phi_q[23] - v133 * v173;
        let v180: f64 = v179 - v140 * v175;
        let v181: f64 = v180 - v147 * v178;
        let v182: f64 = v181 * v152;
        st[42] = v182;
        let v183: f64 = phi_q[27] * v130;
        st[43] = v183;
        let v184: f64 = phi_q[28] - v131 * v183;
        let v185: f64 = v184 * v136;
        st[44] = v185;
        let v186: f64 = phi_q[29] - v132 * v183;
        let v187: f64 = v186 - v138 * v185;
        let v188: f64 = v187 * v144;
        st[45] = v188;
        let v189: f64 = phi_q[30] - v133 * v183;
        let v190: f64 = v189 - v140 * v185;
        let v191: f64 = v190 - v147 * v188;
        let v192: f64 = v191 * v152;
        st[46] = v192;
        let v193: f64 = phi_q[34] * v130;
        st[47] = v193;
        let v194: f64 = phi_q[35] - v131 * v193;
        let v195: f64 = v194 * v136;
        st[48] = v195;
        let v196: f64 = phi_q[36] - v132 * v193;
        let v197: f64 = v196 - v138 * v195;
        let v198: f64 = v197 * v144;
        st[49] = v198;
        let v199: f64 = phi_q[37] - v133 * v193;
        let v200: f64 = v199 - v140 * v195;
        let v201: f64 = v200 - v147 * v198;
        let v202: f64 = v201 * v152;
        st[50] = v202;
        let v203: f64 = phi_q[38] * v130;
        st[51] = v203;
        let v204: f64 = phi_q[39] - v131 * v203;
        let v205: f64 = v204 * v136;
        st[52] = v205;
        let v206: f64 = phi_q[40] - v132 * v203;
        let v207: f64 = v206 - v138 * v205;
        let v208: f64 = v207 * v144;
        st[53] = v208;
        let v209: f64 = phi_q[41] - v133 * v203;
        let v210: f64 = v209 - v140 * v205;
        let v211: f64 = v210 - v147 * v208;
        let v212: f64 = v211 * v152;
        st[54] = v212;
        let v213: f64 = v153 * v153;
        let v214: f64 = v155 * v155;
        let v215: f64 = v213 + v214;
        let v216: f64 = v158 * v158;
        let v217: f64 = v215 + v216;
        let v218: f64 = v162 * v162;
        let v219: f64 = v217 + v218;
        let v220: f64 = v38 + v219;
        let v221: f64 = v163 * v153;
        let v222: f64 = v165 * v155;
        let v223: f64 = v221 + v222;
        let v224: f64 = v168 * v158;
        let v225: f64 = v223 + v224;
        let v226: f64 = v172 * v162;
        let v227: f64 = v225 + v226;
        let v228: f64 = v48 + v227;
        let v229: f64 = v163 * v163;
        let v230: f64 = v165 * v165;
        let v231: f64 = v229 + v230;
        let v232: f64 = v168 * v168;
        let v233: f64 = v231 + v232;
        let v234: f64 = v172 * v172;
        let v235: f64 = v233 + v234;
        let v236: f64 = v53 + v235;
        let v237: f64 = v173 * v153;
        let v238: f64 = v175 * v155;
        let v239: f64 = v237 + v238;
        let v240: f64 = v178 * v158;
        let v241: f64 = v239 + v240;
        let v242: f64 = v182 * v162;
        let v243: f64 = v241 + v242;
        let v244: f64 = v63 + v243;
        let v245: f64 = v173 * v163;
        let v246: f64 = v175 * v165;
        let v247: f64 = v245 + v246;
        let v248: f64 = v178 * v168;
        let v249: f64 = v247 + v248;
        let v250: f64 = v182 * v172;
        let v251: f64 = v249 + v250;
        let v252: f64 = v68 + v251;
        let v253: f64 = v173 * v173;
        let v254: f64 = v175 * v175;
        let v255: f64 = v253 + v254;
        let v256: f64 = v178 * v178;
        let v257: f64 = v255 + v256;
        let v258: f64 = v182 * v182;
        let v259: f64 = v257 + v258;
        let v260: f64 = v73 + v259;
        let v261: f64 = v183 * v153;
        let v262: f64 = v185 * v155;
        let v263: f64 = v261 + v262;
        let v264: f64 = v188 * v158;
        let v265: f64 = v263 + v264;
        let v266: f64 = v192 * v162;
        let v267: f64 = v265 + v266;
        let v268: f64 = v83 + v267;
        let v269: f64 = v183 * v163;
        let v270: f64 = v185 * v165;
        let v271: f64 = v269 + v270;
        let v272: f64 = v188 * v168;
        let v273: f64 = v271 + v272;
        let v274: f64 = v192 * v172;
        let v275: f64 = v273 + v274;
        let v276: f64 = v88 + v275;
        let v277: f64 = v183 * v173;
        let v278: f64 = v185 * v175;
        let v279: f64 = v277 + v278;
        let v280: f64 = v188 * v178;
        let v281: f64 = v279 + v280;
        let v282: f64 = v192 * v182;
        let v283: f64 = v281 + v282;
        let v284: f64 = v93 + v283;
        let v285: f64 = v183 * v183;
        let v286: f64 = v185 * v185;
        let v287: f64 = v285 + v286;
        let v288: f64 = v188 * v188;
        let v289: f64 = v287 + v288;
        let v290: f64 = v192 * v192;
        let v291: f64 = v289 + v290;
        let v292: f64 = v98 + v291;
        let v293: f64 = v193 * v153;
        let v294: f64 = v195 * v155;
        let v295: f64 = v293 + v294;
        let v296: f64 = v198 * v158;
        let v297: f64 = v295 + v296;
        let v298: f64 = v202 * v162;
        let v299: f64 = v297 + v298;
        let v300: f64 = v108 + v299;
        let v301: f64 = v193 * v163;
        let v302: f64 = v195 * v165;
        let v303: f64 = v301 + v302;
        let v304: f64 = v198 * v168;
        let v305: f64 = v303 + v304;
        let v306: f64 = v202 * v172;
        let v307: f64 = v305 + v306;
        let v308: f64 = v113 + v307;
        let v309: f64 = v193 * v173;
        let v310: f64 = v195 * v175;
        let v311: f64 = v309 + v310;
        let v312: f64 = v198 * v178;
        let v313: f64 = v311 + v312;
        let v314: f64 = v202 * v182;
        let v315: f64 = v313 + v314;
        let v316: f64 = v118 + v315;
        let v317: f64 = v193 * v183;
        let v318: f64 = v195 * v185;
        let v319: f64 = v317 + v318;
        let v320: f64 = v198 * v188;
        let v321: f64 = v319 + v320;
        let v322: f64 = v202 * v192;
        let v323: f64 = v321 + v322;
        let v324: f64 = v123 + v323;
        let v325: f64 = v193 * v193;
        let v326: f64 = v195 * v195;
        let v327: f64 = v325 + v326;
        let v328: f64 = v198 * v198;
        let v329: f64 = v327 + v328;
        let v330: f64 = v202 * v202;
        let v331: f64 = v329 + v330;
        let v332: f64 = v128 + v331;
        let v333: f64 = v203 * v153;
        let v334: f64 = v205 * v155;
        let v335: f64 = v333 + v334;
        let v336: f64 = v208 * v158;
        let v337: f64 = v335 + v336;
        let v338: f64 = v212 * v162;
        let v339: f64 = v337 + v338;
        let v340: f64 = v203 * v163;
        let v341: f64 = v205 * v165;
        let v342: f64 = v340 + v341;
        let v343: f64 = v208 * v168;
        let v344: f64 = v342 + v343;
        let v345: f64 = v212 * v172;
        let v346: f64 = v344 + v345;
        let v347: f64 = v203 * v173;
        let v348: f64 = v205 * v175;
        let v349: f64 = v347 + v348;
        let v350: f64 = v208 * v178;
        let v351: f64 = v349 + v350;
        let v352: f64 = v212 * v182;
        let v353: f64 = v351 + v352;
        let v354: f64 = v203 * v183;
        let v355: f64 = v205 * v185;
        let v356: f64 = v354 + v355;
        let v357: f64 = v208 * v188;
        let v358: f64 = v356 + v357;
        let v359: f64 = v212 * v192;
        let v360: f64 = v358 + v359;
        let v361: f64 = v203 * v193;
        let v362: f64 = v205 * v195;
        let v363: f64 = v361 + v362;
        let v364: f64 = v208 * v198;
        let v365: f64 = v363 + v364;
        let v366: f64 = v212 * v202;
        let v367: f64 = v365 + v366;
        let v368: f64 = v203 * v203;
        let v369: f64 = v205 * v205;
        let v370: f64 = v368 + v369;
        let v371: f64 = v208 * v208;
        let v372: f64 = v370 + v371;
        let v373: f64 = v212 * v212;
        let v374: f64 = v372 + v373;
        let (v375, v376) = piv.pivot(v374, v374, 6, false)?;
        st[75] = v375;
        let v377: f64 = v339 * v375;
        st[55] = v377;
        let v378: f64 = v220 - v377 * v376 * v377;
        let v379: f64 = v346 * v375;
        st[56] = v379;
        let v380: f64 = v236 - v379 * v376 * v379;
        let v381: f64 = v353 * v375;
        st[57] = v381;
        let v382: f64 = v260 - v381 * v376 * v381;
        let v383: f64 = v360 * v375;
        st[58] = v383;
        let v384: f64 = v292 - v383 * v376 * v383;
        let v385: f64 = v367 * v375;
        st[59] = v385;
        let v386: f64 = v332 - v385 * v376 * v385;
        let v387: f64 = v228 - v379 * v376 * v377;
        let v388: f64 = v244 - v381 * v376 * v377;
        let v389: f64 = v252 - v381 * v376 * v379;
        let v390: f64 = v268 - v383 * v376 * v377;
        let v391: f64 = v276 - v383 * v376 * v379;
        let v392: f64 = v284 - v383 * v376 * v381;
        let v393: f64 = v300 - v385 * v376 * v377;
        let v394: f64 = v308 - v385 * v376 * v379;
        let v395: f64 = v316 - v385 * v376 * v381;
        let v396: f64 = v324 - v385 * v376 * v383;
        let (v397, v398) = piv.pivot(v28, v28, 0, false)?;
        st[76] = v397;
        let v399: f64 = v33 * v397;
        st[60] = v399;
        let v400: f64 = v378 - v399 * v398 * v399;
        let v401: f64 = v43 * v397;
        st[61] = v401;
        let v402: f64 = v380 - v401 * v398 * v401;
        let v403: f64 = v58 * v397;
        st[62] = v403;
        let v404: f64 = v382 - v403 * v398 * v403;
        let v405: f64 = v78 * v397;
        st[63] = v405;
        let v406: f64 = v384 - v405 * v398 * v405;
        let v407: f64 = v103 * v397;
        st[64] = v407;
        let v408: f64 = v386 - v407 * v398 * v407;
        let v409: f64 = v387 - v401 * v398 * v399;
        let v410: f64 = v388 - v403 * v398 * v399;
        let v411: f64 = v389 - v403 * v398 * v401;
        let v412: f64 = v390 - v405 * v398 * v399;
        let v413: f64 = v391 - v405 * v398 * v401;
        let v414: f64 = v392 - v405 * v398 * v403;
        let v415: f64 = v393 - v407 * v398 * v399;
        let v416: f64 = v394 - v407 * v398 * v401;
        let v417: f64 = v395 - v407 * v398 * v403;
        let v418: f64 = v396 - v407 * v398 * v405;
        let (v419, v420) = piv.pivot(v400, v378, 1, false)?;
        st[77] = v419;
        let v421: f64 = v409 * v419;
        st[65] = v421;
        let v422: f64 = v402 - v421 * v420 * v421;
        let v423: f64 = v410 * v419;
        st[66] = v423;
        let v424: f64 = v404 - v423 * v420 * v423;
        let v425: f64 = v412 * v419;
        st[67] = v425;
        let v426: f64 = v406 - v425 * v420 * v425;
        let v427: f64 = v415 * v419;
        st[68] = v427;
        let v428: f64 = v408 - v427 * v420 * v427;
        let v429: f64 = v411 - v423 * v420 * v421;
        let v430: f64 = v413 - v425 * v420 * v421;
        let v431: f64 = v414 - v425 * v420 * v423;
        let v432: f64 = v416 - v427 * v420 * v421;
        let v433: f64 = v417 - v427 * v420 * v423;
        let v434: f64 = v418 - v427 * v420 * v425;
        let (v435, v436) = piv.pivot(v422, v380, 2, false)?;
        st[78] = v435;
        let v437: f64 = v429 * v435;
        st[69] = v437;
        let v438: f64 = v424 - v437 * v436 * v437;
        let v439: f64 = v430 * v435;
        st[70] = v439;
        let v440: f64 = v426 - v439 * v436 * v439;
        let v441: f64 = v432 * v435;
        st[71] = v441;
        let v442: f64 = v428 - v441 * v436 * v441;
        let v443: f64 = v431 - v439 * v436 * v437;
        let v444: f64 = v433 - v441 * v436 * v437;
        let v445: f64 = v434 - v441 * v436 * v439;
        let (v446, v447) = piv.pivot(v438, v382, 3, false)?;
        st[79] = v446;
        let v448: f64 = v443 * v446;
        st[72] = v448;
        let v449: f64 = v440 - v448 * v447 * v448;
        let v450: f64 = v444 * v446;
        st[73] = v450;
        let v451: f64 = v442 - v450 * v447 * v450;
        let v452: f64 = v445 - v450 * v447 * v448;
        let (v453, v454) = piv.pivot(v449, v384, 4, false)?;
        st[80] = v453;
        let v455: f64 = v452 * v453;
        st[74] = v455;
        let v456: f64 = v451 - v455 * v454 * v455;
        let (v457, v458) = piv.pivot(v456, v386, 5, false)?;
        st[81] = v457;
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
        let f: &[f64; 7] = f.try_into().map_err(|_| length_error(7, f.len()))?;
        let g: &[f64; 7] = g.try_into().map_err(|_| length_error(7, g.len()))?;
        let x_len = x.len();
        let x: &mut [f64; 7] = x.try_into().map_err(|_| length_error(7, x_len))?;
        let y_len = y.len();
        let y: &mut [f64; 7] = y.try_into().map_err(|_| length_error(7, y_len))?;
        let st: &[f64; 82] = st.try_into().map_err(|_| length_error(82, st.len()))?;
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
            let v3: f64 = v0 * st[6];
            let v4: f64 = v1 * st[7];
            let v5: f64 = v2 * st[8];
            let v6: f64 = st[13] * v3;
            let v7: f64 = st[14] * v4;
            let v8: f64 = v6 + v7;
            let v9: f64 = st[15] * v5;
            let v10: f64 = v8 + v9;
            y[0] += v10;
            let v11: f64 = st[16] * v3;
            let v12: f64 = st[17] * v4;
            let v13: f64 = v11 + v12;
            let v14: f64 = st[18] * v5;
            let v15: f64 = v13 + v14;
            y[1] += v15;
            let v16: f64 = st[19] * v3;
            let v17: f64 = st[20] * v4;
            let v18: f64 = v16 + v17;
            let v19: f64 = st[21] * v5;
            let v20: f64 = v18 + v19;
            y[2] += v20;
            let v21: f64 = st[22] * v3;
            let v22: f64 = st[23] * v4;
            let v23: f64 = v21 + v22;
            let v24: f64 = st[24] * v5;
            let v25: f64 = v23 + v24;
            y[3] += v25;
            let v26: f64 = st[25] * v3;
            let v27: f64 = st[26] * v4;
            let v28: f64 = v26 + v27;
            let v29: f64 = st[27] * v5;
            let v30: f64 = v28 + v29;
            y[4] += v30;
            let v31: f64 = st[28] * v3;
            let v32: f64 = st[29] * v4;
            let v33: f64 = v31 + v32;
            let v34: f64 = st[30] * v5;
            let v35: f64 = v33 + v34;
            y[5] += v35;
            x[0] = v3;
            x[1] = v4;
            x[2] = v5;
            let v36: f64 = f[3];
            let v37: f64 = f[4];
            let v38: f64 = f[5];
            let v39: f64 = f[6];
            let v40: f64 = v36 * st[9];
            let v41: f64 = v37 - st[0] * v40;
            let v42: f64 = v41 * st[10];
            let v43: f64 = v38 - st[1] * v40;
            let v44: f64 = v43 - st[2] * v42;
            let v45: f64 = v44 * st[11];
            let v46: f64 = v39 - st[3] * v40;
            let v47: f64 = v46 - st[4] * v42;
            let v48: f64 = v47 - st[5] * v45;
            let v49: f64 = v48 * st[12];
            let v50: f64 = st[31] * v40;
            let v51: f64 = st[32] * v42;
            let v52: f64 = v50 + v51;
            let v53: f64 = st[33] * v45;
            let v54: f64 = v52 + v53;
            let v55: f64 = st[34] * v49;
            let v56: f64 = v54 + v55;
            y[1] += v56;
            let v57: f64 = st[35] * v40;
            let v58: f64 = st[36] * v42;
            let v59: f64 = v57 + v58;
            let v60: f64 = st[37] * v45;
            let v61: f64 = v59 + v60;
            let v62: f64 = st[38] * v49;
            let v63: f64 = v61 + v62;
            y[2] += v63;
            let v64: f64 = st[39] * v40;
            let v65: f64 = st[40] * v42;
            let v66: f64 = v64 + v65;
            let v67: f64 = st[41] * v45;
            let v68: f64 = v66 + v67;
            let v69: f64 = st[42] * v49;
            let v70: f64 = v68 + v69;
            y[3] += v70;
            let v71: f64 = st[43] * v40;
            let v72: f64 = st[44] * v42;
            let v73: f64 = v71 + v72;
            let v74: f64 = st[45] * v45;
            let v75: f64 = v73 + v74;
            let v76: f64 = st[46] * v49;
            let v77: f64 = v75 + v76;
            y[4] += v77;
            let v78: f64 = st[47] * v40;
            let v79: f64 = st[48] * v42;
            let v80: f64 = v78 + v79;
            let v81: f64 = st[49] * v45;
            let v82: f64 = v80 + v81;
            let v83: f64 = st[50] * v49;
            let v84: f64 = v82 + v83;
            y[5] += v84;
            let v85: f64 = st[51] * v40;
            let v86: f64 = st[52] * v42;
            let v87: f64 = v85 + v86;
            let v88: f64 = st[53] * v45;
            let v89: f64 = v87 + v88;
            let v90: f64 = st[54] * v49;
            let v91: f64 = v89 + v90;
            y[6] += v91;
            x[3] = v40;
            x[4] = v42;
            x[5] = v45;
            x[6] = v49;
        }
        let v92: f64 = y[1] - st[55] * y[6];
        let v93: f64 = y[2] - st[56] * y[6];
        let v94: f64 = y[3] - st[57] * y[6];
        let v95: f64 = y[4] - st[58] * y[6];
        let v96: f64 = y[5] - st[59] * y[6];
        let v97: f64 = v92 - st[60] * y[0];
        let v98: f64 = v93 - st[61] * y[0];
        let v99: f64 = v94 - st[62] * y[0];
        let v100: f64 = v95 - st[63] * y[0];
        let v101: f64 = v96 - st[64] * y[0];
        let v102: f64 = v98 - st[65] * v97;
        let v103: f64 = v99 - st[66] * v97;
        let v104: f64 = v100 - st[67] * v97;
        let v105: f64 = v101 - st[68] * v97;
        let v106: f64 = v103 - st[69] * v102;
        let v107: f64 = v104 - st[70] * v102;
        let v108: f64 = v105 - st[71] * v102;
        let v109: f64 = v107 - st[72] * v106;
        let v110: f64 = v108 - st[73] * v106;
        let v111: f64 = v110 - st[74] * v109;
        let v112: f64 = y[6] * st[75];
        let v113: f64 = y[0] * st[76];
        let v114: f64 = v97 * st[77];
        let v115: f64 = v102 * st[78];
        let v116: f64 = v106 * st[79];
        let v117: f64 = v109 * st[80];
        let v118: f64 = v111 * st[81];
        let v119: f64 = v117 - st[74] * v118;
        let v120: f64 = v116 - st[72] * v119;
        let v121: f64 = v120 - st[73] * v118;
        let v122: f64 = v115 - st[69] * v121;
        let v123: f64 = v122 - st[70] * v119;
        let v124: f64 = v123 - st[71] * v118;
        let v125: f64 = v114 - st[65] * v124;
        let v126: f64 = v125 - st[66] * v121;
        let v127: f64 = v126 - st[67] * v119;
        let v128: f64 = v127 - st[68] * v118;
        let v129: f64 = v113 - st[60] * v128;
        let v130: f64 = v129 - st[61] * v124;
        let v131: f64 = v130 - st[62] * v121;
        let v132: f64 = v131 - st[63] * v119;
        let v133: f64 = v132 - st[64] * v118;
        let v134: f64 = v112 - st[55] * v128;
        let v135: f64 = v134 - st[56] * v124;
        let v136: f64 = v135 - st[57] * v121;
        let v137: f64 = v136 - st[58] * v119;
        let v138: f64 = v137 - st[59] * v118;
        y[6] = v138;
        y[0] = v133;
        y[1] = v128;
        y[2] = v124;
        y[3] = v121;
        y[4] = v119;
        y[5] = v118;
        let v139: f64 = x[0] - st[13] * v133;
        let v140: f64 = x[1] - st[14] * v133;
        let v141: f64 = x[2] - st[15] * v133;
        let v142: f64 = v139 - st[16] * v128;
        let v143: f64 = v140 - st[17] * v128;
        let v144: f64 = v141 - st[18] * v128;
        let v145: f64 = v142 - st[19] * v124;
        let v146: f64 = v143 - st[20] * v124;
        let v147: f64 = v144 - st[21] * v124;
        let v148: f64 = v145 - st[22] * v121;
        let v149: f64 = v146 - st[23] * v121;
        let v150: f64 = v147 - st[24] * v121;
        let v151: f64 = v148 - st[25] * v119;
        let v152: f64 = v149 - st[26] * v119;
        let v153: f64 = v150 - st[27] * v119;
        let v154: f64 = v151 - st[28] * v118;
        let v155: f64 = v152 - st[29] * v118;
        let v156: f64 = v153 - st[30] * v118;
        let v157: f64 = v156 * st[8];
        let v158: f64 = v155 * st[7];
        let v159: f64 = v154 * st[6];
        x[0] = v159;
        x[1] = v158;
        x[2] = v157;
        let v160: f64 = x[3] - st[31] * v128;
        let v161: f64 = x[4] - st[32] * v128;
        let v162: f64 = x[5] - st[33] * v128;
        let v163: f64 = x[6] - st[34] * v128;
        let v164: f64 = v160 - st[35] * v124;
        let v165: f64 = v161 - st[36] * v124;
        let v166: f64 = v162 - st[37] * v124;
        let v167: f64 = v163 - st[38] * v124;
        let v168: f64 = v164 - st[39] * v121;
        let v169: f64 = v165 - st[40] * v121;
        let v170: f64 = v166 - st[41] * v121;
        let v171: f64 = v167 - st[42] * v121;
        let v172: f64 = v168 - st[43] * v119;
        let v173: f64 = v169 - st[44] * v119;
        let v174: f64 = v170 - st[45] * v119;
        let v175: f64 = v171 - st[46] * v119;
        let v176: f64 = v172 - st[47] * v118;
        let v177: f64 = v173 - st[48] * v118;
        let v178: f64 = v174 - st[49] * v118;
        let v179: f64 = v175 - st[50] * v118;
        let v180: f64 = v176 - st[51] * v138;
        let v181: f64 = v177 - st[52] * v138;
        let v182: f64 = v178 - st[53] * v138;
        let v183: f64 = v179 - st[54] * v138;
        let v184: f64 = v183 * st[12];
        let v185: f64 = v182 - st[5] * v184;
        let v186: f64 = v185 * st[11];
        let v187: f64 = v181 - st[2] * v186;
        let v188: f64 = v187 - st[4] * v184;
        let v189: f64 = v188 * st[10];
        let v190: f64 = v180 - st[0] * v189;
        let v191: f64 = v190 - st[1] * v186;
        let v192: f64 = v191 - st[3] * v184;
        let v193: f64 = v192 * st[9];
        x[3] = v193;
        x[4] = v189;
        x[5] = v186;
        x[6] = v184;
        Ok(())
    }
    fn kkt_transpose_times(
        phi_q: &[f64],
        y: &[f64],
        out: &mut [f64],
    ) -> Result<(), KktError> {
        let phi_q: &[f64; 42] = phi_q
            .try_into()
            .map_err(|_| length_error(42, phi_q.len()))?;
        let y: &[f64; 7] = y.try_into().map_err(|_| length_error(7, y.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 7] = out.try_into().map_err(|_| length_error(7, out_len))?;
        out[0] = phi_q[0] * y[0] + phi_q[3] * y[1] + phi_q[10] * y[2] + phi_q[17] * y[3]
            + phi_q[24] * y[4] + phi_q[31] * y[5];
        out[1] = phi_q[1] * y[0] + phi_q[4] * y[1] + phi_q[11] * y[2] + phi_q[18] * y[3]
            + phi_q[25] * y[4] + phi_q[32] * y[5];
        out[2] = phi_q[2] * y[0] + phi_q[5] * y[1] + phi_q[12] * y[2] + phi_q[19] * y[3]
            + phi_q[26] * y[4] + phi_q[33] * y[5];
        out[3] = phi_q[6] * y[1] + phi_q[13] * y[2] + phi_q[20] * y[3] + phi_q[27] * y[4]
            + phi_q[34] * y[5] + phi_q[38] * y[6];
        out[4] = phi_q[7] * y[1] + phi_q[14] * y[2] + phi_q[21] * y[3] + phi_q[28] * y[4]
            + phi_q[35] * y[5] + phi_q[39] * y[6];
        out[5] = phi_q[8] * y[1] + phi_q[15] * y[2] + phi_q[22] * y[3] + phi_q[29] * y[4]
            + phi_q[36] * y[5] + phi_q[40] * y[6];
        out[6] = phi_q[9] * y[1] + phi_q[16] * y[2] + phi_q[23] * y[3] + phi_q[30] * y[4]
            + phi_q[37] * y[5] + phi_q[41] * y[6];
        Ok(())
    }
    #[allow(clippy::assign_op_pattern)]
    fn kkt_times_add(phi_q: &[f64], x: &[f64], out: &mut [f64]) -> Result<(), KktError> {
        let phi_q: &[f64; 42] = phi_q
            .try_into()
            .map_err(|_| length_error(42, phi_q.len()))?;
        let x: &[f64; 7] = x.try_into().map_err(|_| length_error(7, x.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 7] = out.try_into().map_err(|_| length_error(7, out_len))?;
        out[0] = out[0] + phi_q[0] * x[0] + phi_q[1] * x[1] + phi_q[2] * x[2];
        out[1] = out[1] + phi_q[3] * x[0] + phi_q[4] * x[1] + phi_q[5] * x[2]
            + phi_q[6] * x[3] + phi_q[7] * x[4] + phi_q[8] * x[5] + phi_q[9] * x[6];
        out[2] = out[2] + phi_q[10] * x[0] + phi_q[11] * x[1] + phi_q[12] * x[2]
            + phi_q[13] * x[3] + phi_q[14] * x[4] + phi_q[15] * x[5] + phi_q[16] * x[6];
        out[3] = out[3] + phi_q[17] * x[0] + phi_q[18] * x[1] + phi_q[19] * x[2]
            + phi_q[20] * x[3] + phi_q[21] * x[4] + phi_q[22] * x[5] + phi_q[23] * x[6];
        out[4] = out[4] + phi_q[24] * x[0] + phi_q[25] * x[1] + phi_q[26] * x[2]
            + phi_q[27] * x[3] + phi_q[28] * x[4] + phi_q[29] * x[5] + phi_q[30] * x[6];
        out[5] = out[5] + phi_q[31] * x[0] + phi_q[32] * x[1] + phi_q[33] * x[2]
            + phi_q[34] * x[3] + phi_q[35] * x[4] + phi_q[36] * x[5] + phi_q[37] * x[6];
        out[6] = out[6] + phi_q[38] * x[3] + phi_q[39] * x[4] + phi_q[40] * x[5]
            + phi_q[41] * x[6];
        Ok(())
    }
    fn kkt_mass_times(mass: &[f64], v: &[f64], out: &mut [f64]) -> Result<(), KktError> {
        let mass: &[f64; 19] = mass
            .try_into()
            .map_err(|_| length_error(19, mass.len()))?;
        let v: &[f64; 7] = v.try_into().map_err(|_| length_error(7, v.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 7] = out.try_into().map_err(|_| length_error(7, out_len))?;
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
        Ok(())
    }
    fn kkt_kinetic_energy(mass: &[f64], qd: &[f64]) -> Result<f64, KktError> {
        let mass: &[f64; 19] = mass
            .try_into()
            .map_err(|_| length_error(19, mass.len()))?;
        let qd: &[f64; 7] = qd.try_into().map_err(|_| length_error(7, qd.len()))?;
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
        let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
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
        let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
        let _ = k;
        mass_part_0(q, out);
    }
    #[inline(never)]
    fn mass_part_0(q: &[f64; 7], out: &mut [f64; 19]) {
        let x20 = q[3] * q[3];
        let x21 = q[4] * q[4];
        let x22 = q[5] * q[5];
        let x23 = q[6] * q[6];
        let x34 = q[4] * q[5];
        let x36 = q[3] * q[6];
        let x41 = q[4] * q[6];
        let x43 = q[3] * q[5];
        let x47 = q[5] * q[6];
        let x49 = q[3] * q[4];
        let x249 = q[3] * 2.0;
        let x250 = q[4] * 2.0;
        let x251 = q[5] * 2.0;
        let x252 = q[6] * 2.0;
        let x301 = 2.0 * x249;
        let x417 = 2.0 * x250;
        let x494 = 2.0 * x251;
        let x568 = 2.0 * x252;
        let x1113 = x250 * x417;
        let x1115 = x251 * x494;
        let x1117 = x252 * x568;
        let x1119 = x1113 + x1115;
        let x1121 = x1117 + x1119;
        let x1123 = 0.5 * x1121;
        let x1125 = x20 * 4.0;
        let x1126 = x1123 + x1125;
        let x1127 = x250 * x301;
        let x1128 = x251 * x568;
        let x1130 = x252 * x494;
        let x1131 = x1127 - x1128;
        let x1132 = x1130 + x1131;
        let x1133 = 0.5 * x1132;
        let x1135 = x49 * 4.0;
        let x1136 = x1135 - x1133;
        let x1137 = x250 * x568;
        let x1138 = x251 * x301;
        let x1139 = x252 * x417;
        let x1141 = x1137 + x1138;
        let x1142 = x1141 - x1139;
        let x1143 = 0.5 * x1142;
        let x1145 = x43 * 4.0;
        let x1146 = x1145 - x1143;
        let x1147 = x250 * x494;
        let x1149 = x251 * x417;
        let x1150 = x252 * x301;
        let x1151 = x1149 - x1147;
        let x1152 = x1150 + x1151;
        let x1153 = 0.5 * x1152;
        let x1155 = x36 * 4.0;
        let x1156 = x1155 - x1153;
        let x1157 = x249 * x417;
        let x1160 = x1130 - x1157;
        let x1161 = x1160 - x1128;
        let x1162 = 0.5 * x1161;
        let x1163 = x1135 + x1162;
        let x1164 = x249 * x301;
        let x1165 = x1117 + x1164;
        let x1166 = x1115 + x1165;
        let x1167 = 0.5 * x1166;
        let x1168 = x21 * 4.0;
        let x1169 = x1167 + x1168;
        let x1170 = x249 * x568;
        let x1173 = x1170 - x1150;
        let x1174 = x1173 - x1149;
        let x1175 = 0.5 * x1174;
        let x1176 = x34 * 4.0;
        let x1177 = x1175 + x1176;
        let x1178 = x249 * x494;
        let x1180 = x1139 + x1178;
        let x1182 = x1138 - x1180;
        let x1183 = 0.5 * x1182;
        let x1184 = x41 * 4.0;
        let x1185 = x1183 + x1184;
        let x1187 = x1137 - x1180;
        let x1188 = 0.5 * x1187;
        let x1189 = x1145 + x1188;
        let x1191 = x1150 - x1170;
        let x1192 = x1191 - x1147;
        let x1193 = 0.5 * x1192;
        let x1194 = x1176 + x1193;
        let x1195 = x1113 + x1165;
        let x1196 = 0.5 * x1195;
        let x1197 = x22 * 4.0;
        let x1198 = x1196 + x1197;
        let x1200 = x1157 - x1130;
        let x1201 = x1200 - x1127;
        let x1202 = 0.5 * x1201;
        let x1203 = x47 * 4.0;
        let x1204 = x1202 + x1203;
        let x1205 = x1151 - x1170;
        let x1206 = 0.5 * x1205;
        let x1207 = x1155 + x1206;
        let x1210 = x1178 - x1141;
        let x1211 = 0.5 * x1210;
        let x1212 = x1184 + x1211;
        let x1213 = x1131 - x1157;
        let x1214 = 0.5 * x1213;
        let x1215 = x1203 + x1214;
        let x1216 = x1119 + x1164;
        let x1217 = 0.5 * x1216;
        let x1218 = x23 * 4.0;
        let x1219 = x1217 + x1218;
        out[0] = 1.0;
        out[1] = 1.0;
        out[2] = 1.0;
        out[3] = x1126;
        out[4] = x1136;
        out[5] = x1146;
        out[6] = x1156;
        out[7] = x1163;
        out[8] = x1169;
        out[9] = x1177;
        out[10] = x1185;
        out[11] = x1189;
        out[12] = x1194;
        out[13] = x1198;
        out[14] = x1204;
        out[15] = x1207;
        out[16] = x1212;
        out[17] = x1215;
        out[18] = x1219;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
        let _ = k;
        let _ = t;
        force_part_0(q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(q: &[f64; 7], qd: &[f64; 7], out: &mut [f64; 7]) {
        let x249 = q[3] * 2.0;
        let x250 = q[4] * 2.0;
        let x251 = q[5] * 2.0;
        let x252 = q[6] * 2.0;
        let x633 = q[5] * qd[4];
        let x634 = q[4] * qd[5];
        let x637 = q[6] * qd[3];
        let x638 = q[3] * qd[6];
        let x643 = q[6] * qd[4];
        let x644 = q[4] * qd[6];
        let x647 = q[5] * qd[3];
        let x648 = q[3] * qd[5];
        let x653 = q[6] * qd[5];
        let x654 = q[5] * qd[6];
        let x657 = q[4] * qd[3];
        let x658 = q[3] * qd[4];
        let x785 = 2.0 * qd[3];
        let x786 = 2.0 * qd[4];
        let x787 = 2.0 * qd[5];
        let x788 = 2.0 * qd[6];
        let x841 = qd[4] * qd[5];
        let x844 = qd[3] * qd[6];
        let x849 = qd[4] * qd[6];
        let x852 = qd[3] * qd[5];
        let x1036 = x658 - x657;
        let x1037 = x653 + x1036;
        let x1038 = x1037 - x654;
        let x1039 = 2.0 * x1038;
        let x1042 = x643 + x647;
        let x1044 = x648 - x1042;
        let x1045 = x644 + x1044;
        let x1046 = 2.0 * x1045;
        let x1049 = x633 - x637;
        let x1050 = x1049 - x634;
        let x1051 = x638 + x1050;
        let x1052 = 2.0 * x1051;
        let x1065 = 2.0 * x1039;
        let x1066 = 2.0 * x1046;
        let x1067 = 2.0 * x1052;
        let x1222 = x849 + x852;
        let x1224 = x852 - x1222;
        let x1225 = x849 + x1224;
        let x1226 = 2.0 * x1225;
        let x1229 = x841 - x844;
        let x1230 = x1229 - x841;
        let x1231 = x844 + x1230;
        let x1232 = 2.0 * x1231;
        let x1233 = 2.0 * x1226;
        let x1234 = 2.0 * x1232;
        let x1235 = x786 * x1065;
        let x1236 = x787 * x1066;
        let x1237 = x251 * x1233;
        let x1238 = x1236 + x1237;
        let x1239 = x788 * x1067;
        let x1240 = x252 * x1234;
        let x1241 = x1239 + x1240;
        let x1242 = x1235 + x1238;
        let x1243 = x1241 + x1242;
        let x1244 = 0.5 * x1243;
        let x1246 = x785 * x1065;
        let x1247 = x788 * x1066;
        let x1248 = x252 * x1233;
        let x1249 = x1247 + x1248;
        let x1251 = x787 * x1067;
        let x1252 = x251 * x1234;
        let x1253 = x1251 + x1252;
        let x1254 = x1246 - x1249;
        let x1255 = x1253 + x1254;
        let x1256 = 0.5 * x1255;
        let x1257 = x788 * x1065;
        let x1258 = x785 * x1066;
        let x1259 = x249 * x1233;
        let x1260 = x1258 + x1259;
        let x1261 = x786 * x1067;
        let x1262 = x250 * x1234;
        let x1263 = x1261 + x1262;
        let x1265 = x1257 + x1260;
        let x1266 = x1265 - x1263;
        let x1267 = 0.5 * x1266;
        let x1268 = x787 * x1065;
        let x1270 = x786 * x1066;
        let x1271 = x250 * x1233;
        let x1272 = x1270 + x1271;
        let x1273 = x785 * x1067;
        let x1274 = x249 * x1234;
        let x1275 = x1273 + x1274;
        let x1276 = x1272 - x1268;
        let x1277 = x1275 + x1276;
        let x1278 = 0.5 * x1277;
        let x1279 = qd[3] * qd[3];
        let x1280 = qd[4] * qd[4];
        let x1281 = qd[5] * qd[5];
        let x1282 = qd[6] * qd[6];
        let x1283 = x1279 + x1280;
        let x1284 = x1281 + x1283;
        let x1285 = x1282 + x1284;
        let x1286 = x1235 + x1236;
        let x1287 = x1239 + x1286;
        let x1288 = 0.5 * x1287;
        let x1289 = x1244 + x1288;
        let x1290 = q[3] * 4.0;
        let x1291 = x1285 * x1290;
        let x1293 = x1289 - x1291;
        let x1300 = x1247 - x1246;
        let x1301 = x1300 - x1251;
        let x1302 = 0.5 * x1301;
        let x1304 = x1302 - x1256;
        let x1305 = q[4] * 4.0;
        let x1306 = x1285 * x1305;
        let x1308 = x1304 - x1306;
        let x1313 = x1257 + x1258;
        let x1315 = x1261 - x1313;
        let x1316 = 0.5 * x1315;
        let x1318 = x1316 - x1267;
        let x1319 = q[5] * 4.0;
        let x1320 = x1285 * x1319;
        let x1322 = x1318 - x1320;
        let x1327 = x1268 - x1270;
        let x1328 = x1327 - x1273;
        let x1329 = 0.5 * x1328;
        let x1331 = x1329 - x1278;
        let x1332 = q[6] * 4.0;
        let x1333 = x1285 * x1332;
        let x1335 = x1331 - x1333;
        out[0] = 0.0;
        out[1] = 0.0;
        out[2] = 0.0;
        out[3] = x1293;
        out[4] = x1308;
        out[5] = x1322;
        out[6] = x1335;
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
        let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 7] = phi.try_into().expect("phi must have 7 entries");
        let phi_q: &mut [f64; 42] = phi_q
            .try_into()
            .expect("phi_q must have 42 entries");
        let mass: &mut [f64; 19] = mass.try_into().expect("mass must have 19 entries");
        let force: &mut [f64; 7] = force.try_into().expect("force must have 7 entries");
        let _ = t;
        let mut s = [0.0f64; 4];
        eval_newton_shared_0(k, q, qd, t, &mut s);
        eval_newton_part_0(k, q, &s, phi, phi_q, mass, force);
        eval_newton_part_1(q, qd, &s, force);
    }
    #[inline(never)]
    fn eval_newton_shared_0(
        _k: &[f64; 6],
        q: &[f64; 7],
        _qd: &[f64; 7],
        _t: f64,
        s: &mut [f64; 4],
    ) {
        let x249 = q[3] * 2.0;
        s[0] = x249;
        let x250 = q[4] * 2.0;
        s[1] = x250;
        let x251 = q[5] * 2.0;
        s[2] = x251;
        let x252 = q[6] * 2.0;
        s[3] = x252;
    }
    #[inline(never)]
    fn eval_newton_part_0(
        k: &[f64; 6],
        q: &[f64; 7],
        s: &[f64; 4],
        phi: &mut [f64; 7],
        phi_q: &mut [f64; 42],
        mass: &mut [f64; 19],
        force: &mut [f64; 7],
    ) {
        let x20 = q[3] * q[3];
        let x21 = q[4] * q[4];
        let x22 = q[5] * q[5];
        let x23 = q[6] * q[6];
        let x24 = x20 + x21;
        let x25 = 2.0 * x24;
        let x27 = x25 - 1.0;
        let x28 = x20 + x22;
        let x29 = 2.0 * x28;
        let x30 = x29 - 1.0;
        let x31 = x20 + x23;
        let x32 = 2.0 * x31;
        let x33 = x32 - 1.0;
        let x34 = q[4] * q[5];
        let x35 = 2.0 * x34;
        let x36 = q[3] * q[6];
        let x38 = 2.0 * x36;
        let x40 = x35 - x38;
        let x41 = q[4] * q[6];
        let x42 = 2.0 * x41;
        let x43 = q[3] * q[5];
        let x44 = 2.0 * x43;
        let x45 = x42 + x44;
        let x46 = x35 + x38;
        let x47 = q[5] * q[6];
        let x48 = 2.0 * x47;
        let x49 = q[3] * q[4];
        let x51 = 2.0 * x49;
        let x53 = x48 - x51;
        let x56 = x42 - x44;
        let x57 = x48 + x51;
        let x59 = q[0] * q[0];
        let x60 = q[1] * q[1];
        let x61 = q[2] * q[2];
        let x62 = x59 + x60;
        let x63 = x61 + x62;
        let x64 = x63.sqrt();
        let x69 = x27 * 0.542805;
        let x70 = x46 * 0.542805;
        let x71 = x56 * 0.542805;
        let x72 = q[0] + x69;
        let x73 = q[1] + x70;
        let x74 = q[2] + x71;
        let x76 = x72 - 1.107915;
        let x77 = x76 * x76;
        let x78 = x73 * x73;
        let x79 = x74 * x74;
        let x80 = x77 + x78;
        let x81 = x79 + x80;
        let x82 = x81.sqrt();
        let x89 = x27 * 0.956919;
        let x91 = x40 * 0.528915;
        let x93 = x89 - x91;
        let x94 = x46 * 0.956919;
        let x95 = x30 * 0.528915;
        let x97 = x94 - x95;
        let x98 = x56 * 0.956919;
        let x99 = x57 * 0.528915;
        let x101 = x98 - x99;
        let x102 = q[0] + x93;
        let x103 = q[1] + x97;
        let x104 = q[2] + x101;
        let x106 = x102 - 0.549094;
        let x108 = x103 - 0.756063;
        let x109 = x106 * x106;
        let x110 = x108 * x108;
        let x111 = x104 * x104;
        let x112 = x109 + x110;
        let x113 = x111 + x112;
        let x114 = x113.sqrt();
        let x123 = x27 * 0.665885;
        let x125 = x40 * 0.353482;
        let x127 = x45 * 1.402538;
        let x128 = x123 - x125;
        let x129 = x127 + x128;
        let x130 = x46 * 0.665885;
        let x131 = x30 * 0.353482;
        let x133 = x53 * 1.402538;
        let x134 = x130 - x131;
        let x135 = x133 + x134;
        let x136 = x56 * 0.665885;
        let x137 = x57 * 0.353482;
        let x139 = x33 * 1.402538;
        let x140 = x136 - x137;
        let x141 = x139 + x140;
        let x142 = q[0] + x129;
        let x143 = q[1] + x135;
        let x144 = q[2] + x141;
        let x146 = x142 - 0.735077;
        let x148 = x143 + 0.223935;
        let x150 = x144 - 0.525991;
        let x151 = x146 * x146;
        let x152 = x148 * x148;
        let x153 = x150 * x150;
        let x154 = x151 + x152;
        let x155 = x153 + x154;
        let x156 = x155.sqrt();
        let x165 = x27 * 0.478359;
        let x166 = x40 * 1.158742;
        let x167 = x45 * 0.107672;
        let x168 = x165 + x166;
        let x169 = x167 + x168;
        let x170 = x46 * 0.478359;
        let x171 = x30 * 1.158742;
        let x172 = x53 * 0.107672;
        let x173 = x170 + x171;
        let x174 = x172 + x173;
        let x175 = x56 * 0.478359;
        let x176 = x57 * 1.158742;
        let x177 = x33 * 0.107672;
        let x178 = x175 + x176;
        let x179 = x177 + x178;
        let x180 = q[0] + x169;
        let x181 = q[1] + x174;
        let x182 = q[2] + x179;
        let x184 = x180 - 0.514188;
        let x186 = x181 + 0.526063;
        let x188 = x182 + 0.368418;
        let x189 = x184 * x184;
        let x190 = x186 * x186;
        let x191 = x188 * x188;
        let x192 = x189 + x190;
        let x193 = x191 + x192;
        let x194 = x193.sqrt();
        let x204 = x27 * 0.137087;
        let x207 = x40 * 0.235121;
        let x209 = x45 * 0.353913;
        let x210 = x204 + x207;
        let x212 = x209 - x210;
        let x213 = x46 * 0.137087;
        let x215 = x30 * 0.235121;
        let x217 = x53 * 0.353913;
        let x218 = x213 + x215;
        let x220 = x217 - x218;
        let x221 = x56 * 0.137087;
        let x223 = x57 * 0.235121;
        let x225 = x33 * 0.353913;
        let x226 = x221 + x223;
        let x228 = x225 - x226;
        let x229 = q[0] + x212;
        let x230 = q[1] + x220;
        let x231 = q[2] + x228;
        let x233 = x229 - 0.590473;
        let x235 = x230 - 0.094733;
        let x237 = x231 + 0.205018;
        let x238 = x233 * x233;
        let x239 = x235 * x235;
        let x240 = x237 * x237;
        let x241 = x238 + x239;
        let x242 = x240 + x241;
        let x243 = x242.sqrt();
        let x246 = x22 + x24;
        let x247 = x23 + x246;
        let x248 = x247 - 1.0;
        let x253 = q[0] * 2.0;
        let x254 = q[1] * 2.0;
        let x255 = q[2] * 2.0;
        let x256 = 2.0 * x64;
        let x257 = 1.0 / x256;
        let x258 = x253 * x257;
        let x259 = 2.0 * x76;
        let x260 = 2.0 * x73;
        let x261 = 2.0 * x74;
        let x262 = 2.0 * x82;
        let x263 = 1.0 / x262;
        let x264 = x259 * x263;
        let x265 = 2.0 * x106;
        let x266 = 2.0 * x108;
        let x267 = 2.0 * x104;
        let x268 = 2.0 * x114;
        let x269 = 1.0 / x268;
        let x270 = x265 * x269;
        let x271 = 2.0 * x146;
        let x272 = 2.0 * x148;
        let x273 = 2.0 * x150;
        let x274 = 2.0 * x156;
        let x275 = 1.0 / x274;
        let x276 = x271 * x275;
        let x277 = 2.0 * x184;
        let x278 = 2.0 * x186;
        let x279 = 2.0 * x188;
        let x280 = 2.0 * x194;
        let x281 = 1.0 / x280;
        let x282 = x277 * x281;
        let x283 = 2.0 * x233;
        let x284 = 2.0 * x235;
        let x285 = 2.0 * x237;
        let x286 = 2.0 * x243;
        let x287 = 1.0 / x286;
        let x288 = x283 * x287;
        let x289 = x254 * x257;
        let x290 = x260 * x263;
        let x291 = x266 * x269;
        let x292 = x272 * x275;
        let x293 = x278 * x281;
        let x294 = x284 * x287;
        let x295 = x255 * x257;
        let x296 = x261 * x263;
        let x297 = x267 * x269;
        let x298 = x273 * x275;
        let x299 = x279 * x281;
        let x300 = x285 * x287;
        let x301 = 2.0 * s[0];
        let x305 = 0.542805 * x301;
        let x306 = 0.542805 * s[3];
        let x307 = 0.542805 * s[2];
        let x309 = x259 * x305;
        let x310 = x260 * x306;
        let x311 = x261 * x307;
        let x313 = x309 + x310;
        let x314 = x313 - x311;
        let x315 = x263 * x314;
        let x316 = 0.956919 * x301;
        let x317 = 0.528915 * s[3];
        let x319 = x316 + x317;
        let x320 = 0.956919 * s[3];
        let x321 = 0.528915 * x301;
        let x323 = x320 - x321;
        let x324 = 0.956919 * s[2];
        let x326 = 0.528915 * s[1];
        let x328 = x324 + x326;
        let x330 = x265 * x319;
        let x331 = x266 * x323;
        let x332 = x267 * x328;
        let x334 = x330 + x331;
        let x335 = x334 - x332;
        let x336 = x269 * x335;
        let x337 = 0.665885 * x301;
        let x338 = 0.353482 * s[3];
        let x340 = 1.402538 * s[2];
        let x341 = x337 + x338;
        let x342 = x340 + x341;
        let x343 = 0.665885 * s[3];
        let x344 = 0.353482 * x301;
        let x346 = 1.402538 * s[1];
        let x348 = x343 - x344;
        let x349 = x348 - x346;
        let x350 = 0.665885 * s[2];
        let x352 = 0.353482 * s[1];
        let x354 = 1.402538 * x301;
        let x355 = x350 + x352;
        let x357 = x354 - x355;
        let x358 = x271 * x342;
        let x359 = x272 * x349;
        let x360 = x273 * x357;
        let x361 = x358 + x359;
        let x362 = x360 + x361;
        let x363 = x275 * x362;
        let x364 = 0.478359 * x301;
        let x365 = 1.158742 * s[3];
        let x367 = 0.107672 * s[2];
        let x368 = x364 - x365;
        let x369 = x367 + x368;
        let x370 = 0.478359 * s[3];
        let x371 = 1.158742 * x301;
        let x372 = 0.107672 * s[1];
        let x374 = x370 + x371;
        let x375 = x374 - x372;
        let x376 = 0.478359 * s[2];
        let x378 = 1.158742 * s[1];
        let x379 = 0.107672 * x301;
        let x380 = x378 - x376;
        let x381 = x379 + x380;
        let x382 = x277 * x369;
        let x383 = x278 * x375;
        let x384 = x279 * x381;
        let x385 = x382 + x383;
        let x386 = x384 + x385;
        let x387 = x281 * x386;
        let x388 = 0.137087 * x301;
        let x389 = 0.235121 * s[3];
        let x391 = 0.353913 * s[2];
        let x392 = x388 - x389;
        let x394 = x391 - x392;
        let x395 = 0.137087 * s[3];
        let x396 = 0.235121 * x301;
        let x397 = 0.353913 * s[1];
        let x399 = x395 + x396;
        let x401 = x397 + x399;
        let x403 = 0.137087 * s[2];
        let x405 = 0.235121 * s[1];
        let x406 = 0.353913 * x301;
        let x407 = x405 - x403;
        let x409 = x406 - x407;
        let x410 = x283 * x394;
        let x411 = x284 * x401;
        let x413 = x285 * x409;
        let x414 = x410 - x411;
        let x415 = x413 + x414;
        let x416 = x287 * x415;
        let x417 = 2.0 * s[1];
        let x419 = 0.542805 * x417;
        let x420 = x259 * x419;
        let x421 = x260 * x307;
        let x422 = x261 * x306;
        let x423 = x420 + x421;
        let x424 = x422 + x423;
        let x425 = x263 * x424;
        let x426 = 0.956919 * x417;
        let x427 = 0.528915 * s[2];
        let x429 = x426 - x427;
        let x430 = 0.528915 * s[0];
        let x432 = x320 - x430;
        let x433 = x265 * x429;
        let x434 = x266 * x324;
        let x435 = x267 * x432;
        let x436 = x433 + x434;
        let x437 = x435 + x436;
        let x438 = x269 * x437;
        let x439 = 0.665885 * x417;
        let x440 = 0.353482 * s[2];
        let x442 = 1.402538 * s[3];
        let x443 = x439 - x440;
        let x444 = x442 + x443;
        let x445 = 1.402538 * s[0];
        let x447 = x350 - x445;
        let x448 = 0.353482 * s[0];
        let x450 = x343 - x448;
        let x451 = x271 * x444;
        let x452 = x272 * x447;
        let x453 = x273 * x450;
        let x454 = x451 + x452;
        let x455 = x453 + x454;
        let x456 = x275 * x455;
        let x457 = 0.478359 * x417;
        let x458 = 1.158742 * s[2];
        let x459 = 0.107672 * s[3];
        let x460 = x457 + x458;
        let x461 = x459 + x460;
        let x462 = 0.107672 * s[0];
        let x464 = x376 - x462;
        let x465 = 1.158742 * s[0];
        let x466 = x370 + x465;
        let x467 = x277 * x461;
        let x468 = x278 * x464;
        let x469 = x279 * x466;
        let x470 = x467 + x468;
        let x471 = x469 + x470;
        let x472 = x281 * x471;
        let x473 = 0.137087 * x417;
        let x474 = 0.235121 * s[2];
        let x475 = 0.353913 * s[3];
        let x476 = x473 + x474;
        let x478 = x475 - x476;
        let x479 = 0.353913 * s[0];
        let x481 = x403 + x479;
        let x483 = 0.235121 * s[0];
        let x484 = x395 + x483;
        let x486 = x283 * x478;
        let x487 = x284 * x481;
        let x489 = x285 * x484;
        let x491 = x486 - x487;
        let x492 = x491 - x489;
        let x493 = x287 * x492;
        let x494 = 2.0 * s[2];
        let x495 = 0.542805 * s[1];
        let x496 = 0.542805 * s[0];
        let x498 = x260 * x495;
        let x499 = x261 * x496;
        let x501 = x498 - x499;
        let x502 = x263 * x501;
        let x503 = 0.956919 * s[1];
        let x504 = 0.528915 * x494;
        let x506 = x503 - x504;
        let x507 = 0.956919 * s[0];
        let x509 = x317 + x507;
        let x511 = x265 * x326;
        let x513 = x266 * x506;
        let x514 = x267 * x509;
        let x516 = x513 - x511;
        let x517 = x516 - x514;
        let x518 = x269 * x517;
        let x519 = x445 - x352;
        let x520 = 0.665885 * s[1];
        let x521 = 0.353482 * x494;
        let x523 = x520 - x521;
        let x524 = x442 + x523;
        let x525 = 0.665885 * s[0];
        let x527 = x338 + x525;
        let x529 = x271 * x519;
        let x530 = x272 * x524;
        let x531 = x273 * x527;
        let x533 = x529 + x530;
        let x534 = x533 - x531;
        let x535 = x275 * x534;
        let x536 = x378 + x462;
        let x537 = 0.478359 * s[1];
        let x538 = 1.158742 * x494;
        let x539 = x537 + x538;
        let x540 = x459 + x539;
        let x541 = 0.478359 * s[0];
        let x543 = x365 - x541;
        let x544 = x277 * x536;
        let x545 = x278 * x540;
        let x546 = x279 * x543;
        let x547 = x544 + x545;
        let x548 = x546 + x547;
        let x549 = x281 * x548;
        let x551 = x479 - x405;
        let x552 = 0.137087 * s[1];
        let x553 = 0.235121 * x494;
        let x554 = x552 + x553;
        let x556 = x475 - x554;
        let x557 = 0.137087 * s[0];
        let x559 = x389 - x557;
        let x561 = x283 * x551;
        let x562 = x284 * x556;
        let x563 = x285 * x559;
        let x565 = x561 + x562;
        let x566 = x565 - x563;
        let x567 = x287 * x566;
        let x568 = 2.0 * s[3];
        let x569 = x260 * x496;
        let x570 = x261 * x495;
        let x571 = x569 + x570;
        let x572 = x263 * x571;
        let x573 = x503 - x427;
        let x574 = x265 * x430;
        let x575 = x266 * x507;
        let x576 = x267 * x573;
        let x577 = x574 + x575;
        let x578 = x576 + x577;
        let x579 = x269 * x578;
        let x580 = x346 + x448;
        let x581 = x340 + x525;
        let x582 = 1.402538 * x568;
        let x583 = x520 - x440;
        let x584 = x582 + x583;
        let x585 = x271 * x580;
        let x586 = x272 * x581;
        let x587 = x273 * x584;
        let x588 = x585 + x586;
        let x589 = x587 + x588;
        let x590 = x275 * x589;
        let x592 = x372 - x465;
        let x593 = x367 + x541;
        let x594 = 0.107672 * x568;
        let x595 = x458 + x537;
        let x596 = x594 + x595;
        let x597 = x277 * x592;
        let x598 = x278 * x593;
        let x599 = x279 * x596;
        let x600 = x597 + x598;
        let x601 = x599 + x600;
        let x602 = x281 * x601;
        let x604 = x397 + x483;
        let x605 = x391 - x557;
        let x606 = 0.353913 * x568;
        let x607 = x474 + x552;
        let x609 = x606 - x607;
        let x610 = x283 * x604;
        let x611 = x284 * x605;
        let x612 = x285 * x609;
        let x613 = x610 + x611;
        let x614 = x612 + x613;
        let x615 = x287 * x614;
        let x1113 = s[1] * x417;
        let x1115 = s[2] * x494;
        let x1117 = s[3] * x568;
        let x1119 = x1113 + x1115;
        let x1121 = x1117 + x1119;
        let x1123 = 0.5 * x1121;
        let x1125 = x20 * 4.0;
        let x1126 = x1123 + x1125;
        let x1127 = s[1] * x301;
        let x1128 = s[2] * x568;
        let x1130 = s[3] * x494;
        let x1131 = x1127 - x1128;
        let x1132 = x1130 + x1131;
        let x1133 = 0.5 * x1132;
        let x1135 = x49 * 4.0;
        let x1136 = x1135 - x1133;
        let x1137 = s[1] * x568;
        let x1138 = s[2] * x301;
        let x1139 = s[3] * x417;
        let x1141 = x1137 + x1138;
        let x1142 = x1141 - x1139;
        let x1143 = 0.5 * x1142;
        let x1145 = x43 * 4.0;
        let x1146 = x1145 - x1143;
        let x1147 = s[1] * x494;
        let x1149 = s[2] * x417;
        let x1150 = s[3] * x301;
        let x1151 = x1149 - x1147;
        let x1152 = x1150 + x1151;
        let x1153 = 0.5 * x1152;
        let x1155 = x36 * 4.0;
        let x1156 = x1155 - x1153;
        let x1157 = s[0] * x417;
        let x1160 = x1130 - x1157;
        let x1161 = x1160 - x1128;
        let x1162 = 0.5 * x1161;
        let x1163 = x1135 + x1162;
        let x1164 = s[0] * x301;
        let x1165 = x1117 + x1164;
        let x1166 = x1115 + x1165;
        let x1167 = 0.5 * x1166;
        let x1168 = x21 * 4.0;
        let x1169 = x1167 + x1168;
        let x1170 = s[0] * x568;
        let x1173 = x1170 - x1150;
        let x1174 = x1173 - x1149;
        let x1175 = 0.5 * x1174;
        let x1176 = x34 * 4.0;
        let x1177 = x1175 + x1176;
        let x1178 = s[0] * x494;
        let x1180 = x1139 + x1178;
        let x1182 = x1138 - x1180;
        let x1183 = 0.5 * x1182;
        let x1184 = x41 * 4.0;
        let x1185 = x1183 + x1184;
        let x1187 = x1137 - x1180;
        let x1188 = 0.5 * x1187;
        let x1189 = x1145 + x1188;
        let x1191 = x1150 - x1170;
        let x1192 = x1191 - x1147;
        let x1193 = 0.5 * x1192;
        let x1194 = x1176 + x1193;
        let x1195 = x1113 + x1165;
        let x1196 = 0.5 * x1195;
        let x1197 = x22 * 4.0;
        let x1198 = x1196 + x1197;
        let x1200 = x1157 - x1130;
        let x1201 = x1200 - x1127;
        let x1202 = 0.5 * x1201;
        let x1203 = x47 * 4.0;
        let x1204 = x1202 + x1203;
        let x1205 = x1151 - x1170;
        let x1206 = 0.5 * x1205;
        let x1207 = x1155 + x1206;
        let x1210 = x1178 - x1141;
        let x1211 = 0.5 * x1210;
        let x1212 = x1184 + x1211;
        let x1213 = x1131 - x1157;
        let x1214 = 0.5 * x1213;
        let x1215 = x1203 + x1214;
        let x1216 = x1119 + x1164;
        let x1217 = 0.5 * x1216;
        let x1218 = x23 * 4.0;
        let x1219 = x1217 + x1218;
        let x3041 = x64 + k[0];
        let x3043 = x82 + k[1];
        let x3045 = x114 + k[2];
        let x3047 = x156 + k[3];
        let x3049 = x194 + k[4];
        let x3051 = x243 + k[5];
        phi[0] = x3041;
        phi_q[0] = x258;
        phi_q[1] = x289;
        phi_q[2] = x295;
        phi[1] = x3043;
        phi_q[3] = x264;
        phi_q[4] = x290;
        phi_q[5] = x296;
        phi_q[6] = x315;
        phi_q[7] = x425;
        phi_q[8] = x502;
        phi_q[9] = x572;
        phi[2] = x3045;
        phi_q[10] = x270;
        phi_q[11] = x291;
        phi_q[12] = x297;
        phi_q[13] = x336;
        phi_q[14] = x438;
        phi_q[15] = x518;
        phi_q[16] = x579;
        phi[3] = x3047;
        phi_q[17] = x276;
        phi_q[18] = x292;
        phi_q[19] = x298;
        phi_q[20] = x363;
        phi_q[21] = x456;
        phi_q[22] = x535;
        phi_q[23] = x590;
        phi[4] = x3049;
        phi_q[24] = x282;
        phi_q[25] = x293;
        phi_q[26] = x299;
        phi_q[27] = x387;
        phi_q[28] = x472;
        phi_q[29] = x549;
        phi_q[30] = x602;
        phi[5] = x3051;
        phi_q[31] = x288;
        phi_q[32] = x294;
        phi_q[33] = x300;
        phi_q[34] = x416;
        phi_q[35] = x493;
        phi_q[36] = x567;
        phi_q[37] = x615;
        phi[6] = x248;
        phi_q[38] = s[0];
        phi_q[39] = s[1];
        phi_q[40] = s[2];
        phi_q[41] = s[3];
        mass[0] = 1.0;
        mass[1] = 1.0;
        mass[2] = 1.0;
        mass[3] = x1126;
        mass[4] = x1136;
        mass[5] = x1146;
        mass[6] = x1156;
        mass[7] = x1163;
        mass[8] = x1169;
        mass[9] = x1177;
        mass[10] = x1185;
        mass[11] = x1189;
        mass[12] = x1194;
        mass[13] = x1198;
        mass[14] = x1204;
        mass[15] = x1207;
        mass[16] = x1212;
        mass[17] = x1215;
        mass[18] = x1219;
        force[0] = 0.0;
        force[1] = 0.0;
        force[2] = 0.0;
    }
    #[inline(never)]
    fn eval_newton_part_1(
        q: &[f64; 7],
        qd: &[f64; 7],
        s: &[f64; 4],
        force: &mut [f64; 7],
    ) {
        let x633 = q[5] * qd[4];
        let x634 = q[4] * qd[5];
        let x637 = q[6] * qd[3];
        let x638 = q[3] * qd[6];
        let x643 = q[6] * qd[4];
        let x644 = q[4] * qd[6];
        let x647 = q[5] * qd[3];
        let x648 = q[3] * qd[5];
        let x653 = q[6] * qd[5];
        let x654 = q[5] * qd[6];
        let x657 = q[4] * qd[3];
        let x658 = q[3] * qd[4];
        let x785 = 2.0 * qd[3];
        let x786 = 2.0 * qd[4];
        let x787 = 2.0 * qd[5];
        let x788 = 2.0 * qd[6];
        let x841 = qd[4] * qd[5];
        let x844 = qd[3] * qd[6];
        let x849 = qd[4] * qd[6];
        let x852 = qd[3] * qd[5];
        let x1036 = x658 - x657;
        let x1037 = x653 + x1036;
        let x1038 = x1037 - x654;
        let x1039 = 2.0 * x1038;
        let x1042 = x643 + x647;
        let x1044 = x648 - x1042;
        let x1045 = x644 + x1044;
        let x1046 = 2.0 * x1045;
        let x1049 = x633 - x637;
        let x1050 = x1049 - x634;
        let x1051 = x638 + x1050;
        let x1052 = 2.0 * x1051;
        let x1065 = 2.0 * x1039;
        let x1066 = 2.0 * x1046;
        let x1067 = 2.0 * x1052;
        let x1222 = x849 + x852;
        let x1224 = x852 - x1222;
        let x1225 = x849 + x1224;
        let x1226 = 2.0 * x1225;
        let x1229 = x841 - x844;
        let x1230 = x1229 - x841;
        let x1231 = x844 + x1230;
        let x1232 = 2.0 * x1231;
        let x1233 = 2.0 * x1226;
        let x1234 = 2.0 * x1232;
        let x1235 = x786 * x1065;
        let x1236 = x787 * x1066;
        let x1237 = s[2] * x1233;
        let x1238 = x1236 + x1237;
        let x1239 = x788 * x1067;
        let x1240 = s[3] * x1234;
        let x1241 = x1239 + x1240;
        let x1242 = x1235 + x1238;
        let x1243 = x1241 + x1242;
        let x1244 = 0.5 * x1243;
        let x1246 = x785 * x1065;
        let x1247 = x788 * x1066;
        let x1248 = s[3] * x1233;
        let x1249 = x1247 + x1248;
        let x1251 = x787 * x1067;
        let x1252 = s[2] * x1234;
        let x1253 = x1251 + x1252;
        let x1254 = x1246 - x1249;
        let x1255 = x1253 + x1254;
        let x1256 = 0.5 * x1255;
        let x1257 = x788 * x1065;
        let x1258 = x785 * x1066;
        let x1259 = s[0] * x1233;
        let x1260 = x1258 + x1259;
        let x1261 = x786 * x1067;
        let x1262 = s[1] * x1234;
        let x1263 = x1261 + x1262;
        let x1265 = x1257 + x1260;
        let x1266 = x1265 - x1263;
        let x1267 = 0.5 * x1266;
        let x1268 = x787 * x1065;
        let x1270 = x786 * x1066;
        let x1271 = s[1] * x1233;
        let x1272 = x1270 + x1271;
        let x1273 = x785 * x1067;
        let x1274 = s[0] * x1234;
        let x1275 = x1273 + x1274;
        let x1276 = x1272 - x1268;
        let x1277 = x1275 + x1276;
        let x1278 = 0.5 * x1277;
        let x1279 = qd[3] * qd[3];
        let x1280 = qd[4] * qd[4];
        let x1281 = qd[5] * qd[5];
        let x1282 = qd[6] * qd[6];
        let x1283 = x1279 + x1280;
        let x1284 = x1281 + x1283;
        let x1285 = x1282 + x1284;
        let x1286 = x1235 + x1236;
        let x1287 = x1239 + x1286;
        let x1288 = 0.5 * x1287;
        let x1289 = x1244 + x1288;
        let x1290 = q[3] * 4.0;
        let x1291 = x1285 * x1290;
        let x1293 = x1289 - x1291;
        let x1300 = x1247 - x1246;
        let x1301 = x1300 - x1251;
        let x1302 = 0.5 * x1301;
        let x1304 = x1302 - x1256;
        let x1305 = q[4] * 4.0;
        let x1306 = x1285 * x1305;
        let x1308 = x1304 - x1306;
        let x1313 = x1257 + x1258;
        let x1315 = x1261 - x1313;
        let x1316 = 0.5 * x1315;
        let x1318 = x1316 - x1267;
        let x1319 = q[5] * 4.0;
        let x1320 = x1285 * x1319;
        let x1322 = x1318 - x1320;
        let x1327 = x1268 - x1270;
        let x1328 = x1327 - x1273;
        let x1329 = 0.5 * x1328;
        let x1331 = x1329 - x1278;
        let x1332 = q[6] * 4.0;
        let x1333 = x1285 * x1332;
        let x1335 = x1331 - x1333;
        force[3] = x1293;
        force[4] = x1308;
        force[5] = x1322;
        force[6] = x1335;
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
        let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let dq: &[f64; 7] = dq.try_into().expect("dq must have n_coords entries");
        let dqd: &[f64; 7] = dqd.try_into().expect("dqd must have n_coords entries");
        let dp: &[f64; 12] = dp.try_into().expect("dp must have 12 entries");
        let mass: &mut [f64; 19] = mass.try_into().expect("mass must have 19 entries");
        let force: &mut [f64; 7] = force.try_into().expect("force must have 7 entries");
        let _ = k;
        let _ = t;
        let _ = dp;
        tangents_part_0(q, qd, dq, dqd, mass, force);
    }
    #[inline(never)]
    fn tangents_part_0(
        q: &[f64; 7],
        qd: &[f64; 7],
        dq: &[f64; 7],
        dqd: &[f64; 7],
        mass: &mut [f64; 19],
        force: &mut [f64; 7],
    ) {
        let x249 = q[3] * 2.0;
        let x250 = q[4] * 2.0;
        let x251 = q[5] * 2.0;
        let x252 = q[6] * 2.0;
        let x301 = 2.0 * x249;
        let x417 = 2.0 * x250;
        let x494 = 2.0 * x251;
        let x568 = 2.0 * x252;
        let x633 = q[5] * qd[4];
        let x634 = q[4] * qd[5];
        let x637 = q[6] * qd[3];
        let x638 = q[3] * qd[6];
        let x643 = q[6] * qd[4];
        let x644 = q[4] * qd[6];
        let x647 = q[5] * qd[3];
        let x648 = q[3] * qd[5];
        let x653 = q[6] * qd[5];
        let x654 = q[5] * qd[6];
        let x657 = q[4] * qd[3];
        let x658 = q[3] * qd[4];
        let x785 = 2.0 * qd[3];
        let x786 = 2.0 * qd[4];
        let x787 = 2.0 * qd[5];
        let x788 = 2.0 * qd[6];
        let x841 = qd[4] * qd[5];
        let x844 = qd[3] * qd[6];
        let x849 = qd[4] * qd[6];
        let x852 = qd[3] * qd[5];
        let x1036 = x658 - x657;
        let x1037 = x653 + x1036;
        let x1038 = x1037 - x654;
        let x1039 = 2.0 * x1038;
        let x1042 = x643 + x647;
        let x1044 = x648 - x1042;
        let x1045 = x644 + x1044;
        let x1046 = 2.0 * x1045;
        let x1049 = x633 - x637;
        let x1050 = x1049 - x634;
        let x1051 = x638 + x1050;
        let x1052 = 2.0 * x1051;
        let x1065 = 2.0 * x1039;
        let x1066 = 2.0 * x1046;
        let x1067 = 2.0 * x1052;
        let x1222 = x849 + x852;
        let x1224 = x852 - x1222;
        let x1225 = x849 + x1224;
        let x1226 = 2.0 * x1225;
        let x1229 = x841 - x844;
        let x1230 = x1229 - x841;
        let x1231 = x844 + x1230;
        let x1232 = 2.0 * x1231;
        let x1233 = 2.0 * x1226;
        let x1234 = 2.0 * x1232;
        let x1279 = qd[3] * qd[3];
        let x1280 = qd[4] * qd[4];
        let x1281 = qd[5] * qd[5];
        let x1282 = qd[6] * qd[6];
        let x1283 = x1279 + x1280;
        let x1284 = x1281 + x1283;
        let x1285 = x1282 + x1284;
        let x1290 = q[3] * 4.0;
        let x1305 = q[4] * 4.0;
        let x1319 = q[5] * 4.0;
        let x1332 = q[6] * 4.0;
        let x1362 = x249 * dq[3];
        let x1363 = x250 * dq[4];
        let x1364 = x251 * dq[5];
        let x1365 = x252 * dq[6];
        let x1372 = q[5] * dq[4];
        let x1373 = q[4] * dq[5];
        let x1374 = x1372 + x1373;
        let x1376 = q[6] * dq[3];
        let x1377 = q[3] * dq[6];
        let x1378 = x1376 + x1377;
        let x1382 = q[6] * dq[4];
        let x1383 = q[4] * dq[6];
        let x1384 = x1382 + x1383;
        let x1386 = q[5] * dq[3];
        let x1387 = q[3] * dq[5];
        let x1388 = x1386 + x1387;
        let x1392 = q[6] * dq[5];
        let x1393 = q[5] * dq[6];
        let x1394 = x1392 + x1393;
        let x1396 = q[4] * dq[3];
        let x1397 = q[3] * dq[4];
        let x1398 = x1396 + x1397;
        let x1536 = 2.0 * dq[3];
        let x1537 = 2.0 * dq[4];
        let x1538 = 2.0 * dq[5];
        let x1539 = 2.0 * dq[6];
        let x1648 = 2.0 * x1536;
        let x1796 = 2.0 * x1537;
        let x1914 = 2.0 * x1538;
        let x2025 = 2.0 * x1539;
        let x2133 = qd[4] * dq[5];
        let x2134 = q[5] * dqd[4];
        let x2135 = x2133 + x2134;
        let x2136 = qd[5] * dq[4];
        let x2137 = q[4] * dqd[5];
        let x2138 = x2136 + x2137;
        let x2141 = qd[3] * dq[6];
        let x2142 = q[6] * dqd[3];
        let x2143 = x2141 + x2142;
        let x2144 = qd[6] * dq[3];
        let x2145 = q[3] * dqd[6];
        let x2146 = x2144 + x2145;
        let x2151 = qd[4] * dq[6];
        let x2152 = q[6] * dqd[4];
        let x2153 = x2151 + x2152;
        let x2154 = qd[6] * dq[4];
        let x2155 = q[4] * dqd[6];
        let x2156 = x2154 + x2155;
        let x2159 = qd[3] * dq[5];
        let x2160 = q[5] * dqd[3];
        let x2161 = x2159 + x2160;
        let x2162 = qd[5] * dq[3];
        let x2163 = q[3] * dqd[5];
        let x2164 = x2162 + x2163;
        let x2169 = qd[5] * dq[6];
        let x2170 = q[6] * dqd[5];
        let x2171 = x2169 + x2170;
        let x2172 = qd[6] * dq[5];
        let x2173 = q[5] * dqd[6];
        let x2174 = x2172 + x2173;
        let x2177 = qd[3] * dq[4];
        let x2178 = q[4] * dqd[3];
        let x2179 = x2177 + x2178;
        let x2180 = qd[4] * dq[3];
        let x2181 = q[3] * dqd[4];
        let x2182 = x2180 + x2181;
        let x2361 = 2.0 * dqd[3];
        let x2362 = 2.0 * dqd[4];
        let x2363 = 2.0 * dqd[5];
        let x2364 = 2.0 * dqd[6];
        let x2431 = x785 * dqd[3];
        let x2434 = x786 * dqd[4];
        let x2437 = x787 * dqd[5];
        let x2440 = x788 * dqd[6];
        let x2449 = qd[5] * dqd[4];
        let x2450 = qd[4] * dqd[5];
        let x2451 = x2449 + x2450;
        let x2454 = qd[6] * dqd[3];
        let x2455 = qd[3] * dqd[6];
        let x2456 = x2454 + x2455;
        let x2461 = qd[6] * dqd[4];
        let x2462 = qd[4] * dqd[6];
        let x2463 = x2461 + x2462;
        let x2466 = qd[5] * dqd[3];
        let x2467 = qd[3] * dqd[5];
        let x2468 = x2466 + x2467;
        let x2745 = x2182 - x2179;
        let x2746 = x2171 + x2745;
        let x2747 = x2746 - x2174;
        let x2748 = 2.0 * x2747;
        let x2749 = x2153 + x2161;
        let x2751 = x2164 - x2749;
        let x2752 = x2156 + x2751;
        let x2753 = 2.0 * x2752;
        let x2756 = x2135 - x2143;
        let x2757 = x2756 - x2138;
        let x2758 = x2146 + x2757;
        let x2759 = 2.0 * x2758;
        let x2760 = 2.0 * x2748;
        let x2761 = 2.0 * x2753;
        let x2762 = 2.0 * x2759;
        let x2763 = x417 * x1537;
        let x2764 = x250 * x1796;
        let x2765 = x2763 + x2764;
        let x2766 = x494 * x1538;
        let x2767 = x251 * x1914;
        let x2768 = x2766 + x2767;
        let x2769 = x568 * x1539;
        let x2770 = x252 * x2025;
        let x2771 = x2769 + x2770;
        let x2772 = x2765 + x2768;
        let x2773 = x2771 + x2772;
        let x2774 = 0.5 * x2773;
        let x2775 = 4.0 * x1362;
        let x2776 = x2774 + x2775;
        let x2777 = x301 * x1537;
        let x2778 = x250 * x1648;
        let x2779 = x2777 + x2778;
        let x2780 = x568 * x1538;
        let x2781 = x251 * x2025;
        let x2782 = x2780 + x2781;
        let x2784 = x494 * x1539;
        let x2785 = x252 * x1914;
        let x2786 = x2784 + x2785;
        let x2787 = x2779 - x2782;
        let x2788 = x2786 + x2787;
        let x2789 = 0.5 * x2788;
        let x2791 = 4.0 * x1398;
        let x2792 = x2791 - x2789;
        let x2793 = x568 * x1537;
        let x2794 = x250 * x2025;
        let x2795 = x2793 + x2794;
        let x2796 = x301 * x1538;
        let x2797 = x251 * x1648;
        let x2798 = x2796 + x2797;
        let x2799 = x417 * x1539;
        let x2800 = x252 * x1796;
        let x2801 = x2799 + x2800;
        let x2803 = x2795 + x2798;
        let x2804 = x2803 - x2801;
        let x2805 = 0.5 * x2804;
        let x2807 = 4.0 * x1388;
        let x2808 = x2807 - x2805;
        let x2809 = x494 * x1537;
        let x2810 = x250 * x1914;
        let x2811 = x2809 + x2810;
        let x2813 = x417 * x1538;
        let x2814 = x251 * x1796;
        let x2815 = x2813 + x2814;
        let x2816 = x301 * x1539;
        let x2817 = x252 * x1648;
        let x2818 = x2816 + x2817;
        let x2819 = x2815 - x2811;
        let x2820 = x2818 + x2819;
        let x2821 = 0.5 * x2820;
        let x2823 = 4.0 * x1378;
        let x2824 = x2823 - x2821;
        let x2825 = x417 * x1536;
        let x2826 = x249 * x1796;
        let x2827 = x2825 + x2826;
        let x2830 = x2786 - x2827;
        let x2831 = x2830 - x2782;
        let x2832 = 0.5 * x2831;
        let x2833 = x2791 + x2832;
        let x2834 = x301 * x1536;
        let x2835 = x249 * x1648;
        let x2836 = x2834 + x2835;
        let x2837 = x2771 + x2836;
        let x2838 = x2768 + x2837;
        let x2839 = 0.5 * x2838;
        let x2840 = 4.0 * x1363;
        let x2841 = x2839 + x2840;
        let x2842 = x568 * x1536;
        let x2843 = x249 * x2025;
        let x2844 = x2842 + x2843;
        let x2847 = x2844 - x2818;
        let x2848 = x2847 - x2815;
        let x2849 = 0.5 * x2848;
        let x2850 = 4.0 * x1374;
        let x2851 = x2849 + x2850;
        let x2852 = x494 * x1536;
        let x2853 = x249 * x1914;
        let x2854 = x2852 + x2853;
        let x2855 = x2801 + x2854;
        let x2857 = x2798 - x2855;
        let x2858 = 0.5 * x2857;
        let x2859 = 4.0 * x1384;
        let x2860 = x2858 + x2859;
        let x2861 = x2795 - x2855;
        let x2862 = 0.5 * x2861;
        let x2863 = x2807 + x2862;
        let x2865 = x2818 - x2844;
        let x2866 = x2865 - x2811;
        let x2867 = 0.5 * x2866;
        let x2868 = x2850 + x2867;
        let x2869 = x2765 + x2837;
        let x2870 = 0.5 * x2869;
        let x2871 = 4.0 * x1364;
        let x2872 = x2870 + x2871;
        let x2874 = x2827 - x2786;
        let x2875 = x2874 - x2779;
        let x2876 = 0.5 * x2875;
        let x2877 = 4.0 * x1394;
        let x2878 = x2876 + x2877;
        let x2879 = x2819 - x2844;
        let x2880 = 0.5 * x2879;
        let x2881 = x2823 + x2880;
        let x2883 = x2854 - x2803;
        let x2884 = 0.5 * x2883;
        let x2885 = x2859 + x2884;
        let x2886 = x2787 - x2827;
        let x2887 = 0.5 * x2886;
        let x2888 = x2877 + x2887;
        let x2889 = x2772 + x2836;
        let x2890 = 0.5 * x2889;
        let x2891 = 4.0 * x1365;
        let x2892 = x2890 + x2891;
        let x2893 = x2463 + x2468;
        let x2895 = x2468 - x2893;
        let x2896 = x2463 + x2895;
        let x2897 = 2.0 * x2896;
        let x2900 = x2451 - x2456;
        let x2901 = x2900 - x2451;
        let x2902 = x2456 + x2901;
        let x2903 = 2.0 * x2902;
        let x2904 = 2.0 * x2897;
        let x2905 = 2.0 * x2903;
        let x2906 = x1065 * x2362;
        let x2907 = x786 * x2760;
        let x2908 = x2906 + x2907;
        let x2909 = x1066 * x2363;
        let x2910 = x787 * x2761;
        let x2911 = x2909 + x2910;
        let x2912 = x1233 * x1538;
        let x2913 = x251 * x2904;
        let x2914 = x2912 + x2913;
        let x2915 = x2911 + x2914;
        let x2916 = x1067 * x2364;
        let x2917 = x788 * x2762;
        let x2918 = x2916 + x2917;
        let x2919 = x1234 * x1539;
        let x2920 = x252 * x2905;
        let x2921 = x2919 + x2920;
        let x2922 = x2918 + x2921;
        let x2923 = x2908 + x2915;
        let x2924 = x2922 + x2923;
        let x2925 = 0.5 * x2924;
        let x2926 = x1065 * x2361;
        let x2927 = x785 * x2760;
        let x2928 = x2926 + x2927;
        let x2929 = x1066 * x2364;
        let x2930 = x788 * x2761;
        let x2931 = x2929 + x2930;
        let x2932 = x1233 * x1539;
        let x2933 = x252 * x2904;
        let x2934 = x2932 + x2933;
        let x2935 = x2931 + x2934;
        let x2937 = x1067 * x2363;
        let x2938 = x787 * x2762;
        let x2939 = x2937 + x2938;
        let x2940 = x1234 * x1538;
        let x2941 = x251 * x2905;
        let x2942 = x2940 + x2941;
        let x2943 = x2939 + x2942;
        let x2944 = x2928 - x2935;
        let x2945 = x2943 + x2944;
        let x2946 = 0.5 * x2945;
        let x2947 = x1065 * x2364;
        let x2948 = x788 * x2760;
        let x2949 = x2947 + x2948;
        let x2950 = x1066 * x2361;
        let x2951 = x785 * x2761;
        let x2952 = x2950 + x2951;
        let x2953 = x1233 * x1536;
        let x2954 = x249 * x2904;
        let x2955 = x2953 + x2954;
        let x2956 = x2952 + x2955;
        let x2957 = x1067 * x2362;
        let x2958 = x786 * x2762;
        let x2959 = x2957 + x2958;
        let x2960 = x1234 * x1537;
        let x2961 = x250 * x2905;
        let x2962 = x2960 + x2961;
        let x2963 = x2959 + x2962;
        let x2965 = x2949 + x2956;
        let x2966 = x2965 - x2963;
        let x2967 = 0.5 * x2966;
        let x2968 = x1065 * x2363;
        let x2969 = x787 * x2760;
        let x2970 = x2968 + x2969;
        let x2972 = x1066 * x2362;
        let x2973 = x786 * x2761;
        let x2974 = x2972 + x2973;
        let x2975 = x1233 * x1537;
        let x2976 = x250 * x2904;
        let x2977 = x2975 + x2976;
        let x2978 = x2974 + x2977;
        let x2979 = x1067 * x2361;
        let x2980 = x785 * x2762;
        let x2981 = x2979 + x2980;
        let x2982 = x1234 * x1536;
        let x2983 = x249 * x2905;
        let x2984 = x2982 + x2983;
        let x2985 = x2981 + x2984;
        let x2986 = x2978 - x2970;
        let x2987 = x2985 + x2986;
        let x2988 = 0.5 * x2987;
        let x2989 = x2431 + x2434;
        let x2990 = x2437 + x2989;
        let x2991 = x2440 + x2990;
        let x2992 = x2908 + x2911;
        let x2993 = x2918 + x2992;
        let x2994 = 0.5 * x2993;
        let x2995 = x2925 + x2994;
        let x2996 = 4.0 * dq[3];
        let x2997 = x1290 * x2991;
        let x2998 = x1285 * x2996;
        let x2999 = x2997 + x2998;
        let x3001 = x2995 - x2999;
        let x3004 = x2931 - x2928;
        let x3005 = x3004 - x2939;
        let x3006 = 0.5 * x3005;
        let x3008 = x3006 - x2946;
        let x3009 = 4.0 * dq[4];
        let x3010 = x1305 * x2991;
        let x3011 = x1285 * x3009;
        let x3012 = x3010 + x3011;
        let x3014 = x3008 - x3012;
        let x3015 = x2949 + x2952;
        let x3017 = x2959 - x3015;
        let x3018 = 0.5 * x3017;
        let x3020 = x3018 - x2967;
        let x3021 = 4.0 * dq[5];
        let x3022 = x1319 * x2991;
        let x3023 = x1285 * x3021;
        let x3024 = x3022 + x3023;
        let x3026 = x3020 - x3024;
        let x3029 = x2970 - x2974;
        let x3030 = x3029 - x2981;
        let x3031 = 0.5 * x3030;
        let x3033 = x3031 - x2988;
        let x3034 = 4.0 * dq[6];
        let x3035 = x1332 * x2991;
        let x3036 = x1285 * x3034;
        let x3037 = x3035 + x3036;
        let x3039 = x3033 - x3037;
        mass[0] = 0.0;
        mass[1] = 0.0;
        mass[2] = 0.0;
        mass[3] = x2776;
        mass[4] = x2792;
        mass[5] = x2808;
        mass[6] = x2824;
        mass[7] = x2833;
        mass[8] = x2841;
        mass[9] = x2851;
        mass[10] = x2860;
        mass[11] = x2863;
        mass[12] = x2868;
        mass[13] = x2872;
        mass[14] = x2878;
        mass[15] = x2881;
        mass[16] = x2885;
        mass[17] = x2888;
        mass[18] = x2892;
        force[0] = 0.0;
        force[1] = 0.0;
        force[2] = 0.0;
        force[3] = x3001;
        force[4] = x3014;
        force[5] = x3026;
        force[6] = x3039;
    }
}
/// `dietmaier_6_6` with the `exact` formulation.
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
/// `dietmaier_6_6` with the `exact` formulation. At run-time parameter values (`Exact::with_parameters`).
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
    name: "dietmaier_6_6",
    t_end: T_END,
    formulations: &[(Formulation::Exact, &Exact as &(dyn Mechanism + Sync))],
    reduced: None,
    origin: Origin::Compiled {
        file: concat!(
            env!("CARGO_MANIFEST_DIR"), "/../../../", "mechanisms/dietmaier_6_6.toml"
        ),
        hash: 11384551771382902092u64,
        parameters: &[],
    },
    run_time: Some(&RUN_TIME_ENTRY),
};
