//! Generated equations of `simple_pendulum` (IFToMM benchmark A01: planar simple pendulum, point mass on a massless link). Do not edit.
//!
//! Regenerate with `cargo xtask generate simple_pendulum` from `mechanisms/simple_pendulum.toml`.
//!
//! 6 coordinates, 1 constraints, 3 structural nonzeros in Φq.
//! Rank 1 at the initial pose; mobility 5 (Grübler count 5), 5 DOF left with drivers.
//! Each body owns `[X, Y, Z]` (centre of mass), then `[θ, β, γ]` (A = Rz(γ)·Ry(β)·Rx(θ))
//! or Euler parameters `[e0, e1, e2, e3]`. Equations of motion: `M q̈ + Φqᵀλ = Q`, `Φq q̈ = γ`.
//! Sparse outputs hold the pattern's nonzeros in order (row-major, columns ascending).
//!
//! Coordinates:
//! - `0..6` p1 (euler)
//!
//! Constraint rows:
//! - `0..1` link (distance, ground – p1)
#![allow(
    clippy::approx_constant,
    clippy::excessive_precision,
    clippy::too_many_arguments,
    clippy::unreadable_literal
)]
use symbody_runtime::{
    BodyInfo, Direction, Entry, Formulation, JointInfo, JointKind, KinematicOutputs,
    Mechanism, MechanismInfo, NewtonOutputs, Origin, PlatformInfo, Reduction,
    Substitution, Rotation, TangentOutputs,
};
use symbody_runtime::parameters::{ParameterError, RunTimeParameters};
/// Constraint residual Φ(q, t).
pub fn phi(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = t;
    phi_part_0(k, q, out);
}
#[inline(never)]
fn phi_part_0(k: &[f64; 6], q: &[f64; 6], out: &mut [f64; 1]) {
    let x35 = q[0] * q[0];
    let x36 = q[1] * q[1];
    let x37 = q[2] * q[2];
    let x38 = x35 + x36;
    let x39 = x37 + x38;
    let x40 = x39.sqrt();
    let x745 = x40 + k[0];
    out[0] = x745;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 3] = out.try_into().expect("out must have 3 entries");
    let _ = k;
    let _ = t;
    phi_q_part_0(q, out);
}
#[inline(never)]
fn phi_q_part_0(q: &[f64; 6], out: &mut [f64; 3]) {
    let x35 = q[0] * q[0];
    let x36 = q[1] * q[1];
    let x37 = q[2] * q[2];
    let x38 = x35 + x36;
    let x39 = x37 + x38;
    let x40 = x39.sqrt();
    let x45 = q[0] * 2.0;
    let x46 = q[1] * 2.0;
    let x47 = q[2] * 2.0;
    let x48 = x40 * 2.0;
    let x49 = 1.0 / x48;
    let x50 = x45 * x49;
    let x51 = x46 * x49;
    let x52 = x47 * x49;
    out[0] = x50;
    out[1] = x51;
    out[2] = x52;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = k;
    let _ = q;
    let _ = t;
    phi_t_part_0(out);
}
#[inline(never)]
fn phi_t_part_0(out: &mut [f64; 1]) {
    out[0] = 0.0;
}
/// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
pub fn gamma(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = k;
    let _ = t;
    gamma_part_0(q, qd, out);
}
#[inline(never)]
fn gamma_part_0(q: &[f64; 6], qd: &[f64; 6], out: &mut [f64; 1]) {
    let x35 = q[0] * q[0];
    let x36 = q[1] * q[1];
    let x37 = q[2] * q[2];
    let x38 = x35 + x36;
    let x39 = x37 + x38;
    let x40 = x39.sqrt();
    let x45 = q[0] * 2.0;
    let x46 = q[1] * 2.0;
    let x47 = q[2] * 2.0;
    let x48 = x40 * 2.0;
    let x49 = 1.0 / x48;
    let x59 = x45 * qd[0];
    let x60 = x46 * qd[1];
    let x61 = x47 * qd[2];
    let x62 = x59 + x60;
    let x63 = x61 + x62;
    let x64 = x49 * x63;
    let x65 = 2.0 * qd[0];
    let x66 = 2.0 * qd[1];
    let x67 = 2.0 * qd[2];
    let x68 = 2.0 * x64;
    let x69 = x49 * x49;
    let x70 = x68 * x69;
    let x72 = qd[0] * x65;
    let x73 = qd[1] * x66;
    let x74 = qd[2] * x67;
    let x75 = x72 + x73;
    let x76 = x74 + x75;
    let x77 = x63 * x70;
    let x79 = x49 * x76;
    let x80 = x79 - x77;
    let x81 = -x80;
    out[0] = x81;
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
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
    let phi: &mut [f64; 1] = phi.try_into().expect("phi must have 1 entries");
    let phi_q: &mut [f64; 3] = phi_q.try_into().expect("phi_q must have 3 entries");
    let phi_t: &mut [f64; 1] = phi_t.try_into().expect("phi_t must have 1 entries");
    let gamma: &mut [f64; 1] = gamma.try_into().expect("gamma must have 1 entries");
    let _ = t;
    eval_kinematics_part_0(k, q, qd, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_part_0(
    k: &[f64; 6],
    q: &[f64; 6],
    qd: &[f64; 6],
    phi: &mut [f64; 1],
    phi_q: &mut [f64; 3],
    phi_t: &mut [f64; 1],
    gamma: &mut [f64; 1],
) {
    let x35 = q[0] * q[0];
    let x36 = q[1] * q[1];
    let x37 = q[2] * q[2];
    let x38 = x35 + x36;
    let x39 = x37 + x38;
    let x40 = x39.sqrt();
    let x45 = q[0] * 2.0;
    let x46 = q[1] * 2.0;
    let x47 = q[2] * 2.0;
    let x48 = x40 * 2.0;
    let x49 = 1.0 / x48;
    let x50 = x45 * x49;
    let x51 = x46 * x49;
    let x52 = x47 * x49;
    let x59 = x45 * qd[0];
    let x60 = x46 * qd[1];
    let x61 = x47 * qd[2];
    let x62 = x59 + x60;
    let x63 = x61 + x62;
    let x64 = x49 * x63;
    let x65 = 2.0 * qd[0];
    let x66 = 2.0 * qd[1];
    let x67 = 2.0 * qd[2];
    let x68 = 2.0 * x64;
    let x69 = x49 * x49;
    let x70 = x68 * x69;
    let x72 = qd[0] * x65;
    let x73 = qd[1] * x66;
    let x74 = qd[2] * x67;
    let x75 = x72 + x73;
    let x76 = x74 + x75;
    let x77 = x63 * x70;
    let x79 = x49 * x76;
    let x80 = x79 - x77;
    let x81 = -x80;
    let x745 = x40 + k[0];
    phi[0] = x745;
    phi_q[0] = x50;
    phi_q[1] = x51;
    phi_q[2] = x52;
    phi_t[0] = 0.0;
    gamma[0] = x81;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    potential_into_part_0(k, q, out);
}
#[inline(never)]
fn potential_into_part_0(k: &[f64; 6], q: &[f64; 6], out: &mut [f64; 1]) {
    let x749 = q[1] * k[2];
    out[0] = x749;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
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
    let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
    let dq: &[f64; 6] = dq.try_into().expect("dq must have n_coords entries");
    let dqd: &[f64; 6] = dqd.try_into().expect("dqd must have n_coords entries");
    let dp: &[f64; 8] = dp.try_into().expect("dp must have 8 entries");
    let phi: &mut [f64; 1] = phi.try_into().expect("phi must have 1 entries");
    let phi_q: &mut [f64; 3] = phi_q.try_into().expect("phi_q must have 3 entries");
    let phi_t: &mut [f64; 1] = phi_t.try_into().expect("phi_t must have 1 entries");
    let gamma: &mut [f64; 1] = gamma.try_into().expect("gamma must have 1 entries");
    let _ = k;
    let _ = t;
    kinematic_tangents_part_0(q, qd, dq, dqd, dp, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn kinematic_tangents_part_0(
    q: &[f64; 6],
    qd: &[f64; 6],
    dq: &[f64; 6],
    dqd: &[f64; 6],
    dp: &[f64; 8],
    phi: &mut [f64; 1],
    phi_q: &mut [f64; 3],
    phi_t: &mut [f64; 1],
    gamma: &mut [f64; 1],
) {
    let x35 = q[0] * q[0];
    let x36 = q[1] * q[1];
    let x37 = q[2] * q[2];
    let x38 = x35 + x36;
    let x39 = x37 + x38;
    let x40 = x39.sqrt();
    let x45 = q[0] * 2.0;
    let x46 = q[1] * 2.0;
    let x47 = q[2] * 2.0;
    let x48 = x40 * 2.0;
    let x49 = 1.0 / x48;
    let x59 = x45 * qd[0];
    let x60 = x46 * qd[1];
    let x61 = x47 * qd[2];
    let x62 = x59 + x60;
    let x63 = x61 + x62;
    let x64 = x49 * x63;
    let x65 = 2.0 * qd[0];
    let x66 = 2.0 * qd[1];
    let x67 = 2.0 * qd[2];
    let x68 = 2.0 * x64;
    let x69 = x49 * x49;
    let x70 = x68 * x69;
    let x72 = qd[0] * x65;
    let x73 = qd[1] * x66;
    let x74 = qd[2] * x67;
    let x75 = x72 + x73;
    let x76 = x74 + x75;
    let x364 = x45 * dq[0];
    let x365 = x46 * dq[1];
    let x366 = x47 * dq[2];
    let x367 = x364 + x365;
    let x368 = x366 + x367;
    let x369 = x49 * x368;
    let x371 = x369 - dp[7];
    let x372 = 2.0 * dq[0];
    let x373 = 2.0 * dq[1];
    let x374 = 2.0 * dq[2];
    let x375 = 2.0 * x369;
    let x376 = x69 * x375;
    let x378 = x49 * x372;
    let x379 = x45 * x376;
    let x381 = x378 - x379;
    let x382 = x49 * x373;
    let x383 = x46 * x376;
    let x385 = x382 - x383;
    let x386 = x49 * x374;
    let x387 = x47 * x376;
    let x389 = x386 - x387;
    let x390 = qd[0] * x372;
    let x391 = x45 * dqd[0];
    let x392 = x390 + x391;
    let x393 = qd[1] * x373;
    let x394 = x46 * dqd[1];
    let x395 = x393 + x394;
    let x396 = qd[2] * x374;
    let x397 = x47 * dqd[2];
    let x398 = x396 + x397;
    let x399 = x392 + x395;
    let x400 = x398 + x399;
    let x401 = x63 * x376;
    let x403 = x49 * x400;
    let x404 = x403 - x401;
    let x405 = 2.0 * dqd[0];
    let x406 = 2.0 * dqd[1];
    let x407 = 2.0 * dqd[2];
    let x408 = 2.0 * x404;
    let x409 = 2.0 * x49;
    let x410 = x376 * x409;
    let x412 = x69 * x408;
    let x413 = x68 * x410;
    let x415 = x412 - x413;
    let x416 = x65 * dqd[0];
    let x417 = qd[0] * x405;
    let x418 = x416 + x417;
    let x419 = x66 * dqd[1];
    let x420 = qd[1] * x406;
    let x421 = x419 + x420;
    let x422 = x67 * dqd[2];
    let x423 = qd[2] * x407;
    let x424 = x422 + x423;
    let x425 = x418 + x421;
    let x426 = x424 + x425;
    let x427 = x70 * x400;
    let x428 = x63 * x415;
    let x429 = x427 + x428;
    let x431 = x76 * x376;
    let x433 = x49 * x426;
    let x434 = x433 - x431;
    let x435 = x434 - x429;
    let x436 = -x435;
    phi[0] = x371;
    phi_q[0] = x381;
    phi_q[1] = x385;
    phi_q[2] = x389;
    phi_t[0] = 0.0;
    gamma[0] = x436;
}
/// Number of generalized coordinates.
pub const N_COORDS: usize = 6usize;
/// Number of constraint rows.
pub const N_CONSTRAINTS: usize = 1usize;
/// Row of each Φq nonzero.
pub static PHI_Q_ROWS: [u32; 3usize] = [0u32, 0u32, 0u32];
/// Column of each Φq nonzero.
pub static PHI_Q_COLS: [u32; 3usize] = [0u32, 1u32, 2u32];
/// Bodies in coordinate order.
pub static BODIES: [BodyInfo; 1usize] = [
    BodyInfo {
        name: "p1",
        coord_offset: 0usize,
        rotation: Rotation::Euler,
        mass: 1f64,
        inertia: [0.00004f64, 0.00004f64, 0.00004f64],
    },
];
/// Joints in row order, then drivers.
pub static JOINTS: [JointInfo; 1usize] = [
    JointInfo {
        name: "link",
        kind: JointKind::Distance,
        body1: None,
        body2: Some(0usize),
        row_start: 0usize,
        rows: 1usize,
        point1: [0f64, 0f64, 0f64],
        point2: [0f64, 0f64, 0f64],
        effort_sign: 0f64,
        effort_unit: "",
    },
];
/// Name of each coordinate.
pub static COORD_NAMES: [&str; 6usize] = [
    "p1.x",
    "p1.y",
    "p1.z",
    "p1.theta",
    "p1.beta",
    "p1.gamma",
];
/// Name of each constraint row.
pub static ROW_NAMES: [&str; 1usize] = ["link.distance"];
/// Initial coordinates: the file's pose, assembled.
pub static Q0: [f64; 6usize] = [1f64, 0f64, 0f64, 0f64, 0f64, 0f64];
/// Initial velocities from the file (to be projected onto the constraints).
pub static QD0: [f64; 6usize] = [0f64, 0f64, 0f64, 0f64, 0f64, 0f64];
/// Constraint rows dependent on others at the initial pose (dropped by the solvers).
pub static REDUNDANT_ROWS: [u32; 0usize] = [];
/// Simulation end time suggested by the mechanism file (s).
pub const T_END: f64 = 2000f64;
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
pub const N_K: usize = 6;
/// `setup` at the file's parameter values: what the types without parameters read.
pub static K: [f64; 6] = [-1f64, 0.00004f64, 9.81f64, -9.81f64, 1f64, 0.00004f64];
/// The values the per-step functions read (`k`), from the run-time parameters `p`.
pub fn setup(p: &[f64], k: &mut [f64]) {
    let p: &[f64; 8] = p.try_into().expect("p must have 8 entries");
    let k: &mut [f64; 6] = k.try_into().expect("k must have 6 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 8], k: &mut [f64; 6]) {
    let x42 = -p[7];
    let x90 = p[0] * 0.4;
    let x92 = x90 * 0.01;
    let x93 = 0.01 * x92;
    let x96 = p[0] * 9.81;
    let x97 = -x96;
    let x160 = 2.0 * p[0];
    let x161 = 0.5 * x160;
    let x162 = 2.0 * x93;
    let x163 = 0.5 * x162;
    k[0] = x42;
    k[1] = x93;
    k[2] = x96;
    k[3] = x97;
    k[4] = x161;
    k[5] = x163;
}
/// The parameters the generated code takes at run time by name: the file's
/// `[parameters]` entries that reach only masses, inertias and springs' constants.
pub static PARAMETERS: [&str; 1] = ["m"];
/// Their values in the file.
pub static PARAMETER_VALUES: [f64; 1] = [1f64];
/// Number of values `p` holds: the parameters by name, then the model's numbers that
/// the other parameters reach (read off the file loaded at their values: `DATA`).
pub const N_P: usize = 8;
/// `p` at the file's values.
pub static P0: [f64; 8] = [
    1f64,
    1f64,
    1f64,
    1f64,
    0.00004f64,
    0.00004f64,
    0.00004f64,
    1f64,
];
/// Where the numbers after the named parameters come from in the model (positions in
/// the generator's `slots::numbers`).
pub static DATA: [u32; 7] = [3u32, 4u32, 5u32, 6u32, 7u32, 8u32, 27u32];
static OTHER_PARAMETERS: [&str; 2] = ["ball", "l"];
static BODY_NAMES: [&str; 1] = ["p1"];
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
    let p: &[f64; 8] = p.try_into().expect("p must have 8 entries");
    let out: &mut [f64; 4] = out.try_into().expect("out must have 4 entries");
    mass_properties_part_0(p, out);
}
#[inline(never)]
fn mass_properties_part_0(p: &[f64; 8], out: &mut [f64; 4]) {
    let x90 = p[0] * 0.4;
    let x92 = x90 * 0.01;
    let x93 = 0.01 * x92;
    out[0] = p[0];
    out[1] = x93;
    out[2] = x93;
    out[3] = x93;
}
/// Each force's stiffness and damping at the run-time parameters `p`.
pub fn force_constants(p: &[f64], out: &mut [f64]) {
    let p: &[f64; 8] = p.try_into().expect("p must have 8 entries");
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
    pub static MASS_ROWS: [u32; 10usize] = [
        0u32, 1u32, 2u32, 3u32, 3u32, 4u32, 4u32, 5u32, 5u32, 5u32,
    ];
    /// Column of each mass-matrix nonzero.
    pub static MASS_COLS: [u32; 10usize] = [
        0u32, 1u32, 2u32, 3u32, 5u32, 4u32, 5u32, 3u32, 4u32, 5u32,
    ];
    /// Row and column of each ∂Q/∂q nonzero.
    pub static FORCE_Q_ROWS: [u32; 0usize] = [];
    pub static FORCE_Q_COLS: [u32; 0usize] = [];
    /// Row and column of each ∂Q/∂q̇ nonzero.
    pub static FORCE_QD_ROWS: [u32; 0usize] = [];
    pub static FORCE_QD_COLS: [u32; 0usize] = [];
    /// Sizes, patterns and names for this formulation.
    pub static INFO: MechanismInfo = MechanismInfo {
        name: "simple_pendulum",
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
            pattern: 0x2c95ee8bb8a17801,
            storage: 12,
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
        let mass: &[f64; 10] = mass
            .try_into()
            .map_err(|_| length_error(10, mass.len()))?;
        let phi_q: &[f64; 3] = phi_q
            .try_into()
            .map_err(|_| length_error(3, phi_q.len()))?;
        let st_len = st.len();
        let st: &mut [f64; 12] = st.try_into().map_err(|_| length_error(12, st_len))?;
        if !((c * mass[0]) > 0.0 && (c * mass[0]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[0]), 0));
        }
        let v0: f64 = (c * mass[0]).sqrt();
        let v1: f64 = 1.0 / v0;
        st[2] = v1;
        if !((c * mass[1]) > 0.0 && (c * mass[1]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[1]), 1));
        }
        let v2: f64 = (c * mass[1]).sqrt();
        let v3: f64 = 1.0 / v2;
        st[3] = v3;
        if !((c * mass[2]) > 0.0 && (c * mass[2]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[2]), 2));
        }
        let v4: f64 = (c * mass[2]).sqrt();
        let v5: f64 = 1.0 / v4;
        st[4] = v5;
        if !((c * mass[3]) > 0.0 && (c * mass[3]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[3]), 3));
        }
        let v6: f64 = (c * mass[3]).sqrt();
        let v7: f64 = 1.0 / v6;
        st[5] = v7;
        let v8: f64 = (c * mass[7]) * v7;
        st[0] = v8;
        if !((c * mass[5]) > 0.0 && (c * mass[5]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[5]), 4));
        }
        let v9: f64 = (c * mass[5]).sqrt();
        let v10: f64 = 1.0 / v9;
        st[6] = v10;
        let v11: f64 = (c * mass[8]) * v10;
        st[1] = v11;
        let v12: f64 = (c * mass[9]) - v8 * v8;
        let v13: f64 = v12 - v11 * v11;
        if !(v13 > 0.0 && v13 <= f64::MAX) {
            return Err(mass_pivot_error(v13, 5));
        }
        let v14: f64 = v13.sqrt();
        let v15: f64 = 1.0 / v14;
        st[7] = v15;
        let v16: f64 = phi_q[0] * v1;
        st[8] = v16;
        let v17: f64 = phi_q[1] * v3;
        st[9] = v17;
        let v18: f64 = phi_q[2] * v5;
        st[10] = v18;
        let v19: f64 = v16 * v16;
        let v20: f64 = v17 * v17;
        let v21: f64 = v19 + v20;
        let v22: f64 = v18 * v18;
        let v23: f64 = v21 + v22;
        let (v24, v25) = piv.pivot(v23, v23, 0, false)?;
        st[11] = v24;
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
        let f: &[f64; 6] = f.try_into().map_err(|_| length_error(6, f.len()))?;
        let g: &[f64; 1] = g.try_into().map_err(|_| length_error(1, g.len()))?;
        let x_len = x.len();
        let x: &mut [f64; 6] = x.try_into().map_err(|_| length_error(6, x_len))?;
        let y_len = y.len();
        let y: &mut [f64; 1] = y.try_into().map_err(|_| length_error(1, y_len))?;
        let st: &[f64; 12] = st.try_into().map_err(|_| length_error(12, st.len()))?;
        x.fill(0.0);
        y[0] = -g[0];
        if f.iter().any(|&v| v != 0.0) {
            let v0: f64 = f[0];
            let v1: f64 = f[1];
            let v2: f64 = f[2];
            let v3: f64 = f[3];
            let v4: f64 = f[4];
            let v5: f64 = f[5];
            let v6: f64 = v0 * st[2];
            let v7: f64 = v1 * st[3];
            let v8: f64 = v2 * st[4];
            let v9: f64 = v3 * st[5];
            let v10: f64 = v4 * st[6];
            let v11: f64 = v5 - st[0] * v9;
            let v12: f64 = v11 - st[1] * v10;
            let v13: f64 = v12 * st[7];
            let v14: f64 = st[8] * v6;
            let v15: f64 = st[9] * v7;
            let v16: f64 = v14 + v15;
            let v17: f64 = st[10] * v8;
            let v18: f64 = v16 + v17;
            y[0] += v18;
            x[0] = v6;
            x[1] = v7;
            x[2] = v8;
            x[3] = v9;
            x[4] = v10;
            x[5] = v13;
        }
        let v19: f64 = y[0] * st[11];
        y[0] = v19;
        let v20: f64 = x[0] - st[8] * v19;
        let v21: f64 = x[1] - st[9] * v19;
        let v22: f64 = x[2] - st[10] * v19;
        let v23: f64 = x[5] * st[7];
        let v24: f64 = x[4] - st[1] * v23;
        let v25: f64 = v24 * st[6];
        let v26: f64 = x[3] - st[0] * v23;
        let v27: f64 = v26 * st[5];
        let v28: f64 = v22 * st[4];
        let v29: f64 = v21 * st[3];
        let v30: f64 = v20 * st[2];
        x[0] = v30;
        x[1] = v29;
        x[2] = v28;
        x[3] = v27;
        x[4] = v25;
        x[5] = v23;
        Ok(())
    }
    fn kkt_transpose_times(
        phi_q: &[f64],
        y: &[f64],
        out: &mut [f64],
    ) -> Result<(), KktError> {
        let phi_q: &[f64; 3] = phi_q
            .try_into()
            .map_err(|_| length_error(3, phi_q.len()))?;
        let y: &[f64; 1] = y.try_into().map_err(|_| length_error(1, y.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 6] = out.try_into().map_err(|_| length_error(6, out_len))?;
        out[0] = phi_q[0] * y[0];
        out[1] = phi_q[1] * y[0];
        out[2] = phi_q[2] * y[0];
        out[3] = 0.0;
        out[4] = 0.0;
        out[5] = 0.0;
        Ok(())
    }
    #[allow(clippy::assign_op_pattern)]
    fn kkt_times_add(phi_q: &[f64], x: &[f64], out: &mut [f64]) -> Result<(), KktError> {
        let phi_q: &[f64; 3] = phi_q
            .try_into()
            .map_err(|_| length_error(3, phi_q.len()))?;
        let x: &[f64; 6] = x.try_into().map_err(|_| length_error(6, x.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 1] = out.try_into().map_err(|_| length_error(1, out_len))?;
        out[0] = out[0] + phi_q[0] * x[0] + phi_q[1] * x[1] + phi_q[2] * x[2];
        Ok(())
    }
    fn kkt_mass_times(mass: &[f64], v: &[f64], out: &mut [f64]) -> Result<(), KktError> {
        let mass: &[f64; 10] = mass
            .try_into()
            .map_err(|_| length_error(10, mass.len()))?;
        let v: &[f64; 6] = v.try_into().map_err(|_| length_error(6, v.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 6] = out.try_into().map_err(|_| length_error(6, out_len))?;
        out[0] = 0.0 + mass[0] * v[0];
        out[1] = 0.0 + mass[1] * v[1];
        out[2] = 0.0 + mass[2] * v[2];
        out[3] = 0.0 + mass[3] * v[3] + mass[4] * v[5];
        out[4] = 0.0 + mass[5] * v[4] + mass[6] * v[5];
        out[5] = 0.0 + mass[7] * v[3] + mass[8] * v[4] + mass[9] * v[5];
        Ok(())
    }
    fn kkt_kinetic_energy(mass: &[f64], qd: &[f64]) -> Result<f64, KktError> {
        let mass: &[f64; 10] = mass
            .try_into()
            .map_err(|_| length_error(10, mass.len()))?;
        let qd: &[f64; 6] = qd.try_into().map_err(|_| length_error(6, qd.len()))?;
        let mut t = 0.0;
        t += qd[0] * mass[0] * qd[0];
        t += qd[1] * mass[1] * qd[1];
        t += qd[2] * mass[2] * qd[2];
        t += qd[3] * mass[3] * qd[3];
        t += qd[3] * mass[4] * qd[5];
        t += qd[4] * mass[5] * qd[4];
        t += qd[4] * mass[6] * qd[5];
        t += qd[5] * mass[7] * qd[3];
        t += qd[5] * mass[8] * qd[4];
        t += qd[5] * mass[9] * qd[5];
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
        let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
        let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
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
        let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 10] = out.try_into().expect("out must have 10 entries");
        mass_part_0(k, q, out);
    }
    #[inline(never)]
    fn mass_part_0(k: &[f64; 6], q: &[f64; 6], out: &mut [f64; 10]) {
        let (x6, x7) = symbody_runtime::trig::sin_cos(q[3]);
        let (x8, x9) = symbody_runtime::trig::sin_cos(q[4]);
        let x16 = x6 * x9;
        let x17 = x7 * x9;
        let x164 = x8 * 2.0;
        let x170 = x7 * 2.0;
        let x171 = x6 * 2.0;
        let x173 = x7 * x170;
        let x175 = x6 * x171;
        let x181 = x16 * 2.0;
        let x182 = x17 * 2.0;
        let x183 = x7 * x181;
        let x185 = x6 * x182;
        let x190 = x16 * x170;
        let x192 = x17 * x171;
        let x198 = x8 * x164;
        let x202 = x16 * x181;
        let x204 = x17 * x182;
        let x752 = x164 * k[1];
        let x753 = 0.5 * x752;
        let x754 = -x753;
        let x755 = x173 * k[1];
        let x756 = x175 * k[1];
        let x757 = x755 + x756;
        let x758 = 0.5 * x757;
        let x759 = x183 * k[1];
        let x760 = x185 * k[1];
        let x762 = x759 - x760;
        let x763 = 0.5 * x762;
        let x764 = x190 * k[1];
        let x765 = x192 * k[1];
        let x767 = x764 - x765;
        let x768 = 0.5 * x767;
        let x769 = x198 * k[1];
        let x770 = x202 * k[1];
        let x771 = x204 * k[1];
        let x772 = x769 + x770;
        let x773 = x771 + x772;
        let x774 = 0.5 * x773;
        out[0] = k[4];
        out[1] = k[4];
        out[2] = k[4];
        out[3] = k[5];
        out[4] = x754;
        out[5] = x758;
        out[6] = x763;
        out[7] = x754;
        out[8] = x768;
        out[9] = x774;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
        let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 6] = out.try_into().expect("out must have 6 entries");
        let _ = t;
        force_part_0(k, q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(k: &[f64; 6], q: &[f64; 6], qd: &[f64; 6], out: &mut [f64; 6]) {
        let (x6, x7) = symbody_runtime::trig::sin_cos(q[3]);
        let (x8, x9) = symbody_runtime::trig::sin_cos(q[4]);
        let x16 = x6 * x9;
        let x17 = x7 * x9;
        let x100 = x8 * qd[5];
        let x102 = x9 * qd[5];
        let x103 = x7 * qd[4];
        let x104 = x6 * x102;
        let x105 = x103 + x104;
        let x106 = x6 * qd[4];
        let x107 = x7 * x102;
        let x109 = x107 - x106;
        let x110 = qd[3] - x100;
        let x130 = 2.0 * x110;
        let x131 = 2.0 * x105;
        let x132 = 2.0 * x109;
        let x209 = x7 * qd[3];
        let x210 = x6 * qd[3];
        let x212 = x9 * qd[4];
        let x213 = x8 * qd[4];
        let x215 = x9 * x209;
        let x216 = x6 * x213;
        let x218 = x215 - x216;
        let x219 = x9 * x210;
        let x221 = x7 * x213;
        let x223 = x219 + x221;
        let x225 = qd[5] * x212;
        let x227 = qd[5] * x213;
        let x229 = qd[4] * x210;
        let x231 = x102 * x209;
        let x232 = x6 * x227;
        let x234 = x231 - x232;
        let x235 = x234 - x229;
        let x236 = qd[4] * x209;
        let x237 = x102 * x210;
        let x239 = x7 * x227;
        let x241 = x237 + x239;
        let x244 = x236 + x241;
        let x246 = 2.0 * x225;
        let x248 = 2.0 * x235;
        let x249 = 2.0 * x244;
        let x255 = x131 * x210;
        let x257 = x7 * x248;
        let x258 = x257 - x255;
        let x260 = x132 * x209;
        let x261 = x6 * x249;
        let x263 = x260 - x261;
        let x268 = x130 * x212;
        let x269 = x8 * x246;
        let x271 = x268 - x269;
        let x274 = x131 * x218;
        let x275 = x16 * x248;
        let x276 = x274 + x275;
        let x278 = x132 * x223;
        let x280 = x17 * x249;
        let x282 = x278 + x280;
        let x292 = x109 * x131;
        let x294 = x105 * x132;
        let x302 = x6 * x100;
        let x304 = x7 * x100;
        let x306 = x102 * x130;
        let x310 = x131 * x302;
        let x314 = x132 * x304;
        let x775 = x246 * k[1];
        let x776 = 0.5 * x775;
        let x777 = x258 * k[1];
        let x778 = x263 * k[1];
        let x780 = x777 - x778;
        let x781 = 0.5 * x780;
        let x782 = x271 * k[1];
        let x784 = x276 * k[1];
        let x785 = x282 * k[1];
        let x787 = x784 - x782;
        let x788 = x787 - x785;
        let x789 = 0.5 * x788;
        let x790 = x292 * k[1];
        let x791 = x294 * k[1];
        let x793 = x790 - x791;
        let x794 = 0.5 * x793;
        let x795 = x776 + x794;
        let x796 = x306 * k[1];
        let x797 = x310 * k[1];
        let x798 = x314 * k[1];
        let x799 = x796 + x797;
        let x800 = x798 + x799;
        let x801 = 0.5 * x800;
        let x802 = x781 + x801;
        let x803 = -x802;
        let x804 = -x789;
        out[0] = 0.0;
        out[1] = k[3];
        out[2] = 0.0;
        out[3] = x795;
        out[4] = x803;
        out[5] = x804;
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
        let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 1] = phi.try_into().expect("phi must have 1 entries");
        let phi_q: &mut [f64; 3] = phi_q.try_into().expect("phi_q must have 3 entries");
        let mass: &mut [f64; 10] = mass.try_into().expect("mass must have 10 entries");
        let force: &mut [f64; 6] = force.try_into().expect("force must have 6 entries");
        let _ = t;
        eval_newton_part_0(k, q, qd, phi, phi_q, mass, force);
    }
    #[inline(never)]
    fn eval_newton_part_0(
        k: &[f64; 6],
        q: &[f64; 6],
        qd: &[f64; 6],
        phi: &mut [f64; 1],
        phi_q: &mut [f64; 3],
        mass: &mut [f64; 10],
        force: &mut [f64; 6],
    ) {
        let (x6, x7) = symbody_runtime::trig::sin_cos(q[3]);
        let (x8, x9) = symbody_runtime::trig::sin_cos(q[4]);
        let x16 = x6 * x9;
        let x17 = x7 * x9;
        let x35 = q[0] * q[0];
        let x36 = q[1] * q[1];
        let x37 = q[2] * q[2];
        let x38 = x35 + x36;
        let x39 = x37 + x38;
        let x40 = x39.sqrt();
        let x45 = q[0] * 2.0;
        let x46 = q[1] * 2.0;
        let x47 = q[2] * 2.0;
        let x48 = x40 * 2.0;
        let x49 = 1.0 / x48;
        let x50 = x45 * x49;
        let x51 = x46 * x49;
        let x52 = x47 * x49;
        let x100 = x8 * qd[5];
        let x102 = x9 * qd[5];
        let x103 = x7 * qd[4];
        let x104 = x6 * x102;
        let x105 = x103 + x104;
        let x106 = x6 * qd[4];
        let x107 = x7 * x102;
        let x109 = x107 - x106;
        let x110 = qd[3] - x100;
        let x130 = 2.0 * x110;
        let x131 = 2.0 * x105;
        let x132 = 2.0 * x109;
        let x164 = x8 * 2.0;
        let x170 = x7 * 2.0;
        let x171 = x6 * 2.0;
        let x173 = x7 * x170;
        let x175 = x6 * x171;
        let x181 = x16 * 2.0;
        let x182 = x17 * 2.0;
        let x183 = x7 * x181;
        let x185 = x6 * x182;
        let x190 = x16 * x170;
        let x192 = x17 * x171;
        let x198 = x8 * x164;
        let x202 = x16 * x181;
        let x204 = x17 * x182;
        let x209 = x7 * qd[3];
        let x210 = x6 * qd[3];
        let x212 = x9 * qd[4];
        let x213 = x8 * qd[4];
        let x215 = x9 * x209;
        let x216 = x6 * x213;
        let x218 = x215 - x216;
        let x219 = x9 * x210;
        let x221 = x7 * x213;
        let x223 = x219 + x221;
        let x225 = qd[5] * x212;
        let x227 = qd[5] * x213;
        let x229 = qd[4] * x210;
        let x231 = x102 * x209;
        let x232 = x6 * x227;
        let x234 = x231 - x232;
        let x235 = x234 - x229;
        let x236 = qd[4] * x209;
        let x237 = x102 * x210;
        let x239 = x7 * x227;
        let x241 = x237 + x239;
        let x244 = x236 + x241;
        let x246 = 2.0 * x225;
        let x248 = 2.0 * x235;
        let x249 = 2.0 * x244;
        let x255 = x131 * x210;
        let x257 = x7 * x248;
        let x258 = x257 - x255;
        let x260 = x132 * x209;
        let x261 = x6 * x249;
        let x263 = x260 - x261;
        let x268 = x130 * x212;
        let x269 = x8 * x246;
        let x271 = x268 - x269;
        let x274 = x131 * x218;
        let x275 = x16 * x248;
        let x276 = x274 + x275;
        let x278 = x132 * x223;
        let x280 = x17 * x249;
        let x282 = x278 + x280;
        let x292 = x109 * x131;
        let x294 = x105 * x132;
        let x302 = x6 * x100;
        let x304 = x7 * x100;
        let x306 = x102 * x130;
        let x310 = x131 * x302;
        let x314 = x132 * x304;
        let x745 = x40 + k[0];
        let x752 = x164 * k[1];
        let x753 = 0.5 * x752;
        let x754 = -x753;
        let x755 = x173 * k[1];
        let x756 = x175 * k[1];
        let x757 = x755 + x756;
        let x758 = 0.5 * x757;
        let x759 = x183 * k[1];
        let x760 = x185 * k[1];
        let x762 = x759 - x760;
        let x763 = 0.5 * x762;
        let x764 = x190 * k[1];
        let x765 = x192 * k[1];
        let x767 = x764 - x765;
        let x768 = 0.5 * x767;
        let x769 = x198 * k[1];
        let x770 = x202 * k[1];
        let x771 = x204 * k[1];
        let x772 = x769 + x770;
        let x773 = x771 + x772;
        let x774 = 0.5 * x773;
        let x775 = x246 * k[1];
        let x776 = 0.5 * x775;
        let x777 = x258 * k[1];
        let x778 = x263 * k[1];
        let x780 = x777 - x778;
        let x781 = 0.5 * x780;
        let x782 = x271 * k[1];
        let x784 = x276 * k[1];
        let x785 = x282 * k[1];
        let x787 = x784 - x782;
        let x788 = x787 - x785;
        let x789 = 0.5 * x788;
        let x790 = x292 * k[1];
        let x791 = x294 * k[1];
        let x793 = x790 - x791;
        let x794 = 0.5 * x793;
        let x795 = x776 + x794;
        let x796 = x306 * k[1];
        let x797 = x310 * k[1];
        let x798 = x314 * k[1];
        let x799 = x796 + x797;
        let x800 = x798 + x799;
        let x801 = 0.5 * x800;
        let x802 = x781 + x801;
        let x803 = -x802;
        let x804 = -x789;
        phi[0] = x745;
        phi_q[0] = x50;
        phi_q[1] = x51;
        phi_q[2] = x52;
        mass[0] = k[4];
        mass[1] = k[4];
        mass[2] = k[4];
        mass[3] = k[5];
        mass[4] = x754;
        mass[5] = x758;
        mass[6] = x763;
        mass[7] = x754;
        mass[8] = x768;
        mass[9] = x774;
        force[0] = 0.0;
        force[1] = k[3];
        force[2] = 0.0;
        force[3] = x795;
        force[4] = x803;
        force[5] = x804;
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
        let k: &[f64; 6] = k.try_into().expect("k must have 6 entries");
        let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
        let dq: &[f64; 6] = dq.try_into().expect("dq must have n_coords entries");
        let dqd: &[f64; 6] = dqd.try_into().expect("dqd must have n_coords entries");
        let dp: &[f64; 8] = dp.try_into().expect("dp must have 8 entries");
        let mass: &mut [f64; 10] = mass.try_into().expect("mass must have 10 entries");
        let force: &mut [f64; 6] = force.try_into().expect("force must have 6 entries");
        let _ = t;
        tangents_part_0(k, q, qd, dq, dqd, dp, mass, force);
    }
    #[inline(never)]
    fn tangents_part_0(
        k: &[f64; 6],
        q: &[f64; 6],
        qd: &[f64; 6],
        dq: &[f64; 6],
        dqd: &[f64; 6],
        dp: &[f64; 8],
        mass: &mut [f64; 10],
        force: &mut [f64; 6],
    ) {
        let (x6, x7) = symbody_runtime::trig::sin_cos(q[3]);
        let (x8, x9) = symbody_runtime::trig::sin_cos(q[4]);
        let x16 = x6 * x9;
        let x17 = x7 * x9;
        let x100 = x8 * qd[5];
        let x102 = x9 * qd[5];
        let x103 = x7 * qd[4];
        let x104 = x6 * x102;
        let x105 = x103 + x104;
        let x106 = x6 * qd[4];
        let x107 = x7 * x102;
        let x109 = x107 - x106;
        let x110 = qd[3] - x100;
        let x130 = 2.0 * x110;
        let x131 = 2.0 * x105;
        let x132 = 2.0 * x109;
        let x164 = x8 * 2.0;
        let x170 = x7 * 2.0;
        let x171 = x6 * 2.0;
        let x173 = x7 * x170;
        let x175 = x6 * x171;
        let x181 = x16 * 2.0;
        let x182 = x17 * 2.0;
        let x183 = x7 * x181;
        let x185 = x6 * x182;
        let x190 = x16 * x170;
        let x192 = x17 * x171;
        let x198 = x8 * x164;
        let x202 = x16 * x181;
        let x204 = x17 * x182;
        let x209 = x7 * qd[3];
        let x210 = x6 * qd[3];
        let x212 = x9 * qd[4];
        let x213 = x8 * qd[4];
        let x215 = x9 * x209;
        let x216 = x6 * x213;
        let x218 = x215 - x216;
        let x219 = x9 * x210;
        let x221 = x7 * x213;
        let x223 = x219 + x221;
        let x225 = qd[5] * x212;
        let x227 = qd[5] * x213;
        let x229 = qd[4] * x210;
        let x231 = x102 * x209;
        let x232 = x6 * x227;
        let x234 = x231 - x232;
        let x235 = x234 - x229;
        let x236 = qd[4] * x209;
        let x237 = x102 * x210;
        let x239 = x7 * x227;
        let x241 = x237 + x239;
        let x244 = x236 + x241;
        let x246 = 2.0 * x225;
        let x248 = 2.0 * x235;
        let x249 = 2.0 * x244;
        let x255 = x131 * x210;
        let x257 = x7 * x248;
        let x258 = x257 - x255;
        let x260 = x132 * x209;
        let x261 = x6 * x249;
        let x263 = x260 - x261;
        let x268 = x130 * x212;
        let x269 = x8 * x246;
        let x271 = x268 - x269;
        let x274 = x131 * x218;
        let x275 = x16 * x248;
        let x276 = x274 + x275;
        let x278 = x132 * x223;
        let x280 = x17 * x249;
        let x282 = x278 + x280;
        let x292 = x109 * x131;
        let x294 = x105 * x132;
        let x302 = x6 * x100;
        let x304 = x7 * x100;
        let x306 = x102 * x130;
        let x310 = x131 * x302;
        let x314 = x132 * x304;
        let x348 = x7 * dq[3];
        let x349 = x6 * dq[3];
        let x351 = x9 * dq[4];
        let x352 = x8 * dq[4];
        let x354 = x9 * x348;
        let x355 = x6 * x352;
        let x357 = x354 - x355;
        let x358 = x9 * x349;
        let x360 = x7 * x352;
        let x362 = x358 + x360;
        let x437 = 0.4 * dp[0];
        let x438 = 0.01 * x437;
        let x439 = 0.01 * x438;
        let x440 = 9.81 * dp[0];
        let x441 = -x440;
        let x442 = qd[5] * x351;
        let x443 = x8 * dqd[5];
        let x444 = x442 + x443;
        let x446 = qd[5] * x352;
        let x448 = x9 * dqd[5];
        let x449 = x448 - x446;
        let x450 = qd[4] * x349;
        let x452 = x7 * dqd[4];
        let x453 = x452 - x450;
        let x454 = x102 * x348;
        let x455 = x6 * x449;
        let x456 = x454 + x455;
        let x457 = x453 + x456;
        let x458 = qd[4] * x348;
        let x459 = x6 * dqd[4];
        let x460 = x458 + x459;
        let x461 = x102 * x349;
        let x463 = x7 * x449;
        let x464 = x463 - x461;
        let x466 = x464 - x460;
        let x467 = dqd[3] - x444;
        let x468 = 2.0 * x467;
        let x469 = 2.0 * x457;
        let x470 = 2.0 * x466;
        let x471 = 2.0 * dp[0];
        let x472 = 0.5 * x471;
        let x473 = 2.0 * x439;
        let x474 = 0.5 * x473;
        let x475 = 2.0 * x351;
        let x476 = x164 * x439;
        let x481 = 2.0 * x349;
        let x483 = 2.0 * x348;
        let x484 = x170 * x349;
        let x486 = x7 * x481;
        let x488 = x484 + x486;
        let x490 = x173 * x439;
        let x494 = x171 * x348;
        let x495 = x6 * x483;
        let x496 = x494 + x495;
        let x497 = x175 * x439;
        let x502 = 2.0 * x357;
        let x503 = 2.0 * x362;
        let x505 = x181 * x349;
        let x507 = x7 * x502;
        let x508 = x507 - x505;
        let x509 = x183 * x439;
        let x512 = x182 * x348;
        let x513 = x6 * x503;
        let x515 = x512 - x513;
        let x516 = x185 * x439;
        let x522 = x170 * x357;
        let x523 = x16 * x481;
        let x525 = x522 - x523;
        let x526 = x190 * x439;
        let x529 = x171 * x362;
        let x531 = x17 * x483;
        let x532 = x531 - x529;
        let x533 = x192 * x439;
        let x539 = x164 * x351;
        let x540 = x8 * x475;
        let x541 = x539 + x540;
        let x542 = x198 * x439;
        let x545 = x181 * x357;
        let x546 = x16 * x502;
        let x547 = x545 + x546;
        let x548 = x202 * x439;
        let x551 = x182 * x362;
        let x553 = x17 * x503;
        let x555 = x551 + x553;
        let x557 = x204 * x439;
        let x564 = qd[3] * x349;
        let x566 = x7 * dqd[3];
        let x567 = x566 - x564;
        let x568 = qd[3] * x348;
        let x569 = x6 * dqd[3];
        let x570 = x568 + x569;
        let x571 = qd[4] * x352;
        let x573 = x9 * dqd[4];
        let x574 = x573 - x571;
        let x575 = qd[4] * x351;
        let x576 = x8 * dqd[4];
        let x577 = x575 + x576;
        let x578 = x209 * x352;
        let x580 = x9 * x567;
        let x581 = x580 - x578;
        let x582 = x213 * x348;
        let x583 = x6 * x577;
        let x584 = x582 + x583;
        let x586 = x581 - x584;
        let x587 = x210 * x352;
        let x589 = x9 * x570;
        let x590 = x589 - x587;
        let x591 = x213 * x349;
        let x593 = x7 * x577;
        let x594 = x593 - x591;
        let x595 = x590 + x594;
        let x596 = x212 * dqd[5];
        let x597 = qd[5] * x574;
        let x598 = x596 + x597;
        let x599 = x213 * dqd[5];
        let x600 = qd[5] * x577;
        let x601 = x599 + x600;
        let x602 = x210 * dqd[4];
        let x603 = qd[4] * x570;
        let x604 = x602 + x603;
        let x606 = x209 * x449;
        let x607 = x102 * x567;
        let x608 = x606 + x607;
        let x609 = x227 * x348;
        let x610 = x6 * x601;
        let x611 = x609 + x610;
        let x613 = x608 - x611;
        let x614 = x613 - x604;
        let x615 = x209 * dqd[4];
        let x616 = qd[4] * x567;
        let x617 = x615 + x616;
        let x618 = x210 * x449;
        let x619 = x102 * x570;
        let x620 = x618 + x619;
        let x621 = x227 * x349;
        let x623 = x7 * x601;
        let x624 = x623 - x621;
        let x625 = x620 + x624;
        let x626 = x617 + x625;
        let x627 = 2.0 * x598;
        let x628 = 2.0 * x614;
        let x629 = 2.0 * x626;
        let x630 = x246 * x439;
        let x634 = x210 * x469;
        let x635 = x131 * x570;
        let x636 = x634 + x635;
        let x638 = x248 * x349;
        let x640 = x7 * x628;
        let x641 = x640 - x638;
        let x642 = x641 - x636;
        let x643 = x258 * x439;
        let x646 = x209 * x470;
        let x647 = x132 * x567;
        let x648 = x646 + x647;
        let x649 = x249 * x348;
        let x650 = x6 * x629;
        let x651 = x649 + x650;
        let x653 = x648 - x651;
        let x654 = x263 * x439;
        let x660 = x212 * x468;
        let x661 = x130 * x574;
        let x662 = x660 + x661;
        let x663 = x246 * x351;
        let x664 = x8 * x627;
        let x665 = x663 + x664;
        let x667 = x662 - x665;
        let x668 = x271 * x439;
        let x672 = x218 * x469;
        let x673 = x131 * x586;
        let x674 = x672 + x673;
        let x675 = x248 * x357;
        let x676 = x16 * x628;
        let x677 = x675 + x676;
        let x678 = x674 + x677;
        let x679 = x276 * x439;
        let x682 = x223 * x470;
        let x683 = x132 * x595;
        let x684 = x682 + x683;
        let x685 = x249 * x362;
        let x687 = x17 * x629;
        let x688 = x687 - x685;
        let x689 = x684 + x688;
        let x690 = x282 * x439;
        let x697 = x131 * x466;
        let x698 = x109 * x469;
        let x699 = x697 + x698;
        let x700 = x292 * x439;
        let x703 = x132 * x457;
        let x704 = x105 * x470;
        let x705 = x703 + x704;
        let x706 = x294 * x439;
        let x713 = x100 * x348;
        let x714 = x6 * x444;
        let x715 = x713 + x714;
        let x716 = x100 * x349;
        let x718 = x7 * x444;
        let x719 = x718 - x716;
        let x720 = x130 * x449;
        let x721 = x102 * x468;
        let x722 = x720 + x721;
        let x723 = x306 * x439;
        let x726 = x302 * x469;
        let x727 = x131 * x715;
        let x728 = x726 + x727;
        let x729 = x310 * x439;
        let x732 = x304 * x470;
        let x733 = x132 * x719;
        let x734 = x732 + x733;
        let x735 = x314 * x439;
        let x805 = x475 * k[1];
        let x806 = x476 + x805;
        let x807 = 0.5 * x806;
        let x808 = -x807;
        let x809 = x488 * k[1];
        let x811 = x490 - x809;
        let x812 = x496 * k[1];
        let x813 = x497 + x812;
        let x814 = x811 + x813;
        let x815 = 0.5 * x814;
        let x816 = x508 * k[1];
        let x817 = x509 + x816;
        let x818 = x515 * k[1];
        let x819 = x516 + x818;
        let x821 = x817 - x819;
        let x822 = 0.5 * x821;
        let x823 = x525 * k[1];
        let x824 = x526 + x823;
        let x825 = x532 * k[1];
        let x826 = x533 + x825;
        let x828 = x824 - x826;
        let x829 = 0.5 * x828;
        let x830 = x541 * k[1];
        let x831 = x542 + x830;
        let x832 = x547 * k[1];
        let x833 = x548 + x832;
        let x834 = x555 * k[1];
        let x836 = x557 - x834;
        let x837 = x831 + x833;
        let x838 = x836 + x837;
        let x839 = 0.5 * x838;
        let x840 = x627 * k[1];
        let x841 = x630 + x840;
        let x842 = 0.5 * x841;
        let x843 = x642 * k[1];
        let x844 = x643 + x843;
        let x845 = x653 * k[1];
        let x846 = x654 + x845;
        let x848 = x844 - x846;
        let x849 = 0.5 * x848;
        let x850 = x667 * k[1];
        let x851 = x668 + x850;
        let x853 = x678 * k[1];
        let x854 = x679 + x853;
        let x855 = x689 * k[1];
        let x856 = x690 + x855;
        let x858 = x854 - x851;
        let x859 = x858 - x856;
        let x860 = 0.5 * x859;
        let x861 = x699 * k[1];
        let x862 = x700 + x861;
        let x863 = x705 * k[1];
        let x864 = x706 + x863;
        let x866 = x862 - x864;
        let x867 = 0.5 * x866;
        let x868 = x842 + x867;
        let x869 = x722 * k[1];
        let x870 = x723 + x869;
        let x871 = x728 * k[1];
        let x872 = x729 + x871;
        let x873 = x734 * k[1];
        let x874 = x735 + x873;
        let x875 = x870 + x872;
        let x876 = x874 + x875;
        let x877 = 0.5 * x876;
        let x878 = x849 + x877;
        let x879 = -x878;
        let x880 = -x860;
        mass[0] = x472;
        mass[1] = x472;
        mass[2] = x472;
        mass[3] = x474;
        mass[4] = x808;
        mass[5] = x815;
        mass[6] = x822;
        mass[7] = x808;
        mass[8] = x829;
        mass[9] = x839;
        force[0] = 0.0;
        force[1] = x441;
        force[2] = 0.0;
        force[3] = x868;
        force[4] = x879;
        force[5] = x880;
    }
}
/// The system after substituting rows `a·qᵢ + b·qⱼ + g(t) = 0` away (docs/design.md,
/// decision 24): fewer coordinates and rows, the same motion and multipliers once
/// mapped back with `REDUCTION`.
pub mod reduced {
    use super::*;
    /// Number of reduced coordinates.
    pub const N_COORDS: usize = 3usize;
    /// Number of reduced rows.
    pub const N_CONSTRAINTS: usize = 1usize;
    /// Row of each Φq nonzero.
    pub static PHI_Q_ROWS: [u32; 2usize] = [0u32, 0u32];
    /// Column of each Φq nonzero.
    pub static PHI_Q_COLS: [u32; 2usize] = [0u32, 1u32];
    /// Name of each reduced coordinate (its full model's name).
    pub static COORD_NAMES: [&str; 3usize] = ["p1.x", "p1.y", "p1.gamma"];
    /// Name of each reduced row (its full model's name).
    pub static ROW_NAMES: [&str; 1usize] = ["link.distance"];
    /// Initial coordinates, from the full model's assembled ones.
    pub static Q0: [f64; 3usize] = [1f64, 0f64, 0f64];
    /// Initial velocities from the file.
    pub static QD0: [f64; 3usize] = [0f64, 0f64, 0f64];
    /// Rows dependent on others at the initial pose.
    pub static REDUNDANT_ROWS: [u32; 0usize] = [];
    /// Full index of each reduced coordinate.
    pub static COORDS: [u32; 3usize] = [0u32, 1u32, 5u32];
    /// Full index of each reduced row.
    pub static ROWS: [u32; 1usize] = [0u32];
    /// The eliminated rows.
    pub static SUBSTITUTIONS: [Substitution; 3usize] = [
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
    ];
    /// The way back to the full model.
    pub static REDUCTION: Reduction = Reduction {
        n_full: 6usize,
        m_full: 1usize,
        coords: &COORDS,
        rows: &ROWS,
        substitutions: &SUBSTITUTIONS,
        offsets: offsets_into,
        offsets_read_parameters: false,
    };
    /// `c, ċ, c̈` of each substitution at time `t`, three per substitution.
    pub fn offsets_into(t: f64, out: &mut [f64]) {
        let out: &mut [f64; 9] = out.try_into().expect("out must have 9 entries");
        let _ = t;
        offsets_into_part_0(out);
    }
    #[inline(never)]
    fn offsets_into_part_0(out: &mut [f64; 9]) {
        out[0] = 0.0;
        out[1] = 0.0;
        out[2] = 0.0;
        out[3] = 0.0;
        out[4] = 0.0;
        out[5] = 0.0;
        out[6] = 0.0;
        out[7] = 0.0;
        out[8] = 0.0;
    }
    /// Number of values `setup` computes from the run-time parameters.
    pub const N_K: usize = 5;
    /// `setup` at the file's parameter values: what the types without parameters read.
    pub static K: [f64; 5] = [-1f64, 9.81f64, -9.81f64, 1f64, 0.00004f64];
    /// The values the per-step functions read (`k`), from the run-time parameters `p`.
    pub fn setup(p: &[f64], k: &mut [f64]) {
        let p: &[f64; 8] = p.try_into().expect("p must have 8 entries");
        let k: &mut [f64; 5] = k.try_into().expect("k must have 5 entries");
        setup_part_0(p, k);
    }
    #[inline(never)]
    fn setup_part_0(p: &[f64; 8], k: &mut [f64; 5]) {
        let x42 = -p[7];
        let x90 = p[0] * 0.4;
        let x92 = x90 * 0.01;
        let x93 = 0.01 * x92;
        let x96 = p[0] * 9.81;
        let x97 = -x96;
        let x160 = 2.0 * p[0];
        let x161 = 0.5 * x160;
        let x162 = 2.0 * x93;
        let x163 = 0.5 * x162;
        k[0] = x42;
        k[1] = x96;
        k[2] = x97;
        k[3] = x161;
        k[4] = x163;
    }
    /// Constraint residual Φ(q, t).
    pub fn phi(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        let _ = t;
        phi_part_0(k, q, out);
    }
    #[inline(never)]
    fn phi_part_0(k: &[f64; 5], q: &[f64; 3], out: &mut [f64; 1]) {
        let x35 = q[0] * q[0];
        let x36 = q[1] * q[1];
        let x38 = x35 + x36;
        let x744 = x38.sqrt();
        let x766 = x744 + k[0];
        out[0] = x766;
    }
    /// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
    pub fn phi_q(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 2] = out.try_into().expect("out must have 2 entries");
        let _ = k;
        let _ = t;
        phi_q_part_0(q, out);
    }
    #[inline(never)]
    fn phi_q_part_0(q: &[f64; 3], out: &mut [f64; 2]) {
        let x35 = q[0] * q[0];
        let x36 = q[1] * q[1];
        let x38 = x35 + x36;
        let x45 = q[0] * 2.0;
        let x46 = q[1] * 2.0;
        let x744 = x38.sqrt();
        let x746 = 2.0 * x744;
        let x747 = 1.0 / x746;
        let x748 = x45 * x747;
        let x749 = x46 * x747;
        out[0] = x748;
        out[1] = x749;
    }
    /// Partial time derivative Φt(q, t).
    pub fn phi_t(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        let _ = k;
        let _ = q;
        let _ = t;
        phi_t_part_0(out);
    }
    #[inline(never)]
    fn phi_t_part_0(out: &mut [f64; 1]) {
        out[0] = 0.0;
    }
    /// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
    pub fn gamma(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        let _ = k;
        let _ = t;
        gamma_part_0(q, qd, out);
    }
    #[inline(never)]
    fn gamma_part_0(q: &[f64; 3], qd: &[f64; 3], out: &mut [f64; 1]) {
        let x35 = q[0] * q[0];
        let x36 = q[1] * q[1];
        let x38 = x35 + x36;
        let x45 = q[0] * 2.0;
        let x46 = q[1] * 2.0;
        let x59 = x45 * qd[0];
        let x60 = x46 * qd[1];
        let x62 = x59 + x60;
        let x65 = 2.0 * qd[0];
        let x66 = 2.0 * qd[1];
        let x72 = qd[0] * x65;
        let x73 = qd[1] * x66;
        let x75 = x72 + x73;
        let x744 = x38.sqrt();
        let x746 = 2.0 * x744;
        let x747 = 1.0 / x746;
        let x750 = x62 * x747;
        let x751 = 2.0 * x750;
        let x752 = x747 * x747;
        let x753 = x751 * x752;
        let x755 = x75 * x747;
        let x756 = x62 * x753;
        let x758 = x755 - x756;
        let x759 = -x758;
        out[0] = x759;
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
        let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 1] = phi.try_into().expect("phi must have 1 entries");
        let phi_q: &mut [f64; 2] = phi_q.try_into().expect("phi_q must have 2 entries");
        let phi_t: &mut [f64; 1] = phi_t.try_into().expect("phi_t must have 1 entries");
        let gamma: &mut [f64; 1] = gamma.try_into().expect("gamma must have 1 entries");
        let _ = t;
        eval_kinematics_part_0(k, q, qd, phi, phi_q, phi_t, gamma);
    }
    #[inline(never)]
    fn eval_kinematics_part_0(
        k: &[f64; 5],
        q: &[f64; 3],
        qd: &[f64; 3],
        phi: &mut [f64; 1],
        phi_q: &mut [f64; 2],
        phi_t: &mut [f64; 1],
        gamma: &mut [f64; 1],
    ) {
        let x35 = q[0] * q[0];
        let x36 = q[1] * q[1];
        let x38 = x35 + x36;
        let x45 = q[0] * 2.0;
        let x46 = q[1] * 2.0;
        let x59 = x45 * qd[0];
        let x60 = x46 * qd[1];
        let x62 = x59 + x60;
        let x65 = 2.0 * qd[0];
        let x66 = 2.0 * qd[1];
        let x72 = qd[0] * x65;
        let x73 = qd[1] * x66;
        let x75 = x72 + x73;
        let x744 = x38.sqrt();
        let x746 = 2.0 * x744;
        let x747 = 1.0 / x746;
        let x748 = x45 * x747;
        let x749 = x46 * x747;
        let x750 = x62 * x747;
        let x751 = 2.0 * x750;
        let x752 = x747 * x747;
        let x753 = x751 * x752;
        let x755 = x75 * x747;
        let x756 = x62 * x753;
        let x758 = x755 - x756;
        let x759 = -x758;
        let x766 = x744 + k[0];
        phi[0] = x766;
        phi_q[0] = x748;
        phi_q[1] = x749;
        phi_t[0] = 0.0;
        gamma[0] = x759;
    }
    /// Potential energy of gravity and springs, written to `out[0]`.
    pub fn potential_into(k: &[f64], q: &[f64], out: &mut [f64]) {
        let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        potential_into_part_0(k, q, out);
    }
    #[inline(never)]
    fn potential_into_part_0(k: &[f64; 5], q: &[f64; 3], out: &mut [f64; 1]) {
        let x763 = q[1] * k[1];
        out[0] = x763;
    }
    /// Power of the non-conservative loads, written to `out[0]`.
    pub fn power_nc_into(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
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
        pub static MASS_ROWS: [u32; 3usize] = [0u32, 1u32, 2u32];
        /// Column of each mass-matrix nonzero.
        pub static MASS_COLS: [u32; 3usize] = [0u32, 1u32, 2u32];
        /// Row and column of each ∂Q/∂q nonzero.
        pub static FORCE_Q_ROWS: [u32; 0usize] = [];
        pub static FORCE_Q_COLS: [u32; 0usize] = [];
        /// Row and column of each ∂Q/∂q̇ nonzero.
        pub static FORCE_QD_ROWS: [u32; 0usize] = [];
        pub static FORCE_QD_COLS: [u32; 0usize] = [];
        /// Sizes, patterns and names for this formulation.
        pub static INFO: MechanismInfo = MechanismInfo {
            name: "simple_pendulum_reduced",
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
            kkt: &KKT,
        };
        use symbody_runtime::kkt::{
            length_error, mass_pivot_error, KktError, KktKernels, Pivoting,
        };
        /// The KKT factor and solve for this model's patterns, straight-line (`KktKernels`).
        pub static KKT: [KktKernels; 1] = [
            KktKernels {
                pattern: 0x9d1f4754d61f1286,
                storage: 6,
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
            let mass: &[f64; 3] = mass
                .try_into()
                .map_err(|_| length_error(3, mass.len()))?;
            let phi_q: &[f64; 2] = phi_q
                .try_into()
                .map_err(|_| length_error(2, phi_q.len()))?;
            let st_len = st.len();
            let st: &mut [f64; 6] = st.try_into().map_err(|_| length_error(6, st_len))?;
            if !((c * mass[0]) > 0.0 && (c * mass[0]) <= f64::MAX) {
                return Err(mass_pivot_error((c * mass[0]), 0));
            }
            let v0: f64 = (c * mass[0]).sqrt();
            let v1: f64 = 1.0 / v0;
            st[0] = v1;
            if !((c * mass[1]) > 0.0 && (c * mass[1]) <= f64::MAX) {
                return Err(mass_pivot_error((c * mass[1]), 1));
            }
            let v2: f64 = (c * mass[1]).sqrt();
            let v3: f64 = 1.0 / v2;
            st[1] = v3;
            if !((c * mass[2]) > 0.0 && (c * mass[2]) <= f64::MAX) {
                return Err(mass_pivot_error((c * mass[2]), 2));
            }
            let v4: f64 = (c * mass[2]).sqrt();
            let v5: f64 = 1.0 / v4;
            st[2] = v5;
            let v6: f64 = phi_q[0] * v1;
            st[3] = v6;
            let v7: f64 = phi_q[1] * v3;
            st[4] = v7;
            let v8: f64 = v6 * v6;
            let v9: f64 = v7 * v7;
            let v10: f64 = v8 + v9;
            let (v11, v12) = piv.pivot(v10, v10, 0, false)?;
            st[5] = v11;
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
            let f: &[f64; 3] = f.try_into().map_err(|_| length_error(3, f.len()))?;
            let g: &[f64; 1] = g.try_into().map_err(|_| length_error(1, g.len()))?;
            let x_len = x.len();
            let x: &mut [f64; 3] = x.try_into().map_err(|_| length_error(3, x_len))?;
            let y_len = y.len();
            let y: &mut [f64; 1] = y.try_into().map_err(|_| length_error(1, y_len))?;
            let st: &[f64; 6] = st.try_into().map_err(|_| length_error(6, st.len()))?;
            x.fill(0.0);
            y[0] = -g[0];
            if f.iter().any(|&v| v != 0.0) {
                let v0: f64 = f[0];
                let v1: f64 = f[1];
                let v2: f64 = f[2];
                let v3: f64 = v0 * st[0];
                let v4: f64 = v1 * st[1];
                let v5: f64 = v2 * st[2];
                let v6: f64 = st[3] * v3;
                let v7: f64 = st[4] * v4;
                let v8: f64 = v6 + v7;
                y[0] += v8;
                x[0] = v3;
                x[1] = v4;
                x[2] = v5;
            }
            let v9: f64 = y[0] * st[5];
            y[0] = v9;
            let v10: f64 = x[0] - st[3] * v9;
            let v11: f64 = x[1] - st[4] * v9;
            let v12: f64 = x[2] * st[2];
            let v13: f64 = v11 * st[1];
            let v14: f64 = v10 * st[0];
            x[0] = v14;
            x[1] = v13;
            x[2] = v12;
            Ok(())
        }
        fn kkt_transpose_times(
            phi_q: &[f64],
            y: &[f64],
            out: &mut [f64],
        ) -> Result<(), KktError> {
            let phi_q: &[f64; 2] = phi_q
                .try_into()
                .map_err(|_| length_error(2, phi_q.len()))?;
            let y: &[f64; 1] = y.try_into().map_err(|_| length_error(1, y.len()))?;
            let out_len = out.len();
            let out: &mut [f64; 3] = out
                .try_into()
                .map_err(|_| length_error(3, out_len))?;
            out[0] = phi_q[0] * y[0];
            out[1] = phi_q[1] * y[0];
            out[2] = 0.0;
            Ok(())
        }
        #[allow(clippy::assign_op_pattern)]
        fn kkt_times_add(
            phi_q: &[f64],
            x: &[f64],
            out: &mut [f64],
        ) -> Result<(), KktError> {
            let phi_q: &[f64; 2] = phi_q
                .try_into()
                .map_err(|_| length_error(2, phi_q.len()))?;
            let x: &[f64; 3] = x.try_into().map_err(|_| length_error(3, x.len()))?;
            let out_len = out.len();
            let out: &mut [f64; 1] = out
                .try_into()
                .map_err(|_| length_error(1, out_len))?;
            out[0] = out[0] + phi_q[0] * x[0] + phi_q[1] * x[1];
            Ok(())
        }
        fn kkt_mass_times(
            mass: &[f64],
            v: &[f64],
            out: &mut [f64],
        ) -> Result<(), KktError> {
            let mass: &[f64; 3] = mass
                .try_into()
                .map_err(|_| length_error(3, mass.len()))?;
            let v: &[f64; 3] = v.try_into().map_err(|_| length_error(3, v.len()))?;
            let out_len = out.len();
            let out: &mut [f64; 3] = out
                .try_into()
                .map_err(|_| length_error(3, out_len))?;
            out[0] = 0.0 + mass[0] * v[0];
            out[1] = 0.0 + mass[1] * v[1];
            out[2] = 0.0 + mass[2] * v[2];
            Ok(())
        }
        fn kkt_kinetic_energy(mass: &[f64], qd: &[f64]) -> Result<f64, KktError> {
            let mass: &[f64; 3] = mass
                .try_into()
                .map_err(|_| length_error(3, mass.len()))?;
            let qd: &[f64; 3] = qd.try_into().map_err(|_| length_error(3, qd.len()))?;
            let mut t = 0.0;
            t += qd[0] * mass[0] * qd[0];
            t += qd[1] * mass[1] * qd[1];
            t += qd[2] * mass[2] * qd[2];
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
            let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
            let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
            let _: &mut [f64; 0] = dq.try_into().expect("dq must have 0 entries");
            let _: &mut [f64; 0] = dqd.try_into().expect("dqd must have 0 entries");
            let _ = k;
            let _ = q;
            let _ = qd;
            let _ = t;
        }
        /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
        pub fn mass(k: &[f64], q: &[f64], out: &mut [f64]) {
            let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
            let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
            let out: &mut [f64; 3] = out.try_into().expect("out must have 3 entries");
            let _ = q;
            mass_part_0(k, out);
        }
        #[inline(never)]
        fn mass_part_0(k: &[f64; 5], out: &mut [f64; 3]) {
            out[0] = k[3];
            out[1] = k[3];
            out[2] = k[4];
        }
        /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
        pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
            let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
            let out: &mut [f64; 3] = out.try_into().expect("out must have 3 entries");
            let _ = q;
            let _ = qd;
            let _ = t;
            force_part_0(k, out);
        }
        #[inline(never)]
        fn force_part_0(k: &[f64; 5], out: &mut [f64; 3]) {
            out[0] = 0.0;
            out[1] = k[2];
            out[2] = 0.0;
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
            let k: &[f64; 5] = k.try_into().expect("k must have 5 entries");
            let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
            let phi: &mut [f64; 1] = phi.try_into().expect("phi must have 1 entries");
            let phi_q: &mut [f64; 2] = phi_q
                .try_into()
                .expect("phi_q must have 2 entries");
            let mass: &mut [f64; 3] = mass.try_into().expect("mass must have 3 entries");
            let force: &mut [f64; 3] = force
                .try_into()
                .expect("force must have 3 entries");
            let _ = qd;
            let _ = t;
            eval_newton_part_0(k, q, phi, phi_q, mass, force);
        }
        #[inline(never)]
        fn eval_newton_part_0(
            k: &[f64; 5],
            q: &[f64; 3],
            phi: &mut [f64; 1],
            phi_q: &mut [f64; 2],
            mass: &mut [f64; 3],
            force: &mut [f64; 3],
        ) {
            let x35 = q[0] * q[0];
            let x36 = q[1] * q[1];
            let x38 = x35 + x36;
            let x45 = q[0] * 2.0;
            let x46 = q[1] * 2.0;
            let x744 = x38.sqrt();
            let x746 = 2.0 * x744;
            let x747 = 1.0 / x746;
            let x748 = x45 * x747;
            let x749 = x46 * x747;
            let x766 = x744 + k[0];
            phi[0] = x766;
            phi_q[0] = x748;
            phi_q[1] = x749;
            mass[0] = k[3];
            mass[1] = k[3];
            mass[2] = k[4];
            force[0] = 0.0;
            force[1] = k[2];
            force[2] = 0.0;
        }
    }
    /// `simple_pendulum` reduced by substitution, with the `exact` formulation.
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
/// `simple_pendulum` with the `exact` formulation.
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
/// `simple_pendulum` with the `exact` formulation. At run-time parameter values (`Exact::with_parameters`).
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
    name: "simple_pendulum",
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
            env!("CARGO_MANIFEST_DIR"), "/../../../", "mechanisms/simple_pendulum.toml"
        ),
        hash: 11379041075575716480u64,
        parameters: &[],
    },
    run_time: Some(&RUN_TIME_ENTRY),
};
