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
    BodyInfo, Direction, Entry, Formulation, JointInfo, JointKind, KinematicOutputs,
    LegInfo, Mechanism, MechanismInfo, NewtonOutputs, Origin, PlatformInfo, Rotation,
    TangentOutputs,
};
use symbody_runtime::parameters::{ParameterError, RunTimeParameters};
/// Constraint residual Φ(q, t).
pub fn phi(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 53] = k.try_into().expect("k must have 53 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
    phi_part_0(k, q, t, out);
}
#[inline(never)]
fn phi_part_0(k: &[f64; 53], q: &[f64; 7], t: f64, out: &mut [f64; 7]) {
    let x7 = 0.8726646259971648 * t;
    let x153 = q[3] * q[3];
    let x154 = q[4] * q[4];
    let x155 = q[5] * q[5];
    let x156 = q[6] * q[6];
    let x157 = x153 + x154;
    let x158 = 2.0 * x157;
    let x160 = x158 - 1.0;
    let x164 = x153 + x156;
    let x165 = 2.0 * x164;
    let x166 = x165 - 1.0;
    let x167 = q[4] * q[5];
    let x168 = 2.0 * x167;
    let x169 = q[3] * q[6];
    let x171 = 2.0 * x169;
    let x174 = q[4] * q[6];
    let x175 = 2.0 * x174;
    let x176 = q[3] * q[5];
    let x177 = 2.0 * x176;
    let x178 = x175 + x177;
    let x179 = x168 + x171;
    let x180 = q[5] * q[6];
    let x181 = 2.0 * x180;
    let x182 = q[3] * q[4];
    let x184 = 2.0 * x182;
    let x186 = x181 - x184;
    let x189 = x175 - x177;
    let x360 = x155 + x157;
    let x361 = x156 + x360;
    let x362 = x361 - 1.0;
    let x4353 = x7 + k[3];
    let x4354 = k[2] + x4353;
    let x4355 = symbody_runtime::trig::cos(x4354);
    let x4356 = k[1] * x4355;
    let x4358 = k[0] - x4356;
    let x4359 = x4358.sqrt();
    let x4364 = x7 + k[7];
    let x4365 = k[6] + x4364;
    let x4366 = symbody_runtime::trig::cos(x4365);
    let x4367 = k[5] * x4366;
    let x4369 = k[4] - x4367;
    let x4370 = x4369.sqrt();
    let x4375 = x7 + k[11];
    let x4376 = k[10] + x4375;
    let x4377 = symbody_runtime::trig::cos(x4376);
    let x4378 = k[9] * x4377;
    let x4380 = k[8] - x4378;
    let x4381 = x4380.sqrt();
    let x4386 = x7 + k[15];
    let x4387 = k[14] + x4386;
    let x4388 = symbody_runtime::trig::cos(x4387);
    let x4389 = k[13] * x4388;
    let x4391 = k[12] - x4389;
    let x4392 = x4391.sqrt();
    let x4397 = x7 + k[19];
    let x4398 = k[18] + x4397;
    let x4399 = symbody_runtime::trig::cos(x4398);
    let x4400 = k[17] * x4399;
    let x4402 = k[16] - x4400;
    let x4403 = x4402.sqrt();
    let x4408 = x7 + k[23];
    let x4409 = k[22] + x4408;
    let x4410 = symbody_runtime::trig::cos(x4409);
    let x4411 = k[21] * x4410;
    let x4413 = k[20] - x4411;
    let x4414 = x4413.sqrt();
    let x4417 = x160 * k[24];
    let x4418 = x178 * k[25];
    let x4419 = x4417 + x4418;
    let x4420 = x179 * k[24];
    let x4421 = x186 * k[25];
    let x4422 = x4420 + x4421;
    let x4423 = x189 * k[24];
    let x4424 = x166 * k[25];
    let x4425 = x4423 + x4424;
    let x4426 = q[0] + x4419;
    let x4427 = q[1] + x4422;
    let x4428 = q[2] + x4425;
    let x4430 = x4426 + k[26];
    let x4432 = x4428 + k[27];
    let x4433 = x4430 * x4430;
    let x4434 = x4427 * x4427;
    let x4435 = x4432 * x4432;
    let x4436 = x4433 + x4434;
    let x4437 = x4435 + x4436;
    let x4438 = x4437.sqrt();
    let x4440 = x4438 - x4359;
    let x4443 = x160 * k[28];
    let x4444 = x178 * k[29];
    let x4445 = x4443 + x4444;
    let x4446 = x179 * k[28];
    let x4447 = x186 * k[29];
    let x4448 = x4446 + x4447;
    let x4449 = x189 * k[28];
    let x4450 = x166 * k[29];
    let x4451 = x4449 + x4450;
    let x4452 = q[0] + x4445;
    let x4453 = q[1] + x4448;
    let x4454 = q[2] + x4451;
    let x4456 = x4452 + k[30];
    let x4458 = x4454 + k[31];
    let x4459 = x4456 * x4456;
    let x4460 = x4453 * x4453;
    let x4461 = x4458 * x4458;
    let x4462 = x4459 + x4460;
    let x4463 = x4461 + x4462;
    let x4464 = x4463.sqrt();
    let x4466 = x4464 - x4370;
    let x4469 = x160 * k[32];
    let x4470 = x178 * k[33];
    let x4471 = x4469 + x4470;
    let x4472 = x179 * k[32];
    let x4473 = x186 * k[33];
    let x4474 = x4472 + x4473;
    let x4475 = x189 * k[32];
    let x4476 = x166 * k[33];
    let x4477 = x4475 + x4476;
    let x4478 = q[0] + x4471;
    let x4479 = q[1] + x4474;
    let x4480 = q[2] + x4477;
    let x4482 = x4478 + k[34];
    let x4484 = x4480 + k[35];
    let x4485 = x4482 * x4482;
    let x4486 = x4479 * x4479;
    let x4487 = x4484 * x4484;
    let x4488 = x4485 + x4486;
    let x4489 = x4487 + x4488;
    let x4490 = x4489.sqrt();
    let x4492 = x4490 - x4381;
    let x4495 = x160 * k[36];
    let x4496 = x178 * k[37];
    let x4497 = x4495 + x4496;
    let x4498 = x179 * k[36];
    let x4499 = x186 * k[37];
    let x4500 = x4498 + x4499;
    let x4501 = x189 * k[36];
    let x4502 = x166 * k[37];
    let x4503 = x4501 + x4502;
    let x4504 = q[0] + x4497;
    let x4505 = q[1] + x4500;
    let x4506 = q[2] + x4503;
    let x4508 = x4504 + k[38];
    let x4510 = x4506 + k[39];
    let x4511 = x4508 * x4508;
    let x4512 = x4505 * x4505;
    let x4513 = x4510 * x4510;
    let x4514 = x4511 + x4512;
    let x4515 = x4513 + x4514;
    let x4516 = x4515.sqrt();
    let x4518 = x4516 - x4392;
    let x4521 = x160 * k[40];
    let x4522 = x178 * k[41];
    let x4523 = x4521 + x4522;
    let x4524 = x179 * k[40];
    let x4525 = x186 * k[41];
    let x4526 = x4524 + x4525;
    let x4527 = x189 * k[40];
    let x4528 = x166 * k[41];
    let x4529 = x4527 + x4528;
    let x4530 = q[0] + x4523;
    let x4531 = q[1] + x4526;
    let x4532 = q[2] + x4529;
    let x4534 = x4530 + k[42];
    let x4536 = x4532 + k[43];
    let x4537 = x4534 * x4534;
    let x4538 = x4531 * x4531;
    let x4539 = x4536 * x4536;
    let x4540 = x4537 + x4538;
    let x4541 = x4539 + x4540;
    let x4542 = x4541.sqrt();
    let x4544 = x4542 - x4403;
    let x4547 = x160 * k[44];
    let x4548 = x178 * k[45];
    let x4549 = x4547 + x4548;
    let x4550 = x179 * k[44];
    let x4551 = x186 * k[45];
    let x4552 = x4550 + x4551;
    let x4553 = x189 * k[44];
    let x4554 = x166 * k[45];
    let x4555 = x4553 + x4554;
    let x4556 = q[0] + x4549;
    let x4557 = q[1] + x4552;
    let x4558 = q[2] + x4555;
    let x4560 = x4556 + k[46];
    let x4562 = x4558 + k[47];
    let x4563 = x4560 * x4560;
    let x4564 = x4557 * x4557;
    let x4565 = x4562 * x4562;
    let x4566 = x4563 + x4564;
    let x4567 = x4565 + x4566;
    let x4568 = x4567.sqrt();
    let x4570 = x4568 - x4414;
    out[0] = x4440;
    out[1] = x4466;
    out[2] = x4492;
    out[3] = x4518;
    out[4] = x4544;
    out[5] = x4570;
    out[6] = x362;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 53] = k.try_into().expect("k must have 53 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 46] = out.try_into().expect("out must have 46 entries");
    let _ = t;
    phi_q_part_0(k, q, out);
}
#[inline(never)]
fn phi_q_part_0(k: &[f64; 53], q: &[f64; 7], out: &mut [f64; 46]) {
    let x153 = q[3] * q[3];
    let x154 = q[4] * q[4];
    let x156 = q[6] * q[6];
    let x157 = x153 + x154;
    let x158 = 2.0 * x157;
    let x160 = x158 - 1.0;
    let x164 = x153 + x156;
    let x165 = 2.0 * x164;
    let x166 = x165 - 1.0;
    let x167 = q[4] * q[5];
    let x168 = 2.0 * x167;
    let x169 = q[3] * q[6];
    let x171 = 2.0 * x169;
    let x174 = q[4] * q[6];
    let x175 = 2.0 * x174;
    let x176 = q[3] * q[5];
    let x177 = 2.0 * x176;
    let x178 = x175 + x177;
    let x179 = x168 + x171;
    let x180 = q[5] * q[6];
    let x181 = 2.0 * x180;
    let x182 = q[3] * q[4];
    let x184 = 2.0 * x182;
    let x186 = x181 - x184;
    let x189 = x175 - x177;
    let x363 = q[3] * 2.0;
    let x364 = q[4] * 2.0;
    let x365 = q[6] * 2.0;
    let x414 = q[5] * 2.0;
    let x415 = 2.0 * x363;
    let x520 = 2.0 * x364;
    let x660 = 2.0 * x365;
    let x4417 = x160 * k[24];
    let x4418 = x178 * k[25];
    let x4419 = x4417 + x4418;
    let x4420 = x179 * k[24];
    let x4421 = x186 * k[25];
    let x4422 = x4420 + x4421;
    let x4423 = x189 * k[24];
    let x4424 = x166 * k[25];
    let x4425 = x4423 + x4424;
    let x4426 = q[0] + x4419;
    let x4427 = q[1] + x4422;
    let x4428 = q[2] + x4425;
    let x4430 = x4426 + k[26];
    let x4432 = x4428 + k[27];
    let x4433 = x4430 * x4430;
    let x4434 = x4427 * x4427;
    let x4435 = x4432 * x4432;
    let x4436 = x4433 + x4434;
    let x4437 = x4435 + x4436;
    let x4438 = x4437.sqrt();
    let x4443 = x160 * k[28];
    let x4444 = x178 * k[29];
    let x4445 = x4443 + x4444;
    let x4446 = x179 * k[28];
    let x4447 = x186 * k[29];
    let x4448 = x4446 + x4447;
    let x4449 = x189 * k[28];
    let x4450 = x166 * k[29];
    let x4451 = x4449 + x4450;
    let x4452 = q[0] + x4445;
    let x4453 = q[1] + x4448;
    let x4454 = q[2] + x4451;
    let x4456 = x4452 + k[30];
    let x4458 = x4454 + k[31];
    let x4459 = x4456 * x4456;
    let x4460 = x4453 * x4453;
    let x4461 = x4458 * x4458;
    let x4462 = x4459 + x4460;
    let x4463 = x4461 + x4462;
    let x4464 = x4463.sqrt();
    let x4469 = x160 * k[32];
    let x4470 = x178 * k[33];
    let x4471 = x4469 + x4470;
    let x4472 = x179 * k[32];
    let x4473 = x186 * k[33];
    let x4474 = x4472 + x4473;
    let x4475 = x189 * k[32];
    let x4476 = x166 * k[33];
    let x4477 = x4475 + x4476;
    let x4478 = q[0] + x4471;
    let x4479 = q[1] + x4474;
    let x4480 = q[2] + x4477;
    let x4482 = x4478 + k[34];
    let x4484 = x4480 + k[35];
    let x4485 = x4482 * x4482;
    let x4486 = x4479 * x4479;
    let x4487 = x4484 * x4484;
    let x4488 = x4485 + x4486;
    let x4489 = x4487 + x4488;
    let x4490 = x4489.sqrt();
    let x4495 = x160 * k[36];
    let x4496 = x178 * k[37];
    let x4497 = x4495 + x4496;
    let x4498 = x179 * k[36];
    let x4499 = x186 * k[37];
    let x4500 = x4498 + x4499;
    let x4501 = x189 * k[36];
    let x4502 = x166 * k[37];
    let x4503 = x4501 + x4502;
    let x4504 = q[0] + x4497;
    let x4505 = q[1] + x4500;
    let x4506 = q[2] + x4503;
    let x4508 = x4504 + k[38];
    let x4510 = x4506 + k[39];
    let x4511 = x4508 * x4508;
    let x4512 = x4505 * x4505;
    let x4513 = x4510 * x4510;
    let x4514 = x4511 + x4512;
    let x4515 = x4513 + x4514;
    let x4516 = x4515.sqrt();
    let x4521 = x160 * k[40];
    let x4522 = x178 * k[41];
    let x4523 = x4521 + x4522;
    let x4524 = x179 * k[40];
    let x4525 = x186 * k[41];
    let x4526 = x4524 + x4525;
    let x4527 = x189 * k[40];
    let x4528 = x166 * k[41];
    let x4529 = x4527 + x4528;
    let x4530 = q[0] + x4523;
    let x4531 = q[1] + x4526;
    let x4532 = q[2] + x4529;
    let x4534 = x4530 + k[42];
    let x4536 = x4532 + k[43];
    let x4537 = x4534 * x4534;
    let x4538 = x4531 * x4531;
    let x4539 = x4536 * x4536;
    let x4540 = x4537 + x4538;
    let x4541 = x4539 + x4540;
    let x4542 = x4541.sqrt();
    let x4547 = x160 * k[44];
    let x4548 = x178 * k[45];
    let x4549 = x4547 + x4548;
    let x4550 = x179 * k[44];
    let x4551 = x186 * k[45];
    let x4552 = x4550 + x4551;
    let x4553 = x189 * k[44];
    let x4554 = x166 * k[45];
    let x4555 = x4553 + x4554;
    let x4556 = q[0] + x4549;
    let x4557 = q[1] + x4552;
    let x4558 = q[2] + x4555;
    let x4560 = x4556 + k[46];
    let x4562 = x4558 + k[47];
    let x4563 = x4560 * x4560;
    let x4564 = x4557 * x4557;
    let x4565 = x4562 * x4562;
    let x4566 = x4563 + x4564;
    let x4567 = x4565 + x4566;
    let x4568 = x4567.sqrt();
    let x4571 = 2.0 * x4430;
    let x4572 = 2.0 * x4427;
    let x4573 = 2.0 * x4432;
    let x4574 = 2.0 * x4438;
    let x4575 = 1.0 / x4574;
    let x4576 = x4571 * x4575;
    let x4577 = 2.0 * x4456;
    let x4578 = 2.0 * x4453;
    let x4579 = 2.0 * x4458;
    let x4580 = 2.0 * x4464;
    let x4581 = 1.0 / x4580;
    let x4582 = x4577 * x4581;
    let x4583 = 2.0 * x4482;
    let x4584 = 2.0 * x4479;
    let x4585 = 2.0 * x4484;
    let x4586 = 2.0 * x4490;
    let x4587 = 1.0 / x4586;
    let x4588 = x4583 * x4587;
    let x4589 = 2.0 * x4508;
    let x4590 = 2.0 * x4505;
    let x4591 = 2.0 * x4510;
    let x4592 = 2.0 * x4516;
    let x4593 = 1.0 / x4592;
    let x4594 = x4589 * x4593;
    let x4595 = 2.0 * x4534;
    let x4596 = 2.0 * x4531;
    let x4597 = 2.0 * x4536;
    let x4598 = 2.0 * x4542;
    let x4599 = 1.0 / x4598;
    let x4600 = x4595 * x4599;
    let x4601 = 2.0 * x4560;
    let x4602 = 2.0 * x4557;
    let x4603 = 2.0 * x4562;
    let x4604 = 2.0 * x4568;
    let x4605 = 1.0 / x4604;
    let x4606 = x4601 * x4605;
    let x4607 = x4572 * x4575;
    let x4608 = x4578 * x4581;
    let x4609 = x4584 * x4587;
    let x4610 = x4590 * x4593;
    let x4611 = x4596 * x4599;
    let x4612 = x4602 * x4605;
    let x4613 = x4573 * x4575;
    let x4614 = x4579 * x4581;
    let x4615 = x4585 * x4587;
    let x4616 = x4591 * x4593;
    let x4617 = x4597 * x4599;
    let x4618 = x4603 * x4605;
    let x4619 = x415 * k[24];
    let x4620 = x414 * k[25];
    let x4621 = x4619 + x4620;
    let x4622 = x365 * k[24];
    let x4623 = x364 * k[25];
    let x4625 = x4622 - x4623;
    let x4626 = x414 * k[24];
    let x4628 = x415 * k[25];
    let x4629 = x4628 - x4626;
    let x4630 = x4571 * x4621;
    let x4631 = x4572 * x4625;
    let x4632 = x4573 * x4629;
    let x4633 = x4630 + x4631;
    let x4634 = x4632 + x4633;
    let x4635 = x4575 * x4634;
    let x4636 = x415 * k[28];
    let x4637 = x414 * k[29];
    let x4638 = x4636 + x4637;
    let x4639 = x365 * k[28];
    let x4640 = x364 * k[29];
    let x4642 = x4639 - x4640;
    let x4643 = x414 * k[28];
    let x4645 = x415 * k[29];
    let x4646 = x4645 - x4643;
    let x4647 = x4577 * x4638;
    let x4648 = x4578 * x4642;
    let x4649 = x4579 * x4646;
    let x4650 = x4647 + x4648;
    let x4651 = x4649 + x4650;
    let x4652 = x4581 * x4651;
    let x4653 = x415 * k[32];
    let x4654 = x414 * k[33];
    let x4655 = x4653 + x4654;
    let x4656 = x365 * k[32];
    let x4657 = x364 * k[33];
    let x4659 = x4656 - x4657;
    let x4660 = x414 * k[32];
    let x4662 = x415 * k[33];
    let x4663 = x4662 - x4660;
    let x4664 = x4583 * x4655;
    let x4665 = x4584 * x4659;
    let x4666 = x4585 * x4663;
    let x4667 = x4664 + x4665;
    let x4668 = x4666 + x4667;
    let x4669 = x4587 * x4668;
    let x4670 = x415 * k[36];
    let x4671 = x414 * k[37];
    let x4672 = x4670 + x4671;
    let x4673 = x365 * k[36];
    let x4674 = x364 * k[37];
    let x4676 = x4673 - x4674;
    let x4677 = x414 * k[36];
    let x4679 = x415 * k[37];
    let x4680 = x4679 - x4677;
    let x4681 = x4589 * x4672;
    let x4682 = x4590 * x4676;
    let x4683 = x4591 * x4680;
    let x4684 = x4681 + x4682;
    let x4685 = x4683 + x4684;
    let x4686 = x4593 * x4685;
    let x4687 = x415 * k[40];
    let x4688 = x414 * k[41];
    let x4689 = x4687 + x4688;
    let x4690 = x365 * k[40];
    let x4691 = x364 * k[41];
    let x4693 = x4690 - x4691;
    let x4694 = x414 * k[40];
    let x4696 = x415 * k[41];
    let x4697 = x4696 - x4694;
    let x4698 = x4595 * x4689;
    let x4699 = x4596 * x4693;
    let x4700 = x4597 * x4697;
    let x4701 = x4698 + x4699;
    let x4702 = x4700 + x4701;
    let x4703 = x4599 * x4702;
    let x4704 = x415 * k[44];
    let x4705 = x414 * k[45];
    let x4706 = x4704 + x4705;
    let x4707 = x365 * k[44];
    let x4708 = x364 * k[45];
    let x4710 = x4707 - x4708;
    let x4711 = x414 * k[44];
    let x4713 = x415 * k[45];
    let x4714 = x4713 - x4711;
    let x4715 = x4601 * x4706;
    let x4716 = x4602 * x4710;
    let x4717 = x4603 * x4714;
    let x4718 = x4715 + x4716;
    let x4719 = x4717 + x4718;
    let x4720 = x4605 * x4719;
    let x4721 = x520 * k[24];
    let x4722 = x365 * k[25];
    let x4723 = x4721 + x4722;
    let x4724 = x363 * k[25];
    let x4726 = x4626 - x4724;
    let x4727 = x4571 * x4723;
    let x4728 = x4572 * x4726;
    let x4729 = x4573 * x4622;
    let x4730 = x4727 + x4728;
    let x4731 = x4729 + x4730;
    let x4732 = x4575 * x4731;
    let x4733 = x520 * k[28];
    let x4734 = x365 * k[29];
    let x4735 = x4733 + x4734;
    let x4736 = x363 * k[29];
    let x4738 = x4643 - x4736;
    let x4739 = x4577 * x4735;
    let x4740 = x4578 * x4738;
    let x4741 = x4579 * x4639;
    let x4742 = x4739 + x4740;
    let x4743 = x4741 + x4742;
    let x4744 = x4581 * x4743;
    let x4745 = x520 * k[32];
    let x4746 = x365 * k[33];
    let x4747 = x4745 + x4746;
    let x4748 = x363 * k[33];
    let x4750 = x4660 - x4748;
    let x4751 = x4583 * x4747;
    let x4752 = x4584 * x4750;
    let x4753 = x4585 * x4656;
    let x4754 = x4751 + x4752;
    let x4755 = x4753 + x4754;
    let x4756 = x4587 * x4755;
    let x4757 = x520 * k[36];
    let x4758 = x365 * k[37];
    let x4759 = x4757 + x4758;
    let x4760 = x363 * k[37];
    let x4762 = x4677 - x4760;
    let x4763 = x4589 * x4759;
    let x4764 = x4590 * x4762;
    let x4765 = x4591 * x4673;
    let x4766 = x4763 + x4764;
    let x4767 = x4765 + x4766;
    let x4768 = x4593 * x4767;
    let x4769 = x520 * k[40];
    let x4770 = x365 * k[41];
    let x4771 = x4769 + x4770;
    let x4772 = x363 * k[41];
    let x4774 = x4694 - x4772;
    let x4775 = x4595 * x4771;
    let x4776 = x4596 * x4774;
    let x4777 = x4597 * x4690;
    let x4778 = x4775 + x4776;
    let x4779 = x4777 + x4778;
    let x4780 = x4599 * x4779;
    let x4781 = x520 * k[44];
    let x4782 = x365 * k[45];
    let x4783 = x4781 + x4782;
    let x4784 = x363 * k[45];
    let x4786 = x4711 - x4784;
    let x4787 = x4601 * x4783;
    let x4788 = x4602 * x4786;
    let x4789 = x4603 * x4707;
    let x4790 = x4787 + x4788;
    let x4791 = x4789 + x4790;
    let x4792 = x4605 * x4791;
    let x4793 = x364 * k[24];
    let x4794 = x4722 + x4793;
    let x4795 = x363 * k[24];
    let x4796 = x4571 * x4724;
    let x4797 = x4572 * x4794;
    let x4798 = x4573 * x4795;
    let x4800 = x4796 + x4797;
    let x4801 = x4800 - x4798;
    let x4802 = x4575 * x4801;
    let x4803 = x364 * k[28];
    let x4804 = x4734 + x4803;
    let x4805 = x363 * k[28];
    let x4806 = x4577 * x4736;
    let x4807 = x4578 * x4804;
    let x4808 = x4579 * x4805;
    let x4810 = x4806 + x4807;
    let x4811 = x4810 - x4808;
    let x4812 = x4581 * x4811;
    let x4813 = x364 * k[32];
    let x4814 = x4746 + x4813;
    let x4815 = x363 * k[32];
    let x4816 = x4583 * x4748;
    let x4817 = x4584 * x4814;
    let x4818 = x4585 * x4815;
    let x4820 = x4816 + x4817;
    let x4821 = x4820 - x4818;
    let x4822 = x4587 * x4821;
    let x4823 = x364 * k[36];
    let x4824 = x4758 + x4823;
    let x4825 = x363 * k[36];
    let x4826 = x4589 * x4760;
    let x4827 = x4590 * x4824;
    let x4828 = x4591 * x4825;
    let x4830 = x4826 + x4827;
    let x4831 = x4830 - x4828;
    let x4832 = x4593 * x4831;
    let x4833 = x364 * k[40];
    let x4834 = x4770 + x4833;
    let x4835 = x363 * k[40];
    let x4836 = x4595 * x4772;
    let x4837 = x4596 * x4834;
    let x4838 = x4597 * x4835;
    let x4840 = x4836 + x4837;
    let x4841 = x4840 - x4838;
    let x4842 = x4599 * x4841;
    let x4843 = x364 * k[44];
    let x4844 = x4782 + x4843;
    let x4845 = x363 * k[44];
    let x4846 = x4601 * x4784;
    let x4847 = x4602 * x4844;
    let x4848 = x4603 * x4845;
    let x4850 = x4846 + x4847;
    let x4851 = x4850 - x4848;
    let x4852 = x4605 * x4851;
    let x4853 = x4620 + x4795;
    let x4854 = x660 * k[25];
    let x4855 = x4793 + x4854;
    let x4856 = x4571 * x4623;
    let x4857 = x4572 * x4853;
    let x4858 = x4573 * x4855;
    let x4859 = x4856 + x4857;
    let x4860 = x4858 + x4859;
    let x4861 = x4575 * x4860;
    let x4862 = x4637 + x4805;
    let x4863 = x660 * k[29];
    let x4864 = x4803 + x4863;
    let x4865 = x4577 * x4640;
    let x4866 = x4578 * x4862;
    let x4867 = x4579 * x4864;
    let x4868 = x4865 + x4866;
    let x4869 = x4867 + x4868;
    let x4870 = x4581 * x4869;
    let x4871 = x4654 + x4815;
    let x4872 = x660 * k[33];
    let x4873 = x4813 + x4872;
    let x4874 = x4583 * x4657;
    let x4875 = x4584 * x4871;
    let x4876 = x4585 * x4873;
    let x4877 = x4874 + x4875;
    let x4878 = x4876 + x4877;
    let x4879 = x4587 * x4878;
    let x4880 = x4671 + x4825;
    let x4881 = x660 * k[37];
    let x4882 = x4823 + x4881;
    let x4883 = x4589 * x4674;
    let x4884 = x4590 * x4880;
    let x4885 = x4591 * x4882;
    let x4886 = x4883 + x4884;
    let x4887 = x4885 + x4886;
    let x4888 = x4593 * x4887;
    let x4889 = x4688 + x4835;
    let x4890 = x660 * k[41];
    let x4891 = x4833 + x4890;
    let x4892 = x4595 * x4691;
    let x4893 = x4596 * x4889;
    let x4894 = x4597 * x4891;
    let x4895 = x4892 + x4893;
    let x4896 = x4894 + x4895;
    let x4897 = x4599 * x4896;
    let x4898 = x4705 + x4845;
    let x4899 = x660 * k[45];
    let x4900 = x4843 + x4899;
    let x4901 = x4601 * x4708;
    let x4902 = x4602 * x4898;
    let x4903 = x4603 * x4900;
    let x4904 = x4901 + x4902;
    let x4905 = x4903 + x4904;
    let x4906 = x4605 * x4905;
    out[0] = x4576;
    out[1] = x4607;
    out[2] = x4613;
    out[3] = x4635;
    out[4] = x4732;
    out[5] = x4802;
    out[6] = x4861;
    out[7] = x4582;
    out[8] = x4608;
    out[9] = x4614;
    out[10] = x4652;
    out[11] = x4744;
    out[12] = x4812;
    out[13] = x4870;
    out[14] = x4588;
    out[15] = x4609;
    out[16] = x4615;
    out[17] = x4669;
    out[18] = x4756;
    out[19] = x4822;
    out[20] = x4879;
    out[21] = x4594;
    out[22] = x4610;
    out[23] = x4616;
    out[24] = x4686;
    out[25] = x4768;
    out[26] = x4832;
    out[27] = x4888;
    out[28] = x4600;
    out[29] = x4611;
    out[30] = x4617;
    out[31] = x4703;
    out[32] = x4780;
    out[33] = x4842;
    out[34] = x4897;
    out[35] = x4606;
    out[36] = x4612;
    out[37] = x4618;
    out[38] = x4720;
    out[39] = x4792;
    out[40] = x4852;
    out[41] = x4906;
    out[42] = x363;
    out[43] = x364;
    out[44] = x414;
    out[45] = x365;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 53] = k.try_into().expect("k must have 53 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
    let _ = q;
    phi_t_part_0(k, t, out);
}
#[inline(never)]
fn phi_t_part_0(k: &[f64; 53], t: f64, out: &mut [f64; 7]) {
    let x7 = 0.8726646259971648 * t;
    let x4353 = x7 + k[3];
    let x4354 = k[2] + x4353;
    let (x4907, x4355) = symbody_runtime::trig::sin_cos(x4354);
    let x4356 = k[1] * x4355;
    let x4358 = k[0] - x4356;
    let x4359 = x4358.sqrt();
    let x4364 = x7 + k[7];
    let x4365 = k[6] + x4364;
    let (x4913, x4366) = symbody_runtime::trig::sin_cos(x4365);
    let x4367 = k[5] * x4366;
    let x4369 = k[4] - x4367;
    let x4370 = x4369.sqrt();
    let x4375 = x7 + k[11];
    let x4376 = k[10] + x4375;
    let (x4919, x4377) = symbody_runtime::trig::sin_cos(x4376);
    let x4378 = k[9] * x4377;
    let x4380 = k[8] - x4378;
    let x4381 = x4380.sqrt();
    let x4386 = x7 + k[15];
    let x4387 = k[14] + x4386;
    let (x4925, x4388) = symbody_runtime::trig::sin_cos(x4387);
    let x4389 = k[13] * x4388;
    let x4391 = k[12] - x4389;
    let x4392 = x4391.sqrt();
    let x4397 = x7 + k[19];
    let x4398 = k[18] + x4397;
    let (x4931, x4399) = symbody_runtime::trig::sin_cos(x4398);
    let x4400 = k[17] * x4399;
    let x4402 = k[16] - x4400;
    let x4403 = x4402.sqrt();
    let x4408 = x7 + k[23];
    let x4409 = k[22] + x4408;
    let (x4937, x4410) = symbody_runtime::trig::sin_cos(x4409);
    let x4411 = k[21] * x4410;
    let x4413 = k[20] - x4411;
    let x4414 = x4413.sqrt();
    let x4908 = 0.8726646259971648 * x4907;
    let x4909 = k[1] * x4908;
    let x4910 = 2.0 * x4359;
    let x4911 = 1.0 / x4910;
    let x4912 = x4909 * x4911;
    let x4914 = 0.8726646259971648 * x4913;
    let x4915 = k[5] * x4914;
    let x4916 = 2.0 * x4370;
    let x4917 = 1.0 / x4916;
    let x4918 = x4915 * x4917;
    let x4920 = 0.8726646259971648 * x4919;
    let x4921 = k[9] * x4920;
    let x4922 = 2.0 * x4381;
    let x4923 = 1.0 / x4922;
    let x4924 = x4921 * x4923;
    let x4926 = 0.8726646259971648 * x4925;
    let x4927 = k[13] * x4926;
    let x4928 = 2.0 * x4392;
    let x4929 = 1.0 / x4928;
    let x4930 = x4927 * x4929;
    let x4932 = 0.8726646259971648 * x4931;
    let x4933 = k[17] * x4932;
    let x4934 = 2.0 * x4403;
    let x4935 = 1.0 / x4934;
    let x4936 = x4933 * x4935;
    let x4938 = 0.8726646259971648 * x4937;
    let x4939 = k[21] * x4938;
    let x4940 = 2.0 * x4414;
    let x4941 = 1.0 / x4940;
    let x4942 = x4939 * x4941;
    let x4943 = -x4912;
    let x4944 = -x4918;
    let x4945 = -x4924;
    let x4946 = -x4930;
    let x4947 = -x4936;
    let x4948 = -x4942;
    out[0] = x4943;
    out[1] = x4944;
    out[2] = x4945;
    out[3] = x4946;
    out[4] = x4947;
    out[5] = x4948;
    out[6] = 0.0;
}
/// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
pub fn gamma(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 53] = k.try_into().expect("k must have 53 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
    let mut s = [0.0f64; 96];
    gamma_shared_0(k, q, qd, t, &mut s);
    gamma_part_0(k, q, qd, &s, out);
    gamma_part_1(k, q, qd, &s, out);
}
#[inline(never)]
fn gamma_shared_0(
    _k: &[f64; 53],
    q: &[f64; 7],
    qd: &[f64; 7],
    t: f64,
    s: &mut [f64; 96],
) {
    let x7 = 0.8726646259971648 * t;
    s[0] = x7;
    let x153 = q[3] * q[3];
    s[1] = x153;
    let x154 = q[4] * q[4];
    s[2] = x154;
    let x156 = q[6] * q[6];
    s[3] = x156;
    let x157 = x153 + x154;
    s[4] = x157;
    let x158 = 2.0 * x157;
    s[5] = x158;
    let x160 = x158 - 1.0;
    s[6] = x160;
    let x164 = x153 + x156;
    s[7] = x164;
    let x165 = 2.0 * x164;
    s[8] = x165;
    let x166 = x165 - 1.0;
    s[9] = x166;
    let x167 = q[4] * q[5];
    s[10] = x167;
    let x168 = 2.0 * x167;
    s[11] = x168;
    let x169 = q[3] * q[6];
    s[12] = x169;
    let x171 = 2.0 * x169;
    s[13] = x171;
    let x174 = q[4] * q[6];
    s[14] = x174;
    let x175 = 2.0 * x174;
    s[15] = x175;
    let x176 = q[3] * q[5];
    s[16] = x176;
    let x177 = 2.0 * x176;
    s[17] = x177;
    let x178 = x175 + x177;
    s[18] = x178;
    let x179 = x168 + x171;
    s[19] = x179;
    let x180 = q[5] * q[6];
    s[20] = x180;
    let x181 = 2.0 * x180;
    s[21] = x181;
    let x182 = q[3] * q[4];
    s[22] = x182;
    let x184 = 2.0 * x182;
    s[23] = x184;
    let x186 = x181 - x184;
    s[24] = x186;
    let x189 = x175 - x177;
    s[25] = x189;
    let x363 = q[3] * 2.0;
    s[26] = x363;
    let x364 = q[4] * 2.0;
    s[27] = x364;
    let x365 = q[6] * 2.0;
    s[28] = x365;
    let x782 = x363 * qd[3];
    s[29] = x782;
    let x783 = x364 * qd[4];
    s[30] = x783;
    let x785 = x365 * qd[6];
    s[31] = x785;
    let x786 = x782 + x783;
    s[32] = x786;
    let x787 = 2.0 * x786;
    s[33] = x787;
    let x788 = x782 + x785;
    s[34] = x788;
    let x789 = 2.0 * x788;
    s[35] = x789;
    let x790 = q[5] * qd[4];
    s[36] = x790;
    let x791 = q[4] * qd[5];
    s[37] = x791;
    let x792 = x790 + x791;
    s[38] = x792;
    let x793 = 2.0 * x792;
    s[39] = x793;
    let x794 = q[6] * qd[3];
    s[40] = x794;
    let x795 = q[3] * qd[6];
    s[41] = x795;
    let x796 = x794 + x795;
    s[42] = x796;
    let x797 = 2.0 * x796;
    s[43] = x797;
    let x798 = q[6] * qd[4];
    s[44] = x798;
    let x799 = q[4] * qd[6];
    s[45] = x799;
    let x800 = x798 + x799;
    s[46] = x800;
    let x801 = 2.0 * x800;
    s[47] = x801;
    let x802 = q[5] * qd[3];
    s[48] = x802;
    let x803 = q[3] * qd[5];
    s[49] = x803;
    let x804 = x802 + x803;
    s[50] = x804;
    let x805 = 2.0 * x804;
    s[51] = x805;
    let x806 = x801 + x805;
    s[52] = x806;
    let x807 = x793 + x797;
    s[53] = x807;
    let x808 = q[6] * qd[5];
    s[54] = x808;
    let x809 = q[5] * qd[6];
    s[55] = x809;
    let x810 = x808 + x809;
    s[56] = x810;
    let x811 = 2.0 * x810;
    s[57] = x811;
    let x812 = q[4] * qd[3];
    s[58] = x812;
    let x813 = q[3] * qd[4];
    s[59] = x813;
    let x814 = x812 + x813;
    s[60] = x814;
    let x815 = 2.0 * x814;
    s[61] = x815;
    let x817 = x811 - x815;
    s[62] = x817;
    let x819 = x801 - x805;
    s[63] = x819;
    let x936 = 2.0 * qd[3];
    s[64] = x936;
    let x937 = 2.0 * qd[4];
    s[65] = x937;
    let x938 = 2.0 * qd[6];
    s[66] = x938;
    let x1054 = qd[3] * x936;
    s[67] = x1054;
    let x1055 = qd[4] * x937;
    s[68] = x1055;
    let x1057 = qd[6] * x938;
    s[69] = x1057;
    let x1058 = x1054 + x1055;
    s[70] = x1058;
    let x1059 = 2.0 * x1058;
    s[71] = x1059;
    let x1060 = x1054 + x1057;
    s[72] = x1060;
    let x1061 = 2.0 * x1060;
    s[73] = x1061;
    let x1062 = qd[4] * qd[5];
    s[74] = x1062;
    let x1063 = x1062 + x1062;
    s[75] = x1063;
    let x1064 = 2.0 * x1063;
    s[76] = x1064;
    let x1065 = qd[3] * qd[6];
    s[77] = x1065;
    let x1066 = x1065 + x1065;
    s[78] = x1066;
    let x1067 = 2.0 * x1066;
    s[79] = x1067;
    let x1068 = qd[4] * qd[6];
    s[80] = x1068;
    let x1069 = x1068 + x1068;
    s[81] = x1069;
    let x1070 = 2.0 * x1069;
    s[82] = x1070;
    let x1071 = qd[3] * qd[5];
    s[83] = x1071;
    let x1072 = x1071 + x1071;
    s[84] = x1072;
    let x1073 = 2.0 * x1072;
    s[85] = x1073;
    let x1074 = x1070 + x1073;
    s[86] = x1074;
    let x1075 = x1064 + x1067;
    s[87] = x1075;
    let x1076 = qd[5] * qd[6];
    s[88] = x1076;
    let x1077 = x1076 + x1076;
    s[89] = x1077;
    let x1078 = 2.0 * x1077;
    s[90] = x1078;
    let x1079 = qd[3] * qd[4];
    s[91] = x1079;
    let x1080 = x1079 + x1079;
    s[92] = x1080;
    let x1081 = 2.0 * x1080;
    s[93] = x1081;
    let x1083 = x1078 - x1081;
    s[94] = x1083;
    let x1085 = x1070 - x1073;
    s[95] = x1085;
}
#[inline(never)]
fn gamma_part_0(
    k: &[f64; 53],
    q: &[f64; 7],
    qd: &[f64; 7],
    s: &[f64; 96],
    out: &mut [f64; 7],
) {
    let x4353 = s[0] + k[3];
    let x4354 = k[2] + x4353;
    let (x4907, x4355) = symbody_runtime::trig::sin_cos(x4354);
    let x4356 = k[1] * x4355;
    let x4358 = k[0] - x4356;
    let x4359 = x4358.sqrt();
    let x4364 = s[0] + k[7];
    let x4365 = k[6] + x4364;
    let (x4913, x4366) = symbody_runtime::trig::sin_cos(x4365);
    let x4367 = k[5] * x4366;
    let x4369 = k[4] - x4367;
    let x4370 = x4369.sqrt();
    let x4375 = s[0] + k[11];
    let x4376 = k[10] + x4375;
    let (x4919, x4377) = symbody_runtime::trig::sin_cos(x4376);
    let x4378 = k[9] * x4377;
    let x4380 = k[8] - x4378;
    let x4381 = x4380.sqrt();
    let x4386 = s[0] + k[15];
    let x4387 = k[14] + x4386;
    let (x4925, x4388) = symbody_runtime::trig::sin_cos(x4387);
    let x4389 = k[13] * x4388;
    let x4391 = k[12] - x4389;
    let x4392 = x4391.sqrt();
    let x4397 = s[0] + k[19];
    let x4398 = k[18] + x4397;
    let (x4931, x4399) = symbody_runtime::trig::sin_cos(x4398);
    let x4400 = k[17] * x4399;
    let x4402 = k[16] - x4400;
    let x4403 = x4402.sqrt();
    let x4417 = s[6] * k[24];
    let x4418 = s[18] * k[25];
    let x4419 = x4417 + x4418;
    let x4420 = s[19] * k[24];
    let x4421 = s[24] * k[25];
    let x4422 = x4420 + x4421;
    let x4423 = s[25] * k[24];
    let x4424 = s[9] * k[25];
    let x4425 = x4423 + x4424;
    let x4426 = q[0] + x4419;
    let x4427 = q[1] + x4422;
    let x4428 = q[2] + x4425;
    let x4430 = x4426 + k[26];
    let x4432 = x4428 + k[27];
    let x4433 = x4430 * x4430;
    let x4434 = x4427 * x4427;
    let x4435 = x4432 * x4432;
    let x4436 = x4433 + x4434;
    let x4437 = x4435 + x4436;
    let x4438 = x4437.sqrt();
    let x4443 = s[6] * k[28];
    let x4444 = s[18] * k[29];
    let x4445 = x4443 + x4444;
    let x4446 = s[19] * k[28];
    let x4447 = s[24] * k[29];
    let x4448 = x4446 + x4447;
    let x4449 = s[25] * k[28];
    let x4450 = s[9] * k[29];
    let x4451 = x4449 + x4450;
    let x4452 = q[0] + x4445;
    let x4453 = q[1] + x4448;
    let x4454 = q[2] + x4451;
    let x4456 = x4452 + k[30];
    let x4458 = x4454 + k[31];
    let x4459 = x4456 * x4456;
    let x4460 = x4453 * x4453;
    let x4461 = x4458 * x4458;
    let x4462 = x4459 + x4460;
    let x4463 = x4461 + x4462;
    let x4464 = x4463.sqrt();
    let x4469 = s[6] * k[32];
    let x4470 = s[18] * k[33];
    let x4471 = x4469 + x4470;
    let x4472 = s[19] * k[32];
    let x4473 = s[24] * k[33];
    let x4474 = x4472 + x4473;
    let x4475 = s[25] * k[32];
    let x4476 = s[9] * k[33];
    let x4477 = x4475 + x4476;
    let x4478 = q[0] + x4471;
    let x4479 = q[1] + x4474;
    let x4480 = q[2] + x4477;
    let x4482 = x4478 + k[34];
    let x4484 = x4480 + k[35];
    let x4485 = x4482 * x4482;
    let x4486 = x4479 * x4479;
    let x4487 = x4484 * x4484;
    let x4488 = x4485 + x4486;
    let x4489 = x4487 + x4488;
    let x4490 = x4489.sqrt();
    let x4495 = s[6] * k[36];
    let x4496 = s[18] * k[37];
    let x4497 = x4495 + x4496;
    let x4498 = s[19] * k[36];
    let x4499 = s[24] * k[37];
    let x4500 = x4498 + x4499;
    let x4501 = s[25] * k[36];
    let x4502 = s[9] * k[37];
    let x4503 = x4501 + x4502;
    let x4504 = q[0] + x4497;
    let x4505 = q[1] + x4500;
    let x4506 = q[2] + x4503;
    let x4508 = x4504 + k[38];
    let x4510 = x4506 + k[39];
    let x4511 = x4508 * x4508;
    let x4512 = x4505 * x4505;
    let x4513 = x4510 * x4510;
    let x4514 = x4511 + x4512;
    let x4515 = x4513 + x4514;
    let x4516 = x4515.sqrt();
    let x4521 = s[6] * k[40];
    let x4522 = s[18] * k[41];
    let x4523 = x4521 + x4522;
    let x4524 = s[19] * k[40];
    let x4525 = s[24] * k[41];
    let x4526 = x4524 + x4525;
    let x4527 = s[25] * k[40];
    let x4528 = s[9] * k[41];
    let x4529 = x4527 + x4528;
    let x4530 = q[0] + x4523;
    let x4531 = q[1] + x4526;
    let x4532 = q[2] + x4529;
    let x4534 = x4530 + k[42];
    let x4536 = x4532 + k[43];
    let x4537 = x4534 * x4534;
    let x4538 = x4531 * x4531;
    let x4539 = x4536 * x4536;
    let x4540 = x4537 + x4538;
    let x4541 = x4539 + x4540;
    let x4542 = x4541.sqrt();
    let x4571 = 2.0 * x4430;
    let x4572 = 2.0 * x4427;
    let x4573 = 2.0 * x4432;
    let x4574 = 2.0 * x4438;
    let x4575 = 1.0 / x4574;
    let x4577 = 2.0 * x4456;
    let x4578 = 2.0 * x4453;
    let x4579 = 2.0 * x4458;
    let x4580 = 2.0 * x4464;
    let x4581 = 1.0 / x4580;
    let x4583 = 2.0 * x4482;
    let x4584 = 2.0 * x4479;
    let x4585 = 2.0 * x4484;
    let x4586 = 2.0 * x4490;
    let x4587 = 1.0 / x4586;
    let x4589 = 2.0 * x4508;
    let x4590 = 2.0 * x4505;
    let x4591 = 2.0 * x4510;
    let x4592 = 2.0 * x4516;
    let x4593 = 1.0 / x4592;
    let x4595 = 2.0 * x4534;
    let x4596 = 2.0 * x4531;
    let x4597 = 2.0 * x4536;
    let x4598 = 2.0 * x4542;
    let x4599 = 1.0 / x4598;
    let x4908 = 0.8726646259971648 * x4907;
    let x4909 = k[1] * x4908;
    let x4910 = 2.0 * x4359;
    let x4911 = 1.0 / x4910;
    let x4912 = x4909 * x4911;
    let x4914 = 0.8726646259971648 * x4913;
    let x4915 = k[5] * x4914;
    let x4916 = 2.0 * x4370;
    let x4917 = 1.0 / x4916;
    let x4918 = x4915 * x4917;
    let x4920 = 0.8726646259971648 * x4919;
    let x4921 = k[9] * x4920;
    let x4922 = 2.0 * x4381;
    let x4923 = 1.0 / x4922;
    let x4924 = x4921 * x4923;
    let x4926 = 0.8726646259971648 * x4925;
    let x4927 = k[13] * x4926;
    let x4928 = 2.0 * x4392;
    let x4929 = 1.0 / x4928;
    let x4930 = x4927 * x4929;
    let x4932 = 0.8726646259971648 * x4931;
    let x4933 = k[17] * x4932;
    let x4934 = 2.0 * x4403;
    let x4935 = 1.0 / x4934;
    let x4936 = x4933 * x4935;
    let x4949 = s[33] * k[24];
    let x4950 = s[52] * k[25];
    let x4951 = x4949 + x4950;
    let x4952 = s[53] * k[24];
    let x4953 = s[62] * k[25];
    let x4954 = x4952 + x4953;
    let x4955 = s[63] * k[24];
    let x4956 = s[35] * k[25];
    let x4957 = x4955 + x4956;
    let x4958 = qd[0] + x4951;
    let x4959 = qd[1] + x4954;
    let x4960 = qd[2] + x4957;
    let x4961 = x4571 * x4958;
    let x4962 = x4572 * x4959;
    let x4963 = x4573 * x4960;
    let x4964 = x4961 + x4962;
    let x4965 = x4963 + x4964;
    let x4966 = x4575 * x4965;
    let x4967 = s[33] * k[28];
    let x4968 = s[52] * k[29];
    let x4969 = x4967 + x4968;
    let x4970 = s[53] * k[28];
    let x4971 = s[62] * k[29];
    let x4972 = x4970 + x4971;
    let x4973 = s[63] * k[28];
    let x4974 = s[35] * k[29];
    let x4975 = x4973 + x4974;
    let x4976 = qd[0] + x4969;
    let x4977 = qd[1] + x4972;
    let x4978 = qd[2] + x4975;
    let x4979 = x4577 * x4976;
    let x4980 = x4578 * x4977;
    let x4981 = x4579 * x4978;
    let x4982 = x4979 + x4980;
    let x4983 = x4981 + x4982;
    let x4984 = x4581 * x4983;
    let x4985 = s[33] * k[32];
    let x4986 = s[52] * k[33];
    let x4987 = x4985 + x4986;
    let x4988 = s[53] * k[32];
    let x4989 = s[62] * k[33];
    let x4990 = x4988 + x4989;
    let x4991 = s[63] * k[32];
    let x4992 = s[35] * k[33];
    let x4993 = x4991 + x4992;
    let x4994 = qd[0] + x4987;
    let x4995 = qd[1] + x4990;
    let x4996 = qd[2] + x4993;
    let x4997 = x4583 * x4994;
    let x4998 = x4584 * x4995;
    let x4999 = x4585 * x4996;
    let x5000 = x4997 + x4998;
    let x5001 = x4999 + x5000;
    let x5002 = x4587 * x5001;
    let x5003 = s[33] * k[36];
    let x5004 = s[52] * k[37];
    let x5005 = x5003 + x5004;
    let x5006 = s[53] * k[36];
    let x5007 = s[62] * k[37];
    let x5008 = x5006 + x5007;
    let x5009 = s[63] * k[36];
    let x5010 = s[35] * k[37];
    let x5011 = x5009 + x5010;
    let x5012 = qd[0] + x5005;
    let x5013 = qd[1] + x5008;
    let x5014 = qd[2] + x5011;
    let x5015 = x4589 * x5012;
    let x5016 = x4590 * x5013;
    let x5017 = x4591 * x5014;
    let x5018 = x5015 + x5016;
    let x5019 = x5017 + x5018;
    let x5020 = x4593 * x5019;
    let x5021 = s[33] * k[40];
    let x5022 = s[52] * k[41];
    let x5023 = x5021 + x5022;
    let x5024 = s[53] * k[40];
    let x5025 = s[62] * k[41];
    let x5026 = x5024 + x5025;
    let x5027 = s[63] * k[40];
    let x5028 = s[35] * k[41];
    let x5029 = x5027 + x5028;
    let x5030 = qd[0] + x5023;
    let x5031 = qd[1] + x5026;
    let x5032 = qd[2] + x5029;
    let x5033 = x4595 * x5030;
    let x5034 = x4596 * x5031;
    let x5035 = x4597 * x5032;
    let x5036 = x5033 + x5034;
    let x5037 = x5035 + x5036;
    let x5038 = x4599 * x5037;
    let x5057 = 2.0 * x4958;
    let x5058 = 2.0 * x4959;
    let x5059 = 2.0 * x4960;
    let x5060 = 2.0 * x4966;
    let x5061 = x4575 * x4575;
    let x5062 = x5060 * x5061;
    let x5063 = 2.0 * x4976;
    let x5064 = 2.0 * x4977;
    let x5065 = 2.0 * x4978;
    let x5066 = 2.0 * x4984;
    let x5067 = x4581 * x4581;
    let x5068 = x5066 * x5067;
    let x5069 = 2.0 * x4994;
    let x5070 = 2.0 * x4995;
    let x5071 = 2.0 * x4996;
    let x5072 = 2.0 * x5002;
    let x5073 = x4587 * x4587;
    let x5074 = x5072 * x5073;
    let x5075 = 2.0 * x5012;
    let x5076 = 2.0 * x5013;
    let x5077 = 2.0 * x5014;
    let x5078 = 2.0 * x5020;
    let x5079 = x4593 * x4593;
    let x5080 = x5078 * x5079;
    let x5081 = 2.0 * x5030;
    let x5082 = 2.0 * x5031;
    let x5083 = 2.0 * x5032;
    let x5084 = 2.0 * x5038;
    let x5085 = x4599 * x4599;
    let x5086 = x5084 * x5085;
    let x5093 = 0.8726646259971648 * x4355;
    let x5094 = 0.8726646259971648 * x5093;
    let x5095 = k[1] * x5094;
    let x5096 = 2.0 * x4912;
    let x5097 = x4911 * x4911;
    let x5098 = x5096 * x5097;
    let x5099 = x4911 * x5095;
    let x5100 = x4909 * x5098;
    let x5102 = x5099 - x5100;
    let x5103 = 0.8726646259971648 * x4366;
    let x5104 = 0.8726646259971648 * x5103;
    let x5105 = k[5] * x5104;
    let x5106 = 2.0 * x4918;
    let x5107 = x4917 * x4917;
    let x5108 = x5106 * x5107;
    let x5109 = x4917 * x5105;
    let x5110 = x4915 * x5108;
    let x5112 = x5109 - x5110;
    let x5113 = 0.8726646259971648 * x4377;
    let x5114 = 0.8726646259971648 * x5113;
    let x5115 = k[9] * x5114;
    let x5116 = 2.0 * x4924;
    let x5117 = x4923 * x4923;
    let x5118 = x5116 * x5117;
    let x5119 = x4923 * x5115;
    let x5120 = x4921 * x5118;
    let x5122 = x5119 - x5120;
    let x5123 = 0.8726646259971648 * x4388;
    let x5124 = 0.8726646259971648 * x5123;
    let x5125 = k[13] * x5124;
    let x5126 = 2.0 * x4930;
    let x5127 = x4929 * x4929;
    let x5128 = x5126 * x5127;
    let x5129 = x4929 * x5125;
    let x5130 = x4927 * x5128;
    let x5132 = x5129 - x5130;
    let x5133 = 0.8726646259971648 * x4399;
    let x5134 = 0.8726646259971648 * x5133;
    let x5135 = k[17] * x5134;
    let x5136 = 2.0 * x4936;
    let x5137 = x4935 * x4935;
    let x5138 = x5136 * x5137;
    let x5139 = x4935 * x5135;
    let x5140 = x4933 * x5138;
    let x5142 = x5139 - x5140;
    let x5159 = s[71] * k[24];
    let x5160 = s[86] * k[25];
    let x5161 = x5159 + x5160;
    let x5162 = s[87] * k[24];
    let x5163 = s[94] * k[25];
    let x5164 = x5162 + x5163;
    let x5165 = s[95] * k[24];
    let x5166 = s[73] * k[25];
    let x5167 = x5165 + x5166;
    let x5168 = x4958 * x5057;
    let x5169 = x4571 * x5161;
    let x5170 = x5168 + x5169;
    let x5171 = x4959 * x5058;
    let x5172 = x4572 * x5164;
    let x5173 = x5171 + x5172;
    let x5174 = x4960 * x5059;
    let x5175 = x4573 * x5167;
    let x5176 = x5174 + x5175;
    let x5177 = x5170 + x5173;
    let x5178 = x5176 + x5177;
    let x5179 = x4965 * x5062;
    let x5181 = x4575 * x5178;
    let x5182 = x5181 - x5179;
    let x5183 = x5182 - x5102;
    let x5184 = s[71] * k[28];
    let x5185 = s[86] * k[29];
    let x5186 = x5184 + x5185;
    let x5187 = s[87] * k[28];
    let x5188 = s[94] * k[29];
    let x5189 = x5187 + x5188;
    let x5190 = s[95] * k[28];
    let x5191 = s[73] * k[29];
    let x5192 = x5190 + x5191;
    let x5193 = x4976 * x5063;
    let x5194 = x4577 * x5186;
    let x5195 = x5193 + x5194;
    let x5196 = x4977 * x5064;
    let x5197 = x4578 * x5189;
    let x5198 = x5196 + x5197;
    let x5199 = x4978 * x5065;
    let x5200 = x4579 * x5192;
    let x5201 = x5199 + x5200;
    let x5202 = x5195 + x5198;
    let x5203 = x5201 + x5202;
    let x5204 = x4983 * x5068;
    let x5206 = x4581 * x5203;
    let x5207 = x5206 - x5204;
    let x5208 = x5207 - x5112;
    let x5209 = s[71] * k[32];
    let x5210 = s[86] * k[33];
    let x5211 = x5209 + x5210;
    let x5212 = s[87] * k[32];
    let x5213 = s[94] * k[33];
    let x5214 = x5212 + x5213;
    let x5215 = s[95] * k[32];
    let x5216 = s[73] * k[33];
    let x5217 = x5215 + x5216;
    let x5218 = x4994 * x5069;
    let x5219 = x4583 * x5211;
    let x5220 = x5218 + x5219;
    let x5221 = x4995 * x5070;
    let x5222 = x4584 * x5214;
    let x5223 = x5221 + x5222;
    let x5224 = x4996 * x5071;
    let x5225 = x4585 * x5217;
    let x5226 = x5224 + x5225;
    let x5227 = x5220 + x5223;
    let x5228 = x5226 + x5227;
    let x5229 = x5001 * x5074;
    let x5231 = x4587 * x5228;
    let x5232 = x5231 - x5229;
    let x5233 = x5232 - x5122;
    let x5234 = s[71] * k[36];
    let x5235 = s[86] * k[37];
    let x5236 = x5234 + x5235;
    let x5237 = s[87] * k[36];
    let x5238 = s[94] * k[37];
    let x5239 = x5237 + x5238;
    let x5240 = s[95] * k[36];
    let x5241 = s[73] * k[37];
    let x5242 = x5240 + x5241;
    let x5243 = x5012 * x5075;
    let x5244 = x4589 * x5236;
    let x5245 = x5243 + x5244;
    let x5246 = x5013 * x5076;
    let x5247 = x4590 * x5239;
    let x5248 = x5246 + x5247;
    let x5249 = x5014 * x5077;
    let x5250 = x4591 * x5242;
    let x5251 = x5249 + x5250;
    let x5252 = x5245 + x5248;
    let x5253 = x5251 + x5252;
    let x5254 = x5019 * x5080;
    let x5256 = x4593 * x5253;
    let x5257 = x5256 - x5254;
    let x5258 = x5257 - x5132;
    let x5259 = s[71] * k[40];
    let x5260 = s[86] * k[41];
    let x5261 = x5259 + x5260;
    let x5262 = s[87] * k[40];
    let x5263 = s[94] * k[41];
    let x5264 = x5262 + x5263;
    let x5265 = s[95] * k[40];
    let x5266 = s[73] * k[41];
    let x5267 = x5265 + x5266;
    let x5268 = x5030 * x5081;
    let x5269 = x4595 * x5261;
    let x5270 = x5268 + x5269;
    let x5271 = x5031 * x5082;
    let x5272 = x4596 * x5264;
    let x5273 = x5271 + x5272;
    let x5274 = x5032 * x5083;
    let x5275 = x4597 * x5267;
    let x5276 = x5274 + x5275;
    let x5277 = x5270 + x5273;
    let x5278 = x5276 + x5277;
    let x5279 = x5037 * x5086;
    let x5281 = x4599 * x5278;
    let x5282 = x5281 - x5279;
    let x5283 = x5282 - x5142;
    let x5309 = -x5183;
    let x5310 = -x5208;
    let x5311 = -x5233;
    let x5312 = -x5258;
    let x5313 = -x5283;
    out[0] = x5309;
    out[1] = x5310;
    out[2] = x5311;
    out[3] = x5312;
    out[4] = x5313;
}
#[inline(never)]
fn gamma_part_1(
    k: &[f64; 53],
    q: &[f64; 7],
    qd: &[f64; 7],
    s: &[f64; 96],
    out: &mut [f64; 7],
) {
    let x981 = 2.0 * qd[5];
    let x1056 = qd[5] * x981;
    let x1236 = x1056 + s[70];
    let x1237 = s[69] + x1236;
    let x1244 = -x1237;
    let x4408 = s[0] + k[23];
    let x4409 = k[22] + x4408;
    let (x4937, x4410) = symbody_runtime::trig::sin_cos(x4409);
    let x4411 = k[21] * x4410;
    let x4413 = k[20] - x4411;
    let x4414 = x4413.sqrt();
    let x4547 = s[6] * k[44];
    let x4548 = s[18] * k[45];
    let x4549 = x4547 + x4548;
    let x4550 = s[19] * k[44];
    let x4551 = s[24] * k[45];
    let x4552 = x4550 + x4551;
    let x4553 = s[25] * k[44];
    let x4554 = s[9] * k[45];
    let x4555 = x4553 + x4554;
    let x4556 = q[0] + x4549;
    let x4557 = q[1] + x4552;
    let x4558 = q[2] + x4555;
    let x4560 = x4556 + k[46];
    let x4562 = x4558 + k[47];
    let x4563 = x4560 * x4560;
    let x4564 = x4557 * x4557;
    let x4565 = x4562 * x4562;
    let x4566 = x4563 + x4564;
    let x4567 = x4565 + x4566;
    let x4568 = x4567.sqrt();
    let x4601 = 2.0 * x4560;
    let x4602 = 2.0 * x4557;
    let x4603 = 2.0 * x4562;
    let x4604 = 2.0 * x4568;
    let x4605 = 1.0 / x4604;
    let x4938 = 0.8726646259971648 * x4937;
    let x4939 = k[21] * x4938;
    let x4940 = 2.0 * x4414;
    let x4941 = 1.0 / x4940;
    let x4942 = x4939 * x4941;
    let x5039 = s[33] * k[44];
    let x5040 = s[52] * k[45];
    let x5041 = x5039 + x5040;
    let x5042 = s[53] * k[44];
    let x5043 = s[62] * k[45];
    let x5044 = x5042 + x5043;
    let x5045 = s[63] * k[44];
    let x5046 = s[35] * k[45];
    let x5047 = x5045 + x5046;
    let x5048 = qd[0] + x5041;
    let x5049 = qd[1] + x5044;
    let x5050 = qd[2] + x5047;
    let x5051 = x4601 * x5048;
    let x5052 = x4602 * x5049;
    let x5053 = x4603 * x5050;
    let x5054 = x5051 + x5052;
    let x5055 = x5053 + x5054;
    let x5056 = x4605 * x5055;
    let x5087 = 2.0 * x5048;
    let x5088 = 2.0 * x5049;
    let x5089 = 2.0 * x5050;
    let x5090 = 2.0 * x5056;
    let x5091 = x4605 * x4605;
    let x5092 = x5090 * x5091;
    let x5143 = 0.8726646259971648 * x4410;
    let x5144 = 0.8726646259971648 * x5143;
    let x5145 = k[21] * x5144;
    let x5146 = 2.0 * x4942;
    let x5147 = x4941 * x4941;
    let x5148 = x5146 * x5147;
    let x5149 = x4941 * x5145;
    let x5150 = x4939 * x5148;
    let x5152 = x5149 - x5150;
    let x5284 = s[71] * k[44];
    let x5285 = s[86] * k[45];
    let x5286 = x5284 + x5285;
    let x5287 = s[87] * k[44];
    let x5288 = s[94] * k[45];
    let x5289 = x5287 + x5288;
    let x5290 = s[95] * k[44];
    let x5291 = s[73] * k[45];
    let x5292 = x5290 + x5291;
    let x5293 = x5048 * x5087;
    let x5294 = x4601 * x5286;
    let x5295 = x5293 + x5294;
    let x5296 = x5049 * x5088;
    let x5297 = x4602 * x5289;
    let x5298 = x5296 + x5297;
    let x5299 = x5050 * x5089;
    let x5300 = x4603 * x5292;
    let x5301 = x5299 + x5300;
    let x5302 = x5295 + x5298;
    let x5303 = x5301 + x5302;
    let x5304 = x5055 * x5092;
    let x5306 = x4605 * x5303;
    let x5307 = x5306 - x5304;
    let x5308 = x5307 - x5152;
    let x5314 = -x5308;
    out[5] = x5314;
    out[6] = x1244;
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
    let k: &[f64; 53] = k.try_into().expect("k must have 53 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let phi: &mut [f64; 7] = phi.try_into().expect("phi must have 7 entries");
    let phi_q: &mut [f64; 46] = phi_q.try_into().expect("phi_q must have 46 entries");
    let phi_t: &mut [f64; 7] = phi_t.try_into().expect("phi_t must have 7 entries");
    let gamma: &mut [f64; 7] = gamma.try_into().expect("gamma must have 7 entries");
    let mut s = [0.0f64; 135];
    eval_kinematics_shared_0(k, q, qd, t, &mut s);
    eval_kinematics_part_0(k, q, qd, &s, phi, phi_q, phi_t, gamma);
    eval_kinematics_part_1(k, q, qd, &s, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_shared_0(
    k: &[f64; 53],
    q: &[f64; 7],
    qd: &[f64; 7],
    t: f64,
    s: &mut [f64; 135],
) {
    let x7 = 0.8726646259971648 * t;
    s[0] = x7;
    let x153 = q[3] * q[3];
    s[1] = x153;
    let x154 = q[4] * q[4];
    s[2] = x154;
    let x156 = q[6] * q[6];
    s[3] = x156;
    let x157 = x153 + x154;
    s[4] = x157;
    let x158 = 2.0 * x157;
    s[5] = x158;
    let x160 = x158 - 1.0;
    s[6] = x160;
    let x164 = x153 + x156;
    s[7] = x164;
    let x165 = 2.0 * x164;
    s[8] = x165;
    let x166 = x165 - 1.0;
    s[9] = x166;
    let x167 = q[4] * q[5];
    s[10] = x167;
    let x168 = 2.0 * x167;
    s[11] = x168;
    let x169 = q[3] * q[6];
    s[12] = x169;
    let x171 = 2.0 * x169;
    s[13] = x171;
    let x174 = q[4] * q[6];
    s[14] = x174;
    let x175 = 2.0 * x174;
    s[15] = x175;
    let x176 = q[3] * q[5];
    s[16] = x176;
    let x177 = 2.0 * x176;
    s[17] = x177;
    let x178 = x175 + x177;
    s[18] = x178;
    let x179 = x168 + x171;
    s[19] = x179;
    let x180 = q[5] * q[6];
    s[20] = x180;
    let x181 = 2.0 * x180;
    s[21] = x181;
    let x182 = q[3] * q[4];
    s[22] = x182;
    let x184 = 2.0 * x182;
    s[23] = x184;
    let x186 = x181 - x184;
    s[24] = x186;
    let x189 = x175 - x177;
    s[25] = x189;
    let x363 = q[3] * 2.0;
    s[26] = x363;
    let x364 = q[4] * 2.0;
    s[27] = x364;
    let x365 = q[6] * 2.0;
    s[28] = x365;
    let x414 = q[5] * 2.0;
    s[29] = x414;
    let x415 = 2.0 * x363;
    s[30] = x415;
    let x520 = 2.0 * x364;
    s[31] = x520;
    let x660 = 2.0 * x365;
    s[32] = x660;
    let x782 = x363 * qd[3];
    s[33] = x782;
    let x783 = x364 * qd[4];
    s[34] = x783;
    let x785 = x365 * qd[6];
    s[35] = x785;
    let x786 = x782 + x783;
    s[36] = x786;
    let x787 = 2.0 * x786;
    s[37] = x787;
    let x788 = x782 + x785;
    s[38] = x788;
    let x789 = 2.0 * x788;
    s[39] = x789;
    let x790 = q[5] * qd[4];
    s[40] = x790;
    let x791 = q[4] * qd[5];
    s[41] = x791;
    let x792 = x790 + x791;
    s[42] = x792;
    let x793 = 2.0 * x792;
    s[43] = x793;
    let x794 = q[6] * qd[3];
    s[44] = x794;
    let x795 = q[3] * qd[6];
    s[45] = x795;
    let x796 = x794 + x795;
    s[46] = x796;
    let x797 = 2.0 * x796;
    s[47] = x797;
    let x798 = q[6] * qd[4];
    s[48] = x798;
    let x799 = q[4] * qd[6];
    s[49] = x799;
    let x800 = x798 + x799;
    s[50] = x800;
    let x801 = 2.0 * x800;
    s[51] = x801;
    let x802 = q[5] * qd[3];
    s[52] = x802;
    let x803 = q[3] * qd[5];
    s[53] = x803;
    let x804 = x802 + x803;
    s[54] = x804;
    let x805 = 2.0 * x804;
    s[55] = x805;
    let x806 = x801 + x805;
    s[56] = x806;
    let x807 = x793 + x797;
    s[57] = x807;
    let x808 = q[6] * qd[5];
    s[58] = x808;
    let x809 = q[5] * qd[6];
    s[59] = x809;
    let x810 = x808 + x809;
    s[60] = x810;
    let x811 = 2.0 * x810;
    s[61] = x811;
    let x812 = q[4] * qd[3];
    s[62] = x812;
    let x813 = q[3] * qd[4];
    s[63] = x813;
    let x814 = x812 + x813;
    s[64] = x814;
    let x815 = 2.0 * x814;
    s[65] = x815;
    let x817 = x811 - x815;
    s[66] = x817;
    let x819 = x801 - x805;
    s[67] = x819;
    let x936 = 2.0 * qd[3];
    s[68] = x936;
    let x937 = 2.0 * qd[4];
    s[69] = x937;
    let x938 = 2.0 * qd[6];
    s[70] = x938;
    let x1054 = qd[3] * x936;
    s[71] = x1054;
    let x1055 = qd[4] * x937;
    s[72] = x1055;
    let x1057 = qd[6] * x938;
    s[73] = x1057;
    let x1058 = x1054 + x1055;
    s[74] = x1058;
    let x1059 = 2.0 * x1058;
    s[75] = x1059;
    let x1060 = x1054 + x1057;
    s[76] = x1060;
    let x1061 = 2.0 * x1060;
    s[77] = x1061;
    let x1062 = qd[4] * qd[5];
    s[78] = x1062;
    let x1063 = x1062 + x1062;
    s[79] = x1063;
    let x1064 = 2.0 * x1063;
    s[80] = x1064;
    let x1065 = qd[3] * qd[6];
    s[81] = x1065;
    let x1066 = x1065 + x1065;
    s[82] = x1066;
    let x1067 = 2.0 * x1066;
    s[83] = x1067;
    let x1068 = qd[4] * qd[6];
    s[84] = x1068;
    let x1069 = x1068 + x1068;
    s[85] = x1069;
    let x1070 = 2.0 * x1069;
    s[86] = x1070;
    let x1071 = qd[3] * qd[5];
    s[87] = x1071;
    let x1072 = x1071 + x1071;
    s[88] = x1072;
    let x1073 = 2.0 * x1072;
    s[89] = x1073;
    let x1074 = x1070 + x1073;
    s[90] = x1074;
    let x1075 = x1064 + x1067;
    s[91] = x1075;
    let x1076 = qd[5] * qd[6];
    s[92] = x1076;
    let x1077 = x1076 + x1076;
    s[93] = x1077;
    let x1078 = 2.0 * x1077;
    s[94] = x1078;
    let x1079 = qd[3] * qd[4];
    s[95] = x1079;
    let x1080 = x1079 + x1079;
    s[96] = x1080;
    let x1081 = 2.0 * x1080;
    s[97] = x1081;
    let x1083 = x1078 - x1081;
    s[98] = x1083;
    let x1085 = x1070 - x1073;
    s[99] = x1085;
    let x4386 = x7 + k[15];
    s[100] = x4386;
    let x4387 = k[14] + x4386;
    s[101] = x4387;
    let x4388 = symbody_runtime::trig::cos(x4387);
    s[102] = x4388;
    let x4389 = k[13] * x4388;
    s[103] = x4389;
    let x4391 = k[12] - x4389;
    s[104] = x4391;
    let x4392 = x4391.sqrt();
    s[105] = x4392;
    let x4495 = x160 * k[36];
    s[106] = x4495;
    let x4496 = x178 * k[37];
    s[107] = x4496;
    let x4497 = x4495 + x4496;
    s[108] = x4497;
    let x4498 = x179 * k[36];
    s[109] = x4498;
    let x4499 = x186 * k[37];
    s[110] = x4499;
    let x4500 = x4498 + x4499;
    s[111] = x4500;
    let x4501 = x189 * k[36];
    s[112] = x4501;
    let x4502 = x166 * k[37];
    s[113] = x4502;
    let x4503 = x4501 + x4502;
    s[114] = x4503;
    let x4504 = q[0] + x4497;
    s[115] = x4504;
    let x4505 = q[1] + x4500;
    s[116] = x4505;
    let x4506 = q[2] + x4503;
    s[117] = x4506;
    let x4508 = x4504 + k[38];
    s[118] = x4508;
    let x4510 = x4506 + k[39];
    s[119] = x4510;
    let x4511 = x4508 * x4508;
    s[120] = x4511;
    let x4512 = x4505 * x4505;
    s[121] = x4512;
    let x4513 = x4510 * x4510;
    s[122] = x4513;
    let x4514 = x4511 + x4512;
    s[123] = x4514;
    let x4515 = x4513 + x4514;
    s[124] = x4515;
    let x4516 = x4515.sqrt();
    s[125] = x4516;
    let x4589 = 2.0 * x4508;
    s[126] = x4589;
    let x4590 = 2.0 * x4505;
    s[127] = x4590;
    let x4591 = 2.0 * x4510;
    s[128] = x4591;
    let x4592 = 2.0 * x4516;
    s[129] = x4592;
    let x4593 = 1.0 / x4592;
    s[130] = x4593;
    let x4671 = x414 * k[37];
    s[131] = x4671;
    let x4674 = x364 * k[37];
    s[132] = x4674;
    let x4758 = x365 * k[37];
    s[133] = x4758;
    let x4760 = x363 * k[37];
    s[134] = x4760;
}
#[inline(never)]
fn eval_kinematics_part_0(
    k: &[f64; 53],
    q: &[f64; 7],
    qd: &[f64; 7],
    s: &[f64; 135],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 46],
    phi_t: &mut [f64; 7],
    gamma: &mut [f64; 7],
) {
    let x4353 = s[0] + k[3];
    let x4354 = k[2] + x4353;
    let (x4907, x4355) = symbody_runtime::trig::sin_cos(x4354);
    let x4356 = k[1] * x4355;
    let x4358 = k[0] - x4356;
    let x4359 = x4358.sqrt();
    let x4364 = s[0] + k[7];
    let x4365 = k[6] + x4364;
    let (x4913, x4366) = symbody_runtime::trig::sin_cos(x4365);
    let x4367 = k[5] * x4366;
    let x4369 = k[4] - x4367;
    let x4370 = x4369.sqrt();
    let x4375 = s[0] + k[11];
    let x4376 = k[10] + x4375;
    let (x4919, x4377) = symbody_runtime::trig::sin_cos(x4376);
    let x4378 = k[9] * x4377;
    let x4380 = k[8] - x4378;
    let x4381 = x4380.sqrt();
    let x4417 = s[6] * k[24];
    let x4418 = s[18] * k[25];
    let x4419 = x4417 + x4418;
    let x4420 = s[19] * k[24];
    let x4421 = s[24] * k[25];
    let x4422 = x4420 + x4421;
    let x4423 = s[25] * k[24];
    let x4424 = s[9] * k[25];
    let x4425 = x4423 + x4424;
    let x4426 = q[0] + x4419;
    let x4427 = q[1] + x4422;
    let x4428 = q[2] + x4425;
    let x4430 = x4426 + k[26];
    let x4432 = x4428 + k[27];
    let x4433 = x4430 * x4430;
    let x4434 = x4427 * x4427;
    let x4435 = x4432 * x4432;
    let x4436 = x4433 + x4434;
    let x4437 = x4435 + x4436;
    let x4438 = x4437.sqrt();
    let x4440 = x4438 - x4359;
    let x4443 = s[6] * k[28];
    let x4444 = s[18] * k[29];
    let x4445 = x4443 + x4444;
    let x4446 = s[19] * k[28];
    let x4447 = s[24] * k[29];
    let x4448 = x4446 + x4447;
    let x4449 = s[25] * k[28];
    let x4450 = s[9] * k[29];
    let x4451 = x4449 + x4450;
    let x4452 = q[0] + x4445;
    let x4453 = q[1] + x4448;
    let x4454 = q[2] + x4451;
    let x4456 = x4452 + k[30];
    let x4458 = x4454 + k[31];
    let x4459 = x4456 * x4456;
    let x4460 = x4453 * x4453;
    let x4461 = x4458 * x4458;
    let x4462 = x4459 + x4460;
    let x4463 = x4461 + x4462;
    let x4464 = x4463.sqrt();
    let x4466 = x4464 - x4370;
    let x4469 = s[6] * k[32];
    let x4470 = s[18] * k[33];
    let x4471 = x4469 + x4470;
    let x4472 = s[19] * k[32];
    let x4473 = s[24] * k[33];
    let x4474 = x4472 + x4473;
    let x4475 = s[25] * k[32];
    let x4476 = s[9] * k[33];
    let x4477 = x4475 + x4476;
    let x4478 = q[0] + x4471;
    let x4479 = q[1] + x4474;
    let x4480 = q[2] + x4477;
    let x4482 = x4478 + k[34];
    let x4484 = x4480 + k[35];
    let x4485 = x4482 * x4482;
    let x4486 = x4479 * x4479;
    let x4487 = x4484 * x4484;
    let x4488 = x4485 + x4486;
    let x4489 = x4487 + x4488;
    let x4490 = x4489.sqrt();
    let x4492 = x4490 - x4381;
    let x4518 = s[125] - s[105];
    let x4571 = 2.0 * x4430;
    let x4572 = 2.0 * x4427;
    let x4573 = 2.0 * x4432;
    let x4574 = 2.0 * x4438;
    let x4575 = 1.0 / x4574;
    let x4576 = x4571 * x4575;
    let x4577 = 2.0 * x4456;
    let x4578 = 2.0 * x4453;
    let x4579 = 2.0 * x4458;
    let x4580 = 2.0 * x4464;
    let x4581 = 1.0 / x4580;
    let x4582 = x4577 * x4581;
    let x4583 = 2.0 * x4482;
    let x4584 = 2.0 * x4479;
    let x4585 = 2.0 * x4484;
    let x4586 = 2.0 * x4490;
    let x4587 = 1.0 / x4586;
    let x4588 = x4583 * x4587;
    let x4594 = s[126] * s[130];
    let x4607 = x4572 * x4575;
    let x4608 = x4578 * x4581;
    let x4609 = x4584 * x4587;
    let x4610 = s[127] * s[130];
    let x4613 = x4573 * x4575;
    let x4614 = x4579 * x4581;
    let x4615 = x4585 * x4587;
    let x4616 = s[128] * s[130];
    let x4619 = s[30] * k[24];
    let x4620 = s[29] * k[25];
    let x4621 = x4619 + x4620;
    let x4622 = s[28] * k[24];
    let x4623 = s[27] * k[25];
    let x4625 = x4622 - x4623;
    let x4626 = s[29] * k[24];
    let x4628 = s[30] * k[25];
    let x4629 = x4628 - x4626;
    let x4630 = x4571 * x4621;
    let x4631 = x4572 * x4625;
    let x4632 = x4573 * x4629;
    let x4633 = x4630 + x4631;
    let x4634 = x4632 + x4633;
    let x4635 = x4575 * x4634;
    let x4636 = s[30] * k[28];
    let x4637 = s[29] * k[29];
    let x4638 = x4636 + x4637;
    let x4639 = s[28] * k[28];
    let x4640 = s[27] * k[29];
    let x4642 = x4639 - x4640;
    let x4643 = s[29] * k[28];
    let x4645 = s[30] * k[29];
    let x4646 = x4645 - x4643;
    let x4647 = x4577 * x4638;
    let x4648 = x4578 * x4642;
    let x4649 = x4579 * x4646;
    let x4650 = x4647 + x4648;
    let x4651 = x4649 + x4650;
    let x4652 = x4581 * x4651;
    let x4653 = s[30] * k[32];
    let x4654 = s[29] * k[33];
    let x4655 = x4653 + x4654;
    let x4656 = s[28] * k[32];
    let x4657 = s[27] * k[33];
    let x4659 = x4656 - x4657;
    let x4660 = s[29] * k[32];
    let x4662 = s[30] * k[33];
    let x4663 = x4662 - x4660;
    let x4664 = x4583 * x4655;
    let x4665 = x4584 * x4659;
    let x4666 = x4585 * x4663;
    let x4667 = x4664 + x4665;
    let x4668 = x4666 + x4667;
    let x4669 = x4587 * x4668;
    let x4670 = s[30] * k[36];
    let x4672 = x4670 + s[131];
    let x4673 = s[28] * k[36];
    let x4676 = x4673 - s[132];
    let x4677 = s[29] * k[36];
    let x4679 = s[30] * k[37];
    let x4680 = x4679 - x4677;
    let x4681 = s[126] * x4672;
    let x4682 = s[127] * x4676;
    let x4683 = s[128] * x4680;
    let x4684 = x4681 + x4682;
    let x4685 = x4683 + x4684;
    let x4686 = s[130] * x4685;
    let x4721 = s[31] * k[24];
    let x4722 = s[28] * k[25];
    let x4723 = x4721 + x4722;
    let x4724 = s[26] * k[25];
    let x4726 = x4626 - x4724;
    let x4727 = x4571 * x4723;
    let x4728 = x4572 * x4726;
    let x4729 = x4573 * x4622;
    let x4730 = x4727 + x4728;
    let x4731 = x4729 + x4730;
    let x4732 = x4575 * x4731;
    let x4733 = s[31] * k[28];
    let x4734 = s[28] * k[29];
    let x4735 = x4733 + x4734;
    let x4736 = s[26] * k[29];
    let x4738 = x4643 - x4736;
    let x4739 = x4577 * x4735;
    let x4740 = x4578 * x4738;
    let x4741 = x4579 * x4639;
    let x4742 = x4739 + x4740;
    let x4743 = x4741 + x4742;
    let x4744 = x4581 * x4743;
    let x4745 = s[31] * k[32];
    let x4746 = s[28] * k[33];
    let x4747 = x4745 + x4746;
    let x4748 = s[26] * k[33];
    let x4750 = x4660 - x4748;
    let x4751 = x4583 * x4747;
    let x4752 = x4584 * x4750;
    let x4753 = x4585 * x4656;
    let x4754 = x4751 + x4752;
    let x4755 = x4753 + x4754;
    let x4756 = x4587 * x4755;
    let x4757 = s[31] * k[36];
    let x4759 = x4757 + s[133];
    let x4762 = x4677 - s[134];
    let x4763 = s[126] * x4759;
    let x4764 = s[127] * x4762;
    let x4765 = s[128] * x4673;
    let x4766 = x4763 + x4764;
    let x4767 = x4765 + x4766;
    let x4768 = s[130] * x4767;
    let x4793 = s[27] * k[24];
    let x4794 = x4722 + x4793;
    let x4795 = s[26] * k[24];
    let x4796 = x4571 * x4724;
    let x4797 = x4572 * x4794;
    let x4798 = x4573 * x4795;
    let x4800 = x4796 + x4797;
    let x4801 = x4800 - x4798;
    let x4802 = x4575 * x4801;
    let x4803 = s[27] * k[28];
    let x4804 = x4734 + x4803;
    let x4805 = s[26] * k[28];
    let x4806 = x4577 * x4736;
    let x4807 = x4578 * x4804;
    let x4808 = x4579 * x4805;
    let x4810 = x4806 + x4807;
    let x4811 = x4810 - x4808;
    let x4812 = x4581 * x4811;
    let x4813 = s[27] * k[32];
    let x4814 = x4746 + x4813;
    let x4815 = s[26] * k[32];
    let x4816 = x4583 * x4748;
    let x4817 = x4584 * x4814;
    let x4818 = x4585 * x4815;
    let x4820 = x4816 + x4817;
    let x4821 = x4820 - x4818;
    let x4822 = x4587 * x4821;
    let x4853 = x4620 + x4795;
    let x4854 = s[32] * k[25];
    let x4855 = x4793 + x4854;
    let x4856 = x4571 * x4623;
    let x4857 = x4572 * x4853;
    let x4858 = x4573 * x4855;
    let x4859 = x4856 + x4857;
    let x4860 = x4858 + x4859;
    let x4861 = x4575 * x4860;
    let x4862 = x4637 + x4805;
    let x4863 = s[32] * k[29];
    let x4864 = x4803 + x4863;
    let x4865 = x4577 * x4640;
    let x4866 = x4578 * x4862;
    let x4867 = x4579 * x4864;
    let x4868 = x4865 + x4866;
    let x4869 = x4867 + x4868;
    let x4870 = x4581 * x4869;
    let x4871 = x4654 + x4815;
    let x4872 = s[32] * k[33];
    let x4873 = x4813 + x4872;
    let x4874 = x4583 * x4657;
    let x4875 = x4584 * x4871;
    let x4876 = x4585 * x4873;
    let x4877 = x4874 + x4875;
    let x4878 = x4876 + x4877;
    let x4879 = x4587 * x4878;
    let x4908 = 0.8726646259971648 * x4907;
    let x4909 = k[1] * x4908;
    let x4910 = 2.0 * x4359;
    let x4911 = 1.0 / x4910;
    let x4912 = x4909 * x4911;
    let x4914 = 0.8726646259971648 * x4913;
    let x4915 = k[5] * x4914;
    let x4916 = 2.0 * x4370;
    let x4917 = 1.0 / x4916;
    let x4918 = x4915 * x4917;
    let x4920 = 0.8726646259971648 * x4919;
    let x4921 = k[9] * x4920;
    let x4922 = 2.0 * x4381;
    let x4923 = 1.0 / x4922;
    let x4924 = x4921 * x4923;
    let x4943 = -x4912;
    let x4944 = -x4918;
    let x4945 = -x4924;
    let x4949 = s[37] * k[24];
    let x4950 = s[56] * k[25];
    let x4951 = x4949 + x4950;
    let x4952 = s[57] * k[24];
    let x4953 = s[66] * k[25];
    let x4954 = x4952 + x4953;
    let x4955 = s[67] * k[24];
    let x4956 = s[39] * k[25];
    let x4957 = x4955 + x4956;
    let x4958 = qd[0] + x4951;
    let x4959 = qd[1] + x4954;
    let x4960 = qd[2] + x4957;
    let x4961 = x4571 * x4958;
    let x4962 = x4572 * x4959;
    let x4963 = x4573 * x4960;
    let x4964 = x4961 + x4962;
    let x4965 = x4963 + x4964;
    let x4966 = x4575 * x4965;
    let x4967 = s[37] * k[28];
    let x4968 = s[56] * k[29];
    let x4969 = x4967 + x4968;
    let x4970 = s[57] * k[28];
    let x4971 = s[66] * k[29];
    let x4972 = x4970 + x4971;
    let x4973 = s[67] * k[28];
    let x4974 = s[39] * k[29];
    let x4975 = x4973 + x4974;
    let x4976 = qd[0] + x4969;
    let x4977 = qd[1] + x4972;
    let x4978 = qd[2] + x4975;
    let x4979 = x4577 * x4976;
    let x4980 = x4578 * x4977;
    let x4981 = x4579 * x4978;
    let x4982 = x4979 + x4980;
    let x4983 = x4981 + x4982;
    let x4984 = x4581 * x4983;
    let x4985 = s[37] * k[32];
    let x4986 = s[56] * k[33];
    let x4987 = x4985 + x4986;
    let x4988 = s[57] * k[32];
    let x4989 = s[66] * k[33];
    let x4990 = x4988 + x4989;
    let x4991 = s[67] * k[32];
    let x4992 = s[39] * k[33];
    let x4993 = x4991 + x4992;
    let x4994 = qd[0] + x4987;
    let x4995 = qd[1] + x4990;
    let x4996 = qd[2] + x4993;
    let x4997 = x4583 * x4994;
    let x4998 = x4584 * x4995;
    let x4999 = x4585 * x4996;
    let x5000 = x4997 + x4998;
    let x5001 = x4999 + x5000;
    let x5002 = x4587 * x5001;
    let x5057 = 2.0 * x4958;
    let x5058 = 2.0 * x4959;
    let x5059 = 2.0 * x4960;
    let x5060 = 2.0 * x4966;
    let x5061 = x4575 * x4575;
    let x5062 = x5060 * x5061;
    let x5063 = 2.0 * x4976;
    let x5064 = 2.0 * x4977;
    let x5065 = 2.0 * x4978;
    let x5066 = 2.0 * x4984;
    let x5067 = x4581 * x4581;
    let x5068 = x5066 * x5067;
    let x5069 = 2.0 * x4994;
    let x5070 = 2.0 * x4995;
    let x5071 = 2.0 * x4996;
    let x5072 = 2.0 * x5002;
    let x5073 = x4587 * x4587;
    let x5074 = x5072 * x5073;
    let x5093 = 0.8726646259971648 * x4355;
    let x5094 = 0.8726646259971648 * x5093;
    let x5095 = k[1] * x5094;
    let x5096 = 2.0 * x4912;
    let x5097 = x4911 * x4911;
    let x5098 = x5096 * x5097;
    let x5099 = x4911 * x5095;
    let x5100 = x4909 * x5098;
    let x5102 = x5099 - x5100;
    let x5103 = 0.8726646259971648 * x4366;
    let x5104 = 0.8726646259971648 * x5103;
    let x5105 = k[5] * x5104;
    let x5106 = 2.0 * x4918;
    let x5107 = x4917 * x4917;
    let x5108 = x5106 * x5107;
    let x5109 = x4917 * x5105;
    let x5110 = x4915 * x5108;
    let x5112 = x5109 - x5110;
    let x5113 = 0.8726646259971648 * x4377;
    let x5114 = 0.8726646259971648 * x5113;
    let x5115 = k[9] * x5114;
    let x5116 = 2.0 * x4924;
    let x5117 = x4923 * x4923;
    let x5118 = x5116 * x5117;
    let x5119 = x4923 * x5115;
    let x5120 = x4921 * x5118;
    let x5122 = x5119 - x5120;
    let x5159 = s[75] * k[24];
    let x5160 = s[90] * k[25];
    let x5161 = x5159 + x5160;
    let x5162 = s[91] * k[24];
    let x5163 = s[98] * k[25];
    let x5164 = x5162 + x5163;
    let x5165 = s[99] * k[24];
    let x5166 = s[77] * k[25];
    let x5167 = x5165 + x5166;
    let x5168 = x4958 * x5057;
    let x5169 = x4571 * x5161;
    let x5170 = x5168 + x5169;
    let x5171 = x4959 * x5058;
    let x5172 = x4572 * x5164;
    let x5173 = x5171 + x5172;
    let x5174 = x4960 * x5059;
    let x5175 = x4573 * x5167;
    let x5176 = x5174 + x5175;
    let x5177 = x5170 + x5173;
    let x5178 = x5176 + x5177;
    let x5179 = x4965 * x5062;
    let x5181 = x4575 * x5178;
    let x5182 = x5181 - x5179;
    let x5183 = x5182 - x5102;
    let x5184 = s[75] * k[28];
    let x5185 = s[90] * k[29];
    let x5186 = x5184 + x5185;
    let x5187 = s[91] * k[28];
    let x5188 = s[98] * k[29];
    let x5189 = x5187 + x5188;
    let x5190 = s[99] * k[28];
    let x5191 = s[77] * k[29];
    let x5192 = x5190 + x5191;
    let x5193 = x4976 * x5063;
    let x5194 = x4577 * x5186;
    let x5195 = x5193 + x5194;
    let x5196 = x4977 * x5064;
    let x5197 = x4578 * x5189;
    let x5198 = x5196 + x5197;
    let x5199 = x4978 * x5065;
    let x5200 = x4579 * x5192;
    let x5201 = x5199 + x5200;
    let x5202 = x5195 + x5198;
    let x5203 = x5201 + x5202;
    let x5204 = x4983 * x5068;
    let x5206 = x4581 * x5203;
    let x5207 = x5206 - x5204;
    let x5208 = x5207 - x5112;
    let x5209 = s[75] * k[32];
    let x5210 = s[90] * k[33];
    let x5211 = x5209 + x5210;
    let x5212 = s[91] * k[32];
    let x5213 = s[98] * k[33];
    let x5214 = x5212 + x5213;
    let x5215 = s[99] * k[32];
    let x5216 = s[77] * k[33];
    let x5217 = x5215 + x5216;
    let x5218 = x4994 * x5069;
    let x5219 = x4583 * x5211;
    let x5220 = x5218 + x5219;
    let x5221 = x4995 * x5070;
    let x5222 = x4584 * x5214;
    let x5223 = x5221 + x5222;
    let x5224 = x4996 * x5071;
    let x5225 = x4585 * x5217;
    let x5226 = x5224 + x5225;
    let x5227 = x5220 + x5223;
    let x5228 = x5226 + x5227;
    let x5229 = x5001 * x5074;
    let x5231 = x4587 * x5228;
    let x5232 = x5231 - x5229;
    let x5233 = x5232 - x5122;
    let x5309 = -x5183;
    let x5310 = -x5208;
    let x5311 = -x5233;
    phi[0] = x4440;
    phi_q[0] = x4576;
    phi_q[1] = x4607;
    phi_q[2] = x4613;
    phi_q[3] = x4635;
    phi_q[4] = x4732;
    phi_q[5] = x4802;
    phi_q[6] = x4861;
    phi_t[0] = x4943;
    gamma[0] = x5309;
    phi[1] = x4466;
    phi_q[7] = x4582;
    phi_q[8] = x4608;
    phi_q[9] = x4614;
    phi_q[10] = x4652;
    phi_q[11] = x4744;
    phi_q[12] = x4812;
    phi_q[13] = x4870;
    phi_t[1] = x4944;
    gamma[1] = x5310;
    phi[2] = x4492;
    phi_q[14] = x4588;
    phi_q[15] = x4609;
    phi_q[16] = x4615;
    phi_q[17] = x4669;
    phi_q[18] = x4756;
    phi_q[19] = x4822;
    phi_q[20] = x4879;
    phi_t[2] = x4945;
    gamma[2] = x5311;
    phi[3] = x4518;
    phi_q[21] = x4594;
    phi_q[22] = x4610;
    phi_q[23] = x4616;
    phi_q[24] = x4686;
    phi_q[25] = x4768;
}
#[inline(never)]
fn eval_kinematics_part_1(
    k: &[f64; 53],
    q: &[f64; 7],
    qd: &[f64; 7],
    s: &[f64; 135],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 46],
    phi_t: &mut [f64; 7],
    gamma: &mut [f64; 7],
) {
    let x155 = q[5] * q[5];
    let x360 = x155 + s[4];
    let x361 = s[3] + x360;
    let x362 = x361 - 1.0;
    let x981 = 2.0 * qd[5];
    let x1056 = qd[5] * x981;
    let x1236 = x1056 + s[74];
    let x1237 = s[73] + x1236;
    let x1244 = -x1237;
    let x4397 = s[0] + k[19];
    let x4398 = k[18] + x4397;
    let (x4931, x4399) = symbody_runtime::trig::sin_cos(x4398);
    let x4400 = k[17] * x4399;
    let x4402 = k[16] - x4400;
    let x4403 = x4402.sqrt();
    let x4408 = s[0] + k[23];
    let x4409 = k[22] + x4408;
    let (x4937, x4410) = symbody_runtime::trig::sin_cos(x4409);
    let x4411 = k[21] * x4410;
    let x4413 = k[20] - x4411;
    let x4414 = x4413.sqrt();
    let x4521 = s[6] * k[40];
    let x4522 = s[18] * k[41];
    let x4523 = x4521 + x4522;
    let x4524 = s[19] * k[40];
    let x4525 = s[24] * k[41];
    let x4526 = x4524 + x4525;
    let x4527 = s[25] * k[40];
    let x4528 = s[9] * k[41];
    let x4529 = x4527 + x4528;
    let x4530 = q[0] + x4523;
    let x4531 = q[1] + x4526;
    let x4532 = q[2] + x4529;
    let x4534 = x4530 + k[42];
    let x4536 = x4532 + k[43];
    let x4537 = x4534 * x4534;
    let x4538 = x4531 * x4531;
    let x4539 = x4536 * x4536;
    let x4540 = x4537 + x4538;
    let x4541 = x4539 + x4540;
    let x4542 = x4541.sqrt();
    let x4544 = x4542 - x4403;
    let x4547 = s[6] * k[44];
    let x4548 = s[18] * k[45];
    let x4549 = x4547 + x4548;
    let x4550 = s[19] * k[44];
    let x4551 = s[24] * k[45];
    let x4552 = x4550 + x4551;
    let x4553 = s[25] * k[44];
    let x4554 = s[9] * k[45];
    let x4555 = x4553 + x4554;
    let x4556 = q[0] + x4549;
    let x4557 = q[1] + x4552;
    let x4558 = q[2] + x4555;
    let x4560 = x4556 + k[46];
    let x4562 = x4558 + k[47];
    let x4563 = x4560 * x4560;
    let x4564 = x4557 * x4557;
    let x4565 = x4562 * x4562;
    let x4566 = x4563 + x4564;
    let x4567 = x4565 + x4566;
    let x4568 = x4567.sqrt();
    let x4570 = x4568 - x4414;
    let x4595 = 2.0 * x4534;
    let x4596 = 2.0 * x4531;
    let x4597 = 2.0 * x4536;
    let x4598 = 2.0 * x4542;
    let x4599 = 1.0 / x4598;
    let x4600 = x4595 * x4599;
    let x4601 = 2.0 * x4560;
    let x4602 = 2.0 * x4557;
    let x4603 = 2.0 * x4562;
    let x4604 = 2.0 * x4568;
    let x4605 = 1.0 / x4604;
    let x4606 = x4601 * x4605;
    let x4611 = x4596 * x4599;
    let x4612 = x4602 * x4605;
    let x4617 = x4597 * x4599;
    let x4618 = x4603 * x4605;
    let x4687 = s[30] * k[40];
    let x4688 = s[29] * k[41];
    let x4689 = x4687 + x4688;
    let x4690 = s[28] * k[40];
    let x4691 = s[27] * k[41];
    let x4693 = x4690 - x4691;
    let x4694 = s[29] * k[40];
    let x4696 = s[30] * k[41];
    let x4697 = x4696 - x4694;
    let x4698 = x4595 * x4689;
    let x4699 = x4596 * x4693;
    let x4700 = x4597 * x4697;
    let x4701 = x4698 + x4699;
    let x4702 = x4700 + x4701;
    let x4703 = x4599 * x4702;
    let x4704 = s[30] * k[44];
    let x4705 = s[29] * k[45];
    let x4706 = x4704 + x4705;
    let x4707 = s[28] * k[44];
    let x4708 = s[27] * k[45];
    let x4710 = x4707 - x4708;
    let x4711 = s[29] * k[44];
    let x4713 = s[30] * k[45];
    let x4714 = x4713 - x4711;
    let x4715 = x4601 * x4706;
    let x4716 = x4602 * x4710;
    let x4717 = x4603 * x4714;
    let x4718 = x4715 + x4716;
    let x4719 = x4717 + x4718;
    let x4720 = x4605 * x4719;
    let x4769 = s[31] * k[40];
    let x4770 = s[28] * k[41];
    let x4771 = x4769 + x4770;
    let x4772 = s[26] * k[41];
    let x4774 = x4694 - x4772;
    let x4775 = x4595 * x4771;
    let x4776 = x4596 * x4774;
    let x4777 = x4597 * x4690;
    let x4778 = x4775 + x4776;
    let x4779 = x4777 + x4778;
    let x4780 = x4599 * x4779;
    let x4781 = s[31] * k[44];
    let x4782 = s[28] * k[45];
    let x4783 = x4781 + x4782;
    let x4784 = s[26] * k[45];
    let x4786 = x4711 - x4784;
    let x4787 = x4601 * x4783;
    let x4788 = x4602 * x4786;
    let x4789 = x4603 * x4707;
    let x4790 = x4787 + x4788;
    let x4791 = x4789 + x4790;
    let x4792 = x4605 * x4791;
    let x4823 = s[27] * k[36];
    let x4824 = s[133] + x4823;
    let x4825 = s[26] * k[36];
    let x4826 = s[126] * s[134];
    let x4827 = s[127] * x4824;
    let x4828 = s[128] * x4825;
    let x4830 = x4826 + x4827;
    let x4831 = x4830 - x4828;
    let x4832 = s[130] * x4831;
    let x4833 = s[27] * k[40];
    let x4834 = x4770 + x4833;
    let x4835 = s[26] * k[40];
    let x4836 = x4595 * x4772;
    let x4837 = x4596 * x4834;
    let x4838 = x4597 * x4835;
    let x4840 = x4836 + x4837;
    let x4841 = x4840 - x4838;
    let x4842 = x4599 * x4841;
    let x4843 = s[27] * k[44];
    let x4844 = x4782 + x4843;
    let x4845 = s[26] * k[44];
    let x4846 = x4601 * x4784;
    let x4847 = x4602 * x4844;
    let x4848 = x4603 * x4845;
    let x4850 = x4846 + x4847;
    let x4851 = x4850 - x4848;
    let x4852 = x4605 * x4851;
    let x4880 = s[131] + x4825;
    let x4881 = s[32] * k[37];
    let x4882 = x4823 + x4881;
    let x4883 = s[126] * s[132];
    let x4884 = s[127] * x4880;
    let x4885 = s[128] * x4882;
    let x4886 = x4883 + x4884;
    let x4887 = x4885 + x4886;
    let x4888 = s[130] * x4887;
    let x4889 = x4688 + x4835;
    let x4890 = s[32] * k[41];
    let x4891 = x4833 + x4890;
    let x4892 = x4595 * x4691;
    let x4893 = x4596 * x4889;
    let x4894 = x4597 * x4891;
    let x4895 = x4892 + x4893;
    let x4896 = x4894 + x4895;
    let x4897 = x4599 * x4896;
    let x4898 = x4705 + x4845;
    let x4899 = s[32] * k[45];
    let x4900 = x4843 + x4899;
    let x4901 = x4601 * x4708;
    let x4902 = x4602 * x4898;
    let x4903 = x4603 * x4900;
    let x4904 = x4901 + x4902;
    let x4905 = x4903 + x4904;
    let x4906 = x4605 * x4905;
    let x4925 = symbody_runtime::trig::sin(s[101]);
    let x4926 = 0.8726646259971648 * x4925;
    let x4927 = k[13] * x4926;
    let x4928 = 2.0 * s[105];
    let x4929 = 1.0 / x4928;
    let x4930 = x4927 * x4929;
    let x4932 = 0.8726646259971648 * x4931;
    let x4933 = k[17] * x4932;
    let x4934 = 2.0 * x4403;
    let x4935 = 1.0 / x4934;
    let x4936 = x4933 * x4935;
    let x4938 = 0.8726646259971648 * x4937;
    let x4939 = k[21] * x4938;
    let x4940 = 2.0 * x4414;
    let x4941 = 1.0 / x4940;
    let x4942 = x4939 * x4941;
    let x4946 = -x4930;
    let x4947 = -x4936;
    let x4948 = -x4942;
    let x5003 = s[37] * k[36];
    let x5004 = s[56] * k[37];
    let x5005 = x5003 + x5004;
    let x5006 = s[57] * k[36];
    let x5007 = s[66] * k[37];
    let x5008 = x5006 + x5007;
    let x5009 = s[67] * k[36];
    let x5010 = s[39] * k[37];
    let x5011 = x5009 + x5010;
    let x5012 = qd[0] + x5005;
    let x5013 = qd[1] + x5008;
    let x5014 = qd[2] + x5011;
    let x5015 = s[126] * x5012;
    let x5016 = s[127] * x5013;
    let x5017 = s[128] * x5014;
    let x5018 = x5015 + x5016;
    let x5019 = x5017 + x5018;
    let x5020 = s[130] * x5019;
    let x5021 = s[37] * k[40];
    let x5022 = s[56] * k[41];
    let x5023 = x5021 + x5022;
    let x5024 = s[57] * k[40];
    let x5025 = s[66] * k[41];
    let x5026 = x5024 + x5025;
    let x5027 = s[67] * k[40];
    let x5028 = s[39] * k[41];
    let x5029 = x5027 + x5028;
    let x5030 = qd[0] + x5023;
    let x5031 = qd[1] + x5026;
    let x5032 = qd[2] + x5029;
    let x5033 = x4595 * x5030;
    let x5034 = x4596 * x5031;
    let x5035 = x4597 * x5032;
    let x5036 = x5033 + x5034;
    let x5037 = x5035 + x5036;
    let x5038 = x4599 * x5037;
    let x5039 = s[37] * k[44];
    let x5040 = s[56] * k[45];
    let x5041 = x5039 + x5040;
    let x5042 = s[57] * k[44];
    let x5043 = s[66] * k[45];
    let x5044 = x5042 + x5043;
    let x5045 = s[67] * k[44];
    let x5046 = s[39] * k[45];
    let x5047 = x5045 + x5046;
    let x5048 = qd[0] + x5041;
    let x5049 = qd[1] + x5044;
    let x5050 = qd[2] + x5047;
    let x5051 = x4601 * x5048;
    let x5052 = x4602 * x5049;
    let x5053 = x4603 * x5050;
    let x5054 = x5051 + x5052;
    let x5055 = x5053 + x5054;
    let x5056 = x4605 * x5055;
    let x5075 = 2.0 * x5012;
    let x5076 = 2.0 * x5013;
    let x5077 = 2.0 * x5014;
    let x5078 = 2.0 * x5020;
    let x5079 = s[130] * s[130];
    let x5080 = x5078 * x5079;
    let x5081 = 2.0 * x5030;
    let x5082 = 2.0 * x5031;
    let x5083 = 2.0 * x5032;
    let x5084 = 2.0 * x5038;
    let x5085 = x4599 * x4599;
    let x5086 = x5084 * x5085;
    let x5087 = 2.0 * x5048;
    let x5088 = 2.0 * x5049;
    let x5089 = 2.0 * x5050;
    let x5090 = 2.0 * x5056;
    let x5091 = x4605 * x4605;
    let x5092 = x5090 * x5091;
    let x5123 = 0.8726646259971648 * s[102];
    let x5124 = 0.8726646259971648 * x5123;
    let x5125 = k[13] * x5124;
    let x5126 = 2.0 * x4930;
    let x5127 = x4929 * x4929;
    let x5128 = x5126 * x5127;
    let x5129 = x4929 * x5125;
    let x5130 = x4927 * x5128;
    let x5132 = x5129 - x5130;
    let x5133 = 0.8726646259971648 * x4399;
    let x5134 = 0.8726646259971648 * x5133;
    let x5135 = k[17] * x5134;
    let x5136 = 2.0 * x4936;
    let x5137 = x4935 * x4935;
    let x5138 = x5136 * x5137;
    let x5139 = x4935 * x5135;
    let x5140 = x4933 * x5138;
    let x5142 = x5139 - x5140;
    let x5143 = 0.8726646259971648 * x4410;
    let x5144 = 0.8726646259971648 * x5143;
    let x5145 = k[21] * x5144;
    let x5146 = 2.0 * x4942;
    let x5147 = x4941 * x4941;
    let x5148 = x5146 * x5147;
    let x5149 = x4941 * x5145;
    let x5150 = x4939 * x5148;
    let x5152 = x5149 - x5150;
    let x5234 = s[75] * k[36];
    let x5235 = s[90] * k[37];
    let x5236 = x5234 + x5235;
    let x5237 = s[91] * k[36];
    let x5238 = s[98] * k[37];
    let x5239 = x5237 + x5238;
    let x5240 = s[99] * k[36];
    let x5241 = s[77] * k[37];
    let x5242 = x5240 + x5241;
    let x5243 = x5012 * x5075;
    let x5244 = s[126] * x5236;
    let x5245 = x5243 + x5244;
    let x5246 = x5013 * x5076;
    let x5247 = s[127] * x5239;
    let x5248 = x5246 + x5247;
    let x5249 = x5014 * x5077;
    let x5250 = s[128] * x5242;
    let x5251 = x5249 + x5250;
    let x5252 = x5245 + x5248;
    let x5253 = x5251 + x5252;
    let x5254 = x5019 * x5080;
    let x5256 = s[130] * x5253;
    let x5257 = x5256 - x5254;
    let x5258 = x5257 - x5132;
    let x5259 = s[75] * k[40];
    let x5260 = s[90] * k[41];
    let x5261 = x5259 + x5260;
    let x5262 = s[91] * k[40];
    let x5263 = s[98] * k[41];
    let x5264 = x5262 + x5263;
    let x5265 = s[99] * k[40];
    let x5266 = s[77] * k[41];
    let x5267 = x5265 + x5266;
    let x5268 = x5030 * x5081;
    let x5269 = x4595 * x5261;
    let x5270 = x5268 + x5269;
    let x5271 = x5031 * x5082;
    let x5272 = x4596 * x5264;
    let x5273 = x5271 + x5272;
    let x5274 = x5032 * x5083;
    let x5275 = x4597 * x5267;
    let x5276 = x5274 + x5275;
    let x5277 = x5270 + x5273;
    let x5278 = x5276 + x5277;
    let x5279 = x5037 * x5086;
    let x5281 = x4599 * x5278;
    let x5282 = x5281 - x5279;
    let x5283 = x5282 - x5142;
    let x5284 = s[75] * k[44];
    let x5285 = s[90] * k[45];
    let x5286 = x5284 + x5285;
    let x5287 = s[91] * k[44];
    let x5288 = s[98] * k[45];
    let x5289 = x5287 + x5288;
    let x5290 = s[99] * k[44];
    let x5291 = s[77] * k[45];
    let x5292 = x5290 + x5291;
    let x5293 = x5048 * x5087;
    let x5294 = x4601 * x5286;
    let x5295 = x5293 + x5294;
    let x5296 = x5049 * x5088;
    let x5297 = x4602 * x5289;
    let x5298 = x5296 + x5297;
    let x5299 = x5050 * x5089;
    let x5300 = x4603 * x5292;
    let x5301 = x5299 + x5300;
    let x5302 = x5295 + x5298;
    let x5303 = x5301 + x5302;
    let x5304 = x5055 * x5092;
    let x5306 = x4605 * x5303;
    let x5307 = x5306 - x5304;
    let x5308 = x5307 - x5152;
    let x5312 = -x5258;
    let x5313 = -x5283;
    let x5314 = -x5308;
    phi_q[26] = x4832;
    phi_q[27] = x4888;
    phi_t[3] = x4946;
    gamma[3] = x5312;
    phi[4] = x4544;
    phi_q[28] = x4600;
    phi_q[29] = x4611;
    phi_q[30] = x4617;
    phi_q[31] = x4703;
    phi_q[32] = x4780;
    phi_q[33] = x4842;
    phi_q[34] = x4897;
    phi_t[4] = x4947;
    gamma[4] = x5313;
    phi[5] = x4570;
    phi_q[35] = x4606;
    phi_q[36] = x4612;
    phi_q[37] = x4618;
    phi_q[38] = x4720;
    phi_q[39] = x4792;
    phi_q[40] = x4852;
    phi_q[41] = x4906;
    phi_t[5] = x4948;
    gamma[5] = x5314;
    phi[6] = x362;
    phi_q[42] = s[26];
    phi_q[43] = s[27];
    phi_q[44] = s[29];
    phi_q[45] = s[28];
    phi_t[6] = 0.0;
    gamma[6] = x1244;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
    let k: &[f64; 53] = k.try_into().expect("k must have 53 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = k;
    potential_into_part_0(q, out);
}
#[inline(never)]
fn potential_into_part_0(q: &[f64; 7], out: &mut [f64; 1]) {
    let x1274 = q[1] * 14.715;
    out[0] = x1274;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 53] = k.try_into().expect("k must have 53 entries");
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
    let k: &[f64; 53] = k.try_into().expect("k must have 53 entries");
    let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
    let dq: &[f64; 7] = dq.try_into().expect("dq must have n_coords entries");
    let dqd: &[f64; 7] = dqd.try_into().expect("dqd must have n_coords entries");
    let dp: &[f64; 66] = dp.try_into().expect("dp must have 66 entries");
    let phi: &mut [f64; 7] = phi.try_into().expect("phi must have 7 entries");
    let phi_q: &mut [f64; 46] = phi_q.try_into().expect("phi_q must have 46 entries");
    let phi_t: &mut [f64; 7] = phi_t.try_into().expect("phi_t must have 7 entries");
    let gamma: &mut [f64; 7] = gamma.try_into().expect("gamma must have 7 entries");
    let mut s = [0.0f64; 809];
    kinematic_tangents_shared_0(k, q, qd, t, dq, dqd, dp, &mut s);
    kinematic_tangents_shared_1(k, q, qd, t, dq, dqd, dp, &mut s);
    kinematic_tangents_part_0(k, dp, &s, phi, phi_q, phi_t);
    kinematic_tangents_part_1(k, qd, dqd, dp, &s, phi, phi_q, gamma);
    kinematic_tangents_part_2(k, dp, &s, phi_q, phi_t);
    kinematic_tangents_part_3(k, qd, dqd, dp, &s, phi, phi_q, gamma);
    kinematic_tangents_part_4(k, dp, &s, phi_q, phi_t);
    kinematic_tangents_part_5(k, qd, dqd, dp, &s, phi, phi_q, gamma);
    kinematic_tangents_part_6(k, dp, &s, phi_q, phi_t);
    kinematic_tangents_part_7(k, qd, dqd, dp, &s, phi, phi_q, gamma);
    kinematic_tangents_part_8(k, dp, &s, phi_q, phi_t);
    kinematic_tangents_part_9(k, qd, dqd, dp, &s, phi, phi_q, gamma);
    kinematic_tangents_part_10(k, dp, &s, phi_q, phi_t);
    kinematic_tangents_part_11(k, qd, dq, dqd, dp, &s, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn kinematic_tangents_shared_0(
    k: &[f64; 53],
    q: &[f64; 7],
    qd: &[f64; 7],
    t: f64,
    dq: &[f64; 7],
    dqd: &[f64; 7],
    dp: &[f64; 66],
    s: &mut [f64; 809],
) {
    let x7 = 0.8726646259971648 * t;
    s[0] = x7;
    let x153 = q[3] * q[3];
    s[1] = x153;
    let x154 = q[4] * q[4];
    s[2] = x154;
    let x156 = q[6] * q[6];
    s[3] = x156;
    let x157 = x153 + x154;
    s[4] = x157;
    let x158 = 2.0 * x157;
    s[5] = x158;
    let x160 = x158 - 1.0;
    s[6] = x160;
    let x164 = x153 + x156;
    s[7] = x164;
    let x165 = 2.0 * x164;
    s[8] = x165;
    let x166 = x165 - 1.0;
    s[9] = x166;
    let x167 = q[4] * q[5];
    s[10] = x167;
    let x168 = 2.0 * x167;
    s[11] = x168;
    let x169 = q[3] * q[6];
    s[12] = x169;
    let x171 = 2.0 * x169;
    s[13] = x171;
    let x174 = q[4] * q[6];
    s[14] = x174;
    let x175 = 2.0 * x174;
    s[15] = x175;
    let x176 = q[3] * q[5];
    s[16] = x176;
    let x177 = 2.0 * x176;
    s[17] = x177;
    let x178 = x175 + x177;
    s[18] = x178;
    let x179 = x168 + x171;
    s[19] = x179;
    let x180 = q[5] * q[6];
    s[20] = x180;
    let x181 = 2.0 * x180;
    s[21] = x181;
    let x182 = q[3] * q[4];
    s[22] = x182;
    let x184 = 2.0 * x182;
    s[23] = x184;
    let x186 = x181 - x184;
    s[24] = x186;
    let x189 = x175 - x177;
    s[25] = x189;
    let x363 = q[3] * 2.0;
    s[26] = x363;
    let x364 = q[4] * 2.0;
    s[27] = x364;
    let x365 = q[6] * 2.0;
    s[28] = x365;
    let x414 = q[5] * 2.0;
    s[29] = x414;
    let x415 = 2.0 * x363;
    s[30] = x415;
    let x520 = 2.0 * x364;
    s[31] = x520;
    let x660 = 2.0 * x365;
    s[32] = x660;
    let x782 = x363 * qd[3];
    s[33] = x782;
    let x783 = x364 * qd[4];
    s[34] = x783;
    let x785 = x365 * qd[6];
    s[35] = x785;
    let x786 = x782 + x783;
    s[36] = x786;
    let x787 = 2.0 * x786;
    s[37] = x787;
    let x788 = x782 + x785;
    s[38] = x788;
    let x789 = 2.0 * x788;
    s[39] = x789;
    let x790 = q[5] * qd[4];
    s[40] = x790;
    let x791 = q[4] * qd[5];
    s[41] = x791;
    let x792 = x790 + x791;
    s[42] = x792;
    let x793 = 2.0 * x792;
    s[43] = x793;
    let x794 = q[6] * qd[3];
    s[44] = x794;
    let x795 = q[3] * qd[6];
    s[45] = x795;
    let x796 = x794 + x795;
    s[46] = x796;
    let x797 = 2.0 * x796;
    s[47] = x797;
    let x798 = q[6] * qd[4];
    s[48] = x798;
    let x799 = q[4] * qd[6];
    s[49] = x799;
    let x800 = x798 + x799;
    s[50] = x800;
    let x801 = 2.0 * x800;
    s[51] = x801;
    let x802 = q[5] * qd[3];
    s[52] = x802;
    let x803 = q[3] * qd[5];
    s[53] = x803;
    let x804 = x802 + x803;
    s[54] = x804;
    let x805 = 2.0 * x804;
    s[55] = x805;
    let x806 = x801 + x805;
    s[56] = x806;
    let x807 = x793 + x797;
    s[57] = x807;
    let x808 = q[6] * qd[5];
    s[58] = x808;
    let x809 = q[5] * qd[6];
    s[59] = x809;
    let x810 = x808 + x809;
    s[60] = x810;
    let x811 = 2.0 * x810;
    s[61] = x811;
    let x812 = q[4] * qd[3];
    s[62] = x812;
    let x813 = q[3] * qd[4];
    s[63] = x813;
    let x814 = x812 + x813;
    s[64] = x814;
    let x815 = 2.0 * x814;
    s[65] = x815;
    let x817 = x811 - x815;
    s[66] = x817;
    let x819 = x801 - x805;
    s[67] = x819;
    let x936 = 2.0 * qd[3];
    s[68] = x936;
    let x937 = 2.0 * qd[4];
    s[69] = x937;
    let x938 = 2.0 * qd[6];
    s[70] = x938;
    let x1054 = qd[3] * x936;
    s[71] = x1054;
    let x1055 = qd[4] * x937;
    s[72] = x1055;
    let x1057 = qd[6] * x938;
    s[73] = x1057;
    let x1058 = x1054 + x1055;
    s[74] = x1058;
    let x1059 = 2.0 * x1058;
    s[75] = x1059;
    let x1060 = x1054 + x1057;
    s[76] = x1060;
    let x1061 = 2.0 * x1060;
    s[77] = x1061;
    let x1062 = qd[4] * qd[5];
    s[78] = x1062;
    let x1063 = x1062 + x1062;
    s[79] = x1063;
    let x1064 = 2.0 * x1063;
    s[80] = x1064;
    let x1065 = qd[3] * qd[6];
    s[81] = x1065;
    let x1066 = x1065 + x1065;
    s[82] = x1066;
    let x1067 = 2.0 * x1066;
    s[83] = x1067;
    let x1068 = qd[4] * qd[6];
    s[84] = x1068;
    let x1069 = x1068 + x1068;
    s[85] = x1069;
    let x1070 = 2.0 * x1069;
    s[86] = x1070;
    let x1071 = qd[3] * qd[5];
    s[87] = x1071;
    let x1072 = x1071 + x1071;
    s[88] = x1072;
    let x1073 = 2.0 * x1072;
    s[89] = x1073;
    let x1074 = x1070 + x1073;
    s[90] = x1074;
    let x1075 = x1064 + x1067;
    s[91] = x1075;
    let x1076 = qd[5] * qd[6];
    s[92] = x1076;
    let x1077 = x1076 + x1076;
    s[93] = x1077;
    let x1078 = 2.0 * x1077;
    s[94] = x1078;
    let x1079 = qd[3] * qd[4];
    s[95] = x1079;
    let x1080 = x1079 + x1079;
    s[96] = x1080;
    let x1081 = 2.0 * x1080;
    s[97] = x1081;
    let x1083 = x1078 - x1081;
    s[98] = x1083;
    let x1085 = x1070 - x1073;
    s[99] = x1085;
    let x1778 = dp[44] + dp[45];
    s[100] = x1778;
    let x1788 = dp[48] + dp[49];
    s[101] = x1788;
    let x1798 = dp[52] + dp[53];
    s[102] = x1798;
    let x1808 = dp[56] + dp[57];
    s[103] = x1808;
    let x1818 = dp[60] + dp[61];
    s[104] = x1818;
    let x1828 = dp[64] + dp[65];
    s[105] = x1828;
    let x1838 = x363 * dq[3];
    s[106] = x1838;
    let x1839 = x364 * dq[4];
    s[107] = x1839;
    let x1841 = x365 * dq[6];
    s[108] = x1841;
    let x1842 = x1838 + x1839;
    s[109] = x1842;
    let x1843 = 2.0 * x1842;
    s[110] = x1843;
    let x1844 = x1838 + x1841;
    s[111] = x1844;
    let x1845 = 2.0 * x1844;
    s[112] = x1845;
    let x1846 = q[5] * dq[4];
    s[113] = x1846;
    let x1847 = q[4] * dq[5];
    s[114] = x1847;
    let x1848 = x1846 + x1847;
    s[115] = x1848;
    let x1849 = 2.0 * x1848;
    s[116] = x1849;
    let x1850 = q[6] * dq[3];
    s[117] = x1850;
    let x1851 = q[3] * dq[6];
    s[118] = x1851;
    let x1852 = x1850 + x1851;
    s[119] = x1852;
    let x1853 = 2.0 * x1852;
    s[120] = x1853;
    let x1854 = q[6] * dq[4];
    s[121] = x1854;
    let x1855 = q[4] * dq[6];
    s[122] = x1855;
    let x1856 = x1854 + x1855;
    s[123] = x1856;
    let x1857 = 2.0 * x1856;
    s[124] = x1857;
    let x1858 = q[5] * dq[3];
    s[125] = x1858;
    let x1859 = q[3] * dq[5];
    s[126] = x1859;
    let x1860 = x1858 + x1859;
    s[127] = x1860;
    let x1861 = 2.0 * x1860;
    s[128] = x1861;
    let x1862 = x1857 + x1861;
    s[129] = x1862;
    let x1863 = x1849 + x1853;
    s[130] = x1863;
    let x1864 = q[6] * dq[5];
    s[131] = x1864;
    let x1865 = q[5] * dq[6];
    s[132] = x1865;
    let x1866 = x1864 + x1865;
    s[133] = x1866;
    let x1867 = 2.0 * x1866;
    s[134] = x1867;
    let x1868 = q[4] * dq[3];
    s[135] = x1868;
    let x1869 = q[3] * dq[4];
    s[136] = x1869;
    let x1870 = x1868 + x1869;
    s[137] = x1870;
    let x1871 = 2.0 * x1870;
    s[138] = x1871;
    let x1873 = x1867 - x1871;
    s[139] = x1873;
    let x1875 = x1857 - x1861;
    s[140] = x1875;
    let x1877 = x160 * dp[20];
    s[141] = x1877;
    let x1880 = x178 * dp[21];
    s[142] = x1880;
    let x1884 = x179 * dp[20];
    s[143] = x1884;
    let x1887 = x186 * dp[21];
    s[144] = x1887;
    let x1891 = x189 * dp[20];
    s[145] = x1891;
    let x1894 = x166 * dp[21];
    s[146] = x1894;
    let x1913 = x160 * dp[24];
    s[147] = x1913;
    let x1916 = x178 * dp[25];
    s[148] = x1916;
    let x1920 = x179 * dp[24];
    s[149] = x1920;
    let x1923 = x186 * dp[25];
    s[150] = x1923;
    let x1927 = x189 * dp[24];
    s[151] = x1927;
    let x1930 = x166 * dp[25];
    s[152] = x1930;
    let x1949 = x160 * dp[28];
    s[153] = x1949;
    let x1952 = x178 * dp[29];
    s[154] = x1952;
    let x1956 = x179 * dp[28];
    s[155] = x1956;
    let x1959 = x186 * dp[29];
    s[156] = x1959;
    let x1963 = x189 * dp[28];
    s[157] = x1963;
    let x1966 = x166 * dp[29];
    s[158] = x1966;
    let x1985 = x160 * dp[32];
    s[159] = x1985;
    let x1988 = x178 * dp[33];
    s[160] = x1988;
    let x1992 = x179 * dp[32];
    s[161] = x1992;
    let x1995 = x186 * dp[33];
    s[162] = x1995;
    let x1999 = x189 * dp[32];
    s[163] = x1999;
    let x2002 = x166 * dp[33];
    s[164] = x2002;
    let x2021 = x160 * dp[36];
    s[165] = x2021;
    let x2024 = x178 * dp[37];
    s[166] = x2024;
    let x2028 = x179 * dp[36];
    s[167] = x2028;
    let x2031 = x186 * dp[37];
    s[168] = x2031;
    let x2035 = x189 * dp[36];
    s[169] = x2035;
    let x2038 = x166 * dp[37];
    s[170] = x2038;
    let x2057 = x160 * dp[40];
    s[171] = x2057;
    let x2060 = x178 * dp[41];
    s[172] = x2060;
    let x2064 = x179 * dp[40];
    s[173] = x2064;
    let x2067 = x186 * dp[41];
    s[174] = x2067;
    let x2071 = x189 * dp[40];
    s[175] = x2071;
    let x2074 = x166 * dp[41];
    s[176] = x2074;
    let x2094 = 2.0 * dq[3];
    s[177] = x2094;
    let x2095 = 2.0 * dq[4];
    s[178] = x2095;
    let x2096 = 2.0 * dq[6];
    s[179] = x2096;
    let x2205 = 2.0 * dq[5];
    s[180] = x2205;
    let x2206 = 2.0 * x2094;
    s[181] = x2206;
    let x2435 = 2.0 * x2095;
    s[182] = x2435;
    let x2736 = 2.0 * x2096;
    s[183] = x2736;
    let x2935 = qd[3] * x2094;
    s[184] = x2935;
    let x2936 = x363 * dqd[3];
    s[185] = x2936;
    let x2937 = x2935 + x2936;
    s[186] = x2937;
    let x2938 = qd[4] * x2095;
    s[187] = x2938;
    let x2939 = x364 * dqd[4];
    s[188] = x2939;
    let x2940 = x2938 + x2939;
    s[189] = x2940;
    let x2941 = qd[6] * x2096;
    s[190] = x2941;
    let x2942 = x365 * dqd[6];
    s[191] = x2942;
    let x2943 = x2941 + x2942;
    s[192] = x2943;
    let x2944 = x2937 + x2940;
    s[193] = x2944;
    let x2945 = 2.0 * x2944;
    s[194] = x2945;
    let x2946 = x2937 + x2943;
    s[195] = x2946;
    let x2947 = 2.0 * x2946;
    s[196] = x2947;
    let x2948 = qd[4] * dq[5];
    s[197] = x2948;
    let x2949 = q[5] * dqd[4];
    s[198] = x2949;
    let x2950 = x2948 + x2949;
    s[199] = x2950;
    let x2951 = qd[5] * dq[4];
    s[200] = x2951;
    let x2952 = q[4] * dqd[5];
    s[201] = x2952;
    let x2953 = x2951 + x2952;
    s[202] = x2953;
    let x2954 = x2950 + x2953;
    s[203] = x2954;
    let x2955 = 2.0 * x2954;
    s[204] = x2955;
    let x2956 = qd[3] * dq[6];
    s[205] = x2956;
    let x2957 = q[6] * dqd[3];
    s[206] = x2957;
    let x2958 = x2956 + x2957;
    s[207] = x2958;
    let x2959 = qd[6] * dq[3];
    s[208] = x2959;
    let x2960 = q[3] * dqd[6];
    s[209] = x2960;
    let x2961 = x2959 + x2960;
    s[210] = x2961;
    let x2962 = x2958 + x2961;
    s[211] = x2962;
    let x2963 = 2.0 * x2962;
    s[212] = x2963;
    let x2964 = qd[4] * dq[6];
    s[213] = x2964;
    let x2965 = q[6] * dqd[4];
    s[214] = x2965;
    let x2966 = x2964 + x2965;
    s[215] = x2966;
    let x2967 = qd[6] * dq[4];
    s[216] = x2967;
    let x2968 = q[4] * dqd[6];
    s[217] = x2968;
    let x2969 = x2967 + x2968;
    s[218] = x2969;
    let x2970 = x2966 + x2969;
    s[219] = x2970;
    let x2971 = 2.0 * x2970;
    s[220] = x2971;
    let x2972 = qd[3] * dq[5];
    s[221] = x2972;
    let x2973 = q[5] * dqd[3];
    s[222] = x2973;
    let x2974 = x2972 + x2973;
    s[223] = x2974;
    let x2975 = qd[5] * dq[3];
    s[224] = x2975;
    let x2976 = q[3] * dqd[5];
    s[225] = x2976;
    let x2977 = x2975 + x2976;
    s[226] = x2977;
    let x2978 = x2974 + x2977;
    s[227] = x2978;
    let x2979 = 2.0 * x2978;
    s[228] = x2979;
    let x2980 = x2971 + x2979;
    s[229] = x2980;
    let x2981 = x2955 + x2963;
    s[230] = x2981;
    let x2982 = qd[5] * dq[6];
    s[231] = x2982;
    let x2983 = q[6] * dqd[5];
    s[232] = x2983;
    let x2984 = x2982 + x2983;
    s[233] = x2984;
    let x2985 = qd[6] * dq[5];
    s[234] = x2985;
    let x2986 = q[5] * dqd[6];
    s[235] = x2986;
    let x2987 = x2985 + x2986;
    s[236] = x2987;
    let x2988 = x2984 + x2987;
    s[237] = x2988;
    let x2989 = 2.0 * x2988;
    s[238] = x2989;
    let x2990 = qd[3] * dq[4];
    s[239] = x2990;
    let x2991 = q[4] * dqd[3];
    s[240] = x2991;
    let x2992 = x2990 + x2991;
    s[241] = x2992;
    let x2993 = qd[4] * dq[3];
    s[242] = x2993;
    let x2994 = q[3] * dqd[4];
    s[243] = x2994;
    let x2995 = x2993 + x2994;
    s[244] = x2995;
    let x2996 = x2992 + x2995;
    s[245] = x2996;
    let x2997 = 2.0 * x2996;
    s[246] = x2997;
    let x2999 = x2989 - x2997;
    s[247] = x2999;
    let x3001 = x2971 - x2979;
    s[248] = x3001;
    let x3236 = 2.0 * dqd[3];
    s[249] = x3236;
    let x3237 = 2.0 * dqd[4];
    s[250] = x3237;
    let x3238 = 2.0 * dqd[6];
    s[251] = x3238;
    let x3462 = x936 * dqd[3];
    s[252] = x3462;
    let x3463 = qd[3] * x3236;
    s[253] = x3463;
    let x3464 = x3462 + x3463;
    s[254] = x3464;
    let x3465 = x937 * dqd[4];
    s[255] = x3465;
    let x3466 = qd[4] * x3237;
    s[256] = x3466;
    let x3467 = x3465 + x3466;
    s[257] = x3467;
    let x3471 = x938 * dqd[6];
    s[258] = x3471;
    let x3472 = qd[6] * x3238;
    s[259] = x3472;
    let x3473 = x3471 + x3472;
    s[260] = x3473;
    let x3474 = x3464 + x3467;
    s[261] = x3474;
    let x3475 = 2.0 * x3474;
    s[262] = x3475;
    let x3476 = x3464 + x3473;
    s[263] = x3476;
    let x3477 = 2.0 * x3476;
    s[264] = x3477;
    let x3478 = qd[5] * dqd[4];
    s[265] = x3478;
    let x3479 = qd[4] * dqd[5];
    s[266] = x3479;
    let x3480 = x3478 + x3479;
    s[267] = x3480;
    let x3481 = x3480 + x3480;
    s[268] = x3481;
    let x3482 = 2.0 * x3481;
    s[269] = x3482;
    let x3483 = qd[6] * dqd[3];
    s[270] = x3483;
    let x3484 = qd[3] * dqd[6];
    s[271] = x3484;
    let x3485 = x3483 + x3484;
    s[272] = x3485;
    let x3486 = x3485 + x3485;
    s[273] = x3486;
    let x3487 = 2.0 * x3486;
    s[274] = x3487;
    let x3488 = qd[6] * dqd[4];
    s[275] = x3488;
    let x3489 = qd[4] * dqd[6];
    s[276] = x3489;
    let x3490 = x3488 + x3489;
    s[277] = x3490;
    let x3491 = x3490 + x3490;
    s[278] = x3491;
    let x3492 = 2.0 * x3491;
    s[279] = x3492;
    let x3493 = qd[5] * dqd[3];
    s[280] = x3493;
    let x3494 = qd[3] * dqd[5];
    s[281] = x3494;
    let x3495 = x3493 + x3494;
    s[282] = x3495;
    let x3496 = x3495 + x3495;
    s[283] = x3496;
    let x3497 = 2.0 * x3496;
    s[284] = x3497;
    let x3498 = x3492 + x3497;
    s[285] = x3498;
    let x3499 = x3482 + x3487;
    s[286] = x3499;
    let x3500 = qd[6] * dqd[5];
    s[287] = x3500;
    let x3501 = qd[5] * dqd[6];
    s[288] = x3501;
    let x3502 = x3500 + x3501;
    s[289] = x3502;
    let x3503 = x3502 + x3502;
    s[290] = x3503;
    let x3504 = 2.0 * x3503;
    s[291] = x3504;
    let x3505 = qd[4] * dqd[3];
    s[292] = x3505;
    let x3506 = qd[3] * dqd[4];
    s[293] = x3506;
    let x3507 = x3505 + x3506;
    s[294] = x3507;
    let x3508 = x3507 + x3507;
    s[295] = x3508;
    let x3509 = 2.0 * x3508;
    s[296] = x3509;
    let x3511 = x3504 - x3509;
    s[297] = x3511;
    let x3513 = x3492 - x3497;
    s[298] = x3513;
    let x4353 = x7 + k[3];
    s[299] = x4353;
    let x4354 = k[2] + x4353;
    s[300] = x4354;
    let (x4907, x4355) = symbody_runtime::trig::sin_cos(x4354);
    s[485] = x4907;
    s[301] = x4355;
    let x4356 = k[1] * x4355;
    s[302] = x4356;
    let x4358 = k[0] - x4356;
    s[303] = x4358;
    let x4359 = x4358.sqrt();
    s[304] = x4359;
    let x4364 = x7 + k[7];
    s[305] = x4364;
    let x4365 = k[6] + x4364;
    s[306] = x4365;
    let (x4913, x4366) = symbody_runtime::trig::sin_cos(x4365);
    s[490] = x4913;
    s[307] = x4366;
    let x4367 = k[5] * x4366;
    s[308] = x4367;
    let x4369 = k[4] - x4367;
    s[309] = x4369;
    let x4370 = x4369.sqrt();
    s[310] = x4370;
    let x4375 = x7 + k[11];
    s[311] = x4375;
    let x4376 = k[10] + x4375;
    s[312] = x4376;
    let (x4919, x4377) = symbody_runtime::trig::sin_cos(x4376);
    s[495] = x4919;
    s[313] = x4377;
    let x4378 = k[9] * x4377;
    s[314] = x4378;
    let x4380 = k[8] - x4378;
    s[315] = x4380;
    let x4381 = x4380.sqrt();
    s[316] = x4381;
    let x4386 = x7 + k[15];
    s[317] = x4386;
    let x4387 = k[14] + x4386;
    s[318] = x4387;
    let (x4925, x4388) = symbody_runtime::trig::sin_cos(x4387);
    s[500] = x4925;
    s[319] = x4388;
    let x4389 = k[13] * x4388;
    s[320] = x4389;
    let x4391 = k[12] - x4389;
    s[321] = x4391;
    let x4392 = x4391.sqrt();
    s[322] = x4392;
    let x4397 = x7 + k[19];
    s[323] = x4397;
    let x4398 = k[18] + x4397;
    s[324] = x4398;
    let (x4931, x4399) = symbody_runtime::trig::sin_cos(x4398);
    s[505] = x4931;
    s[325] = x4399;
    let x4400 = k[17] * x4399;
    s[326] = x4400;
    let x4402 = k[16] - x4400;
    s[327] = x4402;
    let x4403 = x4402.sqrt();
    s[328] = x4403;
    let x4408 = x7 + k[23];
    s[329] = x4408;
    let x4409 = k[22] + x4408;
    s[330] = x4409;
    let (x4937, x4410) = symbody_runtime::trig::sin_cos(x4409);
    s[510] = x4937;
    s[331] = x4410;
    let x4411 = k[21] * x4410;
    s[332] = x4411;
    let x4413 = k[20] - x4411;
    s[333] = x4413;
    let x4414 = x4413.sqrt();
    s[334] = x4414;
    let x4417 = x160 * k[24];
    s[335] = x4417;
    let x4418 = x178 * k[25];
    s[336] = x4418;
    let x4419 = x4417 + x4418;
    s[337] = x4419;
    let x4420 = x179 * k[24];
    s[338] = x4420;
    let x4421 = x186 * k[25];
    s[339] = x4421;
    let x4422 = x4420 + x4421;
    s[340] = x4422;
    let x4423 = x189 * k[24];
    s[341] = x4423;
    let x4424 = x166 * k[25];
    s[342] = x4424;
    let x4425 = x4423 + x4424;
    s[343] = x4425;
    let x4426 = q[0] + x4419;
    s[344] = x4426;
    let x4427 = q[1] + x4422;
    s[345] = x4427;
    let x4428 = q[2] + x4425;
    s[346] = x4428;
    let x4430 = x4426 + k[26];
    s[347] = x4430;
    let x4432 = x4428 + k[27];
    s[348] = x4432;
    let x4433 = x4430 * x4430;
    s[349] = x4433;
    let x4434 = x4427 * x4427;
    s[350] = x4434;
    let x4435 = x4432 * x4432;
    s[351] = x4435;
    let x4436 = x4433 + x4434;
    s[352] = x4436;
    let x4437 = x4435 + x4436;
    s[353] = x4437;
    let x4438 = x4437.sqrt();
    s[354] = x4438;
    let x4443 = x160 * k[28];
    s[355] = x4443;
    let x4444 = x178 * k[29];
    s[356] = x4444;
    let x4445 = x4443 + x4444;
    s[357] = x4445;
    let x4446 = x179 * k[28];
    s[358] = x4446;
    let x4447 = x186 * k[29];
    s[359] = x4447;
    let x4448 = x4446 + x4447;
    s[360] = x4448;
    let x4449 = x189 * k[28];
    s[361] = x4449;
    let x4450 = x166 * k[29];
    s[362] = x4450;
    let x4451 = x4449 + x4450;
    s[363] = x4451;
    let x4452 = q[0] + x4445;
    s[364] = x4452;
    let x4453 = q[1] + x4448;
    s[365] = x4453;
    let x4454 = q[2] + x4451;
    s[366] = x4454;
    let x4456 = x4452 + k[30];
    s[367] = x4456;
    let x4458 = x4454 + k[31];
    s[368] = x4458;
    let x4459 = x4456 * x4456;
    s[369] = x4459;
    let x4460 = x4453 * x4453;
    s[370] = x4460;
    let x4461 = x4458 * x4458;
    s[371] = x4461;
    let x4462 = x4459 + x4460;
    s[372] = x4462;
    let x4463 = x4461 + x4462;
    s[373] = x4463;
    let x4464 = x4463.sqrt();
    s[374] = x4464;
    let x4469 = x160 * k[32];
    s[375] = x4469;
    let x4470 = x178 * k[33];
    s[376] = x4470;
    let x4471 = x4469 + x4470;
    s[377] = x4471;
    let x4472 = x179 * k[32];
    s[378] = x4472;
    let x4473 = x186 * k[33];
    s[379] = x4473;
    let x4474 = x4472 + x4473;
    s[380] = x4474;
    let x4475 = x189 * k[32];
    s[381] = x4475;
    let x4476 = x166 * k[33];
    s[382] = x4476;
    let x4477 = x4475 + x4476;
    s[383] = x4477;
    let x4478 = q[0] + x4471;
    s[384] = x4478;
    let x4479 = q[1] + x4474;
    s[385] = x4479;
    let x4480 = q[2] + x4477;
    s[386] = x4480;
    let x4482 = x4478 + k[34];
    s[387] = x4482;
    let x4484 = x4480 + k[35];
    s[388] = x4484;
    let x4485 = x4482 * x4482;
    s[389] = x4485;
    let x4486 = x4479 * x4479;
    s[390] = x4486;
    let x4487 = x4484 * x4484;
    s[391] = x4487;
    let x4488 = x4485 + x4486;
    s[392] = x4488;
    let x4489 = x4487 + x4488;
    s[393] = x4489;
    let x4490 = x4489.sqrt();
    s[394] = x4490;
    let x4495 = x160 * k[36];
    s[395] = x4495;
    let x4496 = x178 * k[37];
    s[396] = x4496;
    let x4497 = x4495 + x4496;
    s[397] = x4497;
    let x4498 = x179 * k[36];
    s[398] = x4498;
    let x4499 = x186 * k[37];
    s[399] = x4499;
    let x4500 = x4498 + x4499;
    s[400] = x4500;
    let x4501 = x189 * k[36];
    s[401] = x4501;
    let x4502 = x166 * k[37];
    s[402] = x4502;
    let x4503 = x4501 + x4502;
    s[403] = x4503;
    let x4504 = q[0] + x4497;
    s[404] = x4504;
    let x4505 = q[1] + x4500;
    s[405] = x4505;
    let x4506 = q[2] + x4503;
    s[406] = x4506;
    let x4508 = x4504 + k[38];
    s[407] = x4508;
    let x4510 = x4506 + k[39];
    s[408] = x4510;
    let x4511 = x4508 * x4508;
    s[409] = x4511;
    let x4512 = x4505 * x4505;
    s[410] = x4512;
    let x4513 = x4510 * x4510;
    s[411] = x4513;
    let x4514 = x4511 + x4512;
    s[412] = x4514;
    let x4515 = x4513 + x4514;
    s[413] = x4515;
    let x4516 = x4515.sqrt();
    s[414] = x4516;
    let x4521 = x160 * k[40];
    s[415] = x4521;
    let x4522 = x178 * k[41];
    s[416] = x4522;
    let x4523 = x4521 + x4522;
    s[417] = x4523;
    let x4524 = x179 * k[40];
    s[418] = x4524;
    let x4525 = x186 * k[41];
    s[419] = x4525;
    let x4526 = x4524 + x4525;
    s[420] = x4526;
    let x4527 = x189 * k[40];
    s[421] = x4527;
    let x4528 = x166 * k[41];
    s[422] = x4528;
    let x4529 = x4527 + x4528;
    s[423] = x4529;
    let x4530 = q[0] + x4523;
    s[424] = x4530;
    let x4531 = q[1] + x4526;
    s[425] = x4531;
    let x4532 = q[2] + x4529;
    s[426] = x4532;
    let x4534 = x4530 + k[42];
    s[427] = x4534;
    let x4536 = x4532 + k[43];
    s[428] = x4536;
    let x4537 = x4534 * x4534;
    s[429] = x4537;
    let x4538 = x4531 * x4531;
    s[430] = x4538;
    let x4539 = x4536 * x4536;
    s[431] = x4539;
    let x4540 = x4537 + x4538;
    s[432] = x4540;
    let x4541 = x4539 + x4540;
    s[433] = x4541;
    let x4542 = x4541.sqrt();
    s[434] = x4542;
    let x4547 = x160 * k[44];
    s[435] = x4547;
    let x4548 = x178 * k[45];
    s[436] = x4548;
    let x4549 = x4547 + x4548;
    s[437] = x4549;
    let x4550 = x179 * k[44];
    s[438] = x4550;
    let x4551 = x186 * k[45];
    s[439] = x4551;
    let x4552 = x4550 + x4551;
    s[440] = x4552;
    let x4553 = x189 * k[44];
    s[441] = x4553;
    let x4554 = x166 * k[45];
    s[442] = x4554;
    let x4555 = x4553 + x4554;
    s[443] = x4555;
    let x4556 = q[0] + x4549;
    s[444] = x4556;
    let x4557 = q[1] + x4552;
    s[445] = x4557;
    let x4558 = q[2] + x4555;
    s[446] = x4558;
    let x4560 = x4556 + k[46];
    s[447] = x4560;
    let x4562 = x4558 + k[47];
    s[448] = x4562;
    let x4563 = x4560 * x4560;
    s[449] = x4563;
    let x4564 = x4557 * x4557;
    s[450] = x4564;
    let x4565 = x4562 * x4562;
    s[451] = x4565;
    let x4566 = x4563 + x4564;
    s[452] = x4566;
    let x4567 = x4565 + x4566;
    s[453] = x4567;
    let x4568 = x4567.sqrt();
    s[454] = x4568;
    let x4571 = 2.0 * x4430;
    s[455] = x4571;
    let x4572 = 2.0 * x4427;
    s[456] = x4572;
    let x4573 = 2.0 * x4432;
    s[457] = x4573;
    let x4574 = 2.0 * x4438;
    s[458] = x4574;
    let x4575 = 1.0 / x4574;
    s[459] = x4575;
    let x4577 = 2.0 * x4456;
    s[460] = x4577;
    let x4578 = 2.0 * x4453;
    s[461] = x4578;
    let x4579 = 2.0 * x4458;
    s[462] = x4579;
    let x4580 = 2.0 * x4464;
    s[463] = x4580;
    let x4581 = 1.0 / x4580;
    s[464] = x4581;
    let x4583 = 2.0 * x4482;
    s[465] = x4583;
    let x4584 = 2.0 * x4479;
    s[466] = x4584;
    let x4585 = 2.0 * x4484;
    s[467] = x4585;
    let x4586 = 2.0 * x4490;
    s[468] = x4586;
    let x4587 = 1.0 / x4586;
    s[469] = x4587;
    let x4589 = 2.0 * x4508;
    s[470] = x4589;
    let x4590 = 2.0 * x4505;
    s[471] = x4590;
    let x4591 = 2.0 * x4510;
    s[472] = x4591;
    let x4592 = 2.0 * x4516;
    s[473] = x4592;
    let x4593 = 1.0 / x4592;
    s[474] = x4593;
    let x4595 = 2.0 * x4534;
    s[475] = x4595;
    let x4596 = 2.0 * x4531;
    s[476] = x4596;
    let x4597 = 2.0 * x4536;
    s[477] = x4597;
    let x4598 = 2.0 * x4542;
    s[478] = x4598;
    let x4599 = 1.0 / x4598;
    s[479] = x4599;
    let x4601 = 2.0 * x4560;
    s[480] = x4601;
    let x4602 = 2.0 * x4557;
    s[481] = x4602;
    let x4603 = 2.0 * x4562;
    s[482] = x4603;
    let x4604 = 2.0 * x4568;
    s[483] = x4604;
    let x4605 = 1.0 / x4604;
    s[484] = x4605;
    let x4908 = 0.8726646259971648 * x4907;
    s[486] = x4908;
    let x4909 = k[1] * x4908;
    s[487] = x4909;
    let x4910 = 2.0 * x4359;
    s[488] = x4910;
    let x4911 = 1.0 / x4910;
    s[489] = x4911;
    let x4914 = 0.8726646259971648 * x4913;
    s[491] = x4914;
    let x4915 = k[5] * x4914;
    s[492] = x4915;
    let x4916 = 2.0 * x4370;
    s[493] = x4916;
    let x4917 = 1.0 / x4916;
    s[494] = x4917;
    let x4920 = 0.8726646259971648 * x4919;
    s[496] = x4920;
    let x4921 = k[9] * x4920;
    s[497] = x4921;
    let x4922 = 2.0 * x4381;
    s[498] = x4922;
    let x4923 = 1.0 / x4922;
    s[499] = x4923;
    let x4926 = 0.8726646259971648 * x4925;
    s[501] = x4926;
    let x4927 = k[13] * x4926;
    s[502] = x4927;
    let x4928 = 2.0 * x4392;
    s[503] = x4928;
    let x4929 = 1.0 / x4928;
    s[504] = x4929;
    let x4932 = 0.8726646259971648 * x4931;
    s[506] = x4932;
    let x4933 = k[17] * x4932;
    s[507] = x4933;
    let x4934 = 2.0 * x4403;
    s[508] = x4934;
    let x4935 = 1.0 / x4934;
    s[509] = x4935;
    let x4938 = 0.8726646259971648 * x4937;
    s[511] = x4938;
    let x4939 = k[21] * x4938;
    s[512] = x4939;
    let x4940 = 2.0 * x4414;
    s[513] = x4940;
    let x4941 = 1.0 / x4940;
    s[514] = x4941;
    let x5061 = x4575 * x4575;
    s[515] = x5061;
    let x5067 = x4581 * x4581;
    s[516] = x5067;
    let x5073 = x4587 * x4587;
    s[517] = x5073;
    let x5079 = x4593 * x4593;
    s[518] = x5079;
    let x5085 = x4599 * x4599;
    s[519] = x5085;
    let x5091 = x4605 * x4605;
    s[520] = x5091;
    let x5097 = x4911 * x4911;
    s[521] = x5097;
    let x5107 = x4917 * x4917;
    s[522] = x5107;
    let x5117 = x4923 * x4923;
    s[523] = x5117;
    let x5127 = x4929 * x4929;
    s[524] = x5127;
    let x5137 = x4935 * x4935;
    s[525] = x5137;
    let x5147 = x4941 * x4941;
    s[526] = x5147;
    let x5519 = x1778 * x4907;
    s[527] = x5519;
    let x5520 = dp[43] * x4355;
    s[528] = x5520;
    let x5521 = k[1] * x5519;
    s[529] = x5521;
    let x5523 = x5520 - x5521;
    s[530] = x5523;
    let x5525 = dp[42] - x5523;
    s[531] = x5525;
    let x5526 = x4911 * x5525;
    s[532] = x5526;
    let x5527 = x1788 * x4913;
    s[533] = x5527;
    let x5528 = dp[47] * x4366;
    s[534] = x5528;
    let x5529 = k[5] * x5527;
    s[535] = x5529;
    let x5531 = x5528 - x5529;
    s[536] = x5531;
    let x5533 = dp[46] - x5531;
    s[537] = x5533;
    let x5534 = x4917 * x5533;
    s[538] = x5534;
    let x5535 = x1798 * x4919;
    s[539] = x5535;
    let x5536 = dp[51] * x4377;
    s[540] = x5536;
    let x5537 = k[9] * x5535;
    s[541] = x5537;
    let x5539 = x5536 - x5537;
    s[542] = x5539;
    let x5541 = dp[50] - x5539;
    s[543] = x5541;
    let x5542 = x4923 * x5541;
    s[544] = x5542;
    let x5543 = x1808 * x4925;
    s[545] = x5543;
    let x5544 = dp[55] * x4388;
    s[546] = x5544;
    let x5545 = k[13] * x5543;
    s[547] = x5545;
    let x5547 = x5544 - x5545;
    s[548] = x5547;
    let x5549 = dp[54] - x5547;
    s[549] = x5549;
    let x5550 = x4929 * x5549;
    s[550] = x5550;
    let x5551 = x1818 * x4931;
    s[551] = x5551;
    let x5552 = dp[59] * x4399;
    s[552] = x5552;
    let x5553 = k[17] * x5551;
    s[553] = x5553;
    let x5555 = x5552 - x5553;
    s[554] = x5555;
    let x5557 = dp[58] - x5555;
    s[555] = x5557;
    let x5558 = x4935 * x5557;
    s[556] = x5558;
    let x5559 = x1828 * x4937;
    s[557] = x5559;
    let x5560 = dp[63] * x4410;
    s[558] = x5560;
    let x5561 = k[21] * x5559;
    s[559] = x5561;
    let x5563 = x5560 - x5561;
    s[560] = x5563;
    let x5565 = dp[62] - x5563;
    s[561] = x5565;
    let x5566 = x4941 * x5565;
    s[562] = x5566;
    let x5567 = x1843 * k[24];
    s[563] = x5567;
    let x5568 = x1877 + x5567;
    s[564] = x5568;
    let x5569 = x1862 * k[25];
    s[565] = x5569;
    let x5570 = x1880 + x5569;
    s[566] = x5570;
    let x5571 = x5568 + x5570;
    s[567] = x5571;
    let x5572 = x1863 * k[24];
    s[568] = x5572;
    let x5573 = x1884 + x5572;
    s[569] = x5573;
    let x5574 = x1873 * k[25];
    s[570] = x5574;
    let x5575 = x1887 + x5574;
    s[571] = x5575;
    let x5576 = x5573 + x5575;
    s[572] = x5576;
    let x5577 = x1875 * k[24];
    s[573] = x5577;
    let x5578 = x1891 + x5577;
    s[574] = x5578;
    let x5579 = x1845 * k[25];
    s[575] = x5579;
    let x5580 = x1894 + x5579;
    s[576] = x5580;
    let x5581 = x5578 + x5580;
    s[577] = x5581;
    let x5582 = dq[0] + x5571;
    s[578] = x5582;
    let x5583 = dq[1] + x5576;
    s[579] = x5583;
    let x5584 = dq[2] + x5581;
    s[580] = x5584;
    let x5585 = x5582 - dp[18];
    s[581] = x5585;
    let x5586 = x5584 - dp[19];
    s[582] = x5586;
    let x5587 = x4571 * x5585;
    s[583] = x5587;
    let x5588 = x4572 * x5583;
    s[584] = x5588;
    let x5589 = x4573 * x5586;
    s[585] = x5589;
    let x5590 = x5587 + x5588;
    s[586] = x5590;
    let x5591 = x5589 + x5590;
    s[587] = x5591;
    let x5592 = x4575 * x5591;
    s[588] = x5592;
    let x5595 = x1843 * k[28];
    s[589] = x5595;
    let x5596 = x1913 + x5595;
    s[590] = x5596;
    let x5597 = x1862 * k[29];
    s[591] = x5597;
    let x5598 = x1916 + x5597;
    s[592] = x5598;
    let x5599 = x5596 + x5598;
    s[593] = x5599;
    let x5600 = x1863 * k[28];
    s[594] = x5600;
    let x5601 = x1920 + x5600;
    s[595] = x5601;
    let x5602 = x1873 * k[29];
    s[596] = x5602;
    let x5603 = x1923 + x5602;
    s[597] = x5603;
    let x5604 = x5601 + x5603;
    s[598] = x5604;
    let x5605 = x1875 * k[28];
    s[599] = x5605;
}
#[inline(never)]
fn kinematic_tangents_shared_1(
    k: &[f64; 53],
    _q: &[f64; 7],
    _qd: &[f64; 7],
    _t: f64,
    dq: &[f64; 7],
    _dqd: &[f64; 7],
    dp: &[f64; 66],
    s: &mut [f64; 809],
) {
    let x5606 = s[151] + s[599];
    s[600] = x5606;
    let x5607 = s[112] * k[29];
    s[601] = x5607;
    let x5608 = s[152] + x5607;
    s[602] = x5608;
    let x5609 = x5606 + x5608;
    s[603] = x5609;
    let x5610 = dq[0] + s[593];
    s[604] = x5610;
    let x5611 = dq[1] + s[598];
    s[605] = x5611;
    let x5612 = dq[2] + x5609;
    s[606] = x5612;
    let x5613 = x5610 - dp[22];
    s[607] = x5613;
    let x5614 = x5612 - dp[23];
    s[608] = x5614;
    let x5615 = s[460] * x5613;
    s[609] = x5615;
    let x5616 = s[461] * x5611;
    s[610] = x5616;
    let x5617 = s[462] * x5614;
    s[611] = x5617;
    let x5618 = x5615 + x5616;
    s[612] = x5618;
    let x5619 = x5617 + x5618;
    s[613] = x5619;
    let x5620 = s[464] * x5619;
    s[614] = x5620;
    let x5623 = s[110] * k[32];
    s[615] = x5623;
    let x5624 = s[153] + x5623;
    s[616] = x5624;
    let x5625 = s[129] * k[33];
    s[617] = x5625;
    let x5626 = s[154] + x5625;
    s[618] = x5626;
    let x5627 = x5624 + x5626;
    s[619] = x5627;
    let x5628 = s[130] * k[32];
    s[620] = x5628;
    let x5629 = s[155] + x5628;
    s[621] = x5629;
    let x5630 = s[139] * k[33];
    s[622] = x5630;
    let x5631 = s[156] + x5630;
    s[623] = x5631;
    let x5632 = x5629 + x5631;
    s[624] = x5632;
    let x5633 = s[140] * k[32];
    s[625] = x5633;
    let x5634 = s[157] + x5633;
    s[626] = x5634;
    let x5635 = s[112] * k[33];
    s[627] = x5635;
    let x5636 = s[158] + x5635;
    s[628] = x5636;
    let x5637 = x5634 + x5636;
    s[629] = x5637;
    let x5638 = dq[0] + x5627;
    s[630] = x5638;
    let x5639 = dq[1] + x5632;
    s[631] = x5639;
    let x5640 = dq[2] + x5637;
    s[632] = x5640;
    let x5641 = x5638 - dp[26];
    s[633] = x5641;
    let x5642 = x5640 - dp[27];
    s[634] = x5642;
    let x5643 = s[465] * x5641;
    s[635] = x5643;
    let x5644 = s[466] * x5639;
    s[636] = x5644;
    let x5645 = s[467] * x5642;
    s[637] = x5645;
    let x5646 = x5643 + x5644;
    s[638] = x5646;
    let x5647 = x5645 + x5646;
    s[639] = x5647;
    let x5648 = s[469] * x5647;
    s[640] = x5648;
    let x5651 = s[110] * k[36];
    s[641] = x5651;
    let x5652 = s[159] + x5651;
    s[642] = x5652;
    let x5653 = s[129] * k[37];
    s[643] = x5653;
    let x5654 = s[160] + x5653;
    s[644] = x5654;
    let x5655 = x5652 + x5654;
    s[645] = x5655;
    let x5656 = s[130] * k[36];
    s[646] = x5656;
    let x5657 = s[161] + x5656;
    s[647] = x5657;
    let x5658 = s[139] * k[37];
    s[648] = x5658;
    let x5659 = s[162] + x5658;
    s[649] = x5659;
    let x5660 = x5657 + x5659;
    s[650] = x5660;
    let x5661 = s[140] * k[36];
    s[651] = x5661;
    let x5662 = s[163] + x5661;
    s[652] = x5662;
    let x5663 = s[112] * k[37];
    s[653] = x5663;
    let x5664 = s[164] + x5663;
    s[654] = x5664;
    let x5665 = x5662 + x5664;
    s[655] = x5665;
    let x5666 = dq[0] + x5655;
    s[656] = x5666;
    let x5667 = dq[1] + x5660;
    s[657] = x5667;
    let x5668 = dq[2] + x5665;
    s[658] = x5668;
    let x5669 = x5666 - dp[30];
    s[659] = x5669;
    let x5670 = x5668 - dp[31];
    s[660] = x5670;
    let x5671 = s[470] * x5669;
    s[661] = x5671;
    let x5672 = s[471] * x5667;
    s[662] = x5672;
    let x5673 = s[472] * x5670;
    s[663] = x5673;
    let x5674 = x5671 + x5672;
    s[664] = x5674;
    let x5675 = x5673 + x5674;
    s[665] = x5675;
    let x5676 = s[474] * x5675;
    s[666] = x5676;
    let x5679 = s[110] * k[40];
    s[667] = x5679;
    let x5680 = s[165] + x5679;
    s[668] = x5680;
    let x5681 = s[129] * k[41];
    s[669] = x5681;
    let x5682 = s[166] + x5681;
    s[670] = x5682;
    let x5683 = x5680 + x5682;
    s[671] = x5683;
    let x5684 = s[130] * k[40];
    s[672] = x5684;
    let x5685 = s[167] + x5684;
    s[673] = x5685;
    let x5686 = s[139] * k[41];
    s[674] = x5686;
    let x5687 = s[168] + x5686;
    s[675] = x5687;
    let x5688 = x5685 + x5687;
    s[676] = x5688;
    let x5689 = s[140] * k[40];
    s[677] = x5689;
    let x5690 = s[169] + x5689;
    s[678] = x5690;
    let x5691 = s[112] * k[41];
    s[679] = x5691;
    let x5692 = s[170] + x5691;
    s[680] = x5692;
    let x5693 = x5690 + x5692;
    s[681] = x5693;
    let x5694 = dq[0] + x5683;
    s[682] = x5694;
    let x5695 = dq[1] + x5688;
    s[683] = x5695;
    let x5696 = dq[2] + x5693;
    s[684] = x5696;
    let x5697 = x5694 - dp[34];
    s[685] = x5697;
    let x5698 = x5696 - dp[35];
    s[686] = x5698;
    let x5699 = s[475] * x5697;
    s[687] = x5699;
    let x5700 = s[476] * x5695;
    s[688] = x5700;
    let x5701 = s[477] * x5698;
    s[689] = x5701;
    let x5702 = x5699 + x5700;
    s[690] = x5702;
    let x5703 = x5701 + x5702;
    s[691] = x5703;
    let x5704 = s[479] * x5703;
    s[692] = x5704;
    let x5707 = s[110] * k[44];
    s[693] = x5707;
    let x5708 = s[171] + x5707;
    s[694] = x5708;
    let x5709 = s[129] * k[45];
    s[695] = x5709;
    let x5710 = s[172] + x5709;
    s[696] = x5710;
    let x5711 = x5708 + x5710;
    s[697] = x5711;
    let x5712 = s[130] * k[44];
    s[698] = x5712;
    let x5713 = s[173] + x5712;
    s[699] = x5713;
    let x5714 = s[139] * k[45];
    s[700] = x5714;
    let x5715 = s[174] + x5714;
    s[701] = x5715;
    let x5716 = x5713 + x5715;
    s[702] = x5716;
    let x5717 = s[140] * k[44];
    s[703] = x5717;
    let x5718 = s[175] + x5717;
    s[704] = x5718;
    let x5719 = s[112] * k[45];
    s[705] = x5719;
    let x5720 = s[176] + x5719;
    s[706] = x5720;
    let x5721 = x5718 + x5720;
    s[707] = x5721;
    let x5722 = dq[0] + x5711;
    s[708] = x5722;
    let x5723 = dq[1] + x5716;
    s[709] = x5723;
    let x5724 = dq[2] + x5721;
    s[710] = x5724;
    let x5725 = x5722 - dp[38];
    s[711] = x5725;
    let x5726 = x5724 - dp[39];
    s[712] = x5726;
    let x5727 = s[480] * x5725;
    s[713] = x5727;
    let x5728 = s[481] * x5723;
    s[714] = x5728;
    let x5729 = s[482] * x5726;
    s[715] = x5729;
    let x5730 = x5727 + x5728;
    s[716] = x5730;
    let x5731 = x5729 + x5730;
    s[717] = x5731;
    let x5732 = s[484] * x5731;
    s[718] = x5732;
    let x5735 = 2.0 * s[581];
    s[719] = x5735;
    let x5736 = 2.0 * s[579];
    s[720] = x5736;
    let x5737 = 2.0 * s[582];
    s[721] = x5737;
    let x5738 = 2.0 * s[588];
    s[722] = x5738;
    let x5739 = s[515] * x5738;
    s[723] = x5739;
    let x5744 = 2.0 * x5613;
    s[724] = x5744;
    let x5745 = 2.0 * x5611;
    s[725] = x5745;
    let x5746 = 2.0 * x5614;
    s[726] = x5746;
    let x5747 = 2.0 * x5620;
    s[727] = x5747;
    let x5748 = s[516] * x5747;
    s[728] = x5748;
    let x5753 = 2.0 * x5641;
    s[729] = x5753;
    let x5754 = 2.0 * x5639;
    s[730] = x5754;
    let x5755 = 2.0 * x5642;
    s[731] = x5755;
    let x5756 = 2.0 * x5648;
    s[732] = x5756;
    let x5757 = s[517] * x5756;
    s[733] = x5757;
    let x5762 = 2.0 * x5669;
    s[734] = x5762;
    let x5763 = 2.0 * x5667;
    s[735] = x5763;
    let x5764 = 2.0 * x5670;
    s[736] = x5764;
    let x5765 = 2.0 * x5676;
    s[737] = x5765;
    let x5766 = s[518] * x5765;
    s[738] = x5766;
    let x5771 = 2.0 * x5697;
    s[739] = x5771;
    let x5772 = 2.0 * x5695;
    s[740] = x5772;
    let x5773 = 2.0 * x5698;
    s[741] = x5773;
    let x5774 = 2.0 * x5704;
    s[742] = x5774;
    let x5775 = s[519] * x5774;
    s[743] = x5775;
    let x5780 = 2.0 * x5725;
    s[744] = x5780;
    let x5781 = 2.0 * x5723;
    s[745] = x5781;
    let x5782 = 2.0 * x5726;
    s[746] = x5782;
    let x5783 = 2.0 * x5732;
    s[747] = x5783;
    let x5784 = s[520] * x5783;
    s[748] = x5784;
    let x6413 = s[100] * s[301];
    s[749] = x6413;
    let x6414 = 0.8726646259971648 * x6413;
    s[750] = x6414;
    let x6415 = dp[43] * s[486];
    s[751] = x6415;
    let x6416 = k[1] * x6414;
    s[752] = x6416;
    let x6417 = x6415 + x6416;
    s[753] = x6417;
    let x6418 = 2.0 * s[532];
    s[754] = x6418;
    let x6419 = s[521] * x6418;
    s[755] = x6419;
    let x6420 = s[489] * x6417;
    s[756] = x6420;
    let x6421 = s[487] * x6419;
    s[757] = x6421;
    let x6423 = x6420 - x6421;
    s[758] = x6423;
    let x6424 = s[101] * s[307];
    s[759] = x6424;
    let x6425 = 0.8726646259971648 * x6424;
    s[760] = x6425;
    let x6426 = dp[47] * s[491];
    s[761] = x6426;
    let x6427 = k[5] * x6425;
    s[762] = x6427;
    let x6428 = x6426 + x6427;
    s[763] = x6428;
    let x6429 = 2.0 * s[538];
    s[764] = x6429;
    let x6430 = s[522] * x6429;
    s[765] = x6430;
    let x6431 = s[494] * x6428;
    s[766] = x6431;
    let x6432 = s[492] * x6430;
    s[767] = x6432;
    let x6434 = x6431 - x6432;
    s[768] = x6434;
    let x6435 = s[102] * s[313];
    s[769] = x6435;
    let x6436 = 0.8726646259971648 * x6435;
    s[770] = x6436;
    let x6437 = dp[51] * s[496];
    s[771] = x6437;
    let x6438 = k[9] * x6436;
    s[772] = x6438;
    let x6439 = x6437 + x6438;
    s[773] = x6439;
    let x6440 = 2.0 * s[544];
    s[774] = x6440;
    let x6441 = s[523] * x6440;
    s[775] = x6441;
    let x6442 = s[499] * x6439;
    s[776] = x6442;
    let x6443 = s[497] * x6441;
    s[777] = x6443;
    let x6445 = x6442 - x6443;
    s[778] = x6445;
    let x6446 = s[103] * s[319];
    s[779] = x6446;
    let x6447 = 0.8726646259971648 * x6446;
    s[780] = x6447;
    let x6448 = dp[55] * s[501];
    s[781] = x6448;
    let x6449 = k[13] * x6447;
    s[782] = x6449;
    let x6450 = x6448 + x6449;
    s[783] = x6450;
    let x6451 = 2.0 * s[550];
    s[784] = x6451;
    let x6452 = s[524] * x6451;
    s[785] = x6452;
    let x6453 = s[504] * x6450;
    s[786] = x6453;
    let x6454 = s[502] * x6452;
    s[787] = x6454;
    let x6456 = x6453 - x6454;
    s[788] = x6456;
    let x6457 = s[104] * s[325];
    s[789] = x6457;
    let x6458 = 0.8726646259971648 * x6457;
    s[790] = x6458;
    let x6459 = dp[59] * s[506];
    s[791] = x6459;
    let x6460 = k[17] * x6458;
    s[792] = x6460;
    let x6461 = x6459 + x6460;
    s[793] = x6461;
    let x6462 = 2.0 * s[556];
    s[794] = x6462;
    let x6463 = s[525] * x6462;
    s[795] = x6463;
    let x6464 = s[509] * x6461;
    s[796] = x6464;
    let x6465 = s[507] * x6463;
    s[797] = x6465;
    let x6467 = x6464 - x6465;
    s[798] = x6467;
    let x6468 = s[105] * s[331];
    s[799] = x6468;
    let x6469 = 0.8726646259971648 * x6468;
    s[800] = x6469;
    let x6470 = dp[63] * s[511];
    s[801] = x6470;
    let x6471 = k[21] * x6469;
    s[802] = x6471;
    let x6472 = x6470 + x6471;
    s[803] = x6472;
    let x6473 = 2.0 * s[562];
    s[804] = x6473;
    let x6474 = s[526] * x6473;
    s[805] = x6474;
    let x6475 = s[514] * x6472;
    s[806] = x6475;
    let x6476 = s[512] * x6474;
    s[807] = x6476;
    let x6478 = x6475 - x6476;
    s[808] = x6478;
}
#[inline(never)]
fn kinematic_tangents_part_0(
    k: &[f64; 53],
    dp: &[f64; 66],
    s: &[f64; 809],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 46],
    phi_t: &mut [f64; 7],
) {
    let x2207 = s[30] * dp[20];
    let x2210 = s[29] * dp[21];
    let x2214 = s[28] * dp[20];
    let x2217 = s[27] * dp[21];
    let x2222 = s[29] * dp[20];
    let x2226 = s[30] * dp[21];
    let x2436 = s[31] * dp[20];
    let x2439 = s[28] * dp[21];
    let x2443 = s[26] * dp[21];
    let x2598 = s[27] * dp[20];
    let x2602 = s[26] * dp[20];
    let x2738 = s[32] * dp[21];
    let x4619 = s[30] * k[24];
    let x4620 = s[29] * k[25];
    let x4621 = x4619 + x4620;
    let x4622 = s[28] * k[24];
    let x4623 = s[27] * k[25];
    let x4625 = x4622 - x4623;
    let x4626 = s[29] * k[24];
    let x4628 = s[30] * k[25];
    let x4629 = x4628 - x4626;
    let x4630 = s[455] * x4621;
    let x4631 = s[456] * x4625;
    let x4632 = s[457] * x4629;
    let x4633 = x4630 + x4631;
    let x4634 = x4632 + x4633;
    let x4721 = s[31] * k[24];
    let x4722 = s[28] * k[25];
    let x4723 = x4721 + x4722;
    let x4724 = s[26] * k[25];
    let x4726 = x4626 - x4724;
    let x4727 = s[455] * x4723;
    let x4728 = s[456] * x4726;
    let x4729 = s[457] * x4622;
    let x4730 = x4727 + x4728;
    let x4731 = x4729 + x4730;
    let x4793 = s[27] * k[24];
    let x4794 = x4722 + x4793;
    let x4795 = s[26] * k[24];
    let x4796 = s[455] * x4724;
    let x4797 = s[456] * x4794;
    let x4798 = s[457] * x4795;
    let x4800 = x4796 + x4797;
    let x4801 = x4800 - x4798;
    let x4853 = x4620 + x4795;
    let x4854 = s[32] * k[25];
    let x4855 = x4793 + x4854;
    let x4856 = s[455] * x4623;
    let x4857 = s[456] * x4853;
    let x4858 = s[457] * x4855;
    let x4859 = x4856 + x4857;
    let x4860 = x4858 + x4859;
    let x5594 = s[588] - s[532];
    let x5740 = s[459] * s[719];
    let x5741 = s[455] * s[723];
    let x5743 = x5740 - x5741;
    let x5789 = s[459] * s[720];
    let x5790 = s[456] * s[723];
    let x5792 = x5789 - x5790;
    let x5813 = s[459] * s[721];
    let x5814 = s[457] * s[723];
    let x5816 = x5813 - x5814;
    let x5837 = s[181] * k[24];
    let x5838 = x2207 + x5837;
    let x5839 = s[180] * k[25];
    let x5840 = x2210 + x5839;
    let x5841 = x5838 + x5840;
    let x5842 = s[179] * k[24];
    let x5843 = x2214 + x5842;
    let x5844 = s[178] * k[25];
    let x5845 = x2217 + x5844;
    let x5847 = x5843 - x5845;
    let x5848 = s[180] * k[24];
    let x5849 = x2222 + x5848;
    let x5851 = s[181] * k[25];
    let x5852 = x2226 + x5851;
    let x5853 = x5852 - x5849;
    let x5854 = x4621 * s[719];
    let x5855 = s[455] * x5841;
    let x5856 = x5854 + x5855;
    let x5857 = x4625 * s[720];
    let x5858 = s[456] * x5847;
    let x5859 = x5857 + x5858;
    let x5860 = x4629 * s[721];
    let x5861 = s[457] * x5853;
    let x5862 = x5860 + x5861;
    let x5863 = x5856 + x5859;
    let x5864 = x5862 + x5863;
    let x5865 = x4634 * s[723];
    let x5867 = s[459] * x5864;
    let x5868 = x5867 - x5865;
    let x6029 = s[182] * k[24];
    let x6030 = x2436 + x6029;
    let x6031 = s[179] * k[25];
    let x6032 = x2439 + x6031;
    let x6033 = x6030 + x6032;
    let x6034 = s[177] * k[25];
    let x6035 = x2443 + x6034;
    let x6037 = x5849 - x6035;
    let x6038 = x4723 * s[719];
    let x6039 = s[455] * x6033;
    let x6040 = x6038 + x6039;
    let x6041 = x4726 * s[720];
    let x6042 = s[456] * x6037;
    let x6043 = x6041 + x6042;
    let x6044 = x4622 * s[721];
    let x6045 = s[457] * x5843;
    let x6046 = x6044 + x6045;
    let x6047 = x6040 + x6043;
    let x6048 = x6046 + x6047;
    let x6049 = x4731 * s[723];
    let x6051 = s[459] * x6048;
    let x6052 = x6051 - x6049;
    let x6173 = s[178] * k[24];
    let x6174 = x2598 + x6173;
    let x6175 = x6032 + x6174;
    let x6176 = s[177] * k[24];
    let x6177 = x2602 + x6176;
    let x6178 = x4724 * s[719];
    let x6179 = s[455] * x6035;
    let x6180 = x6178 + x6179;
    let x6181 = x4794 * s[720];
    let x6182 = s[456] * x6175;
    let x6183 = x6181 + x6182;
    let x6184 = x4795 * s[721];
    let x6185 = s[457] * x6177;
    let x6186 = x6184 + x6185;
    let x6188 = x6180 + x6183;
    let x6189 = x6188 - x6186;
    let x6190 = x4801 * s[723];
    let x6192 = s[459] * x6189;
    let x6193 = x6192 - x6190;
    let x6299 = x5840 + x6177;
    let x6300 = s[183] * k[25];
    let x6301 = x2738 + x6300;
    let x6302 = x6174 + x6301;
    let x6303 = x4623 * s[719];
    let x6304 = s[455] * x5845;
    let x6305 = x6303 + x6304;
    let x6306 = x4853 * s[720];
    let x6307 = s[456] * x6299;
    let x6308 = x6306 + x6307;
    let x6309 = x4855 * s[721];
    let x6310 = s[457] * x6302;
    let x6311 = x6309 + x6310;
    let x6312 = x6305 + x6308;
    let x6313 = x6311 + x6312;
    let x6314 = x4860 * s[723];
    let x6316 = s[459] * x6313;
    let x6317 = x6316 - x6314;
    let x6479 = -s[758];
    phi[0] = x5594;
    phi_q[0] = x5743;
    phi_q[1] = x5792;
    phi_q[2] = x5816;
    phi_q[3] = x5868;
    phi_q[4] = x6052;
    phi_q[5] = x6193;
    phi_q[6] = x6317;
    phi_t[0] = x6479;
}
#[inline(never)]
fn kinematic_tangents_part_1(
    k: &[f64; 53],
    qd: &[f64; 7],
    dqd: &[f64; 7],
    dp: &[f64; 66],
    s: &[f64; 809],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 46],
    gamma: &mut [f64; 7],
) {
    let x3002 = s[37] * dp[20];
    let x3005 = s[56] * dp[21];
    let x3009 = s[57] * dp[20];
    let x3012 = s[66] * dp[21];
    let x3016 = s[67] * dp[20];
    let x3019 = s[39] * dp[21];
    let x3514 = s[75] * dp[20];
    let x3517 = s[90] * dp[21];
    let x3521 = s[91] * dp[20];
    let x3524 = s[98] * dp[21];
    let x3528 = s[99] * dp[20];
    let x3531 = s[77] * dp[21];
    let x4912 = s[487] * s[489];
    let x4949 = s[37] * k[24];
    let x4950 = s[56] * k[25];
    let x4951 = x4949 + x4950;
    let x4952 = s[57] * k[24];
    let x4953 = s[66] * k[25];
    let x4954 = x4952 + x4953;
    let x4955 = s[67] * k[24];
    let x4956 = s[39] * k[25];
    let x4957 = x4955 + x4956;
    let x4958 = qd[0] + x4951;
    let x4959 = qd[1] + x4954;
    let x4960 = qd[2] + x4957;
    let x4961 = s[455] * x4958;
    let x4962 = s[456] * x4959;
    let x4963 = s[457] * x4960;
    let x4964 = x4961 + x4962;
    let x4965 = x4963 + x4964;
    let x4966 = s[459] * x4965;
    let x5057 = 2.0 * x4958;
    let x5058 = 2.0 * x4959;
    let x5059 = 2.0 * x4960;
    let x5060 = 2.0 * x4966;
    let x5062 = x5060 * s[515];
    let x5093 = 0.8726646259971648 * s[301];
    let x5094 = 0.8726646259971648 * x5093;
    let x5095 = k[1] * x5094;
    let x5096 = 2.0 * x4912;
    let x5098 = x5096 * s[521];
    let x5159 = s[75] * k[24];
    let x5160 = s[90] * k[25];
    let x5161 = x5159 + x5160;
    let x5162 = s[91] * k[24];
    let x5163 = s[98] * k[25];
    let x5164 = x5162 + x5163;
    let x5165 = s[99] * k[24];
    let x5166 = s[77] * k[25];
    let x5167 = x5165 + x5166;
    let x5168 = x4958 * x5057;
    let x5169 = s[455] * x5161;
    let x5170 = x5168 + x5169;
    let x5171 = x4959 * x5058;
    let x5172 = s[456] * x5164;
    let x5173 = x5171 + x5172;
    let x5174 = x4960 * x5059;
    let x5175 = s[457] * x5167;
    let x5176 = x5174 + x5175;
    let x5177 = x5170 + x5173;
    let x5178 = x5176 + x5177;
    let x5622 = s[614] - s[538];
    let x5749 = s[464] * s[724];
    let x5750 = s[460] * s[728];
    let x5752 = x5749 - x5750;
    let x5793 = s[464] * s[725];
    let x5794 = s[461] * s[728];
    let x5796 = x5793 - x5794;
    let x5817 = s[464] * s[726];
    let x5818 = s[462] * s[728];
    let x5820 = x5817 - x5818;
    let x6485 = s[194] * k[24];
    let x6486 = x3002 + x6485;
    let x6487 = s[229] * k[25];
    let x6488 = x3005 + x6487;
    let x6489 = x6486 + x6488;
    let x6490 = s[230] * k[24];
    let x6491 = x3009 + x6490;
    let x6492 = s[247] * k[25];
    let x6493 = x3012 + x6492;
    let x6494 = x6491 + x6493;
    let x6495 = s[248] * k[24];
    let x6496 = x3016 + x6495;
    let x6497 = s[196] * k[25];
    let x6498 = x3019 + x6497;
    let x6499 = x6496 + x6498;
    let x6500 = dqd[0] + x6489;
    let x6501 = dqd[1] + x6494;
    let x6502 = dqd[2] + x6499;
    let x6503 = x4958 * s[719];
    let x6504 = s[455] * x6500;
    let x6505 = x6503 + x6504;
    let x6506 = x4959 * s[720];
    let x6507 = s[456] * x6501;
    let x6508 = x6506 + x6507;
    let x6509 = x4960 * s[721];
    let x6510 = s[457] * x6502;
    let x6511 = x6509 + x6510;
    let x6512 = x6505 + x6508;
    let x6513 = x6511 + x6512;
    let x6514 = x4965 * s[723];
    let x6516 = s[459] * x6513;
    let x6517 = x6516 - x6514;
    let x6683 = 2.0 * x6500;
    let x6684 = 2.0 * x6501;
    let x6685 = 2.0 * x6502;
    let x6686 = 2.0 * x6517;
    let x6687 = 2.0 * s[459];
    let x6688 = s[723] * x6687;
    let x6689 = s[515] * x6686;
    let x6690 = x5060 * x6688;
    let x6692 = x6689 - x6690;
    let x6743 = 0.8726646259971648 * s[527];
    let x6744 = 0.8726646259971648 * x6743;
    let x6745 = dp[43] * x5094;
    let x6746 = k[1] * x6744;
    let x6748 = x6745 - x6746;
    let x6749 = 2.0 * s[758];
    let x6750 = 2.0 * s[489];
    let x6751 = s[755] * x6750;
    let x6752 = s[521] * x6749;
    let x6753 = x5096 * x6751;
    let x6755 = x6752 - x6753;
    let x6756 = x5095 * s[755];
    let x6758 = s[489] * x6748;
    let x6759 = x6758 - x6756;
    let x6760 = x5098 * s[753];
    let x6761 = s[487] * x6755;
    let x6762 = x6760 + x6761;
    let x6764 = x6759 - x6762;
    let x6881 = s[262] * k[24];
    let x6882 = x3514 + x6881;
    let x6883 = s[285] * k[25];
    let x6884 = x3517 + x6883;
    let x6885 = x6882 + x6884;
    let x6886 = s[286] * k[24];
    let x6887 = x3521 + x6886;
    let x6888 = s[297] * k[25];
    let x6889 = x3524 + x6888;
    let x6890 = x6887 + x6889;
    let x6891 = s[298] * k[24];
    let x6892 = x3528 + x6891;
    let x6893 = s[264] * k[25];
    let x6894 = x3531 + x6893;
    let x6895 = x6892 + x6894;
    let x6896 = x5057 * x6500;
    let x6897 = x4958 * x6683;
    let x6898 = x6896 + x6897;
    let x6899 = x5161 * s[719];
    let x6900 = s[455] * x6885;
    let x6901 = x6899 + x6900;
    let x6902 = x6898 + x6901;
    let x6903 = x5058 * x6501;
    let x6904 = x4959 * x6684;
    let x6905 = x6903 + x6904;
    let x6906 = x5164 * s[720];
    let x6907 = s[456] * x6890;
    let x6908 = x6906 + x6907;
    let x6909 = x6905 + x6908;
    let x6910 = x5059 * x6502;
    let x6911 = x4960 * x6685;
    let x6912 = x6910 + x6911;
    let x6913 = x5167 * s[721];
    let x6914 = s[457] * x6895;
    let x6915 = x6913 + x6914;
    let x6916 = x6912 + x6915;
    let x6917 = x6902 + x6909;
    let x6918 = x6916 + x6917;
    let x6919 = x5062 * x6513;
    let x6920 = x4965 * x6692;
    let x6921 = x6919 + x6920;
    let x6923 = x5178 * s[723];
    let x6925 = s[459] * x6918;
    let x6926 = x6925 - x6923;
    let x6927 = x6926 - x6921;
    let x6928 = x6927 - x6764;
    let x7169 = -x6928;
    gamma[0] = x7169;
    phi[1] = x5622;
    phi_q[7] = x5752;
    phi_q[8] = x5796;
    phi_q[9] = x5820;
}
#[inline(never)]
fn kinematic_tangents_part_2(
    k: &[f64; 53],
    dp: &[f64; 66],
    s: &[f64; 809],
    phi_q: &mut [f64; 46],
    phi_t: &mut [f64; 7],
) {
    let x2245 = s[30] * dp[24];
    let x2248 = s[29] * dp[25];
    let x2252 = s[28] * dp[24];
    let x2255 = s[27] * dp[25];
    let x2260 = s[29] * dp[24];
    let x2264 = s[30] * dp[25];
    let x2463 = s[31] * dp[24];
    let x2466 = s[28] * dp[25];
    let x2470 = s[26] * dp[25];
    let x2621 = s[27] * dp[24];
    let x2625 = s[26] * dp[24];
    let x2758 = s[32] * dp[25];
    let x4636 = s[30] * k[28];
    let x4637 = s[29] * k[29];
    let x4638 = x4636 + x4637;
    let x4639 = s[28] * k[28];
    let x4640 = s[27] * k[29];
    let x4642 = x4639 - x4640;
    let x4643 = s[29] * k[28];
    let x4645 = s[30] * k[29];
    let x4646 = x4645 - x4643;
    let x4647 = s[460] * x4638;
    let x4648 = s[461] * x4642;
    let x4649 = s[462] * x4646;
    let x4650 = x4647 + x4648;
    let x4651 = x4649 + x4650;
    let x4733 = s[31] * k[28];
    let x4734 = s[28] * k[29];
    let x4735 = x4733 + x4734;
    let x4736 = s[26] * k[29];
    let x4738 = x4643 - x4736;
    let x4739 = s[460] * x4735;
    let x4740 = s[461] * x4738;
    let x4741 = s[462] * x4639;
    let x4742 = x4739 + x4740;
    let x4743 = x4741 + x4742;
    let x4803 = s[27] * k[28];
    let x4804 = x4734 + x4803;
    let x4805 = s[26] * k[28];
    let x4806 = s[460] * x4736;
    let x4807 = s[461] * x4804;
    let x4808 = s[462] * x4805;
    let x4810 = x4806 + x4807;
    let x4811 = x4810 - x4808;
    let x4862 = x4637 + x4805;
    let x4863 = s[32] * k[29];
    let x4864 = x4803 + x4863;
    let x4865 = s[460] * x4640;
    let x4866 = s[461] * x4862;
    let x4867 = s[462] * x4864;
    let x4868 = x4865 + x4866;
    let x4869 = x4867 + x4868;
    let x5869 = s[181] * k[28];
    let x5870 = x2245 + x5869;
    let x5871 = s[180] * k[29];
    let x5872 = x2248 + x5871;
    let x5873 = x5870 + x5872;
    let x5874 = s[179] * k[28];
    let x5875 = x2252 + x5874;
    let x5876 = s[178] * k[29];
    let x5877 = x2255 + x5876;
    let x5879 = x5875 - x5877;
    let x5880 = s[180] * k[28];
    let x5881 = x2260 + x5880;
    let x5883 = s[181] * k[29];
    let x5884 = x2264 + x5883;
    let x5885 = x5884 - x5881;
    let x5886 = x4638 * s[724];
    let x5887 = s[460] * x5873;
    let x5888 = x5886 + x5887;
    let x5889 = x4642 * s[725];
    let x5890 = s[461] * x5879;
    let x5891 = x5889 + x5890;
    let x5892 = x4646 * s[726];
    let x5893 = s[462] * x5885;
    let x5894 = x5892 + x5893;
    let x5895 = x5888 + x5891;
    let x5896 = x5894 + x5895;
    let x5897 = x4651 * s[728];
    let x5899 = s[464] * x5896;
    let x5900 = x5899 - x5897;
    let x6053 = s[182] * k[28];
    let x6054 = x2463 + x6053;
    let x6055 = s[179] * k[29];
    let x6056 = x2466 + x6055;
    let x6057 = x6054 + x6056;
    let x6058 = s[177] * k[29];
    let x6059 = x2470 + x6058;
    let x6061 = x5881 - x6059;
    let x6062 = x4735 * s[724];
    let x6063 = s[460] * x6057;
    let x6064 = x6062 + x6063;
    let x6065 = x4738 * s[725];
    let x6066 = s[461] * x6061;
    let x6067 = x6065 + x6066;
    let x6068 = x4639 * s[726];
    let x6069 = s[462] * x5875;
    let x6070 = x6068 + x6069;
    let x6071 = x6064 + x6067;
    let x6072 = x6070 + x6071;
    let x6073 = x4743 * s[728];
    let x6075 = s[464] * x6072;
    let x6076 = x6075 - x6073;
    let x6194 = s[178] * k[28];
    let x6195 = x2621 + x6194;
    let x6196 = x6056 + x6195;
    let x6197 = s[177] * k[28];
    let x6198 = x2625 + x6197;
    let x6199 = x4736 * s[724];
    let x6200 = s[460] * x6059;
    let x6201 = x6199 + x6200;
    let x6202 = x4804 * s[725];
    let x6203 = s[461] * x6196;
    let x6204 = x6202 + x6203;
    let x6205 = x4805 * s[726];
    let x6206 = s[462] * x6198;
    let x6207 = x6205 + x6206;
    let x6209 = x6201 + x6204;
    let x6210 = x6209 - x6207;
    let x6211 = x4811 * s[728];
    let x6213 = s[464] * x6210;
    let x6214 = x6213 - x6211;
    let x6318 = x5872 + x6198;
    let x6319 = s[183] * k[29];
    let x6320 = x2758 + x6319;
    let x6321 = x6195 + x6320;
    let x6322 = x4640 * s[724];
    let x6323 = s[460] * x5877;
    let x6324 = x6322 + x6323;
    let x6325 = x4862 * s[725];
    let x6326 = s[461] * x6318;
    let x6327 = x6325 + x6326;
    let x6328 = x4864 * s[726];
    let x6329 = s[462] * x6321;
    let x6330 = x6328 + x6329;
    let x6331 = x6324 + x6327;
    let x6332 = x6330 + x6331;
    let x6333 = x4869 * s[728];
    let x6335 = s[464] * x6332;
    let x6336 = x6335 - x6333;
    let x6480 = -s[768];
    phi_q[10] = x5900;
    phi_q[11] = x6076;
    phi_q[12] = x6214;
    phi_q[13] = x6336;
    phi_t[1] = x6480;
}
#[inline(never)]
fn kinematic_tangents_part_3(
    k: &[f64; 53],
    qd: &[f64; 7],
    dqd: &[f64; 7],
    dp: &[f64; 66],
    s: &[f64; 809],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 46],
    gamma: &mut [f64; 7],
) {
    let x3041 = s[37] * dp[24];
    let x3044 = s[56] * dp[25];
    let x3048 = s[57] * dp[24];
    let x3051 = s[66] * dp[25];
    let x3055 = s[67] * dp[24];
    let x3058 = s[39] * dp[25];
    let x3568 = s[75] * dp[24];
    let x3571 = s[90] * dp[25];
    let x3575 = s[91] * dp[24];
    let x3578 = s[98] * dp[25];
    let x3582 = s[99] * dp[24];
    let x3585 = s[77] * dp[25];
    let x4918 = s[492] * s[494];
    let x4967 = s[37] * k[28];
    let x4968 = s[56] * k[29];
    let x4969 = x4967 + x4968;
    let x4970 = s[57] * k[28];
    let x4971 = s[66] * k[29];
    let x4972 = x4970 + x4971;
    let x4973 = s[67] * k[28];
    let x4974 = s[39] * k[29];
    let x4975 = x4973 + x4974;
    let x4976 = qd[0] + x4969;
    let x4977 = qd[1] + x4972;
    let x4978 = qd[2] + x4975;
    let x4979 = s[460] * x4976;
    let x4980 = s[461] * x4977;
    let x4981 = s[462] * x4978;
    let x4982 = x4979 + x4980;
    let x4983 = x4981 + x4982;
    let x4984 = s[464] * x4983;
    let x5063 = 2.0 * x4976;
    let x5064 = 2.0 * x4977;
    let x5065 = 2.0 * x4978;
    let x5066 = 2.0 * x4984;
    let x5068 = x5066 * s[516];
    let x5103 = 0.8726646259971648 * s[307];
    let x5104 = 0.8726646259971648 * x5103;
    let x5105 = k[5] * x5104;
    let x5106 = 2.0 * x4918;
    let x5108 = x5106 * s[522];
    let x5184 = s[75] * k[28];
    let x5185 = s[90] * k[29];
    let x5186 = x5184 + x5185;
    let x5187 = s[91] * k[28];
    let x5188 = s[98] * k[29];
    let x5189 = x5187 + x5188;
    let x5190 = s[99] * k[28];
    let x5191 = s[77] * k[29];
    let x5192 = x5190 + x5191;
    let x5193 = x4976 * x5063;
    let x5194 = s[460] * x5186;
    let x5195 = x5193 + x5194;
    let x5196 = x4977 * x5064;
    let x5197 = s[461] * x5189;
    let x5198 = x5196 + x5197;
    let x5199 = x4978 * x5065;
    let x5200 = s[462] * x5192;
    let x5201 = x5199 + x5200;
    let x5202 = x5195 + x5198;
    let x5203 = x5201 + x5202;
    let x5650 = s[640] - s[544];
    let x5758 = s[469] * s[729];
    let x5759 = s[465] * s[733];
    let x5761 = x5758 - x5759;
    let x5797 = s[469] * s[730];
    let x5798 = s[466] * s[733];
    let x5800 = x5797 - x5798;
    let x5821 = s[469] * s[731];
    let x5822 = s[467] * s[733];
    let x5824 = x5821 - x5822;
    let x6518 = s[194] * k[28];
    let x6519 = x3041 + x6518;
    let x6520 = s[229] * k[29];
    let x6521 = x3044 + x6520;
    let x6522 = x6519 + x6521;
    let x6523 = s[230] * k[28];
    let x6524 = x3048 + x6523;
    let x6525 = s[247] * k[29];
    let x6526 = x3051 + x6525;
    let x6527 = x6524 + x6526;
    let x6528 = s[248] * k[28];
    let x6529 = x3055 + x6528;
    let x6530 = s[196] * k[29];
    let x6531 = x3058 + x6530;
    let x6532 = x6529 + x6531;
    let x6533 = dqd[0] + x6522;
    let x6534 = dqd[1] + x6527;
    let x6535 = dqd[2] + x6532;
    let x6536 = x4976 * s[724];
    let x6537 = s[460] * x6533;
    let x6538 = x6536 + x6537;
    let x6539 = x4977 * s[725];
    let x6540 = s[461] * x6534;
    let x6541 = x6539 + x6540;
    let x6542 = x4978 * s[726];
    let x6543 = s[462] * x6535;
    let x6544 = x6542 + x6543;
    let x6545 = x6538 + x6541;
    let x6546 = x6544 + x6545;
    let x6547 = x4983 * s[728];
    let x6549 = s[464] * x6546;
    let x6550 = x6549 - x6547;
    let x6693 = 2.0 * x6533;
    let x6694 = 2.0 * x6534;
    let x6695 = 2.0 * x6535;
    let x6696 = 2.0 * x6550;
    let x6697 = 2.0 * s[464];
    let x6698 = s[728] * x6697;
    let x6699 = s[516] * x6696;
    let x6700 = x5066 * x6698;
    let x6702 = x6699 - x6700;
    let x6765 = 0.8726646259971648 * s[533];
    let x6766 = 0.8726646259971648 * x6765;
    let x6767 = dp[47] * x5104;
    let x6768 = k[5] * x6766;
    let x6770 = x6767 - x6768;
    let x6771 = 2.0 * s[768];
    let x6772 = 2.0 * s[494];
    let x6773 = s[765] * x6772;
    let x6774 = s[522] * x6771;
    let x6775 = x5106 * x6773;
    let x6777 = x6774 - x6775;
    let x6778 = x5105 * s[765];
    let x6780 = s[494] * x6770;
    let x6781 = x6780 - x6778;
    let x6782 = x5108 * s[763];
    let x6783 = s[492] * x6777;
    let x6784 = x6782 + x6783;
    let x6786 = x6781 - x6784;
    let x6929 = s[262] * k[28];
    let x6930 = x3568 + x6929;
    let x6931 = s[285] * k[29];
    let x6932 = x3571 + x6931;
    let x6933 = x6930 + x6932;
    let x6934 = s[286] * k[28];
    let x6935 = x3575 + x6934;
    let x6936 = s[297] * k[29];
    let x6937 = x3578 + x6936;
    let x6938 = x6935 + x6937;
    let x6939 = s[298] * k[28];
    let x6940 = x3582 + x6939;
    let x6941 = s[264] * k[29];
    let x6942 = x3585 + x6941;
    let x6943 = x6940 + x6942;
    let x6944 = x5063 * x6533;
    let x6945 = x4976 * x6693;
    let x6946 = x6944 + x6945;
    let x6947 = x5186 * s[724];
    let x6948 = s[460] * x6933;
    let x6949 = x6947 + x6948;
    let x6950 = x6946 + x6949;
    let x6951 = x5064 * x6534;
    let x6952 = x4977 * x6694;
    let x6953 = x6951 + x6952;
    let x6954 = x5189 * s[725];
    let x6955 = s[461] * x6938;
    let x6956 = x6954 + x6955;
    let x6957 = x6953 + x6956;
    let x6958 = x5065 * x6535;
    let x6959 = x4978 * x6695;
    let x6960 = x6958 + x6959;
    let x6961 = x5192 * s[726];
    let x6962 = s[462] * x6943;
    let x6963 = x6961 + x6962;
    let x6964 = x6960 + x6963;
    let x6965 = x6950 + x6957;
    let x6966 = x6964 + x6965;
    let x6967 = x5068 * x6546;
    let x6968 = x4983 * x6702;
    let x6969 = x6967 + x6968;
    let x6971 = x5203 * s[728];
    let x6973 = s[464] * x6966;
    let x6974 = x6973 - x6971;
    let x6975 = x6974 - x6969;
    let x6976 = x6975 - x6786;
    let x7170 = -x6976;
    gamma[1] = x7170;
    phi[2] = x5650;
    phi_q[14] = x5761;
    phi_q[15] = x5800;
    phi_q[16] = x5824;
}
#[inline(never)]
fn kinematic_tangents_part_4(
    k: &[f64; 53],
    dp: &[f64; 66],
    s: &[f64; 809],
    phi_q: &mut [f64; 46],
    phi_t: &mut [f64; 7],
) {
    let x2283 = s[30] * dp[28];
    let x2286 = s[29] * dp[29];
    let x2290 = s[28] * dp[28];
    let x2293 = s[27] * dp[29];
    let x2298 = s[29] * dp[28];
    let x2302 = s[30] * dp[29];
    let x2490 = s[31] * dp[28];
    let x2493 = s[28] * dp[29];
    let x2497 = s[26] * dp[29];
    let x2644 = s[27] * dp[28];
    let x2648 = s[26] * dp[28];
    let x2778 = s[32] * dp[29];
    let x4653 = s[30] * k[32];
    let x4654 = s[29] * k[33];
    let x4655 = x4653 + x4654;
    let x4656 = s[28] * k[32];
    let x4657 = s[27] * k[33];
    let x4659 = x4656 - x4657;
    let x4660 = s[29] * k[32];
    let x4662 = s[30] * k[33];
    let x4663 = x4662 - x4660;
    let x4664 = s[465] * x4655;
    let x4665 = s[466] * x4659;
    let x4666 = s[467] * x4663;
    let x4667 = x4664 + x4665;
    let x4668 = x4666 + x4667;
    let x4745 = s[31] * k[32];
    let x4746 = s[28] * k[33];
    let x4747 = x4745 + x4746;
    let x4748 = s[26] * k[33];
    let x4750 = x4660 - x4748;
    let x4751 = s[465] * x4747;
    let x4752 = s[466] * x4750;
    let x4753 = s[467] * x4656;
    let x4754 = x4751 + x4752;
    let x4755 = x4753 + x4754;
    let x4813 = s[27] * k[32];
    let x4814 = x4746 + x4813;
    let x4815 = s[26] * k[32];
    let x4816 = s[465] * x4748;
    let x4817 = s[466] * x4814;
    let x4818 = s[467] * x4815;
    let x4820 = x4816 + x4817;
    let x4821 = x4820 - x4818;
    let x4871 = x4654 + x4815;
    let x4872 = s[32] * k[33];
    let x4873 = x4813 + x4872;
    let x4874 = s[465] * x4657;
    let x4875 = s[466] * x4871;
    let x4876 = s[467] * x4873;
    let x4877 = x4874 + x4875;
    let x4878 = x4876 + x4877;
    let x5901 = s[181] * k[32];
    let x5902 = x2283 + x5901;
    let x5903 = s[180] * k[33];
    let x5904 = x2286 + x5903;
    let x5905 = x5902 + x5904;
    let x5906 = s[179] * k[32];
    let x5907 = x2290 + x5906;
    let x5908 = s[178] * k[33];
    let x5909 = x2293 + x5908;
    let x5911 = x5907 - x5909;
    let x5912 = s[180] * k[32];
    let x5913 = x2298 + x5912;
    let x5915 = s[181] * k[33];
    let x5916 = x2302 + x5915;
    let x5917 = x5916 - x5913;
    let x5918 = x4655 * s[729];
    let x5919 = s[465] * x5905;
    let x5920 = x5918 + x5919;
    let x5921 = x4659 * s[730];
    let x5922 = s[466] * x5911;
    let x5923 = x5921 + x5922;
    let x5924 = x4663 * s[731];
    let x5925 = s[467] * x5917;
    let x5926 = x5924 + x5925;
    let x5927 = x5920 + x5923;
    let x5928 = x5926 + x5927;
    let x5929 = x4668 * s[733];
    let x5931 = s[469] * x5928;
    let x5932 = x5931 - x5929;
    let x6077 = s[182] * k[32];
    let x6078 = x2490 + x6077;
    let x6079 = s[179] * k[33];
    let x6080 = x2493 + x6079;
    let x6081 = x6078 + x6080;
    let x6082 = s[177] * k[33];
    let x6083 = x2497 + x6082;
    let x6085 = x5913 - x6083;
    let x6086 = x4747 * s[729];
    let x6087 = s[465] * x6081;
    let x6088 = x6086 + x6087;
    let x6089 = x4750 * s[730];
    let x6090 = s[466] * x6085;
    let x6091 = x6089 + x6090;
    let x6092 = x4656 * s[731];
    let x6093 = s[467] * x5907;
    let x6094 = x6092 + x6093;
    let x6095 = x6088 + x6091;
    let x6096 = x6094 + x6095;
    let x6097 = x4755 * s[733];
    let x6099 = s[469] * x6096;
    let x6100 = x6099 - x6097;
    let x6215 = s[178] * k[32];
    let x6216 = x2644 + x6215;
    let x6217 = x6080 + x6216;
    let x6218 = s[177] * k[32];
    let x6219 = x2648 + x6218;
    let x6220 = x4748 * s[729];
    let x6221 = s[465] * x6083;
    let x6222 = x6220 + x6221;
    let x6223 = x4814 * s[730];
    let x6224 = s[466] * x6217;
    let x6225 = x6223 + x6224;
    let x6226 = x4815 * s[731];
    let x6227 = s[467] * x6219;
    let x6228 = x6226 + x6227;
    let x6230 = x6222 + x6225;
    let x6231 = x6230 - x6228;
    let x6232 = x4821 * s[733];
    let x6234 = s[469] * x6231;
    let x6235 = x6234 - x6232;
    let x6337 = x5904 + x6219;
    let x6338 = s[183] * k[33];
    let x6339 = x2778 + x6338;
    let x6340 = x6216 + x6339;
    let x6341 = x4657 * s[729];
    let x6342 = s[465] * x5909;
    let x6343 = x6341 + x6342;
    let x6344 = x4871 * s[730];
    let x6345 = s[466] * x6337;
    let x6346 = x6344 + x6345;
    let x6347 = x4873 * s[731];
    let x6348 = s[467] * x6340;
    let x6349 = x6347 + x6348;
    let x6350 = x6343 + x6346;
    let x6351 = x6349 + x6350;
    let x6352 = x4878 * s[733];
    let x6354 = s[469] * x6351;
    let x6355 = x6354 - x6352;
    let x6481 = -s[778];
    phi_q[17] = x5932;
    phi_q[18] = x6100;
    phi_q[19] = x6235;
    phi_q[20] = x6355;
    phi_t[2] = x6481;
}
#[inline(never)]
fn kinematic_tangents_part_5(
    k: &[f64; 53],
    qd: &[f64; 7],
    dqd: &[f64; 7],
    dp: &[f64; 66],
    s: &[f64; 809],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 46],
    gamma: &mut [f64; 7],
) {
    let x3080 = s[37] * dp[28];
    let x3083 = s[56] * dp[29];
    let x3087 = s[57] * dp[28];
    let x3090 = s[66] * dp[29];
    let x3094 = s[67] * dp[28];
    let x3097 = s[39] * dp[29];
    let x3622 = s[75] * dp[28];
    let x3625 = s[90] * dp[29];
    let x3629 = s[91] * dp[28];
    let x3632 = s[98] * dp[29];
    let x3636 = s[99] * dp[28];
    let x3639 = s[77] * dp[29];
    let x4924 = s[497] * s[499];
    let x4985 = s[37] * k[32];
    let x4986 = s[56] * k[33];
    let x4987 = x4985 + x4986;
    let x4988 = s[57] * k[32];
    let x4989 = s[66] * k[33];
    let x4990 = x4988 + x4989;
    let x4991 = s[67] * k[32];
    let x4992 = s[39] * k[33];
    let x4993 = x4991 + x4992;
    let x4994 = qd[0] + x4987;
    let x4995 = qd[1] + x4990;
    let x4996 = qd[2] + x4993;
    let x4997 = s[465] * x4994;
    let x4998 = s[466] * x4995;
    let x4999 = s[467] * x4996;
    let x5000 = x4997 + x4998;
    let x5001 = x4999 + x5000;
    let x5002 = s[469] * x5001;
    let x5069 = 2.0 * x4994;
    let x5070 = 2.0 * x4995;
    let x5071 = 2.0 * x4996;
    let x5072 = 2.0 * x5002;
    let x5074 = x5072 * s[517];
    let x5113 = 0.8726646259971648 * s[313];
    let x5114 = 0.8726646259971648 * x5113;
    let x5115 = k[9] * x5114;
    let x5116 = 2.0 * x4924;
    let x5118 = x5116 * s[523];
    let x5209 = s[75] * k[32];
    let x5210 = s[90] * k[33];
    let x5211 = x5209 + x5210;
    let x5212 = s[91] * k[32];
    let x5213 = s[98] * k[33];
    let x5214 = x5212 + x5213;
    let x5215 = s[99] * k[32];
    let x5216 = s[77] * k[33];
    let x5217 = x5215 + x5216;
    let x5218 = x4994 * x5069;
    let x5219 = s[465] * x5211;
    let x5220 = x5218 + x5219;
    let x5221 = x4995 * x5070;
    let x5222 = s[466] * x5214;
    let x5223 = x5221 + x5222;
    let x5224 = x4996 * x5071;
    let x5225 = s[467] * x5217;
    let x5226 = x5224 + x5225;
    let x5227 = x5220 + x5223;
    let x5228 = x5226 + x5227;
    let x5678 = s[666] - s[550];
    let x5767 = s[474] * s[734];
    let x5768 = s[470] * s[738];
    let x5770 = x5767 - x5768;
    let x5801 = s[474] * s[735];
    let x5802 = s[471] * s[738];
    let x5804 = x5801 - x5802;
    let x5825 = s[474] * s[736];
    let x5826 = s[472] * s[738];
    let x5828 = x5825 - x5826;
    let x6551 = s[194] * k[32];
    let x6552 = x3080 + x6551;
    let x6553 = s[229] * k[33];
    let x6554 = x3083 + x6553;
    let x6555 = x6552 + x6554;
    let x6556 = s[230] * k[32];
    let x6557 = x3087 + x6556;
    let x6558 = s[247] * k[33];
    let x6559 = x3090 + x6558;
    let x6560 = x6557 + x6559;
    let x6561 = s[248] * k[32];
    let x6562 = x3094 + x6561;
    let x6563 = s[196] * k[33];
    let x6564 = x3097 + x6563;
    let x6565 = x6562 + x6564;
    let x6566 = dqd[0] + x6555;
    let x6567 = dqd[1] + x6560;
    let x6568 = dqd[2] + x6565;
    let x6569 = x4994 * s[729];
    let x6570 = s[465] * x6566;
    let x6571 = x6569 + x6570;
    let x6572 = x4995 * s[730];
    let x6573 = s[466] * x6567;
    let x6574 = x6572 + x6573;
    let x6575 = x4996 * s[731];
    let x6576 = s[467] * x6568;
    let x6577 = x6575 + x6576;
    let x6578 = x6571 + x6574;
    let x6579 = x6577 + x6578;
    let x6580 = x5001 * s[733];
    let x6582 = s[469] * x6579;
    let x6583 = x6582 - x6580;
    let x6703 = 2.0 * x6566;
    let x6704 = 2.0 * x6567;
    let x6705 = 2.0 * x6568;
    let x6706 = 2.0 * x6583;
    let x6707 = 2.0 * s[469];
    let x6708 = s[733] * x6707;
    let x6709 = s[517] * x6706;
    let x6710 = x5072 * x6708;
    let x6712 = x6709 - x6710;
    let x6787 = 0.8726646259971648 * s[539];
    let x6788 = 0.8726646259971648 * x6787;
    let x6789 = dp[51] * x5114;
    let x6790 = k[9] * x6788;
    let x6792 = x6789 - x6790;
    let x6793 = 2.0 * s[778];
    let x6794 = 2.0 * s[499];
    let x6795 = s[775] * x6794;
    let x6796 = s[523] * x6793;
    let x6797 = x5116 * x6795;
    let x6799 = x6796 - x6797;
    let x6800 = x5115 * s[775];
    let x6802 = s[499] * x6792;
    let x6803 = x6802 - x6800;
    let x6804 = x5118 * s[773];
    let x6805 = s[497] * x6799;
    let x6806 = x6804 + x6805;
    let x6808 = x6803 - x6806;
    let x6977 = s[262] * k[32];
    let x6978 = x3622 + x6977;
    let x6979 = s[285] * k[33];
    let x6980 = x3625 + x6979;
    let x6981 = x6978 + x6980;
    let x6982 = s[286] * k[32];
    let x6983 = x3629 + x6982;
    let x6984 = s[297] * k[33];
    let x6985 = x3632 + x6984;
    let x6986 = x6983 + x6985;
    let x6987 = s[298] * k[32];
    let x6988 = x3636 + x6987;
    let x6989 = s[264] * k[33];
    let x6990 = x3639 + x6989;
    let x6991 = x6988 + x6990;
    let x6992 = x5069 * x6566;
    let x6993 = x4994 * x6703;
    let x6994 = x6992 + x6993;
    let x6995 = x5211 * s[729];
    let x6996 = s[465] * x6981;
    let x6997 = x6995 + x6996;
    let x6998 = x6994 + x6997;
    let x6999 = x5070 * x6567;
    let x7000 = x4995 * x6704;
    let x7001 = x6999 + x7000;
    let x7002 = x5214 * s[730];
    let x7003 = s[466] * x6986;
    let x7004 = x7002 + x7003;
    let x7005 = x7001 + x7004;
    let x7006 = x5071 * x6568;
    let x7007 = x4996 * x6705;
    let x7008 = x7006 + x7007;
    let x7009 = x5217 * s[731];
    let x7010 = s[467] * x6991;
    let x7011 = x7009 + x7010;
    let x7012 = x7008 + x7011;
    let x7013 = x6998 + x7005;
    let x7014 = x7012 + x7013;
    let x7015 = x5074 * x6579;
    let x7016 = x5001 * x6712;
    let x7017 = x7015 + x7016;
    let x7019 = x5228 * s[733];
    let x7021 = s[469] * x7014;
    let x7022 = x7021 - x7019;
    let x7023 = x7022 - x7017;
    let x7024 = x7023 - x6808;
    let x7171 = -x7024;
    gamma[2] = x7171;
    phi[3] = x5678;
    phi_q[21] = x5770;
    phi_q[22] = x5804;
    phi_q[23] = x5828;
}
#[inline(never)]
fn kinematic_tangents_part_6(
    k: &[f64; 53],
    dp: &[f64; 66],
    s: &[f64; 809],
    phi_q: &mut [f64; 46],
    phi_t: &mut [f64; 7],
) {
    let x2321 = s[30] * dp[32];
    let x2324 = s[29] * dp[33];
    let x2328 = s[28] * dp[32];
    let x2331 = s[27] * dp[33];
    let x2336 = s[29] * dp[32];
    let x2340 = s[30] * dp[33];
    let x2517 = s[31] * dp[32];
    let x2520 = s[28] * dp[33];
    let x2524 = s[26] * dp[33];
    let x2667 = s[27] * dp[32];
    let x2671 = s[26] * dp[32];
    let x2798 = s[32] * dp[33];
    let x4670 = s[30] * k[36];
    let x4671 = s[29] * k[37];
    let x4672 = x4670 + x4671;
    let x4673 = s[28] * k[36];
    let x4674 = s[27] * k[37];
    let x4676 = x4673 - x4674;
    let x4677 = s[29] * k[36];
    let x4679 = s[30] * k[37];
    let x4680 = x4679 - x4677;
    let x4681 = s[470] * x4672;
    let x4682 = s[471] * x4676;
    let x4683 = s[472] * x4680;
    let x4684 = x4681 + x4682;
    let x4685 = x4683 + x4684;
    let x4757 = s[31] * k[36];
    let x4758 = s[28] * k[37];
    let x4759 = x4757 + x4758;
    let x4760 = s[26] * k[37];
    let x4762 = x4677 - x4760;
    let x4763 = s[470] * x4759;
    let x4764 = s[471] * x4762;
    let x4765 = s[472] * x4673;
    let x4766 = x4763 + x4764;
    let x4767 = x4765 + x4766;
    let x4823 = s[27] * k[36];
    let x4824 = x4758 + x4823;
    let x4825 = s[26] * k[36];
    let x4826 = s[470] * x4760;
    let x4827 = s[471] * x4824;
    let x4828 = s[472] * x4825;
    let x4830 = x4826 + x4827;
    let x4831 = x4830 - x4828;
    let x4880 = x4671 + x4825;
    let x4881 = s[32] * k[37];
    let x4882 = x4823 + x4881;
    let x4883 = s[470] * x4674;
    let x4884 = s[471] * x4880;
    let x4885 = s[472] * x4882;
    let x4886 = x4883 + x4884;
    let x4887 = x4885 + x4886;
    let x5933 = s[181] * k[36];
    let x5934 = x2321 + x5933;
    let x5935 = s[180] * k[37];
    let x5936 = x2324 + x5935;
    let x5937 = x5934 + x5936;
    let x5938 = s[179] * k[36];
    let x5939 = x2328 + x5938;
    let x5940 = s[178] * k[37];
    let x5941 = x2331 + x5940;
    let x5943 = x5939 - x5941;
    let x5944 = s[180] * k[36];
    let x5945 = x2336 + x5944;
    let x5947 = s[181] * k[37];
    let x5948 = x2340 + x5947;
    let x5949 = x5948 - x5945;
    let x5950 = x4672 * s[734];
    let x5951 = s[470] * x5937;
    let x5952 = x5950 + x5951;
    let x5953 = x4676 * s[735];
    let x5954 = s[471] * x5943;
    let x5955 = x5953 + x5954;
    let x5956 = x4680 * s[736];
    let x5957 = s[472] * x5949;
    let x5958 = x5956 + x5957;
    let x5959 = x5952 + x5955;
    let x5960 = x5958 + x5959;
    let x5961 = x4685 * s[738];
    let x5963 = s[474] * x5960;
    let x5964 = x5963 - x5961;
    let x6101 = s[182] * k[36];
    let x6102 = x2517 + x6101;
    let x6103 = s[179] * k[37];
    let x6104 = x2520 + x6103;
    let x6105 = x6102 + x6104;
    let x6106 = s[177] * k[37];
    let x6107 = x2524 + x6106;
    let x6109 = x5945 - x6107;
    let x6110 = x4759 * s[734];
    let x6111 = s[470] * x6105;
    let x6112 = x6110 + x6111;
    let x6113 = x4762 * s[735];
    let x6114 = s[471] * x6109;
    let x6115 = x6113 + x6114;
    let x6116 = x4673 * s[736];
    let x6117 = s[472] * x5939;
    let x6118 = x6116 + x6117;
    let x6119 = x6112 + x6115;
    let x6120 = x6118 + x6119;
    let x6121 = x4767 * s[738];
    let x6123 = s[474] * x6120;
    let x6124 = x6123 - x6121;
    let x6236 = s[178] * k[36];
    let x6237 = x2667 + x6236;
    let x6238 = x6104 + x6237;
    let x6239 = s[177] * k[36];
    let x6240 = x2671 + x6239;
    let x6241 = x4760 * s[734];
    let x6242 = s[470] * x6107;
    let x6243 = x6241 + x6242;
    let x6244 = x4824 * s[735];
    let x6245 = s[471] * x6238;
    let x6246 = x6244 + x6245;
    let x6247 = x4825 * s[736];
    let x6248 = s[472] * x6240;
    let x6249 = x6247 + x6248;
    let x6251 = x6243 + x6246;
    let x6252 = x6251 - x6249;
    let x6253 = x4831 * s[738];
    let x6255 = s[474] * x6252;
    let x6256 = x6255 - x6253;
    let x6356 = x5936 + x6240;
    let x6357 = s[183] * k[37];
    let x6358 = x2798 + x6357;
    let x6359 = x6237 + x6358;
    let x6360 = x4674 * s[734];
    let x6361 = s[470] * x5941;
    let x6362 = x6360 + x6361;
    let x6363 = x4880 * s[735];
    let x6364 = s[471] * x6356;
    let x6365 = x6363 + x6364;
    let x6366 = x4882 * s[736];
    let x6367 = s[472] * x6359;
    let x6368 = x6366 + x6367;
    let x6369 = x6362 + x6365;
    let x6370 = x6368 + x6369;
    let x6371 = x4887 * s[738];
    let x6373 = s[474] * x6370;
    let x6374 = x6373 - x6371;
    let x6482 = -s[788];
    phi_q[24] = x5964;
    phi_q[25] = x6124;
    phi_q[26] = x6256;
    phi_q[27] = x6374;
    phi_t[3] = x6482;
}
#[inline(never)]
fn kinematic_tangents_part_7(
    k: &[f64; 53],
    qd: &[f64; 7],
    dqd: &[f64; 7],
    dp: &[f64; 66],
    s: &[f64; 809],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 46],
    gamma: &mut [f64; 7],
) {
    let x3119 = s[37] * dp[32];
    let x3122 = s[56] * dp[33];
    let x3126 = s[57] * dp[32];
    let x3129 = s[66] * dp[33];
    let x3133 = s[67] * dp[32];
    let x3136 = s[39] * dp[33];
    let x3676 = s[75] * dp[32];
    let x3679 = s[90] * dp[33];
    let x3683 = s[91] * dp[32];
    let x3686 = s[98] * dp[33];
    let x3690 = s[99] * dp[32];
    let x3693 = s[77] * dp[33];
    let x4930 = s[502] * s[504];
    let x5003 = s[37] * k[36];
    let x5004 = s[56] * k[37];
    let x5005 = x5003 + x5004;
    let x5006 = s[57] * k[36];
    let x5007 = s[66] * k[37];
    let x5008 = x5006 + x5007;
    let x5009 = s[67] * k[36];
    let x5010 = s[39] * k[37];
    let x5011 = x5009 + x5010;
    let x5012 = qd[0] + x5005;
    let x5013 = qd[1] + x5008;
    let x5014 = qd[2] + x5011;
    let x5015 = s[470] * x5012;
    let x5016 = s[471] * x5013;
    let x5017 = s[472] * x5014;
    let x5018 = x5015 + x5016;
    let x5019 = x5017 + x5018;
    let x5020 = s[474] * x5019;
    let x5075 = 2.0 * x5012;
    let x5076 = 2.0 * x5013;
    let x5077 = 2.0 * x5014;
    let x5078 = 2.0 * x5020;
    let x5080 = x5078 * s[518];
    let x5123 = 0.8726646259971648 * s[319];
    let x5124 = 0.8726646259971648 * x5123;
    let x5125 = k[13] * x5124;
    let x5126 = 2.0 * x4930;
    let x5128 = x5126 * s[524];
    let x5234 = s[75] * k[36];
    let x5235 = s[90] * k[37];
    let x5236 = x5234 + x5235;
    let x5237 = s[91] * k[36];
    let x5238 = s[98] * k[37];
    let x5239 = x5237 + x5238;
    let x5240 = s[99] * k[36];
    let x5241 = s[77] * k[37];
    let x5242 = x5240 + x5241;
    let x5243 = x5012 * x5075;
    let x5244 = s[470] * x5236;
    let x5245 = x5243 + x5244;
    let x5246 = x5013 * x5076;
    let x5247 = s[471] * x5239;
    let x5248 = x5246 + x5247;
    let x5249 = x5014 * x5077;
    let x5250 = s[472] * x5242;
    let x5251 = x5249 + x5250;
    let x5252 = x5245 + x5248;
    let x5253 = x5251 + x5252;
    let x5706 = s[692] - s[556];
    let x5776 = s[479] * s[739];
    let x5777 = s[475] * s[743];
    let x5779 = x5776 - x5777;
    let x5805 = s[479] * s[740];
    let x5806 = s[476] * s[743];
    let x5808 = x5805 - x5806;
    let x5829 = s[479] * s[741];
    let x5830 = s[477] * s[743];
    let x5832 = x5829 - x5830;
    let x6584 = s[194] * k[36];
    let x6585 = x3119 + x6584;
    let x6586 = s[229] * k[37];
    let x6587 = x3122 + x6586;
    let x6588 = x6585 + x6587;
    let x6589 = s[230] * k[36];
    let x6590 = x3126 + x6589;
    let x6591 = s[247] * k[37];
    let x6592 = x3129 + x6591;
    let x6593 = x6590 + x6592;
    let x6594 = s[248] * k[36];
    let x6595 = x3133 + x6594;
    let x6596 = s[196] * k[37];
    let x6597 = x3136 + x6596;
    let x6598 = x6595 + x6597;
    let x6599 = dqd[0] + x6588;
    let x6600 = dqd[1] + x6593;
    let x6601 = dqd[2] + x6598;
    let x6602 = x5012 * s[734];
    let x6603 = s[470] * x6599;
    let x6604 = x6602 + x6603;
    let x6605 = x5013 * s[735];
    let x6606 = s[471] * x6600;
    let x6607 = x6605 + x6606;
    let x6608 = x5014 * s[736];
    let x6609 = s[472] * x6601;
    let x6610 = x6608 + x6609;
    let x6611 = x6604 + x6607;
    let x6612 = x6610 + x6611;
    let x6613 = x5019 * s[738];
    let x6615 = s[474] * x6612;
    let x6616 = x6615 - x6613;
    let x6713 = 2.0 * x6599;
    let x6714 = 2.0 * x6600;
    let x6715 = 2.0 * x6601;
    let x6716 = 2.0 * x6616;
    let x6717 = 2.0 * s[474];
    let x6718 = s[738] * x6717;
    let x6719 = s[518] * x6716;
    let x6720 = x5078 * x6718;
    let x6722 = x6719 - x6720;
    let x6809 = 0.8726646259971648 * s[545];
    let x6810 = 0.8726646259971648 * x6809;
    let x6811 = dp[55] * x5124;
    let x6812 = k[13] * x6810;
    let x6814 = x6811 - x6812;
    let x6815 = 2.0 * s[788];
    let x6816 = 2.0 * s[504];
    let x6817 = s[785] * x6816;
    let x6818 = s[524] * x6815;
    let x6819 = x5126 * x6817;
    let x6821 = x6818 - x6819;
    let x6822 = x5125 * s[785];
    let x6824 = s[504] * x6814;
    let x6825 = x6824 - x6822;
    let x6826 = x5128 * s[783];
    let x6827 = s[502] * x6821;
    let x6828 = x6826 + x6827;
    let x6830 = x6825 - x6828;
    let x7025 = s[262] * k[36];
    let x7026 = x3676 + x7025;
    let x7027 = s[285] * k[37];
    let x7028 = x3679 + x7027;
    let x7029 = x7026 + x7028;
    let x7030 = s[286] * k[36];
    let x7031 = x3683 + x7030;
    let x7032 = s[297] * k[37];
    let x7033 = x3686 + x7032;
    let x7034 = x7031 + x7033;
    let x7035 = s[298] * k[36];
    let x7036 = x3690 + x7035;
    let x7037 = s[264] * k[37];
    let x7038 = x3693 + x7037;
    let x7039 = x7036 + x7038;
    let x7040 = x5075 * x6599;
    let x7041 = x5012 * x6713;
    let x7042 = x7040 + x7041;
    let x7043 = x5236 * s[734];
    let x7044 = s[470] * x7029;
    let x7045 = x7043 + x7044;
    let x7046 = x7042 + x7045;
    let x7047 = x5076 * x6600;
    let x7048 = x5013 * x6714;
    let x7049 = x7047 + x7048;
    let x7050 = x5239 * s[735];
    let x7051 = s[471] * x7034;
    let x7052 = x7050 + x7051;
    let x7053 = x7049 + x7052;
    let x7054 = x5077 * x6601;
    let x7055 = x5014 * x6715;
    let x7056 = x7054 + x7055;
    let x7057 = x5242 * s[736];
    let x7058 = s[472] * x7039;
    let x7059 = x7057 + x7058;
    let x7060 = x7056 + x7059;
    let x7061 = x7046 + x7053;
    let x7062 = x7060 + x7061;
    let x7063 = x5080 * x6612;
    let x7064 = x5019 * x6722;
    let x7065 = x7063 + x7064;
    let x7067 = x5253 * s[738];
    let x7069 = s[474] * x7062;
    let x7070 = x7069 - x7067;
    let x7071 = x7070 - x7065;
    let x7072 = x7071 - x6830;
    let x7172 = -x7072;
    gamma[3] = x7172;
    phi[4] = x5706;
    phi_q[28] = x5779;
    phi_q[29] = x5808;
    phi_q[30] = x5832;
}
#[inline(never)]
fn kinematic_tangents_part_8(
    k: &[f64; 53],
    dp: &[f64; 66],
    s: &[f64; 809],
    phi_q: &mut [f64; 46],
    phi_t: &mut [f64; 7],
) {
    let x2359 = s[30] * dp[36];
    let x2362 = s[29] * dp[37];
    let x2366 = s[28] * dp[36];
    let x2369 = s[27] * dp[37];
    let x2374 = s[29] * dp[36];
    let x2378 = s[30] * dp[37];
    let x2544 = s[31] * dp[36];
    let x2547 = s[28] * dp[37];
    let x2551 = s[26] * dp[37];
    let x2690 = s[27] * dp[36];
    let x2694 = s[26] * dp[36];
    let x2818 = s[32] * dp[37];
    let x4687 = s[30] * k[40];
    let x4688 = s[29] * k[41];
    let x4689 = x4687 + x4688;
    let x4690 = s[28] * k[40];
    let x4691 = s[27] * k[41];
    let x4693 = x4690 - x4691;
    let x4694 = s[29] * k[40];
    let x4696 = s[30] * k[41];
    let x4697 = x4696 - x4694;
    let x4698 = s[475] * x4689;
    let x4699 = s[476] * x4693;
    let x4700 = s[477] * x4697;
    let x4701 = x4698 + x4699;
    let x4702 = x4700 + x4701;
    let x4769 = s[31] * k[40];
    let x4770 = s[28] * k[41];
    let x4771 = x4769 + x4770;
    let x4772 = s[26] * k[41];
    let x4774 = x4694 - x4772;
    let x4775 = s[475] * x4771;
    let x4776 = s[476] * x4774;
    let x4777 = s[477] * x4690;
    let x4778 = x4775 + x4776;
    let x4779 = x4777 + x4778;
    let x4833 = s[27] * k[40];
    let x4834 = x4770 + x4833;
    let x4835 = s[26] * k[40];
    let x4836 = s[475] * x4772;
    let x4837 = s[476] * x4834;
    let x4838 = s[477] * x4835;
    let x4840 = x4836 + x4837;
    let x4841 = x4840 - x4838;
    let x4889 = x4688 + x4835;
    let x4890 = s[32] * k[41];
    let x4891 = x4833 + x4890;
    let x4892 = s[475] * x4691;
    let x4893 = s[476] * x4889;
    let x4894 = s[477] * x4891;
    let x4895 = x4892 + x4893;
    let x4896 = x4894 + x4895;
    let x5965 = s[181] * k[40];
    let x5966 = x2359 + x5965;
    let x5967 = s[180] * k[41];
    let x5968 = x2362 + x5967;
    let x5969 = x5966 + x5968;
    let x5970 = s[179] * k[40];
    let x5971 = x2366 + x5970;
    let x5972 = s[178] * k[41];
    let x5973 = x2369 + x5972;
    let x5975 = x5971 - x5973;
    let x5976 = s[180] * k[40];
    let x5977 = x2374 + x5976;
    let x5979 = s[181] * k[41];
    let x5980 = x2378 + x5979;
    let x5981 = x5980 - x5977;
    let x5982 = x4689 * s[739];
    let x5983 = s[475] * x5969;
    let x5984 = x5982 + x5983;
    let x5985 = x4693 * s[740];
    let x5986 = s[476] * x5975;
    let x5987 = x5985 + x5986;
    let x5988 = x4697 * s[741];
    let x5989 = s[477] * x5981;
    let x5990 = x5988 + x5989;
    let x5991 = x5984 + x5987;
    let x5992 = x5990 + x5991;
    let x5993 = x4702 * s[743];
    let x5995 = s[479] * x5992;
    let x5996 = x5995 - x5993;
    let x6125 = s[182] * k[40];
    let x6126 = x2544 + x6125;
    let x6127 = s[179] * k[41];
    let x6128 = x2547 + x6127;
    let x6129 = x6126 + x6128;
    let x6130 = s[177] * k[41];
    let x6131 = x2551 + x6130;
    let x6133 = x5977 - x6131;
    let x6134 = x4771 * s[739];
    let x6135 = s[475] * x6129;
    let x6136 = x6134 + x6135;
    let x6137 = x4774 * s[740];
    let x6138 = s[476] * x6133;
    let x6139 = x6137 + x6138;
    let x6140 = x4690 * s[741];
    let x6141 = s[477] * x5971;
    let x6142 = x6140 + x6141;
    let x6143 = x6136 + x6139;
    let x6144 = x6142 + x6143;
    let x6145 = x4779 * s[743];
    let x6147 = s[479] * x6144;
    let x6148 = x6147 - x6145;
    let x6257 = s[178] * k[40];
    let x6258 = x2690 + x6257;
    let x6259 = x6128 + x6258;
    let x6260 = s[177] * k[40];
    let x6261 = x2694 + x6260;
    let x6262 = x4772 * s[739];
    let x6263 = s[475] * x6131;
    let x6264 = x6262 + x6263;
    let x6265 = x4834 * s[740];
    let x6266 = s[476] * x6259;
    let x6267 = x6265 + x6266;
    let x6268 = x4835 * s[741];
    let x6269 = s[477] * x6261;
    let x6270 = x6268 + x6269;
    let x6272 = x6264 + x6267;
    let x6273 = x6272 - x6270;
    let x6274 = x4841 * s[743];
    let x6276 = s[479] * x6273;
    let x6277 = x6276 - x6274;
    let x6375 = x5968 + x6261;
    let x6376 = s[183] * k[41];
    let x6377 = x2818 + x6376;
    let x6378 = x6258 + x6377;
    let x6379 = x4691 * s[739];
    let x6380 = s[475] * x5973;
    let x6381 = x6379 + x6380;
    let x6382 = x4889 * s[740];
    let x6383 = s[476] * x6375;
    let x6384 = x6382 + x6383;
    let x6385 = x4891 * s[741];
    let x6386 = s[477] * x6378;
    let x6387 = x6385 + x6386;
    let x6388 = x6381 + x6384;
    let x6389 = x6387 + x6388;
    let x6390 = x4896 * s[743];
    let x6392 = s[479] * x6389;
    let x6393 = x6392 - x6390;
    let x6483 = -s[798];
    phi_q[31] = x5996;
    phi_q[32] = x6148;
    phi_q[33] = x6277;
    phi_q[34] = x6393;
    phi_t[4] = x6483;
}
#[inline(never)]
fn kinematic_tangents_part_9(
    k: &[f64; 53],
    qd: &[f64; 7],
    dqd: &[f64; 7],
    dp: &[f64; 66],
    s: &[f64; 809],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 46],
    gamma: &mut [f64; 7],
) {
    let x3158 = s[37] * dp[36];
    let x3161 = s[56] * dp[37];
    let x3165 = s[57] * dp[36];
    let x3168 = s[66] * dp[37];
    let x3172 = s[67] * dp[36];
    let x3175 = s[39] * dp[37];
    let x3730 = s[75] * dp[36];
    let x3733 = s[90] * dp[37];
    let x3737 = s[91] * dp[36];
    let x3740 = s[98] * dp[37];
    let x3744 = s[99] * dp[36];
    let x3747 = s[77] * dp[37];
    let x4936 = s[507] * s[509];
    let x5021 = s[37] * k[40];
    let x5022 = s[56] * k[41];
    let x5023 = x5021 + x5022;
    let x5024 = s[57] * k[40];
    let x5025 = s[66] * k[41];
    let x5026 = x5024 + x5025;
    let x5027 = s[67] * k[40];
    let x5028 = s[39] * k[41];
    let x5029 = x5027 + x5028;
    let x5030 = qd[0] + x5023;
    let x5031 = qd[1] + x5026;
    let x5032 = qd[2] + x5029;
    let x5033 = s[475] * x5030;
    let x5034 = s[476] * x5031;
    let x5035 = s[477] * x5032;
    let x5036 = x5033 + x5034;
    let x5037 = x5035 + x5036;
    let x5038 = s[479] * x5037;
    let x5081 = 2.0 * x5030;
    let x5082 = 2.0 * x5031;
    let x5083 = 2.0 * x5032;
    let x5084 = 2.0 * x5038;
    let x5086 = x5084 * s[519];
    let x5133 = 0.8726646259971648 * s[325];
    let x5134 = 0.8726646259971648 * x5133;
    let x5135 = k[17] * x5134;
    let x5136 = 2.0 * x4936;
    let x5138 = x5136 * s[525];
    let x5259 = s[75] * k[40];
    let x5260 = s[90] * k[41];
    let x5261 = x5259 + x5260;
    let x5262 = s[91] * k[40];
    let x5263 = s[98] * k[41];
    let x5264 = x5262 + x5263;
    let x5265 = s[99] * k[40];
    let x5266 = s[77] * k[41];
    let x5267 = x5265 + x5266;
    let x5268 = x5030 * x5081;
    let x5269 = s[475] * x5261;
    let x5270 = x5268 + x5269;
    let x5271 = x5031 * x5082;
    let x5272 = s[476] * x5264;
    let x5273 = x5271 + x5272;
    let x5274 = x5032 * x5083;
    let x5275 = s[477] * x5267;
    let x5276 = x5274 + x5275;
    let x5277 = x5270 + x5273;
    let x5278 = x5276 + x5277;
    let x5734 = s[718] - s[562];
    let x5785 = s[484] * s[744];
    let x5786 = s[480] * s[748];
    let x5788 = x5785 - x5786;
    let x5809 = s[484] * s[745];
    let x5810 = s[481] * s[748];
    let x5812 = x5809 - x5810;
    let x5833 = s[484] * s[746];
    let x5834 = s[482] * s[748];
    let x5836 = x5833 - x5834;
    let x6617 = s[194] * k[40];
    let x6618 = x3158 + x6617;
    let x6619 = s[229] * k[41];
    let x6620 = x3161 + x6619;
    let x6621 = x6618 + x6620;
    let x6622 = s[230] * k[40];
    let x6623 = x3165 + x6622;
    let x6624 = s[247] * k[41];
    let x6625 = x3168 + x6624;
    let x6626 = x6623 + x6625;
    let x6627 = s[248] * k[40];
    let x6628 = x3172 + x6627;
    let x6629 = s[196] * k[41];
    let x6630 = x3175 + x6629;
    let x6631 = x6628 + x6630;
    let x6632 = dqd[0] + x6621;
    let x6633 = dqd[1] + x6626;
    let x6634 = dqd[2] + x6631;
    let x6635 = x5030 * s[739];
    let x6636 = s[475] * x6632;
    let x6637 = x6635 + x6636;
    let x6638 = x5031 * s[740];
    let x6639 = s[476] * x6633;
    let x6640 = x6638 + x6639;
    let x6641 = x5032 * s[741];
    let x6642 = s[477] * x6634;
    let x6643 = x6641 + x6642;
    let x6644 = x6637 + x6640;
    let x6645 = x6643 + x6644;
    let x6646 = x5037 * s[743];
    let x6648 = s[479] * x6645;
    let x6649 = x6648 - x6646;
    let x6723 = 2.0 * x6632;
    let x6724 = 2.0 * x6633;
    let x6725 = 2.0 * x6634;
    let x6726 = 2.0 * x6649;
    let x6727 = 2.0 * s[479];
    let x6728 = s[743] * x6727;
    let x6729 = s[519] * x6726;
    let x6730 = x5084 * x6728;
    let x6732 = x6729 - x6730;
    let x6831 = 0.8726646259971648 * s[551];
    let x6832 = 0.8726646259971648 * x6831;
    let x6833 = dp[59] * x5134;
    let x6834 = k[17] * x6832;
    let x6836 = x6833 - x6834;
    let x6837 = 2.0 * s[798];
    let x6838 = 2.0 * s[509];
    let x6839 = s[795] * x6838;
    let x6840 = s[525] * x6837;
    let x6841 = x5136 * x6839;
    let x6843 = x6840 - x6841;
    let x6844 = x5135 * s[795];
    let x6846 = s[509] * x6836;
    let x6847 = x6846 - x6844;
    let x6848 = x5138 * s[793];
    let x6849 = s[507] * x6843;
    let x6850 = x6848 + x6849;
    let x6852 = x6847 - x6850;
    let x7073 = s[262] * k[40];
    let x7074 = x3730 + x7073;
    let x7075 = s[285] * k[41];
    let x7076 = x3733 + x7075;
    let x7077 = x7074 + x7076;
    let x7078 = s[286] * k[40];
    let x7079 = x3737 + x7078;
    let x7080 = s[297] * k[41];
    let x7081 = x3740 + x7080;
    let x7082 = x7079 + x7081;
    let x7083 = s[298] * k[40];
    let x7084 = x3744 + x7083;
    let x7085 = s[264] * k[41];
    let x7086 = x3747 + x7085;
    let x7087 = x7084 + x7086;
    let x7088 = x5081 * x6632;
    let x7089 = x5030 * x6723;
    let x7090 = x7088 + x7089;
    let x7091 = x5261 * s[739];
    let x7092 = s[475] * x7077;
    let x7093 = x7091 + x7092;
    let x7094 = x7090 + x7093;
    let x7095 = x5082 * x6633;
    let x7096 = x5031 * x6724;
    let x7097 = x7095 + x7096;
    let x7098 = x5264 * s[740];
    let x7099 = s[476] * x7082;
    let x7100 = x7098 + x7099;
    let x7101 = x7097 + x7100;
    let x7102 = x5083 * x6634;
    let x7103 = x5032 * x6725;
    let x7104 = x7102 + x7103;
    let x7105 = x5267 * s[741];
    let x7106 = s[477] * x7087;
    let x7107 = x7105 + x7106;
    let x7108 = x7104 + x7107;
    let x7109 = x7094 + x7101;
    let x7110 = x7108 + x7109;
    let x7111 = x5086 * x6645;
    let x7112 = x5037 * x6732;
    let x7113 = x7111 + x7112;
    let x7115 = x5278 * s[743];
    let x7117 = s[479] * x7110;
    let x7118 = x7117 - x7115;
    let x7119 = x7118 - x7113;
    let x7120 = x7119 - x6852;
    let x7173 = -x7120;
    gamma[4] = x7173;
    phi[5] = x5734;
    phi_q[35] = x5788;
    phi_q[36] = x5812;
    phi_q[37] = x5836;
}
#[inline(never)]
fn kinematic_tangents_part_10(
    k: &[f64; 53],
    dp: &[f64; 66],
    s: &[f64; 809],
    phi_q: &mut [f64; 46],
    phi_t: &mut [f64; 7],
) {
    let x2397 = s[30] * dp[40];
    let x2400 = s[29] * dp[41];
    let x2404 = s[28] * dp[40];
    let x2407 = s[27] * dp[41];
    let x2412 = s[29] * dp[40];
    let x2416 = s[30] * dp[41];
    let x2571 = s[31] * dp[40];
    let x2574 = s[28] * dp[41];
    let x2578 = s[26] * dp[41];
    let x2713 = s[27] * dp[40];
    let x2717 = s[26] * dp[40];
    let x2838 = s[32] * dp[41];
    let x4704 = s[30] * k[44];
    let x4705 = s[29] * k[45];
    let x4706 = x4704 + x4705;
    let x4707 = s[28] * k[44];
    let x4708 = s[27] * k[45];
    let x4710 = x4707 - x4708;
    let x4711 = s[29] * k[44];
    let x4713 = s[30] * k[45];
    let x4714 = x4713 - x4711;
    let x4715 = s[480] * x4706;
    let x4716 = s[481] * x4710;
    let x4717 = s[482] * x4714;
    let x4718 = x4715 + x4716;
    let x4719 = x4717 + x4718;
    let x4781 = s[31] * k[44];
    let x4782 = s[28] * k[45];
    let x4783 = x4781 + x4782;
    let x4784 = s[26] * k[45];
    let x4786 = x4711 - x4784;
    let x4787 = s[480] * x4783;
    let x4788 = s[481] * x4786;
    let x4789 = s[482] * x4707;
    let x4790 = x4787 + x4788;
    let x4791 = x4789 + x4790;
    let x4843 = s[27] * k[44];
    let x4844 = x4782 + x4843;
    let x4845 = s[26] * k[44];
    let x4846 = s[480] * x4784;
    let x4847 = s[481] * x4844;
    let x4848 = s[482] * x4845;
    let x4850 = x4846 + x4847;
    let x4851 = x4850 - x4848;
    let x4898 = x4705 + x4845;
    let x4899 = s[32] * k[45];
    let x4900 = x4843 + x4899;
    let x4901 = s[480] * x4708;
    let x4902 = s[481] * x4898;
    let x4903 = s[482] * x4900;
    let x4904 = x4901 + x4902;
    let x4905 = x4903 + x4904;
    let x5997 = s[181] * k[44];
    let x5998 = x2397 + x5997;
    let x5999 = s[180] * k[45];
    let x6000 = x2400 + x5999;
    let x6001 = x5998 + x6000;
    let x6002 = s[179] * k[44];
    let x6003 = x2404 + x6002;
    let x6004 = s[178] * k[45];
    let x6005 = x2407 + x6004;
    let x6007 = x6003 - x6005;
    let x6008 = s[180] * k[44];
    let x6009 = x2412 + x6008;
    let x6011 = s[181] * k[45];
    let x6012 = x2416 + x6011;
    let x6013 = x6012 - x6009;
    let x6014 = x4706 * s[744];
    let x6015 = s[480] * x6001;
    let x6016 = x6014 + x6015;
    let x6017 = x4710 * s[745];
    let x6018 = s[481] * x6007;
    let x6019 = x6017 + x6018;
    let x6020 = x4714 * s[746];
    let x6021 = s[482] * x6013;
    let x6022 = x6020 + x6021;
    let x6023 = x6016 + x6019;
    let x6024 = x6022 + x6023;
    let x6025 = x4719 * s[748];
    let x6027 = s[484] * x6024;
    let x6028 = x6027 - x6025;
    let x6149 = s[182] * k[44];
    let x6150 = x2571 + x6149;
    let x6151 = s[179] * k[45];
    let x6152 = x2574 + x6151;
    let x6153 = x6150 + x6152;
    let x6154 = s[177] * k[45];
    let x6155 = x2578 + x6154;
    let x6157 = x6009 - x6155;
    let x6158 = x4783 * s[744];
    let x6159 = s[480] * x6153;
    let x6160 = x6158 + x6159;
    let x6161 = x4786 * s[745];
    let x6162 = s[481] * x6157;
    let x6163 = x6161 + x6162;
    let x6164 = x4707 * s[746];
    let x6165 = s[482] * x6003;
    let x6166 = x6164 + x6165;
    let x6167 = x6160 + x6163;
    let x6168 = x6166 + x6167;
    let x6169 = x4791 * s[748];
    let x6171 = s[484] * x6168;
    let x6172 = x6171 - x6169;
    let x6278 = s[178] * k[44];
    let x6279 = x2713 + x6278;
    let x6280 = x6152 + x6279;
    let x6281 = s[177] * k[44];
    let x6282 = x2717 + x6281;
    let x6283 = x4784 * s[744];
    let x6284 = s[480] * x6155;
    let x6285 = x6283 + x6284;
    let x6286 = x4844 * s[745];
    let x6287 = s[481] * x6280;
    let x6288 = x6286 + x6287;
    let x6289 = x4845 * s[746];
    let x6290 = s[482] * x6282;
    let x6291 = x6289 + x6290;
    let x6293 = x6285 + x6288;
    let x6294 = x6293 - x6291;
    let x6295 = x4851 * s[748];
    let x6297 = s[484] * x6294;
    let x6298 = x6297 - x6295;
    let x6394 = x6000 + x6282;
    let x6395 = s[183] * k[45];
    let x6396 = x2838 + x6395;
    let x6397 = x6279 + x6396;
    let x6398 = x4708 * s[744];
    let x6399 = s[480] * x6005;
    let x6400 = x6398 + x6399;
    let x6401 = x4898 * s[745];
    let x6402 = s[481] * x6394;
    let x6403 = x6401 + x6402;
    let x6404 = x4900 * s[746];
    let x6405 = s[482] * x6397;
    let x6406 = x6404 + x6405;
    let x6407 = x6400 + x6403;
    let x6408 = x6406 + x6407;
    let x6409 = x4905 * s[748];
    let x6411 = s[484] * x6408;
    let x6412 = x6411 - x6409;
    let x6484 = -s[808];
    phi_q[38] = x6028;
    phi_q[39] = x6172;
    phi_q[40] = x6298;
    phi_q[41] = x6412;
    phi_t[5] = x6484;
}
#[inline(never)]
fn kinematic_tangents_part_11(
    k: &[f64; 53],
    qd: &[f64; 7],
    dq: &[f64; 7],
    dqd: &[f64; 7],
    dp: &[f64; 66],
    s: &[f64; 809],
    phi: &mut [f64; 7],
    phi_q: &mut [f64; 46],
    phi_t: &mut [f64; 7],
    gamma: &mut [f64; 7],
) {
    let x981 = 2.0 * qd[5];
    let x1840 = s[29] * dq[5];
    let x2092 = x1840 + s[109];
    let x2093 = s[108] + x2092;
    let x3197 = s[37] * dp[40];
    let x3200 = s[56] * dp[41];
    let x3204 = s[57] * dp[40];
    let x3207 = s[66] * dp[41];
    let x3211 = s[67] * dp[40];
    let x3214 = s[39] * dp[41];
    let x3305 = 2.0 * dqd[5];
    let x3468 = x981 * dqd[5];
    let x3469 = qd[5] * x3305;
    let x3470 = x3468 + x3469;
    let x3784 = s[75] * dp[40];
    let x3787 = s[90] * dp[41];
    let x3791 = s[91] * dp[40];
    let x3794 = s[98] * dp[41];
    let x3798 = s[99] * dp[40];
    let x3801 = s[77] * dp[41];
    let x3838 = x3470 + s[261];
    let x3839 = s[260] + x3838;
    let x3846 = -x3839;
    let x4942 = s[512] * s[514];
    let x5039 = s[37] * k[44];
    let x5040 = s[56] * k[45];
    let x5041 = x5039 + x5040;
    let x5042 = s[57] * k[44];
    let x5043 = s[66] * k[45];
    let x5044 = x5042 + x5043;
    let x5045 = s[67] * k[44];
    let x5046 = s[39] * k[45];
    let x5047 = x5045 + x5046;
    let x5048 = qd[0] + x5041;
    let x5049 = qd[1] + x5044;
    let x5050 = qd[2] + x5047;
    let x5051 = s[480] * x5048;
    let x5052 = s[481] * x5049;
    let x5053 = s[482] * x5050;
    let x5054 = x5051 + x5052;
    let x5055 = x5053 + x5054;
    let x5056 = s[484] * x5055;
    let x5087 = 2.0 * x5048;
    let x5088 = 2.0 * x5049;
    let x5089 = 2.0 * x5050;
    let x5090 = 2.0 * x5056;
    let x5092 = x5090 * s[520];
    let x5143 = 0.8726646259971648 * s[331];
    let x5144 = 0.8726646259971648 * x5143;
    let x5145 = k[21] * x5144;
    let x5146 = 2.0 * x4942;
    let x5148 = x5146 * s[526];
    let x5284 = s[75] * k[44];
    let x5285 = s[90] * k[45];
    let x5286 = x5284 + x5285;
    let x5287 = s[91] * k[44];
    let x5288 = s[98] * k[45];
    let x5289 = x5287 + x5288;
    let x5290 = s[99] * k[44];
    let x5291 = s[77] * k[45];
    let x5292 = x5290 + x5291;
    let x5293 = x5048 * x5087;
    let x5294 = s[480] * x5286;
    let x5295 = x5293 + x5294;
    let x5296 = x5049 * x5088;
    let x5297 = s[481] * x5289;
    let x5298 = x5296 + x5297;
    let x5299 = x5050 * x5089;
    let x5300 = s[482] * x5292;
    let x5301 = x5299 + x5300;
    let x5302 = x5295 + x5298;
    let x5303 = x5301 + x5302;
    let x6650 = s[194] * k[44];
    let x6651 = x3197 + x6650;
    let x6652 = s[229] * k[45];
    let x6653 = x3200 + x6652;
    let x6654 = x6651 + x6653;
    let x6655 = s[230] * k[44];
    let x6656 = x3204 + x6655;
    let x6657 = s[247] * k[45];
    let x6658 = x3207 + x6657;
    let x6659 = x6656 + x6658;
    let x6660 = s[248] * k[44];
    let x6661 = x3211 + x6660;
    let x6662 = s[196] * k[45];
    let x6663 = x3214 + x6662;
    let x6664 = x6661 + x6663;
    let x6665 = dqd[0] + x6654;
    let x6666 = dqd[1] + x6659;
    let x6667 = dqd[2] + x6664;
    let x6668 = x5048 * s[744];
    let x6669 = s[480] * x6665;
    let x6670 = x6668 + x6669;
    let x6671 = x5049 * s[745];
    let x6672 = s[481] * x6666;
    let x6673 = x6671 + x6672;
    let x6674 = x5050 * s[746];
    let x6675 = s[482] * x6667;
    let x6676 = x6674 + x6675;
    let x6677 = x6670 + x6673;
    let x6678 = x6676 + x6677;
    let x6679 = x5055 * s[748];
    let x6681 = s[484] * x6678;
    let x6682 = x6681 - x6679;
    let x6733 = 2.0 * x6665;
    let x6734 = 2.0 * x6666;
    let x6735 = 2.0 * x6667;
    let x6736 = 2.0 * x6682;
    let x6737 = 2.0 * s[484];
    let x6738 = s[748] * x6737;
    let x6739 = s[520] * x6736;
    let x6740 = x5090 * x6738;
    let x6742 = x6739 - x6740;
    let x6853 = 0.8726646259971648 * s[557];
    let x6854 = 0.8726646259971648 * x6853;
    let x6855 = dp[63] * x5144;
    let x6856 = k[21] * x6854;
    let x6858 = x6855 - x6856;
    let x6859 = 2.0 * s[808];
    let x6860 = 2.0 * s[514];
    let x6861 = s[805] * x6860;
    let x6862 = s[526] * x6859;
    let x6863 = x5146 * x6861;
    let x6865 = x6862 - x6863;
    let x6866 = x5145 * s[805];
    let x6868 = s[514] * x6858;
    let x6869 = x6868 - x6866;
    let x6870 = x5148 * s[803];
    let x6871 = s[512] * x6865;
    let x6872 = x6870 + x6871;
    let x6874 = x6869 - x6872;
    let x7121 = s[262] * k[44];
    let x7122 = x3784 + x7121;
    let x7123 = s[285] * k[45];
    let x7124 = x3787 + x7123;
    let x7125 = x7122 + x7124;
    let x7126 = s[286] * k[44];
    let x7127 = x3791 + x7126;
    let x7128 = s[297] * k[45];
    let x7129 = x3794 + x7128;
    let x7130 = x7127 + x7129;
    let x7131 = s[298] * k[44];
    let x7132 = x3798 + x7131;
    let x7133 = s[264] * k[45];
    let x7134 = x3801 + x7133;
    let x7135 = x7132 + x7134;
    let x7136 = x5087 * x6665;
    let x7137 = x5048 * x6733;
    let x7138 = x7136 + x7137;
    let x7139 = x5286 * s[744];
    let x7140 = s[480] * x7125;
    let x7141 = x7139 + x7140;
    let x7142 = x7138 + x7141;
    let x7143 = x5088 * x6666;
    let x7144 = x5049 * x6734;
    let x7145 = x7143 + x7144;
    let x7146 = x5289 * s[745];
    let x7147 = s[481] * x7130;
    let x7148 = x7146 + x7147;
    let x7149 = x7145 + x7148;
    let x7150 = x5089 * x6667;
    let x7151 = x5050 * x6735;
    let x7152 = x7150 + x7151;
    let x7153 = x5292 * s[746];
    let x7154 = s[482] * x7135;
    let x7155 = x7153 + x7154;
    let x7156 = x7152 + x7155;
    let x7157 = x7142 + x7149;
    let x7158 = x7156 + x7157;
    let x7159 = x5092 * x6678;
    let x7160 = x5055 * x6742;
    let x7161 = x7159 + x7160;
    let x7163 = x5303 * s[748];
    let x7165 = s[484] * x7158;
    let x7166 = x7165 - x7163;
    let x7167 = x7166 - x7161;
    let x7168 = x7167 - x6874;
    let x7174 = -x7168;
    gamma[5] = x7174;
    phi[6] = x2093;
    phi_q[42] = s[177];
    phi_q[43] = s[178];
    phi_q[44] = s[180];
    phi_q[45] = s[179];
    phi_t[6] = 0.0;
    gamma[6] = x3846;
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
        point1: [-0.17535097304914957f64, 0f64, -0.20530961071200837f64],
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
            base: [-0.17535097304914957f64, 0f64, -0.20530961071200837f64],
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
pub const N_K: usize = 53;
/// `setup` at the file's parameter values: what the types without parameters read.
pub static K: [f64; 53] = [
    0.20409642230625002f64,
    0.0567f64,
    -0.1832595714594046f64,
    0.8639379797371931f64,
    0.20409642230625002f64,
    0.0567f64,
    -1.911135530933791f64,
    1.2304571226560024f64,
    0.20409642230625002f64,
    0.0567f64,
    -2.2776546738526f64,
    2.9583330821303884f64,
    0.20409642230625002f64,
    0.0567f64,
    -4.005530633326987f64,
    3.324852225049198f64,
    0.20409642230625002f64,
    0.0567f64,
    -4.372049776245795f64,
    5.052728184523584f64,
    0.20409642230625002f64,
    0.0567f64,
    -6.0999257357201815f64,
    5.419247327442394f64,
    0.06819204507466928f64,
    -0.07984262638800324f64,
    -0.2654788250422678f64,
    0.04920359188287982f64,
    0.03504972021954594f64,
    -0.09897735656467874f64,
    0.09012785199311818f64,
    0.2545132025948882f64,
    -0.10324176529421522f64,
    -0.01913473017667551f64,
    0.17535097304914957f64,
    0.20530961071200837f64,
    -0.10324176529421523f64,
    0.019134730176675482f64,
    0.17535097304914954f64,
    -0.20530961071200843f64,
    0.03504972021954594f64,
    0.09897735656467874f64,
    0.09012785199311824f64,
    -0.2545132025948882f64,
    0.0681920450746693f64,
    0.07984262638800323f64,
    -0.2654788250422677f64,
    -0.04920359188287992f64,
    0.105f64,
    0.1575f64,
    0.004134375f64,
    0.00826875f64,
    0.02205f64,
];
/// The values the per-step functions read (`k`), from the run-time parameters `p`.
pub fn setup(p: &[f64], k: &mut [f64]) {
    let p: &[f64; 66] = p.try_into().expect("p must have 66 entries");
    let k: &mut [f64; 53] = k.try_into().expect("k must have 53 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 66], k: &mut [f64; 53]) {
    let x208 = -p[18];
    let x210 = -p[19];
    let x236 = -p[22];
    let x238 = -p[23];
    let x264 = -p[26];
    let x266 = -p[27];
    let x292 = -p[30];
    let x294 = -p[31];
    let x320 = -p[34];
    let x322 = -p[35];
    let x348 = -p[38];
    let x350 = -p[39];
    let x1264 = p[14] * 1.5;
    let x1265 = p[14] * x1264;
    let x1268 = x1265 * 0.25;
    let x1270 = x1265 * 0.5;
    let x1379 = x1268 + x1270;
    let x1380 = x1268 + x1379;
    let x1382 = 4.0 * x1380;
    let x1384 = x1382 * 0.3333333333333333;
    k[0] = p[42];
    k[1] = p[43];
    k[2] = p[44];
    k[3] = p[45];
    k[4] = p[46];
    k[5] = p[47];
    k[6] = p[48];
    k[7] = p[49];
    k[8] = p[50];
    k[9] = p[51];
    k[10] = p[52];
    k[11] = p[53];
    k[12] = p[54];
    k[13] = p[55];
    k[14] = p[56];
    k[15] = p[57];
    k[16] = p[58];
    k[17] = p[59];
    k[18] = p[60];
    k[19] = p[61];
    k[20] = p[62];
    k[21] = p[63];
    k[22] = p[64];
    k[23] = p[65];
    k[24] = p[20];
    k[25] = p[21];
    k[26] = x208;
    k[27] = x210;
    k[28] = p[24];
    k[29] = p[25];
    k[30] = x236;
    k[31] = x238;
    k[32] = p[28];
    k[33] = p[29];
    k[34] = x264;
    k[35] = x266;
    k[36] = p[32];
    k[37] = p[33];
    k[38] = x292;
    k[39] = x294;
    k[40] = p[36];
    k[41] = p[37];
    k[42] = x320;
    k[43] = x322;
    k[44] = p[40];
    k[45] = p[41];
    k[46] = x348;
    k[47] = x350;
    k[48] = p[14];
    k[49] = x1264;
    k[50] = x1268;
    k[51] = x1270;
    k[52] = x1384;
}
/// The parameters the generated code takes at run time by name: the file's
/// `[parameters]` entries that reach only masses, inertias and springs' constants.
pub static PARAMETERS: [&str; 0] = [];
/// Their values in the file.
pub static PARAMETER_VALUES: [f64; 0] = [];
/// Number of values `p` holds: the parameters by name, then the model's numbers that
/// the other parameters reach (read off the file loaded at their values: `DATA`).
pub const N_P: usize = 66;
/// `p` at the file's values.
pub static P0: [f64; 66] = [
    49.5f64,
    70.5f64,
    169.5f64,
    190.5f64,
    289.5f64,
    310.5f64,
    0.3466575f64,
    10.5f64,
    109.5f64,
    130.5f64,
    229.5f64,
    250.5f64,
    349.5f64,
    0.27f64,
    0.105f64,
    0.004134375f64,
    0.00826875f64,
    0.004134375f64,
    0.2654788250422678f64,
    -0.04920359188287982f64,
    0.06819204507466928f64,
    -0.07984262638800324f64,
    -0.09012785199311818f64,
    -0.2545132025948882f64,
    0.03504972021954594f64,
    -0.09897735656467874f64,
    -0.17535097304914957f64,
    -0.20530961071200837f64,
    -0.10324176529421522f64,
    -0.01913473017667551f64,
    -0.17535097304914954f64,
    0.20530961071200843f64,
    -0.10324176529421523f64,
    0.019134730176675482f64,
    -0.09012785199311824f64,
    0.2545132025948882f64,
    0.03504972021954594f64,
    0.09897735656467874f64,
    0.2654788250422677f64,
    0.04920359188287992f64,
    0.0681920450746693f64,
    0.07984262638800323f64,
    0.20409642230625002f64,
    0.0567f64,
    -0.1832595714594046f64,
    0.8639379797371931f64,
    0.20409642230625002f64,
    0.0567f64,
    -1.911135530933791f64,
    1.2304571226560024f64,
    0.20409642230625002f64,
    0.0567f64,
    -2.2776546738526f64,
    2.9583330821303884f64,
    0.20409642230625002f64,
    0.0567f64,
    -4.005530633326987f64,
    3.324852225049198f64,
    0.20409642230625002f64,
    0.0567f64,
    -4.372049776245795f64,
    5.052728184523584f64,
    0.20409642230625002f64,
    0.0567f64,
    -6.0999257357201815f64,
    5.419247327442394f64,
];
/// Where the numbers after the named parameters come from in the model (positions in
/// the generator's `slots::numbers`).
pub static DATA: [u32; 66] = [
    3u32, 4u32, 5u32, 6u32, 7u32, 8u32, 9u32, 10u32, 11u32, 12u32, 13u32, 14u32, 15u32,
    16u32, 17u32, 19u32, 20u32, 21u32, 22u32, 24u32, 31u32, 33u32, 40u32, 42u32, 49u32,
    51u32, 58u32, 60u32, 67u32, 69u32, 76u32, 78u32, 85u32, 87u32, 94u32, 96u32, 103u32,
    105u32, 112u32, 114u32, 121u32, 123u32, 130u32, 131u32, 132u32, 133u32, 135u32,
    136u32, 137u32, 138u32, 140u32, 141u32, 142u32, 143u32, 145u32, 146u32, 147u32,
    148u32, 150u32, 151u32, 152u32, 153u32, 155u32, 156u32, 157u32, 158u32,
];
static OTHER_PARAMETERS: [&str; 18] = [
    "alpha1",
    "alpha2",
    "alpha3",
    "alpha4",
    "alpha5",
    "alpha6",
    "c",
    "h",
    "k",
    "phi1",
    "phi2",
    "phi3",
    "phi4",
    "phi5",
    "phi6",
    "r_base",
    "r_platform",
    "rate",
];
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
    let p: &[f64; 66] = p.try_into().expect("p must have 66 entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    mass_properties_part_0(p, out);
}
#[inline(never)]
fn mass_properties_part_0(p: &[f64; 66], out: &mut [f64; 4]) {
    let x1264 = p[14] * 1.5;
    let x1265 = p[14] * x1264;
    let x1268 = x1265 * 0.25;
    let x1270 = x1265 * 0.5;
    out[0] = 1.5;
    out[1] = x1268;
    out[2] = x1270;
    out[3] = x1268;
}
/// Each force's stiffness and damping at the run-time parameters `p`.
pub fn force_constants(p: &[f64], out: &mut [f64]) {
    let p: &[f64; 66] = p.try_into().expect("p must have 66 entries");
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
        kkt: &KKT,
    };
    use symbody_runtime::kkt::{
        length_error, mass_pivot_error, KktError, KktKernels, Pivoting,
    };
    /// The KKT factor and solve for this model's patterns, straight-line (`KktKernels`).
    pub static KKT: [KktKernels; 1] = [
        KktKernels {
            pattern: 0x62013ffd0d457e7,
            storage: 87,
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
        let phi_q: &[f64; 46] = phi_q
            .try_into()
            .map_err(|_| length_error(46, phi_q.len()))?;
        let st_len = st.len();
        let st: &mut [f64; 87] = st.try_into().map_err(|_| length_error(87, st_len))?;
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
        let v31: f64 = phi_q[1] * v3;
        st[14] = v31;
        let v32: f64 = phi_q[2] * v5;
        st[15] = v32;
        let v33: f64 = phi_q[3] * v7;
        st[16] = v33;
        let v34: f64 = phi_q[4] - v8 * v33;
        let v35: f64 = v34 * v13;
        st[17] = v35;
        let v36: f64 = phi_q[5] - v9 * v33;
        let v37: f64 = v36 - v15 * v35;
        let v38: f64 = v37 * v21;
        st[18] = v38;
        let v39: f64 = phi_q[6] - v10 * v33;
        let v40: f64 = v39 - v17 * v35;
        let v41: f64 = v40 - v24 * v38;
        let v42: f64 = v41 * v29;
        st[19] = v42;
        let v43: f64 = phi_q[7] * v1;
        st[20] = v43;
        let v44: f64 = phi_q[8] * v3;
        st[21] = v44;
        let v45: f64 = phi_q[9] * v5;
        st[22] = v45;
        let v46: f64 = phi_q[10] * v7;
        st[23] = v46;
        let v47: f64 = phi_q[11] - v8 * v46;
        let v48: f64 = v47 * v13;
        st[24] = v48;
        let v49: f64 = phi_q[12] - v9 * v46;
        let v50: f64 = v49 - v15 * v48;
        let v51: f64 = v50 * v21;
        st[25] = v51;
        let v52: f64 = phi_q[13] - v10 * v46;
        let v53: f64 = v52 - v17 * v48;
        let v54: f64 = v53 - v24 * v51;
        let v55: f64 = v54 * v29;
        st[26] = v55;
        let v56: f64 = phi_q[14] * v1;
        st[27] = v56;
        let v57: f64 = phi_q[15] * v3;
        st[28] = v57;
        let v58: f64 = phi_q[16] * v5;
        st[29] = v58;
        let v59: f64 = phi_q[17] * v7;
        st[30] = v59;
        let v60: f64 = phi_q[18] - v8 * v59;
        let v61: f64 = v60 * v13;
        st[31] = v61;
        let v62: f64 = phi_q[19] - v9 * v59;
        let v63: f64 = v62 - v15 * v61;
        let v64: f64 = v63 * v21;
        st[32] = v64;
        let v65: f64 = phi_q[20] - v10 * v59;
        let v66: f64 = v65 - v17 * v61;
        let v67: f64 = v66 - v24 * v64;
        let v68: f64 = v67 * v29;
        st[33] = v68;
        let v69: f64 = phi_q[21] * v1;
        st[34] = v69;
        let v70: f64 = phi_q[22] * v3;
        st[35] = v70;
        let v71: f64 = phi_q[23] * v5;
        st[36] = v71;
        let v72: f64 = phi_q[24] * v7;
        st[37] = v72;
        let v73: f64 = phi_q[25] - v8 * v72;
        let v74: f64 = v73 * v13;
        st[38] = v74;
        let v75: f64 = phi_q[26] - v9 * v72;
        let v76: f64 = v75 - v15 * v74;
        let v77: f64 = v76 * v21;
        st[39] = v77;
        let v78: f64 = phi_q[27] - v10 * v72;
        let v79: f64 = v78 - v17 * v74;
        let v80: f64 = v79 - v24 * v77;
        let v81: f64 = v80 * v29;
        st[40] = v81;
        let v82: f64 = phi_q[28] * v1;
        st[41] = v82;
        let v83: f64 = phi_q[29] * v3;
        st[42] = v83;
        let v84: f64 = phi_q[30] * v5;
        st[43] = v84;
        let v85: f64 = phi_q[31] * v7;
        st[44] = v85;
        let v86: f64 = phi_q[32] - v8 * v85;
        let v87: f64 = v86 * v13;
        st[45] = v87;
        let v88: f64 = phi_q[33] - v9 * v85;
        let v89: f64 = v88 - v15 * v87;
        let v90: f64 = v89 * v21;
        st[46] = v90;
        let v91: f64 = phi_q[34] - v10 * v85;
        let v92: f64 = v91 - v17 * v87;
        let v93: f64 = v92 - v24 * v90;
        let v94: f64 = v93 * v29;
        st[47] = v94;
        let v95: f64 = phi_q[35] * v1;
        st[48] = v95;
        let v96: f64 = phi_q[36] * v3;
        st[49] = v96;
        let v97: f64 = phi_q[37] * v5;
        st[50] = v97;
        let v98: f64 = phi_q[38] * v7;
        st[51] = v98;
        let v99: f64 = phi_q[39] - v8 * v98;
        let v100: f64 = v99 * v13;
        st[52] = v100;
        let v101: f64 = phi_q[40] - v9 * v98;
        let v102: f64 = v101 - v15 * v100;
        let v103: f64 = v102 * v21;
        st[53] = v103;
        let v104: f64 = phi_q[41] - v10 * v98;
        let v105: f64 = v104 - v17 * v100;
        let v106: f64 = v105 - v24 * v103;
        let v107: f64 = v106 * v29;
        st[54] = v107;
        let v108: f64 = phi_q[42] * v7;
        st[55] = v108;
        let v109: f64 = phi_q[43] - v8 * v108;
        let v110: f64 = v109 * v13;
        st[56] = v110;
        let v111: f64 = phi_q[44] - v9 * v108;
        let v112: f64 = v111 - v15 * v110;
        let v113: f64 = v112 * v21;
        st[57] = v113;
        let v114: f64 = phi_q[45] - v10 * v108;
        let v115: f64 = v114 - v17 * v110;
        let v116: f64 = v115 - v24 * v113;
        let v117: f64 = v116 * v29;
        st[58] = v117;
        let v118: f64 = v30 * v30;
        let v119: f64 = v31 * v31;
        let v120: f64 = v118 + v119;
        let v121: f64 = v32 * v32;
        let v122: f64 = v120 + v121;
        let v123: f64 = v33 * v33;
        let v124: f64 = v122 + v123;
        let v125: f64 = v35 * v35;
        let v126: f64 = v124 + v125;
        let v127: f64 = v38 * v38;
        let v128: f64 = v126 + v127;
        let v129: f64 = v42 * v42;
        let v130: f64 = v128 + v129;
        let v131: f64 = v43 * v30;
        let v132: f64 = v44 * v31;
        let v133: f64 = v131 + v132;
        let v134: f64 = v45 * v32;
        let v135: f64 = v133 + v134;
        let v136: f64 = v46 * v33;
        let v137: f64 = v135 + v136;
        let v138: f64 = v48 * v35;
        let v139: f64 = v137 + v138;
        let v140: f64 = v51 * v38;
        let v141: f64 = v139 + v140;
        let v142: f64 = v55 * v42;
        let v143: f64 = v141 + v142;
        let v144: f64 = v43 * v43;
        let v145: f64 = v44 * v44;
        let v146: f64 = v144 + v145;
        let v147: f64 = v45 * v45;
        let v148: f64 = v146 + v147;
        let v149: f64 = v46 * v46;
        let v150: f64 = v148 + v149;
        let v151: f64 = v48 * v48;
        let v152: f64 = v150 + v151;
        let v153: f64 = v51 * v51;
        let v154: f64 = v152 + v153;
        let v155: f64 = v55 * v55;
        let v156: f64 = v154 + v155;
        let v157: f64 = v56 * v30;
        let v158: f64 = v57 * v31;
        let v159: f64 = v157 + v158;
        let v160: f64 = v58 * v32;
        let v161: f64 = v159 + v160;
        let v162: f64 = v59 * v33;
        let v163: f64 = v161 + v162;
        let v164: f64 = v61 * v35;
        let v165: f64 = v163 + v164;
        let v166: f64 = v64 * v38;
        let v167: f64 = v165 + v166;
        let v168: f64 = v68 * v42;
        let v169: f64 = v167 + v168;
        let v170: f64 = v56 * v43;
        let v171: f64 = v57 * v44;
        let v172: f64 = v170 + v171;
        let v173: f64 = v58 * v45;
        let v174: f64 = v172 + v173;
        let v175: f64 = v59 * v46;
        let v176: f64 = v174 + v175;
        let v177: f64 = v61 * v48;
        let v178: f64 = v176 + v177;
        let v179: f64 = v64 * v51;
        let v180: f64 = v178 + v179;
        let v181: f64 = v68 * v55;
        let v182: f64 = v180 + v181;
        let v183: f64 = v56 * v56;
        let v184: f64 = v57 * v57;
        let v185: f64 = v183 + v184;
        let v186: f64 = v58 * v58;
        let v187: f64 = v185 + v186;
        let v188: f64 = v59 * v59;
        let v189: f64 = v187 + v188;
        let v190: f64 = v61 * v61;
        let v191: f64 = v189 + v190;
        let v192: f64 = v64 * v64;
        let v193: f64 = v191 + v192;
        let v194: f64 = v68 * v68;
        let v195: f64 = v193 + v194;
        let v196: f64 = v69 * v30;
        let v197: f64 = v70 * v31;
        let v198: f64 = v196 + v197;
        let v199: f64 = v71 * v32;
        let v200: f64 = v198 + v199;
        let v201: f64 = v72 * v33;
        let v202: f64 = v200 + v201;
        let v203: f64 = v74 * v35;
        let v204: f64 = v202 + v203;
        let v205: f64 = v77 * v38;
        let v206: f64 = v204 + v205;
        let v207: f64 = v81 * v42;
        let v208: f64 = v206 + v207;
        let v209: f64 = v69 * v43;
        let v210: f64 = v70 * v44;
        let v211: f64 = v209 + v210;
        let v212: f64 = v71 * v45;
        let v213: f64 = v211 + v212;
        let v214: f64 = v72 * v46;
        let v215: f64 = v213 + v214;
        let v216: f64 = v74 * v48;
        let v217: f64 = v215 + v216;
        let v218: f64 = v77 * v51;
        let v219: f64 = v217 + v218;
        let v220: f64 = v81 * v55;
        let v221: f64 = v219 + v220;
        let v222: f64 = v69 * v56;
        let v223: f64 = v70 * v57;
        let v224: f64 = v222 + v223;
        let v225: f64 = v71 * v58;
        let v226: f64 = v224 + v225;
        let v227: f64 = v72 * v59;
        let v228: f64 = v226 + v227;
        let v229: f64 = v74 * v61;
        let v230: f64 = v228 + v229;
        let v231: f64 = v77 * v64;
        let v232: f64 = v230 + v231;
        let v233: f64 = v81 * v68;
        let v234: f64 = v232 + v233;
        let v235: f64 = v69 * v69;
        let v236: f64 = v70 * v70;
        let v237: f64 = v235 + v236;
        let v238: f64 = v71 * v71;
        let v239: f64 = v237 + v238;
        let v240: f64 = v72 * v72;
        let v241: f64 = v239 + v240;
        let v242: f64 = v74 * v74;
        let v243: f64 = v241 + v242;
        let v244: f64 = v77 * v77;
        let v245: f64 = v243 + v244;
        let v246: f64 = v81 * v81;
        let v247: f64 = v245 + v246;
        let v248: f64 = v82 * v30;
        let v249: f64 = v83 * v31;
        let v250: f64 = v248 + v249;
        let v251: f64 = v84 * v32;
        let v252: f64 = v250 + v251;
        let v253: f64 = v85 * v33;
        let v254: f64 = v252 + v253;
        let v255: f64 = v87 * v35;
        let v256: f64 = v254 + v255;
        let v257: f64 = v90 * v38;
        let v258: f64 = v256 + v257;
        let v259: f64 = v94 * v42;
        let v260: f64 = v258 + v259;
        let v261: f64 = v82 * v43;
        let v262: f64 = v83 * v44;
        let v263: f64 = v261 + v262;
        let v264: f64 = v84 * v45;
        let v265: f64 = v263 + v264;
        let v266: f64 = v85 * v46;
        let v267: f64 = v265 + v266;
        let v268: f64 = v87 * v48;
        let v269: f64 = v267 + v268;
        let v270: f64 = v90 * v51;
        let v271: f64 = v269 + v270;
        let v272: f64 = v94 * v55;
        let v273: f64 = v271 + v272;
        let v274: f64 = v82 * v56;
        let v275: f64 = v83 * v57;
        let v276: f64 = v274 + v275;
        let v277: f64 = v84 * v58;
        let v278: f64 = v276 + v277;
        let v279: f64 = v85 * v59;
        let v280: f64 = v278 + v279;
        let v281: f64 = v87 * v61;
        let v282: f64 = v280 + v281;
        let v283: f64 = v90 * v64;
        let v284: f64 = v282 + v283;
        let v285: f64 = v94 * v68;
        let v286: f64 = v284 + v285;
        let v287: f64 = v82 * v69;
        let v288: f64 = v83 * v70;
        let v289: f64 = v287 + v288;
        let v290: f64 = v84 * v71;
        let v291: f64 = v289 + v290;
        let v292: f64 = v85 * v72;
        let v293: f64 = v291 + v292;
        let v294: f64 = v87 * v74;
        let v295: f64 = v293 + v294;
        let v296: f64 = v90 * v77;
        let v297: f64 = v295 + v296;
        let v298: f64 = v94 * v81;
        let v299: f64 = v297 + v298;
        let v300: f64 = v82 * v82;
        let v301: f64 = v83 * v83;
        let v302: f64 = v300 + v301;
        let v303: f64 = v84 * v84;
        let v304: f64 = v302 + v303;
        let v305: f64 = v85 * v85;
        let v306: f64 = v304 + v305;
        let v307: f64 = v87 * v87;
        let v308: f64 = v306 + v307;
        let v309: f64 = v90 * v90;
        let v310: f64 = v308 + v309;
        let v311: f64 = v94 * v94;
        let v312: f64 = v310 + v311;
        let v313: f64 = v95 * v30;
        let v314: f64 = v96 * v31;
        let v315: f64 = v313 + v314;
        let v316: f64 = v97 * v32;
        let v317: f64 = v315 + v316;
        let v318: f64 = v98 * v33;
        let v319: f64 = v317 + v318;
        let v320: f64 = v100 * v35;
        let v321: f64 = v319 + v320;
        let v322: f64 = v103 * v38;
        let v323: f64 = v321 + v322;
        let v324: f64 = v107 * v42;
        let v325: f64 = v323 + v324;
        let v326: f64 = v95 * v43;
        let v327: f64 = v96 * v44;
        let v328: f64 = v326 + v327;
        let v329: f64 = v97 * v45;
        let v330: f64 = v328 + v329;
        let v331: f64 = v98 * v46;
        let v332: f64 = v330 + v331;
        let v333: f64 = v100 * v48;
        let v334: f64 = v332 + v333;
        let v335: f64 = v103 * v51;
        let v336: f64 = v334 + v335;
        let v337: f64 = v107 * v55;
        let v338: f64 = v336 + v337;
        let v339: f64 = v95 * v56;
        let v340: f64 = v96 * v57;
        let v341: f64 = v339 + v340;
        let v342: f64 = v97 * v58;
        let v343: f64 = v341 + v342;
        let v344: f64 = v98 * v59;
        let v345: f64 = v343 + v344;
        let v346: f64 = v100 * v61;
        let v347: f64 = v345 + v346;
        let v348: f64 = v103 * v64;
        let v349: f64 = v347 + v348;
        let v350: f64 = v107 * v68;
        let v351: f64 = v349 + v350;
        let v352: f64 = v95 * v69;
        let v353: f64 = v96 * v70;
        let v354: f64 = v352 + v353;
        let v355: f64 = v97 * v71;
        let v356: f64 = v354 + v355;
        let v357: f64 = v98 * v72;
        let v358: f64 = v356 + v357;
        let v359: f64 = v100 * v74;
        let v360: f64 = v358 + v359;
        let v361: f64 = v103 * v77;
        let v362: f64 = v360 + v361;
        let v363: f64 = v107 * v81;
        let v364: f64 = v362 + v363;
        let v365: f64 = v95 * v82;
        let v366: f64 = v96 * v83;
        let v367: f64 = v365 + v366;
        let v368: f64 = v97 * v84;
        let v369: f64 = v367 + v368;
        let v370: f64 = v98 * v85;
        let v371: f64 = v369 + v370;
        let v372: f64 = v100 * v87;
        let v373: f64 = v371 + v372;
        let v374: f64 = v103 * v90;
        let v375: f64 = v373 + v374;
        let v376: f64 = v107 * v94;
        let v377: f64 = v375 + v376;
        let v378: f64 = v95 * v95;
        let v379: f64 = v96 * v96;
        let v380: f64 = v378 + v379;
        let v381: f64 = v97 * v97;
        let v382: f64 = v380 + v381;
        let v383: f64 = v98 * v98;
        let v384: f64 = v382 + v383;
        let v385: f64 = v100 * v100;
        let v386: f64 = v384 + v385;
        let v387: f64 = v103 * v103;
        let v388: f64 = v386 + v387;
        let v389: f64 = v107 * v107;
        let v390: f64 = v388 + v389;
        let v391: f64 = v108 * v33;
        let v392: f64 = v110 * v35;
        let v393: f64 = v391 + v392;
        let v394: f64 = v113 * v38;
        let v395: f64 = v393 + v394;
        let v396: f64 = v117 * v42;
        let v397: f64 = v395 + v396;
        let v398: f64 = v108 * v46;
        let v399: f64 = v110 * v48;
        let v400: f64 = v398 + v399;
        let v401: f64 = v113 * v51;
        let v402: f64 = v400 + v401;
        let v403: f64 = v117 * v55;
        let v404: f64 = v402 + v403;
        let v405: f64 = v108 * v59;
        let v406: f64 = v110 * v61;
        let v407: f64 = v405 + v406;
        let v408: f64 = v113 * v64;
        let v409: f64 = v407 + v408;
        let v410: f64 = v117 * v68;
        let v411: f64 = v409 + v410;
        let v412: f64 = v108 * v72;
        let v413: f64 = v110 * v74;
        let v414: f64 = v412 + v413;
        let v415: f64 = v113 * v77;
        let v416: f64 = v414 + v415;
        let v417: f64 = v117 * v81;
        let v418: f64 = v416 + v417;
        let v419: f64 = v108 * v85;
        let v420: f64 = v110 * v87;
        let v421: f64 = v419 + v420;
        let v422: f64 = v113 * v90;
        let v423: f64 = v421 + v422;
        let v424: f64 = v117 * v94;
        let v425: f64 = v423 + v424;
        let v426: f64 = v108 * v98;
        let v427: f64 = v110 * v100;
        let v428: f64 = v426 + v427;
        let v429: f64 = v113 * v103;
        let v430: f64 = v428 + v429;
        let v431: f64 = v117 * v107;
        let v432: f64 = v430 + v431;
        let v433: f64 = v108 * v108;
        let v434: f64 = v110 * v110;
        let v435: f64 = v433 + v434;
        let v436: f64 = v113 * v113;
        let v437: f64 = v435 + v436;
        let v438: f64 = v117 * v117;
        let v439: f64 = v437 + v438;
        let (v440, v441) = piv.pivot(v439, v439, 6, false)?;
        st[80] = v440;
        let v442: f64 = v397 * v440;
        st[59] = v442;
        let v443: f64 = v130 - v442 * v441 * v442;
        let v444: f64 = v404 * v440;
        st[60] = v444;
        let v445: f64 = v156 - v444 * v441 * v444;
        let v446: f64 = v411 * v440;
        st[61] = v446;
        let v447: f64 = v195 - v446 * v441 * v446;
        let v448: f64 = v418 * v440;
        st[62] = v448;
        let v449: f64 = v247 - v448 * v441 * v448;
        let v450: f64 = v425 * v440;
        st[63] = v450;
        let v451: f64 = v312 - v450 * v441 * v450;
        let v452: f64 = v432 * v440;
        st[64] = v452;
        let v453: f64 = v390 - v452 * v441 * v452;
        let v454: f64 = v143 - v444 * v441 * v442;
        let v455: f64 = v169 - v446 * v441 * v442;
        let v456: f64 = v182 - v446 * v441 * v444;
        let v457: f64 = v208 - v448 * v441 * v442;
        let v458: f64 = v221 - v448 * v441 * v444;
        let v459: f64 = v234 - v448 * v441 * v446;
        let v460: f64 = v260 - v450 * v441 * v442;
        let v461: f64 = v273 - v450 * v441 * v444;
        let v462: f64 = v286 - v450 * v441 * v446;
        let v463: f64 = v299 - v450 * v441 * v448;
        let v464: f64 = v325 - v452 * v441 * v442;
        let v465: f64 = v338 - v452 * v441 * v444;
        let v466: f64 = v351 - v452 * v441 * v446;
        let v467: f64 = v364 - v452 * v441 * v448;
        let v468: f64 = v377 - v452 * v441 * v450;
        let (v469, v470) = piv.pivot(v443, v443, 0, false)?;
        st[81] = v469;
        let v471: f64 = v454 * v469;
        st[65] = v471;
        let v472: f64 = v445 - v471 * v470 * v471;
        let v473: f64 = v455 * v469;
        st[66] = v473;
        let v474: f64 = v447 - v473 * v470 * v473;
        let v475: f64 = v457 * v469;
        st[67] = v475;
        let v476: f64 = v449 - v475 * v470 * v475;
        let v477: f64 = v460 * v469;
        st[68] = v477;
        let v478: f64 = v451 - v477 * v470 * v477;
        let v479: f64 = v464 * v469;
        st[69] = v479;
        let v480: f64 = v453 - v479 * v470 * v479;
        let v481: f64 = v456 - v473 * v470 * v471;
        let v482: f64 = v458 - v475 * v470 * v471;
        let v483: f64 = v459 - v475 * v470 * v473;
        let v484: f64 = v461 - v477 * v470 * v471;
        let v485: f64 = v462 - v477 * v470 * v473;
        let v486: f64 = v463 - v477 * v470 * v475;
        let v487: f64 = v465 - v479 * v470 * v471;
        let v488: f64 = v466 - v479 * v470 * v473;
        let v489: f64 = v467 - v479 * v470 * v475;
        let v490: f64 = v468 - v479 * v470 * v477;
        let (v491, v492) = piv.pivot(v472, v445, 1, false)?;
        st[82] = v491;
        let v493: f64 = v481 * v491;
        st[70] = v493;
        let v494: f64 = v474 - v493 * v492 * v493;
        let v495: f64 = v482 * v491;
        st[71] = v495;
        let v496: f64 = v476 - v495 * v492 * v495;
        let v497: f64 = v484 * v491;
        st[72] = v497;
        let v498: f64 = v478 - v497 * v492 * v497;
        let v499: f64 = v487 * v491;
        st[73] = v499;
        let v500: f64 = v480 - v499 * v492 * v499;
        let v501: f64 = v483 - v495 * v492 * v493;
        let v502: f64 = v485 - v497 * v492 * v493;
        let v503: f64 = v486 - v497 * v492 * v495;
        let v504: f64 = v488 - v499 * v492 * v493;
        let v505: f64 = v489 - v499 * v492 * v495;
        let v506: f64 = v490 - v499 * v492 * v497;
        let (v507, v508) = piv.pivot(v494, v447, 2, false)?;
        st[83] = v507;
        let v509: f64 = v501 * v507;
        st[74] = v509;
        let v510: f64 = v496 - v509 * v508 * v509;
        let v511: f64 = v502 * v507;
        st[75] = v511;
        let v512: f64 = v498 - v511 * v508 * v511;
        let v513: f64 = v504 * v507;
        st[76] = v513;
        let v514: f64 = v500 - v513 * v508 * v513;
        let v515: f64 = v503 - v511 * v508 * v509;
        let v516: f64 = v505 - v513 * v508 * v509;
        let v517: f64 = v506 - v513 * v508 * v511;
        let (v518, v519) = piv.pivot(v510, v449, 3, false)?;
        st[84] = v518;
        let v520: f64 = v515 * v518;
        st[77] = v520;
        let v521: f64 = v512 - v520 * v519 * v520;
        let v522: f64 = v516 * v518;
        st[78] = v522;
        let v523: f64 = v514 - v522 * v519 * v522;
        let v524: f64 = v517 - v522 * v519 * v520;
        let (v525, v526) = piv.pivot(v521, v451, 4, false)?;
        st[85] = v525;
        let v527: f64 = v524 * v525;
        st[79] = v527;
        let v528: f64 = v523 - v527 * v526 * v527;
        let (v529, v530) = piv.pivot(v528, v453, 5, false)?;
        st[86] = v529;
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
        let st: &[f64; 87] = st.try_into().map_err(|_| length_error(87, st.len()))?;
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
            let v21: f64 = st[14] * v8;
            let v22: f64 = v20 + v21;
            let v23: f64 = st[15] * v9;
            let v24: f64 = v22 + v23;
            let v25: f64 = st[16] * v10;
            let v26: f64 = v24 + v25;
            let v27: f64 = st[17] * v12;
            let v28: f64 = v26 + v27;
            let v29: f64 = st[18] * v15;
            let v30: f64 = v28 + v29;
            let v31: f64 = st[19] * v19;
            let v32: f64 = v30 + v31;
            y[0] += v32;
            let v33: f64 = st[20] * v7;
            let v34: f64 = st[21] * v8;
            let v35: f64 = v33 + v34;
            let v36: f64 = st[22] * v9;
            let v37: f64 = v35 + v36;
            let v38: f64 = st[23] * v10;
            let v39: f64 = v37 + v38;
            let v40: f64 = st[24] * v12;
            let v41: f64 = v39 + v40;
            let v42: f64 = st[25] * v15;
            let v43: f64 = v41 + v42;
            let v44: f64 = st[26] * v19;
            let v45: f64 = v43 + v44;
            y[1] += v45;
            let v46: f64 = st[27] * v7;
            let v47: f64 = st[28] * v8;
            let v48: f64 = v46 + v47;
            let v49: f64 = st[29] * v9;
            let v50: f64 = v48 + v49;
            let v51: f64 = st[30] * v10;
            let v52: f64 = v50 + v51;
            let v53: f64 = st[31] * v12;
            let v54: f64 = v52 + v53;
            let v55: f64 = st[32] * v15;
            let v56: f64 = v54 + v55;
            let v57: f64 = st[33] * v19;
            let v58: f64 = v56 + v57;
            y[2] += v58;
            let v59: f64 = st[34] * v7;
            let v60: f64 = st[35] * v8;
            let v61: f64 = v59 + v60;
            let v62: f64 = st[36] * v9;
            let v63: f64 = v61 + v62;
            let v64: f64 = st[37] * v10;
            let v65: f64 = v63 + v64;
            let v66: f64 = st[38] * v12;
            let v67: f64 = v65 + v66;
            let v68: f64 = st[39] * v15;
            let v69: f64 = v67 + v68;
            let v70: f64 = st[40] * v19;
            let v71: f64 = v69 + v70;
            y[3] += v71;
            let v72: f64 = st[41] * v7;
            let v73: f64 = st[42] * v8;
            let v74: f64 = v72 + v73;
            let v75: f64 = st[43] * v9;
            let v76: f64 = v74 + v75;
            let v77: f64 = st[44] * v10;
            let v78: f64 = v76 + v77;
            let v79: f64 = st[45] * v12;
            let v80: f64 = v78 + v79;
            let v81: f64 = st[46] * v15;
            let v82: f64 = v80 + v81;
            let v83: f64 = st[47] * v19;
            let v84: f64 = v82 + v83;
            y[4] += v84;
            let v85: f64 = st[48] * v7;
            let v86: f64 = st[49] * v8;
            let v87: f64 = v85 + v86;
            let v88: f64 = st[50] * v9;
            let v89: f64 = v87 + v88;
            let v90: f64 = st[51] * v10;
            let v91: f64 = v89 + v90;
            let v92: f64 = st[52] * v12;
            let v93: f64 = v91 + v92;
            let v94: f64 = st[53] * v15;
            let v95: f64 = v93 + v94;
            let v96: f64 = st[54] * v19;
            let v97: f64 = v95 + v96;
            y[5] += v97;
            let v98: f64 = st[55] * v10;
            let v99: f64 = st[56] * v12;
            let v100: f64 = v98 + v99;
            let v101: f64 = st[57] * v15;
            let v102: f64 = v100 + v101;
            let v103: f64 = st[58] * v19;
            let v104: f64 = v102 + v103;
            y[6] += v104;
            x[0] = v7;
            x[1] = v8;
            x[2] = v9;
            x[3] = v10;
            x[4] = v12;
            x[5] = v15;
            x[6] = v19;
        }
        let v105: f64 = y[0] - st[59] * y[6];
        let v106: f64 = y[1] - st[60] * y[6];
        let v107: f64 = y[2] - st[61] * y[6];
        let v108: f64 = y[3] - st[62] * y[6];
        let v109: f64 = y[4] - st[63] * y[6];
        let v110: f64 = y[5] - st[64] * y[6];
        let v111: f64 = v106 - st[65] * v105;
        let v112: f64 = v107 - st[66] * v105;
        let v113: f64 = v108 - st[67] * v105;
        let v114: f64 = v109 - st[68] * v105;
        let v115: f64 = v110 - st[69] * v105;
        let v116: f64 = v112 - st[70] * v111;
        let v117: f64 = v113 - st[71] * v111;
        let v118: f64 = v114 - st[72] * v111;
        let v119: f64 = v115 - st[73] * v111;
        let v120: f64 = v117 - st[74] * v116;
        let v121: f64 = v118 - st[75] * v116;
        let v122: f64 = v119 - st[76] * v116;
        let v123: f64 = v121 - st[77] * v120;
        let v124: f64 = v122 - st[78] * v120;
        let v125: f64 = v124 - st[79] * v123;
        let v126: f64 = y[6] * st[80];
        let v127: f64 = v105 * st[81];
        let v128: f64 = v111 * st[82];
        let v129: f64 = v116 * st[83];
        let v130: f64 = v120 * st[84];
        let v131: f64 = v123 * st[85];
        let v132: f64 = v125 * st[86];
        let v133: f64 = v131 - st[79] * v132;
        let v134: f64 = v130 - st[77] * v133;
        let v135: f64 = v134 - st[78] * v132;
        let v136: f64 = v129 - st[74] * v135;
        let v137: f64 = v136 - st[75] * v133;
        let v138: f64 = v137 - st[76] * v132;
        let v139: f64 = v128 - st[70] * v138;
        let v140: f64 = v139 - st[71] * v135;
        let v141: f64 = v140 - st[72] * v133;
        let v142: f64 = v141 - st[73] * v132;
        let v143: f64 = v127 - st[65] * v142;
        let v144: f64 = v143 - st[66] * v138;
        let v145: f64 = v144 - st[67] * v135;
        let v146: f64 = v145 - st[68] * v133;
        let v147: f64 = v146 - st[69] * v132;
        let v148: f64 = v126 - st[59] * v147;
        let v149: f64 = v148 - st[60] * v142;
        let v150: f64 = v149 - st[61] * v138;
        let v151: f64 = v150 - st[62] * v135;
        let v152: f64 = v151 - st[63] * v133;
        let v153: f64 = v152 - st[64] * v132;
        y[6] = v153;
        y[0] = v147;
        y[1] = v142;
        y[2] = v138;
        y[3] = v135;
        y[4] = v133;
        y[5] = v132;
        let v154: f64 = x[0] - st[13] * v147;
        let v155: f64 = x[1] - st[14] * v147;
        let v156: f64 = x[2] - st[15] * v147;
        let v157: f64 = x[3] - st[16] * v147;
        let v158: f64 = x[4] - st[17] * v147;
        let v159: f64 = x[5] - st[18] * v147;
        let v160: f64 = x[6] - st[19] * v147;
        let v161: f64 = v154 - st[20] * v142;
        let v162: f64 = v155 - st[21] * v142;
        let v163: f64 = v156 - st[22] * v142;
        let v164: f64 = v157 - st[23] * v142;
        let v165: f64 = v158 - st[24] * v142;
        let v166: f64 = v159 - st[25] * v142;
        let v167: f64 = v160 - st[26] * v142;
        let v168: f64 = v161 - st[27] * v138;
        let v169: f64 = v162 - st[28] * v138;
        let v170: f64 = v163 - st[29] * v138;
        let v171: f64 = v164 - st[30] * v138;
        let v172: f64 = v165 - st[31] * v138;
        let v173: f64 = v166 - st[32] * v138;
        let v174: f64 = v167 - st[33] * v138;
        let v175: f64 = v168 - st[34] * v135;
        let v176: f64 = v169 - st[35] * v135;
        let v177: f64 = v170 - st[36] * v135;
        let v178: f64 = v171 - st[37] * v135;
        let v179: f64 = v172 - st[38] * v135;
        let v180: f64 = v173 - st[39] * v135;
        let v181: f64 = v174 - st[40] * v135;
        let v182: f64 = v175 - st[41] * v133;
        let v183: f64 = v176 - st[42] * v133;
        let v184: f64 = v177 - st[43] * v133;
        let v185: f64 = v178 - st[44] * v133;
        let v186: f64 = v179 - st[45] * v133;
        let v187: f64 = v180 - st[46] * v133;
        let v188: f64 = v181 - st[47] * v133;
        let v189: f64 = v182 - st[48] * v132;
        let v190: f64 = v183 - st[49] * v132;
        let v191: f64 = v184 - st[50] * v132;
        let v192: f64 = v185 - st[51] * v132;
        let v193: f64 = v186 - st[52] * v132;
        let v194: f64 = v187 - st[53] * v132;
        let v195: f64 = v188 - st[54] * v132;
        let v196: f64 = v192 - st[55] * v153;
        let v197: f64 = v193 - st[56] * v153;
        let v198: f64 = v194 - st[57] * v153;
        let v199: f64 = v195 - st[58] * v153;
        let v200: f64 = v199 * st[12];
        let v201: f64 = v198 - st[5] * v200;
        let v202: f64 = v201 * st[11];
        let v203: f64 = v197 - st[2] * v202;
        let v204: f64 = v203 - st[4] * v200;
        let v205: f64 = v204 * st[10];
        let v206: f64 = v196 - st[0] * v205;
        let v207: f64 = v206 - st[1] * v202;
        let v208: f64 = v207 - st[3] * v200;
        let v209: f64 = v208 * st[9];
        let v210: f64 = v191 * st[8];
        let v211: f64 = v190 * st[7];
        let v212: f64 = v189 * st[6];
        x[0] = v212;
        x[1] = v211;
        x[2] = v210;
        x[3] = v209;
        x[4] = v205;
        x[5] = v202;
        x[6] = v200;
        Ok(())
    }
    fn kkt_transpose_times(
        phi_q: &[f64],
        y: &[f64],
        out: &mut [f64],
    ) -> Result<(), KktError> {
        let phi_q: &[f64; 46] = phi_q
            .try_into()
            .map_err(|_| length_error(46, phi_q.len()))?;
        let y: &[f64; 7] = y.try_into().map_err(|_| length_error(7, y.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 7] = out.try_into().map_err(|_| length_error(7, out_len))?;
        out[0] = phi_q[0] * y[0] + phi_q[7] * y[1] + phi_q[14] * y[2] + phi_q[21] * y[3]
            + phi_q[28] * y[4] + phi_q[35] * y[5];
        out[1] = phi_q[1] * y[0] + phi_q[8] * y[1] + phi_q[15] * y[2] + phi_q[22] * y[3]
            + phi_q[29] * y[4] + phi_q[36] * y[5];
        out[2] = phi_q[2] * y[0] + phi_q[9] * y[1] + phi_q[16] * y[2] + phi_q[23] * y[3]
            + phi_q[30] * y[4] + phi_q[37] * y[5];
        out[3] = phi_q[3] * y[0] + phi_q[10] * y[1] + phi_q[17] * y[2] + phi_q[24] * y[3]
            + phi_q[31] * y[4] + phi_q[38] * y[5] + phi_q[42] * y[6];
        out[4] = phi_q[4] * y[0] + phi_q[11] * y[1] + phi_q[18] * y[2] + phi_q[25] * y[3]
            + phi_q[32] * y[4] + phi_q[39] * y[5] + phi_q[43] * y[6];
        out[5] = phi_q[5] * y[0] + phi_q[12] * y[1] + phi_q[19] * y[2] + phi_q[26] * y[3]
            + phi_q[33] * y[4] + phi_q[40] * y[5] + phi_q[44] * y[6];
        out[6] = phi_q[6] * y[0] + phi_q[13] * y[1] + phi_q[20] * y[2] + phi_q[27] * y[3]
            + phi_q[34] * y[4] + phi_q[41] * y[5] + phi_q[45] * y[6];
        Ok(())
    }
    #[allow(clippy::assign_op_pattern)]
    fn kkt_times_add(phi_q: &[f64], x: &[f64], out: &mut [f64]) -> Result<(), KktError> {
        let phi_q: &[f64; 46] = phi_q
            .try_into()
            .map_err(|_| length_error(46, phi_q.len()))?;
        let x: &[f64; 7] = x.try_into().map_err(|_| length_error(7, x.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 7] = out.try_into().map_err(|_| length_error(7, out_len))?;
        out[0] = out[0] + phi_q[0] * x[0] + phi_q[1] * x[1] + phi_q[2] * x[2]
            + phi_q[3] * x[3] + phi_q[4] * x[4] + phi_q[5] * x[5] + phi_q[6] * x[6];
        out[1] = out[1] + phi_q[7] * x[0] + phi_q[8] * x[1] + phi_q[9] * x[2]
            + phi_q[10] * x[3] + phi_q[11] * x[4] + phi_q[12] * x[5] + phi_q[13] * x[6];
        out[2] = out[2] + phi_q[14] * x[0] + phi_q[15] * x[1] + phi_q[16] * x[2]
            + phi_q[17] * x[3] + phi_q[18] * x[4] + phi_q[19] * x[5] + phi_q[20] * x[6];
        out[3] = out[3] + phi_q[21] * x[0] + phi_q[22] * x[1] + phi_q[23] * x[2]
            + phi_q[24] * x[3] + phi_q[25] * x[4] + phi_q[26] * x[5] + phi_q[27] * x[6];
        out[4] = out[4] + phi_q[28] * x[0] + phi_q[29] * x[1] + phi_q[30] * x[2]
            + phi_q[31] * x[3] + phi_q[32] * x[4] + phi_q[33] * x[5] + phi_q[34] * x[6];
        out[5] = out[5] + phi_q[35] * x[0] + phi_q[36] * x[1] + phi_q[37] * x[2]
            + phi_q[38] * x[3] + phi_q[39] * x[4] + phi_q[40] * x[5] + phi_q[41] * x[6];
        out[6] = out[6] + phi_q[42] * x[3] + phi_q[43] * x[4] + phi_q[44] * x[5]
            + phi_q[45] * x[6];
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
        let k: &[f64; 53] = k.try_into().expect("k must have 53 entries");
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
        let k: &[f64; 53] = k.try_into().expect("k must have 53 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 19] = out.try_into().expect("out must have 19 entries");
        mass_part_0(k, q, out);
    }
    #[inline(never)]
    fn mass_part_0(k: &[f64; 53], q: &[f64; 7], out: &mut [f64; 19]) {
        let x153 = q[3] * q[3];
        let x154 = q[4] * q[4];
        let x155 = q[5] * q[5];
        let x156 = q[6] * q[6];
        let x167 = q[4] * q[5];
        let x169 = q[3] * q[6];
        let x174 = q[4] * q[6];
        let x176 = q[3] * q[5];
        let x180 = q[5] * q[6];
        let x182 = q[3] * q[4];
        let x363 = q[3] * 2.0;
        let x364 = q[4] * 2.0;
        let x365 = q[6] * 2.0;
        let x414 = q[5] * 2.0;
        let x415 = 2.0 * x363;
        let x520 = 2.0 * x364;
        let x660 = 2.0 * x365;
        let x1386 = 2.0 * x414;
        let x1389 = x364 * x520;
        let x1393 = x414 * x1386;
        let x1397 = x365 * x660;
        let x1409 = x364 * x415;
        let x1411 = x414 * x660;
        let x1415 = x365 * x1386;
        let x1423 = x364 * x660;
        let x1425 = x414 * x415;
        let x1427 = x365 * x520;
        let x1437 = x364 * x1386;
        let x1441 = x414 * x520;
        let x1443 = x365 * x415;
        let x1451 = x363 * x520;
        let x1464 = x363 * x415;
        let x1474 = x363 * x660;
        let x1486 = x363 * x1386;
        let x5320 = x1389 * k[50];
        let x5321 = x1393 * k[51];
        let x5322 = x1397 * k[50];
        let x5323 = x5320 + x5321;
        let x5324 = x5322 + x5323;
        let x5325 = 0.5 * x5324;
        let x5326 = x153 * k[52];
        let x5327 = x5325 + x5326;
        let x5328 = x1409 * k[50];
        let x5329 = x1411 * k[51];
        let x5331 = x1415 * k[50];
        let x5332 = x5328 - x5329;
        let x5333 = x5331 + x5332;
        let x5334 = 0.5 * x5333;
        let x5336 = x182 * k[52];
        let x5337 = x5336 - x5334;
        let x5338 = x1423 * k[50];
        let x5339 = x1425 * k[51];
        let x5340 = x1427 * k[50];
        let x5342 = x5338 + x5339;
        let x5343 = x5342 - x5340;
        let x5344 = 0.5 * x5343;
        let x5346 = x176 * k[52];
        let x5347 = x5346 - x5344;
        let x5348 = x1437 * k[50];
        let x5350 = x1441 * k[51];
        let x5351 = x1443 * k[50];
        let x5352 = x5350 - x5348;
        let x5353 = x5351 + x5352;
        let x5354 = 0.5 * x5353;
        let x5356 = x169 * k[52];
        let x5357 = x5356 - x5354;
        let x5358 = x1451 * k[50];
        let x5360 = x1415 * k[51];
        let x5361 = x1411 * k[50];
        let x5363 = x5360 - x5358;
        let x5364 = x5363 - x5361;
        let x5365 = 0.5 * x5364;
        let x5366 = x5336 + x5365;
        let x5367 = x1464 * k[50];
        let x5368 = x1397 * k[51];
        let x5369 = x1393 * k[50];
        let x5370 = x5367 + x5368;
        let x5371 = x5369 + x5370;
        let x5372 = 0.5 * x5371;
        let x5373 = x154 * k[52];
        let x5374 = x5372 + x5373;
        let x5375 = x1474 * k[50];
        let x5376 = x1443 * k[51];
        let x5378 = x1441 * k[50];
        let x5380 = x5375 - x5376;
        let x5381 = x5380 - x5378;
        let x5382 = 0.5 * x5381;
        let x5383 = x167 * k[52];
        let x5384 = x5382 + x5383;
        let x5385 = x1486 * k[50];
        let x5386 = x1427 * k[51];
        let x5387 = x1425 * k[50];
        let x5388 = x5385 + x5386;
        let x5390 = x5387 - x5388;
        let x5391 = 0.5 * x5390;
        let x5392 = x174 * k[52];
        let x5393 = x5391 + x5392;
        let x5394 = x1486 * k[51];
        let x5395 = x5340 + x5394;
        let x5397 = x5338 - x5395;
        let x5398 = 0.5 * x5397;
        let x5399 = x5346 + x5398;
        let x5400 = x1474 * k[51];
        let x5402 = x5351 - x5400;
        let x5403 = x5402 - x5348;
        let x5404 = 0.5 * x5403;
        let x5405 = x5383 + x5404;
        let x5406 = x1464 * k[51];
        let x5407 = x5322 + x5406;
        let x5408 = x5320 + x5407;
        let x5409 = 0.5 * x5408;
        let x5410 = x155 * k[52];
        let x5411 = x5409 + x5410;
        let x5413 = x1451 * k[51];
        let x5415 = x5413 - x5331;
        let x5416 = x5415 - x5328;
        let x5417 = 0.5 * x5416;
        let x5418 = x180 * k[52];
        let x5419 = x5417 + x5418;
        let x5420 = x1437 * k[51];
        let x5423 = x5378 - x5420;
        let x5424 = x5423 - x5375;
        let x5425 = 0.5 * x5424;
        let x5426 = x5356 + x5425;
        let x5427 = x1423 * k[51];
        let x5428 = x5387 + x5427;
        let x5430 = x5385 - x5428;
        let x5431 = 0.5 * x5430;
        let x5432 = x5392 + x5431;
        let x5433 = x1409 * k[51];
        let x5434 = x5433 - x5361;
        let x5435 = x5434 - x5358;
        let x5436 = 0.5 * x5435;
        let x5437 = x5418 + x5436;
        let x5438 = x1389 * k[51];
        let x5439 = x5369 + x5438;
        let x5440 = x5367 + x5439;
        let x5441 = 0.5 * x5440;
        let x5442 = x156 * k[52];
        let x5443 = x5441 + x5442;
        out[0] = 1.5;
        out[1] = 1.5;
        out[2] = 1.5;
        out[3] = x5327;
        out[4] = x5337;
        out[5] = x5347;
        out[6] = x5357;
        out[7] = x5366;
        out[8] = x5374;
        out[9] = x5384;
        out[10] = x5393;
        out[11] = x5399;
        out[12] = x5405;
        out[13] = x5411;
        out[14] = x5419;
        out[15] = x5426;
        out[16] = x5432;
        out[17] = x5437;
        out[18] = x5443;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 53] = k.try_into().expect("k must have 53 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 7] = out.try_into().expect("out must have 7 entries");
        let _ = t;
        force_part_0(k, q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(k: &[f64; 53], q: &[f64; 7], qd: &[f64; 7], out: &mut [f64; 7]) {
        let x363 = q[3] * 2.0;
        let x364 = q[4] * 2.0;
        let x365 = q[6] * 2.0;
        let x414 = q[5] * 2.0;
        let x790 = q[5] * qd[4];
        let x791 = q[4] * qd[5];
        let x794 = q[6] * qd[3];
        let x795 = q[3] * qd[6];
        let x798 = q[6] * qd[4];
        let x799 = q[4] * qd[6];
        let x802 = q[5] * qd[3];
        let x803 = q[3] * qd[5];
        let x808 = q[6] * qd[5];
        let x809 = q[5] * qd[6];
        let x812 = q[4] * qd[3];
        let x813 = q[3] * qd[4];
        let x936 = 2.0 * qd[3];
        let x937 = 2.0 * qd[4];
        let x938 = 2.0 * qd[6];
        let x981 = 2.0 * qd[5];
        let x1062 = qd[4] * qd[5];
        let x1065 = qd[3] * qd[6];
        let x1068 = qd[4] * qd[6];
        let x1071 = qd[3] * qd[5];
        let x1277 = x813 - x812;
        let x1278 = x808 + x1277;
        let x1279 = x1278 - x809;
        let x1280 = 2.0 * x1279;
        let x1283 = x798 + x802;
        let x1285 = x803 - x1283;
        let x1286 = x799 + x1285;
        let x1287 = 2.0 * x1286;
        let x1290 = x790 - x794;
        let x1291 = x1290 - x791;
        let x1292 = x795 + x1291;
        let x1293 = 2.0 * x1292;
        let x1314 = 2.0 * x1280;
        let x1316 = 2.0 * x1287;
        let x1318 = 2.0 * x1293;
        let x1558 = x1068 + x1071;
        let x1560 = x1071 - x1558;
        let x1561 = x1068 + x1560;
        let x1562 = 2.0 * x1561;
        let x1565 = x1062 - x1065;
        let x1566 = x1565 - x1062;
        let x1567 = x1065 + x1566;
        let x1568 = 2.0 * x1567;
        let x1569 = 2.0 * x1562;
        let x1570 = 2.0 * x1568;
        let x1571 = x937 * x1314;
        let x1573 = x981 * x1316;
        let x1574 = x414 * x1569;
        let x1575 = x1573 + x1574;
        let x1577 = x938 * x1318;
        let x1578 = x365 * x1570;
        let x1579 = x1577 + x1578;
        let x1585 = x936 * x1314;
        let x1587 = x938 * x1316;
        let x1588 = x365 * x1569;
        let x1589 = x1587 + x1588;
        let x1592 = x981 * x1318;
        let x1593 = x414 * x1570;
        let x1594 = x1592 + x1593;
        let x1599 = x938 * x1314;
        let x1601 = x936 * x1316;
        let x1602 = x363 * x1569;
        let x1603 = x1601 + x1602;
        let x1605 = x937 * x1318;
        let x1606 = x364 * x1570;
        let x1607 = x1605 + x1606;
        let x1613 = x981 * x1314;
        let x1616 = x937 * x1316;
        let x1617 = x364 * x1569;
        let x1618 = x1616 + x1617;
        let x1620 = x936 * x1318;
        let x1621 = x363 * x1570;
        let x1622 = x1620 + x1621;
        let x1627 = qd[3] * qd[3];
        let x1628 = qd[4] * qd[4];
        let x1629 = qd[5] * qd[5];
        let x1630 = qd[6] * qd[6];
        let x1631 = x1627 + x1628;
        let x1632 = x1629 + x1631;
        let x1633 = x1630 + x1632;
        let x5444 = x1571 * k[50];
        let x5445 = x1575 * k[51];
        let x5446 = x1579 * k[50];
        let x5447 = x5444 + x5445;
        let x5448 = x5446 + x5447;
        let x5449 = 0.5 * x5448;
        let x5450 = x1585 * k[50];
        let x5451 = x1589 * k[51];
        let x5453 = x1594 * k[50];
        let x5454 = x5450 - x5451;
        let x5455 = x5453 + x5454;
        let x5456 = 0.5 * x5455;
        let x5457 = x1599 * k[50];
        let x5458 = x1603 * k[51];
        let x5459 = x1607 * k[50];
        let x5461 = x5457 + x5458;
        let x5462 = x5461 - x5459;
        let x5463 = 0.5 * x5462;
        let x5464 = x1613 * k[50];
        let x5466 = x1618 * k[51];
        let x5467 = x1622 * k[50];
        let x5468 = x5466 - x5464;
        let x5469 = x5467 + x5468;
        let x5470 = 0.5 * x5469;
        let x5471 = x1573 * k[51];
        let x5472 = x1577 * k[50];
        let x5473 = x5444 + x5471;
        let x5474 = x5472 + x5473;
        let x5475 = 0.5 * x5474;
        let x5476 = x5449 + x5475;
        let x5477 = q[3] * k[52];
        let x5478 = x1633 * x5477;
        let x5480 = x5476 - x5478;
        let x5482 = x1587 * k[51];
        let x5483 = x1592 * k[50];
        let x5485 = x5482 - x5450;
        let x5486 = x5485 - x5483;
        let x5487 = 0.5 * x5486;
        let x5489 = x5487 - x5456;
        let x5490 = q[4] * k[52];
        let x5491 = x1633 * x5490;
        let x5493 = x5489 - x5491;
        let x5494 = x1601 * k[51];
        let x5495 = x1605 * k[50];
        let x5496 = x5457 + x5494;
        let x5498 = x5495 - x5496;
        let x5499 = 0.5 * x5498;
        let x5501 = x5499 - x5463;
        let x5502 = q[5] * k[52];
        let x5503 = x1633 * x5502;
        let x5505 = x5501 - x5503;
        let x5506 = x1616 * k[51];
        let x5508 = x1620 * k[50];
        let x5510 = x5464 - x5506;
        let x5511 = x5510 - x5508;
        let x5512 = 0.5 * x5511;
        let x5514 = x5512 - x5470;
        let x5515 = q[6] * k[52];
        let x5516 = x1633 * x5515;
        let x5518 = x5514 - x5516;
        out[0] = 0.0;
        out[1] = -14.715;
        out[2] = 0.0;
        out[3] = x5480;
        out[4] = x5493;
        out[5] = x5505;
        out[6] = x5518;
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
        let k: &[f64; 53] = k.try_into().expect("k must have 53 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 7] = phi.try_into().expect("phi must have 7 entries");
        let phi_q: &mut [f64; 46] = phi_q
            .try_into()
            .expect("phi_q must have 46 entries");
        let mass: &mut [f64; 19] = mass.try_into().expect("mass must have 19 entries");
        let force: &mut [f64; 7] = force.try_into().expect("force must have 7 entries");
        let mut s = [0.0f64; 46];
        eval_newton_shared_0(k, q, qd, t, &mut s);
        eval_newton_part_0(k, q, t, &s, phi, phi_q, mass);
        eval_newton_part_1(k, q, qd, &s, mass, force);
    }
    #[inline(never)]
    fn eval_newton_shared_0(
        k: &[f64; 53],
        q: &[f64; 7],
        _qd: &[f64; 7],
        _t: f64,
        s: &mut [f64; 46],
    ) {
        let x155 = q[5] * q[5];
        s[0] = x155;
        let x156 = q[6] * q[6];
        s[1] = x156;
        let x167 = q[4] * q[5];
        s[2] = x167;
        let x169 = q[3] * q[6];
        s[3] = x169;
        let x174 = q[4] * q[6];
        s[4] = x174;
        let x180 = q[5] * q[6];
        s[5] = x180;
        let x363 = q[3] * 2.0;
        s[6] = x363;
        let x364 = q[4] * 2.0;
        s[7] = x364;
        let x365 = q[6] * 2.0;
        s[8] = x365;
        let x414 = q[5] * 2.0;
        s[9] = x414;
        let x415 = 2.0 * x363;
        s[10] = x415;
        let x520 = 2.0 * x364;
        s[11] = x520;
        let x660 = 2.0 * x365;
        s[12] = x660;
        let x1386 = 2.0 * x414;
        s[13] = x1386;
        let x1389 = x364 * x520;
        s[14] = x1389;
        let x1393 = x414 * x1386;
        s[15] = x1393;
        let x1397 = x365 * x660;
        s[16] = x1397;
        let x1409 = x364 * x415;
        s[17] = x1409;
        let x1411 = x414 * x660;
        s[18] = x1411;
        let x1415 = x365 * x1386;
        s[19] = x1415;
        let x1423 = x364 * x660;
        s[20] = x1423;
        let x1425 = x414 * x415;
        s[21] = x1425;
        let x1437 = x364 * x1386;
        s[22] = x1437;
        let x1441 = x414 * x520;
        s[23] = x1441;
        let x1443 = x365 * x415;
        s[24] = x1443;
        let x1451 = x363 * x520;
        s[25] = x1451;
        let x1464 = x363 * x415;
        s[26] = x1464;
        let x1474 = x363 * x660;
        s[27] = x1474;
        let x1486 = x363 * x1386;
        s[28] = x1486;
        let x5320 = x1389 * k[50];
        s[29] = x5320;
        let x5322 = x1397 * k[50];
        s[30] = x5322;
        let x5328 = x1409 * k[50];
        s[31] = x5328;
        let x5331 = x1415 * k[50];
        s[32] = x5331;
        let x5348 = x1437 * k[50];
        s[33] = x5348;
        let x5351 = x1443 * k[50];
        s[34] = x5351;
        let x5356 = x169 * k[52];
        s[35] = x5356;
        let x5358 = x1451 * k[50];
        s[36] = x5358;
        let x5361 = x1411 * k[50];
        s[37] = x5361;
        let x5367 = x1464 * k[50];
        s[38] = x5367;
        let x5369 = x1393 * k[50];
        s[39] = x5369;
        let x5375 = x1474 * k[50];
        s[40] = x5375;
        let x5378 = x1441 * k[50];
        s[41] = x5378;
        let x5383 = x167 * k[52];
        s[42] = x5383;
        let x5385 = x1486 * k[50];
        s[43] = x5385;
        let x5387 = x1425 * k[50];
        s[44] = x5387;
        let x5392 = x174 * k[52];
        s[45] = x5392;
    }
    #[inline(never)]
    fn eval_newton_part_0(
        k: &[f64; 53],
        q: &[f64; 7],
        t: f64,
        s: &[f64; 46],
        phi: &mut [f64; 7],
        phi_q: &mut [f64; 46],
        mass: &mut [f64; 19],
    ) {
        let x7 = 0.8726646259971648 * t;
        let x153 = q[3] * q[3];
        let x154 = q[4] * q[4];
        let x157 = x153 + x154;
        let x158 = 2.0 * x157;
        let x160 = x158 - 1.0;
        let x164 = x153 + s[1];
        let x165 = 2.0 * x164;
        let x166 = x165 - 1.0;
        let x168 = 2.0 * s[2];
        let x171 = 2.0 * s[3];
        let x175 = 2.0 * s[4];
        let x176 = q[3] * q[5];
        let x177 = 2.0 * x176;
        let x178 = x175 + x177;
        let x179 = x168 + x171;
        let x181 = 2.0 * s[5];
        let x182 = q[3] * q[4];
        let x184 = 2.0 * x182;
        let x186 = x181 - x184;
        let x189 = x175 - x177;
        let x360 = s[0] + x157;
        let x361 = s[1] + x360;
        let x362 = x361 - 1.0;
        let x1427 = s[8] * s[11];
        let x4353 = x7 + k[3];
        let x4354 = k[2] + x4353;
        let x4355 = symbody_runtime::trig::cos(x4354);
        let x4356 = k[1] * x4355;
        let x4358 = k[0] - x4356;
        let x4359 = x4358.sqrt();
        let x4364 = x7 + k[7];
        let x4365 = k[6] + x4364;
        let x4366 = symbody_runtime::trig::cos(x4365);
        let x4367 = k[5] * x4366;
        let x4369 = k[4] - x4367;
        let x4370 = x4369.sqrt();
        let x4375 = x7 + k[11];
        let x4376 = k[10] + x4375;
        let x4377 = symbody_runtime::trig::cos(x4376);
        let x4378 = k[9] * x4377;
        let x4380 = k[8] - x4378;
        let x4381 = x4380.sqrt();
        let x4386 = x7 + k[15];
        let x4387 = k[14] + x4386;
        let x4388 = symbody_runtime::trig::cos(x4387);
        let x4389 = k[13] * x4388;
        let x4391 = k[12] - x4389;
        let x4392 = x4391.sqrt();
        let x4397 = x7 + k[19];
        let x4398 = k[18] + x4397;
        let x4399 = symbody_runtime::trig::cos(x4398);
        let x4400 = k[17] * x4399;
        let x4402 = k[16] - x4400;
        let x4403 = x4402.sqrt();
        let x4408 = x7 + k[23];
        let x4409 = k[22] + x4408;
        let x4410 = symbody_runtime::trig::cos(x4409);
        let x4411 = k[21] * x4410;
        let x4413 = k[20] - x4411;
        let x4414 = x4413.sqrt();
        let x4417 = x160 * k[24];
        let x4418 = x178 * k[25];
        let x4419 = x4417 + x4418;
        let x4420 = x179 * k[24];
        let x4421 = x186 * k[25];
        let x4422 = x4420 + x4421;
        let x4423 = x189 * k[24];
        let x4424 = x166 * k[25];
        let x4425 = x4423 + x4424;
        let x4426 = q[0] + x4419;
        let x4427 = q[1] + x4422;
        let x4428 = q[2] + x4425;
        let x4430 = x4426 + k[26];
        let x4432 = x4428 + k[27];
        let x4433 = x4430 * x4430;
        let x4434 = x4427 * x4427;
        let x4435 = x4432 * x4432;
        let x4436 = x4433 + x4434;
        let x4437 = x4435 + x4436;
        let x4438 = x4437.sqrt();
        let x4440 = x4438 - x4359;
        let x4443 = x160 * k[28];
        let x4444 = x178 * k[29];
        let x4445 = x4443 + x4444;
        let x4446 = x179 * k[28];
        let x4447 = x186 * k[29];
        let x4448 = x4446 + x4447;
        let x4449 = x189 * k[28];
        let x4450 = x166 * k[29];
        let x4451 = x4449 + x4450;
        let x4452 = q[0] + x4445;
        let x4453 = q[1] + x4448;
        let x4454 = q[2] + x4451;
        let x4456 = x4452 + k[30];
        let x4458 = x4454 + k[31];
        let x4459 = x4456 * x4456;
        let x4460 = x4453 * x4453;
        let x4461 = x4458 * x4458;
        let x4462 = x4459 + x4460;
        let x4463 = x4461 + x4462;
        let x4464 = x4463.sqrt();
        let x4466 = x4464 - x4370;
        let x4469 = x160 * k[32];
        let x4470 = x178 * k[33];
        let x4471 = x4469 + x4470;
        let x4472 = x179 * k[32];
        let x4473 = x186 * k[33];
        let x4474 = x4472 + x4473;
        let x4475 = x189 * k[32];
        let x4476 = x166 * k[33];
        let x4477 = x4475 + x4476;
        let x4478 = q[0] + x4471;
        let x4479 = q[1] + x4474;
        let x4480 = q[2] + x4477;
        let x4482 = x4478 + k[34];
        let x4484 = x4480 + k[35];
        let x4485 = x4482 * x4482;
        let x4486 = x4479 * x4479;
        let x4487 = x4484 * x4484;
        let x4488 = x4485 + x4486;
        let x4489 = x4487 + x4488;
        let x4490 = x4489.sqrt();
        let x4492 = x4490 - x4381;
        let x4495 = x160 * k[36];
        let x4496 = x178 * k[37];
        let x4497 = x4495 + x4496;
        let x4498 = x179 * k[36];
        let x4499 = x186 * k[37];
        let x4500 = x4498 + x4499;
        let x4501 = x189 * k[36];
        let x4502 = x166 * k[37];
        let x4503 = x4501 + x4502;
        let x4504 = q[0] + x4497;
        let x4505 = q[1] + x4500;
        let x4506 = q[2] + x4503;
        let x4508 = x4504 + k[38];
        let x4510 = x4506 + k[39];
        let x4511 = x4508 * x4508;
        let x4512 = x4505 * x4505;
        let x4513 = x4510 * x4510;
        let x4514 = x4511 + x4512;
        let x4515 = x4513 + x4514;
        let x4516 = x4515.sqrt();
        let x4518 = x4516 - x4392;
        let x4521 = x160 * k[40];
        let x4522 = x178 * k[41];
        let x4523 = x4521 + x4522;
        let x4524 = x179 * k[40];
        let x4525 = x186 * k[41];
        let x4526 = x4524 + x4525;
        let x4527 = x189 * k[40];
        let x4528 = x166 * k[41];
        let x4529 = x4527 + x4528;
        let x4530 = q[0] + x4523;
        let x4531 = q[1] + x4526;
        let x4532 = q[2] + x4529;
        let x4534 = x4530 + k[42];
        let x4536 = x4532 + k[43];
        let x4537 = x4534 * x4534;
        let x4538 = x4531 * x4531;
        let x4539 = x4536 * x4536;
        let x4540 = x4537 + x4538;
        let x4541 = x4539 + x4540;
        let x4542 = x4541.sqrt();
        let x4544 = x4542 - x4403;
        let x4547 = x160 * k[44];
        let x4548 = x178 * k[45];
        let x4549 = x4547 + x4548;
        let x4550 = x179 * k[44];
        let x4551 = x186 * k[45];
        let x4552 = x4550 + x4551;
        let x4553 = x189 * k[44];
        let x4554 = x166 * k[45];
        let x4555 = x4553 + x4554;
        let x4556 = q[0] + x4549;
        let x4557 = q[1] + x4552;
        let x4558 = q[2] + x4555;
        let x4560 = x4556 + k[46];
        let x4562 = x4558 + k[47];
        let x4563 = x4560 * x4560;
        let x4564 = x4557 * x4557;
        let x4565 = x4562 * x4562;
        let x4566 = x4563 + x4564;
        let x4567 = x4565 + x4566;
        let x4568 = x4567.sqrt();
        let x4570 = x4568 - x4414;
        let x4571 = 2.0 * x4430;
        let x4572 = 2.0 * x4427;
        let x4573 = 2.0 * x4432;
        let x4574 = 2.0 * x4438;
        let x4575 = 1.0 / x4574;
        let x4576 = x4571 * x4575;
        let x4577 = 2.0 * x4456;
        let x4578 = 2.0 * x4453;
        let x4579 = 2.0 * x4458;
        let x4580 = 2.0 * x4464;
        let x4581 = 1.0 / x4580;
        let x4582 = x4577 * x4581;
        let x4583 = 2.0 * x4482;
        let x4584 = 2.0 * x4479;
        let x4585 = 2.0 * x4484;
        let x4586 = 2.0 * x4490;
        let x4587 = 1.0 / x4586;
        let x4588 = x4583 * x4587;
        let x4589 = 2.0 * x4508;
        let x4590 = 2.0 * x4505;
        let x4591 = 2.0 * x4510;
        let x4592 = 2.0 * x4516;
        let x4593 = 1.0 / x4592;
        let x4594 = x4589 * x4593;
        let x4595 = 2.0 * x4534;
        let x4596 = 2.0 * x4531;
        let x4597 = 2.0 * x4536;
        let x4598 = 2.0 * x4542;
        let x4599 = 1.0 / x4598;
        let x4600 = x4595 * x4599;
        let x4601 = 2.0 * x4560;
        let x4602 = 2.0 * x4557;
        let x4603 = 2.0 * x4562;
        let x4604 = 2.0 * x4568;
        let x4605 = 1.0 / x4604;
        let x4606 = x4601 * x4605;
        let x4607 = x4572 * x4575;
        let x4608 = x4578 * x4581;
        let x4609 = x4584 * x4587;
        let x4610 = x4590 * x4593;
        let x4611 = x4596 * x4599;
        let x4612 = x4602 * x4605;
        let x4613 = x4573 * x4575;
        let x4614 = x4579 * x4581;
        let x4615 = x4585 * x4587;
        let x4616 = x4591 * x4593;
        let x4617 = x4597 * x4599;
        let x4618 = x4603 * x4605;
        let x4619 = s[10] * k[24];
        let x4620 = s[9] * k[25];
        let x4621 = x4619 + x4620;
        let x4622 = s[8] * k[24];
        let x4623 = s[7] * k[25];
        let x4625 = x4622 - x4623;
        let x4626 = s[9] * k[24];
        let x4628 = s[10] * k[25];
        let x4629 = x4628 - x4626;
        let x4630 = x4571 * x4621;
        let x4631 = x4572 * x4625;
        let x4632 = x4573 * x4629;
        let x4633 = x4630 + x4631;
        let x4634 = x4632 + x4633;
        let x4635 = x4575 * x4634;
        let x4636 = s[10] * k[28];
        let x4637 = s[9] * k[29];
        let x4638 = x4636 + x4637;
        let x4639 = s[8] * k[28];
        let x4640 = s[7] * k[29];
        let x4642 = x4639 - x4640;
        let x4643 = s[9] * k[28];
        let x4645 = s[10] * k[29];
        let x4646 = x4645 - x4643;
        let x4647 = x4577 * x4638;
        let x4648 = x4578 * x4642;
        let x4649 = x4579 * x4646;
        let x4650 = x4647 + x4648;
        let x4651 = x4649 + x4650;
        let x4652 = x4581 * x4651;
        let x4653 = s[10] * k[32];
        let x4654 = s[9] * k[33];
        let x4655 = x4653 + x4654;
        let x4656 = s[8] * k[32];
        let x4657 = s[7] * k[33];
        let x4659 = x4656 - x4657;
        let x4660 = s[9] * k[32];
        let x4662 = s[10] * k[33];
        let x4663 = x4662 - x4660;
        let x4664 = x4583 * x4655;
        let x4665 = x4584 * x4659;
        let x4666 = x4585 * x4663;
        let x4667 = x4664 + x4665;
        let x4668 = x4666 + x4667;
        let x4669 = x4587 * x4668;
        let x4670 = s[10] * k[36];
        let x4671 = s[9] * k[37];
        let x4672 = x4670 + x4671;
        let x4673 = s[8] * k[36];
        let x4674 = s[7] * k[37];
        let x4676 = x4673 - x4674;
        let x4677 = s[9] * k[36];
        let x4679 = s[10] * k[37];
        let x4680 = x4679 - x4677;
        let x4681 = x4589 * x4672;
        let x4682 = x4590 * x4676;
        let x4683 = x4591 * x4680;
        let x4684 = x4681 + x4682;
        let x4685 = x4683 + x4684;
        let x4686 = x4593 * x4685;
        let x4687 = s[10] * k[40];
        let x4688 = s[9] * k[41];
        let x4689 = x4687 + x4688;
        let x4690 = s[8] * k[40];
        let x4691 = s[7] * k[41];
        let x4693 = x4690 - x4691;
        let x4694 = s[9] * k[40];
        let x4696 = s[10] * k[41];
        let x4697 = x4696 - x4694;
        let x4698 = x4595 * x4689;
        let x4699 = x4596 * x4693;
        let x4700 = x4597 * x4697;
        let x4701 = x4698 + x4699;
        let x4702 = x4700 + x4701;
        let x4703 = x4599 * x4702;
        let x4704 = s[10] * k[44];
        let x4705 = s[9] * k[45];
        let x4706 = x4704 + x4705;
        let x4707 = s[8] * k[44];
        let x4708 = s[7] * k[45];
        let x4710 = x4707 - x4708;
        let x4711 = s[9] * k[44];
        let x4713 = s[10] * k[45];
        let x4714 = x4713 - x4711;
        let x4715 = x4601 * x4706;
        let x4716 = x4602 * x4710;
        let x4717 = x4603 * x4714;
        let x4718 = x4715 + x4716;
        let x4719 = x4717 + x4718;
        let x4720 = x4605 * x4719;
        let x4721 = s[11] * k[24];
        let x4722 = s[8] * k[25];
        let x4723 = x4721 + x4722;
        let x4724 = s[6] * k[25];
        let x4726 = x4626 - x4724;
        let x4727 = x4571 * x4723;
        let x4728 = x4572 * x4726;
        let x4729 = x4573 * x4622;
        let x4730 = x4727 + x4728;
        let x4731 = x4729 + x4730;
        let x4732 = x4575 * x4731;
        let x4733 = s[11] * k[28];
        let x4734 = s[8] * k[29];
        let x4735 = x4733 + x4734;
        let x4736 = s[6] * k[29];
        let x4738 = x4643 - x4736;
        let x4739 = x4577 * x4735;
        let x4740 = x4578 * x4738;
        let x4741 = x4579 * x4639;
        let x4742 = x4739 + x4740;
        let x4743 = x4741 + x4742;
        let x4744 = x4581 * x4743;
        let x4745 = s[11] * k[32];
        let x4746 = s[8] * k[33];
        let x4747 = x4745 + x4746;
        let x4748 = s[6] * k[33];
        let x4750 = x4660 - x4748;
        let x4751 = x4583 * x4747;
        let x4752 = x4584 * x4750;
        let x4753 = x4585 * x4656;
        let x4754 = x4751 + x4752;
        let x4755 = x4753 + x4754;
        let x4756 = x4587 * x4755;
        let x4757 = s[11] * k[36];
        let x4758 = s[8] * k[37];
        let x4759 = x4757 + x4758;
        let x4760 = s[6] * k[37];
        let x4762 = x4677 - x4760;
        let x4763 = x4589 * x4759;
        let x4764 = x4590 * x4762;
        let x4765 = x4591 * x4673;
        let x4766 = x4763 + x4764;
        let x4767 = x4765 + x4766;
        let x4768 = x4593 * x4767;
        let x4769 = s[11] * k[40];
        let x4770 = s[8] * k[41];
        let x4771 = x4769 + x4770;
        let x4772 = s[6] * k[41];
        let x4774 = x4694 - x4772;
        let x4775 = x4595 * x4771;
        let x4776 = x4596 * x4774;
        let x4777 = x4597 * x4690;
        let x4778 = x4775 + x4776;
        let x4779 = x4777 + x4778;
        let x4780 = x4599 * x4779;
        let x4781 = s[11] * k[44];
        let x4782 = s[8] * k[45];
        let x4783 = x4781 + x4782;
        let x4784 = s[6] * k[45];
        let x4786 = x4711 - x4784;
        let x4787 = x4601 * x4783;
        let x4788 = x4602 * x4786;
        let x4789 = x4603 * x4707;
        let x4790 = x4787 + x4788;
        let x4791 = x4789 + x4790;
        let x4792 = x4605 * x4791;
        let x4793 = s[7] * k[24];
        let x4794 = x4722 + x4793;
        let x4795 = s[6] * k[24];
        let x4796 = x4571 * x4724;
        let x4797 = x4572 * x4794;
        let x4798 = x4573 * x4795;
        let x4800 = x4796 + x4797;
        let x4801 = x4800 - x4798;
        let x4802 = x4575 * x4801;
        let x4803 = s[7] * k[28];
        let x4804 = x4734 + x4803;
        let x4805 = s[6] * k[28];
        let x4806 = x4577 * x4736;
        let x4807 = x4578 * x4804;
        let x4808 = x4579 * x4805;
        let x4810 = x4806 + x4807;
        let x4811 = x4810 - x4808;
        let x4812 = x4581 * x4811;
        let x4813 = s[7] * k[32];
        let x4814 = x4746 + x4813;
        let x4815 = s[6] * k[32];
        let x4816 = x4583 * x4748;
        let x4817 = x4584 * x4814;
        let x4818 = x4585 * x4815;
        let x4820 = x4816 + x4817;
        let x4821 = x4820 - x4818;
        let x4822 = x4587 * x4821;
        let x4823 = s[7] * k[36];
        let x4824 = x4758 + x4823;
        let x4825 = s[6] * k[36];
        let x4826 = x4589 * x4760;
        let x4827 = x4590 * x4824;
        let x4828 = x4591 * x4825;
        let x4830 = x4826 + x4827;
        let x4831 = x4830 - x4828;
        let x4832 = x4593 * x4831;
        let x4833 = s[7] * k[40];
        let x4834 = x4770 + x4833;
        let x4835 = s[6] * k[40];
        let x4836 = x4595 * x4772;
        let x4837 = x4596 * x4834;
        let x4838 = x4597 * x4835;
        let x4840 = x4836 + x4837;
        let x4841 = x4840 - x4838;
        let x4842 = x4599 * x4841;
        let x4843 = s[7] * k[44];
        let x4844 = x4782 + x4843;
        let x4845 = s[6] * k[44];
        let x4846 = x4601 * x4784;
        let x4847 = x4602 * x4844;
        let x4848 = x4603 * x4845;
        let x4850 = x4846 + x4847;
        let x4851 = x4850 - x4848;
        let x4852 = x4605 * x4851;
        let x4853 = x4620 + x4795;
        let x4854 = s[12] * k[25];
        let x4855 = x4793 + x4854;
        let x4856 = x4571 * x4623;
        let x4857 = x4572 * x4853;
        let x4858 = x4573 * x4855;
        let x4859 = x4856 + x4857;
        let x4860 = x4858 + x4859;
        let x4861 = x4575 * x4860;
        let x4862 = x4637 + x4805;
        let x4863 = s[12] * k[29];
        let x4864 = x4803 + x4863;
        let x4865 = x4577 * x4640;
        let x4866 = x4578 * x4862;
        let x4867 = x4579 * x4864;
        let x4868 = x4865 + x4866;
        let x4869 = x4867 + x4868;
        let x4870 = x4581 * x4869;
        let x4871 = x4654 + x4815;
        let x4872 = s[12] * k[33];
        let x4873 = x4813 + x4872;
        let x4874 = x4583 * x4657;
        let x4875 = x4584 * x4871;
        let x4876 = x4585 * x4873;
        let x4877 = x4874 + x4875;
        let x4878 = x4876 + x4877;
        let x4879 = x4587 * x4878;
        let x4880 = x4671 + x4825;
        let x4881 = s[12] * k[37];
        let x4882 = x4823 + x4881;
        let x4883 = x4589 * x4674;
        let x4884 = x4590 * x4880;
        let x4885 = x4591 * x4882;
        let x4886 = x4883 + x4884;
        let x4887 = x4885 + x4886;
        let x4888 = x4593 * x4887;
        let x4889 = x4688 + x4835;
        let x4890 = s[12] * k[41];
        let x4891 = x4833 + x4890;
        let x4892 = x4595 * x4691;
        let x4893 = x4596 * x4889;
        let x4894 = x4597 * x4891;
        let x4895 = x4892 + x4893;
        let x4896 = x4894 + x4895;
        let x4897 = x4599 * x4896;
        let x4898 = x4705 + x4845;
        let x4899 = s[12] * k[45];
        let x4900 = x4843 + x4899;
        let x4901 = x4601 * x4708;
        let x4902 = x4602 * x4898;
        let x4903 = x4603 * x4900;
        let x4904 = x4901 + x4902;
        let x4905 = x4903 + x4904;
        let x4906 = x4605 * x4905;
        let x5321 = s[15] * k[51];
        let x5323 = s[29] + x5321;
        let x5324 = s[30] + x5323;
        let x5325 = 0.5 * x5324;
        let x5326 = x153 * k[52];
        let x5327 = x5325 + x5326;
        let x5329 = s[18] * k[51];
        let x5332 = s[31] - x5329;
        let x5333 = s[32] + x5332;
        let x5334 = 0.5 * x5333;
        let x5336 = x182 * k[52];
        let x5337 = x5336 - x5334;
        let x5338 = s[20] * k[50];
        let x5339 = s[21] * k[51];
        let x5340 = x1427 * k[50];
        let x5342 = x5338 + x5339;
        let x5343 = x5342 - x5340;
        let x5344 = 0.5 * x5343;
        let x5346 = x176 * k[52];
        let x5347 = x5346 - x5344;
        let x5350 = s[23] * k[51];
        let x5352 = x5350 - s[33];
        let x5353 = s[34] + x5352;
        let x5354 = 0.5 * x5353;
        let x5357 = s[35] - x5354;
        let x5360 = s[19] * k[51];
        let x5363 = x5360 - s[36];
        let x5364 = x5363 - s[37];
        let x5365 = 0.5 * x5364;
        let x5366 = x5336 + x5365;
        let x5368 = s[16] * k[51];
        let x5370 = s[38] + x5368;
        let x5371 = s[39] + x5370;
        let x5372 = 0.5 * x5371;
        let x5373 = x154 * k[52];
        let x5374 = x5372 + x5373;
        let x5376 = s[24] * k[51];
        let x5380 = s[40] - x5376;
        let x5381 = x5380 - s[41];
        let x5382 = 0.5 * x5381;
        let x5384 = x5382 + s[42];
        let x5386 = x1427 * k[51];
        let x5388 = s[43] + x5386;
        let x5390 = s[44] - x5388;
        let x5391 = 0.5 * x5390;
        let x5393 = x5391 + s[45];
        let x5394 = s[28] * k[51];
        let x5395 = x5340 + x5394;
        let x5397 = x5338 - x5395;
        let x5398 = 0.5 * x5397;
        let x5399 = x5346 + x5398;
        phi[0] = x4440;
        phi_q[0] = x4576;
        phi_q[1] = x4607;
        phi_q[2] = x4613;
        phi_q[3] = x4635;
        phi_q[4] = x4732;
        phi_q[5] = x4802;
        phi_q[6] = x4861;
        phi[1] = x4466;
        phi_q[7] = x4582;
        phi_q[8] = x4608;
        phi_q[9] = x4614;
        phi_q[10] = x4652;
        phi_q[11] = x4744;
        phi_q[12] = x4812;
        phi_q[13] = x4870;
        phi[2] = x4492;
        phi_q[14] = x4588;
        phi_q[15] = x4609;
        phi_q[16] = x4615;
        phi_q[17] = x4669;
        phi_q[18] = x4756;
        phi_q[19] = x4822;
        phi_q[20] = x4879;
        phi[3] = x4518;
        phi_q[21] = x4594;
        phi_q[22] = x4610;
        phi_q[23] = x4616;
        phi_q[24] = x4686;
        phi_q[25] = x4768;
        phi_q[26] = x4832;
        phi_q[27] = x4888;
        phi[4] = x4544;
        phi_q[28] = x4600;
        phi_q[29] = x4611;
        phi_q[30] = x4617;
        phi_q[31] = x4703;
        phi_q[32] = x4780;
        phi_q[33] = x4842;
        phi_q[34] = x4897;
        phi[5] = x4570;
        phi_q[35] = x4606;
        phi_q[36] = x4612;
        phi_q[37] = x4618;
        phi_q[38] = x4720;
        phi_q[39] = x4792;
        phi_q[40] = x4852;
        phi_q[41] = x4906;
        phi[6] = x362;
        phi_q[42] = s[6];
        phi_q[43] = s[7];
        phi_q[44] = s[9];
        phi_q[45] = s[8];
        mass[0] = 1.5;
        mass[1] = 1.5;
        mass[2] = 1.5;
        mass[3] = x5327;
        mass[4] = x5337;
        mass[5] = x5347;
        mass[6] = x5357;
        mass[7] = x5366;
        mass[8] = x5374;
        mass[9] = x5384;
        mass[10] = x5393;
        mass[11] = x5399;
    }
    #[inline(never)]
    fn eval_newton_part_1(
        k: &[f64; 53],
        q: &[f64; 7],
        qd: &[f64; 7],
        s: &[f64; 46],
        mass: &mut [f64; 19],
        force: &mut [f64; 7],
    ) {
        let x790 = q[5] * qd[4];
        let x791 = q[4] * qd[5];
        let x794 = q[6] * qd[3];
        let x795 = q[3] * qd[6];
        let x798 = q[6] * qd[4];
        let x799 = q[4] * qd[6];
        let x802 = q[5] * qd[3];
        let x803 = q[3] * qd[5];
        let x808 = q[6] * qd[5];
        let x809 = q[5] * qd[6];
        let x812 = q[4] * qd[3];
        let x813 = q[3] * qd[4];
        let x936 = 2.0 * qd[3];
        let x937 = 2.0 * qd[4];
        let x938 = 2.0 * qd[6];
        let x981 = 2.0 * qd[5];
        let x1062 = qd[4] * qd[5];
        let x1065 = qd[3] * qd[6];
        let x1068 = qd[4] * qd[6];
        let x1071 = qd[3] * qd[5];
        let x1277 = x813 - x812;
        let x1278 = x808 + x1277;
        let x1279 = x1278 - x809;
        let x1280 = 2.0 * x1279;
        let x1283 = x798 + x802;
        let x1285 = x803 - x1283;
        let x1286 = x799 + x1285;
        let x1287 = 2.0 * x1286;
        let x1290 = x790 - x794;
        let x1291 = x1290 - x791;
        let x1292 = x795 + x1291;
        let x1293 = 2.0 * x1292;
        let x1314 = 2.0 * x1280;
        let x1316 = 2.0 * x1287;
        let x1318 = 2.0 * x1293;
        let x1558 = x1068 + x1071;
        let x1560 = x1071 - x1558;
        let x1561 = x1068 + x1560;
        let x1562 = 2.0 * x1561;
        let x1565 = x1062 - x1065;
        let x1566 = x1565 - x1062;
        let x1567 = x1065 + x1566;
        let x1568 = 2.0 * x1567;
        let x1569 = 2.0 * x1562;
        let x1570 = 2.0 * x1568;
        let x1571 = x937 * x1314;
        let x1573 = x981 * x1316;
        let x1574 = s[9] * x1569;
        let x1575 = x1573 + x1574;
        let x1577 = x938 * x1318;
        let x1578 = s[8] * x1570;
        let x1579 = x1577 + x1578;
        let x1585 = x936 * x1314;
        let x1587 = x938 * x1316;
        let x1588 = s[8] * x1569;
        let x1589 = x1587 + x1588;
        let x1592 = x981 * x1318;
        let x1593 = s[9] * x1570;
        let x1594 = x1592 + x1593;
        let x1599 = x938 * x1314;
        let x1601 = x936 * x1316;
        let x1602 = s[6] * x1569;
        let x1603 = x1601 + x1602;
        let x1605 = x937 * x1318;
        let x1606 = s[7] * x1570;
        let x1607 = x1605 + x1606;
        let x1613 = x981 * x1314;
        let x1616 = x937 * x1316;
        let x1617 = s[7] * x1569;
        let x1618 = x1616 + x1617;
        let x1620 = x936 * x1318;
        let x1621 = s[6] * x1570;
        let x1622 = x1620 + x1621;
        let x1627 = qd[3] * qd[3];
        let x1628 = qd[4] * qd[4];
        let x1629 = qd[5] * qd[5];
        let x1630 = qd[6] * qd[6];
        let x1631 = x1627 + x1628;
        let x1632 = x1629 + x1631;
        let x1633 = x1630 + x1632;
        let x5400 = s[27] * k[51];
        let x5402 = s[34] - x5400;
        let x5403 = x5402 - s[33];
        let x5404 = 0.5 * x5403;
        let x5405 = s[42] + x5404;
        let x5406 = s[26] * k[51];
        let x5407 = s[30] + x5406;
        let x5408 = s[29] + x5407;
        let x5409 = 0.5 * x5408;
        let x5410 = s[0] * k[52];
        let x5411 = x5409 + x5410;
        let x5413 = s[25] * k[51];
        let x5415 = x5413 - s[32];
        let x5416 = x5415 - s[31];
        let x5417 = 0.5 * x5416;
        let x5418 = s[5] * k[52];
        let x5419 = x5417 + x5418;
        let x5420 = s[22] * k[51];
        let x5423 = s[41] - x5420;
        let x5424 = x5423 - s[40];
        let x5425 = 0.5 * x5424;
        let x5426 = s[35] + x5425;
        let x5427 = s[20] * k[51];
        let x5428 = s[44] + x5427;
        let x5430 = s[43] - x5428;
        let x5431 = 0.5 * x5430;
        let x5432 = s[45] + x5431;
        let x5433 = s[17] * k[51];
        let x5434 = x5433 - s[37];
        let x5435 = x5434 - s[36];
        let x5436 = 0.5 * x5435;
        let x5437 = x5418 + x5436;
        let x5438 = s[14] * k[51];
        let x5439 = s[39] + x5438;
        let x5440 = s[38] + x5439;
        let x5441 = 0.5 * x5440;
        let x5442 = s[1] * k[52];
        let x5443 = x5441 + x5442;
        let x5444 = x1571 * k[50];
        let x5445 = x1575 * k[51];
        let x5446 = x1579 * k[50];
        let x5447 = x5444 + x5445;
        let x5448 = x5446 + x5447;
        let x5449 = 0.5 * x5448;
        let x5450 = x1585 * k[50];
        let x5451 = x1589 * k[51];
        let x5453 = x1594 * k[50];
        let x5454 = x5450 - x5451;
        let x5455 = x5453 + x5454;
        let x5456 = 0.5 * x5455;
        let x5457 = x1599 * k[50];
        let x5458 = x1603 * k[51];
        let x5459 = x1607 * k[50];
        let x5461 = x5457 + x5458;
        let x5462 = x5461 - x5459;
        let x5463 = 0.5 * x5462;
        let x5464 = x1613 * k[50];
        let x5466 = x1618 * k[51];
        let x5467 = x1622 * k[50];
        let x5468 = x5466 - x5464;
        let x5469 = x5467 + x5468;
        let x5470 = 0.5 * x5469;
        let x5471 = x1573 * k[51];
        let x5472 = x1577 * k[50];
        let x5473 = x5444 + x5471;
        let x5474 = x5472 + x5473;
        let x5475 = 0.5 * x5474;
        let x5476 = x5449 + x5475;
        let x5477 = q[3] * k[52];
        let x5478 = x1633 * x5477;
        let x5480 = x5476 - x5478;
        let x5482 = x1587 * k[51];
        let x5483 = x1592 * k[50];
        let x5485 = x5482 - x5450;
        let x5486 = x5485 - x5483;
        let x5487 = 0.5 * x5486;
        let x5489 = x5487 - x5456;
        let x5490 = q[4] * k[52];
        let x5491 = x1633 * x5490;
        let x5493 = x5489 - x5491;
        let x5494 = x1601 * k[51];
        let x5495 = x1605 * k[50];
        let x5496 = x5457 + x5494;
        let x5498 = x5495 - x5496;
        let x5499 = 0.5 * x5498;
        let x5501 = x5499 - x5463;
        let x5502 = q[5] * k[52];
        let x5503 = x1633 * x5502;
        let x5505 = x5501 - x5503;
        let x5506 = x1616 * k[51];
        let x5508 = x1620 * k[50];
        let x5510 = x5464 - x5506;
        let x5511 = x5510 - x5508;
        let x5512 = 0.5 * x5511;
        let x5514 = x5512 - x5470;
        let x5515 = q[6] * k[52];
        let x5516 = x1633 * x5515;
        let x5518 = x5514 - x5516;
        mass[12] = x5405;
        mass[13] = x5411;
        mass[14] = x5419;
        mass[15] = x5426;
        mass[16] = x5432;
        mass[17] = x5437;
        mass[18] = x5443;
        force[0] = 0.0;
        force[1] = -14.715;
        force[2] = 0.0;
        force[3] = x5480;
        force[4] = x5493;
        force[5] = x5505;
        force[6] = x5518;
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
        let k: &[f64; 53] = k.try_into().expect("k must have 53 entries");
        let q: &[f64; 7] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 7] = qd.try_into().expect("qd must have n_coords entries");
        let dq: &[f64; 7] = dq.try_into().expect("dq must have n_coords entries");
        let dqd: &[f64; 7] = dqd.try_into().expect("dqd must have n_coords entries");
        let dp: &[f64; 66] = dp.try_into().expect("dp must have 66 entries");
        let mass: &mut [f64; 19] = mass.try_into().expect("mass must have 19 entries");
        let force: &mut [f64; 7] = force.try_into().expect("force must have 7 entries");
        let _ = t;
        let mut s = [0.0f64; 150];
        tangents_shared_0(k, q, qd, t, dq, dqd, dp, &mut s);
        tangents_part_0(k, q, dq, &s, mass, force);
        tangents_part_1(k, q, dq, &s, force);
    }
    #[inline(never)]
    fn tangents_shared_0(
        k: &[f64; 53],
        q: &[f64; 7],
        qd: &[f64; 7],
        _t: f64,
        dq: &[f64; 7],
        dqd: &[f64; 7],
        dp: &[f64; 66],
        s: &mut [f64; 150],
    ) {
        let x363 = q[3] * 2.0;
        s[0] = x363;
        let x364 = q[4] * 2.0;
        s[1] = x364;
        let x790 = q[5] * qd[4];
        s[2] = x790;
        let x791 = q[4] * qd[5];
        s[3] = x791;
        let x794 = q[6] * qd[3];
        s[4] = x794;
        let x795 = q[3] * qd[6];
        s[5] = x795;
        let x798 = q[6] * qd[4];
        s[6] = x798;
        let x799 = q[4] * qd[6];
        s[7] = x799;
        let x802 = q[5] * qd[3];
        s[8] = x802;
        let x803 = q[3] * qd[5];
        s[9] = x803;
        let x808 = q[6] * qd[5];
        s[10] = x808;
        let x809 = q[5] * qd[6];
        s[11] = x809;
        let x812 = q[4] * qd[3];
        s[12] = x812;
        let x813 = q[3] * qd[4];
        s[13] = x813;
        let x936 = 2.0 * qd[3];
        s[14] = x936;
        let x937 = 2.0 * qd[4];
        s[15] = x937;
        let x938 = 2.0 * qd[6];
        s[16] = x938;
        let x981 = 2.0 * qd[5];
        s[17] = x981;
        let x1062 = qd[4] * qd[5];
        s[18] = x1062;
        let x1065 = qd[3] * qd[6];
        s[19] = x1065;
        let x1068 = qd[4] * qd[6];
        s[20] = x1068;
        let x1071 = qd[3] * qd[5];
        s[21] = x1071;
        let x1277 = x813 - x812;
        s[22] = x1277;
        let x1278 = x808 + x1277;
        s[23] = x1278;
        let x1279 = x1278 - x809;
        s[24] = x1279;
        let x1280 = 2.0 * x1279;
        s[25] = x1280;
        let x1283 = x798 + x802;
        s[26] = x1283;
        let x1285 = x803 - x1283;
        s[27] = x1285;
        let x1286 = x799 + x1285;
        s[28] = x1286;
        let x1287 = 2.0 * x1286;
        s[29] = x1287;
        let x1290 = x790 - x794;
        s[30] = x1290;
        let x1291 = x1290 - x791;
        s[31] = x1291;
        let x1292 = x795 + x1291;
        s[32] = x1292;
        let x1293 = 2.0 * x1292;
        s[33] = x1293;
        let x1314 = 2.0 * x1280;
        s[34] = x1314;
        let x1316 = 2.0 * x1287;
        s[35] = x1316;
        let x1318 = 2.0 * x1293;
        s[36] = x1318;
        let x1558 = x1068 + x1071;
        s[37] = x1558;
        let x1560 = x1071 - x1558;
        s[38] = x1560;
        let x1561 = x1068 + x1560;
        s[39] = x1561;
        let x1562 = 2.0 * x1561;
        s[40] = x1562;
        let x1565 = x1062 - x1065;
        s[41] = x1565;
        let x1566 = x1565 - x1062;
        s[42] = x1566;
        let x1567 = x1065 + x1566;
        s[43] = x1567;
        let x1568 = 2.0 * x1567;
        s[44] = x1568;
        let x1569 = 2.0 * x1562;
        s[45] = x1569;
        let x1570 = 2.0 * x1568;
        s[46] = x1570;
        let x1627 = qd[3] * qd[3];
        s[47] = x1627;
        let x1628 = qd[4] * qd[4];
        s[48] = x1628;
        let x1629 = qd[5] * qd[5];
        s[49] = x1629;
        let x1630 = qd[6] * qd[6];
        s[50] = x1630;
        let x1631 = x1627 + x1628;
        s[51] = x1631;
        let x1632 = x1629 + x1631;
        s[52] = x1632;
        let x1633 = x1630 + x1632;
        s[53] = x1633;
        let x2094 = 2.0 * dq[3];
        s[54] = x2094;
        let x2095 = 2.0 * dq[4];
        s[55] = x2095;
        let x2948 = qd[4] * dq[5];
        s[56] = x2948;
        let x2949 = q[5] * dqd[4];
        s[57] = x2949;
        let x2950 = x2948 + x2949;
        s[58] = x2950;
        let x2951 = qd[5] * dq[4];
        s[59] = x2951;
        let x2952 = q[4] * dqd[5];
        s[60] = x2952;
        let x2953 = x2951 + x2952;
        s[61] = x2953;
        let x2956 = qd[3] * dq[6];
        s[62] = x2956;
        let x2957 = q[6] * dqd[3];
        s[63] = x2957;
        let x2958 = x2956 + x2957;
        s[64] = x2958;
        let x2959 = qd[6] * dq[3];
        s[65] = x2959;
        let x2960 = q[3] * dqd[6];
        s[66] = x2960;
        let x2961 = x2959 + x2960;
        s[67] = x2961;
        let x2964 = qd[4] * dq[6];
        s[68] = x2964;
        let x2965 = q[6] * dqd[4];
        s[69] = x2965;
        let x2966 = x2964 + x2965;
        s[70] = x2966;
        let x2967 = qd[6] * dq[4];
        s[71] = x2967;
        let x2968 = q[4] * dqd[6];
        s[72] = x2968;
        let x2969 = x2967 + x2968;
        s[73] = x2969;
        let x2972 = qd[3] * dq[5];
        s[74] = x2972;
        let x2973 = q[5] * dqd[3];
        s[75] = x2973;
        let x2974 = x2972 + x2973;
        s[76] = x2974;
        let x2975 = qd[5] * dq[3];
        s[77] = x2975;
        let x2976 = q[3] * dqd[5];
        s[78] = x2976;
        let x2977 = x2975 + x2976;
        s[79] = x2977;
        let x2982 = qd[5] * dq[6];
        s[80] = x2982;
        let x2983 = q[6] * dqd[5];
        s[81] = x2983;
        let x2984 = x2982 + x2983;
        s[82] = x2984;
        let x2985 = qd[6] * dq[5];
        s[83] = x2985;
        let x2986 = q[5] * dqd[6];
        s[84] = x2986;
        let x2987 = x2985 + x2986;
        s[85] = x2987;
        let x2990 = qd[3] * dq[4];
        s[86] = x2990;
        let x2991 = q[4] * dqd[3];
        s[87] = x2991;
        let x2992 = x2990 + x2991;
        s[88] = x2992;
        let x2993 = qd[4] * dq[3];
        s[89] = x2993;
        let x2994 = q[3] * dqd[4];
        s[90] = x2994;
        let x2995 = x2993 + x2994;
        s[91] = x2995;
        let x3236 = 2.0 * dqd[3];
        s[92] = x3236;
        let x3237 = 2.0 * dqd[4];
        s[93] = x3237;
        let x3238 = 2.0 * dqd[6];
        s[94] = x3238;
        let x3305 = 2.0 * dqd[5];
        s[95] = x3305;
        let x3462 = x936 * dqd[3];
        s[96] = x3462;
        let x3465 = x937 * dqd[4];
        s[97] = x3465;
        let x3468 = x981 * dqd[5];
        s[98] = x3468;
        let x3471 = x938 * dqd[6];
        s[99] = x3471;
        let x3478 = qd[5] * dqd[4];
        s[100] = x3478;
        let x3479 = qd[4] * dqd[5];
        s[101] = x3479;
        let x3480 = x3478 + x3479;
        s[102] = x3480;
        let x3483 = qd[6] * dqd[3];
        s[103] = x3483;
        let x3484 = qd[3] * dqd[6];
        s[104] = x3484;
        let x3485 = x3483 + x3484;
        s[105] = x3485;
        let x3488 = qd[6] * dqd[4];
        s[106] = x3488;
        let x3489 = qd[4] * dqd[6];
        s[107] = x3489;
        let x3490 = x3488 + x3489;
        s[108] = x3490;
        let x3493 = qd[5] * dqd[3];
        s[109] = x3493;
        let x3494 = qd[3] * dqd[5];
        s[110] = x3494;
        let x3495 = x3493 + x3494;
        s[111] = x3495;
        let x3847 = 1.5 * dp[14];
        s[112] = x3847;
        let x3855 = x2995 - x2992;
        s[113] = x3855;
        let x3856 = x2984 + x3855;
        s[114] = x3856;
        let x3857 = x3856 - x2987;
        s[115] = x3857;
        let x3858 = 2.0 * x3857;
        s[116] = x3858;
        let x3859 = x2966 + x2974;
        s[117] = x3859;
        let x3861 = x2977 - x3859;
        s[118] = x3861;
        let x3862 = x2969 + x3861;
        s[119] = x3862;
        let x3863 = 2.0 * x3862;
        s[120] = x3863;
        let x3866 = x2950 - x2958;
        s[121] = x3866;
        let x3867 = x3866 - x2953;
        s[122] = x3867;
        let x3868 = x2961 + x3867;
        s[123] = x3868;
        let x3869 = 2.0 * x3868;
        s[124] = x3869;
        let x3870 = 2.0 * x3858;
        s[125] = x3870;
        let x3871 = 2.0 * x3863;
        s[126] = x3871;
        let x3872 = 2.0 * x3869;
        s[127] = x3872;
        let x4134 = x3490 + x3495;
        s[128] = x4134;
        let x4136 = x3495 - x4134;
        s[129] = x4136;
        let x4137 = x3490 + x4136;
        s[130] = x4137;
        let x4138 = 2.0 * x4137;
        s[131] = x4138;
        let x4141 = x3480 - x3485;
        s[132] = x4141;
        let x4142 = x4141 - x3480;
        s[133] = x4142;
        let x4143 = x3485 + x4142;
        s[134] = x4143;
        let x4144 = 2.0 * x4143;
        s[135] = x4144;
        let x4145 = 2.0 * x4138;
        s[136] = x4145;
        let x4146 = 2.0 * x4144;
        s[137] = x4146;
        let x4266 = x3462 + x3465;
        s[138] = x4266;
        let x4267 = x3468 + x4266;
        s[139] = x4267;
        let x4268 = x3471 + x4267;
        s[140] = x4268;
        let x7175 = dp[14] * k[49];
        s[141] = x7175;
        let x7176 = x3847 * k[48];
        s[142] = x7176;
        let x7177 = x7175 + x7176;
        s[143] = x7177;
        let x7178 = 0.25 * x7177;
        s[144] = x7178;
        let x7179 = 0.5 * x7177;
        s[145] = x7179;
        let x7180 = x7178 + x7179;
        s[146] = x7180;
        let x7181 = x7178 + x7180;
        s[147] = x7181;
        let x7182 = 4.0 * x7181;
        s[148] = x7182;
        let x7183 = 0.3333333333333333 * x7182;
        s[149] = x7183;
    }
    #[inline(never)]
    fn tangents_part_0(
        k: &[f64; 53],
        q: &[f64; 7],
        dq: &[f64; 7],
        s: &[f64; 150],
        mass: &mut [f64; 19],
        force: &mut [f64; 7],
    ) {
        let x153 = q[3] * q[3];
        let x154 = q[4] * q[4];
        let x155 = q[5] * q[5];
        let x156 = q[6] * q[6];
        let x167 = q[4] * q[5];
        let x169 = q[3] * q[6];
        let x174 = q[4] * q[6];
        let x176 = q[3] * q[5];
        let x180 = q[5] * q[6];
        let x182 = q[3] * q[4];
        let x365 = q[6] * 2.0;
        let x414 = q[5] * 2.0;
        let x415 = 2.0 * s[0];
        let x520 = 2.0 * s[1];
        let x660 = 2.0 * x365;
        let x1386 = 2.0 * x414;
        let x1389 = s[1] * x520;
        let x1393 = x414 * x1386;
        let x1397 = x365 * x660;
        let x1409 = s[1] * x415;
        let x1411 = x414 * x660;
        let x1415 = x365 * x1386;
        let x1423 = s[1] * x660;
        let x1425 = x414 * x415;
        let x1427 = x365 * x520;
        let x1437 = s[1] * x1386;
        let x1441 = x414 * x520;
        let x1443 = x365 * x415;
        let x1451 = s[0] * x520;
        let x1464 = s[0] * x415;
        let x1474 = s[0] * x660;
        let x1486 = s[0] * x1386;
        let x1571 = s[15] * s[34];
        let x1573 = s[17] * s[35];
        let x1574 = x414 * s[45];
        let x1575 = x1573 + x1574;
        let x1577 = s[16] * s[36];
        let x1578 = x365 * s[46];
        let x1579 = x1577 + x1578;
        let x1585 = s[14] * s[34];
        let x1587 = s[16] * s[35];
        let x1588 = x365 * s[45];
        let x1589 = x1587 + x1588;
        let x1592 = s[17] * s[36];
        let x1593 = x414 * s[46];
        let x1594 = x1592 + x1593;
        let x1838 = s[0] * dq[3];
        let x1839 = s[1] * dq[4];
        let x1840 = x414 * dq[5];
        let x1841 = x365 * dq[6];
        let x1846 = q[5] * dq[4];
        let x1847 = q[4] * dq[5];
        let x1848 = x1846 + x1847;
        let x1850 = q[6] * dq[3];
        let x1851 = q[3] * dq[6];
        let x1852 = x1850 + x1851;
        let x1854 = q[6] * dq[4];
        let x1855 = q[4] * dq[6];
        let x1856 = x1854 + x1855;
        let x1858 = q[5] * dq[3];
        let x1859 = q[3] * dq[5];
        let x1860 = x1858 + x1859;
        let x1864 = q[6] * dq[5];
        let x1865 = q[5] * dq[6];
        let x1866 = x1864 + x1865;
        let x1868 = q[4] * dq[3];
        let x1869 = q[3] * dq[4];
        let x1870 = x1868 + x1869;
        let x2096 = 2.0 * dq[6];
        let x2205 = 2.0 * dq[5];
        let x2206 = 2.0 * s[54];
        let x2435 = 2.0 * s[55];
        let x2736 = 2.0 * x2096;
        let x3877 = 2.0 * x2205;
        let x3878 = x520 * s[55];
        let x3879 = s[1] * x2435;
        let x3880 = x3878 + x3879;
        let x3884 = x1386 * x2205;
        let x3885 = x414 * x3877;
        let x3886 = x3884 + x3885;
        let x3890 = x660 * x2096;
        let x3891 = x365 * x2736;
        let x3892 = x3890 + x3891;
        let x3903 = x415 * s[55];
        let x3904 = s[1] * x2206;
        let x3905 = x3903 + x3904;
        let x3909 = x660 * x2205;
        let x3910 = x414 * x2736;
        let x3911 = x3909 + x3910;
        let x3916 = x1386 * x2096;
        let x3917 = x365 * x3877;
        let x3918 = x3916 + x3917;
        let x3930 = x660 * s[55];
        let x3931 = s[1] * x2736;
        let x3932 = x3930 + x3931;
        let x3936 = x415 * x2205;
        let x3937 = x414 * x2206;
        let x3938 = x3936 + x3937;
        let x3942 = x520 * x2096;
        let x3943 = x365 * x2435;
        let x3944 = x3942 + x3943;
        let x3957 = x1386 * s[55];
        let x3958 = s[1] * x3877;
        let x3959 = x3957 + x3958;
        let x3964 = x520 * x2205;
        let x3965 = x414 * x2435;
        let x3966 = x3964 + x3965;
        let x3970 = x415 * x2096;
        let x3971 = x365 * x2206;
        let x3972 = x3970 + x3971;
        let x3984 = x520 * s[54];
        let x3985 = s[0] * x2435;
        let x3986 = x3984 + x3985;
        let x4002 = x415 * s[54];
        let x4003 = s[0] * x2206;
        let x4004 = x4002 + x4003;
        let x4021 = x660 * s[54];
        let x4022 = s[0] * x2736;
        let x4023 = x4021 + x4022;
        let x4042 = x1386 * s[54];
        let x4043 = s[0] * x3877;
        let x4044 = x4042 + x4043;
        let x4147 = s[34] * s[93];
        let x4148 = s[15] * s[125];
        let x4149 = x4147 + x4148;
        let x4153 = s[35] * s[95];
        let x4154 = s[17] * s[126];
        let x4155 = x4153 + x4154;
        let x4156 = s[45] * x2205;
        let x4157 = x414 * s[136];
        let x4158 = x4156 + x4157;
        let x4159 = x4155 + x4158;
        let x4163 = s[36] * s[94];
        let x4164 = s[16] * s[127];
        let x4165 = x4163 + x4164;
        let x4166 = s[46] * x2096;
        let x4167 = x365 * s[137];
        let x4168 = x4166 + x4167;
        let x4169 = x4165 + x4168;
        let x4176 = s[34] * s[92];
        let x4177 = s[14] * s[125];
        let x4178 = x4176 + x4177;
        let x4182 = s[35] * s[94];
        let x4183 = s[16] * s[126];
        let x4184 = x4182 + x4183;
        let x4185 = s[45] * x2096;
        let x4186 = x365 * s[136];
        let x4187 = x4185 + x4186;
        let x4188 = x4184 + x4187;
        let x4193 = s[36] * s[95];
        let x4194 = s[17] * s[127];
        let x4195 = x4193 + x4194;
        let x4196 = s[46] * x2205;
        let x4197 = x414 * s[137];
        let x4198 = x4196 + x4197;
        let x4199 = x4195 + x4198;
        let x5477 = q[3] * k[52];
        let x5490 = q[4] * k[52];
        let x7184 = x1389 * s[144];
        let x7185 = x3880 * k[50];
        let x7186 = x7184 + x7185;
        let x7187 = x1393 * s[145];
        let x7188 = x3886 * k[51];
        let x7189 = x7187 + x7188;
        let x7190 = x1397 * s[144];
        let x7191 = x3892 * k[50];
        let x7192 = x7190 + x7191;
        let x7193 = x7186 + x7189;
        let x7194 = x7192 + x7193;
        let x7195 = 0.5 * x7194;
        let x7196 = x1838 * k[52];
        let x7197 = x153 * s[149];
        let x7198 = x7196 + x7197;
        let x7199 = x7195 + x7198;
        let x7200 = x1409 * s[144];
        let x7201 = x3905 * k[50];
        let x7202 = x7200 + x7201;
        let x7203 = x1411 * s[145];
        let x7204 = x3911 * k[51];
        let x7205 = x7203 + x7204;
        let x7207 = x1415 * s[144];
        let x7208 = x3918 * k[50];
        let x7209 = x7207 + x7208;
        let x7210 = x7202 - x7205;
        let x7211 = x7209 + x7210;
        let x7212 = 0.5 * x7211;
        let x7214 = x1870 * k[52];
        let x7215 = x182 * s[149];
        let x7216 = x7214 + x7215;
        let x7217 = x7216 - x7212;
        let x7218 = x1423 * s[144];
        let x7219 = x3932 * k[50];
        let x7220 = x7218 + x7219;
        let x7221 = x1425 * s[145];
        let x7222 = x3938 * k[51];
        let x7223 = x7221 + x7222;
        let x7224 = x1427 * s[144];
        let x7225 = x3944 * k[50];
        let x7226 = x7224 + x7225;
        let x7228 = x7220 + x7223;
        let x7229 = x7228 - x7226;
        let x7230 = 0.5 * x7229;
        let x7232 = x1860 * k[52];
        let x7233 = x176 * s[149];
        let x7234 = x7232 + x7233;
        let x7235 = x7234 - x7230;
        let x7236 = x1437 * s[144];
        let x7237 = x3959 * k[50];
        let x7238 = x7236 + x7237;
        let x7240 = x1441 * s[145];
        let x7241 = x3966 * k[51];
        let x7242 = x7240 + x7241;
        let x7243 = x1443 * s[144];
        let x7244 = x3972 * k[50];
        let x7245 = x7243 + x7244;
        let x7246 = x7242 - x7238;
        let x7247 = x7245 + x7246;
        let x7248 = 0.5 * x7247;
        let x7250 = x1852 * k[52];
        let x7251 = x169 * s[149];
        let x7252 = x7250 + x7251;
        let x7253 = x7252 - x7248;
        let x7254 = x1451 * s[144];
        let x7255 = x3986 * k[50];
        let x7256 = x7254 + x7255;
        let x7258 = x1415 * s[145];
        let x7259 = x3918 * k[51];
        let x7260 = x7258 + x7259;
        let x7261 = x1411 * s[144];
        let x7262 = x3911 * k[50];
        let x7263 = x7261 + x7262;
        let x7265 = x7260 - x7256;
        let x7266 = x7265 - x7263;
        let x7267 = 0.5 * x7266;
        let x7268 = x7216 + x7267;
        let x7269 = x1464 * s[144];
        let x7270 = x4004 * k[50];
        let x7271 = x7269 + x7270;
        let x7272 = x1397 * s[145];
        let x7273 = x3892 * k[51];
        let x7274 = x7272 + x7273;
        let x7275 = x1393 * s[144];
        let x7276 = x3886 * k[50];
        let x7277 = x7275 + x7276;
        let x7278 = x7271 + x7274;
        let x7279 = x7277 + x7278;
        let x7280 = 0.5 * x7279;
        let x7281 = x1839 * k[52];
        let x7282 = x154 * s[149];
        let x7283 = x7281 + x7282;
        let x7284 = x7280 + x7283;
        let x7285 = x1474 * s[144];
        let x7286 = x4023 * k[50];
        let x7287 = x7285 + x7286;
        let x7288 = x1443 * s[145];
        let x7289 = x3972 * k[51];
        let x7290 = x7288 + x7289;
        let x7292 = x1441 * s[144];
        let x7293 = x3966 * k[50];
        let x7294 = x7292 + x7293;
        let x7296 = x7287 - x7290;
        let x7297 = x7296 - x7294;
        let x7298 = 0.5 * x7297;
        let x7299 = x1848 * k[52];
        let x7300 = x167 * s[149];
        let x7301 = x7299 + x7300;
        let x7302 = x7298 + x7301;
        let x7303 = x1486 * s[144];
        let x7304 = x4044 * k[50];
        let x7305 = x7303 + x7304;
        let x7306 = x1427 * s[145];
        let x7307 = x3944 * k[51];
        let x7308 = x7306 + x7307;
        let x7309 = x1425 * s[144];
        let x7310 = x3938 * k[50];
        let x7311 = x7309 + x7310;
        let x7312 = x7305 + x7308;
        let x7314 = x7311 - x7312;
        let x7315 = 0.5 * x7314;
        let x7316 = x1856 * k[52];
        let x7317 = x174 * s[149];
        let x7318 = x7316 + x7317;
        let x7319 = x7315 + x7318;
        let x7320 = x1486 * s[145];
        let x7321 = x4044 * k[51];
        let x7322 = x7320 + x7321;
        let x7323 = x7226 + x7322;
        let x7325 = x7220 - x7323;
        let x7326 = 0.5 * x7325;
        let x7327 = x7234 + x7326;
        let x7328 = x1474 * s[145];
        let x7329 = x4023 * k[51];
        let x7330 = x7328 + x7329;
        let x7332 = x7245 - x7330;
        let x7333 = x7332 - x7238;
        let x7334 = 0.5 * x7333;
        let x7335 = x7301 + x7334;
        let x7336 = x1464 * s[145];
        let x7337 = x4004 * k[51];
        let x7338 = x7336 + x7337;
        let x7339 = x7192 + x7338;
        let x7340 = x7186 + x7339;
        let x7341 = 0.5 * x7340;
        let x7342 = x1840 * k[52];
        let x7343 = x155 * s[149];
        let x7344 = x7342 + x7343;
        let x7345 = x7341 + x7344;
        let x7347 = x1451 * s[145];
        let x7348 = x3986 * k[51];
        let x7349 = x7347 + x7348;
        let x7351 = x7349 - x7209;
        let x7352 = x7351 - x7202;
        let x7353 = 0.5 * x7352;
        let x7354 = x1866 * k[52];
        let x7355 = x180 * s[149];
        let x7356 = x7354 + x7355;
        let x7357 = x7353 + x7356;
        let x7358 = x1437 * s[145];
        let x7359 = x3959 * k[51];
        let x7360 = x7358 + x7359;
        let x7363 = x7294 - x7360;
        let x7364 = x7363 - x7287;
        let x7365 = 0.5 * x7364;
        let x7366 = x7252 + x7365;
        let x7367 = x1423 * s[145];
        let x7368 = x3932 * k[51];
        let x7369 = x7367 + x7368;
        let x7370 = x7311 + x7369;
        let x7372 = x7305 - x7370;
        let x7373 = 0.5 * x7372;
        let x7374 = x7318 + x7373;
        let x7375 = x1409 * s[145];
        let x7376 = x3905 * k[51];
        let x7377 = x7375 + x7376;
        let x7378 = x7377 - x7263;
        let x7379 = x7378 - x7256;
        let x7380 = 0.5 * x7379;
        let x7381 = x7356 + x7380;
        let x7382 = x1389 * s[145];
        let x7383 = x3880 * k[51];
        let x7384 = x7382 + x7383;
        let x7385 = x7277 + x7384;
        let x7386 = x7271 + x7385;
        let x7387 = 0.5 * x7386;
        let x7388 = x1841 * k[52];
        let x7389 = x156 * s[149];
        let x7390 = x7388 + x7389;
        let x7391 = x7387 + x7390;
        let x7392 = x1571 * s[144];
        let x7393 = x4149 * k[50];
        let x7394 = x7392 + x7393;
        let x7395 = x1575 * s[145];
        let x7396 = x4159 * k[51];
        let x7397 = x7395 + x7396;
        let x7398 = x1579 * s[144];
        let x7399 = x4169 * k[50];
        let x7400 = x7398 + x7399;
        let x7401 = x7394 + x7397;
        let x7402 = x7400 + x7401;
        let x7403 = 0.5 * x7402;
        let x7404 = x1585 * s[144];
        let x7405 = x4178 * k[50];
        let x7406 = x7404 + x7405;
        let x7407 = x1589 * s[145];
        let x7408 = x4188 * k[51];
        let x7409 = x7407 + x7408;
        let x7411 = x1594 * s[144];
        let x7412 = x4199 * k[50];
        let x7413 = x7411 + x7412;
        let x7414 = x7406 - x7409;
        let x7415 = x7413 + x7414;
        let x7416 = 0.5 * x7415;
        let x7443 = x1573 * s[145];
        let x7444 = x4155 * k[51];
        let x7445 = x7443 + x7444;
        let x7446 = x1577 * s[144];
        let x7447 = x4165 * k[50];
        let x7448 = x7446 + x7447;
        let x7449 = x7394 + x7445;
        let x7450 = x7448 + x7449;
        let x7451 = 0.5 * x7450;
        let x7452 = x7403 + x7451;
        let x7453 = dq[3] * k[52];
        let x7454 = q[3] * s[149];
        let x7455 = x7453 + x7454;
        let x7456 = s[140] * x5477;
        let x7457 = s[53] * x7455;
        let x7458 = x7456 + x7457;
        let x7460 = x7452 - x7458;
        let x7462 = x1587 * s[145];
        let x7463 = x4184 * k[51];
        let x7464 = x7462 + x7463;
        let x7465 = x1592 * s[144];
        let x7466 = x4195 * k[50];
        let x7467 = x7465 + x7466;
        let x7469 = x7464 - x7406;
        let x7470 = x7469 - x7467;
        let x7471 = 0.5 * x7470;
        let x7473 = x7471 - x7416;
        let x7474 = dq[4] * k[52];
        let x7475 = q[4] * s[149];
        let x7476 = x7474 + x7475;
        let x7477 = s[140] * x5490;
        let x7478 = s[53] * x7476;
        let x7479 = x7477 + x7478;
        let x7481 = x7473 - x7479;
        mass[0] = 0.0;
        mass[1] = 0.0;
        mass[2] = 0.0;
        mass[3] = x7199;
        mass[4] = x7217;
        mass[5] = x7235;
        mass[6] = x7253;
        mass[7] = x7268;
        mass[8] = x7284;
        mass[9] = x7302;
        mass[10] = x7319;
        mass[11] = x7327;
        mass[12] = x7335;
        mass[13] = x7345;
        mass[14] = x7357;
        mass[15] = x7366;
        mass[16] = x7374;
        mass[17] = x7381;
        mass[18] = x7391;
        force[0] = 0.0;
        force[1] = 0.0;
        force[2] = 0.0;
        force[3] = x7460;
        force[4] = x7481;
    }
    #[inline(never)]
    fn tangents_part_1(
        k: &[f64; 53],
        q: &[f64; 7],
        dq: &[f64; 7],
        s: &[f64; 150],
        force: &mut [f64; 7],
    ) {
        let x1599 = s[16] * s[34];
        let x1601 = s[14] * s[35];
        let x1602 = s[0] * s[45];
        let x1603 = x1601 + x1602;
        let x1605 = s[15] * s[36];
        let x1606 = s[1] * s[46];
        let x1607 = x1605 + x1606;
        let x1613 = s[17] * s[34];
        let x1616 = s[15] * s[35];
        let x1617 = s[1] * s[45];
        let x1618 = x1616 + x1617;
        let x1620 = s[14] * s[36];
        let x1621 = s[0] * s[46];
        let x1622 = x1620 + x1621;
        let x4206 = s[34] * s[94];
        let x4207 = s[16] * s[125];
        let x4208 = x4206 + x4207;
        let x4212 = s[35] * s[92];
        let x4213 = s[14] * s[126];
        let x4214 = x4212 + x4213;
        let x4215 = s[45] * s[54];
        let x4216 = s[0] * s[136];
        let x4217 = x4215 + x4216;
        let x4218 = x4214 + x4217;
        let x4222 = s[36] * s[93];
        let x4223 = s[15] * s[127];
        let x4224 = x4222 + x4223;
        let x4225 = s[46] * s[55];
        let x4226 = s[1] * s[137];
        let x4227 = x4225 + x4226;
        let x4228 = x4224 + x4227;
        let x4236 = s[34] * s[95];
        let x4237 = s[17] * s[125];
        let x4238 = x4236 + x4237;
        let x4243 = s[35] * s[93];
        let x4244 = s[15] * s[126];
        let x4245 = x4243 + x4244;
        let x4246 = s[45] * s[55];
        let x4247 = s[1] * s[136];
        let x4248 = x4246 + x4247;
        let x4249 = x4245 + x4248;
        let x4253 = s[36] * s[92];
        let x4254 = s[14] * s[127];
        let x4255 = x4253 + x4254;
        let x4256 = s[46] * s[54];
        let x4257 = s[0] * s[137];
        let x4258 = x4256 + x4257;
        let x4259 = x4255 + x4258;
        let x5502 = q[5] * k[52];
        let x5515 = q[6] * k[52];
        let x7417 = x1599 * s[144];
        let x7418 = x4208 * k[50];
        let x7419 = x7417 + x7418;
        let x7420 = x1603 * s[145];
        let x7421 = x4218 * k[51];
        let x7422 = x7420 + x7421;
        let x7423 = x1607 * s[144];
        let x7424 = x4228 * k[50];
        let x7425 = x7423 + x7424;
        let x7427 = x7419 + x7422;
        let x7428 = x7427 - x7425;
        let x7429 = 0.5 * x7428;
        let x7430 = x1613 * s[144];
        let x7431 = x4238 * k[50];
        let x7432 = x7430 + x7431;
        let x7434 = x1618 * s[145];
        let x7435 = x4249 * k[51];
        let x7436 = x7434 + x7435;
        let x7437 = x1622 * s[144];
        let x7438 = x4259 * k[50];
        let x7439 = x7437 + x7438;
        let x7440 = x7436 - x7432;
        let x7441 = x7439 + x7440;
        let x7442 = 0.5 * x7441;
        let x7482 = x1601 * s[145];
        let x7483 = x4214 * k[51];
        let x7484 = x7482 + x7483;
        let x7485 = x1605 * s[144];
        let x7486 = x4224 * k[50];
        let x7487 = x7485 + x7486;
        let x7488 = x7419 + x7484;
        let x7490 = x7487 - x7488;
        let x7491 = 0.5 * x7490;
        let x7493 = x7491 - x7429;
        let x7494 = dq[5] * k[52];
        let x7495 = q[5] * s[149];
        let x7496 = x7494 + x7495;
        let x7497 = s[140] * x5502;
        let x7498 = s[53] * x7496;
        let x7499 = x7497 + x7498;
        let x7501 = x7493 - x7499;
        let x7502 = x1616 * s[145];
        let x7503 = x4245 * k[51];
        let x7504 = x7502 + x7503;
        let x7506 = x1620 * s[144];
        let x7507 = x4255 * k[50];
        let x7508 = x7506 + x7507;
        let x7510 = x7432 - x7504;
        let x7511 = x7510 - x7508;
        let x7512 = 0.5 * x7511;
        let x7514 = x7512 - x7442;
        let x7515 = dq[6] * k[52];
        let x7516 = q[6] * s[149];
        let x7517 = x7515 + x7516;
        let x7518 = s[140] * x5515;
        let x7519 = s[53] * x7517;
        let x7520 = x7518 + x7519;
        let x7522 = x7514 - x7520;
        force[5] = x7501;
        force[6] = x7522;
    }
}
/// `hexapod_twist` with the `exact` formulation.
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
/// `hexapod_twist` with the `exact` formulation. At run-time parameter values (`Exact::with_parameters`).
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
    run_time: Some(&RUN_TIME_ENTRY),
};
