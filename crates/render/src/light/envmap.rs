//! Image environment light in pbrt-v4's equal-area octahedral layout or the
//! lat-long (equirectangular) layout, importance-sampled by pixel brightness.
//!
//! Layouts (directions in light space, `+z` up):
//! * [`EnvLayout::EqualArea`]: square images; `uv` is Clarberg's equal-area
//!   octahedral map of the direction (pbrt-v4's environment-map layout). The
//!   map preserves area, so a density on the square becomes a density on the
//!   sphere by dividing by `4π`.
//! * [`EnvLayout::LatLong`]: `u = φ / 2π` (φ from `+x` towards `+y`),
//!   `v = θ / π` (θ from `+z`, row 0 at the top), as pbrt-v3 used. A density
//!   on the square becomes one on the sphere by dividing by `2π² sin θ`; the
//!   sampling distribution is weighted by `sin θ` accordingly.
//!
//! Radiance is looked up per pixel ([`EnvLookup::Nearest`], pbrt-v4's
//! choice, for which the sampling density is exactly proportional to the
//! pixel average) or bilinearly ([`EnvLookup::Bilinear`]; the equal-area
//! layout then wraps across its folded edges, lat-long wraps in `u`). For
//! bilinear lookups each pixel's sampling weight is the largest pixel average
//! of its 3×3 (wrapped) neighbourhood, so every direction with radiance keeps
//! a positive density.

use super::error::check_scalar;
use super::{LightError, LightLiSample, LightSampleContext, SceneSphere, luminance_normaliser};
use crate::content_hash::{ContentHash, ContentSink};
use crate::math::spherical::{
    equal_area_sphere_to_square, equal_area_square_to_sphere, spherical_direction, spherical_phi,
    spherical_theta,
};
use crate::math::{Bounds3, Point2, Ray, Transform, Vec3};
use crate::sampling::Distribution2D;
use crate::spectrum::Rgb;
use std::f32::consts::PI;

/// How an environment image maps to directions.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EnvLayout {
    /// pbrt-v4's equal-area octahedral layout (square images).
    EqualArea,
    /// Latitude-longitude (equirectangular), usually 2:1.
    LatLong,
}

impl EnvLayout {
    /// The layout implied by an image's shape: square means equal-area,
    /// 2:1 means lat-long; anything else is an error.
    pub fn detect(width: usize, height: usize) -> Result<EnvLayout, LightError> {
        match (width, height) {
            (w, h) if w > 0 && w == h => Ok(EnvLayout::EqualArea),
            (w, h) if h > 0 && w == 2 * h => Ok(EnvLayout::LatLong),
            _ => Err(LightError::InvalidImage(format!(
                "{width}x{height} is neither square (equal-area) nor 2:1 (lat-long); choose a layout explicitly"
            ))),
        }
    }
    /// Image coordinates in `[0,1]^2` of a unit light-space direction.
    pub fn direction_to_uv(self, w: Vec3) -> Point2 {
        match self {
            EnvLayout::EqualArea => equal_area_sphere_to_square(w),
            EnvLayout::LatLong => {
                Point2::new(spherical_phi(w) / (2.0 * PI), spherical_theta(w) / PI)
            }
        }
    }
    /// The unit light-space direction of image coordinates `uv`.
    pub fn uv_to_direction(self, uv: Point2) -> Vec3 {
        match self {
            EnvLayout::EqualArea => equal_area_square_to_sphere(uv),
            EnvLayout::LatLong => {
                let theta = uv.y * PI;
                spherical_direction(theta.sin(), theta.cos(), uv.x * 2.0 * PI)
            }
        }
    }
    /// `dω / d(u,v)` at direction `w`: density on the square divided by this
    /// is density per steradian.
    pub fn jacobian(self, w: Vec3) -> f32 {
        match self {
            EnvLayout::EqualArea => 4.0 * PI,
            EnvLayout::LatLong => 2.0 * PI * PI * (1.0 - w.z * w.z).max(0.0).sqrt(),
        }
    }
}

/// How radiance is read from the image.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum EnvLookup {
    /// The pixel holding the direction (pbrt-v4's choice).
    #[default]
    Nearest,
    /// Bilinear interpolation of the four nearest pixel centres.
    Bilinear,
}

/// Maps a pixel position that may lie one step outside a square equal-area
/// image back inside: crossing an edge of the octahedral layout continues on
/// the same edge mirrored about its midpoint (each edge is folded there), so
/// `x = -1` becomes `x = 0` with `y` reflected, and likewise on every side.
pub fn wrap_equal_area_pixel(x: i64, y: i64, width: usize, height: usize) -> (usize, usize) {
    let (w, h) = (width as i64, height as i64);
    let (mut x, mut y) = (x, y);
    if x < 0 {
        x = -1 - x;
        y = h - 1 - y;
    } else if x >= w {
        x = 2 * w - 1 - x;
        y = h - 1 - y;
    }
    if y < 0 {
        x = w - 1 - x;
        y = -1 - y;
    } else if y >= h {
        x = w - 1 - x;
        y = 2 * h - 1 - y;
    }
    (x.clamp(0, w - 1) as usize, y.clamp(0, h - 1) as usize)
}

/// pbrt-v4's `LightSource "infinite"` with an image.
#[derive(Clone, Debug)]
pub struct ImageInfiniteLight {
    light_to_world: Transform,
    world_to_light: Transform,
    layout: EnvLayout,
    lookup: EnvLookup,
    width: usize,
    height: usize,
    /// Row-major radiance, `scale` applied, negatives and non-finite values zeroed.
    pixels: Vec<Rgb>,
    distribution: Distribution2D,
    scene: SceneSphere,
}

impl ImageInfiniteLight {
    /// An environment light from a `width × height` row-major image.
    /// `layout = None` detects it from the shape ([`EnvLayout::detect`]).
    /// With `illuminance = Some(e)` the radiance is rescaled so that the
    /// luminance of the irradiance on an upward (`+z` in light space) facing,
    /// unoccluded surface is `e`.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        light_to_world: &Transform,
        width: usize,
        height: usize,
        pixels: Vec<Rgb>,
        layout: Option<EnvLayout>,
        lookup: EnvLookup,
        scale: f32,
        illuminance: Option<f32>,
    ) -> Result<Self, LightError> {
        check_scalar("scale", scale)?;
        if width == 0 || height == 0 || width.checked_mul(height) != Some(pixels.len()) {
            return Err(LightError::InvalidImage(format!(
                "{} pixels do not make a {width}x{height} image",
                pixels.len()
            )));
        }
        let layout = match layout {
            Some(l) => l,
            None => EnvLayout::detect(width, height)?,
        };
        if layout == EnvLayout::EqualArea && width != height {
            return Err(LightError::InvalidImage(format!(
                "equal-area maps are square, got {width}x{height}"
            )));
        }
        let clean = |x: f32| {
            if x.is_finite() && x > 0.0 {
                x * scale
            } else {
                0.0
            }
        };
        let mut light = ImageInfiniteLight {
            light_to_world: *light_to_world,
            world_to_light: light_to_world.inverse(),
            layout,
            lookup,
            width,
            height,
            pixels: pixels.into_iter().map(|c| c.map(clean)).collect(),
            distribution: Distribution2D::new(&[0.0], 1, 1).expect("a 1x1 grid is valid"),
            scene: SceneSphere::default(),
        };
        let k = luminance_normaliser(light.upper_irradiance(), 1.0, illuminance);
        if k != 1.0 {
            light.pixels.iter_mut().for_each(|c| *c *= k);
        }
        let weights = light.sampling_weights();
        light.distribution = Distribution2D::new(&weights, width, height).ok_or_else(|| {
            LightError::InvalidImage("cannot build the sampling distribution".into())
        })?;
        Ok(light)
    }

    /// The layout in use.
    pub fn layout(&self) -> EnvLayout {
        self.layout
    }
    /// Image size `(width, height)`.
    pub fn resolution(&self) -> (usize, usize) {
        (self.width, self.height)
    }
    /// The sampling distribution over the image square.
    pub fn distribution(&self) -> &Distribution2D {
        &self.distribution
    }

    fn pixel(&self, x: usize, y: usize) -> Rgb {
        self.pixels[y * self.width + x]
    }

    /// Pixel `(x, y)` where the coordinates may be one step outside the image.
    fn texel(&self, x: i64, y: i64) -> Rgb {
        let (x, y) = match self.layout {
            EnvLayout::EqualArea => wrap_equal_area_pixel(x, y, self.width, self.height),
            EnvLayout::LatLong => (
                x.rem_euclid(self.width as i64) as usize,
                y.clamp(0, self.height as i64 - 1) as usize,
            ),
        };
        self.pixel(x, y)
    }

    /// Radiance at image coordinates `uv` with the configured lookup.
    pub fn lookup_uv(&self, uv: Point2) -> Rgb {
        let (fx, fy) = (uv.x * self.width as f32, uv.y * self.height as f32);
        match self.lookup {
            EnvLookup::Nearest => {
                let x = if fx > 0.0 {
                    (fx as usize).min(self.width - 1)
                } else {
                    0
                };
                let y = if fy > 0.0 {
                    (fy as usize).min(self.height - 1)
                } else {
                    0
                };
                self.pixel(x, y)
            }
            EnvLookup::Bilinear => {
                let (fx, fy) = (fx - 0.5, fy - 0.5);
                let (x0, y0) = (fx.floor(), fy.floor());
                let (dx, dy) = (fx - x0, fy - y0);
                let (x0, y0) = (x0 as i64, y0 as i64);
                self.texel(x0, y0) * ((1.0 - dx) * (1.0 - dy))
                    + self.texel(x0 + 1, y0) * (dx * (1.0 - dy))
                    + self.texel(x0, y0 + 1) * ((1.0 - dx) * dy)
                    + self.texel(x0 + 1, y0 + 1) * (dx * dy)
            }
        }
    }

    /// Radiance arriving from world direction `w` (not necessarily unit).
    pub fn radiance_from(&self, w: Vec3) -> Rgb {
        let wl = self.world_to_light.vector(w).normalize();
        if !wl.is_finite() {
            return Rgb::ZERO;
        }
        self.lookup_uv(self.layout.direction_to_uv(wl))
    }

    /// Solid angle of pixel row `y` per pixel, and the direction of pixel `(x, y)`'s centre.
    fn pixel_solid_angle(&self, y: usize) -> f32 {
        match self.layout {
            EnvLayout::EqualArea => 4.0 * PI / (self.width * self.height) as f32,
            EnvLayout::LatLong => {
                let t0 = y as f32 / self.height as f32 * PI;
                let t1 = (y + 1) as f32 / self.height as f32 * PI;
                2.0 * PI / self.width as f32 * (t0.cos() - t1.cos())
            }
        }
    }
    fn pixel_direction(&self, x: usize, y: usize) -> Vec3 {
        let uv = Point2::new(
            (x as f32 + 0.5) / self.width as f32,
            (y as f32 + 0.5) / self.height as f32,
        );
        self.layout.uv_to_direction(uv)
    }

    /// `∫ L(ω) dω` over the sphere, by pixel (midpoint rule).
    fn radiance_integral(&self) -> Rgb {
        let mut sum = [0.0f64; 3];
        for y in 0..self.height {
            let dw = self.pixel_solid_angle(y) as f64;
            for x in 0..self.width {
                let c = self.pixel(x, y);
                (0..3).for_each(|i| sum[i] += c[i] as f64 * dw);
            }
        }
        Rgb::new(sum[0] as f32, sum[1] as f32, sum[2] as f32)
    }

    /// Irradiance on an unoccluded surface facing light-space `+z`.
    fn upper_irradiance(&self) -> Rgb {
        let mut sum = [0.0f64; 3];
        for y in 0..self.height {
            let dw = self.pixel_solid_angle(y) as f64;
            for x in 0..self.width {
                let cos = self.pixel_direction(x, y).z.max(0.0) as f64;
                let c = self.pixel(x, y);
                (0..3).for_each(|i| sum[i] += c[i] as f64 * cos * dw);
            }
        }
        Rgb::new(sum[0] as f32, sum[1] as f32, sum[2] as f32)
    }

    /// Per-pixel sampling weights (see the module notes).
    fn sampling_weights(&self) -> Vec<f32> {
        let (w, h) = (self.width, self.height);
        let avg: Vec<f32> = self.pixels.iter().map(|c| c.average()).collect();
        let mut out = Vec::with_capacity(w * h);
        for y in 0..h {
            let row_weight = match self.layout {
                EnvLayout::EqualArea => 1.0,
                EnvLayout::LatLong => ((y as f32 + 0.5) / h as f32 * PI).sin(),
            };
            for x in 0..w {
                let v = match self.lookup {
                    EnvLookup::Nearest => avg[y * w + x],
                    EnvLookup::Bilinear => {
                        let mut m = 0.0f32;
                        for dy in -1..=1 {
                            for dx in -1..=1 {
                                m = m.max(self.texel(x as i64 + dx, y as i64 + dy).average());
                            }
                        }
                        m
                    }
                };
                out.push(v * row_weight);
            }
        }
        out
    }

    pub(crate) fn preprocess(&mut self, b: &Bounds3) {
        self.scene = SceneSphere::from_bounds(b);
    }

    pub(crate) fn sample_li(&self, ctx: &LightSampleContext, u: [f32; 2]) -> Option<LightLiSample> {
        let (uv, pdf_uv) = self.distribution.sample(u);
        let wl = self.layout.uv_to_direction(uv);
        let jac = self.layout.jacobian(wl);
        if !(pdf_uv > 0.0 && jac > 0.0) {
            return None;
        }
        let wi = self.light_to_world.vector(wl).normalize();
        Some(LightLiSample {
            l: self.lookup_uv(uv),
            wi,
            pdf: pdf_uv / jac,
            p_light: self.scene.beyond(ctx.p, wi),
            n_light: Vec3::ZERO,
            is_delta: false,
        })
    }

    pub(crate) fn pdf_li(&self, _ctx: &LightSampleContext, wi: Vec3) -> f32 {
        let wl = self.world_to_light.vector(wi).normalize();
        let jac = self.layout.jacobian(wl);
        if !(jac > 0.0) || !wl.is_finite() {
            return 0.0;
        }
        self.distribution.pdf(self.layout.direction_to_uv(wl)) / jac
    }

    pub(crate) fn le(&self, ray: &Ray) -> Rgb {
        self.radiance_from(ray.d)
    }

    pub(crate) fn phi(&self) -> Rgb {
        self.radiance_integral() * (PI * self.scene.radius * self.scene.radius)
    }
}

impl ContentHash for EnvLayout {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let tag: u8 = match self {
            EnvLayout::EqualArea => 0,
            EnvLayout::LatLong => 1,
        };
        tag.feed(sink);
    }
}

impl ContentHash for EnvLookup {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let tag: u8 = match self {
            EnvLookup::Nearest => 0,
            EnvLookup::Bilinear => 1,
        };
        tag.feed(sink);
    }
}

/// The inverse transform and the sampling distribution are derived from
/// the fed fields, the scene's bounding sphere from the shapes.
impl ContentHash for ImageInfiniteLight {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let ImageInfiniteLight {
            light_to_world,
            world_to_light: _,
            layout,
            lookup,
            width,
            height,
            pixels,
            distribution: _,
            scene: _,
        } = self;
        (light_to_world, layout, lookup, [width, height], pixels).feed(sink);
    }
}
