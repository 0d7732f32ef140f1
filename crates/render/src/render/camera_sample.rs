//! One camera sample, the path of every sample from the sampler to the
//! film, written once for both colour modes: [`trace_sample`] is generic
//! over the [`FilmColour`] it traces, RGB or four sampled wavelengths.

use crate::camera::camera_sample;
use crate::integrator::{PathIntegrator, PathStats};
use crate::scene::Scene;
use crate::spectrum::sensor::sample_xyz;
use crate::spectrum::{Colour, Rgb, SampledSpectrum, SampledWavelengths};
use crate::view::View;
use lowdisc::pixel::PixelSampler;

/// What every camera sample of a render reads: the scene, the view, the
/// path tracer and the seed of the BSDFs' random walks.
#[derive(Clone, Copy, Debug)]
pub struct Shot<'a> {
    /// The scene.
    pub scene: &'a Scene,
    /// The camera, film and filter.
    pub view: &'a View,
    /// The path tracer.
    pub integrator: &'a PathIntegrator,
    /// The seed of the BSDFs' random walks (the sampler's seed).
    pub seed: u64,
}

/// A colour mode as a camera sample sees it: what it draws before the film
/// position, and what of its radiance the film adds.
pub trait FilmColour: Colour {
    /// Draws the sample's wavelengths right after the sample starts: none
    /// (and no dimension) in RGB mode; in spectral mode one `get_1d`
    /// (dimension 0, as pbrt-v4's `Get1D` before `GetCameraSample`).
    fn draw_wavelengths<S: PixelSampler>(sampler: &mut S) -> Self::Wavelengths;
    /// The value the film adds: the RGB radiance itself, or the sensor's
    /// XYZ (in an [`Rgb`]'s fields) of the sampled wavelengths.
    fn to_film(self, wavelengths: &Self::Wavelengths) -> Rgb;
}

impl FilmColour for Rgb {
    fn draw_wavelengths<S: PixelSampler>(_sampler: &mut S) {}

    fn to_film(self, _wavelengths: &()) -> Rgb {
        self
    }
}

impl FilmColour for SampledSpectrum {
    fn draw_wavelengths<S: PixelSampler>(sampler: &mut S) -> SampledWavelengths {
        SampledWavelengths::sample_visible(sampler.get_1d())
    }

    fn to_film(self, wavelengths: &SampledWavelengths) -> Rgb {
        sample_xyz(self, wavelengths)
    }
}

/// One camera sample in colour mode `C`: starts sample `index` of `pixel`
/// at dimension 0, draws the wavelengths ([`FilmColour::draw_wavelengths`]),
/// the film position (`get_pixel_2d`) and the lens (`get_2d`), turns them
/// into a camera ray through the pixel filter's importance sampling, and
/// traces it with the shot's integrator (whose vertices draw
/// [`crate::integrator::DIMS_PER_BOUNCE`] dimensions each). Returns the
/// value the film adds ([`FilmColour::to_film`]) and the filter weight.
///
/// ```
/// use lowdisc::catalog::{SamplerConfig, SamplerName};
/// use lowdisc_render::integrator::{PathIntegrator, PathStats};
/// use lowdisc_render::preset::ScenePreset;
/// use lowdisc_render::render::{Shot, trace_sample};
/// use lowdisc_render::spectrum::Rgb;
/// use lowdisc_render::view::View;
///
/// let (scene, spec) = ScenePreset::ALL[0].scene().unwrap();
/// let view = View::new(&spec, [8, 8]).unwrap();
/// let integrator = PathIntegrator::default();
/// let shot = Shot { scene: &scene, view: &view, integrator: &integrator, seed: 0 };
/// let mut config = SamplerConfig::new(SamplerName::Sobol);
/// config.resolution = [8, 8];
/// let mut sampler = config.build().unwrap();
/// let mut stats = PathStats::default();
/// let (l, weight) = trace_sample::<Rgb, _>(&shot, &mut sampler, [3, 4], 0, &mut stats);
/// assert!(l.max_component().is_finite() && weight.is_finite());
/// ```
pub fn trace_sample<C: FilmColour, S: PixelSampler>(
    shot: &Shot<'_>,
    sampler: &mut S,
    pixel: [i32; 2],
    index: u32,
    stats: &mut PathStats,
) -> (Rgb, f32) {
    sampler.start_pixel_sample([pixel[0] as u32, pixel[1] as u32], index, 0);
    let wavelengths = C::draw_wavelengths(sampler);
    let u_film = sampler.get_pixel_2d();
    let u_lens = sampler.get_2d();
    let cs = camera_sample(shot.view.filter(), pixel, u_film, u_lens);
    let ray = shot.view.camera().generate_ray_for(&cs);
    let (scene, seed) = (shot.scene, shot.seed);
    let l: C = (shot.integrator).li_for(scene, ray, sampler, seed, &wavelengths, stats);
    (l.to_film(&wavelengths), cs.filter_weight)
}
