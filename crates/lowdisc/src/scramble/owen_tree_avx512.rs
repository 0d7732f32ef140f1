//! The AVX-512 kernel of [`super::OwenTreePoints`]: eight dimensions of a
//! point per vector, each lane a 64-bit copy of its digit word.
//!
//! Per layer `t >= 1` of the tree (module `owen_tree`): the root (the first
//! `6t` digits) times `GAMMA` plus the lane's `K_t`, then `mix64` with two
//! 64-bit multiplies (AVX-512 DQ); layer 0's bits are the key itself. The 6
//! nodes of the digit word's path through the subtree are then picked at
//! once: the node of local depth `i` is bit `2^i - 1 + q_i` of the subtree's
//! word, `q_i` the `i` local digits before it. One byte shift per depth
//! (VBMI `multishift`) cuts the `q_i` out of the word, a mask and an add
//! make them bit indices, the bit shuffle (BITALG `bitshuffle`) gathers the
//! 6 bits into a mask register, and a masked byte move plus a byte sum
//! (`sad`) turn them into the layer's 6-digit XOR mask, depth 0 first.
//!
//! Byte `p` (0..5) of each lane handles depth `5 - p`, so its bit weighs
//! `2^p` in the sum: the path's last node lands on the lowest digit, as in
//! `owen_tree::path_flips`.

// The unaligned loads and stores of `core::arch` and the call into the
// target-feature function (after run-time detection) are the unsafe parts.
#![allow(unsafe_code)]
// build.rs compiles this module only with Rust 1.89 or newer, where these
// intrinsics are stable; the crate's rust-version builds without it.
#![allow(clippy::incompatible_msrv)]

use alloc::vec::Vec;
use core::arch::x86_64::*;

use super::owen_tree::{GAMMA, LANES, LAYERS_TOTAL, SUBTREE_DEPTH};
use crate::hash::MIX64_MULTIPLIERS;

/// Whether this CPU runs the kernel (every extension it uses).
pub(super) fn available() -> bool {
    std::arch::is_x86_feature_detected!("avx512f")
        && std::arch::is_x86_feature_detected!("avx512dq")
        && std::arch::is_x86_feature_detected!("avx512bw")
        && std::arch::is_x86_feature_detected!("avx512vl")
        && std::arch::is_x86_feature_detected!("avx512vbmi")
        && std::arch::is_x86_feature_detected!("avx512bitalg")
}

/// Scrambles the points of `words` (`d` words each) in place, keeping
/// `digits` digits, with the keys `by_layer` (see `Kernel::Avx512`).
/// `LAYERS` must be `layers_of(digits)`.
pub(super) fn scramble_points<const LAYERS: usize>(
    by_layer: &[Vec<u64>; LAYERS_TOTAL],
    d: usize,
    words: &mut [u32],
    digits: u32,
) {
    assert!(
        available(),
        "the AVX-512 Owen kernel needs AVX-512 VBMI and BITALG"
    );
    let padded = d.div_ceil(LANES) * LANES;
    assert!(by_layer.iter().all(|keys| keys.len() == padded));
    // SAFETY: the CPU has every feature the function enables (checked just
    // above), and the key arrays hold `padded` values, which the function
    // reads for every group of `LANES` dimensions.
    unsafe { scramble::<LAYERS>(by_layer, d, words, digits) }
}

/// `scramble_points`, in the target-feature context.
///
/// # Safety
/// The CPU must have AVX-512 F, DQ, BW, VL, VBMI and BITALG, and each
/// `by_layer[t]` must hold `d` rounded up to a multiple of [`LANES`] keys.
#[target_feature(enable = "avx512f,avx512dq,avx512bw,avx512vl,avx512vbmi,avx512bitalg")]
#[inline]
unsafe fn scramble<const LAYERS: usize>(
    by_layer: &[Vec<u64>; LAYERS_TOTAL],
    d: usize,
    words: &mut [u32],
    digits: u32,
) {
    let keep = _mm512_set1_epi64(i64::from(u32::MAX << (32 - digits)));
    let paths: [PathConstants; LAYERS_TOTAL] = core::array::from_fn(PathConstants::of_layer);
    for point in words.chunks_exact_mut(d) {
        for g in (0..d).step_by(LANES) {
            let lanes = (d - g).min(LANES);
            let active = (u16::MAX >> (16 - lanes)) as __mmask8;
            // SAFETY: the mask reads and writes only the `lanes` words
            // `g .. g + lanes` of `point`; the keys hold `g + LANES` values.
            unsafe {
                let at = point.as_mut_ptr().add(g);
                let word = _mm512_cvtepu32_epi64(_mm256_maskz_loadu_epi32(active, at.cast()));
                let mut flips = _mm512_setzero_si512();
                for (t, path) in paths.iter().enumerate().take(LAYERS) {
                    let key = _mm512_loadu_epi64(by_layer[t].as_ptr().add(g).cast());
                    let bits = if t == 0 {
                        key
                    } else {
                        subtree_bits(key, word, t)
                    };
                    flips = _mm512_or_si512(flips, path.flips(bits, word));
                }
                let out = _mm512_and_si512(_mm512_xor_si512(word, flips), keep);
                _mm256_mask_storeu_epi32(at.cast(), active, _mm512_cvtepi64_epi32(out));
            }
        }
    }
}

/// The 63 node bits of the layer-`t` subtrees of `word`'s prefixes:
/// `mix64(K_t + (word >> (32 - 6t)) * GAMMA)` in each lane.
#[target_feature(enable = "avx512f,avx512dq")]
#[inline]
fn subtree_bits(key: __m512i, word: __m512i, t: usize) -> __m512i {
    let above = SUBTREE_DEPTH as usize * t;
    let root = _mm512_srlv_epi64(word, _mm512_set1_epi64((32 - above) as i64));
    let x = _mm512_add_epi64(key, _mm512_mullo_epi64(root, splat(GAMMA)));
    let x = _mm512_xor_si512(x, _mm512_srli_epi64::<30>(x));
    let x = _mm512_mullo_epi64(x, splat(MIX64_MULTIPLIERS[0]));
    let x = _mm512_xor_si512(x, _mm512_srli_epi64::<27>(x));
    let x = _mm512_mullo_epi64(x, splat(MIX64_MULTIPLIERS[1]));
    _mm512_xor_si512(x, _mm512_srli_epi64::<31>(x))
}

/// A 64-bit constant in every lane.
#[target_feature(enable = "avx512f")]
#[inline]
fn splat(value: u64) -> __m512i {
    _mm512_set1_epi64(value as i64)
}

/// The per-layer constants of the path pick.
struct PathConstants {
    /// Byte `p`: where depth `5 - p`'s `q` starts in the (shifted) word.
    control: u64,
    /// Byte `p`: `2^(5 - p) - 1`, the mask of `q` and the depth's first node.
    nodes: u64,
    /// Shift of the word before the pick (the last layer's 2 digits are
    /// moved up to a 6-digit path's top), and of the mask after it.
    pad: u32,
    /// Where the layer's lowest digit is in the word (after the pad).
    low: u32,
}

impl PathConstants {
    fn of_layer(t: usize) -> Self {
        let above = SUBTREE_DEPTH * t as u32;
        let (low, pad) = match (32 - above).checked_sub(SUBTREE_DEPTH) {
            Some(low) => (low, 0),
            None => (0, above + SUBTREE_DEPTH - 32),
        };
        let bytes =
            |f: &dyn Fn(u32) -> u32| (0..6).fold(0u64, |acc, p| acc | u64::from(f(p)) << (8 * p));
        PathConstants {
            // q of depth i = 5 - p: the i digits above the path's
            // depth-i digit, i.e. the word shifted by low + 6 - i.
            control: bytes(&|p| low + 1 + p),
            nodes: bytes(&|p| (1 << (5 - p)) - 1),
            pad,
            low,
        }
    }

    /// The XOR mask of this layer's digits of `word`, from the subtree's bits.
    #[target_feature(enable = "avx512f,avx512bw,avx512vbmi,avx512bitalg")]
    #[inline]
    fn flips(&self, bits: __m512i, word: __m512i) -> __m512i {
        let pad = _mm512_set1_epi64(i64::from(self.pad));
        let source = _mm512_sllv_epi64(word, pad);
        let nodes = _mm512_set1_epi64(self.nodes as i64);
        let q = _mm512_multishift_epi64_epi8(_mm512_set1_epi64(self.control as i64), source);
        let index = _mm512_add_epi8(_mm512_and_si512(q, nodes), nodes);
        let picked = _mm512_bitshuffle_epi64_mask(bits, index);
        // Bytes 1, 2, 4, ..., 32 (the weights 2^p) where a node flips.
        let weights = _mm512_set1_epi64(0x0000_2010_0804_0201);
        let path = _mm512_sad_epu8(
            _mm512_maskz_mov_epi8(picked, weights),
            _mm512_setzero_si512(),
        );
        let placed = _mm512_sllv_epi64(path, _mm512_set1_epi64(i64::from(self.low)));
        _mm512_srlv_epi64(placed, pad)
    }
}
