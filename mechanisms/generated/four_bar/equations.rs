//! Generated equations of `four_bar` (planar crank-rocker four-bar, crank driven at constant speed). Do not edit.
//!
//! Regenerate with `cargo xtask generate four_bar` from `mechanisms/four_bar.toml`.
//!
//! 18 coordinates, 21 constraints, 96 structural nonzeros in Φq.
//! Rank 18 at the initial pose; mobility 1 (Grübler count -2), 0 DOF left with drivers.
//! Redundant rows (dropped by the solvers): b0.z, b0.dot1(x1,z2), b0.dot1(y1,z2).
//! Each body owns `[X, Y, Z]` (centre of mass), then `[θ, β, γ]` (A = Rz(γ)·Ry(β)·Rx(θ))
//! or Euler parameters `[e0, e1, e2, e3]`. Equations of motion: `M q̈ + Φqᵀλ = Q`, `Φq q̈ = γ`.
//! Sparse outputs hold the pattern's nonzeros in order (row-major, columns ascending).
//!
//! Coordinates:
//! - `0..6` crank (euler)
//! - `6..12` coupler (euler)
//! - `12..18` rocker (euler)
//!
//! Constraint rows:
//! - `0..5` a0 (revolute, ground – crank)
//! - `5..10` a1 (revolute, crank – coupler)
//! - `10..15` b1 (revolute, coupler – rocker)
//! - `15..20` b0 (revolute, ground – rocker)
//! - `20` motor (driver): sin(f − θ) of `a0`, f = initial + 2.0 * pi * t, initial = 0.000000000
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
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
    phi_part_0(q, t, out);
}
#[inline(never)]
fn phi_part_0(q: &[f64; 18], t: f64, out: &mut [f64; 21]) {
    let x5 = 6.283185307179586 * t;
    let x12 = q[3].sin();
    let x13 = q[3].cos();
    let x14 = q[4].sin();
    let x15 = q[4].cos();
    let x16 = q[5].sin();
    let x17 = q[5].cos();
    let x18 = x15 * x17;
    let x19 = x15 * x16;
    let x20 = x14 * x17;
    let x21 = x14 * x16;
    let x22 = x12 * x15;
    let x24 = x12 * x20;
    let x25 = x13 * x16;
    let x26 = x13 * x20;
    let x27 = x12 * x16;
    let x28 = x12 * x21;
    let x29 = x13 * x17;
    let x30 = x13 * x21;
    let x31 = x12 * x17;
    let x33 = x24 - x25;
    let x34 = x26 + x27;
    let x35 = x28 + x29;
    let x37 = x30 - x31;
    let x45 = q[9].sin();
    let x46 = q[9].cos();
    let x47 = q[10].sin();
    let x48 = q[10].cos();
    let x49 = q[11].sin();
    let x50 = q[11].cos();
    let x51 = x48 * x50;
    let x52 = x48 * x49;
    let x53 = x47 * x50;
    let x54 = x47 * x49;
    let x55 = x45 * x48;
    let x56 = x46 * x48;
    let x57 = x45 * x53;
    let x58 = x46 * x49;
    let x59 = x46 * x53;
    let x60 = x45 * x49;
    let x61 = x45 * x54;
    let x62 = x46 * x50;
    let x63 = x46 * x54;
    let x64 = x45 * x50;
    let x66 = x57 - x58;
    let x67 = x59 + x60;
    let x68 = x61 + x62;
    let x70 = x63 - x64;
    let x78 = q[15].sin();
    let x79 = q[15].cos();
    let x80 = q[16].sin();
    let x81 = q[16].cos();
    let x82 = q[17].sin();
    let x83 = q[17].cos();
    let x84 = x81 * x83;
    let x85 = x81 * x82;
    let x86 = x80 * x83;
    let x87 = x80 * x82;
    let x88 = x78 * x81;
    let x89 = x79 * x81;
    let x90 = x78 * x86;
    let x91 = x79 * x82;
    let x92 = x79 * x86;
    let x93 = x78 * x82;
    let x94 = x78 * x87;
    let x95 = x79 * x83;
    let x96 = x79 * x87;
    let x97 = x78 * x83;
    let x99 = x90 - x91;
    let x100 = x92 + x93;
    let x101 = x94 + x95;
    let x103 = x96 - x97;
    let x108 = x18 * 0.05;
    let x110 = x19 * 0.05;
    let x112 = x14 * 0.05;
    let x114 = q[0] - x108;
    let x115 = q[1] - x110;
    let x116 = q[2] + x112;
    let x119 = x18 * 0.00000000000000006123233995736766;
    let x121 = x119 - x33;
    let x122 = x19 * 0.00000000000000006123233995736766;
    let x124 = x122 - x35;
    let x125 = x14 * 0.00000000000000006123233995736766;
    let x128 = x22 + x125;
    let x130 = x33 * 0.00000000000000006123233995736766;
    let x131 = x18 + x130;
    let x132 = x35 * 0.00000000000000006123233995736766;
    let x133 = x19 + x132;
    let x134 = x22 * 0.00000000000000006123233995736766;
    let x135 = x134 - x14;
    let x136 = -x114;
    let x137 = -x115;
    let x138 = -x116;
    let x139 = q[0] + x108;
    let x140 = q[1] + x110;
    let x141 = q[2] - x112;
    let x144 = x51 * 0.17499999999999996;
    let x146 = x52 * 0.17499999999999996;
    let x148 = x47 * 0.17499999999999996;
    let x150 = q[6] - x144;
    let x151 = q[7] - x146;
    let x152 = q[8] + x148;
    let x155 = x51 * 0.8534911287233514;
    let x157 = x66 * 0.5211073720362623;
    let x159 = x155 - x157;
    let x160 = x52 * 0.8534911287233514;
    let x161 = x68 * 0.5211073720362623;
    let x163 = x160 - x161;
    let x164 = x47 * 0.8534911287233514;
    let x166 = x55 * 0.5211073720362623;
    let x168 = x164 + x166;
    let x170 = x51 * 0.5211073720362623;
    let x171 = x66 * 0.8534911287233514;
    let x172 = x170 + x171;
    let x173 = x52 * 0.5211073720362623;
    let x174 = x68 * 0.8534911287233514;
    let x175 = x173 + x174;
    let x176 = x47 * 0.5211073720362623;
    let x178 = x55 * 0.8534911287233514;
    let x179 = x178 - x176;
    let x181 = x139 - x150;
    let x183 = x140 - x151;
    let x185 = x141 - x152;
    let x186 = x67 * x121;
    let x187 = x70 * x124;
    let x188 = x56 * x128;
    let x190 = x186 + x187;
    let x191 = x190 - x188;
    let x192 = x67 * x131;
    let x193 = x70 * x133;
    let x194 = x56 * x135;
    let x195 = x192 + x193;
    let x196 = x194 + x195;
    let x199 = x51 * 0.175;
    let x200 = x66 * 0.000000000000000027755575615628914;
    let x201 = x199 + x200;
    let x202 = x52 * 0.175;
    let x203 = x68 * 0.000000000000000027755575615628914;
    let x204 = x202 + x203;
    let x205 = x47 * 0.175;
    let x207 = x55 * 0.000000000000000027755575615628914;
    let x208 = x207 - x205;
    let x209 = q[6] + x201;
    let x210 = q[7] + x204;
    let x211 = q[8] + x208;
    let x214 = x84 * 0.14999999999999997;
    let x215 = x99 * 0.000000000000000006938893903907228;
    let x216 = x214 + x215;
    let x217 = x85 * 0.14999999999999997;
    let x218 = x101 * 0.000000000000000006938893903907228;
    let x219 = x217 + x218;
    let x220 = x80 * 0.14999999999999997;
    let x222 = x88 * 0.000000000000000006938893903907228;
    let x223 = x222 - x220;
    let x224 = q[12] + x216;
    let x225 = q[13] + x219;
    let x226 = q[14] + x223;
    let x263 = x209 - x224;
    let x265 = x210 - x225;
    let x267 = x211 - x226;
    let x268 = x100 * x159;
    let x269 = x103 * x163;
    let x270 = x89 * x168;
    let x272 = x268 + x269;
    let x273 = x272 - x270;
    let x274 = x100 * x172;
    let x275 = x103 * x175;
    let x276 = x89 * x179;
    let x277 = x274 + x275;
    let x278 = x276 + x277;
    let x283 = x99 * 0.00000000000000004163336342344337;
    let x284 = x283 - x214;
    let x286 = x101 * 0.00000000000000004163336342344337;
    let x287 = x286 - x217;
    let x288 = x88 * 0.00000000000000004163336342344337;
    let x289 = x220 + x288;
    let x290 = q[12] + x284;
    let x291 = q[13] + x287;
    let x292 = q[14] + x289;
    let x294 = 0.4 - x290;
    let x295 = -x291;
    let x296 = -x292;
    let x297 = x5.sin();
    let x298 = x5.cos();
    let x299 = x121 * x297;
    let x300 = x124 * x298;
    let x302 = x299 - x300;
    out[0] = x136;
    out[1] = x137;
    out[2] = x138;
    out[3] = x34;
    out[4] = x37;
    out[5] = x181;
    out[6] = x183;
    out[7] = x185;
    out[8] = x191;
    out[9] = x196;
    out[10] = x263;
    out[11] = x265;
    out[12] = x267;
    out[13] = x273;
    out[14] = x278;
    out[15] = x294;
    out[16] = x295;
    out[17] = x296;
    out[18] = x100;
    out[19] = x103;
    out[20] = x302;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 96] = out.try_into().expect("out must have 96 entries");
    phi_q_part_0(q, t, out);
}
#[inline(never)]
fn phi_q_part_0(q: &[f64; 18], t: f64, out: &mut [f64; 96]) {
    let x5 = 6.283185307179586 * t;
    let x12 = q[3].sin();
    let x13 = q[3].cos();
    let x14 = q[4].sin();
    let x15 = q[4].cos();
    let x16 = q[5].sin();
    let x17 = q[5].cos();
    let x18 = x15 * x17;
    let x19 = x15 * x16;
    let x20 = x14 * x17;
    let x21 = x14 * x16;
    let x22 = x12 * x15;
    let x23 = x13 * x15;
    let x24 = x12 * x20;
    let x25 = x13 * x16;
    let x26 = x13 * x20;
    let x27 = x12 * x16;
    let x28 = x12 * x21;
    let x29 = x13 * x17;
    let x30 = x13 * x21;
    let x31 = x12 * x17;
    let x33 = x24 - x25;
    let x34 = x26 + x27;
    let x35 = x28 + x29;
    let x37 = x30 - x31;
    let x45 = q[9].sin();
    let x46 = q[9].cos();
    let x47 = q[10].sin();
    let x48 = q[10].cos();
    let x49 = q[11].sin();
    let x50 = q[11].cos();
    let x51 = x48 * x50;
    let x52 = x48 * x49;
    let x53 = x47 * x50;
    let x54 = x47 * x49;
    let x55 = x45 * x48;
    let x56 = x46 * x48;
    let x57 = x45 * x53;
    let x58 = x46 * x49;
    let x59 = x46 * x53;
    let x60 = x45 * x49;
    let x61 = x45 * x54;
    let x62 = x46 * x50;
    let x63 = x46 * x54;
    let x64 = x45 * x50;
    let x66 = x57 - x58;
    let x67 = x59 + x60;
    let x68 = x61 + x62;
    let x70 = x63 - x64;
    let x78 = q[15].sin();
    let x79 = q[15].cos();
    let x80 = q[16].sin();
    let x81 = q[16].cos();
    let x82 = q[17].sin();
    let x83 = q[17].cos();
    let x84 = x81 * x83;
    let x85 = x81 * x82;
    let x86 = x80 * x83;
    let x87 = x80 * x82;
    let x88 = x78 * x81;
    let x89 = x79 * x81;
    let x90 = x78 * x86;
    let x91 = x79 * x82;
    let x92 = x79 * x86;
    let x93 = x78 * x82;
    let x94 = x78 * x87;
    let x95 = x79 * x83;
    let x96 = x79 * x87;
    let x97 = x78 * x83;
    let x99 = x90 - x91;
    let x100 = x92 + x93;
    let x101 = x94 + x95;
    let x103 = x96 - x97;
    let x108 = x18 * 0.05;
    let x110 = x19 * 0.05;
    let x111 = -x110;
    let x119 = x18 * 0.00000000000000006123233995736766;
    let x121 = x119 - x33;
    let x122 = x19 * 0.00000000000000006123233995736766;
    let x123 = -x35;
    let x124 = x122 - x35;
    let x125 = x14 * 0.00000000000000006123233995736766;
    let x128 = x22 + x125;
    let x130 = x33 * 0.00000000000000006123233995736766;
    let x131 = x18 + x130;
    let x132 = x35 * 0.00000000000000006123233995736766;
    let x133 = x19 + x132;
    let x134 = x22 * 0.00000000000000006123233995736766;
    let x135 = x134 - x14;
    let x144 = x51 * 0.17499999999999996;
    let x146 = x52 * 0.17499999999999996;
    let x147 = -x146;
    let x155 = x51 * 0.8534911287233514;
    let x157 = x66 * 0.5211073720362623;
    let x159 = x155 - x157;
    let x160 = x52 * 0.8534911287233514;
    let x161 = x68 * 0.5211073720362623;
    let x163 = x160 - x161;
    let x164 = x47 * 0.8534911287233514;
    let x166 = x55 * 0.5211073720362623;
    let x168 = x164 + x166;
    let x170 = x51 * 0.5211073720362623;
    let x171 = x66 * 0.8534911287233514;
    let x172 = x170 + x171;
    let x173 = x52 * 0.5211073720362623;
    let x174 = x68 * 0.8534911287233514;
    let x175 = x173 + x174;
    let x176 = x47 * 0.5211073720362623;
    let x178 = x55 * 0.8534911287233514;
    let x179 = x178 - x176;
    let x199 = x51 * 0.175;
    let x200 = x66 * 0.000000000000000027755575615628914;
    let x201 = x199 + x200;
    let x202 = x52 * 0.175;
    let x203 = x68 * 0.000000000000000027755575615628914;
    let x204 = x202 + x203;
    let x214 = x84 * 0.14999999999999997;
    let x215 = x99 * 0.000000000000000006938893903907228;
    let x216 = x214 + x215;
    let x217 = x85 * 0.14999999999999997;
    let x218 = x101 * 0.000000000000000006938893903907228;
    let x219 = x217 + x218;
    let x283 = x99 * 0.00000000000000004163336342344337;
    let x284 = x283 - x214;
    let x286 = x101 * 0.00000000000000004163336342344337;
    let x297 = x5.sin();
    let x298 = x5.cos();
    let x307 = x25 - x24;
    let x311 = x34 * 0.00000000000000006123233995736766;
    let x312 = x37 * 0.00000000000000006123233995736766;
    let x313 = x23 * 0.00000000000000006123233995736766;
    let x314 = x34 * x67;
    let x316 = x37 * x70;
    let x318 = x23 * x56;
    let x320 = x314 + x316;
    let x322 = x318 + x320;
    let x323 = -x322;
    let x324 = x67 * x311;
    let x325 = x70 * x312;
    let x326 = x56 * x313;
    let x327 = x324 + x325;
    let x328 = x326 + x327;
    let x329 = x34 * x297;
    let x331 = x37 * x298;
    let x333 = x331 - x329;
    let x336 = x12 * x14;
    let x338 = x12 * x18;
    let x339 = x13 * x18;
    let x340 = x12 * x19;
    let x341 = x13 * x19;
    let x343 = x20 * 0.05;
    let x344 = -x343;
    let x345 = x21 * 0.05;
    let x346 = -x345;
    let x347 = x15 * 0.05;
    let x348 = -x347;
    let x349 = x20 * 0.00000000000000006123233995736766;
    let x352 = x338 + x349;
    let x354 = x21 * 0.00000000000000006123233995736766;
    let x357 = x340 + x354;
    let x359 = x15 * 0.00000000000000006123233995736766;
    let x360 = x359 - x336;
    let x361 = 0.00000000000000006123233995736766 * x338;
    let x362 = x361 - x20;
    let x363 = 0.00000000000000006123233995736766 * x340;
    let x364 = x363 - x21;
    let x365 = 0.00000000000000006123233995736766 * x336;
    let x367 = x15 + x365;
    let x369 = x67 * x352;
    let x371 = x70 * x357;
    let x373 = x56 * x360;
    let x375 = x369 + x371;
    let x377 = x373 + x375;
    let x378 = -x377;
    let x379 = x67 * x362;
    let x380 = x70 * x364;
    let x381 = x56 * x367;
    let x383 = x379 + x380;
    let x384 = x383 - x381;
    let x385 = x297 * x352;
    let x387 = x298 * x357;
    let x389 = x387 - x385;
    let x393 = x31 - x30;
    let x395 = x35 - x122;
    let x398 = x67 * x395;
    let x399 = x70 * x121;
    let x400 = x398 + x399;
    let x401 = x67 * x133;
    let x403 = x70 * x131;
    let x404 = x403 - x401;
    let x405 = x297 * x395;
    let x406 = x121 * x298;
    let x408 = x405 - x406;
    let x414 = x58 - x57;
    let x417 = x67 * 0.5211073720362623;
    let x419 = x70 * 0.5211073720362623;
    let x421 = x56 * 0.5211073720362623;
    let x422 = x67 * 0.8534911287233514;
    let x423 = x70 * 0.8534911287233514;
    let x424 = x56 * 0.8534911287233514;
    let x425 = x121 * x414;
    let x426 = x68 * x124;
    let x428 = x55 * x128;
    let x430 = x425 - x426;
    let x431 = x428 + x430;
    let x432 = x131 * x414;
    let x433 = x68 * x133;
    let x435 = x55 * x135;
    let x437 = x432 - x433;
    let x438 = x437 - x435;
    let x439 = x67 * 0.000000000000000027755575615628914;
    let x440 = x70 * 0.000000000000000027755575615628914;
    let x441 = x56 * 0.000000000000000027755575615628914;
    let x442 = x100 * x417;
    let x444 = x103 * x419;
    let x446 = x89 * x421;
    let x448 = x442 + x444;
    let x450 = x446 + x448;
    let x451 = -x450;
    let x452 = x100 * x422;
    let x453 = x103 * x423;
    let x454 = x89 * x424;
    let x455 = x452 + x453;
    let x456 = x454 + x455;
    let x459 = x45 * x47;
    let x461 = x46 * x47;
    let x463 = x45 * x51;
    let x464 = x46 * x51;
    let x465 = x45 * x52;
    let x466 = x46 * x52;
    let x467 = x53 * 0.17499999999999996;
    let x468 = -x467;
    let x469 = x54 * 0.17499999999999996;
    let x470 = -x469;
    let x471 = x48 * 0.17499999999999996;
    let x472 = x53 * 0.8534911287233514;
    let x474 = 0.5211073720362623 * x463;
    let x476 = x472 + x474;
    let x478 = x54 * 0.8534911287233514;
    let x480 = 0.5211073720362623 * x465;
    let x482 = x478 + x480;
    let x484 = x48 * 0.8534911287233514;
    let x485 = 0.5211073720362623 * x459;
    let x487 = x484 - x485;
    let x488 = x53 * 0.5211073720362623;
    let x490 = 0.8534911287233514 * x463;
    let x491 = x490 - x488;
    let x492 = x54 * 0.5211073720362623;
    let x494 = 0.8534911287233514 * x465;
    let x495 = x494 - x492;
    let x496 = x48 * 0.5211073720362623;
    let x498 = 0.8534911287233514 * x459;
    let x500 = x496 + x498;
    let x502 = -x471;
    let x503 = x121 * x464;
    let x504 = x124 * x466;
    let x505 = x128 * x461;
    let x507 = x503 + x504;
    let x508 = x505 + x507;
    let x509 = x131 * x464;
    let x510 = x133 * x466;
    let x511 = x135 * x461;
    let x513 = x509 + x510;
    let x514 = x513 - x511;
    let x515 = x53 * 0.175;
    let x517 = 0.000000000000000027755575615628914 * x463;
    let x518 = x517 - x515;
    let x519 = x54 * 0.175;
    let x521 = 0.000000000000000027755575615628914 * x465;
    let x522 = x521 - x519;
    let x523 = x48 * 0.175;
    let x525 = 0.000000000000000027755575615628914 * x459;
    let x527 = x523 + x525;
    let x528 = -x527;
    let x529 = x100 * x476;
    let x531 = x103 * x482;
    let x533 = x89 * x487;
    let x535 = x529 + x531;
    let x537 = x533 + x535;
    let x538 = -x537;
    let x539 = x100 * x491;
    let x540 = x103 * x495;
    let x541 = x89 * x500;
    let x543 = x539 + x540;
    let x544 = x543 - x541;
    let x548 = x64 - x63;
    let x550 = x161 - x160;
    let x554 = x121 * x548;
    let x555 = x67 * x124;
    let x556 = x554 + x555;
    let x557 = x131 * x548;
    let x558 = x401 + x557;
    let x561 = -x204;
    let x562 = x100 * x550;
    let x563 = x103 * x159;
    let x564 = x562 + x563;
    let x565 = x100 * x175;
    let x567 = x103 * x172;
    let x568 = x567 - x565;
    let x574 = x91 - x90;
    let x576 = -x101;
    let x577 = x100 * 0.000000000000000006938893903907228;
    let x578 = x103 * 0.000000000000000006938893903907228;
    let x579 = x89 * 0.000000000000000006938893903907228;
    let x580 = -x577;
    let x581 = -x578;
    let x582 = -x579;
    let x583 = x159 * x574;
    let x584 = x101 * x163;
    let x586 = x88 * x168;
    let x588 = x583 - x584;
    let x589 = x586 + x588;
    let x590 = x172 * x574;
    let x591 = x101 * x175;
    let x593 = x88 * x179;
    let x595 = x590 - x591;
    let x596 = x595 - x593;
    let x597 = x100 * 0.00000000000000004163336342344337;
    let x598 = x103 * 0.00000000000000004163336342344337;
    let x599 = x89 * 0.00000000000000004163336342344337;
    let x600 = -x597;
    let x601 = -x598;
    let x602 = -x599;
    let x605 = x78 * x80;
    let x607 = x79 * x80;
    let x609 = x78 * x84;
    let x610 = x79 * x84;
    let x611 = x78 * x85;
    let x612 = x79 * x85;
    let x613 = x86 * 0.14999999999999997;
    let x615 = 0.000000000000000006938893903907228 * x609;
    let x616 = x615 - x613;
    let x617 = x87 * 0.14999999999999997;
    let x619 = 0.000000000000000006938893903907228 * x611;
    let x620 = x619 - x617;
    let x621 = x81 * 0.14999999999999997;
    let x623 = 0.000000000000000006938893903907228 * x605;
    let x625 = x621 + x623;
    let x627 = -x616;
    let x628 = -x620;
    let x629 = x159 * x610;
    let x630 = x163 * x612;
    let x631 = x168 * x607;
    let x633 = x629 + x630;
    let x634 = x631 + x633;
    let x635 = x172 * x610;
    let x636 = x175 * x612;
    let x637 = x179 * x607;
    let x639 = x635 + x636;
    let x640 = x639 - x637;
    let x641 = 0.00000000000000004163336342344337 * x609;
    let x642 = x613 + x641;
    let x643 = 0.00000000000000004163336342344337 * x611;
    let x644 = x617 + x643;
    let x645 = 0.00000000000000004163336342344337 * x605;
    let x647 = x621 - x645;
    let x648 = -x642;
    let x649 = -x644;
    let x650 = -x647;
    let x654 = x97 - x96;
    let x657 = -x216;
    let x658 = x159 * x654;
    let x659 = x100 * x163;
    let x660 = x658 + x659;
    let x661 = x172 * x654;
    let x662 = x565 + x661;
    let x664 = x217 - x286;
    let x665 = -x664;
    let x666 = -x284;
    out[0] = -1.0;
    out[1] = x344;
    out[2] = x111;
    out[3] = -1.0;
    out[4] = x346;
    out[5] = x108;
    out[6] = -1.0;
    out[7] = x348;
    out[8] = x307;
    out[9] = x339;
    out[10] = x393;
    out[11] = x123;
    out[12] = x341;
    out[13] = x34;
    out[14] = 1.0;
    out[15] = x344;
    out[16] = x111;
    out[17] = -1.0;
    out[18] = x468;
    out[19] = x147;
    out[20] = 1.0;
    out[21] = x346;
    out[22] = x108;
    out[23] = -1.0;
    out[24] = x470;
    out[25] = x144;
    out[26] = 1.0;
    out[27] = x348;
    out[28] = -1.0;
    out[29] = x502;
    out[30] = x323;
    out[31] = x378;
    out[32] = x400;
    out[33] = x431;
    out[34] = x508;
    out[35] = x556;
    out[36] = x328;
    out[37] = x384;
    out[38] = x404;
    out[39] = x438;
    out[40] = x514;
    out[41] = x558;
    out[42] = 1.0;
    out[43] = x439;
    out[44] = x518;
    out[45] = x561;
    out[46] = -1.0;
    out[47] = x580;
    out[48] = x627;
    out[49] = x219;
    out[50] = 1.0;
    out[51] = x440;
    out[52] = x522;
    out[53] = x201;
    out[54] = -1.0;
    out[55] = x581;
    out[56] = x628;
    out[57] = x657;
    out[58] = 1.0;
    out[59] = x441;
    out[60] = x528;
    out[61] = -1.0;
    out[62] = x582;
    out[63] = x625;
    out[64] = x451;
    out[65] = x538;
    out[66] = x564;
    out[67] = x589;
    out[68] = x634;
    out[69] = x660;
    out[70] = x456;
    out[71] = x544;
    out[72] = x568;
    out[73] = x596;
    out[74] = x640;
    out[75] = x662;
    out[76] = -1.0;
    out[77] = x600;
    out[78] = x648;
    out[79] = x665;
    out[80] = -1.0;
    out[81] = x601;
    out[82] = x649;
    out[83] = x666;
    out[84] = -1.0;
    out[85] = x602;
    out[86] = x650;
    out[87] = x574;
    out[88] = x610;
    out[89] = x654;
    out[90] = x576;
    out[91] = x612;
    out[92] = x100;
    out[93] = x333;
    out[94] = x389;
    out[95] = x408;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
    phi_t_part_0(q, t, out);
}
#[inline(never)]
fn phi_t_part_0(q: &[f64; 18], t: f64, out: &mut [f64; 21]) {
    let x5 = 6.283185307179586 * t;
    let x12 = q[3].sin();
    let x13 = q[3].cos();
    let x14 = q[4].sin();
    let x15 = q[4].cos();
    let x16 = q[5].sin();
    let x17 = q[5].cos();
    let x18 = x15 * x17;
    let x19 = x15 * x16;
    let x20 = x14 * x17;
    let x21 = x14 * x16;
    let x24 = x12 * x20;
    let x25 = x13 * x16;
    let x28 = x12 * x21;
    let x29 = x13 * x17;
    let x33 = x24 - x25;
    let x35 = x28 + x29;
    let x119 = x18 * 0.00000000000000006123233995736766;
    let x121 = x119 - x33;
    let x122 = x19 * 0.00000000000000006123233995736766;
    let x124 = x122 - x35;
    let x297 = x5.sin();
    let x298 = x5.cos();
    let x667 = 6.283185307179586 * x298;
    let x669 = 6.283185307179586 * x297;
    let x671 = x121 * x667;
    let x672 = x124 * x669;
    let x674 = x671 + x672;
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
    out[12] = 0.0;
    out[13] = 0.0;
    out[14] = 0.0;
    out[15] = 0.0;
    out[16] = 0.0;
    out[17] = 0.0;
    out[18] = 0.0;
    out[19] = 0.0;
    out[20] = x674;
}
/// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
pub fn gamma(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 18] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
    let mut s = [0.0f64; 283];
    gamma_shared_0(q, qd, t, &mut s);
    gamma_part_0(&s, out);
    gamma_part_1(t, &s, out);
}
#[inline(never)]
fn gamma_shared_0(q: &[f64; 18], qd: &[f64; 18], _t: f64, s: &mut [f64; 283]) {
    let x12 = q[3].sin();
    s[0] = x12;
    let x13 = q[3].cos();
    s[1] = x13;
    let x14 = q[4].sin();
    s[2] = x14;
    let x15 = q[4].cos();
    s[3] = x15;
    let x16 = q[5].sin();
    s[4] = x16;
    let x17 = q[5].cos();
    s[5] = x17;
    let x18 = x15 * x17;
    s[6] = x18;
    let x19 = x15 * x16;
    s[7] = x19;
    let x20 = x14 * x17;
    s[8] = x20;
    let x21 = x14 * x16;
    s[9] = x21;
    let x24 = x12 * x20;
    s[10] = x24;
    let x25 = x13 * x16;
    s[11] = x25;
    let x28 = x12 * x21;
    s[12] = x28;
    let x29 = x13 * x17;
    s[13] = x29;
    let x33 = x24 - x25;
    s[14] = x33;
    let x35 = x28 + x29;
    s[15] = x35;
    let x45 = q[9].sin();
    s[16] = x45;
    let x46 = q[9].cos();
    s[17] = x46;
    let x47 = q[10].sin();
    s[18] = x47;
    let x48 = q[10].cos();
    s[19] = x48;
    let x49 = q[11].sin();
    s[20] = x49;
    let x50 = q[11].cos();
    s[21] = x50;
    let x53 = x47 * x50;
    s[22] = x53;
    let x54 = x47 * x49;
    s[23] = x54;
    let x78 = q[15].sin();
    s[24] = x78;
    let x79 = q[15].cos();
    s[25] = x79;
    let x80 = q[16].sin();
    s[26] = x80;
    let x81 = q[16].cos();
    s[27] = x81;
    let x82 = q[17].sin();
    s[28] = x82;
    let x83 = q[17].cos();
    s[29] = x83;
    let x86 = x80 * x83;
    s[30] = x86;
    let x87 = x80 * x82;
    s[31] = x87;
    let x119 = x18 * 0.00000000000000006123233995736766;
    s[32] = x119;
    let x121 = x119 - x33;
    s[33] = x121;
    let x122 = x19 * 0.00000000000000006123233995736766;
    s[34] = x122;
    let x124 = x122 - x35;
    s[35] = x124;
    let x693 = x13 * qd[3];
    s[36] = x693;
    let x694 = x12 * qd[3];
    s[37] = x694;
    let x696 = x15 * qd[4];
    s[38] = x696;
    let x697 = x14 * qd[4];
    s[39] = x697;
    let x699 = x17 * qd[5];
    s[40] = x699;
    let x700 = x16 * qd[5];
    s[41] = x700;
    let x702 = x17 * x697;
    s[42] = x702;
    let x704 = x15 * x700;
    s[43] = x704;
    let x706 = x702 + x704;
    s[44] = x706;
    let x708 = x16 * x697;
    s[45] = x708;
    let x710 = x15 * x699;
    s[46] = x710;
    let x711 = x710 - x708;
    s[47] = x711;
    let x712 = x17 * x696;
    s[48] = x712;
    let x713 = x14 * x700;
    s[49] = x713;
    let x715 = x712 - x713;
    s[50] = x715;
    let x716 = x16 * x696;
    s[51] = x716;
    let x717 = x14 * x699;
    s[52] = x717;
    let x718 = x716 + x717;
    s[53] = x718;
    let x723 = x20 * x693;
    s[54] = x723;
    let x724 = x12 * x715;
    s[55] = x724;
    let x725 = x723 + x724;
    s[56] = x725;
    let x726 = x16 * x694;
    s[57] = x726;
    let x728 = x13 * x699;
    s[58] = x728;
    let x729 = x728 - x726;
    s[59] = x729;
    let x737 = x21 * x693;
    s[60] = x737;
    let x738 = x12 * x718;
    s[61] = x738;
    let x739 = x737 + x738;
    s[62] = x739;
    let x740 = x17 * x694;
    s[63] = x740;
    let x742 = x13 * x700;
    s[64] = x742;
    let x744 = x740 + x742;
    s[65] = x744;
    let x755 = x725 - x729;
    s[66] = x755;
    let x757 = x739 - x744;
    s[67] = x757;
    let x761 = x46 * qd[9];
    s[68] = x761;
    let x762 = x45 * qd[9];
    s[69] = x762;
    let x764 = x48 * qd[10];
    s[70] = x764;
    let x765 = x47 * qd[10];
    s[71] = x765;
    let x767 = x50 * qd[11];
    s[72] = x767;
    let x768 = x49 * qd[11];
    s[73] = x768;
    let x780 = x50 * x764;
    s[74] = x780;
    let x781 = x47 * x768;
    s[75] = x781;
    let x783 = x780 - x781;
    s[76] = x783;
    let x784 = x49 * x764;
    s[77] = x784;
    let x785 = x47 * x767;
    s[78] = x785;
    let x786 = x784 + x785;
    s[79] = x786;
    let x834 = x79 * qd[15];
    s[80] = x834;
    let x835 = x78 * qd[15];
    s[81] = x835;
    let x837 = x81 * qd[16];
    s[82] = x837;
    let x838 = x80 * qd[16];
    s[83] = x838;
    let x840 = x83 * qd[17];
    s[84] = x840;
    let x841 = x82 * qd[17];
    s[85] = x841;
    let x853 = x83 * x837;
    s[86] = x853;
    let x854 = x80 * x841;
    s[87] = x854;
    let x856 = x853 - x854;
    s[88] = x856;
    let x857 = x82 * x837;
    s[89] = x857;
    let x858 = x80 * x840;
    s[90] = x858;
    let x859 = x857 + x858;
    s[91] = x859;
    let x916 = 0.00000000000000006123233995736766 * x706;
    s[92] = x916;
    let x919 = x755 + x916;
    s[93] = x919;
    let x921 = 0.00000000000000006123233995736766 * x711;
    s[94] = x921;
    let x923 = x921 - x757;
    s[95] = x923;
    let x1095 = qd[3] * x694;
    s[96] = x1095;
    let x1097 = qd[3] * x693;
    s[97] = x1097;
    let x1098 = qd[4] * x697;
    s[98] = x1098;
    let x1100 = qd[4] * x696;
    s[99] = x1100;
    let x1101 = qd[5] * x700;
    s[100] = x1101;
    let x1103 = qd[5] * x699;
    s[101] = x1103;
    let x1104 = x697 * x700;
    s[102] = x1104;
    let x1106 = x17 * x1100;
    s[103] = x1106;
    let x1107 = x1106 - x1104;
    s[104] = x1107;
    let x1108 = x15 * x1103;
    s[105] = x1108;
    let x1109 = x1108 - x1104;
    s[106] = x1109;
    let x1110 = x1107 + x1109;
    s[107] = x1110;
    let x1112 = x697 * x699;
    s[108] = x1112;
    let x1113 = x16 * x1100;
    s[109] = x1113;
    let x1114 = x1112 + x1113;
    s[110] = x1114;
    let x1117 = x15 * x1101;
    s[111] = x1117;
    let x1119 = x1112 + x1117;
    s[112] = x1119;
    let x1121 = x1114 + x1119;
    s[113] = x1121;
    let x1123 = x696 * x700;
    s[114] = x1123;
    let x1125 = x17 * x1098;
    s[115] = x1125;
    let x1127 = x1123 + x1125;
    s[116] = x1127;
    let x1129 = x14 * x1103;
    s[117] = x1129;
    let x1130 = x1123 + x1129;
    s[118] = x1130;
    let x1132 = x1127 + x1130;
    s[119] = x1132;
    let x1134 = x696 * x699;
    s[120] = x1134;
    let x1135 = x16 * x1098;
    s[121] = x1135;
    let x1137 = x1134 - x1135;
    s[122] = x1137;
    let x1138 = x14 * x1101;
    s[123] = x1138;
    let x1140 = x1134 - x1138;
    s[124] = x1140;
    let x1141 = x1137 + x1140;
    s[125] = x1141;
    let x1153 = x693 * x715;
    s[126] = x1153;
    let x1154 = x20 * x1095;
    s[127] = x1154;
    let x1156 = x1153 - x1154;
    s[128] = x1156;
    let x1157 = x12 * x1132;
    s[129] = x1157;
    let x1159 = x1153 - x1157;
    s[130] = x1159;
    let x1160 = x1156 + x1159;
    s[131] = x1160;
    let x1161 = x694 * x699;
    s[132] = x1161;
    let x1162 = x16 * x1097;
    s[133] = x1162;
    let x1163 = x1161 + x1162;
    s[134] = x1163;
    let x1166 = x13 * x1101;
    s[135] = x1166;
    let x1168 = x1161 + x1166;
    s[136] = x1168;
    let x1170 = x1163 + x1168;
    s[137] = x1170;
    let x1191 = x693 * x718;
    s[138] = x1191;
    let x1192 = x21 * x1095;
    s[139] = x1192;
    let x1194 = x1191 - x1192;
    s[140] = x1194;
    let x1195 = x12 * x1141;
    s[141] = x1195;
    let x1196 = x1191 + x1195;
    s[142] = x1196;
    let x1197 = x1194 + x1196;
    s[143] = x1197;
    let x1198 = x694 * x700;
    s[144] = x1198;
    let x1200 = x17 * x1097;
    s[145] = x1200;
    let x1201 = x1200 - x1198;
    s[146] = x1201;
    let x1202 = x13 * x1103;
    s[147] = x1202;
    let x1203 = x1202 - x1198;
    s[148] = x1203;
    let x1204 = x1201 + x1203;
    s[149] = x1204;
    let x1225 = x1160 + x1170;
    s[150] = x1225;
    let x1227 = x1197 - x1204;
    s[151] = x1227;
    let x1229 = qd[9] * x762;
    s[152] = x1229;
    let x1231 = qd[9] * x761;
    s[153] = x1231;
    let x1232 = qd[10] * x765;
    s[154] = x1232;
    let x1234 = qd[10] * x764;
    s[155] = x1234;
    let x1235 = qd[11] * x768;
    s[156] = x1235;
    let x1237 = qd[11] * x767;
    s[157] = x1237;
    let x1238 = x765 * x768;
    s[158] = x1238;
    let x1240 = x50 * x1234;
    s[159] = x1240;
    let x1241 = x1240 - x1238;
    s[160] = x1241;
    let x1242 = x48 * x1237;
    s[161] = x1242;
    let x1243 = x1242 - x1238;
    s[162] = x1243;
    let x1244 = x1241 + x1243;
    s[163] = x1244;
    let x1245 = x765 * x767;
    s[164] = x1245;
    let x1246 = x49 * x1234;
    s[165] = x1246;
    let x1247 = x1245 + x1246;
    s[166] = x1247;
    let x1250 = x48 * x1235;
    s[167] = x1250;
    let x1252 = x1245 + x1250;
    s[168] = x1252;
    let x1254 = x1247 + x1252;
    s[169] = x1254;
    let x1256 = x764 * x768;
    s[170] = x1256;
    let x1258 = x50 * x1232;
    s[171] = x1258;
    let x1260 = x1256 + x1258;
    s[172] = x1260;
    let x1262 = x47 * x1237;
    s[173] = x1262;
    let x1263 = x1256 + x1262;
    s[174] = x1263;
    let x1265 = x1260 + x1263;
    s[175] = x1265;
    let x1267 = x764 * x767;
    s[176] = x1267;
    let x1268 = x49 * x1232;
    s[177] = x1268;
    let x1270 = x1267 - x1268;
    s[178] = x1270;
    let x1271 = x47 * x1235;
    s[179] = x1271;
    let x1273 = x1267 - x1271;
    s[180] = x1273;
    let x1274 = x1270 + x1273;
    s[181] = x1274;
    let x1275 = x761 * x765;
    s[182] = x1275;
    let x1277 = x48 * x1229;
    s[183] = x1277;
    let x1279 = x1275 + x1277;
    s[184] = x1279;
    let x1281 = x45 * x1234;
    s[185] = x1281;
    let x1282 = x1275 + x1281;
    s[186] = x1282;
    let x1284 = x1279 + x1282;
    s[187] = x1284;
    let x1293 = x761 * x783;
    s[188] = x1293;
    let x1294 = x53 * x1229;
    s[189] = x1294;
    let x1296 = x1293 - x1294;
    s[190] = x1296;
    let x1297 = x45 * x1265;
    s[191] = x1297;
    let x1299 = x1293 - x1297;
    s[192] = x1299;
    let x1300 = x1296 + x1299;
    s[193] = x1300;
    let x1301 = x762 * x767;
    s[194] = x1301;
    let x1302 = x49 * x1231;
    s[195] = x1302;
    let x1303 = x1301 + x1302;
    s[196] = x1303;
    let x1306 = x46 * x1235;
    s[197] = x1306;
    let x1308 = x1301 + x1306;
    s[198] = x1308;
    let x1310 = x1303 + x1308;
    s[199] = x1310;
    let x1331 = x761 * x786;
    s[200] = x1331;
    let x1332 = x54 * x1229;
    s[201] = x1332;
    let x1334 = x1331 - x1332;
    s[202] = x1334;
    let x1335 = x45 * x1274;
    s[203] = x1335;
    let x1336 = x1331 + x1335;
    s[204] = x1336;
    let x1337 = x1334 + x1336;
    s[205] = x1337;
    let x1338 = x762 * x768;
    s[206] = x1338;
    let x1340 = x50 * x1231;
    s[207] = x1340;
    let x1341 = x1340 - x1338;
    s[208] = x1341;
    let x1342 = x46 * x1237;
    s[209] = x1342;
    let x1343 = x1342 - x1338;
    s[210] = x1343;
    let x1344 = x1341 + x1343;
    s[211] = x1344;
    let x1365 = x1300 + x1310;
    s[212] = x1365;
    let x1367 = x1337 - x1344;
    s[213] = x1367;
    let x1369 = qd[15] * x835;
    s[214] = x1369;
    let x1371 = qd[15] * x834;
    s[215] = x1371;
    let x1372 = qd[16] * x838;
    s[216] = x1372;
    let x1374 = qd[16] * x837;
    s[217] = x1374;
    let x1375 = qd[17] * x841;
    s[218] = x1375;
    let x1377 = qd[17] * x840;
    s[219] = x1377;
    let x1378 = x838 * x841;
    s[220] = x1378;
    let x1380 = x83 * x1374;
    s[221] = x1380;
    let x1381 = x1380 - x1378;
    s[222] = x1381;
    let x1382 = x81 * x1377;
    s[223] = x1382;
    let x1383 = x1382 - x1378;
    s[224] = x1383;
    let x1384 = x1381 + x1383;
    s[225] = x1384;
    let x1385 = x838 * x840;
    s[226] = x1385;
    let x1386 = x82 * x1374;
    s[227] = x1386;
    let x1387 = x1385 + x1386;
    s[228] = x1387;
    let x1390 = x81 * x1375;
    s[229] = x1390;
    let x1392 = x1385 + x1390;
    s[230] = x1392;
    let x1394 = x1387 + x1392;
    s[231] = x1394;
    let x1396 = x837 * x841;
    s[232] = x1396;
    let x1398 = x83 * x1372;
    s[233] = x1398;
    let x1400 = x1396 + x1398;
    s[234] = x1400;
    let x1402 = x80 * x1377;
    s[235] = x1402;
    let x1403 = x1396 + x1402;
    s[236] = x1403;
    let x1405 = x1400 + x1403;
    s[237] = x1405;
    let x1407 = x837 * x840;
    s[238] = x1407;
    let x1408 = x82 * x1372;
    s[239] = x1408;
    let x1410 = x1407 - x1408;
    s[240] = x1410;
    let x1411 = x80 * x1375;
    s[241] = x1411;
    let x1413 = x1407 - x1411;
    s[242] = x1413;
    let x1414 = x1410 + x1413;
    s[243] = x1414;
    let x1415 = x834 * x838;
    s[244] = x1415;
    let x1417 = x81 * x1369;
    s[245] = x1417;
    let x1419 = x1415 + x1417;
    s[246] = x1419;
    let x1421 = x78 * x1374;
    s[247] = x1421;
    let x1422 = x1415 + x1421;
    s[248] = x1422;
    let x1424 = x1419 + x1422;
    s[249] = x1424;
    let x1433 = x834 * x856;
    s[250] = x1433;
    let x1434 = x86 * x1369;
    s[251] = x1434;
    let x1436 = x1433 - x1434;
    s[252] = x1436;
    let x1437 = x78 * x1405;
    s[253] = x1437;
    let x1439 = x1433 - x1437;
    s[254] = x1439;
    let x1440 = x1436 + x1439;
    s[255] = x1440;
    let x1441 = x835 * x840;
    s[256] = x1441;
    let x1442 = x82 * x1371;
    s[257] = x1442;
    let x1443 = x1441 + x1442;
    s[258] = x1443;
    let x1446 = x79 * x1375;
    s[259] = x1446;
    let x1448 = x1441 + x1446;
    s[260] = x1448;
    let x1450 = x1443 + x1448;
    s[261] = x1450;
    let x1471 = x834 * x859;
    s[262] = x1471;
    let x1472 = x87 * x1369;
    s[263] = x1472;
    let x1474 = x1471 - x1472;
    s[264] = x1474;
    let x1475 = x78 * x1414;
    s[265] = x1475;
    let x1476 = x1471 + x1475;
    s[266] = x1476;
    let x1477 = x1474 + x1476;
    s[267] = x1477;
    let x1478 = x835 * x841;
    s[268] = x1478;
    let x1480 = x83 * x1371;
    s[269] = x1480;
    let x1481 = x1480 - x1478;
    s[270] = x1481;
    let x1482 = x79 * x1377;
    s[271] = x1482;
    let x1483 = x1482 - x1478;
    s[272] = x1483;
    let x1484 = x1481 + x1483;
    s[273] = x1484;
    let x1505 = x1440 + x1450;
    s[274] = x1505;
    let x1507 = x1477 - x1484;
    s[275] = x1507;
    let x1515 = 0.00000000000000006123233995736766 * x1110;
    s[276] = x1515;
    let x1516 = x1225 + x1515;
    s[277] = x1516;
    let x1517 = 0.00000000000000006123233995736766 * x1121;
    s[278] = x1517;
    let x1520 = x1227 + x1517;
    s[279] = x1520;
    let x1635 = 0.14999999999999997 * x1384;
    s[280] = x1635;
    let x1639 = 0.14999999999999997 * x1394;
    s[281] = x1639;
    let x1643 = 0.14999999999999997 * x1372;
    s[282] = x1643;
}
#[inline(never)]
fn gamma_part_0(s: &[f64; 283], out: &mut [f64; 21]) {
    let x22 = s[0] * s[3];
    let x56 = s[17] * s[19];
    let x59 = s[17] * s[22];
    let x60 = s[16] * s[20];
    let x63 = s[17] * s[23];
    let x64 = s[16] * s[21];
    let x67 = x59 + x60;
    let x70 = x63 - x64;
    let x125 = s[2] * 0.00000000000000006123233995736766;
    let x128 = x22 + x125;
    let x130 = s[14] * 0.00000000000000006123233995736766;
    let x131 = s[6] + x130;
    let x132 = s[15] * 0.00000000000000006123233995736766;
    let x133 = s[7] + x132;
    let x134 = x22 * 0.00000000000000006123233995736766;
    let x135 = x134 - s[2];
    let x719 = s[3] * s[36];
    let x720 = s[0] * s[39];
    let x722 = x719 - x720;
    let x791 = s[19] * s[69];
    let x793 = s[17] * s[71];
    let x795 = x791 + x793;
    let x804 = s[22] * s[69];
    let x806 = s[17] * s[76];
    let x807 = x806 - x804;
    let x808 = s[20] * s[68];
    let x809 = s[16] * s[72];
    let x810 = x808 + x809;
    let x820 = s[23] * s[69];
    let x822 = s[17] * s[79];
    let x823 = x822 - x820;
    let x824 = s[21] * s[68];
    let x825 = s[16] * s[73];
    let x827 = x824 - x825;
    let x830 = x807 + x810;
    let x833 = x823 - x827;
    let x924 = 0.00000000000000006123233995736766 * s[38];
    let x925 = x722 + x924;
    let x926 = 0.00000000000000006123233995736766 * s[66];
    let x927 = x926 - s[44];
    let x928 = 0.00000000000000006123233995736766 * s[67];
    let x929 = s[47] + x928;
    let x930 = 0.00000000000000006123233995736766 * x722;
    let x931 = x930 - s[38];
    let x1142 = s[36] * s[39];
    let x1144 = s[3] * s[96];
    let x1146 = x1142 + x1144;
    let x1148 = s[0] * s[99];
    let x1149 = x1142 + x1148;
    let x1151 = x1146 + x1149;
    let x1172 = s[37] * s[50];
    let x1173 = s[8] * s[97];
    let x1174 = x1172 + x1173;
    let x1177 = s[1] * s[119];
    let x1179 = x1172 + x1177;
    let x1181 = x1174 + x1179;
    let x1183 = s[36] * s[40];
    let x1184 = s[4] * s[96];
    let x1186 = x1183 - x1184;
    let x1187 = s[0] * s[100];
    let x1189 = x1183 - x1187;
    let x1190 = x1186 + x1189;
    let x1206 = s[37] * s[53];
    let x1207 = s[9] * s[97];
    let x1208 = x1206 + x1207;
    let x1211 = s[1] * s[125];
    let x1212 = x1211 - x1206;
    let x1213 = x1212 - x1208;
    let x1214 = s[36] * s[41];
    let x1216 = s[5] * s[96];
    let x1218 = x1214 + x1216;
    let x1220 = s[0] * s[101];
    let x1221 = x1214 + x1220;
    let x1223 = x1218 + x1221;
    let x1226 = x1190 - x1181;
    let x1228 = x1213 + x1223;
    let x1286 = s[69] * s[71];
    let x1288 = s[19] * s[153];
    let x1289 = x1288 - x1286;
    let x1290 = s[17] * s[155];
    let x1291 = x1290 - x1286;
    let x1292 = x1289 + x1291;
    let x1312 = s[69] * s[76];
    let x1313 = s[22] * s[153];
    let x1314 = x1312 + x1313;
    let x1317 = s[17] * s[175];
    let x1319 = x1312 + x1317;
    let x1321 = x1314 + x1319;
    let x1323 = s[68] * s[72];
    let x1324 = s[20] * s[152];
    let x1326 = x1323 - x1324;
    let x1327 = s[16] * s[156];
    let x1329 = x1323 - x1327;
    let x1330 = x1326 + x1329;
    let x1346 = s[69] * s[79];
    let x1347 = s[23] * s[153];
    let x1348 = x1346 + x1347;
    let x1351 = s[17] * s[181];
    let x1352 = x1351 - x1346;
    let x1353 = x1352 - x1348;
    let x1354 = s[68] * s[73];
    let x1356 = s[21] * s[152];
    let x1358 = x1354 + x1356;
    let x1360 = s[16] * s[157];
    let x1361 = x1354 + x1360;
    let x1363 = x1358 + x1361;
    let x1366 = x1330 - x1321;
    let x1368 = x1353 + x1363;
    let x1509 = 0.05 * s[107];
    let x1511 = 0.05 * s[113];
    let x1513 = 0.05 * s[98];
    let x1514 = -x1513;
    let x1522 = 0.00000000000000006123233995736766 * s[98];
    let x1524 = x1151 + x1522;
    let x1526 = 0.00000000000000006123233995736766 * s[150];
    let x1527 = x1526 - s[107];
    let x1528 = 0.00000000000000006123233995736766 * s[151];
    let x1529 = x1528 - s[113];
    let x1530 = 0.00000000000000006123233995736766 * x1151;
    let x1532 = s[98] - x1530;
    let x1533 = 0.17499999999999996 * s[163];
    let x1534 = 0.17499999999999996 * s[169];
    let x1536 = 0.17499999999999996 * s[154];
    let x1567 = x1509 + x1533;
    let x1569 = x1511 + x1534;
    let x1571 = x1513 + x1536;
    let x1572 = x830 * s[93];
    let x1574 = s[33] * x1366;
    let x1575 = x1574 - x1572;
    let x1576 = x67 * s[277];
    let x1577 = x1572 + x1576;
    let x1579 = x1575 - x1577;
    let x1580 = x833 * s[95];
    let x1581 = s[35] * x1368;
    let x1582 = x1580 + x1581;
    let x1583 = x70 * s[279];
    let x1585 = x1580 - x1583;
    let x1586 = x1582 + x1585;
    let x1587 = x795 * x925;
    let x1588 = x128 * x1292;
    let x1589 = x1587 + x1588;
    let x1592 = x56 * x1524;
    let x1594 = x1587 + x1592;
    let x1596 = x1589 + x1594;
    let x1598 = x1579 + x1586;
    let x1599 = x1596 + x1598;
    let x1600 = x830 * x927;
    let x1601 = x131 * x1366;
    let x1602 = x1600 + x1601;
    let x1603 = x67 * x1527;
    let x1604 = x1600 + x1603;
    let x1605 = x1602 + x1604;
    let x1606 = x833 * x929;
    let x1607 = x133 * x1368;
    let x1608 = x1606 + x1607;
    let x1609 = x70 * x1529;
    let x1610 = x1606 + x1609;
    let x1611 = x1608 + x1610;
    let x1612 = x795 * x931;
    let x1613 = x135 * x1292;
    let x1614 = x1612 + x1613;
    let x1617 = x56 * x1532;
    let x1618 = x1617 - x1612;
    let x1619 = x1618 - x1614;
    let x1620 = x1605 + x1611;
    let x1621 = x1619 + x1620;
    let x1622 = 0.175 * s[163];
    let x1624 = 0.000000000000000027755575615628914 * s[212];
    let x1625 = x1624 - x1622;
    let x1626 = 0.175 * s[169];
    let x1628 = 0.000000000000000027755575615628914 * s[213];
    let x1629 = x1628 - x1626;
    let x1630 = 0.175 * s[154];
    let x1632 = 0.000000000000000027755575615628914 * s[187];
    let x1634 = x1630 - x1632;
    let x1637 = 0.000000000000000006938893903907228 * s[274];
    let x1638 = x1637 - s[280];
    let x1641 = 0.000000000000000006938893903907228 * s[275];
    let x1642 = x1641 - s[281];
    let x1645 = 0.000000000000000006938893903907228 * s[249];
    let x1647 = s[282] - x1645;
    let x1649 = x1625 - x1638;
    let x1651 = x1629 - x1642;
    let x1653 = x1634 - x1647;
    let x1727 = -x1226;
    let x1728 = -x1228;
    let x1729 = -x1571;
    let x1730 = -x1599;
    let x1731 = -x1621;
    let x1732 = -x1649;
    let x1733 = -x1651;
    let x1734 = -x1653;
    out[0] = x1509;
    out[1] = x1511;
    out[2] = x1514;
    out[3] = x1727;
    out[4] = x1728;
    out[5] = x1567;
    out[6] = x1569;
    out[7] = x1729;
    out[8] = x1730;
    out[9] = x1731;
    out[10] = x1732;
    out[11] = x1733;
    out[12] = x1734;
}
#[inline(never)]
fn gamma_part_1(t: f64, s: &[f64; 283], out: &mut [f64; 21]) {
    let x5 = 6.283185307179586 * t;
    let x51 = s[19] * s[21];
    let x52 = s[19] * s[20];
    let x55 = s[16] * s[19];
    let x57 = s[16] * s[22];
    let x58 = s[17] * s[20];
    let x61 = s[16] * s[23];
    let x62 = s[17] * s[21];
    let x66 = x57 - x58;
    let x68 = x61 + x62;
    let x89 = s[25] * s[27];
    let x92 = s[25] * s[30];
    let x93 = s[24] * s[28];
    let x96 = s[25] * s[31];
    let x97 = s[24] * s[29];
    let x100 = x92 + x93;
    let x103 = x96 - x97;
    let x155 = x51 * 0.8534911287233514;
    let x157 = x66 * 0.5211073720362623;
    let x159 = x155 - x157;
    let x160 = x52 * 0.8534911287233514;
    let x161 = x68 * 0.5211073720362623;
    let x163 = x160 - x161;
    let x164 = s[18] * 0.8534911287233514;
    let x166 = x55 * 0.5211073720362623;
    let x168 = x164 + x166;
    let x170 = x51 * 0.5211073720362623;
    let x171 = x66 * 0.8534911287233514;
    let x172 = x170 + x171;
    let x173 = x52 * 0.5211073720362623;
    let x174 = x68 * 0.8534911287233514;
    let x175 = x173 + x174;
    let x176 = s[18] * 0.5211073720362623;
    let x178 = x55 * 0.8534911287233514;
    let x179 = x178 - x176;
    let x297 = x5.sin();
    let x298 = x5.cos();
    let x667 = 6.283185307179586 * x298;
    let x669 = 6.283185307179586 * x297;
    let x770 = s[21] * s[71];
    let x772 = s[19] * s[73];
    let x774 = x770 + x772;
    let x776 = s[20] * s[71];
    let x778 = s[19] * s[72];
    let x779 = x778 - x776;
    let x787 = s[19] * s[68];
    let x788 = s[16] * s[71];
    let x790 = x787 - x788;
    let x797 = s[22] * s[68];
    let x798 = s[16] * s[76];
    let x799 = x797 + x798;
    let x800 = s[20] * s[69];
    let x802 = s[17] * s[72];
    let x803 = x802 - x800;
    let x811 = s[23] * s[68];
    let x812 = s[16] * s[79];
    let x813 = x811 + x812;
    let x814 = s[21] * s[69];
    let x816 = s[17] * s[73];
    let x818 = x814 + x816;
    let x829 = x799 - x803;
    let x831 = x813 - x818;
    let x864 = s[27] * s[81];
    let x866 = s[25] * s[83];
    let x868 = x864 + x866;
    let x877 = s[30] * s[81];
    let x879 = s[25] * s[88];
    let x880 = x879 - x877;
    let x881 = s[28] * s[80];
    let x882 = s[24] * s[84];
    let x883 = x881 + x882;
    let x893 = s[31] * s[81];
    let x895 = s[25] * s[91];
    let x896 = x895 - x893;
    let x897 = s[29] * s[80];
    let x898 = s[24] * s[85];
    let x900 = x897 - x898;
    let x903 = x880 + x883;
    let x906 = x896 - x900;
    let x946 = 0.8534911287233514 * x774;
    let x948 = 0.5211073720362623 * x829;
    let x950 = x946 + x948;
    let x952 = 0.8534911287233514 * x779;
    let x953 = 0.5211073720362623 * x831;
    let x955 = x952 - x953;
    let x956 = 0.8534911287233514 * s[70];
    let x957 = 0.5211073720362623 * x790;
    let x958 = x956 + x957;
    let x959 = 0.5211073720362623 * x774;
    let x961 = 0.8534911287233514 * x829;
    let x962 = x961 - x959;
    let x963 = 0.5211073720362623 * x779;
    let x964 = 0.8534911287233514 * x831;
    let x965 = x963 + x964;
    let x966 = 0.5211073720362623 * s[70];
    let x968 = 0.8534911287233514 * x790;
    let x969 = x968 - x966;
    let x1082 = 6.283185307179586 * x669;
    let x1084 = 6.283185307179586 * x667;
    let x1085 = x667 * s[93];
    let x1087 = s[33] * x1082;
    let x1089 = x1085 + x1087;
    let x1091 = x669 * s[95];
    let x1092 = s[35] * x1084;
    let x1093 = x1091 + x1092;
    let x1426 = s[81] * s[83];
    let x1428 = s[27] * s[215];
    let x1429 = x1428 - x1426;
    let x1430 = s[25] * s[217];
    let x1431 = x1430 - x1426;
    let x1432 = x1429 + x1431;
    let x1452 = s[81] * s[88];
    let x1453 = s[30] * s[215];
    let x1454 = x1452 + x1453;
    let x1457 = s[25] * s[237];
    let x1459 = x1452 + x1457;
    let x1461 = x1454 + x1459;
    let x1463 = s[80] * s[84];
    let x1464 = s[28] * s[214];
    let x1466 = x1463 - x1464;
    let x1467 = s[24] * s[218];
    let x1469 = x1463 - x1467;
    let x1470 = x1466 + x1469;
    let x1486 = s[81] * s[91];
    let x1487 = s[31] * s[215];
    let x1488 = x1486 + x1487;
    let x1491 = s[25] * s[243];
    let x1492 = x1491 - x1486;
    let x1493 = x1492 - x1488;
    let x1494 = s[80] * s[85];
    let x1496 = s[29] * s[214];
    let x1498 = x1494 + x1496;
    let x1500 = s[24] * s[219];
    let x1501 = x1494 + x1500;
    let x1503 = x1498 + x1501;
    let x1506 = x1470 - x1461;
    let x1508 = x1493 + x1503;
    let x1538 = 0.8534911287233514 * s[163];
    let x1539 = 0.5211073720362623 * s[212];
    let x1540 = x1538 + x1539;
    let x1541 = 0.8534911287233514 * s[169];
    let x1543 = 0.5211073720362623 * s[213];
    let x1545 = x1541 + x1543;
    let x1547 = 0.8534911287233514 * s[154];
    let x1549 = 0.5211073720362623 * s[187];
    let x1551 = x1547 + x1549;
    let x1553 = 0.5211073720362623 * s[163];
    let x1555 = 0.8534911287233514 * s[212];
    let x1556 = x1555 - x1553;
    let x1557 = 0.5211073720362623 * s[169];
    let x1559 = 0.8534911287233514 * s[213];
    let x1560 = x1559 - x1557;
    let x1561 = 0.5211073720362623 * s[154];
    let x1563 = 0.8534911287233514 * s[187];
    let x1565 = x1561 - x1563;
    let x1654 = x903 * x950;
    let x1656 = x159 * x1506;
    let x1657 = x1656 - x1654;
    let x1658 = x100 * x1540;
    let x1659 = x1654 + x1658;
    let x1661 = x1657 - x1659;
    let x1662 = x906 * x955;
    let x1663 = x163 * x1508;
    let x1664 = x1662 + x1663;
    let x1665 = x103 * x1545;
    let x1667 = x1662 - x1665;
    let x1668 = x1664 + x1667;
    let x1669 = x868 * x958;
    let x1670 = x168 * x1432;
    let x1671 = x1669 + x1670;
    let x1674 = x89 * x1551;
    let x1676 = x1669 + x1674;
    let x1678 = x1671 + x1676;
    let x1680 = x1661 + x1668;
    let x1681 = x1678 + x1680;
    let x1682 = x903 * x962;
    let x1683 = x172 * x1506;
    let x1684 = x1682 + x1683;
    let x1685 = x100 * x1556;
    let x1686 = x1682 + x1685;
    let x1687 = x1684 + x1686;
    let x1688 = x906 * x965;
    let x1689 = x175 * x1508;
    let x1690 = x1688 + x1689;
    let x1691 = x103 * x1560;
    let x1692 = x1688 + x1691;
    let x1693 = x1690 + x1692;
    let x1694 = x868 * x969;
    let x1695 = x179 * x1432;
    let x1696 = x1694 + x1695;
    let x1699 = x89 * x1565;
    let x1700 = x1699 - x1694;
    let x1701 = x1700 - x1696;
    let x1702 = x1687 + x1693;
    let x1703 = x1701 + x1702;
    let x1704 = 0.00000000000000004163336342344337 * s[274];
    let x1705 = s[280] + x1704;
    let x1706 = 0.00000000000000004163336342344337 * s[275];
    let x1707 = s[281] + x1706;
    let x1708 = 0.00000000000000004163336342344337 * s[249];
    let x1710 = s[282] + x1708;
    let x1711 = -x1710;
    let x1714 = x297 * s[277];
    let x1715 = x1085 + x1714;
    let x1717 = x1089 + x1715;
    let x1720 = x298 * s[279];
    let x1722 = x1091 + x1720;
    let x1724 = x1093 + x1722;
    let x1726 = x1724 - x1717;
    let x1735 = -x1681;
    let x1736 = -x1703;
    let x1737 = -x1506;
    let x1738 = -x1508;
    let x1739 = -x1726;
    out[13] = x1735;
    out[14] = x1736;
    out[15] = x1705;
    out[16] = x1707;
    out[17] = x1711;
    out[18] = x1737;
    out[19] = x1738;
    out[20] = x1739;
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
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 18] = qd.try_into().expect("qd must have n_coords entries");
    let phi: &mut [f64; 21] = phi.try_into().expect("phi must have 21 entries");
    let phi_q: &mut [f64; 96] = phi_q.try_into().expect("phi_q must have 96 entries");
    let phi_t: &mut [f64; 21] = phi_t.try_into().expect("phi_t must have 21 entries");
    let gamma: &mut [f64; 21] = gamma.try_into().expect("gamma must have 21 entries");
    let mut s = [0.0f64; 279];
    eval_kinematics_shared_0(q, qd, t, &mut s);
    eval_kinematics_part_0(q, &s, phi, phi_q, phi_t, gamma);
    eval_kinematics_part_1(q, &s, phi, phi_q, phi_t, gamma);
    eval_kinematics_part_2(&s, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_shared_0(q: &[f64; 18], qd: &[f64; 18], t: f64, s: &mut [f64; 279]) {
    let x5 = 6.283185307179586 * t;
    s[0] = x5;
    let x12 = q[3].sin();
    s[1] = x12;
    let x13 = q[3].cos();
    s[2] = x13;
    let x14 = q[4].sin();
    s[3] = x14;
    let x15 = q[4].cos();
    s[4] = x15;
    let x16 = q[5].sin();
    s[5] = x16;
    let x17 = q[5].cos();
    s[6] = x17;
    let x18 = x15 * x17;
    s[7] = x18;
    let x19 = x15 * x16;
    s[8] = x19;
    let x20 = x14 * x17;
    s[9] = x20;
    let x21 = x14 * x16;
    s[10] = x21;
    let x24 = x12 * x20;
    s[11] = x24;
    let x25 = x13 * x16;
    s[12] = x25;
    let x26 = x13 * x20;
    s[13] = x26;
    let x27 = x12 * x16;
    s[14] = x27;
    let x28 = x12 * x21;
    s[15] = x28;
    let x29 = x13 * x17;
    s[16] = x29;
    let x30 = x13 * x21;
    s[17] = x30;
    let x31 = x12 * x17;
    s[18] = x31;
    let x33 = x24 - x25;
    s[19] = x33;
    let x34 = x26 + x27;
    s[20] = x34;
    let x35 = x28 + x29;
    s[21] = x35;
    let x37 = x30 - x31;
    s[22] = x37;
    let x45 = q[9].sin();
    s[23] = x45;
    let x46 = q[9].cos();
    s[24] = x46;
    let x47 = q[10].sin();
    s[25] = x47;
    let x48 = q[10].cos();
    s[26] = x48;
    let x49 = q[11].sin();
    s[27] = x49;
    let x50 = q[11].cos();
    s[28] = x50;
    let x51 = x48 * x50;
    s[29] = x51;
    let x52 = x48 * x49;
    s[30] = x52;
    let x53 = x47 * x50;
    s[31] = x53;
    let x54 = x47 * x49;
    s[32] = x54;
    let x55 = x45 * x48;
    s[33] = x55;
    let x56 = x46 * x48;
    s[34] = x56;
    let x57 = x45 * x53;
    s[35] = x57;
    let x58 = x46 * x49;
    s[36] = x58;
    let x59 = x46 * x53;
    s[37] = x59;
    let x60 = x45 * x49;
    s[38] = x60;
    let x61 = x45 * x54;
    s[39] = x61;
    let x62 = x46 * x50;
    s[40] = x62;
    let x63 = x46 * x54;
    s[41] = x63;
    let x64 = x45 * x50;
    s[42] = x64;
    let x66 = x57 - x58;
    s[43] = x66;
    let x67 = x59 + x60;
    s[44] = x67;
    let x68 = x61 + x62;
    s[45] = x68;
    let x70 = x63 - x64;
    s[46] = x70;
    let x78 = q[15].sin();
    s[47] = x78;
    let x79 = q[15].cos();
    s[48] = x79;
    let x80 = q[16].sin();
    s[49] = x80;
    let x81 = q[16].cos();
    s[50] = x81;
    let x82 = q[17].sin();
    s[51] = x82;
    let x83 = q[17].cos();
    s[52] = x83;
    let x84 = x81 * x83;
    s[53] = x84;
    let x85 = x81 * x82;
    s[54] = x85;
    let x86 = x80 * x83;
    s[55] = x86;
    let x87 = x80 * x82;
    s[56] = x87;
    let x90 = x78 * x86;
    s[57] = x90;
    let x91 = x79 * x82;
    s[58] = x91;
    let x92 = x79 * x86;
    s[59] = x92;
    let x93 = x78 * x82;
    s[60] = x93;
    let x94 = x78 * x87;
    s[61] = x94;
    let x95 = x79 * x83;
    s[62] = x95;
    let x99 = x90 - x91;
    s[63] = x99;
    let x100 = x92 + x93;
    s[64] = x100;
    let x101 = x94 + x95;
    s[65] = x101;
    let x119 = x18 * 0.00000000000000006123233995736766;
    s[66] = x119;
    let x121 = x119 - x33;
    s[67] = x121;
    let x122 = x19 * 0.00000000000000006123233995736766;
    s[68] = x122;
    let x124 = x122 - x35;
    s[69] = x124;
    let x214 = x84 * 0.14999999999999997;
    s[70] = x214;
    let x215 = x99 * 0.000000000000000006938893903907228;
    s[71] = x215;
    let x216 = x214 + x215;
    s[72] = x216;
    let x217 = x85 * 0.14999999999999997;
    s[73] = x217;
    let x297 = x5.sin();
    s[74] = x297;
    let x298 = x5.cos();
    s[75] = x298;
    let x338 = x12 * x18;
    s[76] = x338;
    let x340 = x12 * x19;
    s[77] = x340;
    let x349 = x20 * 0.00000000000000006123233995736766;
    s[78] = x349;
    let x352 = x338 + x349;
    s[79] = x352;
    let x354 = x21 * 0.00000000000000006123233995736766;
    s[80] = x354;
    let x357 = x340 + x354;
    s[81] = x357;
    let x395 = x35 - x122;
    s[82] = x395;
    let x463 = x45 * x51;
    s[83] = x463;
    let x465 = x45 * x52;
    s[84] = x465;
    let x609 = x78 * x84;
    s[85] = x609;
    let x613 = x86 * 0.14999999999999997;
    s[86] = x613;
    let x693 = x13 * qd[3];
    s[87] = x693;
    let x694 = x12 * qd[3];
    s[88] = x694;
    let x696 = x15 * qd[4];
    s[89] = x696;
    let x697 = x14 * qd[4];
    s[90] = x697;
    let x699 = x17 * qd[5];
    s[91] = x699;
    let x700 = x16 * qd[5];
    s[92] = x700;
    let x702 = x17 * x697;
    s[93] = x702;
    let x704 = x15 * x700;
    s[94] = x704;
    let x706 = x702 + x704;
    s[95] = x706;
    let x708 = x16 * x697;
    s[96] = x708;
    let x710 = x15 * x699;
    s[97] = x710;
    let x711 = x710 - x708;
    s[98] = x711;
    let x712 = x17 * x696;
    s[99] = x712;
    let x713 = x14 * x700;
    s[100] = x713;
    let x715 = x712 - x713;
    s[101] = x715;
    let x716 = x16 * x696;
    s[102] = x716;
    let x717 = x14 * x699;
    s[103] = x717;
    let x718 = x716 + x717;
    s[104] = x718;
    let x723 = x20 * x693;
    s[105] = x723;
    let x724 = x12 * x715;
    s[106] = x724;
    let x725 = x723 + x724;
    s[107] = x725;
    let x726 = x16 * x694;
    s[108] = x726;
    let x728 = x13 * x699;
    s[109] = x728;
    let x729 = x728 - x726;
    s[110] = x729;
    let x737 = x21 * x693;
    s[111] = x737;
    let x738 = x12 * x718;
    s[112] = x738;
    let x739 = x737 + x738;
    s[113] = x739;
    let x740 = x17 * x694;
    s[114] = x740;
    let x742 = x13 * x700;
    s[115] = x742;
    let x744 = x740 + x742;
    s[116] = x744;
    let x755 = x725 - x729;
    s[117] = x755;
    let x757 = x739 - x744;
    s[118] = x757;
    let x761 = x46 * qd[9];
    s[119] = x761;
    let x762 = x45 * qd[9];
    s[120] = x762;
    let x764 = x48 * qd[10];
    s[121] = x764;
    let x765 = x47 * qd[10];
    s[122] = x765;
    let x767 = x50 * qd[11];
    s[123] = x767;
    let x768 = x49 * qd[11];
    s[124] = x768;
    let x780 = x50 * x764;
    s[125] = x780;
    let x781 = x47 * x768;
    s[126] = x781;
    let x783 = x780 - x781;
    s[127] = x783;
    let x784 = x49 * x764;
    s[128] = x784;
    let x785 = x47 * x767;
    s[129] = x785;
    let x786 = x784 + x785;
    s[130] = x786;
    let x834 = x79 * qd[15];
    s[131] = x834;
    let x835 = x78 * qd[15];
    s[132] = x835;
    let x837 = x81 * qd[16];
    s[133] = x837;
    let x838 = x80 * qd[16];
    s[134] = x838;
    let x840 = x83 * qd[17];
    s[135] = x840;
    let x841 = x82 * qd[17];
    s[136] = x841;
    let x853 = x83 * x837;
    s[137] = x853;
    let x854 = x80 * x841;
    s[138] = x854;
    let x856 = x853 - x854;
    s[139] = x856;
    let x916 = 0.00000000000000006123233995736766 * x706;
    s[140] = x916;
    let x919 = x755 + x916;
    s[141] = x919;
    let x921 = 0.00000000000000006123233995736766 * x711;
    s[142] = x921;
    let x923 = x921 - x757;
    s[143] = x923;
    let x1095 = qd[3] * x694;
    s[144] = x1095;
    let x1097 = qd[3] * x693;
    s[145] = x1097;
    let x1098 = qd[4] * x697;
    s[146] = x1098;
    let x1100 = qd[4] * x696;
    s[147] = x1100;
    let x1101 = qd[5] * x700;
    s[148] = x1101;
    let x1103 = qd[5] * x699;
    s[149] = x1103;
    let x1104 = x697 * x700;
    s[150] = x1104;
    let x1106 = x17 * x1100;
    s[151] = x1106;
    let x1107 = x1106 - x1104;
    s[152] = x1107;
    let x1108 = x15 * x1103;
    s[153] = x1108;
    let x1109 = x1108 - x1104;
    s[154] = x1109;
    let x1110 = x1107 + x1109;
    s[155] = x1110;
    let x1112 = x697 * x699;
    s[156] = x1112;
    let x1113 = x16 * x1100;
    s[157] = x1113;
    let x1114 = x1112 + x1113;
    s[158] = x1114;
    let x1117 = x15 * x1101;
    s[159] = x1117;
    let x1119 = x1112 + x1117;
    s[160] = x1119;
    let x1121 = x1114 + x1119;
    s[161] = x1121;
    let x1123 = x696 * x700;
    s[162] = x1123;
    let x1125 = x17 * x1098;
    s[163] = x1125;
    let x1127 = x1123 + x1125;
    s[164] = x1127;
    let x1129 = x14 * x1103;
    s[165] = x1129;
    let x1130 = x1123 + x1129;
    s[166] = x1130;
    let x1132 = x1127 + x1130;
    s[167] = x1132;
    let x1134 = x696 * x699;
    s[168] = x1134;
    let x1135 = x16 * x1098;
    s[169] = x1135;
    let x1137 = x1134 - x1135;
    s[170] = x1137;
    let x1138 = x14 * x1101;
    s[171] = x1138;
    let x1140 = x1134 - x1138;
    s[172] = x1140;
    let x1141 = x1137 + x1140;
    s[173] = x1141;
    let x1153 = x693 * x715;
    s[174] = x1153;
    let x1154 = x20 * x1095;
    s[175] = x1154;
    let x1156 = x1153 - x1154;
    s[176] = x1156;
    let x1157 = x12 * x1132;
    s[177] = x1157;
    let x1159 = x1153 - x1157;
    s[178] = x1159;
    let x1160 = x1156 + x1159;
    s[179] = x1160;
    let x1161 = x694 * x699;
    s[180] = x1161;
    let x1162 = x16 * x1097;
    s[181] = x1162;
    let x1163 = x1161 + x1162;
    s[182] = x1163;
    let x1166 = x13 * x1101;
    s[183] = x1166;
    let x1168 = x1161 + x1166;
    s[184] = x1168;
    let x1170 = x1163 + x1168;
    s[185] = x1170;
    let x1191 = x693 * x718;
    s[186] = x1191;
    let x1192 = x21 * x1095;
    s[187] = x1192;
    let x1194 = x1191 - x1192;
    s[188] = x1194;
    let x1195 = x12 * x1141;
    s[189] = x1195;
    let x1196 = x1191 + x1195;
    s[190] = x1196;
    let x1197 = x1194 + x1196;
    s[191] = x1197;
    let x1198 = x694 * x700;
    s[192] = x1198;
    let x1200 = x17 * x1097;
    s[193] = x1200;
    let x1201 = x1200 - x1198;
    s[194] = x1201;
    let x1202 = x13 * x1103;
    s[195] = x1202;
    let x1203 = x1202 - x1198;
    s[196] = x1203;
    let x1204 = x1201 + x1203;
    s[197] = x1204;
    let x1225 = x1160 + x1170;
    s[198] = x1225;
    let x1227 = x1197 - x1204;
    s[199] = x1227;
    let x1229 = qd[9] * x762;
    s[200] = x1229;
    let x1231 = qd[9] * x761;
    s[201] = x1231;
    let x1232 = qd[10] * x765;
    s[202] = x1232;
    let x1234 = qd[10] * x764;
    s[203] = x1234;
    let x1235 = qd[11] * x768;
    s[204] = x1235;
    let x1237 = qd[11] * x767;
    s[205] = x1237;
    let x1238 = x765 * x768;
    s[206] = x1238;
    let x1240 = x50 * x1234;
    s[207] = x1240;
    let x1241 = x1240 - x1238;
    s[208] = x1241;
    let x1242 = x48 * x1237;
    s[209] = x1242;
    let x1243 = x1242 - x1238;
    s[210] = x1243;
    let x1244 = x1241 + x1243;
    s[211] = x1244;
    let x1245 = x765 * x767;
    s[212] = x1245;
    let x1246 = x49 * x1234;
    s[213] = x1246;
    let x1247 = x1245 + x1246;
    s[214] = x1247;
    let x1250 = x48 * x1235;
    s[215] = x1250;
    let x1252 = x1245 + x1250;
    s[216] = x1252;
    let x1254 = x1247 + x1252;
    s[217] = x1254;
    let x1256 = x764 * x768;
    s[218] = x1256;
    let x1258 = x50 * x1232;
    s[219] = x1258;
    let x1260 = x1256 + x1258;
    s[220] = x1260;
    let x1262 = x47 * x1237;
    s[221] = x1262;
    let x1263 = x1256 + x1262;
    s[222] = x1263;
    let x1265 = x1260 + x1263;
    s[223] = x1265;
    let x1267 = x764 * x767;
    s[224] = x1267;
    let x1268 = x49 * x1232;
    s[225] = x1268;
    let x1270 = x1267 - x1268;
    s[226] = x1270;
    let x1271 = x47 * x1235;
    s[227] = x1271;
    let x1273 = x1267 - x1271;
    s[228] = x1273;
    let x1274 = x1270 + x1273;
    s[229] = x1274;
    let x1293 = x761 * x783;
    s[230] = x1293;
    let x1294 = x53 * x1229;
    s[231] = x1294;
    let x1296 = x1293 - x1294;
    s[232] = x1296;
    let x1297 = x45 * x1265;
    s[233] = x1297;
    let x1299 = x1293 - x1297;
    s[234] = x1299;
    let x1300 = x1296 + x1299;
    s[235] = x1300;
    let x1301 = x762 * x767;
    s[236] = x1301;
    let x1302 = x49 * x1231;
    s[237] = x1302;
    let x1303 = x1301 + x1302;
    s[238] = x1303;
    let x1306 = x46 * x1235;
    s[239] = x1306;
    let x1308 = x1301 + x1306;
    s[240] = x1308;
    let x1310 = x1303 + x1308;
    s[241] = x1310;
    let x1365 = x1300 + x1310;
    s[242] = x1365;
    let x1369 = qd[15] * x835;
    s[243] = x1369;
    let x1371 = qd[15] * x834;
    s[244] = x1371;
    let x1372 = qd[16] * x838;
    s[245] = x1372;
    let x1374 = qd[16] * x837;
    s[246] = x1374;
    let x1375 = qd[17] * x841;
    s[247] = x1375;
    let x1377 = qd[17] * x840;
    s[248] = x1377;
    let x1378 = x838 * x841;
    s[249] = x1378;
    let x1380 = x83 * x1374;
    s[250] = x1380;
    let x1381 = x1380 - x1378;
    s[251] = x1381;
    let x1382 = x81 * x1377;
    s[252] = x1382;
    let x1383 = x1382 - x1378;
    s[253] = x1383;
    let x1384 = x1381 + x1383;
    s[254] = x1384;
    let x1396 = x837 * x841;
    s[255] = x1396;
    let x1398 = x83 * x1372;
    s[256] = x1398;
    let x1400 = x1396 + x1398;
    s[257] = x1400;
    let x1402 = x80 * x1377;
    s[258] = x1402;
    let x1403 = x1396 + x1402;
    s[259] = x1403;
    let x1405 = x1400 + x1403;
    s[260] = x1405;
    let x1433 = x834 * x856;
    s[261] = x1433;
    let x1434 = x86 * x1369;
    s[262] = x1434;
    let x1436 = x1433 - x1434;
    s[263] = x1436;
    let x1437 = x78 * x1405;
    s[264] = x1437;
    let x1439 = x1433 - x1437;
    s[265] = x1439;
    let x1440 = x1436 + x1439;
    s[266] = x1440;
    let x1441 = x835 * x840;
    s[267] = x1441;
    let x1442 = x82 * x1371;
    s[268] = x1442;
    let x1443 = x1441 + x1442;
    s[269] = x1443;
    let x1446 = x79 * x1375;
    s[270] = x1446;
    let x1448 = x1441 + x1446;
    s[271] = x1448;
    let x1450 = x1443 + x1448;
    s[272] = x1450;
    let x1505 = x1440 + x1450;
    s[273] = x1505;
    let x1515 = 0.00000000000000006123233995736766 * x1110;
    s[274] = x1515;
    let x1516 = x1225 + x1515;
    s[275] = x1516;
    let x1517 = 0.00000000000000006123233995736766 * x1121;
    s[276] = x1517;
    let x1520 = x1227 + x1517;
    s[277] = x1520;
    let x1635 = 0.14999999999999997 * x1384;
    s[278] = x1635;
}
#[inline(never)]
fn eval_kinematics_part_0(
    q: &[f64; 18],
    s: &[f64; 279],
    phi: &mut [f64; 21],
    phi_q: &mut [f64; 96],
    phi_t: &mut [f64; 21],
    gamma: &mut [f64; 21],
) {
    let x22 = s[1] * s[4];
    let x23 = s[2] * s[4];
    let x108 = s[7] * 0.05;
    let x110 = s[8] * 0.05;
    let x111 = -x110;
    let x112 = s[3] * 0.05;
    let x114 = q[0] - x108;
    let x115 = q[1] - x110;
    let x116 = q[2] + x112;
    let x123 = -s[21];
    let x125 = s[3] * 0.00000000000000006123233995736766;
    let x128 = x22 + x125;
    let x130 = s[19] * 0.00000000000000006123233995736766;
    let x131 = s[7] + x130;
    let x132 = s[21] * 0.00000000000000006123233995736766;
    let x133 = s[8] + x132;
    let x134 = x22 * 0.00000000000000006123233995736766;
    let x135 = x134 - s[3];
    let x136 = -x114;
    let x137 = -x115;
    let x138 = -x116;
    let x139 = q[0] + x108;
    let x140 = q[1] + x110;
    let x141 = q[2] - x112;
    let x144 = s[29] * 0.17499999999999996;
    let x146 = s[30] * 0.17499999999999996;
    let x147 = -x146;
    let x148 = s[25] * 0.17499999999999996;
    let x150 = q[6] - x144;
    let x151 = q[7] - x146;
    let x152 = q[8] + x148;
    let x181 = x139 - x150;
    let x183 = x140 - x151;
    let x185 = x141 - x152;
    let x186 = s[44] * s[67];
    let x187 = s[46] * s[69];
    let x188 = s[34] * x128;
    let x190 = x186 + x187;
    let x191 = x190 - x188;
    let x192 = s[44] * x131;
    let x193 = s[46] * x133;
    let x194 = s[34] * x135;
    let x195 = x192 + x193;
    let x196 = x194 + x195;
    let x199 = s[29] * 0.175;
    let x200 = s[43] * 0.000000000000000027755575615628914;
    let x201 = x199 + x200;
    let x202 = s[30] * 0.175;
    let x203 = s[45] * 0.000000000000000027755575615628914;
    let x204 = x202 + x203;
    let x209 = q[6] + x201;
    let x210 = q[7] + x204;
    let x218 = s[65] * 0.000000000000000006938893903907228;
    let x219 = s[73] + x218;
    let x224 = q[12] + s[72];
    let x225 = q[13] + x219;
    let x263 = x209 - x224;
    let x265 = x210 - x225;
    let x307 = s[12] - s[11];
    let x311 = s[20] * 0.00000000000000006123233995736766;
    let x312 = s[22] * 0.00000000000000006123233995736766;
    let x313 = x23 * 0.00000000000000006123233995736766;
    let x314 = s[20] * s[44];
    let x316 = s[22] * s[46];
    let x318 = x23 * s[34];
    let x320 = x314 + x316;
    let x322 = x318 + x320;
    let x323 = -x322;
    let x324 = s[44] * x311;
    let x325 = s[46] * x312;
    let x326 = s[34] * x313;
    let x327 = x324 + x325;
    let x328 = x326 + x327;
    let x336 = s[1] * s[3];
    let x339 = s[2] * s[7];
    let x341 = s[2] * s[8];
    let x343 = s[9] * 0.05;
    let x344 = -x343;
    let x345 = s[10] * 0.05;
    let x346 = -x345;
    let x347 = s[4] * 0.05;
    let x348 = -x347;
    let x359 = s[4] * 0.00000000000000006123233995736766;
    let x360 = x359 - x336;
    let x361 = 0.00000000000000006123233995736766 * s[76];
    let x362 = x361 - s[9];
    let x363 = 0.00000000000000006123233995736766 * s[77];
    let x364 = x363 - s[10];
    let x365 = 0.00000000000000006123233995736766 * x336;
    let x367 = s[4] + x365;
    let x369 = s[44] * s[79];
    let x371 = s[46] * s[81];
    let x373 = s[34] * x360;
    let x375 = x369 + x371;
    let x377 = x373 + x375;
    let x378 = -x377;
    let x379 = s[44] * x362;
    let x380 = s[46] * x364;
    let x381 = s[34] * x367;
    let x383 = x379 + x380;
    let x384 = x383 - x381;
    let x393 = s[18] - s[17];
    let x398 = s[44] * s[82];
    let x399 = s[46] * s[67];
    let x400 = x398 + x399;
    let x401 = s[44] * x133;
    let x403 = s[46] * x131;
    let x404 = x403 - x401;
    let x414 = s[36] - s[35];
    let x425 = s[67] * x414;
    let x426 = s[45] * s[69];
    let x428 = s[33] * x128;
    let x430 = x425 - x426;
    let x431 = x428 + x430;
    let x432 = x131 * x414;
    let x433 = s[45] * x133;
    let x435 = s[33] * x135;
    let x437 = x432 - x433;
    let x438 = x437 - x435;
    let x439 = s[44] * 0.000000000000000027755575615628914;
    let x440 = s[46] * 0.000000000000000027755575615628914;
    let x461 = s[24] * s[25];
    let x464 = s[24] * s[29];
    let x466 = s[24] * s[30];
    let x467 = s[31] * 0.17499999999999996;
    let x468 = -x467;
    let x469 = s[32] * 0.17499999999999996;
    let x470 = -x469;
    let x471 = s[26] * 0.17499999999999996;
    let x502 = -x471;
    let x503 = s[67] * x464;
    let x504 = s[69] * x466;
    let x505 = x128 * x461;
    let x507 = x503 + x504;
    let x508 = x505 + x507;
    let x509 = x131 * x464;
    let x510 = x133 * x466;
    let x511 = x135 * x461;
    let x513 = x509 + x510;
    let x514 = x513 - x511;
    let x515 = s[31] * 0.175;
    let x517 = 0.000000000000000027755575615628914 * s[83];
    let x518 = x517 - x515;
    let x519 = s[32] * 0.175;
    let x521 = 0.000000000000000027755575615628914 * s[84];
    let x522 = x521 - x519;
    let x548 = s[42] - s[41];
    let x554 = s[67] * x548;
    let x555 = s[44] * s[69];
    let x556 = x554 + x555;
    let x557 = x131 * x548;
    let x558 = x401 + x557;
    let x561 = -x204;
    let x577 = s[64] * 0.000000000000000006938893903907228;
    let x580 = -x577;
    let x615 = 0.000000000000000006938893903907228 * s[85];
    let x616 = x615 - s[86];
    let x627 = -x616;
    let x719 = s[4] * s[87];
    let x720 = s[1] * s[90];
    let x722 = x719 - x720;
    let x791 = s[26] * s[120];
    let x793 = s[24] * s[122];
    let x795 = x791 + x793;
    let x804 = s[31] * s[120];
    let x806 = s[24] * s[127];
    let x807 = x806 - x804;
    let x808 = s[27] * s[119];
    let x809 = s[23] * s[123];
    let x810 = x808 + x809;
    let x820 = s[32] * s[120];
    let x822 = s[24] * s[130];
    let x823 = x822 - x820;
    let x824 = s[28] * s[119];
    let x825 = s[23] * s[124];
    let x827 = x824 - x825;
    let x830 = x807 + x810;
    let x833 = x823 - x827;
    let x924 = 0.00000000000000006123233995736766 * s[89];
    let x925 = x722 + x924;
    let x926 = 0.00000000000000006123233995736766 * s[117];
    let x927 = x926 - s[95];
    let x928 = 0.00000000000000006123233995736766 * s[118];
    let x929 = s[98] + x928;
    let x930 = 0.00000000000000006123233995736766 * x722;
    let x931 = x930 - s[89];
    let x1142 = s[87] * s[90];
    let x1144 = s[4] * s[144];
    let x1146 = x1142 + x1144;
    let x1148 = s[1] * s[147];
    let x1149 = x1142 + x1148;
    let x1151 = x1146 + x1149;
    let x1172 = s[88] * s[101];
    let x1173 = s[9] * s[145];
    let x1174 = x1172 + x1173;
    let x1177 = s[2] * s[167];
    let x1179 = x1172 + x1177;
    let x1181 = x1174 + x1179;
    let x1183 = s[87] * s[91];
    let x1184 = s[5] * s[144];
    let x1186 = x1183 - x1184;
    let x1187 = s[1] * s[148];
    let x1189 = x1183 - x1187;
    let x1190 = x1186 + x1189;
    let x1206 = s[88] * s[104];
    let x1207 = s[10] * s[145];
    let x1208 = x1206 + x1207;
    let x1211 = s[2] * s[173];
    let x1212 = x1211 - x1206;
    let x1213 = x1212 - x1208;
    let x1214 = s[87] * s[92];
    let x1216 = s[6] * s[144];
    let x1218 = x1214 + x1216;
    let x1220 = s[1] * s[149];
    let x1221 = x1214 + x1220;
    let x1223 = x1218 + x1221;
    let x1226 = x1190 - x1181;
    let x1228 = x1213 + x1223;
    let x1286 = s[120] * s[122];
    let x1288 = s[26] * s[201];
    let x1289 = x1288 - x1286;
    let x1290 = s[24] * s[203];
    let x1291 = x1290 - x1286;
    let x1292 = x1289 + x1291;
    let x1312 = s[120] * s[127];
    let x1313 = s[31] * s[201];
    let x1314 = x1312 + x1313;
    let x1317 = s[24] * s[223];
    let x1319 = x1312 + x1317;
    let x1321 = x1314 + x1319;
    let x1323 = s[119] * s[123];
    let x1324 = s[27] * s[200];
    let x1326 = x1323 - x1324;
    let x1327 = s[23] * s[204];
    let x1329 = x1323 - x1327;
    let x1330 = x1326 + x1329;
    let x1346 = s[120] * s[130];
    let x1347 = s[32] * s[201];
    let x1348 = x1346 + x1347;
    let x1351 = s[24] * s[229];
    let x1352 = x1351 - x1346;
    let x1353 = x1352 - x1348;
    let x1354 = s[119] * s[124];
    let x1356 = s[28] * s[200];
    let x1358 = x1354 + x1356;
    let x1360 = s[23] * s[205];
    let x1361 = x1354 + x1360;
    let x1363 = x1358 + x1361;
    let x1366 = x1330 - x1321;
    let x1368 = x1353 + x1363;
    let x1509 = 0.05 * s[155];
    let x1511 = 0.05 * s[161];
    let x1513 = 0.05 * s[146];
    let x1514 = -x1513;
    let x1522 = 0.00000000000000006123233995736766 * s[146];
    let x1524 = x1151 + x1522;
    let x1526 = 0.00000000000000006123233995736766 * s[198];
    let x1527 = x1526 - s[155];
    let x1528 = 0.00000000000000006123233995736766 * s[199];
    let x1529 = x1528 - s[161];
    let x1530 = 0.00000000000000006123233995736766 * x1151;
    let x1532 = s[146] - x1530;
    let x1533 = 0.17499999999999996 * s[211];
    let x1534 = 0.17499999999999996 * s[217];
    let x1536 = 0.17499999999999996 * s[202];
    let x1567 = x1509 + x1533;
    let x1569 = x1511 + x1534;
    let x1571 = x1513 + x1536;
    let x1572 = x830 * s[141];
    let x1574 = s[67] * x1366;
    let x1575 = x1574 - x1572;
    let x1576 = s[44] * s[275];
    let x1577 = x1572 + x1576;
    let x1579 = x1575 - x1577;
    let x1580 = x833 * s[143];
    let x1581 = s[69] * x1368;
    let x1582 = x1580 + x1581;
    let x1583 = s[46] * s[277];
    let x1585 = x1580 - x1583;
    let x1586 = x1582 + x1585;
    let x1587 = x795 * x925;
    let x1588 = x128 * x1292;
    let x1589 = x1587 + x1588;
    let x1592 = s[34] * x1524;
    let x1594 = x1587 + x1592;
    let x1596 = x1589 + x1594;
    let x1598 = x1579 + x1586;
    let x1599 = x1596 + x1598;
    let x1600 = x830 * x927;
    let x1601 = x131 * x1366;
    let x1602 = x1600 + x1601;
    let x1603 = s[44] * x1527;
    let x1604 = x1600 + x1603;
    let x1605 = x1602 + x1604;
    let x1606 = x833 * x929;
    let x1607 = x133 * x1368;
    let x1608 = x1606 + x1607;
    let x1609 = s[46] * x1529;
    let x1610 = x1606 + x1609;
    let x1611 = x1608 + x1610;
    let x1612 = x795 * x931;
    let x1613 = x135 * x1292;
    let x1614 = x1612 + x1613;
    let x1617 = s[34] * x1532;
    let x1618 = x1617 - x1612;
    let x1619 = x1618 - x1614;
    let x1620 = x1605 + x1611;
    let x1621 = x1619 + x1620;
    let x1622 = 0.175 * s[211];
    let x1624 = 0.000000000000000027755575615628914 * s[242];
    let x1625 = x1624 - x1622;
    let x1637 = 0.000000000000000006938893903907228 * s[273];
    let x1638 = x1637 - s[278];
    let x1649 = x1625 - x1638;
    let x1727 = -x1226;
    let x1728 = -x1228;
    let x1729 = -x1571;
    let x1730 = -x1599;
    let x1731 = -x1621;
    let x1732 = -x1649;
    phi[0] = x136;
    phi_q[0] = -1.0;
    phi_q[1] = x344;
    phi_q[2] = x111;
    phi_t[0] = 0.0;
    gamma[0] = x1509;
    phi[1] = x137;
    phi_q[3] = -1.0;
    phi_q[4] = x346;
    phi_q[5] = x108;
    phi_t[1] = 0.0;
    gamma[1] = x1511;
    phi[2] = x138;
    phi_q[6] = -1.0;
    phi_q[7] = x348;
    phi_t[2] = 0.0;
    gamma[2] = x1514;
    phi[3] = s[20];
    phi_q[8] = x307;
    phi_q[9] = x339;
    phi_q[10] = x393;
    phi_t[3] = 0.0;
    gamma[3] = x1727;
    phi[4] = s[22];
    phi_q[11] = x123;
    phi_q[12] = x341;
    phi_q[13] = s[20];
    phi_t[4] = 0.0;
    gamma[4] = x1728;
    phi[5] = x181;
    phi_q[14] = 1.0;
    phi_q[15] = x344;
    phi_q[16] = x111;
    phi_q[17] = -1.0;
    phi_q[18] = x468;
    phi_q[19] = x147;
    phi_t[5] = 0.0;
    gamma[5] = x1567;
    phi[6] = x183;
    phi_q[20] = 1.0;
    phi_q[21] = x346;
    phi_q[22] = x108;
    phi_q[23] = -1.0;
    phi_q[24] = x470;
    phi_q[25] = x144;
    phi_t[6] = 0.0;
    gamma[6] = x1569;
    phi[7] = x185;
    phi_q[26] = 1.0;
    phi_q[27] = x348;
    phi_q[28] = -1.0;
    phi_q[29] = x502;
    phi_t[7] = 0.0;
    gamma[7] = x1729;
    phi[8] = x191;
    phi_q[30] = x323;
    phi_q[31] = x378;
    phi_q[32] = x400;
    phi_q[33] = x431;
    phi_q[34] = x508;
    phi_q[35] = x556;
    phi_t[8] = 0.0;
    gamma[8] = x1730;
    phi[9] = x196;
    phi_q[36] = x328;
    phi_q[37] = x384;
    phi_q[38] = x404;
    phi_q[39] = x438;
    phi_q[40] = x514;
    phi_q[41] = x558;
    phi_t[9] = 0.0;
    gamma[9] = x1731;
    phi[10] = x263;
    phi_q[42] = 1.0;
    phi_q[43] = x439;
    phi_q[44] = x518;
    phi_q[45] = x561;
    phi_q[46] = -1.0;
    phi_q[47] = x580;
    phi_q[48] = x627;
    phi_q[49] = x219;
    phi_t[10] = 0.0;
    gamma[10] = x1732;
    phi[11] = x265;
    phi_q[50] = 1.0;
    phi_q[51] = x440;
    phi_q[52] = x522;
    phi_q[53] = x201;
    phi_q[54] = -1.0;
}
#[inline(never)]
fn eval_kinematics_part_1(
    q: &[f64; 18],
    s: &[f64; 279],
    phi: &mut [f64; 21],
    phi_q: &mut [f64; 96],
    phi_t: &mut [f64; 21],
    gamma: &mut [f64; 21],
) {
    let x88 = s[47] * s[50];
    let x89 = s[48] * s[50];
    let x96 = s[48] * s[56];
    let x97 = s[47] * s[52];
    let x103 = x96 - x97;
    let x155 = s[29] * 0.8534911287233514;
    let x157 = s[43] * 0.5211073720362623;
    let x159 = x155 - x157;
    let x160 = s[30] * 0.8534911287233514;
    let x161 = s[45] * 0.5211073720362623;
    let x163 = x160 - x161;
    let x164 = s[25] * 0.8534911287233514;
    let x166 = s[33] * 0.5211073720362623;
    let x168 = x164 + x166;
    let x170 = s[29] * 0.5211073720362623;
    let x171 = s[43] * 0.8534911287233514;
    let x172 = x170 + x171;
    let x173 = s[30] * 0.5211073720362623;
    let x174 = s[45] * 0.8534911287233514;
    let x175 = x173 + x174;
    let x176 = s[25] * 0.5211073720362623;
    let x178 = s[33] * 0.8534911287233514;
    let x179 = x178 - x176;
    let x205 = s[25] * 0.175;
    let x207 = s[33] * 0.000000000000000027755575615628914;
    let x208 = x207 - x205;
    let x211 = q[8] + x208;
    let x220 = s[49] * 0.14999999999999997;
    let x222 = x88 * 0.000000000000000006938893903907228;
    let x223 = x222 - x220;
    let x226 = q[14] + x223;
    let x267 = x211 - x226;
    let x268 = s[64] * x159;
    let x269 = x103 * x163;
    let x270 = x89 * x168;
    let x272 = x268 + x269;
    let x273 = x272 - x270;
    let x274 = s[64] * x172;
    let x275 = x103 * x175;
    let x276 = x89 * x179;
    let x277 = x274 + x275;
    let x278 = x276 + x277;
    let x283 = s[63] * 0.00000000000000004163336342344337;
    let x284 = x283 - s[70];
    let x286 = s[65] * 0.00000000000000004163336342344337;
    let x287 = x286 - s[73];
    let x288 = x88 * 0.00000000000000004163336342344337;
    let x289 = x220 + x288;
    let x290 = q[12] + x284;
    let x291 = q[13] + x287;
    let x292 = q[14] + x289;
    let x294 = 0.4 - x290;
    let x295 = -x291;
    let x296 = -x292;
    let x299 = s[67] * s[74];
    let x300 = s[69] * s[75];
    let x302 = x299 - x300;
    let x329 = s[20] * s[74];
    let x331 = s[22] * s[75];
    let x333 = x331 - x329;
    let x385 = s[74] * s[79];
    let x387 = s[75] * s[81];
    let x389 = x387 - x385;
    let x405 = s[74] * s[82];
    let x406 = s[67] * s[75];
    let x408 = x405 - x406;
    let x417 = s[44] * 0.5211073720362623;
    let x419 = s[46] * 0.5211073720362623;
    let x421 = s[34] * 0.5211073720362623;
    let x422 = s[44] * 0.8534911287233514;
    let x423 = s[46] * 0.8534911287233514;
    let x424 = s[34] * 0.8534911287233514;
    let x441 = s[34] * 0.000000000000000027755575615628914;
    let x442 = s[64] * x417;
    let x444 = x103 * x419;
    let x446 = x89 * x421;
    let x448 = x442 + x444;
    let x450 = x446 + x448;
    let x451 = -x450;
    let x452 = s[64] * x422;
    let x453 = x103 * x423;
    let x454 = x89 * x424;
    let x455 = x452 + x453;
    let x456 = x454 + x455;
    let x459 = s[23] * s[25];
    let x472 = s[31] * 0.8534911287233514;
    let x474 = 0.5211073720362623 * s[83];
    let x476 = x472 + x474;
    let x478 = s[32] * 0.8534911287233514;
    let x480 = 0.5211073720362623 * s[84];
    let x482 = x478 + x480;
    let x484 = s[26] * 0.8534911287233514;
    let x485 = 0.5211073720362623 * x459;
    let x487 = x484 - x485;
    let x488 = s[31] * 0.5211073720362623;
    let x490 = 0.8534911287233514 * s[83];
    let x491 = x490 - x488;
    let x492 = s[32] * 0.5211073720362623;
    let x494 = 0.8534911287233514 * s[84];
    let x495 = x494 - x492;
    let x496 = s[26] * 0.5211073720362623;
    let x498 = 0.8534911287233514 * x459;
    let x500 = x496 + x498;
    let x523 = s[26] * 0.175;
    let x525 = 0.000000000000000027755575615628914 * x459;
    let x527 = x523 + x525;
    let x528 = -x527;
    let x529 = s[64] * x476;
    let x531 = x103 * x482;
    let x533 = x89 * x487;
    let x535 = x529 + x531;
    let x537 = x533 + x535;
    let x538 = -x537;
    let x539 = s[64] * x491;
    let x540 = x103 * x495;
    let x541 = x89 * x500;
    let x543 = x539 + x540;
    let x544 = x543 - x541;
    let x550 = x161 - x160;
    let x562 = s[64] * x550;
    let x563 = x103 * x159;
    let x564 = x562 + x563;
    let x565 = s[64] * x175;
    let x567 = x103 * x172;
    let x568 = x567 - x565;
    let x574 = s[58] - s[57];
    let x576 = -s[65];
    let x578 = x103 * 0.000000000000000006938893903907228;
    let x579 = x89 * 0.000000000000000006938893903907228;
    let x581 = -x578;
    let x582 = -x579;
    let x583 = x159 * x574;
    let x584 = s[65] * x163;
    let x586 = x88 * x168;
    let x588 = x583 - x584;
    let x589 = x586 + x588;
    let x590 = x172 * x574;
    let x591 = s[65] * x175;
    let x593 = x88 * x179;
    let x595 = x590 - x591;
    let x596 = x595 - x593;
    let x597 = s[64] * 0.00000000000000004163336342344337;
    let x598 = x103 * 0.00000000000000004163336342344337;
    let x599 = x89 * 0.00000000000000004163336342344337;
    let x600 = -x597;
    let x601 = -x598;
    let x602 = -x599;
    let x605 = s[47] * s[49];
    let x607 = s[48] * s[49];
    let x610 = s[48] * s[53];
    let x611 = s[47] * s[54];
    let x612 = s[48] * s[54];
    let x617 = s[56] * 0.14999999999999997;
    let x619 = 0.000000000000000006938893903907228 * x611;
    let x620 = x619 - x617;
    let x621 = s[50] * 0.14999999999999997;
    let x623 = 0.000000000000000006938893903907228 * x605;
    let x625 = x621 + x623;
    let x628 = -x620;
    let x629 = x159 * x610;
    let x630 = x163 * x612;
    let x631 = x168 * x607;
    let x633 = x629 + x630;
    let x634 = x631 + x633;
    let x635 = x172 * x610;
    let x636 = x175 * x612;
    let x637 = x179 * x607;
    let x639 = x635 + x636;
    let x640 = x639 - x637;
    let x641 = 0.00000000000000004163336342344337 * s[85];
    let x642 = s[86] + x641;
    let x643 = 0.00000000000000004163336342344337 * x611;
    let x644 = x617 + x643;
    let x645 = 0.00000000000000004163336342344337 * x605;
    let x647 = x621 - x645;
    let x648 = -x642;
    let x649 = -x644;
    let x650 = -x647;
    let x654 = x97 - x96;
    let x657 = -s[72];
    let x658 = x159 * x654;
    let x659 = s[64] * x163;
    let x660 = x658 + x659;
    let x661 = x172 * x654;
    let x662 = x565 + x661;
    let x664 = s[73] - x286;
    let x665 = -x664;
    let x666 = -x284;
    let x770 = s[28] * s[122];
    let x772 = s[26] * s[124];
    let x774 = x770 + x772;
    let x776 = s[27] * s[122];
    let x778 = s[26] * s[123];
    let x779 = x778 - x776;
    let x787 = s[26] * s[119];
    let x788 = s[23] * s[122];
    let x790 = x787 - x788;
    let x797 = s[31] * s[119];
    let x798 = s[23] * s[127];
    let x799 = x797 + x798;
    let x800 = s[27] * s[120];
    let x802 = s[24] * s[123];
    let x803 = x802 - x800;
    let x811 = s[32] * s[119];
    let x812 = s[23] * s[130];
    let x813 = x811 + x812;
    let x814 = s[28] * s[120];
    let x816 = s[24] * s[124];
    let x818 = x814 + x816;
    let x829 = x799 - x803;
    let x831 = x813 - x818;
    let x857 = s[51] * s[133];
    let x858 = s[49] * s[135];
    let x859 = x857 + x858;
    let x864 = s[50] * s[132];
    let x866 = s[48] * s[134];
    let x868 = x864 + x866;
    let x877 = s[55] * s[132];
    let x879 = s[48] * s[139];
    let x880 = x879 - x877;
    let x881 = s[51] * s[131];
    let x882 = s[47] * s[135];
    let x883 = x881 + x882;
    let x893 = s[56] * s[132];
    let x895 = s[48] * x859;
    let x896 = x895 - x893;
    let x897 = s[52] * s[131];
    let x898 = s[47] * s[136];
    let x900 = x897 - x898;
    let x903 = x880 + x883;
    let x906 = x896 - x900;
    let x946 = 0.8534911287233514 * x774;
    let x948 = 0.5211073720362623 * x829;
    let x950 = x946 + x948;
    let x952 = 0.8534911287233514 * x779;
    let x953 = 0.5211073720362623 * x831;
    let x955 = x952 - x953;
    let x956 = 0.8534911287233514 * s[121];
    let x957 = 0.5211073720362623 * x790;
    let x958 = x956 + x957;
    let x959 = 0.5211073720362623 * x774;
    let x961 = 0.8534911287233514 * x829;
    let x962 = x961 - x959;
    let x963 = 0.5211073720362623 * x779;
    let x964 = 0.8534911287233514 * x831;
    let x965 = x963 + x964;
    let x966 = 0.5211073720362623 * s[121];
    let x968 = 0.8534911287233514 * x790;
    let x969 = x968 - x966;
    let x1275 = s[119] * s[122];
    let x1277 = s[26] * s[200];
    let x1279 = x1275 + x1277;
    let x1281 = s[23] * s[203];
    let x1282 = x1275 + x1281;
    let x1284 = x1279 + x1282;
    let x1331 = s[119] * s[130];
    let x1332 = s[32] * s[200];
    let x1334 = x1331 - x1332;
    let x1335 = s[23] * s[229];
    let x1336 = x1331 + x1335;
    let x1337 = x1334 + x1336;
    let x1338 = s[120] * s[124];
    let x1340 = s[28] * s[201];
    let x1341 = x1340 - x1338;
    let x1342 = s[24] * s[205];
    let x1343 = x1342 - x1338;
    let x1344 = x1341 + x1343;
    let x1367 = x1337 - x1344;
    let x1385 = s[134] * s[135];
    let x1386 = s[51] * s[246];
    let x1387 = x1385 + x1386;
    let x1390 = s[50] * s[247];
    let x1392 = x1385 + x1390;
    let x1394 = x1387 + x1392;
    let x1407 = s[133] * s[135];
    let x1408 = s[51] * s[245];
    let x1410 = x1407 - x1408;
    let x1411 = s[49] * s[247];
    let x1413 = x1407 - x1411;
    let x1414 = x1410 + x1413;
    let x1415 = s[131] * s[134];
    let x1417 = s[50] * s[243];
    let x1419 = x1415 + x1417;
    let x1421 = s[47] * s[246];
    let x1422 = x1415 + x1421;
    let x1424 = x1419 + x1422;
    let x1426 = s[132] * s[134];
    let x1428 = s[50] * s[244];
    let x1429 = x1428 - x1426;
    let x1430 = s[48] * s[246];
    let x1431 = x1430 - x1426;
    let x1432 = x1429 + x1431;
    let x1452 = s[132] * s[139];
    let x1453 = s[55] * s[244];
    let x1454 = x1452 + x1453;
    let x1457 = s[48] * s[260];
    let x1459 = x1452 + x1457;
    let x1461 = x1454 + x1459;
    let x1463 = s[131] * s[135];
    let x1464 = s[51] * s[243];
    let x1466 = x1463 - x1464;
    let x1467 = s[47] * s[247];
    let x1469 = x1463 - x1467;
    let x1470 = x1466 + x1469;
    let x1471 = s[131] * x859;
    let x1472 = s[56] * s[243];
    let x1474 = x1471 - x1472;
    let x1475 = s[47] * x1414;
    let x1476 = x1471 + x1475;
    let x1477 = x1474 + x1476;
    let x1478 = s[132] * s[136];
    let x1480 = s[52] * s[244];
    let x1481 = x1480 - x1478;
    let x1482 = s[48] * s[248];
    let x1483 = x1482 - x1478;
    let x1484 = x1481 + x1483;
    let x1486 = s[132] * x859;
    let x1487 = s[56] * s[244];
    let x1488 = x1486 + x1487;
    let x1491 = s[48] * x1414;
    let x1492 = x1491 - x1486;
    let x1493 = x1492 - x1488;
    let x1494 = s[131] * s[136];
    let x1496 = s[52] * s[243];
    let x1498 = x1494 + x1496;
    let x1500 = s[47] * s[248];
    let x1501 = x1494 + x1500;
    let x1503 = x1498 + x1501;
    let x1506 = x1470 - x1461;
    let x1507 = x1477 - x1484;
    let x1508 = x1493 + x1503;
    let x1538 = 0.8534911287233514 * s[211];
    let x1539 = 0.5211073720362623 * s[242];
    let x1540 = x1538 + x1539;
    let x1541 = 0.8534911287233514 * s[217];
    let x1543 = 0.5211073720362623 * x1367;
    let x1545 = x1541 + x1543;
    let x1547 = 0.8534911287233514 * s[202];
    let x1549 = 0.5211073720362623 * x1284;
    let x1551 = x1547 + x1549;
    let x1553 = 0.5211073720362623 * s[211];
    let x1555 = 0.8534911287233514 * s[242];
    let x1556 = x1555 - x1553;
    let x1557 = 0.5211073720362623 * s[217];
    let x1559 = 0.8534911287233514 * x1367;
    let x1560 = x1559 - x1557;
    let x1561 = 0.5211073720362623 * s[202];
    let x1563 = 0.8534911287233514 * x1284;
    let x1565 = x1561 - x1563;
    let x1626 = 0.175 * s[217];
    let x1628 = 0.000000000000000027755575615628914 * x1367;
    let x1629 = x1628 - x1626;
    let x1630 = 0.175 * s[202];
    let x1632 = 0.000000000000000027755575615628914 * x1284;
    let x1634 = x1630 - x1632;
    let x1639 = 0.14999999999999997 * x1394;
    let x1641 = 0.000000000000000006938893903907228 * x1507;
    let x1642 = x1641 - x1639;
    let x1643 = 0.14999999999999997 * s[245];
    let x1645 = 0.000000000000000006938893903907228 * x1424;
    let x1647 = x1643 - x1645;
    let x1651 = x1629 - x1642;
    let x1653 = x1634 - x1647;
    let x1654 = x903 * x950;
    let x1656 = x159 * x1506;
    let x1657 = x1656 - x1654;
    let x1658 = s[64] * x1540;
    let x1659 = x1654 + x1658;
    let x1661 = x1657 - x1659;
    let x1662 = x906 * x955;
    let x1663 = x163 * x1508;
    let x1664 = x1662 + x1663;
    let x1665 = x103 * x1545;
    let x1667 = x1662 - x1665;
    let x1668 = x1664 + x1667;
    let x1669 = x868 * x958;
    let x1670 = x168 * x1432;
    let x1671 = x1669 + x1670;
    let x1674 = x89 * x1551;
    let x1676 = x1669 + x1674;
    let x1678 = x1671 + x1676;
    let x1680 = x1661 + x1668;
    let x1681 = x1678 + x1680;
    let x1682 = x903 * x962;
    let x1683 = x172 * x1506;
    let x1684 = x1682 + x1683;
    let x1685 = s[64] * x1556;
    let x1686 = x1682 + x1685;
    let x1687 = x1684 + x1686;
    let x1688 = x906 * x965;
    let x1689 = x175 * x1508;
    let x1690 = x1688 + x1689;
    let x1691 = x103 * x1560;
    let x1692 = x1688 + x1691;
    let x1693 = x1690 + x1692;
    let x1694 = x868 * x969;
    let x1695 = x179 * x1432;
    let x1696 = x1694 + x1695;
    let x1699 = x89 * x1565;
    let x1700 = x1699 - x1694;
    let x1701 = x1700 - x1696;
    let x1702 = x1687 + x1693;
    let x1703 = x1701 + x1702;
    let x1704 = 0.00000000000000004163336342344337 * s[273];
    let x1705 = s[278] + x1704;
    let x1706 = 0.00000000000000004163336342344337 * x1507;
    let x1707 = x1639 + x1706;
    let x1708 = 0.00000000000000004163336342344337 * x1424;
    let x1710 = x1643 + x1708;
    let x1711 = -x1710;
    let x1733 = -x1651;
    let x1734 = -x1653;
    let x1735 = -x1681;
    let x1736 = -x1703;
    let x1737 = -x1506;
    let x1738 = -x1508;
    phi_q[55] = x581;
    phi_q[56] = x628;
    phi_q[57] = x657;
    phi_t[11] = 0.0;
    gamma[11] = x1733;
    phi[12] = x267;
    phi_q[58] = 1.0;
    phi_q[59] = x441;
    phi_q[60] = x528;
    phi_q[61] = -1.0;
    phi_q[62] = x582;
    phi_q[63] = x625;
    phi_t[12] = 0.0;
    gamma[12] = x1734;
    phi[13] = x273;
    phi_q[64] = x451;
    phi_q[65] = x538;
    phi_q[66] = x564;
    phi_q[67] = x589;
    phi_q[68] = x634;
    phi_q[69] = x660;
    phi_t[13] = 0.0;
    gamma[13] = x1735;
    phi[14] = x278;
    phi_q[70] = x456;
    phi_q[71] = x544;
    phi_q[72] = x568;
    phi_q[73] = x596;
    phi_q[74] = x640;
    phi_q[75] = x662;
    phi_t[14] = 0.0;
    gamma[14] = x1736;
    phi[15] = x294;
    phi_q[76] = -1.0;
    phi_q[77] = x600;
    phi_q[78] = x648;
    phi_q[79] = x665;
    phi_t[15] = 0.0;
    gamma[15] = x1705;
    phi[16] = x295;
    phi_q[80] = -1.0;
    phi_q[81] = x601;
    phi_q[82] = x649;
    phi_q[83] = x666;
    phi_t[16] = 0.0;
    gamma[16] = x1707;
    phi[17] = x296;
    phi_q[84] = -1.0;
    phi_q[85] = x602;
    phi_q[86] = x650;
    phi_t[17] = 0.0;
    gamma[17] = x1711;
    phi[18] = s[64];
    phi_q[87] = x574;
    phi_q[88] = x610;
    phi_q[89] = x654;
    phi_t[18] = 0.0;
    gamma[18] = x1737;
    phi[19] = x103;
    phi_q[90] = x576;
    phi_q[91] = x612;
    phi_q[92] = s[64];
    phi_t[19] = 0.0;
    gamma[19] = x1738;
    phi[20] = x302;
    phi_q[93] = x333;
    phi_q[94] = x389;
    phi_q[95] = x408;
}
#[inline(never)]
fn eval_kinematics_part_2(s: &[f64; 279], phi_t: &mut [f64; 21], gamma: &mut [f64; 21]) {
    let x667 = 6.283185307179586 * s[75];
    let x669 = 6.283185307179586 * s[74];
    let x671 = s[67] * x667;
    let x672 = s[69] * x669;
    let x674 = x671 + x672;
    let x1082 = 6.283185307179586 * x669;
    let x1084 = 6.283185307179586 * x667;
    let x1085 = x667 * s[141];
    let x1087 = s[67] * x1082;
    let x1089 = x1085 + x1087;
    let x1091 = x669 * s[143];
    let x1092 = s[69] * x1084;
    let x1093 = x1091 + x1092;
    let x1714 = s[74] * s[275];
    let x1715 = x1085 + x1714;
    let x1717 = x1089 + x1715;
    let x1720 = s[75] * s[277];
    let x1722 = x1091 + x1720;
    let x1724 = x1093 + x1722;
    let x1726 = x1724 - x1717;
    let x1739 = -x1726;
    phi_t[20] = x674;
    gamma[20] = x1739;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
    let k: &[f64; 2] = k.try_into().expect("k must have 2 entries");
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = k;
    potential_into_part_0(q, out);
}
#[inline(never)]
fn potential_into_part_0(q: &[f64; 18], out: &mut [f64; 1]) {
    let x1758 = q[1] * 1.9620000000000002;
    let x1761 = q[7] * 4.905;
    let x1764 = q[13] * 3.9240000000000004;
    let x1765 = x1758 + x1761;
    let x1766 = x1764 + x1765;
    out[0] = x1766;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 2] = k.try_into().expect("k must have 2 entries");
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 18] = qd.try_into().expect("qd must have n_coords entries");
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
pub const N_COORDS: usize = 18usize;
/// Number of constraint rows.
pub const N_CONSTRAINTS: usize = 21usize;
/// Row of each Φq nonzero.
pub static PHI_Q_ROWS: [u32; 96usize] = [
    0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 2u32, 2u32, 3u32, 3u32, 3u32, 4u32, 4u32, 4u32,
    5u32, 5u32, 5u32, 5u32, 5u32, 5u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32, 7u32, 7u32,
    7u32, 7u32, 8u32, 8u32, 8u32, 8u32, 8u32, 8u32, 9u32, 9u32, 9u32, 9u32, 9u32, 9u32,
    10u32, 10u32, 10u32, 10u32, 10u32, 10u32, 10u32, 10u32, 11u32, 11u32, 11u32, 11u32,
    11u32, 11u32, 11u32, 11u32, 12u32, 12u32, 12u32, 12u32, 12u32, 12u32, 13u32, 13u32,
    13u32, 13u32, 13u32, 13u32, 14u32, 14u32, 14u32, 14u32, 14u32, 14u32, 15u32, 15u32,
    15u32, 15u32, 16u32, 16u32, 16u32, 16u32, 17u32, 17u32, 17u32, 18u32, 18u32, 18u32,
    19u32, 19u32, 19u32, 20u32, 20u32, 20u32,
];
/// Column of each Φq nonzero.
pub static PHI_Q_COLS: [u32; 96usize] = [
    0u32, 4u32, 5u32, 1u32, 4u32, 5u32, 2u32, 4u32, 3u32, 4u32, 5u32, 3u32, 4u32, 5u32,
    0u32, 4u32, 5u32, 6u32, 10u32, 11u32, 1u32, 4u32, 5u32, 7u32, 10u32, 11u32, 2u32,
    4u32, 8u32, 10u32, 3u32, 4u32, 5u32, 9u32, 10u32, 11u32, 3u32, 4u32, 5u32, 9u32,
    10u32, 11u32, 6u32, 9u32, 10u32, 11u32, 12u32, 15u32, 16u32, 17u32, 7u32, 9u32,
    10u32, 11u32, 13u32, 15u32, 16u32, 17u32, 8u32, 9u32, 10u32, 14u32, 15u32, 16u32,
    9u32, 10u32, 11u32, 15u32, 16u32, 17u32, 9u32, 10u32, 11u32, 15u32, 16u32, 17u32,
    12u32, 15u32, 16u32, 17u32, 13u32, 15u32, 16u32, 17u32, 14u32, 15u32, 16u32, 15u32,
    16u32, 17u32, 15u32, 16u32, 17u32, 3u32, 4u32, 5u32,
];
/// Bodies in coordinate order.
pub static BODIES: [BodyInfo; 3usize] = [
    BodyInfo {
        name: "crank",
        coord_offset: 0usize,
        rotation: Rotation::Euler,
        mass: 0.2f64,
        inertia: [0.0001f64, 0.00016666666666666672f64, 0.00016666666666666672f64],
    },
    BodyInfo {
        name: "coupler",
        coord_offset: 6usize,
        rotation: Rotation::Euler,
        mass: 0.5f64,
        inertia: [0.0001f64, 0.005104166666666666f64, 0.005104166666666666f64],
    },
    BodyInfo {
        name: "rocker",
        coord_offset: 12usize,
        rotation: Rotation::Euler,
        mass: 0.4f64,
        inertia: [0.0001f64, 0.0029999999999999996f64, 0.0029999999999999996f64],
    },
];
/// Joints in row order, then drivers.
pub static JOINTS: [JointInfo; 5usize] = [
    JointInfo {
        name: "a0",
        kind: JointKind::Revolute,
        body1: None,
        body2: Some(0usize),
        row_start: 0usize,
        rows: 5usize,
        point1: [0f64, 0f64, 0f64],
        point2: [-0.05f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
    JointInfo {
        name: "a1",
        kind: JointKind::Revolute,
        body1: Some(0usize),
        body2: Some(1usize),
        row_start: 5usize,
        rows: 5usize,
        point1: [0.05f64, 0f64, 0f64],
        point2: [-0.17499999999999996f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
    JointInfo {
        name: "b1",
        kind: JointKind::Revolute,
        body1: Some(1usize),
        body2: Some(2usize),
        row_start: 10usize,
        rows: 5usize,
        point1: [0.175f64, 0.000000000000000027755575615628914f64, 0f64],
        point2: [0.14999999999999997f64, 0.000000000000000006938893903907228f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
    JointInfo {
        name: "b0",
        kind: JointKind::Revolute,
        body1: None,
        body2: Some(2usize),
        row_start: 15usize,
        rows: 5usize,
        point1: [0.4f64, 0f64, 0f64],
        point2: [-0.14999999999999997f64, 0.00000000000000004163336342344337f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
    JointInfo {
        name: "motor",
        kind: JointKind::Driver,
        body1: None,
        body2: Some(0usize),
        row_start: 20usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [-0.05f64, 0f64, 0f64],
        effort_sign: -1f64,
        effort_unit: "N·m",
    },
];
/// Name of each coordinate.
pub static COORD_NAMES: [&str; 18usize] = [
    "crank.x",
    "crank.y",
    "crank.z",
    "crank.theta",
    "crank.beta",
    "crank.gamma",
    "coupler.x",
    "coupler.y",
    "coupler.z",
    "coupler.theta",
    "coupler.beta",
    "coupler.gamma",
    "rocker.x",
    "rocker.y",
    "rocker.z",
    "rocker.theta",
    "rocker.beta",
    "rocker.gamma",
];
/// Name of each constraint row.
pub static ROW_NAMES: [&str; 21usize] = [
    "a0.x",
    "a0.y",
    "a0.z",
    "a0.dot1(x1,z2)",
    "a0.dot1(y1,z2)",
    "a1.x",
    "a1.y",
    "a1.z",
    "a1.dot1(x1,z2)",
    "a1.dot1(y1,z2)",
    "b1.x",
    "b1.y",
    "b1.z",
    "b1.dot1(x1,z2)",
    "b1.dot1(y1,z2)",
    "b0.x",
    "b0.y",
    "b0.z",
    "b0.dot1(x1,z2)",
    "b0.dot1(y1,z2)",
    "motor",
];
/// Initial coordinates: the file's pose, assembled.
pub static Q0: [f64; 18usize] = [
    0.000000000000000003061616997868383f64,
    0.05f64,
    0f64,
    0f64,
    0f64,
    1.5707963267948966f64,
    0.1493609475265865f64,
    0.1911937901063459f64,
    0f64,
    0f64,
    0f64,
    0.5481478992387209f64,
    0.34936094752658653f64,
    0.14119379010634592f64,
    0f64,
    0f64,
    0f64,
    1.9151556505110297f64,
];
/// Initial velocities from the file (to be projected onto the constraints).
pub static QD0: [f64; 18usize] = [
    0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64,
    0f64, 0f64, 0f64, 0f64,
];
/// Constraint rows dependent on others at the initial pose (dropped by the solvers).
pub static REDUNDANT_ROWS: [u32; 3usize] = [17u32, 18u32, 19u32];
/// Simulation end time suggested by the mechanism file (s).
pub const T_END: f64 = 2f64;
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
pub const N_K: usize = 2;
/// `setup` at the file's parameter values: what the types without parameters read.
pub static K: [f64; 2] = [0.0001f64, 0.0001f64];
/// The values the per-step functions read (`k`), from the run-time parameters `p`.
pub fn setup(p: &[f64], k: &mut [f64]) {
    let p: &[f64; 1] = p.try_into().expect("p must have 1 entries");
    let k: &mut [f64; 2] = k.try_into().expect("k must have 2 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 1], k: &mut [f64; 2]) {
    let x1829 = 2.0 * p[0];
    let x1830 = 0.5 * x1829;
    k[0] = p[0];
    k[1] = x1830;
}
/// The parameters the generated code takes at run time: the file's `[parameters]`
/// entries that reach only masses, inertias and springs' constants (the others are set on
/// the file).
pub static PARAMETERS: [&str; 1] = ["rod"];
/// Their values in the file.
pub static PARAMETER_VALUES: [f64; 1] = [0.0001f64];
static OTHER_PARAMETERS: [&str; 12] = [
    "a",
    "ax",
    "ay",
    "b",
    "bx",
    "by",
    "c",
    "d",
    "e",
    "kappa",
    "psi",
    "theta0",
];
static BODY_NAMES: [&str; 3] = ["crank", "coupler", "rocker"];
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
    let p: &[f64; 1] = p.try_into().expect("p must have 1 entries");
    let out: &mut [f64; 12] = out.try_into().expect("out must have 12 entries");
    mass_properties_part_0(p, out);
}
#[inline(never)]
fn mass_properties_part_0(p: &[f64; 1], out: &mut [f64; 12]) {
    out[0] = 0.2;
    out[1] = p[0];
    out[2] = 0.00016666666666666672;
    out[3] = 0.00016666666666666672;
    out[4] = 0.5;
    out[5] = p[0];
    out[6] = 0.005104166666666666;
    out[7] = 0.005104166666666666;
    out[8] = 0.4;
    out[9] = p[0];
    out[10] = 0.0029999999999999996;
    out[11] = 0.0029999999999999996;
}
/// Each force's stiffness and damping at the run-time parameters `p`.
pub fn force_constants(p: &[f64], out: &mut [f64]) {
    let p: &[f64; 1] = p.try_into().expect("p must have 1 entries");
    let _: &mut [f64; 0] = out.try_into().expect("out must have 0 entries");
    let _ = p;
}
/// One set of run-time parameter values and the values `setup` computed from it.
#[derive(Debug, Clone)]
pub struct Parameters {
    p: [f64; 1],
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
        let (mut props, mut constants) = ([0.0; 12], [0.0; 0]);
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
/// This mechanism at other values of its run-time parameters, for the registries.
pub static RUN_TIME_ENTRY: symbody_runtime::registry::RunTime = symbody_runtime::registry::RunTime {
    parameters: &RUN_TIME,
    build: at_parameters,
    build_reduced: None,
};
/// The `exact` formulation: mass matrix and forces derived from the exact kinetic energy.
pub mod exact {
    use super::*;
    /// Row of each mass-matrix nonzero (both triangles).
    pub static MASS_ROWS: [u32; 30usize] = [
        0u32, 1u32, 2u32, 3u32, 3u32, 4u32, 4u32, 5u32, 5u32, 5u32, 6u32, 7u32, 8u32,
        9u32, 9u32, 10u32, 10u32, 11u32, 11u32, 11u32, 12u32, 13u32, 14u32, 15u32, 15u32,
        16u32, 16u32, 17u32, 17u32, 17u32,
    ];
    /// Column of each mass-matrix nonzero.
    pub static MASS_COLS: [u32; 30usize] = [
        0u32, 1u32, 2u32, 3u32, 5u32, 4u32, 5u32, 3u32, 4u32, 5u32, 6u32, 7u32, 8u32,
        9u32, 11u32, 10u32, 11u32, 9u32, 10u32, 11u32, 12u32, 13u32, 14u32, 15u32, 17u32,
        16u32, 17u32, 15u32, 16u32, 17u32,
    ];
    /// Row and column of each ∂Q/∂q nonzero.
    pub static FORCE_Q_ROWS: [u32; 0usize] = [];
    pub static FORCE_Q_COLS: [u32; 0usize] = [];
    /// Row and column of each ∂Q/∂q̇ nonzero.
    pub static FORCE_QD_ROWS: [u32; 0usize] = [];
    pub static FORCE_QD_COLS: [u32; 0usize] = [];
    /// Sizes, patterns and names for this formulation.
    pub static INFO: MechanismInfo = MechanismInfo {
        name: "four_bar",
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
        let k: &[f64; 2] = k.try_into().expect("k must have 2 entries");
        let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 18] = qd.try_into().expect("qd must have n_coords entries");
        let _: &mut [f64; 0] = dq.try_into().expect("dq must have 0 entries");
        let _: &mut [f64; 0] = dqd.try_into().expect("dqd must have 0 entries");
        let _ = k;
        let _ = q;
        let _ = qd;
        let _ = t;
    }
    /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
    pub fn mass(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 2] = k.try_into().expect("k must have 2 entries");
        let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 30] = out.try_into().expect("out must have 30 entries");
        mass_part_0(k, q, out);
    }
    #[inline(never)]
    fn mass_part_0(k: &[f64; 2], q: &[f64; 18], out: &mut [f64; 30]) {
        let x12 = q[3].sin();
        let x13 = q[3].cos();
        let x14 = q[4].sin();
        let x15 = q[4].cos();
        let x22 = x12 * x15;
        let x23 = x13 * x15;
        let x45 = q[9].sin();
        let x46 = q[9].cos();
        let x47 = q[10].sin();
        let x48 = q[10].cos();
        let x55 = x45 * x48;
        let x56 = x46 * x48;
        let x78 = q[15].sin();
        let x79 = q[15].cos();
        let x80 = q[16].sin();
        let x81 = q[16].cos();
        let x88 = x78 * x81;
        let x89 = x79 * x81;
        let x1831 = 2.0 * x14;
        let x1837 = 2.0 * x13;
        let x1838 = 2.0 * x12;
        let x1840 = x13 * x1837;
        let x1841 = 0.00016666666666666672 * x1840;
        let x1842 = x12 * x1838;
        let x1844 = 0.00016666666666666672 * x1842;
        let x1846 = x1841 + x1844;
        let x1847 = 0.5 * x1846;
        let x1848 = 2.0 * x22;
        let x1849 = 2.0 * x23;
        let x1850 = x13 * x1848;
        let x1851 = 0.00016666666666666672 * x1850;
        let x1852 = x12 * x1849;
        let x1853 = 0.00016666666666666672 * x1852;
        let x1855 = x1851 - x1853;
        let x1856 = 0.5 * x1855;
        let x1857 = x22 * x1837;
        let x1858 = 0.00016666666666666672 * x1857;
        let x1859 = x23 * x1838;
        let x1861 = 0.00016666666666666672 * x1859;
        let x1863 = x1858 - x1861;
        let x1864 = 0.5 * x1863;
        let x1865 = x14 * x1831;
        let x1869 = x22 * x1848;
        let x1870 = 0.00016666666666666672 * x1869;
        let x1871 = x23 * x1849;
        let x1872 = 0.00016666666666666672 * x1871;
        let x2047 = 2.0 * x47;
        let x2053 = 2.0 * x46;
        let x2054 = 2.0 * x45;
        let x2056 = x46 * x2053;
        let x2057 = 0.005104166666666666 * x2056;
        let x2058 = x45 * x2054;
        let x2060 = 0.005104166666666666 * x2058;
        let x2062 = x2057 + x2060;
        let x2063 = 0.5 * x2062;
        let x2064 = 2.0 * x55;
        let x2065 = 2.0 * x56;
        let x2066 = x46 * x2064;
        let x2067 = 0.005104166666666666 * x2066;
        let x2068 = x45 * x2065;
        let x2069 = 0.005104166666666666 * x2068;
        let x2071 = x2067 - x2069;
        let x2072 = 0.5 * x2071;
        let x2073 = x55 * x2053;
        let x2074 = 0.005104166666666666 * x2073;
        let x2075 = x56 * x2054;
        let x2077 = 0.005104166666666666 * x2075;
        let x2079 = x2074 - x2077;
        let x2080 = 0.5 * x2079;
        let x2081 = x47 * x2047;
        let x2085 = x55 * x2064;
        let x2086 = 0.005104166666666666 * x2085;
        let x2087 = x56 * x2065;
        let x2088 = 0.005104166666666666 * x2087;
        let x2258 = 2.0 * x80;
        let x2264 = 2.0 * x79;
        let x2265 = 2.0 * x78;
        let x2267 = x79 * x2264;
        let x2268 = 0.0029999999999999996 * x2267;
        let x2269 = x78 * x2265;
        let x2271 = 0.0029999999999999996 * x2269;
        let x2273 = x2268 + x2271;
        let x2274 = 0.5 * x2273;
        let x2275 = 2.0 * x88;
        let x2276 = 2.0 * x89;
        let x2277 = x79 * x2275;
        let x2278 = 0.0029999999999999996 * x2277;
        let x2279 = x78 * x2276;
        let x2280 = 0.0029999999999999996 * x2279;
        let x2282 = x2278 - x2280;
        let x2283 = 0.5 * x2282;
        let x2284 = x88 * x2264;
        let x2285 = 0.0029999999999999996 * x2284;
        let x2286 = x89 * x2265;
        let x2288 = 0.0029999999999999996 * x2286;
        let x2290 = x2285 - x2288;
        let x2291 = 0.5 * x2290;
        let x2292 = x80 * x2258;
        let x2296 = x88 * x2275;
        let x2297 = 0.0029999999999999996 * x2296;
        let x2298 = x89 * x2276;
        let x2299 = 0.0029999999999999996 * x2298;
        let x2408 = x1831 * k[0];
        let x2409 = 0.5 * x2408;
        let x2410 = -x2409;
        let x2411 = x1865 * k[0];
        let x2412 = x1870 + x2411;
        let x2413 = x1872 + x2412;
        let x2414 = 0.5 * x2413;
        let x2430 = x2047 * k[0];
        let x2431 = 0.5 * x2430;
        let x2432 = -x2431;
        let x2433 = x2081 * k[0];
        let x2434 = x2086 + x2433;
        let x2435 = x2088 + x2434;
        let x2436 = 0.5 * x2435;
        let x2452 = x2258 * k[0];
        let x2453 = 0.5 * x2452;
        let x2454 = -x2453;
        let x2455 = x2292 * k[0];
        let x2456 = x2297 + x2455;
        let x2457 = x2299 + x2456;
        let x2458 = 0.5 * x2457;
        out[0] = 0.2;
        out[1] = 0.2;
        out[2] = 0.2;
        out[3] = k[1];
        out[4] = x2410;
        out[5] = x1847;
        out[6] = x1856;
        out[7] = x2410;
        out[8] = x1864;
        out[9] = x2414;
        out[10] = 0.5;
        out[11] = 0.5;
        out[12] = 0.5;
        out[13] = k[1];
        out[14] = x2432;
        out[15] = x2063;
        out[16] = x2072;
        out[17] = x2432;
        out[18] = x2080;
        out[19] = x2436;
        out[20] = 0.4;
        out[21] = 0.4;
        out[22] = 0.4;
        out[23] = k[1];
        out[24] = x2454;
        out[25] = x2274;
        out[26] = x2283;
        out[27] = x2454;
        out[28] = x2291;
        out[29] = x2458;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 2] = k.try_into().expect("k must have 2 entries");
        let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 18] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 18] = out.try_into().expect("out must have 18 entries");
        let _ = t;
        force_part_0(k, q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(k: &[f64; 2], q: &[f64; 18], qd: &[f64; 18], out: &mut [f64; 18]) {
        let x12 = q[3].sin();
        let x13 = q[3].cos();
        let x14 = q[4].sin();
        let x15 = q[4].cos();
        let x22 = x12 * x15;
        let x23 = x13 * x15;
        let x45 = q[9].sin();
        let x46 = q[9].cos();
        let x47 = q[10].sin();
        let x48 = q[10].cos();
        let x55 = x45 * x48;
        let x56 = x46 * x48;
        let x78 = q[15].sin();
        let x79 = q[15].cos();
        let x80 = q[16].sin();
        let x81 = q[16].cos();
        let x88 = x78 * x81;
        let x89 = x79 * x81;
        let x693 = x13 * qd[3];
        let x694 = x12 * qd[3];
        let x696 = x15 * qd[4];
        let x697 = x14 * qd[4];
        let x719 = x15 * x693;
        let x720 = x12 * x697;
        let x722 = x719 - x720;
        let x761 = x46 * qd[9];
        let x762 = x45 * qd[9];
        let x764 = x48 * qd[10];
        let x765 = x47 * qd[10];
        let x787 = x48 * x761;
        let x788 = x45 * x765;
        let x790 = x787 - x788;
        let x791 = x48 * x762;
        let x793 = x46 * x765;
        let x795 = x791 + x793;
        let x834 = x79 * qd[15];
        let x835 = x78 * qd[15];
        let x837 = x81 * qd[16];
        let x838 = x80 * qd[16];
        let x860 = x81 * x834;
        let x861 = x78 * x838;
        let x863 = x860 - x861;
        let x864 = x81 * x835;
        let x866 = x79 * x838;
        let x868 = x864 + x866;
        let x1767 = x14 * qd[5];
        let x1769 = x15 * qd[5];
        let x1770 = x13 * qd[4];
        let x1771 = x12 * x1769;
        let x1772 = x1770 + x1771;
        let x1773 = x12 * qd[4];
        let x1774 = x13 * x1769;
        let x1776 = x1774 - x1773;
        let x1777 = qd[3] - x1767;
        let x1798 = 2.0 * x1777;
        let x1800 = 2.0 * x1772;
        let x1802 = 2.0 * x1776;
        let x1876 = x15 * x694;
        let x1878 = x13 * x697;
        let x1880 = x1876 + x1878;
        let x1882 = qd[5] * x696;
        let x1884 = qd[5] * x697;
        let x1886 = qd[4] * x694;
        let x1888 = x693 * x1769;
        let x1889 = x12 * x1884;
        let x1891 = x1888 - x1889;
        let x1892 = x1891 - x1886;
        let x1893 = qd[4] * x693;
        let x1894 = x694 * x1769;
        let x1896 = x13 * x1884;
        let x1898 = x1894 + x1896;
        let x1901 = x1893 + x1898;
        let x1903 = 2.0 * x1882;
        let x1905 = 2.0 * x1892;
        let x1906 = 2.0 * x1901;
        let x1912 = x694 * x1800;
        let x1914 = x13 * x1905;
        let x1915 = x1914 - x1912;
        let x1916 = 0.00016666666666666672 * x1915;
        let x1917 = x693 * x1802;
        let x1918 = x12 * x1906;
        let x1920 = x1917 - x1918;
        let x1921 = 0.00016666666666666672 * x1920;
        let x1923 = x1916 - x1921;
        let x1924 = 0.5 * x1923;
        let x1925 = x696 * x1798;
        let x1926 = x14 * x1903;
        let x1928 = x1925 - x1926;
        let x1931 = x722 * x1800;
        let x1932 = x22 * x1905;
        let x1933 = x1931 + x1932;
        let x1934 = 0.00016666666666666672 * x1933;
        let x1935 = x1802 * x1880;
        let x1937 = x23 * x1906;
        let x1939 = x1935 + x1937;
        let x1941 = 0.00016666666666666672 * x1939;
        let x1949 = x1776 * x1800;
        let x1950 = 0.00016666666666666672 * x1949;
        let x1951 = x1772 * x1802;
        let x1953 = 0.00016666666666666672 * x1951;
        let x1955 = x1950 - x1953;
        let x1956 = 0.5 * x1955;
        let x1959 = x12 * x1767;
        let x1961 = x13 * x1767;
        let x1963 = x1769 * x1798;
        let x1967 = x1800 * x1959;
        let x1969 = 0.00016666666666666672 * x1967;
        let x1971 = x1802 * x1961;
        let x1973 = 0.00016666666666666672 * x1971;
        let x1985 = x47 * qd[11];
        let x1987 = x48 * qd[11];
        let x1988 = x46 * qd[10];
        let x1989 = x45 * x1987;
        let x1990 = x1988 + x1989;
        let x1991 = x45 * qd[10];
        let x1992 = x46 * x1987;
        let x1994 = x1992 - x1991;
        let x1995 = qd[9] - x1985;
        let x2016 = 2.0 * x1995;
        let x2018 = 2.0 * x1990;
        let x2020 = 2.0 * x1994;
        let x2092 = qd[11] * x764;
        let x2094 = qd[11] * x765;
        let x2096 = qd[10] * x762;
        let x2098 = x761 * x1987;
        let x2099 = x45 * x2094;
        let x2101 = x2098 - x2099;
        let x2102 = x2101 - x2096;
        let x2103 = qd[10] * x761;
        let x2104 = x762 * x1987;
        let x2106 = x46 * x2094;
        let x2108 = x2104 + x2106;
        let x2111 = x2103 + x2108;
        let x2113 = 2.0 * x2092;
        let x2115 = 2.0 * x2102;
        let x2116 = 2.0 * x2111;
        let x2122 = x762 * x2018;
        let x2124 = x46 * x2115;
        let x2125 = x2124 - x2122;
        let x2126 = 0.005104166666666666 * x2125;
        let x2127 = x761 * x2020;
        let x2128 = x45 * x2116;
        let x2130 = x2127 - x2128;
        let x2131 = 0.005104166666666666 * x2130;
        let x2133 = x2126 - x2131;
        let x2134 = 0.5 * x2133;
        let x2135 = x764 * x2016;
        let x2136 = x47 * x2113;
        let x2138 = x2135 - x2136;
        let x2141 = x790 * x2018;
        let x2142 = x55 * x2115;
        let x2143 = x2141 + x2142;
        let x2144 = 0.005104166666666666 * x2143;
        let x2145 = x795 * x2020;
        let x2147 = x56 * x2116;
        let x2149 = x2145 + x2147;
        let x2151 = 0.005104166666666666 * x2149;
        let x2159 = x1994 * x2018;
        let x2160 = 0.005104166666666666 * x2159;
        let x2161 = x1990 * x2020;
        let x2163 = 0.005104166666666666 * x2161;
        let x2165 = x2160 - x2163;
        let x2166 = 0.5 * x2165;
        let x2169 = x45 * x1985;
        let x2171 = x46 * x1985;
        let x2173 = x1987 * x2016;
        let x2177 = x2018 * x2169;
        let x2179 = 0.005104166666666666 * x2177;
        let x2181 = x2020 * x2171;
        let x2183 = 0.005104166666666666 * x2181;
        let x2195 = x80 * qd[17];
        let x2197 = x81 * qd[17];
        let x2198 = x79 * qd[16];
        let x2199 = x78 * x2197;
        let x2200 = x2198 + x2199;
        let x2201 = x78 * qd[16];
        let x2202 = x79 * x2197;
        let x2204 = x2202 - x2201;
        let x2205 = qd[15] - x2195;
        let x2226 = 2.0 * x2205;
        let x2228 = 2.0 * x2200;
        let x2230 = 2.0 * x2204;
        let x2303 = qd[17] * x837;
        let x2305 = qd[17] * x838;
        let x2307 = qd[16] * x835;
        let x2309 = x834 * x2197;
        let x2310 = x78 * x2305;
        let x2312 = x2309 - x2310;
        let x2313 = x2312 - x2307;
        let x2314 = qd[16] * x834;
        let x2315 = x835 * x2197;
        let x2317 = x79 * x2305;
        let x2319 = x2315 + x2317;
        let x2322 = x2314 + x2319;
        let x2324 = 2.0 * x2303;
        let x2326 = 2.0 * x2313;
        let x2327 = 2.0 * x2322;
        let x2333 = x835 * x2228;
        let x2335 = x79 * x2326;
        let x2336 = x2335 - x2333;
        let x2337 = 0.0029999999999999996 * x2336;
        let x2338 = x834 * x2230;
        let x2339 = x78 * x2327;
        let x2341 = x2338 - x2339;
        let x2342 = 0.0029999999999999996 * x2341;
        let x2344 = x2337 - x2342;
        let x2345 = 0.5 * x2344;
        let x2346 = x837 * x2226;
        let x2347 = x80 * x2324;
        let x2349 = x2346 - x2347;
        let x2352 = x863 * x2228;
        let x2353 = x88 * x2326;
        let x2354 = x2352 + x2353;
        let x2355 = 0.0029999999999999996 * x2354;
        let x2356 = x868 * x2230;
        let x2358 = x89 * x2327;
        let x2360 = x2356 + x2358;
        let x2362 = 0.0029999999999999996 * x2360;
        let x2370 = x2204 * x2228;
        let x2371 = 0.0029999999999999996 * x2370;
        let x2372 = x2200 * x2230;
        let x2374 = 0.0029999999999999996 * x2372;
        let x2376 = x2371 - x2374;
        let x2377 = 0.5 * x2376;
        let x2380 = x78 * x2195;
        let x2382 = x79 * x2195;
        let x2384 = x2197 * x2226;
        let x2388 = x2228 * x2380;
        let x2390 = 0.0029999999999999996 * x2388;
        let x2392 = x2230 * x2382;
        let x2394 = 0.0029999999999999996 * x2392;
        let x2415 = x1903 * k[0];
        let x2416 = 0.5 * x2415;
        let x2417 = x1928 * k[0];
        let x2419 = x1934 - x2417;
        let x2420 = x2419 - x1941;
        let x2421 = 0.5 * x2420;
        let x2422 = x1956 + x2416;
        let x2423 = x1963 * k[0];
        let x2424 = x1969 + x2423;
        let x2425 = x1973 + x2424;
        let x2426 = 0.5 * x2425;
        let x2427 = x1924 + x2426;
        let x2428 = -x2427;
        let x2429 = -x2421;
        let x2437 = x2113 * k[0];
        let x2438 = 0.5 * x2437;
        let x2439 = x2138 * k[0];
        let x2441 = x2144 - x2439;
        let x2442 = x2441 - x2151;
        let x2443 = 0.5 * x2442;
        let x2444 = x2166 + x2438;
        let x2445 = x2173 * k[0];
        let x2446 = x2179 + x2445;
        let x2447 = x2183 + x2446;
        let x2448 = 0.5 * x2447;
        let x2449 = x2134 + x2448;
        let x2450 = -x2449;
        let x2451 = -x2443;
        let x2459 = x2324 * k[0];
        let x2460 = 0.5 * x2459;
        let x2461 = x2349 * k[0];
        let x2463 = x2355 - x2461;
        let x2464 = x2463 - x2362;
        let x2465 = 0.5 * x2464;
        let x2466 = x2377 + x2460;
        let x2467 = x2384 * k[0];
        let x2468 = x2390 + x2467;
        let x2469 = x2394 + x2468;
        let x2470 = 0.5 * x2469;
        let x2471 = x2345 + x2470;
        let x2472 = -x2471;
        let x2473 = -x2465;
        out[0] = 0.0;
        out[1] = -1.9620000000000002;
        out[2] = 0.0;
        out[3] = x2422;
        out[4] = x2428;
        out[5] = x2429;
        out[6] = 0.0;
        out[7] = -4.905;
        out[8] = 0.0;
        out[9] = x2444;
        out[10] = x2450;
        out[11] = x2451;
        out[12] = 0.0;
        out[13] = -3.9240000000000004;
        out[14] = 0.0;
        out[15] = x2466;
        out[16] = x2472;
        out[17] = x2473;
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
        let k: &[f64; 2] = k.try_into().expect("k must have 2 entries");
        let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 18] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 21] = phi.try_into().expect("phi must have 21 entries");
        let phi_q: &mut [f64; 96] = phi_q
            .try_into()
            .expect("phi_q must have 96 entries");
        let mass: &mut [f64; 30] = mass.try_into().expect("mass must have 30 entries");
        let force: &mut [f64; 18] = force
            .try_into()
            .expect("force must have 18 entries");
        let mut s = [0.0f64; 30];
        eval_newton_shared_0(k, q, qd, t, &mut s);
        eval_newton_part_0(k, q, t, &s, phi, phi_q, mass, force);
        eval_newton_part_1(k, qd, &s, force);
    }
    #[inline(never)]
    fn eval_newton_shared_0(
        _k: &[f64; 2],
        q: &[f64; 18],
        qd: &[f64; 18],
        _t: f64,
        s: &mut [f64; 30],
    ) {
        let x12 = q[3].sin();
        s[0] = x12;
        let x13 = q[3].cos();
        s[1] = x13;
        let x14 = q[4].sin();
        s[2] = x14;
        let x15 = q[4].cos();
        s[3] = x15;
        let x22 = x12 * x15;
        s[4] = x22;
        let x23 = x13 * x15;
        s[5] = x23;
        let x45 = q[9].sin();
        s[6] = x45;
        let x46 = q[9].cos();
        s[7] = x46;
        let x47 = q[10].sin();
        s[8] = x47;
        let x48 = q[10].cos();
        s[9] = x48;
        let x55 = x45 * x48;
        s[10] = x55;
        let x56 = x46 * x48;
        s[11] = x56;
        let x78 = q[15].sin();
        s[12] = x78;
        let x79 = q[15].cos();
        s[13] = x79;
        let x80 = q[16].sin();
        s[14] = x80;
        let x81 = q[16].cos();
        s[15] = x81;
        let x88 = x78 * x81;
        s[16] = x88;
        let x89 = x79 * x81;
        s[17] = x89;
        let x696 = x15 * qd[4];
        s[18] = x696;
        let x1769 = x15 * qd[5];
        s[19] = x1769;
        let x1770 = x13 * qd[4];
        s[20] = x1770;
        let x1771 = x12 * x1769;
        s[21] = x1771;
        let x1772 = x1770 + x1771;
        s[22] = x1772;
        let x1773 = x12 * qd[4];
        s[23] = x1773;
        let x1774 = x13 * x1769;
        s[24] = x1774;
        let x1776 = x1774 - x1773;
        s[25] = x1776;
        let x1800 = 2.0 * x1772;
        s[26] = x1800;
        let x1802 = 2.0 * x1776;
        s[27] = x1802;
        let x1882 = qd[5] * x696;
        s[28] = x1882;
        let x1903 = 2.0 * x1882;
        s[29] = x1903;
    }
    #[inline(never)]
    fn eval_newton_part_0(
        k: &[f64; 2],
        q: &[f64; 18],
        t: f64,
        s: &[f64; 30],
        phi: &mut [f64; 21],
        phi_q: &mut [f64; 96],
        mass: &mut [f64; 30],
        force: &mut [f64; 18],
    ) {
        let x5 = 6.283185307179586 * t;
        let x16 = q[5].sin();
        let x17 = q[5].cos();
        let x18 = s[3] * x17;
        let x19 = s[3] * x16;
        let x20 = s[2] * x17;
        let x21 = s[2] * x16;
        let x24 = s[0] * x20;
        let x25 = s[1] * x16;
        let x26 = s[1] * x20;
        let x27 = s[0] * x16;
        let x28 = s[0] * x21;
        let x29 = s[1] * x17;
        let x30 = s[1] * x21;
        let x31 = s[0] * x17;
        let x33 = x24 - x25;
        let x34 = x26 + x27;
        let x35 = x28 + x29;
        let x37 = x30 - x31;
        let x49 = q[11].sin();
        let x50 = q[11].cos();
        let x51 = s[9] * x50;
        let x52 = s[9] * x49;
        let x53 = s[8] * x50;
        let x54 = s[8] * x49;
        let x57 = s[6] * x53;
        let x58 = s[7] * x49;
        let x59 = s[7] * x53;
        let x60 = s[6] * x49;
        let x61 = s[6] * x54;
        let x62 = s[7] * x50;
        let x63 = s[7] * x54;
        let x64 = s[6] * x50;
        let x66 = x57 - x58;
        let x67 = x59 + x60;
        let x68 = x61 + x62;
        let x70 = x63 - x64;
        let x82 = q[17].sin();
        let x83 = q[17].cos();
        let x84 = s[15] * x83;
        let x85 = s[15] * x82;
        let x86 = s[14] * x83;
        let x87 = s[14] * x82;
        let x90 = s[12] * x86;
        let x91 = s[13] * x82;
        let x92 = s[13] * x86;
        let x93 = s[12] * x82;
        let x94 = s[12] * x87;
        let x95 = s[13] * x83;
        let x96 = s[13] * x87;
        let x97 = s[12] * x83;
        let x99 = x90 - x91;
        let x100 = x92 + x93;
        let x101 = x94 + x95;
        let x103 = x96 - x97;
        let x108 = x18 * 0.05;
        let x110 = x19 * 0.05;
        let x111 = -x110;
        let x112 = s[2] * 0.05;
        let x114 = q[0] - x108;
        let x115 = q[1] - x110;
        let x116 = q[2] + x112;
        let x119 = x18 * 0.00000000000000006123233995736766;
        let x121 = x119 - x33;
        let x122 = x19 * 0.00000000000000006123233995736766;
        let x123 = -x35;
        let x124 = x122 - x35;
        let x125 = s[2] * 0.00000000000000006123233995736766;
        let x128 = s[4] + x125;
        let x130 = x33 * 0.00000000000000006123233995736766;
        let x131 = x18 + x130;
        let x132 = x35 * 0.00000000000000006123233995736766;
        let x133 = x19 + x132;
        let x134 = s[4] * 0.00000000000000006123233995736766;
        let x135 = x134 - s[2];
        let x136 = -x114;
        let x137 = -x115;
        let x138 = -x116;
        let x139 = q[0] + x108;
        let x140 = q[1] + x110;
        let x141 = q[2] - x112;
        let x144 = x51 * 0.17499999999999996;
        let x146 = x52 * 0.17499999999999996;
        let x147 = -x146;
        let x148 = s[8] * 0.17499999999999996;
        let x150 = q[6] - x144;
        let x151 = q[7] - x146;
        let x152 = q[8] + x148;
        let x155 = x51 * 0.8534911287233514;
        let x157 = x66 * 0.5211073720362623;
        let x159 = x155 - x157;
        let x160 = x52 * 0.8534911287233514;
        let x161 = x68 * 0.5211073720362623;
        let x163 = x160 - x161;
        let x164 = s[8] * 0.8534911287233514;
        let x166 = s[10] * 0.5211073720362623;
        let x168 = x164 + x166;
        let x170 = x51 * 0.5211073720362623;
        let x171 = x66 * 0.8534911287233514;
        let x172 = x170 + x171;
        let x173 = x52 * 0.5211073720362623;
        let x174 = x68 * 0.8534911287233514;
        let x175 = x173 + x174;
        let x176 = s[8] * 0.5211073720362623;
        let x178 = s[10] * 0.8534911287233514;
        let x179 = x178 - x176;
        let x181 = x139 - x150;
        let x183 = x140 - x151;
        let x185 = x141 - x152;
        let x186 = x67 * x121;
        let x187 = x70 * x124;
        let x188 = s[11] * x128;
        let x190 = x186 + x187;
        let x191 = x190 - x188;
        let x192 = x67 * x131;
        let x193 = x70 * x133;
        let x194 = s[11] * x135;
        let x195 = x192 + x193;
        let x196 = x194 + x195;
        let x199 = x51 * 0.175;
        let x200 = x66 * 0.000000000000000027755575615628914;
        let x201 = x199 + x200;
        let x202 = x52 * 0.175;
        let x203 = x68 * 0.000000000000000027755575615628914;
        let x204 = x202 + x203;
        let x205 = s[8] * 0.175;
        let x207 = s[10] * 0.000000000000000027755575615628914;
        let x208 = x207 - x205;
        let x209 = q[6] + x201;
        let x210 = q[7] + x204;
        let x211 = q[8] + x208;
        let x214 = x84 * 0.14999999999999997;
        let x215 = x99 * 0.000000000000000006938893903907228;
        let x216 = x214 + x215;
        let x217 = x85 * 0.14999999999999997;
        let x218 = x101 * 0.000000000000000006938893903907228;
        let x219 = x217 + x218;
        let x220 = s[14] * 0.14999999999999997;
        let x222 = s[16] * 0.000000000000000006938893903907228;
        let x223 = x222 - x220;
        let x224 = q[12] + x216;
        let x225 = q[13] + x219;
        let x226 = q[14] + x223;
        let x263 = x209 - x224;
        let x265 = x210 - x225;
        let x267 = x211 - x226;
        let x268 = x100 * x159;
        let x269 = x103 * x163;
        let x270 = s[17] * x168;
        let x272 = x268 + x269;
        let x273 = x272 - x270;
        let x274 = x100 * x172;
        let x275 = x103 * x175;
        let x276 = s[17] * x179;
        let x277 = x274 + x275;
        let x278 = x276 + x277;
        let x283 = x99 * 0.00000000000000004163336342344337;
        let x284 = x283 - x214;
        let x286 = x101 * 0.00000000000000004163336342344337;
        let x287 = x286 - x217;
        let x288 = s[16] * 0.00000000000000004163336342344337;
        let x289 = x220 + x288;
        let x290 = q[12] + x284;
        let x291 = q[13] + x287;
        let x292 = q[14] + x289;
        let x294 = 0.4 - x290;
        let x295 = -x291;
        let x296 = -x292;
        let x297 = x5.sin();
        let x298 = x5.cos();
        let x299 = x121 * x297;
        let x300 = x124 * x298;
        let x302 = x299 - x300;
        let x307 = x25 - x24;
        let x311 = x34 * 0.00000000000000006123233995736766;
        let x312 = x37 * 0.00000000000000006123233995736766;
        let x313 = s[5] * 0.00000000000000006123233995736766;
        let x314 = x34 * x67;
        let x316 = x37 * x70;
        let x318 = s[5] * s[11];
        let x320 = x314 + x316;
        let x322 = x318 + x320;
        let x323 = -x322;
        let x324 = x67 * x311;
        let x325 = x70 * x312;
        let x326 = s[11] * x313;
        let x327 = x324 + x325;
        let x328 = x326 + x327;
        let x329 = x34 * x297;
        let x331 = x37 * x298;
        let x333 = x331 - x329;
        let x336 = s[0] * s[2];
        let x338 = s[0] * x18;
        let x339 = s[1] * x18;
        let x340 = s[0] * x19;
        let x341 = s[1] * x19;
        let x343 = x20 * 0.05;
        let x344 = -x343;
        let x345 = x21 * 0.05;
        let x346 = -x345;
        let x347 = s[3] * 0.05;
        let x348 = -x347;
        let x349 = x20 * 0.00000000000000006123233995736766;
        let x352 = x338 + x349;
        let x354 = x21 * 0.00000000000000006123233995736766;
        let x357 = x340 + x354;
        let x359 = s[3] * 0.00000000000000006123233995736766;
        let x360 = x359 - x336;
        let x361 = 0.00000000000000006123233995736766 * x338;
        let x362 = x361 - x20;
        let x363 = 0.00000000000000006123233995736766 * x340;
        let x364 = x363 - x21;
        let x365 = 0.00000000000000006123233995736766 * x336;
        let x367 = s[3] + x365;
        let x369 = x67 * x352;
        let x371 = x70 * x357;
        let x373 = s[11] * x360;
        let x375 = x369 + x371;
        let x377 = x373 + x375;
        let x378 = -x377;
        let x379 = x67 * x362;
        let x380 = x70 * x364;
        let x381 = s[11] * x367;
        let x383 = x379 + x380;
        let x384 = x383 - x381;
        let x385 = x297 * x352;
        let x387 = x298 * x357;
        let x389 = x387 - x385;
        let x393 = x31 - x30;
        let x395 = x35 - x122;
        let x398 = x67 * x395;
        let x399 = x70 * x121;
        let x400 = x398 + x399;
        let x401 = x67 * x133;
        let x403 = x70 * x131;
        let x404 = x403 - x401;
        let x405 = x297 * x395;
        let x406 = x121 * x298;
        let x408 = x405 - x406;
        let x414 = x58 - x57;
        let x417 = x67 * 0.5211073720362623;
        let x419 = x70 * 0.5211073720362623;
        let x421 = s[11] * 0.5211073720362623;
        let x422 = x67 * 0.8534911287233514;
        let x423 = x70 * 0.8534911287233514;
        let x424 = s[11] * 0.8534911287233514;
        let x425 = x121 * x414;
        let x426 = x68 * x124;
        let x428 = s[10] * x128;
        let x430 = x425 - x426;
        let x431 = x428 + x430;
        let x432 = x131 * x414;
        let x433 = x68 * x133;
        let x435 = s[10] * x135;
        let x437 = x432 - x433;
        let x438 = x437 - x435;
        let x439 = x67 * 0.000000000000000027755575615628914;
        let x440 = x70 * 0.000000000000000027755575615628914;
        let x441 = s[11] * 0.000000000000000027755575615628914;
        let x442 = x100 * x417;
        let x444 = x103 * x419;
        let x446 = s[17] * x421;
        let x448 = x442 + x444;
        let x450 = x446 + x448;
        let x451 = -x450;
        let x452 = x100 * x422;
        let x453 = x103 * x423;
        let x454 = s[17] * x424;
        let x455 = x452 + x453;
        let x456 = x454 + x455;
        let x459 = s[6] * s[8];
        let x461 = s[7] * s[8];
        let x463 = s[6] * x51;
        let x464 = s[7] * x51;
        let x465 = s[6] * x52;
        let x466 = s[7] * x52;
        let x467 = x53 * 0.17499999999999996;
        let x468 = -x467;
        let x469 = x54 * 0.17499999999999996;
        let x470 = -x469;
        let x471 = s[9] * 0.17499999999999996;
        let x472 = x53 * 0.8534911287233514;
        let x474 = 0.5211073720362623 * x463;
        let x476 = x472 + x474;
        let x478 = x54 * 0.8534911287233514;
        let x480 = 0.5211073720362623 * x465;
        let x482 = x478 + x480;
        let x484 = s[9] * 0.8534911287233514;
        let x485 = 0.5211073720362623 * x459;
        let x487 = x484 - x485;
        let x488 = x53 * 0.5211073720362623;
        let x490 = 0.8534911287233514 * x463;
        let x491 = x490 - x488;
        let x492 = x54 * 0.5211073720362623;
        let x494 = 0.8534911287233514 * x465;
        let x495 = x494 - x492;
        let x496 = s[9] * 0.5211073720362623;
        let x498 = 0.8534911287233514 * x459;
        let x500 = x496 + x498;
        let x502 = -x471;
        let x503 = x121 * x464;
        let x504 = x124 * x466;
        let x505 = x128 * x461;
        let x507 = x503 + x504;
        let x508 = x505 + x507;
        let x509 = x131 * x464;
        let x510 = x133 * x466;
        let x511 = x135 * x461;
        let x513 = x509 + x510;
        let x514 = x513 - x511;
        let x515 = x53 * 0.175;
        let x517 = 0.000000000000000027755575615628914 * x463;
        let x518 = x517 - x515;
        let x519 = x54 * 0.175;
        let x521 = 0.000000000000000027755575615628914 * x465;
        let x522 = x521 - x519;
        let x523 = s[9] * 0.175;
        let x525 = 0.000000000000000027755575615628914 * x459;
        let x527 = x523 + x525;
        let x528 = -x527;
        let x529 = x100 * x476;
        let x531 = x103 * x482;
        let x533 = s[17] * x487;
        let x535 = x529 + x531;
        let x537 = x533 + x535;
        let x538 = -x537;
        let x539 = x100 * x491;
        let x540 = x103 * x495;
        let x541 = s[17] * x500;
        let x543 = x539 + x540;
        let x544 = x543 - x541;
        let x548 = x64 - x63;
        let x550 = x161 - x160;
        let x554 = x121 * x548;
        let x555 = x67 * x124;
        let x556 = x554 + x555;
        let x557 = x131 * x548;
        let x558 = x401 + x557;
        let x561 = -x204;
        let x562 = x100 * x550;
        let x563 = x103 * x159;
        let x564 = x562 + x563;
        let x565 = x100 * x175;
        let x567 = x103 * x172;
        let x568 = x567 - x565;
        let x574 = x91 - x90;
        let x576 = -x101;
        let x577 = x100 * 0.000000000000000006938893903907228;
        let x578 = x103 * 0.000000000000000006938893903907228;
        let x579 = s[17] * 0.000000000000000006938893903907228;
        let x580 = -x577;
        let x581 = -x578;
        let x582 = -x579;
        let x583 = x159 * x574;
        let x584 = x101 * x163;
        let x586 = s[16] * x168;
        let x588 = x583 - x584;
        let x589 = x586 + x588;
        let x590 = x172 * x574;
        let x591 = x101 * x175;
        let x593 = s[16] * x179;
        let x595 = x590 - x591;
        let x596 = x595 - x593;
        let x597 = x100 * 0.00000000000000004163336342344337;
        let x598 = x103 * 0.00000000000000004163336342344337;
        let x599 = s[17] * 0.00000000000000004163336342344337;
        let x600 = -x597;
        let x601 = -x598;
        let x602 = -x599;
        let x605 = s[12] * s[14];
        let x607 = s[13] * s[14];
        let x609 = s[12] * x84;
        let x610 = s[13] * x84;
        let x611 = s[12] * x85;
        let x612 = s[13] * x85;
        let x613 = x86 * 0.14999999999999997;
        let x615 = 0.000000000000000006938893903907228 * x609;
        let x616 = x615 - x613;
        let x617 = x87 * 0.14999999999999997;
        let x619 = 0.000000000000000006938893903907228 * x611;
        let x620 = x619 - x617;
        let x621 = s[15] * 0.14999999999999997;
        let x623 = 0.000000000000000006938893903907228 * x605;
        let x625 = x621 + x623;
        let x627 = -x616;
        let x628 = -x620;
        let x629 = x159 * x610;
        let x630 = x163 * x612;
        let x631 = x168 * x607;
        let x633 = x629 + x630;
        let x634 = x631 + x633;
        let x635 = x172 * x610;
        let x636 = x175 * x612;
        let x637 = x179 * x607;
        let x639 = x635 + x636;
        let x640 = x639 - x637;
        let x641 = 0.00000000000000004163336342344337 * x609;
        let x642 = x613 + x641;
        let x643 = 0.00000000000000004163336342344337 * x611;
        let x644 = x617 + x643;
        let x645 = 0.00000000000000004163336342344337 * x605;
        let x647 = x621 - x645;
        let x648 = -x642;
        let x649 = -x644;
        let x650 = -x647;
        let x654 = x97 - x96;
        let x657 = -x216;
        let x658 = x159 * x654;
        let x659 = x100 * x163;
        let x660 = x658 + x659;
        let x661 = x172 * x654;
        let x662 = x565 + x661;
        let x664 = x217 - x286;
        let x665 = -x664;
        let x666 = -x284;
        let x1831 = 2.0 * s[2];
        let x1837 = 2.0 * s[1];
        let x1838 = 2.0 * s[0];
        let x1840 = s[1] * x1837;
        let x1841 = 0.00016666666666666672 * x1840;
        let x1842 = s[0] * x1838;
        let x1844 = 0.00016666666666666672 * x1842;
        let x1846 = x1841 + x1844;
        let x1847 = 0.5 * x1846;
        let x1848 = 2.0 * s[4];
        let x1849 = 2.0 * s[5];
        let x1850 = s[1] * x1848;
        let x1851 = 0.00016666666666666672 * x1850;
        let x1852 = s[0] * x1849;
        let x1853 = 0.00016666666666666672 * x1852;
        let x1855 = x1851 - x1853;
        let x1856 = 0.5 * x1855;
        let x1857 = s[4] * x1837;
        let x1858 = 0.00016666666666666672 * x1857;
        let x1859 = s[5] * x1838;
        let x1861 = 0.00016666666666666672 * x1859;
        let x1863 = x1858 - x1861;
        let x1864 = 0.5 * x1863;
        let x1865 = s[2] * x1831;
        let x1869 = s[4] * x1848;
        let x1870 = 0.00016666666666666672 * x1869;
        let x1871 = s[5] * x1849;
        let x1872 = 0.00016666666666666672 * x1871;
        let x1949 = s[25] * s[26];
        let x1950 = 0.00016666666666666672 * x1949;
        let x1951 = s[22] * s[27];
        let x1953 = 0.00016666666666666672 * x1951;
        let x1955 = x1950 - x1953;
        let x1956 = 0.5 * x1955;
        let x2047 = 2.0 * s[8];
        let x2053 = 2.0 * s[7];
        let x2054 = 2.0 * s[6];
        let x2056 = s[7] * x2053;
        let x2057 = 0.005104166666666666 * x2056;
        let x2058 = s[6] * x2054;
        let x2060 = 0.005104166666666666 * x2058;
        let x2062 = x2057 + x2060;
        let x2063 = 0.5 * x2062;
        let x2064 = 2.0 * s[10];
        let x2065 = 2.0 * s[11];
        let x2066 = s[7] * x2064;
        let x2067 = 0.005104166666666666 * x2066;
        let x2068 = s[6] * x2065;
        let x2069 = 0.005104166666666666 * x2068;
        let x2071 = x2067 - x2069;
        let x2072 = 0.5 * x2071;
        let x2073 = s[10] * x2053;
        let x2074 = 0.005104166666666666 * x2073;
        let x2075 = s[11] * x2054;
        let x2077 = 0.005104166666666666 * x2075;
        let x2079 = x2074 - x2077;
        let x2080 = 0.5 * x2079;
        let x2081 = s[8] * x2047;
        let x2085 = s[10] * x2064;
        let x2086 = 0.005104166666666666 * x2085;
        let x2087 = s[11] * x2065;
        let x2088 = 0.005104166666666666 * x2087;
        let x2258 = 2.0 * s[14];
        let x2264 = 2.0 * s[13];
        let x2265 = 2.0 * s[12];
        let x2267 = s[13] * x2264;
        let x2268 = 0.0029999999999999996 * x2267;
        let x2269 = s[12] * x2265;
        let x2271 = 0.0029999999999999996 * x2269;
        let x2273 = x2268 + x2271;
        let x2274 = 0.5 * x2273;
        let x2275 = 2.0 * s[16];
        let x2276 = 2.0 * s[17];
        let x2277 = s[13] * x2275;
        let x2278 = 0.0029999999999999996 * x2277;
        let x2279 = s[12] * x2276;
        let x2280 = 0.0029999999999999996 * x2279;
        let x2282 = x2278 - x2280;
        let x2283 = 0.5 * x2282;
        let x2284 = s[16] * x2264;
        let x2285 = 0.0029999999999999996 * x2284;
        let x2286 = s[17] * x2265;
        let x2288 = 0.0029999999999999996 * x2286;
        let x2290 = x2285 - x2288;
        let x2291 = 0.5 * x2290;
        let x2292 = s[14] * x2258;
        let x2296 = s[16] * x2275;
        let x2297 = 0.0029999999999999996 * x2296;
        let x2298 = s[17] * x2276;
        let x2299 = 0.0029999999999999996 * x2298;
        let x2408 = x1831 * k[0];
        let x2409 = 0.5 * x2408;
        let x2410 = -x2409;
        let x2411 = x1865 * k[0];
        let x2412 = x1870 + x2411;
        let x2413 = x1872 + x2412;
        let x2414 = 0.5 * x2413;
        let x2415 = s[29] * k[0];
        let x2416 = 0.5 * x2415;
        let x2422 = x1956 + x2416;
        let x2430 = x2047 * k[0];
        let x2431 = 0.5 * x2430;
        let x2432 = -x2431;
        let x2433 = x2081 * k[0];
        let x2434 = x2086 + x2433;
        let x2435 = x2088 + x2434;
        let x2436 = 0.5 * x2435;
        let x2452 = x2258 * k[0];
        let x2453 = 0.5 * x2452;
        let x2454 = -x2453;
        let x2455 = x2292 * k[0];
        let x2456 = x2297 + x2455;
        let x2457 = x2299 + x2456;
        let x2458 = 0.5 * x2457;
        phi[0] = x136;
        phi_q[0] = -1.0;
        phi_q[1] = x344;
        phi_q[2] = x111;
        phi[1] = x137;
        phi_q[3] = -1.0;
        phi_q[4] = x346;
        phi_q[5] = x108;
        phi[2] = x138;
        phi_q[6] = -1.0;
        phi_q[7] = x348;
        phi[3] = x34;
        phi_q[8] = x307;
        phi_q[9] = x339;
        phi_q[10] = x393;
        phi[4] = x37;
        phi_q[11] = x123;
        phi_q[12] = x341;
        phi_q[13] = x34;
        phi[5] = x181;
        phi_q[14] = 1.0;
        phi_q[15] = x344;
        phi_q[16] = x111;
        phi_q[17] = -1.0;
        phi_q[18] = x468;
        phi_q[19] = x147;
        phi[6] = x183;
        phi_q[20] = 1.0;
        phi_q[21] = x346;
        phi_q[22] = x108;
        phi_q[23] = -1.0;
        phi_q[24] = x470;
        phi_q[25] = x144;
        phi[7] = x185;
        phi_q[26] = 1.0;
        phi_q[27] = x348;
        phi_q[28] = -1.0;
        phi_q[29] = x502;
        phi[8] = x191;
        phi_q[30] = x323;
        phi_q[31] = x378;
        phi_q[32] = x400;
        phi_q[33] = x431;
        phi_q[34] = x508;
        phi_q[35] = x556;
        phi[9] = x196;
        phi_q[36] = x328;
        phi_q[37] = x384;
        phi_q[38] = x404;
        phi_q[39] = x438;
        phi_q[40] = x514;
        phi_q[41] = x558;
        phi[10] = x263;
        phi_q[42] = 1.0;
        phi_q[43] = x439;
        phi_q[44] = x518;
        phi_q[45] = x561;
        phi_q[46] = -1.0;
        phi_q[47] = x580;
        phi_q[48] = x627;
        phi_q[49] = x219;
        phi[11] = x265;
        phi_q[50] = 1.0;
        phi_q[51] = x440;
        phi_q[52] = x522;
        phi_q[53] = x201;
        phi_q[54] = -1.0;
        phi_q[55] = x581;
        phi_q[56] = x628;
        phi_q[57] = x657;
        phi[12] = x267;
        phi_q[58] = 1.0;
        phi_q[59] = x441;
        phi_q[60] = x528;
        phi_q[61] = -1.0;
        phi_q[62] = x582;
        phi_q[63] = x625;
        phi[13] = x273;
        phi_q[64] = x451;
        phi_q[65] = x538;
        phi_q[66] = x564;
        phi_q[67] = x589;
        phi_q[68] = x634;
        phi_q[69] = x660;
        phi[14] = x278;
        phi_q[70] = x456;
        phi_q[71] = x544;
        phi_q[72] = x568;
        phi_q[73] = x596;
        phi_q[74] = x640;
        phi_q[75] = x662;
        phi[15] = x294;
        phi_q[76] = -1.0;
        phi_q[77] = x600;
        phi_q[78] = x648;
        phi_q[79] = x665;
        phi[16] = x295;
        phi_q[80] = -1.0;
        phi_q[81] = x601;
        phi_q[82] = x649;
        phi_q[83] = x666;
        phi[17] = x296;
        phi_q[84] = -1.0;
        phi_q[85] = x602;
        phi_q[86] = x650;
        phi[18] = x100;
        phi_q[87] = x574;
        phi_q[88] = x610;
        phi_q[89] = x654;
        phi[19] = x103;
        phi_q[90] = x576;
        phi_q[91] = x612;
        phi_q[92] = x100;
        phi[20] = x302;
        phi_q[93] = x333;
        phi_q[94] = x389;
        phi_q[95] = x408;
        mass[0] = 0.2;
        mass[1] = 0.2;
        mass[2] = 0.2;
        mass[3] = k[1];
        mass[4] = x2410;
        mass[5] = x1847;
        mass[6] = x1856;
        mass[7] = x2410;
        mass[8] = x1864;
        mass[9] = x2414;
        mass[10] = 0.5;
        mass[11] = 0.5;
        mass[12] = 0.5;
        mass[13] = k[1];
        mass[14] = x2432;
        mass[15] = x2063;
        mass[16] = x2072;
        mass[17] = x2432;
        mass[18] = x2080;
        mass[19] = x2436;
        mass[20] = 0.4;
        mass[21] = 0.4;
        mass[22] = 0.4;
        mass[23] = k[1];
        mass[24] = x2454;
        mass[25] = x2274;
        mass[26] = x2283;
        mass[27] = x2454;
        mass[28] = x2291;
        mass[29] = x2458;
        force[0] = 0.0;
        force[1] = -1.9620000000000002;
        force[2] = 0.0;
        force[3] = x2422;
    }
    #[inline(never)]
    fn eval_newton_part_1(
        k: &[f64; 2],
        qd: &[f64; 18],
        s: &[f64; 30],
        force: &mut [f64; 18],
    ) {
        let x693 = s[1] * qd[3];
        let x694 = s[0] * qd[3];
        let x697 = s[2] * qd[4];
        let x719 = s[3] * x693;
        let x720 = s[0] * x697;
        let x722 = x719 - x720;
        let x761 = s[7] * qd[9];
        let x762 = s[6] * qd[9];
        let x764 = s[9] * qd[10];
        let x765 = s[8] * qd[10];
        let x787 = s[9] * x761;
        let x788 = s[6] * x765;
        let x790 = x787 - x788;
        let x791 = s[9] * x762;
        let x793 = s[7] * x765;
        let x795 = x791 + x793;
        let x834 = s[13] * qd[15];
        let x835 = s[12] * qd[15];
        let x837 = s[15] * qd[16];
        let x838 = s[14] * qd[16];
        let x860 = s[15] * x834;
        let x861 = s[12] * x838;
        let x863 = x860 - x861;
        let x864 = s[15] * x835;
        let x866 = s[13] * x838;
        let x868 = x864 + x866;
        let x1767 = s[2] * qd[5];
        let x1777 = qd[3] - x1767;
        let x1798 = 2.0 * x1777;
        let x1876 = s[3] * x694;
        let x1878 = s[1] * x697;
        let x1880 = x1876 + x1878;
        let x1884 = qd[5] * x697;
        let x1886 = qd[4] * x694;
        let x1888 = x693 * s[19];
        let x1889 = s[0] * x1884;
        let x1891 = x1888 - x1889;
        let x1892 = x1891 - x1886;
        let x1893 = qd[4] * x693;
        let x1894 = x694 * s[19];
        let x1896 = s[1] * x1884;
        let x1898 = x1894 + x1896;
        let x1901 = x1893 + x1898;
        let x1905 = 2.0 * x1892;
        let x1906 = 2.0 * x1901;
        let x1912 = x694 * s[26];
        let x1914 = s[1] * x1905;
        let x1915 = x1914 - x1912;
        let x1916 = 0.00016666666666666672 * x1915;
        let x1917 = x693 * s[27];
        let x1918 = s[0] * x1906;
        let x1920 = x1917 - x1918;
        let x1921 = 0.00016666666666666672 * x1920;
        let x1923 = x1916 - x1921;
        let x1924 = 0.5 * x1923;
        let x1925 = s[18] * x1798;
        let x1926 = s[2] * s[29];
        let x1928 = x1925 - x1926;
        let x1931 = x722 * s[26];
        let x1932 = s[4] * x1905;
        let x1933 = x1931 + x1932;
        let x1934 = 0.00016666666666666672 * x1933;
        let x1935 = s[27] * x1880;
        let x1937 = s[5] * x1906;
        let x1939 = x1935 + x1937;
        let x1941 = 0.00016666666666666672 * x1939;
        let x1959 = s[0] * x1767;
        let x1961 = s[1] * x1767;
        let x1963 = s[19] * x1798;
        let x1967 = s[26] * x1959;
        let x1969 = 0.00016666666666666672 * x1967;
        let x1971 = s[27] * x1961;
        let x1973 = 0.00016666666666666672 * x1971;
        let x1985 = s[8] * qd[11];
        let x1987 = s[9] * qd[11];
        let x1988 = s[7] * qd[10];
        let x1989 = s[6] * x1987;
        let x1990 = x1988 + x1989;
        let x1991 = s[6] * qd[10];
        let x1992 = s[7] * x1987;
        let x1994 = x1992 - x1991;
        let x1995 = qd[9] - x1985;
        let x2016 = 2.0 * x1995;
        let x2018 = 2.0 * x1990;
        let x2020 = 2.0 * x1994;
        let x2092 = qd[11] * x764;
        let x2094 = qd[11] * x765;
        let x2096 = qd[10] * x762;
        let x2098 = x761 * x1987;
        let x2099 = s[6] * x2094;
        let x2101 = x2098 - x2099;
        let x2102 = x2101 - x2096;
        let x2103 = qd[10] * x761;
        let x2104 = x762 * x1987;
        let x2106 = s[7] * x2094;
        let x2108 = x2104 + x2106;
        let x2111 = x2103 + x2108;
        let x2113 = 2.0 * x2092;
        let x2115 = 2.0 * x2102;
        let x2116 = 2.0 * x2111;
        let x2122 = x762 * x2018;
        let x2124 = s[7] * x2115;
        let x2125 = x2124 - x2122;
        let x2126 = 0.005104166666666666 * x2125;
        let x2127 = x761 * x2020;
        let x2128 = s[6] * x2116;
        let x2130 = x2127 - x2128;
        let x2131 = 0.005104166666666666 * x2130;
        let x2133 = x2126 - x2131;
        let x2134 = 0.5 * x2133;
        let x2135 = x764 * x2016;
        let x2136 = s[8] * x2113;
        let x2138 = x2135 - x2136;
        let x2141 = x790 * x2018;
        let x2142 = s[10] * x2115;
        let x2143 = x2141 + x2142;
        let x2144 = 0.005104166666666666 * x2143;
        let x2145 = x795 * x2020;
        let x2147 = s[11] * x2116;
        let x2149 = x2145 + x2147;
        let x2151 = 0.005104166666666666 * x2149;
        let x2159 = x1994 * x2018;
        let x2160 = 0.005104166666666666 * x2159;
        let x2161 = x1990 * x2020;
        let x2163 = 0.005104166666666666 * x2161;
        let x2165 = x2160 - x2163;
        let x2166 = 0.5 * x2165;
        let x2169 = s[6] * x1985;
        let x2171 = s[7] * x1985;
        let x2173 = x1987 * x2016;
        let x2177 = x2018 * x2169;
        let x2179 = 0.005104166666666666 * x2177;
        let x2181 = x2020 * x2171;
        let x2183 = 0.005104166666666666 * x2181;
        let x2195 = s[14] * qd[17];
        let x2197 = s[15] * qd[17];
        let x2198 = s[13] * qd[16];
        let x2199 = s[12] * x2197;
        let x2200 = x2198 + x2199;
        let x2201 = s[12] * qd[16];
        let x2202 = s[13] * x2197;
        let x2204 = x2202 - x2201;
        let x2205 = qd[15] - x2195;
        let x2226 = 2.0 * x2205;
        let x2228 = 2.0 * x2200;
        let x2230 = 2.0 * x2204;
        let x2303 = qd[17] * x837;
        let x2305 = qd[17] * x838;
        let x2307 = qd[16] * x835;
        let x2309 = x834 * x2197;
        let x2310 = s[12] * x2305;
        let x2312 = x2309 - x2310;
        let x2313 = x2312 - x2307;
        let x2314 = qd[16] * x834;
        let x2315 = x835 * x2197;
        let x2317 = s[13] * x2305;
        let x2319 = x2315 + x2317;
        let x2322 = x2314 + x2319;
        let x2324 = 2.0 * x2303;
        let x2326 = 2.0 * x2313;
        let x2327 = 2.0 * x2322;
        let x2333 = x835 * x2228;
        let x2335 = s[13] * x2326;
        let x2336 = x2335 - x2333;
        let x2337 = 0.0029999999999999996 * x2336;
        let x2338 = x834 * x2230;
        let x2339 = s[12] * x2327;
        let x2341 = x2338 - x2339;
        let x2342 = 0.0029999999999999996 * x2341;
        let x2344 = x2337 - x2342;
        let x2345 = 0.5 * x2344;
        let x2346 = x837 * x2226;
        let x2347 = s[14] * x2324;
        let x2349 = x2346 - x2347;
        let x2352 = x863 * x2228;
        let x2353 = s[16] * x2326;
        let x2354 = x2352 + x2353;
        let x2355 = 0.0029999999999999996 * x2354;
        let x2356 = x868 * x2230;
        let x2358 = s[17] * x2327;
        let x2360 = x2356 + x2358;
        let x2362 = 0.0029999999999999996 * x2360;
        let x2370 = x2204 * x2228;
        let x2371 = 0.0029999999999999996 * x2370;
        let x2372 = x2200 * x2230;
        let x2374 = 0.0029999999999999996 * x2372;
        let x2376 = x2371 - x2374;
        let x2377 = 0.5 * x2376;
        let x2380 = s[12] * x2195;
        let x2382 = s[13] * x2195;
        let x2384 = x2197 * x2226;
        let x2388 = x2228 * x2380;
        let x2390 = 0.0029999999999999996 * x2388;
        let x2392 = x2230 * x2382;
        let x2394 = 0.0029999999999999996 * x2392;
        let x2417 = x1928 * k[0];
        let x2419 = x1934 - x2417;
        let x2420 = x2419 - x1941;
        let x2421 = 0.5 * x2420;
        let x2423 = x1963 * k[0];
        let x2424 = x1969 + x2423;
        let x2425 = x1973 + x2424;
        let x2426 = 0.5 * x2425;
        let x2427 = x1924 + x2426;
        let x2428 = -x2427;
        let x2429 = -x2421;
        let x2437 = x2113 * k[0];
        let x2438 = 0.5 * x2437;
        let x2439 = x2138 * k[0];
        let x2441 = x2144 - x2439;
        let x2442 = x2441 - x2151;
        let x2443 = 0.5 * x2442;
        let x2444 = x2166 + x2438;
        let x2445 = x2173 * k[0];
        let x2446 = x2179 + x2445;
        let x2447 = x2183 + x2446;
        let x2448 = 0.5 * x2447;
        let x2449 = x2134 + x2448;
        let x2450 = -x2449;
        let x2451 = -x2443;
        let x2459 = x2324 * k[0];
        let x2460 = 0.5 * x2459;
        let x2461 = x2349 * k[0];
        let x2463 = x2355 - x2461;
        let x2464 = x2463 - x2362;
        let x2465 = 0.5 * x2464;
        let x2466 = x2377 + x2460;
        let x2467 = x2384 * k[0];
        let x2468 = x2390 + x2467;
        let x2469 = x2394 + x2468;
        let x2470 = 0.5 * x2469;
        let x2471 = x2345 + x2470;
        let x2472 = -x2471;
        let x2473 = -x2465;
        force[4] = x2428;
        force[5] = x2429;
        force[6] = 0.0;
        force[7] = -4.905;
        force[8] = 0.0;
        force[9] = x2444;
        force[10] = x2450;
        force[11] = x2451;
        force[12] = 0.0;
        force[13] = -3.9240000000000004;
        force[14] = 0.0;
        force[15] = x2466;
        force[16] = x2472;
        force[17] = x2473;
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
    pub const N_CONSTRAINTS: usize = 9usize;
    /// Row of each Φq nonzero.
    pub static PHI_Q_ROWS: [u32; 25usize] = [
        0u32, 0u32, 1u32, 1u32, 2u32, 2u32, 2u32, 2u32, 3u32, 3u32, 3u32, 3u32, 4u32,
        4u32, 4u32, 4u32, 5u32, 5u32, 5u32, 5u32, 6u32, 6u32, 7u32, 7u32, 8u32,
    ];
    /// Column of each Φq nonzero.
    pub static PHI_Q_COLS: [u32; 25usize] = [
        0u32, 2u32, 1u32, 2u32, 0u32, 2u32, 3u32, 5u32, 1u32, 2u32, 4u32, 5u32, 3u32,
        5u32, 6u32, 8u32, 4u32, 5u32, 7u32, 8u32, 6u32, 8u32, 7u32, 8u32, 2u32,
    ];
    /// Name of each reduced coordinate (its full model's name).
    pub static COORD_NAMES: [&str; 9usize] = [
        "crank.x",
        "crank.y",
        "crank.gamma",
        "coupler.x",
        "coupler.y",
        "coupler.gamma",
        "rocker.x",
        "rocker.y",
        "rocker.gamma",
    ];
    /// Name of each reduced row (its full model's name).
    pub static ROW_NAMES: [&str; 9usize] = [
        "a0.x",
        "a0.y",
        "a1.x",
        "a1.y",
        "b1.x",
        "b1.y",
        "b0.x",
        "b0.y",
        "motor",
    ];
    /// Initial coordinates, from the full model's assembled ones.
    pub static Q0: [f64; 9usize] = [
        0.000000000000000003061616997868383f64,
        0.05f64,
        1.5707963267948966f64,
        0.1493609475265865f64,
        0.1911937901063459f64,
        0.5481478992387209f64,
        0.34936094752658653f64,
        0.14119379010634592f64,
        1.9151556505110297f64,
    ];
    /// Initial velocities from the file.
    pub static QD0: [f64; 9usize] = [
        0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64,
    ];
    /// Rows dependent on others at the initial pose.
    pub static REDUNDANT_ROWS: [u32; 0usize] = [];
    /// Full index of each reduced coordinate.
    pub static COORDS: [u32; 9usize] = [
        0u32, 1u32, 5u32, 6u32, 7u32, 11u32, 12u32, 13u32, 17u32,
    ];
    /// Full index of each reduced row.
    pub static ROWS: [u32; 9usize] = [
        0u32, 1u32, 5u32, 6u32, 10u32, 11u32, 15u32, 16u32, 20u32,
    ];
    /// The eliminated rows.
    pub static SUBSTITUTIONS: [Substitution; 9usize] = [
        Substitution {
            row: None,
            coord: 2u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: None,
            coord: 3u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: None,
            coord: 4u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: None,
            coord: 8u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: None,
            coord: 9u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: None,
            coord: 10u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: None,
            coord: 14u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: None,
            coord: 15u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: None,
            coord: 16u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
    ];
    /// The way back to the full model.
    pub static REDUCTION: Reduction = Reduction {
        n_full: 18usize,
        m_full: 21usize,
        coords: &COORDS,
        rows: &ROWS,
        substitutions: &SUBSTITUTIONS,
        offsets: offsets_into,
    };
    /// `c, ċ, c̈` of each substitution at time `t`, three per substitution.
    pub fn offsets_into(t: f64, out: &mut [f64]) {
        let out: &mut [f64; 27] = out.try_into().expect("out must have 27 entries");
        let _ = t;
        offsets_into_part_0(out);
    }
    #[inline(never)]
    fn offsets_into_part_0(out: &mut [f64; 27]) {
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
        out[12] = 0.0;
        out[13] = 0.0;
        out[14] = 0.0;
        out[15] = 0.0;
        out[16] = 0.0;
        out[17] = 0.0;
        out[18] = 0.0;
        out[19] = 0.0;
        out[20] = 0.0;
        out[21] = 0.0;
        out[22] = 0.0;
        out[23] = 0.0;
        out[24] = 0.0;
        out[25] = 0.0;
        out[26] = 0.0;
    }
    /// Constraint residual Φ(q, t).
    pub fn phi(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
        phi_part_0(q, t, out);
    }
    #[inline(never)]
    fn phi_part_0(q: &[f64; 9], t: f64, out: &mut [f64; 9]) {
        let x5 = 6.283185307179586 * t;
        let x16 = q[5].sin();
        let x17 = q[5].cos();
        let x297 = x5.sin();
        let x298 = x5.cos();
        let x2406 = q[2].sin();
        let x2407 = q[2].cos();
        let x2409 = q[8].sin();
        let x2410 = q[8].cos();
        let x2412 = 0.05 * x2407;
        let x2414 = 0.05 * x2406;
        let x2416 = q[0] - x2412;
        let x2417 = q[1] - x2414;
        let x2418 = 0.00000000000000006123233995736766 * x2407;
        let x2419 = x2406 + x2418;
        let x2420 = 0.00000000000000006123233995736766 * x2406;
        let x2422 = x2420 - x2407;
        let x2425 = -x2416;
        let x2426 = -x2417;
        let x2427 = q[0] + x2412;
        let x2428 = q[1] + x2414;
        let x2429 = x17 * 0.17499999999999996;
        let x2431 = x16 * 0.17499999999999996;
        let x2433 = q[3] - x2429;
        let x2434 = q[4] - x2431;
        let x2446 = x2427 - x2433;
        let x2448 = x2428 - x2434;
        let x2449 = x17 * 0.175;
        let x2450 = x16 * 0.000000000000000027755575615628914;
        let x2452 = x2449 - x2450;
        let x2453 = x16 * 0.175;
        let x2454 = x17 * 0.000000000000000027755575615628914;
        let x2455 = x2453 + x2454;
        let x2456 = q[3] + x2452;
        let x2457 = q[4] + x2455;
        let x2458 = 0.14999999999999997 * x2410;
        let x2459 = 0.000000000000000006938893903907228 * x2409;
        let x2461 = x2458 - x2459;
        let x2462 = 0.14999999999999997 * x2409;
        let x2463 = 0.000000000000000006938893903907228 * x2410;
        let x2464 = x2462 + x2463;
        let x2465 = q[6] + x2461;
        let x2466 = q[7] + x2464;
        let x2468 = x2456 - x2465;
        let x2470 = x2457 - x2466;
        let x2472 = 0.00000000000000004163336342344337 * x2409;
        let x2474 = x2458 + x2472;
        let x2477 = 0.00000000000000004163336342344337 * x2410;
        let x2478 = x2477 - x2462;
        let x2479 = q[6] - x2474;
        let x2480 = q[7] + x2478;
        let x2482 = 0.4 - x2479;
        let x2483 = -x2480;
        let x2484 = x297 * x2419;
        let x2485 = x298 * x2422;
        let x2487 = x2484 - x2485;
        out[0] = x2425;
        out[1] = x2426;
        out[2] = x2446;
        out[3] = x2448;
        out[4] = x2468;
        out[5] = x2470;
        out[6] = x2482;
        out[7] = x2483;
        out[8] = x2487;
    }
    /// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
    pub fn phi_q(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 25] = out.try_into().expect("out must have 25 entries");
        phi_q_part_0(q, t, out);
    }
    #[inline(never)]
    fn phi_q_part_0(q: &[f64; 9], t: f64, out: &mut [f64; 25]) {
        let x5 = 6.283185307179586 * t;
        let x16 = q[5].sin();
        let x17 = q[5].cos();
        let x297 = x5.sin();
        let x298 = x5.cos();
        let x2406 = q[2].sin();
        let x2407 = q[2].cos();
        let x2409 = q[8].sin();
        let x2410 = q[8].cos();
        let x2412 = 0.05 * x2407;
        let x2414 = 0.05 * x2406;
        let x2415 = -x2414;
        let x2418 = 0.00000000000000006123233995736766 * x2407;
        let x2419 = x2406 + x2418;
        let x2420 = 0.00000000000000006123233995736766 * x2406;
        let x2424 = x2407 - x2420;
        let x2429 = x17 * 0.17499999999999996;
        let x2431 = x16 * 0.17499999999999996;
        let x2432 = -x2431;
        let x2449 = x17 * 0.175;
        let x2450 = x16 * 0.000000000000000027755575615628914;
        let x2452 = x2449 - x2450;
        let x2453 = x16 * 0.175;
        let x2454 = x17 * 0.000000000000000027755575615628914;
        let x2455 = x2453 + x2454;
        let x2458 = 0.14999999999999997 * x2410;
        let x2459 = 0.000000000000000006938893903907228 * x2409;
        let x2461 = x2458 - x2459;
        let x2462 = 0.14999999999999997 * x2409;
        let x2463 = 0.000000000000000006938893903907228 * x2410;
        let x2464 = x2462 + x2463;
        let x2472 = 0.00000000000000004163336342344337 * x2409;
        let x2474 = x2458 + x2472;
        let x2477 = 0.00000000000000004163336342344337 * x2410;
        let x2478 = x2477 - x2462;
        let x2488 = x297 * x2424;
        let x2489 = x298 * x2419;
        let x2491 = x2488 - x2489;
        let x2494 = -x2455;
        let x2497 = -x2461;
        out[0] = -1.0;
        out[1] = x2415;
        out[2] = -1.0;
        out[3] = x2412;
        out[4] = 1.0;
        out[5] = x2415;
        out[6] = -1.0;
        out[7] = x2432;
        out[8] = 1.0;
        out[9] = x2412;
        out[10] = -1.0;
        out[11] = x2429;
        out[12] = 1.0;
        out[13] = x2494;
        out[14] = -1.0;
        out[15] = x2464;
        out[16] = 1.0;
        out[17] = x2452;
        out[18] = -1.0;
        out[19] = x2497;
        out[20] = -1.0;
        out[21] = x2478;
        out[22] = -1.0;
        out[23] = x2474;
        out[24] = x2491;
    }
    /// Partial time derivative Φt(q, t).
    pub fn phi_t(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
        phi_t_part_0(q, t, out);
    }
    #[inline(never)]
    fn phi_t_part_0(q: &[f64; 9], t: f64, out: &mut [f64; 9]) {
        let x5 = 6.283185307179586 * t;
        let x297 = x5.sin();
        let x298 = x5.cos();
        let x667 = 6.283185307179586 * x298;
        let x669 = 6.283185307179586 * x297;
        let x2406 = q[2].sin();
        let x2407 = q[2].cos();
        let x2418 = 0.00000000000000006123233995736766 * x2407;
        let x2419 = x2406 + x2418;
        let x2420 = 0.00000000000000006123233995736766 * x2406;
        let x2422 = x2420 - x2407;
        let x2499 = x667 * x2419;
        let x2500 = x669 * x2422;
        let x2502 = x2499 + x2500;
        out[0] = 0.0;
        out[1] = 0.0;
        out[2] = 0.0;
        out[3] = 0.0;
        out[4] = 0.0;
        out[5] = 0.0;
        out[6] = 0.0;
        out[7] = 0.0;
        out[8] = x2502;
    }
    /// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
    pub fn gamma(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
        gamma_part_0(q, qd, t, out);
    }
    #[inline(never)]
    fn gamma_part_0(q: &[f64; 9], qd: &[f64; 9], t: f64, out: &mut [f64; 9]) {
        let x5 = 6.283185307179586 * t;
        let x16 = q[5].sin();
        let x17 = q[5].cos();
        let x297 = x5.sin();
        let x298 = x5.cos();
        let x667 = 6.283185307179586 * x298;
        let x669 = 6.283185307179586 * x297;
        let x699 = x17 * qd[5];
        let x700 = x16 * qd[5];
        let x1082 = 6.283185307179586 * x669;
        let x1084 = 6.283185307179586 * x667;
        let x1101 = qd[5] * x700;
        let x1103 = qd[5] * x699;
        let x2406 = q[2].sin();
        let x2407 = q[2].cos();
        let x2409 = q[8].sin();
        let x2410 = q[8].cos();
        let x2418 = 0.00000000000000006123233995736766 * x2407;
        let x2419 = x2406 + x2418;
        let x2420 = 0.00000000000000006123233995736766 * x2406;
        let x2422 = x2420 - x2407;
        let x2503 = qd[2] * x2407;
        let x2504 = qd[2] * x2406;
        let x2506 = qd[8] * x2410;
        let x2507 = qd[8] * x2409;
        let x2515 = 0.00000000000000006123233995736766 * x2504;
        let x2517 = x2503 - x2515;
        let x2518 = 0.00000000000000006123233995736766 * x2503;
        let x2519 = x2504 + x2518;
        let x2580 = x1082 * x2419;
        let x2582 = x667 * x2517;
        let x2583 = x2582 - x2580;
        let x2584 = x1084 * x2422;
        let x2585 = x669 * x2519;
        let x2586 = x2584 + x2585;
        let x2588 = qd[2] * x2504;
        let x2590 = qd[2] * x2503;
        let x2591 = qd[8] * x2507;
        let x2593 = qd[8] * x2506;
        let x2594 = 0.05 * x2590;
        let x2596 = 0.05 * x2588;
        let x2598 = 0.00000000000000006123233995736766 * x2590;
        let x2600 = x2588 + x2598;
        let x2602 = 0.00000000000000006123233995736766 * x2588;
        let x2604 = x2590 - x2602;
        let x2605 = 0.17499999999999996 * x1103;
        let x2606 = 0.17499999999999996 * x1101;
        let x2609 = x2594 + x2605;
        let x2611 = x2596 + x2606;
        let x2613 = 0.175 * x1103;
        let x2614 = 0.000000000000000027755575615628914 * x1101;
        let x2616 = x2613 - x2614;
        let x2618 = 0.175 * x1101;
        let x2620 = 0.000000000000000027755575615628914 * x1103;
        let x2622 = x2618 + x2620;
        let x2624 = 0.14999999999999997 * x2593;
        let x2626 = 0.000000000000000006938893903907228 * x2591;
        let x2628 = x2624 - x2626;
        let x2630 = 0.14999999999999997 * x2591;
        let x2632 = 0.000000000000000006938893903907228 * x2593;
        let x2634 = x2630 + x2632;
        let x2636 = x2628 - x2616;
        let x2637 = x2634 - x2622;
        let x2638 = 0.00000000000000004163336342344337 * x2591;
        let x2640 = x2624 + x2638;
        let x2642 = 0.00000000000000004163336342344337 * x2593;
        let x2643 = x2642 - x2630;
        let x2644 = -x2643;
        let x2645 = x297 * x2600;
        let x2647 = x2582 - x2645;
        let x2648 = x2583 + x2647;
        let x2650 = x298 * x2604;
        let x2651 = x2650 - x2585;
        let x2652 = x2651 - x2586;
        let x2654 = x2648 - x2652;
        let x2655 = -x2636;
        let x2656 = -x2637;
        let x2657 = -x2654;
        out[0] = x2594;
        out[1] = x2596;
        out[2] = x2609;
        out[3] = x2611;
        out[4] = x2655;
        out[5] = x2656;
        out[6] = x2640;
        out[7] = x2644;
        out[8] = x2657;
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
        let phi: &mut [f64; 9] = phi.try_into().expect("phi must have 9 entries");
        let phi_q: &mut [f64; 25] = phi_q
            .try_into()
            .expect("phi_q must have 25 entries");
        let phi_t: &mut [f64; 9] = phi_t.try_into().expect("phi_t must have 9 entries");
        let gamma: &mut [f64; 9] = gamma.try_into().expect("gamma must have 9 entries");
        eval_kinematics_part_0(q, qd, t, phi, phi_q, phi_t, gamma);
    }
    #[inline(never)]
    fn eval_kinematics_part_0(
        q: &[f64; 9],
        qd: &[f64; 9],
        t: f64,
        phi: &mut [f64; 9],
        phi_q: &mut [f64; 25],
        phi_t: &mut [f64; 9],
        gamma: &mut [f64; 9],
    ) {
        let x5 = 6.283185307179586 * t;
        let x16 = q[5].sin();
        let x17 = q[5].cos();
        let x297 = x5.sin();
        let x298 = x5.cos();
        let x667 = 6.283185307179586 * x298;
        let x669 = 6.283185307179586 * x297;
        let x699 = x17 * qd[5];
        let x700 = x16 * qd[5];
        let x1082 = 6.283185307179586 * x669;
        let x1084 = 6.283185307179586 * x667;
        let x1101 = qd[5] * x700;
        let x1103 = qd[5] * x699;
        let x2406 = q[2].sin();
        let x2407 = q[2].cos();
        let x2409 = q[8].sin();
        let x2410 = q[8].cos();
        let x2412 = 0.05 * x2407;
        let x2414 = 0.05 * x2406;
        let x2415 = -x2414;
        let x2416 = q[0] - x2412;
        let x2417 = q[1] - x2414;
        let x2418 = 0.00000000000000006123233995736766 * x2407;
        let x2419 = x2406 + x2418;
        let x2420 = 0.00000000000000006123233995736766 * x2406;
        let x2422 = x2420 - x2407;
        let x2424 = x2407 - x2420;
        let x2425 = -x2416;
        let x2426 = -x2417;
        let x2427 = q[0] + x2412;
        let x2428 = q[1] + x2414;
        let x2429 = x17 * 0.17499999999999996;
        let x2431 = x16 * 0.17499999999999996;
        let x2432 = -x2431;
        let x2433 = q[3] - x2429;
        let x2434 = q[4] - x2431;
        let x2446 = x2427 - x2433;
        let x2448 = x2428 - x2434;
        let x2449 = x17 * 0.175;
        let x2450 = x16 * 0.000000000000000027755575615628914;
        let x2452 = x2449 - x2450;
        let x2453 = x16 * 0.175;
        let x2454 = x17 * 0.000000000000000027755575615628914;
        let x2455 = x2453 + x2454;
        let x2456 = q[3] + x2452;
        let x2457 = q[4] + x2455;
        let x2458 = 0.14999999999999997 * x2410;
        let x2459 = 0.000000000000000006938893903907228 * x2409;
        let x2461 = x2458 - x2459;
        let x2462 = 0.14999999999999997 * x2409;
        let x2463 = 0.000000000000000006938893903907228 * x2410;
        let x2464 = x2462 + x2463;
        let x2465 = q[6] + x2461;
        let x2466 = q[7] + x2464;
        let x2468 = x2456 - x2465;
        let x2470 = x2457 - x2466;
        let x2472 = 0.00000000000000004163336342344337 * x2409;
        let x2474 = x2458 + x2472;
        let x2477 = 0.00000000000000004163336342344337 * x2410;
        let x2478 = x2477 - x2462;
        let x2479 = q[6] - x2474;
        let x2480 = q[7] + x2478;
        let x2482 = 0.4 - x2479;
        let x2483 = -x2480;
        let x2484 = x297 * x2419;
        let x2485 = x298 * x2422;
        let x2487 = x2484 - x2485;
        let x2488 = x297 * x2424;
        let x2489 = x298 * x2419;
        let x2491 = x2488 - x2489;
        let x2494 = -x2455;
        let x2497 = -x2461;
        let x2499 = x667 * x2419;
        let x2500 = x669 * x2422;
        let x2502 = x2499 + x2500;
        let x2503 = qd[2] * x2407;
        let x2504 = qd[2] * x2406;
        let x2506 = qd[8] * x2410;
        let x2507 = qd[8] * x2409;
        let x2515 = 0.00000000000000006123233995736766 * x2504;
        let x2517 = x2503 - x2515;
        let x2518 = 0.00000000000000006123233995736766 * x2503;
        let x2519 = x2504 + x2518;
        let x2580 = x1082 * x2419;
        let x2582 = x667 * x2517;
        let x2583 = x2582 - x2580;
        let x2584 = x1084 * x2422;
        let x2585 = x669 * x2519;
        let x2586 = x2584 + x2585;
        let x2588 = qd[2] * x2504;
        let x2590 = qd[2] * x2503;
        let x2591 = qd[8] * x2507;
        let x2593 = qd[8] * x2506;
        let x2594 = 0.05 * x2590;
        let x2596 = 0.05 * x2588;
        let x2598 = 0.00000000000000006123233995736766 * x2590;
        let x2600 = x2588 + x2598;
        let x2602 = 0.00000000000000006123233995736766 * x2588;
        let x2604 = x2590 - x2602;
        let x2605 = 0.17499999999999996 * x1103;
        let x2606 = 0.17499999999999996 * x1101;
        let x2609 = x2594 + x2605;
        let x2611 = x2596 + x2606;
        let x2613 = 0.175 * x1103;
        let x2614 = 0.000000000000000027755575615628914 * x1101;
        let x2616 = x2613 - x2614;
        let x2618 = 0.175 * x1101;
        let x2620 = 0.000000000000000027755575615628914 * x1103;
        let x2622 = x2618 + x2620;
        let x2624 = 0.14999999999999997 * x2593;
        let x2626 = 0.000000000000000006938893903907228 * x2591;
        let x2628 = x2624 - x2626;
        let x2630 = 0.14999999999999997 * x2591;
        let x2632 = 0.000000000000000006938893903907228 * x2593;
        let x2634 = x2630 + x2632;
        let x2636 = x2628 - x2616;
        let x2637 = x2634 - x2622;
        let x2638 = 0.00000000000000004163336342344337 * x2591;
        let x2640 = x2624 + x2638;
        let x2642 = 0.00000000000000004163336342344337 * x2593;
        let x2643 = x2642 - x2630;
        let x2644 = -x2643;
        let x2645 = x297 * x2600;
        let x2647 = x2582 - x2645;
        let x2648 = x2583 + x2647;
        let x2650 = x298 * x2604;
        let x2651 = x2650 - x2585;
        let x2652 = x2651 - x2586;
        let x2654 = x2648 - x2652;
        let x2655 = -x2636;
        let x2656 = -x2637;
        let x2657 = -x2654;
        phi[0] = x2425;
        phi_q[0] = -1.0;
        phi_q[1] = x2415;
        phi_t[0] = 0.0;
        gamma[0] = x2594;
        phi[1] = x2426;
        phi_q[2] = -1.0;
        phi_q[3] = x2412;
        phi_t[1] = 0.0;
        gamma[1] = x2596;
        phi[2] = x2446;
        phi_q[4] = 1.0;
        phi_q[5] = x2415;
        phi_q[6] = -1.0;
        phi_q[7] = x2432;
        phi_t[2] = 0.0;
        gamma[2] = x2609;
        phi[3] = x2448;
        phi_q[8] = 1.0;
        phi_q[9] = x2412;
        phi_q[10] = -1.0;
        phi_q[11] = x2429;
        phi_t[3] = 0.0;
        gamma[3] = x2611;
        phi[4] = x2468;
        phi_q[12] = 1.0;
        phi_q[13] = x2494;
        phi_q[14] = -1.0;
        phi_q[15] = x2464;
        phi_t[4] = 0.0;
        gamma[4] = x2655;
        phi[5] = x2470;
        phi_q[16] = 1.0;
        phi_q[17] = x2452;
        phi_q[18] = -1.0;
        phi_q[19] = x2497;
        phi_t[5] = 0.0;
        gamma[5] = x2656;
        phi[6] = x2482;
        phi_q[20] = -1.0;
        phi_q[21] = x2478;
        phi_t[6] = 0.0;
        gamma[6] = x2640;
        phi[7] = x2483;
        phi_q[22] = -1.0;
        phi_q[23] = x2474;
        phi_t[7] = 0.0;
        gamma[7] = x2644;
        phi[8] = x2487;
        phi_q[24] = x2491;
        phi_t[8] = x2502;
        gamma[8] = x2657;
    }
    /// Potential energy of gravity and springs, written to `out[0]`.
    pub fn potential_into(q: &[f64], out: &mut [f64]) {
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        potential_into_part_0(q, out);
    }
    #[inline(never)]
    fn potential_into_part_0(q: &[f64; 9], out: &mut [f64; 1]) {
        let x1758 = q[1] * 1.9620000000000002;
        let x2658 = q[4] * 4.905;
        let x2659 = q[7] * 3.9240000000000004;
        let x2660 = x1758 + x2658;
        let x2661 = x2659 + x2660;
        out[0] = x2661;
    }
    /// Power of the non-conservative loads, written to `out[0]`.
    pub fn power_nc_into(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
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
        pub static MASS_ROWS: [u32; 9usize] = [
            0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 7u32, 8u32,
        ];
        /// Column of each mass-matrix nonzero.
        pub static MASS_COLS: [u32; 9usize] = [
            0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 7u32, 8u32,
        ];
        /// Row and column of each ∂Q/∂q nonzero.
        pub static FORCE_Q_ROWS: [u32; 0usize] = [];
        pub static FORCE_Q_COLS: [u32; 0usize] = [];
        /// Row and column of each ∂Q/∂q̇ nonzero.
        pub static FORCE_QD_ROWS: [u32; 0usize] = [];
        pub static FORCE_QD_COLS: [u32; 0usize] = [];
        /// Sizes, patterns and names for this formulation.
        pub static INFO: MechanismInfo = MechanismInfo {
            name: "four_bar_reduced",
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
            let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
            let _ = q;
            mass_part_0(out);
        }
        #[inline(never)]
        fn mass_part_0(out: &mut [f64; 9]) {
            out[0] = 0.2;
            out[1] = 0.2;
            out[2] = 0.00016666666666666672;
            out[3] = 0.5;
            out[4] = 0.5;
            out[5] = 0.005104166666666666;
            out[6] = 0.4;
            out[7] = 0.4;
            out[8] = 0.0029999999999999996;
        }
        /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
        pub fn force(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
            let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
            let _ = q;
            let _ = qd;
            let _ = t;
            force_part_0(out);
        }
        #[inline(never)]
        fn force_part_0(out: &mut [f64; 9]) {
            out[0] = 0.0;
            out[1] = -1.9620000000000002;
            out[2] = 0.0;
            out[3] = 0.0;
            out[4] = -4.905;
            out[5] = 0.0;
            out[6] = 0.0;
            out[7] = -3.9240000000000004;
            out[8] = 0.0;
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
            let phi: &mut [f64; 9] = phi.try_into().expect("phi must have 9 entries");
            let phi_q: &mut [f64; 25] = phi_q
                .try_into()
                .expect("phi_q must have 25 entries");
            let mass: &mut [f64; 9] = mass.try_into().expect("mass must have 9 entries");
            let force: &mut [f64; 9] = force
                .try_into()
                .expect("force must have 9 entries");
            let _ = qd;
            eval_newton_part_0(q, t, phi, phi_q, mass, force);
        }
        #[inline(never)]
        fn eval_newton_part_0(
            q: &[f64; 9],
            t: f64,
            phi: &mut [f64; 9],
            phi_q: &mut [f64; 25],
            mass: &mut [f64; 9],
            force: &mut [f64; 9],
        ) {
            let x5 = 6.283185307179586 * t;
            let x16 = q[5].sin();
            let x17 = q[5].cos();
            let x297 = x5.sin();
            let x298 = x5.cos();
            let x2406 = q[2].sin();
            let x2407 = q[2].cos();
            let x2409 = q[8].sin();
            let x2410 = q[8].cos();
            let x2412 = 0.05 * x2407;
            let x2414 = 0.05 * x2406;
            let x2415 = -x2414;
            let x2416 = q[0] - x2412;
            let x2417 = q[1] - x2414;
            let x2418 = 0.00000000000000006123233995736766 * x2407;
            let x2419 = x2406 + x2418;
            let x2420 = 0.00000000000000006123233995736766 * x2406;
            let x2422 = x2420 - x2407;
            let x2424 = x2407 - x2420;
            let x2425 = -x2416;
            let x2426 = -x2417;
            let x2427 = q[0] + x2412;
            let x2428 = q[1] + x2414;
            let x2429 = x17 * 0.17499999999999996;
            let x2431 = x16 * 0.17499999999999996;
            let x2432 = -x2431;
            let x2433 = q[3] - x2429;
            let x2434 = q[4] - x2431;
            let x2446 = x2427 - x2433;
            let x2448 = x2428 - x2434;
            let x2449 = x17 * 0.175;
            let x2450 = x16 * 0.000000000000000027755575615628914;
            let x2452 = x2449 - x2450;
            let x2453 = x16 * 0.175;
            let x2454 = x17 * 0.000000000000000027755575615628914;
            let x2455 = x2453 + x2454;
            let x2456 = q[3] + x2452;
            let x2457 = q[4] + x2455;
            let x2458 = 0.14999999999999997 * x2410;
            let x2459 = 0.000000000000000006938893903907228 * x2409;
            let x2461 = x2458 - x2459;
            let x2462 = 0.14999999999999997 * x2409;
            let x2463 = 0.000000000000000006938893903907228 * x2410;
            let x2464 = x2462 + x2463;
            let x2465 = q[6] + x2461;
            let x2466 = q[7] + x2464;
            let x2468 = x2456 - x2465;
            let x2470 = x2457 - x2466;
            let x2472 = 0.00000000000000004163336342344337 * x2409;
            let x2474 = x2458 + x2472;
            let x2477 = 0.00000000000000004163336342344337 * x2410;
            let x2478 = x2477 - x2462;
            let x2479 = q[6] - x2474;
            let x2480 = q[7] + x2478;
            let x2482 = 0.4 - x2479;
            let x2483 = -x2480;
            let x2484 = x297 * x2419;
            let x2485 = x298 * x2422;
            let x2487 = x2484 - x2485;
            let x2488 = x297 * x2424;
            let x2489 = x298 * x2419;
            let x2491 = x2488 - x2489;
            let x2494 = -x2455;
            let x2497 = -x2461;
            phi[0] = x2425;
            phi_q[0] = -1.0;
            phi_q[1] = x2415;
            phi[1] = x2426;
            phi_q[2] = -1.0;
            phi_q[3] = x2412;
            phi[2] = x2446;
            phi_q[4] = 1.0;
            phi_q[5] = x2415;
            phi_q[6] = -1.0;
            phi_q[7] = x2432;
            phi[3] = x2448;
            phi_q[8] = 1.0;
            phi_q[9] = x2412;
            phi_q[10] = -1.0;
            phi_q[11] = x2429;
            phi[4] = x2468;
            phi_q[12] = 1.0;
            phi_q[13] = x2494;
            phi_q[14] = -1.0;
            phi_q[15] = x2464;
            phi[5] = x2470;
            phi_q[16] = 1.0;
            phi_q[17] = x2452;
            phi_q[18] = -1.0;
            phi_q[19] = x2497;
            phi[6] = x2482;
            phi_q[20] = -1.0;
            phi_q[21] = x2478;
            phi[7] = x2483;
            phi_q[22] = -1.0;
            phi_q[23] = x2474;
            phi[8] = x2487;
            phi_q[24] = x2491;
            mass[0] = 0.2;
            mass[1] = 0.2;
            mass[2] = 0.00016666666666666672;
            mass[3] = 0.5;
            mass[4] = 0.5;
            mass[5] = 0.005104166666666666;
            mass[6] = 0.4;
            mass[7] = 0.4;
            mass[8] = 0.0029999999999999996;
            force[0] = 0.0;
            force[1] = -1.9620000000000002;
            force[2] = 0.0;
            force[3] = 0.0;
            force[4] = -4.905;
            force[5] = 0.0;
            force[6] = 0.0;
            force[7] = -3.9240000000000004;
            force[8] = 0.0;
        }
    }
    /// `four_bar` reduced by substitution, with the `exact` formulation.
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
/// `four_bar` with the `exact` formulation.
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
/// `four_bar` with the `exact` formulation. At run-time parameter values (`Exact::with_parameters`).
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
    name: "four_bar",
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
            env!("CARGO_MANIFEST_DIR"), "/../../../", "mechanisms/four_bar.toml"
        ),
        hash: 7321727117792067321u64,
        parameters: &[],
    },
    run_time: Some(&RUN_TIME_ENTRY),
};
