//! The stratified pixel sampler, after pbrt-v4's `StratifiedSampler`: for
//! each pixel and dimension the `spp` samples of the pixel are spread over
//! `spp` strata, one sample per stratum, in a random order that differs per
//! pixel and dimension (so the dimensions are not correlated), with a
//! random jitter inside the stratum.
//!
//! * 1-D values use `spp` strata of width `1/spp`.
//! * 2-D values and the pixel offset use the `nx x ny` grid of
//!   [`grid_shape`]`(spp)` (`nx * ny = spp`, as square as the divisors allow;
//!   a prime `spp` gives `1 x spp` strips, a non-square count such as 8 a
//!   `2 x 4` grid). Cell `c` is column `c % nx`, row `c / nx`.
//! * Sample `i` of a pixel takes stratum `perm(i mod spp)`, with `perm` the
//!   keyed permutation [`permutation_element`] keyed by
//!   `hash(seed, pixel, i / spp, dimension)`; the jitter is drawn from a
//!   hash of the same key and `i`. Sample indices beyond `spp` therefore
//!   start a fresh, independently permuted round of strata.
//! * The pixel offset uses its own key (a dimension tag no `u32` dimension
//!   can take), so it does not consume dimensions.
//!
//! Every value is a pure function of (seed, pixel, sample index, dimension).
//! Stratum membership is exact in `f32` (at most `2^24` samples per pixel).
//!
//! Speed: the key of a dimension and its permutation depend on the pixel
//! and the round only, so for tags below `CACHED_TAGS` (and the pixel tag)
//! they are kept while those stay the same (the seed and pixel part of the
//! hash is absorbed once per pixel); a value then costs one bit mix for its
//! jitter and the permutation's rounds. The values are unchanged (a test
//! compares with the definition).

use alloc::vec::Vec;

use super::PixelSampler;
use crate::Error;
use crate::hash::{WordHasher, hash_words, mix64};
use crate::scramble::derive_seed;
use crate::stratified::{KeyedPermutation, grid_shape, stratum_f32};

/// Salt separating the stratified sampler from other uses of a seed.
const SALT: u64 = 0x5354_5241_5449_4659; // "STRATIFY"
/// Dimension tag of the pixel offset (above every `u32` dimension).
const PIXEL_TAG: u64 = 1 << 32;
/// Largest supported samples per pixel (strata must be distinct in `f32`).
const MAX_SPP: u32 = 1 << 24;
/// Dimension tags below this are cached (slot `1 + tag`; slot 0 is the
/// pixel tag).
const CACHED_TAGS: u64 = 1024;

/// The key and permutation of one tag for one (pixel, round).
#[derive(Debug, Clone)]
struct Entry {
    /// Whether the fields below are for `pixel` and `round`.
    valid: bool,
    pixel: [u32; 2],
    round: u32,
    key: u64,
    permutation: KeyedPermutation,
}

/// Keys and permutations reused between values (never changes a value).
#[derive(Debug, Clone, Default)]
struct Cache {
    /// The (pixel, round) `prefix` is for, and the hash state after the
    /// seed, the pixel and the round.
    prefix: Option<([u32; 2], u32, WordHasher)>,
    entries: Vec<Entry>,
}

/// Stratified, jittered samples with per-pixel, per-dimension shuffling.
#[derive(Debug, Clone)]
pub struct StratifiedSampler {
    spp: u32,
    seed: u64,
    grid: (u32, u32),
    pixel: [u32; 2],
    sample_index: u32,
    dimension: u32,
    cache: Cache,
}

impl StratifiedSampler {
    /// A sampler with `spp` samples per pixel, seeded by `seed`.
    ///
    /// # Errors
    /// [`Error::InvalidSampleCount`] if `spp == 0` or `spp > 2^24`.
    pub fn new(spp: u32, seed: u64) -> Result<Self, Error> {
        if spp == 0 || spp > MAX_SPP {
            return Err(Error::InvalidSampleCount {
                count: u64::from(spp),
                reason: "the stratified sampler takes 1 to 2^24 samples per pixel",
            });
        }
        Ok(StratifiedSampler {
            spp,
            seed: derive_seed(seed, SALT),
            grid: grid_shape(spp),
            pixel: [0, 0],
            sample_index: 0,
            dimension: 0,
            cache: Cache::default(),
        })
    }

    /// The `(nx, ny)` grid used by 2-D values and the pixel offset.
    pub fn grid(&self) -> (u32, u32) {
        self.grid
    }

    /// Key of the stratum permutation for dimension tag `tag`, and the
    /// position of the current sample in it.
    fn key(&self, tag: u64) -> (u64, u32) {
        let round = self.sample_index / self.spp;
        let key = hash_words(&[
            self.seed,
            u64::from(self.pixel[0]),
            u64::from(self.pixel[1]),
            u64::from(round),
            tag,
        ]);
        (key, self.sample_index % self.spp)
    }

    /// [`StratifiedSampler::key`] and the permutation it keys, through the
    /// cache.
    fn keyed(&mut self, tag: u64) -> (u64, KeyedPermutation, u32) {
        let (spp, pixel) = (self.spp, self.pixel);
        let (round, position) = (self.sample_index / spp, self.sample_index % spp);
        let slot = match tag {
            PIXEL_TAG => 0,
            t if t < CACHED_TAGS => t as usize + 1,
            _ => {
                let (key, position) = self.key(tag);
                return (key, KeyedPermutation::new(spp, key), position);
            }
        };
        let cache = &mut self.cache;
        if let Some(e) = cache.entries.get(slot)
            && e.valid
            && e.pixel == pixel
            && e.round == round
        {
            return (e.key, e.permutation, position);
        }
        let prefix = match cache.prefix {
            Some((p, r, h)) if p == pixel && r == round => h,
            _ => {
                let [x, y] = pixel.map(u64::from);
                let h = WordHasher::new(5)
                    .push(self.seed)
                    .push(x)
                    .push(y)
                    .push(u64::from(round));
                cache.prefix = Some((pixel, round, h));
                h
            }
        };
        let key = prefix.push(tag).finish();
        let permutation = KeyedPermutation::new(spp, key);
        let entry = Entry {
            valid: true,
            pixel,
            round,
            key,
            permutation,
        };
        while cache.entries.len() <= slot {
            // Placeholders, invalid until their own tag is asked for.
            cache.entries.push(Entry {
                valid: false,
                ..entry.clone()
            });
        }
        cache.entries[slot] = entry;
        (key, permutation, position)
    }

    /// The stratified 1-D value of dimension tag `tag`.
    fn value_1d(&mut self, tag: u64) -> f32 {
        let (key, permutation, position) = self.keyed(tag);
        let stratum = permutation.element(position);
        let jitter = mix64(key ^ u64::from(position));
        stratum_f32(stratum, self.spp, unit_f32(jitter >> 40))
    }

    /// The stratified 2-D value of dimension tag `tag`.
    fn value_2d(&mut self, tag: u64) -> [f32; 2] {
        let (key, permutation, position) = self.keyed(tag);
        let (nx, ny) = self.grid;
        let cell = permutation.element(position);
        let jitter = mix64(key ^ u64::from(position));
        [
            stratum_f32(cell % nx, nx, unit_f32(jitter >> 40)),
            stratum_f32(cell / nx, ny, unit_f32(jitter & 0xff_ffff)),
        ]
    }
}

/// A 24-bit integer as an `f32` in `[0, 1)`.
fn unit_f32(bits24: u64) -> f32 {
    bits24 as f32 * (1.0 / 16_777_216.0)
}

impl PixelSampler for StratifiedSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dimension: u32) {
        self.pixel = pixel;
        self.sample_index = sample_index;
        self.dimension = dimension;
    }

    fn get_1d(&mut self) -> f32 {
        let v = self.value_1d(u64::from(self.dimension));
        self.dimension = self.dimension.wrapping_add(1);
        v
    }

    fn get_2d(&mut self) -> [f32; 2] {
        let v = self.value_2d(u64::from(self.dimension));
        self.dimension = self.dimension.wrapping_add(2);
        v
    }

    fn get_pixel_2d(&mut self) -> [f32; 2] {
        self.value_2d(PIXEL_TAG)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stratified::permutation_element;
    use alloc::vec::Vec;

    #[test]
    fn the_cached_path_equals_the_definition() {
        let mut state = 5u64;
        for spp in [1u32, 6, 16] {
            let mut s = StratifiedSampler::new(spp, 8).unwrap();
            for visit in 0..80u32 {
                state = mix64(state.wrapping_add(u64::from(visit)));
                let pixel = [(state % 3) as u32, (state >> 8) as u32 % 2];
                let start = if visit % 3 == 0 { 1020 } else { 0 };
                for k in 0..3 {
                    s.start_pixel_sample(pixel, (state >> 20) as u32 % 40 + k, start);
                    // The definition, from the uncached key.
                    let jitter = |s: &StratifiedSampler, tag: u64| {
                        let (key, position) = s.key(tag);
                        let p = permutation_element(position, spp, key);
                        (p, mix64(key ^ u64::from(position)))
                    };
                    let (nx, ny) = s.grid;
                    let (cell, j) = jitter(&s, PIXEL_TAG);
                    let want = [
                        stratum_f32(cell % nx, nx, unit_f32(j >> 40)),
                        stratum_f32(cell / nx, ny, unit_f32(j & 0xff_ffff)),
                    ];
                    assert_eq!(s.get_pixel_2d(), want);
                    for _ in 0..4 {
                        let (stratum, j) = jitter(&s, u64::from(s.dimension));
                        let want = stratum_f32(stratum, spp, unit_f32(j >> 40));
                        assert_eq!(s.get_1d(), want);
                        let (cell, j) = jitter(&s, u64::from(s.dimension));
                        let want = [
                            stratum_f32(cell % nx, nx, unit_f32(j >> 40)),
                            stratum_f32(cell / nx, ny, unit_f32(j & 0xff_ffff)),
                        ];
                        assert_eq!(s.get_2d(), want);
                    }
                }
            }
        }
    }

    #[test]
    fn bad_sample_counts_are_errors() {
        assert!(StratifiedSampler::new(0, 1).is_err());
        assert!(StratifiedSampler::new(MAX_SPP + 1, 1).is_err());
        assert_eq!(StratifiedSampler::new(12, 1).unwrap().grid(), (3, 4));
        assert_eq!(StratifiedSampler::new(7, 1).unwrap().grid(), (1, 7));
    }

    /// Over the `spp` samples (of round `round`) of each pixel, every 1-D
    /// stratum, every 2-D cell and every pixel-offset cell is hit once.
    fn assert_stratified(spp: u32, round: u32) {
        let mut s = StratifiedSampler::new(spp, 17).unwrap();
        let (nx, ny) = s.grid();
        for pixel in [[0u32, 0], [1, 0], [3, 7], [100, 200]] {
            let mut seen = [
                alloc::vec![0u32; spp as usize], // pixel offset cells
                alloc::vec![0u32; spp as usize], // dimension 0 (1-D)
                alloc::vec![0u32; spp as usize], // dimensions 1-2 (2-D)
                alloc::vec![0u32; spp as usize], // dimension 3 (1-D)
            ];
            for i in round * spp..(round + 1) * spp {
                s.start_pixel_sample(pixel, i, 0);
                let cell = |v: [f32; 2]| -> usize {
                    assert!(v.iter().all(|x| (0.0..1.0).contains(x)));
                    let cx = (v[0] * nx as f32) as u32;
                    let cy = (v[1] * ny as f32) as u32;
                    (cy * nx + cx) as usize
                };
                let stratum = |v: f32| -> usize {
                    assert!((0.0..1.0).contains(&v));
                    (v * spp as f32) as usize
                };
                seen[0][cell(s.get_pixel_2d())] += 1;
                seen[1][stratum(s.get_1d())] += 1;
                seen[2][cell(s.get_2d())] += 1;
                seen[3][stratum(s.get_1d())] += 1;
            }
            for counts in &seen {
                assert!(
                    counts.iter().all(|&c| c == 1),
                    "spp {spp}, pixel {pixel:?}: {counts:?}"
                );
            }
        }
    }

    #[test]
    fn every_stratum_is_hit_once_per_pixel() {
        for spp in [1, 2, 3, 7, 8, 12, 16, 31, 64, 100] {
            assert_stratified(spp, 0);
        }
        assert_stratified(12, 1);
    }

    #[test]
    fn dimensions_and_pixels_are_decorrelated() {
        let spp = 16;
        let mut s = StratifiedSampler::new(spp, 5).unwrap();
        let strata = |s: &mut StratifiedSampler, pixel, dim| -> Vec<u32> {
            (0..spp)
                .map(|i| {
                    s.start_pixel_sample(pixel, i, dim);
                    (s.get_1d() * spp as f32) as u32
                })
                .collect()
        };
        let a = strata(&mut s, [0, 0], 0);
        assert_ne!(a, strata(&mut s, [0, 0], 1));
        assert_ne!(a, strata(&mut s, [1, 0], 0));
        assert_ne!(a, (0..spp).collect::<Vec<_>>());
    }

    #[test]
    fn values_do_not_depend_on_call_order() {
        let mut s = StratifiedSampler::new(9, 2).unwrap();
        let mut record = |p: [u32; 2], i: u32| -> Vec<f32> {
            s.start_pixel_sample(p, i, 0);
            let mut v = s.get_2d().to_vec();
            v.push(s.get_1d());
            v.extend(s.get_pixel_2d());
            v.push(s.get_1d());
            v
        };
        let order: Vec<([u32; 2], u32)> = (0..3)
            .flat_map(|x| (0..9).map(move |i| ([x, 2 * x], i)))
            .collect();
        let forward: Vec<Vec<f32>> = order.iter().map(|&(p, i)| record(p, i)).collect();
        let mut backward: Vec<Vec<f32>> = order.iter().rev().map(|&(p, i)| record(p, i)).collect();
        backward.reverse();
        assert_eq!(forward, backward);
        // Starting at dimension 2 gives what the third 1-D call would give.
        s.start_pixel_sample([1, 1], 4, 0);
        let skipped = [s.get_1d(), s.get_1d(), s.get_1d()];
        s.start_pixel_sample([1, 1], 4, 2);
        assert_eq!(s.get_1d(), skipped[2]);
    }

    #[test]
    fn pinned_values() {
        let mut s = StratifiedSampler::new(16, 42).unwrap();
        s.start_pixel_sample([1, 2], 3, 0);
        let mut got = s.get_pixel_2d().to_vec();
        got.push(s.get_1d());
        got.extend(s.get_2d());
        let bits: Vec<u32> = got.iter().map(|v| v.to_bits()).collect();
        assert_eq!(bits, PINNED);
    }

    const PINNED: [u32; 5] = [1060617577, 1057047576, 1056300979, 1060761592, 1051398738];
}
