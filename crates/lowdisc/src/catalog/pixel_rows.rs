//! The samples a renderer draws for one pixel, as rows of values: what
//! `lowdisc points --pixel` prints and the Python package's `pixel_samples`
//! returns.
//!
//! The renderer (crate `render`) cuts the full image into square tiles of
//! [`DEFAULT_TILE_SIZE`] pixels from the origin, numbered row-major, and
//! renders each tile with `sampler.with_stream(tile index)`, visiting the
//! tile's pixels row by row and each pixel's samples in index order. A
//! sample starts at dimension 0 and its row here is the in-pixel offset
//! (`get_pixel_2d`), then `get_2d` pairs and, for an odd last column, one
//! `get_1d`.
//!
//! Every sampler but one gives values that depend only on (configuration,
//! pixel, index, dimension). The paper's literal sampler (`paper`) draws from
//! one sequential stream per tile, so a pixel's values depend on every call
//! made before it in its tile: [`pixel_rows`] replays the tile's earlier
//! pixels, each sample drawing one row of the same length. That is the
//! renderer's stream exactly when each of its camera samples drew that many
//! values (always for the tile's first sample).

use alloc::vec;

use super::Sampler;
use super::{SamplerConfig, SamplerName};
use crate::pixel::PixelSampler;

/// The renderer's tile side in pixels (its default `tile_size`).
pub const DEFAULT_TILE_SIZE: u32 = 16;

/// A tile of the renderer's grid.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Tile {
    /// Row-major index in the grid (the sampler stream of the tile).
    pub index: u64,
    /// First pixel (x, y), inclusive.
    pub min: [u32; 2],
    /// Last pixel (x, y), exclusive (edge tiles are clipped to the image).
    pub max: [u32; 2],
}

/// The tile holding `pixel` when a `resolution` image is cut into squares of
/// `tile_size` (at least 1) from pixel (0, 0).
pub fn tile_of(pixel: [u32; 2], resolution: [u32; 2], tile_size: u32) -> Tile {
    let s = tile_size.max(1);
    let columns = u64::from(resolution[0].div_ceil(s));
    let (tx, ty) = (pixel[0] / s, pixel[1] / s);
    let min = [tx * s, ty * s];
    Tile {
        index: u64::from(ty) * columns + u64::from(tx),
        min,
        max: [
            min[0].saturating_add(s).min(resolution[0]),
            min[1].saturating_add(s).min(resolution[1]),
        ],
    }
}

/// Whether `name`'s values depend on the calls made before them, so a
/// pixel's samples are replayed from the start of its tile.
pub fn is_sequential(name: SamplerName) -> bool {
    name == SamplerName::Paper
}

/// Sampler draws [`pixel_rows`] makes for `pixel` with rows of `dims`
/// values: the replay of the pixels before it in its tile (sequential
/// samplers only) plus its own `spp` rows.
pub fn pixel_draws(config: &SamplerConfig, pixel: [u32; 2], dims: u32, tile_size: u32) -> u64 {
    let per_pixel = u64::from(config.spp) * u64::from(dims);
    if !is_sequential(config.name) {
        return per_pixel;
    }
    let tile = tile_of(pixel, config.resolution, tile_size);
    let width = u64::from(tile.max[0] - tile.min[0]);
    let before = u64::from(pixel[1] - tile.min[1]) * width + u64::from(pixel[0] - tile.min[0]);
    (before + 1) * per_pixel
}

/// Calls `row` with each of `pixel`'s `config.spp` rows of `dims` values
/// (at least 2), in sample index order, as the renderer draws them with
/// `sampler`, built from `config` (whose resolution is the full image's).
pub fn pixel_rows(
    config: &SamplerConfig,
    sampler: &Sampler,
    pixel: [u32; 2],
    dims: usize,
    tile_size: u32,
    mut row: impl FnMut(&[f32]),
) {
    let mut values = vec![0f32; dims.max(2)];
    let tile = tile_of(pixel, config.resolution, tile_size);
    let mut s = sampler.with_stream(tile.index);
    if is_sequential(config.name) {
        let earlier = (tile.min[1]..tile.max[1])
            .flat_map(|y| (tile.min[0]..tile.max[0]).map(move |x| [x, y]))
            .take_while(|&p| p != pixel);
        for p in earlier {
            for index in 0..config.spp {
                draw_row(&mut s, p, index, &mut values);
            }
        }
    }
    for index in 0..config.spp {
        draw_row(&mut s, pixel, index, &mut values);
        row(&values);
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

    fn config(name: SamplerName) -> SamplerConfig {
        let mut c = SamplerConfig::new(name);
        (c.seed, c.spp, c.resolution) = (3, 4, [37, 20]);
        c
    }

    #[test]
    fn tiles_are_row_major_squares_clipped_at_the_edges() {
        let t = tile_of([36, 19], [37, 20], 16);
        assert_eq!(
            t,
            Tile {
                index: 5,
                min: [32, 16],
                max: [37, 20]
            }
        );
        assert_eq!(tile_of([15, 15], [37, 20], 16).index, 0);
        assert_eq!(tile_of([16, 0], [37, 20], 16).index, 1);
        assert_eq!(tile_of([0, 16], [37, 20], 16).index, 3);
        assert_eq!(tile_of([5, 5], [37, 20], 0).index, 5 * 37 + 5);
    }

    /// A renderer's walk of one tile: the stream of the tile, its pixels
    /// row by row, `dims` values per sample.
    fn walk(name: SamplerName, tile: Tile, dims: usize) -> Vec<([u32; 2], Vec<f32>)> {
        let c = config(name);
        let mut s = c.build().unwrap().with_stream(tile.index);
        let mut rows = Vec::new();
        for y in tile.min[1]..tile.max[1] {
            for x in tile.min[0]..tile.max[0] {
                let mut row = vec![0f32; dims * c.spp as usize];
                for (i, r) in (0..).zip(row.chunks_exact_mut(dims)) {
                    draw_row(&mut s, [x, y], i, r);
                }
                rows.push(([x, y], row));
            }
        }
        rows
    }

    #[test]
    fn every_pixel_gets_what_a_walk_of_its_tile_draws() {
        for name in [
            SamplerName::Paper,
            SamplerName::PaperRepro,
            SamplerName::Sobol,
        ] {
            let c = config(name);
            let sampler = c.build().unwrap();
            for tile in [
                tile_of([0, 0], c.resolution, 16),
                tile_of([33, 17], c.resolution, 16),
            ] {
                for (pixel, want) in walk(name, tile, 5) {
                    let mut got = Vec::new();
                    pixel_rows(&c, &sampler, pixel, 5, 16, |r| got.extend_from_slice(r));
                    assert_eq!(got, want, "{name:?} {pixel:?}");
                }
            }
        }
    }

    #[test]
    fn the_paper_stream_depends_on_the_tile_and_the_pixels_before() {
        let c = config(SamplerName::Paper);
        let s = c.build().unwrap();
        let rows = |pixel, tile_size| {
            let mut out = Vec::new();
            pixel_rows(&c, &s, pixel, 6, tile_size, |r| out.extend_from_slice(r));
            out
        };
        assert_ne!(rows([1, 0], 16), rows([1, 0], 1));
        assert_ne!(rows([0, 0], 16), rows([16, 0], 16));
        assert_eq!(pixel_draws(&c, [1, 0], 6, 16), 2 * 4 * 6);
        assert_eq!(pixel_draws(&c, [33, 17], 6, 16), (5 + 1 + 1) * 4 * 6);
        assert_eq!(
            pixel_draws(&config(SamplerName::Sobol), [33, 17], 6, 16),
            4 * 6
        );
    }
}
