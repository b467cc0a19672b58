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
    BodyInfo, Entry, Formulation, JointInfo, JointKind, KinematicOutputs, Mechanism,
    MechanismInfo, NewtonOutputs, Origin, PlatformInfo, Reduction, Substitution, Rotation,
};
/// Constraint residual Φ(q, t).
pub fn phi(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = t;
    phi_part_0(q, out);
}
#[inline(never)]
fn phi_part_0(q: &[f64; 6], out: &mut [f64; 1]) {
    let x35 = q[0] * q[0];
    let x36 = q[1] * q[1];
    let x37 = q[2] * q[2];
    let x38 = x35 + x36;
    let x39 = x37 + x38;
    let x40 = x39.sqrt();
    let x42 = x40 - 1.0;
    out[0] = x42;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 3] = out.try_into().expect("out must have 3 entries");
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
    let x44 = q[0] * 2.0;
    let x45 = q[1] * 2.0;
    let x46 = q[2] * 2.0;
    let x47 = x40 * 2.0;
    let x48 = 1.0 / x47;
    let x49 = x44 * x48;
    let x50 = x45 * x48;
    let x51 = x46 * x48;
    out[0] = x49;
    out[1] = x50;
    out[2] = x51;
}
/// Partial time derivative Φt(q, t).
pub fn phi_t(q: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    let _ = q;
    let _ = t;
    phi_t_part_0(out);
}
#[inline(never)]
fn phi_t_part_0(out: &mut [f64; 1]) {
    out[0] = 0.0;
}
/// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
pub fn gamma(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
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
    let x44 = q[0] * 2.0;
    let x45 = q[1] * 2.0;
    let x46 = q[2] * 2.0;
    let x47 = x40 * 2.0;
    let x48 = 1.0 / x47;
    let x58 = x44 * qd[0];
    let x59 = x45 * qd[1];
    let x60 = x46 * qd[2];
    let x61 = x58 + x59;
    let x62 = x60 + x61;
    let x63 = x48 * x62;
    let x64 = 2.0 * qd[0];
    let x65 = 2.0 * qd[1];
    let x66 = 2.0 * qd[2];
    let x67 = 2.0 * x63;
    let x68 = x48 * x48;
    let x69 = x67 * x68;
    let x71 = qd[0] * x64;
    let x72 = qd[1] * x65;
    let x73 = qd[2] * x66;
    let x74 = x71 + x72;
    let x75 = x73 + x74;
    let x76 = x62 * x69;
    let x78 = x48 * x75;
    let x79 = x78 - x76;
    let x80 = -x79;
    out[0] = x80;
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
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
    let phi: &mut [f64; 1] = phi.try_into().expect("phi must have 1 entries");
    let phi_q: &mut [f64; 3] = phi_q.try_into().expect("phi_q must have 3 entries");
    let phi_t: &mut [f64; 1] = phi_t.try_into().expect("phi_t must have 1 entries");
    let gamma: &mut [f64; 1] = gamma.try_into().expect("gamma must have 1 entries");
    let _ = t;
    eval_kinematics_part_0(q, qd, phi, phi_q, phi_t, gamma);
}
#[inline(never)]
fn eval_kinematics_part_0(
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
    let x42 = x40 - 1.0;
    let x44 = q[0] * 2.0;
    let x45 = q[1] * 2.0;
    let x46 = q[2] * 2.0;
    let x47 = x40 * 2.0;
    let x48 = 1.0 / x47;
    let x49 = x44 * x48;
    let x50 = x45 * x48;
    let x51 = x46 * x48;
    let x58 = x44 * qd[0];
    let x59 = x45 * qd[1];
    let x60 = x46 * qd[2];
    let x61 = x58 + x59;
    let x62 = x60 + x61;
    let x63 = x48 * x62;
    let x64 = 2.0 * qd[0];
    let x65 = 2.0 * qd[1];
    let x66 = 2.0 * qd[2];
    let x67 = 2.0 * x63;
    let x68 = x48 * x48;
    let x69 = x67 * x68;
    let x71 = qd[0] * x64;
    let x72 = qd[1] * x65;
    let x73 = qd[2] * x66;
    let x74 = x71 + x72;
    let x75 = x73 + x74;
    let x76 = x62 * x69;
    let x78 = x48 * x75;
    let x79 = x78 - x76;
    let x80 = -x79;
    phi[0] = x42;
    phi_q[0] = x49;
    phi_q[1] = x50;
    phi_q[2] = x51;
    phi_t[0] = 0.0;
    gamma[0] = x80;
}
/// Potential energy of gravity and springs, written to `out[0]`.
pub fn potential_into(q: &[f64], out: &mut [f64]) {
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
    potential_into_part_0(q, out);
}
#[inline(never)]
fn potential_into_part_0(q: &[f64; 6], out: &mut [f64; 1]) {
    let x82 = q[1] * 9.81;
    out[0] = x82;
}
/// Power of the non-conservative loads, written to `out[0]`.
pub fn power_nc_into(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
    let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
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
    };
    /// Nonzeros of ∂Q/∂q and ∂Q/∂q̇ in the order of `FORCE_Q_*` and `FORCE_QD_*`.
    pub fn force_jacobian(
        q: &[f64],
        qd: &[f64],
        t: f64,
        dq: &mut [f64],
        dqd: &mut [f64],
    ) {
        let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
        let _: &mut [f64; 0] = dq.try_into().expect("dq must have 0 entries");
        let _: &mut [f64; 0] = dqd.try_into().expect("dqd must have 0 entries");
        let _ = q;
        let _ = qd;
        let _ = t;
    }
    /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
    pub fn mass(q: &[f64], out: &mut [f64]) {
        let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 10] = out.try_into().expect("out must have 10 entries");
        mass_part_0(q, out);
    }
    #[inline(never)]
    fn mass_part_0(q: &[f64; 6], out: &mut [f64; 10]) {
        let x6 = q[3].sin();
        let x7 = q[3].cos();
        let x8 = q[4].sin();
        let x9 = q[4].cos();
        let x16 = x6 * x9;
        let x17 = x7 * x9;
        let x140 = x8 * 2.0;
        let x142 = 0.00004 * x140;
        let x144 = 0.5 * x142;
        let x145 = -x144;
        let x146 = x7 * 2.0;
        let x147 = x6 * 2.0;
        let x149 = x7 * x146;
        let x150 = 0.00004 * x149;
        let x151 = x6 * x147;
        let x153 = 0.00004 * x151;
        let x155 = x150 + x153;
        let x156 = 0.5 * x155;
        let x157 = x16 * 2.0;
        let x158 = x17 * 2.0;
        let x159 = x7 * x157;
        let x160 = 0.00004 * x159;
        let x161 = x6 * x158;
        let x162 = 0.00004 * x161;
        let x164 = x160 - x162;
        let x165 = 0.5 * x164;
        let x166 = x16 * x146;
        let x167 = 0.00004 * x166;
        let x168 = x17 * x147;
        let x170 = 0.00004 * x168;
        let x172 = x167 - x170;
        let x173 = 0.5 * x172;
        let x174 = x8 * x140;
        let x176 = 0.00004 * x174;
        let x178 = x16 * x157;
        let x179 = 0.00004 * x178;
        let x180 = x17 * x158;
        let x181 = 0.00004 * x180;
        let x182 = x176 + x179;
        let x183 = x181 + x182;
        let x184 = 0.5 * x183;
        out[0] = 1.0;
        out[1] = 1.0;
        out[2] = 1.0;
        out[3] = 0.00004;
        out[4] = x145;
        out[5] = x156;
        out[6] = x165;
        out[7] = x145;
        out[8] = x173;
        out[9] = x184;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 6] = out.try_into().expect("out must have 6 entries");
        let _ = t;
        force_part_0(q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(q: &[f64; 6], qd: &[f64; 6], out: &mut [f64; 6]) {
        let x6 = q[3].sin();
        let x7 = q[3].cos();
        let x8 = q[4].sin();
        let x9 = q[4].cos();
        let x16 = x6 * x9;
        let x17 = x7 * x9;
        let x84 = x8 * qd[5];
        let x86 = x9 * qd[5];
        let x87 = x7 * qd[4];
        let x88 = x6 * x86;
        let x89 = x87 + x88;
        let x90 = x6 * qd[4];
        let x91 = x7 * x86;
        let x93 = x91 - x90;
        let x94 = qd[3] - x84;
        let x111 = 2.0 * x94;
        let x112 = 2.0 * x89;
        let x113 = 2.0 * x93;
        let x185 = x7 * qd[3];
        let x186 = x6 * qd[3];
        let x188 = x9 * qd[4];
        let x189 = x8 * qd[4];
        let x191 = x9 * x185;
        let x192 = x6 * x189;
        let x194 = x191 - x192;
        let x195 = x9 * x186;
        let x197 = x7 * x189;
        let x199 = x195 + x197;
        let x201 = qd[5] * x188;
        let x203 = qd[5] * x189;
        let x205 = qd[4] * x186;
        let x207 = x86 * x185;
        let x208 = x6 * x203;
        let x210 = x207 - x208;
        let x211 = x210 - x205;
        let x212 = qd[4] * x185;
        let x213 = x86 * x186;
        let x215 = x7 * x203;
        let x217 = x213 + x215;
        let x220 = x212 + x217;
        let x222 = 2.0 * x201;
        let x224 = 2.0 * x211;
        let x225 = 2.0 * x220;
        let x227 = 0.00004 * x222;
        let x229 = 0.5 * x227;
        let x231 = x112 * x186;
        let x233 = x7 * x224;
        let x234 = x233 - x231;
        let x235 = 0.00004 * x234;
        let x236 = x113 * x185;
        let x237 = x6 * x225;
        let x239 = x236 - x237;
        let x240 = 0.00004 * x239;
        let x242 = x235 - x240;
        let x243 = 0.5 * x242;
        let x244 = x111 * x188;
        let x245 = x8 * x222;
        let x247 = x244 - x245;
        let x248 = 0.00004 * x247;
        let x250 = x112 * x194;
        let x251 = x16 * x224;
        let x252 = x250 + x251;
        let x253 = 0.00004 * x252;
        let x254 = x113 * x199;
        let x256 = x17 * x225;
        let x258 = x254 + x256;
        let x260 = 0.00004 * x258;
        let x262 = x253 - x248;
        let x263 = x262 - x260;
        let x264 = 0.5 * x263;
        let x269 = x93 * x112;
        let x270 = 0.00004 * x269;
        let x271 = x89 * x113;
        let x273 = 0.00004 * x271;
        let x275 = x270 - x273;
        let x276 = 0.5 * x275;
        let x277 = x229 + x276;
        let x279 = x6 * x84;
        let x281 = x7 * x84;
        let x283 = x86 * x111;
        let x285 = 0.00004 * x283;
        let x287 = x112 * x279;
        let x289 = 0.00004 * x287;
        let x291 = x113 * x281;
        let x293 = 0.00004 * x291;
        let x295 = x285 + x289;
        let x297 = x293 + x295;
        let x299 = 0.5 * x297;
        let x302 = x243 + x299;
        let x303 = -x302;
        let x304 = -x264;
        out[0] = 0.0;
        out[1] = -9.81;
        out[2] = 0.0;
        out[3] = x277;
        out[4] = x303;
        out[5] = x304;
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
        let q: &[f64; 6] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 6] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 1] = phi.try_into().expect("phi must have 1 entries");
        let phi_q: &mut [f64; 3] = phi_q.try_into().expect("phi_q must have 3 entries");
        let mass: &mut [f64; 10] = mass.try_into().expect("mass must have 10 entries");
        let force: &mut [f64; 6] = force.try_into().expect("force must have 6 entries");
        let _ = t;
        eval_newton_part_0(q, qd, phi, phi_q, mass, force);
    }
    #[inline(never)]
    fn eval_newton_part_0(
        q: &[f64; 6],
        qd: &[f64; 6],
        phi: &mut [f64; 1],
        phi_q: &mut [f64; 3],
        mass: &mut [f64; 10],
        force: &mut [f64; 6],
    ) {
        let x6 = q[3].sin();
        let x7 = q[3].cos();
        let x8 = q[4].sin();
        let x9 = q[4].cos();
        let x16 = x6 * x9;
        let x17 = x7 * x9;
        let x35 = q[0] * q[0];
        let x36 = q[1] * q[1];
        let x37 = q[2] * q[2];
        let x38 = x35 + x36;
        let x39 = x37 + x38;
        let x40 = x39.sqrt();
        let x42 = x40 - 1.0;
        let x44 = q[0] * 2.0;
        let x45 = q[1] * 2.0;
        let x46 = q[2] * 2.0;
        let x47 = x40 * 2.0;
        let x48 = 1.0 / x47;
        let x49 = x44 * x48;
        let x50 = x45 * x48;
        let x51 = x46 * x48;
        let x84 = x8 * qd[5];
        let x86 = x9 * qd[5];
        let x87 = x7 * qd[4];
        let x88 = x6 * x86;
        let x89 = x87 + x88;
        let x90 = x6 * qd[4];
        let x91 = x7 * x86;
        let x93 = x91 - x90;
        let x94 = qd[3] - x84;
        let x111 = 2.0 * x94;
        let x112 = 2.0 * x89;
        let x113 = 2.0 * x93;
        let x140 = x8 * 2.0;
        let x142 = 0.00004 * x140;
        let x144 = 0.5 * x142;
        let x145 = -x144;
        let x146 = x7 * 2.0;
        let x147 = x6 * 2.0;
        let x149 = x7 * x146;
        let x150 = 0.00004 * x149;
        let x151 = x6 * x147;
        let x153 = 0.00004 * x151;
        let x155 = x150 + x153;
        let x156 = 0.5 * x155;
        let x157 = x16 * 2.0;
        let x158 = x17 * 2.0;
        let x159 = x7 * x157;
        let x160 = 0.00004 * x159;
        let x161 = x6 * x158;
        let x162 = 0.00004 * x161;
        let x164 = x160 - x162;
        let x165 = 0.5 * x164;
        let x166 = x16 * x146;
        let x167 = 0.00004 * x166;
        let x168 = x17 * x147;
        let x170 = 0.00004 * x168;
        let x172 = x167 - x170;
        let x173 = 0.5 * x172;
        let x174 = x8 * x140;
        let x176 = 0.00004 * x174;
        let x178 = x16 * x157;
        let x179 = 0.00004 * x178;
        let x180 = x17 * x158;
        let x181 = 0.00004 * x180;
        let x182 = x176 + x179;
        let x183 = x181 + x182;
        let x184 = 0.5 * x183;
        let x185 = x7 * qd[3];
        let x186 = x6 * qd[3];
        let x188 = x9 * qd[4];
        let x189 = x8 * qd[4];
        let x191 = x9 * x185;
        let x192 = x6 * x189;
        let x194 = x191 - x192;
        let x195 = x9 * x186;
        let x197 = x7 * x189;
        let x199 = x195 + x197;
        let x201 = qd[5] * x188;
        let x203 = qd[5] * x189;
        let x205 = qd[4] * x186;
        let x207 = x86 * x185;
        let x208 = x6 * x203;
        let x210 = x207 - x208;
        let x211 = x210 - x205;
        let x212 = qd[4] * x185;
        let x213 = x86 * x186;
        let x215 = x7 * x203;
        let x217 = x213 + x215;
        let x220 = x212 + x217;
        let x222 = 2.0 * x201;
        let x224 = 2.0 * x211;
        let x225 = 2.0 * x220;
        let x227 = 0.00004 * x222;
        let x229 = 0.5 * x227;
        let x231 = x112 * x186;
        let x233 = x7 * x224;
        let x234 = x233 - x231;
        let x235 = 0.00004 * x234;
        let x236 = x113 * x185;
        let x237 = x6 * x225;
        let x239 = x236 - x237;
        let x240 = 0.00004 * x239;
        let x242 = x235 - x240;
        let x243 = 0.5 * x242;
        let x244 = x111 * x188;
        let x245 = x8 * x222;
        let x247 = x244 - x245;
        let x248 = 0.00004 * x247;
        let x250 = x112 * x194;
        let x251 = x16 * x224;
        let x252 = x250 + x251;
        let x253 = 0.00004 * x252;
        let x254 = x113 * x199;
        let x256 = x17 * x225;
        let x258 = x254 + x256;
        let x260 = 0.00004 * x258;
        let x262 = x253 - x248;
        let x263 = x262 - x260;
        let x264 = 0.5 * x263;
        let x269 = x93 * x112;
        let x270 = 0.00004 * x269;
        let x271 = x89 * x113;
        let x273 = 0.00004 * x271;
        let x275 = x270 - x273;
        let x276 = 0.5 * x275;
        let x277 = x229 + x276;
        let x279 = x6 * x84;
        let x281 = x7 * x84;
        let x283 = x86 * x111;
        let x285 = 0.00004 * x283;
        let x287 = x112 * x279;
        let x289 = 0.00004 * x287;
        let x291 = x113 * x281;
        let x293 = 0.00004 * x291;
        let x295 = x285 + x289;
        let x297 = x293 + x295;
        let x299 = 0.5 * x297;
        let x302 = x243 + x299;
        let x303 = -x302;
        let x304 = -x264;
        phi[0] = x42;
        phi_q[0] = x49;
        phi_q[1] = x50;
        phi_q[2] = x51;
        mass[0] = 1.0;
        mass[1] = 1.0;
        mass[2] = 1.0;
        mass[3] = 0.00004;
        mass[4] = x145;
        mass[5] = x156;
        mass[6] = x165;
        mass[7] = x145;
        mass[8] = x173;
        mass[9] = x184;
        force[0] = 0.0;
        force[1] = -9.81;
        force[2] = 0.0;
        force[3] = x277;
        force[4] = x303;
        force[5] = x304;
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
    /// Constraint residual Φ(q, t).
    pub fn phi(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        let _ = t;
        phi_part_0(q, out);
    }
    #[inline(never)]
    fn phi_part_0(q: &[f64; 3], out: &mut [f64; 1]) {
        let x35 = q[0] * q[0];
        let x36 = q[1] * q[1];
        let x38 = x35 + x36;
        let x305 = x38.sqrt();
        let x306 = x305 - 1.0;
        out[0] = x306;
    }
    /// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
    pub fn phi_q(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 2] = out.try_into().expect("out must have 2 entries");
        let _ = t;
        phi_q_part_0(q, out);
    }
    #[inline(never)]
    fn phi_q_part_0(q: &[f64; 3], out: &mut [f64; 2]) {
        let x35 = q[0] * q[0];
        let x36 = q[1] * q[1];
        let x38 = x35 + x36;
        let x44 = q[0] * 2.0;
        let x45 = q[1] * 2.0;
        let x305 = x38.sqrt();
        let x307 = 2.0 * x305;
        let x308 = 1.0 / x307;
        let x309 = x44 * x308;
        let x310 = x45 * x308;
        out[0] = x309;
        out[1] = x310;
    }
    /// Partial time derivative Φt(q, t).
    pub fn phi_t(q: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        let _ = q;
        let _ = t;
        phi_t_part_0(out);
    }
    #[inline(never)]
    fn phi_t_part_0(out: &mut [f64; 1]) {
        out[0] = 0.0;
    }
    /// Acceleration right-hand side γ(q, q̇, t) = −D²Φ[(q̇,1),(q̇,1)].
    pub fn gamma(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        let _ = t;
        gamma_part_0(q, qd, out);
    }
    #[inline(never)]
    fn gamma_part_0(q: &[f64; 3], qd: &[f64; 3], out: &mut [f64; 1]) {
        let x35 = q[0] * q[0];
        let x36 = q[1] * q[1];
        let x38 = x35 + x36;
        let x44 = q[0] * 2.0;
        let x45 = q[1] * 2.0;
        let x58 = x44 * qd[0];
        let x59 = x45 * qd[1];
        let x61 = x58 + x59;
        let x64 = 2.0 * qd[0];
        let x65 = 2.0 * qd[1];
        let x71 = qd[0] * x64;
        let x72 = qd[1] * x65;
        let x74 = x71 + x72;
        let x305 = x38.sqrt();
        let x307 = 2.0 * x305;
        let x308 = 1.0 / x307;
        let x311 = x61 * x308;
        let x312 = 2.0 * x311;
        let x313 = x308 * x308;
        let x314 = x312 * x313;
        let x316 = x74 * x308;
        let x317 = x61 * x314;
        let x319 = x316 - x317;
        let x320 = -x319;
        out[0] = x320;
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
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
        let phi: &mut [f64; 1] = phi.try_into().expect("phi must have 1 entries");
        let phi_q: &mut [f64; 2] = phi_q.try_into().expect("phi_q must have 2 entries");
        let phi_t: &mut [f64; 1] = phi_t.try_into().expect("phi_t must have 1 entries");
        let gamma: &mut [f64; 1] = gamma.try_into().expect("gamma must have 1 entries");
        let _ = t;
        eval_kinematics_part_0(q, qd, phi, phi_q, phi_t, gamma);
    }
    #[inline(never)]
    fn eval_kinematics_part_0(
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
        let x44 = q[0] * 2.0;
        let x45 = q[1] * 2.0;
        let x58 = x44 * qd[0];
        let x59 = x45 * qd[1];
        let x61 = x58 + x59;
        let x64 = 2.0 * qd[0];
        let x65 = 2.0 * qd[1];
        let x71 = qd[0] * x64;
        let x72 = qd[1] * x65;
        let x74 = x71 + x72;
        let x305 = x38.sqrt();
        let x306 = x305 - 1.0;
        let x307 = 2.0 * x305;
        let x308 = 1.0 / x307;
        let x309 = x44 * x308;
        let x310 = x45 * x308;
        let x311 = x61 * x308;
        let x312 = 2.0 * x311;
        let x313 = x308 * x308;
        let x314 = x312 * x313;
        let x316 = x74 * x308;
        let x317 = x61 * x314;
        let x319 = x316 - x317;
        let x320 = -x319;
        phi[0] = x306;
        phi_q[0] = x309;
        phi_q[1] = x310;
        phi_t[0] = 0.0;
        gamma[0] = x320;
    }
    /// Potential energy of gravity and springs, written to `out[0]`.
    pub fn potential_into(q: &[f64], out: &mut [f64]) {
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 1] = out.try_into().expect("out must have 1 entries");
        potential_into_part_0(q, out);
    }
    #[inline(never)]
    fn potential_into_part_0(q: &[f64; 3], out: &mut [f64; 1]) {
        let x82 = q[1] * 9.81;
        out[0] = x82;
    }
    /// Power of the non-conservative loads, written to `out[0]`.
    pub fn power_nc_into(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
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
        };
        /// Nonzeros of ∂Q/∂q and ∂Q/∂q̇ in the order of `FORCE_Q_*` and `FORCE_QD_*`.
        pub fn force_jacobian(
            q: &[f64],
            qd: &[f64],
            t: f64,
            dq: &mut [f64],
            dqd: &mut [f64],
        ) {
            let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
            let _: &mut [f64; 0] = dq.try_into().expect("dq must have 0 entries");
            let _: &mut [f64; 0] = dqd.try_into().expect("dqd must have 0 entries");
            let _ = q;
            let _ = qd;
            let _ = t;
        }
        /// Nonzeros of M(q) in the order of `MASS_ROWS`/`MASS_COLS`.
        pub fn mass(q: &[f64], out: &mut [f64]) {
            let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
            let out: &mut [f64; 3] = out.try_into().expect("out must have 3 entries");
            let _ = q;
            mass_part_0(out);
        }
        #[inline(never)]
        fn mass_part_0(out: &mut [f64; 3]) {
            out[0] = 1.0;
            out[1] = 1.0;
            out[2] = 0.00004;
        }
        /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
        pub fn force(q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
            let q: &[f64; 3] = q.try_into().expect("q must have n_coords entries");
            let qd: &[f64; 3] = qd.try_into().expect("qd must have n_coords entries");
            let out: &mut [f64; 3] = out.try_into().expect("out must have 3 entries");
            let _ = q;
            let _ = qd;
            let _ = t;
            force_part_0(out);
        }
        #[inline(never)]
        fn force_part_0(out: &mut [f64; 3]) {
            out[0] = 0.0;
            out[1] = -9.81;
            out[2] = 0.0;
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
            eval_newton_part_0(q, phi, phi_q, mass, force);
        }
        #[inline(never)]
        fn eval_newton_part_0(
            q: &[f64; 3],
            phi: &mut [f64; 1],
            phi_q: &mut [f64; 2],
            mass: &mut [f64; 3],
            force: &mut [f64; 3],
        ) {
            let x35 = q[0] * q[0];
            let x36 = q[1] * q[1];
            let x38 = x35 + x36;
            let x44 = q[0] * 2.0;
            let x45 = q[1] * 2.0;
            let x305 = x38.sqrt();
            let x306 = x305 - 1.0;
            let x307 = 2.0 * x305;
            let x308 = 1.0 / x307;
            let x309 = x44 * x308;
            let x310 = x45 * x308;
            phi[0] = x306;
            phi_q[0] = x309;
            phi_q[1] = x310;
            mass[0] = 1.0;
            mass[1] = 1.0;
            mass[2] = 0.00004;
            force[0] = 0.0;
            force[1] = -9.81;
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
/// `simple_pendulum` with the `exact` formulation.
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
    },
};
