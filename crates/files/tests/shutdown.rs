//! What a signal handler relies on: removing the live temporaries deletes a
//! write in progress and refuses every later write. (A test binary of its
//! own, since closing the registry is process-wide and final.)

use std::io::Write;
use std::path::PathBuf;

use lowdisc_files::{remove_live_temporaries, write_bytes, write_with};

#[test]
fn removing_live_temporaries_deletes_the_write_in_progress_and_refuses_new_ones() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("outfile-shutdown");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let target = dir.join("render.exr");
    std::fs::write(&target, b"previous image").unwrap();
    let result = write_with(&target, |w| {
        w.write_all(b"part of a new image")?;
        w.flush()?;
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 2);
        // The signal arrives mid-write.
        assert_eq!(remove_live_temporaries(), 1);
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
        Ok::<(), std::io::Error>(())
    });
    let err = result.unwrap_err();
    assert_eq!(err.kind(), std::io::ErrorKind::Interrupted, "{err}");
    assert_eq!(std::fs::read(&target).unwrap(), b"previous image");
    assert!(write_bytes(dir.join("later.txt"), b"x").is_err());
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
    assert_eq!(remove_live_temporaries(), 0);
}
