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


def test_engines_are_scipy_engines_and_every_scipy_name_is_here():
    assert issubclass(qmc.Sobol, scipy_qmc.QMCEngine)
    assert issubclass(qmc.Halton, scipy_qmc.QMCEngine)
    assert lowdisc.qmc is qmc
    assert set(qmc.__all__) == set(scipy_qmc.__all__)
    for name in scipy_qmc.__all__:
        assert hasattr(qmc, name), name
    assert qmc.LatinHypercube is scipy_qmc.LatinHypercube
    assert qmc.discrepancy is lowdisc.discrepancy


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


def thirty_digits(x):
    """scipy's default bits = 30: the 30 leading digits of lowdisc's points."""
    return x // 2.0**-30 * 2.0**-30


def test_scrambling_is_owen_and_reproducible():
    engine = qmc.Sobol(4, rng=7)
    first = engine.random(256)
    seed = engine.lowdisc_seed
    assert np.array_equal(first, thirty_digits(lowdisc.sobol(256, 4, scramble="owen-tree",
                                                             seed=seed)))
    assert np.array_equal(engine.reset().random(256), first)
    assert np.array_equal(qmc.Sobol(4, rng=7).fast_forward(100).random(156), first[100:])
    for randomize in ("owen", "fast-owen", "xor", "lms"):
        engine = qmc.Sobol(4, rng=7, randomize=randomize)
        assert engine.lowdisc_seed == seed
        assert np.array_equal(engine.random(256), thirty_digits(
            lowdisc.sobol(256, 4, scramble=randomize, seed=seed)))
    g1 = qmc.Sobol(3, rng=np.random.default_rng(5)).random(16)
    g2 = qmc.Sobol(3, rng=np.random.default_rng(5)).random(16)
    assert np.array_equal(g1, g2)


def test_rng_follows_scipys_rules():
    # An integer rng is default_rng(rng) (its whole value counts); the legacy
    # integer seed is RandomState(seed); the scramble is one 64-bit draw.
    big = 2**64 + 5
    assert qmc.Sobol(2, rng=big).lowdisc_seed == int(
        np.random.default_rng(big).spawn(1)[0].integers(0, 2**64, dtype=np.uint64))
    assert qmc.Sobol(2, rng=big).lowdisc_seed != qmc.Sobol(2, rng=5).lowdisc_seed
    assert qmc.Sobol(2, seed=5).lowdisc_seed == int(
        np.random.default_rng(5).integers(0, 2**64, dtype=np.uint64))
    assert qmc.Sobol(2, seed=np.random.RandomState(5)).lowdisc_seed == int(
        np.random.RandomState(5).randint(0, 2**64, dtype=np.uint64))
    for rng in (np.random.SeedSequence(4), np.random.PCG64(4), np.random.default_rng(4)):
        assert qmc.Halton(3, rng=rng).lowdisc_seed == qmc.Halton(
            3, rng=np.random.default_rng(4)).lowdisc_seed
    with pytest.raises(TypeError, match="got multiple values for argument now known as `rng`"):
        qmc.Halton(2, rng=1, seed=1)


@pytest.mark.parametrize("randomize", ["owen-tree", "owen", "fast-owen", "xor", "lms"])
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
            want = lowdisc.sobol(m, 6, start=k, scramble=randomize, seed=engine.lowdisc_seed)
            assert np.array_equal(window, thirty_digits(want))
            if k + m <= 4096:
                assert np.array_equal(window, whole[k:k + m])


def test_dtype_out_and_replications():
    engine = qmc.Sobol(3, rng=2, bits=32)
    x = engine.random(64)
    # float32 keeps the 24 leading digits (truncated, never rounded up to 1).
    assert np.array_equal(engine.reset().random(64, dtype=np.float32),
                          (x // 2.0**-24 * 2.0**-24).astype(np.float32))
    out = np.empty((64, 3), dtype=np.uint32)
    assert engine.reset().random(64, out=out) is out
    assert np.array_equal(out / 2.0**32, x)
    reps = engine.reset().random(64, replications=5)
    assert reps.shape == (5, 64, 3) and engine.num_generated == 64
    assert np.array_equal(reps[0], x)
    seeds = [engine.lowdisc_seed] + [int(np.random.SeedSequence(
        engine.lowdisc_seed, spawn_key=(r,)).generate_state(1, np.uint64)[0]) for r in (1, 2)]
    for r, seed in enumerate(seeds):
        assert np.array_equal(reps[r], lowdisc.sobol(64, 3, scramble="owen-tree", seed=seed))
    assert np.array_equal(reps, lowdisc.sobol(64, 3, scramble="owen-tree",
                                              seed=engine.lowdisc_seed, replications=5))
    assert np.array_equal(qmc.Halton(2, scramble=False).random(4, replications=2)[1],
                          lowdisc.halton(4, 2))


def test_zero_dimensions_and_long_jumps():
    assert qmc.Sobol(0).random(4).shape == (4, 0)
    assert qmc.Halton(0, scramble=False).random(3, dtype=np.float32).shape == (3, 0)
    with pytest.raises(ValueError, match="do not exist"):
        qmc.Halton(2).fast_forward(2**64).random(1)
    with pytest.raises(ValueError, match="2\\*\\*32 points"):
        qmc.Sobol(2, scramble=False, bits=40).fast_forward(2**32).random(1)
    wide = qmc.Halton(2000, rng=1).random(8)
    assert wide.shape == (8, 2000) and 0 <= wide.min() and wide.max() < 1


def test_bits_beyond_32_are_unscrambled_only():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        x = qmc.Sobol(3, scramble=False, bits=64).random(100)
    assert np.array_equal(x, lowdisc.sobol(100, 3))
    with pytest.raises(ValueError, match="at most 32 with scramble=True"):
        qmc.Sobol(2, bits=40)
    with pytest.raises(ValueError, match="Maximum supported 'bits' is 64"):
        qmc.Sobol(2, bits=65, scramble=False)


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
    assert np.array_equal(np.vstack([a, b]), lowdisc.halton(150, 5, scramble="owen",
                                                            seed=engine.lowdisc_seed))
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
