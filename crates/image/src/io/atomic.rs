//! Atomic file output in this crate's error type: the image writers go
//! through `lowdisc-files` (temporary sibling, fsync, rename), which this
//! module adapts to [`ImageError`].

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

use crate::error::ImageError;

impl From<lowdisc_files::Error> for ImageError {
    fn from(err: lowdisc_files::Error) -> Self {
        ImageError::io(err.io_error()).with_path(err.path())
    }
}

/// Writes a file atomically: `write` fills a buffered temporary file next to
/// `path`; on success the file is flushed, fsynced and renamed to `path`, on
/// any error the temporary file is removed and an existing `path` is left as
/// it was (see [`lowdisc_files::write_with`]). Errors carry `path`.
pub fn write_atomically(
    path: impl AsRef<Path>,
    write: impl FnOnce(&mut BufWriter<File>) -> Result<(), ImageError>,
) -> Result<(), ImageError> {
    let path = path.as_ref();
    lowdisc_files::write_with(path, write).map_err(|e| match e.path() {
        Some(_) => e,
        None => e.with_path(path),
    })
}

/// Writes `bytes` to `path` atomically (see [`write_atomically`]).
pub fn write_bytes_atomically(path: impl AsRef<Path>, bytes: &[u8]) -> Result<(), ImageError> {
    write_atomically(path, |w| w.write_all(bytes).map_err(|e| ImageError::io(&e)))
}
