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
    BodyInfo, Direction, Entry, Formulation, JointInfo, JointKind, KinematicOutputs,
    Mechanism, MechanismInfo, NewtonOutputs, Origin, PlatformInfo, Reduction,
    Substitution, Rotation, TangentOutputs,
};
use symbody_runtime::parameters::{ParameterError, RunTimeParameters};
/// Constraint residual Φ(q, t).
pub fn phi(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
    phi_part_0(k, q, t, out);
}
#[inline(never)]
fn phi_part_0(k: &[f64; 23], q: &[f64; 18], t: f64, out: &mut [f64; 21]) {
    let x5 = 6.283185307179586 * t;
    let (x12, x13) = symbody_runtime::trig::sin_cos(q[3]);
    let (x14, x15) = symbody_runtime::trig::sin_cos(q[4]);
    let (x16, x17) = symbody_runtime::trig::sin_cos(q[5]);
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
    let (x45, x46) = symbody_runtime::trig::sin_cos(q[9]);
    let (x47, x48) = symbody_runtime::trig::sin_cos(q[10]);
    let (x49, x50) = symbody_runtime::trig::sin_cos(q[11]);
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
    let (x78, x79) = symbody_runtime::trig::sin_cos(q[15]);
    let (x80, x81) = symbody_runtime::trig::sin_cos(q[16]);
    let (x82, x83) = symbody_runtime::trig::sin_cos(q[17]);
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
    let (x331, x332) = symbody_runtime::trig::sin_cos(x5);
    let x333 = x118 * x331;
    let x334 = x121 * x332;
    let x336 = x333 - x334;
    let x5847 = x18 * k[0];
    let x5848 = x19 * k[0];
    let x5849 = x14 * k[0];
    let x5851 = q[0] + x5847;
    let x5852 = q[1] + x5848;
    let x5853 = q[2] - x5849;
    let x5854 = -x5851;
    let x5855 = -x5852;
    let x5856 = -x5853;
    let x5858 = x18 * k[1];
    let x5859 = x19 * k[1];
    let x5860 = x14 * k[1];
    let x5862 = q[0] + x5858;
    let x5863 = q[1] + x5859;
    let x5864 = q[2] - x5860;
    let x5866 = x51 * k[2];
    let x5867 = x52 * k[2];
    let x5868 = x47 * k[2];
    let x5870 = q[6] + x5866;
    let x5871 = q[7] + x5867;
    let x5872 = q[8] - x5868;
    let x5874 = x5862 - x5870;
    let x5876 = x5863 - x5871;
    let x5878 = x5864 - x5872;
    let x5881 = x51 * k[3];
    let x5882 = x66 * k[4];
    let x5883 = x5881 + x5882;
    let x5884 = x52 * k[3];
    let x5885 = x68 * k[4];
    let x5886 = x5884 + x5885;
    let x5887 = x47 * k[3];
    let x5889 = x55 * k[4];
    let x5890 = x5889 - x5887;
    let x5891 = q[6] + x5883;
    let x5892 = q[7] + x5886;
    let x5893 = q[8] + x5890;
    let x5896 = x51 * k[5];
    let x5897 = x66 * k[6];
    let x5898 = x5896 + x5897;
    let x5899 = x52 * k[5];
    let x5900 = x68 * k[6];
    let x5901 = x5899 + x5900;
    let x5902 = x47 * k[5];
    let x5904 = x55 * k[6];
    let x5905 = x5904 - x5902;
    let x5906 = x51 * k[6];
    let x5908 = x66 * k[5];
    let x5909 = x5908 - x5906;
    let x5910 = x52 * k[6];
    let x5912 = x68 * k[5];
    let x5913 = x5912 - x5910;
    let x5914 = x47 * k[6];
    let x5915 = x55 * k[5];
    let x5916 = x5914 + x5915;
    let x5919 = x84 * k[7];
    let x5920 = x99 * k[8];
    let x5921 = x5919 + x5920;
    let x5922 = x85 * k[7];
    let x5923 = x101 * k[8];
    let x5924 = x5922 + x5923;
    let x5925 = x80 * k[7];
    let x5927 = x88 * k[8];
    let x5928 = x5927 - x5925;
    let x5929 = q[12] + x5921;
    let x5930 = q[13] + x5924;
    let x5931 = q[14] + x5928;
    let x5933 = x5891 - x5929;
    let x5935 = x5892 - x5930;
    let x5937 = x5893 - x5931;
    let x5938 = x100 * x5898;
    let x5939 = x103 * x5901;
    let x5940 = x89 * x5905;
    let x5941 = x5938 + x5939;
    let x5942 = x5940 + x5941;
    let x5943 = x100 * x5909;
    let x5944 = x103 * x5913;
    let x5945 = x89 * x5916;
    let x5946 = x5943 + x5944;
    let x5947 = x5945 + x5946;
    let x5951 = x84 * k[10];
    let x5952 = x99 * k[11];
    let x5953 = x5951 + x5952;
    let x5954 = x85 * k[10];
    let x5955 = x101 * k[11];
    let x5956 = x5954 + x5955;
    let x5957 = x80 * k[10];
    let x5959 = x88 * k[11];
    let x5960 = x5959 - x5957;
    let x5961 = q[12] + x5953;
    let x5962 = q[13] + x5956;
    let x5963 = q[14] + x5960;
    let x5965 = k[9] - x5961;
    let x5966 = -x5962;
    let x5967 = -x5963;
    out[0] = x5854;
    out[1] = x5855;
    out[2] = x5856;
    out[3] = x34;
    out[4] = x37;
    out[5] = x5874;
    out[6] = x5876;
    out[7] = x5878;
    out[8] = x187;
    out[9] = x192;
    out[10] = x5933;
    out[11] = x5935;
    out[12] = x5937;
    out[13] = x5942;
    out[14] = x5947;
    out[15] = x5965;
    out[16] = x5966;
    out[17] = x5967;
    out[18] = x100;
    out[19] = x103;
    out[20] = x336;
}
/// Nonzeros of Φq in the order of `PHI_Q_ROWS`/`PHI_Q_COLS`.
pub fn phi_q(k: &[f64], q: &[f64], t: f64, out: &mut [f64]) {
    let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 96] = out.try_into().expect("out must have 96 entries");
    phi_q_part_0(k, q, t, out);
}
#[inline(never)]
fn phi_q_part_0(k: &[f64; 23], q: &[f64; 18], t: f64, out: &mut [f64; 96]) {
    let x5 = 6.283185307179586 * t;
    let (x12, x13) = symbody_runtime::trig::sin_cos(q[3]);
    let (x14, x15) = symbody_runtime::trig::sin_cos(q[4]);
    let (x16, x17) = symbody_runtime::trig::sin_cos(q[5]);
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
    let (x45, x46) = symbody_runtime::trig::sin_cos(q[9]);
    let (x47, x48) = symbody_runtime::trig::sin_cos(q[10]);
    let (x49, x50) = symbody_runtime::trig::sin_cos(q[11]);
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
    let (x78, x79) = symbody_runtime::trig::sin_cos(q[15]);
    let (x80, x81) = symbody_runtime::trig::sin_cos(q[16]);
    let (x82, x83) = symbody_runtime::trig::sin_cos(q[17]);
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
    let (x331, x332) = symbody_runtime::trig::sin_cos(x5);
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
    let x5847 = x18 * k[0];
    let x5848 = x19 * k[0];
    let x5858 = x18 * k[1];
    let x5859 = x19 * k[1];
    let x5866 = x51 * k[2];
    let x5867 = x52 * k[2];
    let x5881 = x51 * k[3];
    let x5882 = x66 * k[4];
    let x5883 = x5881 + x5882;
    let x5884 = x52 * k[3];
    let x5885 = x68 * k[4];
    let x5886 = x5884 + x5885;
    let x5896 = x51 * k[5];
    let x5897 = x66 * k[6];
    let x5898 = x5896 + x5897;
    let x5899 = x52 * k[5];
    let x5900 = x68 * k[6];
    let x5901 = x5899 + x5900;
    let x5902 = x47 * k[5];
    let x5904 = x55 * k[6];
    let x5905 = x5904 - x5902;
    let x5906 = x51 * k[6];
    let x5908 = x66 * k[5];
    let x5909 = x5908 - x5906;
    let x5910 = x52 * k[6];
    let x5912 = x68 * k[5];
    let x5913 = x5912 - x5910;
    let x5914 = x47 * k[6];
    let x5915 = x55 * k[5];
    let x5916 = x5914 + x5915;
    let x5919 = x84 * k[7];
    let x5920 = x99 * k[8];
    let x5921 = x5919 + x5920;
    let x5922 = x85 * k[7];
    let x5923 = x101 * k[8];
    let x5924 = x5922 + x5923;
    let x5951 = x84 * k[10];
    let x5952 = x99 * k[11];
    let x5953 = x5951 + x5952;
    let x5954 = x85 * k[10];
    let x5955 = x101 * k[11];
    let x5956 = x5954 + x5955;
    let x5968 = x20 * k[0];
    let x5969 = x21 * k[0];
    let x5970 = x15 * k[0];
    let x5971 = x20 * k[1];
    let x5972 = -x5971;
    let x5973 = x21 * k[1];
    let x5974 = -x5973;
    let x5975 = x15 * k[1];
    let x5976 = -x5975;
    let x5977 = -x5847;
    let x5978 = -x5859;
    let x5979 = x67 * k[4];
    let x5980 = x70 * k[4];
    let x5981 = x56 * k[4];
    let x5982 = x67 * k[6];
    let x5983 = x70 * k[6];
    let x5984 = x56 * k[6];
    let x5985 = x67 * k[5];
    let x5986 = x70 * k[5];
    let x5987 = x56 * k[5];
    let x5988 = x100 * x5982;
    let x5989 = x103 * x5983;
    let x5990 = x89 * x5984;
    let x5991 = x5988 + x5989;
    let x5992 = x5990 + x5991;
    let x5993 = x100 * x5985;
    let x5994 = x103 * x5986;
    let x5995 = x89 * x5987;
    let x5996 = x5993 + x5994;
    let x5997 = x5995 + x5996;
    let x5998 = x53 * k[2];
    let x5999 = x54 * k[2];
    let x6000 = x48 * k[2];
    let x6001 = x53 * k[3];
    let x6003 = x499 * k[4];
    let x6004 = x6003 - x6001;
    let x6005 = x54 * k[3];
    let x6007 = x501 * k[4];
    let x6008 = x6007 - x6005;
    let x6009 = x48 * k[3];
    let x6010 = x495 * k[4];
    let x6011 = x6009 + x6010;
    let x6012 = -x6011;
    let x6013 = x53 * k[5];
    let x6015 = x499 * k[6];
    let x6016 = x6015 - x6013;
    let x6017 = x54 * k[5];
    let x6019 = x501 * k[6];
    let x6020 = x6019 - x6017;
    let x6021 = x48 * k[5];
    let x6022 = x495 * k[6];
    let x6023 = x6021 + x6022;
    let x6024 = x53 * k[6];
    let x6025 = x499 * k[5];
    let x6026 = x6024 + x6025;
    let x6027 = x54 * k[6];
    let x6028 = x501 * k[5];
    let x6029 = x6027 + x6028;
    let x6030 = x48 * k[6];
    let x6031 = x495 * k[5];
    let x6033 = x6030 - x6031;
    let x6034 = x100 * x6016;
    let x6035 = x103 * x6020;
    let x6036 = x89 * x6023;
    let x6038 = x6034 + x6035;
    let x6039 = x6038 - x6036;
    let x6040 = x100 * x6026;
    let x6041 = x103 * x6029;
    let x6042 = x89 * x6033;
    let x6043 = x6040 + x6041;
    let x6044 = x6042 + x6043;
    let x6045 = -x5866;
    let x6046 = -x5886;
    let x6048 = x5910 - x5912;
    let x6049 = x100 * x5901;
    let x6051 = x103 * x5898;
    let x6052 = x6051 - x6049;
    let x6053 = x100 * x6048;
    let x6054 = x103 * x5909;
    let x6055 = x6053 + x6054;
    let x6056 = x100 * k[8];
    let x6057 = x103 * k[8];
    let x6058 = x89 * k[8];
    let x6059 = -x6056;
    let x6060 = -x6057;
    let x6061 = -x6058;
    let x6062 = x603 * x5898;
    let x6063 = x101 * x5901;
    let x6065 = x88 * x5905;
    let x6067 = x6062 - x6063;
    let x6068 = x6067 - x6065;
    let x6069 = x603 * x5909;
    let x6070 = x101 * x5913;
    let x6072 = x88 * x5916;
    let x6074 = x6069 - x6070;
    let x6075 = x6074 - x6072;
    let x6076 = x100 * k[11];
    let x6077 = x103 * k[11];
    let x6078 = x89 * k[11];
    let x6079 = -x6076;
    let x6080 = -x6077;
    let x6081 = -x6078;
    let x6082 = x86 * k[7];
    let x6084 = x638 * k[8];
    let x6085 = x6084 - x6082;
    let x6086 = x87 * k[7];
    let x6088 = x640 * k[8];
    let x6089 = x6088 - x6086;
    let x6090 = x81 * k[7];
    let x6091 = x634 * k[8];
    let x6092 = x6090 + x6091;
    let x6093 = -x6085;
    let x6094 = -x6089;
    let x6095 = x639 * x5898;
    let x6096 = x641 * x5901;
    let x6097 = x636 * x5905;
    let x6099 = x6095 + x6096;
    let x6100 = x6099 - x6097;
    let x6101 = x639 * x5909;
    let x6102 = x641 * x5913;
    let x6103 = x636 * x5916;
    let x6105 = x6101 + x6102;
    let x6106 = x6105 - x6103;
    let x6107 = x86 * k[10];
    let x6109 = x638 * k[11];
    let x6110 = x6109 - x6107;
    let x6111 = x87 * k[10];
    let x6113 = x640 * k[11];
    let x6114 = x6113 - x6111;
    let x6115 = x81 * k[10];
    let x6116 = x634 * k[11];
    let x6117 = x6115 + x6116;
    let x6118 = -x6110;
    let x6119 = -x6114;
    let x6120 = -x5921;
    let x6121 = x689 * x5898;
    let x6122 = x6049 + x6121;
    let x6123 = x689 * x5909;
    let x6124 = x100 * x5913;
    let x6125 = x6123 + x6124;
    let x6126 = -x5953;
    out[0] = -1.0;
    out[1] = x5968;
    out[2] = x5848;
    out[3] = -1.0;
    out[4] = x5969;
    out[5] = x5977;
    out[6] = -1.0;
    out[7] = x5970;
    out[8] = x341;
    out[9] = x373;
    out[10] = x433;
    out[11] = x120;
    out[12] = x375;
    out[13] = x34;
    out[14] = 1.0;
    out[15] = x5972;
    out[16] = x5978;
    out[17] = -1.0;
    out[18] = x5998;
    out[19] = x5867;
    out[20] = 1.0;
    out[21] = x5974;
    out[22] = x5858;
    out[23] = -1.0;
    out[24] = x5999;
    out[25] = x6045;
    out[26] = 1.0;
    out[27] = x5976;
    out[28] = -1.0;
    out[29] = x6000;
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
    out[43] = x5979;
    out[44] = x6004;
    out[45] = x6046;
    out[46] = -1.0;
    out[47] = x6059;
    out[48] = x6093;
    out[49] = x5924;
    out[50] = 1.0;
    out[51] = x5980;
    out[52] = x6008;
    out[53] = x5883;
    out[54] = -1.0;
    out[55] = x6060;
    out[56] = x6094;
    out[57] = x6120;
    out[58] = 1.0;
    out[59] = x5981;
    out[60] = x6012;
    out[61] = -1.0;
    out[62] = x6061;
    out[63] = x6092;
    out[64] = x5992;
    out[65] = x6039;
    out[66] = x6052;
    out[67] = x6068;
    out[68] = x6100;
    out[69] = x6122;
    out[70] = x5997;
    out[71] = x6044;
    out[72] = x6055;
    out[73] = x6075;
    out[74] = x6106;
    out[75] = x6125;
    out[76] = -1.0;
    out[77] = x6079;
    out[78] = x6118;
    out[79] = x5956;
    out[80] = -1.0;
    out[81] = x6080;
    out[82] = x6119;
    out[83] = x6126;
    out[84] = -1.0;
    out[85] = x6081;
    out[86] = x6117;
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
    let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let out: &mut [f64; 21] = out.try_into().expect("out must have 21 entries");
    let _ = k;
    phi_t_part_0(q, t, out);
}
#[inline(never)]
fn phi_t_part_0(q: &[f64; 18], t: f64, out: &mut [f64; 21]) {
    let x5 = 6.283185307179586 * t;
    let (x12, x13) = symbody_runtime::trig::sin_cos(q[3]);
    let (x14, x15) = symbody_runtime::trig::sin_cos(q[4]);
    let (x16, x17) = symbody_runtime::trig::sin_cos(q[5]);
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
    let (x331, x332) = symbody_runtime::trig::sin_cos(x5);
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
    let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
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
    _k: &[f64; 23],
    q: &[f64; 18],
    qd: &[f64; 18],
    _t: f64,
    s: &mut [f64; 280],
) {
    let (x12, x13) = symbody_runtime::trig::sin_cos(q[3]);
    s[0] = x12;
    s[1] = x13;
    let (x14, x15) = symbody_runtime::trig::sin_cos(q[4]);
    s[2] = x14;
    s[3] = x15;
    let (x16, x17) = symbody_runtime::trig::sin_cos(q[5]);
    s[4] = x16;
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
    let (x45, x46) = symbody_runtime::trig::sin_cos(q[9]);
    s[16] = x45;
    s[17] = x46;
    let (x47, x48) = symbody_runtime::trig::sin_cos(q[10]);
    s[18] = x47;
    s[19] = x48;
    let (x49, x50) = symbody_runtime::trig::sin_cos(q[11]);
    s[20] = x49;
    s[21] = x50;
    let x53 = x47 * x50;
    s[22] = x53;
    let x54 = x47 * x49;
    s[23] = x54;
    let (x78, x79) = symbody_runtime::trig::sin_cos(q[15]);
    s[24] = x78;
    s[25] = x79;
    let (x80, x81) = symbody_runtime::trig::sin_cos(q[16]);
    s[26] = x80;
    s[27] = x81;
    let (x82, x83) = symbody_runtime::trig::sin_cos(q[17]);
    s[28] = x82;
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
fn gamma_part_0(k: &[f64; 23], s: &[f64; 280], out: &mut [f64; 21]) {
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
    let x6148 = s[107] * k[0];
    let x6149 = -x6148;
    let x6150 = s[113] * k[0];
    let x6151 = -x6150;
    let x6152 = s[98] * k[0];
    let x6153 = s[107] * k[1];
    let x6155 = s[113] * k[1];
    let x6157 = s[98] * k[1];
    let x6158 = s[163] * k[2];
    let x6159 = s[169] * k[2];
    let x6160 = s[154] * k[2];
    let x6162 = x6158 - x6153;
    let x6163 = x6159 - x6155;
    let x6164 = x6157 - x6160;
    let x6165 = s[163] * k[3];
    let x6167 = s[212] * k[4];
    let x6168 = x6167 - x6165;
    let x6169 = s[169] * k[3];
    let x6171 = s[213] * k[4];
    let x6172 = x6171 - x6169;
    let x6173 = s[154] * k[3];
    let x6174 = s[187] * k[4];
    let x6176 = x6173 - x6174;
    let x6198 = s[225] * k[7];
    let x6200 = s[274] * k[8];
    let x6201 = x6200 - x6198;
    let x6202 = s[231] * k[7];
    let x6204 = s[275] * k[8];
    let x6205 = x6204 - x6202;
    let x6206 = s[216] * k[7];
    let x6207 = s[249] * k[8];
    let x6209 = x6206 - x6207;
    let x6211 = x6168 - x6201;
    let x6213 = x6172 - x6205;
    let x6215 = x6176 - x6209;
    let x6271 = -x6162;
    let x6272 = -x6163;
    let x6273 = -x6164;
    let x6274 = -x6211;
    let x6275 = -x6213;
    let x6276 = -x6215;
    out[0] = x6149;
    out[1] = x6151;
    out[2] = x6152;
    out[3] = x1772;
    out[4] = x1773;
    out[5] = x6271;
    out[6] = x6272;
    out[7] = x6273;
    out[8] = x1777;
    out[9] = x1778;
    out[10] = x6274;
    out[11] = x6275;
    out[12] = x6276;
}
#[inline(never)]
fn gamma_part_1(k: &[f64; 23], t: f64, s: &[f64; 280], out: &mut [f64; 21]) {
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
    let (x331, x332) = symbody_runtime::trig::sin_cos(x5);
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
    let x5896 = x51 * k[5];
    let x5897 = x66 * k[6];
    let x5898 = x5896 + x5897;
    let x5899 = x52 * k[5];
    let x5900 = x68 * k[6];
    let x5901 = x5899 + x5900;
    let x5902 = s[18] * k[5];
    let x5904 = x55 * k[6];
    let x5905 = x5904 - x5902;
    let x5906 = x51 * k[6];
    let x5908 = x66 * k[5];
    let x5909 = x5908 - x5906;
    let x5910 = x52 * k[6];
    let x5912 = x68 * k[5];
    let x5913 = x5912 - x5910;
    let x5914 = s[18] * k[6];
    let x5915 = x55 * k[5];
    let x5916 = x5914 + x5915;
    let x6127 = x810 * k[5];
    let x6129 = x865 * k[6];
    let x6130 = x6129 - x6127;
    let x6131 = x815 * k[5];
    let x6132 = x867 * k[6];
    let x6133 = x6131 + x6132;
    let x6134 = s[70] * k[5];
    let x6136 = x826 * k[6];
    let x6137 = x6136 - x6134;
    let x6138 = x810 * k[6];
    let x6139 = x865 * k[5];
    let x6140 = x6138 + x6139;
    let x6141 = x815 * k[6];
    let x6143 = x867 * k[5];
    let x6144 = x6143 - x6141;
    let x6145 = s[70] * k[6];
    let x6146 = x826 * k[5];
    let x6147 = x6145 + x6146;
    let x6177 = s[163] * k[5];
    let x6179 = s[212] * k[6];
    let x6180 = x6179 - x6177;
    let x6181 = s[169] * k[5];
    let x6183 = s[213] * k[6];
    let x6184 = x6183 - x6181;
    let x6185 = s[154] * k[5];
    let x6186 = s[187] * k[6];
    let x6188 = x6185 - x6186;
    let x6189 = s[163] * k[6];
    let x6190 = s[212] * k[5];
    let x6191 = x6189 + x6190;
    let x6192 = s[169] * k[6];
    let x6193 = s[213] * k[5];
    let x6194 = x6192 + x6193;
    let x6195 = s[154] * k[6];
    let x6196 = s[187] * k[5];
    let x6197 = x6195 + x6196;
    let x6216 = x939 * x6130;
    let x6217 = x1546 * x5898;
    let x6218 = x6216 + x6217;
    let x6219 = x100 * x6180;
    let x6220 = x6216 + x6219;
    let x6221 = x6218 + x6220;
    let x6222 = x942 * x6133;
    let x6223 = x1548 * x5901;
    let x6224 = x6222 + x6223;
    let x6225 = x103 * x6184;
    let x6226 = x6222 + x6225;
    let x6227 = x6224 + x6226;
    let x6228 = x904 * x6137;
    let x6229 = x1472 * x5905;
    let x6230 = x6228 + x6229;
    let x6233 = x89 * x6188;
    let x6234 = x6233 - x6228;
    let x6235 = x6234 - x6230;
    let x6236 = x6221 + x6227;
    let x6237 = x6235 + x6236;
    let x6238 = x939 * x6140;
    let x6239 = x1546 * x5909;
    let x6240 = x6238 + x6239;
    let x6241 = x100 * x6191;
    let x6242 = x6238 + x6241;
    let x6243 = x6240 + x6242;
    let x6244 = x942 * x6144;
    let x6245 = x1548 * x5913;
    let x6246 = x6244 + x6245;
    let x6247 = x103 * x6194;
    let x6248 = x6244 + x6247;
    let x6249 = x6246 + x6248;
    let x6250 = x904 * x6147;
    let x6251 = x1472 * x5916;
    let x6252 = x6250 + x6251;
    let x6253 = x89 * x6197;
    let x6254 = x6250 + x6253;
    let x6255 = x6252 + x6254;
    let x6257 = x6243 + x6249;
    let x6258 = x6257 - x6255;
    let x6259 = s[225] * k[10];
    let x6261 = s[274] * k[11];
    let x6262 = x6261 - x6259;
    let x6263 = s[231] * k[10];
    let x6265 = s[275] * k[11];
    let x6266 = x6265 - x6263;
    let x6267 = s[216] * k[10];
    let x6268 = s[249] * k[11];
    let x6270 = x6267 - x6268;
    let x6277 = -x6237;
    let x6278 = -x6258;
    out[13] = x6277;
    out[14] = x6278;
    out[15] = x6262;
    out[16] = x6266;
    out[17] = x6270;
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
    let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
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
    k: &[f64; 23],
    q: &[f64; 18],
    qd: &[f64; 18],
    t: f64,
    s: &mut [f64; 284],
) {
    let x5 = 6.283185307179586 * t;
    s[0] = x5;
    let (x12, x13) = symbody_runtime::trig::sin_cos(q[3]);
    s[1] = x12;
    s[2] = x13;
    let (x14, x15) = symbody_runtime::trig::sin_cos(q[4]);
    s[3] = x14;
    s[4] = x15;
    let (x16, x17) = symbody_runtime::trig::sin_cos(q[5]);
    s[5] = x16;
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
    let (x45, x46) = symbody_runtime::trig::sin_cos(q[9]);
    s[23] = x45;
    s[24] = x46;
    let (x47, x48) = symbody_runtime::trig::sin_cos(q[10]);
    s[25] = x47;
    s[26] = x48;
    let (x49, x50) = symbody_runtime::trig::sin_cos(q[11]);
    s[27] = x49;
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
    let (x78, x79) = symbody_runtime::trig::sin_cos(q[15]);
    s[47] = x78;
    s[48] = x79;
    let (x80, x81) = symbody_runtime::trig::sin_cos(q[16]);
    s[49] = x80;
    s[50] = x81;
    let (x82, x83) = symbody_runtime::trig::sin_cos(q[17]);
    s[51] = x82;
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
    let (x331, x332) = symbody_runtime::trig::sin_cos(x5);
    s[70] = x331;
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
    let x5881 = x51 * k[3];
    s[272] = x5881;
    let x5882 = x66 * k[4];
    s[273] = x5882;
    let x5883 = x5881 + x5882;
    s[274] = x5883;
    let x5884 = x52 * k[3];
    s[275] = x5884;
    let x5885 = x68 * k[4];
    s[276] = x5885;
    let x5886 = x5884 + x5885;
    s[277] = x5886;
    let x5919 = x84 * k[7];
    s[278] = x5919;
    let x5920 = x99 * k[8];
    s[279] = x5920;
    let x5921 = x5919 + x5920;
    s[280] = x5921;
    let x5922 = x85 * k[7];
    s[281] = x5922;
    let x5923 = x101 * k[8];
    s[282] = x5923;
    let x5924 = x5922 + x5923;
    s[283] = x5924;
}
#[inline(never)]
fn eval_kinematics_part_0(
    k: &[f64; 23],
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
    let x5847 = s[7] * k[0];
    let x5848 = s[8] * k[0];
    let x5849 = s[3] * k[0];
    let x5851 = q[0] + x5847;
    let x5852 = q[1] + x5848;
    let x5853 = q[2] - x5849;
    let x5854 = -x5851;
    let x5855 = -x5852;
    let x5856 = -x5853;
    let x5858 = s[7] * k[1];
    let x5859 = s[8] * k[1];
    let x5860 = s[3] * k[1];
    let x5862 = q[0] + x5858;
    let x5863 = q[1] + x5859;
    let x5864 = q[2] - x5860;
    let x5866 = s[29] * k[2];
    let x5867 = s[30] * k[2];
    let x5868 = s[25] * k[2];
    let x5870 = q[6] + x5866;
    let x5871 = q[7] + x5867;
    let x5872 = q[8] - x5868;
    let x5874 = x5862 - x5870;
    let x5876 = x5863 - x5871;
    let x5878 = x5864 - x5872;
    let x5891 = q[6] + s[274];
    let x5929 = q[12] + s[280];
    let x5933 = x5891 - x5929;
    let x5968 = s[9] * k[0];
    let x5969 = s[10] * k[0];
    let x5970 = s[4] * k[0];
    let x5971 = s[9] * k[1];
    let x5972 = -x5971;
    let x5973 = s[10] * k[1];
    let x5974 = -x5973;
    let x5975 = s[4] * k[1];
    let x5976 = -x5975;
    let x5977 = -x5847;
    let x5978 = -x5859;
    let x5979 = s[44] * k[4];
    let x5998 = s[31] * k[2];
    let x5999 = s[32] * k[2];
    let x6000 = s[26] * k[2];
    let x6001 = s[31] * k[3];
    let x6003 = s[79] * k[4];
    let x6004 = x6003 - x6001;
    let x6045 = -x5866;
    let x6046 = -s[277];
    let x6056 = s[64] * k[8];
    let x6059 = -x6056;
    let x6082 = s[55] * k[7];
    let x6084 = s[80] * k[8];
    let x6085 = x6084 - x6082;
    let x6093 = -x6085;
    let x6148 = s[149] * k[0];
    let x6149 = -x6148;
    let x6150 = s[155] * k[0];
    let x6151 = -x6150;
    let x6152 = s[140] * k[0];
    let x6153 = s[149] * k[1];
    let x6155 = s[155] * k[1];
    let x6157 = s[140] * k[1];
    let x6158 = s[205] * k[2];
    let x6159 = s[211] * k[2];
    let x6160 = s[196] * k[2];
    let x6162 = x6158 - x6153;
    let x6163 = x6159 - x6155;
    let x6164 = x6157 - x6160;
    let x6165 = s[205] * k[3];
    let x6167 = s[236] * k[4];
    let x6168 = x6167 - x6165;
    let x6198 = s[248] * k[7];
    let x6200 = s[267] * k[8];
    let x6201 = x6200 - x6198;
    let x6211 = x6168 - x6201;
    let x6271 = -x6162;
    let x6272 = -x6163;
    let x6273 = -x6164;
    let x6274 = -x6211;
    phi[0] = x5854;
    phi_q[0] = -1.0;
    phi_q[1] = x5968;
    phi_q[2] = x5848;
    phi_t[0] = 0.0;
    gamma[0] = x6149;
    phi[1] = x5855;
    phi_q[3] = -1.0;
    phi_q[4] = x5969;
    phi_q[5] = x5977;
    phi_t[1] = 0.0;
    gamma[1] = x6151;
    phi[2] = x5856;
    phi_q[6] = -1.0;
    phi_q[7] = x5970;
    phi_t[2] = 0.0;
    gamma[2] = x6152;
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
    phi[5] = x5874;
    phi_q[14] = 1.0;
    phi_q[15] = x5972;
    phi_q[16] = x5978;
    phi_q[17] = -1.0;
    phi_q[18] = x5998;
    phi_q[19] = x5867;
    phi_t[5] = 0.0;
    gamma[5] = x6271;
    phi[6] = x5876;
    phi_q[20] = 1.0;
    phi_q[21] = x5974;
    phi_q[22] = x5858;
    phi_q[23] = -1.0;
    phi_q[24] = x5999;
    phi_q[25] = x6045;
    phi_t[6] = 0.0;
    gamma[6] = x6272;
    phi[7] = x5878;
    phi_q[26] = 1.0;
    phi_q[27] = x5976;
    phi_q[28] = -1.0;
    phi_q[29] = x6000;
    phi_t[7] = 0.0;
    gamma[7] = x6273;
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
    phi[10] = x5933;
    phi_q[42] = 1.0;
    phi_q[43] = x5979;
    phi_q[44] = x6004;
    phi_q[45] = x6046;
    phi_q[46] = -1.0;
    phi_q[47] = x6059;
    phi_q[48] = x6093;
    phi_q[49] = s[283];
    phi_t[10] = 0.0;
    gamma[10] = x6274;
}
#[inline(never)]
fn eval_kinematics_part_1(
    k: &[f64; 23],
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
    let x5887 = s[25] * k[3];
    let x5889 = s[33] * k[4];
    let x5890 = x5889 - x5887;
    let x5892 = q[7] + s[277];
    let x5893 = q[8] + x5890;
    let x5896 = s[29] * k[5];
    let x5897 = s[43] * k[6];
    let x5898 = x5896 + x5897;
    let x5899 = s[30] * k[5];
    let x5900 = s[45] * k[6];
    let x5901 = x5899 + x5900;
    let x5902 = s[25] * k[5];
    let x5904 = s[33] * k[6];
    let x5905 = x5904 - x5902;
    let x5906 = s[29] * k[6];
    let x5908 = s[43] * k[5];
    let x5909 = x5908 - x5906;
    let x5910 = s[30] * k[6];
    let x5912 = s[45] * k[5];
    let x5913 = x5912 - x5910;
    let x5914 = s[25] * k[6];
    let x5915 = s[33] * k[5];
    let x5916 = x5914 + x5915;
    let x5925 = s[49] * k[7];
    let x5927 = x88 * k[8];
    let x5928 = x5927 - x5925;
    let x5930 = q[13] + s[283];
    let x5931 = q[14] + x5928;
    let x5935 = x5892 - x5930;
    let x5937 = x5893 - x5931;
    let x5938 = s[64] * x5898;
    let x5939 = x103 * x5901;
    let x5940 = x89 * x5905;
    let x5941 = x5938 + x5939;
    let x5942 = x5940 + x5941;
    let x5943 = s[64] * x5909;
    let x5944 = x103 * x5913;
    let x5945 = x89 * x5916;
    let x5946 = x5943 + x5944;
    let x5947 = x5945 + x5946;
    let x5951 = s[53] * k[10];
    let x5952 = s[63] * k[11];
    let x5953 = x5951 + x5952;
    let x5954 = s[54] * k[10];
    let x5955 = s[65] * k[11];
    let x5956 = x5954 + x5955;
    let x5957 = s[49] * k[10];
    let x5959 = x88 * k[11];
    let x5960 = x5959 - x5957;
    let x5961 = q[12] + x5953;
    let x5962 = q[13] + x5956;
    let x5963 = q[14] + x5960;
    let x5965 = k[9] - x5961;
    let x5966 = -x5962;
    let x5967 = -x5963;
    let x5980 = s[46] * k[4];
    let x5981 = s[34] * k[4];
    let x5982 = s[44] * k[6];
    let x5983 = s[46] * k[6];
    let x5984 = s[34] * k[6];
    let x5985 = s[44] * k[5];
    let x5986 = s[46] * k[5];
    let x5987 = s[34] * k[5];
    let x5988 = s[64] * x5982;
    let x5989 = x103 * x5983;
    let x5990 = x89 * x5984;
    let x5991 = x5988 + x5989;
    let x5992 = x5990 + x5991;
    let x5993 = s[64] * x5985;
    let x5994 = x103 * x5986;
    let x5995 = x89 * x5987;
    let x5996 = x5993 + x5994;
    let x5997 = x5995 + x5996;
    let x6005 = s[32] * k[3];
    let x6007 = x501 * k[4];
    let x6008 = x6007 - x6005;
    let x6009 = s[26] * k[3];
    let x6010 = x495 * k[4];
    let x6011 = x6009 + x6010;
    let x6012 = -x6011;
    let x6013 = s[31] * k[5];
    let x6015 = s[79] * k[6];
    let x6016 = x6015 - x6013;
    let x6017 = s[32] * k[5];
    let x6019 = x501 * k[6];
    let x6020 = x6019 - x6017;
    let x6021 = s[26] * k[5];
    let x6022 = x495 * k[6];
    let x6023 = x6021 + x6022;
    let x6024 = s[31] * k[6];
    let x6025 = s[79] * k[5];
    let x6026 = x6024 + x6025;
    let x6027 = s[32] * k[6];
    let x6028 = x501 * k[5];
    let x6029 = x6027 + x6028;
    let x6030 = s[26] * k[6];
    let x6031 = x495 * k[5];
    let x6033 = x6030 - x6031;
    let x6034 = s[64] * x6016;
    let x6035 = x103 * x6020;
    let x6036 = x89 * x6023;
    let x6038 = x6034 + x6035;
    let x6039 = x6038 - x6036;
    let x6040 = s[64] * x6026;
    let x6041 = x103 * x6029;
    let x6042 = x89 * x6033;
    let x6043 = x6040 + x6041;
    let x6044 = x6042 + x6043;
    let x6048 = x5910 - x5912;
    let x6049 = s[64] * x5901;
    let x6051 = x103 * x5898;
    let x6052 = x6051 - x6049;
    let x6053 = s[64] * x6048;
    let x6054 = x103 * x5909;
    let x6055 = x6053 + x6054;
    let x6057 = x103 * k[8];
    let x6058 = x89 * k[8];
    let x6060 = -x6057;
    let x6061 = -x6058;
    let x6062 = x603 * x5898;
    let x6063 = s[65] * x5901;
    let x6065 = x88 * x5905;
    let x6067 = x6062 - x6063;
    let x6068 = x6067 - x6065;
    let x6069 = x603 * x5909;
    let x6070 = s[65] * x5913;
    let x6072 = x88 * x5916;
    let x6074 = x6069 - x6070;
    let x6075 = x6074 - x6072;
    let x6076 = s[64] * k[11];
    let x6077 = x103 * k[11];
    let x6078 = x89 * k[11];
    let x6079 = -x6076;
    let x6080 = -x6077;
    let x6081 = -x6078;
    let x6086 = s[56] * k[7];
    let x6088 = x640 * k[8];
    let x6089 = x6088 - x6086;
    let x6090 = s[50] * k[7];
    let x6091 = x634 * k[8];
    let x6092 = x6090 + x6091;
    let x6094 = -x6089;
    let x6095 = x639 * x5898;
    let x6096 = x641 * x5901;
    let x6097 = x636 * x5905;
    let x6099 = x6095 + x6096;
    let x6100 = x6099 - x6097;
    let x6101 = x639 * x5909;
    let x6102 = x641 * x5913;
    let x6103 = x636 * x5916;
    let x6105 = x6101 + x6102;
    let x6106 = x6105 - x6103;
    let x6107 = s[55] * k[10];
    let x6109 = s[80] * k[11];
    let x6110 = x6109 - x6107;
    let x6111 = s[56] * k[10];
    let x6113 = x640 * k[11];
    let x6114 = x6113 - x6111;
    let x6115 = s[50] * k[10];
    let x6116 = x634 * k[11];
    let x6117 = x6115 + x6116;
    let x6118 = -x6110;
    let x6119 = -x6114;
    let x6120 = -s[280];
    let x6121 = x689 * x5898;
    let x6122 = x6049 + x6121;
    let x6123 = x689 * x5909;
    let x6124 = s[64] * x5913;
    let x6125 = x6123 + x6124;
    let x6126 = -x5953;
    let x6127 = x810 * k[5];
    let x6129 = x865 * k[6];
    let x6130 = x6129 - x6127;
    let x6131 = x815 * k[5];
    let x6132 = x867 * k[6];
    let x6133 = x6131 + x6132;
    let x6134 = s[115] * k[5];
    let x6136 = x826 * k[6];
    let x6137 = x6136 - x6134;
    let x6138 = x810 * k[6];
    let x6139 = x865 * k[5];
    let x6140 = x6138 + x6139;
    let x6141 = x815 * k[6];
    let x6143 = x867 * k[5];
    let x6144 = x6143 - x6141;
    let x6145 = s[115] * k[6];
    let x6146 = x826 * k[5];
    let x6147 = x6145 + x6146;
    let x6169 = s[211] * k[3];
    let x6171 = x1407 * k[4];
    let x6172 = x6171 - x6169;
    let x6173 = s[196] * k[3];
    let x6174 = x1324 * k[4];
    let x6176 = x6173 - x6174;
    let x6177 = s[205] * k[5];
    let x6179 = s[236] * k[6];
    let x6180 = x6179 - x6177;
    let x6181 = s[211] * k[5];
    let x6183 = x1407 * k[6];
    let x6184 = x6183 - x6181;
    let x6185 = s[196] * k[5];
    let x6186 = x1324 * k[6];
    let x6188 = x6185 - x6186;
    let x6189 = s[205] * k[6];
    let x6190 = s[236] * k[5];
    let x6191 = x6189 + x6190;
    let x6192 = s[211] * k[6];
    let x6193 = x1407 * k[5];
    let x6194 = x6192 + x6193;
    let x6195 = s[196] * k[6];
    let x6196 = x1324 * k[5];
    let x6197 = x6195 + x6196;
    let x6202 = x1434 * k[7];
    let x6204 = x1547 * k[8];
    let x6205 = x6204 - x6202;
    let x6206 = s[239] * k[7];
    let x6207 = x1464 * k[8];
    let x6209 = x6206 - x6207;
    let x6213 = x6172 - x6205;
    let x6215 = x6176 - x6209;
    let x6216 = x939 * x6130;
    let x6217 = x1546 * x5898;
    let x6218 = x6216 + x6217;
    let x6219 = s[64] * x6180;
    let x6220 = x6216 + x6219;
    let x6221 = x6218 + x6220;
    let x6222 = x942 * x6133;
    let x6223 = x1548 * x5901;
    let x6224 = x6222 + x6223;
    let x6225 = x103 * x6184;
    let x6226 = x6222 + x6225;
    let x6227 = x6224 + x6226;
    let x6228 = x904 * x6137;
    let x6229 = x1472 * x5905;
    let x6230 = x6228 + x6229;
    let x6233 = x89 * x6188;
    let x6234 = x6233 - x6228;
    let x6235 = x6234 - x6230;
    let x6236 = x6221 + x6227;
    let x6237 = x6235 + x6236;
    let x6238 = x939 * x6140;
    let x6239 = x1546 * x5909;
    let x6240 = x6238 + x6239;
    let x6241 = s[64] * x6191;
    let x6242 = x6238 + x6241;
    let x6243 = x6240 + x6242;
    let x6244 = x942 * x6144;
    let x6245 = x1548 * x5913;
    let x6246 = x6244 + x6245;
    let x6247 = x103 * x6194;
    let x6248 = x6244 + x6247;
    let x6249 = x6246 + x6248;
    let x6250 = x904 * x6147;
    let x6251 = x1472 * x5916;
    let x6252 = x6250 + x6251;
    let x6253 = x89 * x6197;
    let x6254 = x6250 + x6253;
    let x6255 = x6252 + x6254;
    let x6257 = x6243 + x6249;
    let x6258 = x6257 - x6255;
    let x6259 = s[248] * k[10];
    let x6261 = s[267] * k[11];
    let x6262 = x6261 - x6259;
    let x6263 = x1434 * k[10];
    let x6265 = x1547 * k[11];
    let x6266 = x6265 - x6263;
    let x6267 = s[239] * k[10];
    let x6268 = x1464 * k[11];
    let x6270 = x6267 - x6268;
    let x6275 = -x6213;
    let x6276 = -x6215;
    let x6277 = -x6237;
    let x6278 = -x6258;
    phi[11] = x5935;
    phi_q[50] = 1.0;
    phi_q[51] = x5980;
    phi_q[52] = x6008;
    phi_q[53] = s[274];
    phi_q[54] = -1.0;
    phi_q[55] = x6060;
    phi_q[56] = x6094;
    phi_q[57] = x6120;
    phi_t[11] = 0.0;
    gamma[11] = x6275;
    phi[12] = x5937;
    phi_q[58] = 1.0;
    phi_q[59] = x5981;
    phi_q[60] = x6012;
    phi_q[61] = -1.0;
    phi_q[62] = x6061;
    phi_q[63] = x6092;
    phi_t[12] = 0.0;
    gamma[12] = x6276;
    phi[13] = x5942;
    phi_q[64] = x5992;
    phi_q[65] = x6039;
    phi_q[66] = x6052;
    phi_q[67] = x6068;
    phi_q[68] = x6100;
    phi_q[69] = x6122;
    phi_t[13] = 0.0;
    gamma[13] = x6277;
    phi[14] = x5947;
    phi_q[70] = x5997;
    phi_q[71] = x6044;
    phi_q[72] = x6055;
    phi_q[73] = x6075;
    phi_q[74] = x6106;
    phi_q[75] = x6125;
    phi_t[14] = 0.0;
    gamma[14] = x6278;
    phi[15] = x5965;
    phi_q[76] = -1.0;
    phi_q[77] = x6079;
    phi_q[78] = x6118;
    phi_q[79] = x5956;
    phi_t[15] = 0.0;
    gamma[15] = x6262;
    phi[16] = x5966;
    phi_q[80] = -1.0;
    phi_q[81] = x6080;
    phi_q[82] = x6119;
    phi_q[83] = x6126;
    phi_t[16] = 0.0;
    gamma[16] = x6266;
    phi[17] = x5967;
    phi_q[84] = -1.0;
    phi_q[85] = x6081;
    phi_q[86] = x6117;
    phi_t[17] = 0.0;
    gamma[17] = x6270;
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
    let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
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
    let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
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
    let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
    let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
    let qd: &[f64; 18] = qd.try_into().expect("qd must have n_coords entries");
    let dq: &[f64; 18] = dq.try_into().expect("dq must have n_coords entries");
    let dqd: &[f64; 18] = dqd.try_into().expect("dqd must have n_coords entries");
    let dp: &[f64; 33] = dp.try_into().expect("dp must have 33 entries");
    let phi: &mut [f64; 21] = phi.try_into().expect("phi must have 21 entries");
    let phi_q: &mut [f64; 96] = phi_q.try_into().expect("phi_q must have 96 entries");
    let phi_t: &mut [f64; 21] = phi_t.try_into().expect("phi_t must have 21 entries");
    let gamma: &mut [f64; 21] = gamma.try_into().expect("gamma must have 21 entries");
    let mut s = [0.0f64; 1544];
    kinematic_tangents_shared_0(k, q, qd, t, dq, dqd, dp, &mut s);
    kinematic_tangents_shared_1(k, q, qd, t, dq, dqd, dp, &mut s);
    kinematic_tangents_shared_2(k, q, qd, t, dq, dqd, dp, &mut s);
    kinematic_tangents_part_0(k, dq, dp, &s, phi, phi_q, phi_t, gamma);
    kinematic_tangents_part_1(&s, phi_q, phi_t);
    kinematic_tangents_part_2(&s, gamma);
    kinematic_tangents_part_3(&s, phi, phi_q, phi_t);
    kinematic_tangents_part_4(&s, gamma);
    kinematic_tangents_part_5(k, dq, dp, &s, phi, phi_q, phi_t, gamma);
    kinematic_tangents_part_6(k, dq, dp, &s, phi, phi_q, phi_t, gamma);
    kinematic_tangents_part_7(k, dp, &s, phi_q, phi_t);
    kinematic_tangents_part_8(k, dp, &s, gamma);
    kinematic_tangents_part_9(k, dp, &s, phi, phi_q, phi_t);
    kinematic_tangents_part_10(k, dp, &s, gamma);
    kinematic_tangents_part_11(k, dq, dp, &s, phi, phi_q, phi_t, gamma);
    kinematic_tangents_part_12(&s, gamma);
}
#[inline(never)]
fn kinematic_tangents_shared_0(
    _k: &[f64; 23],
    q: &[f64; 18],
    qd: &[f64; 18],
    t: f64,
    dq: &[f64; 18],
    _dqd: &[f64; 18],
    _dp: &[f64; 33],
    s: &mut [f64; 1544],
) {
    let x5 = 6.283185307179586 * t;
    s[0] = x5;
    let (x12, x13) = symbody_runtime::trig::sin_cos(q[3]);
    s[1] = x12;
    s[2] = x13;
    let (x14, x15) = symbody_runtime::trig::sin_cos(q[4]);
    s[3] = x14;
    s[4] = x15;
    let (x16, x17) = symbody_runtime::trig::sin_cos(q[5]);
    s[5] = x16;
    s[6] = x17;
    let x18 = x15 * x17;
    s[7] = x18;
    let x19 = x15 * x16;
    s[8] = x19;
    let x20 = x14 * x17;
    s[9] = x20;
    let x21 = x14 * x16;
    s[10] = x21;
    let x22 = x12 * x15;
    s[11] = x22;
    let x23 = x13 * x15;
    s[12] = x23;
    let x24 = x12 * x20;
    s[13] = x24;
    let x25 = x13 * x16;
    s[14] = x25;
    let x26 = x13 * x20;
    s[15] = x26;
    let x27 = x12 * x16;
    s[16] = x27;
    let x28 = x12 * x21;
    s[17] = x28;
    let x29 = x13 * x17;
    s[18] = x29;
    let x30 = x13 * x21;
    s[19] = x30;
    let x31 = x12 * x17;
    s[20] = x31;
    let x33 = x24 - x25;
    s[21] = x33;
    let x34 = x26 + x27;
    s[22] = x34;
    let x35 = x28 + x29;
    s[23] = x35;
    let x37 = x30 - x31;
    s[24] = x37;
    let (x45, x46) = symbody_runtime::trig::sin_cos(q[9]);
    s[25] = x45;
    s[26] = x46;
    let (x47, x48) = symbody_runtime::trig::sin_cos(q[10]);
    s[27] = x47;
    s[28] = x48;
    let (x49, x50) = symbody_runtime::trig::sin_cos(q[11]);
    s[29] = x49;
    s[30] = x50;
    let x51 = x48 * x50;
    s[31] = x51;
    let x52 = x48 * x49;
    s[32] = x52;
    let x53 = x47 * x50;
    s[33] = x53;
    let x54 = x47 * x49;
    s[34] = x54;
    let x55 = x45 * x48;
    s[35] = x55;
    let x56 = x46 * x48;
    s[36] = x56;
    let x57 = x45 * x53;
    s[37] = x57;
    let x58 = x46 * x49;
    s[38] = x58;
    let x59 = x46 * x53;
    s[39] = x59;
    let x60 = x45 * x49;
    s[40] = x60;
    let x61 = x45 * x54;
    s[41] = x61;
    let x62 = x46 * x50;
    s[42] = x62;
    let x63 = x46 * x54;
    s[43] = x63;
    let x64 = x45 * x50;
    s[44] = x64;
    let x66 = x57 - x58;
    s[45] = x66;
    let x67 = x59 + x60;
    s[46] = x67;
    let x68 = x61 + x62;
    s[47] = x68;
    let x70 = x63 - x64;
    s[48] = x70;
    let (x78, x79) = symbody_runtime::trig::sin_cos(q[15]);
    s[49] = x78;
    s[50] = x79;
    let (x80, x81) = symbody_runtime::trig::sin_cos(q[16]);
    s[51] = x80;
    s[52] = x81;
    let (x82, x83) = symbody_runtime::trig::sin_cos(q[17]);
    s[53] = x82;
    s[54] = x83;
    let x84 = x81 * x83;
    s[55] = x84;
    let x85 = x81 * x82;
    s[56] = x85;
    let x86 = x80 * x83;
    s[57] = x86;
    let x87 = x80 * x82;
    s[58] = x87;
    let x88 = x78 * x81;
    s[59] = x88;
    let x89 = x79 * x81;
    s[60] = x89;
    let x90 = x78 * x86;
    s[61] = x90;
    let x91 = x79 * x82;
    s[62] = x91;
    let x92 = x79 * x86;
    s[63] = x92;
    let x93 = x78 * x82;
    s[64] = x93;
    let x94 = x78 * x87;
    s[65] = x94;
    let x95 = x79 * x83;
    s[66] = x95;
    let x96 = x79 * x87;
    s[67] = x96;
    let x97 = x78 * x83;
    s[68] = x97;
    let x99 = x90 - x91;
    s[69] = x99;
    let x100 = x92 + x93;
    s[70] = x100;
    let x101 = x94 + x95;
    s[71] = x101;
    let x103 = x96 - x97;
    s[72] = x103;
    let x116 = x18 * 0.00000000000000006123233995736766;
    s[73] = x116;
    let x118 = x116 - x33;
    s[74] = x118;
    let x119 = x19 * 0.00000000000000006123233995736766;
    s[75] = x119;
    let x121 = x119 - x35;
    s[76] = x121;
    let x122 = x14 * 0.00000000000000006123233995736766;
    s[77] = x122;
    let x125 = x22 + x122;
    s[78] = x125;
    let x127 = x33 * 0.00000000000000006123233995736766;
    s[79] = x127;
    let x128 = x18 + x127;
    s[80] = x128;
    let x129 = x35 * 0.00000000000000006123233995736766;
    s[81] = x129;
    let x130 = x19 + x129;
    s[82] = x130;
    let x131 = x22 * 0.00000000000000006123233995736766;
    s[83] = x131;
    let x132 = x131 - x14;
    s[84] = x132;
    let (x331, x332) = symbody_runtime::trig::sin_cos(x5);
    s[85] = x331;
    s[86] = x332;
    let x370 = x12 * x14;
    s[87] = x370;
    let x372 = x12 * x18;
    s[88] = x372;
    let x374 = x12 * x19;
    s[89] = x374;
    let x457 = x58 - x57;
    s[90] = x457;
    let x495 = x45 * x47;
    s[91] = x495;
    let x497 = x46 * x47;
    s[92] = x497;
    let x499 = x45 * x51;
    s[93] = x499;
    let x500 = x46 * x51;
    s[94] = x500;
    let x501 = x45 * x52;
    s[95] = x501;
    let x502 = x46 * x52;
    s[96] = x502;
    let x575 = x64 - x63;
    s[97] = x575;
    let x603 = x91 - x90;
    s[98] = x603;
    let x634 = x78 * x80;
    s[99] = x634;
    let x636 = x79 * x80;
    s[100] = x636;
    let x638 = x78 * x84;
    s[101] = x638;
    let x639 = x79 * x84;
    s[102] = x639;
    let x640 = x78 * x85;
    s[103] = x640;
    let x641 = x79 * x85;
    s[104] = x641;
    let x689 = x97 - x96;
    s[105] = x689;
    let x703 = 6.283185307179586 * x332;
    s[106] = x703;
    let x705 = 6.283185307179586 * x331;
    s[107] = x705;
    let x729 = x13 * qd[3];
    s[108] = x729;
    let x730 = x12 * qd[3];
    s[109] = x730;
    let x732 = x15 * qd[4];
    s[110] = x732;
    let x733 = x14 * qd[4];
    s[111] = x733;
    let x735 = x17 * qd[5];
    s[112] = x735;
    let x736 = x16 * qd[5];
    s[113] = x736;
    let x738 = x17 * x733;
    s[114] = x738;
    let x740 = x15 * x736;
    s[115] = x740;
    let x742 = x738 + x740;
    s[116] = x742;
    let x744 = x16 * x733;
    s[117] = x744;
    let x746 = x15 * x735;
    s[118] = x746;
    let x747 = x746 - x744;
    s[119] = x747;
    let x748 = x17 * x732;
    s[120] = x748;
    let x749 = x14 * x736;
    s[121] = x749;
    let x751 = x748 - x749;
    s[122] = x751;
    let x752 = x16 * x732;
    s[123] = x752;
    let x753 = x14 * x735;
    s[124] = x753;
    let x754 = x752 + x753;
    s[125] = x754;
    let x755 = x15 * x729;
    s[126] = x755;
    let x756 = x12 * x733;
    s[127] = x756;
    let x758 = x755 - x756;
    s[128] = x758;
    let x759 = x20 * x729;
    s[129] = x759;
    let x760 = x12 * x751;
    s[130] = x760;
    let x761 = x759 + x760;
    s[131] = x761;
    let x762 = x16 * x730;
    s[132] = x762;
    let x764 = x13 * x735;
    s[133] = x764;
    let x765 = x764 - x762;
    s[134] = x765;
    let x773 = x21 * x729;
    s[135] = x773;
    let x774 = x12 * x754;
    s[136] = x774;
    let x775 = x773 + x774;
    s[137] = x775;
    let x776 = x17 * x730;
    s[138] = x776;
    let x778 = x13 * x736;
    s[139] = x778;
    let x780 = x776 + x778;
    s[140] = x780;
    let x791 = x761 - x765;
    s[141] = x791;
    let x793 = x775 - x780;
    s[142] = x793;
    let x797 = x46 * qd[9];
    s[143] = x797;
    let x798 = x45 * qd[9];
    s[144] = x798;
    let x800 = x48 * qd[10];
    s[145] = x800;
    let x801 = x47 * qd[10];
    s[146] = x801;
    let x803 = x50 * qd[11];
    s[147] = x803;
    let x804 = x49 * qd[11];
    s[148] = x804;
    let x806 = x50 * x801;
    s[149] = x806;
    let x808 = x48 * x804;
    s[150] = x808;
    let x810 = x806 + x808;
    s[151] = x810;
    let x812 = x49 * x801;
    s[152] = x812;
    let x814 = x48 * x803;
    s[153] = x814;
    let x815 = x814 - x812;
    s[154] = x815;
    let x816 = x50 * x800;
    s[155] = x816;
    let x817 = x47 * x804;
    s[156] = x817;
    let x819 = x816 - x817;
    s[157] = x819;
    let x820 = x49 * x800;
    s[158] = x820;
    let x821 = x47 * x803;
    s[159] = x821;
    let x822 = x820 + x821;
    s[160] = x822;
    let x823 = x48 * x797;
    s[161] = x823;
    let x824 = x45 * x801;
    s[162] = x824;
    let x826 = x823 - x824;
    s[163] = x826;
    let x827 = x48 * x798;
    s[164] = x827;
    let x829 = x46 * x801;
    s[165] = x829;
    let x831 = x827 + x829;
    s[166] = x831;
    let x833 = x53 * x797;
    s[167] = x833;
    let x834 = x45 * x819;
    s[168] = x834;
    let x835 = x833 + x834;
    s[169] = x835;
    let x836 = x49 * x798;
    s[170] = x836;
    let x838 = x46 * x803;
    s[171] = x838;
    let x839 = x838 - x836;
    s[172] = x839;
    let x840 = x53 * x798;
    s[173] = x840;
    let x842 = x46 * x819;
    s[174] = x842;
    let x843 = x842 - x840;
    s[175] = x843;
    let x844 = x49 * x797;
    s[176] = x844;
    let x845 = x45 * x803;
    s[177] = x845;
    let x846 = x844 + x845;
    s[178] = x846;
    let x847 = x54 * x797;
    s[179] = x847;
    let x848 = x45 * x822;
    s[180] = x848;
    let x849 = x847 + x848;
    s[181] = x849;
    let x850 = x50 * x798;
    s[182] = x850;
    let x852 = x46 * x804;
    s[183] = x852;
    let x854 = x850 + x852;
    s[184] = x854;
    let x856 = x54 * x798;
    s[185] = x856;
    let x858 = x46 * x822;
    s[186] = x858;
    let x859 = x858 - x856;
    s[187] = x859;
    let x860 = x50 * x797;
    s[188] = x860;
    let x861 = x45 * x804;
    s[189] = x861;
    let x863 = x860 - x861;
    s[190] = x863;
    let x865 = x835 - x839;
    s[191] = x865;
    let x866 = x843 + x846;
    s[192] = x866;
    let x867 = x849 - x854;
    s[193] = x867;
    let x869 = x859 - x863;
    s[194] = x869;
    let x870 = x79 * qd[15];
    s[195] = x870;
    let x871 = x78 * qd[15];
    s[196] = x871;
    let x873 = x81 * qd[16];
    s[197] = x873;
    let x874 = x80 * qd[16];
    s[198] = x874;
    let x876 = x83 * qd[17];
    s[199] = x876;
    let x877 = x82 * qd[17];
    s[200] = x877;
    let x889 = x83 * x873;
    s[201] = x889;
    let x890 = x80 * x877;
    s[202] = x890;
    let x892 = x889 - x890;
    s[203] = x892;
    let x893 = x82 * x873;
    s[204] = x893;
    let x894 = x80 * x876;
    s[205] = x894;
    let x895 = x893 + x894;
    s[206] = x895;
    let x900 = x81 * x871;
    s[207] = x900;
    let x902 = x79 * x874;
    s[208] = x902;
    let x904 = x900 + x902;
    s[209] = x904;
    let x913 = x86 * x871;
    s[210] = x913;
    let x915 = x79 * x892;
    s[211] = x915;
    let x916 = x915 - x913;
    s[212] = x916;
    let x917 = x82 * x870;
    s[213] = x917;
    let x918 = x78 * x876;
    s[214] = x918;
    let x919 = x917 + x918;
    s[215] = x919;
    let x929 = x87 * x871;
    s[216] = x929;
    let x931 = x79 * x895;
    s[217] = x931;
    let x932 = x931 - x929;
    s[218] = x932;
    let x933 = x83 * x870;
    s[219] = x933;
    let x934 = x78 * x877;
    s[220] = x934;
    let x936 = x933 - x934;
    s[221] = x936;
    let x939 = x916 + x919;
    s[222] = x939;
    let x942 = x932 - x936;
    s[223] = x942;
    let x1135 = qd[3] * x730;
    s[224] = x1135;
    let x1137 = qd[3] * x729;
    s[225] = x1137;
    let x1138 = qd[4] * x733;
    s[226] = x1138;
    let x1140 = qd[4] * x732;
    s[227] = x1140;
    let x1141 = qd[5] * x736;
    s[228] = x1141;
    let x1143 = qd[5] * x735;
    s[229] = x1143;
    let x1144 = x733 * x736;
    s[230] = x1144;
    let x1146 = x17 * x1140;
    s[231] = x1146;
    let x1147 = x1146 - x1144;
    s[232] = x1147;
    let x1148 = x15 * x1143;
    s[233] = x1148;
    let x1149 = x1148 - x1144;
    s[234] = x1149;
    let x1150 = x1147 + x1149;
    s[235] = x1150;
    let x1152 = x733 * x735;
    s[236] = x1152;
    let x1153 = x16 * x1140;
    s[237] = x1153;
    let x1154 = x1152 + x1153;
    s[238] = x1154;
    let x1157 = x15 * x1141;
    s[239] = x1157;
    let x1159 = x1152 + x1157;
    s[240] = x1159;
    let x1161 = x1154 + x1159;
    s[241] = x1161;
    let x1163 = x732 * x736;
    s[242] = x1163;
    let x1165 = x17 * x1138;
    s[243] = x1165;
    let x1167 = x1163 + x1165;
    s[244] = x1167;
    let x1169 = x14 * x1143;
    s[245] = x1169;
    let x1170 = x1163 + x1169;
    s[246] = x1170;
    let x1172 = x1167 + x1170;
    s[247] = x1172;
    let x1174 = x732 * x735;
    s[248] = x1174;
    let x1175 = x16 * x1138;
    s[249] = x1175;
    let x1177 = x1174 - x1175;
    s[250] = x1177;
    let x1178 = x14 * x1141;
    s[251] = x1178;
    let x1180 = x1174 - x1178;
    s[252] = x1180;
    let x1181 = x1177 + x1180;
    s[253] = x1181;
    let x1182 = x729 * x733;
    s[254] = x1182;
    let x1184 = x15 * x1135;
    s[255] = x1184;
    let x1186 = x1182 + x1184;
    s[256] = x1186;
    let x1188 = x12 * x1140;
    s[257] = x1188;
    let x1189 = x1182 + x1188;
    s[258] = x1189;
    let x1191 = x1186 + x1189;
    s[259] = x1191;
    let x1193 = x729 * x751;
    s[260] = x1193;
    let x1194 = x20 * x1135;
    s[261] = x1194;
    let x1196 = x1193 - x1194;
    s[262] = x1196;
    let x1197 = x12 * x1172;
    s[263] = x1197;
    let x1199 = x1193 - x1197;
    s[264] = x1199;
    let x1200 = x1196 + x1199;
    s[265] = x1200;
    let x1201 = x730 * x735;
    s[266] = x1201;
    let x1202 = x16 * x1137;
    s[267] = x1202;
    let x1203 = x1201 + x1202;
    s[268] = x1203;
    let x1206 = x13 * x1141;
    s[269] = x1206;
    let x1208 = x1201 + x1206;
    s[270] = x1208;
    let x1210 = x1203 + x1208;
    s[271] = x1210;
    let x1231 = x729 * x754;
    s[272] = x1231;
    let x1232 = x21 * x1135;
    s[273] = x1232;
    let x1234 = x1231 - x1232;
    s[274] = x1234;
    let x1235 = x12 * x1181;
    s[275] = x1235;
    let x1236 = x1231 + x1235;
    s[276] = x1236;
    let x1237 = x1234 + x1236;
    s[277] = x1237;
    let x1238 = x730 * x736;
    s[278] = x1238;
    let x1240 = x17 * x1137;
    s[279] = x1240;
    let x1241 = x1240 - x1238;
    s[280] = x1241;
    let x1242 = x13 * x1143;
    s[281] = x1242;
    let x1243 = x1242 - x1238;
    s[282] = x1243;
    let x1244 = x1241 + x1243;
    s[283] = x1244;
    let x1265 = x1200 + x1210;
    s[284] = x1265;
    let x1267 = x1237 - x1244;
    s[285] = x1267;
    let x1269 = qd[9] * x798;
    s[286] = x1269;
    let x1271 = qd[9] * x797;
    s[287] = x1271;
    let x1272 = qd[10] * x801;
    s[288] = x1272;
    let x1274 = qd[10] * x800;
    s[289] = x1274;
    let x1275 = qd[11] * x804;
    s[290] = x1275;
    let x1277 = qd[11] * x803;
    s[291] = x1277;
    let x1278 = x801 * x804;
    s[292] = x1278;
    let x1280 = x50 * x1274;
    s[293] = x1280;
    let x1281 = x1280 - x1278;
    s[294] = x1281;
    let x1282 = x48 * x1277;
    s[295] = x1282;
    let x1283 = x1282 - x1278;
    s[296] = x1283;
    let x1284 = x1281 + x1283;
    s[297] = x1284;
    let x1285 = x801 * x803;
    s[298] = x1285;
    let x1286 = x49 * x1274;
    s[299] = x1286;
    let x1287 = x1285 + x1286;
    s[300] = x1287;
    let x1290 = x48 * x1275;
    s[301] = x1290;
    let x1292 = x1285 + x1290;
    s[302] = x1292;
    let x1294 = x1287 + x1292;
    s[303] = x1294;
    let x1296 = x800 * x804;
    s[304] = x1296;
    let x1298 = x50 * x1272;
    s[305] = x1298;
    let x1300 = x1296 + x1298;
    s[306] = x1300;
    let x1302 = x47 * x1277;
    s[307] = x1302;
    let x1303 = x1296 + x1302;
    s[308] = x1303;
    let x1305 = x1300 + x1303;
    s[309] = x1305;
    let x1307 = x800 * x803;
    s[310] = x1307;
    let x1308 = x49 * x1272;
    s[311] = x1308;
    let x1310 = x1307 - x1308;
    s[312] = x1310;
    let x1311 = x47 * x1275;
    s[313] = x1311;
    let x1313 = x1307 - x1311;
    s[314] = x1313;
    let x1314 = x1310 + x1313;
    s[315] = x1314;
    let x1315 = x797 * x801;
    s[316] = x1315;
    let x1317 = x48 * x1269;
    s[317] = x1317;
    let x1319 = x1315 + x1317;
    s[318] = x1319;
    let x1321 = x45 * x1274;
    s[319] = x1321;
    let x1322 = x1315 + x1321;
    s[320] = x1322;
    let x1324 = x1319 + x1322;
    s[321] = x1324;
    let x1326 = x798 * x801;
    s[322] = x1326;
    let x1328 = x48 * x1271;
    s[323] = x1328;
    let x1329 = x1328 - x1326;
    s[324] = x1329;
    let x1330 = x46 * x1274;
    s[325] = x1330;
    let x1331 = x1330 - x1326;
    s[326] = x1331;
    let x1332 = x1329 + x1331;
    s[327] = x1332;
    let x1333 = x797 * x819;
    s[328] = x1333;
    let x1334 = x53 * x1269;
    s[329] = x1334;
    let x1336 = x1333 - x1334;
    s[330] = x1336;
    let x1337 = x45 * x1305;
    s[331] = x1337;
    let x1339 = x1333 - x1337;
    s[332] = x1339;
    let x1340 = x1336 + x1339;
    s[333] = x1340;
    let x1341 = x798 * x803;
    s[334] = x1341;
    let x1342 = x49 * x1271;
    s[335] = x1342;
    let x1343 = x1341 + x1342;
    s[336] = x1343;
    let x1346 = x46 * x1275;
    s[337] = x1346;
    let x1348 = x1341 + x1346;
    s[338] = x1348;
    let x1350 = x1343 + x1348;
    s[339] = x1350;
    let x1352 = x798 * x819;
    s[340] = x1352;
    let x1353 = x53 * x1271;
    s[341] = x1353;
    let x1354 = x1352 + x1353;
    s[342] = x1354;
    let x1357 = x46 * x1305;
    s[343] = x1357;
    let x1359 = x1352 + x1357;
    s[344] = x1359;
    let x1361 = x1354 + x1359;
    s[345] = x1361;
    let x1363 = x797 * x803;
    s[346] = x1363;
    let x1364 = x49 * x1269;
    s[347] = x1364;
    let x1366 = x1363 - x1364;
    s[348] = x1366;
    let x1367 = x45 * x1275;
    s[349] = x1367;
    let x1369 = x1363 - x1367;
    s[350] = x1369;
    let x1370 = x1366 + x1369;
    s[351] = x1370;
    let x1371 = x797 * x822;
    s[352] = x1371;
    let x1372 = x54 * x1269;
    s[353] = x1372;
    let x1374 = x1371 - x1372;
    s[354] = x1374;
    let x1375 = x45 * x1314;
    s[355] = x1375;
    let x1376 = x1371 + x1375;
    s[356] = x1376;
    let x1377 = x1374 + x1376;
    s[357] = x1377;
    let x1378 = x798 * x804;
    s[358] = x1378;
    let x1380 = x50 * x1271;
    s[359] = x1380;
    let x1381 = x1380 - x1378;
    s[360] = x1381;
    let x1382 = x46 * x1277;
    s[361] = x1382;
    let x1383 = x1382 - x1378;
    s[362] = x1383;
    let x1384 = x1381 + x1383;
    s[363] = x1384;
    let x1386 = x798 * x822;
    s[364] = x1386;
    let x1387 = x54 * x1271;
    s[365] = x1387;
    let x1388 = x1386 + x1387;
    s[366] = x1388;
    let x1391 = x46 * x1314;
    s[367] = x1391;
    let x1392 = x1391 - x1386;
    s[368] = x1392;
    let x1393 = x1392 - x1388;
    s[369] = x1393;
    let x1394 = x797 * x804;
    s[370] = x1394;
    let x1396 = x50 * x1269;
    s[371] = x1396;
    let x1398 = x1394 + x1396;
    s[372] = x1398;
    let x1400 = x45 * x1277;
    s[373] = x1400;
    let x1401 = x1394 + x1400;
    s[374] = x1401;
    let x1403 = x1398 + x1401;
    s[375] = x1403;
    let x1405 = x1340 + x1350;
    s[376] = x1405;
    let x1406 = x1370 - x1361;
    s[377] = x1406;
    let x1407 = x1377 - x1384;
    s[378] = x1407;
    let x1408 = x1393 + x1403;
    s[379] = x1408;
    let x1409 = qd[15] * x871;
    s[380] = x1409;
    let x1411 = qd[15] * x870;
    s[381] = x1411;
    let x1412 = qd[16] * x874;
    s[382] = x1412;
    let x1414 = qd[16] * x873;
    s[383] = x1414;
    let x1415 = qd[17] * x877;
    s[384] = x1415;
    let x1417 = qd[17] * x876;
    s[385] = x1417;
    let x1418 = x874 * x877;
    s[386] = x1418;
    let x1420 = x83 * x1414;
    s[387] = x1420;
    let x1421 = x1420 - x1418;
    s[388] = x1421;
    let x1422 = x81 * x1417;
    s[389] = x1422;
    let x1423 = x1422 - x1418;
    s[390] = x1423;
    let x1424 = x1421 + x1423;
    s[391] = x1424;
    let x1425 = x874 * x876;
    s[392] = x1425;
    let x1426 = x82 * x1414;
    s[393] = x1426;
    let x1427 = x1425 + x1426;
    s[394] = x1427;
    let x1430 = x81 * x1415;
    s[395] = x1430;
    let x1432 = x1425 + x1430;
    s[396] = x1432;
    let x1434 = x1427 + x1432;
    s[397] = x1434;
    let x1436 = x873 * x877;
    s[398] = x1436;
    let x1438 = x83 * x1412;
    s[399] = x1438;
    let x1440 = x1436 + x1438;
    s[400] = x1440;
    let x1442 = x80 * x1417;
    s[401] = x1442;
    let x1443 = x1436 + x1442;
    s[402] = x1443;
    let x1445 = x1440 + x1443;
    s[403] = x1445;
    let x1447 = x873 * x876;
    s[404] = x1447;
    let x1448 = x82 * x1412;
    s[405] = x1448;
    let x1450 = x1447 - x1448;
    s[406] = x1450;
    let x1451 = x80 * x1415;
    s[407] = x1451;
    let x1453 = x1447 - x1451;
    s[408] = x1453;
    let x1454 = x1450 + x1453;
    s[409] = x1454;
    let x1455 = x870 * x874;
    s[410] = x1455;
    let x1457 = x81 * x1409;
    s[411] = x1457;
    let x1459 = x1455 + x1457;
    s[412] = x1459;
    let x1461 = x78 * x1414;
    s[413] = x1461;
    let x1462 = x1455 + x1461;
    s[414] = x1462;
    let x1464 = x1459 + x1462;
    s[415] = x1464;
    let x1466 = x871 * x874;
    s[416] = x1466;
    let x1468 = x81 * x1411;
    s[417] = x1468;
    let x1469 = x1468 - x1466;
    s[418] = x1469;
    let x1470 = x79 * x1414;
    s[419] = x1470;
    let x1471 = x1470 - x1466;
    s[420] = x1471;
    let x1472 = x1469 + x1471;
    s[421] = x1472;
    let x1473 = x870 * x892;
    s[422] = x1473;
    let x1474 = x86 * x1409;
    s[423] = x1474;
    let x1476 = x1473 - x1474;
    s[424] = x1476;
    let x1477 = x78 * x1445;
    s[425] = x1477;
    let x1479 = x1473 - x1477;
    s[426] = x1479;
    let x1480 = x1476 + x1479;
    s[427] = x1480;
    let x1481 = x871 * x876;
    s[428] = x1481;
    let x1482 = x82 * x1411;
    s[429] = x1482;
    let x1483 = x1481 + x1482;
    s[430] = x1483;
    let x1486 = x79 * x1415;
    s[431] = x1486;
    let x1488 = x1481 + x1486;
    s[432] = x1488;
    let x1490 = x1483 + x1488;
    s[433] = x1490;
    let x1492 = x871 * x892;
    s[434] = x1492;
    let x1493 = x86 * x1411;
    s[435] = x1493;
    let x1494 = x1492 + x1493;
    s[436] = x1494;
    let x1497 = x79 * x1445;
    s[437] = x1497;
    let x1499 = x1492 + x1497;
    s[438] = x1499;
    let x1501 = x1494 + x1499;
    s[439] = x1501;
    let x1503 = x870 * x876;
    s[440] = x1503;
    let x1504 = x82 * x1409;
    s[441] = x1504;
    let x1506 = x1503 - x1504;
    s[442] = x1506;
    let x1507 = x78 * x1415;
    s[443] = x1507;
    let x1509 = x1503 - x1507;
    s[444] = x1509;
    let x1510 = x1506 + x1509;
    s[445] = x1510;
    let x1511 = x870 * x895;
    s[446] = x1511;
    let x1512 = x87 * x1409;
    s[447] = x1512;
    let x1514 = x1511 - x1512;
    s[448] = x1514;
    let x1515 = x78 * x1454;
    s[449] = x1515;
    let x1516 = x1511 + x1515;
    s[450] = x1516;
    let x1517 = x1514 + x1516;
    s[451] = x1517;
    let x1518 = x871 * x877;
    s[452] = x1518;
    let x1520 = x83 * x1411;
    s[453] = x1520;
    let x1521 = x1520 - x1518;
    s[454] = x1521;
    let x1522 = x79 * x1417;
    s[455] = x1522;
    let x1523 = x1522 - x1518;
    s[456] = x1523;
    let x1524 = x1521 + x1523;
    s[457] = x1524;
    let x1526 = x871 * x895;
    s[458] = x1526;
    let x1527 = x87 * x1411;
    s[459] = x1527;
    let x1528 = x1526 + x1527;
    s[460] = x1528;
    let x1531 = x79 * x1454;
    s[461] = x1531;
    let x1532 = x1531 - x1526;
    s[462] = x1532;
    let x1533 = x1532 - x1528;
    s[463] = x1533;
    let x1534 = x870 * x877;
    s[464] = x1534;
    let x1536 = x83 * x1409;
    s[465] = x1536;
    let x1538 = x1534 + x1536;
    s[466] = x1538;
    let x1540 = x78 * x1417;
    s[467] = x1540;
    let x1541 = x1534 + x1540;
    s[468] = x1541;
    let x1543 = x1538 + x1541;
    s[469] = x1543;
    let x1545 = x1480 + x1490;
    s[470] = x1545;
    let x1546 = x1510 - x1501;
    s[471] = x1546;
    let x1547 = x1517 - x1524;
    s[472] = x1547;
    let x1548 = x1533 + x1543;
    s[473] = x1548;
    let x2536 = x13 * dq[3];
    s[474] = x2536;
    let x2537 = x12 * dq[3];
    s[475] = x2537;
    let x2539 = x15 * dq[4];
    s[476] = x2539;
    let x2540 = x14 * dq[4];
    s[477] = x2540;
    let x2542 = x17 * dq[5];
    s[478] = x2542;
    let x2543 = x16 * dq[5];
    s[479] = x2543;
    let x2545 = x17 * x2540;
    s[480] = x2545;
    let x2547 = x15 * x2543;
    s[481] = x2547;
    let x2549 = x2545 + x2547;
    s[482] = x2549;
    let x2551 = x16 * x2540;
    s[483] = x2551;
    let x2553 = x15 * x2542;
    s[484] = x2553;
    let x2554 = x2553 - x2551;
    s[485] = x2554;
    let x2555 = x17 * x2539;
    s[486] = x2555;
    let x2556 = x14 * x2543;
    s[487] = x2556;
    let x2558 = x2555 - x2556;
    s[488] = x2558;
    let x2559 = x16 * x2539;
    s[489] = x2559;
    let x2560 = x14 * x2542;
    s[490] = x2560;
    let x2561 = x2559 + x2560;
    s[491] = x2561;
    let x2562 = x15 * x2536;
    s[492] = x2562;
    let x2563 = x12 * x2540;
    s[493] = x2563;
    let x2565 = x2562 - x2563;
    s[494] = x2565;
    let x2566 = x15 * x2537;
    s[495] = x2566;
    let x2568 = x13 * x2540;
    s[496] = x2568;
    let x2570 = x2566 + x2568;
    s[497] = x2570;
    let x2572 = x20 * x2536;
    s[498] = x2572;
    let x2573 = x12 * x2558;
    s[499] = x2573;
    let x2574 = x2572 + x2573;
    s[500] = x2574;
    let x2575 = x16 * x2537;
    s[501] = x2575;
    let x2577 = x13 * x2542;
    s[502] = x2577;
    let x2578 = x2577 - x2575;
    s[503] = x2578;
    let x2579 = x20 * x2537;
    s[504] = x2579;
    let x2581 = x13 * x2558;
    s[505] = x2581;
    let x2582 = x2581 - x2579;
    s[506] = x2582;
    let x2583 = x16 * x2536;
    s[507] = x2583;
    let x2584 = x12 * x2542;
    s[508] = x2584;
    let x2585 = x2583 + x2584;
    s[509] = x2585;
    let x2586 = x21 * x2536;
    s[510] = x2586;
    let x2587 = x12 * x2561;
    s[511] = x2587;
    let x2588 = x2586 + x2587;
    s[512] = x2588;
    let x2589 = x17 * x2537;
    s[513] = x2589;
    let x2591 = x13 * x2543;
    s[514] = x2591;
    let x2593 = x2589 + x2591;
    s[515] = x2593;
    let x2595 = x21 * x2537;
    s[516] = x2595;
    let x2597 = x13 * x2561;
    s[517] = x2597;
    let x2598 = x2597 - x2595;
    s[518] = x2598;
    let x2599 = x17 * x2536;
    s[519] = x2599;
    let x2600 = x12 * x2543;
    s[520] = x2600;
    let x2602 = x2599 - x2600;
    s[521] = x2602;
    let x2604 = x2574 - x2578;
    s[522] = x2604;
    let x2605 = x2582 + x2585;
    s[523] = x2605;
    let x2606 = x2588 - x2593;
    s[524] = x2606;
    let x2608 = x2598 - x2602;
    s[525] = x2608;
    let x2610 = x46 * dq[9];
    s[526] = x2610;
    let x2611 = x45 * dq[9];
    s[527] = x2611;
    let x2613 = x48 * dq[10];
    s[528] = x2613;
    let x2614 = x47 * dq[10];
    s[529] = x2614;
    let x2616 = x50 * dq[11];
    s[530] = x2616;
    let x2617 = x49 * dq[11];
    s[531] = x2617;
    let x2619 = x50 * x2614;
    s[532] = x2619;
    let x2621 = x48 * x2617;
    s[533] = x2621;
    let x2623 = x2619 + x2621;
    s[534] = x2623;
    let x2625 = x49 * x2614;
    s[535] = x2625;
    let x2627 = x48 * x2616;
    s[536] = x2627;
    let x2628 = x2627 - x2625;
    s[537] = x2628;
    let x2629 = x50 * x2613;
    s[538] = x2629;
    let x2630 = x47 * x2617;
    s[539] = x2630;
    let x2632 = x2629 - x2630;
    s[540] = x2632;
    let x2633 = x49 * x2613;
    s[541] = x2633;
    let x2634 = x47 * x2616;
    s[542] = x2634;
    let x2635 = x2633 + x2634;
    s[543] = x2635;
    let x2636 = x48 * x2610;
    s[544] = x2636;
    let x2637 = x45 * x2614;
    s[545] = x2637;
    let x2639 = x2636 - x2637;
    s[546] = x2639;
    let x2640 = x48 * x2611;
    s[547] = x2640;
    let x2642 = x46 * x2614;
    s[548] = x2642;
    let x2644 = x2640 + x2642;
    s[549] = x2644;
    let x2646 = x53 * x2610;
    s[550] = x2646;
    let x2647 = x45 * x2632;
    s[551] = x2647;
    let x2648 = x2646 + x2647;
    s[552] = x2648;
    let x2649 = x49 * x2611;
    s[553] = x2649;
    let x2651 = x46 * x2616;
    s[554] = x2651;
    let x2652 = x2651 - x2649;
    s[555] = x2652;
    let x2653 = x53 * x2611;
    s[556] = x2653;
    let x2655 = x46 * x2632;
    s[557] = x2655;
    let x2656 = x2655 - x2653;
    s[558] = x2656;
    let x2657 = x49 * x2610;
    s[559] = x2657;
    let x2658 = x45 * x2616;
    s[560] = x2658;
    let x2659 = x2657 + x2658;
    s[561] = x2659;
    let x2660 = x54 * x2610;
    s[562] = x2660;
    let x2661 = x45 * x2635;
    s[563] = x2661;
    let x2662 = x2660 + x2661;
    s[564] = x2662;
    let x2663 = x50 * x2611;
    s[565] = x2663;
    let x2665 = x46 * x2617;
    s[566] = x2665;
    let x2667 = x2663 + x2665;
    s[567] = x2667;
    let x2669 = x54 * x2611;
    s[568] = x2669;
    let x2671 = x46 * x2635;
    s[569] = x2671;
    let x2672 = x2671 - x2669;
    s[570] = x2672;
    let x2673 = x50 * x2610;
    s[571] = x2673;
    let x2674 = x45 * x2617;
    s[572] = x2674;
    let x2676 = x2673 - x2674;
    s[573] = x2676;
    let x2678 = x2648 - x2652;
    s[574] = x2678;
    let x2679 = x2656 + x2659;
    s[575] = x2679;
    let x2680 = x2662 - x2667;
    s[576] = x2680;
    let x2682 = x2672 - x2676;
    s[577] = x2682;
    let x2683 = x79 * dq[15];
    s[578] = x2683;
    let x2684 = x78 * dq[15];
    s[579] = x2684;
    let x2686 = x81 * dq[16];
    s[580] = x2686;
    let x2687 = x80 * dq[16];
    s[581] = x2687;
    let x2689 = x83 * dq[17];
    s[582] = x2689;
    let x2690 = x82 * dq[17];
    s[583] = x2690;
    let x2692 = x83 * x2687;
    s[584] = x2692;
    let x2694 = x81 * x2690;
    s[585] = x2694;
    let x2696 = x2692 + x2694;
    s[586] = x2696;
    let x2698 = x82 * x2687;
    s[587] = x2698;
    let x2700 = x81 * x2689;
    s[588] = x2700;
    let x2701 = x2700 - x2698;
    s[589] = x2701;
    let x2702 = x83 * x2686;
    s[590] = x2702;
    let x2703 = x80 * x2690;
    s[591] = x2703;
    let x2705 = x2702 - x2703;
    s[592] = x2705;
    let x2706 = x82 * x2686;
    s[593] = x2706;
    let x2707 = x80 * x2689;
    s[594] = x2707;
    let x2708 = x2706 + x2707;
    s[595] = x2708;
    let x2709 = x81 * x2683;
    s[596] = x2709;
    let x2710 = x78 * x2687;
    s[597] = x2710;
    let x2712 = x2709 - x2710;
    s[598] = x2712;
    let x2713 = x81 * x2684;
    s[599] = x2713;
}
#[inline(never)]
fn kinematic_tangents_shared_1(
    _k: &[f64; 23],
    _q: &[f64; 18],
    qd: &[f64; 18],
    _t: f64,
    _dq: &[f64; 18],
    dqd: &[f64; 18],
    dp: &[f64; 33],
    s: &mut [f64; 1544],
) {
    let x2715 = s[50] * s[581];
    s[600] = x2715;
    let x2717 = s[599] + x2715;
    s[601] = x2717;
    let x2719 = s[57] * s[578];
    s[602] = x2719;
    let x2720 = s[49] * s[592];
    s[603] = x2720;
    let x2721 = x2719 + x2720;
    s[604] = x2721;
    let x2722 = s[53] * s[579];
    s[605] = x2722;
    let x2724 = s[50] * s[582];
    s[606] = x2724;
    let x2725 = x2724 - x2722;
    s[607] = x2725;
    let x2726 = s[57] * s[579];
    s[608] = x2726;
    let x2728 = s[50] * s[592];
    s[609] = x2728;
    let x2729 = x2728 - x2726;
    s[610] = x2729;
    let x2730 = s[53] * s[578];
    s[611] = x2730;
    let x2731 = s[49] * s[582];
    s[612] = x2731;
    let x2732 = x2730 + x2731;
    s[613] = x2732;
    let x2733 = s[58] * s[578];
    s[614] = x2733;
    let x2734 = s[49] * s[595];
    s[615] = x2734;
    let x2735 = x2733 + x2734;
    s[616] = x2735;
    let x2736 = s[54] * s[579];
    s[617] = x2736;
    let x2738 = s[50] * s[583];
    s[618] = x2738;
    let x2740 = x2736 + x2738;
    s[619] = x2740;
    let x2742 = s[58] * s[579];
    s[620] = x2742;
    let x2744 = s[50] * s[595];
    s[621] = x2744;
    let x2745 = x2744 - x2742;
    s[622] = x2745;
    let x2746 = s[54] * s[578];
    s[623] = x2746;
    let x2747 = s[49] * s[583];
    s[624] = x2747;
    let x2749 = x2746 - x2747;
    s[625] = x2749;
    let x2751 = x2721 - x2725;
    s[626] = x2751;
    let x2752 = x2729 + x2732;
    s[627] = x2752;
    let x2753 = x2735 - x2740;
    s[628] = x2753;
    let x2755 = x2745 - x2749;
    s[629] = x2755;
    let x2770 = 0.00000000000000006123233995736766 * s[482];
    s[630] = x2770;
    let x2773 = s[522] + x2770;
    s[631] = x2773;
    let x2775 = 0.00000000000000006123233995736766 * s[485];
    s[632] = x2775;
    let x2777 = x2775 - s[524];
    s[633] = x2777;
    let x2778 = 0.00000000000000006123233995736766 * s[476];
    s[634] = x2778;
    let x2779 = s[494] + x2778;
    s[635] = x2779;
    let x2780 = 0.00000000000000006123233995736766 * s[522];
    s[636] = x2780;
    let x2781 = x2780 - s[482];
    s[637] = x2781;
    let x2782 = 0.00000000000000006123233995736766 * s[524];
    s[638] = x2782;
    let x2783 = s[485] + x2782;
    s[639] = x2783;
    let x2784 = 0.00000000000000006123233995736766 * s[494];
    s[640] = x2784;
    let x2785 = x2784 - s[476];
    s[641] = x2785;
    let x2877 = s[31] * dp[22];
    s[642] = x2877;
    let x2880 = s[45] * dp[23];
    s[643] = x2880;
    let x2884 = s[32] * dp[22];
    s[644] = x2884;
    let x2887 = s[47] * dp[23];
    s[645] = x2887;
    let x2891 = s[27] * dp[22];
    s[646] = x2891;
    let x2895 = s[35] * dp[23];
    s[647] = x2895;
    let x2900 = s[31] * dp[23];
    s[648] = x2900;
    let x2904 = s[45] * dp[22];
    s[649] = x2904;
    let x2908 = s[32] * dp[23];
    s[650] = x2908;
    let x2912 = s[47] * dp[22];
    s[651] = x2912;
    let x2916 = s[27] * dp[23];
    s[652] = x2916;
    let x2919 = s[35] * dp[22];
    s[653] = x2919;
    let x3055 = s[3] * s[474];
    s[654] = x3055;
    let x3056 = s[1] * s[476];
    s[655] = x3056;
    let x3057 = x3055 + x3056;
    s[656] = x3057;
    let x3059 = s[7] * s[474];
    s[657] = x3059;
    let x3060 = s[1] * s[482];
    s[658] = x3060;
    let x3062 = x3059 - x3060;
    s[659] = x3062;
    let x3069 = s[8] * s[474];
    s[660] = x3069;
    let x3070 = s[1] * s[485];
    s[661] = x3070;
    let x3071 = x3069 + x3070;
    s[662] = x3071;
    let x3086 = 0.00000000000000006123233995736766 * s[488];
    s[663] = x3086;
    let x3087 = x3062 + x3086;
    s[664] = x3087;
    let x3088 = 0.00000000000000006123233995736766 * s[491];
    s[665] = x3088;
    let x3089 = x3071 + x3088;
    s[666] = x3089;
    let x3148 = s[524] - x2775;
    s[667] = x3148;
    let x3172 = s[555] - s[552];
    s[668] = x3172;
    let x3253 = s[27] * s[526];
    s[669] = x3253;
    let x3254 = s[25] * s[528];
    s[670] = x3254;
    let x3255 = x3253 + x3254;
    s[671] = x3255;
    let x3256 = s[27] * s[527];
    s[672] = x3256;
    let x3258 = s[26] * s[528];
    s[673] = x3258;
    let x3259 = x3258 - x3256;
    s[674] = x3259;
    let x3260 = s[31] * s[526];
    s[675] = x3260;
    let x3261 = s[25] * s[534];
    s[676] = x3261;
    let x3263 = x3260 - x3261;
    s[677] = x3263;
    let x3264 = s[31] * s[527];
    s[678] = x3264;
    let x3266 = s[26] * s[534];
    s[679] = x3266;
    let x3268 = x3264 + x3266;
    s[680] = x3268;
    let x3270 = s[32] * s[526];
    s[681] = x3270;
    let x3271 = s[25] * s[537];
    s[682] = x3271;
    let x3272 = x3270 + x3271;
    s[683] = x3272;
    let x3273 = s[32] * s[527];
    s[684] = x3273;
    let x3275 = s[26] * s[537];
    s[685] = x3275;
    let x3276 = x3275 - x3273;
    s[686] = x3276;
    let x3412 = s[573] - s[570];
    s[687] = x3412;
    let x3445 = x2725 - x2721;
    s[688] = x3445;
    let x3499 = s[51] * s[578];
    s[689] = x3499;
    let x3500 = s[49] * s[580];
    s[690] = x3500;
    let x3501 = x3499 + x3500;
    s[691] = x3501;
    let x3502 = s[51] * s[579];
    s[692] = x3502;
    let x3504 = s[50] * s[580];
    s[693] = x3504;
    let x3505 = x3504 - x3502;
    s[694] = x3505;
    let x3506 = s[55] * s[578];
    s[695] = x3506;
    let x3507 = s[49] * s[586];
    s[696] = x3507;
    let x3509 = x3506 - x3507;
    s[697] = x3509;
    let x3510 = s[55] * s[579];
    s[698] = x3510;
    let x3512 = s[50] * s[586];
    s[699] = x3512;
    let x3514 = x3510 + x3512;
    s[700] = x3514;
    let x3516 = s[56] * s[578];
    s[701] = x3516;
    let x3517 = s[49] * s[589];
    s[702] = x3517;
    let x3518 = x3516 + x3517;
    s[703] = x3518;
    let x3519 = s[56] * s[579];
    s[704] = x3519;
    let x3521 = s[50] * s[589];
    s[705] = x3521;
    let x3522 = x3521 - x3519;
    s[706] = x3522;
    let x3602 = x2749 - x2745;
    s[707] = x3602;
    let x3620 = qd[3] * s[475];
    s[708] = x3620;
    let x3622 = s[2] * dqd[3];
    s[709] = x3622;
    let x3623 = x3622 - x3620;
    s[710] = x3623;
    let x3624 = qd[3] * s[474];
    s[711] = x3624;
    let x3625 = s[1] * dqd[3];
    s[712] = x3625;
    let x3626 = x3624 + x3625;
    s[713] = x3626;
    let x3627 = qd[4] * s[477];
    s[714] = x3627;
    let x3629 = s[4] * dqd[4];
    s[715] = x3629;
    let x3630 = x3629 - x3627;
    s[716] = x3630;
    let x3631 = qd[4] * s[476];
    s[717] = x3631;
    let x3632 = s[3] * dqd[4];
    s[718] = x3632;
    let x3633 = x3631 + x3632;
    s[719] = x3633;
    let x3634 = qd[5] * s[479];
    s[720] = x3634;
    let x3636 = s[6] * dqd[5];
    s[721] = x3636;
    let x3637 = x3636 - x3634;
    s[722] = x3637;
    let x3638 = qd[5] * s[478];
    s[723] = x3638;
    let x3639 = s[5] * dqd[5];
    s[724] = x3639;
    let x3640 = x3638 + x3639;
    s[725] = x3640;
    let x3641 = s[111] * s[479];
    s[726] = x3641;
    let x3643 = s[6] * x3633;
    s[727] = x3643;
    let x3644 = x3643 - x3641;
    s[728] = x3644;
    let x3645 = s[113] * s[477];
    s[729] = x3645;
    let x3647 = s[4] * x3640;
    s[730] = x3647;
    let x3648 = x3647 - x3645;
    s[731] = x3648;
    let x3649 = x3644 + x3648;
    s[732] = x3649;
    let x3651 = s[111] * s[478];
    s[733] = x3651;
    let x3652 = s[5] * x3633;
    s[734] = x3652;
    let x3653 = x3651 + x3652;
    s[735] = x3653;
    let x3655 = s[112] * s[477];
    s[736] = x3655;
    let x3657 = s[4] * x3637;
    s[737] = x3657;
    let x3658 = x3657 - x3655;
    s[738] = x3658;
    let x3659 = x3658 - x3653;
    s[739] = x3659;
    let x3660 = s[110] * s[479];
    s[740] = x3660;
    let x3662 = s[6] * x3630;
    s[741] = x3662;
    let x3663 = x3662 - x3660;
    s[742] = x3663;
    let x3664 = s[113] * s[476];
    s[743] = x3664;
    let x3665 = s[3] * x3640;
    s[744] = x3665;
    let x3666 = x3664 + x3665;
    s[745] = x3666;
    let x3668 = x3663 - x3666;
    s[746] = x3668;
    let x3669 = s[110] * s[478];
    s[747] = x3669;
    let x3670 = s[5] * x3630;
    s[748] = x3670;
    let x3671 = x3669 + x3670;
    s[749] = x3671;
    let x3672 = s[112] * s[476];
    s[750] = x3672;
    let x3673 = s[3] * x3637;
    s[751] = x3673;
    let x3674 = x3672 + x3673;
    s[752] = x3674;
    let x3675 = x3671 + x3674;
    s[753] = x3675;
    let x3676 = s[108] * s[477];
    s[754] = x3676;
    let x3678 = s[4] * x3623;
    s[755] = x3678;
    let x3679 = x3678 - x3676;
    s[756] = x3679;
    let x3680 = s[111] * s[474];
    s[757] = x3680;
    let x3681 = s[1] * x3633;
    s[758] = x3681;
    let x3682 = x3680 + x3681;
    s[759] = x3682;
    let x3684 = x3679 - x3682;
    s[760] = x3684;
    let x3685 = s[108] * s[488];
    s[761] = x3685;
    let x3686 = s[9] * x3623;
    s[762] = x3686;
    let x3687 = x3685 + x3686;
    s[763] = x3687;
    let x3688 = s[122] * s[474];
    s[764] = x3688;
    let x3689 = s[1] * x3668;
    s[765] = x3689;
    let x3690 = x3688 + x3689;
    s[766] = x3690;
    let x3691 = x3687 + x3690;
    s[767] = x3691;
    let x3692 = s[109] * s[478];
    s[768] = x3692;
    let x3693 = s[5] * x3626;
    s[769] = x3693;
    let x3694 = x3692 + x3693;
    s[770] = x3694;
    let x3696 = s[112] * s[475];
    s[771] = x3696;
    let x3698 = s[2] * x3637;
    s[772] = x3698;
    let x3699 = x3698 - x3696;
    s[773] = x3699;
    let x3700 = x3699 - x3694;
    s[774] = x3700;
    let x3701 = s[108] * s[491];
    s[775] = x3701;
    let x3702 = s[10] * x3623;
    s[776] = x3702;
    let x3703 = x3701 + x3702;
    s[777] = x3703;
    let x3704 = s[125] * s[474];
    s[778] = x3704;
    let x3705 = s[1] * x3675;
    s[779] = x3705;
    let x3706 = x3704 + x3705;
    s[780] = x3706;
    let x3707 = x3703 + x3706;
    s[781] = x3707;
    let x3708 = s[109] * s[479];
    s[782] = x3708;
    let x3710 = s[6] * x3626;
    s[783] = x3710;
    let x3711 = x3710 - x3708;
    s[784] = x3711;
    let x3712 = s[113] * s[475];
    s[785] = x3712;
    let x3714 = s[2] * x3640;
    s[786] = x3714;
    let x3715 = x3714 - x3712;
    s[787] = x3715;
    let x3716 = x3711 + x3715;
    s[788] = x3716;
    let x3719 = x3691 - x3700;
    s[789] = x3719;
    let x3720 = x3707 - x3716;
    s[790] = x3720;
    let x3722 = qd[9] * s[527];
    s[791] = x3722;
    let x3724 = s[26] * dqd[9];
    s[792] = x3724;
    let x3725 = x3724 - x3722;
    s[793] = x3725;
    let x3726 = qd[9] * s[526];
    s[794] = x3726;
    let x3727 = s[25] * dqd[9];
    s[795] = x3727;
    let x3728 = x3726 + x3727;
    s[796] = x3728;
    let x3729 = qd[10] * s[529];
    s[797] = x3729;
    let x3731 = s[28] * dqd[10];
    s[798] = x3731;
    let x3732 = x3731 - x3729;
    s[799] = x3732;
    let x3733 = qd[10] * s[528];
    s[800] = x3733;
    let x3734 = s[27] * dqd[10];
    s[801] = x3734;
    let x3735 = x3733 + x3734;
    s[802] = x3735;
    let x3736 = qd[11] * s[531];
    s[803] = x3736;
    let x3738 = s[30] * dqd[11];
    s[804] = x3738;
    let x3739 = x3738 - x3736;
    s[805] = x3739;
    let x3740 = qd[11] * s[530];
    s[806] = x3740;
    let x3741 = s[29] * dqd[11];
    s[807] = x3741;
    let x3742 = x3740 + x3741;
    s[808] = x3742;
    let x3743 = s[146] * s[531];
    s[809] = x3743;
    let x3745 = s[30] * x3735;
    s[810] = x3745;
    let x3746 = x3745 - x3743;
    s[811] = x3746;
    let x3747 = s[148] * s[529];
    s[812] = x3747;
    let x3749 = s[28] * x3742;
    s[813] = x3749;
    let x3750 = x3749 - x3747;
    s[814] = x3750;
    let x3751 = x3746 + x3750;
    s[815] = x3751;
    let x3752 = s[146] * s[530];
    s[816] = x3752;
    let x3753 = s[29] * x3735;
    s[817] = x3753;
    let x3754 = x3752 + x3753;
    s[818] = x3754;
    let x3756 = s[147] * s[529];
    s[819] = x3756;
    let x3758 = s[28] * x3739;
    s[820] = x3758;
    let x3759 = x3758 - x3756;
    s[821] = x3759;
    let x3760 = x3759 - x3754;
    s[822] = x3760;
    let x3761 = s[145] * s[531];
    s[823] = x3761;
    let x3763 = s[30] * x3732;
    s[824] = x3763;
    let x3764 = x3763 - x3761;
    s[825] = x3764;
    let x3765 = s[148] * s[528];
    s[826] = x3765;
    let x3766 = s[27] * x3742;
    s[827] = x3766;
    let x3767 = x3765 + x3766;
    s[828] = x3767;
    let x3769 = x3764 - x3767;
    s[829] = x3769;
    let x3770 = s[145] * s[530];
    s[830] = x3770;
    let x3771 = s[29] * x3732;
    s[831] = x3771;
    let x3772 = x3770 + x3771;
    s[832] = x3772;
    let x3773 = s[147] * s[528];
    s[833] = x3773;
    let x3774 = s[27] * x3739;
    s[834] = x3774;
    let x3775 = x3773 + x3774;
    s[835] = x3775;
    let x3776 = x3772 + x3775;
    s[836] = x3776;
    let x3777 = s[143] * s[529];
    s[837] = x3777;
    let x3779 = s[28] * x3725;
    s[838] = x3779;
    let x3780 = x3779 - x3777;
    s[839] = x3780;
    let x3781 = s[146] * s[526];
    s[840] = x3781;
    let x3782 = s[25] * x3735;
    s[841] = x3782;
    let x3783 = x3781 + x3782;
    s[842] = x3783;
    let x3785 = x3780 - x3783;
    s[843] = x3785;
    let x3786 = s[144] * s[529];
    s[844] = x3786;
    let x3788 = s[28] * x3728;
    s[845] = x3788;
    let x3789 = x3788 - x3786;
    s[846] = x3789;
    let x3790 = s[146] * s[527];
    s[847] = x3790;
    let x3792 = s[26] * x3735;
    s[848] = x3792;
    let x3793 = x3792 - x3790;
    s[849] = x3793;
    let x3794 = x3789 + x3793;
    s[850] = x3794;
    let x3795 = s[143] * s[540];
    s[851] = x3795;
    let x3796 = s[33] * x3725;
    s[852] = x3796;
    let x3797 = x3795 + x3796;
    s[853] = x3797;
    let x3798 = s[157] * s[526];
    s[854] = x3798;
    let x3799 = s[25] * x3769;
    s[855] = x3799;
    let x3800 = x3798 + x3799;
    s[856] = x3800;
    let x3801 = x3797 + x3800;
    s[857] = x3801;
    let x3802 = s[144] * s[530];
    s[858] = x3802;
    let x3803 = s[29] * x3728;
    s[859] = x3803;
    let x3804 = x3802 + x3803;
    s[860] = x3804;
    let x3806 = s[147] * s[527];
    s[861] = x3806;
    let x3808 = s[26] * x3739;
    s[862] = x3808;
    let x3809 = x3808 - x3806;
    s[863] = x3809;
    let x3810 = x3809 - x3804;
    s[864] = x3810;
    let x3811 = s[144] * s[540];
    s[865] = x3811;
    let x3812 = s[33] * x3728;
    s[866] = x3812;
    let x3813 = x3811 + x3812;
    s[867] = x3813;
    let x3815 = s[157] * s[527];
    s[868] = x3815;
    let x3817 = s[26] * x3769;
    s[869] = x3817;
    let x3818 = x3817 - x3815;
    s[870] = x3818;
    let x3819 = x3818 - x3813;
    s[871] = x3819;
    let x3820 = s[143] * s[530];
    s[872] = x3820;
    let x3821 = s[29] * x3725;
    s[873] = x3821;
    let x3822 = x3820 + x3821;
    s[874] = x3822;
    let x3823 = s[147] * s[526];
    s[875] = x3823;
    let x3824 = s[25] * x3739;
    s[876] = x3824;
    let x3825 = x3823 + x3824;
    s[877] = x3825;
    let x3826 = x3822 + x3825;
    s[878] = x3826;
    let x3827 = s[143] * s[543];
    s[879] = x3827;
    let x3828 = s[34] * x3725;
    s[880] = x3828;
    let x3829 = x3827 + x3828;
    s[881] = x3829;
    let x3830 = s[160] * s[526];
    s[882] = x3830;
    let x3831 = s[25] * x3776;
    s[883] = x3831;
    let x3832 = x3830 + x3831;
    s[884] = x3832;
    let x3833 = x3829 + x3832;
    s[885] = x3833;
    let x3834 = s[144] * s[531];
    s[886] = x3834;
    let x3836 = s[30] * x3728;
    s[887] = x3836;
    let x3837 = x3836 - x3834;
    s[888] = x3837;
    let x3838 = s[148] * s[527];
    s[889] = x3838;
    let x3840 = s[26] * x3742;
    s[890] = x3840;
    let x3841 = x3840 - x3838;
    s[891] = x3841;
    let x3842 = x3837 + x3841;
    s[892] = x3842;
    let x3844 = s[144] * s[543];
    s[893] = x3844;
    let x3845 = s[34] * x3728;
    s[894] = x3845;
    let x3846 = x3844 + x3845;
    s[895] = x3846;
    let x3848 = s[160] * s[527];
    s[896] = x3848;
    let x3850 = s[26] * x3776;
    s[897] = x3850;
    let x3851 = x3850 - x3848;
    s[898] = x3851;
    let x3852 = x3851 - x3846;
    s[899] = x3852;
    let x3853 = s[143] * s[531];
    s[900] = x3853;
    let x3855 = s[30] * x3725;
    s[901] = x3855;
    let x3856 = x3855 - x3853;
    s[902] = x3856;
    let x3857 = s[148] * s[526];
    s[903] = x3857;
    let x3858 = s[25] * x3742;
    s[904] = x3858;
    let x3859 = x3857 + x3858;
    s[905] = x3859;
    let x3861 = x3856 - x3859;
    s[906] = x3861;
    let x3863 = x3801 - x3810;
    s[907] = x3863;
    let x3864 = x3819 + x3826;
    s[908] = x3864;
    let x3865 = x3833 - x3842;
    s[909] = x3865;
    let x3867 = x3852 - x3861;
    s[910] = x3867;
    let x3868 = qd[15] * s[579];
    s[911] = x3868;
    let x3870 = s[50] * dqd[15];
    s[912] = x3870;
    let x3871 = x3870 - x3868;
    s[913] = x3871;
    let x3872 = qd[15] * s[578];
    s[914] = x3872;
    let x3873 = s[49] * dqd[15];
    s[915] = x3873;
    let x3874 = x3872 + x3873;
    s[916] = x3874;
    let x3875 = qd[16] * s[581];
    s[917] = x3875;
    let x3877 = s[52] * dqd[16];
    s[918] = x3877;
    let x3878 = x3877 - x3875;
    s[919] = x3878;
    let x3879 = qd[16] * s[580];
    s[920] = x3879;
    let x3880 = s[51] * dqd[16];
    s[921] = x3880;
    let x3881 = x3879 + x3880;
    s[922] = x3881;
    let x3882 = qd[17] * s[583];
    s[923] = x3882;
    let x3884 = s[54] * dqd[17];
    s[924] = x3884;
    let x3885 = x3884 - x3882;
    s[925] = x3885;
    let x3886 = qd[17] * s[582];
    s[926] = x3886;
    let x3887 = s[53] * dqd[17];
    s[927] = x3887;
    let x3888 = x3886 + x3887;
    s[928] = x3888;
    let x3889 = s[197] * s[583];
    s[929] = x3889;
    let x3891 = s[54] * x3878;
    s[930] = x3891;
    let x3892 = x3891 - x3889;
    s[931] = x3892;
    let x3893 = s[200] * s[580];
    s[932] = x3893;
    let x3894 = s[51] * x3888;
    s[933] = x3894;
    let x3895 = x3893 + x3894;
    s[934] = x3895;
    let x3897 = x3892 - x3895;
    s[935] = x3897;
    let x3898 = s[197] * s[582];
    s[936] = x3898;
    let x3899 = s[53] * x3878;
    s[937] = x3899;
    let x3900 = x3898 + x3899;
    s[938] = x3900;
    let x3901 = s[199] * s[580];
    s[939] = x3901;
    let x3902 = s[51] * x3885;
    s[940] = x3902;
    let x3903 = x3901 + x3902;
    s[941] = x3903;
    let x3904 = x3900 + x3903;
    s[942] = x3904;
    let x3914 = s[196] * s[581];
    s[943] = x3914;
    let x3916 = s[52] * x3874;
    s[944] = x3916;
    let x3917 = x3916 - x3914;
    s[945] = x3917;
    let x3918 = s[198] * s[579];
    s[946] = x3918;
    let x3920 = s[50] * x3881;
    s[947] = x3920;
    let x3921 = x3920 - x3918;
    s[948] = x3921;
    let x3922 = x3917 + x3921;
    s[949] = x3922;
    let x3923 = s[196] * s[592];
    s[950] = x3923;
    let x3924 = s[57] * x3874;
    s[951] = x3924;
    let x3925 = x3923 + x3924;
    s[952] = x3925;
    let x3927 = s[203] * s[579];
    s[953] = x3927;
    let x3929 = s[50] * x3897;
    s[954] = x3929;
    let x3930 = x3929 - x3927;
    s[955] = x3930;
    let x3931 = x3930 - x3925;
    s[956] = x3931;
    let x3932 = s[195] * s[582];
    s[957] = x3932;
    let x3933 = s[53] * x3871;
    s[958] = x3933;
    let x3934 = x3932 + x3933;
    s[959] = x3934;
    let x3935 = s[199] * s[578];
    s[960] = x3935;
    let x3936 = s[49] * x3885;
    s[961] = x3936;
    let x3937 = x3935 + x3936;
    s[962] = x3937;
    let x3938 = x3934 + x3937;
    s[963] = x3938;
    let x3939 = s[196] * s[595];
    s[964] = x3939;
    let x3940 = s[58] * x3874;
    s[965] = x3940;
    let x3941 = x3939 + x3940;
    s[966] = x3941;
    let x3943 = s[206] * s[579];
    s[967] = x3943;
    let x3945 = s[50] * x3904;
    s[968] = x3945;
    let x3946 = x3945 - x3943;
    s[969] = x3946;
    let x3947 = x3946 - x3941;
    s[970] = x3947;
    let x3948 = s[195] * s[583];
    s[971] = x3948;
    let x3950 = s[54] * x3871;
    s[972] = x3950;
    let x3951 = x3950 - x3948;
    s[973] = x3951;
    let x3952 = s[200] * s[578];
    s[974] = x3952;
    let x3953 = s[49] * x3888;
    s[975] = x3953;
    let x3954 = x3952 + x3953;
    s[976] = x3954;
    let x3956 = x3951 - x3954;
    s[977] = x3956;
    let x3957 = x3931 + x3938;
    s[978] = x3957;
    let x3959 = x3947 - x3956;
    s[979] = x3959;
    let x3960 = 0.00000000000000006123233995736766 * x3649;
    s[980] = x3960;
    let x3961 = x3719 + x3960;
    s[981] = x3961;
    let x3962 = 0.00000000000000006123233995736766 * x3659;
    s[982] = x3962;
    let x3964 = x3962 - x3720;
    s[983] = x3964;
    let x4025 = s[109] * dqd[3];
    s[984] = x4025;
    let x4026 = qd[3] * x3626;
    s[985] = x4026;
    let x4027 = x4025 + x4026;
    s[986] = x4027;
    let x4028 = s[108] * dqd[3];
    s[987] = x4028;
    let x4029 = qd[3] * x3623;
    s[988] = x4029;
    let x4030 = x4028 + x4029;
    s[989] = x4030;
    let x4031 = s[111] * dqd[4];
    s[990] = x4031;
    let x4032 = qd[4] * x3633;
    s[991] = x4032;
    let x4033 = x4031 + x4032;
    s[992] = x4033;
    let x4034 = s[110] * dqd[4];
    s[993] = x4034;
    let x4035 = qd[4] * x3630;
    s[994] = x4035;
    let x4036 = x4034 + x4035;
    s[995] = x4036;
    let x4037 = s[113] * dqd[5];
    s[996] = x4037;
    let x4038 = qd[5] * x3640;
    s[997] = x4038;
    let x4039 = x4037 + x4038;
    s[998] = x4039;
    let x4040 = s[112] * dqd[5];
    s[999] = x4040;
    let x4041 = qd[5] * x3637;
    s[1000] = x4041;
    let x4042 = x4040 + x4041;
    s[1001] = x4042;
    let x4043 = s[113] * x3633;
    s[1002] = x4043;
    let x4044 = s[111] * x3640;
    s[1003] = x4044;
    let x4045 = x4043 + x4044;
    s[1004] = x4045;
    let x4047 = s[227] * s[479];
    s[1005] = x4047;
    let x4049 = s[6] * x4036;
    s[1006] = x4049;
    let x4050 = x4049 - x4047;
    s[1007] = x4050;
    let x4051 = x4050 - x4045;
    s[1008] = x4051;
    let x4052 = s[229] * s[477];
    s[1009] = x4052;
    let x4054 = s[4] * x4042;
    s[1010] = x4054;
    let x4055 = x4054 - x4052;
    s[1011] = x4055;
    let x4056 = x4055 - x4045;
    s[1012] = x4056;
    let x4057 = x4051 + x4056;
    s[1013] = x4057;
    let x4059 = s[112] * x3633;
    s[1014] = x4059;
    let x4060 = s[111] * x3637;
    s[1015] = x4060;
    let x4061 = x4059 + x4060;
    s[1016] = x4061;
    let x4062 = s[227] * s[478];
    s[1017] = x4062;
    let x4063 = s[5] * x4036;
    s[1018] = x4063;
    let x4064 = x4062 + x4063;
    s[1019] = x4064;
    let x4065 = x4061 + x4064;
    s[1020] = x4065;
    let x4066 = s[228] * s[477];
    s[1021] = x4066;
    let x4068 = s[4] * x4039;
    s[1022] = x4068;
    let x4069 = x4068 - x4066;
    s[1023] = x4069;
    let x4070 = x4061 + x4069;
    s[1024] = x4070;
    let x4071 = x4065 + x4070;
    s[1025] = x4071;
    let x4073 = s[113] * x3630;
    s[1026] = x4073;
    let x4074 = s[110] * x3640;
    s[1027] = x4074;
    let x4075 = x4073 + x4074;
    s[1028] = x4075;
    let x4076 = s[226] * s[479];
    s[1029] = x4076;
    let x4078 = s[6] * x4033;
    s[1030] = x4078;
    let x4079 = x4078 - x4076;
    s[1031] = x4079;
    let x4080 = x4075 + x4079;
    s[1032] = x4080;
    let x4081 = s[229] * s[476];
    s[1033] = x4081;
    let x4082 = s[3] * x4042;
    s[1034] = x4082;
    let x4083 = x4081 + x4082;
    s[1035] = x4083;
    let x4084 = x4075 + x4083;
    s[1036] = x4084;
    let x4085 = x4080 + x4084;
    s[1037] = x4085;
    let x4086 = s[112] * x3630;
    s[1038] = x4086;
    let x4087 = s[110] * x3637;
    s[1039] = x4087;
    let x4088 = x4086 + x4087;
    s[1040] = x4088;
    let x4089 = s[226] * s[478];
    s[1041] = x4089;
    let x4090 = s[5] * x4033;
    s[1042] = x4090;
    let x4091 = x4089 + x4090;
    s[1043] = x4091;
    let x4093 = x4088 - x4091;
    s[1044] = x4093;
    let x4094 = s[228] * s[476];
    s[1045] = x4094;
    let x4095 = s[3] * x4039;
    s[1046] = x4095;
    let x4096 = x4094 + x4095;
    s[1047] = x4096;
    let x4098 = x4088 - x4096;
    s[1048] = x4098;
    let x4099 = x4093 + x4098;
    s[1049] = x4099;
    let x4100 = s[111] * x3623;
    s[1050] = x4100;
    let x4101 = s[108] * x3633;
    s[1051] = x4101;
    let x4102 = x4100 + x4101;
    s[1052] = x4102;
    let x4103 = s[224] * s[477];
    s[1053] = x4103;
    let x4105 = s[4] * x4027;
    s[1054] = x4105;
    let x4106 = x4105 - x4103;
    s[1055] = x4106;
    let x4107 = x4102 + x4106;
    s[1056] = x4107;
    let x4108 = s[227] * s[474];
    s[1057] = x4108;
    let x4109 = s[1] * x4036;
    s[1058] = x4109;
    let x4110 = x4108 + x4109;
    s[1059] = x4110;
    let x4111 = x4102 + x4110;
    s[1060] = x4111;
    let x4112 = x4107 + x4111;
    s[1061] = x4112;
    let x4113 = s[122] * x3623;
    s[1062] = x4113;
    let x4114 = s[108] * x3668;
    s[1063] = x4114;
    let x4115 = x4113 + x4114;
    s[1064] = x4115;
    let x4116 = s[224] * s[488];
    s[1065] = x4116;
    let x4117 = s[9] * x4027;
    s[1066] = x4117;
    let x4118 = x4116 + x4117;
    s[1067] = x4118;
    let x4120 = x4115 - x4118;
    s[1068] = x4120;
    let x4121 = s[247] * s[474];
    s[1069] = x4121;
    let x4122 = s[1] * x4085;
    s[1070] = x4122;
    let x4123 = x4121 + x4122;
    s[1071] = x4123;
    let x4125 = x4115 - x4123;
    s[1072] = x4125;
    let x4126 = x4120 + x4125;
    s[1073] = x4126;
    let x4127 = s[112] * x3626;
    s[1074] = x4127;
    let x4128 = s[109] * x3637;
    s[1075] = x4128;
    let x4129 = x4127 + x4128;
    s[1076] = x4129;
    let x4130 = s[225] * s[478];
    s[1077] = x4130;
    let x4131 = s[5] * x4030;
    s[1078] = x4131;
    let x4132 = x4130 + x4131;
    s[1079] = x4132;
    let x4133 = x4129 + x4132;
    s[1080] = x4133;
    let x4134 = s[228] * s[475];
    s[1081] = x4134;
    let x4136 = s[2] * x4039;
    s[1082] = x4136;
    let x4137 = x4136 - x4134;
    s[1083] = x4137;
    let x4138 = x4129 + x4137;
    s[1084] = x4138;
    let x4139 = x4133 + x4138;
    s[1085] = x4139;
    let x4168 = s[125] * x3623;
    s[1086] = x4168;
    let x4169 = s[108] * x3675;
    s[1087] = x4169;
    let x4170 = x4168 + x4169;
    s[1088] = x4170;
    let x4171 = s[224] * s[491];
    s[1089] = x4171;
    let x4172 = s[10] * x4027;
    s[1090] = x4172;
    let x4173 = x4171 + x4172;
    s[1091] = x4173;
    let x4175 = x4170 - x4173;
    s[1092] = x4175;
    let x4176 = s[253] * s[474];
    s[1093] = x4176;
    let x4177 = s[1] * x4099;
    s[1094] = x4177;
    let x4178 = x4176 + x4177;
    s[1095] = x4178;
    let x4179 = x4170 + x4178;
    s[1096] = x4179;
    let x4180 = x4175 + x4179;
    s[1097] = x4180;
    let x4181 = s[113] * x3626;
    s[1098] = x4181;
    let x4182 = s[109] * x3640;
    s[1099] = x4182;
    let x4183 = x4181 + x4182;
    s[1100] = x4183;
    let x4185 = s[225] * s[479];
    s[1101] = x4185;
    let x4187 = s[6] * x4030;
    s[1102] = x4187;
    let x4188 = x4187 - x4185;
    s[1103] = x4188;
    let x4189 = x4188 - x4183;
    s[1104] = x4189;
    let x4190 = s[229] * s[475];
    s[1105] = x4190;
    let x4192 = s[2] * x4042;
    s[1106] = x4192;
    let x4193 = x4192 - x4190;
    s[1107] = x4193;
    let x4194 = x4193 - x4183;
    s[1108] = x4194;
    let x4195 = x4189 + x4194;
    s[1109] = x4195;
    let x4225 = x4126 + x4139;
    s[1110] = x4225;
    let x4227 = x4180 - x4195;
    s[1111] = x4227;
    let x4229 = s[144] * dqd[9];
    s[1112] = x4229;
    let x4230 = qd[9] * x3728;
    s[1113] = x4230;
    let x4231 = x4229 + x4230;
    s[1114] = x4231;
    let x4232 = s[143] * dqd[9];
    s[1115] = x4232;
    let x4233 = qd[9] * x3725;
    s[1116] = x4233;
    let x4234 = x4232 + x4233;
    s[1117] = x4234;
    let x4235 = s[146] * dqd[10];
    s[1118] = x4235;
    let x4236 = qd[10] * x3735;
    s[1119] = x4236;
    let x4237 = x4235 + x4236;
    s[1120] = x4237;
    let x4238 = s[145] * dqd[10];
    s[1121] = x4238;
    let x4239 = qd[10] * x3732;
    s[1122] = x4239;
    let x4240 = x4238 + x4239;
    s[1123] = x4240;
    let x4241 = s[148] * dqd[11];
    s[1124] = x4241;
    let x4242 = qd[11] * x3742;
    s[1125] = x4242;
    let x4243 = x4241 + x4242;
    s[1126] = x4243;
    let x4244 = s[147] * dqd[11];
    s[1127] = x4244;
    let x4245 = qd[11] * x3739;
    s[1128] = x4245;
    let x4246 = x4244 + x4245;
    s[1129] = x4246;
    let x4247 = s[148] * x3735;
    s[1130] = x4247;
    let x4248 = s[146] * x3742;
    s[1131] = x4248;
    let x4249 = x4247 + x4248;
    s[1132] = x4249;
    let x4251 = s[289] * s[531];
    s[1133] = x4251;
    let x4253 = s[30] * x4240;
    s[1134] = x4253;
    let x4254 = x4253 - x4251;
    s[1135] = x4254;
    let x4255 = x4254 - x4249;
    s[1136] = x4255;
    let x4256 = s[291] * s[529];
    s[1137] = x4256;
    let x4258 = s[28] * x4246;
    s[1138] = x4258;
    let x4259 = x4258 - x4256;
    s[1139] = x4259;
    let x4260 = x4259 - x4249;
    s[1140] = x4260;
    let x4261 = x4255 + x4260;
    s[1141] = x4261;
    let x4262 = s[147] * x3735;
    s[1142] = x4262;
    let x4263 = s[146] * x3739;
    s[1143] = x4263;
    let x4264 = x4262 + x4263;
    s[1144] = x4264;
    let x4265 = s[289] * s[530];
    s[1145] = x4265;
    let x4266 = s[29] * x4240;
    s[1146] = x4266;
    let x4267 = x4265 + x4266;
    s[1147] = x4267;
    let x4268 = x4264 + x4267;
    s[1148] = x4268;
    let x4269 = s[290] * s[529];
    s[1149] = x4269;
    let x4271 = s[28] * x4243;
    s[1150] = x4271;
    let x4272 = x4271 - x4269;
    s[1151] = x4272;
    let x4273 = x4264 + x4272;
    s[1152] = x4273;
    let x4274 = x4268 + x4273;
    s[1153] = x4274;
    let x4275 = s[148] * x3732;
    s[1154] = x4275;
    let x4276 = s[145] * x3742;
    s[1155] = x4276;
    let x4277 = x4275 + x4276;
    s[1156] = x4277;
    let x4278 = s[288] * s[531];
    s[1157] = x4278;
    let x4280 = s[30] * x4237;
    s[1158] = x4280;
    let x4281 = x4280 - x4278;
    s[1159] = x4281;
    let x4282 = x4277 + x4281;
    s[1160] = x4282;
    let x4283 = s[291] * s[528];
    s[1161] = x4283;
    let x4284 = s[27] * x4246;
    s[1162] = x4284;
    let x4285 = x4283 + x4284;
    s[1163] = x4285;
    let x4286 = x4277 + x4285;
    s[1164] = x4286;
    let x4287 = x4282 + x4286;
    s[1165] = x4287;
    let x4288 = s[147] * x3732;
    s[1166] = x4288;
    let x4289 = s[145] * x3739;
    s[1167] = x4289;
    let x4290 = x4288 + x4289;
    s[1168] = x4290;
    let x4291 = s[288] * s[530];
    s[1169] = x4291;
    let x4292 = s[29] * x4237;
    s[1170] = x4292;
    let x4293 = x4291 + x4292;
    s[1171] = x4293;
    let x4295 = x4290 - x4293;
    s[1172] = x4295;
    let x4296 = s[290] * s[528];
    s[1173] = x4296;
    let x4297 = s[27] * x4243;
    s[1174] = x4297;
    let x4298 = x4296 + x4297;
    s[1175] = x4298;
    let x4300 = x4290 - x4298;
    s[1176] = x4300;
    let x4301 = x4295 + x4300;
    s[1177] = x4301;
    let x4302 = s[146] * x3725;
    s[1178] = x4302;
    let x4303 = s[143] * x3735;
    s[1179] = x4303;
    let x4304 = x4302 + x4303;
    s[1180] = x4304;
    let x4305 = s[286] * s[529];
    s[1181] = x4305;
    let x4307 = s[28] * x4231;
    s[1182] = x4307;
    let x4308 = x4307 - x4305;
    s[1183] = x4308;
    let x4309 = x4304 + x4308;
    s[1184] = x4309;
    let x4310 = s[289] * s[526];
    s[1185] = x4310;
    let x4311 = s[25] * x4240;
    s[1186] = x4311;
    let x4312 = x4310 + x4311;
    s[1187] = x4312;
    let x4313 = x4304 + x4312;
    s[1188] = x4313;
    let x4314 = x4309 + x4313;
    s[1189] = x4314;
    let x4315 = s[146] * x3728;
    s[1190] = x4315;
    let x4316 = s[144] * x3735;
    s[1191] = x4316;
    let x4317 = x4315 + x4316;
    s[1192] = x4317;
    let x4319 = s[287] * s[529];
    s[1193] = x4319;
    let x4321 = s[28] * x4234;
    s[1194] = x4321;
    let x4322 = x4321 - x4319;
    s[1195] = x4322;
    let x4323 = x4322 - x4317;
    s[1196] = x4323;
    let x4324 = s[289] * s[527];
    s[1197] = x4324;
    let x4326 = s[26] * x4240;
    s[1198] = x4326;
    let x4327 = x4326 - x4324;
    s[1199] = x4327;
}
#[inline(never)]
fn kinematic_tangents_shared_2(
    k: &[f64; 23],
    _q: &[f64; 18],
    qd: &[f64; 18],
    _t: f64,
    _dq: &[f64; 18],
    dqd: &[f64; 18],
    _dp: &[f64; 33],
    s: &mut [f64; 1544],
) {
    let x4328 = s[1199] - s[1192];
    s[1200] = x4328;
    let x4329 = s[1196] + x4328;
    s[1201] = x4329;
    let x4330 = s[157] * s[793];
    s[1202] = x4330;
    let x4331 = s[143] * s[829];
    s[1203] = x4331;
    let x4332 = x4330 + x4331;
    s[1204] = x4332;
    let x4333 = s[286] * s[540];
    s[1205] = x4333;
    let x4334 = s[33] * s[1114];
    s[1206] = x4334;
    let x4335 = x4333 + x4334;
    s[1207] = x4335;
    let x4337 = x4332 - x4335;
    s[1208] = x4337;
    let x4338 = s[309] * s[526];
    s[1209] = x4338;
    let x4339 = s[25] * s[1165];
    s[1210] = x4339;
    let x4340 = x4338 + x4339;
    s[1211] = x4340;
    let x4342 = x4332 - x4340;
    s[1212] = x4342;
    let x4343 = x4337 + x4342;
    s[1213] = x4343;
    let x4344 = s[147] * s[796];
    s[1214] = x4344;
    let x4345 = s[144] * s[805];
    s[1215] = x4345;
    let x4346 = x4344 + x4345;
    s[1216] = x4346;
    let x4347 = s[287] * s[530];
    s[1217] = x4347;
    let x4348 = s[29] * s[1117];
    s[1218] = x4348;
    let x4349 = x4347 + x4348;
    s[1219] = x4349;
    let x4350 = x4346 + x4349;
    s[1220] = x4350;
    let x4351 = s[290] * s[527];
    s[1221] = x4351;
    let x4353 = s[26] * s[1126];
    s[1222] = x4353;
    let x4354 = x4353 - x4351;
    s[1223] = x4354;
    let x4355 = x4346 + x4354;
    s[1224] = x4355;
    let x4356 = x4350 + x4355;
    s[1225] = x4356;
    let x4357 = s[157] * s[796];
    s[1226] = x4357;
    let x4358 = s[144] * s[829];
    s[1227] = x4358;
    let x4359 = x4357 + x4358;
    s[1228] = x4359;
    let x4360 = s[287] * s[540];
    s[1229] = x4360;
    let x4361 = s[33] * s[1117];
    s[1230] = x4361;
    let x4362 = x4360 + x4361;
    s[1231] = x4362;
    let x4363 = x4359 + x4362;
    s[1232] = x4363;
    let x4364 = s[309] * s[527];
    s[1233] = x4364;
    let x4366 = s[26] * s[1165];
    s[1234] = x4366;
    let x4367 = x4366 - x4364;
    s[1235] = x4367;
    let x4368 = x4359 + x4367;
    s[1236] = x4368;
    let x4369 = x4363 + x4368;
    s[1237] = x4369;
    let x4371 = s[147] * s[793];
    s[1238] = x4371;
    let x4372 = s[143] * s[805];
    s[1239] = x4372;
    let x4373 = x4371 + x4372;
    s[1240] = x4373;
    let x4374 = s[286] * s[530];
    s[1241] = x4374;
    let x4375 = s[29] * s[1114];
    s[1242] = x4375;
    let x4376 = x4374 + x4375;
    s[1243] = x4376;
    let x4378 = x4373 - x4376;
    s[1244] = x4378;
    let x4379 = s[290] * s[526];
    s[1245] = x4379;
    let x4380 = s[25] * s[1126];
    s[1246] = x4380;
    let x4381 = x4379 + x4380;
    s[1247] = x4381;
    let x4383 = x4373 - x4381;
    s[1248] = x4383;
    let x4384 = x4378 + x4383;
    s[1249] = x4384;
    let x4385 = s[160] * s[793];
    s[1250] = x4385;
    let x4386 = s[143] * s[836];
    s[1251] = x4386;
    let x4387 = x4385 + x4386;
    s[1252] = x4387;
    let x4388 = s[286] * s[543];
    s[1253] = x4388;
    let x4389 = s[34] * s[1114];
    s[1254] = x4389;
    let x4390 = x4388 + x4389;
    s[1255] = x4390;
    let x4392 = x4387 - x4390;
    s[1256] = x4392;
    let x4393 = s[315] * s[526];
    s[1257] = x4393;
    let x4394 = s[25] * s[1177];
    s[1258] = x4394;
    let x4395 = x4393 + x4394;
    s[1259] = x4395;
    let x4396 = x4387 + x4395;
    s[1260] = x4396;
    let x4397 = x4392 + x4396;
    s[1261] = x4397;
    let x4398 = s[148] * s[796];
    s[1262] = x4398;
    let x4399 = s[144] * s[808];
    s[1263] = x4399;
    let x4400 = x4398 + x4399;
    s[1264] = x4400;
    let x4402 = s[287] * s[531];
    s[1265] = x4402;
    let x4404 = s[30] * s[1117];
    s[1266] = x4404;
    let x4405 = x4404 - x4402;
    s[1267] = x4405;
    let x4406 = x4405 - x4400;
    s[1268] = x4406;
    let x4407 = s[291] * s[527];
    s[1269] = x4407;
    let x4409 = s[26] * s[1129];
    s[1270] = x4409;
    let x4410 = x4409 - x4407;
    s[1271] = x4410;
    let x4411 = x4410 - x4400;
    s[1272] = x4411;
    let x4412 = x4406 + x4411;
    s[1273] = x4412;
    let x4414 = s[160] * s[796];
    s[1274] = x4414;
    let x4415 = s[144] * s[836];
    s[1275] = x4415;
    let x4416 = x4414 + x4415;
    s[1276] = x4416;
    let x4417 = s[287] * s[543];
    s[1277] = x4417;
    let x4418 = s[34] * s[1117];
    s[1278] = x4418;
    let x4419 = x4417 + x4418;
    s[1279] = x4419;
    let x4420 = x4416 + x4419;
    s[1280] = x4420;
    let x4423 = s[315] * s[527];
    s[1281] = x4423;
    let x4425 = s[26] * s[1177];
    s[1282] = x4425;
    let x4426 = x4425 - x4423;
    s[1283] = x4426;
    let x4427 = x4426 - x4416;
    s[1284] = x4427;
    let x4428 = x4427 - x4420;
    s[1285] = x4428;
    let x4429 = s[148] * s[793];
    s[1286] = x4429;
    let x4430 = s[143] * s[808];
    s[1287] = x4430;
    let x4431 = x4429 + x4430;
    s[1288] = x4431;
    let x4432 = s[286] * s[531];
    s[1289] = x4432;
    let x4434 = s[30] * s[1114];
    s[1290] = x4434;
    let x4435 = x4434 - x4432;
    s[1291] = x4435;
    let x4436 = x4431 + x4435;
    s[1292] = x4436;
    let x4437 = s[291] * s[526];
    s[1293] = x4437;
    let x4438 = s[25] * s[1129];
    s[1294] = x4438;
    let x4439 = x4437 + x4438;
    s[1295] = x4439;
    let x4440 = x4431 + x4439;
    s[1296] = x4440;
    let x4441 = x4436 + x4440;
    s[1297] = x4441;
    let x4442 = x4343 + x4356;
    s[1298] = x4442;
    let x4443 = x4384 - x4369;
    s[1299] = x4443;
    let x4444 = x4397 - x4412;
    s[1300] = x4444;
    let x4445 = x4428 + x4441;
    s[1301] = x4445;
    let x4446 = s[196] * dqd[15];
    s[1302] = x4446;
    let x4447 = qd[15] * s[916];
    s[1303] = x4447;
    let x4448 = x4446 + x4447;
    s[1304] = x4448;
    let x4449 = s[195] * dqd[15];
    s[1305] = x4449;
    let x4450 = qd[15] * s[913];
    s[1306] = x4450;
    let x4451 = x4449 + x4450;
    s[1307] = x4451;
    let x4452 = s[198] * dqd[16];
    s[1308] = x4452;
    let x4453 = qd[16] * s[922];
    s[1309] = x4453;
    let x4454 = x4452 + x4453;
    s[1310] = x4454;
    let x4455 = s[197] * dqd[16];
    s[1311] = x4455;
    let x4456 = qd[16] * s[919];
    s[1312] = x4456;
    let x4457 = x4455 + x4456;
    s[1313] = x4457;
    let x4458 = s[200] * dqd[17];
    s[1314] = x4458;
    let x4459 = qd[17] * s[928];
    s[1315] = x4459;
    let x4460 = x4458 + x4459;
    s[1316] = x4460;
    let x4461 = s[199] * dqd[17];
    s[1317] = x4461;
    let x4462 = qd[17] * s[925];
    s[1318] = x4462;
    let x4463 = x4461 + x4462;
    s[1319] = x4463;
    let x4464 = s[200] * s[922];
    s[1320] = x4464;
    let x4465 = s[198] * s[928];
    s[1321] = x4465;
    let x4466 = x4464 + x4465;
    s[1322] = x4466;
    let x4468 = s[383] * s[583];
    s[1323] = x4468;
    let x4470 = s[54] * x4457;
    s[1324] = x4470;
    let x4471 = x4470 - x4468;
    s[1325] = x4471;
    let x4472 = x4471 - x4466;
    s[1326] = x4472;
    let x4473 = s[385] * s[581];
    s[1327] = x4473;
    let x4475 = s[52] * x4463;
    s[1328] = x4475;
    let x4476 = x4475 - x4473;
    s[1329] = x4476;
    let x4477 = x4476 - x4466;
    s[1330] = x4477;
    let x4478 = x4472 + x4477;
    s[1331] = x4478;
    let x4479 = s[199] * s[922];
    s[1332] = x4479;
    let x4480 = s[198] * s[925];
    s[1333] = x4480;
    let x4481 = x4479 + x4480;
    s[1334] = x4481;
    let x4482 = s[383] * s[582];
    s[1335] = x4482;
    let x4483 = s[53] * x4457;
    s[1336] = x4483;
    let x4484 = x4482 + x4483;
    s[1337] = x4484;
    let x4485 = x4481 + x4484;
    s[1338] = x4485;
    let x4486 = s[384] * s[581];
    s[1339] = x4486;
    let x4488 = s[52] * x4460;
    s[1340] = x4488;
    let x4489 = x4488 - x4486;
    s[1341] = x4489;
    let x4490 = x4481 + x4489;
    s[1342] = x4490;
    let x4491 = x4485 + x4490;
    s[1343] = x4491;
    let x4492 = s[200] * s[919];
    s[1344] = x4492;
    let x4493 = s[197] * s[928];
    s[1345] = x4493;
    let x4494 = x4492 + x4493;
    s[1346] = x4494;
    let x4495 = s[382] * s[583];
    s[1347] = x4495;
    let x4497 = s[54] * x4454;
    s[1348] = x4497;
    let x4498 = x4497 - x4495;
    s[1349] = x4498;
    let x4499 = x4494 + x4498;
    s[1350] = x4499;
    let x4500 = s[385] * s[580];
    s[1351] = x4500;
    let x4501 = s[51] * x4463;
    s[1352] = x4501;
    let x4502 = x4500 + x4501;
    s[1353] = x4502;
    let x4503 = x4494 + x4502;
    s[1354] = x4503;
    let x4504 = x4499 + x4503;
    s[1355] = x4504;
    let x4505 = s[199] * s[919];
    s[1356] = x4505;
    let x4506 = s[197] * s[925];
    s[1357] = x4506;
    let x4507 = x4505 + x4506;
    s[1358] = x4507;
    let x4508 = s[382] * s[582];
    s[1359] = x4508;
    let x4509 = s[53] * x4454;
    s[1360] = x4509;
    let x4510 = x4508 + x4509;
    s[1361] = x4510;
    let x4512 = x4507 - x4510;
    s[1362] = x4512;
    let x4513 = s[384] * s[580];
    s[1363] = x4513;
    let x4514 = s[51] * x4460;
    s[1364] = x4514;
    let x4515 = x4513 + x4514;
    s[1365] = x4515;
    let x4517 = x4507 - x4515;
    s[1366] = x4517;
    let x4518 = x4512 + x4517;
    s[1367] = x4518;
    let x4519 = s[198] * s[913];
    s[1368] = x4519;
    let x4520 = s[195] * s[922];
    s[1369] = x4520;
    let x4521 = x4519 + x4520;
    s[1370] = x4521;
    let x4522 = s[380] * s[581];
    s[1371] = x4522;
    let x4524 = s[52] * x4448;
    s[1372] = x4524;
    let x4525 = x4524 - x4522;
    s[1373] = x4525;
    let x4526 = x4521 + x4525;
    s[1374] = x4526;
    let x4527 = s[383] * s[578];
    s[1375] = x4527;
    let x4528 = s[49] * x4457;
    s[1376] = x4528;
    let x4529 = x4527 + x4528;
    s[1377] = x4529;
    let x4530 = x4521 + x4529;
    s[1378] = x4530;
    let x4531 = x4526 + x4530;
    s[1379] = x4531;
    let x4532 = s[198] * s[916];
    s[1380] = x4532;
    let x4533 = s[196] * s[922];
    s[1381] = x4533;
    let x4534 = x4532 + x4533;
    s[1382] = x4534;
    let x4536 = s[381] * s[581];
    s[1383] = x4536;
    let x4538 = s[52] * x4451;
    s[1384] = x4538;
    let x4539 = x4538 - x4536;
    s[1385] = x4539;
    let x4540 = x4539 - x4534;
    s[1386] = x4540;
    let x4541 = s[383] * s[579];
    s[1387] = x4541;
    let x4543 = s[50] * x4457;
    s[1388] = x4543;
    let x4544 = x4543 - x4541;
    s[1389] = x4544;
    let x4545 = x4544 - x4534;
    s[1390] = x4545;
    let x4546 = x4540 + x4545;
    s[1391] = x4546;
    let x4547 = s[203] * s[913];
    s[1392] = x4547;
    let x4548 = s[195] * s[935];
    s[1393] = x4548;
    let x4549 = x4547 + x4548;
    s[1394] = x4549;
    let x4550 = s[380] * s[592];
    s[1395] = x4550;
    let x4551 = s[57] * x4448;
    s[1396] = x4551;
    let x4552 = x4550 + x4551;
    s[1397] = x4552;
    let x4554 = x4549 - x4552;
    s[1398] = x4554;
    let x4555 = s[403] * s[578];
    s[1399] = x4555;
    let x4556 = s[49] * x4504;
    s[1400] = x4556;
    let x4557 = x4555 + x4556;
    s[1401] = x4557;
    let x4559 = x4549 - x4557;
    s[1402] = x4559;
    let x4560 = x4554 + x4559;
    s[1403] = x4560;
    let x4561 = s[199] * s[916];
    s[1404] = x4561;
    let x4562 = s[196] * s[925];
    s[1405] = x4562;
    let x4563 = x4561 + x4562;
    s[1406] = x4563;
    let x4564 = s[381] * s[582];
    s[1407] = x4564;
    let x4565 = s[53] * x4451;
    s[1408] = x4565;
    let x4566 = x4564 + x4565;
    s[1409] = x4566;
    let x4567 = x4563 + x4566;
    s[1410] = x4567;
    let x4568 = s[384] * s[579];
    s[1411] = x4568;
    let x4570 = s[50] * x4460;
    s[1412] = x4570;
    let x4571 = x4570 - x4568;
    s[1413] = x4571;
    let x4572 = x4563 + x4571;
    s[1414] = x4572;
    let x4573 = x4567 + x4572;
    s[1415] = x4573;
    let x4574 = s[203] * s[916];
    s[1416] = x4574;
    let x4575 = s[196] * s[935];
    s[1417] = x4575;
    let x4576 = x4574 + x4575;
    s[1418] = x4576;
    let x4577 = s[381] * s[592];
    s[1419] = x4577;
    let x4578 = s[57] * x4451;
    s[1420] = x4578;
    let x4579 = x4577 + x4578;
    s[1421] = x4579;
    let x4580 = x4576 + x4579;
    s[1422] = x4580;
    let x4581 = s[403] * s[579];
    s[1423] = x4581;
    let x4583 = s[50] * x4504;
    s[1424] = x4583;
    let x4584 = x4583 - x4581;
    s[1425] = x4584;
    let x4585 = x4576 + x4584;
    s[1426] = x4585;
    let x4586 = x4580 + x4585;
    s[1427] = x4586;
    let x4588 = s[199] * s[913];
    s[1428] = x4588;
    let x4589 = s[195] * s[925];
    s[1429] = x4589;
    let x4590 = x4588 + x4589;
    s[1430] = x4590;
    let x4591 = s[380] * s[582];
    s[1431] = x4591;
    let x4592 = s[53] * x4448;
    s[1432] = x4592;
    let x4593 = x4591 + x4592;
    s[1433] = x4593;
    let x4595 = x4590 - x4593;
    s[1434] = x4595;
    let x4596 = s[384] * s[578];
    s[1435] = x4596;
    let x4597 = s[49] * x4460;
    s[1436] = x4597;
    let x4598 = x4596 + x4597;
    s[1437] = x4598;
    let x4600 = x4590 - x4598;
    s[1438] = x4600;
    let x4601 = x4595 + x4600;
    s[1439] = x4601;
    let x4602 = s[206] * s[913];
    s[1440] = x4602;
    let x4603 = s[195] * s[942];
    s[1441] = x4603;
    let x4604 = x4602 + x4603;
    s[1442] = x4604;
    let x4605 = s[380] * s[595];
    s[1443] = x4605;
    let x4606 = s[58] * x4448;
    s[1444] = x4606;
    let x4607 = x4605 + x4606;
    s[1445] = x4607;
    let x4609 = x4604 - x4607;
    s[1446] = x4609;
    let x4610 = s[409] * s[578];
    s[1447] = x4610;
    let x4611 = s[49] * x4518;
    s[1448] = x4611;
    let x4612 = x4610 + x4611;
    s[1449] = x4612;
    let x4613 = x4604 + x4612;
    s[1450] = x4613;
    let x4614 = x4609 + x4613;
    s[1451] = x4614;
    let x4615 = s[200] * s[916];
    s[1452] = x4615;
    let x4616 = s[196] * s[928];
    s[1453] = x4616;
    let x4617 = x4615 + x4616;
    s[1454] = x4617;
    let x4619 = s[381] * s[583];
    s[1455] = x4619;
    let x4621 = s[54] * x4451;
    s[1456] = x4621;
    let x4622 = x4621 - x4619;
    s[1457] = x4622;
    let x4623 = x4622 - x4617;
    s[1458] = x4623;
    let x4624 = s[385] * s[579];
    s[1459] = x4624;
    let x4626 = s[50] * x4463;
    s[1460] = x4626;
    let x4627 = x4626 - x4624;
    s[1461] = x4627;
    let x4628 = x4627 - x4617;
    s[1462] = x4628;
    let x4629 = x4623 + x4628;
    s[1463] = x4629;
    let x4631 = s[206] * s[916];
    s[1464] = x4631;
    let x4632 = s[196] * s[942];
    s[1465] = x4632;
    let x4633 = x4631 + x4632;
    s[1466] = x4633;
    let x4634 = s[381] * s[595];
    s[1467] = x4634;
    let x4635 = s[58] * x4451;
    s[1468] = x4635;
    let x4636 = x4634 + x4635;
    s[1469] = x4636;
    let x4637 = x4633 + x4636;
    s[1470] = x4637;
    let x4640 = s[409] * s[579];
    s[1471] = x4640;
    let x4642 = s[50] * x4518;
    s[1472] = x4642;
    let x4643 = x4642 - x4640;
    s[1473] = x4643;
    let x4644 = x4643 - x4633;
    s[1474] = x4644;
    let x4645 = x4644 - x4637;
    s[1475] = x4645;
    let x4646 = s[200] * s[913];
    s[1476] = x4646;
    let x4647 = s[195] * s[928];
    s[1477] = x4647;
    let x4648 = x4646 + x4647;
    s[1478] = x4648;
    let x4649 = s[380] * s[583];
    s[1479] = x4649;
    let x4651 = s[54] * x4448;
    s[1480] = x4651;
    let x4652 = x4651 - x4649;
    s[1481] = x4652;
    let x4653 = x4648 + x4652;
    s[1482] = x4653;
    let x4654 = s[385] * s[578];
    s[1483] = x4654;
    let x4655 = s[49] * x4463;
    s[1484] = x4655;
    let x4656 = x4654 + x4655;
    s[1485] = x4656;
    let x4657 = x4648 + x4656;
    s[1486] = x4657;
    let x4658 = x4653 + x4657;
    s[1487] = x4658;
    let x4659 = x4560 + x4573;
    s[1488] = x4659;
    let x4660 = x4601 - x4586;
    s[1489] = x4660;
    let x4661 = x4614 - x4629;
    s[1490] = x4661;
    let x4662 = x4645 + x4658;
    s[1491] = x4662;
    let x4674 = 0.00000000000000006123233995736766 * s[1013];
    s[1492] = x4674;
    let x4675 = s[1110] + x4674;
    s[1493] = x4675;
    let x4676 = 0.00000000000000006123233995736766 * s[1025];
    s[1494] = x4676;
    let x4677 = s[1111] + x4676;
    s[1495] = x4677;
    let x5896 = s[31] * k[5];
    s[1496] = x5896;
    let x5897 = s[45] * k[6];
    s[1497] = x5897;
    let x5898 = x5896 + x5897;
    s[1498] = x5898;
    let x5899 = s[32] * k[5];
    s[1499] = x5899;
    let x5900 = s[47] * k[6];
    s[1500] = x5900;
    let x5901 = x5899 + x5900;
    s[1501] = x5901;
    let x5902 = s[27] * k[5];
    s[1502] = x5902;
    let x5904 = s[35] * k[6];
    s[1503] = x5904;
    let x5905 = x5904 - x5902;
    s[1504] = x5905;
    let x5906 = s[31] * k[6];
    s[1505] = x5906;
    let x5908 = s[45] * k[5];
    s[1506] = x5908;
    let x5909 = x5908 - x5906;
    s[1507] = x5909;
    let x5910 = s[32] * k[6];
    s[1508] = x5910;
    let x5912 = s[47] * k[5];
    s[1509] = x5912;
    let x5913 = x5912 - x5910;
    s[1510] = x5913;
    let x5914 = s[27] * k[6];
    s[1511] = x5914;
    let x5915 = s[35] * k[5];
    s[1512] = x5915;
    let x5916 = x5914 + x5915;
    s[1513] = x5916;
    let x6511 = s[534] * k[5];
    s[1514] = x6511;
    let x6513 = s[642] - x6511;
    s[1515] = x6513;
    let x6514 = s[574] * k[6];
    s[1516] = x6514;
    let x6515 = s[643] + x6514;
    s[1517] = x6515;
    let x6516 = x6513 + x6515;
    s[1518] = x6516;
    let x6517 = s[537] * k[5];
    s[1519] = x6517;
    let x6518 = s[644] + x6517;
    s[1520] = x6518;
    let x6519 = s[576] * k[6];
    s[1521] = x6519;
    let x6520 = s[645] + x6519;
    s[1522] = x6520;
    let x6521 = x6518 + x6520;
    s[1523] = x6521;
    let x6522 = s[528] * k[5];
    s[1524] = x6522;
    let x6523 = s[646] + x6522;
    s[1525] = x6523;
    let x6525 = s[546] * k[6];
    s[1526] = x6525;
    let x6526 = s[647] + x6525;
    s[1527] = x6526;
    let x6527 = x6526 - x6523;
    s[1528] = x6527;
    let x6528 = s[534] * k[6];
    s[1529] = x6528;
    let x6530 = s[648] - x6528;
    s[1530] = x6530;
    let x6532 = s[574] * k[5];
    s[1531] = x6532;
    let x6533 = s[649] + x6532;
    s[1532] = x6533;
    let x6534 = x6533 - x6530;
    s[1533] = x6534;
    let x6535 = s[537] * k[6];
    s[1534] = x6535;
    let x6536 = s[650] + x6535;
    s[1535] = x6536;
    let x6538 = s[576] * k[5];
    s[1536] = x6538;
    let x6539 = s[651] + x6538;
    s[1537] = x6539;
    let x6540 = x6539 - x6536;
    s[1538] = x6540;
    let x6541 = s[528] * k[6];
    s[1539] = x6541;
    let x6542 = s[652] + x6541;
    s[1540] = x6542;
    let x6543 = s[546] * k[5];
    s[1541] = x6543;
    let x6544 = s[653] + x6543;
    s[1542] = x6544;
    let x6545 = x6542 + x6544;
    s[1543] = x6545;
}
#[inline(never)]
fn kinematic_tangents_part_0(
    k: &[f64; 23],
    dq: &[f64; 18],
    dp: &[f64; 33],
    s: &[f64; 1544],
    phi: &mut [f64; 21],
    phi_q: &mut [f64; 96],
    phi_t: &mut [f64; 21],
    gamma: &mut [f64; 21],
) {
    let x383 = s[9] * 0.00000000000000006123233995736766;
    let x386 = s[88] + x383;
    let x388 = s[10] * 0.00000000000000006123233995736766;
    let x391 = s[89] + x388;
    let x393 = s[4] * 0.00000000000000006123233995736766;
    let x394 = x393 - s[87];
    let x436 = s[23] - s[75];
    let x2758 = s[7] * dp[15];
    let x2761 = s[8] * dp[15];
    let x2764 = s[3] * dp[15];
    let x2776 = -s[524];
    let x2791 = s[7] * dp[16];
    let x2794 = s[8] * dp[16];
    let x2797 = s[3] * dp[16];
    let x2805 = s[31] * dp[17];
    let x2808 = s[32] * dp[17];
    let x2811 = s[27] * dp[17];
    let x2823 = s[74] * s[575];
    let x2824 = s[46] * s[631];
    let x2826 = x2823 - x2824;
    let x2827 = s[76] * s[577];
    let x2828 = s[48] * s[633];
    let x2829 = x2827 + x2828;
    let x2830 = s[78] * s[549];
    let x2832 = s[36] * s[635];
    let x2833 = x2832 - x2830;
    let x2835 = x2826 + x2829;
    let x2836 = x2835 - x2833;
    let x3015 = s[503] - s[500];
    let x3020 = s[46] * s[523];
    let x3021 = s[22] * s[575];
    let x3022 = x3020 + x3021;
    let x3023 = s[48] * s[525];
    let x3024 = s[24] * s[577];
    let x3025 = x3023 + x3024;
    let x3026 = s[36] * s[497];
    let x3028 = s[12] * s[549];
    let x3030 = x3026 + x3028;
    let x3032 = x3022 + x3025;
    let x3033 = x3032 - x3030;
    let x3034 = -x3033;
    let x3063 = s[7] * s[475];
    let x3065 = s[2] * s[482];
    let x3067 = x3063 + x3065;
    let x3068 = -x3067;
    let x3072 = s[8] * s[475];
    let x3074 = s[2] * s[485];
    let x3075 = x3074 - x3072;
    let x3077 = s[9] * dp[15];
    let x3080 = s[10] * dp[15];
    let x3084 = s[4] * dp[15];
    let x3090 = 0.00000000000000006123233995736766 * s[477];
    let x3092 = s[656] + x3090;
    let x3101 = s[9] * dp[16];
    let x3105 = s[10] * dp[16];
    let x3110 = s[4] * dp[16];
    let x3113 = x386 * s[575];
    let x3114 = s[46] * s[664];
    let x3115 = x3113 + x3114;
    let x3116 = x391 * s[577];
    let x3117 = s[48] * s[666];
    let x3118 = x3116 + x3117;
    let x3119 = x394 * s[549];
    let x3121 = s[36] * x3092;
    let x3123 = x3119 + x3121;
    let x3125 = x3115 + x3118;
    let x3126 = x3125 - x3123;
    let x3127 = -x3126;
    let x3146 = s[521] - s[518];
    let x3151 = x436 * s[575];
    let x3152 = s[46] * s[667];
    let x3153 = x3151 + x3152;
    let x3154 = s[74] * s[577];
    let x3155 = s[48] * s[631];
    let x3157 = x3154 - x3155;
    let x3158 = x3153 + x3157;
    let x3278 = s[33] * dp[17];
    let x3281 = s[34] * dp[17];
    let x3285 = s[28] * dp[17];
    let x4140 = s[122] * s[713];
    let x4141 = s[109] * s[746];
    let x4142 = x4140 + x4141;
    let x4143 = s[225] * s[488];
    let x4144 = s[9] * s[989];
    let x4145 = x4143 + x4144;
    let x4146 = x4142 + x4145;
    let x4147 = s[247] * s[475];
    let x4149 = s[2] * s[1037];
    let x4150 = x4149 - x4147;
    let x4151 = x4142 + x4150;
    let x4152 = x4146 + x4151;
    let x4154 = s[112] * s[710];
    let x4155 = s[108] * s[722];
    let x4156 = x4154 + x4155;
    let x4157 = s[224] * s[478];
    let x4158 = s[5] * s[986];
    let x4159 = x4157 + x4158;
    let x4161 = x4156 - x4159;
    let x4162 = s[228] * s[474];
    let x4163 = s[1] * s[998];
    let x4164 = x4162 + x4163;
    let x4166 = x4156 - x4164;
    let x4167 = x4161 + x4166;
    let x4197 = s[125] * s[713];
    let x4198 = s[109] * s[753];
    let x4199 = x4197 + x4198;
    let x4200 = s[225] * s[491];
    let x4201 = s[10] * s[989];
    let x4202 = x4200 + x4201;
    let x4203 = x4199 + x4202;
    let x4206 = s[253] * s[475];
    let x4208 = s[2] * s[1049];
    let x4209 = x4208 - x4206;
    let x4210 = x4209 - x4199;
    let x4211 = x4210 - x4203;
    let x4212 = s[113] * s[710];
    let x4213 = s[108] * s[725];
    let x4214 = x4212 + x4213;
    let x4215 = s[224] * s[479];
    let x4217 = s[6] * s[986];
    let x4218 = x4217 - x4215;
    let x4219 = x4214 + x4218;
    let x4220 = s[229] * s[474];
    let x4221 = s[1] * s[1001];
    let x4222 = x4220 + x4221;
    let x4223 = x4214 + x4222;
    let x4224 = x4219 + x4223;
    let x4226 = x4167 - x4152;
    let x4228 = x4211 + x4224;
    let x4663 = s[235] * dp[15];
    let x4667 = s[241] * dp[15];
    let x4671 = s[226] * dp[15];
    let x4687 = s[235] * dp[16];
    let x4691 = s[241] * dp[16];
    let x4695 = s[226] * dp[16];
    let x4698 = s[297] * dp[17];
    let x4701 = s[303] * dp[17];
    let x4704 = s[288] * dp[17];
    let x5007 = -x4226;
    let x5008 = -x4228;
    let x6449 = s[482] * k[0];
    let x6451 = x2758 - x6449;
    let x6452 = s[485] * k[0];
    let x6453 = x2761 + x6452;
    let x6454 = s[476] * k[0];
    let x6455 = x2764 + x6454;
    let x6457 = dq[0] + x6451;
    let x6458 = dq[1] + x6453;
    let x6459 = dq[2] - x6455;
    let x6460 = -x6457;
    let x6461 = -x6458;
    let x6462 = -x6459;
    let x6463 = s[482] * k[1];
    let x6465 = x2791 - x6463;
    let x6466 = s[485] * k[1];
    let x6467 = x2794 + x6466;
    let x6468 = s[476] * k[1];
    let x6469 = x2797 + x6468;
    let x6471 = dq[0] + x6465;
    let x6472 = dq[1] + x6467;
    let x6473 = dq[2] - x6469;
    let x6474 = s[534] * k[2];
    let x6476 = x2805 - x6474;
    let x6477 = s[537] * k[2];
    let x6478 = x2808 + x6477;
    let x6479 = s[528] * k[2];
    let x6480 = x2811 + x6479;
    let x6482 = dq[6] + x6476;
    let x6483 = dq[7] + x6478;
    let x6484 = dq[8] - x6480;
    let x6486 = x6471 - x6482;
    let x6488 = x6472 - x6483;
    let x6490 = x6473 - x6484;
    let x6620 = s[488] * k[0];
    let x6621 = x3077 + x6620;
    let x6622 = s[491] * k[0];
    let x6623 = x3080 + x6622;
    let x6624 = s[477] * k[0];
    let x6626 = x3084 - x6624;
    let x6627 = s[488] * k[1];
    let x6628 = x3101 + x6627;
    let x6629 = -x6628;
    let x6630 = s[491] * k[1];
    let x6631 = x3105 + x6630;
    let x6632 = -x6631;
    let x6633 = s[477] * k[1];
    let x6635 = x3110 - x6633;
    let x6636 = -x6635;
    let x6637 = -x6451;
    let x6638 = -x6467;
    let x6684 = s[540] * k[2];
    let x6685 = x3278 + x6684;
    let x6686 = s[543] * k[2];
    let x6687 = x3281 + x6686;
    let x6688 = s[529] * k[2];
    let x6690 = x3285 - x6688;
    let x6770 = -x6476;
    let x6947 = s[1013] * k[0];
    let x6948 = x4663 + x6947;
    let x6949 = -x6948;
    let x6950 = s[1025] * k[0];
    let x6951 = x4667 + x6950;
    let x6952 = -x6951;
    let x6953 = s[992] * k[0];
    let x6954 = x4671 + x6953;
    let x6955 = s[1013] * k[1];
    let x6956 = x4687 + x6955;
    let x6958 = s[1025] * k[1];
    let x6959 = x4691 + x6958;
    let x6961 = s[992] * k[1];
    let x6962 = x4695 + x6961;
    let x6963 = s[1141] * k[2];
    let x6964 = x4698 + x6963;
    let x6965 = s[1153] * k[2];
    let x6966 = x4701 + x6965;
    let x6967 = s[1120] * k[2];
    let x6968 = x4704 + x6967;
    let x6970 = x6964 - x6956;
    let x6971 = x6966 - x6959;
    let x6972 = x6962 - x6968;
    let x7147 = -x6970;
    let x7148 = -x6971;
    let x7149 = -x6972;
    phi[0] = x6460;
    phi_q[0] = 0.0;
    phi_q[1] = x6621;
    phi_q[2] = x6453;
    phi_t[0] = 0.0;
    gamma[0] = x6949;
    phi[1] = x6461;
    phi_q[3] = 0.0;
    phi_q[4] = x6623;
    phi_q[5] = x6637;
    phi_t[1] = 0.0;
    gamma[1] = x6952;
    phi[2] = x6462;
    phi_q[6] = 0.0;
    phi_q[7] = x6626;
    phi_t[2] = 0.0;
    gamma[2] = x6954;
    phi[3] = s[523];
    phi_q[8] = x3015;
    phi_q[9] = x3068;
    phi_q[10] = x3146;
    phi_t[3] = 0.0;
    gamma[3] = x5007;
    phi[4] = s[525];
    phi_q[11] = x2776;
    phi_q[12] = x3075;
    phi_q[13] = s[523];
    phi_t[4] = 0.0;
    gamma[4] = x5008;
    phi[5] = x6486;
    phi_q[14] = 0.0;
    phi_q[15] = x6629;
    phi_q[16] = x6638;
    phi_q[17] = 0.0;
    phi_q[18] = x6685;
    phi_q[19] = x6478;
    phi_t[5] = 0.0;
    gamma[5] = x7147;
    phi[6] = x6488;
    phi_q[20] = 0.0;
    phi_q[21] = x6632;
    phi_q[22] = x6465;
    phi_q[23] = 0.0;
    phi_q[24] = x6687;
    phi_q[25] = x6770;
    phi_t[6] = 0.0;
    gamma[6] = x7148;
    phi[7] = x6490;
    phi_q[26] = 0.0;
    phi_q[27] = x6636;
    phi_q[28] = 0.0;
    phi_q[29] = x6690;
    phi_t[7] = 0.0;
    gamma[7] = x7149;
    phi[8] = x2836;
    phi_q[30] = x3034;
    phi_q[31] = x3127;
    phi_q[32] = x3158;
}
#[inline(never)]
fn kinematic_tangents_part_1(
    s: &[f64; 1544],
    phi_q: &mut [f64; 96],
    phi_t: &mut [f64; 21],
) {
    let x3173 = s[90] * s[631];
    let x3175 = s[74] * s[668];
    let x3176 = x3175 - x3173;
    let x3177 = s[76] * s[576];
    let x3178 = s[47] * s[633];
    let x3179 = x3177 + x3178;
    let x3181 = s[78] * s[546];
    let x3182 = s[35] * s[635];
    let x3183 = x3181 + x3182;
    let x3184 = x3176 - x3179;
    let x3185 = x3183 + x3184;
    let x3287 = s[94] * s[631];
    let x3289 = s[74] * s[680];
    let x3291 = x3287 + x3289;
    let x3293 = s[96] * s[633];
    let x3294 = s[76] * s[686];
    let x3295 = x3293 + x3294;
    let x3296 = s[92] * s[635];
    let x3297 = s[78] * s[674];
    let x3298 = x3296 + x3297;
    let x3299 = x3295 - x3291;
    let x3300 = x3298 + x3299;
    let x3414 = s[97] * s[631];
    let x3416 = s[74] * s[687];
    let x3417 = x3416 - x3414;
    let x3418 = s[76] * s[575];
    let x3419 = s[46] * s[633];
    let x3420 = x3418 + x3419;
    let x3421 = x3417 + x3420;
    phi_q[33] = x3185;
    phi_q[34] = x3300;
    phi_q[35] = x3421;
    phi_t[8] = 0.0;
}
#[inline(never)]
fn kinematic_tangents_part_2(s: &[f64; 1544], gamma: &mut [f64; 21]) {
    let x951 = 0.00000000000000006123233995736766 * s[116];
    let x954 = s[141] + x951;
    let x956 = 0.00000000000000006123233995736766 * s[119];
    let x958 = x956 - s[142];
    let x959 = 0.00000000000000006123233995736766 * s[110];
    let x960 = s[128] + x959;
    let x1555 = 0.00000000000000006123233995736766 * s[235];
    let x1556 = s[284] + x1555;
    let x1557 = 0.00000000000000006123233995736766 * s[241];
    let x1560 = s[285] + x1557;
    let x1562 = 0.00000000000000006123233995736766 * s[226];
    let x1564 = s[259] + x1562;
    let x3965 = 0.00000000000000006123233995736766 * s[716];
    let x3966 = s[760] + x3965;
    let x4678 = 0.00000000000000006123233995736766 * s[992];
    let x4679 = s[1061] + x4678;
    let x4711 = x954 * s[908];
    let x4712 = s[192] * s[981];
    let x4713 = x4711 + x4712;
    let x4715 = s[377] * s[631];
    let x4717 = s[74] * s[1299];
    let x4718 = x4717 - x4715;
    let x4719 = x4718 - x4713;
    let x4720 = x1556 * s[575];
    let x4721 = s[46] * s[1493];
    let x4722 = x4720 + x4721;
    let x4723 = x4713 + x4722;
    let x4725 = x4719 - x4723;
    let x4726 = x958 * s[910];
    let x4727 = s[194] * s[983];
    let x4728 = x4726 + x4727;
    let x4729 = s[379] * s[633];
    let x4730 = s[76] * s[1301];
    let x4731 = x4729 + x4730;
    let x4732 = x4728 + x4731;
    let x4733 = x1560 * s[577];
    let x4734 = s[48] * s[1495];
    let x4735 = x4733 + x4734;
    let x4737 = x4728 - x4735;
    let x4738 = x4732 + x4737;
    let x4739 = x960 * s[850];
    let x4740 = s[166] * x3966;
    let x4741 = x4739 + x4740;
    let x4742 = s[327] * s[635];
    let x4743 = s[78] * s[1201];
    let x4744 = x4742 + x4743;
    let x4745 = x4741 + x4744;
    let x4746 = x1564 * s[549];
    let x4748 = s[36] * x4679;
    let x4749 = x4748 - x4746;
    let x4750 = x4741 + x4749;
    let x4751 = x4745 + x4750;
    let x4752 = x4725 + x4738;
    let x4753 = x4751 + x4752;
    let x5012 = -x4753;
    gamma[8] = x5012;
}
#[inline(never)]
fn kinematic_tangents_part_3(
    s: &[f64; 1544],
    phi: &mut [f64; 21],
    phi_q: &mut [f64; 96],
    phi_t: &mut [f64; 21],
) {
    let x345 = s[22] * 0.00000000000000006123233995736766;
    let x346 = s[24] * 0.00000000000000006123233995736766;
    let x347 = s[12] * 0.00000000000000006123233995736766;
    let x395 = 0.00000000000000006123233995736766 * s[88];
    let x396 = x395 - s[9];
    let x397 = 0.00000000000000006123233995736766 * s[89];
    let x398 = x397 - s[10];
    let x399 = 0.00000000000000006123233995736766 * s[87];
    let x401 = s[4] + x399;
    let x2837 = s[80] * s[575];
    let x2838 = s[46] * s[637];
    let x2839 = x2837 + x2838;
    let x2840 = s[82] * s[577];
    let x2841 = s[48] * s[639];
    let x2842 = x2840 + x2841;
    let x2843 = s[84] * s[549];
    let x2845 = s[36] * s[641];
    let x2846 = x2845 - x2843;
    let x2847 = x2839 + x2842;
    let x2848 = x2846 + x2847;
    let x3016 = 0.00000000000000006123233995736766 * s[523];
    let x3017 = 0.00000000000000006123233995736766 * s[525];
    let x3018 = 0.00000000000000006123233995736766 * s[497];
    let x3035 = x345 * s[575];
    let x3036 = s[46] * x3016;
    let x3037 = x3035 + x3036;
    let x3038 = x346 * s[577];
    let x3039 = s[48] * x3017;
    let x3040 = x3038 + x3039;
    let x3041 = x347 * s[549];
    let x3043 = s[36] * x3018;
    let x3045 = x3041 + x3043;
    let x3047 = x3037 + x3040;
    let x3048 = x3047 - x3045;
    let x3094 = 0.00000000000000006123233995736766 * s[659];
    let x3095 = x3094 - s[488];
    let x3096 = 0.00000000000000006123233995736766 * s[662];
    let x3097 = x3096 - s[491];
    let x3098 = 0.00000000000000006123233995736766 * s[656];
    let x3099 = x3098 - s[477];
    let x3128 = x396 * s[575];
    let x3129 = s[46] * x3095;
    let x3130 = x3128 + x3129;
    let x3131 = x398 * s[577];
    let x3132 = s[48] * x3097;
    let x3133 = x3131 + x3132;
    let x3134 = x401 * s[549];
    let x3136 = s[36] * x3099;
    let x3137 = x3136 - x3134;
    let x3139 = x3130 + x3133;
    let x3140 = x3139 - x3137;
    let x3159 = s[82] * s[575];
    let x3160 = s[46] * s[639];
    let x3161 = x3159 + x3160;
    let x3163 = s[80] * s[577];
    let x3164 = s[48] * s[637];
    let x3165 = x3163 + x3164;
    let x3166 = x3165 - x3161;
    let x3186 = s[90] * s[637];
    let x3187 = s[80] * s[668];
    let x3188 = x3186 + x3187;
    let x3189 = s[82] * s[576];
    let x3190 = s[47] * s[639];
    let x3191 = x3189 + x3190;
    let x3193 = s[84] * s[546];
    let x3194 = s[35] * s[641];
    let x3195 = x3193 + x3194;
    let x3197 = x3188 - x3191;
    let x3198 = x3197 - x3195;
    let x3301 = s[94] * s[637];
    let x3302 = s[80] * s[680];
    let x3304 = x3301 - x3302;
    let x3305 = s[96] * s[639];
    let x3306 = s[82] * s[686];
    let x3307 = x3305 + x3306;
    let x3308 = s[92] * s[641];
    let x3309 = s[84] * s[674];
    let x3310 = x3308 + x3309;
    let x3312 = x3304 + x3307;
    let x3313 = x3312 - x3310;
    let x3422 = s[97] * s[637];
    let x3423 = s[80] * s[687];
    let x3424 = x3422 + x3423;
    let x3425 = x3161 + x3424;
    phi[9] = x2848;
    phi_q[36] = x3048;
    phi_q[37] = x3140;
    phi_q[38] = x3166;
    phi_q[39] = x3198;
    phi_q[40] = x3313;
    phi_q[41] = x3425;
    phi_t[9] = 0.0;
}
#[inline(never)]
fn kinematic_tangents_part_4(s: &[f64; 1544], gamma: &mut [f64; 21]) {
    let x961 = 0.00000000000000006123233995736766 * s[141];
    let x962 = x961 - s[116];
    let x963 = 0.00000000000000006123233995736766 * s[142];
    let x964 = s[119] + x963;
    let x965 = 0.00000000000000006123233995736766 * s[128];
    let x966 = x965 - s[110];
    let x1566 = 0.00000000000000006123233995736766 * s[284];
    let x1567 = x1566 - s[235];
    let x1568 = 0.00000000000000006123233995736766 * s[285];
    let x1569 = x1568 - s[241];
    let x1570 = 0.00000000000000006123233995736766 * s[259];
    let x1572 = s[226] - x1570;
    let x3967 = 0.00000000000000006123233995736766 * s[789];
    let x3968 = x3967 - s[732];
    let x3969 = 0.00000000000000006123233995736766 * s[790];
    let x3970 = s[739] + x3969;
    let x3971 = 0.00000000000000006123233995736766 * s[760];
    let x3972 = x3971 - s[716];
    let x4680 = 0.00000000000000006123233995736766 * s[1110];
    let x4681 = x4680 - s[1013];
    let x4682 = 0.00000000000000006123233995736766 * s[1111];
    let x4683 = x4682 - s[1025];
    let x4684 = 0.00000000000000006123233995736766 * s[1061];
    let x4686 = s[992] - x4684;
    let x4754 = x962 * s[908];
    let x4755 = s[192] * x3968;
    let x4756 = x4754 + x4755;
    let x4757 = s[377] * s[637];
    let x4758 = s[80] * s[1299];
    let x4759 = x4757 + x4758;
    let x4760 = x4756 + x4759;
    let x4761 = x1567 * s[575];
    let x4762 = s[46] * x4681;
    let x4763 = x4761 + x4762;
    let x4764 = x4756 + x4763;
    let x4765 = x4760 + x4764;
    let x4766 = x964 * s[910];
    let x4767 = s[194] * x3970;
    let x4768 = x4766 + x4767;
    let x4769 = s[379] * s[639];
    let x4770 = s[82] * s[1301];
    let x4771 = x4769 + x4770;
    let x4772 = x4768 + x4771;
    let x4773 = x1569 * s[577];
    let x4774 = s[48] * x4683;
    let x4775 = x4773 + x4774;
    let x4776 = x4768 + x4775;
    let x4777 = x4772 + x4776;
    let x4778 = x966 * s[850];
    let x4779 = s[166] * x3972;
    let x4780 = x4778 + x4779;
    let x4781 = s[327] * s[641];
    let x4782 = s[84] * s[1201];
    let x4783 = x4781 + x4782;
    let x4784 = x4780 + x4783;
    let x4787 = x1572 * s[549];
    let x4789 = s[36] * x4686;
    let x4790 = x4789 - x4787;
    let x4791 = x4790 - x4780;
    let x4792 = x4791 - x4784;
    let x4793 = x4765 + x4777;
    let x4794 = x4792 + x4793;
    let x5013 = -x4794;
    gamma[9] = x5013;
}
#[inline(never)]
fn kinematic_tangents_part_5(
    k: &[f64; 23],
    dq: &[f64; 18],
    dp: &[f64; 33],
    s: &[f64; 1544],
    phi: &mut [f64; 21],
    phi_q: &mut [f64; 96],
    phi_t: &mut [f64; 21],
    gamma: &mut [f64; 21],
) {
    let x2851 = s[31] * dp[20];
    let x2854 = s[45] * dp[21];
    let x2858 = s[32] * dp[20];
    let x2861 = s[47] * dp[21];
    let x2924 = s[55] * dp[24];
    let x2927 = s[69] * dp[25];
    let x2931 = s[56] * dp[24];
    let x2934 = s[71] * dp[25];
    let x3200 = s[46] * dp[21];
    let x3203 = s[48] * dp[21];
    let x3315 = s[33] * dp[20];
    let x3318 = s[93] * dp[21];
    let x3323 = s[34] * dp[20];
    let x3326 = s[95] * dp[21];
    let x3448 = s[70] * dp[25];
    let x3451 = s[72] * dp[25];
    let x3524 = s[57] * dp[24];
    let x3527 = s[101] * dp[25];
    let x3532 = s[58] * dp[24];
    let x3535 = s[103] * dp[25];
    let x4795 = s[297] * dp[20];
    let x4799 = s[376] * dp[21];
    let x4864 = s[391] * dp[24];
    let x4868 = s[470] * dp[25];
    let x6491 = s[534] * k[3];
    let x6493 = x2851 - x6491;
    let x6494 = s[574] * k[4];
    let x6495 = x2854 + x6494;
    let x6496 = x6493 + x6495;
    let x6497 = s[537] * k[3];
    let x6498 = x2858 + x6497;
    let x6499 = s[576] * k[4];
    let x6500 = x2861 + x6499;
    let x6501 = x6498 + x6500;
    let x6508 = dq[6] + x6496;
    let x6509 = dq[7] + x6501;
    let x6546 = s[586] * k[7];
    let x6548 = x2924 - x6546;
    let x6549 = s[626] * k[8];
    let x6550 = x2927 + x6549;
    let x6551 = x6548 + x6550;
    let x6552 = s[589] * k[7];
    let x6553 = x2931 + x6552;
    let x6554 = s[628] * k[8];
    let x6555 = x2934 + x6554;
    let x6556 = x6553 + x6555;
    let x6563 = dq[12] + x6551;
    let x6564 = dq[13] + x6556;
    let x6567 = x6508 - x6563;
    let x6569 = x6509 - x6564;
    let x6639 = s[575] * k[4];
    let x6640 = x3200 + x6639;
    let x6641 = s[577] * k[4];
    let x6642 = x3203 + x6641;
    let x6691 = s[540] * k[3];
    let x6692 = x3315 + x6691;
    let x6694 = s[677] * k[4];
    let x6695 = x3318 + x6694;
    let x6696 = x6695 - x6692;
    let x6697 = s[543] * k[3];
    let x6698 = x3323 + x6697;
    let x6700 = s[683] * k[4];
    let x6701 = x3326 + x6700;
    let x6702 = x6701 - x6698;
    let x6771 = -x6501;
    let x6789 = s[627] * k[8];
    let x6790 = x3448 + x6789;
    let x6791 = s[629] * k[8];
    let x6792 = x3451 + x6791;
    let x6796 = -x6790;
    let x6797 = -x6792;
    let x6835 = s[592] * k[7];
    let x6836 = x3524 + x6835;
    let x6838 = s[697] * k[8];
    let x6839 = x3527 + x6838;
    let x6840 = x6839 - x6836;
    let x6841 = s[595] * k[7];
    let x6842 = x3532 + x6841;
    let x6844 = s[703] * k[8];
    let x6845 = x3535 + x6844;
    let x6846 = x6845 - x6842;
    let x6853 = -x6840;
    let x6854 = -x6846;
    let x6901 = -x6551;
    let x6973 = s[1141] * k[3];
    let x6974 = x4795 + x6973;
    let x6976 = s[1298] * k[4];
    let x6977 = x4799 + x6976;
    let x6978 = x6977 - x6974;
    let x7024 = s[1331] * k[7];
    let x7025 = x4864 + x7024;
    let x7027 = s[1488] * k[8];
    let x7028 = x4868 + x7027;
    let x7029 = x7028 - x7025;
    let x7043 = x6978 - x7029;
    let x7150 = -x7043;
    phi[10] = x6567;
    phi_q[42] = 0.0;
    phi_q[43] = x6640;
    phi_q[44] = x6696;
    phi_q[45] = x6771;
    phi_q[46] = 0.0;
    phi_q[47] = x6796;
    phi_q[48] = x6853;
    phi_q[49] = x6556;
    phi_t[10] = 0.0;
    gamma[10] = x7150;
    phi[11] = x6569;
    phi_q[50] = 0.0;
    phi_q[51] = x6642;
    phi_q[52] = x6702;
    phi_q[53] = x6496;
    phi_q[54] = 0.0;
    phi_q[55] = x6797;
    phi_q[56] = x6854;
    phi_q[57] = x6901;
    phi_t[11] = 0.0;
}
#[inline(never)]
fn kinematic_tangents_part_6(
    k: &[f64; 23],
    dq: &[f64; 18],
    dp: &[f64; 33],
    s: &[f64; 1544],
    phi: &mut [f64; 21],
    phi_q: &mut [f64; 96],
    phi_t: &mut [f64; 21],
    gamma: &mut [f64; 21],
) {
    let x2865 = s[27] * dp[20];
    let x2869 = s[35] * dp[21];
    let x2938 = s[51] * dp[24];
    let x2942 = s[59] * dp[25];
    let x3207 = s[36] * dp[21];
    let x3210 = s[46] * dp[23];
    let x3213 = s[48] * dp[23];
    let x3217 = s[36] * dp[23];
    let x3332 = s[28] * dp[20];
    let x3334 = s[91] * dp[21];
    let x3455 = s[60] * dp[25];
    let x3541 = s[52] * dp[24];
    let x3543 = s[99] * dp[25];
    let x4803 = s[303] * dp[20];
    let x4807 = s[378] * dp[21];
    let x4811 = s[288] * dp[20];
    let x4814 = s[321] * dp[21];
    let x4872 = s[397] * dp[24];
    let x4876 = s[472] * dp[25];
    let x4880 = s[382] * dp[24];
    let x4883 = s[415] * dp[25];
    let x5982 = s[46] * k[6];
    let x5983 = s[48] * k[6];
    let x5984 = s[36] * k[6];
    let x6502 = s[528] * k[3];
    let x6503 = x2865 + x6502;
    let x6505 = s[546] * k[4];
    let x6506 = x2869 + x6505;
    let x6507 = x6506 - x6503;
    let x6510 = dq[8] + x6507;
    let x6557 = s[580] * k[7];
    let x6558 = x2938 + x6557;
    let x6560 = s[598] * k[8];
    let x6561 = x2942 + x6560;
    let x6562 = x6561 - x6558;
    let x6565 = dq[14] + x6562;
    let x6571 = x6510 - x6565;
    let x6572 = s[627] * s[1498];
    let x6573 = s[70] * s[1518];
    let x6574 = x6572 + x6573;
    let x6575 = s[629] * s[1501];
    let x6576 = s[72] * s[1523];
    let x6577 = x6575 + x6576;
    let x6578 = s[601] * s[1504];
    let x6580 = s[60] * s[1528];
    let x6581 = x6580 - x6578;
    let x6582 = x6574 + x6577;
    let x6583 = x6581 + x6582;
    let x6643 = s[549] * k[4];
    let x6645 = x3207 - x6643;
    let x6646 = s[575] * k[6];
    let x6647 = x3210 + x6646;
    let x6648 = s[577] * k[6];
    let x6649 = x3213 + x6648;
    let x6650 = s[549] * k[6];
    let x6652 = x3217 - x6650;
    let x6660 = s[627] * x5982;
    let x6661 = s[70] * x6647;
    let x6662 = x6660 + x6661;
    let x6663 = s[629] * x5983;
    let x6664 = s[72] * x6649;
    let x6665 = x6663 + x6664;
    let x6666 = s[601] * x5984;
    let x6668 = s[60] * x6652;
    let x6669 = x6668 - x6666;
    let x6670 = x6662 + x6665;
    let x6671 = x6669 + x6670;
    let x6703 = s[529] * k[3];
    let x6705 = x3332 - x6703;
    let x6706 = s[671] * k[4];
    let x6707 = x3334 + x6706;
    let x6708 = x6705 + x6707;
    let x6709 = -x6708;
    let x6793 = s[601] * k[8];
    let x6795 = x3455 - x6793;
    let x6798 = -x6795;
    let x6847 = s[581] * k[7];
    let x6849 = x3541 - x6847;
    let x6850 = s[691] * k[8];
    let x6851 = x3543 + x6850;
    let x6852 = x6849 + x6851;
    let x6979 = s[1153] * k[3];
    let x6980 = x4803 + x6979;
    let x6982 = s[1300] * k[4];
    let x6983 = x4807 + x6982;
    let x6984 = x6983 - x6980;
    let x6985 = s[1120] * k[3];
    let x6986 = x4811 + x6985;
    let x6987 = s[1189] * k[4];
    let x6988 = x4814 + x6987;
    let x6990 = x6986 - x6988;
    let x7030 = s[1343] * k[7];
    let x7031 = x4872 + x7030;
    let x7033 = s[1490] * k[8];
    let x7034 = x4876 + x7033;
    let x7035 = x7034 - x7031;
    let x7036 = s[1310] * k[7];
    let x7037 = x4880 + x7036;
    let x7038 = s[1379] * k[8];
    let x7039 = x4883 + x7038;
    let x7041 = x7037 - x7039;
    let x7045 = x6984 - x7035;
    let x7047 = x6990 - x7041;
    let x7151 = -x7045;
    let x7152 = -x7047;
    gamma[11] = x7151;
    phi[12] = x6571;
    phi_q[58] = 0.0;
    phi_q[59] = x6645;
    phi_q[60] = x6709;
    phi_q[61] = 0.0;
    phi_q[62] = x6798;
    phi_q[63] = x6852;
    phi_t[12] = 0.0;
    gamma[12] = x7152;
    phi[13] = x6583;
    phi_q[64] = x6671;
}
#[inline(never)]
fn kinematic_tangents_part_7(
    k: &[f64; 23],
    dp: &[f64; 33],
    s: &[f64; 1544],
    phi_q: &mut [f64; 96],
    phi_t: &mut [f64; 21],
) {
    let x3340 = s[33] * dp[22];
    let x3343 = s[93] * dp[23];
    let x3348 = s[34] * dp[22];
    let x3351 = s[95] * dp[23];
    let x3357 = s[28] * dp[22];
    let x3359 = s[91] * dp[23];
    let x6013 = s[33] * k[5];
    let x6015 = s[93] * k[6];
    let x6016 = x6015 - x6013;
    let x6017 = s[34] * k[5];
    let x6019 = s[95] * k[6];
    let x6020 = x6019 - x6017;
    let x6021 = s[28] * k[5];
    let x6022 = s[91] * k[6];
    let x6023 = x6021 + x6022;
    let x6710 = s[540] * k[5];
    let x6711 = x3340 + x6710;
    let x6713 = s[677] * k[6];
    let x6714 = x3343 + x6713;
    let x6715 = x6714 - x6711;
    let x6716 = s[543] * k[5];
    let x6717 = x3348 + x6716;
    let x6719 = s[683] * k[6];
    let x6720 = x3351 + x6719;
    let x6721 = x6720 - x6717;
    let x6722 = s[529] * k[5];
    let x6724 = x3357 - x6722;
    let x6725 = s[671] * k[6];
    let x6726 = x3359 + x6725;
    let x6727 = x6724 + x6726;
    let x6745 = s[627] * x6016;
    let x6746 = s[70] * x6715;
    let x6747 = x6745 + x6746;
    let x6748 = s[629] * x6020;
    let x6749 = s[72] * x6721;
    let x6750 = x6748 + x6749;
    let x6751 = s[601] * x6023;
    let x6753 = s[60] * x6727;
    let x6754 = x6753 - x6751;
    let x6756 = x6747 + x6750;
    let x6757 = x6756 - x6754;
    let x6774 = s[627] * s[1501];
    let x6775 = s[70] * s[1523];
    let x6776 = x6774 + x6775;
    let x6778 = s[629] * s[1498];
    let x6779 = s[72] * s[1518];
    let x6780 = x6778 + x6779;
    let x6781 = x6780 - x6776;
    let x6799 = s[98] * s[1518];
    let x6800 = s[688] * s[1498];
    let x6801 = x6799 + x6800;
    let x6802 = s[628] * s[1501];
    let x6803 = s[71] * s[1523];
    let x6804 = x6802 + x6803;
    let x6806 = s[598] * s[1504];
    let x6807 = s[59] * s[1528];
    let x6808 = x6806 + x6807;
    let x6810 = x6801 - x6804;
    let x6811 = x6810 - x6808;
    let x6855 = s[102] * s[1518];
    let x6856 = s[700] * s[1498];
    let x6858 = x6855 - x6856;
    let x6859 = s[104] * s[1523];
    let x6860 = s[706] * s[1501];
    let x6861 = x6859 + x6860;
    let x6862 = s[100] * s[1528];
    let x6863 = s[694] * s[1504];
    let x6864 = x6862 + x6863;
    let x6866 = x6858 + x6861;
    let x6867 = x6866 - x6864;
    let x6902 = s[105] * s[1518];
    let x6903 = s[707] * s[1498];
    let x6904 = x6902 + x6903;
    let x6905 = x6776 + x6904;
    phi_q[65] = x6757;
    phi_q[66] = x6781;
    phi_q[67] = x6811;
    phi_q[68] = x6867;
    phi_q[69] = x6905;
    phi_t[13] = 0.0;
}
#[inline(never)]
fn kinematic_tangents_part_8(
    k: &[f64; 23],
    dp: &[f64; 33],
    s: &[f64; 1544],
    gamma: &mut [f64; 21],
) {
    let x3973 = s[151] * dp[22];
    let x3977 = s[191] * dp[23];
    let x3981 = s[154] * dp[22];
    let x3984 = s[193] * dp[23];
    let x3988 = s[145] * dp[22];
    let x3992 = s[163] * dp[23];
    let x4819 = s[297] * dp[22];
    let x4823 = s[376] * dp[23];
    let x4827 = s[303] * dp[22];
    let x4831 = s[378] * dp[23];
    let x4835 = s[288] * dp[22];
    let x4838 = s[321] * dp[23];
    let x6127 = s[151] * k[5];
    let x6129 = s[191] * k[6];
    let x6130 = x6129 - x6127;
    let x6131 = s[154] * k[5];
    let x6132 = s[193] * k[6];
    let x6133 = x6131 + x6132;
    let x6134 = s[145] * k[5];
    let x6136 = s[163] * k[6];
    let x6137 = x6136 - x6134;
    let x6177 = s[297] * k[5];
    let x6179 = s[376] * k[6];
    let x6180 = x6179 - x6177;
    let x6181 = s[303] * k[5];
    let x6183 = s[378] * k[6];
    let x6184 = x6183 - x6181;
    let x6185 = s[288] * k[5];
    let x6186 = s[321] * k[6];
    let x6188 = x6185 - x6186;
    let x6914 = s[815] * k[5];
    let x6915 = x3973 + x6914;
    let x6917 = s[907] * k[6];
    let x6918 = x3977 + x6917;
    let x6919 = x6918 - x6915;
    let x6920 = s[822] * k[5];
    let x6921 = x3981 + x6920;
    let x6922 = s[909] * k[6];
    let x6923 = x3984 + x6922;
    let x6924 = x6921 + x6923;
    let x6925 = s[799] * k[5];
    let x6926 = x3988 + x6925;
    let x6928 = s[843] * k[6];
    let x6929 = x3992 + x6928;
    let x6930 = x6929 - x6926;
    let x6991 = s[1141] * k[5];
    let x6992 = x4819 + x6991;
    let x6994 = s[1298] * k[6];
    let x6995 = x4823 + x6994;
    let x6996 = x6995 - x6992;
    let x6997 = s[1153] * k[5];
    let x6998 = x4827 + x6997;
    let x7000 = s[1300] * k[6];
    let x7001 = x4831 + x7000;
    let x7002 = x7001 - x6998;
    let x7003 = s[1120] * k[5];
    let x7004 = x4835 + x7003;
    let x7005 = s[1189] * k[6];
    let x7006 = x4838 + x7005;
    let x7008 = x7004 - x7006;
    let x7048 = s[978] * x6130;
    let x7049 = s[222] * x6919;
    let x7050 = x7048 + x7049;
    let x7051 = s[471] * s[1518];
    let x7052 = s[1489] * s[1498];
    let x7053 = x7051 + x7052;
    let x7054 = x7050 + x7053;
    let x7055 = s[627] * x6180;
    let x7056 = s[70] * x6996;
    let x7057 = x7055 + x7056;
    let x7058 = x7050 + x7057;
    let x7059 = x7054 + x7058;
    let x7060 = s[979] * x6133;
    let x7061 = s[223] * x6924;
    let x7062 = x7060 + x7061;
    let x7063 = s[473] * s[1523];
    let x7064 = s[1491] * s[1501];
    let x7065 = x7063 + x7064;
    let x7066 = x7062 + x7065;
    let x7067 = s[629] * x6184;
    let x7068 = s[72] * x7002;
    let x7069 = x7067 + x7068;
    let x7070 = x7062 + x7069;
    let x7071 = x7066 + x7070;
    let x7072 = s[949] * x6137;
    let x7073 = s[209] * x6930;
    let x7074 = x7072 + x7073;
    let x7075 = s[421] * s[1528];
    let x7076 = s[1391] * s[1504];
    let x7077 = x7075 + x7076;
    let x7078 = x7074 + x7077;
    let x7081 = s[601] * x6188;
    let x7083 = s[60] * x7008;
    let x7084 = x7083 - x7081;
    let x7085 = x7084 - x7074;
    let x7086 = x7085 - x7078;
    let x7087 = x7059 + x7071;
    let x7088 = x7086 + x7087;
    let x7153 = -x7088;
    gamma[13] = x7153;
}
#[inline(never)]
fn kinematic_tangents_part_9(
    k: &[f64; 23],
    dp: &[f64; 33],
    s: &[f64; 1544],
    phi: &mut [f64; 21],
    phi_q: &mut [f64; 96],
    phi_t: &mut [f64; 21],
) {
    let x3220 = s[46] * dp[22];
    let x3223 = s[48] * dp[22];
    let x3227 = s[36] * dp[22];
    let x3364 = s[33] * dp[23];
    let x3366 = s[93] * dp[22];
    let x3371 = s[34] * dp[23];
    let x3373 = s[95] * dp[22];
    let x3379 = s[28] * dp[23];
    let x3381 = s[91] * dp[22];
    let x5985 = s[46] * k[5];
    let x5986 = s[48] * k[5];
    let x5987 = s[36] * k[5];
    let x6024 = s[33] * k[6];
    let x6025 = s[93] * k[5];
    let x6026 = x6024 + x6025;
    let x6027 = s[34] * k[6];
    let x6028 = s[95] * k[5];
    let x6029 = x6027 + x6028;
    let x6030 = s[28] * k[6];
    let x6031 = s[91] * k[5];
    let x6033 = x6030 - x6031;
    let x6048 = s[1508] - s[1509];
    let x6584 = s[627] * s[1507];
    let x6585 = s[70] * s[1533];
    let x6586 = x6584 + x6585;
    let x6587 = s[629] * s[1510];
    let x6588 = s[72] * s[1538];
    let x6589 = x6587 + x6588;
    let x6590 = s[601] * s[1513];
    let x6592 = s[60] * s[1543];
    let x6593 = x6592 - x6590;
    let x6594 = x6586 + x6589;
    let x6595 = x6593 + x6594;
    let x6653 = s[575] * k[5];
    let x6654 = x3220 + x6653;
    let x6655 = s[577] * k[5];
    let x6656 = x3223 + x6655;
    let x6657 = s[549] * k[5];
    let x6659 = x3227 - x6657;
    let x6672 = s[627] * x5985;
    let x6673 = s[70] * x6654;
    let x6674 = x6672 + x6673;
    let x6675 = s[629] * x5986;
    let x6676 = s[72] * x6656;
    let x6677 = x6675 + x6676;
    let x6678 = s[601] * x5987;
    let x6680 = s[60] * x6659;
    let x6681 = x6680 - x6678;
    let x6682 = x6674 + x6677;
    let x6683 = x6681 + x6682;
    let x6728 = s[540] * k[6];
    let x6729 = x3364 + x6728;
    let x6730 = s[677] * k[5];
    let x6731 = x3366 + x6730;
    let x6732 = x6729 + x6731;
    let x6733 = s[543] * k[6];
    let x6734 = x3371 + x6733;
    let x6735 = s[683] * k[5];
    let x6736 = x3373 + x6735;
    let x6737 = x6734 + x6736;
    let x6738 = s[529] * k[6];
    let x6740 = x3379 - x6738;
    let x6741 = s[671] * k[5];
    let x6742 = x3381 + x6741;
    let x6744 = x6740 - x6742;
    let x6758 = s[627] * x6026;
    let x6759 = s[70] * x6732;
    let x6760 = x6758 + x6759;
    let x6761 = s[629] * x6029;
    let x6762 = s[72] * x6737;
    let x6763 = x6761 + x6762;
    let x6764 = s[601] * x6033;
    let x6766 = s[60] * x6744;
    let x6767 = x6766 - x6764;
    let x6768 = x6760 + x6763;
    let x6769 = x6767 + x6768;
    let x6773 = s[1535] - s[1537];
    let x6782 = s[627] * x6048;
    let x6783 = s[70] * x6773;
    let x6784 = x6782 + x6783;
    let x6785 = s[629] * s[1507];
    let x6786 = s[72] * s[1533];
    let x6787 = x6785 + x6786;
    let x6788 = x6784 + x6787;
    let x6812 = s[98] * s[1533];
    let x6813 = s[688] * s[1507];
    let x6814 = x6812 + x6813;
    let x6815 = s[628] * s[1510];
    let x6816 = s[71] * s[1538];
    let x6817 = x6815 + x6816;
    let x6819 = s[598] * s[1513];
    let x6820 = s[59] * s[1543];
    let x6821 = x6819 + x6820;
    let x6823 = x6814 - x6817;
    let x6824 = x6823 - x6821;
    let x6868 = s[102] * s[1533];
    let x6869 = s[700] * s[1507];
    let x6871 = x6868 - x6869;
    let x6872 = s[104] * s[1538];
    let x6873 = s[706] * s[1510];
    let x6874 = x6872 + x6873;
    let x6875 = s[100] * s[1543];
    let x6876 = s[694] * s[1513];
    let x6877 = x6875 + x6876;
    let x6879 = x6871 + x6874;
    let x6880 = x6879 - x6877;
    let x6906 = s[105] * s[1533];
    let x6907 = s[707] * s[1507];
    let x6908 = x6906 + x6907;
    let x6909 = s[627] * s[1510];
    let x6910 = s[70] * s[1538];
    let x6911 = x6909 + x6910;
    let x6912 = x6908 + x6911;
    phi[14] = x6595;
    phi_q[70] = x6683;
    phi_q[71] = x6769;
    phi_q[72] = x6788;
    phi_q[73] = x6824;
    phi_q[74] = x6880;
    phi_q[75] = x6912;
    phi_t[14] = 0.0;
}
#[inline(never)]
fn kinematic_tangents_part_10(
    k: &[f64; 23],
    dp: &[f64; 33],
    s: &[f64; 1544],
    gamma: &mut [f64; 21],
) {
    let x3996 = s[151] * dp[23];
    let x3999 = s[191] * dp[22];
    let x4003 = s[154] * dp[23];
    let x4007 = s[193] * dp[22];
    let x4011 = s[145] * dp[23];
    let x4014 = s[163] * dp[22];
    let x4843 = s[297] * dp[23];
    let x4846 = s[376] * dp[22];
    let x4850 = s[303] * dp[23];
    let x4853 = s[378] * dp[22];
    let x4857 = s[288] * dp[23];
    let x4860 = s[321] * dp[22];
    let x6138 = s[151] * k[6];
    let x6139 = s[191] * k[5];
    let x6140 = x6138 + x6139;
    let x6141 = s[154] * k[6];
    let x6143 = s[193] * k[5];
    let x6144 = x6143 - x6141;
    let x6145 = s[145] * k[6];
    let x6146 = s[163] * k[5];
    let x6147 = x6145 + x6146;
    let x6189 = s[297] * k[6];
    let x6190 = s[376] * k[5];
    let x6191 = x6189 + x6190;
    let x6192 = s[303] * k[6];
    let x6193 = s[378] * k[5];
    let x6194 = x6192 + x6193;
    let x6195 = s[288] * k[6];
    let x6196 = s[321] * k[5];
    let x6197 = x6195 + x6196;
    let x6931 = s[815] * k[6];
    let x6932 = x3996 + x6931;
    let x6933 = s[907] * k[5];
    let x6934 = x3999 + x6933;
    let x6935 = x6932 + x6934;
    let x6936 = s[822] * k[6];
    let x6937 = x4003 + x6936;
    let x6939 = s[909] * k[5];
    let x6940 = x4007 + x6939;
    let x6941 = x6940 - x6937;
    let x6942 = s[799] * k[6];
    let x6943 = x4011 + x6942;
    let x6944 = s[843] * k[5];
    let x6945 = x4014 + x6944;
    let x6946 = x6943 + x6945;
    let x7009 = s[1141] * k[6];
    let x7010 = x4843 + x7009;
    let x7011 = s[1298] * k[5];
    let x7012 = x4846 + x7011;
    let x7013 = x7010 + x7012;
    let x7014 = s[1153] * k[6];
    let x7015 = x4850 + x7014;
    let x7016 = s[1300] * k[5];
    let x7017 = x4853 + x7016;
    let x7018 = x7015 + x7017;
    let x7019 = s[1120] * k[6];
    let x7020 = x4857 + x7019;
    let x7021 = s[1189] * k[5];
    let x7022 = x4860 + x7021;
    let x7023 = x7020 + x7022;
    let x7089 = s[978] * x6140;
    let x7090 = s[222] * x6935;
    let x7091 = x7089 + x7090;
    let x7092 = s[471] * s[1533];
    let x7093 = s[1489] * s[1507];
    let x7094 = x7092 + x7093;
    let x7095 = x7091 + x7094;
    let x7096 = s[627] * x6191;
    let x7097 = s[70] * x7013;
    let x7098 = x7096 + x7097;
    let x7099 = x7091 + x7098;
    let x7100 = x7095 + x7099;
    let x7101 = s[979] * x6144;
    let x7102 = s[223] * x6941;
    let x7103 = x7101 + x7102;
    let x7104 = s[473] * s[1538];
    let x7105 = s[1491] * s[1510];
    let x7106 = x7104 + x7105;
    let x7107 = x7103 + x7106;
    let x7108 = s[629] * x6194;
    let x7109 = s[72] * x7018;
    let x7110 = x7108 + x7109;
    let x7111 = x7103 + x7110;
    let x7112 = x7107 + x7111;
    let x7113 = s[949] * x6147;
    let x7114 = s[209] * x6946;
    let x7115 = x7113 + x7114;
    let x7116 = s[421] * s[1543];
    let x7117 = s[1391] * s[1513];
    let x7118 = x7116 + x7117;
    let x7119 = x7115 + x7118;
    let x7120 = s[601] * x6197;
    let x7122 = s[60] * x7023;
    let x7123 = x7122 - x7120;
    let x7124 = x7115 + x7123;
    let x7125 = x7119 + x7124;
    let x7127 = x7100 + x7112;
    let x7128 = x7127 - x7125;
    let x7154 = -x7128;
    gamma[14] = x7154;
}
#[inline(never)]
fn kinematic_tangents_part_11(
    k: &[f64; 23],
    dq: &[f64; 18],
    dp: &[f64; 33],
    s: &[f64; 1544],
    phi: &mut [f64; 21],
    phi_q: &mut [f64; 96],
    phi_t: &mut [f64; 21],
    gamma: &mut [f64; 21],
) {
    let x2980 = s[55] * dp[29];
    let x2983 = s[69] * dp[30];
    let x2987 = s[56] * dp[29];
    let x2990 = s[71] * dp[30];
    let x2994 = s[51] * dp[29];
    let x2998 = s[59] * dp[30];
    let x3008 = s[85] * s[631];
    let x3010 = s[86] * s[633];
    let x3012 = x3008 + x3010;
    let x3013 = -x3012;
    let x3049 = s[85] * s[523];
    let x3051 = s[86] * s[525];
    let x3052 = x3051 - x3049;
    let x3141 = s[85] * s[664];
    let x3143 = s[86] * s[666];
    let x3144 = x3143 - x3141;
    let x3167 = s[85] * s[667];
    let x3168 = s[86] * s[631];
    let x3170 = x3167 + x3168;
    let x3446 = -s[628];
    let x3487 = s[70] * dp[30];
    let x3490 = s[72] * dp[30];
    let x3494 = s[60] * dp[30];
    let x3515 = -s[700];
    let x3576 = s[57] * dp[29];
    let x3579 = s[101] * dp[30];
    let x3584 = s[58] * dp[29];
    let x3587 = s[103] * dp[30];
    let x3593 = s[52] * dp[29];
    let x3595 = s[99] * dp[30];
    let x3616 = s[106] * s[631];
    let x3618 = s[107] * s[633];
    let x3619 = x3618 - x3616;
    let x4975 = s[391] * dp[29];
    let x4979 = s[470] * dp[30];
    let x4983 = s[397] * dp[29];
    let x4987 = s[472] * dp[30];
    let x4991 = s[382] * dp[29];
    let x4994 = s[415] * dp[30];
    let x5019 = -s[1489];
    let x5020 = -s[1491];
    let x6596 = s[586] * k[10];
    let x6598 = x2980 - x6596;
    let x6599 = s[626] * k[11];
    let x6600 = x2983 + x6599;
    let x6601 = x6598 + x6600;
    let x6602 = s[589] * k[10];
    let x6603 = x2987 + x6602;
    let x6604 = s[628] * k[11];
    let x6605 = x2990 + x6604;
    let x6606 = x6603 + x6605;
    let x6607 = s[580] * k[10];
    let x6608 = x2994 + x6607;
    let x6610 = s[598] * k[11];
    let x6611 = x2998 + x6610;
    let x6612 = x6611 - x6608;
    let x6613 = dq[12] + x6601;
    let x6614 = dq[13] + x6606;
    let x6615 = dq[14] + x6612;
    let x6617 = dp[28] - x6613;
    let x6618 = -x6614;
    let x6619 = -x6615;
    let x6825 = s[627] * k[11];
    let x6826 = x3487 + x6825;
    let x6827 = s[629] * k[11];
    let x6828 = x3490 + x6827;
    let x6829 = s[601] * k[11];
    let x6831 = x3494 - x6829;
    let x6832 = -x6826;
    let x6833 = -x6828;
    let x6834 = -x6831;
    let x6881 = s[592] * k[10];
    let x6882 = x3576 + x6881;
    let x6884 = s[697] * k[11];
    let x6885 = x3579 + x6884;
    let x6886 = x6885 - x6882;
    let x6887 = s[595] * k[10];
    let x6888 = x3584 + x6887;
    let x6890 = s[703] * k[11];
    let x6891 = x3587 + x6890;
    let x6892 = x6891 - x6888;
    let x6893 = s[581] * k[10];
    let x6895 = x3593 - x6893;
    let x6896 = s[691] * k[11];
    let x6897 = x3595 + x6896;
    let x6898 = x6895 + x6897;
    let x6899 = -x6886;
    let x6900 = -x6892;
    let x6913 = -x6601;
    let x7129 = s[1331] * k[10];
    let x7130 = x4975 + x7129;
    let x7132 = s[1488] * k[11];
    let x7133 = x4979 + x7132;
    let x7134 = x7133 - x7130;
    let x7135 = s[1343] * k[10];
    let x7136 = x4983 + x7135;
    let x7138 = s[1490] * k[11];
    let x7139 = x4987 + x7138;
    let x7140 = x7139 - x7136;
    let x7141 = s[1310] * k[10];
    let x7142 = x4991 + x7141;
    let x7143 = s[1379] * k[11];
    let x7144 = x4994 + x7143;
    let x7146 = x7142 - x7144;
    phi[15] = x6617;
    phi_q[76] = 0.0;
    phi_q[77] = x6832;
    phi_q[78] = x6899;
    phi_q[79] = x6606;
    phi_t[15] = 0.0;
    gamma[15] = x7134;
    phi[16] = x6618;
    phi_q[80] = 0.0;
    phi_q[81] = x6833;
    phi_q[82] = x6900;
    phi_q[83] = x6913;
    phi_t[16] = 0.0;
    gamma[16] = x7140;
    phi[17] = x6619;
    phi_q[84] = 0.0;
    phi_q[85] = x6834;
    phi_q[86] = x6898;
    phi_t[17] = 0.0;
    gamma[17] = x7146;
    phi[18] = s[627];
    phi_q[87] = s[688];
    phi_q[88] = x3515;
    phi_q[89] = s[707];
    phi_t[18] = 0.0;
    gamma[18] = x5019;
    phi[19] = s[629];
    phi_q[90] = x3446;
    phi_q[91] = s[706];
    phi_q[92] = s[627];
    phi_t[19] = 0.0;
    gamma[19] = x5020;
    phi[20] = x3013;
    phi_q[93] = x3052;
    phi_q[94] = x3144;
    phi_q[95] = x3170;
    phi_t[20] = x3619;
}
#[inline(never)]
fn kinematic_tangents_part_12(s: &[f64; 1544], gamma: &mut [f64; 21]) {
    let x1122 = 6.283185307179586 * s[107];
    let x1124 = 6.283185307179586 * s[106];
    let x4018 = s[106] * s[981];
    let x4019 = x1122 * s[631];
    let x4021 = x4018 - x4019;
    let x4022 = s[107] * s[983];
    let x4023 = x1124 * s[633];
    let x4024 = x4022 + x4023;
    let x4999 = s[85] * s[1493];
    let x5000 = x4018 + x4999;
    let x5001 = x4021 + x5000;
    let x5003 = s[86] * s[1495];
    let x5004 = x4022 + x5003;
    let x5005 = x4024 + x5004;
    let x5006 = x5005 - x5001;
    let x5021 = -x5006;
    gamma[20] = x5021;
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
pub const N_K: usize = 23;
/// `setup` at the file's parameter values: what the types without parameters read.
pub static K: [f64; 23] = [
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
    0.1f64,
    0.35f64,
    0.3f64,
    0.020000000000000004f64,
    0.0001666666666666667f64,
    0.175f64,
    0.005104166666666666f64,
    0.12f64,
    0.0029999999999999996f64,
    0.0001f64,
];
/// The values the per-step functions read (`k`), from the run-time parameters `p`.
pub fn setup(p: &[f64], k: &mut [f64]) {
    let p: &[f64; 33] = p.try_into().expect("p must have 33 entries");
    let k: &mut [f64; 23] = k.try_into().expect("k must have 23 entries");
    setup_part_0(p, k);
}
#[inline(never)]
fn setup_part_0(p: &[f64; 33], k: &mut [f64; 23]) {
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
    k[13] = p[1];
    k[14] = p[2];
    k[15] = p[3];
    k[16] = x1803;
    k[17] = x1807;
    k[18] = x1809;
    k[19] = x1811;
    k[20] = x1813;
    k[21] = x1815;
    k[22] = x1891;
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
        kkt: &KKT,
    };
    use symbody_runtime::kkt::{
        length_error, mass_pivot_error, KktError, KktKernels, Pivoting,
    };
    /// The KKT factor and solve for this model's patterns, straight-line (`KktKernels`).
    pub static KKT: [KktKernels; 1] = [
        KktKernels {
            pattern: 0xf23dca50f6ec13b8,
            storage: 238,
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
        let mass: &[f64; 30] = mass
            .try_into()
            .map_err(|_| length_error(30, mass.len()))?;
        let phi_q: &[f64; 96] = phi_q
            .try_into()
            .map_err(|_| length_error(96, phi_q.len()))?;
        let st_len = st.len();
        let st: &mut [f64; 238] = st.try_into().map_err(|_| length_error(238, st_len))?;
        if !phi_q[84].is_finite() {
            return Err(KktError::NotFinite);
        }
        if !phi_q[85].is_finite() {
            return Err(KktError::NotFinite);
        }
        if !phi_q[86].is_finite() {
            return Err(KktError::NotFinite);
        }
        if !phi_q[87].is_finite() {
            return Err(KktError::NotFinite);
        }
        if !phi_q[88].is_finite() {
            return Err(KktError::NotFinite);
        }
        if !phi_q[89].is_finite() {
            return Err(KktError::NotFinite);
        }
        if !phi_q[90].is_finite() {
            return Err(KktError::NotFinite);
        }
        if !phi_q[91].is_finite() {
            return Err(KktError::NotFinite);
        }
        if !phi_q[92].is_finite() {
            return Err(KktError::NotFinite);
        }
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
        if !((c * mass[5]) > 0.0 && (c * mass[5]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[5]), 4));
        }
        let v9: f64 = (c * mass[5]).sqrt();
        let v10: f64 = 1.0 / v9;
        st[10] = v10;
        let v11: f64 = (c * mass[8]) * v10;
        st[1] = v11;
        let v12: f64 = (c * mass[9]) - v8 * v8;
        let v13: f64 = v12 - v11 * v11;
        if !(v13 > 0.0 && v13 <= f64::MAX) {
            return Err(mass_pivot_error(v13, 5));
        }
        let v14: f64 = v13.sqrt();
        let v15: f64 = 1.0 / v14;
        st[11] = v15;
        let v16: f64 = phi_q[0] * v1;
        st[24] = v16;
        let v17: f64 = phi_q[1] * v10;
        st[25] = v17;
        let v18: f64 = phi_q[2] - v11 * v17;
        let v19: f64 = v18 * v15;
        st[26] = v19;
        let v20: f64 = phi_q[3] * v3;
        st[27] = v20;
        let v21: f64 = phi_q[4] * v10;
        st[28] = v21;
        let v22: f64 = phi_q[5] - v11 * v21;
        let v23: f64 = v22 * v15;
        st[29] = v23;
        let v24: f64 = phi_q[6] * v5;
        st[30] = v24;
        let v25: f64 = phi_q[7] * v10;
        st[31] = v25;
        let v26: f64 = -(v11 * v25);
        let v27: f64 = v26 * v15;
        st[32] = v27;
        let v28: f64 = phi_q[8] * v7;
        st[33] = v28;
        let v29: f64 = phi_q[9] * v10;
        st[34] = v29;
        let v30: f64 = phi_q[10] - v8 * v28;
        let v31: f64 = v30 - v11 * v29;
        let v32: f64 = v31 * v15;
        st[35] = v32;
        let v33: f64 = phi_q[11] * v7;
        st[36] = v33;
        let v34: f64 = phi_q[12] * v10;
        st[37] = v34;
        let v35: f64 = phi_q[13] - v8 * v33;
        let v36: f64 = v35 - v11 * v34;
        let v37: f64 = v36 * v15;
        st[38] = v37;
        let v38: f64 = phi_q[14] * v1;
        st[39] = v38;
        let v39: f64 = phi_q[15] * v10;
        st[40] = v39;
        let v40: f64 = phi_q[16] - v11 * v39;
        let v41: f64 = v40 * v15;
        st[41] = v41;
        let v42: f64 = phi_q[20] * v3;
        st[42] = v42;
        let v43: f64 = phi_q[21] * v10;
        st[43] = v43;
        let v44: f64 = phi_q[22] - v11 * v43;
        let v45: f64 = v44 * v15;
        st[44] = v45;
        let v46: f64 = phi_q[26] * v5;
        st[45] = v46;
        let v47: f64 = phi_q[27] * v10;
        st[46] = v47;
        let v48: f64 = -(v11 * v47);
        let v49: f64 = v48 * v15;
        st[47] = v49;
        let v50: f64 = phi_q[30] * v7;
        st[48] = v50;
        let v51: f64 = phi_q[31] * v10;
        st[49] = v51;
        let v52: f64 = phi_q[32] - v8 * v50;
        let v53: f64 = v52 - v11 * v51;
        let v54: f64 = v53 * v15;
        st[50] = v54;
        let v55: f64 = phi_q[36] * v7;
        st[51] = v55;
        let v56: f64 = phi_q[37] * v10;
        st[52] = v56;
        let v57: f64 = phi_q[38] - v8 * v55;
        let v58: f64 = v57 - v11 * v56;
        let v59: f64 = v58 * v15;
        st[53] = v59;
        let v60: f64 = phi_q[93] * v7;
        st[54] = v60;
        let v61: f64 = phi_q[94] * v10;
        st[55] = v61;
        let v62: f64 = phi_q[95] - v8 * v60;
        let v63: f64 = v62 - v11 * v61;
        let v64: f64 = v63 * v15;
        st[56] = v64;
        let v65: f64 = v16 * v16;
        let v66: f64 = v17 * v17;
        let v67: f64 = v65 + v66;
        let v68: f64 = v19 * v19;
        let v69: f64 = v67 + v68;
        let v70: f64 = v21 * v17;
        let v71: f64 = v23 * v19;
        let v72: f64 = v70 + v71;
        let v73: f64 = v20 * v20;
        let v74: f64 = v21 * v21;
        let v75: f64 = v73 + v74;
        let v76: f64 = v23 * v23;
        let v77: f64 = v75 + v76;
        let v78: f64 = v25 * v17;
        let v79: f64 = v27 * v19;
        let v80: f64 = v78 + v79;
        let v81: f64 = v25 * v21;
        let v82: f64 = v27 * v23;
        let v83: f64 = v81 + v82;
        let v84: f64 = v24 * v24;
        let v85: f64 = v25 * v25;
        let v86: f64 = v84 + v85;
        let v87: f64 = v27 * v27;
        let v88: f64 = v86 + v87;
        let v89: f64 = v29 * v17;
        let v90: f64 = v32 * v19;
        let v91: f64 = v89 + v90;
        let v92: f64 = v29 * v21;
        let v93: f64 = v32 * v23;
        let v94: f64 = v92 + v93;
        let v95: f64 = v29 * v25;
        let v96: f64 = v32 * v27;
        let v97: f64 = v95 + v96;
        let v98: f64 = v28 * v28;
        let v99: f64 = v29 * v29;
        let v100: f64 = v98 + v99;
        let v101: f64 = v32 * v32;
        let v102: f64 = v100 + v101;
        let v103: f64 = v34 * v17;
        let v104: f64 = v37 * v19;
        let v105: f64 = v103 + v104;
        let v106: f64 = v34 * v21;
        let v107: f64 = v37 * v23;
        let v108: f64 = v106 + v107;
        let v109: f64 = v34 * v25;
        let v110: f64 = v37 * v27;
        let v111: f64 = v109 + v110;
        let v112: f64 = v33 * v28;
        let v113: f64 = v34 * v29;
        let v114: f64 = v112 + v113;
        let v115: f64 = v37 * v32;
        let v116: f64 = v114 + v115;
        let v117: f64 = v33 * v33;
        let v118: f64 = v34 * v34;
        let v119: f64 = v117 + v118;
        let v120: f64 = v37 * v37;
        let v121: f64 = v119 + v120;
        let v122: f64 = v38 * v16;
        let v123: f64 = v39 * v17;
        let v124: f64 = v122 + v123;
        let v125: f64 = v41 * v19;
        let v126: f64 = v124 + v125;
        let v127: f64 = v39 * v21;
        let v128: f64 = v41 * v23;
        let v129: f64 = v127 + v128;
        let v130: f64 = v39 * v25;
        let v131: f64 = v41 * v27;
        let v132: f64 = v130 + v131;
        let v133: f64 = v39 * v29;
        let v134: f64 = v41 * v32;
        let v135: f64 = v133 + v134;
        let v136: f64 = v39 * v34;
        let v137: f64 = v41 * v37;
        let v138: f64 = v136 + v137;
        let v139: f64 = v38 * v38;
        let v140: f64 = v39 * v39;
        let v141: f64 = v139 + v140;
        let v142: f64 = v41 * v41;
        let v143: f64 = v141 + v142;
        let v144: f64 = v43 * v17;
        let v145: f64 = v45 * v19;
        let v146: f64 = v144 + v145;
        let v147: f64 = v42 * v20;
        let v148: f64 = v43 * v21;
        let v149: f64 = v147 + v148;
        let v150: f64 = v45 * v23;
        let v151: f64 = v149 + v150;
        let v152: f64 = v43 * v25;
        let v153: f64 = v45 * v27;
        let v154: f64 = v152 + v153;
        let v155: f64 = v43 * v29;
        let v156: f64 = v45 * v32;
        let v157: f64 = v155 + v156;
        let v158: f64 = v43 * v34;
        let v159: f64 = v45 * v37;
        let v160: f64 = v158 + v159;
        let v161: f64 = v43 * v39;
        let v162: f64 = v45 * v41;
        let v163: f64 = v161 + v162;
        let v164: f64 = v42 * v42;
        let v165: f64 = v43 * v43;
        let v166: f64 = v164 + v165;
        let v167: f64 = v45 * v45;
        let v168: f64 = v166 + v167;
        let v169: f64 = v47 * v17;
        let v170: f64 = v49 * v19;
        let v171: f64 = v169 + v170;
        let v172: f64 = v47 * v21;
        let v173: f64 = v49 * v23;
        let v174: f64 = v172 + v173;
        let v175: f64 = v46 * v24;
        let v176: f64 = v47 * v25;
        let v177: f64 = v175 + v176;
        let v178: f64 = v49 * v27;
        let v179: f64 = v177 + v178;
        let v180: f64 = v47 * v29;
        let v181: f64 = v49 * v32;
        let v182: f64 = v180 + v181;
        let v183: f64 = v47 * v34;
        let v184: f64 = v49 * v37;
        let v185: f64 = v183 + v184;
        let v186: f64 = v47 * v39;
        let v187: f64 = v49 * v41;
        let v188: f64 = v186 + v187;
        let v189: f64 = v47 * v43;
        let v190: f64 = v49 * v45;
        let v191: f64 = v189 + v190;
        let v192: f64 = v46 * v46;
        let v193: f64 = v47 * v47;
        let v194: f64 = v192 + v193;
        let v195: f64 = v49 * v49;
        let v196: f64 = v194 + v195;
        let v197: f64 = v51 * v17;
        let v198: f64 = v54 * v19;
        let v199: f64 = v197 + v198;
        let v200: f64 = v51 * v21;
        let v201: f64 = v54 * v23;
        let v202: f64 = v200 + v201;
        let v203: f64 = v51 * v25;
        let v204: f64 = v54 * v27;
        let v205: f64 = v203 + v204;
        let v206: f64 = v50 * v28;
        let v207: f64 = v51 * v29;
        let v208: f64 = v206 + v207;
        let v209: f64 = v54 * v32;
        let v210: f64 = v208 + v209;
        let v211: f64 = v50 * v33;
        let v212: f64 = v51 * v34;
        let v213: f64 = v211 + v212;
        let v214: f64 = v54 * v37;
        let v215: f64 = v213 + v214;
        let v216: f64 = v51 * v39;
        let v217: f64 = v54 * v41;
        let v218: f64 = v216 + v217;
        let v219: f64 = v51 * v43;
        let v220: f64 = v54 * v45;
        let v221: f64 = v219 + v220;
        let v222: f64 = v51 * v47;
        let v223: f64 = v54 * v49;
        let v224: f64 = v222 + v223;
        let v225: f64 = v50 * v50;
        let v226: f64 = v51 * v51;
        let v227: f64 = v225 + v226;
        let v228: f64 = v54 * v54;
        let v229: f64 = v227 + v228;
        let v230: f64 = v56 * v17;
        let v231: f64 = v59 * v19;
        let v232: f64 = v230 + v231;
        let v233: f64 = v56 * v21;
        let v234: f64 = v59 * v23;
        let v235: f64 = v233 + v234;
        let v236: f64 = v56 * v25;
        let v237: f64 = v59 * v27;
        let v238: f64 = v236 + v237;
        let v239: f64 = v55 * v28;
        let v240: f64 = v56 * v29;
        let v241: f64 = v239 + v240;
        let v242: f64 = v59 * v32;
        let v243: f64 = v241 + v242;
        let v244: f64 = v55 * v33;
        let v245: f64 = v56 * v34;
        let v246: f64 = v244 + v245;
        let v247: f64 = v59 * v37;
        let v248: f64 = v246 + v247;
        let v249: f64 = v56 * v39;
        let v250: f64 = v59 * v41;
        let v251: f64 = v249 + v250;
        let v252: f64 = v56 * v43;
        let v253: f64 = v59 * v45;
        let v254: f64 = v252 + v253;
        let v255: f64 = v56 * v47;
        let v256: f64 = v59 * v49;
        let v257: f64 = v255 + v256;
        let v258: f64 = v55 * v50;
        let v259: f64 = v56 * v51;
        let v260: f64 = v258 + v259;
        let v261: f64 = v59 * v54;
        let v262: f64 = v260 + v261;
        let v263: f64 = v55 * v55;
        let v264: f64 = v56 * v56;
        let v265: f64 = v263 + v264;
        let v266: f64 = v59 * v59;
        let v267: f64 = v265 + v266;
        let v268: f64 = v61 * v17;
        let v269: f64 = v64 * v19;
        let v270: f64 = v268 + v269;
        let v271: f64 = v61 * v21;
        let v272: f64 = v64 * v23;
        let v273: f64 = v271 + v272;
        let v274: f64 = v61 * v25;
        let v275: f64 = v64 * v27;
        let v276: f64 = v274 + v275;
        let v277: f64 = v60 * v28;
        let v278: f64 = v61 * v29;
        let v279: f64 = v277 + v278;
        let v280: f64 = v64 * v32;
        let v281: f64 = v279 + v280;
        let v282: f64 = v60 * v33;
        let v283: f64 = v61 * v34;
        let v284: f64 = v282 + v283;
        let v285: f64 = v64 * v37;
        let v286: f64 = v284 + v285;
        let v287: f64 = v61 * v39;
        let v288: f64 = v64 * v41;
        let v289: f64 = v287 + v288;
        let v290: f64 = v61 * v43;
        let v291: f64 = v64 * v45;
        let v292: f64 = v290 + v291;
        let v293: f64 = v61 * v47;
        let v294: f64 = v64 * v49;
        let v295: f64 = v293 + v294;
        let v296: f64 = v60 * v50;
        let v297: f64 = v61 * v51;
        let v298: f64 = v296 + v297;
        let v299: f64 = v64 * v54;
        let v300: f64 = v298 + v299;
        let v301: f64 = v60 * v55;
        let v302: f64 = v61 * v56;
        let v303: f64 = v301 + v302;
        let v304: f64 = v64 * v59;
        let v305: f64 = v303 + v304;
        let v306: f64 = v60 * v60;
        let v307: f64 = v61 * v61;
        let v308: f64 = v306 + v307;
        let v309: f64 = v64 * v64;
        let v310: f64 = v308 + v309;
        if !((c * mass[10]) > 0.0 && (c * mass[10]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[10]), 6));
        }
        let v311: f64 = (c * mass[10]).sqrt();
        let v312: f64 = 1.0 / v311;
        st[12] = v312;
        if !((c * mass[11]) > 0.0 && (c * mass[11]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[11]), 7));
        }
        let v313: f64 = (c * mass[11]).sqrt();
        let v314: f64 = 1.0 / v313;
        st[13] = v314;
        if !((c * mass[12]) > 0.0 && (c * mass[12]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[12]), 8));
        }
        let v315: f64 = (c * mass[12]).sqrt();
        let v316: f64 = 1.0 / v315;
        st[14] = v316;
        if !((c * mass[13]) > 0.0 && (c * mass[13]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[13]), 9));
        }
        let v317: f64 = (c * mass[13]).sqrt();
        let v318: f64 = 1.0 / v317;
        st[15] = v318;
        let v319: f64 = (c * mass[17]) * v318;
        st[2] = v319;
        if !((c * mass[15]) > 0.0 && (c * mass[15]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[15]), 10));
        }
        let v320: f64 = (c * mass[15]).sqrt();
        let v321: f64 = 1.0 / v320;
        st[16] = v321;
        let v322: f64 = (c * mass[18]) * v321;
        st[3] = v322;
        let v323: f64 = (c * mass[19]) - v319 * v319;
        let v324: f64 = v323 - v322 * v322;
        if !(v324 > 0.0 && v324 <= f64::MAX) {
            return Err(mass_pivot_error(v324, 11));
        }
        let v325: f64 = v324.sqrt();
        let v326: f64 = 1.0 / v325;
        st[17] = v326;
        let v327: f64 = phi_q[17] * v312;
        st[57] = v327;
        let v328: f64 = phi_q[18] * v321;
        st[58] = v328;
        let v329: f64 = phi_q[19] - v322 * v328;
        let v330: f64 = v329 * v326;
        st[59] = v330;
        let v331: f64 = phi_q[23] * v314;
        st[60] = v331;
        let v332: f64 = phi_q[24] * v321;
        st[61] = v332;
        let v333: f64 = phi_q[25] - v322 * v332;
        let v334: f64 = v333 * v326;
        st[62] = v334;
        let v335: f64 = phi_q[28] * v316;
        st[63] = v335;
        let v336: f64 = phi_q[29] * v321;
        st[64] = v336;
        let v337: f64 = -(v322 * v336);
        let v338: f64 = v337 * v326;
        st[65] = v338;
        let v339: f64 = phi_q[33] * v318;
        st[66] = v339;
        let v340: f64 = phi_q[34] * v321;
        st[67] = v340;
        let v341: f64 = phi_q[35] - v319 * v339;
        let v342: f64 = v341 - v322 * v340;
        let v343: f64 = v342 * v326;
        st[68] = v343;
        let v344: f64 = phi_q[39] * v318;
        st[69] = v344;
        let v345: f64 = phi_q[40] * v321;
        st[70] = v345;
        let v346: f64 = phi_q[41] - v319 * v344;
        let v347: f64 = v346 - v322 * v345;
        let v348: f64 = v347 * v326;
        st[71] = v348;
        let v349: f64 = phi_q[42] * v312;
        st[72] = v349;
        let v350: f64 = phi_q[43] * v318;
        st[73] = v350;
        let v351: f64 = phi_q[44] * v321;
        st[74] = v351;
        let v352: f64 = phi_q[45] - v319 * v350;
        let v353: f64 = v352 - v322 * v351;
        let v354: f64 = v353 * v326;
        st[75] = v354;
        let v355: f64 = phi_q[50] * v314;
        st[76] = v355;
        let v356: f64 = phi_q[51] * v318;
        st[77] = v356;
        let v357: f64 = phi_q[52] * v321;
        st[78] = v357;
        let v358: f64 = phi_q[53] - v319 * v356;
        let v359: f64 = v358 - v322 * v357;
        let v360: f64 = v359 * v326;
        st[79] = v360;
        let v361: f64 = phi_q[58] * v316;
        st[80] = v361;
        let v362: f64 = phi_q[59] * v318;
        st[81] = v362;
        let v363: f64 = phi_q[60] * v321;
        st[82] = v363;
        let v364: f64 = -(v319 * v362);
        let v365: f64 = v364 - v322 * v363;
        let v366: f64 = v365 * v326;
        st[83] = v366;
        let v367: f64 = phi_q[64] * v318;
        st[84] = v367;
        let v368: f64 = phi_q[65] * v321;
        st[85] = v368;
        let v369: f64 = phi_q[66] - v319 * v367;
        let v370: f64 = v369 - v322 * v368;
        let v371: f64 = v370 * v326;
        st[86] = v371;
        let v372: f64 = phi_q[70] * v318;
        st[87] = v372;
        let v373: f64 = phi_q[71] * v321;
        st[88] = v373;
        let v374: f64 = phi_q[72] - v319 * v372;
        let v375: f64 = v374 - v322 * v373;
        let v376: f64 = v375 * v326;
        st[89] = v376;
        let v377: f64 = v327 * v327;
        let v378: f64 = v328 * v328;
        let v379: f64 = v377 + v378;
        let v380: f64 = v330 * v330;
        let v381: f64 = v379 + v380;
        let v382: f64 = v143 + v381;
        let v383: f64 = v332 * v328;
        let v384: f64 = v334 * v330;
        let v385: f64 = v383 + v384;
        let v386: f64 = v163 + v385;
        let v387: f64 = v331 * v331;
        let v388: f64 = v332 * v332;
        let v389: f64 = v387 + v388;
        let v390: f64 = v334 * v334;
        let v391: f64 = v389 + v390;
        let v392: f64 = v168 + v391;
        let v393: f64 = v336 * v328;
        let v394: f64 = v338 * v330;
        let v395: f64 = v393 + v394;
        let v396: f64 = v188 + v395;
        let v397: f64 = v336 * v332;
        let v398: f64 = v338 * v334;
        let v399: f64 = v397 + v398;
        let v400: f64 = v191 + v399;
        let v401: f64 = v335 * v335;
        let v402: f64 = v336 * v336;
        let v403: f64 = v401 + v402;
        let v404: f64 = v338 * v338;
        let v405: f64 = v403 + v404;
        let v406: f64 = v196 + v405;
        let v407: f64 = v340 * v328;
        let v408: f64 = v343 * v330;
        let v409: f64 = v407 + v408;
        let v410: f64 = v218 + v409;
        let v411: f64 = v340 * v332;
        let v412: f64 = v343 * v334;
        let v413: f64 = v411 + v412;
        let v414: f64 = v221 + v413;
        let v415: f64 = v340 * v336;
        let v416: f64 = v343 * v338;
        let v417: f64 = v415 + v416;
        let v418: f64 = v224 + v417;
        let v419: f64 = v339 * v339;
        let v420: f64 = v340 * v340;
        let v421: f64 = v419 + v420;
        let v422: f64 = v343 * v343;
        let v423: f64 = v421 + v422;
        let v424: f64 = v229 + v423;
        let v425: f64 = v345 * v328;
        let v426: f64 = v348 * v330;
        let v427: f64 = v425 + v426;
        let v428: f64 = v251 + v427;
        let v429: f64 = v345 * v332;
        let v430: f64 = v348 * v334;
        let v431: f64 = v429 + v430;
        let v432: f64 = v254 + v431;
        let v433: f64 = v345 * v336;
        let v434: f64 = v348 * v338;
        let v435: f64 = v433 + v434;
        let v436: f64 = v257 + v435;
        let v437: f64 = v344 * v339;
        let v438: f64 = v345 * v340;
        let v439: f64 = v437 + v438;
        let v440: f64 = v348 * v343;
        let v441: f64 = v439 + v440;
        let v442: f64 = v262 + v441;
        let v443: f64 = v344 * v344;
        let v444: f64 = v345 * v345;
        let v445: f64 = v443 + v444;
        let v446: f64 = v348 * v348;
        let v447: f64 = v445 + v446;
        let v448: f64 = v267 + v447;
        let v449: f64 = v349 * v327;
        let v450: f64 = v351 * v328;
        let v451: f64 = v449 + v450;
        let v452: f64 = v354 * v330;
        let v453: f64 = v451 + v452;
        let v454: f64 = v351 * v332;
        let v455: f64 = v354 * v334;
        let v456: f64 = v454 + v455;
        let v457: f64 = v351 * v336;
        let v458: f64 = v354 * v338;
        let v459: f64 = v457 + v458;
        let v460: f64 = v350 * v339;
        let v461: f64 = v351 * v340;
        let v462: f64 = v460 + v461;
        let v463: f64 = v354 * v343;
        let v464: f64 = v462 + v463;
        let v465: f64 = v350 * v344;
        let v466: f64 = v351 * v345;
        let v467: f64 = v465 + v466;
        let v468: f64 = v354 * v348;
        let v469: f64 = v467 + v468;
        let v470: f64 = v349 * v349;
        let v471: f64 = v350 * v350;
        let v472: f64 = v470 + v471;
        let v473: f64 = v351 * v351;
        let v474: f64 = v472 + v473;
        let v475: f64 = v354 * v354;
        let v476: f64 = v474 + v475;
        let v477: f64 = v357 * v328;
        let v478: f64 = v360 * v330;
        let v479: f64 = v477 + v478;
        let v480: f64 = v355 * v331;
        let v481: f64 = v357 * v332;
        let v482: f64 = v480 + v481;
        let v483: f64 = v360 * v334;
        let v484: f64 = v482 + v483;
        let v485: f64 = v357 * v336;
        let v486: f64 = v360 * v338;
        let v487: f64 = v485 + v486;
        let v488: f64 = v356 * v339;
        let v489: f64 = v357 * v340;
        let v490: f64 = v488 + v489;
        let v491: f64 = v360 * v343;
        let v492: f64 = v490 + v491;
        let v493: f64 = v356 * v344;
        let v494: f64 = v357 * v345;
        let v495: f64 = v493 + v494;
        let v496: f64 = v360 * v348;
        let v497: f64 = v495 + v496;
        let v498: f64 = v356 * v350;
        let v499: f64 = v357 * v351;
        let v500: f64 = v498 + v499;
        let v501: f64 = v360 * v354;
        let v502: f64 = v500 + v501;
        let v503: f64 = v355 * v355;
        let v504: f64 = v356 * v356;
        let v505: f64 = v503 + v504;
        let v506: f64 = v357 * v357;
        let v507: f64 = v505 + v506;
        let v508: f64 = v360 * v360;
        let v509: f64 = v507 + v508;
        let v510: f64 = v363 * v328;
        let v511: f64 = v366 * v330;
        let v512: f64 = v510 + v511;
        let v513: f64 = v363 * v332;
        let v514: f64 = v366 * v334;
        let v515: f64 = v513 + v514;
        let v516: f64 = v361 * v335;
        let v517: f64 = v363 * v336;
        let v518: f64 = v516 + v517;
        let v519: f64 = v366 * v338;
        let v520: f64 = v518 + v519;
        let v521: f64 = v362 * v339;
        let v522: f64 = v363 * v340;
        let v523: f64 = v521 + v522;
        let v524: f64 = v366 * v343;
        let v525: f64 = v523 + v524;
        let v526: f64 = v362 * v344;
        let v527: f64 = v363 * v345;
        let v528: f64 = v526 + v527;
        let v529: f64 = v366 * v348;
        let v530: f64 = v528 + v529;
        let v531: f64 = v362 * v350;
        let v532: f64 = v363 * v351;
        let v533: f64 = v531 + v532;
        let v534: f64 = v366 * v354;
        let v535: f64 = v533 + v534;
        let v536: f64 = v362 * v356;
        let v537: f64 = v363 * v357;
        let v538: f64 = v536 + v537;
        let v539: f64 = v366 * v360;
        let v540: f64 = v538 + v539;
        let v541: f64 = v361 * v361;
        let v542: f64 = v362 * v362;
        let v543: f64 = v541 + v542;
        let v544: f64 = v363 * v363;
        let v545: f64 = v543 + v544;
        let v546: f64 = v366 * v366;
        let v547: f64 = v545 + v546;
        let v548: f64 = v368 * v328;
        let v549: f64 = v371 * v330;
        let v550: f64 = v548 + v549;
        let v551: f64 = v368 * v332;
        let v552: f64 = v371 * v334;
        let v553: f64 = v551 + v552;
        let v554: f64 = v368 * v336;
        let v555: f64 = v371 * v338;
        let v556: f64 = v554 + v555;
        let v557: f64 = v367 * v339;
        let v558: f64 = v368 * v340;
        let v559: f64 = v557 + v558;
        let v560: f64 = v371 * v343;
        let v561: f64 = v559 + v560;
        let v562: f64 = v367 * v344;
        let v563: f64 = v368 * v345;
        let v564: f64 = v562 + v563;
        let v565: f64 = v371 * v348;
        let v566: f64 = v564 + v565;
        let v567: f64 = v367 * v350;
        let v568: f64 = v368 * v351;
        let v569: f64 = v567 + v568;
        let v570: f64 = v371 * v354;
        let v571: f64 = v569 + v570;
        let v572: f64 = v367 * v356;
        let v573: f64 = v368 * v357;
        let v574: f64 = v572 + v573;
        let v575: f64 = v371 * v360;
        let v576: f64 = v574 + v575;
        let v577: f64 = v367 * v362;
        let v578: f64 = v368 * v363;
        let v579: f64 = v577 + v578;
        let v580: f64 = v371 * v366;
        let v581: f64 = v579 + v580;
        let v582: f64 = v367 * v367;
        let v583: f64 = v368 * v368;
        let v584: f64 = v582 + v583;
        let v585: f64 = v371 * v371;
        let v586: f64 = v584 + v585;
        let v587: f64 = v373 * v328;
        let v588: f64 = v376 * v330;
        let v589: f64 = v587 + v588;
        let v590: f64 = v373 * v332;
        let v591: f64 = v376 * v334;
        let v592: f64 = v590 + v591;
        let v593: f64 = v373 * v336;
        let v594: f64 = v376 * v338;
        let v595: f64 = v593 + v594;
        let v596: f64 = v372 * v339;
        let v597: f64 = v373 * v340;
        let v598: f64 = v596 + v597;
        let v599: f64 = v376 * v343;
        let v600: f64 = v598 + v599;
        let v601: f64 = v372 * v344;
        let v602: f64 = v373 * v345;
        let v603: f64 = v601 + v602;
        let v604: f64 = v376 * v348;
        let v605: f64 = v603 + v604;
        let v606: f64 = v372 * v350;
        let v607: f64 = v373 * v351;
        let v608: f64 = v606 + v607;
        let v609: f64 = v376 * v354;
        let v610: f64 = v608 + v609;
        let v611: f64 = v372 * v356;
        let v612: f64 = v373 * v357;
        let v613: f64 = v611 + v612;
        let v614: f64 = v376 * v360;
        let v615: f64 = v613 + v614;
        let v616: f64 = v372 * v362;
        let v617: f64 = v373 * v363;
        let v618: f64 = v616 + v617;
        let v619: f64 = v376 * v366;
        let v620: f64 = v618 + v619;
        let v621: f64 = v372 * v367;
        let v622: f64 = v373 * v368;
        let v623: f64 = v621 + v622;
        let v624: f64 = v376 * v371;
        let v625: f64 = v623 + v624;
        let v626: f64 = v372 * v372;
        let v627: f64 = v373 * v373;
        let v628: f64 = v626 + v627;
        let v629: f64 = v376 * v376;
        let v630: f64 = v628 + v629;
        if !((c * mass[20]) > 0.0 && (c * mass[20]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[20]), 12));
        }
        let v631: f64 = (c * mass[20]).sqrt();
        let v632: f64 = 1.0 / v631;
        st[18] = v632;
        if !((c * mass[21]) > 0.0 && (c * mass[21]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[21]), 13));
        }
        let v633: f64 = (c * mass[21]).sqrt();
        let v634: f64 = 1.0 / v633;
        st[19] = v634;
        if !((c * mass[22]) > 0.0 && (c * mass[22]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[22]), 14));
        }
        let v635: f64 = (c * mass[22]).sqrt();
        let v636: f64 = 1.0 / v635;
        st[20] = v636;
        if !((c * mass[23]) > 0.0 && (c * mass[23]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[23]), 15));
        }
        let v637: f64 = (c * mass[23]).sqrt();
        let v638: f64 = 1.0 / v637;
        st[21] = v638;
        let v639: f64 = (c * mass[27]) * v638;
        st[4] = v639;
        if !((c * mass[25]) > 0.0 && (c * mass[25]) <= f64::MAX) {
            return Err(mass_pivot_error((c * mass[25]), 16));
        }
        let v640: f64 = (c * mass[25]).sqrt();
        let v641: f64 = 1.0 / v640;
        st[22] = v641;
        let v642: f64 = (c * mass[28]) * v641;
        st[5] = v642;
        let v643: f64 = (c * mass[29]) - v639 * v639;
        let v644: f64 = v643 - v642 * v642;
        if !(v644 > 0.0 && v644 <= f64::MAX) {
            return Err(mass_pivot_error(v644, 17));
        }
        let v645: f64 = v644.sqrt();
        let v646: f64 = 1.0 / v645;
        st[23] = v646;
        let v647: f64 = phi_q[46] * v632;
        st[90] = v647;
        let v648: f64 = phi_q[47] * v638;
        st[91] = v648;
        let v649: f64 = phi_q[48] * v641;
        st[92] = v649;
        let v650: f64 = phi_q[49] - v639 * v648;
        let v651: f64 = v650 - v642 * v649;
        let v652: f64 = v651 * v646;
        st[93] = v652;
        let v653: f64 = phi_q[54] * v634;
        st[94] = v653;
        let v654: f64 = phi_q[55] * v638;
        st[95] = v654;
        let v655: f64 = phi_q[56] * v641;
        st[96] = v655;
        let v656: f64 = phi_q[57] - v639 * v654;
        let v657: f64 = v656 - v642 * v655;
        let v658: f64 = v657 * v646;
        st[97] = v658;
        let v659: f64 = phi_q[61] * v636;
        st[98] = v659;
        let v660: f64 = phi_q[62] * v638;
        st[99] = v660;
        let v661: f64 = phi_q[63] * v641;
        st[100] = v661;
        let v662: f64 = -(v639 * v660);
        let v663: f64 = v662 - v642 * v661;
        let v664: f64 = v663 * v646;
        st[101] = v664;
        let v665: f64 = phi_q[67] * v638;
        st[102] = v665;
        let v666: f64 = phi_q[68] * v641;
        st[103] = v666;
        let v667: f64 = phi_q[69] - v639 * v665;
        let v668: f64 = v667 - v642 * v666;
        let v669: f64 = v668 * v646;
        st[104] = v669;
        let v670: f64 = phi_q[73] * v638;
        st[105] = v670;
        let v671: f64 = phi_q[74] * v641;
        st[106] = v671;
        let v672: f64 = phi_q[75] - v639 * v670;
        let v673: f64 = v672 - v642 * v671;
        let v674: f64 = v673 * v646;
        st[107] = v674;
        let v675: f64 = phi_q[76] * v632;
        st[108] = v675;
        let v676: f64 = phi_q[77] * v638;
        st[109] = v676;
        let v677: f64 = phi_q[78] * v641;
        st[110] = v677;
        let v678: f64 = phi_q[79] - v639 * v676;
        let v679: f64 = v678 - v642 * v677;
        let v680: f64 = v679 * v646;
        st[111] = v680;
        let v681: f64 = phi_q[80] * v634;
        st[112] = v681;
        let v682: f64 = phi_q[81] * v638;
        st[113] = v682;
        let v683: f64 = phi_q[82] * v641;
        st[114] = v683;
        let v684: f64 = phi_q[83] - v639 * v682;
        let v685: f64 = v684 - v642 * v683;
        let v686: f64 = v685 * v646;
        st[115] = v686;
        let v687: f64 = v647 * v647;
        let v688: f64 = v648 * v648;
        let v689: f64 = v687 + v688;
        let v690: f64 = v649 * v649;
        let v691: f64 = v689 + v690;
        let v692: f64 = v652 * v652;
        let v693: f64 = v691 + v692;
        let v694: f64 = v476 + v693;
        let v695: f64 = v654 * v648;
        let v696: f64 = v655 * v649;
        let v697: f64 = v695 + v696;
        let v698: f64 = v658 * v652;
        let v699: f64 = v697 + v698;
        let v700: f64 = v502 + v699;
        let v701: f64 = v653 * v653;
        let v702: f64 = v654 * v654;
        let v703: f64 = v701 + v702;
        let v704: f64 = v655 * v655;
        let v705: f64 = v703 + v704;
        let v706: f64 = v658 * v658;
        let v707: f64 = v705 + v706;
        let v708: f64 = v509 + v707;
        let v709: f64 = v660 * v648;
        let v710: f64 = v661 * v649;
        let v711: f64 = v709 + v710;
        let v712: f64 = v664 * v652;
        let v713: f64 = v711 + v712;
        let v714: f64 = v535 + v713;
        let v715: f64 = v660 * v654;
        let v716: f64 = v661 * v655;
        let v717: f64 = v715 + v716;
        let v718: f64 = v664 * v658;
        let v719: f64 = v717 + v718;
        let v720: f64 = v540 + v719;
        let v721: f64 = v659 * v659;
        let v722: f64 = v660 * v660;
        let v723: f64 = v721 + v722;
        let v724: f64 = v661 * v661;
        let v725: f64 = v723 + v724;
        let v726: f64 = v664 * v664;
        let v727: f64 = v725 + v726;
        let v728: f64 = v547 + v727;
        let v729: f64 = v665 * v648;
        let v730: f64 = v666 * v649;
        let v731: f64 = v729 + v730;
        let v732: f64 = v669 * v652;
        let v733: f64 = v731 + v732;
        let v734: f64 = v571 + v733;
        let v735: f64 = v665 * v654;
        let v736: f64 = v666 * v655;
        let v737: f64 = v735 + v736;
        let v738: f64 = v669 * v658;
        let v739: f64 = v737 + v738;
        let v740: f64 = v576 + v739;
        let v741: f64 = v665 * v660;
        let v742: f64 = v666 * v661;
        let v743: f64 = v741 + v742;
        let v744: f64 = v669 * v664;
        let v745: f64 = v743 + v744;
        let v746: f64 = v581 + v745;
        let v747: f64 = v665 * v665;
        let v748: f64 = v666 * v666;
        let v749: f64 = v747 + v748;
        let v750: f64 = v669 * v669;
        let v751: f64 = v749 + v750;
        let v752: f64 = v586 + v751;
        let v753: f64 = v670 * v648;
        let v754: f64 = v671 * v649;
        let v755: f64 = v753 + v754;
        let v756: f64 = v674 * v652;
        let v757: f64 = v755 + v756;
        let v758: f64 = v610 + v757;
        let v759: f64 = v670 * v654;
        let v760: f64 = v671 * v655;
        let v761: f64 = v759 + v760;
        let v762: f64 = v674 * v658;
        let v763: f64 = v761 + v762;
        let v764: f64 = v615 + v763;
        let v765: f64 = v670 * v660;
        let v766: f64 = v671 * v661;
        let v767: f64 = v765 + v766;
        let v768: f64 = v674 * v664;
        let v769: f64 = v767 + v768;
        let v770: f64 = v620 + v769;
        let v771: f64 = v670 * v665;
        let v772: f64 = v671 * v666;
        let v773: f64 = v771 + v772;
        let v774: f64 = v674 * v669;
        let v775: f64 = v773 + v774;
        let v776: f64 = v625 + v775;
        let v777: f64 = v670 * v670;
        let v778: f64 = v671 * v671;
        let v779: f64 = v777 + v778;
        let v780: f64 = v674 * v674;
        let v781: f64 = v779 + v780;
        let v782: f64 = v630 + v781;
        let v783: f64 = v675 * v647;
        let v784: f64 = v676 * v648;
        let v785: f64 = v783 + v784;
        let v786: f64 = v677 * v649;
        let v787: f64 = v785 + v786;
        let v788: f64 = v680 * v652;
        let v789: f64 = v787 + v788;
        let v790: f64 = v676 * v654;
        let v791: f64 = v677 * v655;
        let v792: f64 = v790 + v791;
        let v793: f64 = v680 * v658;
        let v794: f64 = v792 + v793;
        let v795: f64 = v676 * v660;
        let v796: f64 = v677 * v661;
        let v797: f64 = v795 + v796;
        let v798: f64 = v680 * v664;
        let v799: f64 = v797 + v798;
        let v800: f64 = v676 * v665;
        let v801: f64 = v677 * v666;
        let v802: f64 = v800 + v801;
        let v803: f64 = v680 * v669;
        let v804: f64 = v802 + v803;
        let v805: f64 = v676 * v670;
        let v806: f64 = v677 * v671;
        let v807: f64 = v805 + v806;
        let v808: f64 = v680 * v674;
        let v809: f64 = v807 + v808;
        let v810: f64 = v675 * v675;
        let v811: f64 = v676 * v676;
        let v812: f64 = v810 + v811;
        let v813: f64 = v677 * v677;
        let v814: f64 = v812 + v813;
        let v815: f64 = v680 * v680;
        let v816: f64 = v814 + v815;
        let v817: f64 = v682 * v648;
        let v818: f64 = v683 * v649;
        let v819: f64 = v817 + v818;
        let v820: f64 = v686 * v652;
        let v821: f64 = v819 + v820;
        let v822: f64 = v681 * v653;
        let v823: f64 = v682 * v654;
        let v824: f64 = v822 + v823;
        let v825: f64 = v683 * v655;
        let v826: f64 = v824 + v825;
        let v827: f64 = v686 * v658;
        let v828: f64 = v826 + v827;
        let v829: f64 = v682 * v660;
        let v830: f64 = v683 * v661;
        let v831: f64 = v829 + v830;
        let v832: f64 = v686 * v664;
        let v833: f64 = v831 + v832;
        let v834: f64 = v682 * v665;
        let v835: f64 = v683 * v666;
        let v836: f64 = v834 + v835;
        let v837: f64 = v686 * v669;
        let v838: f64 = v836 + v837;
        let v839: f64 = v682 * v670;
        let v840: f64 = v683 * v671;
        let v841: f64 = v839 + v840;
        let v842: f64 = v686 * v674;
        let v843: f64 = v841 + v842;
        let v844: f64 = v682 * v676;
        let v845: f64 = v683 * v677;
        let v846: f64 = v844 + v845;
        let v847: f64 = v686 * v680;
        let v848: f64 = v846 + v847;
        let v849: f64 = v681 * v681;
        let v850: f64 = v682 * v682;
        let v851: f64 = v849 + v850;
        let v852: f64 = v683 * v683;
        let v853: f64 = v851 + v852;
        let v854: f64 = v686 * v686;
        let v855: f64 = v853 + v854;
        let (v856, v857) = piv.pivot(0.0, 0.0, 17, true)?;
        st[217] = v856;
        let (v858, v859) = piv.pivot(0.0, 0.0, 18, true)?;
        st[218] = v858;
        let (v860, v861) = piv.pivot(0.0, 0.0, 19, true)?;
        st[219] = v860;
        let (v862, v863) = piv.pivot(v816, v816, 15, false)?;
        st[220] = v862;
        let v864: f64 = v848 * v862;
        st[116] = v864;
        let v865: f64 = v855 - v864 * v863 * v864;
        let v866: f64 = v789 * v862;
        st[117] = v866;
        let v867: f64 = v694 - v866 * v863 * v866;
        let v868: f64 = v794 * v862;
        st[118] = v868;
        let v869: f64 = v708 - v868 * v863 * v868;
        let v870: f64 = v799 * v862;
        st[119] = v870;
        let v871: f64 = v728 - v870 * v863 * v870;
        let v872: f64 = v804 * v862;
        st[120] = v872;
        let v873: f64 = v752 - v872 * v863 * v872;
        let v874: f64 = v809 * v862;
        st[121] = v874;
        let v875: f64 = v782 - v874 * v863 * v874;
        let v876: f64 = v821 - v866 * v863 * v864;
        let v877: f64 = v828 - v868 * v863 * v864;
        let v878: f64 = v700 - v868 * v863 * v866;
        let v879: f64 = v833 - v870 * v863 * v864;
        let v880: f64 = v714 - v870 * v863 * v866;
        let v881: f64 = v720 - v870 * v863 * v868;
        let v882: f64 = v838 - v872 * v863 * v864;
        let v883: f64 = v734 - v872 * v863 * v866;
        let v884: f64 = v740 - v872 * v863 * v868;
        let v885: f64 = v746 - v872 * v863 * v870;
        let v886: f64 = v843 - v874 * v863 * v864;
        let v887: f64 = v758 - v874 * v863 * v866;
        let v888: f64 = v764 - v874 * v863 * v868;
        let v889: f64 = v770 - v874 * v863 * v870;
        let v890: f64 = v776 - v874 * v863 * v872;
        let (v891, v892) = piv.pivot(v865, v855, 16, false)?;
        st[221] = v891;
        let v893: f64 = v876 * v891;
        st[122] = v893;
        let v894: f64 = v867 - v893 * v892 * v893;
        let v895: f64 = v877 * v891;
        st[123] = v895;
        let v896: f64 = v869 - v895 * v892 * v895;
        let v897: f64 = v879 * v891;
        st[124] = v897;
        let v898: f64 = v871 - v897 * v892 * v897;
        let v899: f64 = v882 * v891;
        st[125] = v899;
        let v900: f64 = v873 - v899 * v892 * v899;
        let v901: f64 = v886 * v891;
        st[126] = v901;
        let v902: f64 = v875 - v901 * v892 * v901;
        let v903: f64 = v878 - v895 * v892 * v893;
        let v904: f64 = v880 - v897 * v892 * v893;
        let v905: f64 = v881 - v897 * v892 * v895;
        let v906: f64 = v883 - v899 * v892 * v893;
        let v907: f64 = v884 - v899 * v892 * v895;
        let v908: f64 = v885 - v899 * v892 * v897;
        let v909: f64 = v887 - v901 * v892 * v893;
        let v910: f64 = v888 - v901 * v892 * v895;
        let v911: f64 = v889 - v901 * v892 * v897;
        let v912: f64 = v890 - v901 * v892 * v899;
        let (v913, v914) = piv.pivot(v894, v694, 10, false)?;
        st[222] = v913;
        let v915: f64 = v903 * v913;
        st[127] = v915;
        let v916: f64 = v896 - v915 * v914 * v915;
        let v917: f64 = v904 * v913;
        st[128] = v917;
        let v918: f64 = v898 - v917 * v914 * v917;
        let v919: f64 = v906 * v913;
        st[129] = v919;
        let v920: f64 = v900 - v919 * v914 * v919;
        let v921: f64 = v909 * v913;
        st[130] = v921;
        let v922: f64 = v902 - v921 * v914 * v921;
        let v923: f64 = v453 * v913;
        st[131] = v923;
        let v924: f64 = v382 - v923 * v914 * v923;
        let v925: f64 = v456 * v913;
        st[132] = v925;
        let v926: f64 = v392 - v925 * v914 * v925;
        let v927: f64 = v459 * v913;
        st[133] = v927;
        let v928: f64 = v406 - v927 * v914 * v927;
        let v929: f64 = v464 * v913;
        st[134] = v929;
        let v930: f64 = v424 - v929 * v914 * v929;
        let v931: f64 = v469 * v913;
        st[135] = v931;
        let v932: f64 = v448 - v931 * v914 * v931;
        let v933: f64 = v905 - v917 * v914 * v915;
        let v934: f64 = v907 - v919 * v914 * v915;
        let v935: f64 = v908 - v919 * v914 * v917;
        let v936: f64 = v910 - v921 * v914 * v915;
        let v937: f64 = v911 - v921 * v914 * v917;
        let v938: f64 = v912 - v921 * v914 * v919;
        let v939: f64 = v479 - v923 * v914 * v915;
        let v940: f64 = v512 - v923 * v914 * v917;
        let v941: f64 = v550 - v923 * v914 * v919;
        let v942: f64 = v589 - v923 * v914 * v921;
        let v943: f64 = v484 - v925 * v914 * v915;
        let v944: f64 = v515 - v925 * v914 * v917;
        let v945: f64 = v553 - v925 * v914 * v919;
        let v946: f64 = v592 - v925 * v914 * v921;
        let v947: f64 = v386 - v925 * v914 * v923;
        let v948: f64 = v487 - v927 * v914 * v915;
        let v949: f64 = v520 - v927 * v914 * v917;
        let v950: f64 = v556 - v927 * v914 * v919;
        let v951: f64 = v595 - v927 * v914 * v921;
        let v952: f64 = v396 - v927 * v914 * v923;
        let v953: f64 = v400 - v927 * v914 * v925;
        let v954: f64 = v492 - v929 * v914 * v915;
        let v955: f64 = v525 - v929 * v914 * v917;
        let v956: f64 = v561 - v929 * v914 * v919;
        let v957: f64 = v600 - v929 * v914 * v921;
        let v958: f64 = v410 - v929 * v914 * v923;
        let v959: f64 = v414 - v929 * v914 * v925;
        let v960: f64 = v418 - v929 * v914 * v927;
        let v961: f64 = v497 - v931 * v914 * v915;
        let v962: f64 = v530 - v931 * v914 * v917;
        let v963: f64 = v566 - v931 * v914 * v919;
        let v964: f64 = v605 - v931 * v914 * v921;
        let v965: f64 = v428 - v931 * v914 * v923;
        let v966: f64 = v432 - v931 * v914 * v925;
        let v967: f64 = v436 - v931 * v914 * v927;
        let v968: f64 = v442 - v931 * v914 * v929;
        let (v969, v970) = piv.pivot(v916, v708, 11, false)?;
        st[223] = v969;
        let v971: f64 = v933 * v969;
        st[136] = v971;
        let v972: f64 = v918 - v971 * v970 * v971;
        let v973: f64 = v934 * v969;
        st[137] = v973;
        let v974: f64 = v920 - v973 * v970 * v973;
        let v975: f64 = v936 * v969;
        st[138] = v975;
        let v976: f64 = v922 - v975 * v970 * v975;
        let v977: f64 = v939 * v969;
        st[139] = v977;
        let v978: f64 = v924 - v977 * v970 * v977;
        let v979: f64 = v943 * v969;
        st[140] = v979;
        let v980: f64 = v926 - v979 * v970 * v979;
        let v981: f64 = v948 * v969;
        st[141] = v981;
        let v982: f64 = v928 - v981 * v970 * v981;
        let v983: f64 = v954 * v969;
        st[142] = v983;
        let v984: f64 = v930 - v983 * v970 * v983;
        let v985: f64 = v961 * v969;
        st[143] = v985;
        let v986: f64 = v932 - v985 * v970 * v985;
        let v987: f64 = v935 - v973 * v970 * v971;
        let v988: f64 = v937 - v975 * v970 * v971;
        let v989: f64 = v938 - v975 * v970 * v973;
        let v990: f64 = v940 - v977 * v970 * v971;
        let v991: f64 = v941 - v977 * v970 * v973;
        let v992: f64 = v942 - v977 * v970 * v975;
        let v993: f64 = v944 - v979 * v970 * v971;
        let v994: f64 = v945 - v979 * v970 * v973;
        let v995: f64 = v946 - v979 * v970 * v975;
        let v996: f64 = v947 - v979 * v970 * v977;
        let v997: f64 = v949 - v981 * v970 * v971;
        let v998: f64 = v950 - v981 * v970 * v973;
        let v999: f64 = v951 - v981 * v970 * v975;
        let v1000: f64 = v952 - v981 * v970 * v977;
        let v1001: f64 = v953 - v981 * v970 * v979;
        let v1002: f64 = v955 - v983 * v970 * v971;
        let v1003: f64 = v956 - v983 * v970 * v973;
        let v1004: f64 = v957 - v983 * v970 * v975;
        let v1005: f64 = v958 - v983 * v970 * v977;
        let v1006: f64 = v959 - v983 * v970 * v979;
        let v1007: f64 = v960 - v983 * v970 * v981;
        let v1008: f64 = v962 - v985 * v970 * v971;
        let v1009: f64 = v963 - v985 * v970 * v973;
        let v1010: f64 = v964 - v985 * v970 * v975;
        let v1011: f64 = v965 - v985 * v970 * v977;
        let v1012: f64 = v966 - v985 * v970 * v979;
        let v1013: f64 = v967 - v985 * v970 * v981;
        let v1014: f64 = v968 - v985 * v970 * v983;
        let (v1015, v1016) = piv.pivot(v972, v728, 12, false)?;
        st[224] = v1015;
        let v1017: f64 = v987 * v1015;
        st[144] = v1017;
        let v1018: f64 = v974 - v1017 * v1016 * v1017;
        let v1019: f64 = v988 * v1015;
        st[145] = v1019;
        let v1020: f64 = v976 - v1019 * v1016 * v1019;
        let v1021: f64 = v990 * v1015;
        st[146] = v1021;
        let v1022: f64 = v978 - v1021 * v1016 * v1021;
        let v1023: f64 = v993 * v1015;
        st[147] = v1023;
        let v1024: f64 = v980 - v1023 * v1016 * v1023;
        let v1025: f64 = v997 * v1015;
        st[148] = v1025;
        let v1026: f64 = v982 - v1025 * v1016 * v1025;
        let v1027: f64 = v1002 * v1015;
        st[149] = v1027;
        let v1028: f64 = v984 - v1027 * v1016 * v1027;
        let v1029: f64 = v1008 * v1015;
        st[150] = v1029;
        let v1030: f64 = v986 - v1029 * v1016 * v1029;
        let v1031: f64 = v989 - v1019 * v1016 * v1017;
        let v1032: f64 = v991 - v1021 * v1016 * v1017;
        let v1033: f64 = v992 - v1021 * v1016 * v1019;
        let v1034: f64 = v994 - v1023 * v1016 * v1017;
        let v1035: f64 = v995 - v1023 * v1016 * v1019;
        let v1036: f64 = v996 - v1023 * v1016 * v1021;
        let v1037: f64 = v998 - v1025 * v1016 * v1017;
        let v1038: f64 = v999 - v1025 * v1016 * v1019;
        let v1039: f64 = v1000 - v1025 * v1016 * v1021;
        let v1040: f64 = v1001 - v1025 * v1016 * v1023;
        let v1041: f64 = v1003 - v1027 * v1016 * v1017;
        let v1042: f64 = v1004 - v1027 * v1016 * v1019;
        let v1043: f64 = v1005 - v1027 * v1016 * v1021;
        let v1044: f64 = v1006 - v1027 * v1016 * v1023;
        let v1045: f64 = v1007 - v1027 * v1016 * v1025;
        let v1046: f64 = v1009 - v1029 * v1016 * v1017;
        let v1047: f64 = v1010 - v1029 * v1016 * v1019;
        let v1048: f64 = v1011 - v1029 * v1016 * v1021;
        let v1049: f64 = v1012 - v1029 * v1016 * v1023;
        let v1050: f64 = v1013 - v1029 * v1016 * v1025;
        let v1051: f64 = v1014 - v1029 * v1016 * v1027;
        let (v1052, v1053) = piv.pivot(v1018, v752, 13, false)?;
        st[225] = v1052;
        let v1054: f64 = v1031 * v1052;
        st[151] = v1054;
        let v1055: f64 = v1020 - v1054 * v1053 * v1054;
        let v1056: f64 = v1032 * v1052;
        st[152] = v1056;
        let v1057: f64 = v1022 - v1056 * v1053 * v1056;
        let v1058: f64 = v1034 * v1052;
        st[153] = v1058;
        let v1059: f64 = v1024 - v1058 * v1053 * v1058;
        let v1060: f64 = v1037 * v1052;
        st[154] = v1060;
        let v1061: f64 = v1026 - v1060 * v1053 * v1060;
        let v1062: f64 = v1041 * v1052;
        st[155] = v1062;
        let v1063: f64 = v1028 - v1062 * v1053 * v1062;
        let v1064: f64 = v1046 * v1052;
        st[156] = v1064;
        let v1065: f64 = v1030 - v1064 * v1053 * v1064;
        let v1066: f64 = v1033 - v1056 * v1053 * v1054;
        let v1067: f64 = v1035 - v1058 * v1053 * v1054;
        let v1068: f64 = v1036 - v1058 * v1053 * v1056;
        let v1069: f64 = v1038 - v1060 * v1053 * v1054;
        let v1070: f64 = v1039 - v1060 * v1053 * v1056;
        let v1071: f64 = v1040 - v1060 * v1053 * v1058;
        let v1072: f64 = v1042 - v1062 * v1053 * v1054;
        let v1073: f64 = v1043 - v1062 * v1053 * v1056;
        let v1074: f64 = v1044 - v1062 * v1053 * v1058;
        let v1075: f64 = v1045 - v1062 * v1053 * v1060;
        let v1076: f64 = v1047 - v1064 * v1053 * v1054;
        let v1077: f64 = v1048 - v1064 * v1053 * v1056;
        let v1078: f64 = v1049 - v1064 * v1053 * v1058;
        let v1079: f64 = v1050 - v1064 * v1053 * v1060;
        let v1080: f64 = v1051 - v1064 * v1053 * v1062;
        let (v1081, v1082) = piv.pivot(v1055, v782, 14, false)?;
        st[226] = v1081;
        let v1083: f64 = v1066 * v1081;
        st[157] = v1083;
        let v1084: f64 = v1057 - v1083 * v1082 * v1083;
        let v1085: f64 = v1067 * v1081;
        st[158] = v1085;
        let v1086: f64 = v1059 - v1085 * v1082 * v1085;
        let v1087: f64 = v1069 * v1081;
        st[159] = v1087;
        let v1088: f64 = v1061 - v1087 * v1082 * v1087;
        let v1089: f64 = v1072 * v1081;
        st[160] = v1089;
        let v1090: f64 = v1063 - v1089 * v1082 * v1089;
        let v1091: f64 = v1076 * v1081;
        st[161] = v1091;
        let v1092: f64 = v1065 - v1091 * v1082 * v1091;
        let v1093: f64 = v1068 - v1085 * v1082 * v1083;
        let v1094: f64 = v1070 - v1087 * v1082 * v1083;
        let v1095: f64 = v1071 - v1087 * v1082 * v1085;
        let v1096: f64 = v1073 - v1089 * v1082 * v1083;
        let v1097: f64 = v1074 - v1089 * v1082 * v1085;
        let v1098: f64 = v1075 - v1089 * v1082 * v1087;
        let v1099: f64 = v1077 - v1091 * v1082 * v1083;
        let v1100: f64 = v1078 - v1091 * v1082 * v1085;
        let v1101: f64 = v1079 - v1091 * v1082 * v1087;
        let v1102: f64 = v1080 - v1091 * v1082 * v1089;
        let (v1103, v1104) = piv.pivot(v69, v69, 0, false)?;
        st[227] = v1103;
        let v1105: f64 = v72 * v1103;
        st[162] = v1105;
        let v1106: f64 = v77 - v1105 * v1104 * v1105;
        let v1107: f64 = v80 * v1103;
        st[163] = v1107;
        let v1108: f64 = v88 - v1107 * v1104 * v1107;
        let v1109: f64 = v91 * v1103;
        st[164] = v1109;
        let v1110: f64 = v102 - v1109 * v1104 * v1109;
        let v1111: f64 = v105 * v1103;
        st[165] = v1111;
        let v1112: f64 = v121 - v1111 * v1104 * v1111;
        let v1113: f64 = v126 * v1103;
        st[166] = v1113;
        let v1114: f64 = v1084 - v1113 * v1104 * v1113;
        let v1115: f64 = v146 * v1103;
        st[167] = v1115;
        let v1116: f64 = v1086 - v1115 * v1104 * v1115;
        let v1117: f64 = v171 * v1103;
        st[168] = v1117;
        let v1118: f64 = v1088 - v1117 * v1104 * v1117;
        let v1119: f64 = v199 * v1103;
        st[169] = v1119;
        let v1120: f64 = v1090 - v1119 * v1104 * v1119;
        let v1121: f64 = v232 * v1103;
        st[170] = v1121;
        let v1122: f64 = v1092 - v1121 * v1104 * v1121;
        let v1123: f64 = v270 * v1103;
        st[171] = v1123;
        let v1124: f64 = v310 - v1123 * v1104 * v1123;
        let v1125: f64 = v83 - v1107 * v1104 * v1105;
        let v1126: f64 = v94 - v1109 * v1104 * v1105;
        let v1127: f64 = v97 - v1109 * v1104 * v1107;
        let v1128: f64 = v108 - v1111 * v1104 * v1105;
        let v1129: f64 = v111 - v1111 * v1104 * v1107;
        let v1130: f64 = v116 - v1111 * v1104 * v1109;
        let v1131: f64 = v129 - v1113 * v1104 * v1105;
        let v1132: f64 = v132 - v1113 * v1104 * v1107;
        let v1133: f64 = v135 - v1113 * v1104 * v1109;
        let v1134: f64 = v138 - v1113 * v1104 * v1111;
        let v1135: f64 = v151 - v1115 * v1104 * v1105;
        let v1136: f64 = v154 - v1115 * v1104 * v1107;
        let v1137: f64 = v157 - v1115 * v1104 * v1109;
        let v1138: f64 = v160 - v1115 * v1104 * v1111;
        let v1139: f64 = v1093 - v1115 * v1104 * v1113;
        let v1140: f64 = v174 - v1117 * v1104 * v1105;
        let v1141: f64 = v179 - v1117 * v1104 * v1107;
        let v1142: f64 = v182 - v1117 * v1104 * v1109;
        let v1143: f64 = v185 - v1117 * v1104 * v1111;
        let v1144: f64 = v1094 - v1117 * v1104 * v1113;
        let v1145: f64 = v1095 - v1117 * v1104 * v1115;
        let v1146: f64 = v202 - v1119 * v1104 * v1105;
        let v1147: f64 = v205 - v1119 * v1104 * v1107;
        let v1148: f64 = v210 - v1119 * v1104 * v1109;
        let v1149: f64 = v215 - v1119 * v1104 * v1111;
        let v1150: f64 = v1096 - v1119 * v1104 * v1113;
        let v1151: f64 = v1097 - v1119 * v1104 * v1115;
        let v1152: f64 = v1098 - v1119 * v1104 * v1117;
        let v1153: f64 = v235 - v1121 * v1104 * v1105;
        let v1154: f64 = v238 - v1121 * v1104 * v1107;
        let v1155: f64 = v243 - v1121 * v1104 * v1109;
        let v1156: f64 = v248 - v1121 * v1104 * v1111;
        let v1157: f64 = v1099 - v1121 * v1104 * v1113;
        let v1158: f64 = v1100 - v1121 * v1104 * v1115;
        let v1159: f64 = v1101 - v1121 * v1104 * v1117;
        let v1160: f64 = v1102 - v1121 * v1104 * v1119;
        let v1161: f64 = v273 - v1123 * v1104 * v1105;
        let v1162: f64 = v276 - v1123 * v1104 * v1107;
        let v1163: f64 = v281 - v1123 * v1104 * v1109;
        let v1164: f64 = v286 - v1123 * v1104 * v1111;
        let v1165: f64 = v289 - v1123 * v1104 * v1113;
        let v1166: f64 = v292 - v1123 * v1104 * v1115;
        let v1167: f64 = v295 - v1123 * v1104 * v1117;
        let v1168: f64 = v300 - v1123 * v1104 * v1119;
        let v1169: f64 = v305 - v1123 * v1104 * v1121;
        let (v1170, v1171) = piv.pivot(v1106, v77, 1, false)?;
        st[228] = v1170;
        let v1172: f64 = v1125 * v1170;
        st[172] = v1172;
        let v1173: f64 = v1108 - v1172 * v1171 * v1172;
        let v1174: f64 = v1126 * v1170;
        st[173] = v1174;
        let v1175: f64 = v1110 - v1174 * v1171 * v1174;
        let v1176: f64 = v1128 * v1170;
        st[174] = v1176;
        let v1177: f64 = v1112 - v1176 * v1171 * v1176;
        let v1178: f64 = v1131 * v1170;
        st[175] = v1178;
        let v1179: f64 = v1114 - v1178 * v1171 * v1178;
        let v1180: f64 = v1135 * v1170;
        st[176] = v1180;
        let v1181: f64 = v1116 - v1180 * v1171 * v1180;
        let v1182: f64 = v1140 * v1170;
        st[177] = v1182;
        let v1183: f64 = v1118 - v1182 * v1171 * v1182;
        let v1184: f64 = v1146 * v1170;
        st[178] = v1184;
        let v1185: f64 = v1120 - v1184 * v1171 * v1184;
        let v1186: f64 = v1153 * v1170;
        st[179] = v1186;
        let v1187: f64 = v1122 - v1186 * v1171 * v1186;
        let v1188: f64 = v1161 * v1170;
        st[180] = v1188;
        let v1189: f64 = v1124 - v1188 * v1171 * v1188;
        let v1190: f64 = v1127 - v1174 * v1171 * v1172;
        let v1191: f64 = v1129 - v1176 * v1171 * v1172;
        let v1192: f64 = v1130 - v1176 * v1171 * v1174;
        let v1193: f64 = v1132 - v1178 * v1171 * v1172;
        let v1194: f64 = v1133 - v1178 * v1171 * v1174;
        let v1195: f64 = v1134 - v1178 * v1171 * v1176;
        let v1196: f64 = v1136 - v1180 * v1171 * v1172;
        let v1197: f64 = v1137 - v1180 * v1171 * v1174;
        let v1198: f64 = v1138 - v1180 * v1171 * v1176;
        let v1199: f64 = v1139 - v1180 * v1171 * v1178;
        let v1200: f64 = v1141 - v1182 * v1171 * v1172;
        let v1201: f64 = v1142 - v1182 * v1171 * v1174;
        let v1202: f64 = v1143 - v1182 * v1171 * v1176;
        let v1203: f64 = v1144 - v1182 * v1171 * v1178;
        let v1204: f64 = v1145 - v1182 * v1171 * v1180;
        let v1205: f64 = v1147 - v1184 * v1171 * v1172;
        let v1206: f64 = v1148 - v1184 * v1171 * v1174;
        let v1207: f64 = v1149 - v1184 * v1171 * v1176;
        let v1208: f64 = v1150 - v1184 * v1171 * v1178;
        let v1209: f64 = v1151 - v1184 * v1171 * v1180;
        let v1210: f64 = v1152 - v1184 * v1171 * v1182;
        let v1211: f64 = v1154 - v1186 * v1171 * v1172;
        let v1212: f64 = v1155 - v1186 * v1171 * v1174;
        let v1213: f64 = v1156 - v1186 * v1171 * v1176;
        let v1214: f64 = v1157 - v1186 * v1171 * v1178;
        let v1215: f64 = v1158 - v1186 * v1171 * v1180;
        let v1216: f64 = v1159 - v1186 * v1171 * v1182;
        let v1217: f64 = v1160 - v1186 * v1171 * v1184;
        let v1218: f64 = v1162 - v1188 * v1171 * v1172;
        let v1219: f64 = v1163 - v1188 * v1171 * v1174;
        let v1220: f64 = v1164 - v1188 * v1171 * v1176;
        let v1221: f64 = v1165 - v1188 * v1171 * v1178;
        let v1222: f64 = v1166 - v1188 * v1171 * v1180;
        let v1223: f64 = v1167 - v1188 * v1171 * v1182;
        let v1224: f64 = v1168 - v1188 * v1171 * v1184;
        let v1225: f64 = v1169 - v1188 * v1171 * v1186;
        let (v1226, v1227) = piv.pivot(v1173, v88, 2, false)?;
        st[229] = v1226;
        let v1228: f64 = v1190 * v1226;
        st[181] = v1228;
        let v1229: f64 = v1175 - v1228 * v1227 * v1228;
        let v1230: f64 = v1191 * v1226;
        st[182] = v1230;
        let v1231: f64 = v1177 - v1230 * v1227 * v1230;
        let v1232: f64 = v1193 * v1226;
        st[183] = v1232;
        let v1233: f64 = v1179 - v1232 * v1227 * v1232;
        let v1234: f64 = v1196 * v1226;
        st[184] = v1234;
        let v1235: f64 = v1181 - v1234 * v1227 * v1234;
        let v1236: f64 = v1200 * v1226;
        st[185] = v1236;
        let v1237: f64 = v1183 - v1236 * v1227 * v1236;
        let v1238: f64 = v1205 * v1226;
        st[186] = v1238;
        let v1239: f64 = v1185 - v1238 * v1227 * v1238;
        let v1240: f64 = v1211 * v1226;
        st[187] = v1240;
        let v1241: f64 = v1187 - v1240 * v1227 * v1240;
        let v1242: f64 = v1218 * v1226;
        st[188] = v1242;
        let v1243: f64 = v1189 - v1242 * v1227 * v1242;
        let v1244: f64 = v1192 - v1230 * v1227 * v1228;
        let v1245: f64 = v1194 - v1232 * v1227 * v1228;
        let v1246: f64 = v1195 - v1232 * v1227 * v1230;
        let v1247: f64 = v1197 - v1234 * v1227 * v1228;
        let v1248: f64 = v1198 - v1234 * v1227 * v1230;
        let v1249: f64 = v1199 - v1234 * v1227 * v1232;
        let v1250: f64 = v1201 - v1236 * v1227 * v1228;
        let v1251: f64 = v1202 - v1236 * v1227 * v1230;
        let v1252: f64 = v1203 - v1236 * v1227 * v1232;
        let v1253: f64 = v1204 - v1236 * v1227 * v1234;
        let v1254: f64 = v1206 - v1238 * v1227 * v1228;
        let v1255: f64 = v1207 - v1238 * v1227 * v1230;
        let v1256: f64 = v1208 - v1238 * v1227 * v1232;
        let v1257: f64 = v1209 - v1238 * v1227 * v1234;
        let v1258: f64 = v1210 - v1238 * v1227 * v1236;
        let v1259: f64 = v1212 - v1240 * v1227 * v1228;
        let v1260: f64 = v1213 - v1240 * v1227 * v1230;
        let v1261: f64 = v1214 - v1240 * v1227 * v1232;
        let v1262: f64 = v1215 - v1240 * v1227 * v1234;
        let v1263: f64 = v1216 - v1240 * v1227 * v1236;
        let v1264: f64 = v1217 - v1240 * v1227 * v1238;
        let v1265: f64 = v1219 - v1242 * v1227 * v1228;
        let v1266: f64 = v1220 - v1242 * v1227 * v1230;
        let v1267: f64 = v1221 - v1242 * v1227 * v1232;
        let v1268: f64 = v1222 - v1242 * v1227 * v1234;
        let v1269: f64 = v1223 - v1242 * v1227 * v1236;
        let v1270: f64 = v1224 - v1242 * v1227 * v1238;
        let v1271: f64 = v1225 - v1242 * v1227 * v1240;
        let (v1272, v1273) = piv.pivot(v1229, v102, 3, false)?;
        st[230] = v1272;
        let v1274: f64 = v1244 * v1272;
        st[189] = v1274;
        let v1275: f64 = v1231 - v1274 * v1273 * v1274;
        let v1276: f64 = v1245 * v1272;
        st[190] = v1276;
        let v1277: f64 = v1233 - v1276 * v1273 * v1276;
        let v1278: f64 = v1247 * v1272;
        st[191] = v1278;
        let v1279: f64 = v1235 - v1278 * v1273 * v1278;
        let v1280: f64 = v1250 * v1272;
        st[192] = v1280;
        let v1281: f64 = v1237 - v1280 * v1273 * v1280;
        let v1282: f64 = v1254 * v1272;
        st[193] = v1282;
        let v1283: f64 = v1239 - v1282 * v1273 * v1282;
        let v1284: f64 = v1259 * v1272;
        st[194] = v1284;
        let v1285: f64 = v1241 - v1284 * v1273 * v1284;
        let v1286: f64 = v1265 * v1272;
        st[195] = v1286;
        let v1287: f64 = v1243 - v1286 * v1273 * v1286;
        let v1288: f64 = v1246 - v1276 * v1273 * v1274;
        let v1289: f64 = v1248 - v1278 * v1273 * v1274;
        let v1290: f64 = v1249 - v1278 * v1273 * v1276;
        let v1291: f64 = v1251 - v1280 * v1273 * v1274;
        let v1292: f64 = v1252 - v1280 * v1273 * v1276;
        let v1293: f64 = v1253 - v1280 * v1273 * v1278;
        let v1294: f64 = v1255 - v1282 * v1273 * v1274;
        let v1295: f64 = v1256 - v1282 * v1273 * v1276;
        let v1296: f64 = v1257 - v1282 * v1273 * v1278;
        let v1297: f64 = v1258 - v1282 * v1273 * v1280;
        let v1298: f64 = v1260 - v1284 * v1273 * v1274;
        let v1299: f64 = v1261 - v1284 * v1273 * v1276;
        let v1300: f64 = v1262 - v1284 * v1273 * v1278;
        let v1301: f64 = v1263 - v1284 * v1273 * v1280;
        let v1302: f64 = v1264 - v1284 * v1273 * v1282;
        let v1303: f64 = v1266 - v1286 * v1273 * v1274;
        let v1304: f64 = v1267 - v1286 * v1273 * v1276;
        let v1305: f64 = v1268 - v1286 * v1273 * v1278;
        let v1306: f64 = v1269 - v1286 * v1273 * v1280;
        let v1307: f64 = v1270 - v1286 * v1273 * v1282;
        let v1308: f64 = v1271 - v1286 * v1273 * v1284;
        let (v1309, v1310) = piv.pivot(v1275, v121, 4, false)?;
        st[231] = v1309;
        let v1311: f64 = v1288 * v1309;
        st[196] = v1311;
        let v1312: f64 = v1277 - v1311 * v1310 * v1311;
        let v1313: f64 = v1289 * v1309;
        st[197] = v1313;
        let v1314: f64 = v1279 - v1313 * v1310 * v1313;
        let v1315: f64 = v1291 * v1309;
        st[198] = v1315;
        let v1316: f64 = v1281 - v1315 * v1310 * v1315;
        let v1317: f64 = v1294 * v1309;
        st[199] = v1317;
        let v1318: f64 = v1283 - v1317 * v1310 * v1317;
        let v1319: f64 = v1298 * v1309;
        st[200] = v1319;
        let v1320: f64 = v1285 - v1319 * v1310 * v1319;
        let v1321: f64 = v1303 * v1309;
        st[201] = v1321;
        let v1322: f64 = v1287 - v1321 * v1310 * v1321;
        let v1323: f64 = v1290 - v1313 * v1310 * v1311;
        let v1324: f64 = v1292 - v1315 * v1310 * v1311;
        let v1325: f64 = v1293 - v1315 * v1310 * v1313;
        let v1326: f64 = v1295 - v1317 * v1310 * v1311;
        let v1327: f64 = v1296 - v1317 * v1310 * v1313;
        let v1328: f64 = v1297 - v1317 * v1310 * v1315;
        let v1329: f64 = v1299 - v1319 * v1310 * v1311;
        let v1330: f64 = v1300 - v1319 * v1310 * v1313;
        let v1331: f64 = v1301 - v1319 * v1310 * v1315;
        let v1332: f64 = v1302 - v1319 * v1310 * v1317;
        let v1333: f64 = v1304 - v1321 * v1310 * v1311;
        let v1334: f64 = v1305 - v1321 * v1310 * v1313;
        let v1335: f64 = v1306 - v1321 * v1310 * v1315;
        let v1336: f64 = v1307 - v1321 * v1310 * v1317;
        let v1337: f64 = v1308 - v1321 * v1310 * v1319;
        let (v1338, v1339) = piv.pivot(v1312, v382, 5, false)?;
        st[232] = v1338;
        let v1340: f64 = v1323 * v1338;
        st[202] = v1340;
        let v1341: f64 = v1314 - v1340 * v1339 * v1340;
        let v1342: f64 = v1324 * v1338;
        st[203] = v1342;
        let v1343: f64 = v1316 - v1342 * v1339 * v1342;
        let v1344: f64 = v1326 * v1338;
        st[204] = v1344;
        let v1345: f64 = v1318 - v1344 * v1339 * v1344;
        let v1346: f64 = v1329 * v1338;
        st[205] = v1346;
        let v1347: f64 = v1320 - v1346 * v1339 * v1346;
        let v1348: f64 = v1333 * v1338;
        st[206] = v1348;
        let v1349: f64 = v1322 - v1348 * v1339 * v1348;
        let v1350: f64 = v1325 - v1342 * v1339 * v1340;
        let v1351: f64 = v1327 - v1344 * v1339 * v1340;
        let v1352: f64 = v1328 - v1344 * v1339 * v1342;
        let v1353: f64 = v1330 - v1346 * v1339 * v1340;
        let v1354: f64 = v1331 - v1346 * v1339 * v1342;
        let v1355: f64 = v1332 - v1346 * v1339 * v1344;
        let v1356: f64 = v1334 - v1348 * v1339 * v1340;
        let v1357: f64 = v1335 - v1348 * v1339 * v1342;
        let v1358: f64 = v1336 - v1348 * v1339 * v1344;
        let v1359: f64 = v1337 - v1348 * v1339 * v1346;
        let (v1360, v1361) = piv.pivot(v1341, v392, 6, false)?;
        st[233] = v1360;
        let v1362: f64 = v1350 * v1360;
        st[207] = v1362;
        let v1363: f64 = v1343 - v1362 * v1361 * v1362;
        let v1364: f64 = v1351 * v1360;
        st[208] = v1364;
        let v1365: f64 = v1345 - v1364 * v1361 * v1364;
        let v1366: f64 = v1353 * v1360;
        st[209] = v1366;
        let v1367: f64 = v1347 - v1366 * v1361 * v1366;
        let v1368: f64 = v1356 * v1360;
        st[210] = v1368;
        let v1369: f64 = v1349 - v1368 * v1361 * v1368;
        let v1370: f64 = v1352 - v1364 * v1361 * v1362;
        let v1371: f64 = v1354 - v1366 * v1361 * v1362;
        let v1372: f64 = v1355 - v1366 * v1361 * v1364;
        let v1373: f64 = v1357 - v1368 * v1361 * v1362;
        let v1374: f64 = v1358 - v1368 * v1361 * v1364;
        let v1375: f64 = v1359 - v1368 * v1361 * v1366;
        let (v1376, v1377) = piv.pivot(v1363, v406, 7, false)?;
        st[234] = v1376;
        let v1378: f64 = v1370 * v1376;
        st[211] = v1378;
        let v1379: f64 = v1365 - v1378 * v1377 * v1378;
        let v1380: f64 = v1371 * v1376;
        st[212] = v1380;
        let v1381: f64 = v1367 - v1380 * v1377 * v1380;
        let v1382: f64 = v1373 * v1376;
        st[213] = v1382;
        let v1383: f64 = v1369 - v1382 * v1377 * v1382;
        let v1384: f64 = v1372 - v1380 * v1377 * v1378;
        let v1385: f64 = v1374 - v1382 * v1377 * v1378;
        let v1386: f64 = v1375 - v1382 * v1377 * v1380;
        let (v1387, v1388) = piv.pivot(v1379, v424, 8, false)?;
        st[235] = v1387;
        let v1389: f64 = v1384 * v1387;
        st[214] = v1389;
        let v1390: f64 = v1381 - v1389 * v1388 * v1389;
        let v1391: f64 = v1385 * v1387;
        st[215] = v1391;
        let v1392: f64 = v1383 - v1391 * v1388 * v1391;
        let v1393: f64 = v1386 - v1391 * v1388 * v1389;
        let (v1394, v1395) = piv.pivot(v1390, v448, 9, false)?;
        st[236] = v1394;
        let v1396: f64 = v1393 * v1394;
        st[216] = v1396;
        let v1397: f64 = v1392 - v1396 * v1395 * v1396;
        let (v1398, v1399) = piv.pivot(v1397, v310, 20, false)?;
        st[237] = v1398;
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
        let f: &[f64; 18] = f.try_into().map_err(|_| length_error(18, f.len()))?;
        let g: &[f64; 21] = g.try_into().map_err(|_| length_error(21, g.len()))?;
        let x_len = x.len();
        let x: &mut [f64; 18] = x.try_into().map_err(|_| length_error(18, x_len))?;
        let y_len = y.len();
        let y: &mut [f64; 21] = y.try_into().map_err(|_| length_error(21, y_len))?;
        let st: &[f64; 238] = st.try_into().map_err(|_| length_error(238, st.len()))?;
        x.fill(0.0);
        y[0] = -g[0];
        y[1] = -g[1];
        y[2] = -g[2];
        y[3] = -g[3];
        y[4] = -g[4];
        y[5] = -g[5];
        y[6] = -g[6];
        y[7] = -g[7];
        y[8] = -g[8];
        y[9] = -g[9];
        y[10] = -g[10];
        y[11] = -g[11];
        y[12] = -g[12];
        y[13] = -g[13];
        y[14] = -g[14];
        y[15] = -g[15];
        y[16] = -g[16];
        y[17] = -g[17];
        y[18] = -g[18];
        y[19] = -g[19];
        y[20] = -g[20];
        if f.iter().any(|&v| v != 0.0) {
            let v0: f64 = f[0];
            let v1: f64 = f[1];
            let v2: f64 = f[2];
            let v3: f64 = f[3];
            let v4: f64 = f[4];
            let v5: f64 = f[5];
            let v6: f64 = v0 * st[6];
            let v7: f64 = v1 * st[7];
            let v8: f64 = v2 * st[8];
            let v9: f64 = v3 * st[9];
            let v10: f64 = v4 * st[10];
            let v11: f64 = v5 - st[0] * v9;
            let v12: f64 = v11 - st[1] * v10;
            let v13: f64 = v12 * st[11];
            let v14: f64 = st[24] * v6;
            let v15: f64 = st[25] * v10;
            let v16: f64 = v14 + v15;
            let v17: f64 = st[26] * v13;
            let v18: f64 = v16 + v17;
            y[0] += v18;
            let v19: f64 = st[27] * v7;
            let v20: f64 = st[28] * v10;
            let v21: f64 = v19 + v20;
            let v22: f64 = st[29] * v13;
            let v23: f64 = v21 + v22;
            y[1] += v23;
            let v24: f64 = st[30] * v8;
            let v25: f64 = st[31] * v10;
            let v26: f64 = v24 + v25;
            let v27: f64 = st[32] * v13;
            let v28: f64 = v26 + v27;
            y[2] += v28;
            let v29: f64 = st[33] * v9;
            let v30: f64 = st[34] * v10;
            let v31: f64 = v29 + v30;
            let v32: f64 = st[35] * v13;
            let v33: f64 = v31 + v32;
            y[3] += v33;
            let v34: f64 = st[36] * v9;
            let v35: f64 = st[37] * v10;
            let v36: f64 = v34 + v35;
            let v37: f64 = st[38] * v13;
            let v38: f64 = v36 + v37;
            y[4] += v38;
            let v39: f64 = st[39] * v6;
            let v40: f64 = st[40] * v10;
            let v41: f64 = v39 + v40;
            let v42: f64 = st[41] * v13;
            let v43: f64 = v41 + v42;
            y[5] += v43;
            let v44: f64 = st[42] * v7;
            let v45: f64 = st[43] * v10;
            let v46: f64 = v44 + v45;
            let v47: f64 = st[44] * v13;
            let v48: f64 = v46 + v47;
            y[6] += v48;
            let v49: f64 = st[45] * v8;
            let v50: f64 = st[46] * v10;
            let v51: f64 = v49 + v50;
            let v52: f64 = st[47] * v13;
            let v53: f64 = v51 + v52;
            y[7] += v53;
            let v54: f64 = st[48] * v9;
            let v55: f64 = st[49] * v10;
            let v56: f64 = v54 + v55;
            let v57: f64 = st[50] * v13;
            let v58: f64 = v56 + v57;
            y[8] += v58;
            let v59: f64 = st[51] * v9;
            let v60: f64 = st[52] * v10;
            let v61: f64 = v59 + v60;
            let v62: f64 = st[53] * v13;
            let v63: f64 = v61 + v62;
            y[9] += v63;
            let v64: f64 = st[54] * v9;
            let v65: f64 = st[55] * v10;
            let v66: f64 = v64 + v65;
            let v67: f64 = st[56] * v13;
            let v68: f64 = v66 + v67;
            y[20] += v68;
            x[0] = v6;
            x[1] = v7;
            x[2] = v8;
            x[3] = v9;
            x[4] = v10;
            x[5] = v13;
            let v69: f64 = f[6];
            let v70: f64 = f[7];
            let v71: f64 = f[8];
            let v72: f64 = f[9];
            let v73: f64 = f[10];
            let v74: f64 = f[11];
            let v75: f64 = v69 * st[12];
            let v76: f64 = v70 * st[13];
            let v77: f64 = v71 * st[14];
            let v78: f64 = v72 * st[15];
            let v79: f64 = v73 * st[16];
            let v80: f64 = v74 - st[2] * v78;
            let v81: f64 = v80 - st[3] * v79;
            let v82: f64 = v81 * st[17];
            let v83: f64 = st[57] * v75;
            let v84: f64 = st[58] * v79;
            let v85: f64 = v83 + v84;
            let v86: f64 = st[59] * v82;
            let v87: f64 = v85 + v86;
            y[5] += v87;
            let v88: f64 = st[60] * v76;
            let v89: f64 = st[61] * v79;
            let v90: f64 = v88 + v89;
            let v91: f64 = st[62] * v82;
            let v92: f64 = v90 + v91;
            y[6] += v92;
            let v93: f64 = st[63] * v77;
            let v94: f64 = st[64] * v79;
            let v95: f64 = v93 + v94;
            let v96: f64 = st[65] * v82;
            let v97: f64 = v95 + v96;
            y[7] += v97;
            let v98: f64 = st[66] * v78;
            let v99: f64 = st[67] * v79;
            let v100: f64 = v98 + v99;
            let v101: f64 = st[68] * v82;
            let v102: f64 = v100 + v101;
            y[8] += v102;
            let v103: f64 = st[69] * v78;
            let v104: f64 = st[70] * v79;
            let v105: f64 = v103 + v104;
            let v106: f64 = st[71] * v82;
            let v107: f64 = v105 + v106;
            y[9] += v107;
            let v108: f64 = st[72] * v75;
            let v109: f64 = st[73] * v78;
            let v110: f64 = v108 + v109;
            let v111: f64 = st[74] * v79;
            let v112: f64 = v110 + v111;
            let v113: f64 = st[75] * v82;
            let v114: f64 = v112 + v113;
            y[10] += v114;
            let v115: f64 = st[76] * v76;
            let v116: f64 = st[77] * v78;
            let v117: f64 = v115 + v116;
            let v118: f64 = st[78] * v79;
            let v119: f64 = v117 + v118;
            let v120: f64 = st[79] * v82;
            let v121: f64 = v119 + v120;
            y[11] += v121;
            let v122: f64 = st[80] * v77;
            let v123: f64 = st[81] * v78;
            let v124: f64 = v122 + v123;
            let v125: f64 = st[82] * v79;
            let v126: f64 = v124 + v125;
            let v127: f64 = st[83] * v82;
            let v128: f64 = v126 + v127;
            y[12] += v128;
            let v129: f64 = st[84] * v78;
            let v130: f64 = st[85] * v79;
            let v131: f64 = v129 + v130;
            let v132: f64 = st[86] * v82;
            let v133: f64 = v131 + v132;
            y[13] += v133;
            let v134: f64 = st[87] * v78;
            let v135: f64 = st[88] * v79;
            let v136: f64 = v134 + v135;
            let v137: f64 = st[89] * v82;
            let v138: f64 = v136 + v137;
            y[14] += v138;
            x[6] = v75;
            x[7] = v76;
            x[8] = v77;
            x[9] = v78;
            x[10] = v79;
            x[11] = v82;
            let v139: f64 = f[12];
            let v140: f64 = f[13];
            let v141: f64 = f[14];
            let v142: f64 = f[15];
            let v143: f64 = f[16];
            let v144: f64 = f[17];
            let v145: f64 = v139 * st[18];
            let v146: f64 = v140 * st[19];
            let v147: f64 = v141 * st[20];
            let v148: f64 = v142 * st[21];
            let v149: f64 = v143 * st[22];
            let v150: f64 = v144 - st[4] * v148;
            let v151: f64 = v150 - st[5] * v149;
            let v152: f64 = v151 * st[23];
            let v153: f64 = st[90] * v145;
            let v154: f64 = st[91] * v148;
            let v155: f64 = v153 + v154;
            let v156: f64 = st[92] * v149;
            let v157: f64 = v155 + v156;
            let v158: f64 = st[93] * v152;
            let v159: f64 = v157 + v158;
            y[10] += v159;
            let v160: f64 = st[94] * v146;
            let v161: f64 = st[95] * v148;
            let v162: f64 = v160 + v161;
            let v163: f64 = st[96] * v149;
            let v164: f64 = v162 + v163;
            let v165: f64 = st[97] * v152;
            let v166: f64 = v164 + v165;
            y[11] += v166;
            let v167: f64 = st[98] * v147;
            let v168: f64 = st[99] * v148;
            let v169: f64 = v167 + v168;
            let v170: f64 = st[100] * v149;
            let v171: f64 = v169 + v170;
            let v172: f64 = st[101] * v152;
            let v173: f64 = v171 + v172;
            y[12] += v173;
            let v174: f64 = st[102] * v148;
            let v175: f64 = st[103] * v149;
            let v176: f64 = v174 + v175;
            let v177: f64 = st[104] * v152;
            let v178: f64 = v176 + v177;
            y[13] += v178;
            let v179: f64 = st[105] * v148;
            let v180: f64 = st[106] * v149;
            let v181: f64 = v179 + v180;
            let v182: f64 = st[107] * v152;
            let v183: f64 = v181 + v182;
            y[14] += v183;
            let v184: f64 = st[108] * v145;
            let v185: f64 = st[109] * v148;
            let v186: f64 = v184 + v185;
            let v187: f64 = st[110] * v149;
            let v188: f64 = v186 + v187;
            let v189: f64 = st[111] * v152;
            let v190: f64 = v188 + v189;
            y[15] += v190;
            let v191: f64 = st[112] * v146;
            let v192: f64 = st[113] * v148;
            let v193: f64 = v191 + v192;
            let v194: f64 = st[114] * v149;
            let v195: f64 = v193 + v194;
            let v196: f64 = st[115] * v152;
            let v197: f64 = v195 + v196;
            y[16] += v197;
            x[12] = v145;
            x[13] = v146;
            x[14] = v147;
            x[15] = v148;
            x[16] = v149;
            x[17] = v152;
        }
        let v198: f64 = y[16] - st[116] * y[15];
        let v199: f64 = y[10] - st[117] * y[15];
        let v200: f64 = y[11] - st[118] * y[15];
        let v201: f64 = y[12] - st[119] * y[15];
        let v202: f64 = y[13] - st[120] * y[15];
        let v203: f64 = y[14] - st[121] * y[15];
        let v204: f64 = v199 - st[122] * v198;
        let v205: f64 = v200 - st[123] * v198;
        let v206: f64 = v201 - st[124] * v198;
        let v207: f64 = v202 - st[125] * v198;
        let v208: f64 = v203 - st[126] * v198;
        let v209: f64 = v205 - st[127] * v204;
        let v210: f64 = v206 - st[128] * v204;
        let v211: f64 = v207 - st[129] * v204;
        let v212: f64 = v208 - st[130] * v204;
        let v213: f64 = y[5] - st[131] * v204;
        let v214: f64 = y[6] - st[132] * v204;
        let v215: f64 = y[7] - st[133] * v204;
        let v216: f64 = y[8] - st[134] * v204;
        let v217: f64 = y[9] - st[135] * v204;
        let v218: f64 = v210 - st[136] * v209;
        let v219: f64 = v211 - st[137] * v209;
        let v220: f64 = v212 - st[138] * v209;
        let v221: f64 = v213 - st[139] * v209;
        let v222: f64 = v214 - st[140] * v209;
        let v223: f64 = v215 - st[141] * v209;
        let v224: f64 = v216 - st[142] * v209;
        let v225: f64 = v217 - st[143] * v209;
        let v226: f64 = v219 - st[144] * v218;
        let v227: f64 = v220 - st[145] * v218;
        let v228: f64 = v221 - st[146] * v218;
        let v229: f64 = v222 - st[147] * v218;
        let v230: f64 = v223 - st[148] * v218;
        let v231: f64 = v224 - st[149] * v218;
        let v232: f64 = v225 - st[150] * v218;
        let v233: f64 = v227 - st[151] * v226;
        let v234: f64 = v228 - st[152] * v226;
        let v235: f64 = v229 - st[153] * v226;
        let v236: f64 = v230 - st[154] * v226;
        let v237: f64 = v231 - st[155] * v226;
        let v238: f64 = v232 - st[156] * v226;
        let v239: f64 = v234 - st[157] * v233;
        let v240: f64 = v235 - st[158] * v233;
        let v241: f64 = v236 - st[159] * v233;
        let v242: f64 = v237 - st[160] * v233;
        let v243: f64 = v238 - st[161] * v233;
        let v244: f64 = y[1] - st[162] * y[0];
        let v245: f64 = y[2] - st[163] * y[0];
        let v246: f64 = y[3] - st[164] * y[0];
        let v247: f64 = y[4] - st[165] * y[0];
        let v248: f64 = v239 - st[166] * y[0];
        let v249: f64 = v240 - st[167] * y[0];
        let v250: f64 = v241 - st[168] * y[0];
        let v251: f64 = v242 - st[169] * y[0];
        let v252: f64 = v243 - st[170] * y[0];
        let v253: f64 = y[20] - st[171] * y[0];
        let v254: f64 = v245 - st[172] * v244;
        let v255: f64 = v246 - st[173] * v244;
        let v256: f64 = v247 - st[174] * v244;
        let v257: f64 = v248 - st[175] * v244;
        let v258: f64 = v249 - st[176] * v244;
        let v259: f64 = v250 - st[177] * v244;
        let v260: f64 = v251 - st[178] * v244;
        let v261: f64 = v252 - st[179] * v244;
        let v262: f64 = v253 - st[180] * v244;
        let v263: f64 = v255 - st[181] * v254;
        let v264: f64 = v256 - st[182] * v254;
        let v265: f64 = v257 - st[183] * v254;
        let v266: f64 = v258 - st[184] * v254;
        let v267: f64 = v259 - st[185] * v254;
        let v268: f64 = v260 - st[186] * v254;
        let v269: f64 = v261 - st[187] * v254;
        let v270: f64 = v262 - st[188] * v254;
        let v271: f64 = v264 - st[189] * v263;
        let v272: f64 = v265 - st[190] * v263;
        let v273: f64 = v266 - st[191] * v263;
        let v274: f64 = v267 - st[192] * v263;
        let v275: f64 = v268 - st[193] * v263;
        let v276: f64 = v269 - st[194] * v263;
        let v277: f64 = v270 - st[195] * v263;
        let v278: f64 = v272 - st[196] * v271;
        let v279: f64 = v273 - st[197] * v271;
        let v280: f64 = v274 - st[198] * v271;
        let v281: f64 = v275 - st[199] * v271;
        let v282: f64 = v276 - st[200] * v271;
        let v283: f64 = v277 - st[201] * v271;
        let v284: f64 = v279 - st[202] * v278;
        let v285: f64 = v280 - st[203] * v278;
        let v286: f64 = v281 - st[204] * v278;
        let v287: f64 = v282 - st[205] * v278;
        let v288: f64 = v283 - st[206] * v278;
        let v289: f64 = v285 - st[207] * v284;
        let v290: f64 = v286 - st[208] * v284;
        let v291: f64 = v287 - st[209] * v284;
        let v292: f64 = v288 - st[210] * v284;
        let v293: f64 = v290 - st[211] * v289;
        let v294: f64 = v291 - st[212] * v289;
        let v295: f64 = v292 - st[213] * v289;
        let v296: f64 = v294 - st[214] * v293;
        let v297: f64 = v295 - st[215] * v293;
        let v298: f64 = v297 - st[216] * v296;
        let v299: f64 = y[17] * st[217];
        let v300: f64 = y[18] * st[218];
        let v301: f64 = y[19] * st[219];
        let v302: f64 = y[15] * st[220];
        let v303: f64 = v198 * st[221];
        let v304: f64 = v204 * st[222];
        let v305: f64 = v209 * st[223];
        let v306: f64 = v218 * st[224];
        let v307: f64 = v226 * st[225];
        let v308: f64 = v233 * st[226];
        let v309: f64 = y[0] * st[227];
        let v310: f64 = v244 * st[228];
        let v311: f64 = v254 * st[229];
        let v312: f64 = v263 * st[230];
        let v313: f64 = v271 * st[231];
        let v314: f64 = v278 * st[232];
        let v315: f64 = v284 * st[233];
        let v316: f64 = v289 * st[234];
        let v317: f64 = v293 * st[235];
        let v318: f64 = v296 * st[236];
        let v319: f64 = v298 * st[237];
        let v320: f64 = v318 - st[216] * v319;
        let v321: f64 = v317 - st[214] * v320;
        let v322: f64 = v321 - st[215] * v319;
        let v323: f64 = v316 - st[211] * v322;
        let v324: f64 = v323 - st[212] * v320;
        let v325: f64 = v324 - st[213] * v319;
        let v326: f64 = v315 - st[207] * v325;
        let v327: f64 = v326 - st[208] * v322;
        let v328: f64 = v327 - st[209] * v320;
        let v329: f64 = v328 - st[210] * v319;
        let v330: f64 = v314 - st[202] * v329;
        let v331: f64 = v330 - st[203] * v325;
        let v332: f64 = v331 - st[204] * v322;
        let v333: f64 = v332 - st[205] * v320;
        let v334: f64 = v333 - st[206] * v319;
        let v335: f64 = v313 - st[196] * v334;
        let v336: f64 = v335 - st[197] * v329;
        let v337: f64 = v336 - st[198] * v325;
        let v338: f64 = v337 - st[199] * v322;
        let v339: f64 = v338 - st[200] * v320;
        let v340: f64 = v339 - st[201] * v319;
        let v341: f64 = v312 - st[189] * v340;
        let v342: f64 = v341 - st[190] * v334;
        let v343: f64 = v342 - st[191] * v329;
        let v344: f64 = v343 - st[192] * v325;
        let v345: f64 = v344 - st[193] * v322;
        let v346: f64 = v345 - st[194] * v320;
        let v347: f64 = v346 - st[195] * v319;
        let v348: f64 = v311 - st[181] * v347;
        let v349: f64 = v348 - st[182] * v340;
        let v350: f64 = v349 - st[183] * v334;
        let v351: f64 = v350 - st[184] * v329;
        let v352: f64 = v351 - st[185] * v325;
        let v353: f64 = v352 - st[186] * v322;
        let v354: f64 = v353 - st[187] * v320;
        let v355: f64 = v354 - st[188] * v319;
        let v356: f64 = v310 - st[172] * v355;
        let v357: f64 = v356 - st[173] * v347;
        let v358: f64 = v357 - st[174] * v340;
        let v359: f64 = v358 - st[175] * v334;
        let v360: f64 = v359 - st[176] * v329;
        let v361: f64 = v360 - st[177] * v325;
        let v362: f64 = v361 - st[178] * v322;
        let v363: f64 = v362 - st[179] * v320;
        let v364: f64 = v363 - st[180] * v319;
        let v365: f64 = v309 - st[162] * v364;
        let v366: f64 = v365 - st[163] * v355;
        let v367: f64 = v366 - st[164] * v347;
        let v368: f64 = v367 - st[165] * v340;
        let v369: f64 = v368 - st[166] * v334;
        let v370: f64 = v369 - st[167] * v329;
        let v371: f64 = v370 - st[168] * v325;
        let v372: f64 = v371 - st[169] * v322;
        let v373: f64 = v372 - st[170] * v320;
        let v374: f64 = v373 - st[171] * v319;
        let v375: f64 = v308 - st[157] * v334;
        let v376: f64 = v375 - st[158] * v329;
        let v377: f64 = v376 - st[159] * v325;
        let v378: f64 = v377 - st[160] * v322;
        let v379: f64 = v378 - st[161] * v320;
        let v380: f64 = v307 - st[151] * v379;
        let v381: f64 = v380 - st[152] * v334;
        let v382: f64 = v381 - st[153] * v329;
        let v383: f64 = v382 - st[154] * v325;
        let v384: f64 = v383 - st[155] * v322;
        let v385: f64 = v384 - st[156] * v320;
        let v386: f64 = v306 - st[144] * v385;
        let v387: f64 = v386 - st[145] * v379;
        let v388: f64 = v387 - st[146] * v334;
        let v389: f64 = v388 - st[147] * v329;
        let v390: f64 = v389 - st[148] * v325;
        let v391: f64 = v390 - st[149] * v322;
        let v392: f64 = v391 - st[150] * v320;
        let v393: f64 = v305 - st[136] * v392;
        let v394: f64 = v393 - st[137] * v385;
        let v395: f64 = v394 - st[138] * v379;
        let v396: f64 = v395 - st[139] * v334;
        let v397: f64 = v396 - st[140] * v329;
        let v398: f64 = v397 - st[141] * v325;
        let v399: f64 = v398 - st[142] * v322;
        let v400: f64 = v399 - st[143] * v320;
        let v401: f64 = v304 - st[127] * v400;
        let v402: f64 = v401 - st[128] * v392;
        let v403: f64 = v402 - st[129] * v385;
        let v404: f64 = v403 - st[130] * v379;
        let v405: f64 = v404 - st[131] * v334;
        let v406: f64 = v405 - st[132] * v329;
        let v407: f64 = v406 - st[133] * v325;
        let v408: f64 = v407 - st[134] * v322;
        let v409: f64 = v408 - st[135] * v320;
        let v410: f64 = v303 - st[122] * v409;
        let v411: f64 = v410 - st[123] * v400;
        let v412: f64 = v411 - st[124] * v392;
        let v413: f64 = v412 - st[125] * v385;
        let v414: f64 = v413 - st[126] * v379;
        let v415: f64 = v302 - st[116] * v414;
        let v416: f64 = v415 - st[117] * v409;
        let v417: f64 = v416 - st[118] * v400;
        let v418: f64 = v417 - st[119] * v392;
        let v419: f64 = v418 - st[120] * v385;
        let v420: f64 = v419 - st[121] * v379;
        y[17] = v299;
        y[18] = v300;
        y[19] = v301;
        y[15] = v420;
        y[16] = v414;
        y[10] = v409;
        y[11] = v400;
        y[12] = v392;
        y[13] = v385;
        y[14] = v379;
        y[0] = v374;
        y[1] = v364;
        y[2] = v355;
        y[3] = v347;
        y[4] = v340;
        y[5] = v334;
        y[6] = v329;
        y[7] = v325;
        y[8] = v322;
        y[9] = v320;
        y[20] = v319;
        let v421: f64 = x[0] - st[24] * v374;
        let v422: f64 = x[4] - st[25] * v374;
        let v423: f64 = x[5] - st[26] * v374;
        let v424: f64 = x[1] - st[27] * v364;
        let v425: f64 = v422 - st[28] * v364;
        let v426: f64 = v423 - st[29] * v364;
        let v427: f64 = x[2] - st[30] * v355;
        let v428: f64 = v425 - st[31] * v355;
        let v429: f64 = v426 - st[32] * v355;
        let v430: f64 = x[3] - st[33] * v347;
        let v431: f64 = v428 - st[34] * v347;
        let v432: f64 = v429 - st[35] * v347;
        let v433: f64 = v430 - st[36] * v340;
        let v434: f64 = v431 - st[37] * v340;
        let v435: f64 = v432 - st[38] * v340;
        let v436: f64 = v421 - st[39] * v334;
        let v437: f64 = v434 - st[40] * v334;
        let v438: f64 = v435 - st[41] * v334;
        let v439: f64 = v424 - st[42] * v329;
        let v440: f64 = v437 - st[43] * v329;
        let v441: f64 = v438 - st[44] * v329;
        let v442: f64 = v427 - st[45] * v325;
        let v443: f64 = v440 - st[46] * v325;
        let v444: f64 = v441 - st[47] * v325;
        let v445: f64 = v433 - st[48] * v322;
        let v446: f64 = v443 - st[49] * v322;
        let v447: f64 = v444 - st[50] * v322;
        let v448: f64 = v445 - st[51] * v320;
        let v449: f64 = v446 - st[52] * v320;
        let v450: f64 = v447 - st[53] * v320;
        let v451: f64 = v448 - st[54] * v319;
        let v452: f64 = v449 - st[55] * v319;
        let v453: f64 = v450 - st[56] * v319;
        let v454: f64 = v453 * st[11];
        let v455: f64 = v452 - st[1] * v454;
        let v456: f64 = v455 * st[10];
        let v457: f64 = v451 - st[0] * v454;
        let v458: f64 = v457 * st[9];
        let v459: f64 = v442 * st[8];
        let v460: f64 = v439 * st[7];
        let v461: f64 = v436 * st[6];
        x[0] = v461;
        x[1] = v460;
        x[2] = v459;
        x[3] = v458;
        x[4] = v456;
        x[5] = v454;
        let v462: f64 = x[6] - st[57] * v334;
        let v463: f64 = x[10] - st[58] * v334;
        let v464: f64 = x[11] - st[59] * v334;
        let v465: f64 = x[7] - st[60] * v329;
        let v466: f64 = v463 - st[61] * v329;
        let v467: f64 = v464 - st[62] * v329;
        let v468: f64 = x[8] - st[63] * v325;
        let v469: f64 = v466 - st[64] * v325;
        let v470: f64 = v467 - st[65] * v325;
        let v471: f64 = x[9] - st[66] * v322;
        let v472: f64 = v469 - st[67] * v322;
        let v473: f64 = v470 - st[68] * v322;
        let v474: f64 = v471 - st[69] * v320;
        let v475: f64 = v472 - st[70] * v320;
        let v476: f64 = v473 - st[71] * v320;
        let v477: f64 = v462 - st[72] * v409;
        let v478: f64 = v474 - st[73] * v409;
        let v479: f64 = v475 - st[74] * v409;
        let v480: f64 = v476 - st[75] * v409;
        let v481: f64 = v465 - st[76] * v400;
        let v482: f64 = v478 - st[77] * v400;
        let v483: f64 = v479 - st[78] * v400;
        let v484: f64 = v480 - st[79] * v400;
        let v485: f64 = v468 - st[80] * v392;
        let v486: f64 = v482 - st[81] * v392;
        let v487: f64 = v483 - st[82] * v392;
        let v488: f64 = v484 - st[83] * v392;
        let v489: f64 = v486 - st[84] * v385;
        let v490: f64 = v487 - st[85] * v385;
        let v491: f64 = v488 - st[86] * v385;
        let v492: f64 = v489 - st[87] * v379;
        let v493: f64 = v490 - st[88] * v379;
        let v494: f64 = v491 - st[89] * v379;
        let v495: f64 = v494 * st[17];
        let v496: f64 = v493 - st[3] * v495;
        let v497: f64 = v496 * st[16];
        let v498: f64 = v492 - st[2] * v495;
        let v499: f64 = v498 * st[15];
        let v500: f64 = v485 * st[14];
        let v501: f64 = v481 * st[13];
        let v502: f64 = v477 * st[12];
        x[6] = v502;
        x[7] = v501;
        x[8] = v500;
        x[9] = v499;
        x[10] = v497;
        x[11] = v495;
        let v503: f64 = x[12] - st[90] * v409;
        let v504: f64 = x[15] - st[91] * v409;
        let v505: f64 = x[16] - st[92] * v409;
        let v506: f64 = x[17] - st[93] * v409;
        let v507: f64 = x[13] - st[94] * v400;
        let v508: f64 = v504 - st[95] * v400;
        let v509: f64 = v505 - st[96] * v400;
        let v510: f64 = v506 - st[97] * v400;
        let v511: f64 = x[14] - st[98] * v392;
        let v512: f64 = v508 - st[99] * v392;
        let v513: f64 = v509 - st[100] * v392;
        let v514: f64 = v510 - st[101] * v392;
        let v515: f64 = v512 - st[102] * v385;
        let v516: f64 = v513 - st[103] * v385;
        let v517: f64 = v514 - st[104] * v385;
        let v518: f64 = v515 - st[105] * v379;
        let v519: f64 = v516 - st[106] * v379;
        let v520: f64 = v517 - st[107] * v379;
        let v521: f64 = v503 - st[108] * v420;
        let v522: f64 = v518 - st[109] * v420;
        let v523: f64 = v519 - st[110] * v420;
        let v524: f64 = v520 - st[111] * v420;
        let v525: f64 = v507 - st[112] * v414;
        let v526: f64 = v522 - st[113] * v414;
        let v527: f64 = v523 - st[114] * v414;
        let v528: f64 = v524 - st[115] * v414;
        let v529: f64 = v528 * st[23];
        let v530: f64 = v527 - st[5] * v529;
        let v531: f64 = v530 * st[22];
        let v532: f64 = v526 - st[4] * v529;
        let v533: f64 = v532 * st[21];
        let v534: f64 = v511 * st[20];
        let v535: f64 = v525 * st[19];
        let v536: f64 = v521 * st[18];
        x[12] = v536;
        x[13] = v535;
        x[14] = v534;
        x[15] = v533;
        x[16] = v531;
        x[17] = v529;
        Ok(())
    }
    fn kkt_transpose_times(
        phi_q: &[f64],
        y: &[f64],
        out: &mut [f64],
    ) -> Result<(), KktError> {
        let phi_q: &[f64; 96] = phi_q
            .try_into()
            .map_err(|_| length_error(96, phi_q.len()))?;
        let y: &[f64; 21] = y.try_into().map_err(|_| length_error(21, y.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 18] = out.try_into().map_err(|_| length_error(18, out_len))?;
        out[0] = phi_q[0] * y[0] + phi_q[14] * y[5];
        out[1] = phi_q[3] * y[1] + phi_q[20] * y[6];
        out[2] = phi_q[6] * y[2] + phi_q[26] * y[7];
        out[3] = phi_q[8] * y[3] + phi_q[11] * y[4] + phi_q[30] * y[8] + phi_q[36] * y[9]
            + phi_q[93] * y[20];
        out[4] = phi_q[1] * y[0] + phi_q[4] * y[1] + phi_q[7] * y[2] + phi_q[9] * y[3]
            + phi_q[12] * y[4] + phi_q[15] * y[5] + phi_q[21] * y[6] + phi_q[27] * y[7]
            + phi_q[31] * y[8] + phi_q[37] * y[9] + phi_q[94] * y[20];
        out[5] = phi_q[2] * y[0] + phi_q[5] * y[1] + phi_q[10] * y[3] + phi_q[13] * y[4]
            + phi_q[16] * y[5] + phi_q[22] * y[6] + phi_q[32] * y[8] + phi_q[38] * y[9]
            + phi_q[95] * y[20];
        out[6] = phi_q[17] * y[5] + phi_q[42] * y[10];
        out[7] = phi_q[23] * y[6] + phi_q[50] * y[11];
        out[8] = phi_q[28] * y[7] + phi_q[58] * y[12];
        out[9] = phi_q[33] * y[8] + phi_q[39] * y[9] + phi_q[43] * y[10]
            + phi_q[51] * y[11] + phi_q[59] * y[12] + phi_q[64] * y[13]
            + phi_q[70] * y[14];
        out[10] = phi_q[18] * y[5] + phi_q[24] * y[6] + phi_q[29] * y[7]
            + phi_q[34] * y[8] + phi_q[40] * y[9] + phi_q[44] * y[10] + phi_q[52] * y[11]
            + phi_q[60] * y[12] + phi_q[65] * y[13] + phi_q[71] * y[14];
        out[11] = phi_q[19] * y[5] + phi_q[25] * y[6] + phi_q[35] * y[8]
            + phi_q[41] * y[9] + phi_q[45] * y[10] + phi_q[53] * y[11]
            + phi_q[66] * y[13] + phi_q[72] * y[14];
        out[12] = phi_q[46] * y[10] + phi_q[76] * y[15];
        out[13] = phi_q[54] * y[11] + phi_q[80] * y[16];
        out[14] = phi_q[61] * y[12] + phi_q[84] * y[17];
        out[15] = phi_q[47] * y[10] + phi_q[55] * y[11] + phi_q[62] * y[12]
            + phi_q[67] * y[13] + phi_q[73] * y[14] + phi_q[77] * y[15]
            + phi_q[81] * y[16] + phi_q[85] * y[17] + phi_q[87] * y[18]
            + phi_q[90] * y[19];
        out[16] = phi_q[48] * y[10] + phi_q[56] * y[11] + phi_q[63] * y[12]
            + phi_q[68] * y[13] + phi_q[74] * y[14] + phi_q[78] * y[15]
            + phi_q[82] * y[16] + phi_q[86] * y[17] + phi_q[88] * y[18]
            + phi_q[91] * y[19];
        out[17] = phi_q[49] * y[10] + phi_q[57] * y[11] + phi_q[69] * y[13]
            + phi_q[75] * y[14] + phi_q[79] * y[15] + phi_q[83] * y[16]
            + phi_q[89] * y[18] + phi_q[92] * y[19];
        Ok(())
    }
    #[allow(clippy::assign_op_pattern)]
    fn kkt_times_add(phi_q: &[f64], x: &[f64], out: &mut [f64]) -> Result<(), KktError> {
        let phi_q: &[f64; 96] = phi_q
            .try_into()
            .map_err(|_| length_error(96, phi_q.len()))?;
        let x: &[f64; 18] = x.try_into().map_err(|_| length_error(18, x.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 21] = out.try_into().map_err(|_| length_error(21, out_len))?;
        out[0] = out[0] + phi_q[0] * x[0] + phi_q[1] * x[4] + phi_q[2] * x[5];
        out[1] = out[1] + phi_q[3] * x[1] + phi_q[4] * x[4] + phi_q[5] * x[5];
        out[2] = out[2] + phi_q[6] * x[2] + phi_q[7] * x[4];
        out[3] = out[3] + phi_q[8] * x[3] + phi_q[9] * x[4] + phi_q[10] * x[5];
        out[4] = out[4] + phi_q[11] * x[3] + phi_q[12] * x[4] + phi_q[13] * x[5];
        out[5] = out[5] + phi_q[14] * x[0] + phi_q[15] * x[4] + phi_q[16] * x[5]
            + phi_q[17] * x[6] + phi_q[18] * x[10] + phi_q[19] * x[11];
        out[6] = out[6] + phi_q[20] * x[1] + phi_q[21] * x[4] + phi_q[22] * x[5]
            + phi_q[23] * x[7] + phi_q[24] * x[10] + phi_q[25] * x[11];
        out[7] = out[7] + phi_q[26] * x[2] + phi_q[27] * x[4] + phi_q[28] * x[8]
            + phi_q[29] * x[10];
        out[8] = out[8] + phi_q[30] * x[3] + phi_q[31] * x[4] + phi_q[32] * x[5]
            + phi_q[33] * x[9] + phi_q[34] * x[10] + phi_q[35] * x[11];
        out[9] = out[9] + phi_q[36] * x[3] + phi_q[37] * x[4] + phi_q[38] * x[5]
            + phi_q[39] * x[9] + phi_q[40] * x[10] + phi_q[41] * x[11];
        out[10] = out[10] + phi_q[42] * x[6] + phi_q[43] * x[9] + phi_q[44] * x[10]
            + phi_q[45] * x[11] + phi_q[46] * x[12] + phi_q[47] * x[15]
            + phi_q[48] * x[16] + phi_q[49] * x[17];
        out[11] = out[11] + phi_q[50] * x[7] + phi_q[51] * x[9] + phi_q[52] * x[10]
            + phi_q[53] * x[11] + phi_q[54] * x[13] + phi_q[55] * x[15]
            + phi_q[56] * x[16] + phi_q[57] * x[17];
        out[12] = out[12] + phi_q[58] * x[8] + phi_q[59] * x[9] + phi_q[60] * x[10]
            + phi_q[61] * x[14] + phi_q[62] * x[15] + phi_q[63] * x[16];
        out[13] = out[13] + phi_q[64] * x[9] + phi_q[65] * x[10] + phi_q[66] * x[11]
            + phi_q[67] * x[15] + phi_q[68] * x[16] + phi_q[69] * x[17];
        out[14] = out[14] + phi_q[70] * x[9] + phi_q[71] * x[10] + phi_q[72] * x[11]
            + phi_q[73] * x[15] + phi_q[74] * x[16] + phi_q[75] * x[17];
        out[15] = out[15] + phi_q[76] * x[12] + phi_q[77] * x[15] + phi_q[78] * x[16]
            + phi_q[79] * x[17];
        out[16] = out[16] + phi_q[80] * x[13] + phi_q[81] * x[15] + phi_q[82] * x[16]
            + phi_q[83] * x[17];
        out[17] = out[17] + phi_q[84] * x[14] + phi_q[85] * x[15] + phi_q[86] * x[16];
        out[18] = out[18] + phi_q[87] * x[15] + phi_q[88] * x[16] + phi_q[89] * x[17];
        out[19] = out[19] + phi_q[90] * x[15] + phi_q[91] * x[16] + phi_q[92] * x[17];
        out[20] = out[20] + phi_q[93] * x[3] + phi_q[94] * x[4] + phi_q[95] * x[5];
        Ok(())
    }
    fn kkt_mass_times(mass: &[f64], v: &[f64], out: &mut [f64]) -> Result<(), KktError> {
        let mass: &[f64; 30] = mass
            .try_into()
            .map_err(|_| length_error(30, mass.len()))?;
        let v: &[f64; 18] = v.try_into().map_err(|_| length_error(18, v.len()))?;
        let out_len = out.len();
        let out: &mut [f64; 18] = out.try_into().map_err(|_| length_error(18, out_len))?;
        out[0] = 0.0 + mass[0] * v[0];
        out[1] = 0.0 + mass[1] * v[1];
        out[2] = 0.0 + mass[2] * v[2];
        out[3] = 0.0 + mass[3] * v[3] + mass[4] * v[5];
        out[4] = 0.0 + mass[5] * v[4] + mass[6] * v[5];
        out[5] = 0.0 + mass[7] * v[3] + mass[8] * v[4] + mass[9] * v[5];
        out[6] = 0.0 + mass[10] * v[6];
        out[7] = 0.0 + mass[11] * v[7];
        out[8] = 0.0 + mass[12] * v[8];
        out[9] = 0.0 + mass[13] * v[9] + mass[14] * v[11];
        out[10] = 0.0 + mass[15] * v[10] + mass[16] * v[11];
        out[11] = 0.0 + mass[17] * v[9] + mass[18] * v[10] + mass[19] * v[11];
        out[12] = 0.0 + mass[20] * v[12];
        out[13] = 0.0 + mass[21] * v[13];
        out[14] = 0.0 + mass[22] * v[14];
        out[15] = 0.0 + mass[23] * v[15] + mass[24] * v[17];
        out[16] = 0.0 + mass[25] * v[16] + mass[26] * v[17];
        out[17] = 0.0 + mass[27] * v[15] + mass[28] * v[16] + mass[29] * v[17];
        Ok(())
    }
    fn kkt_kinetic_energy(mass: &[f64], qd: &[f64]) -> Result<f64, KktError> {
        let mass: &[f64; 30] = mass
            .try_into()
            .map_err(|_| length_error(30, mass.len()))?;
        let qd: &[f64; 18] = qd.try_into().map_err(|_| length_error(18, qd.len()))?;
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
        t += qd[6] * mass[10] * qd[6];
        t += qd[7] * mass[11] * qd[7];
        t += qd[8] * mass[12] * qd[8];
        t += qd[9] * mass[13] * qd[9];
        t += qd[9] * mass[14] * qd[11];
        t += qd[10] * mass[15] * qd[10];
        t += qd[10] * mass[16] * qd[11];
        t += qd[11] * mass[17] * qd[9];
        t += qd[11] * mass[18] * qd[10];
        t += qd[11] * mass[19] * qd[11];
        t += qd[12] * mass[20] * qd[12];
        t += qd[13] * mass[21] * qd[13];
        t += qd[14] * mass[22] * qd[14];
        t += qd[15] * mass[23] * qd[15];
        t += qd[15] * mass[24] * qd[17];
        t += qd[16] * mass[25] * qd[16];
        t += qd[16] * mass[26] * qd[17];
        t += qd[17] * mass[27] * qd[15];
        t += qd[17] * mass[28] * qd[16];
        t += qd[17] * mass[29] * qd[17];
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
        let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
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
        let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
        let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
        let out: &mut [f64; 30] = out.try_into().expect("out must have 30 entries");
        mass_part_0(k, q, out);
    }
    #[inline(never)]
    fn mass_part_0(k: &[f64; 23], q: &[f64; 18], out: &mut [f64; 30]) {
        let (x12, x13) = symbody_runtime::trig::sin_cos(q[3]);
        let (x14, x15) = symbody_runtime::trig::sin_cos(q[4]);
        let x22 = x12 * x15;
        let x23 = x13 * x15;
        let (x45, x46) = symbody_runtime::trig::sin_cos(q[9]);
        let (x47, x48) = symbody_runtime::trig::sin_cos(q[10]);
        let x55 = x45 * x48;
        let x56 = x46 * x48;
        let (x78, x79) = symbody_runtime::trig::sin_cos(q[15]);
        let (x80, x81) = symbody_runtime::trig::sin_cos(q[16]);
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
        let x6290 = x1892 * k[12];
        let x6291 = 0.5 * x6290;
        let x6292 = -x6291;
        let x6293 = x1901 * k[17];
        let x6294 = x1903 * k[17];
        let x6295 = x6293 + x6294;
        let x6296 = 0.5 * x6295;
        let x6297 = x1911 * k[17];
        let x6298 = x1913 * k[17];
        let x6300 = x6297 - x6298;
        let x6301 = 0.5 * x6300;
        let x6302 = x1918 * k[17];
        let x6303 = x1920 * k[17];
        let x6305 = x6302 - x6303;
        let x6306 = 0.5 * x6305;
        let x6307 = x1926 * k[12];
        let x6308 = x1930 * k[17];
        let x6309 = x1932 * k[17];
        let x6310 = x6307 + x6308;
        let x6311 = x6309 + x6310;
        let x6312 = 0.5 * x6311;
        let x6343 = x2108 * k[12];
        let x6344 = 0.5 * x6343;
        let x6345 = -x6344;
        let x6346 = x2117 * k[19];
        let x6347 = x2119 * k[19];
        let x6348 = x6346 + x6347;
        let x6349 = 0.5 * x6348;
        let x6350 = x2127 * k[19];
        let x6351 = x2129 * k[19];
        let x6353 = x6350 - x6351;
        let x6354 = 0.5 * x6353;
        let x6355 = x2134 * k[19];
        let x6356 = x2136 * k[19];
        let x6358 = x6355 - x6356;
        let x6359 = 0.5 * x6358;
        let x6360 = x2142 * k[12];
        let x6361 = x2146 * k[19];
        let x6362 = x2148 * k[19];
        let x6363 = x6360 + x6361;
        let x6364 = x6362 + x6363;
        let x6365 = 0.5 * x6364;
        let x6396 = x2319 * k[12];
        let x6397 = 0.5 * x6396;
        let x6398 = -x6397;
        let x6399 = x2328 * k[21];
        let x6400 = x2330 * k[21];
        let x6401 = x6399 + x6400;
        let x6402 = 0.5 * x6401;
        let x6403 = x2338 * k[21];
        let x6404 = x2340 * k[21];
        let x6406 = x6403 - x6404;
        let x6407 = 0.5 * x6406;
        let x6408 = x2345 * k[21];
        let x6409 = x2347 * k[21];
        let x6411 = x6408 - x6409;
        let x6412 = 0.5 * x6411;
        let x6413 = x2353 * k[12];
        let x6414 = x2357 * k[21];
        let x6415 = x2359 * k[21];
        let x6416 = x6413 + x6414;
        let x6417 = x6415 + x6416;
        let x6418 = 0.5 * x6417;
        out[0] = 0.2;
        out[1] = 0.2;
        out[2] = 0.2;
        out[3] = k[22];
        out[4] = x6292;
        out[5] = x6296;
        out[6] = x6301;
        out[7] = x6292;
        out[8] = x6306;
        out[9] = x6312;
        out[10] = 0.5;
        out[11] = 0.5;
        out[12] = 0.5;
        out[13] = k[22];
        out[14] = x6345;
        out[15] = x6349;
        out[16] = x6354;
        out[17] = x6345;
        out[18] = x6359;
        out[19] = x6365;
        out[20] = 0.4;
        out[21] = 0.4;
        out[22] = 0.4;
        out[23] = k[22];
        out[24] = x6398;
        out[25] = x6402;
        out[26] = x6407;
        out[27] = x6398;
        out[28] = x6412;
        out[29] = x6418;
    }
    /// Generalized forces Q(q, q̇, t): gravity and velocity-dependent terms.
    pub fn force(k: &[f64], q: &[f64], qd: &[f64], t: f64, out: &mut [f64]) {
        let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
        let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 18] = qd.try_into().expect("qd must have n_coords entries");
        let out: &mut [f64; 18] = out.try_into().expect("out must have 18 entries");
        let _ = t;
        force_part_0(k, q, qd, out);
    }
    #[inline(never)]
    fn force_part_0(k: &[f64; 23], q: &[f64; 18], qd: &[f64; 18], out: &mut [f64; 18]) {
        let (x12, x13) = symbody_runtime::trig::sin_cos(q[3]);
        let (x14, x15) = symbody_runtime::trig::sin_cos(q[4]);
        let x22 = x12 * x15;
        let x23 = x13 * x15;
        let (x45, x46) = symbody_runtime::trig::sin_cos(q[9]);
        let (x47, x48) = symbody_runtime::trig::sin_cos(q[10]);
        let x55 = x45 * x48;
        let x56 = x46 * x48;
        let (x78, x79) = symbody_runtime::trig::sin_cos(q[15]);
        let (x80, x81) = symbody_runtime::trig::sin_cos(q[16]);
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
        let x6313 = x1964 * k[12];
        let x6314 = 0.5 * x6313;
        let x6315 = x1976 * k[17];
        let x6316 = x1981 * k[17];
        let x6318 = x6315 - x6316;
        let x6319 = 0.5 * x6318;
        let x6320 = x1989 * k[12];
        let x6322 = x1994 * k[17];
        let x6323 = x2000 * k[17];
        let x6325 = x6322 - x6320;
        let x6326 = x6325 - x6323;
        let x6327 = 0.5 * x6326;
        let x6328 = x2010 * k[17];
        let x6329 = x2012 * k[17];
        let x6331 = x6328 - x6329;
        let x6332 = 0.5 * x6331;
        let x6333 = x6314 + x6332;
        let x6334 = x2024 * k[12];
        let x6335 = x2028 * k[17];
        let x6336 = x2032 * k[17];
        let x6337 = x6334 + x6335;
        let x6338 = x6336 + x6337;
        let x6339 = 0.5 * x6338;
        let x6340 = x6319 + x6339;
        let x6341 = -x6340;
        let x6342 = -x6327;
        let x6366 = x2174 * k[12];
        let x6367 = 0.5 * x6366;
        let x6368 = x2186 * k[19];
        let x6369 = x2191 * k[19];
        let x6371 = x6368 - x6369;
        let x6372 = 0.5 * x6371;
        let x6373 = x2199 * k[12];
        let x6375 = x2204 * k[19];
        let x6376 = x2210 * k[19];
        let x6378 = x6375 - x6373;
        let x6379 = x6378 - x6376;
        let x6380 = 0.5 * x6379;
        let x6381 = x2220 * k[19];
        let x6382 = x2222 * k[19];
        let x6384 = x6381 - x6382;
        let x6385 = 0.5 * x6384;
        let x6386 = x6367 + x6385;
        let x6387 = x2234 * k[12];
        let x6388 = x2238 * k[19];
        let x6389 = x2242 * k[19];
        let x6390 = x6387 + x6388;
        let x6391 = x6389 + x6390;
        let x6392 = 0.5 * x6391;
        let x6393 = x6372 + x6392;
        let x6394 = -x6393;
        let x6395 = -x6380;
        let x6419 = x2385 * k[12];
        let x6420 = 0.5 * x6419;
        let x6421 = x2397 * k[21];
        let x6422 = x2402 * k[21];
        let x6424 = x6421 - x6422;
        let x6425 = 0.5 * x6424;
        let x6426 = x2410 * k[12];
        let x6428 = x2415 * k[21];
        let x6429 = x2421 * k[21];
        let x6431 = x6428 - x6426;
        let x6432 = x6431 - x6429;
        let x6433 = 0.5 * x6432;
        let x6434 = x2431 * k[21];
        let x6435 = x2433 * k[21];
        let x6437 = x6434 - x6435;
        let x6438 = 0.5 * x6437;
        let x6439 = x6420 + x6438;
        let x6440 = x2445 * k[12];
        let x6441 = x2449 * k[21];
        let x6442 = x2453 * k[21];
        let x6443 = x6440 + x6441;
        let x6444 = x6442 + x6443;
        let x6445 = 0.5 * x6444;
        let x6446 = x6425 + x6445;
        let x6447 = -x6446;
        let x6448 = -x6433;
        out[0] = 0.0;
        out[1] = -1.9620000000000002;
        out[2] = 0.0;
        out[3] = x6333;
        out[4] = x6341;
        out[5] = x6342;
        out[6] = 0.0;
        out[7] = -4.905;
        out[8] = 0.0;
        out[9] = x6386;
        out[10] = x6394;
        out[11] = x6395;
        out[12] = 0.0;
        out[13] = -3.9240000000000004;
        out[14] = 0.0;
        out[15] = x6439;
        out[16] = x6447;
        out[17] = x6448;
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
        _k: &[f64; 23],
        q: &[f64; 18],
        qd: &[f64; 18],
        _t: f64,
        s: &mut [f64; 30],
    ) {
        let (x12, x13) = symbody_runtime::trig::sin_cos(q[3]);
        s[0] = x12;
        s[1] = x13;
        let (x14, x15) = symbody_runtime::trig::sin_cos(q[4]);
        s[2] = x14;
        s[3] = x15;
        let x22 = x12 * x15;
        s[4] = x22;
        let x23 = x13 * x15;
        s[5] = x23;
        let (x45, x46) = symbody_runtime::trig::sin_cos(q[9]);
        s[6] = x45;
        s[7] = x46;
        let (x47, x48) = symbody_runtime::trig::sin_cos(q[10]);
        s[8] = x47;
        s[9] = x48;
        let x55 = x45 * x48;
        s[10] = x55;
        let x56 = x46 * x48;
        s[11] = x56;
        let (x78, x79) = symbody_runtime::trig::sin_cos(q[15]);
        s[12] = x78;
        s[13] = x79;
        let (x80, x81) = symbody_runtime::trig::sin_cos(q[16]);
        s[14] = x80;
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
        k: &[f64; 23],
        q: &[f64; 18],
        t: f64,
        s: &[f64; 30],
        phi: &mut [f64; 21],
        phi_q: &mut [f64; 96],
        mass: &mut [f64; 30],
        force: &mut [f64; 18],
    ) {
        let x5 = 6.283185307179586 * t;
        let (x16, x17) = symbody_runtime::trig::sin_cos(q[5]);
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
        let (x49, x50) = symbody_runtime::trig::sin_cos(q[11]);
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
        let (x82, x83) = symbody_runtime::trig::sin_cos(q[17]);
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
        let (x331, x332) = symbody_runtime::trig::sin_cos(x5);
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
        let x5847 = x18 * k[0];
        let x5848 = x19 * k[0];
        let x5849 = s[2] * k[0];
        let x5851 = q[0] + x5847;
        let x5852 = q[1] + x5848;
        let x5853 = q[2] - x5849;
        let x5854 = -x5851;
        let x5855 = -x5852;
        let x5856 = -x5853;
        let x5858 = x18 * k[1];
        let x5859 = x19 * k[1];
        let x5860 = s[2] * k[1];
        let x5862 = q[0] + x5858;
        let x5863 = q[1] + x5859;
        let x5864 = q[2] - x5860;
        let x5866 = x51 * k[2];
        let x5867 = x52 * k[2];
        let x5868 = s[8] * k[2];
        let x5870 = q[6] + x5866;
        let x5871 = q[7] + x5867;
        let x5872 = q[8] - x5868;
        let x5874 = x5862 - x5870;
        let x5876 = x5863 - x5871;
        let x5878 = x5864 - x5872;
        let x5881 = x51 * k[3];
        let x5882 = x66 * k[4];
        let x5883 = x5881 + x5882;
        let x5884 = x52 * k[3];
        let x5885 = x68 * k[4];
        let x5886 = x5884 + x5885;
        let x5887 = s[8] * k[3];
        let x5889 = s[10] * k[4];
        let x5890 = x5889 - x5887;
        let x5891 = q[6] + x5883;
        let x5892 = q[7] + x5886;
        let x5893 = q[8] + x5890;
        let x5896 = x51 * k[5];
        let x5897 = x66 * k[6];
        let x5898 = x5896 + x5897;
        let x5899 = x52 * k[5];
        let x5900 = x68 * k[6];
        let x5901 = x5899 + x5900;
        let x5902 = s[8] * k[5];
        let x5904 = s[10] * k[6];
        let x5905 = x5904 - x5902;
        let x5906 = x51 * k[6];
        let x5908 = x66 * k[5];
        let x5909 = x5908 - x5906;
        let x5910 = x52 * k[6];
        let x5912 = x68 * k[5];
        let x5913 = x5912 - x5910;
        let x5914 = s[8] * k[6];
        let x5915 = s[10] * k[5];
        let x5916 = x5914 + x5915;
        let x5919 = x84 * k[7];
        let x5920 = x99 * k[8];
        let x5921 = x5919 + x5920;
        let x5922 = x85 * k[7];
        let x5923 = x101 * k[8];
        let x5924 = x5922 + x5923;
        let x5925 = s[14] * k[7];
        let x5927 = s[16] * k[8];
        let x5928 = x5927 - x5925;
        let x5929 = q[12] + x5921;
        let x5930 = q[13] + x5924;
        let x5931 = q[14] + x5928;
        let x5933 = x5891 - x5929;
        let x5935 = x5892 - x5930;
        let x5937 = x5893 - x5931;
        let x5938 = x100 * x5898;
        let x5939 = x103 * x5901;
        let x5940 = s[17] * x5905;
        let x5941 = x5938 + x5939;
        let x5942 = x5940 + x5941;
        let x5943 = x100 * x5909;
        let x5944 = x103 * x5913;
        let x5945 = s[17] * x5916;
        let x5946 = x5943 + x5944;
        let x5947 = x5945 + x5946;
        let x5951 = x84 * k[10];
        let x5952 = x99 * k[11];
        let x5953 = x5951 + x5952;
        let x5954 = x85 * k[10];
        let x5955 = x101 * k[11];
        let x5956 = x5954 + x5955;
        let x5957 = s[14] * k[10];
        let x5959 = s[16] * k[11];
        let x5960 = x5959 - x5957;
        let x5961 = q[12] + x5953;
        let x5962 = q[13] + x5956;
        let x5963 = q[14] + x5960;
        let x5965 = k[9] - x5961;
        let x5966 = -x5962;
        let x5967 = -x5963;
        let x5968 = x20 * k[0];
        let x5969 = x21 * k[0];
        let x5970 = s[3] * k[0];
        let x5971 = x20 * k[1];
        let x5972 = -x5971;
        let x5973 = x21 * k[1];
        let x5974 = -x5973;
        let x5975 = s[3] * k[1];
        let x5976 = -x5975;
        let x5977 = -x5847;
        let x5978 = -x5859;
        let x5979 = x67 * k[4];
        let x5980 = x70 * k[4];
        let x5981 = s[11] * k[4];
        let x5982 = x67 * k[6];
        let x5983 = x70 * k[6];
        let x5984 = s[11] * k[6];
        let x5985 = x67 * k[5];
        let x5986 = x70 * k[5];
        let x5987 = s[11] * k[5];
        let x5988 = x100 * x5982;
        let x5989 = x103 * x5983;
        let x5990 = s[17] * x5984;
        let x5991 = x5988 + x5989;
        let x5992 = x5990 + x5991;
        let x5993 = x100 * x5985;
        let x5994 = x103 * x5986;
        let x5995 = s[17] * x5987;
        let x5996 = x5993 + x5994;
        let x5997 = x5995 + x5996;
        let x5998 = x53 * k[2];
        let x5999 = x54 * k[2];
        let x6000 = s[9] * k[2];
        let x6001 = x53 * k[3];
        let x6003 = x499 * k[4];
        let x6004 = x6003 - x6001;
        let x6005 = x54 * k[3];
        let x6007 = x501 * k[4];
        let x6008 = x6007 - x6005;
        let x6009 = s[9] * k[3];
        let x6010 = x495 * k[4];
        let x6011 = x6009 + x6010;
        let x6012 = -x6011;
        let x6013 = x53 * k[5];
        let x6015 = x499 * k[6];
        let x6016 = x6015 - x6013;
        let x6017 = x54 * k[5];
        let x6019 = x501 * k[6];
        let x6020 = x6019 - x6017;
        let x6021 = s[9] * k[5];
        let x6022 = x495 * k[6];
        let x6023 = x6021 + x6022;
        let x6024 = x53 * k[6];
        let x6025 = x499 * k[5];
        let x6026 = x6024 + x6025;
        let x6027 = x54 * k[6];
        let x6028 = x501 * k[5];
        let x6029 = x6027 + x6028;
        let x6030 = s[9] * k[6];
        let x6031 = x495 * k[5];
        let x6033 = x6030 - x6031;
        let x6034 = x100 * x6016;
        let x6035 = x103 * x6020;
        let x6036 = s[17] * x6023;
        let x6038 = x6034 + x6035;
        let x6039 = x6038 - x6036;
        let x6040 = x100 * x6026;
        let x6041 = x103 * x6029;
        let x6042 = s[17] * x6033;
        let x6043 = x6040 + x6041;
        let x6044 = x6042 + x6043;
        let x6045 = -x5866;
        let x6046 = -x5886;
        let x6048 = x5910 - x5912;
        let x6049 = x100 * x5901;
        let x6051 = x103 * x5898;
        let x6052 = x6051 - x6049;
        let x6053 = x100 * x6048;
        let x6054 = x103 * x5909;
        let x6055 = x6053 + x6054;
        let x6056 = x100 * k[8];
        let x6057 = x103 * k[8];
        let x6058 = s[17] * k[8];
        let x6059 = -x6056;
        let x6060 = -x6057;
        let x6061 = -x6058;
        let x6062 = x603 * x5898;
        let x6063 = x101 * x5901;
        let x6065 = s[16] * x5905;
        let x6067 = x6062 - x6063;
        let x6068 = x6067 - x6065;
        let x6069 = x603 * x5909;
        let x6070 = x101 * x5913;
        let x6072 = s[16] * x5916;
        let x6074 = x6069 - x6070;
        let x6075 = x6074 - x6072;
        let x6076 = x100 * k[11];
        let x6077 = x103 * k[11];
        let x6078 = s[17] * k[11];
        let x6079 = -x6076;
        let x6080 = -x6077;
        let x6081 = -x6078;
        let x6082 = x86 * k[7];
        let x6084 = x638 * k[8];
        let x6085 = x6084 - x6082;
        let x6086 = x87 * k[7];
        let x6088 = x640 * k[8];
        let x6089 = x6088 - x6086;
        let x6090 = s[15] * k[7];
        let x6091 = x634 * k[8];
        let x6092 = x6090 + x6091;
        let x6093 = -x6085;
        let x6094 = -x6089;
        let x6095 = x639 * x5898;
        let x6096 = x641 * x5901;
        let x6097 = x636 * x5905;
        let x6099 = x6095 + x6096;
        let x6100 = x6099 - x6097;
        let x6101 = x639 * x5909;
        let x6102 = x641 * x5913;
        let x6103 = x636 * x5916;
        let x6105 = x6101 + x6102;
        let x6106 = x6105 - x6103;
        let x6107 = x86 * k[10];
        let x6109 = x638 * k[11];
        let x6110 = x6109 - x6107;
        let x6111 = x87 * k[10];
        let x6113 = x640 * k[11];
        let x6114 = x6113 - x6111;
        let x6115 = s[15] * k[10];
        let x6116 = x634 * k[11];
        let x6117 = x6115 + x6116;
        let x6118 = -x6110;
        let x6119 = -x6114;
        let x6120 = -x5921;
        let x6121 = x689 * x5898;
        let x6122 = x6049 + x6121;
        let x6123 = x689 * x5909;
        let x6124 = x100 * x5913;
        let x6125 = x6123 + x6124;
        let x6126 = -x5953;
        let x6290 = x1892 * k[12];
        let x6291 = 0.5 * x6290;
        let x6292 = -x6291;
        let x6293 = x1901 * k[17];
        let x6294 = x1903 * k[17];
        let x6295 = x6293 + x6294;
        let x6296 = 0.5 * x6295;
        let x6297 = x1911 * k[17];
        let x6298 = x1913 * k[17];
        let x6300 = x6297 - x6298;
        let x6301 = 0.5 * x6300;
        let x6302 = x1918 * k[17];
        let x6303 = x1920 * k[17];
        let x6305 = x6302 - x6303;
        let x6306 = 0.5 * x6305;
        let x6307 = x1926 * k[12];
        let x6308 = x1930 * k[17];
        let x6309 = x1932 * k[17];
        let x6310 = x6307 + x6308;
        let x6311 = x6309 + x6310;
        let x6312 = 0.5 * x6311;
        let x6313 = s[29] * k[12];
        let x6314 = 0.5 * x6313;
        let x6328 = x2010 * k[17];
        let x6329 = x2012 * k[17];
        let x6331 = x6328 - x6329;
        let x6332 = 0.5 * x6331;
        let x6333 = x6314 + x6332;
        let x6343 = x2108 * k[12];
        let x6344 = 0.5 * x6343;
        let x6345 = -x6344;
        let x6346 = x2117 * k[19];
        let x6347 = x2119 * k[19];
        let x6348 = x6346 + x6347;
        let x6349 = 0.5 * x6348;
        let x6350 = x2127 * k[19];
        let x6351 = x2129 * k[19];
        let x6353 = x6350 - x6351;
        let x6354 = 0.5 * x6353;
        let x6355 = x2134 * k[19];
        let x6356 = x2136 * k[19];
        let x6358 = x6355 - x6356;
        let x6359 = 0.5 * x6358;
        let x6360 = x2142 * k[12];
        let x6361 = x2146 * k[19];
        let x6362 = x2148 * k[19];
        let x6363 = x6360 + x6361;
        let x6364 = x6362 + x6363;
        let x6365 = 0.5 * x6364;
        let x6396 = x2319 * k[12];
        let x6397 = 0.5 * x6396;
        let x6398 = -x6397;
        let x6399 = x2328 * k[21];
        let x6400 = x2330 * k[21];
        let x6401 = x6399 + x6400;
        let x6402 = 0.5 * x6401;
        let x6403 = x2338 * k[21];
        let x6404 = x2340 * k[21];
        let x6406 = x6403 - x6404;
        let x6407 = 0.5 * x6406;
        let x6408 = x2345 * k[21];
        let x6409 = x2347 * k[21];
        let x6411 = x6408 - x6409;
        let x6412 = 0.5 * x6411;
        let x6413 = x2353 * k[12];
        let x6414 = x2357 * k[21];
        let x6415 = x2359 * k[21];
        let x6416 = x6413 + x6414;
        let x6417 = x6415 + x6416;
        let x6418 = 0.5 * x6417;
        phi[0] = x5854;
        phi_q[0] = -1.0;
        phi_q[1] = x5968;
        phi_q[2] = x5848;
        phi[1] = x5855;
        phi_q[3] = -1.0;
        phi_q[4] = x5969;
        phi_q[5] = x5977;
        phi[2] = x5856;
        phi_q[6] = -1.0;
        phi_q[7] = x5970;
        phi[3] = x34;
        phi_q[8] = x341;
        phi_q[9] = x373;
        phi_q[10] = x433;
        phi[4] = x37;
        phi_q[11] = x120;
        phi_q[12] = x375;
        phi_q[13] = x34;
        phi[5] = x5874;
        phi_q[14] = 1.0;
        phi_q[15] = x5972;
        phi_q[16] = x5978;
        phi_q[17] = -1.0;
        phi_q[18] = x5998;
        phi_q[19] = x5867;
        phi[6] = x5876;
        phi_q[20] = 1.0;
        phi_q[21] = x5974;
        phi_q[22] = x5858;
        phi_q[23] = -1.0;
        phi_q[24] = x5999;
        phi_q[25] = x6045;
        phi[7] = x5878;
        phi_q[26] = 1.0;
        phi_q[27] = x5976;
        phi_q[28] = -1.0;
        phi_q[29] = x6000;
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
        phi[10] = x5933;
        phi_q[42] = 1.0;
        phi_q[43] = x5979;
        phi_q[44] = x6004;
        phi_q[45] = x6046;
        phi_q[46] = -1.0;
        phi_q[47] = x6059;
        phi_q[48] = x6093;
        phi_q[49] = x5924;
        phi[11] = x5935;
        phi_q[50] = 1.0;
        phi_q[51] = x5980;
        phi_q[52] = x6008;
        phi_q[53] = x5883;
        phi_q[54] = -1.0;
        phi_q[55] = x6060;
        phi_q[56] = x6094;
        phi_q[57] = x6120;
        phi[12] = x5937;
        phi_q[58] = 1.0;
        phi_q[59] = x5981;
        phi_q[60] = x6012;
        phi_q[61] = -1.0;
        phi_q[62] = x6061;
        phi_q[63] = x6092;
        phi[13] = x5942;
        phi_q[64] = x5992;
        phi_q[65] = x6039;
        phi_q[66] = x6052;
        phi_q[67] = x6068;
        phi_q[68] = x6100;
        phi_q[69] = x6122;
        phi[14] = x5947;
        phi_q[70] = x5997;
        phi_q[71] = x6044;
        phi_q[72] = x6055;
        phi_q[73] = x6075;
        phi_q[74] = x6106;
        phi_q[75] = x6125;
        phi[15] = x5965;
        phi_q[76] = -1.0;
        phi_q[77] = x6079;
        phi_q[78] = x6118;
        phi_q[79] = x5956;
        phi[16] = x5966;
        phi_q[80] = -1.0;
        phi_q[81] = x6080;
        phi_q[82] = x6119;
        phi_q[83] = x6126;
        phi[17] = x5967;
        phi_q[84] = -1.0;
        phi_q[85] = x6081;
        phi_q[86] = x6117;
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
        mass[3] = k[22];
        mass[4] = x6292;
        mass[5] = x6296;
        mass[6] = x6301;
        mass[7] = x6292;
        mass[8] = x6306;
        mass[9] = x6312;
        mass[10] = 0.5;
        mass[11] = 0.5;
        mass[12] = 0.5;
        mass[13] = k[22];
        mass[14] = x6345;
        mass[15] = x6349;
        mass[16] = x6354;
        mass[17] = x6345;
        mass[18] = x6359;
        mass[19] = x6365;
        mass[20] = 0.4;
        mass[21] = 0.4;
        mass[22] = 0.4;
        mass[23] = k[22];
        mass[24] = x6398;
        mass[25] = x6402;
        mass[26] = x6407;
        mass[27] = x6398;
        mass[28] = x6412;
        mass[29] = x6418;
        force[0] = 0.0;
        force[1] = -1.9620000000000002;
        force[2] = 0.0;
        force[3] = x6333;
    }
    #[inline(never)]
    fn eval_newton_part_1(
        k: &[f64; 23],
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
        let x6315 = x1976 * k[17];
        let x6316 = x1981 * k[17];
        let x6318 = x6315 - x6316;
        let x6319 = 0.5 * x6318;
        let x6320 = x1989 * k[12];
        let x6322 = x1994 * k[17];
        let x6323 = x2000 * k[17];
        let x6325 = x6322 - x6320;
        let x6326 = x6325 - x6323;
        let x6327 = 0.5 * x6326;
        let x6334 = x2024 * k[12];
        let x6335 = x2028 * k[17];
        let x6336 = x2032 * k[17];
        let x6337 = x6334 + x6335;
        let x6338 = x6336 + x6337;
        let x6339 = 0.5 * x6338;
        let x6340 = x6319 + x6339;
        let x6341 = -x6340;
        let x6342 = -x6327;
        let x6366 = x2174 * k[12];
        let x6367 = 0.5 * x6366;
        let x6368 = x2186 * k[19];
        let x6369 = x2191 * k[19];
        let x6371 = x6368 - x6369;
        let x6372 = 0.5 * x6371;
        let x6373 = x2199 * k[12];
        let x6375 = x2204 * k[19];
        let x6376 = x2210 * k[19];
        let x6378 = x6375 - x6373;
        let x6379 = x6378 - x6376;
        let x6380 = 0.5 * x6379;
        let x6381 = x2220 * k[19];
        let x6382 = x2222 * k[19];
        let x6384 = x6381 - x6382;
        let x6385 = 0.5 * x6384;
        let x6386 = x6367 + x6385;
        let x6387 = x2234 * k[12];
        let x6388 = x2238 * k[19];
        let x6389 = x2242 * k[19];
        let x6390 = x6387 + x6388;
        let x6391 = x6389 + x6390;
        let x6392 = 0.5 * x6391;
        let x6393 = x6372 + x6392;
        let x6394 = -x6393;
        let x6395 = -x6380;
        let x6419 = x2385 * k[12];
        let x6420 = 0.5 * x6419;
        let x6421 = x2397 * k[21];
        let x6422 = x2402 * k[21];
        let x6424 = x6421 - x6422;
        let x6425 = 0.5 * x6424;
        let x6426 = x2410 * k[12];
        let x6428 = x2415 * k[21];
        let x6429 = x2421 * k[21];
        let x6431 = x6428 - x6426;
        let x6432 = x6431 - x6429;
        let x6433 = 0.5 * x6432;
        let x6434 = x2431 * k[21];
        let x6435 = x2433 * k[21];
        let x6437 = x6434 - x6435;
        let x6438 = 0.5 * x6437;
        let x6439 = x6420 + x6438;
        let x6440 = x2445 * k[12];
        let x6441 = x2449 * k[21];
        let x6442 = x2453 * k[21];
        let x6443 = x6440 + x6441;
        let x6444 = x6442 + x6443;
        let x6445 = 0.5 * x6444;
        let x6446 = x6425 + x6445;
        let x6447 = -x6446;
        let x6448 = -x6433;
        force[4] = x6341;
        force[5] = x6342;
        force[6] = 0.0;
        force[7] = -4.905;
        force[8] = 0.0;
        force[9] = x6386;
        force[10] = x6394;
        force[11] = x6395;
        force[12] = 0.0;
        force[13] = -3.9240000000000004;
        force[14] = 0.0;
        force[15] = x6439;
        force[16] = x6447;
        force[17] = x6448;
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
        let k: &[f64; 23] = k.try_into().expect("k must have 23 entries");
        let q: &[f64; 18] = q.try_into().expect("q must have n_coords entries");
        let qd: &[f64; 18] = qd.try_into().expect("qd must have n_coords entries");
        let dq: &[f64; 18] = dq.try_into().expect("dq must have n_coords entries");
        let dqd: &[f64; 18] = dqd.try_into().expect("dqd must have n_coords entries");
        let dp: &[f64; 33] = dp.try_into().expect("dp must have 33 entries");
        let mass: &mut [f64; 30] = mass.try_into().expect("mass must have 30 entries");
        let force: &mut [f64; 18] = force
            .try_into()
            .expect("force must have 18 entries");
        let _ = t;
        let mut s = [0.0f64; 42];
        tangents_shared_0(k, q, qd, t, dq, dqd, dp, &mut s);
        tangents_part_0(k, q, qd, dq, dqd, dp, &s, mass, force);
        tangents_part_1(k, qd, dqd, dp, &s, force);
    }
    #[inline(never)]
    fn tangents_shared_0(
        k: &[f64; 23],
        q: &[f64; 18],
        _qd: &[f64; 18],
        _t: f64,
        dq: &[f64; 18],
        _dqd: &[f64; 18],
        dp: &[f64; 33],
        s: &mut [f64; 42],
    ) {
        let (x45, x46) = symbody_runtime::trig::sin_cos(q[9]);
        s[0] = x45;
        s[1] = x46;
        let (x47, x48) = symbody_runtime::trig::sin_cos(q[10]);
        s[2] = x47;
        s[3] = x48;
        let x55 = x45 * x48;
        s[4] = x55;
        let x56 = x46 * x48;
        s[5] = x56;
        let (x78, x79) = symbody_runtime::trig::sin_cos(q[15]);
        s[6] = x78;
        s[7] = x79;
        let (x80, x81) = symbody_runtime::trig::sin_cos(q[16]);
        s[8] = x80;
        s[9] = x81;
        let x88 = x78 * x81;
        s[10] = x88;
        let x89 = x79 * x81;
        s[11] = x89;
        let x2610 = x46 * dq[9];
        s[12] = x2610;
        let x2611 = x45 * dq[9];
        s[13] = x2611;
        let x2613 = x48 * dq[10];
        s[14] = x2613;
        let x2614 = x47 * dq[10];
        s[15] = x2614;
        let x2636 = x48 * x2610;
        s[16] = x2636;
        let x2637 = x45 * x2614;
        s[17] = x2637;
        let x2639 = x2636 - x2637;
        s[18] = x2639;
        let x2640 = x48 * x2611;
        s[19] = x2640;
        let x2642 = x46 * x2614;
        s[20] = x2642;
        let x2644 = x2640 + x2642;
        s[21] = x2644;
        let x2683 = x79 * dq[15];
        s[22] = x2683;
        let x2684 = x78 * dq[15];
        s[23] = x2684;
        let x2686 = x81 * dq[16];
        s[24] = x2686;
        let x2687 = x80 * dq[16];
        s[25] = x2687;
        let x2709 = x81 * x2683;
        s[26] = x2709;
        let x2710 = x78 * x2687;
        s[27] = x2710;
        let x2712 = x2709 - x2710;
        s[28] = x2712;
        let x2713 = x81 * x2684;
        s[29] = x2713;
        let x2715 = x79 * x2687;
        s[30] = x2715;
        let x2717 = x2713 + x2715;
        s[31] = x2717;
        let x5027 = 0.5 * dp[2];
        s[32] = x5027;
        let x5032 = 0.4 * dp[3];
        s[33] = x5032;
        let x7159 = dp[2] * k[18];
        s[34] = x7159;
        let x7160 = x5027 * k[14];
        s[35] = x7160;
        let x7161 = x7159 + x7160;
        s[36] = x7161;
        let x7162 = 0.08333333333333333 * x7161;
        s[37] = x7162;
        let x7163 = dp[3] * k[20];
        s[38] = x7163;
        let x7164 = x5032 * k[15];
        s[39] = x7164;
        let x7165 = x7163 + x7164;
        s[40] = x7165;
        let x7166 = 0.08333333333333333 * x7165;
        s[41] = x7166;
    }
    #[inline(never)]
    fn tangents_part_0(
        k: &[f64; 23],
        q: &[f64; 18],
        qd: &[f64; 18],
        dq: &[f64; 18],
        dqd: &[f64; 18],
        dp: &[f64; 33],
        s: &[f64; 42],
        mass: &mut [f64; 30],
        force: &mut [f64; 18],
    ) {
        let (x12, x13) = symbody_runtime::trig::sin_cos(q[3]);
        let (x14, x15) = symbody_runtime::trig::sin_cos(q[4]);
        let x22 = x12 * x15;
        let x23 = x13 * x15;
        let x729 = x13 * qd[3];
        let x730 = x12 * qd[3];
        let x732 = x15 * qd[4];
        let x733 = x14 * qd[4];
        let x755 = x15 * x729;
        let x756 = x12 * x733;
        let x758 = x755 - x756;
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
        let x2108 = 2.0 * s[2];
        let x2114 = 2.0 * s[1];
        let x2115 = 2.0 * s[0];
        let x2117 = s[1] * x2114;
        let x2119 = s[0] * x2115;
        let x2125 = 2.0 * s[4];
        let x2126 = 2.0 * s[5];
        let x2127 = s[1] * x2125;
        let x2129 = s[0] * x2126;
        let x2134 = s[4] * x2114;
        let x2136 = s[5] * x2115;
        let x2142 = s[2] * x2108;
        let x2146 = s[4] * x2125;
        let x2148 = s[5] * x2126;
        let x2319 = 2.0 * s[8];
        let x2325 = 2.0 * s[7];
        let x2326 = 2.0 * s[6];
        let x2328 = s[7] * x2325;
        let x2330 = s[6] * x2326;
        let x2336 = 2.0 * s[10];
        let x2337 = 2.0 * s[11];
        let x2338 = s[7] * x2336;
        let x2340 = s[6] * x2337;
        let x2345 = s[10] * x2325;
        let x2347 = s[11] * x2326;
        let x2353 = s[8] * x2319;
        let x2357 = s[10] * x2336;
        let x2359 = s[11] * x2337;
        let x2536 = x13 * dq[3];
        let x2537 = x12 * dq[3];
        let x2539 = x15 * dq[4];
        let x2540 = x14 * dq[4];
        let x2562 = x15 * x2536;
        let x2563 = x12 * x2540;
        let x2565 = x2562 - x2563;
        let x2566 = x15 * x2537;
        let x2568 = x13 * x2540;
        let x2570 = x2566 + x2568;
        let x3620 = qd[3] * x2537;
        let x3622 = x13 * dqd[3];
        let x3623 = x3622 - x3620;
        let x3624 = qd[3] * x2536;
        let x3625 = x12 * dqd[3];
        let x3626 = x3624 + x3625;
        let x3627 = qd[4] * x2540;
        let x3629 = x15 * dqd[4];
        let x3630 = x3629 - x3627;
        let x3631 = qd[4] * x2539;
        let x3632 = x14 * dqd[4];
        let x3633 = x3631 + x3632;
        let x3676 = x729 * x2540;
        let x3678 = x15 * x3623;
        let x3679 = x3678 - x3676;
        let x3680 = x733 * x2536;
        let x3681 = x12 * x3633;
        let x3682 = x3680 + x3681;
        let x3684 = x3679 - x3682;
        let x5022 = 0.2 * dp[1];
        let x5037 = qd[5] * x2539;
        let x5038 = x14 * dqd[5];
        let x5039 = x5037 + x5038;
        let x5041 = qd[5] * x2540;
        let x5043 = x15 * dqd[5];
        let x5044 = x5043 - x5041;
        let x5045 = qd[4] * x2537;
        let x5047 = x13 * dqd[4];
        let x5048 = x5047 - x5045;
        let x5049 = x1830 * x2536;
        let x5050 = x12 * x5044;
        let x5051 = x5049 + x5050;
        let x5052 = x5048 + x5051;
        let x5053 = qd[4] * x2536;
        let x5054 = x12 * dqd[4];
        let x5055 = x5053 + x5054;
        let x5056 = x1830 * x2537;
        let x5058 = x13 * x5044;
        let x5059 = x5058 - x5056;
        let x5061 = x5059 - x5055;
        let x5062 = dqd[3] - x5039;
        let x5063 = 2.0 * x5062;
        let x5064 = 2.0 * x5052;
        let x5065 = 2.0 * x5061;
        let x5066 = 2.0 * dp[0];
        let x5067 = 0.5 * x5066;
        let x5068 = 2.0 * x2539;
        let x5069 = x1892 * dp[0];
        let x5074 = 2.0 * x2537;
        let x5076 = 2.0 * x2536;
        let x5077 = x1898 * x2537;
        let x5079 = x13 * x5074;
        let x5081 = x5077 + x5079;
        let x5087 = x1899 * x2536;
        let x5088 = x12 * x5076;
        let x5089 = x5087 + x5088;
        let x5095 = 2.0 * x2565;
        let x5096 = 2.0 * x2570;
        let x5098 = x1909 * x2537;
        let x5100 = x13 * x5095;
        let x5101 = x5100 - x5098;
        let x5105 = x1910 * x2536;
        let x5106 = x12 * x5096;
        let x5108 = x5105 - x5106;
        let x5115 = x1898 * x2565;
        let x5116 = x22 * x5074;
        let x5118 = x5115 - x5116;
        let x5122 = x1899 * x2570;
        let x5124 = x23 * x5076;
        let x5125 = x5124 - x5122;
        let x5132 = x1892 * x2539;
        let x5133 = x14 * x5068;
        let x5134 = x5132 + x5133;
        let x5135 = x1926 * dp[0];
        let x5138 = x1909 * x2565;
        let x5139 = x22 * x5095;
        let x5140 = x5138 + x5139;
        let x5144 = x1910 * x2570;
        let x5146 = x23 * x5096;
        let x5148 = x5144 + x5146;
        let x5157 = x730 * x2540;
        let x5159 = x15 * x3626;
        let x5160 = x5159 - x5157;
        let x5161 = x733 * x2537;
        let x5163 = x13 * x3633;
        let x5164 = x5163 - x5161;
        let x5165 = x5160 + x5164;
        let x5166 = x732 * dqd[5];
        let x5167 = qd[5] * x3630;
        let x5168 = x5166 + x5167;
        let x5169 = x733 * dqd[5];
        let x5170 = qd[5] * x3633;
        let x5171 = x5169 + x5170;
        let x5172 = x730 * dqd[4];
        let x5173 = qd[4] * x3626;
        let x5174 = x5172 + x5173;
        let x5176 = x1830 * x3623;
        let x5177 = x729 * x5044;
        let x5178 = x5176 + x5177;
        let x5179 = x1945 * x2536;
        let x5180 = x12 * x5171;
        let x5181 = x5179 + x5180;
        let x5183 = x5178 - x5181;
        let x5184 = x5183 - x5174;
        let x5185 = x729 * dqd[4];
        let x5186 = qd[4] * x3623;
        let x5187 = x5185 + x5186;
        let x5188 = x1830 * x3626;
        let x5189 = x730 * x5044;
        let x5190 = x5188 + x5189;
        let x5191 = x1945 * x2537;
        let x5193 = x13 * x5171;
        let x5194 = x5193 - x5191;
        let x5195 = x5190 + x5194;
        let x5196 = x5187 + x5195;
        let x5197 = 2.0 * x5168;
        let x5198 = 2.0 * x5184;
        let x5199 = 2.0 * x5196;
        let x5200 = x1964 * dp[0];
        let x5204 = x1861 * x3626;
        let x5205 = x730 * x5064;
        let x5206 = x5204 + x5205;
        let x5208 = x1966 * x2537;
        let x5210 = x13 * x5198;
        let x5211 = x5210 - x5208;
        let x5212 = x5211 - x5206;
        let x5216 = x1863 * x3623;
        let x5217 = x729 * x5065;
        let x5218 = x5216 + x5217;
        let x5219 = x1967 * x2536;
        let x5220 = x12 * x5199;
        let x5221 = x5219 + x5220;
        let x5223 = x5218 - x5221;
        let x5230 = x1859 * x3630;
        let x5231 = x732 * x5063;
        let x5232 = x5230 + x5231;
        let x5233 = x1964 * x2539;
        let x5234 = x14 * x5197;
        let x5235 = x5233 + x5234;
        let x5237 = x5232 - x5235;
        let x5238 = x1989 * dp[0];
        let x5242 = x1861 * x3684;
        let x5243 = x758 * x5064;
        let x5244 = x5242 + x5243;
        let x5245 = x1966 * x2565;
        let x5246 = x22 * x5198;
        let x5247 = x5245 + x5246;
        let x5248 = x5244 + x5247;
        let x5252 = x1941 * x5065;
        let x5253 = x1863 * x5165;
        let x5254 = x5252 + x5253;
        let x5255 = x1967 * x2570;
        let x5257 = x23 * x5199;
        let x5258 = x5257 - x5255;
        let x5259 = x5254 + x5258;
        let x5267 = x1861 * x5061;
        let x5268 = x1837 * x5064;
        let x5269 = x5267 + x5268;
        let x5273 = x1863 * x5052;
        let x5274 = x1833 * x5065;
        let x5275 = x5273 + x5274;
        let x5283 = x1828 * x2536;
        let x5284 = x12 * x5039;
        let x5285 = x5283 + x5284;
        let x5286 = x1828 * x2537;
        let x5288 = x13 * x5039;
        let x5289 = x5288 - x5286;
        let x5290 = x1859 * x5044;
        let x5291 = x1830 * x5063;
        let x5292 = x5290 + x5291;
        let x5293 = x2024 * dp[0];
        let x5296 = x2020 * x5064;
        let x5297 = x1861 * x5285;
        let x5298 = x5296 + x5297;
        let x5302 = x2022 * x5065;
        let x5303 = x1863 * x5289;
        let x5304 = x5302 + x5303;
        let x5343 = 2.0 * s[14];
        let x5344 = x2108 * dp[0];
        let x5349 = 2.0 * s[13];
        let x5351 = 2.0 * s[12];
        let x5352 = x2114 * s[13];
        let x5354 = s[1] * x5349;
        let x5356 = x5352 + x5354;
        let x5362 = x2115 * s[12];
        let x5363 = s[0] * x5351;
        let x5364 = x5362 + x5363;
        let x5370 = 2.0 * s[18];
        let x5371 = 2.0 * s[21];
        let x5373 = x2125 * s[13];
        let x5375 = s[1] * x5370;
        let x5376 = x5375 - x5373;
        let x5380 = x2126 * s[12];
        let x5381 = s[0] * x5371;
        let x5383 = x5380 - x5381;
        let x5390 = x2114 * s[18];
        let x5391 = s[4] * x5349;
        let x5393 = x5390 - x5391;
        let x5397 = x2115 * s[21];
        let x5399 = s[5] * x5351;
        let x5400 = x5399 - x5397;
        let x5407 = x2108 * s[14];
        let x5408 = s[2] * x5343;
        let x5409 = x5407 + x5408;
        let x5410 = x2142 * dp[0];
        let x5413 = x2125 * s[18];
        let x5414 = s[4] * x5370;
        let x5415 = x5413 + x5414;
        let x5419 = x2126 * s[21];
        let x5421 = s[5] * x5371;
        let x5423 = x5419 + x5421;
        let x5609 = 2.0 * s[24];
        let x5610 = x2319 * dp[0];
        let x5615 = 2.0 * s[23];
        let x5617 = 2.0 * s[22];
        let x5618 = x2325 * s[23];
        let x5620 = s[7] * x5615;
        let x5622 = x5618 + x5620;
        let x5628 = x2326 * s[22];
        let x5629 = s[6] * x5617;
        let x5630 = x5628 + x5629;
        let x5636 = 2.0 * s[28];
        let x5637 = 2.0 * s[31];
        let x5639 = x2336 * s[23];
        let x5641 = s[7] * x5636;
        let x5642 = x5641 - x5639;
        let x5646 = x2337 * s[22];
        let x5647 = s[6] * x5637;
        let x5649 = x5646 - x5647;
        let x5656 = x2325 * s[28];
        let x5657 = s[10] * x5615;
        let x5659 = x5656 - x5657;
        let x5663 = x2326 * s[31];
        let x5665 = s[11] * x5617;
        let x5666 = x5665 - x5663;
        let x5673 = x2319 * s[24];
        let x5674 = s[8] * x5609;
        let x5675 = x5673 + x5674;
        let x5676 = x2353 * dp[0];
        let x5679 = x2336 * s[28];
        let x5680 = s[10] * x5636;
        let x5681 = x5679 + x5680;
        let x5685 = x2337 * s[31];
        let x5687 = s[11] * x5637;
        let x5689 = x5685 + x5687;
        let x7155 = dp[1] * k[16];
        let x7156 = x5022 * k[13];
        let x7157 = x7155 + x7156;
        let x7158 = 0.08333333333333333 * x7157;
        let x7167 = x5068 * k[12];
        let x7168 = x5069 + x7167;
        let x7169 = 0.5 * x7168;
        let x7170 = -x7169;
        let x7171 = x1901 * x7158;
        let x7172 = x5081 * k[17];
        let x7174 = x7171 - x7172;
        let x7175 = x1903 * x7158;
        let x7176 = x5089 * k[17];
        let x7177 = x7175 + x7176;
        let x7178 = x7174 + x7177;
        let x7179 = 0.5 * x7178;
        let x7180 = x1911 * x7158;
        let x7181 = x5101 * k[17];
        let x7182 = x7180 + x7181;
        let x7183 = x1913 * x7158;
        let x7184 = x5108 * k[17];
        let x7185 = x7183 + x7184;
        let x7187 = x7182 - x7185;
        let x7188 = 0.5 * x7187;
        let x7189 = x1918 * x7158;
        let x7190 = x5118 * k[17];
        let x7191 = x7189 + x7190;
        let x7192 = x1920 * x7158;
        let x7193 = x5125 * k[17];
        let x7194 = x7192 + x7193;
        let x7196 = x7191 - x7194;
        let x7197 = 0.5 * x7196;
        let x7198 = x5134 * k[12];
        let x7199 = x5135 + x7198;
        let x7200 = x1930 * x7158;
        let x7201 = x5140 * k[17];
        let x7202 = x7200 + x7201;
        let x7203 = x1932 * x7158;
        let x7204 = x5148 * k[17];
        let x7206 = x7203 - x7204;
        let x7207 = x7199 + x7202;
        let x7208 = x7206 + x7207;
        let x7209 = 0.5 * x7208;
        let x7210 = x5197 * k[12];
        let x7211 = x5200 + x7210;
        let x7212 = 0.5 * x7211;
        let x7213 = x1976 * x7158;
        let x7214 = x5212 * k[17];
        let x7215 = x7213 + x7214;
        let x7216 = x1981 * x7158;
        let x7217 = x5223 * k[17];
        let x7218 = x7216 + x7217;
        let x7220 = x7215 - x7218;
        let x7221 = 0.5 * x7220;
        let x7222 = x5237 * k[12];
        let x7223 = x5238 + x7222;
        let x7225 = x1994 * x7158;
        let x7226 = x5248 * k[17];
        let x7227 = x7225 + x7226;
        let x7228 = x2000 * x7158;
        let x7229 = x5259 * k[17];
        let x7230 = x7228 + x7229;
        let x7232 = x7227 - x7223;
        let x7233 = x7232 - x7230;
        let x7234 = 0.5 * x7233;
        let x7235 = x2010 * x7158;
        let x7236 = x5269 * k[17];
        let x7237 = x7235 + x7236;
        let x7238 = x2012 * x7158;
        let x7239 = x5275 * k[17];
        let x7240 = x7238 + x7239;
        let x7242 = x7237 - x7240;
        let x7243 = 0.5 * x7242;
        let x7244 = x7212 + x7243;
        let x7245 = x5292 * k[12];
        let x7246 = x5293 + x7245;
        let x7247 = x2028 * x7158;
        let x7248 = x5298 * k[17];
        let x7249 = x7247 + x7248;
        let x7250 = x2032 * x7158;
        let x7251 = x5304 * k[17];
        let x7252 = x7250 + x7251;
        let x7253 = x7246 + x7249;
        let x7254 = x7252 + x7253;
        let x7255 = 0.5 * x7254;
        let x7256 = x7221 + x7255;
        let x7257 = -x7256;
        let x7258 = -x7234;
        let x7259 = x5343 * k[12];
        let x7260 = x5344 + x7259;
        let x7261 = 0.5 * x7260;
        let x7262 = -x7261;
        let x7263 = x2117 * s[37];
        let x7264 = x5356 * k[19];
        let x7266 = x7263 - x7264;
        let x7267 = x2119 * s[37];
        let x7268 = x5364 * k[19];
        let x7269 = x7267 + x7268;
        let x7270 = x7266 + x7269;
        let x7271 = 0.5 * x7270;
        let x7272 = x2127 * s[37];
        let x7273 = x5376 * k[19];
        let x7274 = x7272 + x7273;
        let x7275 = x2129 * s[37];
        let x7276 = x5383 * k[19];
        let x7277 = x7275 + x7276;
        let x7279 = x7274 - x7277;
        let x7280 = 0.5 * x7279;
        let x7281 = x2134 * s[37];
        let x7282 = x5393 * k[19];
        let x7283 = x7281 + x7282;
        let x7284 = x2136 * s[37];
        let x7285 = x5400 * k[19];
        let x7286 = x7284 + x7285;
        let x7288 = x7283 - x7286;
        let x7289 = 0.5 * x7288;
        let x7290 = x5409 * k[12];
        let x7291 = x5410 + x7290;
        let x7292 = x2146 * s[37];
        let x7293 = x5415 * k[19];
        let x7294 = x7292 + x7293;
        let x7295 = x2148 * s[37];
        let x7296 = x5423 * k[19];
        let x7298 = x7295 - x7296;
        let x7299 = x7291 + x7294;
        let x7300 = x7298 + x7299;
        let x7301 = 0.5 * x7300;
        let x7351 = x5609 * k[12];
        let x7352 = x5610 + x7351;
        let x7353 = 0.5 * x7352;
        let x7354 = -x7353;
        let x7355 = x2328 * s[41];
        let x7356 = x5622 * k[21];
        let x7358 = x7355 - x7356;
        let x7359 = x2330 * s[41];
        let x7360 = x5630 * k[21];
        let x7361 = x7359 + x7360;
        let x7362 = x7358 + x7361;
        let x7363 = 0.5 * x7362;
        let x7364 = x2338 * s[41];
        let x7365 = x5642 * k[21];
        let x7366 = x7364 + x7365;
        let x7367 = x2340 * s[41];
        let x7368 = x5649 * k[21];
        let x7369 = x7367 + x7368;
        let x7371 = x7366 - x7369;
        let x7372 = 0.5 * x7371;
        let x7373 = x2345 * s[41];
        let x7374 = x5659 * k[21];
        let x7375 = x7373 + x7374;
        let x7376 = x2347 * s[41];
        let x7377 = x5666 * k[21];
        let x7378 = x7376 + x7377;
        let x7380 = x7375 - x7378;
        let x7381 = 0.5 * x7380;
        let x7382 = x5675 * k[12];
        let x7383 = x5676 + x7382;
        let x7384 = x2357 * s[41];
        let x7385 = x5681 * k[21];
        let x7386 = x7384 + x7385;
        let x7387 = x2359 * s[41];
        let x7388 = x5689 * k[21];
        let x7390 = x7387 - x7388;
        let x7391 = x7383 + x7386;
        let x7392 = x7390 + x7391;
        let x7393 = 0.5 * x7392;
        mass[0] = 0.0;
        mass[1] = 0.0;
        mass[2] = 0.0;
        mass[3] = x5067;
        mass[4] = x7170;
        mass[5] = x7179;
        mass[6] = x7188;
        mass[7] = x7170;
        mass[8] = x7197;
        mass[9] = x7209;
        mass[10] = 0.0;
        mass[11] = 0.0;
        mass[12] = 0.0;
        mass[13] = x5067;
        mass[14] = x7262;
        mass[15] = x7271;
        mass[16] = x7280;
        mass[17] = x7262;
        mass[18] = x7289;
        mass[19] = x7301;
        mass[20] = 0.0;
        mass[21] = 0.0;
        mass[22] = 0.0;
        mass[23] = x5067;
        mass[24] = x7354;
        mass[25] = x7363;
        mass[26] = x7372;
        mass[27] = x7354;
        mass[28] = x7381;
        mass[29] = x7393;
        force[0] = 0.0;
        force[1] = 0.0;
        force[2] = 0.0;
        force[3] = x7244;
        force[4] = x7257;
        force[5] = x7258;
        force[6] = 0.0;
        force[7] = 0.0;
        force[8] = 0.0;
    }
    #[inline(never)]
    fn tangents_part_1(
        k: &[f64; 23],
        qd: &[f64; 18],
        dqd: &[f64; 18],
        dp: &[f64; 33],
        s: &[f64; 42],
        force: &mut [f64; 18],
    ) {
        let x797 = s[1] * qd[9];
        let x798 = s[0] * qd[9];
        let x800 = s[3] * qd[10];
        let x801 = s[2] * qd[10];
        let x823 = s[3] * x797;
        let x824 = s[0] * x801;
        let x826 = x823 - x824;
        let x827 = s[3] * x798;
        let x829 = s[1] * x801;
        let x831 = x827 + x829;
        let x870 = s[7] * qd[15];
        let x871 = s[6] * qd[15];
        let x873 = s[9] * qd[16];
        let x874 = s[8] * qd[16];
        let x896 = s[9] * x870;
        let x897 = s[6] * x874;
        let x899 = x896 - x897;
        let x900 = s[9] * x871;
        let x902 = s[7] * x874;
        let x904 = x900 + x902;
        let x2046 = s[2] * qd[11];
        let x2048 = s[3] * qd[11];
        let x2049 = s[1] * qd[10];
        let x2050 = s[0] * x2048;
        let x2051 = x2049 + x2050;
        let x2052 = s[0] * qd[10];
        let x2053 = s[1] * x2048;
        let x2055 = x2053 - x2052;
        let x2056 = qd[9] - x2046;
        let x2077 = 2.0 * x2056;
        let x2079 = 2.0 * x2051;
        let x2081 = 2.0 * x2055;
        let x2153 = qd[11] * x800;
        let x2155 = qd[11] * x801;
        let x2157 = qd[10] * x798;
        let x2159 = x797 * x2048;
        let x2160 = s[0] * x2155;
        let x2162 = x2159 - x2160;
        let x2163 = x2162 - x2157;
        let x2164 = qd[10] * x797;
        let x2165 = x798 * x2048;
        let x2167 = s[1] * x2155;
        let x2169 = x2165 + x2167;
        let x2172 = x2164 + x2169;
        let x2174 = 2.0 * x2153;
        let x2176 = 2.0 * x2163;
        let x2177 = 2.0 * x2172;
        let x2183 = x798 * x2079;
        let x2185 = s[1] * x2176;
        let x2186 = x2185 - x2183;
        let x2188 = x797 * x2081;
        let x2189 = s[0] * x2177;
        let x2191 = x2188 - x2189;
        let x2196 = x800 * x2077;
        let x2197 = s[2] * x2174;
        let x2199 = x2196 - x2197;
        let x2202 = x826 * x2079;
        let x2203 = s[4] * x2176;
        let x2204 = x2202 + x2203;
        let x2206 = x831 * x2081;
        let x2208 = s[5] * x2177;
        let x2210 = x2206 + x2208;
        let x2220 = x2055 * x2079;
        let x2222 = x2051 * x2081;
        let x2230 = s[0] * x2046;
        let x2232 = s[1] * x2046;
        let x2234 = x2048 * x2077;
        let x2238 = x2079 * x2230;
        let x2242 = x2081 * x2232;
        let x2256 = s[8] * qd[17];
        let x2258 = s[9] * qd[17];
        let x2259 = s[7] * qd[16];
        let x2260 = s[6] * x2258;
        let x2261 = x2259 + x2260;
        let x2262 = s[6] * qd[16];
        let x2263 = s[7] * x2258;
        let x2265 = x2263 - x2262;
        let x2266 = qd[15] - x2256;
        let x2287 = 2.0 * x2266;
        let x2289 = 2.0 * x2261;
        let x2291 = 2.0 * x2265;
        let x2364 = qd[17] * x873;
        let x2366 = qd[17] * x874;
        let x2368 = qd[16] * x871;
        let x2370 = x870 * x2258;
        let x2371 = s[6] * x2366;
        let x2373 = x2370 - x2371;
        let x2374 = x2373 - x2368;
        let x2375 = qd[16] * x870;
        let x2376 = x871 * x2258;
        let x2378 = s[7] * x2366;
        let x2380 = x2376 + x2378;
        let x2383 = x2375 + x2380;
        let x2385 = 2.0 * x2364;
        let x2387 = 2.0 * x2374;
        let x2388 = 2.0 * x2383;
        let x2394 = x871 * x2289;
        let x2396 = s[7] * x2387;
        let x2397 = x2396 - x2394;
        let x2399 = x870 * x2291;
        let x2400 = s[6] * x2388;
        let x2402 = x2399 - x2400;
        let x2407 = x873 * x2287;
        let x2408 = s[8] * x2385;
        let x2410 = x2407 - x2408;
        let x2413 = x899 * x2289;
        let x2414 = s[10] * x2387;
        let x2415 = x2413 + x2414;
        let x2417 = x904 * x2291;
        let x2419 = s[11] * x2388;
        let x2421 = x2417 + x2419;
        let x2431 = x2265 * x2289;
        let x2433 = x2261 * x2291;
        let x2441 = s[6] * x2256;
        let x2443 = s[7] * x2256;
        let x2445 = x2258 * x2287;
        let x2449 = x2289 * x2441;
        let x2453 = x2291 * x2443;
        let x3722 = qd[9] * s[13];
        let x3724 = s[1] * dqd[9];
        let x3725 = x3724 - x3722;
        let x3726 = qd[9] * s[12];
        let x3727 = s[0] * dqd[9];
        let x3728 = x3726 + x3727;
        let x3729 = qd[10] * s[15];
        let x3731 = s[3] * dqd[10];
        let x3732 = x3731 - x3729;
        let x3733 = qd[10] * s[14];
        let x3734 = s[2] * dqd[10];
        let x3735 = x3733 + x3734;
        let x3777 = x797 * s[15];
        let x3779 = s[3] * x3725;
        let x3780 = x3779 - x3777;
        let x3781 = x801 * s[12];
        let x3782 = s[0] * x3735;
        let x3783 = x3781 + x3782;
        let x3785 = x3780 - x3783;
        let x3786 = x798 * s[15];
        let x3788 = s[3] * x3728;
        let x3789 = x3788 - x3786;
        let x3790 = x801 * s[13];
        let x3792 = s[1] * x3735;
        let x3793 = x3792 - x3790;
        let x3794 = x3789 + x3793;
        let x3868 = qd[15] * s[23];
        let x3870 = s[7] * dqd[15];
        let x3871 = x3870 - x3868;
        let x3872 = qd[15] * s[22];
        let x3873 = s[6] * dqd[15];
        let x3874 = x3872 + x3873;
        let x3875 = qd[16] * s[25];
        let x3877 = s[9] * dqd[16];
        let x3878 = x3877 - x3875;
        let x3879 = qd[16] * s[24];
        let x3880 = s[8] * dqd[16];
        let x3881 = x3879 + x3880;
        let x3905 = x870 * s[25];
        let x3907 = s[9] * x3871;
        let x3908 = x3907 - x3905;
        let x3909 = x874 * s[22];
        let x3910 = s[6] * x3881;
        let x3911 = x3909 + x3910;
        let x3913 = x3908 - x3911;
        let x3914 = x871 * s[25];
        let x3916 = s[9] * x3874;
        let x3917 = x3916 - x3914;
        let x3918 = x874 * s[23];
        let x3920 = s[7] * x3881;
        let x3921 = x3920 - x3918;
        let x3922 = x3917 + x3921;
        let x5314 = qd[11] * s[14];
        let x5315 = s[2] * dqd[11];
        let x5316 = x5314 + x5315;
        let x5318 = qd[11] * s[15];
        let x5320 = s[3] * dqd[11];
        let x5321 = x5320 - x5318;
        let x5322 = qd[10] * s[13];
        let x5324 = s[1] * dqd[10];
        let x5325 = x5324 - x5322;
        let x5326 = x2048 * s[12];
        let x5327 = s[0] * x5321;
        let x5328 = x5326 + x5327;
        let x5329 = x5325 + x5328;
        let x5330 = qd[10] * s[12];
        let x5331 = s[0] * dqd[10];
        let x5332 = x5330 + x5331;
        let x5333 = x2048 * s[13];
        let x5335 = s[1] * x5321;
        let x5336 = x5335 - x5333;
        let x5338 = x5336 - x5332;
        let x5339 = dqd[9] - x5316;
        let x5340 = 2.0 * x5339;
        let x5341 = 2.0 * x5329;
        let x5342 = 2.0 * x5338;
        let x5432 = x800 * dqd[11];
        let x5433 = qd[11] * x3732;
        let x5434 = x5432 + x5433;
        let x5435 = x801 * dqd[11];
        let x5436 = qd[11] * x3735;
        let x5437 = x5435 + x5436;
        let x5438 = x798 * dqd[10];
        let x5439 = qd[10] * x3728;
        let x5440 = x5438 + x5439;
        let x5442 = x2048 * x3725;
        let x5443 = x797 * x5321;
        let x5444 = x5442 + x5443;
        let x5445 = x2155 * s[12];
        let x5446 = s[0] * x5437;
        let x5447 = x5445 + x5446;
        let x5449 = x5444 - x5447;
        let x5450 = x5449 - x5440;
        let x5451 = x797 * dqd[10];
        let x5452 = qd[10] * x3725;
        let x5453 = x5451 + x5452;
        let x5454 = x2048 * x3728;
        let x5455 = x798 * x5321;
        let x5456 = x5454 + x5455;
        let x5457 = x2155 * s[13];
        let x5459 = s[1] * x5437;
        let x5460 = x5459 - x5457;
        let x5461 = x5456 + x5460;
        let x5462 = x5453 + x5461;
        let x5463 = 2.0 * x5434;
        let x5464 = 2.0 * x5450;
        let x5465 = 2.0 * x5462;
        let x5466 = x2174 * dp[0];
        let x5470 = x2079 * x3728;
        let x5471 = x798 * x5341;
        let x5472 = x5470 + x5471;
        let x5474 = x2176 * s[13];
        let x5476 = s[1] * x5464;
        let x5477 = x5476 - x5474;
        let x5478 = x5477 - x5472;
        let x5482 = x2081 * x3725;
        let x5483 = x797 * x5342;
        let x5484 = x5482 + x5483;
        let x5485 = x2177 * s[12];
        let x5486 = s[0] * x5465;
        let x5487 = x5485 + x5486;
        let x5489 = x5484 - x5487;
        let x5496 = x2077 * x3732;
        let x5497 = x800 * x5340;
        let x5498 = x5496 + x5497;
        let x5499 = x2174 * s[14];
        let x5500 = s[2] * x5463;
        let x5501 = x5499 + x5500;
        let x5503 = x5498 - x5501;
        let x5504 = x2199 * dp[0];
        let x5508 = x2079 * x3785;
        let x5509 = x826 * x5341;
        let x5510 = x5508 + x5509;
        let x5511 = x2176 * s[18];
        let x5512 = s[4] * x5464;
        let x5513 = x5511 + x5512;
        let x5514 = x5510 + x5513;
        let x5518 = x2081 * x3794;
        let x5519 = x831 * x5342;
        let x5520 = x5518 + x5519;
        let x5521 = x2177 * s[21];
        let x5523 = s[5] * x5465;
        let x5524 = x5523 - x5521;
        let x5525 = x5520 + x5524;
        let x5533 = x2079 * x5338;
        let x5534 = x2055 * x5341;
        let x5535 = x5533 + x5534;
        let x5539 = x2081 * x5329;
        let x5540 = x2051 * x5342;
        let x5541 = x5539 + x5540;
        let x5549 = x2046 * s[12];
        let x5550 = s[0] * x5316;
        let x5551 = x5549 + x5550;
        let x5552 = x2046 * s[13];
        let x5554 = s[1] * x5316;
        let x5555 = x5554 - x5552;
        let x5556 = x2077 * x5321;
        let x5557 = x2048 * x5340;
        let x5558 = x5556 + x5557;
        let x5559 = x2234 * dp[0];
        let x5562 = x2230 * x5341;
        let x5563 = x2079 * x5551;
        let x5564 = x5562 + x5563;
        let x5568 = x2232 * x5342;
        let x5569 = x2081 * x5555;
        let x5570 = x5568 + x5569;
        let x5580 = qd[17] * s[24];
        let x5581 = s[8] * dqd[17];
        let x5582 = x5580 + x5581;
        let x5584 = qd[17] * s[25];
        let x5586 = s[9] * dqd[17];
        let x5587 = x5586 - x5584;
        let x5588 = qd[16] * s[23];
        let x5590 = s[7] * dqd[16];
        let x5591 = x5590 - x5588;
        let x5592 = x2258 * s[22];
        let x5593 = s[6] * x5587;
        let x5594 = x5592 + x5593;
        let x5595 = x5591 + x5594;
        let x5596 = qd[16] * s[22];
        let x5597 = s[6] * dqd[16];
        let x5598 = x5596 + x5597;
        let x5599 = x2258 * s[23];
        let x5601 = s[7] * x5587;
        let x5602 = x5601 - x5599;
        let x5604 = x5602 - x5598;
        let x5605 = dqd[15] - x5582;
        let x5606 = 2.0 * x5605;
        let x5607 = 2.0 * x5595;
        let x5608 = 2.0 * x5604;
        let x5698 = x873 * dqd[17];
        let x5699 = qd[17] * x3878;
        let x5700 = x5698 + x5699;
        let x5701 = x874 * dqd[17];
        let x5702 = qd[17] * x3881;
        let x5703 = x5701 + x5702;
        let x5704 = x871 * dqd[16];
        let x5705 = qd[16] * x3874;
        let x5706 = x5704 + x5705;
        let x5708 = x2258 * x3871;
        let x5709 = x870 * x5587;
        let x5710 = x5708 + x5709;
        let x5711 = x2366 * s[22];
        let x5712 = s[6] * x5703;
        let x5713 = x5711 + x5712;
        let x5715 = x5710 - x5713;
        let x5716 = x5715 - x5706;
        let x5717 = x870 * dqd[16];
        let x5718 = qd[16] * x3871;
        let x5719 = x5717 + x5718;
        let x5720 = x2258 * x3874;
        let x5721 = x871 * x5587;
        let x5722 = x5720 + x5721;
        let x5723 = x2366 * s[23];
        let x5725 = s[7] * x5703;
        let x5726 = x5725 - x5723;
        let x5727 = x5722 + x5726;
        let x5728 = x5719 + x5727;
        let x5729 = 2.0 * x5700;
        let x5730 = 2.0 * x5716;
        let x5731 = 2.0 * x5728;
        let x5732 = x2385 * dp[0];
        let x5736 = x2289 * x3874;
        let x5737 = x871 * x5607;
        let x5738 = x5736 + x5737;
        let x5740 = x2387 * s[23];
        let x5742 = s[7] * x5730;
        let x5743 = x5742 - x5740;
        let x5744 = x5743 - x5738;
        let x5748 = x2291 * x3871;
        let x5749 = x870 * x5608;
        let x5750 = x5748 + x5749;
        let x5751 = x2388 * s[22];
        let x5752 = s[6] * x5731;
        let x5753 = x5751 + x5752;
        let x5755 = x5750 - x5753;
        let x5762 = x2287 * x3878;
        let x5763 = x873 * x5606;
        let x5764 = x5762 + x5763;
        let x5765 = x2385 * s[24];
        let x5766 = s[8] * x5729;
        let x5767 = x5765 + x5766;
        let x5769 = x5764 - x5767;
        let x5770 = x2410 * dp[0];
        let x5774 = x2289 * x3913;
        let x5775 = x899 * x5607;
        let x5776 = x5774 + x5775;
        let x5777 = x2387 * s[28];
        let x5778 = s[10] * x5730;
        let x5779 = x5777 + x5778;
        let x5780 = x5776 + x5779;
        let x5784 = x2291 * x3922;
        let x5785 = x904 * x5608;
        let x5786 = x5784 + x5785;
        let x5787 = x2388 * s[31];
        let x5789 = s[11] * x5731;
        let x5790 = x5789 - x5787;
        let x5791 = x5786 + x5790;
        let x5799 = x2289 * x5604;
        let x5800 = x2265 * x5607;
        let x5801 = x5799 + x5800;
        let x5805 = x2291 * x5595;
        let x5806 = x2261 * x5608;
        let x5807 = x5805 + x5806;
        let x5815 = x2256 * s[22];
        let x5816 = s[6] * x5582;
        let x5817 = x5815 + x5816;
        let x5818 = x2256 * s[23];
        let x5820 = s[7] * x5582;
        let x5821 = x5820 - x5818;
        let x5822 = x2287 * x5587;
        let x5823 = x2258 * x5606;
        let x5824 = x5822 + x5823;
        let x5825 = x2445 * dp[0];
        let x5828 = x2441 * x5607;
        let x5829 = x2289 * x5817;
        let x5830 = x5828 + x5829;
        let x5834 = x2443 * x5608;
        let x5835 = x2291 * x5821;
        let x5836 = x5834 + x5835;
        let x7302 = x5463 * k[12];
        let x7303 = x5466 + x7302;
        let x7304 = 0.5 * x7303;
        let x7305 = x2186 * s[37];
        let x7306 = x5478 * k[19];
        let x7307 = x7305 + x7306;
        let x7308 = x2191 * s[37];
        let x7309 = x5489 * k[19];
        let x7310 = x7308 + x7309;
        let x7312 = x7307 - x7310;
        let x7313 = 0.5 * x7312;
        let x7314 = x5503 * k[12];
        let x7315 = x5504 + x7314;
        let x7317 = x2204 * s[37];
        let x7318 = x5514 * k[19];
        let x7319 = x7317 + x7318;
        let x7320 = x2210 * s[37];
        let x7321 = x5525 * k[19];
        let x7322 = x7320 + x7321;
        let x7324 = x7319 - x7315;
        let x7325 = x7324 - x7322;
        let x7326 = 0.5 * x7325;
        let x7327 = x2220 * s[37];
        let x7328 = x5535 * k[19];
        let x7329 = x7327 + x7328;
        let x7330 = x2222 * s[37];
        let x7331 = x5541 * k[19];
        let x7332 = x7330 + x7331;
        let x7334 = x7329 - x7332;
        let x7335 = 0.5 * x7334;
        let x7336 = x7304 + x7335;
        let x7337 = x5558 * k[12];
        let x7338 = x5559 + x7337;
        let x7339 = x2238 * s[37];
        let x7340 = x5564 * k[19];
        let x7341 = x7339 + x7340;
        let x7342 = x2242 * s[37];
        let x7343 = x5570 * k[19];
        let x7344 = x7342 + x7343;
        let x7345 = x7338 + x7341;
        let x7346 = x7344 + x7345;
        let x7347 = 0.5 * x7346;
        let x7348 = x7313 + x7347;
        let x7349 = -x7348;
        let x7350 = -x7326;
        let x7394 = x5729 * k[12];
        let x7395 = x5732 + x7394;
        let x7396 = 0.5 * x7395;
        let x7397 = x2397 * s[41];
        let x7398 = x5744 * k[21];
        let x7399 = x7397 + x7398;
        let x7400 = x2402 * s[41];
        let x7401 = x5755 * k[21];
        let x7402 = x7400 + x7401;
        let x7404 = x7399 - x7402;
        let x7405 = 0.5 * x7404;
        let x7406 = x5769 * k[12];
        let x7407 = x5770 + x7406;
        let x7409 = x2415 * s[41];
        let x7410 = x5780 * k[21];
        let x7411 = x7409 + x7410;
        let x7412 = x2421 * s[41];
        let x7413 = x5791 * k[21];
        let x7414 = x7412 + x7413;
        let x7416 = x7411 - x7407;
        let x7417 = x7416 - x7414;
        let x7418 = 0.5 * x7417;
        let x7419 = x2431 * s[41];
        let x7420 = x5801 * k[21];
        let x7421 = x7419 + x7420;
        let x7422 = x2433 * s[41];
        let x7423 = x5807 * k[21];
        let x7424 = x7422 + x7423;
        let x7426 = x7421 - x7424;
        let x7427 = 0.5 * x7426;
        let x7428 = x7396 + x7427;
        let x7429 = x5824 * k[12];
        let x7430 = x5825 + x7429;
        let x7431 = x2449 * s[41];
        let x7432 = x5830 * k[21];
        let x7433 = x7431 + x7432;
        let x7434 = x2453 * s[41];
        let x7435 = x5836 * k[21];
        let x7436 = x7434 + x7435;
        let x7437 = x7430 + x7433;
        let x7438 = x7436 + x7437;
        let x7439 = 0.5 * x7438;
        let x7440 = x7405 + x7439;
        let x7441 = -x7440;
        let x7442 = -x7418;
        force[9] = x7336;
        force[10] = x7349;
        force[11] = x7350;
        force[12] = 0.0;
        force[13] = 0.0;
        force[14] = 0.0;
        force[15] = x7428;
        force[16] = x7441;
        force[17] = x7442;
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
        let x6118 = 2.0 * x1807;
        let x6119 = 0.5 * x6118;
        let x6120 = 2.0 * x1811;
        let x6121 = 0.5 * x6120;
        let x6122 = 2.0 * x1815;
        let x6123 = 0.5 * x6122;
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
        k[10] = x6119;
        k[11] = x6121;
        k[12] = x6123;
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
        let (x16, x17) = symbody_runtime::trig::sin_cos(q[5]);
        let (x331, x332) = symbody_runtime::trig::sin_cos(x5);
        let (x5846, x5847) = symbody_runtime::trig::sin_cos(q[2]);
        let (x5849, x5850) = symbody_runtime::trig::sin_cos(q[8]);
        let x5856 = 0.00000000000000006123233995736766 * x5847;
        let x5857 = x5846 + x5856;
        let x5858 = 0.00000000000000006123233995736766 * x5846;
        let x5860 = x5858 - x5847;
        let x5921 = x331 * x5857;
        let x5922 = x332 * x5860;
        let x5924 = x5921 - x5922;
        let x6135 = x5847 * k[0];
        let x6136 = x5846 * k[0];
        let x6137 = q[0] + x6135;
        let x6138 = q[1] + x6136;
        let x6139 = -x6137;
        let x6140 = -x6138;
        let x6141 = x5847 * k[1];
        let x6142 = x5846 * k[1];
        let x6143 = q[0] + x6141;
        let x6144 = q[1] + x6142;
        let x6145 = x17 * k[2];
        let x6146 = x16 * k[2];
        let x6147 = q[3] + x6145;
        let x6148 = q[4] + x6146;
        let x6150 = x6143 - x6147;
        let x6152 = x6144 - x6148;
        let x6153 = x17 * k[3];
        let x6154 = x16 * k[4];
        let x6156 = x6153 - x6154;
        let x6157 = x16 * k[3];
        let x6158 = x17 * k[4];
        let x6159 = x6157 + x6158;
        let x6160 = q[3] + x6156;
        let x6161 = q[4] + x6159;
        let x6162 = x5850 * k[5];
        let x6163 = x5849 * k[6];
        let x6165 = x6162 - x6163;
        let x6166 = x5849 * k[5];
        let x6167 = x5850 * k[6];
        let x6168 = x6166 + x6167;
        let x6169 = q[6] + x6165;
        let x6170 = q[7] + x6168;
        let x6172 = x6160 - x6169;
        let x6174 = x6161 - x6170;
        let x6175 = x5850 * k[8];
        let x6176 = x5849 * k[9];
        let x6178 = x6175 - x6176;
        let x6179 = x5849 * k[8];
        let x6180 = x5850 * k[9];
        let x6181 = x6179 + x6180;
        let x6182 = q[6] + x6178;
        let x6183 = q[7] + x6181;
        let x6185 = k[7] - x6182;
        let x6186 = -x6183;
        out[0] = x6139;
        out[1] = x6140;
        out[2] = x6150;
        out[3] = x6152;
        out[4] = x6172;
        out[5] = x6174;
        out[6] = x6185;
        out[7] = x6186;
        out[8] = x5924;
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
        let (x16, x17) = symbody_runtime::trig::sin_cos(q[5]);
        let (x331, x332) = symbody_runtime::trig::sin_cos(x5);
        let (x5846, x5847) = symbody_runtime::trig::sin_cos(q[2]);
        let (x5849, x5850) = symbody_runtime::trig::sin_cos(q[8]);
        let x5856 = 0.00000000000000006123233995736766 * x5847;
        let x5857 = x5846 + x5856;
        let x5858 = 0.00000000000000006123233995736766 * x5846;
        let x5862 = x5847 - x5858;
        let x5928 = x331 * x5862;
        let x5929 = x332 * x5857;
        let x5931 = x5928 - x5929;
        let x6135 = x5847 * k[0];
        let x6136 = x5846 * k[0];
        let x6141 = x5847 * k[1];
        let x6142 = x5846 * k[1];
        let x6145 = x17 * k[2];
        let x6146 = x16 * k[2];
        let x6153 = x17 * k[3];
        let x6154 = x16 * k[4];
        let x6156 = x6153 - x6154;
        let x6157 = x16 * k[3];
        let x6158 = x17 * k[4];
        let x6159 = x6157 + x6158;
        let x6162 = x5850 * k[5];
        let x6163 = x5849 * k[6];
        let x6165 = x6162 - x6163;
        let x6166 = x5849 * k[5];
        let x6167 = x5850 * k[6];
        let x6168 = x6166 + x6167;
        let x6175 = x5850 * k[8];
        let x6176 = x5849 * k[9];
        let x6178 = x6175 - x6176;
        let x6179 = x5849 * k[8];
        let x6180 = x5850 * k[9];
        let x6181 = x6179 + x6180;
        let x6187 = -x6135;
        let x6188 = -x6142;
        let x6189 = -x6145;
        let x6190 = -x6159;
        let x6191 = -x6165;
        let x6192 = -x6178;
        out[0] = -1.0;
        out[1] = x6136;
        out[2] = -1.0;
        out[3] = x6187;
        out[4] = 1.0;
        out[5] = x6188;
        out[6] = -1.0;
        out[7] = x6146;
        out[8] = 1.0;
        out[9] = x6141;
        out[10] = -1.0;
        out[11] = x6189;
        out[12] = 1.0;
        out[13] = x6190;
        out[14] = -1.0;
        out[15] = x6168;
        out[16] = 1.0;
        out[17] = x6156;
        out[18] = -1.0;
        out[19] = x6191;
        out[20] = -1.0;
        out[21] = x6181;
        out[22] = -1.0;
        out[23] = x6192;
        out[24] = x5931;
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
        let (x331, x332) = symbody_runtime::trig::sin_cos(x5);
        let x703 = 6.283185307179586 * x332;
        let x705 = 6.283185307179586 * x331;
        let (x5846, x5847) = symbody_runtime::trig::sin_cos(q[2]);
        let x5856 = 0.00000000000000006123233995736766 * x5847;
        let x5857 = x5846 + x5856;
        let x5858 = 0.00000000000000006123233995736766 * x5846;
        let x5860 = x5858 - x5847;
        let x5945 = x703 * x5857;
        let x5946 = x705 * x5860;
        let x5948 = x5945 + x5946;
        out[0] = 0.0;
        out[1] = 0.0;
        out[2] = 0.0;
        out[3] = 0.0;
        out[4] = 0.0;
        out[5] = 0.0;
        out[6] = 0.0;
        out[7] = 0.0;
        out[8] = x5948;
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
        let (x16, x17) = symbody_runtime::trig::sin_cos(q[5]);
        let (x331, x332) = symbody_runtime::trig::sin_cos(x5);
        let x703 = 6.283185307179586 * x332;
        let x705 = 6.283185307179586 * x331;
        let x735 = x17 * qd[5];
        let x736 = x16 * qd[5];
        let x1122 = 6.283185307179586 * x705;
        let x1124 = 6.283185307179586 * x703;
        let x1141 = qd[5] * x736;
        let x1143 = qd[5] * x735;
        let (x5846, x5847) = symbody_runtime::trig::sin_cos(q[2]);
        let (x5849, x5850) = symbody_runtime::trig::sin_cos(q[8]);
        let x5856 = 0.00000000000000006123233995736766 * x5847;
        let x5857 = x5846 + x5856;
        let x5858 = 0.00000000000000006123233995736766 * x5846;
        let x5860 = x5858 - x5847;
        let x5949 = qd[2] * x5847;
        let x5950 = qd[2] * x5846;
        let x5952 = qd[8] * x5850;
        let x5953 = qd[8] * x5849;
        let x5960 = 0.00000000000000006123233995736766 * x5950;
        let x5962 = x5949 - x5960;
        let x5963 = 0.00000000000000006123233995736766 * x5949;
        let x5964 = x5950 + x5963;
        let x6029 = x1122 * x5857;
        let x6031 = x703 * x5962;
        let x6032 = x6031 - x6029;
        let x6033 = x1124 * x5860;
        let x6034 = x705 * x5964;
        let x6035 = x6033 + x6034;
        let x6037 = qd[2] * x5950;
        let x6039 = qd[2] * x5949;
        let x6040 = qd[8] * x5953;
        let x6042 = qd[8] * x5952;
        let x6047 = 0.00000000000000006123233995736766 * x6039;
        let x6049 = x6037 + x6047;
        let x6051 = 0.00000000000000006123233995736766 * x6037;
        let x6053 = x6039 - x6051;
        let x6099 = x331 * x6049;
        let x6101 = x6031 - x6099;
        let x6102 = x6032 + x6101;
        let x6104 = x332 * x6053;
        let x6105 = x6104 - x6034;
        let x6106 = x6105 - x6035;
        let x6108 = x6102 - x6106;
        let x6113 = -x6108;
        let x6193 = x6039 * k[0];
        let x6194 = -x6193;
        let x6195 = x6037 * k[0];
        let x6196 = -x6195;
        let x6197 = x6039 * k[1];
        let x6199 = x6037 * k[1];
        let x6201 = x1143 * k[2];
        let x6202 = x1141 * k[2];
        let x6203 = x6201 - x6197;
        let x6204 = x6202 - x6199;
        let x6205 = x1143 * k[3];
        let x6206 = x1141 * k[4];
        let x6208 = x6205 - x6206;
        let x6210 = x1141 * k[3];
        let x6211 = x1143 * k[4];
        let x6212 = x6210 + x6211;
        let x6214 = x6042 * k[5];
        let x6215 = x6040 * k[6];
        let x6217 = x6214 - x6215;
        let x6218 = x6040 * k[5];
        let x6219 = x6042 * k[6];
        let x6220 = x6218 + x6219;
        let x6221 = x6217 - x6208;
        let x6222 = x6220 - x6212;
        let x6223 = x6042 * k[8];
        let x6224 = x6040 * k[9];
        let x6226 = x6223 - x6224;
        let x6227 = -x6226;
        let x6228 = x6040 * k[8];
        let x6229 = x6042 * k[9];
        let x6230 = x6228 + x6229;
        let x6231 = -x6230;
        let x6232 = -x6203;
        let x6233 = -x6204;
        let x6234 = -x6221;
        let x6235 = -x6222;
        out[0] = x6194;
        out[1] = x6196;
        out[2] = x6232;
        out[3] = x6233;
        out[4] = x6234;
        out[5] = x6235;
        out[6] = x6227;
        out[7] = x6231;
        out[8] = x6113;
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
        let (x16, x17) = symbody_runtime::trig::sin_cos(q[5]);
        let (x331, x332) = symbody_runtime::trig::sin_cos(x5);
        let x703 = 6.283185307179586 * x332;
        let x705 = 6.283185307179586 * x331;
        let x735 = x17 * qd[5];
        let x736 = x16 * qd[5];
        let x1122 = 6.283185307179586 * x705;
        let x1124 = 6.283185307179586 * x703;
        let x1141 = qd[5] * x736;
        let x1143 = qd[5] * x735;
        let (x5846, x5847) = symbody_runtime::trig::sin_cos(q[2]);
        let (x5849, x5850) = symbody_runtime::trig::sin_cos(q[8]);
        let x5856 = 0.00000000000000006123233995736766 * x5847;
        let x5857 = x5846 + x5856;
        let x5858 = 0.00000000000000006123233995736766 * x5846;
        let x5860 = x5858 - x5847;
        let x5862 = x5847 - x5858;
        let x5921 = x331 * x5857;
        let x5922 = x332 * x5860;
        let x5924 = x5921 - x5922;
        let x5928 = x331 * x5862;
        let x5929 = x332 * x5857;
        let x5931 = x5928 - x5929;
        let x5945 = x703 * x5857;
        let x5946 = x705 * x5860;
        let x5948 = x5945 + x5946;
        let x5949 = qd[2] * x5847;
        let x5950 = qd[2] * x5846;
        let x5952 = qd[8] * x5850;
        let x5953 = qd[8] * x5849;
        let x5960 = 0.00000000000000006123233995736766 * x5950;
        let x5962 = x5949 - x5960;
        let x5963 = 0.00000000000000006123233995736766 * x5949;
        let x5964 = x5950 + x5963;
        let x6029 = x1122 * x5857;
        let x6031 = x703 * x5962;
        let x6032 = x6031 - x6029;
        let x6033 = x1124 * x5860;
        let x6034 = x705 * x5964;
        let x6035 = x6033 + x6034;
        let x6037 = qd[2] * x5950;
        let x6039 = qd[2] * x5949;
        let x6040 = qd[8] * x5953;
        let x6042 = qd[8] * x5952;
        let x6047 = 0.00000000000000006123233995736766 * x6039;
        let x6049 = x6037 + x6047;
        let x6051 = 0.00000000000000006123233995736766 * x6037;
        let x6053 = x6039 - x6051;
        let x6099 = x331 * x6049;
        let x6101 = x6031 - x6099;
        let x6102 = x6032 + x6101;
        let x6104 = x332 * x6053;
        let x6105 = x6104 - x6034;
        let x6106 = x6105 - x6035;
        let x6108 = x6102 - x6106;
        let x6113 = -x6108;
        let x6135 = x5847 * k[0];
        let x6136 = x5846 * k[0];
        let x6137 = q[0] + x6135;
        let x6138 = q[1] + x6136;
        let x6139 = -x6137;
        let x6140 = -x6138;
        let x6141 = x5847 * k[1];
        let x6142 = x5846 * k[1];
        let x6143 = q[0] + x6141;
        let x6144 = q[1] + x6142;
        let x6145 = x17 * k[2];
        let x6146 = x16 * k[2];
        let x6147 = q[3] + x6145;
        let x6148 = q[4] + x6146;
        let x6150 = x6143 - x6147;
        let x6152 = x6144 - x6148;
        let x6153 = x17 * k[3];
        let x6154 = x16 * k[4];
        let x6156 = x6153 - x6154;
        let x6157 = x16 * k[3];
        let x6158 = x17 * k[4];
        let x6159 = x6157 + x6158;
        let x6160 = q[3] + x6156;
        let x6161 = q[4] + x6159;
        let x6162 = x5850 * k[5];
        let x6163 = x5849 * k[6];
        let x6165 = x6162 - x6163;
        let x6166 = x5849 * k[5];
        let x6167 = x5850 * k[6];
        let x6168 = x6166 + x6167;
        let x6169 = q[6] + x6165;
        let x6170 = q[7] + x6168;
        let x6172 = x6160 - x6169;
        let x6174 = x6161 - x6170;
        let x6175 = x5850 * k[8];
        let x6176 = x5849 * k[9];
        let x6178 = x6175 - x6176;
        let x6179 = x5849 * k[8];
        let x6180 = x5850 * k[9];
        let x6181 = x6179 + x6180;
        let x6182 = q[6] + x6178;
        let x6183 = q[7] + x6181;
        let x6185 = k[7] - x6182;
        let x6186 = -x6183;
        let x6187 = -x6135;
        let x6188 = -x6142;
        let x6189 = -x6145;
        let x6190 = -x6159;
        let x6191 = -x6165;
        let x6192 = -x6178;
        let x6193 = x6039 * k[0];
        let x6194 = -x6193;
        let x6195 = x6037 * k[0];
        let x6196 = -x6195;
        let x6197 = x6039 * k[1];
        let x6199 = x6037 * k[1];
        let x6201 = x1143 * k[2];
        let x6202 = x1141 * k[2];
        let x6203 = x6201 - x6197;
        let x6204 = x6202 - x6199;
        let x6205 = x1143 * k[3];
        let x6206 = x1141 * k[4];
        let x6208 = x6205 - x6206;
        let x6210 = x1141 * k[3];
        let x6211 = x1143 * k[4];
        let x6212 = x6210 + x6211;
        let x6214 = x6042 * k[5];
        let x6215 = x6040 * k[6];
        let x6217 = x6214 - x6215;
        let x6218 = x6040 * k[5];
        let x6219 = x6042 * k[6];
        let x6220 = x6218 + x6219;
        let x6221 = x6217 - x6208;
        let x6222 = x6220 - x6212;
        let x6223 = x6042 * k[8];
        let x6224 = x6040 * k[9];
        let x6226 = x6223 - x6224;
        let x6227 = -x6226;
        let x6228 = x6040 * k[8];
        let x6229 = x6042 * k[9];
        let x6230 = x6228 + x6229;
        let x6231 = -x6230;
        let x6232 = -x6203;
        let x6233 = -x6204;
        let x6234 = -x6221;
        let x6235 = -x6222;
        phi[0] = x6139;
        phi_q[0] = -1.0;
        phi_q[1] = x6136;
        phi_t[0] = 0.0;
        gamma[0] = x6194;
        phi[1] = x6140;
        phi_q[2] = -1.0;
        phi_q[3] = x6187;
        phi_t[1] = 0.0;
        gamma[1] = x6196;
        phi[2] = x6150;
        phi_q[4] = 1.0;
        phi_q[5] = x6188;
        phi_q[6] = -1.0;
        phi_q[7] = x6146;
        phi_t[2] = 0.0;
        gamma[2] = x6232;
        phi[3] = x6152;
        phi_q[8] = 1.0;
        phi_q[9] = x6141;
        phi_q[10] = -1.0;
        phi_q[11] = x6189;
        phi_t[3] = 0.0;
        gamma[3] = x6233;
        phi[4] = x6172;
        phi_q[12] = 1.0;
        phi_q[13] = x6190;
        phi_q[14] = -1.0;
        phi_q[15] = x6168;
        phi_t[4] = 0.0;
        gamma[4] = x6234;
        phi[5] = x6174;
        phi_q[16] = 1.0;
        phi_q[17] = x6156;
        phi_q[18] = -1.0;
        phi_q[19] = x6191;
        phi_t[5] = 0.0;
        gamma[5] = x6235;
        phi[6] = x6185;
        phi_q[20] = -1.0;
        phi_q[21] = x6181;
        phi_t[6] = 0.0;
        gamma[6] = x6227;
        phi[7] = x6186;
        phi_q[22] = -1.0;
        phi_q[23] = x6192;
        phi_t[7] = 0.0;
        gamma[7] = x6231;
        phi[8] = x5924;
        phi_q[24] = x5931;
        phi_t[8] = x5948;
        gamma[8] = x6113;
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
        let x6114 = q[4] * 4.905;
        let x6115 = q[7] * 3.9240000000000004;
        let x6116 = x1819 + x6114;
        let x6117 = x6115 + x6116;
        out[0] = x6117;
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
            kkt: &KKT,
        };
        use symbody_runtime::kkt::{
            length_error, mass_pivot_error, KktError, KktKernels, Pivoting,
        };
        /// The KKT factor and solve for this model's patterns, straight-line (`KktKernels`).
        pub static KKT: [KktKernels; 1] = [
            KktKernels {
                pattern: 0x5e5818ff5987afef,
                storage: 63,
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
            let mass: &[f64; 9] = mass
                .try_into()
                .map_err(|_| length_error(9, mass.len()))?;
            let phi_q: &[f64; 25] = phi_q
                .try_into()
                .map_err(|_| length_error(25, phi_q.len()))?;
            let st_len = st.len();
            let st: &mut [f64; 63] = st
                .try_into()
                .map_err(|_| length_error(63, st_len))?;
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
            st[9] = v6;
            let v7: f64 = phi_q[1] * v5;
            st[10] = v7;
            let v8: f64 = phi_q[2] * v3;
            st[11] = v8;
            let v9: f64 = phi_q[3] * v5;
            st[12] = v9;
            let v10: f64 = phi_q[4] * v1;
            st[13] = v10;
            let v11: f64 = phi_q[5] * v5;
            st[14] = v11;
            let v12: f64 = phi_q[8] * v3;
            st[15] = v12;
            let v13: f64 = phi_q[9] * v5;
            st[16] = v13;
            let v14: f64 = phi_q[24] * v5;
            st[17] = v14;
            let v15: f64 = v6 * v6;
            let v16: f64 = v7 * v7;
            let v17: f64 = v15 + v16;
            let v18: f64 = v9 * v7;
            let v19: f64 = v8 * v8;
            let v20: f64 = v9 * v9;
            let v21: f64 = v19 + v20;
            let v22: f64 = v10 * v6;
            let v23: f64 = v11 * v7;
            let v24: f64 = v22 + v23;
            let v25: f64 = v11 * v9;
            let v26: f64 = v10 * v10;
            let v27: f64 = v11 * v11;
            let v28: f64 = v26 + v27;
            let v29: f64 = v13 * v7;
            let v30: f64 = v12 * v8;
            let v31: f64 = v13 * v9;
            let v32: f64 = v30 + v31;
            let v33: f64 = v13 * v11;
            let v34: f64 = v12 * v12;
            let v35: f64 = v13 * v13;
            let v36: f64 = v34 + v35;
            let v37: f64 = v14 * v7;
            let v38: f64 = v14 * v9;
            let v39: f64 = v14 * v11;
            let v40: f64 = v14 * v13;
            let v41: f64 = v14 * v14;
            if !((c * mass[3]) > 0.0 && (c * mass[3]) <= f64::MAX) {
                return Err(mass_pivot_error((c * mass[3]), 3));
            }
            let v42: f64 = (c * mass[3]).sqrt();
            let v43: f64 = 1.0 / v42;
            st[3] = v43;
            if !((c * mass[4]) > 0.0 && (c * mass[4]) <= f64::MAX) {
                return Err(mass_pivot_error((c * mass[4]), 4));
            }
            let v44: f64 = (c * mass[4]).sqrt();
            let v45: f64 = 1.0 / v44;
            st[4] = v45;
            if !((c * mass[5]) > 0.0 && (c * mass[5]) <= f64::MAX) {
                return Err(mass_pivot_error((c * mass[5]), 5));
            }
            let v46: f64 = (c * mass[5]).sqrt();
            let v47: f64 = 1.0 / v46;
            st[5] = v47;
            let v48: f64 = phi_q[6] * v43;
            st[18] = v48;
            let v49: f64 = phi_q[7] * v47;
            st[19] = v49;
            let v50: f64 = phi_q[10] * v45;
            st[20] = v50;
            let v51: f64 = phi_q[11] * v47;
            st[21] = v51;
            let v52: f64 = phi_q[12] * v43;
            st[22] = v52;
            let v53: f64 = phi_q[13] * v47;
            st[23] = v53;
            let v54: f64 = phi_q[16] * v45;
            st[24] = v54;
            let v55: f64 = phi_q[17] * v47;
            st[25] = v55;
            let v56: f64 = v48 * v48;
            let v57: f64 = v49 * v49;
            let v58: f64 = v56 + v57;
            let v59: f64 = v28 + v58;
            let v60: f64 = v51 * v49;
            let v61: f64 = v33 + v60;
            let v62: f64 = v50 * v50;
            let v63: f64 = v51 * v51;
            let v64: f64 = v62 + v63;
            let v65: f64 = v36 + v64;
            let v66: f64 = v52 * v48;
            let v67: f64 = v53 * v49;
            let v68: f64 = v66 + v67;
            let v69: f64 = v53 * v51;
            let v70: f64 = v52 * v52;
            let v71: f64 = v53 * v53;
            let v72: f64 = v70 + v71;
            let v73: f64 = v55 * v49;
            let v74: f64 = v54 * v50;
            let v75: f64 = v55 * v51;
            let v76: f64 = v74 + v75;
            let v77: f64 = v55 * v53;
            let v78: f64 = v54 * v54;
            let v79: f64 = v55 * v55;
            let v80: f64 = v78 + v79;
            if !((c * mass[6]) > 0.0 && (c * mass[6]) <= f64::MAX) {
                return Err(mass_pivot_error((c * mass[6]), 6));
            }
            let v81: f64 = (c * mass[6]).sqrt();
            let v82: f64 = 1.0 / v81;
            st[6] = v82;
            if !((c * mass[7]) > 0.0 && (c * mass[7]) <= f64::MAX) {
                return Err(mass_pivot_error((c * mass[7]), 7));
            }
            let v83: f64 = (c * mass[7]).sqrt();
            let v84: f64 = 1.0 / v83;
            st[7] = v84;
            if !((c * mass[8]) > 0.0 && (c * mass[8]) <= f64::MAX) {
                return Err(mass_pivot_error((c * mass[8]), 8));
            }
            let v85: f64 = (c * mass[8]).sqrt();
            let v86: f64 = 1.0 / v85;
            st[8] = v86;
            let v87: f64 = phi_q[14] * v82;
            st[26] = v87;
            let v88: f64 = phi_q[15] * v86;
            st[27] = v88;
            let v89: f64 = phi_q[18] * v84;
            st[28] = v89;
            let v90: f64 = phi_q[19] * v86;
            st[29] = v90;
            let v91: f64 = phi_q[20] * v82;
            st[30] = v91;
            let v92: f64 = phi_q[21] * v86;
            st[31] = v92;
            let v93: f64 = phi_q[22] * v84;
            st[32] = v93;
            let v94: f64 = phi_q[23] * v86;
            st[33] = v94;
            let v95: f64 = v87 * v87;
            let v96: f64 = v88 * v88;
            let v97: f64 = v95 + v96;
            let v98: f64 = v72 + v97;
            let v99: f64 = v90 * v88;
            let v100: f64 = v77 + v99;
            let v101: f64 = v89 * v89;
            let v102: f64 = v90 * v90;
            let v103: f64 = v101 + v102;
            let v104: f64 = v80 + v103;
            let v105: f64 = v91 * v87;
            let v106: f64 = v92 * v88;
            let v107: f64 = v105 + v106;
            let v108: f64 = v92 * v90;
            let v109: f64 = v91 * v91;
            let v110: f64 = v92 * v92;
            let v111: f64 = v109 + v110;
            let v112: f64 = v94 * v88;
            let v113: f64 = v93 * v89;
            let v114: f64 = v94 * v90;
            let v115: f64 = v113 + v114;
            let v116: f64 = v94 * v92;
            let v117: f64 = v93 * v93;
            let v118: f64 = v94 * v94;
            let v119: f64 = v117 + v118;
            let (v120, v121) = piv.pivot(v111, v111, 6, false)?;
            st[54] = v120;
            let v122: f64 = v116 * v120;
            st[34] = v122;
            let v123: f64 = v119 - v122 * v121 * v122;
            let v124: f64 = v107 * v120;
            st[35] = v124;
            let v125: f64 = v98 - v124 * v121 * v124;
            let v126: f64 = v108 * v120;
            st[36] = v126;
            let v127: f64 = v104 - v126 * v121 * v126;
            let v128: f64 = v112 - v124 * v121 * v122;
            let v129: f64 = v115 - v126 * v121 * v122;
            let v130: f64 = v100 - v126 * v121 * v124;
            let (v131, v132) = piv.pivot(v123, v119, 7, false)?;
            st[55] = v131;
            let v133: f64 = v128 * v131;
            st[37] = v133;
            let v134: f64 = v125 - v133 * v132 * v133;
            let v135: f64 = v129 * v131;
            st[38] = v135;
            let v136: f64 = v127 - v135 * v132 * v135;
            let v137: f64 = v130 - v135 * v132 * v133;
            let (v138, v139) = piv.pivot(v134, v98, 4, false)?;
            st[56] = v138;
            let v140: f64 = v137 * v138;
            st[39] = v140;
            let v141: f64 = v136 - v140 * v139 * v140;
            let v142: f64 = v68 * v138;
            st[40] = v142;
            let v143: f64 = v59 - v142 * v139 * v142;
            let v144: f64 = v69 * v138;
            st[41] = v144;
            let v145: f64 = v65 - v144 * v139 * v144;
            let v146: f64 = v73 - v142 * v139 * v140;
            let v147: f64 = v76 - v144 * v139 * v140;
            let v148: f64 = v61 - v144 * v139 * v142;
            let (v149, v150) = piv.pivot(v141, v104, 5, false)?;
            st[57] = v149;
            let v151: f64 = v146 * v149;
            st[42] = v151;
            let v152: f64 = v143 - v151 * v150 * v151;
            let v153: f64 = v147 * v149;
            st[43] = v153;
            let v154: f64 = v145 - v153 * v150 * v153;
            let v155: f64 = v148 - v153 * v150 * v151;
            let (v156, v157) = piv.pivot(v17, v17, 0, false)?;
            st[58] = v156;
            let v158: f64 = v18 * v156;
            st[44] = v158;
            let v159: f64 = v21 - v158 * v157 * v158;
            let v160: f64 = v24 * v156;
            st[45] = v160;
            let v161: f64 = v152 - v160 * v157 * v160;
            let v162: f64 = v29 * v156;
            st[46] = v162;
            let v163: f64 = v154 - v162 * v157 * v162;
            let v164: f64 = v37 * v156;
            st[47] = v164;
            let v165: f64 = v41 - v164 * v157 * v164;
            let v166: f64 = v25 - v160 * v157 * v158;
            let v167: f64 = v32 - v162 * v157 * v158;
            let v168: f64 = v155 - v162 * v157 * v160;
            let v169: f64 = v38 - v164 * v157 * v158;
            let v170: f64 = v39 - v164 * v157 * v160;
            let v171: f64 = v40 - v164 * v157 * v162;
            let (v172, v173) = piv.pivot(v159, v21, 1, false)?;
            st[59] = v172;
            let v174: f64 = v166 * v172;
            st[48] = v174;
            let v175: f64 = v161 - v174 * v173 * v174;
            let v176: f64 = v167 * v172;
            st[49] = v176;
            let v177: f64 = v163 - v176 * v173 * v176;
            let v178: f64 = v169 * v172;
            st[50] = v178;
            let v179: f64 = v165 - v178 * v173 * v178;
            let v180: f64 = v168 - v176 * v173 * v174;
            let v181: f64 = v170 - v178 * v173 * v174;
            let v182: f64 = v171 - v178 * v173 * v176;
            let (v183, v184) = piv.pivot(v175, v59, 2, false)?;
            st[60] = v183;
            let v185: f64 = v180 * v183;
            st[51] = v185;
            let v186: f64 = v177 - v185 * v184 * v185;
            let v187: f64 = v181 * v183;
            st[52] = v187;
            let v188: f64 = v179 - v187 * v184 * v187;
            let v189: f64 = v182 - v187 * v184 * v185;
            let (v190, v191) = piv.pivot(v186, v65, 3, false)?;
            st[61] = v190;
            let v192: f64 = v189 * v190;
            st[53] = v192;
            let v193: f64 = v188 - v192 * v191 * v192;
            let (v194, v195) = piv.pivot(v193, v41, 8, false)?;
            st[62] = v194;
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
            let f: &[f64; 9] = f.try_into().map_err(|_| length_error(9, f.len()))?;
            let g: &[f64; 9] = g.try_into().map_err(|_| length_error(9, g.len()))?;
            let x_len = x.len();
            let x: &mut [f64; 9] = x.try_into().map_err(|_| length_error(9, x_len))?;
            let y_len = y.len();
            let y: &mut [f64; 9] = y.try_into().map_err(|_| length_error(9, y_len))?;
            let st: &[f64; 63] = st.try_into().map_err(|_| length_error(63, st.len()))?;
            x.fill(0.0);
            y[0] = -g[0];
            y[1] = -g[1];
            y[2] = -g[2];
            y[3] = -g[3];
            y[4] = -g[4];
            y[5] = -g[5];
            y[6] = -g[6];
            y[7] = -g[7];
            y[8] = -g[8];
            if f.iter().any(|&v| v != 0.0) {
                let v0: f64 = f[0];
                let v1: f64 = f[1];
                let v2: f64 = f[2];
                let v3: f64 = v0 * st[0];
                let v4: f64 = v1 * st[1];
                let v5: f64 = v2 * st[2];
                let v6: f64 = st[9] * v3;
                let v7: f64 = st[10] * v5;
                let v8: f64 = v6 + v7;
                y[0] += v8;
                let v9: f64 = st[11] * v4;
                let v10: f64 = st[12] * v5;
                let v11: f64 = v9 + v10;
                y[1] += v11;
                let v12: f64 = st[13] * v3;
                let v13: f64 = st[14] * v5;
                let v14: f64 = v12 + v13;
                y[2] += v14;
                let v15: f64 = st[15] * v4;
                let v16: f64 = st[16] * v5;
                let v17: f64 = v15 + v16;
                y[3] += v17;
                let v18: f64 = st[17] * v5;
                y[8] += v18;
                x[0] = v3;
                x[1] = v4;
                x[2] = v5;
                let v19: f64 = f[3];
                let v20: f64 = f[4];
                let v21: f64 = f[5];
                let v22: f64 = v19 * st[3];
                let v23: f64 = v20 * st[4];
                let v24: f64 = v21 * st[5];
                let v25: f64 = st[18] * v22;
                let v26: f64 = st[19] * v24;
                let v27: f64 = v25 + v26;
                y[2] += v27;
                let v28: f64 = st[20] * v23;
                let v29: f64 = st[21] * v24;
                let v30: f64 = v28 + v29;
                y[3] += v30;
                let v31: f64 = st[22] * v22;
                let v32: f64 = st[23] * v24;
                let v33: f64 = v31 + v32;
                y[4] += v33;
                let v34: f64 = st[24] * v23;
                let v35: f64 = st[25] * v24;
                let v36: f64 = v34 + v35;
                y[5] += v36;
                x[3] = v22;
                x[4] = v23;
                x[5] = v24;
                let v37: f64 = f[6];
                let v38: f64 = f[7];
                let v39: f64 = f[8];
                let v40: f64 = v37 * st[6];
                let v41: f64 = v38 * st[7];
                let v42: f64 = v39 * st[8];
                let v43: f64 = st[26] * v40;
                let v44: f64 = st[27] * v42;
                let v45: f64 = v43 + v44;
                y[4] += v45;
                let v46: f64 = st[28] * v41;
                let v47: f64 = st[29] * v42;
                let v48: f64 = v46 + v47;
                y[5] += v48;
                let v49: f64 = st[30] * v40;
                let v50: f64 = st[31] * v42;
                let v51: f64 = v49 + v50;
                y[6] += v51;
                let v52: f64 = st[32] * v41;
                let v53: f64 = st[33] * v42;
                let v54: f64 = v52 + v53;
                y[7] += v54;
                x[6] = v40;
                x[7] = v41;
                x[8] = v42;
            }
            let v55: f64 = y[7] - st[34] * y[6];
            let v56: f64 = y[4] - st[35] * y[6];
            let v57: f64 = y[5] - st[36] * y[6];
            let v58: f64 = v56 - st[37] * v55;
            let v59: f64 = v57 - st[38] * v55;
            let v60: f64 = v59 - st[39] * v58;
            let v61: f64 = y[2] - st[40] * v58;
            let v62: f64 = y[3] - st[41] * v58;
            let v63: f64 = v61 - st[42] * v60;
            let v64: f64 = v62 - st[43] * v60;
            let v65: f64 = y[1] - st[44] * y[0];
            let v66: f64 = v63 - st[45] * y[0];
            let v67: f64 = v64 - st[46] * y[0];
            let v68: f64 = y[8] - st[47] * y[0];
            let v69: f64 = v66 - st[48] * v65;
            let v70: f64 = v67 - st[49] * v65;
            let v71: f64 = v68 - st[50] * v65;
            let v72: f64 = v70 - st[51] * v69;
            let v73: f64 = v71 - st[52] * v69;
            let v74: f64 = v73 - st[53] * v72;
            let v75: f64 = y[6] * st[54];
            let v76: f64 = v55 * st[55];
            let v77: f64 = v58 * st[56];
            let v78: f64 = v60 * st[57];
            let v79: f64 = y[0] * st[58];
            let v80: f64 = v65 * st[59];
            let v81: f64 = v69 * st[60];
            let v82: f64 = v72 * st[61];
            let v83: f64 = v74 * st[62];
            let v84: f64 = v82 - st[53] * v83;
            let v85: f64 = v81 - st[51] * v84;
            let v86: f64 = v85 - st[52] * v83;
            let v87: f64 = v80 - st[48] * v86;
            let v88: f64 = v87 - st[49] * v84;
            let v89: f64 = v88 - st[50] * v83;
            let v90: f64 = v79 - st[44] * v89;
            let v91: f64 = v90 - st[45] * v86;
            let v92: f64 = v91 - st[46] * v84;
            let v93: f64 = v92 - st[47] * v83;
            let v94: f64 = v78 - st[42] * v86;
            let v95: f64 = v94 - st[43] * v84;
            let v96: f64 = v77 - st[39] * v95;
            let v97: f64 = v96 - st[40] * v86;
            let v98: f64 = v97 - st[41] * v84;
            let v99: f64 = v76 - st[37] * v98;
            let v100: f64 = v99 - st[38] * v95;
            let v101: f64 = v75 - st[34] * v100;
            let v102: f64 = v101 - st[35] * v98;
            let v103: f64 = v102 - st[36] * v95;
            y[6] = v103;
            y[7] = v100;
            y[4] = v98;
            y[5] = v95;
            y[0] = v93;
            y[1] = v89;
            y[2] = v86;
            y[3] = v84;
            y[8] = v83;
            let v104: f64 = x[0] - st[9] * v93;
            let v105: f64 = x[2] - st[10] * v93;
            let v106: f64 = x[1] - st[11] * v89;
            let v107: f64 = v105 - st[12] * v89;
            let v108: f64 = v104 - st[13] * v86;
            let v109: f64 = v107 - st[14] * v86;
            let v110: f64 = v106 - st[15] * v84;
            let v111: f64 = v109 - st[16] * v84;
            let v112: f64 = v111 - st[17] * v83;
            let v113: f64 = v112 * st[2];
            let v114: f64 = v110 * st[1];
            let v115: f64 = v108 * st[0];
            x[0] = v115;
            x[1] = v114;
            x[2] = v113;
            let v116: f64 = x[3] - st[18] * v86;
            let v117: f64 = x[5] - st[19] * v86;
            let v118: f64 = x[4] - st[20] * v84;
            let v119: f64 = v117 - st[21] * v84;
            let v120: f64 = v116 - st[22] * v98;
            let v121: f64 = v119 - st[23] * v98;
            let v122: f64 = v118 - st[24] * v95;
            let v123: f64 = v121 - st[25] * v95;
            let v124: f64 = v123 * st[5];
            let v125: f64 = v122 * st[4];
            let v126: f64 = v120 * st[3];
            x[3] = v126;
            x[4] = v125;
            x[5] = v124;
            let v127: f64 = x[6] - st[26] * v98;
            let v128: f64 = x[8] - st[27] * v98;
            let v129: f64 = x[7] - st[28] * v95;
            let v130: f64 = v128 - st[29] * v95;
            let v131: f64 = v127 - st[30] * v103;
            let v132: f64 = v130 - st[31] * v103;
            let v133: f64 = v129 - st[32] * v100;
            let v134: f64 = v132 - st[33] * v100;
            let v135: f64 = v134 * st[8];
            let v136: f64 = v133 * st[7];
            let v137: f64 = v131 * st[6];
            x[6] = v137;
            x[7] = v136;
            x[8] = v135;
            Ok(())
        }
        fn kkt_transpose_times(
            phi_q: &[f64],
            y: &[f64],
            out: &mut [f64],
        ) -> Result<(), KktError> {
            let phi_q: &[f64; 25] = phi_q
                .try_into()
                .map_err(|_| length_error(25, phi_q.len()))?;
            let y: &[f64; 9] = y.try_into().map_err(|_| length_error(9, y.len()))?;
            let out_len = out.len();
            let out: &mut [f64; 9] = out
                .try_into()
                .map_err(|_| length_error(9, out_len))?;
            out[0] = phi_q[0] * y[0] + phi_q[4] * y[2];
            out[1] = phi_q[2] * y[1] + phi_q[8] * y[3];
            out[2] = phi_q[1] * y[0] + phi_q[3] * y[1] + phi_q[5] * y[2]
                + phi_q[9] * y[3] + phi_q[24] * y[8];
            out[3] = phi_q[6] * y[2] + phi_q[12] * y[4];
            out[4] = phi_q[10] * y[3] + phi_q[16] * y[5];
            out[5] = phi_q[7] * y[2] + phi_q[11] * y[3] + phi_q[13] * y[4]
                + phi_q[17] * y[5];
            out[6] = phi_q[14] * y[4] + phi_q[20] * y[6];
            out[7] = phi_q[18] * y[5] + phi_q[22] * y[7];
            out[8] = phi_q[15] * y[4] + phi_q[19] * y[5] + phi_q[21] * y[6]
                + phi_q[23] * y[7];
            Ok(())
        }
        #[allow(clippy::assign_op_pattern)]
        fn kkt_times_add(
            phi_q: &[f64],
            x: &[f64],
            out: &mut [f64],
        ) -> Result<(), KktError> {
            let phi_q: &[f64; 25] = phi_q
                .try_into()
                .map_err(|_| length_error(25, phi_q.len()))?;
            let x: &[f64; 9] = x.try_into().map_err(|_| length_error(9, x.len()))?;
            let out_len = out.len();
            let out: &mut [f64; 9] = out
                .try_into()
                .map_err(|_| length_error(9, out_len))?;
            out[0] = out[0] + phi_q[0] * x[0] + phi_q[1] * x[2];
            out[1] = out[1] + phi_q[2] * x[1] + phi_q[3] * x[2];
            out[2] = out[2] + phi_q[4] * x[0] + phi_q[5] * x[2] + phi_q[6] * x[3]
                + phi_q[7] * x[5];
            out[3] = out[3] + phi_q[8] * x[1] + phi_q[9] * x[2] + phi_q[10] * x[4]
                + phi_q[11] * x[5];
            out[4] = out[4] + phi_q[12] * x[3] + phi_q[13] * x[5] + phi_q[14] * x[6]
                + phi_q[15] * x[8];
            out[5] = out[5] + phi_q[16] * x[4] + phi_q[17] * x[5] + phi_q[18] * x[7]
                + phi_q[19] * x[8];
            out[6] = out[6] + phi_q[20] * x[6] + phi_q[21] * x[8];
            out[7] = out[7] + phi_q[22] * x[7] + phi_q[23] * x[8];
            out[8] = out[8] + phi_q[24] * x[2];
            Ok(())
        }
        fn kkt_mass_times(
            mass: &[f64],
            v: &[f64],
            out: &mut [f64],
        ) -> Result<(), KktError> {
            let mass: &[f64; 9] = mass
                .try_into()
                .map_err(|_| length_error(9, mass.len()))?;
            let v: &[f64; 9] = v.try_into().map_err(|_| length_error(9, v.len()))?;
            let out_len = out.len();
            let out: &mut [f64; 9] = out
                .try_into()
                .map_err(|_| length_error(9, out_len))?;
            out[0] = 0.0 + mass[0] * v[0];
            out[1] = 0.0 + mass[1] * v[1];
            out[2] = 0.0 + mass[2] * v[2];
            out[3] = 0.0 + mass[3] * v[3];
            out[4] = 0.0 + mass[4] * v[4];
            out[5] = 0.0 + mass[5] * v[5];
            out[6] = 0.0 + mass[6] * v[6];
            out[7] = 0.0 + mass[7] * v[7];
            out[8] = 0.0 + mass[8] * v[8];
            Ok(())
        }
        fn kkt_kinetic_energy(mass: &[f64], qd: &[f64]) -> Result<f64, KktError> {
            let mass: &[f64; 9] = mass
                .try_into()
                .map_err(|_| length_error(9, mass.len()))?;
            let qd: &[f64; 9] = qd.try_into().map_err(|_| length_error(9, qd.len()))?;
            let mut t = 0.0;
            t += qd[0] * mass[0] * qd[0];
            t += qd[1] * mass[1] * qd[1];
            t += qd[2] * mass[2] * qd[2];
            t += qd[3] * mass[3] * qd[3];
            t += qd[4] * mass[4] * qd[4];
            t += qd[5] * mass[5] * qd[5];
            t += qd[6] * mass[6] * qd[6];
            t += qd[7] * mass[7] * qd[7];
            t += qd[8] * mass[8] * qd[8];
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
            let (x16, x17) = symbody_runtime::trig::sin_cos(q[5]);
            let (x331, x332) = symbody_runtime::trig::sin_cos(x5);
            let (x5846, x5847) = symbody_runtime::trig::sin_cos(q[2]);
            let (x5849, x5850) = symbody_runtime::trig::sin_cos(q[8]);
            let x5856 = 0.00000000000000006123233995736766 * x5847;
            let x5857 = x5846 + x5856;
            let x5858 = 0.00000000000000006123233995736766 * x5846;
            let x5860 = x5858 - x5847;
            let x5862 = x5847 - x5858;
            let x5921 = x331 * x5857;
            let x5922 = x332 * x5860;
            let x5924 = x5921 - x5922;
            let x5928 = x331 * x5862;
            let x5929 = x332 * x5857;
            let x5931 = x5928 - x5929;
            let x6135 = x5847 * k[0];
            let x6136 = x5846 * k[0];
            let x6137 = q[0] + x6135;
            let x6138 = q[1] + x6136;
            let x6139 = -x6137;
            let x6140 = -x6138;
            let x6141 = x5847 * k[1];
            let x6142 = x5846 * k[1];
            let x6143 = q[0] + x6141;
            let x6144 = q[1] + x6142;
            let x6145 = x17 * k[2];
            let x6146 = x16 * k[2];
            let x6147 = q[3] + x6145;
            let x6148 = q[4] + x6146;
            let x6150 = x6143 - x6147;
            let x6152 = x6144 - x6148;
            let x6153 = x17 * k[3];
            let x6154 = x16 * k[4];
            let x6156 = x6153 - x6154;
            let x6157 = x16 * k[3];
            let x6158 = x17 * k[4];
            let x6159 = x6157 + x6158;
            let x6160 = q[3] + x6156;
            let x6161 = q[4] + x6159;
            let x6162 = x5850 * k[5];
            let x6163 = x5849 * k[6];
            let x6165 = x6162 - x6163;
            let x6166 = x5849 * k[5];
            let x6167 = x5850 * k[6];
            let x6168 = x6166 + x6167;
            let x6169 = q[6] + x6165;
            let x6170 = q[7] + x6168;
            let x6172 = x6160 - x6169;
            let x6174 = x6161 - x6170;
            let x6175 = x5850 * k[8];
            let x6176 = x5849 * k[9];
            let x6178 = x6175 - x6176;
            let x6179 = x5849 * k[8];
            let x6180 = x5850 * k[9];
            let x6181 = x6179 + x6180;
            let x6182 = q[6] + x6178;
            let x6183 = q[7] + x6181;
            let x6185 = k[7] - x6182;
            let x6186 = -x6183;
            let x6187 = -x6135;
            let x6188 = -x6142;
            let x6189 = -x6145;
            let x6190 = -x6159;
            let x6191 = -x6165;
            let x6192 = -x6178;
            phi[0] = x6139;
            phi_q[0] = -1.0;
            phi_q[1] = x6136;
            phi[1] = x6140;
            phi_q[2] = -1.0;
            phi_q[3] = x6187;
            phi[2] = x6150;
            phi_q[4] = 1.0;
            phi_q[5] = x6188;
            phi_q[6] = -1.0;
            phi_q[7] = x6146;
            phi[3] = x6152;
            phi_q[8] = 1.0;
            phi_q[9] = x6141;
            phi_q[10] = -1.0;
            phi_q[11] = x6189;
            phi[4] = x6172;
            phi_q[12] = 1.0;
            phi_q[13] = x6190;
            phi_q[14] = -1.0;
            phi_q[15] = x6168;
            phi[5] = x6174;
            phi_q[16] = 1.0;
            phi_q[17] = x6156;
            phi_q[18] = -1.0;
            phi_q[19] = x6191;
            phi[6] = x6185;
            phi_q[20] = -1.0;
            phi_q[21] = x6181;
            phi[7] = x6186;
            phi_q[22] = -1.0;
            phi_q[23] = x6192;
            phi[8] = x5924;
            phi_q[24] = x5931;
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
/// `four_bar` with the `exact` formulation. At run-time parameter values (`Exact::with_parameters`).
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
