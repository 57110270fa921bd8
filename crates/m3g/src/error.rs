//! The error type of every fallible M3G call.

use std::fmt;

/// An M3G exception. Each kind is named after the Java exception the specification says the
/// call throws, so tests (and ports of Java code) can tell them apart.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum M3gError {
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
}

impl M3gError {
    /// The Java exception's simple name, e.g. `"IllegalArgumentException"`.
    pub fn java_name(&self) -> &'static str {
        match self {
            M3gError::NullPointer(_) => "NullPointerException",
            M3gError::IllegalArgument(_) => "IllegalArgumentException",
            M3gError::IllegalState(_) => "IllegalStateException",
            M3gError::IndexOutOfBounds(_) => "IndexOutOfBoundsException",
            M3gError::Arithmetic(_) => "ArithmeticException",
        }
    }

    /// The message.
    pub fn message(&self) -> &str {
        match self {
            M3gError::NullPointer(m)
            | M3gError::IllegalArgument(m)
            | M3gError::IllegalState(m)
            | M3gError::IndexOutOfBounds(m)
            | M3gError::Arithmetic(m) => m,
        }
    }
}

impl fmt::Display for M3gError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.java_name(), self.message())
    }
}

impl std::error::Error for M3gError {}

/// The result of a fallible M3G call.
pub type Result<T> = std::result::Result<T, M3gError>;

pub(crate) fn iae<T>(m: impl Into<String>) -> Result<T> {
    Err(M3gError::IllegalArgument(m.into()))
}
pub(crate) fn ise<T>(m: impl Into<String>) -> Result<T> {
    Err(M3gError::IllegalState(m.into()))
}
pub(crate) fn ioobe<T>(m: impl Into<String>) -> Result<T> {
    Err(M3gError::IndexOutOfBounds(m.into()))
}
pub(crate) fn ae<T>(m: impl Into<String>) -> Result<T> {
    Err(M3gError::Arithmetic(m.into()))
}
#[allow(dead_code)]
pub(crate) fn npe<T>(m: impl Into<String>) -> Result<T> {
    Err(M3gError::NullPointer(m.into()))
}
