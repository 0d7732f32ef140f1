//! Power-proportional light selection (pbrt-v4's `PowerLightSampler`).

use super::Light;
use crate::sampling::Distribution1D;

/// Chooses a light with probability proportional to the average of its RGB
/// power ([`Light::phi`]), uniformly when every power is 0 (or not finite).
///
/// Build it after [`Light::preprocess`], since lights at infinity report
/// their power through the scene's bounding disk.
#[derive(Clone, Debug, PartialEq)]
pub struct LightSampler {
    /// `None` when there are no lights.
    distribution: Option<Distribution1D>,
}

impl LightSampler {
    /// A sampler over `lights` (indices follow the slice).
    pub fn new(lights: &[Light]) -> Self {
        let powers: Vec<f32> = lights.iter().map(|l| l.phi().average()).collect();
        Self::from_powers(&powers)
    }

    /// A sampler from explicit selection weights (negative or non-finite
    /// weights count as 0).
    pub fn from_powers(powers: &[f32]) -> Self {
        let clean: Vec<f32> = powers
            .iter()
            .map(|&p| if p.is_finite() && p > 0.0 { p } else { 0.0 })
            .collect();
        LightSampler {
            distribution: Distribution1D::new(&clean),
        }
    }

    /// Number of lights.
    pub fn len(&self) -> usize {
        self.distribution.as_ref().map_or(0, Distribution1D::len)
    }
    /// True when there is no light to choose.
    pub fn is_empty(&self) -> bool {
        self.distribution.is_none()
    }

    /// Picks a light with the uniform sample `u`: `(index, probability)`,
    /// or `None` when there are no lights.
    pub fn sample(&self, u: f32) -> Option<(usize, f32)> {
        let s = self.distribution.as_ref()?.sample_discrete(u);
        Some((s.index, s.pmf))
    }

    /// Probability that [`LightSampler::sample`] picks light `index` (0 when
    /// out of range).
    pub fn pmf(&self, index: usize) -> f32 {
        self.distribution.as_ref().map_or(0.0, |d| d.pmf(index))
    }
}
