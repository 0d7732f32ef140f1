//! A [`Canvas`] out: as an SVG document, as PNG bytes, or into a file
//! written atomically. The canvas itself ([`crate::canvas`]) knows nothing
//! of the back ends ([`crate::svg`], [`crate::raster`]) that draw it.

use std::path::Path;

use crate::canvas::{Canvas, Format};
use crate::{Error, raster, svg, write_atomically};

impl Canvas {
    /// Renders the canvas as an SVG document.
    pub fn to_svg(&self) -> String {
        svg::render(self)
    }

    /// Renders the canvas as PNG bytes.
    pub fn to_png(&self) -> Result<Vec<u8>, Error> {
        raster::render(self)
    }

    /// Renders in `format`.
    pub fn encode(&self, format: Format) -> Result<Vec<u8>, Error> {
        match format {
            Format::Png => self.to_png(),
            Format::Svg => Ok(self.to_svg().into_bytes()),
        }
    }

    /// Writes the canvas to `path`, as PNG or SVG by its extension. The file is
    /// written under a temporary name in the same directory and then renamed,
    /// so `path` never holds a half-written file.
    pub fn save(&self, path: impl AsRef<Path>) -> Result<(), Error> {
        let path = path.as_ref();
        let bytes = self.encode(Format::from_path(path)?)?;
        write_atomically(path, &bytes)
    }
}
