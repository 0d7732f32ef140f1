//! Atomic writes: the destination holds the old or the complete new contents,
//! and no temporary file survives success or failure.

use std::io::{self, Write};
use std::path::{Path, PathBuf};

use lowdisc_files::{Error, write_bytes, write_with};

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("outfile-atomic")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn success_replaces_the_destination_and_leaves_only_it() {
    let dir = scratch("ok");
    let target = dir.join("a.csv");
    std::fs::write(&target, b"old").unwrap();
    write_bytes(&target, b"new contents").unwrap();
    assert_eq!(std::fs::read(&target).unwrap(), b"new contents");
    write_with(dir.join("b.txt"), |w| -> Result<(), Error> {
        for k in 0..10_000 {
            writeln!(w, "{k}").map_err(|e| Error::new(Path::new("b"), "cannot write", e))?;
        }
        Ok(())
    })
    .unwrap();
    let b = std::fs::read_to_string(dir.join("b.txt")).unwrap();
    assert_eq!(b.lines().count(), 10_000);
    assert_eq!(entries(&dir), ["a.csv", "b.txt"]);
}

#[test]
fn failure_keeps_the_old_file_and_removes_the_temporary() {
    let dir = scratch("fail");
    let target = dir.join("claim.md");
    std::fs::write(&target, b"good old report").unwrap();
    let err = write_with(&target, |w| {
        w.write_all(b"half a report")?;
        w.flush()?;
        // The temporary exists while the closure runs.
        assert_eq!(entries(&dir).len(), 2);
        Err(io::Error::other("simulated failure"))
    })
    .unwrap_err();
    assert_eq!(err.to_string(), "simulated failure");
    assert_eq!(entries(&dir), ["claim.md"]);
    assert_eq!(std::fs::read(&target).unwrap(), b"good old report");
}

#[test]
fn a_missing_folder_or_a_folder_as_destination_is_an_error_naming_the_path() {
    let dir = scratch("missing");
    let missing = dir.join("no/such/x.png");
    let err = write_bytes(&missing, b"x").unwrap_err();
    assert_eq!(err.path(), missing);
    assert!(err.to_string().contains("no/such/x.png"), "{err}");
    let folder = dir.join("sub");
    std::fs::create_dir(&folder).unwrap();
    assert!(write_bytes(&folder, b"x").is_err());
    assert!(folder.is_dir());
    assert_eq!(entries(&dir), ["sub"]);
    assert!(write_bytes(Path::new("/"), b"x").is_err());
}

#[test]
fn temporaries_have_distinct_names_for_concurrent_writes() {
    let dir = scratch("concurrent");
    std::thread::scope(|s| {
        for t in 0..4 {
            let dir = &dir;
            s.spawn(move || {
                for k in 0..25 {
                    let bytes = format!("{t}-{k}");
                    write_bytes(dir.join("same.txt"), bytes.as_bytes()).unwrap();
                }
            });
        }
    });
    assert_eq!(entries(&dir), ["same.txt"]);
    let last = std::fs::read_to_string(dir.join("same.txt")).unwrap();
    assert!(last.ends_with("-24"), "{last}");
}

#[cfg(unix)]
#[test]
fn outputs_are_not_private_scratch_files() {
    use std::os::unix::fs::PermissionsExt;
    let dir = scratch("mode");
    let target = dir.join("image.exr");
    write_bytes(&target, b"x").unwrap();
    let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o777;
    // A new output gets the mode any new file gets here (0666 less the
    // umask), not the private 0600 of a scratch file.
    let plain = dir.join("plain.txt");
    std::fs::write(&plain, b"x").unwrap();
    assert_eq!(mode(&target), mode(&plain));
}

#[test]
fn a_failed_creation_names_the_destination_not_the_temporary() {
    let dir = scratch("names");
    let err = write_bytes(dir.join("no/x.exr"), b"x")
        .unwrap_err()
        .to_string();
    assert!(err.contains("no/x.exr") && !err.contains(".tmp"), "{err}");
}
