//! A counting global allocator, for proving that hot paths never touch the heap: install it
//! with `#[global_allocator]` in a test binary and wrap the code under test in
//! [`CountingAllocator::count`].

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Forwards to the system allocator and counts allocations while counting is on.
pub struct CountingAllocator;

thread_local! {
    // Only the thread under test counts: the test harness's own threads allocate at any
    // moment (seen once in CI as 4 stray allocations). A const-initialised Cell needs no
    // allocation or destructor, so it is safe to read inside the allocator.
    static COUNTING: Cell<bool> = const { Cell::new(false) };
}
static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

fn counting() -> bool {
    COUNTING.try_with(Cell::get).unwrap_or(false)
}

// SAFETY: every call is forwarded unchanged to `System`; only a counter is added.
unsafe impl GlobalAlloc for CountingAllocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if counting() {
            ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        }
        System.alloc(layout)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if counting() {
            ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        }
        System.realloc(ptr, layout, new_size)
    }
}

impl CountingAllocator {
    /// Runs `f` and returns how many allocations (and reallocations) it made on this
    /// thread. The total is shared, so keep the counted sections of one test binary in one
    /// test function (tests run in parallel).
    pub fn count(f: impl FnOnce()) -> usize {
        ALLOCATIONS.store(0, Ordering::SeqCst);
        COUNTING.with(|c| c.set(true));
        f();
        COUNTING.with(|c| c.set(false));
        ALLOCATIONS.load(Ordering::SeqCst)
    }
}
