//! The base-4 digit permutations of the cached path (`cache.rs`): the
//! sample digits below the tabled ones, one at a time ([`below_top`]), and
//! the pixel part of a dimension key's entry ([`refresh`]), computed as
//! [`super::ZSobolSampler::sample_index`] defines it, with less work:
//!
//! * **Hashes**: every permutation is chosen by
//!   `mix64(level ^ higher)`, whose first step `x ^ (x >> 30)` is linear
//!   over XOR, so the cache keeps that step of each level hash and
//!   [`PixelSteps`] computes it of a pixel's inputs once for every key.
//! * **Pixel digits**: digit `i` of the pixel's Morton code is permuted by
//!   a hash of the digits above it, so when the pixel changes only the
//!   digits at or below the highest changed one are permuted again (a
//!   renderer walks neighbouring pixels, whose codes differ in one or two
//!   low digits); the Sobol words follow by XOR, one table entry per digit.
//!   The digit whose value changed keeps its permutation (chosen by the
//!   digits above it), so a step to the next pixel in a row hashes about
//!   one digit.
//! * **Tabled sample digits**: a level of `4^j` permutations hashes inputs
//!   `input ^ v` with `v < 4^j`, so the first step of
//!   [`mix64`](crate::hash::mix64) is done once per level
//!   ([`mix64_from_product`]).

use super::BASE4_PERMUTATIONS;
use super::entry::{Entry, Layout, TOP_LEN, top_digits};
use crate::hash::{MIX64_MULTIPLIERS, bounded, hash_words, mix64, mix64_from_product};
use crate::pixel::SEED_PAD;
use crate::scramble::{dimension_seed, fast_owen_multiplier};

/// [`BASE4_PERMUTATIONS`] packed two bits per image: permutation `p` maps
/// digit `d` to `(PACKED_PERMUTATIONS[p] >> 2d) & 3`.
const PACKED_PERMUTATIONS: [u8; 24] = {
    let mut out = [0u8; 24];
    let mut p = 0;
    while p < 24 {
        let q = BASE4_PERMUTATIONS[p];
        out[p] = q[0] | (q[1] << 2) | (q[2] << 4) | (q[3] << 6);
        p += 1;
    }
    out
};

/// [`BASE4_PERMUTATIONS`] as four bytes, image of digit `d` in byte `d`
/// (little-endian): a digit's permuted images appended to a prefix `q`
/// are `SPREAD_PERMUTATIONS[p] | q * 0x0404_0404`.
const SPREAD_PERMUTATIONS: [u32; 24] = {
    let mut out = [0u32; 24];
    let mut p = 0;
    while p < 24 {
        out[p] = u32::from_le_bytes(BASE4_PERMUTATIONS[p]);
        p += 1;
    }
    out
};

/// The first step of [`mix64`](crate::hash::mix64), `x ^ (x >> 30)`,
/// which is linear over XOR: the cache keeps it of every level hash, and of
/// the pixel's higher digits once per pixel.
#[inline(always)]
pub(super) fn first_step(x: u64) -> u64 {
    x ^ (x >> 30)
}

/// The index (into [`BASE4_PERMUTATIONS`]) of the permutation chosen for a
/// digit with level hash `level` and higher digits `higher`, given
/// `first_step(level) ^ first_step(higher)`: it is
/// `bounded(mix64(level ^ higher), 24)`.
#[inline(always)]
fn permutation_index(first: u64) -> usize {
    let product = first.wrapping_mul(MIX64_MULTIPLIERS[0]);
    bounded(mix64_from_product(product), 24) as usize
}

/// The permuted base-4 digit of `morton` at `shift`, in place, for the
/// digit whose level hash has the first step `level_step`.
#[inline(always)]
fn permuted_digit(level_step: u64, morton: u64, shift: u32) -> u64 {
    let higher = morton.checked_shr(shift + 2).unwrap_or(0);
    let packed = PACKED_PERMUTATIONS[permutation_index(level_step ^ first_step(higher))];
    u64::from((packed >> (2 * ((morton >> shift) & 3))) & 3) << shift
}

/// The permuted index bits below the tabled sample digits at Morton index
/// `morton` (`m` sample bits), for the key whose level hashes have the
/// first steps `levels` and whose odd low bit's flip has the key
/// `low_key`: the sample digits under the tabled ones (one bit mix each)
/// and the odd low bit.
#[inline(never)]
pub(super) fn below_top(levels: &[u64], low_key: u64, m: u32, morton: u64) -> u64 {
    let odd = m & 1;
    let mut lower = 0;
    // The digits below the top ones (index `i` at shift `2i - odd`).
    let rest = m / 2 - top_digits(m) + odd;
    for (i, &level) in (odd..rest).zip(&levels[odd as usize..]) {
        lower |= permuted_digit(level, morton, 2 * i - odd);
    }
    if odd == 1 {
        let flip = mix64(low_key ^ (morton >> 1)) >> 63;
        lower |= (morton & 1) ^ flip;
    }
    lower
}

/// The first steps of one pixel's hash inputs, shared by every dimension
/// key: of the digits above each pixel digit, and of the code shifted for
/// each level of tabled sample digits.
#[derive(Debug, Clone)]
pub(super) struct PixelSteps {
    /// The pixel's Morton code.
    pub code: u64,
    /// `first_step(code >> (2i + 2))` for pixel digit `i`.
    higher: [u64; 32],
    /// Pixel digit `i` of the code.
    digits: [u8; 32],
    /// `first_step(code << 2j)` for level `j` of the tabled digits.
    top: [u64; 4],
}

impl PixelSteps {
    /// The steps of the pixel with Morton code `code` (`pixel_digits` of
    /// them, at most 32).
    pub fn new(code: u64, pixel_digits: u32) -> Self {
        let (mut higher, mut digits) = ([0; 32], [0; 32]);
        for (i, (h, d)) in (0..pixel_digits).zip(higher.iter_mut().zip(&mut digits)) {
            *h = first_step(code.checked_shr(2 * i + 2).unwrap_or(0));
            *d = (code.checked_shr(2 * i).unwrap_or(0) & 3) as u8;
        }
        PixelSteps {
            code,
            higher,
            digits,
            top: core::array::from_fn(|j| first_step(code.checked_shl(2 * j as u32).unwrap_or(0))),
        }
    }
}

/// Recomputes the pixel part of `entry` (the dimension key `key`, whose
/// digits' level hashes have the first steps `levels`) for the pixel with
/// the steps `steps`. `digit_words[i][d]` are the bit-reversed Sobol words
/// of pixel digit `i` with value `d` (see `Cache::digit_words`).
#[inline(always)]
pub(super) fn refresh(
    entry: &mut Entry,
    levels: &[u64],
    layout: &Layout,
    digit_words: &[[u64; 4]],
    key: u64,
    steps: &PixelSteps,
) {
    let m = layout.log2_spp;
    let code = steps.code;
    let first_pixel_digit = m.div_ceil(2) as usize;
    permute_pixel_digits(entry, &levels[first_pixel_digit..], m, digit_words, steps);
    // The highest sample digits (a constant count per layout, so each
    // count gets its own unrolled copy).
    let top = &levels[..first_pixel_digit];
    match top_digits(m) {
        0 => entry.top[0] = 0,
        1 => fill_top::<1>(&mut entry.top, top, steps),
        2 => fill_top::<2>(&mut entry.top, top, steps),
        3 => fill_top::<3>(&mut entry.top, top, steps),
        _ => fill_top::<4>(&mut entry.top, top, steps),
    }
    let high = entry.upper >> 32;
    if !entry.seeded || entry.high != high {
        let h = hash_words(&[layout.seed, SEED_PAD, key, high]);
        entry.keys = [0, 1].map(|d| layout.strategy.scramble_key(dimension_seed(h, d)));
        entry.multipliers = entry.keys.map(fast_owen_multiplier);
        entry.high = high;
        entry.seeded = true;
    }
    entry.code = code;
    entry.valid = true;
}

/// Fills `top` with the permuted values of the `T` highest sample digits:
/// the `j`-th from the top is the last but `j` of `levels` (the first
/// steps of the sample digits' level hashes); its permutation is chosen by
/// the pixel code and the `j` digits above it (value `v`). Each pass
/// extends the permuted prefixes of `j` digits (`top[v]`) by one digit, in
/// place from the end, four prefixes at a time (entries `16g..16g + 16`
/// are written after prefixes `4g..4g + 4` are read).
#[inline(always)]
fn fill_top<const T: usize>(top: &mut [u8; TOP_LEN], levels: &[u64], steps: &PixelSteps) {
    let levels: &[u64; T] = levels[levels.len() - T..].try_into().expect("T levels");
    for j in 0..T {
        // Every input is `level ^ (code << 2j) ^ v` (`v < 4^j`), whose
        // first step is `first ^ v`.
        let first = levels[T - 1 - j] ^ steps.top[j & 3];
        let permutation = |v: usize| SPREAD_PERMUTATIONS[permutation_index(first ^ v as u64)];
        if j == 0 {
            top[..4].copy_from_slice(&permutation(0).to_le_bytes());
            continue;
        }
        for g in (0..1usize << (2 * j - 2)).rev() {
            let g = g & (TOP_LEN / 16 - 1);
            let prefixes: [u8; 4] = core::array::from_fn(|r| top[4 * g + r]);
            let mut block = [0u8; 16];
            for (r, &prefix) in prefixes.iter().enumerate() {
                let extended = permutation(4 * g + r) | (u32::from(prefix) * 0x0404_0404);
                block[4 * r..4 * r + 4].copy_from_slice(&extended.to_le_bytes());
            }
            top[16 * g..16 * g + 16].copy_from_slice(&block);
        }
    }
}

/// Brings `entry.upper` and `entry.upper_words` (and the kept pixel digit
/// permutations) from the entry's pixel to the pixel of `steps`; `levels`
/// are the first steps of the pixel digits' level hashes. Pixel digit
/// `i` sits at index bit `m + 2i`; its permutation depends only on the
/// digits above it, so the digits above the highest changed one are kept,
/// that digit keeps its permutation, and only the digits below it are
/// hashed again.
#[inline(always)]
fn permute_pixel_digits(
    entry: &mut Entry,
    levels: &[u64],
    m: u32,
    digit_words: &[[u64; 4]],
    steps: &PixelSteps,
) {
    let (changed, kept_permutation) = if entry.valid {
        let bits = 64 - (entry.code ^ steps.code).leading_zeros();
        (bits.div_ceil(2) as usize, bits != 0)
    } else {
        (levels.len(), false)
    };
    let (mut upper, mut words) = (entry.upper, entry.upper_words);
    let changed = changed.min(levels.len()).min(digit_words.len()).min(32);
    let (levels, digit_words) = (&levels[..changed], &digit_words[..changed]);
    for i in (0..changed).rev() {
        let p = if kept_permutation && i + 1 == changed {
            entry.pixel_permutations[i]
        } else {
            permutation_index(levels[i] ^ steps.higher[i]) as u8
        };
        entry.pixel_permutations[i] = p;
        let permuted = BASE4_PERMUTATIONS[usize::from(p)][usize::from(steps.digits[i] & 3)];
        let flip = entry.pixel_digits[i] ^ permuted;
        entry.pixel_digits[i] = permuted;
        upper ^= u64::from(flip) << (m + 2 * i as u32);
        words ^= digit_words[i][usize::from(flip & 3)];
    }
    entry.upper = upper;
    entry.upper_words = words;
}
