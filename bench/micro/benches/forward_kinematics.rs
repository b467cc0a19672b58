//! Forward kinematics of six-leg platforms: every assembly mode (parameter homotopy over 40
//! paths from the shipped generic platform) on Dietmaier's 40-real-mode geometry and on the
//! paper's platform, and the warm
//! tracked solve a controller would run each cycle (Newton on six lengths from the previous
//! pose). Results: the "Forward kinematics" section of BENCHMARKS.md.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::Duration;
use symbody_benchmark_mechanisms::find;
use symbody_runtime::fk::{assembly_modes, Platform, Settings};

fn platform(name: &str) -> Platform<'static, dyn symbody_runtime::Mechanism + Sync> {
    Platform::new(find(name).expect("registered").default_mechanism()).expect("a platform")
}

fn all_modes(c: &mut Criterion) {
    let mut g = c.benchmark_group("fk_all_modes");
    g.sample_size(20).measurement_time(Duration::from_secs(10));
    for name in ["dietmaier_6_6", "stewart_6_6"] {
        let p = platform(name);
        let lengths = p.lengths_at(0.0);
        g.bench_function(name, |b| {
            b.iter(|| assembly_modes(black_box(p.legs()), black_box(&lengths)).unwrap())
        });
    }
    g.finish();
}

/// The paper platform's pose at t = 1 s, solved for the lengths 1 ms later: what a
/// controller reading leg sensors at 1 kHz does every cycle.
fn warm_solve(c: &mut Criterion) {
    let p = platform("stewart_6_6");
    let home = p.pose(p.q0()).unwrap();
    let legs = p.legs();
    let at_1s = legs
        .solve(&p.lengths_at(1.0), &home, Settings::default())
        .unwrap()
        .pose;
    let next = p.lengths_at(1.001);
    c.bench_function("fk_warm_solve_1ms", |b| {
        b.iter(|| {
            legs.solve(black_box(&next), black_box(&at_1s), Settings::default())
                .unwrap()
        })
    });
}

criterion_group!(benches, all_modes, warm_solve);
criterion_main!(benches);
