//! Integer hashing used to derive every random choice from explicit seeds.
//!
//! All functions are pure: the same inputs give the same outputs on every
//! platform. The 64-bit finaliser is the "mix13" variant of the SplitMix64
//! finaliser (David Stafford's published constants); the combination scheme
//! is lowdisc's own.

/// The two multipliers of [`mix64`] (for vectorised copies of it).
pub(crate) const MIX64_MULTIPLIERS: [u64; 2] = [0xbf58_476d_1ce4_e5b9, 0x94d0_49bb_1331_11eb];

/// A strong 64-bit bit mixer (bijective).
#[inline]
pub fn mix64(x: u64) -> u64 {
    mix64_from_product((x ^ (x >> 30)).wrapping_mul(MIX64_MULTIPLIERS[0]))
}

/// The steps of [`mix64`] after its first multiplication:
/// `mix64(x) == mix64_from_product((x ^ (x >> 30)) * MIX64_MULTIPLIERS[0])`
/// (wrapping). Lets a caller that hashes a run of inputs differing only in
/// their low bits step that product by addition.
#[inline(always)]
pub(crate) fn mix64_from_product(mut x: u64) -> u64 {
    x ^= x >> 27;
    x = x.wrapping_mul(MIX64_MULTIPLIERS[1]);
    x ^= x >> 31;
    x
}

/// Hashes a list of words into 64 bits. Order matters; the length is mixed in
/// so `[a]` and `[a, 0]` differ.
#[inline]
pub fn hash_words(words: &[u64]) -> u64 {
    words
        .iter()
        .fold(WordHasher::new(words.len()), |h, &w| h.push(w))
        .finish()
}

/// [`hash_words`] one word at a time, so a prefix shared by many hashes is
/// absorbed once: `WordHasher::new(n).push(w_1)...push(w_n).finish()` equals
/// `hash_words(&[w_1, ..., w_n])` (the length is fixed up front).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct WordHasher {
    state: u64,
}

impl WordHasher {
    /// A hasher of `len` words.
    #[inline]
    pub fn new(len: usize) -> Self {
        WordHasher {
            state: 0x9e37_79b9_7f4a_7c15u64 ^ (len as u64),
        }
    }

    /// Absorbs the next word.
    #[inline]
    pub fn push(self, word: u64) -> Self {
        WordHasher {
            state: mix64(self.state ^ word).wrapping_add(0x9e37_79b9_7f4a_7c15),
        }
    }

    /// The hash (meaningful once `len` words were pushed).
    #[inline]
    pub fn finish(self) -> u64 {
        mix64(self.state)
    }
}

/// Hash of two words.
#[inline]
pub fn hash2(a: u64, b: u64) -> u64 {
    hash_words(&[a, b])
}

/// Hash of three words.
#[inline]
pub fn hash3(a: u64, b: u64, c: u64) -> u64 {
    hash_words(&[a, b, c])
}

/// Hash of four words.
#[inline]
pub fn hash4(a: u64, b: u64, c: u64, d: u64) -> u64 {
    hash_words(&[a, b, c, d])
}

/// Uniform `f64` in `[0, 1)` from the top 53 bits of a hash.
#[inline]
pub fn unit_f64(h: u64) -> f64 {
    (h >> 11) as f64 * (1.0 / 9_007_199_254_740_992.0)
}

/// A uniformly distributed integer in `[0, n)` from a hash (Lemire's
/// multiply-shift reduction; bias below `n / 2^64`).
#[inline]
pub fn bounded(h: u64, n: u64) -> u64 {
    ((h as u128 * n as u128) >> 64) as u64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pinned_values() {
        assert_eq!(mix64(0), 0);
        assert_eq!(mix64(1), 0x5692_161d_100b_05e5); // checked with an independent Python evaluation
        assert_eq!(hash2(1, 2), hash2(1, 2));
        assert_ne!(hash2(1, 2), hash2(2, 1));
        assert_ne!(hash_words(&[5]), hash_words(&[5, 0]));
        // The chain as first written, one round per word.
        let words = [3u64, u64::MAX, 0, 17, 1 << 40];
        let mut h = 0x9e37_79b9_7f4a_7c15u64 ^ 5;
        for &w in &words {
            h = mix64(h ^ w).wrapping_add(0x9e37_79b9_7f4a_7c15);
        }
        assert_eq!(hash_words(&words), mix64(h));
        let prefix = WordHasher::new(5).push(3).push(u64::MAX).push(0);
        assert_eq!(prefix.push(17).push(1 << 40).finish(), mix64(h));
    }

    #[test]
    fn bounded_stays_in_range() {
        for i in 0..1000u64 {
            assert!(bounded(mix64(i), 7) < 7);
        }
        assert_eq!(bounded(u64::MAX, 10), 9);
    }
}
