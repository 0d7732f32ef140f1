//! [`Family`]: how a catalog name's raw points are made (points mode), which
//! also says which point order and dimension range apply.

use crate::RandomizeStrategy;
use crate::halton::{self, HaltonRandomize};
use crate::sobol;

/// The kind of sequence behind a catalog name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Family {
    /// The Sobol sequence with a standard randomization (seeded by the
    /// configuration's seed).
    Sobol(RandomizeStrategy),
    /// The paper's permuted Sobol with one sequential stream.
    PaperLiteral,
    /// The paper's permuted Sobol with hashed, order-independent draws.
    PaperReproducible,
    /// The Halton sequence with a randomization.
    Halton(HaltonRandomize),
    /// Independent uniform random numbers.
    Independent,
    /// Jittered stratified points.
    Stratified,
    /// A per-pixel sampler: its points are the samples of pixel (0,0) of a
    /// 1x1 image.
    PerPixel,
}

impl Family {
    /// A short label (the same for every randomization of a sequence).
    pub fn label(self) -> &'static str {
        match self {
            Family::Sobol(_) => "sobol",
            Family::PaperLiteral => "paper (literal)",
            Family::PaperReproducible => "paper (reproducible)",
            Family::Halton(_) => "halton",
            Family::Independent => "independent",
            Family::Stratified => "stratified",
            Family::PerPixel => "per-pixel",
        }
    }

    /// What the points mode ([`super::generate_points`]) emits for the
    /// family's names.
    pub fn points_mode(self) -> &'static str {
        match self {
            Family::Sobol(_) => {
                "the Sobol sequence with that randomization; Gray-code order by default \
                 (Joe & Kuo, scipy), natural order on request"
            }
            Family::PaperLiteral => {
                "the permuted Sobol over the same indices from one stream consumed \
                 point-major, so the words depend on the range asked for"
            }
            Family::PaperReproducible => {
                "the permuted Sobol with hashed draws, independent of the range and order"
            }
            Family::Halton(_) => "the Halton sequence with that randomization",
            Family::Independent => "stream = dimension, offset = point index",
            Family::Stratified => "jittered points over dimensions 0..end, sliced to the range",
            Family::PerPixel => {
                "the n samples of pixel (0,0) of a 1x1 image at n samples per pixel: \
                 dimensions 0-1 the in-pixel offset, then the get_2d pairs"
            }
        }
    }

    /// A Sobol sequence indexed like Sobol's (the `sobol*` and `paper*`
    /// names), for which [`super::Order::Gray`] applies.
    pub fn is_sobol(self) -> bool {
        matches!(
            self,
            Family::Sobol(_) | Family::PaperLiteral | Family::PaperReproducible
        )
    }

    /// The number of dimensions the family's points offer.
    pub fn dimensions(self) -> u64 {
        match self {
            Family::Halton(_) => u64::from(halton::NUM_DIMENSIONS),
            f if f.is_sobol() => sobol::NUM_DIMENSIONS as u64,
            _ => u64::from(u32::MAX),
        }
    }
}
