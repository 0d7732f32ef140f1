//! What [`Sampler`] adds to the generated enum: per-stream copies for the
//! sampler whose values depend on the order of calls.

use super::table::Sampler;

impl Sampler {
    /// A copy for one stream of work: samplers with internal sequential
    /// state (the paper's literal mode) are re-seeded from `stream`, so
    /// output does not depend on how the streams are spread over threads;
    /// stateless samplers are simply cloned.
    pub fn with_stream(&self, stream: u64) -> Self {
        match self {
            Sampler::GlobalSobol(s) => Sampler::GlobalSobol(s.with_stream(stream)),
            other => other.clone(),
        }
    }

    /// True when a value depends on the calls made before it in the same
    /// stream (the paper's literal mode), not only on the pixel, sample
    /// index and dimension: to reproduce part of a stream, a caller must
    /// replay the stream's earlier calls in their order.
    pub fn is_order_dependent(&self) -> bool {
        match self {
            Sampler::GlobalSobol(s) => s.is_order_dependent(),
            _ => false,
        }
    }
}
