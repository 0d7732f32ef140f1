//! Rendering options: `Camera`, `Film`, `Sampler`, `Integrator` and
//! `PixelFilter`.

use super::loader::PbrtLoader;
use crate::camera::PerspectiveParams;
use crate::filter::{Filter, FilterParams};
use crate::settings::Given;
use crate::view::CameraSpec;
use lowdisc::catalog::SamplerName;
use pbrt_format::{Loc, ParamSet, ParseError};

fn float4(ps: &ParamSet, name: &str) -> Option<[f32; 4]> {
    let v = ps.get_floats(name)?;
    (v.len() == 4).then(|| [v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32])
}

fn resolution_value(v: i64, name: &str, loc: &Loc) -> Result<u32, ParseError> {
    u32::try_from(v)
        .ok()
        .filter(|&r| (1..=1 << 16).contains(&r))
        .ok_or_else(|| {
            ParseError::scene(loc, format!("Film: {name} {v} must be between 1 and 65536"))
        })
}

impl PbrtLoader {
    /// `Camera "perspective"`: the CTM is camera-from-world.
    pub(super) fn camera_directive(
        &mut self,
        ty: &str,
        ps: &ParamSet,
        loc: &Loc,
    ) -> Result<(), ParseError> {
        self.camera_loc = Some(loc.clone());
        // pbrt-v4's camera is in the current interface's outside medium.
        self.builder.set_camera_medium(self.state.cur.media.outside);
        let camera_from_world = self.state.cur.ctm;
        let world_from_camera = camera_from_world.inverse();
        self.state.named.insert("camera".into(), world_from_camera);
        if ty != "perspective" {
            let what = format!("Camera \"{ty}\"");
            self.approximated(loc, &what, "a perspective camera is used")?;
        }
        let d = PerspectiveParams::default();
        let params = PerspectiveParams {
            fov: ps.float_or("fov", d.fov as f64) as f32,
            lens_radius: ps.float_or("lensradius", 0.0) as f32,
            focal_distance: ps.float_or("focaldistance", d.focal_distance as f64) as f32,
            frame_aspect_ratio: ps.get_float("frameaspectratio").map(|v| v as f32),
            screen_window: float4(ps, "screenwindow"),
        };
        let open = ps.float_or("shutteropen", 0.0);
        let close = ps.float_or("shutterclose", 1.0);
        if !(close > open) {
            return Err(ParseError::scene(
                loc,
                "Camera: shutterclose must exceed shutteropen",
            ));
        }
        self.film.exposure_time = (close - open) as f32;
        ps.finish(&format!("Camera \"{ty}\""), &mut self.warnings)?;
        self.camera = Some(CameraSpec {
            world_from_camera,
            params,
        });
        Ok(())
    }

    /// `Film "rgb"`.
    pub(super) fn film_directive(
        &mut self,
        ty: &str,
        ps: &ParamSet,
        loc: &Loc,
    ) -> Result<(), ParseError> {
        self.film_loc = Some(loc.clone());
        match ty {
            "rgb" => {}
            // Their RGB channels are the "rgb" film's image.
            "gbuffer" | "spectral" => self.warn(
                loc,
                format!("Film \"{ty}\": only the RGB image is written, as by Film \"rgb\""),
            ),
            _ => {
                let what = format!("Film \"{ty}\"");
                self.approximated(loc, &what, "Film \"rgb\" is used")?;
            }
        }
        let [w, h] = self.film.resolution;
        let w = resolution_value(ps.int_or("xresolution", w as i64), "xresolution", loc)?;
        let h = resolution_value(ps.int_or("yresolution", h as i64), "yresolution", loc)?;
        self.film.resolution = [w, h];
        if let Some(f) = ps.get_string("filename") {
            self.film.filename = f.to_string();
            self.settings.output = Some(f.to_string());
        }
        self.film.iso = ps.float_or("iso", self.film.iso as f64) as f32;
        self.film.max_component_value = ps.float_or("maxcomponentvalue", f64::INFINITY) as f32;
        self.film.crop_window = float4(ps, "cropwindow");
        self.film.pixel_bounds = ps
            .get_ints("pixelbounds")
            .filter(|v| v.len() == 4)
            .map(|v| [v[0] as i32, v[1] as i32, v[2] as i32, v[3] as i32]);
        if let Some(s) = ps.get_string("sensor")
            && s != "cie1931"
        {
            let what = format!("Film sensor \"{s}\"");
            self.approximated(loc, &what, "the cie1931 sensor is used")?;
        }
        let white_balance = ps.float_or("whitebalance", 0.0);
        if !(white_balance >= 0.0 && white_balance.is_finite()) {
            return Err(ParseError::scene(
                loc,
                format!(
                    "Film: whitebalance {white_balance} must be 0 (none) or a temperature in kelvin"
                ),
            ));
        }
        self.film.white_balance = white_balance as f32;
        // The diagonal only matters for the realistic camera; half floats
        // only change the file's precision.
        for p in ["diagonal", "savefp16"] {
            ps.mark_used(p);
        }
        ps.finish(&format!("Film \"{ty}\""), &mut self.warnings)?;
        Ok(())
    }

    /// `Sampler`: its type mapped to a lowdisc sampler, and `pixelsamples`.
    pub(super) fn sampler_directive(
        &mut self,
        ty: &str,
        ps: &ParamSet,
        loc: &Loc,
    ) -> Result<(), ParseError> {
        let rand = ps.get_string("randomization").map(str::to_string);
        // Without a count the settings' default applies (pbrt's, 16).
        let spp = if ty == "stratified" {
            ps.mark_used("jitter");
            let (x, y) = (ps.get_int("xsamples"), ps.get_int("ysamples"));
            (x.is_some() || y.is_some()).then(|| x.unwrap_or(4).saturating_mul(y.unwrap_or(4)))
        } else {
            ps.get_int("pixelsamples")
        };
        let name = match (ty, rand.as_deref()) {
            ("halton", Some("owen") | Some("fastowen")) => SamplerName::HaltonOwen,
            ("halton", _) => SamplerName::Halton,
            ("sobol", Some("none")) => SamplerName::Sobol,
            ("sobol", Some("permutedigits")) => SamplerName::SobolXor,
            ("sobol", Some("owen")) => SamplerName::SobolOwen,
            ("sobol", _) => SamplerName::SobolFastOwen,
            ("zsobol", _) => SamplerName::ZSobol,
            ("paddedsobol", _) => SamplerName::PaddedSobol,
            ("pmj02bn", _) => SamplerName::Pmj02Bn,
            ("independent", _) => SamplerName::Independent,
            ("stratified", _) => SamplerName::Stratified,
            (other, _) => {
                self.warn(
                    loc,
                    format!("Sampler \"{other}\" is not available; using zsobol"),
                );
                SamplerName::ZSobol
            }
        };
        if ps.find("seed").is_some() {
            ps.mark_used("seed");
            self.warn(
                loc,
                "Sampler \"seed\" is ignored; the renderer's --seed applies",
            );
        }
        let at = format!("{loc}: Sampler \"{ty}\"");
        if let Some(spp) = spp {
            match u32::try_from(spp).ok().filter(|&n| n > 0) {
                Some(n) => self.settings.layer.spp = Some(Given::new(n, at.clone())),
                None => self.warn(loc, format!("Sampler: invalid sample count {spp}; ignored")),
            }
        }
        self.settings.layer.sampler = Some(Given::new(name, at));
        self.settings.sampler_type = Some(ty.to_string());
        ps.finish(&format!("Sampler \"{ty}\""), &mut self.warnings)
    }

    /// `Integrator`: the path tracer's maximum depth.
    pub(super) fn integrator_directive(
        &mut self,
        ty: &str,
        ps: &ParamSet,
        loc: &Loc,
    ) -> Result<(), ParseError> {
        // Both are rendered: a scene with media by the volumetric path
        // tracer (see `media.rs`), one without by the path tracer, which
        // computes what pbrt-v4's "volpath" computes there.
        if !matches!(ty, "path" | "volpath") {
            let what = format!("Integrator \"{ty}\"");
            self.approximated(loc, &what, "rendered by the path tracer")?;
            // The other integrator's own parameters mean nothing here.
            for p in ps {
                if !matches!(p.name.as_str(), "maxdepth" | "regularize" | "lightsampler") {
                    p.mark_used();
                }
            }
        }
        // Without "maxdepth" the settings' default applies (pbrt's, 5).
        if let Some(depth) = ps.get_int("maxdepth") {
            match u32::try_from(depth) {
                Ok(d) => {
                    let at = format!("{loc}: Integrator \"maxdepth\"");
                    self.settings.layer.max_depth = Some(Given::new(d, at));
                }
                Err(_) => self.warn(loc, format!("Integrator: maxdepth {depth} < 0; ignored")),
            }
        }
        if ps.bool_or("regularize", false) {
            self.approximated(loc, "Integrator \"regularize\"", "no regularization")?;
        }
        // The light sampler only changes the noise.
        if ps.find("lightsampler").is_some() {
            ps.mark_used("lightsampler");
            self.unsupported(loc, "Integrator parameter \"lightsampler\"");
        }
        self.settings.integrator = Some(ty.to_string());
        ps.finish(&format!("Integrator \"{ty}\""), &mut self.warnings)
    }

    /// `PixelFilter`.
    pub(super) fn filter_directive(
        &mut self,
        ty: &str,
        ps: &ParamSet,
        loc: &Loc,
    ) -> Result<(), ParseError> {
        let f = |n: &str| ps.get_float(n).map(|v| v as f32);
        let p = FilterParams {
            x_radius: f("xradius"),
            y_radius: f("yradius"),
            sigma: f("sigma"),
            b: f("B"),
            c: f("C"),
            tau: f("tau"),
        };
        self.filter = Filter::create(ty, &p)
            .map_err(|e| ParseError::scene(loc, format!("PixelFilter: {e}")))?;
        ps.finish(&format!("PixelFilter \"{ty}\""), &mut self.warnings)?;
        Ok(())
    }
}
