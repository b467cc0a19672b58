//! Interpreted against compiled (decision 31): each generated function and one HHT step of
//! the Stewart platform (`stewart_6_6`, exact) and of `slider_crank`, the compiled module
//! against the instruction tape interpreted from the same file, both called through
//! `&dyn Mechanism` at the same state. Results: BENCHMARKS.md, "Interpreted and compiled".

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::{Duration, Instant};
use symbody_benchmark_mechanisms::REGISTRY;
use symbody_runtime::{Entry, HhtBuilder, KinematicOutputs, Mechanism, NewtonOutputs, Origin};

type Dyn = &'static (dyn Mechanism + Sync);

/// Time from which steps are measured, and the span they are measured over (s).
const T_STATE: f64 = 0.5;
const SPAN: f64 = 1.0;

fn both(name: &str) -> [(&'static str, Dyn); 2] {
    let entry: &Entry = REGISTRY.find(name).expect("registered");
    let Origin::Compiled { file, .. } = entry.origin else {
        panic!("{name} is compiled")
    };
    let text = std::fs::read_to_string(file).expect("the mechanism file");
    let interpreted = symbody_codegen::interpret::load(file, &text, false)
        .expect("the file loads")
        .entry;
    [
        ("compiled", entry.default_mechanism()),
        ("interpreted", interpreted.default_mechanism()),
    ]
}

fn functions(c: &mut Criterion, name: &str) {
    for (route, mech) in both(name) {
        let info = mech.info();
        let mut it = HhtBuilder::new().build(mech).expect("consistent start");
        it.advance_to(T_STATE).expect("HHT");
        let (q, qd, t) = (it.q().to_vec(), it.qd().to_vec(), it.t());
        let (n, m, nnz, mnnz) = (
            info.n_coords,
            info.n_constraints,
            info.phi_q_nnz(),
            info.mass_nnz(),
        );
        let (mut a, mut b, mut c2, mut d) =
            (vec![0.0; m], vec![0.0; nnz], vec![0.0; m], vec![0.0; m]);
        let (mut mass, mut force) = (vec![0.0; mnnz], vec![0.0; n]);
        let mut g = c.benchmark_group(format!("{name}/{route}"));
        g.bench_function("phi_q", |bch| {
            bch.iter(|| mech.phi_q(black_box(&q), t, &mut b))
        });
        g.bench_function("gamma", |bch| {
            bch.iter(|| mech.gamma(black_box(&q), &qd, t, &mut a))
        });
        g.bench_function("mass", |bch| {
            bch.iter(|| mech.mass(black_box(&q), &mut mass))
        });
        g.bench_function("force", |bch| {
            bch.iter(|| mech.force(black_box(&q), &qd, t, &mut force))
        });
        g.bench_function("eval_kinematics", |bch| {
            bch.iter(|| {
                let out = KinematicOutputs {
                    phi: &mut a,
                    phi_q: &mut b,
                    phi_t: &mut c2,
                    gamma: &mut d,
                };
                mech.eval_kinematics(black_box(&q), &qd, t, out)
            })
        });
        g.bench_function("eval_newton", |bch| {
            bch.iter(|| {
                let out = NewtonOutputs {
                    phi: &mut a,
                    phi_q: &mut b,
                    mass: &mut mass,
                    force: &mut force,
                };
                mech.eval_newton(black_box(&q), &qd, t, out)
            })
        });
        // Steps over [T_STATE, T_STATE + SPAN], the integrator rebuilt (untimed) past it.
        g.measurement_time(Duration::from_secs(4));
        g.bench_function("hht_step", |bch| {
            bch.iter_custom(|iters| {
                let mut total = Duration::ZERO;
                for _ in 0..iters {
                    if it.t() >= T_STATE + SPAN {
                        it = HhtBuilder::new().build(mech).expect("consistent start");
                        it.advance_to(T_STATE).expect("HHT");
                    }
                    let start = Instant::now();
                    black_box(it.step().expect("HHT step"));
                    total += start.elapsed();
                }
                total
            })
        });
        g.finish();
    }
}

fn interpreter(c: &mut Criterion) {
    functions(c, "stewart_6_6");
    functions(c, "slider_crank");
}

fn config() -> Criterion {
    // Small samples: the suite must finish in a few minutes on two cores.
    Criterion::default()
        .sample_size(30)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
}

criterion_group! {
    name = benches;
    config = config();
    targets = interpreter
}
criterion_main!(benches);
