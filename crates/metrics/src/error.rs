//! The error type shared by every metric: bad input points, unaffordable exact
//! computations and invalid options. Library code never panics on bad input; it
//! returns one of these.

use thiserror::Error;

/// Everything that can go wrong when building a [`crate::PointSet`] or computing a metric.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MetricsError {
    /// The point set has no points.
    #[error("the point set is empty")]
    Empty,
    /// The dimension count is zero.
    #[error("the dimension count must be at least 1")]
    ZeroDims,
    /// The coordinate buffer length is not a multiple of the dimension count.
    #[error("{len} coordinates do not form whole points of {dims} dimensions")]
    Ragged {
        /// Number of coordinates given.
        len: usize,
        /// Dimension count given.
        dims: usize,
    },
    /// A row of a row-wise input has a different length from the first row.
    #[error("point {point} has {got} coordinates, expected {expected}")]
    RowLength {
        /// Zero-based index of the offending point.
        point: usize,
        /// Its number of coordinates.
        got: usize,
        /// The number of coordinates of the first point.
        expected: usize,
    },
    /// A coordinate is NaN or infinite.
    #[error("point {point}, coordinate {dim} is not finite ({value})")]
    NotFinite {
        /// Zero-based point index.
        point: usize,
        /// Zero-based coordinate index.
        dim: usize,
        /// The offending value.
        value: f64,
    },
    /// A coordinate lies outside the closed unit interval.
    #[error("point {point}, coordinate {dim} = {value} is outside [0, 1]")]
    OutOfRange {
        /// Zero-based point index.
        point: usize,
        /// Zero-based coordinate index.
        dim: usize,
        /// The offending value.
        value: f64,
    },
    /// The exact star discrepancy would cost more than the configured limit.
    #[error(
        "exact star discrepancy for n = {n}, d = {dims} needs about {estimated_work:.3e} \
         operations, above the limit {limit:.3e}; use star_bounds (lower and upper bounds) \
         instead, or raise ExactOptions::max_work"
    )]
    TooExpensive {
        /// Number of points.
        n: usize,
        /// Dimension count.
        dims: usize,
        /// Estimated elementary operations.
        estimated_work: f64,
        /// The configured limit.
        limit: f64,
    },
    /// The exact star discrepancy's recursion (one level per dimension) would
    /// be deeper than [`crate::MAX_EXACT_DIMS`].
    #[error(
        "exact star discrepancy supports at most {limit} dimensions, got {dims}; \
         use star_bounds (lower and upper bounds) instead"
    )]
    TooManyDims {
        /// Dimension count given.
        dims: usize,
        /// The largest dimension count accepted.
        limit: usize,
    },
    /// The metric needs more points than given (e.g. distances need two).
    #[error("this metric needs at least {needed} points, got {got}")]
    TooFewPoints {
        /// Minimum number of points.
        needed: usize,
        /// Number given.
        got: usize,
    },
    /// The metric is defined only for another dimension count.
    #[error("this metric needs {expected}-dimensional points, got {got}")]
    WrongDims {
        /// Required dimension count.
        expected: usize,
        /// Dimension count given.
        got: usize,
    },
    /// An option is out of its valid range.
    #[error("invalid option: {0}")]
    InvalidOption(String),
}

/// Shorthand for results of this crate.
pub type Result<T> = std::result::Result<T, MetricsError>;
