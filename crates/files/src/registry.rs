//! The process-wide registry of live temporary files.
//!
//! Every temporary file that [`crate::write_with`] creates is recorded here
//! from its creation until it is renamed into place or removed. A signal
//! handler calls [`remove_live_temporaries`], which removes them all and
//! closes the registry, so a write that starts or finishes afterwards fails
//! instead of leaving a file behind while the process exits.

use std::fs::File;
use std::io;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};

use tempfile::TempPath;

use crate::Error;

/// The live temporaries, and whether the process is shutting down.
struct Registry {
    live: Vec<PathBuf>,
    closed: bool,
}

static REGISTRY: Mutex<Registry> = Mutex::new(Registry {
    live: Vec::new(),
    closed: false,
});

/// The registry, even if a thread panicked while holding it (its contents
/// are a plain list that every operation leaves consistent).
fn registry() -> MutexGuard<'static, Registry> {
    REGISTRY
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner())
}

/// Removes every live temporary file and refuses new ones from now on;
/// returns how many were removed. Meant for a binary's signal handler just
/// before it exits; safe to call from any thread, any number of times.
pub fn remove_live_temporaries() -> usize {
    let mut reg = registry();
    reg.closed = true;
    let mut removed = 0;
    for path in reg.live.drain(..) {
        if std::fs::remove_file(&path).is_ok() {
            removed += 1;
        }
    }
    removed
}

/// The folder that holds `path` (`.` for a bare file name).
pub(crate) fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// The error of a write refused because the process is exiting.
fn exiting(path: &Path) -> Error {
    let e = io::Error::new(io::ErrorKind::Interrupted, "the process is exiting");
    Error::new(path, "cannot write", e)
}

/// A registered temporary file for one destination; removed (and
/// unregistered) when dropped unless [`Temporary::persist`] renamed it.
pub(crate) struct Temporary {
    destination: PathBuf,
    path: Option<TempPath>,
}

/// Creates a fresh temporary sibling of `destination` and registers it.
pub(crate) fn create_temporary(destination: &Path) -> Result<(File, Temporary), Error> {
    let name = destination.file_name().ok_or_else(|| {
        let e = io::Error::new(io::ErrorKind::InvalidInput, "the path has no file name");
        Error::new(destination, "cannot write", e)
    })?;
    let mut prefix = std::ffi::OsString::from(".");
    prefix.push(name);
    prefix.push(".");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp").rand_bytes(8);
    #[cfg(unix)]
    {
        // Outputs get the permissions any new file gets (0666 less the
        // umask), not the private 0600 of a scratch file.
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(std::fs::Permissions::from_mode(0o666));
    }
    let mut reg = registry();
    if reg.closed {
        return Err(exiting(destination));
    }
    let file = builder.tempfile_in(folder_of(destination)).map_err(|e| {
        // The destination is what the user named; the random temporary
        // name that `tempfile` adds to its message would only confuse.
        let text = e.to_string();
        let reason = text.split(" at path ").next().unwrap_or(&text);
        let e = io::Error::new(e.kind(), reason.to_string());
        Error::new(destination, "cannot write", e)
    })?;
    let (file, path) = file.into_parts();
    reg.live.push(path.to_path_buf());
    let temporary = Temporary {
        destination: destination.to_path_buf(),
        path: Some(path),
    };
    Ok((file, temporary))
}

impl Temporary {
    /// Renames the temporary file over the destination.
    pub(crate) fn persist(mut self) -> Result<(), Error> {
        let Some(path) = self.path.take() else {
            return Ok(());
        };
        let mut reg = registry();
        unregister(&mut reg, &path);
        if reg.closed {
            drop(path);
            return Err(exiting(&self.destination));
        }
        path.persist(&self.destination)
            .map_err(|e| Error::new(&self.destination, "cannot rename into", e.error))
    }

    /// Removes the temporary file (also what dropping does).
    pub(crate) fn discard(self) {}
}

fn unregister(reg: &mut Registry, path: &Path) {
    if let Some(i) = reg.live.iter().position(|p| p == path) {
        reg.live.swap_remove(i);
    }
}

impl Drop for Temporary {
    fn drop(&mut self) {
        if let Some(path) = self.path.take() {
            let mut reg = registry();
            unregister(&mut reg, &path);
            // Dropping the `TempPath` removes the file (best effort).
            drop(path);
        }
    }
}
