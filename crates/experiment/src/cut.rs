//! One large render cut into units and put back together, exactly.
//!
//! A [`Cut`] is `bands` bands of whole rows of tiles times `ranges` sample
//! ranges; a [`Piece`] is one band's pixels over one range. A piece keeps
//! the exact `f64` sums of its pixels (a [`RenderPart`] of `lowdisc-split`),
//! and a [`Joiner`] merges the pieces with [`lowdisc_split::merge`] (each
//! band's ranges in ascending order, then the bands) and turns the merged
//! sums into the image ([`image_of_sums`]). The one-machine run renders
//! the same pieces and joins them with the same code as the merge of a
//! planned run, so both compute the same floating-point operations and
//! give the same bits.
//!
//! Bands keep the whole film's tile grid and sampler streams, so a cut into
//! bands alone gives the whole render's image bit for bit. Sample ranges
//! add per-range sums: equal to the whole render's sample-by-sample sums
//! only up to `f64` rounding, which is why every run of one experiment
//! (planned or not) cuts its references the same way ([`cut`]), and why the
//! reference cache's key names the number of ranges.

use anyhow::{Context, Result, bail};
use lowdisc_image::RgbImage;
use lowdisc_render::film::PixelBounds;
use lowdisc_render::render::{SampleRange, image_of_sums};
use lowdisc_render::view::View;
use lowdisc_split::{NamedPart, RenderPart, merge};

/// The rows of a render's tiles ([`lowdisc_tiles::TILE_SIZE`]): a band is
/// whole rows of tiles.
pub const BAND_ROWS: u32 = lowdisc_tiles::TILE_SIZE;

/// The camera samples of one render at `resolution` with `spp` samples.
pub fn samples(resolution: [u32; 2], spp: u32) -> u64 {
    u64::from(resolution[0]) * u64::from(resolution[1]) * u64::from(spp)
}

/// How a render is cut: `bands` x `ranges` pieces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Cut {
    /// Bands of whole rows of tiles, from the top ([`band_rows`]).
    pub bands: u32,
    /// Sample ranges of every band ([`sample_range`]).
    pub ranges: u32,
}

impl Cut {
    /// Not cut: one piece.
    pub const WHOLE: Cut = Cut {
        bands: 1,
        ranges: 1,
    };

    /// Every piece, band by band, each band's ranges in ascending order.
    pub fn pieces(self) -> impl Iterator<Item = Piece> {
        (0..self.bands).flat_map(move |band| {
            (0..self.ranges).map(move |range| Piece {
                band,
                range,
                cut: self,
            })
        })
    }
}

/// One piece of a [`Cut`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Piece {
    /// Its band, `0..cut.bands`.
    pub band: u32,
    /// Its sample range, `0..cut.ranges`.
    pub range: u32,
    /// The cut it belongs to.
    pub cut: Cut,
}

impl Piece {
    /// The whole render.
    pub const WHOLE: Piece = Piece {
        band: 0,
        range: 0,
        cut: Cut::WHOLE,
    };

    /// ` band 2 of 5 range 1 of 8` (each part only when cut so), an empty
    /// text for the whole render.
    pub fn describe(&self) -> String {
        let Cut { bands, ranges } = self.cut;
        let mut text = String::new();
        if bands > 1 {
            text += &format!(" band {} of {bands}", self.band + 1);
        }
        if ranges > 1 {
            text += &format!(" range {} of {ranges}", self.range + 1);
        }
        text
    }

    /// Its camera samples in a render of `[w, h]` pixels at `spp`.
    pub fn samples(&self, [w, h]: [u32; 2], spp: u32) -> u64 {
        let [y0, y1] = band_rows(h, self.band, self.cut.bands);
        let r = sample_range(spp, self.range, self.cut.ranges);
        samples([w, y1 - y0], r.len())
    }

    /// Its pixels in a film of pixel bounds `bounds`.
    pub fn window(&self, bounds: PixelBounds) -> PixelBounds {
        let [y0, y1] = band_rows(bounds.height() as u32, self.band, self.cut.bands);
        PixelBounds::new(
            [bounds.min[0], bounds.min[1] + y0 as i32],
            [bounds.max[0], bounds.min[1] + y1 as i32],
        )
    }
}

/// The cut of a render of `resolution` at `spp` into units of at most about
/// `budget` camera samples: bands of as many whole rows of tiles as fit the
/// budget; when one row of tiles alone holds more, one band per row of
/// tiles, and (if `ranges_allowed`) each band in the fewest equal sample
/// ranges that fit.
pub fn cut(resolution: [u32; 2], spp: u32, budget: u64, ranges_allowed: bool) -> Cut {
    let [w, h] = resolution;
    let tile_rows = h.div_ceil(BAND_ROWS).max(1);
    let row = samples([w, BAND_ROWS.min(h)], spp).max(1);
    let budget = budget.max(1);
    if row <= budget {
        let rows_per_band = (budget / row).min(u64::from(tile_rows)) as u32;
        return Cut {
            bands: tile_rows.div_ceil(rows_per_band),
            ranges: 1,
        };
    }
    let ranges = if ranges_allowed {
        row.div_ceil(budget).min(u64::from(spp.max(1))) as u32
    } else {
        1
    };
    Cut {
        bands: tile_rows,
        ranges,
    }
}

/// The rows `[y0, y1)` of band `band` of `bands` of an image `height` rows
/// high (counted from the top of the film's pixel bounds): consecutive
/// whole rows of tiles, as equal in number as they can be.
pub fn band_rows(height: u32, band: u32, bands: u32) -> [u32; 2] {
    let tile_rows = u64::from(height.div_ceil(BAND_ROWS));
    let bands = u64::from(bands.max(1));
    let edge = |p: u64| ((p * tile_rows / bands) as u32 * BAND_ROWS).min(height);
    [edge(u64::from(band)), edge(u64::from(band) + 1)]
}

/// The sample indices of range `range` of `ranges` of `0..spp`:
/// consecutive, as equal in length as they can be.
pub fn sample_range(spp: u32, range: u32, ranges: u32) -> SampleRange {
    let ranges = u64::from(ranges.max(1));
    let edge = |r: u32| (u64::from(r) * u64::from(spp) / ranges) as u32;
    SampleRange::new(edge(range), edge(range + 1))
}

/// The pieces of one cut render, joined as they come (in [`Cut::pieces`]
/// order): each band's ranges are merged when the band is complete, which
/// keeps one band's ranges in memory, not the whole image's.
pub struct Joiner {
    band: Vec<NamedPart>,
    bands: Vec<NamedPart>,
}

impl Joiner {
    /// An empty joiner.
    pub fn new() -> Joiner {
        Joiner {
            band: Vec::new(),
            bands: Vec::new(),
        }
    }

    /// Adds `part`, piece `piece` of the render, named `name` in errors.
    pub fn push(&mut self, piece: Piece, name: String, part: RenderPart) -> Result<()> {
        self.band.push(NamedPart { name, part });
        if piece.range + 1 == piece.cut.ranges {
            let merged = merge(&self.band)?;
            let name = format!("band {} of {}", piece.band + 1, piece.cut.bands);
            self.band.clear();
            self.bands.push(NamedPart { name, part: merged });
        }
        Ok(())
    }

    /// The image of the whole render, the film of `view` (spectral or
    /// not); an error unless the pieces make every pixel of the film with
    /// every sample.
    pub fn finish(self, view: &View, spectral: bool) -> Result<RgbImage> {
        if !self.band.is_empty() {
            bail!("the last band of the render lacks sample ranges");
        }
        let whole = merge(&self.bands)?;
        if !whole.is_complete() {
            let i = &whole.info;
            bail!(
                "the pieces cover pixels {}..{} x {}..{} and samples {} only, not the whole render",
                i.window.min[0],
                i.window.max[0],
                i.window.min[1],
                i.window.max[1],
                i.samples
            );
        }
        image_of_sums(view, whole.info.window, spectral, &whole.sums)
            .context("cannot make the image of the merged pieces")
    }
}

impl Default for Joiner {
    fn default() -> Self {
        Joiner::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_render_has_pixels_times_spp_samples() {
        assert_eq!(samples([4, 3], 2), 24);
    }

    #[test]
    fn bands_cover_every_row_once_in_whole_tile_rows() {
        for height in 1..200u32 {
            let tile_rows = height.div_ceil(BAND_ROWS);
            for bands in 1..=tile_rows {
                let mut next = 0;
                for band in 0..bands {
                    let [y0, y1] = band_rows(height, band, bands);
                    assert_eq!(y0, next, "height {height}, {bands} bands");
                    assert!(y1 > y0 && y0 % BAND_ROWS == 0, "{height} {bands} {band}");
                    next = y1;
                }
                assert_eq!(next, height);
            }
        }
    }

    #[test]
    fn ranges_cover_every_sample_once() {
        for spp in 1..70u32 {
            for ranges in 1..=spp {
                let mut next = 0;
                for range in 0..ranges {
                    let r = sample_range(spp, range, ranges);
                    assert_eq!(r.start, next, "{spp} spp, {ranges} ranges");
                    assert!(!r.is_empty() && r.len() <= spp.div_ceil(ranges));
                    next = r.end;
                }
                assert_eq!(next, spp);
            }
        }
    }

    #[test]
    fn no_piece_exceeds_the_budget_unless_one_sample_row_does() {
        for (res, spp) in [([256, 144], 1024), ([128, 72], 8192), ([1280, 720], 4096)] {
            for budget in [1 << 10, 590_000, 1 << 23, 14_745_600, 1 << 40] {
                for ranges_allowed in [false, true] {
                    let c = cut(res, spp, budget, ranges_allowed);
                    let total: u64 = c.pieces().map(|p| p.samples(res, spp)).sum();
                    assert_eq!(total, samples(res, spp));
                    let largest = c.pieces().map(|p| p.samples(res, spp)).max().unwrap();
                    // Ranges round up to whole samples per pixel of a row
                    // of tiles; without ranges, a row of tiles is the least.
                    let row = |spp| samples([res[0], BAND_ROWS], spp);
                    let slack = if ranges_allowed { row(1) } else { row(spp) };
                    assert!(
                        largest <= budget + slack,
                        "{res:?} {spp} {budget}: {largest}"
                    );
                    if !ranges_allowed {
                        assert_eq!(c.ranges, 1);
                    }
                }
            }
        }
        // Ranges only once the bands are single rows of tiles.
        assert_eq!(
            cut([256, 144], 1024, 1 << 23, true),
            Cut {
                bands: 5,
                ranges: 1
            }
        );
        assert_eq!(
            cut([128, 72], 8192, 1 << 23, true),
            Cut {
                bands: 5,
                ranges: 2
            }
        );
        assert_eq!(
            cut([128, 72], 8192, 1 << 23, false),
            Cut {
                bands: 5,
                ranges: 1
            }
        );
        assert_eq!(
            cut([1280, 720], 4096, 1280 * 720 * 16, true),
            Cut {
                bands: 45,
                ranges: 6
            }
        );
        assert_eq!(cut([32, 24], 64, 1 << 40, true), Cut::WHOLE);
    }
}
