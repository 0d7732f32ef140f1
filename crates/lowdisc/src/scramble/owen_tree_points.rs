//! Owen tree scrambling of whole points: the [`OwenTreeKey`]s of dimensions
//! `0..d` under one seed, applied to many points at once.
//!
//! [`OwenTreePoints::scramble_points`] gives exactly the values of
//! [`OwenTreeKey::scramble_digits`] with `OwenTreeKey::new(seed, j)` for
//! dimension `j` (the tests compare them over many words, seeds and digit
//! counts). On x86-64 CPUs with AVX-512 (F, DQ, BW, VL, VBMI and BITALG,
//! detected at run time; e.g. AMD Zen 4 and later, Intel Ice Lake and later)
//! it scrambles eight dimensions per vector instruction
//! (`owen_tree_avx512.rs`): each hashed layer is one vectorised `mix64`
//! and its 6-node path is picked from the subtree's 64 bits by one bit
//! shuffle, with no table. Elsewhere it runs each dimension's
//! [`OwenTreeKey`] (its 4096-entry table and a hash per further layer).

use alloc::vec::Vec;

use super::owen_tree::{LANES, OwenTreeKey, layers_of};

/// Dimensions up to this get portable keys with the 4096-entry table (8 KiB
/// each); beyond, the 64-entry one (the values are the same).
const LARGE_TABLE_DIMENSIONS: u32 = 1024;

/// The Owen tree scramble of dimensions `0..d` under one seed.
#[derive(Debug, Clone)]
pub struct OwenTreePoints {
    /// Dimensions per point.
    d: usize,
    /// How the points are scrambled.
    kernel: Kernel,
}

/// The code that scrambles, chosen once when the keys are built.
#[derive(Debug, Clone)]
enum Kernel {
    /// The AVX-512 kernel, with `by_layer[t][j]` the `K_t` of dimension `j`
    /// (layer 0: the root subtree's bits `mix64(K_0)`), zero-padded to a
    /// multiple of [`LANES`] dimensions.
    #[cfg(all(feature = "std", target_arch = "x86_64", lowdisc_avx512))]
    Avx512 {
        /// The keys by layer.
        by_layer: [Vec<u64>; super::owen_tree::LAYERS_TOTAL],
    },
    /// Each dimension's key.
    Portable(Vec<OwenTreeKey>),
}

impl OwenTreePoints {
    /// The scramble of dimensions `0..d` under `seed`, vectorised if the CPU
    /// allows it.
    pub fn new(seed: u64, d: u32) -> Self {
        #[cfg(all(feature = "std", target_arch = "x86_64", lowdisc_avx512))]
        if super::owen_tree_avx512::available() {
            return Self::vectorised(seed, d);
        }
        Self::portable(seed, d)
    }

    /// Whether [`OwenTreePoints::new`] gives the vector kernel on this CPU
    /// (if not, a caller may build the portable keys itself, e.g. in
    /// parallel, with [`OwenTreePoints::portable_key`]).
    pub fn vector_kernel_available() -> bool {
        #[cfg(all(feature = "std", target_arch = "x86_64", lowdisc_avx512))]
        if super::owen_tree_avx512::available() {
            return true;
        }
        false
    }

    /// The same scramble without vector instructions, on any CPU.
    pub fn portable(seed: u64, d: u32) -> Self {
        Self::from_keys((0..d).map(|j| Self::portable_key(seed, j, d)).collect())
    }

    /// The portable kernel's key of dimension `dim` of `d` under `seed`:
    /// `OwenTreeKey::new(seed, dim)`'s values, with the 4096-entry table for
    /// up to 1024 dimensions and the 64-entry one beyond.
    pub fn portable_key(seed: u64, dim: u32, d: u32) -> OwenTreeKey {
        let table = if d <= LARGE_TABLE_DIMENSIONS { 12 } else { 6 };
        OwenTreeKey::with_table(seed, dim, table)
    }

    /// The portable kernel with the keys of dimensions `0..keys.len()`.
    pub fn from_keys(keys: Vec<OwenTreeKey>) -> Self {
        OwenTreePoints {
            d: keys.len(),
            kernel: Kernel::Portable(keys),
        }
    }

    /// The AVX-512 keys (the caller checked the CPU).
    #[cfg(all(feature = "std", target_arch = "x86_64", lowdisc_avx512))]
    fn vectorised(seed: u64, d: u32) -> Self {
        let padded = (d as usize).div_ceil(LANES) * LANES;
        let mut by_layer: [Vec<u64>; super::owen_tree::LAYERS_TOTAL] =
            core::array::from_fn(|_| alloc::vec![0; padded]);
        for j in 0..d {
            let keys = super::owen_tree::layer_keys(seed, j);
            for (t, k) in keys.into_iter().enumerate() {
                // Layer 0 has the one root 0: its subtree bits, ready.
                by_layer[t][j as usize] = if t == 0 { crate::hash::mix64(k) } else { k };
            }
        }
        OwenTreePoints {
            d: d as usize,
            kernel: Kernel::Avx512 { by_layer },
        }
    }

    /// Dimensions per point.
    pub fn dimensions(&self) -> usize {
        self.d
    }

    /// Whether the vector kernel runs (false: the portable one).
    pub fn is_vectorised(&self) -> bool {
        !matches!(self.kernel, Kernel::Portable(_))
    }

    /// Scrambles, in place, the points of `words` (point-major, `d` digit
    /// words each; a trailing partial point is left alone), keeping the
    /// first `digits` digits (`1..=32`) of each: word `i * d + j` becomes
    /// `OwenTreeKey::new(seed, j).scramble_digits(word, digits)`.
    pub fn scramble_points(&self, words: &mut [u32], digits: u32) {
        if self.d == 0 {
            return;
        }
        let digits = digits.clamp(1, 32);
        match layers_of(digits) {
            0..=1 => self.run::<1>(words, digits),
            2 => self.run::<2>(words, digits),
            3 => self.run::<3>(words, digits),
            4 => self.run::<4>(words, digits),
            5 => self.run::<5>(words, digits),
            _ => self.run::<6>(words, digits),
        }
    }

    /// [`OwenTreePoints::scramble_points`] with `LAYERS = layers_of(digits)`.
    #[inline(always)]
    fn run<const LAYERS: usize>(&self, words: &mut [u32], digits: u32) {
        match &self.kernel {
            #[cfg(all(feature = "std", target_arch = "x86_64", lowdisc_avx512))]
            Kernel::Avx512 { by_layer } => {
                super::owen_tree_avx512::scramble_points::<LAYERS>(by_layer, self.d, words, digits)
            }
            Kernel::Portable(keys) => {
                for point in words.chunks_exact_mut(self.d) {
                    for (w, key) in point.iter_mut().zip(keys) {
                        *w = key.scramble_layers::<LAYERS>(*w, digits);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
#[path = "owen_tree_points_tests.rs"]
mod tests;
