//! Atomic file output: write to a temporary file in the destination's folder,
//! then rename it over the destination only when everything succeeded.

use std::fs::{self, File, OpenOptions};
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use crate::error::{ErrorKind, ImageError};

/// Distinguishes temporary files of concurrent writes within one process.
static COUNTER: AtomicU64 = AtomicU64::new(0);

/// The temporary path used for writing `path`: a hidden sibling
/// `.NAME.PID-N.tmp` in the same folder, so the final rename stays on one
/// file system.
fn temporary_path(path: &Path) -> Result<PathBuf, ImageError> {
    let name = path.file_name().ok_or_else(|| {
        ImageError::new(ErrorKind::InvalidArgument, "output path has no file name").with_path(path)
    })?;
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let tmp_name = format!(".{}.{}-{n}.tmp", name.to_string_lossy(), std::process::id());
    Ok(path.with_file_name(tmp_name))
}

/// Writes a file atomically: `write` fills a buffered temporary file next to
/// `path`; on success the file is flushed and renamed to `path`, on any error
/// (from `write`, the flush or the rename) the temporary file is removed and
/// an existing `path` is left as it was. Errors carry `path`.
pub fn write_atomically(
    path: impl AsRef<Path>,
    write: impl FnOnce(&mut BufWriter<File>) -> Result<(), ImageError>,
) -> Result<(), ImageError> {
    let path = path.as_ref();
    let tmp = temporary_path(path)?;
    let file = OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&tmp)
        .map_err(|e| ImageError::io(&e).with_path(path))?;
    let mut writer = BufWriter::new(file);
    let result = write(&mut writer).and_then(|()| {
        writer.flush().map_err(|e| ImageError::io(&e))?;
        drop(writer);
        fs::rename(&tmp, path).map_err(|e| ImageError::io(&e))
    });
    if result.is_err() {
        // Best effort: the file may already be gone; the original error matters.
        let _ = fs::remove_file(&tmp);
    }
    result.map_err(|e| match e.path() {
        Some(_) => e,
        None => e.with_path(path),
    })
}

/// Writes `bytes` to `path` atomically (see [`write_atomically`]).
pub fn write_bytes_atomically(path: impl AsRef<Path>, bytes: &[u8]) -> Result<(), ImageError> {
    write_atomically(path, |w| w.write_all(bytes).map_err(|e| ImageError::io(&e)))
}
