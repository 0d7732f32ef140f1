//! `Material`, `MakeNamedMaterial` and `Texture`: pbrt-v4 materials reduced
//! to this crate's constant-parameter [`Material`]s, spectra reduced to RGB,
//! textures reduced to their average value.

use super::sink::PbrtLoader;
use super::state::MatRef;
use crate::bsdf::metals::{named_glass_eta, named_spectrum_rgb};
use crate::bsdf::{ConductorSpec, Material, Roughness};
use crate::spectrum::{Rgb, spectrum_file_to_rgb, spectrum_samples_to_rgb};
use crate::texture::{ColorEncoding, TexImage};
use pbrt_format::{FloatOrTexture, Loc, ParamSet, ParseError, SpectrumOrTexture, SpectrumValue};
use std::path::Path;

/// Planck's law at `lambda_nm` for temperature `t` kelvin (relative units).
fn planck(lambda_nm: f64, t: f64) -> f64 {
    const C: f64 = 299_792_458.0;
    const H: f64 = 6.626_070_15e-34;
    const KB: f64 = 1.380_649e-23;
    let l = lambda_nm * 1e-9;
    2.0 * H * C * C / (l.powi(5) * ((H * C / (l * KB * t)).exp() - 1.0))
}

/// A blackbody's colour, normalised to luminance 1.
pub(super) fn blackbody_rgb(t: f64) -> Option<Rgb> {
    if !(t > 0.0 && t.is_finite()) {
        return None;
    }
    let samples: Vec<(f32, f32)> = (0..=100)
        .map(|i| {
            let l = 350.0 + 4.5 * i as f64;
            (l as f32, planck(l, t) as f32)
        })
        .collect();
    let rgb = spectrum_samples_to_rgb(&samples, Path::new("blackbody")).ok()?;
    let y = rgb.luminance();
    (y > 0.0 && y.is_finite()).then(|| rgb * (1.0 / y))
}

impl PbrtLoader {
    /// An RGB value for a spectrum parameter (`rgb`, `blackbody`, sampled,
    /// named or a file relative to the scene). `illuminant` normalises
    /// non-RGB spectra to luminance 1 as pbrt-v4 does for lights.
    pub(super) fn spectrum_value(
        &mut self,
        v: SpectrumValue<'_>,
        illuminant: bool,
        loc: &Loc,
    ) -> Result<Rgb, ParseError> {
        let rgb = match v {
            SpectrumValue::Rgb(c) => return Ok(Rgb::new(c[0] as f32, c[1] as f32, c[2] as f32)),
            SpectrumValue::Blackbody(t) => {
                return blackbody_rgb(t).ok_or_else(|| {
                    ParseError::scene(loc, format!("invalid blackbody temperature {t}"))
                });
            }
            SpectrumValue::Samples(s) => {
                let pairs: Vec<(f32, f32)> = s
                    .chunks_exact(2)
                    .map(|c| (c[0] as f32, c[1] as f32))
                    .collect();
                spectrum_samples_to_rgb(&pairs, Path::new("inline spectrum"))
                    .map_err(|e| ParseError::scene(loc, e.to_string()))?
            }
            SpectrumValue::Named(name) => match named_spectrum_rgb(name) {
                Some(c) => c,
                None => match named_glass_eta(name) {
                    Some(e) => Rgb::splat(e),
                    None => {
                        let path = self.resolve(name);
                        let c = spectrum_file_to_rgb(&path).map_err(|e| {
                            ParseError::scene(loc, format!("spectrum \"{name}\": {e}"))
                        })?;
                        Rgb::from_array(c)
                    }
                },
            },
        };
        let y = rgb.luminance();
        Ok(if illuminant && y > 0.0 {
            rgb * (1.0 / y)
        } else {
            rgb
        })
    }

    /// A spectrum-or-texture parameter as a constant RGB.
    pub(super) fn rgb_param(
        &mut self,
        ps: &ParamSet,
        name: &str,
        default: Rgb,
        loc: &Loc,
    ) -> Result<Rgb, ParseError> {
        match ps.get_spectrum_or_texture(name) {
            None => Ok(default),
            Some(SpectrumOrTexture::Value(v)) => self.spectrum_value(v, false, loc),
            Some(SpectrumOrTexture::Texture(t)) => match self.spectrum_textures.get(t) {
                Some(c) => Ok(*c),
                None => match self.float_textures.get(t) {
                    Some(&f) => Ok(Rgb::splat(f)),
                    None => Err(ParseError::scene(
                        loc,
                        format!("texture \"{t}\" is not defined"),
                    )),
                },
            },
        }
    }

    /// A float-or-texture parameter as a constant.
    pub(super) fn float_param(
        &mut self,
        ps: &ParamSet,
        name: &str,
        default: f32,
        loc: &Loc,
    ) -> Result<f32, ParseError> {
        match ps.get_float_or_texture(name) {
            None => Ok(default),
            Some(FloatOrTexture::Value(v)) => Ok(v as f32),
            Some(FloatOrTexture::Texture(t)) => {
                self.float_textures.get(t).copied().ok_or_else(|| {
                    ParseError::scene(loc, format!("float texture \"{t}\" is not defined"))
                })
            }
        }
    }

    /// `eta` as a float, a named glass or a spectrum (averaged).
    fn eta_param(&mut self, ps: &ParamSet, name: &str, loc: &Loc) -> Result<f32, ParseError> {
        if let Some(FloatOrTexture::Value(v)) = ps.get_float_or_texture(name) {
            return Ok(v as f32);
        }
        if let Some(FloatOrTexture::Texture(_)) = ps.get_float_or_texture(name) {
            return self.float_param(ps, name, 1.5, loc);
        }
        match ps.get_spectrum(name) {
            Some(v) => Ok(self.spectrum_value(v, false, loc)?.average()),
            None => Ok(1.5),
        }
    }

    fn roughness(
        &mut self,
        ps: &ParamSet,
        prefix: &str,
        loc: &Loc,
    ) -> Result<Roughness, ParseError> {
        let r = self.float_param(ps, &format!("{prefix}roughness"), 0.0, loc)?;
        let u = self.float_param(ps, &format!("{prefix}uroughness"), r, loc)?;
        let v = self.float_param(ps, &format!("{prefix}vroughness"), r, loc)?;
        let remap = ps.bool_or("remaproughness", true);
        Ok(Roughness { u, v, remap })
    }

    fn conductor_spec(
        &mut self,
        ps: &ParamSet,
        prefix: &str,
        loc: &Loc,
    ) -> Result<ConductorSpec, ParseError> {
        if ps.find("reflectance").is_some() {
            let r = self.rgb_param(ps, "reflectance", Rgb::ONE, loc)?;
            return Ok(ConductorSpec::Reflectance(r));
        }
        let cu = |w: &str| named_spectrum_rgb(&format!("metal-Cu-{w}")).unwrap_or(Rgb::ONE);
        let eta = self.rgb_param(ps, &format!("{prefix}eta"), cu("eta"), loc)?;
        let k = self.rgb_param(ps, &format!("{prefix}k"), cu("k"), loc)?;
        Ok(ConductorSpec::EtaK { eta, k })
    }

    fn build_material(
        &mut self,
        ty: &str,
        ps: &ParamSet,
        loc: &Loc,
    ) -> Result<Option<Material>, ParseError> {
        let half = Rgb::splat(0.5);
        let depth = |ps: &ParamSet, d: i64| ps.int_or("maxdepth", d).clamp(1, 100) as u32;
        let nsamples = |ps: &ParamSet| ps.int_or("nsamples", 1).clamp(1, 64) as u32;
        Ok(Some(match ty {
            "diffuse" => Material::Diffuse {
                reflectance: self.rgb_param(ps, "reflectance", half, loc)?,
            },
            "conductor" => Material::Conductor {
                spec: self.conductor_spec(ps, "", loc)?,
                roughness: self.roughness(ps, "", loc)?,
            },
            "dielectric" => Material::Dielectric {
                eta: self.eta_param(ps, "eta", loc)?,
                roughness: self.roughness(ps, "", loc)?,
            },
            "thindielectric" => Material::ThinDielectric {
                eta: self.eta_param(ps, "eta", loc)?,
            },
            "diffusetransmission" => Material::DiffuseTransmission {
                reflectance: self.rgb_param(ps, "reflectance", Rgb::splat(0.25), loc)?,
                transmittance: self.rgb_param(ps, "transmittance", Rgb::splat(0.25), loc)?,
                scale: ps.float_or("scale", 1.0) as f32,
            },
            "coateddiffuse" => Material::CoatedDiffuse {
                reflectance: self.rgb_param(ps, "reflectance", half, loc)?,
                roughness: self.roughness(ps, "", loc)?,
                thickness: self.float_param(ps, "thickness", 0.01, loc)?,
                eta: self.eta_param(ps, "eta", loc)?,
                max_depth: depth(ps, 10),
                n_samples: nsamples(ps),
            },
            "coatedconductor" => Material::CoatedConductor {
                interface_roughness: self.roughness(ps, "interface.", loc)?,
                interface_eta: self.eta_param(ps, "interface.eta", loc)?,
                thickness: self.float_param(ps, "thickness", 0.01, loc)?,
                conductor: self.conductor_spec(ps, "conductor.", loc)?,
                conductor_roughness: self.roughness(ps, "conductor.", loc)?,
                max_depth: depth(ps, 10),
                n_samples: nsamples(ps),
            },
            "measured" => {
                let f = ps.get_string("filename").unwrap_or("").to_string();
                self.warn(loc, format!(
                    "measured material \"{f}\" is approximated by a diffuse or rough conductor fallback"
                ));
                super::measured(&f)
            }
            _ => return Ok(None),
        }))
    }

    /// Creates the material of a `Material` or `MakeNamedMaterial` directive.
    pub(super) fn create_material(
        &mut self,
        ty: &str,
        ps: &ParamSet,
        loc: &Loc,
    ) -> Result<MatRef, ParseError> {
        let context = format!("material \"{ty}\"");
        let m = match ty {
            "" | "none" | "interface" => {
                ps.warn_unused(&context, &mut self.warnings);
                return Ok(MatRef::Interface);
            }
            "mix" => {
                let names: Vec<String> = ps
                    .get_strings("materials")
                    .map(<[String]>::to_vec)
                    .unwrap_or_default();
                if names.len() != 2 {
                    return Err(ParseError::scene(
                        loc,
                        "mix: \"string materials\" must name two materials",
                    ));
                }
                let amount = self.float_param(ps, "amount", 0.5, loc)?;
                self.warn(
                    loc,
                    "mix material: using the material with the larger weight",
                );
                let pick = &names[usize::from(amount > 0.5)];
                let m = *self.named_materials.get(pick).ok_or_else(|| {
                    ParseError::scene(loc, format!("mix: material \"{pick}\" is not defined"))
                })?;
                ps.warn_unused(&context, &mut self.warnings);
                return Ok(m);
            }
            _ => self.build_material(ty, ps, loc)?,
        };
        let m = match m {
            Some(m) => m,
            None => {
                self.warn(
                    loc,
                    format!("unknown material type \"{ty}\"; using diffuse"),
                );
                Material::Diffuse {
                    reflectance: Rgb::splat(0.5),
                }
            }
        };
        for p in ["displacement", "normalmap"] {
            if ps.find(p).is_some() {
                ps.mark_used(p);
                let what = format!("material parameter \"{p}\"");
                self.unsupported(loc, &what);
            }
        }
        ps.warn_unused(&context, &mut self.warnings);
        self.counts.materials += 1;
        Ok(MatRef::Index(self.builder.add_material(m)))
    }

    /// `Texture "name" "float"|"spectrum" "class" params`: stored as its average.
    pub(super) fn texture_directive(
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
        for p in [
            "mapping",
            "uscale",
            "vscale",
            "udelta",
            "vdelta",
            "filter",
            "maxanisotropy",
            "wrap",
            "dimension",
        ] {
            ps.mark_used(p);
        }
        let get = |me: &mut Self, p: &str, d: f32| -> Result<Rgb, ParseError> {
            if spectral {
                me.rgb_param(ps, p, Rgb::splat(d), loc)
            } else {
                me.float_param(ps, p, d, loc).map(Rgb::splat)
            }
        };
        let value = match class {
            "constant" => get(self, "value", 1.0)?,
            "checkerboard" => (get(self, "tex1", 1.0)? + get(self, "tex2", 0.0)?) * 0.5,
            "scale" => get(self, "tex", 1.0)? * self.float_param(ps, "scale", 1.0, loc)?,
            "mix" => {
                let a = self.float_param(ps, "amount", 0.5, loc)?;
                get(self, "tex1", 0.0)? * (1.0 - a) + get(self, "tex2", 1.0)? * a
            }
            "imagemap" => {
                let file = ps.get_string("filename").ok_or_else(|| {
                    ParseError::scene(loc, "imagemap: \"string filename\" is required")
                })?;
                let path = self.resolve(file);
                let enc = match ps.get_string("encoding") {
                    Some(e) => ColorEncoding::parse(e)
                        .map_err(|e| ParseError::scene(loc, e.to_string()))?,
                    None => ColorEncoding::default_for(&path),
                };
                if !path.is_file() {
                    self.warn(
                        loc,
                        format!("imagemap: {} not found; using grey 0.5", path.display()),
                    );
                    ps.mark_used("scale");
                    ps.mark_used("invert");
                    self.store_texture(name, spectral, Rgb::splat(0.5));
                    return Ok(());
                }
                let img = TexImage::load(&path, enc)
                    .map_err(|e| ParseError::scene(loc, format!("imagemap: {e}")))?;
                let px = img.image().pixels();
                let mut sum = [0.0f64; 3];
                for p in px {
                    for c in 0..3 {
                        sum[c] += p[c] as f64;
                    }
                }
                let n = px.len().max(1) as f64;
                let mut avg = Rgb::new(
                    (sum[0] / n) as f32,
                    (sum[1] / n) as f32,
                    (sum[2] / n) as f32,
                );
                if ps.bool_or("invert", false) {
                    avg = Rgb::ONE - avg;
                }
                avg * ps.float_or("scale", 1.0) as f32
            }
            other => {
                let what = format!("texture class \"{other}\"");
                self.unsupported(loc, &what);
                Rgb::splat(0.5)
            }
        };
        self.warnings
            .warn_once(loc, "textures are approximated by their average value");
        ps.warn_unused(&format!("texture \"{name}\""), &mut self.warnings);
        self.store_texture(name, spectral, value);
        Ok(())
    }

    fn store_texture(&mut self, name: &str, spectral: bool, value: Rgb) {
        if spectral {
            self.spectrum_textures.insert(name.to_string(), value);
        } else {
            self.float_textures
                .insert(name.to_string(), value.average());
        }
    }
}
