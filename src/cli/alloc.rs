//! The binary's counting global allocator (the library sets none): the
//! system allocator plus, per thread, the bytes that thread allocated minus
//! the bytes it freed.  That count is the memory probe of the compute
//! budgets ([`crate::budget::set_memory_probe`]): a budget's memory
//! limit applies to the growth of its own thread's count, so each batch
//! line (one worker thread) has its own limit.
//!
//! Cost: one thread-local add per allocation and per free, no atomic and
//! no lock (a shared atomic counter would be contended by the batch
//! workers).  Memory freed by another thread than the one that allocated
//! it (a batch answer written by the main thread) lowers that other
//! thread's count: counts are differences, so that is harmless.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// The system allocator, counting.
pub struct Counting;

thread_local! {
    /// Bytes allocated minus bytes freed by this thread (wrapping).
    static NET: Cell<usize> = const { Cell::new(0) };
}

#[inline]
fn grow(n: usize) {
    // a `const` thread-local without destructor: no allocation, no
    // registration, usable inside the allocator
    NET.with(|c| c.set(c.get().wrapping_add(n)));
}

#[inline]
fn shrink(n: usize) {
    NET.with(|c| c.set(c.get().wrapping_sub(n)));
}

// SAFETY: every method forwards to `System` with the same arguments and
// only updates plain thread-local counters besides.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: forwarded unchanged.
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            grow(layout.size());
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: forwarded unchanged.
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            grow(layout.size());
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: forwarded unchanged.
        unsafe { System.dealloc(ptr, layout) };
        shrink(layout.size());
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: forwarded unchanged.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            if new_size >= layout.size() {
                grow(new_size - layout.size());
            } else {
                shrink(layout.size() - new_size);
            }
        }
        p
    }
}

/// The calling thread's count: bytes allocated minus bytes freed (the
/// memory probe; wrapping, only differences mean something).
pub fn thread_net_bytes() -> usize {
    NET.with(Cell::get)
}

#[cfg(test)]
mod tests {
    use super::*;

    // The library's own test executable counts with the same allocator the
    // `quadsect` binary installs, so these tests see real numbers.
    #[global_allocator]
    static TEST_ALLOC: Counting = Counting;

    #[test]
    fn counts_allocations_and_frees_of_this_thread() {
        let before = thread_net_bytes();
        let v: Vec<u8> = Vec::with_capacity(1 << 20);
        let during = thread_net_bytes().wrapping_sub(before);
        assert!(during >= 1 << 20, "a 1 MiB allocation counts: {during}");
        drop(v);
        let after = thread_net_bytes().wrapping_sub(before) as isize;
        assert!(after < 4096, "freed memory is uncounted again: {after}");
    }

    #[test]
    fn reallocation_counts_the_difference() {
        let mut v: Vec<u64> = Vec::with_capacity(1000);
        let base = thread_net_bytes();
        v.reserve_exact(100_000);
        let grown = thread_net_bytes().wrapping_sub(base) as isize;
        assert!(grown >= 8 * 99_000, "{grown}");
        v.shrink_to(10);
        let shrunk = thread_net_bytes().wrapping_sub(base) as isize;
        assert!(shrunk < 0, "shrinking gives memory back: {shrunk}");
    }

    #[test]
    fn other_threads_do_not_count_here() {
        let before = thread_net_bytes();
        std::thread::spawn(|| {
            let v = vec![0u8; 4 << 20];
            std::hint::black_box(&v);
        })
        .join()
        .unwrap();
        let d = thread_net_bytes().wrapping_sub(before) as isize;
        assert!(
            d.abs() < 64 << 10,
            "another thread's 4 MiB is not ours: {d}"
        );
    }

    #[test]
    fn the_memory_limit_of_a_budget_uses_the_probe() {
        use crate::budget::{self, Budget, Limit};
        budget::set_memory_probe(thread_net_bytes);
        let b = Budget::unlimited().with_memory_limit(Some(8 << 20));
        let r = budget::run(&b, || {
            let mut keep = Vec::new();
            loop {
                keep.push(vec![1u8; 1 << 20]);
                budget::check_now();
            }
        });
        let e = r.unwrap_err();
        assert_eq!(e.limit(), Limit::Memory);
        // the same budget is fine for an operation that stays small
        let ok = budget::run(&b, || {
            for _ in 0..100 {
                let v = vec![1u8; 1 << 20];
                std::hint::black_box(&v);
                budget::check_now();
            }
        });
        assert!(ok.is_ok());
    }
}
