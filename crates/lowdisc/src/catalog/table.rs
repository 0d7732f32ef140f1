//! The sampler table: every pixel sampler type and, under it, every catalog
//! name built on it, with its command-line name, family, description and
//! constructor. This is the one place a sampler is declared: the name enum,
//! its parsing and listing, the sampler enum and its dispatch, building and
//! points mode all come from here (see [`super::define`]), and the
//! reference page `docs/reference/samplers.md` is generated from it.
//!
//! An entry reads `Name "name", family, "description", |p| constructor;`
//! where `p` is the checked [`Params`] of the configuration.

use super::define::sampler_table;
use super::family::Family;
use super::params::Params;
use crate::halton::HaltonRandomize;
use crate::pixel::{
    BurleySampler, CascadedSobolSampler, Dims, GlobalSobolMode, GlobalSobolSampler, GroupLayout,
    HaltonSampler, IndependentSampler, NestedHash, OpenQmcKind, OpenQmcSampler, PaddedSobolSampler,
    PixelSampler, PixelXorSampler, PmjSampler, StratifiedSampler, ZOrderSzSampler,
    ZSobolJointSampler, ZSobolSampler,
};
use crate::pmj::PmjKind;
use crate::{Error, RandomizeStrategy};

use HaltonRandomize::{Owen as HaltonOwenScramble, PermuteDigits};
use RandomizeStrategy::{FastOwen, Lms, None as Plain, Owen, Xor};

sampler_table! {
    /// Independent uniform random numbers.
    values Independent(IndependentSampler) {
        Independent "independent", Family::Independent,
            "independent uniform random numbers (seeded PCG32)",
            |p| IndependentSampler::new(p.spp, p.seed);
    }
    /// Jittered stratified samples.
    values Stratified(StratifiedSampler) {
        Stratified "stratified", Family::Stratified,
            "jittered stratified samples",
            |p| StratifiedSampler::new(p.spp, p.seed);
    }
    /// Global image-plane Halton (pbrt).
    values Halton(HaltonSampler) {
        Halton "halton", Family::Halton(PermuteDigits),
            "Halton sequence with random digit permutations",
            |p| HaltonSampler::new(p.spp, p.resolution, PermuteDigits, p.seed);
        HaltonOwen "halton-owen", Family::Halton(HaltonOwenScramble),
            "Halton sequence with Owen scrambling",
            |p| HaltonSampler::new(p.spp, p.resolution, HaltonOwenScramble, p.seed);
    }
    /// Global image-plane Sobol (pbrt-v3), plain, randomized or paper-permuted.
    words GlobalSobol(GlobalSobolSampler) {
        Sobol "sobol", Family::Sobol(Plain),
            "unscrambled Sobol (Joe-Kuo); pixels: pbrt-v3 global sampler",
            |p| p.global_sobol(GlobalSobolMode::Randomize(Plain));
        SobolXor "sobol-xor", Family::Sobol(Xor),
            "Sobol with a random digital shift (XOR)",
            |p| p.global_sobol(GlobalSobolMode::Randomize(Xor));
        SobolOwen "sobol-owen", Family::Sobol(Owen),
            "Sobol with exact Owen (nested uniform) scrambling",
            |p| p.global_sobol(GlobalSobolMode::Randomize(Owen));
        SobolFastOwen "sobol-fast-owen", Family::Sobol(FastOwen),
            "Sobol with fast hash-based Owen scrambling",
            |p| p.global_sobol(GlobalSobolMode::Randomize(FastOwen));
        SobolLms "sobol-lms", Family::Sobol(Lms),
            "Sobol with Matousek linear matrix scrambling + digital shift (LMS+shift)",
            |p| p.global_sobol(GlobalSobolMode::Randomize(Lms));
        Paper "paper", Family::PaperLiteral,
            "Song & Ro permuted Sobol, literal: one sequential stream",
            |p| p.global_sobol(GlobalSobolMode::PaperLiteral {
                threshold: p.threshold,
                all_dims: p.paper_all_dims,
            });
        PaperRepro "paper-repro", Family::PaperReproducible,
            "Song & Ro permuted Sobol, reproducible: hashed draws",
            |p| p.global_sobol(GlobalSobolMode::PaperReproducible {
                threshold: p.threshold,
                all_dims: p.paper_all_dims,
            });
    }
    /// Padded per-pixel Sobol (pbrt-v4).
    words PaddedSobol(PaddedSobolSampler) {
        PaddedSobol "padded-sobol", Family::PerPixel,
            "pbrt-v4 padded per-pixel Owen-scrambled Sobol",
            |p| PaddedSobolSampler::with_net(p.spp, Owen, p.seed, p.net);
        PaddedSobolLms "padded-sobol-lms", Family::PerPixel,
            "padded per-pixel Sobol with LMS + digital shift",
            |p| PaddedSobolSampler::with_net(p.spp, Lms, p.seed, p.net);
    }
    /// Z-order blue-noise Sobol (pbrt-v4's default).
    words ZSobol(ZSobolSampler) {
        ZSobol "zsobol", Family::PerPixel,
            "pbrt-v4 Z-order blue-noise Sobol (Ahmed & Wonka 2020)",
            |p| ZSobolSampler::with_net(p.spp, p.resolution, FastOwen, p.seed, p.net);
    }
    /// Burley 2020: shuffled, Owen-scrambled, 4-D padded per-pixel Sobol.
    words Burley(BurleySampler) {
        SobolBurley "sobol-burley", Family::PerPixel,
            "Burley 2020 per-pixel shuffled Owen-scrambled Sobol, padded by 4-D groups",
            |p| BurleySampler::new(p.spp, NestedHash::Vegdahl, p.seed);
        LaineKarras "laine-karras", Family::PerPixel,
            "as sobol-burley with the Laine-Karras 2011 hash",
            |p| BurleySampler::new(p.spp, NestedHash::LaineKarras, p.seed);
    }
    /// Per-pixel Sobol with a random digital shift.
    words PixelXor(PixelXorSampler) {
        SobolPixelXor "sobol-pixel-xor", Family::PerPixel,
            "per-pixel Sobol with a random digital shift per pixel",
            |p| PixelXorSampler::new(p.spp, p.seed);
    }
    /// PMJ02 / pmj02bn point sets.
    words Pmj(PmjSampler) {
        Pmj02 "pmj02", Family::PerPixel,
            "progressive multi-jittered (0,2) sets (Christensen et al. 2018)",
            |p| PmjSampler::new(p.spp, PmjKind::Pmj02, p.seed);
        Pmj02Bn "pmj02bn", Family::PerPixel,
            "pmj02 with best-candidate blue-noise placement (pmj02bn)",
            |p| PmjSampler::new(p.spp, PmjKind::Pmj02Bn, p.seed);
    }
    /// Z-order Sobol padded by 4-D groups.
    words ZSobolJoint(ZSobolJointSampler) {
        ZSobol4d "zsobol-4d", Family::PerPixel,
            "Z-order Sobol padded by 4-D groups in Burley's order",
            |p| ZSobolJointSampler::with_net(
                p.spp, p.resolution, GroupLayout::Sequential, FastOwen, p.seed, p.net,
            );
        ZSobolJoint "zsobol-joint", Family::PerPixel,
            "Z-order Sobol padded by 4-D groups aligned with the path tracer's vertices",
            |p| ZSobolJointSampler::with_net(
                p.spp, p.resolution, GroupLayout::PathVertices, FastOwen, p.seed, p.net,
            );
    }
    /// Z-order over the base-4 (0,4)-sequence, film and light sample in 5-D.
    words ZOrderSz(ZOrderSzSampler) {
        ZOrderSz "zorder-sz", Family::PerPixel,
            "Z-order base-4 (0,4)-sequence (SZ-style), film x light choice x light in 5-D",
            |p| ZOrderSzSampler::new(p.spp, p.resolution, FastOwen, p.seed);
    }
    /// Cascaded Sobol': every consecutive pair of dimensions a (0,m,2)-net.
    words CascadedSobol(CascadedSobolSampler) {
        CascadedSobol "cascaded-sobol", Family::PerPixel,
            "Cascaded Sobol' (Paulin et al. 2021) per pixel: consecutive dimension pairs (0,2)",
            |p| CascadedSobolSampler::new(p.spp, FastOwen, p.seed);
    }
    /// The ASWF OpenQMC library's samplers, padded by call.
    words OpenQmc(OpenQmcSampler) {
        OpenQmcSobol "openqmc-sobol", Family::PerPixel,
            "OpenQMC (ASWF) Owen-scrambled Sobol, one domain per call",
            |p| OpenQmcSampler::new(OpenQmcKind::Sobol, p.spp, p.seed);
        OpenQmcSobolBn "openqmc-sobol-bn", Family::PerPixel,
            "OpenQMC (ASWF) Sobol with blue-noise pixel tables, one domain per call",
            |p| OpenQmcSampler::new(OpenQmcKind::SobolBn, p.spp, p.seed);
        OpenQmcLattice "openqmc-lattice", Family::PerPixel,
            "OpenQMC (ASWF) randomised rank-1 lattice, one domain per call",
            |p| OpenQmcSampler::new(OpenQmcKind::Lattice, p.spp, p.seed);
        OpenQmcLatticeBn "openqmc-lattice-bn", Family::PerPixel,
            "OpenQMC (ASWF) rank-1 lattice with blue-noise pixel tables, one domain per call",
            |p| OpenQmcSampler::new(OpenQmcKind::LatticeBn, p.spp, p.seed);
        OpenQmcPmj "openqmc-pmj", Family::PerPixel,
            "OpenQMC (ASWF) progressive multi-jittered (0,2), one domain per call",
            |p| OpenQmcSampler::new(OpenQmcKind::Pmj, p.spp, p.seed);
        OpenQmcPmjBn "openqmc-pmj-bn", Family::PerPixel,
            "OpenQMC (ASWF) progressive multi-jittered (0,2) with blue-noise pixel tables",
            |p| OpenQmcSampler::new(OpenQmcKind::PmjBn, p.spp, p.seed);
    }
}
