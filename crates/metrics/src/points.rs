//! The validated input of every metric: `n` points in `[0,1]^d`, stored point-major
//! (`coords[i * dims + j]` is coordinate `j` of point `i`).
//!
//! Validation guarantees: at least one point, `dims >= 1`, a whole number of points,
//! every coordinate finite and inside the closed interval `[0, 1]`. Metrics can then
//! rely on these facts without re-checking.

use crate::error::{MetricsError, Result};

/// A validated, non-empty set of points in the closed unit cube `[0,1]^dims`.
#[derive(Debug, Clone, PartialEq)]
pub struct PointSet {
    dims: usize,
    coords: Vec<f64>,
}

impl PointSet {
    /// Builds a point set from point-major coordinates, validating every value.
    ///
    /// Errors: [`MetricsError::ZeroDims`], [`MetricsError::Empty`],
    /// [`MetricsError::Ragged`], [`MetricsError::NotFinite`], [`MetricsError::OutOfRange`].
    pub fn new(dims: usize, coords: Vec<f64>) -> Result<Self> {
        if dims == 0 {
            return Err(MetricsError::ZeroDims);
        }
        if coords.is_empty() {
            return Err(MetricsError::Empty);
        }
        if coords.len() % dims != 0 {
            return Err(MetricsError::Ragged {
                len: coords.len(),
                dims,
            });
        }
        for (k, &value) in coords.iter().enumerate() {
            let (point, dim) = (k / dims, k % dims);
            if !value.is_finite() {
                return Err(MetricsError::NotFinite { point, dim, value });
            }
            if !(0.0..=1.0).contains(&value) {
                return Err(MetricsError::OutOfRange { point, dim, value });
            }
        }
        // Normalise -0.0 to +0.0 so that sorting and equality agree everywhere.
        let coords = coords.into_iter().map(|v| v + 0.0).collect();
        Ok(Self { dims, coords })
    }

    /// Builds a point set from a slice of point-major coordinates (copied).
    pub fn from_slice(dims: usize, coords: &[f64]) -> Result<Self> {
        Self::new(dims, coords.to_vec())
    }

    /// Builds a point set from rows (one row per point); all rows must have the same
    /// length as the first. Errors as [`PointSet::new`], plus
    /// [`MetricsError::RowLength`] for a ragged row.
    pub fn from_rows<R: AsRef<[f64]>>(rows: &[R]) -> Result<Self> {
        let first = rows.first().ok_or(MetricsError::Empty)?.as_ref().len();
        let mut coords = Vec::with_capacity(first * rows.len());
        for (point, row) in rows.iter().enumerate() {
            let row = row.as_ref();
            if row.len() != first {
                return Err(MetricsError::RowLength {
                    point,
                    got: row.len(),
                    expected: first,
                });
            }
            coords.extend_from_slice(row);
        }
        Self::new(first, coords)
    }

    /// Number of coordinates per point.
    pub fn dims(&self) -> usize {
        self.dims
    }

    /// Number of points (always at least 1).
    pub fn len(&self) -> usize {
        self.coords.len() / self.dims
    }

    /// Always false: a validated set has at least one point.
    pub fn is_empty(&self) -> bool {
        self.coords.is_empty()
    }

    /// All coordinates, point-major.
    pub fn coords(&self) -> &[f64] {
        &self.coords
    }

    /// The coordinates of point `i`. Panics if `i >= len()` (a caller bug, not input).
    pub fn point(&self, i: usize) -> &[f64] {
        &self.coords[i * self.dims..(i + 1) * self.dims]
    }

    /// Iterator over the points, each as a slice of `dims` coordinates.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = &[f64]> + '_ {
        self.coords.chunks_exact(self.dims)
    }

    /// Coordinate `j` of every point, as one contiguous vector (dimension-major view).
    pub fn column(&self, j: usize) -> Vec<f64> {
        self.iter().map(|p| p[j]).collect()
    }

    /// Projection onto the given coordinates, in the given order. Errors with
    /// [`MetricsError::InvalidOption`] when an index is out of range or the list is empty.
    pub fn project(&self, dims: &[usize]) -> Result<PointSet> {
        if dims.is_empty() {
            return Err(MetricsError::InvalidOption(
                "projection onto no coordinates".into(),
            ));
        }
        if let Some(&bad) = dims.iter().find(|&&j| j >= self.dims) {
            return Err(MetricsError::InvalidOption(format!(
                "coordinate {bad} does not exist in a {}-dimensional set",
                self.dims
            )));
        }
        let coords = self
            .iter()
            .flat_map(|p| dims.iter().map(move |&j| p[j]))
            .collect();
        Ok(PointSet {
            dims: dims.len(),
            coords,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn validation_errors() {
        assert_eq!(PointSet::new(0, vec![0.5]), Err(MetricsError::ZeroDims));
        assert_eq!(PointSet::new(2, vec![]), Err(MetricsError::Empty));
        assert_eq!(
            PointSet::new(2, vec![0.1, 0.2, 0.3]),
            Err(MetricsError::Ragged { len: 3, dims: 2 })
        );
        assert!(matches!(
            PointSet::new(2, vec![0.1, f64::NAN]),
            Err(MetricsError::NotFinite {
                point: 0,
                dim: 1,
                ..
            })
        ));
        assert!(matches!(
            PointSet::new(1, vec![0.1, 1.5]),
            Err(MetricsError::OutOfRange {
                point: 1,
                dim: 0,
                ..
            })
        ));
        assert!(matches!(
            PointSet::new(1, vec![-0.0, -1e-300]),
            Err(MetricsError::OutOfRange { point: 1, .. })
        ));
        let rows: Vec<Vec<f64>> = vec![vec![0.1, 0.2], vec![0.3]];
        assert_eq!(
            PointSet::from_rows(&rows),
            Err(MetricsError::RowLength {
                point: 1,
                got: 1,
                expected: 2
            })
        );
    }

    #[test]
    fn accessors_and_projection() {
        let p = PointSet::new(3, vec![0.0, 0.5, 1.0, 0.25, 0.75, 0.125]).unwrap();
        assert_eq!(p.len(), 2);
        assert_eq!(p.point(1), &[0.25, 0.75, 0.125]);
        assert_eq!(p.column(2), vec![1.0, 0.125]);
        let q = p.project(&[2, 0]).unwrap();
        assert_eq!(q.coords(), &[1.0, 0.0, 0.125, 0.25]);
        assert!(p.project(&[3]).is_err());
    }
}
