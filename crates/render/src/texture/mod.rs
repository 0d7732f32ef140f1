//! pbrt-v4 textures: constant, imagemap, checkerboard, scale and mix, as
//! float and RGB ("spectrum") textures, evaluated at a surface point's `uv`
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

use crate::math::{Point2, Point3, Transform, Vec3};
use crate::spectrum::Rgb;
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

/// A scalar texture.
#[derive(Clone, Debug, PartialEq)]
pub enum FloatTexture {
    /// A constant (`value`).
    Constant(f32),
    /// An image map.
    Image(ImageTexture),
    /// `tex1` or `tex2` by checker parity.
    Checkerboard {
        /// The pattern.
        checker: Checker,
        /// Where the pattern is even.
        tex1: Arc<FloatTexture>,
        /// Where it is odd.
        tex2: Arc<FloatTexture>,
    },
    /// `tex * scale`.
    Scale {
        /// The texture.
        tex: Arc<FloatTexture>,
        /// The factor.
        scale: Arc<FloatTexture>,
    },
    /// `(1 - amount) tex1 + amount tex2`.
    Mix {
        /// At amount 0.
        tex1: Arc<FloatTexture>,
        /// At amount 1.
        tex2: Arc<FloatTexture>,
        /// The blend.
        amount: Arc<FloatTexture>,
    },
}

impl FloatTexture {
    /// The value at `ctx`.
    pub fn evaluate(&self, ctx: &TextureEvalContext) -> f32 {
        match self {
            FloatTexture::Constant(v) => *v,
            FloatTexture::Image(t) => t.evaluate_float(ctx),
            FloatTexture::Checkerboard {
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
            FloatTexture::Scale { tex, scale } => {
                let s = scale.evaluate(ctx);
                if s == 0.0 { 0.0 } else { tex.evaluate(ctx) * s }
            }
            FloatTexture::Mix { tex1, tex2, amount } => {
                let a = amount.evaluate(ctx);
                let t1 = if a != 1.0 { tex1.evaluate(ctx) } else { 0.0 };
                let t2 = if a != 0.0 { tex2.evaluate(ctx) } else { 0.0 };
                (1.0 - a) * t1 + a * t2
            }
        }
    }

    /// The value when the texture is a constant.
    pub fn as_constant(&self) -> Option<f32> {
        match self {
            FloatTexture::Constant(v) => Some(*v),
            _ => None,
        }
    }
}

/// An RGB texture (pbrt's "spectrum" texture).
#[derive(Clone, Debug, PartialEq)]
pub enum SpectrumTexture {
    /// A constant (`value`).
    Constant(Rgb),
    /// An image map.
    Image(ImageTexture),
    /// `tex1` or `tex2` by checker parity.
    Checkerboard {
        /// The pattern.
        checker: Checker,
        /// Where the pattern is even.
        tex1: Arc<SpectrumTexture>,
        /// Where it is odd.
        tex2: Arc<SpectrumTexture>,
    },
    /// `tex * scale` (a float texture).
    Scale {
        /// The texture.
        tex: Arc<SpectrumTexture>,
        /// The factor.
        scale: Arc<FloatTexture>,
    },
    /// `(1 - amount) tex1 + amount tex2`.
    Mix {
        /// At amount 0.
        tex1: Arc<SpectrumTexture>,
        /// At amount 1.
        tex2: Arc<SpectrumTexture>,
        /// The blend.
        amount: Arc<FloatTexture>,
    },
}

impl SpectrumTexture {
    /// The value at `ctx`.
    pub fn evaluate(&self, ctx: &TextureEvalContext) -> Rgb {
        match self {
            SpectrumTexture::Constant(v) => *v,
            SpectrumTexture::Image(t) => t.evaluate_rgb(ctx),
            SpectrumTexture::Checkerboard {
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
            SpectrumTexture::Scale { tex, scale } => {
                let s = scale.evaluate(ctx);
                if s == 0.0 {
                    Rgb::ZERO
                } else {
                    tex.evaluate(ctx) * s
                }
            }
            SpectrumTexture::Mix { tex1, tex2, amount } => {
                let a = amount.evaluate(ctx);
                let t1 = if a != 1.0 {
                    tex1.evaluate(ctx)
                } else {
                    Rgb::ZERO
                };
                let t2 = if a != 0.0 {
                    tex2.evaluate(ctx)
                } else {
                    Rgb::ZERO
                };
                t1 * (1.0 - a) + t2 * a
            }
        }
    }

    /// The value when the texture is a constant.
    pub fn as_constant(&self) -> Option<Rgb> {
        match self {
            SpectrumTexture::Constant(v) => Some(*v),
            _ => None,
        }
    }
}
