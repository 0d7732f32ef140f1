//! `LightSource` (point, spot, distant, infinite) and `AreaLightSource
//! "diffuse"`; the CTM is the light-to-world transform.

use super::loader::PbrtLoader;
use super::state::AreaSpec;
use crate::light::{
    DistantLight, EnvLookup, ImageInfiniteLight, Light, PointLight, SpotLight, UniformInfiniteLight,
};
use crate::math::{Point3, Vec3};
use crate::spectrum::named::{EmissionSpectrum, blackbody, named_metal, sampled_emission};
use crate::spectrum::{Rgb, parse_spectrum_text};
use pbrt_format::SpectrumValue;
use pbrt_format::{Loc, ParamSet, ParseError};
use std::sync::Arc;

fn point(ps: &ParamSet, name: &str, d: [f32; 3]) -> Point3 {
    ps.get_point3(name)
        .map(|a| Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32))
        .unwrap_or(Vec3::new(d[0], d[1], d[2]))
}

impl PbrtLoader {
    /// A light's spectrum parameter (pbrt-v4 normalises non-RGB spectra to
    /// luminance 1; the default is the colour space's white).
    fn light_rgb(&mut self, ps: &ParamSet, name: &str, loc: &Loc) -> Result<Rgb, ParseError> {
        match ps.get_spectrum(name) {
            Some(v) => self.spectrum_value(v, true, loc),
            None => Ok(Rgb::ONE),
        }
    }

    /// The emission spectrum (spectral mode) of a light's spectrum
    /// parameter when it is not RGB: a blackbody, inline samples, or a file
    /// (`None` for RGB, absent or unreadable values; `light_rgb` reports
    /// the errors).
    fn light_spectrum(&self, ps: &ParamSet, name: &str) -> Option<EmissionSpectrum> {
        let t = match ps.get_spectrum(name)? {
            SpectrumValue::Rgb(_) => return None,
            SpectrumValue::Blackbody(t) => blackbody(t)?,
            SpectrumValue::Samples(s) => {
                let pairs: Vec<(f32, f32)> = s
                    .chunks_exact(2)
                    .map(|c| (c[0] as f32, c[1] as f32))
                    .collect();
                sampled_emission(&pairs)?
            }
            SpectrumValue::Named(n) => {
                if named_metal(n).is_some() {
                    return None;
                }
                let path = self.resolve(n);
                let bytes = lowdisc_files::read_input(&path).ok()?;
                let text = String::from_utf8(bytes).ok()?;
                sampled_emission(&parse_spectrum_text(&text, &path).ok()?)?
            }
        };
        Some(Arc::new(t))
    }

    fn positive(ps: &ParamSet, name: &str) -> Option<f32> {
        ps.get_float(name).map(|v| v as f32).filter(|&v| v > 0.0)
    }

    fn infinite_light(&mut self, ps: &ParamSet, loc: &Loc) -> Result<Light, ParseError> {
        let ctm = self.state.cur.ctm;
        let scale = ps.float_or("scale", 1.0) as f32;
        let illum = Self::positive(ps, "illuminance");
        let lerr =
            |e: crate::light::LightError| ParseError::scene(loc, format!("infinite light: {e}"));
        if ps.find("portal").is_some() {
            ps.mark_used("portal");
            // pbrt-v4's portal light is dark behind the portal.
            let instead = "the light shines from every direction";
            self.approximated(loc, "infinite light portal", instead)?;
        }
        let file = ps.get_string("filename").map(|f| self.resolve(f));
        let path = match (self.options.envmap_override.clone(), file) {
            (Some(o), f) => {
                self.envmap_used = true;
                let what = match &f {
                    Some(f) => format!(
                        "environment map {} replaced by {}",
                        f.display(),
                        o.display()
                    ),
                    None => format!(
                        "constant infinite light replaced by environment map {}",
                        o.display()
                    ),
                };
                self.warn(loc, what);
                if ps.find("L").is_some() {
                    ps.mark_used("L");
                }
                Some(o)
            }
            (None, Some(f)) => {
                if let Err(e) = lowdisc_files::check_input(&f, u64::MAX) {
                    let why = e.io_error();
                    let msg = format!(
                        "environment map {}: {why} (--envmap FILE replaces it)",
                        f.display()
                    );
                    return Err(ParseError::scene(loc, msg));
                }
                Some(f)
            }
            (None, None) => None,
        };
        Ok(match path {
            Some(p) => Light::ImageInfinite(Box::new(
                ImageInfiniteLight::from_file(&ctm, &p, None, EnvLookup::default(), scale, illum)
                    .map_err(lerr)?,
            )),
            None => {
                let l = self.light_rgb(ps, "L", loc)?;
                Light::UniformInfinite(UniformInfiniteLight::new(l, scale, illum).map_err(lerr)?)
            }
        })
    }

    /// `LightSource "type" params`.
    pub(super) fn light_directive(
        &mut self,
        ty: &str,
        ps: &ParamSet,
        loc: &Loc,
    ) -> Result<(), ParseError> {
        let ctm = self.state.cur.ctm;
        let scale = ps.float_or("scale", 1.0) as f32;
        let lerr = |e: crate::light::LightError| ParseError::scene(loc, format!("{ty} light: {e}"));
        let light = match ty {
            "point" => {
                let i = self.light_rgb(ps, "I", loc)?;
                let from = point(ps, "from", [0.0; 3]);
                Light::Point(
                    PointLight::new(&ctm, from, i, scale, Self::positive(ps, "power"))
                        .map_err(lerr)?,
                )
            }
            "spot" => {
                let i = self.light_rgb(ps, "I", loc)?;
                let from = point(ps, "from", [0.0; 3]);
                let to = point(ps, "to", [0.0, 0.0, 1.0]);
                let cone = ps.float_or("coneangle", 30.0) as f32;
                let delta = ps.float_or("conedeltaangle", 5.0) as f32;
                let power = Self::positive(ps, "power");
                Light::Spot(
                    SpotLight::new(&ctm, from, to, i, scale, cone, delta, power).map_err(lerr)?,
                )
            }
            "distant" => {
                let l = self.light_rgb(ps, "L", loc)?;
                let from = point(ps, "from", [0.0; 3]);
                let to = point(ps, "to", [0.0, 0.0, 1.0]);
                let illum = Self::positive(ps, "illuminance");
                Light::Distant(DistantLight::new(&ctm, from, to, l, scale, illum).map_err(lerr)?)
            }
            "infinite" => self.infinite_light(ps, loc)?,
            other => {
                let what = format!("LightSource \"{other}\"");
                self.approximated(loc, &what, "the light is left out")?;
                ps.into_iter().for_each(pbrt_format::Param::mark_used);
                return Ok(());
            }
        };
        ps.finish(&format!("LightSource \"{ty}\""), &mut self.warnings)?;
        let spectrum = self.light_spectrum(
            ps,
            if ty == "point" || ty == "spot" {
                "I"
            } else {
                "L"
            },
        );
        self.builder.set_emission_spectrum(spectrum);
        self.builder.add_light(light);
        self.builder.set_emission_spectrum(None);
        self.counts.lights += 1;
        Ok(())
    }

    /// `AreaLightSource "diffuse" params`: applies to later shapes in the
    /// same attribute block.
    pub(super) fn area_light_directive(
        &mut self,
        ty: &str,
        ps: &ParamSet,
        loc: &Loc,
    ) -> Result<(), ParseError> {
        if ty != "diffuse" {
            let what = format!("AreaLightSource \"{ty}\"");
            self.approximated(loc, &what, "the shapes do not emit")?;
            ps.into_iter().for_each(pbrt_format::Param::mark_used);
            return Ok(());
        }
        if ps.find("filename").is_some() {
            ps.mark_used("filename");
            let what = "image area light (AreaLightSource \"filename\")";
            self.approximated(loc, what, "\"L\" is used")?;
        }
        let l = self.light_rgb(ps, "L", loc)?;
        let scale = ps.float_or("scale", 1.0) as f32;
        if !(l.is_finite() && l.min_component() >= 0.0 && scale.is_finite() && scale >= 0.0) {
            return Err(ParseError::scene(
                loc,
                "area light L and scale must be finite and non-negative",
            ));
        }
        let spec = AreaSpec {
            l: l * scale,
            two_sided: ps.bool_or("twosided", false),
            power: Self::positive(ps, "power"),
            spectrum: self.light_spectrum(ps, "L"),
        };
        ps.finish("AreaLightSource \"diffuse\"", &mut self.warnings)?;
        self.state.cur.area = Some(spec);
        Ok(())
    }
}
