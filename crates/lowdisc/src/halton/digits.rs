//! Digit arithmetic of the radical inverse, exact and without 128-bit
//! division.
//!
//! A value is built from its base-`b` digits `d_0, d_1, ...` (first digit
//! after the point first) as `floor(x * 2^64)` by Horner's rule run from the
//! last digit: `x <- floor((d_i * 2^64 + x) / b)`. Nested floors of this form
//! equal the floor of the exact value (`floor((n + floor(y)) / b) =
//! floor((n + y) / b)` for integers `n`, `b`), so the result is exact.
//! Digits are grouped into chunks of `g` digits with `b^g < 2^32`, so each
//! step divides a 96-bit number by a 32-bit one: two `u64` divisions.
//!
//! Divisions by the base itself use Lemire, Kaser and Kurz's "direct
//! remainder" method (2019, "Faster remainder by direct computation"): with
//! `M = ceil(2^64 / b)`, `a / b = (M a) >> 64` and `a mod b = ((M a mod 2^64)
//! b) >> 64`, exact for all 32-bit `a` and `b`.

use super::primes::{NUM_DIMENSIONS, PRIMES, scrambled_digits};

/// Most digits any `u64` index or scrambled value uses (base 2: 64).
pub(super) const MAX_DIGITS: usize = 64;

/// Precomputed constants of one base.
#[derive(Debug, Clone, Copy)]
pub(super) struct Base {
    /// The base `b`.
    pub b: u32,
    /// `ceil(2^64 / b)`, the direct-remainder multiplier.
    magic: u64,
    /// Digits per chunk `g`: the largest `g` with `b^g < 2^32`.
    chunk_digits: u32,
    /// `b^g`.
    chunk_power: u32,
    /// How many digit positions the randomizations scramble.
    pub scrambled: u32,
}

impl Base {
    /// The constants of base `b >= 2`.
    pub const fn new(b: u32) -> Base {
        let mut chunk_digits = 0;
        let mut power: u64 = 1;
        while power * (b as u64) < (1u64 << 32) {
            power *= b as u64;
            chunk_digits += 1;
        }
        Base {
            b,
            magic: u64::MAX / b as u64 + 1,
            chunk_digits,
            chunk_power: power as u32,
            scrambled: scrambled_digits(b),
        }
    }

    /// `a / b`.
    #[inline]
    pub fn div(&self, a: u32) -> u32 {
        ((u128::from(self.magic) * u128::from(a)) >> 64) as u32
    }

    /// `a mod b`.
    #[inline]
    pub fn rem(&self, a: u32) -> u32 {
        let low = self.magic.wrapping_mul(u64::from(a));
        ((u128::from(low) * u128::from(self.b)) >> 64) as u32
    }

    /// Writes the base-`b` digits of `index` (least significant first) to
    /// `out` and returns how many there are (0 for index 0).
    #[inline]
    pub fn digits(&self, index: u64, out: &mut [u32; MAX_DIGITS]) -> usize {
        let power = u64::from(self.chunk_power);
        let (mut rest, mut n) = (index, 0usize);
        while rest > 0 {
            let mut chunk = (rest % power) as u32;
            rest /= power;
            if rest > 0 {
                for _ in 0..self.chunk_digits {
                    let q = self.div(chunk);
                    out[n] = chunk - q * self.b;
                    chunk = q;
                    n += 1;
                }
            } else {
                while chunk > 0 {
                    let q = self.div(chunk);
                    out[n] = chunk - q * self.b;
                    chunk = q;
                    n += 1;
                }
            }
        }
        n
    }

    /// `floor(x * 2^64)` for `x = sum_i digits[i] b^-(i+1)` (exact).
    #[inline]
    pub fn fixed64(&self, digits: &[u32]) -> u64 {
        self.fixed64_with_tail(digits, 0)
    }

    /// `floor(x * 2^64)` for `x = sum_{i < n} digits[i] b^-(i+1) + t b^-n`,
    /// where `n = digits.len()` and `tail = floor(t * 2^64)` for a tail value
    /// `t` in `[0, 1)` (exact, by the nested-floor identity).
    #[inline]
    pub fn fixed64_with_tail(&self, digits: &[u32], tail: u64) -> u64 {
        let g = self.chunk_digits as usize;
        let (mut x, mut end) = (tail, digits.len());
        while end > 0 {
            let start = end.saturating_sub(g);
            let (mut chunk, mut power) = (0u64, 1u64);
            for &d in &digits[start..end] {
                chunk = chunk * u64::from(self.b) + u64::from(d);
                power *= u64::from(self.b);
            }
            // x <- floor((chunk * 2^64 + x) / power), chunk < power < 2^32.
            let high = (chunk << 32) | (x >> 32);
            let (q1, r1) = (high / power, high % power);
            let q2 = ((r1 << 32) | (x & 0xffff_ffff)) / power;
            x = (q1 << 32) | q2;
            end = start;
        }
        x
    }
}

/// The constants of every Halton base.
pub(super) static BASES: [Base; NUM_DIMENSIONS as usize] = {
    let mut bases = [Base::new(2); NUM_DIMENSIONS as usize];
    let mut i = 0;
    while i < bases.len() {
        bases[i] = Base::new(PRIMES[i]);
        i += 1;
    }
    bases
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pcg::Pcg32;

    #[test]
    fn direct_remainder_is_exact() {
        let mut rng = Pcg32::new(1, 2);
        for base in BASES
            .iter()
            .chain([Base::new(u32::MAX), Base::new(65_537)].iter())
        {
            for a in (0..2000u32).chain([
                u32::MAX,
                u32::MAX - 1,
                base.b - 1,
                base.b,
                base.b.saturating_add(1),
            ]) {
                assert_eq!(base.div(a), a / base.b);
                assert_eq!(base.rem(a), a % base.b);
            }
            for _ in 0..200 {
                let a = rng.next_u32();
                assert_eq!((base.div(a), base.rem(a)), (a / base.b, a % base.b));
            }
        }
    }

    #[test]
    fn chunks_fit_32_bits() {
        for base in &BASES {
            let p = u64::from(base.chunk_power);
            assert!(
                p < 1 << 32 && p * u64::from(base.b) >= 1 << 32,
                "base {}",
                base.b
            );
            assert_eq!(p, u64::from(base.b).pow(base.chunk_digits));
        }
        assert_eq!(BASES[0].chunk_digits, 31);
        assert_eq!(BASES[1].chunk_digits, 20);
    }

    /// Continuing from a tail's value equals evaluating all digits at once.
    #[test]
    fn tails_continue_exactly() {
        let mut rng = Pcg32::new(8, 9);
        for base in [&BASES[0], &BASES[1], &BASES[7], &BASES[1023]] {
            let k = base.scrambled as usize;
            let digits: alloc::vec::Vec<u32> = (0..k).map(|_| rng.next_u32() % base.b).collect();
            for m in 0..=k {
                let tail = base.fixed64(&digits[m..]);
                assert_eq!(
                    base.fixed64_with_tail(&digits[..m], tail),
                    base.fixed64(&digits)
                );
            }
        }
    }

    #[test]
    fn digits_round_trip() {
        let mut rng = Pcg32::new(3, 4);
        let mut out = [0u32; MAX_DIGITS];
        for base in &BASES {
            for _ in 0..20 {
                let index = (u64::from(rng.next_u32()) << 32 | u64::from(rng.next_u32()))
                    >> (rng.next_u32() % 64);
                let n = base.digits(index, &mut out);
                let back = out[..n]
                    .iter()
                    .rev()
                    .fold(0u128, |acc, &d| acc * u128::from(base.b) + u128::from(d));
                assert_eq!(back, u128::from(index));
                assert!(n == 0 || out[n - 1] != 0);
                assert!(out[..n].iter().all(|&d| d < base.b));
            }
        }
        assert_eq!(BASES[0].digits(0, &mut out), 0);
        assert_eq!(BASES[0].digits(u64::MAX, &mut out), 64);
    }
}
