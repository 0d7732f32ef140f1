//! [`RenderPart`]: one part of a split render (its window's exact pixel sums
//! over its sample range) and [`PartInfo`], what a part must agree on with
//! the others to be merged.

use lowdisc::catalog::SamplerConfig;
use lowdisc_image::{ImageError, RgbImage};
use lowdisc_render::content_hash::{ContentHash, ContentSink};
use lowdisc_render::film::{FilmParams, PixelBounds, PixelSum};
use lowdisc_render::integrator::PathIntegrator;
use lowdisc_render::render::{RenderOptions, RenderOutput, SampleRange};
use lowdisc_render::scene::Scene;
use lowdisc_render::spectrum::sensor::{output_matrix, sensor_to_output};
use lowdisc_render::view::View;
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
    /// The part that `output` (a render of `scene` through `view` with
    /// `opts`) holds.
    pub fn new(
        scene: &Scene,
        view: &View,
        opts: &RenderOptions,
        output: &RenderOutput,
    ) -> RenderPart {
        RenderPart::of_render(scene_hash(scene, view), view, opts, output)
    }

    /// The part that `output` holds, a render through `view` with `opts` of
    /// a scene named `scene`: for a caller that names the scene itself (an
    /// experiment's plan, by its content hash) instead of hashing the
    /// parsed scene ([`scene_hash`]) for every part.
    pub fn of_render(
        scene: String,
        view: &View,
        opts: &RenderOptions,
        output: &RenderOutput,
    ) -> RenderPart {
        RenderPart {
            info: PartInfo {
                scene,
                settings: settings(opts, view.film()),
                resolution: view.resolution(),
                film_bounds: view.pixel_bounds(),
                window: output.film.pixel_bounds(),
                samples: opts.sample_range(),
                spp: opts.sampler.spp,
                nonfinite: output.stats.nonfinite_samples,
            },
            sums: output.film.sums().to_vec(),
        }
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
        let spectral = s.get("spectral").map(String::as_str) == Some("true");
        let white_balance = s.get("white_balance").and_then(|w| w.parse().ok());
        let output = output_matrix(spectral, white_balance.unwrap_or(0.0));
        let sums = self.sums.iter().map(PixelSum::value);
        match output {
            Some(m) => sums.map(|v| sensor_to_output(&m, v)).collect(),
            None => sums.collect(),
        }
    }
}

/// The settings that change pixels, by name: every field of the render
/// options and of the film's parameters except those parts differ in
/// (threads, window, sample range) and those recorded elsewhere in
/// [`PartInfo`] (resolution, crop). The structures are destructured
/// field by field, so a new setting cannot be added without deciding here
/// whether parts that differ in it may be merged.
pub fn settings(opts: &RenderOptions, film: &FilmParams) -> BTreeMap<String, String> {
    let RenderOptions {
        sampler,
        integrator,
        threads: _,
        window: _,
        samples: _,
        spectral,
    } = *opts;
    let SamplerConfig {
        name,
        seed,
        threshold,
        paper_all_dims,
        spp,
        resolution: _,
        net,
    } = sampler;
    let PathIntegrator {
        max_depth,
        strategy,
        layered_exit_weight,
    } = integrator;
    let FilmParams {
        resolution: _,
        crop_window: _,
        pixel_bounds: _,
        iso,
        exposure_time,
        max_component_value,
        white_balance,
        filename: _,
    } = film;
    [
        ("sampler", name.to_string()),
        ("seed", seed.to_string()),
        ("spp", spp.to_string()),
        ("threshold", format!("{threshold:?}")),
        ("paper_all_dims", paper_all_dims.to_string()),
        ("maxdepth", max_depth.to_string()),
        ("light_strategy", format!("{strategy:?}")),
        ("layered_weight", layered_exit_weight.name().to_string()),
        ("spectral", spectral.to_string()),
        ("iso", format!("{iso:?}")),
        ("exposure_time", format!("{exposure_time:?}")),
        ("max_component_value", format!("{max_component_value:?}")),
        ("white_balance", format!("{white_balance:?}")),
    ]
    .into_iter()
    // The net is recorded by the hash of its matrices (not its file name),
    // and only when it is
    // not the built-in Sobol table (so parts from before nets still merge).
    .chain(net.id().map(|id| ("net", format!("{id:016x}"))))
    .map(|(k, v)| (k.to_string(), v))
    .collect()
}

/// The version of what [`scene_hash`] hashes, its first bytes: raised
/// whenever what is fed changes, so that parts hashed by another version
/// never merge with this version's.
pub const SCENE_HASH_VERSION: &str =
    "lowdisc scene hash 3: explicit serialisation of the scene, camera and filter";

/// The SHA-256 (hexadecimal) of the parsed scene and of how the view sees
/// it: the scene's [`ContentHash`] (every shape, material, light) and the
/// view's ([`lowdisc_render::view::ViewSpec`]: camera and pixel filter),
/// after [`SCENE_HASH_VERSION`], streamed through the hasher, never held
/// in memory. The film's parameters are settings ([`settings`]) and
/// [`PartInfo`] fields. It names what is rendered, not where it was read
/// from, so parts rendered from copies of a scene in different folders
/// agree.
pub fn scene_hash(scene: &Scene, view: &View) -> String {
    content_digest(SCENE_HASH_VERSION, &(scene, view.spec()))
}

/// The SHA-256 (hexadecimal) of `version` (its length and bytes) and
/// `content`'s [`ContentHash`]: [`scene_hash`] at a given version.
pub fn content_digest(version: &str, content: &impl ContentHash) -> String {
    let mut sink = HashSink {
        hasher: Sha256::new(),
        buffer: Vec::with_capacity(HashSink::CAPACITY),
    };
    version.feed(&mut sink);
    content.feed(&mut sink);
    let digest = sink.finish();
    digest.iter().fold(String::with_capacity(64), |mut s, b| {
        let _ = write!(s, "{b:02x}");
        s
    })
}

/// A [`ContentSink`] that feeds a SHA-256 hasher in blocks (the content
/// comes a few bytes at a time: a mesh is millions of floats).
struct HashSink {
    hasher: Sha256,
    buffer: Vec<u8>,
}

impl HashSink {
    const CAPACITY: usize = 1 << 16;

    fn finish(mut self) -> Vec<u8> {
        self.hasher.update(&self.buffer);
        self.hasher.finalize().to_vec()
    }
}

impl ContentSink for HashSink {
    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        if self.buffer.len() + bytes.len() > Self::CAPACITY {
            self.hasher.update(&self.buffer);
            self.buffer.clear();
        }
        self.buffer.extend_from_slice(bytes);
    }
}
