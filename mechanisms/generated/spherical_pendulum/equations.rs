//! Generated equations of `spherical_pendulum` (rigid spherical pendulum released into a steady cone, Y up). Do not edit.
//!
//! Regenerate with `cargo xtask generate spherical_pendulum` from `mechanisms/spherical_pendulum.toml`.
//!
//! 7 coordinates, 4 constraints, 19 structural nonzeros in Φq.
//! Rank 4 at the initial pose; mobility 3 (Grübler count 3), 3 DOF left with drivers.
//! Each body owns `[X, Y, Z]` (centre of mass), then `[θ, β, γ]` (A = Rz(γ)·Ry(β)·Rx(θ))
//! or Euler parameters `[e0, e1, e2, e3]`. Equations of motion: `M q̈ + Φqᵀλ = Q`, `Φq q̈ = γ`.
//! Sparse outputs hold the pattern's nonzeros in order (row-major, columns ascending).
//!
//! Coordinates:
//! - `0..7` bob (quaternion)
//!
//! Constraint rows:
//! - `0..3` pivot (spherical, ground – bob)
//! - `3` bob.norm: eᵀe − 1
#![allow(
    clippy::approx_constant,
    clippy::excessive_precision,
    clippy::too_many_arguments,
    clippy::unreadable_literal
)]
use symbody_runtime::{
    BodyInfo, Direction, Entry, Formulation, JointInfo, JointKind, KinematicOutputs,
    Mechanism, MechanismInfo, NewtonOutputs, Origin, PlatformInfo, Rotation,
    TangentOutputs,
};
use symbody_runtime::parameters::{ParameterError, RunTimeParameters};
/// Constraint residual Φ(q, t).
pub fn phi(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    let _ = t;
    phi_part_0(k, q, out);
}
#[inline(never)]
fn phi_part_0(k: &[f64; 8], q: &[f64; 7], out: &mut [f64; 4]) {
    let x9 = q[3] * q[3];
    let x10 = q[4] * q[4];
    let x11 = q[5] * q[5];
    let x12 = q[6] * q[6];
    let x13 = x9 + x10;
    let x14 = 2.0 * x13;
    let x16 = x14 - 1.0;
    let x17 = x9 + x11;
    let x18 = 2.0 * x17;
    let x19 = x18 - 1.0;
    let x23 = q[4] * q[5];
    let x24 = 2.0 * x23;
    let x25 = q[3] * q[6];
    let x27 = 2.0 * x25;
    let x29 = x24 - x27;
    let x30 = q[4] * q[6];
    let x31 = 2.0 * x30;
    let x32 = q[3] * q[5];
    let x33 = 2.0 * x32;
    let x35 = x24 + x27;
    let x36 = q[5] * q[6];
    let x37 = 2.0 * x36;
    let x38 = q[3] * q[4];
    let x40 = 2.0 * x38;
    let x45 = x31 - x33;
    let x46 = x37 + x40;
    let x65 = x11 + x13;
    let x66 = x12 + x65;
    let x67 = x66 - 1.0;
    let x1436 = x16 * k[0];
    let x1437 = x29 * k[1];
    let x1438 = x1436 + x1437;
    let x1439 = x35 * k[0];
    let x1440 = x19 * k[1];
    let x1441 = x1439 + x1440;
    let x1442 = x45 * k[0];
    let x1443 = x46 * k[1];
    let x1444 = x1442 + x1443;
    let x1445 = q[0] + x1438;
    let x1446 = q[1] + x1441;
    let x1447 = q[2] + x1444;
    let x1448 = -x1445;
    let x1449 = -x1446;
    let x1450 = -x1447;
    out[0] = x1448;
    out[1] = x1449;
    out[2] = x1450;
    out[3] = x67;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
    let _ = t;
    phi_q_part_0(k, q, out);
}
#[inline(never)]
fn phi_q_part_0(k: &[f64; 8], q: &[f64; 7], out: &mut [f64; 19]) {
    let x68 = q[3] * 2.0;
    let x69 = q[4] * 2.0;
    let x70 = q[5] * 2.0;
    let x71 = q[6] * 2.0;
    let x72 = 2.0 * x68;
    let x89 = 2.0 * x69;
    let x97 = 2.0 * x70;
    let x1451 = x72 * k[0];
    let x1452 = x71 * k[1];
    let x1454 = x1451 - x1452;
    let x1455 = x71 * k[0];
    let x1456 = x72 * k[1];
    let x1457 = x1455 + x1456;
    let x1458 = x70 * k[0];
    let x1459 = -x1458;
    let x1460 = x69 * k[1];
    let x1461 = x1460 - x1458;
    let x1462 = -x1454;
    let x1463 = -x1457;
    let x1464 = -x1461;
    let x1465 = x89 * k[0];
    let x1466 = x70 * k[1];
    let x1467 = x1465 + x1466;
    let x1468 = x68 * k[1];
    let x1469 = x1455 + x1468;
    let x1470 = -x1467;
    let x1471 = -x1469;
    let x1472 = x69 * k[0];
    let x1473 = x97 * k[1];
    let x1474 = x1472 + x1473;
    let x1475 = x68 * k[0];
    let x1476 = -x1475;
    let x1477 = x1452 - x1475;
    let x1478 = -x1460;
    let x1479 = -x1474;
    let x1480 = -x1477;
    let x1481 = x1466 + x1472;
    let x1482 = -x1481;
    out[0] = -1.0;
    out[1] = x1462;
    out[2] = x1470;
    out[3] = x1478;
    out[4] = x1468;
    out[5] = -1.0;
    out[6] = x1463;
    out[7] = x1459;
    out[8] = x1479;
    out[9] = x1476;
    out[10] = -1.0;
    out[11] = x1464;
    out[12] = x1471;
    out[13] = x1480;
    out[14] = x1482;
    out[15] = x68;
    out[16] = x69;
    out[17] = x70;
    out[18] = x71;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    let _ = k;
    let _ = q;
    let _ = t;
    phi_t_part_0(out);
}
#[inline(never)]
fn phi_t_part_0(out: &mut [f64; 4]) {
    out[0] = 0.0;
    out[1] = 0.0;
    out[2] = 0.0;
    out[3] = 0.0;
}
/// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
pub fn gamma(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    let _ = q;
    let _ = t;
    gamma_part_0(k, qd, out);
}
#[inline(never)]
fn gamma_part_0(k: &[f64; 8], qd: &[f64; 7], out: &mut [f64; 4]) {
    let x173 = 2.0 * qd[3];
    let x174 = 2.0 * qd[4];
    let x175 = 2.0 * qd[5];
    let x176 = 2.0 * qd[6];
    let x177 = qd[3] * x173;
    let x178 = qd[4] * x174;
    let x179 = qd[5] * x175;
    let x180 = qd[6] * x176;
    let x181 = x177 + x178;
    let x182 = 2.0 * x181;
    let x183 = x177 + x179;
    let x184 = 2.0 * x183;
    let x185 = qd[4] * qd[5];
    let x186 = x185 + x185;
    let x187 = 2.0 * x186;
    let x188 = qd[3] * qd[6];
    let x189 = x188 + x188;
    let x190 = 2.0 * x189;
    let x192 = x187 - x190;
    let x193 = qd[4] * qd[6];
    let x194 = x193 + x193;
    let x195 = 2.0 * x194;
    let x196 = qd[3] * qd[5];
    let x197 = x196 + x196;
    let x198 = 2.0 * x197;
    let x199 = x187 + x190;
    let x200 = qd[5] * qd[6];
    let x201 = x200 + x200;
    let x202 = 2.0 * x201;
    let x203 = qd[3] * qd[4];
    let x204 = x203 + x203;
    let x205 = 2.0 * x204;
    let x207 = x195 - x198;
    let x208 = x202 + x205;
    let x221 = x179 + x181;
    let x222 = x180 + x221;
    let x223 = -x222;
    let x1483 = x182 * k[0];
    let x1484 = x192 * k[1];
    let x1485 = x1483 + x1484;
    let x1486 = x199 * k[0];
    let x1487 = x184 * k[1];
    let x1488 = x1486 + x1487;
    let x1489 = x207 * k[0];
    let x1490 = x208 * k[1];
    let x1491 = x1489 + x1490;
    out[0] = x1485;
    out[1] = x1488;
    out[2] = x1491;
    out[3] = x223;
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
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let phi: &mut [f64; 4] = phi.try_into().expect("phi must have 4 entries");
    let phi_q: &mut [f64; 19] = phi_q.try_into().expect("phi_q must have 19 entries");
    let phi_t: &mut [f64; 4] = phi_t.try_into().expect("phi_t must have 4 entries");
    let gamma: &mut [f64; 4] = gamma.try_into().expect("gamma must have 4 entries");
    let _ = t;
    eval_kinematics_part_0(k, q, qd, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_part_0(
    k: &[f64; 8],
    q: &[f64; 7],
    qd: &[f64; 7],
    phi: &mut [f64; 4],
    phi_q: &mut [f64; 19],
    phi_t: &mut [f64; 4],
    gamma: &mut [f64; 4],
) {
    let x9 = q[3] * q[3];
    let x10 = q[4] * q[4];
    let x11 = q[5] * q[5];
    let x12 = q[6] * q[6];
    let x13 = x9 + x10;
    let x14 = 2.0 * x13;
    let x16 = x14 - 1.0;
    let x17 = x9 + x11;
    let x18 = 2.0 * x17;
    let x19 = x18 - 1.0;
    let x23 = q[4] * q[5];
    let x24 = 2.0 * x23;
    let x25 = q[3] * q[6];
    let x27 = 2.0 * x25;
    let x29 = x24 - x27;
    let x30 = q[4] * q[6];
    let x31 = 2.0 * x30;
    let x32 = q[3] * q[5];
    let x33 = 2.0 * x32;
    let x35 = x24 + x27;
    let x36 = q[5] * q[6];
    let x37 = 2.0 * x36;
    let x38 = q[3] * q[4];
    let x40 = 2.0 * x38;
    let x45 = x31 - x33;
    let x46 = x37 + x40;
    let x65 = x11 + x13;
    let x66 = x12 + x65;
    let x67 = x66 - 1.0;
    let x68 = q[3] * 2.0;
    let x69 = q[4] * 2.0;
    let x70 = q[5] * 2.0;
    let x71 = q[6] * 2.0;
    let x72 = 2.0 * x68;
    let x89 = 2.0 * x69;
    let x97 = 2.0 * x70;
    let x173 = 2.0 * qd[3];
    let x174 = 2.0 * qd[4];
    let x175 = 2.0 * qd[5];
    let x176 = 2.0 * qd[6];
    let x177 = qd[3] * x173;
    let x178 = qd[4] * x174;
    let x179 = qd[5] * x175;
    let x180 = qd[6] * x176;
    let x181 = x177 + x178;
    let x182 = 2.0 * x181;
    let x183 = x177 + x179;
    let x184 = 2.0 * x183;
    let x185 = qd[4] * qd[5];
    let x186 = x185 + x185;
    let x187 = 2.0 * x186;
    let x188 = qd[3] * qd[6];
    let x189 = x188 + x188;
    let x190 = 2.0 * x189;
    let x192 = x187 - x190;
    let x193 = qd[4] * qd[6];
    let x194 = x193 + x193;
    let x195 = 2.0 * x194;
    let x196 = qd[3] * qd[5];
    let x197 = x196 + x196;
    let x198 = 2.0 * x197;
    let x199 = x187 + x190;
    let x200 = qd[5] * qd[6];
    let x201 = x200 + x200;
    let x202 = 2.0 * x201;
    let x203 = qd[3] * qd[4];
    let x204 = x203 + x203;
    let x205 = 2.0 * x204;
    let x207 = x195 - x198;
    let x208 = x202 + x205;
    let x221 = x179 + x181;
    let x222 = x180 + x221;
    let x223 = -x222;
    let x1436 = x16 * k[0];
    let x1437 = x29 * k[1];
    let x1438 = x1436 + x1437;
    let x1439 = x35 * k[0];
    let x1440 = x19 * k[1];
    let x1441 = x1439 + x1440;
    let x1442 = x45 * k[0];
    let x1443 = x46 * k[1];
    let x1444 = x1442 + x1443;
    let x1445 = q[0] + x1438;
    let x1446 = q[1] + x1441;
    let x1447 = q[2] + x1444;
    let x1448 = -x1445;
    let x1449 = -x1446;
    let x1450 = -x1447;
    let x1451 = x72 * k[0];
    let x1452 = x71 * k[1];
    let x1454 = x1451 - x1452;
    let x1455 = x71 * k[0];
    let x1456 = x72 * k[1];
    let x1457 = x1455 + x1456;
    let x1458 = x70 * k[0];
    let x1459 = -x1458;
    let x1460 = x69 * k[1];
    let x1461 = x1460 - x1458;
    let x1462 = -x1454;
    let x1463 = -x1457;
    let x1464 = -x1461;
    let x1465 = x89 * k[0];
    let x1466 = x70 * k[1];
    let x1467 = x1465 + x1466;
    let x1468 = x68 * k[1];
    let x1469 = x1455 + x1468;
    let x1470 = -x1467;
    let x1471 = -x1469;
    let x1472 = x69 * k[0];
    let x1473 = x97 * k[1];
    let x1474 = x1472 + x1473;
    let x1475 = x68 * k[0];
    let x1476 = -x1475;
    let x1477 = x1452 - x1475;
    let x1478 = -x1460;
    let x1479 = -x1474;
    let x1480 = -x1477;
    let x1481 = x1466 + x1472;
    let x1482 = -x1481;
    let x1483 = x182 * k[0];
    let x1484 = x192 * k[1];
    let x1485 = x1483 + x1484;
    let x1486 = x199 * k[0];
    let x1487 = x184 * k[1];
    let x1488 = x1486 + x1487;
    let x1489 = x207 * k[0];
    let x1490 = x208 * k[1];
    let x1491 = x1489 + x1490;
    phi[0] = x1448;
    phi_q[0] = -1.0;
    phi_q[1] = x1462;
    phi_q[2] = x1470;
    phi_q[3] = x1478;
    phi_q[4] = x1468;
    phi_t[0] = 0.0;
    gamma[0] = x1485;
    phi[1] = x1449;
    phi_q[5] = -1.0;
    phi_q[6] = x1463;
    phi_q[7] = x1459;
    phi_q[8] = x1479;
    phi_q[9] = x1476;
    phi_t[1] = 0.0;
    gamma[1] = x1488;
    phi[2] = x1450;
    phi_q[10] = -1.0;
    phi_q[11] = x1464;
    phi_q[12] = x1471;
    phi_q[13] = x1480;
    phi_q[14] = x1482;
    phi_t[2] = 0.0;
    gamma[2] = x1491;
    phi[3] = x67;
    phi_q[15] = x68;
    phi_q[16] = x69;
    phi_q[17] = x70;
    phi_q[18] = x71;
    phi_t[3] = 0.0;
    gamma[3] = x223;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    potential_into_part_0(k, q, out);
}
#[inline(never)]
fn potential_into_part_0(k: &[f64; 8], q: &[f64; 7], out: &mut [f64; 1]) {
    let x1496 = q[1] * k[4];
    out[0] = x1496;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
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
    let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let dq: &[f64; 7] = dq.try_into().expect("dq must have n_coords entries");
    let dqd: &[f64; 7] = dqd.try_into().expect("dqd must have n_coords entries");
    let dp: &[f64; 10] = dp.try_into().expect("dp must have 10 entries");
    let phi: &mut [f64; 4] = phi.try_into().expect("phi must have 4 entries");
    let phi_q: &mut [f64; 19] = phi_q.try_into().expect("phi_q must have 19 entries");
    let phi_t: &mut [f64; 4] = phi_t.try_into().expect("phi_t must have 4 entries");
    let gamma: &mut [f64; 4] = gamma.try_into().expect("gamma must have 4 entries");
    let _ = t;
    kinematic_tangents_part_0(k, q, qd, dq, dqd, dp, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn kinematic_tangents_part_0(
    k: &[f64; 8],
    q: &[f64; 7],
    qd: &[f64; 7],
    dq: &[f64; 7],
    dqd: &[f64; 7],
    dp: &[f64; 10],
    phi: &mut [f64; 4],
    phi_q: &mut [f64; 19],
    phi_t: &mut [f64; 4],
    gamma: &mut [f64; 4],
) {
    let x9 = q[3] * q[3];
    let x10 = q[4] * q[4];
    let x11 = q[5] * q[5];
    let x13 = x9 + x10;
    let x14 = 2.0 * x13;
    let x16 = x14 - 1.0;
    let x17 = x9 + x11;
    let x18 = 2.0 * x17;
    let x19 = x18 - 1.0;
    let x23 = q[4] * q[5];
    let x24 = 2.0 * x23;
    let x25 = q[3] * q[6];
    let x27 = 2.0 * x25;
    let x29 = x24 - x27;
    let x30 = q[4] * q[6];
    let x31 = 2.0 * x30;
    let x32 = q[3] * q[5];
    let x33 = 2.0 * x32;
    let x35 = x24 + x27;
    let x36 = q[5] * q[6];
    let x37 = 2.0 * x36;
    let x38 = q[3] * q[4];
    let x40 = 2.0 * x38;
    let x45 = x31 - x33;
    let x46 = x37 + x40;
    let x68 = q[3] * 2.0;
    let x69 = q[4] * 2.0;
    let x70 = q[5] * 2.0;
    let x71 = q[6] * 2.0;
    let x72 = 2.0 * x68;
    let x89 = 2.0 * x69;
    let x97 = 2.0 * x70;
    let x173 = 2.0 * qd[3];
    let x174 = 2.0 * qd[4];
    let x175 = 2.0 * qd[5];
    let x176 = 2.0 * qd[6];
    let x177 = qd[3] * x173;
    let x178 = qd[4] * x174;
    let x179 = qd[5] * x175;
    let x181 = x177 + x178;
    let x182 = 2.0 * x181;
    let x183 = x177 + x179;
    let x184 = 2.0 * x183;
    let x185 = qd[4] * qd[5];
    let x186 = x185 + x185;
    let x187 = 2.0 * x186;
    let x188 = qd[3] * qd[6];
    let x189 = x188 + x188;
    let x190 = 2.0 * x189;
    let x192 = x187 - x190;
    let x193 = qd[4] * qd[6];
    let x194 = x193 + x193;
    let x195 = 2.0 * x194;
    let x196 = qd[3] * qd[5];
    let x197 = x196 + x196;
    let x198 = 2.0 * x197;
    let x199 = x187 + x190;
    let x200 = qd[5] * qd[6];
    let x201 = x200 + x200;
    let x202 = 2.0 * x201;
    let x203 = qd[3] * qd[4];
    let x204 = x203 + x203;
    let x205 = 2.0 * x204;
    let x207 = x195 - x198;
    let x208 = x202 + x205;
    let x688 = x68 * dq[3];
    let x689 = x69 * dq[4];
    let x690 = x70 * dq[5];
    let x691 = x71 * dq[6];
    let x692 = x688 + x689;
    let x693 = 2.0 * x692;
    let x694 = x688 + x690;
    let x695 = 2.0 * x694;
    let x696 = q[5] * dq[4];
    let x697 = q[4] * dq[5];
    let x698 = x696 + x697;
    let x699 = 2.0 * x698;
    let x700 = q[6] * dq[3];
    let x701 = q[3] * dq[6];
    let x702 = x700 + x701;
    let x703 = 2.0 * x702;
    let x705 = x699 - x703;
    let x706 = q[6] * dq[4];
    let x707 = q[4] * dq[6];
    let x708 = x706 + x707;
    let x709 = 2.0 * x708;
    let x710 = q[5] * dq[3];
    let x711 = q[3] * dq[5];
    let x712 = x710 + x711;
    let x713 = 2.0 * x712;
    let x714 = x699 + x703;
    let x715 = q[6] * dq[5];
    let x716 = q[5] * dq[6];
    let x717 = x715 + x716;
    let x718 = 2.0 * x717;
    let x719 = q[4] * dq[3];
    let x720 = q[3] * dq[4];
    let x721 = x719 + x720;
    let x722 = 2.0 * x721;
    let x724 = x709 - x713;
    let x725 = x718 + x722;
    let x727 = x16 * dp[8];
    let x730 = x29 * dp[9];
    let x734 = x35 * dp[8];
    let x737 = x19 * dp[9];
    let x741 = x45 * dp[8];
    let x744 = x46 * dp[9];
    let x753 = x690 + x692;
    let x754 = x691 + x753;
    let x755 = 2.0 * dq[3];
    let x756 = 2.0 * dq[4];
    let x757 = 2.0 * dq[5];
    let x758 = 2.0 * dq[6];
    let x759 = 2.0 * x755;
    let x760 = x72 * dp[8];
    let x763 = x71 * dp[9];
    let x768 = x71 * dp[8];
    let x771 = x72 * dp[9];
    let x775 = x70 * dp[8];
    let x779 = x69 * dp[9];
    let x786 = 2.0 * x756;
    let x787 = x89 * dp[8];
    let x790 = x70 * dp[9];
    let x794 = x68 * dp[9];
    let x800 = 2.0 * x757;
    let x801 = x69 * dp[8];
    let x804 = x97 * dp[9];
    let x808 = x68 * dp[8];
    let x854 = 2.0 * dqd[3];
    let x855 = 2.0 * dqd[4];
    let x856 = 2.0 * dqd[5];
    let x857 = 2.0 * dqd[6];
    let x858 = x173 * dqd[3];
    let x859 = qd[3] * x854;
    let x860 = x858 + x859;
    let x861 = x174 * dqd[4];
    let x862 = qd[4] * x855;
    let x863 = x861 + x862;
    let x864 = x175 * dqd[5];
    let x865 = qd[5] * x856;
    let x866 = x864 + x865;
    let x867 = x176 * dqd[6];
    let x868 = qd[6] * x857;
    let x869 = x867 + x868;
    let x870 = x860 + x863;
    let x871 = 2.0 * x870;
    let x872 = x860 + x866;
    let x873 = 2.0 * x872;
    let x874 = qd[5] * dqd[4];
    let x875 = qd[4] * dqd[5];
    let x876 = x874 + x875;
    let x877 = x876 + x876;
    let x878 = 2.0 * x877;
    let x879 = qd[6] * dqd[3];
    let x880 = qd[3] * dqd[6];
    let x881 = x879 + x880;
    let x882 = x881 + x881;
    let x883 = 2.0 * x882;
    let x885 = x878 - x883;
    let x886 = qd[6] * dqd[4];
    let x887 = qd[4] * dqd[6];
    let x888 = x886 + x887;
    let x889 = x888 + x888;
    let x890 = 2.0 * x889;
    let x891 = qd[5] * dqd[3];
    let x892 = qd[3] * dqd[5];
    let x893 = x891 + x892;
    let x894 = x893 + x893;
    let x895 = 2.0 * x894;
    let x896 = x878 + x883;
    let x897 = qd[6] * dqd[5];
    let x898 = qd[5] * dqd[6];
    let x899 = x897 + x898;
    let x900 = x899 + x899;
    let x901 = 2.0 * x900;
    let x902 = qd[4] * dqd[3];
    let x903 = qd[3] * dqd[4];
    let x904 = x902 + x903;
    let x905 = x904 + x904;
    let x906 = 2.0 * x905;
    let x908 = x890 - x895;
    let x909 = x901 + x906;
    let x910 = x182 * dp[8];
    let x913 = x192 * dp[9];
    let x917 = x199 * dp[8];
    let x920 = x184 * dp[9];
    let x924 = x207 * dp[8];
    let x927 = x208 * dp[9];
    let x931 = x866 + x870;
    let x932 = x869 + x931;
    let x933 = -x932;
    let x1698 = x693 * k[0];
    let x1699 = x727 + x1698;
    let x1700 = x705 * k[1];
    let x1701 = x730 + x1700;
    let x1702 = x1699 + x1701;
    let x1703 = x714 * k[0];
    let x1704 = x734 + x1703;
    let x1705 = x695 * k[1];
    let x1706 = x737 + x1705;
    let x1707 = x1704 + x1706;
    let x1708 = x724 * k[0];
    let x1709 = x741 + x1708;
    let x1710 = x725 * k[1];
    let x1711 = x744 + x1710;
    let x1712 = x1709 + x1711;
    let x1713 = dq[0] + x1702;
    let x1714 = dq[1] + x1707;
    let x1715 = dq[2] + x1712;
    let x1716 = -x1713;
    let x1717 = -x1714;
    let x1718 = -x1715;
    let x1719 = x759 * k[0];
    let x1720 = x760 + x1719;
    let x1721 = x758 * k[1];
    let x1722 = x763 + x1721;
    let x1724 = x1720 - x1722;
    let x1725 = x758 * k[0];
    let x1726 = x768 + x1725;
    let x1727 = x759 * k[1];
    let x1728 = x771 + x1727;
    let x1729 = x1726 + x1728;
    let x1730 = x757 * k[0];
    let x1731 = x775 + x1730;
    let x1732 = -x1731;
    let x1733 = x756 * k[1];
    let x1734 = x779 + x1733;
    let x1735 = x1734 - x1731;
    let x1736 = -x1724;
    let x1737 = -x1729;
    let x1738 = -x1735;
    let x1739 = x786 * k[0];
    let x1740 = x787 + x1739;
    let x1741 = x757 * k[1];
    let x1742 = x790 + x1741;
    let x1743 = x1740 + x1742;
    let x1744 = x755 * k[1];
    let x1745 = x794 + x1744;
    let x1746 = x1726 + x1745;
    let x1747 = -x1743;
    let x1748 = -x1746;
    let x1749 = x756 * k[0];
    let x1750 = x801 + x1749;
    let x1751 = x800 * k[1];
    let x1752 = x804 + x1751;
    let x1753 = x1750 + x1752;
    let x1754 = x755 * k[0];
    let x1755 = x808 + x1754;
    let x1756 = -x1755;
    let x1757 = x1722 - x1755;
    let x1758 = -x1734;
    let x1759 = -x1753;
    let x1760 = -x1757;
    let x1761 = x1742 + x1750;
    let x1762 = -x1761;
    let x1763 = x871 * k[0];
    let x1764 = x910 + x1763;
    let x1765 = x885 * k[1];
    let x1766 = x913 + x1765;
    let x1767 = x1764 + x1766;
    let x1768 = x896 * k[0];
    let x1769 = x917 + x1768;
    let x1770 = x873 * k[1];
    let x1771 = x920 + x1770;
    let x1772 = x1769 + x1771;
    let x1773 = x908 * k[0];
    let x1774 = x924 + x1773;
    let x1775 = x909 * k[1];
    let x1776 = x927 + x1775;
    let x1777 = x1774 + x1776;
    phi[0] = x1716;
    phi_q[0] = 0.0;
    phi_q[1] = x1736;
    phi_q[2] = x1747;
    phi_q[3] = x1758;
    phi_q[4] = x1745;
    phi_t[0] = 0.0;
    gamma[0] = x1767;
    phi[1] = x1717;
    phi_q[5] = 0.0;
    phi_q[6] = x1737;
    phi_q[7] = x1732;
    phi_q[8] = x1759;
    phi_q[9] = x1756;
    phi_t[1] = 0.0;
    gamma[1] = x1772;
    phi[2] = x1718;
    phi_q[10] = 0.0;
    phi_q[11] = x1738;
    phi_q[12] = x1748;
    phi_q[13] = x1760;
    phi_q[14] = x1762;
    phi_t[2] = 0.0;
    gamma[2] = x1777;
    phi[3] = x754;
    phi_q[15] = x755;
    phi_q[16] = x756;
    phi_q[17] = x757;
    phi_q[18] = x758;
    phi_t[3] = 0.0;
    gamma[3] = x933;
}
/// Number of generalized coordinates.
pub const N_COORDS: usize = 7usize;
/// Number of constraint rows.
pub const N_CONSTRAINTS: usize = 4usize;
/// Row of each Φq nonzero.
pub static PHI_Q_ROWS: [u32; 19usize] = [
    0u32, 0u32, 0u32, 0u32, 0u32, 1u32, 1u32, 1u32, 1u32, 1u32, 2u32, 2u32, 2u32, 2u32,
    2u32, 3u32, 3u32, 3u32, 3u32,
];
/// Column of each Φq nonzero.
pub static PHI_Q_COLS: [u32; 19usize] = [
    0u32, 3u32, 4u32, 5u32, 6u32, 1u32, 3u32, 4u32, 5u32, 6u32, 2u32, 3u32, 4u32, 5u32,
    6u32, 3u32, 4u32, 5u32, 6u32,
];
/// Bodies in coordinate order.
pub static BODIES: [BodyInfo; 1usize] = [
    BodyInfo {
        name: "bob",
        coord_offset: 0usize,
        rotation: Rotation::Quaternion,
        mass: 1f64,
        inertia: [0.05f64, 0.01f64, 0.05f64],
    },
];
/// Joints in row order, then drivers.
pub static JOINTS: [JointInfo; 2usize] = [
    JointInfo {
        name: "pivot",
        kind: JointKind::Spherical,
        body1: None,
        body2: Some(0usize),
        row_start: 0usize,
        rows: 3usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0.00000000000000011102230246251565f64, 0.9999999999999999f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
    JointInfo {
        name: "bob.norm",
        kind: JointKind::Normalization,
        body1: Some(0usize),
        body2: None,
        row_start: 3usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
];
/// Name of each coordinate.
pub static COORD_NAMES: [&str; 7usize] = [
    "bob.x",
    "bob.y",
    "bob.z",
    "bob.e0",
    "bob.e1",
    "bob.e2",
    "bob.e3",
];
/// Name of each constraint row.
pub static ROW_NAMES: [&str; 4usize] = ["pivot.x", "pivot.y", "pivot.z", "bob.norm"];
/// Initial coordinates: the file's pose, assembled.
pub static Q0: [f64; 7usize] = [
    0.7071067811865475f64,
    -0.7071067811865476f64,
    0f64,
    0.9238795325112867f64,
    0f64,
    0f64,
    0.3826834323650897f64,
];
/// Initial velocities from the file (to be projected onto the constraints).
pub static QD0: [f64; 7usize] = [
    0f64,
    0f64,
    -2.582618960593183f64,
    -0f64,
    0.6988516548183277f64,
    1.6871771431492877f64,
    0f64,
];
/// Constraint rows dependent on others at the initial pose (dropped by the solvers).
pub static REDUNDANT_ROWS: [u32; 0usize] = [];
/// Simulation end time suggested by the mechanism file (s).
pub const T_END: f64 = 60f64;
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
pub const N_K: usize = 8;
/// `setup` at the file's parameter values: what the types without parameters read.
pub static K: [f64; 8] = [
    0.00000000000000011102230246251565f64,
    0.9999999999999999f64,
    0.01f64,
    0.05f64,
    9.81f64,
    -9.81f64,
    0.14666666666666667f64,
    1f64,
];
/// The values the per-step functions read (`k`), from the run-time parameters `p`.
pub fn setup(p: &[f64], k: &mut [f64]) {
    let p: &[f64; 10] = p.try_into().expect("p must have 10 entries");
    let k: &mut [f64; 8] = k.try_into().expect("k must have 8 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 10], k: &mut [f64; 8]) {
    let x234 = p[3] * 9.81;
    let x235 = -x234;
    let x342 = p[0] + p[1];
    let x343 = p[1] + x342;
    let x346 = x343 * 4.0;
    let x348 = x346 * 0.3333333333333333;
    let x349 = 2.0 * p[3];
    let x350 = 0.5 * x349;
    k[0] = p[8];
    k[1] = p[9];
    k[2] = p[0];
    k[3] = p[1];
    k[4] = x234;
    k[5] = x235;
    k[6] = x348;
    k[7] = x350;
}
/// The parameters the generated code takes at run time by name: the file's
/// `[parameters]` entries that reach only masses, inertias and springs' constants.
pub static PARAMETERS: [&str; 0] = [];
/// Their values in the file.
pub static PARAMETER_VALUES: [f64; 0] = [];
/// Number of values `p` holds: the parameters by name, then the model's numbers that
/// the other parameters reach (read off the file loaded at their values: `DATA`).
pub const N_P: usize = 10;
/// `p` at the file's values.
pub static P0: [f64; 10] = [
    0.01f64,
    0.05f64,
    1f64,
    1f64,
    1f64,
    0.05f64,
    0.01f64,
    0.05f64,
    0.00000000000000011102230246251565f64,
    0.9999999999999999f64,
];
/// Where the numbers after the named parameters come from in the model (positions in
/// the generator's `slots::numbers`).
pub static DATA: [u32; 10] = [
    3u32, 4u32, 5u32, 6u32, 7u32, 8u32, 9u32, 10u32, 20u32, 21u32,
];
static OTHER_PARAMETERS: [&str; 6] = ["i_a", "i_t", "l", "m", "omega", "phi"];
static BODY_NAMES: [&str; 1] = ["bob"];
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
    let p: &[f64; 10] = p.try_into().expect("p must have 10 entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    mass_properties_part_0(p, out);
}
#[inline(never)]
fn mass_properties_part_0(p: &[f64; 10], out: &mut [f64; 4]) {
    out[0] = p[3];
    out[1] = p[1];
    out[2] = p[0];
    out[3] = p[1];
}
/// Each force's stiffness and damping at the run-time parameters `p`.
pub fn force_constants(p: &[f64], out: &mut [f64]) {
    let p: &[f64; 10] = p.try_into().expect("p must have 10 entries");
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
        name: "spherical_pendulum",
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
    pub static KKT: [KktKernels; 1] = [
        KktKernels {
            pattern: 0xcbae71240afc4a04,
            storage: 42,
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
        let phi_q: &[f64; 19] = phi_q
            .try_into()
            .map_err(|_| length_error(19, phi_q.len()))?;
        let st_len = st.len();
        let st: &mut [f64; 42] = st.try_into().map_err(|_| length_error(42, st_len))?;
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
        if !((c * mass[3]) > 0.0 && (c * mass[3]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[3]), 3));
        }
        let v6: f64 = (c * mass[3]).sqrt();
        let v7: f64 = 1.0 / v6;
        st[9] = v7;
        let v8: f64 = (c * mass[7]) * v7;
        st[0] = v8;
        let v9: f64 = (c * mass[11]) * v7;
        st[1] = v9;
        let v10: f64 = (c * mass[15]) * v7;
        st[3] = v10;
        let v11: f64 = (c * mass[8]) - v8 * v8;
        if !(v11 > 0.0 && v11 <= f64::MAX) {
            return Err(mass_pivot_error(v11, 4));
        }
        let v12: f64 = v11.sqrt();
        let v13: f64 = 1.0 / v12;
        st[10] = v13;
        let v14: f64 = (c * mass[12]) - v9 * v8;
        let v15: f64 = v14 * v13;
        st[2] = v15;
        let v16: f64 = (c * mass[16]) - v10 * v8;
        let v17: f64 = v16 * v13;
        st[4] = v17;
        let v18: f64 = (c * mass[13]) - v9 * v9;
        let v19: f64 = v18 - v15 * v15;
        if !(v19 > 0.0 && v19 <= f64::MAX) {
            return Err(mass_pivot_error(v19, 5));
        }
        let v20: f64 = v19.sqrt();
        let v21: f64 = 1.0 / v20;
        st[11] = v21;
        let v22: f64 = (c * mass[17]) - v10 * v9;
        let v23: f64 = v22 - v17 * v15;
        let v24: f64 = v23 * v21;
        st[5] = v24;
        let v25: f64 = (c * mass[18]) - v10 * v10;
        let v26: f64 = v25 - v17 * v17;
        let v27: f64 = v26 - v24 * v24;
        if !(v27 > 0.0 && v27 <= f64::MAX) {
            return Err(mass_pivot_error(v27, 6));
        }
        let v28: f64 = v27.sqrt();
        let v29: f64 = 1.0 / v28;
        st[12] = v29;
        let v30: f64 = phi_q[0] * v1;
        st[13] = v30;
        let v31: f64 = phi_q[1] * v7;
        st[14] = v31;
        let v32: f64 = phi_q[2] - v8 * v31;
        let v33: f64 = v32 * v13;
        st[15] = v33;
        let v34: f64 = phi_q[3] - v9 * v31;
        let v35: f64 = v34 - v15 * v33;
        let v36: f64 = v35 * v21;
        st[16] = v36;
        let v37: f64 = phi_q[4] - v10 * v31;
        let v38: f64 = v37 - v17 * v33;
        let v39: f64 = v38 - v24 * v36;
        let v40: f64 = v39 * v29;
        st[17] = v40;
        let v41: f64 = phi_q[5] * v3;
        st[18] = v41;
        let v42: f64 = phi_q[6] * v7;
        st[19] = v42;
        let v43: f64 = phi_q[7] - v8 * v42;
        let v44: f64 = v43 * v13;
        st[20] = v44;
        let v45: f64 = phi_q[8] - v9 * v42;
        let v46: f64 = v45 - v15 * v44;
        let v47: f64 = v46 * v21;
        st[21] = v47;
        let v48: f64 = phi_q[9] - v10 * v42;
        let v49: f64 = v48 - v17 * v44;
        let v50: f64 = v49 - v24 * v47;
        let v51: f64 = v50 * v29;
        st[22] = v51;
        let v52: f64 = phi_q[10] * v5;
        st[23] = v52;
        let v53: f64 = phi_q[11] * v7;
        st[24] = v53;
        let v54: f64 = phi_q[12] - v8 * v53;
        let v55: f64 = v54 * v13;
        st[25] = v55;
        let v56: f64 = phi_q[13] - v9 * v53;
        let v57: f64 = v56 - v15 * v55;
        let v58: f64 = v57 * v21;
        st[26] = v58;
        let v59: f64 = phi_q[14] - v10 * v53;
        let v60: f64 = v59 - v17 * v55;
        let v61: f64 = v60 - v24 * v58;
        let v62: f64 = v61 * v29;
        st[27] = v62;
        let v63: f64 = phi_q[15] * v7;
        st[28] = v63;
        let v64: f64 = phi_q[16] - v8 * v63;
        let v65: f64 = v64 * v13;
        st[29] = v65;
        let v66: f64 = phi_q[17] - v9 * v63;
        let v67: f64 = v66 - v15 * v65;
        let v68: f64 = v67 * v21;
        st[30] = v68;
        let v69: f64 = phi_q[18] - v10 * v63;
        let v70: f64 = v69 - v17 * v65;
        let v71: f64 = v70 - v24 * v68;
        let v72: f64 = v71 * v29;
        st[31] = v72;
        let v73: f64 = v30 * v30;
        let v74: f64 = v31 * v31;
        let v75: f64 = v73 + v74;
        let v76: f64 = v33 * v33;
        let v77: f64 = v75 + v76;
        let v78: f64 = v36 * v36;
        let v79: f64 = v77 + v78;
        let v80: f64 = v40 * v40;
        let v81: f64 = v79 + v80;
        let v82: f64 = v42 * v31;
        let v83: f64 = v44 * v33;
        let v84: f64 = v82 + v83;
        let v85: f64 = v47 * v36;
        let v86: f64 = v84 + v85;
        let v87: f64 = v51 * v40;
        let v88: f64 = v86 + v87;
        let v89: f64 = v41 * v41;
        let v90: f64 = v42 * v42;
        let v91: f64 = v89 + v90;
        let v92: f64 = v44 * v44;
        let v93: f64 = v91 + v92;
        let v94: f64 = v47 * v47;
        let v95: f64 = v93 + v94;
        let v96: f64 = v51 * v51;
        let v97: f64 = v95 + v96;
        let v98: f64 = v53 * v31;
        let v99: f64 = v55 * v33;
        let v100: f64 = v98 + v99;
        let v101: f64 = v58 * v36;
        let v102: f64 = v100 + v101;
        let v103: f64 = v62 * v40;
        let v104: f64 = v102 + v103;
        let v105: f64 = v53 * v42;
        let v106: f64 = v55 * v44;
        let v107: f64 = v105 + v106;
        let v108: f64 = v58 * v47;
        let v109: f64 = v107 + v108;
        let v110: f64 = v62 * v51;
        let v111: f64 = v109 + v110;
        let v112: f64 = v52 * v52;
        let v113: f64 = v53 * v53;
        let v114: f64 = v112 + v113;
        let v115: f64 = v55 * v55;
        let v116: f64 = v114 + v115;
        let v117: f64 = v58 * v58;
        let v118: f64 = v116 + v117;
        let v119: f64 = v62 * v62;
        let v120: f64 = v118 + v119;
        let v121: f64 = v63 * v31;
        let v122: f64 = v65 * v33;
        let v123: f64 = v121 + v122;
        let v124: f64 = v68 * v36;
        let v125: f64 = v123 + v124;
        let v126: f64 = v72 * v40;
        let v127: f64 = v125 + v126;
        let v128: f64 = v63 * v42;
        let v129: f64 = v65 * v44;
        let v130: f64 = v128 + v129;
        let v131: f64 = v68 * v47;
        let v132: f64 = v130 + v131;
        let v133: f64 = v72 * v51;
        let v134: f64 = v132 + v133;
        let v135: f64 = v63 * v53;
        let v136: f64 = v65 * v55;
        let v137: f64 = v135 + v136;
        let v138: f64 = v68 * v58;
        let v139: f64 = v137 + v138;
        let v140: f64 = v72 * v62;
        let v141: f64 = v139 + v140;
        let v142: f64 = v63 * v63;
        let v143: f64 = v65 * v65;
        let v144: f64 = v142 + v143;
        let v145: f64 = v68 * v68;
        let v146: f64 = v144 + v145;
        let v147: f64 = v72 * v72;
        let v148: f64 = v146 + v147;
        let (v149, v150) = piv.pivot(v148, v148, 3, false)?;
        st[38] = v149;
        let v151: f64 = v127 * v149;
        st[32] = v151;
        let v152: f64 = v81 - v151 * v150 * v151;
        let v153: f64 = v134 * v149;
        st[33] = v153;
        let v154: f64 = v97 - v153 * v150 * v153;
        let v155: f64 = v141 * v149;
        st[34] = v155;
        let v156: f64 = v120 - v155 * v150 * v155;
        let v157: f64 = v88 - v153 * v150 * v151;
        let v158: f64 = v104 - v155 * v150 * v151;
        let v159: f64 = v111 - v155 * v150 * v153;
        let (v160, v161) = piv.pivot(v152, v152, 0, false)?;
        st[39] = v160;
        let v162: f64 = v157 * v160;
        st[35] = v162;
        let v163: f64 = v154 - v162 * v161 * v162;
        let v164: f64 = v158 * v160;
        st[36] = v164;
        let v165: f64 = v156 - v164 * v161 * v164;
        let v166: f64 = v159 - v164 * v161 * v162;
        let (v167, v168) = piv.pivot(v163, v154, 1, false)?;
        st[40] = v167;
        let v169: f64 = v166 * v167;
        st[37] = v169;
        let v170: f64 = v165 - v169 * v168 * v169;
        let (v171, v172) = piv.pivot(v170, v156, 2, false)?;
        st[41] = v171;
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
        let g: &[f64; 4] = g.try_into().map_err(|_| length_error(4, g.len()))?;
        let x_len = x.len();
        let x: &mut [f64; 7] = x.try_into().map_err(|_| length_error(7, x_len))?;
        let y_len = y.len();
        let y: &mut [f64; 4] = y.try_into().map_err(|_| length_error(4, y_len))?;
        let st: &[f64; 42] = st.try_into().map_err(|_| length_error(42, st.len()))?;
        x.fill(0.0);
        y[0] = -g[0];
        y[1] = -g[1];
        y[2] = -g[2];
        y[3] = -g[3];
        if f.iter().any(|&v| v != 0.0) {
            let v0: f64 = f[0];
            let v1: f64 = f[1];
            let v2: f64 = f[2];
            let v3: f64 = f[3];
            let v4: f64 = f[4];
            let v5: f64 = f[5];
            let v6: f64 = f[6];
            let v7: f64 = v0 * st[6];
            let v8: f64 = v1 * st[7];
            let v9: f64 = v2 * st[8];
            let v10: f64 = v3 * st[9];
            let v11: f64 = v4 - st[0] * v10;
            let v12: f64 = v11 * st[10];
            let v13: f64 = v5 - st[1] * v10;
            let v14: f64 = v13 - st[2] * v12;
            let v15: f64 = v14 * st[11];
            let v16: f64 = v6 - st[3] * v10;
            let v17: f64 = v16 - st[4] * v12;
            let v18: f64 = v17 - st[5] * v15;
            let v19: f64 = v18 * st[12];
            let v20: f64 = st[13] * v7;
            let v21: f64 = st[14] * v10;
            let v22: f64 = v20 + v21;
            let v23: f64 = st[15] * v12;
            let v24: f64 = v22 + v23;
            let v25: f64 = st[16] * v15;
            let v26: f64 = v24 + v25;
            let v27: f64 = st[17] * v19;
            let v28: f64 = v26 + v27;
            y[0] += v28;
            let v29: f64 = st[18] * v8;
            let v30: f64 = st[19] * v10;
            let v31: f64 = v29 + v30;
            let v32: f64 = st[20] * v12;
            let v33: f64 = v31 + v32;
            let v34: f64 = st[21] * v15;
            let v35: f64 = v33 + v34;
            let v36: f64 = st[22] * v19;
            let v37: f64 = v35 + v36;
            y[1] += v37;
            let v38: f64 = st[23] * v9;
            let v39: f64 = st[24] * v10;
            let v40: f64 = v38 + v39;
            let v41: f64 = st[25] * v12;
            let v42: f64 = v40 + v41;
            let v43: f64 = st[26] * v15;
            let v44: f64 = v42 + v43;
            let v45: f64 = st[27] * v19;
            let v46: f64 = v44 + v45;
            y[2] += v46;
            let v47: f64 = st[28] * v10;
            let v48: f64 = st[29] * v12;
            let v49: f64 = v47 + v48;
            let v50: f64 = st[30] * v15;
            let v51: f64 = v49 + v50;
            let v52: f64 = st[31] * v19;
            let v53: f64 = v51 + v52;
            y[3] += v53;
            x[0] = v7;
            x[1] = v8;
            x[2] = v9;
            x[3] = v10;
            x[4] = v12;
            x[5] = v15;
            x[6] = v19;
        }
        let v54: f64 = y[0] - st[32] * y[3];
        let v55: f64 = y[1] - st[33] * y[3];
        let v56: f64 = y[2] - st[34] * y[3];
        let v57: f64 = v55 - st[35] * v54;
        let v58: f64 = v56 - st[36] * v54;
        let v59: f64 = v58 - st[37] * v57;
        let v60: f64 = y[3] * st[38];
        let v61: f64 = v54 * st[39];
        let v62: f64 = v57 * st[40];
        let v63: f64 = v59 * st[41];
        let v64: f64 = v62 - st[37] * v63;
        let v65: f64 = v61 - st[35] * v64;
        let v66: f64 = v65 - st[36] * v63;
        let v67: f64 = v60 - st[32] * v66;
        let v68: f64 = v67 - st[33] * v64;
        let v69: f64 = v68 - st[34] * v63;
        y[3] = v69;
        y[0] = v66;
        y[1] = v64;
        y[2] = v63;
        let v70: f64 = x[0] - st[13] * v66;
        let v71: f64 = x[3] - st[14] * v66;
        let v72: f64 = x[4] - st[15] * v66;
        let v73: f64 = x[5] - st[16] * v66;
        let v74: f64 = x[6] - st[17] * v66;
        let v75: f64 = x[1] - st[18] * v64;
        let v76: f64 = v71 - st[19] * v64;
        let v77: f64 = v72 - st[20] * v64;
        let v78: f64 = v73 - st[21] * v64;
        let v79: f64 = v74 - st[22] * v64;
        let v80: f64 = x[2] - st[23] * v63;
        let v81: f64 = v76 - st[24] * v63;
        let v82: f64 = v77 - st[25] * v63;
        let v83: f64 = v78 - st[26] * v63;
        let v84: f64 = v79 - st[27] * v63;
        let v85: f64 = v81 - st[28] * v69;
        let v86: f64 = v82 - st[29] * v69;
        let v87: f64 = v83 - st[30] * v69;
        let v88: f64 = v84 - st[31] * v69;
        let v89: f64 = v88 * st[12];
        let v90: f64 = v87 - st[5] * v89;
        let v91: f64 = v90 * st[11];
        let v92: f64 = v86 - st[2] * v91;
        let v93: f64 = v92 - st[4] * v89;
        let v94: f64 = v93 * st[10];
        let v95: f64 = v85 - st[0] * v94;
        let v96: f64 = v95 - st[1] * v91;
        let v97: f64 = v96 - st[3] * v89;
        let v98: f64 = v97 * st[9];
        let v99: f64 = v80 * st[8];
        let v100: f64 = v75 * st[7];
        let v101: f64 = v70 * st[6];
        x[0] = v101;
        x[1] = v100;
        x[2] = v99;
        x[3] = v98;
        x[4] = v94;
        x[5] = v91;
        x[6] = v89;
        Ok(())
    }
    fn kkt_transpose_times(
        phi_q: &[f64],
        y: &[f64],
        out: &mut [f64],
    ) -> Result<(), KktError> {
        let phi_q: &[f64; 19] = phi_q
            .try_into()
            .map_err(|_| length_error(19, phi_q.len()))?;
        let y: &[f64; 4] = y.try_into().map_err(|_| length_error(4, y.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 7] = out.try_into().map_err(|_| length_error(7, out_len))?;
        out[0] = phi_q[0] * y[0];
        out[1] = phi_q[5] * y[1];
        out[2] = phi_q[10] * y[2];
        out[3] = phi_q[1] * y[0] + phi_q[6] * y[1] + phi_q[11] * y[2] + phi_q[15] * y[3];
        out[4] = phi_q[2] * y[0] + phi_q[7] * y[1] + phi_q[12] * y[2] + phi_q[16] * y[3];
        out[5] = phi_q[3] * y[0] + phi_q[8] * y[1] + phi_q[13] * y[2] + phi_q[17] * y[3];
        out[6] = phi_q[4] * y[0] + phi_q[9] * y[1] + phi_q[14] * y[2] + phi_q[18] * y[3];
        Ok(())
    }
    #[allow(clippy::assign_op_pattern)]
    fn kkt_times_add(phi_q: &[f64], x: &[f64], out: &mut [f64]) -> Result<(), KktError> {
        let phi_q: &[f64; 19] = phi_q
            .try_into()
            .map_err(|_| length_error(19, phi_q.len()))?;
        let x: &[f64; 7] = x.try_into().map_err(|_| length_error(7, x.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 4] = out.try_into().map_err(|_| length_error(4, out_len))?;
        out[0] = out[0] + phi_q[0] * x[0] + phi_q[1] * x[3] + phi_q[2] * x[4]
            + phi_q[3] * x[5] + phi_q[4] * x[6];
        out[1] = out[1] + phi_q[5] * x[1] + phi_q[6] * x[3] + phi_q[7] * x[4]
            + phi_q[8] * x[5] + phi_q[9] * x[6];
        out[2] = out[2] + phi_q[10] * x[2] + phi_q[11] * x[3] + phi_q[12] * x[4]
            + phi_q[13] * x[5] + phi_q[14] * x[6];
        out[3] = out[3] + phi_q[15] * x[3] + phi_q[16] * x[4] + phi_q[17] * x[5]
            + phi_q[18] * x[6];
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
        let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
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
        let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
        mass_part_0(k, q, out);
    }
    #[inline(never)]
    fn mass_part_0(k: &[f64; 8], q: &[f64; 7], out: &mut [f64; 19]) {
        let x9 = q[3] * q[3];
        let x10 = q[4] * q[4];
        let x11 = q[5] * q[5];
        let x12 = q[6] * q[6];
        let x23 = q[4] * q[5];
        let x25 = q[3] * q[6];
        let x30 = q[4] * q[6];
        let x32 = q[3] * q[5];
        let x36 = q[5] * q[6];
        let x38 = q[3] * q[4];
        let x68 = q[3] * 2.0;
        let x69 = q[4] * 2.0;
        let x70 = q[5] * 2.0;
        let x71 = q[6] * 2.0;
        let x72 = 2.0 * x68;
        let x89 = 2.0 * x69;
        let x97 = 2.0 * x70;
        let x353 = 2.0 * x71;
        let x355 = x69 * x89;
        let x359 = x70 * x97;
        let x363 = x71 * x353;
        let x375 = x69 * x72;
        let x377 = x70 * x353;
        let x381 = x71 * x97;
        let x389 = x69 * x353;
        let x391 = x70 * x72;
        let x393 = x71 * x89;
        let x403 = x69 * x97;
        let x407 = x70 * x89;
        let x409 = x71 * x72;
        let x417 = x68 * x89;
        let x430 = x68 * x72;
        let x440 = x68 * x353;
        let x452 = x68 * x97;
        let x1499 = x355 * k[3];
        let x1500 = x359 * k[2];
        let x1501 = x363 * k[3];
        let x1502 = x1499 + x1500;
        let x1503 = x1501 + x1502;
        let x1504 = 0.5 * x1503;
        let x1505 = x9 * k[6];
        let x1506 = x1504 + x1505;
        let x1507 = x375 * k[3];
        let x1508 = x377 * k[2];
        let x1510 = x381 * k[3];
        let x1511 = x1507 - x1508;
        let x1512 = x1510 + x1511;
        let x1513 = 0.5 * x1512;
        let x1515 = x38 * k[6];
        let x1516 = x1515 - x1513;
        let x1517 = x389 * k[3];
        let x1518 = x391 * k[2];
        let x1519 = x393 * k[3];
        let x1521 = x1517 + x1518;
        let x1522 = x1521 - x1519;
        let x1523 = 0.5 * x1522;
        let x1525 = x32 * k[6];
        let x1526 = x1525 - x1523;
        let x1527 = x403 * k[3];
        let x1529 = x407 * k[2];
        let x1530 = x409 * k[3];
        let x1531 = x1529 - x1527;
        let x1532 = x1530 + x1531;
        let x1533 = 0.5 * x1532;
        let x1535 = x25 * k[6];
        let x1536 = x1535 - x1533;
        let x1537 = x417 * k[3];
        let x1539 = x381 * k[2];
        let x1540 = x377 * k[3];
        let x1542 = x1539 - x1537;
        let x1543 = x1542 - x1540;
        let x1544 = 0.5 * x1543;
        let x1545 = x1515 + x1544;
        let x1546 = x430 * k[3];
        let x1547 = x363 * k[2];
        let x1548 = x359 * k[3];
        let x1549 = x1546 + x1547;
        let x1550 = x1548 + x1549;
        let x1551 = 0.5 * x1550;
        let x1552 = x10 * k[6];
        let x1553 = x1551 + x1552;
        let x1554 = x440 * k[3];
        let x1555 = x409 * k[2];
        let x1557 = x407 * k[3];
        let x1559 = x1554 - x1555;
        let x1560 = x1559 - x1557;
        let x1561 = 0.5 * x1560;
        let x1562 = x23 * k[6];
        let x1563 = x1561 + x1562;
        let x1564 = x452 * k[3];
        let x1565 = x393 * k[2];
        let x1566 = x391 * k[3];
        let x1567 = x1564 + x1565;
        let x1569 = x1566 - x1567;
        let x1570 = 0.5 * x1569;
        let x1571 = x30 * k[6];
        let x1572 = x1570 + x1571;
        let x1573 = x452 * k[2];
        let x1574 = x1519 + x1573;
        let x1576 = x1517 - x1574;
        let x1577 = 0.5 * x1576;
        let x1578 = x1525 + x1577;
        let x1579 = x440 * k[2];
        let x1581 = x1530 - x1579;
        let x1582 = x1581 - x1527;
        let x1583 = 0.5 * x1582;
        let x1584 = x1562 + x1583;
        let x1585 = x430 * k[2];
        let x1586 = x1501 + x1585;
        let x1587 = x1499 + x1586;
        let x1588 = 0.5 * x1587;
        let x1589 = x11 * k[6];
        let x1590 = x1588 + x1589;
        let x1592 = x417 * k[2];
        let x1594 = x1592 - x1510;
        let x1595 = x1594 - x1507;
        let x1596 = 0.5 * x1595;
        let x1597 = x36 * k[6];
        let x1598 = x1596 + x1597;
        let x1599 = x403 * k[2];
        let x1602 = x1557 - x1599;
        let x1603 = x1602 - x1554;
        let x1604 = 0.5 * x1603;
        let x1605 = x1535 + x1604;
        let x1606 = x389 * k[2];
        let x1607 = x1566 + x1606;
        let x1609 = x1564 - x1607;
        let x1610 = 0.5 * x1609;
        let x1611 = x1571 + x1610;
        let x1612 = x375 * k[2];
        let x1613 = x1612 - x1540;
        let x1614 = x1613 - x1537;
        let x1615 = 0.5 * x1614;
        let x1616 = x1597 + x1615;
        let x1617 = x355 * k[2];
        let x1618 = x1548 + x1617;
        let x1619 = x1546 + x1618;
        let x1620 = 0.5 * x1619;
        let x1621 = x12 * k[6];
        let x1622 = x1620 + x1621;
        out[0] = k[7];
        out[1] = k[7];
        out[2] = k[7];
        out[3] = x1506;
        out[4] = x1516;
        out[5] = x1526;
        out[6] = x1536;
        out[7] = x1545;
        out[8] = x1553;
        out[9] = x1563;
        out[10] = x1572;
        out[11] = x1578;
        out[12] = x1584;
        out[13] = x1590;
        out[14] = x1598;
        out[15] = x1605;
        out[16] = x1611;
        out[17] = x1616;
        out[18] = x1622;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
        let _ = t;
        force_part_0(k, q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(k: &[f64; 8], q: &[f64; 7], qd: &[f64; 7], out: &mut [f64; 7]) {
        let x68 = q[3] * 2.0;
        let x69 = q[4] * 2.0;
        let x70 = q[5] * 2.0;
        let x71 = q[6] * 2.0;
        let x126 = q[5] * qd[4];
        let x127 = q[4] * qd[5];
        let x130 = q[6] * qd[3];
        let x131 = q[3] * qd[6];
        let x136 = q[6] * qd[4];
        let x137 = q[4] * qd[6];
        let x140 = q[5] * qd[3];
        let x141 = q[3] * qd[5];
        let x145 = q[6] * qd[5];
        let x146 = q[5] * qd[6];
        let x149 = q[4] * qd[3];
        let x150 = q[3] * qd[4];
        let x173 = 2.0 * qd[3];
        let x174 = 2.0 * qd[4];
        let x175 = 2.0 * qd[5];
        let x176 = 2.0 * qd[6];
        let x185 = qd[4] * qd[5];
        let x188 = qd[3] * qd[6];
        let x193 = qd[4] * qd[6];
        let x196 = qd[3] * qd[5];
        let x240 = x150 - x149;
        let x241 = x145 + x240;
        let x242 = x241 - x146;
        let x243 = 2.0 * x242;
        let x246 = x136 + x140;
        let x248 = x141 - x246;
        let x249 = x137 + x248;
        let x250 = 2.0 * x249;
        let x253 = x126 - x130;
        let x254 = x253 - x127;
        let x255 = x131 + x254;
        let x256 = 2.0 * x255;
        let x277 = 2.0 * x243;
        let x279 = 2.0 * x250;
        let x281 = 2.0 * x256;
        let x524 = x193 + x196;
        let x526 = x196 - x524;
        let x527 = x193 + x526;
        let x528 = 2.0 * x527;
        let x531 = x185 - x188;
        let x532 = x531 - x185;
        let x533 = x188 + x532;
        let x534 = 2.0 * x533;
        let x535 = 2.0 * x528;
        let x536 = 2.0 * x534;
        let x537 = x174 * x277;
        let x539 = x175 * x279;
        let x540 = x70 * x535;
        let x541 = x539 + x540;
        let x543 = x176 * x281;
        let x544 = x71 * x536;
        let x545 = x543 + x544;
        let x551 = x173 * x277;
        let x553 = x176 * x279;
        let x554 = x71 * x535;
        let x555 = x553 + x554;
        let x558 = x175 * x281;
        let x559 = x70 * x536;
        let x560 = x558 + x559;
        let x565 = x176 * x277;
        let x567 = x173 * x279;
        let x568 = x68 * x535;
        let x569 = x567 + x568;
        let x571 = x174 * x281;
        let x572 = x69 * x536;
        let x573 = x571 + x572;
        let x579 = x175 * x277;
        let x582 = x174 * x279;
        let x583 = x69 * x535;
        let x584 = x582 + x583;
        let x586 = x173 * x281;
        let x587 = x68 * x536;
        let x588 = x586 + x587;
        let x593 = qd[3] * qd[3];
        let x594 = qd[4] * qd[4];
        let x595 = qd[5] * qd[5];
        let x596 = qd[6] * qd[6];
        let x597 = x593 + x594;
        let x598 = x595 + x597;
        let x599 = x596 + x598;
        let x1623 = x537 * k[3];
        let x1624 = x541 * k[2];
        let x1625 = x545 * k[3];
        let x1626 = x1623 + x1624;
        let x1627 = x1625 + x1626;
        let x1628 = 0.5 * x1627;
        let x1629 = x551 * k[3];
        let x1630 = x555 * k[2];
        let x1632 = x560 * k[3];
        let x1633 = x1629 - x1630;
        let x1634 = x1632 + x1633;
        let x1635 = 0.5 * x1634;
        let x1636 = x565 * k[3];
        let x1637 = x569 * k[2];
        let x1638 = x573 * k[3];
        let x1640 = x1636 + x1637;
        let x1641 = x1640 - x1638;
        let x1642 = 0.5 * x1641;
        let x1643 = x579 * k[3];
        let x1645 = x584 * k[2];
        let x1646 = x588 * k[3];
        let x1647 = x1645 - x1643;
        let x1648 = x1646 + x1647;
        let x1649 = 0.5 * x1648;
        let x1650 = x539 * k[2];
        let x1651 = x543 * k[3];
        let x1652 = x1623 + x1650;
        let x1653 = x1651 + x1652;
        let x1654 = 0.5 * x1653;
        let x1655 = x1628 + x1654;
        let x1656 = q[3] * k[6];
        let x1657 = x599 * x1656;
        let x1659 = x1655 - x1657;
        let x1661 = x553 * k[2];
        let x1662 = x558 * k[3];
        let x1664 = x1661 - x1629;
        let x1665 = x1664 - x1662;
        let x1666 = 0.5 * x1665;
        let x1668 = x1666 - x1635;
        let x1669 = q[4] * k[6];
        let x1670 = x599 * x1669;
        let x1672 = x1668 - x1670;
        let x1673 = x567 * k[2];
        let x1674 = x571 * k[3];
        let x1675 = x1636 + x1673;
        let x1677 = x1674 - x1675;
        let x1678 = 0.5 * x1677;
        let x1680 = x1678 - x1642;
        let x1681 = q[5] * k[6];
        let x1682 = x599 * x1681;
        let x1684 = x1680 - x1682;
        let x1685 = x582 * k[2];
        let x1687 = x586 * k[3];
        let x1689 = x1643 - x1685;
        let x1690 = x1689 - x1687;
        let x1691 = 0.5 * x1690;
        let x1693 = x1691 - x1649;
        let x1694 = q[6] * k[6];
        let x1695 = x599 * x1694;
        let x1697 = x1693 - x1695;
        out[0] = 0.0;
        out[1] = k[5];
        out[2] = 0.0;
        out[3] = x1659;
        out[4] = x1672;
        out[5] = x1684;
        out[6] = x1697;
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
        let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 4] = phi.try_into().expect("phi must have 4 entries");
        let phi_q: &mut [f64; 19] = phi_q
            .try_into()
            .expect("phi_q must have 19 entries");
        let mass: &mut [f64; 19] = mass.try_into().expect("mass must have 19 entries");
        let force: &mut [f64; 7] = force.try_into().expect("force must have 7 entries");
        let _ = t;
        eval_newton_part_0(k, q, qd, phi, phi_q, mass, force);
    }
    #[inline(never)]
    fn eval_newton_part_0(
        k: &[f64; 8],
        q: &[f64; 7],
        qd: &[f64; 7],
        phi: &mut [f64; 4],
        phi_q: &mut [f64; 19],
        mass: &mut [f64; 19],
        force: &mut [f64; 7],
    ) {
        let x9 = q[3] * q[3];
        let x10 = q[4] * q[4];
        let x11 = q[5] * q[5];
        let x12 = q[6] * q[6];
        let x13 = x9 + x10;
        let x14 = 2.0 * x13;
        let x16 = x14 - 1.0;
        let x17 = x9 + x11;
        let x18 = 2.0 * x17;
        let x19 = x18 - 1.0;
        let x23 = q[4] * q[5];
        let x24 = 2.0 * x23;
        let x25 = q[3] * q[6];
        let x27 = 2.0 * x25;
        let x29 = x24 - x27;
        let x30 = q[4] * q[6];
        let x31 = 2.0 * x30;
        let x32 = q[3] * q[5];
        let x33 = 2.0 * x32;
        let x35 = x24 + x27;
        let x36 = q[5] * q[6];
        let x37 = 2.0 * x36;
        let x38 = q[3] * q[4];
        let x40 = 2.0 * x38;
        let x45 = x31 - x33;
        let x46 = x37 + x40;
        let x65 = x11 + x13;
        let x66 = x12 + x65;
        let x67 = x66 - 1.0;
        let x68 = q[3] * 2.0;
        let x69 = q[4] * 2.0;
        let x70 = q[5] * 2.0;
        let x71 = q[6] * 2.0;
        let x72 = 2.0 * x68;
        let x89 = 2.0 * x69;
        let x97 = 2.0 * x70;
        let x126 = q[5] * qd[4];
        let x127 = q[4] * qd[5];
        let x130 = q[6] * qd[3];
        let x131 = q[3] * qd[6];
        let x136 = q[6] * qd[4];
        let x137 = q[4] * qd[6];
        let x140 = q[5] * qd[3];
        let x141 = q[3] * qd[5];
        let x145 = q[6] * qd[5];
        let x146 = q[5] * qd[6];
        let x149 = q[4] * qd[3];
        let x150 = q[3] * qd[4];
        let x173 = 2.0 * qd[3];
        let x174 = 2.0 * qd[4];
        let x175 = 2.0 * qd[5];
        let x176 = 2.0 * qd[6];
        let x185 = qd[4] * qd[5];
        let x188 = qd[3] * qd[6];
        let x193 = qd[4] * qd[6];
        let x196 = qd[3] * qd[5];
        let x240 = x150 - x149;
        let x241 = x145 + x240;
        let x242 = x241 - x146;
        let x243 = 2.0 * x242;
        let x246 = x136 + x140;
        let x248 = x141 - x246;
        let x249 = x137 + x248;
        let x250 = 2.0 * x249;
        let x253 = x126 - x130;
        let x254 = x253 - x127;
        let x255 = x131 + x254;
        let x256 = 2.0 * x255;
        let x277 = 2.0 * x243;
        let x279 = 2.0 * x250;
        let x281 = 2.0 * x256;
        let x353 = 2.0 * x71;
        let x355 = x69 * x89;
        let x359 = x70 * x97;
        let x363 = x71 * x353;
        let x375 = x69 * x72;
        let x377 = x70 * x353;
        let x381 = x71 * x97;
        let x389 = x69 * x353;
        let x391 = x70 * x72;
        let x393 = x71 * x89;
        let x403 = x69 * x97;
        let x407 = x70 * x89;
        let x409 = x71 * x72;
        let x417 = x68 * x89;
        let x430 = x68 * x72;
        let x440 = x68 * x353;
        let x452 = x68 * x97;
        let x524 = x193 + x196;
        let x526 = x196 - x524;
        let x527 = x193 + x526;
        let x528 = 2.0 * x527;
        let x531 = x185 - x188;
        let x532 = x531 - x185;
        let x533 = x188 + x532;
        let x534 = 2.0 * x533;
        let x535 = 2.0 * x528;
        let x536 = 2.0 * x534;
        let x537 = x174 * x277;
        let x539 = x175 * x279;
        let x540 = x70 * x535;
        let x541 = x539 + x540;
        let x543 = x176 * x281;
        let x544 = x71 * x536;
        let x545 = x543 + x544;
        let x551 = x173 * x277;
        let x553 = x176 * x279;
        let x554 = x71 * x535;
        let x555 = x553 + x554;
        let x558 = x175 * x281;
        let x559 = x70 * x536;
        let x560 = x558 + x559;
        let x565 = x176 * x277;
        let x567 = x173 * x279;
        let x568 = x68 * x535;
        let x569 = x567 + x568;
        let x571 = x174 * x281;
        let x572 = x69 * x536;
        let x573 = x571 + x572;
        let x579 = x175 * x277;
        let x582 = x174 * x279;
        let x583 = x69 * x535;
        let x584 = x582 + x583;
        let x586 = x173 * x281;
        let x587 = x68 * x536;
        let x588 = x586 + x587;
        let x593 = qd[3] * qd[3];
        let x594 = qd[4] * qd[4];
        let x595 = qd[5] * qd[5];
        let x596 = qd[6] * qd[6];
        let x597 = x593 + x594;
        let x598 = x595 + x597;
        let x599 = x596 + x598;
        let x1436 = x16 * k[0];
        let x1437 = x29 * k[1];
        let x1438 = x1436 + x1437;
        let x1439 = x35 * k[0];
        let x1440 = x19 * k[1];
        let x1441 = x1439 + x1440;
        let x1442 = x45 * k[0];
        let x1443 = x46 * k[1];
        let x1444 = x1442 + x1443;
        let x1445 = q[0] + x1438;
        let x1446 = q[1] + x1441;
        let x1447 = q[2] + x1444;
        let x1448 = -x1445;
        let x1449 = -x1446;
        let x1450 = -x1447;
        let x1451 = x72 * k[0];
        let x1452 = x71 * k[1];
        let x1454 = x1451 - x1452;
        let x1455 = x71 * k[0];
        let x1456 = x72 * k[1];
        let x1457 = x1455 + x1456;
        let x1458 = x70 * k[0];
        let x1459 = -x1458;
        let x1460 = x69 * k[1];
        let x1461 = x1460 - x1458;
        let x1462 = -x1454;
        let x1463 = -x1457;
        let x1464 = -x1461;
        let x1465 = x89 * k[0];
        let x1466 = x70 * k[1];
        let x1467 = x1465 + x1466;
        let x1468 = x68 * k[1];
        let x1469 = x1455 + x1468;
        let x1470 = -x1467;
        let x1471 = -x1469;
        let x1472 = x69 * k[0];
        let x1473 = x97 * k[1];
        let x1474 = x1472 + x1473;
        let x1475 = x68 * k[0];
        let x1476 = -x1475;
        let x1477 = x1452 - x1475;
        let x1478 = -x1460;
        let x1479 = -x1474;
        let x1480 = -x1477;
        let x1481 = x1466 + x1472;
        let x1482 = -x1481;
        let x1499 = x355 * k[3];
        let x1500 = x359 * k[2];
        let x1501 = x363 * k[3];
        let x1502 = x1499 + x1500;
        let x1503 = x1501 + x1502;
        let x1504 = 0.5 * x1503;
        let x1505 = x9 * k[6];
        let x1506 = x1504 + x1505;
        let x1507 = x375 * k[3];
        let x1508 = x377 * k[2];
        let x1510 = x381 * k[3];
        let x1511 = x1507 - x1508;
        let x1512 = x1510 + x1511;
        let x1513 = 0.5 * x1512;
        let x1515 = x38 * k[6];
        let x1516 = x1515 - x1513;
        let x1517 = x389 * k[3];
        let x1518 = x391 * k[2];
        let x1519 = x393 * k[3];
        let x1521 = x1517 + x1518;
        let x1522 = x1521 - x1519;
        let x1523 = 0.5 * x1522;
        let x1525 = x32 * k[6];
        let x1526 = x1525 - x1523;
        let x1527 = x403 * k[3];
        let x1529 = x407 * k[2];
        let x1530 = x409 * k[3];
        let x1531 = x1529 - x1527;
        let x1532 = x1530 + x1531;
        let x1533 = 0.5 * x1532;
        let x1535 = x25 * k[6];
        let x1536 = x1535 - x1533;
        let x1537 = x417 * k[3];
        let x1539 = x381 * k[2];
        let x1540 = x377 * k[3];
        let x1542 = x1539 - x1537;
        let x1543 = x1542 - x1540;
        let x1544 = 0.5 * x1543;
        let x1545 = x1515 + x1544;
        let x1546 = x430 * k[3];
        let x1547 = x363 * k[2];
        let x1548 = x359 * k[3];
        let x1549 = x1546 + x1547;
        let x1550 = x1548 + x1549;
        let x1551 = 0.5 * x1550;
        let x1552 = x10 * k[6];
        let x1553 = x1551 + x1552;
        let x1554 = x440 * k[3];
        let x1555 = x409 * k[2];
        let x1557 = x407 * k[3];
        let x1559 = x1554 - x1555;
        let x1560 = x1559 - x1557;
        let x1561 = 0.5 * x1560;
        let x1562 = x23 * k[6];
        let x1563 = x1561 + x1562;
        let x1564 = x452 * k[3];
        let x1565 = x393 * k[2];
        let x1566 = x391 * k[3];
        let x1567 = x1564 + x1565;
        let x1569 = x1566 - x1567;
        let x1570 = 0.5 * x1569;
        let x1571 = x30 * k[6];
        let x1572 = x1570 + x1571;
        let x1573 = x452 * k[2];
        let x1574 = x1519 + x1573;
        let x1576 = x1517 - x1574;
        let x1577 = 0.5 * x1576;
        let x1578 = x1525 + x1577;
        let x1579 = x440 * k[2];
        let x1581 = x1530 - x1579;
        let x1582 = x1581 - x1527;
        let x1583 = 0.5 * x1582;
        let x1584 = x1562 + x1583;
        let x1585 = x430 * k[2];
        let x1586 = x1501 + x1585;
        let x1587 = x1499 + x1586;
        let x1588 = 0.5 * x1587;
        let x1589 = x11 * k[6];
        let x1590 = x1588 + x1589;
        let x1592 = x417 * k[2];
        let x1594 = x1592 - x1510;
        let x1595 = x1594 - x1507;
        let x1596 = 0.5 * x1595;
        let x1597 = x36 * k[6];
        let x1598 = x1596 + x1597;
        let x1599 = x403 * k[2];
        let x1602 = x1557 - x1599;
        let x1603 = x1602 - x1554;
        let x1604 = 0.5 * x1603;
        let x1605 = x1535 + x1604;
        let x1606 = x389 * k[2];
        let x1607 = x1566 + x1606;
        let x1609 = x1564 - x1607;
        let x1610 = 0.5 * x1609;
        let x1611 = x1571 + x1610;
        let x1612 = x375 * k[2];
        let x1613 = x1612 - x1540;
        let x1614 = x1613 - x1537;
        let x1615 = 0.5 * x1614;
        let x1616 = x1597 + x1615;
        let x1617 = x355 * k[2];
        let x1618 = x1548 + x1617;
        let x1619 = x1546 + x1618;
        let x1620 = 0.5 * x1619;
        let x1621 = x12 * k[6];
        let x1622 = x1620 + x1621;
        let x1623 = x537 * k[3];
        let x1624 = x541 * k[2];
        let x1625 = x545 * k[3];
        let x1626 = x1623 + x1624;
        let x1627 = x1625 + x1626;
        let x1628 = 0.5 * x1627;
        let x1629 = x551 * k[3];
        let x1630 = x555 * k[2];
        let x1632 = x560 * k[3];
        let x1633 = x1629 - x1630;
        let x1634 = x1632 + x1633;
        let x1635 = 0.5 * x1634;
        let x1636 = x565 * k[3];
        let x1637 = x569 * k[2];
        let x1638 = x573 * k[3];
        let x1640 = x1636 + x1637;
        let x1641 = x1640 - x1638;
        let x1642 = 0.5 * x1641;
        let x1643 = x579 * k[3];
        let x1645 = x584 * k[2];
        let x1646 = x588 * k[3];
        let x1647 = x1645 - x1643;
        let x1648 = x1646 + x1647;
        let x1649 = 0.5 * x1648;
        let x1650 = x539 * k[2];
        let x1651 = x543 * k[3];
        let x1652 = x1623 + x1650;
        let x1653 = x1651 + x1652;
        let x1654 = 0.5 * x1653;
        let x1655 = x1628 + x1654;
        let x1656 = q[3] * k[6];
        let x1657 = x599 * x1656;
        let x1659 = x1655 - x1657;
        let x1661 = x553 * k[2];
        let x1662 = x558 * k[3];
        let x1664 = x1661 - x1629;
        let x1665 = x1664 - x1662;
        let x1666 = 0.5 * x1665;
        let x1668 = x1666 - x1635;
        let x1669 = q[4] * k[6];
        let x1670 = x599 * x1669;
        let x1672 = x1668 - x1670;
        let x1673 = x567 * k[2];
        let x1674 = x571 * k[3];
        let x1675 = x1636 + x1673;
        let x1677 = x1674 - x1675;
        let x1678 = 0.5 * x1677;
        let x1680 = x1678 - x1642;
        let x1681 = q[5] * k[6];
        let x1682 = x599 * x1681;
        let x1684 = x1680 - x1682;
        let x1685 = x582 * k[2];
        let x1687 = x586 * k[3];
        let x1689 = x1643 - x1685;
        let x1690 = x1689 - x1687;
        let x1691 = 0.5 * x1690;
        let x1693 = x1691 - x1649;
        let x1694 = q[6] * k[6];
        let x1695 = x599 * x1694;
        let x1697 = x1693 - x1695;
        phi[0] = x1448;
        phi_q[0] = -1.0;
        phi_q[1] = x1462;
        phi_q[2] = x1470;
        phi_q[3] = x1478;
        phi_q[4] = x1468;
        phi[1] = x1449;
        phi_q[5] = -1.0;
        phi_q[6] = x1463;
        phi_q[7] = x1459;
        phi_q[8] = x1479;
        phi_q[9] = x1476;
        phi[2] = x1450;
        phi_q[10] = -1.0;
        phi_q[11] = x1464;
        phi_q[12] = x1471;
        phi_q[13] = x1480;
        phi_q[14] = x1482;
        phi[3] = x67;
        phi_q[15] = x68;
        phi_q[16] = x69;
        phi_q[17] = x70;
        phi_q[18] = x71;
        mass[0] = k[7];
        mass[1] = k[7];
        mass[2] = k[7];
        mass[3] = x1506;
        mass[4] = x1516;
        mass[5] = x1526;
        mass[6] = x1536;
        mass[7] = x1545;
        mass[8] = x1553;
        mass[9] = x1563;
        mass[10] = x1572;
        mass[11] = x1578;
        mass[12] = x1584;
        mass[13] = x1590;
        mass[14] = x1598;
        mass[15] = x1605;
        mass[16] = x1611;
        mass[17] = x1616;
        mass[18] = x1622;
        force[0] = 0.0;
        force[1] = k[5];
        force[2] = 0.0;
        force[3] = x1659;
        force[4] = x1672;
        force[5] = x1684;
        force[6] = x1697;
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
        let k: &[f64; 8] = k.try_into().expect("k must have 8 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let dq: &[f64; 7] = dq.try_into().expect("dq must have n_coords entries");
        let dqd: &[f64; 7] = dqd.try_into().expect("dqd must have n_coords entries");
        let dp: &[f64; 10] = dp.try_into().expect("dp must have 10 entries");
        let mass: &mut [f64; 19] = mass.try_into().expect("mass must have 19 entries");
        let force: &mut [f64; 7] = force.try_into().expect("force must have 7 entries");
        let _ = t;
        let mut s = [0.0f64; 144];
        tangents_shared_0(k, q, qd, t, dq, dqd, dp, &mut s);
        tangents_part_0(k, q, dq, dp, &s, mass, force);
        tangents_part_1(k, q, dq, dp, &s, force);
    }
    #[inline(never)]
    fn tangents_shared_0(
        _k: &[f64; 8],
        q: &[f64; 7],
        qd: &[f64; 7],
        _t: f64,
        dq: &[f64; 7],
        dqd: &[f64; 7],
        dp: &[f64; 10],
        s: &mut [f64; 144],
    ) {
        let x68 = q[3] * 2.0;
        s[0] = x68;
        let x69 = q[4] * 2.0;
        s[1] = x69;
        let x126 = q[5] * qd[4];
        s[2] = x126;
        let x127 = q[4] * qd[5];
        s[3] = x127;
        let x130 = q[6] * qd[3];
        s[4] = x130;
        let x131 = q[3] * qd[6];
        s[5] = x131;
        let x136 = q[6] * qd[4];
        s[6] = x136;
        let x137 = q[4] * qd[6];
        s[7] = x137;
        let x140 = q[5] * qd[3];
        s[8] = x140;
        let x141 = q[3] * qd[5];
        s[9] = x141;
        let x145 = q[6] * qd[5];
        s[10] = x145;
        let x146 = q[5] * qd[6];
        s[11] = x146;
        let x149 = q[4] * qd[3];
        s[12] = x149;
        let x150 = q[3] * qd[4];
        s[13] = x150;
        let x173 = 2.0 * qd[3];
        s[14] = x173;
        let x174 = 2.0 * qd[4];
        s[15] = x174;
        let x175 = 2.0 * qd[5];
        s[16] = x175;
        let x176 = 2.0 * qd[6];
        s[17] = x176;
        let x185 = qd[4] * qd[5];
        s[18] = x185;
        let x188 = qd[3] * qd[6];
        s[19] = x188;
        let x193 = qd[4] * qd[6];
        s[20] = x193;
        let x196 = qd[3] * qd[5];
        s[21] = x196;
        let x240 = x150 - x149;
        s[22] = x240;
        let x241 = x145 + x240;
        s[23] = x241;
        let x242 = x241 - x146;
        s[24] = x242;
        let x243 = 2.0 * x242;
        s[25] = x243;
        let x246 = x136 + x140;
        s[26] = x246;
        let x248 = x141 - x246;
        s[27] = x248;
        let x249 = x137 + x248;
        s[28] = x249;
        let x250 = 2.0 * x249;
        s[29] = x250;
        let x253 = x126 - x130;
        s[30] = x253;
        let x254 = x253 - x127;
        s[31] = x254;
        let x255 = x131 + x254;
        s[32] = x255;
        let x256 = 2.0 * x255;
        s[33] = x256;
        let x277 = 2.0 * x243;
        s[34] = x277;
        let x279 = 2.0 * x250;
        s[35] = x279;
        let x281 = 2.0 * x256;
        s[36] = x281;
        let x524 = x193 + x196;
        s[37] = x524;
        let x526 = x196 - x524;
        s[38] = x526;
        let x527 = x193 + x526;
        s[39] = x527;
        let x528 = 2.0 * x527;
        s[40] = x528;
        let x531 = x185 - x188;
        s[41] = x531;
        let x532 = x531 - x185;
        s[42] = x532;
        let x533 = x188 + x532;
        s[43] = x533;
        let x534 = 2.0 * x533;
        s[44] = x534;
        let x535 = 2.0 * x528;
        s[45] = x535;
        let x536 = 2.0 * x534;
        s[46] = x536;
        let x593 = qd[3] * qd[3];
        s[47] = x593;
        let x594 = qd[4] * qd[4];
        s[48] = x594;
        let x595 = qd[5] * qd[5];
        s[49] = x595;
        let x596 = qd[6] * qd[6];
        s[50] = x596;
        let x597 = x593 + x594;
        s[51] = x597;
        let x598 = x595 + x597;
        s[52] = x598;
        let x599 = x596 + x598;
        s[53] = x599;
        let x755 = 2.0 * dq[3];
        s[54] = x755;
        let x756 = 2.0 * dq[4];
        s[55] = x756;
        let x818 = qd[4] * dq[5];
        s[56] = x818;
        let x819 = q[5] * dqd[4];
        s[57] = x819;
        let x820 = x818 + x819;
        s[58] = x820;
        let x821 = qd[5] * dq[4];
        s[59] = x821;
        let x822 = q[4] * dqd[5];
        s[60] = x822;
        let x823 = x821 + x822;
        s[61] = x823;
        let x824 = qd[3] * dq[6];
        s[62] = x824;
        let x825 = q[6] * dqd[3];
        s[63] = x825;
        let x826 = x824 + x825;
        s[64] = x826;
        let x827 = qd[6] * dq[3];
        s[65] = x827;
        let x828 = q[3] * dqd[6];
        s[66] = x828;
        let x829 = x827 + x828;
        s[67] = x829;
        let x830 = qd[4] * dq[6];
        s[68] = x830;
        let x831 = q[6] * dqd[4];
        s[69] = x831;
        let x832 = x830 + x831;
        s[70] = x832;
        let x833 = qd[6] * dq[4];
        s[71] = x833;
        let x834 = q[4] * dqd[6];
        s[72] = x834;
        let x835 = x833 + x834;
        s[73] = x835;
        let x836 = qd[3] * dq[5];
        s[74] = x836;
        let x837 = q[5] * dqd[3];
        s[75] = x837;
        let x838 = x836 + x837;
        s[76] = x838;
        let x839 = qd[5] * dq[3];
        s[77] = x839;
        let x840 = q[3] * dqd[5];
        s[78] = x840;
        let x841 = x839 + x840;
        s[79] = x841;
        let x842 = qd[5] * dq[6];
        s[80] = x842;
        let x843 = q[6] * dqd[5];
        s[81] = x843;
        let x844 = x842 + x843;
        s[82] = x844;
        let x845 = qd[6] * dq[5];
        s[83] = x845;
        let x846 = q[5] * dqd[6];
        s[84] = x846;
        let x847 = x845 + x846;
        s[85] = x847;
        let x848 = qd[3] * dq[4];
        s[86] = x848;
        let x849 = q[4] * dqd[3];
        s[87] = x849;
        let x850 = x848 + x849;
        s[88] = x850;
        let x851 = qd[4] * dq[3];
        s[89] = x851;
        let x852 = q[3] * dqd[4];
        s[90] = x852;
        let x853 = x851 + x852;
        s[91] = x853;
        let x854 = 2.0 * dqd[3];
        s[92] = x854;
        let x855 = 2.0 * dqd[4];
        s[93] = x855;
        let x856 = 2.0 * dqd[5];
        s[94] = x856;
        let x857 = 2.0 * dqd[6];
        s[95] = x857;
        let x858 = x173 * dqd[3];
        s[96] = x858;
        let x861 = x174 * dqd[4];
        s[97] = x861;
        let x864 = x175 * dqd[5];
        s[98] = x864;
        let x867 = x176 * dqd[6];
        s[99] = x867;
        let x874 = qd[5] * dqd[4];
        s[100] = x874;
        let x875 = qd[4] * dqd[5];
        s[101] = x875;
        let x876 = x874 + x875;
        s[102] = x876;
        let x879 = qd[6] * dqd[3];
        s[103] = x879;
        let x880 = qd[3] * dqd[6];
        s[104] = x880;
        let x881 = x879 + x880;
        s[105] = x881;
        let x886 = qd[6] * dqd[4];
        s[106] = x886;
        let x887 = qd[4] * dqd[6];
        s[107] = x887;
        let x888 = x886 + x887;
        s[108] = x888;
        let x891 = qd[5] * dqd[3];
        s[109] = x891;
        let x892 = qd[3] * dqd[5];
        s[110] = x892;
        let x893 = x891 + x892;
        s[111] = x893;
        let x938 = x853 - x850;
        s[112] = x938;
        let x939 = x844 + x938;
        s[113] = x939;
        let x940 = x939 - x847;
        s[114] = x940;
        let x941 = 2.0 * x940;
        s[115] = x941;
        let x942 = x832 + x838;
        s[116] = x942;
        let x944 = x841 - x942;
        s[117] = x944;
        let x945 = x835 + x944;
        s[118] = x945;
        let x946 = 2.0 * x945;
        s[119] = x946;
        let x949 = x820 - x826;
        s[120] = x949;
        let x950 = x949 - x823;
        s[121] = x950;
        let x951 = x829 + x950;
        s[122] = x951;
        let x952 = 2.0 * x951;
        s[123] = x952;
        let x953 = 2.0 * x941;
        s[124] = x953;
        let x954 = 2.0 * x946;
        s[125] = x954;
        let x955 = 2.0 * x952;
        s[126] = x955;
        let x956 = dp[0] + dp[1];
        s[127] = x956;
        let x957 = dp[1] + x956;
        s[128] = x957;
        let x958 = 4.0 * x957;
        s[129] = x958;
        let x959 = 0.3333333333333333 * x958;
        s[130] = x959;
        let x1219 = x888 + x893;
        s[131] = x1219;
        let x1221 = x893 - x1219;
        s[132] = x1221;
        let x1222 = x888 + x1221;
        s[133] = x1222;
        let x1223 = 2.0 * x1222;
        s[134] = x1223;
        let x1226 = x876 - x881;
        s[135] = x1226;
        let x1227 = x1226 - x876;
        s[136] = x1227;
        let x1228 = x881 + x1227;
        s[137] = x1228;
        let x1229 = 2.0 * x1228;
        s[138] = x1229;
        let x1230 = 2.0 * x1223;
        s[139] = x1230;
        let x1231 = 2.0 * x1229;
        s[140] = x1231;
        let x1351 = x858 + x861;
        s[141] = x1351;
        let x1352 = x864 + x1351;
        s[142] = x1352;
        let x1353 = x867 + x1352;
        s[143] = x1353;
    }
    #[inline(never)]
    fn tangents_part_0(
        k: &[f64; 8],
        q: &[f64; 7],
        dq: &[f64; 7],
        dp: &[f64; 10],
        s: &[f64; 144],
        mass: &mut [f64; 19],
        force: &mut [f64; 7],
    ) {
        let x9 = q[3] * q[3];
        let x10 = q[4] * q[4];
        let x11 = q[5] * q[5];
        let x12 = q[6] * q[6];
        let x23 = q[4] * q[5];
        let x25 = q[3] * q[6];
        let x30 = q[4] * q[6];
        let x32 = q[3] * q[5];
        let x36 = q[5] * q[6];
        let x38 = q[3] * q[4];
        let x70 = q[5] * 2.0;
        let x71 = q[6] * 2.0;
        let x72 = 2.0 * s[0];
        let x89 = 2.0 * s[1];
        let x97 = 2.0 * x70;
        let x353 = 2.0 * x71;
        let x355 = s[1] * x89;
        let x359 = x70 * x97;
        let x363 = x71 * x353;
        let x375 = s[1] * x72;
        let x377 = x70 * x353;
        let x381 = x71 * x97;
        let x389 = s[1] * x353;
        let x391 = x70 * x72;
        let x393 = x71 * x89;
        let x403 = s[1] * x97;
        let x407 = x70 * x89;
        let x409 = x71 * x72;
        let x417 = s[0] * x89;
        let x430 = s[0] * x72;
        let x440 = s[0] * x353;
        let x452 = s[0] * x97;
        let x537 = s[15] * s[34];
        let x539 = s[16] * s[35];
        let x540 = x70 * s[45];
        let x541 = x539 + x540;
        let x543 = s[17] * s[36];
        let x544 = x71 * s[46];
        let x545 = x543 + x544;
        let x551 = s[14] * s[34];
        let x553 = s[17] * s[35];
        let x554 = x71 * s[45];
        let x555 = x553 + x554;
        let x558 = s[16] * s[36];
        let x559 = x70 * s[46];
        let x560 = x558 + x559;
        let x688 = s[0] * dq[3];
        let x689 = s[1] * dq[4];
        let x690 = x70 * dq[5];
        let x691 = x71 * dq[6];
        let x696 = q[5] * dq[4];
        let x697 = q[4] * dq[5];
        let x698 = x696 + x697;
        let x700 = q[6] * dq[3];
        let x701 = q[3] * dq[6];
        let x702 = x700 + x701;
        let x706 = q[6] * dq[4];
        let x707 = q[4] * dq[6];
        let x708 = x706 + x707;
        let x710 = q[5] * dq[3];
        let x711 = q[3] * dq[5];
        let x712 = x710 + x711;
        let x715 = q[6] * dq[5];
        let x716 = q[5] * dq[6];
        let x717 = x715 + x716;
        let x719 = q[4] * dq[3];
        let x720 = q[3] * dq[4];
        let x721 = x719 + x720;
        let x757 = 2.0 * dq[5];
        let x758 = 2.0 * dq[6];
        let x759 = 2.0 * s[54];
        let x786 = 2.0 * s[55];
        let x800 = 2.0 * x757;
        let x934 = 9.81 * dp[3];
        let x935 = -x934;
        let x960 = 2.0 * dp[3];
        let x961 = 0.5 * x960;
        let x962 = 2.0 * x758;
        let x963 = x89 * s[55];
        let x964 = s[1] * x786;
        let x965 = x963 + x964;
        let x966 = x355 * dp[1];
        let x969 = x97 * x757;
        let x970 = x70 * x800;
        let x971 = x969 + x970;
        let x972 = x359 * dp[0];
        let x975 = x353 * x758;
        let x976 = x71 * x962;
        let x977 = x975 + x976;
        let x978 = x363 * dp[1];
        let x985 = x9 * s[130];
        let x988 = x72 * s[55];
        let x989 = s[1] * x759;
        let x990 = x988 + x989;
        let x991 = x375 * dp[1];
        let x994 = x353 * x757;
        let x995 = x70 * x962;
        let x996 = x994 + x995;
        let x997 = x377 * dp[0];
        let x1001 = x97 * x758;
        let x1002 = x71 * x800;
        let x1003 = x1001 + x1002;
        let x1004 = x381 * dp[1];
        let x1012 = x38 * s[130];
        let x1015 = x353 * s[55];
        let x1016 = s[1] * x962;
        let x1017 = x1015 + x1016;
        let x1018 = x389 * dp[1];
        let x1021 = x72 * x757;
        let x1022 = x70 * x759;
        let x1023 = x1021 + x1022;
        let x1024 = x391 * dp[0];
        let x1027 = x89 * x758;
        let x1028 = x71 * x786;
        let x1029 = x1027 + x1028;
        let x1030 = x393 * dp[1];
        let x1039 = x32 * s[130];
        let x1042 = x97 * s[55];
        let x1043 = s[1] * x800;
        let x1044 = x1042 + x1043;
        let x1045 = x403 * dp[1];
        let x1049 = x89 * x757;
        let x1050 = x70 * x786;
        let x1051 = x1049 + x1050;
        let x1052 = x407 * dp[0];
        let x1055 = x72 * x758;
        let x1056 = x71 * x759;
        let x1057 = x1055 + x1056;
        let x1058 = x409 * dp[1];
        let x1066 = x25 * s[130];
        let x1069 = x89 * s[54];
        let x1070 = s[0] * x786;
        let x1071 = x1069 + x1070;
        let x1072 = x417 * dp[1];
        let x1076 = x381 * dp[0];
        let x1079 = x377 * dp[1];
        let x1087 = x72 * s[54];
        let x1088 = s[0] * x759;
        let x1089 = x1087 + x1088;
        let x1090 = x430 * dp[1];
        let x1093 = x363 * dp[0];
        let x1096 = x359 * dp[1];
        let x1103 = x10 * s[130];
        let x1106 = x353 * s[54];
        let x1107 = s[0] * x962;
        let x1108 = x1106 + x1107;
        let x1109 = x440 * dp[1];
        let x1112 = x409 * dp[0];
        let x1116 = x407 * dp[1];
        let x1124 = x23 * s[130];
        let x1127 = x97 * s[54];
        let x1128 = s[0] * x800;
        let x1129 = x1127 + x1128;
        let x1130 = x452 * dp[1];
        let x1133 = x393 * dp[0];
        let x1136 = x391 * dp[1];
        let x1144 = x30 * s[130];
        let x1147 = x452 * dp[0];
        let x1155 = x440 * dp[0];
        let x1163 = x430 * dp[0];
        let x1170 = x11 * s[130];
        let x1174 = x417 * dp[0];
        let x1182 = x36 * s[130];
        let x1185 = x403 * dp[0];
        let x1194 = x389 * dp[0];
        let x1202 = x375 * dp[0];
        let x1209 = x355 * dp[0];
        let x1216 = x12 * s[130];
        let x1232 = s[34] * s[93];
        let x1233 = s[15] * s[124];
        let x1234 = x1232 + x1233;
        let x1235 = x537 * dp[1];
        let x1238 = s[35] * s[94];
        let x1239 = s[16] * s[125];
        let x1240 = x1238 + x1239;
        let x1241 = s[45] * x757;
        let x1242 = x70 * s[139];
        let x1243 = x1241 + x1242;
        let x1244 = x1240 + x1243;
        let x1245 = x541 * dp[0];
        let x1248 = s[36] * s[95];
        let x1249 = s[17] * s[126];
        let x1250 = x1248 + x1249;
        let x1251 = s[46] * x758;
        let x1252 = x71 * s[140];
        let x1253 = x1251 + x1252;
        let x1254 = x1250 + x1253;
        let x1255 = x545 * dp[1];
        let x1261 = s[34] * s[92];
        let x1262 = s[14] * s[124];
        let x1263 = x1261 + x1262;
        let x1264 = x551 * dp[1];
        let x1267 = s[35] * s[95];
        let x1268 = s[17] * s[125];
        let x1269 = x1267 + x1268;
        let x1270 = s[45] * x758;
        let x1271 = x71 * s[139];
        let x1272 = x1270 + x1271;
        let x1273 = x1269 + x1272;
        let x1274 = x555 * dp[0];
        let x1278 = s[36] * s[94];
        let x1279 = s[16] * s[126];
        let x1280 = x1278 + x1279;
        let x1281 = s[46] * x757;
        let x1282 = x70 * s[140];
        let x1283 = x1281 + x1282;
        let x1284 = x1280 + x1283;
        let x1285 = x560 * dp[1];
        let x1354 = x539 * dp[0];
        let x1357 = x543 * dp[1];
        let x1365 = q[3] * s[130];
        let x1373 = x553 * dp[0];
        let x1376 = x558 * dp[1];
        let x1386 = q[4] * s[130];
        let x1656 = q[3] * k[6];
        let x1669 = q[4] * k[6];
        let x1778 = x965 * k[3];
        let x1779 = x966 + x1778;
        let x1780 = x971 * k[2];
        let x1781 = x972 + x1780;
        let x1782 = x977 * k[3];
        let x1783 = x978 + x1782;
        let x1784 = x1779 + x1781;
        let x1785 = x1783 + x1784;
        let x1786 = 0.5 * x1785;
        let x1787 = x688 * k[6];
        let x1788 = x985 + x1787;
        let x1789 = x1786 + x1788;
        let x1790 = x990 * k[3];
        let x1791 = x991 + x1790;
        let x1792 = x996 * k[2];
        let x1793 = x997 + x1792;
        let x1795 = x1003 * k[3];
        let x1796 = x1004 + x1795;
        let x1797 = x1791 - x1793;
        let x1798 = x1796 + x1797;
        let x1799 = 0.5 * x1798;
        let x1801 = x721 * k[6];
        let x1802 = x1012 + x1801;
        let x1803 = x1802 - x1799;
        let x1804 = x1017 * k[3];
        let x1805 = x1018 + x1804;
        let x1806 = x1023 * k[2];
        let x1807 = x1024 + x1806;
        let x1808 = x1029 * k[3];
        let x1809 = x1030 + x1808;
        let x1811 = x1805 + x1807;
        let x1812 = x1811 - x1809;
        let x1813 = 0.5 * x1812;
        let x1815 = x712 * k[6];
        let x1816 = x1039 + x1815;
        let x1817 = x1816 - x1813;
        let x1818 = x1044 * k[3];
        let x1819 = x1045 + x1818;
        let x1821 = x1051 * k[2];
        let x1822 = x1052 + x1821;
        let x1823 = x1057 * k[3];
        let x1824 = x1058 + x1823;
        let x1825 = x1822 - x1819;
        let x1826 = x1824 + x1825;
        let x1827 = 0.5 * x1826;
        let x1829 = x702 * k[6];
        let x1830 = x1066 + x1829;
        let x1831 = x1830 - x1827;
        let x1832 = x1071 * k[3];
        let x1833 = x1072 + x1832;
        let x1835 = x1003 * k[2];
        let x1836 = x1076 + x1835;
        let x1837 = x996 * k[3];
        let x1838 = x1079 + x1837;
        let x1840 = x1836 - x1833;
        let x1841 = x1840 - x1838;
        let x1842 = 0.5 * x1841;
        let x1843 = x1802 + x1842;
        let x1844 = x1089 * k[3];
        let x1845 = x1090 + x1844;
        let x1846 = x977 * k[2];
        let x1847 = x1093 + x1846;
        let x1848 = x971 * k[3];
        let x1849 = x1096 + x1848;
        let x1850 = x1845 + x1847;
        let x1851 = x1849 + x1850;
        let x1852 = 0.5 * x1851;
        let x1853 = x689 * k[6];
        let x1854 = x1103 + x1853;
        let x1855 = x1852 + x1854;
        let x1856 = x1108 * k[3];
        let x1857 = x1109 + x1856;
        let x1858 = x1057 * k[2];
        let x1859 = x1112 + x1858;
        let x1861 = x1051 * k[3];
        let x1862 = x1116 + x1861;
        let x1864 = x1857 - x1859;
        let x1865 = x1864 - x1862;
        let x1866 = 0.5 * x1865;
        let x1867 = x698 * k[6];
        let x1868 = x1124 + x1867;
        let x1869 = x1866 + x1868;
        let x1870 = x1129 * k[3];
        let x1871 = x1130 + x1870;
        let x1872 = x1029 * k[2];
        let x1873 = x1133 + x1872;
        let x1874 = x1023 * k[3];
        let x1875 = x1136 + x1874;
        let x1876 = x1871 + x1873;
        let x1878 = x1875 - x1876;
        let x1879 = 0.5 * x1878;
        let x1880 = x708 * k[6];
        let x1881 = x1144 + x1880;
        let x1882 = x1879 + x1881;
        let x1883 = x1129 * k[2];
        let x1884 = x1147 + x1883;
        let x1885 = x1809 + x1884;
        let x1887 = x1805 - x1885;
        let x1888 = 0.5 * x1887;
        let x1889 = x1816 + x1888;
        let x1890 = x1108 * k[2];
        let x1891 = x1155 + x1890;
        let x1893 = x1824 - x1891;
        let x1894 = x1893 - x1819;
        let x1895 = 0.5 * x1894;
        let x1896 = x1868 + x1895;
        let x1897 = x1089 * k[2];
        let x1898 = x1163 + x1897;
        let x1899 = x1783 + x1898;
        let x1900 = x1779 + x1899;
        let x1901 = 0.5 * x1900;
        let x1902 = x690 * k[6];
        let x1903 = x1170 + x1902;
        let x1904 = x1901 + x1903;
        let x1906 = x1071 * k[2];
        let x1907 = x1174 + x1906;
        let x1909 = x1907 - x1796;
        let x1910 = x1909 - x1791;
        let x1911 = 0.5 * x1910;
        let x1912 = x717 * k[6];
        let x1913 = x1182 + x1912;
        let x1914 = x1911 + x1913;
        let x1915 = x1044 * k[2];
        let x1916 = x1185 + x1915;
        let x1919 = x1862 - x1916;
        let x1920 = x1919 - x1857;
        let x1921 = 0.5 * x1920;
        let x1922 = x1830 + x1921;
        let x1923 = x1017 * k[2];
        let x1924 = x1194 + x1923;
        let x1925 = x1875 + x1924;
        let x1927 = x1871 - x1925;
        let x1928 = 0.5 * x1927;
        let x1929 = x1881 + x1928;
        let x1930 = x990 * k[2];
        let x1931 = x1202 + x1930;
        let x1932 = x1931 - x1838;
        let x1933 = x1932 - x1833;
        let x1934 = 0.5 * x1933;
        let x1935 = x1913 + x1934;
        let x1936 = x965 * k[2];
        let x1937 = x1209 + x1936;
        let x1938 = x1849 + x1937;
        let x1939 = x1845 + x1938;
        let x1940 = 0.5 * x1939;
        let x1941 = x691 * k[6];
        let x1942 = x1216 + x1941;
        let x1943 = x1940 + x1942;
        let x1944 = x1234 * k[3];
        let x1945 = x1235 + x1944;
        let x1946 = x1244 * k[2];
        let x1947 = x1245 + x1946;
        let x1948 = x1254 * k[3];
        let x1949 = x1255 + x1948;
        let x1950 = x1945 + x1947;
        let x1951 = x1949 + x1950;
        let x1952 = 0.5 * x1951;
        let x1953 = x1263 * k[3];
        let x1954 = x1264 + x1953;
        let x1955 = x1273 * k[2];
        let x1956 = x1274 + x1955;
        let x1958 = x1284 * k[3];
        let x1959 = x1285 + x1958;
        let x1960 = x1954 - x1956;
        let x1961 = x1959 + x1960;
        let x1962 = 0.5 * x1961;
        let x1983 = x1240 * k[2];
        let x1984 = x1354 + x1983;
        let x1985 = x1250 * k[3];
        let x1986 = x1357 + x1985;
        let x1987 = x1945 + x1984;
        let x1988 = x1986 + x1987;
        let x1989 = 0.5 * x1988;
        let x1990 = x1952 + x1989;
        let x1991 = dq[3] * k[6];
        let x1992 = x1365 + x1991;
        let x1993 = s[143] * x1656;
        let x1994 = s[53] * x1992;
        let x1995 = x1993 + x1994;
        let x1997 = x1990 - x1995;
        let x1999 = x1269 * k[2];
        let x2000 = x1373 + x1999;
        let x2001 = x1280 * k[3];
        let x2002 = x1376 + x2001;
        let x2004 = x2000 - x1954;
        let x2005 = x2004 - x2002;
        let x2006 = 0.5 * x2005;
        let x2008 = x2006 - x1962;
        let x2009 = dq[4] * k[6];
        let x2010 = x1386 + x2009;
        let x2011 = s[143] * x1669;
        let x2012 = s[53] * x2010;
        let x2013 = x2011 + x2012;
        let x2015 = x2008 - x2013;
        mass[0] = x961;
        mass[1] = x961;
        mass[2] = x961;
        mass[3] = x1789;
        mass[4] = x1803;
        mass[5] = x1817;
        mass[6] = x1831;
        mass[7] = x1843;
        mass[8] = x1855;
        mass[9] = x1869;
        mass[10] = x1882;
        mass[11] = x1889;
        mass[12] = x1896;
        mass[13] = x1904;
        mass[14] = x1914;
        mass[15] = x1922;
        mass[16] = x1929;
        mass[17] = x1935;
        mass[18] = x1943;
        force[0] = 0.0;
        force[1] = x935;
        force[2] = 0.0;
        force[3] = x1997;
        force[4] = x2015;
    }
    #[inline(never)]
    fn tangents_part_1(
        k: &[f64; 8],
        q: &[f64; 7],
        dq: &[f64; 7],
        dp: &[f64; 10],
        s: &[f64; 144],
        force: &mut [f64; 7],
    ) {
        let x565 = s[17] * s[34];
        let x567 = s[14] * s[35];
        let x568 = s[0] * s[45];
        let x569 = x567 + x568;
        let x571 = s[15] * s[36];
        let x572 = s[1] * s[46];
        let x573 = x571 + x572;
        let x579 = s[16] * s[34];
        let x582 = s[15] * s[35];
        let x583 = s[1] * s[45];
        let x584 = x582 + x583;
        let x586 = s[14] * s[36];
        let x587 = s[0] * s[46];
        let x588 = x586 + x587;
        let x1291 = s[34] * s[95];
        let x1292 = s[17] * s[124];
        let x1293 = x1291 + x1292;
        let x1294 = x565 * dp[1];
        let x1297 = s[35] * s[92];
        let x1298 = s[14] * s[125];
        let x1299 = x1297 + x1298;
        let x1300 = s[45] * s[54];
        let x1301 = s[0] * s[139];
        let x1302 = x1300 + x1301;
        let x1303 = x1299 + x1302;
        let x1304 = x569 * dp[0];
        let x1307 = s[36] * s[93];
        let x1308 = s[15] * s[126];
        let x1309 = x1307 + x1308;
        let x1310 = s[46] * s[55];
        let x1311 = s[1] * s[140];
        let x1312 = x1310 + x1311;
        let x1313 = x1309 + x1312;
        let x1314 = x573 * dp[1];
        let x1321 = s[34] * s[94];
        let x1322 = s[16] * s[124];
        let x1323 = x1321 + x1322;
        let x1324 = x579 * dp[1];
        let x1328 = s[35] * s[93];
        let x1329 = s[15] * s[125];
        let x1330 = x1328 + x1329;
        let x1331 = s[45] * s[55];
        let x1332 = s[1] * s[139];
        let x1333 = x1331 + x1332;
        let x1334 = x1330 + x1333;
        let x1335 = x584 * dp[0];
        let x1338 = s[36] * s[92];
        let x1339 = s[14] * s[126];
        let x1340 = x1338 + x1339;
        let x1341 = s[46] * s[54];
        let x1342 = s[0] * s[140];
        let x1343 = x1341 + x1342;
        let x1344 = x1340 + x1343;
        let x1345 = x588 * dp[1];
        let x1393 = x567 * dp[0];
        let x1396 = x571 * dp[1];
        let x1406 = q[5] * s[130];
        let x1413 = x582 * dp[0];
        let x1417 = x586 * dp[1];
        let x1427 = q[6] * s[130];
        let x1681 = q[5] * k[6];
        let x1694 = q[6] * k[6];
        let x1963 = x1293 * k[3];
        let x1964 = x1294 + x1963;
        let x1965 = x1303 * k[2];
        let x1966 = x1304 + x1965;
        let x1967 = x1313 * k[3];
        let x1968 = x1314 + x1967;
        let x1970 = x1964 + x1966;
        let x1971 = x1970 - x1968;
        let x1972 = 0.5 * x1971;
        let x1973 = x1323 * k[3];
        let x1974 = x1324 + x1973;
        let x1976 = x1334 * k[2];
        let x1977 = x1335 + x1976;
        let x1978 = x1344 * k[3];
        let x1979 = x1345 + x1978;
        let x1980 = x1977 - x1974;
        let x1981 = x1979 + x1980;
        let x1982 = 0.5 * x1981;
        let x2016 = x1299 * k[2];
        let x2017 = x1393 + x2016;
        let x2018 = x1309 * k[3];
        let x2019 = x1396 + x2018;
        let x2020 = x1964 + x2017;
        let x2022 = x2019 - x2020;
        let x2023 = 0.5 * x2022;
        let x2025 = x2023 - x1972;
        let x2026 = dq[5] * k[6];
        let x2027 = x1406 + x2026;
        let x2028 = s[143] * x1681;
        let x2029 = s[53] * x2027;
        let x2030 = x2028 + x2029;
        let x2032 = x2025 - x2030;
        let x2033 = x1330 * k[2];
        let x2034 = x1413 + x2033;
        let x2036 = x1340 * k[3];
        let x2037 = x1417 + x2036;
        let x2039 = x1974 - x2034;
        let x2040 = x2039 - x2037;
        let x2041 = 0.5 * x2040;
        let x2043 = x2041 - x1982;
        let x2044 = dq[6] * k[6];
        let x2045 = x1427 + x2044;
        let x2046 = s[143] * x1694;
        let x2047 = s[53] * x2045;
        let x2048 = x2046 + x2047;
        let x2050 = x2043 - x2048;
        force[5] = x2032;
        force[6] = x2050;
    }
}
/// `spherical_pendulum` with the `exact` formulation.
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
/// `spherical_pendulum` with the `exact` formulation. At run-time parameter values (`Exact::with_parameters`).
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
    name: "spherical_pendulum",
    t_end: T_END,
    formulations: &[(Formulation::Exact, &Exact as &(dyn Mechanism + Sync))],
    reduced: None,
    origin: Origin::Compiled {
        file: concat!(
            env!("CARGO_MANIFEST_DIR"), "/../../../",
            "mechanisms/spherical_pendulum.toml"
        ),
        hash: 11312270152100685384u64,
        parameters: &[],
    },
    run_time: Some(&RUN_TIME_ENTRY),
};
