//! The one error type of the crate: the specification's exception kinds, plus the Loader's
//! and the writer's failures with their details.

use std::fmt;

pub use super::loader::LoadError;

/// An M3G exception. Each kind is named after the Java exception the specification says the
/// call throws, so tests (and ports of Java code) can tell them apart; the Loader's
/// `IOException` carries where in the file it happened ([`LoadError`]).
///
/// ```
/// use m3g::prelude::*;
///
/// let e = KeyframeSequence::new(0, 3, Interpolation::Linear).unwrap_err();
/// assert!(matches!(e, Error::IllegalArgument(_)));
/// let e = Loader::load(b"not an m3g file").unwrap_err();
/// assert!(matches!(e, Error::Io(_)));
/// assert_eq!(e.java_name(), "IOException");
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Error {
    /// `NullPointerException`: a required object is missing.
    NullPointer(String),
    /// `IllegalArgumentException`: an argument is out of its documented range.
    IllegalArgument(String),
    /// `IllegalStateException`: the objects involved are not in a usable state (including
    /// the deferred checks made by rendering and picking).
    IllegalState(String),
    /// `IndexOutOfBoundsException`: an index is out of range.
    IndexOutOfBounds(String),
    /// `ArithmeticException`: a transformation needed is not invertible.
    Arithmetic(String),
    /// `IOException` from the [`Loader`](crate::Loader): the object, class and field at fault.
    Io(LoadError),
    /// The [`writer`](crate::writer) cannot represent the graph in a .m3g file (no Java
    /// counterpart).
    Write(String),
}

impl Error {
    /// The Java exception's simple name, e.g. `"IllegalArgumentException"`.
    pub fn java_name(&self) -> &'static str {
        match self {
            Error::NullPointer(_) => "NullPointerException",
            Error::IllegalArgument(_) => "IllegalArgumentException",
            Error::IllegalState(_) => "IllegalStateException",
            Error::IndexOutOfBounds(_) => "IndexOutOfBoundsException",
            Error::Arithmetic(_) => "ArithmeticException",
            Error::Io(_) | Error::Write(_) => "IOException",
        }
    }

    /// The message (for [`Error::Io`], without the location).
    pub fn message(&self) -> &str {
        match self {
            Error::NullPointer(m)
            | Error::IllegalArgument(m)
            | Error::IllegalState(m)
            | Error::IndexOutOfBounds(m)
            | Error::Arithmetic(m)
            | Error::Write(m) => m,
            Error::Io(e) => &e.message,
        }
    }

    /// The same kind of error with `context` put before the message.
    pub(crate) fn context(mut self, context: &str) -> Error {
        let m = match &mut self {
            Error::NullPointer(m)
            | Error::IllegalArgument(m)
            | Error::IllegalState(m)
            | Error::IndexOutOfBounds(m)
            | Error::Arithmetic(m)
            | Error::Write(m) => m,
            Error::Io(e) => &mut e.message,
        };
        *m = format!("{context}: {m}");
        self
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            // The location already says what failed; tools print it as it is.
            Error::Io(e) => e.fmt(f),
            Error::Write(m) => write!(f, "cannot write .m3g: {m}"),
            _ => write!(f, "{}: {}", self.java_name(), self.message()),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Io(e) => Some(e),
            _ => None,
        }
    }
}

impl From<LoadError> for Error {
    fn from(e: LoadError) -> Error {
        Error::Io(e)
    }
}

/// The result of a fallible M3G call.
pub type Result<T> = std::result::Result<T, Error>;

pub(crate) fn iae<T>(m: impl Into<String>) -> Result<T> {
    Err(Error::IllegalArgument(m.into()))
}
pub(crate) fn ise<T>(m: impl Into<String>) -> Result<T> {
    Err(Error::IllegalState(m.into()))
}
pub(crate) fn ioobe<T>(m: impl Into<String>) -> Result<T> {
    Err(Error::IndexOutOfBounds(m.into()))
}
pub(crate) fn ae<T>(m: impl Into<String>) -> Result<T> {
    Err(Error::Arithmetic(m.into()))
}
#[allow(dead_code)]
pub(crate) fn npe<T>(m: impl Into<String>) -> Result<T> {
    Err(Error::NullPointer(m.into()))
}
