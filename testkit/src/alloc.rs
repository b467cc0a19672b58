//! A counting global allocator, for proving that hot paths never touch the heap: install it
//! with `#[global_allocator]` in a test binary and wrap the code under test in
//! [`CountingAllocator::count`].

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// Forwards to the system allocator and counts allocations while counting is on.
pub struct CountingAllocator;

thread_local! {
    // Both the switch and the count belong to the thread under test: the harness's own
    // threads allocate at any moment (seen once in CI as 4 stray allocations), and counted
    // sections of tests running in parallel on other threads must not reset or add to this
    // thread's count (a shared total made `the_kinematic_path_allocates_nothing_per_output`
    // fail once on a loaded machine). Const-initialised Cells need no allocation or
    // destructor, so they are safe to touch inside the allocator.
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn record() {
    if COUNTING.try_with(Cell::get).unwrap_or(false) {
        let _ = ALLOCATIONS.try_with(|n| n.set(n.get() + 1));
    }
}

// SAFETY: every call is forwarded unchanged to `System`; only a counter is added.
unsafe impl GlobalAlloc for CountingAllocator {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        record();
        System.alloc(layout)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        record();
        System.realloc(ptr, layout, new_size)
    }
}

impl CountingAllocator {
    /// Runs `f` and returns how many allocations (and reallocations) it made on this
    /// thread; other threads, and counted sections running on them, do not touch the count.
    pub fn count(f: impl FnOnce()) -> usize {
        ALLOCATIONS.with(|n| n.set(0));
        COUNTING.with(|c| c.set(true));
        f();
        COUNTING.with(|c| c.set(false));
        ALLOCATIONS.with(Cell::get)
    }
}
