//! Errors from building lights.

use std::path::PathBuf;

/// Why a light could not be built.
#[derive(Debug)]
pub enum LightError {
    /// A parameter is out of range or not finite.
    InvalidParameter(String),
    /// An environment image has unusable dimensions or data.
    InvalidImage(String),
    /// An environment image file could not be read.
    ImageFile {
        /// The file.
        path: PathBuf,
        /// What went wrong, as reported by the image reader.
        message: String,
    },
}

impl std::fmt::Display for LightError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            LightError::InvalidParameter(m) => write!(f, "invalid light parameter: {m}"),
            LightError::InvalidImage(m) => write!(f, "invalid environment map: {m}"),
            LightError::ImageFile { path, message } => write!(f, "{}: {message}", path.display()),
        }
    }
}

impl std::error::Error for LightError {}

/// Checks that every channel of `c` is finite and non-negative.
pub(crate) fn check_rgb(name: &str, c: crate::spectrum::Rgb) -> Result<(), LightError> {
    if c.is_finite() && c.min_component() >= 0.0 {
        Ok(())
    } else {
        Err(LightError::InvalidParameter(format!(
            "{name} must be finite and non-negative, got {c:?}"
        )))
    }
}

/// Checks that `x` is finite and non-negative.
pub(crate) fn check_scalar(name: &str, x: f32) -> Result<(), LightError> {
    if x.is_finite() && x >= 0.0 {
        Ok(())
    } else {
        Err(LightError::InvalidParameter(format!(
            "{name} must be finite and non-negative, got {x}"
        )))
    }
}
