//! The definition of [`ZSobolSampler::sample_index`], split where the
//! pixel ends: the base-4 digits at or above the sample bits (shift `>= m`)
//! are permuted by hashes of the dimension key's level hashes and the
//! digits above them, which are all pixel digits, so a [`KeyIndex`] keeps
//! the level hashes of its key and the permuted pixel digits of the last
//! pixel; only the sample digits (`ceil(m / 2)` bit mixes) and the odd low
//! bit are computed per sample. `sample_index` is this with a fresh
//! [`KeyIndex`], so there is one definition; the group-padded samplers keep
//! one [`KeyIndex`] per group.

use super::{BASE4_PERMUTATIONS, LOW_BIT_SALT, ZSobolSampler, cache};
use crate::hash::{bounded, hash_words, mix64};
use crate::pixel::SEED_PAD;

/// Base-4 digits of a 64-bit index.
const MAX_DIGITS: usize = 32;

/// The parts of one dimension key's index permutation that do not change
/// from sample to sample; see the module documentation.
#[derive(Debug, Clone)]
pub(crate) struct KeyIndex {
    /// Level hash of every base-4 digit.
    levels: [u64; MAX_DIGITS],
    /// Key of the odd low bit's flip.
    low_key: u64,
    /// The pixel (Morton code) whose permuted digits `upper` holds.
    code: Option<u64>,
    /// The permuted pixel digits, in place.
    upper: u64,
}

impl ZSobolSampler {
    /// The per-key part of [`ZSobolSampler::sample_index`] for dimension
    /// key `key`.
    pub(crate) fn key_index(&self, key: u64) -> KeyIndex {
        let dim_seed = hash_words(&[self.seed, SEED_PAD, key]);
        let mut levels = [0; MAX_DIGITS];
        for (i, level) in levels.iter_mut().enumerate() {
            if i < self.base4_digits as usize {
                *level = cache::level(dim_seed, i as u64);
            }
        }
        KeyIndex {
            levels,
            low_key: mix64(dim_seed ^ LOW_BIT_SALT),
            code: None,
            upper: 0,
        }
    }

    /// [`ZSobolSampler::sample_index`] of `key`'s dimension key at the
    /// current pixel sample, recomputing `key`'s pixel digits only when the
    /// pixel changed.
    pub(crate) fn sample_index_with(&self, key: &mut KeyIndex) -> u64 {
        let m = self.log2_spp;
        let odd = m & 1;
        // Digits `i >= ceil(m / 2)` sit at shift `2i - odd >= m`.
        let first_pixel_digit = m.div_ceil(2);
        let code = self.morton >> m;
        if key.code != Some(code) {
            key.upper = (first_pixel_digit..self.base4_digits)
                .map(|i| permuted_digit(key.levels[i as usize], self.morton, 2 * i - odd))
                .fold(0, |upper, digit| upper | digit);
            key.code = Some(code);
        }
        let mut index = key.upper;
        for i in odd..first_pixel_digit {
            index |= permuted_digit(key.levels[i as usize], self.morton, 2 * i - odd);
        }
        if odd == 1 {
            let flip = mix64(key.low_key ^ (self.morton >> 1)) >> 63;
            index |= (self.morton & 1) ^ flip;
        }
        index
    }
}

/// The base-4 digit of `morton` at `shift`, mapped through the permutation
/// chosen by the digit's level hash and the digits above it.
#[inline]
fn permuted_digit(level: u64, morton: u64, shift: u32) -> u64 {
    let digit = (morton >> shift) & 3;
    let higher = morton.checked_shr(shift + 2).unwrap_or(0);
    let p = bounded(mix64(level ^ higher), 24) as usize;
    u64::from(BASE4_PERMUTATIONS[p][digit as usize]) << shift
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::RandomizeStrategy;
    use crate::pixel::WordSampler;

    #[test]
    fn a_kept_key_index_gives_the_fresh_index_across_pixels() {
        // Even and odd m, more than 32 index bits, one pixel wide.
        for (spp, res) in [
            (16u32, [40u32, 24u32]),
            (8, [1 << 15, 5]),
            (1, [7, 7]),
            (2, [1, 1]),
        ] {
            let mut s = ZSobolSampler::new(spp, res, RandomizeStrategy::FastOwen, 5).unwrap();
            let mut kept = s.key_index(1 << 40);
            let mut state = 7u64;
            for _ in 0..300 {
                state = mix64(state);
                // Runs of samples in one pixel, then a jump.
                let pixel = [(state as u32) % res[0], ((state >> 32) as u32) % res[1]];
                for k in 0..=(state >> 60) as u32 {
                    s.start_pixel_sample(pixel, k, 0);
                    let fresh = s.sample_index_with(&mut s.key_index(1 << 40));
                    assert_eq!(s.sample_index_with(&mut kept), fresh, "{spp} {pixel:?} {k}");
                }
            }
        }
    }
}
