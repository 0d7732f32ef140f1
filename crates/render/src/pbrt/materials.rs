//! `Material` and `MakeNamedMaterial`: pbrt-v4 materials as this crate's
//! [`Material`]s, spectra reduced to RGB. Parameters pbrt-v4 allows to be
//! textures become texture parameters (constant textures for values); `mix`
//! becomes a [`MixMaterial`]. The `Texture` directive is in [`textures`].

mod textures;

use super::loader::PbrtLoader;
use super::state::MatRef;
use crate::bsdf::{Bump, BumpedMaterial, ConductorSpec, Material, MixMaterial, Roughness};
use crate::spectrum::metals::{named_glass_eta, named_spectrum_rgb};
use crate::spectrum::named::{NamedSpectrum, intern_measured, named_metal, planck};
use crate::spectrum::{Rgb, spectrum_file_to_rgb, spectrum_samples_to_rgb};
use crate::texture::{ColorEncoding, FloatTexture, SpectrumTexture, TexImage, TextureEvalContext};
use pbrt_format::{FloatOrTexture, Loc, ParamSet, ParseError, SpectrumOrTexture, SpectrumValue};
use std::path::Path;
use std::sync::Arc;

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

    /// A spectrum-or-texture parameter as an RGB texture (a constant one
    /// for values). As in pbrt-v4, the texture named must be a spectrum
    /// texture: a float texture there is an error at the parameter.
    pub(super) fn rgb_tex(
        &mut self,
        ps: &ParamSet,
        name: &str,
        default: Rgb,
        loc: &Loc,
    ) -> Result<SpectrumTexture, ParseError> {
        match ps.get_spectrum_or_texture(name) {
            None => Ok(default.into()),
            Some(SpectrumOrTexture::Value(v)) => Ok(self.spectrum_value(v, false, loc)?.into()),
            Some(SpectrumOrTexture::Texture(t)) => self
                .textures
                .spectrum(t)
                .ok_or_else(|| self.texture_error(ps, name, t, "float", "spectrum", loc)),
        }
    }

    /// The error for parameter `name` naming texture `t`, which is not a
    /// `wanted` texture: it is an `other` one, or not defined. It is located
    /// at the parameter (pbrt-v4: "Couldn't find spectrum texture named").
    fn texture_error(
        &self,
        ps: &ParamSet,
        name: &str,
        t: &str,
        other: &str,
        wanted: &str,
        loc: &Loc,
    ) -> ParseError {
        let is_other = match other {
            "float" => self.textures.float(t).is_some(),
            _ => self.textures.spectrum(t).is_some(),
        };
        let why = if is_other {
            format!("is a {other} texture; a {wanted} texture is needed")
        } else {
            "is not defined".to_string()
        };
        let at = ps.find(name).map_or(loc, |p| &p.loc);
        ParseError::scene(at, format!("parameter \"{name}\": texture \"{t}\" {why}"))
    }

    /// A float-or-texture parameter as a float texture (`default` when
    /// absent); the texture named must be a float texture.
    pub(super) fn float_tex(
        &mut self,
        ps: &ParamSet,
        name: &str,
        default: FloatTexture,
        loc: &Loc,
    ) -> Result<FloatTexture, ParseError> {
        match ps.get_float_or_texture(name) {
            None => Ok(default),
            Some(FloatOrTexture::Value(v)) => Ok((v as f32).into()),
            Some(FloatOrTexture::Texture(t)) => self
                .textures
                .float(t)
                .ok_or_else(|| self.texture_error(ps, name, t, "spectrum", "float", loc)),
        }
    }

    /// `eta` as a float, a named glass or a spectrum (averaged). A float
    /// texture that is not constant is not supported (read at `uv = (0, 0)`
    /// with `--approximate`).
    fn eta_param(&mut self, ps: &ParamSet, name: &str, loc: &Loc) -> Result<f32, ParseError> {
        if let Some(FloatOrTexture::Value(v)) = ps.get_float_or_texture(name) {
            return Ok(v as f32);
        }
        if let Some(FloatOrTexture::Texture(_)) = ps.get_float_or_texture(name) {
            let t = self.float_tex(ps, name, 1.5.into(), loc)?;
            if t.as_constant().is_none() {
                let what = format!("a textured \"{name}\"");
                self.approximated(loc, &what, "its value at uv (0, 0) is used")?;
            }
            return Ok(t.evaluate(&TextureEvalContext::default()));
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
    ) -> Result<Roughness<FloatTexture>, ParseError> {
        let r = self.float_tex(ps, &format!("{prefix}roughness"), 0.0.into(), loc)?;
        let u = self.float_tex(ps, &format!("{prefix}uroughness"), r.clone(), loc)?;
        let v = self.float_tex(ps, &format!("{prefix}vroughness"), r, loc)?;
        let remap = ps.bool_or("remaproughness", true);
        Ok(Roughness { u, v, remap })
    }

    fn conductor_spec(
        &mut self,
        ps: &ParamSet,
        prefix: &str,
        loc: &Loc,
    ) -> Result<ConductorSpec<SpectrumTexture>, ParseError> {
        if ps.find("reflectance").is_some() {
            let r = self.rgb_tex(ps, "reflectance", Rgb::ONE, loc)?;
            return Ok(ConductorSpec::Reflectance(r));
        }
        let cu = |w: &str| named_spectrum_rgb(&format!("metal-Cu-{w}")).unwrap_or(Rgb::ONE);
        let (eta_name, k_name) = (format!("{prefix}eta"), format!("{prefix}k"));
        // Measured spectra (named metals, the default copper, files or
        // inline samples) for both: the spectra themselves.
        let spectra = (
            self.measured(ps, &eta_name, "eta"),
            self.measured(ps, &k_name, "k"),
        );
        let eta = self.rgb_tex(ps, &eta_name, cu("eta"), loc)?;
        let k = self.rgb_tex(ps, &k_name, cu("k"), loc)?;
        Ok(match spectra {
            (Some(eta), Some(k)) => ConductorSpec::Named { eta, k },
            _ => ConductorSpec::EtaK { eta, k },
        })
    }

    /// A conductor's `eta` or `k` parameter as a measured spectrum, when it
    /// is one: a named metal, a `.spd` file or inline samples (`None` for
    /// RGB, textures and unreadable files, which `rgb_tex` reports).
    fn measured(&self, ps: &ParamSet, name: &str, which: &str) -> Option<&'static NamedSpectrum> {
        let samples = match ps.get_spectrum_or_texture(name) {
            None => return named_metal(&format!("metal-Cu-{which}")),
            Some(SpectrumOrTexture::Value(SpectrumValue::Named(n))) => {
                if let Some(m) = named_metal(n) {
                    return Some(m);
                }
                let path = self.resolve(n);
                let text = String::from_utf8(lowdisc_files::read_input(&path).ok()?).ok()?;
                crate::spectrum::parse_spectrum_text(&text, &path).ok()?
            }
            Some(SpectrumOrTexture::Value(SpectrumValue::Samples(s))) => s
                .chunks_exact(2)
                .map(|c| (c[0] as f32, c[1] as f32))
                .collect(),
            Some(_) => return None,
        };
        let rgb = spectrum_samples_to_rgb(&samples, Path::new(name)).ok()?;
        Some(intern_measured(name, &samples, rgb))
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
        let material = match ty {
            "diffuse" => Material::Diffuse {
                reflectance: self.rgb_tex(ps, "reflectance", half, loc)?,
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
                reflectance: self.rgb_tex(ps, "reflectance", Rgb::splat(0.25), loc)?,
                transmittance: self.rgb_tex(ps, "transmittance", Rgb::splat(0.25), loc)?,
                scale: ps.float_or("scale", 1.0) as f32,
            },
            "coateddiffuse" => Material::CoatedDiffuse {
                reflectance: self.rgb_tex(ps, "reflectance", half, loc)?,
                roughness: self.roughness(ps, "", loc)?,
                thickness: self.float_tex(ps, "thickness", 0.01.into(), loc)?,
                eta: self.eta_param(ps, "eta", loc)?,
                max_depth: depth(ps, 10),
                n_samples: nsamples(ps),
            },
            "coatedconductor" => Material::CoatedConductor {
                interface_roughness: self.roughness(ps, "interface.", loc)?,
                interface_eta: self.eta_param(ps, "interface.eta", loc)?,
                thickness: self.float_tex(ps, "thickness", 0.01.into(), loc)?,
                conductor: self.conductor_spec(ps, "conductor.", loc)?,
                conductor_roughness: self.roughness(ps, "conductor.", loc)?,
                max_depth: depth(ps, 10),
                n_samples: nsamples(ps),
            },
            "measured" => {
                let f = ps.get_string("filename").unwrap_or("").to_string();
                let what = format!("material \"measured\" (\"{f}\")");
                let instead = "a diffuse or rough conductor fallback is used";
                self.approximated(loc, &what, instead)?;
                Material::measured_fallback(&f)
            }
            _ => return Ok(None),
        };
        Ok(Some(material))
    }

    /// `m` with the bump map (`"displacement"`) or normal map
    /// (`"normalmap"`) the material's parameters give, if any. As in
    /// pbrt-v4, a normal map wins over a displacement.
    fn with_bump(&mut self, m: Material, ps: &ParamSet, loc: &Loc) -> Result<Material, ParseError> {
        let displacement = match ps.find("displacement") {
            Some(_) => Some(self.float_tex(ps, "displacement", 0.0.into(), loc)?),
            None => None,
        };
        let bump = match ps.get_string("normalmap") {
            Some(file) if !file.is_empty() => Bump::NormalMap(self.normal_map(file, ps, loc)?),
            _ => match displacement {
                Some(d) => Bump::Displacement(d),
                None => return Ok(m),
            },
        };
        let material = m;
        Ok(Material::Bumped(Arc::new(BumpedMaterial {
            material,
            bump,
        })))
    }

    /// The image of a `"normalmap"` parameter, read as pbrt-v4 reads it
    /// (linear, unless the file is 8-bit and not a PNG: sRGB, see
    /// [`ColorEncoding::for_file`]).
    fn normal_map(
        &mut self,
        file: &str,
        ps: &ParamSet,
        loc: &Loc,
    ) -> Result<Arc<TexImage>, ParseError> {
        let path = self.resolve(file);
        let at = ps.find("normalmap").map_or(loc, |p| &p.loc);
        let error =
            |why: String| ParseError::scene(at, format!("normalmap: {}: {why}", path.display()));
        if let Err(e) = lowdisc_files::check_input(&path, u64::MAX) {
            return Err(error(e.io_error().to_string()));
        }
        self.textures
            .load_image(&path, Some(ColorEncoding::Linear))
            .map_err(|e| error(e.to_string()))
    }

    /// A material named in a `mix`: its value, or `None` for `interface`.
    fn mix_part(&self, name: &str, loc: &Loc) -> Result<(MatRef, Option<Material>), ParseError> {
        let r = *self.named_materials.get(name).ok_or_else(|| {
            ParseError::scene(loc, format!("mix: material \"{name}\" is not defined"))
        })?;
        let m = match r {
            MatRef::Index(i) => self.material_values.get(&i).cloned(),
            MatRef::Default => Material::pbrt_default("diffuse").ok(),
            MatRef::Interface => None,
        };
        Ok((r, m))
    }

    /// pbrt-v4's `mix`: a [`MixMaterial`] choosing per shading point. It is
    /// not counted in `counts.materials` (it only combines two materials
    /// that are). An amount that is a constant `<= 0` or `>= 1` is the first
    /// or second material itself; with an `interface` side the other is used.
    fn mix_material(&mut self, ps: &ParamSet, loc: &Loc) -> Result<MatRef, ParseError> {
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
        let amount = self.float_tex(ps, "amount", 0.5.into(), loc)?;
        let (r0, m0) = self.mix_part(&names[0], loc)?;
        let (r1, m1) = self.mix_part(&names[1], loc)?;
        match amount.as_constant() {
            Some(a) if !(a > 0.0) => return Ok(r0),
            Some(a) if a >= 1.0 => return Ok(r1),
            _ => {}
        }
        let (m0, m1) = match (m0, m1) {
            (Some(m0), Some(m1)) => (m0, m1),
            (m0, _) => {
                let what = "mix with an \"interface\" material";
                self.approximated(loc, what, "the other material is used")?;
                return Ok(if m0.is_some() { r0 } else { r1 });
            }
        };
        let mix = Material::Mix(Arc::new(MixMaterial {
            materials: [m0, m1],
            amount,
        }));
        Ok(self.add_material(mix))
    }

    /// Adds `m` to the scene, remembering its value for `mix` materials.
    fn add_material(&mut self, m: Material) -> MatRef {
        let i = self.builder.add_material(m.clone());
        self.material_values.insert(i, m);
        MatRef::Index(i)
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
                ps.finish(&context, &mut self.warnings)?;
                return Ok(MatRef::Interface);
            }
            "mix" => {
                let m = self.mix_material(ps, loc)?;
                ps.finish(&context, &mut self.warnings)?;
                return Ok(m);
            }
            _ => self.build_material(ty, ps, loc)?,
        };
        let m = match m {
            Some(m) => m,
            None => {
                let what = format!("material \"{ty}\"");
                self.approximated(loc, &what, "a diffuse material is used")?;
                // Its parameters are the missing material's, not typos.
                ps.into_iter().for_each(pbrt_format::Param::mark_used);
                Material::diffuse(Rgb::splat(0.5))
            }
        };
        let m = self.with_bump(m, ps, loc)?;
        ps.finish(&context, &mut self.warnings)?;
        self.counts.materials += 1;
        Ok(self.add_material(m))
    }
}
