//! Pixel mode: the samples a render draws for one pixel, as rows of values
//! (what `lowdisc points --pixel` prints and the Python package's
//! `pixel_samples` returns).
//!
//! A sample's row is its in-pixel offset (`get_pixel_2d`), then `get_2d`
//! pairs and, for an odd last column, one `get_1d`, starting at dimension
//! 0, drawn from the stream of the pixel's tile in the grid of the full
//! image ([`crate::tiles`]) along the tile's [`Walk`]. For the paper's
//! literal stream the tile's earlier pixels are replayed, each sample
//! drawing one row of the same length: that is the render's stream exactly
//! when each of its camera samples drew that many values (always for the
//! tile's first sample).

use lowdisc::catalog::{Sampler, SamplerConfig};
use lowdisc::pixel::PixelSampler;

use crate::bounds::PixelBounds;
use crate::grid::tile_of;
use crate::walk::Walk;

/// The walk that reaches the samples of `pixel` of the image of `config`
/// (`None` outside the image).
fn walk_to(config: &SamplerConfig, sampler: &Sampler, pixel: [u32; 2]) -> Option<(u64, Walk)> {
    let [w, h] = config
        .resolution
        .map(|s| i32::try_from(s).unwrap_or(i32::MAX));
    let film = PixelBounds::new([0, 0], [w, h]);
    let p = pixel.map(|c| i32::try_from(c).unwrap_or(i32::MAX));
    let tile = tile_of(film, p)?;
    let only = PixelBounds::new(p, [p[0] + 1, p[1] + 1]);
    let walk = Walk::new(
        tile.bounds,
        only,
        0..config.spp,
        config.spp,
        sampler.is_order_dependent(),
    );
    Some((tile.index, walk))
}

/// The sampler draws [`pixel_rows`] makes for `pixel` with rows of `dims`
/// values: the replayed samples and the pixel's own, times `dims`.
pub fn pixel_draws(config: &SamplerConfig, sampler: &Sampler, pixel: [u32; 2], dims: u32) -> u64 {
    walk_to(config, sampler, pixel).map_or(0, |(_, walk)| walk.len() * u64::from(dims))
}

/// Calls `row` with each of `pixel`'s `config.spp` rows of `dims` values
/// (at least 2), in sample index order, as a render draws them with
/// `sampler`, built from `config` (whose resolution is the full image's).
/// Nothing is called for a pixel outside the image.
pub fn pixel_rows(
    config: &SamplerConfig,
    sampler: &Sampler,
    pixel: [u32; 2],
    dims: usize,
    mut row: impl FnMut(&[f32]),
) {
    let Some((stream, walk)) = walk_to(config, sampler, pixel) else {
        return;
    };
    let mut values = vec![0f32; dims.max(2)];
    let mut s = sampler.with_stream(stream);
    for visit in walk {
        let p = visit.pixel.map(|c| c as u32);
        draw_row(&mut s, p, visit.index, &mut values);
        if visit.keep {
            row(&values);
        }
    }
}

/// One sample's row: starts sample `index` of `pixel` at dimension 0, then
/// the offset, `get_2d` pairs and an odd last `get_1d`.
fn draw_row(s: &mut Sampler, pixel: [u32; 2], index: u32, row: &mut [f32]) {
    s.start_pixel_sample(pixel, index, 0);
    let [ox, oy] = s.get_pixel_2d();
    row[0] = ox;
    row[1] = oy;
    let mut rest = row[2..].chunks_exact_mut(2);
    for pair in &mut rest {
        pair.copy_from_slice(&s.get_2d());
    }
    if let [last] = rest.into_remainder() {
        *last = s.get_1d();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::{Tile, tiles};
    use lowdisc::catalog::SamplerName;

    fn config(name: SamplerName) -> SamplerConfig {
        let mut c = SamplerConfig::new(name);
        (c.seed, c.spp, c.resolution) = (3, 4, [37, 20]);
        c
    }

    /// A render's walk of one whole tile: the stream of the tile, its
    /// pixels row by row, `dims` values per sample.
    fn walk(name: SamplerName, tile: Tile, dims: usize) -> Vec<([u32; 2], Vec<f32>)> {
        let c = config(name);
        let mut s = c.build().unwrap().with_stream(tile.index);
        let mut rows = Vec::new();
        for p in tile.bounds.pixels() {
            let p = p.map(|c| c as u32);
            let mut row = vec![0f32; dims * c.spp as usize];
            for (i, r) in (0..).zip(row.chunks_exact_mut(dims)) {
                draw_row(&mut s, p, i, r);
            }
            rows.push((p, row));
        }
        rows
    }

    #[test]
    fn every_pixel_gets_what_a_walk_of_its_tile_draws() {
        let film = PixelBounds::new([0, 0], [37, 20]);
        for name in [
            SamplerName::Paper,
            SamplerName::PaperRepro,
            SamplerName::Sobol,
        ] {
            let c = config(name);
            let sampler = c.build().unwrap();
            let grid: Vec<Tile> = tiles(film).collect();
            for tile in [grid[0], grid[5]] {
                for (pixel, want) in walk(name, tile, 5) {
                    let mut got = Vec::new();
                    pixel_rows(&c, &sampler, pixel, 5, |r| got.extend_from_slice(r));
                    assert_eq!(got, want, "{name:?} {pixel:?}");
                }
            }
        }
    }

    #[test]
    fn the_paper_stream_depends_on_the_tile_and_the_pixels_before() {
        let c = config(SamplerName::Paper);
        let s = c.build().unwrap();
        let rows = |pixel| {
            let mut out = Vec::new();
            pixel_rows(&c, &s, pixel, 6, |r| out.extend_from_slice(r));
            out
        };
        // Pixel (16, 0) starts tile 1: its stream differs from tile 0's.
        assert_ne!(rows([0, 0]), rows([16, 0]));
        assert_eq!(pixel_draws(&c, &s, [1, 0], 6), 2 * 4 * 6);
        assert_eq!(pixel_draws(&c, &s, [33, 17], 6), (5 + 1 + 1) * 4 * 6);
        let sobol = config(SamplerName::Sobol);
        let plain = sobol.build().unwrap();
        assert_eq!(pixel_draws(&sobol, &plain, [33, 17], 6), 4 * 6);
        assert_eq!(pixel_draws(&c, &s, [37, 0], 6), 0);
    }
}
