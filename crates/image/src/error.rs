//! The crate's error type: what went wrong, with which file, and why.
//!
//! Every fallible operation of this crate returns [`ImageError`]. Readers never
//! panic on malformed, truncated or hostile files; they return an error whose
//! [`ErrorKind`] says which class of problem it was.

use std::fmt;
use std::path::{Path, PathBuf};

/// The class of an [`ImageError`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The operating system refused a read, write, create or rename.
    Io,
    /// The file ended before all the data its header announced.
    Truncated,
    /// The file's bytes do not follow the format (bad header, bad run length...).
    Malformed,
    /// A valid file in a variant this crate does not read or write.
    Unsupported,
    /// The format could not be told from the magic bytes nor the extension.
    UnknownFormat,
    /// The image is larger than [`crate::MAX_PIXELS`] or a size overflows.
    TooLarge,
    /// Two images that must have the same size do not.
    SizeMismatch,
    /// A pixel position or rectangle lies outside the image.
    OutOfBounds,
    /// An argument is not allowed (zero size, non-positive factor, NaN bound...).
    InvalidArgument,
}

impl ErrorKind {
    /// A short lower-case name of the kind, used in messages.
    pub fn name(self) -> &'static str {
        match self {
            ErrorKind::Io => "i/o error",
            ErrorKind::Truncated => "truncated file",
            ErrorKind::Malformed => "malformed file",
            ErrorKind::Unsupported => "unsupported variant",
            ErrorKind::UnknownFormat => "unknown image format",
            ErrorKind::TooLarge => "image too large",
            ErrorKind::SizeMismatch => "size mismatch",
            ErrorKind::OutOfBounds => "out of bounds",
            ErrorKind::InvalidArgument => "invalid argument",
        }
    }
}

impl fmt::Display for ErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An error from reading, writing or processing an image.
///
/// Displays as `PATH: KIND: MESSAGE`, or `KIND: MESSAGE` for in-memory work.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ImageError {
    kind: ErrorKind,
    path: Option<PathBuf>,
    message: String,
}

impl ImageError {
    /// An error of `kind` with a message and no file path.
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Self {
        ImageError {
            kind,
            path: None,
            message: message.into(),
        }
    }

    /// The same error, naming the file it concerns.
    #[must_use]
    pub fn with_path(mut self, path: impl AsRef<Path>) -> Self {
        self.path = Some(path.as_ref().to_path_buf());
        self
    }

    /// An [`ErrorKind::Io`] error (or [`ErrorKind::Truncated`] for an unexpected
    /// end of file) from a `std::io::Error`.
    pub fn io(err: &std::io::Error) -> Self {
        let kind = if err.kind() == std::io::ErrorKind::UnexpectedEof {
            ErrorKind::Truncated
        } else {
            ErrorKind::Io
        };
        ImageError::new(kind, err.to_string())
    }

    /// The class of the error.
    pub fn kind(&self) -> ErrorKind {
        self.kind
    }

    /// The file the error concerns, when there is one.
    pub fn path(&self) -> Option<&Path> {
        self.path.as_deref()
    }

    /// The human-readable explanation, without kind and path.
    pub fn message(&self) -> &str {
        &self.message
    }
}

impl fmt::Display for ImageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(path) = &self.path {
            write!(f, "{}: ", path.display())?;
        }
        write!(f, "{}: {}", self.kind, self.message)
    }
}

impl std::error::Error for ImageError {}

/// Shorthand for a malformed-file error.
pub(crate) fn malformed(message: impl Into<String>) -> ImageError {
    ImageError::new(ErrorKind::Malformed, message)
}

/// Shorthand for a truncated-file error.
pub(crate) fn truncated(message: impl Into<String>) -> ImageError {
    ImageError::new(ErrorKind::Truncated, message)
}

/// Shorthand for an unsupported-variant error.
pub(crate) fn unsupported(message: impl Into<String>) -> ImageError {
    ImageError::new(ErrorKind::Unsupported, message)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn display_names_path_kind_and_message() {
        let e = malformed("bad magic").with_path("/tmp/x.pfm");
        assert_eq!(e.to_string(), "/tmp/x.pfm: malformed file: bad magic");
        let e = ImageError::new(ErrorKind::SizeMismatch, "2x2 vs 3x1");
        assert_eq!(e.to_string(), "size mismatch: 2x2 vs 3x1");
        assert_eq!(e.path(), None);
    }

    #[test]
    fn unexpected_eof_maps_to_truncated() {
        let io = std::io::Error::new(std::io::ErrorKind::UnexpectedEof, "eof");
        assert_eq!(ImageError::io(&io).kind(), ErrorKind::Truncated);
        let io = std::io::Error::new(std::io::ErrorKind::PermissionDenied, "no");
        assert_eq!(ImageError::io(&io).kind(), ErrorKind::Io);
    }
}
