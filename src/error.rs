//! The crate-level error: bad input (exit status 2) versus internal failure
//! (exit status 1).  Each layer's own error converts into it at the boundary.

use crate::number::NumberError;
use crate::poly::ParseError;
use std::fmt;

/// What went wrong, for the CLI and the batch protocol.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Error {
    /// The input is not acceptable: `kind` is a short machine-readable tag
    /// (`parse`, `input`, `not-univariate`, …), `message` says what, where
    /// and why.
    Input {
        /// Machine-readable category.
        kind: &'static str,
        /// Human-readable explanation.
        message: String,
    },
    /// A failure inside quadsect (a bug): never a wrong answer, but no
    /// answer either.
    Internal(String),
}

impl Error {
    /// A bad-input error of the given kind.
    pub fn input(kind: &'static str, message: impl Into<String>) -> Error {
        Error::Input {
            kind,
            message: message.into(),
        }
    }

    /// The machine-readable kind (`internal` for internal failures).
    pub fn kind(&self) -> &'static str {
        match self {
            Error::Input { kind, .. } => kind,
            Error::Internal(_) => "internal",
        }
    }

    /// The message without the kind.
    pub fn message(&self) -> &str {
        match self {
            Error::Input { message, .. } => message,
            Error::Internal(m) => m,
        }
    }

    /// Process exit status for this error (2 bad input, 1 internal).
    pub fn exit_code(&self) -> i32 {
        match self {
            Error::Input { .. } => 2,
            Error::Internal(_) => 1,
        }
    }

    /// Prefixes the message with context (`in --surface: …`).
    pub fn context(self, what: &str) -> Error {
        match self {
            Error::Input { kind, message } => Error::Input {
                kind,
                message: format!("{what}: {message}"),
            },
            Error::Internal(m) => Error::Internal(format!("{what}: {m}")),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Input { message, .. } => write!(f, "{message}"),
            Error::Internal(m) => write!(f, "internal error: {m}"),
        }
    }
}

impl std::error::Error for Error {}

impl From<ParseError> for Error {
    fn from(e: ParseError) -> Error {
        Error::input("parse", e.to_string())
    }
}

impl From<NumberError> for Error {
    fn from(e: NumberError) -> Error {
        Error::input("number", e.to_string())
    }
}
