//! Where `render` and `figure` write without `-o`: a file in `out/` under
//! the current directory (ignored by git), created when it is missing. An
//! output named with `-o` is used as given, and its directory must exist.

use std::io::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};

/// The folder of default outputs, relative to the current directory.
pub const DIR: &str = "out";

/// The default output path of a file named `file`: `out/FILE`.
pub fn path(file: impl AsRef<Path>) -> PathBuf {
    Path::new(DIR).join(file)
}

/// Creates the folder of a default output when it is missing.
pub fn create_dir() -> Result<()> {
    std::fs::create_dir_all(DIR).with_context(|| format!("cannot create `{DIR}`"))
}

/// Tells the user which file a command wrote (on stderr, which carries the
/// commands' progress; stdout stays for data).
pub fn report_written(path: &Path) {
    // A stderr that cannot be written loses the note, not the file.
    let _ = writeln!(std::io::stderr(), "wrote {}", path.display());
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_outputs_go_to_the_out_folder() {
        assert_eq!(path("render.exr"), Path::new("out").join("render.exr"));
        assert_eq!(path("figure.png").parent(), Some(Path::new(DIR)));
    }
}
