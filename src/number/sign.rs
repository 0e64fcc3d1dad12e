//! The sign of an exact quantity, as a type (not an `i32`).

use std::cmp::Ordering;
use std::fmt;

/// The exact sign of a number: negative, zero or positive.
///
/// ```
/// use quadsect::Sign;
/// assert_eq!(Sign::from_i32(-7), Sign::Negative);
/// assert_eq!(-Sign::Positive, Sign::Negative);
/// assert_eq!(Sign::Negative * Sign::Negative, Sign::Positive);
/// assert_eq!(Sign::Zero.to_string(), "0");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Sign {
    /// `< 0`.
    Negative,
    /// `= 0`.
    Zero,
    /// `> 0`.
    Positive,
}

impl Sign {
    /// The sign of an integer (`-1`, `0`, `1` for any negative, zero,
    /// positive value).
    pub fn from_i32(s: i32) -> Sign {
        match s.cmp(&0) {
            Ordering::Less => Sign::Negative,
            Ordering::Equal => Sign::Zero,
            Ordering::Greater => Sign::Positive,
        }
    }

    /// The sign of `a − b` for an ordering of `a` and `b`.
    pub fn from_ordering(o: Ordering) -> Sign {
        match o {
            Ordering::Less => Sign::Negative,
            Ordering::Equal => Sign::Zero,
            Ordering::Greater => Sign::Positive,
        }
    }

    /// `-1`, `0` or `1`.
    pub fn as_i32(self) -> i32 {
        match self {
            Sign::Negative => -1,
            Sign::Zero => 0,
            Sign::Positive => 1,
        }
    }

    /// True for [`Sign::Zero`].
    pub fn is_zero(self) -> bool {
        self == Sign::Zero
    }
}

impl std::ops::Neg for Sign {
    type Output = Sign;
    fn neg(self) -> Sign {
        Sign::from_i32(-self.as_i32())
    }
}

impl std::ops::Mul for Sign {
    type Output = Sign;
    fn mul(self, o: Sign) -> Sign {
        Sign::from_i32(self.as_i32() * o.as_i32())
    }
}

impl fmt::Display for Sign {
    /// `-`, `0` or `+`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Sign::Negative => "-",
            Sign::Zero => "0",
            Sign::Positive => "+",
        })
    }
}
