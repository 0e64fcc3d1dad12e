//! Compute budgets: a wall-time limit, a memory limit, size limits on
//! intermediate objects and a cancellation flag, checked inside every loop
//! whose cost can grow with the input (Gröbner bases, RUR, isolation,
//! resultants, sweeps).
//!
//! Key idea: the budget of the running operation lives in a thread-local
//! slot set by [`run`].  The long loops call the engine's internal checks
//! (`check`, amortised: a countdown, the clock is read every
//! `CHECK_EVERY` (64) calls; `check_now` in coarse loops; `check_size` where
//! objects grow).  When a limit is hit, the check unwinds to the enclosing
//! [`run`] with an [`Exhausted`] payload (through
//! [`std::panic::resume_unwind`], which does not call the panic hook), and
//! `run` returns `Err(Exhausted)`.  No kernel function needs a `Result` for
//! this, and nothing computed under an exhausted budget escapes.  Outside
//! any `run` the checks cost one thread-local read and never fail.  A user
//! gives a budget through the options of a call
//! ([`crate::TangentOptions::with_budget`],
//! [`crate::ClassifyOptions::with_budget`], the `_with` functions); running
//! out is an answer (`undecided`, kind `budget`).
//!
//! This needs the default `panic = "unwind"`; a program built with
//! `panic = "abort"` aborts when a budget runs out.
//!
//! ```
//! use quadsect::{Budget, Ellipsoid, Limit, TangentOptions, Verdict};
//! use quadsect::tangent::Undecided;
//! use std::time::Duration;
//! let e = Ellipsoid::new(&"x^2 + 2y^2 + 3z^2 - 1".parse()?)?;
//! let s = "x^3 + y^2*z - 1".parse()?;
//! let b = Budget::unlimited().with_time_limit(Some(Duration::ZERO));
//! let r = quadsect::decide_with(&e, &s, &TangentOptions::with_budget(b))?;
//! assert_eq!(r.verdict(), Verdict::Undecided);
//! assert!(matches!(r.undecided(), Some(Undecided::Budget(x)) if x.limit() == Limit::Time));
//! # Ok::<(), quadsect::Error>(())
//! ```

use std::cell::{Cell, RefCell};
use std::panic::{AssertUnwindSafe, catch_unwind, resume_unwind};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, OnceLock};
use std::time::{Duration, Instant};

/// How many calls of `check` share one reading of the clock.
pub(crate) const CHECK_EVERY: u32 = 64;

/// Default wall-time limit of one CLI operation (or one batch line).
pub const DEFAULT_TIME_LIMIT: Duration = Duration::from_secs(10);
/// Default memory limit of one CLI operation (or one batch line), in bytes:
/// the growth of the memory probe's count during the operation (see
/// [`set_memory_probe`]; the CLI counts per thread), and the largest
/// estimated size of one intermediate object (`check_size`).
pub const DEFAULT_MEMORY_LIMIT: usize = 1 << 30;
/// Default largest number of terms of an intermediate polynomial (or
/// entries of a Gröbner basis / matrix) checked by `check_size`.
pub const DEFAULT_MAX_TERMS: usize = 2_000_000;
/// Default largest bit size of an intermediate coefficient checked by
/// `check_size`.
pub const DEFAULT_MAX_BITS: u64 = 4_000_000;

pub(crate) mod limits;
pub(crate) use limits::{Budget, Exhausted, Limit};

/// The budget of the running operation on this thread.
struct Active {
    deadline: Option<Instant>,
    time: Option<Duration>,
    memory: Option<usize>,
    /// The memory probe's reading when the outermost `run` started: the
    /// limit applies to the growth since then.
    memory_base: usize,
    max_terms: Option<usize>,
    max_bits: Option<u64>,
    cancel: Option<Arc<AtomicBool>>,
}

thread_local! {
    static ACTIVE: RefCell<Option<Active>> = const { RefCell::new(None) };
    static COUNTDOWN: Cell<u32> = const { Cell::new(CHECK_EVERY) };
}

static MEMORY_PROBE: OnceLock<fn() -> usize> = OnceLock::new();

/// Installs a function that returns a count of bytes in use (typically
/// from a counting global allocator).  The memory limit of a [`run`] is
/// checked against the *growth* of this count since the run started, so
/// the probe may count the whole process or, better, the calling thread's
/// own allocations minus its frees (then each thread's operation has its
/// own limit, as batch lines need).  The count may wrap around: only
/// differences are used.  Only the first installation counts.
pub fn set_memory_probe(probe: fn() -> usize) {
    let _ = MEMORY_PROBE.set(probe);
}

fn memory_in_use() -> Option<usize> {
    MEMORY_PROBE.get().map(|f| f())
}

/// The growth of the probe's count from `base`, in bytes (0 when it shrank).
fn memory_growth(base: usize, now: usize) -> usize {
    let d = now.wrapping_sub(base);
    if d > usize::MAX / 2 { 0 } else { d }
}

fn exhaust(e: Exhausted) -> ! {
    resume_unwind(Box::new(e))
}

/// Runs `f` under `budget`.  Budgets nest: inside another `run`, the
/// tighter deadline and limits of the two apply.  Returns `Err` when a
/// limit ran out (everything `f` computed is dropped); other panics
/// propagate unchanged.
pub fn run<T>(budget: &Budget, f: impl FnOnce() -> T) -> Result<T, Exhausted> {
    let now = Instant::now();
    let new = ACTIVE.with(|a| {
        let outer = a.borrow();
        let min_opt = |x: Option<usize>, y: Option<usize>| match (x, y) {
            (Some(x), Some(y)) => Some(x.min(y)),
            (x, y) => x.or(y),
        };
        let own_deadline = budget.time.and_then(|t| now.checked_add(t));
        let (deadline, time) = match outer.as_ref() {
            Some(o) => match (o.deadline, own_deadline) {
                (Some(d), Some(e)) if d < e => (Some(d), o.time),
                (Some(d), None) => (Some(d), o.time),
                (_, e) => (e, budget.time),
            },
            None => (own_deadline, budget.time),
        };
        let o = outer.as_ref();
        Active {
            deadline,
            time,
            memory_base: match o {
                Some(o) => o.memory_base,
                None => memory_in_use().unwrap_or(0),
            },
            memory: min_opt(o.and_then(|o| o.memory), budget.memory),
            max_terms: min_opt(o.and_then(|o| o.max_terms), budget.max_terms),
            max_bits: match (o.and_then(|o| o.max_bits), budget.max_bits) {
                (Some(x), Some(y)) => Some(x.min(y)),
                (x, y) => x.or(y),
            },
            cancel: budget
                .cancel
                .clone()
                .or_else(|| o.and_then(|o| o.cancel.clone())),
        }
    });
    let previous = ACTIVE.with(|a| a.borrow_mut().replace(new));
    // the first check of the run reads the clock
    COUNTDOWN.with(|c| c.set(1));
    let result = catch_unwind(AssertUnwindSafe(f));
    ACTIVE.with(|a| *a.borrow_mut() = previous);
    match result {
        Ok(v) => Ok(v),
        Err(payload) => match payload.downcast::<Exhausted>() {
            Ok(e) => Err(*e),
            Err(other) => resume_unwind(other),
        },
    }
}

/// Runs an optional part of a computation (one the caller can do without,
/// e.g. a second certificate) under the running budget: `None` when it
/// would exceed a size limit, so that the main computation goes on.  The
/// other limits (time, memory, cancellation) end the whole operation as
/// usual.  Outside any [`run`], simply `Some(f())`.
pub(crate) fn run_optional<T>(f: impl FnOnce() -> T) -> Option<T> {
    if !is_active() {
        return Some(f());
    }
    match run(&Budget::unlimited(), f) {
        Ok(v) => Some(v),
        Err(e) if e.limit() == Limit::Size => None,
        Err(e) => exhaust(e),
    }
}

/// [`run_optional`] with a time cap of its own: the part is also skipped
/// (`None`) when it runs longer than `cap`, so that an optional second
/// certificate cannot spend the whole operation's time; the operation's
/// own limits (its deadline included) end it as usual.  The cap holds
/// outside any [`run`] too.
pub(crate) fn run_optional_for<T>(cap: Duration, f: impl FnOnce() -> T) -> Option<T> {
    match run(&Budget::unlimited().with_time_limit(Some(cap)), f) {
        Ok(v) => Some(v),
        Err(e) if e.limit() == Limit::Size => None,
        Err(e) if e.limit() == Limit::Time && !deadline_passed() => None,
        Err(e) => exhaust(e),
    }
}

/// True when the running operation's deadline has passed.
fn deadline_passed() -> bool {
    ACTIVE.with(|a| {
        a.borrow()
            .as_ref()
            .and_then(|a| a.deadline)
            .is_some_and(|d| Instant::now() >= d)
    })
}

/// True when an operation with a budget is running on this thread.
pub(crate) fn is_active() -> bool {
    ACTIVE.with(|a| a.borrow().is_some())
}

/// Checks the clock, the cancellation flag and the memory probe every
/// [`CHECK_EVERY`] calls.  Put it in inner loops; unwinds to [`run`] when
/// a limit ran out.
#[inline]
pub(crate) fn check() {
    let n = COUNTDOWN.with(|c| {
        let n = c.get().saturating_sub(1);
        c.set(n);
        n
    });
    if n == 0 {
        COUNTDOWN.with(|c| c.set(CHECK_EVERY));
        check_now();
    }
}

/// Numbers of more bits than this make one arithmetic operation expensive
/// enough (a gcd of two such numbers takes milliseconds) that
/// [`check_for`] reads the clock at once instead of amortising.
pub(crate) const LARGE_BITS: u64 = 1 << 14;

/// [`check`] next to an operation on numbers of `bits` bits (or a step of
/// about that much work: bits times the number of operations of a matrix
/// row): amortised for small work, [`check_now`] beyond [`LARGE_BITS`]
/// (where the step itself costs far more than reading the clock).  The
/// amortised count alone would let 64 slow steps pass between two
/// readings of the clock.
#[inline]
pub(crate) fn check_for(bits: u64) {
    if bits > LARGE_BITS {
        check_now();
    } else {
        check();
    }
}

/// Checks the clock, the cancellation flag and the memory probe now (for
/// coarse loops whose iterations may take long).
pub(crate) fn check_now() {
    let hit = ACTIVE.with(|a| {
        let a = a.borrow();
        let a = a.as_ref()?;
        if let Some(flag) = &a.cancel
            && flag.load(Ordering::Relaxed)
        {
            return Some(Exhausted::new(
                Limit::Cancelled,
                "the operation was cancelled",
            ));
        }
        if let Some(d) = a.deadline
            && Instant::now() >= d
        {
            let t = a.time.unwrap_or_default();
            return Some(Exhausted::new(
                Limit::Time,
                format!("time limit of {} s", fmt_secs(t)),
            ));
        }
        if let Some(limit) = a.memory
            && let Some(now) = memory_in_use()
            && memory_growth(a.memory_base, now) > limit
        {
            return Some(Exhausted::new(
                Limit::Memory,
                format!("memory limit of {}", fmt_mib(limit)),
            ));
        }
        None
    });
    if let Some(e) = hit {
        exhaust(e);
    }
}

/// The storage of one term (or matrix entry) besides its coefficient's
/// digits, in the memory estimate of [`check_size`]: an exponent vector or
/// index and the big integers' headers.
const TERM_BYTES: u128 = 48;

/// Checks the size of an intermediate object that is about to be built or
/// has just grown: `terms` (terms of a polynomial, entries of a matrix or
/// basis) and `bits` (the largest coefficient's bit size).  `what` names
/// the object for the message.  Besides the term and bit limits, an object
/// whose estimated storage (`terms · (bits / 8 + 48)` bytes) alone exceeds
/// the memory limit is refused (this needs no memory probe).  Also performs
/// [`check`].
///
/// The estimates passed here are upper bounds computed from the operands
/// (a product of polynomials with `a` and `b` terms has at most `a · b`
/// terms), so an object is refused before the memory is spent.
pub(crate) fn check_size(what: &str, terms: usize, bits: u64) {
    let hit = ACTIVE.with(|a| {
        let a = a.borrow();
        let a = a.as_ref()?;
        if let Some(limit) = a.memory {
            let bytes = (terms as u128) * (bits as u128 / 8 + TERM_BYTES);
            if bytes > limit as u128 {
                return Some(Exhausted::new(
                    Limit::Size,
                    format!(
                        "{what} would need about {} ({terms} terms of up to {bits} bits); the memory limit is {}",
                        fmt_mib(bytes.min(usize::MAX as u128) as usize),
                        fmt_mib(limit)
                    ),
                ));
            }
        }
        if let Some(m) = a.max_terms
            && terms > m
        {
            return Some(Exhausted::new(
                Limit::Size,
                format!("{what} would have {terms} terms; the limit is {m}"),
            ));
        }
        if let Some(m) = a.max_bits
            && bits > m
        {
            return Some(Exhausted::new(
                Limit::Size,
                format!("{what} would have {bits}-bit coefficients; the limit is {m} bits"),
            ));
        }
        None
    });
    if let Some(e) = hit {
        exhaust(e);
    }
    check_for(bits);
}

fn fmt_secs(t: Duration) -> String {
    let s = t.as_secs_f64();
    if s == s.trunc() {
        format!("{}", s as u64)
    } else {
        format!("{s}")
    }
}

/// A number of bytes in MiB: whole MiB as an integer (`1024 MiB`), a
/// fraction to three decimals (`0.5 MiB`, as `--memory-limit 0.5` or a
/// batch line's `memory_limit` may give), or bytes below that.
fn fmt_mib(bytes: usize) -> String {
    if bytes.is_multiple_of(1 << 20) {
        return format!("{} MiB", bytes >> 20);
    }
    let mib = format!("{:.3}", bytes as f64 / 1048576.0);
    let mib = mib.trim_end_matches('0').trim_end_matches('.');
    if mib == "0" {
        format!("{bytes} bytes")
    } else {
        format!("{mib} MiB")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn memory_sizes_print_in_mib() {
        assert_eq!(fmt_mib(1 << 30), "1024 MiB");
        assert_eq!(fmt_mib(0), "0 MiB");
        assert_eq!(fmt_mib(512 << 10), "0.5 MiB");
        assert_eq!(fmt_mib(1048), "0.001 MiB");
        assert_eq!(fmt_mib((3 << 20) + 1), "3 MiB");
        assert_eq!(fmt_mib(100), "100 bytes");
    }

    #[test]
    fn tightened_only_lowers_limits() {
        let s = Duration::from_secs;
        let b = Budget::default().tightened(Some(s(2)), None);
        assert_eq!(b.time_limit(), Some(s(2)));
        assert_eq!(b.memory_limit(), Some(DEFAULT_MEMORY_LIMIT));
        // never loosened
        let b = b.tightened(Some(s(60)), Some(usize::MAX));
        assert_eq!(b.time_limit(), Some(s(2)));
        assert_eq!(b.memory_limit(), Some(DEFAULT_MEMORY_LIMIT));
        let b = Budget::default().tightened(None, Some(64 << 20));
        assert_eq!(b.time_limit(), Some(DEFAULT_TIME_LIMIT));
        assert_eq!(b.memory_limit(), Some(64 << 20));
        // no limits: each given one applies; a memory limit brings the
        // default size limits back, as `--memory-limit MiB` has them
        let none = Budget::unlimited();
        let b = none.clone().tightened(Some(Duration::ZERO), None);
        assert_eq!(b.time_limit(), Some(Duration::ZERO));
        assert_eq!(b.size_limits(), (None, None));
        let b = none.tightened(None, Some(1 << 20));
        assert_eq!((b.time_limit(), b.memory_limit()), (None, Some(1 << 20)));
        assert_eq!(
            b.size_limits(),
            (Some(DEFAULT_MAX_TERMS), Some(DEFAULT_MAX_BITS))
        );
        let small = Budget::default().with_size_limits(Some(10), Some(20));
        let b = small.tightened(None, Some(1 << 20));
        assert_eq!(b.size_limits(), (Some(10), Some(20)));
    }

    #[test]
    fn unlimited_and_outside_never_fail() {
        for _ in 0..1000 {
            check();
        }
        check_size("x", usize::MAX, u64::MAX);
        let r = run(&Budget::unlimited(), || {
            check_size("x", usize::MAX, u64::MAX);
            7
        });
        assert_eq!(r, Ok(7));
        assert!(!is_active());
    }

    #[test]
    fn time_limit_unwinds_to_run() {
        let b = Budget::unlimited().with_time_limit(Some(Duration::from_millis(5)));
        let t0 = Instant::now();
        let r: Result<(), _> = run(&b, || {
            loop {
                check();
            }
        });
        assert_eq!(r.unwrap_err().limit(), Limit::Time);
        assert!(t0.elapsed() < Duration::from_secs(2));
        assert!(!is_active(), "the slot is restored");
    }

    #[test]
    fn size_limit_names_the_object() {
        let b = Budget::unlimited().with_size_limits(Some(10), Some(64));
        let e = run(&b, || check_size("a Gröbner basis", 11, 0)).unwrap_err();
        assert_eq!(e.limit(), Limit::Size);
        assert!(e.detail().contains("a Gröbner basis"), "{e}");
        let e = run(&b, || check_size("a resultant", 1, 65)).unwrap_err();
        assert!(e.detail().contains("65-bit"), "{e}");
        assert_eq!(run(&b, || check_size("ok", 10, 64)), Ok(()));
    }

    #[test]
    fn nested_budgets_take_the_tighter_limit() {
        let outer = Budget::unlimited().with_size_limits(Some(5), None);
        let inner = Budget::unlimited().with_size_limits(Some(100), None);
        let r = run(&outer, || run(&inner, || check_size("p", 6, 0)));
        // the inner run catches the exhaustion of the combined budget
        assert_eq!(r.unwrap().unwrap_err().limit(), Limit::Size);
    }

    #[test]
    fn cancel_flag() {
        let flag = Arc::new(AtomicBool::new(true));
        let b = Budget::unlimited().with_cancel_flag(flag);
        assert_eq!(run(&b, check_now).unwrap_err().limit(), Limit::Cancelled);
    }

    #[test]
    fn a_run_checks_at_its_first_check() {
        // whatever the countdown was left at by earlier work on this thread
        for _ in 0..10 {
            check();
        }
        let zero = Budget::unlimited().with_time_limit(Some(Duration::ZERO));
        assert_eq!(run(&zero, check).unwrap_err().limit(), Limit::Time);
    }

    #[test]
    fn large_steps_read_the_clock_at_once() {
        let b = Budget::unlimited().with_time_limit(Some(Duration::from_millis(20)));
        let r = run(&b, || {
            check(); // the run's first check reads the clock, in time
            std::thread::sleep(Duration::from_millis(40));
            // small work is amortised: no reading of the clock yet
            for _ in 0..(CHECK_EVERY - 2) {
                check_for(10);
            }
            "amortised"
        });
        assert_eq!(r, Ok("amortised"));
        let r = run(&b, || {
            check();
            std::thread::sleep(Duration::from_millis(40));
            check_for(LARGE_BITS + 1);
            "not reached"
        });
        assert_eq!(r.unwrap_err().limit(), Limit::Time);
    }

    #[test]
    fn objects_larger_than_the_memory_limit_are_refused_before_they_exist() {
        let b = Budget::unlimited().with_memory_limit(Some(1 << 20));
        // 10⁶ terms of 64 bits: far more than 1 MiB, whatever the probe says
        let e = run(&b, || check_size("a matrix", 1_000_000, 64)).unwrap_err();
        assert_eq!(e.limit(), Limit::Size);
        assert!(e.detail().contains("memory limit is 1 MiB"), "{e}");
        assert_eq!(run(&b, || check_size("a matrix", 1000, 64)), Ok(()));
    }

    #[test]
    fn optional_parts_give_way_to_size_but_not_to_time() {
        let sized = Budget::unlimited().with_size_limits(Some(10), None);
        let r = run(&sized, || {
            let skipped = run_optional(|| check_size("an extra", 11, 0));
            (skipped, run_optional(|| 5))
        });
        assert_eq!(r, Ok((None, Some(5))));
        let timed = Budget::unlimited().with_time_limit(Some(Duration::ZERO));
        let r = run(&timed, || run_optional(check_now));
        assert_eq!(r.unwrap_err().limit(), Limit::Time);
        // outside a budget the part simply runs
        assert_eq!(run_optional(|| 3), Some(3));
    }

    #[test]
    fn memory_growth_counts_from_the_start_of_the_run() {
        assert_eq!(memory_growth(100, 150), 50);
        assert_eq!(memory_growth(150, 100), 0, "freed memory is no growth");
        assert_eq!(memory_growth(usize::MAX - 9, 10), 20, "the count may wrap");
    }

    #[test]
    fn other_panics_propagate() {
        let r = std::panic::catch_unwind(|| run(&Budget::unlimited(), || panic!("boom")));
        assert!(r.is_err());
        assert!(!is_active());
    }
}
