//! Building image environment lights from [`lowdisc_image`] images and files.

use super::{EnvLayout, EnvLookup, ImageInfiniteLight, LightError};
use crate::math::Transform;
use crate::spectrum::Rgb;
use lowdisc_image::RgbImage;
use std::path::Path;

impl ImageInfiniteLight {
    /// An environment light from a linear RGB image (row 0 at the top); see
    /// [`ImageInfiniteLight::new`] for the other parameters.
    pub fn from_image(
        light_to_world: &Transform,
        image: &RgbImage,
        layout: Option<EnvLayout>,
        lookup: EnvLookup,
        scale: f32,
        illuminance: Option<f32>,
    ) -> Result<Self, LightError> {
        let pixels = image.pixels().iter().map(|&p| Rgb::from_array(p)).collect();
        Self::new(
            light_to_world,
            image.width(),
            image.height(),
            pixels,
            layout,
            lookup,
            scale,
            illuminance,
        )
    }

    /// An environment light from an image file (EXR, HDR, PFM, PNG, TGA).
    pub fn from_file(
        light_to_world: &Transform,
        path: &Path,
        layout: Option<EnvLayout>,
        lookup: EnvLookup,
        scale: f32,
        illuminance: Option<f32>,
    ) -> Result<Self, LightError> {
        let image = lowdisc_image::read_image(path).map_err(|e| LightError::ImageFile {
            path: path.to_path_buf(),
            message: e.to_string(),
        })?;
        Self::from_image(light_to_world, &image, layout, lookup, scale, illuminance)
    }
}
