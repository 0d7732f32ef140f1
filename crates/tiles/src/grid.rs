//! The tile grid: squares of [`TILE_SIZE`] pixels over a film's pixel
//! bounds, numbered row-major; a tile's number is its sampler stream.

use crate::bounds::PixelBounds;

/// The side of a tile in pixels.
pub const TILE_SIZE: u32 = 16;

/// A tile of the grid.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Tile {
    /// Row-major number in the grid: the tile's sampler stream.
    pub index: u64,
    /// Its pixels (edge tiles are clipped to the film's bounds).
    pub bounds: PixelBounds,
}

/// The tiles of a film whose pixel bounds are `film`, in row-major order.
pub fn tiles(film: PixelBounds) -> impl Iterator<Item = Tile> {
    (0u64..)
        .zip(film.tiles(TILE_SIZE))
        .map(|(index, bounds)| Tile { index, bounds })
}

/// The tile of `film`'s grid that holds `pixel` (`None` outside `film`).
pub fn tile_of(film: PixelBounds, pixel: [i32; 2]) -> Option<Tile> {
    if !film.contains(pixel) {
        return None;
    }
    let s = TILE_SIZE as i32;
    let columns = film.width().div_ceil(TILE_SIZE as usize) as u64;
    let (tx, ty) = ((pixel[0] - film.min[0]) / s, (pixel[1] - film.min[1]) / s);
    let min = [film.min[0] + tx * s, film.min[1] + ty * s];
    let max = [(min[0] + s).min(film.max[0]), (min[1] + s).min(film.max[1])];
    Some(Tile {
        index: ty as u64 * columns + tx as u64,
        bounds: PixelBounds::new(min, max),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_pixel_finds_the_tile_that_holds_it() {
        for film in [
            PixelBounds::new([0, 0], [37, 20]),
            PixelBounds::new([3, 5], [40, 21]),
            PixelBounds::new([0, 0], [16, 16]),
            PixelBounds::new([-4, 2], [1, 3]),
        ] {
            for tile in tiles(film) {
                for p in tile.bounds.pixels() {
                    assert_eq!(tile_of(film, p), Some(tile), "{film:?} {p:?}");
                }
            }
        }
        let film = PixelBounds::new([3, 5], [40, 21]);
        assert_eq!(tile_of(film, [2, 5]), None);
        assert_eq!(tile_of(film, [40, 5]), None);
    }

    #[test]
    fn tiles_are_row_major_squares_from_the_first_pixel_clipped_at_the_edges() {
        let film = PixelBounds::new([3, 5], [40, 21]);
        let grid: Vec<Tile> = tiles(film).collect();
        assert_eq!(grid.len(), 3);
        assert_eq!(grid[0].bounds, PixelBounds::new([3, 5], [19, 21]));
        assert_eq!(grid[2].bounds, PixelBounds::new([35, 5], [40, 21]));
        assert_eq!(tile_of(film, [36, 20]).map(|t| t.index), Some(2));
    }
}
