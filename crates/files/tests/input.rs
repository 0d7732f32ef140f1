//! Bounded input reads: regular files only, limited in size, refusals that
//! say what the path is.

use std::path::PathBuf;

use lowdisc_files::{read_input, read_input_limited};

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("files-input")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn a_regular_file_is_read_whole() {
    let dir = scratch("ok");
    let file = dir.join("scene.pbrt");
    std::fs::write(&file, b"WorldBegin\n").unwrap();
    assert_eq!(read_input(&file).unwrap(), b"WorldBegin\n");
    assert_eq!(read_input_limited(&file, 11).unwrap().len(), 11);
}

#[test]
fn directories_devices_missing_and_oversized_files_are_refused_by_name() {
    let dir = scratch("refused");
    let err = read_input(&dir).unwrap_err().to_string();
    assert!(
        err.contains("is a directory") && err.contains("refused"),
        "{err}"
    );
    let err = read_input("/dev/zero").unwrap_err().to_string();
    assert!(err.contains("not a regular file"), "{err}");
    let err = read_input(dir.join("missing.pbrt")).unwrap_err();
    assert_eq!(err.io_error().kind(), std::io::ErrorKind::NotFound);
    let big = dir.join("big.ply");
    std::fs::write(&big, vec![b'x'; 100]).unwrap();
    let err = read_input_limited(&big, 99).unwrap_err().to_string();
    assert!(
        err.contains("larger than the input limit of 99 bytes"),
        "{err}"
    );
}
