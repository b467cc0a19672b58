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
pub fn phi(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
    phi_part_0(k, q, t, out);
}
#[inline(never)]
fn phi_part_0(k: &[f64; 17], q: &[f64; 18], t: f64, out: &mut [f64; 21]) {
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
    let x116 = x18 * 0.00000000000000006123233995736766;
    let x118 = x116 - x33;
    let x119 = x19 * 0.00000000000000006123233995736766;
    let x121 = x119 - x35;
    let x122 = x14 * 0.00000000000000006123233995736766;
    let x125 = x22 + x122;
    let x127 = x33 * 0.00000000000000006123233995736766;
    let x128 = x18 + x127;
    let x129 = x35 * 0.00000000000000006123233995736766;
    let x130 = x19 + x129;
    let x131 = x22 * 0.00000000000000006123233995736766;
    let x132 = x131 - x14;
    let x182 = x67 * x118;
    let x183 = x70 * x121;
    let x184 = x56 * x125;
    let x186 = x182 + x183;
    let x187 = x186 - x184;
    let x188 = x67 * x128;
    let x189 = x70 * x130;
    let x190 = x56 * x132;
    let x191 = x188 + x189;
    let x192 = x190 + x191;
    let x331 = x5.sin();
    let x332 = x5.cos();
    let x333 = x118 * x331;
    let x334 = x121 * x332;
    let x336 = x333 - x334;
    let x2468 = x18 * k[0];
    let x2469 = x19 * k[0];
    let x2470 = x14 * k[0];
    let x2472 = q[0] + x2468;
    let x2473 = q[1] + x2469;
    let x2474 = q[2] - x2470;
    let x2475 = -x2472;
    let x2476 = -x2473;
    let x2477 = -x2474;
    let x2479 = x18 * k[1];
    let x2480 = x19 * k[1];
    let x2481 = x14 * k[1];
    let x2483 = q[0] + x2479;
    let x2484 = q[1] + x2480;
    let x2485 = q[2] - x2481;
    let x2487 = x51 * k[2];
    let x2488 = x52 * k[2];
    let x2489 = x47 * k[2];
    let x2491 = q[6] + x2487;
    let x2492 = q[7] + x2488;
    let x2493 = q[8] - x2489;
    let x2495 = x2483 - x2491;
    let x2497 = x2484 - x2492;
    let x2499 = x2485 - x2493;
    let x2502 = x51 * k[3];
    let x2503 = x66 * k[4];
    let x2504 = x2502 + x2503;
    let x2505 = x52 * k[3];
    let x2506 = x68 * k[4];
    let x2507 = x2505 + x2506;
    let x2508 = x47 * k[3];
    let x2510 = x55 * k[4];
    let x2511 = x2510 - x2508;
    let x2512 = q[6] + x2504;
    let x2513 = q[7] + x2507;
    let x2514 = q[8] + x2511;
    let x2517 = x51 * k[5];
    let x2518 = x66 * k[6];
    let x2519 = x2517 + x2518;
    let x2520 = x52 * k[5];
    let x2521 = x68 * k[6];
    let x2522 = x2520 + x2521;
    let x2523 = x47 * k[5];
    let x2525 = x55 * k[6];
    let x2526 = x2525 - x2523;
    let x2527 = x51 * k[6];
    let x2529 = x66 * k[5];
    let x2530 = x2529 - x2527;
    let x2531 = x52 * k[6];
    let x2533 = x68 * k[5];
    let x2534 = x2533 - x2531;
    let x2535 = x47 * k[6];
    let x2536 = x55 * k[5];
    let x2537 = x2535 + x2536;
    let x2540 = x84 * k[7];
    let x2541 = x99 * k[8];
    let x2542 = x2540 + x2541;
    let x2543 = x85 * k[7];
    let x2544 = x101 * k[8];
    let x2545 = x2543 + x2544;
    let x2546 = x80 * k[7];
    let x2548 = x88 * k[8];
    let x2549 = x2548 - x2546;
    let x2550 = q[12] + x2542;
    let x2551 = q[13] + x2545;
    let x2552 = q[14] + x2549;
    let x2554 = x2512 - x2550;
    let x2556 = x2513 - x2551;
    let x2558 = x2514 - x2552;
    let x2559 = x100 * x2519;
    let x2560 = x103 * x2522;
    let x2561 = x89 * x2526;
    let x2562 = x2559 + x2560;
    let x2563 = x2561 + x2562;
    let x2564 = x100 * x2530;
    let x2565 = x103 * x2534;
    let x2566 = x89 * x2537;
    let x2567 = x2564 + x2565;
    let x2568 = x2566 + x2567;
    let x2572 = x84 * k[10];
    let x2573 = x99 * k[11];
    let x2574 = x2572 + x2573;
    let x2575 = x85 * k[10];
    let x2576 = x101 * k[11];
    let x2577 = x2575 + x2576;
    let x2578 = x80 * k[10];
    let x2580 = x88 * k[11];
    let x2581 = x2580 - x2578;
    let x2582 = q[12] + x2574;
    let x2583 = q[13] + x2577;
    let x2584 = q[14] + x2581;
    let x2586 = k[9] - x2582;
    let x2587 = -x2583;
    let x2588 = -x2584;
    out[0] = x2475;
    out[1] = x2476;
    out[2] = x2477;
    out[3] = x34;
    out[4] = x37;
    out[5] = x2495;
    out[6] = x2497;
    out[7] = x2499;
    out[8] = x187;
    out[9] = x192;
    out[10] = x2554;
    out[11] = x2556;
    out[12] = x2558;
    out[13] = x2563;
    out[14] = x2568;
    out[15] = x2586;
    out[16] = x2587;
    out[17] = x2588;
    out[18] = x100;
    out[19] = x103;
    out[20] = x336;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 96] = out.try_into().expect("out must have 96 entries");
    phi_q_part_0(k, q, t, out);
}
#[inline(never)]
fn phi_q_part_0(k: &[f64; 17], q: &[f64; 18], t: f64, out: &mut [f64; 96]) {
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
    let x116 = x18 * 0.00000000000000006123233995736766;
    let x118 = x116 - x33;
    let x119 = x19 * 0.00000000000000006123233995736766;
    let x120 = -x35;
    let x121 = x119 - x35;
    let x122 = x14 * 0.00000000000000006123233995736766;
    let x125 = x22 + x122;
    let x127 = x33 * 0.00000000000000006123233995736766;
    let x128 = x18 + x127;
    let x129 = x35 * 0.00000000000000006123233995736766;
    let x130 = x19 + x129;
    let x131 = x22 * 0.00000000000000006123233995736766;
    let x132 = x131 - x14;
    let x331 = x5.sin();
    let x332 = x5.cos();
    let x341 = x25 - x24;
    let x345 = x34 * 0.00000000000000006123233995736766;
    let x346 = x37 * 0.00000000000000006123233995736766;
    let x347 = x23 * 0.00000000000000006123233995736766;
    let x348 = x34 * x67;
    let x350 = x37 * x70;
    let x352 = x23 * x56;
    let x354 = x348 + x350;
    let x356 = x352 + x354;
    let x357 = -x356;
    let x358 = x67 * x345;
    let x359 = x70 * x346;
    let x360 = x56 * x347;
    let x361 = x358 + x359;
    let x362 = x360 + x361;
    let x363 = x34 * x331;
    let x365 = x37 * x332;
    let x367 = x365 - x363;
    let x370 = x12 * x14;
    let x372 = x12 * x18;
    let x373 = x13 * x18;
    let x374 = x12 * x19;
    let x375 = x13 * x19;
    let x383 = x20 * 0.00000000000000006123233995736766;
    let x386 = x372 + x383;
    let x388 = x21 * 0.00000000000000006123233995736766;
    let x391 = x374 + x388;
    let x393 = x15 * 0.00000000000000006123233995736766;
    let x394 = x393 - x370;
    let x395 = 0.00000000000000006123233995736766 * x372;
    let x396 = x395 - x20;
    let x397 = 0.00000000000000006123233995736766 * x374;
    let x398 = x397 - x21;
    let x399 = 0.00000000000000006123233995736766 * x370;
    let x401 = x15 + x399;
    let x409 = x67 * x386;
    let x411 = x70 * x391;
    let x413 = x56 * x394;
    let x415 = x409 + x411;
    let x417 = x413 + x415;
    let x418 = -x417;
    let x419 = x67 * x396;
    let x420 = x70 * x398;
    let x421 = x56 * x401;
    let x423 = x419 + x420;
    let x424 = x423 - x421;
    let x425 = x331 * x386;
    let x427 = x332 * x391;
    let x429 = x427 - x425;
    let x433 = x31 - x30;
    let x436 = x35 - x119;
    let x441 = x67 * x436;
    let x442 = x70 * x118;
    let x443 = x441 + x442;
    let x444 = x67 * x130;
    let x446 = x70 * x128;
    let x447 = x446 - x444;
    let x448 = x331 * x436;
    let x449 = x118 * x332;
    let x451 = x448 - x449;
    let x457 = x58 - x57;
    let x460 = x118 * x457;
    let x461 = x68 * x121;
    let x463 = x55 * x125;
    let x465 = x460 - x461;
    let x466 = x463 + x465;
    let x467 = x128 * x457;
    let x468 = x68 * x130;
    let x470 = x55 * x132;
    let x472 = x467 - x468;
    let x473 = x472 - x470;
    let x495 = x45 * x47;
    let x497 = x46 * x47;
    let x499 = x45 * x51;
    let x500 = x46 * x51;
    let x501 = x45 * x52;
    let x502 = x46 * x52;
    let x509 = x118 * x500;
    let x510 = x121 * x502;
    let x511 = x125 * x497;
    let x513 = x509 + x510;
    let x514 = x511 + x513;
    let x515 = x128 * x500;
    let x516 = x130 * x502;
    let x517 = x132 * x497;
    let x519 = x515 + x516;
    let x520 = x519 - x517;
    let x575 = x64 - x63;
    let x578 = x118 * x575;
    let x579 = x67 * x121;
    let x580 = x578 + x579;
    let x581 = x128 * x575;
    let x582 = x444 + x581;
    let x603 = x91 - x90;
    let x605 = -x101;
    let x634 = x78 * x80;
    let x636 = x79 * x80;
    let x638 = x78 * x84;
    let x639 = x79 * x84;
    let x640 = x78 * x85;
    let x641 = x79 * x85;
    let x689 = x97 - x96;
    let x2468 = x18 * k[0];
    let x2469 = x19 * k[0];
    let x2479 = x18 * k[1];
    let x2480 = x19 * k[1];
    let x2487 = x51 * k[2];
    let x2488 = x52 * k[2];
    let x2502 = x51 * k[3];
    let x2503 = x66 * k[4];
    let x2504 = x2502 + x2503;
    let x2505 = x52 * k[3];
    let x2506 = x68 * k[4];
    let x2507 = x2505 + x2506;
    let x2517 = x51 * k[5];
    let x2518 = x66 * k[6];
    let x2519 = x2517 + x2518;
    let x2520 = x52 * k[5];
    let x2521 = x68 * k[6];
    let x2522 = x2520 + x2521;
    let x2523 = x47 * k[5];
    let x2525 = x55 * k[6];
    let x2526 = x2525 - x2523;
    let x2527 = x51 * k[6];
    let x2529 = x66 * k[5];
    let x2530 = x2529 - x2527;
    let x2531 = x52 * k[6];
    let x2533 = x68 * k[5];
    let x2534 = x2533 - x2531;
    let x2535 = x47 * k[6];
    let x2536 = x55 * k[5];
    let x2537 = x2535 + x2536;
    let x2540 = x84 * k[7];
    let x2541 = x99 * k[8];
    let x2542 = x2540 + x2541;
    let x2543 = x85 * k[7];
    let x2544 = x101 * k[8];
    let x2545 = x2543 + x2544;
    let x2572 = x84 * k[10];
    let x2573 = x99 * k[11];
    let x2574 = x2572 + x2573;
    let x2575 = x85 * k[10];
    let x2576 = x101 * k[11];
    let x2577 = x2575 + x2576;
    let x2589 = x20 * k[0];
    let x2590 = x21 * k[0];
    let x2591 = x15 * k[0];
    let x2592 = x20 * k[1];
    let x2593 = -x2592;
    let x2594 = x21 * k[1];
    let x2595 = -x2594;
    let x2596 = x15 * k[1];
    let x2597 = -x2596;
    let x2598 = -x2468;
    let x2599 = -x2480;
    let x2600 = x67 * k[4];
    let x2601 = x70 * k[4];
    let x2602 = x56 * k[4];
    let x2603 = x67 * k[6];
    let x2604 = x70 * k[6];
    let x2605 = x56 * k[6];
    let x2606 = x67 * k[5];
    let x2607 = x70 * k[5];
    let x2608 = x56 * k[5];
    let x2609 = x100 * x2603;
    let x2610 = x103 * x2604;
    let x2611 = x89 * x2605;
    let x2612 = x2609 + x2610;
    let x2613 = x2611 + x2612;
    let x2614 = x100 * x2606;
    let x2615 = x103 * x2607;
    let x2616 = x89 * x2608;
    let x2617 = x2614 + x2615;
    let x2618 = x2616 + x2617;
    let x2619 = x53 * k[2];
    let x2620 = x54 * k[2];
    let x2621 = x48 * k[2];
    let x2622 = x53 * k[3];
    let x2624 = x499 * k[4];
    let x2625 = x2624 - x2622;
    let x2626 = x54 * k[3];
    let x2628 = x501 * k[4];
    let x2629 = x2628 - x2626;
    let x2630 = x48 * k[3];
    let x2631 = x495 * k[4];
    let x2632 = x2630 + x2631;
    let x2633 = -x2632;
    let x2634 = x53 * k[5];
    let x2636 = x499 * k[6];
    let x2637 = x2636 - x2634;
    let x2638 = x54 * k[5];
    let x2640 = x501 * k[6];
    let x2641 = x2640 - x2638;
    let x2642 = x48 * k[5];
    let x2643 = x495 * k[6];
    let x2644 = x2642 + x2643;
    let x2645 = x53 * k[6];
    let x2646 = x499 * k[5];
    let x2647 = x2645 + x2646;
    let x2648 = x54 * k[6];
    let x2649 = x501 * k[5];
    let x2650 = x2648 + x2649;
    let x2651 = x48 * k[6];
    let x2652 = x495 * k[5];
    let x2654 = x2651 - x2652;
    let x2655 = x100 * x2637;
    let x2656 = x103 * x2641;
    let x2657 = x89 * x2644;
    let x2659 = x2655 + x2656;
    let x2660 = x2659 - x2657;
    let x2661 = x100 * x2647;
    let x2662 = x103 * x2650;
    let x2663 = x89 * x2654;
    let x2664 = x2661 + x2662;
    let x2665 = x2663 + x2664;
    let x2666 = -x2487;
    let x2667 = -x2507;
    let x2669 = x2531 - x2533;
    let x2670 = x100 * x2522;
    let x2672 = x103 * x2519;
    let x2673 = x2672 - x2670;
    let x2674 = x100 * x2669;
    let x2675 = x103 * x2530;
    let x2676 = x2674 + x2675;
    let x2677 = x100 * k[8];
    let x2678 = x103 * k[8];
    let x2679 = x89 * k[8];
    let x2680 = -x2677;
    let x2681 = -x2678;
    let x2682 = -x2679;
    let x2683 = x603 * x2519;
    let x2684 = x101 * x2522;
    let x2686 = x88 * x2526;
    let x2688 = x2683 - x2684;
    let x2689 = x2688 - x2686;
    let x2690 = x603 * x2530;
    let x2691 = x101 * x2534;
    let x2693 = x88 * x2537;
    let x2695 = x2690 - x2691;
    let x2696 = x2695 - x2693;
    let x2697 = x100 * k[11];
    let x2698 = x103 * k[11];
    let x2699 = x89 * k[11];
    let x2700 = -x2697;
    let x2701 = -x2698;
    let x2702 = -x2699;
    let x2703 = x86 * k[7];
    let x2705 = x638 * k[8];
    let x2706 = x2705 - x2703;
    let x2707 = x87 * k[7];
    let x2709 = x640 * k[8];
    let x2710 = x2709 - x2707;
    let x2711 = x81 * k[7];
    let x2712 = x634 * k[8];
    let x2713 = x2711 + x2712;
    let x2714 = -x2706;
    let x2715 = -x2710;
    let x2716 = x639 * x2519;
    let x2717 = x641 * x2522;
    let x2718 = x636 * x2526;
    let x2720 = x2716 + x2717;
    let x2721 = x2720 - x2718;
    let x2722 = x639 * x2530;
    let x2723 = x641 * x2534;
    let x2724 = x636 * x2537;
    let x2726 = x2722 + x2723;
    let x2727 = x2726 - x2724;
    let x2728 = x86 * k[10];
    let x2730 = x638 * k[11];
    let x2731 = x2730 - x2728;
    let x2732 = x87 * k[10];
    let x2734 = x640 * k[11];
    let x2735 = x2734 - x2732;
    let x2736 = x81 * k[10];
    let x2737 = x634 * k[11];
    let x2738 = x2736 + x2737;
    let x2739 = -x2731;
    let x2740 = -x2735;
    let x2741 = -x2542;
    let x2742 = x689 * x2519;
    let x2743 = x2670 + x2742;
    let x2744 = x689 * x2530;
    let x2745 = x100 * x2534;
    let x2746 = x2744 + x2745;
    let x2747 = -x2574;
    out[0] = -1.0;
    out[1] = x2589;
    out[2] = x2469;
    out[3] = -1.0;
    out[4] = x2590;
    out[5] = x2598;
    out[6] = -1.0;
    out[7] = x2591;
    out[8] = x341;
    out[9] = x373;
    out[10] = x433;
    out[11] = x120;
    out[12] = x375;
    out[13] = x34;
    out[14] = 1.0;
    out[15] = x2593;
    out[16] = x2599;
    out[17] = -1.0;
    out[18] = x2619;
    out[19] = x2488;
    out[20] = 1.0;
    out[21] = x2595;
    out[22] = x2479;
    out[23] = -1.0;
    out[24] = x2620;
    out[25] = x2666;
    out[26] = 1.0;
    out[27] = x2597;
    out[28] = -1.0;
    out[29] = x2621;
    out[30] = x357;
    out[31] = x418;
    out[32] = x443;
    out[33] = x466;
    out[34] = x514;
    out[35] = x580;
    out[36] = x362;
    out[37] = x424;
    out[38] = x447;
    out[39] = x473;
    out[40] = x520;
    out[41] = x582;
    out[42] = 1.0;
    out[43] = x2600;
    out[44] = x2625;
    out[45] = x2667;
    out[46] = -1.0;
    out[47] = x2680;
    out[48] = x2714;
    out[49] = x2545;
    out[50] = 1.0;
    out[51] = x2601;
    out[52] = x2629;
    out[53] = x2504;
    out[54] = -1.0;
    out[55] = x2681;
    out[56] = x2715;
    out[57] = x2741;
    out[58] = 1.0;
    out[59] = x2602;
    out[60] = x2633;
    out[61] = -1.0;
    out[62] = x2682;
    out[63] = x2713;
    out[64] = x2613;
    out[65] = x2660;
    out[66] = x2673;
    out[67] = x2689;
    out[68] = x2721;
    out[69] = x2743;
    out[70] = x2618;
    out[71] = x2665;
    out[72] = x2676;
    out[73] = x2696;
    out[74] = x2727;
    out[75] = x2746;
    out[76] = -1.0;
    out[77] = x2700;
    out[78] = x2739;
    out[79] = x2577;
    out[80] = -1.0;
    out[81] = x2701;
    out[82] = x2740;
    out[83] = x2747;
    out[84] = -1.0;
    out[85] = x2702;
    out[86] = x2738;
    out[87] = x603;
    out[88] = x639;
    out[89] = x689;
    out[90] = x605;
    out[91] = x641;
    out[92] = x100;
    out[93] = x367;
    out[94] = x429;
    out[95] = x451;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
    let _ = k;
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
    let x116 = x18 * 0.00000000000000006123233995736766;
    let x118 = x116 - x33;
    let x119 = x19 * 0.00000000000000006123233995736766;
    let x121 = x119 - x35;
    let x331 = x5.sin();
    let x332 = x5.cos();
    let x703 = 6.283185307179586 * x332;
    let x705 = 6.283185307179586 * x331;
    let x707 = x118 * x703;
    let x708 = x121 * x705;
    let x710 = x707 + x708;
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
    out[20] = x710;
}
/// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
pub fn gamma(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 18] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
    let mut s = [0.0f64; 280];
    gamma_shared_0(k, q, qd, t, &mut s);
    gamma_part_0(k, &s, out);
    gamma_part_1(k, t, &s, out);
}
#[inline(never)]
fn gamma_shared_0(
    _k: &[f64; 17],
    q: &[f64; 18],
    qd: &[f64; 18],
    _t: f64,
    s: &mut [f64; 280],
) {
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
    let x116 = x18 * 0.00000000000000006123233995736766;
    s[32] = x116;
    let x118 = x116 - x33;
    s[33] = x118;
    let x119 = x19 * 0.00000000000000006123233995736766;
    s[34] = x119;
    let x121 = x119 - x35;
    s[35] = x121;
    let x729 = x13 * qd[3];
    s[36] = x729;
    let x730 = x12 * qd[3];
    s[37] = x730;
    let x732 = x15 * qd[4];
    s[38] = x732;
    let x733 = x14 * qd[4];
    s[39] = x733;
    let x735 = x17 * qd[5];
    s[40] = x735;
    let x736 = x16 * qd[5];
    s[41] = x736;
    let x738 = x17 * x733;
    s[42] = x738;
    let x740 = x15 * x736;
    s[43] = x740;
    let x742 = x738 + x740;
    s[44] = x742;
    let x744 = x16 * x733;
    s[45] = x744;
    let x746 = x15 * x735;
    s[46] = x746;
    let x747 = x746 - x744;
    s[47] = x747;
    let x748 = x17 * x732;
    s[48] = x748;
    let x749 = x14 * x736;
    s[49] = x749;
    let x751 = x748 - x749;
    s[50] = x751;
    let x752 = x16 * x732;
    s[51] = x752;
    let x753 = x14 * x735;
    s[52] = x753;
    let x754 = x752 + x753;
    s[53] = x754;
    let x759 = x20 * x729;
    s[54] = x759;
    let x760 = x12 * x751;
    s[55] = x760;
    let x761 = x759 + x760;
    s[56] = x761;
    let x762 = x16 * x730;
    s[57] = x762;
    let x764 = x13 * x735;
    s[58] = x764;
    let x765 = x764 - x762;
    s[59] = x765;
    let x773 = x21 * x729;
    s[60] = x773;
    let x774 = x12 * x754;
    s[61] = x774;
    let x775 = x773 + x774;
    s[62] = x775;
    let x776 = x17 * x730;
    s[63] = x776;
    let x778 = x13 * x736;
    s[64] = x778;
    let x780 = x776 + x778;
    s[65] = x780;
    let x791 = x761 - x765;
    s[66] = x791;
    let x793 = x775 - x780;
    s[67] = x793;
    let x797 = x46 * qd[9];
    s[68] = x797;
    let x798 = x45 * qd[9];
    s[69] = x798;
    let x800 = x48 * qd[10];
    s[70] = x800;
    let x801 = x47 * qd[10];
    s[71] = x801;
    let x803 = x50 * qd[11];
    s[72] = x803;
    let x804 = x49 * qd[11];
    s[73] = x804;
    let x816 = x50 * x800;
    s[74] = x816;
    let x817 = x47 * x804;
    s[75] = x817;
    let x819 = x816 - x817;
    s[76] = x819;
    let x820 = x49 * x800;
    s[77] = x820;
    let x821 = x47 * x803;
    s[78] = x821;
    let x822 = x820 + x821;
    s[79] = x822;
    let x870 = x79 * qd[15];
    s[80] = x870;
    let x871 = x78 * qd[15];
    s[81] = x871;
    let x873 = x81 * qd[16];
    s[82] = x873;
    let x874 = x80 * qd[16];
    s[83] = x874;
    let x876 = x83 * qd[17];
    s[84] = x876;
    let x877 = x82 * qd[17];
    s[85] = x877;
    let x889 = x83 * x873;
    s[86] = x889;
    let x890 = x80 * x877;
    s[87] = x890;
    let x892 = x889 - x890;
    s[88] = x892;
    let x893 = x82 * x873;
    s[89] = x893;
    let x894 = x80 * x876;
    s[90] = x894;
    let x895 = x893 + x894;
    s[91] = x895;
    let x951 = 0.00000000000000006123233995736766 * x742;
    s[92] = x951;
    let x954 = x791 + x951;
    s[93] = x954;
    let x956 = 0.00000000000000006123233995736766 * x747;
    s[94] = x956;
    let x958 = x956 - x793;
    s[95] = x958;
    let x1135 = qd[3] * x730;
    s[96] = x1135;
    let x1137 = qd[3] * x729;
    s[97] = x1137;
    let x1138 = qd[4] * x733;
    s[98] = x1138;
    let x1140 = qd[4] * x732;
    s[99] = x1140;
    let x1141 = qd[5] * x736;
    s[100] = x1141;
    let x1143 = qd[5] * x735;
    s[101] = x1143;
    let x1144 = x733 * x736;
    s[102] = x1144;
    let x1146 = x17 * x1140;
    s[103] = x1146;
    let x1147 = x1146 - x1144;
    s[104] = x1147;
    let x1148 = x15 * x1143;
    s[105] = x1148;
    let x1149 = x1148 - x1144;
    s[106] = x1149;
    let x1150 = x1147 + x1149;
    s[107] = x1150;
    let x1152 = x733 * x735;
    s[108] = x1152;
    let x1153 = x16 * x1140;
    s[109] = x1153;
    let x1154 = x1152 + x1153;
    s[110] = x1154;
    let x1157 = x15 * x1141;
    s[111] = x1157;
    let x1159 = x1152 + x1157;
    s[112] = x1159;
    let x1161 = x1154 + x1159;
    s[113] = x1161;
    let x1163 = x732 * x736;
    s[114] = x1163;
    let x1165 = x17 * x1138;
    s[115] = x1165;
    let x1167 = x1163 + x1165;
    s[116] = x1167;
    let x1169 = x14 * x1143;
    s[117] = x1169;
    let x1170 = x1163 + x1169;
    s[118] = x1170;
    let x1172 = x1167 + x1170;
    s[119] = x1172;
    let x1174 = x732 * x735;
    s[120] = x1174;
    let x1175 = x16 * x1138;
    s[121] = x1175;
    let x1177 = x1174 - x1175;
    s[122] = x1177;
    let x1178 = x14 * x1141;
    s[123] = x1178;
    let x1180 = x1174 - x1178;
    s[124] = x1180;
    let x1181 = x1177 + x1180;
    s[125] = x1181;
    let x1193 = x729 * x751;
    s[126] = x1193;
    let x1194 = x20 * x1135;
    s[127] = x1194;
    let x1196 = x1193 - x1194;
    s[128] = x1196;
    let x1197 = x12 * x1172;
    s[129] = x1197;
    let x1199 = x1193 - x1197;
    s[130] = x1199;
    let x1200 = x1196 + x1199;
    s[131] = x1200;
    let x1201 = x730 * x735;
    s[132] = x1201;
    let x1202 = x16 * x1137;
    s[133] = x1202;
    let x1203 = x1201 + x1202;
    s[134] = x1203;
    let x1206 = x13 * x1141;
    s[135] = x1206;
    let x1208 = x1201 + x1206;
    s[136] = x1208;
    let x1210 = x1203 + x1208;
    s[137] = x1210;
    let x1231 = x729 * x754;
    s[138] = x1231;
    let x1232 = x21 * x1135;
    s[139] = x1232;
    let x1234 = x1231 - x1232;
    s[140] = x1234;
    let x1235 = x12 * x1181;
    s[141] = x1235;
    let x1236 = x1231 + x1235;
    s[142] = x1236;
    let x1237 = x1234 + x1236;
    s[143] = x1237;
    let x1238 = x730 * x736;
    s[144] = x1238;
    let x1240 = x17 * x1137;
    s[145] = x1240;
    let x1241 = x1240 - x1238;
    s[146] = x1241;
    let x1242 = x13 * x1143;
    s[147] = x1242;
    let x1243 = x1242 - x1238;
    s[148] = x1243;
    let x1244 = x1241 + x1243;
    s[149] = x1244;
    let x1265 = x1200 + x1210;
    s[150] = x1265;
    let x1267 = x1237 - x1244;
    s[151] = x1267;
    let x1269 = qd[9] * x798;
    s[152] = x1269;
    let x1271 = qd[9] * x797;
    s[153] = x1271;
    let x1272 = qd[10] * x801;
    s[154] = x1272;
    let x1274 = qd[10] * x800;
    s[155] = x1274;
    let x1275 = qd[11] * x804;
    s[156] = x1275;
    let x1277 = qd[11] * x803;
    s[157] = x1277;
    let x1278 = x801 * x804;
    s[158] = x1278;
    let x1280 = x50 * x1274;
    s[159] = x1280;
    let x1281 = x1280 - x1278;
    s[160] = x1281;
    let x1282 = x48 * x1277;
    s[161] = x1282;
    let x1283 = x1282 - x1278;
    s[162] = x1283;
    let x1284 = x1281 + x1283;
    s[163] = x1284;
    let x1285 = x801 * x803;
    s[164] = x1285;
    let x1286 = x49 * x1274;
    s[165] = x1286;
    let x1287 = x1285 + x1286;
    s[166] = x1287;
    let x1290 = x48 * x1275;
    s[167] = x1290;
    let x1292 = x1285 + x1290;
    s[168] = x1292;
    let x1294 = x1287 + x1292;
    s[169] = x1294;
    let x1296 = x800 * x804;
    s[170] = x1296;
    let x1298 = x50 * x1272;
    s[171] = x1298;
    let x1300 = x1296 + x1298;
    s[172] = x1300;
    let x1302 = x47 * x1277;
    s[173] = x1302;
    let x1303 = x1296 + x1302;
    s[174] = x1303;
    let x1305 = x1300 + x1303;
    s[175] = x1305;
    let x1307 = x800 * x803;
    s[176] = x1307;
    let x1308 = x49 * x1272;
    s[177] = x1308;
    let x1310 = x1307 - x1308;
    s[178] = x1310;
    let x1311 = x47 * x1275;
    s[179] = x1311;
    let x1313 = x1307 - x1311;
    s[180] = x1313;
    let x1314 = x1310 + x1313;
    s[181] = x1314;
    let x1315 = x797 * x801;
    s[182] = x1315;
    let x1317 = x48 * x1269;
    s[183] = x1317;
    let x1319 = x1315 + x1317;
    s[184] = x1319;
    let x1321 = x45 * x1274;
    s[185] = x1321;
    let x1322 = x1315 + x1321;
    s[186] = x1322;
    let x1324 = x1319 + x1322;
    s[187] = x1324;
    let x1333 = x797 * x819;
    s[188] = x1333;
    let x1334 = x53 * x1269;
    s[189] = x1334;
    let x1336 = x1333 - x1334;
    s[190] = x1336;
    let x1337 = x45 * x1305;
    s[191] = x1337;
    let x1339 = x1333 - x1337;
    s[192] = x1339;
    let x1340 = x1336 + x1339;
    s[193] = x1340;
    let x1341 = x798 * x803;
    s[194] = x1341;
    let x1342 = x49 * x1271;
    s[195] = x1342;
    let x1343 = x1341 + x1342;
    s[196] = x1343;
    let x1346 = x46 * x1275;
    s[197] = x1346;
    let x1348 = x1341 + x1346;
    s[198] = x1348;
    let x1350 = x1343 + x1348;
    s[199] = x1350;
    let x1371 = x797 * x822;
    s[200] = x1371;
    let x1372 = x54 * x1269;
    s[201] = x1372;
    let x1374 = x1371 - x1372;
    s[202] = x1374;
    let x1375 = x45 * x1314;
    s[203] = x1375;
    let x1376 = x1371 + x1375;
    s[204] = x1376;
    let x1377 = x1374 + x1376;
    s[205] = x1377;
    let x1378 = x798 * x804;
    s[206] = x1378;
    let x1380 = x50 * x1271;
    s[207] = x1380;
    let x1381 = x1380 - x1378;
    s[208] = x1381;
    let x1382 = x46 * x1277;
    s[209] = x1382;
    let x1383 = x1382 - x1378;
    s[210] = x1383;
    let x1384 = x1381 + x1383;
    s[211] = x1384;
    let x1405 = x1340 + x1350;
    s[212] = x1405;
    let x1407 = x1377 - x1384;
    s[213] = x1407;
    let x1409 = qd[15] * x871;
    s[214] = x1409;
    let x1411 = qd[15] * x870;
    s[215] = x1411;
    let x1412 = qd[16] * x874;
    s[216] = x1412;
    let x1414 = qd[16] * x873;
    s[217] = x1414;
    let x1415 = qd[17] * x877;
    s[218] = x1415;
    let x1417 = qd[17] * x876;
    s[219] = x1417;
    let x1418 = x874 * x877;
    s[220] = x1418;
    let x1420 = x83 * x1414;
    s[221] = x1420;
    let x1421 = x1420 - x1418;
    s[222] = x1421;
    let x1422 = x81 * x1417;
    s[223] = x1422;
    let x1423 = x1422 - x1418;
    s[224] = x1423;
    let x1424 = x1421 + x1423;
    s[225] = x1424;
    let x1425 = x874 * x876;
    s[226] = x1425;
    let x1426 = x82 * x1414;
    s[227] = x1426;
    let x1427 = x1425 + x1426;
    s[228] = x1427;
    let x1430 = x81 * x1415;
    s[229] = x1430;
    let x1432 = x1425 + x1430;
    s[230] = x1432;
    let x1434 = x1427 + x1432;
    s[231] = x1434;
    let x1436 = x873 * x877;
    s[232] = x1436;
    let x1438 = x83 * x1412;
    s[233] = x1438;
    let x1440 = x1436 + x1438;
    s[234] = x1440;
    let x1442 = x80 * x1417;
    s[235] = x1442;
    let x1443 = x1436 + x1442;
    s[236] = x1443;
    let x1445 = x1440 + x1443;
    s[237] = x1445;
    let x1447 = x873 * x876;
    s[238] = x1447;
    let x1448 = x82 * x1412;
    s[239] = x1448;
    let x1450 = x1447 - x1448;
    s[240] = x1450;
    let x1451 = x80 * x1415;
    s[241] = x1451;
    let x1453 = x1447 - x1451;
    s[242] = x1453;
    let x1454 = x1450 + x1453;
    s[243] = x1454;
    let x1455 = x870 * x874;
    s[244] = x1455;
    let x1457 = x81 * x1409;
    s[245] = x1457;
    let x1459 = x1455 + x1457;
    s[246] = x1459;
    let x1461 = x78 * x1414;
    s[247] = x1461;
    let x1462 = x1455 + x1461;
    s[248] = x1462;
    let x1464 = x1459 + x1462;
    s[249] = x1464;
    let x1473 = x870 * x892;
    s[250] = x1473;
    let x1474 = x86 * x1409;
    s[251] = x1474;
    let x1476 = x1473 - x1474;
    s[252] = x1476;
    let x1477 = x78 * x1445;
    s[253] = x1477;
    let x1479 = x1473 - x1477;
    s[254] = x1479;
    let x1480 = x1476 + x1479;
    s[255] = x1480;
    let x1481 = x871 * x876;
    s[256] = x1481;
    let x1482 = x82 * x1411;
    s[257] = x1482;
    let x1483 = x1481 + x1482;
    s[258] = x1483;
    let x1486 = x79 * x1415;
    s[259] = x1486;
    let x1488 = x1481 + x1486;
    s[260] = x1488;
    let x1490 = x1483 + x1488;
    s[261] = x1490;
    let x1511 = x870 * x895;
    s[262] = x1511;
    let x1512 = x87 * x1409;
    s[263] = x1512;
    let x1514 = x1511 - x1512;
    s[264] = x1514;
    let x1515 = x78 * x1454;
    s[265] = x1515;
    let x1516 = x1511 + x1515;
    s[266] = x1516;
    let x1517 = x1514 + x1516;
    s[267] = x1517;
    let x1518 = x871 * x877;
    s[268] = x1518;
    let x1520 = x83 * x1411;
    s[269] = x1520;
    let x1521 = x1520 - x1518;
    s[270] = x1521;
    let x1522 = x79 * x1417;
    s[271] = x1522;
    let x1523 = x1522 - x1518;
    s[272] = x1523;
    let x1524 = x1521 + x1523;
    s[273] = x1524;
    let x1545 = x1480 + x1490;
    s[274] = x1545;
    let x1547 = x1517 - x1524;
    s[275] = x1547;
    let x1555 = 0.00000000000000006123233995736766 * x1150;
    s[276] = x1555;
    let x1556 = x1265 + x1555;
    s[277] = x1556;
    let x1557 = 0.00000000000000006123233995736766 * x1161;
    s[278] = x1557;
    let x1560 = x1267 + x1557;
    s[279] = x1560;
}
#[inline(never)]
fn gamma_part_0(k: &[f64; 17], s: &[f64; 280], out: &mut [f64; 21]) {
    let x22 = s[0] * s[3];
    let x56 = s[17] * s[19];
    let x59 = s[17] * s[22];
    let x60 = s[16] * s[20];
    let x63 = s[17] * s[23];
    let x64 = s[16] * s[21];
    let x67 = x59 + x60;
    let x70 = x63 - x64;
    let x122 = s[2] * 0.00000000000000006123233995736766;
    let x125 = x22 + x122;
    let x127 = s[14] * 0.00000000000000006123233995736766;
    let x128 = s[6] + x127;
    let x129 = s[15] * 0.00000000000000006123233995736766;
    let x130 = s[7] + x129;
    let x131 = x22 * 0.00000000000000006123233995736766;
    let x132 = x131 - s[2];
    let x755 = s[3] * s[36];
    let x756 = s[0] * s[39];
    let x758 = x755 - x756;
    let x827 = s[19] * s[69];
    let x829 = s[17] * s[71];
    let x831 = x827 + x829;
    let x840 = s[22] * s[69];
    let x842 = s[17] * s[76];
    let x843 = x842 - x840;
    let x844 = s[20] * s[68];
    let x845 = s[16] * s[72];
    let x846 = x844 + x845;
    let x856 = s[23] * s[69];
    let x858 = s[17] * s[79];
    let x859 = x858 - x856;
    let x860 = s[21] * s[68];
    let x861 = s[16] * s[73];
    let x863 = x860 - x861;
    let x866 = x843 + x846;
    let x869 = x859 - x863;
    let x959 = 0.00000000000000006123233995736766 * s[38];
    let x960 = x758 + x959;
    let x961 = 0.00000000000000006123233995736766 * s[66];
    let x962 = x961 - s[44];
    let x963 = 0.00000000000000006123233995736766 * s[67];
    let x964 = s[47] + x963;
    let x965 = 0.00000000000000006123233995736766 * x758;
    let x966 = x965 - s[38];
    let x1182 = s[36] * s[39];
    let x1184 = s[3] * s[96];
    let x1186 = x1182 + x1184;
    let x1188 = s[0] * s[99];
    let x1189 = x1182 + x1188;
    let x1191 = x1186 + x1189;
    let x1212 = s[37] * s[50];
    let x1213 = s[8] * s[97];
    let x1214 = x1212 + x1213;
    let x1217 = s[1] * s[119];
    let x1219 = x1212 + x1217;
    let x1221 = x1214 + x1219;
    let x1223 = s[36] * s[40];
    let x1224 = s[4] * s[96];
    let x1226 = x1223 - x1224;
    let x1227 = s[0] * s[100];
    let x1229 = x1223 - x1227;
    let x1230 = x1226 + x1229;
    let x1246 = s[37] * s[53];
    let x1247 = s[9] * s[97];
    let x1248 = x1246 + x1247;
    let x1251 = s[1] * s[125];
    let x1252 = x1251 - x1246;
    let x1253 = x1252 - x1248;
    let x1254 = s[36] * s[41];
    let x1256 = s[5] * s[96];
    let x1258 = x1254 + x1256;
    let x1260 = s[0] * s[101];
    let x1261 = x1254 + x1260;
    let x1263 = x1258 + x1261;
    let x1266 = x1230 - x1221;
    let x1268 = x1253 + x1263;
    let x1326 = s[69] * s[71];
    let x1328 = s[19] * s[153];
    let x1329 = x1328 - x1326;
    let x1330 = s[17] * s[155];
    let x1331 = x1330 - x1326;
    let x1332 = x1329 + x1331;
    let x1352 = s[69] * s[76];
    let x1353 = s[22] * s[153];
    let x1354 = x1352 + x1353;
    let x1357 = s[17] * s[175];
    let x1359 = x1352 + x1357;
    let x1361 = x1354 + x1359;
    let x1363 = s[68] * s[72];
    let x1364 = s[20] * s[152];
    let x1366 = x1363 - x1364;
    let x1367 = s[16] * s[156];
    let x1369 = x1363 - x1367;
    let x1370 = x1366 + x1369;
    let x1386 = s[69] * s[79];
    let x1387 = s[23] * s[153];
    let x1388 = x1386 + x1387;
    let x1391 = s[17] * s[181];
    let x1392 = x1391 - x1386;
    let x1393 = x1392 - x1388;
    let x1394 = s[68] * s[73];
    let x1396 = s[21] * s[152];
    let x1398 = x1394 + x1396;
    let x1400 = s[16] * s[157];
    let x1401 = x1394 + x1400;
    let x1403 = x1398 + x1401;
    let x1406 = x1370 - x1361;
    let x1408 = x1393 + x1403;
    let x1562 = 0.00000000000000006123233995736766 * s[98];
    let x1564 = x1191 + x1562;
    let x1566 = 0.00000000000000006123233995736766 * s[150];
    let x1567 = x1566 - s[107];
    let x1568 = 0.00000000000000006123233995736766 * s[151];
    let x1569 = x1568 - s[113];
    let x1570 = 0.00000000000000006123233995736766 * x1191;
    let x1572 = s[98] - x1570;
    let x1588 = x866 * s[93];
    let x1590 = s[33] * x1406;
    let x1591 = x1590 - x1588;
    let x1592 = x67 * s[277];
    let x1593 = x1588 + x1592;
    let x1595 = x1591 - x1593;
    let x1596 = x869 * s[95];
    let x1597 = s[35] * x1408;
    let x1598 = x1596 + x1597;
    let x1599 = x70 * s[279];
    let x1601 = x1596 - x1599;
    let x1602 = x1598 + x1601;
    let x1603 = x831 * x960;
    let x1604 = x125 * x1332;
    let x1605 = x1603 + x1604;
    let x1608 = x56 * x1564;
    let x1610 = x1603 + x1608;
    let x1612 = x1605 + x1610;
    let x1614 = x1595 + x1602;
    let x1615 = x1612 + x1614;
    let x1616 = x866 * x962;
    let x1617 = x128 * x1406;
    let x1618 = x1616 + x1617;
    let x1619 = x67 * x1567;
    let x1620 = x1616 + x1619;
    let x1621 = x1618 + x1620;
    let x1622 = x869 * x964;
    let x1623 = x130 * x1408;
    let x1624 = x1622 + x1623;
    let x1625 = x70 * x1569;
    let x1626 = x1622 + x1625;
    let x1627 = x1624 + x1626;
    let x1628 = x831 * x966;
    let x1629 = x132 * x1332;
    let x1630 = x1628 + x1629;
    let x1633 = x56 * x1572;
    let x1634 = x1633 - x1628;
    let x1635 = x1634 - x1630;
    let x1636 = x1621 + x1627;
    let x1637 = x1635 + x1636;
    let x1772 = -x1266;
    let x1773 = -x1268;
    let x1777 = -x1615;
    let x1778 = -x1637;
    let x2769 = s[107] * k[0];
    let x2770 = -x2769;
    let x2771 = s[113] * k[0];
    let x2772 = -x2771;
    let x2773 = s[98] * k[0];
    let x2774 = s[107] * k[1];
    let x2776 = s[113] * k[1];
    let x2778 = s[98] * k[1];
    let x2779 = s[163] * k[2];
    let x2780 = s[169] * k[2];
    let x2781 = s[154] * k[2];
    let x2783 = x2779 - x2774;
    let x2784 = x2780 - x2776;
    let x2785 = x2778 - x2781;
    let x2786 = s[163] * k[3];
    let x2788 = s[212] * k[4];
    let x2789 = x2788 - x2786;
    let x2790 = s[169] * k[3];
    let x2792 = s[213] * k[4];
    let x2793 = x2792 - x2790;
    let x2794 = s[154] * k[3];
    let x2795 = s[187] * k[4];
    let x2797 = x2794 - x2795;
    let x2819 = s[225] * k[7];
    let x2821 = s[274] * k[8];
    let x2822 = x2821 - x2819;
    let x2823 = s[231] * k[7];
    let x2825 = s[275] * k[8];
    let x2826 = x2825 - x2823;
    let x2827 = s[216] * k[7];
    let x2828 = s[249] * k[8];
    let x2830 = x2827 - x2828;
    let x2832 = x2789 - x2822;
    let x2834 = x2793 - x2826;
    let x2836 = x2797 - x2830;
    let x2892 = -x2783;
    let x2893 = -x2784;
    let x2894 = -x2785;
    let x2895 = -x2832;
    let x2896 = -x2834;
    let x2897 = -x2836;
    out[0] = x2770;
    out[1] = x2772;
    out[2] = x2773;
    out[3] = x1772;
    out[4] = x1773;
    out[5] = x2892;
    out[6] = x2893;
    out[7] = x2894;
    out[8] = x1777;
    out[9] = x1778;
    out[10] = x2895;
    out[11] = x2896;
    out[12] = x2897;
}
#[inline(never)]
fn gamma_part_1(k: &[f64; 17], t: f64, s: &[f64; 280], out: &mut [f64; 21]) {
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
    let x331 = x5.sin();
    let x332 = x5.cos();
    let x703 = 6.283185307179586 * x332;
    let x705 = 6.283185307179586 * x331;
    let x806 = s[21] * s[71];
    let x808 = s[19] * s[73];
    let x810 = x806 + x808;
    let x812 = s[20] * s[71];
    let x814 = s[19] * s[72];
    let x815 = x814 - x812;
    let x823 = s[19] * s[68];
    let x824 = s[16] * s[71];
    let x826 = x823 - x824;
    let x833 = s[22] * s[68];
    let x834 = s[16] * s[76];
    let x835 = x833 + x834;
    let x836 = s[20] * s[69];
    let x838 = s[17] * s[72];
    let x839 = x838 - x836;
    let x847 = s[23] * s[68];
    let x848 = s[16] * s[79];
    let x849 = x847 + x848;
    let x850 = s[21] * s[69];
    let x852 = s[17] * s[73];
    let x854 = x850 + x852;
    let x865 = x835 - x839;
    let x867 = x849 - x854;
    let x900 = s[27] * s[81];
    let x902 = s[25] * s[83];
    let x904 = x900 + x902;
    let x913 = s[30] * s[81];
    let x915 = s[25] * s[88];
    let x916 = x915 - x913;
    let x917 = s[28] * s[80];
    let x918 = s[24] * s[84];
    let x919 = x917 + x918;
    let x929 = s[31] * s[81];
    let x931 = s[25] * s[91];
    let x932 = x931 - x929;
    let x933 = s[29] * s[80];
    let x934 = s[24] * s[85];
    let x936 = x933 - x934;
    let x939 = x916 + x919;
    let x942 = x932 - x936;
    let x1122 = 6.283185307179586 * x705;
    let x1124 = 6.283185307179586 * x703;
    let x1125 = x703 * s[93];
    let x1127 = s[33] * x1122;
    let x1129 = x1125 + x1127;
    let x1131 = x705 * s[95];
    let x1132 = s[35] * x1124;
    let x1133 = x1131 + x1132;
    let x1466 = s[81] * s[83];
    let x1468 = s[27] * s[215];
    let x1469 = x1468 - x1466;
    let x1470 = s[25] * s[217];
    let x1471 = x1470 - x1466;
    let x1472 = x1469 + x1471;
    let x1492 = s[81] * s[88];
    let x1493 = s[30] * s[215];
    let x1494 = x1492 + x1493;
    let x1497 = s[25] * s[237];
    let x1499 = x1492 + x1497;
    let x1501 = x1494 + x1499;
    let x1503 = s[80] * s[84];
    let x1504 = s[28] * s[214];
    let x1506 = x1503 - x1504;
    let x1507 = s[24] * s[218];
    let x1509 = x1503 - x1507;
    let x1510 = x1506 + x1509;
    let x1526 = s[81] * s[91];
    let x1527 = s[31] * s[215];
    let x1528 = x1526 + x1527;
    let x1531 = s[25] * s[243];
    let x1532 = x1531 - x1526;
    let x1533 = x1532 - x1528;
    let x1534 = s[80] * s[85];
    let x1536 = s[29] * s[214];
    let x1538 = x1534 + x1536;
    let x1540 = s[24] * s[219];
    let x1541 = x1534 + x1540;
    let x1543 = x1538 + x1541;
    let x1546 = x1510 - x1501;
    let x1548 = x1533 + x1543;
    let x1759 = x331 * s[277];
    let x1760 = x1125 + x1759;
    let x1762 = x1129 + x1760;
    let x1765 = x332 * s[279];
    let x1767 = x1131 + x1765;
    let x1769 = x1133 + x1767;
    let x1771 = x1769 - x1762;
    let x1784 = -x1546;
    let x1785 = -x1548;
    let x1786 = -x1771;
    let x2517 = x51 * k[5];
    let x2518 = x66 * k[6];
    let x2519 = x2517 + x2518;
    let x2520 = x52 * k[5];
    let x2521 = x68 * k[6];
    let x2522 = x2520 + x2521;
    let x2523 = s[18] * k[5];
    let x2525 = x55 * k[6];
    let x2526 = x2525 - x2523;
    let x2527 = x51 * k[6];
    let x2529 = x66 * k[5];
    let x2530 = x2529 - x2527;
    let x2531 = x52 * k[6];
    let x2533 = x68 * k[5];
    let x2534 = x2533 - x2531;
    let x2535 = s[18] * k[6];
    let x2536 = x55 * k[5];
    let x2537 = x2535 + x2536;
    let x2748 = x810 * k[5];
    let x2750 = x865 * k[6];
    let x2751 = x2750 - x2748;
    let x2752 = x815 * k[5];
    let x2753 = x867 * k[6];
    let x2754 = x2752 + x2753;
    let x2755 = s[70] * k[5];
    let x2757 = x826 * k[6];
    let x2758 = x2757 - x2755;
    let x2759 = x810 * k[6];
    let x2760 = x865 * k[5];
    let x2761 = x2759 + x2760;
    let x2762 = x815 * k[6];
    let x2764 = x867 * k[5];
    let x2765 = x2764 - x2762;
    let x2766 = s[70] * k[6];
    let x2767 = x826 * k[5];
    let x2768 = x2766 + x2767;
    let x2798 = s[163] * k[5];
    let x2800 = s[212] * k[6];
    let x2801 = x2800 - x2798;
    let x2802 = s[169] * k[5];
    let x2804 = s[213] * k[6];
    let x2805 = x2804 - x2802;
    let x2806 = s[154] * k[5];
    let x2807 = s[187] * k[6];
    let x2809 = x2806 - x2807;
    let x2810 = s[163] * k[6];
    let x2811 = s[212] * k[5];
    let x2812 = x2810 + x2811;
    let x2813 = s[169] * k[6];
    let x2814 = s[213] * k[5];
    let x2815 = x2813 + x2814;
    let x2816 = s[154] * k[6];
    let x2817 = s[187] * k[5];
    let x2818 = x2816 + x2817;
    let x2837 = x939 * x2751;
    let x2838 = x1546 * x2519;
    let x2839 = x2837 + x2838;
    let x2840 = x100 * x2801;
    let x2841 = x2837 + x2840;
    let x2842 = x2839 + x2841;
    let x2843 = x942 * x2754;
    let x2844 = x1548 * x2522;
    let x2845 = x2843 + x2844;
    let x2846 = x103 * x2805;
    let x2847 = x2843 + x2846;
    let x2848 = x2845 + x2847;
    let x2849 = x904 * x2758;
    let x2850 = x1472 * x2526;
    let x2851 = x2849 + x2850;
    let x2854 = x89 * x2809;
    let x2855 = x2854 - x2849;
    let x2856 = x2855 - x2851;
    let x2857 = x2842 + x2848;
    let x2858 = x2856 + x2857;
    let x2859 = x939 * x2761;
    let x2860 = x1546 * x2530;
    let x2861 = x2859 + x2860;
    let x2862 = x100 * x2812;
    let x2863 = x2859 + x2862;
    let x2864 = x2861 + x2863;
    let x2865 = x942 * x2765;
    let x2866 = x1548 * x2534;
    let x2867 = x2865 + x2866;
    let x2868 = x103 * x2815;
    let x2869 = x2865 + x2868;
    let x2870 = x2867 + x2869;
    let x2871 = x904 * x2768;
    let x2872 = x1472 * x2537;
    let x2873 = x2871 + x2872;
    let x2874 = x89 * x2818;
    let x2875 = x2871 + x2874;
    let x2876 = x2873 + x2875;
    let x2878 = x2864 + x2870;
    let x2879 = x2878 - x2876;
    let x2880 = s[225] * k[10];
    let x2882 = s[274] * k[11];
    let x2883 = x2882 - x2880;
    let x2884 = s[231] * k[10];
    let x2886 = s[275] * k[11];
    let x2887 = x2886 - x2884;
    let x2888 = s[216] * k[10];
    let x2889 = s[249] * k[11];
    let x2891 = x2888 - x2889;
    let x2898 = -x2858;
    let x2899 = -x2879;
    out[13] = x2898;
    out[14] = x2899;
    out[15] = x2883;
    out[16] = x2887;
    out[17] = x2891;
    out[18] = x1784;
    out[19] = x1785;
    out[20] = x1786;
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
    let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 18] = qd.try_into().expect("qd must have n_coords entries");
    let phi: &mut [f64; 21] = phi.try_into().expect("phi must have 21 entries");
    let phi_q: &mut [f64; 96] = phi_q.try_into().expect("phi_q must have 96 entries");
    let phi_t: &mut [f64; 21] = phi_t.try_into().expect("phi_t must have 21 entries");
    let gamma: &mut [f64; 21] = gamma.try_into().expect("gamma must have 21 entries");
    let mut s = [0.0f64; 284];
    eval_kinematics_shared_0(k, q, qd, t, &mut s);
    eval_kinematics_part_0(k, q, &s, phi, phi_q, phi_t, gamma);
    eval_kinematics_part_1(k, q, &s, phi, phi_q, phi_t, gamma);
    eval_kinematics_part_2(&s, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_shared_0(
    k: &[f64; 17],
    q: &[f64; 18],
    qd: &[f64; 18],
    t: f64,
    s: &mut [f64; 284],
) {
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
    let x116 = x18 * 0.00000000000000006123233995736766;
    s[66] = x116;
    let x118 = x116 - x33;
    s[67] = x118;
    let x119 = x19 * 0.00000000000000006123233995736766;
    s[68] = x119;
    let x121 = x119 - x35;
    s[69] = x121;
    let x331 = x5.sin();
    s[70] = x331;
    let x332 = x5.cos();
    s[71] = x332;
    let x372 = x12 * x18;
    s[72] = x372;
    let x374 = x12 * x19;
    s[73] = x374;
    let x383 = x20 * 0.00000000000000006123233995736766;
    s[74] = x383;
    let x386 = x372 + x383;
    s[75] = x386;
    let x388 = x21 * 0.00000000000000006123233995736766;
    s[76] = x388;
    let x391 = x374 + x388;
    s[77] = x391;
    let x436 = x35 - x119;
    s[78] = x436;
    let x499 = x45 * x51;
    s[79] = x499;
    let x638 = x78 * x84;
    s[80] = x638;
    let x729 = x13 * qd[3];
    s[81] = x729;
    let x730 = x12 * qd[3];
    s[82] = x730;
    let x732 = x15 * qd[4];
    s[83] = x732;
    let x733 = x14 * qd[4];
    s[84] = x733;
    let x735 = x17 * qd[5];
    s[85] = x735;
    let x736 = x16 * qd[5];
    s[86] = x736;
    let x738 = x17 * x733;
    s[87] = x738;
    let x740 = x15 * x736;
    s[88] = x740;
    let x742 = x738 + x740;
    s[89] = x742;
    let x744 = x16 * x733;
    s[90] = x744;
    let x746 = x15 * x735;
    s[91] = x746;
    let x747 = x746 - x744;
    s[92] = x747;
    let x748 = x17 * x732;
    s[93] = x748;
    let x749 = x14 * x736;
    s[94] = x749;
    let x751 = x748 - x749;
    s[95] = x751;
    let x752 = x16 * x732;
    s[96] = x752;
    let x753 = x14 * x735;
    s[97] = x753;
    let x754 = x752 + x753;
    s[98] = x754;
    let x759 = x20 * x729;
    s[99] = x759;
    let x760 = x12 * x751;
    s[100] = x760;
    let x761 = x759 + x760;
    s[101] = x761;
    let x762 = x16 * x730;
    s[102] = x762;
    let x764 = x13 * x735;
    s[103] = x764;
    let x765 = x764 - x762;
    s[104] = x765;
    let x773 = x21 * x729;
    s[105] = x773;
    let x774 = x12 * x754;
    s[106] = x774;
    let x775 = x773 + x774;
    s[107] = x775;
    let x776 = x17 * x730;
    s[108] = x776;
    let x778 = x13 * x736;
    s[109] = x778;
    let x780 = x776 + x778;
    s[110] = x780;
    let x791 = x761 - x765;
    s[111] = x791;
    let x793 = x775 - x780;
    s[112] = x793;
    let x797 = x46 * qd[9];
    s[113] = x797;
    let x798 = x45 * qd[9];
    s[114] = x798;
    let x800 = x48 * qd[10];
    s[115] = x800;
    let x801 = x47 * qd[10];
    s[116] = x801;
    let x803 = x50 * qd[11];
    s[117] = x803;
    let x804 = x49 * qd[11];
    s[118] = x804;
    let x816 = x50 * x800;
    s[119] = x816;
    let x817 = x47 * x804;
    s[120] = x817;
    let x819 = x816 - x817;
    s[121] = x819;
    let x820 = x49 * x800;
    s[122] = x820;
    let x821 = x47 * x803;
    s[123] = x821;
    let x822 = x820 + x821;
    s[124] = x822;
    let x870 = x79 * qd[15];
    s[125] = x870;
    let x871 = x78 * qd[15];
    s[126] = x871;
    let x873 = x81 * qd[16];
    s[127] = x873;
    let x874 = x80 * qd[16];
    s[128] = x874;
    let x876 = x83 * qd[17];
    s[129] = x876;
    let x877 = x82 * qd[17];
    s[130] = x877;
    let x889 = x83 * x873;
    s[131] = x889;
    let x890 = x80 * x877;
    s[132] = x890;
    let x892 = x889 - x890;
    s[133] = x892;
    let x951 = 0.00000000000000006123233995736766 * x742;
    s[134] = x951;
    let x954 = x791 + x951;
    s[135] = x954;
    let x956 = 0.00000000000000006123233995736766 * x747;
    s[136] = x956;
    let x958 = x956 - x793;
    s[137] = x958;
    let x1135 = qd[3] * x730;
    s[138] = x1135;
    let x1137 = qd[3] * x729;
    s[139] = x1137;
    let x1138 = qd[4] * x733;
    s[140] = x1138;
    let x1140 = qd[4] * x732;
    s[141] = x1140;
    let x1141 = qd[5] * x736;
    s[142] = x1141;
    let x1143 = qd[5] * x735;
    s[143] = x1143;
    let x1144 = x733 * x736;
    s[144] = x1144;
    let x1146 = x17 * x1140;
    s[145] = x1146;
    let x1147 = x1146 - x1144;
    s[146] = x1147;
    let x1148 = x15 * x1143;
    s[147] = x1148;
    let x1149 = x1148 - x1144;
    s[148] = x1149;
    let x1150 = x1147 + x1149;
    s[149] = x1150;
    let x1152 = x733 * x735;
    s[150] = x1152;
    let x1153 = x16 * x1140;
    s[151] = x1153;
    let x1154 = x1152 + x1153;
    s[152] = x1154;
    let x1157 = x15 * x1141;
    s[153] = x1157;
    let x1159 = x1152 + x1157;
    s[154] = x1159;
    let x1161 = x1154 + x1159;
    s[155] = x1161;
    let x1163 = x732 * x736;
    s[156] = x1163;
    let x1165 = x17 * x1138;
    s[157] = x1165;
    let x1167 = x1163 + x1165;
    s[158] = x1167;
    let x1169 = x14 * x1143;
    s[159] = x1169;
    let x1170 = x1163 + x1169;
    s[160] = x1170;
    let x1172 = x1167 + x1170;
    s[161] = x1172;
    let x1174 = x732 * x735;
    s[162] = x1174;
    let x1175 = x16 * x1138;
    s[163] = x1175;
    let x1177 = x1174 - x1175;
    s[164] = x1177;
    let x1178 = x14 * x1141;
    s[165] = x1178;
    let x1180 = x1174 - x1178;
    s[166] = x1180;
    let x1181 = x1177 + x1180;
    s[167] = x1181;
    let x1193 = x729 * x751;
    s[168] = x1193;
    let x1194 = x20 * x1135;
    s[169] = x1194;
    let x1196 = x1193 - x1194;
    s[170] = x1196;
    let x1197 = x12 * x1172;
    s[171] = x1197;
    let x1199 = x1193 - x1197;
    s[172] = x1199;
    let x1200 = x1196 + x1199;
    s[173] = x1200;
    let x1201 = x730 * x735;
    s[174] = x1201;
    let x1202 = x16 * x1137;
    s[175] = x1202;
    let x1203 = x1201 + x1202;
    s[176] = x1203;
    let x1206 = x13 * x1141;
    s[177] = x1206;
    let x1208 = x1201 + x1206;
    s[178] = x1208;
    let x1210 = x1203 + x1208;
    s[179] = x1210;
    let x1231 = x729 * x754;
    s[180] = x1231;
    let x1232 = x21 * x1135;
    s[181] = x1232;
    let x1234 = x1231 - x1232;
    s[182] = x1234;
    let x1235 = x12 * x1181;
    s[183] = x1235;
    let x1236 = x1231 + x1235;
    s[184] = x1236;
    let x1237 = x1234 + x1236;
    s[185] = x1237;
    let x1238 = x730 * x736;
    s[186] = x1238;
    let x1240 = x17 * x1137;
    s[187] = x1240;
    let x1241 = x1240 - x1238;
    s[188] = x1241;
    let x1242 = x13 * x1143;
    s[189] = x1242;
    let x1243 = x1242 - x1238;
    s[190] = x1243;
    let x1244 = x1241 + x1243;
    s[191] = x1244;
    let x1265 = x1200 + x1210;
    s[192] = x1265;
    let x1267 = x1237 - x1244;
    s[193] = x1267;
    let x1269 = qd[9] * x798;
    s[194] = x1269;
    let x1271 = qd[9] * x797;
    s[195] = x1271;
    let x1272 = qd[10] * x801;
    s[196] = x1272;
    let x1274 = qd[10] * x800;
    s[197] = x1274;
    let x1275 = qd[11] * x804;
    s[198] = x1275;
    let x1277 = qd[11] * x803;
    s[199] = x1277;
    let x1278 = x801 * x804;
    s[200] = x1278;
    let x1280 = x50 * x1274;
    s[201] = x1280;
    let x1281 = x1280 - x1278;
    s[202] = x1281;
    let x1282 = x48 * x1277;
    s[203] = x1282;
    let x1283 = x1282 - x1278;
    s[204] = x1283;
    let x1284 = x1281 + x1283;
    s[205] = x1284;
    let x1285 = x801 * x803;
    s[206] = x1285;
    let x1286 = x49 * x1274;
    s[207] = x1286;
    let x1287 = x1285 + x1286;
    s[208] = x1287;
    let x1290 = x48 * x1275;
    s[209] = x1290;
    let x1292 = x1285 + x1290;
    s[210] = x1292;
    let x1294 = x1287 + x1292;
    s[211] = x1294;
    let x1296 = x800 * x804;
    s[212] = x1296;
    let x1298 = x50 * x1272;
    s[213] = x1298;
    let x1300 = x1296 + x1298;
    s[214] = x1300;
    let x1302 = x47 * x1277;
    s[215] = x1302;
    let x1303 = x1296 + x1302;
    s[216] = x1303;
    let x1305 = x1300 + x1303;
    s[217] = x1305;
    let x1307 = x800 * x803;
    s[218] = x1307;
    let x1308 = x49 * x1272;
    s[219] = x1308;
    let x1310 = x1307 - x1308;
    s[220] = x1310;
    let x1311 = x47 * x1275;
    s[221] = x1311;
    let x1313 = x1307 - x1311;
    s[222] = x1313;
    let x1314 = x1310 + x1313;
    s[223] = x1314;
    let x1333 = x797 * x819;
    s[224] = x1333;
    let x1334 = x53 * x1269;
    s[225] = x1334;
    let x1336 = x1333 - x1334;
    s[226] = x1336;
    let x1337 = x45 * x1305;
    s[227] = x1337;
    let x1339 = x1333 - x1337;
    s[228] = x1339;
    let x1340 = x1336 + x1339;
    s[229] = x1340;
    let x1341 = x798 * x803;
    s[230] = x1341;
    let x1342 = x49 * x1271;
    s[231] = x1342;
    let x1343 = x1341 + x1342;
    s[232] = x1343;
    let x1346 = x46 * x1275;
    s[233] = x1346;
    let x1348 = x1341 + x1346;
    s[234] = x1348;
    let x1350 = x1343 + x1348;
    s[235] = x1350;
    let x1405 = x1340 + x1350;
    s[236] = x1405;
    let x1409 = qd[15] * x871;
    s[237] = x1409;
    let x1411 = qd[15] * x870;
    s[238] = x1411;
    let x1412 = qd[16] * x874;
    s[239] = x1412;
    let x1414 = qd[16] * x873;
    s[240] = x1414;
    let x1415 = qd[17] * x877;
    s[241] = x1415;
    let x1417 = qd[17] * x876;
    s[242] = x1417;
    let x1418 = x874 * x877;
    s[243] = x1418;
    let x1420 = x83 * x1414;
    s[244] = x1420;
    let x1421 = x1420 - x1418;
    s[245] = x1421;
    let x1422 = x81 * x1417;
    s[246] = x1422;
    let x1423 = x1422 - x1418;
    s[247] = x1423;
    let x1424 = x1421 + x1423;
    s[248] = x1424;
    let x1436 = x873 * x877;
    s[249] = x1436;
    let x1438 = x83 * x1412;
    s[250] = x1438;
    let x1440 = x1436 + x1438;
    s[251] = x1440;
    let x1442 = x80 * x1417;
    s[252] = x1442;
    let x1443 = x1436 + x1442;
    s[253] = x1443;
    let x1445 = x1440 + x1443;
    s[254] = x1445;
    let x1473 = x870 * x892;
    s[255] = x1473;
    let x1474 = x86 * x1409;
    s[256] = x1474;
    let x1476 = x1473 - x1474;
    s[257] = x1476;
    let x1477 = x78 * x1445;
    s[258] = x1477;
    let x1479 = x1473 - x1477;
    s[259] = x1479;
    let x1480 = x1476 + x1479;
    s[260] = x1480;
    let x1481 = x871 * x876;
    s[261] = x1481;
    let x1482 = x82 * x1411;
    s[262] = x1482;
    let x1483 = x1481 + x1482;
    s[263] = x1483;
    let x1486 = x79 * x1415;
    s[264] = x1486;
    let x1488 = x1481 + x1486;
    s[265] = x1488;
    let x1490 = x1483 + x1488;
    s[266] = x1490;
    let x1545 = x1480 + x1490;
    s[267] = x1545;
    let x1555 = 0.00000000000000006123233995736766 * x1150;
    s[268] = x1555;
    let x1556 = x1265 + x1555;
    s[269] = x1556;
    let x1557 = 0.00000000000000006123233995736766 * x1161;
    s[270] = x1557;
    let x1560 = x1267 + x1557;
    s[271] = x1560;
    let x2502 = x51 * k[3];
    s[272] = x2502;
    let x2503 = x66 * k[4];
    s[273] = x2503;
    let x2504 = x2502 + x2503;
    s[274] = x2504;
    let x2505 = x52 * k[3];
    s[275] = x2505;
    let x2506 = x68 * k[4];
    s[276] = x2506;
    let x2507 = x2505 + x2506;
    s[277] = x2507;
    let x2540 = x84 * k[7];
    s[278] = x2540;
    let x2541 = x99 * k[8];
    s[279] = x2541;
    let x2542 = x2540 + x2541;
    s[280] = x2542;
    let x2543 = x85 * k[7];
    s[281] = x2543;
    let x2544 = x101 * k[8];
    s[282] = x2544;
    let x2545 = x2543 + x2544;
    s[283] = x2545;
}
#[inline(never)]
fn eval_kinematics_part_0(
    k: &[f64; 17],
    q: &[f64; 18],
    s: &[f64; 284],
    phi: &mut [f64; 21],
    phi_q: &mut [f64; 96],
    phi_t: &mut [f64; 21],
    gamma: &mut [f64; 21],
) {
    let x22 = s[1] * s[4];
    let x23 = s[2] * s[4];
    let x120 = -s[21];
    let x122 = s[3] * 0.00000000000000006123233995736766;
    let x125 = x22 + x122;
    let x127 = s[19] * 0.00000000000000006123233995736766;
    let x128 = s[7] + x127;
    let x129 = s[21] * 0.00000000000000006123233995736766;
    let x130 = s[8] + x129;
    let x131 = x22 * 0.00000000000000006123233995736766;
    let x132 = x131 - s[3];
    let x182 = s[44] * s[67];
    let x183 = s[46] * s[69];
    let x184 = s[34] * x125;
    let x186 = x182 + x183;
    let x187 = x186 - x184;
    let x188 = s[44] * x128;
    let x189 = s[46] * x130;
    let x190 = s[34] * x132;
    let x191 = x188 + x189;
    let x192 = x190 + x191;
    let x341 = s[12] - s[11];
    let x345 = s[20] * 0.00000000000000006123233995736766;
    let x346 = s[22] * 0.00000000000000006123233995736766;
    let x347 = x23 * 0.00000000000000006123233995736766;
    let x348 = s[20] * s[44];
    let x350 = s[22] * s[46];
    let x352 = x23 * s[34];
    let x354 = x348 + x350;
    let x356 = x352 + x354;
    let x357 = -x356;
    let x358 = s[44] * x345;
    let x359 = s[46] * x346;
    let x360 = s[34] * x347;
    let x361 = x358 + x359;
    let x362 = x360 + x361;
    let x370 = s[1] * s[3];
    let x373 = s[2] * s[7];
    let x375 = s[2] * s[8];
    let x393 = s[4] * 0.00000000000000006123233995736766;
    let x394 = x393 - x370;
    let x395 = 0.00000000000000006123233995736766 * s[72];
    let x396 = x395 - s[9];
    let x397 = 0.00000000000000006123233995736766 * s[73];
    let x398 = x397 - s[10];
    let x399 = 0.00000000000000006123233995736766 * x370;
    let x401 = s[4] + x399;
    let x409 = s[44] * s[75];
    let x411 = s[46] * s[77];
    let x413 = s[34] * x394;
    let x415 = x409 + x411;
    let x417 = x413 + x415;
    let x418 = -x417;
    let x419 = s[44] * x396;
    let x420 = s[46] * x398;
    let x421 = s[34] * x401;
    let x423 = x419 + x420;
    let x424 = x423 - x421;
    let x433 = s[18] - s[17];
    let x441 = s[44] * s[78];
    let x442 = s[46] * s[67];
    let x443 = x441 + x442;
    let x444 = s[44] * x130;
    let x446 = s[46] * x128;
    let x447 = x446 - x444;
    let x457 = s[36] - s[35];
    let x460 = s[67] * x457;
    let x461 = s[45] * s[69];
    let x463 = s[33] * x125;
    let x465 = x460 - x461;
    let x466 = x463 + x465;
    let x467 = x128 * x457;
    let x468 = s[45] * x130;
    let x470 = s[33] * x132;
    let x472 = x467 - x468;
    let x473 = x472 - x470;
    let x497 = s[24] * s[25];
    let x500 = s[24] * s[29];
    let x502 = s[24] * s[30];
    let x509 = s[67] * x500;
    let x510 = s[69] * x502;
    let x511 = x125 * x497;
    let x513 = x509 + x510;
    let x514 = x511 + x513;
    let x515 = x128 * x500;
    let x516 = x130 * x502;
    let x517 = x132 * x497;
    let x519 = x515 + x516;
    let x520 = x519 - x517;
    let x575 = s[42] - s[41];
    let x578 = s[67] * x575;
    let x579 = s[44] * s[69];
    let x580 = x578 + x579;
    let x581 = x128 * x575;
    let x582 = x444 + x581;
    let x755 = s[4] * s[81];
    let x756 = s[1] * s[84];
    let x758 = x755 - x756;
    let x827 = s[26] * s[114];
    let x829 = s[24] * s[116];
    let x831 = x827 + x829;
    let x840 = s[31] * s[114];
    let x842 = s[24] * s[121];
    let x843 = x842 - x840;
    let x844 = s[27] * s[113];
    let x845 = s[23] * s[117];
    let x846 = x844 + x845;
    let x856 = s[32] * s[114];
    let x858 = s[24] * s[124];
    let x859 = x858 - x856;
    let x860 = s[28] * s[113];
    let x861 = s[23] * s[118];
    let x863 = x860 - x861;
    let x866 = x843 + x846;
    let x869 = x859 - x863;
    let x959 = 0.00000000000000006123233995736766 * s[83];
    let x960 = x758 + x959;
    let x961 = 0.00000000000000006123233995736766 * s[111];
    let x962 = x961 - s[89];
    let x963 = 0.00000000000000006123233995736766 * s[112];
    let x964 = s[92] + x963;
    let x965 = 0.00000000000000006123233995736766 * x758;
    let x966 = x965 - s[83];
    let x1182 = s[81] * s[84];
    let x1184 = s[4] * s[138];
    let x1186 = x1182 + x1184;
    let x1188 = s[1] * s[141];
    let x1189 = x1182 + x1188;
    let x1191 = x1186 + x1189;
    let x1212 = s[82] * s[95];
    let x1213 = s[9] * s[139];
    let x1214 = x1212 + x1213;
    let x1217 = s[2] * s[161];
    let x1219 = x1212 + x1217;
    let x1221 = x1214 + x1219;
    let x1223 = s[81] * s[85];
    let x1224 = s[5] * s[138];
    let x1226 = x1223 - x1224;
    let x1227 = s[1] * s[142];
    let x1229 = x1223 - x1227;
    let x1230 = x1226 + x1229;
    let x1246 = s[82] * s[98];
    let x1247 = s[10] * s[139];
    let x1248 = x1246 + x1247;
    let x1251 = s[2] * s[167];
    let x1252 = x1251 - x1246;
    let x1253 = x1252 - x1248;
    let x1254 = s[81] * s[86];
    let x1256 = s[6] * s[138];
    let x1258 = x1254 + x1256;
    let x1260 = s[1] * s[143];
    let x1261 = x1254 + x1260;
    let x1263 = x1258 + x1261;
    let x1266 = x1230 - x1221;
    let x1268 = x1253 + x1263;
    let x1326 = s[114] * s[116];
    let x1328 = s[26] * s[195];
    let x1329 = x1328 - x1326;
    let x1330 = s[24] * s[197];
    let x1331 = x1330 - x1326;
    let x1332 = x1329 + x1331;
    let x1352 = s[114] * s[121];
    let x1353 = s[31] * s[195];
    let x1354 = x1352 + x1353;
    let x1357 = s[24] * s[217];
    let x1359 = x1352 + x1357;
    let x1361 = x1354 + x1359;
    let x1363 = s[113] * s[117];
    let x1364 = s[27] * s[194];
    let x1366 = x1363 - x1364;
    let x1367 = s[23] * s[198];
    let x1369 = x1363 - x1367;
    let x1370 = x1366 + x1369;
    let x1386 = s[114] * s[124];
    let x1387 = s[32] * s[195];
    let x1388 = x1386 + x1387;
    let x1391 = s[24] * s[223];
    let x1392 = x1391 - x1386;
    let x1393 = x1392 - x1388;
    let x1394 = s[113] * s[118];
    let x1396 = s[28] * s[194];
    let x1398 = x1394 + x1396;
    let x1400 = s[23] * s[199];
    let x1401 = x1394 + x1400;
    let x1403 = x1398 + x1401;
    let x1406 = x1370 - x1361;
    let x1408 = x1393 + x1403;
    let x1562 = 0.00000000000000006123233995736766 * s[140];
    let x1564 = x1191 + x1562;
    let x1566 = 0.00000000000000006123233995736766 * s[192];
    let x1567 = x1566 - s[149];
    let x1568 = 0.00000000000000006123233995736766 * s[193];
    let x1569 = x1568 - s[155];
    let x1570 = 0.00000000000000006123233995736766 * x1191;
    let x1572 = s[140] - x1570;
    let x1588 = x866 * s[135];
    let x1590 = s[67] * x1406;
    let x1591 = x1590 - x1588;
    let x1592 = s[44] * s[269];
    let x1593 = x1588 + x1592;
    let x1595 = x1591 - x1593;
    let x1596 = x869 * s[137];
    let x1597 = s[69] * x1408;
    let x1598 = x1596 + x1597;
    let x1599 = s[46] * s[271];
    let x1601 = x1596 - x1599;
    let x1602 = x1598 + x1601;
    let x1603 = x831 * x960;
    let x1604 = x125 * x1332;
    let x1605 = x1603 + x1604;
    let x1608 = s[34] * x1564;
    let x1610 = x1603 + x1608;
    let x1612 = x1605 + x1610;
    let x1614 = x1595 + x1602;
    let x1615 = x1612 + x1614;
    let x1616 = x866 * x962;
    let x1617 = x128 * x1406;
    let x1618 = x1616 + x1617;
    let x1619 = s[44] * x1567;
    let x1620 = x1616 + x1619;
    let x1621 = x1618 + x1620;
    let x1622 = x869 * x964;
    let x1623 = x130 * x1408;
    let x1624 = x1622 + x1623;
    let x1625 = s[46] * x1569;
    let x1626 = x1622 + x1625;
    let x1627 = x1624 + x1626;
    let x1628 = x831 * x966;
    let x1629 = x132 * x1332;
    let x1630 = x1628 + x1629;
    let x1633 = s[34] * x1572;
    let x1634 = x1633 - x1628;
    let x1635 = x1634 - x1630;
    let x1636 = x1621 + x1627;
    let x1637 = x1635 + x1636;
    let x1772 = -x1266;
    let x1773 = -x1268;
    let x1777 = -x1615;
    let x1778 = -x1637;
    let x2468 = s[7] * k[0];
    let x2469 = s[8] * k[0];
    let x2470 = s[3] * k[0];
    let x2472 = q[0] + x2468;
    let x2473 = q[1] + x2469;
    let x2474 = q[2] - x2470;
    let x2475 = -x2472;
    let x2476 = -x2473;
    let x2477 = -x2474;
    let x2479 = s[7] * k[1];
    let x2480 = s[8] * k[1];
    let x2481 = s[3] * k[1];
    let x2483 = q[0] + x2479;
    let x2484 = q[1] + x2480;
    let x2485 = q[2] - x2481;
    let x2487 = s[29] * k[2];
    let x2488 = s[30] * k[2];
    let x2489 = s[25] * k[2];
    let x2491 = q[6] + x2487;
    let x2492 = q[7] + x2488;
    let x2493 = q[8] - x2489;
    let x2495 = x2483 - x2491;
    let x2497 = x2484 - x2492;
    let x2499 = x2485 - x2493;
    let x2512 = q[6] + s[274];
    let x2550 = q[12] + s[280];
    let x2554 = x2512 - x2550;
    let x2589 = s[9] * k[0];
    let x2590 = s[10] * k[0];
    let x2591 = s[4] * k[0];
    let x2592 = s[9] * k[1];
    let x2593 = -x2592;
    let x2594 = s[10] * k[1];
    let x2595 = -x2594;
    let x2596 = s[4] * k[1];
    let x2597 = -x2596;
    let x2598 = -x2468;
    let x2599 = -x2480;
    let x2600 = s[44] * k[4];
    let x2619 = s[31] * k[2];
    let x2620 = s[32] * k[2];
    let x2621 = s[26] * k[2];
    let x2622 = s[31] * k[3];
    let x2624 = s[79] * k[4];
    let x2625 = x2624 - x2622;
    let x2666 = -x2487;
    let x2667 = -s[277];
    let x2677 = s[64] * k[8];
    let x2680 = -x2677;
    let x2703 = s[55] * k[7];
    let x2705 = s[80] * k[8];
    let x2706 = x2705 - x2703;
    let x2714 = -x2706;
    let x2769 = s[149] * k[0];
    let x2770 = -x2769;
    let x2771 = s[155] * k[0];
    let x2772 = -x2771;
    let x2773 = s[140] * k[0];
    let x2774 = s[149] * k[1];
    let x2776 = s[155] * k[1];
    let x2778 = s[140] * k[1];
    let x2779 = s[205] * k[2];
    let x2780 = s[211] * k[2];
    let x2781 = s[196] * k[2];
    let x2783 = x2779 - x2774;
    let x2784 = x2780 - x2776;
    let x2785 = x2778 - x2781;
    let x2786 = s[205] * k[3];
    let x2788 = s[236] * k[4];
    let x2789 = x2788 - x2786;
    let x2819 = s[248] * k[7];
    let x2821 = s[267] * k[8];
    let x2822 = x2821 - x2819;
    let x2832 = x2789 - x2822;
    let x2892 = -x2783;
    let x2893 = -x2784;
    let x2894 = -x2785;
    let x2895 = -x2832;
    phi[0] = x2475;
    phi_q[0] = -1.0;
    phi_q[1] = x2589;
    phi_q[2] = x2469;
    phi_t[0] = 0.0;
    gamma[0] = x2770;
    phi[1] = x2476;
    phi_q[3] = -1.0;
    phi_q[4] = x2590;
    phi_q[5] = x2598;
    phi_t[1] = 0.0;
    gamma[1] = x2772;
    phi[2] = x2477;
    phi_q[6] = -1.0;
    phi_q[7] = x2591;
    phi_t[2] = 0.0;
    gamma[2] = x2773;
    phi[3] = s[20];
    phi_q[8] = x341;
    phi_q[9] = x373;
    phi_q[10] = x433;
    phi_t[3] = 0.0;
    gamma[3] = x1772;
    phi[4] = s[22];
    phi_q[11] = x120;
    phi_q[12] = x375;
    phi_q[13] = s[20];
    phi_t[4] = 0.0;
    gamma[4] = x1773;
    phi[5] = x2495;
    phi_q[14] = 1.0;
    phi_q[15] = x2593;
    phi_q[16] = x2599;
    phi_q[17] = -1.0;
    phi_q[18] = x2619;
    phi_q[19] = x2488;
    phi_t[5] = 0.0;
    gamma[5] = x2892;
    phi[6] = x2497;
    phi_q[20] = 1.0;
    phi_q[21] = x2595;
    phi_q[22] = x2479;
    phi_q[23] = -1.0;
    phi_q[24] = x2620;
    phi_q[25] = x2666;
    phi_t[6] = 0.0;
    gamma[6] = x2893;
    phi[7] = x2499;
    phi_q[26] = 1.0;
    phi_q[27] = x2597;
    phi_q[28] = -1.0;
    phi_q[29] = x2621;
    phi_t[7] = 0.0;
    gamma[7] = x2894;
    phi[8] = x187;
    phi_q[30] = x357;
    phi_q[31] = x418;
    phi_q[32] = x443;
    phi_q[33] = x466;
    phi_q[34] = x514;
    phi_q[35] = x580;
    phi_t[8] = 0.0;
    gamma[8] = x1777;
    phi[9] = x192;
    phi_q[36] = x362;
    phi_q[37] = x424;
    phi_q[38] = x447;
    phi_q[39] = x473;
    phi_q[40] = x520;
    phi_q[41] = x582;
    phi_t[9] = 0.0;
    gamma[9] = x1778;
    phi[10] = x2554;
    phi_q[42] = 1.0;
    phi_q[43] = x2600;
    phi_q[44] = x2625;
    phi_q[45] = x2667;
    phi_q[46] = -1.0;
    phi_q[47] = x2680;
    phi_q[48] = x2714;
    phi_q[49] = s[283];
    phi_t[10] = 0.0;
    gamma[10] = x2895;
}
#[inline(never)]
fn eval_kinematics_part_1(
    k: &[f64; 17],
    q: &[f64; 18],
    s: &[f64; 284],
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
    let x333 = s[67] * s[70];
    let x334 = s[69] * s[71];
    let x336 = x333 - x334;
    let x495 = s[23] * s[25];
    let x501 = s[23] * s[30];
    let x603 = s[58] - s[57];
    let x605 = -s[65];
    let x634 = s[47] * s[49];
    let x636 = s[48] * s[49];
    let x639 = s[48] * s[53];
    let x640 = s[47] * s[54];
    let x641 = s[48] * s[54];
    let x689 = x97 - x96;
    let x806 = s[28] * s[116];
    let x808 = s[26] * s[118];
    let x810 = x806 + x808;
    let x812 = s[27] * s[116];
    let x814 = s[26] * s[117];
    let x815 = x814 - x812;
    let x823 = s[26] * s[113];
    let x824 = s[23] * s[116];
    let x826 = x823 - x824;
    let x833 = s[31] * s[113];
    let x834 = s[23] * s[121];
    let x835 = x833 + x834;
    let x836 = s[27] * s[114];
    let x838 = s[24] * s[117];
    let x839 = x838 - x836;
    let x847 = s[32] * s[113];
    let x848 = s[23] * s[124];
    let x849 = x847 + x848;
    let x850 = s[28] * s[114];
    let x852 = s[24] * s[118];
    let x854 = x850 + x852;
    let x865 = x835 - x839;
    let x867 = x849 - x854;
    let x893 = s[51] * s[127];
    let x894 = s[49] * s[129];
    let x895 = x893 + x894;
    let x900 = s[50] * s[126];
    let x902 = s[48] * s[128];
    let x904 = x900 + x902;
    let x913 = s[55] * s[126];
    let x915 = s[48] * s[133];
    let x916 = x915 - x913;
    let x917 = s[51] * s[125];
    let x918 = s[47] * s[129];
    let x919 = x917 + x918;
    let x929 = s[56] * s[126];
    let x931 = s[48] * x895;
    let x932 = x931 - x929;
    let x933 = s[52] * s[125];
    let x934 = s[47] * s[130];
    let x936 = x933 - x934;
    let x939 = x916 + x919;
    let x942 = x932 - x936;
    let x1315 = s[113] * s[116];
    let x1317 = s[26] * s[194];
    let x1319 = x1315 + x1317;
    let x1321 = s[23] * s[197];
    let x1322 = x1315 + x1321;
    let x1324 = x1319 + x1322;
    let x1371 = s[113] * s[124];
    let x1372 = s[32] * s[194];
    let x1374 = x1371 - x1372;
    let x1375 = s[23] * s[223];
    let x1376 = x1371 + x1375;
    let x1377 = x1374 + x1376;
    let x1378 = s[114] * s[118];
    let x1380 = s[28] * s[195];
    let x1381 = x1380 - x1378;
    let x1382 = s[24] * s[199];
    let x1383 = x1382 - x1378;
    let x1384 = x1381 + x1383;
    let x1407 = x1377 - x1384;
    let x1425 = s[128] * s[129];
    let x1426 = s[51] * s[240];
    let x1427 = x1425 + x1426;
    let x1430 = s[50] * s[241];
    let x1432 = x1425 + x1430;
    let x1434 = x1427 + x1432;
    let x1447 = s[127] * s[129];
    let x1448 = s[51] * s[239];
    let x1450 = x1447 - x1448;
    let x1451 = s[49] * s[241];
    let x1453 = x1447 - x1451;
    let x1454 = x1450 + x1453;
    let x1455 = s[125] * s[128];
    let x1457 = s[50] * s[237];
    let x1459 = x1455 + x1457;
    let x1461 = s[47] * s[240];
    let x1462 = x1455 + x1461;
    let x1464 = x1459 + x1462;
    let x1466 = s[126] * s[128];
    let x1468 = s[50] * s[238];
    let x1469 = x1468 - x1466;
    let x1470 = s[48] * s[240];
    let x1471 = x1470 - x1466;
    let x1472 = x1469 + x1471;
    let x1492 = s[126] * s[133];
    let x1493 = s[55] * s[238];
    let x1494 = x1492 + x1493;
    let x1497 = s[48] * s[254];
    let x1499 = x1492 + x1497;
    let x1501 = x1494 + x1499;
    let x1503 = s[125] * s[129];
    let x1504 = s[51] * s[237];
    let x1506 = x1503 - x1504;
    let x1507 = s[47] * s[241];
    let x1509 = x1503 - x1507;
    let x1510 = x1506 + x1509;
    let x1511 = s[125] * x895;
    let x1512 = s[56] * s[237];
    let x1514 = x1511 - x1512;
    let x1515 = s[47] * x1454;
    let x1516 = x1511 + x1515;
    let x1517 = x1514 + x1516;
    let x1518 = s[126] * s[130];
    let x1520 = s[52] * s[238];
    let x1521 = x1520 - x1518;
    let x1522 = s[48] * s[242];
    let x1523 = x1522 - x1518;
    let x1524 = x1521 + x1523;
    let x1526 = s[126] * x895;
    let x1527 = s[56] * s[238];
    let x1528 = x1526 + x1527;
    let x1531 = s[48] * x1454;
    let x1532 = x1531 - x1526;
    let x1533 = x1532 - x1528;
    let x1534 = s[125] * s[130];
    let x1536 = s[52] * s[237];
    let x1538 = x1534 + x1536;
    let x1540 = s[47] * s[242];
    let x1541 = x1534 + x1540;
    let x1543 = x1538 + x1541;
    let x1546 = x1510 - x1501;
    let x1547 = x1517 - x1524;
    let x1548 = x1533 + x1543;
    let x1784 = -x1546;
    let x1785 = -x1548;
    let x2508 = s[25] * k[3];
    let x2510 = s[33] * k[4];
    let x2511 = x2510 - x2508;
    let x2513 = q[7] + s[277];
    let x2514 = q[8] + x2511;
    let x2517 = s[29] * k[5];
    let x2518 = s[43] * k[6];
    let x2519 = x2517 + x2518;
    let x2520 = s[30] * k[5];
    let x2521 = s[45] * k[6];
    let x2522 = x2520 + x2521;
    let x2523 = s[25] * k[5];
    let x2525 = s[33] * k[6];
    let x2526 = x2525 - x2523;
    let x2527 = s[29] * k[6];
    let x2529 = s[43] * k[5];
    let x2530 = x2529 - x2527;
    let x2531 = s[30] * k[6];
    let x2533 = s[45] * k[5];
    let x2534 = x2533 - x2531;
    let x2535 = s[25] * k[6];
    let x2536 = s[33] * k[5];
    let x2537 = x2535 + x2536;
    let x2546 = s[49] * k[7];
    let x2548 = x88 * k[8];
    let x2549 = x2548 - x2546;
    let x2551 = q[13] + s[283];
    let x2552 = q[14] + x2549;
    let x2556 = x2513 - x2551;
    let x2558 = x2514 - x2552;
    let x2559 = s[64] * x2519;
    let x2560 = x103 * x2522;
    let x2561 = x89 * x2526;
    let x2562 = x2559 + x2560;
    let x2563 = x2561 + x2562;
    let x2564 = s[64] * x2530;
    let x2565 = x103 * x2534;
    let x2566 = x89 * x2537;
    let x2567 = x2564 + x2565;
    let x2568 = x2566 + x2567;
    let x2572 = s[53] * k[10];
    let x2573 = s[63] * k[11];
    let x2574 = x2572 + x2573;
    let x2575 = s[54] * k[10];
    let x2576 = s[65] * k[11];
    let x2577 = x2575 + x2576;
    let x2578 = s[49] * k[10];
    let x2580 = x88 * k[11];
    let x2581 = x2580 - x2578;
    let x2582 = q[12] + x2574;
    let x2583 = q[13] + x2577;
    let x2584 = q[14] + x2581;
    let x2586 = k[9] - x2582;
    let x2587 = -x2583;
    let x2588 = -x2584;
    let x2601 = s[46] * k[4];
    let x2602 = s[34] * k[4];
    let x2603 = s[44] * k[6];
    let x2604 = s[46] * k[6];
    let x2605 = s[34] * k[6];
    let x2606 = s[44] * k[5];
    let x2607 = s[46] * k[5];
    let x2608 = s[34] * k[5];
    let x2609 = s[64] * x2603;
    let x2610 = x103 * x2604;
    let x2611 = x89 * x2605;
    let x2612 = x2609 + x2610;
    let x2613 = x2611 + x2612;
    let x2614 = s[64] * x2606;
    let x2615 = x103 * x2607;
    let x2616 = x89 * x2608;
    let x2617 = x2614 + x2615;
    let x2618 = x2616 + x2617;
    let x2626 = s[32] * k[3];
    let x2628 = x501 * k[4];
    let x2629 = x2628 - x2626;
    let x2630 = s[26] * k[3];
    let x2631 = x495 * k[4];
    let x2632 = x2630 + x2631;
    let x2633 = -x2632;
    let x2634 = s[31] * k[5];
    let x2636 = s[79] * k[6];
    let x2637 = x2636 - x2634;
    let x2638 = s[32] * k[5];
    let x2640 = x501 * k[6];
    let x2641 = x2640 - x2638;
    let x2642 = s[26] * k[5];
    let x2643 = x495 * k[6];
    let x2644 = x2642 + x2643;
    let x2645 = s[31] * k[6];
    let x2646 = s[79] * k[5];
    let x2647 = x2645 + x2646;
    let x2648 = s[32] * k[6];
    let x2649 = x501 * k[5];
    let x2650 = x2648 + x2649;
    let x2651 = s[26] * k[6];
    let x2652 = x495 * k[5];
    let x2654 = x2651 - x2652;
    let x2655 = s[64] * x2637;
    let x2656 = x103 * x2641;
    let x2657 = x89 * x2644;
    let x2659 = x2655 + x2656;
    let x2660 = x2659 - x2657;
    let x2661 = s[64] * x2647;
    let x2662 = x103 * x2650;
    let x2663 = x89 * x2654;
    let x2664 = x2661 + x2662;
    let x2665 = x2663 + x2664;
    let x2669 = x2531 - x2533;
    let x2670 = s[64] * x2522;
    let x2672 = x103 * x2519;
    let x2673 = x2672 - x2670;
    let x2674 = s[64] * x2669;
    let x2675 = x103 * x2530;
    let x2676 = x2674 + x2675;
    let x2678 = x103 * k[8];
    let x2679 = x89 * k[8];
    let x2681 = -x2678;
    let x2682 = -x2679;
    let x2683 = x603 * x2519;
    let x2684 = s[65] * x2522;
    let x2686 = x88 * x2526;
    let x2688 = x2683 - x2684;
    let x2689 = x2688 - x2686;
    let x2690 = x603 * x2530;
    let x2691 = s[65] * x2534;
    let x2693 = x88 * x2537;
    let x2695 = x2690 - x2691;
    let x2696 = x2695 - x2693;
    let x2697 = s[64] * k[11];
    let x2698 = x103 * k[11];
    let x2699 = x89 * k[11];
    let x2700 = -x2697;
    let x2701 = -x2698;
    let x2702 = -x2699;
    let x2707 = s[56] * k[7];
    let x2709 = x640 * k[8];
    let x2710 = x2709 - x2707;
    let x2711 = s[50] * k[7];
    let x2712 = x634 * k[8];
    let x2713 = x2711 + x2712;
    let x2715 = -x2710;
    let x2716 = x639 * x2519;
    let x2717 = x641 * x2522;
    let x2718 = x636 * x2526;
    let x2720 = x2716 + x2717;
    let x2721 = x2720 - x2718;
    let x2722 = x639 * x2530;
    let x2723 = x641 * x2534;
    let x2724 = x636 * x2537;
    let x2726 = x2722 + x2723;
    let x2727 = x2726 - x2724;
    let x2728 = s[55] * k[10];
    let x2730 = s[80] * k[11];
    let x2731 = x2730 - x2728;
    let x2732 = s[56] * k[10];
    let x2734 = x640 * k[11];
    let x2735 = x2734 - x2732;
    let x2736 = s[50] * k[10];
    let x2737 = x634 * k[11];
    let x2738 = x2736 + x2737;
    let x2739 = -x2731;
    let x2740 = -x2735;
    let x2741 = -s[280];
    let x2742 = x689 * x2519;
    let x2743 = x2670 + x2742;
    let x2744 = x689 * x2530;
    let x2745 = s[64] * x2534;
    let x2746 = x2744 + x2745;
    let x2747 = -x2574;
    let x2748 = x810 * k[5];
    let x2750 = x865 * k[6];
    let x2751 = x2750 - x2748;
    let x2752 = x815 * k[5];
    let x2753 = x867 * k[6];
    let x2754 = x2752 + x2753;
    let x2755 = s[115] * k[5];
    let x2757 = x826 * k[6];
    let x2758 = x2757 - x2755;
    let x2759 = x810 * k[6];
    let x2760 = x865 * k[5];
    let x2761 = x2759 + x2760;
    let x2762 = x815 * k[6];
    let x2764 = x867 * k[5];
    let x2765 = x2764 - x2762;
    let x2766 = s[115] * k[6];
    let x2767 = x826 * k[5];
    let x2768 = x2766 + x2767;
    let x2790 = s[211] * k[3];
    let x2792 = x1407 * k[4];
    let x2793 = x2792 - x2790;
    let x2794 = s[196] * k[3];
    let x2795 = x1324 * k[4];
    let x2797 = x2794 - x2795;
    let x2798 = s[205] * k[5];
    let x2800 = s[236] * k[6];
    let x2801 = x2800 - x2798;
    let x2802 = s[211] * k[5];
    let x2804 = x1407 * k[6];
    let x2805 = x2804 - x2802;
    let x2806 = s[196] * k[5];
    let x2807 = x1324 * k[6];
    let x2809 = x2806 - x2807;
    let x2810 = s[205] * k[6];
    let x2811 = s[236] * k[5];
    let x2812 = x2810 + x2811;
    let x2813 = s[211] * k[6];
    let x2814 = x1407 * k[5];
    let x2815 = x2813 + x2814;
    let x2816 = s[196] * k[6];
    let x2817 = x1324 * k[5];
    let x2818 = x2816 + x2817;
    let x2823 = x1434 * k[7];
    let x2825 = x1547 * k[8];
    let x2826 = x2825 - x2823;
    let x2827 = s[239] * k[7];
    let x2828 = x1464 * k[8];
    let x2830 = x2827 - x2828;
    let x2834 = x2793 - x2826;
    let x2836 = x2797 - x2830;
    let x2837 = x939 * x2751;
    let x2838 = x1546 * x2519;
    let x2839 = x2837 + x2838;
    let x2840 = s[64] * x2801;
    let x2841 = x2837 + x2840;
    let x2842 = x2839 + x2841;
    let x2843 = x942 * x2754;
    let x2844 = x1548 * x2522;
    let x2845 = x2843 + x2844;
    let x2846 = x103 * x2805;
    let x2847 = x2843 + x2846;
    let x2848 = x2845 + x2847;
    let x2849 = x904 * x2758;
    let x2850 = x1472 * x2526;
    let x2851 = x2849 + x2850;
    let x2854 = x89 * x2809;
    let x2855 = x2854 - x2849;
    let x2856 = x2855 - x2851;
    let x2857 = x2842 + x2848;
    let x2858 = x2856 + x2857;
    let x2859 = x939 * x2761;
    let x2860 = x1546 * x2530;
    let x2861 = x2859 + x2860;
    let x2862 = s[64] * x2812;
    let x2863 = x2859 + x2862;
    let x2864 = x2861 + x2863;
    let x2865 = x942 * x2765;
    let x2866 = x1548 * x2534;
    let x2867 = x2865 + x2866;
    let x2868 = x103 * x2815;
    let x2869 = x2865 + x2868;
    let x2870 = x2867 + x2869;
    let x2871 = x904 * x2768;
    let x2872 = x1472 * x2537;
    let x2873 = x2871 + x2872;
    let x2874 = x89 * x2818;
    let x2875 = x2871 + x2874;
    let x2876 = x2873 + x2875;
    let x2878 = x2864 + x2870;
    let x2879 = x2878 - x2876;
    let x2880 = s[248] * k[10];
    let x2882 = s[267] * k[11];
    let x2883 = x2882 - x2880;
    let x2884 = x1434 * k[10];
    let x2886 = x1547 * k[11];
    let x2887 = x2886 - x2884;
    let x2888 = s[239] * k[10];
    let x2889 = x1464 * k[11];
    let x2891 = x2888 - x2889;
    let x2896 = -x2834;
    let x2897 = -x2836;
    let x2898 = -x2858;
    let x2899 = -x2879;
    phi[11] = x2556;
    phi_q[50] = 1.0;
    phi_q[51] = x2601;
    phi_q[52] = x2629;
    phi_q[53] = s[274];
    phi_q[54] = -1.0;
    phi_q[55] = x2681;
    phi_q[56] = x2715;
    phi_q[57] = x2741;
    phi_t[11] = 0.0;
    gamma[11] = x2896;
    phi[12] = x2558;
    phi_q[58] = 1.0;
    phi_q[59] = x2602;
    phi_q[60] = x2633;
    phi_q[61] = -1.0;
    phi_q[62] = x2682;
    phi_q[63] = x2713;
    phi_t[12] = 0.0;
    gamma[12] = x2897;
    phi[13] = x2563;
    phi_q[64] = x2613;
    phi_q[65] = x2660;
    phi_q[66] = x2673;
    phi_q[67] = x2689;
    phi_q[68] = x2721;
    phi_q[69] = x2743;
    phi_t[13] = 0.0;
    gamma[13] = x2898;
    phi[14] = x2568;
    phi_q[70] = x2618;
    phi_q[71] = x2665;
    phi_q[72] = x2676;
    phi_q[73] = x2696;
    phi_q[74] = x2727;
    phi_q[75] = x2746;
    phi_t[14] = 0.0;
    gamma[14] = x2899;
    phi[15] = x2586;
    phi_q[76] = -1.0;
    phi_q[77] = x2700;
    phi_q[78] = x2739;
    phi_q[79] = x2577;
    phi_t[15] = 0.0;
    gamma[15] = x2883;
    phi[16] = x2587;
    phi_q[80] = -1.0;
    phi_q[81] = x2701;
    phi_q[82] = x2740;
    phi_q[83] = x2747;
    phi_t[16] = 0.0;
    gamma[16] = x2887;
    phi[17] = x2588;
    phi_q[84] = -1.0;
    phi_q[85] = x2702;
    phi_q[86] = x2738;
    phi_t[17] = 0.0;
    gamma[17] = x2891;
    phi[18] = s[64];
    phi_q[87] = x603;
    phi_q[88] = x639;
    phi_q[89] = x689;
    phi_t[18] = 0.0;
    gamma[18] = x1784;
    phi[19] = x103;
    phi_q[90] = x605;
    phi_q[91] = x641;
    phi_q[92] = s[64];
    phi_t[19] = 0.0;
    gamma[19] = x1785;
    phi[20] = x336;
}
#[inline(never)]
fn eval_kinematics_part_2(
    s: &[f64; 284],
    phi_q: &mut [f64; 96],
    phi_t: &mut [f64; 21],
    gamma: &mut [f64; 21],
) {
    let x363 = s[20] * s[70];
    let x365 = s[22] * s[71];
    let x367 = x365 - x363;
    let x425 = s[70] * s[75];
    let x427 = s[71] * s[77];
    let x429 = x427 - x425;
    let x448 = s[70] * s[78];
    let x449 = s[67] * s[71];
    let x451 = x448 - x449;
    let x703 = 6.283185307179586 * s[71];
    let x705 = 6.283185307179586 * s[70];
    let x707 = s[67] * x703;
    let x708 = s[69] * x705;
    let x710 = x707 + x708;
    let x1122 = 6.283185307179586 * x705;
    let x1124 = 6.283185307179586 * x703;
    let x1125 = x703 * s[135];
    let x1127 = s[67] * x1122;
    let x1129 = x1125 + x1127;
    let x1131 = x705 * s[137];
    let x1132 = s[69] * x1124;
    let x1133 = x1131 + x1132;
    let x1759 = s[70] * s[269];
    let x1760 = x1125 + x1759;
    let x1762 = x1129 + x1760;
    let x1765 = s[71] * s[271];
    let x1767 = x1131 + x1765;
    let x1769 = x1133 + x1767;
    let x1771 = x1769 - x1762;
    let x1786 = -x1771;
    phi_q[93] = x367;
    phi_q[94] = x429;
    phi_q[95] = x451;
    phi_t[20] = x710;
    gamma[20] = x1786;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
    let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = k;
    potential_into_part_0(q, out);
}
#[inline(never)]
fn potential_into_part_0(q: &[f64; 18], out: &mut [f64; 1]) {
    let x1819 = q[1] * 1.9620000000000002;
    let x1822 = q[7] * 4.905;
    let x1825 = q[13] * 3.9240000000000004;
    let x1826 = x1819 + x1822;
    let x1827 = x1825 + x1826;
    out[0] = x1827;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
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
pub const N_K: usize = 17;
/// `setup` at the file's parameter values: what the types without parameters read.
pub static K: [f64; 17] = [
    -0.05f64,
    0.05f64,
    -0.17499999999999996f64,
    0.175f64,
    0.000000000000000027755575615628914f64,
    0.8534911287233514f64,
    -0.5211073720362623f64,
    0.14999999999999997f64,
    0.000000000000000006938893903907228f64,
    0.4f64,
    -0.14999999999999997f64,
    0.00000000000000004163336342344337f64,
    0.0001f64,
    0.0001666666666666667f64,
    0.005104166666666666f64,
    0.0029999999999999996f64,
    0.0001f64,
];
/// The values the per-step functions read (`k`), from the run-time parameters `p`.
pub fn setup(p: &[f64], k: &mut [f64]) {
    let p: &[f64; 33] = p.try_into().expect("p must have 33 entries");
    let k: &mut [f64; 17] = k.try_into().expect("k must have 17 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 33], k: &mut [f64; 17]) {
    let x1803 = p[1] * 0.2;
    let x1804 = p[1] * x1803;
    let x1807 = x1804 * 0.08333333333333333;
    let x1809 = p[2] * 0.5;
    let x1810 = p[2] * x1809;
    let x1811 = 0.08333333333333333 * x1810;
    let x1813 = p[3] * 0.4;
    let x1814 = p[3] * x1813;
    let x1815 = 0.08333333333333333 * x1814;
    let x1890 = 2.0 * p[0];
    let x1891 = 0.5 * x1890;
    k[0] = p[15];
    k[1] = p[16];
    k[2] = p[17];
    k[3] = p[20];
    k[4] = p[21];
    k[5] = p[22];
    k[6] = p[23];
    k[7] = p[24];
    k[8] = p[25];
    k[9] = p[28];
    k[10] = p[29];
    k[11] = p[30];
    k[12] = p[0];
    k[13] = x1807;
    k[14] = x1811;
    k[15] = x1815;
    k[16] = x1891;
}
/// The parameters the generated code takes at run time by name: the file's
/// `[parameters]` entries that reach only masses, inertias and springs' constants.
pub static PARAMETERS: [&str; 1] = ["rod"];
/// Their values in the file.
pub static PARAMETER_VALUES: [f64; 1] = [0.0001f64];
/// Number of values `p` holds: the parameters by name, then the model's numbers that
/// the other parameters reach (read off the file loaded at their values: `DATA`).
pub const N_P: usize = 33;
/// `p` at the file's values.
pub static P0: [f64; 33] = [
    0.0001f64,
    0.1f64,
    0.35f64,
    0.3f64,
    0.4f64,
    0.0001f64,
    0.0001f64,
    0.00016666666666666672f64,
    0.00016666666666666672f64,
    0.0001f64,
    0.005104166666666666f64,
    0.005104166666666666f64,
    0.0001f64,
    0.0029999999999999996f64,
    0.0029999999999999996f64,
    -0.05f64,
    0.05f64,
    -0.17499999999999996f64,
    0.8534911287233514f64,
    -0.5211073720362623f64,
    0.175f64,
    0.000000000000000027755575615628914f64,
    0.8534911287233514f64,
    -0.5211073720362623f64,
    0.14999999999999997f64,
    0.000000000000000006938893903907228f64,
    -0.3375936831560903f64,
    -0.9412919340423062f64,
    0.4f64,
    -0.14999999999999997f64,
    0.00000000000000004163336342344337f64,
    -0.3375936831560903f64,
    -0.9412919340423062f64,
];
/// Where the numbers after the named parameters come from in the model (positions in
/// the generator's `slots::numbers`).
pub static DATA: [u32; 32] = [
    3u32, 4u32, 5u32, 6u32, 7u32, 9u32, 10u32, 11u32, 13u32, 14u32, 15u32, 17u32, 18u32,
    19u32, 29u32, 38u32, 47u32, 50u32, 51u32, 56u32, 57u32, 59u32, 60u32, 65u32, 66u32,
    68u32, 69u32, 74u32, 83u32, 84u32, 86u32, 87u32,
];
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
    let p: &[f64; 33] = p.try_into().expect("p must have 33 entries");
    let out: &mut [f64; 12] = out.try_into().expect("out must have 12 entries");
    mass_properties_part_0(p, out);
}
#[inline(never)]
fn mass_properties_part_0(p: &[f64; 33], out: &mut [f64; 12]) {
    let x1803 = p[1] * 0.2;
    let x1804 = p[1] * x1803;
    let x1807 = x1804 * 0.08333333333333333;
    let x1809 = p[2] * 0.5;
    let x1810 = p[2] * x1809;
    let x1811 = 0.08333333333333333 * x1810;
    let x1813 = p[3] * 0.4;
    let x1814 = p[3] * x1813;
    let x1815 = 0.08333333333333333 * x1814;
    out[0] = 0.2;
    out[1] = p[0];
    out[2] = x1807;
    out[3] = x1807;
    out[4] = 0.5;
    out[5] = p[0];
    out[6] = x1811;
    out[7] = x1811;
    out[8] = 0.4;
    out[9] = p[0];
    out[10] = x1815;
    out[11] = x1815;
}
/// Each force's stiffness and damping at the run-time parameters `p`.
pub fn force_constants(p: &[f64], out: &mut [f64]) {
    let p: &[f64; 33] = p.try_into().expect("p must have 33 entries");
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
        let (mut props, mut constants) = ([0.0; 12], [0.0; 0]);
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
        let (mut props, mut constants) = ([0.0; 12], [0.0; 0]);
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
        let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
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
        let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
        let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 30] = out.try_into().expect("out must have 30 entries");
        mass_part_0(k, q, out);
    }
    #[inline(never)]
    fn mass_part_0(k: &[f64; 17], q: &[f64; 18], out: &mut [f64; 30]) {
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
        let x1892 = 2.0 * x14;
        let x1898 = 2.0 * x13;
        let x1899 = 2.0 * x12;
        let x1901 = x13 * x1898;
        let x1903 = x12 * x1899;
        let x1909 = 2.0 * x22;
        let x1910 = 2.0 * x23;
        let x1911 = x13 * x1909;
        let x1913 = x12 * x1910;
        let x1918 = x22 * x1898;
        let x1920 = x23 * x1899;
        let x1926 = x14 * x1892;
        let x1930 = x22 * x1909;
        let x1932 = x23 * x1910;
        let x2108 = 2.0 * x47;
        let x2114 = 2.0 * x46;
        let x2115 = 2.0 * x45;
        let x2117 = x46 * x2114;
        let x2119 = x45 * x2115;
        let x2125 = 2.0 * x55;
        let x2126 = 2.0 * x56;
        let x2127 = x46 * x2125;
        let x2129 = x45 * x2126;
        let x2134 = x55 * x2114;
        let x2136 = x56 * x2115;
        let x2142 = x47 * x2108;
        let x2146 = x55 * x2125;
        let x2148 = x56 * x2126;
        let x2319 = 2.0 * x80;
        let x2325 = 2.0 * x79;
        let x2326 = 2.0 * x78;
        let x2328 = x79 * x2325;
        let x2330 = x78 * x2326;
        let x2336 = 2.0 * x88;
        let x2337 = 2.0 * x89;
        let x2338 = x79 * x2336;
        let x2340 = x78 * x2337;
        let x2345 = x88 * x2325;
        let x2347 = x89 * x2326;
        let x2353 = x80 * x2319;
        let x2357 = x88 * x2336;
        let x2359 = x89 * x2337;
        let x2905 = x1892 * k[12];
        let x2906 = 0.5 * x2905;
        let x2907 = -x2906;
        let x2908 = x1901 * k[13];
        let x2909 = x1903 * k[13];
        let x2910 = x2908 + x2909;
        let x2911 = 0.5 * x2910;
        let x2912 = x1911 * k[13];
        let x2913 = x1913 * k[13];
        let x2915 = x2912 - x2913;
        let x2916 = 0.5 * x2915;
        let x2917 = x1918 * k[13];
        let x2918 = x1920 * k[13];
        let x2920 = x2917 - x2918;
        let x2921 = 0.5 * x2920;
        let x2922 = x1926 * k[12];
        let x2923 = x1930 * k[13];
        let x2924 = x1932 * k[13];
        let x2925 = x2922 + x2923;
        let x2926 = x2924 + x2925;
        let x2927 = 0.5 * x2926;
        let x2958 = x2108 * k[12];
        let x2959 = 0.5 * x2958;
        let x2960 = -x2959;
        let x2961 = x2117 * k[14];
        let x2962 = x2119 * k[14];
        let x2963 = x2961 + x2962;
        let x2964 = 0.5 * x2963;
        let x2965 = x2127 * k[14];
        let x2966 = x2129 * k[14];
        let x2968 = x2965 - x2966;
        let x2969 = 0.5 * x2968;
        let x2970 = x2134 * k[14];
        let x2971 = x2136 * k[14];
        let x2973 = x2970 - x2971;
        let x2974 = 0.5 * x2973;
        let x2975 = x2142 * k[12];
        let x2976 = x2146 * k[14];
        let x2977 = x2148 * k[14];
        let x2978 = x2975 + x2976;
        let x2979 = x2977 + x2978;
        let x2980 = 0.5 * x2979;
        let x3011 = x2319 * k[12];
        let x3012 = 0.5 * x3011;
        let x3013 = -x3012;
        let x3014 = x2328 * k[15];
        let x3015 = x2330 * k[15];
        let x3016 = x3014 + x3015;
        let x3017 = 0.5 * x3016;
        let x3018 = x2338 * k[15];
        let x3019 = x2340 * k[15];
        let x3021 = x3018 - x3019;
        let x3022 = 0.5 * x3021;
        let x3023 = x2345 * k[15];
        let x3024 = x2347 * k[15];
        let x3026 = x3023 - x3024;
        let x3027 = 0.5 * x3026;
        let x3028 = x2353 * k[12];
        let x3029 = x2357 * k[15];
        let x3030 = x2359 * k[15];
        let x3031 = x3028 + x3029;
        let x3032 = x3030 + x3031;
        let x3033 = 0.5 * x3032;
        out[0] = 0.2;
        out[1] = 0.2;
        out[2] = 0.2;
        out[3] = k[16];
        out[4] = x2907;
        out[5] = x2911;
        out[6] = x2916;
        out[7] = x2907;
        out[8] = x2921;
        out[9] = x2927;
        out[10] = 0.5;
        out[11] = 0.5;
        out[12] = 0.5;
        out[13] = k[16];
        out[14] = x2960;
        out[15] = x2964;
        out[16] = x2969;
        out[17] = x2960;
        out[18] = x2974;
        out[19] = x2980;
        out[20] = 0.4;
        out[21] = 0.4;
        out[22] = 0.4;
        out[23] = k[16];
        out[24] = x3013;
        out[25] = x3017;
        out[26] = x3022;
        out[27] = x3013;
        out[28] = x3027;
        out[29] = x3033;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 17] = k.try_into().expect("k must have 17 entries");
        let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 18] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 18] = out.try_into().expect("out must have 18 entries");
        let _ = t;
        force_part_0(k, q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(k: &[f64; 17], q: &[f64; 18], qd: &[f64; 18], out: &mut [f64; 18]) {
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
        let x729 = x13 * qd[3];
        let x730 = x12 * qd[3];
        let x732 = x15 * qd[4];
        let x733 = x14 * qd[4];
        let x755 = x15 * x729;
        let x756 = x12 * x733;
        let x758 = x755 - x756;
        let x797 = x46 * qd[9];
        let x798 = x45 * qd[9];
        let x800 = x48 * qd[10];
        let x801 = x47 * qd[10];
        let x823 = x48 * x797;
        let x824 = x45 * x801;
        let x826 = x823 - x824;
        let x827 = x48 * x798;
        let x829 = x46 * x801;
        let x831 = x827 + x829;
        let x870 = x79 * qd[15];
        let x871 = x78 * qd[15];
        let x873 = x81 * qd[16];
        let x874 = x80 * qd[16];
        let x896 = x81 * x870;
        let x897 = x78 * x874;
        let x899 = x896 - x897;
        let x900 = x81 * x871;
        let x902 = x79 * x874;
        let x904 = x900 + x902;
        let x1828 = x14 * qd[5];
        let x1830 = x15 * qd[5];
        let x1831 = x13 * qd[4];
        let x1832 = x12 * x1830;
        let x1833 = x1831 + x1832;
        let x1834 = x12 * qd[4];
        let x1835 = x13 * x1830;
        let x1837 = x1835 - x1834;
        let x1838 = qd[3] - x1828;
        let x1859 = 2.0 * x1838;
        let x1861 = 2.0 * x1833;
        let x1863 = 2.0 * x1837;
        let x1937 = x15 * x730;
        let x1939 = x13 * x733;
        let x1941 = x1937 + x1939;
        let x1943 = qd[5] * x732;
        let x1945 = qd[5] * x733;
        let x1947 = qd[4] * x730;
        let x1949 = x729 * x1830;
        let x1950 = x12 * x1945;
        let x1952 = x1949 - x1950;
        let x1953 = x1952 - x1947;
        let x1954 = qd[4] * x729;
        let x1955 = x730 * x1830;
        let x1957 = x13 * x1945;
        let x1959 = x1955 + x1957;
        let x1962 = x1954 + x1959;
        let x1964 = 2.0 * x1943;
        let x1966 = 2.0 * x1953;
        let x1967 = 2.0 * x1962;
        let x1973 = x730 * x1861;
        let x1975 = x13 * x1966;
        let x1976 = x1975 - x1973;
        let x1978 = x729 * x1863;
        let x1979 = x12 * x1967;
        let x1981 = x1978 - x1979;
        let x1986 = x732 * x1859;
        let x1987 = x14 * x1964;
        let x1989 = x1986 - x1987;
        let x1992 = x758 * x1861;
        let x1993 = x22 * x1966;
        let x1994 = x1992 + x1993;
        let x1996 = x1863 * x1941;
        let x1998 = x23 * x1967;
        let x2000 = x1996 + x1998;
        let x2010 = x1837 * x1861;
        let x2012 = x1833 * x1863;
        let x2020 = x12 * x1828;
        let x2022 = x13 * x1828;
        let x2024 = x1830 * x1859;
        let x2028 = x1861 * x2020;
        let x2032 = x1863 * x2022;
        let x2046 = x47 * qd[11];
        let x2048 = x48 * qd[11];
        let x2049 = x46 * qd[10];
        let x2050 = x45 * x2048;
        let x2051 = x2049 + x2050;
        let x2052 = x45 * qd[10];
        let x2053 = x46 * x2048;
        let x2055 = x2053 - x2052;
        let x2056 = qd[9] - x2046;
        let x2077 = 2.0 * x2056;
        let x2079 = 2.0 * x2051;
        let x2081 = 2.0 * x2055;
        let x2153 = qd[11] * x800;
        let x2155 = qd[11] * x801;
        let x2157 = qd[10] * x798;
        let x2159 = x797 * x2048;
        let x2160 = x45 * x2155;
        let x2162 = x2159 - x2160;
        let x2163 = x2162 - x2157;
        let x2164 = qd[10] * x797;
        let x2165 = x798 * x2048;
        let x2167 = x46 * x2155;
        let x2169 = x2165 + x2167;
        let x2172 = x2164 + x2169;
        let x2174 = 2.0 * x2153;
        let x2176 = 2.0 * x2163;
        let x2177 = 2.0 * x2172;
        let x2183 = x798 * x2079;
        let x2185 = x46 * x2176;
        let x2186 = x2185 - x2183;
        let x2188 = x797 * x2081;
        let x2189 = x45 * x2177;
        let x2191 = x2188 - x2189;
        let x2196 = x800 * x2077;
        let x2197 = x47 * x2174;
        let x2199 = x2196 - x2197;
        let x2202 = x826 * x2079;
        let x2203 = x55 * x2176;
        let x2204 = x2202 + x2203;
        let x2206 = x831 * x2081;
        let x2208 = x56 * x2177;
        let x2210 = x2206 + x2208;
        let x2220 = x2055 * x2079;
        let x2222 = x2051 * x2081;
        let x2230 = x45 * x2046;
        let x2232 = x46 * x2046;
        let x2234 = x2048 * x2077;
        let x2238 = x2079 * x2230;
        let x2242 = x2081 * x2232;
        let x2256 = x80 * qd[17];
        let x2258 = x81 * qd[17];
        let x2259 = x79 * qd[16];
        let x2260 = x78 * x2258;
        let x2261 = x2259 + x2260;
        let x2262 = x78 * qd[16];
        let x2263 = x79 * x2258;
        let x2265 = x2263 - x2262;
        let x2266 = qd[15] - x2256;
        let x2287 = 2.0 * x2266;
        let x2289 = 2.0 * x2261;
        let x2291 = 2.0 * x2265;
        let x2364 = qd[17] * x873;
        let x2366 = qd[17] * x874;
        let x2368 = qd[16] * x871;
        let x2370 = x870 * x2258;
        let x2371 = x78 * x2366;
        let x2373 = x2370 - x2371;
        let x2374 = x2373 - x2368;
        let x2375 = qd[16] * x870;
        let x2376 = x871 * x2258;
        let x2378 = x79 * x2366;
        let x2380 = x2376 + x2378;
        let x2383 = x2375 + x2380;
        let x2385 = 2.0 * x2364;
        let x2387 = 2.0 * x2374;
        let x2388 = 2.0 * x2383;
        let x2394 = x871 * x2289;
        let x2396 = x79 * x2387;
        let x2397 = x2396 - x2394;
        let x2399 = x870 * x2291;
        let x2400 = x78 * x2388;
        let x2402 = x2399 - x2400;
        let x2407 = x873 * x2287;
        let x2408 = x80 * x2385;
        let x2410 = x2407 - x2408;
        let x2413 = x899 * x2289;
        let x2414 = x88 * x2387;
        let x2415 = x2413 + x2414;
        let x2417 = x904 * x2291;
        let x2419 = x89 * x2388;
        let x2421 = x2417 + x2419;
        let x2431 = x2265 * x2289;
        let x2433 = x2261 * x2291;
        let x2441 = x78 * x2256;
        let x2443 = x79 * x2256;
        let x2445 = x2258 * x2287;
        let x2449 = x2289 * x2441;
        let x2453 = x2291 * x2443;
        let x2928 = x1964 * k[12];
        let x2929 = 0.5 * x2928;
        let x2930 = x1976 * k[13];
        let x2931 = x1981 * k[13];
        let x2933 = x2930 - x2931;
        let x2934 = 0.5 * x2933;
        let x2935 = x1989 * k[12];
        let x2937 = x1994 * k[13];
        let x2938 = x2000 * k[13];
        let x2940 = x2937 - x2935;
        let x2941 = x2940 - x2938;
        let x2942 = 0.5 * x2941;
        let x2943 = x2010 * k[13];
        let x2944 = x2012 * k[13];
        let x2946 = x2943 - x2944;
        let x2947 = 0.5 * x2946;
        let x2948 = x2929 + x2947;
        let x2949 = x2024 * k[12];
        let x2950 = x2028 * k[13];
        let x2951 = x2032 * k[13];
        let x2952 = x2949 + x2950;
        let x2953 = x2951 + x2952;
        let x2954 = 0.5 * x2953;
        let x2955 = x2934 + x2954;
        let x2956 = -x2955;
        let x2957 = -x2942;
        let x2981 = x2174 * k[12];
        let x2982 = 0.5 * x2981;
        let x2983 = x2186 * k[14];
        let x2984 = x2191 * k[14];
        let x2986 = x2983 - x2984;
        let x2987 = 0.5 * x2986;
        let x2988 = x2199 * k[12];
        let x2990 = x2204 * k[14];
        let x2991 = x2210 * k[14];
        let x2993 = x2990 - x2988;
        let x2994 = x2993 - x2991;
        let x2995 = 0.5 * x2994;
        let x2996 = x2220 * k[14];
        let x2997 = x2222 * k[14];
        let x2999 = x2996 - x2997;
        let x3000 = 0.5 * x2999;
        let x3001 = x2982 + x3000;
        let x3002 = x2234 * k[12];
        let x3003 = x2238 * k[14];
        let x3004 = x2242 * k[14];
        let x3005 = x3002 + x3003;
        let x3006 = x3004 + x3005;
        let x3007 = 0.5 * x3006;
        let x3008 = x2987 + x3007;
        let x3009 = -x3008;
        let x3010 = -x2995;
        let x3034 = x2385 * k[12];
        let x3035 = 0.5 * x3034;
        let x3036 = x2397 * k[15];
        let x3037 = x2402 * k[15];
        let x3039 = x3036 - x3037;
        let x3040 = 0.5 * x3039;
        let x3041 = x2410 * k[12];
        let x3043 = x2415 * k[15];
        let x3044 = x2421 * k[15];
        let x3046 = x3043 - x3041;
        let x3047 = x3046 - x3044;
        let x3048 = 0.5 * x3047;
        let x3049 = x2431 * k[15];
        let x3050 = x2433 * k[15];
        let x3052 = x3049 - x3050;
        let x3053 = 0.5 * x3052;
        let x3054 = x3035 + x3053;
        let x3055 = x2445 * k[12];
        let x3056 = x2449 * k[15];
        let x3057 = x2453 * k[15];
        let x3058 = x3055 + x3056;
        let x3059 = x3057 + x3058;
        let x3060 = 0.5 * x3059;
        let x3061 = x3040 + x3060;
        let x3062 = -x3061;
        let x3063 = -x3048;
        out[0] = 0.0;
        out[1] = -1.9620000000000002;
        out[2] = 0.0;
        out[3] = x2948;
        out[4] = x2956;
        out[5] = x2957;
        out[6] = 0.0;
        out[7] = -4.905;
        out[8] = 0.0;
        out[9] = x3001;
        out[10] = x3009;
        out[11] = x3010;
        out[12] = 0.0;
        out[13] = -3.9240000000000004;
        out[14] = 0.0;
        out[15] = x3054;
        out[16] = x3062;
        out[17] = x3063;
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
        _k: &[f64; 17],
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
        let x732 = x15 * qd[4];
        s[18] = x732;
        let x1830 = x15 * qd[5];
        s[19] = x1830;
        let x1831 = x13 * qd[4];
        s[20] = x1831;
        let x1832 = x12 * x1830;
        s[21] = x1832;
        let x1833 = x1831 + x1832;
        s[22] = x1833;
        let x1834 = x12 * qd[4];
        s[23] = x1834;
        let x1835 = x13 * x1830;
        s[24] = x1835;
        let x1837 = x1835 - x1834;
        s[25] = x1837;
        let x1861 = 2.0 * x1833;
        s[26] = x1861;
        let x1863 = 2.0 * x1837;
        s[27] = x1863;
        let x1943 = qd[5] * x732;
        s[28] = x1943;
        let x1964 = 2.0 * x1943;
        s[29] = x1964;
    }
    #[inline(never)]
    fn eval_newton_part_0(
        k: &[f64; 17],
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
        let x116 = x18 * 0.00000000000000006123233995736766;
        let x118 = x116 - x33;
        let x119 = x19 * 0.00000000000000006123233995736766;
        let x120 = -x35;
        let x121 = x119 - x35;
        let x122 = s[2] * 0.00000000000000006123233995736766;
        let x125 = s[4] + x122;
        let x127 = x33 * 0.00000000000000006123233995736766;
        let x128 = x18 + x127;
        let x129 = x35 * 0.00000000000000006123233995736766;
        let x130 = x19 + x129;
        let x131 = s[4] * 0.00000000000000006123233995736766;
        let x132 = x131 - s[2];
        let x182 = x67 * x118;
        let x183 = x70 * x121;
        let x184 = s[11] * x125;
        let x186 = x182 + x183;
        let x187 = x186 - x184;
        let x188 = x67 * x128;
        let x189 = x70 * x130;
        let x190 = s[11] * x132;
        let x191 = x188 + x189;
        let x192 = x190 + x191;
        let x331 = x5.sin();
        let x332 = x5.cos();
        let x333 = x118 * x331;
        let x334 = x121 * x332;
        let x336 = x333 - x334;
        let x341 = x25 - x24;
        let x345 = x34 * 0.00000000000000006123233995736766;
        let x346 = x37 * 0.00000000000000006123233995736766;
        let x347 = s[5] * 0.00000000000000006123233995736766;
        let x348 = x34 * x67;
        let x350 = x37 * x70;
        let x352 = s[5] * s[11];
        let x354 = x348 + x350;
        let x356 = x352 + x354;
        let x357 = -x356;
        let x358 = x67 * x345;
        let x359 = x70 * x346;
        let x360 = s[11] * x347;
        let x361 = x358 + x359;
        let x362 = x360 + x361;
        let x363 = x34 * x331;
        let x365 = x37 * x332;
        let x367 = x365 - x363;
        let x370 = s[0] * s[2];
        let x372 = s[0] * x18;
        let x373 = s[1] * x18;
        let x374 = s[0] * x19;
        let x375 = s[1] * x19;
        let x383 = x20 * 0.00000000000000006123233995736766;
        let x386 = x372 + x383;
        let x388 = x21 * 0.00000000000000006123233995736766;
        let x391 = x374 + x388;
        let x393 = s[3] * 0.00000000000000006123233995736766;
        let x394 = x393 - x370;
        let x395 = 0.00000000000000006123233995736766 * x372;
        let x396 = x395 - x20;
        let x397 = 0.00000000000000006123233995736766 * x374;
        let x398 = x397 - x21;
        let x399 = 0.00000000000000006123233995736766 * x370;
        let x401 = s[3] + x399;
        let x409 = x67 * x386;
        let x411 = x70 * x391;
        let x413 = s[11] * x394;
        let x415 = x409 + x411;
        let x417 = x413 + x415;
        let x418 = -x417;
        let x419 = x67 * x396;
        let x420 = x70 * x398;
        let x421 = s[11] * x401;
        let x423 = x419 + x420;
        let x424 = x423 - x421;
        let x425 = x331 * x386;
        let x427 = x332 * x391;
        let x429 = x427 - x425;
        let x433 = x31 - x30;
        let x436 = x35 - x119;
        let x441 = x67 * x436;
        let x442 = x70 * x118;
        let x443 = x441 + x442;
        let x444 = x67 * x130;
        let x446 = x70 * x128;
        let x447 = x446 - x444;
        let x448 = x331 * x436;
        let x449 = x118 * x332;
        let x451 = x448 - x449;
        let x457 = x58 - x57;
        let x460 = x118 * x457;
        let x461 = x68 * x121;
        let x463 = s[10] * x125;
        let x465 = x460 - x461;
        let x466 = x463 + x465;
        let x467 = x128 * x457;
        let x468 = x68 * x130;
        let x470 = s[10] * x132;
        let x472 = x467 - x468;
        let x473 = x472 - x470;
        let x495 = s[6] * s[8];
        let x497 = s[7] * s[8];
        let x499 = s[6] * x51;
        let x500 = s[7] * x51;
        let x501 = s[6] * x52;
        let x502 = s[7] * x52;
        let x509 = x118 * x500;
        let x510 = x121 * x502;
        let x511 = x125 * x497;
        let x513 = x509 + x510;
        let x514 = x511 + x513;
        let x515 = x128 * x500;
        let x516 = x130 * x502;
        let x517 = x132 * x497;
        let x519 = x515 + x516;
        let x520 = x519 - x517;
        let x575 = x64 - x63;
        let x578 = x118 * x575;
        let x579 = x67 * x121;
        let x580 = x578 + x579;
        let x581 = x128 * x575;
        let x582 = x444 + x581;
        let x603 = x91 - x90;
        let x605 = -x101;
        let x634 = s[12] * s[14];
        let x636 = s[13] * s[14];
        let x638 = s[12] * x84;
        let x639 = s[13] * x84;
        let x640 = s[12] * x85;
        let x641 = s[13] * x85;
        let x689 = x97 - x96;
        let x1892 = 2.0 * s[2];
        let x1898 = 2.0 * s[1];
        let x1899 = 2.0 * s[0];
        let x1901 = s[1] * x1898;
        let x1903 = s[0] * x1899;
        let x1909 = 2.0 * s[4];
        let x1910 = 2.0 * s[5];
        let x1911 = s[1] * x1909;
        let x1913 = s[0] * x1910;
        let x1918 = s[4] * x1898;
        let x1920 = s[5] * x1899;
        let x1926 = s[2] * x1892;
        let x1930 = s[4] * x1909;
        let x1932 = s[5] * x1910;
        let x2010 = s[25] * s[26];
        let x2012 = s[22] * s[27];
        let x2108 = 2.0 * s[8];
        let x2114 = 2.0 * s[7];
        let x2115 = 2.0 * s[6];
        let x2117 = s[7] * x2114;
        let x2119 = s[6] * x2115;
        let x2125 = 2.0 * s[10];
        let x2126 = 2.0 * s[11];
        let x2127 = s[7] * x2125;
        let x2129 = s[6] * x2126;
        let x2134 = s[10] * x2114;
        let x2136 = s[11] * x2115;
        let x2142 = s[8] * x2108;
        let x2146 = s[10] * x2125;
        let x2148 = s[11] * x2126;
        let x2319 = 2.0 * s[14];
        let x2325 = 2.0 * s[13];
        let x2326 = 2.0 * s[12];
        let x2328 = s[13] * x2325;
        let x2330 = s[12] * x2326;
        let x2336 = 2.0 * s[16];
        let x2337 = 2.0 * s[17];
        let x2338 = s[13] * x2336;
        let x2340 = s[12] * x2337;
        let x2345 = s[16] * x2325;
        let x2347 = s[17] * x2326;
        let x2353 = s[14] * x2319;
        let x2357 = s[16] * x2336;
        let x2359 = s[17] * x2337;
        let x2468 = x18 * k[0];
        let x2469 = x19 * k[0];
        let x2470 = s[2] * k[0];
        let x2472 = q[0] + x2468;
        let x2473 = q[1] + x2469;
        let x2474 = q[2] - x2470;
        let x2475 = -x2472;
        let x2476 = -x2473;
        let x2477 = -x2474;
        let x2479 = x18 * k[1];
        let x2480 = x19 * k[1];
        let x2481 = s[2] * k[1];
        let x2483 = q[0] + x2479;
        let x2484 = q[1] + x2480;
        let x2485 = q[2] - x2481;
        let x2487 = x51 * k[2];
        let x2488 = x52 * k[2];
        let x2489 = s[8] * k[2];
        let x2491 = q[6] + x2487;
        let x2492 = q[7] + x2488;
        let x2493 = q[8] - x2489;
        let x2495 = x2483 - x2491;
        let x2497 = x2484 - x2492;
        let x2499 = x2485 - x2493;
        let x2502 = x51 * k[3];
        let x2503 = x66 * k[4];
        let x2504 = x2502 + x2503;
        let x2505 = x52 * k[3];
        let x2506 = x68 * k[4];
        let x2507 = x2505 + x2506;
        let x2508 = s[8] * k[3];
        let x2510 = s[10] * k[4];
        let x2511 = x2510 - x2508;
        let x2512 = q[6] + x2504;
        let x2513 = q[7] + x2507;
        let x2514 = q[8] + x2511;
        let x2517 = x51 * k[5];
        let x2518 = x66 * k[6];
        let x2519 = x2517 + x2518;
        let x2520 = x52 * k[5];
        let x2521 = x68 * k[6];
        let x2522 = x2520 + x2521;
        let x2523 = s[8] * k[5];
        let x2525 = s[10] * k[6];
        let x2526 = x2525 - x2523;
        let x2527 = x51 * k[6];
        let x2529 = x66 * k[5];
        let x2530 = x2529 - x2527;
        let x2531 = x52 * k[6];
        let x2533 = x68 * k[5];
        let x2534 = x2533 - x2531;
        let x2535 = s[8] * k[6];
        let x2536 = s[10] * k[5];
        let x2537 = x2535 + x2536;
        let x2540 = x84 * k[7];
        let x2541 = x99 * k[8];
        let x2542 = x2540 + x2541;
        let x2543 = x85 * k[7];
        let x2544 = x101 * k[8];
        let x2545 = x2543 + x2544;
        let x2546 = s[14] * k[7];
        let x2548 = s[16] * k[8];
        let x2549 = x2548 - x2546;
        let x2550 = q[12] + x2542;
        let x2551 = q[13] + x2545;
        let x2552 = q[14] + x2549;
        let x2554 = x2512 - x2550;
        let x2556 = x2513 - x2551;
        let x2558 = x2514 - x2552;
        let x2559 = x100 * x2519;
        let x2560 = x103 * x2522;
        let x2561 = s[17] * x2526;
        let x2562 = x2559 + x2560;
        let x2563 = x2561 + x2562;
        let x2564 = x100 * x2530;
        let x2565 = x103 * x2534;
        let x2566 = s[17] * x2537;
        let x2567 = x2564 + x2565;
        let x2568 = x2566 + x2567;
        let x2572 = x84 * k[10];
        let x2573 = x99 * k[11];
        let x2574 = x2572 + x2573;
        let x2575 = x85 * k[10];
        let x2576 = x101 * k[11];
        let x2577 = x2575 + x2576;
        let x2578 = s[14] * k[10];
        let x2580 = s[16] * k[11];
        let x2581 = x2580 - x2578;
        let x2582 = q[12] + x2574;
        let x2583 = q[13] + x2577;
        let x2584 = q[14] + x2581;
        let x2586 = k[9] - x2582;
        let x2587 = -x2583;
        let x2588 = -x2584;
        let x2589 = x20 * k[0];
        let x2590 = x21 * k[0];
        let x2591 = s[3] * k[0];
        let x2592 = x20 * k[1];
        let x2593 = -x2592;
        let x2594 = x21 * k[1];
        let x2595 = -x2594;
        let x2596 = s[3] * k[1];
        let x2597 = -x2596;
        let x2598 = -x2468;
        let x2599 = -x2480;
        let x2600 = x67 * k[4];
        let x2601 = x70 * k[4];
        let x2602 = s[11] * k[4];
        let x2603 = x67 * k[6];
        let x2604 = x70 * k[6];
        let x2605 = s[11] * k[6];
        let x2606 = x67 * k[5];
        let x2607 = x70 * k[5];
        let x2608 = s[11] * k[5];
        let x2609 = x100 * x2603;
        let x2610 = x103 * x2604;
        let x2611 = s[17] * x2605;
        let x2612 = x2609 + x2610;
        let x2613 = x2611 + x2612;
        let x2614 = x100 * x2606;
        let x2615 = x103 * x2607;
        let x2616 = s[17] * x2608;
        let x2617 = x2614 + x2615;
        let x2618 = x2616 + x2617;
        let x2619 = x53 * k[2];
        let x2620 = x54 * k[2];
        let x2621 = s[9] * k[2];
        let x2622 = x53 * k[3];
        let x2624 = x499 * k[4];
        let x2625 = x2624 - x2622;
        let x2626 = x54 * k[3];
        let x2628 = x501 * k[4];
        let x2629 = x2628 - x2626;
        let x2630 = s[9] * k[3];
        let x2631 = x495 * k[4];
        let x2632 = x2630 + x2631;
        let x2633 = -x2632;
        let x2634 = x53 * k[5];
        let x2636 = x499 * k[6];
        let x2637 = x2636 - x2634;
        let x2638 = x54 * k[5];
        let x2640 = x501 * k[6];
        let x2641 = x2640 - x2638;
        let x2642 = s[9] * k[5];
        let x2643 = x495 * k[6];
        let x2644 = x2642 + x2643;
        let x2645 = x53 * k[6];
        let x2646 = x499 * k[5];
        let x2647 = x2645 + x2646;
        let x2648 = x54 * k[6];
        let x2649 = x501 * k[5];
        let x2650 = x2648 + x2649;
        let x2651 = s[9] * k[6];
        let x2652 = x495 * k[5];
        let x2654 = x2651 - x2652;
        let x2655 = x100 * x2637;
        let x2656 = x103 * x2641;
        let x2657 = s[17] * x2644;
        let x2659 = x2655 + x2656;
        let x2660 = x2659 - x2657;
        let x2661 = x100 * x2647;
        let x2662 = x103 * x2650;
        let x2663 = s[17] * x2654;
        let x2664 = x2661 + x2662;
        let x2665 = x2663 + x2664;
        let x2666 = -x2487;
        let x2667 = -x2507;
        let x2669 = x2531 - x2533;
        let x2670 = x100 * x2522;
        let x2672 = x103 * x2519;
        let x2673 = x2672 - x2670;
        let x2674 = x100 * x2669;
        let x2675 = x103 * x2530;
        let x2676 = x2674 + x2675;
        let x2677 = x100 * k[8];
        let x2678 = x103 * k[8];
        let x2679 = s[17] * k[8];
        let x2680 = -x2677;
        let x2681 = -x2678;
        let x2682 = -x2679;
        let x2683 = x603 * x2519;
        let x2684 = x101 * x2522;
        let x2686 = s[16] * x2526;
        let x2688 = x2683 - x2684;
        let x2689 = x2688 - x2686;
        let x2690 = x603 * x2530;
        let x2691 = x101 * x2534;
        let x2693 = s[16] * x2537;
        let x2695 = x2690 - x2691;
        let x2696 = x2695 - x2693;
        let x2697 = x100 * k[11];
        let x2698 = x103 * k[11];
        let x2699 = s[17] * k[11];
        let x2700 = -x2697;
        let x2701 = -x2698;
        let x2702 = -x2699;
        let x2703 = x86 * k[7];
        let x2705 = x638 * k[8];
        let x2706 = x2705 - x2703;
        let x2707 = x87 * k[7];
        let x2709 = x640 * k[8];
        let x2710 = x2709 - x2707;
        let x2711 = s[15] * k[7];
        let x2712 = x634 * k[8];
        let x2713 = x2711 + x2712;
        let x2714 = -x2706;
        let x2715 = -x2710;
        let x2716 = x639 * x2519;
        let x2717 = x641 * x2522;
        let x2718 = x636 * x2526;
        let x2720 = x2716 + x2717;
        let x2721 = x2720 - x2718;
        let x2722 = x639 * x2530;
        let x2723 = x641 * x2534;
        let x2724 = x636 * x2537;
        let x2726 = x2722 + x2723;
        let x2727 = x2726 - x2724;
        let x2728 = x86 * k[10];
        let x2730 = x638 * k[11];
        let x2731 = x2730 - x2728;
        let x2732 = x87 * k[10];
        let x2734 = x640 * k[11];
        let x2735 = x2734 - x2732;
        let x2736 = s[15] * k[10];
        let x2737 = x634 * k[11];
        let x2738 = x2736 + x2737;
        let x2739 = -x2731;
        let x2740 = -x2735;
        let x2741 = -x2542;
        let x2742 = x689 * x2519;
        let x2743 = x2670 + x2742;
        let x2744 = x689 * x2530;
        let x2745 = x100 * x2534;
        let x2746 = x2744 + x2745;
        let x2747 = -x2574;
        let x2905 = x1892 * k[12];
        let x2906 = 0.5 * x2905;
        let x2907 = -x2906;
        let x2908 = x1901 * k[13];
        let x2909 = x1903 * k[13];
        let x2910 = x2908 + x2909;
        let x2911 = 0.5 * x2910;
        let x2912 = x1911 * k[13];
        let x2913 = x1913 * k[13];
        let x2915 = x2912 - x2913;
        let x2916 = 0.5 * x2915;
        let x2917 = x1918 * k[13];
        let x2918 = x1920 * k[13];
        let x2920 = x2917 - x2918;
        let x2921 = 0.5 * x2920;
        let x2922 = x1926 * k[12];
        let x2923 = x1930 * k[13];
        let x2924 = x1932 * k[13];
        let x2925 = x2922 + x2923;
        let x2926 = x2924 + x2925;
        let x2927 = 0.5 * x2926;
        let x2928 = s[29] * k[12];
        let x2929 = 0.5 * x2928;
        let x2943 = x2010 * k[13];
        let x2944 = x2012 * k[13];
        let x2946 = x2943 - x2944;
        let x2947 = 0.5 * x2946;
        let x2948 = x2929 + x2947;
        let x2958 = x2108 * k[12];
        let x2959 = 0.5 * x2958;
        let x2960 = -x2959;
        let x2961 = x2117 * k[14];
        let x2962 = x2119 * k[14];
        let x2963 = x2961 + x2962;
        let x2964 = 0.5 * x2963;
        let x2965 = x2127 * k[14];
        let x2966 = x2129 * k[14];
        let x2968 = x2965 - x2966;
        let x2969 = 0.5 * x2968;
        let x2970 = x2134 * k[14];
        let x2971 = x2136 * k[14];
        let x2973 = x2970 - x2971;
        let x2974 = 0.5 * x2973;
        let x2975 = x2142 * k[12];
        let x2976 = x2146 * k[14];
        let x2977 = x2148 * k[14];
        let x2978 = x2975 + x2976;
        let x2979 = x2977 + x2978;
        let x2980 = 0.5 * x2979;
        let x3011 = x2319 * k[12];
        let x3012 = 0.5 * x3011;
        let x3013 = -x3012;
        let x3014 = x2328 * k[15];
        let x3015 = x2330 * k[15];
        let x3016 = x3014 + x3015;
        let x3017 = 0.5 * x3016;
        let x3018 = x2338 * k[15];
        let x3019 = x2340 * k[15];
        let x3021 = x3018 - x3019;
        let x3022 = 0.5 * x3021;
        let x3023 = x2345 * k[15];
        let x3024 = x2347 * k[15];
        let x3026 = x3023 - x3024;
        let x3027 = 0.5 * x3026;
        let x3028 = x2353 * k[12];
        let x3029 = x2357 * k[15];
        let x3030 = x2359 * k[15];
        let x3031 = x3028 + x3029;
        let x3032 = x3030 + x3031;
        let x3033 = 0.5 * x3032;
        phi[0] = x2475;
        phi_q[0] = -1.0;
        phi_q[1] = x2589;
        phi_q[2] = x2469;
        phi[1] = x2476;
        phi_q[3] = -1.0;
        phi_q[4] = x2590;
        phi_q[5] = x2598;
        phi[2] = x2477;
        phi_q[6] = -1.0;
        phi_q[7] = x2591;
        phi[3] = x34;
        phi_q[8] = x341;
        phi_q[9] = x373;
        phi_q[10] = x433;
        phi[4] = x37;
        phi_q[11] = x120;
        phi_q[12] = x375;
        phi_q[13] = x34;
        phi[5] = x2495;
        phi_q[14] = 1.0;
        phi_q[15] = x2593;
        phi_q[16] = x2599;
        phi_q[17] = -1.0;
        phi_q[18] = x2619;
        phi_q[19] = x2488;
        phi[6] = x2497;
        phi_q[20] = 1.0;
        phi_q[21] = x2595;
        phi_q[22] = x2479;
        phi_q[23] = -1.0;
        phi_q[24] = x2620;
        phi_q[25] = x2666;
        phi[7] = x2499;
        phi_q[26] = 1.0;
        phi_q[27] = x2597;
        phi_q[28] = -1.0;
        phi_q[29] = x2621;
        phi[8] = x187;
        phi_q[30] = x357;
        phi_q[31] = x418;
        phi_q[32] = x443;
        phi_q[33] = x466;
        phi_q[34] = x514;
        phi_q[35] = x580;
        phi[9] = x192;
        phi_q[36] = x362;
        phi_q[37] = x424;
        phi_q[38] = x447;
        phi_q[39] = x473;
        phi_q[40] = x520;
        phi_q[41] = x582;
        phi[10] = x2554;
        phi_q[42] = 1.0;
        phi_q[43] = x2600;
        phi_q[44] = x2625;
        phi_q[45] = x2667;
        phi_q[46] = -1.0;
        phi_q[47] = x2680;
        phi_q[48] = x2714;
        phi_q[49] = x2545;
        phi[11] = x2556;
        phi_q[50] = 1.0;
        phi_q[51] = x2601;
        phi_q[52] = x2629;
        phi_q[53] = x2504;
        phi_q[54] = -1.0;
        phi_q[55] = x2681;
        phi_q[56] = x2715;
        phi_q[57] = x2741;
        phi[12] = x2558;
        phi_q[58] = 1.0;
        phi_q[59] = x2602;
        phi_q[60] = x2633;
        phi_q[61] = -1.0;
        phi_q[62] = x2682;
        phi_q[63] = x2713;
        phi[13] = x2563;
        phi_q[64] = x2613;
        phi_q[65] = x2660;
        phi_q[66] = x2673;
        phi_q[67] = x2689;
        phi_q[68] = x2721;
        phi_q[69] = x2743;
        phi[14] = x2568;
        phi_q[70] = x2618;
        phi_q[71] = x2665;
        phi_q[72] = x2676;
        phi_q[73] = x2696;
        phi_q[74] = x2727;
        phi_q[75] = x2746;
        phi[15] = x2586;
        phi_q[76] = -1.0;
        phi_q[77] = x2700;
        phi_q[78] = x2739;
        phi_q[79] = x2577;
        phi[16] = x2587;
        phi_q[80] = -1.0;
        phi_q[81] = x2701;
        phi_q[82] = x2740;
        phi_q[83] = x2747;
        phi[17] = x2588;
        phi_q[84] = -1.0;
        phi_q[85] = x2702;
        phi_q[86] = x2738;
        phi[18] = x100;
        phi_q[87] = x603;
        phi_q[88] = x639;
        phi_q[89] = x689;
        phi[19] = x103;
        phi_q[90] = x605;
        phi_q[91] = x641;
        phi_q[92] = x100;
        phi[20] = x336;
        phi_q[93] = x367;
        phi_q[94] = x429;
        phi_q[95] = x451;
        mass[0] = 0.2;
        mass[1] = 0.2;
        mass[2] = 0.2;
        mass[3] = k[16];
        mass[4] = x2907;
        mass[5] = x2911;
        mass[6] = x2916;
        mass[7] = x2907;
        mass[8] = x2921;
        mass[9] = x2927;
        mass[10] = 0.5;
        mass[11] = 0.5;
        mass[12] = 0.5;
        mass[13] = k[16];
        mass[14] = x2960;
        mass[15] = x2964;
        mass[16] = x2969;
        mass[17] = x2960;
        mass[18] = x2974;
        mass[19] = x2980;
        mass[20] = 0.4;
        mass[21] = 0.4;
        mass[22] = 0.4;
        mass[23] = k[16];
        mass[24] = x3013;
        mass[25] = x3017;
        mass[26] = x3022;
        mass[27] = x3013;
        mass[28] = x3027;
        mass[29] = x3033;
        force[0] = 0.0;
        force[1] = -1.9620000000000002;
        force[2] = 0.0;
        force[3] = x2948;
    }
    #[inline(never)]
    fn eval_newton_part_1(
        k: &[f64; 17],
        qd: &[f64; 18],
        s: &[f64; 30],
        force: &mut [f64; 18],
    ) {
        let x729 = s[1] * qd[3];
        let x730 = s[0] * qd[3];
        let x733 = s[2] * qd[4];
        let x755 = s[3] * x729;
        let x756 = s[0] * x733;
        let x758 = x755 - x756;
        let x797 = s[7] * qd[9];
        let x798 = s[6] * qd[9];
        let x800 = s[9] * qd[10];
        let x801 = s[8] * qd[10];
        let x823 = s[9] * x797;
        let x824 = s[6] * x801;
        let x826 = x823 - x824;
        let x827 = s[9] * x798;
        let x829 = s[7] * x801;
        let x831 = x827 + x829;
        let x870 = s[13] * qd[15];
        let x871 = s[12] * qd[15];
        let x873 = s[15] * qd[16];
        let x874 = s[14] * qd[16];
        let x896 = s[15] * x870;
        let x897 = s[12] * x874;
        let x899 = x896 - x897;
        let x900 = s[15] * x871;
        let x902 = s[13] * x874;
        let x904 = x900 + x902;
        let x1828 = s[2] * qd[5];
        let x1838 = qd[3] - x1828;
        let x1859 = 2.0 * x1838;
        let x1937 = s[3] * x730;
        let x1939 = s[1] * x733;
        let x1941 = x1937 + x1939;
        let x1945 = qd[5] * x733;
        let x1947 = qd[4] * x730;
        let x1949 = x729 * s[19];
        let x1950 = s[0] * x1945;
        let x1952 = x1949 - x1950;
        let x1953 = x1952 - x1947;
        let x1954 = qd[4] * x729;
        let x1955 = x730 * s[19];
        let x1957 = s[1] * x1945;
        let x1959 = x1955 + x1957;
        let x1962 = x1954 + x1959;
        let x1966 = 2.0 * x1953;
        let x1967 = 2.0 * x1962;
        let x1973 = x730 * s[26];
        let x1975 = s[1] * x1966;
        let x1976 = x1975 - x1973;
        let x1978 = x729 * s[27];
        let x1979 = s[0] * x1967;
        let x1981 = x1978 - x1979;
        let x1986 = s[18] * x1859;
        let x1987 = s[2] * s[29];
        let x1989 = x1986 - x1987;
        let x1992 = x758 * s[26];
        let x1993 = s[4] * x1966;
        let x1994 = x1992 + x1993;
        let x1996 = s[27] * x1941;
        let x1998 = s[5] * x1967;
        let x2000 = x1996 + x1998;
        let x2020 = s[0] * x1828;
        let x2022 = s[1] * x1828;
        let x2024 = s[19] * x1859;
        let x2028 = s[26] * x2020;
        let x2032 = s[27] * x2022;
        let x2046 = s[8] * qd[11];
        let x2048 = s[9] * qd[11];
        let x2049 = s[7] * qd[10];
        let x2050 = s[6] * x2048;
        let x2051 = x2049 + x2050;
        let x2052 = s[6] * qd[10];
        let x2053 = s[7] * x2048;
        let x2055 = x2053 - x2052;
        let x2056 = qd[9] - x2046;
        let x2077 = 2.0 * x2056;
        let x2079 = 2.0 * x2051;
        let x2081 = 2.0 * x2055;
        let x2153 = qd[11] * x800;
        let x2155 = qd[11] * x801;
        let x2157 = qd[10] * x798;
        let x2159 = x797 * x2048;
        let x2160 = s[6] * x2155;
        let x2162 = x2159 - x2160;
        let x2163 = x2162 - x2157;
        let x2164 = qd[10] * x797;
        let x2165 = x798 * x2048;
        let x2167 = s[7] * x2155;
        let x2169 = x2165 + x2167;
        let x2172 = x2164 + x2169;
        let x2174 = 2.0 * x2153;
        let x2176 = 2.0 * x2163;
        let x2177 = 2.0 * x2172;
        let x2183 = x798 * x2079;
        let x2185 = s[7] * x2176;
        let x2186 = x2185 - x2183;
        let x2188 = x797 * x2081;
        let x2189 = s[6] * x2177;
        let x2191 = x2188 - x2189;
        let x2196 = x800 * x2077;
        let x2197 = s[8] * x2174;
        let x2199 = x2196 - x2197;
        let x2202 = x826 * x2079;
        let x2203 = s[10] * x2176;
        let x2204 = x2202 + x2203;
        let x2206 = x831 * x2081;
        let x2208 = s[11] * x2177;
        let x2210 = x2206 + x2208;
        let x2220 = x2055 * x2079;
        let x2222 = x2051 * x2081;
        let x2230 = s[6] * x2046;
        let x2232 = s[7] * x2046;
        let x2234 = x2048 * x2077;
        let x2238 = x2079 * x2230;
        let x2242 = x2081 * x2232;
        let x2256 = s[14] * qd[17];
        let x2258 = s[15] * qd[17];
        let x2259 = s[13] * qd[16];
        let x2260 = s[12] * x2258;
        let x2261 = x2259 + x2260;
        let x2262 = s[12] * qd[16];
        let x2263 = s[13] * x2258;
        let x2265 = x2263 - x2262;
        let x2266 = qd[15] - x2256;
        let x2287 = 2.0 * x2266;
        let x2289 = 2.0 * x2261;
        let x2291 = 2.0 * x2265;
        let x2364 = qd[17] * x873;
        let x2366 = qd[17] * x874;
        let x2368 = qd[16] * x871;
        let x2370 = x870 * x2258;
        let x2371 = s[12] * x2366;
        let x2373 = x2370 - x2371;
        let x2374 = x2373 - x2368;
        let x2375 = qd[16] * x870;
        let x2376 = x871 * x2258;
        let x2378 = s[13] * x2366;
        let x2380 = x2376 + x2378;
        let x2383 = x2375 + x2380;
        let x2385 = 2.0 * x2364;
        let x2387 = 2.0 * x2374;
        let x2388 = 2.0 * x2383;
        let x2394 = x871 * x2289;
        let x2396 = s[13] * x2387;
        let x2397 = x2396 - x2394;
        let x2399 = x870 * x2291;
        let x2400 = s[12] * x2388;
        let x2402 = x2399 - x2400;
        let x2407 = x873 * x2287;
        let x2408 = s[14] * x2385;
        let x2410 = x2407 - x2408;
        let x2413 = x899 * x2289;
        let x2414 = s[16] * x2387;
        let x2415 = x2413 + x2414;
        let x2417 = x904 * x2291;
        let x2419 = s[17] * x2388;
        let x2421 = x2417 + x2419;
        let x2431 = x2265 * x2289;
        let x2433 = x2261 * x2291;
        let x2441 = s[12] * x2256;
        let x2443 = s[13] * x2256;
        let x2445 = x2258 * x2287;
        let x2449 = x2289 * x2441;
        let x2453 = x2291 * x2443;
        let x2930 = x1976 * k[13];
        let x2931 = x1981 * k[13];
        let x2933 = x2930 - x2931;
        let x2934 = 0.5 * x2933;
        let x2935 = x1989 * k[12];
        let x2937 = x1994 * k[13];
        let x2938 = x2000 * k[13];
        let x2940 = x2937 - x2935;
        let x2941 = x2940 - x2938;
        let x2942 = 0.5 * x2941;
        let x2949 = x2024 * k[12];
        let x2950 = x2028 * k[13];
        let x2951 = x2032 * k[13];
        let x2952 = x2949 + x2950;
        let x2953 = x2951 + x2952;
        let x2954 = 0.5 * x2953;
        let x2955 = x2934 + x2954;
        let x2956 = -x2955;
        let x2957 = -x2942;
        let x2981 = x2174 * k[12];
        let x2982 = 0.5 * x2981;
        let x2983 = x2186 * k[14];
        let x2984 = x2191 * k[14];
        let x2986 = x2983 - x2984;
        let x2987 = 0.5 * x2986;
        let x2988 = x2199 * k[12];
        let x2990 = x2204 * k[14];
        let x2991 = x2210 * k[14];
        let x2993 = x2990 - x2988;
        let x2994 = x2993 - x2991;
        let x2995 = 0.5 * x2994;
        let x2996 = x2220 * k[14];
        let x2997 = x2222 * k[14];
        let x2999 = x2996 - x2997;
        let x3000 = 0.5 * x2999;
        let x3001 = x2982 + x3000;
        let x3002 = x2234 * k[12];
        let x3003 = x2238 * k[14];
        let x3004 = x2242 * k[14];
        let x3005 = x3002 + x3003;
        let x3006 = x3004 + x3005;
        let x3007 = 0.5 * x3006;
        let x3008 = x2987 + x3007;
        let x3009 = -x3008;
        let x3010 = -x2995;
        let x3034 = x2385 * k[12];
        let x3035 = 0.5 * x3034;
        let x3036 = x2397 * k[15];
        let x3037 = x2402 * k[15];
        let x3039 = x3036 - x3037;
        let x3040 = 0.5 * x3039;
        let x3041 = x2410 * k[12];
        let x3043 = x2415 * k[15];
        let x3044 = x2421 * k[15];
        let x3046 = x3043 - x3041;
        let x3047 = x3046 - x3044;
        let x3048 = 0.5 * x3047;
        let x3049 = x2431 * k[15];
        let x3050 = x2433 * k[15];
        let x3052 = x3049 - x3050;
        let x3053 = 0.5 * x3052;
        let x3054 = x3035 + x3053;
        let x3055 = x2445 * k[12];
        let x3056 = x2449 * k[15];
        let x3057 = x2453 * k[15];
        let x3058 = x3055 + x3056;
        let x3059 = x3057 + x3058;
        let x3060 = 0.5 * x3059;
        let x3061 = x3040 + x3060;
        let x3062 = -x3061;
        let x3063 = -x3048;
        force[4] = x2956;
        force[5] = x2957;
        force[6] = 0.0;
        force[7] = -4.905;
        force[8] = 0.0;
        force[9] = x3001;
        force[10] = x3009;
        force[11] = x3010;
        force[12] = 0.0;
        force[13] = -3.9240000000000004;
        force[14] = 0.0;
        force[15] = x3054;
        force[16] = x3062;
        force[17] = x3063;
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
        offsets_read_parameters: false,
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
    /// Number of values `setup` computes from the run-time parameters.
    pub const N_K: usize = 13;
    /// `setup` at the file's parameter values: what the types without parameters read.
    pub static K: [f64; 13] = [
        -0.05f64,
        0.05f64,
        -0.17499999999999996f64,
        0.175f64,
        0.000000000000000027755575615628914f64,
        0.14999999999999997f64,
        0.000000000000000006938893903907228f64,
        0.4f64,
        -0.14999999999999997f64,
        0.00000000000000004163336342344337f64,
        0.0001666666666666667f64,
        0.005104166666666666f64,
        0.0029999999999999996f64,
    ];
    /// The values the per-step functions read (`k`), from the run-time parameters `p`.
    pub fn setup(p: &[f64], k: &mut [f64]) {
        let p: &[f64; 33] = p.try_into().expect("p must have 33 entries");
        let k: &mut [f64; 13] = k.try_into().expect("k must have 13 entries");
        setup_part_0(p, k);
    }
    #[inline(never)]
    fn setup_part_0(p: &[f64; 33], k: &mut [f64; 13]) {
        let x1803 = p[1] * 0.2;
        let x1804 = p[1] * x1803;
        let x1807 = x1804 * 0.08333333333333333;
        let x1809 = p[2] * 0.5;
        let x1810 = p[2] * x1809;
        let x1811 = 0.08333333333333333 * x1810;
        let x1813 = p[3] * 0.4;
        let x1814 = p[3] * x1813;
        let x1815 = 0.08333333333333333 * x1814;
        let x2739 = 2.0 * x1807;
        let x2740 = 0.5 * x2739;
        let x2741 = 2.0 * x1811;
        let x2742 = 0.5 * x2741;
        let x2743 = 2.0 * x1815;
        let x2744 = 0.5 * x2743;
        k[0] = p[15];
        k[1] = p[16];
        k[2] = p[17];
        k[3] = p[20];
        k[4] = p[21];
        k[5] = p[24];
        k[6] = p[25];
        k[7] = p[28];
        k[8] = p[29];
        k[9] = p[30];
        k[10] = x2740;
        k[11] = x2742;
        k[12] = x2744;
    }
    /// Constraint residual Φ(q, t).
    pub fn phi(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 13] = k.try_into().expect("k must have 13 entries");
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
        phi_part_0(k, q, t, out);
    }
    #[inline(never)]
    fn phi_part_0(k: &[f64; 13], q: &[f64; 9], t: f64, out: &mut [f64; 9]) {
        let x5 = 6.283185307179586 * t;
        let x16 = q[5].sin();
        let x17 = q[5].cos();
        let x331 = x5.sin();
        let x332 = x5.cos();
        let x2467 = q[2].sin();
        let x2468 = q[2].cos();
        let x2470 = q[8].sin();
        let x2471 = q[8].cos();
        let x2477 = 0.00000000000000006123233995736766 * x2468;
        let x2478 = x2467 + x2477;
        let x2479 = 0.00000000000000006123233995736766 * x2467;
        let x2481 = x2479 - x2468;
        let x2542 = x331 * x2478;
        let x2543 = x332 * x2481;
        let x2545 = x2542 - x2543;
        let x2756 = x2468 * k[0];
        let x2757 = x2467 * k[0];
        let x2758 = q[0] + x2756;
        let x2759 = q[1] + x2757;
        let x2760 = -x2758;
        let x2761 = -x2759;
        let x2762 = x2468 * k[1];
        let x2763 = x2467 * k[1];
        let x2764 = q[0] + x2762;
        let x2765 = q[1] + x2763;
        let x2766 = x17 * k[2];
        let x2767 = x16 * k[2];
        let x2768 = q[3] + x2766;
        let x2769 = q[4] + x2767;
        let x2771 = x2764 - x2768;
        let x2773 = x2765 - x2769;
        let x2774 = x17 * k[3];
        let x2775 = x16 * k[4];
        let x2777 = x2774 - x2775;
        let x2778 = x16 * k[3];
        let x2779 = x17 * k[4];
        let x2780 = x2778 + x2779;
        let x2781 = q[3] + x2777;
        let x2782 = q[4] + x2780;
        let x2783 = x2471 * k[5];
        let x2784 = x2470 * k[6];
        let x2786 = x2783 - x2784;
        let x2787 = x2470 * k[5];
        let x2788 = x2471 * k[6];
        let x2789 = x2787 + x2788;
        let x2790 = q[6] + x2786;
        let x2791 = q[7] + x2789;
        let x2793 = x2781 - x2790;
        let x2795 = x2782 - x2791;
        let x2796 = x2471 * k[8];
        let x2797 = x2470 * k[9];
        let x2799 = x2796 - x2797;
        let x2800 = x2470 * k[8];
        let x2801 = x2471 * k[9];
        let x2802 = x2800 + x2801;
        let x2803 = q[6] + x2799;
        let x2804 = q[7] + x2802;
        let x2806 = k[7] - x2803;
        let x2807 = -x2804;
        out[0] = x2760;
        out[1] = x2761;
        out[2] = x2771;
        out[3] = x2773;
        out[4] = x2793;
        out[5] = x2795;
        out[6] = x2806;
        out[7] = x2807;
        out[8] = x2545;
    }
    /// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
    pub fn phi_q(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 13] = k.try_into().expect("k must have 13 entries");
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 25] = out.try_into().expect("out must have 25 entries");
        phi_q_part_0(k, q, t, out);
    }
    #[inline(never)]
    fn phi_q_part_0(k: &[f64; 13], q: &[f64; 9], t: f64, out: &mut [f64; 25]) {
        let x5 = 6.283185307179586 * t;
        let x16 = q[5].sin();
        let x17 = q[5].cos();
        let x331 = x5.sin();
        let x332 = x5.cos();
        let x2467 = q[2].sin();
        let x2468 = q[2].cos();
        let x2470 = q[8].sin();
        let x2471 = q[8].cos();
        let x2477 = 0.00000000000000006123233995736766 * x2468;
        let x2478 = x2467 + x2477;
        let x2479 = 0.00000000000000006123233995736766 * x2467;
        let x2483 = x2468 - x2479;
        let x2549 = x331 * x2483;
        let x2550 = x332 * x2478;
        let x2552 = x2549 - x2550;
        let x2756 = x2468 * k[0];
        let x2757 = x2467 * k[0];
        let x2762 = x2468 * k[1];
        let x2763 = x2467 * k[1];
        let x2766 = x17 * k[2];
        let x2767 = x16 * k[2];
        let x2774 = x17 * k[3];
        let x2775 = x16 * k[4];
        let x2777 = x2774 - x2775;
        let x2778 = x16 * k[3];
        let x2779 = x17 * k[4];
        let x2780 = x2778 + x2779;
        let x2783 = x2471 * k[5];
        let x2784 = x2470 * k[6];
        let x2786 = x2783 - x2784;
        let x2787 = x2470 * k[5];
        let x2788 = x2471 * k[6];
        let x2789 = x2787 + x2788;
        let x2796 = x2471 * k[8];
        let x2797 = x2470 * k[9];
        let x2799 = x2796 - x2797;
        let x2800 = x2470 * k[8];
        let x2801 = x2471 * k[9];
        let x2802 = x2800 + x2801;
        let x2808 = -x2756;
        let x2809 = -x2763;
        let x2810 = -x2766;
        let x2811 = -x2780;
        let x2812 = -x2786;
        let x2813 = -x2799;
        out[0] = -1.0;
        out[1] = x2757;
        out[2] = -1.0;
        out[3] = x2808;
        out[4] = 1.0;
        out[5] = x2809;
        out[6] = -1.0;
        out[7] = x2767;
        out[8] = 1.0;
        out[9] = x2762;
        out[10] = -1.0;
        out[11] = x2810;
        out[12] = 1.0;
        out[13] = x2811;
        out[14] = -1.0;
        out[15] = x2789;
        out[16] = 1.0;
        out[17] = x2777;
        out[18] = -1.0;
        out[19] = x2812;
        out[20] = -1.0;
        out[21] = x2802;
        out[22] = -1.0;
        out[23] = x2813;
        out[24] = x2552;
    }
    /// Partial time derivative Φt(q, t).
    pub fn phi_t(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 13] = k.try_into().expect("k must have 13 entries");
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
        let _ = k;
        phi_t_part_0(q, t, out);
    }
    #[inline(never)]
    fn phi_t_part_0(q: &[f64; 9], t: f64, out: &mut [f64; 9]) {
        let x5 = 6.283185307179586 * t;
        let x331 = x5.sin();
        let x332 = x5.cos();
        let x703 = 6.283185307179586 * x332;
        let x705 = 6.283185307179586 * x331;
        let x2467 = q[2].sin();
        let x2468 = q[2].cos();
        let x2477 = 0.00000000000000006123233995736766 * x2468;
        let x2478 = x2467 + x2477;
        let x2479 = 0.00000000000000006123233995736766 * x2467;
        let x2481 = x2479 - x2468;
        let x2566 = x703 * x2478;
        let x2567 = x705 * x2481;
        let x2569 = x2566 + x2567;
        out[0] = 0.0;
        out[1] = 0.0;
        out[2] = 0.0;
        out[3] = 0.0;
        out[4] = 0.0;
        out[5] = 0.0;
        out[6] = 0.0;
        out[7] = 0.0;
        out[8] = x2569;
    }
    /// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
    pub fn gamma(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 13] = k.try_into().expect("k must have 13 entries");
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
        gamma_part_0(k, q, qd, t, out);
    }
    #[inline(never)]
    fn gamma_part_0(
        k: &[f64; 13],
        q: &[f64; 9],
        qd: &[f64; 9],
        t: f64,
        out: &mut [f64; 9],
    ) {
        let x5 = 6.283185307179586 * t;
        let x16 = q[5].sin();
        let x17 = q[5].cos();
        let x331 = x5.sin();
        let x332 = x5.cos();
        let x703 = 6.283185307179586 * x332;
        let x705 = 6.283185307179586 * x331;
        let x735 = x17 * qd[5];
        let x736 = x16 * qd[5];
        let x1122 = 6.283185307179586 * x705;
        let x1124 = 6.283185307179586 * x703;
        let x1141 = qd[5] * x736;
        let x1143 = qd[5] * x735;
        let x2467 = q[2].sin();
        let x2468 = q[2].cos();
        let x2470 = q[8].sin();
        let x2471 = q[8].cos();
        let x2477 = 0.00000000000000006123233995736766 * x2468;
        let x2478 = x2467 + x2477;
        let x2479 = 0.00000000000000006123233995736766 * x2467;
        let x2481 = x2479 - x2468;
        let x2570 = qd[2] * x2468;
        let x2571 = qd[2] * x2467;
        let x2573 = qd[8] * x2471;
        let x2574 = qd[8] * x2470;
        let x2581 = 0.00000000000000006123233995736766 * x2571;
        let x2583 = x2570 - x2581;
        let x2584 = 0.00000000000000006123233995736766 * x2570;
        let x2585 = x2571 + x2584;
        let x2650 = x1122 * x2478;
        let x2652 = x703 * x2583;
        let x2653 = x2652 - x2650;
        let x2654 = x1124 * x2481;
        let x2655 = x705 * x2585;
        let x2656 = x2654 + x2655;
        let x2658 = qd[2] * x2571;
        let x2660 = qd[2] * x2570;
        let x2661 = qd[8] * x2574;
        let x2663 = qd[8] * x2573;
        let x2668 = 0.00000000000000006123233995736766 * x2660;
        let x2670 = x2658 + x2668;
        let x2672 = 0.00000000000000006123233995736766 * x2658;
        let x2674 = x2660 - x2672;
        let x2720 = x331 * x2670;
        let x2722 = x2652 - x2720;
        let x2723 = x2653 + x2722;
        let x2725 = x332 * x2674;
        let x2726 = x2725 - x2655;
        let x2727 = x2726 - x2656;
        let x2729 = x2723 - x2727;
        let x2734 = -x2729;
        let x2814 = x2660 * k[0];
        let x2815 = -x2814;
        let x2816 = x2658 * k[0];
        let x2817 = -x2816;
        let x2818 = x2660 * k[1];
        let x2820 = x2658 * k[1];
        let x2822 = x1143 * k[2];
        let x2823 = x1141 * k[2];
        let x2824 = x2822 - x2818;
        let x2825 = x2823 - x2820;
        let x2826 = x1143 * k[3];
        let x2827 = x1141 * k[4];
        let x2829 = x2826 - x2827;
        let x2831 = x1141 * k[3];
        let x2832 = x1143 * k[4];
        let x2833 = x2831 + x2832;
        let x2835 = x2663 * k[5];
        let x2836 = x2661 * k[6];
        let x2838 = x2835 - x2836;
        let x2839 = x2661 * k[5];
        let x2840 = x2663 * k[6];
        let x2841 = x2839 + x2840;
        let x2842 = x2838 - x2829;
        let x2843 = x2841 - x2833;
        let x2844 = x2663 * k[8];
        let x2845 = x2661 * k[9];
        let x2847 = x2844 - x2845;
        let x2848 = -x2847;
        let x2849 = x2661 * k[8];
        let x2850 = x2663 * k[9];
        let x2851 = x2849 + x2850;
        let x2852 = -x2851;
        let x2853 = -x2824;
        let x2854 = -x2825;
        let x2855 = -x2842;
        let x2856 = -x2843;
        out[0] = x2815;
        out[1] = x2817;
        out[2] = x2853;
        out[3] = x2854;
        out[4] = x2855;
        out[5] = x2856;
        out[6] = x2848;
        out[7] = x2852;
        out[8] = x2734;
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
        let k: &[f64; 13] = k.try_into().expect("k must have 13 entries");
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 9] = phi.try_into().expect("phi must have 9 entries");
        let phi_q: &mut [f64; 25] = phi_q
            .try_into()
            .expect("phi_q must have 25 entries");
        let phi_t: &mut [f64; 9] = phi_t.try_into().expect("phi_t must have 9 entries");
        let gamma: &mut [f64; 9] = gamma.try_into().expect("gamma must have 9 entries");
        eval_kinematics_part_0(k, q, qd, t, phi, phi_q, phi_t, gamma);
    }
    #[inline(never)]
    fn eval_kinematics_part_0(
        k: &[f64; 13],
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
        let x331 = x5.sin();
        let x332 = x5.cos();
        let x703 = 6.283185307179586 * x332;
        let x705 = 6.283185307179586 * x331;
        let x735 = x17 * qd[5];
        let x736 = x16 * qd[5];
        let x1122 = 6.283185307179586 * x705;
        let x1124 = 6.283185307179586 * x703;
        let x1141 = qd[5] * x736;
        let x1143 = qd[5] * x735;
        let x2467 = q[2].sin();
        let x2468 = q[2].cos();
        let x2470 = q[8].sin();
        let x2471 = q[8].cos();
        let x2477 = 0.00000000000000006123233995736766 * x2468;
        let x2478 = x2467 + x2477;
        let x2479 = 0.00000000000000006123233995736766 * x2467;
        let x2481 = x2479 - x2468;
        let x2483 = x2468 - x2479;
        let x2542 = x331 * x2478;
        let x2543 = x332 * x2481;
        let x2545 = x2542 - x2543;
        let x2549 = x331 * x2483;
        let x2550 = x332 * x2478;
        let x2552 = x2549 - x2550;
        let x2566 = x703 * x2478;
        let x2567 = x705 * x2481;
        let x2569 = x2566 + x2567;
        let x2570 = qd[2] * x2468;
        let x2571 = qd[2] * x2467;
        let x2573 = qd[8] * x2471;
        let x2574 = qd[8] * x2470;
        let x2581 = 0.00000000000000006123233995736766 * x2571;
        let x2583 = x2570 - x2581;
        let x2584 = 0.00000000000000006123233995736766 * x2570;
        let x2585 = x2571 + x2584;
        let x2650 = x1122 * x2478;
        let x2652 = x703 * x2583;
        let x2653 = x2652 - x2650;
        let x2654 = x1124 * x2481;
        let x2655 = x705 * x2585;
        let x2656 = x2654 + x2655;
        let x2658 = qd[2] * x2571;
        let x2660 = qd[2] * x2570;
        let x2661 = qd[8] * x2574;
        let x2663 = qd[8] * x2573;
        let x2668 = 0.00000000000000006123233995736766 * x2660;
        let x2670 = x2658 + x2668;
        let x2672 = 0.00000000000000006123233995736766 * x2658;
        let x2674 = x2660 - x2672;
        let x2720 = x331 * x2670;
        let x2722 = x2652 - x2720;
        let x2723 = x2653 + x2722;
        let x2725 = x332 * x2674;
        let x2726 = x2725 - x2655;
        let x2727 = x2726 - x2656;
        let x2729 = x2723 - x2727;
        let x2734 = -x2729;
        let x2756 = x2468 * k[0];
        let x2757 = x2467 * k[0];
        let x2758 = q[0] + x2756;
        let x2759 = q[1] + x2757;
        let x2760 = -x2758;
        let x2761 = -x2759;
        let x2762 = x2468 * k[1];
        let x2763 = x2467 * k[1];
        let x2764 = q[0] + x2762;
        let x2765 = q[1] + x2763;
        let x2766 = x17 * k[2];
        let x2767 = x16 * k[2];
        let x2768 = q[3] + x2766;
        let x2769 = q[4] + x2767;
        let x2771 = x2764 - x2768;
        let x2773 = x2765 - x2769;
        let x2774 = x17 * k[3];
        let x2775 = x16 * k[4];
        let x2777 = x2774 - x2775;
        let x2778 = x16 * k[3];
        let x2779 = x17 * k[4];
        let x2780 = x2778 + x2779;
        let x2781 = q[3] + x2777;
        let x2782 = q[4] + x2780;
        let x2783 = x2471 * k[5];
        let x2784 = x2470 * k[6];
        let x2786 = x2783 - x2784;
        let x2787 = x2470 * k[5];
        let x2788 = x2471 * k[6];
        let x2789 = x2787 + x2788;
        let x2790 = q[6] + x2786;
        let x2791 = q[7] + x2789;
        let x2793 = x2781 - x2790;
        let x2795 = x2782 - x2791;
        let x2796 = x2471 * k[8];
        let x2797 = x2470 * k[9];
        let x2799 = x2796 - x2797;
        let x2800 = x2470 * k[8];
        let x2801 = x2471 * k[9];
        let x2802 = x2800 + x2801;
        let x2803 = q[6] + x2799;
        let x2804 = q[7] + x2802;
        let x2806 = k[7] - x2803;
        let x2807 = -x2804;
        let x2808 = -x2756;
        let x2809 = -x2763;
        let x2810 = -x2766;
        let x2811 = -x2780;
        let x2812 = -x2786;
        let x2813 = -x2799;
        let x2814 = x2660 * k[0];
        let x2815 = -x2814;
        let x2816 = x2658 * k[0];
        let x2817 = -x2816;
        let x2818 = x2660 * k[1];
        let x2820 = x2658 * k[1];
        let x2822 = x1143 * k[2];
        let x2823 = x1141 * k[2];
        let x2824 = x2822 - x2818;
        let x2825 = x2823 - x2820;
        let x2826 = x1143 * k[3];
        let x2827 = x1141 * k[4];
        let x2829 = x2826 - x2827;
        let x2831 = x1141 * k[3];
        let x2832 = x1143 * k[4];
        let x2833 = x2831 + x2832;
        let x2835 = x2663 * k[5];
        let x2836 = x2661 * k[6];
        let x2838 = x2835 - x2836;
        let x2839 = x2661 * k[5];
        let x2840 = x2663 * k[6];
        let x2841 = x2839 + x2840;
        let x2842 = x2838 - x2829;
        let x2843 = x2841 - x2833;
        let x2844 = x2663 * k[8];
        let x2845 = x2661 * k[9];
        let x2847 = x2844 - x2845;
        let x2848 = -x2847;
        let x2849 = x2661 * k[8];
        let x2850 = x2663 * k[9];
        let x2851 = x2849 + x2850;
        let x2852 = -x2851;
        let x2853 = -x2824;
        let x2854 = -x2825;
        let x2855 = -x2842;
        let x2856 = -x2843;
        phi[0] = x2760;
        phi_q[0] = -1.0;
        phi_q[1] = x2757;
        phi_t[0] = 0.0;
        gamma[0] = x2815;
        phi[1] = x2761;
        phi_q[2] = -1.0;
        phi_q[3] = x2808;
        phi_t[1] = 0.0;
        gamma[1] = x2817;
        phi[2] = x2771;
        phi_q[4] = 1.0;
        phi_q[5] = x2809;
        phi_q[6] = -1.0;
        phi_q[7] = x2767;
        phi_t[2] = 0.0;
        gamma[2] = x2853;
        phi[3] = x2773;
        phi_q[8] = 1.0;
        phi_q[9] = x2762;
        phi_q[10] = -1.0;
        phi_q[11] = x2810;
        phi_t[3] = 0.0;
        gamma[3] = x2854;
        phi[4] = x2793;
        phi_q[12] = 1.0;
        phi_q[13] = x2811;
        phi_q[14] = -1.0;
        phi_q[15] = x2789;
        phi_t[4] = 0.0;
        gamma[4] = x2855;
        phi[5] = x2795;
        phi_q[16] = 1.0;
        phi_q[17] = x2777;
        phi_q[18] = -1.0;
        phi_q[19] = x2812;
        phi_t[5] = 0.0;
        gamma[5] = x2856;
        phi[6] = x2806;
        phi_q[20] = -1.0;
        phi_q[21] = x2802;
        phi_t[6] = 0.0;
        gamma[6] = x2848;
        phi[7] = x2807;
        phi_q[22] = -1.0;
        phi_q[23] = x2813;
        phi_t[7] = 0.0;
        gamma[7] = x2852;
        phi[8] = x2545;
        phi_q[24] = x2552;
        phi_t[8] = x2569;
        gamma[8] = x2734;
    }
    /// Potential energy of gravity and springs, written to `out[0]`.
    pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 13] = k.try_into().expect("k must have 13 entries");
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        let _ = k;
        potential_into_part_0(q, out);
    }
    #[inline(never)]
    fn potential_into_part_0(q: &[f64; 9], out: &mut [f64; 1]) {
        let x1819 = q[1] * 1.9620000000000002;
        let x2735 = q[4] * 4.905;
        let x2736 = q[7] * 3.9240000000000004;
        let x2737 = x1819 + x2735;
        let x2738 = x2736 + x2737;
        out[0] = x2738;
    }
    /// Power of the non-conservative loads, written to `out[0]`.
    pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 13] = k.try_into().expect("k must have 13 entries");
        let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
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
            k: &[f64],
            q: &[f64],
            qd: &[f64],
            t: f64,
            dq: &mut [f64],
            dqd: &mut [f64],
        ) {
            let k: &[f64; 13] = k.try_into().expect("k must have 13 entries");
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
            let k: &[f64; 13] = k.try_into().expect("k must have 13 entries");
            let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
            let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
            let _ = q;
            mass_part_0(k, out);
        }
        #[inline(never)]
        fn mass_part_0(k: &[f64; 13], out: &mut [f64; 9]) {
            out[0] = 0.2;
            out[1] = 0.2;
            out[2] = k[10];
            out[3] = 0.5;
            out[4] = 0.5;
            out[5] = k[11];
            out[6] = 0.4;
            out[7] = 0.4;
            out[8] = k[12];
        }
        /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
        pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            let k: &[f64; 13] = k.try_into().expect("k must have 13 entries");
            let q: &[f64; 9] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 9] = qd.try_into().expect("qd must have n_coords entries");
            let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
            let _ = k;
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
            k: &[f64],
            q: &[f64],
            qd: &[f64],
            t: f64,
            phi: &mut [f64],
            phi_q: &mut [f64],
            mass: &mut [f64],
            force: &mut [f64],
        ) {
            let k: &[f64; 13] = k.try_into().expect("k must have 13 entries");
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
            eval_newton_part_0(k, q, t, phi, phi_q, mass, force);
        }
        #[inline(never)]
        fn eval_newton_part_0(
            k: &[f64; 13],
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
            let x331 = x5.sin();
            let x332 = x5.cos();
            let x2467 = q[2].sin();
            let x2468 = q[2].cos();
            let x2470 = q[8].sin();
            let x2471 = q[8].cos();
            let x2477 = 0.00000000000000006123233995736766 * x2468;
            let x2478 = x2467 + x2477;
            let x2479 = 0.00000000000000006123233995736766 * x2467;
            let x2481 = x2479 - x2468;
            let x2483 = x2468 - x2479;
            let x2542 = x331 * x2478;
            let x2543 = x332 * x2481;
            let x2545 = x2542 - x2543;
            let x2549 = x331 * x2483;
            let x2550 = x332 * x2478;
            let x2552 = x2549 - x2550;
            let x2756 = x2468 * k[0];
            let x2757 = x2467 * k[0];
            let x2758 = q[0] + x2756;
            let x2759 = q[1] + x2757;
            let x2760 = -x2758;
            let x2761 = -x2759;
            let x2762 = x2468 * k[1];
            let x2763 = x2467 * k[1];
            let x2764 = q[0] + x2762;
            let x2765 = q[1] + x2763;
            let x2766 = x17 * k[2];
            let x2767 = x16 * k[2];
            let x2768 = q[3] + x2766;
            let x2769 = q[4] + x2767;
            let x2771 = x2764 - x2768;
            let x2773 = x2765 - x2769;
            let x2774 = x17 * k[3];
            let x2775 = x16 * k[4];
            let x2777 = x2774 - x2775;
            let x2778 = x16 * k[3];
            let x2779 = x17 * k[4];
            let x2780 = x2778 + x2779;
            let x2781 = q[3] + x2777;
            let x2782 = q[4] + x2780;
            let x2783 = x2471 * k[5];
            let x2784 = x2470 * k[6];
            let x2786 = x2783 - x2784;
            let x2787 = x2470 * k[5];
            let x2788 = x2471 * k[6];
            let x2789 = x2787 + x2788;
            let x2790 = q[6] + x2786;
            let x2791 = q[7] + x2789;
            let x2793 = x2781 - x2790;
            let x2795 = x2782 - x2791;
            let x2796 = x2471 * k[8];
            let x2797 = x2470 * k[9];
            let x2799 = x2796 - x2797;
            let x2800 = x2470 * k[8];
            let x2801 = x2471 * k[9];
            let x2802 = x2800 + x2801;
            let x2803 = q[6] + x2799;
            let x2804 = q[7] + x2802;
            let x2806 = k[7] - x2803;
            let x2807 = -x2804;
            let x2808 = -x2756;
            let x2809 = -x2763;
            let x2810 = -x2766;
            let x2811 = -x2780;
            let x2812 = -x2786;
            let x2813 = -x2799;
            phi[0] = x2760;
            phi_q[0] = -1.0;
            phi_q[1] = x2757;
            phi[1] = x2761;
            phi_q[2] = -1.0;
            phi_q[3] = x2808;
            phi[2] = x2771;
            phi_q[4] = 1.0;
            phi_q[5] = x2809;
            phi_q[6] = -1.0;
            phi_q[7] = x2767;
            phi[3] = x2773;
            phi_q[8] = 1.0;
            phi_q[9] = x2762;
            phi_q[10] = -1.0;
            phi_q[11] = x2810;
            phi[4] = x2793;
            phi_q[12] = 1.0;
            phi_q[13] = x2811;
            phi_q[14] = -1.0;
            phi_q[15] = x2789;
            phi[5] = x2795;
            phi_q[16] = 1.0;
            phi_q[17] = x2777;
            phi_q[18] = -1.0;
            phi_q[19] = x2812;
            phi[6] = x2806;
            phi_q[20] = -1.0;
            phi_q[21] = x2802;
            phi[7] = x2807;
            phi_q[22] = -1.0;
            phi_q[23] = x2813;
            phi[8] = x2545;
            phi_q[24] = x2552;
            mass[0] = 0.2;
            mass[1] = 0.2;
            mass[2] = k[10];
            mass[3] = 0.5;
            mass[4] = 0.5;
            mass[5] = k[11];
            mass[6] = 0.4;
            mass[7] = 0.4;
            mass[8] = k[12];
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
        fn eval_kinematics(
            &self,
            q: &[f64],
            qd: &[f64],
            t: f64,
            out: KinematicOutputs<'_>,
        ) {
            eval_kinematics(&K, q, qd, t, out.phi, out.phi_q, out.phi_t, out.gamma)
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
            phi(&self.k, q, t, out)
        }
        fn phi_q(&self, q: &[f64], t: f64, out: &mut [f64]) {
            phi_q(&self.k, q, t, out)
        }
        fn phi_t(&self, q: &[f64], t: f64, out: &mut [f64]) {
            phi_t(&self.k, q, t, out)
        }
        fn gamma(&self, q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            gamma(&self.k, q, qd, t, out)
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
            eval_kinematics(&self.k, q, qd, t, out.phi, out.phi_q, out.phi_t, out.gamma)
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
/// `four_bar` with the `exact` formulation. At run-time parameter values (`Exact::with_parameters`).
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
