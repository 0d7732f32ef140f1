//! [`ScrambleCache`]: a [`Randomize`] whose per-dimension seed hashing is
//! done once per dimension and kept, for callers that scramble many words of
//! the same few dimensions (the pixel samplers).

use alloc::vec::Vec;

use super::{OwenKey, Randomize, dimension_seed};

/// Dimensions below this are cached; the others are hashed on every call.
const CACHED_DIMENSIONS: u32 = 1024;

/// A [`Randomize`] with its per-dimension seeds (and, for Owen scrambling,
/// the [`OwenKey`]s) computed on first use and kept: `apply` gives exactly
/// `randomize.apply(word, dim)`.
#[derive(Debug, Clone)]
pub struct ScrambleCache {
    randomize: Randomize,
    /// Per-dimension seeds of dimensions `0..seeds.len()`.
    seeds: Vec<u32>,
    /// Owen keys of dimensions `0..owen.len()` (Owen only).
    owen: Vec<OwenKey>,
}

impl ScrambleCache {
    /// An empty cache for `randomize`.
    pub fn new(randomize: Randomize) -> Self {
        ScrambleCache {
            randomize,
            seeds: Vec::new(),
            owen: Vec::new(),
        }
    }

    /// The randomization.
    pub fn randomize(&self) -> Randomize {
        self.randomize
    }

    /// Equals `self.randomize().apply(word, dim)`.
    #[inline]
    pub fn apply(&mut self, word: u32, dim: u32) -> u32 {
        let r = self.randomize;
        if r == Randomize::None {
            return word;
        }
        if dim >= CACHED_DIMENSIONS {
            return r.apply(word, dim);
        }
        let d = dim as usize;
        if d >= self.seeds.len() {
            self.grow(d);
        }
        match r {
            Randomize::Owen { .. } => self.owen[d].scramble(word),
            _ => r.apply_dimension_seed(word, self.seeds[d]),
        }
    }

    /// Computes the entries of dimensions up to `d`.
    #[cold]
    fn grow(&mut self, d: usize) {
        let seed = match self.randomize {
            Randomize::None => return,
            Randomize::Xor { seed } | Randomize::Owen { seed } | Randomize::FastOwen { seed } => {
                seed
            }
        };
        let owen = matches!(self.randomize, Randomize::Owen { .. });
        for dim in self.seeds.len()..=d {
            let s = dimension_seed(seed, dim as u32);
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
        for r in [
            Randomize::None,
            Randomize::Xor { seed: 1 },
            Randomize::Owen { seed: 2 },
            Randomize::FastOwen { seed: 3 },
        ] {
            let mut cache = ScrambleCache::new(r);
            for (k, dim) in [5u32, 0, 3, 40, 7, 1023, 1024, 9000, 2]
                .into_iter()
                .enumerate()
            {
                for word in [0u32, u32::MAX, 0x1234_5678 ^ k as u32] {
                    assert_eq!(cache.apply(word, dim), r.apply(word, dim), "{r:?} {dim}");
                }
            }
        }
    }
}
