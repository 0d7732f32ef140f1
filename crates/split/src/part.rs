//! [`RenderPart`]: one part of a split render (its window's exact pixel sums
//! over its sample range) and [`PartInfo`], what a part must agree on with
//! the others to be merged.

use lowdisc_image::{ImageError, RgbImage};
use lowdisc_render::film::{Film, FilmParams, PixelBounds, PixelSum};
use lowdisc_render::render::{RenderError, RenderOptions, RenderOutput, SampleRange};
use lowdisc_render::scene::Scene;
use lowdisc_render::spectrum::sensor::{output_from_sensor, sensor_to_output};
use sha2::{Digest, Sha256};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// What a part is a part of, and which part it is.
#[derive(Clone, Debug, PartialEq)]
pub struct PartInfo {
    /// [`scene_hash`] of the rendered scene.
    pub scene: String,
    /// The settings that change pixels ([`settings`]), by name.
    pub settings: BTreeMap<String, String>,
    /// The full image's resolution (the EXR display window).
    pub resolution: [u32; 2],
    /// The film's pixel bounds (the scene's crop): the tile grid's domain and
    /// what a complete merge covers.
    pub film_bounds: PixelBounds,
    /// The pixels this part holds (the EXR data window).
    pub window: PixelBounds,
    /// The sample indices this part's sums cover.
    pub samples: SampleRange,
    /// The samples per pixel of the whole render.
    pub spp: u32,
    /// Samples dropped for NaN or infinite radiance.
    pub nonfinite: u64,
}

/// One part of a split render: [`PartInfo`] and each pixel's sums,
/// row-major over `info.window`.
#[derive(Clone, Debug, PartialEq)]
pub struct RenderPart {
    /// What the part is.
    pub info: PartInfo,
    /// Each pixel's exact sums.
    pub sums: Vec<PixelSum>,
}

impl RenderPart {
    /// The part that `output` (a render of `scene` with `opts`) holds.
    pub fn new(
        scene: &Scene,
        opts: &RenderOptions,
        output: &RenderOutput,
    ) -> Result<RenderPart, RenderError> {
        RenderPart::of_render(scene_hash(scene), &scene.film().params, opts, output)
    }

    /// The part that `output` holds, a render with `opts` of a scene named
    /// `scene` whose film has `params`: for a caller that names the scene
    /// itself (an experiment's plan, by its content hash) instead of
    /// hashing the parsed scene ([`scene_hash`]) for every part.
    pub fn of_render(
        scene: String,
        params: &FilmParams,
        opts: &RenderOptions,
        output: &RenderOutput,
    ) -> Result<RenderPart, RenderError> {
        let film_bounds = Film::checked_bounds(params).map_err(RenderError::Film)?;
        Ok(RenderPart {
            info: PartInfo {
                scene,
                settings: settings_of(params, opts),
                resolution: params.resolution,
                film_bounds,
                window: output.film.pixel_bounds(),
                samples: opts.sample_range(),
                spp: opts.sampler.spp,
                nonfinite: output.stats.nonfinite_samples,
            },
            sums: output.film.sums().to_vec(),
        })
    }

    /// True when the part holds every pixel of the film and every sample.
    pub fn is_complete(&self) -> bool {
        let i = &self.info;
        i.window == i.film_bounds && i.samples == SampleRange::all(i.spp)
    }

    /// The part's image: [`RenderPart::values`], the same values a single
    /// render's film gives.
    /// Fails only when `sums` does not match the window's size.
    pub fn image(&self) -> Result<RgbImage, ImageError> {
        let w = self.info.window;
        RgbImage::from_pixels(w.width(), w.height(), self.values())
    }

    /// Each pixel's output value: its [`PixelSum::value`], which a spectral
    /// render's film then takes from the sensor's XYZ to linear sRGB with
    /// the film's white balance (recorded in the settings), as the film
    /// does.
    pub fn values(&self) -> Vec<[f32; 3]> {
        let s = &self.info.settings;
        let output = (s.get("spectral").map(String::as_str) == Some("true")).then(|| {
            let white_balance = s.get("white_balance").and_then(|w| w.parse().ok());
            output_from_sensor(white_balance.unwrap_or(0.0))
        });
        let sums = self.sums.iter().map(PixelSum::value);
        match output {
            Some(m) => sums.map(|v| sensor_to_output(&m, v)).collect(),
            None => sums.collect(),
        }
    }
}

/// [`settings`], and for a spectral render the film's white balance, which
/// takes its pixels from the sensor to the output.
fn settings_of(params: &FilmParams, opts: &RenderOptions) -> BTreeMap<String, String> {
    let mut s = settings(opts);
    if opts.spectral {
        s.insert(
            "white_balance".into(),
            format!("{:?}", params.white_balance),
        );
    }
    s
}

/// The settings of `opts` that change pixels, by name: the sampler, its
/// seed, samples per pixel, threshold and paper-dimensions flag, and the
/// path tracer's depth and light strategy. Threads, window and sample range
/// are not settings: parts differ in them.
pub fn settings(opts: &RenderOptions) -> BTreeMap<String, String> {
    let s = &opts.sampler;
    [
        ("sampler", s.name.to_string()),
        ("seed", s.seed.to_string()),
        ("spp", s.spp.to_string()),
        ("threshold", format!("{:?}", s.threshold)),
        ("paper_all_dims", s.paper_all_dims.to_string()),
        ("maxdepth", opts.integrator.max_depth.to_string()),
        ("light_strategy", format!("{:?}", opts.integrator.strategy)),
        ("spectral", opts.spectral.to_string()),
    ]
    .into_iter()
    .map(|(k, v)| (k.to_string(), v))
    .collect()
}

/// The SHA-256 (hexadecimal) of the parsed scene: [`Scene::write_content`]
/// (every shape, material, light, the camera and the film's parameters in
/// `Debug` form, floats in their exact shortest form) streamed through the
/// hasher, never held in memory. It names what is rendered, not where it was read from, so parts
/// rendered from copies of a scene in different folders agree.
pub fn scene_hash(scene: &Scene) -> String {
    let mut sink = HashSink(Sha256::new());
    // The sink never fails, and `Debug` of the scene's data never fails.
    let _ = scene.write_content(&mut sink);
    let digest = sink.0.finalize();
    digest.iter().fold(String::with_capacity(64), |mut s, b| {
        let _ = write!(s, "{b:02x}");
        s
    })
}

/// A `fmt::Write` that feeds a hasher.
struct HashSink(Sha256);

impl std::fmt::Write for HashSink {
    fn write_str(&mut self, s: &str) -> std::fmt::Result {
        self.0.update(s.as_bytes());
        Ok(())
    }
}
