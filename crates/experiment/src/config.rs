//! The settings of one experiment ([`ExperimentConfig`]), the fixed choices
//! of the reference render, and the checks that every setting is in range.
//!
//! The render settings every render of the experiment shares (threshold,
//! depth, threads, spectral mode) are the renderer's one settings type:
//! [`ExperimentConfig::settings`] is their [`SettingsLayer`], each value
//! named by its flag, and [`ExperimentConfig::render_options`] resolves it
//! with one render's own layer (sampler, seed, spp, ...) through
//! [`Settings::resolve`], where the defaults and the ranges are declared.

use std::path::PathBuf;

use anyhow::{Result, bail};
use lowdisc::catalog::SamplerName;
use lowdisc::net::Net;
use lowdisc_render::preset::ScenePreset;
use lowdisc_render::render::RenderOptions;
use lowdisc_render::settings::{Given, Settings, SettingsLayer, ranges};

/// The seed of the reference render.
pub const REF_SEED: u64 = 0x0005_EED0_F2EF;
/// The sampler of the reference render.
pub const REF_SAMPLER: SamplerName = SamplerName::SobolOwen;
/// The samplers compared by default.
pub const DEFAULT_SAMPLERS: &str = "independent,stratified,halton,sobol,paper,paper-repro,sobol-xor,padded-sobol,sobol-fast-owen,zsobol";
/// The least default unit budget of [`ExperimentConfig::unit_budget`]: 2^23
/// camera samples (about 10 s at the 1.26 s per million samples the README
/// measured for the default experiment on its idle 2-core machine), so that
/// small experiments are not cut into units whose start costs as much as
/// their render.
pub const DEFAULT_UNIT_SAMPLES: u64 = 1 << 23;
/// The smallest `--unit-samples` accepted.
pub const MIN_UNIT_SAMPLES: u64 = 1 << 10;

/// A complete experiment: what to render, how often and where to write.
#[derive(Debug, Clone)]
pub struct ExperimentConfig {
    /// Scene file or `None` for the built-in scene.
    pub scene: Option<PathBuf>,
    /// A built-in comparison scene (`lowdisc_render::preset`) instead of
    /// the default built-in scene; never together with `scene`.
    pub preset: Option<ScenePreset>,
    /// Border in pixels around directly visible emitters left out of the
    /// masked metrics ([`crate::quality`]).
    pub emitter_border: u32,
    /// Standard deviation in pixels of the blurred MSE's Gaussian.
    pub blur_sigma: f64,
    /// Samplers, in the order given.
    pub samplers: Vec<SamplerName>,
    /// The generator matrices of the compared samplers that read a net
    /// (`--net`; never of the references, which stay Sobol's).
    pub net: Net,
    /// Samples per pixel.
    pub spp: u32,
    /// Runs per sampler.
    pub runs: u32,
    /// Resolution.
    pub resolution: [u32; 2],
    /// Reference spp.
    pub ref_spp: u32,
    /// Convergence plot cap.
    pub conv_max: u32,
    /// Resolution of the convergence series.
    pub conv_res: [u32; 2],
    /// Seeds of each sampler's convergence series (`0..conv_seeds`): the
    /// log-log slope is fitted per seed and reported with its interval
    /// over the seeds.
    pub conv_seeds: u32,
    /// Reference spp of the convergence series.
    pub conv_ref_spp: u32,
    /// Environment map.
    pub envmap: Option<PathBuf>,
    /// Load a scene file that uses pbrt-v4 features lowdisc lacks, rendering
    /// them approximately (`--approximate`; see
    /// `lowdisc_render::pbrt::LoadOptions::approximate`).
    pub approximate: bool,
    /// Paper threshold (renders of `paper`/`paper-repro` and the figure).
    pub threshold: f64,
    /// Maximum depth.
    pub max_depth: u32,
    /// Threads.
    pub threads: Option<usize>,
    /// Render spectrally (wavelength sampling in the loop) instead of in
    /// RGB, the default.
    pub spectral: bool,
    /// The most camera samples of a unit that is cut (`--unit-samples`;
    /// `None`: see [`ExperimentConfig::unit_budget`]).
    pub unit_samples: Option<u64>,
    /// Output folder.
    pub out: PathBuf,
    /// The command line that asked for this experiment, kept in `results.json`.
    pub command: Vec<String>,
}

impl ExperimentConfig {
    /// The camera samples a unit may hold before its render is cut
    /// ([`crate::cut::cut`]): `--unit-samples`, else the larger of a run's
    /// samples (a run is never cut) and [`DEFAULT_UNIT_SAMPLES`].
    pub fn unit_budget(&self) -> u64 {
        self.unit_samples.unwrap_or_else(|| {
            crate::cut::samples(self.resolution, self.spp).max(DEFAULT_UNIT_SAMPLES)
        })
    }

    /// The render settings every render of the experiment shares, each
    /// named by its flag.
    pub fn settings(&self) -> SettingsLayer {
        SettingsLayer {
            threshold: Some(Given::new(self.threshold, "--threshold")),
            max_depth: Some(Given::new(self.max_depth, "--maxdepth")),
            threads: Given::maybe(self.threads, "--threads"),
            spectral: Some(Given::new(self.spectral, "--spectral")),
            ..SettingsLayer::default()
        }
    }

    /// The render options of one render: [`ExperimentConfig::settings`],
    /// then `render`'s own settings (its sampler, seed, spp, ...), resolved
    /// by [`Settings::resolve`]; an error names the setting's source.
    pub fn render_options(&self, render: &SettingsLayer) -> Result<RenderOptions> {
        Ok(Settings::resolve(&[&self.settings(), render])?.render)
    }

    /// Checks that every setting is in range and that the scene and
    /// environment map files exist; the messages name the command-line
    /// options.
    pub fn validate(&self) -> Result<()> {
        self.validate_ranges()?;
        if let Some(e) = &self.envmap {
            if !e.is_file() {
                bail!("--envmap `{}` is not a file", e.display());
            }
        }
        if let Some(s) = &self.scene {
            if !s.is_file() {
                bail!("scene `{}` is not a file", s.display());
            }
        }
        Ok(())
    }

    /// Checks that every setting is in range (files aside).
    pub fn validate_ranges(&self) -> Result<()> {
        if self.samplers.is_empty() {
            bail!("--samplers needs at least one sampler name");
        }
        if !self.net.is_sobol() && !self.samplers.iter().any(|s| s.takes_net()) {
            bail!(
                "--net: none of --samplers reads a net; those that do: {}",
                lowdisc::catalog::net_sampler_list()
            );
        }
        for (flag, res) in [("--res", self.resolution), ("--conv-res", self.conv_res)] {
            named(flag, ranges::resolution(res))?;
        }
        let (spp, runs, ref_spp, conv_max) = (self.spp, self.runs, self.ref_spp, self.conv_max);
        if spp == 0 || spp > 1 << 16 {
            bail!("--spp must be between 1 and 65536, got {spp}");
        }
        if runs == 0 || runs > 1000 {
            bail!("--runs must be between 1 and 1000, got {runs}");
        }
        if ref_spp == 0 || ref_spp > 1 << 20 {
            bail!("--ref-spp must be between 1 and 1048576, got {ref_spp}");
        }
        if !conv_max.is_power_of_two() || conv_max > 1 << 16 {
            bail!("--conv-max must be a power of two up to 65536, got {conv_max}");
        }
        if self.conv_seeds == 0 || self.conv_seeds > 1000 {
            bail!(
                "--conv-seeds must be between 1 and 1000, got {}",
                self.conv_seeds
            );
        }
        let conv_ref_spp = self.conv_ref_spp;
        if conv_ref_spp == 0 || conv_ref_spp > 1 << 20 {
            bail!("--conv-ref-spp must be between 1 and 1048576, got {conv_ref_spp}");
        }
        Settings::resolve(&[&self.settings()])?;
        if let Some(n) = self.unit_samples {
            if n < MIN_UNIT_SAMPLES {
                bail!("--unit-samples must be at least {MIN_UNIT_SAMPLES}, got {n}");
            }
        }
        if self.scene.is_some() && self.preset.is_some() {
            bail!("a scene file and --preset cannot be used together");
        }
        if self.emitter_border > 64 {
            bail!(
                "--emitter-border must be at most 64 pixels, got {}",
                self.emitter_border
            );
        }
        let max_sigma = lowdisc_image::perceptual::MAX_SIGMA;
        if !(self.blur_sigma > 0.0 && self.blur_sigma <= max_sigma) {
            bail!(
                "--blur-sigma must be in (0, {max_sigma}] pixels, got {}",
                self.blur_sigma
            );
        }
        Ok(())
    }
}

/// `check`'s problem, if any, as an error naming `flag`.
fn named(flag: &str, check: ranges::Check) -> Result<()> {
    check.map_err(|p| anyhow::anyhow!("{flag}: {p}"))
}
