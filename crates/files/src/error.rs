//! The crate's error: which output, which step, and the operating system's
//! reason.

use std::fmt;
use std::io;
use std::path::{Path, PathBuf};

/// A failed atomic write. Displays as ``cannot write `PATH`: REASON``
/// (the verb names the failed step: write, sync, rename...).
#[derive(Debug)]
pub struct Error {
    path: PathBuf,
    step: &'static str,
    source: io::Error,
}

impl Error {
    /// An error of `step` (a phrase such as `"cannot write"`) on `path`.
    pub fn new(path: &Path, step: &'static str, source: io::Error) -> Self {
        Error {
            path: path.to_path_buf(),
            step,
            source,
        }
    }

    /// The destination the write was for.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The operating system's error.
    pub fn io_error(&self) -> &io::Error {
        &self.source
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} `{}`: {}",
            self.step,
            self.path.display(),
            self.source
        )
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        Some(&self.source)
    }
}

impl From<Error> for io::Error {
    fn from(err: Error) -> io::Error {
        io::Error::new(err.source.kind(), err.to_string())
    }
}
