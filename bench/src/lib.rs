//! symbody's benchmarks: the IFToMM multibody benchmark problems A01–A05 ([`iftomm`], run by
//! `mbs_benchmarks`), and the binaries in `src/bin/` (work-precision, step profile, long
//! runs); criterion micro-benchmarks in `micro/` (their own package); harnesses for peers in `peers/`. The
//! benchmark problems' mechanisms are compiled only here and in the tests.

pub mod iftomm;

/// Every mechanism the benchmarks run: the shipped ones and the benchmark problems.
pub use symbody_benchmark_mechanisms::REGISTRY;
