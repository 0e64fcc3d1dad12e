//! The crate's one error type: a typed [`ErrorKind`] and a message that
//! says what went wrong, where and why.  Bad input (exit status 2), an
//! exhausted budget (exit status 3) and internal failures (exit status 1)
//! are told apart by the kind.  Each layer's own error converts into it at
//! the boundary.  Library messages never name CLI flags: the CLI adds its
//! own context (`in --surface: …`).

use crate::budget::Exhausted;
use crate::number::NumberError;
use crate::poly::ParseError;
use std::fmt;

/// What kind of failure an [`Error`] is.  The batch protocol, the Python
/// and C bindings report it by [`ErrorKind::as_str`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[non_exhaustive]
pub enum ErrorKind {
    /// An expression could not be read (`parse`).
    Parse,
    /// A number could not be read (`number`).
    Number,
    /// The ellipsoid is not a real ellipsoid (`not-an-ellipsoid`).
    NotAnEllipsoid,
    /// A natural quadric's parameters are invalid (`bad-quadric`).
    BadQuadric,
    /// Another unacceptable argument (`input`): a surface in the wrong
    /// variables, an unknown variable name, …
    Input,
    /// `roots` needs a univariate polynomial (`not-univariate`).
    NotUnivariate,
    /// The zero polynomial where a non-zero one is needed (`zero-polynomial`).
    ZeroPolynomial,
    /// A batch line is not a JSON object (`json`).
    Json,
    /// A batch line lacks a field (`missing-field`).
    MissingField,
    /// A batch field has the wrong type (`bad-field`).
    BadField,
    /// A batch line names an unknown operation (`unknown-op`).
    UnknownOp,
    /// Reading or writing failed (`io`).
    Io,
    /// A compute budget ran out (`budget`): the time limit, the memory
    /// limit or a size limit; the message says which.
    Budget,
    /// A failure inside quadsect (`internal`): never a wrong answer, but no
    /// answer either.  Please report it.
    Internal,
}

impl ErrorKind {
    /// The machine-readable tag (`parse`, `not-an-ellipsoid`, `budget`, …).
    pub fn as_str(self) -> &'static str {
        match self {
            ErrorKind::Parse => "parse",
            ErrorKind::Number => "number",
            ErrorKind::NotAnEllipsoid => "not-an-ellipsoid",
            ErrorKind::BadQuadric => "bad-quadric",
            ErrorKind::Input => "input",
            ErrorKind::NotUnivariate => "not-univariate",
            ErrorKind::ZeroPolynomial => "zero-polynomial",
            ErrorKind::Json => "json",
            ErrorKind::MissingField => "missing-field",
            ErrorKind::BadField => "bad-field",
            ErrorKind::UnknownOp => "unknown-op",
            ErrorKind::Io => "io",
            ErrorKind::Budget => "budget",
            ErrorKind::Internal => "internal",
        }
    }

    /// Process exit status for this kind: 2 bad input, 3 budget exhausted,
    /// 1 internal failure.
    pub fn exit_code(self) -> i32 {
        match self {
            ErrorKind::Internal => 1,
            ErrorKind::Budget => 3,
            _ => 2,
        }
    }
}

impl fmt::Display for ErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// An error: its [`ErrorKind`] and a message for people.
///
/// ```
/// use quadsect::{Error, ErrorKind};
/// let e = Error::new(ErrorKind::BadQuadric, "radius2 must be > 0, got -1");
/// assert_eq!(e.kind(), ErrorKind::BadQuadric);
/// assert_eq!(e.kind().as_str(), "bad-quadric");
/// assert_eq!(e.context("in A").to_string(), "in A: radius2 must be > 0, got -1");
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    kind: ErrorKind,
    message: String,
}

impl Error {
    /// An error of the given kind.
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Error {
        Error {
            kind,
            message: message.into(),
        }
    }

    /// An internal failure (a bug in quadsect).
    pub fn internal(message: impl Into<String>) -> Error {
        Error::new(ErrorKind::Internal, message)
    }

    /// The kind.
    pub fn kind(&self) -> ErrorKind {
        self.kind
    }

    /// True for bad input (neither a budget nor an internal failure).
    pub fn is_input(&self) -> bool {
        !matches!(self.kind, ErrorKind::Internal | ErrorKind::Budget)
    }

    /// The message without the kind.
    pub fn message(&self) -> &str {
        &self.message
    }

    /// Process exit status for this error (see [`ErrorKind::exit_code`]).
    pub fn exit_code(&self) -> i32 {
        self.kind.exit_code()
    }

    /// Prefixes the message with context (`in A: …`).
    pub fn context(self, what: &str) -> Error {
        Error {
            kind: self.kind,
            message: format!("{what}: {}", self.message),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.kind {
            ErrorKind::Internal => write!(f, "internal error: {}", self.message),
            _ => f.write_str(&self.message),
        }
    }
}

impl std::error::Error for Error {}

impl From<ParseError> for Error {
    fn from(e: ParseError) -> Error {
        Error::new(ErrorKind::Parse, e.to_string())
    }
}

impl From<NumberError> for Error {
    fn from(e: NumberError) -> Error {
        Error::new(ErrorKind::Number, e.to_string())
    }
}

impl From<Exhausted> for Error {
    fn from(e: Exhausted) -> Error {
        Error::new(ErrorKind::Budget, e.to_string())
    }
}
