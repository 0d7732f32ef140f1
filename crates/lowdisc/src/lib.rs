//! # lowdisc: sample sequences for Monte Carlo rendering
//!
//! Exact Sobol sequences (all 21,201 dimensions of Joe & Kuo 2008), the
//! digit-permuted Sobol of Song & Ro (2019) in a literal and a reproducible
//! form, the modern randomizations (random digital shift, exact Owen, fast
//! hash-based Owen, linear matrix scrambling), Halton, progressive
//! multi-jittered (0,2), stratified and independent sequences, and the
//! pixel samplers a renderer drives through four calls (`start_pixel_sample`,
//! `get_1d`, `get_2d`, `get_pixel_2d`).
//!
//! ## Conventions
//! * A sample value is a 32-bit *digit word*: bit 31 is the first binary digit
//!   after the point, so the value is `word * 2^-32`. Every sequence here is
//!   defined on these words; floats are derived with [`to_f32`]/[`to_f64`],
//!   which never round up to 1.
//! * [`sobol::sample`] is Sobol's own definition (natural order: index bit `c`
//!   selects matrix column `c`), which is what pbrt uses. Joe & Kuo's reference
//!   generator and `scipy.stats.qmc.Sobol` emit the same points in Gray-code
//!   order: their point `k` is `sample(gray(k), d)`; [`sobol::GrayCodeBatch`]
//!   produces that order fast. The first `2^m` points are the same set in
//!   both orders.
//! * Every random choice takes an explicit seed.
//!
//! ## Modules
//! * sequences: [`sobol`] (matrices, points, Gray-code batches), [`net`]
//!   (any digital net from user-given matrices), [`sz`] (a
//!   (0,4)-sequence in base 4 as binary columns), [`halton`],
//!   [`stratified`], [`independent`];
//! * randomizations: [`scramble`] (digital shift, Owen, fast Owen), [`paper`]
//!   (Song & Ro's permutation), [`hash`] and [`pcg`] (seeded randomness);
//! * [`pixel`]: the pixel samplers a renderer drives; [`catalog`]: every
//!   sampler by name, declared in one table, and the enum over them built
//!   from one configuration; [`error`].
//!
//! The crate is `no_std` (with `alloc`) when the default `std` feature is off.
#![cfg_attr(not(feature = "std"), no_std)]

extern crate alloc;

pub mod catalog;
pub mod error;
pub mod halton;
pub mod hash;
pub mod independent;
pub mod net;
#[cfg(test)]
mod net_check;
pub mod paper;
pub mod pcg;
pub mod pixel;
pub mod pmj;
pub mod scramble;
pub mod sobol;
pub mod stratified;
pub mod sz;

pub use error::Error;
pub use scramble::RandomizeStrategy;

/// The largest `f32` below 1.
pub const ONE_MINUS_EPSILON_F32: f32 = 1.0 - f32::EPSILON / 2.0;

/// Converts a 32-bit digit word to `[0, 1)` as `f32`, keeping the 24 leading
/// digits exactly (the value is never rounded up to 1).
#[inline]
pub fn to_f32(word: u32) -> f32 {
    (word >> 8) as f32 * (1.0 / 16_777_216.0)
}

/// [`to_f32`] of `reversed.reverse_bits()`, without the reversal: the 24
/// digits `to_f32` keeps are the low three bytes of `reversed`, each
/// reversed by a table that holds its value already scaled to its place.
/// Each table value is a multiple of `2^-24` below 1 and so is every
/// partial sum, so the additions are exact and the result is bit for bit
/// `to_f32`'s (tested over every byte in every place).
#[inline(always)]
pub fn reversed_to_f32(reversed: u32) -> f32 {
    let [b0, b1, b2, _] = reversed.to_le_bytes();
    REVERSED_BYTE_VALUES[0][usize::from(b0)]
        + REVERSED_BYTE_VALUES[1][usize::from(b1)]
        + REVERSED_BYTE_VALUES[2][usize::from(b2)]
}

/// `REVERSED_BYTE_VALUES[k][b]`: the value `to_f32` gives the reversed byte
/// `b` as digits `8k + 1..=8k + 8` (that is, `b.reverse_bits() * 2^-8(k+1)`).
static REVERSED_BYTE_VALUES: [[f32; 256]; 3] = {
    let mut out = [[0.0f32; 256]; 3];
    let mut k = 0;
    while k < 3 {
        let mut b = 0;
        while b < 256 {
            let place = (1u32 << (8 * (k + 1))) as f32;
            out[k][b] = (b as u8).reverse_bits() as f32 / place;
            b += 1;
        }
        k += 1;
    }
    out
};

/// Converts a 32-bit digit word to `[0, 1)` as `f64`, exactly.
#[inline]
pub fn to_f64(word: u32) -> f64 {
    word as f64 * (1.0 / 4_294_967_296.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reversed_to_f32_is_to_f32_of_the_reversed_word() {
        // Every value of the three bytes that matter, under changing top bytes.
        for low in 0..1u32 << 24 {
            let reversed = low | (low.wrapping_mul(0x9e37_79b9) & 0xff00_0000);
            let want = to_f32(reversed.reverse_bits());
            assert_eq!(
                reversed_to_f32(reversed).to_bits(),
                want.to_bits(),
                "{reversed:#x}"
            );
        }
        assert_eq!(reversed_to_f32(u32::MAX), ONE_MINUS_EPSILON_F32);
        assert_eq!(reversed_to_f32(0), 0.0);
    }
}
