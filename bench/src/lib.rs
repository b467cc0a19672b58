//! symbody's benchmarks: the IFToMM multibody benchmark problems A01–A05 ([`iftomm`], run by
//! `mbs_benchmarks`), and the binaries in `src/bin/` (work-precision, step profile, long
//! runs); criterion micro-benchmarks in `micro/` (their own package); harnesses for peers in `peers/`. The
//! benchmark problems' mechanisms are compiled only here and in the tests.

pub mod iftomm;

/// Every mechanism the benchmarks run: the shipped ones and the benchmark problems.
pub use symbody_benchmark_mechanisms::REGISTRY;

use std::hint::black_box;
use std::time::Instant;
use symbody_runtime::{Mechanism, MechanismInfo, NewtonOutputs};

/// Prints `error: msg` and exits with status 2: a benchmark that cannot run says why.
pub fn fail(msg: &str) -> ! {
    eprintln!("error: {msg}");
    std::process::exit(2)
}

/// Best-of-`rounds` mean time per call (s) of `f` called `reps` times: the minimum over
/// rounds discards the rounds another process on the machine interrupted.
pub fn best_time(rounds: usize, reps: usize, mut f: impl FnMut()) -> f64 {
    (0..rounds)
        .map(|_| {
            let t = Instant::now();
            for _ in 0..reps {
                f();
            }
            t.elapsed().as_secs_f64() / reps as f64
        })
        .fold(f64::INFINITY, f64::min)
}

/// What `eval_newton` fills (Φ, Φq, M, Q), sized for one mechanism, for timing it and for
/// feeding its results to the KKT solvers.
pub struct NewtonBuffers {
    pub phi: Vec<f64>,
    pub phi_q: Vec<f64>,
    pub mass: Vec<f64>,
    pub force: Vec<f64>,
}

impl NewtonBuffers {
    pub fn new(info: &MechanismInfo) -> Self {
        NewtonBuffers {
            phi: vec![0.0; info.n_constraints],
            phi_q: vec![0.0; info.phi_q_nnz()],
            mass: vec![0.0; info.mass_nnz()],
            force: vec![0.0; info.n_coords],
        }
    }

    /// `mech.eval_newton` at `(q, q̇, t)`, its inputs hidden from the optimiser.
    pub fn eval<M: Mechanism + ?Sized>(&mut self, mech: &M, q: &[f64], qd: &[f64], t: f64) {
        mech.eval_newton(
            black_box(q),
            black_box(qd),
            black_box(t),
            NewtonOutputs {
                phi: &mut self.phi,
                phi_q: &mut self.phi_q,
                mass: &mut self.mass,
                force: &mut self.force,
            },
        );
    }
}
