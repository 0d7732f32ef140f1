//! Renders of the path tracer, as `lowdisc render` makes them: a pbrt-v4
//! scene file or a built-in scene, its settings resolved by the renderer's
//! one [`Settings::resolve`] (the scene's layer, then the caller's), the
//! same render loop; so an image equals the CLI's with the same options bit
//! for bit.
//!
//! The built-in scenes are the CLI's: `cornell` (what `lowdisc render`
//! renders without a scene file) and the experiment's presets `direct` and
//! `gi` ([`ScenePreset`], which also set the path depth). Any other name is
//! a file.

use std::collections::HashSet;
use std::path::PathBuf;
use std::sync::atomic::AtomicBool;

use lowdisc::net::Net;
use lowdisc_render::cornell::{CORNELL_RESOLUTION, cornell_scene};
use lowdisc_render::pbrt::{LoadOptions, load_pbrt_scene};
use lowdisc_render::preset::ScenePreset;
use lowdisc_render::render::{Progress, RenderError, render_cancellable};
use lowdisc_render::scene::Scene;
use lowdisc_render::settings::{Given, Settings, SettingsLayer};
use lowdisc_render::view::{View, ViewSpec};

use super::pixel::sampler_name;
use super::{EngineError, Result};

/// The name of the CLI's built-in Cornell box.
pub const CORNELL: &str = "cornell";

/// The built-in scenes' names: the Cornell box, then the presets.
pub fn builtin_scenes() -> Vec<&'static str> {
    let mut names = vec![CORNELL];
    names.extend(ScenePreset::ALL.map(ScenePreset::name));
    names
}

/// What a render asks for; `None` takes the scene's value, else the
/// renderer's default (as the CLI's flags do).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RenderRequest {
    /// A built-in scene's name ([`builtin_scenes`]) or a pbrt-v4 file.
    pub scene: String,
    /// The pixel sampler's catalog name.
    pub sampler: Option<String>,
    /// The generator matrices of the Sobol samplers (`--net`); `None`
    /// keeps the built-in Sobol matrices.
    pub net: Option<Net>,
    /// Samples per pixel.
    pub spp: Option<u32>,
    /// Seed of every random choice.
    pub seed: Option<u64>,
    /// The path tracer's maximum depth.
    pub max_depth: Option<u32>,
    /// Width and height.
    pub resolution: Option<[u32; 2]>,
    /// Worker threads (all cores when `None`).
    pub threads: Option<usize>,
    /// The paper permutation's threshold.
    pub threshold: Option<f64>,
    /// The paper permutation on the film dimensions too.
    pub paper_all_dims: Option<bool>,
    /// Spectral rendering.
    pub spectral: bool,
    /// Render a file's unsupported pbrt-v4 features approximately.
    pub approximate: bool,
}

/// A rendered image.
#[derive(Debug, Clone, PartialEq)]
pub struct Rendered {
    /// Image rows (the film's pixel bounds).
    pub height: usize,
    /// Image columns.
    pub width: usize,
    /// Linear RGB, row-major, top row first, `height * width * 3` values.
    pub pixels: Vec<f32>,
    /// What the loader and the render warned about, each once.
    pub warnings: Vec<String>,
}

/// Renders `request`, reporting `progress(samples done, samples in all)`
/// after every tile, stopping with an error once `cancel` is set.
pub fn render(
    request: &RenderRequest,
    progress: &(dyn Fn(u64, u64) + Sync),
    cancel: &AtomicBool,
) -> Result<Rendered> {
    let flags = flags_layer(request)?;
    Settings::resolve(&[&flags]).map_err(render_error)?;
    let (scene, spec, layer, mut warnings) = load(request)?;
    let settings = Settings::resolve(&[&layer, &flags]).map_err(render_error)?;
    let view = View::new(&spec, settings.resolution).map_err(render_error)?;
    let sink = |p: Progress| progress(p.samples_done, p.samples_total);
    let out =
        render_cancellable(&scene, &view, &settings.render, &sink, cancel).map_err(render_error)?;
    warnings.extend(out.warnings);
    let mut seen = HashSet::new();
    warnings.retain(|w| seen.insert(w.clone()));
    Ok(Rendered {
        height: out.image.height(),
        width: out.image.width(),
        pixels: out.image.into_pixels().into_iter().flatten().collect(),
        warnings,
    })
}

/// The caller's settings, each named by its Python argument.
fn flags_layer(r: &RenderRequest) -> Result<SettingsLayer> {
    Ok(SettingsLayer {
        sampler: Given::maybe(
            r.sampler.as_deref().map(sampler_name).transpose()?,
            "sampler",
        ),
        net: Given::maybe(r.net, "net"),
        spp: Given::maybe(r.spp, "spp"),
        seed: Given::maybe(r.seed, "seed"),
        threshold: Given::maybe(r.threshold, "threshold"),
        paper_all_dims: Given::maybe(r.paper_all_dims, "paper_all_dims"),
        max_depth: Given::maybe(r.max_depth, "max_depth"),
        resolution: Given::maybe(r.resolution, "resolution"),
        threads: Given::maybe(r.threads, "threads"),
        spectral: r.spectral.then(|| Given::new(true, "spectral")),
        ..SettingsLayer::default()
    })
}

/// The scene, its view, the settings it asks for and the loader's warnings.
fn load(r: &RenderRequest) -> Result<(Scene, ViewSpec, SettingsLayer, Vec<String>)> {
    let builtin = |what: &str, max_depth: Option<u32>| SettingsLayer {
        resolution: Some(Given::new(CORNELL_RESOLUTION, what)),
        max_depth: max_depth.map(|d| Given::new(d, what)),
        ..SettingsLayer::default()
    };
    if r.scene == CORNELL {
        let (scene, spec) = cornell_scene().map_err(render_error)?;
        return Ok((scene, spec, builtin("the Cornell box", None), Vec::new()));
    }
    if let Some(preset) = ScenePreset::from_name(&r.scene) {
        let (scene, spec) = preset.scene().map_err(render_error)?;
        let what = format!("the {} preset", preset.name());
        let layer = builtin(&what, Some(preset.max_depth()));
        return Ok((scene, spec, layer, Vec::new()));
    }
    let path = PathBuf::from(&r.scene);
    let options = LoadOptions {
        envmap_override: None,
        approximate: r.approximate,
    };
    let loaded = load_pbrt_scene(&path, &options)
        .map_err(|e| EngineError::value(format!("cannot load scene `{}`: {e}", path.display())))?;
    Ok((
        loaded.scene,
        loaded.view,
        loaded.settings.layer,
        loaded.warnings,
    ))
}

/// A render error's one-line message.
fn render_error(e: RenderError) -> EngineError {
    EngineError::value(e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// No progress reports.
    fn quiet(_: u64, _: u64) {}

    fn request(scene: &str) -> RenderRequest {
        RenderRequest {
            scene: scene.into(),
            spp: Some(2),
            resolution: Some([8, 6]),
            threads: Some(1),
            ..RenderRequest::default()
        }
    }

    #[test]
    fn a_builtin_scene_renders_at_the_asked_size_and_the_same_bits_twice() {
        let go = AtomicBool::new(false);
        let a = render(&request("cornell"), &quiet, &go).unwrap();
        assert_eq!((a.height, a.width, a.pixels.len()), (6, 8, 6 * 8 * 3));
        assert!(a.pixels.iter().any(|&v| v > 0.0));
        let b = render(
            &RenderRequest {
                threads: Some(2),
                ..request("cornell")
            },
            &quiet,
            &go,
        )
        .unwrap();
        assert_eq!(a, b);
        // The presets are other scenes (direct: depth 1), the same size.
        let direct = render(&request("direct"), &quiet, &go).unwrap();
        assert_eq!(direct.pixels.len(), a.pixels.len());
        assert_ne!(direct.pixels, a.pixels);
    }

    #[test]
    fn a_net_reaches_the_sampler_and_a_sampler_without_one_refuses_it() {
        use crate::engine::nets::{NetSource, resolve};
        let go = AtomicBool::new(false);
        let base = RenderRequest {
            sampler: Some("zsobol-4d".into()),
            ..request("cornell")
        };
        let plain = render(&base, &quiet, &go).unwrap();
        let sobol = lowdisc::sobol::matrices()[..4].to_vec();
        let same = RenderRequest {
            net: Some(resolve(&NetSource::Matrices(sobol)).unwrap()),
            ..base.clone()
        };
        assert_eq!(render(&same, &quiet, &go).unwrap(), plain);
        let onetwo = RenderRequest {
            net: Net::named("onetwo"),
            ..base.clone()
        };
        assert_ne!(render(&onetwo, &quiet, &go).unwrap().pixels, plain.pixels);
        let halton = RenderRequest {
            sampler: Some("halton".into()),
            ..onetwo
        };
        let e = render(&halton, &quiet, &go).unwrap_err().to_string();
        assert!(
            e.contains("net: sampler `halton` does not take generator matrices"),
            "{e}"
        );
    }

    #[test]
    fn bad_requests_name_the_argument_or_the_file() {
        let go = AtomicBool::new(false);
        let err = |r: RenderRequest| render(&r, &quiet, &go).unwrap_err().to_string();
        let zero = RenderRequest {
            spp: Some(0),
            ..request("cornell")
        };
        let zero = err(zero);
        assert!(zero.contains("spp: samples per pixel 0"), "{zero}");
        let bad = RenderRequest {
            sampler: Some("sobl".into()),
            ..request("cornell")
        };
        assert!(err(bad).contains("unknown sampler \"sobl\""));
        let missing = err(request("no/such/scene.pbrt"));
        assert!(
            missing.starts_with("cannot load scene `no/such/scene.pbrt`"),
            "{missing}"
        );
        let stop = AtomicBool::new(true);
        let cancelled = render(&request("cornell"), &quiet, &stop).unwrap_err();
        assert!(cancelled.to_string().contains("cancelled"));
    }
}
