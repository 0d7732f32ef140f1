"""Drop-in engines for ``scipy.stats.qmc``: :class:`Sobol` and :class:`Halton`.

Both subclass ``scipy.stats.qmc.QMCEngine`` when scipy is installed (without
it, a small base class with the same ``random``/``reset``/``fast_forward``
methods is used), so they work with ``scipy.stats.qmc.scale``,
``scipy.integrate.qmc_quad`` and everything else that takes an engine.

Differences from scipy, by design:

* ``scramble=True`` means lowdisc's **Owen** (nested uniform) scrambling by
  default (``randomize="owen"``; also ``"owen-per-digit"``, ``"fast-owen"``,
  ``"xor"``, as in :func:`lowdisc.sobol`), not scipy's linear matrix
  scramble plus digital shift.
* ``scramble=False`` gives exactly scipy's numbers for ``bits <= 32``;
  lowdisc's Sobol has 32 digits, so ``bits > 32`` raises ``ValueError``.
* ``fast_forward`` is O(1): points are computed from their index.
* An integer ``seed``/``rng`` is lowdisc's seed itself, so
  ``Sobol(d, seed=7).random(n)`` equals
  ``lowdisc.sobol(n, d, scramble="owen", seed=7)`` (up to ``bits``); a numpy
  ``Generator`` gives one 64-bit seed drawn from it.
"""

from __future__ import annotations

import copy
import operator
import warnings
from typing import Any

import numpy as np

from . import _checks, _lowdisc

try:
    from scipy.stats.qmc import QMCEngine as _Base
except ImportError:  # scipy is optional

    class _Base:  # type: ignore[no-redef]
        """The part of scipy's ``QMCEngine`` the engines here rely on."""

        def _initialize(self, d: int, *, optimization: Any = None, rng: Any = None) -> None:
            if optimization is not None:
                raise ValueError("optimization needs scipy")
            self.d = d
            self.rng = rng if isinstance(rng, np.random.Generator) else np.random.default_rng(rng)
            self.rng_seed = copy.deepcopy(self.rng)
            self.num_generated = 0

        def random(self, n: int = 1, *, workers: int = 1) -> np.ndarray:
            sample = self._random(n, workers=workers)
            self.num_generated += n
            return sample

        def reset(self) -> Any:
            self.rng = copy.deepcopy(self.rng_seed)
            self.num_generated = 0
            return self


def _lowdisc_seed(given: Any, rng: Any) -> int:
    """lowdisc's 64-bit seed: an integer as given, else one drawn from ``rng``."""
    if given is not None and not isinstance(given, bool):
        try:
            return operator.index(given) % 2**64
        except TypeError:
            pass
    if isinstance(rng, np.random.Generator):
        return int(rng.integers(0, 2**64, dtype=np.uint64))
    return int(rng.randint(0, 2**64, dtype=np.uint64))


def _rng_argument(rng: Any, seed: Any) -> Any:
    if seed is not None:
        if rng is not None:
            raise TypeError("give rng or seed, not both")
        return seed
    return rng


def _dimension(d: Any, limit: int) -> int:
    if isinstance(d, bool) or not isinstance(d, (int, np.integer)) or d < 1:
        raise ValueError("d must be a positive integer value")
    if d > limit:
        raise ValueError(f"Maximum supported dimensionality is {limit}.")
    return int(d)


class Sobol(_Base):
    """scipy.stats.qmc.Sobol with lowdisc's Sobol (Joe & Kuo, Gray-code order).

    ``randomize``: the scramble used when ``scramble=True``: ``"owen"``
    (nested uniform, exact in distribution, a few hashes per value, eight
    dimensions per instruction on CPUs with AVX-512),
    ``"owen-per-digit"`` (the same law, the renderer's ``sobol-owen``
    values), ``"fast-owen"`` (hash-based) or ``"xor"`` (random digital shift).
    """

    MAXDIM: int = _lowdisc.SOBOL_DIMENSIONS

    def __init__(self, d: int, *, scramble: bool = True, bits: int | None = None,
                 rng: Any = None, seed: Any = None, optimization: str | None = None,
                 randomize: str = "owen") -> None:
        rng = _rng_argument(rng, seed)
        d = _dimension(d, self.MAXDIM)
        bits = 30 if bits is None else _checks.integer(bits, "bits", low=1)
        if bits > 32:
            raise ValueError(f"lowdisc's Sobol points have 32 digits: bits must be at most 32, "
                             f"got {bits}")
        randomize = _checks.choice(randomize, "randomize",
                                   ("owen", "owen-per-digit", "fast-owen", "xor"))
        # Used by scipy.integrate.qmc_quad to make independent copies.
        self._init_quad = {"d": d, "scramble": True, "bits": bits,
                           "optimization": optimization, "randomize": randomize}
        super()._initialize(d=d, optimization=optimization, rng=rng)
        self.bits = bits
        self.maxn = 2**bits
        self.scramble = bool(scramble)
        self.randomize = randomize if self.scramble else "none"
        self._seed = _lowdisc_seed(rng, self.rng) if self.scramble else 0

    def _random(self, n: int = 1, *, workers: int = 1) -> np.ndarray:
        n = _checks.integer(n, "n")
        total = self.num_generated + n
        if total > self.maxn:
            msg = (f"At most 2**{self.bits}={self.maxn} distinct points can be generated. "
                   f"{self.num_generated} points have been previously generated, then: "
                   f"n={self.num_generated}+{n}={total}. ")
            if self.bits != 32:
                msg += "Consider increasing `bits`."
            raise ValueError(msg)
        if self.num_generated == 0 and n & (n - 1) != 0:
            warnings.warn("The balance properties of Sobol' points require n to be a power of 2.",
                          stacklevel=3)
        return _lowdisc.points("sobol", n, self.d, self.num_generated, "gray", self.randomize,
                               self._seed, self.bits, "float64")

    def random_base2(self, m: int) -> np.ndarray:
        """Draw ``2**m`` points; the total drawn must stay a power of 2."""
        n = 2 ** _checks.integer(m, "m")
        total = self.num_generated + n
        if total & (total - 1) != 0:
            raise ValueError("The balance properties of Sobol' points require "
                             f"n to be a power of 2. {self.num_generated} points "
                             "have been previously generated, then: "
                             f"n={self.num_generated}+2**{m}={total}. "
                             "If you still want to do this, the function "
                             "'Sobol.random()' can be used.")
        return self.random(n)

    def reset(self) -> Sobol:
        """Back to the first point (same scramble)."""
        super().reset()
        return self

    def fast_forward(self, n: int) -> Sobol:
        """Skip ``n`` points, in constant time."""
        self.num_generated += _checks.integer(n, "n")
        return self


class Halton(_Base):
    """scipy.stats.qmc.Halton with lowdisc's Halton (at most 1024 dimensions).

    ``scramble=False`` is the radical-inverse sequence, as scipy's; with
    ``scramble=True`` the ``randomize`` scramble is ``"owen"`` (nested, in
    each base) or ``"permute"`` (random digit permutations, as pbrt-v4),
    not scipy's permutations.
    """

    MAXDIM: int = _lowdisc.HALTON_DIMENSIONS

    def __init__(self, d: int, *, scramble: bool = True, rng: Any = None, seed: Any = None,
                 optimization: str | None = None, randomize: str = "owen") -> None:
        rng = _rng_argument(rng, seed)
        d = _dimension(d, self.MAXDIM)
        randomize = _checks.choice(randomize, "randomize", ("owen", "permute"))
        self._init_quad = {"d": d, "scramble": True, "optimization": optimization,
                           "randomize": randomize}
        super()._initialize(d=d, optimization=optimization, rng=rng)
        self.scramble = bool(scramble)
        self.randomize = randomize if self.scramble else "none"
        self._seed = _lowdisc_seed(rng, self.rng) if self.scramble else 0

    def _random(self, n: int = 1, *, workers: int = 1) -> np.ndarray:
        _checks.workers(workers)
        n = _checks.integer(n, "n")
        return _lowdisc.points("halton", n, self.d, self.num_generated, "gray", self.randomize,
                               self._seed, 32, "float64")

    def fast_forward(self, n: int) -> Halton:
        """Skip ``n`` points, in constant time."""
        self.num_generated += _checks.integer(n, "n")
        return self
