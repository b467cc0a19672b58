//! Micro-benchmarks of the generated Stewart kernels against the baselines they replace:
//! Φq by central differences and by forward-mode AD (num-dual) of a hand-written Φ, γ by
//! second differences and by second-order AD, fused against separate evaluation, and the
//! two solver hot paths (one HHT step, one warm-started forward-kinematics solve).
//!
//! Every kernel runs at the same state: the consistent start advanced by HHT to t = 1 s,
//! where no coordinate or velocity is at a special value. Results: the "Micro-benchmarks" section of BENCHMARKS.md.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::{Duration, Instant};
use symbody_benchmark_mechanisms::stewart_6_6::{self as st, exact, reduced, Exact};
use symbody_runtime::{HhtBuilder, Integrator, Kinematics, Mechanism, Stats};
use symbody_testkit::reference::{PatternIndex, Stewart, M, N};

const NNZ: usize = 390;
/// Time at which every kernel is evaluated (s).
const T_STATE: f64 = 1.0;
/// Step of the central differences (the task's baseline).
const H_FD: f64 = 1e-6;
/// Step of the second difference for γ: balances the O(h²) truncation against the
/// O(ε/h²) roundoff of differencing Φ ~ 0.1.
const H_FD2: f64 = 1e-4;

/// The paper scenario's integrator, started consistently and advanced to `T_STATE`.
fn integrator_at_state() -> Integrator<Exact> {
    integrator_of(Exact)
}

/// `mech`'s integrator at the scenario's defaults, advanced to `T_STATE`.
fn integrator_of<M: Mechanism>(mech: M) -> Integrator<M> {
    let mut it = HhtBuilder::new().build(mech).expect("consistent start");
    it.advance_to(T_STATE).expect("HHT to t = 1");
    it
}

/// The (q, q̇, t) every kernel is measured at.
struct State {
    q: [f64; N],
    qd: [f64; N],
    t: f64,
}

fn state() -> State {
    let it = integrator_at_state();
    State {
        q: it.q().try_into().unwrap(),
        qd: it.qd().try_into().unwrap(),
        t: it.t(),
    }
}

/// Φq by central differences of the generated Φ: 156 evaluations.
fn phi_q_central_fd(q: &[f64; N], t: f64, index: &PatternIndex, out: &mut [f64; NNZ]) {
    let mut x = *q;
    let (mut plus, mut minus) = ([0.0; M], [0.0; M]);
    for j in 0..N {
        x[j] = q[j] + H_FD;
        st::phi(&st::K, &x, t, &mut plus);
        x[j] = q[j] - H_FD;
        st::phi(&st::K, &x, t, &mut minus);
        x[j] = q[j];
        for &(row, slot) in index.column(j) {
            let row = row as usize;
            out[slot as usize] = (plus[row] - minus[row]) / (2.0 * H_FD);
        }
    }
}

/// Φq by forward AD of the reference, one `Dual64` pass per coordinate (78 passes).
fn phi_q_dual(r: &Stewart, q: &[f64; N], t: f64, index: &PatternIndex, out: &mut [f64; NNZ]) {
    r.phi_q_columns(q, t, |j, phi| {
        for &(row, slot) in index.column(j) {
            out[slot as usize] = phi[row as usize].eps;
        }
    });
}

/// Φq by forward AD of the reference, one 6-wide vector-dual pass per body (13 passes).
fn phi_q_dual_block(r: &Stewart, q: &[f64; N], t: f64, index: &PatternIndex, out: &mut [f64; NNZ]) {
    r.phi_q_blocks(q, t, |body, phi| {
        for (row, p) in phi.iter().enumerate() {
            let eps = p.eps.unwrap_generic(nalgebra::Const::<6>, nalgebra::U1);
            for (k, &e) in eps.iter().enumerate() {
                let slot = index.get(row, 6 * body + k);
                if slot != PatternIndex::NONE {
                    out[slot as usize] = e;
                }
            }
        }
    });
}

/// γ = −d²Φ/ds² along (q̇, 1) by the three-point second difference of the generated Φ.
fn gamma_fd(q: &[f64; N], qd: &[f64; N], t: f64, out: &mut [f64; M]) {
    let h = H_FD2;
    let (mut x, mut plus, mut mid, mut minus) = (*q, [0.0; M], [0.0; M], [0.0; M]);
    for k in 0..N {
        x[k] = q[k] + h * qd[k];
    }
    st::phi(&st::K, &x, t + h, &mut plus);
    st::phi(&st::K, q, t, &mut mid);
    for k in 0..N {
        x[k] = q[k] - h * qd[k];
    }
    st::phi(&st::K, &x, t - h, &mut minus);
    for r in 0..M {
        out[r] = -(plus[r] - 2.0 * mid[r] + minus[r]) / (h * h);
    }
}

fn max_rel(a: &[f64], b: &[f64]) -> f64 {
    let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs() / y.abs().max(1e-3 * scale))
        .fold(0.0, f64::max)
}

/// How accurate each baseline is at the benchmark state, so the speed ratios are read
/// against what the slower methods deliver.
fn report_accuracy(r: &Stewart, s: &State, index: &PatternIndex) {
    let (mut gen, mut other) = ([0.0; NNZ], [0.0; NNZ]);
    st::phi_q(&st::K, &s.q, s.t, &mut gen);
    phi_q_central_fd(&s.q, s.t, index, &mut other);
    eprintln!(
        "accuracy: Φq central FD max rel err {:.1e}",
        max_rel(&other, &gen)
    );
    phi_q_dual(r, &s.q, s.t, index, &mut other);
    eprintln!(
        "accuracy: Φq num-dual   max rel err {:.1e}",
        max_rel(&other, &gen)
    );
    phi_q_dual_block(r, &s.q, s.t, index, &mut other);
    eprintln!(
        "accuracy: Φq num-dual6  max rel err {:.1e}",
        max_rel(&other, &gen)
    );
    let (mut g, mut o) = ([0.0; M], [0.0; M]);
    st::gamma(&st::K, &s.q, &s.qd, s.t, &mut g);
    gamma_fd(&s.q, &s.qd, s.t, &mut o);
    eprintln!(
        "accuracy: γ second diff max rel err {:.1e}",
        max_rel(&o, &g)
    );
    r.gamma(&s.q, &s.qd, s.t, &mut o);
    eprintln!(
        "accuracy: γ num-dual    max rel err {:.1e}",
        max_rel(&o, &g)
    );
}

fn kernels(c: &mut Criterion) {
    let s = state();
    let r = Stewart::new(&st::Q0);
    let index = PatternIndex::new(&st::PHI_Q_ROWS, &st::PHI_Q_COLS);
    report_accuracy(&r, &s, &index);
    let (q, qd, t) = (&s.q, &s.qd, s.t);

    let mut phi = [0.0; M];
    let mut g = c.benchmark_group("phi");
    g.bench_function("generated", |b| {
        b.iter(|| st::phi(&st::K, black_box(q), black_box(t), &mut phi))
    });
    g.bench_function("reference", |b| {
        b.iter(|| r.phi(black_box(q), black_box(t), &mut phi))
    });
    g.finish();

    let mut jac = [0.0; NNZ];
    let mut g = c.benchmark_group("phi_q");
    g.bench_function("generated", |b| {
        b.iter(|| st::phi_q(&st::K, black_box(q), black_box(t), &mut jac))
    });
    g.bench_function("central_fd", |b| {
        b.iter(|| phi_q_central_fd(black_box(q), black_box(t), &index, &mut jac))
    });
    g.bench_function("num_dual", |b| {
        b.iter(|| phi_q_dual(&r, black_box(q), black_box(t), &index, &mut jac))
    });
    g.bench_function("num_dual_block6", |b| {
        b.iter(|| phi_q_dual_block(&r, black_box(q), black_box(t), &index, &mut jac))
    });
    g.finish();

    let mut gam = [0.0; M];
    let mut g = c.benchmark_group("gamma");
    g.bench_function("generated", |b| {
        b.iter(|| st::gamma(&st::K, black_box(q), black_box(qd), black_box(t), &mut gam))
    });
    g.bench_function("fd", |b| {
        b.iter(|| gamma_fd(black_box(q), black_box(qd), black_box(t), &mut gam))
    });
    g.bench_function("num_dual", |b| {
        b.iter(|| r.gamma(black_box(q), black_box(qd), black_box(t), &mut gam))
    });
    g.finish();

    let (mut phi_t, mut mass, mut force) = ([0.0; M], [0.0; 130], [0.0; N]);
    assert_eq!(Exact.info().mass_nnz(), mass.len());
    // The remaining pieces of the separate calls, so the fused ratios can be explained.
    let mut g = c.benchmark_group("parts");
    g.bench_function("phi_t", |b| {
        b.iter(|| st::phi_t(&st::K, black_box(q), black_box(t), &mut phi_t))
    });
    g.bench_function("mass", |b| {
        b.iter(|| exact::mass(&st::K, black_box(q), &mut mass))
    });
    g.bench_function("force", |b| {
        b.iter(|| {
            exact::force(
                &st::K,
                black_box(q),
                black_box(qd),
                black_box(t),
                &mut force,
            )
        })
    });
    g.finish();

    let mut g = c.benchmark_group("fused");
    g.bench_function("eval_kinematics", |b| {
        b.iter(|| {
            st::eval_kinematics(
                &st::K,
                black_box(q),
                black_box(qd),
                black_box(t),
                &mut phi,
                &mut jac,
                &mut phi_t,
                &mut gam,
            )
        })
    });
    g.bench_function("kinematics_separate", |b| {
        b.iter(|| {
            let (q, qd, t) = (black_box(q), black_box(qd), black_box(t));
            st::phi(&st::K, q, t, &mut phi);
            st::phi_q(&st::K, q, t, &mut jac);
            st::phi_t(&st::K, q, t, &mut phi_t);
            st::gamma(&st::K, q, qd, t, &mut gam);
        })
    });
    g.bench_function("eval_newton", |b| {
        b.iter(|| {
            exact::eval_newton(
                &st::K,
                black_box(q),
                black_box(qd),
                black_box(t),
                &mut phi,
                &mut jac,
                &mut mass,
                &mut force,
            )
        })
    });
    g.bench_function("newton_separate", |b| {
        b.iter(|| {
            let (q, qd, t) = (black_box(q), black_box(qd), black_box(t));
            st::phi(&st::K, q, t, &mut phi);
            st::phi_q(&st::K, q, t, &mut jac);
            exact::mass(&st::K, q, &mut mass);
            exact::force(&st::K, q, qd, t, &mut force);
        })
    });
    g.finish();

    bench_hht(c, "hht", Exact);
    bench_reduced(c);
    bench_fk(c, &s);
}

/// The reduced model (`stewart_6_6::reduced`, 60 coordinates, 54 rows) at the same state.
fn bench_reduced(c: &mut Criterion) {
    let it = integrator_of(reduced::Exact);
    let (q, qd, t) = (it.q().to_vec(), it.qd().to_vec(), it.t());
    let info = reduced::Exact.info();
    let (mut phi, mut phi_t, mut gam) = (
        vec![0.0; info.n_constraints],
        vec![0.0; info.n_constraints],
        vec![0.0; info.n_constraints],
    );
    let mut jac = vec![0.0; info.phi_q_nnz()];
    let (mut mass, mut force) = (vec![0.0; info.mass_nnz()], vec![0.0; info.n_coords]);
    let mut g = c.benchmark_group("reduced");
    g.bench_function("eval_kinematics", |b| {
        b.iter(|| {
            reduced::eval_kinematics(
                &reduced::K,
                black_box(&q),
                black_box(&qd),
                black_box(t),
                &mut phi,
                &mut jac,
                &mut phi_t,
                &mut gam,
            )
        })
    });
    g.bench_function("eval_newton", |b| {
        b.iter(|| {
            reduced::exact::eval_newton(
                &reduced::K,
                black_box(&q),
                black_box(&qd),
                black_box(t),
                &mut phi,
                &mut jac,
                &mut mass,
                &mut force,
            )
        })
    });
    g.finish();
    bench_hht(c, "hht_reduced", reduced::Exact);
}

/// Steps of the integrator are timed over one period of the motion from t = 1 s; past
/// that, it is rebuilt (untimed) so every measured step lies in the validated scenario.
fn bench_hht<M: Mechanism + Copy>(c: &mut Criterion, group: &str, mech: M) {
    const T_WRAP: f64 = T_STATE + std::f64::consts::TAU;
    let mut it = integrator_of(mech);
    let mut base = it.stats();
    // Work done in measured steps only, summed over rebuilt integrators.
    let (mut steps, mut newton, mut factorizations, mut rejected) = (0, 0, 0, 0);
    let mut retire = |it: &Integrator<M>, base: &Stats| {
        let s = it.stats();
        steps += s.steps - base.steps;
        newton += s.newton_iterations - base.newton_iterations;
        factorizations += s.factorizations - base.factorizations;
        rejected += s.rejected_steps - base.rejected_steps;
    };
    let mut g = c.benchmark_group(group);
    g.measurement_time(Duration::from_secs(4));
    g.bench_function("step", |b| {
        b.iter_custom(|iters| {
            let mut total = Duration::ZERO;
            let mut left = iters;
            while left > 0 {
                if it.t() >= T_WRAP {
                    retire(&it, &base);
                    it = integrator_of(mech);
                    base = it.stats();
                }
                let room = ((T_WRAP - it.t()) / it.step_size()).ceil().max(1.0) as u64;
                let n = left.min(room);
                let start = Instant::now();
                for _ in 0..n {
                    black_box(it.step().expect("HHT step"));
                }
                total += start.elapsed();
                left -= n;
            }
            total
        })
    });
    g.finish();
    retire(&it, &base);
    eprintln!(
        "{group}/step: {steps} measured steps, {:.3} Newton iterations/step, {:.3} \
         factorizations/step, {rejected} rejected",
        newton as f64 / steps as f64,
        factorizations as f64 / steps as f64
    );
}

/// One position analysis at t + 1 ms from the converged pose at t.
fn bench_fk(c: &mut Criterion, s: &State) {
    let mut kin: Kinematics = Kinematics::new(Exact.info()).expect("kinematics");
    let t_new = s.t + 1e-3;
    let mut q = s.q;
    let report = kin
        .position(&Exact, t_new, &mut q)
        .expect("forward kinematics");
    eprintln!(
        "fk/warm: {} Newton iterations to |Φ| = {:.1e}",
        report.iterations, report.residual
    );
    let mut g = c.benchmark_group("fk");
    g.bench_function("warm", |b| {
        b.iter(|| {
            q.copy_from_slice(&s.q);
            black_box(kin.position(&Exact, black_box(t_new), &mut q).unwrap())
        })
    });
    g.finish();
}

fn config() -> Criterion {
    // Small samples: the whole suite must finish in a few minutes on two cores.
    Criterion::default()
        .sample_size(30)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
}

criterion_group! {
    name = benches;
    config = config();
    targets = kernels
}
criterion_main!(benches);
