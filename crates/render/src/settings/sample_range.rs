//! [`SampleRange`]: the part of a pixel's sample indices a render takes
//! ([`super::RenderOptions::samples`]).

/// A half-open range `start..end` of sample indices (`Copy`, unlike
/// `std::ops::Range`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct SampleRange {
    /// The first sample index taken.
    pub start: u32,
    /// One past the last sample index taken.
    pub end: u32,
}

impl SampleRange {
    /// `start..end`.
    pub const fn new(start: u32, end: u32) -> SampleRange {
        SampleRange { start, end }
    }
    /// Every sample of a pixel, `0..spp`.
    pub const fn all(spp: u32) -> SampleRange {
        SampleRange { start: 0, end: spp }
    }
    /// Number of indices (0 when empty).
    pub fn len(&self) -> u32 {
        self.end.saturating_sub(self.start)
    }
    /// True when the range holds no index.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// True when `s` is in the range.
    pub fn contains(&self, s: u32) -> bool {
        (self.start..self.end).contains(&s)
    }
}

impl std::fmt::Display for SampleRange {
    /// `start..end`, the form `--sample-range` takes.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}..{}", self.start, self.end)
    }
}
