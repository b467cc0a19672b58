//! Generated equations of `slider_crank` (spatial slider-crank, slider axis offset from the crank plane, crank driven). Do not edit.
//!
//! Regenerate with `cargo xtask generate slider_crank` from `mechanisms/slider_crank.toml`.
//!
//! 21 coordinates, 21 constraints, 105 structural nonzeros in Φq.
//! Rank 21 at the initial pose; mobility 1 (Grübler count 1), 0 DOF left with drivers.
//! Each body owns `[X, Y, Z]` (centre of mass), then `[θ, β, γ]` (A = Rz(γ)·Ry(β)·Rx(θ))
//! or Euler parameters `[e0, e1, e2, e3]`. Equations of motion: `M q̈ + Φqᵀλ = Q`, `Φq q̈ = γ`.
//! Sparse outputs hold the pattern's nonzeros in order (row-major, columns ascending).
//!
//! Coordinates:
//! - `0..7` crank (quaternion)
//! - `7..14` rod (quaternion)
//! - `14..21` slider (quaternion)
//!
//! Constraint rows:
//! - `0..5` crank_pivot (revolute, ground – crank)
//! - `5..8` crank_pin (spherical, crank – rod)
//! - `8..12` slider_pin (universal, slider – rod)
//! - `12..17` guide (prismatic, ground – slider)
//! - `17` motor (driver): sin(f − θ) of `crank_pivot`, f = initial + 2.0 * pi * t, initial = 0.000000000
//! - `18` crank.norm: eᵀe − 1
//! - `19` rod.norm: eᵀe − 1
//! - `20` slider.norm: eᵀe − 1
#![allow(
    clippy::approx_constant,
    clippy::excessive_precision,
    clippy::too_many_arguments,
    clippy::unreadable_literal
)]
use symbody_runtime::{
    BodyInfo, Formulation, JointInfo, JointKind, KinematicOutputs, Mechanism,
    MechanismInfo, NewtonOutputs, PlatformInfo, Rotation,
};
/// Constraint residual Φ(q, t).
pub fn phi(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
    phi_part_0(q, t, out);
}
#[inline(never)]
fn phi_part_0(q: &[f64; 21], t: f64, out: &mut [f64; 21]) {
    let x5 = 6.283185307179586 * t;
    let x14 = q[3] * q[3];
    let x15 = q[4] * q[4];
    let x16 = q[5] * q[5];
    let x17 = q[6] * q[6];
    let x18 = x14 + x15;
    let x19 = 2.0 * x18;
    let x21 = x19 - 1.0;
    let x28 = q[4] * q[5];
    let x29 = 2.0 * x28;
    let x30 = q[3] * q[6];
    let x32 = 2.0 * x30;
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
    let x59 = q[10] * q[10];
    let x60 = q[11] * q[11];
    let x61 = q[12] * q[12];
    let x62 = q[13] * q[13];
    let x63 = x59 + x60;
    let x64 = 2.0 * x63;
    let x65 = x64 - 1.0;
    let x66 = x59 + x61;
    let x67 = 2.0 * x66;
    let x68 = x67 - 1.0;
    let x69 = x59 + x62;
    let x70 = 2.0 * x69;
    let x71 = x70 - 1.0;
    let x72 = q[11] * q[12];
    let x73 = 2.0 * x72;
    let x74 = q[10] * q[13];
    let x76 = 2.0 * x74;
    let x78 = x73 - x76;
    let x79 = q[11] * q[13];
    let x80 = 2.0 * x79;
    let x81 = q[10] * q[12];
    let x82 = 2.0 * x81;
    let x83 = x80 + x82;
    let x84 = x73 + x76;
    let x85 = q[12] * q[13];
    let x86 = 2.0 * x85;
    let x87 = q[10] * q[11];
    let x89 = 2.0 * x87;
    let x91 = x86 - x89;
    let x94 = x80 - x82;
    let x95 = x86 + x89;
    let x103 = q[17] * q[17];
    let x104 = q[18] * q[18];
    let x105 = q[19] * q[19];
    let x106 = q[20] * q[20];
    let x107 = x103 + x104;
    let x113 = x103 + x106;
    let x114 = 2.0 * x113;
    let x115 = x114 - 1.0;
    let x116 = q[18] * q[19];
    let x117 = 2.0 * x116;
    let x118 = q[17] * q[20];
    let x120 = 2.0 * x118;
    let x123 = q[18] * q[20];
    let x124 = 2.0 * x123;
    let x125 = q[17] * q[19];
    let x126 = 2.0 * x125;
    let x127 = x124 + x126;
    let x128 = x117 + x120;
    let x129 = q[19] * q[20];
    let x130 = 2.0 * x129;
    let x131 = q[17] * q[18];
    let x133 = 2.0 * x131;
    let x135 = x130 - x133;
    let x138 = x124 - x126;
    let x139 = x130 + x133;
    let x142 = x21 * 0.05;
    let x144 = x40 * 0.05;
    let x146 = x50 * 0.05;
    let x148 = q[0] - x142;
    let x149 = q[1] - x144;
    let x150 = q[2] - x146;
    let x151 = -x148;
    let x152 = -x149;
    let x153 = -x150;
    let x154 = q[0] + x142;
    let x155 = q[1] + x144;
    let x156 = q[2] + x146;
    let x161 = x65 * 0.1749999999999999;
    let x163 = x78 * 0.000000000000000003677613769070831;
    let x164 = x83 * 0.000000000000000013877787807814457;
    let x165 = x163 - x161;
    let x166 = x164 + x165;
    let x167 = x84 * 0.1749999999999999;
    let x169 = x68 * 0.000000000000000003677613769070831;
    let x170 = x91 * 0.000000000000000013877787807814457;
    let x171 = x169 - x167;
    let x172 = x170 + x171;
    let x173 = x94 * 0.1749999999999999;
    let x175 = x95 * 0.000000000000000003677613769070831;
    let x176 = x71 * 0.000000000000000013877787807814457;
    let x177 = x175 - x173;
    let x178 = x176 + x177;
    let x179 = q[7] + x166;
    let x180 = q[8] + x172;
    let x181 = q[9] + x178;
    let x183 = x154 - x179;
    let x185 = x155 - x180;
    let x187 = x156 - x181;
    let x191 = x65 * 0.17499999999999993;
    let x193 = x78 * 0.00000000000000001061650767297806;
    let x196 = x83 * 0.000000000000000027755575615628914;
    let x198 = x191 - x193;
    let x199 = x198 - x196;
    let x200 = x84 * 0.17499999999999993;
    let x201 = x68 * 0.00000000000000001061650767297806;
    let x203 = x91 * 0.000000000000000027755575615628914;
    let x205 = x200 - x201;
    let x206 = x205 - x203;
    let x207 = x94 * 0.17499999999999993;
    let x208 = x95 * 0.00000000000000001061650767297806;
    let x210 = x71 * 0.000000000000000027755575615628914;
    let x212 = x207 - x208;
    let x213 = x212 - x210;
    let x214 = q[7] + x199;
    let x215 = q[8] + x206;
    let x216 = q[9] + x213;
    let x271 = x65 * 0.00000000000000005551115123125783;
    let x272 = x78 * 0.9999999999999994;
    let x273 = x271 + x272;
    let x274 = x84 * 0.00000000000000005551115123125783;
    let x275 = x68 * 0.9999999999999994;
    let x276 = x274 + x275;
    let x277 = x94 * 0.00000000000000005551115123125783;
    let x278 = x95 * 0.9999999999999994;
    let x279 = x277 + x278;
    let x281 = q[14] - x214;
    let x283 = q[15] - x215;
    let x285 = q[16] - x216;
    let x286 = x127 * x273;
    let x287 = x135 * x276;
    let x288 = x115 * x279;
    let x289 = x286 + x287;
    let x290 = x288 + x289;
    let x295 = q[15] - 0.05;
    let x297 = q[16] - 0.12;
    let x298 = x5.sin();
    let x299 = x5.cos();
    let x300 = x21 * x298;
    let x301 = x40 * x299;
    let x303 = x300 - x301;
    let x304 = x16 + x18;
    let x305 = x17 + x304;
    let x306 = x305 - 1.0;
    let x307 = x61 + x63;
    let x308 = x62 + x307;
    let x309 = x308 - 1.0;
    let x310 = x105 + x107;
    let x311 = x106 + x310;
    let x312 = x311 - 1.0;
    out[0] = x151;
    out[1] = x152;
    out[2] = x153;
    out[3] = x39;
    out[4] = x47;
    out[5] = x183;
    out[6] = x185;
    out[7] = x187;
    out[8] = x281;
    out[9] = x283;
    out[10] = x285;
    out[11] = x290;
    out[12] = x128;
    out[13] = x138;
    out[14] = x295;
    out[15] = x297;
    out[16] = x139;
    out[17] = x303;
    out[18] = x306;
    out[19] = x309;
    out[20] = x312;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 105] = out.try_into().expect("out must have 105 entries");
    phi_q_part_0(q, t, out);
}
#[inline(never)]
fn phi_q_part_0(q: &[f64; 21], t: f64, out: &mut [f64; 105]) {
    let x5 = 6.283185307179586 * t;
    let x59 = q[10] * q[10];
    let x60 = q[11] * q[11];
    let x61 = q[12] * q[12];
    let x63 = x59 + x60;
    let x64 = 2.0 * x63;
    let x65 = x64 - 1.0;
    let x66 = x59 + x61;
    let x67 = 2.0 * x66;
    let x68 = x67 - 1.0;
    let x72 = q[11] * q[12];
    let x73 = 2.0 * x72;
    let x74 = q[10] * q[13];
    let x76 = 2.0 * x74;
    let x78 = x73 - x76;
    let x79 = q[11] * q[13];
    let x80 = 2.0 * x79;
    let x81 = q[10] * q[12];
    let x82 = 2.0 * x81;
    let x84 = x73 + x76;
    let x85 = q[12] * q[13];
    let x86 = 2.0 * x85;
    let x87 = q[10] * q[11];
    let x89 = 2.0 * x87;
    let x94 = x80 - x82;
    let x95 = x86 + x89;
    let x103 = q[17] * q[17];
    let x106 = q[20] * q[20];
    let x113 = x103 + x106;
    let x114 = 2.0 * x113;
    let x115 = x114 - 1.0;
    let x123 = q[18] * q[20];
    let x124 = 2.0 * x123;
    let x125 = q[17] * q[19];
    let x126 = 2.0 * x125;
    let x127 = x124 + x126;
    let x129 = q[19] * q[20];
    let x130 = 2.0 * x129;
    let x131 = q[17] * q[18];
    let x133 = 2.0 * x131;
    let x135 = x130 - x133;
    let x271 = x65 * 0.00000000000000005551115123125783;
    let x272 = x78 * 0.9999999999999994;
    let x273 = x271 + x272;
    let x274 = x84 * 0.00000000000000005551115123125783;
    let x275 = x68 * 0.9999999999999994;
    let x276 = x274 + x275;
    let x277 = x94 * 0.00000000000000005551115123125783;
    let x278 = x95 * 0.9999999999999994;
    let x279 = x277 + x278;
    let x298 = x5.sin();
    let x299 = x5.cos();
    let x313 = 2.0 * q[3];
    let x314 = 2.0 * q[4];
    let x315 = 2.0 * q[10];
    let x316 = 2.0 * q[11];
    let x317 = 2.0 * q[12];
    let x318 = 2.0 * q[13];
    let x319 = 2.0 * q[5];
    let x320 = 2.0 * q[6];
    let x321 = 2.0 * x313;
    let x322 = -x314;
    let x324 = 0.05 * x321;
    let x326 = 0.05 * x320;
    let x328 = 0.05 * x319;
    let x329 = -x328;
    let x330 = x298 * x321;
    let x331 = x299 * x320;
    let x333 = x330 - x331;
    let x334 = 2.0 * x314;
    let x335 = -x313;
    let x336 = 0.05 * x334;
    let x338 = x298 * x334;
    let x339 = x299 * x319;
    let x341 = x338 - x339;
    let x342 = 0.05 * x314;
    let x344 = 0.05 * x313;
    let x345 = -x344;
    let x346 = x299 * x314;
    let x347 = -x346;
    let x348 = x299 * x313;
    let x349 = -x348;
    let x350 = 2.0 * x315;
    let x354 = 2.0 * q[17];
    let x355 = 2.0 * q[20];
    let x356 = 0.1749999999999999 * x350;
    let x358 = 0.000000000000000003677613769070831 * x318;
    let x360 = 0.000000000000000013877787807814457 * x317;
    let x361 = x356 + x358;
    let x363 = x360 - x361;
    let x364 = 0.1749999999999999 * x318;
    let x366 = 0.000000000000000003677613769070831 * x350;
    let x367 = 0.000000000000000013877787807814457 * x316;
    let x369 = x366 - x364;
    let x370 = x369 - x367;
    let x371 = 0.1749999999999999 * x317;
    let x373 = 0.000000000000000003677613769070831 * x316;
    let x374 = 0.000000000000000013877787807814457 * x350;
    let x375 = x371 + x373;
    let x376 = x374 + x375;
    let x377 = -x363;
    let x378 = -x370;
    let x379 = -x376;
    let x380 = 0.17499999999999993 * x350;
    let x381 = 0.00000000000000001061650767297806 * x318;
    let x383 = 0.000000000000000027755575615628914 * x317;
    let x385 = x380 + x381;
    let x386 = x385 - x383;
    let x387 = 0.17499999999999993 * x318;
    let x388 = 0.00000000000000001061650767297806 * x350;
    let x390 = 0.000000000000000027755575615628914 * x316;
    let x392 = x387 - x388;
    let x393 = x390 + x392;
    let x394 = 0.17499999999999993 * x317;
    let x396 = 0.00000000000000001061650767297806 * x316;
    let x398 = 0.000000000000000027755575615628914 * x350;
    let x400 = x394 + x396;
    let x402 = x398 + x400;
    let x404 = 0.00000000000000005551115123125783 * x350;
    let x405 = 0.9999999999999994 * x318;
    let x407 = x404 - x405;
    let x408 = 0.00000000000000005551115123125783 * x318;
    let x409 = 0.9999999999999994 * x350;
    let x410 = x408 + x409;
    let x411 = 0.00000000000000005551115123125783 * x317;
    let x413 = 0.9999999999999994 * x316;
    let x414 = x413 - x411;
    let x415 = -x386;
    let x416 = -x393;
    let x417 = x127 * x407;
    let x418 = x135 * x410;
    let x419 = x115 * x414;
    let x420 = x417 + x418;
    let x421 = x419 + x420;
    let x422 = 2.0 * x316;
    let x424 = 0.1749999999999999 * x422;
    let x426 = 0.000000000000000003677613769070831 * x317;
    let x427 = 0.000000000000000013877787807814457 * x318;
    let x428 = x426 - x424;
    let x429 = x427 + x428;
    let x430 = 0.000000000000000013877787807814457 * x315;
    let x432 = x371 + x430;
    let x434 = 0.000000000000000003677613769070831 * x315;
    let x435 = x434 - x364;
    let x436 = -x429;
    let x437 = -x435;
    let x438 = 0.17499999999999993 * x422;
    let x439 = 0.00000000000000001061650767297806 * x317;
    let x441 = 0.000000000000000027755575615628914 * x318;
    let x443 = x438 - x439;
    let x444 = x443 - x441;
    let x445 = 0.000000000000000027755575615628914 * x315;
    let x447 = x394 + x445;
    let x448 = 0.00000000000000001061650767297806 * x315;
    let x450 = x387 - x448;
    let x451 = 0.00000000000000005551115123125783 * x422;
    let x452 = 0.9999999999999994 * x317;
    let x453 = x451 + x452;
    let x454 = 0.9999999999999994 * x315;
    let x455 = x408 + x454;
    let x456 = -x444;
    let x457 = -x447;
    let x458 = -x450;
    let x459 = x127 * x453;
    let x460 = x135 * x411;
    let x461 = x115 * x455;
    let x462 = x459 + x460;
    let x463 = x461 + x462;
    let x464 = 2.0 * x317;
    let x465 = x373 + x430;
    let x466 = 0.1749999999999999 * x316;
    let x468 = 0.000000000000000003677613769070831 * x464;
    let x469 = x468 - x466;
    let x470 = x427 + x469;
    let x471 = 0.1749999999999999 * x315;
    let x473 = x358 + x471;
    let x474 = -x465;
    let x475 = -x470;
    let x476 = -x473;
    let x477 = x396 + x445;
    let x479 = 0.17499999999999993 * x316;
    let x480 = 0.00000000000000001061650767297806 * x464;
    let x482 = x479 - x480;
    let x483 = x482 - x441;
    let x484 = 0.17499999999999993 * x315;
    let x486 = x381 + x484;
    let x488 = 0.00000000000000005551115123125783 * x316;
    let x489 = 0.9999999999999994 * x464;
    let x490 = x488 + x489;
    let x491 = 0.00000000000000005551115123125783 * x315;
    let x493 = x405 - x491;
    let x494 = -x483;
    let x495 = x127 * x413;
    let x496 = x135 * x490;
    let x497 = x115 * x493;
    let x498 = x495 + x496;
    let x499 = x497 + x498;
    let x500 = 2.0 * x318;
    let x502 = x367 - x434;
    let x503 = x360 - x471;
    let x504 = 0.000000000000000013877787807814457 * x500;
    let x505 = x426 - x466;
    let x506 = x504 + x505;
    let x507 = -x502;
    let x508 = -x503;
    let x509 = -x506;
    let x510 = x448 - x390;
    let x511 = x484 - x383;
    let x512 = 0.000000000000000027755575615628914 * x500;
    let x514 = x479 - x439;
    let x515 = x514 - x512;
    let x517 = x452 + x488;
    let x518 = -x510;
    let x519 = -x511;
    let x520 = -x515;
    let x521 = x127 * x454;
    let x523 = x135 * x491;
    let x524 = x115 * x517;
    let x525 = x523 - x521;
    let x526 = x524 + x525;
    let x527 = 2.0 * q[18];
    let x528 = 2.0 * q[19];
    let x529 = 2.0 * x354;
    let x531 = -x528;
    let x532 = x273 * x528;
    let x533 = x276 * x527;
    let x535 = x279 * x529;
    let x536 = x532 - x533;
    let x537 = x535 + x536;
    let x538 = -x354;
    let x539 = x273 * x355;
    let x540 = x276 * x354;
    let x542 = x539 - x540;
    let x543 = x273 * x354;
    let x544 = x276 * x355;
    let x545 = x543 + x544;
    let x546 = 2.0 * x355;
    let x547 = x273 * x527;
    let x548 = x276 * x528;
    let x549 = x279 * x546;
    let x550 = x547 + x548;
    let x551 = x549 + x550;
    out[0] = -1.0;
    out[1] = x324;
    out[2] = x336;
    out[3] = -1.0;
    out[4] = x326;
    out[5] = x328;
    out[6] = x342;
    out[7] = x344;
    out[8] = -1.0;
    out[9] = x329;
    out[10] = x326;
    out[11] = x345;
    out[12] = x342;
    out[13] = x319;
    out[14] = x320;
    out[15] = x313;
    out[16] = x314;
    out[17] = x322;
    out[18] = x335;
    out[19] = x320;
    out[20] = x319;
    out[21] = 1.0;
    out[22] = x324;
    out[23] = x336;
    out[24] = -1.0;
    out[25] = x377;
    out[26] = x436;
    out[27] = x474;
    out[28] = x507;
    out[29] = 1.0;
    out[30] = x326;
    out[31] = x328;
    out[32] = x342;
    out[33] = x344;
    out[34] = -1.0;
    out[35] = x378;
    out[36] = x432;
    out[37] = x475;
    out[38] = x508;
    out[39] = 1.0;
    out[40] = x329;
    out[41] = x326;
    out[42] = x345;
    out[43] = x342;
    out[44] = -1.0;
    out[45] = x379;
    out[46] = x437;
    out[47] = x476;
    out[48] = x509;
    out[49] = -1.0;
    out[50] = x415;
    out[51] = x456;
    out[52] = x477;
    out[53] = x518;
    out[54] = 1.0;
    out[55] = -1.0;
    out[56] = x416;
    out[57] = x457;
    out[58] = x494;
    out[59] = x519;
    out[60] = 1.0;
    out[61] = -1.0;
    out[62] = x402;
    out[63] = x458;
    out[64] = x486;
    out[65] = x520;
    out[66] = 1.0;
    out[67] = x421;
    out[68] = x463;
    out[69] = x499;
    out[70] = x526;
    out[71] = x537;
    out[72] = x542;
    out[73] = x545;
    out[74] = x551;
    out[75] = x355;
    out[76] = x528;
    out[77] = x527;
    out[78] = x354;
    out[79] = x531;
    out[80] = x355;
    out[81] = x538;
    out[82] = x527;
    out[83] = 1.0;
    out[84] = 1.0;
    out[85] = x527;
    out[86] = x354;
    out[87] = x355;
    out[88] = x528;
    out[89] = x333;
    out[90] = x341;
    out[91] = x347;
    out[92] = x349;
    out[93] = x313;
    out[94] = x314;
    out[95] = x319;
    out[96] = x320;
    out[97] = x315;
    out[98] = x316;
    out[99] = x317;
    out[100] = x318;
    out[101] = x354;
    out[102] = x527;
    out[103] = x528;
    out[104] = x355;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
    phi_t_part_0(q, t, out);
}
#[inline(never)]
fn phi_t_part_0(q: &[f64; 21], t: f64, out: &mut [f64; 21]) {
    let x5 = 6.283185307179586 * t;
    let x14 = q[3] * q[3];
    let x15 = q[4] * q[4];
    let x18 = x14 + x15;
    let x19 = 2.0 * x18;
    let x21 = x19 - 1.0;
    let x28 = q[4] * q[5];
    let x29 = 2.0 * x28;
    let x30 = q[3] * q[6];
    let x32 = 2.0 * x30;
    let x40 = x29 + x32;
    let x298 = x5.sin();
    let x299 = x5.cos();
    let x552 = 6.283185307179586 * x299;
    let x554 = 6.283185307179586 * x298;
    let x556 = x21 * x552;
    let x557 = x40 * x554;
    let x559 = x556 + x557;
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
    out[17] = x559;
    out[18] = 0.0;
    out[19] = 0.0;
    out[20] = 0.0;
}
/// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
pub fn gamma(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 21] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
    gamma_part_0(q, qd, t, out);
}
#[inline(never)]
fn gamma_part_0(q: &[f64; 21], qd: &[f64; 21], t: f64, out: &mut [f64; 21]) {
    let x5 = 6.283185307179586 * t;
    let x14 = q[3] * q[3];
    let x15 = q[4] * q[4];
    let x18 = x14 + x15;
    let x19 = 2.0 * x18;
    let x21 = x19 - 1.0;
    let x28 = q[4] * q[5];
    let x29 = 2.0 * x28;
    let x30 = q[3] * q[6];
    let x32 = 2.0 * x30;
    let x40 = x29 + x32;
    let x59 = q[10] * q[10];
    let x60 = q[11] * q[11];
    let x61 = q[12] * q[12];
    let x63 = x59 + x60;
    let x64 = 2.0 * x63;
    let x65 = x64 - 1.0;
    let x66 = x59 + x61;
    let x67 = 2.0 * x66;
    let x68 = x67 - 1.0;
    let x72 = q[11] * q[12];
    let x73 = 2.0 * x72;
    let x74 = q[10] * q[13];
    let x76 = 2.0 * x74;
    let x78 = x73 - x76;
    let x79 = q[11] * q[13];
    let x80 = 2.0 * x79;
    let x81 = q[10] * q[12];
    let x82 = 2.0 * x81;
    let x84 = x73 + x76;
    let x85 = q[12] * q[13];
    let x86 = 2.0 * x85;
    let x87 = q[10] * q[11];
    let x89 = 2.0 * x87;
    let x94 = x80 - x82;
    let x95 = x86 + x89;
    let x103 = q[17] * q[17];
    let x106 = q[20] * q[20];
    let x113 = x103 + x106;
    let x114 = 2.0 * x113;
    let x115 = x114 - 1.0;
    let x123 = q[18] * q[20];
    let x124 = 2.0 * x123;
    let x125 = q[17] * q[19];
    let x126 = 2.0 * x125;
    let x127 = x124 + x126;
    let x129 = q[19] * q[20];
    let x130 = 2.0 * x129;
    let x131 = q[17] * q[18];
    let x133 = 2.0 * x131;
    let x135 = x130 - x133;
    let x271 = x65 * 0.00000000000000005551115123125783;
    let x272 = x78 * 0.9999999999999994;
    let x273 = x271 + x272;
    let x274 = x84 * 0.00000000000000005551115123125783;
    let x275 = x68 * 0.9999999999999994;
    let x276 = x274 + x275;
    let x277 = x94 * 0.00000000000000005551115123125783;
    let x278 = x95 * 0.9999999999999994;
    let x279 = x277 + x278;
    let x298 = x5.sin();
    let x299 = x5.cos();
    let x313 = 2.0 * q[3];
    let x314 = 2.0 * q[4];
    let x315 = 2.0 * q[10];
    let x316 = 2.0 * q[11];
    let x317 = 2.0 * q[12];
    let x354 = 2.0 * q[17];
    let x355 = 2.0 * q[20];
    let x552 = 6.283185307179586 * x299;
    let x554 = 6.283185307179586 * x298;
    let x581 = x313 * qd[3];
    let x582 = x314 * qd[4];
    let x585 = x581 + x582;
    let x586 = 2.0 * x585;
    let x587 = q[5] * qd[4];
    let x588 = q[4] * qd[5];
    let x589 = x587 + x588;
    let x590 = 2.0 * x589;
    let x591 = q[6] * qd[3];
    let x592 = q[3] * qd[6];
    let x593 = x591 + x592;
    let x594 = 2.0 * x593;
    let x604 = x590 + x594;
    let x617 = x315 * qd[10];
    let x618 = x316 * qd[11];
    let x619 = x317 * qd[12];
    let x621 = x617 + x618;
    let x622 = 2.0 * x621;
    let x623 = x617 + x619;
    let x624 = 2.0 * x623;
    let x627 = q[12] * qd[11];
    let x628 = q[11] * qd[12];
    let x629 = x627 + x628;
    let x630 = 2.0 * x629;
    let x631 = q[13] * qd[10];
    let x632 = q[10] * qd[13];
    let x633 = x631 + x632;
    let x634 = 2.0 * x633;
    let x636 = x630 - x634;
    let x637 = q[13] * qd[11];
    let x638 = q[11] * qd[13];
    let x639 = x637 + x638;
    let x640 = 2.0 * x639;
    let x641 = q[12] * qd[10];
    let x642 = q[10] * qd[12];
    let x643 = x641 + x642;
    let x644 = 2.0 * x643;
    let x646 = x630 + x634;
    let x647 = q[13] * qd[12];
    let x648 = q[12] * qd[13];
    let x649 = x647 + x648;
    let x650 = 2.0 * x649;
    let x651 = q[11] * qd[10];
    let x652 = q[10] * qd[11];
    let x653 = x651 + x652;
    let x654 = 2.0 * x653;
    let x658 = x640 - x644;
    let x659 = x650 + x654;
    let x660 = x354 * qd[17];
    let x663 = x355 * qd[20];
    let x665 = x660 + x663;
    let x666 = 2.0 * x665;
    let x675 = q[20] * qd[18];
    let x676 = q[18] * qd[20];
    let x677 = x675 + x676;
    let x678 = 2.0 * x677;
    let x679 = q[19] * qd[17];
    let x680 = q[17] * qd[19];
    let x681 = x679 + x680;
    let x682 = 2.0 * x681;
    let x683 = x678 + x682;
    let x685 = q[20] * qd[19];
    let x686 = q[19] * qd[20];
    let x687 = x685 + x686;
    let x688 = 2.0 * x687;
    let x689 = q[18] * qd[17];
    let x690 = q[17] * qd[18];
    let x691 = x689 + x690;
    let x692 = 2.0 * x691;
    let x694 = x688 - x692;
    let x764 = 0.00000000000000005551115123125783 * x622;
    let x765 = 0.9999999999999994 * x636;
    let x766 = x764 + x765;
    let x767 = 0.00000000000000005551115123125783 * x646;
    let x768 = 0.9999999999999994 * x624;
    let x769 = x767 + x768;
    let x770 = 0.00000000000000005551115123125783 * x658;
    let x771 = 0.9999999999999994 * x659;
    let x772 = x770 + x771;
    let x802 = 2.0 * qd[3];
    let x803 = 2.0 * qd[4];
    let x804 = 2.0 * qd[10];
    let x805 = 2.0 * qd[11];
    let x806 = 2.0 * qd[12];
    let x807 = 2.0 * qd[13];
    let x808 = 2.0 * qd[5];
    let x809 = 2.0 * qd[6];
    let x810 = 2.0 * qd[17];
    let x811 = 2.0 * qd[20];
    let x812 = 2.0 * qd[18];
    let x813 = 2.0 * qd[19];
    let x814 = 6.283185307179586 * x554;
    let x816 = 6.283185307179586 * x552;
    let x817 = x552 * x586;
    let x818 = x21 * x814;
    let x820 = x817 - x818;
    let x821 = x554 * x604;
    let x822 = x40 * x816;
    let x823 = x821 + x822;
    let x825 = qd[3] * x802;
    let x826 = qd[4] * x803;
    let x827 = qd[5] * x808;
    let x828 = qd[6] * x809;
    let x829 = x825 + x826;
    let x830 = 2.0 * x829;
    let x831 = qd[4] * qd[5];
    let x832 = x831 + x831;
    let x833 = 2.0 * x832;
    let x834 = qd[3] * qd[6];
    let x835 = x834 + x834;
    let x836 = 2.0 * x835;
    let x837 = qd[4] * qd[6];
    let x838 = x837 + x837;
    let x839 = 2.0 * x838;
    let x840 = qd[3] * qd[5];
    let x841 = x840 + x840;
    let x842 = 2.0 * x841;
    let x843 = x839 + x842;
    let x844 = x833 + x836;
    let x845 = qd[5] * qd[6];
    let x846 = x845 + x845;
    let x847 = 2.0 * x846;
    let x848 = qd[3] * qd[4];
    let x849 = x848 + x848;
    let x850 = 2.0 * x849;
    let x852 = x847 - x850;
    let x854 = x839 - x842;
    let x855 = qd[10] * x804;
    let x856 = qd[11] * x805;
    let x857 = qd[12] * x806;
    let x858 = qd[13] * x807;
    let x859 = x855 + x856;
    let x860 = 2.0 * x859;
    let x861 = x855 + x857;
    let x862 = 2.0 * x861;
    let x863 = x855 + x858;
    let x864 = 2.0 * x863;
    let x865 = qd[11] * qd[12];
    let x866 = x865 + x865;
    let x867 = 2.0 * x866;
    let x868 = qd[10] * qd[13];
    let x869 = x868 + x868;
    let x870 = 2.0 * x869;
    let x872 = x867 - x870;
    let x873 = qd[11] * qd[13];
    let x874 = x873 + x873;
    let x875 = 2.0 * x874;
    let x876 = qd[10] * qd[12];
    let x877 = x876 + x876;
    let x878 = 2.0 * x877;
    let x879 = x875 + x878;
    let x880 = x867 + x870;
    let x881 = qd[12] * qd[13];
    let x882 = x881 + x881;
    let x883 = 2.0 * x882;
    let x884 = qd[10] * qd[11];
    let x885 = x884 + x884;
    let x886 = 2.0 * x885;
    let x888 = x883 - x886;
    let x890 = x875 - x878;
    let x891 = x883 + x886;
    let x892 = qd[17] * x810;
    let x893 = qd[18] * x812;
    let x894 = qd[19] * x813;
    let x895 = qd[20] * x811;
    let x896 = x892 + x893;
    let x897 = x892 + x895;
    let x898 = 2.0 * x897;
    let x899 = qd[18] * qd[19];
    let x900 = x899 + x899;
    let x901 = 2.0 * x900;
    let x902 = qd[17] * qd[20];
    let x903 = x902 + x902;
    let x904 = 2.0 * x903;
    let x905 = qd[18] * qd[20];
    let x906 = x905 + x905;
    let x907 = 2.0 * x906;
    let x908 = qd[17] * qd[19];
    let x909 = x908 + x908;
    let x910 = 2.0 * x909;
    let x911 = x907 + x910;
    let x912 = x901 + x904;
    let x913 = qd[19] * qd[20];
    let x914 = x913 + x913;
    let x915 = 2.0 * x914;
    let x916 = qd[17] * qd[18];
    let x917 = x916 + x916;
    let x918 = 2.0 * x917;
    let x920 = x915 - x918;
    let x922 = x907 - x910;
    let x923 = x915 + x918;
    let x924 = 0.05 * x830;
    let x925 = -x924;
    let x926 = 0.05 * x844;
    let x927 = -x926;
    let x928 = 0.05 * x854;
    let x929 = -x928;
    let x930 = 0.1749999999999999 * x860;
    let x932 = 0.000000000000000003677613769070831 * x872;
    let x933 = 0.000000000000000013877787807814457 * x879;
    let x934 = x932 - x930;
    let x935 = x933 + x934;
    let x936 = 0.1749999999999999 * x880;
    let x938 = 0.000000000000000003677613769070831 * x862;
    let x939 = 0.000000000000000013877787807814457 * x888;
    let x940 = x938 - x936;
    let x941 = x939 + x940;
    let x942 = 0.1749999999999999 * x890;
    let x944 = 0.000000000000000003677613769070831 * x891;
    let x945 = 0.000000000000000013877787807814457 * x864;
    let x946 = x944 - x942;
    let x947 = x945 + x946;
    let x949 = x924 - x935;
    let x951 = x926 - x941;
    let x953 = x928 - x947;
    let x954 = 0.17499999999999993 * x860;
    let x955 = 0.00000000000000001061650767297806 * x872;
    let x957 = 0.000000000000000027755575615628914 * x879;
    let x959 = x954 - x955;
    let x960 = x959 - x957;
    let x961 = 0.17499999999999993 * x880;
    let x962 = 0.00000000000000001061650767297806 * x862;
    let x964 = 0.000000000000000027755575615628914 * x888;
    let x966 = x961 - x962;
    let x967 = x966 - x964;
    let x968 = 0.17499999999999993 * x890;
    let x969 = 0.00000000000000001061650767297806 * x891;
    let x971 = 0.000000000000000027755575615628914 * x864;
    let x973 = x968 - x969;
    let x974 = x973 - x971;
    let x975 = 0.00000000000000005551115123125783 * x860;
    let x976 = 0.9999999999999994 * x872;
    let x977 = x975 + x976;
    let x978 = 0.00000000000000005551115123125783 * x880;
    let x979 = 0.9999999999999994 * x862;
    let x980 = x978 + x979;
    let x981 = 0.00000000000000005551115123125783 * x890;
    let x982 = 0.9999999999999994 * x891;
    let x983 = x981 + x982;
    let x987 = x683 * x766;
    let x988 = x273 * x911;
    let x989 = x987 + x988;
    let x990 = x127 * x977;
    let x991 = x987 + x990;
    let x992 = x989 + x991;
    let x993 = x694 * x769;
    let x994 = x276 * x920;
    let x995 = x993 + x994;
    let x996 = x135 * x980;
    let x997 = x993 + x996;
    let x998 = x995 + x997;
    let x999 = x666 * x772;
    let x1000 = x279 * x898;
    let x1001 = x999 + x1000;
    let x1002 = x115 * x983;
    let x1003 = x999 + x1002;
    let x1004 = x1001 + x1003;
    let x1005 = x992 + x998;
    let x1006 = x1004 + x1005;
    let x1007 = x298 * x830;
    let x1008 = x817 + x1007;
    let x1009 = x820 + x1008;
    let x1011 = x299 * x844;
    let x1012 = x1011 - x821;
    let x1013 = x1012 - x823;
    let x1015 = x1009 - x1013;
    let x1016 = x827 + x829;
    let x1017 = x828 + x1016;
    let x1018 = x857 + x859;
    let x1019 = x858 + x1018;
    let x1020 = x894 + x896;
    let x1021 = x895 + x1020;
    let x1022 = -x843;
    let x1023 = -x852;
    let x1024 = -x949;
    let x1025 = -x951;
    let x1026 = -x953;
    let x1027 = -x1006;
    let x1028 = -x912;
    let x1029 = -x922;
    let x1030 = -x923;
    let x1031 = -x1015;
    let x1032 = -x1017;
    let x1033 = -x1019;
    let x1034 = -x1021;
    out[0] = x925;
    out[1] = x927;
    out[2] = x929;
    out[3] = x1022;
    out[4] = x1023;
    out[5] = x1024;
    out[6] = x1025;
    out[7] = x1026;
    out[8] = x960;
    out[9] = x967;
    out[10] = x974;
    out[11] = x1027;
    out[12] = x1028;
    out[13] = x1029;
    out[14] = 0.0;
    out[15] = 0.0;
    out[16] = x1030;
    out[17] = x1031;
    out[18] = x1032;
    out[19] = x1033;
    out[20] = x1034;
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
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 21] = qd.try_into().expect("qd must have n_coords entries");
    let phi: &mut [f64; 21] = phi.try_into().expect("phi must have 21 entries");
    let phi_q: &mut [f64; 105] = phi_q.try_into().expect("phi_q must have 105 entries");
    let phi_t: &mut [f64; 21] = phi_t.try_into().expect("phi_t must have 21 entries");
    let gamma: &mut [f64; 21] = gamma.try_into().expect("gamma must have 21 entries");
    let mut s = [0.0f64; 60];
    eval_kinematics_shared_0(q, qd, t, &mut s);
    eval_kinematics_part_0(q, qd, &s, phi, phi_q, phi_t, gamma);
    eval_kinematics_part_1(q, qd, &s, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_shared_0(q: &[f64; 21], qd: &[f64; 21], t: f64, s: &mut [f64; 60]) {
    let x5 = 6.283185307179586 * t;
    s[0] = x5;
    let x14 = q[3] * q[3];
    s[1] = x14;
    let x15 = q[4] * q[4];
    s[2] = x15;
    let x18 = x14 + x15;
    s[3] = x18;
    let x19 = 2.0 * x18;
    s[4] = x19;
    let x21 = x19 - 1.0;
    s[5] = x21;
    let x28 = q[4] * q[5];
    s[6] = x28;
    let x29 = 2.0 * x28;
    s[7] = x29;
    let x30 = q[3] * q[6];
    s[8] = x30;
    let x32 = 2.0 * x30;
    s[9] = x32;
    let x40 = x29 + x32;
    s[10] = x40;
    let x59 = q[10] * q[10];
    s[11] = x59;
    let x60 = q[11] * q[11];
    s[12] = x60;
    let x61 = q[12] * q[12];
    s[13] = x61;
    let x62 = q[13] * q[13];
    s[14] = x62;
    let x63 = x59 + x60;
    s[15] = x63;
    let x103 = q[17] * q[17];
    s[16] = x103;
    let x106 = q[20] * q[20];
    s[17] = x106;
    let x298 = x5.sin();
    s[18] = x298;
    let x299 = x5.cos();
    s[19] = x299;
    let x313 = 2.0 * q[3];
    s[20] = x313;
    let x314 = 2.0 * q[4];
    s[21] = x314;
    let x315 = 2.0 * q[10];
    s[22] = x315;
    let x316 = 2.0 * q[11];
    s[23] = x316;
    let x317 = 2.0 * q[12];
    s[24] = x317;
    let x318 = 2.0 * q[13];
    s[25] = x318;
    let x319 = 2.0 * q[5];
    s[26] = x319;
    let x320 = 2.0 * q[6];
    s[27] = x320;
    let x354 = 2.0 * q[17];
    s[28] = x354;
    let x355 = 2.0 * q[20];
    s[29] = x355;
    let x527 = 2.0 * q[18];
    s[30] = x527;
    let x528 = 2.0 * q[19];
    s[31] = x528;
    let x552 = 6.283185307179586 * x299;
    s[32] = x552;
    let x554 = 6.283185307179586 * x298;
    s[33] = x554;
    let x802 = 2.0 * qd[3];
    s[34] = x802;
    let x803 = 2.0 * qd[4];
    s[35] = x803;
    let x804 = 2.0 * qd[10];
    s[36] = x804;
    let x805 = 2.0 * qd[11];
    s[37] = x805;
    let x806 = 2.0 * qd[12];
    s[38] = x806;
    let x807 = 2.0 * qd[13];
    s[39] = x807;
    let x810 = 2.0 * qd[17];
    s[40] = x810;
    let x811 = 2.0 * qd[20];
    s[41] = x811;
    let x825 = qd[3] * x802;
    s[42] = x825;
    let x826 = qd[4] * x803;
    s[43] = x826;
    let x829 = x825 + x826;
    s[44] = x829;
    let x830 = 2.0 * x829;
    s[45] = x830;
    let x831 = qd[4] * qd[5];
    s[46] = x831;
    let x832 = x831 + x831;
    s[47] = x832;
    let x833 = 2.0 * x832;
    s[48] = x833;
    let x834 = qd[3] * qd[6];
    s[49] = x834;
    let x835 = x834 + x834;
    s[50] = x835;
    let x836 = 2.0 * x835;
    s[51] = x836;
    let x844 = x833 + x836;
    s[52] = x844;
    let x855 = qd[10] * x804;
    s[53] = x855;
    let x856 = qd[11] * x805;
    s[54] = x856;
    let x857 = qd[12] * x806;
    s[55] = x857;
    let x858 = qd[13] * x807;
    s[56] = x858;
    let x859 = x855 + x856;
    s[57] = x859;
    let x892 = qd[17] * x810;
    s[58] = x892;
    let x895 = qd[20] * x811;
    s[59] = x895;
}
#[inline(never)]
fn eval_kinematics_part_0(
    q: &[f64; 21],
    qd: &[f64; 21],
    s: &[f64; 60],
    phi: &mut [f64; 21],
    phi_q: &mut [f64; 105],
    phi_t: &mut [f64; 21],
    gamma: &mut [f64; 21],
) {
    let x35 = q[4] * q[6];
    let x36 = 2.0 * x35;
    let x37 = q[3] * q[5];
    let x38 = 2.0 * x37;
    let x39 = x36 + x38;
    let x41 = q[5] * q[6];
    let x42 = 2.0 * x41;
    let x43 = q[3] * q[4];
    let x45 = 2.0 * x43;
    let x47 = x42 - x45;
    let x50 = x36 - x38;
    let x64 = 2.0 * s[15];
    let x65 = x64 - 1.0;
    let x66 = s[11] + s[13];
    let x67 = 2.0 * x66;
    let x68 = x67 - 1.0;
    let x69 = s[11] + s[14];
    let x70 = 2.0 * x69;
    let x71 = x70 - 1.0;
    let x72 = q[11] * q[12];
    let x73 = 2.0 * x72;
    let x74 = q[10] * q[13];
    let x76 = 2.0 * x74;
    let x78 = x73 - x76;
    let x79 = q[11] * q[13];
    let x80 = 2.0 * x79;
    let x81 = q[10] * q[12];
    let x82 = 2.0 * x81;
    let x83 = x80 + x82;
    let x84 = x73 + x76;
    let x85 = q[12] * q[13];
    let x86 = 2.0 * x85;
    let x87 = q[10] * q[11];
    let x89 = 2.0 * x87;
    let x91 = x86 - x89;
    let x94 = x80 - x82;
    let x95 = x86 + x89;
    let x113 = s[16] + s[17];
    let x114 = 2.0 * x113;
    let x115 = x114 - 1.0;
    let x116 = q[18] * q[19];
    let x117 = 2.0 * x116;
    let x118 = q[17] * q[20];
    let x120 = 2.0 * x118;
    let x123 = q[18] * q[20];
    let x124 = 2.0 * x123;
    let x125 = q[17] * q[19];
    let x126 = 2.0 * x125;
    let x127 = x124 + x126;
    let x128 = x117 + x120;
    let x129 = q[19] * q[20];
    let x130 = 2.0 * x129;
    let x131 = q[17] * q[18];
    let x133 = 2.0 * x131;
    let x135 = x130 - x133;
    let x138 = x124 - x126;
    let x139 = x130 + x133;
    let x142 = s[5] * 0.05;
    let x144 = s[10] * 0.05;
    let x146 = x50 * 0.05;
    let x148 = q[0] - x142;
    let x149 = q[1] - x144;
    let x150 = q[2] - x146;
    let x151 = -x148;
    let x152 = -x149;
    let x153 = -x150;
    let x154 = q[0] + x142;
    let x155 = q[1] + x144;
    let x156 = q[2] + x146;
    let x161 = x65 * 0.1749999999999999;
    let x163 = x78 * 0.000000000000000003677613769070831;
    let x164 = x83 * 0.000000000000000013877787807814457;
    let x165 = x163 - x161;
    let x166 = x164 + x165;
    let x167 = x84 * 0.1749999999999999;
    let x169 = x68 * 0.000000000000000003677613769070831;
    let x170 = x91 * 0.000000000000000013877787807814457;
    let x171 = x169 - x167;
    let x172 = x170 + x171;
    let x173 = x94 * 0.1749999999999999;
    let x175 = x95 * 0.000000000000000003677613769070831;
    let x176 = x71 * 0.000000000000000013877787807814457;
    let x177 = x175 - x173;
    let x178 = x176 + x177;
    let x179 = q[7] + x166;
    let x180 = q[8] + x172;
    let x181 = q[9] + x178;
    let x183 = x154 - x179;
    let x185 = x155 - x180;
    let x187 = x156 - x181;
    let x191 = x65 * 0.17499999999999993;
    let x193 = x78 * 0.00000000000000001061650767297806;
    let x196 = x83 * 0.000000000000000027755575615628914;
    let x198 = x191 - x193;
    let x199 = x198 - x196;
    let x200 = x84 * 0.17499999999999993;
    let x201 = x68 * 0.00000000000000001061650767297806;
    let x203 = x91 * 0.000000000000000027755575615628914;
    let x205 = x200 - x201;
    let x206 = x205 - x203;
    let x207 = x94 * 0.17499999999999993;
    let x208 = x95 * 0.00000000000000001061650767297806;
    let x210 = x71 * 0.000000000000000027755575615628914;
    let x212 = x207 - x208;
    let x213 = x212 - x210;
    let x214 = q[7] + x199;
    let x215 = q[8] + x206;
    let x216 = q[9] + x213;
    let x271 = x65 * 0.00000000000000005551115123125783;
    let x272 = x78 * 0.9999999999999994;
    let x273 = x271 + x272;
    let x274 = x84 * 0.00000000000000005551115123125783;
    let x275 = x68 * 0.9999999999999994;
    let x276 = x274 + x275;
    let x277 = x94 * 0.00000000000000005551115123125783;
    let x278 = x95 * 0.9999999999999994;
    let x279 = x277 + x278;
    let x281 = q[14] - x214;
    let x283 = q[15] - x215;
    let x285 = q[16] - x216;
    let x286 = x127 * x273;
    let x287 = x135 * x276;
    let x288 = x115 * x279;
    let x289 = x286 + x287;
    let x290 = x288 + x289;
    let x295 = q[15] - 0.05;
    let x297 = q[16] - 0.12;
    let x300 = s[5] * s[18];
    let x301 = s[10] * s[19];
    let x303 = x300 - x301;
    let x321 = 2.0 * s[20];
    let x322 = -s[21];
    let x324 = 0.05 * x321;
    let x326 = 0.05 * s[27];
    let x328 = 0.05 * s[26];
    let x329 = -x328;
    let x330 = s[18] * x321;
    let x331 = s[19] * s[27];
    let x333 = x330 - x331;
    let x334 = 2.0 * s[21];
    let x335 = -s[20];
    let x336 = 0.05 * x334;
    let x338 = s[18] * x334;
    let x339 = s[19] * s[26];
    let x341 = x338 - x339;
    let x342 = 0.05 * s[21];
    let x344 = 0.05 * s[20];
    let x345 = -x344;
    let x346 = s[19] * s[21];
    let x347 = -x346;
    let x348 = s[19] * s[20];
    let x349 = -x348;
    let x350 = 2.0 * s[22];
    let x356 = 0.1749999999999999 * x350;
    let x358 = 0.000000000000000003677613769070831 * s[25];
    let x360 = 0.000000000000000013877787807814457 * s[24];
    let x361 = x356 + x358;
    let x363 = x360 - x361;
    let x364 = 0.1749999999999999 * s[25];
    let x366 = 0.000000000000000003677613769070831 * x350;
    let x367 = 0.000000000000000013877787807814457 * s[23];
    let x369 = x366 - x364;
    let x370 = x369 - x367;
    let x371 = 0.1749999999999999 * s[24];
    let x373 = 0.000000000000000003677613769070831 * s[23];
    let x374 = 0.000000000000000013877787807814457 * x350;
    let x375 = x371 + x373;
    let x376 = x374 + x375;
    let x377 = -x363;
    let x378 = -x370;
    let x379 = -x376;
    let x380 = 0.17499999999999993 * x350;
    let x381 = 0.00000000000000001061650767297806 * s[25];
    let x383 = 0.000000000000000027755575615628914 * s[24];
    let x385 = x380 + x381;
    let x386 = x385 - x383;
    let x387 = 0.17499999999999993 * s[25];
    let x388 = 0.00000000000000001061650767297806 * x350;
    let x390 = 0.000000000000000027755575615628914 * s[23];
    let x392 = x387 - x388;
    let x393 = x390 + x392;
    let x394 = 0.17499999999999993 * s[24];
    let x396 = 0.00000000000000001061650767297806 * s[23];
    let x398 = 0.000000000000000027755575615628914 * x350;
    let x400 = x394 + x396;
    let x402 = x398 + x400;
    let x404 = 0.00000000000000005551115123125783 * x350;
    let x405 = 0.9999999999999994 * s[25];
    let x407 = x404 - x405;
    let x408 = 0.00000000000000005551115123125783 * s[25];
    let x409 = 0.9999999999999994 * x350;
    let x410 = x408 + x409;
    let x411 = 0.00000000000000005551115123125783 * s[24];
    let x413 = 0.9999999999999994 * s[23];
    let x414 = x413 - x411;
    let x415 = -x386;
    let x416 = -x393;
    let x417 = x127 * x407;
    let x418 = x135 * x410;
    let x419 = x115 * x414;
    let x420 = x417 + x418;
    let x421 = x419 + x420;
    let x422 = 2.0 * s[23];
    let x424 = 0.1749999999999999 * x422;
    let x426 = 0.000000000000000003677613769070831 * s[24];
    let x427 = 0.000000000000000013877787807814457 * s[25];
    let x428 = x426 - x424;
    let x429 = x427 + x428;
    let x430 = 0.000000000000000013877787807814457 * s[22];
    let x432 = x371 + x430;
    let x434 = 0.000000000000000003677613769070831 * s[22];
    let x435 = x434 - x364;
    let x436 = -x429;
    let x437 = -x435;
    let x438 = 0.17499999999999993 * x422;
    let x439 = 0.00000000000000001061650767297806 * s[24];
    let x441 = 0.000000000000000027755575615628914 * s[25];
    let x443 = x438 - x439;
    let x444 = x443 - x441;
    let x445 = 0.000000000000000027755575615628914 * s[22];
    let x447 = x394 + x445;
    let x448 = 0.00000000000000001061650767297806 * s[22];
    let x450 = x387 - x448;
    let x451 = 0.00000000000000005551115123125783 * x422;
    let x452 = 0.9999999999999994 * s[24];
    let x453 = x451 + x452;
    let x454 = 0.9999999999999994 * s[22];
    let x455 = x408 + x454;
    let x456 = -x444;
    let x457 = -x447;
    let x458 = -x450;
    let x459 = x127 * x453;
    let x460 = x135 * x411;
    let x461 = x115 * x455;
    let x462 = x459 + x460;
    let x463 = x461 + x462;
    let x464 = 2.0 * s[24];
    let x465 = x373 + x430;
    let x466 = 0.1749999999999999 * s[23];
    let x468 = 0.000000000000000003677613769070831 * x464;
    let x469 = x468 - x466;
    let x470 = x427 + x469;
    let x471 = 0.1749999999999999 * s[22];
    let x473 = x358 + x471;
    let x474 = -x465;
    let x475 = -x470;
    let x476 = -x473;
    let x477 = x396 + x445;
    let x479 = 0.17499999999999993 * s[23];
    let x480 = 0.00000000000000001061650767297806 * x464;
    let x482 = x479 - x480;
    let x483 = x482 - x441;
    let x484 = 0.17499999999999993 * s[22];
    let x486 = x381 + x484;
    let x488 = 0.00000000000000005551115123125783 * s[23];
    let x489 = 0.9999999999999994 * x464;
    let x490 = x488 + x489;
    let x491 = 0.00000000000000005551115123125783 * s[22];
    let x493 = x405 - x491;
    let x494 = -x483;
    let x495 = x127 * x413;
    let x496 = x135 * x490;
    let x497 = x115 * x493;
    let x498 = x495 + x496;
    let x499 = x497 + x498;
    let x500 = 2.0 * s[25];
    let x502 = x367 - x434;
    let x503 = x360 - x471;
    let x504 = 0.000000000000000013877787807814457 * x500;
    let x505 = x426 - x466;
    let x506 = x504 + x505;
    let x507 = -x502;
    let x508 = -x503;
    let x509 = -x506;
    let x510 = x448 - x390;
    let x511 = x484 - x383;
    let x512 = 0.000000000000000027755575615628914 * x500;
    let x514 = x479 - x439;
    let x515 = x514 - x512;
    let x517 = x452 + x488;
    let x518 = -x510;
    let x519 = -x511;
    let x520 = -x515;
    let x521 = x127 * x454;
    let x523 = x135 * x491;
    let x524 = x115 * x517;
    let x525 = x523 - x521;
    let x526 = x524 + x525;
    let x529 = 2.0 * s[28];
    let x531 = -s[31];
    let x532 = x273 * s[31];
    let x533 = x276 * s[30];
    let x535 = x279 * x529;
    let x536 = x532 - x533;
    let x537 = x535 + x536;
    let x538 = -s[28];
    let x539 = x273 * s[29];
    let x540 = x276 * s[28];
    let x542 = x539 - x540;
    let x543 = x273 * s[28];
    let x544 = x276 * s[29];
    let x545 = x543 + x544;
    let x546 = 2.0 * s[29];
    let x547 = x273 * s[30];
    let x548 = x276 * s[31];
    let x549 = x279 * x546;
    let x550 = x547 + x548;
    let x551 = x549 + x550;
    let x556 = s[5] * s[32];
    let x557 = s[10] * s[33];
    let x559 = x556 + x557;
    let x617 = s[22] * qd[10];
    let x618 = s[23] * qd[11];
    let x619 = s[24] * qd[12];
    let x621 = x617 + x618;
    let x622 = 2.0 * x621;
    let x623 = x617 + x619;
    let x624 = 2.0 * x623;
    let x627 = q[12] * qd[11];
    let x628 = q[11] * qd[12];
    let x629 = x627 + x628;
    let x630 = 2.0 * x629;
    let x631 = q[13] * qd[10];
    let x632 = q[10] * qd[13];
    let x633 = x631 + x632;
    let x634 = 2.0 * x633;
    let x636 = x630 - x634;
    let x637 = q[13] * qd[11];
    let x638 = q[11] * qd[13];
    let x639 = x637 + x638;
    let x640 = 2.0 * x639;
    let x641 = q[12] * qd[10];
    let x642 = q[10] * qd[12];
    let x643 = x641 + x642;
    let x644 = 2.0 * x643;
    let x646 = x630 + x634;
    let x647 = q[13] * qd[12];
    let x648 = q[12] * qd[13];
    let x649 = x647 + x648;
    let x650 = 2.0 * x649;
    let x651 = q[11] * qd[10];
    let x652 = q[10] * qd[11];
    let x653 = x651 + x652;
    let x654 = 2.0 * x653;
    let x658 = x640 - x644;
    let x659 = x650 + x654;
    let x660 = s[28] * qd[17];
    let x663 = s[29] * qd[20];
    let x665 = x660 + x663;
    let x666 = 2.0 * x665;
    let x675 = q[20] * qd[18];
    let x676 = q[18] * qd[20];
    let x677 = x675 + x676;
    let x678 = 2.0 * x677;
    let x679 = q[19] * qd[17];
    let x680 = q[17] * qd[19];
    let x681 = x679 + x680;
    let x682 = 2.0 * x681;
    let x683 = x678 + x682;
    let x685 = q[20] * qd[19];
    let x686 = q[19] * qd[20];
    let x687 = x685 + x686;
    let x688 = 2.0 * x687;
    let x689 = q[18] * qd[17];
    let x690 = q[17] * qd[18];
    let x691 = x689 + x690;
    let x692 = 2.0 * x691;
    let x694 = x688 - x692;
    let x764 = 0.00000000000000005551115123125783 * x622;
    let x765 = 0.9999999999999994 * x636;
    let x766 = x764 + x765;
    let x767 = 0.00000000000000005551115123125783 * x646;
    let x768 = 0.9999999999999994 * x624;
    let x769 = x767 + x768;
    let x770 = 0.00000000000000005551115123125783 * x658;
    let x771 = 0.9999999999999994 * x659;
    let x772 = x770 + x771;
    let x837 = qd[4] * qd[6];
    let x838 = x837 + x837;
    let x839 = 2.0 * x838;
    let x840 = qd[3] * qd[5];
    let x841 = x840 + x840;
    let x842 = 2.0 * x841;
    let x843 = x839 + x842;
    let x845 = qd[5] * qd[6];
    let x846 = x845 + x845;
    let x847 = 2.0 * x846;
    let x848 = qd[3] * qd[4];
    let x849 = x848 + x848;
    let x850 = 2.0 * x849;
    let x852 = x847 - x850;
    let x854 = x839 - x842;
    let x860 = 2.0 * s[57];
    let x861 = s[53] + s[55];
    let x862 = 2.0 * x861;
    let x863 = s[53] + s[56];
    let x864 = 2.0 * x863;
    let x865 = qd[11] * qd[12];
    let x866 = x865 + x865;
    let x867 = 2.0 * x866;
    let x868 = qd[10] * qd[13];
    let x869 = x868 + x868;
    let x870 = 2.0 * x869;
    let x872 = x867 - x870;
    let x873 = qd[11] * qd[13];
    let x874 = x873 + x873;
    let x875 = 2.0 * x874;
    let x876 = qd[10] * qd[12];
    let x877 = x876 + x876;
    let x878 = 2.0 * x877;
    let x879 = x875 + x878;
    let x880 = x867 + x870;
    let x881 = qd[12] * qd[13];
    let x882 = x881 + x881;
    let x883 = 2.0 * x882;
    let x884 = qd[10] * qd[11];
    let x885 = x884 + x884;
    let x886 = 2.0 * x885;
    let x888 = x883 - x886;
    let x890 = x875 - x878;
    let x891 = x883 + x886;
    let x897 = s[58] + s[59];
    let x898 = 2.0 * x897;
    let x899 = qd[18] * qd[19];
    let x900 = x899 + x899;
    let x901 = 2.0 * x900;
    let x902 = qd[17] * qd[20];
    let x903 = x902 + x902;
    let x904 = 2.0 * x903;
    let x905 = qd[18] * qd[20];
    let x906 = x905 + x905;
    let x907 = 2.0 * x906;
    let x908 = qd[17] * qd[19];
    let x909 = x908 + x908;
    let x910 = 2.0 * x909;
    let x911 = x907 + x910;
    let x912 = x901 + x904;
    let x913 = qd[19] * qd[20];
    let x914 = x913 + x913;
    let x915 = 2.0 * x914;
    let x916 = qd[17] * qd[18];
    let x917 = x916 + x916;
    let x918 = 2.0 * x917;
    let x920 = x915 - x918;
    let x922 = x907 - x910;
    let x923 = x915 + x918;
    let x924 = 0.05 * s[45];
    let x925 = -x924;
    let x926 = 0.05 * s[52];
    let x927 = -x926;
    let x928 = 0.05 * x854;
    let x929 = -x928;
    let x930 = 0.1749999999999999 * x860;
    let x932 = 0.000000000000000003677613769070831 * x872;
    let x933 = 0.000000000000000013877787807814457 * x879;
    let x934 = x932 - x930;
    let x935 = x933 + x934;
    let x936 = 0.1749999999999999 * x880;
    let x938 = 0.000000000000000003677613769070831 * x862;
    let x939 = 0.000000000000000013877787807814457 * x888;
    let x940 = x938 - x936;
    let x941 = x939 + x940;
    let x942 = 0.1749999999999999 * x890;
    let x944 = 0.000000000000000003677613769070831 * x891;
    let x945 = 0.000000000000000013877787807814457 * x864;
    let x946 = x944 - x942;
    let x947 = x945 + x946;
    let x949 = x924 - x935;
    let x951 = x926 - x941;
    let x953 = x928 - x947;
    let x954 = 0.17499999999999993 * x860;
    let x955 = 0.00000000000000001061650767297806 * x872;
    let x957 = 0.000000000000000027755575615628914 * x879;
    let x959 = x954 - x955;
    let x960 = x959 - x957;
    let x961 = 0.17499999999999993 * x880;
    let x962 = 0.00000000000000001061650767297806 * x862;
    let x964 = 0.000000000000000027755575615628914 * x888;
    let x966 = x961 - x962;
    let x967 = x966 - x964;
    let x968 = 0.17499999999999993 * x890;
    let x969 = 0.00000000000000001061650767297806 * x891;
    let x971 = 0.000000000000000027755575615628914 * x864;
    let x973 = x968 - x969;
    let x974 = x973 - x971;
    let x975 = 0.00000000000000005551115123125783 * x860;
    let x976 = 0.9999999999999994 * x872;
    let x977 = x975 + x976;
    let x978 = 0.00000000000000005551115123125783 * x880;
    let x979 = 0.9999999999999994 * x862;
    let x980 = x978 + x979;
    let x981 = 0.00000000000000005551115123125783 * x890;
    let x982 = 0.9999999999999994 * x891;
    let x983 = x981 + x982;
    let x987 = x683 * x766;
    let x988 = x273 * x911;
    let x989 = x987 + x988;
    let x990 = x127 * x977;
    let x991 = x987 + x990;
    let x992 = x989 + x991;
    let x993 = x694 * x769;
    let x994 = x276 * x920;
    let x995 = x993 + x994;
    let x996 = x135 * x980;
    let x997 = x993 + x996;
    let x998 = x995 + x997;
    let x999 = x666 * x772;
    let x1000 = x279 * x898;
    let x1001 = x999 + x1000;
    let x1002 = x115 * x983;
    let x1003 = x999 + x1002;
    let x1004 = x1001 + x1003;
    let x1005 = x992 + x998;
    let x1006 = x1004 + x1005;
    let x1022 = -x843;
    let x1023 = -x852;
    let x1024 = -x949;
    let x1025 = -x951;
    let x1026 = -x953;
    let x1027 = -x1006;
    let x1028 = -x912;
    let x1029 = -x922;
    let x1030 = -x923;
    phi[0] = x151;
    phi_q[0] = -1.0;
    phi_q[1] = x324;
    phi_q[2] = x336;
    phi_t[0] = 0.0;
    gamma[0] = x925;
    phi[1] = x152;
    phi_q[3] = -1.0;
    phi_q[4] = x326;
    phi_q[5] = x328;
    phi_q[6] = x342;
    phi_q[7] = x344;
    phi_t[1] = 0.0;
    gamma[1] = x927;
    phi[2] = x153;
    phi_q[8] = -1.0;
    phi_q[9] = x329;
    phi_q[10] = x326;
    phi_q[11] = x345;
    phi_q[12] = x342;
    phi_t[2] = 0.0;
    gamma[2] = x929;
    phi[3] = x39;
    phi_q[13] = s[26];
    phi_q[14] = s[27];
    phi_q[15] = s[20];
    phi_q[16] = s[21];
    phi_t[3] = 0.0;
    gamma[3] = x1022;
    phi[4] = x47;
    phi_q[17] = x322;
    phi_q[18] = x335;
    phi_q[19] = s[27];
    phi_q[20] = s[26];
    phi_t[4] = 0.0;
    gamma[4] = x1023;
    phi[5] = x183;
    phi_q[21] = 1.0;
    phi_q[22] = x324;
    phi_q[23] = x336;
    phi_q[24] = -1.0;
    phi_q[25] = x377;
    phi_q[26] = x436;
    phi_q[27] = x474;
    phi_q[28] = x507;
    phi_t[5] = 0.0;
    gamma[5] = x1024;
    phi[6] = x185;
    phi_q[29] = 1.0;
    phi_q[30] = x326;
    phi_q[31] = x328;
    phi_q[32] = x342;
    phi_q[33] = x344;
    phi_q[34] = -1.0;
    phi_q[35] = x378;
    phi_q[36] = x432;
    phi_q[37] = x475;
    phi_q[38] = x508;
    phi_t[6] = 0.0;
    gamma[6] = x1025;
    phi[7] = x187;
    phi_q[39] = 1.0;
    phi_q[40] = x329;
    phi_q[41] = x326;
    phi_q[42] = x345;
    phi_q[43] = x342;
    phi_q[44] = -1.0;
    phi_q[45] = x379;
    phi_q[46] = x437;
    phi_q[47] = x476;
    phi_q[48] = x509;
    phi_t[7] = 0.0;
    gamma[7] = x1026;
    phi[8] = x281;
    phi_q[49] = -1.0;
    phi_q[50] = x415;
    phi_q[51] = x456;
    phi_q[52] = x477;
    phi_q[53] = x518;
    phi_q[54] = 1.0;
    phi_t[8] = 0.0;
    gamma[8] = x960;
    phi[9] = x283;
    phi_q[55] = -1.0;
    phi_q[56] = x416;
    phi_q[57] = x457;
    phi_q[58] = x494;
    phi_q[59] = x519;
    phi_q[60] = 1.0;
    phi_t[9] = 0.0;
    gamma[9] = x967;
    phi[10] = x285;
    phi_q[61] = -1.0;
    phi_q[62] = x402;
    phi_q[63] = x458;
    phi_q[64] = x486;
    phi_q[65] = x520;
    phi_q[66] = 1.0;
    phi_t[10] = 0.0;
    gamma[10] = x974;
    phi[11] = x290;
    phi_q[67] = x421;
    phi_q[68] = x463;
    phi_q[69] = x499;
    phi_q[70] = x526;
    phi_q[71] = x537;
    phi_q[72] = x542;
    phi_q[73] = x545;
    phi_q[74] = x551;
    phi_t[11] = 0.0;
    gamma[11] = x1027;
    phi[12] = x128;
    phi_q[75] = s[29];
    phi_q[76] = s[31];
    phi_q[77] = s[30];
    phi_q[78] = s[28];
    phi_t[12] = 0.0;
    gamma[12] = x1028;
    phi[13] = x138;
    phi_q[79] = x531;
    phi_q[80] = s[29];
    phi_q[81] = x538;
    phi_q[82] = s[30];
    phi_t[13] = 0.0;
    gamma[13] = x1029;
    phi[14] = x295;
    phi_q[83] = 1.0;
    phi_t[14] = 0.0;
    gamma[14] = 0.0;
    phi[15] = x297;
    phi_q[84] = 1.0;
    phi_t[15] = 0.0;
    gamma[15] = 0.0;
    phi[16] = x139;
    phi_q[85] = s[30];
    phi_q[86] = s[28];
    phi_q[87] = s[29];
    phi_q[88] = s[31];
    phi_t[16] = 0.0;
    gamma[16] = x1030;
    phi[17] = x303;
    phi_q[89] = x333;
    phi_q[90] = x341;
    phi_q[91] = x347;
    phi_q[92] = x349;
    phi_t[17] = x559;
}
#[inline(never)]
fn eval_kinematics_part_1(
    q: &[f64; 21],
    qd: &[f64; 21],
    s: &[f64; 60],
    phi: &mut [f64; 21],
    phi_q: &mut [f64; 105],
    phi_t: &mut [f64; 21],
    gamma: &mut [f64; 21],
) {
    let x16 = q[5] * q[5];
    let x17 = q[6] * q[6];
    let x104 = q[18] * q[18];
    let x105 = q[19] * q[19];
    let x107 = s[16] + x104;
    let x304 = x16 + s[3];
    let x305 = x17 + x304;
    let x306 = x305 - 1.0;
    let x307 = s[13] + s[15];
    let x308 = s[14] + x307;
    let x309 = x308 - 1.0;
    let x310 = x105 + x107;
    let x311 = s[17] + x310;
    let x312 = x311 - 1.0;
    let x581 = s[20] * qd[3];
    let x582 = s[21] * qd[4];
    let x585 = x581 + x582;
    let x586 = 2.0 * x585;
    let x587 = q[5] * qd[4];
    let x588 = q[4] * qd[5];
    let x589 = x587 + x588;
    let x590 = 2.0 * x589;
    let x591 = q[6] * qd[3];
    let x592 = q[3] * qd[6];
    let x593 = x591 + x592;
    let x594 = 2.0 * x593;
    let x604 = x590 + x594;
    let x808 = 2.0 * qd[5];
    let x809 = 2.0 * qd[6];
    let x812 = 2.0 * qd[18];
    let x813 = 2.0 * qd[19];
    let x814 = 6.283185307179586 * s[33];
    let x816 = 6.283185307179586 * s[32];
    let x817 = s[32] * x586;
    let x818 = s[5] * x814;
    let x820 = x817 - x818;
    let x821 = s[33] * x604;
    let x822 = s[10] * x816;
    let x823 = x821 + x822;
    let x827 = qd[5] * x808;
    let x828 = qd[6] * x809;
    let x893 = qd[18] * x812;
    let x894 = qd[19] * x813;
    let x896 = s[58] + x893;
    let x1007 = s[18] * s[45];
    let x1008 = x817 + x1007;
    let x1009 = x820 + x1008;
    let x1011 = s[19] * s[52];
    let x1012 = x1011 - x821;
    let x1013 = x1012 - x823;
    let x1015 = x1009 - x1013;
    let x1016 = x827 + s[44];
    let x1017 = x828 + x1016;
    let x1018 = s[55] + s[57];
    let x1019 = s[56] + x1018;
    let x1020 = x894 + x896;
    let x1021 = s[59] + x1020;
    let x1031 = -x1015;
    let x1032 = -x1017;
    let x1033 = -x1019;
    let x1034 = -x1021;
    gamma[17] = x1031;
    phi[18] = x306;
    phi_q[93] = s[20];
    phi_q[94] = s[21];
    phi_q[95] = s[26];
    phi_q[96] = s[27];
    phi_t[18] = 0.0;
    gamma[18] = x1032;
    phi[19] = x309;
    phi_q[97] = s[22];
    phi_q[98] = s[23];
    phi_q[99] = s[24];
    phi_q[100] = s[25];
    phi_t[19] = 0.0;
    gamma[19] = x1033;
    phi[20] = x312;
    phi_q[101] = s[28];
    phi_q[102] = s[30];
    phi_q[103] = s[31];
    phi_q[104] = s[29];
    phi_t[20] = 0.0;
    gamma[20] = x1034;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(q: &[f64], out: &mut [f64]) {
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    potential_into_part_0(q, out);
}
#[inline(never)]
fn potential_into_part_0(q: &[f64; 21], out: &mut [f64; 1]) {
    let x1036 = q[1] * 2.943;
    let x1038 = q[8] * 5.886;
    let x1040 = q[15] * 9.81;
    let x1041 = x1036 + x1038;
    let x1042 = x1040 + x1041;
    out[0] = x1042;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 21] = qd.try_into().expect("qd must have n_coords entries");
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
pub const N_COORDS: usize = 21usize;
/// Number of constraint rows.
pub const N_CONSTRAINTS: usize = 21usize;
/// Row of each Φq nonzero.
pub static PHI_Q_ROWS: [u32; 105usize] = [
    0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 1u32, 1u32, 2u32, 2u32, 2u32, 2u32, 2u32, 3u32,
    3u32, 3u32, 3u32, 4u32, 4u32, 4u32, 4u32, 5u32, 5u32, 5u32, 5u32, 5u32, 5u32, 5u32,
    5u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32, 7u32, 7u32, 7u32,
    7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 8u32, 8u32, 8u32, 8u32, 8u32, 8u32, 9u32,
    9u32, 9u32, 9u32, 9u32, 9u32, 10u32, 10u32, 10u32, 10u32, 10u32, 10u32, 11u32, 11u32,
    11u32, 11u32, 11u32, 11u32, 11u32, 11u32, 12u32, 12u32, 12u32, 12u32, 13u32, 13u32,
    13u32, 13u32, 14u32, 15u32, 16u32, 16u32, 16u32, 16u32, 17u32, 17u32, 17u32, 17u32,
    18u32, 18u32, 18u32, 18u32, 19u32, 19u32, 19u32, 19u32, 20u32, 20u32, 20u32, 20u32,
];
/// Column of each Φq nonzero.
pub static PHI_Q_COLS: [u32; 105usize] = [
    0u32, 3u32, 4u32, 1u32, 3u32, 4u32, 5u32, 6u32, 2u32, 3u32, 4u32, 5u32, 6u32, 3u32,
    4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 0u32, 3u32, 4u32, 7u32, 10u32, 11u32,
    12u32, 13u32, 1u32, 3u32, 4u32, 5u32, 6u32, 8u32, 10u32, 11u32, 12u32, 13u32, 2u32,
    3u32, 4u32, 5u32, 6u32, 9u32, 10u32, 11u32, 12u32, 13u32, 7u32, 10u32, 11u32, 12u32,
    13u32, 14u32, 8u32, 10u32, 11u32, 12u32, 13u32, 15u32, 9u32, 10u32, 11u32, 12u32,
    13u32, 16u32, 10u32, 11u32, 12u32, 13u32, 17u32, 18u32, 19u32, 20u32, 17u32, 18u32,
    19u32, 20u32, 17u32, 18u32, 19u32, 20u32, 15u32, 16u32, 17u32, 18u32, 19u32, 20u32,
    3u32, 4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 10u32, 11u32, 12u32, 13u32, 17u32,
    18u32, 19u32, 20u32,
];
/// Bodies in coordinate order.
pub static BODIES: [BodyInfo; 3usize] = [
    BodyInfo {
        name: "crank",
        coord_offset: 0usize,
        rotation: Rotation::Quaternion,
        mass: 0.3f64,
        inertia: [0.0001f64, 0.00025f64, 0.00025f64],
    },
    BodyInfo {
        name: "rod",
        coord_offset: 7usize,
        rotation: Rotation::Quaternion,
        mass: 0.6f64,
        inertia: [0.0001f64, 0.006124999999999999f64, 0.006124999999999999f64],
    },
    BodyInfo {
        name: "slider",
        coord_offset: 14usize,
        rotation: Rotation::Quaternion,
        mass: 1f64,
        inertia: [0.001f64, 0.001f64, 0.001f64],
    },
];
/// Joints in row order, then drivers.
pub static JOINTS: [JointInfo; 8usize] = [
    JointInfo {
        name: "crank_pivot",
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
        name: "crank_pin",
        kind: JointKind::Spherical,
        body1: Some(0usize),
        body2: Some(1usize),
        row_start: 5usize,
        rows: 3usize,
        point1: [0.05f64, 0f64, 0f64],
        point2: [
            -0.1749999999999999f64,
            0.000000000000000003677613769070831f64,
            0.000000000000000013877787807814457f64,
        ],
        effort_sign: 0f64,
        effort_unit: "",
    },
    JointInfo {
        name: "slider_pin",
        kind: JointKind::Universal,
        body1: Some(2usize),
        body2: Some(1usize),
        row_start: 8usize,
        rows: 4usize,
        point1: [0f64, 0f64, 0f64],
        point2: [
            0.17499999999999993f64,
            -0.00000000000000001061650767297806f64,
            -0.000000000000000027755575615628914f64,
        ],
        effort_sign: 0f64,
        effort_unit: "",
    },
    JointInfo {
        name: "guide",
        kind: JointKind::Prismatic,
        body1: None,
        body2: Some(2usize),
        row_start: 12usize,
        rows: 5usize,
        point1: [0.4249615361854384f64, 0.05f64, 0.12f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
    JointInfo {
        name: "motor",
        kind: JointKind::Driver,
        body1: None,
        body2: Some(0usize),
        row_start: 17usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [-0.05f64, 0f64, 0f64],
        effort_sign: -1f64,
        effort_unit: "N·m",
    },
    JointInfo {
        name: "crank.norm",
        kind: JointKind::Normalization,
        body1: Some(0usize),
        body2: None,
        row_start: 18usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
    JointInfo {
        name: "rod.norm",
        kind: JointKind::Normalization,
        body1: Some(1usize),
        body2: None,
        row_start: 19usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
    JointInfo {
        name: "slider.norm",
        kind: JointKind::Normalization,
        body1: Some(2usize),
        body2: None,
        row_start: 20usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
];
/// Name of each coordinate.
pub static COORD_NAMES: [&str; 21usize] = [
    "crank.x",
    "crank.y",
    "crank.z",
    "crank.e0",
    "crank.e1",
    "crank.e2",
    "crank.e3",
    "rod.x",
    "rod.y",
    "rod.z",
    "rod.e0",
    "rod.e1",
    "rod.e2",
    "rod.e3",
    "slider.x",
    "slider.y",
    "slider.z",
    "slider.e0",
    "slider.e1",
    "slider.e2",
    "slider.e3",
];
/// Name of each constraint row.
pub static ROW_NAMES: [&str; 21usize] = [
    "crank_pivot.x",
    "crank_pivot.y",
    "crank_pivot.z",
    "crank_pivot.dot1(x1,z2)",
    "crank_pivot.dot1(y1,z2)",
    "crank_pin.x",
    "crank_pin.y",
    "crank_pin.z",
    "slider_pin.x",
    "slider_pin.y",
    "slider_pin.z",
    "slider_pin.dot1(z1,z2)",
    "guide.dot1(x1,z2)",
    "guide.dot1(y1,z2)",
    "guide.dot2(x1,d)",
    "guide.dot2(y1,d)",
    "guide.dot1(y1,x2)",
    "motor",
    "crank.norm",
    "rod.norm",
    "slider.norm",
];
/// Initial coordinates: the file's pose, assembled.
pub static Q0: [f64; 21usize] = [
    0.05f64,
    0f64,
    0f64,
    1f64,
    0f64,
    0f64,
    0f64,
    0.2624807680927192f64,
    0.025f64,
    0.06f64,
    0.9818627806529433f64,
    0.013275765426813475f64,
    -0.17357988437258765f64,
    0.07509499159066049f64,
    0.4249615361854384f64,
    0.05f64,
    0.12f64,
    1f64,
    0f64,
    0f64,
    0f64,
];
/// Initial velocities from the file (to be projected onto the constraints).
pub static QD0: [f64; 21usize] = [
    0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64,
    0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64,
];
/// Constraint rows dependent on others at the initial pose (dropped by the solvers).
pub static REDUNDANT_ROWS: [u32; 0usize] = [];
/// Simulation end time suggested by the mechanism file (s).
pub const T_END: f64 = 2f64;
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
    pub static MASS_ROWS: [u32; 57usize] = [
        0u32, 1u32, 2u32, 3u32, 3u32, 3u32, 3u32, 4u32, 4u32, 4u32, 4u32, 5u32, 5u32,
        5u32, 5u32, 6u32, 6u32, 6u32, 6u32, 7u32, 8u32, 9u32, 10u32, 10u32, 10u32, 10u32,
        11u32, 11u32, 11u32, 11u32, 12u32, 12u32, 12u32, 12u32, 13u32, 13u32, 13u32,
        13u32, 14u32, 15u32, 16u32, 17u32, 17u32, 17u32, 17u32, 18u32, 18u32, 18u32,
        18u32, 19u32, 19u32, 19u32, 19u32, 20u32, 20u32, 20u32, 20u32,
    ];
    /// Column of each mass-matrix nonzero.
    pub static MASS_COLS: [u32; 57usize] = [
        0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32,
        5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 7u32, 8u32, 9u32, 10u32, 11u32, 12u32, 13u32,
        10u32, 11u32, 12u32, 13u32, 10u32, 11u32, 12u32, 13u32, 10u32, 11u32, 12u32,
        13u32, 14u32, 15u32, 16u32, 17u32, 18u32, 19u32, 20u32, 17u32, 18u32, 19u32,
        20u32, 17u32, 18u32, 19u32, 20u32, 17u32, 18u32, 19u32, 20u32,
    ];
    /// Sizes, patterns and names for this formulation.
    pub static INFO: MechanismInfo = MechanismInfo {
        name: "slider_crank",
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
        let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 57] = out.try_into().expect("out must have 57 entries");
        mass_part_0(q, out);
    }
    #[inline(never)]
    fn mass_part_0(q: &[f64; 21], out: &mut [f64; 57]) {
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
        let x59 = q[10] * q[10];
        let x60 = q[11] * q[11];
        let x61 = q[12] * q[12];
        let x62 = q[13] * q[13];
        let x72 = q[11] * q[12];
        let x74 = q[10] * q[13];
        let x79 = q[11] * q[13];
        let x81 = q[10] * q[12];
        let x85 = q[12] * q[13];
        let x87 = q[10] * q[11];
        let x103 = q[17] * q[17];
        let x104 = q[18] * q[18];
        let x105 = q[19] * q[19];
        let x106 = q[20] * q[20];
        let x116 = q[18] * q[19];
        let x118 = q[17] * q[20];
        let x123 = q[18] * q[20];
        let x125 = q[17] * q[19];
        let x129 = q[19] * q[20];
        let x131 = q[17] * q[18];
        let x313 = 2.0 * q[3];
        let x314 = 2.0 * q[4];
        let x315 = 2.0 * q[10];
        let x316 = 2.0 * q[11];
        let x317 = 2.0 * q[12];
        let x318 = 2.0 * q[13];
        let x319 = 2.0 * q[5];
        let x320 = 2.0 * q[6];
        let x321 = 2.0 * x313;
        let x334 = 2.0 * x314;
        let x350 = 2.0 * x315;
        let x354 = 2.0 * q[17];
        let x355 = 2.0 * q[20];
        let x422 = 2.0 * x316;
        let x464 = 2.0 * x317;
        let x500 = 2.0 * x318;
        let x527 = 2.0 * q[18];
        let x528 = 2.0 * q[19];
        let x529 = 2.0 * x354;
        let x546 = 2.0 * x355;
        let x1154 = 2.0 * x319;
        let x1156 = 2.0 * x320;
        let x1158 = x314 * x334;
        let x1160 = 0.0001 * x1158;
        let x1162 = x319 * x1154;
        let x1164 = 0.00025 * x1162;
        let x1166 = x320 * x1156;
        let x1168 = 0.00025 * x1166;
        let x1170 = x1160 + x1164;
        let x1172 = x1168 + x1170;
        let x1174 = 0.5 * x1172;
        let x1176 = x14 * 0.0008;
        let x1177 = x1174 + x1176;
        let x1178 = x314 * x321;
        let x1179 = 0.0001 * x1178;
        let x1180 = x319 * x1156;
        let x1182 = 0.00025 * x1180;
        let x1184 = x320 * x1154;
        let x1185 = 0.00025 * x1184;
        let x1186 = x1179 - x1182;
        let x1187 = x1185 + x1186;
        let x1188 = 0.5 * x1187;
        let x1190 = x43 * 0.0008;
        let x1191 = x1190 - x1188;
        let x1192 = x314 * x1156;
        let x1193 = 0.0001 * x1192;
        let x1194 = x319 * x321;
        let x1195 = 0.00025 * x1194;
        let x1196 = x320 * x334;
        let x1198 = 0.00025 * x1196;
        let x1200 = x1193 + x1195;
        let x1201 = x1200 - x1198;
        let x1202 = 0.5 * x1201;
        let x1204 = x37 * 0.0008;
        let x1205 = x1204 - x1202;
        let x1206 = x314 * x1154;
        let x1208 = 0.0001 * x1206;
        let x1210 = x319 * x334;
        let x1211 = 0.00025 * x1210;
        let x1212 = x320 * x321;
        let x1213 = 0.00025 * x1212;
        let x1214 = x1211 - x1208;
        let x1215 = x1213 + x1214;
        let x1216 = 0.5 * x1215;
        let x1218 = x30 * 0.0008;
        let x1219 = x1218 - x1216;
        let x1220 = x313 * x334;
        let x1222 = 0.0001 * x1220;
        let x1226 = x1185 - x1222;
        let x1227 = x1226 - x1182;
        let x1228 = 0.5 * x1227;
        let x1229 = x1190 + x1228;
        let x1230 = x313 * x321;
        let x1231 = 0.0001 * x1230;
        let x1232 = x1168 + x1231;
        let x1233 = x1164 + x1232;
        let x1234 = 0.5 * x1233;
        let x1235 = x15 * 0.0008;
        let x1236 = x1234 + x1235;
        let x1237 = x313 * x1156;
        let x1238 = 0.0001 * x1237;
        let x1242 = x1238 - x1213;
        let x1243 = x1242 - x1211;
        let x1244 = 0.5 * x1243;
        let x1245 = x28 * 0.0008;
        let x1246 = x1244 + x1245;
        let x1247 = x313 * x1154;
        let x1249 = 0.0001 * x1247;
        let x1251 = x1198 + x1249;
        let x1253 = x1195 - x1251;
        let x1254 = 0.5 * x1253;
        let x1255 = x35 * 0.0008;
        let x1256 = x1254 + x1255;
        let x1257 = 0.0001 * x1196;
        let x1259 = 0.00025 * x1247;
        let x1262 = 0.00025 * x1192;
        let x1264 = x1257 + x1259;
        let x1266 = x1262 - x1264;
        let x1267 = 0.5 * x1266;
        let x1268 = x1204 + x1267;
        let x1269 = 0.0001 * x1212;
        let x1271 = 0.00025 * x1237;
        let x1273 = 0.00025 * x1206;
        let x1275 = x1269 - x1271;
        let x1276 = x1275 - x1273;
        let x1277 = 0.5 * x1276;
        let x1278 = x1245 + x1277;
        let x1279 = 0.0001 * x1166;
        let x1280 = 0.00025 * x1230;
        let x1281 = 0.00025 * x1158;
        let x1283 = x1279 + x1280;
        let x1284 = x1281 + x1283;
        let x1285 = 0.5 * x1284;
        let x1286 = x16 * 0.0008;
        let x1287 = x1285 + x1286;
        let x1288 = 0.0001 * x1184;
        let x1290 = 0.00025 * x1220;
        let x1291 = 0.00025 * x1178;
        let x1293 = x1290 - x1288;
        let x1294 = x1293 - x1291;
        let x1295 = 0.5 * x1294;
        let x1296 = x41 * 0.0008;
        let x1297 = x1295 + x1296;
        let x1298 = 0.0001 * x1210;
        let x1300 = x1298 - x1273;
        let x1301 = x1300 - x1271;
        let x1302 = 0.5 * x1301;
        let x1303 = x1218 + x1302;
        let x1304 = 0.0001 * x1194;
        let x1306 = x1262 + x1304;
        let x1308 = x1259 - x1306;
        let x1309 = 0.5 * x1308;
        let x1310 = x1255 + x1309;
        let x1311 = 0.0001 * x1180;
        let x1314 = x1291 - x1311;
        let x1315 = x1314 - x1290;
        let x1316 = 0.5 * x1315;
        let x1317 = x1296 + x1316;
        let x1318 = 0.0001 * x1162;
        let x1320 = x1281 + x1318;
        let x1321 = x1280 + x1320;
        let x1322 = 0.5 * x1321;
        let x1323 = x17 * 0.0008;
        let x1324 = x1322 + x1323;
        let x1577 = x316 * x422;
        let x1579 = 0.0001 * x1577;
        let x1581 = x317 * x464;
        let x1583 = 0.006124999999999999 * x1581;
        let x1585 = x318 * x500;
        let x1587 = 0.006124999999999999 * x1585;
        let x1589 = x1579 + x1583;
        let x1591 = x1587 + x1589;
        let x1593 = 0.5 * x1591;
        let x1595 = x59 * 0.016466666666666668;
        let x1596 = x1593 + x1595;
        let x1597 = x316 * x350;
        let x1598 = 0.0001 * x1597;
        let x1599 = x317 * x500;
        let x1601 = 0.006124999999999999 * x1599;
        let x1603 = x318 * x464;
        let x1604 = 0.006124999999999999 * x1603;
        let x1605 = x1598 - x1601;
        let x1606 = x1604 + x1605;
        let x1607 = 0.5 * x1606;
        let x1609 = x87 * 0.016466666666666668;
        let x1610 = x1609 - x1607;
        let x1611 = x316 * x500;
        let x1612 = 0.0001 * x1611;
        let x1613 = x317 * x350;
        let x1614 = 0.006124999999999999 * x1613;
        let x1615 = x318 * x422;
        let x1617 = 0.006124999999999999 * x1615;
        let x1619 = x1612 + x1614;
        let x1620 = x1619 - x1617;
        let x1621 = 0.5 * x1620;
        let x1623 = x81 * 0.016466666666666668;
        let x1624 = x1623 - x1621;
        let x1625 = x316 * x464;
        let x1627 = 0.0001 * x1625;
        let x1629 = x317 * x422;
        let x1630 = 0.006124999999999999 * x1629;
        let x1631 = x318 * x350;
        let x1632 = 0.006124999999999999 * x1631;
        let x1633 = x1630 - x1627;
        let x1634 = x1632 + x1633;
        let x1635 = 0.5 * x1634;
        let x1637 = x74 * 0.016466666666666668;
        let x1638 = x1637 - x1635;
        let x1639 = x315 * x422;
        let x1641 = 0.0001 * x1639;
        let x1645 = x1604 - x1641;
        let x1646 = x1645 - x1601;
        let x1647 = 0.5 * x1646;
        let x1648 = x1609 + x1647;
        let x1649 = x315 * x350;
        let x1650 = 0.0001 * x1649;
        let x1651 = x1587 + x1650;
        let x1652 = x1583 + x1651;
        let x1653 = 0.5 * x1652;
        let x1654 = x60 * 0.016466666666666668;
        let x1655 = x1653 + x1654;
        let x1656 = x315 * x500;
        let x1657 = 0.0001 * x1656;
        let x1661 = x1657 - x1632;
        let x1662 = x1661 - x1630;
        let x1663 = 0.5 * x1662;
        let x1664 = x72 * 0.016466666666666668;
        let x1665 = x1663 + x1664;
        let x1666 = x315 * x464;
        let x1668 = 0.0001 * x1666;
        let x1670 = x1617 + x1668;
        let x1672 = x1614 - x1670;
        let x1673 = 0.5 * x1672;
        let x1674 = x79 * 0.016466666666666668;
        let x1675 = x1673 + x1674;
        let x1676 = 0.0001 * x1615;
        let x1678 = 0.006124999999999999 * x1666;
        let x1681 = 0.006124999999999999 * x1611;
        let x1683 = x1676 + x1678;
        let x1685 = x1681 - x1683;
        let x1686 = 0.5 * x1685;
        let x1687 = x1623 + x1686;
        let x1688 = 0.0001 * x1631;
        let x1690 = 0.006124999999999999 * x1656;
        let x1692 = 0.006124999999999999 * x1625;
        let x1694 = x1688 - x1690;
        let x1695 = x1694 - x1692;
        let x1696 = 0.5 * x1695;
        let x1697 = x1664 + x1696;
        let x1698 = 0.0001 * x1585;
        let x1699 = 0.006124999999999999 * x1649;
        let x1700 = 0.006124999999999999 * x1577;
        let x1702 = x1698 + x1699;
        let x1703 = x1700 + x1702;
        let x1704 = 0.5 * x1703;
        let x1705 = x61 * 0.016466666666666668;
        let x1706 = x1704 + x1705;
        let x1707 = 0.0001 * x1603;
        let x1709 = 0.006124999999999999 * x1639;
        let x1710 = 0.006124999999999999 * x1597;
        let x1712 = x1709 - x1707;
        let x1713 = x1712 - x1710;
        let x1714 = 0.5 * x1713;
        let x1715 = x85 * 0.016466666666666668;
        let x1716 = x1714 + x1715;
        let x1717 = 0.0001 * x1629;
        let x1719 = x1717 - x1692;
        let x1720 = x1719 - x1690;
        let x1721 = 0.5 * x1720;
        let x1722 = x1637 + x1721;
        let x1723 = 0.0001 * x1613;
        let x1725 = x1681 + x1723;
        let x1727 = x1678 - x1725;
        let x1728 = 0.5 * x1727;
        let x1729 = x1674 + x1728;
        let x1730 = 0.0001 * x1599;
        let x1733 = x1710 - x1730;
        let x1734 = x1733 - x1709;
        let x1735 = 0.5 * x1734;
        let x1736 = x1715 + x1735;
        let x1737 = 0.0001 * x1581;
        let x1739 = x1700 + x1737;
        let x1740 = x1699 + x1739;
        let x1741 = 0.5 * x1740;
        let x1742 = x62 * 0.016466666666666668;
        let x1743 = x1741 + x1742;
        let x1987 = 2.0 * x527;
        let x1989 = 2.0 * x528;
        let x1992 = x527 * x1987;
        let x1994 = 0.001 * x1992;
        let x1996 = x528 * x1989;
        let x1998 = 0.001 * x1996;
        let x2000 = x355 * x546;
        let x2002 = 0.001 * x2000;
        let x2004 = x1994 + x1998;
        let x2006 = x2002 + x2004;
        let x2008 = 0.5 * x2006;
        let x2010 = x103 * 0.004;
        let x2011 = x2008 + x2010;
        let x2012 = x527 * x529;
        let x2013 = 0.001 * x2012;
        let x2014 = x528 * x546;
        let x2016 = 0.001 * x2014;
        let x2018 = x355 * x1989;
        let x2019 = 0.001 * x2018;
        let x2020 = x2013 - x2016;
        let x2021 = x2019 + x2020;
        let x2022 = 0.5 * x2021;
        let x2024 = x131 * 0.004;
        let x2025 = x2024 - x2022;
        let x2026 = x527 * x546;
        let x2027 = 0.001 * x2026;
        let x2028 = x528 * x529;
        let x2029 = 0.001 * x2028;
        let x2030 = x355 * x1987;
        let x2032 = 0.001 * x2030;
        let x2034 = x2027 + x2029;
        let x2035 = x2034 - x2032;
        let x2036 = 0.5 * x2035;
        let x2038 = x125 * 0.004;
        let x2039 = x2038 - x2036;
        let x2040 = x527 * x1989;
        let x2042 = 0.001 * x2040;
        let x2044 = x528 * x1987;
        let x2045 = 0.001 * x2044;
        let x2046 = x355 * x529;
        let x2047 = 0.001 * x2046;
        let x2048 = x2045 - x2042;
        let x2049 = x2047 + x2048;
        let x2050 = 0.5 * x2049;
        let x2052 = x118 * 0.004;
        let x2053 = x2052 - x2050;
        let x2054 = x354 * x1987;
        let x2056 = 0.001 * x2054;
        let x2060 = x2019 - x2056;
        let x2061 = x2060 - x2016;
        let x2062 = 0.5 * x2061;
        let x2063 = x2024 + x2062;
        let x2064 = x354 * x529;
        let x2065 = 0.001 * x2064;
        let x2066 = x2002 + x2065;
        let x2067 = x1998 + x2066;
        let x2068 = 0.5 * x2067;
        let x2069 = x104 * 0.004;
        let x2070 = x2068 + x2069;
        let x2071 = x354 * x546;
        let x2072 = 0.001 * x2071;
        let x2076 = x2072 - x2047;
        let x2077 = x2076 - x2045;
        let x2078 = 0.5 * x2077;
        let x2079 = x116 * 0.004;
        let x2080 = x2078 + x2079;
        let x2081 = x354 * x1989;
        let x2083 = 0.001 * x2081;
        let x2085 = x2032 + x2083;
        let x2087 = x2029 - x2085;
        let x2088 = 0.5 * x2087;
        let x2089 = x123 * 0.004;
        let x2090 = x2088 + x2089;
        let x2093 = x2027 - x2085;
        let x2094 = 0.5 * x2093;
        let x2095 = x2038 + x2094;
        let x2098 = x2047 - x2072;
        let x2099 = x2098 - x2042;
        let x2100 = 0.5 * x2099;
        let x2101 = x2079 + x2100;
        let x2102 = x1994 + x2066;
        let x2103 = 0.5 * x2102;
        let x2104 = x105 * 0.004;
        let x2105 = x2103 + x2104;
        let x2107 = x2056 - x2019;
        let x2108 = x2107 - x2013;
        let x2109 = 0.5 * x2108;
        let x2110 = x129 * 0.004;
        let x2111 = x2109 + x2110;
        let x2112 = x2048 - x2072;
        let x2113 = 0.5 * x2112;
        let x2114 = x2052 + x2113;
        let x2117 = x2083 - x2034;
        let x2118 = 0.5 * x2117;
        let x2119 = x2089 + x2118;
        let x2120 = x2020 - x2056;
        let x2121 = 0.5 * x2120;
        let x2122 = x2110 + x2121;
        let x2123 = x2004 + x2065;
        let x2124 = 0.5 * x2123;
        let x2125 = x106 * 0.004;
        let x2126 = x2124 + x2125;
        out[0] = 0.3;
        out[1] = 0.3;
        out[2] = 0.3;
        out[3] = x1177;
        out[4] = x1191;
        out[5] = x1205;
        out[6] = x1219;
        out[7] = x1229;
        out[8] = x1236;
        out[9] = x1246;
        out[10] = x1256;
        out[11] = x1268;
        out[12] = x1278;
        out[13] = x1287;
        out[14] = x1297;
        out[15] = x1303;
        out[16] = x1310;
        out[17] = x1317;
        out[18] = x1324;
        out[19] = 0.6;
        out[20] = 0.6;
        out[21] = 0.6;
        out[22] = x1596;
        out[23] = x1610;
        out[24] = x1624;
        out[25] = x1638;
        out[26] = x1648;
        out[27] = x1655;
        out[28] = x1665;
        out[29] = x1675;
        out[30] = x1687;
        out[31] = x1697;
        out[32] = x1706;
        out[33] = x1716;
        out[34] = x1722;
        out[35] = x1729;
        out[36] = x1736;
        out[37] = x1743;
        out[38] = 1.0;
        out[39] = 1.0;
        out[40] = 1.0;
        out[41] = x2011;
        out[42] = x2025;
        out[43] = x2039;
        out[44] = x2053;
        out[45] = x2063;
        out[46] = x2070;
        out[47] = x2080;
        out[48] = x2090;
        out[49] = x2095;
        out[50] = x2101;
        out[51] = x2105;
        out[52] = x2111;
        out[53] = x2114;
        out[54] = x2119;
        out[55] = x2122;
        out[56] = x2126;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 21] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
        let _ = t;
        force_part_0(q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(q: &[f64; 21], qd: &[f64; 21], out: &mut [f64; 21]) {
        let x313 = 2.0 * q[3];
        let x314 = 2.0 * q[4];
        let x315 = 2.0 * q[10];
        let x316 = 2.0 * q[11];
        let x317 = 2.0 * q[12];
        let x318 = 2.0 * q[13];
        let x319 = 2.0 * q[5];
        let x320 = 2.0 * q[6];
        let x354 = 2.0 * q[17];
        let x355 = 2.0 * q[20];
        let x527 = 2.0 * q[18];
        let x528 = 2.0 * q[19];
        let x587 = q[5] * qd[4];
        let x588 = q[4] * qd[5];
        let x591 = q[6] * qd[3];
        let x592 = q[3] * qd[6];
        let x595 = q[6] * qd[4];
        let x596 = q[4] * qd[6];
        let x599 = q[5] * qd[3];
        let x600 = q[3] * qd[5];
        let x605 = q[6] * qd[5];
        let x606 = q[5] * qd[6];
        let x609 = q[4] * qd[3];
        let x610 = q[3] * qd[4];
        let x627 = q[12] * qd[11];
        let x628 = q[11] * qd[12];
        let x631 = q[13] * qd[10];
        let x632 = q[10] * qd[13];
        let x637 = q[13] * qd[11];
        let x638 = q[11] * qd[13];
        let x641 = q[12] * qd[10];
        let x642 = q[10] * qd[12];
        let x647 = q[13] * qd[12];
        let x648 = q[12] * qd[13];
        let x651 = q[11] * qd[10];
        let x652 = q[10] * qd[11];
        let x667 = q[19] * qd[18];
        let x668 = q[18] * qd[19];
        let x671 = q[20] * qd[17];
        let x672 = q[17] * qd[20];
        let x675 = q[20] * qd[18];
        let x676 = q[18] * qd[20];
        let x679 = q[19] * qd[17];
        let x680 = q[17] * qd[19];
        let x685 = q[20] * qd[19];
        let x686 = q[19] * qd[20];
        let x689 = q[18] * qd[17];
        let x690 = q[17] * qd[18];
        let x802 = 2.0 * qd[3];
        let x803 = 2.0 * qd[4];
        let x804 = 2.0 * qd[10];
        let x805 = 2.0 * qd[11];
        let x806 = 2.0 * qd[12];
        let x807 = 2.0 * qd[13];
        let x808 = 2.0 * qd[5];
        let x809 = 2.0 * qd[6];
        let x810 = 2.0 * qd[17];
        let x811 = 2.0 * qd[20];
        let x812 = 2.0 * qd[18];
        let x813 = 2.0 * qd[19];
        let x831 = qd[4] * qd[5];
        let x834 = qd[3] * qd[6];
        let x837 = qd[4] * qd[6];
        let x840 = qd[3] * qd[5];
        let x865 = qd[11] * qd[12];
        let x868 = qd[10] * qd[13];
        let x873 = qd[11] * qd[13];
        let x876 = qd[10] * qd[12];
        let x899 = qd[18] * qd[19];
        let x902 = qd[17] * qd[20];
        let x905 = qd[18] * qd[20];
        let x908 = qd[17] * qd[19];
        let x1046 = x610 - x609;
        let x1047 = x605 + x1046;
        let x1048 = x1047 - x606;
        let x1049 = 2.0 * x1048;
        let x1052 = x595 + x599;
        let x1054 = x600 - x1052;
        let x1055 = x596 + x1054;
        let x1056 = 2.0 * x1055;
        let x1059 = x587 - x591;
        let x1060 = x1059 - x588;
        let x1061 = x592 + x1060;
        let x1062 = 2.0 * x1061;
        let x1086 = 2.0 * x1049;
        let x1088 = 2.0 * x1056;
        let x1090 = 2.0 * x1062;
        let x1327 = x837 + x840;
        let x1329 = x840 - x1327;
        let x1330 = x837 + x1329;
        let x1331 = 2.0 * x1330;
        let x1334 = x831 - x834;
        let x1335 = x1334 - x831;
        let x1336 = x834 + x1335;
        let x1337 = 2.0 * x1336;
        let x1338 = 2.0 * x1331;
        let x1339 = 2.0 * x1337;
        let x1340 = x803 * x1086;
        let x1341 = 0.0001 * x1340;
        let x1342 = x808 * x1088;
        let x1343 = x319 * x1338;
        let x1344 = x1342 + x1343;
        let x1345 = 0.00025 * x1344;
        let x1346 = x809 * x1090;
        let x1347 = x320 * x1339;
        let x1348 = x1346 + x1347;
        let x1349 = 0.00025 * x1348;
        let x1350 = x1341 + x1345;
        let x1351 = x1349 + x1350;
        let x1352 = 0.5 * x1351;
        let x1354 = x802 * x1086;
        let x1355 = 0.0001 * x1354;
        let x1356 = x809 * x1088;
        let x1357 = x320 * x1338;
        let x1358 = x1356 + x1357;
        let x1359 = 0.00025 * x1358;
        let x1361 = x808 * x1090;
        let x1362 = x319 * x1339;
        let x1363 = x1361 + x1362;
        let x1364 = 0.00025 * x1363;
        let x1365 = x1355 - x1359;
        let x1366 = x1364 + x1365;
        let x1367 = 0.5 * x1366;
        let x1368 = x809 * x1086;
        let x1369 = 0.0001 * x1368;
        let x1370 = x802 * x1088;
        let x1371 = x313 * x1338;
        let x1372 = x1370 + x1371;
        let x1373 = 0.00025 * x1372;
        let x1374 = x803 * x1090;
        let x1375 = x314 * x1339;
        let x1376 = x1374 + x1375;
        let x1377 = 0.00025 * x1376;
        let x1379 = x1369 + x1373;
        let x1380 = x1379 - x1377;
        let x1381 = 0.5 * x1380;
        let x1382 = x808 * x1086;
        let x1383 = 0.0001 * x1382;
        let x1385 = x803 * x1088;
        let x1386 = x314 * x1338;
        let x1387 = x1385 + x1386;
        let x1388 = 0.00025 * x1387;
        let x1389 = x802 * x1090;
        let x1390 = x313 * x1339;
        let x1391 = x1389 + x1390;
        let x1392 = 0.00025 * x1391;
        let x1393 = x1388 - x1383;
        let x1394 = x1392 + x1393;
        let x1395 = 0.5 * x1394;
        let x1396 = qd[3] * qd[3];
        let x1397 = qd[4] * qd[4];
        let x1398 = qd[5] * qd[5];
        let x1399 = qd[6] * qd[6];
        let x1400 = x1396 + x1397;
        let x1401 = x1398 + x1400;
        let x1402 = x1399 + x1401;
        let x1404 = 0.00025 * x1342;
        let x1405 = 0.00025 * x1346;
        let x1406 = x1341 + x1404;
        let x1407 = x1405 + x1406;
        let x1408 = 0.5 * x1407;
        let x1409 = x1352 + x1408;
        let x1410 = q[3] * 0.0008;
        let x1411 = x1402 * x1410;
        let x1413 = x1409 - x1411;
        let x1420 = 0.00025 * x1356;
        let x1422 = 0.00025 * x1361;
        let x1424 = x1420 - x1355;
        let x1425 = x1424 - x1422;
        let x1426 = 0.5 * x1425;
        let x1428 = x1426 - x1367;
        let x1429 = q[4] * 0.0008;
        let x1430 = x1402 * x1429;
        let x1432 = x1428 - x1430;
        let x1438 = 0.00025 * x1370;
        let x1440 = 0.00025 * x1374;
        let x1441 = x1369 + x1438;
        let x1443 = x1440 - x1441;
        let x1444 = 0.5 * x1443;
        let x1446 = x1444 - x1381;
        let x1447 = q[5] * 0.0008;
        let x1448 = x1402 * x1447;
        let x1450 = x1446 - x1448;
        let x1454 = 0.00025 * x1385;
        let x1457 = 0.00025 * x1389;
        let x1459 = x1383 - x1454;
        let x1460 = x1459 - x1457;
        let x1461 = 0.5 * x1460;
        let x1463 = x1461 - x1395;
        let x1464 = q[6] * 0.0008;
        let x1465 = x1402 * x1464;
        let x1467 = x1463 - x1465;
        let x1470 = x652 - x651;
        let x1471 = x647 + x1470;
        let x1472 = x1471 - x648;
        let x1473 = 2.0 * x1472;
        let x1476 = x637 + x641;
        let x1478 = x642 - x1476;
        let x1479 = x638 + x1478;
        let x1480 = 2.0 * x1479;
        let x1483 = x627 - x631;
        let x1484 = x1483 - x628;
        let x1485 = x632 + x1484;
        let x1486 = 2.0 * x1485;
        let x1508 = 2.0 * x1473;
        let x1510 = 2.0 * x1480;
        let x1512 = 2.0 * x1486;
        let x1746 = x873 + x876;
        let x1748 = x876 - x1746;
        let x1749 = x873 + x1748;
        let x1750 = 2.0 * x1749;
        let x1753 = x865 - x868;
        let x1754 = x1753 - x865;
        let x1755 = x868 + x1754;
        let x1756 = 2.0 * x1755;
        let x1757 = 2.0 * x1750;
        let x1758 = 2.0 * x1756;
        let x1759 = x805 * x1508;
        let x1760 = 0.0001 * x1759;
        let x1761 = x806 * x1510;
        let x1762 = x317 * x1757;
        let x1763 = x1761 + x1762;
        let x1764 = 0.006124999999999999 * x1763;
        let x1765 = x807 * x1512;
        let x1766 = x318 * x1758;
        let x1767 = x1765 + x1766;
        let x1768 = 0.006124999999999999 * x1767;
        let x1769 = x1760 + x1764;
        let x1770 = x1768 + x1769;
        let x1771 = 0.5 * x1770;
        let x1773 = x804 * x1508;
        let x1774 = 0.0001 * x1773;
        let x1775 = x807 * x1510;
        let x1776 = x318 * x1757;
        let x1777 = x1775 + x1776;
        let x1778 = 0.006124999999999999 * x1777;
        let x1780 = x806 * x1512;
        let x1781 = x317 * x1758;
        let x1782 = x1780 + x1781;
        let x1783 = 0.006124999999999999 * x1782;
        let x1784 = x1774 - x1778;
        let x1785 = x1783 + x1784;
        let x1786 = 0.5 * x1785;
        let x1787 = x807 * x1508;
        let x1788 = 0.0001 * x1787;
        let x1789 = x804 * x1510;
        let x1790 = x315 * x1757;
        let x1791 = x1789 + x1790;
        let x1792 = 0.006124999999999999 * x1791;
        let x1793 = x805 * x1512;
        let x1794 = x316 * x1758;
        let x1795 = x1793 + x1794;
        let x1796 = 0.006124999999999999 * x1795;
        let x1798 = x1788 + x1792;
        let x1799 = x1798 - x1796;
        let x1800 = 0.5 * x1799;
        let x1801 = x806 * x1508;
        let x1802 = 0.0001 * x1801;
        let x1804 = x805 * x1510;
        let x1805 = x316 * x1757;
        let x1806 = x1804 + x1805;
        let x1807 = 0.006124999999999999 * x1806;
        let x1808 = x804 * x1512;
        let x1809 = x315 * x1758;
        let x1810 = x1808 + x1809;
        let x1811 = 0.006124999999999999 * x1810;
        let x1812 = x1807 - x1802;
        let x1813 = x1811 + x1812;
        let x1814 = 0.5 * x1813;
        let x1815 = qd[10] * qd[10];
        let x1816 = qd[11] * qd[11];
        let x1817 = qd[12] * qd[12];
        let x1818 = qd[13] * qd[13];
        let x1819 = x1815 + x1816;
        let x1820 = x1817 + x1819;
        let x1821 = x1818 + x1820;
        let x1823 = 0.006124999999999999 * x1761;
        let x1824 = 0.006124999999999999 * x1765;
        let x1825 = x1760 + x1823;
        let x1826 = x1824 + x1825;
        let x1827 = 0.5 * x1826;
        let x1828 = x1771 + x1827;
        let x1829 = q[10] * 0.016466666666666668;
        let x1830 = x1821 * x1829;
        let x1832 = x1828 - x1830;
        let x1839 = 0.006124999999999999 * x1775;
        let x1841 = 0.006124999999999999 * x1780;
        let x1843 = x1839 - x1774;
        let x1844 = x1843 - x1841;
        let x1845 = 0.5 * x1844;
        let x1847 = x1845 - x1786;
        let x1848 = q[11] * 0.016466666666666668;
        let x1849 = x1821 * x1848;
        let x1851 = x1847 - x1849;
        let x1857 = 0.006124999999999999 * x1789;
        let x1859 = 0.006124999999999999 * x1793;
        let x1860 = x1788 + x1857;
        let x1862 = x1859 - x1860;
        let x1863 = 0.5 * x1862;
        let x1865 = x1863 - x1800;
        let x1866 = q[12] * 0.016466666666666668;
        let x1867 = x1821 * x1866;
        let x1869 = x1865 - x1867;
        let x1873 = 0.006124999999999999 * x1804;
        let x1876 = 0.006124999999999999 * x1808;
        let x1878 = x1802 - x1873;
        let x1879 = x1878 - x1876;
        let x1880 = 0.5 * x1879;
        let x1882 = x1880 - x1814;
        let x1883 = q[13] * 0.016466666666666668;
        let x1884 = x1821 * x1883;
        let x1886 = x1882 - x1884;
        let x1889 = x690 - x689;
        let x1890 = x685 + x1889;
        let x1891 = x1890 - x686;
        let x1892 = 2.0 * x1891;
        let x1895 = x675 + x679;
        let x1897 = x680 - x1895;
        let x1898 = x676 + x1897;
        let x1899 = 2.0 * x1898;
        let x1902 = x667 - x671;
        let x1903 = x1902 - x668;
        let x1904 = x672 + x1903;
        let x1905 = 2.0 * x1904;
        let x1923 = 2.0 * x1892;
        let x1925 = 2.0 * x1899;
        let x1927 = 2.0 * x1905;
        let x2129 = x905 + x908;
        let x2131 = x908 - x2129;
        let x2132 = x905 + x2131;
        let x2133 = 2.0 * x2132;
        let x2136 = x899 - x902;
        let x2137 = x2136 - x899;
        let x2138 = x902 + x2137;
        let x2139 = 2.0 * x2138;
        let x2140 = 2.0 * x2133;
        let x2141 = 2.0 * x2139;
        let x2142 = x812 * x1923;
        let x2143 = 0.001 * x2142;
        let x2144 = x813 * x1925;
        let x2145 = x528 * x2140;
        let x2146 = x2144 + x2145;
        let x2147 = 0.001 * x2146;
        let x2148 = x811 * x1927;
        let x2149 = x355 * x2141;
        let x2150 = x2148 + x2149;
        let x2151 = 0.001 * x2150;
        let x2152 = x2143 + x2147;
        let x2153 = x2151 + x2152;
        let x2154 = 0.5 * x2153;
        let x2156 = x810 * x1923;
        let x2157 = 0.001 * x2156;
        let x2158 = x811 * x1925;
        let x2159 = x355 * x2140;
        let x2160 = x2158 + x2159;
        let x2161 = 0.001 * x2160;
        let x2163 = x813 * x1927;
        let x2164 = x528 * x2141;
        let x2165 = x2163 + x2164;
        let x2166 = 0.001 * x2165;
        let x2167 = x2157 - x2161;
        let x2168 = x2166 + x2167;
        let x2169 = 0.5 * x2168;
        let x2170 = x811 * x1923;
        let x2171 = 0.001 * x2170;
        let x2172 = x810 * x1925;
        let x2173 = x354 * x2140;
        let x2174 = x2172 + x2173;
        let x2175 = 0.001 * x2174;
        let x2176 = x812 * x1927;
        let x2177 = x527 * x2141;
        let x2178 = x2176 + x2177;
        let x2179 = 0.001 * x2178;
        let x2181 = x2171 + x2175;
        let x2182 = x2181 - x2179;
        let x2183 = 0.5 * x2182;
        let x2184 = x813 * x1923;
        let x2185 = 0.001 * x2184;
        let x2187 = x812 * x1925;
        let x2188 = x527 * x2140;
        let x2189 = x2187 + x2188;
        let x2190 = 0.001 * x2189;
        let x2191 = x810 * x1927;
        let x2192 = x354 * x2141;
        let x2193 = x2191 + x2192;
        let x2194 = 0.001 * x2193;
        let x2195 = x2190 - x2185;
        let x2196 = x2194 + x2195;
        let x2197 = 0.5 * x2196;
        let x2198 = qd[17] * qd[17];
        let x2199 = qd[18] * qd[18];
        let x2200 = qd[19] * qd[19];
        let x2201 = qd[20] * qd[20];
        let x2202 = x2198 + x2199;
        let x2203 = x2200 + x2202;
        let x2204 = x2201 + x2203;
        let x2206 = 0.001 * x2144;
        let x2207 = 0.001 * x2148;
        let x2208 = x2143 + x2206;
        let x2209 = x2207 + x2208;
        let x2210 = 0.5 * x2209;
        let x2211 = x2154 + x2210;
        let x2212 = q[17] * 0.004;
        let x2213 = x2204 * x2212;
        let x2215 = x2211 - x2213;
        let x2222 = 0.001 * x2158;
        let x2224 = 0.001 * x2163;
        let x2226 = x2222 - x2157;
        let x2227 = x2226 - x2224;
        let x2228 = 0.5 * x2227;
        let x2230 = x2228 - x2169;
        let x2231 = q[18] * 0.004;
        let x2232 = x2204 * x2231;
        let x2234 = x2230 - x2232;
        let x2240 = 0.001 * x2172;
        let x2242 = 0.001 * x2176;
        let x2243 = x2171 + x2240;
        let x2245 = x2242 - x2243;
        let x2246 = 0.5 * x2245;
        let x2248 = x2246 - x2183;
        let x2249 = q[19] * 0.004;
        let x2250 = x2204 * x2249;
        let x2252 = x2248 - x2250;
        let x2256 = 0.001 * x2187;
        let x2259 = 0.001 * x2191;
        let x2261 = x2185 - x2256;
        let x2262 = x2261 - x2259;
        let x2263 = 0.5 * x2262;
        let x2265 = x2263 - x2197;
        let x2266 = q[20] * 0.004;
        let x2267 = x2204 * x2266;
        let x2269 = x2265 - x2267;
        out[0] = 0.0;
        out[1] = -2.943;
        out[2] = 0.0;
        out[3] = x1413;
        out[4] = x1432;
        out[5] = x1450;
        out[6] = x1467;
        out[7] = 0.0;
        out[8] = -5.886;
        out[9] = 0.0;
        out[10] = x1832;
        out[11] = x1851;
        out[12] = x1869;
        out[13] = x1886;
        out[14] = 0.0;
        out[15] = -9.81;
        out[16] = 0.0;
        out[17] = x2215;
        out[18] = x2234;
        out[19] = x2252;
        out[20] = x2269;
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
        let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 21] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 21] = phi.try_into().expect("phi must have 21 entries");
        let phi_q: &mut [f64; 105] = phi_q
            .try_into()
            .expect("phi_q must have 105 entries");
        let mass: &mut [f64; 57] = mass.try_into().expect("mass must have 57 entries");
        let force: &mut [f64; 21] = force
            .try_into()
            .expect("force must have 21 entries");
        let mut s = [0.0f64; 24];
        eval_newton_shared_0(q, qd, t, &mut s);
        eval_newton_part_0(q, t, &s, phi, phi_q, mass);
        eval_newton_part_1(q, qd, &s, mass, force);
    }
    #[inline(never)]
    fn eval_newton_shared_0(q: &[f64; 21], _qd: &[f64; 21], _t: f64, s: &mut [f64; 24]) {
        let x103 = q[17] * q[17];
        s[0] = x103;
        let x104 = q[18] * q[18];
        s[1] = x104;
        let x105 = q[19] * q[19];
        s[2] = x105;
        let x106 = q[20] * q[20];
        s[3] = x106;
        let x116 = q[18] * q[19];
        s[4] = x116;
        let x118 = q[17] * q[20];
        s[5] = x118;
        let x123 = q[18] * q[20];
        s[6] = x123;
        let x125 = q[17] * q[19];
        s[7] = x125;
        let x129 = q[19] * q[20];
        s[8] = x129;
        let x131 = q[17] * q[18];
        s[9] = x131;
        let x313 = 2.0 * q[3];
        s[10] = x313;
        let x314 = 2.0 * q[4];
        s[11] = x314;
        let x315 = 2.0 * q[10];
        s[12] = x315;
        let x316 = 2.0 * q[11];
        s[13] = x316;
        let x317 = 2.0 * q[12];
        s[14] = x317;
        let x318 = 2.0 * q[13];
        s[15] = x318;
        let x319 = 2.0 * q[5];
        s[16] = x319;
        let x320 = 2.0 * q[6];
        s[17] = x320;
        let x354 = 2.0 * q[17];
        s[18] = x354;
        let x355 = 2.0 * q[20];
        s[19] = x355;
        let x527 = 2.0 * q[18];
        s[20] = x527;
        let x528 = 2.0 * q[19];
        s[21] = x528;
        let x529 = 2.0 * x354;
        s[22] = x529;
        let x546 = 2.0 * x355;
        s[23] = x546;
    }
    #[inline(never)]
    fn eval_newton_part_0(
        q: &[f64; 21],
        t: f64,
        s: &[f64; 24],
        phi: &mut [f64; 21],
        phi_q: &mut [f64; 105],
        mass: &mut [f64; 57],
    ) {
        let x5 = 6.283185307179586 * t;
        let x14 = q[3] * q[3];
        let x15 = q[4] * q[4];
        let x16 = q[5] * q[5];
        let x17 = q[6] * q[6];
        let x18 = x14 + x15;
        let x19 = 2.0 * x18;
        let x21 = x19 - 1.0;
        let x28 = q[4] * q[5];
        let x29 = 2.0 * x28;
        let x30 = q[3] * q[6];
        let x32 = 2.0 * x30;
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
        let x59 = q[10] * q[10];
        let x60 = q[11] * q[11];
        let x61 = q[12] * q[12];
        let x62 = q[13] * q[13];
        let x63 = x59 + x60;
        let x64 = 2.0 * x63;
        let x65 = x64 - 1.0;
        let x66 = x59 + x61;
        let x67 = 2.0 * x66;
        let x68 = x67 - 1.0;
        let x69 = x59 + x62;
        let x70 = 2.0 * x69;
        let x71 = x70 - 1.0;
        let x72 = q[11] * q[12];
        let x73 = 2.0 * x72;
        let x74 = q[10] * q[13];
        let x76 = 2.0 * x74;
        let x78 = x73 - x76;
        let x79 = q[11] * q[13];
        let x80 = 2.0 * x79;
        let x81 = q[10] * q[12];
        let x82 = 2.0 * x81;
        let x83 = x80 + x82;
        let x84 = x73 + x76;
        let x85 = q[12] * q[13];
        let x86 = 2.0 * x85;
        let x87 = q[10] * q[11];
        let x89 = 2.0 * x87;
        let x91 = x86 - x89;
        let x94 = x80 - x82;
        let x95 = x86 + x89;
        let x107 = s[0] + s[1];
        let x113 = s[0] + s[3];
        let x114 = 2.0 * x113;
        let x115 = x114 - 1.0;
        let x117 = 2.0 * s[4];
        let x120 = 2.0 * s[5];
        let x124 = 2.0 * s[6];
        let x126 = 2.0 * s[7];
        let x127 = x124 + x126;
        let x128 = x117 + x120;
        let x130 = 2.0 * s[8];
        let x133 = 2.0 * s[9];
        let x135 = x130 - x133;
        let x138 = x124 - x126;
        let x139 = x130 + x133;
        let x142 = x21 * 0.05;
        let x144 = x40 * 0.05;
        let x146 = x50 * 0.05;
        let x148 = q[0] - x142;
        let x149 = q[1] - x144;
        let x150 = q[2] - x146;
        let x151 = -x148;
        let x152 = -x149;
        let x153 = -x150;
        let x154 = q[0] + x142;
        let x155 = q[1] + x144;
        let x156 = q[2] + x146;
        let x161 = x65 * 0.1749999999999999;
        let x163 = x78 * 0.000000000000000003677613769070831;
        let x164 = x83 * 0.000000000000000013877787807814457;
        let x165 = x163 - x161;
        let x166 = x164 + x165;
        let x167 = x84 * 0.1749999999999999;
        let x169 = x68 * 0.000000000000000003677613769070831;
        let x170 = x91 * 0.000000000000000013877787807814457;
        let x171 = x169 - x167;
        let x172 = x170 + x171;
        let x173 = x94 * 0.1749999999999999;
        let x175 = x95 * 0.000000000000000003677613769070831;
        let x176 = x71 * 0.000000000000000013877787807814457;
        let x177 = x175 - x173;
        let x178 = x176 + x177;
        let x179 = q[7] + x166;
        let x180 = q[8] + x172;
        let x181 = q[9] + x178;
        let x183 = x154 - x179;
        let x185 = x155 - x180;
        let x187 = x156 - x181;
        let x191 = x65 * 0.17499999999999993;
        let x193 = x78 * 0.00000000000000001061650767297806;
        let x196 = x83 * 0.000000000000000027755575615628914;
        let x198 = x191 - x193;
        let x199 = x198 - x196;
        let x200 = x84 * 0.17499999999999993;
        let x201 = x68 * 0.00000000000000001061650767297806;
        let x203 = x91 * 0.000000000000000027755575615628914;
        let x205 = x200 - x201;
        let x206 = x205 - x203;
        let x207 = x94 * 0.17499999999999993;
        let x208 = x95 * 0.00000000000000001061650767297806;
        let x210 = x71 * 0.000000000000000027755575615628914;
        let x212 = x207 - x208;
        let x213 = x212 - x210;
        let x214 = q[7] + x199;
        let x215 = q[8] + x206;
        let x216 = q[9] + x213;
        let x271 = x65 * 0.00000000000000005551115123125783;
        let x272 = x78 * 0.9999999999999994;
        let x273 = x271 + x272;
        let x274 = x84 * 0.00000000000000005551115123125783;
        let x275 = x68 * 0.9999999999999994;
        let x276 = x274 + x275;
        let x277 = x94 * 0.00000000000000005551115123125783;
        let x278 = x95 * 0.9999999999999994;
        let x279 = x277 + x278;
        let x281 = q[14] - x214;
        let x283 = q[15] - x215;
        let x285 = q[16] - x216;
        let x286 = x127 * x273;
        let x287 = x135 * x276;
        let x288 = x115 * x279;
        let x289 = x286 + x287;
        let x290 = x288 + x289;
        let x295 = q[15] - 0.05;
        let x297 = q[16] - 0.12;
        let x298 = x5.sin();
        let x299 = x5.cos();
        let x300 = x21 * x298;
        let x301 = x40 * x299;
        let x303 = x300 - x301;
        let x304 = x16 + x18;
        let x305 = x17 + x304;
        let x306 = x305 - 1.0;
        let x307 = x61 + x63;
        let x308 = x62 + x307;
        let x309 = x308 - 1.0;
        let x310 = s[2] + x107;
        let x311 = s[3] + x310;
        let x312 = x311 - 1.0;
        let x321 = 2.0 * s[10];
        let x322 = -s[11];
        let x324 = 0.05 * x321;
        let x326 = 0.05 * s[17];
        let x328 = 0.05 * s[16];
        let x329 = -x328;
        let x330 = x298 * x321;
        let x331 = x299 * s[17];
        let x333 = x330 - x331;
        let x334 = 2.0 * s[11];
        let x335 = -s[10];
        let x336 = 0.05 * x334;
        let x338 = x298 * x334;
        let x339 = x299 * s[16];
        let x341 = x338 - x339;
        let x342 = 0.05 * s[11];
        let x344 = 0.05 * s[10];
        let x345 = -x344;
        let x346 = x299 * s[11];
        let x347 = -x346;
        let x348 = x299 * s[10];
        let x349 = -x348;
        let x350 = 2.0 * s[12];
        let x356 = 0.1749999999999999 * x350;
        let x358 = 0.000000000000000003677613769070831 * s[15];
        let x360 = 0.000000000000000013877787807814457 * s[14];
        let x361 = x356 + x358;
        let x363 = x360 - x361;
        let x364 = 0.1749999999999999 * s[15];
        let x366 = 0.000000000000000003677613769070831 * x350;
        let x367 = 0.000000000000000013877787807814457 * s[13];
        let x369 = x366 - x364;
        let x370 = x369 - x367;
        let x371 = 0.1749999999999999 * s[14];
        let x373 = 0.000000000000000003677613769070831 * s[13];
        let x374 = 0.000000000000000013877787807814457 * x350;
        let x375 = x371 + x373;
        let x376 = x374 + x375;
        let x377 = -x363;
        let x378 = -x370;
        let x379 = -x376;
        let x380 = 0.17499999999999993 * x350;
        let x381 = 0.00000000000000001061650767297806 * s[15];
        let x383 = 0.000000000000000027755575615628914 * s[14];
        let x385 = x380 + x381;
        let x386 = x385 - x383;
        let x387 = 0.17499999999999993 * s[15];
        let x388 = 0.00000000000000001061650767297806 * x350;
        let x390 = 0.000000000000000027755575615628914 * s[13];
        let x392 = x387 - x388;
        let x393 = x390 + x392;
        let x394 = 0.17499999999999993 * s[14];
        let x396 = 0.00000000000000001061650767297806 * s[13];
        let x398 = 0.000000000000000027755575615628914 * x350;
        let x400 = x394 + x396;
        let x402 = x398 + x400;
        let x404 = 0.00000000000000005551115123125783 * x350;
        let x405 = 0.9999999999999994 * s[15];
        let x407 = x404 - x405;
        let x408 = 0.00000000000000005551115123125783 * s[15];
        let x409 = 0.9999999999999994 * x350;
        let x410 = x408 + x409;
        let x411 = 0.00000000000000005551115123125783 * s[14];
        let x413 = 0.9999999999999994 * s[13];
        let x414 = x413 - x411;
        let x415 = -x386;
        let x416 = -x393;
        let x417 = x127 * x407;
        let x418 = x135 * x410;
        let x419 = x115 * x414;
        let x420 = x417 + x418;
        let x421 = x419 + x420;
        let x422 = 2.0 * s[13];
        let x424 = 0.1749999999999999 * x422;
        let x426 = 0.000000000000000003677613769070831 * s[14];
        let x427 = 0.000000000000000013877787807814457 * s[15];
        let x428 = x426 - x424;
        let x429 = x427 + x428;
        let x430 = 0.000000000000000013877787807814457 * s[12];
        let x432 = x371 + x430;
        let x434 = 0.000000000000000003677613769070831 * s[12];
        let x435 = x434 - x364;
        let x436 = -x429;
        let x437 = -x435;
        let x438 = 0.17499999999999993 * x422;
        let x439 = 0.00000000000000001061650767297806 * s[14];
        let x441 = 0.000000000000000027755575615628914 * s[15];
        let x443 = x438 - x439;
        let x444 = x443 - x441;
        let x445 = 0.000000000000000027755575615628914 * s[12];
        let x447 = x394 + x445;
        let x448 = 0.00000000000000001061650767297806 * s[12];
        let x450 = x387 - x448;
        let x451 = 0.00000000000000005551115123125783 * x422;
        let x452 = 0.9999999999999994 * s[14];
        let x453 = x451 + x452;
        let x454 = 0.9999999999999994 * s[12];
        let x455 = x408 + x454;
        let x456 = -x444;
        let x457 = -x447;
        let x458 = -x450;
        let x459 = x127 * x453;
        let x460 = x135 * x411;
        let x461 = x115 * x455;
        let x462 = x459 + x460;
        let x463 = x461 + x462;
        let x464 = 2.0 * s[14];
        let x465 = x373 + x430;
        let x466 = 0.1749999999999999 * s[13];
        let x468 = 0.000000000000000003677613769070831 * x464;
        let x469 = x468 - x466;
        let x470 = x427 + x469;
        let x471 = 0.1749999999999999 * s[12];
        let x473 = x358 + x471;
        let x474 = -x465;
        let x475 = -x470;
        let x476 = -x473;
        let x477 = x396 + x445;
        let x479 = 0.17499999999999993 * s[13];
        let x480 = 0.00000000000000001061650767297806 * x464;
        let x482 = x479 - x480;
        let x483 = x482 - x441;
        let x484 = 0.17499999999999993 * s[12];
        let x486 = x381 + x484;
        let x488 = 0.00000000000000005551115123125783 * s[13];
        let x489 = 0.9999999999999994 * x464;
        let x490 = x488 + x489;
        let x491 = 0.00000000000000005551115123125783 * s[12];
        let x493 = x405 - x491;
        let x494 = -x483;
        let x495 = x127 * x413;
        let x496 = x135 * x490;
        let x497 = x115 * x493;
        let x498 = x495 + x496;
        let x499 = x497 + x498;
        let x500 = 2.0 * s[15];
        let x502 = x367 - x434;
        let x503 = x360 - x471;
        let x504 = 0.000000000000000013877787807814457 * x500;
        let x505 = x426 - x466;
        let x506 = x504 + x505;
        let x507 = -x502;
        let x508 = -x503;
        let x509 = -x506;
        let x510 = x448 - x390;
        let x511 = x484 - x383;
        let x512 = 0.000000000000000027755575615628914 * x500;
        let x514 = x479 - x439;
        let x515 = x514 - x512;
        let x517 = x452 + x488;
        let x518 = -x510;
        let x519 = -x511;
        let x520 = -x515;
        let x521 = x127 * x454;
        let x523 = x135 * x491;
        let x524 = x115 * x517;
        let x525 = x523 - x521;
        let x526 = x524 + x525;
        let x531 = -s[21];
        let x532 = x273 * s[21];
        let x533 = x276 * s[20];
        let x535 = x279 * s[22];
        let x536 = x532 - x533;
        let x537 = x535 + x536;
        let x538 = -s[18];
        let x539 = x273 * s[19];
        let x540 = x276 * s[18];
        let x542 = x539 - x540;
        let x543 = x273 * s[18];
        let x544 = x276 * s[19];
        let x545 = x543 + x544;
        let x547 = x273 * s[20];
        let x548 = x276 * s[21];
        let x549 = x279 * s[23];
        let x550 = x547 + x548;
        let x551 = x549 + x550;
        let x1154 = 2.0 * s[16];
        let x1156 = 2.0 * s[17];
        let x1158 = s[11] * x334;
        let x1160 = 0.0001 * x1158;
        let x1162 = s[16] * x1154;
        let x1164 = 0.00025 * x1162;
        let x1166 = s[17] * x1156;
        let x1168 = 0.00025 * x1166;
        let x1170 = x1160 + x1164;
        let x1172 = x1168 + x1170;
        let x1174 = 0.5 * x1172;
        let x1176 = x14 * 0.0008;
        let x1177 = x1174 + x1176;
        let x1178 = s[11] * x321;
        let x1179 = 0.0001 * x1178;
        let x1180 = s[16] * x1156;
        let x1182 = 0.00025 * x1180;
        let x1184 = s[17] * x1154;
        let x1185 = 0.00025 * x1184;
        let x1186 = x1179 - x1182;
        let x1187 = x1185 + x1186;
        let x1188 = 0.5 * x1187;
        let x1190 = x43 * 0.0008;
        let x1191 = x1190 - x1188;
        let x1192 = s[11] * x1156;
        let x1193 = 0.0001 * x1192;
        let x1194 = s[16] * x321;
        let x1195 = 0.00025 * x1194;
        let x1196 = s[17] * x334;
        let x1198 = 0.00025 * x1196;
        let x1200 = x1193 + x1195;
        let x1201 = x1200 - x1198;
        let x1202 = 0.5 * x1201;
        let x1204 = x37 * 0.0008;
        let x1205 = x1204 - x1202;
        let x1206 = s[11] * x1154;
        let x1208 = 0.0001 * x1206;
        let x1210 = s[16] * x334;
        let x1211 = 0.00025 * x1210;
        let x1212 = s[17] * x321;
        let x1213 = 0.00025 * x1212;
        let x1214 = x1211 - x1208;
        let x1215 = x1213 + x1214;
        let x1216 = 0.5 * x1215;
        let x1218 = x30 * 0.0008;
        let x1219 = x1218 - x1216;
        let x1220 = s[10] * x334;
        let x1222 = 0.0001 * x1220;
        let x1226 = x1185 - x1222;
        let x1227 = x1226 - x1182;
        let x1228 = 0.5 * x1227;
        let x1229 = x1190 + x1228;
        let x1230 = s[10] * x321;
        let x1231 = 0.0001 * x1230;
        let x1232 = x1168 + x1231;
        let x1233 = x1164 + x1232;
        let x1234 = 0.5 * x1233;
        let x1235 = x15 * 0.0008;
        let x1236 = x1234 + x1235;
        let x1237 = s[10] * x1156;
        let x1238 = 0.0001 * x1237;
        let x1242 = x1238 - x1213;
        let x1243 = x1242 - x1211;
        let x1244 = 0.5 * x1243;
        let x1245 = x28 * 0.0008;
        let x1246 = x1244 + x1245;
        let x1247 = s[10] * x1154;
        let x1249 = 0.0001 * x1247;
        let x1251 = x1198 + x1249;
        let x1253 = x1195 - x1251;
        let x1254 = 0.5 * x1253;
        let x1255 = x35 * 0.0008;
        let x1256 = x1254 + x1255;
        let x1257 = 0.0001 * x1196;
        let x1259 = 0.00025 * x1247;
        let x1262 = 0.00025 * x1192;
        let x1264 = x1257 + x1259;
        let x1266 = x1262 - x1264;
        let x1267 = 0.5 * x1266;
        let x1268 = x1204 + x1267;
        let x1269 = 0.0001 * x1212;
        let x1271 = 0.00025 * x1237;
        let x1273 = 0.00025 * x1206;
        let x1275 = x1269 - x1271;
        let x1276 = x1275 - x1273;
        let x1277 = 0.5 * x1276;
        let x1278 = x1245 + x1277;
        let x1279 = 0.0001 * x1166;
        let x1280 = 0.00025 * x1230;
        let x1281 = 0.00025 * x1158;
        let x1283 = x1279 + x1280;
        let x1284 = x1281 + x1283;
        let x1285 = 0.5 * x1284;
        let x1286 = x16 * 0.0008;
        let x1287 = x1285 + x1286;
        let x1288 = 0.0001 * x1184;
        let x1290 = 0.00025 * x1220;
        let x1291 = 0.00025 * x1178;
        let x1293 = x1290 - x1288;
        let x1294 = x1293 - x1291;
        let x1295 = 0.5 * x1294;
        let x1296 = x41 * 0.0008;
        let x1297 = x1295 + x1296;
        let x1298 = 0.0001 * x1210;
        let x1300 = x1298 - x1273;
        let x1301 = x1300 - x1271;
        let x1302 = 0.5 * x1301;
        let x1303 = x1218 + x1302;
        let x1304 = 0.0001 * x1194;
        let x1306 = x1262 + x1304;
        let x1308 = x1259 - x1306;
        let x1309 = 0.5 * x1308;
        let x1310 = x1255 + x1309;
        let x1311 = 0.0001 * x1180;
        let x1314 = x1291 - x1311;
        let x1315 = x1314 - x1290;
        let x1316 = 0.5 * x1315;
        let x1317 = x1296 + x1316;
        let x1318 = 0.0001 * x1162;
        let x1320 = x1281 + x1318;
        let x1321 = x1280 + x1320;
        let x1322 = 0.5 * x1321;
        let x1323 = x17 * 0.0008;
        let x1324 = x1322 + x1323;
        let x1577 = s[13] * x422;
        let x1579 = 0.0001 * x1577;
        let x1581 = s[14] * x464;
        let x1583 = 0.006124999999999999 * x1581;
        let x1585 = s[15] * x500;
        let x1587 = 0.006124999999999999 * x1585;
        let x1589 = x1579 + x1583;
        let x1591 = x1587 + x1589;
        let x1593 = 0.5 * x1591;
        let x1595 = x59 * 0.016466666666666668;
        let x1596 = x1593 + x1595;
        let x1597 = s[13] * x350;
        let x1598 = 0.0001 * x1597;
        let x1599 = s[14] * x500;
        let x1601 = 0.006124999999999999 * x1599;
        let x1603 = s[15] * x464;
        let x1604 = 0.006124999999999999 * x1603;
        let x1605 = x1598 - x1601;
        let x1606 = x1604 + x1605;
        let x1607 = 0.5 * x1606;
        let x1609 = x87 * 0.016466666666666668;
        let x1610 = x1609 - x1607;
        let x1611 = s[13] * x500;
        let x1612 = 0.0001 * x1611;
        let x1613 = s[14] * x350;
        let x1614 = 0.006124999999999999 * x1613;
        let x1615 = s[15] * x422;
        let x1617 = 0.006124999999999999 * x1615;
        let x1619 = x1612 + x1614;
        let x1620 = x1619 - x1617;
        let x1621 = 0.5 * x1620;
        let x1623 = x81 * 0.016466666666666668;
        let x1624 = x1623 - x1621;
        let x1625 = s[13] * x464;
        let x1627 = 0.0001 * x1625;
        let x1629 = s[14] * x422;
        let x1630 = 0.006124999999999999 * x1629;
        let x1631 = s[15] * x350;
        let x1632 = 0.006124999999999999 * x1631;
        let x1633 = x1630 - x1627;
        let x1634 = x1632 + x1633;
        let x1635 = 0.5 * x1634;
        let x1637 = x74 * 0.016466666666666668;
        let x1638 = x1637 - x1635;
        let x1639 = s[12] * x422;
        let x1641 = 0.0001 * x1639;
        let x1645 = x1604 - x1641;
        let x1646 = x1645 - x1601;
        let x1647 = 0.5 * x1646;
        let x1648 = x1609 + x1647;
        let x1649 = s[12] * x350;
        let x1650 = 0.0001 * x1649;
        let x1651 = x1587 + x1650;
        let x1652 = x1583 + x1651;
        let x1653 = 0.5 * x1652;
        let x1654 = x60 * 0.016466666666666668;
        let x1655 = x1653 + x1654;
        let x1656 = s[12] * x500;
        let x1657 = 0.0001 * x1656;
        let x1661 = x1657 - x1632;
        let x1662 = x1661 - x1630;
        let x1663 = 0.5 * x1662;
        let x1664 = x72 * 0.016466666666666668;
        let x1665 = x1663 + x1664;
        let x1666 = s[12] * x464;
        let x1668 = 0.0001 * x1666;
        let x1670 = x1617 + x1668;
        let x1672 = x1614 - x1670;
        let x1673 = 0.5 * x1672;
        let x1674 = x79 * 0.016466666666666668;
        let x1675 = x1673 + x1674;
        let x1676 = 0.0001 * x1615;
        let x1678 = 0.006124999999999999 * x1666;
        let x1681 = 0.006124999999999999 * x1611;
        let x1683 = x1676 + x1678;
        let x1685 = x1681 - x1683;
        let x1686 = 0.5 * x1685;
        let x1687 = x1623 + x1686;
        let x1688 = 0.0001 * x1631;
        let x1690 = 0.006124999999999999 * x1656;
        let x1692 = 0.006124999999999999 * x1625;
        let x1694 = x1688 - x1690;
        let x1695 = x1694 - x1692;
        let x1696 = 0.5 * x1695;
        let x1697 = x1664 + x1696;
        let x1698 = 0.0001 * x1585;
        let x1699 = 0.006124999999999999 * x1649;
        let x1700 = 0.006124999999999999 * x1577;
        let x1702 = x1698 + x1699;
        let x1703 = x1700 + x1702;
        let x1704 = 0.5 * x1703;
        let x1705 = x61 * 0.016466666666666668;
        let x1706 = x1704 + x1705;
        let x1707 = 0.0001 * x1603;
        let x1709 = 0.006124999999999999 * x1639;
        let x1710 = 0.006124999999999999 * x1597;
        let x1712 = x1709 - x1707;
        let x1713 = x1712 - x1710;
        let x1714 = 0.5 * x1713;
        let x1715 = x85 * 0.016466666666666668;
        let x1716 = x1714 + x1715;
        let x1717 = 0.0001 * x1629;
        let x1719 = x1717 - x1692;
        let x1720 = x1719 - x1690;
        let x1721 = 0.5 * x1720;
        let x1722 = x1637 + x1721;
        let x1723 = 0.0001 * x1613;
        let x1725 = x1681 + x1723;
        let x1727 = x1678 - x1725;
        let x1728 = 0.5 * x1727;
        let x1729 = x1674 + x1728;
        let x1730 = 0.0001 * x1599;
        let x1733 = x1710 - x1730;
        let x1734 = x1733 - x1709;
        let x1735 = 0.5 * x1734;
        let x1736 = x1715 + x1735;
        let x1737 = 0.0001 * x1581;
        let x1739 = x1700 + x1737;
        let x1740 = x1699 + x1739;
        let x1741 = 0.5 * x1740;
        let x1742 = x62 * 0.016466666666666668;
        let x1743 = x1741 + x1742;
        phi[0] = x151;
        phi_q[0] = -1.0;
        phi_q[1] = x324;
        phi_q[2] = x336;
        phi[1] = x152;
        phi_q[3] = -1.0;
        phi_q[4] = x326;
        phi_q[5] = x328;
        phi_q[6] = x342;
        phi_q[7] = x344;
        phi[2] = x153;
        phi_q[8] = -1.0;
        phi_q[9] = x329;
        phi_q[10] = x326;
        phi_q[11] = x345;
        phi_q[12] = x342;
        phi[3] = x39;
        phi_q[13] = s[16];
        phi_q[14] = s[17];
        phi_q[15] = s[10];
        phi_q[16] = s[11];
        phi[4] = x47;
        phi_q[17] = x322;
        phi_q[18] = x335;
        phi_q[19] = s[17];
        phi_q[20] = s[16];
        phi[5] = x183;
        phi_q[21] = 1.0;
        phi_q[22] = x324;
        phi_q[23] = x336;
        phi_q[24] = -1.0;
        phi_q[25] = x377;
        phi_q[26] = x436;
        phi_q[27] = x474;
        phi_q[28] = x507;
        phi[6] = x185;
        phi_q[29] = 1.0;
        phi_q[30] = x326;
        phi_q[31] = x328;
        phi_q[32] = x342;
        phi_q[33] = x344;
        phi_q[34] = -1.0;
        phi_q[35] = x378;
        phi_q[36] = x432;
        phi_q[37] = x475;
        phi_q[38] = x508;
        phi[7] = x187;
        phi_q[39] = 1.0;
        phi_q[40] = x329;
        phi_q[41] = x326;
        phi_q[42] = x345;
        phi_q[43] = x342;
        phi_q[44] = -1.0;
        phi_q[45] = x379;
        phi_q[46] = x437;
        phi_q[47] = x476;
        phi_q[48] = x509;
        phi[8] = x281;
        phi_q[49] = -1.0;
        phi_q[50] = x415;
        phi_q[51] = x456;
        phi_q[52] = x477;
        phi_q[53] = x518;
        phi_q[54] = 1.0;
        phi[9] = x283;
        phi_q[55] = -1.0;
        phi_q[56] = x416;
        phi_q[57] = x457;
        phi_q[58] = x494;
        phi_q[59] = x519;
        phi_q[60] = 1.0;
        phi[10] = x285;
        phi_q[61] = -1.0;
        phi_q[62] = x402;
        phi_q[63] = x458;
        phi_q[64] = x486;
        phi_q[65] = x520;
        phi_q[66] = 1.0;
        phi[11] = x290;
        phi_q[67] = x421;
        phi_q[68] = x463;
        phi_q[69] = x499;
        phi_q[70] = x526;
        phi_q[71] = x537;
        phi_q[72] = x542;
        phi_q[73] = x545;
        phi_q[74] = x551;
        phi[12] = x128;
        phi_q[75] = s[19];
        phi_q[76] = s[21];
        phi_q[77] = s[20];
        phi_q[78] = s[18];
        phi[13] = x138;
        phi_q[79] = x531;
        phi_q[80] = s[19];
        phi_q[81] = x538;
        phi_q[82] = s[20];
        phi[14] = x295;
        phi_q[83] = 1.0;
        phi[15] = x297;
        phi_q[84] = 1.0;
        phi[16] = x139;
        phi_q[85] = s[20];
        phi_q[86] = s[18];
        phi_q[87] = s[19];
        phi_q[88] = s[21];
        phi[17] = x303;
        phi_q[89] = x333;
        phi_q[90] = x341;
        phi_q[91] = x347;
        phi_q[92] = x349;
        phi[18] = x306;
        phi_q[93] = s[10];
        phi_q[94] = s[11];
        phi_q[95] = s[16];
        phi_q[96] = s[17];
        phi[19] = x309;
        phi_q[97] = s[12];
        phi_q[98] = s[13];
        phi_q[99] = s[14];
        phi_q[100] = s[15];
        phi[20] = x312;
        phi_q[101] = s[18];
        phi_q[102] = s[20];
        phi_q[103] = s[21];
        phi_q[104] = s[19];
        mass[0] = 0.3;
        mass[1] = 0.3;
        mass[2] = 0.3;
        mass[3] = x1177;
        mass[4] = x1191;
        mass[5] = x1205;
        mass[6] = x1219;
        mass[7] = x1229;
        mass[8] = x1236;
        mass[9] = x1246;
        mass[10] = x1256;
        mass[11] = x1268;
        mass[12] = x1278;
        mass[13] = x1287;
        mass[14] = x1297;
        mass[15] = x1303;
        mass[16] = x1310;
        mass[17] = x1317;
        mass[18] = x1324;
        mass[19] = 0.6;
        mass[20] = 0.6;
        mass[21] = 0.6;
        mass[22] = x1596;
        mass[23] = x1610;
        mass[24] = x1624;
        mass[25] = x1638;
        mass[26] = x1648;
        mass[27] = x1655;
        mass[28] = x1665;
        mass[29] = x1675;
        mass[30] = x1687;
        mass[31] = x1697;
        mass[32] = x1706;
        mass[33] = x1716;
        mass[34] = x1722;
        mass[35] = x1729;
        mass[36] = x1736;
        mass[37] = x1743;
        mass[38] = 1.0;
        mass[39] = 1.0;
        mass[40] = 1.0;
    }
    #[inline(never)]
    fn eval_newton_part_1(
        q: &[f64; 21],
        qd: &[f64; 21],
        s: &[f64; 24],
        mass: &mut [f64; 57],
        force: &mut [f64; 21],
    ) {
        let x587 = q[5] * qd[4];
        let x588 = q[4] * qd[5];
        let x591 = q[6] * qd[3];
        let x592 = q[3] * qd[6];
        let x595 = q[6] * qd[4];
        let x596 = q[4] * qd[6];
        let x599 = q[5] * qd[3];
        let x600 = q[3] * qd[5];
        let x605 = q[6] * qd[5];
        let x606 = q[5] * qd[6];
        let x609 = q[4] * qd[3];
        let x610 = q[3] * qd[4];
        let x627 = q[12] * qd[11];
        let x628 = q[11] * qd[12];
        let x631 = q[13] * qd[10];
        let x632 = q[10] * qd[13];
        let x637 = q[13] * qd[11];
        let x638 = q[11] * qd[13];
        let x641 = q[12] * qd[10];
        let x642 = q[10] * qd[12];
        let x647 = q[13] * qd[12];
        let x648 = q[12] * qd[13];
        let x651 = q[11] * qd[10];
        let x652 = q[10] * qd[11];
        let x667 = q[19] * qd[18];
        let x668 = q[18] * qd[19];
        let x671 = q[20] * qd[17];
        let x672 = q[17] * qd[20];
        let x675 = q[20] * qd[18];
        let x676 = q[18] * qd[20];
        let x679 = q[19] * qd[17];
        let x680 = q[17] * qd[19];
        let x685 = q[20] * qd[19];
        let x686 = q[19] * qd[20];
        let x689 = q[18] * qd[17];
        let x690 = q[17] * qd[18];
        let x802 = 2.0 * qd[3];
        let x803 = 2.0 * qd[4];
        let x804 = 2.0 * qd[10];
        let x805 = 2.0 * qd[11];
        let x806 = 2.0 * qd[12];
        let x807 = 2.0 * qd[13];
        let x808 = 2.0 * qd[5];
        let x809 = 2.0 * qd[6];
        let x810 = 2.0 * qd[17];
        let x811 = 2.0 * qd[20];
        let x812 = 2.0 * qd[18];
        let x813 = 2.0 * qd[19];
        let x831 = qd[4] * qd[5];
        let x834 = qd[3] * qd[6];
        let x837 = qd[4] * qd[6];
        let x840 = qd[3] * qd[5];
        let x865 = qd[11] * qd[12];
        let x868 = qd[10] * qd[13];
        let x873 = qd[11] * qd[13];
        let x876 = qd[10] * qd[12];
        let x899 = qd[18] * qd[19];
        let x902 = qd[17] * qd[20];
        let x905 = qd[18] * qd[20];
        let x908 = qd[17] * qd[19];
        let x1046 = x610 - x609;
        let x1047 = x605 + x1046;
        let x1048 = x1047 - x606;
        let x1049 = 2.0 * x1048;
        let x1052 = x595 + x599;
        let x1054 = x600 - x1052;
        let x1055 = x596 + x1054;
        let x1056 = 2.0 * x1055;
        let x1059 = x587 - x591;
        let x1060 = x1059 - x588;
        let x1061 = x592 + x1060;
        let x1062 = 2.0 * x1061;
        let x1086 = 2.0 * x1049;
        let x1088 = 2.0 * x1056;
        let x1090 = 2.0 * x1062;
        let x1327 = x837 + x840;
        let x1329 = x840 - x1327;
        let x1330 = x837 + x1329;
        let x1331 = 2.0 * x1330;
        let x1334 = x831 - x834;
        let x1335 = x1334 - x831;
        let x1336 = x834 + x1335;
        let x1337 = 2.0 * x1336;
        let x1338 = 2.0 * x1331;
        let x1339 = 2.0 * x1337;
        let x1340 = x803 * x1086;
        let x1341 = 0.0001 * x1340;
        let x1342 = x808 * x1088;
        let x1343 = s[16] * x1338;
        let x1344 = x1342 + x1343;
        let x1345 = 0.00025 * x1344;
        let x1346 = x809 * x1090;
        let x1347 = s[17] * x1339;
        let x1348 = x1346 + x1347;
        let x1349 = 0.00025 * x1348;
        let x1350 = x1341 + x1345;
        let x1351 = x1349 + x1350;
        let x1352 = 0.5 * x1351;
        let x1354 = x802 * x1086;
        let x1355 = 0.0001 * x1354;
        let x1356 = x809 * x1088;
        let x1357 = s[17] * x1338;
        let x1358 = x1356 + x1357;
        let x1359 = 0.00025 * x1358;
        let x1361 = x808 * x1090;
        let x1362 = s[16] * x1339;
        let x1363 = x1361 + x1362;
        let x1364 = 0.00025 * x1363;
        let x1365 = x1355 - x1359;
        let x1366 = x1364 + x1365;
        let x1367 = 0.5 * x1366;
        let x1368 = x809 * x1086;
        let x1369 = 0.0001 * x1368;
        let x1370 = x802 * x1088;
        let x1371 = s[10] * x1338;
        let x1372 = x1370 + x1371;
        let x1373 = 0.00025 * x1372;
        let x1374 = x803 * x1090;
        let x1375 = s[11] * x1339;
        let x1376 = x1374 + x1375;
        let x1377 = 0.00025 * x1376;
        let x1379 = x1369 + x1373;
        let x1380 = x1379 - x1377;
        let x1381 = 0.5 * x1380;
        let x1382 = x808 * x1086;
        let x1383 = 0.0001 * x1382;
        let x1385 = x803 * x1088;
        let x1386 = s[11] * x1338;
        let x1387 = x1385 + x1386;
        let x1388 = 0.00025 * x1387;
        let x1389 = x802 * x1090;
        let x1390 = s[10] * x1339;
        let x1391 = x1389 + x1390;
        let x1392 = 0.00025 * x1391;
        let x1393 = x1388 - x1383;
        let x1394 = x1392 + x1393;
        let x1395 = 0.5 * x1394;
        let x1396 = qd[3] * qd[3];
        let x1397 = qd[4] * qd[4];
        let x1398 = qd[5] * qd[5];
        let x1399 = qd[6] * qd[6];
        let x1400 = x1396 + x1397;
        let x1401 = x1398 + x1400;
        let x1402 = x1399 + x1401;
        let x1404 = 0.00025 * x1342;
        let x1405 = 0.00025 * x1346;
        let x1406 = x1341 + x1404;
        let x1407 = x1405 + x1406;
        let x1408 = 0.5 * x1407;
        let x1409 = x1352 + x1408;
        let x1410 = q[3] * 0.0008;
        let x1411 = x1402 * x1410;
        let x1413 = x1409 - x1411;
        let x1420 = 0.00025 * x1356;
        let x1422 = 0.00025 * x1361;
        let x1424 = x1420 - x1355;
        let x1425 = x1424 - x1422;
        let x1426 = 0.5 * x1425;
        let x1428 = x1426 - x1367;
        let x1429 = q[4] * 0.0008;
        let x1430 = x1402 * x1429;
        let x1432 = x1428 - x1430;
        let x1438 = 0.00025 * x1370;
        let x1440 = 0.00025 * x1374;
        let x1441 = x1369 + x1438;
        let x1443 = x1440 - x1441;
        let x1444 = 0.5 * x1443;
        let x1446 = x1444 - x1381;
        let x1447 = q[5] * 0.0008;
        let x1448 = x1402 * x1447;
        let x1450 = x1446 - x1448;
        let x1454 = 0.00025 * x1385;
        let x1457 = 0.00025 * x1389;
        let x1459 = x1383 - x1454;
        let x1460 = x1459 - x1457;
        let x1461 = 0.5 * x1460;
        let x1463 = x1461 - x1395;
        let x1464 = q[6] * 0.0008;
        let x1465 = x1402 * x1464;
        let x1467 = x1463 - x1465;
        let x1470 = x652 - x651;
        let x1471 = x647 + x1470;
        let x1472 = x1471 - x648;
        let x1473 = 2.0 * x1472;
        let x1476 = x637 + x641;
        let x1478 = x642 - x1476;
        let x1479 = x638 + x1478;
        let x1480 = 2.0 * x1479;
        let x1483 = x627 - x631;
        let x1484 = x1483 - x628;
        let x1485 = x632 + x1484;
        let x1486 = 2.0 * x1485;
        let x1508 = 2.0 * x1473;
        let x1510 = 2.0 * x1480;
        let x1512 = 2.0 * x1486;
        let x1746 = x873 + x876;
        let x1748 = x876 - x1746;
        let x1749 = x873 + x1748;
        let x1750 = 2.0 * x1749;
        let x1753 = x865 - x868;
        let x1754 = x1753 - x865;
        let x1755 = x868 + x1754;
        let x1756 = 2.0 * x1755;
        let x1757 = 2.0 * x1750;
        let x1758 = 2.0 * x1756;
        let x1759 = x805 * x1508;
        let x1760 = 0.0001 * x1759;
        let x1761 = x806 * x1510;
        let x1762 = s[14] * x1757;
        let x1763 = x1761 + x1762;
        let x1764 = 0.006124999999999999 * x1763;
        let x1765 = x807 * x1512;
        let x1766 = s[15] * x1758;
        let x1767 = x1765 + x1766;
        let x1768 = 0.006124999999999999 * x1767;
        let x1769 = x1760 + x1764;
        let x1770 = x1768 + x1769;
        let x1771 = 0.5 * x1770;
        let x1773 = x804 * x1508;
        let x1774 = 0.0001 * x1773;
        let x1775 = x807 * x1510;
        let x1776 = s[15] * x1757;
        let x1777 = x1775 + x1776;
        let x1778 = 0.006124999999999999 * x1777;
        let x1780 = x806 * x1512;
        let x1781 = s[14] * x1758;
        let x1782 = x1780 + x1781;
        let x1783 = 0.006124999999999999 * x1782;
        let x1784 = x1774 - x1778;
        let x1785 = x1783 + x1784;
        let x1786 = 0.5 * x1785;
        let x1787 = x807 * x1508;
        let x1788 = 0.0001 * x1787;
        let x1789 = x804 * x1510;
        let x1790 = s[12] * x1757;
        let x1791 = x1789 + x1790;
        let x1792 = 0.006124999999999999 * x1791;
        let x1793 = x805 * x1512;
        let x1794 = s[13] * x1758;
        let x1795 = x1793 + x1794;
        let x1796 = 0.006124999999999999 * x1795;
        let x1798 = x1788 + x1792;
        let x1799 = x1798 - x1796;
        let x1800 = 0.5 * x1799;
        let x1801 = x806 * x1508;
        let x1802 = 0.0001 * x1801;
        let x1804 = x805 * x1510;
        let x1805 = s[13] * x1757;
        let x1806 = x1804 + x1805;
        let x1807 = 0.006124999999999999 * x1806;
        let x1808 = x804 * x1512;
        let x1809 = s[12] * x1758;
        let x1810 = x1808 + x1809;
        let x1811 = 0.006124999999999999 * x1810;
        let x1812 = x1807 - x1802;
        let x1813 = x1811 + x1812;
        let x1814 = 0.5 * x1813;
        let x1815 = qd[10] * qd[10];
        let x1816 = qd[11] * qd[11];
        let x1817 = qd[12] * qd[12];
        let x1818 = qd[13] * qd[13];
        let x1819 = x1815 + x1816;
        let x1820 = x1817 + x1819;
        let x1821 = x1818 + x1820;
        let x1823 = 0.006124999999999999 * x1761;
        let x1824 = 0.006124999999999999 * x1765;
        let x1825 = x1760 + x1823;
        let x1826 = x1824 + x1825;
        let x1827 = 0.5 * x1826;
        let x1828 = x1771 + x1827;
        let x1829 = q[10] * 0.016466666666666668;
        let x1830 = x1821 * x1829;
        let x1832 = x1828 - x1830;
        let x1839 = 0.006124999999999999 * x1775;
        let x1841 = 0.006124999999999999 * x1780;
        let x1843 = x1839 - x1774;
        let x1844 = x1843 - x1841;
        let x1845 = 0.5 * x1844;
        let x1847 = x1845 - x1786;
        let x1848 = q[11] * 0.016466666666666668;
        let x1849 = x1821 * x1848;
        let x1851 = x1847 - x1849;
        let x1857 = 0.006124999999999999 * x1789;
        let x1859 = 0.006124999999999999 * x1793;
        let x1860 = x1788 + x1857;
        let x1862 = x1859 - x1860;
        let x1863 = 0.5 * x1862;
        let x1865 = x1863 - x1800;
        let x1866 = q[12] * 0.016466666666666668;
        let x1867 = x1821 * x1866;
        let x1869 = x1865 - x1867;
        let x1873 = 0.006124999999999999 * x1804;
        let x1876 = 0.006124999999999999 * x1808;
        let x1878 = x1802 - x1873;
        let x1879 = x1878 - x1876;
        let x1880 = 0.5 * x1879;
        let x1882 = x1880 - x1814;
        let x1883 = q[13] * 0.016466666666666668;
        let x1884 = x1821 * x1883;
        let x1886 = x1882 - x1884;
        let x1889 = x690 - x689;
        let x1890 = x685 + x1889;
        let x1891 = x1890 - x686;
        let x1892 = 2.0 * x1891;
        let x1895 = x675 + x679;
        let x1897 = x680 - x1895;
        let x1898 = x676 + x1897;
        let x1899 = 2.0 * x1898;
        let x1902 = x667 - x671;
        let x1903 = x1902 - x668;
        let x1904 = x672 + x1903;
        let x1905 = 2.0 * x1904;
        let x1923 = 2.0 * x1892;
        let x1925 = 2.0 * x1899;
        let x1927 = 2.0 * x1905;
        let x1987 = 2.0 * s[20];
        let x1989 = 2.0 * s[21];
        let x1992 = s[20] * x1987;
        let x1994 = 0.001 * x1992;
        let x1996 = s[21] * x1989;
        let x1998 = 0.001 * x1996;
        let x2000 = s[19] * s[23];
        let x2002 = 0.001 * x2000;
        let x2004 = x1994 + x1998;
        let x2006 = x2002 + x2004;
        let x2008 = 0.5 * x2006;
        let x2010 = s[0] * 0.004;
        let x2011 = x2008 + x2010;
        let x2012 = s[20] * s[22];
        let x2013 = 0.001 * x2012;
        let x2014 = s[21] * s[23];
        let x2016 = 0.001 * x2014;
        let x2018 = s[19] * x1989;
        let x2019 = 0.001 * x2018;
        let x2020 = x2013 - x2016;
        let x2021 = x2019 + x2020;
        let x2022 = 0.5 * x2021;
        let x2024 = s[9] * 0.004;
        let x2025 = x2024 - x2022;
        let x2026 = s[20] * s[23];
        let x2027 = 0.001 * x2026;
        let x2028 = s[21] * s[22];
        let x2029 = 0.001 * x2028;
        let x2030 = s[19] * x1987;
        let x2032 = 0.001 * x2030;
        let x2034 = x2027 + x2029;
        let x2035 = x2034 - x2032;
        let x2036 = 0.5 * x2035;
        let x2038 = s[7] * 0.004;
        let x2039 = x2038 - x2036;
        let x2040 = s[20] * x1989;
        let x2042 = 0.001 * x2040;
        let x2044 = s[21] * x1987;
        let x2045 = 0.001 * x2044;
        let x2046 = s[19] * s[22];
        let x2047 = 0.001 * x2046;
        let x2048 = x2045 - x2042;
        let x2049 = x2047 + x2048;
        let x2050 = 0.5 * x2049;
        let x2052 = s[5] * 0.004;
        let x2053 = x2052 - x2050;
        let x2054 = s[18] * x1987;
        let x2056 = 0.001 * x2054;
        let x2060 = x2019 - x2056;
        let x2061 = x2060 - x2016;
        let x2062 = 0.5 * x2061;
        let x2063 = x2024 + x2062;
        let x2064 = s[18] * s[22];
        let x2065 = 0.001 * x2064;
        let x2066 = x2002 + x2065;
        let x2067 = x1998 + x2066;
        let x2068 = 0.5 * x2067;
        let x2069 = s[1] * 0.004;
        let x2070 = x2068 + x2069;
        let x2071 = s[18] * s[23];
        let x2072 = 0.001 * x2071;
        let x2076 = x2072 - x2047;
        let x2077 = x2076 - x2045;
        let x2078 = 0.5 * x2077;
        let x2079 = s[4] * 0.004;
        let x2080 = x2078 + x2079;
        let x2081 = s[18] * x1989;
        let x2083 = 0.001 * x2081;
        let x2085 = x2032 + x2083;
        let x2087 = x2029 - x2085;
        let x2088 = 0.5 * x2087;
        let x2089 = s[6] * 0.004;
        let x2090 = x2088 + x2089;
        let x2093 = x2027 - x2085;
        let x2094 = 0.5 * x2093;
        let x2095 = x2038 + x2094;
        let x2098 = x2047 - x2072;
        let x2099 = x2098 - x2042;
        let x2100 = 0.5 * x2099;
        let x2101 = x2079 + x2100;
        let x2102 = x1994 + x2066;
        let x2103 = 0.5 * x2102;
        let x2104 = s[2] * 0.004;
        let x2105 = x2103 + x2104;
        let x2107 = x2056 - x2019;
        let x2108 = x2107 - x2013;
        let x2109 = 0.5 * x2108;
        let x2110 = s[8] * 0.004;
        let x2111 = x2109 + x2110;
        let x2112 = x2048 - x2072;
        let x2113 = 0.5 * x2112;
        let x2114 = x2052 + x2113;
        let x2117 = x2083 - x2034;
        let x2118 = 0.5 * x2117;
        let x2119 = x2089 + x2118;
        let x2120 = x2020 - x2056;
        let x2121 = 0.5 * x2120;
        let x2122 = x2110 + x2121;
        let x2123 = x2004 + x2065;
        let x2124 = 0.5 * x2123;
        let x2125 = s[3] * 0.004;
        let x2126 = x2124 + x2125;
        let x2129 = x905 + x908;
        let x2131 = x908 - x2129;
        let x2132 = x905 + x2131;
        let x2133 = 2.0 * x2132;
        let x2136 = x899 - x902;
        let x2137 = x2136 - x899;
        let x2138 = x902 + x2137;
        let x2139 = 2.0 * x2138;
        let x2140 = 2.0 * x2133;
        let x2141 = 2.0 * x2139;
        let x2142 = x812 * x1923;
        let x2143 = 0.001 * x2142;
        let x2144 = x813 * x1925;
        let x2145 = s[21] * x2140;
        let x2146 = x2144 + x2145;
        let x2147 = 0.001 * x2146;
        let x2148 = x811 * x1927;
        let x2149 = s[19] * x2141;
        let x2150 = x2148 + x2149;
        let x2151 = 0.001 * x2150;
        let x2152 = x2143 + x2147;
        let x2153 = x2151 + x2152;
        let x2154 = 0.5 * x2153;
        let x2156 = x810 * x1923;
        let x2157 = 0.001 * x2156;
        let x2158 = x811 * x1925;
        let x2159 = s[19] * x2140;
        let x2160 = x2158 + x2159;
        let x2161 = 0.001 * x2160;
        let x2163 = x813 * x1927;
        let x2164 = s[21] * x2141;
        let x2165 = x2163 + x2164;
        let x2166 = 0.001 * x2165;
        let x2167 = x2157 - x2161;
        let x2168 = x2166 + x2167;
        let x2169 = 0.5 * x2168;
        let x2170 = x811 * x1923;
        let x2171 = 0.001 * x2170;
        let x2172 = x810 * x1925;
        let x2173 = s[18] * x2140;
        let x2174 = x2172 + x2173;
        let x2175 = 0.001 * x2174;
        let x2176 = x812 * x1927;
        let x2177 = s[20] * x2141;
        let x2178 = x2176 + x2177;
        let x2179 = 0.001 * x2178;
        let x2181 = x2171 + x2175;
        let x2182 = x2181 - x2179;
        let x2183 = 0.5 * x2182;
        let x2184 = x813 * x1923;
        let x2185 = 0.001 * x2184;
        let x2187 = x812 * x1925;
        let x2188 = s[20] * x2140;
        let x2189 = x2187 + x2188;
        let x2190 = 0.001 * x2189;
        let x2191 = x810 * x1927;
        let x2192 = s[18] * x2141;
        let x2193 = x2191 + x2192;
        let x2194 = 0.001 * x2193;
        let x2195 = x2190 - x2185;
        let x2196 = x2194 + x2195;
        let x2197 = 0.5 * x2196;
        let x2198 = qd[17] * qd[17];
        let x2199 = qd[18] * qd[18];
        let x2200 = qd[19] * qd[19];
        let x2201 = qd[20] * qd[20];
        let x2202 = x2198 + x2199;
        let x2203 = x2200 + x2202;
        let x2204 = x2201 + x2203;
        let x2206 = 0.001 * x2144;
        let x2207 = 0.001 * x2148;
        let x2208 = x2143 + x2206;
        let x2209 = x2207 + x2208;
        let x2210 = 0.5 * x2209;
        let x2211 = x2154 + x2210;
        let x2212 = q[17] * 0.004;
        let x2213 = x2204 * x2212;
        let x2215 = x2211 - x2213;
        let x2222 = 0.001 * x2158;
        let x2224 = 0.001 * x2163;
        let x2226 = x2222 - x2157;
        let x2227 = x2226 - x2224;
        let x2228 = 0.5 * x2227;
        let x2230 = x2228 - x2169;
        let x2231 = q[18] * 0.004;
        let x2232 = x2204 * x2231;
        let x2234 = x2230 - x2232;
        let x2240 = 0.001 * x2172;
        let x2242 = 0.001 * x2176;
        let x2243 = x2171 + x2240;
        let x2245 = x2242 - x2243;
        let x2246 = 0.5 * x2245;
        let x2248 = x2246 - x2183;
        let x2249 = q[19] * 0.004;
        let x2250 = x2204 * x2249;
        let x2252 = x2248 - x2250;
        let x2256 = 0.001 * x2187;
        let x2259 = 0.001 * x2191;
        let x2261 = x2185 - x2256;
        let x2262 = x2261 - x2259;
        let x2263 = 0.5 * x2262;
        let x2265 = x2263 - x2197;
        let x2266 = q[20] * 0.004;
        let x2267 = x2204 * x2266;
        let x2269 = x2265 - x2267;
        mass[41] = x2011;
        mass[42] = x2025;
        mass[43] = x2039;
        mass[44] = x2053;
        mass[45] = x2063;
        mass[46] = x2070;
        mass[47] = x2080;
        mass[48] = x2090;
        mass[49] = x2095;
        mass[50] = x2101;
        mass[51] = x2105;
        mass[52] = x2111;
        mass[53] = x2114;
        mass[54] = x2119;
        mass[55] = x2122;
        mass[56] = x2126;
        force[0] = 0.0;
        force[1] = -2.943;
        force[2] = 0.0;
        force[3] = x1413;
        force[4] = x1432;
        force[5] = x1450;
        force[6] = x1467;
        force[7] = 0.0;
        force[8] = -5.886;
        force[9] = 0.0;
        force[10] = x1832;
        force[11] = x1851;
        force[12] = x1869;
        force[13] = x1886;
        force[14] = 0.0;
        force[15] = -9.81;
        force[16] = 0.0;
        force[17] = x2215;
        force[18] = x2234;
        force[19] = x2252;
        force[20] = x2269;
    }
}
/// `slider_crank` with the `exact` formulation.
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
