//! [`SamplerConfig`]: everything needed to build a named sampler, checked
//! before the sampler is built.

use super::params::Params;
use super::table::{Sampler, SamplerName};
use crate::Error;
use crate::net::Net;
use crate::paper::check_threshold;

/// The largest image side a configuration accepts.
pub const MAX_RESOLUTION: u32 = 1 << 20;

/// Everything needed to build a named sampler.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SamplerConfig {
    /// Which sampler.
    pub name: SamplerName,
    /// Seed of every random choice.
    pub seed: u64,
    /// The paper permutation's threshold in `[0, 1]`: the probability that a
    /// column is left unflipped (default 0.5).
    pub threshold: f64,
    /// Let the paper permutation act on dimensions 0-1 too (pixel samplers).
    pub paper_all_dims: bool,
    /// Samples per pixel.
    pub spp: u32,
    /// Image width and height in pixels.
    pub resolution: [u32; 2],
    /// The generator matrices of the samplers that read them
    /// ([`super::NET_SAMPLERS`]); [`Net::SOBOL`], the default, is the
    /// built-in Sobol table, and any other net is refused by the others.
    pub net: Net,
}

impl SamplerConfig {
    /// The default threshold: each column flipped with probability 1/2.
    pub const DEFAULT_THRESHOLD: f64 = 0.5;

    /// A configuration with defaults: seed 0, threshold 0.5, permutation on
    /// dimensions >= 2 only, 16 samples per pixel, a 2x2 image (the paper's
    /// figure).
    pub fn new(name: SamplerName) -> Self {
        SamplerConfig {
            name,
            seed: 0,
            threshold: Self::DEFAULT_THRESHOLD,
            paper_all_dims: false,
            spp: 16,
            resolution: [2, 2],
            net: Net::SOBOL,
        }
    }

    /// Checks the fields every sampler needs: `spp >= 1`, a threshold in
    /// `[0, 1]` (NaN rejected), sides in `1..=MAX_RESOLUTION`, and no net
    /// other than [`Net::SOBOL`] for a sampler that does not read one.
    pub fn validate(&self) -> Result<(), Error> {
        crate::pixel::check_spp(self.spp)?;
        self.validate_net()?;
        check_threshold(self.threshold)?;
        let [w, h] = self.resolution;
        if w == 0 || h == 0 || w > MAX_RESOLUTION || h > MAX_RESOLUTION {
            return Err(Error::InvalidResolution {
                width: w,
                height: h,
                reason: "each side must be between 1 and 1048576 pixels",
            });
        }
        Ok(())
    }

    /// Refuses a net other than [`Net::SOBOL`] for a sampler that does not
    /// read one.
    pub fn validate_net(&self) -> Result<(), Error> {
        if self.net.is_sobol() || self.name.takes_net() {
            return Ok(());
        }
        Err(Error::NetNotSupported {
            sampler: self.name.as_str(),
        })
    }

    /// Builds the pixel sampler, validating every field and the index range
    /// of the chosen sampler.
    ///
    /// ```
    /// use lowdisc::catalog::{SamplerConfig, SamplerName};
    /// use lowdisc::pixel::PixelSampler;
    ///
    /// let mut sampler = SamplerConfig::new(SamplerName::ZSobol).build()?;
    /// sampler.start_pixel_sample([1, 0], 3, 0);
    /// let [x, y] = sampler.get_pixel_2d();
    /// assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
    /// # Ok::<(), lowdisc::Error>(())
    /// ```
    pub fn build(&self) -> Result<Sampler, Error> {
        self.validate()?;
        self.name.build(&self.params())
    }

    /// The configuration's settings as a table constructor takes them.
    pub(crate) fn params(&self) -> Params {
        Params {
            spp: self.spp,
            resolution: self.resolution,
            seed: self.seed,
            threshold: self.threshold,
            paper_all_dims: self.paper_all_dims,
            net: self.net,
        }
    }
}
