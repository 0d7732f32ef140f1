//! Helpers shared by the integration tests: the shared scene directory and
//! scratch directories for `Include` tests.

#![allow(dead_code)] // each test binary uses a different subset

use std::path::{Path, PathBuf};

use pbrt_format::{Directive, Recorder, parse_str};

/// The shared scene directory, or `None` (with a message) when it is absent.
pub fn scenes_dir() -> Option<PathBuf> {
    shared_scenes::existing(shared_scenes::dir())
}

/// Every `*.pbrt` file under `dir`, sorted.
pub fn pbrt_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "pbrt") {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// A scratch directory, removed when dropped.
pub struct ScratchDir(PathBuf);

impl std::ops::Deref for ScratchDir {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl Drop for ScratchDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// A fresh, empty scratch directory for one test.
pub fn scratch_dir(test: &str) -> ScratchDir {
    let dir = std::env::temp_dir().join(format!("pbrt-format-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    ScratchDir(dir)
}

/// Parses `text` into a recorder, panicking with the error on failure.
pub fn record(text: &str) -> Recorder {
    let mut rec = Recorder::new();
    if let Err(e) = parse_str(text, "test.pbrt", &mut rec) {
        panic!("unexpected error: {e}");
    }
    rec
}

/// Parses `text` and returns the calls without locations.
pub fn calls(text: &str) -> Vec<Directive> {
    record(text).calls_only()
}
