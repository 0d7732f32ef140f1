//! The catalog of named samplers: what the CLI and the renderer accept as
//! `--sampler NAME`, a validated configuration that builds the pixel
//! [`Sampler`], and a *points mode* ([`generate_points`]) that emits the raw
//! sequence behind each name.
//!
//! | name | pixel sampler | points mode |
//! |---|---|---|
//! | `independent` | independent PCG32 | stream = dimension, offset = index |
//! | `stratified` | jittered strata | jittered points |
//! | `halton` | Halton, random digit permutations | same sequence |
//! | `halton-owen` | Halton, Owen-scrambled | same sequence |
//! | `sobol` | pbrt-v3 global Sobol, unscrambled | Sobol sequence |
//! | `sobol-xor` | global Sobol, random digital shift | XOR-scrambled Sobol |
//! | `sobol-owen` | global Sobol, exact Owen | Owen-scrambled Sobol |
//! | `sobol-fast-owen` | global Sobol, fast Owen | fast-Owen Sobol |
//! | `sobol-lms` | global Sobol, LMS + digital shift | LMS-scrambled Sobol |
//! | `paper` | global Sobol, paper permutation, literal stream | same |
//! | `paper-repro` | global Sobol, paper permutation, hashed | same |
//! | `padded-sobol` | pbrt-v4 padded Sobol (Owen) | pixel (0,0) of a 1x1 image |
//! | `padded-sobol-lms` | padded per-pixel Sobol, LMS + shift | pixel (0,0) of a 1x1 image |
//! | `zsobol` | pbrt-v4 Z-order Sobol (fast Owen) | pixel (0,0) of a 1x1 image |
//! | `sobol-burley` | Burley 2020 shuffled Owen Sobol, 4-D padding | pixel (0,0) of a 1x1 image |
//! | `laine-karras` | the same with the 2011 Laine-Karras hash | pixel (0,0) of a 1x1 image |
//! | `sobol-pixel-xor` | per-pixel Sobol, random digital shift | pixel (0,0) of a 1x1 image |
//! | `pmj02` | generated PMJ02 sets, per-pixel permuted | pixel (0,0) of a 1x1 image |
//! | `pmj02bn` | generated pmj02bn (blue-noise) sets | pixel (0,0) of a 1x1 image |
//! | `zsobol-4d` | Z-order Sobol, 4-D groups in Burley's order | pixel (0,0) of a 1x1 image |
//! | `zsobol-joint` | Z-order Sobol, 4-D groups per path vertex | pixel (0,0) of a 1x1 image |
//! | `zorder-sz` | Z-order base-4 (0,4)-sequence, film x light in 5-D | pixel (0,0) of a 1x1 image |
//! | `cascaded-sobol` | Cascaded Sobol' per pixel (fast Owen), consecutive pairs (0,2) | pixel (0,0) of a 1x1 image |

pub mod pixel_rows;
mod points;

use core::fmt;
use core::str::FromStr;

use crate::halton::HaltonRandomize;
use crate::paper::check_threshold;
use crate::pixel::{
    BurleySampler, CascadedSobolSampler, GlobalSobolMode, GlobalSobolSampler, GroupLayout,
    HaltonSampler, IndependentSampler, NestedHash, PaddedSobolSampler, PixelXorSampler, PmjSampler,
    Sampler, StratifiedSampler, ZOrderSzSampler, ZSobolJointSampler, ZSobolSampler,
};
use crate::pmj::PmjKind;
use crate::{Error, RandomizeStrategy};

pub use pixel_rows::{DEFAULT_TILE_SIZE, pixel_rows};
pub use points::{MAX_POINT_WORDS, Order, generate_points};

/// The largest image side a configuration accepts.
pub const MAX_RESOLUTION: u32 = 1 << 20;

/// The samplers the catalog knows, by name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SamplerName {
    /// `independent`: independent uniform random numbers (PCG32).
    Independent,
    /// `stratified`: jittered stratified samples.
    Stratified,
    /// `halton`: Halton with random digit permutations.
    Halton,
    /// `halton-owen`: Owen-scrambled Halton.
    HaltonOwen,
    /// `sobol`: unscrambled Sobol (pixel: pbrt-v3 global sampler).
    Sobol,
    /// `sobol-xor`: Sobol with a random digital shift.
    SobolXor,
    /// `sobol-owen`: Sobol with exact Owen scrambling.
    SobolOwen,
    /// `sobol-fast-owen`: Sobol with fast hash-based Owen scrambling.
    SobolFastOwen,
    /// `sobol-lms`: Sobol with Matoušek's linear matrix scrambling and a
    /// digital shift (pixel: pbrt-v3 global sampler).
    SobolLms,
    /// `paper`: the paper's permuted Sobol, literal (one sequential stream).
    Paper,
    /// `paper-repro`: the paper's permuted Sobol, reproducible (hashed draws).
    PaperRepro,
    /// `padded-sobol`: pbrt-v4's padded per-pixel Owen-scrambled Sobol.
    PaddedSobol,
    /// `padded-sobol-lms`: padded per-pixel Sobol, LMS + shift scrambled.
    PaddedSobolLms,
    /// `zsobol`: pbrt-v4's Z-order blue-noise Sobol.
    ZSobol,
    /// `sobol-burley`: Burley 2020's shuffled Owen-scrambled Sobol padded
    /// by groups of four dimensions.
    SobolBurley,
    /// `laine-karras`: as `sobol-burley` with the 2011 Laine-Karras hash.
    LaineKarras,
    /// `sobol-pixel-xor`: per-pixel Sobol with a random digital shift.
    SobolPixelXor,
    /// `pmj02`: progressive multi-jittered (0,2) point sets.
    Pmj02,
    /// `pmj02bn`: the blue-noise variant of `pmj02`.
    Pmj02Bn,
    /// `zsobol-4d`: Z-order Sobol padded by 4-D groups in Burley's order.
    ZSobol4d,
    /// `zsobol-joint`: Z-order Sobol padded by 4-D groups aligned with the
    /// path tracer's scattering vertices.
    ZSobolJoint,
    /// `zorder-sz`: Z-order over the base-4 (0,4)-sequence of [`crate::sz`],
    /// film offset, light choice and light position jointly stratified.
    ZOrderSz,
    /// `cascaded-sobol`: Cascaded Sobol' (Paulin et al. 2021) per pixel,
    /// every consecutive pair of dimensions a (0,m,2)-net.
    CascadedSobol,
}

impl SamplerName {
    /// Every name, in the order the documentation lists them.
    pub const ALL: [SamplerName; 23] = [
        SamplerName::Independent,
        SamplerName::Stratified,
        SamplerName::Halton,
        SamplerName::HaltonOwen,
        SamplerName::Sobol,
        SamplerName::SobolXor,
        SamplerName::SobolOwen,
        SamplerName::SobolFastOwen,
        SamplerName::SobolLms,
        SamplerName::Paper,
        SamplerName::PaperRepro,
        SamplerName::PaddedSobol,
        SamplerName::PaddedSobolLms,
        SamplerName::ZSobol,
        SamplerName::SobolBurley,
        SamplerName::LaineKarras,
        SamplerName::SobolPixelXor,
        SamplerName::Pmj02,
        SamplerName::Pmj02Bn,
        SamplerName::ZSobol4d,
        SamplerName::ZSobolJoint,
        SamplerName::ZOrderSz,
        SamplerName::CascadedSobol,
    ];

    /// The name as written on the command line.
    pub fn as_str(self) -> &'static str {
        match self {
            SamplerName::Independent => "independent",
            SamplerName::Stratified => "stratified",
            SamplerName::Halton => "halton",
            SamplerName::HaltonOwen => "halton-owen",
            SamplerName::Sobol => "sobol",
            SamplerName::SobolXor => "sobol-xor",
            SamplerName::SobolOwen => "sobol-owen",
            SamplerName::SobolFastOwen => "sobol-fast-owen",
            SamplerName::SobolLms => "sobol-lms",
            SamplerName::Paper => "paper",
            SamplerName::PaperRepro => "paper-repro",
            SamplerName::PaddedSobol => "padded-sobol",
            SamplerName::PaddedSobolLms => "padded-sobol-lms",
            SamplerName::ZSobol => "zsobol",
            SamplerName::SobolBurley => "sobol-burley",
            SamplerName::LaineKarras => "laine-karras",
            SamplerName::SobolPixelXor => "sobol-pixel-xor",
            SamplerName::Pmj02 => "pmj02",
            SamplerName::Pmj02Bn => "pmj02bn",
            SamplerName::ZSobol4d => "zsobol-4d",
            SamplerName::ZSobolJoint => "zsobol-joint",
            SamplerName::ZOrderSz => "zorder-sz",
            SamplerName::CascadedSobol => "cascaded-sobol",
        }
    }

    /// A one-line description.
    pub fn description(self) -> &'static str {
        match self {
            SamplerName::Independent => "independent uniform random numbers (seeded PCG32)",
            SamplerName::Stratified => "jittered stratified samples",
            SamplerName::Halton => "Halton sequence with random digit permutations",
            SamplerName::HaltonOwen => "Halton sequence with Owen scrambling",
            SamplerName::Sobol => "unscrambled Sobol (Joe-Kuo); pixels: pbrt-v3 global sampler",
            SamplerName::SobolXor => "Sobol with a random digital shift (XOR)",
            SamplerName::SobolOwen => "Sobol with exact Owen (nested uniform) scrambling",
            SamplerName::SobolFastOwen => "Sobol with fast hash-based Owen scrambling",
            SamplerName::SobolLms => {
                "Sobol with Matousek linear matrix scrambling + digital shift (LMS+shift)"
            }
            SamplerName::Paper => "Song & Ro permuted Sobol, literal: one sequential stream",
            SamplerName::PaperRepro => "Song & Ro permuted Sobol, reproducible: hashed draws",
            SamplerName::PaddedSobol => "pbrt-v4 padded per-pixel Owen-scrambled Sobol",
            SamplerName::PaddedSobolLms => "padded per-pixel Sobol with LMS + digital shift",
            SamplerName::ZSobol => "pbrt-v4 Z-order blue-noise Sobol (Ahmed & Wonka 2020)",
            SamplerName::SobolBurley => {
                "Burley 2020 per-pixel shuffled Owen-scrambled Sobol, padded by 4-D groups"
            }
            SamplerName::LaineKarras => "as sobol-burley with the Laine-Karras 2011 hash",
            SamplerName::SobolPixelXor => "per-pixel Sobol with a random digital shift per pixel",
            SamplerName::Pmj02 => "progressive multi-jittered (0,2) sets (Christensen et al. 2018)",
            SamplerName::Pmj02Bn => "pmj02 with best-candidate blue-noise placement (pmj02bn)",
            SamplerName::ZSobol4d => "Z-order Sobol padded by 4-D groups in Burley's order",
            SamplerName::ZSobolJoint => {
                "Z-order Sobol padded by 4-D groups aligned with the path tracer's vertices"
            }
            SamplerName::ZOrderSz => {
                "Z-order base-4 (0,4)-sequence (SZ-style), film x light choice x light in 5-D"
            }
            SamplerName::CascadedSobol => {
                "Cascaded Sobol' (Paulin et al. 2021) per pixel: consecutive dimension pairs (0,2)"
            }
        }
    }

    /// Whether the name is a Sobol sequence indexed like Sobol's (the
    /// `sobol*` and `paper*` names), for which [`Order::Gray`] applies.
    pub fn is_sobol_family(self) -> bool {
        matches!(
            self,
            SamplerName::Sobol
                | SamplerName::SobolXor
                | SamplerName::SobolOwen
                | SamplerName::SobolFastOwen
                | SamplerName::SobolLms
                | SamplerName::Paper
                | SamplerName::PaperRepro
        )
    }

    /// The 4-D group layout of the `zsobol-4d` and `zsobol-joint` names.
    pub fn group_layout(self) -> Option<GroupLayout> {
        match self {
            SamplerName::ZSobol4d => Some(GroupLayout::Sequential),
            SamplerName::ZSobolJoint => Some(GroupLayout::PathVertices),
            _ => None,
        }
    }

    /// The randomization strategy of the `sobol*` names (`None` for others).
    pub fn sobol_strategy(self) -> Option<RandomizeStrategy> {
        match self {
            SamplerName::Sobol => Some(RandomizeStrategy::None),
            SamplerName::SobolXor => Some(RandomizeStrategy::Xor),
            SamplerName::SobolOwen => Some(RandomizeStrategy::Owen),
            SamplerName::SobolFastOwen => Some(RandomizeStrategy::FastOwen),
            SamplerName::SobolLms => Some(RandomizeStrategy::Lms),
            _ => None,
        }
    }
}

impl fmt::Display for SamplerName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for SamplerName {
    type Err = Error;

    fn from_str(s: &str) -> Result<Self, Error> {
        SamplerName::ALL
            .into_iter()
            .find(|n| n.as_str() == s)
            .ok_or_else(|| Error::UnknownSampler(s.into()))
    }
}

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
        }
    }

    /// Checks the fields every sampler needs: `spp >= 1`, a threshold in
    /// `[0, 1]` (NaN rejected), sides in `1..=MAX_RESOLUTION`.
    pub fn validate(&self) -> Result<(), Error> {
        crate::pixel::check_spp(self.spp)?;
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

    /// Builds the pixel sampler, validating every field and the index range
    /// of the chosen sampler.
    pub fn build(&self) -> Result<Sampler, Error> {
        self.validate()?;
        let (spp, res, seed) = (self.spp, self.resolution, self.seed);
        let (threshold, all_dims) = (self.threshold, self.paper_all_dims);
        let global = |mode| GlobalSobolSampler::new(spp, res, mode, seed).map(Sampler::from);
        match self.name {
            SamplerName::Independent => IndependentSampler::new(spp, seed).map(Sampler::from),
            SamplerName::Stratified => StratifiedSampler::new(spp, seed).map(Sampler::from),
            SamplerName::Halton => {
                HaltonSampler::new(spp, res, HaltonRandomize::PermuteDigits, seed)
                    .map(Sampler::from)
            }
            SamplerName::HaltonOwen => {
                HaltonSampler::new(spp, res, HaltonRandomize::Owen, seed).map(Sampler::from)
            }
            SamplerName::Sobol
            | SamplerName::SobolXor
            | SamplerName::SobolOwen
            | SamplerName::SobolFastOwen
            | SamplerName::SobolLms => {
                let r = self.name.sobol_strategy().unwrap_or_default();
                global(GlobalSobolMode::Randomize(r))
            }
            SamplerName::Paper => global(GlobalSobolMode::PaperLiteral {
                threshold,
                all_dims,
            }),
            SamplerName::PaperRepro => global(GlobalSobolMode::PaperReproducible {
                threshold,
                all_dims,
            }),
            SamplerName::PaddedSobol => {
                PaddedSobolSampler::new(spp, RandomizeStrategy::Owen, seed).map(Sampler::from)
            }
            SamplerName::PaddedSobolLms => {
                PaddedSobolSampler::new(spp, RandomizeStrategy::Lms, seed).map(Sampler::from)
            }
            SamplerName::ZSobol => {
                ZSobolSampler::new(spp, res, RandomizeStrategy::FastOwen, seed).map(Sampler::from)
            }
            SamplerName::SobolBurley => {
                BurleySampler::new(spp, NestedHash::Vegdahl, seed).map(Sampler::from)
            }
            SamplerName::LaineKarras => {
                BurleySampler::new(spp, NestedHash::LaineKarras, seed).map(Sampler::from)
            }
            SamplerName::SobolPixelXor => PixelXorSampler::new(spp, seed).map(Sampler::from),
            SamplerName::Pmj02 => PmjSampler::new(spp, PmjKind::Pmj02, seed).map(Sampler::from),
            SamplerName::Pmj02Bn => PmjSampler::new(spp, PmjKind::Pmj02Bn, seed).map(Sampler::from),
            SamplerName::ZSobol4d | SamplerName::ZSobolJoint => {
                let layout = self.name.group_layout().unwrap_or(GroupLayout::Sequential);
                ZSobolJointSampler::new(spp, res, layout, RandomizeStrategy::FastOwen, seed)
                    .map(Sampler::from)
            }
            SamplerName::ZOrderSz => {
                ZOrderSzSampler::new(spp, res, RandomizeStrategy::FastOwen, seed).map(Sampler::from)
            }
            SamplerName::CascadedSobol => {
                CascadedSobolSampler::new(spp, RandomizeStrategy::FastOwen, seed).map(Sampler::from)
            }
        }
    }
}
