//! # lowdisc-tiles: the image's tiles and the order of their samples
//!
//! The render loop cuts the film's pixel bounds into square tiles of
//! [`TILE_SIZE`] pixels, numbered row-major from the bounds' first pixel
//! ([`tiles`]). Tile `k` is rendered with its own copy of the pixel
//! sampler, `sampler.with_stream(k)`, visiting its pixels row by row and
//! each pixel's samples in index order ([`Walk`]). For every sampler but
//! one, a value depends only on (configuration, pixel, sample index,
//! dimension), so the tiles only divide the work. The paper's literal
//! sampler draws from one sequential stream per tile: its values depend on
//! every call made before them in the tile, so to take some of a tile's
//! samples (a window, a sample range, one pixel) a [`Walk`] replays the
//! tile from its first pixel and marks which samples to keep.
//!
//! This crate is the one place that knows the grid, the stream of a tile
//! and the replay: the render loop follows a [`Walk`] for each tile, and
//! the pixel mode of `lowdisc points` and of the Python package
//! ([`pixel_rows`]) follows the same walk with rows of fixed length.
//!
//! ```
//! use lowdisc_tiles::{PixelBounds, TILE_SIZE, tiles};
//!
//! let film = PixelBounds::new([0, 0], [40, 20]);
//! let grid: Vec<_> = tiles(film).collect();
//! assert_eq!(grid.len(), 3 * 2);
//! assert_eq!(grid[4].index, 4);
//! assert_eq!(grid[4].bounds, PixelBounds::new([16, 16], [32, 20]));
//! assert_eq!(TILE_SIZE, 16);
//! ```

mod bounds;
mod grid;
mod rows;
mod walk;

pub use bounds::PixelBounds;
pub use grid::{TILE_SIZE, Tile, tile_of, tiles};
pub use rows::{pixel_draws, pixel_rows};
pub use walk::{Visit, Walk};
