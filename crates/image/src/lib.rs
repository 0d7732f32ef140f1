//! Linear RGB images for lowdisc.
//!
//! - [`RgbImage`]: `f32` linear RGB, row-major, top row first.
//! - Files ([`io`]): OpenEXR, Radiance HDR, PFM, PNG and TGA input
//!   ([`read_image`]), EXR, PNG (8-bit sRGB with exposure), PFM and HDR output
//!   ([`write_image`]), all written atomically.
//! - Colour ([`color`]): the exact sRGB curve, Rec.709 luminance, 8-bit
//!   quantisation.
//! - Error metrics ([`metrics`]): MSE, relMSE, RMSE and MAE on linear radiance
//!   and on 8-bit sRGB, per-pixel error images; the same over the pixels a
//!   [`PixelMask`] keeps ([`mask`]: directly visible emitters left out); the
//!   blurred (perceptual) error ([`perceptual`]); NVIDIA's FLIP ([`flip`]).
//! - Utilities ([`ops`]): crops, nearest-neighbour upscaling, statistics.
//!   (False-colour heatmaps with a colour bar are `lowdisc-plot`'s.)
//!
//! Nothing here panics on bad input: every failure is an [`ImageError`].

pub mod color;
pub mod error;
pub mod flip;
pub mod image;
pub mod io;
pub mod mask;
pub mod metrics;
pub mod ops;
pub mod perceptual;

pub use color::{luminance, srgb_decode, srgb_encode, srgb8_decode, srgb8_encode, to_srgb8};
pub use error::{ErrorKind, ImageError};
pub use flip::{flip_error, flip_error_map};
pub use image::{MAX_PIXELS, RgbImage};
pub use io::{
    ImageFormat, ReadOptions, Transfer, WriteOptions, decode_image, encode_image, read_image,
    read_image_with, write_atomically, write_exr, write_hdr, write_image, write_pfm, write_png,
};
pub use mask::{DEFAULT_EMITTER_BORDER, PixelMask, masked_error_metrics};
pub use metrics::{ErrorMetrics, ErrorStats, PixelError, error_image, error_metrics, pixel_errors};
pub use ops::{ImageStats, crop, stats, upscale_nearest};
pub use perceptual::blurred_mse;
