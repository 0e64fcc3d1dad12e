//! The limits of a computation ([`Budget`]), which one ran out
//! ([`Limit`]) and the answer when one did ([`Exhausted`]).

use super::{DEFAULT_MAX_BITS, DEFAULT_MAX_TERMS, DEFAULT_MEMORY_LIMIT, DEFAULT_TIME_LIMIT};
use std::fmt;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use std::time::Duration;

/// Which limit ran out.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Limit {
    /// The wall-time limit.
    Time,
    /// The memory limit (bytes in use by the process).
    Memory,
    /// A size limit on an intermediate object (terms or coefficient bits).
    Size,
    /// The cancellation flag was raised.
    Cancelled,
}

impl Limit {
    /// `time`, `memory`, `size` or `cancelled`.
    pub fn as_str(self) -> &'static str {
        match self {
            Limit::Time => "time",
            Limit::Memory => "memory",
            Limit::Size => "size",
            Limit::Cancelled => "cancelled",
        }
    }
}

impl fmt::Display for Limit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A budget ran out: which limit, and what was being computed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Exhausted {
    pub(super) limit: Limit,
    pub(super) detail: String,
}

impl Exhausted {
    /// A budget exhaustion of the given limit.
    pub fn new(limit: Limit, detail: impl Into<String>) -> Exhausted {
        Exhausted {
            limit,
            detail: detail.into(),
        }
    }

    /// Which limit ran out.
    pub fn limit(&self) -> Limit {
        self.limit
    }

    /// What was hit, in words (e.g. `time limit of 10 s`).
    pub fn detail(&self) -> &str {
        &self.detail
    }
}

impl fmt::Display for Exhausted {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "budget exhausted ({}): {}", self.limit, self.detail)
    }
}

impl std::error::Error for Exhausted {}

/// The limits of one operation.  `Budget::default()` is the CLI's default
/// ([`DEFAULT_TIME_LIMIT`], [`DEFAULT_MEMORY_LIMIT`], [`DEFAULT_MAX_TERMS`],
/// [`DEFAULT_MAX_BITS`]); [`Budget::unlimited`] has no limit at all.
///
/// How closely a limit is kept: the checks sit between arithmetic
/// operations, so a run ends at most one operation after its deadline.
/// With the parser's limits (coefficients of at most 330 000 bits) one
/// operation on the largest numbers (a rational gcd) takes up to about half
/// a second on a 2020s machine; on ordinary inputs the overshoot is below
/// a millisecond.
#[derive(Clone, Debug)]
pub struct Budget {
    pub(super) time: Option<Duration>,
    pub(super) memory: Option<usize>,
    pub(super) max_terms: Option<usize>,
    pub(super) max_bits: Option<u64>,
    pub(super) cancel: Option<Arc<AtomicBool>>,
}

impl Default for Budget {
    fn default() -> Self {
        Budget {
            time: Some(DEFAULT_TIME_LIMIT),
            memory: Some(DEFAULT_MEMORY_LIMIT),
            max_terms: Some(DEFAULT_MAX_TERMS),
            max_bits: Some(DEFAULT_MAX_BITS),
            cancel: None,
        }
    }
}

impl Budget {
    /// No limits (the checks never fail).
    pub fn unlimited() -> Budget {
        Budget {
            time: None,
            memory: None,
            max_terms: None,
            max_bits: None,
            cancel: None,
        }
    }

    /// Sets the wall-time limit (`None`: no limit).
    pub fn with_time_limit(mut self, t: Option<Duration>) -> Budget {
        self.time = t;
        self
    }

    /// Sets the memory limit in bytes (`None`: no limit).  It is enforced
    /// only where a memory probe is installed ([`set_memory_probe`](super::set_memory_probe); the
    /// CLI installs one), and applies to the whole process.
    pub fn with_memory_limit(mut self, bytes: Option<usize>) -> Budget {
        self.memory = bytes;
        self
    }

    /// Sets the size limits: most terms of an intermediate object and most
    /// bits of an intermediate coefficient (`None`: no limit).
    pub fn with_size_limits(mut self, max_terms: Option<usize>, max_bits: Option<u64>) -> Budget {
        self.max_terms = max_terms;
        self.max_bits = max_bits;
        self
    }

    /// A flag another thread may raise to cancel the operation.
    pub fn with_cancel_flag(mut self, flag: Arc<AtomicBool>) -> Budget {
        self.cancel = Some(flag);
        self
    }

    /// This budget with its time and memory limits lowered to `time` and
    /// `memory` where those are smaller (`None`: that limit stays as it
    /// is): a limit can only be tightened here, never loosened.  A memory
    /// limit also brings the size limits down to at most their defaults
    /// ([`DEFAULT_MAX_TERMS`], [`DEFAULT_MAX_BITS`]), which a budget
    /// without a memory limit may have lifted: the result is the tighter
    /// of this budget and `Budget::default()` with these limits (the
    /// per-line `time_limit` and `memory_limit` of the batch protocol).
    pub(crate) fn tightened(mut self, time: Option<Duration>, memory: Option<usize>) -> Budget {
        fn min<T: Ord>(a: Option<T>, b: Option<T>) -> Option<T> {
            match (a, b) {
                (Some(a), Some(b)) => Some(a.min(b)),
                (a, b) => a.or(b),
            }
        }
        self.time = min(self.time, time);
        if memory.is_some() {
            self.memory = min(self.memory, memory);
            self.max_terms = min(self.max_terms, Some(DEFAULT_MAX_TERMS));
            self.max_bits = min(self.max_bits, Some(DEFAULT_MAX_BITS));
        }
        self
    }

    /// The wall-time limit.
    pub fn time_limit(&self) -> Option<Duration> {
        self.time
    }

    /// The memory limit in bytes.
    pub fn memory_limit(&self) -> Option<usize> {
        self.memory
    }

    /// The size limits (terms, coefficient bits).
    pub fn size_limits(&self) -> (Option<usize>, Option<u64>) {
        (self.max_terms, self.max_bits)
    }
}
