//! [`PixelBounds`]: half-open pixel rectangles, their pixels in row-major
//! order and square tile grids over them.

/// A half-open rectangle of pixels `[min, max)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PixelBounds {
    /// Inclusive top-left pixel.
    pub min: [i32; 2],
    /// Exclusive bottom-right pixel.
    pub max: [i32; 2],
}

impl PixelBounds {
    /// Bounds from corners (empty when `max <= min` on an axis).
    pub const fn new(min: [i32; 2], max: [i32; 2]) -> PixelBounds {
        PixelBounds { min, max }
    }
    /// Width (0 when empty).
    pub fn width(&self) -> usize {
        (self.max[0] - self.min[0]).max(0) as usize
    }
    /// Height (0 when empty).
    pub fn height(&self) -> usize {
        (self.max[1] - self.min[1]).max(0) as usize
    }
    /// Number of pixels.
    pub fn area(&self) -> usize {
        self.width() * self.height()
    }
    /// True when `p` is inside.
    pub fn contains(&self, p: [i32; 2]) -> bool {
        p[0] >= self.min[0] && p[0] < self.max[0] && p[1] >= self.min[1] && p[1] < self.max[1]
    }
    /// The overlap with `o` (possibly empty).
    pub fn intersect(&self, o: &PixelBounds) -> PixelBounds {
        PixelBounds {
            min: [self.min[0].max(o.min[0]), self.min[1].max(o.min[1])],
            max: [self.max[0].min(o.max[0]), self.max[1].min(o.max[1])],
        }
    }
    /// The pixels, row by row.
    pub fn pixels(&self) -> impl Iterator<Item = [i32; 2]> + '_ {
        (self.min[1]..self.max[1])
            .flat_map(move |y| (self.min[0]..self.max[0]).map(move |x| [x, y]))
    }
    /// Square tiles of side `size` (at least 1) covering the bounds, in a
    /// fixed row-major order; edge tiles are clipped.
    pub fn tiles(&self, size: u32) -> Vec<PixelBounds> {
        let s = size.max(1) as i32;
        let mut out = Vec::new();
        let mut y = self.min[1];
        while y < self.max[1] {
            let mut x = self.min[0];
            while x < self.max[0] {
                out.push(PixelBounds::new(
                    [x, y],
                    [(x + s).min(self.max[0]), (y + s).min(self.max[1])],
                ));
                x += s;
            }
            y += s;
        }
        out
    }
}
