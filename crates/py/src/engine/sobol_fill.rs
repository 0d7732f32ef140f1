//! Sobol points written straight into the output array, point-major as
//! numpy's C order wants, in parallel chunks of whole points.
//!
//! A chunk starts from its first point's digit words (one matrix product per
//! dimension) and then, in Gray-code order, moves to the next point by
//! XORing one column into every dimension (`trailing_zeros` of the index);
//! in natural order every value is a matrix product. Each word is scrambled
//! by the per-dimension state of a [`Scrambler`], built once per request,
//! and converted as it is stored. The Owen tree scramble works on blocks of
//! points at once (its vector kernel takes eight dimensions per
//! instruction), through a small buffer of words. Every value depends only
//! on its index and dimension: chunks can run on any thread in any order
//! and give the same bits.

use lowdisc::scramble::{LmsKey, OwenTreePoints, PreparedKey, RandomizeStrategy, dimension_seed};
use lowdisc::sobol::{self, gray_code};
use rayon::prelude::*;

use super::{CHUNK_VALUES, EngineError, Result};

/// Words per block of the Owen tree scramble's buffer (16 KiB, in L1).
const TREE_BLOCK_VALUES: usize = 4096;

/// The per-dimension state of one request's scramble.
pub enum Scrambler {
    /// No scramble.
    None,
    /// A catalog strategy that needs only each dimension's seed (`xor`,
    /// `fast-owen`): `strategy.apply_dimension_seed(word, seeds[j])`.
    Seeded(RandomizeStrategy, Vec<u32>),
    /// The catalog's exact Owen scramble with one hash per digit (`owen`:
    /// the renderer's `sobol-owen` values), prepared per dimension.
    PerDigit(Vec<PreparedKey>),
    /// Owen scrambling at a few hashes per value
    /// ([`lowdisc::scramble::OwenTreeKey`], `owen-tree`): the same law as
    /// `owen`, other values; whole points at once.
    Tree(OwenTreePoints),
    /// Matoušek's linear matrix scramble plus digital shift (`lms`, the
    /// catalog's [`RandomizeStrategy::Lms`] values), one key per dimension.
    Lms(Vec<LmsKey>),
}

/// The names [`Scrambler::new`] accepts.
pub const SCRAMBLES: [&str; 6] = ["none", "xor", "owen", "owen-tree", "fast-owen", "lms"];

impl Scrambler {
    /// Whether `name` is one of [`SCRAMBLES`].
    pub fn check_name(name: &str) -> Result<()> {
        if SCRAMBLES.contains(&name) {
            return Ok(());
        }
        Err(EngineError::value(format!(
            "Sobol scramble must be 'none', 'xor', 'owen', 'owen-tree', 'fast-owen' or 'lms', \
             got {name:?}"
        )))
    }

    /// The scramble called `name` of dimensions `0..d` under `seed`.
    pub fn new(name: &str, seed: u64, d: u32) -> Result<Scrambler> {
        Scrambler::check_name(name)?;
        let seeds = || (0..d).map(|j| dimension_seed(seed, j)).collect();
        Ok(match name {
            "xor" => Scrambler::Seeded(RandomizeStrategy::Xor, seeds()),
            "fast-owen" => Scrambler::Seeded(RandomizeStrategy::FastOwen, seeds()),
            "lms" => Scrambler::Lms(
                (0..d)
                    .map(|j| LmsKey::new(dimension_seed(seed, j)))
                    .collect(),
            ),
            "owen" => Scrambler::PerDigit(
                (0..d)
                    .filter_map(|j| RandomizeStrategy::Owen.prepare(dimension_seed(seed, j)))
                    .collect(),
            ),
            "owen-tree" if OwenTreePoints::vector_kernel_available() => {
                Scrambler::Tree(OwenTreePoints::new(seed, d))
            }
            // The portable keys' tables (8 KiB each), built on all cores.
            "owen-tree" => Scrambler::Tree(OwenTreePoints::from_keys(
                (0..d)
                    .into_par_iter()
                    .map(|j| OwenTreePoints::portable_key(seed, j, d))
                    .collect(),
            )),
            // "none", the one name left that check_name accepts.
            _ => Scrambler::None,
        })
    }

    /// Scrambles one point's words into `out`, keeping `digits` leading
    /// digits and converting each word with `convert` (all but the tree
    /// scramble, which [`fill`] runs on blocks of points).
    #[inline]
    fn row<T>(&self, words: &[u32], out: &mut [T], digits: u32, convert: &impl Fn(u32) -> T) {
        let mask = u32::MAX << (32 - digits);
        let pairs = out.iter_mut().zip(words);
        match self {
            Scrambler::None => pairs.for_each(|(o, &w)| *o = convert(w & mask)),
            Scrambler::Seeded(r, seeds) => pairs
                .zip(seeds)
                .for_each(|((o, &w), &s)| *o = convert(r.apply_dimension_seed(w, s) & mask)),
            Scrambler::PerDigit(keys) => pairs
                .zip(keys)
                .for_each(|((o, &w), k)| *o = convert(k.scramble(w) & mask)),
            Scrambler::Lms(keys) => pairs
                .zip(keys)
                .for_each(|((o, &w), k)| *o = convert(k.scramble(w) & mask)),
            Scrambler::Tree(keys) => {
                let mut scrambled = words.to_vec();
                keys.scramble_points(&mut scrambled, digits);
                pairs
                    .zip(&scrambled)
                    .for_each(|((o, _), &w)| *o = convert(w));
            }
        }
    }
}

/// The request's shape: points `start .. start + n` of dimensions `0..d`.
#[derive(Debug, Clone, Copy)]
pub struct SobolRange {
    /// Index of the first point (`start + n <= 2^32`, checked by the caller).
    pub start: u64,
    /// Dimensions per point (at most the table's, checked by the caller).
    pub d: usize,
    /// Natural order instead of Gray code.
    pub natural_order: bool,
    /// Leading digits kept, `1..=32`.
    pub digits: u32,
}

/// Fills `out` (`n * d` values, point-major) with the scrambled points of
/// `range`, each word converted by `convert`.
pub fn fill<T: Send>(
    out: &mut [T],
    range: SobolRange,
    scrambler: &Scrambler,
    convert: impl Fn(u32) -> T + Sync,
) {
    let d = range.d;
    // columns[c * d + j]: column c of dimension j.
    let columns: Vec<u32> = (0..32)
        .flat_map(|c| (0..d as u32).map(move |j| sobol::matrix(j)[c]))
        .collect();
    let per = (CHUNK_VALUES / d).max(1);
    out.par_chunks_mut(per * d)
        .enumerate()
        .for_each(|(c, block)| {
            let mut walk = Walk::new(range, &columns, range.start + (c * per) as u64);
            let Scrambler::Tree(keys) = scrambler else {
                for row in block.chunks_exact_mut(d) {
                    scrambler.row(&walk.words, row, range.digits, &convert);
                    walk.advance();
                }
                return;
            };
            let mut buffer = vec![0u32; (TREE_BLOCK_VALUES / d).max(1) * d];
            for rows in block.chunks_mut(buffer.len()) {
                let words = &mut buffer[..rows.len()];
                for point in words.chunks_exact_mut(d) {
                    point.copy_from_slice(&walk.words);
                    walk.advance();
                }
                keys.scramble_points(words, range.digits);
                for (o, &w) in rows.iter_mut().zip(words.iter()) {
                    *o = convert(w);
                }
            }
        });
}

/// The digit words of consecutive points, from a chunk's first.
struct Walk<'a> {
    /// The words of point `index`.
    words: Vec<u32>,
    /// The current point's index.
    index: u64,
    /// Natural order (else Gray code).
    natural_order: bool,
    /// The generator matrices' columns, `columns[c * d + j]`.
    columns: &'a [u32],
}

impl<'a> Walk<'a> {
    fn new(range: SobolRange, columns: &'a [u32], first: u64) -> Self {
        let mut walk = Walk {
            words: vec![0; range.d],
            index: first,
            natural_order: range.natural_order,
            columns,
        };
        walk.compute();
        walk
    }

    /// The words of point `index` from scratch (a matrix product each).
    fn compute(&mut self) {
        let k = self.index as u32;
        let k = if self.natural_order { k } else { gray_code(k) };
        for (j, w) in self.words.iter_mut().enumerate() {
            *w = sobol::sample(k, j as u32);
        }
    }

    /// On to the next point (past the last one the words are meaningless).
    #[inline]
    fn advance(&mut self) {
        self.index += 1;
        if self.natural_order {
            self.compute();
            return;
        }
        // Gray code: point k + 1 (< 2^32 while points remain) XORs column
        // trailing_zeros(k + 1) into every dimension.
        let d = self.words.len();
        let c = self.index.trailing_zeros().min(31) as usize;
        for (w, &col) in self.words.iter_mut().zip(&self.columns[c * d..(c + 1) * d]) {
            *w ^= col;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use lowdisc::scramble::OwenTreeKey;
    use lowdisc::sobol::GrayCodeBatch;

    fn words(scramble: &str, n: usize, d: usize, start: u64, natural: bool) -> Vec<u32> {
        let mut out = vec![0u32; n * d];
        let range = SobolRange {
            start,
            d,
            natural_order: natural,
            digits: 32,
        };
        fill(
            &mut out,
            range,
            &Scrambler::new(scramble, 3, d as u32).unwrap(),
            |w| w,
        );
        out
    }

    #[test]
    fn gray_code_points_equal_the_batch_generator_across_chunks() {
        // 2 dimensions: chunks of 32768 points, so 70,000 points span three.
        for (d, n, start) in [(2usize, 70_000usize, 5u64), (64, 3000, 1 << 31), (1, 10, 0)] {
            let mut batch = GrayCodeBatch::new(0, d as u32).unwrap();
            batch.seek(start as u32);
            let mut want = vec![0u32; n * d];
            batch.fill(&mut want);
            assert_eq!(words("none", n, d, start, false), want, "d {d}");
        }
    }

    #[test]
    fn the_tree_scramble_is_the_key_of_each_dimension() {
        let (n, d) = (5000, 70);
        let got = words("owen-tree", n, d, 100, true);
        let keys: Vec<_> = (0..d as u32).map(|j| OwenTreeKey::new(3, j)).collect();
        for (k, point) in (100..).zip(got.chunks_exact(d)) {
            for ((j, &w), key) in (0..).zip(point).zip(&keys) {
                assert_eq!(w, key.scramble(sobol::sample(k, j)));
            }
        }
    }

    #[test]
    fn gray_code_tree_scrambled_points_keep_the_asked_digits() {
        // 13 dimensions (not a multiple of the vector width), chunks of 5041
        // points, blocks of 315: 12,000 points cross both kinds of boundary.
        let (n, d, start) = (12_000, 13, 77);
        let plain = words("none", n, d, start, false);
        let keys: Vec<_> = (0..d as u32).map(|j| OwenTreeKey::new(3, j)).collect();
        for digits in [30, 17] {
            let mut out = vec![0u32; n * d];
            let range = SobolRange {
                start,
                d,
                natural_order: false,
                digits,
            };
            fill(
                &mut out,
                range,
                &Scrambler::new("owen-tree", 3, d as u32).unwrap(),
                |w| w,
            );
            for (i, (&got, &w)) in out.iter().zip(&plain).enumerate() {
                assert_eq!(got, keys[i % d].scramble_digits(w, digits), "value {i}");
            }
        }
    }

    #[test]
    fn unknown_scrambles_are_refused_with_the_choices() {
        let err = Scrambler::new("owen-per-digit", 0, 2)
            .err()
            .unwrap()
            .to_string();
        assert!(err.contains("'lms', got \"owen-per-digit\""), "{err}");
    }
}
