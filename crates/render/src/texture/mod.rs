//! pbrt-v4 textures: constant, imagemap, checkerboard, scale and mix, as one
//! generic [`Texture`] over float and RGB ("spectrum") values, evaluated at a surface point's `uv`
//! (and position, for 3-D checkerboards and planar mappings).
//!
//! Evaluation is a point lookup: there are no ray differentials, so image
//! maps are always filtered bilinearly (pbrt's `filter` parameter —
//! `point`, `bilinear`, `trilinear`, `ewa` — only changes aliasing, and is
//! ignored) and checkerboards are not antialiased. As in pbrt-v4:
//! * the image texture flips `t` (`t = 1 - t`) because texture coordinates
//!   start at the bottom-left and image rows at the top;
//! * `scale` multiplies the lookup and `invert` gives `max(0, 1 - v)`;
//!   RGB image lookups are clamped at zero;
//! * a float image texture reads the image's first channel;
//! * the checkerboard picks `tex1` where `floor(s) + floor(t)` is even
//!   (`floor(x) + floor(y) + floor(z)` for the 3-D variant), else `tex2`.
//!
//! Named textures live in a [`TextureRegistry`].

pub mod image;
mod registry;

pub use image::{ColorEncoding, TexImage, WrapMode};
pub use registry::{TextureError, TextureRegistry};

use crate::content_hash::{ContentHash, ContentSink};
use crate::math::{Point2, Point3, Transform, Vec3};
use crate::spectrum::Rgb;
use std::ops::{Add, Mul};
use std::sync::Arc;

/// Where a texture is evaluated.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TextureEvalContext {
    /// World-space position.
    pub p: Point3,
    /// Surface parameterisation.
    pub uv: Point2,
}

/// pbrt-v4's 2-D texture mappings from a surface point to `(s, t)`.
#[derive(Clone, Debug, PartialEq)]
pub enum TextureMapping {
    /// `s = su u + du`, `t = sv v + dv` (`uscale`, `vscale`, `udelta`, `vdelta`).
    Uv {
        /// `uscale`.
        su: f32,
        /// `vscale`.
        sv: f32,
        /// `udelta`.
        du: f32,
        /// `vdelta`.
        dv: f32,
    },
    /// `s = ds + (T p)·vs`, `t = dt + (T p)·vt` with `T` the texture-from-world transform.
    Planar {
        /// Texture-from-world transform (inverse of the CTM at the `Texture` directive).
        texture_from_world: Transform,
        /// `v1`.
        vs: Vec3,
        /// `v2`.
        vt: Vec3,
        /// `udelta`.
        ds: f32,
        /// `vdelta`.
        dt: f32,
    },
}

impl Default for TextureMapping {
    fn default() -> Self {
        TextureMapping::Uv {
            su: 1.0,
            sv: 1.0,
            du: 0.0,
            dv: 0.0,
        }
    }
}

impl TextureMapping {
    /// The texture coordinates `(s, t)` at `ctx`.
    pub fn map(&self, ctx: &TextureEvalContext) -> [f32; 2] {
        match self {
            TextureMapping::Uv { su, sv, du, dv } => [su * ctx.uv.x + du, sv * ctx.uv.y + dv],
            TextureMapping::Planar {
                texture_from_world,
                vs,
                vt,
                ds,
                dt,
            } => {
                let v = texture_from_world.point(ctx.p);
                [ds + v.dot(*vs), dt + v.dot(*vt)]
            }
        }
    }
}

/// The checkerboard's pattern: 2-D over a mapping, or 3-D over texture space.
#[derive(Clone, Debug, PartialEq)]
pub enum Checker {
    /// `floor(s) + floor(t)` parity.
    TwoD(TextureMapping),
    /// `floor(x) + floor(y) + floor(z)` parity of the texture-space point.
    ThreeD(Transform),
}

impl Checker {
    /// True where the first texture shows.
    pub fn is_first(&self, ctx: &TextureEvalContext) -> bool {
        let sum = match self {
            Checker::TwoD(m) => {
                let [s, t] = m.map(ctx);
                s.floor() as i64 + t.floor() as i64
            }
            Checker::ThreeD(tr) => {
                let q = tr.point(ctx.p);
                q.x.floor() as i64 + q.y.floor() as i64 + q.z.floor() as i64
            }
        };
        sum.rem_euclid(2) == 0
    }
}

/// An image lookup with its mapping and pbrt's `wrap`, `scale`, `invert`.
#[derive(Clone, Debug, PartialEq)]
pub struct ImageTexture {
    /// The texels (shared between textures using the same file).
    pub image: Arc<TexImage>,
    /// The mapping.
    pub mapping: TextureMapping,
    /// The wrap mode.
    pub wrap: WrapMode,
    /// Multiplier (`scale`, default 1).
    pub scale: f32,
    /// `invert`: `max(0, 1 - v)`.
    pub invert: bool,
}

impl ImageTexture {
    /// An image texture with the uv mapping, repeat wrap, scale 1, no invert.
    pub fn new(image: Arc<TexImage>) -> ImageTexture {
        ImageTexture {
            image,
            mapping: TextureMapping::default(),
            wrap: WrapMode::Repeat,
            scale: 1.0,
            invert: false,
        }
    }

    fn lookup(&self, ctx: &TextureEvalContext) -> [f32; 3] {
        let [s, t] = self.mapping.map(ctx);
        self.image
            .bilerp([s, 1.0 - t], self.wrap)
            .map(|v| v * self.scale)
    }

    /// The float value (first channel).
    pub fn evaluate_float(&self, ctx: &TextureEvalContext) -> f32 {
        let v = self.lookup(ctx)[0];
        if self.invert { (1.0 - v).max(0.0) } else { v }
    }

    /// The RGB value, clamped at zero.
    pub fn evaluate_rgb(&self, ctx: &TextureEvalContext) -> Rgb {
        let v = Rgb::from_array(self.lookup(ctx));
        let v = if self.invert { Rgb::ONE - v } else { v };
        v.map(|c| c.max(0.0))
    }
}

/// What a texture can return: `f32` (pbrt's float textures) or [`Rgb`]
/// (its spectrum textures). The arithmetic is what `scale` and `mix` need.
pub trait TextureValue:
    Copy + std::fmt::Debug + PartialEq + Mul<f32, Output = Self> + Add<Output = Self>
{
    /// Zero (what `scale` returns for a zero factor).
    const ZERO: Self;
    /// `v` (in every channel).
    fn splat(v: f32) -> Self;
    /// The value of an image texture at `ctx`.
    fn from_image(image: &ImageTexture, ctx: &TextureEvalContext) -> Self;
}

impl TextureValue for f32 {
    const ZERO: f32 = 0.0;
    fn splat(v: f32) -> f32 {
        v
    }
    fn from_image(image: &ImageTexture, ctx: &TextureEvalContext) -> f32 {
        image.evaluate_float(ctx)
    }
}

impl TextureValue for Rgb {
    const ZERO: Rgb = Rgb::ZERO;
    fn splat(v: f32) -> Rgb {
        Rgb::splat(v)
    }
    fn from_image(image: &ImageTexture, ctx: &TextureEvalContext) -> Rgb {
        image.evaluate_rgb(ctx)
    }
}

/// A texture returning `T` ([`FloatTexture`] or [`SpectrumTexture`]).
///
/// A constant is stored inline and evaluates without indirection (the fast
/// path of every untextured material parameter); the other variants share
/// their data, so cloning a texture is cheap.
#[derive(Clone, Debug, PartialEq)]
pub enum Texture<T> {
    /// A constant (`value`).
    Constant(T),
    /// An image map.
    Image(Arc<ImageTexture>),
    /// `tex1` or `tex2` by checker parity.
    Checkerboard {
        /// The pattern.
        checker: Arc<Checker>,
        /// Where the pattern is even.
        tex1: Arc<Texture<T>>,
        /// Where it is odd.
        tex2: Arc<Texture<T>>,
    },
    /// `tex * scale` (a float texture).
    Scale {
        /// The texture.
        tex: Arc<Texture<T>>,
        /// The factor.
        scale: Arc<FloatTexture>,
    },
    /// `(1 - amount) tex1 + amount tex2`.
    Mix {
        /// At amount 0.
        tex1: Arc<Texture<T>>,
        /// At amount 1.
        tex2: Arc<Texture<T>>,
        /// The blend.
        amount: Arc<FloatTexture>,
    },
}

/// A scalar texture.
pub type FloatTexture = Texture<f32>;
/// An RGB texture (pbrt's "spectrum" texture).
pub type SpectrumTexture = Texture<Rgb>;

impl<T> From<T> for Texture<T> {
    fn from(value: T) -> Texture<T> {
        Texture::Constant(value)
    }
}

impl<T: TextureValue> Texture<T> {
    /// The value at `ctx`. A constant is read inline; the other kinds go
    /// through one call.
    #[inline]
    pub fn evaluate(&self, ctx: &TextureEvalContext) -> T {
        match self {
            Texture::Constant(v) => *v,
            _ => self.evaluate_varying(ctx),
        }
    }

    /// [`Self::evaluate`] of a texture that is not a constant.
    #[inline(never)]
    fn evaluate_varying(&self, ctx: &TextureEvalContext) -> T {
        match self {
            Texture::Constant(v) => *v,
            Texture::Image(t) => T::from_image(t, ctx),
            Texture::Checkerboard {
                checker,
                tex1,
                tex2,
            } => {
                if checker.is_first(ctx) {
                    tex1.evaluate(ctx)
                } else {
                    tex2.evaluate(ctx)
                }
            }
            Texture::Scale { tex, scale } => {
                let s = scale.evaluate(ctx);
                if s == 0.0 {
                    T::ZERO
                } else {
                    tex.evaluate(ctx) * s
                }
            }
            Texture::Mix { tex1, tex2, amount } => {
                let a = amount.evaluate(ctx);
                let t1 = if a != 1.0 {
                    tex1.evaluate(ctx)
                } else {
                    T::ZERO
                };
                let t2 = if a != 0.0 {
                    tex2.evaluate(ctx)
                } else {
                    T::ZERO
                };
                t1 * (1.0 - a) + t2 * a
            }
        }
    }

    /// The value when the texture is a constant.
    #[inline]
    pub fn as_constant(&self) -> Option<T> {
        match self {
            Texture::Constant(v) => Some(*v),
            _ => None,
        }
    }

    /// A `scale` or `mix` of constants as the constant it is (so materials
    /// using it keep the constant fast path); any other texture unchanged.
    pub fn folded(self) -> Texture<T> {
        let constant = match &self {
            Texture::Scale { tex, scale } => {
                tex.as_constant().is_some() && scale.as_constant().is_some()
            }
            Texture::Mix { tex1, tex2, amount } => {
                tex1.as_constant().is_some()
                    && tex2.as_constant().is_some()
                    && amount.as_constant().is_some()
            }
            _ => false,
        };
        if constant {
            Texture::Constant(self.evaluate(&TextureEvalContext::default()))
        } else {
            self
        }
    }
}

impl ContentHash for TextureMapping {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        match self {
            TextureMapping::Uv { su, sv, du, dv } => (0u8, [su, sv, du, dv]).feed(sink),
            TextureMapping::Planar {
                texture_from_world,
                vs,
                vt,
                ds,
                dt,
            } => (1u8, texture_from_world, [vs, vt], [ds, dt]).feed(sink),
        }
    }
}

impl ContentHash for Checker {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        match self {
            Checker::TwoD(mapping) => (0u8, mapping).feed(sink),
            Checker::ThreeD(texture_from_world) => (1u8, texture_from_world).feed(sink),
        }
    }
}

impl ContentHash for ImageTexture {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        let ImageTexture {
            image,
            mapping,
            wrap,
            scale,
            invert,
        } = self;
        (image, mapping, wrap, scale, invert).feed(sink);
    }
}

impl<T: ContentHash> ContentHash for Texture<T> {
    fn feed<S: ContentSink + ?Sized>(&self, sink: &mut S) {
        match self {
            Texture::Constant(v) => (0u8, v).feed(sink),
            Texture::Image(image) => (1u8, image).feed(sink),
            Texture::Checkerboard {
                checker,
                tex1,
                tex2,
            } => (2u8, checker, tex1, tex2).feed(sink),
            Texture::Scale { tex, scale } => (3u8, tex, scale).feed(sink),
            Texture::Mix { tex1, tex2, amount } => (4u8, tex1, tex2, amount).feed(sink),
        }
    }
}
