//! Pixel reconstruction filters (pbrt-v4's `PixelFilter`) and their
//! importance sampling.
//!
//! Like pbrt-v4, the film does not splat a sample to its neighbours: the
//! camera ray's film position is offset from the pixel centre by a sample of
//! the filter (density proportional to `|f|`) and the sample is added to the
//! pixel it was generated for with weight `f / pdf`. For a positive filter
//! that weight is a constant (the filter's integral), so the pixel value
//! `Σ w L / Σ w` is the plain mean of the samples, distributed as the filter.
//!
//! * box (radius 0.5): uniform offsets, weight `4 rx ry`;
//! * triangle (radius 2): the separable tent, sampled exactly, weight `rx² ry²`;
//! * gaussian (radius 1.5, sigma 0.5): `(g(x) - g(r))⁺ (g(y) - g(r))⁺` with `g`
//!   the normal density, i.e. with the tail subtracted (pbrt-v4);
//! * mitchell (radius 2, B = C = 1/3) and lanczos/sinc (radius 4, tau 3): these
//!   and the gaussian are sampled from a [`table::FilterTable`]; the negative
//!   lobes give negative weights.

pub mod table;

use crate::content_hash::{ContentHash, ContentSink};
use std::f64::consts::PI;
use table::FilterTable;

/// Why a filter could not be built.
#[derive(Clone, Debug, PartialEq)]
pub enum FilterError {
    /// The filter name is not one of box, gaussian, triangle, mitchell, sinc/lanczos.
    UnknownFilter(String),
    /// A parameter is out of range (name and value).
    InvalidParameter(&'static str, f32),
}

impl std::fmt::Display for FilterError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FilterError::UnknownFilter(n) => write!(f, "unknown pixel filter \"{n}\""),
            FilterError::InvalidParameter(n, v) => {
                write!(f, "invalid pixel filter parameter \"{n}\": {v}")
            }
        }
    }
}

impl std::error::Error for FilterError {}

/// A sampled filter offset with its weight `f(offset) / pdf(offset)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FilterSample {
    /// Offset from the pixel centre, in pixels, within the filter radius.
    pub offset: [f32; 2],
    /// `f / pdf` (may be negative for filters with negative lobes).
    pub weight: f32,
}

/// The optional parameters of pbrt's `PixelFilter` directive; `None` takes
/// the named filter's default.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FilterParams {
    /// `xradius`.
    pub x_radius: Option<f32>,
    /// `yradius`.
    pub y_radius: Option<f32>,
    /// `sigma` (gaussian).
    pub sigma: Option<f32>,
    /// `B` (mitchell).
    pub b: Option<f32>,
    /// `C` (mitchell).
    pub c: Option<f32>,
    /// `tau` (sinc).
    pub tau: Option<f32>,
}

/// A pixel reconstruction filter.
#[derive(Clone, Debug)]
pub enum Filter {
    /// Constant 1 inside the radius.
    Box {
        /// Radius per axis.
        radius: [f32; 2],
    },
    /// Separable tent `(rx - |x|)⁺ (ry - |y|)⁺`.
    Triangle {
        /// Radius per axis.
        radius: [f32; 2],
    },
    /// Separable Gaussian with the value at the radius subtracted.
    Gaussian {
        /// Radius per axis.
        radius: [f32; 2],
        /// Standard deviation.
        sigma: f32,
        /// Tabulated sampler.
        table: Box<FilterTable>,
    },
    /// Mitchell-Netravali cubic.
    Mitchell {
        /// Radius per axis.
        radius: [f32; 2],
        /// `B`.
        b: f32,
        /// `C`.
        c: f32,
        /// Tabulated sampler.
        table: Box<FilterTable>,
    },
    /// Windowed sinc `sinc(x) sinc(x / tau)`.
    Lanczos {
        /// Radius per axis.
        radius: [f32; 2],
        /// Window parameter.
        tau: f32,
        /// Tabulated sampler.
        table: Box<FilterTable>,
    },
}

impl Default for Filter {
    /// pbrt-v4's default pixel filter: gaussian, radius 1.5, sigma 0.5.
    fn default() -> Self {
        Filter::gaussian([1.5, 1.5], 0.5).unwrap_or(Filter::Box { radius: [0.5, 0.5] })
    }
}

fn check_radius(radius: [f32; 2]) -> Result<[f32; 2], FilterError> {
    for (name, r) in [("xradius", radius[0]), ("yradius", radius[1])] {
        // Beyond 64 pixels the tabulated samplers would be needlessly huge.
        if !(r > 0.0 && r <= 64.0) {
            return Err(FilterError::InvalidParameter(name, r));
        }
    }
    Ok(radius)
}

impl Filter {
    /// A box filter.
    pub fn box_filter(radius: [f32; 2]) -> Result<Filter, FilterError> {
        Ok(Filter::Box {
            radius: check_radius(radius)?,
        })
    }
    /// A triangle filter.
    pub fn triangle(radius: [f32; 2]) -> Result<Filter, FilterError> {
        Ok(Filter::Triangle {
            radius: check_radius(radius)?,
        })
    }
    /// A Gaussian filter (pbrt-v4 normalisation: tail subtracted).
    pub fn gaussian(radius: [f32; 2], sigma: f32) -> Result<Filter, FilterError> {
        let radius = check_radius(radius)?;
        if !(sigma > 0.0 && sigma.is_finite()) {
            return Err(FilterError::InvalidParameter("sigma", sigma));
        }
        let table = Box::new(FilterTable::new(radius, |x, y| {
            gaussian_2d(x, y, radius, sigma)
        }));
        Ok(Filter::Gaussian {
            radius,
            sigma,
            table,
        })
    }
    /// A Mitchell-Netravali filter.
    pub fn mitchell(radius: [f32; 2], b: f32, c: f32) -> Result<Filter, FilterError> {
        let radius = check_radius(radius)?;
        for (name, v) in [("B", b), ("C", c)] {
            if !v.is_finite() {
                return Err(FilterError::InvalidParameter(name, v));
            }
        }
        let table = Box::new(FilterTable::new(radius, |x, y| {
            mitchell_1d(2.0 * x / radius[0], b, c) * mitchell_1d(2.0 * y / radius[1], b, c)
        }));
        Ok(Filter::Mitchell {
            radius,
            b,
            c,
            table,
        })
    }
    /// A Lanczos (windowed sinc) filter.
    pub fn lanczos(radius: [f32; 2], tau: f32) -> Result<Filter, FilterError> {
        let radius = check_radius(radius)?;
        if !(tau > 0.0 && tau.is_finite()) {
            return Err(FilterError::InvalidParameter("tau", tau));
        }
        let table = Box::new(FilterTable::new(radius, |x, y| {
            windowed_sinc(x, radius[0], tau) * windowed_sinc(y, radius[1], tau)
        }));
        Ok(Filter::Lanczos { radius, tau, table })
    }

    /// The filter named as in pbrt's `PixelFilter` directive (`box`,
    /// `gaussian`, `triangle`, `mitchell`, `sinc` or `lanczos`), with pbrt-v4's
    /// defaults for parameters not given.
    pub fn create(name: &str, p: &FilterParams) -> Result<Filter, FilterError> {
        let r = |d: f32| [p.x_radius.unwrap_or(d), p.y_radius.unwrap_or(d)];
        match name {
            "box" => Filter::box_filter(r(0.5)),
            "triangle" => Filter::triangle(r(2.0)),
            "gaussian" => Filter::gaussian(r(1.5), p.sigma.unwrap_or(0.5)),
            "mitchell" => {
                Filter::mitchell(r(2.0), p.b.unwrap_or(1.0 / 3.0), p.c.unwrap_or(1.0 / 3.0))
            }
            "sinc" | "lanczos" => Filter::lanczos(r(4.0), p.tau.unwrap_or(3.0)),
            other => Err(FilterError::UnknownFilter(other.to_string())),
        }
    }

    /// The radius per axis.
    pub fn radius(&self) -> [f32; 2] {
        match self {
            Filter::Box { radius }
            | Filter::Triangle { radius }
            | Filter::Gaussian { radius, .. }
            | Filter::Mitchell { radius, .. }
            | Filter::Lanczos { radius, .. } => *radius,
        }
    }

    /// The filter value at offset `p` from the pixel centre.
    pub fn evaluate(&self, p: [f32; 2]) -> f32 {
        match self {
            Filter::Box { radius } => {
                if p[0].abs() <= radius[0] && p[1].abs() <= radius[1] {
                    1.0
                } else {
                    0.0
                }
            }
            Filter::Triangle { radius } => {
                (radius[0] - p[0].abs()).max(0.0) * (radius[1] - p[1].abs()).max(0.0)
            }
            Filter::Gaussian { radius, sigma, .. } => gaussian_2d(p[0], p[1], *radius, *sigma),
            Filter::Mitchell { radius, b, c, .. } => {
                if p[0].abs() > radius[0] || p[1].abs() > radius[1] {
                    return 0.0;
                }
                mitchell_1d(2.0 * p[0] / radius[0], *b, *c)
                    * mitchell_1d(2.0 * p[1] / radius[1], *b, *c)
            }
            Filter::Lanczos { radius, tau, .. } => {
                windowed_sinc(p[0], radius[0], *tau) * windowed_sinc(p[1], radius[1], *tau)
            }
        }
    }

    /// The exact integral of the filter over the plane (numerical, to about
    /// 1e-7 relative, for the windowed sinc).
    pub fn integral(&self) -> f64 {
        match self {
            Filter::Box { radius } => 4.0 * f64::from(radius[0]) * f64::from(radius[1]),
            Filter::Triangle { radius } => {
                f64::from(radius[0]).powi(2) * f64::from(radius[1]).powi(2)
            }
            Filter::Gaussian { radius, sigma, .. } => {
                gaussian_integral_1d(radius[0], *sigma) * gaussian_integral_1d(radius[1], *sigma)
            }
            Filter::Mitchell { radius, .. } => f64::from(radius[0]) * f64::from(radius[1]) / 4.0,
            Filter::Lanczos { radius, tau, .. } => {
                let one = |r: f32| {
                    midpoint(
                        |x| f64::from(windowed_sinc(x as f32, r, *tau)),
                        -f64::from(r),
                        f64::from(r),
                    )
                };
                one(radius[0]) * one(radius[1])
            }
        }
    }

    /// Importance-samples an offset with density proportional to `|f|`
    /// (piecewise constant for the tabulated filters) from `u` in `[0,1)^2`.
    #[inline]
    pub fn sample(&self, u: [f32; 2]) -> FilterSample {
        match self {
            Filter::Box { radius } => FilterSample {
                offset: [
                    -radius[0] + 2.0 * radius[0] * u[0],
                    -radius[1] + 2.0 * radius[1] * u[1],
                ],
                weight: 4.0 * radius[0] * radius[1],
            },
            Filter::Triangle { radius } => FilterSample {
                offset: [sample_tent(u[0], radius[0]), sample_tent(u[1], radius[1])],
                weight: radius[0] * radius[0] * radius[1] * radius[1],
            },
            Filter::Gaussian { table, .. }
            | Filter::Mitchell { table, .. }
            | Filter::Lanczos { table, .. } => {
                let (offset, weight) = table.sample(u);
                FilterSample { offset, weight }
            }
        }
    }

    /// The density of [`Self::sample`] at offset `p` (per unit area).
    pub fn pdf(&self, p: [f32; 2]) -> f32 {
        let r = self.radius();
        if !(p[0].abs() <= r[0] && p[1].abs() <= r[1]) {
            return 0.0;
        }
        match self {
            Filter::Box { radius } => 1.0 / (4.0 * radius[0] * radius[1]),
            Filter::Triangle { radius } => {
                self.evaluate(p) / (radius[0] * radius[0] * radius[1] * radius[1])
            }
            Filter::Gaussian { table, .. }
            | Filter::Mitchell { table, .. }
            | Filter::Lanczos { table, .. } => table.pdf(p),
        }
    }
}

/// The normal density with mean 0 and deviation `sigma`.
fn gaussian(x: f32, sigma: f32) -> f32 {
    let s = f64::from(sigma);
    ((-f64::from(x) * f64::from(x) / (2.0 * s * s)).exp() / (2.0 * PI * s * s).sqrt()) as f32
}

fn gaussian_2d(x: f32, y: f32, radius: [f32; 2], sigma: f32) -> f32 {
    (gaussian(x, sigma) - gaussian(radius[0], sigma)).max(0.0)
        * (gaussian(y, sigma) - gaussian(radius[1], sigma)).max(0.0)
}

/// `∫_{-r}^{r} (g(x) - g(r)) dx`, numerically.
fn gaussian_integral_1d(r: f32, sigma: f32) -> f64 {
    let s = f64::from(sigma);
    let g = |x: f64| (-x * x / (2.0 * s * s)).exp() / (2.0 * PI * s * s).sqrt();
    let r = f64::from(r);
    midpoint(g, -r, r) - 2.0 * r * g(r)
}

/// Composite midpoint rule with 8192 intervals (error ~1e-8 relative for the
/// smooth integrands here).
fn midpoint(f: impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    const N: usize = 8192;
    let h = (b - a) / N as f64;
    (0..N).map(|i| f(a + (i as f64 + 0.5) * h)).sum::<f64>() * h
}

/// The Mitchell-Netravali cubic on `[-2, 2]` (Mitchell & Netravali 1988).
fn mitchell_1d(x: f32, b: f32, c: f32) -> f32 {
    let x = x.abs();
    if x <= 1.0 {
        ((12.0 - 9.0 * b - 6.0 * c) * x * x * x
            + (-18.0 + 12.0 * b + 6.0 * c) * x * x
            + (6.0 - 2.0 * b))
            / 6.0
    } else if x <= 2.0 {
        ((-b - 6.0 * c) * x * x * x
            + (6.0 * b + 30.0 * c) * x * x
            + (-12.0 * b - 48.0 * c) * x
            + (8.0 * b + 24.0 * c))
            / 6.0
    } else {
        0.0
    }
}

/// `sin(πx) / (πx)`.
fn sinc(x: f32) -> f32 {
    let px = std::f32::consts::PI * x;
    if px.abs() < 1e-4 {
        1.0 - px * px / 6.0
    } else {
        px.sin() / px
    }
}

fn windowed_sinc(x: f32, radius: f32, tau: f32) -> f32 {
    if x.abs() > radius {
        0.0
    } else {
        sinc(x) * sinc(x / tau)
    }
}

/// Samples the tent `(r - |x|)⁺` from `u` in `[0,1)`: the left half for
/// `u < 1/2`, the right half otherwise, each by inverting its linear CDF.
fn sample_tent(u: f32, r: f32) -> f32 {
    if u < 0.5 {
        let v = 2.0 * u;
        -r + r * v.sqrt()
    } else {
        let v = (2.0 * u - 1.0).min(1.0);
        r * (1.0 - (1.0 - v).sqrt())
    }
}

/// The tabulated samplers are derived from the fed parameters.
impl ContentHash for Filter {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        match self {
            Filter::Box { radius } => (0u8, radius).feed(sink),
            Filter::Triangle { radius } => (1u8, radius).feed(sink),
            Filter::Gaussian {
                radius,
                sigma,
                table: _,
            } => (2u8, radius, sigma).feed(sink),
            Filter::Mitchell {
                radius,
                b,
                c,
                table: _,
            } => (3u8, radius, b, c).feed(sink),
            Filter::Lanczos {
                radius,
                tau,
                table: _,
            } => (4u8, radius, tau).feed(sink),
        }
    }
}
