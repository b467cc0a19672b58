//! Generated equations of `hexapod_twist` (the paper's platform on massless legs twisted into its 90° parallel singularity). Do not edit.
//!
//! Regenerate with `cargo xtask generate hexapod_twist` from `mechanisms/hexapod_twist.toml`.
//!
//! 7 coordinates, 7 constraints, 46 structural nonzeros in Φq.
//! Rank 7 at the initial pose; mobility 6 (Grübler count 6), 0 DOF left with drivers.
//! Each body owns `[X, Y, Z]` (centre of mass), then `[θ, β, γ]` (A = Rz(γ)·Ry(β)·Rx(θ))
//! or Euler parameters `[e0, e1, e2, e3]`. Equations of motion: `M q̈ + Φqᵀλ = Q`, `Φq q̈ = γ`.
//! Sparse outputs hold the pattern's nonzeros in order (row-major, columns ascending).
//!
//! Coordinates:
//! - `0..7` platform (quaternion)
//!
//! Constraint rows:
//! - `0` leg1 (driver): point distance − f, f = (k - c * cos(alpha1.to_radians() + rate * t - phi1.to_radians())).sqrt(), initial = 0.400040306
//! - `1` leg2 (driver): point distance − f, f = (k - c * cos(alpha2.to_radians() + rate * t - phi2.to_radians())).sqrt(), initial = 0.400040306
//! - `2` leg3 (driver): point distance − f, f = (k - c * cos(alpha3.to_radians() + rate * t - phi3.to_radians())).sqrt(), initial = 0.400040306
//! - `3` leg4 (driver): point distance − f, f = (k - c * cos(alpha4.to_radians() + rate * t - phi4.to_radians())).sqrt(), initial = 0.400040306
//! - `4` leg5 (driver): point distance − f, f = (k - c * cos(alpha5.to_radians() + rate * t - phi5.to_radians())).sqrt(), initial = 0.400040306
//! - `5` leg6 (driver): point distance − f, f = (k - c * cos(alpha6.to_radians() + rate * t - phi6.to_radians())).sqrt(), initial = 0.400040306
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
    phi_part_0(q, t, out);
}
#[inline(never)]
fn phi_part_0(q: &[f64; 7], t: f64, out: &mut [f64; 7]) {
    let x7 = 0.8726646259971648 * t;
    let x8 = 0.8639379797371931 + x7;
    let x12 = x8 - 0.1832595714594046;
    let x13 = x12.cos();
    let x14 = 0.0567 * x13;
    let x16 = 0.20409642230625002 - x14;
    let x17 = x16.sqrt();
    let x20 = x7 + 1.2304571226560024;
    let x24 = x20 - 1.911135530933791;
    let x25 = x24.cos();
    let x26 = 0.0567 * x25;
    let x28 = 0.20409642230625002 - x26;
    let x29 = x28.sqrt();
    let x32 = x7 + 2.9583330821303884;
    let x36 = x32 - 2.2776546738526;
    let x37 = x36.cos();
    let x38 = 0.0567 * x37;
    let x40 = 0.20409642230625002 - x38;
    let x41 = x40.sqrt();
    let x44 = x7 + 3.324852225049198;
    let x48 = x44 - 4.005530633326987;
    let x49 = x48.cos();
    let x50 = 0.0567 * x49;
    let x52 = 0.20409642230625002 - x50;
    let x53 = x52.sqrt();
    let x56 = x7 + 5.052728184523584;
    let x60 = x56 - 4.372049776245795;
    let x61 = x60.cos();
    let x62 = 0.0567 * x61;
    let x64 = 0.20409642230625002 - x62;
    let x65 = x64.sqrt();
    let x68 = x7 + 5.419247327442394;
    let x72 = x68 - 6.0999257357201815;
    let x73 = x72.cos();
    let x74 = 0.0567 * x73;
    let x76 = 0.20409642230625002 - x74;
    let x77 = x76.sqrt();
    let x87 = q[3] * q[3];
    let x88 = q[4] * q[4];
    let x89 = q[5] * q[5];
    let x90 = q[6] * q[6];
    let x91 = x87 + x88;
    let x92 = 2.0 * x91;
    let x94 = x92 - 1.0;
    let x98 = x87 + x90;
    let x99 = 2.0 * x98;
    let x100 = x99 - 1.0;
    let x101 = q[4] * q[5];
    let x102 = 2.0 * x101;
    let x103 = q[3] * q[6];
    let x105 = 2.0 * x103;
    let x108 = q[4] * q[6];
    let x109 = 2.0 * x108;
    let x110 = q[3] * q[5];
    let x111 = 2.0 * x110;
    let x112 = x109 + x111;
    let x113 = x102 + x105;
    let x114 = q[5] * q[6];
    let x115 = 2.0 * x114;
    let x116 = q[3] * q[4];
    let x118 = 2.0 * x116;
    let x120 = x115 - x118;
    let x123 = x109 - x111;
    let x130 = x94 * 0.06819204507466928;
    let x132 = x112 * 0.07984262638800324;
    let x134 = x130 - x132;
    let x135 = x113 * 0.06819204507466928;
    let x136 = x120 * 0.07984262638800324;
    let x138 = x135 - x136;
    let x139 = x123 * 0.06819204507466928;
    let x140 = x100 * 0.07984262638800324;
    let x142 = x139 - x140;
    let x143 = q[0] + x134;
    let x144 = q[1] + x138;
    let x145 = q[2] + x142;
    let x147 = x143 - 0.2654788250422678;
    let x149 = x145 + 0.04920359188287982;
    let x150 = x147 * x147;
    let x151 = x144 * x144;
    let x152 = x149 * x149;
    let x153 = x150 + x151;
    let x154 = x152 + x153;
    let x155 = x154.sqrt();
    let x157 = x155 - x17;
    let x162 = x94 * 0.03504972021954594;
    let x164 = x112 * 0.09897735656467874;
    let x166 = x162 - x164;
    let x167 = x113 * 0.03504972021954594;
    let x168 = x120 * 0.09897735656467874;
    let x170 = x167 - x168;
    let x171 = x123 * 0.03504972021954594;
    let x172 = x100 * 0.09897735656467874;
    let x174 = x171 - x172;
    let x175 = q[0] + x166;
    let x176 = q[1] + x170;
    let x177 = q[2] + x174;
    let x179 = x175 + 0.09012785199311818;
    let x181 = x177 + 0.2545132025948882;
    let x182 = x179 * x179;
    let x183 = x176 * x176;
    let x184 = x181 * x181;
    let x185 = x182 + x183;
    let x186 = x184 + x185;
    let x187 = x186.sqrt();
    let x189 = x187 - x29;
    let x195 = x94 * 0.10324176529421522;
    let x198 = x112 * 0.01913473017667551;
    let x200 = x195 + x198;
    let x202 = x113 * 0.10324176529421522;
    let x204 = x120 * 0.01913473017667551;
    let x206 = x202 + x204;
    let x208 = x123 * 0.10324176529421522;
    let x210 = x100 * 0.01913473017667551;
    let x212 = x208 + x210;
    let x214 = q[0] - x200;
    let x215 = q[1] - x206;
    let x216 = q[2] - x212;
    let x218 = x214 + 0.17535097304914957;
    let x220 = x216 + 0.2053096107120084;
    let x221 = x218 * x218;
    let x222 = x215 * x215;
    let x223 = x220 * x220;
    let x224 = x221 + x222;
    let x225 = x223 + x224;
    let x226 = x225.sqrt();
    let x228 = x226 - x41;
    let x234 = x94 * 0.10324176529421523;
    let x236 = x112 * 0.019134730176675482;
    let x237 = x236 - x234;
    let x238 = x113 * 0.10324176529421523;
    let x240 = x120 * 0.019134730176675482;
    let x241 = x240 - x238;
    let x242 = x123 * 0.10324176529421523;
    let x244 = x100 * 0.019134730176675482;
    let x245 = x244 - x242;
    let x246 = q[0] + x237;
    let x247 = q[1] + x241;
    let x248 = q[2] + x245;
    let x250 = x246 + 0.17535097304914954;
    let x252 = x248 - 0.20530961071200843;
    let x253 = x250 * x250;
    let x254 = x247 * x247;
    let x255 = x252 * x252;
    let x256 = x253 + x254;
    let x257 = x255 + x256;
    let x258 = x257.sqrt();
    let x260 = x258 - x53;
    let x262 = x162 + x164;
    let x263 = x167 + x168;
    let x264 = x171 + x172;
    let x265 = q[0] + x262;
    let x266 = q[1] + x263;
    let x267 = q[2] + x264;
    let x269 = x265 + 0.09012785199311824;
    let x270 = x267 - 0.2545132025948882;
    let x271 = x269 * x269;
    let x272 = x266 * x266;
    let x273 = x270 * x270;
    let x274 = x271 + x272;
    let x275 = x273 + x274;
    let x276 = x275.sqrt();
    let x278 = x276 - x65;
    let x283 = x94 * 0.0681920450746693;
    let x284 = x112 * 0.07984262638800323;
    let x285 = x283 + x284;
    let x286 = x113 * 0.0681920450746693;
    let x287 = x120 * 0.07984262638800323;
    let x288 = x286 + x287;
    let x289 = x123 * 0.0681920450746693;
    let x290 = x100 * 0.07984262638800323;
    let x291 = x289 + x290;
    let x292 = q[0] + x285;
    let x293 = q[1] + x288;
    let x294 = q[2] + x291;
    let x296 = x292 - 0.2654788250422677;
    let x298 = x294 - 0.04920359188287992;
    let x299 = x296 * x296;
    let x300 = x293 * x293;
    let x301 = x298 * x298;
    let x302 = x299 + x300;
    let x303 = x301 + x302;
    let x304 = x303.sqrt();
    let x306 = x304 - x77;
    let x307 = x89 + x91;
    let x308 = x90 + x307;
    let x309 = x308 - 1.0;
    out[0] = x157;
    out[1] = x189;
    out[2] = x228;
    out[3] = x260;
    out[4] = x278;
    out[5] = x306;
    out[6] = x309;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 46] = out.try_into().expect("out must have 46 entries");
    let _ = t;
    phi_q_part_0(q, out);
}
#[inline(never)]
fn phi_q_part_0(q: &[f64; 7], out: &mut [f64; 46]) {
    let x87 = q[3] * q[3];
    let x88 = q[4] * q[4];
    let x90 = q[6] * q[6];
    let x91 = x87 + x88;
    let x92 = 2.0 * x91;
    let x94 = x92 - 1.0;
    let x98 = x87 + x90;
    let x99 = 2.0 * x98;
    let x100 = x99 - 1.0;
    let x101 = q[4] * q[5];
    let x102 = 2.0 * x101;
    let x103 = q[3] * q[6];
    let x105 = 2.0 * x103;
    let x108 = q[4] * q[6];
    let x109 = 2.0 * x108;
    let x110 = q[3] * q[5];
    let x111 = 2.0 * x110;
    let x112 = x109 + x111;
    let x113 = x102 + x105;
    let x114 = q[5] * q[6];
    let x115 = 2.0 * x114;
    let x116 = q[3] * q[4];
    let x118 = 2.0 * x116;
    let x120 = x115 - x118;
    let x123 = x109 - x111;
    let x130 = x94 * 0.06819204507466928;
    let x132 = x112 * 0.07984262638800324;
    let x134 = x130 - x132;
    let x135 = x113 * 0.06819204507466928;
    let x136 = x120 * 0.07984262638800324;
    let x138 = x135 - x136;
    let x139 = x123 * 0.06819204507466928;
    let x140 = x100 * 0.07984262638800324;
    let x142 = x139 - x140;
    let x143 = q[0] + x134;
    let x144 = q[1] + x138;
    let x145 = q[2] + x142;
    let x147 = x143 - 0.2654788250422678;
    let x149 = x145 + 0.04920359188287982;
    let x150 = x147 * x147;
    let x151 = x144 * x144;
    let x152 = x149 * x149;
    let x153 = x150 + x151;
    let x154 = x152 + x153;
    let x155 = x154.sqrt();
    let x162 = x94 * 0.03504972021954594;
    let x164 = x112 * 0.09897735656467874;
    let x166 = x162 - x164;
    let x167 = x113 * 0.03504972021954594;
    let x168 = x120 * 0.09897735656467874;
    let x170 = x167 - x168;
    let x171 = x123 * 0.03504972021954594;
    let x172 = x100 * 0.09897735656467874;
    let x174 = x171 - x172;
    let x175 = q[0] + x166;
    let x176 = q[1] + x170;
    let x177 = q[2] + x174;
    let x179 = x175 + 0.09012785199311818;
    let x181 = x177 + 0.2545132025948882;
    let x182 = x179 * x179;
    let x183 = x176 * x176;
    let x184 = x181 * x181;
    let x185 = x182 + x183;
    let x186 = x184 + x185;
    let x187 = x186.sqrt();
    let x195 = x94 * 0.10324176529421522;
    let x198 = x112 * 0.01913473017667551;
    let x200 = x195 + x198;
    let x202 = x113 * 0.10324176529421522;
    let x204 = x120 * 0.01913473017667551;
    let x206 = x202 + x204;
    let x208 = x123 * 0.10324176529421522;
    let x210 = x100 * 0.01913473017667551;
    let x212 = x208 + x210;
    let x214 = q[0] - x200;
    let x215 = q[1] - x206;
    let x216 = q[2] - x212;
    let x218 = x214 + 0.17535097304914957;
    let x220 = x216 + 0.2053096107120084;
    let x221 = x218 * x218;
    let x222 = x215 * x215;
    let x223 = x220 * x220;
    let x224 = x221 + x222;
    let x225 = x223 + x224;
    let x226 = x225.sqrt();
    let x234 = x94 * 0.10324176529421523;
    let x236 = x112 * 0.019134730176675482;
    let x237 = x236 - x234;
    let x238 = x113 * 0.10324176529421523;
    let x240 = x120 * 0.019134730176675482;
    let x241 = x240 - x238;
    let x242 = x123 * 0.10324176529421523;
    let x244 = x100 * 0.019134730176675482;
    let x245 = x244 - x242;
    let x246 = q[0] + x237;
    let x247 = q[1] + x241;
    let x248 = q[2] + x245;
    let x250 = x246 + 0.17535097304914954;
    let x252 = x248 - 0.20530961071200843;
    let x253 = x250 * x250;
    let x254 = x247 * x247;
    let x255 = x252 * x252;
    let x256 = x253 + x254;
    let x257 = x255 + x256;
    let x258 = x257.sqrt();
    let x262 = x162 + x164;
    let x263 = x167 + x168;
    let x264 = x171 + x172;
    let x265 = q[0] + x262;
    let x266 = q[1] + x263;
    let x267 = q[2] + x264;
    let x269 = x265 + 0.09012785199311824;
    let x270 = x267 - 0.2545132025948882;
    let x271 = x269 * x269;
    let x272 = x266 * x266;
    let x273 = x270 * x270;
    let x274 = x271 + x272;
    let x275 = x273 + x274;
    let x276 = x275.sqrt();
    let x283 = x94 * 0.0681920450746693;
    let x284 = x112 * 0.07984262638800323;
    let x285 = x283 + x284;
    let x286 = x113 * 0.0681920450746693;
    let x287 = x120 * 0.07984262638800323;
    let x288 = x286 + x287;
    let x289 = x123 * 0.0681920450746693;
    let x290 = x100 * 0.07984262638800323;
    let x291 = x289 + x290;
    let x292 = q[0] + x285;
    let x293 = q[1] + x288;
    let x294 = q[2] + x291;
    let x296 = x292 - 0.2654788250422677;
    let x298 = x294 - 0.04920359188287992;
    let x299 = x296 * x296;
    let x300 = x293 * x293;
    let x301 = x298 * x298;
    let x302 = x299 + x300;
    let x303 = x301 + x302;
    let x304 = x303.sqrt();
    let x310 = q[3] * 2.0;
    let x311 = q[4] * 2.0;
    let x312 = q[6] * 2.0;
    let x313 = 2.0 * x147;
    let x314 = 2.0 * x144;
    let x315 = 2.0 * x149;
    let x316 = 2.0 * x155;
    let x317 = 1.0 / x316;
    let x318 = x313 * x317;
    let x319 = 2.0 * x179;
    let x320 = 2.0 * x176;
    let x321 = 2.0 * x181;
    let x322 = 2.0 * x187;
    let x323 = 1.0 / x322;
    let x324 = x319 * x323;
    let x325 = 2.0 * x218;
    let x326 = 2.0 * x215;
    let x327 = 2.0 * x220;
    let x328 = 2.0 * x226;
    let x329 = 1.0 / x328;
    let x330 = x325 * x329;
    let x331 = 2.0 * x250;
    let x332 = 2.0 * x247;
    let x333 = 2.0 * x252;
    let x334 = 2.0 * x258;
    let x335 = 1.0 / x334;
    let x336 = x331 * x335;
    let x337 = 2.0 * x269;
    let x338 = 2.0 * x266;
    let x339 = 2.0 * x270;
    let x340 = 2.0 * x276;
    let x341 = 1.0 / x340;
    let x342 = x337 * x341;
    let x343 = 2.0 * x296;
    let x344 = 2.0 * x293;
    let x345 = 2.0 * x298;
    let x346 = 2.0 * x304;
    let x347 = 1.0 / x346;
    let x348 = x343 * x347;
    let x349 = x314 * x317;
    let x350 = x320 * x323;
    let x351 = x326 * x329;
    let x352 = x332 * x335;
    let x353 = x338 * x341;
    let x354 = x344 * x347;
    let x355 = x315 * x317;
    let x356 = x321 * x323;
    let x357 = x327 * x329;
    let x358 = x333 * x335;
    let x359 = x339 * x341;
    let x360 = x345 * x347;
    let x361 = q[5] * 2.0;
    let x362 = 2.0 * x310;
    let x365 = 0.06819204507466928 * x362;
    let x366 = 0.07984262638800324 * x361;
    let x368 = x365 - x366;
    let x369 = 0.06819204507466928 * x312;
    let x370 = 0.07984262638800324 * x311;
    let x372 = x369 + x370;
    let x373 = 0.06819204507466928 * x361;
    let x375 = 0.07984262638800324 * x362;
    let x377 = x373 + x375;
    let x379 = x313 * x368;
    let x380 = x314 * x372;
    let x381 = x315 * x377;
    let x383 = x379 + x380;
    let x384 = x383 - x381;
    let x385 = x317 * x384;
    let x386 = 0.03504972021954594 * x362;
    let x387 = 0.09897735656467874 * x361;
    let x389 = x386 - x387;
    let x390 = 0.03504972021954594 * x312;
    let x391 = 0.09897735656467874 * x311;
    let x393 = x390 + x391;
    let x394 = 0.03504972021954594 * x361;
    let x396 = 0.09897735656467874 * x362;
    let x398 = x394 + x396;
    let x400 = x319 * x389;
    let x401 = x320 * x393;
    let x402 = x321 * x398;
    let x404 = x400 + x401;
    let x405 = x404 - x402;
    let x406 = x323 * x405;
    let x407 = 0.10324176529421522 * x362;
    let x408 = 0.01913473017667551 * x361;
    let x409 = x407 + x408;
    let x411 = 0.10324176529421522 * x312;
    let x412 = 0.01913473017667551 * x311;
    let x414 = x411 - x412;
    let x416 = 0.10324176529421522 * x361;
    let x418 = 0.01913473017667551 * x362;
    let x419 = x418 - x416;
    let x421 = x325 * x409;
    let x423 = x326 * x414;
    let x425 = x327 * x419;
    let x427 = x421 + x423;
    let x429 = x425 + x427;
    let x431 = x329 * x429;
    let x432 = -x431;
    let x433 = 0.10324176529421523 * x362;
    let x435 = 0.019134730176675482 * x361;
    let x436 = x435 - x433;
    let x437 = 0.10324176529421523 * x312;
    let x439 = 0.019134730176675482 * x311;
    let x441 = x437 + x439;
    let x443 = 0.10324176529421523 * x361;
    let x445 = 0.019134730176675482 * x362;
    let x446 = x443 + x445;
    let x447 = x331 * x436;
    let x448 = x332 * x441;
    let x450 = x333 * x446;
    let x451 = x447 - x448;
    let x452 = x450 + x451;
    let x453 = x335 * x452;
    let x454 = x386 + x387;
    let x455 = x390 - x391;
    let x456 = x396 - x394;
    let x457 = x337 * x454;
    let x458 = x338 * x455;
    let x459 = x339 * x456;
    let x460 = x457 + x458;
    let x461 = x459 + x460;
    let x462 = x341 * x461;
    let x463 = 0.0681920450746693 * x362;
    let x464 = 0.07984262638800323 * x361;
    let x465 = x463 + x464;
    let x466 = 0.0681920450746693 * x312;
    let x467 = 0.07984262638800323 * x311;
    let x469 = x466 - x467;
    let x470 = 0.0681920450746693 * x361;
    let x472 = 0.07984262638800323 * x362;
    let x473 = x472 - x470;
    let x474 = x343 * x465;
    let x475 = x344 * x469;
    let x476 = x345 * x473;
    let x477 = x474 + x475;
    let x478 = x476 + x477;
    let x479 = x347 * x478;
    let x480 = 2.0 * x311;
    let x482 = 0.06819204507466928 * x480;
    let x483 = 0.07984262638800324 * x312;
    let x485 = x482 - x483;
    let x486 = 0.07984262638800324 * x310;
    let x488 = x373 + x486;
    let x489 = x313 * x485;
    let x490 = x314 * x488;
    let x491 = x315 * x369;
    let x492 = x489 + x490;
    let x493 = x491 + x492;
    let x494 = x317 * x493;
    let x495 = 0.03504972021954594 * x480;
    let x496 = 0.09897735656467874 * x312;
    let x498 = x495 - x496;
    let x499 = 0.09897735656467874 * x310;
    let x501 = x394 + x499;
    let x502 = x319 * x498;
    let x503 = x320 * x501;
    let x504 = x321 * x390;
    let x505 = x502 + x503;
    let x506 = x504 + x505;
    let x507 = x323 * x506;
    let x508 = 0.10324176529421522 * x480;
    let x509 = 0.01913473017667551 * x312;
    let x510 = x508 + x509;
    let x512 = 0.01913473017667551 * x310;
    let x514 = x416 - x512;
    let x517 = x325 * x510;
    let x519 = x326 * x514;
    let x521 = x327 * x411;
    let x523 = x517 + x519;
    let x525 = x521 + x523;
    let x527 = x329 * x525;
    let x528 = -x527;
    let x529 = 0.10324176529421523 * x480;
    let x531 = 0.019134730176675482 * x312;
    let x532 = x531 - x529;
    let x533 = 0.019134730176675482 * x310;
    let x535 = x443 + x533;
    let x537 = x331 * x532;
    let x538 = x332 * x535;
    let x540 = x333 * x437;
    let x542 = x537 - x538;
    let x543 = x542 - x540;
    let x544 = x335 * x543;
    let x545 = x495 + x496;
    let x546 = x394 - x499;
    let x547 = x337 * x545;
    let x548 = x338 * x546;
    let x549 = x339 * x390;
    let x550 = x547 + x548;
    let x551 = x549 + x550;
    let x552 = x341 * x551;
    let x553 = 0.0681920450746693 * x480;
    let x554 = 0.07984262638800323 * x312;
    let x555 = x553 + x554;
    let x556 = 0.07984262638800323 * x310;
    let x558 = x470 - x556;
    let x559 = x343 * x555;
    let x560 = x344 * x558;
    let x561 = x345 * x466;
    let x562 = x559 + x560;
    let x563 = x561 + x562;
    let x564 = x347 * x563;
    let x565 = 0.06819204507466928 * x311;
    let x566 = x565 - x483;
    let x567 = 0.06819204507466928 * x310;
    let x569 = x313 * x486;
    let x571 = x314 * x566;
    let x572 = x315 * x567;
    let x574 = x571 - x569;
    let x575 = x574 - x572;
    let x576 = x317 * x575;
    let x577 = 0.03504972021954594 * x311;
    let x578 = x577 - x496;
    let x579 = 0.03504972021954594 * x310;
    let x581 = x319 * x499;
    let x583 = x320 * x578;
    let x584 = x321 * x579;
    let x586 = x583 - x581;
    let x587 = x586 - x584;
    let x588 = x323 * x587;
    let x589 = 0.10324176529421522 * x311;
    let x590 = x509 + x589;
    let x592 = 0.10324176529421522 * x310;
    let x594 = x325 * x512;
    let x596 = x326 * x590;
    let x598 = x327 * x592;
    let x599 = x594 + x596;
    let x601 = x598 - x599;
    let x602 = x329 * x601;
    let x603 = 0.10324176529421523 * x311;
    let x605 = x531 - x603;
    let x606 = 0.10324176529421523 * x310;
    let x608 = x331 * x533;
    let x609 = x332 * x605;
    let x610 = x333 * x606;
    let x611 = x608 + x609;
    let x612 = x610 + x611;
    let x613 = x335 * x612;
    let x614 = x496 + x577;
    let x615 = x337 * x499;
    let x616 = x338 * x614;
    let x617 = x339 * x579;
    let x619 = x615 + x616;
    let x620 = x619 - x617;
    let x621 = x341 * x620;
    let x622 = 0.0681920450746693 * x311;
    let x623 = x554 + x622;
    let x624 = 0.0681920450746693 * x310;
    let x626 = x343 * x556;
    let x627 = x344 * x623;
    let x628 = x345 * x624;
    let x630 = x626 + x627;
    let x631 = x630 - x628;
    let x632 = x347 * x631;
    let x633 = 2.0 * x312;
    let x634 = x567 - x366;
    let x635 = 0.07984262638800324 * x633;
    let x637 = x565 - x635;
    let x638 = x313 * x370;
    let x640 = x314 * x634;
    let x641 = x315 * x637;
    let x642 = x640 - x638;
    let x643 = x641 + x642;
    let x644 = x317 * x643;
    let x645 = x579 - x387;
    let x646 = 0.09897735656467874 * x633;
    let x648 = x577 - x646;
    let x649 = x319 * x391;
    let x651 = x320 * x645;
    let x652 = x321 * x648;
    let x653 = x651 - x649;
    let x654 = x652 + x653;
    let x655 = x323 * x654;
    let x656 = x408 + x592;
    let x658 = 0.01913473017667551 * x633;
    let x659 = x589 + x658;
    let x661 = x325 * x412;
    let x663 = x326 * x656;
    let x665 = x327 * x659;
    let x667 = x661 + x663;
    let x669 = x665 + x667;
    let x671 = x329 * x669;
    let x672 = -x671;
    let x673 = x435 - x606;
    let x674 = 0.019134730176675482 * x633;
    let x675 = x674 - x603;
    let x676 = x331 * x439;
    let x677 = x332 * x673;
    let x678 = x333 * x675;
    let x679 = x676 + x677;
    let x680 = x678 + x679;
    let x681 = x335 * x680;
    let x682 = x387 + x579;
    let x683 = x577 + x646;
    let x684 = x337 * x391;
    let x685 = x338 * x682;
    let x686 = x339 * x683;
    let x687 = x684 + x685;
    let x688 = x686 + x687;
    let x689 = x341 * x688;
    let x690 = x464 + x624;
    let x691 = 0.07984262638800323 * x633;
    let x692 = x622 + x691;
    let x693 = x343 * x467;
    let x694 = x344 * x690;
    let x695 = x345 * x692;
    let x696 = x693 + x694;
    let x697 = x695 + x696;
    let x698 = x347 * x697;
    out[0] = x318;
    out[1] = x349;
    out[2] = x355;
    out[3] = x385;
    out[4] = x494;
    out[5] = x576;
    out[6] = x644;
    out[7] = x324;
    out[8] = x350;
    out[9] = x356;
    out[10] = x406;
    out[11] = x507;
    out[12] = x588;
    out[13] = x655;
    out[14] = x330;
    out[15] = x351;
    out[16] = x357;
    out[17] = x432;
    out[18] = x528;
    out[19] = x602;
    out[20] = x672;
    out[21] = x336;
    out[22] = x352;
    out[23] = x358;
    out[24] = x453;
    out[25] = x544;
    out[26] = x613;
    out[27] = x681;
    out[28] = x342;
    out[29] = x353;
    out[30] = x359;
    out[31] = x462;
    out[32] = x552;
    out[33] = x621;
    out[34] = x689;
    out[35] = x348;
    out[36] = x354;
    out[37] = x360;
    out[38] = x479;
    out[39] = x564;
    out[40] = x632;
    out[41] = x698;
    out[42] = x310;
    out[43] = x311;
    out[44] = x361;
    out[45] = x312;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
    let _ = q;
    phi_t_part_0(t, out);
}
#[inline(never)]
fn phi_t_part_0(t: f64, out: &mut [f64; 7]) {
    let x7 = 0.8726646259971648 * t;
    let x8 = 0.8639379797371931 + x7;
    let x12 = x8 - 0.1832595714594046;
    let x13 = x12.cos();
    let x14 = 0.0567 * x13;
    let x16 = 0.20409642230625002 - x14;
    let x17 = x16.sqrt();
    let x20 = x7 + 1.2304571226560024;
    let x24 = x20 - 1.911135530933791;
    let x25 = x24.cos();
    let x26 = 0.0567 * x25;
    let x28 = 0.20409642230625002 - x26;
    let x29 = x28.sqrt();
    let x32 = x7 + 2.9583330821303884;
    let x36 = x32 - 2.2776546738526;
    let x37 = x36.cos();
    let x38 = 0.0567 * x37;
    let x40 = 0.20409642230625002 - x38;
    let x41 = x40.sqrt();
    let x44 = x7 + 3.324852225049198;
    let x48 = x44 - 4.005530633326987;
    let x49 = x48.cos();
    let x50 = 0.0567 * x49;
    let x52 = 0.20409642230625002 - x50;
    let x53 = x52.sqrt();
    let x56 = x7 + 5.052728184523584;
    let x60 = x56 - 4.372049776245795;
    let x61 = x60.cos();
    let x62 = 0.0567 * x61;
    let x64 = 0.20409642230625002 - x62;
    let x65 = x64.sqrt();
    let x68 = x7 + 5.419247327442394;
    let x72 = x68 - 6.0999257357201815;
    let x73 = x72.cos();
    let x74 = 0.0567 * x73;
    let x76 = 0.20409642230625002 - x74;
    let x77 = x76.sqrt();
    let x699 = x12.sin();
    let x701 = 0.8726646259971648 * x699;
    let x703 = 0.0567 * x701;
    let x705 = x17 * 2.0;
    let x706 = 1.0 / x705;
    let x707 = x703 * x706;
    let x708 = x24.sin();
    let x710 = 0.8726646259971648 * x708;
    let x712 = 0.0567 * x710;
    let x714 = x29 * 2.0;
    let x715 = 1.0 / x714;
    let x716 = x712 * x715;
    let x717 = x36.sin();
    let x719 = 0.8726646259971648 * x717;
    let x721 = 0.0567 * x719;
    let x723 = x41 * 2.0;
    let x724 = 1.0 / x723;
    let x725 = x721 * x724;
    let x726 = x48.sin();
    let x728 = 0.8726646259971648 * x726;
    let x730 = 0.0567 * x728;
    let x732 = x53 * 2.0;
    let x733 = 1.0 / x732;
    let x734 = x730 * x733;
    let x735 = x60.sin();
    let x737 = 0.8726646259971648 * x735;
    let x739 = 0.0567 * x737;
    let x741 = x65 * 2.0;
    let x742 = 1.0 / x741;
    let x743 = x739 * x742;
    let x744 = x72.sin();
    let x746 = 0.8726646259971648 * x744;
    let x748 = 0.0567 * x746;
    let x750 = x77 * 2.0;
    let x751 = 1.0 / x750;
    let x752 = x748 * x751;
    let x753 = -x707;
    let x754 = -x716;
    let x755 = -x725;
    let x756 = -x734;
    let x757 = -x743;
    let x758 = -x752;
    out[0] = x753;
    out[1] = x754;
    out[2] = x755;
    out[3] = x756;
    out[4] = x757;
    out[5] = x758;
    out[6] = 0.0;
}
/// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
pub fn gamma(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
    let mut s = [0.0f64; 96];
    gamma_shared_0(q, qd, t, &mut s);
    gamma_part_0(q, qd, &s, out);
    gamma_part_1(q, qd, &s, out);
}
#[inline(never)]
fn gamma_shared_0(q: &[f64; 7], qd: &[f64; 7], t: f64, s: &mut [f64; 96]) {
    let x7 = 0.8726646259971648 * t;
    s[0] = x7;
    let x87 = q[3] * q[3];
    s[1] = x87;
    let x88 = q[4] * q[4];
    s[2] = x88;
    let x90 = q[6] * q[6];
    s[3] = x90;
    let x91 = x87 + x88;
    s[4] = x91;
    let x92 = 2.0 * x91;
    s[5] = x92;
    let x94 = x92 - 1.0;
    s[6] = x94;
    let x98 = x87 + x90;
    s[7] = x98;
    let x99 = 2.0 * x98;
    s[8] = x99;
    let x100 = x99 - 1.0;
    s[9] = x100;
    let x101 = q[4] * q[5];
    s[10] = x101;
    let x102 = 2.0 * x101;
    s[11] = x102;
    let x103 = q[3] * q[6];
    s[12] = x103;
    let x105 = 2.0 * x103;
    s[13] = x105;
    let x108 = q[4] * q[6];
    s[14] = x108;
    let x109 = 2.0 * x108;
    s[15] = x109;
    let x110 = q[3] * q[5];
    s[16] = x110;
    let x111 = 2.0 * x110;
    s[17] = x111;
    let x112 = x109 + x111;
    s[18] = x112;
    let x113 = x102 + x105;
    s[19] = x113;
    let x114 = q[5] * q[6];
    s[20] = x114;
    let x115 = 2.0 * x114;
    s[21] = x115;
    let x116 = q[3] * q[4];
    s[22] = x116;
    let x118 = 2.0 * x116;
    s[23] = x118;
    let x120 = x115 - x118;
    s[24] = x120;
    let x123 = x109 - x111;
    s[25] = x123;
    let x310 = q[3] * 2.0;
    s[26] = x310;
    let x311 = q[4] * 2.0;
    s[27] = x311;
    let x312 = q[6] * 2.0;
    s[28] = x312;
    let x766 = x310 * qd[3];
    s[29] = x766;
    let x767 = x311 * qd[4];
    s[30] = x767;
    let x769 = x312 * qd[6];
    s[31] = x769;
    let x770 = x766 + x767;
    s[32] = x770;
    let x771 = 2.0 * x770;
    s[33] = x771;
    let x772 = x766 + x769;
    s[34] = x772;
    let x773 = 2.0 * x772;
    s[35] = x773;
    let x774 = q[5] * qd[4];
    s[36] = x774;
    let x775 = q[4] * qd[5];
    s[37] = x775;
    let x776 = x774 + x775;
    s[38] = x776;
    let x777 = 2.0 * x776;
    s[39] = x777;
    let x778 = q[6] * qd[3];
    s[40] = x778;
    let x779 = q[3] * qd[6];
    s[41] = x779;
    let x780 = x778 + x779;
    s[42] = x780;
    let x781 = 2.0 * x780;
    s[43] = x781;
    let x782 = q[6] * qd[4];
    s[44] = x782;
    let x783 = q[4] * qd[6];
    s[45] = x783;
    let x784 = x782 + x783;
    s[46] = x784;
    let x785 = 2.0 * x784;
    s[47] = x785;
    let x786 = q[5] * qd[3];
    s[48] = x786;
    let x787 = q[3] * qd[5];
    s[49] = x787;
    let x788 = x786 + x787;
    s[50] = x788;
    let x789 = 2.0 * x788;
    s[51] = x789;
    let x790 = x785 + x789;
    s[52] = x790;
    let x791 = x777 + x781;
    s[53] = x791;
    let x792 = q[6] * qd[5];
    s[54] = x792;
    let x793 = q[5] * qd[6];
    s[55] = x793;
    let x794 = x792 + x793;
    s[56] = x794;
    let x795 = 2.0 * x794;
    s[57] = x795;
    let x796 = q[4] * qd[3];
    s[58] = x796;
    let x797 = q[3] * qd[4];
    s[59] = x797;
    let x798 = x796 + x797;
    s[60] = x798;
    let x799 = 2.0 * x798;
    s[61] = x799;
    let x801 = x795 - x799;
    s[62] = x801;
    let x803 = x785 - x789;
    s[63] = x803;
    let x926 = 2.0 * qd[3];
    s[64] = x926;
    let x927 = 2.0 * qd[4];
    s[65] = x927;
    let x928 = 2.0 * qd[6];
    s[66] = x928;
    let x1044 = qd[3] * x926;
    s[67] = x1044;
    let x1045 = qd[4] * x927;
    s[68] = x1045;
    let x1047 = qd[6] * x928;
    s[69] = x1047;
    let x1048 = x1044 + x1045;
    s[70] = x1048;
    let x1049 = 2.0 * x1048;
    s[71] = x1049;
    let x1050 = x1044 + x1047;
    s[72] = x1050;
    let x1051 = 2.0 * x1050;
    s[73] = x1051;
    let x1052 = qd[4] * qd[5];
    s[74] = x1052;
    let x1053 = x1052 + x1052;
    s[75] = x1053;
    let x1054 = 2.0 * x1053;
    s[76] = x1054;
    let x1055 = qd[3] * qd[6];
    s[77] = x1055;
    let x1056 = x1055 + x1055;
    s[78] = x1056;
    let x1057 = 2.0 * x1056;
    s[79] = x1057;
    let x1058 = qd[4] * qd[6];
    s[80] = x1058;
    let x1059 = x1058 + x1058;
    s[81] = x1059;
    let x1060 = 2.0 * x1059;
    s[82] = x1060;
    let x1061 = qd[3] * qd[5];
    s[83] = x1061;
    let x1062 = x1061 + x1061;
    s[84] = x1062;
    let x1063 = 2.0 * x1062;
    s[85] = x1063;
    let x1064 = x1060 + x1063;
    s[86] = x1064;
    let x1065 = x1054 + x1057;
    s[87] = x1065;
    let x1066 = qd[5] * qd[6];
    s[88] = x1066;
    let x1067 = x1066 + x1066;
    s[89] = x1067;
    let x1068 = 2.0 * x1067;
    s[90] = x1068;
    let x1069 = qd[3] * qd[4];
    s[91] = x1069;
    let x1070 = x1069 + x1069;
    s[92] = x1070;
    let x1071 = 2.0 * x1070;
    s[93] = x1071;
    let x1073 = x1068 - x1071;
    s[94] = x1073;
    let x1075 = x1060 - x1063;
    s[95] = x1075;
}
#[inline(never)]
fn gamma_part_0(q: &[f64; 7], qd: &[f64; 7], s: &[f64; 96], out: &mut [f64; 7]) {
    let x8 = 0.8639379797371931 + s[0];
    let x12 = x8 - 0.1832595714594046;
    let x13 = x12.cos();
    let x14 = 0.0567 * x13;
    let x16 = 0.20409642230625002 - x14;
    let x17 = x16.sqrt();
    let x20 = s[0] + 1.2304571226560024;
    let x24 = x20 - 1.911135530933791;
    let x25 = x24.cos();
    let x26 = 0.0567 * x25;
    let x28 = 0.20409642230625002 - x26;
    let x29 = x28.sqrt();
    let x32 = s[0] + 2.9583330821303884;
    let x36 = x32 - 2.2776546738526;
    let x37 = x36.cos();
    let x38 = 0.0567 * x37;
    let x40 = 0.20409642230625002 - x38;
    let x41 = x40.sqrt();
    let x44 = s[0] + 3.324852225049198;
    let x48 = x44 - 4.005530633326987;
    let x49 = x48.cos();
    let x50 = 0.0567 * x49;
    let x52 = 0.20409642230625002 - x50;
    let x53 = x52.sqrt();
    let x56 = s[0] + 5.052728184523584;
    let x60 = x56 - 4.372049776245795;
    let x61 = x60.cos();
    let x62 = 0.0567 * x61;
    let x64 = 0.20409642230625002 - x62;
    let x65 = x64.sqrt();
    let x130 = s[6] * 0.06819204507466928;
    let x132 = s[18] * 0.07984262638800324;
    let x134 = x130 - x132;
    let x135 = s[19] * 0.06819204507466928;
    let x136 = s[24] * 0.07984262638800324;
    let x138 = x135 - x136;
    let x139 = s[25] * 0.06819204507466928;
    let x140 = s[9] * 0.07984262638800324;
    let x142 = x139 - x140;
    let x143 = q[0] + x134;
    let x144 = q[1] + x138;
    let x145 = q[2] + x142;
    let x147 = x143 - 0.2654788250422678;
    let x149 = x145 + 0.04920359188287982;
    let x150 = x147 * x147;
    let x151 = x144 * x144;
    let x152 = x149 * x149;
    let x153 = x150 + x151;
    let x154 = x152 + x153;
    let x155 = x154.sqrt();
    let x162 = s[6] * 0.03504972021954594;
    let x164 = s[18] * 0.09897735656467874;
    let x166 = x162 - x164;
    let x167 = s[19] * 0.03504972021954594;
    let x168 = s[24] * 0.09897735656467874;
    let x170 = x167 - x168;
    let x171 = s[25] * 0.03504972021954594;
    let x172 = s[9] * 0.09897735656467874;
    let x174 = x171 - x172;
    let x175 = q[0] + x166;
    let x176 = q[1] + x170;
    let x177 = q[2] + x174;
    let x179 = x175 + 0.09012785199311818;
    let x181 = x177 + 0.2545132025948882;
    let x182 = x179 * x179;
    let x183 = x176 * x176;
    let x184 = x181 * x181;
    let x185 = x182 + x183;
    let x186 = x184 + x185;
    let x187 = x186.sqrt();
    let x195 = s[6] * 0.10324176529421522;
    let x198 = s[18] * 0.01913473017667551;
    let x200 = x195 + x198;
    let x202 = s[19] * 0.10324176529421522;
    let x204 = s[24] * 0.01913473017667551;
    let x206 = x202 + x204;
    let x208 = s[25] * 0.10324176529421522;
    let x210 = s[9] * 0.01913473017667551;
    let x212 = x208 + x210;
    let x214 = q[0] - x200;
    let x215 = q[1] - x206;
    let x216 = q[2] - x212;
    let x218 = x214 + 0.17535097304914957;
    let x220 = x216 + 0.2053096107120084;
    let x221 = x218 * x218;
    let x222 = x215 * x215;
    let x223 = x220 * x220;
    let x224 = x221 + x222;
    let x225 = x223 + x224;
    let x226 = x225.sqrt();
    let x234 = s[6] * 0.10324176529421523;
    let x236 = s[18] * 0.019134730176675482;
    let x237 = x236 - x234;
    let x238 = s[19] * 0.10324176529421523;
    let x240 = s[24] * 0.019134730176675482;
    let x241 = x240 - x238;
    let x242 = s[25] * 0.10324176529421523;
    let x244 = s[9] * 0.019134730176675482;
    let x245 = x244 - x242;
    let x246 = q[0] + x237;
    let x247 = q[1] + x241;
    let x248 = q[2] + x245;
    let x250 = x246 + 0.17535097304914954;
    let x252 = x248 - 0.20530961071200843;
    let x253 = x250 * x250;
    let x254 = x247 * x247;
    let x255 = x252 * x252;
    let x256 = x253 + x254;
    let x257 = x255 + x256;
    let x258 = x257.sqrt();
    let x262 = x162 + x164;
    let x263 = x167 + x168;
    let x264 = x171 + x172;
    let x265 = q[0] + x262;
    let x266 = q[1] + x263;
    let x267 = q[2] + x264;
    let x269 = x265 + 0.09012785199311824;
    let x270 = x267 - 0.2545132025948882;
    let x271 = x269 * x269;
    let x272 = x266 * x266;
    let x273 = x270 * x270;
    let x274 = x271 + x272;
    let x275 = x273 + x274;
    let x276 = x275.sqrt();
    let x313 = 2.0 * x147;
    let x314 = 2.0 * x144;
    let x315 = 2.0 * x149;
    let x316 = 2.0 * x155;
    let x317 = 1.0 / x316;
    let x319 = 2.0 * x179;
    let x320 = 2.0 * x176;
    let x321 = 2.0 * x181;
    let x322 = 2.0 * x187;
    let x323 = 1.0 / x322;
    let x325 = 2.0 * x218;
    let x326 = 2.0 * x215;
    let x327 = 2.0 * x220;
    let x328 = 2.0 * x226;
    let x329 = 1.0 / x328;
    let x331 = 2.0 * x250;
    let x332 = 2.0 * x247;
    let x333 = 2.0 * x252;
    let x334 = 2.0 * x258;
    let x335 = 1.0 / x334;
    let x337 = 2.0 * x269;
    let x338 = 2.0 * x266;
    let x339 = 2.0 * x270;
    let x340 = 2.0 * x276;
    let x341 = 1.0 / x340;
    let x699 = x12.sin();
    let x701 = 0.8726646259971648 * x699;
    let x703 = 0.0567 * x701;
    let x705 = x17 * 2.0;
    let x706 = 1.0 / x705;
    let x707 = x703 * x706;
    let x708 = x24.sin();
    let x710 = 0.8726646259971648 * x708;
    let x712 = 0.0567 * x710;
    let x714 = x29 * 2.0;
    let x715 = 1.0 / x714;
    let x716 = x712 * x715;
    let x717 = x36.sin();
    let x719 = 0.8726646259971648 * x717;
    let x721 = 0.0567 * x719;
    let x723 = x41 * 2.0;
    let x724 = 1.0 / x723;
    let x725 = x721 * x724;
    let x726 = x48.sin();
    let x728 = 0.8726646259971648 * x726;
    let x730 = 0.0567 * x728;
    let x732 = x53 * 2.0;
    let x733 = 1.0 / x732;
    let x734 = x730 * x733;
    let x735 = x60.sin();
    let x737 = 0.8726646259971648 * x735;
    let x739 = 0.0567 * x737;
    let x741 = x65 * 2.0;
    let x742 = 1.0 / x741;
    let x743 = x739 * x742;
    let x804 = 0.06819204507466928 * s[33];
    let x805 = 0.07984262638800324 * s[52];
    let x807 = x804 - x805;
    let x808 = 0.06819204507466928 * s[53];
    let x809 = 0.07984262638800324 * s[62];
    let x811 = x808 - x809;
    let x812 = 0.06819204507466928 * s[63];
    let x813 = 0.07984262638800324 * s[35];
    let x815 = x812 - x813;
    let x816 = qd[0] + x807;
    let x817 = qd[1] + x811;
    let x818 = qd[2] + x815;
    let x819 = x313 * x816;
    let x820 = x314 * x817;
    let x821 = x315 * x818;
    let x822 = x819 + x820;
    let x823 = x821 + x822;
    let x824 = x317 * x823;
    let x826 = 0.03504972021954594 * s[33];
    let x827 = 0.09897735656467874 * s[52];
    let x829 = x826 - x827;
    let x830 = 0.03504972021954594 * s[53];
    let x831 = 0.09897735656467874 * s[62];
    let x833 = x830 - x831;
    let x834 = 0.03504972021954594 * s[63];
    let x835 = 0.09897735656467874 * s[35];
    let x837 = x834 - x835;
    let x838 = qd[0] + x829;
    let x839 = qd[1] + x833;
    let x840 = qd[2] + x837;
    let x841 = x319 * x838;
    let x842 = x320 * x839;
    let x843 = x321 * x840;
    let x844 = x841 + x842;
    let x845 = x843 + x844;
    let x846 = x323 * x845;
    let x848 = 0.10324176529421522 * s[33];
    let x849 = 0.01913473017667551 * s[52];
    let x850 = x848 + x849;
    let x852 = 0.10324176529421522 * s[53];
    let x853 = 0.01913473017667551 * s[62];
    let x854 = x852 + x853;
    let x856 = 0.10324176529421522 * s[63];
    let x857 = 0.01913473017667551 * s[35];
    let x858 = x856 + x857;
    let x860 = qd[0] - x850;
    let x861 = qd[1] - x854;
    let x862 = qd[2] - x858;
    let x863 = x325 * x860;
    let x864 = x326 * x861;
    let x865 = x327 * x862;
    let x866 = x863 + x864;
    let x867 = x865 + x866;
    let x868 = x329 * x867;
    let x870 = 0.10324176529421523 * s[33];
    let x872 = 0.019134730176675482 * s[52];
    let x873 = x872 - x870;
    let x874 = 0.10324176529421523 * s[53];
    let x876 = 0.019134730176675482 * s[62];
    let x877 = x876 - x874;
    let x878 = 0.10324176529421523 * s[63];
    let x880 = 0.019134730176675482 * s[35];
    let x881 = x880 - x878;
    let x882 = qd[0] + x873;
    let x883 = qd[1] + x877;
    let x884 = qd[2] + x881;
    let x885 = x331 * x882;
    let x886 = x332 * x883;
    let x887 = x333 * x884;
    let x888 = x885 + x886;
    let x889 = x887 + x888;
    let x890 = x335 * x889;
    let x892 = x826 + x827;
    let x893 = x830 + x831;
    let x894 = x834 + x835;
    let x895 = qd[0] + x892;
    let x896 = qd[1] + x893;
    let x897 = qd[2] + x894;
    let x898 = x337 * x895;
    let x899 = x338 * x896;
    let x900 = x339 * x897;
    let x901 = x898 + x899;
    let x902 = x900 + x901;
    let x903 = x341 * x902;
    let x929 = 2.0 * x816;
    let x930 = 2.0 * x817;
    let x931 = 2.0 * x818;
    let x932 = 2.0 * x824;
    let x933 = x317 * x317;
    let x934 = x932 * x933;
    let x936 = 2.0 * x838;
    let x937 = 2.0 * x839;
    let x938 = 2.0 * x840;
    let x939 = 2.0 * x846;
    let x940 = x323 * x323;
    let x941 = x939 * x940;
    let x943 = 2.0 * x860;
    let x944 = 2.0 * x861;
    let x945 = 2.0 * x862;
    let x946 = 2.0 * x868;
    let x947 = x329 * x329;
    let x948 = x946 * x947;
    let x950 = 2.0 * x882;
    let x951 = 2.0 * x883;
    let x952 = 2.0 * x884;
    let x953 = 2.0 * x890;
    let x954 = x335 * x335;
    let x955 = x953 * x954;
    let x957 = 2.0 * x895;
    let x958 = 2.0 * x896;
    let x959 = 2.0 * x897;
    let x960 = 2.0 * x903;
    let x961 = x341 * x341;
    let x962 = x960 * x961;
    let x972 = 0.8726646259971648 * x13;
    let x973 = 0.8726646259971648 * x972;
    let x974 = 0.0567 * x973;
    let x975 = 2.0 * x707;
    let x976 = x706 * x706;
    let x977 = x975 * x976;
    let x979 = x706 * x974;
    let x980 = x703 * x977;
    let x982 = x979 - x980;
    let x983 = 0.8726646259971648 * x25;
    let x984 = 0.8726646259971648 * x983;
    let x985 = 0.0567 * x984;
    let x986 = 2.0 * x716;
    let x987 = x715 * x715;
    let x988 = x986 * x987;
    let x990 = x715 * x985;
    let x991 = x712 * x988;
    let x993 = x990 - x991;
    let x994 = 0.8726646259971648 * x37;
    let x995 = 0.8726646259971648 * x994;
    let x996 = 0.0567 * x995;
    let x997 = 2.0 * x725;
    let x998 = x724 * x724;
    let x999 = x997 * x998;
    let x1001 = x724 * x996;
    let x1002 = x721 * x999;
    let x1004 = x1001 - x1002;
    let x1005 = 0.8726646259971648 * x49;
    let x1006 = 0.8726646259971648 * x1005;
    let x1007 = 0.0567 * x1006;
    let x1008 = 2.0 * x734;
    let x1009 = x733 * x733;
    let x1010 = x1008 * x1009;
    let x1012 = x733 * x1007;
    let x1013 = x730 * x1010;
    let x1015 = x1012 - x1013;
    let x1016 = 0.8726646259971648 * x61;
    let x1017 = 0.8726646259971648 * x1016;
    let x1018 = 0.0567 * x1017;
    let x1019 = 2.0 * x743;
    let x1020 = x742 * x742;
    let x1021 = x1019 * x1020;
    let x1023 = x742 * x1018;
    let x1024 = x739 * x1021;
    let x1026 = x1023 - x1024;
    let x1076 = 0.06819204507466928 * s[71];
    let x1077 = 0.07984262638800324 * s[86];
    let x1079 = x1076 - x1077;
    let x1080 = 0.06819204507466928 * s[87];
    let x1081 = 0.07984262638800324 * s[94];
    let x1083 = x1080 - x1081;
    let x1084 = 0.06819204507466928 * s[95];
    let x1085 = 0.07984262638800324 * s[73];
    let x1087 = x1084 - x1085;
    let x1088 = x816 * x929;
    let x1089 = x313 * x1079;
    let x1090 = x1088 + x1089;
    let x1091 = x817 * x930;
    let x1092 = x314 * x1083;
    let x1093 = x1091 + x1092;
    let x1094 = x818 * x931;
    let x1095 = x315 * x1087;
    let x1096 = x1094 + x1095;
    let x1097 = x1090 + x1093;
    let x1098 = x1096 + x1097;
    let x1099 = x823 * x934;
    let x1101 = x317 * x1098;
    let x1102 = x1101 - x1099;
    let x1103 = x1102 - x982;
    let x1104 = 0.03504972021954594 * s[71];
    let x1105 = 0.09897735656467874 * s[86];
    let x1107 = x1104 - x1105;
    let x1108 = 0.03504972021954594 * s[87];
    let x1109 = 0.09897735656467874 * s[94];
    let x1111 = x1108 - x1109;
    let x1112 = 0.03504972021954594 * s[95];
    let x1113 = 0.09897735656467874 * s[73];
    let x1115 = x1112 - x1113;
    let x1116 = x838 * x936;
    let x1117 = x319 * x1107;
    let x1118 = x1116 + x1117;
    let x1119 = x839 * x937;
    let x1120 = x320 * x1111;
    let x1121 = x1119 + x1120;
    let x1122 = x840 * x938;
    let x1123 = x321 * x1115;
    let x1124 = x1122 + x1123;
    let x1125 = x1118 + x1121;
    let x1126 = x1124 + x1125;
    let x1127 = x845 * x941;
    let x1129 = x323 * x1126;
    let x1130 = x1129 - x1127;
    let x1131 = x1130 - x993;
    let x1132 = 0.10324176529421522 * s[71];
    let x1133 = 0.01913473017667551 * s[86];
    let x1134 = x1132 + x1133;
    let x1136 = 0.10324176529421522 * s[87];
    let x1137 = 0.01913473017667551 * s[94];
    let x1138 = x1136 + x1137;
    let x1140 = 0.10324176529421522 * s[95];
    let x1141 = 0.01913473017667551 * s[73];
    let x1142 = x1140 + x1141;
    let x1144 = x860 * x943;
    let x1145 = x325 * x1134;
    let x1147 = x1144 - x1145;
    let x1148 = x861 * x944;
    let x1149 = x326 * x1138;
    let x1151 = x1148 - x1149;
    let x1152 = x862 * x945;
    let x1153 = x327 * x1142;
    let x1155 = x1152 - x1153;
    let x1156 = x1147 + x1151;
    let x1157 = x1155 + x1156;
    let x1158 = x867 * x948;
    let x1160 = x329 * x1157;
    let x1161 = x1160 - x1158;
    let x1162 = x1161 - x1004;
    let x1163 = 0.10324176529421523 * s[71];
    let x1165 = 0.019134730176675482 * s[86];
    let x1166 = x1165 - x1163;
    let x1167 = 0.10324176529421523 * s[87];
    let x1169 = 0.019134730176675482 * s[94];
    let x1170 = x1169 - x1167;
    let x1171 = 0.10324176529421523 * s[95];
    let x1173 = 0.019134730176675482 * s[73];
    let x1174 = x1173 - x1171;
    let x1175 = x882 * x950;
    let x1176 = x331 * x1166;
    let x1177 = x1175 + x1176;
    let x1178 = x883 * x951;
    let x1179 = x332 * x1170;
    let x1180 = x1178 + x1179;
    let x1181 = x884 * x952;
    let x1182 = x333 * x1174;
    let x1183 = x1181 + x1182;
    let x1184 = x1177 + x1180;
    let x1185 = x1183 + x1184;
    let x1186 = x889 * x955;
    let x1188 = x335 * x1185;
    let x1189 = x1188 - x1186;
    let x1190 = x1189 - x1015;
    let x1191 = x1104 + x1105;
    let x1192 = x1108 + x1109;
    let x1193 = x1112 + x1113;
    let x1194 = x895 * x957;
    let x1195 = x337 * x1191;
    let x1196 = x1194 + x1195;
    let x1197 = x896 * x958;
    let x1198 = x338 * x1192;
    let x1199 = x1197 + x1198;
    let x1200 = x897 * x959;
    let x1201 = x339 * x1193;
    let x1202 = x1200 + x1201;
    let x1203 = x1196 + x1199;
    let x1204 = x1202 + x1203;
    let x1205 = x902 * x962;
    let x1207 = x341 * x1204;
    let x1208 = x1207 - x1205;
    let x1209 = x1208 - x1026;
    let x1237 = -x1103;
    let x1238 = -x1131;
    let x1239 = -x1162;
    let x1240 = -x1190;
    let x1241 = -x1209;
    out[0] = x1237;
    out[1] = x1238;
    out[2] = x1239;
    out[3] = x1240;
    out[4] = x1241;
}
#[inline(never)]
fn gamma_part_1(q: &[f64; 7], qd: &[f64; 7], s: &[f64; 96], out: &mut [f64; 7]) {
    let x68 = s[0] + 5.419247327442394;
    let x72 = x68 - 6.0999257357201815;
    let x73 = x72.cos();
    let x74 = 0.0567 * x73;
    let x76 = 0.20409642230625002 - x74;
    let x77 = x76.sqrt();
    let x283 = s[6] * 0.0681920450746693;
    let x284 = s[18] * 0.07984262638800323;
    let x285 = x283 + x284;
    let x286 = s[19] * 0.0681920450746693;
    let x287 = s[24] * 0.07984262638800323;
    let x288 = x286 + x287;
    let x289 = s[25] * 0.0681920450746693;
    let x290 = s[9] * 0.07984262638800323;
    let x291 = x289 + x290;
    let x292 = q[0] + x285;
    let x293 = q[1] + x288;
    let x294 = q[2] + x291;
    let x296 = x292 - 0.2654788250422677;
    let x298 = x294 - 0.04920359188287992;
    let x299 = x296 * x296;
    let x300 = x293 * x293;
    let x301 = x298 * x298;
    let x302 = x299 + x300;
    let x303 = x301 + x302;
    let x304 = x303.sqrt();
    let x343 = 2.0 * x296;
    let x344 = 2.0 * x293;
    let x345 = 2.0 * x298;
    let x346 = 2.0 * x304;
    let x347 = 1.0 / x346;
    let x744 = x72.sin();
    let x746 = 0.8726646259971648 * x744;
    let x748 = 0.0567 * x746;
    let x750 = x77 * 2.0;
    let x751 = 1.0 / x750;
    let x752 = x748 * x751;
    let x905 = 0.0681920450746693 * s[33];
    let x906 = 0.07984262638800323 * s[52];
    let x907 = x905 + x906;
    let x908 = 0.0681920450746693 * s[53];
    let x909 = 0.07984262638800323 * s[62];
    let x910 = x908 + x909;
    let x911 = 0.0681920450746693 * s[63];
    let x912 = 0.07984262638800323 * s[35];
    let x913 = x911 + x912;
    let x914 = qd[0] + x907;
    let x915 = qd[1] + x910;
    let x916 = qd[2] + x913;
    let x917 = x343 * x914;
    let x918 = x344 * x915;
    let x919 = x345 * x916;
    let x920 = x917 + x918;
    let x921 = x919 + x920;
    let x922 = x347 * x921;
    let x964 = 2.0 * x914;
    let x965 = 2.0 * x915;
    let x966 = 2.0 * x916;
    let x967 = 2.0 * x922;
    let x968 = x347 * x347;
    let x969 = x967 * x968;
    let x971 = 2.0 * qd[5];
    let x1027 = 0.8726646259971648 * x73;
    let x1028 = 0.8726646259971648 * x1027;
    let x1029 = 0.0567 * x1028;
    let x1030 = 2.0 * x752;
    let x1031 = x751 * x751;
    let x1032 = x1030 * x1031;
    let x1034 = x751 * x1029;
    let x1035 = x748 * x1032;
    let x1037 = x1034 - x1035;
    let x1046 = qd[5] * x971;
    let x1210 = 0.0681920450746693 * s[71];
    let x1211 = 0.07984262638800323 * s[86];
    let x1212 = x1210 + x1211;
    let x1213 = 0.0681920450746693 * s[87];
    let x1214 = 0.07984262638800323 * s[94];
    let x1215 = x1213 + x1214;
    let x1216 = 0.0681920450746693 * s[95];
    let x1217 = 0.07984262638800323 * s[73];
    let x1218 = x1216 + x1217;
    let x1219 = x914 * x964;
    let x1220 = x343 * x1212;
    let x1221 = x1219 + x1220;
    let x1222 = x915 * x965;
    let x1223 = x344 * x1215;
    let x1224 = x1222 + x1223;
    let x1225 = x916 * x966;
    let x1226 = x345 * x1218;
    let x1227 = x1225 + x1226;
    let x1228 = x1221 + x1224;
    let x1229 = x1227 + x1228;
    let x1230 = x921 * x969;
    let x1232 = x347 * x1229;
    let x1233 = x1232 - x1230;
    let x1234 = x1233 - x1037;
    let x1235 = x1046 + s[70];
    let x1236 = s[69] + x1235;
    let x1242 = -x1234;
    let x1243 = -x1236;
    out[5] = x1242;
    out[6] = x1243;
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
    let phi_q: &mut [f64; 46] = phi_q.try_into().expect("phi_q must have 46 entries");
    let phi_t: &mut [f64; 7] = phi_t.try_into().expect("phi_t must have 7 entries");
    let gamma: &mut [f64; 7] = gamma.try_into().expect("gamma must have 7 entries");
    let mut s = [0.0f64; 165];
    eval_kinematics_shared_0(q, qd, t, &mut s);
    eval_kinematics_part_0(q, qd, &s, phi, phi_q, phi_t, gamma);
    eval_kinematics_part_1(q, qd, &s, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_shared_0(q: &[f64; 7], qd: &[f64; 7], t: f64, s: &mut [f64; 165]) {
    let x7 = 0.8726646259971648 * t;
    s[0] = x7;
    let x44 = x7 + 3.324852225049198;
    s[1] = x44;
    let x48 = x44 - 4.005530633326987;
    s[2] = x48;
    let x49 = x48.cos();
    s[3] = x49;
    let x50 = 0.0567 * x49;
    s[4] = x50;
    let x52 = 0.20409642230625002 - x50;
    s[5] = x52;
    let x53 = x52.sqrt();
    s[6] = x53;
    let x87 = q[3] * q[3];
    s[7] = x87;
    let x88 = q[4] * q[4];
    s[8] = x88;
    let x90 = q[6] * q[6];
    s[9] = x90;
    let x91 = x87 + x88;
    s[10] = x91;
    let x92 = 2.0 * x91;
    s[11] = x92;
    let x94 = x92 - 1.0;
    s[12] = x94;
    let x98 = x87 + x90;
    s[13] = x98;
    let x99 = 2.0 * x98;
    s[14] = x99;
    let x100 = x99 - 1.0;
    s[15] = x100;
    let x101 = q[4] * q[5];
    s[16] = x101;
    let x102 = 2.0 * x101;
    s[17] = x102;
    let x103 = q[3] * q[6];
    s[18] = x103;
    let x105 = 2.0 * x103;
    s[19] = x105;
    let x108 = q[4] * q[6];
    s[20] = x108;
    let x109 = 2.0 * x108;
    s[21] = x109;
    let x110 = q[3] * q[5];
    s[22] = x110;
    let x111 = 2.0 * x110;
    s[23] = x111;
    let x112 = x109 + x111;
    s[24] = x112;
    let x113 = x102 + x105;
    s[25] = x113;
    let x114 = q[5] * q[6];
    s[26] = x114;
    let x115 = 2.0 * x114;
    s[27] = x115;
    let x116 = q[3] * q[4];
    s[28] = x116;
    let x118 = 2.0 * x116;
    s[29] = x118;
    let x120 = x115 - x118;
    s[30] = x120;
    let x123 = x109 - x111;
    s[31] = x123;
    let x162 = x94 * 0.03504972021954594;
    s[32] = x162;
    let x164 = x112 * 0.09897735656467874;
    s[33] = x164;
    let x167 = x113 * 0.03504972021954594;
    s[34] = x167;
    let x168 = x120 * 0.09897735656467874;
    s[35] = x168;
    let x171 = x123 * 0.03504972021954594;
    s[36] = x171;
    let x172 = x100 * 0.09897735656467874;
    s[37] = x172;
    let x234 = x94 * 0.10324176529421523;
    s[38] = x234;
    let x236 = x112 * 0.019134730176675482;
    s[39] = x236;
    let x237 = x236 - x234;
    s[40] = x237;
    let x238 = x113 * 0.10324176529421523;
    s[41] = x238;
    let x240 = x120 * 0.019134730176675482;
    s[42] = x240;
    let x241 = x240 - x238;
    s[43] = x241;
    let x242 = x123 * 0.10324176529421523;
    s[44] = x242;
    let x244 = x100 * 0.019134730176675482;
    s[45] = x244;
    let x245 = x244 - x242;
    s[46] = x245;
    let x246 = q[0] + x237;
    s[47] = x246;
    let x247 = q[1] + x241;
    s[48] = x247;
    let x248 = q[2] + x245;
    s[49] = x248;
    let x250 = x246 + 0.17535097304914954;
    s[50] = x250;
    let x252 = x248 - 0.20530961071200843;
    s[51] = x252;
    let x253 = x250 * x250;
    s[52] = x253;
    let x254 = x247 * x247;
    s[53] = x254;
    let x255 = x252 * x252;
    s[54] = x255;
    let x256 = x253 + x254;
    s[55] = x256;
    let x257 = x255 + x256;
    s[56] = x257;
    let x258 = x257.sqrt();
    s[57] = x258;
    let x310 = q[3] * 2.0;
    s[58] = x310;
    let x311 = q[4] * 2.0;
    s[59] = x311;
    let x312 = q[6] * 2.0;
    s[60] = x312;
    let x331 = 2.0 * x250;
    s[61] = x331;
    let x332 = 2.0 * x247;
    s[62] = x332;
    let x333 = 2.0 * x252;
    s[63] = x333;
    let x334 = 2.0 * x258;
    s[64] = x334;
    let x335 = 1.0 / x334;
    s[65] = x335;
    let x361 = q[5] * 2.0;
    s[66] = x361;
    let x362 = 2.0 * x310;
    s[67] = x362;
    let x386 = 0.03504972021954594 * x362;
    s[68] = x386;
    let x387 = 0.09897735656467874 * x361;
    s[69] = x387;
    let x390 = 0.03504972021954594 * x312;
    s[70] = x390;
    let x391 = 0.09897735656467874 * x311;
    s[71] = x391;
    let x394 = 0.03504972021954594 * x361;
    s[72] = x394;
    let x396 = 0.09897735656467874 * x362;
    s[73] = x396;
    let x435 = 0.019134730176675482 * x361;
    s[74] = x435;
    let x439 = 0.019134730176675482 * x311;
    s[75] = x439;
    let x480 = 2.0 * x311;
    s[76] = x480;
    let x495 = 0.03504972021954594 * x480;
    s[77] = x495;
    let x496 = 0.09897735656467874 * x312;
    s[78] = x496;
    let x499 = 0.09897735656467874 * x310;
    s[79] = x499;
    let x531 = 0.019134730176675482 * x312;
    s[80] = x531;
    let x533 = 0.019134730176675482 * x310;
    s[81] = x533;
    let x577 = 0.03504972021954594 * x311;
    s[82] = x577;
    let x579 = 0.03504972021954594 * x310;
    s[83] = x579;
    let x633 = 2.0 * x312;
    s[84] = x633;
    let x646 = 0.09897735656467874 * x633;
    s[85] = x646;
    let x766 = x310 * qd[3];
    s[86] = x766;
    let x767 = x311 * qd[4];
    s[87] = x767;
    let x769 = x312 * qd[6];
    s[88] = x769;
    let x770 = x766 + x767;
    s[89] = x770;
    let x771 = 2.0 * x770;
    s[90] = x771;
    let x772 = x766 + x769;
    s[91] = x772;
    let x773 = 2.0 * x772;
    s[92] = x773;
    let x774 = q[5] * qd[4];
    s[93] = x774;
    let x775 = q[4] * qd[5];
    s[94] = x775;
    let x776 = x774 + x775;
    s[95] = x776;
    let x777 = 2.0 * x776;
    s[96] = x777;
    let x778 = q[6] * qd[3];
    s[97] = x778;
    let x779 = q[3] * qd[6];
    s[98] = x779;
    let x780 = x778 + x779;
    s[99] = x780;
    let x781 = 2.0 * x780;
    s[100] = x781;
    let x782 = q[6] * qd[4];
    s[101] = x782;
    let x783 = q[4] * qd[6];
    s[102] = x783;
    let x784 = x782 + x783;
    s[103] = x784;
    let x785 = 2.0 * x784;
    s[104] = x785;
    let x786 = q[5] * qd[3];
    s[105] = x786;
    let x787 = q[3] * qd[5];
    s[106] = x787;
    let x788 = x786 + x787;
    s[107] = x788;
    let x789 = 2.0 * x788;
    s[108] = x789;
    let x790 = x785 + x789;
    s[109] = x790;
    let x791 = x777 + x781;
    s[110] = x791;
    let x792 = q[6] * qd[5];
    s[111] = x792;
    let x793 = q[5] * qd[6];
    s[112] = x793;
    let x794 = x792 + x793;
    s[113] = x794;
    let x795 = 2.0 * x794;
    s[114] = x795;
    let x796 = q[4] * qd[3];
    s[115] = x796;
    let x797 = q[3] * qd[4];
    s[116] = x797;
    let x798 = x796 + x797;
    s[117] = x798;
    let x799 = 2.0 * x798;
    s[118] = x799;
    let x801 = x795 - x799;
    s[119] = x801;
    let x803 = x785 - x789;
    s[120] = x803;
    let x826 = 0.03504972021954594 * x771;
    s[121] = x826;
    let x827 = 0.09897735656467874 * x790;
    s[122] = x827;
    let x830 = 0.03504972021954594 * x791;
    s[123] = x830;
    let x831 = 0.09897735656467874 * x801;
    s[124] = x831;
    let x834 = 0.03504972021954594 * x803;
    s[125] = x834;
    let x835 = 0.09897735656467874 * x773;
    s[126] = x835;
    let x926 = 2.0 * qd[3];
    s[127] = x926;
    let x927 = 2.0 * qd[4];
    s[128] = x927;
    let x928 = 2.0 * qd[6];
    s[129] = x928;
    let x1044 = qd[3] * x926;
    s[130] = x1044;
    let x1045 = qd[4] * x927;
    s[131] = x1045;
    let x1047 = qd[6] * x928;
    s[132] = x1047;
    let x1048 = x1044 + x1045;
    s[133] = x1048;
    let x1049 = 2.0 * x1048;
    s[134] = x1049;
    let x1050 = x1044 + x1047;
    s[135] = x1050;
    let x1051 = 2.0 * x1050;
    s[136] = x1051;
    let x1052 = qd[4] * qd[5];
    s[137] = x1052;
    let x1053 = x1052 + x1052;
    s[138] = x1053;
    let x1054 = 2.0 * x1053;
    s[139] = x1054;
    let x1055 = qd[3] * qd[6];
    s[140] = x1055;
    let x1056 = x1055 + x1055;
    s[141] = x1056;
    let x1057 = 2.0 * x1056;
    s[142] = x1057;
    let x1058 = qd[4] * qd[6];
    s[143] = x1058;
    let x1059 = x1058 + x1058;
    s[144] = x1059;
    let x1060 = 2.0 * x1059;
    s[145] = x1060;
    let x1061 = qd[3] * qd[5];
    s[146] = x1061;
    let x1062 = x1061 + x1061;
    s[147] = x1062;
    let x1063 = 2.0 * x1062;
    s[148] = x1063;
    let x1064 = x1060 + x1063;
    s[149] = x1064;
    let x1065 = x1054 + x1057;
    s[150] = x1065;
    let x1066 = qd[5] * qd[6];
    s[151] = x1066;
    let x1067 = x1066 + x1066;
    s[152] = x1067;
    let x1068 = 2.0 * x1067;
    s[153] = x1068;
    let x1069 = qd[3] * qd[4];
    s[154] = x1069;
    let x1070 = x1069 + x1069;
    s[155] = x1070;
    let x1071 = 2.0 * x1070;
    s[156] = x1071;
    let x1073 = x1068 - x1071;
    s[157] = x1073;
    let x1075 = x1060 - x1063;
    s[158] = x1075;
    let x1104 = 0.03504972021954594 * x1049;
    s[159] = x1104;
    let x1105 = 0.09897735656467874 * x1064;
    s[160] = x1105;
    let x1108 = 0.03504972021954594 * x1065;
    s[161] = x1108;
    let x1109 = 0.09897735656467874 * x1073;
    s[162] = x1109;
    let x1112 = 0.03504972021954594 * x1075;
    s[163] = x1112;
    let x1113 = 0.09897735656467874 * x1051;
    s[164] = x1113;
}
#[inline(never)]
fn eval_kinematics_part_0(
    q: &[f64; 7],
    qd: &[f64; 7],
    s: &[f64; 165],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 46],
    phi_t: &mut [f64; 7],
    gamma: &mut [f64; 7],
) {
    let x8 = 0.8639379797371931 + s[0];
    let x12 = x8 - 0.1832595714594046;
    let x13 = x12.cos();
    let x14 = 0.0567 * x13;
    let x16 = 0.20409642230625002 - x14;
    let x17 = x16.sqrt();
    let x20 = s[0] + 1.2304571226560024;
    let x24 = x20 - 1.911135530933791;
    let x25 = x24.cos();
    let x26 = 0.0567 * x25;
    let x28 = 0.20409642230625002 - x26;
    let x29 = x28.sqrt();
    let x32 = s[0] + 2.9583330821303884;
    let x36 = x32 - 2.2776546738526;
    let x37 = x36.cos();
    let x38 = 0.0567 * x37;
    let x40 = 0.20409642230625002 - x38;
    let x41 = x40.sqrt();
    let x130 = s[12] * 0.06819204507466928;
    let x132 = s[24] * 0.07984262638800324;
    let x134 = x130 - x132;
    let x135 = s[25] * 0.06819204507466928;
    let x136 = s[30] * 0.07984262638800324;
    let x138 = x135 - x136;
    let x139 = s[31] * 0.06819204507466928;
    let x140 = s[15] * 0.07984262638800324;
    let x142 = x139 - x140;
    let x143 = q[0] + x134;
    let x144 = q[1] + x138;
    let x145 = q[2] + x142;
    let x147 = x143 - 0.2654788250422678;
    let x149 = x145 + 0.04920359188287982;
    let x150 = x147 * x147;
    let x151 = x144 * x144;
    let x152 = x149 * x149;
    let x153 = x150 + x151;
    let x154 = x152 + x153;
    let x155 = x154.sqrt();
    let x157 = x155 - x17;
    let x166 = s[32] - s[33];
    let x170 = s[34] - s[35];
    let x174 = s[36] - s[37];
    let x175 = q[0] + x166;
    let x176 = q[1] + x170;
    let x177 = q[2] + x174;
    let x179 = x175 + 0.09012785199311818;
    let x181 = x177 + 0.2545132025948882;
    let x182 = x179 * x179;
    let x183 = x176 * x176;
    let x184 = x181 * x181;
    let x185 = x182 + x183;
    let x186 = x184 + x185;
    let x187 = x186.sqrt();
    let x189 = x187 - x29;
    let x195 = s[12] * 0.10324176529421522;
    let x198 = s[24] * 0.01913473017667551;
    let x200 = x195 + x198;
    let x202 = s[25] * 0.10324176529421522;
    let x204 = s[30] * 0.01913473017667551;
    let x206 = x202 + x204;
    let x208 = s[31] * 0.10324176529421522;
    let x210 = s[15] * 0.01913473017667551;
    let x212 = x208 + x210;
    let x214 = q[0] - x200;
    let x215 = q[1] - x206;
    let x216 = q[2] - x212;
    let x218 = x214 + 0.17535097304914957;
    let x220 = x216 + 0.2053096107120084;
    let x221 = x218 * x218;
    let x222 = x215 * x215;
    let x223 = x220 * x220;
    let x224 = x221 + x222;
    let x225 = x223 + x224;
    let x226 = x225.sqrt();
    let x228 = x226 - x41;
    let x260 = s[57] - s[6];
    let x313 = 2.0 * x147;
    let x314 = 2.0 * x144;
    let x315 = 2.0 * x149;
    let x316 = 2.0 * x155;
    let x317 = 1.0 / x316;
    let x318 = x313 * x317;
    let x319 = 2.0 * x179;
    let x320 = 2.0 * x176;
    let x321 = 2.0 * x181;
    let x322 = 2.0 * x187;
    let x323 = 1.0 / x322;
    let x324 = x319 * x323;
    let x325 = 2.0 * x218;
    let x326 = 2.0 * x215;
    let x327 = 2.0 * x220;
    let x328 = 2.0 * x226;
    let x329 = 1.0 / x328;
    let x330 = x325 * x329;
    let x336 = s[61] * s[65];
    let x349 = x314 * x317;
    let x350 = x320 * x323;
    let x351 = x326 * x329;
    let x352 = s[62] * s[65];
    let x355 = x315 * x317;
    let x356 = x321 * x323;
    let x357 = x327 * x329;
    let x358 = s[63] * s[65];
    let x365 = 0.06819204507466928 * s[67];
    let x366 = 0.07984262638800324 * s[66];
    let x368 = x365 - x366;
    let x369 = 0.06819204507466928 * s[60];
    let x370 = 0.07984262638800324 * s[59];
    let x372 = x369 + x370;
    let x373 = 0.06819204507466928 * s[66];
    let x375 = 0.07984262638800324 * s[67];
    let x377 = x373 + x375;
    let x379 = x313 * x368;
    let x380 = x314 * x372;
    let x381 = x315 * x377;
    let x383 = x379 + x380;
    let x384 = x383 - x381;
    let x385 = x317 * x384;
    let x389 = s[68] - s[69];
    let x393 = s[70] + s[71];
    let x398 = s[72] + s[73];
    let x400 = x319 * x389;
    let x401 = x320 * x393;
    let x402 = x321 * x398;
    let x404 = x400 + x401;
    let x405 = x404 - x402;
    let x406 = x323 * x405;
    let x407 = 0.10324176529421522 * s[67];
    let x408 = 0.01913473017667551 * s[66];
    let x409 = x407 + x408;
    let x411 = 0.10324176529421522 * s[60];
    let x412 = 0.01913473017667551 * s[59];
    let x414 = x411 - x412;
    let x416 = 0.10324176529421522 * s[66];
    let x418 = 0.01913473017667551 * s[67];
    let x419 = x418 - x416;
    let x421 = x325 * x409;
    let x423 = x326 * x414;
    let x425 = x327 * x419;
    let x427 = x421 + x423;
    let x429 = x425 + x427;
    let x431 = x329 * x429;
    let x432 = -x431;
    let x433 = 0.10324176529421523 * s[67];
    let x436 = s[74] - x433;
    let x437 = 0.10324176529421523 * s[60];
    let x441 = x437 + s[75];
    let x443 = 0.10324176529421523 * s[66];
    let x445 = 0.019134730176675482 * s[67];
    let x446 = x443 + x445;
    let x447 = s[61] * x436;
    let x448 = s[62] * x441;
    let x450 = s[63] * x446;
    let x451 = x447 - x448;
    let x452 = x450 + x451;
    let x453 = s[65] * x452;
    let x482 = 0.06819204507466928 * s[76];
    let x483 = 0.07984262638800324 * s[60];
    let x485 = x482 - x483;
    let x486 = 0.07984262638800324 * s[58];
    let x488 = x373 + x486;
    let x489 = x313 * x485;
    let x490 = x314 * x488;
    let x491 = x315 * x369;
    let x492 = x489 + x490;
    let x493 = x491 + x492;
    let x494 = x317 * x493;
    let x498 = s[77] - s[78];
    let x501 = s[72] + s[79];
    let x502 = x319 * x498;
    let x503 = x320 * x501;
    let x504 = x321 * s[70];
    let x505 = x502 + x503;
    let x506 = x504 + x505;
    let x507 = x323 * x506;
    let x508 = 0.10324176529421522 * s[76];
    let x509 = 0.01913473017667551 * s[60];
    let x510 = x508 + x509;
    let x512 = 0.01913473017667551 * s[58];
    let x514 = x416 - x512;
    let x517 = x325 * x510;
    let x519 = x326 * x514;
    let x521 = x327 * x411;
    let x523 = x517 + x519;
    let x525 = x521 + x523;
    let x527 = x329 * x525;
    let x528 = -x527;
    let x529 = 0.10324176529421523 * s[76];
    let x532 = s[80] - x529;
    let x535 = x443 + s[81];
    let x537 = s[61] * x532;
    let x538 = s[62] * x535;
    let x540 = s[63] * x437;
    let x542 = x537 - x538;
    let x543 = x542 - x540;
    let x544 = s[65] * x543;
    let x565 = 0.06819204507466928 * s[59];
    let x566 = x565 - x483;
    let x567 = 0.06819204507466928 * s[58];
    let x569 = x313 * x486;
    let x571 = x314 * x566;
    let x572 = x315 * x567;
    let x574 = x571 - x569;
    let x575 = x574 - x572;
    let x576 = x317 * x575;
    let x578 = s[82] - s[78];
    let x581 = x319 * s[79];
    let x583 = x320 * x578;
    let x584 = x321 * s[83];
    let x586 = x583 - x581;
    let x587 = x586 - x584;
    let x588 = x323 * x587;
    let x589 = 0.10324176529421522 * s[59];
    let x590 = x509 + x589;
    let x592 = 0.10324176529421522 * s[58];
    let x594 = x325 * x512;
    let x596 = x326 * x590;
    let x598 = x327 * x592;
    let x599 = x594 + x596;
    let x601 = x598 - x599;
    let x602 = x329 * x601;
    let x634 = x567 - x366;
    let x635 = 0.07984262638800324 * s[84];
    let x637 = x565 - x635;
    let x638 = x313 * x370;
    let x640 = x314 * x634;
    let x641 = x315 * x637;
    let x642 = x640 - x638;
    let x643 = x641 + x642;
    let x644 = x317 * x643;
    let x645 = s[83] - s[69];
    let x648 = s[82] - s[85];
    let x649 = x319 * s[71];
    let x651 = x320 * x645;
    let x652 = x321 * x648;
    let x653 = x651 - x649;
    let x654 = x652 + x653;
    let x655 = x323 * x654;
    let x656 = x408 + x592;
    let x658 = 0.01913473017667551 * s[84];
    let x659 = x589 + x658;
    let x661 = x325 * x412;
    let x663 = x326 * x656;
    let x665 = x327 * x659;
    let x667 = x661 + x663;
    let x669 = x665 + x667;
    let x671 = x329 * x669;
    let x672 = -x671;
    let x699 = x12.sin();
    let x701 = 0.8726646259971648 * x699;
    let x703 = 0.0567 * x701;
    let x705 = x17 * 2.0;
    let x706 = 1.0 / x705;
    let x707 = x703 * x706;
    let x708 = x24.sin();
    let x710 = 0.8726646259971648 * x708;
    let x712 = 0.0567 * x710;
    let x714 = x29 * 2.0;
    let x715 = 1.0 / x714;
    let x716 = x712 * x715;
    let x717 = x36.sin();
    let x719 = 0.8726646259971648 * x717;
    let x721 = 0.0567 * x719;
    let x723 = x41 * 2.0;
    let x724 = 1.0 / x723;
    let x725 = x721 * x724;
    let x753 = -x707;
    let x754 = -x716;
    let x755 = -x725;
    let x804 = 0.06819204507466928 * s[90];
    let x805 = 0.07984262638800324 * s[109];
    let x807 = x804 - x805;
    let x808 = 0.06819204507466928 * s[110];
    let x809 = 0.07984262638800324 * s[119];
    let x811 = x808 - x809;
    let x812 = 0.06819204507466928 * s[120];
    let x813 = 0.07984262638800324 * s[92];
    let x815 = x812 - x813;
    let x816 = qd[0] + x807;
    let x817 = qd[1] + x811;
    let x818 = qd[2] + x815;
    let x819 = x313 * x816;
    let x820 = x314 * x817;
    let x821 = x315 * x818;
    let x822 = x819 + x820;
    let x823 = x821 + x822;
    let x824 = x317 * x823;
    let x829 = s[121] - s[122];
    let x833 = s[123] - s[124];
    let x837 = s[125] - s[126];
    let x838 = qd[0] + x829;
    let x839 = qd[1] + x833;
    let x840 = qd[2] + x837;
    let x841 = x319 * x838;
    let x842 = x320 * x839;
    let x843 = x321 * x840;
    let x844 = x841 + x842;
    let x845 = x843 + x844;
    let x846 = x323 * x845;
    let x848 = 0.10324176529421522 * s[90];
    let x849 = 0.01913473017667551 * s[109];
    let x850 = x848 + x849;
    let x852 = 0.10324176529421522 * s[110];
    let x853 = 0.01913473017667551 * s[119];
    let x854 = x852 + x853;
    let x856 = 0.10324176529421522 * s[120];
    let x857 = 0.01913473017667551 * s[92];
    let x858 = x856 + x857;
    let x860 = qd[0] - x850;
    let x861 = qd[1] - x854;
    let x862 = qd[2] - x858;
    let x863 = x325 * x860;
    let x864 = x326 * x861;
    let x865 = x327 * x862;
    let x866 = x863 + x864;
    let x867 = x865 + x866;
    let x868 = x329 * x867;
    let x929 = 2.0 * x816;
    let x930 = 2.0 * x817;
    let x931 = 2.0 * x818;
    let x932 = 2.0 * x824;
    let x933 = x317 * x317;
    let x934 = x932 * x933;
    let x936 = 2.0 * x838;
    let x937 = 2.0 * x839;
    let x938 = 2.0 * x840;
    let x939 = 2.0 * x846;
    let x940 = x323 * x323;
    let x941 = x939 * x940;
    let x943 = 2.0 * x860;
    let x944 = 2.0 * x861;
    let x945 = 2.0 * x862;
    let x946 = 2.0 * x868;
    let x947 = x329 * x329;
    let x948 = x946 * x947;
    let x972 = 0.8726646259971648 * x13;
    let x973 = 0.8726646259971648 * x972;
    let x974 = 0.0567 * x973;
    let x975 = 2.0 * x707;
    let x976 = x706 * x706;
    let x977 = x975 * x976;
    let x979 = x706 * x974;
    let x980 = x703 * x977;
    let x982 = x979 - x980;
    let x983 = 0.8726646259971648 * x25;
    let x984 = 0.8726646259971648 * x983;
    let x985 = 0.0567 * x984;
    let x986 = 2.0 * x716;
    let x987 = x715 * x715;
    let x988 = x986 * x987;
    let x990 = x715 * x985;
    let x991 = x712 * x988;
    let x993 = x990 - x991;
    let x994 = 0.8726646259971648 * x37;
    let x995 = 0.8726646259971648 * x994;
    let x996 = 0.0567 * x995;
    let x997 = 2.0 * x725;
    let x998 = x724 * x724;
    let x999 = x997 * x998;
    let x1001 = x724 * x996;
    let x1002 = x721 * x999;
    let x1004 = x1001 - x1002;
    let x1076 = 0.06819204507466928 * s[134];
    let x1077 = 0.07984262638800324 * s[149];
    let x1079 = x1076 - x1077;
    let x1080 = 0.06819204507466928 * s[150];
    let x1081 = 0.07984262638800324 * s[157];
    let x1083 = x1080 - x1081;
    let x1084 = 0.06819204507466928 * s[158];
    let x1085 = 0.07984262638800324 * s[136];
    let x1087 = x1084 - x1085;
    let x1088 = x816 * x929;
    let x1089 = x313 * x1079;
    let x1090 = x1088 + x1089;
    let x1091 = x817 * x930;
    let x1092 = x314 * x1083;
    let x1093 = x1091 + x1092;
    let x1094 = x818 * x931;
    let x1095 = x315 * x1087;
    let x1096 = x1094 + x1095;
    let x1097 = x1090 + x1093;
    let x1098 = x1096 + x1097;
    let x1099 = x823 * x934;
    let x1101 = x317 * x1098;
    let x1102 = x1101 - x1099;
    let x1103 = x1102 - x982;
    let x1107 = s[159] - s[160];
    let x1111 = s[161] - s[162];
    let x1115 = s[163] - s[164];
    let x1116 = x838 * x936;
    let x1117 = x319 * x1107;
    let x1118 = x1116 + x1117;
    let x1119 = x839 * x937;
    let x1120 = x320 * x1111;
    let x1121 = x1119 + x1120;
    let x1122 = x840 * x938;
    let x1123 = x321 * x1115;
    let x1124 = x1122 + x1123;
    let x1125 = x1118 + x1121;
    let x1126 = x1124 + x1125;
    let x1127 = x845 * x941;
    let x1129 = x323 * x1126;
    let x1130 = x1129 - x1127;
    let x1131 = x1130 - x993;
    let x1132 = 0.10324176529421522 * s[134];
    let x1133 = 0.01913473017667551 * s[149];
    let x1134 = x1132 + x1133;
    let x1136 = 0.10324176529421522 * s[150];
    let x1137 = 0.01913473017667551 * s[157];
    let x1138 = x1136 + x1137;
    let x1140 = 0.10324176529421522 * s[158];
    let x1141 = 0.01913473017667551 * s[136];
    let x1142 = x1140 + x1141;
    let x1144 = x860 * x943;
    let x1145 = x325 * x1134;
    let x1147 = x1144 - x1145;
    let x1148 = x861 * x944;
    let x1149 = x326 * x1138;
    let x1151 = x1148 - x1149;
    let x1152 = x862 * x945;
    let x1153 = x327 * x1142;
    let x1155 = x1152 - x1153;
    let x1156 = x1147 + x1151;
    let x1157 = x1155 + x1156;
    let x1158 = x867 * x948;
    let x1160 = x329 * x1157;
    let x1161 = x1160 - x1158;
    let x1162 = x1161 - x1004;
    let x1237 = -x1103;
    let x1238 = -x1131;
    let x1239 = -x1162;
    phi[0] = x157;
    phi_q[0] = x318;
    phi_q[1] = x349;
    phi_q[2] = x355;
    phi_q[3] = x385;
    phi_q[4] = x494;
    phi_q[5] = x576;
    phi_q[6] = x644;
    phi_t[0] = x753;
    gamma[0] = x1237;
    phi[1] = x189;
    phi_q[7] = x324;
    phi_q[8] = x350;
    phi_q[9] = x356;
    phi_q[10] = x406;
    phi_q[11] = x507;
    phi_q[12] = x588;
    phi_q[13] = x655;
    phi_t[1] = x754;
    gamma[1] = x1238;
    phi[2] = x228;
    phi_q[14] = x330;
    phi_q[15] = x351;
    phi_q[16] = x357;
    phi_q[17] = x432;
    phi_q[18] = x528;
    phi_q[19] = x602;
    phi_q[20] = x672;
    phi_t[2] = x755;
    gamma[2] = x1239;
    phi[3] = x260;
    phi_q[21] = x336;
    phi_q[22] = x352;
    phi_q[23] = x358;
    phi_q[24] = x453;
    phi_q[25] = x544;
}
#[inline(never)]
fn eval_kinematics_part_1(
    q: &[f64; 7],
    qd: &[f64; 7],
    s: &[f64; 165],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 46],
    phi_t: &mut [f64; 7],
    gamma: &mut [f64; 7],
) {
    let x56 = s[0] + 5.052728184523584;
    let x60 = x56 - 4.372049776245795;
    let x61 = x60.cos();
    let x62 = 0.0567 * x61;
    let x64 = 0.20409642230625002 - x62;
    let x65 = x64.sqrt();
    let x68 = s[0] + 5.419247327442394;
    let x72 = x68 - 6.0999257357201815;
    let x73 = x72.cos();
    let x74 = 0.0567 * x73;
    let x76 = 0.20409642230625002 - x74;
    let x77 = x76.sqrt();
    let x89 = q[5] * q[5];
    let x262 = s[32] + s[33];
    let x263 = s[34] + s[35];
    let x264 = s[36] + s[37];
    let x265 = q[0] + x262;
    let x266 = q[1] + x263;
    let x267 = q[2] + x264;
    let x269 = x265 + 0.09012785199311824;
    let x270 = x267 - 0.2545132025948882;
    let x271 = x269 * x269;
    let x272 = x266 * x266;
    let x273 = x270 * x270;
    let x274 = x271 + x272;
    let x275 = x273 + x274;
    let x276 = x275.sqrt();
    let x278 = x276 - x65;
    let x283 = s[12] * 0.0681920450746693;
    let x284 = s[24] * 0.07984262638800323;
    let x285 = x283 + x284;
    let x286 = s[25] * 0.0681920450746693;
    let x287 = s[30] * 0.07984262638800323;
    let x288 = x286 + x287;
    let x289 = s[31] * 0.0681920450746693;
    let x290 = s[15] * 0.07984262638800323;
    let x291 = x289 + x290;
    let x292 = q[0] + x285;
    let x293 = q[1] + x288;
    let x294 = q[2] + x291;
    let x296 = x292 - 0.2654788250422677;
    let x298 = x294 - 0.04920359188287992;
    let x299 = x296 * x296;
    let x300 = x293 * x293;
    let x301 = x298 * x298;
    let x302 = x299 + x300;
    let x303 = x301 + x302;
    let x304 = x303.sqrt();
    let x306 = x304 - x77;
    let x307 = x89 + s[10];
    let x308 = s[9] + x307;
    let x309 = x308 - 1.0;
    let x337 = 2.0 * x269;
    let x338 = 2.0 * x266;
    let x339 = 2.0 * x270;
    let x340 = 2.0 * x276;
    let x341 = 1.0 / x340;
    let x342 = x337 * x341;
    let x343 = 2.0 * x296;
    let x344 = 2.0 * x293;
    let x345 = 2.0 * x298;
    let x346 = 2.0 * x304;
    let x347 = 1.0 / x346;
    let x348 = x343 * x347;
    let x353 = x338 * x341;
    let x354 = x344 * x347;
    let x359 = x339 * x341;
    let x360 = x345 * x347;
    let x454 = s[68] + s[69];
    let x455 = s[70] - s[71];
    let x456 = s[73] - s[72];
    let x457 = x337 * x454;
    let x458 = x338 * x455;
    let x459 = x339 * x456;
    let x460 = x457 + x458;
    let x461 = x459 + x460;
    let x462 = x341 * x461;
    let x463 = 0.0681920450746693 * s[67];
    let x464 = 0.07984262638800323 * s[66];
    let x465 = x463 + x464;
    let x466 = 0.0681920450746693 * s[60];
    let x467 = 0.07984262638800323 * s[59];
    let x469 = x466 - x467;
    let x470 = 0.0681920450746693 * s[66];
    let x472 = 0.07984262638800323 * s[67];
    let x473 = x472 - x470;
    let x474 = x343 * x465;
    let x475 = x344 * x469;
    let x476 = x345 * x473;
    let x477 = x474 + x475;
    let x478 = x476 + x477;
    let x479 = x347 * x478;
    let x545 = s[77] + s[78];
    let x546 = s[72] - s[79];
    let x547 = x337 * x545;
    let x548 = x338 * x546;
    let x549 = x339 * s[70];
    let x550 = x547 + x548;
    let x551 = x549 + x550;
    let x552 = x341 * x551;
    let x553 = 0.0681920450746693 * s[76];
    let x554 = 0.07984262638800323 * s[60];
    let x555 = x553 + x554;
    let x556 = 0.07984262638800323 * s[58];
    let x558 = x470 - x556;
    let x559 = x343 * x555;
    let x560 = x344 * x558;
    let x561 = x345 * x466;
    let x562 = x559 + x560;
    let x563 = x561 + x562;
    let x564 = x347 * x563;
    let x603 = 0.10324176529421523 * s[59];
    let x605 = s[80] - x603;
    let x606 = 0.10324176529421523 * s[58];
    let x608 = s[61] * s[81];
    let x609 = s[62] * x605;
    let x610 = s[63] * x606;
    let x611 = x608 + x609;
    let x612 = x610 + x611;
    let x613 = s[65] * x612;
    let x614 = s[78] + s[82];
    let x615 = x337 * s[79];
    let x616 = x338 * x614;
    let x617 = x339 * s[83];
    let x619 = x615 + x616;
    let x620 = x619 - x617;
    let x621 = x341 * x620;
    let x622 = 0.0681920450746693 * s[59];
    let x623 = x554 + x622;
    let x624 = 0.0681920450746693 * s[58];
    let x626 = x343 * x556;
    let x627 = x344 * x623;
    let x628 = x345 * x624;
    let x630 = x626 + x627;
    let x631 = x630 - x628;
    let x632 = x347 * x631;
    let x673 = s[74] - x606;
    let x674 = 0.019134730176675482 * s[84];
    let x675 = x674 - x603;
    let x676 = s[61] * s[75];
    let x677 = s[62] * x673;
    let x678 = s[63] * x675;
    let x679 = x676 + x677;
    let x680 = x678 + x679;
    let x681 = s[65] * x680;
    let x682 = s[69] + s[83];
    let x683 = s[82] + s[85];
    let x684 = x337 * s[71];
    let x685 = x338 * x682;
    let x686 = x339 * x683;
    let x687 = x684 + x685;
    let x688 = x686 + x687;
    let x689 = x341 * x688;
    let x690 = x464 + x624;
    let x691 = 0.07984262638800323 * s[84];
    let x692 = x622 + x691;
    let x693 = x343 * x467;
    let x694 = x344 * x690;
    let x695 = x345 * x692;
    let x696 = x693 + x694;
    let x697 = x695 + x696;
    let x698 = x347 * x697;
    let x726 = s[2].sin();
    let x728 = 0.8726646259971648 * x726;
    let x730 = 0.0567 * x728;
    let x732 = s[6] * 2.0;
    let x733 = 1.0 / x732;
    let x734 = x730 * x733;
    let x735 = x60.sin();
    let x737 = 0.8726646259971648 * x735;
    let x739 = 0.0567 * x737;
    let x741 = x65 * 2.0;
    let x742 = 1.0 / x741;
    let x743 = x739 * x742;
    let x744 = x72.sin();
    let x746 = 0.8726646259971648 * x744;
    let x748 = 0.0567 * x746;
    let x750 = x77 * 2.0;
    let x751 = 1.0 / x750;
    let x752 = x748 * x751;
    let x756 = -x734;
    let x757 = -x743;
    let x758 = -x752;
    let x870 = 0.10324176529421523 * s[90];
    let x872 = 0.019134730176675482 * s[109];
    let x873 = x872 - x870;
    let x874 = 0.10324176529421523 * s[110];
    let x876 = 0.019134730176675482 * s[119];
    let x877 = x876 - x874;
    let x878 = 0.10324176529421523 * s[120];
    let x880 = 0.019134730176675482 * s[92];
    let x881 = x880 - x878;
    let x882 = qd[0] + x873;
    let x883 = qd[1] + x877;
    let x884 = qd[2] + x881;
    let x885 = s[61] * x882;
    let x886 = s[62] * x883;
    let x887 = s[63] * x884;
    let x888 = x885 + x886;
    let x889 = x887 + x888;
    let x890 = s[65] * x889;
    let x892 = s[121] + s[122];
    let x893 = s[123] + s[124];
    let x894 = s[125] + s[126];
    let x895 = qd[0] + x892;
    let x896 = qd[1] + x893;
    let x897 = qd[2] + x894;
    let x898 = x337 * x895;
    let x899 = x338 * x896;
    let x900 = x339 * x897;
    let x901 = x898 + x899;
    let x902 = x900 + x901;
    let x903 = x341 * x902;
    let x905 = 0.0681920450746693 * s[90];
    let x906 = 0.07984262638800323 * s[109];
    let x907 = x905 + x906;
    let x908 = 0.0681920450746693 * s[110];
    let x909 = 0.07984262638800323 * s[119];
    let x910 = x908 + x909;
    let x911 = 0.0681920450746693 * s[120];
    let x912 = 0.07984262638800323 * s[92];
    let x913 = x911 + x912;
    let x914 = qd[0] + x907;
    let x915 = qd[1] + x910;
    let x916 = qd[2] + x913;
    let x917 = x343 * x914;
    let x918 = x344 * x915;
    let x919 = x345 * x916;
    let x920 = x917 + x918;
    let x921 = x919 + x920;
    let x922 = x347 * x921;
    let x950 = 2.0 * x882;
    let x951 = 2.0 * x883;
    let x952 = 2.0 * x884;
    let x953 = 2.0 * x890;
    let x954 = s[65] * s[65];
    let x955 = x953 * x954;
    let x957 = 2.0 * x895;
    let x958 = 2.0 * x896;
    let x959 = 2.0 * x897;
    let x960 = 2.0 * x903;
    let x961 = x341 * x341;
    let x962 = x960 * x961;
    let x964 = 2.0 * x914;
    let x965 = 2.0 * x915;
    let x966 = 2.0 * x916;
    let x967 = 2.0 * x922;
    let x968 = x347 * x347;
    let x969 = x967 * x968;
    let x971 = 2.0 * qd[5];
    let x1005 = 0.8726646259971648 * s[3];
    let x1006 = 0.8726646259971648 * x1005;
    let x1007 = 0.0567 * x1006;
    let x1008 = 2.0 * x734;
    let x1009 = x733 * x733;
    let x1010 = x1008 * x1009;
    let x1012 = x733 * x1007;
    let x1013 = x730 * x1010;
    let x1015 = x1012 - x1013;
    let x1016 = 0.8726646259971648 * x61;
    let x1017 = 0.8726646259971648 * x1016;
    let x1018 = 0.0567 * x1017;
    let x1019 = 2.0 * x743;
    let x1020 = x742 * x742;
    let x1021 = x1019 * x1020;
    let x1023 = x742 * x1018;
    let x1024 = x739 * x1021;
    let x1026 = x1023 - x1024;
    let x1027 = 0.8726646259971648 * x73;
    let x1028 = 0.8726646259971648 * x1027;
    let x1029 = 0.0567 * x1028;
    let x1030 = 2.0 * x752;
    let x1031 = x751 * x751;
    let x1032 = x1030 * x1031;
    let x1034 = x751 * x1029;
    let x1035 = x748 * x1032;
    let x1037 = x1034 - x1035;
    let x1046 = qd[5] * x971;
    let x1163 = 0.10324176529421523 * s[134];
    let x1165 = 0.019134730176675482 * s[149];
    let x1166 = x1165 - x1163;
    let x1167 = 0.10324176529421523 * s[150];
    let x1169 = 0.019134730176675482 * s[157];
    let x1170 = x1169 - x1167;
    let x1171 = 0.10324176529421523 * s[158];
    let x1173 = 0.019134730176675482 * s[136];
    let x1174 = x1173 - x1171;
    let x1175 = x882 * x950;
    let x1176 = s[61] * x1166;
    let x1177 = x1175 + x1176;
    let x1178 = x883 * x951;
    let x1179 = s[62] * x1170;
    let x1180 = x1178 + x1179;
    let x1181 = x884 * x952;
    let x1182 = s[63] * x1174;
    let x1183 = x1181 + x1182;
    let x1184 = x1177 + x1180;
    let x1185 = x1183 + x1184;
    let x1186 = x889 * x955;
    let x1188 = s[65] * x1185;
    let x1189 = x1188 - x1186;
    let x1190 = x1189 - x1015;
    let x1191 = s[159] + s[160];
    let x1192 = s[161] + s[162];
    let x1193 = s[163] + s[164];
    let x1194 = x895 * x957;
    let x1195 = x337 * x1191;
    let x1196 = x1194 + x1195;
    let x1197 = x896 * x958;
    let x1198 = x338 * x1192;
    let x1199 = x1197 + x1198;
    let x1200 = x897 * x959;
    let x1201 = x339 * x1193;
    let x1202 = x1200 + x1201;
    let x1203 = x1196 + x1199;
    let x1204 = x1202 + x1203;
    let x1205 = x902 * x962;
    let x1207 = x341 * x1204;
    let x1208 = x1207 - x1205;
    let x1209 = x1208 - x1026;
    let x1210 = 0.0681920450746693 * s[134];
    let x1211 = 0.07984262638800323 * s[149];
    let x1212 = x1210 + x1211;
    let x1213 = 0.0681920450746693 * s[150];
    let x1214 = 0.07984262638800323 * s[157];
    let x1215 = x1213 + x1214;
    let x1216 = 0.0681920450746693 * s[158];
    let x1217 = 0.07984262638800323 * s[136];
    let x1218 = x1216 + x1217;
    let x1219 = x914 * x964;
    let x1220 = x343 * x1212;
    let x1221 = x1219 + x1220;
    let x1222 = x915 * x965;
    let x1223 = x344 * x1215;
    let x1224 = x1222 + x1223;
    let x1225 = x916 * x966;
    let x1226 = x345 * x1218;
    let x1227 = x1225 + x1226;
    let x1228 = x1221 + x1224;
    let x1229 = x1227 + x1228;
    let x1230 = x921 * x969;
    let x1232 = x347 * x1229;
    let x1233 = x1232 - x1230;
    let x1234 = x1233 - x1037;
    let x1235 = x1046 + s[133];
    let x1236 = s[132] + x1235;
    let x1240 = -x1190;
    let x1241 = -x1209;
    let x1242 = -x1234;
    let x1243 = -x1236;
    phi_q[26] = x613;
    phi_q[27] = x681;
    phi_t[3] = x756;
    gamma[3] = x1240;
    phi[4] = x278;
    phi_q[28] = x342;
    phi_q[29] = x353;
    phi_q[30] = x359;
    phi_q[31] = x462;
    phi_q[32] = x552;
    phi_q[33] = x621;
    phi_q[34] = x689;
    phi_t[4] = x757;
    gamma[4] = x1241;
    phi[5] = x306;
    phi_q[35] = x348;
    phi_q[36] = x354;
    phi_q[37] = x360;
    phi_q[38] = x479;
    phi_q[39] = x564;
    phi_q[40] = x632;
    phi_q[41] = x698;
    phi_t[5] = x758;
    gamma[5] = x1242;
    phi[6] = x309;
    phi_q[42] = s[58];
    phi_q[43] = s[59];
    phi_q[44] = s[66];
    phi_q[45] = s[60];
    phi_t[6] = 0.0;
    gamma[6] = x1243;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(q: &[f64], out: &mut [f64]) {
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    potential_into_part_0(q, out);
}
#[inline(never)]
fn potential_into_part_0(q: &[f64; 7], out: &mut [f64; 1]) {
    let x1254 = q[1] * 14.715;
    out[0] = x1254;
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
pub static PHI_Q_ROWS: [u32; 46usize] = [
    0u32, 0u32, 0u32, 0u32, 0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 1u32, 1u32, 1u32, 1u32,
    2u32, 2u32, 2u32, 2u32, 2u32, 2u32, 2u32, 3u32, 3u32, 3u32, 3u32, 3u32, 3u32, 3u32,
    4u32, 4u32, 4u32, 4u32, 4u32, 4u32, 4u32, 5u32, 5u32, 5u32, 5u32, 5u32, 5u32, 5u32,
    6u32, 6u32, 6u32, 6u32,
];
/// Column of each Φq nonzero.
pub static PHI_Q_COLS: [u32; 46usize] = [
    0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32,
    0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32,
    0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32,
    3u32, 4u32, 5u32, 6u32,
];
/// Bodies in coordinate order.
pub static BODIES: [BodyInfo; 1usize] = [
    BodyInfo {
        name: "platform",
        coord_offset: 0usize,
        rotation: Rotation::Quaternion,
        mass: 1.5f64,
        inertia: [0.004134375f64, 0.00826875f64, 0.004134375f64],
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
        point1: [0.2654788250422678f64, 0f64, -0.04920359188287982f64],
        point2: [0.06819204507466928f64, 0f64, -0.07984262638800324f64],
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
        point1: [-0.09012785199311818f64, 0f64, -0.2545132025948882f64],
        point2: [0.03504972021954594f64, 0f64, -0.09897735656467874f64],
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
        point1: [-0.17535097304914957f64, 0f64, -0.2053096107120084f64],
        point2: [-0.10324176529421522f64, 0f64, -0.01913473017667551f64],
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
        point1: [-0.17535097304914954f64, 0f64, 0.20530961071200843f64],
        point2: [-0.10324176529421523f64, 0f64, 0.019134730176675482f64],
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
        point1: [-0.09012785199311824f64, 0f64, 0.2545132025948882f64],
        point2: [0.03504972021954594f64, 0f64, 0.09897735656467874f64],
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
        point1: [0.2654788250422677f64, 0f64, 0.04920359188287992f64],
        point2: [0.0681920450746693f64, 0f64, 0.07984262638800323f64],
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
pub static Q0: [f64; 7usize] = [0f64, 0.3466575f64, 0f64, 1f64, 0f64, 0f64, 0f64];
/// Initial velocities from the file (to be projected onto the constraints).
pub static QD0: [f64; 7usize] = [0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64];
/// Constraint rows dependent on others at the initial pose (dropped by the solvers).
pub static REDUNDANT_ROWS: [u32; 0usize] = [];
/// Simulation end time suggested by the mechanism file (s).
pub const T_END: f64 = 2.5f64;
/// The platform held by six legs of driven length, for forward kinematics (`None`:
/// not such a mechanism).
pub const PLATFORM: Option<PlatformInfo> = Some(PlatformInfo {
    body: 0usize,
    legs: &[
        LegInfo {
            driver: "leg1",
            base: [0.2654788250422678f64, 0f64, -0.04920359188287982f64],
            platform: [0.06819204507466928f64, 0f64, -0.07984262638800324f64],
            row: 0usize,
        },
        LegInfo {
            driver: "leg2",
            base: [-0.09012785199311818f64, 0f64, -0.2545132025948882f64],
            platform: [0.03504972021954594f64, 0f64, -0.09897735656467874f64],
            row: 1usize,
        },
        LegInfo {
            driver: "leg3",
            base: [-0.17535097304914957f64, 0f64, -0.2053096107120084f64],
            platform: [-0.10324176529421522f64, 0f64, -0.01913473017667551f64],
            row: 2usize,
        },
        LegInfo {
            driver: "leg4",
            base: [-0.17535097304914954f64, 0f64, 0.20530961071200843f64],
            platform: [-0.10324176529421523f64, 0f64, 0.019134730176675482f64],
            row: 3usize,
        },
        LegInfo {
            driver: "leg5",
            base: [-0.09012785199311824f64, 0f64, 0.2545132025948882f64],
            platform: [0.03504972021954594f64, 0f64, 0.09897735656467874f64],
            row: 4usize,
        },
        LegInfo {
            driver: "leg6",
            base: [0.2654788250422677f64, 0f64, 0.04920359188287992f64],
            platform: [0.0681920450746693f64, 0f64, 0.07984262638800323f64],
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
        name: "hexapod_twist",
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
        let x87 = q[3] * q[3];
        let x88 = q[4] * q[4];
        let x89 = q[5] * q[5];
        let x90 = q[6] * q[6];
        let x101 = q[4] * q[5];
        let x103 = q[3] * q[6];
        let x108 = q[4] * q[6];
        let x110 = q[3] * q[5];
        let x114 = q[5] * q[6];
        let x116 = q[3] * q[4];
        let x310 = q[3] * 2.0;
        let x311 = q[4] * 2.0;
        let x312 = q[6] * 2.0;
        let x361 = q[5] * 2.0;
        let x362 = 2.0 * x310;
        let x480 = 2.0 * x311;
        let x633 = 2.0 * x312;
        let x1365 = 2.0 * x361;
        let x1368 = x311 * x480;
        let x1370 = 0.004134375 * x1368;
        let x1372 = x361 * x1365;
        let x1374 = 0.00826875 * x1372;
        let x1376 = x312 * x633;
        let x1378 = 0.004134375 * x1376;
        let x1380 = x1370 + x1374;
        let x1382 = x1378 + x1380;
        let x1384 = 0.5 * x1382;
        let x1386 = x87 * 0.02205;
        let x1387 = x1384 + x1386;
        let x1388 = x311 * x362;
        let x1389 = 0.004134375 * x1388;
        let x1390 = x361 * x633;
        let x1392 = 0.00826875 * x1390;
        let x1394 = x312 * x1365;
        let x1395 = 0.004134375 * x1394;
        let x1396 = x1389 - x1392;
        let x1397 = x1395 + x1396;
        let x1398 = 0.5 * x1397;
        let x1400 = x116 * 0.02205;
        let x1401 = x1400 - x1398;
        let x1402 = x311 * x633;
        let x1403 = 0.004134375 * x1402;
        let x1404 = x361 * x362;
        let x1405 = 0.00826875 * x1404;
        let x1406 = x312 * x480;
        let x1408 = 0.004134375 * x1406;
        let x1410 = x1403 + x1405;
        let x1411 = x1410 - x1408;
        let x1412 = 0.5 * x1411;
        let x1414 = x110 * 0.02205;
        let x1415 = x1414 - x1412;
        let x1416 = x311 * x1365;
        let x1418 = 0.004134375 * x1416;
        let x1420 = x361 * x480;
        let x1421 = 0.00826875 * x1420;
        let x1422 = x312 * x362;
        let x1423 = 0.004134375 * x1422;
        let x1424 = x1421 - x1418;
        let x1425 = x1423 + x1424;
        let x1426 = 0.5 * x1425;
        let x1428 = x103 * 0.02205;
        let x1429 = x1428 - x1426;
        let x1430 = x310 * x480;
        let x1432 = 0.004134375 * x1430;
        let x1435 = 0.00826875 * x1394;
        let x1437 = 0.004134375 * x1390;
        let x1439 = x1435 - x1432;
        let x1440 = x1439 - x1437;
        let x1441 = 0.5 * x1440;
        let x1442 = x1400 + x1441;
        let x1443 = x310 * x362;
        let x1444 = 0.004134375 * x1443;
        let x1445 = 0.00826875 * x1376;
        let x1447 = 0.004134375 * x1372;
        let x1448 = x1444 + x1445;
        let x1449 = x1447 + x1448;
        let x1450 = 0.5 * x1449;
        let x1451 = x88 * 0.02205;
        let x1452 = x1450 + x1451;
        let x1453 = x310 * x633;
        let x1454 = 0.004134375 * x1453;
        let x1455 = 0.00826875 * x1422;
        let x1458 = 0.004134375 * x1420;
        let x1460 = x1454 - x1455;
        let x1461 = x1460 - x1458;
        let x1462 = 0.5 * x1461;
        let x1463 = x101 * 0.02205;
        let x1464 = x1462 + x1463;
        let x1465 = x310 * x1365;
        let x1467 = 0.004134375 * x1465;
        let x1469 = 0.00826875 * x1406;
        let x1471 = 0.004134375 * x1404;
        let x1472 = x1467 + x1469;
        let x1474 = x1471 - x1472;
        let x1475 = 0.5 * x1474;
        let x1476 = x108 * 0.02205;
        let x1477 = x1475 + x1476;
        let x1478 = 0.00826875 * x1465;
        let x1482 = x1408 + x1478;
        let x1484 = x1403 - x1482;
        let x1485 = 0.5 * x1484;
        let x1486 = x1414 + x1485;
        let x1488 = 0.00826875 * x1453;
        let x1490 = x1423 - x1488;
        let x1491 = x1490 - x1418;
        let x1492 = 0.5 * x1491;
        let x1493 = x1463 + x1492;
        let x1494 = 0.00826875 * x1443;
        let x1495 = x1378 + x1494;
        let x1496 = x1370 + x1495;
        let x1497 = 0.5 * x1496;
        let x1498 = x89 * 0.02205;
        let x1499 = x1497 + x1498;
        let x1501 = 0.00826875 * x1430;
        let x1503 = x1501 - x1395;
        let x1504 = x1503 - x1389;
        let x1505 = 0.5 * x1504;
        let x1506 = x114 * 0.02205;
        let x1507 = x1505 + x1506;
        let x1508 = 0.00826875 * x1416;
        let x1511 = x1458 - x1508;
        let x1512 = x1511 - x1454;
        let x1513 = 0.5 * x1512;
        let x1514 = x1428 + x1513;
        let x1516 = 0.00826875 * x1402;
        let x1518 = x1471 + x1516;
        let x1520 = x1467 - x1518;
        let x1521 = 0.5 * x1520;
        let x1522 = x1476 + x1521;
        let x1523 = 0.00826875 * x1388;
        let x1524 = x1523 - x1437;
        let x1525 = x1524 - x1432;
        let x1526 = 0.5 * x1525;
        let x1527 = x1506 + x1526;
        let x1529 = 0.00826875 * x1368;
        let x1530 = x1447 + x1529;
        let x1531 = x1444 + x1530;
        let x1532 = 0.5 * x1531;
        let x1533 = x90 * 0.02205;
        let x1534 = x1532 + x1533;
        out[0] = 1.5;
        out[1] = 1.5;
        out[2] = 1.5;
        out[3] = x1387;
        out[4] = x1401;
        out[5] = x1415;
        out[6] = x1429;
        out[7] = x1442;
        out[8] = x1452;
        out[9] = x1464;
        out[10] = x1477;
        out[11] = x1486;
        out[12] = x1493;
        out[13] = x1499;
        out[14] = x1507;
        out[15] = x1514;
        out[16] = x1522;
        out[17] = x1527;
        out[18] = x1534;
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
        let x310 = q[3] * 2.0;
        let x311 = q[4] * 2.0;
        let x312 = q[6] * 2.0;
        let x361 = q[5] * 2.0;
        let x774 = q[5] * qd[4];
        let x775 = q[4] * qd[5];
        let x778 = q[6] * qd[3];
        let x779 = q[3] * qd[6];
        let x782 = q[6] * qd[4];
        let x783 = q[4] * qd[6];
        let x786 = q[5] * qd[3];
        let x787 = q[3] * qd[5];
        let x792 = q[6] * qd[5];
        let x793 = q[5] * qd[6];
        let x796 = q[4] * qd[3];
        let x797 = q[3] * qd[4];
        let x926 = 2.0 * qd[3];
        let x927 = 2.0 * qd[4];
        let x928 = 2.0 * qd[6];
        let x971 = 2.0 * qd[5];
        let x1052 = qd[4] * qd[5];
        let x1055 = qd[3] * qd[6];
        let x1058 = qd[4] * qd[6];
        let x1061 = qd[3] * qd[5];
        let x1258 = x797 - x796;
        let x1259 = x792 + x1258;
        let x1260 = x1259 - x793;
        let x1261 = 2.0 * x1260;
        let x1264 = x782 + x786;
        let x1266 = x787 - x1264;
        let x1267 = x783 + x1266;
        let x1268 = 2.0 * x1267;
        let x1271 = x774 - x778;
        let x1272 = x1271 - x775;
        let x1273 = x779 + x1272;
        let x1274 = 2.0 * x1273;
        let x1295 = 2.0 * x1261;
        let x1297 = 2.0 * x1268;
        let x1299 = 2.0 * x1274;
        let x1537 = x1058 + x1061;
        let x1539 = x1061 - x1537;
        let x1540 = x1058 + x1539;
        let x1541 = 2.0 * x1540;
        let x1544 = x1052 - x1055;
        let x1545 = x1544 - x1052;
        let x1546 = x1055 + x1545;
        let x1547 = 2.0 * x1546;
        let x1548 = 2.0 * x1541;
        let x1549 = 2.0 * x1547;
        let x1550 = x927 * x1295;
        let x1551 = 0.004134375 * x1550;
        let x1552 = x971 * x1297;
        let x1553 = x361 * x1548;
        let x1554 = x1552 + x1553;
        let x1555 = 0.00826875 * x1554;
        let x1556 = x928 * x1299;
        let x1557 = x312 * x1549;
        let x1558 = x1556 + x1557;
        let x1559 = 0.004134375 * x1558;
        let x1560 = x1551 + x1555;
        let x1561 = x1559 + x1560;
        let x1562 = 0.5 * x1561;
        let x1564 = x926 * x1295;
        let x1565 = 0.004134375 * x1564;
        let x1566 = x928 * x1297;
        let x1567 = x312 * x1548;
        let x1568 = x1566 + x1567;
        let x1569 = 0.00826875 * x1568;
        let x1571 = x971 * x1299;
        let x1572 = x361 * x1549;
        let x1573 = x1571 + x1572;
        let x1574 = 0.004134375 * x1573;
        let x1575 = x1565 - x1569;
        let x1576 = x1574 + x1575;
        let x1577 = 0.5 * x1576;
        let x1578 = x928 * x1295;
        let x1579 = 0.004134375 * x1578;
        let x1580 = x926 * x1297;
        let x1581 = x310 * x1548;
        let x1582 = x1580 + x1581;
        let x1583 = 0.00826875 * x1582;
        let x1584 = x927 * x1299;
        let x1585 = x311 * x1549;
        let x1586 = x1584 + x1585;
        let x1587 = 0.004134375 * x1586;
        let x1589 = x1579 + x1583;
        let x1590 = x1589 - x1587;
        let x1591 = 0.5 * x1590;
        let x1592 = x971 * x1295;
        let x1593 = 0.004134375 * x1592;
        let x1595 = x927 * x1297;
        let x1596 = x311 * x1548;
        let x1597 = x1595 + x1596;
        let x1598 = 0.00826875 * x1597;
        let x1599 = x926 * x1299;
        let x1600 = x310 * x1549;
        let x1601 = x1599 + x1600;
        let x1602 = 0.004134375 * x1601;
        let x1603 = x1598 - x1593;
        let x1604 = x1602 + x1603;
        let x1605 = 0.5 * x1604;
        let x1606 = qd[3] * qd[3];
        let x1607 = qd[4] * qd[4];
        let x1608 = qd[5] * qd[5];
        let x1609 = qd[6] * qd[6];
        let x1610 = x1606 + x1607;
        let x1611 = x1608 + x1610;
        let x1612 = x1609 + x1611;
        let x1613 = 0.00826875 * x1552;
        let x1614 = 0.004134375 * x1556;
        let x1615 = x1551 + x1613;
        let x1616 = x1614 + x1615;
        let x1617 = 0.5 * x1616;
        let x1618 = x1562 + x1617;
        let x1619 = q[3] * 0.02205;
        let x1620 = x1612 * x1619;
        let x1622 = x1618 - x1620;
        let x1629 = 0.00826875 * x1566;
        let x1631 = 0.004134375 * x1571;
        let x1633 = x1629 - x1565;
        let x1634 = x1633 - x1631;
        let x1635 = 0.5 * x1634;
        let x1637 = x1635 - x1577;
        let x1638 = q[4] * 0.02205;
        let x1639 = x1612 * x1638;
        let x1641 = x1637 - x1639;
        let x1647 = 0.00826875 * x1580;
        let x1649 = 0.004134375 * x1584;
        let x1650 = x1579 + x1647;
        let x1652 = x1649 - x1650;
        let x1653 = 0.5 * x1652;
        let x1655 = x1653 - x1591;
        let x1656 = q[5] * 0.02205;
        let x1657 = x1612 * x1656;
        let x1659 = x1655 - x1657;
        let x1663 = 0.00826875 * x1595;
        let x1666 = 0.004134375 * x1599;
        let x1668 = x1593 - x1663;
        let x1669 = x1668 - x1666;
        let x1670 = 0.5 * x1669;
        let x1672 = x1670 - x1605;
        let x1673 = q[6] * 0.02205;
        let x1674 = x1612 * x1673;
        let x1676 = x1672 - x1674;
        out[0] = 0.0;
        out[1] = -14.715;
        out[2] = 0.0;
        out[3] = x1622;
        out[4] = x1641;
        out[5] = x1659;
        out[6] = x1676;
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
        let phi_q: &mut [f64; 46] = phi_q
            .try_into()
            .expect("phi_q must have 46 entries");
        let mass: &mut [f64; 19] = mass.try_into().expect("mass must have 19 entries");
        let force: &mut [f64; 7] = force.try_into().expect("force must have 7 entries");
        let mut s = [0.0f64; 35];
        eval_newton_shared_0(q, qd, t, &mut s);
        eval_newton_part_0(q, t, &s, phi, phi_q, mass);
        eval_newton_part_1(q, qd, &s, mass, force);
    }
    #[inline(never)]
    fn eval_newton_shared_0(q: &[f64; 7], _qd: &[f64; 7], _t: f64, s: &mut [f64; 35]) {
        let x90 = q[6] * q[6];
        s[0] = x90;
        let x103 = q[3] * q[6];
        s[1] = x103;
        let x108 = q[4] * q[6];
        s[2] = x108;
        let x114 = q[5] * q[6];
        s[3] = x114;
        let x310 = q[3] * 2.0;
        s[4] = x310;
        let x311 = q[4] * 2.0;
        s[5] = x311;
        let x312 = q[6] * 2.0;
        s[6] = x312;
        let x361 = q[5] * 2.0;
        s[7] = x361;
        let x362 = 2.0 * x310;
        s[8] = x362;
        let x480 = 2.0 * x311;
        s[9] = x480;
        let x633 = 2.0 * x312;
        s[10] = x633;
        let x1365 = 2.0 * x361;
        s[11] = x1365;
        let x1368 = x311 * x480;
        s[12] = x1368;
        let x1372 = x361 * x1365;
        s[13] = x1372;
        let x1388 = x311 * x362;
        s[14] = x1388;
        let x1390 = x361 * x633;
        s[15] = x1390;
        let x1402 = x311 * x633;
        s[16] = x1402;
        let x1404 = x361 * x362;
        s[17] = x1404;
        let x1416 = x311 * x1365;
        s[18] = x1416;
        let x1420 = x361 * x480;
        s[19] = x1420;
        let x1428 = x103 * 0.02205;
        s[20] = x1428;
        let x1430 = x310 * x480;
        s[21] = x1430;
        let x1432 = 0.004134375 * x1430;
        s[22] = x1432;
        let x1437 = 0.004134375 * x1390;
        s[23] = x1437;
        let x1443 = x310 * x362;
        s[24] = x1443;
        let x1444 = 0.004134375 * x1443;
        s[25] = x1444;
        let x1447 = 0.004134375 * x1372;
        s[26] = x1447;
        let x1453 = x310 * x633;
        s[27] = x1453;
        let x1454 = 0.004134375 * x1453;
        s[28] = x1454;
        let x1458 = 0.004134375 * x1420;
        s[29] = x1458;
        let x1465 = x310 * x1365;
        s[30] = x1465;
        let x1467 = 0.004134375 * x1465;
        s[31] = x1467;
        let x1471 = 0.004134375 * x1404;
        s[32] = x1471;
        let x1476 = x108 * 0.02205;
        s[33] = x1476;
        let x1506 = x114 * 0.02205;
        s[34] = x1506;
    }
    #[inline(never)]
    fn eval_newton_part_0(
        q: &[f64; 7],
        t: f64,
        s: &[f64; 35],
        phi: &mut [f64; 7],
        phi_q: &mut [f64; 46],
        mass: &mut [f64; 19],
    ) {
        let x7 = 0.8726646259971648 * t;
        let x8 = 0.8639379797371931 + x7;
        let x12 = x8 - 0.1832595714594046;
        let x13 = x12.cos();
        let x14 = 0.0567 * x13;
        let x16 = 0.20409642230625002 - x14;
        let x17 = x16.sqrt();
        let x20 = x7 + 1.2304571226560024;
        let x24 = x20 - 1.911135530933791;
        let x25 = x24.cos();
        let x26 = 0.0567 * x25;
        let x28 = 0.20409642230625002 - x26;
        let x29 = x28.sqrt();
        let x32 = x7 + 2.9583330821303884;
        let x36 = x32 - 2.2776546738526;
        let x37 = x36.cos();
        let x38 = 0.0567 * x37;
        let x40 = 0.20409642230625002 - x38;
        let x41 = x40.sqrt();
        let x44 = x7 + 3.324852225049198;
        let x48 = x44 - 4.005530633326987;
        let x49 = x48.cos();
        let x50 = 0.0567 * x49;
        let x52 = 0.20409642230625002 - x50;
        let x53 = x52.sqrt();
        let x56 = x7 + 5.052728184523584;
        let x60 = x56 - 4.372049776245795;
        let x61 = x60.cos();
        let x62 = 0.0567 * x61;
        let x64 = 0.20409642230625002 - x62;
        let x65 = x64.sqrt();
        let x68 = x7 + 5.419247327442394;
        let x72 = x68 - 6.0999257357201815;
        let x73 = x72.cos();
        let x74 = 0.0567 * x73;
        let x76 = 0.20409642230625002 - x74;
        let x77 = x76.sqrt();
        let x87 = q[3] * q[3];
        let x88 = q[4] * q[4];
        let x89 = q[5] * q[5];
        let x91 = x87 + x88;
        let x92 = 2.0 * x91;
        let x94 = x92 - 1.0;
        let x98 = x87 + s[0];
        let x99 = 2.0 * x98;
        let x100 = x99 - 1.0;
        let x101 = q[4] * q[5];
        let x102 = 2.0 * x101;
        let x105 = 2.0 * s[1];
        let x109 = 2.0 * s[2];
        let x110 = q[3] * q[5];
        let x111 = 2.0 * x110;
        let x112 = x109 + x111;
        let x113 = x102 + x105;
        let x115 = 2.0 * s[3];
        let x116 = q[3] * q[4];
        let x118 = 2.0 * x116;
        let x120 = x115 - x118;
        let x123 = x109 - x111;
        let x130 = x94 * 0.06819204507466928;
        let x132 = x112 * 0.07984262638800324;
        let x134 = x130 - x132;
        let x135 = x113 * 0.06819204507466928;
        let x136 = x120 * 0.07984262638800324;
        let x138 = x135 - x136;
        let x139 = x123 * 0.06819204507466928;
        let x140 = x100 * 0.07984262638800324;
        let x142 = x139 - x140;
        let x143 = q[0] + x134;
        let x144 = q[1] + x138;
        let x145 = q[2] + x142;
        let x147 = x143 - 0.2654788250422678;
        let x149 = x145 + 0.04920359188287982;
        let x150 = x147 * x147;
        let x151 = x144 * x144;
        let x152 = x149 * x149;
        let x153 = x150 + x151;
        let x154 = x152 + x153;
        let x155 = x154.sqrt();
        let x157 = x155 - x17;
        let x162 = x94 * 0.03504972021954594;
        let x164 = x112 * 0.09897735656467874;
        let x166 = x162 - x164;
        let x167 = x113 * 0.03504972021954594;
        let x168 = x120 * 0.09897735656467874;
        let x170 = x167 - x168;
        let x171 = x123 * 0.03504972021954594;
        let x172 = x100 * 0.09897735656467874;
        let x174 = x171 - x172;
        let x175 = q[0] + x166;
        let x176 = q[1] + x170;
        let x177 = q[2] + x174;
        let x179 = x175 + 0.09012785199311818;
        let x181 = x177 + 0.2545132025948882;
        let x182 = x179 * x179;
        let x183 = x176 * x176;
        let x184 = x181 * x181;
        let x185 = x182 + x183;
        let x186 = x184 + x185;
        let x187 = x186.sqrt();
        let x189 = x187 - x29;
        let x195 = x94 * 0.10324176529421522;
        let x198 = x112 * 0.01913473017667551;
        let x200 = x195 + x198;
        let x202 = x113 * 0.10324176529421522;
        let x204 = x120 * 0.01913473017667551;
        let x206 = x202 + x204;
        let x208 = x123 * 0.10324176529421522;
        let x210 = x100 * 0.01913473017667551;
        let x212 = x208 + x210;
        let x214 = q[0] - x200;
        let x215 = q[1] - x206;
        let x216 = q[2] - x212;
        let x218 = x214 + 0.17535097304914957;
        let x220 = x216 + 0.2053096107120084;
        let x221 = x218 * x218;
        let x222 = x215 * x215;
        let x223 = x220 * x220;
        let x224 = x221 + x222;
        let x225 = x223 + x224;
        let x226 = x225.sqrt();
        let x228 = x226 - x41;
        let x234 = x94 * 0.10324176529421523;
        let x236 = x112 * 0.019134730176675482;
        let x237 = x236 - x234;
        let x238 = x113 * 0.10324176529421523;
        let x240 = x120 * 0.019134730176675482;
        let x241 = x240 - x238;
        let x242 = x123 * 0.10324176529421523;
        let x244 = x100 * 0.019134730176675482;
        let x245 = x244 - x242;
        let x246 = q[0] + x237;
        let x247 = q[1] + x241;
        let x248 = q[2] + x245;
        let x250 = x246 + 0.17535097304914954;
        let x252 = x248 - 0.20530961071200843;
        let x253 = x250 * x250;
        let x254 = x247 * x247;
        let x255 = x252 * x252;
        let x256 = x253 + x254;
        let x257 = x255 + x256;
        let x258 = x257.sqrt();
        let x260 = x258 - x53;
        let x262 = x162 + x164;
        let x263 = x167 + x168;
        let x264 = x171 + x172;
        let x265 = q[0] + x262;
        let x266 = q[1] + x263;
        let x267 = q[2] + x264;
        let x269 = x265 + 0.09012785199311824;
        let x270 = x267 - 0.2545132025948882;
        let x271 = x269 * x269;
        let x272 = x266 * x266;
        let x273 = x270 * x270;
        let x274 = x271 + x272;
        let x275 = x273 + x274;
        let x276 = x275.sqrt();
        let x278 = x276 - x65;
        let x283 = x94 * 0.0681920450746693;
        let x284 = x112 * 0.07984262638800323;
        let x285 = x283 + x284;
        let x286 = x113 * 0.0681920450746693;
        let x287 = x120 * 0.07984262638800323;
        let x288 = x286 + x287;
        let x289 = x123 * 0.0681920450746693;
        let x290 = x100 * 0.07984262638800323;
        let x291 = x289 + x290;
        let x292 = q[0] + x285;
        let x293 = q[1] + x288;
        let x294 = q[2] + x291;
        let x296 = x292 - 0.2654788250422677;
        let x298 = x294 - 0.04920359188287992;
        let x299 = x296 * x296;
        let x300 = x293 * x293;
        let x301 = x298 * x298;
        let x302 = x299 + x300;
        let x303 = x301 + x302;
        let x304 = x303.sqrt();
        let x306 = x304 - x77;
        let x307 = x89 + x91;
        let x308 = s[0] + x307;
        let x309 = x308 - 1.0;
        let x313 = 2.0 * x147;
        let x314 = 2.0 * x144;
        let x315 = 2.0 * x149;
        let x316 = 2.0 * x155;
        let x317 = 1.0 / x316;
        let x318 = x313 * x317;
        let x319 = 2.0 * x179;
        let x320 = 2.0 * x176;
        let x321 = 2.0 * x181;
        let x322 = 2.0 * x187;
        let x323 = 1.0 / x322;
        let x324 = x319 * x323;
        let x325 = 2.0 * x218;
        let x326 = 2.0 * x215;
        let x327 = 2.0 * x220;
        let x328 = 2.0 * x226;
        let x329 = 1.0 / x328;
        let x330 = x325 * x329;
        let x331 = 2.0 * x250;
        let x332 = 2.0 * x247;
        let x333 = 2.0 * x252;
        let x334 = 2.0 * x258;
        let x335 = 1.0 / x334;
        let x336 = x331 * x335;
        let x337 = 2.0 * x269;
        let x338 = 2.0 * x266;
        let x339 = 2.0 * x270;
        let x340 = 2.0 * x276;
        let x341 = 1.0 / x340;
        let x342 = x337 * x341;
        let x343 = 2.0 * x296;
        let x344 = 2.0 * x293;
        let x345 = 2.0 * x298;
        let x346 = 2.0 * x304;
        let x347 = 1.0 / x346;
        let x348 = x343 * x347;
        let x349 = x314 * x317;
        let x350 = x320 * x323;
        let x351 = x326 * x329;
        let x352 = x332 * x335;
        let x353 = x338 * x341;
        let x354 = x344 * x347;
        let x355 = x315 * x317;
        let x356 = x321 * x323;
        let x357 = x327 * x329;
        let x358 = x333 * x335;
        let x359 = x339 * x341;
        let x360 = x345 * x347;
        let x365 = 0.06819204507466928 * s[8];
        let x366 = 0.07984262638800324 * s[7];
        let x368 = x365 - x366;
        let x369 = 0.06819204507466928 * s[6];
        let x370 = 0.07984262638800324 * s[5];
        let x372 = x369 + x370;
        let x373 = 0.06819204507466928 * s[7];
        let x375 = 0.07984262638800324 * s[8];
        let x377 = x373 + x375;
        let x379 = x313 * x368;
        let x380 = x314 * x372;
        let x381 = x315 * x377;
        let x383 = x379 + x380;
        let x384 = x383 - x381;
        let x385 = x317 * x384;
        let x386 = 0.03504972021954594 * s[8];
        let x387 = 0.09897735656467874 * s[7];
        let x389 = x386 - x387;
        let x390 = 0.03504972021954594 * s[6];
        let x391 = 0.09897735656467874 * s[5];
        let x393 = x390 + x391;
        let x394 = 0.03504972021954594 * s[7];
        let x396 = 0.09897735656467874 * s[8];
        let x398 = x394 + x396;
        let x400 = x319 * x389;
        let x401 = x320 * x393;
        let x402 = x321 * x398;
        let x404 = x400 + x401;
        let x405 = x404 - x402;
        let x406 = x323 * x405;
        let x407 = 0.10324176529421522 * s[8];
        let x408 = 0.01913473017667551 * s[7];
        let x409 = x407 + x408;
        let x411 = 0.10324176529421522 * s[6];
        let x412 = 0.01913473017667551 * s[5];
        let x414 = x411 - x412;
        let x416 = 0.10324176529421522 * s[7];
        let x418 = 0.01913473017667551 * s[8];
        let x419 = x418 - x416;
        let x421 = x325 * x409;
        let x423 = x326 * x414;
        let x425 = x327 * x419;
        let x427 = x421 + x423;
        let x429 = x425 + x427;
        let x431 = x329 * x429;
        let x432 = -x431;
        let x433 = 0.10324176529421523 * s[8];
        let x435 = 0.019134730176675482 * s[7];
        let x436 = x435 - x433;
        let x437 = 0.10324176529421523 * s[6];
        let x439 = 0.019134730176675482 * s[5];
        let x441 = x437 + x439;
        let x443 = 0.10324176529421523 * s[7];
        let x445 = 0.019134730176675482 * s[8];
        let x446 = x443 + x445;
        let x447 = x331 * x436;
        let x448 = x332 * x441;
        let x450 = x333 * x446;
        let x451 = x447 - x448;
        let x452 = x450 + x451;
        let x453 = x335 * x452;
        let x454 = x386 + x387;
        let x455 = x390 - x391;
        let x456 = x396 - x394;
        let x457 = x337 * x454;
        let x458 = x338 * x455;
        let x459 = x339 * x456;
        let x460 = x457 + x458;
        let x461 = x459 + x460;
        let x462 = x341 * x461;
        let x463 = 0.0681920450746693 * s[8];
        let x464 = 0.07984262638800323 * s[7];
        let x465 = x463 + x464;
        let x466 = 0.0681920450746693 * s[6];
        let x467 = 0.07984262638800323 * s[5];
        let x469 = x466 - x467;
        let x470 = 0.0681920450746693 * s[7];
        let x472 = 0.07984262638800323 * s[8];
        let x473 = x472 - x470;
        let x474 = x343 * x465;
        let x475 = x344 * x469;
        let x476 = x345 * x473;
        let x477 = x474 + x475;
        let x478 = x476 + x477;
        let x479 = x347 * x478;
        let x482 = 0.06819204507466928 * s[9];
        let x483 = 0.07984262638800324 * s[6];
        let x485 = x482 - x483;
        let x486 = 0.07984262638800324 * s[4];
        let x488 = x373 + x486;
        let x489 = x313 * x485;
        let x490 = x314 * x488;
        let x491 = x315 * x369;
        let x492 = x489 + x490;
        let x493 = x491 + x492;
        let x494 = x317 * x493;
        let x495 = 0.03504972021954594 * s[9];
        let x496 = 0.09897735656467874 * s[6];
        let x498 = x495 - x496;
        let x499 = 0.09897735656467874 * s[4];
        let x501 = x394 + x499;
        let x502 = x319 * x498;
        let x503 = x320 * x501;
        let x504 = x321 * x390;
        let x505 = x502 + x503;
        let x506 = x504 + x505;
        let x507 = x323 * x506;
        let x508 = 0.10324176529421522 * s[9];
        let x509 = 0.01913473017667551 * s[6];
        let x510 = x508 + x509;
        let x512 = 0.01913473017667551 * s[4];
        let x514 = x416 - x512;
        let x517 = x325 * x510;
        let x519 = x326 * x514;
        let x521 = x327 * x411;
        let x523 = x517 + x519;
        let x525 = x521 + x523;
        let x527 = x329 * x525;
        let x528 = -x527;
        let x529 = 0.10324176529421523 * s[9];
        let x531 = 0.019134730176675482 * s[6];
        let x532 = x531 - x529;
        let x533 = 0.019134730176675482 * s[4];
        let x535 = x443 + x533;
        let x537 = x331 * x532;
        let x538 = x332 * x535;
        let x540 = x333 * x437;
        let x542 = x537 - x538;
        let x543 = x542 - x540;
        let x544 = x335 * x543;
        let x545 = x495 + x496;
        let x546 = x394 - x499;
        let x547 = x337 * x545;
        let x548 = x338 * x546;
        let x549 = x339 * x390;
        let x550 = x547 + x548;
        let x551 = x549 + x550;
        let x552 = x341 * x551;
        let x553 = 0.0681920450746693 * s[9];
        let x554 = 0.07984262638800323 * s[6];
        let x555 = x553 + x554;
        let x556 = 0.07984262638800323 * s[4];
        let x558 = x470 - x556;
        let x559 = x343 * x555;
        let x560 = x344 * x558;
        let x561 = x345 * x466;
        let x562 = x559 + x560;
        let x563 = x561 + x562;
        let x564 = x347 * x563;
        let x565 = 0.06819204507466928 * s[5];
        let x566 = x565 - x483;
        let x567 = 0.06819204507466928 * s[4];
        let x569 = x313 * x486;
        let x571 = x314 * x566;
        let x572 = x315 * x567;
        let x574 = x571 - x569;
        let x575 = x574 - x572;
        let x576 = x317 * x575;
        let x577 = 0.03504972021954594 * s[5];
        let x578 = x577 - x496;
        let x579 = 0.03504972021954594 * s[4];
        let x581 = x319 * x499;
        let x583 = x320 * x578;
        let x584 = x321 * x579;
        let x586 = x583 - x581;
        let x587 = x586 - x584;
        let x588 = x323 * x587;
        let x589 = 0.10324176529421522 * s[5];
        let x590 = x509 + x589;
        let x592 = 0.10324176529421522 * s[4];
        let x594 = x325 * x512;
        let x596 = x326 * x590;
        let x598 = x327 * x592;
        let x599 = x594 + x596;
        let x601 = x598 - x599;
        let x602 = x329 * x601;
        let x603 = 0.10324176529421523 * s[5];
        let x605 = x531 - x603;
        let x606 = 0.10324176529421523 * s[4];
        let x608 = x331 * x533;
        let x609 = x332 * x605;
        let x610 = x333 * x606;
        let x611 = x608 + x609;
        let x612 = x610 + x611;
        let x613 = x335 * x612;
        let x614 = x496 + x577;
        let x615 = x337 * x499;
        let x616 = x338 * x614;
        let x617 = x339 * x579;
        let x619 = x615 + x616;
        let x620 = x619 - x617;
        let x621 = x341 * x620;
        let x622 = 0.0681920450746693 * s[5];
        let x623 = x554 + x622;
        let x624 = 0.0681920450746693 * s[4];
        let x626 = x343 * x556;
        let x627 = x344 * x623;
        let x628 = x345 * x624;
        let x630 = x626 + x627;
        let x631 = x630 - x628;
        let x632 = x347 * x631;
        let x634 = x567 - x366;
        let x635 = 0.07984262638800324 * s[10];
        let x637 = x565 - x635;
        let x638 = x313 * x370;
        let x640 = x314 * x634;
        let x641 = x315 * x637;
        let x642 = x640 - x638;
        let x643 = x641 + x642;
        let x644 = x317 * x643;
        let x645 = x579 - x387;
        let x646 = 0.09897735656467874 * s[10];
        let x648 = x577 - x646;
        let x649 = x319 * x391;
        let x651 = x320 * x645;
        let x652 = x321 * x648;
        let x653 = x651 - x649;
        let x654 = x652 + x653;
        let x655 = x323 * x654;
        let x656 = x408 + x592;
        let x658 = 0.01913473017667551 * s[10];
        let x659 = x589 + x658;
        let x661 = x325 * x412;
        let x663 = x326 * x656;
        let x665 = x327 * x659;
        let x667 = x661 + x663;
        let x669 = x665 + x667;
        let x671 = x329 * x669;
        let x672 = -x671;
        let x673 = x435 - x606;
        let x674 = 0.019134730176675482 * s[10];
        let x675 = x674 - x603;
        let x676 = x331 * x439;
        let x677 = x332 * x673;
        let x678 = x333 * x675;
        let x679 = x676 + x677;
        let x680 = x678 + x679;
        let x681 = x335 * x680;
        let x682 = x387 + x579;
        let x683 = x577 + x646;
        let x684 = x337 * x391;
        let x685 = x338 * x682;
        let x686 = x339 * x683;
        let x687 = x684 + x685;
        let x688 = x686 + x687;
        let x689 = x341 * x688;
        let x690 = x464 + x624;
        let x691 = 0.07984262638800323 * s[10];
        let x692 = x622 + x691;
        let x693 = x343 * x467;
        let x694 = x344 * x690;
        let x695 = x345 * x692;
        let x696 = x693 + x694;
        let x697 = x695 + x696;
        let x698 = x347 * x697;
        let x1370 = 0.004134375 * s[12];
        let x1374 = 0.00826875 * s[13];
        let x1376 = s[6] * s[10];
        let x1378 = 0.004134375 * x1376;
        let x1380 = x1370 + x1374;
        let x1382 = x1378 + x1380;
        let x1384 = 0.5 * x1382;
        let x1386 = x87 * 0.02205;
        let x1387 = x1384 + x1386;
        let x1389 = 0.004134375 * s[14];
        let x1392 = 0.00826875 * s[15];
        let x1394 = s[6] * s[11];
        let x1395 = 0.004134375 * x1394;
        let x1396 = x1389 - x1392;
        let x1397 = x1395 + x1396;
        let x1398 = 0.5 * x1397;
        let x1400 = x116 * 0.02205;
        let x1401 = x1400 - x1398;
        let x1403 = 0.004134375 * s[16];
        let x1405 = 0.00826875 * s[17];
        let x1406 = s[6] * s[9];
        let x1408 = 0.004134375 * x1406;
        let x1410 = x1403 + x1405;
        let x1411 = x1410 - x1408;
        let x1412 = 0.5 * x1411;
        let x1414 = x110 * 0.02205;
        let x1415 = x1414 - x1412;
        let x1418 = 0.004134375 * s[18];
        let x1421 = 0.00826875 * s[19];
        let x1422 = s[6] * s[8];
        let x1423 = 0.004134375 * x1422;
        let x1424 = x1421 - x1418;
        let x1425 = x1423 + x1424;
        let x1426 = 0.5 * x1425;
        let x1429 = s[20] - x1426;
        let x1435 = 0.00826875 * x1394;
        let x1439 = x1435 - s[22];
        let x1440 = x1439 - s[23];
        let x1441 = 0.5 * x1440;
        let x1442 = x1400 + x1441;
        let x1445 = 0.00826875 * x1376;
        let x1448 = s[25] + x1445;
        let x1449 = s[26] + x1448;
        let x1450 = 0.5 * x1449;
        let x1451 = x88 * 0.02205;
        let x1452 = x1450 + x1451;
        let x1455 = 0.00826875 * x1422;
        let x1460 = s[28] - x1455;
        let x1461 = x1460 - s[29];
        let x1462 = 0.5 * x1461;
        let x1463 = x101 * 0.02205;
        let x1464 = x1462 + x1463;
        let x1469 = 0.00826875 * x1406;
        let x1472 = s[31] + x1469;
        let x1474 = s[32] - x1472;
        let x1475 = 0.5 * x1474;
        let x1477 = x1475 + s[33];
        let x1478 = 0.00826875 * s[30];
        let x1482 = x1408 + x1478;
        let x1484 = x1403 - x1482;
        let x1485 = 0.5 * x1484;
        let x1486 = x1414 + x1485;
        let x1488 = 0.00826875 * s[27];
        let x1490 = x1423 - x1488;
        let x1491 = x1490 - x1418;
        let x1492 = 0.5 * x1491;
        let x1493 = x1463 + x1492;
        let x1494 = 0.00826875 * s[24];
        let x1495 = x1378 + x1494;
        let x1496 = x1370 + x1495;
        let x1497 = 0.5 * x1496;
        let x1498 = x89 * 0.02205;
        let x1499 = x1497 + x1498;
        let x1501 = 0.00826875 * s[21];
        let x1503 = x1501 - x1395;
        let x1504 = x1503 - x1389;
        let x1505 = 0.5 * x1504;
        let x1507 = x1505 + s[34];
        phi[0] = x157;
        phi_q[0] = x318;
        phi_q[1] = x349;
        phi_q[2] = x355;
        phi_q[3] = x385;
        phi_q[4] = x494;
        phi_q[5] = x576;
        phi_q[6] = x644;
        phi[1] = x189;
        phi_q[7] = x324;
        phi_q[8] = x350;
        phi_q[9] = x356;
        phi_q[10] = x406;
        phi_q[11] = x507;
        phi_q[12] = x588;
        phi_q[13] = x655;
        phi[2] = x228;
        phi_q[14] = x330;
        phi_q[15] = x351;
        phi_q[16] = x357;
        phi_q[17] = x432;
        phi_q[18] = x528;
        phi_q[19] = x602;
        phi_q[20] = x672;
        phi[3] = x260;
        phi_q[21] = x336;
        phi_q[22] = x352;
        phi_q[23] = x358;
        phi_q[24] = x453;
        phi_q[25] = x544;
        phi_q[26] = x613;
        phi_q[27] = x681;
        phi[4] = x278;
        phi_q[28] = x342;
        phi_q[29] = x353;
        phi_q[30] = x359;
        phi_q[31] = x462;
        phi_q[32] = x552;
        phi_q[33] = x621;
        phi_q[34] = x689;
        phi[5] = x306;
        phi_q[35] = x348;
        phi_q[36] = x354;
        phi_q[37] = x360;
        phi_q[38] = x479;
        phi_q[39] = x564;
        phi_q[40] = x632;
        phi_q[41] = x698;
        phi[6] = x309;
        phi_q[42] = s[4];
        phi_q[43] = s[5];
        phi_q[44] = s[7];
        phi_q[45] = s[6];
        mass[0] = 1.5;
        mass[1] = 1.5;
        mass[2] = 1.5;
        mass[3] = x1387;
        mass[4] = x1401;
        mass[5] = x1415;
        mass[6] = x1429;
        mass[7] = x1442;
        mass[8] = x1452;
        mass[9] = x1464;
        mass[10] = x1477;
        mass[11] = x1486;
        mass[12] = x1493;
        mass[13] = x1499;
        mass[14] = x1507;
    }
    #[inline(never)]
    fn eval_newton_part_1(
        q: &[f64; 7],
        qd: &[f64; 7],
        s: &[f64; 35],
        mass: &mut [f64; 19],
        force: &mut [f64; 7],
    ) {
        let x774 = q[5] * qd[4];
        let x775 = q[4] * qd[5];
        let x778 = q[6] * qd[3];
        let x779 = q[3] * qd[6];
        let x782 = q[6] * qd[4];
        let x783 = q[4] * qd[6];
        let x786 = q[5] * qd[3];
        let x787 = q[3] * qd[5];
        let x792 = q[6] * qd[5];
        let x793 = q[5] * qd[6];
        let x796 = q[4] * qd[3];
        let x797 = q[3] * qd[4];
        let x926 = 2.0 * qd[3];
        let x927 = 2.0 * qd[4];
        let x928 = 2.0 * qd[6];
        let x971 = 2.0 * qd[5];
        let x1052 = qd[4] * qd[5];
        let x1055 = qd[3] * qd[6];
        let x1058 = qd[4] * qd[6];
        let x1061 = qd[3] * qd[5];
        let x1258 = x797 - x796;
        let x1259 = x792 + x1258;
        let x1260 = x1259 - x793;
        let x1261 = 2.0 * x1260;
        let x1264 = x782 + x786;
        let x1266 = x787 - x1264;
        let x1267 = x783 + x1266;
        let x1268 = 2.0 * x1267;
        let x1271 = x774 - x778;
        let x1272 = x1271 - x775;
        let x1273 = x779 + x1272;
        let x1274 = 2.0 * x1273;
        let x1295 = 2.0 * x1261;
        let x1297 = 2.0 * x1268;
        let x1299 = 2.0 * x1274;
        let x1508 = 0.00826875 * s[18];
        let x1511 = s[29] - x1508;
        let x1512 = x1511 - s[28];
        let x1513 = 0.5 * x1512;
        let x1514 = s[20] + x1513;
        let x1516 = 0.00826875 * s[16];
        let x1518 = s[32] + x1516;
        let x1520 = s[31] - x1518;
        let x1521 = 0.5 * x1520;
        let x1522 = s[33] + x1521;
        let x1523 = 0.00826875 * s[14];
        let x1524 = x1523 - s[23];
        let x1525 = x1524 - s[22];
        let x1526 = 0.5 * x1525;
        let x1527 = s[34] + x1526;
        let x1529 = 0.00826875 * s[12];
        let x1530 = s[26] + x1529;
        let x1531 = s[25] + x1530;
        let x1532 = 0.5 * x1531;
        let x1533 = s[0] * 0.02205;
        let x1534 = x1532 + x1533;
        let x1537 = x1058 + x1061;
        let x1539 = x1061 - x1537;
        let x1540 = x1058 + x1539;
        let x1541 = 2.0 * x1540;
        let x1544 = x1052 - x1055;
        let x1545 = x1544 - x1052;
        let x1546 = x1055 + x1545;
        let x1547 = 2.0 * x1546;
        let x1548 = 2.0 * x1541;
        let x1549 = 2.0 * x1547;
        let x1550 = x927 * x1295;
        let x1551 = 0.004134375 * x1550;
        let x1552 = x971 * x1297;
        let x1553 = s[7] * x1548;
        let x1554 = x1552 + x1553;
        let x1555 = 0.00826875 * x1554;
        let x1556 = x928 * x1299;
        let x1557 = s[6] * x1549;
        let x1558 = x1556 + x1557;
        let x1559 = 0.004134375 * x1558;
        let x1560 = x1551 + x1555;
        let x1561 = x1559 + x1560;
        let x1562 = 0.5 * x1561;
        let x1564 = x926 * x1295;
        let x1565 = 0.004134375 * x1564;
        let x1566 = x928 * x1297;
        let x1567 = s[6] * x1548;
        let x1568 = x1566 + x1567;
        let x1569 = 0.00826875 * x1568;
        let x1571 = x971 * x1299;
        let x1572 = s[7] * x1549;
        let x1573 = x1571 + x1572;
        let x1574 = 0.004134375 * x1573;
        let x1575 = x1565 - x1569;
        let x1576 = x1574 + x1575;
        let x1577 = 0.5 * x1576;
        let x1578 = x928 * x1295;
        let x1579 = 0.004134375 * x1578;
        let x1580 = x926 * x1297;
        let x1581 = s[4] * x1548;
        let x1582 = x1580 + x1581;
        let x1583 = 0.00826875 * x1582;
        let x1584 = x927 * x1299;
        let x1585 = s[5] * x1549;
        let x1586 = x1584 + x1585;
        let x1587 = 0.004134375 * x1586;
        let x1589 = x1579 + x1583;
        let x1590 = x1589 - x1587;
        let x1591 = 0.5 * x1590;
        let x1592 = x971 * x1295;
        let x1593 = 0.004134375 * x1592;
        let x1595 = x927 * x1297;
        let x1596 = s[5] * x1548;
        let x1597 = x1595 + x1596;
        let x1598 = 0.00826875 * x1597;
        let x1599 = x926 * x1299;
        let x1600 = s[4] * x1549;
        let x1601 = x1599 + x1600;
        let x1602 = 0.004134375 * x1601;
        let x1603 = x1598 - x1593;
        let x1604 = x1602 + x1603;
        let x1605 = 0.5 * x1604;
        let x1606 = qd[3] * qd[3];
        let x1607 = qd[4] * qd[4];
        let x1608 = qd[5] * qd[5];
        let x1609 = qd[6] * qd[6];
        let x1610 = x1606 + x1607;
        let x1611 = x1608 + x1610;
        let x1612 = x1609 + x1611;
        let x1613 = 0.00826875 * x1552;
        let x1614 = 0.004134375 * x1556;
        let x1615 = x1551 + x1613;
        let x1616 = x1614 + x1615;
        let x1617 = 0.5 * x1616;
        let x1618 = x1562 + x1617;
        let x1619 = q[3] * 0.02205;
        let x1620 = x1612 * x1619;
        let x1622 = x1618 - x1620;
        let x1629 = 0.00826875 * x1566;
        let x1631 = 0.004134375 * x1571;
        let x1633 = x1629 - x1565;
        let x1634 = x1633 - x1631;
        let x1635 = 0.5 * x1634;
        let x1637 = x1635 - x1577;
        let x1638 = q[4] * 0.02205;
        let x1639 = x1612 * x1638;
        let x1641 = x1637 - x1639;
        let x1647 = 0.00826875 * x1580;
        let x1649 = 0.004134375 * x1584;
        let x1650 = x1579 + x1647;
        let x1652 = x1649 - x1650;
        let x1653 = 0.5 * x1652;
        let x1655 = x1653 - x1591;
        let x1656 = q[5] * 0.02205;
        let x1657 = x1612 * x1656;
        let x1659 = x1655 - x1657;
        let x1663 = 0.00826875 * x1595;
        let x1666 = 0.004134375 * x1599;
        let x1668 = x1593 - x1663;
        let x1669 = x1668 - x1666;
        let x1670 = 0.5 * x1669;
        let x1672 = x1670 - x1605;
        let x1673 = q[6] * 0.02205;
        let x1674 = x1612 * x1673;
        let x1676 = x1672 - x1674;
        mass[15] = x1514;
        mass[16] = x1522;
        mass[17] = x1527;
        mass[18] = x1534;
        force[0] = 0.0;
        force[1] = -14.715;
        force[2] = 0.0;
        force[3] = x1622;
        force[4] = x1641;
        force[5] = x1659;
        force[6] = x1676;
    }
}
/// `hexapod_twist` with the `exact` formulation.
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
    name: "hexapod_twist",
    t_end: T_END,
    formulations: &[(Formulation::Exact, &Exact as &(dyn Mechanism + Sync))],
    reduced: None,
    origin: Origin::Compiled {
        file: concat!(
            env!("CARGO_MANIFEST_DIR"), "/../../../", "mechanisms/hexapod_twist.toml"
        ),
        hash: 13001661441132106976u64,
        parameters: &[],
    },
    run_time: None,
};
