//! Generated equations of `slider_crank` (spatial slider-crank, slider axis offset from the crank plane, crank driven). Do not edit.
//!
//! Regenerate with `cargo xtask generate slider_crank` from `mechanisms/slider_crank.toml`.
//!
//! 21 coordinates, 21 constraints, 109 structural nonzeros in Φq.
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
pub fn phi(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 22] = k.try_into().expect("k must have 22 entries");
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
    phi_part_0(k, q, t, out);
}
#[inline(never)]
fn phi_part_0(k: &[f64; 22], q: &[f64; 21], t: f64, out: &mut [f64; 21]) {
    let x5 = 6.283185307179586 * t;
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
    let x323 = x5.sin();
    let x324 = x5.cos();
    let x329 = x16 + x18;
    let x330 = x17 + x329;
    let x331 = x330 - 1.0;
    let x332 = x61 + x63;
    let x333 = x62 + x332;
    let x334 = x333 - 1.0;
    let x335 = x105 + x107;
    let x336 = x106 + x335;
    let x337 = x336 - 1.0;
    let x2423 = x21 * k[0];
    let x2424 = x34 * k[1];
    let x2425 = x2423 + x2424;
    let x2426 = x40 * k[0];
    let x2427 = x24 * k[1];
    let x2428 = x2426 + x2427;
    let x2429 = x50 * k[0];
    let x2430 = x51 * k[1];
    let x2431 = x2429 + x2430;
    let x2432 = q[0] + x2425;
    let x2433 = q[1] + x2428;
    let x2434 = q[2] + x2431;
    let x2437 = x21 * k[2];
    let x2438 = x34 * k[3];
    let x2439 = x2437 + x2438;
    let x2440 = x40 * k[2];
    let x2441 = x24 * k[3];
    let x2442 = x2440 + x2441;
    let x2444 = x39 * k[4];
    let x2445 = x47 * k[4];
    let x2446 = -x2432;
    let x2447 = -x2433;
    let x2448 = -x2434;
    let x2451 = x21 * k[5];
    let x2452 = x34 * k[6];
    let x2453 = x2451 + x2452;
    let x2454 = x40 * k[5];
    let x2455 = x24 * k[6];
    let x2456 = x2454 + x2455;
    let x2457 = x50 * k[5];
    let x2458 = x51 * k[6];
    let x2459 = x2457 + x2458;
    let x2460 = q[0] + x2453;
    let x2461 = q[1] + x2456;
    let x2462 = q[2] + x2459;
    let x2466 = x65 * k[7];
    let x2467 = x78 * k[8];
    let x2468 = x83 * k[9];
    let x2469 = x2466 + x2467;
    let x2470 = x2468 + x2469;
    let x2471 = x84 * k[7];
    let x2472 = x68 * k[8];
    let x2473 = x91 * k[9];
    let x2474 = x2471 + x2472;
    let x2475 = x2473 + x2474;
    let x2476 = x94 * k[7];
    let x2477 = x95 * k[8];
    let x2478 = x71 * k[9];
    let x2479 = x2476 + x2477;
    let x2480 = x2478 + x2479;
    let x2481 = q[7] + x2470;
    let x2482 = q[8] + x2475;
    let x2483 = q[9] + x2480;
    let x2485 = x2460 - x2481;
    let x2487 = x2461 - x2482;
    let x2489 = x2462 - x2483;
    let x2493 = x65 * k[10];
    let x2494 = x78 * k[11];
    let x2495 = x83 * k[12];
    let x2496 = x2493 + x2494;
    let x2497 = x2495 + x2496;
    let x2498 = x84 * k[10];
    let x2499 = x68 * k[11];
    let x2500 = x91 * k[12];
    let x2501 = x2498 + x2499;
    let x2502 = x2500 + x2501;
    let x2503 = x94 * k[10];
    let x2504 = x95 * k[11];
    let x2505 = x71 * k[12];
    let x2506 = x2503 + x2504;
    let x2507 = x2505 + x2506;
    let x2508 = q[7] + x2497;
    let x2509 = q[8] + x2502;
    let x2510 = q[9] + x2507;
    let x2513 = x65 * k[13];
    let x2514 = x78 * k[14];
    let x2515 = x2513 + x2514;
    let x2516 = x84 * k[13];
    let x2517 = x68 * k[14];
    let x2518 = x2516 + x2517;
    let x2519 = x94 * k[13];
    let x2520 = x95 * k[14];
    let x2521 = x2519 + x2520;
    let x2523 = q[14] - x2508;
    let x2525 = q[15] - x2509;
    let x2527 = q[16] - x2510;
    let x2528 = x127 * x2515;
    let x2529 = x135 * x2518;
    let x2530 = x115 * x2521;
    let x2531 = x2528 + x2529;
    let x2532 = x2530 + x2531;
    let x2534 = q[15] + k[15];
    let x2536 = q[16] + k[16];
    let x2537 = x323 * x2439;
    let x2538 = x324 * x2442;
    let x2540 = x2537 - x2538;
    out[0] = x2446;
    out[1] = x2447;
    out[2] = x2448;
    out[3] = x2444;
    out[4] = x2445;
    out[5] = x2485;
    out[6] = x2487;
    out[7] = x2489;
    out[8] = x2523;
    out[9] = x2525;
    out[10] = x2527;
    out[11] = x2532;
    out[12] = x128;
    out[13] = x138;
    out[14] = x2534;
    out[15] = x2536;
    out[16] = x139;
    out[17] = x2540;
    out[18] = x331;
    out[19] = x334;
    out[20] = x337;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 22] = k.try_into().expect("k must have 22 entries");
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 109] = out.try_into().expect("out must have 109 entries");
    phi_q_part_0(k, q, t, out);
}
#[inline(never)]
fn phi_q_part_0(k: &[f64; 22], q: &[f64; 21], t: f64, out: &mut [f64; 109]) {
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
    let x323 = x5.sin();
    let x324 = x5.cos();
    let x338 = 2.0 * q[3];
    let x339 = 2.0 * q[4];
    let x340 = 2.0 * q[10];
    let x341 = 2.0 * q[11];
    let x342 = 2.0 * q[5];
    let x343 = 2.0 * q[12];
    let x344 = 2.0 * q[13];
    let x345 = 2.0 * q[6];
    let x346 = 2.0 * x338;
    let x389 = 2.0 * x339;
    let x414 = 2.0 * x342;
    let x452 = 2.0 * x340;
    let x456 = 2.0 * q[17];
    let x457 = 2.0 * q[20];
    let x516 = 2.0 * x341;
    let x554 = 2.0 * x343;
    let x588 = 2.0 * x344;
    let x615 = 2.0 * q[18];
    let x616 = 2.0 * q[19];
    let x617 = 2.0 * x456;
    let x619 = -x616;
    let x626 = -x456;
    let x634 = 2.0 * x457;
    let x2513 = x65 * k[13];
    let x2514 = x78 * k[14];
    let x2515 = x2513 + x2514;
    let x2516 = x84 * k[13];
    let x2517 = x68 * k[14];
    let x2518 = x2516 + x2517;
    let x2519 = x94 * k[13];
    let x2520 = x95 * k[14];
    let x2521 = x2519 + x2520;
    let x2541 = x346 * k[0];
    let x2542 = x345 * k[1];
    let x2544 = x2541 - x2542;
    let x2545 = x345 * k[0];
    let x2546 = x346 * k[1];
    let x2547 = x2545 + x2546;
    let x2548 = x342 * k[0];
    let x2549 = -x2548;
    let x2550 = x339 * k[1];
    let x2551 = x2550 - x2548;
    let x2552 = x346 * k[2];
    let x2553 = x345 * k[3];
    let x2555 = x2552 - x2553;
    let x2556 = x345 * k[2];
    let x2557 = x346 * k[3];
    let x2558 = x2556 + x2557;
    let x2559 = x342 * k[4];
    let x2560 = x339 * k[4];
    let x2561 = -x2560;
    let x2562 = -x2544;
    let x2563 = -x2547;
    let x2564 = -x2551;
    let x2565 = x346 * k[5];
    let x2566 = x345 * k[6];
    let x2568 = x2565 - x2566;
    let x2569 = x345 * k[5];
    let x2570 = x346 * k[6];
    let x2571 = x2569 + x2570;
    let x2572 = x342 * k[5];
    let x2574 = x339 * k[6];
    let x2575 = x2574 - x2572;
    let x2576 = x323 * x2555;
    let x2577 = x324 * x2558;
    let x2579 = x2576 - x2577;
    let x2580 = x389 * k[0];
    let x2581 = x342 * k[1];
    let x2582 = x2580 + x2581;
    let x2583 = x338 * k[1];
    let x2584 = x2545 + x2583;
    let x2585 = x389 * k[2];
    let x2586 = x342 * k[3];
    let x2587 = x2585 + x2586;
    let x2588 = x342 * k[2];
    let x2589 = x345 * k[4];
    let x2590 = x338 * k[4];
    let x2591 = -x2590;
    let x2592 = -x2582;
    let x2593 = -x2584;
    let x2594 = x389 * k[5];
    let x2595 = x342 * k[6];
    let x2596 = x2594 + x2595;
    let x2597 = x338 * k[6];
    let x2598 = x2569 + x2597;
    let x2599 = x323 * x2587;
    let x2600 = x324 * x2588;
    let x2602 = x2599 - x2600;
    let x2603 = x339 * k[0];
    let x2604 = x414 * k[1];
    let x2605 = x2603 + x2604;
    let x2606 = x338 * k[0];
    let x2607 = -x2606;
    let x2608 = x2542 - x2606;
    let x2609 = x339 * k[3];
    let x2610 = x339 * k[2];
    let x2611 = x414 * k[3];
    let x2612 = x2610 + x2611;
    let x2613 = -x2550;
    let x2614 = -x2605;
    let x2615 = -x2608;
    let x2616 = x339 * k[5];
    let x2617 = x414 * k[6];
    let x2618 = x2616 + x2617;
    let x2619 = x338 * k[5];
    let x2621 = x2566 - x2619;
    let x2622 = x323 * x2609;
    let x2623 = x324 * x2612;
    let x2625 = x2622 - x2623;
    let x2626 = x2581 + x2603;
    let x2627 = x338 * k[3];
    let x2628 = x338 * k[2];
    let x2629 = -x2626;
    let x2630 = -x2597;
    let x2631 = x2595 + x2616;
    let x2632 = x323 * x2627;
    let x2633 = x324 * x2628;
    let x2634 = x2632 + x2633;
    let x2635 = -x2634;
    let x2636 = x452 * k[7];
    let x2637 = x344 * k[8];
    let x2639 = x343 * k[9];
    let x2640 = x2636 - x2637;
    let x2641 = x2639 + x2640;
    let x2642 = x344 * k[7];
    let x2643 = x452 * k[8];
    let x2644 = x341 * k[9];
    let x2646 = x2642 + x2643;
    let x2647 = x2646 - x2644;
    let x2648 = x343 * k[7];
    let x2650 = x341 * k[8];
    let x2651 = x452 * k[9];
    let x2652 = x2650 - x2648;
    let x2653 = x2651 + x2652;
    let x2654 = -x2641;
    let x2655 = -x2647;
    let x2656 = -x2653;
    let x2657 = x452 * k[10];
    let x2658 = x344 * k[11];
    let x2660 = x343 * k[12];
    let x2661 = x2657 - x2658;
    let x2662 = x2660 + x2661;
    let x2663 = x344 * k[10];
    let x2664 = x452 * k[11];
    let x2665 = x341 * k[12];
    let x2667 = x2663 + x2664;
    let x2668 = x2667 - x2665;
    let x2669 = x343 * k[10];
    let x2671 = x341 * k[11];
    let x2672 = x452 * k[12];
    let x2673 = x2671 - x2669;
    let x2674 = x2672 + x2673;
    let x2675 = x452 * k[13];
    let x2676 = x344 * k[14];
    let x2678 = x2675 - x2676;
    let x2679 = x344 * k[13];
    let x2680 = x452 * k[14];
    let x2681 = x2679 + x2680;
    let x2682 = x343 * k[13];
    let x2684 = x341 * k[14];
    let x2685 = x2684 - x2682;
    let x2686 = -x2662;
    let x2687 = -x2668;
    let x2688 = -x2674;
    let x2689 = x127 * x2678;
    let x2690 = x135 * x2681;
    let x2691 = x115 * x2685;
    let x2692 = x2689 + x2690;
    let x2693 = x2691 + x2692;
    let x2694 = x516 * k[7];
    let x2695 = x343 * k[8];
    let x2696 = x344 * k[9];
    let x2697 = x2694 + x2695;
    let x2698 = x2696 + x2697;
    let x2699 = x340 * k[9];
    let x2701 = x2648 - x2699;
    let x2702 = x340 * k[8];
    let x2703 = x2642 + x2702;
    let x2704 = -x2698;
    let x2705 = -x2701;
    let x2706 = -x2703;
    let x2707 = x516 * k[10];
    let x2708 = x343 * k[11];
    let x2709 = x344 * k[12];
    let x2710 = x2707 + x2708;
    let x2711 = x2709 + x2710;
    let x2712 = x340 * k[12];
    let x2714 = x2669 - x2712;
    let x2715 = x340 * k[11];
    let x2716 = x2663 + x2715;
    let x2717 = x516 * k[13];
    let x2718 = x343 * k[14];
    let x2719 = x2717 + x2718;
    let x2720 = x340 * k[14];
    let x2721 = x2679 + x2720;
    let x2722 = -x2711;
    let x2723 = -x2714;
    let x2724 = -x2716;
    let x2725 = x127 * x2719;
    let x2726 = x135 * x2682;
    let x2727 = x115 * x2721;
    let x2728 = x2725 + x2726;
    let x2729 = x2727 + x2728;
    let x2730 = x2650 + x2699;
    let x2731 = x341 * k[7];
    let x2732 = x554 * k[8];
    let x2733 = x2731 + x2732;
    let x2734 = x2696 + x2733;
    let x2735 = x340 * k[7];
    let x2737 = x2637 - x2735;
    let x2738 = -x2730;
    let x2739 = -x2734;
    let x2740 = -x2737;
    let x2741 = x2671 + x2712;
    let x2742 = x341 * k[10];
    let x2743 = x554 * k[11];
    let x2744 = x2742 + x2743;
    let x2745 = x2709 + x2744;
    let x2746 = x340 * k[10];
    let x2748 = x2658 - x2746;
    let x2749 = x341 * k[13];
    let x2750 = x554 * k[14];
    let x2751 = x2749 + x2750;
    let x2752 = x340 * k[13];
    let x2754 = x2676 - x2752;
    let x2755 = -x2741;
    let x2756 = -x2745;
    let x2757 = -x2748;
    let x2758 = x127 * x2684;
    let x2759 = x135 * x2751;
    let x2760 = x115 * x2754;
    let x2761 = x2758 + x2759;
    let x2762 = x2760 + x2761;
    let x2764 = x2644 - x2702;
    let x2765 = x2639 + x2735;
    let x2766 = x588 * k[9];
    let x2767 = x2695 + x2731;
    let x2768 = x2766 + x2767;
    let x2769 = -x2764;
    let x2770 = -x2765;
    let x2771 = -x2768;
    let x2773 = x2665 - x2715;
    let x2774 = x2660 + x2746;
    let x2775 = x588 * k[12];
    let x2776 = x2708 + x2742;
    let x2777 = x2775 + x2776;
    let x2778 = x2718 + x2749;
    let x2779 = -x2773;
    let x2780 = -x2774;
    let x2781 = -x2777;
    let x2782 = x127 * x2720;
    let x2784 = x135 * x2752;
    let x2785 = x115 * x2778;
    let x2786 = x2784 - x2782;
    let x2787 = x2785 + x2786;
    let x2788 = x616 * x2515;
    let x2789 = x615 * x2518;
    let x2791 = x617 * x2521;
    let x2792 = x2788 - x2789;
    let x2793 = x2791 + x2792;
    let x2794 = x457 * x2515;
    let x2795 = x456 * x2518;
    let x2797 = x2794 - x2795;
    let x2798 = x456 * x2515;
    let x2799 = x457 * x2518;
    let x2800 = x2798 + x2799;
    let x2801 = x615 * x2515;
    let x2802 = x616 * x2518;
    let x2803 = x634 * x2521;
    let x2804 = x2801 + x2802;
    let x2805 = x2803 + x2804;
    out[0] = -1.0;
    out[1] = x2562;
    out[2] = x2592;
    out[3] = x2613;
    out[4] = x2583;
    out[5] = -1.0;
    out[6] = x2563;
    out[7] = x2549;
    out[8] = x2614;
    out[9] = x2607;
    out[10] = -1.0;
    out[11] = x2564;
    out[12] = x2593;
    out[13] = x2615;
    out[14] = x2629;
    out[15] = x2559;
    out[16] = x2589;
    out[17] = x2590;
    out[18] = x2560;
    out[19] = x2561;
    out[20] = x2591;
    out[21] = x2589;
    out[22] = x2559;
    out[23] = 1.0;
    out[24] = x2568;
    out[25] = x2596;
    out[26] = x2574;
    out[27] = x2630;
    out[28] = -1.0;
    out[29] = x2654;
    out[30] = x2704;
    out[31] = x2738;
    out[32] = x2769;
    out[33] = 1.0;
    out[34] = x2571;
    out[35] = x2572;
    out[36] = x2618;
    out[37] = x2619;
    out[38] = -1.0;
    out[39] = x2655;
    out[40] = x2705;
    out[41] = x2739;
    out[42] = x2770;
    out[43] = 1.0;
    out[44] = x2575;
    out[45] = x2598;
    out[46] = x2621;
    out[47] = x2631;
    out[48] = -1.0;
    out[49] = x2656;
    out[50] = x2706;
    out[51] = x2740;
    out[52] = x2771;
    out[53] = -1.0;
    out[54] = x2686;
    out[55] = x2722;
    out[56] = x2755;
    out[57] = x2779;
    out[58] = 1.0;
    out[59] = -1.0;
    out[60] = x2687;
    out[61] = x2723;
    out[62] = x2756;
    out[63] = x2780;
    out[64] = 1.0;
    out[65] = -1.0;
    out[66] = x2688;
    out[67] = x2724;
    out[68] = x2757;
    out[69] = x2781;
    out[70] = 1.0;
    out[71] = x2693;
    out[72] = x2729;
    out[73] = x2762;
    out[74] = x2787;
    out[75] = x2793;
    out[76] = x2797;
    out[77] = x2800;
    out[78] = x2805;
    out[79] = x457;
    out[80] = x616;
    out[81] = x615;
    out[82] = x456;
    out[83] = x619;
    out[84] = x457;
    out[85] = x626;
    out[86] = x615;
    out[87] = 1.0;
    out[88] = 1.0;
    out[89] = x615;
    out[90] = x456;
    out[91] = x457;
    out[92] = x616;
    out[93] = x2579;
    out[94] = x2602;
    out[95] = x2625;
    out[96] = x2635;
    out[97] = x338;
    out[98] = x339;
    out[99] = x342;
    out[100] = x345;
    out[101] = x340;
    out[102] = x341;
    out[103] = x343;
    out[104] = x344;
    out[105] = x456;
    out[106] = x615;
    out[107] = x616;
    out[108] = x457;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 22] = k.try_into().expect("k must have 22 entries");
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
    phi_t_part_0(k, q, t, out);
}
#[inline(never)]
fn phi_t_part_0(k: &[f64; 22], q: &[f64; 21], t: f64, out: &mut [f64; 21]) {
    let x5 = 6.283185307179586 * t;
    let x14 = q[3] * q[3];
    let x15 = q[4] * q[4];
    let x16 = q[5] * q[5];
    let x18 = x14 + x15;
    let x19 = 2.0 * x18;
    let x21 = x19 - 1.0;
    let x22 = x14 + x16;
    let x23 = 2.0 * x22;
    let x24 = x23 - 1.0;
    let x28 = q[4] * q[5];
    let x29 = 2.0 * x28;
    let x30 = q[3] * q[6];
    let x32 = 2.0 * x30;
    let x34 = x29 - x32;
    let x40 = x29 + x32;
    let x323 = x5.sin();
    let x324 = x5.cos();
    let x640 = 6.283185307179586 * x324;
    let x642 = 6.283185307179586 * x323;
    let x2437 = x21 * k[2];
    let x2438 = x34 * k[3];
    let x2439 = x2437 + x2438;
    let x2440 = x40 * k[2];
    let x2441 = x24 * k[3];
    let x2442 = x2440 + x2441;
    let x2806 = x640 * x2439;
    let x2807 = x642 * x2442;
    let x2808 = x2806 + x2807;
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
    out[17] = x2808;
    out[18] = 0.0;
    out[19] = 0.0;
    out[20] = 0.0;
}
/// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
pub fn gamma(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 22] = k.try_into().expect("k must have 22 entries");
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 21] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
    gamma_part_0(k, q, qd, t, out);
}
#[inline(never)]
fn gamma_part_0(
    k: &[f64; 22],
    q: &[f64; 21],
    qd: &[f64; 21],
    t: f64,
    out: &mut [f64; 21],
) {
    let x5 = 6.283185307179586 * t;
    let x14 = q[3] * q[3];
    let x15 = q[4] * q[4];
    let x16 = q[5] * q[5];
    let x18 = x14 + x15;
    let x19 = 2.0 * x18;
    let x21 = x19 - 1.0;
    let x22 = x14 + x16;
    let x23 = 2.0 * x22;
    let x24 = x23 - 1.0;
    let x28 = q[4] * q[5];
    let x29 = 2.0 * x28;
    let x30 = q[3] * q[6];
    let x32 = 2.0 * x30;
    let x34 = x29 - x32;
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
    let x323 = x5.sin();
    let x324 = x5.cos();
    let x338 = 2.0 * q[3];
    let x339 = 2.0 * q[4];
    let x340 = 2.0 * q[10];
    let x341 = 2.0 * q[11];
    let x342 = 2.0 * q[5];
    let x343 = 2.0 * q[12];
    let x456 = 2.0 * q[17];
    let x457 = 2.0 * q[20];
    let x640 = 6.283185307179586 * x324;
    let x642 = 6.283185307179586 * x323;
    let x669 = x338 * qd[3];
    let x670 = x339 * qd[4];
    let x671 = x342 * qd[5];
    let x673 = x669 + x670;
    let x674 = 2.0 * x673;
    let x675 = x669 + x671;
    let x676 = 2.0 * x675;
    let x677 = q[5] * qd[4];
    let x678 = q[4] * qd[5];
    let x679 = x677 + x678;
    let x680 = 2.0 * x679;
    let x681 = q[6] * qd[3];
    let x682 = q[3] * qd[6];
    let x683 = x681 + x682;
    let x684 = 2.0 * x683;
    let x686 = x680 - x684;
    let x696 = x680 + x684;
    let x710 = x340 * qd[10];
    let x711 = x341 * qd[11];
    let x712 = x343 * qd[12];
    let x714 = x710 + x711;
    let x715 = 2.0 * x714;
    let x716 = x710 + x712;
    let x717 = 2.0 * x716;
    let x720 = q[12] * qd[11];
    let x721 = q[11] * qd[12];
    let x722 = x720 + x721;
    let x723 = 2.0 * x722;
    let x724 = q[13] * qd[10];
    let x725 = q[10] * qd[13];
    let x726 = x724 + x725;
    let x727 = 2.0 * x726;
    let x729 = x723 - x727;
    let x730 = q[13] * qd[11];
    let x731 = q[11] * qd[13];
    let x732 = x730 + x731;
    let x733 = 2.0 * x732;
    let x734 = q[12] * qd[10];
    let x735 = q[10] * qd[12];
    let x736 = x734 + x735;
    let x737 = 2.0 * x736;
    let x739 = x723 + x727;
    let x740 = q[13] * qd[12];
    let x741 = q[12] * qd[13];
    let x742 = x740 + x741;
    let x743 = 2.0 * x742;
    let x744 = q[11] * qd[10];
    let x745 = q[10] * qd[11];
    let x746 = x744 + x745;
    let x747 = 2.0 * x746;
    let x751 = x733 - x737;
    let x752 = x743 + x747;
    let x753 = x456 * qd[17];
    let x756 = x457 * qd[20];
    let x758 = x753 + x756;
    let x759 = 2.0 * x758;
    let x768 = q[20] * qd[18];
    let x769 = q[18] * qd[20];
    let x770 = x768 + x769;
    let x771 = 2.0 * x770;
    let x772 = q[19] * qd[17];
    let x773 = q[17] * qd[19];
    let x774 = x772 + x773;
    let x775 = 2.0 * x774;
    let x776 = x771 + x775;
    let x778 = q[20] * qd[19];
    let x779 = q[19] * qd[20];
    let x780 = x778 + x779;
    let x781 = 2.0 * x780;
    let x782 = q[18] * qd[17];
    let x783 = q[17] * qd[18];
    let x784 = x782 + x783;
    let x785 = 2.0 * x784;
    let x787 = x781 - x785;
    let x906 = 2.0 * qd[3];
    let x907 = 2.0 * qd[4];
    let x908 = 2.0 * qd[10];
    let x909 = 2.0 * qd[11];
    let x910 = 2.0 * qd[5];
    let x911 = 2.0 * qd[12];
    let x912 = 2.0 * qd[13];
    let x913 = 2.0 * qd[6];
    let x914 = 2.0 * qd[17];
    let x915 = 2.0 * qd[20];
    let x916 = 2.0 * qd[18];
    let x917 = 2.0 * qd[19];
    let x918 = 6.283185307179586 * x642;
    let x920 = 6.283185307179586 * x640;
    let x929 = qd[3] * x906;
    let x930 = qd[4] * x907;
    let x931 = qd[5] * x910;
    let x932 = qd[6] * x913;
    let x933 = x929 + x930;
    let x934 = 2.0 * x933;
    let x935 = x929 + x931;
    let x936 = 2.0 * x935;
    let x937 = qd[4] * qd[5];
    let x938 = x937 + x937;
    let x939 = 2.0 * x938;
    let x940 = qd[3] * qd[6];
    let x941 = x940 + x940;
    let x942 = 2.0 * x941;
    let x944 = x939 - x942;
    let x945 = qd[4] * qd[6];
    let x946 = x945 + x945;
    let x947 = 2.0 * x946;
    let x948 = qd[3] * qd[5];
    let x949 = x948 + x948;
    let x950 = 2.0 * x949;
    let x951 = x947 + x950;
    let x952 = x939 + x942;
    let x953 = qd[5] * qd[6];
    let x954 = x953 + x953;
    let x955 = 2.0 * x954;
    let x956 = qd[3] * qd[4];
    let x957 = x956 + x956;
    let x958 = 2.0 * x957;
    let x960 = x955 - x958;
    let x962 = x947 - x950;
    let x963 = x955 + x958;
    let x964 = qd[10] * x908;
    let x965 = qd[11] * x909;
    let x966 = qd[12] * x911;
    let x967 = qd[13] * x912;
    let x968 = x964 + x965;
    let x969 = 2.0 * x968;
    let x970 = x964 + x966;
    let x971 = 2.0 * x970;
    let x972 = x964 + x967;
    let x973 = 2.0 * x972;
    let x974 = qd[11] * qd[12];
    let x975 = x974 + x974;
    let x976 = 2.0 * x975;
    let x977 = qd[10] * qd[13];
    let x978 = x977 + x977;
    let x979 = 2.0 * x978;
    let x981 = x976 - x979;
    let x982 = qd[11] * qd[13];
    let x983 = x982 + x982;
    let x984 = 2.0 * x983;
    let x985 = qd[10] * qd[12];
    let x986 = x985 + x985;
    let x987 = 2.0 * x986;
    let x988 = x984 + x987;
    let x989 = x976 + x979;
    let x990 = qd[12] * qd[13];
    let x991 = x990 + x990;
    let x992 = 2.0 * x991;
    let x993 = qd[10] * qd[11];
    let x994 = x993 + x993;
    let x995 = 2.0 * x994;
    let x997 = x992 - x995;
    let x999 = x984 - x987;
    let x1000 = x992 + x995;
    let x1001 = qd[17] * x914;
    let x1002 = qd[18] * x916;
    let x1003 = qd[19] * x917;
    let x1004 = qd[20] * x915;
    let x1005 = x1001 + x1002;
    let x1006 = x1001 + x1004;
    let x1007 = 2.0 * x1006;
    let x1008 = qd[18] * qd[19];
    let x1009 = x1008 + x1008;
    let x1010 = 2.0 * x1009;
    let x1011 = qd[17] * qd[20];
    let x1012 = x1011 + x1011;
    let x1013 = 2.0 * x1012;
    let x1014 = qd[18] * qd[20];
    let x1015 = x1014 + x1014;
    let x1016 = 2.0 * x1015;
    let x1017 = qd[17] * qd[19];
    let x1018 = x1017 + x1017;
    let x1019 = 2.0 * x1018;
    let x1020 = x1016 + x1019;
    let x1021 = x1010 + x1013;
    let x1022 = qd[19] * qd[20];
    let x1023 = x1022 + x1022;
    let x1024 = 2.0 * x1023;
    let x1025 = qd[17] * qd[18];
    let x1026 = x1025 + x1025;
    let x1027 = 2.0 * x1026;
    let x1029 = x1024 - x1027;
    let x1031 = x1016 - x1019;
    let x1032 = x1024 + x1027;
    let x1139 = x931 + x933;
    let x1140 = x932 + x1139;
    let x1141 = x966 + x968;
    let x1142 = x967 + x1141;
    let x1143 = x1003 + x1005;
    let x1144 = x1004 + x1143;
    let x1151 = -x1021;
    let x1152 = -x1031;
    let x1153 = -x1032;
    let x1155 = -x1140;
    let x1156 = -x1142;
    let x1157 = -x1144;
    let x2437 = x21 * k[2];
    let x2438 = x34 * k[3];
    let x2439 = x2437 + x2438;
    let x2440 = x40 * k[2];
    let x2441 = x24 * k[3];
    let x2442 = x2440 + x2441;
    let x2513 = x65 * k[13];
    let x2514 = x78 * k[14];
    let x2515 = x2513 + x2514;
    let x2516 = x84 * k[13];
    let x2517 = x68 * k[14];
    let x2518 = x2516 + x2517;
    let x2519 = x94 * k[13];
    let x2520 = x95 * k[14];
    let x2521 = x2519 + x2520;
    let x2809 = x674 * k[2];
    let x2810 = x686 * k[3];
    let x2811 = x2809 + x2810;
    let x2812 = x696 * k[2];
    let x2813 = x676 * k[3];
    let x2814 = x2812 + x2813;
    let x2815 = x715 * k[13];
    let x2816 = x729 * k[14];
    let x2817 = x2815 + x2816;
    let x2818 = x739 * k[13];
    let x2819 = x717 * k[14];
    let x2820 = x2818 + x2819;
    let x2821 = x751 * k[13];
    let x2822 = x752 * k[14];
    let x2823 = x2821 + x2822;
    let x2824 = x640 * x2811;
    let x2825 = x918 * x2439;
    let x2827 = x2824 - x2825;
    let x2828 = x642 * x2814;
    let x2829 = x920 * x2442;
    let x2830 = x2828 + x2829;
    let x2832 = x934 * k[0];
    let x2833 = x944 * k[1];
    let x2834 = x2832 + x2833;
    let x2835 = x952 * k[0];
    let x2836 = x936 * k[1];
    let x2837 = x2835 + x2836;
    let x2838 = x962 * k[0];
    let x2839 = x963 * k[1];
    let x2840 = x2838 + x2839;
    let x2841 = x934 * k[2];
    let x2842 = x944 * k[3];
    let x2843 = x2841 + x2842;
    let x2844 = x952 * k[2];
    let x2845 = x936 * k[3];
    let x2846 = x2844 + x2845;
    let x2847 = x951 * k[4];
    let x2848 = x960 * k[4];
    let x2849 = x934 * k[5];
    let x2850 = x944 * k[6];
    let x2851 = x2849 + x2850;
    let x2852 = x952 * k[5];
    let x2853 = x936 * k[6];
    let x2854 = x2852 + x2853;
    let x2855 = x962 * k[5];
    let x2856 = x963 * k[6];
    let x2857 = x2855 + x2856;
    let x2858 = x969 * k[7];
    let x2859 = x981 * k[8];
    let x2860 = x988 * k[9];
    let x2861 = x2858 + x2859;
    let x2862 = x2860 + x2861;
    let x2863 = x989 * k[7];
    let x2864 = x971 * k[8];
    let x2865 = x997 * k[9];
    let x2866 = x2863 + x2864;
    let x2867 = x2865 + x2866;
    let x2868 = x999 * k[7];
    let x2869 = x1000 * k[8];
    let x2870 = x973 * k[9];
    let x2871 = x2868 + x2869;
    let x2872 = x2870 + x2871;
    let x2874 = x2851 - x2862;
    let x2876 = x2854 - x2867;
    let x2878 = x2857 - x2872;
    let x2879 = x969 * k[10];
    let x2880 = x981 * k[11];
    let x2881 = x988 * k[12];
    let x2882 = x2879 + x2880;
    let x2883 = x2881 + x2882;
    let x2884 = x989 * k[10];
    let x2885 = x971 * k[11];
    let x2886 = x997 * k[12];
    let x2887 = x2884 + x2885;
    let x2888 = x2886 + x2887;
    let x2889 = x999 * k[10];
    let x2890 = x1000 * k[11];
    let x2891 = x973 * k[12];
    let x2892 = x2889 + x2890;
    let x2893 = x2891 + x2892;
    let x2894 = x969 * k[13];
    let x2895 = x981 * k[14];
    let x2896 = x2894 + x2895;
    let x2897 = x989 * k[13];
    let x2898 = x971 * k[14];
    let x2899 = x2897 + x2898;
    let x2900 = x999 * k[13];
    let x2901 = x1000 * k[14];
    let x2902 = x2900 + x2901;
    let x2903 = x776 * x2817;
    let x2904 = x1020 * x2515;
    let x2905 = x2903 + x2904;
    let x2906 = x127 * x2896;
    let x2907 = x2903 + x2906;
    let x2908 = x2905 + x2907;
    let x2909 = x787 * x2820;
    let x2910 = x1029 * x2518;
    let x2911 = x2909 + x2910;
    let x2912 = x135 * x2899;
    let x2913 = x2909 + x2912;
    let x2914 = x2911 + x2913;
    let x2915 = x759 * x2823;
    let x2916 = x1007 * x2521;
    let x2917 = x2915 + x2916;
    let x2918 = x115 * x2902;
    let x2919 = x2915 + x2918;
    let x2920 = x2917 + x2919;
    let x2921 = x2908 + x2914;
    let x2922 = x2920 + x2921;
    let x2923 = x323 * x2843;
    let x2924 = x2824 + x2923;
    let x2925 = x2827 + x2924;
    let x2927 = x324 * x2846;
    let x2928 = x2927 - x2828;
    let x2929 = x2928 - x2830;
    let x2931 = x2925 - x2929;
    let x2932 = -x2847;
    let x2933 = -x2848;
    let x2934 = -x2874;
    let x2935 = -x2876;
    let x2936 = -x2878;
    let x2937 = -x2922;
    let x2938 = -x2931;
    out[0] = x2834;
    out[1] = x2837;
    out[2] = x2840;
    out[3] = x2932;
    out[4] = x2933;
    out[5] = x2934;
    out[6] = x2935;
    out[7] = x2936;
    out[8] = x2883;
    out[9] = x2888;
    out[10] = x2893;
    out[11] = x2937;
    out[12] = x1151;
    out[13] = x1152;
    out[14] = 0.0;
    out[15] = 0.0;
    out[16] = x1153;
    out[17] = x2938;
    out[18] = x1155;
    out[19] = x1156;
    out[20] = x1157;
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
    let k: &[f64; 22] = k.try_into().expect("k must have 22 entries");
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 21] = qd.try_into().expect("qd must have n_coords entries");
    let phi: &mut [f64; 21] = phi.try_into().expect("phi must have 21 entries");
    let phi_q: &mut [f64; 109] = phi_q.try_into().expect("phi_q must have 109 entries");
    let phi_t: &mut [f64; 21] = phi_t.try_into().expect("phi_t must have 21 entries");
    let gamma: &mut [f64; 21] = gamma.try_into().expect("gamma must have 21 entries");
    let mut s = [0.0f64; 132];
    eval_kinematics_shared_0(k, q, qd, t, &mut s);
    eval_kinematics_part_0(k, q, qd, &s, phi, phi_q, phi_t, gamma);
    eval_kinematics_part_1(k, q, qd, t, &s, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_shared_0(
    k: &[f64; 22],
    q: &[f64; 21],
    qd: &[f64; 21],
    _t: f64,
    s: &mut [f64; 132],
) {
    let x14 = q[3] * q[3];
    s[0] = x14;
    let x15 = q[4] * q[4];
    s[1] = x15;
    let x16 = q[5] * q[5];
    s[2] = x16;
    let x18 = x14 + x15;
    s[3] = x18;
    let x19 = 2.0 * x18;
    s[4] = x19;
    let x21 = x19 - 1.0;
    s[5] = x21;
    let x22 = x14 + x16;
    s[6] = x22;
    let x23 = 2.0 * x22;
    s[7] = x23;
    let x24 = x23 - 1.0;
    s[8] = x24;
    let x28 = q[4] * q[5];
    s[9] = x28;
    let x29 = 2.0 * x28;
    s[10] = x29;
    let x30 = q[3] * q[6];
    s[11] = x30;
    let x32 = 2.0 * x30;
    s[12] = x32;
    let x34 = x29 - x32;
    s[13] = x34;
    let x40 = x29 + x32;
    s[14] = x40;
    let x59 = q[10] * q[10];
    s[15] = x59;
    let x60 = q[11] * q[11];
    s[16] = x60;
    let x61 = q[12] * q[12];
    s[17] = x61;
    let x62 = q[13] * q[13];
    s[18] = x62;
    let x63 = x59 + x60;
    s[19] = x63;
    let x64 = 2.0 * x63;
    s[20] = x64;
    let x65 = x64 - 1.0;
    s[21] = x65;
    let x66 = x59 + x61;
    s[22] = x66;
    let x67 = 2.0 * x66;
    s[23] = x67;
    let x68 = x67 - 1.0;
    s[24] = x68;
    let x72 = q[11] * q[12];
    s[25] = x72;
    let x73 = 2.0 * x72;
    s[26] = x73;
    let x74 = q[10] * q[13];
    s[27] = x74;
    let x76 = 2.0 * x74;
    s[28] = x76;
    let x78 = x73 - x76;
    s[29] = x78;
    let x79 = q[11] * q[13];
    s[30] = x79;
    let x80 = 2.0 * x79;
    s[31] = x80;
    let x81 = q[10] * q[12];
    s[32] = x81;
    let x82 = 2.0 * x81;
    s[33] = x82;
    let x84 = x73 + x76;
    s[34] = x84;
    let x85 = q[12] * q[13];
    s[35] = x85;
    let x86 = 2.0 * x85;
    s[36] = x86;
    let x87 = q[10] * q[11];
    s[37] = x87;
    let x89 = 2.0 * x87;
    s[38] = x89;
    let x94 = x80 - x82;
    s[39] = x94;
    let x95 = x86 + x89;
    s[40] = x95;
    let x103 = q[17] * q[17];
    s[41] = x103;
    let x106 = q[20] * q[20];
    s[42] = x106;
    let x113 = x103 + x106;
    s[43] = x113;
    let x114 = 2.0 * x113;
    s[44] = x114;
    let x115 = x114 - 1.0;
    s[45] = x115;
    let x123 = q[18] * q[20];
    s[46] = x123;
    let x124 = 2.0 * x123;
    s[47] = x124;
    let x125 = q[17] * q[19];
    s[48] = x125;
    let x126 = 2.0 * x125;
    s[49] = x126;
    let x127 = x124 + x126;
    s[50] = x127;
    let x129 = q[19] * q[20];
    s[51] = x129;
    let x130 = 2.0 * x129;
    s[52] = x130;
    let x131 = q[17] * q[18];
    s[53] = x131;
    let x133 = 2.0 * x131;
    s[54] = x133;
    let x135 = x130 - x133;
    s[55] = x135;
    let x338 = 2.0 * q[3];
    s[56] = x338;
    let x339 = 2.0 * q[4];
    s[57] = x339;
    let x340 = 2.0 * q[10];
    s[58] = x340;
    let x341 = 2.0 * q[11];
    s[59] = x341;
    let x342 = 2.0 * q[5];
    s[60] = x342;
    let x343 = 2.0 * q[12];
    s[61] = x343;
    let x344 = 2.0 * q[13];
    s[62] = x344;
    let x345 = 2.0 * q[6];
    s[63] = x345;
    let x346 = 2.0 * x338;
    s[64] = x346;
    let x389 = 2.0 * x339;
    s[65] = x389;
    let x414 = 2.0 * x342;
    s[66] = x414;
    let x456 = 2.0 * q[17];
    s[67] = x456;
    let x457 = 2.0 * q[20];
    s[68] = x457;
    let x615 = 2.0 * q[18];
    s[69] = x615;
    let x616 = 2.0 * q[19];
    s[70] = x616;
    let x906 = 2.0 * qd[3];
    s[71] = x906;
    let x907 = 2.0 * qd[4];
    s[72] = x907;
    let x908 = 2.0 * qd[10];
    s[73] = x908;
    let x909 = 2.0 * qd[11];
    s[74] = x909;
    let x910 = 2.0 * qd[5];
    s[75] = x910;
    let x911 = 2.0 * qd[12];
    s[76] = x911;
    let x912 = 2.0 * qd[13];
    s[77] = x912;
    let x929 = qd[3] * x906;
    s[78] = x929;
    let x930 = qd[4] * x907;
    s[79] = x930;
    let x931 = qd[5] * x910;
    s[80] = x931;
    let x933 = x929 + x930;
    s[81] = x933;
    let x934 = 2.0 * x933;
    s[82] = x934;
    let x935 = x929 + x931;
    s[83] = x935;
    let x936 = 2.0 * x935;
    s[84] = x936;
    let x937 = qd[4] * qd[5];
    s[85] = x937;
    let x938 = x937 + x937;
    s[86] = x938;
    let x939 = 2.0 * x938;
    s[87] = x939;
    let x940 = qd[3] * qd[6];
    s[88] = x940;
    let x941 = x940 + x940;
    s[89] = x941;
    let x942 = 2.0 * x941;
    s[90] = x942;
    let x944 = x939 - x942;
    s[91] = x944;
    let x952 = x939 + x942;
    s[92] = x952;
    let x964 = qd[10] * x908;
    s[93] = x964;
    let x965 = qd[11] * x909;
    s[94] = x965;
    let x966 = qd[12] * x911;
    s[95] = x966;
    let x967 = qd[13] * x912;
    s[96] = x967;
    let x968 = x964 + x965;
    s[97] = x968;
    let x969 = 2.0 * x968;
    s[98] = x969;
    let x970 = x964 + x966;
    s[99] = x970;
    let x971 = 2.0 * x970;
    s[100] = x971;
    let x974 = qd[11] * qd[12];
    s[101] = x974;
    let x975 = x974 + x974;
    s[102] = x975;
    let x976 = 2.0 * x975;
    s[103] = x976;
    let x977 = qd[10] * qd[13];
    s[104] = x977;
    let x978 = x977 + x977;
    s[105] = x978;
    let x979 = 2.0 * x978;
    s[106] = x979;
    let x981 = x976 - x979;
    s[107] = x981;
    let x982 = qd[11] * qd[13];
    s[108] = x982;
    let x983 = x982 + x982;
    s[109] = x983;
    let x984 = 2.0 * x983;
    s[110] = x984;
    let x985 = qd[10] * qd[12];
    s[111] = x985;
    let x986 = x985 + x985;
    s[112] = x986;
    let x987 = 2.0 * x986;
    s[113] = x987;
    let x989 = x976 + x979;
    s[114] = x989;
    let x990 = qd[12] * qd[13];
    s[115] = x990;
    let x991 = x990 + x990;
    s[116] = x991;
    let x992 = 2.0 * x991;
    s[117] = x992;
    let x993 = qd[10] * qd[11];
    s[118] = x993;
    let x994 = x993 + x993;
    s[119] = x994;
    let x995 = 2.0 * x994;
    s[120] = x995;
    let x999 = x984 - x987;
    s[121] = x999;
    let x1000 = x992 + x995;
    s[122] = x1000;
    let x2513 = x65 * k[13];
    s[123] = x2513;
    let x2514 = x78 * k[14];
    s[124] = x2514;
    let x2515 = x2513 + x2514;
    s[125] = x2515;
    let x2516 = x84 * k[13];
    s[126] = x2516;
    let x2517 = x68 * k[14];
    s[127] = x2517;
    let x2518 = x2516 + x2517;
    s[128] = x2518;
    let x2519 = x94 * k[13];
    s[129] = x2519;
    let x2520 = x95 * k[14];
    s[130] = x2520;
    let x2521 = x2519 + x2520;
    s[131] = x2521;
}
#[inline(never)]
fn eval_kinematics_part_0(
    k: &[f64; 22],
    q: &[f64; 21],
    qd: &[f64; 21],
    s: &[f64; 132],
    phi: &mut [f64; 21],
    phi_q: &mut [f64; 109],
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
    let x51 = x42 + x45;
    let x69 = s[15] + s[18];
    let x70 = 2.0 * x69;
    let x71 = x70 - 1.0;
    let x83 = s[31] + s[33];
    let x91 = s[36] - s[38];
    let x452 = 2.0 * s[58];
    let x516 = 2.0 * s[59];
    let x554 = 2.0 * s[61];
    let x588 = 2.0 * s[62];
    let x617 = 2.0 * s[67];
    let x634 = 2.0 * s[68];
    let x945 = qd[4] * qd[6];
    let x946 = x945 + x945;
    let x947 = 2.0 * x946;
    let x948 = qd[3] * qd[5];
    let x949 = x948 + x948;
    let x950 = 2.0 * x949;
    let x951 = x947 + x950;
    let x953 = qd[5] * qd[6];
    let x954 = x953 + x953;
    let x955 = 2.0 * x954;
    let x956 = qd[3] * qd[4];
    let x957 = x956 + x956;
    let x958 = 2.0 * x957;
    let x960 = x955 - x958;
    let x962 = x947 - x950;
    let x963 = x955 + x958;
    let x972 = s[93] + s[96];
    let x973 = 2.0 * x972;
    let x988 = s[110] + s[113];
    let x997 = s[117] - s[120];
    let x2423 = s[5] * k[0];
    let x2424 = s[13] * k[1];
    let x2425 = x2423 + x2424;
    let x2426 = s[14] * k[0];
    let x2427 = s[8] * k[1];
    let x2428 = x2426 + x2427;
    let x2429 = x50 * k[0];
    let x2430 = x51 * k[1];
    let x2431 = x2429 + x2430;
    let x2432 = q[0] + x2425;
    let x2433 = q[1] + x2428;
    let x2434 = q[2] + x2431;
    let x2444 = x39 * k[4];
    let x2445 = x47 * k[4];
    let x2446 = -x2432;
    let x2447 = -x2433;
    let x2448 = -x2434;
    let x2451 = s[5] * k[5];
    let x2452 = s[13] * k[6];
    let x2453 = x2451 + x2452;
    let x2454 = s[14] * k[5];
    let x2455 = s[8] * k[6];
    let x2456 = x2454 + x2455;
    let x2457 = x50 * k[5];
    let x2458 = x51 * k[6];
    let x2459 = x2457 + x2458;
    let x2460 = q[0] + x2453;
    let x2461 = q[1] + x2456;
    let x2462 = q[2] + x2459;
    let x2466 = s[21] * k[7];
    let x2467 = s[29] * k[8];
    let x2468 = x83 * k[9];
    let x2469 = x2466 + x2467;
    let x2470 = x2468 + x2469;
    let x2471 = s[34] * k[7];
    let x2472 = s[24] * k[8];
    let x2473 = x91 * k[9];
    let x2474 = x2471 + x2472;
    let x2475 = x2473 + x2474;
    let x2476 = s[39] * k[7];
    let x2477 = s[40] * k[8];
    let x2478 = x71 * k[9];
    let x2479 = x2476 + x2477;
    let x2480 = x2478 + x2479;
    let x2481 = q[7] + x2470;
    let x2482 = q[8] + x2475;
    let x2483 = q[9] + x2480;
    let x2485 = x2460 - x2481;
    let x2487 = x2461 - x2482;
    let x2489 = x2462 - x2483;
    let x2493 = s[21] * k[10];
    let x2494 = s[29] * k[11];
    let x2495 = x83 * k[12];
    let x2496 = x2493 + x2494;
    let x2497 = x2495 + x2496;
    let x2498 = s[34] * k[10];
    let x2499 = s[24] * k[11];
    let x2500 = x91 * k[12];
    let x2501 = x2498 + x2499;
    let x2502 = x2500 + x2501;
    let x2503 = s[39] * k[10];
    let x2504 = s[40] * k[11];
    let x2505 = x71 * k[12];
    let x2506 = x2503 + x2504;
    let x2507 = x2505 + x2506;
    let x2508 = q[7] + x2497;
    let x2509 = q[8] + x2502;
    let x2510 = q[9] + x2507;
    let x2523 = q[14] - x2508;
    let x2525 = q[15] - x2509;
    let x2527 = q[16] - x2510;
    let x2528 = s[50] * s[125];
    let x2529 = s[55] * s[128];
    let x2530 = s[45] * s[131];
    let x2531 = x2528 + x2529;
    let x2532 = x2530 + x2531;
    let x2541 = s[64] * k[0];
    let x2542 = s[63] * k[1];
    let x2544 = x2541 - x2542;
    let x2545 = s[63] * k[0];
    let x2546 = s[64] * k[1];
    let x2547 = x2545 + x2546;
    let x2548 = s[60] * k[0];
    let x2549 = -x2548;
    let x2550 = s[57] * k[1];
    let x2551 = x2550 - x2548;
    let x2559 = s[60] * k[4];
    let x2560 = s[57] * k[4];
    let x2561 = -x2560;
    let x2562 = -x2544;
    let x2563 = -x2547;
    let x2564 = -x2551;
    let x2565 = s[64] * k[5];
    let x2566 = s[63] * k[6];
    let x2568 = x2565 - x2566;
    let x2569 = s[63] * k[5];
    let x2570 = s[64] * k[6];
    let x2571 = x2569 + x2570;
    let x2572 = s[60] * k[5];
    let x2574 = s[57] * k[6];
    let x2575 = x2574 - x2572;
    let x2580 = s[65] * k[0];
    let x2581 = s[60] * k[1];
    let x2582 = x2580 + x2581;
    let x2583 = s[56] * k[1];
    let x2584 = x2545 + x2583;
    let x2589 = s[63] * k[4];
    let x2590 = s[56] * k[4];
    let x2591 = -x2590;
    let x2592 = -x2582;
    let x2593 = -x2584;
    let x2594 = s[65] * k[5];
    let x2595 = s[60] * k[6];
    let x2596 = x2594 + x2595;
    let x2597 = s[56] * k[6];
    let x2598 = x2569 + x2597;
    let x2603 = s[57] * k[0];
    let x2604 = s[66] * k[1];
    let x2605 = x2603 + x2604;
    let x2606 = s[56] * k[0];
    let x2607 = -x2606;
    let x2608 = x2542 - x2606;
    let x2613 = -x2550;
    let x2614 = -x2605;
    let x2615 = -x2608;
    let x2616 = s[57] * k[5];
    let x2617 = s[66] * k[6];
    let x2618 = x2616 + x2617;
    let x2619 = s[56] * k[5];
    let x2621 = x2566 - x2619;
    let x2626 = x2581 + x2603;
    let x2629 = -x2626;
    let x2630 = -x2597;
    let x2631 = x2595 + x2616;
    let x2636 = x452 * k[7];
    let x2637 = s[62] * k[8];
    let x2639 = s[61] * k[9];
    let x2640 = x2636 - x2637;
    let x2641 = x2639 + x2640;
    let x2642 = s[62] * k[7];
    let x2643 = x452 * k[8];
    let x2644 = s[59] * k[9];
    let x2646 = x2642 + x2643;
    let x2647 = x2646 - x2644;
    let x2648 = s[61] * k[7];
    let x2650 = s[59] * k[8];
    let x2651 = x452 * k[9];
    let x2652 = x2650 - x2648;
    let x2653 = x2651 + x2652;
    let x2654 = -x2641;
    let x2655 = -x2647;
    let x2656 = -x2653;
    let x2657 = x452 * k[10];
    let x2658 = s[62] * k[11];
    let x2660 = s[61] * k[12];
    let x2661 = x2657 - x2658;
    let x2662 = x2660 + x2661;
    let x2663 = s[62] * k[10];
    let x2664 = x452 * k[11];
    let x2665 = s[59] * k[12];
    let x2667 = x2663 + x2664;
    let x2668 = x2667 - x2665;
    let x2669 = s[61] * k[10];
    let x2671 = s[59] * k[11];
    let x2672 = x452 * k[12];
    let x2673 = x2671 - x2669;
    let x2674 = x2672 + x2673;
    let x2675 = x452 * k[13];
    let x2676 = s[62] * k[14];
    let x2678 = x2675 - x2676;
    let x2679 = s[62] * k[13];
    let x2680 = x452 * k[14];
    let x2681 = x2679 + x2680;
    let x2682 = s[61] * k[13];
    let x2684 = s[59] * k[14];
    let x2685 = x2684 - x2682;
    let x2686 = -x2662;
    let x2687 = -x2668;
    let x2688 = -x2674;
    let x2689 = s[50] * x2678;
    let x2690 = s[55] * x2681;
    let x2691 = s[45] * x2685;
    let x2692 = x2689 + x2690;
    let x2693 = x2691 + x2692;
    let x2694 = x516 * k[7];
    let x2695 = s[61] * k[8];
    let x2696 = s[62] * k[9];
    let x2697 = x2694 + x2695;
    let x2698 = x2696 + x2697;
    let x2699 = s[58] * k[9];
    let x2701 = x2648 - x2699;
    let x2702 = s[58] * k[8];
    let x2703 = x2642 + x2702;
    let x2704 = -x2698;
    let x2705 = -x2701;
    let x2706 = -x2703;
    let x2707 = x516 * k[10];
    let x2708 = s[61] * k[11];
    let x2709 = s[62] * k[12];
    let x2710 = x2707 + x2708;
    let x2711 = x2709 + x2710;
    let x2712 = s[58] * k[12];
    let x2714 = x2669 - x2712;
    let x2715 = s[58] * k[11];
    let x2716 = x2663 + x2715;
    let x2717 = x516 * k[13];
    let x2718 = s[61] * k[14];
    let x2719 = x2717 + x2718;
    let x2720 = s[58] * k[14];
    let x2721 = x2679 + x2720;
    let x2722 = -x2711;
    let x2723 = -x2714;
    let x2724 = -x2716;
    let x2725 = s[50] * x2719;
    let x2726 = s[55] * x2682;
    let x2727 = s[45] * x2721;
    let x2728 = x2725 + x2726;
    let x2729 = x2727 + x2728;
    let x2730 = x2650 + x2699;
    let x2731 = s[59] * k[7];
    let x2732 = x554 * k[8];
    let x2733 = x2731 + x2732;
    let x2734 = x2696 + x2733;
    let x2735 = s[58] * k[7];
    let x2737 = x2637 - x2735;
    let x2738 = -x2730;
    let x2739 = -x2734;
    let x2740 = -x2737;
    let x2741 = x2671 + x2712;
    let x2742 = s[59] * k[10];
    let x2743 = x554 * k[11];
    let x2744 = x2742 + x2743;
    let x2745 = x2709 + x2744;
    let x2746 = s[58] * k[10];
    let x2748 = x2658 - x2746;
    let x2749 = s[59] * k[13];
    let x2750 = x554 * k[14];
    let x2751 = x2749 + x2750;
    let x2752 = s[58] * k[13];
    let x2754 = x2676 - x2752;
    let x2755 = -x2741;
    let x2756 = -x2745;
    let x2757 = -x2748;
    let x2758 = s[50] * x2684;
    let x2759 = s[55] * x2751;
    let x2760 = s[45] * x2754;
    let x2761 = x2758 + x2759;
    let x2762 = x2760 + x2761;
    let x2764 = x2644 - x2702;
    let x2765 = x2639 + x2735;
    let x2766 = x588 * k[9];
    let x2767 = x2695 + x2731;
    let x2768 = x2766 + x2767;
    let x2769 = -x2764;
    let x2770 = -x2765;
    let x2771 = -x2768;
    let x2773 = x2665 - x2715;
    let x2774 = x2660 + x2746;
    let x2775 = x588 * k[12];
    let x2776 = x2708 + x2742;
    let x2777 = x2775 + x2776;
    let x2778 = x2718 + x2749;
    let x2779 = -x2773;
    let x2780 = -x2774;
    let x2781 = -x2777;
    let x2782 = s[50] * x2720;
    let x2784 = s[55] * x2752;
    let x2785 = s[45] * x2778;
    let x2786 = x2784 - x2782;
    let x2787 = x2785 + x2786;
    let x2788 = s[70] * s[125];
    let x2789 = s[69] * s[128];
    let x2791 = x617 * s[131];
    let x2792 = x2788 - x2789;
    let x2793 = x2791 + x2792;
    let x2794 = s[68] * s[125];
    let x2795 = s[67] * s[128];
    let x2797 = x2794 - x2795;
    let x2798 = s[67] * s[125];
    let x2799 = s[68] * s[128];
    let x2800 = x2798 + x2799;
    let x2801 = s[69] * s[125];
    let x2802 = s[70] * s[128];
    let x2803 = x634 * s[131];
    let x2804 = x2801 + x2802;
    let x2805 = x2803 + x2804;
    let x2832 = s[82] * k[0];
    let x2833 = s[91] * k[1];
    let x2834 = x2832 + x2833;
    let x2835 = s[92] * k[0];
    let x2836 = s[84] * k[1];
    let x2837 = x2835 + x2836;
    let x2838 = x962 * k[0];
    let x2839 = x963 * k[1];
    let x2840 = x2838 + x2839;
    let x2847 = x951 * k[4];
    let x2848 = x960 * k[4];
    let x2849 = s[82] * k[5];
    let x2850 = s[91] * k[6];
    let x2851 = x2849 + x2850;
    let x2852 = s[92] * k[5];
    let x2853 = s[84] * k[6];
    let x2854 = x2852 + x2853;
    let x2855 = x962 * k[5];
    let x2856 = x963 * k[6];
    let x2857 = x2855 + x2856;
    let x2858 = s[98] * k[7];
    let x2859 = s[107] * k[8];
    let x2860 = x988 * k[9];
    let x2861 = x2858 + x2859;
    let x2862 = x2860 + x2861;
    let x2863 = s[114] * k[7];
    let x2864 = s[100] * k[8];
    let x2865 = x997 * k[9];
    let x2866 = x2863 + x2864;
    let x2867 = x2865 + x2866;
    let x2868 = s[121] * k[7];
    let x2869 = s[122] * k[8];
    let x2870 = x973 * k[9];
    let x2871 = x2868 + x2869;
    let x2872 = x2870 + x2871;
    let x2874 = x2851 - x2862;
    let x2876 = x2854 - x2867;
    let x2878 = x2857 - x2872;
    let x2879 = s[98] * k[10];
    let x2880 = s[107] * k[11];
    let x2881 = x988 * k[12];
    let x2882 = x2879 + x2880;
    let x2883 = x2881 + x2882;
    let x2884 = s[114] * k[10];
    let x2885 = s[100] * k[11];
    let x2886 = x997 * k[12];
    let x2887 = x2884 + x2885;
    let x2888 = x2886 + x2887;
    let x2889 = s[121] * k[10];
    let x2890 = s[122] * k[11];
    let x2891 = x973 * k[12];
    let x2892 = x2889 + x2890;
    let x2893 = x2891 + x2892;
    let x2932 = -x2847;
    let x2933 = -x2848;
    let x2934 = -x2874;
    let x2935 = -x2876;
    let x2936 = -x2878;
    phi[0] = x2446;
    phi_q[0] = -1.0;
    phi_q[1] = x2562;
    phi_q[2] = x2592;
    phi_q[3] = x2613;
    phi_q[4] = x2583;
    phi_t[0] = 0.0;
    gamma[0] = x2834;
    phi[1] = x2447;
    phi_q[5] = -1.0;
    phi_q[6] = x2563;
    phi_q[7] = x2549;
    phi_q[8] = x2614;
    phi_q[9] = x2607;
    phi_t[1] = 0.0;
    gamma[1] = x2837;
    phi[2] = x2448;
    phi_q[10] = -1.0;
    phi_q[11] = x2564;
    phi_q[12] = x2593;
    phi_q[13] = x2615;
    phi_q[14] = x2629;
    phi_t[2] = 0.0;
    gamma[2] = x2840;
    phi[3] = x2444;
    phi_q[15] = x2559;
    phi_q[16] = x2589;
    phi_q[17] = x2590;
    phi_q[18] = x2560;
    phi_t[3] = 0.0;
    gamma[3] = x2932;
    phi[4] = x2445;
    phi_q[19] = x2561;
    phi_q[20] = x2591;
    phi_q[21] = x2589;
    phi_q[22] = x2559;
    phi_t[4] = 0.0;
    gamma[4] = x2933;
    phi[5] = x2485;
    phi_q[23] = 1.0;
    phi_q[24] = x2568;
    phi_q[25] = x2596;
    phi_q[26] = x2574;
    phi_q[27] = x2630;
    phi_q[28] = -1.0;
    phi_q[29] = x2654;
    phi_q[30] = x2704;
    phi_q[31] = x2738;
    phi_q[32] = x2769;
    phi_t[5] = 0.0;
    gamma[5] = x2934;
    phi[6] = x2487;
    phi_q[33] = 1.0;
    phi_q[34] = x2571;
    phi_q[35] = x2572;
    phi_q[36] = x2618;
    phi_q[37] = x2619;
    phi_q[38] = -1.0;
    phi_q[39] = x2655;
    phi_q[40] = x2705;
    phi_q[41] = x2739;
    phi_q[42] = x2770;
    phi_t[6] = 0.0;
    gamma[6] = x2935;
    phi[7] = x2489;
    phi_q[43] = 1.0;
    phi_q[44] = x2575;
    phi_q[45] = x2598;
    phi_q[46] = x2621;
    phi_q[47] = x2631;
    phi_q[48] = -1.0;
    phi_q[49] = x2656;
    phi_q[50] = x2706;
    phi_q[51] = x2740;
    phi_q[52] = x2771;
    phi_t[7] = 0.0;
    gamma[7] = x2936;
    phi[8] = x2523;
    phi_q[53] = -1.0;
    phi_q[54] = x2686;
    phi_q[55] = x2722;
    phi_q[56] = x2755;
    phi_q[57] = x2779;
    phi_q[58] = 1.0;
    phi_t[8] = 0.0;
    gamma[8] = x2883;
    phi[9] = x2525;
    phi_q[59] = -1.0;
    phi_q[60] = x2687;
    phi_q[61] = x2723;
    phi_q[62] = x2756;
    phi_q[63] = x2780;
    phi_q[64] = 1.0;
    phi_t[9] = 0.0;
    gamma[9] = x2888;
    phi[10] = x2527;
    phi_q[65] = -1.0;
    phi_q[66] = x2688;
    phi_q[67] = x2724;
    phi_q[68] = x2757;
    phi_q[69] = x2781;
    phi_q[70] = 1.0;
    phi_t[10] = 0.0;
    gamma[10] = x2893;
    phi[11] = x2532;
    phi_q[71] = x2693;
    phi_q[72] = x2729;
    phi_q[73] = x2762;
    phi_q[74] = x2787;
    phi_q[75] = x2793;
    phi_q[76] = x2797;
    phi_q[77] = x2800;
    phi_q[78] = x2805;
    phi_t[11] = 0.0;
}
#[inline(never)]
fn eval_kinematics_part_1(
    k: &[f64; 22],
    q: &[f64; 21],
    qd: &[f64; 21],
    t: f64,
    s: &[f64; 132],
    phi: &mut [f64; 21],
    phi_q: &mut [f64; 109],
    phi_t: &mut [f64; 21],
    gamma: &mut [f64; 21],
) {
    let x5 = 6.283185307179586 * t;
    let x17 = q[6] * q[6];
    let x104 = q[18] * q[18];
    let x105 = q[19] * q[19];
    let x107 = s[41] + x104;
    let x116 = q[18] * q[19];
    let x117 = 2.0 * x116;
    let x118 = q[17] * q[20];
    let x120 = 2.0 * x118;
    let x128 = x117 + x120;
    let x138 = s[47] - s[49];
    let x139 = s[52] + s[54];
    let x323 = x5.sin();
    let x324 = x5.cos();
    let x329 = s[2] + s[3];
    let x330 = x17 + x329;
    let x331 = x330 - 1.0;
    let x332 = s[17] + s[19];
    let x333 = s[18] + x332;
    let x334 = x333 - 1.0;
    let x335 = x105 + x107;
    let x336 = s[42] + x335;
    let x337 = x336 - 1.0;
    let x619 = -s[70];
    let x626 = -s[67];
    let x640 = 6.283185307179586 * x324;
    let x642 = 6.283185307179586 * x323;
    let x669 = s[56] * qd[3];
    let x670 = s[57] * qd[4];
    let x671 = s[60] * qd[5];
    let x673 = x669 + x670;
    let x674 = 2.0 * x673;
    let x675 = x669 + x671;
    let x676 = 2.0 * x675;
    let x677 = q[5] * qd[4];
    let x678 = q[4] * qd[5];
    let x679 = x677 + x678;
    let x680 = 2.0 * x679;
    let x681 = q[6] * qd[3];
    let x682 = q[3] * qd[6];
    let x683 = x681 + x682;
    let x684 = 2.0 * x683;
    let x686 = x680 - x684;
    let x696 = x680 + x684;
    let x710 = s[58] * qd[10];
    let x711 = s[59] * qd[11];
    let x712 = s[61] * qd[12];
    let x714 = x710 + x711;
    let x715 = 2.0 * x714;
    let x716 = x710 + x712;
    let x717 = 2.0 * x716;
    let x720 = q[12] * qd[11];
    let x721 = q[11] * qd[12];
    let x722 = x720 + x721;
    let x723 = 2.0 * x722;
    let x724 = q[13] * qd[10];
    let x725 = q[10] * qd[13];
    let x726 = x724 + x725;
    let x727 = 2.0 * x726;
    let x729 = x723 - x727;
    let x730 = q[13] * qd[11];
    let x731 = q[11] * qd[13];
    let x732 = x730 + x731;
    let x733 = 2.0 * x732;
    let x734 = q[12] * qd[10];
    let x735 = q[10] * qd[12];
    let x736 = x734 + x735;
    let x737 = 2.0 * x736;
    let x739 = x723 + x727;
    let x740 = q[13] * qd[12];
    let x741 = q[12] * qd[13];
    let x742 = x740 + x741;
    let x743 = 2.0 * x742;
    let x744 = q[11] * qd[10];
    let x745 = q[10] * qd[11];
    let x746 = x744 + x745;
    let x747 = 2.0 * x746;
    let x751 = x733 - x737;
    let x752 = x743 + x747;
    let x753 = s[67] * qd[17];
    let x756 = s[68] * qd[20];
    let x758 = x753 + x756;
    let x759 = 2.0 * x758;
    let x768 = q[20] * qd[18];
    let x769 = q[18] * qd[20];
    let x770 = x768 + x769;
    let x771 = 2.0 * x770;
    let x772 = q[19] * qd[17];
    let x773 = q[17] * qd[19];
    let x774 = x772 + x773;
    let x775 = 2.0 * x774;
    let x776 = x771 + x775;
    let x778 = q[20] * qd[19];
    let x779 = q[19] * qd[20];
    let x780 = x778 + x779;
    let x781 = 2.0 * x780;
    let x782 = q[18] * qd[17];
    let x783 = q[17] * qd[18];
    let x784 = x782 + x783;
    let x785 = 2.0 * x784;
    let x787 = x781 - x785;
    let x913 = 2.0 * qd[6];
    let x914 = 2.0 * qd[17];
    let x915 = 2.0 * qd[20];
    let x916 = 2.0 * qd[18];
    let x917 = 2.0 * qd[19];
    let x918 = 6.283185307179586 * x642;
    let x920 = 6.283185307179586 * x640;
    let x932 = qd[6] * x913;
    let x1001 = qd[17] * x914;
    let x1002 = qd[18] * x916;
    let x1003 = qd[19] * x917;
    let x1004 = qd[20] * x915;
    let x1005 = x1001 + x1002;
    let x1006 = x1001 + x1004;
    let x1007 = 2.0 * x1006;
    let x1008 = qd[18] * qd[19];
    let x1009 = x1008 + x1008;
    let x1010 = 2.0 * x1009;
    let x1011 = qd[17] * qd[20];
    let x1012 = x1011 + x1011;
    let x1013 = 2.0 * x1012;
    let x1014 = qd[18] * qd[20];
    let x1015 = x1014 + x1014;
    let x1016 = 2.0 * x1015;
    let x1017 = qd[17] * qd[19];
    let x1018 = x1017 + x1017;
    let x1019 = 2.0 * x1018;
    let x1020 = x1016 + x1019;
    let x1021 = x1010 + x1013;
    let x1022 = qd[19] * qd[20];
    let x1023 = x1022 + x1022;
    let x1024 = 2.0 * x1023;
    let x1025 = qd[17] * qd[18];
    let x1026 = x1025 + x1025;
    let x1027 = 2.0 * x1026;
    let x1029 = x1024 - x1027;
    let x1031 = x1016 - x1019;
    let x1032 = x1024 + x1027;
    let x1139 = s[80] + s[81];
    let x1140 = x932 + x1139;
    let x1141 = s[95] + s[97];
    let x1142 = s[96] + x1141;
    let x1143 = x1003 + x1005;
    let x1144 = x1004 + x1143;
    let x1151 = -x1021;
    let x1152 = -x1031;
    let x1153 = -x1032;
    let x1155 = -x1140;
    let x1156 = -x1142;
    let x1157 = -x1144;
    let x2437 = s[5] * k[2];
    let x2438 = s[13] * k[3];
    let x2439 = x2437 + x2438;
    let x2440 = s[14] * k[2];
    let x2441 = s[8] * k[3];
    let x2442 = x2440 + x2441;
    let x2534 = q[15] + k[15];
    let x2536 = q[16] + k[16];
    let x2537 = x323 * x2439;
    let x2538 = x324 * x2442;
    let x2540 = x2537 - x2538;
    let x2552 = s[64] * k[2];
    let x2553 = s[63] * k[3];
    let x2555 = x2552 - x2553;
    let x2556 = s[63] * k[2];
    let x2557 = s[64] * k[3];
    let x2558 = x2556 + x2557;
    let x2576 = x323 * x2555;
    let x2577 = x324 * x2558;
    let x2579 = x2576 - x2577;
    let x2585 = s[65] * k[2];
    let x2586 = s[60] * k[3];
    let x2587 = x2585 + x2586;
    let x2588 = s[60] * k[2];
    let x2599 = x323 * x2587;
    let x2600 = x324 * x2588;
    let x2602 = x2599 - x2600;
    let x2609 = s[57] * k[3];
    let x2610 = s[57] * k[2];
    let x2611 = s[66] * k[3];
    let x2612 = x2610 + x2611;
    let x2622 = x323 * x2609;
    let x2623 = x324 * x2612;
    let x2625 = x2622 - x2623;
    let x2627 = s[56] * k[3];
    let x2628 = s[56] * k[2];
    let x2632 = x323 * x2627;
    let x2633 = x324 * x2628;
    let x2634 = x2632 + x2633;
    let x2635 = -x2634;
    let x2806 = x640 * x2439;
    let x2807 = x642 * x2442;
    let x2808 = x2806 + x2807;
    let x2809 = x674 * k[2];
    let x2810 = x686 * k[3];
    let x2811 = x2809 + x2810;
    let x2812 = x696 * k[2];
    let x2813 = x676 * k[3];
    let x2814 = x2812 + x2813;
    let x2815 = x715 * k[13];
    let x2816 = x729 * k[14];
    let x2817 = x2815 + x2816;
    let x2818 = x739 * k[13];
    let x2819 = x717 * k[14];
    let x2820 = x2818 + x2819;
    let x2821 = x751 * k[13];
    let x2822 = x752 * k[14];
    let x2823 = x2821 + x2822;
    let x2824 = x640 * x2811;
    let x2825 = x918 * x2439;
    let x2827 = x2824 - x2825;
    let x2828 = x642 * x2814;
    let x2829 = x920 * x2442;
    let x2830 = x2828 + x2829;
    let x2841 = s[82] * k[2];
    let x2842 = s[91] * k[3];
    let x2843 = x2841 + x2842;
    let x2844 = s[92] * k[2];
    let x2845 = s[84] * k[3];
    let x2846 = x2844 + x2845;
    let x2894 = s[98] * k[13];
    let x2895 = s[107] * k[14];
    let x2896 = x2894 + x2895;
    let x2897 = s[114] * k[13];
    let x2898 = s[100] * k[14];
    let x2899 = x2897 + x2898;
    let x2900 = s[121] * k[13];
    let x2901 = s[122] * k[14];
    let x2902 = x2900 + x2901;
    let x2903 = x776 * x2817;
    let x2904 = x1020 * s[125];
    let x2905 = x2903 + x2904;
    let x2906 = s[50] * x2896;
    let x2907 = x2903 + x2906;
    let x2908 = x2905 + x2907;
    let x2909 = x787 * x2820;
    let x2910 = x1029 * s[128];
    let x2911 = x2909 + x2910;
    let x2912 = s[55] * x2899;
    let x2913 = x2909 + x2912;
    let x2914 = x2911 + x2913;
    let x2915 = x759 * x2823;
    let x2916 = x1007 * s[131];
    let x2917 = x2915 + x2916;
    let x2918 = s[45] * x2902;
    let x2919 = x2915 + x2918;
    let x2920 = x2917 + x2919;
    let x2921 = x2908 + x2914;
    let x2922 = x2920 + x2921;
    let x2923 = x323 * x2843;
    let x2924 = x2824 + x2923;
    let x2925 = x2827 + x2924;
    let x2927 = x324 * x2846;
    let x2928 = x2927 - x2828;
    let x2929 = x2928 - x2830;
    let x2931 = x2925 - x2929;
    let x2937 = -x2922;
    let x2938 = -x2931;
    gamma[11] = x2937;
    phi[12] = x128;
    phi_q[79] = s[68];
    phi_q[80] = s[70];
    phi_q[81] = s[69];
    phi_q[82] = s[67];
    phi_t[12] = 0.0;
    gamma[12] = x1151;
    phi[13] = x138;
    phi_q[83] = x619;
    phi_q[84] = s[68];
    phi_q[85] = x626;
    phi_q[86] = s[69];
    phi_t[13] = 0.0;
    gamma[13] = x1152;
    phi[14] = x2534;
    phi_q[87] = 1.0;
    phi_t[14] = 0.0;
    gamma[14] = 0.0;
    phi[15] = x2536;
    phi_q[88] = 1.0;
    phi_t[15] = 0.0;
    gamma[15] = 0.0;
    phi[16] = x139;
    phi_q[89] = s[69];
    phi_q[90] = s[67];
    phi_q[91] = s[68];
    phi_q[92] = s[70];
    phi_t[16] = 0.0;
    gamma[16] = x1153;
    phi[17] = x2540;
    phi_q[93] = x2579;
    phi_q[94] = x2602;
    phi_q[95] = x2625;
    phi_q[96] = x2635;
    phi_t[17] = x2808;
    gamma[17] = x2938;
    phi[18] = x331;
    phi_q[97] = s[56];
    phi_q[98] = s[57];
    phi_q[99] = s[60];
    phi_q[100] = s[63];
    phi_t[18] = 0.0;
    gamma[18] = x1155;
    phi[19] = x334;
    phi_q[101] = s[58];
    phi_q[102] = s[59];
    phi_q[103] = s[61];
    phi_q[104] = s[62];
    phi_t[19] = 0.0;
    gamma[19] = x1156;
    phi[20] = x337;
    phi_q[105] = s[67];
    phi_q[106] = s[69];
    phi_q[107] = s[70];
    phi_q[108] = s[68];
    phi_t[20] = 0.0;
    gamma[20] = x1157;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
    let k: &[f64; 22] = k.try_into().expect("k must have 22 entries");
    let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = k;
    potential_into_part_0(q, out);
}
#[inline(never)]
fn potential_into_part_0(q: &[f64; 21], out: &mut [f64; 1]) {
    let x1185 = q[1] * 2.943;
    let x1188 = q[8] * 5.886;
    let x1190 = q[15] * 9.81;
    let x1191 = x1185 + x1188;
    let x1192 = x1190 + x1191;
    out[0] = x1192;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 22] = k.try_into().expect("k must have 22 entries");
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
pub static PHI_Q_ROWS: [u32; 109usize] = [
    0u32, 0u32, 0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 1u32, 1u32, 2u32, 2u32, 2u32, 2u32,
    2u32, 3u32, 3u32, 3u32, 3u32, 4u32, 4u32, 4u32, 4u32, 5u32, 5u32, 5u32, 5u32, 5u32,
    5u32, 5u32, 5u32, 5u32, 5u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32,
    6u32, 7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 8u32, 8u32, 8u32,
    8u32, 8u32, 8u32, 9u32, 9u32, 9u32, 9u32, 9u32, 9u32, 10u32, 10u32, 10u32, 10u32,
    10u32, 10u32, 11u32, 11u32, 11u32, 11u32, 11u32, 11u32, 11u32, 11u32, 12u32, 12u32,
    12u32, 12u32, 13u32, 13u32, 13u32, 13u32, 14u32, 15u32, 16u32, 16u32, 16u32, 16u32,
    17u32, 17u32, 17u32, 17u32, 18u32, 18u32, 18u32, 18u32, 19u32, 19u32, 19u32, 19u32,
    20u32, 20u32, 20u32, 20u32,
];
/// Column of each Φq nonzero.
pub static PHI_Q_COLS: [u32; 109usize] = [
    0u32, 3u32, 4u32, 5u32, 6u32, 1u32, 3u32, 4u32, 5u32, 6u32, 2u32, 3u32, 4u32, 5u32,
    6u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 0u32, 3u32, 4u32, 5u32, 6u32,
    7u32, 10u32, 11u32, 12u32, 13u32, 1u32, 3u32, 4u32, 5u32, 6u32, 8u32, 10u32, 11u32,
    12u32, 13u32, 2u32, 3u32, 4u32, 5u32, 6u32, 9u32, 10u32, 11u32, 12u32, 13u32, 7u32,
    10u32, 11u32, 12u32, 13u32, 14u32, 8u32, 10u32, 11u32, 12u32, 13u32, 15u32, 9u32,
    10u32, 11u32, 12u32, 13u32, 16u32, 10u32, 11u32, 12u32, 13u32, 17u32, 18u32, 19u32,
    20u32, 17u32, 18u32, 19u32, 20u32, 17u32, 18u32, 19u32, 20u32, 15u32, 16u32, 17u32,
    18u32, 19u32, 20u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 10u32, 11u32,
    12u32, 13u32, 17u32, 18u32, 19u32, 20u32,
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
pub const N_K: usize = 22;
/// `setup` at the file's parameter values: what the types without parameters read.
pub static K: [f64; 22] = [
    -0.05f64,
    0f64,
    1f64,
    0f64,
    1f64,
    0.05f64,
    0f64,
    -0.1749999999999999f64,
    0.000000000000000003677613769070831f64,
    0.000000000000000013877787807814457f64,
    0.17499999999999993f64,
    -0.00000000000000001061650767297806f64,
    -0.000000000000000027755575615628914f64,
    0.00000000000000005551115123125783f64,
    0.9999999999999994f64,
    -0.05f64,
    -0.12f64,
    0.0001f64,
    0.00025f64,
    0.006124999999999999f64,
    0.0008f64,
    0.016466666666666664f64,
];
/// The values the per-step functions read (`k`), from the run-time parameters `p`.
pub fn setup(p: &[f64], k: &mut [f64]) {
    let p: &[f64; 34] = p.try_into().expect("p must have 34 entries");
    let k: &mut [f64; 22] = k.try_into().expect("k must have 22 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 34], k: &mut [f64; 22]) {
    let x319 = -p[32];
    let x321 = -p[33];
    let x1172 = p[4] * 0.3;
    let x1173 = p[4] * x1172;
    let x1176 = x1173 * 0.08333333333333333;
    let x1178 = p[3] * 0.6;
    let x1179 = p[3] * x1178;
    let x1180 = 0.08333333333333333 * x1179;
    let x1297 = p[0] + x1176;
    let x1298 = x1176 + x1297;
    let x1301 = x1298 * 4.0;
    let x1303 = x1301 * 0.3333333333333333;
    let x1720 = p[0] + x1180;
    let x1721 = x1180 + x1720;
    let x1722 = 4.0 * x1721;
    let x1723 = 0.3333333333333333 * x1722;
    k[0] = p[13];
    k[1] = p[14];
    k[2] = p[15];
    k[3] = p[16];
    k[4] = p[17];
    k[5] = p[18];
    k[6] = p[19];
    k[7] = p[20];
    k[8] = p[21];
    k[9] = p[22];
    k[10] = p[23];
    k[11] = p[24];
    k[12] = p[25];
    k[13] = p[29];
    k[14] = p[30];
    k[15] = x319;
    k[16] = x321;
    k[17] = p[0];
    k[18] = x1176;
    k[19] = x1180;
    k[20] = x1303;
    k[21] = x1723;
}
/// The parameters the generated code takes at run time by name: the file's
/// `[parameters]` entries that reach only masses, inertias and springs' constants.
pub static PARAMETERS: [&str; 1] = ["rod"];
/// Their values in the file.
pub static PARAMETER_VALUES: [f64; 1] = [0.0001f64];
/// Number of values `p` holds: the parameters by name, then the model's numbers that
/// the other parameters reach (read off the file loaded at their values: `DATA`).
pub const N_P: usize = 34;
/// `p` at the file's values.
pub static P0: [f64; 34] = [
    0.0001f64,
    0.05f64,
    0.12f64,
    0.35f64,
    0.1f64,
    0.0001f64,
    0f64,
    0.0001f64,
    0.00025f64,
    0.00025f64,
    0.0001f64,
    0.006124999999999999f64,
    0.006124999999999999f64,
    -0.05f64,
    0f64,
    1f64,
    0f64,
    1f64,
    0.05f64,
    0f64,
    -0.1749999999999999f64,
    0.000000000000000003677613769070831f64,
    0.000000000000000013877787807814457f64,
    0.17499999999999993f64,
    -0.00000000000000001061650767297806f64,
    -0.000000000000000027755575615628914f64,
    0.9393875555870622f64,
    -0.00000000000000011102230246251565f64,
    -0.3428571428571428f64,
    0.00000000000000005551115123125783f64,
    0.9999999999999994f64,
    0.4249615361854384f64,
    0.05f64,
    0.12f64,
];
/// Where the numbers after the named parameters come from in the model (positions in
/// the generator's `slots::numbers`).
pub static DATA: [u32; 33] = [
    3u32, 4u32, 5u32, 6u32, 7u32, 8u32, 10u32, 11u32, 12u32, 14u32, 15u32, 16u32, 30u32,
    31u32, 33u32, 34u32, 38u32, 39u32, 40u32, 48u32, 49u32, 50u32, 66u32, 67u32, 68u32,
    69u32, 70u32, 71u32, 72u32, 73u32, 75u32, 76u32, 77u32,
];
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
    let p: &[f64; 34] = p.try_into().expect("p must have 34 entries");
    let out: &mut [f64; 12] = out.try_into().expect("out must have 12 entries");
    mass_properties_part_0(p, out);
}
#[inline(never)]
fn mass_properties_part_0(p: &[f64; 34], out: &mut [f64; 12]) {
    let x1172 = p[4] * 0.3;
    let x1173 = p[4] * x1172;
    let x1176 = x1173 * 0.08333333333333333;
    let x1178 = p[3] * 0.6;
    let x1179 = p[3] * x1178;
    let x1180 = 0.08333333333333333 * x1179;
    out[0] = 0.3;
    out[1] = p[0];
    out[2] = x1176;
    out[3] = x1176;
    out[4] = 0.6;
    out[5] = p[0];
    out[6] = x1180;
    out[7] = x1180;
    out[8] = 1.0;
    out[9] = 0.001;
    out[10] = 0.001;
    out[11] = 0.001;
}
/// Each force's stiffness and damping at the run-time parameters `p`.
pub fn force_constants(p: &[f64], out: &mut [f64]) {
    let p: &[f64; 34] = p.try_into().expect("p must have 34 entries");
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
        let k: &[f64; 22] = k.try_into().expect("k must have 22 entries");
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
        let k: &[f64; 22] = k.try_into().expect("k must have 22 entries");
        let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 57] = out.try_into().expect("out must have 57 entries");
        mass_part_0(k, q, out);
    }
    #[inline(never)]
    fn mass_part_0(k: &[f64; 22], q: &[f64; 21], out: &mut [f64; 57]) {
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
        let x338 = 2.0 * q[3];
        let x339 = 2.0 * q[4];
        let x340 = 2.0 * q[10];
        let x341 = 2.0 * q[11];
        let x342 = 2.0 * q[5];
        let x343 = 2.0 * q[12];
        let x344 = 2.0 * q[13];
        let x345 = 2.0 * q[6];
        let x346 = 2.0 * x338;
        let x389 = 2.0 * x339;
        let x414 = 2.0 * x342;
        let x452 = 2.0 * x340;
        let x456 = 2.0 * q[17];
        let x457 = 2.0 * q[20];
        let x516 = 2.0 * x341;
        let x554 = 2.0 * x343;
        let x588 = 2.0 * x344;
        let x615 = 2.0 * q[18];
        let x616 = 2.0 * q[19];
        let x617 = 2.0 * x456;
        let x634 = 2.0 * x457;
        let x1306 = 2.0 * x345;
        let x1308 = x339 * x389;
        let x1312 = x342 * x414;
        let x1316 = x345 * x1306;
        let x1328 = x339 * x346;
        let x1330 = x342 * x1306;
        let x1334 = x345 * x414;
        let x1342 = x339 * x1306;
        let x1344 = x342 * x346;
        let x1346 = x345 * x389;
        let x1356 = x339 * x414;
        let x1360 = x342 * x389;
        let x1362 = x345 * x346;
        let x1370 = x338 * x389;
        let x1380 = x338 * x346;
        let x1387 = x338 * x1306;
        let x1397 = x338 * x414;
        let x1728 = x341 * x516;
        let x1732 = x343 * x554;
        let x1736 = x344 * x588;
        let x1748 = x341 * x452;
        let x1750 = x343 * x588;
        let x1754 = x344 * x554;
        let x1762 = x341 * x588;
        let x1764 = x343 * x452;
        let x1766 = x344 * x516;
        let x1776 = x341 * x554;
        let x1780 = x343 * x516;
        let x1782 = x344 * x452;
        let x1790 = x340 * x516;
        let x1800 = x340 * x452;
        let x1807 = x340 * x588;
        let x1817 = x340 * x554;
        let x2139 = 2.0 * x615;
        let x2141 = 2.0 * x616;
        let x2144 = x615 * x2139;
        let x2146 = 0.001 * x2144;
        let x2148 = x616 * x2141;
        let x2150 = 0.001 * x2148;
        let x2152 = x457 * x634;
        let x2154 = 0.001 * x2152;
        let x2156 = x2146 + x2150;
        let x2158 = x2154 + x2156;
        let x2160 = 0.5 * x2158;
        let x2162 = x103 * 0.004;
        let x2163 = x2160 + x2162;
        let x2164 = x615 * x617;
        let x2165 = 0.001 * x2164;
        let x2166 = x616 * x634;
        let x2168 = 0.001 * x2166;
        let x2170 = x457 * x2141;
        let x2171 = 0.001 * x2170;
        let x2172 = x2165 - x2168;
        let x2173 = x2171 + x2172;
        let x2174 = 0.5 * x2173;
        let x2176 = x131 * 0.004;
        let x2177 = x2176 - x2174;
        let x2178 = x615 * x634;
        let x2179 = 0.001 * x2178;
        let x2180 = x616 * x617;
        let x2181 = 0.001 * x2180;
        let x2182 = x457 * x2139;
        let x2184 = 0.001 * x2182;
        let x2186 = x2179 + x2181;
        let x2187 = x2186 - x2184;
        let x2188 = 0.5 * x2187;
        let x2190 = x125 * 0.004;
        let x2191 = x2190 - x2188;
        let x2192 = x615 * x2141;
        let x2194 = 0.001 * x2192;
        let x2196 = x616 * x2139;
        let x2197 = 0.001 * x2196;
        let x2198 = x457 * x617;
        let x2199 = 0.001 * x2198;
        let x2200 = x2197 - x2194;
        let x2201 = x2199 + x2200;
        let x2202 = 0.5 * x2201;
        let x2204 = x118 * 0.004;
        let x2205 = x2204 - x2202;
        let x2206 = x456 * x2139;
        let x2208 = 0.001 * x2206;
        let x2212 = x2171 - x2208;
        let x2213 = x2212 - x2168;
        let x2214 = 0.5 * x2213;
        let x2215 = x2176 + x2214;
        let x2216 = x456 * x617;
        let x2217 = 0.001 * x2216;
        let x2218 = x2154 + x2217;
        let x2219 = x2150 + x2218;
        let x2220 = 0.5 * x2219;
        let x2221 = x104 * 0.004;
        let x2222 = x2220 + x2221;
        let x2223 = x456 * x634;
        let x2224 = 0.001 * x2223;
        let x2228 = x2224 - x2199;
        let x2229 = x2228 - x2197;
        let x2230 = 0.5 * x2229;
        let x2231 = x116 * 0.004;
        let x2232 = x2230 + x2231;
        let x2233 = x456 * x2141;
        let x2235 = 0.001 * x2233;
        let x2237 = x2184 + x2235;
        let x2239 = x2181 - x2237;
        let x2240 = 0.5 * x2239;
        let x2241 = x123 * 0.004;
        let x2242 = x2240 + x2241;
        let x2245 = x2179 - x2237;
        let x2246 = 0.5 * x2245;
        let x2247 = x2190 + x2246;
        let x2250 = x2199 - x2224;
        let x2251 = x2250 - x2194;
        let x2252 = 0.5 * x2251;
        let x2253 = x2231 + x2252;
        let x2254 = x2146 + x2218;
        let x2255 = 0.5 * x2254;
        let x2256 = x105 * 0.004;
        let x2257 = x2255 + x2256;
        let x2259 = x2208 - x2171;
        let x2260 = x2259 - x2165;
        let x2261 = 0.5 * x2260;
        let x2262 = x129 * 0.004;
        let x2263 = x2261 + x2262;
        let x2264 = x2200 - x2224;
        let x2265 = 0.5 * x2264;
        let x2266 = x2204 + x2265;
        let x2269 = x2235 - x2186;
        let x2270 = 0.5 * x2269;
        let x2271 = x2241 + x2270;
        let x2272 = x2172 - x2208;
        let x2273 = 0.5 * x2272;
        let x2274 = x2262 + x2273;
        let x2275 = x2156 + x2217;
        let x2276 = 0.5 * x2275;
        let x2277 = x106 * 0.004;
        let x2278 = x2276 + x2277;
        let x2943 = x1308 * k[17];
        let x2944 = x1312 * k[18];
        let x2945 = x1316 * k[18];
        let x2946 = x2943 + x2944;
        let x2947 = x2945 + x2946;
        let x2948 = 0.5 * x2947;
        let x2949 = x14 * k[20];
        let x2950 = x2948 + x2949;
        let x2951 = x1328 * k[17];
        let x2952 = x1330 * k[18];
        let x2954 = x1334 * k[18];
        let x2955 = x2951 - x2952;
        let x2956 = x2954 + x2955;
        let x2957 = 0.5 * x2956;
        let x2959 = x43 * k[20];
        let x2960 = x2959 - x2957;
        let x2961 = x1342 * k[17];
        let x2962 = x1344 * k[18];
        let x2963 = x1346 * k[18];
        let x2965 = x2961 + x2962;
        let x2966 = x2965 - x2963;
        let x2967 = 0.5 * x2966;
        let x2969 = x37 * k[20];
        let x2970 = x2969 - x2967;
        let x2971 = x1356 * k[17];
        let x2973 = x1360 * k[18];
        let x2974 = x1362 * k[18];
        let x2975 = x2973 - x2971;
        let x2976 = x2974 + x2975;
        let x2977 = 0.5 * x2976;
        let x2979 = x30 * k[20];
        let x2980 = x2979 - x2977;
        let x2981 = x1370 * k[17];
        let x2983 = x2954 - x2981;
        let x2984 = x2983 - x2952;
        let x2985 = 0.5 * x2984;
        let x2986 = x2959 + x2985;
        let x2987 = x1380 * k[17];
        let x2988 = x2945 + x2987;
        let x2989 = x2944 + x2988;
        let x2990 = 0.5 * x2989;
        let x2991 = x15 * k[20];
        let x2992 = x2990 + x2991;
        let x2993 = x1387 * k[17];
        let x2996 = x2993 - x2974;
        let x2997 = x2996 - x2973;
        let x2998 = 0.5 * x2997;
        let x2999 = x28 * k[20];
        let x3000 = x2998 + x2999;
        let x3001 = x1397 * k[17];
        let x3002 = x2963 + x3001;
        let x3004 = x2962 - x3002;
        let x3005 = 0.5 * x3004;
        let x3006 = x35 * k[20];
        let x3007 = x3005 + x3006;
        let x3008 = x1346 * k[17];
        let x3009 = x1397 * k[18];
        let x3010 = x1342 * k[18];
        let x3011 = x3008 + x3009;
        let x3013 = x3010 - x3011;
        let x3014 = 0.5 * x3013;
        let x3015 = x2969 + x3014;
        let x3016 = x1362 * k[17];
        let x3017 = x1387 * k[18];
        let x3019 = x1356 * k[18];
        let x3021 = x3016 - x3017;
        let x3022 = x3021 - x3019;
        let x3023 = 0.5 * x3022;
        let x3024 = x2999 + x3023;
        let x3025 = x1316 * k[17];
        let x3026 = x1380 * k[18];
        let x3027 = x1308 * k[18];
        let x3028 = x3025 + x3026;
        let x3029 = x3027 + x3028;
        let x3030 = 0.5 * x3029;
        let x3031 = x16 * k[20];
        let x3032 = x3030 + x3031;
        let x3033 = x1334 * k[17];
        let x3035 = x1370 * k[18];
        let x3036 = x1328 * k[18];
        let x3038 = x3035 - x3033;
        let x3039 = x3038 - x3036;
        let x3040 = 0.5 * x3039;
        let x3041 = x41 * k[20];
        let x3042 = x3040 + x3041;
        let x3043 = x1360 * k[17];
        let x3044 = x3043 - x3019;
        let x3045 = x3044 - x3017;
        let x3046 = 0.5 * x3045;
        let x3047 = x2979 + x3046;
        let x3048 = x1344 * k[17];
        let x3049 = x3010 + x3048;
        let x3051 = x3009 - x3049;
        let x3052 = 0.5 * x3051;
        let x3053 = x3006 + x3052;
        let x3054 = x1330 * k[17];
        let x3057 = x3036 - x3054;
        let x3058 = x3057 - x3035;
        let x3059 = 0.5 * x3058;
        let x3060 = x3041 + x3059;
        let x3061 = x1312 * k[17];
        let x3062 = x3027 + x3061;
        let x3063 = x3026 + x3062;
        let x3064 = 0.5 * x3063;
        let x3065 = x17 * k[20];
        let x3066 = x3064 + x3065;
        let x3143 = x1728 * k[17];
        let x3144 = x1732 * k[19];
        let x3145 = x1736 * k[19];
        let x3146 = x3143 + x3144;
        let x3147 = x3145 + x3146;
        let x3148 = 0.5 * x3147;
        let x3149 = x59 * k[21];
        let x3150 = x3148 + x3149;
        let x3151 = x1748 * k[17];
        let x3152 = x1750 * k[19];
        let x3154 = x1754 * k[19];
        let x3155 = x3151 - x3152;
        let x3156 = x3154 + x3155;
        let x3157 = 0.5 * x3156;
        let x3159 = x87 * k[21];
        let x3160 = x3159 - x3157;
        let x3161 = x1762 * k[17];
        let x3162 = x1764 * k[19];
        let x3163 = x1766 * k[19];
        let x3165 = x3161 + x3162;
        let x3166 = x3165 - x3163;
        let x3167 = 0.5 * x3166;
        let x3169 = x81 * k[21];
        let x3170 = x3169 - x3167;
        let x3171 = x1776 * k[17];
        let x3173 = x1780 * k[19];
        let x3174 = x1782 * k[19];
        let x3175 = x3173 - x3171;
        let x3176 = x3174 + x3175;
        let x3177 = 0.5 * x3176;
        let x3179 = x74 * k[21];
        let x3180 = x3179 - x3177;
        let x3181 = x1790 * k[17];
        let x3183 = x3154 - x3181;
        let x3184 = x3183 - x3152;
        let x3185 = 0.5 * x3184;
        let x3186 = x3159 + x3185;
        let x3187 = x1800 * k[17];
        let x3188 = x3145 + x3187;
        let x3189 = x3144 + x3188;
        let x3190 = 0.5 * x3189;
        let x3191 = x60 * k[21];
        let x3192 = x3190 + x3191;
        let x3193 = x1807 * k[17];
        let x3196 = x3193 - x3174;
        let x3197 = x3196 - x3173;
        let x3198 = 0.5 * x3197;
        let x3199 = x72 * k[21];
        let x3200 = x3198 + x3199;
        let x3201 = x1817 * k[17];
        let x3202 = x3163 + x3201;
        let x3204 = x3162 - x3202;
        let x3205 = 0.5 * x3204;
        let x3206 = x79 * k[21];
        let x3207 = x3205 + x3206;
        let x3208 = x1766 * k[17];
        let x3209 = x1817 * k[19];
        let x3210 = x1762 * k[19];
        let x3211 = x3208 + x3209;
        let x3213 = x3210 - x3211;
        let x3214 = 0.5 * x3213;
        let x3215 = x3169 + x3214;
        let x3216 = x1782 * k[17];
        let x3217 = x1807 * k[19];
        let x3219 = x1776 * k[19];
        let x3221 = x3216 - x3217;
        let x3222 = x3221 - x3219;
        let x3223 = 0.5 * x3222;
        let x3224 = x3199 + x3223;
        let x3225 = x1736 * k[17];
        let x3226 = x1800 * k[19];
        let x3227 = x1728 * k[19];
        let x3228 = x3225 + x3226;
        let x3229 = x3227 + x3228;
        let x3230 = 0.5 * x3229;
        let x3231 = x61 * k[21];
        let x3232 = x3230 + x3231;
        let x3233 = x1754 * k[17];
        let x3235 = x1790 * k[19];
        let x3236 = x1748 * k[19];
        let x3238 = x3235 - x3233;
        let x3239 = x3238 - x3236;
        let x3240 = 0.5 * x3239;
        let x3241 = x85 * k[21];
        let x3242 = x3240 + x3241;
        let x3243 = x1780 * k[17];
        let x3244 = x3243 - x3219;
        let x3245 = x3244 - x3217;
        let x3246 = 0.5 * x3245;
        let x3247 = x3179 + x3246;
        let x3248 = x1764 * k[17];
        let x3249 = x3210 + x3248;
        let x3251 = x3209 - x3249;
        let x3252 = 0.5 * x3251;
        let x3253 = x3206 + x3252;
        let x3254 = x1750 * k[17];
        let x3257 = x3236 - x3254;
        let x3258 = x3257 - x3235;
        let x3259 = 0.5 * x3258;
        let x3260 = x3241 + x3259;
        let x3261 = x1732 * k[17];
        let x3262 = x3227 + x3261;
        let x3263 = x3226 + x3262;
        let x3264 = 0.5 * x3263;
        let x3265 = x62 * k[21];
        let x3266 = x3264 + x3265;
        out[0] = 0.3;
        out[1] = 0.3;
        out[2] = 0.3;
        out[3] = x2950;
        out[4] = x2960;
        out[5] = x2970;
        out[6] = x2980;
        out[7] = x2986;
        out[8] = x2992;
        out[9] = x3000;
        out[10] = x3007;
        out[11] = x3015;
        out[12] = x3024;
        out[13] = x3032;
        out[14] = x3042;
        out[15] = x3047;
        out[16] = x3053;
        out[17] = x3060;
        out[18] = x3066;
        out[19] = 0.6;
        out[20] = 0.6;
        out[21] = 0.6;
        out[22] = x3150;
        out[23] = x3160;
        out[24] = x3170;
        out[25] = x3180;
        out[26] = x3186;
        out[27] = x3192;
        out[28] = x3200;
        out[29] = x3207;
        out[30] = x3215;
        out[31] = x3224;
        out[32] = x3232;
        out[33] = x3242;
        out[34] = x3247;
        out[35] = x3253;
        out[36] = x3260;
        out[37] = x3266;
        out[38] = 1.0;
        out[39] = 1.0;
        out[40] = 1.0;
        out[41] = x2163;
        out[42] = x2177;
        out[43] = x2191;
        out[44] = x2205;
        out[45] = x2215;
        out[46] = x2222;
        out[47] = x2232;
        out[48] = x2242;
        out[49] = x2247;
        out[50] = x2253;
        out[51] = x2257;
        out[52] = x2263;
        out[53] = x2266;
        out[54] = x2271;
        out[55] = x2274;
        out[56] = x2278;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 22] = k.try_into().expect("k must have 22 entries");
        let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 21] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
        let _ = t;
        force_part_0(k, q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(k: &[f64; 22], q: &[f64; 21], qd: &[f64; 21], out: &mut [f64; 21]) {
        let x338 = 2.0 * q[3];
        let x339 = 2.0 * q[4];
        let x340 = 2.0 * q[10];
        let x341 = 2.0 * q[11];
        let x342 = 2.0 * q[5];
        let x343 = 2.0 * q[12];
        let x344 = 2.0 * q[13];
        let x345 = 2.0 * q[6];
        let x456 = 2.0 * q[17];
        let x457 = 2.0 * q[20];
        let x615 = 2.0 * q[18];
        let x616 = 2.0 * q[19];
        let x677 = q[5] * qd[4];
        let x678 = q[4] * qd[5];
        let x681 = q[6] * qd[3];
        let x682 = q[3] * qd[6];
        let x687 = q[6] * qd[4];
        let x688 = q[4] * qd[6];
        let x691 = q[5] * qd[3];
        let x692 = q[3] * qd[5];
        let x697 = q[6] * qd[5];
        let x698 = q[5] * qd[6];
        let x701 = q[4] * qd[3];
        let x702 = q[3] * qd[4];
        let x720 = q[12] * qd[11];
        let x721 = q[11] * qd[12];
        let x724 = q[13] * qd[10];
        let x725 = q[10] * qd[13];
        let x730 = q[13] * qd[11];
        let x731 = q[11] * qd[13];
        let x734 = q[12] * qd[10];
        let x735 = q[10] * qd[12];
        let x740 = q[13] * qd[12];
        let x741 = q[12] * qd[13];
        let x744 = q[11] * qd[10];
        let x745 = q[10] * qd[11];
        let x760 = q[19] * qd[18];
        let x761 = q[18] * qd[19];
        let x764 = q[20] * qd[17];
        let x765 = q[17] * qd[20];
        let x768 = q[20] * qd[18];
        let x769 = q[18] * qd[20];
        let x772 = q[19] * qd[17];
        let x773 = q[17] * qd[19];
        let x778 = q[20] * qd[19];
        let x779 = q[19] * qd[20];
        let x782 = q[18] * qd[17];
        let x783 = q[17] * qd[18];
        let x906 = 2.0 * qd[3];
        let x907 = 2.0 * qd[4];
        let x908 = 2.0 * qd[10];
        let x909 = 2.0 * qd[11];
        let x910 = 2.0 * qd[5];
        let x911 = 2.0 * qd[12];
        let x912 = 2.0 * qd[13];
        let x913 = 2.0 * qd[6];
        let x914 = 2.0 * qd[17];
        let x915 = 2.0 * qd[20];
        let x916 = 2.0 * qd[18];
        let x917 = 2.0 * qd[19];
        let x937 = qd[4] * qd[5];
        let x940 = qd[3] * qd[6];
        let x945 = qd[4] * qd[6];
        let x948 = qd[3] * qd[5];
        let x974 = qd[11] * qd[12];
        let x977 = qd[10] * qd[13];
        let x982 = qd[11] * qd[13];
        let x985 = qd[10] * qd[12];
        let x1008 = qd[18] * qd[19];
        let x1011 = qd[17] * qd[20];
        let x1014 = qd[18] * qd[20];
        let x1017 = qd[17] * qd[19];
        let x1196 = x702 - x701;
        let x1197 = x697 + x1196;
        let x1198 = x1197 - x698;
        let x1199 = 2.0 * x1198;
        let x1202 = x687 + x691;
        let x1204 = x692 - x1202;
        let x1205 = x688 + x1204;
        let x1206 = 2.0 * x1205;
        let x1209 = x677 - x681;
        let x1210 = x1209 - x678;
        let x1211 = x682 + x1210;
        let x1212 = 2.0 * x1211;
        let x1233 = 2.0 * x1199;
        let x1235 = 2.0 * x1206;
        let x1237 = 2.0 * x1212;
        let x1477 = x945 + x948;
        let x1479 = x948 - x1477;
        let x1480 = x945 + x1479;
        let x1481 = 2.0 * x1480;
        let x1484 = x937 - x940;
        let x1485 = x1484 - x937;
        let x1486 = x940 + x1485;
        let x1487 = 2.0 * x1486;
        let x1488 = 2.0 * x1481;
        let x1489 = 2.0 * x1487;
        let x1490 = x907 * x1233;
        let x1492 = x910 * x1235;
        let x1493 = x342 * x1488;
        let x1494 = x1492 + x1493;
        let x1496 = x913 * x1237;
        let x1497 = x345 * x1489;
        let x1498 = x1496 + x1497;
        let x1504 = x906 * x1233;
        let x1506 = x913 * x1235;
        let x1507 = x345 * x1488;
        let x1508 = x1506 + x1507;
        let x1511 = x910 * x1237;
        let x1512 = x342 * x1489;
        let x1513 = x1511 + x1512;
        let x1518 = x913 * x1233;
        let x1520 = x906 * x1235;
        let x1521 = x338 * x1488;
        let x1522 = x1520 + x1521;
        let x1524 = x907 * x1237;
        let x1525 = x339 * x1489;
        let x1526 = x1524 + x1525;
        let x1532 = x910 * x1233;
        let x1535 = x907 * x1235;
        let x1536 = x339 * x1488;
        let x1537 = x1535 + x1536;
        let x1539 = x906 * x1237;
        let x1540 = x338 * x1489;
        let x1541 = x1539 + x1540;
        let x1546 = qd[3] * qd[3];
        let x1547 = qd[4] * qd[4];
        let x1548 = qd[5] * qd[5];
        let x1549 = qd[6] * qd[6];
        let x1550 = x1546 + x1547;
        let x1551 = x1548 + x1550;
        let x1552 = x1549 + x1551;
        let x1619 = x745 - x744;
        let x1620 = x740 + x1619;
        let x1621 = x1620 - x741;
        let x1622 = 2.0 * x1621;
        let x1625 = x730 + x734;
        let x1627 = x735 - x1625;
        let x1628 = x731 + x1627;
        let x1629 = 2.0 * x1628;
        let x1632 = x720 - x724;
        let x1633 = x1632 - x721;
        let x1634 = x725 + x1633;
        let x1635 = 2.0 * x1634;
        let x1656 = 2.0 * x1622;
        let x1658 = 2.0 * x1629;
        let x1660 = 2.0 * x1635;
        let x1897 = x982 + x985;
        let x1899 = x985 - x1897;
        let x1900 = x982 + x1899;
        let x1901 = 2.0 * x1900;
        let x1904 = x974 - x977;
        let x1905 = x1904 - x974;
        let x1906 = x977 + x1905;
        let x1907 = 2.0 * x1906;
        let x1908 = 2.0 * x1901;
        let x1909 = 2.0 * x1907;
        let x1910 = x909 * x1656;
        let x1912 = x911 * x1658;
        let x1913 = x343 * x1908;
        let x1914 = x1912 + x1913;
        let x1916 = x912 * x1660;
        let x1917 = x344 * x1909;
        let x1918 = x1916 + x1917;
        let x1924 = x908 * x1656;
        let x1926 = x912 * x1658;
        let x1927 = x344 * x1908;
        let x1928 = x1926 + x1927;
        let x1931 = x911 * x1660;
        let x1932 = x343 * x1909;
        let x1933 = x1931 + x1932;
        let x1938 = x912 * x1656;
        let x1940 = x908 * x1658;
        let x1941 = x340 * x1908;
        let x1942 = x1940 + x1941;
        let x1944 = x909 * x1660;
        let x1945 = x341 * x1909;
        let x1946 = x1944 + x1945;
        let x1952 = x911 * x1656;
        let x1955 = x909 * x1658;
        let x1956 = x341 * x1908;
        let x1957 = x1955 + x1956;
        let x1959 = x908 * x1660;
        let x1960 = x340 * x1909;
        let x1961 = x1959 + x1960;
        let x1966 = qd[10] * qd[10];
        let x1967 = qd[11] * qd[11];
        let x1968 = qd[12] * qd[12];
        let x1969 = qd[13] * qd[13];
        let x1970 = x1966 + x1967;
        let x1971 = x1968 + x1970;
        let x1972 = x1969 + x1971;
        let x2039 = x783 - x782;
        let x2040 = x778 + x2039;
        let x2041 = x2040 - x779;
        let x2042 = 2.0 * x2041;
        let x2045 = x768 + x772;
        let x2047 = x773 - x2045;
        let x2048 = x769 + x2047;
        let x2049 = 2.0 * x2048;
        let x2052 = x760 - x764;
        let x2053 = x2052 - x761;
        let x2054 = x765 + x2053;
        let x2055 = 2.0 * x2054;
        let x2072 = 2.0 * x2042;
        let x2074 = 2.0 * x2049;
        let x2076 = 2.0 * x2055;
        let x2281 = x1014 + x1017;
        let x2283 = x1017 - x2281;
        let x2284 = x1014 + x2283;
        let x2285 = 2.0 * x2284;
        let x2288 = x1008 - x1011;
        let x2289 = x2288 - x1008;
        let x2290 = x1011 + x2289;
        let x2291 = 2.0 * x2290;
        let x2292 = 2.0 * x2285;
        let x2293 = 2.0 * x2291;
        let x2294 = x916 * x2072;
        let x2295 = 0.001 * x2294;
        let x2296 = x917 * x2074;
        let x2297 = x616 * x2292;
        let x2298 = x2296 + x2297;
        let x2299 = 0.001 * x2298;
        let x2300 = x915 * x2076;
        let x2301 = x457 * x2293;
        let x2302 = x2300 + x2301;
        let x2303 = 0.001 * x2302;
        let x2304 = x2295 + x2299;
        let x2305 = x2303 + x2304;
        let x2306 = 0.5 * x2305;
        let x2308 = x914 * x2072;
        let x2309 = 0.001 * x2308;
        let x2310 = x915 * x2074;
        let x2311 = x457 * x2292;
        let x2312 = x2310 + x2311;
        let x2313 = 0.001 * x2312;
        let x2315 = x917 * x2076;
        let x2316 = x616 * x2293;
        let x2317 = x2315 + x2316;
        let x2318 = 0.001 * x2317;
        let x2319 = x2309 - x2313;
        let x2320 = x2318 + x2319;
        let x2321 = 0.5 * x2320;
        let x2322 = x915 * x2072;
        let x2323 = 0.001 * x2322;
        let x2324 = x914 * x2074;
        let x2325 = x456 * x2292;
        let x2326 = x2324 + x2325;
        let x2327 = 0.001 * x2326;
        let x2328 = x916 * x2076;
        let x2329 = x615 * x2293;
        let x2330 = x2328 + x2329;
        let x2331 = 0.001 * x2330;
        let x2333 = x2323 + x2327;
        let x2334 = x2333 - x2331;
        let x2335 = 0.5 * x2334;
        let x2336 = x917 * x2072;
        let x2337 = 0.001 * x2336;
        let x2339 = x916 * x2074;
        let x2340 = x615 * x2292;
        let x2341 = x2339 + x2340;
        let x2342 = 0.001 * x2341;
        let x2343 = x914 * x2076;
        let x2344 = x456 * x2293;
        let x2345 = x2343 + x2344;
        let x2346 = 0.001 * x2345;
        let x2347 = x2342 - x2337;
        let x2348 = x2346 + x2347;
        let x2349 = 0.5 * x2348;
        let x2350 = qd[17] * qd[17];
        let x2351 = qd[18] * qd[18];
        let x2352 = qd[19] * qd[19];
        let x2353 = qd[20] * qd[20];
        let x2354 = x2350 + x2351;
        let x2355 = x2352 + x2354;
        let x2356 = x2353 + x2355;
        let x2357 = 0.001 * x2296;
        let x2358 = 0.001 * x2300;
        let x2359 = x2295 + x2357;
        let x2360 = x2358 + x2359;
        let x2361 = 0.5 * x2360;
        let x2362 = x2306 + x2361;
        let x2363 = q[17] * 0.004;
        let x2364 = x2356 * x2363;
        let x2366 = x2362 - x2364;
        let x2373 = 0.001 * x2310;
        let x2375 = 0.001 * x2315;
        let x2377 = x2373 - x2309;
        let x2378 = x2377 - x2375;
        let x2379 = 0.5 * x2378;
        let x2381 = x2379 - x2321;
        let x2382 = q[18] * 0.004;
        let x2383 = x2356 * x2382;
        let x2385 = x2381 - x2383;
        let x2391 = 0.001 * x2324;
        let x2393 = 0.001 * x2328;
        let x2394 = x2323 + x2391;
        let x2396 = x2393 - x2394;
        let x2397 = 0.5 * x2396;
        let x2399 = x2397 - x2335;
        let x2400 = q[19] * 0.004;
        let x2401 = x2356 * x2400;
        let x2403 = x2399 - x2401;
        let x2407 = 0.001 * x2339;
        let x2410 = 0.001 * x2343;
        let x2412 = x2337 - x2407;
        let x2413 = x2412 - x2410;
        let x2414 = 0.5 * x2413;
        let x2416 = x2414 - x2349;
        let x2417 = q[20] * 0.004;
        let x2418 = x2356 * x2417;
        let x2420 = x2416 - x2418;
        let x3067 = x1490 * k[17];
        let x3068 = x1494 * k[18];
        let x3069 = x1498 * k[18];
        let x3070 = x3067 + x3068;
        let x3071 = x3069 + x3070;
        let x3072 = 0.5 * x3071;
        let x3073 = x1504 * k[17];
        let x3074 = x1508 * k[18];
        let x3076 = x1513 * k[18];
        let x3077 = x3073 - x3074;
        let x3078 = x3076 + x3077;
        let x3079 = 0.5 * x3078;
        let x3080 = x1518 * k[17];
        let x3081 = x1522 * k[18];
        let x3082 = x1526 * k[18];
        let x3084 = x3080 + x3081;
        let x3085 = x3084 - x3082;
        let x3086 = 0.5 * x3085;
        let x3087 = x1532 * k[17];
        let x3089 = x1537 * k[18];
        let x3090 = x1541 * k[18];
        let x3091 = x3089 - x3087;
        let x3092 = x3090 + x3091;
        let x3093 = 0.5 * x3092;
        let x3094 = x1492 * k[18];
        let x3095 = x1496 * k[18];
        let x3096 = x3067 + x3094;
        let x3097 = x3095 + x3096;
        let x3098 = 0.5 * x3097;
        let x3099 = x3072 + x3098;
        let x3100 = q[3] * k[20];
        let x3101 = x1552 * x3100;
        let x3103 = x3099 - x3101;
        let x3105 = x1506 * k[18];
        let x3106 = x1511 * k[18];
        let x3108 = x3105 - x3073;
        let x3109 = x3108 - x3106;
        let x3110 = 0.5 * x3109;
        let x3112 = x3110 - x3079;
        let x3113 = q[4] * k[20];
        let x3114 = x1552 * x3113;
        let x3116 = x3112 - x3114;
        let x3117 = x1520 * k[18];
        let x3118 = x1524 * k[18];
        let x3119 = x3080 + x3117;
        let x3121 = x3118 - x3119;
        let x3122 = 0.5 * x3121;
        let x3124 = x3122 - x3086;
        let x3125 = q[5] * k[20];
        let x3126 = x1552 * x3125;
        let x3128 = x3124 - x3126;
        let x3129 = x1535 * k[18];
        let x3131 = x1539 * k[18];
        let x3133 = x3087 - x3129;
        let x3134 = x3133 - x3131;
        let x3135 = 0.5 * x3134;
        let x3137 = x3135 - x3093;
        let x3138 = q[6] * k[20];
        let x3139 = x1552 * x3138;
        let x3141 = x3137 - x3139;
        let x3267 = x1910 * k[17];
        let x3268 = x1914 * k[19];
        let x3269 = x1918 * k[19];
        let x3270 = x3267 + x3268;
        let x3271 = x3269 + x3270;
        let x3272 = 0.5 * x3271;
        let x3273 = x1924 * k[17];
        let x3274 = x1928 * k[19];
        let x3276 = x1933 * k[19];
        let x3277 = x3273 - x3274;
        let x3278 = x3276 + x3277;
        let x3279 = 0.5 * x3278;
        let x3280 = x1938 * k[17];
        let x3281 = x1942 * k[19];
        let x3282 = x1946 * k[19];
        let x3284 = x3280 + x3281;
        let x3285 = x3284 - x3282;
        let x3286 = 0.5 * x3285;
        let x3287 = x1952 * k[17];
        let x3289 = x1957 * k[19];
        let x3290 = x1961 * k[19];
        let x3291 = x3289 - x3287;
        let x3292 = x3290 + x3291;
        let x3293 = 0.5 * x3292;
        let x3294 = x1912 * k[19];
        let x3295 = x1916 * k[19];
        let x3296 = x3267 + x3294;
        let x3297 = x3295 + x3296;
        let x3298 = 0.5 * x3297;
        let x3299 = x3272 + x3298;
        let x3300 = q[10] * k[21];
        let x3301 = x1972 * x3300;
        let x3303 = x3299 - x3301;
        let x3305 = x1926 * k[19];
        let x3306 = x1931 * k[19];
        let x3308 = x3305 - x3273;
        let x3309 = x3308 - x3306;
        let x3310 = 0.5 * x3309;
        let x3312 = x3310 - x3279;
        let x3313 = q[11] * k[21];
        let x3314 = x1972 * x3313;
        let x3316 = x3312 - x3314;
        let x3317 = x1940 * k[19];
        let x3318 = x1944 * k[19];
        let x3319 = x3280 + x3317;
        let x3321 = x3318 - x3319;
        let x3322 = 0.5 * x3321;
        let x3324 = x3322 - x3286;
        let x3325 = q[12] * k[21];
        let x3326 = x1972 * x3325;
        let x3328 = x3324 - x3326;
        let x3329 = x1955 * k[19];
        let x3331 = x1959 * k[19];
        let x3333 = x3287 - x3329;
        let x3334 = x3333 - x3331;
        let x3335 = 0.5 * x3334;
        let x3337 = x3335 - x3293;
        let x3338 = q[13] * k[21];
        let x3339 = x1972 * x3338;
        let x3341 = x3337 - x3339;
        out[0] = 0.0;
        out[1] = -2.943;
        out[2] = 0.0;
        out[3] = x3103;
        out[4] = x3116;
        out[5] = x3128;
        out[6] = x3141;
        out[7] = 0.0;
        out[8] = -5.886;
        out[9] = 0.0;
        out[10] = x3303;
        out[11] = x3316;
        out[12] = x3328;
        out[13] = x3341;
        out[14] = 0.0;
        out[15] = -9.81;
        out[16] = 0.0;
        out[17] = x2366;
        out[18] = x2385;
        out[19] = x2403;
        out[20] = x2420;
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
        let k: &[f64; 22] = k.try_into().expect("k must have 22 entries");
        let q: &[f64; 21] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 21] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 21] = phi.try_into().expect("phi must have 21 entries");
        let phi_q: &mut [f64; 109] = phi_q
            .try_into()
            .expect("phi_q must have 109 entries");
        let mass: &mut [f64; 57] = mass.try_into().expect("mass must have 57 entries");
        let force: &mut [f64; 21] = force
            .try_into()
            .expect("force must have 21 entries");
        let mut s = [0.0f64; 48];
        eval_newton_shared_0(k, q, qd, t, &mut s);
        eval_newton_part_0(k, q, t, &s, phi, phi_q, mass);
        eval_newton_part_1(k, q, qd, &s, mass, force);
        eval_newton_part_2(q, qd, &s, force);
    }
    #[inline(never)]
    fn eval_newton_shared_0(
        k: &[f64; 22],
        q: &[f64; 21],
        _qd: &[f64; 21],
        _t: f64,
        s: &mut [f64; 48],
    ) {
        let x60 = q[11] * q[11];
        s[0] = x60;
        let x61 = q[12] * q[12];
        s[1] = x61;
        let x62 = q[13] * q[13];
        s[2] = x62;
        let x72 = q[11] * q[12];
        s[3] = x72;
        let x74 = q[10] * q[13];
        s[4] = x74;
        let x79 = q[11] * q[13];
        s[5] = x79;
        let x81 = q[10] * q[12];
        s[6] = x81;
        let x85 = q[12] * q[13];
        s[7] = x85;
        let x87 = q[10] * q[11];
        s[8] = x87;
        let x103 = q[17] * q[17];
        s[9] = x103;
        let x104 = q[18] * q[18];
        s[10] = x104;
        let x105 = q[19] * q[19];
        s[11] = x105;
        let x106 = q[20] * q[20];
        s[12] = x106;
        let x116 = q[18] * q[19];
        s[13] = x116;
        let x118 = q[17] * q[20];
        s[14] = x118;
        let x123 = q[18] * q[20];
        s[15] = x123;
        let x125 = q[17] * q[19];
        s[16] = x125;
        let x129 = q[19] * q[20];
        s[17] = x129;
        let x131 = q[17] * q[18];
        s[18] = x131;
        let x338 = 2.0 * q[3];
        s[19] = x338;
        let x339 = 2.0 * q[4];
        s[20] = x339;
        let x340 = 2.0 * q[10];
        s[21] = x340;
        let x341 = 2.0 * q[11];
        s[22] = x341;
        let x342 = 2.0 * q[5];
        s[23] = x342;
        let x343 = 2.0 * q[12];
        s[24] = x343;
        let x344 = 2.0 * q[13];
        s[25] = x344;
        let x345 = 2.0 * q[6];
        s[26] = x345;
        let x452 = 2.0 * x340;
        s[27] = x452;
        let x456 = 2.0 * q[17];
        s[28] = x456;
        let x457 = 2.0 * q[20];
        s[29] = x457;
        let x516 = 2.0 * x341;
        s[30] = x516;
        let x554 = 2.0 * x343;
        s[31] = x554;
        let x588 = 2.0 * x344;
        s[32] = x588;
        let x615 = 2.0 * q[18];
        s[33] = x615;
        let x616 = 2.0 * q[19];
        s[34] = x616;
        let x617 = 2.0 * x456;
        s[35] = x617;
        let x634 = 2.0 * x457;
        s[36] = x634;
        let x1728 = x341 * x516;
        s[37] = x1728;
        let x1732 = x343 * x554;
        s[38] = x1732;
        let x1736 = x344 * x588;
        s[39] = x1736;
        let x1748 = x341 * x452;
        s[40] = x1748;
        let x1750 = x343 * x588;
        s[41] = x1750;
        let x1754 = x344 * x554;
        s[42] = x1754;
        let x3144 = x1732 * k[19];
        s[43] = x3144;
        let x3145 = x1736 * k[19];
        s[44] = x3145;
        let x3152 = x1750 * k[19];
        s[45] = x3152;
        let x3154 = x1754 * k[19];
        s[46] = x3154;
        let x3159 = x87 * k[21];
        s[47] = x3159;
    }
    #[inline(never)]
    fn eval_newton_part_0(
        k: &[f64; 22],
        q: &[f64; 21],
        t: f64,
        s: &[f64; 48],
        phi: &mut [f64; 21],
        phi_q: &mut [f64; 109],
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
        let x22 = x14 + x16;
        let x23 = 2.0 * x22;
        let x24 = x23 - 1.0;
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
        let x59 = q[10] * q[10];
        let x63 = x59 + s[0];
        let x64 = 2.0 * x63;
        let x65 = x64 - 1.0;
        let x66 = x59 + s[1];
        let x67 = 2.0 * x66;
        let x68 = x67 - 1.0;
        let x69 = x59 + s[2];
        let x70 = 2.0 * x69;
        let x71 = x70 - 1.0;
        let x73 = 2.0 * s[3];
        let x76 = 2.0 * s[4];
        let x78 = x73 - x76;
        let x80 = 2.0 * s[5];
        let x82 = 2.0 * s[6];
        let x83 = x80 + x82;
        let x84 = x73 + x76;
        let x86 = 2.0 * s[7];
        let x89 = 2.0 * s[8];
        let x91 = x86 - x89;
        let x94 = x80 - x82;
        let x95 = x86 + x89;
        let x107 = s[9] + s[10];
        let x113 = s[9] + s[12];
        let x114 = 2.0 * x113;
        let x115 = x114 - 1.0;
        let x117 = 2.0 * s[13];
        let x120 = 2.0 * s[14];
        let x124 = 2.0 * s[15];
        let x126 = 2.0 * s[16];
        let x127 = x124 + x126;
        let x128 = x117 + x120;
        let x130 = 2.0 * s[17];
        let x133 = 2.0 * s[18];
        let x135 = x130 - x133;
        let x138 = x124 - x126;
        let x139 = x130 + x133;
        let x323 = x5.sin();
        let x324 = x5.cos();
        let x329 = x16 + x18;
        let x330 = x17 + x329;
        let x331 = x330 - 1.0;
        let x332 = s[1] + x63;
        let x333 = s[2] + x332;
        let x334 = x333 - 1.0;
        let x335 = s[11] + x107;
        let x336 = s[12] + x335;
        let x337 = x336 - 1.0;
        let x346 = 2.0 * s[19];
        let x389 = 2.0 * s[20];
        let x414 = 2.0 * s[23];
        let x619 = -s[34];
        let x626 = -s[28];
        let x1306 = 2.0 * s[26];
        let x1308 = s[20] * x389;
        let x1312 = s[23] * x414;
        let x1316 = s[26] * x1306;
        let x1328 = s[20] * x346;
        let x1330 = s[23] * x1306;
        let x1334 = s[26] * x414;
        let x1342 = s[20] * x1306;
        let x1344 = s[23] * x346;
        let x1346 = s[26] * x389;
        let x1356 = s[20] * x414;
        let x1360 = s[23] * x389;
        let x1362 = s[26] * x346;
        let x1370 = s[19] * x389;
        let x1380 = s[19] * x346;
        let x1387 = s[19] * x1306;
        let x1397 = s[19] * x414;
        let x2423 = x21 * k[0];
        let x2424 = x34 * k[1];
        let x2425 = x2423 + x2424;
        let x2426 = x40 * k[0];
        let x2427 = x24 * k[1];
        let x2428 = x2426 + x2427;
        let x2429 = x50 * k[0];
        let x2430 = x51 * k[1];
        let x2431 = x2429 + x2430;
        let x2432 = q[0] + x2425;
        let x2433 = q[1] + x2428;
        let x2434 = q[2] + x2431;
        let x2437 = x21 * k[2];
        let x2438 = x34 * k[3];
        let x2439 = x2437 + x2438;
        let x2440 = x40 * k[2];
        let x2441 = x24 * k[3];
        let x2442 = x2440 + x2441;
        let x2444 = x39 * k[4];
        let x2445 = x47 * k[4];
        let x2446 = -x2432;
        let x2447 = -x2433;
        let x2448 = -x2434;
        let x2451 = x21 * k[5];
        let x2452 = x34 * k[6];
        let x2453 = x2451 + x2452;
        let x2454 = x40 * k[5];
        let x2455 = x24 * k[6];
        let x2456 = x2454 + x2455;
        let x2457 = x50 * k[5];
        let x2458 = x51 * k[6];
        let x2459 = x2457 + x2458;
        let x2460 = q[0] + x2453;
        let x2461 = q[1] + x2456;
        let x2462 = q[2] + x2459;
        let x2466 = x65 * k[7];
        let x2467 = x78 * k[8];
        let x2468 = x83 * k[9];
        let x2469 = x2466 + x2467;
        let x2470 = x2468 + x2469;
        let x2471 = x84 * k[7];
        let x2472 = x68 * k[8];
        let x2473 = x91 * k[9];
        let x2474 = x2471 + x2472;
        let x2475 = x2473 + x2474;
        let x2476 = x94 * k[7];
        let x2477 = x95 * k[8];
        let x2478 = x71 * k[9];
        let x2479 = x2476 + x2477;
        let x2480 = x2478 + x2479;
        let x2481 = q[7] + x2470;
        let x2482 = q[8] + x2475;
        let x2483 = q[9] + x2480;
        let x2485 = x2460 - x2481;
        let x2487 = x2461 - x2482;
        let x2489 = x2462 - x2483;
        let x2493 = x65 * k[10];
        let x2494 = x78 * k[11];
        let x2495 = x83 * k[12];
        let x2496 = x2493 + x2494;
        let x2497 = x2495 + x2496;
        let x2498 = x84 * k[10];
        let x2499 = x68 * k[11];
        let x2500 = x91 * k[12];
        let x2501 = x2498 + x2499;
        let x2502 = x2500 + x2501;
        let x2503 = x94 * k[10];
        let x2504 = x95 * k[11];
        let x2505 = x71 * k[12];
        let x2506 = x2503 + x2504;
        let x2507 = x2505 + x2506;
        let x2508 = q[7] + x2497;
        let x2509 = q[8] + x2502;
        let x2510 = q[9] + x2507;
        let x2513 = x65 * k[13];
        let x2514 = x78 * k[14];
        let x2515 = x2513 + x2514;
        let x2516 = x84 * k[13];
        let x2517 = x68 * k[14];
        let x2518 = x2516 + x2517;
        let x2519 = x94 * k[13];
        let x2520 = x95 * k[14];
        let x2521 = x2519 + x2520;
        let x2523 = q[14] - x2508;
        let x2525 = q[15] - x2509;
        let x2527 = q[16] - x2510;
        let x2528 = x127 * x2515;
        let x2529 = x135 * x2518;
        let x2530 = x115 * x2521;
        let x2531 = x2528 + x2529;
        let x2532 = x2530 + x2531;
        let x2534 = q[15] + k[15];
        let x2536 = q[16] + k[16];
        let x2537 = x323 * x2439;
        let x2538 = x324 * x2442;
        let x2540 = x2537 - x2538;
        let x2541 = x346 * k[0];
        let x2542 = s[26] * k[1];
        let x2544 = x2541 - x2542;
        let x2545 = s[26] * k[0];
        let x2546 = x346 * k[1];
        let x2547 = x2545 + x2546;
        let x2548 = s[23] * k[0];
        let x2549 = -x2548;
        let x2550 = s[20] * k[1];
        let x2551 = x2550 - x2548;
        let x2552 = x346 * k[2];
        let x2553 = s[26] * k[3];
        let x2555 = x2552 - x2553;
        let x2556 = s[26] * k[2];
        let x2557 = x346 * k[3];
        let x2558 = x2556 + x2557;
        let x2559 = s[23] * k[4];
        let x2560 = s[20] * k[4];
        let x2561 = -x2560;
        let x2562 = -x2544;
        let x2563 = -x2547;
        let x2564 = -x2551;
        let x2565 = x346 * k[5];
        let x2566 = s[26] * k[6];
        let x2568 = x2565 - x2566;
        let x2569 = s[26] * k[5];
        let x2570 = x346 * k[6];
        let x2571 = x2569 + x2570;
        let x2572 = s[23] * k[5];
        let x2574 = s[20] * k[6];
        let x2575 = x2574 - x2572;
        let x2576 = x323 * x2555;
        let x2577 = x324 * x2558;
        let x2579 = x2576 - x2577;
        let x2580 = x389 * k[0];
        let x2581 = s[23] * k[1];
        let x2582 = x2580 + x2581;
        let x2583 = s[19] * k[1];
        let x2584 = x2545 + x2583;
        let x2585 = x389 * k[2];
        let x2586 = s[23] * k[3];
        let x2587 = x2585 + x2586;
        let x2588 = s[23] * k[2];
        let x2589 = s[26] * k[4];
        let x2590 = s[19] * k[4];
        let x2591 = -x2590;
        let x2592 = -x2582;
        let x2593 = -x2584;
        let x2594 = x389 * k[5];
        let x2595 = s[23] * k[6];
        let x2596 = x2594 + x2595;
        let x2597 = s[19] * k[6];
        let x2598 = x2569 + x2597;
        let x2599 = x323 * x2587;
        let x2600 = x324 * x2588;
        let x2602 = x2599 - x2600;
        let x2603 = s[20] * k[0];
        let x2604 = x414 * k[1];
        let x2605 = x2603 + x2604;
        let x2606 = s[19] * k[0];
        let x2607 = -x2606;
        let x2608 = x2542 - x2606;
        let x2609 = s[20] * k[3];
        let x2610 = s[20] * k[2];
        let x2611 = x414 * k[3];
        let x2612 = x2610 + x2611;
        let x2613 = -x2550;
        let x2614 = -x2605;
        let x2615 = -x2608;
        let x2616 = s[20] * k[5];
        let x2617 = x414 * k[6];
        let x2618 = x2616 + x2617;
        let x2619 = s[19] * k[5];
        let x2621 = x2566 - x2619;
        let x2622 = x323 * x2609;
        let x2623 = x324 * x2612;
        let x2625 = x2622 - x2623;
        let x2626 = x2581 + x2603;
        let x2627 = s[19] * k[3];
        let x2628 = s[19] * k[2];
        let x2629 = -x2626;
        let x2630 = -x2597;
        let x2631 = x2595 + x2616;
        let x2632 = x323 * x2627;
        let x2633 = x324 * x2628;
        let x2634 = x2632 + x2633;
        let x2635 = -x2634;
        let x2636 = s[27] * k[7];
        let x2637 = s[25] * k[8];
        let x2639 = s[24] * k[9];
        let x2640 = x2636 - x2637;
        let x2641 = x2639 + x2640;
        let x2642 = s[25] * k[7];
        let x2643 = s[27] * k[8];
        let x2644 = s[22] * k[9];
        let x2646 = x2642 + x2643;
        let x2647 = x2646 - x2644;
        let x2648 = s[24] * k[7];
        let x2650 = s[22] * k[8];
        let x2651 = s[27] * k[9];
        let x2652 = x2650 - x2648;
        let x2653 = x2651 + x2652;
        let x2654 = -x2641;
        let x2655 = -x2647;
        let x2656 = -x2653;
        let x2657 = s[27] * k[10];
        let x2658 = s[25] * k[11];
        let x2660 = s[24] * k[12];
        let x2661 = x2657 - x2658;
        let x2662 = x2660 + x2661;
        let x2663 = s[25] * k[10];
        let x2664 = s[27] * k[11];
        let x2665 = s[22] * k[12];
        let x2667 = x2663 + x2664;
        let x2668 = x2667 - x2665;
        let x2669 = s[24] * k[10];
        let x2671 = s[22] * k[11];
        let x2672 = s[27] * k[12];
        let x2673 = x2671 - x2669;
        let x2674 = x2672 + x2673;
        let x2675 = s[27] * k[13];
        let x2676 = s[25] * k[14];
        let x2678 = x2675 - x2676;
        let x2679 = s[25] * k[13];
        let x2680 = s[27] * k[14];
        let x2681 = x2679 + x2680;
        let x2682 = s[24] * k[13];
        let x2684 = s[22] * k[14];
        let x2685 = x2684 - x2682;
        let x2686 = -x2662;
        let x2687 = -x2668;
        let x2688 = -x2674;
        let x2689 = x127 * x2678;
        let x2690 = x135 * x2681;
        let x2691 = x115 * x2685;
        let x2692 = x2689 + x2690;
        let x2693 = x2691 + x2692;
        let x2694 = s[30] * k[7];
        let x2695 = s[24] * k[8];
        let x2696 = s[25] * k[9];
        let x2697 = x2694 + x2695;
        let x2698 = x2696 + x2697;
        let x2699 = s[21] * k[9];
        let x2701 = x2648 - x2699;
        let x2702 = s[21] * k[8];
        let x2703 = x2642 + x2702;
        let x2704 = -x2698;
        let x2705 = -x2701;
        let x2706 = -x2703;
        let x2707 = s[30] * k[10];
        let x2708 = s[24] * k[11];
        let x2709 = s[25] * k[12];
        let x2710 = x2707 + x2708;
        let x2711 = x2709 + x2710;
        let x2712 = s[21] * k[12];
        let x2714 = x2669 - x2712;
        let x2715 = s[21] * k[11];
        let x2716 = x2663 + x2715;
        let x2717 = s[30] * k[13];
        let x2718 = s[24] * k[14];
        let x2719 = x2717 + x2718;
        let x2720 = s[21] * k[14];
        let x2721 = x2679 + x2720;
        let x2722 = -x2711;
        let x2723 = -x2714;
        let x2724 = -x2716;
        let x2725 = x127 * x2719;
        let x2726 = x135 * x2682;
        let x2727 = x115 * x2721;
        let x2728 = x2725 + x2726;
        let x2729 = x2727 + x2728;
        let x2730 = x2650 + x2699;
        let x2731 = s[22] * k[7];
        let x2732 = s[31] * k[8];
        let x2733 = x2731 + x2732;
        let x2734 = x2696 + x2733;
        let x2735 = s[21] * k[7];
        let x2737 = x2637 - x2735;
        let x2738 = -x2730;
        let x2739 = -x2734;
        let x2740 = -x2737;
        let x2741 = x2671 + x2712;
        let x2742 = s[22] * k[10];
        let x2743 = s[31] * k[11];
        let x2744 = x2742 + x2743;
        let x2745 = x2709 + x2744;
        let x2746 = s[21] * k[10];
        let x2748 = x2658 - x2746;
        let x2749 = s[22] * k[13];
        let x2750 = s[31] * k[14];
        let x2751 = x2749 + x2750;
        let x2752 = s[21] * k[13];
        let x2754 = x2676 - x2752;
        let x2755 = -x2741;
        let x2756 = -x2745;
        let x2757 = -x2748;
        let x2758 = x127 * x2684;
        let x2759 = x135 * x2751;
        let x2760 = x115 * x2754;
        let x2761 = x2758 + x2759;
        let x2762 = x2760 + x2761;
        let x2764 = x2644 - x2702;
        let x2765 = x2639 + x2735;
        let x2766 = s[32] * k[9];
        let x2767 = x2695 + x2731;
        let x2768 = x2766 + x2767;
        let x2769 = -x2764;
        let x2770 = -x2765;
        let x2771 = -x2768;
        let x2773 = x2665 - x2715;
        let x2774 = x2660 + x2746;
        let x2775 = s[32] * k[12];
        let x2776 = x2708 + x2742;
        let x2777 = x2775 + x2776;
        let x2778 = x2718 + x2749;
        let x2779 = -x2773;
        let x2780 = -x2774;
        let x2781 = -x2777;
        let x2782 = x127 * x2720;
        let x2784 = x135 * x2752;
        let x2785 = x115 * x2778;
        let x2786 = x2784 - x2782;
        let x2787 = x2785 + x2786;
        let x2788 = s[34] * x2515;
        let x2789 = s[33] * x2518;
        let x2791 = s[35] * x2521;
        let x2792 = x2788 - x2789;
        let x2793 = x2791 + x2792;
        let x2794 = s[29] * x2515;
        let x2795 = s[28] * x2518;
        let x2797 = x2794 - x2795;
        let x2798 = s[28] * x2515;
        let x2799 = s[29] * x2518;
        let x2800 = x2798 + x2799;
        let x2801 = s[33] * x2515;
        let x2802 = s[34] * x2518;
        let x2803 = s[36] * x2521;
        let x2804 = x2801 + x2802;
        let x2805 = x2803 + x2804;
        let x2943 = x1308 * k[17];
        let x2944 = x1312 * k[18];
        let x2945 = x1316 * k[18];
        let x2946 = x2943 + x2944;
        let x2947 = x2945 + x2946;
        let x2948 = 0.5 * x2947;
        let x2949 = x14 * k[20];
        let x2950 = x2948 + x2949;
        let x2951 = x1328 * k[17];
        let x2952 = x1330 * k[18];
        let x2954 = x1334 * k[18];
        let x2955 = x2951 - x2952;
        let x2956 = x2954 + x2955;
        let x2957 = 0.5 * x2956;
        let x2959 = x43 * k[20];
        let x2960 = x2959 - x2957;
        let x2961 = x1342 * k[17];
        let x2962 = x1344 * k[18];
        let x2963 = x1346 * k[18];
        let x2965 = x2961 + x2962;
        let x2966 = x2965 - x2963;
        let x2967 = 0.5 * x2966;
        let x2969 = x37 * k[20];
        let x2970 = x2969 - x2967;
        let x2971 = x1356 * k[17];
        let x2973 = x1360 * k[18];
        let x2974 = x1362 * k[18];
        let x2975 = x2973 - x2971;
        let x2976 = x2974 + x2975;
        let x2977 = 0.5 * x2976;
        let x2979 = x30 * k[20];
        let x2980 = x2979 - x2977;
        let x2981 = x1370 * k[17];
        let x2983 = x2954 - x2981;
        let x2984 = x2983 - x2952;
        let x2985 = 0.5 * x2984;
        let x2986 = x2959 + x2985;
        let x2987 = x1380 * k[17];
        let x2988 = x2945 + x2987;
        let x2989 = x2944 + x2988;
        let x2990 = 0.5 * x2989;
        let x2991 = x15 * k[20];
        let x2992 = x2990 + x2991;
        let x2993 = x1387 * k[17];
        let x2996 = x2993 - x2974;
        let x2997 = x2996 - x2973;
        let x2998 = 0.5 * x2997;
        let x2999 = x28 * k[20];
        let x3000 = x2998 + x2999;
        let x3001 = x1397 * k[17];
        let x3002 = x2963 + x3001;
        let x3004 = x2962 - x3002;
        let x3005 = 0.5 * x3004;
        let x3006 = x35 * k[20];
        let x3007 = x3005 + x3006;
        let x3008 = x1346 * k[17];
        let x3009 = x1397 * k[18];
        let x3010 = x1342 * k[18];
        let x3011 = x3008 + x3009;
        let x3013 = x3010 - x3011;
        let x3014 = 0.5 * x3013;
        let x3015 = x2969 + x3014;
        let x3016 = x1362 * k[17];
        let x3017 = x1387 * k[18];
        let x3019 = x1356 * k[18];
        let x3021 = x3016 - x3017;
        let x3022 = x3021 - x3019;
        let x3023 = 0.5 * x3022;
        let x3024 = x2999 + x3023;
        let x3025 = x1316 * k[17];
        let x3026 = x1380 * k[18];
        let x3027 = x1308 * k[18];
        let x3028 = x3025 + x3026;
        let x3029 = x3027 + x3028;
        let x3030 = 0.5 * x3029;
        let x3031 = x16 * k[20];
        let x3032 = x3030 + x3031;
        let x3033 = x1334 * k[17];
        let x3035 = x1370 * k[18];
        let x3036 = x1328 * k[18];
        let x3038 = x3035 - x3033;
        let x3039 = x3038 - x3036;
        let x3040 = 0.5 * x3039;
        let x3041 = x41 * k[20];
        let x3042 = x3040 + x3041;
        let x3043 = x1360 * k[17];
        let x3044 = x3043 - x3019;
        let x3045 = x3044 - x3017;
        let x3046 = 0.5 * x3045;
        let x3047 = x2979 + x3046;
        let x3048 = x1344 * k[17];
        let x3049 = x3010 + x3048;
        let x3051 = x3009 - x3049;
        let x3052 = 0.5 * x3051;
        let x3053 = x3006 + x3052;
        let x3054 = x1330 * k[17];
        let x3057 = x3036 - x3054;
        let x3058 = x3057 - x3035;
        let x3059 = 0.5 * x3058;
        let x3060 = x3041 + x3059;
        let x3061 = x1312 * k[17];
        let x3062 = x3027 + x3061;
        let x3063 = x3026 + x3062;
        let x3064 = 0.5 * x3063;
        let x3065 = x17 * k[20];
        let x3066 = x3064 + x3065;
        let x3143 = s[37] * k[17];
        let x3146 = x3143 + s[43];
        let x3147 = s[44] + x3146;
        let x3148 = 0.5 * x3147;
        let x3149 = x59 * k[21];
        let x3150 = x3148 + x3149;
        let x3151 = s[40] * k[17];
        let x3155 = x3151 - s[45];
        let x3156 = s[46] + x3155;
        let x3157 = 0.5 * x3156;
        let x3160 = s[47] - x3157;
        phi[0] = x2446;
        phi_q[0] = -1.0;
        phi_q[1] = x2562;
        phi_q[2] = x2592;
        phi_q[3] = x2613;
        phi_q[4] = x2583;
        phi[1] = x2447;
        phi_q[5] = -1.0;
        phi_q[6] = x2563;
        phi_q[7] = x2549;
        phi_q[8] = x2614;
        phi_q[9] = x2607;
        phi[2] = x2448;
        phi_q[10] = -1.0;
        phi_q[11] = x2564;
        phi_q[12] = x2593;
        phi_q[13] = x2615;
        phi_q[14] = x2629;
        phi[3] = x2444;
        phi_q[15] = x2559;
        phi_q[16] = x2589;
        phi_q[17] = x2590;
        phi_q[18] = x2560;
        phi[4] = x2445;
        phi_q[19] = x2561;
        phi_q[20] = x2591;
        phi_q[21] = x2589;
        phi_q[22] = x2559;
        phi[5] = x2485;
        phi_q[23] = 1.0;
        phi_q[24] = x2568;
        phi_q[25] = x2596;
        phi_q[26] = x2574;
        phi_q[27] = x2630;
        phi_q[28] = -1.0;
        phi_q[29] = x2654;
        phi_q[30] = x2704;
        phi_q[31] = x2738;
        phi_q[32] = x2769;
        phi[6] = x2487;
        phi_q[33] = 1.0;
        phi_q[34] = x2571;
        phi_q[35] = x2572;
        phi_q[36] = x2618;
        phi_q[37] = x2619;
        phi_q[38] = -1.0;
        phi_q[39] = x2655;
        phi_q[40] = x2705;
        phi_q[41] = x2739;
        phi_q[42] = x2770;
        phi[7] = x2489;
        phi_q[43] = 1.0;
        phi_q[44] = x2575;
        phi_q[45] = x2598;
        phi_q[46] = x2621;
        phi_q[47] = x2631;
        phi_q[48] = -1.0;
        phi_q[49] = x2656;
        phi_q[50] = x2706;
        phi_q[51] = x2740;
        phi_q[52] = x2771;
        phi[8] = x2523;
        phi_q[53] = -1.0;
        phi_q[54] = x2686;
        phi_q[55] = x2722;
        phi_q[56] = x2755;
        phi_q[57] = x2779;
        phi_q[58] = 1.0;
        phi[9] = x2525;
        phi_q[59] = -1.0;
        phi_q[60] = x2687;
        phi_q[61] = x2723;
        phi_q[62] = x2756;
        phi_q[63] = x2780;
        phi_q[64] = 1.0;
        phi[10] = x2527;
        phi_q[65] = -1.0;
        phi_q[66] = x2688;
        phi_q[67] = x2724;
        phi_q[68] = x2757;
        phi_q[69] = x2781;
        phi_q[70] = 1.0;
        phi[11] = x2532;
        phi_q[71] = x2693;
        phi_q[72] = x2729;
        phi_q[73] = x2762;
        phi_q[74] = x2787;
        phi_q[75] = x2793;
        phi_q[76] = x2797;
        phi_q[77] = x2800;
        phi_q[78] = x2805;
        phi[12] = x128;
        phi_q[79] = s[29];
        phi_q[80] = s[34];
        phi_q[81] = s[33];
        phi_q[82] = s[28];
        phi[13] = x138;
        phi_q[83] = x619;
        phi_q[84] = s[29];
        phi_q[85] = x626;
        phi_q[86] = s[33];
        phi[14] = x2534;
        phi_q[87] = 1.0;
        phi[15] = x2536;
        phi_q[88] = 1.0;
        phi[16] = x139;
        phi_q[89] = s[33];
        phi_q[90] = s[28];
        phi_q[91] = s[29];
        phi_q[92] = s[34];
        phi[17] = x2540;
        phi_q[93] = x2579;
        phi_q[94] = x2602;
        phi_q[95] = x2625;
        phi_q[96] = x2635;
        phi[18] = x331;
        phi_q[97] = s[19];
        phi_q[98] = s[20];
        phi_q[99] = s[23];
        phi_q[100] = s[26];
        phi[19] = x334;
        phi_q[101] = s[21];
        phi_q[102] = s[22];
        phi_q[103] = s[24];
        phi_q[104] = s[25];
        phi[20] = x337;
        phi_q[105] = s[28];
        phi_q[106] = s[33];
        phi_q[107] = s[34];
        phi_q[108] = s[29];
        mass[0] = 0.3;
        mass[1] = 0.3;
        mass[2] = 0.3;
        mass[3] = x2950;
        mass[4] = x2960;
        mass[5] = x2970;
        mass[6] = x2980;
        mass[7] = x2986;
        mass[8] = x2992;
        mass[9] = x3000;
        mass[10] = x3007;
        mass[11] = x3015;
        mass[12] = x3024;
        mass[13] = x3032;
        mass[14] = x3042;
        mass[15] = x3047;
        mass[16] = x3053;
        mass[17] = x3060;
        mass[18] = x3066;
        mass[19] = 0.6;
        mass[20] = 0.6;
        mass[21] = 0.6;
        mass[22] = x3150;
        mass[23] = x3160;
    }
    #[inline(never)]
    fn eval_newton_part_1(
        k: &[f64; 22],
        q: &[f64; 21],
        qd: &[f64; 21],
        s: &[f64; 48],
        mass: &mut [f64; 57],
        force: &mut [f64; 21],
    ) {
        let x677 = q[5] * qd[4];
        let x678 = q[4] * qd[5];
        let x681 = q[6] * qd[3];
        let x682 = q[3] * qd[6];
        let x687 = q[6] * qd[4];
        let x688 = q[4] * qd[6];
        let x691 = q[5] * qd[3];
        let x692 = q[3] * qd[5];
        let x697 = q[6] * qd[5];
        let x698 = q[5] * qd[6];
        let x701 = q[4] * qd[3];
        let x702 = q[3] * qd[4];
        let x720 = q[12] * qd[11];
        let x721 = q[11] * qd[12];
        let x724 = q[13] * qd[10];
        let x725 = q[10] * qd[13];
        let x730 = q[13] * qd[11];
        let x731 = q[11] * qd[13];
        let x734 = q[12] * qd[10];
        let x735 = q[10] * qd[12];
        let x740 = q[13] * qd[12];
        let x741 = q[12] * qd[13];
        let x744 = q[11] * qd[10];
        let x745 = q[10] * qd[11];
        let x906 = 2.0 * qd[3];
        let x907 = 2.0 * qd[4];
        let x908 = 2.0 * qd[10];
        let x909 = 2.0 * qd[11];
        let x910 = 2.0 * qd[5];
        let x911 = 2.0 * qd[12];
        let x912 = 2.0 * qd[13];
        let x913 = 2.0 * qd[6];
        let x937 = qd[4] * qd[5];
        let x940 = qd[3] * qd[6];
        let x945 = qd[4] * qd[6];
        let x948 = qd[3] * qd[5];
        let x974 = qd[11] * qd[12];
        let x977 = qd[10] * qd[13];
        let x982 = qd[11] * qd[13];
        let x985 = qd[10] * qd[12];
        let x1196 = x702 - x701;
        let x1197 = x697 + x1196;
        let x1198 = x1197 - x698;
        let x1199 = 2.0 * x1198;
        let x1202 = x687 + x691;
        let x1204 = x692 - x1202;
        let x1205 = x688 + x1204;
        let x1206 = 2.0 * x1205;
        let x1209 = x677 - x681;
        let x1210 = x1209 - x678;
        let x1211 = x682 + x1210;
        let x1212 = 2.0 * x1211;
        let x1233 = 2.0 * x1199;
        let x1235 = 2.0 * x1206;
        let x1237 = 2.0 * x1212;
        let x1477 = x945 + x948;
        let x1479 = x948 - x1477;
        let x1480 = x945 + x1479;
        let x1481 = 2.0 * x1480;
        let x1484 = x937 - x940;
        let x1485 = x1484 - x937;
        let x1486 = x940 + x1485;
        let x1487 = 2.0 * x1486;
        let x1488 = 2.0 * x1481;
        let x1489 = 2.0 * x1487;
        let x1490 = x907 * x1233;
        let x1492 = x910 * x1235;
        let x1493 = s[23] * x1488;
        let x1494 = x1492 + x1493;
        let x1496 = x913 * x1237;
        let x1497 = s[26] * x1489;
        let x1498 = x1496 + x1497;
        let x1504 = x906 * x1233;
        let x1506 = x913 * x1235;
        let x1507 = s[26] * x1488;
        let x1508 = x1506 + x1507;
        let x1511 = x910 * x1237;
        let x1512 = s[23] * x1489;
        let x1513 = x1511 + x1512;
        let x1518 = x913 * x1233;
        let x1520 = x906 * x1235;
        let x1521 = s[19] * x1488;
        let x1522 = x1520 + x1521;
        let x1524 = x907 * x1237;
        let x1525 = s[20] * x1489;
        let x1526 = x1524 + x1525;
        let x1532 = x910 * x1233;
        let x1535 = x907 * x1235;
        let x1536 = s[20] * x1488;
        let x1537 = x1535 + x1536;
        let x1539 = x906 * x1237;
        let x1540 = s[19] * x1489;
        let x1541 = x1539 + x1540;
        let x1546 = qd[3] * qd[3];
        let x1547 = qd[4] * qd[4];
        let x1548 = qd[5] * qd[5];
        let x1549 = qd[6] * qd[6];
        let x1550 = x1546 + x1547;
        let x1551 = x1548 + x1550;
        let x1552 = x1549 + x1551;
        let x1619 = x745 - x744;
        let x1620 = x740 + x1619;
        let x1621 = x1620 - x741;
        let x1622 = 2.0 * x1621;
        let x1625 = x730 + x734;
        let x1627 = x735 - x1625;
        let x1628 = x731 + x1627;
        let x1629 = 2.0 * x1628;
        let x1632 = x720 - x724;
        let x1633 = x1632 - x721;
        let x1634 = x725 + x1633;
        let x1635 = 2.0 * x1634;
        let x1656 = 2.0 * x1622;
        let x1658 = 2.0 * x1629;
        let x1660 = 2.0 * x1635;
        let x1762 = s[22] * s[32];
        let x1764 = s[24] * s[27];
        let x1766 = s[25] * s[30];
        let x1776 = s[22] * s[31];
        let x1780 = s[24] * s[30];
        let x1782 = s[25] * s[27];
        let x1790 = s[21] * s[30];
        let x1800 = s[21] * s[27];
        let x1807 = s[21] * s[32];
        let x1817 = s[21] * s[31];
        let x1897 = x982 + x985;
        let x1899 = x985 - x1897;
        let x1900 = x982 + x1899;
        let x1901 = 2.0 * x1900;
        let x1904 = x974 - x977;
        let x1905 = x1904 - x974;
        let x1906 = x977 + x1905;
        let x1907 = 2.0 * x1906;
        let x1908 = 2.0 * x1901;
        let x1909 = 2.0 * x1907;
        let x1910 = x909 * x1656;
        let x1912 = x911 * x1658;
        let x1913 = s[24] * x1908;
        let x1914 = x1912 + x1913;
        let x1916 = x912 * x1660;
        let x1917 = s[25] * x1909;
        let x1918 = x1916 + x1917;
        let x1924 = x908 * x1656;
        let x1926 = x912 * x1658;
        let x1927 = s[25] * x1908;
        let x1928 = x1926 + x1927;
        let x1931 = x911 * x1660;
        let x1932 = s[24] * x1909;
        let x1933 = x1931 + x1932;
        let x1938 = x912 * x1656;
        let x1940 = x908 * x1658;
        let x1941 = s[21] * x1908;
        let x1942 = x1940 + x1941;
        let x1944 = x909 * x1660;
        let x1945 = s[22] * x1909;
        let x1946 = x1944 + x1945;
        let x1952 = x911 * x1656;
        let x1955 = x909 * x1658;
        let x1956 = s[22] * x1908;
        let x1957 = x1955 + x1956;
        let x1959 = x908 * x1660;
        let x1960 = s[21] * x1909;
        let x1961 = x1959 + x1960;
        let x1966 = qd[10] * qd[10];
        let x1967 = qd[11] * qd[11];
        let x1968 = qd[12] * qd[12];
        let x1969 = qd[13] * qd[13];
        let x1970 = x1966 + x1967;
        let x1971 = x1968 + x1970;
        let x1972 = x1969 + x1971;
        let x2139 = 2.0 * s[33];
        let x2141 = 2.0 * s[34];
        let x2144 = s[33] * x2139;
        let x2146 = 0.001 * x2144;
        let x2148 = s[34] * x2141;
        let x2150 = 0.001 * x2148;
        let x2152 = s[29] * s[36];
        let x2154 = 0.001 * x2152;
        let x2156 = x2146 + x2150;
        let x2158 = x2154 + x2156;
        let x2160 = 0.5 * x2158;
        let x2162 = s[9] * 0.004;
        let x2163 = x2160 + x2162;
        let x2164 = s[33] * s[35];
        let x2165 = 0.001 * x2164;
        let x2166 = s[34] * s[36];
        let x2168 = 0.001 * x2166;
        let x2170 = s[29] * x2141;
        let x2171 = 0.001 * x2170;
        let x2172 = x2165 - x2168;
        let x2173 = x2171 + x2172;
        let x2174 = 0.5 * x2173;
        let x2176 = s[18] * 0.004;
        let x2177 = x2176 - x2174;
        let x2178 = s[33] * s[36];
        let x2179 = 0.001 * x2178;
        let x2180 = s[34] * s[35];
        let x2181 = 0.001 * x2180;
        let x2182 = s[29] * x2139;
        let x2184 = 0.001 * x2182;
        let x2186 = x2179 + x2181;
        let x2187 = x2186 - x2184;
        let x2188 = 0.5 * x2187;
        let x2190 = s[16] * 0.004;
        let x2191 = x2190 - x2188;
        let x2192 = s[33] * x2141;
        let x2194 = 0.001 * x2192;
        let x2196 = s[34] * x2139;
        let x2197 = 0.001 * x2196;
        let x2198 = s[29] * s[35];
        let x2199 = 0.001 * x2198;
        let x2200 = x2197 - x2194;
        let x2201 = x2199 + x2200;
        let x2202 = 0.5 * x2201;
        let x2204 = s[14] * 0.004;
        let x2205 = x2204 - x2202;
        let x2206 = s[28] * x2139;
        let x2208 = 0.001 * x2206;
        let x2212 = x2171 - x2208;
        let x2213 = x2212 - x2168;
        let x2214 = 0.5 * x2213;
        let x2215 = x2176 + x2214;
        let x2216 = s[28] * s[35];
        let x2217 = 0.001 * x2216;
        let x2218 = x2154 + x2217;
        let x2219 = x2150 + x2218;
        let x2220 = 0.5 * x2219;
        let x2221 = s[10] * 0.004;
        let x2222 = x2220 + x2221;
        let x2223 = s[28] * s[36];
        let x2224 = 0.001 * x2223;
        let x2228 = x2224 - x2199;
        let x2229 = x2228 - x2197;
        let x2230 = 0.5 * x2229;
        let x2231 = s[13] * 0.004;
        let x2232 = x2230 + x2231;
        let x2233 = s[28] * x2141;
        let x2235 = 0.001 * x2233;
        let x2237 = x2184 + x2235;
        let x2239 = x2181 - x2237;
        let x2240 = 0.5 * x2239;
        let x2241 = s[15] * 0.004;
        let x2242 = x2240 + x2241;
        let x2245 = x2179 - x2237;
        let x2246 = 0.5 * x2245;
        let x2247 = x2190 + x2246;
        let x2250 = x2199 - x2224;
        let x2251 = x2250 - x2194;
        let x2252 = 0.5 * x2251;
        let x2253 = x2231 + x2252;
        let x2254 = x2146 + x2218;
        let x2255 = 0.5 * x2254;
        let x2256 = s[11] * 0.004;
        let x2257 = x2255 + x2256;
        let x2259 = x2208 - x2171;
        let x2260 = x2259 - x2165;
        let x2261 = 0.5 * x2260;
        let x2262 = s[17] * 0.004;
        let x2263 = x2261 + x2262;
        let x2264 = x2200 - x2224;
        let x2265 = 0.5 * x2264;
        let x2266 = x2204 + x2265;
        let x2269 = x2235 - x2186;
        let x2270 = 0.5 * x2269;
        let x2271 = x2241 + x2270;
        let x2272 = x2172 - x2208;
        let x2273 = 0.5 * x2272;
        let x2274 = x2262 + x2273;
        let x2275 = x2156 + x2217;
        let x2276 = 0.5 * x2275;
        let x2277 = s[12] * 0.004;
        let x2278 = x2276 + x2277;
        let x3067 = x1490 * k[17];
        let x3068 = x1494 * k[18];
        let x3069 = x1498 * k[18];
        let x3070 = x3067 + x3068;
        let x3071 = x3069 + x3070;
        let x3072 = 0.5 * x3071;
        let x3073 = x1504 * k[17];
        let x3074 = x1508 * k[18];
        let x3076 = x1513 * k[18];
        let x3077 = x3073 - x3074;
        let x3078 = x3076 + x3077;
        let x3079 = 0.5 * x3078;
        let x3080 = x1518 * k[17];
        let x3081 = x1522 * k[18];
        let x3082 = x1526 * k[18];
        let x3084 = x3080 + x3081;
        let x3085 = x3084 - x3082;
        let x3086 = 0.5 * x3085;
        let x3087 = x1532 * k[17];
        let x3089 = x1537 * k[18];
        let x3090 = x1541 * k[18];
        let x3091 = x3089 - x3087;
        let x3092 = x3090 + x3091;
        let x3093 = 0.5 * x3092;
        let x3094 = x1492 * k[18];
        let x3095 = x1496 * k[18];
        let x3096 = x3067 + x3094;
        let x3097 = x3095 + x3096;
        let x3098 = 0.5 * x3097;
        let x3099 = x3072 + x3098;
        let x3100 = q[3] * k[20];
        let x3101 = x1552 * x3100;
        let x3103 = x3099 - x3101;
        let x3105 = x1506 * k[18];
        let x3106 = x1511 * k[18];
        let x3108 = x3105 - x3073;
        let x3109 = x3108 - x3106;
        let x3110 = 0.5 * x3109;
        let x3112 = x3110 - x3079;
        let x3113 = q[4] * k[20];
        let x3114 = x1552 * x3113;
        let x3116 = x3112 - x3114;
        let x3117 = x1520 * k[18];
        let x3118 = x1524 * k[18];
        let x3119 = x3080 + x3117;
        let x3121 = x3118 - x3119;
        let x3122 = 0.5 * x3121;
        let x3124 = x3122 - x3086;
        let x3125 = q[5] * k[20];
        let x3126 = x1552 * x3125;
        let x3128 = x3124 - x3126;
        let x3129 = x1535 * k[18];
        let x3131 = x1539 * k[18];
        let x3133 = x3087 - x3129;
        let x3134 = x3133 - x3131;
        let x3135 = 0.5 * x3134;
        let x3137 = x3135 - x3093;
        let x3138 = q[6] * k[20];
        let x3139 = x1552 * x3138;
        let x3141 = x3137 - x3139;
        let x3161 = x1762 * k[17];
        let x3162 = x1764 * k[19];
        let x3163 = x1766 * k[19];
        let x3165 = x3161 + x3162;
        let x3166 = x3165 - x3163;
        let x3167 = 0.5 * x3166;
        let x3169 = s[6] * k[21];
        let x3170 = x3169 - x3167;
        let x3171 = x1776 * k[17];
        let x3173 = x1780 * k[19];
        let x3174 = x1782 * k[19];
        let x3175 = x3173 - x3171;
        let x3176 = x3174 + x3175;
        let x3177 = 0.5 * x3176;
        let x3179 = s[4] * k[21];
        let x3180 = x3179 - x3177;
        let x3181 = x1790 * k[17];
        let x3183 = s[46] - x3181;
        let x3184 = x3183 - s[45];
        let x3185 = 0.5 * x3184;
        let x3186 = s[47] + x3185;
        let x3187 = x1800 * k[17];
        let x3188 = s[44] + x3187;
        let x3189 = s[43] + x3188;
        let x3190 = 0.5 * x3189;
        let x3191 = s[0] * k[21];
        let x3192 = x3190 + x3191;
        let x3193 = x1807 * k[17];
        let x3196 = x3193 - x3174;
        let x3197 = x3196 - x3173;
        let x3198 = 0.5 * x3197;
        let x3199 = s[3] * k[21];
        let x3200 = x3198 + x3199;
        let x3201 = x1817 * k[17];
        let x3202 = x3163 + x3201;
        let x3204 = x3162 - x3202;
        let x3205 = 0.5 * x3204;
        let x3206 = s[5] * k[21];
        let x3207 = x3205 + x3206;
        let x3208 = x1766 * k[17];
        let x3209 = x1817 * k[19];
        let x3210 = x1762 * k[19];
        let x3211 = x3208 + x3209;
        let x3213 = x3210 - x3211;
        let x3214 = 0.5 * x3213;
        let x3215 = x3169 + x3214;
        let x3216 = x1782 * k[17];
        let x3217 = x1807 * k[19];
        let x3219 = x1776 * k[19];
        let x3221 = x3216 - x3217;
        let x3222 = x3221 - x3219;
        let x3223 = 0.5 * x3222;
        let x3224 = x3199 + x3223;
        let x3225 = s[39] * k[17];
        let x3226 = x1800 * k[19];
        let x3227 = s[37] * k[19];
        let x3228 = x3225 + x3226;
        let x3229 = x3227 + x3228;
        let x3230 = 0.5 * x3229;
        let x3231 = s[1] * k[21];
        let x3232 = x3230 + x3231;
        let x3233 = s[42] * k[17];
        let x3235 = x1790 * k[19];
        let x3236 = s[40] * k[19];
        let x3238 = x3235 - x3233;
        let x3239 = x3238 - x3236;
        let x3240 = 0.5 * x3239;
        let x3241 = s[7] * k[21];
        let x3242 = x3240 + x3241;
        let x3243 = x1780 * k[17];
        let x3244 = x3243 - x3219;
        let x3245 = x3244 - x3217;
        let x3246 = 0.5 * x3245;
        let x3247 = x3179 + x3246;
        let x3248 = x1764 * k[17];
        let x3249 = x3210 + x3248;
        let x3251 = x3209 - x3249;
        let x3252 = 0.5 * x3251;
        let x3253 = x3206 + x3252;
        let x3254 = s[41] * k[17];
        let x3257 = x3236 - x3254;
        let x3258 = x3257 - x3235;
        let x3259 = 0.5 * x3258;
        let x3260 = x3241 + x3259;
        let x3261 = s[38] * k[17];
        let x3262 = x3227 + x3261;
        let x3263 = x3226 + x3262;
        let x3264 = 0.5 * x3263;
        let x3265 = s[2] * k[21];
        let x3266 = x3264 + x3265;
        let x3267 = x1910 * k[17];
        let x3268 = x1914 * k[19];
        let x3269 = x1918 * k[19];
        let x3270 = x3267 + x3268;
        let x3271 = x3269 + x3270;
        let x3272 = 0.5 * x3271;
        let x3273 = x1924 * k[17];
        let x3274 = x1928 * k[19];
        let x3276 = x1933 * k[19];
        let x3277 = x3273 - x3274;
        let x3278 = x3276 + x3277;
        let x3279 = 0.5 * x3278;
        let x3280 = x1938 * k[17];
        let x3281 = x1942 * k[19];
        let x3282 = x1946 * k[19];
        let x3284 = x3280 + x3281;
        let x3285 = x3284 - x3282;
        let x3286 = 0.5 * x3285;
        let x3287 = x1952 * k[17];
        let x3289 = x1957 * k[19];
        let x3290 = x1961 * k[19];
        let x3291 = x3289 - x3287;
        let x3292 = x3290 + x3291;
        let x3293 = 0.5 * x3292;
        let x3294 = x1912 * k[19];
        let x3295 = x1916 * k[19];
        let x3296 = x3267 + x3294;
        let x3297 = x3295 + x3296;
        let x3298 = 0.5 * x3297;
        let x3299 = x3272 + x3298;
        let x3300 = q[10] * k[21];
        let x3301 = x1972 * x3300;
        let x3303 = x3299 - x3301;
        let x3305 = x1926 * k[19];
        let x3306 = x1931 * k[19];
        let x3308 = x3305 - x3273;
        let x3309 = x3308 - x3306;
        let x3310 = 0.5 * x3309;
        let x3312 = x3310 - x3279;
        let x3313 = q[11] * k[21];
        let x3314 = x1972 * x3313;
        let x3316 = x3312 - x3314;
        let x3317 = x1940 * k[19];
        let x3318 = x1944 * k[19];
        let x3319 = x3280 + x3317;
        let x3321 = x3318 - x3319;
        let x3322 = 0.5 * x3321;
        let x3324 = x3322 - x3286;
        let x3325 = q[12] * k[21];
        let x3326 = x1972 * x3325;
        let x3328 = x3324 - x3326;
        let x3329 = x1955 * k[19];
        let x3331 = x1959 * k[19];
        let x3333 = x3287 - x3329;
        let x3334 = x3333 - x3331;
        let x3335 = 0.5 * x3334;
        let x3337 = x3335 - x3293;
        let x3338 = q[13] * k[21];
        let x3339 = x1972 * x3338;
        let x3341 = x3337 - x3339;
        mass[24] = x3170;
        mass[25] = x3180;
        mass[26] = x3186;
        mass[27] = x3192;
        mass[28] = x3200;
        mass[29] = x3207;
        mass[30] = x3215;
        mass[31] = x3224;
        mass[32] = x3232;
        mass[33] = x3242;
        mass[34] = x3247;
        mass[35] = x3253;
        mass[36] = x3260;
        mass[37] = x3266;
        mass[38] = 1.0;
        mass[39] = 1.0;
        mass[40] = 1.0;
        mass[41] = x2163;
        mass[42] = x2177;
        mass[43] = x2191;
        mass[44] = x2205;
        mass[45] = x2215;
        mass[46] = x2222;
        mass[47] = x2232;
        mass[48] = x2242;
        mass[49] = x2247;
        mass[50] = x2253;
        mass[51] = x2257;
        mass[52] = x2263;
        mass[53] = x2266;
        mass[54] = x2271;
        mass[55] = x2274;
        mass[56] = x2278;
        force[0] = 0.0;
        force[1] = -2.943;
        force[2] = 0.0;
        force[3] = x3103;
        force[4] = x3116;
        force[5] = x3128;
        force[6] = x3141;
        force[7] = 0.0;
        force[8] = -5.886;
        force[9] = 0.0;
        force[10] = x3303;
        force[11] = x3316;
        force[12] = x3328;
        force[13] = x3341;
        force[14] = 0.0;
        force[15] = -9.81;
        force[16] = 0.0;
    }
    #[inline(never)]
    fn eval_newton_part_2(
        q: &[f64; 21],
        qd: &[f64; 21],
        s: &[f64; 48],
        force: &mut [f64; 21],
    ) {
        let x760 = q[19] * qd[18];
        let x761 = q[18] * qd[19];
        let x764 = q[20] * qd[17];
        let x765 = q[17] * qd[20];
        let x768 = q[20] * qd[18];
        let x769 = q[18] * qd[20];
        let x772 = q[19] * qd[17];
        let x773 = q[17] * qd[19];
        let x778 = q[20] * qd[19];
        let x779 = q[19] * qd[20];
        let x782 = q[18] * qd[17];
        let x783 = q[17] * qd[18];
        let x914 = 2.0 * qd[17];
        let x915 = 2.0 * qd[20];
        let x916 = 2.0 * qd[18];
        let x917 = 2.0 * qd[19];
        let x1008 = qd[18] * qd[19];
        let x1011 = qd[17] * qd[20];
        let x1014 = qd[18] * qd[20];
        let x1017 = qd[17] * qd[19];
        let x2039 = x783 - x782;
        let x2040 = x778 + x2039;
        let x2041 = x2040 - x779;
        let x2042 = 2.0 * x2041;
        let x2045 = x768 + x772;
        let x2047 = x773 - x2045;
        let x2048 = x769 + x2047;
        let x2049 = 2.0 * x2048;
        let x2052 = x760 - x764;
        let x2053 = x2052 - x761;
        let x2054 = x765 + x2053;
        let x2055 = 2.0 * x2054;
        let x2072 = 2.0 * x2042;
        let x2074 = 2.0 * x2049;
        let x2076 = 2.0 * x2055;
        let x2281 = x1014 + x1017;
        let x2283 = x1017 - x2281;
        let x2284 = x1014 + x2283;
        let x2285 = 2.0 * x2284;
        let x2288 = x1008 - x1011;
        let x2289 = x2288 - x1008;
        let x2290 = x1011 + x2289;
        let x2291 = 2.0 * x2290;
        let x2292 = 2.0 * x2285;
        let x2293 = 2.0 * x2291;
        let x2294 = x916 * x2072;
        let x2295 = 0.001 * x2294;
        let x2296 = x917 * x2074;
        let x2297 = s[34] * x2292;
        let x2298 = x2296 + x2297;
        let x2299 = 0.001 * x2298;
        let x2300 = x915 * x2076;
        let x2301 = s[29] * x2293;
        let x2302 = x2300 + x2301;
        let x2303 = 0.001 * x2302;
        let x2304 = x2295 + x2299;
        let x2305 = x2303 + x2304;
        let x2306 = 0.5 * x2305;
        let x2308 = x914 * x2072;
        let x2309 = 0.001 * x2308;
        let x2310 = x915 * x2074;
        let x2311 = s[29] * x2292;
        let x2312 = x2310 + x2311;
        let x2313 = 0.001 * x2312;
        let x2315 = x917 * x2076;
        let x2316 = s[34] * x2293;
        let x2317 = x2315 + x2316;
        let x2318 = 0.001 * x2317;
        let x2319 = x2309 - x2313;
        let x2320 = x2318 + x2319;
        let x2321 = 0.5 * x2320;
        let x2322 = x915 * x2072;
        let x2323 = 0.001 * x2322;
        let x2324 = x914 * x2074;
        let x2325 = s[28] * x2292;
        let x2326 = x2324 + x2325;
        let x2327 = 0.001 * x2326;
        let x2328 = x916 * x2076;
        let x2329 = s[33] * x2293;
        let x2330 = x2328 + x2329;
        let x2331 = 0.001 * x2330;
        let x2333 = x2323 + x2327;
        let x2334 = x2333 - x2331;
        let x2335 = 0.5 * x2334;
        let x2336 = x917 * x2072;
        let x2337 = 0.001 * x2336;
        let x2339 = x916 * x2074;
        let x2340 = s[33] * x2292;
        let x2341 = x2339 + x2340;
        let x2342 = 0.001 * x2341;
        let x2343 = x914 * x2076;
        let x2344 = s[28] * x2293;
        let x2345 = x2343 + x2344;
        let x2346 = 0.001 * x2345;
        let x2347 = x2342 - x2337;
        let x2348 = x2346 + x2347;
        let x2349 = 0.5 * x2348;
        let x2350 = qd[17] * qd[17];
        let x2351 = qd[18] * qd[18];
        let x2352 = qd[19] * qd[19];
        let x2353 = qd[20] * qd[20];
        let x2354 = x2350 + x2351;
        let x2355 = x2352 + x2354;
        let x2356 = x2353 + x2355;
        let x2357 = 0.001 * x2296;
        let x2358 = 0.001 * x2300;
        let x2359 = x2295 + x2357;
        let x2360 = x2358 + x2359;
        let x2361 = 0.5 * x2360;
        let x2362 = x2306 + x2361;
        let x2363 = q[17] * 0.004;
        let x2364 = x2356 * x2363;
        let x2366 = x2362 - x2364;
        let x2373 = 0.001 * x2310;
        let x2375 = 0.001 * x2315;
        let x2377 = x2373 - x2309;
        let x2378 = x2377 - x2375;
        let x2379 = 0.5 * x2378;
        let x2381 = x2379 - x2321;
        let x2382 = q[18] * 0.004;
        let x2383 = x2356 * x2382;
        let x2385 = x2381 - x2383;
        let x2391 = 0.001 * x2324;
        let x2393 = 0.001 * x2328;
        let x2394 = x2323 + x2391;
        let x2396 = x2393 - x2394;
        let x2397 = 0.5 * x2396;
        let x2399 = x2397 - x2335;
        let x2400 = q[19] * 0.004;
        let x2401 = x2356 * x2400;
        let x2403 = x2399 - x2401;
        let x2407 = 0.001 * x2339;
        let x2410 = 0.001 * x2343;
        let x2412 = x2337 - x2407;
        let x2413 = x2412 - x2410;
        let x2414 = 0.5 * x2413;
        let x2416 = x2414 - x2349;
        let x2417 = q[20] * 0.004;
        let x2418 = x2356 * x2417;
        let x2420 = x2416 - x2418;
        force[17] = x2366;
        force[18] = x2385;
        force[19] = x2403;
        force[20] = x2420;
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
    pub static PHI_Q_ROWS: [u32; 105usize] = [
        0u32, 0u32, 0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 1u32, 1u32, 2u32, 2u32, 2u32,
        2u32, 2u32, 3u32, 3u32, 3u32, 3u32, 4u32, 4u32, 4u32, 4u32, 5u32, 5u32, 5u32,
        5u32, 5u32, 5u32, 5u32, 5u32, 5u32, 5u32, 6u32, 6u32, 6u32, 6u32, 6u32, 6u32,
        6u32, 6u32, 6u32, 6u32, 7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 7u32, 7u32,
        7u32, 8u32, 8u32, 8u32, 8u32, 8u32, 8u32, 9u32, 9u32, 9u32, 9u32, 9u32, 10u32,
        10u32, 10u32, 10u32, 10u32, 11u32, 11u32, 11u32, 11u32, 11u32, 11u32, 11u32,
        11u32, 12u32, 12u32, 12u32, 12u32, 13u32, 13u32, 13u32, 13u32, 14u32, 14u32,
        14u32, 14u32, 15u32, 15u32, 15u32, 15u32, 16u32, 16u32, 16u32, 16u32, 17u32,
        17u32, 17u32, 17u32, 18u32, 18u32, 18u32, 18u32,
    ];
    /// Column of each Φq nonzero.
    pub static PHI_Q_COLS: [u32; 105usize] = [
        0u32, 3u32, 4u32, 5u32, 6u32, 1u32, 3u32, 4u32, 5u32, 6u32, 2u32, 3u32, 4u32,
        5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32, 0u32, 3u32, 4u32,
        5u32, 6u32, 7u32, 10u32, 11u32, 12u32, 13u32, 1u32, 3u32, 4u32, 5u32, 6u32, 8u32,
        10u32, 11u32, 12u32, 13u32, 2u32, 3u32, 4u32, 5u32, 6u32, 9u32, 10u32, 11u32,
        12u32, 13u32, 7u32, 10u32, 11u32, 12u32, 13u32, 14u32, 8u32, 10u32, 11u32, 12u32,
        13u32, 9u32, 10u32, 11u32, 12u32, 13u32, 10u32, 11u32, 12u32, 13u32, 15u32,
        16u32, 17u32, 18u32, 15u32, 16u32, 17u32, 18u32, 15u32, 16u32, 17u32, 18u32,
        15u32, 16u32, 17u32, 18u32, 3u32, 4u32, 5u32, 6u32, 3u32, 4u32, 5u32, 6u32,
        10u32, 11u32, 12u32, 13u32, 15u32, 16u32, 17u32, 18u32,
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
        offsets: offsets_at_file_values,
        offsets_read_parameters: true,
    };
    /// `c, ċ, c̈` of each substitution at time `t`, three per substitution.
    pub fn offsets_into(p: &[f64], t: f64, out: &mut [f64]) {
        let p: &[f64; 34] = p.try_into().expect("p must have 34 entries");
        let out: &mut [f64; 6] = out.try_into().expect("out must have 6 entries");
        let _ = t;
        offsets_into_part_0(p, out);
    }
    #[inline(never)]
    fn offsets_into_part_0(p: &[f64; 34], out: &mut [f64; 6]) {
        out[0] = p[32];
        out[1] = 0.0;
        out[2] = 0.0;
        out[3] = p[33];
        out[4] = 0.0;
        out[5] = 0.0;
    }
    fn offsets_at_file_values(t: f64, out: &mut [f64]) {
        offsets_into(&super::P0, t, out)
    }
    /// Number of values `setup` computes from the run-time parameters.
    pub const N_K: usize = 23;
    /// `setup` at the file's parameter values: what the types without parameters read.
    pub static K: [f64; 23] = [
        -0.05f64,
        0f64,
        1f64,
        0f64,
        1f64,
        0.05f64,
        0f64,
        -0.1749999999999999f64,
        0.000000000000000003677613769070831f64,
        0.000000000000000013877787807814457f64,
        0.17499999999999993f64,
        -0.00000000000000001061650767297806f64,
        -0.000000000000000027755575615628914f64,
        0.00000000000000005551115123125783f64,
        0.9999999999999994f64,
        0.05f64,
        0.12f64,
        0.0001f64,
        0.00025f64,
        0.006124999999999999f64,
        0.0008f64,
        0.016466666666666664f64,
        0.49050000000000005f64,
    ];
    /// The values the per-step functions read (`k`), from the run-time parameters `p`.
    pub fn setup(p: &[f64], k: &mut [f64]) {
        let p: &[f64; 34] = p.try_into().expect("p must have 34 entries");
        let k: &mut [f64; 23] = k.try_into().expect("k must have 23 entries");
        setup_part_0(p, k);
    }
    #[inline(never)]
    fn setup_part_0(p: &[f64; 34], k: &mut [f64; 23]) {
        let x1172 = p[4] * 0.3;
        let x1173 = p[4] * x1172;
        let x1176 = x1173 * 0.08333333333333333;
        let x1178 = p[3] * 0.6;
        let x1179 = p[3] * x1178;
        let x1180 = 0.08333333333333333 * x1179;
        let x1297 = p[0] + x1176;
        let x1298 = x1176 + x1297;
        let x1301 = x1298 * 4.0;
        let x1303 = x1301 * 0.3333333333333333;
        let x1720 = p[0] + x1180;
        let x1721 = x1180 + x1720;
        let x1722 = 4.0 * x1721;
        let x1723 = 0.3333333333333333 * x1722;
        let x2593 = p[32] * 9.81;
        k[0] = p[13];
        k[1] = p[14];
        k[2] = p[15];
        k[3] = p[16];
        k[4] = p[17];
        k[5] = p[18];
        k[6] = p[19];
        k[7] = p[20];
        k[8] = p[21];
        k[9] = p[22];
        k[10] = p[23];
        k[11] = p[24];
        k[12] = p[25];
        k[13] = p[29];
        k[14] = p[30];
        k[15] = p[32];
        k[16] = p[33];
        k[17] = p[0];
        k[18] = x1176;
        k[19] = x1180;
        k[20] = x1303;
        k[21] = x1723;
        k[22] = x2593;
    }
    /// Constraint residual Φ(q, t).
    pub fn phi(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
        let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
        phi_part_0(k, q, t, out);
    }
    #[inline(never)]
    fn phi_part_0(k: &[f64; 23], q: &[f64; 19], t: f64, out: &mut [f64; 19]) {
        let x5 = 6.283185307179586 * t;
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
        let x323 = x5.sin();
        let x324 = x5.cos();
        let x329 = x16 + x18;
        let x330 = x17 + x329;
        let x331 = x330 - 1.0;
        let x332 = x61 + x63;
        let x333 = x62 + x332;
        let x334 = x333 - 1.0;
        let x2421 = q[15] * q[15];
        let x2422 = q[16] * q[16];
        let x2423 = x2421 + x2422;
        let x2424 = x104 + x2421;
        let x2425 = 2.0 * x2424;
        let x2426 = x2425 - 1.0;
        let x2427 = q[16] * q[17];
        let x2428 = 2.0 * x2427;
        let x2429 = q[15] * q[18];
        let x2430 = 2.0 * x2429;
        let x2431 = q[16] * q[18];
        let x2432 = 2.0 * x2431;
        let x2433 = q[15] * q[17];
        let x2434 = 2.0 * x2433;
        let x2435 = x2432 + x2434;
        let x2436 = x2428 + x2430;
        let x2437 = q[15] * q[16];
        let x2438 = 2.0 * x2437;
        let x2440 = x133 - x2438;
        let x2442 = x2432 - x2434;
        let x2443 = x133 + x2438;
        let x2451 = x103 + x2423;
        let x2452 = x104 + x2451;
        let x2453 = x2452 - 1.0;
        let x2836 = x21 * k[0];
        let x2837 = x34 * k[1];
        let x2838 = x2836 + x2837;
        let x2839 = x40 * k[0];
        let x2840 = x24 * k[1];
        let x2841 = x2839 + x2840;
        let x2842 = x50 * k[0];
        let x2843 = x51 * k[1];
        let x2844 = x2842 + x2843;
        let x2845 = q[0] + x2838;
        let x2846 = q[1] + x2841;
        let x2847 = q[2] + x2844;
        let x2850 = x21 * k[2];
        let x2851 = x34 * k[3];
        let x2852 = x2850 + x2851;
        let x2853 = x40 * k[2];
        let x2854 = x24 * k[3];
        let x2855 = x2853 + x2854;
        let x2857 = x39 * k[4];
        let x2858 = x47 * k[4];
        let x2859 = -x2845;
        let x2860 = -x2846;
        let x2861 = -x2847;
        let x2864 = x21 * k[5];
        let x2865 = x34 * k[6];
        let x2866 = x2864 + x2865;
        let x2867 = x40 * k[5];
        let x2868 = x24 * k[6];
        let x2869 = x2867 + x2868;
        let x2870 = x50 * k[5];
        let x2871 = x51 * k[6];
        let x2872 = x2870 + x2871;
        let x2873 = q[0] + x2866;
        let x2874 = q[1] + x2869;
        let x2875 = q[2] + x2872;
        let x2879 = x65 * k[7];
        let x2880 = x78 * k[8];
        let x2881 = x83 * k[9];
        let x2882 = x2879 + x2880;
        let x2883 = x2881 + x2882;
        let x2884 = x84 * k[7];
        let x2885 = x68 * k[8];
        let x2886 = x91 * k[9];
        let x2887 = x2884 + x2885;
        let x2888 = x2886 + x2887;
        let x2889 = x94 * k[7];
        let x2890 = x95 * k[8];
        let x2891 = x71 * k[9];
        let x2892 = x2889 + x2890;
        let x2893 = x2891 + x2892;
        let x2894 = q[7] + x2883;
        let x2895 = q[8] + x2888;
        let x2896 = q[9] + x2893;
        let x2898 = x2873 - x2894;
        let x2900 = x2874 - x2895;
        let x2902 = x2875 - x2896;
        let x2906 = x65 * k[10];
        let x2907 = x78 * k[11];
        let x2908 = x83 * k[12];
        let x2909 = x2906 + x2907;
        let x2910 = x2908 + x2909;
        let x2911 = x84 * k[10];
        let x2912 = x68 * k[11];
        let x2913 = x91 * k[12];
        let x2914 = x2911 + x2912;
        let x2915 = x2913 + x2914;
        let x2916 = x94 * k[10];
        let x2917 = x95 * k[11];
        let x2918 = x71 * k[12];
        let x2919 = x2916 + x2917;
        let x2920 = x2918 + x2919;
        let x2921 = q[7] + x2910;
        let x2922 = q[8] + x2915;
        let x2923 = q[9] + x2920;
        let x2926 = x65 * k[13];
        let x2927 = x78 * k[14];
        let x2928 = x2926 + x2927;
        let x2929 = x84 * k[13];
        let x2930 = x68 * k[14];
        let x2931 = x2929 + x2930;
        let x2932 = x94 * k[13];
        let x2933 = x95 * k[14];
        let x2934 = x2932 + x2933;
        let x2936 = q[14] - x2921;
        let x2941 = x323 * x2852;
        let x2942 = x324 * x2855;
        let x2944 = x2941 - x2942;
        let x3690 = k[15] - x2922;
        let x3691 = k[16] - x2923;
        let x3692 = x2435 * x2928;
        let x3693 = x2440 * x2931;
        let x3694 = x2426 * x2934;
        let x3695 = x3692 + x3693;
        let x3696 = x3694 + x3695;
        out[0] = x2859;
        out[1] = x2860;
        out[2] = x2861;
        out[3] = x2857;
        out[4] = x2858;
        out[5] = x2898;
        out[6] = x2900;
        out[7] = x2902;
        out[8] = x2936;
        out[9] = x3690;
        out[10] = x3691;
        out[11] = x3696;
        out[12] = x2436;
        out[13] = x2442;
        out[14] = x2443;
        out[15] = x2944;
        out[16] = x331;
        out[17] = x334;
        out[18] = x2453;
    }
    /// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
    pub fn phi_q(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
        let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 105] = out.try_into().expect("out must have 105 entries");
        phi_q_part_0(k, q, t, out);
    }
    #[inline(never)]
    fn phi_q_part_0(k: &[f64; 23], q: &[f64; 19], t: f64, out: &mut [f64; 105]) {
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
        let x323 = x5.sin();
        let x324 = x5.cos();
        let x338 = 2.0 * q[3];
        let x339 = 2.0 * q[4];
        let x340 = 2.0 * q[10];
        let x341 = 2.0 * q[11];
        let x342 = 2.0 * q[5];
        let x343 = 2.0 * q[12];
        let x344 = 2.0 * q[13];
        let x345 = 2.0 * q[6];
        let x346 = 2.0 * x338;
        let x389 = 2.0 * x339;
        let x414 = 2.0 * x342;
        let x452 = 2.0 * x340;
        let x456 = 2.0 * q[17];
        let x516 = 2.0 * x341;
        let x554 = 2.0 * x343;
        let x588 = 2.0 * x344;
        let x615 = 2.0 * q[18];
        let x626 = -x456;
        let x2139 = 2.0 * x615;
        let x2421 = q[15] * q[15];
        let x2424 = x104 + x2421;
        let x2425 = 2.0 * x2424;
        let x2426 = x2425 - 1.0;
        let x2431 = q[16] * q[18];
        let x2432 = 2.0 * x2431;
        let x2433 = q[15] * q[17];
        let x2434 = 2.0 * x2433;
        let x2435 = x2432 + x2434;
        let x2437 = q[15] * q[16];
        let x2438 = 2.0 * x2437;
        let x2440 = x133 - x2438;
        let x2454 = 2.0 * q[15];
        let x2476 = 2.0 * q[16];
        let x2477 = 2.0 * x2454;
        let x2484 = -x2454;
        let x2926 = x65 * k[13];
        let x2927 = x78 * k[14];
        let x2928 = x2926 + x2927;
        let x2929 = x84 * k[13];
        let x2930 = x68 * k[14];
        let x2931 = x2929 + x2930;
        let x2932 = x94 * k[13];
        let x2933 = x95 * k[14];
        let x2934 = x2932 + x2933;
        let x2945 = x346 * k[0];
        let x2946 = x345 * k[1];
        let x2948 = x2945 - x2946;
        let x2949 = x345 * k[0];
        let x2950 = x346 * k[1];
        let x2951 = x2949 + x2950;
        let x2952 = x342 * k[0];
        let x2953 = -x2952;
        let x2954 = x339 * k[1];
        let x2955 = x2954 - x2952;
        let x2956 = x346 * k[2];
        let x2957 = x345 * k[3];
        let x2959 = x2956 - x2957;
        let x2960 = x345 * k[2];
        let x2961 = x346 * k[3];
        let x2962 = x2960 + x2961;
        let x2963 = x342 * k[4];
        let x2964 = x339 * k[4];
        let x2965 = -x2964;
        let x2966 = -x2948;
        let x2967 = -x2951;
        let x2968 = -x2955;
        let x2969 = x346 * k[5];
        let x2970 = x345 * k[6];
        let x2972 = x2969 - x2970;
        let x2973 = x345 * k[5];
        let x2974 = x346 * k[6];
        let x2975 = x2973 + x2974;
        let x2976 = x342 * k[5];
        let x2978 = x339 * k[6];
        let x2979 = x2978 - x2976;
        let x2980 = x323 * x2959;
        let x2981 = x324 * x2962;
        let x2983 = x2980 - x2981;
        let x2984 = x389 * k[0];
        let x2985 = x342 * k[1];
        let x2986 = x2984 + x2985;
        let x2987 = x338 * k[1];
        let x2988 = x2949 + x2987;
        let x2989 = x389 * k[2];
        let x2990 = x342 * k[3];
        let x2991 = x2989 + x2990;
        let x2992 = x342 * k[2];
        let x2993 = x345 * k[4];
        let x2994 = x338 * k[4];
        let x2995 = -x2994;
        let x2996 = -x2986;
        let x2997 = -x2988;
        let x2998 = x389 * k[5];
        let x2999 = x342 * k[6];
        let x3000 = x2998 + x2999;
        let x3001 = x338 * k[6];
        let x3002 = x2973 + x3001;
        let x3003 = x323 * x2991;
        let x3004 = x324 * x2992;
        let x3006 = x3003 - x3004;
        let x3007 = x339 * k[0];
        let x3008 = x414 * k[1];
        let x3009 = x3007 + x3008;
        let x3010 = x338 * k[0];
        let x3011 = -x3010;
        let x3012 = x2946 - x3010;
        let x3013 = x339 * k[3];
        let x3014 = x339 * k[2];
        let x3015 = x414 * k[3];
        let x3016 = x3014 + x3015;
        let x3017 = -x2954;
        let x3018 = -x3009;
        let x3019 = -x3012;
        let x3020 = x339 * k[5];
        let x3021 = x414 * k[6];
        let x3022 = x3020 + x3021;
        let x3023 = x338 * k[5];
        let x3025 = x2970 - x3023;
        let x3026 = x323 * x3013;
        let x3027 = x324 * x3016;
        let x3029 = x3026 - x3027;
        let x3030 = x2985 + x3007;
        let x3031 = x338 * k[3];
        let x3032 = x338 * k[2];
        let x3033 = -x3030;
        let x3034 = -x3001;
        let x3035 = x2999 + x3020;
        let x3036 = x323 * x3031;
        let x3037 = x324 * x3032;
        let x3038 = x3036 + x3037;
        let x3039 = -x3038;
        let x3040 = x452 * k[7];
        let x3041 = x344 * k[8];
        let x3043 = x343 * k[9];
        let x3044 = x3040 - x3041;
        let x3045 = x3043 + x3044;
        let x3046 = x344 * k[7];
        let x3047 = x452 * k[8];
        let x3048 = x341 * k[9];
        let x3050 = x3046 + x3047;
        let x3051 = x3050 - x3048;
        let x3052 = x343 * k[7];
        let x3054 = x341 * k[8];
        let x3055 = x452 * k[9];
        let x3056 = x3054 - x3052;
        let x3057 = x3055 + x3056;
        let x3058 = -x3045;
        let x3059 = -x3051;
        let x3060 = -x3057;
        let x3061 = x452 * k[10];
        let x3062 = x344 * k[11];
        let x3064 = x343 * k[12];
        let x3065 = x3061 - x3062;
        let x3066 = x3064 + x3065;
        let x3067 = x344 * k[10];
        let x3068 = x452 * k[11];
        let x3069 = x341 * k[12];
        let x3071 = x3067 + x3068;
        let x3072 = x3071 - x3069;
        let x3073 = x343 * k[10];
        let x3075 = x341 * k[11];
        let x3076 = x452 * k[12];
        let x3077 = x3075 - x3073;
        let x3078 = x3076 + x3077;
        let x3079 = x452 * k[13];
        let x3080 = x344 * k[14];
        let x3082 = x3079 - x3080;
        let x3083 = x344 * k[13];
        let x3084 = x452 * k[14];
        let x3085 = x3083 + x3084;
        let x3086 = x343 * k[13];
        let x3088 = x341 * k[14];
        let x3089 = x3088 - x3086;
        let x3090 = -x3066;
        let x3091 = -x3072;
        let x3092 = -x3078;
        let x3093 = x516 * k[7];
        let x3094 = x343 * k[8];
        let x3095 = x344 * k[9];
        let x3096 = x3093 + x3094;
        let x3097 = x3095 + x3096;
        let x3098 = x340 * k[9];
        let x3100 = x3052 - x3098;
        let x3101 = x340 * k[8];
        let x3102 = x3046 + x3101;
        let x3103 = -x3097;
        let x3104 = -x3100;
        let x3105 = -x3102;
        let x3106 = x516 * k[10];
        let x3107 = x343 * k[11];
        let x3108 = x344 * k[12];
        let x3109 = x3106 + x3107;
        let x3110 = x3108 + x3109;
        let x3111 = x340 * k[12];
        let x3113 = x3073 - x3111;
        let x3114 = x340 * k[11];
        let x3115 = x3067 + x3114;
        let x3116 = x516 * k[13];
        let x3117 = x343 * k[14];
        let x3118 = x3116 + x3117;
        let x3119 = x340 * k[14];
        let x3120 = x3083 + x3119;
        let x3121 = -x3110;
        let x3122 = -x3113;
        let x3123 = -x3115;
        let x3124 = x3054 + x3098;
        let x3125 = x341 * k[7];
        let x3126 = x554 * k[8];
        let x3127 = x3125 + x3126;
        let x3128 = x3095 + x3127;
        let x3129 = x340 * k[7];
        let x3131 = x3041 - x3129;
        let x3132 = -x3124;
        let x3133 = -x3128;
        let x3134 = -x3131;
        let x3135 = x3075 + x3111;
        let x3136 = x341 * k[10];
        let x3137 = x554 * k[11];
        let x3138 = x3136 + x3137;
        let x3139 = x3108 + x3138;
        let x3140 = x340 * k[10];
        let x3142 = x3062 - x3140;
        let x3143 = x341 * k[13];
        let x3144 = x554 * k[14];
        let x3145 = x3143 + x3144;
        let x3146 = x340 * k[13];
        let x3148 = x3080 - x3146;
        let x3149 = -x3135;
        let x3150 = -x3139;
        let x3151 = -x3142;
        let x3153 = x3048 - x3101;
        let x3154 = x3043 + x3129;
        let x3155 = x588 * k[9];
        let x3156 = x3094 + x3125;
        let x3157 = x3155 + x3156;
        let x3158 = -x3153;
        let x3159 = -x3154;
        let x3160 = -x3157;
        let x3162 = x3069 - x3114;
        let x3163 = x3064 + x3140;
        let x3164 = x588 * k[12];
        let x3165 = x3107 + x3136;
        let x3166 = x3164 + x3165;
        let x3167 = x3117 + x3143;
        let x3168 = -x3162;
        let x3169 = -x3163;
        let x3170 = -x3166;
        let x3171 = x615 * x2931;
        let x3172 = x456 * x2931;
        let x3173 = x456 * x2928;
        let x3174 = x615 * x2928;
        let x3697 = x2435 * x3082;
        let x3698 = x2440 * x3085;
        let x3699 = x2426 * x3089;
        let x3700 = x3697 + x3698;
        let x3701 = x3699 + x3700;
        let x3702 = x2435 * x3118;
        let x3703 = x2440 * x3086;
        let x3704 = x2426 * x3120;
        let x3705 = x3702 + x3703;
        let x3706 = x3704 + x3705;
        let x3707 = x2435 * x3088;
        let x3708 = x2440 * x3145;
        let x3709 = x2426 * x3148;
        let x3710 = x3707 + x3708;
        let x3711 = x3709 + x3710;
        let x3712 = x2435 * x3119;
        let x3714 = x2440 * x3146;
        let x3715 = x2426 * x3167;
        let x3716 = x3714 - x3712;
        let x3717 = x3715 + x3716;
        let x3718 = x2476 * x2931;
        let x3720 = x2477 * x2934;
        let x3721 = x3173 - x3718;
        let x3722 = x3720 + x3721;
        let x3723 = x2454 * x2931;
        let x3725 = x3174 - x3723;
        let x3726 = x2454 * x2928;
        let x3727 = x3171 + x3726;
        let x3728 = x2476 * x2928;
        let x3729 = x2139 * x2934;
        let x3730 = x3172 + x3728;
        let x3731 = x3729 + x3730;
        out[0] = -1.0;
        out[1] = x2966;
        out[2] = x2996;
        out[3] = x3017;
        out[4] = x2987;
        out[5] = -1.0;
        out[6] = x2967;
        out[7] = x2953;
        out[8] = x3018;
        out[9] = x3011;
        out[10] = -1.0;
        out[11] = x2968;
        out[12] = x2997;
        out[13] = x3019;
        out[14] = x3033;
        out[15] = x2963;
        out[16] = x2993;
        out[17] = x2994;
        out[18] = x2964;
        out[19] = x2965;
        out[20] = x2995;
        out[21] = x2993;
        out[22] = x2963;
        out[23] = 1.0;
        out[24] = x2972;
        out[25] = x3000;
        out[26] = x2978;
        out[27] = x3034;
        out[28] = -1.0;
        out[29] = x3058;
        out[30] = x3103;
        out[31] = x3132;
        out[32] = x3158;
        out[33] = 1.0;
        out[34] = x2975;
        out[35] = x2976;
        out[36] = x3022;
        out[37] = x3023;
        out[38] = -1.0;
        out[39] = x3059;
        out[40] = x3104;
        out[41] = x3133;
        out[42] = x3159;
        out[43] = 1.0;
        out[44] = x2979;
        out[45] = x3002;
        out[46] = x3025;
        out[47] = x3035;
        out[48] = -1.0;
        out[49] = x3060;
        out[50] = x3105;
        out[51] = x3134;
        out[52] = x3160;
        out[53] = -1.0;
        out[54] = x3090;
        out[55] = x3121;
        out[56] = x3149;
        out[57] = x3168;
        out[58] = 1.0;
        out[59] = -1.0;
        out[60] = x3091;
        out[61] = x3122;
        out[62] = x3150;
        out[63] = x3169;
        out[64] = -1.0;
        out[65] = x3092;
        out[66] = x3123;
        out[67] = x3151;
        out[68] = x3170;
        out[69] = x3701;
        out[70] = x3706;
        out[71] = x3711;
        out[72] = x3717;
        out[73] = x3722;
        out[74] = x3725;
        out[75] = x3727;
        out[76] = x3731;
        out[77] = x615;
        out[78] = x456;
        out[79] = x2476;
        out[80] = x2454;
        out[81] = x626;
        out[82] = x615;
        out[83] = x2484;
        out[84] = x2476;
        out[85] = x2476;
        out[86] = x2454;
        out[87] = x615;
        out[88] = x456;
        out[89] = x2983;
        out[90] = x3006;
        out[91] = x3029;
        out[92] = x3039;
        out[93] = x338;
        out[94] = x339;
        out[95] = x342;
        out[96] = x345;
        out[97] = x340;
        out[98] = x341;
        out[99] = x343;
        out[100] = x344;
        out[101] = x2454;
        out[102] = x2476;
        out[103] = x456;
        out[104] = x615;
    }
    /// Partial time derivative Φt(q, t).
    pub fn phi_t(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
        let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
        phi_t_part_0(k, q, t, out);
    }
    #[inline(never)]
    fn phi_t_part_0(k: &[f64; 23], q: &[f64; 19], t: f64, out: &mut [f64; 19]) {
        let x5 = 6.283185307179586 * t;
        let x14 = q[3] * q[3];
        let x15 = q[4] * q[4];
        let x16 = q[5] * q[5];
        let x18 = x14 + x15;
        let x19 = 2.0 * x18;
        let x21 = x19 - 1.0;
        let x22 = x14 + x16;
        let x23 = 2.0 * x22;
        let x24 = x23 - 1.0;
        let x28 = q[4] * q[5];
        let x29 = 2.0 * x28;
        let x30 = q[3] * q[6];
        let x32 = 2.0 * x30;
        let x34 = x29 - x32;
        let x40 = x29 + x32;
        let x323 = x5.sin();
        let x324 = x5.cos();
        let x640 = 6.283185307179586 * x324;
        let x642 = 6.283185307179586 * x323;
        let x2850 = x21 * k[2];
        let x2851 = x34 * k[3];
        let x2852 = x2850 + x2851;
        let x2853 = x40 * k[2];
        let x2854 = x24 * k[3];
        let x2855 = x2853 + x2854;
        let x3175 = x640 * x2852;
        let x3176 = x642 * x2855;
        let x3177 = x3175 + x3176;
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
        out[15] = x3177;
        out[16] = 0.0;
        out[17] = 0.0;
        out[18] = 0.0;
    }
    /// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
    pub fn gamma(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
        let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 19] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
        gamma_part_0(k, q, qd, t, out);
    }
    #[inline(never)]
    fn gamma_part_0(
        k: &[f64; 23],
        q: &[f64; 19],
        qd: &[f64; 19],
        t: f64,
        out: &mut [f64; 19],
    ) {
        let x5 = 6.283185307179586 * t;
        let x14 = q[3] * q[3];
        let x15 = q[4] * q[4];
        let x16 = q[5] * q[5];
        let x18 = x14 + x15;
        let x19 = 2.0 * x18;
        let x21 = x19 - 1.0;
        let x22 = x14 + x16;
        let x23 = 2.0 * x22;
        let x24 = x23 - 1.0;
        let x28 = q[4] * q[5];
        let x29 = 2.0 * x28;
        let x30 = q[3] * q[6];
        let x32 = 2.0 * x30;
        let x34 = x29 - x32;
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
        let x323 = x5.sin();
        let x324 = x5.cos();
        let x338 = 2.0 * q[3];
        let x339 = 2.0 * q[4];
        let x340 = 2.0 * q[10];
        let x341 = 2.0 * q[11];
        let x342 = 2.0 * q[5];
        let x343 = 2.0 * q[12];
        let x615 = 2.0 * q[18];
        let x640 = 6.283185307179586 * x324;
        let x642 = 6.283185307179586 * x323;
        let x669 = x338 * qd[3];
        let x670 = x339 * qd[4];
        let x671 = x342 * qd[5];
        let x673 = x669 + x670;
        let x674 = 2.0 * x673;
        let x675 = x669 + x671;
        let x676 = 2.0 * x675;
        let x677 = q[5] * qd[4];
        let x678 = q[4] * qd[5];
        let x679 = x677 + x678;
        let x680 = 2.0 * x679;
        let x681 = q[6] * qd[3];
        let x682 = q[3] * qd[6];
        let x683 = x681 + x682;
        let x684 = 2.0 * x683;
        let x686 = x680 - x684;
        let x696 = x680 + x684;
        let x710 = x340 * qd[10];
        let x711 = x341 * qd[11];
        let x712 = x343 * qd[12];
        let x714 = x710 + x711;
        let x715 = 2.0 * x714;
        let x716 = x710 + x712;
        let x717 = 2.0 * x716;
        let x720 = q[12] * qd[11];
        let x721 = q[11] * qd[12];
        let x722 = x720 + x721;
        let x723 = 2.0 * x722;
        let x724 = q[13] * qd[10];
        let x725 = q[10] * qd[13];
        let x726 = x724 + x725;
        let x727 = 2.0 * x726;
        let x729 = x723 - x727;
        let x730 = q[13] * qd[11];
        let x731 = q[11] * qd[13];
        let x732 = x730 + x731;
        let x733 = 2.0 * x732;
        let x734 = q[12] * qd[10];
        let x735 = q[10] * qd[12];
        let x736 = x734 + x735;
        let x737 = 2.0 * x736;
        let x739 = x723 + x727;
        let x740 = q[13] * qd[12];
        let x741 = q[12] * qd[13];
        let x742 = x740 + x741;
        let x743 = 2.0 * x742;
        let x744 = q[11] * qd[10];
        let x745 = q[10] * qd[11];
        let x746 = x744 + x745;
        let x747 = 2.0 * x746;
        let x751 = x733 - x737;
        let x752 = x743 + x747;
        let x754 = x615 * qd[18];
        let x782 = q[18] * qd[17];
        let x783 = q[17] * qd[18];
        let x784 = x782 + x783;
        let x785 = 2.0 * x784;
        let x906 = 2.0 * qd[3];
        let x907 = 2.0 * qd[4];
        let x908 = 2.0 * qd[10];
        let x909 = 2.0 * qd[11];
        let x910 = 2.0 * qd[5];
        let x911 = 2.0 * qd[12];
        let x912 = 2.0 * qd[13];
        let x913 = 2.0 * qd[6];
        let x914 = 2.0 * qd[17];
        let x916 = 2.0 * qd[18];
        let x918 = 6.283185307179586 * x642;
        let x920 = 6.283185307179586 * x640;
        let x929 = qd[3] * x906;
        let x930 = qd[4] * x907;
        let x931 = qd[5] * x910;
        let x932 = qd[6] * x913;
        let x933 = x929 + x930;
        let x934 = 2.0 * x933;
        let x935 = x929 + x931;
        let x936 = 2.0 * x935;
        let x937 = qd[4] * qd[5];
        let x938 = x937 + x937;
        let x939 = 2.0 * x938;
        let x940 = qd[3] * qd[6];
        let x941 = x940 + x940;
        let x942 = 2.0 * x941;
        let x944 = x939 - x942;
        let x945 = qd[4] * qd[6];
        let x946 = x945 + x945;
        let x947 = 2.0 * x946;
        let x948 = qd[3] * qd[5];
        let x949 = x948 + x948;
        let x950 = 2.0 * x949;
        let x951 = x947 + x950;
        let x952 = x939 + x942;
        let x953 = qd[5] * qd[6];
        let x954 = x953 + x953;
        let x955 = 2.0 * x954;
        let x956 = qd[3] * qd[4];
        let x957 = x956 + x956;
        let x958 = 2.0 * x957;
        let x960 = x955 - x958;
        let x962 = x947 - x950;
        let x963 = x955 + x958;
        let x964 = qd[10] * x908;
        let x965 = qd[11] * x909;
        let x966 = qd[12] * x911;
        let x967 = qd[13] * x912;
        let x968 = x964 + x965;
        let x969 = 2.0 * x968;
        let x970 = x964 + x966;
        let x971 = 2.0 * x970;
        let x972 = x964 + x967;
        let x973 = 2.0 * x972;
        let x974 = qd[11] * qd[12];
        let x975 = x974 + x974;
        let x976 = 2.0 * x975;
        let x977 = qd[10] * qd[13];
        let x978 = x977 + x977;
        let x979 = 2.0 * x978;
        let x981 = x976 - x979;
        let x982 = qd[11] * qd[13];
        let x983 = x982 + x982;
        let x984 = 2.0 * x983;
        let x985 = qd[10] * qd[12];
        let x986 = x985 + x985;
        let x987 = 2.0 * x986;
        let x988 = x984 + x987;
        let x989 = x976 + x979;
        let x990 = qd[12] * qd[13];
        let x991 = x990 + x990;
        let x992 = 2.0 * x991;
        let x993 = qd[10] * qd[11];
        let x994 = x993 + x993;
        let x995 = 2.0 * x994;
        let x997 = x992 - x995;
        let x999 = x984 - x987;
        let x1000 = x992 + x995;
        let x1001 = qd[17] * x914;
        let x1002 = qd[18] * x916;
        let x1025 = qd[17] * qd[18];
        let x1026 = x1025 + x1025;
        let x1027 = 2.0 * x1026;
        let x1139 = x931 + x933;
        let x1140 = x932 + x1139;
        let x1141 = x966 + x968;
        let x1142 = x967 + x1141;
        let x1155 = -x1140;
        let x1156 = -x1142;
        let x2073 = 2.0 * qd[15];
        let x2075 = 2.0 * qd[16];
        let x2421 = q[15] * q[15];
        let x2424 = x104 + x2421;
        let x2425 = 2.0 * x2424;
        let x2426 = x2425 - 1.0;
        let x2431 = q[16] * q[18];
        let x2432 = 2.0 * x2431;
        let x2433 = q[15] * q[17];
        let x2434 = 2.0 * x2433;
        let x2435 = x2432 + x2434;
        let x2437 = q[15] * q[16];
        let x2438 = 2.0 * x2437;
        let x2440 = x133 - x2438;
        let x2454 = 2.0 * q[15];
        let x2494 = qd[15] * x2454;
        let x2497 = x754 + x2494;
        let x2498 = 2.0 * x2497;
        let x2507 = q[18] * qd[16];
        let x2508 = q[16] * qd[18];
        let x2509 = x2507 + x2508;
        let x2510 = 2.0 * x2509;
        let x2511 = q[17] * qd[15];
        let x2512 = q[15] * qd[17];
        let x2513 = x2511 + x2512;
        let x2514 = 2.0 * x2513;
        let x2515 = x2510 + x2514;
        let x2517 = q[16] * qd[15];
        let x2518 = q[15] * qd[16];
        let x2519 = x2517 + x2518;
        let x2520 = 2.0 * x2519;
        let x2522 = x785 - x2520;
        let x2539 = qd[15] * x2073;
        let x2540 = qd[16] * x2075;
        let x2541 = x2539 + x2540;
        let x2542 = x1002 + x2539;
        let x2543 = 2.0 * x2542;
        let x2544 = qd[16] * qd[17];
        let x2545 = x2544 + x2544;
        let x2546 = 2.0 * x2545;
        let x2547 = qd[15] * qd[18];
        let x2548 = x2547 + x2547;
        let x2549 = 2.0 * x2548;
        let x2550 = qd[16] * qd[18];
        let x2551 = x2550 + x2550;
        let x2552 = 2.0 * x2551;
        let x2553 = qd[15] * qd[17];
        let x2554 = x2553 + x2553;
        let x2555 = 2.0 * x2554;
        let x2556 = x2552 + x2555;
        let x2557 = x2546 + x2549;
        let x2558 = qd[15] * qd[16];
        let x2559 = x2558 + x2558;
        let x2560 = 2.0 * x2559;
        let x2562 = x1027 - x2560;
        let x2564 = x2552 - x2555;
        let x2565 = x1027 + x2560;
        let x2586 = x1001 + x2541;
        let x2587 = x1002 + x2586;
        let x2589 = -x2557;
        let x2590 = -x2564;
        let x2591 = -x2565;
        let x2592 = -x2587;
        let x2850 = x21 * k[2];
        let x2851 = x34 * k[3];
        let x2852 = x2850 + x2851;
        let x2853 = x40 * k[2];
        let x2854 = x24 * k[3];
        let x2855 = x2853 + x2854;
        let x2926 = x65 * k[13];
        let x2927 = x78 * k[14];
        let x2928 = x2926 + x2927;
        let x2929 = x84 * k[13];
        let x2930 = x68 * k[14];
        let x2931 = x2929 + x2930;
        let x2932 = x94 * k[13];
        let x2933 = x95 * k[14];
        let x2934 = x2932 + x2933;
        let x3178 = x674 * k[2];
        let x3179 = x686 * k[3];
        let x3180 = x3178 + x3179;
        let x3181 = x696 * k[2];
        let x3182 = x676 * k[3];
        let x3183 = x3181 + x3182;
        let x3184 = x715 * k[13];
        let x3185 = x729 * k[14];
        let x3186 = x3184 + x3185;
        let x3187 = x739 * k[13];
        let x3188 = x717 * k[14];
        let x3189 = x3187 + x3188;
        let x3190 = x751 * k[13];
        let x3191 = x752 * k[14];
        let x3192 = x3190 + x3191;
        let x3193 = x640 * x3180;
        let x3194 = x918 * x2852;
        let x3196 = x3193 - x3194;
        let x3197 = x642 * x3183;
        let x3198 = x920 * x2855;
        let x3199 = x3197 + x3198;
        let x3201 = x934 * k[0];
        let x3202 = x944 * k[1];
        let x3203 = x3201 + x3202;
        let x3204 = x952 * k[0];
        let x3205 = x936 * k[1];
        let x3206 = x3204 + x3205;
        let x3207 = x962 * k[0];
        let x3208 = x963 * k[1];
        let x3209 = x3207 + x3208;
        let x3210 = x934 * k[2];
        let x3211 = x944 * k[3];
        let x3212 = x3210 + x3211;
        let x3213 = x952 * k[2];
        let x3214 = x936 * k[3];
        let x3215 = x3213 + x3214;
        let x3216 = x951 * k[4];
        let x3217 = x960 * k[4];
        let x3218 = x934 * k[5];
        let x3219 = x944 * k[6];
        let x3220 = x3218 + x3219;
        let x3221 = x952 * k[5];
        let x3222 = x936 * k[6];
        let x3223 = x3221 + x3222;
        let x3224 = x962 * k[5];
        let x3225 = x963 * k[6];
        let x3226 = x3224 + x3225;
        let x3227 = x969 * k[7];
        let x3228 = x981 * k[8];
        let x3229 = x988 * k[9];
        let x3230 = x3227 + x3228;
        let x3231 = x3229 + x3230;
        let x3232 = x989 * k[7];
        let x3233 = x971 * k[8];
        let x3234 = x997 * k[9];
        let x3235 = x3232 + x3233;
        let x3236 = x3234 + x3235;
        let x3237 = x999 * k[7];
        let x3238 = x1000 * k[8];
        let x3239 = x973 * k[9];
        let x3240 = x3237 + x3238;
        let x3241 = x3239 + x3240;
        let x3243 = x3220 - x3231;
        let x3245 = x3223 - x3236;
        let x3247 = x3226 - x3241;
        let x3248 = x969 * k[10];
        let x3249 = x981 * k[11];
        let x3250 = x988 * k[12];
        let x3251 = x3248 + x3249;
        let x3252 = x3250 + x3251;
        let x3253 = x989 * k[10];
        let x3254 = x971 * k[11];
        let x3255 = x997 * k[12];
        let x3256 = x3253 + x3254;
        let x3257 = x3255 + x3256;
        let x3258 = x999 * k[10];
        let x3259 = x1000 * k[11];
        let x3260 = x973 * k[12];
        let x3261 = x3258 + x3259;
        let x3262 = x3260 + x3261;
        let x3263 = x969 * k[13];
        let x3264 = x981 * k[14];
        let x3265 = x3263 + x3264;
        let x3266 = x989 * k[13];
        let x3267 = x971 * k[14];
        let x3268 = x3266 + x3267;
        let x3269 = x999 * k[13];
        let x3270 = x1000 * k[14];
        let x3271 = x3269 + x3270;
        let x3272 = x323 * x3212;
        let x3273 = x3193 + x3272;
        let x3274 = x3196 + x3273;
        let x3276 = x324 * x3215;
        let x3277 = x3276 - x3197;
        let x3278 = x3277 - x3199;
        let x3280 = x3274 - x3278;
        let x3281 = -x3216;
        let x3282 = -x3217;
        let x3283 = -x3243;
        let x3284 = -x3245;
        let x3285 = -x3247;
        let x3286 = -x3280;
        let x3732 = x2435 * x3265;
        let x3733 = x2515 * x3186;
        let x3734 = x3732 + x3733;
        let x3735 = x2556 * x2928;
        let x3736 = x3733 + x3735;
        let x3737 = x3734 + x3736;
        let x3738 = x2440 * x3268;
        let x3739 = x2522 * x3189;
        let x3740 = x3738 + x3739;
        let x3741 = x2562 * x2931;
        let x3742 = x3739 + x3741;
        let x3743 = x3740 + x3742;
        let x3744 = x2426 * x3271;
        let x3745 = x2498 * x3192;
        let x3746 = x3744 + x3745;
        let x3747 = x2543 * x2934;
        let x3748 = x3745 + x3747;
        let x3749 = x3746 + x3748;
        let x3750 = x3737 + x3743;
        let x3751 = x3749 + x3750;
        let x3752 = -x3751;
        out[0] = x3203;
        out[1] = x3206;
        out[2] = x3209;
        out[3] = x3281;
        out[4] = x3282;
        out[5] = x3283;
        out[6] = x3284;
        out[7] = x3285;
        out[8] = x3252;
        out[9] = x3257;
        out[10] = x3262;
        out[11] = x3752;
        out[12] = x2589;
        out[13] = x2590;
        out[14] = x2591;
        out[15] = x3286;
        out[16] = x1155;
        out[17] = x1156;
        out[18] = x2592;
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
        let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
        let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 19] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 19] = phi.try_into().expect("phi must have 19 entries");
        let phi_q: &mut [f64; 105] = phi_q
            .try_into()
            .expect("phi_q must have 105 entries");
        let phi_t: &mut [f64; 19] = phi_t
            .try_into()
            .expect("phi_t must have 19 entries");
        let gamma: &mut [f64; 19] = gamma
            .try_into()
            .expect("gamma must have 19 entries");
        let mut s = [0.0f64; 132];
        eval_kinematics_shared_0(k, q, qd, t, &mut s);
        eval_kinematics_part_0(k, q, qd, &s, phi, phi_q, phi_t, gamma);
        eval_kinematics_part_1(k, q, qd, t, &s, phi, phi_q, phi_t, gamma);
    }
    #[inline(never)]
    fn eval_kinematics_shared_0(
        k: &[f64; 23],
        q: &[f64; 19],
        qd: &[f64; 19],
        _t: f64,
        s: &mut [f64; 132],
    ) {
        let x14 = q[3] * q[3];
        s[0] = x14;
        let x15 = q[4] * q[4];
        s[1] = x15;
        let x16 = q[5] * q[5];
        s[2] = x16;
        let x18 = x14 + x15;
        s[3] = x18;
        let x19 = 2.0 * x18;
        s[4] = x19;
        let x21 = x19 - 1.0;
        s[5] = x21;
        let x22 = x14 + x16;
        s[6] = x22;
        let x23 = 2.0 * x22;
        s[7] = x23;
        let x24 = x23 - 1.0;
        s[8] = x24;
        let x28 = q[4] * q[5];
        s[9] = x28;
        let x29 = 2.0 * x28;
        s[10] = x29;
        let x30 = q[3] * q[6];
        s[11] = x30;
        let x32 = 2.0 * x30;
        s[12] = x32;
        let x34 = x29 - x32;
        s[13] = x34;
        let x40 = x29 + x32;
        s[14] = x40;
        let x59 = q[10] * q[10];
        s[15] = x59;
        let x60 = q[11] * q[11];
        s[16] = x60;
        let x61 = q[12] * q[12];
        s[17] = x61;
        let x62 = q[13] * q[13];
        s[18] = x62;
        let x63 = x59 + x60;
        s[19] = x63;
        let x64 = 2.0 * x63;
        s[20] = x64;
        let x65 = x64 - 1.0;
        s[21] = x65;
        let x66 = x59 + x61;
        s[22] = x66;
        let x67 = 2.0 * x66;
        s[23] = x67;
        let x68 = x67 - 1.0;
        s[24] = x68;
        let x72 = q[11] * q[12];
        s[25] = x72;
        let x73 = 2.0 * x72;
        s[26] = x73;
        let x74 = q[10] * q[13];
        s[27] = x74;
        let x76 = 2.0 * x74;
        s[28] = x76;
        let x78 = x73 - x76;
        s[29] = x78;
        let x79 = q[11] * q[13];
        s[30] = x79;
        let x80 = 2.0 * x79;
        s[31] = x80;
        let x81 = q[10] * q[12];
        s[32] = x81;
        let x82 = 2.0 * x81;
        s[33] = x82;
        let x84 = x73 + x76;
        s[34] = x84;
        let x85 = q[12] * q[13];
        s[35] = x85;
        let x86 = 2.0 * x85;
        s[36] = x86;
        let x87 = q[10] * q[11];
        s[37] = x87;
        let x89 = 2.0 * x87;
        s[38] = x89;
        let x94 = x80 - x82;
        s[39] = x94;
        let x95 = x86 + x89;
        s[40] = x95;
        let x104 = q[18] * q[18];
        s[41] = x104;
        let x131 = q[17] * q[18];
        s[42] = x131;
        let x133 = 2.0 * x131;
        s[43] = x133;
        let x338 = 2.0 * q[3];
        s[44] = x338;
        let x339 = 2.0 * q[4];
        s[45] = x339;
        let x340 = 2.0 * q[10];
        s[46] = x340;
        let x341 = 2.0 * q[11];
        s[47] = x341;
        let x342 = 2.0 * q[5];
        s[48] = x342;
        let x343 = 2.0 * q[12];
        s[49] = x343;
        let x344 = 2.0 * q[13];
        s[50] = x344;
        let x345 = 2.0 * q[6];
        s[51] = x345;
        let x346 = 2.0 * x338;
        s[52] = x346;
        let x389 = 2.0 * x339;
        s[53] = x389;
        let x414 = 2.0 * x342;
        s[54] = x414;
        let x456 = 2.0 * q[17];
        s[55] = x456;
        let x615 = 2.0 * q[18];
        s[56] = x615;
        let x906 = 2.0 * qd[3];
        s[57] = x906;
        let x907 = 2.0 * qd[4];
        s[58] = x907;
        let x908 = 2.0 * qd[10];
        s[59] = x908;
        let x909 = 2.0 * qd[11];
        s[60] = x909;
        let x910 = 2.0 * qd[5];
        s[61] = x910;
        let x911 = 2.0 * qd[12];
        s[62] = x911;
        let x912 = 2.0 * qd[13];
        s[63] = x912;
        let x929 = qd[3] * x906;
        s[64] = x929;
        let x930 = qd[4] * x907;
        s[65] = x930;
        let x931 = qd[5] * x910;
        s[66] = x931;
        let x933 = x929 + x930;
        s[67] = x933;
        let x934 = 2.0 * x933;
        s[68] = x934;
        let x935 = x929 + x931;
        s[69] = x935;
        let x936 = 2.0 * x935;
        s[70] = x936;
        let x937 = qd[4] * qd[5];
        s[71] = x937;
        let x938 = x937 + x937;
        s[72] = x938;
        let x939 = 2.0 * x938;
        s[73] = x939;
        let x940 = qd[3] * qd[6];
        s[74] = x940;
        let x941 = x940 + x940;
        s[75] = x941;
        let x942 = 2.0 * x941;
        s[76] = x942;
        let x944 = x939 - x942;
        s[77] = x944;
        let x952 = x939 + x942;
        s[78] = x952;
        let x964 = qd[10] * x908;
        s[79] = x964;
        let x965 = qd[11] * x909;
        s[80] = x965;
        let x966 = qd[12] * x911;
        s[81] = x966;
        let x967 = qd[13] * x912;
        s[82] = x967;
        let x968 = x964 + x965;
        s[83] = x968;
        let x969 = 2.0 * x968;
        s[84] = x969;
        let x970 = x964 + x966;
        s[85] = x970;
        let x971 = 2.0 * x970;
        s[86] = x971;
        let x974 = qd[11] * qd[12];
        s[87] = x974;
        let x975 = x974 + x974;
        s[88] = x975;
        let x976 = 2.0 * x975;
        s[89] = x976;
        let x977 = qd[10] * qd[13];
        s[90] = x977;
        let x978 = x977 + x977;
        s[91] = x978;
        let x979 = 2.0 * x978;
        s[92] = x979;
        let x981 = x976 - x979;
        s[93] = x981;
        let x982 = qd[11] * qd[13];
        s[94] = x982;
        let x983 = x982 + x982;
        s[95] = x983;
        let x984 = 2.0 * x983;
        s[96] = x984;
        let x985 = qd[10] * qd[12];
        s[97] = x985;
        let x986 = x985 + x985;
        s[98] = x986;
        let x987 = 2.0 * x986;
        s[99] = x987;
        let x989 = x976 + x979;
        s[100] = x989;
        let x990 = qd[12] * qd[13];
        s[101] = x990;
        let x991 = x990 + x990;
        s[102] = x991;
        let x992 = 2.0 * x991;
        s[103] = x992;
        let x993 = qd[10] * qd[11];
        s[104] = x993;
        let x994 = x993 + x993;
        s[105] = x994;
        let x995 = 2.0 * x994;
        s[106] = x995;
        let x999 = x984 - x987;
        s[107] = x999;
        let x1000 = x992 + x995;
        s[108] = x1000;
        let x2421 = q[15] * q[15];
        s[109] = x2421;
        let x2424 = x104 + x2421;
        s[110] = x2424;
        let x2425 = 2.0 * x2424;
        s[111] = x2425;
        let x2426 = x2425 - 1.0;
        s[112] = x2426;
        let x2431 = q[16] * q[18];
        s[113] = x2431;
        let x2432 = 2.0 * x2431;
        s[114] = x2432;
        let x2433 = q[15] * q[17];
        s[115] = x2433;
        let x2434 = 2.0 * x2433;
        s[116] = x2434;
        let x2435 = x2432 + x2434;
        s[117] = x2435;
        let x2437 = q[15] * q[16];
        s[118] = x2437;
        let x2438 = 2.0 * x2437;
        s[119] = x2438;
        let x2440 = x133 - x2438;
        s[120] = x2440;
        let x2454 = 2.0 * q[15];
        s[121] = x2454;
        let x2476 = 2.0 * q[16];
        s[122] = x2476;
        let x2926 = x65 * k[13];
        s[123] = x2926;
        let x2927 = x78 * k[14];
        s[124] = x2927;
        let x2928 = x2926 + x2927;
        s[125] = x2928;
        let x2929 = x84 * k[13];
        s[126] = x2929;
        let x2930 = x68 * k[14];
        s[127] = x2930;
        let x2931 = x2929 + x2930;
        s[128] = x2931;
        let x2932 = x94 * k[13];
        s[129] = x2932;
        let x2933 = x95 * k[14];
        s[130] = x2933;
        let x2934 = x2932 + x2933;
        s[131] = x2934;
    }
    #[inline(never)]
    fn eval_kinematics_part_0(
        k: &[f64; 23],
        q: &[f64; 19],
        qd: &[f64; 19],
        s: &[f64; 132],
        phi: &mut [f64; 19],
        phi_q: &mut [f64; 105],
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
        let x51 = x42 + x45;
        let x69 = s[15] + s[18];
        let x70 = 2.0 * x69;
        let x71 = x70 - 1.0;
        let x83 = s[31] + s[33];
        let x91 = s[36] - s[38];
        let x452 = 2.0 * s[46];
        let x516 = 2.0 * s[47];
        let x554 = 2.0 * s[49];
        let x588 = 2.0 * s[50];
        let x945 = qd[4] * qd[6];
        let x946 = x945 + x945;
        let x947 = 2.0 * x946;
        let x948 = qd[3] * qd[5];
        let x949 = x948 + x948;
        let x950 = 2.0 * x949;
        let x951 = x947 + x950;
        let x953 = qd[5] * qd[6];
        let x954 = x953 + x953;
        let x955 = 2.0 * x954;
        let x956 = qd[3] * qd[4];
        let x957 = x956 + x956;
        let x958 = 2.0 * x957;
        let x960 = x955 - x958;
        let x962 = x947 - x950;
        let x963 = x955 + x958;
        let x972 = s[79] + s[82];
        let x973 = 2.0 * x972;
        let x988 = s[96] + s[99];
        let x997 = s[103] - s[106];
        let x2139 = 2.0 * s[56];
        let x2477 = 2.0 * s[121];
        let x2836 = s[5] * k[0];
        let x2837 = s[13] * k[1];
        let x2838 = x2836 + x2837;
        let x2839 = s[14] * k[0];
        let x2840 = s[8] * k[1];
        let x2841 = x2839 + x2840;
        let x2842 = x50 * k[0];
        let x2843 = x51 * k[1];
        let x2844 = x2842 + x2843;
        let x2845 = q[0] + x2838;
        let x2846 = q[1] + x2841;
        let x2847 = q[2] + x2844;
        let x2857 = x39 * k[4];
        let x2858 = x47 * k[4];
        let x2859 = -x2845;
        let x2860 = -x2846;
        let x2861 = -x2847;
        let x2864 = s[5] * k[5];
        let x2865 = s[13] * k[6];
        let x2866 = x2864 + x2865;
        let x2867 = s[14] * k[5];
        let x2868 = s[8] * k[6];
        let x2869 = x2867 + x2868;
        let x2870 = x50 * k[5];
        let x2871 = x51 * k[6];
        let x2872 = x2870 + x2871;
        let x2873 = q[0] + x2866;
        let x2874 = q[1] + x2869;
        let x2875 = q[2] + x2872;
        let x2879 = s[21] * k[7];
        let x2880 = s[29] * k[8];
        let x2881 = x83 * k[9];
        let x2882 = x2879 + x2880;
        let x2883 = x2881 + x2882;
        let x2884 = s[34] * k[7];
        let x2885 = s[24] * k[8];
        let x2886 = x91 * k[9];
        let x2887 = x2884 + x2885;
        let x2888 = x2886 + x2887;
        let x2889 = s[39] * k[7];
        let x2890 = s[40] * k[8];
        let x2891 = x71 * k[9];
        let x2892 = x2889 + x2890;
        let x2893 = x2891 + x2892;
        let x2894 = q[7] + x2883;
        let x2895 = q[8] + x2888;
        let x2896 = q[9] + x2893;
        let x2898 = x2873 - x2894;
        let x2900 = x2874 - x2895;
        let x2902 = x2875 - x2896;
        let x2906 = s[21] * k[10];
        let x2907 = s[29] * k[11];
        let x2908 = x83 * k[12];
        let x2909 = x2906 + x2907;
        let x2910 = x2908 + x2909;
        let x2911 = s[34] * k[10];
        let x2912 = s[24] * k[11];
        let x2913 = x91 * k[12];
        let x2914 = x2911 + x2912;
        let x2915 = x2913 + x2914;
        let x2916 = s[39] * k[10];
        let x2917 = s[40] * k[11];
        let x2918 = x71 * k[12];
        let x2919 = x2916 + x2917;
        let x2920 = x2918 + x2919;
        let x2921 = q[7] + x2910;
        let x2922 = q[8] + x2915;
        let x2923 = q[9] + x2920;
        let x2936 = q[14] - x2921;
        let x2945 = s[52] * k[0];
        let x2946 = s[51] * k[1];
        let x2948 = x2945 - x2946;
        let x2949 = s[51] * k[0];
        let x2950 = s[52] * k[1];
        let x2951 = x2949 + x2950;
        let x2952 = s[48] * k[0];
        let x2953 = -x2952;
        let x2954 = s[45] * k[1];
        let x2955 = x2954 - x2952;
        let x2963 = s[48] * k[4];
        let x2964 = s[45] * k[4];
        let x2965 = -x2964;
        let x2966 = -x2948;
        let x2967 = -x2951;
        let x2968 = -x2955;
        let x2969 = s[52] * k[5];
        let x2970 = s[51] * k[6];
        let x2972 = x2969 - x2970;
        let x2973 = s[51] * k[5];
        let x2974 = s[52] * k[6];
        let x2975 = x2973 + x2974;
        let x2976 = s[48] * k[5];
        let x2978 = s[45] * k[6];
        let x2979 = x2978 - x2976;
        let x2984 = s[53] * k[0];
        let x2985 = s[48] * k[1];
        let x2986 = x2984 + x2985;
        let x2987 = s[44] * k[1];
        let x2988 = x2949 + x2987;
        let x2993 = s[51] * k[4];
        let x2994 = s[44] * k[4];
        let x2995 = -x2994;
        let x2996 = -x2986;
        let x2997 = -x2988;
        let x2998 = s[53] * k[5];
        let x2999 = s[48] * k[6];
        let x3000 = x2998 + x2999;
        let x3001 = s[44] * k[6];
        let x3002 = x2973 + x3001;
        let x3007 = s[45] * k[0];
        let x3008 = s[54] * k[1];
        let x3009 = x3007 + x3008;
        let x3010 = s[44] * k[0];
        let x3011 = -x3010;
        let x3012 = x2946 - x3010;
        let x3017 = -x2954;
        let x3018 = -x3009;
        let x3019 = -x3012;
        let x3020 = s[45] * k[5];
        let x3021 = s[54] * k[6];
        let x3022 = x3020 + x3021;
        let x3023 = s[44] * k[5];
        let x3025 = x2970 - x3023;
        let x3030 = x2985 + x3007;
        let x3033 = -x3030;
        let x3034 = -x3001;
        let x3035 = x2999 + x3020;
        let x3040 = x452 * k[7];
        let x3041 = s[50] * k[8];
        let x3043 = s[49] * k[9];
        let x3044 = x3040 - x3041;
        let x3045 = x3043 + x3044;
        let x3046 = s[50] * k[7];
        let x3047 = x452 * k[8];
        let x3048 = s[47] * k[9];
        let x3050 = x3046 + x3047;
        let x3051 = x3050 - x3048;
        let x3052 = s[49] * k[7];
        let x3054 = s[47] * k[8];
        let x3055 = x452 * k[9];
        let x3056 = x3054 - x3052;
        let x3057 = x3055 + x3056;
        let x3058 = -x3045;
        let x3059 = -x3051;
        let x3060 = -x3057;
        let x3061 = x452 * k[10];
        let x3062 = s[50] * k[11];
        let x3064 = s[49] * k[12];
        let x3065 = x3061 - x3062;
        let x3066 = x3064 + x3065;
        let x3067 = s[50] * k[10];
        let x3068 = x452 * k[11];
        let x3069 = s[47] * k[12];
        let x3071 = x3067 + x3068;
        let x3072 = x3071 - x3069;
        let x3073 = s[49] * k[10];
        let x3075 = s[47] * k[11];
        let x3076 = x452 * k[12];
        let x3077 = x3075 - x3073;
        let x3078 = x3076 + x3077;
        let x3079 = x452 * k[13];
        let x3080 = s[50] * k[14];
        let x3082 = x3079 - x3080;
        let x3083 = s[50] * k[13];
        let x3084 = x452 * k[14];
        let x3085 = x3083 + x3084;
        let x3086 = s[49] * k[13];
        let x3088 = s[47] * k[14];
        let x3089 = x3088 - x3086;
        let x3090 = -x3066;
        let x3091 = -x3072;
        let x3092 = -x3078;
        let x3093 = x516 * k[7];
        let x3094 = s[49] * k[8];
        let x3095 = s[50] * k[9];
        let x3096 = x3093 + x3094;
        let x3097 = x3095 + x3096;
        let x3098 = s[46] * k[9];
        let x3100 = x3052 - x3098;
        let x3101 = s[46] * k[8];
        let x3102 = x3046 + x3101;
        let x3103 = -x3097;
        let x3104 = -x3100;
        let x3105 = -x3102;
        let x3106 = x516 * k[10];
        let x3107 = s[49] * k[11];
        let x3108 = s[50] * k[12];
        let x3109 = x3106 + x3107;
        let x3110 = x3108 + x3109;
        let x3111 = s[46] * k[12];
        let x3113 = x3073 - x3111;
        let x3114 = s[46] * k[11];
        let x3115 = x3067 + x3114;
        let x3116 = x516 * k[13];
        let x3117 = s[49] * k[14];
        let x3118 = x3116 + x3117;
        let x3119 = s[46] * k[14];
        let x3120 = x3083 + x3119;
        let x3121 = -x3110;
        let x3122 = -x3113;
        let x3123 = -x3115;
        let x3124 = x3054 + x3098;
        let x3125 = s[47] * k[7];
        let x3126 = x554 * k[8];
        let x3127 = x3125 + x3126;
        let x3128 = x3095 + x3127;
        let x3129 = s[46] * k[7];
        let x3131 = x3041 - x3129;
        let x3132 = -x3124;
        let x3133 = -x3128;
        let x3134 = -x3131;
        let x3135 = x3075 + x3111;
        let x3136 = s[47] * k[10];
        let x3137 = x554 * k[11];
        let x3138 = x3136 + x3137;
        let x3139 = x3108 + x3138;
        let x3140 = s[46] * k[10];
        let x3142 = x3062 - x3140;
        let x3143 = s[47] * k[13];
        let x3144 = x554 * k[14];
        let x3145 = x3143 + x3144;
        let x3146 = s[46] * k[13];
        let x3148 = x3080 - x3146;
        let x3149 = -x3135;
        let x3150 = -x3139;
        let x3151 = -x3142;
        let x3153 = x3048 - x3101;
        let x3154 = x3043 + x3129;
        let x3155 = x588 * k[9];
        let x3156 = x3094 + x3125;
        let x3157 = x3155 + x3156;
        let x3158 = -x3153;
        let x3159 = -x3154;
        let x3160 = -x3157;
        let x3162 = x3069 - x3114;
        let x3163 = x3064 + x3140;
        let x3164 = x588 * k[12];
        let x3165 = x3107 + x3136;
        let x3166 = x3164 + x3165;
        let x3167 = x3117 + x3143;
        let x3168 = -x3162;
        let x3169 = -x3163;
        let x3170 = -x3166;
        let x3171 = s[56] * s[128];
        let x3172 = s[55] * s[128];
        let x3173 = s[55] * s[125];
        let x3174 = s[56] * s[125];
        let x3201 = s[68] * k[0];
        let x3202 = s[77] * k[1];
        let x3203 = x3201 + x3202;
        let x3204 = s[78] * k[0];
        let x3205 = s[70] * k[1];
        let x3206 = x3204 + x3205;
        let x3207 = x962 * k[0];
        let x3208 = x963 * k[1];
        let x3209 = x3207 + x3208;
        let x3216 = x951 * k[4];
        let x3217 = x960 * k[4];
        let x3218 = s[68] * k[5];
        let x3219 = s[77] * k[6];
        let x3220 = x3218 + x3219;
        let x3221 = s[78] * k[5];
        let x3222 = s[70] * k[6];
        let x3223 = x3221 + x3222;
        let x3224 = x962 * k[5];
        let x3225 = x963 * k[6];
        let x3226 = x3224 + x3225;
        let x3227 = s[84] * k[7];
        let x3228 = s[93] * k[8];
        let x3229 = x988 * k[9];
        let x3230 = x3227 + x3228;
        let x3231 = x3229 + x3230;
        let x3232 = s[100] * k[7];
        let x3233 = s[86] * k[8];
        let x3234 = x997 * k[9];
        let x3235 = x3232 + x3233;
        let x3236 = x3234 + x3235;
        let x3237 = s[107] * k[7];
        let x3238 = s[108] * k[8];
        let x3239 = x973 * k[9];
        let x3240 = x3237 + x3238;
        let x3241 = x3239 + x3240;
        let x3243 = x3220 - x3231;
        let x3245 = x3223 - x3236;
        let x3247 = x3226 - x3241;
        let x3248 = s[84] * k[10];
        let x3249 = s[93] * k[11];
        let x3250 = x988 * k[12];
        let x3251 = x3248 + x3249;
        let x3252 = x3250 + x3251;
        let x3253 = s[100] * k[10];
        let x3254 = s[86] * k[11];
        let x3255 = x997 * k[12];
        let x3256 = x3253 + x3254;
        let x3257 = x3255 + x3256;
        let x3258 = s[107] * k[10];
        let x3259 = s[108] * k[11];
        let x3260 = x973 * k[12];
        let x3261 = x3258 + x3259;
        let x3262 = x3260 + x3261;
        let x3281 = -x3216;
        let x3282 = -x3217;
        let x3283 = -x3243;
        let x3284 = -x3245;
        let x3285 = -x3247;
        let x3690 = k[15] - x2922;
        let x3691 = k[16] - x2923;
        let x3692 = s[117] * s[125];
        let x3693 = s[120] * s[128];
        let x3694 = s[112] * s[131];
        let x3695 = x3692 + x3693;
        let x3696 = x3694 + x3695;
        let x3697 = s[117] * x3082;
        let x3698 = s[120] * x3085;
        let x3699 = s[112] * x3089;
        let x3700 = x3697 + x3698;
        let x3701 = x3699 + x3700;
        let x3702 = s[117] * x3118;
        let x3703 = s[120] * x3086;
        let x3704 = s[112] * x3120;
        let x3705 = x3702 + x3703;
        let x3706 = x3704 + x3705;
        let x3707 = s[117] * x3088;
        let x3708 = s[120] * x3145;
        let x3709 = s[112] * x3148;
        let x3710 = x3707 + x3708;
        let x3711 = x3709 + x3710;
        let x3712 = s[117] * x3119;
        let x3714 = s[120] * x3146;
        let x3715 = s[112] * x3167;
        let x3716 = x3714 - x3712;
        let x3717 = x3715 + x3716;
        let x3718 = s[122] * s[128];
        let x3720 = x2477 * s[131];
        let x3721 = x3173 - x3718;
        let x3722 = x3720 + x3721;
        let x3723 = s[121] * s[128];
        let x3725 = x3174 - x3723;
        let x3726 = s[121] * s[125];
        let x3727 = x3171 + x3726;
        let x3728 = s[122] * s[125];
        let x3729 = x2139 * s[131];
        let x3730 = x3172 + x3728;
        let x3731 = x3729 + x3730;
        phi[0] = x2859;
        phi_q[0] = -1.0;
        phi_q[1] = x2966;
        phi_q[2] = x2996;
        phi_q[3] = x3017;
        phi_q[4] = x2987;
        phi_t[0] = 0.0;
        gamma[0] = x3203;
        phi[1] = x2860;
        phi_q[5] = -1.0;
        phi_q[6] = x2967;
        phi_q[7] = x2953;
        phi_q[8] = x3018;
        phi_q[9] = x3011;
        phi_t[1] = 0.0;
        gamma[1] = x3206;
        phi[2] = x2861;
        phi_q[10] = -1.0;
        phi_q[11] = x2968;
        phi_q[12] = x2997;
        phi_q[13] = x3019;
        phi_q[14] = x3033;
        phi_t[2] = 0.0;
        gamma[2] = x3209;
        phi[3] = x2857;
        phi_q[15] = x2963;
        phi_q[16] = x2993;
        phi_q[17] = x2994;
        phi_q[18] = x2964;
        phi_t[3] = 0.0;
        gamma[3] = x3281;
        phi[4] = x2858;
        phi_q[19] = x2965;
        phi_q[20] = x2995;
        phi_q[21] = x2993;
        phi_q[22] = x2963;
        phi_t[4] = 0.0;
        gamma[4] = x3282;
        phi[5] = x2898;
        phi_q[23] = 1.0;
        phi_q[24] = x2972;
        phi_q[25] = x3000;
        phi_q[26] = x2978;
        phi_q[27] = x3034;
        phi_q[28] = -1.0;
        phi_q[29] = x3058;
        phi_q[30] = x3103;
        phi_q[31] = x3132;
        phi_q[32] = x3158;
        phi_t[5] = 0.0;
        gamma[5] = x3283;
        phi[6] = x2900;
        phi_q[33] = 1.0;
        phi_q[34] = x2975;
        phi_q[35] = x2976;
        phi_q[36] = x3022;
        phi_q[37] = x3023;
        phi_q[38] = -1.0;
        phi_q[39] = x3059;
        phi_q[40] = x3104;
        phi_q[41] = x3133;
        phi_q[42] = x3159;
        phi_t[6] = 0.0;
        gamma[6] = x3284;
        phi[7] = x2902;
        phi_q[43] = 1.0;
        phi_q[44] = x2979;
        phi_q[45] = x3002;
        phi_q[46] = x3025;
        phi_q[47] = x3035;
        phi_q[48] = -1.0;
        phi_q[49] = x3060;
        phi_q[50] = x3105;
        phi_q[51] = x3134;
        phi_q[52] = x3160;
        phi_t[7] = 0.0;
        gamma[7] = x3285;
        phi[8] = x2936;
        phi_q[53] = -1.0;
        phi_q[54] = x3090;
        phi_q[55] = x3121;
        phi_q[56] = x3149;
        phi_q[57] = x3168;
        phi_q[58] = 1.0;
        phi_t[8] = 0.0;
        gamma[8] = x3252;
        phi[9] = x3690;
        phi_q[59] = -1.0;
        phi_q[60] = x3091;
        phi_q[61] = x3122;
        phi_q[62] = x3150;
        phi_q[63] = x3169;
        phi_t[9] = 0.0;
        gamma[9] = x3257;
        phi[10] = x3691;
        phi_q[64] = -1.0;
        phi_q[65] = x3092;
        phi_q[66] = x3123;
        phi_q[67] = x3151;
        phi_q[68] = x3170;
        phi_t[10] = 0.0;
        gamma[10] = x3262;
        phi[11] = x3696;
        phi_q[69] = x3701;
        phi_q[70] = x3706;
        phi_q[71] = x3711;
        phi_q[72] = x3717;
        phi_q[73] = x3722;
        phi_q[74] = x3725;
        phi_q[75] = x3727;
        phi_q[76] = x3731;
        phi_t[11] = 0.0;
    }
    #[inline(never)]
    fn eval_kinematics_part_1(
        k: &[f64; 23],
        q: &[f64; 19],
        qd: &[f64; 19],
        t: f64,
        s: &[f64; 132],
        phi: &mut [f64; 19],
        phi_q: &mut [f64; 105],
        phi_t: &mut [f64; 19],
        gamma: &mut [f64; 19],
    ) {
        let x5 = 6.283185307179586 * t;
        let x17 = q[6] * q[6];
        let x103 = q[17] * q[17];
        let x323 = x5.sin();
        let x324 = x5.cos();
        let x329 = s[2] + s[3];
        let x330 = x17 + x329;
        let x331 = x330 - 1.0;
        let x332 = s[17] + s[19];
        let x333 = s[18] + x332;
        let x334 = x333 - 1.0;
        let x626 = -s[55];
        let x640 = 6.283185307179586 * x324;
        let x642 = 6.283185307179586 * x323;
        let x669 = s[44] * qd[3];
        let x670 = s[45] * qd[4];
        let x671 = s[48] * qd[5];
        let x673 = x669 + x670;
        let x674 = 2.0 * x673;
        let x675 = x669 + x671;
        let x676 = 2.0 * x675;
        let x677 = q[5] * qd[4];
        let x678 = q[4] * qd[5];
        let x679 = x677 + x678;
        let x680 = 2.0 * x679;
        let x681 = q[6] * qd[3];
        let x682 = q[3] * qd[6];
        let x683 = x681 + x682;
        let x684 = 2.0 * x683;
        let x686 = x680 - x684;
        let x696 = x680 + x684;
        let x710 = s[46] * qd[10];
        let x711 = s[47] * qd[11];
        let x712 = s[49] * qd[12];
        let x714 = x710 + x711;
        let x715 = 2.0 * x714;
        let x716 = x710 + x712;
        let x717 = 2.0 * x716;
        let x720 = q[12] * qd[11];
        let x721 = q[11] * qd[12];
        let x722 = x720 + x721;
        let x723 = 2.0 * x722;
        let x724 = q[13] * qd[10];
        let x725 = q[10] * qd[13];
        let x726 = x724 + x725;
        let x727 = 2.0 * x726;
        let x729 = x723 - x727;
        let x730 = q[13] * qd[11];
        let x731 = q[11] * qd[13];
        let x732 = x730 + x731;
        let x733 = 2.0 * x732;
        let x734 = q[12] * qd[10];
        let x735 = q[10] * qd[12];
        let x736 = x734 + x735;
        let x737 = 2.0 * x736;
        let x739 = x723 + x727;
        let x740 = q[13] * qd[12];
        let x741 = q[12] * qd[13];
        let x742 = x740 + x741;
        let x743 = 2.0 * x742;
        let x744 = q[11] * qd[10];
        let x745 = q[10] * qd[11];
        let x746 = x744 + x745;
        let x747 = 2.0 * x746;
        let x751 = x733 - x737;
        let x752 = x743 + x747;
        let x754 = s[56] * qd[18];
        let x782 = q[18] * qd[17];
        let x783 = q[17] * qd[18];
        let x784 = x782 + x783;
        let x785 = 2.0 * x784;
        let x913 = 2.0 * qd[6];
        let x914 = 2.0 * qd[17];
        let x916 = 2.0 * qd[18];
        let x918 = 6.283185307179586 * x642;
        let x920 = 6.283185307179586 * x640;
        let x932 = qd[6] * x913;
        let x1001 = qd[17] * x914;
        let x1002 = qd[18] * x916;
        let x1025 = qd[17] * qd[18];
        let x1026 = x1025 + x1025;
        let x1027 = 2.0 * x1026;
        let x1139 = s[66] + s[67];
        let x1140 = x932 + x1139;
        let x1141 = s[81] + s[83];
        let x1142 = s[82] + x1141;
        let x1155 = -x1140;
        let x1156 = -x1142;
        let x2073 = 2.0 * qd[15];
        let x2075 = 2.0 * qd[16];
        let x2422 = q[16] * q[16];
        let x2423 = s[109] + x2422;
        let x2427 = q[16] * q[17];
        let x2428 = 2.0 * x2427;
        let x2429 = q[15] * q[18];
        let x2430 = 2.0 * x2429;
        let x2436 = x2428 + x2430;
        let x2442 = s[114] - s[116];
        let x2443 = s[43] + s[119];
        let x2451 = x103 + x2423;
        let x2452 = s[41] + x2451;
        let x2453 = x2452 - 1.0;
        let x2484 = -s[121];
        let x2494 = qd[15] * s[121];
        let x2497 = x754 + x2494;
        let x2498 = 2.0 * x2497;
        let x2507 = q[18] * qd[16];
        let x2508 = q[16] * qd[18];
        let x2509 = x2507 + x2508;
        let x2510 = 2.0 * x2509;
        let x2511 = q[17] * qd[15];
        let x2512 = q[15] * qd[17];
        let x2513 = x2511 + x2512;
        let x2514 = 2.0 * x2513;
        let x2515 = x2510 + x2514;
        let x2517 = q[16] * qd[15];
        let x2518 = q[15] * qd[16];
        let x2519 = x2517 + x2518;
        let x2520 = 2.0 * x2519;
        let x2522 = x785 - x2520;
        let x2539 = qd[15] * x2073;
        let x2540 = qd[16] * x2075;
        let x2541 = x2539 + x2540;
        let x2542 = x1002 + x2539;
        let x2543 = 2.0 * x2542;
        let x2544 = qd[16] * qd[17];
        let x2545 = x2544 + x2544;
        let x2546 = 2.0 * x2545;
        let x2547 = qd[15] * qd[18];
        let x2548 = x2547 + x2547;
        let x2549 = 2.0 * x2548;
        let x2550 = qd[16] * qd[18];
        let x2551 = x2550 + x2550;
        let x2552 = 2.0 * x2551;
        let x2553 = qd[15] * qd[17];
        let x2554 = x2553 + x2553;
        let x2555 = 2.0 * x2554;
        let x2556 = x2552 + x2555;
        let x2557 = x2546 + x2549;
        let x2558 = qd[15] * qd[16];
        let x2559 = x2558 + x2558;
        let x2560 = 2.0 * x2559;
        let x2562 = x1027 - x2560;
        let x2564 = x2552 - x2555;
        let x2565 = x1027 + x2560;
        let x2586 = x1001 + x2541;
        let x2587 = x1002 + x2586;
        let x2589 = -x2557;
        let x2590 = -x2564;
        let x2591 = -x2565;
        let x2592 = -x2587;
        let x2850 = s[5] * k[2];
        let x2851 = s[13] * k[3];
        let x2852 = x2850 + x2851;
        let x2853 = s[14] * k[2];
        let x2854 = s[8] * k[3];
        let x2855 = x2853 + x2854;
        let x2941 = x323 * x2852;
        let x2942 = x324 * x2855;
        let x2944 = x2941 - x2942;
        let x2956 = s[52] * k[2];
        let x2957 = s[51] * k[3];
        let x2959 = x2956 - x2957;
        let x2960 = s[51] * k[2];
        let x2961 = s[52] * k[3];
        let x2962 = x2960 + x2961;
        let x2980 = x323 * x2959;
        let x2981 = x324 * x2962;
        let x2983 = x2980 - x2981;
        let x2989 = s[53] * k[2];
        let x2990 = s[48] * k[3];
        let x2991 = x2989 + x2990;
        let x2992 = s[48] * k[2];
        let x3003 = x323 * x2991;
        let x3004 = x324 * x2992;
        let x3006 = x3003 - x3004;
        let x3013 = s[45] * k[3];
        let x3014 = s[45] * k[2];
        let x3015 = s[54] * k[3];
        let x3016 = x3014 + x3015;
        let x3026 = x323 * x3013;
        let x3027 = x324 * x3016;
        let x3029 = x3026 - x3027;
        let x3031 = s[44] * k[3];
        let x3032 = s[44] * k[2];
        let x3036 = x323 * x3031;
        let x3037 = x324 * x3032;
        let x3038 = x3036 + x3037;
        let x3039 = -x3038;
        let x3175 = x640 * x2852;
        let x3176 = x642 * x2855;
        let x3177 = x3175 + x3176;
        let x3178 = x674 * k[2];
        let x3179 = x686 * k[3];
        let x3180 = x3178 + x3179;
        let x3181 = x696 * k[2];
        let x3182 = x676 * k[3];
        let x3183 = x3181 + x3182;
        let x3184 = x715 * k[13];
        let x3185 = x729 * k[14];
        let x3186 = x3184 + x3185;
        let x3187 = x739 * k[13];
        let x3188 = x717 * k[14];
        let x3189 = x3187 + x3188;
        let x3190 = x751 * k[13];
        let x3191 = x752 * k[14];
        let x3192 = x3190 + x3191;
        let x3193 = x640 * x3180;
        let x3194 = x918 * x2852;
        let x3196 = x3193 - x3194;
        let x3197 = x642 * x3183;
        let x3198 = x920 * x2855;
        let x3199 = x3197 + x3198;
        let x3210 = s[68] * k[2];
        let x3211 = s[77] * k[3];
        let x3212 = x3210 + x3211;
        let x3213 = s[78] * k[2];
        let x3214 = s[70] * k[3];
        let x3215 = x3213 + x3214;
        let x3263 = s[84] * k[13];
        let x3264 = s[93] * k[14];
        let x3265 = x3263 + x3264;
        let x3266 = s[100] * k[13];
        let x3267 = s[86] * k[14];
        let x3268 = x3266 + x3267;
        let x3269 = s[107] * k[13];
        let x3270 = s[108] * k[14];
        let x3271 = x3269 + x3270;
        let x3272 = x323 * x3212;
        let x3273 = x3193 + x3272;
        let x3274 = x3196 + x3273;
        let x3276 = x324 * x3215;
        let x3277 = x3276 - x3197;
        let x3278 = x3277 - x3199;
        let x3280 = x3274 - x3278;
        let x3286 = -x3280;
        let x3732 = s[117] * x3265;
        let x3733 = x2515 * x3186;
        let x3734 = x3732 + x3733;
        let x3735 = x2556 * s[125];
        let x3736 = x3733 + x3735;
        let x3737 = x3734 + x3736;
        let x3738 = s[120] * x3268;
        let x3739 = x2522 * x3189;
        let x3740 = x3738 + x3739;
        let x3741 = x2562 * s[128];
        let x3742 = x3739 + x3741;
        let x3743 = x3740 + x3742;
        let x3744 = s[112] * x3271;
        let x3745 = x2498 * x3192;
        let x3746 = x3744 + x3745;
        let x3747 = x2543 * s[131];
        let x3748 = x3745 + x3747;
        let x3749 = x3746 + x3748;
        let x3750 = x3737 + x3743;
        let x3751 = x3749 + x3750;
        let x3752 = -x3751;
        gamma[11] = x3752;
        phi[12] = x2436;
        phi_q[77] = s[56];
        phi_q[78] = s[55];
        phi_q[79] = s[122];
        phi_q[80] = s[121];
        phi_t[12] = 0.0;
        gamma[12] = x2589;
        phi[13] = x2442;
        phi_q[81] = x626;
        phi_q[82] = s[56];
        phi_q[83] = x2484;
        phi_q[84] = s[122];
        phi_t[13] = 0.0;
        gamma[13] = x2590;
        phi[14] = x2443;
        phi_q[85] = s[122];
        phi_q[86] = s[121];
        phi_q[87] = s[56];
        phi_q[88] = s[55];
        phi_t[14] = 0.0;
        gamma[14] = x2591;
        phi[15] = x2944;
        phi_q[89] = x2983;
        phi_q[90] = x3006;
        phi_q[91] = x3029;
        phi_q[92] = x3039;
        phi_t[15] = x3177;
        gamma[15] = x3286;
        phi[16] = x331;
        phi_q[93] = s[44];
        phi_q[94] = s[45];
        phi_q[95] = s[48];
        phi_q[96] = s[51];
        phi_t[16] = 0.0;
        gamma[16] = x1155;
        phi[17] = x334;
        phi_q[97] = s[46];
        phi_q[98] = s[47];
        phi_q[99] = s[49];
        phi_q[100] = s[50];
        phi_t[17] = 0.0;
        gamma[17] = x1156;
        phi[18] = x2453;
        phi_q[101] = s[121];
        phi_q[102] = s[122];
        phi_q[103] = s[55];
        phi_q[104] = s[56];
        phi_t[18] = 0.0;
        gamma[18] = x2592;
    }
    /// Potential energy of gravity and springs, written to `out[0]`.
    pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
        let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        potential_into_part_0(k, q, out);
    }
    #[inline(never)]
    fn potential_into_part_0(k: &[f64; 23], q: &[f64; 19], out: &mut [f64; 1]) {
        let x1185 = q[1] * 2.943;
        let x1188 = q[8] * 5.886;
        let x1191 = x1185 + x1188;
        let x3754 = x1191 + k[22];
        out[0] = x3754;
    }
    /// Power of the non-conservative loads, written to `out[0]`.
    pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
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
            let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
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
            let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
            let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
            let out: &mut [f64; 55] = out.try_into().expect("out must have 55 entries");
            mass_part_0(k, q, out);
        }
        #[inline(never)]
        fn mass_part_0(k: &[f64; 23], q: &[f64; 19], out: &mut [f64; 55]) {
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
            let x338 = 2.0 * q[3];
            let x339 = 2.0 * q[4];
            let x340 = 2.0 * q[10];
            let x341 = 2.0 * q[11];
            let x342 = 2.0 * q[5];
            let x343 = 2.0 * q[12];
            let x344 = 2.0 * q[13];
            let x345 = 2.0 * q[6];
            let x346 = 2.0 * x338;
            let x389 = 2.0 * x339;
            let x414 = 2.0 * x342;
            let x452 = 2.0 * x340;
            let x456 = 2.0 * q[17];
            let x516 = 2.0 * x341;
            let x554 = 2.0 * x343;
            let x588 = 2.0 * x344;
            let x615 = 2.0 * q[18];
            let x617 = 2.0 * x456;
            let x1306 = 2.0 * x345;
            let x1308 = x339 * x389;
            let x1312 = x342 * x414;
            let x1316 = x345 * x1306;
            let x1328 = x339 * x346;
            let x1330 = x342 * x1306;
            let x1334 = x345 * x414;
            let x1342 = x339 * x1306;
            let x1344 = x342 * x346;
            let x1346 = x345 * x389;
            let x1356 = x339 * x414;
            let x1360 = x342 * x389;
            let x1362 = x345 * x346;
            let x1370 = x338 * x389;
            let x1380 = x338 * x346;
            let x1387 = x338 * x1306;
            let x1397 = x338 * x414;
            let x1728 = x341 * x516;
            let x1732 = x343 * x554;
            let x1736 = x344 * x588;
            let x1748 = x341 * x452;
            let x1750 = x343 * x588;
            let x1754 = x344 * x554;
            let x1762 = x341 * x588;
            let x1764 = x343 * x452;
            let x1766 = x344 * x516;
            let x1776 = x341 * x554;
            let x1780 = x343 * x516;
            let x1782 = x344 * x452;
            let x1790 = x340 * x516;
            let x1800 = x340 * x452;
            let x1807 = x340 * x588;
            let x1817 = x340 * x554;
            let x2139 = 2.0 * x615;
            let x2144 = x615 * x2139;
            let x2146 = 0.001 * x2144;
            let x2162 = x103 * 0.004;
            let x2164 = x615 * x617;
            let x2165 = 0.001 * x2164;
            let x2176 = x131 * 0.004;
            let x2206 = x456 * x2139;
            let x2208 = 0.001 * x2206;
            let x2216 = x456 * x617;
            let x2217 = 0.001 * x2216;
            let x2221 = x104 * 0.004;
            let x2421 = q[15] * q[15];
            let x2422 = q[16] * q[16];
            let x2427 = q[16] * q[17];
            let x2429 = q[15] * q[18];
            let x2431 = q[16] * q[18];
            let x2433 = q[15] * q[17];
            let x2437 = q[15] * q[16];
            let x2454 = 2.0 * q[15];
            let x2476 = 2.0 * q[16];
            let x2477 = 2.0 * x2454;
            let x2595 = 2.0 * x2476;
            let x2596 = x2476 * x2595;
            let x2597 = 0.001 * x2596;
            let x2598 = x2217 + x2597;
            let x2599 = x2146 + x2598;
            let x2600 = 0.5 * x2599;
            let x2601 = 0.004 * x2421;
            let x2602 = x2600 + x2601;
            let x2603 = x2476 * x2477;
            let x2604 = 0.001 * x2603;
            let x2605 = x2604 - x2208;
            let x2606 = x2165 + x2605;
            let x2607 = 0.5 * x2606;
            let x2609 = 0.004 * x2437;
            let x2610 = x2609 - x2607;
            let x2611 = x2139 * x2476;
            let x2612 = 0.001 * x2611;
            let x2613 = x456 * x2477;
            let x2614 = 0.001 * x2613;
            let x2615 = x615 * x2595;
            let x2616 = 0.001 * x2615;
            let x2618 = x2612 + x2614;
            let x2619 = x2618 - x2616;
            let x2620 = 0.5 * x2619;
            let x2622 = 0.004 * x2433;
            let x2623 = x2622 - x2620;
            let x2624 = x617 * x2476;
            let x2625 = 0.001 * x2624;
            let x2627 = x456 * x2595;
            let x2628 = 0.001 * x2627;
            let x2629 = x615 * x2477;
            let x2630 = 0.001 * x2629;
            let x2631 = x2628 - x2625;
            let x2632 = x2630 + x2631;
            let x2633 = 0.5 * x2632;
            let x2635 = 0.004 * x2429;
            let x2636 = x2635 - x2633;
            let x2637 = x2454 * x2595;
            let x2638 = 0.001 * x2637;
            let x2640 = x2165 - x2638;
            let x2641 = x2640 - x2208;
            let x2642 = 0.5 * x2641;
            let x2643 = x2609 + x2642;
            let x2644 = x2454 * x2477;
            let x2645 = 0.001 * x2644;
            let x2646 = x2146 + x2645;
            let x2647 = x2217 + x2646;
            let x2648 = 0.5 * x2647;
            let x2649 = 0.004 * x2422;
            let x2650 = x2648 + x2649;
            let x2651 = x2139 * x2454;
            let x2652 = 0.001 * x2651;
            let x2655 = x2652 - x2630;
            let x2656 = x2655 - x2628;
            let x2657 = 0.5 * x2656;
            let x2658 = 0.004 * x2427;
            let x2659 = x2657 + x2658;
            let x2660 = x617 * x2454;
            let x2661 = 0.001 * x2660;
            let x2662 = x2616 + x2661;
            let x2664 = x2614 - x2662;
            let x2665 = 0.5 * x2664;
            let x2666 = 0.004 * x2431;
            let x2667 = x2665 + x2666;
            let x2668 = x2612 - x2662;
            let x2669 = 0.5 * x2668;
            let x2670 = x2622 + x2669;
            let x2672 = x2630 - x2652;
            let x2673 = x2672 - x2625;
            let x2674 = 0.5 * x2673;
            let x2675 = x2658 + x2674;
            let x2676 = x2597 + x2646;
            let x2677 = 0.5 * x2676;
            let x2678 = x2162 + x2677;
            let x2680 = x2638 - x2165;
            let x2681 = x2680 - x2604;
            let x2682 = 0.5 * x2681;
            let x2683 = x2176 + x2682;
            let x2684 = x2631 - x2652;
            let x2685 = 0.5 * x2684;
            let x2686 = x2635 + x2685;
            let x2688 = x2661 - x2618;
            let x2689 = 0.5 * x2688;
            let x2690 = x2666 + x2689;
            let x2691 = x2605 - x2638;
            let x2692 = 0.5 * x2691;
            let x2693 = x2176 + x2692;
            let x2694 = x2598 + x2645;
            let x2695 = 0.5 * x2694;
            let x2696 = x2221 + x2695;
            let x3291 = x1308 * k[17];
            let x3292 = x1312 * k[18];
            let x3293 = x1316 * k[18];
            let x3294 = x3291 + x3292;
            let x3295 = x3293 + x3294;
            let x3296 = 0.5 * x3295;
            let x3297 = x14 * k[20];
            let x3298 = x3296 + x3297;
            let x3299 = x1328 * k[17];
            let x3300 = x1330 * k[18];
            let x3302 = x1334 * k[18];
            let x3303 = x3299 - x3300;
            let x3304 = x3302 + x3303;
            let x3305 = 0.5 * x3304;
            let x3307 = x43 * k[20];
            let x3308 = x3307 - x3305;
            let x3309 = x1342 * k[17];
            let x3310 = x1344 * k[18];
            let x3311 = x1346 * k[18];
            let x3313 = x3309 + x3310;
            let x3314 = x3313 - x3311;
            let x3315 = 0.5 * x3314;
            let x3317 = x37 * k[20];
            let x3318 = x3317 - x3315;
            let x3319 = x1356 * k[17];
            let x3321 = x1360 * k[18];
            let x3322 = x1362 * k[18];
            let x3323 = x3321 - x3319;
            let x3324 = x3322 + x3323;
            let x3325 = 0.5 * x3324;
            let x3327 = x30 * k[20];
            let x3328 = x3327 - x3325;
            let x3329 = x1370 * k[17];
            let x3331 = x3302 - x3329;
            let x3332 = x3331 - x3300;
            let x3333 = 0.5 * x3332;
            let x3334 = x3307 + x3333;
            let x3335 = x1380 * k[17];
            let x3336 = x3293 + x3335;
            let x3337 = x3292 + x3336;
            let x3338 = 0.5 * x3337;
            let x3339 = x15 * k[20];
            let x3340 = x3338 + x3339;
            let x3341 = x1387 * k[17];
            let x3344 = x3341 - x3322;
            let x3345 = x3344 - x3321;
            let x3346 = 0.5 * x3345;
            let x3347 = x28 * k[20];
            let x3348 = x3346 + x3347;
            let x3349 = x1397 * k[17];
            let x3350 = x3311 + x3349;
            let x3352 = x3310 - x3350;
            let x3353 = 0.5 * x3352;
            let x3354 = x35 * k[20];
            let x3355 = x3353 + x3354;
            let x3356 = x1346 * k[17];
            let x3357 = x1397 * k[18];
            let x3358 = x1342 * k[18];
            let x3359 = x3356 + x3357;
            let x3361 = x3358 - x3359;
            let x3362 = 0.5 * x3361;
            let x3363 = x3317 + x3362;
            let x3364 = x1362 * k[17];
            let x3365 = x1387 * k[18];
            let x3367 = x1356 * k[18];
            let x3369 = x3364 - x3365;
            let x3370 = x3369 - x3367;
            let x3371 = 0.5 * x3370;
            let x3372 = x3347 + x3371;
            let x3373 = x1316 * k[17];
            let x3374 = x1380 * k[18];
            let x3375 = x1308 * k[18];
            let x3376 = x3373 + x3374;
            let x3377 = x3375 + x3376;
            let x3378 = 0.5 * x3377;
            let x3379 = x16 * k[20];
            let x3380 = x3378 + x3379;
            let x3381 = x1334 * k[17];
            let x3383 = x1370 * k[18];
            let x3384 = x1328 * k[18];
            let x3386 = x3383 - x3381;
            let x3387 = x3386 - x3384;
            let x3388 = 0.5 * x3387;
            let x3389 = x41 * k[20];
            let x3390 = x3388 + x3389;
            let x3391 = x1360 * k[17];
            let x3392 = x3391 - x3367;
            let x3393 = x3392 - x3365;
            let x3394 = 0.5 * x3393;
            let x3395 = x3327 + x3394;
            let x3396 = x1344 * k[17];
            let x3397 = x3358 + x3396;
            let x3399 = x3357 - x3397;
            let x3400 = 0.5 * x3399;
            let x3401 = x3354 + x3400;
            let x3402 = x1330 * k[17];
            let x3405 = x3384 - x3402;
            let x3406 = x3405 - x3383;
            let x3407 = 0.5 * x3406;
            let x3408 = x3389 + x3407;
            let x3409 = x1312 * k[17];
            let x3410 = x3375 + x3409;
            let x3411 = x3374 + x3410;
            let x3412 = 0.5 * x3411;
            let x3413 = x17 * k[20];
            let x3414 = x3412 + x3413;
            let x3491 = x1728 * k[17];
            let x3492 = x1732 * k[19];
            let x3493 = x1736 * k[19];
            let x3494 = x3491 + x3492;
            let x3495 = x3493 + x3494;
            let x3496 = 0.5 * x3495;
            let x3497 = x59 * k[21];
            let x3498 = x3496 + x3497;
            let x3499 = x1748 * k[17];
            let x3500 = x1750 * k[19];
            let x3502 = x1754 * k[19];
            let x3503 = x3499 - x3500;
            let x3504 = x3502 + x3503;
            let x3505 = 0.5 * x3504;
            let x3507 = x87 * k[21];
            let x3508 = x3507 - x3505;
            let x3509 = x1762 * k[17];
            let x3510 = x1764 * k[19];
            let x3511 = x1766 * k[19];
            let x3513 = x3509 + x3510;
            let x3514 = x3513 - x3511;
            let x3515 = 0.5 * x3514;
            let x3517 = x81 * k[21];
            let x3518 = x3517 - x3515;
            let x3519 = x1776 * k[17];
            let x3521 = x1780 * k[19];
            let x3522 = x1782 * k[19];
            let x3523 = x3521 - x3519;
            let x3524 = x3522 + x3523;
            let x3525 = 0.5 * x3524;
            let x3527 = x74 * k[21];
            let x3528 = x3527 - x3525;
            let x3529 = x1790 * k[17];
            let x3531 = x3502 - x3529;
            let x3532 = x3531 - x3500;
            let x3533 = 0.5 * x3532;
            let x3534 = x3507 + x3533;
            let x3535 = x1800 * k[17];
            let x3536 = x3493 + x3535;
            let x3537 = x3492 + x3536;
            let x3538 = 0.5 * x3537;
            let x3539 = x60 * k[21];
            let x3540 = x3538 + x3539;
            let x3541 = x1807 * k[17];
            let x3544 = x3541 - x3522;
            let x3545 = x3544 - x3521;
            let x3546 = 0.5 * x3545;
            let x3547 = x72 * k[21];
            let x3548 = x3546 + x3547;
            let x3549 = x1817 * k[17];
            let x3550 = x3511 + x3549;
            let x3552 = x3510 - x3550;
            let x3553 = 0.5 * x3552;
            let x3554 = x79 * k[21];
            let x3555 = x3553 + x3554;
            let x3556 = x1766 * k[17];
            let x3557 = x1817 * k[19];
            let x3558 = x1762 * k[19];
            let x3559 = x3556 + x3557;
            let x3561 = x3558 - x3559;
            let x3562 = 0.5 * x3561;
            let x3563 = x3517 + x3562;
            let x3564 = x1782 * k[17];
            let x3565 = x1807 * k[19];
            let x3567 = x1776 * k[19];
            let x3569 = x3564 - x3565;
            let x3570 = x3569 - x3567;
            let x3571 = 0.5 * x3570;
            let x3572 = x3547 + x3571;
            let x3573 = x1736 * k[17];
            let x3574 = x1800 * k[19];
            let x3575 = x1728 * k[19];
            let x3576 = x3573 + x3574;
            let x3577 = x3575 + x3576;
            let x3578 = 0.5 * x3577;
            let x3579 = x61 * k[21];
            let x3580 = x3578 + x3579;
            let x3581 = x1754 * k[17];
            let x3583 = x1790 * k[19];
            let x3584 = x1748 * k[19];
            let x3586 = x3583 - x3581;
            let x3587 = x3586 - x3584;
            let x3588 = 0.5 * x3587;
            let x3589 = x85 * k[21];
            let x3590 = x3588 + x3589;
            let x3591 = x1780 * k[17];
            let x3592 = x3591 - x3567;
            let x3593 = x3592 - x3565;
            let x3594 = 0.5 * x3593;
            let x3595 = x3527 + x3594;
            let x3596 = x1764 * k[17];
            let x3597 = x3558 + x3596;
            let x3599 = x3557 - x3597;
            let x3600 = 0.5 * x3599;
            let x3601 = x3554 + x3600;
            let x3602 = x1750 * k[17];
            let x3605 = x3584 - x3602;
            let x3606 = x3605 - x3583;
            let x3607 = 0.5 * x3606;
            let x3608 = x3589 + x3607;
            let x3609 = x1732 * k[17];
            let x3610 = x3575 + x3609;
            let x3611 = x3574 + x3610;
            let x3612 = 0.5 * x3611;
            let x3613 = x62 * k[21];
            let x3614 = x3612 + x3613;
            out[0] = 0.3;
            out[1] = 0.3;
            out[2] = 0.3;
            out[3] = x3298;
            out[4] = x3308;
            out[5] = x3318;
            out[6] = x3328;
            out[7] = x3334;
            out[8] = x3340;
            out[9] = x3348;
            out[10] = x3355;
            out[11] = x3363;
            out[12] = x3372;
            out[13] = x3380;
            out[14] = x3390;
            out[15] = x3395;
            out[16] = x3401;
            out[17] = x3408;
            out[18] = x3414;
            out[19] = 0.6;
            out[20] = 0.6;
            out[21] = 0.6;
            out[22] = x3498;
            out[23] = x3508;
            out[24] = x3518;
            out[25] = x3528;
            out[26] = x3534;
            out[27] = x3540;
            out[28] = x3548;
            out[29] = x3555;
            out[30] = x3563;
            out[31] = x3572;
            out[32] = x3580;
            out[33] = x3590;
            out[34] = x3595;
            out[35] = x3601;
            out[36] = x3608;
            out[37] = x3614;
            out[38] = 1.0;
            out[39] = x2602;
            out[40] = x2610;
            out[41] = x2623;
            out[42] = x2636;
            out[43] = x2643;
            out[44] = x2650;
            out[45] = x2659;
            out[46] = x2667;
            out[47] = x2670;
            out[48] = x2675;
            out[49] = x2678;
            out[50] = x2683;
            out[51] = x2686;
            out[52] = x2690;
            out[53] = x2693;
            out[54] = x2696;
        }
        /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
        pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
            let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 19] = qd.try_into().expect("qd must have n_coords entries");
            let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
            let _ = t;
            force_part_0(k, q, qd, out);
        }
        #[inline(never)]
        fn force_part_0(
            k: &[f64; 23],
            q: &[f64; 19],
            qd: &[f64; 19],
            out: &mut [f64; 19],
        ) {
            let x338 = 2.0 * q[3];
            let x339 = 2.0 * q[4];
            let x340 = 2.0 * q[10];
            let x341 = 2.0 * q[11];
            let x342 = 2.0 * q[5];
            let x343 = 2.0 * q[12];
            let x344 = 2.0 * q[13];
            let x345 = 2.0 * q[6];
            let x456 = 2.0 * q[17];
            let x615 = 2.0 * q[18];
            let x677 = q[5] * qd[4];
            let x678 = q[4] * qd[5];
            let x681 = q[6] * qd[3];
            let x682 = q[3] * qd[6];
            let x687 = q[6] * qd[4];
            let x688 = q[4] * qd[6];
            let x691 = q[5] * qd[3];
            let x692 = q[3] * qd[5];
            let x697 = q[6] * qd[5];
            let x698 = q[5] * qd[6];
            let x701 = q[4] * qd[3];
            let x702 = q[3] * qd[4];
            let x720 = q[12] * qd[11];
            let x721 = q[11] * qd[12];
            let x724 = q[13] * qd[10];
            let x725 = q[10] * qd[13];
            let x730 = q[13] * qd[11];
            let x731 = q[11] * qd[13];
            let x734 = q[12] * qd[10];
            let x735 = q[10] * qd[12];
            let x740 = q[13] * qd[12];
            let x741 = q[12] * qd[13];
            let x744 = q[11] * qd[10];
            let x745 = q[10] * qd[11];
            let x782 = q[18] * qd[17];
            let x783 = q[17] * qd[18];
            let x906 = 2.0 * qd[3];
            let x907 = 2.0 * qd[4];
            let x908 = 2.0 * qd[10];
            let x909 = 2.0 * qd[11];
            let x910 = 2.0 * qd[5];
            let x911 = 2.0 * qd[12];
            let x912 = 2.0 * qd[13];
            let x913 = 2.0 * qd[6];
            let x914 = 2.0 * qd[17];
            let x916 = 2.0 * qd[18];
            let x937 = qd[4] * qd[5];
            let x940 = qd[3] * qd[6];
            let x945 = qd[4] * qd[6];
            let x948 = qd[3] * qd[5];
            let x974 = qd[11] * qd[12];
            let x977 = qd[10] * qd[13];
            let x982 = qd[11] * qd[13];
            let x985 = qd[10] * qd[12];
            let x1196 = x702 - x701;
            let x1197 = x697 + x1196;
            let x1198 = x1197 - x698;
            let x1199 = 2.0 * x1198;
            let x1202 = x687 + x691;
            let x1204 = x692 - x1202;
            let x1205 = x688 + x1204;
            let x1206 = 2.0 * x1205;
            let x1209 = x677 - x681;
            let x1210 = x1209 - x678;
            let x1211 = x682 + x1210;
            let x1212 = 2.0 * x1211;
            let x1233 = 2.0 * x1199;
            let x1235 = 2.0 * x1206;
            let x1237 = 2.0 * x1212;
            let x1477 = x945 + x948;
            let x1479 = x948 - x1477;
            let x1480 = x945 + x1479;
            let x1481 = 2.0 * x1480;
            let x1484 = x937 - x940;
            let x1485 = x1484 - x937;
            let x1486 = x940 + x1485;
            let x1487 = 2.0 * x1486;
            let x1488 = 2.0 * x1481;
            let x1489 = 2.0 * x1487;
            let x1490 = x907 * x1233;
            let x1492 = x910 * x1235;
            let x1493 = x342 * x1488;
            let x1494 = x1492 + x1493;
            let x1496 = x913 * x1237;
            let x1497 = x345 * x1489;
            let x1498 = x1496 + x1497;
            let x1504 = x906 * x1233;
            let x1506 = x913 * x1235;
            let x1507 = x345 * x1488;
            let x1508 = x1506 + x1507;
            let x1511 = x910 * x1237;
            let x1512 = x342 * x1489;
            let x1513 = x1511 + x1512;
            let x1518 = x913 * x1233;
            let x1520 = x906 * x1235;
            let x1521 = x338 * x1488;
            let x1522 = x1520 + x1521;
            let x1524 = x907 * x1237;
            let x1525 = x339 * x1489;
            let x1526 = x1524 + x1525;
            let x1532 = x910 * x1233;
            let x1535 = x907 * x1235;
            let x1536 = x339 * x1488;
            let x1537 = x1535 + x1536;
            let x1539 = x906 * x1237;
            let x1540 = x338 * x1489;
            let x1541 = x1539 + x1540;
            let x1546 = qd[3] * qd[3];
            let x1547 = qd[4] * qd[4];
            let x1548 = qd[5] * qd[5];
            let x1549 = qd[6] * qd[6];
            let x1550 = x1546 + x1547;
            let x1551 = x1548 + x1550;
            let x1552 = x1549 + x1551;
            let x1619 = x745 - x744;
            let x1620 = x740 + x1619;
            let x1621 = x1620 - x741;
            let x1622 = 2.0 * x1621;
            let x1625 = x730 + x734;
            let x1627 = x735 - x1625;
            let x1628 = x731 + x1627;
            let x1629 = 2.0 * x1628;
            let x1632 = x720 - x724;
            let x1633 = x1632 - x721;
            let x1634 = x725 + x1633;
            let x1635 = 2.0 * x1634;
            let x1656 = 2.0 * x1622;
            let x1658 = 2.0 * x1629;
            let x1660 = 2.0 * x1635;
            let x1897 = x982 + x985;
            let x1899 = x985 - x1897;
            let x1900 = x982 + x1899;
            let x1901 = 2.0 * x1900;
            let x1904 = x974 - x977;
            let x1905 = x1904 - x974;
            let x1906 = x977 + x1905;
            let x1907 = 2.0 * x1906;
            let x1908 = 2.0 * x1901;
            let x1909 = 2.0 * x1907;
            let x1910 = x909 * x1656;
            let x1912 = x911 * x1658;
            let x1913 = x343 * x1908;
            let x1914 = x1912 + x1913;
            let x1916 = x912 * x1660;
            let x1917 = x344 * x1909;
            let x1918 = x1916 + x1917;
            let x1924 = x908 * x1656;
            let x1926 = x912 * x1658;
            let x1927 = x344 * x1908;
            let x1928 = x1926 + x1927;
            let x1931 = x911 * x1660;
            let x1932 = x343 * x1909;
            let x1933 = x1931 + x1932;
            let x1938 = x912 * x1656;
            let x1940 = x908 * x1658;
            let x1941 = x340 * x1908;
            let x1942 = x1940 + x1941;
            let x1944 = x909 * x1660;
            let x1945 = x341 * x1909;
            let x1946 = x1944 + x1945;
            let x1952 = x911 * x1656;
            let x1955 = x909 * x1658;
            let x1956 = x341 * x1908;
            let x1957 = x1955 + x1956;
            let x1959 = x908 * x1660;
            let x1960 = x340 * x1909;
            let x1961 = x1959 + x1960;
            let x1966 = qd[10] * qd[10];
            let x1967 = qd[11] * qd[11];
            let x1968 = qd[12] * qd[12];
            let x1969 = qd[13] * qd[13];
            let x1970 = x1966 + x1967;
            let x1971 = x1968 + x1970;
            let x1972 = x1969 + x1971;
            let x2059 = qd[15] * qd[15];
            let x2062 = qd[16] * qd[16];
            let x2073 = 2.0 * qd[15];
            let x2075 = 2.0 * qd[16];
            let x2350 = qd[17] * qd[17];
            let x2351 = qd[18] * qd[18];
            let x2363 = q[17] * 0.004;
            let x2382 = q[18] * 0.004;
            let x2454 = 2.0 * q[15];
            let x2476 = 2.0 * q[16];
            let x2499 = q[17] * qd[16];
            let x2500 = q[16] * qd[17];
            let x2503 = q[18] * qd[15];
            let x2504 = q[15] * qd[18];
            let x2507 = q[18] * qd[16];
            let x2508 = q[16] * qd[18];
            let x2511 = q[17] * qd[15];
            let x2512 = q[15] * qd[17];
            let x2517 = q[16] * qd[15];
            let x2518 = q[15] * qd[16];
            let x2544 = qd[16] * qd[17];
            let x2547 = qd[15] * qd[18];
            let x2550 = qd[16] * qd[18];
            let x2553 = qd[15] * qd[17];
            let x2699 = x2518 - x2517;
            let x2700 = x782 + x2699;
            let x2701 = x2700 - x783;
            let x2702 = 2.0 * x2701;
            let x2703 = x2507 + x2511;
            let x2705 = x2512 - x2703;
            let x2706 = x2508 + x2705;
            let x2707 = 2.0 * x2706;
            let x2710 = x2499 - x2503;
            let x2711 = x2710 - x2500;
            let x2712 = x2504 + x2711;
            let x2713 = 2.0 * x2712;
            let x2714 = 2.0 * x2702;
            let x2715 = 2.0 * x2707;
            let x2716 = 2.0 * x2713;
            let x2717 = x2550 + x2553;
            let x2719 = x2553 - x2717;
            let x2720 = x2550 + x2719;
            let x2721 = 2.0 * x2720;
            let x2724 = x2544 - x2547;
            let x2725 = x2724 - x2544;
            let x2726 = x2547 + x2725;
            let x2727 = 2.0 * x2726;
            let x2728 = 2.0 * x2721;
            let x2729 = 2.0 * x2727;
            let x2730 = x2075 * x2714;
            let x2731 = 0.001 * x2730;
            let x2732 = x914 * x2715;
            let x2733 = x456 * x2728;
            let x2734 = x2732 + x2733;
            let x2735 = 0.001 * x2734;
            let x2736 = x916 * x2716;
            let x2737 = x615 * x2729;
            let x2738 = x2736 + x2737;
            let x2739 = 0.001 * x2738;
            let x2740 = x2731 + x2735;
            let x2741 = x2739 + x2740;
            let x2742 = 0.5 * x2741;
            let x2743 = x2073 * x2714;
            let x2744 = 0.001 * x2743;
            let x2745 = x916 * x2715;
            let x2746 = x615 * x2728;
            let x2747 = x2745 + x2746;
            let x2748 = 0.001 * x2747;
            let x2750 = x914 * x2716;
            let x2751 = x456 * x2729;
            let x2752 = x2750 + x2751;
            let x2753 = 0.001 * x2752;
            let x2754 = x2744 - x2748;
            let x2755 = x2753 + x2754;
            let x2756 = 0.5 * x2755;
            let x2757 = x916 * x2714;
            let x2758 = 0.001 * x2757;
            let x2759 = x2073 * x2715;
            let x2760 = x2454 * x2728;
            let x2761 = x2759 + x2760;
            let x2762 = 0.001 * x2761;
            let x2763 = x2075 * x2716;
            let x2764 = x2476 * x2729;
            let x2765 = x2763 + x2764;
            let x2766 = 0.001 * x2765;
            let x2768 = x2758 + x2762;
            let x2769 = x2768 - x2766;
            let x2770 = 0.5 * x2769;
            let x2771 = x914 * x2714;
            let x2772 = 0.001 * x2771;
            let x2774 = x2075 * x2715;
            let x2775 = x2476 * x2728;
            let x2776 = x2774 + x2775;
            let x2777 = 0.001 * x2776;
            let x2778 = x2073 * x2716;
            let x2779 = x2454 * x2729;
            let x2780 = x2778 + x2779;
            let x2781 = 0.001 * x2780;
            let x2782 = x2777 - x2772;
            let x2783 = x2781 + x2782;
            let x2784 = 0.5 * x2783;
            let x2785 = x2059 + x2062;
            let x2786 = x2350 + x2785;
            let x2787 = x2351 + x2786;
            let x2788 = 0.001 * x2732;
            let x2789 = 0.001 * x2736;
            let x2790 = x2731 + x2788;
            let x2791 = x2789 + x2790;
            let x2792 = 0.5 * x2791;
            let x2793 = x2742 + x2792;
            let x2794 = q[15] * 0.004;
            let x2795 = x2787 * x2794;
            let x2797 = x2793 - x2795;
            let x2799 = 0.001 * x2745;
            let x2800 = 0.001 * x2750;
            let x2802 = x2799 - x2744;
            let x2803 = x2802 - x2800;
            let x2804 = 0.5 * x2803;
            let x2806 = x2804 - x2756;
            let x2807 = q[16] * 0.004;
            let x2808 = x2787 * x2807;
            let x2810 = x2806 - x2808;
            let x2811 = 0.001 * x2759;
            let x2812 = 0.001 * x2763;
            let x2813 = x2758 + x2811;
            let x2815 = x2812 - x2813;
            let x2816 = 0.5 * x2815;
            let x2818 = x2816 - x2770;
            let x2819 = x2363 * x2787;
            let x2821 = x2818 - x2819;
            let x2822 = 0.001 * x2774;
            let x2824 = 0.001 * x2778;
            let x2826 = x2772 - x2822;
            let x2827 = x2826 - x2824;
            let x2828 = 0.5 * x2827;
            let x2830 = x2828 - x2784;
            let x2831 = x2382 * x2787;
            let x2833 = x2830 - x2831;
            let x3415 = x1490 * k[17];
            let x3416 = x1494 * k[18];
            let x3417 = x1498 * k[18];
            let x3418 = x3415 + x3416;
            let x3419 = x3417 + x3418;
            let x3420 = 0.5 * x3419;
            let x3421 = x1504 * k[17];
            let x3422 = x1508 * k[18];
            let x3424 = x1513 * k[18];
            let x3425 = x3421 - x3422;
            let x3426 = x3424 + x3425;
            let x3427 = 0.5 * x3426;
            let x3428 = x1518 * k[17];
            let x3429 = x1522 * k[18];
            let x3430 = x1526 * k[18];
            let x3432 = x3428 + x3429;
            let x3433 = x3432 - x3430;
            let x3434 = 0.5 * x3433;
            let x3435 = x1532 * k[17];
            let x3437 = x1537 * k[18];
            let x3438 = x1541 * k[18];
            let x3439 = x3437 - x3435;
            let x3440 = x3438 + x3439;
            let x3441 = 0.5 * x3440;
            let x3442 = x1492 * k[18];
            let x3443 = x1496 * k[18];
            let x3444 = x3415 + x3442;
            let x3445 = x3443 + x3444;
            let x3446 = 0.5 * x3445;
            let x3447 = x3420 + x3446;
            let x3448 = q[3] * k[20];
            let x3449 = x1552 * x3448;
            let x3451 = x3447 - x3449;
            let x3453 = x1506 * k[18];
            let x3454 = x1511 * k[18];
            let x3456 = x3453 - x3421;
            let x3457 = x3456 - x3454;
            let x3458 = 0.5 * x3457;
            let x3460 = x3458 - x3427;
            let x3461 = q[4] * k[20];
            let x3462 = x1552 * x3461;
            let x3464 = x3460 - x3462;
            let x3465 = x1520 * k[18];
            let x3466 = x1524 * k[18];
            let x3467 = x3428 + x3465;
            let x3469 = x3466 - x3467;
            let x3470 = 0.5 * x3469;
            let x3472 = x3470 - x3434;
            let x3473 = q[5] * k[20];
            let x3474 = x1552 * x3473;
            let x3476 = x3472 - x3474;
            let x3477 = x1535 * k[18];
            let x3479 = x1539 * k[18];
            let x3481 = x3435 - x3477;
            let x3482 = x3481 - x3479;
            let x3483 = 0.5 * x3482;
            let x3485 = x3483 - x3441;
            let x3486 = q[6] * k[20];
            let x3487 = x1552 * x3486;
            let x3489 = x3485 - x3487;
            let x3615 = x1910 * k[17];
            let x3616 = x1914 * k[19];
            let x3617 = x1918 * k[19];
            let x3618 = x3615 + x3616;
            let x3619 = x3617 + x3618;
            let x3620 = 0.5 * x3619;
            let x3621 = x1924 * k[17];
            let x3622 = x1928 * k[19];
            let x3624 = x1933 * k[19];
            let x3625 = x3621 - x3622;
            let x3626 = x3624 + x3625;
            let x3627 = 0.5 * x3626;
            let x3628 = x1938 * k[17];
            let x3629 = x1942 * k[19];
            let x3630 = x1946 * k[19];
            let x3632 = x3628 + x3629;
            let x3633 = x3632 - x3630;
            let x3634 = 0.5 * x3633;
            let x3635 = x1952 * k[17];
            let x3637 = x1957 * k[19];
            let x3638 = x1961 * k[19];
            let x3639 = x3637 - x3635;
            let x3640 = x3638 + x3639;
            let x3641 = 0.5 * x3640;
            let x3642 = x1912 * k[19];
            let x3643 = x1916 * k[19];
            let x3644 = x3615 + x3642;
            let x3645 = x3643 + x3644;
            let x3646 = 0.5 * x3645;
            let x3647 = x3620 + x3646;
            let x3648 = q[10] * k[21];
            let x3649 = x1972 * x3648;
            let x3651 = x3647 - x3649;
            let x3653 = x1926 * k[19];
            let x3654 = x1931 * k[19];
            let x3656 = x3653 - x3621;
            let x3657 = x3656 - x3654;
            let x3658 = 0.5 * x3657;
            let x3660 = x3658 - x3627;
            let x3661 = q[11] * k[21];
            let x3662 = x1972 * x3661;
            let x3664 = x3660 - x3662;
            let x3665 = x1940 * k[19];
            let x3666 = x1944 * k[19];
            let x3667 = x3628 + x3665;
            let x3669 = x3666 - x3667;
            let x3670 = 0.5 * x3669;
            let x3672 = x3670 - x3634;
            let x3673 = q[12] * k[21];
            let x3674 = x1972 * x3673;
            let x3676 = x3672 - x3674;
            let x3677 = x1955 * k[19];
            let x3679 = x1959 * k[19];
            let x3681 = x3635 - x3677;
            let x3682 = x3681 - x3679;
            let x3683 = 0.5 * x3682;
            let x3685 = x3683 - x3641;
            let x3686 = q[13] * k[21];
            let x3687 = x1972 * x3686;
            let x3689 = x3685 - x3687;
            out[0] = 0.0;
            out[1] = -2.943;
            out[2] = 0.0;
            out[3] = x3451;
            out[4] = x3464;
            out[5] = x3476;
            out[6] = x3489;
            out[7] = 0.0;
            out[8] = -5.886;
            out[9] = 0.0;
            out[10] = x3651;
            out[11] = x3664;
            out[12] = x3676;
            out[13] = x3689;
            out[14] = 0.0;
            out[15] = x2797;
            out[16] = x2810;
            out[17] = x2821;
            out[18] = x2833;
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
            let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
            let q: &[f64; 19] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 19] = qd.try_into().expect("qd must have n_coords entries");
            let phi: &mut [f64; 19] = phi.try_into().expect("phi must have 19 entries");
            let phi_q: &mut [f64; 105] = phi_q
                .try_into()
                .expect("phi_q must have 105 entries");
            let mass: &mut [f64; 55] = mass
                .try_into()
                .expect("mass must have 55 entries");
            let force: &mut [f64; 19] = force
                .try_into()
                .expect("force must have 19 entries");
            let mut s = [0.0f64; 48];
            eval_newton_shared_0(k, q, qd, t, &mut s);
            eval_newton_part_0(k, q, t, &s, phi, phi_q, mass);
            eval_newton_part_1(k, q, qd, &s, mass, force);
            eval_newton_part_2(q, qd, &s, force);
        }
        #[inline(never)]
        fn eval_newton_shared_0(
            k: &[f64; 23],
            q: &[f64; 19],
            _qd: &[f64; 19],
            _t: f64,
            s: &mut [f64; 48],
        ) {
            let x60 = q[11] * q[11];
            s[0] = x60;
            let x61 = q[12] * q[12];
            s[1] = x61;
            let x62 = q[13] * q[13];
            s[2] = x62;
            let x72 = q[11] * q[12];
            s[3] = x72;
            let x74 = q[10] * q[13];
            s[4] = x74;
            let x79 = q[11] * q[13];
            s[5] = x79;
            let x81 = q[10] * q[12];
            s[6] = x81;
            let x85 = q[12] * q[13];
            s[7] = x85;
            let x87 = q[10] * q[11];
            s[8] = x87;
            let x103 = q[17] * q[17];
            s[9] = x103;
            let x104 = q[18] * q[18];
            s[10] = x104;
            let x131 = q[17] * q[18];
            s[11] = x131;
            let x338 = 2.0 * q[3];
            s[12] = x338;
            let x339 = 2.0 * q[4];
            s[13] = x339;
            let x340 = 2.0 * q[10];
            s[14] = x340;
            let x341 = 2.0 * q[11];
            s[15] = x341;
            let x342 = 2.0 * q[5];
            s[16] = x342;
            let x343 = 2.0 * q[12];
            s[17] = x343;
            let x344 = 2.0 * q[13];
            s[18] = x344;
            let x345 = 2.0 * q[6];
            s[19] = x345;
            let x452 = 2.0 * x340;
            s[20] = x452;
            let x456 = 2.0 * q[17];
            s[21] = x456;
            let x516 = 2.0 * x341;
            s[22] = x516;
            let x554 = 2.0 * x343;
            s[23] = x554;
            let x588 = 2.0 * x344;
            s[24] = x588;
            let x615 = 2.0 * q[18];
            s[25] = x615;
            let x1728 = x341 * x516;
            s[26] = x1728;
            let x1732 = x343 * x554;
            s[27] = x1732;
            let x1736 = x344 * x588;
            s[28] = x1736;
            let x1748 = x341 * x452;
            s[29] = x1748;
            let x1750 = x343 * x588;
            s[30] = x1750;
            let x1754 = x344 * x554;
            s[31] = x1754;
            let x2139 = 2.0 * x615;
            s[32] = x2139;
            let x2421 = q[15] * q[15];
            s[33] = x2421;
            let x2422 = q[16] * q[16];
            s[34] = x2422;
            let x2427 = q[16] * q[17];
            s[35] = x2427;
            let x2429 = q[15] * q[18];
            s[36] = x2429;
            let x2431 = q[16] * q[18];
            s[37] = x2431;
            let x2433 = q[15] * q[17];
            s[38] = x2433;
            let x2437 = q[15] * q[16];
            s[39] = x2437;
            let x2454 = 2.0 * q[15];
            s[40] = x2454;
            let x2476 = 2.0 * q[16];
            s[41] = x2476;
            let x2477 = 2.0 * x2454;
            s[42] = x2477;
            let x3492 = x1732 * k[19];
            s[43] = x3492;
            let x3493 = x1736 * k[19];
            s[44] = x3493;
            let x3500 = x1750 * k[19];
            s[45] = x3500;
            let x3502 = x1754 * k[19];
            s[46] = x3502;
            let x3507 = x87 * k[21];
            s[47] = x3507;
        }
        #[inline(never)]
        fn eval_newton_part_0(
            k: &[f64; 23],
            q: &[f64; 19],
            t: f64,
            s: &[f64; 48],
            phi: &mut [f64; 19],
            phi_q: &mut [f64; 105],
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
            let x22 = x14 + x16;
            let x23 = 2.0 * x22;
            let x24 = x23 - 1.0;
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
            let x59 = q[10] * q[10];
            let x63 = x59 + s[0];
            let x64 = 2.0 * x63;
            let x65 = x64 - 1.0;
            let x66 = x59 + s[1];
            let x67 = 2.0 * x66;
            let x68 = x67 - 1.0;
            let x69 = x59 + s[2];
            let x70 = 2.0 * x69;
            let x71 = x70 - 1.0;
            let x73 = 2.0 * s[3];
            let x76 = 2.0 * s[4];
            let x78 = x73 - x76;
            let x80 = 2.0 * s[5];
            let x82 = 2.0 * s[6];
            let x83 = x80 + x82;
            let x84 = x73 + x76;
            let x86 = 2.0 * s[7];
            let x89 = 2.0 * s[8];
            let x91 = x86 - x89;
            let x94 = x80 - x82;
            let x95 = x86 + x89;
            let x133 = 2.0 * s[11];
            let x323 = x5.sin();
            let x324 = x5.cos();
            let x329 = x16 + x18;
            let x330 = x17 + x329;
            let x331 = x330 - 1.0;
            let x332 = s[1] + x63;
            let x333 = s[2] + x332;
            let x334 = x333 - 1.0;
            let x346 = 2.0 * s[12];
            let x389 = 2.0 * s[13];
            let x414 = 2.0 * s[16];
            let x626 = -s[21];
            let x1306 = 2.0 * s[19];
            let x1308 = s[13] * x389;
            let x1312 = s[16] * x414;
            let x1316 = s[19] * x1306;
            let x1328 = s[13] * x346;
            let x1330 = s[16] * x1306;
            let x1334 = s[19] * x414;
            let x1342 = s[13] * x1306;
            let x1344 = s[16] * x346;
            let x1346 = s[19] * x389;
            let x1356 = s[13] * x414;
            let x1360 = s[16] * x389;
            let x1362 = s[19] * x346;
            let x1370 = s[12] * x389;
            let x1380 = s[12] * x346;
            let x1387 = s[12] * x1306;
            let x1397 = s[12] * x414;
            let x2423 = s[33] + s[34];
            let x2424 = s[10] + s[33];
            let x2425 = 2.0 * x2424;
            let x2426 = x2425 - 1.0;
            let x2428 = 2.0 * s[35];
            let x2430 = 2.0 * s[36];
            let x2432 = 2.0 * s[37];
            let x2434 = 2.0 * s[38];
            let x2435 = x2432 + x2434;
            let x2436 = x2428 + x2430;
            let x2438 = 2.0 * s[39];
            let x2440 = x133 - x2438;
            let x2442 = x2432 - x2434;
            let x2443 = x133 + x2438;
            let x2451 = s[9] + x2423;
            let x2452 = s[10] + x2451;
            let x2453 = x2452 - 1.0;
            let x2484 = -s[40];
            let x2836 = x21 * k[0];
            let x2837 = x34 * k[1];
            let x2838 = x2836 + x2837;
            let x2839 = x40 * k[0];
            let x2840 = x24 * k[1];
            let x2841 = x2839 + x2840;
            let x2842 = x50 * k[0];
            let x2843 = x51 * k[1];
            let x2844 = x2842 + x2843;
            let x2845 = q[0] + x2838;
            let x2846 = q[1] + x2841;
            let x2847 = q[2] + x2844;
            let x2850 = x21 * k[2];
            let x2851 = x34 * k[3];
            let x2852 = x2850 + x2851;
            let x2853 = x40 * k[2];
            let x2854 = x24 * k[3];
            let x2855 = x2853 + x2854;
            let x2857 = x39 * k[4];
            let x2858 = x47 * k[4];
            let x2859 = -x2845;
            let x2860 = -x2846;
            let x2861 = -x2847;
            let x2864 = x21 * k[5];
            let x2865 = x34 * k[6];
            let x2866 = x2864 + x2865;
            let x2867 = x40 * k[5];
            let x2868 = x24 * k[6];
            let x2869 = x2867 + x2868;
            let x2870 = x50 * k[5];
            let x2871 = x51 * k[6];
            let x2872 = x2870 + x2871;
            let x2873 = q[0] + x2866;
            let x2874 = q[1] + x2869;
            let x2875 = q[2] + x2872;
            let x2879 = x65 * k[7];
            let x2880 = x78 * k[8];
            let x2881 = x83 * k[9];
            let x2882 = x2879 + x2880;
            let x2883 = x2881 + x2882;
            let x2884 = x84 * k[7];
            let x2885 = x68 * k[8];
            let x2886 = x91 * k[9];
            let x2887 = x2884 + x2885;
            let x2888 = x2886 + x2887;
            let x2889 = x94 * k[7];
            let x2890 = x95 * k[8];
            let x2891 = x71 * k[9];
            let x2892 = x2889 + x2890;
            let x2893 = x2891 + x2892;
            let x2894 = q[7] + x2883;
            let x2895 = q[8] + x2888;
            let x2896 = q[9] + x2893;
            let x2898 = x2873 - x2894;
            let x2900 = x2874 - x2895;
            let x2902 = x2875 - x2896;
            let x2906 = x65 * k[10];
            let x2907 = x78 * k[11];
            let x2908 = x83 * k[12];
            let x2909 = x2906 + x2907;
            let x2910 = x2908 + x2909;
            let x2911 = x84 * k[10];
            let x2912 = x68 * k[11];
            let x2913 = x91 * k[12];
            let x2914 = x2911 + x2912;
            let x2915 = x2913 + x2914;
            let x2916 = x94 * k[10];
            let x2917 = x95 * k[11];
            let x2918 = x71 * k[12];
            let x2919 = x2916 + x2917;
            let x2920 = x2918 + x2919;
            let x2921 = q[7] + x2910;
            let x2922 = q[8] + x2915;
            let x2923 = q[9] + x2920;
            let x2926 = x65 * k[13];
            let x2927 = x78 * k[14];
            let x2928 = x2926 + x2927;
            let x2929 = x84 * k[13];
            let x2930 = x68 * k[14];
            let x2931 = x2929 + x2930;
            let x2932 = x94 * k[13];
            let x2933 = x95 * k[14];
            let x2934 = x2932 + x2933;
            let x2936 = q[14] - x2921;
            let x2941 = x323 * x2852;
            let x2942 = x324 * x2855;
            let x2944 = x2941 - x2942;
            let x2945 = x346 * k[0];
            let x2946 = s[19] * k[1];
            let x2948 = x2945 - x2946;
            let x2949 = s[19] * k[0];
            let x2950 = x346 * k[1];
            let x2951 = x2949 + x2950;
            let x2952 = s[16] * k[0];
            let x2953 = -x2952;
            let x2954 = s[13] * k[1];
            let x2955 = x2954 - x2952;
            let x2956 = x346 * k[2];
            let x2957 = s[19] * k[3];
            let x2959 = x2956 - x2957;
            let x2960 = s[19] * k[2];
            let x2961 = x346 * k[3];
            let x2962 = x2960 + x2961;
            let x2963 = s[16] * k[4];
            let x2964 = s[13] * k[4];
            let x2965 = -x2964;
            let x2966 = -x2948;
            let x2967 = -x2951;
            let x2968 = -x2955;
            let x2969 = x346 * k[5];
            let x2970 = s[19] * k[6];
            let x2972 = x2969 - x2970;
            let x2973 = s[19] * k[5];
            let x2974 = x346 * k[6];
            let x2975 = x2973 + x2974;
            let x2976 = s[16] * k[5];
            let x2978 = s[13] * k[6];
            let x2979 = x2978 - x2976;
            let x2980 = x323 * x2959;
            let x2981 = x324 * x2962;
            let x2983 = x2980 - x2981;
            let x2984 = x389 * k[0];
            let x2985 = s[16] * k[1];
            let x2986 = x2984 + x2985;
            let x2987 = s[12] * k[1];
            let x2988 = x2949 + x2987;
            let x2989 = x389 * k[2];
            let x2990 = s[16] * k[3];
            let x2991 = x2989 + x2990;
            let x2992 = s[16] * k[2];
            let x2993 = s[19] * k[4];
            let x2994 = s[12] * k[4];
            let x2995 = -x2994;
            let x2996 = -x2986;
            let x2997 = -x2988;
            let x2998 = x389 * k[5];
            let x2999 = s[16] * k[6];
            let x3000 = x2998 + x2999;
            let x3001 = s[12] * k[6];
            let x3002 = x2973 + x3001;
            let x3003 = x323 * x2991;
            let x3004 = x324 * x2992;
            let x3006 = x3003 - x3004;
            let x3007 = s[13] * k[0];
            let x3008 = x414 * k[1];
            let x3009 = x3007 + x3008;
            let x3010 = s[12] * k[0];
            let x3011 = -x3010;
            let x3012 = x2946 - x3010;
            let x3013 = s[13] * k[3];
            let x3014 = s[13] * k[2];
            let x3015 = x414 * k[3];
            let x3016 = x3014 + x3015;
            let x3017 = -x2954;
            let x3018 = -x3009;
            let x3019 = -x3012;
            let x3020 = s[13] * k[5];
            let x3021 = x414 * k[6];
            let x3022 = x3020 + x3021;
            let x3023 = s[12] * k[5];
            let x3025 = x2970 - x3023;
            let x3026 = x323 * x3013;
            let x3027 = x324 * x3016;
            let x3029 = x3026 - x3027;
            let x3030 = x2985 + x3007;
            let x3031 = s[12] * k[3];
            let x3032 = s[12] * k[2];
            let x3033 = -x3030;
            let x3034 = -x3001;
            let x3035 = x2999 + x3020;
            let x3036 = x323 * x3031;
            let x3037 = x324 * x3032;
            let x3038 = x3036 + x3037;
            let x3039 = -x3038;
            let x3040 = s[20] * k[7];
            let x3041 = s[18] * k[8];
            let x3043 = s[17] * k[9];
            let x3044 = x3040 - x3041;
            let x3045 = x3043 + x3044;
            let x3046 = s[18] * k[7];
            let x3047 = s[20] * k[8];
            let x3048 = s[15] * k[9];
            let x3050 = x3046 + x3047;
            let x3051 = x3050 - x3048;
            let x3052 = s[17] * k[7];
            let x3054 = s[15] * k[8];
            let x3055 = s[20] * k[9];
            let x3056 = x3054 - x3052;
            let x3057 = x3055 + x3056;
            let x3058 = -x3045;
            let x3059 = -x3051;
            let x3060 = -x3057;
            let x3061 = s[20] * k[10];
            let x3062 = s[18] * k[11];
            let x3064 = s[17] * k[12];
            let x3065 = x3061 - x3062;
            let x3066 = x3064 + x3065;
            let x3067 = s[18] * k[10];
            let x3068 = s[20] * k[11];
            let x3069 = s[15] * k[12];
            let x3071 = x3067 + x3068;
            let x3072 = x3071 - x3069;
            let x3073 = s[17] * k[10];
            let x3075 = s[15] * k[11];
            let x3076 = s[20] * k[12];
            let x3077 = x3075 - x3073;
            let x3078 = x3076 + x3077;
            let x3079 = s[20] * k[13];
            let x3080 = s[18] * k[14];
            let x3082 = x3079 - x3080;
            let x3083 = s[18] * k[13];
            let x3084 = s[20] * k[14];
            let x3085 = x3083 + x3084;
            let x3086 = s[17] * k[13];
            let x3088 = s[15] * k[14];
            let x3089 = x3088 - x3086;
            let x3090 = -x3066;
            let x3091 = -x3072;
            let x3092 = -x3078;
            let x3093 = s[22] * k[7];
            let x3094 = s[17] * k[8];
            let x3095 = s[18] * k[9];
            let x3096 = x3093 + x3094;
            let x3097 = x3095 + x3096;
            let x3098 = s[14] * k[9];
            let x3100 = x3052 - x3098;
            let x3101 = s[14] * k[8];
            let x3102 = x3046 + x3101;
            let x3103 = -x3097;
            let x3104 = -x3100;
            let x3105 = -x3102;
            let x3106 = s[22] * k[10];
            let x3107 = s[17] * k[11];
            let x3108 = s[18] * k[12];
            let x3109 = x3106 + x3107;
            let x3110 = x3108 + x3109;
            let x3111 = s[14] * k[12];
            let x3113 = x3073 - x3111;
            let x3114 = s[14] * k[11];
            let x3115 = x3067 + x3114;
            let x3116 = s[22] * k[13];
            let x3117 = s[17] * k[14];
            let x3118 = x3116 + x3117;
            let x3119 = s[14] * k[14];
            let x3120 = x3083 + x3119;
            let x3121 = -x3110;
            let x3122 = -x3113;
            let x3123 = -x3115;
            let x3124 = x3054 + x3098;
            let x3125 = s[15] * k[7];
            let x3126 = s[23] * k[8];
            let x3127 = x3125 + x3126;
            let x3128 = x3095 + x3127;
            let x3129 = s[14] * k[7];
            let x3131 = x3041 - x3129;
            let x3132 = -x3124;
            let x3133 = -x3128;
            let x3134 = -x3131;
            let x3135 = x3075 + x3111;
            let x3136 = s[15] * k[10];
            let x3137 = s[23] * k[11];
            let x3138 = x3136 + x3137;
            let x3139 = x3108 + x3138;
            let x3140 = s[14] * k[10];
            let x3142 = x3062 - x3140;
            let x3143 = s[15] * k[13];
            let x3144 = s[23] * k[14];
            let x3145 = x3143 + x3144;
            let x3146 = s[14] * k[13];
            let x3148 = x3080 - x3146;
            let x3149 = -x3135;
            let x3150 = -x3139;
            let x3151 = -x3142;
            let x3153 = x3048 - x3101;
            let x3154 = x3043 + x3129;
            let x3155 = s[24] * k[9];
            let x3156 = x3094 + x3125;
            let x3157 = x3155 + x3156;
            let x3158 = -x3153;
            let x3159 = -x3154;
            let x3160 = -x3157;
            let x3162 = x3069 - x3114;
            let x3163 = x3064 + x3140;
            let x3164 = s[24] * k[12];
            let x3165 = x3107 + x3136;
            let x3166 = x3164 + x3165;
            let x3167 = x3117 + x3143;
            let x3168 = -x3162;
            let x3169 = -x3163;
            let x3170 = -x3166;
            let x3171 = s[25] * x2931;
            let x3172 = s[21] * x2931;
            let x3173 = s[21] * x2928;
            let x3174 = s[25] * x2928;
            let x3291 = x1308 * k[17];
            let x3292 = x1312 * k[18];
            let x3293 = x1316 * k[18];
            let x3294 = x3291 + x3292;
            let x3295 = x3293 + x3294;
            let x3296 = 0.5 * x3295;
            let x3297 = x14 * k[20];
            let x3298 = x3296 + x3297;
            let x3299 = x1328 * k[17];
            let x3300 = x1330 * k[18];
            let x3302 = x1334 * k[18];
            let x3303 = x3299 - x3300;
            let x3304 = x3302 + x3303;
            let x3305 = 0.5 * x3304;
            let x3307 = x43 * k[20];
            let x3308 = x3307 - x3305;
            let x3309 = x1342 * k[17];
            let x3310 = x1344 * k[18];
            let x3311 = x1346 * k[18];
            let x3313 = x3309 + x3310;
            let x3314 = x3313 - x3311;
            let x3315 = 0.5 * x3314;
            let x3317 = x37 * k[20];
            let x3318 = x3317 - x3315;
            let x3319 = x1356 * k[17];
            let x3321 = x1360 * k[18];
            let x3322 = x1362 * k[18];
            let x3323 = x3321 - x3319;
            let x3324 = x3322 + x3323;
            let x3325 = 0.5 * x3324;
            let x3327 = x30 * k[20];
            let x3328 = x3327 - x3325;
            let x3329 = x1370 * k[17];
            let x3331 = x3302 - x3329;
            let x3332 = x3331 - x3300;
            let x3333 = 0.5 * x3332;
            let x3334 = x3307 + x3333;
            let x3335 = x1380 * k[17];
            let x3336 = x3293 + x3335;
            let x3337 = x3292 + x3336;
            let x3338 = 0.5 * x3337;
            let x3339 = x15 * k[20];
            let x3340 = x3338 + x3339;
            let x3341 = x1387 * k[17];
            let x3344 = x3341 - x3322;
            let x3345 = x3344 - x3321;
            let x3346 = 0.5 * x3345;
            let x3347 = x28 * k[20];
            let x3348 = x3346 + x3347;
            let x3349 = x1397 * k[17];
            let x3350 = x3311 + x3349;
            let x3352 = x3310 - x3350;
            let x3353 = 0.5 * x3352;
            let x3354 = x35 * k[20];
            let x3355 = x3353 + x3354;
            let x3356 = x1346 * k[17];
            let x3357 = x1397 * k[18];
            let x3358 = x1342 * k[18];
            let x3359 = x3356 + x3357;
            let x3361 = x3358 - x3359;
            let x3362 = 0.5 * x3361;
            let x3363 = x3317 + x3362;
            let x3364 = x1362 * k[17];
            let x3365 = x1387 * k[18];
            let x3367 = x1356 * k[18];
            let x3369 = x3364 - x3365;
            let x3370 = x3369 - x3367;
            let x3371 = 0.5 * x3370;
            let x3372 = x3347 + x3371;
            let x3373 = x1316 * k[17];
            let x3374 = x1380 * k[18];
            let x3375 = x1308 * k[18];
            let x3376 = x3373 + x3374;
            let x3377 = x3375 + x3376;
            let x3378 = 0.5 * x3377;
            let x3379 = x16 * k[20];
            let x3380 = x3378 + x3379;
            let x3381 = x1334 * k[17];
            let x3383 = x1370 * k[18];
            let x3384 = x1328 * k[18];
            let x3386 = x3383 - x3381;
            let x3387 = x3386 - x3384;
            let x3388 = 0.5 * x3387;
            let x3389 = x41 * k[20];
            let x3390 = x3388 + x3389;
            let x3391 = x1360 * k[17];
            let x3392 = x3391 - x3367;
            let x3393 = x3392 - x3365;
            let x3394 = 0.5 * x3393;
            let x3395 = x3327 + x3394;
            let x3396 = x1344 * k[17];
            let x3397 = x3358 + x3396;
            let x3399 = x3357 - x3397;
            let x3400 = 0.5 * x3399;
            let x3401 = x3354 + x3400;
            let x3402 = x1330 * k[17];
            let x3405 = x3384 - x3402;
            let x3406 = x3405 - x3383;
            let x3407 = 0.5 * x3406;
            let x3408 = x3389 + x3407;
            let x3409 = x1312 * k[17];
            let x3410 = x3375 + x3409;
            let x3411 = x3374 + x3410;
            let x3412 = 0.5 * x3411;
            let x3413 = x17 * k[20];
            let x3414 = x3412 + x3413;
            let x3491 = s[26] * k[17];
            let x3494 = x3491 + s[43];
            let x3495 = s[44] + x3494;
            let x3496 = 0.5 * x3495;
            let x3497 = x59 * k[21];
            let x3498 = x3496 + x3497;
            let x3499 = s[29] * k[17];
            let x3503 = x3499 - s[45];
            let x3504 = s[46] + x3503;
            let x3505 = 0.5 * x3504;
            let x3508 = s[47] - x3505;
            let x3690 = k[15] - x2922;
            let x3691 = k[16] - x2923;
            let x3692 = x2435 * x2928;
            let x3693 = x2440 * x2931;
            let x3694 = x2426 * x2934;
            let x3695 = x3692 + x3693;
            let x3696 = x3694 + x3695;
            let x3697 = x2435 * x3082;
            let x3698 = x2440 * x3085;
            let x3699 = x2426 * x3089;
            let x3700 = x3697 + x3698;
            let x3701 = x3699 + x3700;
            let x3702 = x2435 * x3118;
            let x3703 = x2440 * x3086;
            let x3704 = x2426 * x3120;
            let x3705 = x3702 + x3703;
            let x3706 = x3704 + x3705;
            let x3707 = x2435 * x3088;
            let x3708 = x2440 * x3145;
            let x3709 = x2426 * x3148;
            let x3710 = x3707 + x3708;
            let x3711 = x3709 + x3710;
            let x3712 = x2435 * x3119;
            let x3714 = x2440 * x3146;
            let x3715 = x2426 * x3167;
            let x3716 = x3714 - x3712;
            let x3717 = x3715 + x3716;
            let x3718 = s[41] * x2931;
            let x3720 = s[42] * x2934;
            let x3721 = x3173 - x3718;
            let x3722 = x3720 + x3721;
            let x3723 = s[40] * x2931;
            let x3725 = x3174 - x3723;
            let x3726 = s[40] * x2928;
            let x3727 = x3171 + x3726;
            let x3728 = s[41] * x2928;
            let x3729 = s[32] * x2934;
            let x3730 = x3172 + x3728;
            let x3731 = x3729 + x3730;
            phi[0] = x2859;
            phi_q[0] = -1.0;
            phi_q[1] = x2966;
            phi_q[2] = x2996;
            phi_q[3] = x3017;
            phi_q[4] = x2987;
            phi[1] = x2860;
            phi_q[5] = -1.0;
            phi_q[6] = x2967;
            phi_q[7] = x2953;
            phi_q[8] = x3018;
            phi_q[9] = x3011;
            phi[2] = x2861;
            phi_q[10] = -1.0;
            phi_q[11] = x2968;
            phi_q[12] = x2997;
            phi_q[13] = x3019;
            phi_q[14] = x3033;
            phi[3] = x2857;
            phi_q[15] = x2963;
            phi_q[16] = x2993;
            phi_q[17] = x2994;
            phi_q[18] = x2964;
            phi[4] = x2858;
            phi_q[19] = x2965;
            phi_q[20] = x2995;
            phi_q[21] = x2993;
            phi_q[22] = x2963;
            phi[5] = x2898;
            phi_q[23] = 1.0;
            phi_q[24] = x2972;
            phi_q[25] = x3000;
            phi_q[26] = x2978;
            phi_q[27] = x3034;
            phi_q[28] = -1.0;
            phi_q[29] = x3058;
            phi_q[30] = x3103;
            phi_q[31] = x3132;
            phi_q[32] = x3158;
            phi[6] = x2900;
            phi_q[33] = 1.0;
            phi_q[34] = x2975;
            phi_q[35] = x2976;
            phi_q[36] = x3022;
            phi_q[37] = x3023;
            phi_q[38] = -1.0;
            phi_q[39] = x3059;
            phi_q[40] = x3104;
            phi_q[41] = x3133;
            phi_q[42] = x3159;
            phi[7] = x2902;
            phi_q[43] = 1.0;
            phi_q[44] = x2979;
            phi_q[45] = x3002;
            phi_q[46] = x3025;
            phi_q[47] = x3035;
            phi_q[48] = -1.0;
            phi_q[49] = x3060;
            phi_q[50] = x3105;
            phi_q[51] = x3134;
            phi_q[52] = x3160;
            phi[8] = x2936;
            phi_q[53] = -1.0;
            phi_q[54] = x3090;
            phi_q[55] = x3121;
            phi_q[56] = x3149;
            phi_q[57] = x3168;
            phi_q[58] = 1.0;
            phi[9] = x3690;
            phi_q[59] = -1.0;
            phi_q[60] = x3091;
            phi_q[61] = x3122;
            phi_q[62] = x3150;
            phi_q[63] = x3169;
            phi[10] = x3691;
            phi_q[64] = -1.0;
            phi_q[65] = x3092;
            phi_q[66] = x3123;
            phi_q[67] = x3151;
            phi_q[68] = x3170;
            phi[11] = x3696;
            phi_q[69] = x3701;
            phi_q[70] = x3706;
            phi_q[71] = x3711;
            phi_q[72] = x3717;
            phi_q[73] = x3722;
            phi_q[74] = x3725;
            phi_q[75] = x3727;
            phi_q[76] = x3731;
            phi[12] = x2436;
            phi_q[77] = s[25];
            phi_q[78] = s[21];
            phi_q[79] = s[41];
            phi_q[80] = s[40];
            phi[13] = x2442;
            phi_q[81] = x626;
            phi_q[82] = s[25];
            phi_q[83] = x2484;
            phi_q[84] = s[41];
            phi[14] = x2443;
            phi_q[85] = s[41];
            phi_q[86] = s[40];
            phi_q[87] = s[25];
            phi_q[88] = s[21];
            phi[15] = x2944;
            phi_q[89] = x2983;
            phi_q[90] = x3006;
            phi_q[91] = x3029;
            phi_q[92] = x3039;
            phi[16] = x331;
            phi_q[93] = s[12];
            phi_q[94] = s[13];
            phi_q[95] = s[16];
            phi_q[96] = s[19];
            phi[17] = x334;
            phi_q[97] = s[14];
            phi_q[98] = s[15];
            phi_q[99] = s[17];
            phi_q[100] = s[18];
            phi[18] = x2453;
            phi_q[101] = s[40];
            phi_q[102] = s[41];
            phi_q[103] = s[21];
            phi_q[104] = s[25];
            mass[0] = 0.3;
            mass[1] = 0.3;
            mass[2] = 0.3;
            mass[3] = x3298;
            mass[4] = x3308;
            mass[5] = x3318;
            mass[6] = x3328;
            mass[7] = x3334;
            mass[8] = x3340;
            mass[9] = x3348;
            mass[10] = x3355;
            mass[11] = x3363;
            mass[12] = x3372;
            mass[13] = x3380;
            mass[14] = x3390;
            mass[15] = x3395;
            mass[16] = x3401;
            mass[17] = x3408;
            mass[18] = x3414;
            mass[19] = 0.6;
            mass[20] = 0.6;
            mass[21] = 0.6;
            mass[22] = x3498;
            mass[23] = x3508;
        }
        #[inline(never)]
        fn eval_newton_part_1(
            k: &[f64; 23],
            q: &[f64; 19],
            qd: &[f64; 19],
            s: &[f64; 48],
            mass: &mut [f64; 55],
            force: &mut [f64; 19],
        ) {
            let x617 = 2.0 * s[21];
            let x677 = q[5] * qd[4];
            let x678 = q[4] * qd[5];
            let x681 = q[6] * qd[3];
            let x682 = q[3] * qd[6];
            let x687 = q[6] * qd[4];
            let x688 = q[4] * qd[6];
            let x691 = q[5] * qd[3];
            let x692 = q[3] * qd[5];
            let x697 = q[6] * qd[5];
            let x698 = q[5] * qd[6];
            let x701 = q[4] * qd[3];
            let x702 = q[3] * qd[4];
            let x720 = q[12] * qd[11];
            let x721 = q[11] * qd[12];
            let x724 = q[13] * qd[10];
            let x725 = q[10] * qd[13];
            let x730 = q[13] * qd[11];
            let x731 = q[11] * qd[13];
            let x734 = q[12] * qd[10];
            let x735 = q[10] * qd[12];
            let x740 = q[13] * qd[12];
            let x741 = q[12] * qd[13];
            let x744 = q[11] * qd[10];
            let x745 = q[10] * qd[11];
            let x906 = 2.0 * qd[3];
            let x907 = 2.0 * qd[4];
            let x908 = 2.0 * qd[10];
            let x909 = 2.0 * qd[11];
            let x910 = 2.0 * qd[5];
            let x911 = 2.0 * qd[12];
            let x912 = 2.0 * qd[13];
            let x913 = 2.0 * qd[6];
            let x937 = qd[4] * qd[5];
            let x940 = qd[3] * qd[6];
            let x945 = qd[4] * qd[6];
            let x948 = qd[3] * qd[5];
            let x974 = qd[11] * qd[12];
            let x977 = qd[10] * qd[13];
            let x982 = qd[11] * qd[13];
            let x985 = qd[10] * qd[12];
            let x1196 = x702 - x701;
            let x1197 = x697 + x1196;
            let x1198 = x1197 - x698;
            let x1199 = 2.0 * x1198;
            let x1202 = x687 + x691;
            let x1204 = x692 - x1202;
            let x1205 = x688 + x1204;
            let x1206 = 2.0 * x1205;
            let x1209 = x677 - x681;
            let x1210 = x1209 - x678;
            let x1211 = x682 + x1210;
            let x1212 = 2.0 * x1211;
            let x1233 = 2.0 * x1199;
            let x1235 = 2.0 * x1206;
            let x1237 = 2.0 * x1212;
            let x1477 = x945 + x948;
            let x1479 = x948 - x1477;
            let x1480 = x945 + x1479;
            let x1481 = 2.0 * x1480;
            let x1484 = x937 - x940;
            let x1485 = x1484 - x937;
            let x1486 = x940 + x1485;
            let x1487 = 2.0 * x1486;
            let x1488 = 2.0 * x1481;
            let x1489 = 2.0 * x1487;
            let x1490 = x907 * x1233;
            let x1492 = x910 * x1235;
            let x1493 = s[16] * x1488;
            let x1494 = x1492 + x1493;
            let x1496 = x913 * x1237;
            let x1497 = s[19] * x1489;
            let x1498 = x1496 + x1497;
            let x1504 = x906 * x1233;
            let x1506 = x913 * x1235;
            let x1507 = s[19] * x1488;
            let x1508 = x1506 + x1507;
            let x1511 = x910 * x1237;
            let x1512 = s[16] * x1489;
            let x1513 = x1511 + x1512;
            let x1518 = x913 * x1233;
            let x1520 = x906 * x1235;
            let x1521 = s[12] * x1488;
            let x1522 = x1520 + x1521;
            let x1524 = x907 * x1237;
            let x1525 = s[13] * x1489;
            let x1526 = x1524 + x1525;
            let x1532 = x910 * x1233;
            let x1535 = x907 * x1235;
            let x1536 = s[13] * x1488;
            let x1537 = x1535 + x1536;
            let x1539 = x906 * x1237;
            let x1540 = s[12] * x1489;
            let x1541 = x1539 + x1540;
            let x1546 = qd[3] * qd[3];
            let x1547 = qd[4] * qd[4];
            let x1548 = qd[5] * qd[5];
            let x1549 = qd[6] * qd[6];
            let x1550 = x1546 + x1547;
            let x1551 = x1548 + x1550;
            let x1552 = x1549 + x1551;
            let x1619 = x745 - x744;
            let x1620 = x740 + x1619;
            let x1621 = x1620 - x741;
            let x1622 = 2.0 * x1621;
            let x1625 = x730 + x734;
            let x1627 = x735 - x1625;
            let x1628 = x731 + x1627;
            let x1629 = 2.0 * x1628;
            let x1632 = x720 - x724;
            let x1633 = x1632 - x721;
            let x1634 = x725 + x1633;
            let x1635 = 2.0 * x1634;
            let x1656 = 2.0 * x1622;
            let x1658 = 2.0 * x1629;
            let x1660 = 2.0 * x1635;
            let x1762 = s[15] * s[24];
            let x1764 = s[17] * s[20];
            let x1766 = s[18] * s[22];
            let x1776 = s[15] * s[23];
            let x1780 = s[17] * s[22];
            let x1782 = s[18] * s[20];
            let x1790 = s[14] * s[22];
            let x1800 = s[14] * s[20];
            let x1807 = s[14] * s[24];
            let x1817 = s[14] * s[23];
            let x1897 = x982 + x985;
            let x1899 = x985 - x1897;
            let x1900 = x982 + x1899;
            let x1901 = 2.0 * x1900;
            let x1904 = x974 - x977;
            let x1905 = x1904 - x974;
            let x1906 = x977 + x1905;
            let x1907 = 2.0 * x1906;
            let x1908 = 2.0 * x1901;
            let x1909 = 2.0 * x1907;
            let x1910 = x909 * x1656;
            let x1912 = x911 * x1658;
            let x1913 = s[17] * x1908;
            let x1914 = x1912 + x1913;
            let x1916 = x912 * x1660;
            let x1917 = s[18] * x1909;
            let x1918 = x1916 + x1917;
            let x1924 = x908 * x1656;
            let x1926 = x912 * x1658;
            let x1927 = s[18] * x1908;
            let x1928 = x1926 + x1927;
            let x1931 = x911 * x1660;
            let x1932 = s[17] * x1909;
            let x1933 = x1931 + x1932;
            let x1938 = x912 * x1656;
            let x1940 = x908 * x1658;
            let x1941 = s[14] * x1908;
            let x1942 = x1940 + x1941;
            let x1944 = x909 * x1660;
            let x1945 = s[15] * x1909;
            let x1946 = x1944 + x1945;
            let x1952 = x911 * x1656;
            let x1955 = x909 * x1658;
            let x1956 = s[15] * x1908;
            let x1957 = x1955 + x1956;
            let x1959 = x908 * x1660;
            let x1960 = s[14] * x1909;
            let x1961 = x1959 + x1960;
            let x1966 = qd[10] * qd[10];
            let x1967 = qd[11] * qd[11];
            let x1968 = qd[12] * qd[12];
            let x1969 = qd[13] * qd[13];
            let x1970 = x1966 + x1967;
            let x1971 = x1968 + x1970;
            let x1972 = x1969 + x1971;
            let x2144 = s[25] * s[32];
            let x2146 = 0.001 * x2144;
            let x2162 = s[9] * 0.004;
            let x2164 = s[25] * x617;
            let x2165 = 0.001 * x2164;
            let x2176 = s[11] * 0.004;
            let x2206 = s[21] * s[32];
            let x2208 = 0.001 * x2206;
            let x2216 = s[21] * x617;
            let x2217 = 0.001 * x2216;
            let x2221 = s[10] * 0.004;
            let x2595 = 2.0 * s[41];
            let x2596 = s[41] * x2595;
            let x2597 = 0.001 * x2596;
            let x2598 = x2217 + x2597;
            let x2599 = x2146 + x2598;
            let x2600 = 0.5 * x2599;
            let x2601 = 0.004 * s[33];
            let x2602 = x2600 + x2601;
            let x2603 = s[41] * s[42];
            let x2604 = 0.001 * x2603;
            let x2605 = x2604 - x2208;
            let x2606 = x2165 + x2605;
            let x2607 = 0.5 * x2606;
            let x2609 = 0.004 * s[39];
            let x2610 = x2609 - x2607;
            let x2611 = s[32] * s[41];
            let x2612 = 0.001 * x2611;
            let x2613 = s[21] * s[42];
            let x2614 = 0.001 * x2613;
            let x2615 = s[25] * x2595;
            let x2616 = 0.001 * x2615;
            let x2618 = x2612 + x2614;
            let x2619 = x2618 - x2616;
            let x2620 = 0.5 * x2619;
            let x2622 = 0.004 * s[38];
            let x2623 = x2622 - x2620;
            let x2624 = x617 * s[41];
            let x2625 = 0.001 * x2624;
            let x2627 = s[21] * x2595;
            let x2628 = 0.001 * x2627;
            let x2629 = s[25] * s[42];
            let x2630 = 0.001 * x2629;
            let x2631 = x2628 - x2625;
            let x2632 = x2630 + x2631;
            let x2633 = 0.5 * x2632;
            let x2635 = 0.004 * s[36];
            let x2636 = x2635 - x2633;
            let x2637 = s[40] * x2595;
            let x2638 = 0.001 * x2637;
            let x2640 = x2165 - x2638;
            let x2641 = x2640 - x2208;
            let x2642 = 0.5 * x2641;
            let x2643 = x2609 + x2642;
            let x2644 = s[40] * s[42];
            let x2645 = 0.001 * x2644;
            let x2646 = x2146 + x2645;
            let x2647 = x2217 + x2646;
            let x2648 = 0.5 * x2647;
            let x2649 = 0.004 * s[34];
            let x2650 = x2648 + x2649;
            let x2651 = s[32] * s[40];
            let x2652 = 0.001 * x2651;
            let x2655 = x2652 - x2630;
            let x2656 = x2655 - x2628;
            let x2657 = 0.5 * x2656;
            let x2658 = 0.004 * s[35];
            let x2659 = x2657 + x2658;
            let x2660 = x617 * s[40];
            let x2661 = 0.001 * x2660;
            let x2662 = x2616 + x2661;
            let x2664 = x2614 - x2662;
            let x2665 = 0.5 * x2664;
            let x2666 = 0.004 * s[37];
            let x2667 = x2665 + x2666;
            let x2668 = x2612 - x2662;
            let x2669 = 0.5 * x2668;
            let x2670 = x2622 + x2669;
            let x2672 = x2630 - x2652;
            let x2673 = x2672 - x2625;
            let x2674 = 0.5 * x2673;
            let x2675 = x2658 + x2674;
            let x2676 = x2597 + x2646;
            let x2677 = 0.5 * x2676;
            let x2678 = x2162 + x2677;
            let x2680 = x2638 - x2165;
            let x2681 = x2680 - x2604;
            let x2682 = 0.5 * x2681;
            let x2683 = x2176 + x2682;
            let x2684 = x2631 - x2652;
            let x2685 = 0.5 * x2684;
            let x2686 = x2635 + x2685;
            let x2688 = x2661 - x2618;
            let x2689 = 0.5 * x2688;
            let x2690 = x2666 + x2689;
            let x2691 = x2605 - x2638;
            let x2692 = 0.5 * x2691;
            let x2693 = x2176 + x2692;
            let x2694 = x2598 + x2645;
            let x2695 = 0.5 * x2694;
            let x2696 = x2221 + x2695;
            let x3415 = x1490 * k[17];
            let x3416 = x1494 * k[18];
            let x3417 = x1498 * k[18];
            let x3418 = x3415 + x3416;
            let x3419 = x3417 + x3418;
            let x3420 = 0.5 * x3419;
            let x3421 = x1504 * k[17];
            let x3422 = x1508 * k[18];
            let x3424 = x1513 * k[18];
            let x3425 = x3421 - x3422;
            let x3426 = x3424 + x3425;
            let x3427 = 0.5 * x3426;
            let x3428 = x1518 * k[17];
            let x3429 = x1522 * k[18];
            let x3430 = x1526 * k[18];
            let x3432 = x3428 + x3429;
            let x3433 = x3432 - x3430;
            let x3434 = 0.5 * x3433;
            let x3435 = x1532 * k[17];
            let x3437 = x1537 * k[18];
            let x3438 = x1541 * k[18];
            let x3439 = x3437 - x3435;
            let x3440 = x3438 + x3439;
            let x3441 = 0.5 * x3440;
            let x3442 = x1492 * k[18];
            let x3443 = x1496 * k[18];
            let x3444 = x3415 + x3442;
            let x3445 = x3443 + x3444;
            let x3446 = 0.5 * x3445;
            let x3447 = x3420 + x3446;
            let x3448 = q[3] * k[20];
            let x3449 = x1552 * x3448;
            let x3451 = x3447 - x3449;
            let x3453 = x1506 * k[18];
            let x3454 = x1511 * k[18];
            let x3456 = x3453 - x3421;
            let x3457 = x3456 - x3454;
            let x3458 = 0.5 * x3457;
            let x3460 = x3458 - x3427;
            let x3461 = q[4] * k[20];
            let x3462 = x1552 * x3461;
            let x3464 = x3460 - x3462;
            let x3465 = x1520 * k[18];
            let x3466 = x1524 * k[18];
            let x3467 = x3428 + x3465;
            let x3469 = x3466 - x3467;
            let x3470 = 0.5 * x3469;
            let x3472 = x3470 - x3434;
            let x3473 = q[5] * k[20];
            let x3474 = x1552 * x3473;
            let x3476 = x3472 - x3474;
            let x3477 = x1535 * k[18];
            let x3479 = x1539 * k[18];
            let x3481 = x3435 - x3477;
            let x3482 = x3481 - x3479;
            let x3483 = 0.5 * x3482;
            let x3485 = x3483 - x3441;
            let x3486 = q[6] * k[20];
            let x3487 = x1552 * x3486;
            let x3489 = x3485 - x3487;
            let x3509 = x1762 * k[17];
            let x3510 = x1764 * k[19];
            let x3511 = x1766 * k[19];
            let x3513 = x3509 + x3510;
            let x3514 = x3513 - x3511;
            let x3515 = 0.5 * x3514;
            let x3517 = s[6] * k[21];
            let x3518 = x3517 - x3515;
            let x3519 = x1776 * k[17];
            let x3521 = x1780 * k[19];
            let x3522 = x1782 * k[19];
            let x3523 = x3521 - x3519;
            let x3524 = x3522 + x3523;
            let x3525 = 0.5 * x3524;
            let x3527 = s[4] * k[21];
            let x3528 = x3527 - x3525;
            let x3529 = x1790 * k[17];
            let x3531 = s[46] - x3529;
            let x3532 = x3531 - s[45];
            let x3533 = 0.5 * x3532;
            let x3534 = s[47] + x3533;
            let x3535 = x1800 * k[17];
            let x3536 = s[44] + x3535;
            let x3537 = s[43] + x3536;
            let x3538 = 0.5 * x3537;
            let x3539 = s[0] * k[21];
            let x3540 = x3538 + x3539;
            let x3541 = x1807 * k[17];
            let x3544 = x3541 - x3522;
            let x3545 = x3544 - x3521;
            let x3546 = 0.5 * x3545;
            let x3547 = s[3] * k[21];
            let x3548 = x3546 + x3547;
            let x3549 = x1817 * k[17];
            let x3550 = x3511 + x3549;
            let x3552 = x3510 - x3550;
            let x3553 = 0.5 * x3552;
            let x3554 = s[5] * k[21];
            let x3555 = x3553 + x3554;
            let x3556 = x1766 * k[17];
            let x3557 = x1817 * k[19];
            let x3558 = x1762 * k[19];
            let x3559 = x3556 + x3557;
            let x3561 = x3558 - x3559;
            let x3562 = 0.5 * x3561;
            let x3563 = x3517 + x3562;
            let x3564 = x1782 * k[17];
            let x3565 = x1807 * k[19];
            let x3567 = x1776 * k[19];
            let x3569 = x3564 - x3565;
            let x3570 = x3569 - x3567;
            let x3571 = 0.5 * x3570;
            let x3572 = x3547 + x3571;
            let x3573 = s[28] * k[17];
            let x3574 = x1800 * k[19];
            let x3575 = s[26] * k[19];
            let x3576 = x3573 + x3574;
            let x3577 = x3575 + x3576;
            let x3578 = 0.5 * x3577;
            let x3579 = s[1] * k[21];
            let x3580 = x3578 + x3579;
            let x3581 = s[31] * k[17];
            let x3583 = x1790 * k[19];
            let x3584 = s[29] * k[19];
            let x3586 = x3583 - x3581;
            let x3587 = x3586 - x3584;
            let x3588 = 0.5 * x3587;
            let x3589 = s[7] * k[21];
            let x3590 = x3588 + x3589;
            let x3591 = x1780 * k[17];
            let x3592 = x3591 - x3567;
            let x3593 = x3592 - x3565;
            let x3594 = 0.5 * x3593;
            let x3595 = x3527 + x3594;
            let x3596 = x1764 * k[17];
            let x3597 = x3558 + x3596;
            let x3599 = x3557 - x3597;
            let x3600 = 0.5 * x3599;
            let x3601 = x3554 + x3600;
            let x3602 = s[30] * k[17];
            let x3605 = x3584 - x3602;
            let x3606 = x3605 - x3583;
            let x3607 = 0.5 * x3606;
            let x3608 = x3589 + x3607;
            let x3609 = s[27] * k[17];
            let x3610 = x3575 + x3609;
            let x3611 = x3574 + x3610;
            let x3612 = 0.5 * x3611;
            let x3613 = s[2] * k[21];
            let x3614 = x3612 + x3613;
            let x3615 = x1910 * k[17];
            let x3616 = x1914 * k[19];
            let x3617 = x1918 * k[19];
            let x3618 = x3615 + x3616;
            let x3619 = x3617 + x3618;
            let x3620 = 0.5 * x3619;
            let x3621 = x1924 * k[17];
            let x3622 = x1928 * k[19];
            let x3624 = x1933 * k[19];
            let x3625 = x3621 - x3622;
            let x3626 = x3624 + x3625;
            let x3627 = 0.5 * x3626;
            let x3628 = x1938 * k[17];
            let x3629 = x1942 * k[19];
            let x3630 = x1946 * k[19];
            let x3632 = x3628 + x3629;
            let x3633 = x3632 - x3630;
            let x3634 = 0.5 * x3633;
            let x3635 = x1952 * k[17];
            let x3637 = x1957 * k[19];
            let x3638 = x1961 * k[19];
            let x3639 = x3637 - x3635;
            let x3640 = x3638 + x3639;
            let x3641 = 0.5 * x3640;
            let x3642 = x1912 * k[19];
            let x3643 = x1916 * k[19];
            let x3644 = x3615 + x3642;
            let x3645 = x3643 + x3644;
            let x3646 = 0.5 * x3645;
            let x3647 = x3620 + x3646;
            let x3648 = q[10] * k[21];
            let x3649 = x1972 * x3648;
            let x3651 = x3647 - x3649;
            let x3653 = x1926 * k[19];
            let x3654 = x1931 * k[19];
            let x3656 = x3653 - x3621;
            let x3657 = x3656 - x3654;
            let x3658 = 0.5 * x3657;
            let x3660 = x3658 - x3627;
            let x3661 = q[11] * k[21];
            let x3662 = x1972 * x3661;
            let x3664 = x3660 - x3662;
            let x3665 = x1940 * k[19];
            let x3666 = x1944 * k[19];
            let x3667 = x3628 + x3665;
            let x3669 = x3666 - x3667;
            let x3670 = 0.5 * x3669;
            let x3672 = x3670 - x3634;
            let x3673 = q[12] * k[21];
            let x3674 = x1972 * x3673;
            let x3676 = x3672 - x3674;
            let x3677 = x1955 * k[19];
            let x3679 = x1959 * k[19];
            let x3681 = x3635 - x3677;
            let x3682 = x3681 - x3679;
            let x3683 = 0.5 * x3682;
            let x3685 = x3683 - x3641;
            let x3686 = q[13] * k[21];
            let x3687 = x1972 * x3686;
            let x3689 = x3685 - x3687;
            mass[24] = x3518;
            mass[25] = x3528;
            mass[26] = x3534;
            mass[27] = x3540;
            mass[28] = x3548;
            mass[29] = x3555;
            mass[30] = x3563;
            mass[31] = x3572;
            mass[32] = x3580;
            mass[33] = x3590;
            mass[34] = x3595;
            mass[35] = x3601;
            mass[36] = x3608;
            mass[37] = x3614;
            mass[38] = 1.0;
            mass[39] = x2602;
            mass[40] = x2610;
            mass[41] = x2623;
            mass[42] = x2636;
            mass[43] = x2643;
            mass[44] = x2650;
            mass[45] = x2659;
            mass[46] = x2667;
            mass[47] = x2670;
            mass[48] = x2675;
            mass[49] = x2678;
            mass[50] = x2683;
            mass[51] = x2686;
            mass[52] = x2690;
            mass[53] = x2693;
            mass[54] = x2696;
            force[0] = 0.0;
            force[1] = -2.943;
            force[2] = 0.0;
            force[3] = x3451;
            force[4] = x3464;
            force[5] = x3476;
            force[6] = x3489;
            force[7] = 0.0;
            force[8] = -5.886;
            force[9] = 0.0;
            force[10] = x3651;
            force[11] = x3664;
            force[12] = x3676;
            force[13] = x3689;
            force[14] = 0.0;
        }
        #[inline(never)]
        fn eval_newton_part_2(
            q: &[f64; 19],
            qd: &[f64; 19],
            s: &[f64; 48],
            force: &mut [f64; 19],
        ) {
            let x782 = q[18] * qd[17];
            let x783 = q[17] * qd[18];
            let x914 = 2.0 * qd[17];
            let x916 = 2.0 * qd[18];
            let x2059 = qd[15] * qd[15];
            let x2062 = qd[16] * qd[16];
            let x2073 = 2.0 * qd[15];
            let x2075 = 2.0 * qd[16];
            let x2350 = qd[17] * qd[17];
            let x2351 = qd[18] * qd[18];
            let x2363 = q[17] * 0.004;
            let x2382 = q[18] * 0.004;
            let x2499 = q[17] * qd[16];
            let x2500 = q[16] * qd[17];
            let x2503 = q[18] * qd[15];
            let x2504 = q[15] * qd[18];
            let x2507 = q[18] * qd[16];
            let x2508 = q[16] * qd[18];
            let x2511 = q[17] * qd[15];
            let x2512 = q[15] * qd[17];
            let x2517 = q[16] * qd[15];
            let x2518 = q[15] * qd[16];
            let x2544 = qd[16] * qd[17];
            let x2547 = qd[15] * qd[18];
            let x2550 = qd[16] * qd[18];
            let x2553 = qd[15] * qd[17];
            let x2699 = x2518 - x2517;
            let x2700 = x782 + x2699;
            let x2701 = x2700 - x783;
            let x2702 = 2.0 * x2701;
            let x2703 = x2507 + x2511;
            let x2705 = x2512 - x2703;
            let x2706 = x2508 + x2705;
            let x2707 = 2.0 * x2706;
            let x2710 = x2499 - x2503;
            let x2711 = x2710 - x2500;
            let x2712 = x2504 + x2711;
            let x2713 = 2.0 * x2712;
            let x2714 = 2.0 * x2702;
            let x2715 = 2.0 * x2707;
            let x2716 = 2.0 * x2713;
            let x2717 = x2550 + x2553;
            let x2719 = x2553 - x2717;
            let x2720 = x2550 + x2719;
            let x2721 = 2.0 * x2720;
            let x2724 = x2544 - x2547;
            let x2725 = x2724 - x2544;
            let x2726 = x2547 + x2725;
            let x2727 = 2.0 * x2726;
            let x2728 = 2.0 * x2721;
            let x2729 = 2.0 * x2727;
            let x2730 = x2075 * x2714;
            let x2731 = 0.001 * x2730;
            let x2732 = x914 * x2715;
            let x2733 = s[21] * x2728;
            let x2734 = x2732 + x2733;
            let x2735 = 0.001 * x2734;
            let x2736 = x916 * x2716;
            let x2737 = s[25] * x2729;
            let x2738 = x2736 + x2737;
            let x2739 = 0.001 * x2738;
            let x2740 = x2731 + x2735;
            let x2741 = x2739 + x2740;
            let x2742 = 0.5 * x2741;
            let x2743 = x2073 * x2714;
            let x2744 = 0.001 * x2743;
            let x2745 = x916 * x2715;
            let x2746 = s[25] * x2728;
            let x2747 = x2745 + x2746;
            let x2748 = 0.001 * x2747;
            let x2750 = x914 * x2716;
            let x2751 = s[21] * x2729;
            let x2752 = x2750 + x2751;
            let x2753 = 0.001 * x2752;
            let x2754 = x2744 - x2748;
            let x2755 = x2753 + x2754;
            let x2756 = 0.5 * x2755;
            let x2757 = x916 * x2714;
            let x2758 = 0.001 * x2757;
            let x2759 = x2073 * x2715;
            let x2760 = s[40] * x2728;
            let x2761 = x2759 + x2760;
            let x2762 = 0.001 * x2761;
            let x2763 = x2075 * x2716;
            let x2764 = s[41] * x2729;
            let x2765 = x2763 + x2764;
            let x2766 = 0.001 * x2765;
            let x2768 = x2758 + x2762;
            let x2769 = x2768 - x2766;
            let x2770 = 0.5 * x2769;
            let x2771 = x914 * x2714;
            let x2772 = 0.001 * x2771;
            let x2774 = x2075 * x2715;
            let x2775 = s[41] * x2728;
            let x2776 = x2774 + x2775;
            let x2777 = 0.001 * x2776;
            let x2778 = x2073 * x2716;
            let x2779 = s[40] * x2729;
            let x2780 = x2778 + x2779;
            let x2781 = 0.001 * x2780;
            let x2782 = x2777 - x2772;
            let x2783 = x2781 + x2782;
            let x2784 = 0.5 * x2783;
            let x2785 = x2059 + x2062;
            let x2786 = x2350 + x2785;
            let x2787 = x2351 + x2786;
            let x2788 = 0.001 * x2732;
            let x2789 = 0.001 * x2736;
            let x2790 = x2731 + x2788;
            let x2791 = x2789 + x2790;
            let x2792 = 0.5 * x2791;
            let x2793 = x2742 + x2792;
            let x2794 = q[15] * 0.004;
            let x2795 = x2787 * x2794;
            let x2797 = x2793 - x2795;
            let x2799 = 0.001 * x2745;
            let x2800 = 0.001 * x2750;
            let x2802 = x2799 - x2744;
            let x2803 = x2802 - x2800;
            let x2804 = 0.5 * x2803;
            let x2806 = x2804 - x2756;
            let x2807 = q[16] * 0.004;
            let x2808 = x2787 * x2807;
            let x2810 = x2806 - x2808;
            let x2811 = 0.001 * x2759;
            let x2812 = 0.001 * x2763;
            let x2813 = x2758 + x2811;
            let x2815 = x2812 - x2813;
            let x2816 = 0.5 * x2815;
            let x2818 = x2816 - x2770;
            let x2819 = x2363 * x2787;
            let x2821 = x2818 - x2819;
            let x2822 = 0.001 * x2774;
            let x2824 = 0.001 * x2778;
            let x2826 = x2772 - x2822;
            let x2827 = x2826 - x2824;
            let x2828 = 0.5 * x2827;
            let x2830 = x2828 - x2784;
            let x2831 = x2382 * x2787;
            let x2833 = x2830 - x2831;
            force[15] = x2797;
            force[16] = x2810;
            force[17] = x2821;
            force[18] = x2833;
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
/// `slider_crank` with the `exact` formulation.
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
/// `slider_crank` with the `exact` formulation. At run-time parameter values (`Exact::with_parameters`).
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
