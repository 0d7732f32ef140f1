//! Matoušek's linear matrix scrambling with a random digital shift
//! (LMS + shift: J. Matoušek 1998, "On the L2-discrepancy for anchored
//! boxes", J. Complexity 14; the scramble of `scipy.stats.qmc.Sobol`).
//!
//! Each dimension's generator matrix `C` is replaced by `L C`, with `L` a
//! random nonsingular lower-triangular 32x32 matrix over GF(2) (ones on the
//! diagonal, independent fair bits below it), and the point is XORed with a
//! random word (the digital shift). Because the Sobol point is `C i`, this is
//! a map of the output word alone: `w -> L w ^ shift`. Output digit `r` is
//! input digit `r` plus a random linear combination of digits `0..r`, so the
//! top `k` digits depend only on the top `k` digits: every elementary
//! interval is mapped onto one of the same size, and a (t,m,s)-net stays a
//! (t,m,s)-net. Unlike Owen scrambling it is linear, so it costs one XOR per
//! set bit of the word once `L` is built ([`LmsKey`]).

use crate::hash::{hash2, mix64};

/// Salt of the matrix and shift of [`LmsKey::new`].
const LMS_SALT: u64 = 0x6c6d_735f_7368_6966;

/// The scramble of one dimension: the columns of `L` and the shift.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LmsKey {
    /// Column of input bit `p` (digit `31 - p`): bit `p` set, random bits
    /// below it (the later digits), none above.
    columns: [u32; 32],
    /// The digital shift.
    shift: u32,
}

impl LmsKey {
    /// The scramble drawn from a per-dimension seed.
    pub fn new(seed: u32) -> Self {
        let base = hash2(LMS_SALT, u64::from(seed));
        let columns = core::array::from_fn(|p| {
            let below = (1u32 << p) - 1;
            let random =
                (mix64(base ^ (p as u64 + 1).wrapping_mul(0x9e37_79b9_7f4a_7c15)) >> 32) as u32;
            (1 << p) | (random & below)
        });
        LmsKey {
            columns,
            shift: (mix64(base) >> 32) as u32,
        }
    }

    /// `L word ^ shift`.
    #[inline]
    pub fn scramble(&self, word: u32) -> u32 {
        let mut out = self.shift;
        let mut rest = word;
        while rest != 0 {
            out ^= self.columns[rest.trailing_zeros() as usize];
            rest &= rest - 1;
        }
        out
    }

    /// The digital shift (the image of the zero word).
    pub fn shift(&self) -> u32 {
        self.shift
    }
}

/// LMS + shift of one word under a per-dimension seed (builds the key; see
/// [`LmsKey`] to reuse it).
// Not inlined, as `owen_scramble`: building the key dwarfs a call.
#[inline(never)]
pub fn lms_scramble(word: u32, seed: u32) -> u32 {
    LmsKey::new(seed).scramble(word)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_matrix_is_unit_lower_triangular_and_random_below() {
        let key = LmsKey::new(7);
        let mut below_bits = 0;
        for (p, &c) in key.columns.iter().enumerate() {
            assert_eq!(c >> p, 1, "column {p}: diagonal set, nothing above");
            below_bits += (c & ((1u32 << p) - 1)).count_ones();
        }
        // 496 entries below the diagonal, each a fair bit: 248 +- 11.
        assert!((200..300).contains(&below_bits), "{below_bits}");
    }

    #[test]
    fn the_scramble_is_linear_plus_shift_and_a_bijection_on_prefixes() {
        let key = LmsKey::new(99);
        let s = key.shift();
        for (a, b) in [(1u32, 2u32), (0xdead_beef, 0x1234_5678), (u32::MAX, 5)] {
            assert_eq!(
                key.scramble(a ^ b) ^ s,
                (key.scramble(a) ^ s) ^ (key.scramble(b) ^ s)
            );
        }
        // The top 10 digits of the image depend on the top 10 digits only,
        // bijectively.
        let mut seen = alloc::vec![false; 1024];
        for top in 0..1024u32 {
            let low = mix64(u64::from(top)) as u32 >> 10;
            let image = key.scramble(top << 22 | low) >> 22;
            assert_eq!(image, key.scramble(top << 22) >> 22);
            assert!(!core::mem::replace(&mut seen[image as usize], true));
        }
    }

    #[test]
    fn seeds_give_different_scrambles() {
        let (a, b) = (LmsKey::new(1), LmsKey::new(2));
        assert_ne!(a, b);
        assert_eq!(lms_scramble(0x8000_0000, 1), a.scramble(0x8000_0000));
        assert_ne!(a.scramble(0x4000_0000), 0x4000_0000 ^ a.shift());
    }
}
