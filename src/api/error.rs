//! The API's error type.

/// What went wrong in an API call.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Error {
    /// The model could not be loaded; 2.2.2's message.
    Load(String),
    /// The engine stopped with an error (2.2.2's `mju_error` text).
    Engine(String),
    /// No object of this kind has this name.
    NotFound { kind: &'static str, name: String },
    /// An index out of range or an argument of the wrong size.
    Invalid(String),
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Error::Load(m) => write!(f, "load error: {m}"),
            Error::Engine(m) => write!(f, "engine error: {m}"),
            Error::NotFound { kind, name } => write!(f, "no {kind} named '{name}'"),
            Error::Invalid(m) => write!(f, "invalid argument: {m}"),
        }
    }
}

impl std::error::Error for Error {}
