//! Bounded reading of input files: regular files only, and no more than a
//! size limit, checked before anything is read.
//!
//! A directory, a FIFO or a device (`/dev/zero` reads forever, a FIFO blocks
//! on open) given where a file is expected is refused with a message saying
//! what it is, rather than "does not exist" or an endless read. The check
//! looks at the metadata without opening the path; the read itself is capped
//! too, for files whose size the metadata does not tell (such as `/proc`).

use std::fs::File;
use std::io::{self, Read};
use std::path::Path;

use crate::Error;

/// The default size limit of [`read_input`]: 1 GiB.
pub const MAX_INPUT_BYTES: u64 = 1 << 30;

fn refuse(path: &Path, kind: io::ErrorKind, why: String) -> Error {
    Error::new(path, "cannot read", io::Error::new(kind, why))
}

/// Checks that `path` is an existing regular file (symbolic links followed)
/// of at most `limit` bytes, without opening it.
pub fn check_input(path: &Path, limit: u64) -> Result<(), Error> {
    let meta = std::fs::metadata(path).map_err(|e| Error::new(path, "cannot read", e))?;
    if meta.is_dir() {
        return Err(refuse(
            path,
            io::ErrorKind::InvalidInput,
            "is a directory".into(),
        ));
    }
    if !meta.is_file() {
        let what = "is not a regular file (a device, FIFO or socket)".into();
        return Err(refuse(path, io::ErrorKind::InvalidInput, what));
    }
    if meta.len() > limit {
        return Err(too_large(path, limit));
    }
    Ok(())
}

fn too_large(path: &Path, limit: u64) -> Error {
    let why = format!("is larger than the input limit of {limit} bytes");
    refuse(path, io::ErrorKind::InvalidData, why)
}

/// Reads a regular file of at most [`MAX_INPUT_BYTES`] (see
/// [`read_input_limited`]).
pub fn read_input(path: impl AsRef<Path>) -> Result<Vec<u8>, Error> {
    read_input_limited(path, MAX_INPUT_BYTES)
}

/// Reads the whole of the regular file `path`, refusing directories,
/// devices, FIFOs and sockets, and any file of more than `limit` bytes
/// (including one that grows past it while being read).
pub fn read_input_limited(path: impl AsRef<Path>, limit: u64) -> Result<Vec<u8>, Error> {
    let path = path.as_ref();
    check_input(path, limit)?;
    let file = File::open(path).map_err(|e| Error::new(path, "cannot read", e))?;
    let mut bytes = Vec::new();
    file.take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| Error::new(path, "cannot read", e))?;
    if bytes.len() as u64 > limit {
        return Err(too_large(path, limit));
    }
    Ok(bytes)
}
