//! Render settings, in one place: what a render is asked to do
//! ([`RenderOptions`]: sampler, path tracer, threads, window, sample
//! range, spectral mode), the film's resolution, their defaults
//! ([`RenderOptions::default`], [`FilmParams::default`]) and the range of
//! each ([`ranges`]).
//!
//! **Resolution.** Every front end describes what its sources ask for as
//! [`SettingsLayer`]s (a scene file's `Sampler`, `Integrator` and `Film`;
//! the command line's flags; an experiment's configuration), each value
//! naming where it was given, and calls [`Settings::resolve`] once: for
//! every setting the last layer that gives it wins, else the default, and
//! every given value is checked, the error naming its flag or
//! `file:line:column`. The renderer, the experiment and the split crate all
//! read the result. The view (camera, film, filter) is built from it once,
//! at [`Settings::resolution`] ([`crate::view::View::new`]).
//!
//! ```
//! use lowdisc::catalog::SamplerName;
//! use lowdisc_render::settings::{Given, Settings, SettingsLayer};
//! let scene = SettingsLayer {
//!     sampler: Some(Given::new(SamplerName::Halton, "scene.pbrt:4:1: Sampler")),
//!     spp: Some(Given::new(64, "scene.pbrt:4:1: Sampler \"pixelsamples\"")),
//!     ..SettingsLayer::default()
//! };
//! let flags = SettingsLayer {
//!     spp: Some(Given::new(4, "--spp")),
//!     ..SettingsLayer::default()
//! };
//! let s = Settings::resolve(&[&scene, &flags]).unwrap();
//! assert_eq!((s.render.sampler.name, s.render.sampler.spp), (SamplerName::Halton, 4));
//! assert_eq!(s.render.integrator.max_depth, 5); // the default
//! let bad = SettingsLayer { spp: Some(Given::new(0, "--spp")), ..flags };
//! let e = Settings::resolve(&[&scene, &bad]).unwrap_err();
//! assert!(e.to_string().contains("--spp: samples per pixel 0"));
//! ```

mod layer;
mod options;
pub mod ranges;
mod sample_range;

pub use layer::{Given, SettingsLayer};
pub use options::RenderOptions;
pub use sample_range::SampleRange;

use crate::error::RenderError;
use crate::film::FilmParams;
use crate::integrator::PathIntegrator;
use lowdisc::catalog::SamplerConfig;
use ranges::Check;

/// The resolved settings of one render.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// How to render.
    pub render: RenderOptions,
    /// The film's full resolution, at which the view is built.
    pub resolution: [u32; 2],
}

impl Settings {
    /// The settings `layers` ask for, later layers overriding earlier ones,
    /// defaults for what none gives; every given value is checked and an
    /// error names where the bad one was given.
    pub fn resolve(layers: &[&SettingsLayer]) -> Result<Settings, RenderError> {
        let l = chosen(layers);
        check(&l)?;
        let d = RenderOptions::default();
        let (ds, di) = (d.sampler, d.integrator);
        let sampler = SamplerConfig {
            name: value(&l.sampler, ds.name),
            seed: value(&l.seed, ds.seed),
            threshold: value(&l.threshold, ds.threshold),
            paper_all_dims: value(&l.paper_all_dims, ds.paper_all_dims),
            spp: value(&l.spp, ds.spp),
            net: value(&l.net, ds.net),
            ..ds
        };
        if let Some(g) = &l.net {
            sampler
                .validate_net()
                .map_err(|e| RenderError::InvalidOptions(format!("{}: {e}", g.from)))?;
        }
        let integrator = PathIntegrator {
            max_depth: value(&l.max_depth, di.max_depth),
            layered_exit_weight: value(&l.layered_exit_weight, di.layered_exit_weight),
            ..di
        };
        let render = RenderOptions {
            sampler,
            integrator,
            threads: l.threads.map(|g| g.value).or(d.threads),
            window: l.window.map(|g| g.value).or(d.window),
            samples: l.samples.map(|g| g.value).or(d.samples),
            spectral: value(&l.spectral, d.spectral),
        };
        let resolution = value(&l.resolution, FilmParams::default().resolution);
        Ok(Settings { render, resolution })
    }
}

/// Checks every value of `l` (the chosen layer), naming its source.
fn check(l: &SettingsLayer) -> Result<(), RenderError> {
    let spp = value(&l.spp, RenderOptions::default().sampler.spp);
    named(&l.spp, ranges::spp)?;
    named(&l.threshold, ranges::threshold)?;
    named(&l.max_depth, ranges::max_depth)?;
    named(&l.threads, ranges::threads)?;
    named(&l.resolution, ranges::resolution)?;
    named(&l.samples, |r| ranges::samples(r, spp))
}

/// The layer of every setting's last given value.
fn chosen(layers: &[&SettingsLayer]) -> SettingsLayer {
    fn last<T: Clone>(
        layers: &[&SettingsLayer],
        field: impl Fn(&SettingsLayer) -> &Option<Given<T>>,
    ) -> Option<Given<T>> {
        layers.iter().rev().find_map(|l| field(l).clone())
    }
    SettingsLayer {
        sampler: last(layers, |l| &l.sampler),
        net: last(layers, |l| &l.net),
        spp: last(layers, |l| &l.spp),
        seed: last(layers, |l| &l.seed),
        threshold: last(layers, |l| &l.threshold),
        paper_all_dims: last(layers, |l| &l.paper_all_dims),
        max_depth: last(layers, |l| &l.max_depth),
        layered_exit_weight: last(layers, |l| &l.layered_exit_weight),
        resolution: last(layers, |l| &l.resolution),
        threads: last(layers, |l| &l.threads),
        window: last(layers, |l| &l.window),
        samples: last(layers, |l| &l.samples),
        spectral: last(layers, |l| &l.spectral),
    }
}

/// The given value, or `default`.
fn value<T: Copy>(g: &Option<Given<T>>, default: T) -> T {
    g.as_ref().map_or(default, |g| g.value)
}

/// `check` of the given value, its problem prefixed with where it was given.
fn named<T: Copy>(g: &Option<Given<T>>, check: impl Fn(T) -> Check) -> Result<(), RenderError> {
    match g {
        Some(g) => {
            check(g.value).map_err(|p| RenderError::InvalidOptions(format!("{}: {p}", g.from)))
        }
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use lowdisc::catalog::SamplerName;

    fn layer(spp: u32, from: &str) -> SettingsLayer {
        SettingsLayer {
            spp: Some(Given::new(spp, from)),
            ..SettingsLayer::default()
        }
    }

    #[test]
    fn no_layer_gives_the_defaults() {
        let s = Settings::resolve(&[]).unwrap();
        assert_eq!(s.render, RenderOptions::default());
        assert_eq!(s.resolution, FilmParams::default().resolution);
    }

    #[test]
    fn the_last_layer_that_gives_a_value_wins() {
        let scene = SettingsLayer {
            sampler: Some(Given::new(SamplerName::Halton, "scene")),
            ..layer(64, "scene")
        };
        let s = Settings::resolve(&[&scene, &layer(4, "--spp")]).unwrap();
        assert_eq!(s.render.sampler.spp, 4);
        assert_eq!(s.render.sampler.name, SamplerName::Halton);
        let s = Settings::resolve(&[&layer(4, "--spp"), &scene]).unwrap();
        assert_eq!(s.render.sampler.spp, 64);
    }

    #[test]
    fn a_bad_value_is_named_by_its_source_even_when_overridden_values_are_fine() {
        let e = Settings::resolve(&[&layer(0, "a.pbrt:3:1")]).unwrap_err();
        assert!(
            e.to_string().contains("a.pbrt:3:1: samples per pixel 0"),
            "{e}"
        );
        // An overridden bad value is never used, so it is not an error.
        assert!(Settings::resolve(&[&layer(0, "a.pbrt:3:1"), &layer(2, "--spp")]).is_ok());
        let range = SettingsLayer {
            samples: Some(Given::new(SampleRange::new(0, 8), "--sample-range")),
            ..layer(4, "--spp")
        };
        let e = Settings::resolve(&[&range]).unwrap_err();
        assert!(
            e.to_string().contains("--sample-range: sample range 0..8"),
            "{e}"
        );
    }
}
