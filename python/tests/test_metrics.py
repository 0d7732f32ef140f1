"""Metrics: scipy's discrepancies to 1e-12 relative (and closer to an
extended-precision evaluation than scipy where they differ), analytic values
of the star discrepancy, distances and spectra."""

from __future__ import annotations

import numpy as np
import pytest

import lowdisc

scipy_qmc = pytest.importorskip("scipy.stats.qmc")

METHODS = ["CD", "WD", "MD", "L2-star"]


def reference(x, method, iterative=False):
    """The discrepancy from its formula (Zhou et al. 2013; Warnock 1972) in
    numpy's extended precision: what both implementations approximate."""
    x = x.astype(np.longdouble)
    n, d = x.shape
    m = n + 1 if iterative else n
    z = np.abs(x - 0.5)
    ld = np.longdouble
    if method == "CD":
        c, single = (ld(13) / 12) ** d, np.prod(1 + z / 2 - z**2 / 2, axis=1)
    elif method == "WD":
        c, single = -(ld(4) / 3) ** d, np.zeros(n, dtype=ld)
    elif method == "MD":
        c, single = (ld(19) / 12) ** d, np.prod(ld(5) / 3 - z / 4 - z**2 / 4, axis=1)
    else:
        c, single = ld(1) / ld(3) ** d, np.prod(1 - x**2, axis=1) / ld(2) ** d
    pairs = ld(0)
    for i in range(0, n, 64):  # blocks of rows keep memory small
        xi, zi = x[i:i + 64, None, :], z[i:i + 64, None, :]
        dist = np.abs(xi - x[None, :, :])
        if method == "CD":
            pair = 1 + zi / 2 + z / 2 - dist / 2
        elif method == "WD":
            pair = ld(3) / 2 - dist + dist**2
        elif method == "MD":
            pair = ld(15) / 8 - zi / 4 - z / 4 - 3 * dist / 4 + dist**2 / 2
        else:
            pair = 1 - np.maximum(xi, x[None, :, :])
        pairs += np.prod(pair, axis=2).sum()
    value = c - 2 * single.sum() / m + pairs / m**2
    return np.sqrt(value) if method == "L2-star" else value


EXTENDED = np.finfo(np.longdouble).eps < np.finfo(np.float64).eps


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("iterative", [False, True])
def test_discrepancies_equal_scipys(method, iterative):
    rng = np.random.default_rng(7)
    for n, d in [(1, 1), (37, 2), (200, 3), (128, 5)]:
        x = rng.random((n, d))
        ours = lowdisc.discrepancy(x, method=method, iterative=iterative)
        theirs = scipy_qmc.discrepancy(x, method=method, iterative=iterative)
        # scipy's MD multiplies rounded constants (5/3, 15/8 - ...), which
        # shifts it by up to about 2e-12 relative; lowdisc's does not.
        tolerance = 5e-12 if method == "MD" else 1e-12
        assert ours == pytest.approx(theirs, rel=tolerance, abs=0), (n, d)
        if EXTENDED:
            exact = reference(x, method, iterative)
            assert abs(ours - exact) <= 2e-13 * abs(exact), (n, d)


def test_discrepancies_at_1024_by_8_are_as_close_to_the_formula_as_scipys():
    if not EXTENDED:
        pytest.skip("numpy's longdouble is double on this platform")
    x = np.random.default_rng(2).random((1024, 8))
    for method in METHODS:
        exact = reference(x, method)
        ours = lowdisc.discrepancy(x, method=method)
        theirs = scipy_qmc.discrepancy(x, method=method)
        assert abs(ours - exact) <= 1e-12 * abs(exact), method
        assert abs(ours - exact) <= abs(theirs - exact), method


def test_geometric_discrepancy_equals_scipys_and_handles_duplicates():
    x = np.random.default_rng(3).random((300, 3))
    assert lowdisc.geometric_discrepancy(x) == pytest.approx(
        scipy_qmc.geometric_discrepancy(x), rel=1e-14)
    assert lowdisc.geometric_discrepancy(x, method="mst") == pytest.approx(
        scipy_qmc.geometric_discrepancy(x, method="mst"), rel=1e-14)
    doubled = np.vstack([x, x[:5]])
    with pytest.warns(UserWarning, match="duplicate"):
        ours = lowdisc.geometric_discrepancy(doubled)
    with pytest.warns(UserWarning, match="duplicate"):
        theirs = scipy_qmc.geometric_discrepancy(doubled)
    assert ours == pytest.approx(theirs, rel=1e-14)


def test_star_discrepancy_analytic_values():
    # 1-D: n equispaced centres (2i+1)/2n have D* = 1/(2n).
    n = 100
    assert lowdisc.star_discrepancy(((np.arange(n) + 0.5) / n)[:, None]) == pytest.approx(0.005)
    # One point p in 2-D: D* = max(1 - p1 p2 (closed box [0,p] holds it), the
    # open boxes that miss it: largest volume 1 * max(p1, p2)).
    p = np.array([[0.3, 0.6]])
    assert lowdisc.star_discrepancy(p) == pytest.approx(max(1 - 0.18, 0.6))


def test_star_bounds_bracket_the_exact_value():
    x = lowdisc.sobol(512, 2, scramble="owen", seed=5)
    exact = lowdisc.star_discrepancy(x)
    b = lowdisc.star_bounds(x)
    assert b.lower <= exact <= b.upper
    assert lowdisc.star_discrepancy(x, exact=False) == b.lower
    assert "grid" in b.upper_method


def test_exact_star_discrepancy_refuses_unaffordable_work():
    x = lowdisc.sobol(4096, 6)
    with pytest.raises(ValueError, match="star_bounds"):
        lowdisc.star_discrepancy(x, max_work=1e6)
    assert lowdisc.star_work(4096, 6) > 1e6


def test_toroidal_distance_wraps_around():
    x = np.array([[0.02, 0.5], [0.98, 0.5], [0.5, 0.1]])
    # Euclidean: (0.5, 0.1) is sqrt(0.48^2 + 0.4^2) from the first point.
    assert lowdisc.min_distance(x) == pytest.approx(np.hypot(0.48, 0.4))
    assert lowdisc.min_distance(x, metric="toroidal") == pytest.approx(0.04)
    nn = lowdisc.nearest_neighbour_distances(x, metric="toroidal")
    assert nn[:2] == pytest.approx([0.04, 0.04])


def test_power_spectrum_of_white_noise_is_flat_near_one():
    x = lowdisc.independent(4096, 2, seed=1)
    radii, power, counts = lowdisc.power_spectrum(x, max_frequency=32)
    assert list(radii) == list(range(1, 33)) and counts.sum() > 0
    assert abs(power[8:].mean() - 1) < 0.1
    # A Sobol net is far below white noise at low frequencies.
    _, sobol_power, _ = lowdisc.power_spectrum(lowdisc.sobol(4096, 2), max_frequency=32)
    assert sobol_power[:4].mean() < 0.1


@pytest.mark.parametrize("method", ["CD", "WD", "MD", "L2-star"])
def test_discrepancy_is_the_same_bits_for_every_worker_count(method):
    # workers runs the sums on that many threads (-1: all cores); the chunks
    # are fixed, so every count gives the same value bit for bit.
    x = lowdisc.sobol(6000, 5, scramble="owen", seed=2)
    values = {w: lowdisc.discrepancy(x, method=method, workers=w) for w in (1, 2, 3, -1)}
    assert len(set(values.values())) == 1, values
    assert (lowdisc.discrepancy(x, method=method, iterative=True, workers=1)
            == lowdisc.discrepancy(x, method=method, iterative=True, workers=4))
    for bad in (0, -2):
        with pytest.raises(ValueError, match="Invalid number of workers"):
            lowdisc.discrepancy(x, method=method, workers=bad)


LONG_METRICS = {
    # A pair sum of about a minute.
    "discrepancy": ("x = np.random.default_rng(0).random((120_000, 8))\n"
                    "lowdisc.discrepancy(x, max_work=None, workers=-1)\n"),
    # The exact star discrepancy of 3-D points, minutes (its recursion).
    "star_discrepancy": ("x = np.random.default_rng(0).random((60_000, 3))\n"
                         "lowdisc.star_discrepancy(x, max_work=1e15)\n"),
    # The 2-D sweep alone, about ten seconds on two idle cores.
    "star_discrepancy_2d": ("x = np.random.default_rng(0).random((700_000, 2))\n"
                            "lowdisc.star_discrepancy(x, max_work=1e11)\n"),
    # The bounds' random boxes and threshold accepting: about a minute.
    "star_bounds": ("x = np.random.default_rng(0).random((2_000_000, 3))\n"
                    "lowdisc.star_bounds(x)\n"),
    # In 20-D the distance grid has one cell: every point scans all others
    # (n^2 d, many minutes).
    "min_distance": ("x = np.random.default_rng(0).random((200_000, 20))\n"
                     "lowdisc.min_distance(x)\n"),
    "nearest_neighbour_distances": ("x = np.random.default_rng(0).random((200_000, 20))\n"
                                    "lowdisc.nearest_neighbour_distances(x, metric='toroidal')\n"),
    # n K^2 with K = 4096: tens of seconds.
    "power_spectrum": ("x = np.random.default_rng(0).random((1_000, 2))\n"
                       "lowdisc.power_spectrum(x, max_frequency=4096)\n"),
}


@pytest.mark.parametrize("metric", sorted(LONG_METRICS))
def test_a_long_metric_stops_at_ctrl_c(metric):
    # Interrupted after one second: the interpreter gets KeyboardInterrupt
    # within a few seconds.
    import signal
    import subprocess
    import sys
    import time

    script = ("import numpy as np, lowdisc\n"
              "print('start', flush=True)\n"
              + LONG_METRICS[metric] +
              "print('finished')\n")
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
    assert child.stdout.readline() == "start\n"
    time.sleep(1.0)
    child.send_signal(signal.SIGINT)
    sent = time.monotonic()
    out, err = child.communicate(timeout=60)
    assert "KeyboardInterrupt" in err, err
    assert "finished" not in out
    assert time.monotonic() - sent < 5


def test_discrepancy_refuses_work_above_max_work():
    x = np.random.default_rng(1).random((2000, 4))
    with pytest.raises(ValueError, match="more than max_work"):
        lowdisc.discrepancy(x, max_work=1e6)
    assert lowdisc.discrepancy(x, max_work=None) == lowdisc.discrepancy(x)


def test_patching_scipys_geometric_discrepancy_with_lowdiscs_does_not_loop(monkeypatch):
    # lowdisc hands "mst" to scipy's function, bound when lowdisc was
    # imported: replacing scipy's name by lowdisc's later cannot recurse.
    x = np.random.default_rng(4).random((50, 3))
    want = scipy_qmc.geometric_discrepancy(x, method="mst")
    monkeypatch.setattr(scipy_qmc, "geometric_discrepancy", lowdisc.geometric_discrepancy)
    assert scipy_qmc.geometric_discrepancy(x, method="mst") == want
