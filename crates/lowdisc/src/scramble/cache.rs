//! [`ScrambleCache`]: a [`RandomizeStrategy`] and its seed, with the
//! per-dimension seed hashing done once per dimension and kept, for callers
//! that scramble many words of the same few dimensions (the pixel samplers);
//! and [`PreparedKey`], the kept per-seed setup of the costly strategies.

use alloc::vec::Vec;

use super::{LmsKey, OwenKey, RandomizeStrategy, dimension_seed};

/// Dimensions below this are cached; the others are hashed on every call.
const CACHED_DIMENSIONS: u32 = 1024;

/// The per-seed setup of a strategy that is worth keeping: the digit hashes'
/// first rounds of Owen scrambling, the matrix and shift of LMS. Built by
/// [`RandomizeStrategy::prepare`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PreparedKey {
    /// Exact Owen scrambling.
    Owen(OwenKey),
    /// Linear matrix scrambling plus a digital shift.
    Lms(LmsKey),
}

impl PreparedKey {
    /// Equals `strategy.apply_dimension_seed(word, seed)` for the strategy
    /// and seed the key was prepared from.
    #[inline]
    pub fn scramble(&self, word: u32) -> u32 {
        match self {
            PreparedKey::Owen(key) => key.scramble(word),
            PreparedKey::Lms(key) => key.scramble(word),
        }
    }
}

/// A [`RandomizeStrategy`] under one seed, with its per-dimension seeds
/// (and, for Owen and LMS, the [`PreparedKey`]s) computed on first use and
/// kept: `apply` gives exactly `strategy.apply(word, seed, dim)`.
#[derive(Debug, Clone)]
pub struct ScrambleCache {
    strategy: RandomizeStrategy,
    seed: u64,
    /// Per-dimension seeds of dimensions `0..seeds.len()`.
    seeds: Vec<u32>,
    /// Prepared keys of dimensions `0..prepared.len()` (Owen and LMS only).
    prepared: Vec<PreparedKey>,
}

impl ScrambleCache {
    /// An empty cache for `strategy` under `seed`.
    pub fn new(strategy: RandomizeStrategy, seed: u64) -> Self {
        ScrambleCache {
            strategy,
            seed,
            seeds: Vec::new(),
            prepared: Vec::new(),
        }
    }

    /// The strategy.
    pub fn strategy(&self) -> RandomizeStrategy {
        self.strategy
    }

    /// Equals `self.strategy().apply(word, seed, dim)` for the seed given
    /// to [`ScrambleCache::new`].
    #[inline]
    pub fn apply(&mut self, word: u32, dim: u32) -> u32 {
        let r = self.strategy;
        if r == RandomizeStrategy::None {
            return word;
        }
        if dim >= CACHED_DIMENSIONS {
            return r.apply(word, self.seed, dim);
        }
        let d = dim as usize;
        if d >= self.seeds.len() {
            self.grow(d);
        }
        match self.prepared.get(d) {
            Some(key) => key.scramble(word),
            None => r.apply_dimension_seed(word, self.seeds[d]),
        }
    }

    /// Computes the entries of dimensions up to `d`.
    #[cold]
    fn grow(&mut self, d: usize) {
        for dim in self.seeds.len()..=d {
            let s = dimension_seed(self.seed, dim as u32);
            self.seeds.push(s);
            self.prepared.extend(self.strategy.prepare(s));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cached_scrambles_equal_apply() {
        for (seed, r) in (1u64..).zip(RandomizeStrategy::ALL) {
            let mut cache = ScrambleCache::new(r, seed);
            for (k, dim) in [5u32, 0, 3, 40, 7, 1023, 1024, 9000, 2]
                .into_iter()
                .enumerate()
            {
                for word in [0u32, u32::MAX, 0x1234_5678 ^ k as u32] {
                    let want = r.apply(word, seed, dim);
                    assert_eq!(cache.apply(word, dim), want, "{r:?} {dim}");
                }
            }
        }
    }

    #[test]
    fn prepared_keys_equal_the_plain_scramble() {
        for r in RandomizeStrategy::ALL {
            assert_eq!(r.prepare(77).is_some(), r.prepares());
            if let Some(key) = r.prepare(77) {
                for word in [0u32, 1, 0xdead_beef, u32::MAX] {
                    assert_eq!(key.scramble(word), r.apply_dimension_seed(word, 77));
                }
            }
        }
    }
}
