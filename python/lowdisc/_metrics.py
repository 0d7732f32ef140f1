"""Point-set metrics: scipy's ``discrepancy`` and ``geometric_discrepancy``
with scipy's signatures and conventions, and what scipy lacks: the exact star
discrepancy, star-discrepancy bounds, toroidal distances and the radial
power spectrum.

Samples are ``(n, d)`` arrays in the unit hypercube. The sums run in fixed
chunks added in a fixed order, so every value is the same whatever the
number of threads: ``discrepancy``'s ``workers`` (scipy's: -1 all cores, k
threads) changes only the speed; the other metrics use all cores.
"""

from __future__ import annotations

import warnings
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from . import _checks, _lowdisc

#: Largest estimated work the exact star discrepancy accepts by default
#: (a few seconds on two cores).
DEFAULT_MAX_WORK = 4e9


def discrepancy(sample: npt.ArrayLike, *, iterative: bool = False, method: str = "CD",
                workers: int = 1) -> float:
    """scipy.stats.qmc.discrepancy, same arguments and values: ``"CD"``,
    ``"WD"`` and ``"MD"`` are returned squared (as scipy does), ``"L2-star"``
    as its square root. ``iterative=True`` normalises as if the sample had
    one more point (the start of ``scipy.stats.qmc.update_discrepancy``).
    Sums are compensated: at n = 4096, d = 8 the values agree with an
    extended-precision evaluation to about 1e-12 relative. ``workers``: the
    threads of the sums, as scipy's (-1: all cores); the value is the same
    bits for every count."""
    x = _checks.sample(sample)
    workers = _checks.workers(workers)
    methods = ("CD", "WD", "MD", "L2-star")
    if method not in methods:
        raise ValueError(f"{method!r} is not a valid method. It must be one of {set(methods)!r}")
    return _lowdisc.discrepancy(x, method, bool(iterative), workers)


def geometric_discrepancy(sample: npt.ArrayLike, method: str = "mindist",
                          metric: str = "euclidean") -> float:
    """scipy.stats.qmc.geometric_discrepancy. ``"mindist"`` with the
    ``"euclidean"`` (or lowdisc's ``"toroidal"``) metric runs on a uniform
    grid in O(n) memory instead of scipy's O(n^2) distance matrix; other
    metrics and ``"mst"`` are passed to scipy (which must be installed)."""
    x = _checks.sample(sample)
    if x.shape[0] < 2:
        raise ValueError("Sample must contain at least two points")
    if method not in ("mindist", "mst"):
        raise ValueError(f"{method!r} is not a valid method. "
                         f"It must be one of {{'mindist', 'mst'}}")
    if method == "mindist" and metric in ("euclidean", "toroidal"):
        distance = _lowdisc.min_distance(x, metric)
        if distance == 0.0:
            warnings.warn("Sample contains duplicate points.", stacklevel=2)
            unique = np.ascontiguousarray(np.unique(x, axis=0))
            if unique.shape[0] < 2:
                raise ValueError("Sample has fewer than two distinct points")
            distance = _lowdisc.min_distance(unique, metric)
        return distance
    if metric == "toroidal":
        raise ValueError("the 'toroidal' metric is available with method='mindist' only")
    try:
        from scipy.stats import qmc
    except ImportError:
        raise ValueError(f"method={method!r}, metric={metric!r} needs scipy") from None
    return float(qmc.geometric_discrepancy(x, method=method, metric=metric))


def star_discrepancy(sample: npt.ArrayLike, *, exact: bool = True,
                     max_work: float = DEFAULT_MAX_WORK) -> float:
    """The star discrepancy D*: the largest ``|A(B)/n - vol(B)|`` over boxes
    ``B = [0, y)`` or ``[0, y]`` anchored at the origin.

    ``exact=True`` computes it exactly (1-D closed form, an O(n^1.5) sweep in
    2-D, a guarded recursion above) and raises ``ValueError`` when its
    estimated work (``star_work(n, d)``) exceeds ``max_work``; raise it or use
    ``star_bounds``. ``exact=False`` returns ``star_bounds(sample).lower``,
    the largest value attained by a box that the searches found.
    """
    x = _checks.sample(sample)
    if not exact:
        return star_bounds(x).lower
    return _lowdisc.star_discrepancy(x, float(max_work))


def star_work(n: int, d: int) -> float:
    """The estimated elementary operations of the exact star discrepancy."""
    return _lowdisc.star_work(_checks.integer(n, "n", low=1), _checks.integer(d, "d", low=1))


class StarBounds(NamedTuple):
    """Bounds ``lower <= D* <= upper`` and how each was found."""

    lower: float
    upper: float
    lower_method: str
    upper_method: str


def star_bounds(sample: npt.ArrayLike, *, random_boxes: int | None = None,
                ta_iterations: int | None = None, ta_restarts: int | None = None,
                grid_cells: int | None = None, seed: int = 1) -> StarBounds:
    """Lower and upper bounds of the star discrepancy, for sets too large for
    the exact value: the lower bound is the best box of random anchored boxes
    and threshold accepting, the upper a bracketing grid of ``grid_cells``
    per axis (``None``: the defaults of lowdisc-metrics)."""
    x = _checks.sample(sample)
    options = [None if v is None else _checks.integer(v, name, low=1)
               for v, name in ((random_boxes, "random_boxes"),
                               (ta_iterations, "ta_iterations"),
                               (ta_restarts, "ta_restarts"),
                               (grid_cells, "grid_cells"))]
    return StarBounds(*_lowdisc.star_bounds(x, *options, _checks.seed(seed)))


def min_distance(sample: npt.ArrayLike, *, metric: str = "euclidean") -> float:
    """The smallest distance between two points (0 with duplicates);
    ``metric="toroidal"`` measures on the unit torus (each axis wraps)."""
    x = _checks.sample(sample)
    return _lowdisc.min_distance(x, _checks.choice(metric, "metric", ("euclidean", "toroidal")))


def nearest_neighbour_distances(sample: npt.ArrayLike, *,
                                metric: str = "euclidean") -> np.ndarray:
    """Each point's distance to its nearest other point, in input order."""
    x = _checks.sample(sample)
    return _lowdisc.nearest_neighbour_distances(
        x, _checks.choice(metric, "metric", ("euclidean", "toroidal")))


def power_spectrum(sample: npt.ArrayLike, *,
                   max_frequency: int = 64) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The radially averaged power spectrum of 2-D points: ring radii
    ``1..max_frequency``, the mean periodogram ``|sum exp(-2 pi i k.x)|^2 / n``
    in each ring (1 for white noise, below 1 at low frequencies for blue
    noise) and the number of integer frequencies per ring."""
    x = _checks.sample(sample)
    k = _checks.integer(max_frequency, "max_frequency", low=1, high=4096)
    return _lowdisc.power_spectrum(x, k)
