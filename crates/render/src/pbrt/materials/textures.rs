//! The `Texture` directive: pbrt-v4's `constant`, `scale`, `mix`,
//! `checkerboard` (2-D over a `uv` or `planar` mapping, or 3-D) and
//! `imagemap` float and spectrum textures, kept in the loader's
//! [`crate::texture::TextureRegistry`] and evaluated at shading points.
//!
//! Lookups are point evaluations (no ray differentials): image maps are
//! filtered bilinearly whatever `filter` says, checkerboards are not
//! antialiased. Not supported (errors, or with `--approximate` warnings):
//! the `spherical` and `cylindrical` mappings (the `uv` mapping is used), the
//! `octahedralsphere` wrap mode (`repeat` is used) and the procedural classes
//! (`bilerp`, `dots`, `fbm`, `marble`, `windy`, `wrinkled`, `ptex`,
//! `directionmix`), which become a constant 0.5. A missing or unreadable
//! image file is an error, as in pbrt-v4 ("file not found").
//!
//! An image's 8-bit codes are decoded as pbrt-v4 decodes them
//! ([`ColorEncoding::for_file`]): a PNG by `encoding` (default sRGB), any
//! other 8-bit file (TGA) as sRGB whatever `encoding` says, with a warning
//! when it says something else.

use crate::math::Vec3;
use crate::pbrt::loader::PbrtLoader;
use crate::spectrum::Rgb;
use crate::texture::{
    Checker, ColorEncoding, ImageTexture, Texture, TextureMapping, TextureValue, WrapMode,
};
use pbrt_format::{Loc, ParamSet, ParseError};
use std::sync::Arc;

fn vec3(v: Option<[f64; 3]>, default: Vec3) -> Vec3 {
    v.map_or(default, |v| {
        Vec3::new(v[0] as f32, v[1] as f32, v[2] as f32)
    })
}

impl PbrtLoader {
    /// The 2-D mapping of a texture (`mapping`, `uscale`, ..., `v1`, `v2`).
    fn texture_mapping(&mut self, ps: &ParamSet, loc: &Loc) -> Result<TextureMapping, ParseError> {
        let f = |p: &str, d: f64| ps.float_or(p, d) as f32;
        let (du, dv) = (f("udelta", 0.0), f("vdelta", 0.0));
        Ok(match ps.string_or("mapping", "uv") {
            "planar" => TextureMapping::Planar {
                texture_from_world: self.state.cur.ctm.inverse(),
                vs: vec3(ps.get_vector3("v1"), Vec3::X),
                vt: vec3(ps.get_vector3("v2"), Vec3::Y),
                ds: du,
                dt: dv,
            },
            other => {
                if other != "uv" {
                    let what = format!("texture mapping \"{other}\"");
                    self.approximated(loc, &what, "the uv mapping is used")?;
                }
                TextureMapping::Uv {
                    su: f("uscale", 1.0),
                    sv: f("vscale", 1.0),
                    du,
                    dv,
                }
            }
        })
    }

    /// The checkerboard's pattern (`dimension` 2 or 3).
    fn checker(&mut self, ps: &ParamSet, loc: &Loc) -> Result<Checker, ParseError> {
        match ps.int_or("dimension", 2) {
            2 => Ok(Checker::TwoD(self.texture_mapping(ps, loc)?)),
            3 => Ok(Checker::ThreeD(self.state.cur.ctm.inverse())),
            d => Err(ParseError::scene(
                loc,
                format!("checkerboard: dimension {d} is not 2 or 3"),
            )),
        }
    }

    /// An `imagemap` texture; its file must exist.
    fn image_texture(&mut self, ps: &ParamSet, loc: &Loc) -> Result<ImageTexture, ParseError> {
        let file = ps
            .get_string("filename")
            .ok_or_else(|| ParseError::scene(loc, "imagemap: \"string filename\" is required"))?;
        let path = self.resolve(file);
        let encoding = match ps.get_string("encoding") {
            Some(e) => {
                Some(ColorEncoding::parse(e).map_err(|e| ParseError::scene(loc, e.to_string()))?)
            }
            None => None,
        };
        // Point lookups are always bilinear.
        ps.mark_used("filter");
        ps.mark_used("maxanisotropy");
        let wrap = match ps.string_or("wrap", "repeat") {
            "octahedralsphere" => {
                let what = "texture wrap mode \"octahedralsphere\"";
                self.approximated(loc, what, "repeat is used")?;
                WrapMode::Repeat
            }
            w => WrapMode::parse(w).map_err(|e| ParseError::scene(loc, e.to_string()))?,
        };
        let mapping = self.texture_mapping(ps, loc)?;
        let scale = ps.float_or("scale", 1.0) as f32;
        let invert = ps.bool_or("invert", false);
        if let Err(e) = lowdisc_files::check_input(&path, u64::MAX) {
            let why = e.io_error();
            let message = format!("imagemap: {}: {why}", path.display());
            return Err(ParseError::scene(loc, message));
        }
        if let Some(e) = encoding
            && ColorEncoding::for_file(&path, Some(e)) != e
            && !ColorEncoding::is_float_file(&path)
        {
            let at = ps.find("encoding").map_or(loc, |p| &p.loc).clone();
            let message = format!(
                "imagemap: \"encoding\" is ignored for {}: pbrt-v4 decodes 8-bit files other than PNG as sRGB",
                path.display()
            );
            self.warn(&at, message);
        }
        let image = self
            .textures
            .load_image(&path, encoding)
            .map_err(|e| ParseError::scene(loc, format!("imagemap: {e}")))?;
        Ok(ImageTexture {
            image,
            mapping,
            wrap,
            scale,
            invert,
        })
    }

    /// `Texture "name" "float"|"spectrum" "class" params`.
    pub(in crate::pbrt) fn texture_directive(
        &mut self,
        name: &str,
        ty: &str,
        class: &str,
        ps: &ParamSet,
        loc: &Loc,
    ) -> Result<(), ParseError> {
        let spectral = match ty {
            "float" => false,
            "spectrum" | "color" => true,
            other => {
                return Err(ParseError::scene(
                    loc,
                    format!("texture type \"{other}\" is not float or spectrum"),
                ));
            }
        };
        let replaced = if spectral {
            let param = |me: &mut Self, p: &str, d: f32| me.rgb_tex(ps, p, Rgb::splat(d), loc);
            let tex = self.texture_of_class(class, ps, loc, param)?;
            self.textures.add_spectrum(name, tex).is_some()
        } else {
            let param = |me: &mut Self, p: &str, d: f32| me.float_tex(ps, p, d.into(), loc);
            let tex = self.texture_of_class(class, ps, loc, param)?;
            self.textures.add_float(name, tex).is_some()
        };
        if replaced {
            self.warn(loc, format!("texture \"{name}\" redefined"));
        }
        ps.finish(&format!("texture \"{name}\""), &mut self.warnings)?;
        Ok(())
    }

    /// A texture of pbrt class `class` whose `T`-valued parameters `param`
    /// reads (with the default it is given); constant sub-expressions are
    /// folded into constants.
    fn texture_of_class<T: TextureValue>(
        &mut self,
        class: &str,
        ps: &ParamSet,
        loc: &Loc,
        param: impl Fn(&mut Self, &str, f32) -> Result<Texture<T>, ParseError>,
    ) -> Result<Texture<T>, ParseError> {
        let amount = |me: &mut Self, p: &str, d: f32| -> Result<_, ParseError> {
            Ok(Arc::new(me.float_tex(ps, p, d.into(), loc)?))
        };
        let sub = |me: &mut Self, p: &str, d: f32| Ok::<_, ParseError>(Arc::new(param(me, p, d)?));
        let tex = match class {
            "constant" => param(self, "value", 1.0)?,
            "scale" => Texture::Scale {
                tex: sub(self, "tex", 1.0)?,
                scale: amount(self, "scale", 1.0)?,
            },
            "mix" => Texture::Mix {
                tex1: sub(self, "tex1", 0.0)?,
                tex2: sub(self, "tex2", 1.0)?,
                amount: amount(self, "amount", 0.5)?,
            },
            "checkerboard" => Texture::Checkerboard {
                checker: Arc::new(self.checker(ps, loc)?),
                tex1: sub(self, "tex1", 1.0)?,
                tex2: sub(self, "tex2", 0.0)?,
            },
            "imagemap" => Texture::Image(Arc::new(self.image_texture(ps, loc)?)),
            _ => {
                let what = format!("texture class \"{class}\"");
                self.approximated(loc, &what, "a constant 0.5 is used")?;
                ps.into_iter().for_each(pbrt_format::Param::mark_used);
                Texture::Constant(T::splat(0.5))
            }
        };
        Ok(tex.folded())
    }
}
