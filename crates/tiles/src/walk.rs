//! [`Walk`]: the camera samples a tile takes, in order, and which of them
//! the film keeps.
//!
//! A tile visits its pixels row by row and each pixel's samples in index
//! order. With an order-independent sampler only the samples asked for are
//! taken: the pixels of the tile inside the window, the indices of the
//! sample range. With an order-dependent one (the paper's literal stream)
//! the tile is replayed from its first pixel with every index, up to the
//! last sample asked for, so that each kept sample draws the values it
//! draws in a render of the whole tile; the samples outside the window or
//! the range are taken and dropped.

use core::ops::Range;

use crate::bounds::PixelBounds;

/// One camera sample of a walk.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Visit {
    /// The pixel.
    pub pixel: [i32; 2],
    /// The sample index within the pixel.
    pub index: u32,
    /// Whether the sample is one asked for (the others are replayed only).
    pub keep: bool,
}

/// The camera samples of one tile; iterate it for its [`Visit`]s.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Walk {
    /// The pixels visited, row by row.
    pixels: PixelBounds,
    /// The indices visited in each pixel.
    indices: Range<u32>,
    /// The pixels asked for.
    kept: PixelBounds,
    /// The indices asked for.
    range: Range<u32>,
    /// The last visit: its pixel and the index it stops before.
    end: ([i32; 2], u32),
}

impl Walk {
    /// The walk of the tile `tile` that takes the samples `range` (within
    /// `0..spp`) of its pixels inside `window`; `replay` for a sampler
    /// whose values depend on the order of calls. Empty when the tile and
    /// the window do not meet or the range is empty.
    ///
    /// ```
    /// use lowdisc_tiles::{PixelBounds, Walk};
    ///
    /// let tile = PixelBounds::new([0, 0], [4, 4]);
    /// let window = PixelBounds::new([1, 0], [2, 1]);
    /// // Order-independent: just the two samples of pixel (1, 0).
    /// let plain: Vec<_> = Walk::new(tile, window, 0..2, 2, false).into_iter().collect();
    /// assert_eq!(plain.len(), 2);
    /// // The literal stream: pixel (0, 0) is replayed first, and dropped.
    /// let replay: Vec<_> = Walk::new(tile, window, 0..2, 2, true).into_iter().collect();
    /// assert_eq!(replay.len(), 4);
    /// assert!(!replay[0].keep && replay[3].keep && replay[3].pixel == [1, 0]);
    /// ```
    pub fn new(
        tile: PixelBounds,
        window: PixelBounds,
        range: Range<u32>,
        spp: u32,
        replay: bool,
    ) -> Walk {
        let kept = tile.intersect(&window);
        let last = [kept.max[0] - 1, kept.max[1] - 1];
        let (pixels, indices) = if replay {
            (tile, 0..spp)
        } else {
            (kept, range.clone())
        };
        let end = if kept.area() == 0 || range.is_empty() {
            (pixels.min, indices.start)
        } else {
            (last, if replay { range.end } else { indices.end })
        };
        Walk {
            pixels,
            indices,
            kept,
            range,
            end,
        }
    }

    /// The number of samples the walk takes, kept or not.
    pub fn len(&self) -> u64 {
        let (last, stop) = self.end;
        let width = self.pixels.width() as u64;
        let before =
            (last[1] - self.pixels.min[1]) as u64 * width + (last[0] - self.pixels.min[0]) as u64;
        before * u64::from(self.indices.len() as u32)
            + u64::from(stop.saturating_sub(self.indices.start))
    }

    /// True when the walk takes no sample.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Whether the sample `index` of `pixel` is one asked for.
    pub fn keeps(&self, pixel: [i32; 2], index: u32) -> bool {
        self.kept.contains(pixel) && self.range.contains(&index)
    }
}

impl IntoIterator for Walk {
    type Item = Visit;
    type IntoIter = Visits;

    fn into_iter(self) -> Visits {
        Visits {
            next: (self.pixels.min, self.indices.start),
            remaining: self.len(),
            walk: self,
        }
    }
}

/// The [`Visit`]s of a [`Walk`], in order.
#[derive(Debug, Clone)]
pub struct Visits {
    walk: Walk,
    /// The next visit's pixel and index.
    next: ([i32; 2], u32),
    /// Visits left.
    remaining: u64,
}

impl Iterator for Visits {
    type Item = Visit;

    fn next(&mut self) -> Option<Visit> {
        if self.remaining == 0 {
            return None;
        }
        self.remaining -= 1;
        let (pixel, index) = self.next;
        let (pixels, indices) = (&self.walk.pixels, &self.walk.indices);
        self.next = if index + 1 < indices.end {
            (pixel, index + 1)
        } else if pixel[0] + 1 < pixels.max[0] {
            ([pixel[0] + 1, pixel[1]], indices.start)
        } else {
            ([pixels.min[0], pixel[1] + 1], indices.start)
        };
        Some(Visit {
            pixel,
            index,
            keep: self.walk.keeps(pixel, index),
        })
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = usize::try_from(self.remaining).unwrap_or(usize::MAX);
        (n, usize::try_from(self.remaining).ok())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The visits as the render loop took them before walks: every pixel of
    /// `pixels` row by row, every index of `indices`, stopping at the last
    /// kept pixel's sample `range.end` when replaying.
    fn nested_loops(
        tile: PixelBounds,
        window: PixelBounds,
        range: Range<u32>,
        spp: u32,
        replay: bool,
    ) -> Vec<Visit> {
        let kept = tile.intersect(&window);
        let (pixels, indices) = if replay {
            (tile, 0..spp)
        } else {
            (kept, range.clone())
        };
        let last = [kept.max[0] - 1, kept.max[1] - 1];
        let mut out = Vec::new();
        for pixel in pixels.pixels() {
            for index in indices.clone() {
                if replay && pixel == last && index >= range.end {
                    break;
                }
                let keep = kept.contains(pixel) && range.contains(&index);
                out.push(Visit { pixel, index, keep });
            }
            if pixel == last {
                break;
            }
        }
        out
    }

    #[test]
    fn walks_visit_what_nested_loops_visit() {
        let tile = PixelBounds::new([16, 0], [32, 7]);
        let windows = [
            PixelBounds::new([0, 0], [40, 20]),
            PixelBounds::new([18, 2], [25, 5]),
            PixelBounds::new([31, 6], [40, 20]),
            PixelBounds::new([16, 0], [17, 1]),
        ];
        for window in windows {
            for range in [0..4, 1..3, 3..4, 0..1] {
                for replay in [false, true] {
                    let walk = Walk::new(tile, window, range.clone(), 4, replay);
                    let want = nested_loops(tile, window, range.clone(), 4, replay);
                    assert_eq!(walk.len(), want.len() as u64);
                    let got: Vec<Visit> = walk.into_iter().collect();
                    assert_eq!(got, want, "{window:?} {range:?} {replay}");
                    assert!(got.iter().any(|v| v.keep));
                }
            }
        }
    }

    #[test]
    fn a_window_outside_the_tile_takes_nothing() {
        let tile = PixelBounds::new([0, 0], [16, 16]);
        let away = PixelBounds::new([20, 0], [30, 5]);
        for replay in [false, true] {
            assert!(Walk::new(tile, away, 0..4, 4, replay).is_empty());
            assert_eq!(
                Walk::new(tile, away, 0..4, 4, replay).into_iter().count(),
                0
            );
        }
    }
}
