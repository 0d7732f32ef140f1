//! Piecewise-constant 2D distribution on `[0,1]^2`: a marginal over rows and
//! one conditional per row.

use super::Distribution1D;
use crate::math::Point2;

/// A piecewise-constant density on `[0,1]^2` from a `width × height` grid of
/// values (row-major, row `y` covering `v` in `[y/height, (y+1)/height)`).
///
/// Sampling draws a row from the marginal (row integrals) with `u[1]`, then a
/// column from that row's conditional with `u[0]`. An all-zero grid samples
/// uniformly.
#[derive(Clone, Debug, PartialEq)]
pub struct Distribution2D {
    conditional: Vec<Distribution1D>,
    marginal: Distribution1D,
}

impl Distribution2D {
    /// Builds the distribution; `None` unless `width, height > 0` and
    /// `func.len() == width * height`.
    pub fn new(func: &[f32], width: usize, height: usize) -> Option<Self> {
        if width == 0 || height == 0 || width.checked_mul(height) != Some(func.len()) {
            return None;
        }
        let conditional: Vec<Distribution1D> = func
            .chunks_exact(width)
            .map(Distribution1D::new)
            .collect::<Option<_>>()?;
        let row_integrals: Vec<f32> = conditional.iter().map(Distribution1D::integral).collect();
        let marginal = Distribution1D::new(&row_integrals)?;
        Some(Distribution2D {
            conditional,
            marginal,
        })
    }

    /// Grid width (columns, the `u` direction).
    pub fn width(&self) -> usize {
        self.conditional[0].len()
    }
    /// Grid height (rows, the `v` direction).
    pub fn height(&self) -> usize {
        self.conditional.len()
    }
    /// Integral of the function over `[0,1]^2` (0 when all values are 0).
    pub fn integral(&self) -> f32 {
        self.marginal.integral()
    }

    /// Samples a point of `[0,1]^2` and returns it with its density.
    pub fn sample(&self, u: [f32; 2]) -> (Point2, f32) {
        let row = self.marginal.sample_continuous(u[1]);
        let col = self.conditional[row.offset].sample_continuous(u[0]);
        (Point2::new(col.x, row.x), col.pdf * row.pdf)
    }

    /// Density of [`Distribution2D::sample`] at `p` (0 outside `[0,1]^2`).
    pub fn pdf(&self, p: Point2) -> f32 {
        if !(p.x >= 0.0 && p.x <= 1.0 && p.y >= 0.0 && p.y <= 1.0) {
            return 0.0;
        }
        if self.marginal.is_all_zero() {
            return 1.0;
        }
        let row = &self.conditional[self.marginal.offset_of(p.y)];
        let col = row.offset_of(p.x);
        row.func()[col] / self.marginal.integral()
    }
}
