//! Named textures (float and spectrum kept apart, as in pbrt) and a cache of
//! loaded images so that textures sharing a file share its texels.

use super::image::{ColorEncoding, TexImage};
use super::{FloatTexture, SpectrumTexture};
use lowdisc_image::ImageError;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Why a texture could not be built.
#[derive(Clone, Debug, PartialEq)]
pub enum TextureError {
    /// Reading the image failed.
    Image(ImageError),
    /// The `wrap` parameter is not repeat, clamp or black.
    UnknownWrap(String),
    /// The `encoding` parameter is not sRGB, linear or `gamma G`.
    UnknownEncoding(String),
    /// A named texture does not exist (kind and name).
    Missing(&'static str, String),
}

impl std::fmt::Display for TextureError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            TextureError::Image(e) => write!(f, "{e}"),
            TextureError::UnknownWrap(w) => write!(f, "unknown texture wrap mode \"{w}\""),
            TextureError::UnknownEncoding(e) => write!(f, "unknown texture encoding \"{e}\""),
            TextureError::Missing(kind, name) => {
                write!(f, "{kind} texture \"{name}\" is not defined")
            }
        }
    }
}

impl std::error::Error for TextureError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            TextureError::Image(e) => Some(e),
            _ => None,
        }
    }
}

impl From<ImageError> for TextureError {
    fn from(e: ImageError) -> Self {
        TextureError::Image(e)
    }
}

/// The key of a cached image: the file and how its codes are decoded.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
struct ImageKey {
    path: PathBuf,
    /// The encoding, as a string (gamma values are floats).
    encoding: String,
}

/// Float and spectrum textures by name, plus the image cache.
#[derive(Clone, Debug, Default)]
pub struct TextureRegistry {
    float: HashMap<String, FloatTexture>,
    spectrum: HashMap<String, SpectrumTexture>,
    images: HashMap<ImageKey, Arc<TexImage>>,
}

impl TextureRegistry {
    /// An empty registry.
    pub fn new() -> TextureRegistry {
        TextureRegistry::default()
    }

    /// Defines (or redefines) a float texture; returns the one it replaces,
    /// so the caller can warn as pbrt does.
    pub fn add_float(&mut self, name: &str, tex: FloatTexture) -> Option<FloatTexture> {
        self.float.insert(name.to_string(), tex)
    }
    /// Defines (or redefines) a spectrum texture; returns the one it replaces.
    pub fn add_spectrum(&mut self, name: &str, tex: SpectrumTexture) -> Option<SpectrumTexture> {
        self.spectrum.insert(name.to_string(), tex)
    }

    /// The float texture `name`.
    pub fn float(&self, name: &str) -> Option<FloatTexture> {
        self.float.get(name).cloned()
    }
    /// The spectrum texture `name`.
    pub fn spectrum(&self, name: &str) -> Option<SpectrumTexture> {
        self.spectrum.get(name).cloned()
    }
    /// The float texture `name`, or an error naming it.
    pub fn require_float(&self, name: &str) -> Result<FloatTexture, TextureError> {
        self.float(name)
            .ok_or_else(|| TextureError::Missing("float", name.to_string()))
    }
    /// The spectrum texture `name`, or an error naming it.
    pub fn require_spectrum(&self, name: &str) -> Result<SpectrumTexture, TextureError> {
        self.spectrum(name)
            .ok_or_else(|| TextureError::Missing("spectrum", name.to_string()))
    }

    /// Number of float and spectrum textures defined.
    pub fn len(&self) -> usize {
        self.float.len() + self.spectrum.len()
    }
    /// True when no texture is defined.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// Number of distinct images loaded.
    pub fn image_count(&self) -> usize {
        self.images.len()
    }

    /// Loads an image once per (file, encoding), decoded as pbrt-v4 decodes
    /// it when the texture declares `encoding` ([`ColorEncoding::for_file`]:
    /// only PNG files obey it; `None` is pbrt-v4's default).
    pub fn load_image(
        &mut self,
        path: &Path,
        encoding: Option<ColorEncoding>,
    ) -> Result<Arc<TexImage>, TextureError> {
        let encoding = ColorEncoding::for_file(path, encoding);
        let key = ImageKey {
            path: path.to_path_buf(),
            encoding: format!("{encoding:?}"),
        };
        if let Some(img) = self.images.get(&key) {
            return Ok(img.clone());
        }
        let img = Arc::new(TexImage::load(path, encoding)?);
        self.images.insert(key, img.clone());
        Ok(img)
    }
}
