//! Test and benchmark support: where the public scene data lives
//! (`../shared/scenes` next to the repository) and what a test does when a
//! file it needs is absent.
//!
//! * [`dir`]: the scene directory (whether or not it exists);
//! * [`file`]: a file or directory under it, or `None` after [`skip`];
//! * [`skip`]: prints one `SKIPPED: ...` line, or, when the environment
//!   variable [`REQUIRE_VAR`] is `1` (as `.ci/run` sets it), panics so that
//!   the test fails instead of passing silently.
//!
//! Only tests, benchmarks and examples depend on this crate; printing (to the
//! test's captured output) is its purpose.

use std::path::{Path, PathBuf};

/// The environment variable that turns every skip into a failure.
pub const REQUIRE_VAR: &str = "LOWDISC_REQUIRE_SCENES";

/// The shared scene directory: `shared/scenes` beside the repository
/// (the repository's `../shared/scenes`).
pub fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/scenes")
}

/// Whether [`REQUIRE_VAR`] is set to `1`.
pub fn required() -> bool {
    std::env::var(REQUIRE_VAR).is_ok_and(|v| v == "1")
}

/// What a test should do about something absent.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Absent {
    /// Print this line and skip the test.
    Skip(String),
    /// Fail the test with this message.
    Fail(String),
}

/// The decision [`skip`] acts on (`required`: is [`REQUIRE_VAR`] set).
pub fn decide(reason: &str, required: bool) -> Absent {
    if required {
        Absent::Fail(format!(
            "{reason}, and {REQUIRE_VAR}=1 requires the shared scenes"
        ))
    } else {
        Absent::Skip(format!("SKIPPED: {reason}"))
    }
}

/// Skips (prints `SKIPPED: reason`) or, with [`REQUIRE_VAR`]`=1`, panics.
pub fn skip(reason: &str) {
    match decide(reason, required()) {
        Absent::Skip(line) => println!("{line}"),
        Absent::Fail(message) => panic!("{message}"),
    }
}

/// `rel` under [`dir`] when it exists; otherwise [`skip`] and `None`.
pub fn file(rel: &str) -> Option<PathBuf> {
    existing(dir().join(rel))
}

/// `path` when it exists; otherwise [`skip`] and `None`.
pub fn existing(path: PathBuf) -> Option<PathBuf> {
    if path.exists() {
        Some(path)
    } else {
        skip(&format!("{} is absent", path.display()));
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn absent_data_skips_with_a_visible_line_unless_required() {
        assert_eq!(
            decide("x.pbrt is absent", false),
            Absent::Skip("SKIPPED: x.pbrt is absent".into())
        );
        let Absent::Fail(m) = decide("x.pbrt is absent", true) else {
            panic!("required data must fail");
        };
        assert!(m.starts_with("x.pbrt is absent") && m.contains(REQUIRE_VAR));
    }

    #[test]
    fn existing_files_are_returned_and_the_directory_is_the_shared_one() {
        let me = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml");
        assert_eq!(existing(me.clone()), Some(me));
        assert!(dir().ends_with("shared/scenes"));
    }
}
