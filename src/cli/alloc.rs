//! The binary's counting global allocator (the library sets none): the
//! system allocator plus, per thread, the bytes that thread allocated minus
//! the bytes it freed.  That count is the memory probe of the compute
//! budgets ([`crate::budget::set_memory_probe`]): a budget's memory
//! limit applies to the growth of its own thread's count, so each batch
//! line (one worker thread) has its own limit.
//!
//! Cost: one thread-local add per allocation and per free, no atomic and
//! no lock (a shared atomic counter would be contended by the batch
//! workers).  Small blocks (≤ 256 bytes) are recycled through per-thread
//! free lists (below): exact arithmetic makes and drops many small
//! integers, and that cache takes about a sixth of the batch's
//! instructions off (glibc's malloc and free were a quarter of them).  Memory freed by another thread than the one that allocated
//! it (a batch answer written by the main thread) lowers that other
//! thread's count: counts are differences, so that is harmless.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

/// The system allocator, counting, with a small per-thread cache of small
/// blocks.
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

// The cache of small blocks.  Exact arithmetic allocates and frees many
// short-lived small blocks (a `BigInt` of a few words is one heap block; a
// batch line of the natural-quadric mix makes about 1 100), and glibc's
// malloc/free cost ≈ 230 instructions a pair there (a quarter of all of
// them).  Blocks of at most `SMALL` bytes with an alignment of at most
// `GRAIN` are taken from the system in size classes (multiples of
// `GRAIN`) and, when freed, kept on a per-thread free list of their class
// (at most `CAP` blocks a class; the rest go back to the system) for the
// next allocation of that class on the thread: a push or a pop, no lock,
// no atomic.  Invariants (what makes each forwarding to `System` valid):
//
// * a small layout (`small(layout)`) is always served by a block the system
//   allocated with `class_layout` of its class, and a large one by the
//   system with the layout itself;
// * a block on a free list is free (nobody else holds it), of that class,
//   and its first word holds the next block of the list (null at the end);
// * a block freed on another thread than the one that allocated it joins
//   the freeing thread's list: blocks are interchangeable within a class;
// * blocks still cached when a thread ends stay allocated (at most
//   `CAP × (16 + 32 + … + SMALL)` bytes a thread; the binary's threads live
//   as long as its run).
//
// Cached blocks are not counted in `NET`: the memory probe counts the
// bytes the program holds, not the cache.

/// Size-class step and the alignment every cached block has.
const GRAIN: usize = 16;
/// The largest size served from the cache.
const SMALL: usize = 256;
/// Number of size classes: `GRAIN, 2·GRAIN, …, SMALL`.
const CLASSES: usize = SMALL / GRAIN;
/// Blocks kept per class and thread.
const CAP: u32 = 1024;

/// A free list of one size class.
struct Bin {
    head: Cell<*mut u8>,
    len: Cell<u32>,
}

impl Bin {
    const fn new() -> Bin {
        Bin {
            head: Cell::new(std::ptr::null_mut()),
            len: Cell::new(0),
        }
    }
}

thread_local! {
    /// This thread's free lists, one per size class.
    static BINS: [Bin; CLASSES] = const { [const { Bin::new() }; CLASSES] };
}

/// Whether the cache serves `layout` (non-zero size by the allocator's
/// contract).
#[inline]
fn small(layout: &Layout) -> bool {
    layout.size() <= SMALL && layout.align() <= GRAIN
}

/// The size class of a small layout (0 for 1..=16 bytes, …).
#[inline]
fn class(size: usize) -> usize {
    (size - 1) / GRAIN
}

/// The layout the system allocates blocks of class `c` with.
#[inline]
fn class_layout(c: usize) -> Layout {
    // SAFETY: a non-zero multiple of 16, power-of-two alignment 16.
    unsafe { Layout::from_size_align_unchecked((c + 1) * GRAIN, GRAIN) }
}

/// A cached block of class `c` (null when the list is empty).
#[inline]
fn pop(c: usize) -> *mut u8 {
    BINS.try_with(|bins| {
        let bin = &bins[c];
        let p = bin.head.get();
        if !p.is_null() {
            // SAFETY: a block on the list is free, of ≥ 16 bytes, aligned
            // to 16, and its first word is the next block.
            bin.head.set(unsafe { p.cast::<*mut u8>().read() });
            bin.len.set(bin.len.get() - 1);
        }
        p
    })
    .unwrap_or(std::ptr::null_mut())
}

/// Keeps a freed block of class `c`; `false` when the list is full (the
/// caller gives it back to the system).
#[inline]
fn push(c: usize, p: *mut u8) -> bool {
    BINS.try_with(|bins| {
        let bin = &bins[c];
        if bin.len.get() >= CAP {
            return false;
        }
        // SAFETY: `p` is a free block of class `c` (≥ 16 bytes, aligned to
        // 16) that nobody else holds: its first word becomes the link.
        unsafe { p.cast::<*mut u8>().write(bin.head.get()) };
        bin.head.set(p);
        bin.len.set(bin.len.get() + 1);
        true
    })
    .unwrap_or(false)
}

/// An allocation (`zeroed`: filled with zeros): a cached block of the
/// layout's class, else one from the system.
///
/// # Safety
/// `layout` has a non-zero size.
#[inline]
unsafe fn take(layout: Layout, zeroed: bool) -> *mut u8 {
    let p = if small(&layout) {
        let c = class(layout.size());
        let p = pop(c);
        if !p.is_null() {
            if zeroed {
                // SAFETY: a free block of at least `layout.size()` bytes.
                unsafe { p.write_bytes(0, layout.size()) };
            }
            p
        } else if zeroed {
            // SAFETY: a valid non-zero layout.
            unsafe { System.alloc_zeroed(class_layout(c)) }
        } else {
            // SAFETY: a valid non-zero layout.
            unsafe { System.alloc(class_layout(c)) }
        }
    } else if zeroed {
        // SAFETY: forwarded unchanged.
        unsafe { System.alloc_zeroed(layout) }
    } else {
        // SAFETY: forwarded unchanged.
        unsafe { System.alloc(layout) }
    };
    if !p.is_null() {
        grow(layout.size());
    }
    p
}

// SAFETY: large layouts are forwarded to `System` unchanged; small ones are
// served by blocks the system allocated with their class's layout and
// given back with that same layout (the invariants above); besides, only
// plain thread-local cells are updated.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller's contract (a valid non-zero layout).
        unsafe { take(layout, false) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller's contract (a valid non-zero layout).
        unsafe { take(layout, true) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        if small(&layout) {
            let c = class(layout.size());
            if !push(c, ptr) {
                // SAFETY: the block was allocated with its class's layout.
                unsafe { System.dealloc(ptr, class_layout(c)) };
            }
        } else {
            // SAFETY: forwarded unchanged.
            unsafe { System.dealloc(ptr, layout) };
        }
        shrink(layout.size());
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: the caller's contract: `new_size` rounded up to the
        // alignment does not overflow, so this is a valid layout.
        let new_layout = unsafe { Layout::from_size_align_unchecked(new_size, layout.align()) };
        if !small(&layout) && !small(&new_layout) {
            // SAFETY: forwarded unchanged (both sizes above the cache's).
            let p = unsafe { System.realloc(ptr, layout, new_size) };
            if !p.is_null() {
                if new_size >= layout.size() {
                    grow(new_size - layout.size());
                } else {
                    shrink(layout.size() - new_size);
                }
            }
            return p;
        }
        if small(&layout) && small(&new_layout) && class(layout.size()) == class(new_size) {
            // the same block fits
            grow(new_size);
            shrink(layout.size());
            return ptr;
        }
        // across the cache's boundary or between classes: a new block, the
        // contents copied, the old block freed (each through this allocator)
        // SAFETY: a valid non-zero layout.
        let p = unsafe { self.alloc(new_layout) };
        if !p.is_null() {
            // SAFETY: both blocks hold at least the smaller size and do not
            // overlap; the old one is freed with the layout it was given.
            unsafe {
                std::ptr::copy_nonoverlapping(ptr, p, layout.size().min(new_size));
                self.dealloc(ptr, layout);
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
    fn cached_blocks_are_reused_zeroed_and_kept_through_reallocation() {
        // a freed small block is the next one of its class on this thread
        let a = Box::new([7u64; 3]);
        let pa = &*a as *const [u64; 3] as usize;
        drop(a);
        let b = Box::new([9u64; 3]);
        assert_eq!(&*b as *const [u64; 3] as usize, pa, "the cached block");
        drop(b);
        // a recycled block asked for zeroed is zeroed
        let z = vec![0u64; std::hint::black_box(3)];
        assert!(z.iter().all(|&w| w == 0));
        // growth through every class and past the cache keeps the contents,
        // and so does shrinking back into the cache
        let mut v: Vec<u8> = Vec::new();
        for i in 0..5000u32 {
            v.push(i as u8);
            if i % 7 == 0 {
                v.shrink_to_fit();
            }
        }
        assert!(v.iter().enumerate().all(|(i, &x)| x == i as u8));
        v.truncate(40);
        v.shrink_to_fit();
        assert!(v.iter().enumerate().all(|(i, &x)| x == i as u8));
        // blocks of every size and alignment up to the cache's, freed on
        // another thread, serve this one's later allocations intact
        let blocks: Vec<Vec<u128>> = (1..=20).map(|n| vec![n as u128; n]).collect();
        std::thread::spawn(move || drop(blocks)).join().unwrap();
        let again: Vec<Vec<u128>> = (1..=20).map(|n| vec![n as u128; n]).collect();
        for (n, b) in (1..=20).zip(&again) {
            assert!(b.iter().all(|&x| x == n as u128));
            assert_eq!(b.as_ptr() as usize % 16, 0);
        }
        // more frees than a list keeps: the rest go back to the system
        let many: Vec<Box<u64>> = (0..3 * CAP as u64).map(Box::new).collect();
        assert!(many.iter().enumerate().all(|(i, b)| **b == i as u64));
        drop(many);
        let count = BINS.with(|bins| bins[class(8)].len.get());
        assert!(count <= CAP, "{count}");
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
