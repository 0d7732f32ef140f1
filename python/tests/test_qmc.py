"""lowdisc.qmc engines: scipy's QMCEngine protocol, bit identity with scipy's
unscrambled Sobol, scipy's warnings and errors, scale and qmc_quad."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import lowdisc
from lowdisc import qmc

scipy_qmc = pytest.importorskip("scipy.stats.qmc")
from scipy.integrate import qmc_quad  # noqa: E402


def test_engines_are_scipy_engines():
    assert issubclass(qmc.Sobol, scipy_qmc.QMCEngine)
    assert issubclass(qmc.Halton, scipy_qmc.QMCEngine)


@pytest.mark.parametrize("bits", [None, 10, 30, 32])
def test_unscrambled_sobol_is_scipys_bit_for_bit(bits):
    ours, theirs = qmc.Sobol(12, scramble=False, bits=bits), scipy_qmc.Sobol(12, scramble=False, bits=bits)
    assert np.array_equal(ours.random_base2(6), theirs.random_base2(6))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert np.array_equal(ours.random(37), theirs.random(37))
    ours.fast_forward(100), theirs.fast_forward(100)
    assert np.array_equal(ours.random(27), theirs.random(27))
    assert ours.num_generated == theirs.num_generated == 228
    ours.reset(), theirs.reset()
    assert np.array_equal(ours.random(8), theirs.random(8))


def test_scrambling_is_owen_and_reproducible():
    engine = qmc.Sobol(4, seed=7)
    first = engine.random(256)
    # scipy's default bits = 30: the 30 leading digits of lowdisc's points.
    assert np.array_equal(first, lowdisc.sobol(256, 4, scramble="owen", seed=7)
                          // 2.0**-30 * 2.0**-30)
    assert np.array_equal(engine.reset().random(256), first)
    assert np.array_equal(qmc.Sobol(4, seed=7).fast_forward(100).random(156), first[100:])
    fast = qmc.Sobol(4, seed=7, randomize="fast-owen").random(256)
    assert np.array_equal(fast, lowdisc.sobol(256, 4, scramble="fast-owen", seed=7)
                          // 2.0**-30 * 2.0**-30)
    per_digit = qmc.Sobol(4, seed=7, randomize="owen-per-digit").random(256)
    assert np.array_equal(per_digit, lowdisc.sobol(256, 4, scramble="owen-per-digit", seed=7)
                          // 2.0**-30 * 2.0**-30)
    g1 = qmc.Sobol(3, rng=np.random.default_rng(5)).random(16)
    g2 = qmc.Sobol(3, rng=np.random.default_rng(5)).random(16)
    assert np.array_equal(g1, g2)


@pytest.mark.parametrize("randomize", ["owen", "owen-per-digit", "fast-owen", "xor"])
def test_random_streams_and_fast_forward_jumps(randomize):
    # random(n) twice is random(2n); fast_forward(k) then random(m) is the
    # window k..k+m of one long draw, at any k (the call does no work).
    whole = qmc.Sobol(6, seed=3, randomize=randomize).random(4096)
    engine = qmc.Sobol(6, seed=3, randomize=randomize)
    assert np.array_equal(np.vstack([engine.random(2048), engine.random(2048)]), whole)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for k, m in [(1, 5), (1000, 3000), (2**29 - 7, 7)]:
            jumped = qmc.Sobol(6, seed=3, randomize=randomize).fast_forward(k)
            window = jumped.random(m)
            assert jumped.num_generated == k + m
            want = lowdisc.sobol(m, 6, start=k, scramble=randomize, seed=3) // 2.0**-30 * 2.0**-30
            assert np.array_equal(window, want)
            if k + m <= 4096:
                assert np.array_equal(window, whole[k:k + m])


def test_scipys_power_of_two_warning_and_errors():
    engine = qmc.Sobol(2, seed=1)
    with pytest.warns(UserWarning, match="balance properties"):
        engine.random(10)
    with pytest.raises(ValueError, match="n to be a power of 2. 10 points"):
        engine.random_base2(2)
    small = qmc.Sobol(2, bits=3, seed=1)
    small.random(8)
    with pytest.raises(ValueError, match=r"At most 2\*\*3=8 distinct points"):
        small.random(1)
    with pytest.raises(ValueError, match="bits must be at most 32"):
        qmc.Sobol(2, bits=33)
    with pytest.raises(ValueError, match="Maximum supported dimensionality is 21201"):
        qmc.Sobol(21202)


def test_fast_forward_is_constant_time():
    engine = qmc.Sobol(3, scramble=False, bits=32)
    engine.fast_forward(2**31)  # drawing 2^31 points would take minutes
    assert np.array_equal(engine.random(4), lowdisc.sobol(4, 3, start=2**31))


def test_halton_continues_and_matches_the_function():
    engine = qmc.Halton(5, seed=3)
    a, b = engine.random(100), engine.random(50)
    assert np.array_equal(np.vstack([a, b]), lowdisc.halton(150, 5, scramble="owen", seed=3))
    plain = qmc.Halton(3, scramble=False).random(500)
    assert np.max(np.abs(plain - scipy_qmc.Halton(3, scramble=False).random(500))) <= 2.0**-52


def test_scale_integers_and_qmc_quad_work():
    sample = qmc.Sobol(2, seed=1).random(8)
    scaled = scipy_qmc.scale(sample, [0, 2], [10, 5])
    assert np.all((scaled[:, 0] >= 0) & (scaled[:, 0] < 10) & (scaled[:, 1] >= 2))
    ints = qmc.Sobol(2, seed=1).integers([0, 0], u_bounds=[4, 4], n=16)
    assert len({tuple(p) for p in ints}) == 16  # a (0,4,2)-net: one point per cell
    result = qmc_quad(lambda x: np.prod(x, axis=0), [0, 0, 0], [1, 1, 1],
                      qrng=qmc.Sobol(3, seed=2), n_points=1024)
    assert abs(result.integral - 0.125) < 5 * result.standard_error + 1e-9
    assert result.standard_error < 1e-4


def test_scipys_subclassing_pattern_and_optimization_work():
    class Shifted(qmc.Sobol):
        def _random(self, n=1, *, workers=1):
            return (super()._random(n, workers=workers) + 0.5) % 1.0

    x = Shifted(2, scramble=False).random(4)
    assert np.array_equal(x, (lowdisc.sobol(4, 2) + 0.5) % 1.0)
    optimized = qmc.Sobol(2, seed=1, optimization="random-cd").random(16)
    assert optimized.shape == (16, 2)
