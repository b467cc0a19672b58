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
    BodyInfo, Entry, Formulation, JointInfo, JointKind, KinematicOutputs, LegInfo,
    Mechanism, MechanismInfo, NewtonOutputs, Origin, PlatformInfo, Rotation,
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
    let x1337 = x64 + k[0];
    let x1339 = x82 + k[1];
    let x1341 = x114 + k[2];
    let x1343 = x156 + k[3];
    let x1345 = x194 + k[4];
    let x1347 = x243 + k[5];
    out[0] = x1337;
    out[1] = x1339;
    out[2] = x1341;
    out[3] = x1343;
    out[4] = x1345;
    out[5] = x1347;
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
    let x1337 = x64 + k[0];
    let x1339 = x82 + k[1];
    let x1341 = x114 + k[2];
    let x1343 = x156 + k[3];
    let x1345 = s[57] + k[4];
    phi[0] = x1337;
    phi_q[0] = x258;
    phi_q[1] = x289;
    phi_q[2] = x295;
    phi_t[0] = 0.0;
    gamma[0] = x1020;
    phi[1] = x1339;
    phi_q[3] = x264;
    phi_q[4] = x290;
    phi_q[5] = x296;
    phi_q[6] = x315;
    phi_q[7] = x425;
    phi_q[8] = x502;
    phi_q[9] = x572;
    phi_t[1] = 0.0;
    gamma[1] = x1021;
    phi[2] = x1341;
    phi_q[10] = x270;
    phi_q[11] = x291;
    phi_q[12] = x297;
    phi_q[13] = x336;
    phi_q[14] = x438;
    phi_q[15] = x518;
    phi_q[16] = x579;
    phi_t[2] = 0.0;
    gamma[2] = x1022;
    phi[3] = x1343;
    phi_q[17] = x276;
    phi_q[18] = x292;
    phi_q[19] = x298;
    phi_q[20] = x363;
    phi_q[21] = x456;
    phi_q[22] = x535;
    phi_q[23] = x590;
    phi_t[3] = 0.0;
    gamma[3] = x1023;
    phi[4] = x1345;
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
    let x1347 = x243 + k[5];
    phi_q[30] = x602;
    phi_t[4] = 0.0;
    gamma[4] = x1024;
    phi[5] = x1347;
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
        let x1337 = x64 + k[0];
        let x1339 = x82 + k[1];
        let x1341 = x114 + k[2];
        let x1343 = x156 + k[3];
        let x1345 = x194 + k[4];
        let x1347 = x243 + k[5];
        phi[0] = x1337;
        phi_q[0] = x258;
        phi_q[1] = x289;
        phi_q[2] = x295;
        phi[1] = x1339;
        phi_q[3] = x264;
        phi_q[4] = x290;
        phi_q[5] = x296;
        phi_q[6] = x315;
        phi_q[7] = x425;
        phi_q[8] = x502;
        phi_q[9] = x572;
        phi[2] = x1341;
        phi_q[10] = x270;
        phi_q[11] = x291;
        phi_q[12] = x297;
        phi_q[13] = x336;
        phi_q[14] = x438;
        phi_q[15] = x518;
        phi_q[16] = x579;
        phi[3] = x1343;
        phi_q[17] = x276;
        phi_q[18] = x292;
        phi_q[19] = x298;
        phi_q[20] = x363;
        phi_q[21] = x456;
        phi_q[22] = x535;
        phi_q[23] = x590;
        phi[4] = x1345;
        phi_q[24] = x282;
        phi_q[25] = x293;
        phi_q[26] = x299;
        phi_q[27] = x387;
        phi_q[28] = x472;
        phi_q[29] = x549;
        phi_q[30] = x602;
        phi[5] = x1347;
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
}
/// `dietmaier_6_6` with the `exact` formulation.
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
/// `dietmaier_6_6` with the `exact` formulation. At run-time parameter values (`Exact::with_parameters`).
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
