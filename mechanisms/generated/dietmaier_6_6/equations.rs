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
/// Constraint residual Φ(q, t).
pub fn phi(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
    let _ = t;
    phi_part_0(q, out);
}
#[inline(never)]
fn phi_part_0(q: &[f64; 7], out: &mut [f64; 7]) {
    let x14 = q[3] * q[3];
    let x15 = q[4] * q[4];
    let x16 = q[5] * q[5];
    let x17 = q[6] * q[6];
    let x18 = x14 + x15;
    let x19 = 2.0 * x18;
    let x21 = x19 - 1.0;
    let x22 = x14 + x16;
    let x23 = 2.0 * x22;
    let x24 = x23 - 1.0;
    let x25 = x14 + x17;
    let x26 = 2.0 * x25;
    let x27 = x26 - 1.0;
    let x28 = q[4] * q[5];
    let x29 = 2.0 * x28;
    let x30 = q[3] * q[6];
    let x32 = 2.0 * x30;
    let x34 = x29 - x32;
    let x35 = q[4] * q[6];
    let x36 = 2.0 * x35;
    let x37 = q[3] * q[5];
    let x38 = 2.0 * x37;
    let x39 = x36 + x38;
    let x40 = x29 + x32;
    let x41 = q[5] * q[6];
    let x42 = 2.0 * x41;
    let x43 = q[3] * q[4];
    let x45 = 2.0 * x43;
    let x47 = x42 - x45;
    let x50 = x36 - x38;
    let x51 = x42 + x45;
    let x53 = q[0] * q[0];
    let x54 = q[1] * q[1];
    let x55 = q[2] * q[2];
    let x56 = x53 + x54;
    let x57 = x55 + x56;
    let x58 = x57.sqrt();
    let x59 = x58 - 1.0;
    let x62 = x21 * 0.542805;
    let x63 = x40 * 0.542805;
    let x64 = x50 * 0.542805;
    let x65 = q[0] + x62;
    let x66 = q[1] + x63;
    let x67 = q[2] + x64;
    let x69 = x65 - 1.107915;
    let x70 = x69 * x69;
    let x71 = x66 * x66;
    let x72 = x67 * x67;
    let x73 = x70 + x71;
    let x74 = x72 + x73;
    let x75 = x74.sqrt();
    let x77 = x75 - 0.645275;
    let x82 = x21 * 0.956919;
    let x84 = x34 * 0.528915;
    let x86 = x82 - x84;
    let x87 = x40 * 0.956919;
    let x88 = x24 * 0.528915;
    let x90 = x87 - x88;
    let x91 = x50 * 0.956919;
    let x92 = x51 * 0.528915;
    let x94 = x91 - x92;
    let x95 = q[0] + x86;
    let x96 = q[1] + x90;
    let x97 = q[2] + x94;
    let x99 = x95 - 0.549094;
    let x101 = x96 - 0.756063;
    let x102 = x99 * x99;
    let x103 = x101 * x101;
    let x104 = x97 * x97;
    let x105 = x102 + x103;
    let x106 = x104 + x105;
    let x107 = x106.sqrt();
    let x109 = x107 - 1.086284;
    let x116 = x21 * 0.665885;
    let x118 = x34 * 0.353482;
    let x120 = x39 * 1.402538;
    let x121 = x116 - x118;
    let x122 = x120 + x121;
    let x123 = x40 * 0.665885;
    let x124 = x24 * 0.353482;
    let x126 = x47 * 1.402538;
    let x127 = x123 - x124;
    let x128 = x126 + x127;
    let x129 = x50 * 0.665885;
    let x130 = x51 * 0.353482;
    let x132 = x27 * 1.402538;
    let x133 = x129 - x130;
    let x134 = x132 + x133;
    let x135 = q[0] + x122;
    let x136 = q[1] + x128;
    let x137 = q[2] + x134;
    let x139 = x135 - 0.735077;
    let x141 = x136 + 0.223935;
    let x143 = x137 - 0.525991;
    let x144 = x139 * x139;
    let x145 = x141 * x141;
    let x146 = x143 * x143;
    let x147 = x144 + x145;
    let x148 = x146 + x147;
    let x149 = x148.sqrt();
    let x151 = x149 - 1.503439;
    let x158 = x21 * 0.478359;
    let x159 = x34 * 1.158742;
    let x160 = x39 * 0.107672;
    let x161 = x158 + x159;
    let x162 = x160 + x161;
    let x163 = x40 * 0.478359;
    let x164 = x24 * 1.158742;
    let x165 = x47 * 0.107672;
    let x166 = x163 + x164;
    let x167 = x165 + x166;
    let x168 = x50 * 0.478359;
    let x169 = x51 * 1.158742;
    let x170 = x27 * 0.107672;
    let x171 = x168 + x169;
    let x172 = x170 + x171;
    let x173 = q[0] + x162;
    let x174 = q[1] + x167;
    let x175 = q[2] + x172;
    let x177 = x173 - 0.514188;
    let x179 = x174 + 0.526063;
    let x181 = x175 + 0.368418;
    let x182 = x177 * x177;
    let x183 = x179 * x179;
    let x184 = x181 * x181;
    let x185 = x182 + x183;
    let x186 = x184 + x185;
    let x187 = x186.sqrt();
    let x189 = x187 - 1.281933;
    let x197 = x21 * 0.137087;
    let x200 = x34 * 0.235121;
    let x202 = x39 * 0.353913;
    let x203 = x197 + x200;
    let x205 = x202 - x203;
    let x206 = x40 * 0.137087;
    let x208 = x24 * 0.235121;
    let x210 = x47 * 0.353913;
    let x211 = x206 + x208;
    let x213 = x210 - x211;
    let x214 = x50 * 0.137087;
    let x216 = x51 * 0.235121;
    let x218 = x27 * 0.353913;
    let x219 = x214 + x216;
    let x221 = x218 - x219;
    let x222 = q[0] + x205;
    let x223 = q[1] + x213;
    let x224 = q[2] + x221;
    let x226 = x222 - 0.590473;
    let x228 = x223 - 0.094733;
    let x230 = x224 + 0.205018;
    let x231 = x226 * x226;
    let x232 = x228 * x228;
    let x233 = x230 * x230;
    let x234 = x231 + x232;
    let x235 = x233 + x234;
    let x236 = x235.sqrt();
    let x238 = x236 - 0.771071;
    let x239 = x16 + x18;
    let x240 = x17 + x239;
    let x241 = x240 - 1.0;
    out[0] = x59;
    out[1] = x77;
    out[2] = x109;
    out[3] = x151;
    out[4] = x189;
    out[5] = x238;
    out[6] = x241;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 42] = out.try_into().expect("out must have 42 entries");
    let _ = t;
    phi_q_part_0(q, out);
}
#[inline(never)]
fn phi_q_part_0(q: &[f64; 7], out: &mut [f64; 42]) {
    let x14 = q[3] * q[3];
    let x15 = q[4] * q[4];
    let x16 = q[5] * q[5];
    let x17 = q[6] * q[6];
    let x18 = x14 + x15;
    let x19 = 2.0 * x18;
    let x21 = x19 - 1.0;
    let x22 = x14 + x16;
    let x23 = 2.0 * x22;
    let x24 = x23 - 1.0;
    let x25 = x14 + x17;
    let x26 = 2.0 * x25;
    let x27 = x26 - 1.0;
    let x28 = q[4] * q[5];
    let x29 = 2.0 * x28;
    let x30 = q[3] * q[6];
    let x32 = 2.0 * x30;
    let x34 = x29 - x32;
    let x35 = q[4] * q[6];
    let x36 = 2.0 * x35;
    let x37 = q[3] * q[5];
    let x38 = 2.0 * x37;
    let x39 = x36 + x38;
    let x40 = x29 + x32;
    let x41 = q[5] * q[6];
    let x42 = 2.0 * x41;
    let x43 = q[3] * q[4];
    let x45 = 2.0 * x43;
    let x47 = x42 - x45;
    let x50 = x36 - x38;
    let x51 = x42 + x45;
    let x53 = q[0] * q[0];
    let x54 = q[1] * q[1];
    let x55 = q[2] * q[2];
    let x56 = x53 + x54;
    let x57 = x55 + x56;
    let x58 = x57.sqrt();
    let x62 = x21 * 0.542805;
    let x63 = x40 * 0.542805;
    let x64 = x50 * 0.542805;
    let x65 = q[0] + x62;
    let x66 = q[1] + x63;
    let x67 = q[2] + x64;
    let x69 = x65 - 1.107915;
    let x70 = x69 * x69;
    let x71 = x66 * x66;
    let x72 = x67 * x67;
    let x73 = x70 + x71;
    let x74 = x72 + x73;
    let x75 = x74.sqrt();
    let x82 = x21 * 0.956919;
    let x84 = x34 * 0.528915;
    let x86 = x82 - x84;
    let x87 = x40 * 0.956919;
    let x88 = x24 * 0.528915;
    let x90 = x87 - x88;
    let x91 = x50 * 0.956919;
    let x92 = x51 * 0.528915;
    let x94 = x91 - x92;
    let x95 = q[0] + x86;
    let x96 = q[1] + x90;
    let x97 = q[2] + x94;
    let x99 = x95 - 0.549094;
    let x101 = x96 - 0.756063;
    let x102 = x99 * x99;
    let x103 = x101 * x101;
    let x104 = x97 * x97;
    let x105 = x102 + x103;
    let x106 = x104 + x105;
    let x107 = x106.sqrt();
    let x116 = x21 * 0.665885;
    let x118 = x34 * 0.353482;
    let x120 = x39 * 1.402538;
    let x121 = x116 - x118;
    let x122 = x120 + x121;
    let x123 = x40 * 0.665885;
    let x124 = x24 * 0.353482;
    let x126 = x47 * 1.402538;
    let x127 = x123 - x124;
    let x128 = x126 + x127;
    let x129 = x50 * 0.665885;
    let x130 = x51 * 0.353482;
    let x132 = x27 * 1.402538;
    let x133 = x129 - x130;
    let x134 = x132 + x133;
    let x135 = q[0] + x122;
    let x136 = q[1] + x128;
    let x137 = q[2] + x134;
    let x139 = x135 - 0.735077;
    let x141 = x136 + 0.223935;
    let x143 = x137 - 0.525991;
    let x144 = x139 * x139;
    let x145 = x141 * x141;
    let x146 = x143 * x143;
    let x147 = x144 + x145;
    let x148 = x146 + x147;
    let x149 = x148.sqrt();
    let x158 = x21 * 0.478359;
    let x159 = x34 * 1.158742;
    let x160 = x39 * 0.107672;
    let x161 = x158 + x159;
    let x162 = x160 + x161;
    let x163 = x40 * 0.478359;
    let x164 = x24 * 1.158742;
    let x165 = x47 * 0.107672;
    let x166 = x163 + x164;
    let x167 = x165 + x166;
    let x168 = x50 * 0.478359;
    let x169 = x51 * 1.158742;
    let x170 = x27 * 0.107672;
    let x171 = x168 + x169;
    let x172 = x170 + x171;
    let x173 = q[0] + x162;
    let x174 = q[1] + x167;
    let x175 = q[2] + x172;
    let x177 = x173 - 0.514188;
    let x179 = x174 + 0.526063;
    let x181 = x175 + 0.368418;
    let x182 = x177 * x177;
    let x183 = x179 * x179;
    let x184 = x181 * x181;
    let x185 = x182 + x183;
    let x186 = x184 + x185;
    let x187 = x186.sqrt();
    let x197 = x21 * 0.137087;
    let x200 = x34 * 0.235121;
    let x202 = x39 * 0.353913;
    let x203 = x197 + x200;
    let x205 = x202 - x203;
    let x206 = x40 * 0.137087;
    let x208 = x24 * 0.235121;
    let x210 = x47 * 0.353913;
    let x211 = x206 + x208;
    let x213 = x210 - x211;
    let x214 = x50 * 0.137087;
    let x216 = x51 * 0.235121;
    let x218 = x27 * 0.353913;
    let x219 = x214 + x216;
    let x221 = x218 - x219;
    let x222 = q[0] + x205;
    let x223 = q[1] + x213;
    let x224 = q[2] + x221;
    let x226 = x222 - 0.590473;
    let x228 = x223 - 0.094733;
    let x230 = x224 + 0.205018;
    let x231 = x226 * x226;
    let x232 = x228 * x228;
    let x233 = x230 * x230;
    let x234 = x231 + x232;
    let x235 = x233 + x234;
    let x236 = x235.sqrt();
    let x242 = q[3] * 2.0;
    let x243 = q[4] * 2.0;
    let x244 = q[5] * 2.0;
    let x245 = q[6] * 2.0;
    let x246 = q[0] * 2.0;
    let x247 = q[1] * 2.0;
    let x248 = q[2] * 2.0;
    let x249 = 2.0 * x58;
    let x250 = 1.0 / x249;
    let x251 = x246 * x250;
    let x252 = 2.0 * x69;
    let x253 = 2.0 * x66;
    let x254 = 2.0 * x67;
    let x255 = 2.0 * x75;
    let x256 = 1.0 / x255;
    let x257 = x252 * x256;
    let x258 = 2.0 * x99;
    let x259 = 2.0 * x101;
    let x260 = 2.0 * x97;
    let x261 = 2.0 * x107;
    let x262 = 1.0 / x261;
    let x263 = x258 * x262;
    let x264 = 2.0 * x139;
    let x265 = 2.0 * x141;
    let x266 = 2.0 * x143;
    let x267 = 2.0 * x149;
    let x268 = 1.0 / x267;
    let x269 = x264 * x268;
    let x270 = 2.0 * x177;
    let x271 = 2.0 * x179;
    let x272 = 2.0 * x181;
    let x273 = 2.0 * x187;
    let x274 = 1.0 / x273;
    let x275 = x270 * x274;
    let x276 = 2.0 * x226;
    let x277 = 2.0 * x228;
    let x278 = 2.0 * x230;
    let x279 = 2.0 * x236;
    let x280 = 1.0 / x279;
    let x281 = x276 * x280;
    let x282 = x247 * x250;
    let x283 = x253 * x256;
    let x284 = x259 * x262;
    let x285 = x265 * x268;
    let x286 = x271 * x274;
    let x287 = x277 * x280;
    let x288 = x248 * x250;
    let x289 = x254 * x256;
    let x290 = x260 * x262;
    let x291 = x266 * x268;
    let x292 = x272 * x274;
    let x293 = x278 * x280;
    let x294 = 2.0 * x242;
    let x298 = 0.542805 * x294;
    let x299 = 0.542805 * x245;
    let x300 = 0.542805 * x244;
    let x302 = x252 * x298;
    let x303 = x253 * x299;
    let x304 = x254 * x300;
    let x306 = x302 + x303;
    let x307 = x306 - x304;
    let x308 = x256 * x307;
    let x309 = 0.956919 * x294;
    let x310 = 0.528915 * x245;
    let x312 = x309 + x310;
    let x313 = 0.956919 * x245;
    let x314 = 0.528915 * x294;
    let x316 = x313 - x314;
    let x317 = 0.956919 * x244;
    let x319 = 0.528915 * x243;
    let x321 = x317 + x319;
    let x323 = x258 * x312;
    let x324 = x259 * x316;
    let x325 = x260 * x321;
    let x327 = x323 + x324;
    let x328 = x327 - x325;
    let x329 = x262 * x328;
    let x330 = 0.665885 * x294;
    let x331 = 0.353482 * x245;
    let x333 = 1.402538 * x244;
    let x334 = x330 + x331;
    let x335 = x333 + x334;
    let x336 = 0.665885 * x245;
    let x337 = 0.353482 * x294;
    let x339 = 1.402538 * x243;
    let x341 = x336 - x337;
    let x342 = x341 - x339;
    let x343 = 0.665885 * x244;
    let x345 = 0.353482 * x243;
    let x347 = 1.402538 * x294;
    let x348 = x343 + x345;
    let x350 = x347 - x348;
    let x351 = x264 * x335;
    let x352 = x265 * x342;
    let x353 = x266 * x350;
    let x354 = x351 + x352;
    let x355 = x353 + x354;
    let x356 = x268 * x355;
    let x357 = 0.478359 * x294;
    let x358 = 1.158742 * x245;
    let x360 = 0.107672 * x244;
    let x361 = x357 - x358;
    let x362 = x360 + x361;
    let x363 = 0.478359 * x245;
    let x364 = 1.158742 * x294;
    let x365 = 0.107672 * x243;
    let x367 = x363 + x364;
    let x368 = x367 - x365;
    let x369 = 0.478359 * x244;
    let x371 = 1.158742 * x243;
    let x372 = 0.107672 * x294;
    let x373 = x371 - x369;
    let x374 = x372 + x373;
    let x375 = x270 * x362;
    let x376 = x271 * x368;
    let x377 = x272 * x374;
    let x378 = x375 + x376;
    let x379 = x377 + x378;
    let x380 = x274 * x379;
    let x381 = 0.137087 * x294;
    let x382 = 0.235121 * x245;
    let x384 = 0.353913 * x244;
    let x385 = x381 - x382;
    let x387 = x384 - x385;
    let x388 = 0.137087 * x245;
    let x389 = 0.235121 * x294;
    let x390 = 0.353913 * x243;
    let x392 = x388 + x389;
    let x394 = x390 + x392;
    let x396 = 0.137087 * x244;
    let x398 = 0.235121 * x243;
    let x399 = 0.353913 * x294;
    let x400 = x398 - x396;
    let x402 = x399 - x400;
    let x403 = x276 * x387;
    let x404 = x277 * x394;
    let x406 = x278 * x402;
    let x407 = x403 - x404;
    let x408 = x406 + x407;
    let x409 = x280 * x408;
    let x410 = 2.0 * x243;
    let x412 = 0.542805 * x410;
    let x413 = x252 * x412;
    let x414 = x253 * x300;
    let x415 = x254 * x299;
    let x416 = x413 + x414;
    let x417 = x415 + x416;
    let x418 = x256 * x417;
    let x419 = 0.956919 * x410;
    let x420 = 0.528915 * x244;
    let x422 = x419 - x420;
    let x423 = 0.528915 * x242;
    let x425 = x313 - x423;
    let x426 = x258 * x422;
    let x427 = x259 * x317;
    let x428 = x260 * x425;
    let x429 = x426 + x427;
    let x430 = x428 + x429;
    let x431 = x262 * x430;
    let x432 = 0.665885 * x410;
    let x433 = 0.353482 * x244;
    let x435 = 1.402538 * x245;
    let x436 = x432 - x433;
    let x437 = x435 + x436;
    let x438 = 1.402538 * x242;
    let x440 = x343 - x438;
    let x441 = 0.353482 * x242;
    let x443 = x336 - x441;
    let x444 = x264 * x437;
    let x445 = x265 * x440;
    let x446 = x266 * x443;
    let x447 = x444 + x445;
    let x448 = x446 + x447;
    let x449 = x268 * x448;
    let x450 = 0.478359 * x410;
    let x451 = 1.158742 * x244;
    let x452 = 0.107672 * x245;
    let x453 = x450 + x451;
    let x454 = x452 + x453;
    let x455 = 0.107672 * x242;
    let x457 = x369 - x455;
    let x458 = 1.158742 * x242;
    let x459 = x363 + x458;
    let x460 = x270 * x454;
    let x461 = x271 * x457;
    let x462 = x272 * x459;
    let x463 = x460 + x461;
    let x464 = x462 + x463;
    let x465 = x274 * x464;
    let x466 = 0.137087 * x410;
    let x467 = 0.235121 * x244;
    let x468 = 0.353913 * x245;
    let x469 = x466 + x467;
    let x471 = x468 - x469;
    let x472 = 0.353913 * x242;
    let x474 = x396 + x472;
    let x476 = 0.235121 * x242;
    let x477 = x388 + x476;
    let x479 = x276 * x471;
    let x480 = x277 * x474;
    let x482 = x278 * x477;
    let x484 = x479 - x480;
    let x485 = x484 - x482;
    let x486 = x280 * x485;
    let x487 = 2.0 * x244;
    let x488 = 0.542805 * x243;
    let x489 = 0.542805 * x242;
    let x491 = x253 * x488;
    let x492 = x254 * x489;
    let x494 = x491 - x492;
    let x495 = x256 * x494;
    let x496 = 0.956919 * x243;
    let x497 = 0.528915 * x487;
    let x499 = x496 - x497;
    let x500 = 0.956919 * x242;
    let x502 = x310 + x500;
    let x504 = x258 * x319;
    let x506 = x259 * x499;
    let x507 = x260 * x502;
    let x509 = x506 - x504;
    let x510 = x509 - x507;
    let x511 = x262 * x510;
    let x512 = x438 - x345;
    let x513 = 0.665885 * x243;
    let x514 = 0.353482 * x487;
    let x516 = x513 - x514;
    let x517 = x435 + x516;
    let x518 = 0.665885 * x242;
    let x520 = x331 + x518;
    let x522 = x264 * x512;
    let x523 = x265 * x517;
    let x524 = x266 * x520;
    let x526 = x522 + x523;
    let x527 = x526 - x524;
    let x528 = x268 * x527;
    let x529 = x371 + x455;
    let x530 = 0.478359 * x243;
    let x531 = 1.158742 * x487;
    let x532 = x530 + x531;
    let x533 = x452 + x532;
    let x534 = 0.478359 * x242;
    let x536 = x358 - x534;
    let x537 = x270 * x529;
    let x538 = x271 * x533;
    let x539 = x272 * x536;
    let x540 = x537 + x538;
    let x541 = x539 + x540;
    let x542 = x274 * x541;
    let x544 = x472 - x398;
    let x545 = 0.137087 * x243;
    let x546 = 0.235121 * x487;
    let x547 = x545 + x546;
    let x549 = x468 - x547;
    let x550 = 0.137087 * x242;
    let x552 = x382 - x550;
    let x554 = x276 * x544;
    let x555 = x277 * x549;
    let x556 = x278 * x552;
    let x558 = x554 + x555;
    let x559 = x558 - x556;
    let x560 = x280 * x559;
    let x561 = 2.0 * x245;
    let x562 = x253 * x489;
    let x563 = x254 * x488;
    let x564 = x562 + x563;
    let x565 = x256 * x564;
    let x566 = x496 - x420;
    let x567 = x258 * x423;
    let x568 = x259 * x500;
    let x569 = x260 * x566;
    let x570 = x567 + x568;
    let x571 = x569 + x570;
    let x572 = x262 * x571;
    let x573 = x339 + x441;
    let x574 = x333 + x518;
    let x575 = 1.402538 * x561;
    let x576 = x513 - x433;
    let x577 = x575 + x576;
    let x578 = x264 * x573;
    let x579 = x265 * x574;
    let x580 = x266 * x577;
    let x581 = x578 + x579;
    let x582 = x580 + x581;
    let x583 = x268 * x582;
    let x585 = x365 - x458;
    let x586 = x360 + x534;
    let x587 = 0.107672 * x561;
    let x588 = x451 + x530;
    let x589 = x587 + x588;
    let x590 = x270 * x585;
    let x591 = x271 * x586;
    let x592 = x272 * x589;
    let x593 = x590 + x591;
    let x594 = x592 + x593;
    let x595 = x274 * x594;
    let x597 = x390 + x476;
    let x598 = x384 - x550;
    let x599 = 0.353913 * x561;
    let x600 = x467 + x545;
    let x602 = x599 - x600;
    let x603 = x276 * x597;
    let x604 = x277 * x598;
    let x605 = x278 * x602;
    let x606 = x603 + x604;
    let x607 = x605 + x606;
    let x608 = x280 * x607;
    out[0] = x251;
    out[1] = x282;
    out[2] = x288;
    out[3] = x257;
    out[4] = x283;
    out[5] = x289;
    out[6] = x308;
    out[7] = x418;
    out[8] = x495;
    out[9] = x565;
    out[10] = x263;
    out[11] = x284;
    out[12] = x290;
    out[13] = x329;
    out[14] = x431;
    out[15] = x511;
    out[16] = x572;
    out[17] = x269;
    out[18] = x285;
    out[19] = x291;
    out[20] = x356;
    out[21] = x449;
    out[22] = x528;
    out[23] = x583;
    out[24] = x275;
    out[25] = x286;
    out[26] = x292;
    out[27] = x380;
    out[28] = x465;
    out[29] = x542;
    out[30] = x595;
    out[31] = x281;
    out[32] = x287;
    out[33] = x293;
    out[34] = x409;
    out[35] = x486;
    out[36] = x560;
    out[37] = x608;
    out[38] = x242;
    out[39] = x243;
    out[40] = x244;
    out[41] = x245;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
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
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
    let _ = t;
    gamma_part_0(q, qd, out);
}
#[inline(never)]
fn gamma_part_0(q: &[f64; 7], qd: &[f64; 7], out: &mut [f64; 7]) {
    let x14 = q[3] * q[3];
    let x15 = q[4] * q[4];
    let x16 = q[5] * q[5];
    let x17 = q[6] * q[6];
    let x18 = x14 + x15;
    let x19 = 2.0 * x18;
    let x21 = x19 - 1.0;
    let x22 = x14 + x16;
    let x23 = 2.0 * x22;
    let x24 = x23 - 1.0;
    let x25 = x14 + x17;
    let x26 = 2.0 * x25;
    let x27 = x26 - 1.0;
    let x28 = q[4] * q[5];
    let x29 = 2.0 * x28;
    let x30 = q[3] * q[6];
    let x32 = 2.0 * x30;
    let x34 = x29 - x32;
    let x35 = q[4] * q[6];
    let x36 = 2.0 * x35;
    let x37 = q[3] * q[5];
    let x38 = 2.0 * x37;
    let x39 = x36 + x38;
    let x40 = x29 + x32;
    let x41 = q[5] * q[6];
    let x42 = 2.0 * x41;
    let x43 = q[3] * q[4];
    let x45 = 2.0 * x43;
    let x47 = x42 - x45;
    let x50 = x36 - x38;
    let x51 = x42 + x45;
    let x53 = q[0] * q[0];
    let x54 = q[1] * q[1];
    let x55 = q[2] * q[2];
    let x56 = x53 + x54;
    let x57 = x55 + x56;
    let x58 = x57.sqrt();
    let x62 = x21 * 0.542805;
    let x63 = x40 * 0.542805;
    let x64 = x50 * 0.542805;
    let x65 = q[0] + x62;
    let x66 = q[1] + x63;
    let x67 = q[2] + x64;
    let x69 = x65 - 1.107915;
    let x70 = x69 * x69;
    let x71 = x66 * x66;
    let x72 = x67 * x67;
    let x73 = x70 + x71;
    let x74 = x72 + x73;
    let x75 = x74.sqrt();
    let x82 = x21 * 0.956919;
    let x84 = x34 * 0.528915;
    let x86 = x82 - x84;
    let x87 = x40 * 0.956919;
    let x88 = x24 * 0.528915;
    let x90 = x87 - x88;
    let x91 = x50 * 0.956919;
    let x92 = x51 * 0.528915;
    let x94 = x91 - x92;
    let x95 = q[0] + x86;
    let x96 = q[1] + x90;
    let x97 = q[2] + x94;
    let x99 = x95 - 0.549094;
    let x101 = x96 - 0.756063;
    let x102 = x99 * x99;
    let x103 = x101 * x101;
    let x104 = x97 * x97;
    let x105 = x102 + x103;
    let x106 = x104 + x105;
    let x107 = x106.sqrt();
    let x116 = x21 * 0.665885;
    let x118 = x34 * 0.353482;
    let x120 = x39 * 1.402538;
    let x121 = x116 - x118;
    let x122 = x120 + x121;
    let x123 = x40 * 0.665885;
    let x124 = x24 * 0.353482;
    let x126 = x47 * 1.402538;
    let x127 = x123 - x124;
    let x128 = x126 + x127;
    let x129 = x50 * 0.665885;
    let x130 = x51 * 0.353482;
    let x132 = x27 * 1.402538;
    let x133 = x129 - x130;
    let x134 = x132 + x133;
    let x135 = q[0] + x122;
    let x136 = q[1] + x128;
    let x137 = q[2] + x134;
    let x139 = x135 - 0.735077;
    let x141 = x136 + 0.223935;
    let x143 = x137 - 0.525991;
    let x144 = x139 * x139;
    let x145 = x141 * x141;
    let x146 = x143 * x143;
    let x147 = x144 + x145;
    let x148 = x146 + x147;
    let x149 = x148.sqrt();
    let x158 = x21 * 0.478359;
    let x159 = x34 * 1.158742;
    let x160 = x39 * 0.107672;
    let x161 = x158 + x159;
    let x162 = x160 + x161;
    let x163 = x40 * 0.478359;
    let x164 = x24 * 1.158742;
    let x165 = x47 * 0.107672;
    let x166 = x163 + x164;
    let x167 = x165 + x166;
    let x168 = x50 * 0.478359;
    let x169 = x51 * 1.158742;
    let x170 = x27 * 0.107672;
    let x171 = x168 + x169;
    let x172 = x170 + x171;
    let x173 = q[0] + x162;
    let x174 = q[1] + x167;
    let x175 = q[2] + x172;
    let x177 = x173 - 0.514188;
    let x179 = x174 + 0.526063;
    let x181 = x175 + 0.368418;
    let x182 = x177 * x177;
    let x183 = x179 * x179;
    let x184 = x181 * x181;
    let x185 = x182 + x183;
    let x186 = x184 + x185;
    let x187 = x186.sqrt();
    let x197 = x21 * 0.137087;
    let x200 = x34 * 0.235121;
    let x202 = x39 * 0.353913;
    let x203 = x197 + x200;
    let x205 = x202 - x203;
    let x206 = x40 * 0.137087;
    let x208 = x24 * 0.235121;
    let x210 = x47 * 0.353913;
    let x211 = x206 + x208;
    let x213 = x210 - x211;
    let x214 = x50 * 0.137087;
    let x216 = x51 * 0.235121;
    let x218 = x27 * 0.353913;
    let x219 = x214 + x216;
    let x221 = x218 - x219;
    let x222 = q[0] + x205;
    let x223 = q[1] + x213;
    let x224 = q[2] + x221;
    let x226 = x222 - 0.590473;
    let x228 = x223 - 0.094733;
    let x230 = x224 + 0.205018;
    let x231 = x226 * x226;
    let x232 = x228 * x228;
    let x233 = x230 * x230;
    let x234 = x231 + x232;
    let x235 = x233 + x234;
    let x236 = x235.sqrt();
    let x242 = q[3] * 2.0;
    let x243 = q[4] * 2.0;
    let x244 = q[5] * 2.0;
    let x245 = q[6] * 2.0;
    let x246 = q[0] * 2.0;
    let x247 = q[1] * 2.0;
    let x248 = q[2] * 2.0;
    let x249 = 2.0 * x58;
    let x250 = 1.0 / x249;
    let x252 = 2.0 * x69;
    let x253 = 2.0 * x66;
    let x254 = 2.0 * x67;
    let x255 = 2.0 * x75;
    let x256 = 1.0 / x255;
    let x258 = 2.0 * x99;
    let x259 = 2.0 * x101;
    let x260 = 2.0 * x97;
    let x261 = 2.0 * x107;
    let x262 = 1.0 / x261;
    let x264 = 2.0 * x139;
    let x265 = 2.0 * x141;
    let x266 = 2.0 * x143;
    let x267 = 2.0 * x149;
    let x268 = 1.0 / x267;
    let x270 = 2.0 * x177;
    let x271 = 2.0 * x179;
    let x272 = 2.0 * x181;
    let x273 = 2.0 * x187;
    let x274 = 1.0 / x273;
    let x276 = 2.0 * x226;
    let x277 = 2.0 * x228;
    let x278 = 2.0 * x230;
    let x279 = 2.0 * x236;
    let x280 = 1.0 / x279;
    let x616 = x242 * qd[3];
    let x617 = x243 * qd[4];
    let x618 = x244 * qd[5];
    let x619 = x245 * qd[6];
    let x620 = x616 + x617;
    let x621 = 2.0 * x620;
    let x622 = x616 + x618;
    let x623 = 2.0 * x622;
    let x624 = x616 + x619;
    let x625 = 2.0 * x624;
    let x626 = q[5] * qd[4];
    let x627 = q[4] * qd[5];
    let x628 = x626 + x627;
    let x629 = 2.0 * x628;
    let x630 = q[6] * qd[3];
    let x631 = q[3] * qd[6];
    let x632 = x630 + x631;
    let x633 = 2.0 * x632;
    let x635 = x629 - x633;
    let x636 = q[6] * qd[4];
    let x637 = q[4] * qd[6];
    let x638 = x636 + x637;
    let x639 = 2.0 * x638;
    let x640 = q[5] * qd[3];
    let x641 = q[3] * qd[5];
    let x642 = x640 + x641;
    let x643 = 2.0 * x642;
    let x644 = x639 + x643;
    let x645 = x629 + x633;
    let x646 = q[6] * qd[5];
    let x647 = q[5] * qd[6];
    let x648 = x646 + x647;
    let x649 = 2.0 * x648;
    let x650 = q[4] * qd[3];
    let x651 = q[3] * qd[4];
    let x652 = x650 + x651;
    let x653 = 2.0 * x652;
    let x655 = x649 - x653;
    let x657 = x639 - x643;
    let x658 = x649 + x653;
    let x659 = x246 * qd[0];
    let x660 = x247 * qd[1];
    let x661 = x248 * qd[2];
    let x662 = x659 + x660;
    let x663 = x661 + x662;
    let x664 = x250 * x663;
    let x665 = 0.542805 * x621;
    let x666 = 0.542805 * x645;
    let x667 = 0.542805 * x657;
    let x668 = qd[0] + x665;
    let x669 = qd[1] + x666;
    let x670 = qd[2] + x667;
    let x671 = x252 * x668;
    let x672 = x253 * x669;
    let x673 = x254 * x670;
    let x674 = x671 + x672;
    let x675 = x673 + x674;
    let x676 = x256 * x675;
    let x677 = 0.956919 * x621;
    let x678 = 0.528915 * x635;
    let x680 = x677 - x678;
    let x681 = 0.956919 * x645;
    let x682 = 0.528915 * x623;
    let x684 = x681 - x682;
    let x685 = 0.956919 * x657;
    let x686 = 0.528915 * x658;
    let x688 = x685 - x686;
    let x689 = qd[0] + x680;
    let x690 = qd[1] + x684;
    let x691 = qd[2] + x688;
    let x692 = x258 * x689;
    let x693 = x259 * x690;
    let x694 = x260 * x691;
    let x695 = x692 + x693;
    let x696 = x694 + x695;
    let x697 = x262 * x696;
    let x698 = 0.665885 * x621;
    let x699 = 0.353482 * x635;
    let x701 = 1.402538 * x644;
    let x702 = x698 - x699;
    let x703 = x701 + x702;
    let x704 = 0.665885 * x645;
    let x705 = 0.353482 * x623;
    let x707 = 1.402538 * x655;
    let x708 = x704 - x705;
    let x709 = x707 + x708;
    let x710 = 0.665885 * x657;
    let x711 = 0.353482 * x658;
    let x713 = 1.402538 * x625;
    let x714 = x710 - x711;
    let x715 = x713 + x714;
    let x716 = qd[0] + x703;
    let x717 = qd[1] + x709;
    let x718 = qd[2] + x715;
    let x719 = x264 * x716;
    let x720 = x265 * x717;
    let x721 = x266 * x718;
    let x722 = x719 + x720;
    let x723 = x721 + x722;
    let x724 = x268 * x723;
    let x725 = 0.478359 * x621;
    let x726 = 1.158742 * x635;
    let x727 = 0.107672 * x644;
    let x728 = x725 + x726;
    let x729 = x727 + x728;
    let x730 = 0.478359 * x645;
    let x731 = 1.158742 * x623;
    let x732 = 0.107672 * x655;
    let x733 = x730 + x731;
    let x734 = x732 + x733;
    let x735 = 0.478359 * x657;
    let x736 = 1.158742 * x658;
    let x737 = 0.107672 * x625;
    let x738 = x735 + x736;
    let x739 = x737 + x738;
    let x740 = qd[0] + x729;
    let x741 = qd[1] + x734;
    let x742 = qd[2] + x739;
    let x743 = x270 * x740;
    let x744 = x271 * x741;
    let x745 = x272 * x742;
    let x746 = x743 + x744;
    let x747 = x745 + x746;
    let x748 = x274 * x747;
    let x749 = 0.137087 * x621;
    let x750 = 0.235121 * x635;
    let x751 = 0.353913 * x644;
    let x752 = x749 + x750;
    let x754 = x751 - x752;
    let x755 = 0.137087 * x645;
    let x756 = 0.235121 * x623;
    let x757 = 0.353913 * x655;
    let x758 = x755 + x756;
    let x760 = x757 - x758;
    let x761 = 0.137087 * x657;
    let x762 = 0.235121 * x658;
    let x763 = 0.353913 * x625;
    let x764 = x761 + x762;
    let x766 = x763 - x764;
    let x767 = qd[0] + x754;
    let x768 = qd[1] + x760;
    let x769 = qd[2] + x766;
    let x770 = x276 * x767;
    let x771 = x277 * x768;
    let x772 = x278 * x769;
    let x773 = x770 + x771;
    let x774 = x772 + x773;
    let x775 = x280 * x774;
    let x778 = 2.0 * qd[3];
    let x779 = 2.0 * qd[4];
    let x780 = 2.0 * qd[5];
    let x781 = 2.0 * qd[6];
    let x782 = 2.0 * qd[0];
    let x783 = 2.0 * qd[1];
    let x784 = 2.0 * qd[2];
    let x785 = 2.0 * x664;
    let x786 = x250 * x250;
    let x787 = x785 * x786;
    let x789 = 2.0 * x668;
    let x790 = 2.0 * x669;
    let x791 = 2.0 * x670;
    let x792 = 2.0 * x676;
    let x793 = x256 * x256;
    let x794 = x792 * x793;
    let x796 = 2.0 * x689;
    let x797 = 2.0 * x690;
    let x798 = 2.0 * x691;
    let x799 = 2.0 * x697;
    let x800 = x262 * x262;
    let x801 = x799 * x800;
    let x803 = 2.0 * x716;
    let x804 = 2.0 * x717;
    let x805 = 2.0 * x718;
    let x806 = 2.0 * x724;
    let x807 = x268 * x268;
    let x808 = x806 * x807;
    let x810 = 2.0 * x740;
    let x811 = 2.0 * x741;
    let x812 = 2.0 * x742;
    let x813 = 2.0 * x748;
    let x814 = x274 * x274;
    let x815 = x813 * x814;
    let x817 = 2.0 * x767;
    let x818 = 2.0 * x768;
    let x819 = 2.0 * x769;
    let x820 = 2.0 * x775;
    let x821 = x280 * x280;
    let x822 = x820 * x821;
    let x824 = qd[3] * x778;
    let x825 = qd[4] * x779;
    let x826 = qd[5] * x780;
    let x827 = qd[6] * x781;
    let x828 = x824 + x825;
    let x829 = 2.0 * x828;
    let x830 = x824 + x826;
    let x831 = 2.0 * x830;
    let x832 = x824 + x827;
    let x833 = 2.0 * x832;
    let x834 = qd[4] * qd[5];
    let x835 = x834 + x834;
    let x836 = 2.0 * x835;
    let x837 = qd[3] * qd[6];
    let x838 = x837 + x837;
    let x839 = 2.0 * x838;
    let x841 = x836 - x839;
    let x842 = qd[4] * qd[6];
    let x843 = x842 + x842;
    let x844 = 2.0 * x843;
    let x845 = qd[3] * qd[5];
    let x846 = x845 + x845;
    let x847 = 2.0 * x846;
    let x848 = x844 + x847;
    let x849 = x836 + x839;
    let x850 = qd[5] * qd[6];
    let x851 = x850 + x850;
    let x852 = 2.0 * x851;
    let x853 = qd[3] * qd[4];
    let x854 = x853 + x853;
    let x855 = 2.0 * x854;
    let x857 = x852 - x855;
    let x859 = x844 - x847;
    let x860 = x852 + x855;
    let x861 = qd[0] * x782;
    let x862 = qd[1] * x783;
    let x863 = qd[2] * x784;
    let x864 = x861 + x862;
    let x865 = x863 + x864;
    let x866 = x663 * x787;
    let x868 = x250 * x865;
    let x869 = x868 - x866;
    let x870 = 0.542805 * x829;
    let x871 = 0.542805 * x849;
    let x872 = 0.542805 * x859;
    let x873 = x668 * x789;
    let x874 = x252 * x870;
    let x875 = x873 + x874;
    let x876 = x669 * x790;
    let x877 = x253 * x871;
    let x878 = x876 + x877;
    let x879 = x670 * x791;
    let x880 = x254 * x872;
    let x881 = x879 + x880;
    let x882 = x875 + x878;
    let x883 = x881 + x882;
    let x884 = x675 * x794;
    let x886 = x256 * x883;
    let x887 = x886 - x884;
    let x888 = 0.956919 * x829;
    let x889 = 0.528915 * x841;
    let x891 = x888 - x889;
    let x892 = 0.956919 * x849;
    let x893 = 0.528915 * x831;
    let x895 = x892 - x893;
    let x896 = 0.956919 * x859;
    let x897 = 0.528915 * x860;
    let x899 = x896 - x897;
    let x900 = x689 * x796;
    let x901 = x258 * x891;
    let x902 = x900 + x901;
    let x903 = x690 * x797;
    let x904 = x259 * x895;
    let x905 = x903 + x904;
    let x906 = x691 * x798;
    let x907 = x260 * x899;
    let x908 = x906 + x907;
    let x909 = x902 + x905;
    let x910 = x908 + x909;
    let x911 = x696 * x801;
    let x913 = x262 * x910;
    let x914 = x913 - x911;
    let x915 = 0.665885 * x829;
    let x916 = 0.353482 * x841;
    let x918 = 1.402538 * x848;
    let x919 = x915 - x916;
    let x920 = x918 + x919;
    let x921 = 0.665885 * x849;
    let x922 = 0.353482 * x831;
    let x924 = 1.402538 * x857;
    let x925 = x921 - x922;
    let x926 = x924 + x925;
    let x927 = 0.665885 * x859;
    let x928 = 0.353482 * x860;
    let x930 = 1.402538 * x833;
    let x931 = x927 - x928;
    let x932 = x930 + x931;
    let x933 = x716 * x803;
    let x934 = x264 * x920;
    let x935 = x933 + x934;
    let x936 = x717 * x804;
    let x937 = x265 * x926;
    let x938 = x936 + x937;
    let x939 = x718 * x805;
    let x940 = x266 * x932;
    let x941 = x939 + x940;
    let x942 = x935 + x938;
    let x943 = x941 + x942;
    let x944 = x723 * x808;
    let x946 = x268 * x943;
    let x947 = x946 - x944;
    let x948 = 0.478359 * x829;
    let x949 = 1.158742 * x841;
    let x950 = 0.107672 * x848;
    let x951 = x948 + x949;
    let x952 = x950 + x951;
    let x953 = 0.478359 * x849;
    let x954 = 1.158742 * x831;
    let x955 = 0.107672 * x857;
    let x956 = x953 + x954;
    let x957 = x955 + x956;
    let x958 = 0.478359 * x859;
    let x959 = 1.158742 * x860;
    let x960 = 0.107672 * x833;
    let x961 = x958 + x959;
    let x962 = x960 + x961;
    let x963 = x740 * x810;
    let x964 = x270 * x952;
    let x965 = x963 + x964;
    let x966 = x741 * x811;
    let x967 = x271 * x957;
    let x968 = x966 + x967;
    let x969 = x742 * x812;
    let x970 = x272 * x962;
    let x971 = x969 + x970;
    let x972 = x965 + x968;
    let x973 = x971 + x972;
    let x974 = x747 * x815;
    let x976 = x274 * x973;
    let x977 = x976 - x974;
    let x978 = 0.137087 * x829;
    let x979 = 0.235121 * x841;
    let x980 = 0.353913 * x848;
    let x981 = x978 + x979;
    let x983 = x980 - x981;
    let x984 = 0.137087 * x849;
    let x985 = 0.235121 * x831;
    let x986 = 0.353913 * x857;
    let x987 = x984 + x985;
    let x989 = x986 - x987;
    let x990 = 0.137087 * x859;
    let x991 = 0.235121 * x860;
    let x992 = 0.353913 * x833;
    let x993 = x990 + x991;
    let x995 = x992 - x993;
    let x996 = x767 * x817;
    let x997 = x276 * x983;
    let x998 = x996 + x997;
    let x999 = x768 * x818;
    let x1000 = x277 * x989;
    let x1001 = x999 + x1000;
    let x1002 = x769 * x819;
    let x1003 = x278 * x995;
    let x1004 = x1002 + x1003;
    let x1005 = x998 + x1001;
    let x1006 = x1004 + x1005;
    let x1007 = x774 * x822;
    let x1009 = x280 * x1006;
    let x1010 = x1009 - x1007;
    let x1011 = x826 + x828;
    let x1012 = x827 + x1011;
    let x1013 = -x869;
    let x1014 = -x887;
    let x1015 = -x914;
    let x1016 = -x947;
    let x1017 = -x977;
    let x1018 = -x1010;
    let x1019 = -x1012;
    out[0] = x1013;
    out[1] = x1014;
    out[2] = x1015;
    out[3] = x1016;
    out[4] = x1017;
    out[5] = x1018;
    out[6] = x1019;
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
    let phi: &mut [f64; 7] = phi.try_into().expect("phi must have 7 entries");
    let phi_q: &mut [f64; 42] = phi_q.try_into().expect("phi_q must have 42 entries");
    let phi_t: &mut [f64; 7] = phi_t.try_into().expect("phi_t must have 7 entries");
    let gamma: &mut [f64; 7] = gamma.try_into().expect("gamma must have 7 entries");
    let _ = t;
    let mut s = [0.0f64; 155];
    eval_kinematics_shared_0(q, qd, t, &mut s);
    eval_kinematics_part_0(q, qd, &s, phi, phi_q, phi_t, gamma);
    eval_kinematics_part_1(q, qd, &s, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_shared_0(q: &[f64; 7], qd: &[f64; 7], _t: f64, s: &mut [f64; 155]) {
    let x14 = q[3] * q[3];
    s[0] = x14;
    let x15 = q[4] * q[4];
    s[1] = x15;
    let x16 = q[5] * q[5];
    s[2] = x16;
    let x17 = q[6] * q[6];
    s[3] = x17;
    let x18 = x14 + x15;
    s[4] = x18;
    let x19 = 2.0 * x18;
    s[5] = x19;
    let x21 = x19 - 1.0;
    s[6] = x21;
    let x22 = x14 + x16;
    s[7] = x22;
    let x23 = 2.0 * x22;
    s[8] = x23;
    let x24 = x23 - 1.0;
    s[9] = x24;
    let x25 = x14 + x17;
    s[10] = x25;
    let x26 = 2.0 * x25;
    s[11] = x26;
    let x27 = x26 - 1.0;
    s[12] = x27;
    let x28 = q[4] * q[5];
    s[13] = x28;
    let x29 = 2.0 * x28;
    s[14] = x29;
    let x30 = q[3] * q[6];
    s[15] = x30;
    let x32 = 2.0 * x30;
    s[16] = x32;
    let x34 = x29 - x32;
    s[17] = x34;
    let x35 = q[4] * q[6];
    s[18] = x35;
    let x36 = 2.0 * x35;
    s[19] = x36;
    let x37 = q[3] * q[5];
    s[20] = x37;
    let x38 = 2.0 * x37;
    s[21] = x38;
    let x39 = x36 + x38;
    s[22] = x39;
    let x40 = x29 + x32;
    s[23] = x40;
    let x41 = q[5] * q[6];
    s[24] = x41;
    let x42 = 2.0 * x41;
    s[25] = x42;
    let x43 = q[3] * q[4];
    s[26] = x43;
    let x45 = 2.0 * x43;
    s[27] = x45;
    let x47 = x42 - x45;
    s[28] = x47;
    let x50 = x36 - x38;
    s[29] = x50;
    let x51 = x42 + x45;
    s[30] = x51;
    let x158 = x21 * 0.478359;
    s[31] = x158;
    let x159 = x34 * 1.158742;
    s[32] = x159;
    let x160 = x39 * 0.107672;
    s[33] = x160;
    let x161 = x158 + x159;
    s[34] = x161;
    let x162 = x160 + x161;
    s[35] = x162;
    let x163 = x40 * 0.478359;
    s[36] = x163;
    let x164 = x24 * 1.158742;
    s[37] = x164;
    let x165 = x47 * 0.107672;
    s[38] = x165;
    let x166 = x163 + x164;
    s[39] = x166;
    let x167 = x165 + x166;
    s[40] = x167;
    let x168 = x50 * 0.478359;
    s[41] = x168;
    let x169 = x51 * 1.158742;
    s[42] = x169;
    let x170 = x27 * 0.107672;
    s[43] = x170;
    let x171 = x168 + x169;
    s[44] = x171;
    let x172 = x170 + x171;
    s[45] = x172;
    let x173 = q[0] + x162;
    s[46] = x173;
    let x174 = q[1] + x167;
    s[47] = x174;
    let x175 = q[2] + x172;
    s[48] = x175;
    let x177 = x173 - 0.514188;
    s[49] = x177;
    let x179 = x174 + 0.526063;
    s[50] = x179;
    let x181 = x175 + 0.368418;
    s[51] = x181;
    let x182 = x177 * x177;
    s[52] = x182;
    let x183 = x179 * x179;
    s[53] = x183;
    let x184 = x181 * x181;
    s[54] = x184;
    let x185 = x182 + x183;
    s[55] = x185;
    let x186 = x184 + x185;
    s[56] = x186;
    let x187 = x186.sqrt();
    s[57] = x187;
    let x242 = q[3] * 2.0;
    s[58] = x242;
    let x243 = q[4] * 2.0;
    s[59] = x243;
    let x244 = q[5] * 2.0;
    s[60] = x244;
    let x245 = q[6] * 2.0;
    s[61] = x245;
    let x270 = 2.0 * x177;
    s[62] = x270;
    let x271 = 2.0 * x179;
    s[63] = x271;
    let x272 = 2.0 * x181;
    s[64] = x272;
    let x273 = 2.0 * x187;
    s[65] = x273;
    let x274 = 1.0 / x273;
    s[66] = x274;
    let x294 = 2.0 * x242;
    s[67] = x294;
    let x360 = 0.107672 * x244;
    s[68] = x360;
    let x365 = 0.107672 * x243;
    s[69] = x365;
    let x410 = 2.0 * x243;
    s[70] = x410;
    let x451 = 1.158742 * x244;
    s[71] = x451;
    let x458 = 1.158742 * x242;
    s[72] = x458;
    let x487 = 2.0 * x244;
    s[73] = x487;
    let x530 = 0.478359 * x243;
    s[74] = x530;
    let x534 = 0.478359 * x242;
    s[75] = x534;
    let x561 = 2.0 * x245;
    s[76] = x561;
    let x616 = x242 * qd[3];
    s[77] = x616;
    let x617 = x243 * qd[4];
    s[78] = x617;
    let x618 = x244 * qd[5];
    s[79] = x618;
    let x619 = x245 * qd[6];
    s[80] = x619;
    let x620 = x616 + x617;
    s[81] = x620;
    let x621 = 2.0 * x620;
    s[82] = x621;
    let x622 = x616 + x618;
    s[83] = x622;
    let x623 = 2.0 * x622;
    s[84] = x623;
    let x624 = x616 + x619;
    s[85] = x624;
    let x625 = 2.0 * x624;
    s[86] = x625;
    let x626 = q[5] * qd[4];
    s[87] = x626;
    let x627 = q[4] * qd[5];
    s[88] = x627;
    let x628 = x626 + x627;
    s[89] = x628;
    let x629 = 2.0 * x628;
    s[90] = x629;
    let x630 = q[6] * qd[3];
    s[91] = x630;
    let x631 = q[3] * qd[6];
    s[92] = x631;
    let x632 = x630 + x631;
    s[93] = x632;
    let x633 = 2.0 * x632;
    s[94] = x633;
    let x635 = x629 - x633;
    s[95] = x635;
    let x636 = q[6] * qd[4];
    s[96] = x636;
    let x637 = q[4] * qd[6];
    s[97] = x637;
    let x638 = x636 + x637;
    s[98] = x638;
    let x639 = 2.0 * x638;
    s[99] = x639;
    let x640 = q[5] * qd[3];
    s[100] = x640;
    let x641 = q[3] * qd[5];
    s[101] = x641;
    let x642 = x640 + x641;
    s[102] = x642;
    let x643 = 2.0 * x642;
    s[103] = x643;
    let x644 = x639 + x643;
    s[104] = x644;
    let x645 = x629 + x633;
    s[105] = x645;
    let x646 = q[6] * qd[5];
    s[106] = x646;
    let x647 = q[5] * qd[6];
    s[107] = x647;
    let x648 = x646 + x647;
    s[108] = x648;
    let x649 = 2.0 * x648;
    s[109] = x649;
    let x650 = q[4] * qd[3];
    s[110] = x650;
    let x651 = q[3] * qd[4];
    s[111] = x651;
    let x652 = x650 + x651;
    s[112] = x652;
    let x653 = 2.0 * x652;
    s[113] = x653;
    let x655 = x649 - x653;
    s[114] = x655;
    let x657 = x639 - x643;
    s[115] = x657;
    let x658 = x649 + x653;
    s[116] = x658;
    let x778 = 2.0 * qd[3];
    s[117] = x778;
    let x779 = 2.0 * qd[4];
    s[118] = x779;
    let x780 = 2.0 * qd[5];
    s[119] = x780;
    let x781 = 2.0 * qd[6];
    s[120] = x781;
    let x824 = qd[3] * x778;
    s[121] = x824;
    let x825 = qd[4] * x779;
    s[122] = x825;
    let x826 = qd[5] * x780;
    s[123] = x826;
    let x827 = qd[6] * x781;
    s[124] = x827;
    let x828 = x824 + x825;
    s[125] = x828;
    let x829 = 2.0 * x828;
    s[126] = x829;
    let x830 = x824 + x826;
    s[127] = x830;
    let x831 = 2.0 * x830;
    s[128] = x831;
    let x832 = x824 + x827;
    s[129] = x832;
    let x833 = 2.0 * x832;
    s[130] = x833;
    let x834 = qd[4] * qd[5];
    s[131] = x834;
    let x835 = x834 + x834;
    s[132] = x835;
    let x836 = 2.0 * x835;
    s[133] = x836;
    let x837 = qd[3] * qd[6];
    s[134] = x837;
    let x838 = x837 + x837;
    s[135] = x838;
    let x839 = 2.0 * x838;
    s[136] = x839;
    let x841 = x836 - x839;
    s[137] = x841;
    let x842 = qd[4] * qd[6];
    s[138] = x842;
    let x843 = x842 + x842;
    s[139] = x843;
    let x844 = 2.0 * x843;
    s[140] = x844;
    let x845 = qd[3] * qd[5];
    s[141] = x845;
    let x846 = x845 + x845;
    s[142] = x846;
    let x847 = 2.0 * x846;
    s[143] = x847;
    let x848 = x844 + x847;
    s[144] = x848;
    let x849 = x836 + x839;
    s[145] = x849;
    let x850 = qd[5] * qd[6];
    s[146] = x850;
    let x851 = x850 + x850;
    s[147] = x851;
    let x852 = 2.0 * x851;
    s[148] = x852;
    let x853 = qd[3] * qd[4];
    s[149] = x853;
    let x854 = x853 + x853;
    s[150] = x854;
    let x855 = 2.0 * x854;
    s[151] = x855;
    let x857 = x852 - x855;
    s[152] = x857;
    let x859 = x844 - x847;
    s[153] = x859;
    let x860 = x852 + x855;
    s[154] = x860;
}
#[inline(never)]
fn eval_kinematics_part_0(
    q: &[f64; 7],
    qd: &[f64; 7],
    s: &[f64; 155],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 42],
    phi_t: &mut [f64; 7],
    gamma: &mut [f64; 7],
) {
    let x53 = q[0] * q[0];
    let x54 = q[1] * q[1];
    let x55 = q[2] * q[2];
    let x56 = x53 + x54;
    let x57 = x55 + x56;
    let x58 = x57.sqrt();
    let x59 = x58 - 1.0;
    let x62 = s[6] * 0.542805;
    let x63 = s[23] * 0.542805;
    let x64 = s[29] * 0.542805;
    let x65 = q[0] + x62;
    let x66 = q[1] + x63;
    let x67 = q[2] + x64;
    let x69 = x65 - 1.107915;
    let x70 = x69 * x69;
    let x71 = x66 * x66;
    let x72 = x67 * x67;
    let x73 = x70 + x71;
    let x74 = x72 + x73;
    let x75 = x74.sqrt();
    let x77 = x75 - 0.645275;
    let x82 = s[6] * 0.956919;
    let x84 = s[17] * 0.528915;
    let x86 = x82 - x84;
    let x87 = s[23] * 0.956919;
    let x88 = s[9] * 0.528915;
    let x90 = x87 - x88;
    let x91 = s[29] * 0.956919;
    let x92 = s[30] * 0.528915;
    let x94 = x91 - x92;
    let x95 = q[0] + x86;
    let x96 = q[1] + x90;
    let x97 = q[2] + x94;
    let x99 = x95 - 0.549094;
    let x101 = x96 - 0.756063;
    let x102 = x99 * x99;
    let x103 = x101 * x101;
    let x104 = x97 * x97;
    let x105 = x102 + x103;
    let x106 = x104 + x105;
    let x107 = x106.sqrt();
    let x109 = x107 - 1.086284;
    let x116 = s[6] * 0.665885;
    let x118 = s[17] * 0.353482;
    let x120 = s[22] * 1.402538;
    let x121 = x116 - x118;
    let x122 = x120 + x121;
    let x123 = s[23] * 0.665885;
    let x124 = s[9] * 0.353482;
    let x126 = s[28] * 1.402538;
    let x127 = x123 - x124;
    let x128 = x126 + x127;
    let x129 = s[29] * 0.665885;
    let x130 = s[30] * 0.353482;
    let x132 = s[12] * 1.402538;
    let x133 = x129 - x130;
    let x134 = x132 + x133;
    let x135 = q[0] + x122;
    let x136 = q[1] + x128;
    let x137 = q[2] + x134;
    let x139 = x135 - 0.735077;
    let x141 = x136 + 0.223935;
    let x143 = x137 - 0.525991;
    let x144 = x139 * x139;
    let x145 = x141 * x141;
    let x146 = x143 * x143;
    let x147 = x144 + x145;
    let x148 = x146 + x147;
    let x149 = x148.sqrt();
    let x151 = x149 - 1.503439;
    let x189 = s[57] - 1.281933;
    let x246 = q[0] * 2.0;
    let x247 = q[1] * 2.0;
    let x248 = q[2] * 2.0;
    let x249 = 2.0 * x58;
    let x250 = 1.0 / x249;
    let x251 = x246 * x250;
    let x252 = 2.0 * x69;
    let x253 = 2.0 * x66;
    let x254 = 2.0 * x67;
    let x255 = 2.0 * x75;
    let x256 = 1.0 / x255;
    let x257 = x252 * x256;
    let x258 = 2.0 * x99;
    let x259 = 2.0 * x101;
    let x260 = 2.0 * x97;
    let x261 = 2.0 * x107;
    let x262 = 1.0 / x261;
    let x263 = x258 * x262;
    let x264 = 2.0 * x139;
    let x265 = 2.0 * x141;
    let x266 = 2.0 * x143;
    let x267 = 2.0 * x149;
    let x268 = 1.0 / x267;
    let x269 = x264 * x268;
    let x275 = s[62] * s[66];
    let x282 = x247 * x250;
    let x283 = x253 * x256;
    let x284 = x259 * x262;
    let x285 = x265 * x268;
    let x286 = s[63] * s[66];
    let x288 = x248 * x250;
    let x289 = x254 * x256;
    let x290 = x260 * x262;
    let x291 = x266 * x268;
    let x292 = s[64] * s[66];
    let x298 = 0.542805 * s[67];
    let x299 = 0.542805 * s[61];
    let x300 = 0.542805 * s[60];
    let x302 = x252 * x298;
    let x303 = x253 * x299;
    let x304 = x254 * x300;
    let x306 = x302 + x303;
    let x307 = x306 - x304;
    let x308 = x256 * x307;
    let x309 = 0.956919 * s[67];
    let x310 = 0.528915 * s[61];
    let x312 = x309 + x310;
    let x313 = 0.956919 * s[61];
    let x314 = 0.528915 * s[67];
    let x316 = x313 - x314;
    let x317 = 0.956919 * s[60];
    let x319 = 0.528915 * s[59];
    let x321 = x317 + x319;
    let x323 = x258 * x312;
    let x324 = x259 * x316;
    let x325 = x260 * x321;
    let x327 = x323 + x324;
    let x328 = x327 - x325;
    let x329 = x262 * x328;
    let x330 = 0.665885 * s[67];
    let x331 = 0.353482 * s[61];
    let x333 = 1.402538 * s[60];
    let x334 = x330 + x331;
    let x335 = x333 + x334;
    let x336 = 0.665885 * s[61];
    let x337 = 0.353482 * s[67];
    let x339 = 1.402538 * s[59];
    let x341 = x336 - x337;
    let x342 = x341 - x339;
    let x343 = 0.665885 * s[60];
    let x345 = 0.353482 * s[59];
    let x347 = 1.402538 * s[67];
    let x348 = x343 + x345;
    let x350 = x347 - x348;
    let x351 = x264 * x335;
    let x352 = x265 * x342;
    let x353 = x266 * x350;
    let x354 = x351 + x352;
    let x355 = x353 + x354;
    let x356 = x268 * x355;
    let x357 = 0.478359 * s[67];
    let x358 = 1.158742 * s[61];
    let x361 = x357 - x358;
    let x362 = s[68] + x361;
    let x363 = 0.478359 * s[61];
    let x364 = 1.158742 * s[67];
    let x367 = x363 + x364;
    let x368 = x367 - s[69];
    let x369 = 0.478359 * s[60];
    let x371 = 1.158742 * s[59];
    let x372 = 0.107672 * s[67];
    let x373 = x371 - x369;
    let x374 = x372 + x373;
    let x375 = s[62] * x362;
    let x376 = s[63] * x368;
    let x377 = s[64] * x374;
    let x378 = x375 + x376;
    let x379 = x377 + x378;
    let x380 = s[66] * x379;
    let x412 = 0.542805 * s[70];
    let x413 = x252 * x412;
    let x414 = x253 * x300;
    let x415 = x254 * x299;
    let x416 = x413 + x414;
    let x417 = x415 + x416;
    let x418 = x256 * x417;
    let x419 = 0.956919 * s[70];
    let x420 = 0.528915 * s[60];
    let x422 = x419 - x420;
    let x423 = 0.528915 * s[58];
    let x425 = x313 - x423;
    let x426 = x258 * x422;
    let x427 = x259 * x317;
    let x428 = x260 * x425;
    let x429 = x426 + x427;
    let x430 = x428 + x429;
    let x431 = x262 * x430;
    let x432 = 0.665885 * s[70];
    let x433 = 0.353482 * s[60];
    let x435 = 1.402538 * s[61];
    let x436 = x432 - x433;
    let x437 = x435 + x436;
    let x438 = 1.402538 * s[58];
    let x440 = x343 - x438;
    let x441 = 0.353482 * s[58];
    let x443 = x336 - x441;
    let x444 = x264 * x437;
    let x445 = x265 * x440;
    let x446 = x266 * x443;
    let x447 = x444 + x445;
    let x448 = x446 + x447;
    let x449 = x268 * x448;
    let x450 = 0.478359 * s[70];
    let x452 = 0.107672 * s[61];
    let x453 = x450 + s[71];
    let x454 = x452 + x453;
    let x455 = 0.107672 * s[58];
    let x457 = x369 - x455;
    let x459 = x363 + s[72];
    let x460 = s[62] * x454;
    let x461 = s[63] * x457;
    let x462 = s[64] * x459;
    let x463 = x460 + x461;
    let x464 = x462 + x463;
    let x465 = s[66] * x464;
    let x488 = 0.542805 * s[59];
    let x489 = 0.542805 * s[58];
    let x491 = x253 * x488;
    let x492 = x254 * x489;
    let x494 = x491 - x492;
    let x495 = x256 * x494;
    let x496 = 0.956919 * s[59];
    let x497 = 0.528915 * s[73];
    let x499 = x496 - x497;
    let x500 = 0.956919 * s[58];
    let x502 = x310 + x500;
    let x504 = x258 * x319;
    let x506 = x259 * x499;
    let x507 = x260 * x502;
    let x509 = x506 - x504;
    let x510 = x509 - x507;
    let x511 = x262 * x510;
    let x512 = x438 - x345;
    let x513 = 0.665885 * s[59];
    let x514 = 0.353482 * s[73];
    let x516 = x513 - x514;
    let x517 = x435 + x516;
    let x518 = 0.665885 * s[58];
    let x520 = x331 + x518;
    let x522 = x264 * x512;
    let x523 = x265 * x517;
    let x524 = x266 * x520;
    let x526 = x522 + x523;
    let x527 = x526 - x524;
    let x528 = x268 * x527;
    let x529 = x371 + x455;
    let x531 = 1.158742 * s[73];
    let x532 = s[74] + x531;
    let x533 = x452 + x532;
    let x536 = x358 - s[75];
    let x537 = s[62] * x529;
    let x538 = s[63] * x533;
    let x539 = s[64] * x536;
    let x540 = x537 + x538;
    let x541 = x539 + x540;
    let x542 = s[66] * x541;
    let x562 = x253 * x489;
    let x563 = x254 * x488;
    let x564 = x562 + x563;
    let x565 = x256 * x564;
    let x566 = x496 - x420;
    let x567 = x258 * x423;
    let x568 = x259 * x500;
    let x569 = x260 * x566;
    let x570 = x567 + x568;
    let x571 = x569 + x570;
    let x572 = x262 * x571;
    let x573 = x339 + x441;
    let x574 = x333 + x518;
    let x575 = 1.402538 * s[76];
    let x576 = x513 - x433;
    let x577 = x575 + x576;
    let x578 = x264 * x573;
    let x579 = x265 * x574;
    let x580 = x266 * x577;
    let x581 = x578 + x579;
    let x582 = x580 + x581;
    let x583 = x268 * x582;
    let x659 = x246 * qd[0];
    let x660 = x247 * qd[1];
    let x661 = x248 * qd[2];
    let x662 = x659 + x660;
    let x663 = x661 + x662;
    let x664 = x250 * x663;
    let x665 = 0.542805 * s[82];
    let x666 = 0.542805 * s[105];
    let x667 = 0.542805 * s[115];
    let x668 = qd[0] + x665;
    let x669 = qd[1] + x666;
    let x670 = qd[2] + x667;
    let x671 = x252 * x668;
    let x672 = x253 * x669;
    let x673 = x254 * x670;
    let x674 = x671 + x672;
    let x675 = x673 + x674;
    let x676 = x256 * x675;
    let x677 = 0.956919 * s[82];
    let x678 = 0.528915 * s[95];
    let x680 = x677 - x678;
    let x681 = 0.956919 * s[105];
    let x682 = 0.528915 * s[84];
    let x684 = x681 - x682;
    let x685 = 0.956919 * s[115];
    let x686 = 0.528915 * s[116];
    let x688 = x685 - x686;
    let x689 = qd[0] + x680;
    let x690 = qd[1] + x684;
    let x691 = qd[2] + x688;
    let x692 = x258 * x689;
    let x693 = x259 * x690;
    let x694 = x260 * x691;
    let x695 = x692 + x693;
    let x696 = x694 + x695;
    let x697 = x262 * x696;
    let x698 = 0.665885 * s[82];
    let x699 = 0.353482 * s[95];
    let x701 = 1.402538 * s[104];
    let x702 = x698 - x699;
    let x703 = x701 + x702;
    let x704 = 0.665885 * s[105];
    let x705 = 0.353482 * s[84];
    let x707 = 1.402538 * s[114];
    let x708 = x704 - x705;
    let x709 = x707 + x708;
    let x710 = 0.665885 * s[115];
    let x711 = 0.353482 * s[116];
    let x713 = 1.402538 * s[86];
    let x714 = x710 - x711;
    let x715 = x713 + x714;
    let x716 = qd[0] + x703;
    let x717 = qd[1] + x709;
    let x718 = qd[2] + x715;
    let x719 = x264 * x716;
    let x720 = x265 * x717;
    let x721 = x266 * x718;
    let x722 = x719 + x720;
    let x723 = x721 + x722;
    let x724 = x268 * x723;
    let x782 = 2.0 * qd[0];
    let x783 = 2.0 * qd[1];
    let x784 = 2.0 * qd[2];
    let x785 = 2.0 * x664;
    let x786 = x250 * x250;
    let x787 = x785 * x786;
    let x789 = 2.0 * x668;
    let x790 = 2.0 * x669;
    let x791 = 2.0 * x670;
    let x792 = 2.0 * x676;
    let x793 = x256 * x256;
    let x794 = x792 * x793;
    let x796 = 2.0 * x689;
    let x797 = 2.0 * x690;
    let x798 = 2.0 * x691;
    let x799 = 2.0 * x697;
    let x800 = x262 * x262;
    let x801 = x799 * x800;
    let x803 = 2.0 * x716;
    let x804 = 2.0 * x717;
    let x805 = 2.0 * x718;
    let x806 = 2.0 * x724;
    let x807 = x268 * x268;
    let x808 = x806 * x807;
    let x861 = qd[0] * x782;
    let x862 = qd[1] * x783;
    let x863 = qd[2] * x784;
    let x864 = x861 + x862;
    let x865 = x863 + x864;
    let x866 = x663 * x787;
    let x868 = x250 * x865;
    let x869 = x868 - x866;
    let x870 = 0.542805 * s[126];
    let x871 = 0.542805 * s[145];
    let x872 = 0.542805 * s[153];
    let x873 = x668 * x789;
    let x874 = x252 * x870;
    let x875 = x873 + x874;
    let x876 = x669 * x790;
    let x877 = x253 * x871;
    let x878 = x876 + x877;
    let x879 = x670 * x791;
    let x880 = x254 * x872;
    let x881 = x879 + x880;
    let x882 = x875 + x878;
    let x883 = x881 + x882;
    let x884 = x675 * x794;
    let x886 = x256 * x883;
    let x887 = x886 - x884;
    let x888 = 0.956919 * s[126];
    let x889 = 0.528915 * s[137];
    let x891 = x888 - x889;
    let x892 = 0.956919 * s[145];
    let x893 = 0.528915 * s[128];
    let x895 = x892 - x893;
    let x896 = 0.956919 * s[153];
    let x897 = 0.528915 * s[154];
    let x899 = x896 - x897;
    let x900 = x689 * x796;
    let x901 = x258 * x891;
    let x902 = x900 + x901;
    let x903 = x690 * x797;
    let x904 = x259 * x895;
    let x905 = x903 + x904;
    let x906 = x691 * x798;
    let x907 = x260 * x899;
    let x908 = x906 + x907;
    let x909 = x902 + x905;
    let x910 = x908 + x909;
    let x911 = x696 * x801;
    let x913 = x262 * x910;
    let x914 = x913 - x911;
    let x915 = 0.665885 * s[126];
    let x916 = 0.353482 * s[137];
    let x918 = 1.402538 * s[144];
    let x919 = x915 - x916;
    let x920 = x918 + x919;
    let x921 = 0.665885 * s[145];
    let x922 = 0.353482 * s[128];
    let x924 = 1.402538 * s[152];
    let x925 = x921 - x922;
    let x926 = x924 + x925;
    let x927 = 0.665885 * s[153];
    let x928 = 0.353482 * s[154];
    let x930 = 1.402538 * s[130];
    let x931 = x927 - x928;
    let x932 = x930 + x931;
    let x933 = x716 * x803;
    let x934 = x264 * x920;
    let x935 = x933 + x934;
    let x936 = x717 * x804;
    let x937 = x265 * x926;
    let x938 = x936 + x937;
    let x939 = x718 * x805;
    let x940 = x266 * x932;
    let x941 = x939 + x940;
    let x942 = x935 + x938;
    let x943 = x941 + x942;
    let x944 = x723 * x808;
    let x946 = x268 * x943;
    let x947 = x946 - x944;
    let x1013 = -x869;
    let x1014 = -x887;
    let x1015 = -x914;
    let x1016 = -x947;
    phi[0] = x59;
    phi_q[0] = x251;
    phi_q[1] = x282;
    phi_q[2] = x288;
    phi_t[0] = 0.0;
    gamma[0] = x1013;
    phi[1] = x77;
    phi_q[3] = x257;
    phi_q[4] = x283;
    phi_q[5] = x289;
    phi_q[6] = x308;
    phi_q[7] = x418;
    phi_q[8] = x495;
    phi_q[9] = x565;
    phi_t[1] = 0.0;
    gamma[1] = x1014;
    phi[2] = x109;
    phi_q[10] = x263;
    phi_q[11] = x284;
    phi_q[12] = x290;
    phi_q[13] = x329;
    phi_q[14] = x431;
    phi_q[15] = x511;
    phi_q[16] = x572;
    phi_t[2] = 0.0;
    gamma[2] = x1015;
    phi[3] = x151;
    phi_q[17] = x269;
    phi_q[18] = x285;
    phi_q[19] = x291;
    phi_q[20] = x356;
    phi_q[21] = x449;
    phi_q[22] = x528;
    phi_q[23] = x583;
    phi_t[3] = 0.0;
    gamma[3] = x1016;
    phi[4] = x189;
    phi_q[24] = x275;
    phi_q[25] = x286;
    phi_q[26] = x292;
    phi_q[27] = x380;
    phi_q[28] = x465;
    phi_q[29] = x542;
}
#[inline(never)]
fn eval_kinematics_part_1(
    q: &[f64; 7],
    qd: &[f64; 7],
    s: &[f64; 155],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 42],
    phi_t: &mut [f64; 7],
    gamma: &mut [f64; 7],
) {
    let x197 = s[6] * 0.137087;
    let x200 = s[17] * 0.235121;
    let x202 = s[22] * 0.353913;
    let x203 = x197 + x200;
    let x205 = x202 - x203;
    let x206 = s[23] * 0.137087;
    let x208 = s[9] * 0.235121;
    let x210 = s[28] * 0.353913;
    let x211 = x206 + x208;
    let x213 = x210 - x211;
    let x214 = s[29] * 0.137087;
    let x216 = s[30] * 0.235121;
    let x218 = s[12] * 0.353913;
    let x219 = x214 + x216;
    let x221 = x218 - x219;
    let x222 = q[0] + x205;
    let x223 = q[1] + x213;
    let x224 = q[2] + x221;
    let x226 = x222 - 0.590473;
    let x228 = x223 - 0.094733;
    let x230 = x224 + 0.205018;
    let x231 = x226 * x226;
    let x232 = x228 * x228;
    let x233 = x230 * x230;
    let x234 = x231 + x232;
    let x235 = x233 + x234;
    let x236 = x235.sqrt();
    let x238 = x236 - 0.771071;
    let x239 = s[2] + s[4];
    let x240 = s[3] + x239;
    let x241 = x240 - 1.0;
    let x276 = 2.0 * x226;
    let x277 = 2.0 * x228;
    let x278 = 2.0 * x230;
    let x279 = 2.0 * x236;
    let x280 = 1.0 / x279;
    let x281 = x276 * x280;
    let x287 = x277 * x280;
    let x293 = x278 * x280;
    let x381 = 0.137087 * s[67];
    let x382 = 0.235121 * s[61];
    let x384 = 0.353913 * s[60];
    let x385 = x381 - x382;
    let x387 = x384 - x385;
    let x388 = 0.137087 * s[61];
    let x389 = 0.235121 * s[67];
    let x390 = 0.353913 * s[59];
    let x392 = x388 + x389;
    let x394 = x390 + x392;
    let x396 = 0.137087 * s[60];
    let x398 = 0.235121 * s[59];
    let x399 = 0.353913 * s[67];
    let x400 = x398 - x396;
    let x402 = x399 - x400;
    let x403 = x276 * x387;
    let x404 = x277 * x394;
    let x406 = x278 * x402;
    let x407 = x403 - x404;
    let x408 = x406 + x407;
    let x409 = x280 * x408;
    let x466 = 0.137087 * s[70];
    let x467 = 0.235121 * s[60];
    let x468 = 0.353913 * s[61];
    let x469 = x466 + x467;
    let x471 = x468 - x469;
    let x472 = 0.353913 * s[58];
    let x474 = x396 + x472;
    let x476 = 0.235121 * s[58];
    let x477 = x388 + x476;
    let x479 = x276 * x471;
    let x480 = x277 * x474;
    let x482 = x278 * x477;
    let x484 = x479 - x480;
    let x485 = x484 - x482;
    let x486 = x280 * x485;
    let x544 = x472 - x398;
    let x545 = 0.137087 * s[59];
    let x546 = 0.235121 * s[73];
    let x547 = x545 + x546;
    let x549 = x468 - x547;
    let x550 = 0.137087 * s[58];
    let x552 = x382 - x550;
    let x554 = x276 * x544;
    let x555 = x277 * x549;
    let x556 = x278 * x552;
    let x558 = x554 + x555;
    let x559 = x558 - x556;
    let x560 = x280 * x559;
    let x585 = s[69] - s[72];
    let x586 = s[68] + s[75];
    let x587 = 0.107672 * s[76];
    let x588 = s[71] + s[74];
    let x589 = x587 + x588;
    let x590 = s[62] * x585;
    let x591 = s[63] * x586;
    let x592 = s[64] * x589;
    let x593 = x590 + x591;
    let x594 = x592 + x593;
    let x595 = s[66] * x594;
    let x597 = x390 + x476;
    let x598 = x384 - x550;
    let x599 = 0.353913 * s[76];
    let x600 = x467 + x545;
    let x602 = x599 - x600;
    let x603 = x276 * x597;
    let x604 = x277 * x598;
    let x605 = x278 * x602;
    let x606 = x603 + x604;
    let x607 = x605 + x606;
    let x608 = x280 * x607;
    let x725 = 0.478359 * s[82];
    let x726 = 1.158742 * s[95];
    let x727 = 0.107672 * s[104];
    let x728 = x725 + x726;
    let x729 = x727 + x728;
    let x730 = 0.478359 * s[105];
    let x731 = 1.158742 * s[84];
    let x732 = 0.107672 * s[114];
    let x733 = x730 + x731;
    let x734 = x732 + x733;
    let x735 = 0.478359 * s[115];
    let x736 = 1.158742 * s[116];
    let x737 = 0.107672 * s[86];
    let x738 = x735 + x736;
    let x739 = x737 + x738;
    let x740 = qd[0] + x729;
    let x741 = qd[1] + x734;
    let x742 = qd[2] + x739;
    let x743 = s[62] * x740;
    let x744 = s[63] * x741;
    let x745 = s[64] * x742;
    let x746 = x743 + x744;
    let x747 = x745 + x746;
    let x748 = s[66] * x747;
    let x749 = 0.137087 * s[82];
    let x750 = 0.235121 * s[95];
    let x751 = 0.353913 * s[104];
    let x752 = x749 + x750;
    let x754 = x751 - x752;
    let x755 = 0.137087 * s[105];
    let x756 = 0.235121 * s[84];
    let x757 = 0.353913 * s[114];
    let x758 = x755 + x756;
    let x760 = x757 - x758;
    let x761 = 0.137087 * s[115];
    let x762 = 0.235121 * s[116];
    let x763 = 0.353913 * s[86];
    let x764 = x761 + x762;
    let x766 = x763 - x764;
    let x767 = qd[0] + x754;
    let x768 = qd[1] + x760;
    let x769 = qd[2] + x766;
    let x770 = x276 * x767;
    let x771 = x277 * x768;
    let x772 = x278 * x769;
    let x773 = x770 + x771;
    let x774 = x772 + x773;
    let x775 = x280 * x774;
    let x810 = 2.0 * x740;
    let x811 = 2.0 * x741;
    let x812 = 2.0 * x742;
    let x813 = 2.0 * x748;
    let x814 = s[66] * s[66];
    let x815 = x813 * x814;
    let x817 = 2.0 * x767;
    let x818 = 2.0 * x768;
    let x819 = 2.0 * x769;
    let x820 = 2.0 * x775;
    let x821 = x280 * x280;
    let x822 = x820 * x821;
    let x948 = 0.478359 * s[126];
    let x949 = 1.158742 * s[137];
    let x950 = 0.107672 * s[144];
    let x951 = x948 + x949;
    let x952 = x950 + x951;
    let x953 = 0.478359 * s[145];
    let x954 = 1.158742 * s[128];
    let x955 = 0.107672 * s[152];
    let x956 = x953 + x954;
    let x957 = x955 + x956;
    let x958 = 0.478359 * s[153];
    let x959 = 1.158742 * s[154];
    let x960 = 0.107672 * s[130];
    let x961 = x958 + x959;
    let x962 = x960 + x961;
    let x963 = x740 * x810;
    let x964 = s[62] * x952;
    let x965 = x963 + x964;
    let x966 = x741 * x811;
    let x967 = s[63] * x957;
    let x968 = x966 + x967;
    let x969 = x742 * x812;
    let x970 = s[64] * x962;
    let x971 = x969 + x970;
    let x972 = x965 + x968;
    let x973 = x971 + x972;
    let x974 = x747 * x815;
    let x976 = s[66] * x973;
    let x977 = x976 - x974;
    let x978 = 0.137087 * s[126];
    let x979 = 0.235121 * s[137];
    let x980 = 0.353913 * s[144];
    let x981 = x978 + x979;
    let x983 = x980 - x981;
    let x984 = 0.137087 * s[145];
    let x985 = 0.235121 * s[128];
    let x986 = 0.353913 * s[152];
    let x987 = x984 + x985;
    let x989 = x986 - x987;
    let x990 = 0.137087 * s[153];
    let x991 = 0.235121 * s[154];
    let x992 = 0.353913 * s[130];
    let x993 = x990 + x991;
    let x995 = x992 - x993;
    let x996 = x767 * x817;
    let x997 = x276 * x983;
    let x998 = x996 + x997;
    let x999 = x768 * x818;
    let x1000 = x277 * x989;
    let x1001 = x999 + x1000;
    let x1002 = x769 * x819;
    let x1003 = x278 * x995;
    let x1004 = x1002 + x1003;
    let x1005 = x998 + x1001;
    let x1006 = x1004 + x1005;
    let x1007 = x774 * x822;
    let x1009 = x280 * x1006;
    let x1010 = x1009 - x1007;
    let x1011 = s[123] + s[125];
    let x1012 = s[124] + x1011;
    let x1017 = -x977;
    let x1018 = -x1010;
    let x1019 = -x1012;
    phi_q[30] = x595;
    phi_t[4] = 0.0;
    gamma[4] = x1017;
    phi[5] = x238;
    phi_q[31] = x281;
    phi_q[32] = x287;
    phi_q[33] = x293;
    phi_q[34] = x409;
    phi_q[35] = x486;
    phi_q[36] = x560;
    phi_q[37] = x608;
    phi_t[5] = 0.0;
    gamma[5] = x1018;
    phi[6] = x241;
    phi_q[38] = s[58];
    phi_q[39] = s[59];
    phi_q[40] = s[60];
    phi_q[41] = s[61];
    phi_t[6] = 0.0;
    gamma[6] = x1019;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(q: &[f64], out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = q;
    potential_into_part_0(out);
}
#[inline(never)]
fn potential_into_part_0(out: &mut [f64; 1]) {
    out[0] = 0.0;
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
        let x14 = q[3] * q[3];
        let x15 = q[4] * q[4];
        let x16 = q[5] * q[5];
        let x17 = q[6] * q[6];
        let x28 = q[4] * q[5];
        let x30 = q[3] * q[6];
        let x35 = q[4] * q[6];
        let x37 = q[3] * q[5];
        let x41 = q[5] * q[6];
        let x43 = q[3] * q[4];
        let x242 = q[3] * 2.0;
        let x243 = q[4] * 2.0;
        let x244 = q[5] * 2.0;
        let x245 = q[6] * 2.0;
        let x294 = 2.0 * x242;
        let x410 = 2.0 * x243;
        let x487 = 2.0 * x244;
        let x561 = 2.0 * x245;
        let x1100 = x243 * x410;
        let x1102 = x244 * x487;
        let x1104 = x245 * x561;
        let x1106 = x1100 + x1102;
        let x1108 = x1104 + x1106;
        let x1110 = 0.5 * x1108;
        let x1112 = x14 * 4.0;
        let x1113 = x1110 + x1112;
        let x1114 = x243 * x294;
        let x1115 = x244 * x561;
        let x1117 = x245 * x487;
        let x1118 = x1114 - x1115;
        let x1119 = x1117 + x1118;
        let x1120 = 0.5 * x1119;
        let x1122 = x43 * 4.0;
        let x1123 = x1122 - x1120;
        let x1124 = x243 * x561;
        let x1125 = x244 * x294;
        let x1126 = x245 * x410;
        let x1128 = x1124 + x1125;
        let x1129 = x1128 - x1126;
        let x1130 = 0.5 * x1129;
        let x1132 = x37 * 4.0;
        let x1133 = x1132 - x1130;
        let x1134 = x243 * x487;
        let x1136 = x244 * x410;
        let x1137 = x245 * x294;
        let x1138 = x1136 - x1134;
        let x1139 = x1137 + x1138;
        let x1140 = 0.5 * x1139;
        let x1142 = x30 * 4.0;
        let x1143 = x1142 - x1140;
        let x1144 = x242 * x410;
        let x1147 = x1117 - x1144;
        let x1148 = x1147 - x1115;
        let x1149 = 0.5 * x1148;
        let x1150 = x1122 + x1149;
        let x1151 = x242 * x294;
        let x1152 = x1104 + x1151;
        let x1153 = x1102 + x1152;
        let x1154 = 0.5 * x1153;
        let x1155 = x15 * 4.0;
        let x1156 = x1154 + x1155;
        let x1157 = x242 * x561;
        let x1160 = x1157 - x1137;
        let x1161 = x1160 - x1136;
        let x1162 = 0.5 * x1161;
        let x1163 = x28 * 4.0;
        let x1164 = x1162 + x1163;
        let x1165 = x242 * x487;
        let x1167 = x1126 + x1165;
        let x1169 = x1125 - x1167;
        let x1170 = 0.5 * x1169;
        let x1171 = x35 * 4.0;
        let x1172 = x1170 + x1171;
        let x1174 = x1124 - x1167;
        let x1175 = 0.5 * x1174;
        let x1176 = x1132 + x1175;
        let x1178 = x1137 - x1157;
        let x1179 = x1178 - x1134;
        let x1180 = 0.5 * x1179;
        let x1181 = x1163 + x1180;
        let x1182 = x1100 + x1152;
        let x1183 = 0.5 * x1182;
        let x1184 = x16 * 4.0;
        let x1185 = x1183 + x1184;
        let x1187 = x1144 - x1117;
        let x1188 = x1187 - x1114;
        let x1189 = 0.5 * x1188;
        let x1190 = x41 * 4.0;
        let x1191 = x1189 + x1190;
        let x1192 = x1138 - x1157;
        let x1193 = 0.5 * x1192;
        let x1194 = x1142 + x1193;
        let x1197 = x1165 - x1128;
        let x1198 = 0.5 * x1197;
        let x1199 = x1171 + x1198;
        let x1200 = x1118 - x1144;
        let x1201 = 0.5 * x1200;
        let x1202 = x1190 + x1201;
        let x1203 = x1106 + x1151;
        let x1204 = 0.5 * x1203;
        let x1205 = x17 * 4.0;
        let x1206 = x1204 + x1205;
        out[0] = 1.0;
        out[1] = 1.0;
        out[2] = 1.0;
        out[3] = x1113;
        out[4] = x1123;
        out[5] = x1133;
        out[6] = x1143;
        out[7] = x1150;
        out[8] = x1156;
        out[9] = x1164;
        out[10] = x1172;
        out[11] = x1176;
        out[12] = x1181;
        out[13] = x1185;
        out[14] = x1191;
        out[15] = x1194;
        out[16] = x1199;
        out[17] = x1202;
        out[18] = x1206;
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
        let x242 = q[3] * 2.0;
        let x243 = q[4] * 2.0;
        let x244 = q[5] * 2.0;
        let x245 = q[6] * 2.0;
        let x626 = q[5] * qd[4];
        let x627 = q[4] * qd[5];
        let x630 = q[6] * qd[3];
        let x631 = q[3] * qd[6];
        let x636 = q[6] * qd[4];
        let x637 = q[4] * qd[6];
        let x640 = q[5] * qd[3];
        let x641 = q[3] * qd[5];
        let x646 = q[6] * qd[5];
        let x647 = q[5] * qd[6];
        let x650 = q[4] * qd[3];
        let x651 = q[3] * qd[4];
        let x778 = 2.0 * qd[3];
        let x779 = 2.0 * qd[4];
        let x780 = 2.0 * qd[5];
        let x781 = 2.0 * qd[6];
        let x834 = qd[4] * qd[5];
        let x837 = qd[3] * qd[6];
        let x842 = qd[4] * qd[6];
        let x845 = qd[3] * qd[5];
        let x1023 = x651 - x650;
        let x1024 = x646 + x1023;
        let x1025 = x1024 - x647;
        let x1026 = 2.0 * x1025;
        let x1029 = x636 + x640;
        let x1031 = x641 - x1029;
        let x1032 = x637 + x1031;
        let x1033 = 2.0 * x1032;
        let x1036 = x626 - x630;
        let x1037 = x1036 - x627;
        let x1038 = x631 + x1037;
        let x1039 = 2.0 * x1038;
        let x1052 = 2.0 * x1026;
        let x1053 = 2.0 * x1033;
        let x1054 = 2.0 * x1039;
        let x1209 = x842 + x845;
        let x1211 = x845 - x1209;
        let x1212 = x842 + x1211;
        let x1213 = 2.0 * x1212;
        let x1216 = x834 - x837;
        let x1217 = x1216 - x834;
        let x1218 = x837 + x1217;
        let x1219 = 2.0 * x1218;
        let x1220 = 2.0 * x1213;
        let x1221 = 2.0 * x1219;
        let x1222 = x779 * x1052;
        let x1223 = x780 * x1053;
        let x1224 = x244 * x1220;
        let x1225 = x1223 + x1224;
        let x1226 = x781 * x1054;
        let x1227 = x245 * x1221;
        let x1228 = x1226 + x1227;
        let x1229 = x1222 + x1225;
        let x1230 = x1228 + x1229;
        let x1231 = 0.5 * x1230;
        let x1233 = x778 * x1052;
        let x1234 = x781 * x1053;
        let x1235 = x245 * x1220;
        let x1236 = x1234 + x1235;
        let x1238 = x780 * x1054;
        let x1239 = x244 * x1221;
        let x1240 = x1238 + x1239;
        let x1241 = x1233 - x1236;
        let x1242 = x1240 + x1241;
        let x1243 = 0.5 * x1242;
        let x1244 = x781 * x1052;
        let x1245 = x778 * x1053;
        let x1246 = x242 * x1220;
        let x1247 = x1245 + x1246;
        let x1248 = x779 * x1054;
        let x1249 = x243 * x1221;
        let x1250 = x1248 + x1249;
        let x1252 = x1244 + x1247;
        let x1253 = x1252 - x1250;
        let x1254 = 0.5 * x1253;
        let x1255 = x780 * x1052;
        let x1257 = x779 * x1053;
        let x1258 = x243 * x1220;
        let x1259 = x1257 + x1258;
        let x1260 = x778 * x1054;
        let x1261 = x242 * x1221;
        let x1262 = x1260 + x1261;
        let x1263 = x1259 - x1255;
        let x1264 = x1262 + x1263;
        let x1265 = 0.5 * x1264;
        let x1266 = qd[3] * qd[3];
        let x1267 = qd[4] * qd[4];
        let x1268 = qd[5] * qd[5];
        let x1269 = qd[6] * qd[6];
        let x1270 = x1266 + x1267;
        let x1271 = x1268 + x1270;
        let x1272 = x1269 + x1271;
        let x1273 = x1222 + x1223;
        let x1274 = x1226 + x1273;
        let x1275 = 0.5 * x1274;
        let x1276 = x1231 + x1275;
        let x1277 = q[3] * 4.0;
        let x1278 = x1272 * x1277;
        let x1280 = x1276 - x1278;
        let x1287 = x1234 - x1233;
        let x1288 = x1287 - x1238;
        let x1289 = 0.5 * x1288;
        let x1291 = x1289 - x1243;
        let x1292 = q[4] * 4.0;
        let x1293 = x1272 * x1292;
        let x1295 = x1291 - x1293;
        let x1300 = x1244 + x1245;
        let x1302 = x1248 - x1300;
        let x1303 = 0.5 * x1302;
        let x1305 = x1303 - x1254;
        let x1306 = q[5] * 4.0;
        let x1307 = x1272 * x1306;
        let x1309 = x1305 - x1307;
        let x1314 = x1255 - x1257;
        let x1315 = x1314 - x1260;
        let x1316 = 0.5 * x1315;
        let x1318 = x1316 - x1265;
        let x1319 = q[6] * 4.0;
        let x1320 = x1272 * x1319;
        let x1322 = x1318 - x1320;
        out[0] = 0.0;
        out[1] = 0.0;
        out[2] = 0.0;
        out[3] = x1280;
        out[4] = x1295;
        out[5] = x1309;
        out[6] = x1322;
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
        let phi: &mut [f64; 7] = phi.try_into().expect("phi must have 7 entries");
        let phi_q: &mut [f64; 42] = phi_q
            .try_into()
            .expect("phi_q must have 42 entries");
        let mass: &mut [f64; 19] = mass.try_into().expect("mass must have 19 entries");
        let force: &mut [f64; 7] = force.try_into().expect("force must have 7 entries");
        let _ = t;
        let mut s = [0.0f64; 4];
        eval_newton_shared_0(q, qd, t, &mut s);
        eval_newton_part_0(q, &s, phi, phi_q, mass, force);
        eval_newton_part_1(q, qd, &s, force);
    }
    #[inline(never)]
    fn eval_newton_shared_0(q: &[f64; 7], _qd: &[f64; 7], _t: f64, s: &mut [f64; 4]) {
        let x242 = q[3] * 2.0;
        s[0] = x242;
        let x243 = q[4] * 2.0;
        s[1] = x243;
        let x244 = q[5] * 2.0;
        s[2] = x244;
        let x245 = q[6] * 2.0;
        s[3] = x245;
    }
    #[inline(never)]
    fn eval_newton_part_0(
        q: &[f64; 7],
        s: &[f64; 4],
        phi: &mut [f64; 7],
        phi_q: &mut [f64; 42],
        mass: &mut [f64; 19],
        force: &mut [f64; 7],
    ) {
        let x14 = q[3] * q[3];
        let x15 = q[4] * q[4];
        let x16 = q[5] * q[5];
        let x17 = q[6] * q[6];
        let x18 = x14 + x15;
        let x19 = 2.0 * x18;
        let x21 = x19 - 1.0;
        let x22 = x14 + x16;
        let x23 = 2.0 * x22;
        let x24 = x23 - 1.0;
        let x25 = x14 + x17;
        let x26 = 2.0 * x25;
        let x27 = x26 - 1.0;
        let x28 = q[4] * q[5];
        let x29 = 2.0 * x28;
        let x30 = q[3] * q[6];
        let x32 = 2.0 * x30;
        let x34 = x29 - x32;
        let x35 = q[4] * q[6];
        let x36 = 2.0 * x35;
        let x37 = q[3] * q[5];
        let x38 = 2.0 * x37;
        let x39 = x36 + x38;
        let x40 = x29 + x32;
        let x41 = q[5] * q[6];
        let x42 = 2.0 * x41;
        let x43 = q[3] * q[4];
        let x45 = 2.0 * x43;
        let x47 = x42 - x45;
        let x50 = x36 - x38;
        let x51 = x42 + x45;
        let x53 = q[0] * q[0];
        let x54 = q[1] * q[1];
        let x55 = q[2] * q[2];
        let x56 = x53 + x54;
        let x57 = x55 + x56;
        let x58 = x57.sqrt();
        let x59 = x58 - 1.0;
        let x62 = x21 * 0.542805;
        let x63 = x40 * 0.542805;
        let x64 = x50 * 0.542805;
        let x65 = q[0] + x62;
        let x66 = q[1] + x63;
        let x67 = q[2] + x64;
        let x69 = x65 - 1.107915;
        let x70 = x69 * x69;
        let x71 = x66 * x66;
        let x72 = x67 * x67;
        let x73 = x70 + x71;
        let x74 = x72 + x73;
        let x75 = x74.sqrt();
        let x77 = x75 - 0.645275;
        let x82 = x21 * 0.956919;
        let x84 = x34 * 0.528915;
        let x86 = x82 - x84;
        let x87 = x40 * 0.956919;
        let x88 = x24 * 0.528915;
        let x90 = x87 - x88;
        let x91 = x50 * 0.956919;
        let x92 = x51 * 0.528915;
        let x94 = x91 - x92;
        let x95 = q[0] + x86;
        let x96 = q[1] + x90;
        let x97 = q[2] + x94;
        let x99 = x95 - 0.549094;
        let x101 = x96 - 0.756063;
        let x102 = x99 * x99;
        let x103 = x101 * x101;
        let x104 = x97 * x97;
        let x105 = x102 + x103;
        let x106 = x104 + x105;
        let x107 = x106.sqrt();
        let x109 = x107 - 1.086284;
        let x116 = x21 * 0.665885;
        let x118 = x34 * 0.353482;
        let x120 = x39 * 1.402538;
        let x121 = x116 - x118;
        let x122 = x120 + x121;
        let x123 = x40 * 0.665885;
        let x124 = x24 * 0.353482;
        let x126 = x47 * 1.402538;
        let x127 = x123 - x124;
        let x128 = x126 + x127;
        let x129 = x50 * 0.665885;
        let x130 = x51 * 0.353482;
        let x132 = x27 * 1.402538;
        let x133 = x129 - x130;
        let x134 = x132 + x133;
        let x135 = q[0] + x122;
        let x136 = q[1] + x128;
        let x137 = q[2] + x134;
        let x139 = x135 - 0.735077;
        let x141 = x136 + 0.223935;
        let x143 = x137 - 0.525991;
        let x144 = x139 * x139;
        let x145 = x141 * x141;
        let x146 = x143 * x143;
        let x147 = x144 + x145;
        let x148 = x146 + x147;
        let x149 = x148.sqrt();
        let x151 = x149 - 1.503439;
        let x158 = x21 * 0.478359;
        let x159 = x34 * 1.158742;
        let x160 = x39 * 0.107672;
        let x161 = x158 + x159;
        let x162 = x160 + x161;
        let x163 = x40 * 0.478359;
        let x164 = x24 * 1.158742;
        let x165 = x47 * 0.107672;
        let x166 = x163 + x164;
        let x167 = x165 + x166;
        let x168 = x50 * 0.478359;
        let x169 = x51 * 1.158742;
        let x170 = x27 * 0.107672;
        let x171 = x168 + x169;
        let x172 = x170 + x171;
        let x173 = q[0] + x162;
        let x174 = q[1] + x167;
        let x175 = q[2] + x172;
        let x177 = x173 - 0.514188;
        let x179 = x174 + 0.526063;
        let x181 = x175 + 0.368418;
        let x182 = x177 * x177;
        let x183 = x179 * x179;
        let x184 = x181 * x181;
        let x185 = x182 + x183;
        let x186 = x184 + x185;
        let x187 = x186.sqrt();
        let x189 = x187 - 1.281933;
        let x197 = x21 * 0.137087;
        let x200 = x34 * 0.235121;
        let x202 = x39 * 0.353913;
        let x203 = x197 + x200;
        let x205 = x202 - x203;
        let x206 = x40 * 0.137087;
        let x208 = x24 * 0.235121;
        let x210 = x47 * 0.353913;
        let x211 = x206 + x208;
        let x213 = x210 - x211;
        let x214 = x50 * 0.137087;
        let x216 = x51 * 0.235121;
        let x218 = x27 * 0.353913;
        let x219 = x214 + x216;
        let x221 = x218 - x219;
        let x222 = q[0] + x205;
        let x223 = q[1] + x213;
        let x224 = q[2] + x221;
        let x226 = x222 - 0.590473;
        let x228 = x223 - 0.094733;
        let x230 = x224 + 0.205018;
        let x231 = x226 * x226;
        let x232 = x228 * x228;
        let x233 = x230 * x230;
        let x234 = x231 + x232;
        let x235 = x233 + x234;
        let x236 = x235.sqrt();
        let x238 = x236 - 0.771071;
        let x239 = x16 + x18;
        let x240 = x17 + x239;
        let x241 = x240 - 1.0;
        let x246 = q[0] * 2.0;
        let x247 = q[1] * 2.0;
        let x248 = q[2] * 2.0;
        let x249 = 2.0 * x58;
        let x250 = 1.0 / x249;
        let x251 = x246 * x250;
        let x252 = 2.0 * x69;
        let x253 = 2.0 * x66;
        let x254 = 2.0 * x67;
        let x255 = 2.0 * x75;
        let x256 = 1.0 / x255;
        let x257 = x252 * x256;
        let x258 = 2.0 * x99;
        let x259 = 2.0 * x101;
        let x260 = 2.0 * x97;
        let x261 = 2.0 * x107;
        let x262 = 1.0 / x261;
        let x263 = x258 * x262;
        let x264 = 2.0 * x139;
        let x265 = 2.0 * x141;
        let x266 = 2.0 * x143;
        let x267 = 2.0 * x149;
        let x268 = 1.0 / x267;
        let x269 = x264 * x268;
        let x270 = 2.0 * x177;
        let x271 = 2.0 * x179;
        let x272 = 2.0 * x181;
        let x273 = 2.0 * x187;
        let x274 = 1.0 / x273;
        let x275 = x270 * x274;
        let x276 = 2.0 * x226;
        let x277 = 2.0 * x228;
        let x278 = 2.0 * x230;
        let x279 = 2.0 * x236;
        let x280 = 1.0 / x279;
        let x281 = x276 * x280;
        let x282 = x247 * x250;
        let x283 = x253 * x256;
        let x284 = x259 * x262;
        let x285 = x265 * x268;
        let x286 = x271 * x274;
        let x287 = x277 * x280;
        let x288 = x248 * x250;
        let x289 = x254 * x256;
        let x290 = x260 * x262;
        let x291 = x266 * x268;
        let x292 = x272 * x274;
        let x293 = x278 * x280;
        let x294 = 2.0 * s[0];
        let x298 = 0.542805 * x294;
        let x299 = 0.542805 * s[3];
        let x300 = 0.542805 * s[2];
        let x302 = x252 * x298;
        let x303 = x253 * x299;
        let x304 = x254 * x300;
        let x306 = x302 + x303;
        let x307 = x306 - x304;
        let x308 = x256 * x307;
        let x309 = 0.956919 * x294;
        let x310 = 0.528915 * s[3];
        let x312 = x309 + x310;
        let x313 = 0.956919 * s[3];
        let x314 = 0.528915 * x294;
        let x316 = x313 - x314;
        let x317 = 0.956919 * s[2];
        let x319 = 0.528915 * s[1];
        let x321 = x317 + x319;
        let x323 = x258 * x312;
        let x324 = x259 * x316;
        let x325 = x260 * x321;
        let x327 = x323 + x324;
        let x328 = x327 - x325;
        let x329 = x262 * x328;
        let x330 = 0.665885 * x294;
        let x331 = 0.353482 * s[3];
        let x333 = 1.402538 * s[2];
        let x334 = x330 + x331;
        let x335 = x333 + x334;
        let x336 = 0.665885 * s[3];
        let x337 = 0.353482 * x294;
        let x339 = 1.402538 * s[1];
        let x341 = x336 - x337;
        let x342 = x341 - x339;
        let x343 = 0.665885 * s[2];
        let x345 = 0.353482 * s[1];
        let x347 = 1.402538 * x294;
        let x348 = x343 + x345;
        let x350 = x347 - x348;
        let x351 = x264 * x335;
        let x352 = x265 * x342;
        let x353 = x266 * x350;
        let x354 = x351 + x352;
        let x355 = x353 + x354;
        let x356 = x268 * x355;
        let x357 = 0.478359 * x294;
        let x358 = 1.158742 * s[3];
        let x360 = 0.107672 * s[2];
        let x361 = x357 - x358;
        let x362 = x360 + x361;
        let x363 = 0.478359 * s[3];
        let x364 = 1.158742 * x294;
        let x365 = 0.107672 * s[1];
        let x367 = x363 + x364;
        let x368 = x367 - x365;
        let x369 = 0.478359 * s[2];
        let x371 = 1.158742 * s[1];
        let x372 = 0.107672 * x294;
        let x373 = x371 - x369;
        let x374 = x372 + x373;
        let x375 = x270 * x362;
        let x376 = x271 * x368;
        let x377 = x272 * x374;
        let x378 = x375 + x376;
        let x379 = x377 + x378;
        let x380 = x274 * x379;
        let x381 = 0.137087 * x294;
        let x382 = 0.235121 * s[3];
        let x384 = 0.353913 * s[2];
        let x385 = x381 - x382;
        let x387 = x384 - x385;
        let x388 = 0.137087 * s[3];
        let x389 = 0.235121 * x294;
        let x390 = 0.353913 * s[1];
        let x392 = x388 + x389;
        let x394 = x390 + x392;
        let x396 = 0.137087 * s[2];
        let x398 = 0.235121 * s[1];
        let x399 = 0.353913 * x294;
        let x400 = x398 - x396;
        let x402 = x399 - x400;
        let x403 = x276 * x387;
        let x404 = x277 * x394;
        let x406 = x278 * x402;
        let x407 = x403 - x404;
        let x408 = x406 + x407;
        let x409 = x280 * x408;
        let x410 = 2.0 * s[1];
        let x412 = 0.542805 * x410;
        let x413 = x252 * x412;
        let x414 = x253 * x300;
        let x415 = x254 * x299;
        let x416 = x413 + x414;
        let x417 = x415 + x416;
        let x418 = x256 * x417;
        let x419 = 0.956919 * x410;
        let x420 = 0.528915 * s[2];
        let x422 = x419 - x420;
        let x423 = 0.528915 * s[0];
        let x425 = x313 - x423;
        let x426 = x258 * x422;
        let x427 = x259 * x317;
        let x428 = x260 * x425;
        let x429 = x426 + x427;
        let x430 = x428 + x429;
        let x431 = x262 * x430;
        let x432 = 0.665885 * x410;
        let x433 = 0.353482 * s[2];
        let x435 = 1.402538 * s[3];
        let x436 = x432 - x433;
        let x437 = x435 + x436;
        let x438 = 1.402538 * s[0];
        let x440 = x343 - x438;
        let x441 = 0.353482 * s[0];
        let x443 = x336 - x441;
        let x444 = x264 * x437;
        let x445 = x265 * x440;
        let x446 = x266 * x443;
        let x447 = x444 + x445;
        let x448 = x446 + x447;
        let x449 = x268 * x448;
        let x450 = 0.478359 * x410;
        let x451 = 1.158742 * s[2];
        let x452 = 0.107672 * s[3];
        let x453 = x450 + x451;
        let x454 = x452 + x453;
        let x455 = 0.107672 * s[0];
        let x457 = x369 - x455;
        let x458 = 1.158742 * s[0];
        let x459 = x363 + x458;
        let x460 = x270 * x454;
        let x461 = x271 * x457;
        let x462 = x272 * x459;
        let x463 = x460 + x461;
        let x464 = x462 + x463;
        let x465 = x274 * x464;
        let x466 = 0.137087 * x410;
        let x467 = 0.235121 * s[2];
        let x468 = 0.353913 * s[3];
        let x469 = x466 + x467;
        let x471 = x468 - x469;
        let x472 = 0.353913 * s[0];
        let x474 = x396 + x472;
        let x476 = 0.235121 * s[0];
        let x477 = x388 + x476;
        let x479 = x276 * x471;
        let x480 = x277 * x474;
        let x482 = x278 * x477;
        let x484 = x479 - x480;
        let x485 = x484 - x482;
        let x486 = x280 * x485;
        let x487 = 2.0 * s[2];
        let x488 = 0.542805 * s[1];
        let x489 = 0.542805 * s[0];
        let x491 = x253 * x488;
        let x492 = x254 * x489;
        let x494 = x491 - x492;
        let x495 = x256 * x494;
        let x496 = 0.956919 * s[1];
        let x497 = 0.528915 * x487;
        let x499 = x496 - x497;
        let x500 = 0.956919 * s[0];
        let x502 = x310 + x500;
        let x504 = x258 * x319;
        let x506 = x259 * x499;
        let x507 = x260 * x502;
        let x509 = x506 - x504;
        let x510 = x509 - x507;
        let x511 = x262 * x510;
        let x512 = x438 - x345;
        let x513 = 0.665885 * s[1];
        let x514 = 0.353482 * x487;
        let x516 = x513 - x514;
        let x517 = x435 + x516;
        let x518 = 0.665885 * s[0];
        let x520 = x331 + x518;
        let x522 = x264 * x512;
        let x523 = x265 * x517;
        let x524 = x266 * x520;
        let x526 = x522 + x523;
        let x527 = x526 - x524;
        let x528 = x268 * x527;
        let x529 = x371 + x455;
        let x530 = 0.478359 * s[1];
        let x531 = 1.158742 * x487;
        let x532 = x530 + x531;
        let x533 = x452 + x532;
        let x534 = 0.478359 * s[0];
        let x536 = x358 - x534;
        let x537 = x270 * x529;
        let x538 = x271 * x533;
        let x539 = x272 * x536;
        let x540 = x537 + x538;
        let x541 = x539 + x540;
        let x542 = x274 * x541;
        let x544 = x472 - x398;
        let x545 = 0.137087 * s[1];
        let x546 = 0.235121 * x487;
        let x547 = x545 + x546;
        let x549 = x468 - x547;
        let x550 = 0.137087 * s[0];
        let x552 = x382 - x550;
        let x554 = x276 * x544;
        let x555 = x277 * x549;
        let x556 = x278 * x552;
        let x558 = x554 + x555;
        let x559 = x558 - x556;
        let x560 = x280 * x559;
        let x561 = 2.0 * s[3];
        let x562 = x253 * x489;
        let x563 = x254 * x488;
        let x564 = x562 + x563;
        let x565 = x256 * x564;
        let x566 = x496 - x420;
        let x567 = x258 * x423;
        let x568 = x259 * x500;
        let x569 = x260 * x566;
        let x570 = x567 + x568;
        let x571 = x569 + x570;
        let x572 = x262 * x571;
        let x573 = x339 + x441;
        let x574 = x333 + x518;
        let x575 = 1.402538 * x561;
        let x576 = x513 - x433;
        let x577 = x575 + x576;
        let x578 = x264 * x573;
        let x579 = x265 * x574;
        let x580 = x266 * x577;
        let x581 = x578 + x579;
        let x582 = x580 + x581;
        let x583 = x268 * x582;
        let x585 = x365 - x458;
        let x586 = x360 + x534;
        let x587 = 0.107672 * x561;
        let x588 = x451 + x530;
        let x589 = x587 + x588;
        let x590 = x270 * x585;
        let x591 = x271 * x586;
        let x592 = x272 * x589;
        let x593 = x590 + x591;
        let x594 = x592 + x593;
        let x595 = x274 * x594;
        let x597 = x390 + x476;
        let x598 = x384 - x550;
        let x599 = 0.353913 * x561;
        let x600 = x467 + x545;
        let x602 = x599 - x600;
        let x603 = x276 * x597;
        let x604 = x277 * x598;
        let x605 = x278 * x602;
        let x606 = x603 + x604;
        let x607 = x605 + x606;
        let x608 = x280 * x607;
        let x1100 = s[1] * x410;
        let x1102 = s[2] * x487;
        let x1104 = s[3] * x561;
        let x1106 = x1100 + x1102;
        let x1108 = x1104 + x1106;
        let x1110 = 0.5 * x1108;
        let x1112 = x14 * 4.0;
        let x1113 = x1110 + x1112;
        let x1114 = s[1] * x294;
        let x1115 = s[2] * x561;
        let x1117 = s[3] * x487;
        let x1118 = x1114 - x1115;
        let x1119 = x1117 + x1118;
        let x1120 = 0.5 * x1119;
        let x1122 = x43 * 4.0;
        let x1123 = x1122 - x1120;
        let x1124 = s[1] * x561;
        let x1125 = s[2] * x294;
        let x1126 = s[3] * x410;
        let x1128 = x1124 + x1125;
        let x1129 = x1128 - x1126;
        let x1130 = 0.5 * x1129;
        let x1132 = x37 * 4.0;
        let x1133 = x1132 - x1130;
        let x1134 = s[1] * x487;
        let x1136 = s[2] * x410;
        let x1137 = s[3] * x294;
        let x1138 = x1136 - x1134;
        let x1139 = x1137 + x1138;
        let x1140 = 0.5 * x1139;
        let x1142 = x30 * 4.0;
        let x1143 = x1142 - x1140;
        let x1144 = s[0] * x410;
        let x1147 = x1117 - x1144;
        let x1148 = x1147 - x1115;
        let x1149 = 0.5 * x1148;
        let x1150 = x1122 + x1149;
        let x1151 = s[0] * x294;
        let x1152 = x1104 + x1151;
        let x1153 = x1102 + x1152;
        let x1154 = 0.5 * x1153;
        let x1155 = x15 * 4.0;
        let x1156 = x1154 + x1155;
        let x1157 = s[0] * x561;
        let x1160 = x1157 - x1137;
        let x1161 = x1160 - x1136;
        let x1162 = 0.5 * x1161;
        let x1163 = x28 * 4.0;
        let x1164 = x1162 + x1163;
        let x1165 = s[0] * x487;
        let x1167 = x1126 + x1165;
        let x1169 = x1125 - x1167;
        let x1170 = 0.5 * x1169;
        let x1171 = x35 * 4.0;
        let x1172 = x1170 + x1171;
        let x1174 = x1124 - x1167;
        let x1175 = 0.5 * x1174;
        let x1176 = x1132 + x1175;
        let x1178 = x1137 - x1157;
        let x1179 = x1178 - x1134;
        let x1180 = 0.5 * x1179;
        let x1181 = x1163 + x1180;
        let x1182 = x1100 + x1152;
        let x1183 = 0.5 * x1182;
        let x1184 = x16 * 4.0;
        let x1185 = x1183 + x1184;
        let x1187 = x1144 - x1117;
        let x1188 = x1187 - x1114;
        let x1189 = 0.5 * x1188;
        let x1190 = x41 * 4.0;
        let x1191 = x1189 + x1190;
        let x1192 = x1138 - x1157;
        let x1193 = 0.5 * x1192;
        let x1194 = x1142 + x1193;
        let x1197 = x1165 - x1128;
        let x1198 = 0.5 * x1197;
        let x1199 = x1171 + x1198;
        let x1200 = x1118 - x1144;
        let x1201 = 0.5 * x1200;
        let x1202 = x1190 + x1201;
        let x1203 = x1106 + x1151;
        let x1204 = 0.5 * x1203;
        let x1205 = x17 * 4.0;
        let x1206 = x1204 + x1205;
        phi[0] = x59;
        phi_q[0] = x251;
        phi_q[1] = x282;
        phi_q[2] = x288;
        phi[1] = x77;
        phi_q[3] = x257;
        phi_q[4] = x283;
        phi_q[5] = x289;
        phi_q[6] = x308;
        phi_q[7] = x418;
        phi_q[8] = x495;
        phi_q[9] = x565;
        phi[2] = x109;
        phi_q[10] = x263;
        phi_q[11] = x284;
        phi_q[12] = x290;
        phi_q[13] = x329;
        phi_q[14] = x431;
        phi_q[15] = x511;
        phi_q[16] = x572;
        phi[3] = x151;
        phi_q[17] = x269;
        phi_q[18] = x285;
        phi_q[19] = x291;
        phi_q[20] = x356;
        phi_q[21] = x449;
        phi_q[22] = x528;
        phi_q[23] = x583;
        phi[4] = x189;
        phi_q[24] = x275;
        phi_q[25] = x286;
        phi_q[26] = x292;
        phi_q[27] = x380;
        phi_q[28] = x465;
        phi_q[29] = x542;
        phi_q[30] = x595;
        phi[5] = x238;
        phi_q[31] = x281;
        phi_q[32] = x287;
        phi_q[33] = x293;
        phi_q[34] = x409;
        phi_q[35] = x486;
        phi_q[36] = x560;
        phi_q[37] = x608;
        phi[6] = x241;
        phi_q[38] = s[0];
        phi_q[39] = s[1];
        phi_q[40] = s[2];
        phi_q[41] = s[3];
        mass[0] = 1.0;
        mass[1] = 1.0;
        mass[2] = 1.0;
        mass[3] = x1113;
        mass[4] = x1123;
        mass[5] = x1133;
        mass[6] = x1143;
        mass[7] = x1150;
        mass[8] = x1156;
        mass[9] = x1164;
        mass[10] = x1172;
        mass[11] = x1176;
        mass[12] = x1181;
        mass[13] = x1185;
        mass[14] = x1191;
        mass[15] = x1194;
        mass[16] = x1199;
        mass[17] = x1202;
        mass[18] = x1206;
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
        let x626 = q[5] * qd[4];
        let x627 = q[4] * qd[5];
        let x630 = q[6] * qd[3];
        let x631 = q[3] * qd[6];
        let x636 = q[6] * qd[4];
        let x637 = q[4] * qd[6];
        let x640 = q[5] * qd[3];
        let x641 = q[3] * qd[5];
        let x646 = q[6] * qd[5];
        let x647 = q[5] * qd[6];
        let x650 = q[4] * qd[3];
        let x651 = q[3] * qd[4];
        let x778 = 2.0 * qd[3];
        let x779 = 2.0 * qd[4];
        let x780 = 2.0 * qd[5];
        let x781 = 2.0 * qd[6];
        let x834 = qd[4] * qd[5];
        let x837 = qd[3] * qd[6];
        let x842 = qd[4] * qd[6];
        let x845 = qd[3] * qd[5];
        let x1023 = x651 - x650;
        let x1024 = x646 + x1023;
        let x1025 = x1024 - x647;
        let x1026 = 2.0 * x1025;
        let x1029 = x636 + x640;
        let x1031 = x641 - x1029;
        let x1032 = x637 + x1031;
        let x1033 = 2.0 * x1032;
        let x1036 = x626 - x630;
        let x1037 = x1036 - x627;
        let x1038 = x631 + x1037;
        let x1039 = 2.0 * x1038;
        let x1052 = 2.0 * x1026;
        let x1053 = 2.0 * x1033;
        let x1054 = 2.0 * x1039;
        let x1209 = x842 + x845;
        let x1211 = x845 - x1209;
        let x1212 = x842 + x1211;
        let x1213 = 2.0 * x1212;
        let x1216 = x834 - x837;
        let x1217 = x1216 - x834;
        let x1218 = x837 + x1217;
        let x1219 = 2.0 * x1218;
        let x1220 = 2.0 * x1213;
        let x1221 = 2.0 * x1219;
        let x1222 = x779 * x1052;
        let x1223 = x780 * x1053;
        let x1224 = s[2] * x1220;
        let x1225 = x1223 + x1224;
        let x1226 = x781 * x1054;
        let x1227 = s[3] * x1221;
        let x1228 = x1226 + x1227;
        let x1229 = x1222 + x1225;
        let x1230 = x1228 + x1229;
        let x1231 = 0.5 * x1230;
        let x1233 = x778 * x1052;
        let x1234 = x781 * x1053;
        let x1235 = s[3] * x1220;
        let x1236 = x1234 + x1235;
        let x1238 = x780 * x1054;
        let x1239 = s[2] * x1221;
        let x1240 = x1238 + x1239;
        let x1241 = x1233 - x1236;
        let x1242 = x1240 + x1241;
        let x1243 = 0.5 * x1242;
        let x1244 = x781 * x1052;
        let x1245 = x778 * x1053;
        let x1246 = s[0] * x1220;
        let x1247 = x1245 + x1246;
        let x1248 = x779 * x1054;
        let x1249 = s[1] * x1221;
        let x1250 = x1248 + x1249;
        let x1252 = x1244 + x1247;
        let x1253 = x1252 - x1250;
        let x1254 = 0.5 * x1253;
        let x1255 = x780 * x1052;
        let x1257 = x779 * x1053;
        let x1258 = s[1] * x1220;
        let x1259 = x1257 + x1258;
        let x1260 = x778 * x1054;
        let x1261 = s[0] * x1221;
        let x1262 = x1260 + x1261;
        let x1263 = x1259 - x1255;
        let x1264 = x1262 + x1263;
        let x1265 = 0.5 * x1264;
        let x1266 = qd[3] * qd[3];
        let x1267 = qd[4] * qd[4];
        let x1268 = qd[5] * qd[5];
        let x1269 = qd[6] * qd[6];
        let x1270 = x1266 + x1267;
        let x1271 = x1268 + x1270;
        let x1272 = x1269 + x1271;
        let x1273 = x1222 + x1223;
        let x1274 = x1226 + x1273;
        let x1275 = 0.5 * x1274;
        let x1276 = x1231 + x1275;
        let x1277 = q[3] * 4.0;
        let x1278 = x1272 * x1277;
        let x1280 = x1276 - x1278;
        let x1287 = x1234 - x1233;
        let x1288 = x1287 - x1238;
        let x1289 = 0.5 * x1288;
        let x1291 = x1289 - x1243;
        let x1292 = q[4] * 4.0;
        let x1293 = x1272 * x1292;
        let x1295 = x1291 - x1293;
        let x1300 = x1244 + x1245;
        let x1302 = x1248 - x1300;
        let x1303 = 0.5 * x1302;
        let x1305 = x1303 - x1254;
        let x1306 = q[5] * 4.0;
        let x1307 = x1272 * x1306;
        let x1309 = x1305 - x1307;
        let x1314 = x1255 - x1257;
        let x1315 = x1314 - x1260;
        let x1316 = 0.5 * x1315;
        let x1318 = x1316 - x1265;
        let x1319 = q[6] * 4.0;
        let x1320 = x1272 * x1319;
        let x1322 = x1318 - x1320;
        force[3] = x1280;
        force[4] = x1295;
        force[5] = x1309;
        force[6] = x1322;
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
    run_time: None,
};
