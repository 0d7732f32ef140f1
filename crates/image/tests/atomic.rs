//! Atomic writes: no partial output and no temporary file after a failure.

use std::io::Write;
use std::path::PathBuf;

use lowdisc_image::{ErrorKind, ImageError, RgbImage, write_atomically, write_exr, write_png};

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("image-atomic")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn entries(dir: &PathBuf) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn failed_write_leaves_no_temporary_and_keeps_the_old_file() {
    let dir = scratch("fail");
    let target = dir.join("out.exr");
    std::fs::write(&target, b"old contents").unwrap();
    let err = write_atomically(&target, |w| {
        w.write_all(b"half of a new file").unwrap();
        w.flush().unwrap();
        Err(ImageError::new(ErrorKind::Io, "simulated failure"))
    })
    .unwrap_err();
    assert_eq!(err.kind(), ErrorKind::Io);
    assert_eq!(err.path(), Some(target.as_path()));
    assert_eq!(entries(&dir), ["out.exr"]);
    assert_eq!(std::fs::read(&target).unwrap(), b"old contents");

    // Same without an old file: nothing at all is left.
    let fresh = dir.join("fresh.png");
    assert!(write_atomically(&fresh, |_| Err(ImageError::new(ErrorKind::Io, "no"))).is_err());
    assert_eq!(entries(&dir), ["out.exr"]);
}

#[test]
fn successful_write_replaces_and_leaves_only_the_target() {
    let dir = scratch("ok");
    let img = RgbImage::filled(4, 4, [0.5, 0.25, 1.0]).unwrap();
    std::fs::write(dir.join("a.exr"), b"stale").unwrap();
    write_exr(dir.join("a.exr"), &img).unwrap();
    write_png(dir.join("a.png"), &img, 1.0).unwrap();
    assert_eq!(entries(&dir), ["a.exr", "a.png"]);
    assert_eq!(lowdisc_image::read_image(dir.join("a.exr")).unwrap(), img);
}

#[test]
fn missing_folder_is_an_error_not_a_panic() {
    let dir = scratch("missing");
    let img = RgbImage::new(2, 2).unwrap();
    let err = write_exr(dir.join("no/such/folder/x.exr"), &img).unwrap_err();
    assert_eq!(err.kind(), ErrorKind::Io);
    assert!(entries(&dir).is_empty());
}
