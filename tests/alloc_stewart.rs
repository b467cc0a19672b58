//! The HHT hot path on the real generated model allocates nothing: a counting global
//! allocator fails the test on any allocation during 100 steps of the exact Stewart platform
//! (runtime/tests/alloc.rs does the same for the hand-written test models).

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use symbody_mechanisms::stewart_6_6::{Exact, Paper};
use symbody_runtime::{DenseKkt, HhtBuilder};

struct Counting;

static COUNTING: AtomicBool = AtomicBool::new(false);
static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if COUNTING.load(Ordering::SeqCst) {
            ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        }
        System.alloc(layout)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if COUNTING.load(Ordering::SeqCst) {
            ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        }
        System.realloc(ptr, layout, new_size)
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// Runs `f` and returns how many allocations it made. The harness runs tests on several
/// threads, so everything is counted inside one test function.
fn allocations(f: impl FnOnce()) -> usize {
    ALLOCATIONS.store(0, Ordering::SeqCst);
    COUNTING.store(true, Ordering::SeqCst);
    f();
    COUNTING.store(false, Ordering::SeqCst);
    ALLOCATIONS.load(Ordering::SeqCst)
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
