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

#[test]
fn reading_a_reduced_state_in_full_terms_allocates_nothing() {
    use symbody_benchmark_mechanisms::stewart_6_6::reduced;
    use symbody_runtime::Mechanism;
    let r = &reduced::REDUCTION;
    let q = reduced::Exact.info().q0;
    let qd: Vec<f64> = (0..q.len()).map(|i| 0.01 * i as f64 - 0.2).collect();
    let mut offsets = vec![0.0; 3 * r.substitutions.len()];
    let (mut full_q, mut full_qd) = (vec![0.0; r.n_full], vec![0.0; r.n_full]);
    let n = allocations(|| {
        r.expand_state((q, &qd), 0.3, &mut offsets, (&mut full_q, &mut full_qd))
            .unwrap();
    });
    assert_eq!(n, 0, "{n} allocations");
    // What the per-vector expansion (which allocates its offsets) gives.
    let (mut each_q, mut each_qd) = (vec![0.0; r.n_full], vec![0.0; r.n_full]);
    r.expand(q, 0.3, 0, &mut each_q).unwrap();
    r.expand(&qd, 0.3, 1, &mut each_qd).unwrap();
    assert_eq!((full_q, full_qd), (each_q, each_qd));
    // Work memory of the wrong length is an error, not a panic.
    let (mut a, mut b) = (vec![0.0; r.n_full], vec![0.0; r.n_full]);
    assert!(r
        .expand_state((q, &qd), 0.3, &mut [0.0; 2], (&mut a, &mut b))
        .is_err());
}
