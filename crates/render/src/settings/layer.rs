//! [`SettingsLayer`]: the settings one source asks for (a scene file, the
//! command line, an experiment's configuration), each value with the place
//! it came from ([`Given`]), so that a bad value is reported where it was
//! written.

use super::sample_range::SampleRange;
use crate::bsdf::LayeredExitWeight;
use crate::film::PixelBounds;
use lowdisc::catalog::SamplerName;
use lowdisc::net::Net;

/// A value and where it was given: a flag (`--spp`) or a scene file's
/// directive (`scene.pbrt:3:1: Sampler "pixelsamples"`).
#[derive(Clone, Debug, PartialEq)]
pub struct Given<T> {
    /// The value.
    pub value: T,
    /// Where it was given, the prefix of an error about it.
    pub from: String,
}

impl<T> Given<T> {
    /// `value`, given at `from`.
    pub fn new(value: T, from: impl Into<String>) -> Given<T> {
        Given {
            value,
            from: from.into(),
        }
    }

    /// `value` given at `from`, or nothing when `value` is `None`.
    pub fn maybe(value: Option<T>, from: &str) -> Option<Given<T>> {
        value.map(|v| Given::new(v, from))
    }
}

/// The settings one source gives; `None` where it says nothing. Layers are
/// resolved in order, a later one's values overriding an earlier one's,
/// by [`super::Settings::resolve`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SettingsLayer {
    /// The pixel sampler.
    pub sampler: Option<Given<SamplerName>>,
    /// The generator matrices of the Sobol samplers (`--net`).
    pub net: Option<Given<Net>>,
    /// Samples per pixel.
    pub spp: Option<Given<u32>>,
    /// Seed of every random choice.
    pub seed: Option<Given<u64>>,
    /// The paper permutation's threshold.
    pub threshold: Option<Given<f64>>,
    /// The paper permutation on the film dimensions too.
    pub paper_all_dims: Option<Given<bool>>,
    /// The path tracer's maximum depth.
    pub max_depth: Option<Given<u32>>,
    /// The layered materials' exit weight.
    pub layered_exit_weight: Option<Given<LayeredExitWeight>>,
    /// The film's full resolution.
    pub resolution: Option<Given<[u32; 2]>>,
    /// Worker threads.
    pub threads: Option<Given<usize>>,
    /// The pixels to render.
    pub window: Option<Given<PixelBounds>>,
    /// The sample indices to take.
    pub samples: Option<Given<SampleRange>>,
    /// Spectral rendering.
    pub spectral: Option<Given<bool>>,
}
