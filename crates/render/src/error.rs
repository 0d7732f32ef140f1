//! The crate's error type.

use std::path::PathBuf;

/// Errors from loading or building geometry.
#[derive(Debug)]
pub enum Error {
    /// A file could not be read.
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// A PLY file is malformed or truncated.
    Ply {
        /// The file (or `<memory>` for in-memory data).
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
    /// Shape parameters are invalid (bad indices, counts, non-finite values...).
    InvalidShape(String),
    /// A transform is singular where an inverse is needed.
    SingularTransform,
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Error::Io { path, source } => write!(f, "{}: {source}", path.display()),
            Error::Ply { path, message } => write!(f, "{}: invalid PLY: {message}", path.display()),
            Error::InvalidShape(m) => write!(f, "invalid shape: {m}"),
            Error::SingularTransform => f.write_str("transform matrix is singular"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Io { source, .. } => Some(source),
            _ => None,
        }
    }
}

impl From<crate::math::SingularMatrix> for Error {
    fn from(_: crate::math::SingularMatrix) -> Self {
        Error::SingularTransform
    }
}
