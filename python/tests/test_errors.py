"""Bad arguments raise ValueError or TypeError with a clear message, both
through the package and straight into the extension, and never crash the
interpreter."""

from __future__ import annotations

import numpy as np
import pytest

import lowdisc
from lowdisc import _lowdisc


@pytest.mark.parametrize("call, error, message", [
    (lambda: lowdisc.sobol(-1, 2), ValueError, "n must be at least 0, got -1"),
    (lambda: lowdisc.sobol(2.5, 2), TypeError, "n must be an integer, got float"),
    (lambda: lowdisc.sobol(4, 21202), ValueError, "21201 dimensions"),
    (lambda: lowdisc.sobol(4, -1), ValueError, "d must be between 0"),
    (lambda: lowdisc.halton(4, 6543), ValueError, "6542 dimensions"),
    (lambda: lowdisc.sobol(4, 2, scramble="owen-per-digit"), ValueError,
     "scramble must be one of"),
    (lambda: lowdisc.halton(4, 2, scramble="lms"), ValueError, "scramble must be one of"),
    (lambda: lowdisc.sobol(4, 2, order="random"), ValueError, "order must be one of"),
    (lambda: lowdisc.sobol(4, 2, dtype=np.int8), TypeError, "dtype must be float64"),
    (lambda: lowdisc.sobol(4, 2, seed=-1), ValueError, "seed must be between 0"),
    (lambda: lowdisc.sobol(4, 2, start=2**32), ValueError, r"2\^32 points"),
    (lambda: lowdisc.sobol(2**40, 2**10), MemoryError, "Unable to allocate"),
    (lambda: lowdisc.sobol(4, 2, out=np.empty((4, 3))), ValueError,
     r"out must have shape \(4, 2\)"),
    (lambda: lowdisc.sobol(4, 2, out=np.empty((4, 2), dtype=np.int64)), TypeError,
     "dtype must be float64"),
    (lambda: lowdisc.sobol(4, 2, out=np.empty((2, 4)).T), ValueError, "C-contiguous"),
    (lambda: lowdisc.sobol(4, 2, dtype=np.float32, out=np.empty((4, 2))), TypeError,
     "dtype=float32 was asked for"),
    (lambda: lowdisc.sobol(4, 2, replications=0), ValueError,
     "replications must be at least 1"),
    (lambda: lowdisc.discrepancy(np.zeros((1000, 10)), max_work=1e6), ValueError,
     "more than max_work"),
    (lambda: lowdisc.update_discrepancy([0.5], [[0.2, 0.3]], 0.1), ValueError,
     "broadcastable"),
    (lambda: lowdisc.stratified(0, 2), ValueError, "1 <= n"),
    (lambda: lowdisc.pixel_samples("nope", 4, (2, 2), [(0, 0)]), ValueError,
     "unknown sampler"),
    (lambda: lowdisc.pixel_samples("sobol", 4, (2, 2), [(2, 0)]), ValueError,
     "outside the 2x2 image"),
    (lambda: lowdisc.pixel_samples("sobol", 4, (2, 2), [(0.5, 0)]), TypeError,
     "pixels must be integers"),
    (lambda: lowdisc.pixel_samples("sobol", 0, (2, 2), [(0, 0)]), ValueError,
     "spp must be between 1"),
    (lambda: lowdisc.discrepancy([[0.1, np.nan]]), ValueError, "Sample contains NaN"),
    (lambda: lowdisc.discrepancy([0.1, 0.2]), ValueError, "Sample is not a 2D array"),
    (lambda: lowdisc.discrepancy([[1.5]]), ValueError, "Sample is not in unit hypercube"),
    (lambda: lowdisc.discrepancy([[0.5]], method="XD"), ValueError,
     "'XD' is not a valid method"),
    (lambda: lowdisc.discrepancy([[0.5]], workers=0), ValueError,
     "Invalid number of workers"),
    (lambda: lowdisc.discrepancy(np.array([["a"]])), TypeError, "real numbers"),
    (lambda: lowdisc.discrepancy(np.zeros((2, 2), dtype=complex)), TypeError,
     "real numbers"),
    (lambda: lowdisc.geometric_discrepancy([[0.5, 0.5]]), ValueError,
     "at least two points"),
    (lambda: lowdisc.min_distance([[0.5], [0.2]], metric="cosine"), ValueError,
     "metric must be one of"),
    (lambda: lowdisc.power_spectrum([[0.5, 0.5, 0.5]]), ValueError, "2-dimensional"),
    (lambda: lowdisc.star_bounds([[0.5]], grid_cells=0), ValueError,
     "grid_cells must be at least 1"),
])
def test_bad_arguments_raise_clear_errors(call, error, message):
    with pytest.raises(error, match=message):
        call()


def test_the_extension_checks_arrays_itself():
    x = np.random.default_rng(0).random((8, 4))
    with pytest.raises(ValueError, match="C-contiguous"):
        _lowdisc.discrepancy(x[:, ::2], "CD", False, 1)
    with pytest.raises(TypeError, match="dtype float64, got float32"):
        _lowdisc.discrepancy(x.astype(np.float32), "CD", False, 1)
    with pytest.raises(TypeError, match="must be a numpy array, got list"):
        _lowdisc.min_distance([[0.5]], "euclidean")
    with pytest.raises(ValueError, match="2-D array, got 1"):
        _lowdisc.star_discrepancy(x[0], 1e9)
    with pytest.raises(ValueError, match="not finite"):
        _lowdisc.discrepancy(np.full((2, 2), np.nan), "CD", False, 1)
    with pytest.raises(ValueError, match="outside"):
        _lowdisc.star_discrepancy(np.full((2, 2), -1.0), 1e9)
    with pytest.raises(TypeError, match="dtype uint32"):
        _lowdisc.pixel_samples("sobol", 4, (2, 2), np.zeros((1, 2), dtype=np.int64), 2, 0)
    with pytest.raises(ValueError, match=r"shape \(p, 2\)"):
        _lowdisc.pixel_samples("sobol", 4, (2, 2), np.zeros((1, 3), dtype=np.uint32), 2, 0)
    out = np.empty((1, 2))
    with pytest.raises(OverflowError):
        _lowdisc.points_into(out, "sobol", -1, "gray", "none", 0, 32)
    with pytest.raises(ValueError, match="unknown sequence"):
        _lowdisc.points_into(out, "sobel", 0, "gray", "none", 0, 32)
    with pytest.raises(TypeError, match="out must have dtype float64, float32 or uint32"):
        _lowdisc.points_into(out.astype(np.int16), "sobol", 0, "gray", "none", 0, 32)
    with pytest.raises(ValueError, match="2-D"):
        _lowdisc.points_into(np.empty(3), "sobol", 0, "gray", "none", 0, 32)
    with pytest.raises(ValueError, match="writeable"):
        frozen = np.empty((2, 2))
        frozen.flags.writeable = False
        _lowdisc.points_into(frozen, "sobol", 0, "gray", "none", 0, 32)


def test_non_contiguous_input_is_copied_by_the_package():
    x = np.random.default_rng(0).random((64, 4))
    assert lowdisc.discrepancy(x[:, ::2]) == lowdisc.discrepancy(np.ascontiguousarray(x[:, ::2]))


def test_empty_requests_give_empty_arrays():
    assert lowdisc.sobol(0, 3).shape == (0, 3)
    assert lowdisc.halton(5, 0).shape == (5, 0)
    assert lowdisc.pixel_samples("zsobol", 2, (2, 2), np.zeros((0, 2), dtype=int), 4).shape \
        == (0, 2, 4)
