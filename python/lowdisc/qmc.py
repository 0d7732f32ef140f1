"""``scipy.stats.qmc`` with lowdisc's engines and metrics.

Every public name of ``scipy.stats.qmc`` is here: :class:`Sobol`,
:class:`Halton`, :func:`discrepancy`, :func:`geometric_discrepancy` and
:func:`update_discrepancy` are lowdisc's; ``scale``, ``QMCEngine``,
``LatinHypercube``, ``PoissonDisk``, ``MultinomialQMC`` and
``MultivariateNormalQMC`` are scipy's own (the last two take lowdisc's
engines through their ``engine=`` argument). So ``from lowdisc import qmc``
can replace ``from scipy.stats import qmc``; scipy's own test suite of the
module passes against it, apart from the tests listed in ``docs/guide/python.md``.

The engines subclass ``scipy.stats.qmc.QMCEngine`` when scipy is installed
(without it, a small base class with the same ``random``/``integers``-free
protocol is used and scipy's names are missing), so they work with
``scipy.integrate.qmc_quad`` and everything else that takes an engine.

Randomness (``rng``/``seed``) follows scipy exactly: ``rng`` is normalised
by ``numpy.random.default_rng`` (``None``, an integer of any size, a
``SeedSequence``, a ``BitGenerator`` or a ``Generator``) and the engine
owns a child generator spawned from it; the legacy ``seed`` keyword takes
``None`` or an integer (``default_rng(seed)`` itself, not a child, so
``seed=5`` and ``rng=5`` differ, as in scipy), a ``RandomState`` or a
``Generator`` (spawned); giving both is a ``TypeError``. The scramble is
then one 64-bit draw from the engine's generator, ``integers(0, 2**64,
dtype=uint64)`` (``randint`` for a ``RandomState``), kept as the engine's
``lowdisc_seed``: ``Sobol(d, rng=7).random(n)`` is ``lowdisc.sobol(n, d,
scramble="owen-tree", seed=Sobol(d, rng=7).lowdisc_seed)`` to ``bits``.

Differences from scipy, by design:

* ``scramble=True`` means Owen's nested uniform scrambling (``randomize``,
  default ``"owen-tree"`` for Sobol, ``"owen"`` for Halton), not scipy's
  linear matrix scramble plus digital shift (``randomize="lms"`` is that
  kind of scramble, with other values). So scrambled values differ from
  scipy's for the same ``rng``.
* ``scramble=False`` gives scipy's Sobol numbers bit for bit and scipy's
  Halton numbers to 1 ulp. lowdisc's Sobol points have 32 digits and the
  sequence 2**32 points: ``bits`` up to 64 is accepted unscrambled (the
  digits past 32 are zero, as scipy's for those points); scrambled,
  ``bits`` must be at most 32.
* ``fast_forward`` is O(1): points are computed from their index.
* ``random`` also takes ``dtype`` (float64, float32, uint32), ``out`` and
  ``replications`` (independent scrambles, shape ``(R, n, d)``).
"""

from __future__ import annotations

import copy
import operator
import warnings
from typing import Any

import numpy as np
import numpy.typing as npt

from . import _checks, _lowdisc
from ._metrics import discrepancy, geometric_discrepancy, update_discrepancy

try:
    from scipy.stats import qmc as _scipy_qmc
except ImportError:  # scipy is optional
    _scipy_qmc = None

__all__ = ["scale", "discrepancy", "geometric_discrepancy", "update_discrepancy",
           "QMCEngine", "Sobol", "Halton", "LatinHypercube", "PoissonDisk",
           "MultinomialQMC", "MultivariateNormalQMC"]

#: The names that are scipy's own (present when scipy is installed).
SCIPY_NAMES = ("scale", "QMCEngine", "LatinHypercube", "PoissonDisk", "MultinomialQMC",
               "MultivariateNormalQMC")

if _scipy_qmc is not None:
    scale = _scipy_qmc.scale
    QMCEngine = _scipy_qmc.QMCEngine
    LatinHypercube = _scipy_qmc.LatinHypercube
    PoissonDisk = _scipy_qmc.PoissonDisk
    MultinomialQMC = _scipy_qmc.MultinomialQMC
    MultivariateNormalQMC = _scipy_qmc.MultivariateNormalQMC
    _Base: Any = QMCEngine
else:

    class _Base:  # type: ignore[no-redef]
        """The part of scipy's ``QMCEngine`` the engines here rely on."""

        def _initialize(self, d: int, *, optimization: Any = None, rng: Any = None) -> None:
            if optimization is not None:
                raise ValueError("optimization needs scipy")
            self.d = d
            if isinstance(rng, np.random.Generator):
                self.rng = rng.spawn(1)[0]
            elif isinstance(rng, np.random.RandomState):
                self.rng = rng
            else:
                self.rng = np.random.default_rng(rng)
            self.rng_seed = copy.deepcopy(self.rng)
            self.num_generated = 0
            self.optimization_method = None

        def random(self, n: int = 1, *, workers: int = 1) -> np.ndarray:
            sample = self._random(n, workers=workers)
            self.num_generated += n
            return sample

        def reset(self) -> Any:
            self.rng = copy.deepcopy(self.rng_seed)
            self.num_generated = 0
            return self

    def __getattr__(name: str) -> Any:
        if name in SCIPY_NAMES:
            raise ImportError(f"lowdisc.qmc.{name} is scipy's: install scipy")
        raise AttributeError(f"module 'lowdisc.qmc' has no attribute {name!r}")


def _generator(owner: str, rng: Any, seed: Any) -> Any:
    """scipy's normalisation of ``rng`` and the legacy ``seed``: what its
    ``QMCEngine._initialize`` receives."""
    if seed is not None:
        if rng is not None:
            raise TypeError(f"{owner}() got multiple values for argument now known as "
                            "`rng`. Specify one of `rng` or `seed`.")
        return seed
    if rng is not None:
        return np.random.default_rng(rng)
    return None


def _draw_seed(generator: Any) -> int:
    """One 64-bit lowdisc seed from a numpy ``Generator`` or ``RandomState``."""
    if isinstance(generator, np.random.Generator):
        return int(generator.integers(0, 2**64, dtype=np.uint64))
    return int(generator.randint(0, 2**64, dtype=np.uint64))


def _dimension(d: Any, limit: int) -> int:
    if isinstance(d, bool) or not isinstance(d, (int, np.integer)) or d < 0:
        raise ValueError("d must be a non-negative integer value")
    if d > limit:
        raise ValueError(f"Maximum supported dimensionality is {limit}.")
    return int(d)


class _Engine(_Base):
    """What lowdisc's engines share: the scramble seed and ``random`` with
    ``dtype``, ``out`` and ``replications``."""

    _sequence = ""
    _bits = 32

    def _setup(self, owner: str, d: int, scramble: bool, randomize: str,
               optimization: str | None, rng: Any, seed: Any) -> None:
        super()._initialize(d=d, optimization=optimization, rng=_generator(owner, rng, seed))
        self.scramble = bool(scramble)
        self.randomize = randomize if self.scramble else "none"
        #: The lowdisc seed of the scramble, drawn from ``rng`` (0 unscrambled).
        self.lowdisc_seed = _draw_seed(self.rng) if self.scramble else 0

    def _check_window(self, n: int) -> None:
        """Raises if points ``num_generated .. + n`` do not exist."""

    def _fill(self, out: np.ndarray, n: int, seed: int) -> None:
        if self.d > 0 and n > 0:
            _lowdisc.points_into(out, self._sequence, self.num_generated, "gray",
                                 self.randomize, seed, self._bits)

    def _random(self, n: int = 1, *, workers: int = 1) -> np.ndarray:
        n = _checks.integer(n, "n")
        _checks.workers(workers)
        self._check_window(n)
        out = np.empty((n, self.d))
        self._fill(out, n, self.lowdisc_seed)
        return out

    def random(self, n: int = 1, *, workers: int = 1, dtype: npt.DTypeLike | None = None,
               out: np.ndarray | None = None,
               replications: int | None = None) -> np.ndarray:
        """Draw the next ``n`` points in ``[0, 1)``.

        Parameters
        ----------
        n : int, default 1
            Number of points.
        workers : int, default 1
            Accepted for scipy's signature; lowdisc always uses every core
            for large requests (the values do not depend on it).
        dtype : {float64, float32, uint32}, optional
            The element type (default float64; uint32 gives the digit words
            ``floor(x * 2**32)``).
        out : numpy.ndarray, optional
            A writeable C-contiguous array to write into (shape ``(n, d)``,
            or ``(replications, n, d)``).
        replications : int, optional
            Draw the same ``n`` points under this many independent
            scrambles: replication 0 is the engine's own, replication r
            seeded as :func:`lowdisc.sobol`'s ``replications`` from
            ``lowdisc_seed``. Not with ``optimization``.

        Returns
        -------
        numpy.ndarray
            Shape ``(n, d)``, or ``(replications, n, d)``.
        """
        if dtype is None and out is None and replications is None:
            return super().random(n, workers=workers)
        n = _checks.integer(n, "n")
        _checks.workers(workers)
        self._check_window(n)
        if replications is None:
            optimizing = getattr(self, "optimization_method", None) is not None
            if optimizing:
                sample = super().random(n, workers=workers)
                array = _checks.output(out, (n, self.d), dtype)
                array[...] = sample if array.dtype != np.uint32 else sample * 2.0**32
                return array
            array = _checks.output(out, (n, self.d), dtype)
            self._fill(array, n, self.lowdisc_seed)
        else:
            if getattr(self, "optimization_method", None) is not None:
                raise ValueError("replications cannot be combined with optimization")
            r = _checks.integer(replications, "replications", low=1)
            array = _checks.output(out, (r, n, self.d), dtype)
            seeds = _checks.replication_seeds(self.lowdisc_seed, r) if self.scramble \
                else [0] * r
            for target, seed in zip(array, seeds):
                self._fill(target, n, seed)
        self.num_generated += n
        return array

    def fast_forward(self, n: int) -> _Engine:
        """Skip ``n`` points, in constant time.

        Parameters
        ----------
        n : int
            Number of points to skip.

        Returns
        -------
        engine
            The engine itself.
        """
        self.num_generated += _checks.integer(n, "n")
        return self

    def reset(self) -> _Engine:
        """Back to the first point (the same scramble).

        Returns
        -------
        engine
            The engine itself.
        """
        super().reset()
        return self


class Sobol(_Engine):
    """Engine for generating (scrambled) Sobol' sequences:
    ``scipy.stats.qmc.Sobol`` with lowdisc's Sobol.

    Joe and Kuo's direction numbers (21,201 dimensions), Gray-code order as
    scipy's, points computed from their index (so ``fast_forward`` is O(1))
    on all cores.

    Parameters
    ----------
    d : int
        Dimension, ``0 <= d <= 21201``.
    scramble : bool, default True
        Randomize the points by ``randomize``.
    bits : int, optional
        Binary digits of each value (default 30, as scipy): at most 2**bits
        points. At most 32 scrambled; up to 64 unscrambled (zeros past 32).
    rng, seed
        The randomness, as scipy's (see the module documentation).
    optimization : {None, "random-cd", "lloyd"}
        scipy's post-processing of each draw.
    randomize : {"owen-tree", "owen", "fast-owen", "xor", "lms"}
        The scramble, as :func:`lowdisc.sobol`'s ``scramble``. ``"owen-tree"``
        and ``"owen"`` are both Owen's exact nested uniform scrambling.

    Examples
    --------
    >>> from lowdisc import qmc
    >>> engine = qmc.Sobol(d=2, scramble=False)
    >>> engine.random_base2(2)
    array([[0.  , 0.  ],
           [0.5 , 0.5 ],
           [0.75, 0.25],
           [0.25, 0.75]])
    >>> sample = qmc.Sobol(d=3, rng=7).random(1024, dtype="float32")
    >>> sample.shape, sample.dtype.name
    ((1024, 3), 'float32')
    >>> qmc.Sobol(d=3, rng=7).random(256, replications=10).shape
    (10, 256, 3)
    """

    MAXDIM: int = _lowdisc.SOBOL_DIMENSIONS
    _sequence = "sobol"

    def __init__(self, d: int, *, scramble: bool = True, bits: int | None = None,
                 rng: Any = None, seed: Any = None, optimization: str | None = None,
                 randomize: str = "owen-tree") -> None:
        d = _dimension(d, self.MAXDIM)
        bits = 30 if bits is None else operator.index(bits)
        if bits > 64:
            raise ValueError("Maximum supported 'bits' is 64")
        if bits < 1:
            raise ValueError(f"bits must be at least 1, got {bits}")
        if scramble and bits > 32:
            raise ValueError(f"lowdisc's scrambled Sobol points have 32 random digits: "
                             f"bits must be at most 32 with scramble=True, got {bits}")
        randomize = _checks.choice(randomize, "randomize",
                                   ("owen-tree", "owen", "fast-owen", "xor", "lms"))
        # Used by scipy.integrate.qmc_quad to make independent copies.
        self._init_quad = {"d": d, "scramble": True, "bits": bits,
                           "optimization": optimization, "randomize": randomize}
        self._setup("Sobol", d, scramble, randomize, optimization, rng, seed)
        self.bits = bits
        self._bits = min(bits, 32)
        self.maxn = 2**bits

    def _check_window(self, n: int) -> None:
        total = self.num_generated + n
        if total > self.maxn:
            msg = (f"At most 2**{self.bits}={self.maxn} distinct points can be generated. "
                   f"{self.num_generated} points have been previously generated, then: "
                   f"n={self.num_generated}+{n}={total}. ")
            if self.bits != 64:
                msg += "Consider increasing `bits`."
            raise ValueError(msg)
        if total > 2**32:
            raise ValueError(f"lowdisc's Sobol sequence has 2**32 points: points "
                             f"{self.num_generated}..{total - 1} do not exist")
        if self.num_generated == 0 and n & (n - 1) != 0:
            warnings.warn("The balance properties of Sobol' points require n to be a power of 2.",
                          stacklevel=4)

    def random_base2(self, m: int) -> np.ndarray:
        """Draw ``2**m`` points; the total drawn must stay a power of 2.

        Parameters
        ----------
        m : int
            Logarithm in base 2 of the number of points.

        Returns
        -------
        numpy.ndarray
            Shape ``(2**m, d)``.
        """
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


class Halton(_Engine):
    """Halton sequence: ``scipy.stats.qmc.Halton`` with lowdisc's Halton.

    Dimension j is the radical inverse in the j-th prime; 6,542 dimensions
    (every prime below 2**16).

    Parameters
    ----------
    d : int
        Dimension, ``0 <= d <= 6542``.
    scramble : bool, default True
        Randomize the points by ``randomize``.
    rng, seed
        The randomness, as scipy's (see the module documentation).
    optimization : {None, "random-cd", "lloyd"}
        scipy's post-processing of each draw.
    randomize : {"owen", "permute", "nested-affine"}
        The scramble, as :func:`lowdisc.halton`'s ``scramble``: ``"owen"``
        is Owen's nested uniform scrambling in each base, ``"permute"``
        random digit permutations (scipy's kind of scramble, other values).

    Examples
    --------
    >>> from lowdisc import qmc
    >>> qmc.Halton(d=2, scramble=False).random(4) * [4, 9]
    array([[0., 0.],
           [2., 3.],
           [1., 6.],
           [3., 1.]])
    >>> sample = qmc.Halton(d=50, rng=1).random(1024)
    >>> bool(abs(sample.mean() - 0.5) < 0.01)
    True
    """

    MAXDIM: int = _lowdisc.HALTON_DIMENSIONS
    _sequence = "halton"

    def __init__(self, d: int, *, scramble: bool = True, rng: Any = None, seed: Any = None,
                 optimization: str | None = None, randomize: str = "owen") -> None:
        d = _dimension(d, self.MAXDIM)
        randomize = _checks.choice(randomize, "randomize", ("owen", "permute", "nested-affine"))
        self._init_quad = {"d": d, "scramble": True, "optimization": optimization,
                           "randomize": randomize}
        self._setup("Halton", d, scramble, randomize, optimization, rng, seed)

    def _check_window(self, n: int) -> None:
        if self.num_generated + n > 2**64:
            raise ValueError(f"Halton points have 64-bit indices: points {self.num_generated}"
                             f"..{self.num_generated + n - 1} do not exist")
