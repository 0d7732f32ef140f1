//! [`Params`]: what a constructor of the sampler table is given, the
//! checked fields of a [`super::SamplerConfig`] without the name.

use crate::Error;
use crate::net::Net;
use crate::pixel::{GlobalSobolMode, GlobalSobolSampler};

/// The settings a table entry builds its sampler from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Params {
    /// Samples per pixel (at least 1).
    pub spp: u32,
    /// Image width and height in pixels.
    pub resolution: [u32; 2],
    /// Seed of every random choice.
    pub seed: u64,
    /// The paper permutation's threshold, in `[0, 1]`.
    pub threshold: f64,
    /// Let the paper permutation act on dimensions 0-1 too.
    pub paper_all_dims: bool,
    /// The generator matrices of the samplers that read them.
    pub net: Net,
}

impl Params {
    /// The global Sobol sampler in `mode` with these settings.
    pub fn global_sobol(&self, mode: GlobalSobolMode) -> Result<GlobalSobolSampler, Error> {
        GlobalSobolSampler::with_net(self.spp, self.resolution, mode, self.seed, self.net)
    }
}
