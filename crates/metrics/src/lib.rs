//! Point-set quality metrics for low-discrepancy samples.
//!
//! Every metric takes a validated [`PointSet`] (points in `[0,1]^d`, point-major) and is
//! one function call, returning plain numbers or a `serde::Serialize` struct, so that a
//! command-line tool can print a table or JSON directly.
//!
//! | metric | function | definition | algorithm | cost |
//! |---|---|---|---|---|
//! | star discrepancy, exact | [`star_discrepancy`] | largest `abs(A(B)/N − V(B))` over open and closed boxes `B` anchored at 0 | 1-D closed form; 2-D sweep with block upper envelopes; d ≥ 3 DEM-style recursion with a cost guard | `N log N`; `N^{3/2}`; `N^{d−2}/(d−2)!·N^{3/2}` |
//! | star discrepancy, bounds | [`star_bounds`] | `lower ≤ D* ≤ upper` | random boxes (paper) and threshold accepting; grid bracketing | `K N d`; `R I N d`; `N d + (k+1)^d d` |
//! | L2-star, CD, WD, MD | [`l2_discrepancy`], [`l2_discrepancies`] | SciPy's formulas and conventions (L2-star as root, others squared) | symmetric pair sum, vectorised, parallel | `N² d / 2` |
//! | minimum / mean NN distance | [`distance_stats`], [`min_distance`] | Euclidean or toroidal | uniform grid, ring search | about `N·3^d` |
//! | error-image structure | [`nyquist_power`] | mean periodogram power near `(½,½)`, `(½,0)`, `(0,½)` over the mean power (white noise ≈ 1, checkerboard or stripes ≫ 1) | DFT at the bins used only, separable | `0.4 W² H + 0.16 W H²` |
//! | error-image spectral peak | [`spectral_peak`] | largest mean periodogram power over 0.1-wide frequency cells (any period, any direction) over the mean power | full DFT, separable | `W² H + W H²` |
//! | radial power spectrum (2-D) | [`radial_power_spectrum`] | `abs(Σ e^{−2πi k·x})²/N` averaged over rings | separable phases | `N K²` |
//!
//! Module [`cost`] estimates every metric's work and memory before it runs, so
//! callers can refuse unaffordable jobs. Details, formulas and references are in each
//! module's documentation: [`star`], [`l2`], [`distance`], [`spectrum`], [`structure`]. Parallel parts use rayon and sum in a fixed
//! order, so every result is bit-identical whatever the thread count.

pub mod cost;
pub mod distance;
mod error;
pub mod l2;
mod points;
pub mod spectrum;
pub mod star;
pub mod structure;

pub use distance::{
    DistanceMetric, DistanceStats, distance_stats, distance_stats_cancellable, min_distance,
    min_distance_cancellable, nearest_neighbour_distances, nearest_neighbour_distances_cancellable,
};
pub use error::{MetricsError, Result};
pub use l2::{
    L2Discrepancies, L2Method, l2_discrepancies, l2_discrepancy, l2_discrepancy_cancellable,
    l2_discrepancy_iterative,
};
pub use points::PointSet;
pub use spectrum::{RadialSpectrum, radial_power_spectrum, radial_power_spectrum_cancellable};
pub use star::{
    BoundsOptions, ExactOptions, MAX_EXACT_DIMS, StarBounds, estimated_work, grid_upper_bound,
    random_box_lower_bound, star_bounds, star_bounds_cancellable, star_discrepancy,
    star_discrepancy_1d, star_discrepancy_cancellable, star_discrepancy_with,
    threshold_accepting_lower_bound,
};
pub use structure::{NyquistPower, SpectralPeak, nyquist_power, spectral_peak};
