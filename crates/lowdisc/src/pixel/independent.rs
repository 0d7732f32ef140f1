//! The independent pixel sampler: every value is a fresh uniform random
//! number, addressed by (seed, pixel, sample index, dimension) alone.
//!
//! Pixel `(x, y)` reads stream `x * 2^32 + y` of an [`Independent`] family;
//! sample `s` owns the offsets `s * 2^32 .. (s + 1) * 2^32` of that stream,
//! dimension `d` being offset `s * 2^32 + d`. The pixel offset uses the two
//! offsets reserved at the end of the sample's block (`d = 2^32 - 2` and
//! `2^32 - 1`), so it never collides with the `get_1d`/`get_2d` dimensions a
//! renderer can reach. `start_pixel_sample` jumps the PCG32 generator to the
//! first offset; `get_1d`/`get_2d` then step it, so a value does not depend
//! on which pixels or samples were visited before.
//!
//! ## Speed
//! The generator of the current pixel's stream is kept, at the start of the
//! current sample's block: the next sample of the same pixel is one jump of
//! `2^32` draws away and the pixel offset one jump of `2^32 - 2` draws, each
//! two multiplications with a precomputed [`Jump`]. A new pixel seeds its
//! stream once; any other sample index is reached by
//! [`crate::pcg::Pcg32::advance`]. Jumps and advances land on the same states
//! as stepping (tested in `pcg`), so the values are those of
//! [`Independent::sample_u32`].

use super::PixelSampler;
use crate::Error;
use crate::independent::Independent;
use crate::pcg::{Jump, Pcg32};

/// Offset (inside a sample's block) of the first pixel-offset value.
const PIXEL_OFFSET: u64 = (1 << 32) - 2;

/// Independent uniform samples with random access.
#[derive(Debug, Clone)]
pub struct IndependentSampler {
    spp: u32,
    sequence: Independent,
    /// The jump from one sample's block to the next (`2^32` draws).
    block_jump: Jump,
    /// The jump from a sample's block to its pixel offset (`2^32 - 2`).
    offset_jump: Jump,
    /// The current pixel's stream, if one was started.
    stream: Option<u64>,
    /// The generator of `stream` at offset 0.
    stream_start: Pcg32,
    /// The current sample index.
    sample_index: u32,
    /// The generator at the start of the current sample's block.
    block_start: Pcg32,
    /// The generator of `get_1d` / `get_2d`.
    rng: Pcg32,
}

impl IndependentSampler {
    /// A sampler with `spp` samples per pixel, seeded by `seed`.
    ///
    /// # Errors
    /// [`Error::InvalidSampleCount`] if `spp == 0`.
    pub fn new(spp: u32, seed: u64) -> Result<Self, Error> {
        super::check_spp(spp)?;
        let sequence = Independent::new(seed);
        let rng = sequence.rng(0);
        Ok(IndependentSampler {
            spp,
            sequence,
            block_jump: Jump::new(1 << 32),
            offset_jump: Jump::new(PIXEL_OFFSET),
            stream: None,
            stream_start: rng.clone(),
            sample_index: 0,
            block_start: rng.clone(),
            rng,
        })
    }

    /// The stream of pixel `(x, y)`: `x * 2^32 + y`.
    fn stream_of(pixel: [u32; 2]) -> u64 {
        (u64::from(pixel[0]) << 32) | u64::from(pixel[1])
    }
}

impl PixelSampler for IndependentSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        let stream = Self::stream_of(pixel);
        if self.stream != Some(stream) {
            self.stream = Some(stream);
            self.stream_start = self.sequence.rng(stream);
            self.sample_index = 0;
            self.block_start = self.stream_start.clone();
        }
        if sample_index != self.sample_index {
            if Some(sample_index) == self.sample_index.checked_add(1) {
                self.block_start.jump(&self.block_jump);
            } else {
                self.block_start = self.stream_start.clone();
                self.block_start.advance(u64::from(sample_index) << 32);
            }
            self.sample_index = sample_index;
        }
        self.rng = self.block_start.clone();
        if dimension != 0 {
            self.rng.advance(u64::from(dimension));
        }
    }

    fn get_1d(&mut self) -> f32 {
        crate::to_f32(self.rng.next_u32())
    }

    fn get_2d(&mut self) -> [f32; 2] {
        let x = crate::to_f32(self.rng.next_u32());
        [x, crate::to_f32(self.rng.next_u32())]
    }

    fn get_pixel_2d(&mut self) -> [f32; 2] {
        let mut rng = self.block_start.clone();
        rng.jump(&self.offset_jump);
        let x = crate::to_f32(rng.next_u32());
        [x, crate::to_f32(rng.next_u32())]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use alloc::vec::Vec;

    /// Pixel offset, then 1-D, 2-D, 1-D values of one sample.
    fn sample(s: &mut IndependentSampler, pixel: [u32; 2], index: u32) -> Vec<f32> {
        s.start_pixel_sample(pixel, index, 0);
        let mut out = s.get_pixel_2d().to_vec();
        out.push(s.get_1d());
        out.extend(s.get_2d());
        out.push(s.get_1d());
        out
    }

    #[test]
    fn zero_samples_is_an_error() {
        assert!(matches!(
            IndependentSampler::new(0, 1),
            Err(Error::InvalidSampleCount { count: 0, .. })
        ));
    }

    #[test]
    fn values_do_not_depend_on_call_order() {
        let mut s = IndependentSampler::new(8, 3).unwrap();
        let pixels = [[0u32, 0], [5, 2], [2, 5], [u32::MAX, 7]];
        let forward: Vec<Vec<f32>> = pixels
            .iter()
            .flat_map(|&p| (0..8).map(move |i| (p, i)))
            .map(|(p, i)| sample(&mut s, p, i))
            .collect();
        let mut t = IndependentSampler::new(8, 3).unwrap();
        let mut backward: Vec<Vec<f32>> = pixels
            .iter()
            .rev()
            .flat_map(|&p| (0..8).rev().map(move |i| (p, i)))
            .map(|(p, i)| sample(&mut t, p, i))
            .collect();
        backward.reverse();
        assert_eq!(forward, backward);
        // Starting at dimension 1 continues the same dimensions.
        s.start_pixel_sample([5, 2], 3, 0);
        let first = s.get_1d();
        let second = s.get_1d();
        s.start_pixel_sample([5, 2], 3, 1);
        assert_eq!(s.get_1d(), second);
        assert_ne!(first, second);
        // get_pixel_2d does not move the dimension counter.
        s.start_pixel_sample([5, 2], 3, 0);
        s.get_pixel_2d();
        assert_eq!(s.get_1d(), first);
    }

    #[test]
    fn values_are_the_streams_in_any_visiting_order() {
        let seq = Independent::new(5);
        let mut s = IndependentSampler::new(4, 5).unwrap();
        let mut state = 1u64;
        for _ in 0..400 {
            state = crate::hash::mix64(state.wrapping_add(7));
            let pixel = [(state % 3) as u32, ((state >> 8) % 2) as u32];
            let index = match (state >> 16) % 4 {
                0 => u32::MAX - (state >> 20) as u32 % 2,
                _ => (state >> 20) as u32 % 6,
            };
            let dim = if (state >> 30) % 3 == 0 {
                (state >> 32) as u32 % 9
            } else {
                0
            };
            s.start_pixel_sample(pixel, index, dim);
            let stream = IndependentSampler::stream_of(pixel);
            let block = u64::from(index) << 32;
            let at = |offset: u64| crate::to_f32(seq.sample_u32(stream, block + offset));
            let d = u64::from(dim);
            assert_eq!(s.get_1d(), at(d));
            assert_eq!(s.get_pixel_2d(), [at(PIXEL_OFFSET), at(PIXEL_OFFSET + 1)]);
            assert_eq!(s.get_2d(), [at(d + 1), at(d + 2)]);
        }
    }

    #[test]
    fn values_are_in_the_unit_square_and_the_pixel() {
        let mut s = IndependentSampler::new(4, 9).unwrap();
        for y in 0..16 {
            for x in 0..16 {
                for i in 0..4 {
                    for v in sample(&mut s, [x, y], i) {
                        assert!((0.0..1.0).contains(&v));
                    }
                }
            }
        }
    }

    #[test]
    fn values_are_the_independent_streams() {
        let seq = Independent::new(21);
        let mut s = IndependentSampler::new(2, 21).unwrap();
        s.start_pixel_sample([3, 4], 1, 5);
        let stream = (3u64 << 32) | 4;
        assert_eq!(
            s.get_1d(),
            crate::to_f32(seq.sample_u32(stream, (1 << 32) + 5))
        );
        assert_eq!(
            s.get_pixel_2d()[1],
            crate::to_f32(seq.sample_u32(stream, (2 << 32) - 1))
        );
    }

    #[test]
    fn pinned_values() {
        let mut s = IndependentSampler::new(16, 42).unwrap();
        let got: Vec<u32> = sample(&mut s, [1, 2], 3)
            .iter()
            .map(|v| v.to_bits())
            .collect();
        assert_eq!(got, PINNED);
    }

    const PINNED: [u32; 6] = [
        1053015164, 1060823819, 1055819120, 1062652853, 1057460751, 1049038396,
    ];
}
