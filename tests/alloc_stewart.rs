//! The HHT hot path on the real generated model allocates nothing: a counting global
//! allocator fails the test on any allocation during 100 steps of the exact Stewart platform
//! (runtime/tests/alloc.rs does the same for the hand-written test models).

use symbody_testkit::alloc::CountingAllocator;

use symbody_benchmark_mechanisms::stewart_6_6::{Exact, Paper};
use symbody_runtime::{DenseKkt, HhtBuilder};

#[global_allocator]
static GLOBAL: CountingAllocator = CountingAllocator;

fn allocations(f: impl FnOnce()) -> usize {
    CountingAllocator::count(f)
}

#[test]
fn hundred_hht_steps_of_the_stewart_platform_allocate_nothing() {
    // The counter itself works.
    assert!(allocations(|| drop(std::hint::black_box(vec![1u8; 10]))) > 0);

    let mut exact = HhtBuilder::new().build(Exact).unwrap();
    let mut paper = HhtBuilder::new().step(2e-3).build(Paper).unwrap();
    let info = exact.info();
    let act1 = info.joint_index("act1").unwrap();
    let (upper1, platform) = (
        info.joint_index("upper_sph1").unwrap(),
        info.body_index("platform").unwrap(),
    );
    let mut dense = HhtBuilder::new()
        .build_with_solver::<_, DenseKkt>(Exact)
        .unwrap();
    let n = allocations(|| {
        for _ in 0..100 {
            exact.step().unwrap();
            paper.step().unwrap();
        }
        for _ in 0..10 {
            dense.step().unwrap();
        }
        // Landing on an output time (shortened steps) and the outputs the scenario records.
        exact.advance_to(0.1234).unwrap();
        let _ = exact.joint_force(upper1, platform).unwrap();
        let _ = exact.actuator_force(act1).unwrap();
        let _ = exact.energy();
    });
    assert_eq!(
        n, 0,
        "HHT steps on the Stewart platform allocated {n} times"
    );
    assert_eq!(exact.stats().steps, 124, "{:?}", exact.stats());
    assert_eq!(exact.stats().rejected_steps, 0, "{:?}", exact.stats());
}

#[test]
fn the_kinematic_path_allocates_nothing_per_output() {
    let mut path = symbody_runtime::KinematicPath::<_>::new(Exact, 0.0).unwrap();
    // The first output sets up the predictor's history; every later one must be free.
    path.advance_to(0.01).unwrap();
    let n = allocations(|| {
        for k in 2..=100 {
            path.advance_to(k as f64 * 0.01).unwrap();
        }
    });
    assert_eq!(n, 0, "{n} allocations in 99 outputs");
}
