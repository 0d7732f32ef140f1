//! [`ScrambleCache`]: a [`RandomizeStrategy`] and its seed, with the
//! per-dimension seed hashing done once per dimension and kept, for callers
//! that scramble many words of the same few dimensions (the pixel samplers).

use alloc::vec::Vec;

use super::{OwenKey, RandomizeStrategy, dimension_seed};

/// Dimensions below this are cached; the others are hashed on every call.
const CACHED_DIMENSIONS: u32 = 1024;

/// A [`RandomizeStrategy`] under one seed, with its per-dimension seeds
/// (and, for Owen scrambling, the [`OwenKey`]s) computed on first use and
/// kept: `apply` gives exactly `strategy.apply(word, seed, dim)`.
#[derive(Debug, Clone)]
pub struct ScrambleCache {
    strategy: RandomizeStrategy,
    seed: u64,
    /// Per-dimension seeds of dimensions `0..seeds.len()`.
    seeds: Vec<u32>,
    /// Owen keys of dimensions `0..owen.len()` (Owen only).
    owen: Vec<OwenKey>,
}

impl ScrambleCache {
    /// An empty cache for `strategy` under `seed`.
    pub fn new(strategy: RandomizeStrategy, seed: u64) -> Self {
        ScrambleCache {
            strategy,
            seed,
            seeds: Vec::new(),
            owen: Vec::new(),
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
        match r {
            RandomizeStrategy::Owen => self.owen[d].scramble(word),
            _ => r.apply_dimension_seed(word, self.seeds[d]),
        }
    }

    /// Computes the entries of dimensions up to `d`.
    #[cold]
    fn grow(&mut self, d: usize) {
        let owen = self.strategy == RandomizeStrategy::Owen;
        for dim in self.seeds.len()..=d {
            let s = dimension_seed(self.seed, dim as u32);
            self.seeds.push(s);
            if owen {
                self.owen.push(OwenKey::new(s));
            }
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
}
