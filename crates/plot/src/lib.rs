//! # lowdisc-plot: small plots written as SVG and PNG
//!
//! Three chart kinds, each turned into a [`Canvas`] and saved by extension:
//! * [`ScatterGrid`] of titled [`ScatterPanel`]s (point sets, with grid lines
//!   at elementary intervals and heavier boundary lines, e.g. pixel edges);
//! * [`LineChart`] of [`Series`] on linear or log-log axes with a legend
//!   (convergence plots);
//! * [`Heatmap`] of a value grid through a [`ColorMap`] (error images,
//!   spectra).
//!
//! [`compose::grid`] places several canvases in rows in one picture.
//!
//! ```no_run
//! use lowdisc_plot::{ScatterGrid, ScatterPanel};
//! let panel = ScatterPanel::new("points", vec![[0.25, 0.5], [0.75, 0.125]]).with_regular_grid(2);
//! ScatterGrid::row(vec![panel]).to_canvas().save("points.svg")?;
//! # Ok::<(), lowdisc_plot::Error>(())
//! ```
//!
//! Modules: [`scatter`], [`mod@line`] and [`mod@heatmap`] (the charts), [`canvas`]
//! (the drawing surface and saving), [`axis`] (ticks and labels), [`color`]
//! (colour maps); `svg` and `raster` write the two formats.
//!
//! SVG is written by hand with real `<text>` elements. PNG is rasterised with
//! `tiny-skia`, and text is drawn with `ab_glyph` from the Ubuntu Light and
//! Hack fonts shipped inside the `epaint_default_fonts` crate, so PNG output
//! needs no system fonts. [`Canvas::save`] writes to a temporary file and
//! renames it, so a failed save never leaves a half-written file.

pub mod axis;
pub mod canvas;
pub mod color;
pub mod compose;
mod encode;
pub mod heatmap;
pub mod line;
mod raster;
pub mod scatter;
mod svg;

use std::fmt;
use std::path::Path;

pub use axis::{Axis, Frame};
pub use canvas::{Anchor, Canvas, Face, Format, Raster, Shape, Stroke, TextStyle};
pub use color::{Color, ColorMap};
pub use heatmap::{Heatmap, quantile};
pub use line::{LineChart, Series};
pub use raster::text_width;
pub use scatter::{ScatterGrid, ScatterPanel};

/// What can go wrong when rendering or saving a plot.
#[derive(Debug)]
pub enum Error {
    /// The file name's extension is not `.png` or `.svg`.
    UnsupportedFormat(String),
    /// Inconsistent input data (sizes that do not match, empty images).
    InvalidData(String),
    /// Encoding the image failed.
    Encode(String),
    /// Writing the file failed.
    Io {
        /// The file being written.
        path: String,
        /// The underlying error.
        source: std::io::Error,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::UnsupportedFormat(p) => {
                write!(
                    f,
                    "cannot tell the image format of `{p}`: use a .png or .svg file name"
                )
            }
            Error::InvalidData(m) => write!(f, "invalid plot data: {m}"),
            Error::Encode(m) => write!(f, "cannot encode the image: {m}"),
            Error::Io { path, source } => write!(f, "cannot write `{path}`: {source}"),
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Io { source, .. } => Some(source),
            _ => None,
        }
    }
}

/// Writes `bytes` to `path` atomically (see [`lowdisc_files::write_bytes`]):
/// `path` holds its old contents or the complete new ones, never a mix.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    lowdisc_files::write_bytes(path, bytes).map_err(|e| Error::Io {
        path: path.display().to_string(),
        source: std::io::Error::new(e.io_error().kind(), e.io_error().to_string()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn save_picks_the_format_and_leaves_no_temporary_file() {
        let dir = std::env::temp_dir().join(format!("lowdisc-plot-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let canvas = ScatterGrid::row(vec![ScatterPanel::new("p", vec![[0.5, 0.5]])]).to_canvas();
        canvas.save(dir.join("a.svg")).unwrap();
        canvas.save(dir.join("a.PNG")).unwrap();
        assert!(
            std::fs::read_to_string(dir.join("a.svg"))
                .unwrap()
                .starts_with("<svg")
        );
        assert_eq!(&std::fs::read(dir.join("a.PNG")).unwrap()[..4], b"\x89PNG");
        assert!(matches!(
            canvas.save(dir.join("a.jpg")),
            Err(Error::UnsupportedFormat(_))
        ));
        assert!(matches!(
            canvas.save(dir.join("missing/a.png")),
            Err(Error::Io { .. })
        ));
        let mut names: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        names.sort();
        assert_eq!(names, ["a.PNG", "a.svg"]);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
