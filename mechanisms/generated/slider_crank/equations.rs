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
    BodyInfo, Entry, Formulation, JointInfo, JointKind, KinematicOutputs, Mechanism,
    MechanismInfo, NewtonOutputs, Origin, PlatformInfo, Reduction, Substitution, Rotation,
};
use symbody_runtime::parameters::{ParameterError, RunTimeParameters};
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
pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
    let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = k;
    potential_into_part_0(q, out);
}
#[inline(never)]
fn potential_into_part_0(q: &[f64; 21], out: &mut [f64; 1]) {
    let x1051 = q[1] * 2.943;
    let x1054 = q[8] * 5.886;
    let x1056 = q[15] * 9.81;
    let x1057 = x1051 + x1054;
    let x1058 = x1056 + x1057;
    out[0] = x1058;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 21] = qd.try_into().expect("qd must have n_coords entries");
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
pub const N_K: usize = 3;
/// `setup` at the file's parameter values: what the types without parameters read.
pub static K: [f64; 3] = [0.0001f64, 0.0008f64, 0.016466666666666664f64];
/// The values the per-step functions read (`k`), from the run-time parameters `p`.
pub fn setup(p: &[f64], k: &mut [f64]) {
    let p: &[f64; 1] = p.try_into().expect("p must have 1 entries");
    let k: &mut [f64; 3] = k.try_into().expect("k must have 3 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 1], k: &mut [f64; 3]) {
    let x1164 = p[0] + 0.00025;
    let x1165 = 0.00025 + x1164;
    let x1168 = x1165 * 4.0;
    let x1170 = x1168 * 0.3333333333333333;
    let x1588 = p[0] + 0.006124999999999999;
    let x1589 = 0.006124999999999999 + x1588;
    let x1590 = 4.0 * x1589;
    let x1591 = 0.3333333333333333 * x1590;
    k[0] = p[0];
    k[1] = x1170;
    k[2] = x1591;
}
/// The parameters the generated code takes at run time: the file's `[parameters]`
/// entries that reach only masses, inertias and springs' constants (the others are set on
/// the file).
pub static PARAMETERS: [&str; 1] = ["rod"];
/// Their values in the file.
pub static PARAMETER_VALUES: [f64; 1] = [0.0001f64];
static OTHER_PARAMETERS: [&str; 11] = [
    "cx",
    "cy",
    "dx",
    "dy",
    "dz",
    "e",
    "h",
    "len",
    "r",
    "s0",
    "theta0",
];
static BODY_NAMES: [&str; 3] = ["crank", "rod", "slider"];
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
    out[0] = 0.3;
    out[1] = p[0];
    out[2] = 0.00025;
    out[3] = 0.00025;
    out[4] = 0.6;
    out[5] = p[0];
    out[6] = 0.006124999999999999;
    out[7] = 0.006124999999999999;
    out[8] = 1.0;
    out[9] = 0.001;
    out[10] = 0.001;
    out[11] = 0.001;
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
fn at_parameters_reduced(
    set: &[(&str, f64)],
) -> Result<symbody_runtime::registry::Built, ParameterError> {
    let p = Parameters::at(set)?;
    Ok(
        vec![
            (Formulation::Exact, Box::new(reduced::ExactAt::new(& p)) as Box < dyn
            Mechanism + Sync >)
        ],
    )
}
/// This mechanism at other values of its run-time parameters, for the registries.
pub static RUN_TIME_ENTRY: symbody_runtime::registry::RunTime = symbody_runtime::registry::RunTime {
    parameters: &RUN_TIME,
    build: at_parameters,
    build_reduced: Some(at_parameters_reduced),
};
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
    /// Row and column of each ∂Q/∂q nonzero.
    pub static FORCE_Q_ROWS: [u32; 0usize] = [];
    pub static FORCE_Q_COLS: [u32; 0usize] = [];
    /// Row and column of each ∂Q/∂q̇ nonzero.
    pub static FORCE_QD_ROWS: [u32; 0usize] = [];
    pub static FORCE_QD_COLS: [u32; 0usize] = [];
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
        let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
        let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 21] = qd.try_into().expect("qd must have n_coords entries");
        let _: &mut [f64; 0] = dq.try_into().expect("dq must have 0 entries");
        let _: &mut [f64; 0] = dqd.try_into().expect("dqd must have 0 entries");
        let _ = k;
        let _ = q;
        let _ = qd;
        let _ = t;
    }
    /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
    pub fn mass(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
        let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 57] = out.try_into().expect("out must have 57 entries");
        mass_part_0(k, q, out);
    }
    #[inline(never)]
    fn mass_part_0(k: &[f64; 3], q: &[f64; 21], out: &mut [f64; 57]) {
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
        let x1172 = 2.0 * x319;
        let x1174 = 2.0 * x320;
        let x1176 = x314 * x334;
        let x1180 = x319 * x1172;
        let x1182 = 0.00025 * x1180;
        let x1184 = x320 * x1174;
        let x1186 = 0.00025 * x1184;
        let x1196 = x314 * x321;
        let x1198 = x319 * x1174;
        let x1200 = 0.00025 * x1198;
        let x1202 = x320 * x1172;
        let x1203 = 0.00025 * x1202;
        let x1210 = x314 * x1174;
        let x1212 = x319 * x321;
        let x1213 = 0.00025 * x1212;
        let x1214 = x320 * x334;
        let x1216 = 0.00025 * x1214;
        let x1224 = x314 * x1172;
        let x1228 = x319 * x334;
        let x1229 = 0.00025 * x1228;
        let x1230 = x320 * x321;
        let x1231 = 0.00025 * x1230;
        let x1238 = x313 * x334;
        let x1248 = x313 * x321;
        let x1255 = x313 * x1174;
        let x1265 = x313 * x1172;
        let x1277 = 0.00025 * x1265;
        let x1280 = 0.00025 * x1210;
        let x1289 = 0.00025 * x1255;
        let x1291 = 0.00025 * x1224;
        let x1298 = 0.00025 * x1248;
        let x1299 = 0.00025 * x1176;
        let x1308 = 0.00025 * x1238;
        let x1309 = 0.00025 * x1196;
        let x1596 = x316 * x422;
        let x1600 = x317 * x464;
        let x1602 = 0.006124999999999999 * x1600;
        let x1604 = x318 * x500;
        let x1606 = 0.006124999999999999 * x1604;
        let x1616 = x316 * x350;
        let x1618 = x317 * x500;
        let x1620 = 0.006124999999999999 * x1618;
        let x1622 = x318 * x464;
        let x1623 = 0.006124999999999999 * x1622;
        let x1630 = x316 * x500;
        let x1632 = x317 * x350;
        let x1633 = 0.006124999999999999 * x1632;
        let x1634 = x318 * x422;
        let x1636 = 0.006124999999999999 * x1634;
        let x1644 = x316 * x464;
        let x1648 = x317 * x422;
        let x1649 = 0.006124999999999999 * x1648;
        let x1650 = x318 * x350;
        let x1651 = 0.006124999999999999 * x1650;
        let x1658 = x315 * x422;
        let x1668 = x315 * x350;
        let x1675 = x315 * x500;
        let x1685 = x315 * x464;
        let x1697 = 0.006124999999999999 * x1685;
        let x1700 = 0.006124999999999999 * x1630;
        let x1709 = 0.006124999999999999 * x1675;
        let x1711 = 0.006124999999999999 * x1644;
        let x1718 = 0.006124999999999999 * x1668;
        let x1719 = 0.006124999999999999 * x1596;
        let x1728 = 0.006124999999999999 * x1658;
        let x1729 = 0.006124999999999999 * x1616;
        let x2006 = 2.0 * x527;
        let x2008 = 2.0 * x528;
        let x2011 = x527 * x2006;
        let x2013 = 0.001 * x2011;
        let x2015 = x528 * x2008;
        let x2017 = 0.001 * x2015;
        let x2019 = x355 * x546;
        let x2021 = 0.001 * x2019;
        let x2023 = x2013 + x2017;
        let x2025 = x2021 + x2023;
        let x2027 = 0.5 * x2025;
        let x2029 = x103 * 0.004;
        let x2030 = x2027 + x2029;
        let x2031 = x527 * x529;
        let x2032 = 0.001 * x2031;
        let x2033 = x528 * x546;
        let x2035 = 0.001 * x2033;
        let x2037 = x355 * x2008;
        let x2038 = 0.001 * x2037;
        let x2039 = x2032 - x2035;
        let x2040 = x2038 + x2039;
        let x2041 = 0.5 * x2040;
        let x2043 = x131 * 0.004;
        let x2044 = x2043 - x2041;
        let x2045 = x527 * x546;
        let x2046 = 0.001 * x2045;
        let x2047 = x528 * x529;
        let x2048 = 0.001 * x2047;
        let x2049 = x355 * x2006;
        let x2051 = 0.001 * x2049;
        let x2053 = x2046 + x2048;
        let x2054 = x2053 - x2051;
        let x2055 = 0.5 * x2054;
        let x2057 = x125 * 0.004;
        let x2058 = x2057 - x2055;
        let x2059 = x527 * x2008;
        let x2061 = 0.001 * x2059;
        let x2063 = x528 * x2006;
        let x2064 = 0.001 * x2063;
        let x2065 = x355 * x529;
        let x2066 = 0.001 * x2065;
        let x2067 = x2064 - x2061;
        let x2068 = x2066 + x2067;
        let x2069 = 0.5 * x2068;
        let x2071 = x118 * 0.004;
        let x2072 = x2071 - x2069;
        let x2073 = x354 * x2006;
        let x2075 = 0.001 * x2073;
        let x2079 = x2038 - x2075;
        let x2080 = x2079 - x2035;
        let x2081 = 0.5 * x2080;
        let x2082 = x2043 + x2081;
        let x2083 = x354 * x529;
        let x2084 = 0.001 * x2083;
        let x2085 = x2021 + x2084;
        let x2086 = x2017 + x2085;
        let x2087 = 0.5 * x2086;
        let x2088 = x104 * 0.004;
        let x2089 = x2087 + x2088;
        let x2090 = x354 * x546;
        let x2091 = 0.001 * x2090;
        let x2095 = x2091 - x2066;
        let x2096 = x2095 - x2064;
        let x2097 = 0.5 * x2096;
        let x2098 = x116 * 0.004;
        let x2099 = x2097 + x2098;
        let x2100 = x354 * x2008;
        let x2102 = 0.001 * x2100;
        let x2104 = x2051 + x2102;
        let x2106 = x2048 - x2104;
        let x2107 = 0.5 * x2106;
        let x2108 = x123 * 0.004;
        let x2109 = x2107 + x2108;
        let x2112 = x2046 - x2104;
        let x2113 = 0.5 * x2112;
        let x2114 = x2057 + x2113;
        let x2117 = x2066 - x2091;
        let x2118 = x2117 - x2061;
        let x2119 = 0.5 * x2118;
        let x2120 = x2098 + x2119;
        let x2121 = x2013 + x2085;
        let x2122 = 0.5 * x2121;
        let x2123 = x105 * 0.004;
        let x2124 = x2122 + x2123;
        let x2126 = x2075 - x2038;
        let x2127 = x2126 - x2032;
        let x2128 = 0.5 * x2127;
        let x2129 = x129 * 0.004;
        let x2130 = x2128 + x2129;
        let x2131 = x2067 - x2091;
        let x2132 = 0.5 * x2131;
        let x2133 = x2071 + x2132;
        let x2136 = x2102 - x2053;
        let x2137 = 0.5 * x2136;
        let x2138 = x2108 + x2137;
        let x2139 = x2039 - x2075;
        let x2140 = 0.5 * x2139;
        let x2141 = x2129 + x2140;
        let x2142 = x2023 + x2084;
        let x2143 = 0.5 * x2142;
        let x2144 = x106 * 0.004;
        let x2145 = x2143 + x2144;
        let x2290 = x1176 * k[0];
        let x2291 = x1182 + x2290;
        let x2292 = x1186 + x2291;
        let x2293 = 0.5 * x2292;
        let x2294 = x14 * k[1];
        let x2295 = x2293 + x2294;
        let x2296 = x1196 * k[0];
        let x2297 = x2296 - x1200;
        let x2298 = x1203 + x2297;
        let x2299 = 0.5 * x2298;
        let x2301 = x43 * k[1];
        let x2302 = x2301 - x2299;
        let x2303 = x1210 * k[0];
        let x2304 = x1213 + x2303;
        let x2305 = x2304 - x1216;
        let x2306 = 0.5 * x2305;
        let x2308 = x37 * k[1];
        let x2309 = x2308 - x2306;
        let x2310 = x1224 * k[0];
        let x2312 = x1229 - x2310;
        let x2313 = x1231 + x2312;
        let x2314 = 0.5 * x2313;
        let x2316 = x30 * k[1];
        let x2317 = x2316 - x2314;
        let x2318 = x1238 * k[0];
        let x2320 = x1203 - x2318;
        let x2321 = x2320 - x1200;
        let x2322 = 0.5 * x2321;
        let x2323 = x2301 + x2322;
        let x2324 = x1248 * k[0];
        let x2325 = x1186 + x2324;
        let x2326 = x1182 + x2325;
        let x2327 = 0.5 * x2326;
        let x2328 = x15 * k[1];
        let x2329 = x2327 + x2328;
        let x2330 = x1255 * k[0];
        let x2331 = x2330 - x1231;
        let x2332 = x2331 - x1229;
        let x2333 = 0.5 * x2332;
        let x2334 = x28 * k[1];
        let x2335 = x2333 + x2334;
        let x2336 = x1265 * k[0];
        let x2337 = x1216 + x2336;
        let x2339 = x1213 - x2337;
        let x2340 = 0.5 * x2339;
        let x2341 = x35 * k[1];
        let x2342 = x2340 + x2341;
        let x2343 = x1214 * k[0];
        let x2344 = x1277 + x2343;
        let x2346 = x1280 - x2344;
        let x2347 = 0.5 * x2346;
        let x2348 = x2308 + x2347;
        let x2349 = x1230 * k[0];
        let x2350 = x2349 - x1289;
        let x2351 = x2350 - x1291;
        let x2352 = 0.5 * x2351;
        let x2353 = x2334 + x2352;
        let x2354 = x1184 * k[0];
        let x2355 = x1298 + x2354;
        let x2356 = x1299 + x2355;
        let x2357 = 0.5 * x2356;
        let x2358 = x16 * k[1];
        let x2359 = x2357 + x2358;
        let x2360 = x1202 * k[0];
        let x2362 = x1308 - x2360;
        let x2363 = x2362 - x1309;
        let x2364 = 0.5 * x2363;
        let x2365 = x41 * k[1];
        let x2366 = x2364 + x2365;
        let x2367 = x1228 * k[0];
        let x2368 = x2367 - x1291;
        let x2369 = x2368 - x1289;
        let x2370 = 0.5 * x2369;
        let x2371 = x2316 + x2370;
        let x2372 = x1212 * k[0];
        let x2373 = x1280 + x2372;
        let x2375 = x1277 - x2373;
        let x2376 = 0.5 * x2375;
        let x2377 = x2341 + x2376;
        let x2378 = x1198 * k[0];
        let x2380 = x1309 - x2378;
        let x2381 = x2380 - x1308;
        let x2382 = 0.5 * x2381;
        let x2383 = x2365 + x2382;
        let x2384 = x1180 * k[0];
        let x2385 = x1299 + x2384;
        let x2386 = x1298 + x2385;
        let x2387 = 0.5 * x2386;
        let x2388 = x17 * k[1];
        let x2389 = x2387 + x2388;
        let x2445 = x1596 * k[0];
        let x2446 = x1602 + x2445;
        let x2447 = x1606 + x2446;
        let x2448 = 0.5 * x2447;
        let x2449 = x59 * k[2];
        let x2450 = x2448 + x2449;
        let x2451 = x1616 * k[0];
        let x2452 = x2451 - x1620;
        let x2453 = x1623 + x2452;
        let x2454 = 0.5 * x2453;
        let x2456 = x87 * k[2];
        let x2457 = x2456 - x2454;
        let x2458 = x1630 * k[0];
        let x2459 = x1633 + x2458;
        let x2460 = x2459 - x1636;
        let x2461 = 0.5 * x2460;
        let x2463 = x81 * k[2];
        let x2464 = x2463 - x2461;
        let x2465 = x1644 * k[0];
        let x2467 = x1649 - x2465;
        let x2468 = x1651 + x2467;
        let x2469 = 0.5 * x2468;
        let x2471 = x74 * k[2];
        let x2472 = x2471 - x2469;
        let x2473 = x1658 * k[0];
        let x2475 = x1623 - x2473;
        let x2476 = x2475 - x1620;
        let x2477 = 0.5 * x2476;
        let x2478 = x2456 + x2477;
        let x2479 = x1668 * k[0];
        let x2480 = x1606 + x2479;
        let x2481 = x1602 + x2480;
        let x2482 = 0.5 * x2481;
        let x2483 = x60 * k[2];
        let x2484 = x2482 + x2483;
        let x2485 = x1675 * k[0];
        let x2486 = x2485 - x1651;
        let x2487 = x2486 - x1649;
        let x2488 = 0.5 * x2487;
        let x2489 = x72 * k[2];
        let x2490 = x2488 + x2489;
        let x2491 = x1685 * k[0];
        let x2492 = x1636 + x2491;
        let x2494 = x1633 - x2492;
        let x2495 = 0.5 * x2494;
        let x2496 = x79 * k[2];
        let x2497 = x2495 + x2496;
        let x2498 = x1634 * k[0];
        let x2499 = x1697 + x2498;
        let x2501 = x1700 - x2499;
        let x2502 = 0.5 * x2501;
        let x2503 = x2463 + x2502;
        let x2504 = x1650 * k[0];
        let x2505 = x2504 - x1709;
        let x2506 = x2505 - x1711;
        let x2507 = 0.5 * x2506;
        let x2508 = x2489 + x2507;
        let x2509 = x1604 * k[0];
        let x2510 = x1718 + x2509;
        let x2511 = x1719 + x2510;
        let x2512 = 0.5 * x2511;
        let x2513 = x61 * k[2];
        let x2514 = x2512 + x2513;
        let x2515 = x1622 * k[0];
        let x2517 = x1728 - x2515;
        let x2518 = x2517 - x1729;
        let x2519 = 0.5 * x2518;
        let x2520 = x85 * k[2];
        let x2521 = x2519 + x2520;
        let x2522 = x1648 * k[0];
        let x2523 = x2522 - x1711;
        let x2524 = x2523 - x1709;
        let x2525 = 0.5 * x2524;
        let x2526 = x2471 + x2525;
        let x2527 = x1632 * k[0];
        let x2528 = x1700 + x2527;
        let x2530 = x1697 - x2528;
        let x2531 = 0.5 * x2530;
        let x2532 = x2496 + x2531;
        let x2533 = x1618 * k[0];
        let x2535 = x1729 - x2533;
        let x2536 = x2535 - x1728;
        let x2537 = 0.5 * x2536;
        let x2538 = x2520 + x2537;
        let x2539 = x1600 * k[0];
        let x2540 = x1719 + x2539;
        let x2541 = x1718 + x2540;
        let x2542 = 0.5 * x2541;
        let x2543 = x62 * k[2];
        let x2544 = x2542 + x2543;
        out[0] = 0.3;
        out[1] = 0.3;
        out[2] = 0.3;
        out[3] = x2295;
        out[4] = x2302;
        out[5] = x2309;
        out[6] = x2317;
        out[7] = x2323;
        out[8] = x2329;
        out[9] = x2335;
        out[10] = x2342;
        out[11] = x2348;
        out[12] = x2353;
        out[13] = x2359;
        out[14] = x2366;
        out[15] = x2371;
        out[16] = x2377;
        out[17] = x2383;
        out[18] = x2389;
        out[19] = 0.6;
        out[20] = 0.6;
        out[21] = 0.6;
        out[22] = x2450;
        out[23] = x2457;
        out[24] = x2464;
        out[25] = x2472;
        out[26] = x2478;
        out[27] = x2484;
        out[28] = x2490;
        out[29] = x2497;
        out[30] = x2503;
        out[31] = x2508;
        out[32] = x2514;
        out[33] = x2521;
        out[34] = x2526;
        out[35] = x2532;
        out[36] = x2538;
        out[37] = x2544;
        out[38] = 1.0;
        out[39] = 1.0;
        out[40] = 1.0;
        out[41] = x2030;
        out[42] = x2044;
        out[43] = x2058;
        out[44] = x2072;
        out[45] = x2082;
        out[46] = x2089;
        out[47] = x2099;
        out[48] = x2109;
        out[49] = x2114;
        out[50] = x2120;
        out[51] = x2124;
        out[52] = x2130;
        out[53] = x2133;
        out[54] = x2138;
        out[55] = x2141;
        out[56] = x2145;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
        let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 21] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
        let _ = t;
        force_part_0(k, q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(k: &[f64; 3], q: &[f64; 21], qd: &[f64; 21], out: &mut [f64; 21]) {
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
        let x1062 = x610 - x609;
        let x1063 = x605 + x1062;
        let x1064 = x1063 - x606;
        let x1065 = 2.0 * x1064;
        let x1068 = x595 + x599;
        let x1070 = x600 - x1068;
        let x1071 = x596 + x1070;
        let x1072 = 2.0 * x1071;
        let x1075 = x587 - x591;
        let x1076 = x1075 - x588;
        let x1077 = x592 + x1076;
        let x1078 = 2.0 * x1077;
        let x1099 = 2.0 * x1065;
        let x1101 = 2.0 * x1072;
        let x1103 = 2.0 * x1078;
        let x1345 = x837 + x840;
        let x1347 = x840 - x1345;
        let x1348 = x837 + x1347;
        let x1349 = 2.0 * x1348;
        let x1352 = x831 - x834;
        let x1353 = x1352 - x831;
        let x1354 = x834 + x1353;
        let x1355 = 2.0 * x1354;
        let x1356 = 2.0 * x1349;
        let x1357 = 2.0 * x1355;
        let x1358 = x803 * x1099;
        let x1360 = x808 * x1101;
        let x1361 = x319 * x1356;
        let x1362 = x1360 + x1361;
        let x1363 = 0.00025 * x1362;
        let x1364 = x809 * x1103;
        let x1365 = x320 * x1357;
        let x1366 = x1364 + x1365;
        let x1367 = 0.00025 * x1366;
        let x1372 = x802 * x1099;
        let x1374 = x809 * x1101;
        let x1375 = x320 * x1356;
        let x1376 = x1374 + x1375;
        let x1377 = 0.00025 * x1376;
        let x1379 = x808 * x1103;
        let x1380 = x319 * x1357;
        let x1381 = x1379 + x1380;
        let x1382 = 0.00025 * x1381;
        let x1386 = x809 * x1099;
        let x1388 = x802 * x1101;
        let x1389 = x313 * x1356;
        let x1390 = x1388 + x1389;
        let x1391 = 0.00025 * x1390;
        let x1392 = x803 * x1103;
        let x1393 = x314 * x1357;
        let x1394 = x1392 + x1393;
        let x1395 = 0.00025 * x1394;
        let x1400 = x808 * x1099;
        let x1403 = x803 * x1101;
        let x1404 = x314 * x1356;
        let x1405 = x1403 + x1404;
        let x1406 = 0.00025 * x1405;
        let x1407 = x802 * x1103;
        let x1408 = x313 * x1357;
        let x1409 = x1407 + x1408;
        let x1410 = 0.00025 * x1409;
        let x1414 = qd[3] * qd[3];
        let x1415 = qd[4] * qd[4];
        let x1416 = qd[5] * qd[5];
        let x1417 = qd[6] * qd[6];
        let x1418 = x1414 + x1415;
        let x1419 = x1416 + x1418;
        let x1420 = x1417 + x1419;
        let x1421 = 0.00025 * x1360;
        let x1422 = 0.00025 * x1364;
        let x1437 = 0.00025 * x1374;
        let x1439 = 0.00025 * x1379;
        let x1455 = 0.00025 * x1388;
        let x1457 = 0.00025 * x1392;
        let x1471 = 0.00025 * x1403;
        let x1474 = 0.00025 * x1407;
        let x1487 = x652 - x651;
        let x1488 = x647 + x1487;
        let x1489 = x1488 - x648;
        let x1490 = 2.0 * x1489;
        let x1493 = x637 + x641;
        let x1495 = x642 - x1493;
        let x1496 = x638 + x1495;
        let x1497 = 2.0 * x1496;
        let x1500 = x627 - x631;
        let x1501 = x1500 - x628;
        let x1502 = x632 + x1501;
        let x1503 = 2.0 * x1502;
        let x1524 = 2.0 * x1490;
        let x1526 = 2.0 * x1497;
        let x1528 = 2.0 * x1503;
        let x1765 = x873 + x876;
        let x1767 = x876 - x1765;
        let x1768 = x873 + x1767;
        let x1769 = 2.0 * x1768;
        let x1772 = x865 - x868;
        let x1773 = x1772 - x865;
        let x1774 = x868 + x1773;
        let x1775 = 2.0 * x1774;
        let x1776 = 2.0 * x1769;
        let x1777 = 2.0 * x1775;
        let x1778 = x805 * x1524;
        let x1780 = x806 * x1526;
        let x1781 = x317 * x1776;
        let x1782 = x1780 + x1781;
        let x1783 = 0.006124999999999999 * x1782;
        let x1784 = x807 * x1528;
        let x1785 = x318 * x1777;
        let x1786 = x1784 + x1785;
        let x1787 = 0.006124999999999999 * x1786;
        let x1792 = x804 * x1524;
        let x1794 = x807 * x1526;
        let x1795 = x318 * x1776;
        let x1796 = x1794 + x1795;
        let x1797 = 0.006124999999999999 * x1796;
        let x1799 = x806 * x1528;
        let x1800 = x317 * x1777;
        let x1801 = x1799 + x1800;
        let x1802 = 0.006124999999999999 * x1801;
        let x1806 = x807 * x1524;
        let x1808 = x804 * x1526;
        let x1809 = x315 * x1776;
        let x1810 = x1808 + x1809;
        let x1811 = 0.006124999999999999 * x1810;
        let x1812 = x805 * x1528;
        let x1813 = x316 * x1777;
        let x1814 = x1812 + x1813;
        let x1815 = 0.006124999999999999 * x1814;
        let x1820 = x806 * x1524;
        let x1823 = x805 * x1526;
        let x1824 = x316 * x1776;
        let x1825 = x1823 + x1824;
        let x1826 = 0.006124999999999999 * x1825;
        let x1827 = x804 * x1528;
        let x1828 = x315 * x1777;
        let x1829 = x1827 + x1828;
        let x1830 = 0.006124999999999999 * x1829;
        let x1834 = qd[10] * qd[10];
        let x1835 = qd[11] * qd[11];
        let x1836 = qd[12] * qd[12];
        let x1837 = qd[13] * qd[13];
        let x1838 = x1834 + x1835;
        let x1839 = x1836 + x1838;
        let x1840 = x1837 + x1839;
        let x1841 = 0.006124999999999999 * x1780;
        let x1842 = 0.006124999999999999 * x1784;
        let x1857 = 0.006124999999999999 * x1794;
        let x1859 = 0.006124999999999999 * x1799;
        let x1875 = 0.006124999999999999 * x1808;
        let x1877 = 0.006124999999999999 * x1812;
        let x1891 = 0.006124999999999999 * x1823;
        let x1894 = 0.006124999999999999 * x1827;
        let x1907 = x690 - x689;
        let x1908 = x685 + x1907;
        let x1909 = x1908 - x686;
        let x1910 = 2.0 * x1909;
        let x1913 = x675 + x679;
        let x1915 = x680 - x1913;
        let x1916 = x676 + x1915;
        let x1917 = 2.0 * x1916;
        let x1920 = x667 - x671;
        let x1921 = x1920 - x668;
        let x1922 = x672 + x1921;
        let x1923 = 2.0 * x1922;
        let x1940 = 2.0 * x1910;
        let x1942 = 2.0 * x1917;
        let x1944 = 2.0 * x1923;
        let x2148 = x905 + x908;
        let x2150 = x908 - x2148;
        let x2151 = x905 + x2150;
        let x2152 = 2.0 * x2151;
        let x2155 = x899 - x902;
        let x2156 = x2155 - x899;
        let x2157 = x902 + x2156;
        let x2158 = 2.0 * x2157;
        let x2159 = 2.0 * x2152;
        let x2160 = 2.0 * x2158;
        let x2161 = x812 * x1940;
        let x2162 = 0.001 * x2161;
        let x2163 = x813 * x1942;
        let x2164 = x528 * x2159;
        let x2165 = x2163 + x2164;
        let x2166 = 0.001 * x2165;
        let x2167 = x811 * x1944;
        let x2168 = x355 * x2160;
        let x2169 = x2167 + x2168;
        let x2170 = 0.001 * x2169;
        let x2171 = x2162 + x2166;
        let x2172 = x2170 + x2171;
        let x2173 = 0.5 * x2172;
        let x2175 = x810 * x1940;
        let x2176 = 0.001 * x2175;
        let x2177 = x811 * x1942;
        let x2178 = x355 * x2159;
        let x2179 = x2177 + x2178;
        let x2180 = 0.001 * x2179;
        let x2182 = x813 * x1944;
        let x2183 = x528 * x2160;
        let x2184 = x2182 + x2183;
        let x2185 = 0.001 * x2184;
        let x2186 = x2176 - x2180;
        let x2187 = x2185 + x2186;
        let x2188 = 0.5 * x2187;
        let x2189 = x811 * x1940;
        let x2190 = 0.001 * x2189;
        let x2191 = x810 * x1942;
        let x2192 = x354 * x2159;
        let x2193 = x2191 + x2192;
        let x2194 = 0.001 * x2193;
        let x2195 = x812 * x1944;
        let x2196 = x527 * x2160;
        let x2197 = x2195 + x2196;
        let x2198 = 0.001 * x2197;
        let x2200 = x2190 + x2194;
        let x2201 = x2200 - x2198;
        let x2202 = 0.5 * x2201;
        let x2203 = x813 * x1940;
        let x2204 = 0.001 * x2203;
        let x2206 = x812 * x1942;
        let x2207 = x527 * x2159;
        let x2208 = x2206 + x2207;
        let x2209 = 0.001 * x2208;
        let x2210 = x810 * x1944;
        let x2211 = x354 * x2160;
        let x2212 = x2210 + x2211;
        let x2213 = 0.001 * x2212;
        let x2214 = x2209 - x2204;
        let x2215 = x2213 + x2214;
        let x2216 = 0.5 * x2215;
        let x2217 = qd[17] * qd[17];
        let x2218 = qd[18] * qd[18];
        let x2219 = qd[19] * qd[19];
        let x2220 = qd[20] * qd[20];
        let x2221 = x2217 + x2218;
        let x2222 = x2219 + x2221;
        let x2223 = x2220 + x2222;
        let x2224 = 0.001 * x2163;
        let x2225 = 0.001 * x2167;
        let x2226 = x2162 + x2224;
        let x2227 = x2225 + x2226;
        let x2228 = 0.5 * x2227;
        let x2229 = x2173 + x2228;
        let x2230 = q[17] * 0.004;
        let x2231 = x2223 * x2230;
        let x2233 = x2229 - x2231;
        let x2240 = 0.001 * x2177;
        let x2242 = 0.001 * x2182;
        let x2244 = x2240 - x2176;
        let x2245 = x2244 - x2242;
        let x2246 = 0.5 * x2245;
        let x2248 = x2246 - x2188;
        let x2249 = q[18] * 0.004;
        let x2250 = x2223 * x2249;
        let x2252 = x2248 - x2250;
        let x2258 = 0.001 * x2191;
        let x2260 = 0.001 * x2195;
        let x2261 = x2190 + x2258;
        let x2263 = x2260 - x2261;
        let x2264 = 0.5 * x2263;
        let x2266 = x2264 - x2202;
        let x2267 = q[19] * 0.004;
        let x2268 = x2223 * x2267;
        let x2270 = x2266 - x2268;
        let x2274 = 0.001 * x2206;
        let x2277 = 0.001 * x2210;
        let x2279 = x2204 - x2274;
        let x2280 = x2279 - x2277;
        let x2281 = 0.5 * x2280;
        let x2283 = x2281 - x2216;
        let x2284 = q[20] * 0.004;
        let x2285 = x2223 * x2284;
        let x2287 = x2283 - x2285;
        let x2390 = x1358 * k[0];
        let x2391 = x1363 + x2390;
        let x2392 = x1367 + x2391;
        let x2393 = 0.5 * x2392;
        let x2394 = x1372 * k[0];
        let x2395 = x2394 - x1377;
        let x2396 = x1382 + x2395;
        let x2397 = 0.5 * x2396;
        let x2398 = x1386 * k[0];
        let x2399 = x1391 + x2398;
        let x2400 = x2399 - x1395;
        let x2401 = 0.5 * x2400;
        let x2402 = x1400 * k[0];
        let x2404 = x1406 - x2402;
        let x2405 = x1410 + x2404;
        let x2406 = 0.5 * x2405;
        let x2407 = x1421 + x2390;
        let x2408 = x1422 + x2407;
        let x2409 = 0.5 * x2408;
        let x2410 = x2393 + x2409;
        let x2411 = q[3] * k[1];
        let x2412 = x1420 * x2411;
        let x2414 = x2410 - x2412;
        let x2416 = x1437 - x2394;
        let x2417 = x2416 - x1439;
        let x2418 = 0.5 * x2417;
        let x2420 = x2418 - x2397;
        let x2421 = q[4] * k[1];
        let x2422 = x1420 * x2421;
        let x2424 = x2420 - x2422;
        let x2425 = x1455 + x2398;
        let x2427 = x1457 - x2425;
        let x2428 = 0.5 * x2427;
        let x2430 = x2428 - x2401;
        let x2431 = q[5] * k[1];
        let x2432 = x1420 * x2431;
        let x2434 = x2430 - x2432;
        let x2435 = x2402 - x1471;
        let x2436 = x2435 - x1474;
        let x2437 = 0.5 * x2436;
        let x2439 = x2437 - x2406;
        let x2440 = q[6] * k[1];
        let x2441 = x1420 * x2440;
        let x2443 = x2439 - x2441;
        let x2545 = x1778 * k[0];
        let x2546 = x1783 + x2545;
        let x2547 = x1787 + x2546;
        let x2548 = 0.5 * x2547;
        let x2549 = x1792 * k[0];
        let x2550 = x2549 - x1797;
        let x2551 = x1802 + x2550;
        let x2552 = 0.5 * x2551;
        let x2553 = x1806 * k[0];
        let x2554 = x1811 + x2553;
        let x2555 = x2554 - x1815;
        let x2556 = 0.5 * x2555;
        let x2557 = x1820 * k[0];
        let x2559 = x1826 - x2557;
        let x2560 = x1830 + x2559;
        let x2561 = 0.5 * x2560;
        let x2562 = x1841 + x2545;
        let x2563 = x1842 + x2562;
        let x2564 = 0.5 * x2563;
        let x2565 = x2548 + x2564;
        let x2566 = q[10] * k[2];
        let x2567 = x1840 * x2566;
        let x2569 = x2565 - x2567;
        let x2571 = x1857 - x2549;
        let x2572 = x2571 - x1859;
        let x2573 = 0.5 * x2572;
        let x2575 = x2573 - x2552;
        let x2576 = q[11] * k[2];
        let x2577 = x1840 * x2576;
        let x2579 = x2575 - x2577;
        let x2580 = x1875 + x2553;
        let x2582 = x1877 - x2580;
        let x2583 = 0.5 * x2582;
        let x2585 = x2583 - x2556;
        let x2586 = q[12] * k[2];
        let x2587 = x1840 * x2586;
        let x2589 = x2585 - x2587;
        let x2590 = x2557 - x1891;
        let x2591 = x2590 - x1894;
        let x2592 = 0.5 * x2591;
        let x2594 = x2592 - x2561;
        let x2595 = q[13] * k[2];
        let x2596 = x1840 * x2595;
        let x2598 = x2594 - x2596;
        out[0] = 0.0;
        out[1] = -2.943;
        out[2] = 0.0;
        out[3] = x2414;
        out[4] = x2424;
        out[5] = x2434;
        out[6] = x2443;
        out[7] = 0.0;
        out[8] = -5.886;
        out[9] = 0.0;
        out[10] = x2569;
        out[11] = x2579;
        out[12] = x2589;
        out[13] = x2598;
        out[14] = 0.0;
        out[15] = -9.81;
        out[16] = 0.0;
        out[17] = x2233;
        out[18] = x2252;
        out[19] = x2270;
        out[20] = x2287;
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
        let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
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
        eval_newton_shared_0(k, q, qd, t, &mut s);
        eval_newton_part_0(k, q, t, &s, phi, phi_q, mass);
        eval_newton_part_1(k, q, qd, &s, mass, force);
    }
    #[inline(never)]
    fn eval_newton_shared_0(
        _k: &[f64; 3],
        q: &[f64; 21],
        _qd: &[f64; 21],
        _t: f64,
        s: &mut [f64; 24],
    ) {
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
        k: &[f64; 3],
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
        let x1172 = 2.0 * s[16];
        let x1174 = 2.0 * s[17];
        let x1176 = s[11] * x334;
        let x1180 = s[16] * x1172;
        let x1182 = 0.00025 * x1180;
        let x1184 = s[17] * x1174;
        let x1186 = 0.00025 * x1184;
        let x1196 = s[11] * x321;
        let x1198 = s[16] * x1174;
        let x1200 = 0.00025 * x1198;
        let x1202 = s[17] * x1172;
        let x1203 = 0.00025 * x1202;
        let x1210 = s[11] * x1174;
        let x1212 = s[16] * x321;
        let x1213 = 0.00025 * x1212;
        let x1214 = s[17] * x334;
        let x1216 = 0.00025 * x1214;
        let x1224 = s[11] * x1172;
        let x1228 = s[16] * x334;
        let x1229 = 0.00025 * x1228;
        let x1230 = s[17] * x321;
        let x1231 = 0.00025 * x1230;
        let x1238 = s[10] * x334;
        let x1248 = s[10] * x321;
        let x1255 = s[10] * x1174;
        let x1265 = s[10] * x1172;
        let x1277 = 0.00025 * x1265;
        let x1280 = 0.00025 * x1210;
        let x1289 = 0.00025 * x1255;
        let x1291 = 0.00025 * x1224;
        let x1298 = 0.00025 * x1248;
        let x1299 = 0.00025 * x1176;
        let x1308 = 0.00025 * x1238;
        let x1309 = 0.00025 * x1196;
        let x1596 = s[13] * x422;
        let x1600 = s[14] * x464;
        let x1602 = 0.006124999999999999 * x1600;
        let x1604 = s[15] * x500;
        let x1606 = 0.006124999999999999 * x1604;
        let x1616 = s[13] * x350;
        let x1618 = s[14] * x500;
        let x1620 = 0.006124999999999999 * x1618;
        let x1622 = s[15] * x464;
        let x1623 = 0.006124999999999999 * x1622;
        let x1630 = s[13] * x500;
        let x1632 = s[14] * x350;
        let x1633 = 0.006124999999999999 * x1632;
        let x1634 = s[15] * x422;
        let x1636 = 0.006124999999999999 * x1634;
        let x1644 = s[13] * x464;
        let x1648 = s[14] * x422;
        let x1649 = 0.006124999999999999 * x1648;
        let x1650 = s[15] * x350;
        let x1651 = 0.006124999999999999 * x1650;
        let x1658 = s[12] * x422;
        let x1668 = s[12] * x350;
        let x1675 = s[12] * x500;
        let x1685 = s[12] * x464;
        let x1697 = 0.006124999999999999 * x1685;
        let x1700 = 0.006124999999999999 * x1630;
        let x1709 = 0.006124999999999999 * x1675;
        let x1711 = 0.006124999999999999 * x1644;
        let x1718 = 0.006124999999999999 * x1668;
        let x1719 = 0.006124999999999999 * x1596;
        let x1728 = 0.006124999999999999 * x1658;
        let x1729 = 0.006124999999999999 * x1616;
        let x2290 = x1176 * k[0];
        let x2291 = x1182 + x2290;
        let x2292 = x1186 + x2291;
        let x2293 = 0.5 * x2292;
        let x2294 = x14 * k[1];
        let x2295 = x2293 + x2294;
        let x2296 = x1196 * k[0];
        let x2297 = x2296 - x1200;
        let x2298 = x1203 + x2297;
        let x2299 = 0.5 * x2298;
        let x2301 = x43 * k[1];
        let x2302 = x2301 - x2299;
        let x2303 = x1210 * k[0];
        let x2304 = x1213 + x2303;
        let x2305 = x2304 - x1216;
        let x2306 = 0.5 * x2305;
        let x2308 = x37 * k[1];
        let x2309 = x2308 - x2306;
        let x2310 = x1224 * k[0];
        let x2312 = x1229 - x2310;
        let x2313 = x1231 + x2312;
        let x2314 = 0.5 * x2313;
        let x2316 = x30 * k[1];
        let x2317 = x2316 - x2314;
        let x2318 = x1238 * k[0];
        let x2320 = x1203 - x2318;
        let x2321 = x2320 - x1200;
        let x2322 = 0.5 * x2321;
        let x2323 = x2301 + x2322;
        let x2324 = x1248 * k[0];
        let x2325 = x1186 + x2324;
        let x2326 = x1182 + x2325;
        let x2327 = 0.5 * x2326;
        let x2328 = x15 * k[1];
        let x2329 = x2327 + x2328;
        let x2330 = x1255 * k[0];
        let x2331 = x2330 - x1231;
        let x2332 = x2331 - x1229;
        let x2333 = 0.5 * x2332;
        let x2334 = x28 * k[1];
        let x2335 = x2333 + x2334;
        let x2336 = x1265 * k[0];
        let x2337 = x1216 + x2336;
        let x2339 = x1213 - x2337;
        let x2340 = 0.5 * x2339;
        let x2341 = x35 * k[1];
        let x2342 = x2340 + x2341;
        let x2343 = x1214 * k[0];
        let x2344 = x1277 + x2343;
        let x2346 = x1280 - x2344;
        let x2347 = 0.5 * x2346;
        let x2348 = x2308 + x2347;
        let x2349 = x1230 * k[0];
        let x2350 = x2349 - x1289;
        let x2351 = x2350 - x1291;
        let x2352 = 0.5 * x2351;
        let x2353 = x2334 + x2352;
        let x2354 = x1184 * k[0];
        let x2355 = x1298 + x2354;
        let x2356 = x1299 + x2355;
        let x2357 = 0.5 * x2356;
        let x2358 = x16 * k[1];
        let x2359 = x2357 + x2358;
        let x2360 = x1202 * k[0];
        let x2362 = x1308 - x2360;
        let x2363 = x2362 - x1309;
        let x2364 = 0.5 * x2363;
        let x2365 = x41 * k[1];
        let x2366 = x2364 + x2365;
        let x2367 = x1228 * k[0];
        let x2368 = x2367 - x1291;
        let x2369 = x2368 - x1289;
        let x2370 = 0.5 * x2369;
        let x2371 = x2316 + x2370;
        let x2372 = x1212 * k[0];
        let x2373 = x1280 + x2372;
        let x2375 = x1277 - x2373;
        let x2376 = 0.5 * x2375;
        let x2377 = x2341 + x2376;
        let x2378 = x1198 * k[0];
        let x2380 = x1309 - x2378;
        let x2381 = x2380 - x1308;
        let x2382 = 0.5 * x2381;
        let x2383 = x2365 + x2382;
        let x2384 = x1180 * k[0];
        let x2385 = x1299 + x2384;
        let x2386 = x1298 + x2385;
        let x2387 = 0.5 * x2386;
        let x2388 = x17 * k[1];
        let x2389 = x2387 + x2388;
        let x2445 = x1596 * k[0];
        let x2446 = x1602 + x2445;
        let x2447 = x1606 + x2446;
        let x2448 = 0.5 * x2447;
        let x2449 = x59 * k[2];
        let x2450 = x2448 + x2449;
        let x2451 = x1616 * k[0];
        let x2452 = x2451 - x1620;
        let x2453 = x1623 + x2452;
        let x2454 = 0.5 * x2453;
        let x2456 = x87 * k[2];
        let x2457 = x2456 - x2454;
        let x2458 = x1630 * k[0];
        let x2459 = x1633 + x2458;
        let x2460 = x2459 - x1636;
        let x2461 = 0.5 * x2460;
        let x2463 = x81 * k[2];
        let x2464 = x2463 - x2461;
        let x2465 = x1644 * k[0];
        let x2467 = x1649 - x2465;
        let x2468 = x1651 + x2467;
        let x2469 = 0.5 * x2468;
        let x2471 = x74 * k[2];
        let x2472 = x2471 - x2469;
        let x2473 = x1658 * k[0];
        let x2475 = x1623 - x2473;
        let x2476 = x2475 - x1620;
        let x2477 = 0.5 * x2476;
        let x2478 = x2456 + x2477;
        let x2479 = x1668 * k[0];
        let x2480 = x1606 + x2479;
        let x2481 = x1602 + x2480;
        let x2482 = 0.5 * x2481;
        let x2483 = x60 * k[2];
        let x2484 = x2482 + x2483;
        let x2485 = x1675 * k[0];
        let x2486 = x2485 - x1651;
        let x2487 = x2486 - x1649;
        let x2488 = 0.5 * x2487;
        let x2489 = x72 * k[2];
        let x2490 = x2488 + x2489;
        let x2491 = x1685 * k[0];
        let x2492 = x1636 + x2491;
        let x2494 = x1633 - x2492;
        let x2495 = 0.5 * x2494;
        let x2496 = x79 * k[2];
        let x2497 = x2495 + x2496;
        let x2498 = x1634 * k[0];
        let x2499 = x1697 + x2498;
        let x2501 = x1700 - x2499;
        let x2502 = 0.5 * x2501;
        let x2503 = x2463 + x2502;
        let x2504 = x1650 * k[0];
        let x2505 = x2504 - x1709;
        let x2506 = x2505 - x1711;
        let x2507 = 0.5 * x2506;
        let x2508 = x2489 + x2507;
        let x2509 = x1604 * k[0];
        let x2510 = x1718 + x2509;
        let x2511 = x1719 + x2510;
        let x2512 = 0.5 * x2511;
        let x2513 = x61 * k[2];
        let x2514 = x2512 + x2513;
        let x2515 = x1622 * k[0];
        let x2517 = x1728 - x2515;
        let x2518 = x2517 - x1729;
        let x2519 = 0.5 * x2518;
        let x2520 = x85 * k[2];
        let x2521 = x2519 + x2520;
        let x2522 = x1648 * k[0];
        let x2523 = x2522 - x1711;
        let x2524 = x2523 - x1709;
        let x2525 = 0.5 * x2524;
        let x2526 = x2471 + x2525;
        let x2527 = x1632 * k[0];
        let x2528 = x1700 + x2527;
        let x2530 = x1697 - x2528;
        let x2531 = 0.5 * x2530;
        let x2532 = x2496 + x2531;
        let x2533 = x1618 * k[0];
        let x2535 = x1729 - x2533;
        let x2536 = x2535 - x1728;
        let x2537 = 0.5 * x2536;
        let x2538 = x2520 + x2537;
        let x2539 = x1600 * k[0];
        let x2540 = x1719 + x2539;
        let x2541 = x1718 + x2540;
        let x2542 = 0.5 * x2541;
        let x2543 = x62 * k[2];
        let x2544 = x2542 + x2543;
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
        mass[3] = x2295;
        mass[4] = x2302;
        mass[5] = x2309;
        mass[6] = x2317;
        mass[7] = x2323;
        mass[8] = x2329;
        mass[9] = x2335;
        mass[10] = x2342;
        mass[11] = x2348;
        mass[12] = x2353;
        mass[13] = x2359;
        mass[14] = x2366;
        mass[15] = x2371;
        mass[16] = x2377;
        mass[17] = x2383;
        mass[18] = x2389;
        mass[19] = 0.6;
        mass[20] = 0.6;
        mass[21] = 0.6;
        mass[22] = x2450;
        mass[23] = x2457;
        mass[24] = x2464;
        mass[25] = x2472;
        mass[26] = x2478;
        mass[27] = x2484;
        mass[28] = x2490;
        mass[29] = x2497;
        mass[30] = x2503;
        mass[31] = x2508;
        mass[32] = x2514;
        mass[33] = x2521;
        mass[34] = x2526;
        mass[35] = x2532;
        mass[36] = x2538;
        mass[37] = x2544;
        mass[38] = 1.0;
        mass[39] = 1.0;
        mass[40] = 1.0;
    }
    #[inline(never)]
    fn eval_newton_part_1(
        k: &[f64; 3],
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
        let x1062 = x610 - x609;
        let x1063 = x605 + x1062;
        let x1064 = x1063 - x606;
        let x1065 = 2.0 * x1064;
        let x1068 = x595 + x599;
        let x1070 = x600 - x1068;
        let x1071 = x596 + x1070;
        let x1072 = 2.0 * x1071;
        let x1075 = x587 - x591;
        let x1076 = x1075 - x588;
        let x1077 = x592 + x1076;
        let x1078 = 2.0 * x1077;
        let x1099 = 2.0 * x1065;
        let x1101 = 2.0 * x1072;
        let x1103 = 2.0 * x1078;
        let x1345 = x837 + x840;
        let x1347 = x840 - x1345;
        let x1348 = x837 + x1347;
        let x1349 = 2.0 * x1348;
        let x1352 = x831 - x834;
        let x1353 = x1352 - x831;
        let x1354 = x834 + x1353;
        let x1355 = 2.0 * x1354;
        let x1356 = 2.0 * x1349;
        let x1357 = 2.0 * x1355;
        let x1358 = x803 * x1099;
        let x1360 = x808 * x1101;
        let x1361 = s[16] * x1356;
        let x1362 = x1360 + x1361;
        let x1363 = 0.00025 * x1362;
        let x1364 = x809 * x1103;
        let x1365 = s[17] * x1357;
        let x1366 = x1364 + x1365;
        let x1367 = 0.00025 * x1366;
        let x1372 = x802 * x1099;
        let x1374 = x809 * x1101;
        let x1375 = s[17] * x1356;
        let x1376 = x1374 + x1375;
        let x1377 = 0.00025 * x1376;
        let x1379 = x808 * x1103;
        let x1380 = s[16] * x1357;
        let x1381 = x1379 + x1380;
        let x1382 = 0.00025 * x1381;
        let x1386 = x809 * x1099;
        let x1388 = x802 * x1101;
        let x1389 = s[10] * x1356;
        let x1390 = x1388 + x1389;
        let x1391 = 0.00025 * x1390;
        let x1392 = x803 * x1103;
        let x1393 = s[11] * x1357;
        let x1394 = x1392 + x1393;
        let x1395 = 0.00025 * x1394;
        let x1400 = x808 * x1099;
        let x1403 = x803 * x1101;
        let x1404 = s[11] * x1356;
        let x1405 = x1403 + x1404;
        let x1406 = 0.00025 * x1405;
        let x1407 = x802 * x1103;
        let x1408 = s[10] * x1357;
        let x1409 = x1407 + x1408;
        let x1410 = 0.00025 * x1409;
        let x1414 = qd[3] * qd[3];
        let x1415 = qd[4] * qd[4];
        let x1416 = qd[5] * qd[5];
        let x1417 = qd[6] * qd[6];
        let x1418 = x1414 + x1415;
        let x1419 = x1416 + x1418;
        let x1420 = x1417 + x1419;
        let x1421 = 0.00025 * x1360;
        let x1422 = 0.00025 * x1364;
        let x1437 = 0.00025 * x1374;
        let x1439 = 0.00025 * x1379;
        let x1455 = 0.00025 * x1388;
        let x1457 = 0.00025 * x1392;
        let x1471 = 0.00025 * x1403;
        let x1474 = 0.00025 * x1407;
        let x1487 = x652 - x651;
        let x1488 = x647 + x1487;
        let x1489 = x1488 - x648;
        let x1490 = 2.0 * x1489;
        let x1493 = x637 + x641;
        let x1495 = x642 - x1493;
        let x1496 = x638 + x1495;
        let x1497 = 2.0 * x1496;
        let x1500 = x627 - x631;
        let x1501 = x1500 - x628;
        let x1502 = x632 + x1501;
        let x1503 = 2.0 * x1502;
        let x1524 = 2.0 * x1490;
        let x1526 = 2.0 * x1497;
        let x1528 = 2.0 * x1503;
        let x1765 = x873 + x876;
        let x1767 = x876 - x1765;
        let x1768 = x873 + x1767;
        let x1769 = 2.0 * x1768;
        let x1772 = x865 - x868;
        let x1773 = x1772 - x865;
        let x1774 = x868 + x1773;
        let x1775 = 2.0 * x1774;
        let x1776 = 2.0 * x1769;
        let x1777 = 2.0 * x1775;
        let x1778 = x805 * x1524;
        let x1780 = x806 * x1526;
        let x1781 = s[14] * x1776;
        let x1782 = x1780 + x1781;
        let x1783 = 0.006124999999999999 * x1782;
        let x1784 = x807 * x1528;
        let x1785 = s[15] * x1777;
        let x1786 = x1784 + x1785;
        let x1787 = 0.006124999999999999 * x1786;
        let x1792 = x804 * x1524;
        let x1794 = x807 * x1526;
        let x1795 = s[15] * x1776;
        let x1796 = x1794 + x1795;
        let x1797 = 0.006124999999999999 * x1796;
        let x1799 = x806 * x1528;
        let x1800 = s[14] * x1777;
        let x1801 = x1799 + x1800;
        let x1802 = 0.006124999999999999 * x1801;
        let x1806 = x807 * x1524;
        let x1808 = x804 * x1526;
        let x1809 = s[12] * x1776;
        let x1810 = x1808 + x1809;
        let x1811 = 0.006124999999999999 * x1810;
        let x1812 = x805 * x1528;
        let x1813 = s[13] * x1777;
        let x1814 = x1812 + x1813;
        let x1815 = 0.006124999999999999 * x1814;
        let x1820 = x806 * x1524;
        let x1823 = x805 * x1526;
        let x1824 = s[13] * x1776;
        let x1825 = x1823 + x1824;
        let x1826 = 0.006124999999999999 * x1825;
        let x1827 = x804 * x1528;
        let x1828 = s[12] * x1777;
        let x1829 = x1827 + x1828;
        let x1830 = 0.006124999999999999 * x1829;
        let x1834 = qd[10] * qd[10];
        let x1835 = qd[11] * qd[11];
        let x1836 = qd[12] * qd[12];
        let x1837 = qd[13] * qd[13];
        let x1838 = x1834 + x1835;
        let x1839 = x1836 + x1838;
        let x1840 = x1837 + x1839;
        let x1841 = 0.006124999999999999 * x1780;
        let x1842 = 0.006124999999999999 * x1784;
        let x1857 = 0.006124999999999999 * x1794;
        let x1859 = 0.006124999999999999 * x1799;
        let x1875 = 0.006124999999999999 * x1808;
        let x1877 = 0.006124999999999999 * x1812;
        let x1891 = 0.006124999999999999 * x1823;
        let x1894 = 0.006124999999999999 * x1827;
        let x1907 = x690 - x689;
        let x1908 = x685 + x1907;
        let x1909 = x1908 - x686;
        let x1910 = 2.0 * x1909;
        let x1913 = x675 + x679;
        let x1915 = x680 - x1913;
        let x1916 = x676 + x1915;
        let x1917 = 2.0 * x1916;
        let x1920 = x667 - x671;
        let x1921 = x1920 - x668;
        let x1922 = x672 + x1921;
        let x1923 = 2.0 * x1922;
        let x1940 = 2.0 * x1910;
        let x1942 = 2.0 * x1917;
        let x1944 = 2.0 * x1923;
        let x2006 = 2.0 * s[20];
        let x2008 = 2.0 * s[21];
        let x2011 = s[20] * x2006;
        let x2013 = 0.001 * x2011;
        let x2015 = s[21] * x2008;
        let x2017 = 0.001 * x2015;
        let x2019 = s[19] * s[23];
        let x2021 = 0.001 * x2019;
        let x2023 = x2013 + x2017;
        let x2025 = x2021 + x2023;
        let x2027 = 0.5 * x2025;
        let x2029 = s[0] * 0.004;
        let x2030 = x2027 + x2029;
        let x2031 = s[20] * s[22];
        let x2032 = 0.001 * x2031;
        let x2033 = s[21] * s[23];
        let x2035 = 0.001 * x2033;
        let x2037 = s[19] * x2008;
        let x2038 = 0.001 * x2037;
        let x2039 = x2032 - x2035;
        let x2040 = x2038 + x2039;
        let x2041 = 0.5 * x2040;
        let x2043 = s[9] * 0.004;
        let x2044 = x2043 - x2041;
        let x2045 = s[20] * s[23];
        let x2046 = 0.001 * x2045;
        let x2047 = s[21] * s[22];
        let x2048 = 0.001 * x2047;
        let x2049 = s[19] * x2006;
        let x2051 = 0.001 * x2049;
        let x2053 = x2046 + x2048;
        let x2054 = x2053 - x2051;
        let x2055 = 0.5 * x2054;
        let x2057 = s[7] * 0.004;
        let x2058 = x2057 - x2055;
        let x2059 = s[20] * x2008;
        let x2061 = 0.001 * x2059;
        let x2063 = s[21] * x2006;
        let x2064 = 0.001 * x2063;
        let x2065 = s[19] * s[22];
        let x2066 = 0.001 * x2065;
        let x2067 = x2064 - x2061;
        let x2068 = x2066 + x2067;
        let x2069 = 0.5 * x2068;
        let x2071 = s[5] * 0.004;
        let x2072 = x2071 - x2069;
        let x2073 = s[18] * x2006;
        let x2075 = 0.001 * x2073;
        let x2079 = x2038 - x2075;
        let x2080 = x2079 - x2035;
        let x2081 = 0.5 * x2080;
        let x2082 = x2043 + x2081;
        let x2083 = s[18] * s[22];
        let x2084 = 0.001 * x2083;
        let x2085 = x2021 + x2084;
        let x2086 = x2017 + x2085;
        let x2087 = 0.5 * x2086;
        let x2088 = s[1] * 0.004;
        let x2089 = x2087 + x2088;
        let x2090 = s[18] * s[23];
        let x2091 = 0.001 * x2090;
        let x2095 = x2091 - x2066;
        let x2096 = x2095 - x2064;
        let x2097 = 0.5 * x2096;
        let x2098 = s[4] * 0.004;
        let x2099 = x2097 + x2098;
        let x2100 = s[18] * x2008;
        let x2102 = 0.001 * x2100;
        let x2104 = x2051 + x2102;
        let x2106 = x2048 - x2104;
        let x2107 = 0.5 * x2106;
        let x2108 = s[6] * 0.004;
        let x2109 = x2107 + x2108;
        let x2112 = x2046 - x2104;
        let x2113 = 0.5 * x2112;
        let x2114 = x2057 + x2113;
        let x2117 = x2066 - x2091;
        let x2118 = x2117 - x2061;
        let x2119 = 0.5 * x2118;
        let x2120 = x2098 + x2119;
        let x2121 = x2013 + x2085;
        let x2122 = 0.5 * x2121;
        let x2123 = s[2] * 0.004;
        let x2124 = x2122 + x2123;
        let x2126 = x2075 - x2038;
        let x2127 = x2126 - x2032;
        let x2128 = 0.5 * x2127;
        let x2129 = s[8] * 0.004;
        let x2130 = x2128 + x2129;
        let x2131 = x2067 - x2091;
        let x2132 = 0.5 * x2131;
        let x2133 = x2071 + x2132;
        let x2136 = x2102 - x2053;
        let x2137 = 0.5 * x2136;
        let x2138 = x2108 + x2137;
        let x2139 = x2039 - x2075;
        let x2140 = 0.5 * x2139;
        let x2141 = x2129 + x2140;
        let x2142 = x2023 + x2084;
        let x2143 = 0.5 * x2142;
        let x2144 = s[3] * 0.004;
        let x2145 = x2143 + x2144;
        let x2148 = x905 + x908;
        let x2150 = x908 - x2148;
        let x2151 = x905 + x2150;
        let x2152 = 2.0 * x2151;
        let x2155 = x899 - x902;
        let x2156 = x2155 - x899;
        let x2157 = x902 + x2156;
        let x2158 = 2.0 * x2157;
        let x2159 = 2.0 * x2152;
        let x2160 = 2.0 * x2158;
        let x2161 = x812 * x1940;
        let x2162 = 0.001 * x2161;
        let x2163 = x813 * x1942;
        let x2164 = s[21] * x2159;
        let x2165 = x2163 + x2164;
        let x2166 = 0.001 * x2165;
        let x2167 = x811 * x1944;
        let x2168 = s[19] * x2160;
        let x2169 = x2167 + x2168;
        let x2170 = 0.001 * x2169;
        let x2171 = x2162 + x2166;
        let x2172 = x2170 + x2171;
        let x2173 = 0.5 * x2172;
        let x2175 = x810 * x1940;
        let x2176 = 0.001 * x2175;
        let x2177 = x811 * x1942;
        let x2178 = s[19] * x2159;
        let x2179 = x2177 + x2178;
        let x2180 = 0.001 * x2179;
        let x2182 = x813 * x1944;
        let x2183 = s[21] * x2160;
        let x2184 = x2182 + x2183;
        let x2185 = 0.001 * x2184;
        let x2186 = x2176 - x2180;
        let x2187 = x2185 + x2186;
        let x2188 = 0.5 * x2187;
        let x2189 = x811 * x1940;
        let x2190 = 0.001 * x2189;
        let x2191 = x810 * x1942;
        let x2192 = s[18] * x2159;
        let x2193 = x2191 + x2192;
        let x2194 = 0.001 * x2193;
        let x2195 = x812 * x1944;
        let x2196 = s[20] * x2160;
        let x2197 = x2195 + x2196;
        let x2198 = 0.001 * x2197;
        let x2200 = x2190 + x2194;
        let x2201 = x2200 - x2198;
        let x2202 = 0.5 * x2201;
        let x2203 = x813 * x1940;
        let x2204 = 0.001 * x2203;
        let x2206 = x812 * x1942;
        let x2207 = s[20] * x2159;
        let x2208 = x2206 + x2207;
        let x2209 = 0.001 * x2208;
        let x2210 = x810 * x1944;
        let x2211 = s[18] * x2160;
        let x2212 = x2210 + x2211;
        let x2213 = 0.001 * x2212;
        let x2214 = x2209 - x2204;
        let x2215 = x2213 + x2214;
        let x2216 = 0.5 * x2215;
        let x2217 = qd[17] * qd[17];
        let x2218 = qd[18] * qd[18];
        let x2219 = qd[19] * qd[19];
        let x2220 = qd[20] * qd[20];
        let x2221 = x2217 + x2218;
        let x2222 = x2219 + x2221;
        let x2223 = x2220 + x2222;
        let x2224 = 0.001 * x2163;
        let x2225 = 0.001 * x2167;
        let x2226 = x2162 + x2224;
        let x2227 = x2225 + x2226;
        let x2228 = 0.5 * x2227;
        let x2229 = x2173 + x2228;
        let x2230 = q[17] * 0.004;
        let x2231 = x2223 * x2230;
        let x2233 = x2229 - x2231;
        let x2240 = 0.001 * x2177;
        let x2242 = 0.001 * x2182;
        let x2244 = x2240 - x2176;
        let x2245 = x2244 - x2242;
        let x2246 = 0.5 * x2245;
        let x2248 = x2246 - x2188;
        let x2249 = q[18] * 0.004;
        let x2250 = x2223 * x2249;
        let x2252 = x2248 - x2250;
        let x2258 = 0.001 * x2191;
        let x2260 = 0.001 * x2195;
        let x2261 = x2190 + x2258;
        let x2263 = x2260 - x2261;
        let x2264 = 0.5 * x2263;
        let x2266 = x2264 - x2202;
        let x2267 = q[19] * 0.004;
        let x2268 = x2223 * x2267;
        let x2270 = x2266 - x2268;
        let x2274 = 0.001 * x2206;
        let x2277 = 0.001 * x2210;
        let x2279 = x2204 - x2274;
        let x2280 = x2279 - x2277;
        let x2281 = 0.5 * x2280;
        let x2283 = x2281 - x2216;
        let x2284 = q[20] * 0.004;
        let x2285 = x2223 * x2284;
        let x2287 = x2283 - x2285;
        let x2390 = x1358 * k[0];
        let x2391 = x1363 + x2390;
        let x2392 = x1367 + x2391;
        let x2393 = 0.5 * x2392;
        let x2394 = x1372 * k[0];
        let x2395 = x2394 - x1377;
        let x2396 = x1382 + x2395;
        let x2397 = 0.5 * x2396;
        let x2398 = x1386 * k[0];
        let x2399 = x1391 + x2398;
        let x2400 = x2399 - x1395;
        let x2401 = 0.5 * x2400;
        let x2402 = x1400 * k[0];
        let x2404 = x1406 - x2402;
        let x2405 = x1410 + x2404;
        let x2406 = 0.5 * x2405;
        let x2407 = x1421 + x2390;
        let x2408 = x1422 + x2407;
        let x2409 = 0.5 * x2408;
        let x2410 = x2393 + x2409;
        let x2411 = q[3] * k[1];
        let x2412 = x1420 * x2411;
        let x2414 = x2410 - x2412;
        let x2416 = x1437 - x2394;
        let x2417 = x2416 - x1439;
        let x2418 = 0.5 * x2417;
        let x2420 = x2418 - x2397;
        let x2421 = q[4] * k[1];
        let x2422 = x1420 * x2421;
        let x2424 = x2420 - x2422;
        let x2425 = x1455 + x2398;
        let x2427 = x1457 - x2425;
        let x2428 = 0.5 * x2427;
        let x2430 = x2428 - x2401;
        let x2431 = q[5] * k[1];
        let x2432 = x1420 * x2431;
        let x2434 = x2430 - x2432;
        let x2435 = x2402 - x1471;
        let x2436 = x2435 - x1474;
        let x2437 = 0.5 * x2436;
        let x2439 = x2437 - x2406;
        let x2440 = q[6] * k[1];
        let x2441 = x1420 * x2440;
        let x2443 = x2439 - x2441;
        let x2545 = x1778 * k[0];
        let x2546 = x1783 + x2545;
        let x2547 = x1787 + x2546;
        let x2548 = 0.5 * x2547;
        let x2549 = x1792 * k[0];
        let x2550 = x2549 - x1797;
        let x2551 = x1802 + x2550;
        let x2552 = 0.5 * x2551;
        let x2553 = x1806 * k[0];
        let x2554 = x1811 + x2553;
        let x2555 = x2554 - x1815;
        let x2556 = 0.5 * x2555;
        let x2557 = x1820 * k[0];
        let x2559 = x1826 - x2557;
        let x2560 = x1830 + x2559;
        let x2561 = 0.5 * x2560;
        let x2562 = x1841 + x2545;
        let x2563 = x1842 + x2562;
        let x2564 = 0.5 * x2563;
        let x2565 = x2548 + x2564;
        let x2566 = q[10] * k[2];
        let x2567 = x1840 * x2566;
        let x2569 = x2565 - x2567;
        let x2571 = x1857 - x2549;
        let x2572 = x2571 - x1859;
        let x2573 = 0.5 * x2572;
        let x2575 = x2573 - x2552;
        let x2576 = q[11] * k[2];
        let x2577 = x1840 * x2576;
        let x2579 = x2575 - x2577;
        let x2580 = x1875 + x2553;
        let x2582 = x1877 - x2580;
        let x2583 = 0.5 * x2582;
        let x2585 = x2583 - x2556;
        let x2586 = q[12] * k[2];
        let x2587 = x1840 * x2586;
        let x2589 = x2585 - x2587;
        let x2590 = x2557 - x1891;
        let x2591 = x2590 - x1894;
        let x2592 = 0.5 * x2591;
        let x2594 = x2592 - x2561;
        let x2595 = q[13] * k[2];
        let x2596 = x1840 * x2595;
        let x2598 = x2594 - x2596;
        mass[41] = x2030;
        mass[42] = x2044;
        mass[43] = x2058;
        mass[44] = x2072;
        mass[45] = x2082;
        mass[46] = x2089;
        mass[47] = x2099;
        mass[48] = x2109;
        mass[49] = x2114;
        mass[50] = x2120;
        mass[51] = x2124;
        mass[52] = x2130;
        mass[53] = x2133;
        mass[54] = x2138;
        mass[55] = x2141;
        mass[56] = x2145;
        force[0] = 0.0;
        force[1] = -2.943;
        force[2] = 0.0;
        force[3] = x2414;
        force[4] = x2424;
        force[5] = x2434;
        force[6] = x2443;
        force[7] = 0.0;
        force[8] = -5.886;
        force[9] = 0.0;
        force[10] = x2569;
        force[11] = x2579;
        force[12] = x2589;
        force[13] = x2598;
        force[14] = 0.0;
        force[15] = -9.81;
        force[16] = 0.0;
        force[17] = x2233;
        force[18] = x2252;
        force[19] = x2270;
        force[20] = x2287;
    }
}
/// The system after substituting rows `a·qᵢ + b·qⱼ + g(t) = 0` away (docs/design.md,
/// decision 24): fewer coordinates and rows, the same motion and multipliers once
/// mapped back with `REDUCTION`.
pub mod reduced {
    use super::*;
    /// Number of reduced coordinates.
    pub const N_COORDS: usize = 19usize;
    /// Number of reduced rows.
    pub const N_CONSTRAINTS: usize = 19usize;
    /// Row of each Φq nonzero.
    pub static PHI_Q_ROWS: [u32; 101usize] = [
        0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 1u32, 1u32, 2u32, 2u32, 2u32, 2u32, 2u32,
        3u32, 3u32, 3u32, 3u32, 4u32, 4u32, 4u32, 4u32, 5u32, 5u32, 5u32, 5u32, 5u32,
        5u32, 5u32, 5u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32,
        7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 8u32, 8u32, 8u32,
        8u32, 8u32, 8u32, 9u32, 9u32, 9u32, 9u32, 9u32, 10u32, 10u32, 10u32, 10u32,
        10u32, 11u32, 11u32, 11u32, 11u32, 11u32, 11u32, 11u32, 11u32, 12u32, 12u32,
        12u32, 12u32, 13u32, 13u32, 13u32, 13u32, 14u32, 14u32, 14u32, 14u32, 15u32,
        15u32, 15u32, 15u32, 16u32, 16u32, 16u32, 16u32, 17u32, 17u32, 17u32, 17u32,
        18u32, 18u32, 18u32, 18u32,
    ];
    /// Column of each Φq nonzero.
    pub static PHI_Q_COLS: [u32; 101usize] = [
        0u32, 3u32, 4u32, 1u32, 3u32, 4u32, 5u32, 6u32, 2u32, 3u32, 4u32, 5u32, 6u32,
        3u32, 4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 0u32, 3u32, 4u32, 7u32, 10u32,
        11u32, 12u32, 13u32, 1u32, 3u32, 4u32, 5u32, 6u32, 8u32, 10u32, 11u32, 12u32,
        13u32, 2u32, 3u32, 4u32, 5u32, 6u32, 9u32, 10u32, 11u32, 12u32, 13u32, 7u32,
        10u32, 11u32, 12u32, 13u32, 14u32, 8u32, 10u32, 11u32, 12u32, 13u32, 9u32, 10u32,
        11u32, 12u32, 13u32, 10u32, 11u32, 12u32, 13u32, 15u32, 16u32, 17u32, 18u32,
        15u32, 16u32, 17u32, 18u32, 15u32, 16u32, 17u32, 18u32, 15u32, 16u32, 17u32,
        18u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 10u32, 11u32, 12u32,
        13u32, 15u32, 16u32, 17u32, 18u32,
    ];
    /// Name of each reduced coordinate (its full model's name).
    pub static COORD_NAMES: [&str; 19usize] = [
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
        "slider.e0",
        "slider.e1",
        "slider.e2",
        "slider.e3",
    ];
    /// Name of each reduced row (its full model's name).
    pub static ROW_NAMES: [&str; 19usize] = [
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
        "guide.dot1(y1,x2)",
        "motor",
        "crank.norm",
        "rod.norm",
        "slider.norm",
    ];
    /// Initial coordinates, from the full model's assembled ones.
    pub static Q0: [f64; 19usize] = [
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
        1f64,
        0f64,
        0f64,
        0f64,
    ];
    /// Initial velocities from the file.
    pub static QD0: [f64; 19usize] = [
        0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64, 0f64,
        0f64, 0f64, 0f64, 0f64, 0f64, 0f64,
    ];
    /// Rows dependent on others at the initial pose.
    pub static REDUNDANT_ROWS: [u32; 0usize] = [];
    /// Full index of each reduced coordinate.
    pub static COORDS: [u32; 19usize] = [
        0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 7u32, 8u32, 9u32, 10u32, 11u32, 12u32,
        13u32, 14u32, 17u32, 18u32, 19u32, 20u32,
    ];
    /// Full index of each reduced row.
    pub static ROWS: [u32; 19usize] = [
        0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 7u32, 8u32, 9u32, 10u32, 11u32, 12u32,
        13u32, 16u32, 17u32, 18u32, 19u32, 20u32,
    ];
    /// The eliminated rows.
    pub static SUBSTITUTIONS: [Substitution; 2usize] = [
        Substitution {
            row: Some(14u32),
            coord: 15u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
        Substitution {
            row: Some(15u32),
            coord: 16u32,
            target: None,
            weight: -0f64,
            slope: 1f64,
        },
    ];
    /// The way back to the full model.
    pub static REDUCTION: Reduction = Reduction {
        n_full: 21usize,
        m_full: 21usize,
        coords: &COORDS,
        rows: &ROWS,
        substitutions: &SUBSTITUTIONS,
        offsets: offsets_into,
    };
    /// `c, ċ, c̈` of each substitution at time `t`, three per substitution.
    pub fn offsets_into(t: f64, out: &mut [f64]) {
        let out: &mut [f64; 6] = out.try_into().expect("out must have 6 entries");
        let _ = t;
        offsets_into_part_0(out);
    }
    #[inline(never)]
    fn offsets_into_part_0(out: &mut [f64; 6]) {
        out[0] = 0.05;
        out[1] = 0.0;
        out[2] = 0.0;
        out[3] = 0.12;
        out[4] = 0.0;
        out[5] = 0.0;
    }
    /// Number of values `setup` computes from the run-time parameters.
    pub const N_K: usize = 3;
    /// `setup` at the file's parameter values: what the types without parameters read.
    pub static K: [f64; 3] = [0.0001f64, 0.0008f64, 0.016466666666666664f64];
    /// The values the per-step functions read (`k`), from the run-time parameters `p`.
    pub fn setup(p: &[f64], k: &mut [f64]) {
        let p: &[f64; 1] = p.try_into().expect("p must have 1 entries");
        let k: &mut [f64; 3] = k.try_into().expect("k must have 3 entries");
        setup_part_0(p, k);
    }
    #[inline(never)]
    fn setup_part_0(p: &[f64; 1], k: &mut [f64; 3]) {
        let x1164 = p[0] + 0.00025;
        let x1165 = 0.00025 + x1164;
        let x1168 = x1165 * 4.0;
        let x1170 = x1168 * 0.3333333333333333;
        let x1588 = p[0] + 0.006124999999999999;
        let x1589 = 0.006124999999999999 + x1588;
        let x1590 = 4.0 * x1589;
        let x1591 = 0.3333333333333333 * x1590;
        k[0] = p[0];
        k[1] = x1170;
        k[2] = x1591;
    }
    /// Constraint residual Φ(q, t).
    pub fn phi(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
        phi_part_0(q, t, out);
    }
    #[inline(never)]
    fn phi_part_0(q: &[f64; 19], t: f64, out: &mut [f64; 19]) {
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
        let x131 = q[17] * q[18];
        let x133 = 2.0 * x131;
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
        let x2288 = q[15] * q[15];
        let x2289 = q[16] * q[16];
        let x2290 = x2288 + x2289;
        let x2291 = x104 + x2288;
        let x2292 = 2.0 * x2291;
        let x2293 = x2292 - 1.0;
        let x2294 = q[16] * q[17];
        let x2295 = 2.0 * x2294;
        let x2296 = q[15] * q[18];
        let x2297 = 2.0 * x2296;
        let x2298 = q[16] * q[18];
        let x2299 = 2.0 * x2298;
        let x2300 = q[15] * q[17];
        let x2301 = 2.0 * x2300;
        let x2302 = x2299 + x2301;
        let x2303 = x2295 + x2297;
        let x2304 = q[15] * q[16];
        let x2305 = 2.0 * x2304;
        let x2307 = x133 - x2305;
        let x2309 = x2299 - x2301;
        let x2310 = x133 + x2305;
        let x2311 = 0.05 - x215;
        let x2312 = 0.12 - x216;
        let x2313 = x273 * x2302;
        let x2314 = x276 * x2307;
        let x2315 = x279 * x2293;
        let x2316 = x2313 + x2314;
        let x2317 = x2315 + x2316;
        let x2318 = x103 + x2290;
        let x2319 = x104 + x2318;
        let x2320 = x2319 - 1.0;
        out[0] = x151;
        out[1] = x152;
        out[2] = x153;
        out[3] = x39;
        out[4] = x47;
        out[5] = x183;
        out[6] = x185;
        out[7] = x187;
        out[8] = x281;
        out[9] = x2311;
        out[10] = x2312;
        out[11] = x2317;
        out[12] = x2303;
        out[13] = x2309;
        out[14] = x2310;
        out[15] = x303;
        out[16] = x306;
        out[17] = x309;
        out[18] = x2320;
    }
    /// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
    pub fn phi_q(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 101] = out.try_into().expect("out must have 101 entries");
        phi_q_part_0(q, t, out);
    }
    #[inline(never)]
    fn phi_q_part_0(q: &[f64; 19], t: f64, out: &mut [f64; 101]) {
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
        let x104 = q[18] * q[18];
        let x131 = q[17] * q[18];
        let x133 = 2.0 * x131;
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
        let x527 = 2.0 * q[18];
        let x533 = x276 * x527;
        let x538 = -x354;
        let x540 = x276 * x354;
        let x543 = x273 * x354;
        let x547 = x273 * x527;
        let x2006 = 2.0 * x527;
        let x2288 = q[15] * q[15];
        let x2291 = x104 + x2288;
        let x2292 = 2.0 * x2291;
        let x2293 = x2292 - 1.0;
        let x2298 = q[16] * q[18];
        let x2299 = 2.0 * x2298;
        let x2300 = q[15] * q[17];
        let x2301 = 2.0 * x2300;
        let x2302 = x2299 + x2301;
        let x2304 = q[15] * q[16];
        let x2305 = 2.0 * x2304;
        let x2307 = x133 - x2305;
        let x2321 = 2.0 * q[15];
        let x2322 = x407 * x2302;
        let x2323 = x410 * x2307;
        let x2324 = x414 * x2293;
        let x2325 = x2322 + x2323;
        let x2326 = x2324 + x2325;
        let x2327 = x453 * x2302;
        let x2328 = x411 * x2307;
        let x2329 = x455 * x2293;
        let x2330 = x2327 + x2328;
        let x2331 = x2329 + x2330;
        let x2332 = x413 * x2302;
        let x2333 = x490 * x2307;
        let x2334 = x493 * x2293;
        let x2335 = x2332 + x2333;
        let x2336 = x2334 + x2335;
        let x2337 = x454 * x2302;
        let x2339 = x491 * x2307;
        let x2340 = x517 * x2293;
        let x2341 = x2339 - x2337;
        let x2342 = x2340 + x2341;
        let x2343 = 2.0 * q[16];
        let x2344 = 2.0 * x2321;
        let x2346 = x276 * x2343;
        let x2348 = x279 * x2344;
        let x2349 = x543 - x2346;
        let x2350 = x2348 + x2349;
        let x2351 = -x2321;
        let x2352 = x276 * x2321;
        let x2354 = x547 - x2352;
        let x2355 = x273 * x2321;
        let x2356 = x533 + x2355;
        let x2357 = x273 * x2343;
        let x2358 = x279 * x2006;
        let x2359 = x540 + x2357;
        let x2360 = x2358 + x2359;
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
        out[60] = -1.0;
        out[61] = x402;
        out[62] = x458;
        out[63] = x486;
        out[64] = x520;
        out[65] = x2326;
        out[66] = x2331;
        out[67] = x2336;
        out[68] = x2342;
        out[69] = x2350;
        out[70] = x2354;
        out[71] = x2356;
        out[72] = x2360;
        out[73] = x527;
        out[74] = x354;
        out[75] = x2343;
        out[76] = x2321;
        out[77] = x538;
        out[78] = x527;
        out[79] = x2351;
        out[80] = x2343;
        out[81] = x2343;
        out[82] = x2321;
        out[83] = x527;
        out[84] = x354;
        out[85] = x333;
        out[86] = x341;
        out[87] = x347;
        out[88] = x349;
        out[89] = x313;
        out[90] = x314;
        out[91] = x319;
        out[92] = x320;
        out[93] = x315;
        out[94] = x316;
        out[95] = x317;
        out[96] = x318;
        out[97] = x2321;
        out[98] = x2343;
        out[99] = x354;
        out[100] = x527;
    }
    /// Partial time derivative Φt(q, t).
    pub fn phi_t(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
        phi_t_part_0(q, t, out);
    }
    #[inline(never)]
    fn phi_t_part_0(q: &[f64; 19], t: f64, out: &mut [f64; 19]) {
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
        out[15] = x559;
        out[16] = 0.0;
        out[17] = 0.0;
        out[18] = 0.0;
    }
    /// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
    pub fn gamma(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 19] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
        gamma_part_0(q, qd, t, out);
    }
    #[inline(never)]
    fn gamma_part_0(q: &[f64; 19], qd: &[f64; 19], t: f64, out: &mut [f64; 19]) {
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
        let x104 = q[18] * q[18];
        let x131 = q[17] * q[18];
        let x133 = 2.0 * x131;
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
        let x527 = 2.0 * q[18];
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
        let x661 = x527 * qd[18];
        let x689 = q[18] * qd[17];
        let x690 = q[17] * qd[18];
        let x691 = x689 + x690;
        let x692 = 2.0 * x691;
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
        let x812 = 2.0 * qd[18];
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
        let x916 = qd[17] * qd[18];
        let x917 = x916 + x916;
        let x918 = 2.0 * x917;
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
        let x1022 = -x843;
        let x1023 = -x852;
        let x1024 = -x949;
        let x1025 = -x951;
        let x1026 = -x953;
        let x1031 = -x1015;
        let x1032 = -x1017;
        let x1033 = -x1019;
        let x1941 = 2.0 * qd[15];
        let x1943 = 2.0 * qd[16];
        let x2288 = q[15] * q[15];
        let x2291 = x104 + x2288;
        let x2292 = 2.0 * x2291;
        let x2293 = x2292 - 1.0;
        let x2298 = q[16] * q[18];
        let x2299 = 2.0 * x2298;
        let x2300 = q[15] * q[17];
        let x2301 = 2.0 * x2300;
        let x2302 = x2299 + x2301;
        let x2304 = q[15] * q[16];
        let x2305 = 2.0 * x2304;
        let x2307 = x133 - x2305;
        let x2321 = 2.0 * q[15];
        let x2361 = qd[15] * x2321;
        let x2364 = x661 + x2361;
        let x2365 = 2.0 * x2364;
        let x2374 = q[18] * qd[16];
        let x2375 = q[16] * qd[18];
        let x2376 = x2374 + x2375;
        let x2377 = 2.0 * x2376;
        let x2378 = q[17] * qd[15];
        let x2379 = q[15] * qd[17];
        let x2380 = x2378 + x2379;
        let x2381 = 2.0 * x2380;
        let x2382 = x2377 + x2381;
        let x2384 = q[16] * qd[15];
        let x2385 = q[15] * qd[16];
        let x2386 = x2384 + x2385;
        let x2387 = 2.0 * x2386;
        let x2389 = x692 - x2387;
        let x2406 = qd[15] * x1941;
        let x2407 = qd[16] * x1943;
        let x2408 = x2406 + x2407;
        let x2409 = x893 + x2406;
        let x2410 = 2.0 * x2409;
        let x2411 = qd[16] * qd[17];
        let x2412 = x2411 + x2411;
        let x2413 = 2.0 * x2412;
        let x2414 = qd[15] * qd[18];
        let x2415 = x2414 + x2414;
        let x2416 = 2.0 * x2415;
        let x2417 = qd[16] * qd[18];
        let x2418 = x2417 + x2417;
        let x2419 = 2.0 * x2418;
        let x2420 = qd[15] * qd[17];
        let x2421 = x2420 + x2420;
        let x2422 = 2.0 * x2421;
        let x2423 = x2419 + x2422;
        let x2424 = x2413 + x2416;
        let x2425 = qd[15] * qd[16];
        let x2426 = x2425 + x2425;
        let x2427 = 2.0 * x2426;
        let x2429 = x918 - x2427;
        let x2431 = x2419 - x2422;
        let x2432 = x918 + x2427;
        let x2433 = x977 * x2302;
        let x2434 = x766 * x2382;
        let x2435 = x2433 + x2434;
        let x2436 = x273 * x2423;
        let x2437 = x2434 + x2436;
        let x2438 = x2435 + x2437;
        let x2439 = x980 * x2307;
        let x2440 = x769 * x2389;
        let x2441 = x2439 + x2440;
        let x2442 = x276 * x2429;
        let x2443 = x2440 + x2442;
        let x2444 = x2441 + x2443;
        let x2445 = x983 * x2293;
        let x2446 = x772 * x2365;
        let x2447 = x2445 + x2446;
        let x2448 = x279 * x2410;
        let x2449 = x2446 + x2448;
        let x2450 = x2447 + x2449;
        let x2451 = x2438 + x2444;
        let x2452 = x2450 + x2451;
        let x2453 = x892 + x2408;
        let x2454 = x893 + x2453;
        let x2455 = -x2452;
        let x2456 = -x2424;
        let x2457 = -x2431;
        let x2458 = -x2432;
        let x2459 = -x2454;
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
        out[11] = x2455;
        out[12] = x2456;
        out[13] = x2457;
        out[14] = x2458;
        out[15] = x1031;
        out[16] = x1032;
        out[17] = x1033;
        out[18] = x2459;
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
        let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 19] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 19] = phi.try_into().expect("phi must have 19 entries");
        let phi_q: &mut [f64; 101] = phi_q
            .try_into()
            .expect("phi_q must have 101 entries");
        let phi_t: &mut [f64; 19] = phi_t
            .try_into()
            .expect("phi_t must have 19 entries");
        let gamma: &mut [f64; 19] = gamma
            .try_into()
            .expect("gamma must have 19 entries");
        let mut s = [0.0f64; 60];
        eval_kinematics_shared_0(q, qd, t, &mut s);
        eval_kinematics_part_0(q, qd, &s, phi, phi_q, phi_t, gamma);
        eval_kinematics_part_1(q, qd, &s, phi, phi_q, phi_t, gamma);
    }
    #[inline(never)]
    fn eval_kinematics_shared_0(
        q: &[f64; 19],
        qd: &[f64; 19],
        t: f64,
        s: &mut [f64; 60],
    ) {
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
        let x104 = q[18] * q[18];
        s[16] = x104;
        let x298 = x5.sin();
        s[17] = x298;
        let x299 = x5.cos();
        s[18] = x299;
        let x313 = 2.0 * q[3];
        s[19] = x313;
        let x314 = 2.0 * q[4];
        s[20] = x314;
        let x315 = 2.0 * q[10];
        s[21] = x315;
        let x316 = 2.0 * q[11];
        s[22] = x316;
        let x317 = 2.0 * q[12];
        s[23] = x317;
        let x318 = 2.0 * q[13];
        s[24] = x318;
        let x319 = 2.0 * q[5];
        s[25] = x319;
        let x320 = 2.0 * q[6];
        s[26] = x320;
        let x354 = 2.0 * q[17];
        s[27] = x354;
        let x527 = 2.0 * q[18];
        s[28] = x527;
        let x552 = 6.283185307179586 * x299;
        s[29] = x552;
        let x554 = 6.283185307179586 * x298;
        s[30] = x554;
        let x802 = 2.0 * qd[3];
        s[31] = x802;
        let x803 = 2.0 * qd[4];
        s[32] = x803;
        let x804 = 2.0 * qd[10];
        s[33] = x804;
        let x805 = 2.0 * qd[11];
        s[34] = x805;
        let x806 = 2.0 * qd[12];
        s[35] = x806;
        let x807 = 2.0 * qd[13];
        s[36] = x807;
        let x812 = 2.0 * qd[18];
        s[37] = x812;
        let x825 = qd[3] * x802;
        s[38] = x825;
        let x826 = qd[4] * x803;
        s[39] = x826;
        let x829 = x825 + x826;
        s[40] = x829;
        let x830 = 2.0 * x829;
        s[41] = x830;
        let x831 = qd[4] * qd[5];
        s[42] = x831;
        let x832 = x831 + x831;
        s[43] = x832;
        let x833 = 2.0 * x832;
        s[44] = x833;
        let x834 = qd[3] * qd[6];
        s[45] = x834;
        let x835 = x834 + x834;
        s[46] = x835;
        let x836 = 2.0 * x835;
        s[47] = x836;
        let x844 = x833 + x836;
        s[48] = x844;
        let x855 = qd[10] * x804;
        s[49] = x855;
        let x856 = qd[11] * x805;
        s[50] = x856;
        let x857 = qd[12] * x806;
        s[51] = x857;
        let x858 = qd[13] * x807;
        s[52] = x858;
        let x859 = x855 + x856;
        s[53] = x859;
        let x893 = qd[18] * x812;
        s[54] = x893;
        let x1941 = 2.0 * qd[15];
        s[55] = x1941;
        let x2288 = q[15] * q[15];
        s[56] = x2288;
        let x2321 = 2.0 * q[15];
        s[57] = x2321;
        let x2343 = 2.0 * q[16];
        s[58] = x2343;
        let x2406 = qd[15] * x1941;
        s[59] = x2406;
    }
    #[inline(never)]
    fn eval_kinematics_part_0(
        q: &[f64; 19],
        qd: &[f64; 19],
        s: &[f64; 60],
        phi: &mut [f64; 19],
        phi_q: &mut [f64; 101],
        phi_t: &mut [f64; 19],
        gamma: &mut [f64; 19],
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
        let x131 = q[17] * q[18];
        let x133 = 2.0 * x131;
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
        let x300 = s[5] * s[17];
        let x301 = s[10] * s[18];
        let x303 = x300 - x301;
        let x321 = 2.0 * s[19];
        let x322 = -s[20];
        let x324 = 0.05 * x321;
        let x326 = 0.05 * s[26];
        let x328 = 0.05 * s[25];
        let x329 = -x328;
        let x330 = s[17] * x321;
        let x331 = s[18] * s[26];
        let x333 = x330 - x331;
        let x334 = 2.0 * s[20];
        let x335 = -s[19];
        let x336 = 0.05 * x334;
        let x338 = s[17] * x334;
        let x339 = s[18] * s[25];
        let x341 = x338 - x339;
        let x342 = 0.05 * s[20];
        let x344 = 0.05 * s[19];
        let x345 = -x344;
        let x346 = s[18] * s[20];
        let x347 = -x346;
        let x348 = s[18] * s[19];
        let x349 = -x348;
        let x350 = 2.0 * s[21];
        let x356 = 0.1749999999999999 * x350;
        let x358 = 0.000000000000000003677613769070831 * s[24];
        let x360 = 0.000000000000000013877787807814457 * s[23];
        let x361 = x356 + x358;
        let x363 = x360 - x361;
        let x364 = 0.1749999999999999 * s[24];
        let x366 = 0.000000000000000003677613769070831 * x350;
        let x367 = 0.000000000000000013877787807814457 * s[22];
        let x369 = x366 - x364;
        let x370 = x369 - x367;
        let x371 = 0.1749999999999999 * s[23];
        let x373 = 0.000000000000000003677613769070831 * s[22];
        let x374 = 0.000000000000000013877787807814457 * x350;
        let x375 = x371 + x373;
        let x376 = x374 + x375;
        let x377 = -x363;
        let x378 = -x370;
        let x379 = -x376;
        let x380 = 0.17499999999999993 * x350;
        let x381 = 0.00000000000000001061650767297806 * s[24];
        let x383 = 0.000000000000000027755575615628914 * s[23];
        let x385 = x380 + x381;
        let x386 = x385 - x383;
        let x387 = 0.17499999999999993 * s[24];
        let x388 = 0.00000000000000001061650767297806 * x350;
        let x390 = 0.000000000000000027755575615628914 * s[22];
        let x392 = x387 - x388;
        let x393 = x390 + x392;
        let x394 = 0.17499999999999993 * s[23];
        let x396 = 0.00000000000000001061650767297806 * s[22];
        let x398 = 0.000000000000000027755575615628914 * x350;
        let x400 = x394 + x396;
        let x402 = x398 + x400;
        let x404 = 0.00000000000000005551115123125783 * x350;
        let x405 = 0.9999999999999994 * s[24];
        let x407 = x404 - x405;
        let x408 = 0.00000000000000005551115123125783 * s[24];
        let x409 = 0.9999999999999994 * x350;
        let x410 = x408 + x409;
        let x411 = 0.00000000000000005551115123125783 * s[23];
        let x413 = 0.9999999999999994 * s[22];
        let x414 = x413 - x411;
        let x415 = -x386;
        let x416 = -x393;
        let x422 = 2.0 * s[22];
        let x424 = 0.1749999999999999 * x422;
        let x426 = 0.000000000000000003677613769070831 * s[23];
        let x427 = 0.000000000000000013877787807814457 * s[24];
        let x428 = x426 - x424;
        let x429 = x427 + x428;
        let x430 = 0.000000000000000013877787807814457 * s[21];
        let x432 = x371 + x430;
        let x434 = 0.000000000000000003677613769070831 * s[21];
        let x435 = x434 - x364;
        let x436 = -x429;
        let x437 = -x435;
        let x438 = 0.17499999999999993 * x422;
        let x439 = 0.00000000000000001061650767297806 * s[23];
        let x441 = 0.000000000000000027755575615628914 * s[24];
        let x443 = x438 - x439;
        let x444 = x443 - x441;
        let x445 = 0.000000000000000027755575615628914 * s[21];
        let x447 = x394 + x445;
        let x448 = 0.00000000000000001061650767297806 * s[21];
        let x450 = x387 - x448;
        let x451 = 0.00000000000000005551115123125783 * x422;
        let x452 = 0.9999999999999994 * s[23];
        let x453 = x451 + x452;
        let x454 = 0.9999999999999994 * s[21];
        let x455 = x408 + x454;
        let x456 = -x444;
        let x457 = -x447;
        let x458 = -x450;
        let x464 = 2.0 * s[23];
        let x465 = x373 + x430;
        let x466 = 0.1749999999999999 * s[22];
        let x468 = 0.000000000000000003677613769070831 * x464;
        let x469 = x468 - x466;
        let x470 = x427 + x469;
        let x471 = 0.1749999999999999 * s[21];
        let x473 = x358 + x471;
        let x474 = -x465;
        let x475 = -x470;
        let x476 = -x473;
        let x477 = x396 + x445;
        let x479 = 0.17499999999999993 * s[22];
        let x480 = 0.00000000000000001061650767297806 * x464;
        let x482 = x479 - x480;
        let x483 = x482 - x441;
        let x484 = 0.17499999999999993 * s[21];
        let x486 = x381 + x484;
        let x488 = 0.00000000000000005551115123125783 * s[22];
        let x489 = 0.9999999999999994 * x464;
        let x490 = x488 + x489;
        let x491 = 0.00000000000000005551115123125783 * s[21];
        let x493 = x405 - x491;
        let x494 = -x483;
        let x500 = 2.0 * s[24];
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
        let x533 = x276 * s[28];
        let x538 = -s[27];
        let x540 = x276 * s[27];
        let x543 = x273 * s[27];
        let x547 = x273 * s[28];
        let x556 = s[5] * s[29];
        let x557 = s[10] * s[30];
        let x559 = x556 + x557;
        let x617 = s[21] * qd[10];
        let x618 = s[22] * qd[11];
        let x619 = s[23] * qd[12];
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
        let x661 = s[28] * qd[18];
        let x689 = q[18] * qd[17];
        let x690 = q[17] * qd[18];
        let x691 = x689 + x690;
        let x692 = 2.0 * x691;
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
        let x860 = 2.0 * s[53];
        let x861 = s[49] + s[51];
        let x862 = 2.0 * x861;
        let x863 = s[49] + s[52];
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
        let x916 = qd[17] * qd[18];
        let x917 = x916 + x916;
        let x918 = 2.0 * x917;
        let x924 = 0.05 * s[41];
        let x925 = -x924;
        let x926 = 0.05 * s[48];
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
        let x1022 = -x843;
        let x1023 = -x852;
        let x1024 = -x949;
        let x1025 = -x951;
        let x1026 = -x953;
        let x2006 = 2.0 * s[28];
        let x2291 = s[16] + s[56];
        let x2292 = 2.0 * x2291;
        let x2293 = x2292 - 1.0;
        let x2294 = q[16] * q[17];
        let x2295 = 2.0 * x2294;
        let x2296 = q[15] * q[18];
        let x2297 = 2.0 * x2296;
        let x2298 = q[16] * q[18];
        let x2299 = 2.0 * x2298;
        let x2300 = q[15] * q[17];
        let x2301 = 2.0 * x2300;
        let x2302 = x2299 + x2301;
        let x2303 = x2295 + x2297;
        let x2304 = q[15] * q[16];
        let x2305 = 2.0 * x2304;
        let x2307 = x133 - x2305;
        let x2309 = x2299 - x2301;
        let x2310 = x133 + x2305;
        let x2311 = 0.05 - x215;
        let x2312 = 0.12 - x216;
        let x2313 = x273 * x2302;
        let x2314 = x276 * x2307;
        let x2315 = x279 * x2293;
        let x2316 = x2313 + x2314;
        let x2317 = x2315 + x2316;
        let x2322 = x407 * x2302;
        let x2323 = x410 * x2307;
        let x2324 = x414 * x2293;
        let x2325 = x2322 + x2323;
        let x2326 = x2324 + x2325;
        let x2327 = x453 * x2302;
        let x2328 = x411 * x2307;
        let x2329 = x455 * x2293;
        let x2330 = x2327 + x2328;
        let x2331 = x2329 + x2330;
        let x2332 = x413 * x2302;
        let x2333 = x490 * x2307;
        let x2334 = x493 * x2293;
        let x2335 = x2332 + x2333;
        let x2336 = x2334 + x2335;
        let x2337 = x454 * x2302;
        let x2339 = x491 * x2307;
        let x2340 = x517 * x2293;
        let x2341 = x2339 - x2337;
        let x2342 = x2340 + x2341;
        let x2344 = 2.0 * s[57];
        let x2346 = x276 * s[58];
        let x2348 = x279 * x2344;
        let x2349 = x543 - x2346;
        let x2350 = x2348 + x2349;
        let x2351 = -s[57];
        let x2352 = x276 * s[57];
        let x2354 = x547 - x2352;
        let x2355 = x273 * s[57];
        let x2356 = x533 + x2355;
        let x2357 = x273 * s[58];
        let x2358 = x279 * x2006;
        let x2359 = x540 + x2357;
        let x2360 = x2358 + x2359;
        let x2361 = qd[15] * s[57];
        let x2364 = x661 + x2361;
        let x2365 = 2.0 * x2364;
        let x2374 = q[18] * qd[16];
        let x2375 = q[16] * qd[18];
        let x2376 = x2374 + x2375;
        let x2377 = 2.0 * x2376;
        let x2378 = q[17] * qd[15];
        let x2379 = q[15] * qd[17];
        let x2380 = x2378 + x2379;
        let x2381 = 2.0 * x2380;
        let x2382 = x2377 + x2381;
        let x2384 = q[16] * qd[15];
        let x2385 = q[15] * qd[16];
        let x2386 = x2384 + x2385;
        let x2387 = 2.0 * x2386;
        let x2389 = x692 - x2387;
        let x2409 = s[54] + s[59];
        let x2410 = 2.0 * x2409;
        let x2411 = qd[16] * qd[17];
        let x2412 = x2411 + x2411;
        let x2413 = 2.0 * x2412;
        let x2414 = qd[15] * qd[18];
        let x2415 = x2414 + x2414;
        let x2416 = 2.0 * x2415;
        let x2417 = qd[16] * qd[18];
        let x2418 = x2417 + x2417;
        let x2419 = 2.0 * x2418;
        let x2420 = qd[15] * qd[17];
        let x2421 = x2420 + x2420;
        let x2422 = 2.0 * x2421;
        let x2423 = x2419 + x2422;
        let x2424 = x2413 + x2416;
        let x2425 = qd[15] * qd[16];
        let x2426 = x2425 + x2425;
        let x2427 = 2.0 * x2426;
        let x2429 = x918 - x2427;
        let x2431 = x2419 - x2422;
        let x2432 = x918 + x2427;
        let x2433 = x977 * x2302;
        let x2434 = x766 * x2382;
        let x2435 = x2433 + x2434;
        let x2436 = x273 * x2423;
        let x2437 = x2434 + x2436;
        let x2438 = x2435 + x2437;
        let x2439 = x980 * x2307;
        let x2440 = x769 * x2389;
        let x2441 = x2439 + x2440;
        let x2442 = x276 * x2429;
        let x2443 = x2440 + x2442;
        let x2444 = x2441 + x2443;
        let x2445 = x983 * x2293;
        let x2446 = x772 * x2365;
        let x2447 = x2445 + x2446;
        let x2448 = x279 * x2410;
        let x2449 = x2446 + x2448;
        let x2450 = x2447 + x2449;
        let x2451 = x2438 + x2444;
        let x2452 = x2450 + x2451;
        let x2455 = -x2452;
        let x2456 = -x2424;
        let x2457 = -x2431;
        let x2458 = -x2432;
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
        phi_q[13] = s[25];
        phi_q[14] = s[26];
        phi_q[15] = s[19];
        phi_q[16] = s[20];
        phi_t[3] = 0.0;
        gamma[3] = x1022;
        phi[4] = x47;
        phi_q[17] = x322;
        phi_q[18] = x335;
        phi_q[19] = s[26];
        phi_q[20] = s[25];
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
        phi[9] = x2311;
        phi_q[55] = -1.0;
        phi_q[56] = x416;
        phi_q[57] = x457;
        phi_q[58] = x494;
        phi_q[59] = x519;
        phi_t[9] = 0.0;
        gamma[9] = x967;
        phi[10] = x2312;
        phi_q[60] = -1.0;
        phi_q[61] = x402;
        phi_q[62] = x458;
        phi_q[63] = x486;
        phi_q[64] = x520;
        phi_t[10] = 0.0;
        gamma[10] = x974;
        phi[11] = x2317;
        phi_q[65] = x2326;
        phi_q[66] = x2331;
        phi_q[67] = x2336;
        phi_q[68] = x2342;
        phi_q[69] = x2350;
        phi_q[70] = x2354;
        phi_q[71] = x2356;
        phi_q[72] = x2360;
        phi_t[11] = 0.0;
        gamma[11] = x2455;
        phi[12] = x2303;
        phi_q[73] = s[28];
        phi_q[74] = s[27];
        phi_q[75] = s[58];
        phi_q[76] = s[57];
        phi_t[12] = 0.0;
        gamma[12] = x2456;
        phi[13] = x2309;
        phi_q[77] = x538;
        phi_q[78] = s[28];
        phi_q[79] = x2351;
        phi_q[80] = s[58];
        phi_t[13] = 0.0;
        gamma[13] = x2457;
        phi[14] = x2310;
        phi_q[81] = s[58];
        phi_q[82] = s[57];
        phi_q[83] = s[28];
        phi_q[84] = s[27];
        phi_t[14] = 0.0;
        gamma[14] = x2458;
        phi[15] = x303;
        phi_q[85] = x333;
        phi_q[86] = x341;
        phi_q[87] = x347;
        phi_q[88] = x349;
        phi_t[15] = x559;
    }
    #[inline(never)]
    fn eval_kinematics_part_1(
        q: &[f64; 19],
        qd: &[f64; 19],
        s: &[f64; 60],
        phi: &mut [f64; 19],
        phi_q: &mut [f64; 101],
        phi_t: &mut [f64; 19],
        gamma: &mut [f64; 19],
    ) {
        let x16 = q[5] * q[5];
        let x17 = q[6] * q[6];
        let x103 = q[17] * q[17];
        let x304 = x16 + s[3];
        let x305 = x17 + x304;
        let x306 = x305 - 1.0;
        let x307 = s[13] + s[15];
        let x308 = s[14] + x307;
        let x309 = x308 - 1.0;
        let x581 = s[19] * qd[3];
        let x582 = s[20] * qd[4];
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
        let x810 = 2.0 * qd[17];
        let x814 = 6.283185307179586 * s[30];
        let x816 = 6.283185307179586 * s[29];
        let x817 = s[29] * x586;
        let x818 = s[5] * x814;
        let x820 = x817 - x818;
        let x821 = s[30] * x604;
        let x822 = s[10] * x816;
        let x823 = x821 + x822;
        let x827 = qd[5] * x808;
        let x828 = qd[6] * x809;
        let x892 = qd[17] * x810;
        let x1007 = s[17] * s[41];
        let x1008 = x817 + x1007;
        let x1009 = x820 + x1008;
        let x1011 = s[18] * s[48];
        let x1012 = x1011 - x821;
        let x1013 = x1012 - x823;
        let x1015 = x1009 - x1013;
        let x1016 = x827 + s[40];
        let x1017 = x828 + x1016;
        let x1018 = s[51] + s[53];
        let x1019 = s[52] + x1018;
        let x1031 = -x1015;
        let x1032 = -x1017;
        let x1033 = -x1019;
        let x1943 = 2.0 * qd[16];
        let x2289 = q[16] * q[16];
        let x2290 = s[56] + x2289;
        let x2318 = x103 + x2290;
        let x2319 = s[16] + x2318;
        let x2320 = x2319 - 1.0;
        let x2407 = qd[16] * x1943;
        let x2408 = s[59] + x2407;
        let x2453 = x892 + x2408;
        let x2454 = s[54] + x2453;
        let x2459 = -x2454;
        gamma[15] = x1031;
        phi[16] = x306;
        phi_q[89] = s[19];
        phi_q[90] = s[20];
        phi_q[91] = s[25];
        phi_q[92] = s[26];
        phi_t[16] = 0.0;
        gamma[16] = x1032;
        phi[17] = x309;
        phi_q[93] = s[21];
        phi_q[94] = s[22];
        phi_q[95] = s[23];
        phi_q[96] = s[24];
        phi_t[17] = 0.0;
        gamma[17] = x1033;
        phi[18] = x2320;
        phi_q[97] = s[57];
        phi_q[98] = s[58];
        phi_q[99] = s[27];
        phi_q[100] = s[28];
        phi_t[18] = 0.0;
        gamma[18] = x2459;
    }
    /// Potential energy of gravity and springs, written to `out[0]`.
    pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
        let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        let _ = k;
        potential_into_part_0(q, out);
    }
    #[inline(never)]
    fn potential_into_part_0(q: &[f64; 19], out: &mut [f64; 1]) {
        let x1051 = q[1] * 2.943;
        let x1054 = q[8] * 5.886;
        let x1057 = x1051 + x1054;
        let x2461 = x1057 + 0.49050000000000005;
        out[0] = x2461;
    }
    /// Power of the non-conservative loads, written to `out[0]`.
    pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
        let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 19] = qd.try_into().expect("qd must have n_coords entries");
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
        pub static MASS_ROWS: [u32; 55usize] = [
            0u32, 1u32, 2u32, 3u32, 3u32, 3u32, 3u32, 4u32, 4u32, 4u32, 4u32, 5u32, 5u32,
            5u32, 5u32, 6u32, 6u32, 6u32, 6u32, 7u32, 8u32, 9u32, 10u32, 10u32, 10u32,
            10u32, 11u32, 11u32, 11u32, 11u32, 12u32, 12u32, 12u32, 12u32, 13u32, 13u32,
            13u32, 13u32, 14u32, 15u32, 15u32, 15u32, 15u32, 16u32, 16u32, 16u32, 16u32,
            17u32, 17u32, 17u32, 17u32, 18u32, 18u32, 18u32, 18u32,
        ];
        /// Column of each mass-matrix nonzero.
        pub static MASS_COLS: [u32; 55usize] = [
            0u32, 1u32, 2u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32,
            5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 7u32, 8u32, 9u32, 10u32, 11u32, 12u32,
            13u32, 10u32, 11u32, 12u32, 13u32, 10u32, 11u32, 12u32, 13u32, 10u32, 11u32,
            12u32, 13u32, 14u32, 15u32, 16u32, 17u32, 18u32, 15u32, 16u32, 17u32, 18u32,
            15u32, 16u32, 17u32, 18u32, 15u32, 16u32, 17u32, 18u32,
        ];
        /// Row and column of each ∂Q/∂q nonzero.
        pub static FORCE_Q_ROWS: [u32; 0usize] = [];
        pub static FORCE_Q_COLS: [u32; 0usize] = [];
        /// Row and column of each ∂Q/∂q̇ nonzero.
        pub static FORCE_QD_ROWS: [u32; 0usize] = [];
        pub static FORCE_QD_COLS: [u32; 0usize] = [];
        /// Sizes, patterns and names for this formulation.
        pub static INFO: MechanismInfo = MechanismInfo {
            name: "slider_crank_reduced",
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
            let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
            let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 19] = qd.try_into().expect("qd must have n_coords entries");
            let _: &mut [f64; 0] = dq.try_into().expect("dq must have 0 entries");
            let _: &mut [f64; 0] = dqd.try_into().expect("dqd must have 0 entries");
            let _ = k;
            let _ = q;
            let _ = qd;
            let _ = t;
        }
        /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
        pub fn mass(k: &[f64], q: &[f64], out: &mut [f64]) {
            let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
            let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
            let out: &mut [f64; 55] = out.try_into().expect("out must have 55 entries");
            mass_part_0(k, q, out);
        }
        #[inline(never)]
        fn mass_part_0(k: &[f64; 3], q: &[f64; 19], out: &mut [f64; 55]) {
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
            let x422 = 2.0 * x316;
            let x464 = 2.0 * x317;
            let x500 = 2.0 * x318;
            let x527 = 2.0 * q[18];
            let x529 = 2.0 * x354;
            let x1172 = 2.0 * x319;
            let x1174 = 2.0 * x320;
            let x1176 = x314 * x334;
            let x1180 = x319 * x1172;
            let x1182 = 0.00025 * x1180;
            let x1184 = x320 * x1174;
            let x1186 = 0.00025 * x1184;
            let x1196 = x314 * x321;
            let x1198 = x319 * x1174;
            let x1200 = 0.00025 * x1198;
            let x1202 = x320 * x1172;
            let x1203 = 0.00025 * x1202;
            let x1210 = x314 * x1174;
            let x1212 = x319 * x321;
            let x1213 = 0.00025 * x1212;
            let x1214 = x320 * x334;
            let x1216 = 0.00025 * x1214;
            let x1224 = x314 * x1172;
            let x1228 = x319 * x334;
            let x1229 = 0.00025 * x1228;
            let x1230 = x320 * x321;
            let x1231 = 0.00025 * x1230;
            let x1238 = x313 * x334;
            let x1248 = x313 * x321;
            let x1255 = x313 * x1174;
            let x1265 = x313 * x1172;
            let x1277 = 0.00025 * x1265;
            let x1280 = 0.00025 * x1210;
            let x1289 = 0.00025 * x1255;
            let x1291 = 0.00025 * x1224;
            let x1298 = 0.00025 * x1248;
            let x1299 = 0.00025 * x1176;
            let x1308 = 0.00025 * x1238;
            let x1309 = 0.00025 * x1196;
            let x1596 = x316 * x422;
            let x1600 = x317 * x464;
            let x1602 = 0.006124999999999999 * x1600;
            let x1604 = x318 * x500;
            let x1606 = 0.006124999999999999 * x1604;
            let x1616 = x316 * x350;
            let x1618 = x317 * x500;
            let x1620 = 0.006124999999999999 * x1618;
            let x1622 = x318 * x464;
            let x1623 = 0.006124999999999999 * x1622;
            let x1630 = x316 * x500;
            let x1632 = x317 * x350;
            let x1633 = 0.006124999999999999 * x1632;
            let x1634 = x318 * x422;
            let x1636 = 0.006124999999999999 * x1634;
            let x1644 = x316 * x464;
            let x1648 = x317 * x422;
            let x1649 = 0.006124999999999999 * x1648;
            let x1650 = x318 * x350;
            let x1651 = 0.006124999999999999 * x1650;
            let x1658 = x315 * x422;
            let x1668 = x315 * x350;
            let x1675 = x315 * x500;
            let x1685 = x315 * x464;
            let x1697 = 0.006124999999999999 * x1685;
            let x1700 = 0.006124999999999999 * x1630;
            let x1709 = 0.006124999999999999 * x1675;
            let x1711 = 0.006124999999999999 * x1644;
            let x1718 = 0.006124999999999999 * x1668;
            let x1719 = 0.006124999999999999 * x1596;
            let x1728 = 0.006124999999999999 * x1658;
            let x1729 = 0.006124999999999999 * x1616;
            let x2006 = 2.0 * x527;
            let x2011 = x527 * x2006;
            let x2013 = 0.001 * x2011;
            let x2029 = x103 * 0.004;
            let x2031 = x527 * x529;
            let x2032 = 0.001 * x2031;
            let x2043 = x131 * 0.004;
            let x2073 = x354 * x2006;
            let x2075 = 0.001 * x2073;
            let x2083 = x354 * x529;
            let x2084 = 0.001 * x2083;
            let x2088 = x104 * 0.004;
            let x2288 = q[15] * q[15];
            let x2289 = q[16] * q[16];
            let x2294 = q[16] * q[17];
            let x2296 = q[15] * q[18];
            let x2298 = q[16] * q[18];
            let x2300 = q[15] * q[17];
            let x2304 = q[15] * q[16];
            let x2321 = 2.0 * q[15];
            let x2343 = 2.0 * q[16];
            let x2344 = 2.0 * x2321;
            let x2462 = 2.0 * x2343;
            let x2463 = x2343 * x2462;
            let x2464 = 0.001 * x2463;
            let x2465 = x2084 + x2464;
            let x2466 = x2013 + x2465;
            let x2467 = 0.5 * x2466;
            let x2468 = 0.004 * x2288;
            let x2469 = x2467 + x2468;
            let x2470 = x2343 * x2344;
            let x2471 = 0.001 * x2470;
            let x2472 = x2471 - x2075;
            let x2473 = x2032 + x2472;
            let x2474 = 0.5 * x2473;
            let x2476 = 0.004 * x2304;
            let x2477 = x2476 - x2474;
            let x2478 = x2006 * x2343;
            let x2479 = 0.001 * x2478;
            let x2480 = x354 * x2344;
            let x2481 = 0.001 * x2480;
            let x2482 = x527 * x2462;
            let x2483 = 0.001 * x2482;
            let x2485 = x2479 + x2481;
            let x2486 = x2485 - x2483;
            let x2487 = 0.5 * x2486;
            let x2489 = 0.004 * x2300;
            let x2490 = x2489 - x2487;
            let x2491 = x529 * x2343;
            let x2492 = 0.001 * x2491;
            let x2494 = x354 * x2462;
            let x2495 = 0.001 * x2494;
            let x2496 = x527 * x2344;
            let x2497 = 0.001 * x2496;
            let x2498 = x2495 - x2492;
            let x2499 = x2497 + x2498;
            let x2500 = 0.5 * x2499;
            let x2502 = 0.004 * x2296;
            let x2503 = x2502 - x2500;
            let x2504 = x2321 * x2462;
            let x2505 = 0.001 * x2504;
            let x2507 = x2032 - x2505;
            let x2508 = x2507 - x2075;
            let x2509 = 0.5 * x2508;
            let x2510 = x2476 + x2509;
            let x2511 = x2321 * x2344;
            let x2512 = 0.001 * x2511;
            let x2513 = x2013 + x2512;
            let x2514 = x2084 + x2513;
            let x2515 = 0.5 * x2514;
            let x2516 = 0.004 * x2289;
            let x2517 = x2515 + x2516;
            let x2518 = x2006 * x2321;
            let x2519 = 0.001 * x2518;
            let x2522 = x2519 - x2497;
            let x2523 = x2522 - x2495;
            let x2524 = 0.5 * x2523;
            let x2525 = 0.004 * x2294;
            let x2526 = x2524 + x2525;
            let x2527 = x529 * x2321;
            let x2528 = 0.001 * x2527;
            let x2529 = x2483 + x2528;
            let x2531 = x2481 - x2529;
            let x2532 = 0.5 * x2531;
            let x2533 = 0.004 * x2298;
            let x2534 = x2532 + x2533;
            let x2535 = x2479 - x2529;
            let x2536 = 0.5 * x2535;
            let x2537 = x2489 + x2536;
            let x2539 = x2497 - x2519;
            let x2540 = x2539 - x2492;
            let x2541 = 0.5 * x2540;
            let x2542 = x2525 + x2541;
            let x2543 = x2464 + x2513;
            let x2544 = 0.5 * x2543;
            let x2545 = x2029 + x2544;
            let x2547 = x2505 - x2032;
            let x2548 = x2547 - x2471;
            let x2549 = 0.5 * x2548;
            let x2550 = x2043 + x2549;
            let x2551 = x2498 - x2519;
            let x2552 = 0.5 * x2551;
            let x2553 = x2502 + x2552;
            let x2555 = x2528 - x2485;
            let x2556 = 0.5 * x2555;
            let x2557 = x2533 + x2556;
            let x2558 = x2472 - x2505;
            let x2559 = 0.5 * x2558;
            let x2560 = x2043 + x2559;
            let x2561 = x2465 + x2512;
            let x2562 = 0.5 * x2561;
            let x2563 = x2088 + x2562;
            let x2703 = x1176 * k[0];
            let x2704 = x1182 + x2703;
            let x2705 = x1186 + x2704;
            let x2706 = 0.5 * x2705;
            let x2707 = x14 * k[1];
            let x2708 = x2706 + x2707;
            let x2709 = x1196 * k[0];
            let x2710 = x2709 - x1200;
            let x2711 = x1203 + x2710;
            let x2712 = 0.5 * x2711;
            let x2714 = x43 * k[1];
            let x2715 = x2714 - x2712;
            let x2716 = x1210 * k[0];
            let x2717 = x1213 + x2716;
            let x2718 = x2717 - x1216;
            let x2719 = 0.5 * x2718;
            let x2721 = x37 * k[1];
            let x2722 = x2721 - x2719;
            let x2723 = x1224 * k[0];
            let x2725 = x1229 - x2723;
            let x2726 = x1231 + x2725;
            let x2727 = 0.5 * x2726;
            let x2729 = x30 * k[1];
            let x2730 = x2729 - x2727;
            let x2731 = x1238 * k[0];
            let x2733 = x1203 - x2731;
            let x2734 = x2733 - x1200;
            let x2735 = 0.5 * x2734;
            let x2736 = x2714 + x2735;
            let x2737 = x1248 * k[0];
            let x2738 = x1186 + x2737;
            let x2739 = x1182 + x2738;
            let x2740 = 0.5 * x2739;
            let x2741 = x15 * k[1];
            let x2742 = x2740 + x2741;
            let x2743 = x1255 * k[0];
            let x2744 = x2743 - x1231;
            let x2745 = x2744 - x1229;
            let x2746 = 0.5 * x2745;
            let x2747 = x28 * k[1];
            let x2748 = x2746 + x2747;
            let x2749 = x1265 * k[0];
            let x2750 = x1216 + x2749;
            let x2752 = x1213 - x2750;
            let x2753 = 0.5 * x2752;
            let x2754 = x35 * k[1];
            let x2755 = x2753 + x2754;
            let x2756 = x1214 * k[0];
            let x2757 = x1277 + x2756;
            let x2759 = x1280 - x2757;
            let x2760 = 0.5 * x2759;
            let x2761 = x2721 + x2760;
            let x2762 = x1230 * k[0];
            let x2763 = x2762 - x1289;
            let x2764 = x2763 - x1291;
            let x2765 = 0.5 * x2764;
            let x2766 = x2747 + x2765;
            let x2767 = x1184 * k[0];
            let x2768 = x1298 + x2767;
            let x2769 = x1299 + x2768;
            let x2770 = 0.5 * x2769;
            let x2771 = x16 * k[1];
            let x2772 = x2770 + x2771;
            let x2773 = x1202 * k[0];
            let x2775 = x1308 - x2773;
            let x2776 = x2775 - x1309;
            let x2777 = 0.5 * x2776;
            let x2778 = x41 * k[1];
            let x2779 = x2777 + x2778;
            let x2780 = x1228 * k[0];
            let x2781 = x2780 - x1291;
            let x2782 = x2781 - x1289;
            let x2783 = 0.5 * x2782;
            let x2784 = x2729 + x2783;
            let x2785 = x1212 * k[0];
            let x2786 = x1280 + x2785;
            let x2788 = x1277 - x2786;
            let x2789 = 0.5 * x2788;
            let x2790 = x2754 + x2789;
            let x2791 = x1198 * k[0];
            let x2793 = x1309 - x2791;
            let x2794 = x2793 - x1308;
            let x2795 = 0.5 * x2794;
            let x2796 = x2778 + x2795;
            let x2797 = x1180 * k[0];
            let x2798 = x1299 + x2797;
            let x2799 = x1298 + x2798;
            let x2800 = 0.5 * x2799;
            let x2801 = x17 * k[1];
            let x2802 = x2800 + x2801;
            let x2858 = x1596 * k[0];
            let x2859 = x1602 + x2858;
            let x2860 = x1606 + x2859;
            let x2861 = 0.5 * x2860;
            let x2862 = x59 * k[2];
            let x2863 = x2861 + x2862;
            let x2864 = x1616 * k[0];
            let x2865 = x2864 - x1620;
            let x2866 = x1623 + x2865;
            let x2867 = 0.5 * x2866;
            let x2869 = x87 * k[2];
            let x2870 = x2869 - x2867;
            let x2871 = x1630 * k[0];
            let x2872 = x1633 + x2871;
            let x2873 = x2872 - x1636;
            let x2874 = 0.5 * x2873;
            let x2876 = x81 * k[2];
            let x2877 = x2876 - x2874;
            let x2878 = x1644 * k[0];
            let x2880 = x1649 - x2878;
            let x2881 = x1651 + x2880;
            let x2882 = 0.5 * x2881;
            let x2884 = x74 * k[2];
            let x2885 = x2884 - x2882;
            let x2886 = x1658 * k[0];
            let x2888 = x1623 - x2886;
            let x2889 = x2888 - x1620;
            let x2890 = 0.5 * x2889;
            let x2891 = x2869 + x2890;
            let x2892 = x1668 * k[0];
            let x2893 = x1606 + x2892;
            let x2894 = x1602 + x2893;
            let x2895 = 0.5 * x2894;
            let x2896 = x60 * k[2];
            let x2897 = x2895 + x2896;
            let x2898 = x1675 * k[0];
            let x2899 = x2898 - x1651;
            let x2900 = x2899 - x1649;
            let x2901 = 0.5 * x2900;
            let x2902 = x72 * k[2];
            let x2903 = x2901 + x2902;
            let x2904 = x1685 * k[0];
            let x2905 = x1636 + x2904;
            let x2907 = x1633 - x2905;
            let x2908 = 0.5 * x2907;
            let x2909 = x79 * k[2];
            let x2910 = x2908 + x2909;
            let x2911 = x1634 * k[0];
            let x2912 = x1697 + x2911;
            let x2914 = x1700 - x2912;
            let x2915 = 0.5 * x2914;
            let x2916 = x2876 + x2915;
            let x2917 = x1650 * k[0];
            let x2918 = x2917 - x1709;
            let x2919 = x2918 - x1711;
            let x2920 = 0.5 * x2919;
            let x2921 = x2902 + x2920;
            let x2922 = x1604 * k[0];
            let x2923 = x1718 + x2922;
            let x2924 = x1719 + x2923;
            let x2925 = 0.5 * x2924;
            let x2926 = x61 * k[2];
            let x2927 = x2925 + x2926;
            let x2928 = x1622 * k[0];
            let x2930 = x1728 - x2928;
            let x2931 = x2930 - x1729;
            let x2932 = 0.5 * x2931;
            let x2933 = x85 * k[2];
            let x2934 = x2932 + x2933;
            let x2935 = x1648 * k[0];
            let x2936 = x2935 - x1711;
            let x2937 = x2936 - x1709;
            let x2938 = 0.5 * x2937;
            let x2939 = x2884 + x2938;
            let x2940 = x1632 * k[0];
            let x2941 = x1700 + x2940;
            let x2943 = x1697 - x2941;
            let x2944 = 0.5 * x2943;
            let x2945 = x2909 + x2944;
            let x2946 = x1618 * k[0];
            let x2948 = x1729 - x2946;
            let x2949 = x2948 - x1728;
            let x2950 = 0.5 * x2949;
            let x2951 = x2933 + x2950;
            let x2952 = x1600 * k[0];
            let x2953 = x1719 + x2952;
            let x2954 = x1718 + x2953;
            let x2955 = 0.5 * x2954;
            let x2956 = x62 * k[2];
            let x2957 = x2955 + x2956;
            out[0] = 0.3;
            out[1] = 0.3;
            out[2] = 0.3;
            out[3] = x2708;
            out[4] = x2715;
            out[5] = x2722;
            out[6] = x2730;
            out[7] = x2736;
            out[8] = x2742;
            out[9] = x2748;
            out[10] = x2755;
            out[11] = x2761;
            out[12] = x2766;
            out[13] = x2772;
            out[14] = x2779;
            out[15] = x2784;
            out[16] = x2790;
            out[17] = x2796;
            out[18] = x2802;
            out[19] = 0.6;
            out[20] = 0.6;
            out[21] = 0.6;
            out[22] = x2863;
            out[23] = x2870;
            out[24] = x2877;
            out[25] = x2885;
            out[26] = x2891;
            out[27] = x2897;
            out[28] = x2903;
            out[29] = x2910;
            out[30] = x2916;
            out[31] = x2921;
            out[32] = x2927;
            out[33] = x2934;
            out[34] = x2939;
            out[35] = x2945;
            out[36] = x2951;
            out[37] = x2957;
            out[38] = 1.0;
            out[39] = x2469;
            out[40] = x2477;
            out[41] = x2490;
            out[42] = x2503;
            out[43] = x2510;
            out[44] = x2517;
            out[45] = x2526;
            out[46] = x2534;
            out[47] = x2537;
            out[48] = x2542;
            out[49] = x2545;
            out[50] = x2550;
            out[51] = x2553;
            out[52] = x2557;
            out[53] = x2560;
            out[54] = x2563;
        }
        /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
        pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
            let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 19] = qd.try_into().expect("qd must have n_coords entries");
            let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
            let _ = t;
            force_part_0(k, q, qd, out);
        }
        #[inline(never)]
        fn force_part_0(
            k: &[f64; 3],
            q: &[f64; 19],
            qd: &[f64; 19],
            out: &mut [f64; 19],
        ) {
            let x313 = 2.0 * q[3];
            let x314 = 2.0 * q[4];
            let x315 = 2.0 * q[10];
            let x316 = 2.0 * q[11];
            let x317 = 2.0 * q[12];
            let x318 = 2.0 * q[13];
            let x319 = 2.0 * q[5];
            let x320 = 2.0 * q[6];
            let x354 = 2.0 * q[17];
            let x527 = 2.0 * q[18];
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
            let x812 = 2.0 * qd[18];
            let x831 = qd[4] * qd[5];
            let x834 = qd[3] * qd[6];
            let x837 = qd[4] * qd[6];
            let x840 = qd[3] * qd[5];
            let x865 = qd[11] * qd[12];
            let x868 = qd[10] * qd[13];
            let x873 = qd[11] * qd[13];
            let x876 = qd[10] * qd[12];
            let x1062 = x610 - x609;
            let x1063 = x605 + x1062;
            let x1064 = x1063 - x606;
            let x1065 = 2.0 * x1064;
            let x1068 = x595 + x599;
            let x1070 = x600 - x1068;
            let x1071 = x596 + x1070;
            let x1072 = 2.0 * x1071;
            let x1075 = x587 - x591;
            let x1076 = x1075 - x588;
            let x1077 = x592 + x1076;
            let x1078 = 2.0 * x1077;
            let x1099 = 2.0 * x1065;
            let x1101 = 2.0 * x1072;
            let x1103 = 2.0 * x1078;
            let x1345 = x837 + x840;
            let x1347 = x840 - x1345;
            let x1348 = x837 + x1347;
            let x1349 = 2.0 * x1348;
            let x1352 = x831 - x834;
            let x1353 = x1352 - x831;
            let x1354 = x834 + x1353;
            let x1355 = 2.0 * x1354;
            let x1356 = 2.0 * x1349;
            let x1357 = 2.0 * x1355;
            let x1358 = x803 * x1099;
            let x1360 = x808 * x1101;
            let x1361 = x319 * x1356;
            let x1362 = x1360 + x1361;
            let x1363 = 0.00025 * x1362;
            let x1364 = x809 * x1103;
            let x1365 = x320 * x1357;
            let x1366 = x1364 + x1365;
            let x1367 = 0.00025 * x1366;
            let x1372 = x802 * x1099;
            let x1374 = x809 * x1101;
            let x1375 = x320 * x1356;
            let x1376 = x1374 + x1375;
            let x1377 = 0.00025 * x1376;
            let x1379 = x808 * x1103;
            let x1380 = x319 * x1357;
            let x1381 = x1379 + x1380;
            let x1382 = 0.00025 * x1381;
            let x1386 = x809 * x1099;
            let x1388 = x802 * x1101;
            let x1389 = x313 * x1356;
            let x1390 = x1388 + x1389;
            let x1391 = 0.00025 * x1390;
            let x1392 = x803 * x1103;
            let x1393 = x314 * x1357;
            let x1394 = x1392 + x1393;
            let x1395 = 0.00025 * x1394;
            let x1400 = x808 * x1099;
            let x1403 = x803 * x1101;
            let x1404 = x314 * x1356;
            let x1405 = x1403 + x1404;
            let x1406 = 0.00025 * x1405;
            let x1407 = x802 * x1103;
            let x1408 = x313 * x1357;
            let x1409 = x1407 + x1408;
            let x1410 = 0.00025 * x1409;
            let x1414 = qd[3] * qd[3];
            let x1415 = qd[4] * qd[4];
            let x1416 = qd[5] * qd[5];
            let x1417 = qd[6] * qd[6];
            let x1418 = x1414 + x1415;
            let x1419 = x1416 + x1418;
            let x1420 = x1417 + x1419;
            let x1421 = 0.00025 * x1360;
            let x1422 = 0.00025 * x1364;
            let x1437 = 0.00025 * x1374;
            let x1439 = 0.00025 * x1379;
            let x1455 = 0.00025 * x1388;
            let x1457 = 0.00025 * x1392;
            let x1471 = 0.00025 * x1403;
            let x1474 = 0.00025 * x1407;
            let x1487 = x652 - x651;
            let x1488 = x647 + x1487;
            let x1489 = x1488 - x648;
            let x1490 = 2.0 * x1489;
            let x1493 = x637 + x641;
            let x1495 = x642 - x1493;
            let x1496 = x638 + x1495;
            let x1497 = 2.0 * x1496;
            let x1500 = x627 - x631;
            let x1501 = x1500 - x628;
            let x1502 = x632 + x1501;
            let x1503 = 2.0 * x1502;
            let x1524 = 2.0 * x1490;
            let x1526 = 2.0 * x1497;
            let x1528 = 2.0 * x1503;
            let x1765 = x873 + x876;
            let x1767 = x876 - x1765;
            let x1768 = x873 + x1767;
            let x1769 = 2.0 * x1768;
            let x1772 = x865 - x868;
            let x1773 = x1772 - x865;
            let x1774 = x868 + x1773;
            let x1775 = 2.0 * x1774;
            let x1776 = 2.0 * x1769;
            let x1777 = 2.0 * x1775;
            let x1778 = x805 * x1524;
            let x1780 = x806 * x1526;
            let x1781 = x317 * x1776;
            let x1782 = x1780 + x1781;
            let x1783 = 0.006124999999999999 * x1782;
            let x1784 = x807 * x1528;
            let x1785 = x318 * x1777;
            let x1786 = x1784 + x1785;
            let x1787 = 0.006124999999999999 * x1786;
            let x1792 = x804 * x1524;
            let x1794 = x807 * x1526;
            let x1795 = x318 * x1776;
            let x1796 = x1794 + x1795;
            let x1797 = 0.006124999999999999 * x1796;
            let x1799 = x806 * x1528;
            let x1800 = x317 * x1777;
            let x1801 = x1799 + x1800;
            let x1802 = 0.006124999999999999 * x1801;
            let x1806 = x807 * x1524;
            let x1808 = x804 * x1526;
            let x1809 = x315 * x1776;
            let x1810 = x1808 + x1809;
            let x1811 = 0.006124999999999999 * x1810;
            let x1812 = x805 * x1528;
            let x1813 = x316 * x1777;
            let x1814 = x1812 + x1813;
            let x1815 = 0.006124999999999999 * x1814;
            let x1820 = x806 * x1524;
            let x1823 = x805 * x1526;
            let x1824 = x316 * x1776;
            let x1825 = x1823 + x1824;
            let x1826 = 0.006124999999999999 * x1825;
            let x1827 = x804 * x1528;
            let x1828 = x315 * x1777;
            let x1829 = x1827 + x1828;
            let x1830 = 0.006124999999999999 * x1829;
            let x1834 = qd[10] * qd[10];
            let x1835 = qd[11] * qd[11];
            let x1836 = qd[12] * qd[12];
            let x1837 = qd[13] * qd[13];
            let x1838 = x1834 + x1835;
            let x1839 = x1836 + x1838;
            let x1840 = x1837 + x1839;
            let x1841 = 0.006124999999999999 * x1780;
            let x1842 = 0.006124999999999999 * x1784;
            let x1857 = 0.006124999999999999 * x1794;
            let x1859 = 0.006124999999999999 * x1799;
            let x1875 = 0.006124999999999999 * x1808;
            let x1877 = 0.006124999999999999 * x1812;
            let x1891 = 0.006124999999999999 * x1823;
            let x1894 = 0.006124999999999999 * x1827;
            let x1927 = qd[15] * qd[15];
            let x1930 = qd[16] * qd[16];
            let x1941 = 2.0 * qd[15];
            let x1943 = 2.0 * qd[16];
            let x2217 = qd[17] * qd[17];
            let x2218 = qd[18] * qd[18];
            let x2230 = q[17] * 0.004;
            let x2249 = q[18] * 0.004;
            let x2321 = 2.0 * q[15];
            let x2343 = 2.0 * q[16];
            let x2366 = q[17] * qd[16];
            let x2367 = q[16] * qd[17];
            let x2370 = q[18] * qd[15];
            let x2371 = q[15] * qd[18];
            let x2374 = q[18] * qd[16];
            let x2375 = q[16] * qd[18];
            let x2378 = q[17] * qd[15];
            let x2379 = q[15] * qd[17];
            let x2384 = q[16] * qd[15];
            let x2385 = q[15] * qd[16];
            let x2411 = qd[16] * qd[17];
            let x2414 = qd[15] * qd[18];
            let x2417 = qd[16] * qd[18];
            let x2420 = qd[15] * qd[17];
            let x2566 = x2385 - x2384;
            let x2567 = x689 + x2566;
            let x2568 = x2567 - x690;
            let x2569 = 2.0 * x2568;
            let x2570 = x2374 + x2378;
            let x2572 = x2379 - x2570;
            let x2573 = x2375 + x2572;
            let x2574 = 2.0 * x2573;
            let x2577 = x2366 - x2370;
            let x2578 = x2577 - x2367;
            let x2579 = x2371 + x2578;
            let x2580 = 2.0 * x2579;
            let x2581 = 2.0 * x2569;
            let x2582 = 2.0 * x2574;
            let x2583 = 2.0 * x2580;
            let x2584 = x2417 + x2420;
            let x2586 = x2420 - x2584;
            let x2587 = x2417 + x2586;
            let x2588 = 2.0 * x2587;
            let x2591 = x2411 - x2414;
            let x2592 = x2591 - x2411;
            let x2593 = x2414 + x2592;
            let x2594 = 2.0 * x2593;
            let x2595 = 2.0 * x2588;
            let x2596 = 2.0 * x2594;
            let x2597 = x1943 * x2581;
            let x2598 = 0.001 * x2597;
            let x2599 = x810 * x2582;
            let x2600 = x354 * x2595;
            let x2601 = x2599 + x2600;
            let x2602 = 0.001 * x2601;
            let x2603 = x812 * x2583;
            let x2604 = x527 * x2596;
            let x2605 = x2603 + x2604;
            let x2606 = 0.001 * x2605;
            let x2607 = x2598 + x2602;
            let x2608 = x2606 + x2607;
            let x2609 = 0.5 * x2608;
            let x2610 = x1941 * x2581;
            let x2611 = 0.001 * x2610;
            let x2612 = x812 * x2582;
            let x2613 = x527 * x2595;
            let x2614 = x2612 + x2613;
            let x2615 = 0.001 * x2614;
            let x2617 = x810 * x2583;
            let x2618 = x354 * x2596;
            let x2619 = x2617 + x2618;
            let x2620 = 0.001 * x2619;
            let x2621 = x2611 - x2615;
            let x2622 = x2620 + x2621;
            let x2623 = 0.5 * x2622;
            let x2624 = x812 * x2581;
            let x2625 = 0.001 * x2624;
            let x2626 = x1941 * x2582;
            let x2627 = x2321 * x2595;
            let x2628 = x2626 + x2627;
            let x2629 = 0.001 * x2628;
            let x2630 = x1943 * x2583;
            let x2631 = x2343 * x2596;
            let x2632 = x2630 + x2631;
            let x2633 = 0.001 * x2632;
            let x2635 = x2625 + x2629;
            let x2636 = x2635 - x2633;
            let x2637 = 0.5 * x2636;
            let x2638 = x810 * x2581;
            let x2639 = 0.001 * x2638;
            let x2641 = x1943 * x2582;
            let x2642 = x2343 * x2595;
            let x2643 = x2641 + x2642;
            let x2644 = 0.001 * x2643;
            let x2645 = x1941 * x2583;
            let x2646 = x2321 * x2596;
            let x2647 = x2645 + x2646;
            let x2648 = 0.001 * x2647;
            let x2649 = x2644 - x2639;
            let x2650 = x2648 + x2649;
            let x2651 = 0.5 * x2650;
            let x2652 = x1927 + x1930;
            let x2653 = x2217 + x2652;
            let x2654 = x2218 + x2653;
            let x2655 = 0.001 * x2599;
            let x2656 = 0.001 * x2603;
            let x2657 = x2598 + x2655;
            let x2658 = x2656 + x2657;
            let x2659 = 0.5 * x2658;
            let x2660 = x2609 + x2659;
            let x2661 = q[15] * 0.004;
            let x2662 = x2654 * x2661;
            let x2664 = x2660 - x2662;
            let x2666 = 0.001 * x2612;
            let x2667 = 0.001 * x2617;
            let x2669 = x2666 - x2611;
            let x2670 = x2669 - x2667;
            let x2671 = 0.5 * x2670;
            let x2673 = x2671 - x2623;
            let x2674 = q[16] * 0.004;
            let x2675 = x2654 * x2674;
            let x2677 = x2673 - x2675;
            let x2678 = 0.001 * x2626;
            let x2679 = 0.001 * x2630;
            let x2680 = x2625 + x2678;
            let x2682 = x2679 - x2680;
            let x2683 = 0.5 * x2682;
            let x2685 = x2683 - x2637;
            let x2686 = x2230 * x2654;
            let x2688 = x2685 - x2686;
            let x2689 = 0.001 * x2641;
            let x2691 = 0.001 * x2645;
            let x2693 = x2639 - x2689;
            let x2694 = x2693 - x2691;
            let x2695 = 0.5 * x2694;
            let x2697 = x2695 - x2651;
            let x2698 = x2249 * x2654;
            let x2700 = x2697 - x2698;
            let x2803 = x1358 * k[0];
            let x2804 = x1363 + x2803;
            let x2805 = x1367 + x2804;
            let x2806 = 0.5 * x2805;
            let x2807 = x1372 * k[0];
            let x2808 = x2807 - x1377;
            let x2809 = x1382 + x2808;
            let x2810 = 0.5 * x2809;
            let x2811 = x1386 * k[0];
            let x2812 = x1391 + x2811;
            let x2813 = x2812 - x1395;
            let x2814 = 0.5 * x2813;
            let x2815 = x1400 * k[0];
            let x2817 = x1406 - x2815;
            let x2818 = x1410 + x2817;
            let x2819 = 0.5 * x2818;
            let x2820 = x1421 + x2803;
            let x2821 = x1422 + x2820;
            let x2822 = 0.5 * x2821;
            let x2823 = x2806 + x2822;
            let x2824 = q[3] * k[1];
            let x2825 = x1420 * x2824;
            let x2827 = x2823 - x2825;
            let x2829 = x1437 - x2807;
            let x2830 = x2829 - x1439;
            let x2831 = 0.5 * x2830;
            let x2833 = x2831 - x2810;
            let x2834 = q[4] * k[1];
            let x2835 = x1420 * x2834;
            let x2837 = x2833 - x2835;
            let x2838 = x1455 + x2811;
            let x2840 = x1457 - x2838;
            let x2841 = 0.5 * x2840;
            let x2843 = x2841 - x2814;
            let x2844 = q[5] * k[1];
            let x2845 = x1420 * x2844;
            let x2847 = x2843 - x2845;
            let x2848 = x2815 - x1471;
            let x2849 = x2848 - x1474;
            let x2850 = 0.5 * x2849;
            let x2852 = x2850 - x2819;
            let x2853 = q[6] * k[1];
            let x2854 = x1420 * x2853;
            let x2856 = x2852 - x2854;
            let x2958 = x1778 * k[0];
            let x2959 = x1783 + x2958;
            let x2960 = x1787 + x2959;
            let x2961 = 0.5 * x2960;
            let x2962 = x1792 * k[0];
            let x2963 = x2962 - x1797;
            let x2964 = x1802 + x2963;
            let x2965 = 0.5 * x2964;
            let x2966 = x1806 * k[0];
            let x2967 = x1811 + x2966;
            let x2968 = x2967 - x1815;
            let x2969 = 0.5 * x2968;
            let x2970 = x1820 * k[0];
            let x2972 = x1826 - x2970;
            let x2973 = x1830 + x2972;
            let x2974 = 0.5 * x2973;
            let x2975 = x1841 + x2958;
            let x2976 = x1842 + x2975;
            let x2977 = 0.5 * x2976;
            let x2978 = x2961 + x2977;
            let x2979 = q[10] * k[2];
            let x2980 = x1840 * x2979;
            let x2982 = x2978 - x2980;
            let x2984 = x1857 - x2962;
            let x2985 = x2984 - x1859;
            let x2986 = 0.5 * x2985;
            let x2988 = x2986 - x2965;
            let x2989 = q[11] * k[2];
            let x2990 = x1840 * x2989;
            let x2992 = x2988 - x2990;
            let x2993 = x1875 + x2966;
            let x2995 = x1877 - x2993;
            let x2996 = 0.5 * x2995;
            let x2998 = x2996 - x2969;
            let x2999 = q[12] * k[2];
            let x3000 = x1840 * x2999;
            let x3002 = x2998 - x3000;
            let x3003 = x2970 - x1891;
            let x3004 = x3003 - x1894;
            let x3005 = 0.5 * x3004;
            let x3007 = x3005 - x2974;
            let x3008 = q[13] * k[2];
            let x3009 = x1840 * x3008;
            let x3011 = x3007 - x3009;
            out[0] = 0.0;
            out[1] = -2.943;
            out[2] = 0.0;
            out[3] = x2827;
            out[4] = x2837;
            out[5] = x2847;
            out[6] = x2856;
            out[7] = 0.0;
            out[8] = -5.886;
            out[9] = 0.0;
            out[10] = x2982;
            out[11] = x2992;
            out[12] = x3002;
            out[13] = x3011;
            out[14] = 0.0;
            out[15] = x2664;
            out[16] = x2677;
            out[17] = x2688;
            out[18] = x2700;
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
            let k: &[f64; 3] = k.try_into().expect("k must have 3 entries");
            let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 19] = qd.try_into().expect("qd must have n_coords entries");
            let phi: &mut [f64; 19] = phi.try_into().expect("phi must have 19 entries");
            let phi_q: &mut [f64; 101] = phi_q
                .try_into()
                .expect("phi_q must have 101 entries");
            let mass: &mut [f64; 55] = mass
                .try_into()
                .expect("mass must have 55 entries");
            let force: &mut [f64; 19] = force
                .try_into()
                .expect("force must have 19 entries");
            let mut s = [0.0f64; 24];
            eval_newton_shared_0(k, q, qd, t, &mut s);
            eval_newton_part_0(k, q, t, &s, phi, phi_q, mass);
            eval_newton_part_1(k, q, qd, &s, mass, force);
        }
        #[inline(never)]
        fn eval_newton_shared_0(
            _k: &[f64; 3],
            q: &[f64; 19],
            _qd: &[f64; 19],
            _t: f64,
            s: &mut [f64; 24],
        ) {
            let x103 = q[17] * q[17];
            s[0] = x103;
            let x104 = q[18] * q[18];
            s[1] = x104;
            let x131 = q[17] * q[18];
            s[2] = x131;
            let x313 = 2.0 * q[3];
            s[3] = x313;
            let x314 = 2.0 * q[4];
            s[4] = x314;
            let x315 = 2.0 * q[10];
            s[5] = x315;
            let x316 = 2.0 * q[11];
            s[6] = x316;
            let x317 = 2.0 * q[12];
            s[7] = x317;
            let x318 = 2.0 * q[13];
            s[8] = x318;
            let x319 = 2.0 * q[5];
            s[9] = x319;
            let x320 = 2.0 * q[6];
            s[10] = x320;
            let x354 = 2.0 * q[17];
            s[11] = x354;
            let x527 = 2.0 * q[18];
            s[12] = x527;
            let x2006 = 2.0 * x527;
            s[13] = x2006;
            let x2288 = q[15] * q[15];
            s[14] = x2288;
            let x2289 = q[16] * q[16];
            s[15] = x2289;
            let x2294 = q[16] * q[17];
            s[16] = x2294;
            let x2296 = q[15] * q[18];
            s[17] = x2296;
            let x2298 = q[16] * q[18];
            s[18] = x2298;
            let x2300 = q[15] * q[17];
            s[19] = x2300;
            let x2304 = q[15] * q[16];
            s[20] = x2304;
            let x2321 = 2.0 * q[15];
            s[21] = x2321;
            let x2343 = 2.0 * q[16];
            s[22] = x2343;
            let x2344 = 2.0 * x2321;
            s[23] = x2344;
        }
        #[inline(never)]
        fn eval_newton_part_0(
            k: &[f64; 3],
            q: &[f64; 19],
            t: f64,
            s: &[f64; 24],
            phi: &mut [f64; 19],
            phi_q: &mut [f64; 101],
            mass: &mut [f64; 55],
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
            let x133 = 2.0 * s[2];
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
            let x321 = 2.0 * s[3];
            let x322 = -s[4];
            let x324 = 0.05 * x321;
            let x326 = 0.05 * s[10];
            let x328 = 0.05 * s[9];
            let x329 = -x328;
            let x330 = x298 * x321;
            let x331 = x299 * s[10];
            let x333 = x330 - x331;
            let x334 = 2.0 * s[4];
            let x335 = -s[3];
            let x336 = 0.05 * x334;
            let x338 = x298 * x334;
            let x339 = x299 * s[9];
            let x341 = x338 - x339;
            let x342 = 0.05 * s[4];
            let x344 = 0.05 * s[3];
            let x345 = -x344;
            let x346 = x299 * s[4];
            let x347 = -x346;
            let x348 = x299 * s[3];
            let x349 = -x348;
            let x350 = 2.0 * s[5];
            let x356 = 0.1749999999999999 * x350;
            let x358 = 0.000000000000000003677613769070831 * s[8];
            let x360 = 0.000000000000000013877787807814457 * s[7];
            let x361 = x356 + x358;
            let x363 = x360 - x361;
            let x364 = 0.1749999999999999 * s[8];
            let x366 = 0.000000000000000003677613769070831 * x350;
            let x367 = 0.000000000000000013877787807814457 * s[6];
            let x369 = x366 - x364;
            let x370 = x369 - x367;
            let x371 = 0.1749999999999999 * s[7];
            let x373 = 0.000000000000000003677613769070831 * s[6];
            let x374 = 0.000000000000000013877787807814457 * x350;
            let x375 = x371 + x373;
            let x376 = x374 + x375;
            let x377 = -x363;
            let x378 = -x370;
            let x379 = -x376;
            let x380 = 0.17499999999999993 * x350;
            let x381 = 0.00000000000000001061650767297806 * s[8];
            let x383 = 0.000000000000000027755575615628914 * s[7];
            let x385 = x380 + x381;
            let x386 = x385 - x383;
            let x387 = 0.17499999999999993 * s[8];
            let x388 = 0.00000000000000001061650767297806 * x350;
            let x390 = 0.000000000000000027755575615628914 * s[6];
            let x392 = x387 - x388;
            let x393 = x390 + x392;
            let x394 = 0.17499999999999993 * s[7];
            let x396 = 0.00000000000000001061650767297806 * s[6];
            let x398 = 0.000000000000000027755575615628914 * x350;
            let x400 = x394 + x396;
            let x402 = x398 + x400;
            let x404 = 0.00000000000000005551115123125783 * x350;
            let x405 = 0.9999999999999994 * s[8];
            let x407 = x404 - x405;
            let x408 = 0.00000000000000005551115123125783 * s[8];
            let x409 = 0.9999999999999994 * x350;
            let x410 = x408 + x409;
            let x411 = 0.00000000000000005551115123125783 * s[7];
            let x413 = 0.9999999999999994 * s[6];
            let x414 = x413 - x411;
            let x415 = -x386;
            let x416 = -x393;
            let x422 = 2.0 * s[6];
            let x424 = 0.1749999999999999 * x422;
            let x426 = 0.000000000000000003677613769070831 * s[7];
            let x427 = 0.000000000000000013877787807814457 * s[8];
            let x428 = x426 - x424;
            let x429 = x427 + x428;
            let x430 = 0.000000000000000013877787807814457 * s[5];
            let x432 = x371 + x430;
            let x434 = 0.000000000000000003677613769070831 * s[5];
            let x435 = x434 - x364;
            let x436 = -x429;
            let x437 = -x435;
            let x438 = 0.17499999999999993 * x422;
            let x439 = 0.00000000000000001061650767297806 * s[7];
            let x441 = 0.000000000000000027755575615628914 * s[8];
            let x443 = x438 - x439;
            let x444 = x443 - x441;
            let x445 = 0.000000000000000027755575615628914 * s[5];
            let x447 = x394 + x445;
            let x448 = 0.00000000000000001061650767297806 * s[5];
            let x450 = x387 - x448;
            let x451 = 0.00000000000000005551115123125783 * x422;
            let x452 = 0.9999999999999994 * s[7];
            let x453 = x451 + x452;
            let x454 = 0.9999999999999994 * s[5];
            let x455 = x408 + x454;
            let x456 = -x444;
            let x457 = -x447;
            let x458 = -x450;
            let x464 = 2.0 * s[7];
            let x465 = x373 + x430;
            let x466 = 0.1749999999999999 * s[6];
            let x468 = 0.000000000000000003677613769070831 * x464;
            let x469 = x468 - x466;
            let x470 = x427 + x469;
            let x471 = 0.1749999999999999 * s[5];
            let x473 = x358 + x471;
            let x474 = -x465;
            let x475 = -x470;
            let x476 = -x473;
            let x477 = x396 + x445;
            let x479 = 0.17499999999999993 * s[6];
            let x480 = 0.00000000000000001061650767297806 * x464;
            let x482 = x479 - x480;
            let x483 = x482 - x441;
            let x484 = 0.17499999999999993 * s[5];
            let x486 = x381 + x484;
            let x488 = 0.00000000000000005551115123125783 * s[6];
            let x489 = 0.9999999999999994 * x464;
            let x490 = x488 + x489;
            let x491 = 0.00000000000000005551115123125783 * s[5];
            let x493 = x405 - x491;
            let x494 = -x483;
            let x500 = 2.0 * s[8];
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
            let x533 = x276 * s[12];
            let x538 = -s[11];
            let x540 = x276 * s[11];
            let x543 = x273 * s[11];
            let x547 = x273 * s[12];
            let x1172 = 2.0 * s[9];
            let x1174 = 2.0 * s[10];
            let x1176 = s[4] * x334;
            let x1180 = s[9] * x1172;
            let x1182 = 0.00025 * x1180;
            let x1184 = s[10] * x1174;
            let x1186 = 0.00025 * x1184;
            let x1196 = s[4] * x321;
            let x1198 = s[9] * x1174;
            let x1200 = 0.00025 * x1198;
            let x1202 = s[10] * x1172;
            let x1203 = 0.00025 * x1202;
            let x1210 = s[4] * x1174;
            let x1212 = s[9] * x321;
            let x1213 = 0.00025 * x1212;
            let x1214 = s[10] * x334;
            let x1216 = 0.00025 * x1214;
            let x1224 = s[4] * x1172;
            let x1228 = s[9] * x334;
            let x1229 = 0.00025 * x1228;
            let x1230 = s[10] * x321;
            let x1231 = 0.00025 * x1230;
            let x1238 = s[3] * x334;
            let x1248 = s[3] * x321;
            let x1255 = s[3] * x1174;
            let x1265 = s[3] * x1172;
            let x1277 = 0.00025 * x1265;
            let x1280 = 0.00025 * x1210;
            let x1289 = 0.00025 * x1255;
            let x1291 = 0.00025 * x1224;
            let x1298 = 0.00025 * x1248;
            let x1299 = 0.00025 * x1176;
            let x1308 = 0.00025 * x1238;
            let x1309 = 0.00025 * x1196;
            let x1596 = s[6] * x422;
            let x1600 = s[7] * x464;
            let x1602 = 0.006124999999999999 * x1600;
            let x1604 = s[8] * x500;
            let x1606 = 0.006124999999999999 * x1604;
            let x1616 = s[6] * x350;
            let x1618 = s[7] * x500;
            let x1620 = 0.006124999999999999 * x1618;
            let x1622 = s[8] * x464;
            let x1623 = 0.006124999999999999 * x1622;
            let x1630 = s[6] * x500;
            let x1632 = s[7] * x350;
            let x1633 = 0.006124999999999999 * x1632;
            let x1634 = s[8] * x422;
            let x1636 = 0.006124999999999999 * x1634;
            let x1644 = s[6] * x464;
            let x1648 = s[7] * x422;
            let x1649 = 0.006124999999999999 * x1648;
            let x1650 = s[8] * x350;
            let x1651 = 0.006124999999999999 * x1650;
            let x1658 = s[5] * x422;
            let x1668 = s[5] * x350;
            let x1675 = s[5] * x500;
            let x1685 = s[5] * x464;
            let x1697 = 0.006124999999999999 * x1685;
            let x1700 = 0.006124999999999999 * x1630;
            let x1709 = 0.006124999999999999 * x1675;
            let x1711 = 0.006124999999999999 * x1644;
            let x1718 = 0.006124999999999999 * x1668;
            let x1719 = 0.006124999999999999 * x1596;
            let x1728 = 0.006124999999999999 * x1658;
            let x1729 = 0.006124999999999999 * x1616;
            let x2290 = s[14] + s[15];
            let x2291 = s[1] + s[14];
            let x2292 = 2.0 * x2291;
            let x2293 = x2292 - 1.0;
            let x2295 = 2.0 * s[16];
            let x2297 = 2.0 * s[17];
            let x2299 = 2.0 * s[18];
            let x2301 = 2.0 * s[19];
            let x2302 = x2299 + x2301;
            let x2303 = x2295 + x2297;
            let x2305 = 2.0 * s[20];
            let x2307 = x133 - x2305;
            let x2309 = x2299 - x2301;
            let x2310 = x133 + x2305;
            let x2311 = 0.05 - x215;
            let x2312 = 0.12 - x216;
            let x2313 = x273 * x2302;
            let x2314 = x276 * x2307;
            let x2315 = x279 * x2293;
            let x2316 = x2313 + x2314;
            let x2317 = x2315 + x2316;
            let x2318 = s[0] + x2290;
            let x2319 = s[1] + x2318;
            let x2320 = x2319 - 1.0;
            let x2322 = x407 * x2302;
            let x2323 = x410 * x2307;
            let x2324 = x414 * x2293;
            let x2325 = x2322 + x2323;
            let x2326 = x2324 + x2325;
            let x2327 = x453 * x2302;
            let x2328 = x411 * x2307;
            let x2329 = x455 * x2293;
            let x2330 = x2327 + x2328;
            let x2331 = x2329 + x2330;
            let x2332 = x413 * x2302;
            let x2333 = x490 * x2307;
            let x2334 = x493 * x2293;
            let x2335 = x2332 + x2333;
            let x2336 = x2334 + x2335;
            let x2337 = x454 * x2302;
            let x2339 = x491 * x2307;
            let x2340 = x517 * x2293;
            let x2341 = x2339 - x2337;
            let x2342 = x2340 + x2341;
            let x2346 = x276 * s[22];
            let x2348 = x279 * s[23];
            let x2349 = x543 - x2346;
            let x2350 = x2348 + x2349;
            let x2351 = -s[21];
            let x2352 = x276 * s[21];
            let x2354 = x547 - x2352;
            let x2355 = x273 * s[21];
            let x2356 = x533 + x2355;
            let x2357 = x273 * s[22];
            let x2358 = x279 * s[13];
            let x2359 = x540 + x2357;
            let x2360 = x2358 + x2359;
            let x2703 = x1176 * k[0];
            let x2704 = x1182 + x2703;
            let x2705 = x1186 + x2704;
            let x2706 = 0.5 * x2705;
            let x2707 = x14 * k[1];
            let x2708 = x2706 + x2707;
            let x2709 = x1196 * k[0];
            let x2710 = x2709 - x1200;
            let x2711 = x1203 + x2710;
            let x2712 = 0.5 * x2711;
            let x2714 = x43 * k[1];
            let x2715 = x2714 - x2712;
            let x2716 = x1210 * k[0];
            let x2717 = x1213 + x2716;
            let x2718 = x2717 - x1216;
            let x2719 = 0.5 * x2718;
            let x2721 = x37 * k[1];
            let x2722 = x2721 - x2719;
            let x2723 = x1224 * k[0];
            let x2725 = x1229 - x2723;
            let x2726 = x1231 + x2725;
            let x2727 = 0.5 * x2726;
            let x2729 = x30 * k[1];
            let x2730 = x2729 - x2727;
            let x2731 = x1238 * k[0];
            let x2733 = x1203 - x2731;
            let x2734 = x2733 - x1200;
            let x2735 = 0.5 * x2734;
            let x2736 = x2714 + x2735;
            let x2737 = x1248 * k[0];
            let x2738 = x1186 + x2737;
            let x2739 = x1182 + x2738;
            let x2740 = 0.5 * x2739;
            let x2741 = x15 * k[1];
            let x2742 = x2740 + x2741;
            let x2743 = x1255 * k[0];
            let x2744 = x2743 - x1231;
            let x2745 = x2744 - x1229;
            let x2746 = 0.5 * x2745;
            let x2747 = x28 * k[1];
            let x2748 = x2746 + x2747;
            let x2749 = x1265 * k[0];
            let x2750 = x1216 + x2749;
            let x2752 = x1213 - x2750;
            let x2753 = 0.5 * x2752;
            let x2754 = x35 * k[1];
            let x2755 = x2753 + x2754;
            let x2756 = x1214 * k[0];
            let x2757 = x1277 + x2756;
            let x2759 = x1280 - x2757;
            let x2760 = 0.5 * x2759;
            let x2761 = x2721 + x2760;
            let x2762 = x1230 * k[0];
            let x2763 = x2762 - x1289;
            let x2764 = x2763 - x1291;
            let x2765 = 0.5 * x2764;
            let x2766 = x2747 + x2765;
            let x2767 = x1184 * k[0];
            let x2768 = x1298 + x2767;
            let x2769 = x1299 + x2768;
            let x2770 = 0.5 * x2769;
            let x2771 = x16 * k[1];
            let x2772 = x2770 + x2771;
            let x2773 = x1202 * k[0];
            let x2775 = x1308 - x2773;
            let x2776 = x2775 - x1309;
            let x2777 = 0.5 * x2776;
            let x2778 = x41 * k[1];
            let x2779 = x2777 + x2778;
            let x2780 = x1228 * k[0];
            let x2781 = x2780 - x1291;
            let x2782 = x2781 - x1289;
            let x2783 = 0.5 * x2782;
            let x2784 = x2729 + x2783;
            let x2785 = x1212 * k[0];
            let x2786 = x1280 + x2785;
            let x2788 = x1277 - x2786;
            let x2789 = 0.5 * x2788;
            let x2790 = x2754 + x2789;
            let x2791 = x1198 * k[0];
            let x2793 = x1309 - x2791;
            let x2794 = x2793 - x1308;
            let x2795 = 0.5 * x2794;
            let x2796 = x2778 + x2795;
            let x2797 = x1180 * k[0];
            let x2798 = x1299 + x2797;
            let x2799 = x1298 + x2798;
            let x2800 = 0.5 * x2799;
            let x2801 = x17 * k[1];
            let x2802 = x2800 + x2801;
            let x2858 = x1596 * k[0];
            let x2859 = x1602 + x2858;
            let x2860 = x1606 + x2859;
            let x2861 = 0.5 * x2860;
            let x2862 = x59 * k[2];
            let x2863 = x2861 + x2862;
            let x2864 = x1616 * k[0];
            let x2865 = x2864 - x1620;
            let x2866 = x1623 + x2865;
            let x2867 = 0.5 * x2866;
            let x2869 = x87 * k[2];
            let x2870 = x2869 - x2867;
            let x2871 = x1630 * k[0];
            let x2872 = x1633 + x2871;
            let x2873 = x2872 - x1636;
            let x2874 = 0.5 * x2873;
            let x2876 = x81 * k[2];
            let x2877 = x2876 - x2874;
            let x2878 = x1644 * k[0];
            let x2880 = x1649 - x2878;
            let x2881 = x1651 + x2880;
            let x2882 = 0.5 * x2881;
            let x2884 = x74 * k[2];
            let x2885 = x2884 - x2882;
            let x2886 = x1658 * k[0];
            let x2888 = x1623 - x2886;
            let x2889 = x2888 - x1620;
            let x2890 = 0.5 * x2889;
            let x2891 = x2869 + x2890;
            let x2892 = x1668 * k[0];
            let x2893 = x1606 + x2892;
            let x2894 = x1602 + x2893;
            let x2895 = 0.5 * x2894;
            let x2896 = x60 * k[2];
            let x2897 = x2895 + x2896;
            let x2898 = x1675 * k[0];
            let x2899 = x2898 - x1651;
            let x2900 = x2899 - x1649;
            let x2901 = 0.5 * x2900;
            let x2902 = x72 * k[2];
            let x2903 = x2901 + x2902;
            let x2904 = x1685 * k[0];
            let x2905 = x1636 + x2904;
            let x2907 = x1633 - x2905;
            let x2908 = 0.5 * x2907;
            let x2909 = x79 * k[2];
            let x2910 = x2908 + x2909;
            let x2911 = x1634 * k[0];
            let x2912 = x1697 + x2911;
            let x2914 = x1700 - x2912;
            let x2915 = 0.5 * x2914;
            let x2916 = x2876 + x2915;
            let x2917 = x1650 * k[0];
            let x2918 = x2917 - x1709;
            let x2919 = x2918 - x1711;
            let x2920 = 0.5 * x2919;
            let x2921 = x2902 + x2920;
            let x2922 = x1604 * k[0];
            let x2923 = x1718 + x2922;
            let x2924 = x1719 + x2923;
            let x2925 = 0.5 * x2924;
            let x2926 = x61 * k[2];
            let x2927 = x2925 + x2926;
            let x2928 = x1622 * k[0];
            let x2930 = x1728 - x2928;
            let x2931 = x2930 - x1729;
            let x2932 = 0.5 * x2931;
            let x2933 = x85 * k[2];
            let x2934 = x2932 + x2933;
            let x2935 = x1648 * k[0];
            let x2936 = x2935 - x1711;
            let x2937 = x2936 - x1709;
            let x2938 = 0.5 * x2937;
            let x2939 = x2884 + x2938;
            let x2940 = x1632 * k[0];
            let x2941 = x1700 + x2940;
            let x2943 = x1697 - x2941;
            let x2944 = 0.5 * x2943;
            let x2945 = x2909 + x2944;
            let x2946 = x1618 * k[0];
            let x2948 = x1729 - x2946;
            let x2949 = x2948 - x1728;
            let x2950 = 0.5 * x2949;
            let x2951 = x2933 + x2950;
            let x2952 = x1600 * k[0];
            let x2953 = x1719 + x2952;
            let x2954 = x1718 + x2953;
            let x2955 = 0.5 * x2954;
            let x2956 = x62 * k[2];
            let x2957 = x2955 + x2956;
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
            phi_q[13] = s[9];
            phi_q[14] = s[10];
            phi_q[15] = s[3];
            phi_q[16] = s[4];
            phi[4] = x47;
            phi_q[17] = x322;
            phi_q[18] = x335;
            phi_q[19] = s[10];
            phi_q[20] = s[9];
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
            phi[9] = x2311;
            phi_q[55] = -1.0;
            phi_q[56] = x416;
            phi_q[57] = x457;
            phi_q[58] = x494;
            phi_q[59] = x519;
            phi[10] = x2312;
            phi_q[60] = -1.0;
            phi_q[61] = x402;
            phi_q[62] = x458;
            phi_q[63] = x486;
            phi_q[64] = x520;
            phi[11] = x2317;
            phi_q[65] = x2326;
            phi_q[66] = x2331;
            phi_q[67] = x2336;
            phi_q[68] = x2342;
            phi_q[69] = x2350;
            phi_q[70] = x2354;
            phi_q[71] = x2356;
            phi_q[72] = x2360;
            phi[12] = x2303;
            phi_q[73] = s[12];
            phi_q[74] = s[11];
            phi_q[75] = s[22];
            phi_q[76] = s[21];
            phi[13] = x2309;
            phi_q[77] = x538;
            phi_q[78] = s[12];
            phi_q[79] = x2351;
            phi_q[80] = s[22];
            phi[14] = x2310;
            phi_q[81] = s[22];
            phi_q[82] = s[21];
            phi_q[83] = s[12];
            phi_q[84] = s[11];
            phi[15] = x303;
            phi_q[85] = x333;
            phi_q[86] = x341;
            phi_q[87] = x347;
            phi_q[88] = x349;
            phi[16] = x306;
            phi_q[89] = s[3];
            phi_q[90] = s[4];
            phi_q[91] = s[9];
            phi_q[92] = s[10];
            phi[17] = x309;
            phi_q[93] = s[5];
            phi_q[94] = s[6];
            phi_q[95] = s[7];
            phi_q[96] = s[8];
            phi[18] = x2320;
            phi_q[97] = s[21];
            phi_q[98] = s[22];
            phi_q[99] = s[11];
            phi_q[100] = s[12];
            mass[0] = 0.3;
            mass[1] = 0.3;
            mass[2] = 0.3;
            mass[3] = x2708;
            mass[4] = x2715;
            mass[5] = x2722;
            mass[6] = x2730;
            mass[7] = x2736;
            mass[8] = x2742;
            mass[9] = x2748;
            mass[10] = x2755;
            mass[11] = x2761;
            mass[12] = x2766;
            mass[13] = x2772;
            mass[14] = x2779;
            mass[15] = x2784;
            mass[16] = x2790;
            mass[17] = x2796;
            mass[18] = x2802;
            mass[19] = 0.6;
            mass[20] = 0.6;
            mass[21] = 0.6;
            mass[22] = x2863;
            mass[23] = x2870;
            mass[24] = x2877;
            mass[25] = x2885;
            mass[26] = x2891;
            mass[27] = x2897;
            mass[28] = x2903;
            mass[29] = x2910;
            mass[30] = x2916;
            mass[31] = x2921;
            mass[32] = x2927;
            mass[33] = x2934;
            mass[34] = x2939;
            mass[35] = x2945;
            mass[36] = x2951;
            mass[37] = x2957;
            mass[38] = 1.0;
        }
        #[inline(never)]
        fn eval_newton_part_1(
            k: &[f64; 3],
            q: &[f64; 19],
            qd: &[f64; 19],
            s: &[f64; 24],
            mass: &mut [f64; 55],
            force: &mut [f64; 19],
        ) {
            let x529 = 2.0 * s[11];
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
            let x812 = 2.0 * qd[18];
            let x831 = qd[4] * qd[5];
            let x834 = qd[3] * qd[6];
            let x837 = qd[4] * qd[6];
            let x840 = qd[3] * qd[5];
            let x865 = qd[11] * qd[12];
            let x868 = qd[10] * qd[13];
            let x873 = qd[11] * qd[13];
            let x876 = qd[10] * qd[12];
            let x1062 = x610 - x609;
            let x1063 = x605 + x1062;
            let x1064 = x1063 - x606;
            let x1065 = 2.0 * x1064;
            let x1068 = x595 + x599;
            let x1070 = x600 - x1068;
            let x1071 = x596 + x1070;
            let x1072 = 2.0 * x1071;
            let x1075 = x587 - x591;
            let x1076 = x1075 - x588;
            let x1077 = x592 + x1076;
            let x1078 = 2.0 * x1077;
            let x1099 = 2.0 * x1065;
            let x1101 = 2.0 * x1072;
            let x1103 = 2.0 * x1078;
            let x1345 = x837 + x840;
            let x1347 = x840 - x1345;
            let x1348 = x837 + x1347;
            let x1349 = 2.0 * x1348;
            let x1352 = x831 - x834;
            let x1353 = x1352 - x831;
            let x1354 = x834 + x1353;
            let x1355 = 2.0 * x1354;
            let x1356 = 2.0 * x1349;
            let x1357 = 2.0 * x1355;
            let x1358 = x803 * x1099;
            let x1360 = x808 * x1101;
            let x1361 = s[9] * x1356;
            let x1362 = x1360 + x1361;
            let x1363 = 0.00025 * x1362;
            let x1364 = x809 * x1103;
            let x1365 = s[10] * x1357;
            let x1366 = x1364 + x1365;
            let x1367 = 0.00025 * x1366;
            let x1372 = x802 * x1099;
            let x1374 = x809 * x1101;
            let x1375 = s[10] * x1356;
            let x1376 = x1374 + x1375;
            let x1377 = 0.00025 * x1376;
            let x1379 = x808 * x1103;
            let x1380 = s[9] * x1357;
            let x1381 = x1379 + x1380;
            let x1382 = 0.00025 * x1381;
            let x1386 = x809 * x1099;
            let x1388 = x802 * x1101;
            let x1389 = s[3] * x1356;
            let x1390 = x1388 + x1389;
            let x1391 = 0.00025 * x1390;
            let x1392 = x803 * x1103;
            let x1393 = s[4] * x1357;
            let x1394 = x1392 + x1393;
            let x1395 = 0.00025 * x1394;
            let x1400 = x808 * x1099;
            let x1403 = x803 * x1101;
            let x1404 = s[4] * x1356;
            let x1405 = x1403 + x1404;
            let x1406 = 0.00025 * x1405;
            let x1407 = x802 * x1103;
            let x1408 = s[3] * x1357;
            let x1409 = x1407 + x1408;
            let x1410 = 0.00025 * x1409;
            let x1414 = qd[3] * qd[3];
            let x1415 = qd[4] * qd[4];
            let x1416 = qd[5] * qd[5];
            let x1417 = qd[6] * qd[6];
            let x1418 = x1414 + x1415;
            let x1419 = x1416 + x1418;
            let x1420 = x1417 + x1419;
            let x1421 = 0.00025 * x1360;
            let x1422 = 0.00025 * x1364;
            let x1437 = 0.00025 * x1374;
            let x1439 = 0.00025 * x1379;
            let x1455 = 0.00025 * x1388;
            let x1457 = 0.00025 * x1392;
            let x1471 = 0.00025 * x1403;
            let x1474 = 0.00025 * x1407;
            let x1487 = x652 - x651;
            let x1488 = x647 + x1487;
            let x1489 = x1488 - x648;
            let x1490 = 2.0 * x1489;
            let x1493 = x637 + x641;
            let x1495 = x642 - x1493;
            let x1496 = x638 + x1495;
            let x1497 = 2.0 * x1496;
            let x1500 = x627 - x631;
            let x1501 = x1500 - x628;
            let x1502 = x632 + x1501;
            let x1503 = 2.0 * x1502;
            let x1524 = 2.0 * x1490;
            let x1526 = 2.0 * x1497;
            let x1528 = 2.0 * x1503;
            let x1765 = x873 + x876;
            let x1767 = x876 - x1765;
            let x1768 = x873 + x1767;
            let x1769 = 2.0 * x1768;
            let x1772 = x865 - x868;
            let x1773 = x1772 - x865;
            let x1774 = x868 + x1773;
            let x1775 = 2.0 * x1774;
            let x1776 = 2.0 * x1769;
            let x1777 = 2.0 * x1775;
            let x1778 = x805 * x1524;
            let x1780 = x806 * x1526;
            let x1781 = s[7] * x1776;
            let x1782 = x1780 + x1781;
            let x1783 = 0.006124999999999999 * x1782;
            let x1784 = x807 * x1528;
            let x1785 = s[8] * x1777;
            let x1786 = x1784 + x1785;
            let x1787 = 0.006124999999999999 * x1786;
            let x1792 = x804 * x1524;
            let x1794 = x807 * x1526;
            let x1795 = s[8] * x1776;
            let x1796 = x1794 + x1795;
            let x1797 = 0.006124999999999999 * x1796;
            let x1799 = x806 * x1528;
            let x1800 = s[7] * x1777;
            let x1801 = x1799 + x1800;
            let x1802 = 0.006124999999999999 * x1801;
            let x1806 = x807 * x1524;
            let x1808 = x804 * x1526;
            let x1809 = s[5] * x1776;
            let x1810 = x1808 + x1809;
            let x1811 = 0.006124999999999999 * x1810;
            let x1812 = x805 * x1528;
            let x1813 = s[6] * x1777;
            let x1814 = x1812 + x1813;
            let x1815 = 0.006124999999999999 * x1814;
            let x1820 = x806 * x1524;
            let x1823 = x805 * x1526;
            let x1824 = s[6] * x1776;
            let x1825 = x1823 + x1824;
            let x1826 = 0.006124999999999999 * x1825;
            let x1827 = x804 * x1528;
            let x1828 = s[5] * x1777;
            let x1829 = x1827 + x1828;
            let x1830 = 0.006124999999999999 * x1829;
            let x1834 = qd[10] * qd[10];
            let x1835 = qd[11] * qd[11];
            let x1836 = qd[12] * qd[12];
            let x1837 = qd[13] * qd[13];
            let x1838 = x1834 + x1835;
            let x1839 = x1836 + x1838;
            let x1840 = x1837 + x1839;
            let x1841 = 0.006124999999999999 * x1780;
            let x1842 = 0.006124999999999999 * x1784;
            let x1857 = 0.006124999999999999 * x1794;
            let x1859 = 0.006124999999999999 * x1799;
            let x1875 = 0.006124999999999999 * x1808;
            let x1877 = 0.006124999999999999 * x1812;
            let x1891 = 0.006124999999999999 * x1823;
            let x1894 = 0.006124999999999999 * x1827;
            let x1927 = qd[15] * qd[15];
            let x1930 = qd[16] * qd[16];
            let x1941 = 2.0 * qd[15];
            let x1943 = 2.0 * qd[16];
            let x2011 = s[12] * s[13];
            let x2013 = 0.001 * x2011;
            let x2029 = s[0] * 0.004;
            let x2031 = s[12] * x529;
            let x2032 = 0.001 * x2031;
            let x2043 = s[2] * 0.004;
            let x2073 = s[11] * s[13];
            let x2075 = 0.001 * x2073;
            let x2083 = s[11] * x529;
            let x2084 = 0.001 * x2083;
            let x2088 = s[1] * 0.004;
            let x2217 = qd[17] * qd[17];
            let x2218 = qd[18] * qd[18];
            let x2230 = q[17] * 0.004;
            let x2249 = q[18] * 0.004;
            let x2366 = q[17] * qd[16];
            let x2367 = q[16] * qd[17];
            let x2370 = q[18] * qd[15];
            let x2371 = q[15] * qd[18];
            let x2374 = q[18] * qd[16];
            let x2375 = q[16] * qd[18];
            let x2378 = q[17] * qd[15];
            let x2379 = q[15] * qd[17];
            let x2384 = q[16] * qd[15];
            let x2385 = q[15] * qd[16];
            let x2411 = qd[16] * qd[17];
            let x2414 = qd[15] * qd[18];
            let x2417 = qd[16] * qd[18];
            let x2420 = qd[15] * qd[17];
            let x2462 = 2.0 * s[22];
            let x2463 = s[22] * x2462;
            let x2464 = 0.001 * x2463;
            let x2465 = x2084 + x2464;
            let x2466 = x2013 + x2465;
            let x2467 = 0.5 * x2466;
            let x2468 = 0.004 * s[14];
            let x2469 = x2467 + x2468;
            let x2470 = s[22] * s[23];
            let x2471 = 0.001 * x2470;
            let x2472 = x2471 - x2075;
            let x2473 = x2032 + x2472;
            let x2474 = 0.5 * x2473;
            let x2476 = 0.004 * s[20];
            let x2477 = x2476 - x2474;
            let x2478 = s[13] * s[22];
            let x2479 = 0.001 * x2478;
            let x2480 = s[11] * s[23];
            let x2481 = 0.001 * x2480;
            let x2482 = s[12] * x2462;
            let x2483 = 0.001 * x2482;
            let x2485 = x2479 + x2481;
            let x2486 = x2485 - x2483;
            let x2487 = 0.5 * x2486;
            let x2489 = 0.004 * s[19];
            let x2490 = x2489 - x2487;
            let x2491 = x529 * s[22];
            let x2492 = 0.001 * x2491;
            let x2494 = s[11] * x2462;
            let x2495 = 0.001 * x2494;
            let x2496 = s[12] * s[23];
            let x2497 = 0.001 * x2496;
            let x2498 = x2495 - x2492;
            let x2499 = x2497 + x2498;
            let x2500 = 0.5 * x2499;
            let x2502 = 0.004 * s[17];
            let x2503 = x2502 - x2500;
            let x2504 = s[21] * x2462;
            let x2505 = 0.001 * x2504;
            let x2507 = x2032 - x2505;
            let x2508 = x2507 - x2075;
            let x2509 = 0.5 * x2508;
            let x2510 = x2476 + x2509;
            let x2511 = s[21] * s[23];
            let x2512 = 0.001 * x2511;
            let x2513 = x2013 + x2512;
            let x2514 = x2084 + x2513;
            let x2515 = 0.5 * x2514;
            let x2516 = 0.004 * s[15];
            let x2517 = x2515 + x2516;
            let x2518 = s[13] * s[21];
            let x2519 = 0.001 * x2518;
            let x2522 = x2519 - x2497;
            let x2523 = x2522 - x2495;
            let x2524 = 0.5 * x2523;
            let x2525 = 0.004 * s[16];
            let x2526 = x2524 + x2525;
            let x2527 = x529 * s[21];
            let x2528 = 0.001 * x2527;
            let x2529 = x2483 + x2528;
            let x2531 = x2481 - x2529;
            let x2532 = 0.5 * x2531;
            let x2533 = 0.004 * s[18];
            let x2534 = x2532 + x2533;
            let x2535 = x2479 - x2529;
            let x2536 = 0.5 * x2535;
            let x2537 = x2489 + x2536;
            let x2539 = x2497 - x2519;
            let x2540 = x2539 - x2492;
            let x2541 = 0.5 * x2540;
            let x2542 = x2525 + x2541;
            let x2543 = x2464 + x2513;
            let x2544 = 0.5 * x2543;
            let x2545 = x2029 + x2544;
            let x2547 = x2505 - x2032;
            let x2548 = x2547 - x2471;
            let x2549 = 0.5 * x2548;
            let x2550 = x2043 + x2549;
            let x2551 = x2498 - x2519;
            let x2552 = 0.5 * x2551;
            let x2553 = x2502 + x2552;
            let x2555 = x2528 - x2485;
            let x2556 = 0.5 * x2555;
            let x2557 = x2533 + x2556;
            let x2558 = x2472 - x2505;
            let x2559 = 0.5 * x2558;
            let x2560 = x2043 + x2559;
            let x2561 = x2465 + x2512;
            let x2562 = 0.5 * x2561;
            let x2563 = x2088 + x2562;
            let x2566 = x2385 - x2384;
            let x2567 = x689 + x2566;
            let x2568 = x2567 - x690;
            let x2569 = 2.0 * x2568;
            let x2570 = x2374 + x2378;
            let x2572 = x2379 - x2570;
            let x2573 = x2375 + x2572;
            let x2574 = 2.0 * x2573;
            let x2577 = x2366 - x2370;
            let x2578 = x2577 - x2367;
            let x2579 = x2371 + x2578;
            let x2580 = 2.0 * x2579;
            let x2581 = 2.0 * x2569;
            let x2582 = 2.0 * x2574;
            let x2583 = 2.0 * x2580;
            let x2584 = x2417 + x2420;
            let x2586 = x2420 - x2584;
            let x2587 = x2417 + x2586;
            let x2588 = 2.0 * x2587;
            let x2591 = x2411 - x2414;
            let x2592 = x2591 - x2411;
            let x2593 = x2414 + x2592;
            let x2594 = 2.0 * x2593;
            let x2595 = 2.0 * x2588;
            let x2596 = 2.0 * x2594;
            let x2597 = x1943 * x2581;
            let x2598 = 0.001 * x2597;
            let x2599 = x810 * x2582;
            let x2600 = s[11] * x2595;
            let x2601 = x2599 + x2600;
            let x2602 = 0.001 * x2601;
            let x2603 = x812 * x2583;
            let x2604 = s[12] * x2596;
            let x2605 = x2603 + x2604;
            let x2606 = 0.001 * x2605;
            let x2607 = x2598 + x2602;
            let x2608 = x2606 + x2607;
            let x2609 = 0.5 * x2608;
            let x2610 = x1941 * x2581;
            let x2611 = 0.001 * x2610;
            let x2612 = x812 * x2582;
            let x2613 = s[12] * x2595;
            let x2614 = x2612 + x2613;
            let x2615 = 0.001 * x2614;
            let x2617 = x810 * x2583;
            let x2618 = s[11] * x2596;
            let x2619 = x2617 + x2618;
            let x2620 = 0.001 * x2619;
            let x2621 = x2611 - x2615;
            let x2622 = x2620 + x2621;
            let x2623 = 0.5 * x2622;
            let x2624 = x812 * x2581;
            let x2625 = 0.001 * x2624;
            let x2626 = x1941 * x2582;
            let x2627 = s[21] * x2595;
            let x2628 = x2626 + x2627;
            let x2629 = 0.001 * x2628;
            let x2630 = x1943 * x2583;
            let x2631 = s[22] * x2596;
            let x2632 = x2630 + x2631;
            let x2633 = 0.001 * x2632;
            let x2635 = x2625 + x2629;
            let x2636 = x2635 - x2633;
            let x2637 = 0.5 * x2636;
            let x2638 = x810 * x2581;
            let x2639 = 0.001 * x2638;
            let x2641 = x1943 * x2582;
            let x2642 = s[22] * x2595;
            let x2643 = x2641 + x2642;
            let x2644 = 0.001 * x2643;
            let x2645 = x1941 * x2583;
            let x2646 = s[21] * x2596;
            let x2647 = x2645 + x2646;
            let x2648 = 0.001 * x2647;
            let x2649 = x2644 - x2639;
            let x2650 = x2648 + x2649;
            let x2651 = 0.5 * x2650;
            let x2652 = x1927 + x1930;
            let x2653 = x2217 + x2652;
            let x2654 = x2218 + x2653;
            let x2655 = 0.001 * x2599;
            let x2656 = 0.001 * x2603;
            let x2657 = x2598 + x2655;
            let x2658 = x2656 + x2657;
            let x2659 = 0.5 * x2658;
            let x2660 = x2609 + x2659;
            let x2661 = q[15] * 0.004;
            let x2662 = x2654 * x2661;
            let x2664 = x2660 - x2662;
            let x2666 = 0.001 * x2612;
            let x2667 = 0.001 * x2617;
            let x2669 = x2666 - x2611;
            let x2670 = x2669 - x2667;
            let x2671 = 0.5 * x2670;
            let x2673 = x2671 - x2623;
            let x2674 = q[16] * 0.004;
            let x2675 = x2654 * x2674;
            let x2677 = x2673 - x2675;
            let x2678 = 0.001 * x2626;
            let x2679 = 0.001 * x2630;
            let x2680 = x2625 + x2678;
            let x2682 = x2679 - x2680;
            let x2683 = 0.5 * x2682;
            let x2685 = x2683 - x2637;
            let x2686 = x2230 * x2654;
            let x2688 = x2685 - x2686;
            let x2689 = 0.001 * x2641;
            let x2691 = 0.001 * x2645;
            let x2693 = x2639 - x2689;
            let x2694 = x2693 - x2691;
            let x2695 = 0.5 * x2694;
            let x2697 = x2695 - x2651;
            let x2698 = x2249 * x2654;
            let x2700 = x2697 - x2698;
            let x2803 = x1358 * k[0];
            let x2804 = x1363 + x2803;
            let x2805 = x1367 + x2804;
            let x2806 = 0.5 * x2805;
            let x2807 = x1372 * k[0];
            let x2808 = x2807 - x1377;
            let x2809 = x1382 + x2808;
            let x2810 = 0.5 * x2809;
            let x2811 = x1386 * k[0];
            let x2812 = x1391 + x2811;
            let x2813 = x2812 - x1395;
            let x2814 = 0.5 * x2813;
            let x2815 = x1400 * k[0];
            let x2817 = x1406 - x2815;
            let x2818 = x1410 + x2817;
            let x2819 = 0.5 * x2818;
            let x2820 = x1421 + x2803;
            let x2821 = x1422 + x2820;
            let x2822 = 0.5 * x2821;
            let x2823 = x2806 + x2822;
            let x2824 = q[3] * k[1];
            let x2825 = x1420 * x2824;
            let x2827 = x2823 - x2825;
            let x2829 = x1437 - x2807;
            let x2830 = x2829 - x1439;
            let x2831 = 0.5 * x2830;
            let x2833 = x2831 - x2810;
            let x2834 = q[4] * k[1];
            let x2835 = x1420 * x2834;
            let x2837 = x2833 - x2835;
            let x2838 = x1455 + x2811;
            let x2840 = x1457 - x2838;
            let x2841 = 0.5 * x2840;
            let x2843 = x2841 - x2814;
            let x2844 = q[5] * k[1];
            let x2845 = x1420 * x2844;
            let x2847 = x2843 - x2845;
            let x2848 = x2815 - x1471;
            let x2849 = x2848 - x1474;
            let x2850 = 0.5 * x2849;
            let x2852 = x2850 - x2819;
            let x2853 = q[6] * k[1];
            let x2854 = x1420 * x2853;
            let x2856 = x2852 - x2854;
            let x2958 = x1778 * k[0];
            let x2959 = x1783 + x2958;
            let x2960 = x1787 + x2959;
            let x2961 = 0.5 * x2960;
            let x2962 = x1792 * k[0];
            let x2963 = x2962 - x1797;
            let x2964 = x1802 + x2963;
            let x2965 = 0.5 * x2964;
            let x2966 = x1806 * k[0];
            let x2967 = x1811 + x2966;
            let x2968 = x2967 - x1815;
            let x2969 = 0.5 * x2968;
            let x2970 = x1820 * k[0];
            let x2972 = x1826 - x2970;
            let x2973 = x1830 + x2972;
            let x2974 = 0.5 * x2973;
            let x2975 = x1841 + x2958;
            let x2976 = x1842 + x2975;
            let x2977 = 0.5 * x2976;
            let x2978 = x2961 + x2977;
            let x2979 = q[10] * k[2];
            let x2980 = x1840 * x2979;
            let x2982 = x2978 - x2980;
            let x2984 = x1857 - x2962;
            let x2985 = x2984 - x1859;
            let x2986 = 0.5 * x2985;
            let x2988 = x2986 - x2965;
            let x2989 = q[11] * k[2];
            let x2990 = x1840 * x2989;
            let x2992 = x2988 - x2990;
            let x2993 = x1875 + x2966;
            let x2995 = x1877 - x2993;
            let x2996 = 0.5 * x2995;
            let x2998 = x2996 - x2969;
            let x2999 = q[12] * k[2];
            let x3000 = x1840 * x2999;
            let x3002 = x2998 - x3000;
            let x3003 = x2970 - x1891;
            let x3004 = x3003 - x1894;
            let x3005 = 0.5 * x3004;
            let x3007 = x3005 - x2974;
            let x3008 = q[13] * k[2];
            let x3009 = x1840 * x3008;
            let x3011 = x3007 - x3009;
            mass[39] = x2469;
            mass[40] = x2477;
            mass[41] = x2490;
            mass[42] = x2503;
            mass[43] = x2510;
            mass[44] = x2517;
            mass[45] = x2526;
            mass[46] = x2534;
            mass[47] = x2537;
            mass[48] = x2542;
            mass[49] = x2545;
            mass[50] = x2550;
            mass[51] = x2553;
            mass[52] = x2557;
            mass[53] = x2560;
            mass[54] = x2563;
            force[0] = 0.0;
            force[1] = -2.943;
            force[2] = 0.0;
            force[3] = x2827;
            force[4] = x2837;
            force[5] = x2847;
            force[6] = x2856;
            force[7] = 0.0;
            force[8] = -5.886;
            force[9] = 0.0;
            force[10] = x2982;
            force[11] = x2992;
            force[12] = x3002;
            force[13] = x3011;
            force[14] = 0.0;
            force[15] = x2664;
            force[16] = x2677;
            force[17] = x2688;
            force[18] = x2700;
        }
    }
    /// `slider_crank` reduced by substitution, with the `exact` formulation.
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
/// `slider_crank` with the `exact` formulation. At run-time parameter values (`Exact::with_parameters`).
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
    name: "slider_crank",
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
            env!("CARGO_MANIFEST_DIR"), "/../../../", "mechanisms/slider_crank.toml"
        ),
        hash: 7502150094150027739u64,
        parameters: &[],
    },
    run_time: Some(&RUN_TIME_ENTRY),
};
