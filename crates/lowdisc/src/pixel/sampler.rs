//! [`Sampler`]: one enum over every pixel sampler, dispatching
//! [`PixelSampler`] by `match` so renderers can hold a concrete, `Clone +
//! Send + Sync` value without trait objects. Build one from a
//! [`crate::catalog::SamplerConfig`].

use super::{
    BurleySampler, CascadedSobolSampler, Dims, GlobalSobolSampler, HaltonSampler,
    IndependentSampler, PaddedSobolSampler, PixelSampler, PixelXorSampler, PmjSampler,
    StratifiedSampler, ZOrderSzSampler, ZSobolJointSampler, ZSobolSampler,
};

/// Every pixel sampler of the crate.
#[derive(Debug, Clone)]
pub enum Sampler {
    /// Independent uniform random numbers.
    Independent(IndependentSampler),
    /// Jittered stratified samples.
    Stratified(StratifiedSampler),
    /// Global image-plane Halton (pbrt).
    Halton(HaltonSampler),
    /// Global image-plane Sobol (pbrt-v3), plain, randomized or paper-permuted.
    GlobalSobol(GlobalSobolSampler),
    /// Padded per-pixel Sobol (pbrt-v4).
    PaddedSobol(PaddedSobolSampler),
    /// Z-order blue-noise Sobol (pbrt-v4's default).
    ZSobol(ZSobolSampler),
    /// Burley 2020: shuffled, Owen-scrambled, 4-D padded per-pixel Sobol.
    Burley(BurleySampler),
    /// Per-pixel Sobol with a random digital shift.
    PixelXor(PixelXorSampler),
    /// PMJ02 / pmj02bn point sets.
    Pmj(PmjSampler),
    /// Z-order Sobol padded by 4-D groups.
    ZSobolJoint(ZSobolJointSampler),
    /// Z-order over the base-4 (0,4)-sequence, film and light sample in 5-D.
    ZOrderSz(ZOrderSzSampler),
    /// Cascaded Sobol': every consecutive pair of dimensions a (0,m,2)-net.
    CascadedSobol(CascadedSobolSampler),
}

/// Applies `$body` to the sampler inside whatever variant `$s` is.
macro_rules! dispatch {
    ($s:expr, $inner:ident => $body:expr) => {
        match $s {
            Sampler::Independent($inner) => $body,
            Sampler::Stratified($inner) => $body,
            Sampler::Halton($inner) => $body,
            Sampler::GlobalSobol($inner) => $body,
            Sampler::PaddedSobol($inner) => $body,
            Sampler::ZSobol($inner) => $body,
            Sampler::Burley($inner) => $body,
            Sampler::PixelXor($inner) => $body,
            Sampler::Pmj($inner) => $body,
            Sampler::ZSobolJoint($inner) => $body,
            Sampler::ZOrderSz($inner) => $body,
            Sampler::CascadedSobol($inner) => $body,
        }
    };
}

impl Sampler {
    /// A copy for one stream of work (a tile): samplers with internal
    /// sequential state (the paper's literal mode) are re-seeded from
    /// `stream`, so output does not depend on how tiles are spread over
    /// threads; stateless samplers are simply cloned.
    pub fn with_stream(&self, stream: u64) -> Self {
        match self {
            Sampler::GlobalSobol(s) => Sampler::GlobalSobol(s.with_stream(stream)),
            other => other.clone(),
        }
    }

    /// True when a value depends on the calls made before it in the same
    /// stream (the paper's literal mode), not only on the pixel, sample
    /// index and dimension: to reproduce part of a tile, a renderer must
    /// replay the tile's earlier calls in their order.
    pub fn is_order_dependent(&self) -> bool {
        match self {
            Sampler::GlobalSobol(s) => s.is_order_dependent(),
            _ => false,
        }
    }
}

impl PixelSampler for Sampler {
    fn samples_per_pixel(&self) -> u32 {
        dispatch!(self, s => s.samples_per_pixel())
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        dispatch!(self, s => s.start_pixel_sample(pixel, sample_index, dimension))
    }

    fn get_1d(&mut self) -> f32 {
        dispatch!(self, s => s.get_1d())
    }

    fn get_2d(&mut self) -> [f32; 2] {
        dispatch!(self, s => s.get_2d())
    }

    fn get_pixel_2d(&mut self) -> [f32; 2] {
        dispatch!(self, s => s.get_pixel_2d())
    }

    fn get_values<const N: usize>(&mut self, dims: [Dims; N]) -> [[f32; 2]; N]
    where
        Self: Sized,
    {
        dispatch!(self, s => s.get_values(dims))
    }
}

impl From<GlobalSobolSampler> for Sampler {
    fn from(s: GlobalSobolSampler) -> Self {
        Sampler::GlobalSobol(s)
    }
}

impl From<PaddedSobolSampler> for Sampler {
    fn from(s: PaddedSobolSampler) -> Self {
        Sampler::PaddedSobol(s)
    }
}

impl From<ZSobolSampler> for Sampler {
    fn from(s: ZSobolSampler) -> Self {
        Sampler::ZSobol(s)
    }
}

impl From<IndependentSampler> for Sampler {
    fn from(s: IndependentSampler) -> Self {
        Sampler::Independent(s)
    }
}

impl From<StratifiedSampler> for Sampler {
    fn from(s: StratifiedSampler) -> Self {
        Sampler::Stratified(s)
    }
}

impl From<HaltonSampler> for Sampler {
    fn from(s: HaltonSampler) -> Self {
        Sampler::Halton(s)
    }
}

impl From<BurleySampler> for Sampler {
    fn from(s: BurleySampler) -> Self {
        Sampler::Burley(s)
    }
}

impl From<PixelXorSampler> for Sampler {
    fn from(s: PixelXorSampler) -> Self {
        Sampler::PixelXor(s)
    }
}

impl From<PmjSampler> for Sampler {
    fn from(s: PmjSampler) -> Self {
        Sampler::Pmj(s)
    }
}

impl From<ZSobolJointSampler> for Sampler {
    fn from(s: ZSobolJointSampler) -> Self {
        Sampler::ZSobolJoint(s)
    }
}

impl From<ZOrderSzSampler> for Sampler {
    fn from(s: ZOrderSzSampler) -> Self {
        Sampler::ZOrderSz(s)
    }
}

impl From<CascadedSobolSampler> for Sampler {
    fn from(s: CascadedSobolSampler) -> Self {
        Sampler::CascadedSobol(s)
    }
}
