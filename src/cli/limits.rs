//! The compute-budget options of the CLI (`--time-limit`, `--memory-limit`)
//! shared by every computing subcommand.

use crate::budget::Budget;
use std::time::Duration;

/// The default `--time-limit`, in seconds (see the README: every example
/// and benchmark input answers in well under a second, so the default
/// leaves a wide margin on a slow machine and still ends a hostile input
/// quickly).
pub const DEFAULT_TIME_LIMIT: &str = "10";
/// The default `--memory-limit`, in MiB.
pub const DEFAULT_MEMORY_LIMIT_MIB: &str = "1024";

/// `--time-limit` and `--memory-limit`.
#[derive(clap::Args, Clone, Debug)]
pub struct LimitArgs {
    /// Wall-time limit of the operation (of each line in batch), in seconds
    /// (fractions allowed), or "none".
    #[arg(long, value_name = "SECONDS|none", default_value = DEFAULT_TIME_LIMIT, value_parser = parse_time)]
    pub time_limit: TimeLimit,
    /// Memory limit of the operation (of each line in batch), in MiB, or
    /// "none" (which also lifts the size limits on intermediate objects).
    #[arg(long, value_name = "MiB|none", default_value = DEFAULT_MEMORY_LIMIT_MIB, value_parser = parse_memory)]
    pub memory_limit: MemoryLimit,
}

/// A parsed `--time-limit` (`None`: no limit).
#[derive(Clone, Copy, Debug)]
pub struct TimeLimit(pub Option<Duration>);

/// A parsed `--memory-limit` in bytes (`None`: no limit).
#[derive(Clone, Copy, Debug)]
pub struct MemoryLimit(pub Option<usize>);

fn positive(s: &str, what: &str) -> Result<Option<f64>, String> {
    let t = s.trim();
    if t.eq_ignore_ascii_case("none") {
        return Ok(None);
    }
    match t.parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(Some(v)),
        _ => Err(format!(
            "expected a positive number of {what} or \"none\", got \"{s}\""
        )),
    }
}

fn parse_time(s: &str) -> Result<TimeLimit, String> {
    let v = positive(s, "seconds")?;
    Ok(TimeLimit(v.map(|v| Duration::from_secs_f64(v.min(1e9)))))
}

fn parse_memory(s: &str) -> Result<MemoryLimit, String> {
    let v = positive(s, "MiB")?;
    Ok(MemoryLimit(v.map(|v| (v.min(1e12) * 1048576.0) as usize)))
}

impl LimitArgs {
    /// The budget of one operation: the library's default size limits,
    /// these time and memory limits (`--memory-limit none` lifts the size
    /// limits too).
    pub fn budget(&self) -> Budget {
        let b = Budget::default()
            .with_time_limit(self.time_limit.0)
            .with_memory_limit(self.memory_limit.0);
        if self.memory_limit.0.is_none() {
            b.with_size_limits(None, None)
        } else {
            b
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn limits_parse() {
        assert_eq!(
            parse_time("1.5").unwrap().0,
            Some(Duration::from_millis(1500))
        );
        assert_eq!(parse_time("none").unwrap().0, None);
        assert!(parse_time("0").is_err());
        assert!(parse_time("-1").is_err());
        assert!(parse_time("soon").is_err());
        assert_eq!(parse_memory("64").unwrap().0, Some(64 << 20));
        assert_eq!(parse_memory("0.5").unwrap().0, Some(512 << 10));
        assert_eq!(parse_memory("NONE").unwrap().0, None);
        assert!(parse_memory("inf").is_err());
    }

    #[test]
    fn the_defaults_are_the_library_defaults() {
        let t = parse_time(DEFAULT_TIME_LIMIT).unwrap().0;
        assert_eq!(t, Some(crate::budget::DEFAULT_TIME_LIMIT));
        let m = parse_memory(DEFAULT_MEMORY_LIMIT_MIB).unwrap().0;
        assert_eq!(m, Some(crate::budget::DEFAULT_MEMORY_LIMIT));
    }

    #[test]
    fn no_memory_limit_lifts_the_size_limits() {
        let args = LimitArgs {
            time_limit: TimeLimit(None),
            memory_limit: MemoryLimit(None),
        };
        let b = args.budget();
        assert_eq!(b.size_limits(), (None, None));
        assert_eq!(b.time_limit(), None);
        let args = LimitArgs {
            time_limit: TimeLimit(Some(Duration::from_secs(2))),
            memory_limit: MemoryLimit(Some(1 << 30)),
        };
        let b = args.budget();
        assert!(b.size_limits().0.is_some());
        assert_eq!(b.memory_limit(), Some(1 << 30));
    }
}
