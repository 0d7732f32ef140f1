//! Colour science for spectral rendering, in one place:
//!
//! * [`cie`]: the CIE 1931 2° colour-matching functions (1 nm tables), the
//!   CIE standard illuminant D65 and the CIE daylight series `D(T)`, as
//!   published by the CIE (data files in `data/`, each naming its source);
//! * [`matrix`]: 3x3 matrices, XYZ↔RGB for a colour space given by its
//!   primaries and white, and von Kries white balance in Bradford's cone
//!   space (what pbrt-v4's `rgb` film does when `whitebalance` is set);
//! * [`sigmoid`]: Jakob & Hanika's (2019) RGB-to-spectrum uplift: a
//!   spectrum `S(λ) = σ(c0 λ² + c1 λ + c2)` per RGB reflectance, fitted by a
//!   Gauss-Newton optimiser of this crate over a grid of the RGB cube, and
//!   the table's trilinear lookup.
//!
//! Wavelengths are in nanometres throughout. The library never prints.

// The numeric code indexes several parallel arrays (matching functions,
// weights, lanes) with one index; iterators would obscure it.
#![allow(clippy::needless_range_loop)]

pub mod cie;
pub mod matrix;
pub mod sigmoid;

pub use cie::{CIE_Y_INTEGRAL, LAMBDA_MAX, LAMBDA_MIN};
pub use matrix::{Mat3, srgb};
pub use sigmoid::{SigmoidTable, sigmoid};
