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

import os
import warnings
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from . import _checks, _lowdisc

#: Largest estimated work the exact star discrepancy accepts by default
#: (a few seconds on two cores).
DEFAULT_MAX_WORK = 4e9

#: Largest work ``n (n + 1) / 2 * d`` the L2 discrepancies accept by default
#: (about a minute on two cores; ``max_work=None`` lifts it).
DEFAULT_DISCREPANCY_WORK = 1e11

try:  # Bound now, so that patching scipy's name later cannot loop back here.
    from scipy.stats.qmc import geometric_discrepancy as _scipy_geometric_discrepancy
except ImportError:  # scipy is optional
    _scipy_geometric_discrepancy = None


def discrepancy(sample: npt.ArrayLike, *, iterative: bool = False, method: str = "CD",
                workers: int = 1, max_work: float | None = DEFAULT_DISCREPANCY_WORK) -> float:
    """Discrepancy of a given sample: ``scipy.stats.qmc.discrepancy``.

    Same arguments, conventions and values as scipy's (to about 1e-12
    relative; the sums are compensated, so at n = 4096, d = 8 the values
    agree with an extended-precision evaluation to about 1e-12), with every
    thread count giving the same bits. The pair sum, O(n^2 d), can be
    interrupted with Ctrl-C.

    Parameters
    ----------
    sample : array_like (n, d)
        The sample, in the unit hypercube.
    iterative : bool, default False
        Normalise as if the sample had one more point (the start of
        :func:`update_discrepancy`).
    method : {"CD", "WD", "MD", "L2-star"}, default "CD"
        Centered, wrap-around, mixture or L2-star discrepancy. CD, WD and MD
        are returned squared (as scipy does), L2-star as its square root.
    workers : int, default 1
        Threads of the sums (-1: all cores, as scipy's).
    max_work : float or None, default DEFAULT_DISCREPANCY_WORK
        Refuse (``ValueError``) samples whose ``n (n + 1) / 2 * d`` exceeds
        it; ``None`` accepts any size.

    Returns
    -------
    float
        The discrepancy.

    Examples
    --------
    >>> import numpy as np
    >>> import lowdisc
    >>> space = (2 * np.array([[1, 3], [2, 6], [3, 2], [4, 5], [5, 1], [6, 4]]) - 1) / 12
    >>> round(lowdisc.discrepancy(space), 4)
    0.0081
    >>> round(lowdisc.discrepancy(space, method="L2-star"), 4)
    0.0683
    """
    x = _checks.sample(sample)
    workers = _checks.workers(workers)
    if workers == -1 and os.cpu_count() is None:
        raise NotImplementedError("Cannot determine the number of cpus using os.cpu_count(), "
                                  "cannot use -1 for the number of workers")
    methods = ("CD", "WD", "MD", "L2-star")
    if method not in methods:
        raise ValueError(f"{method!r} is not a valid method. It must be one of {set(methods)!r}")
    work = _lowdisc.discrepancy_work(*x.shape)
    if max_work is not None and work > max_work:
        raise ValueError(f"the discrepancy of {x.shape[0]} points in {x.shape[1]} dimensions "
                         f"visits n (n + 1) / 2 * d = {work:.3g} pairs and coordinates, more "
                         f"than max_work={max_work:.3g}; raise max_work (or None) to compute it")
    return _lowdisc.discrepancy(x, method, bool(iterative), workers)


def update_discrepancy(x_new: npt.ArrayLike, sample: npt.ArrayLike,
                       initial_disc: float) -> float:
    """Centered discrepancy after adding ``x_new`` to ``sample``:
    ``scipy.stats.qmc.update_discrepancy``, in O(n d).

    Parameters
    ----------
    x_new : array_like (d,)
        The new point, in the unit hypercube.
    sample : array_like (n, d)
        The points before it.
    initial_disc : float
        ``discrepancy(sample, iterative=True)``: the centered discrepancy of
        ``sample`` normalised for ``n + 1`` points.

    Returns
    -------
    float
        The centered discrepancy (squared, as scipy's) of the ``n + 1`` points.

    Examples
    --------
    >>> import numpy as np
    >>> import lowdisc
    >>> x = np.random.default_rng(3).random((20, 4))
    >>> start = lowdisc.discrepancy(x[:-1], iterative=True)
    >>> bool(np.isclose(lowdisc.update_discrepancy(x[-1], x[:-1], start),
    ...                 lowdisc.discrepancy(x), rtol=1e-12))
    True
    """
    sample = np.asarray(sample, dtype=np.float64)
    x_new = np.asarray(x_new, dtype=np.float64)
    if sample.ndim != 2:
        raise ValueError("Sample is not a 2D array")
    if sample.max() > 1.0 or sample.min() < 0.0:
        raise ValueError("Sample is not in unit hypercube")
    if x_new.ndim != 1:
        raise ValueError("x_new is not a 1D array")
    if not (np.all(x_new >= 0) and np.all(x_new <= 1)):
        raise ValueError("x_new is not in unit hypercube")
    if x_new.shape[0] != sample.shape[1]:
        raise ValueError("x_new and sample must be broadcastable")
    # The centered discrepancy's terms involving the new point x (Hickernell
    # 1998), with N = n + 1 already in initial_disc's normalisation:
    # -2/N prod(1 + |z|/2 - z^2/2) + (2 sum_i prod(1 + |z|/2 + |z_i|/2
    # - |x - x_i|/2) + prod(1 + |z|)) / N^2, z = x - 1/2.
    n = sample.shape[0] + 1
    z_new = np.abs(x_new - 0.5)
    z = np.abs(sample - 0.5)
    single = np.prod(1 + 0.5 * z_new - 0.5 * z_new**2)
    cross = np.prod(1 + 0.5 * z_new + 0.5 * z - 0.5 * np.abs(x_new - sample), axis=1).sum()
    own = np.prod(1 + z_new)
    return float(initial_disc - 2.0 / n * single + (2.0 * cross + own) / n**2)


def geometric_discrepancy(sample: npt.ArrayLike, method: str = "mindist",
                          metric: str = "euclidean") -> float:
    """Discrepancy of a sample based on its geometric properties:
    ``scipy.stats.qmc.geometric_discrepancy``.

    ``"mindist"`` with the ``"euclidean"`` (or lowdisc's ``"toroidal"``)
    metric runs on a uniform grid in O(n) memory instead of scipy's O(n^2)
    distance matrix; other metrics and ``"mst"`` are scipy's own (scipy
    must be installed).

    Parameters
    ----------
    sample : array_like (n, d)
        The sample, in the unit hypercube, at least two points.
    method : {"mindist", "mst"}, default "mindist"
        The smallest distance between two distinct points, or the mean edge
        length of the minimum spanning tree.
    metric : str, default "euclidean"
        ``"euclidean"``, ``"toroidal"`` (each axis wraps) or any of
        ``scipy.spatial.distance.pdist``'s metrics.

    Returns
    -------
    float
        The discrepancy (larger is more evenly spread).

    Examples
    --------
    >>> import lowdisc
    >>> round(lowdisc.geometric_discrepancy([[0, 0], [0.25, 0.25], [1, 1]]) ** 2, 12)
    0.125
    >>> round(lowdisc.geometric_discrepancy([[0.05, 0.5], [0.95, 0.5]], metric="toroidal"), 12)
    0.1
    """
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
    if _scipy_geometric_discrepancy is None:
        raise ValueError(f"method={method!r}, metric={metric!r} needs scipy")
    return float(_scipy_geometric_discrepancy(x, method=method, metric=metric))


def star_discrepancy(sample: npt.ArrayLike, *, exact: bool = True,
                     max_work: float = DEFAULT_MAX_WORK) -> float:
    """The star discrepancy D*: the largest ``|A(B)/n - vol(B)|`` over boxes
    ``B = [0, y)`` or ``[0, y]`` anchored at the origin.

    ``exact=True`` computes it exactly (1-D closed form, an O(n^1.5) sweep in
    2-D, a guarded recursion above) and raises ``ValueError`` when its
    estimated work (``star_work(n, d)``) exceeds ``max_work``; raise it or use
    ``star_bounds``. ``exact=False`` returns ``star_bounds(sample).lower``,
    the largest value attained by a box that the searches found.

    Parameters
    ----------
    sample : array_like (n, d)
        The points, in the unit hypercube.
    exact : bool, default True
        Compute the exact value (else the best lower bound found).
    max_work : float, default DEFAULT_MAX_WORK
        The largest estimated work accepted.

    Returns
    -------
    float
        D*.

    Examples
    --------
    >>> import numpy as np
    >>> import lowdisc
    >>> centres = ((np.arange(100) + 0.5) / 100)[:, None]  # D* = 1 / (2 n)
    >>> round(lowdisc.star_discrepancy(centres), 12)
    0.005
    """
    x = _checks.sample(sample)
    if not exact:
        return star_bounds(x).lower
    return _lowdisc.star_discrepancy(x, float(max_work))


def star_work(n: int, d: int) -> float:
    """The estimated elementary operations of the exact star discrepancy.

    Parameters
    ----------
    n, d : int
        Points and dimensions.

    Returns
    -------
    float
        The estimate :func:`star_discrepancy` compares with ``max_work``.

    Examples
    --------
    >>> import lowdisc
    >>> lowdisc.star_work(4096, 6) > lowdisc.star_work(4096, 2)
    True
    """
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
    per axis (``None``: the defaults of lowdisc-metrics).

    Parameters
    ----------
    sample : array_like (n, d)
        The points, in the unit hypercube.
    random_boxes, ta_iterations, ta_restarts, grid_cells : int, optional
        Effort of the searches and the grid (``None``: the defaults).
    seed : int, default 1
        Seed of the random searches.

    Returns
    -------
    StarBounds
        ``(lower, upper, lower_method, upper_method)``.

    Examples
    --------
    >>> import lowdisc
    >>> x = lowdisc.sobol(512, 2, scramble="owen", seed=5)
    >>> b = lowdisc.star_bounds(x)
    >>> bool(b.lower <= lowdisc.star_discrepancy(x) <= b.upper)
    True
    """
    x = _checks.sample(sample)
    options = [None if v is None else _checks.integer(v, name, low=1)
               for v, name in ((random_boxes, "random_boxes"),
                               (ta_iterations, "ta_iterations"),
                               (ta_restarts, "ta_restarts"),
                               (grid_cells, "grid_cells"))]
    return StarBounds(*_lowdisc.star_bounds(x, *options, _checks.seed(seed)))


def min_distance(sample: npt.ArrayLike, *, metric: str = "euclidean") -> float:
    """The smallest distance between two points (0 with duplicates);
    ``metric="toroidal"`` measures on the unit torus (each axis wraps).

    Parameters
    ----------
    sample : array_like (n, d)
        The points, in the unit hypercube.
    metric : {"euclidean", "toroidal"}, default "euclidean"
        The distance.

    Returns
    -------
    float
        The smallest distance.

    Examples
    --------
    >>> import lowdisc
    >>> x = [[0.02, 0.5], [0.98, 0.5], [0.5, 0.1]]
    >>> round(lowdisc.min_distance(x, metric="toroidal"), 12)
    0.04
    """
    x = _checks.sample(sample)
    return _lowdisc.min_distance(x, _checks.choice(metric, "metric", ("euclidean", "toroidal")))


def nearest_neighbour_distances(sample: npt.ArrayLike, *,
                                metric: str = "euclidean") -> np.ndarray:
    """Each point's distance to its nearest other point, in input order.

    Parameters
    ----------
    sample : array_like (n, d)
        The points, in the unit hypercube.
    metric : {"euclidean", "toroidal"}, default "euclidean"
        The distance.

    Returns
    -------
    numpy.ndarray
        ``n`` distances.

    Examples
    --------
    >>> import lowdisc
    >>> lowdisc.nearest_neighbour_distances([[0.1, 0.1], [0.1, 0.6], [0.9, 0.6]])
    array([0.5, 0.5, 0.8])
    """
    x = _checks.sample(sample)
    return _lowdisc.nearest_neighbour_distances(
        x, _checks.choice(metric, "metric", ("euclidean", "toroidal")))


def power_spectrum(sample: npt.ArrayLike, *,
                   max_frequency: int = 64) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The radially averaged power spectrum of 2-D points: ring radii
    ``1..max_frequency``, the mean periodogram ``|sum exp(-2 pi i k.x)|^2 / n``
    in each ring (1 for white noise, below 1 at low frequencies for blue
    noise) and the number of integer frequencies per ring.

    Parameters
    ----------
    sample : array_like (n, 2)
        2-D points in the unit square.
    max_frequency : int, default 64
        The largest ring radius.

    Returns
    -------
    tuple of numpy.ndarray
        ``(radii, power, counts)``.

    Examples
    --------
    >>> import lowdisc
    >>> radii, power, counts = lowdisc.power_spectrum(lowdisc.independent(4096, 2, seed=1),
    ...                                               max_frequency=32)
    >>> bool(abs(power[8:].mean() - 1) < 0.1)  # white noise is flat near 1
    True
    """
    x = _checks.sample(sample)
    k = _checks.integer(max_frequency, "max_frequency", low=1, high=4096)
    return _lowdisc.power_spectrum(x, k)
