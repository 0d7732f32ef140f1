//! Atomic writing of output files (see the crate documentation).

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

use crate::{Error, registry};

/// Writes `path` atomically: `write` fills a buffered temporary file next to
/// `path`; once it returns `Ok` the data is flushed, fsynced and renamed over
/// `path`, and the folder is fsynced. On any error (from `write`, the flush,
/// the fsync or the rename) the temporary file is removed and an existing
/// `path` keeps its old contents. Errors of this crate name `path`.
pub fn write_with<E: From<Error>>(
    path: impl AsRef<Path>,
    write: impl FnOnce(&mut BufWriter<File>) -> Result<(), E>,
) -> Result<(), E> {
    let path = path.as_ref();
    let (file, temporary) = registry::create_temporary(path)?;
    let mut writer = BufWriter::new(file);
    let filled = write(&mut writer);
    let synced = filled.and_then(|()| {
        let file = writer
            .into_inner()
            .map_err(|e| Error::new(path, "cannot write", e.into_error()))?;
        file.sync_all()
            .map_err(|e| Error::new(path, "cannot sync", e))?;
        Ok(())
    });
    match synced {
        Ok(()) => {
            temporary.persist()?;
            sync_folder(path)?;
            Ok(())
        }
        Err(err) => {
            temporary.discard();
            Err(err)
        }
    }
}

/// Writes `bytes` to `path` atomically (see [`write_with`]).
pub fn write_bytes(path: impl AsRef<Path>, bytes: &[u8]) -> Result<(), Error> {
    let path = path.as_ref();
    write_with(path, |w| {
        w.write_all(bytes)
            .map_err(|e| Error::new(path, "cannot write", e))
    })
}

/// Fsyncs the folder holding `path`, so the rename that made `path` is on
/// disk. File systems that cannot sync a folder (some network and FUSE
/// systems answer `EINVAL`) are accepted as they are.
fn sync_folder(path: &Path) -> Result<(), Error> {
    let folder = registry::folder_of(path);
    let synced = File::open(folder).and_then(|dir| dir.sync_all());
    match synced {
        Err(e) if e.kind() != std::io::ErrorKind::InvalidInput => {
            Err(Error::new(path, "cannot sync the folder of", e))
        }
        _ => Ok(()),
    }
}
