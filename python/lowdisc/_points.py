"""Points as numpy arrays: sequences (Sobol, Halton, independent,
stratified), the renderer's pixel samplers, and the Sobol generator matrices.

Every function returns an ``(n, d)`` array (``pixel_samples``: ``(pixels,
spp, dims)``) and takes an explicit seed; values in ``[0, 1)`` never round
up to 1. Large requests run on all cores with the GIL released; results do
not depend on the thread count.
"""

from __future__ import annotations

import os

import numpy as np
import numpy.typing as npt

from . import _checks, _lowdisc

#: Dimensions of the Sobol table (Joe & Kuo's new-joe-kuo-6.21201).
SOBOL_DIMENSIONS: int = _lowdisc.SOBOL_DIMENSIONS
#: Dimensions of the Halton sequence (the first primes).
HALTON_DIMENSIONS: int = _lowdisc.HALTON_DIMENSIONS

SOBOL_SCRAMBLES = ("none", "xor", "owen", "owen-tree", "fast-owen", "lms")
HALTON_SCRAMBLES = ("none", "permute", "owen", "nested-affine")


def _points(sequence: str, n: int, d: int, *, start: int = 0, order: str = "gray",
            scramble: str = "none", seed: int = 0, bits: int = 32,
            dtype: npt.DTypeLike | None = None, out: np.ndarray | None = None,
            replications: int | None = None) -> np.ndarray:
    n = _checks.integer(n, "n")
    d = _checks.integer(d, "d", high=2**32 - 1)
    start = _checks.integer(start, "start", high=2**64 - 1)
    order = _checks.choice(order, "order", ("gray", "natural"))
    seed = _checks.seed(seed)
    if replications is None:
        array = _checks.output(out, (n, d), dtype)
        targets = [(array, seed)]
    else:
        r = _checks.integer(replications, "replications", low=1)
        array = _checks.output(out, (r, n, d), dtype)
        targets = list(zip(array, _checks.replication_seeds(seed, r)))
    if d == 0:
        return array
    for target, target_seed in targets:
        _lowdisc.points_into(target, sequence, start, order, scramble, target_seed, bits)
    return array


_COMMON_PARAMETERS = """start : int, default 0
        Index of the first point: a request can continue where another ended.
    seed : int, default 0
        The randomization's seed, any integer in ``[0, 2**64)``.
    dtype : {float64, float32, uint32}, default float64
        float64 gives the values exactly; float32 the 24 leading binary
        digits (never rounded up to 1); uint32 the digit words
        ``floor(x * 2**32)``. Ignored when ``out`` is given.
    out : numpy.ndarray, optional
        A writeable C-contiguous array of shape ``(n, d)`` (``(replications,
        n, d)`` with ``replications``) and one of those dtypes to write into.
    replications : int, optional
        Draw this many independent randomizations at once: replication 0
        uses ``seed``, replication ``r`` the 64-bit word
        ``SeedSequence(seed, spawn_key=(r,)).generate_state(1, uint64)[0]``."""

_RETURNS = """Returns
    -------
    numpy.ndarray
        The points, shape ``(n, d)`` or ``(replications, n, d)``: ``out``
        itself when it was given."""


def sobol(n: int, d: int, *, start: int = 0, order: str = "gray",
          scramble: str = "none", seed: int = 0, dtype: npt.DTypeLike | None = None,
          out: np.ndarray | None = None, replications: int | None = None) -> np.ndarray:
    """Points ``start .. start + n`` of the Sobol sequence in dimensions ``0..d``.

    Joe and Kuo's direction numbers (new-joe-kuo-6.21201, 21,201
    dimensions), 32 binary digits per value, 2**32 points.

    Parameters
    ----------
    n : int
        Number of points.
    d : int
        Number of dimensions, ``0 <= d <= 21201``.
    order : {"gray", "natural"}, default "gray"
        ``"gray"`` is the order of Joe and Kuo's generator and of
        ``scipy.stats.qmc.Sobol`` (unscrambled, the same numbers bit for
        bit); ``"natural"`` is Sobol's own (point k uses index k), as pbrt's.
        The first ``2**m`` points are the same set in both.
    scramble : {"none", "xor", "owen", "owen-tree", "fast-owen", "lms"}
        ``"xor"``: a random digital shift. ``"owen"``: Owen's nested uniform
        scrambling with one hash per digit, the values of the renderer's
        ``sobol-owen`` sampler. ``"owen-tree"``: the same law (exact Owen)
        with other values, drawn 63 tree nodes per hash: 3-5 hashes per
        value and eight dimensions per instruction on CPUs with AVX-512,
        the fastest exact scramble here. ``"fast-owen"``: a
        Laine-Karras-style hash, nested but not exactly Owen's law (the
        renderer's ``sobol-fast-owen``). ``"lms"``: Matoušek's linear matrix
        scramble plus a digital shift, the kind of scramble scipy uses (the
        renderer's ``sobol-lms``; scipy's own values differ).
    {common}

    {returns}

    Examples
    --------
    >>> import lowdisc
    >>> lowdisc.sobol(4, 2)
    array([[0.  , 0.  ],
           [0.5 , 0.5 ],
           [0.75, 0.25],
           [0.25, 0.75]])
    >>> x = lowdisc.sobol(1024, 3, scramble="owen", seed=7, dtype="float32")
    >>> x.shape, x.dtype.name
    ((1024, 3), 'float32')
    >>> lowdisc.sobol(256, 5, scramble="owen-tree", seed=1, replications=8).shape
    (8, 256, 5)
    """
    _checks.choice(scramble, "scramble", SOBOL_SCRAMBLES)
    return _points("sobol", n, d, start=start, order=order, scramble=scramble,
                   seed=seed, dtype=dtype, out=out, replications=replications)


def halton(n: int, d: int, *, start: int = 0, scramble: str = "none", seed: int = 0,
           dtype: npt.DTypeLike | None = None, out: np.ndarray | None = None,
           replications: int | None = None) -> np.ndarray:
    """Points ``start .. start + n`` of the Halton sequence in dimensions ``0..d``.

    Dimension j is the radical inverse in base ``PRIMES[j]`` (2, 3, 5, ...):
    ``HALTON_DIMENSIONS`` = 6,542 dimensions, every prime below 2**16.

    Parameters
    ----------
    n : int
        Number of points.
    d : int
        Number of dimensions, ``0 <= d <= 6542``.
    scramble : {"none", "permute", "owen", "nested-affine"}
        ``"permute"``: one random permutation per dimension and digit
        position (pbrt-v4's, the renderer's ``halton`` sampler).
        ``"owen"``: Owen's nested uniform scrambling in each base (every
        node of the digit tree gets its own uniformly random permutation;
        the renderer's ``halton-owen``), about ``b / 2`` hashes per nonzero
        digit in base b. ``"nested-affine"``: the same nesting with random
        affine digit maps ``a -> (m a + c) mod b``, one hash per digit:
        Owen's variance for pairs of points, but not Owen's law (it keeps
        arithmetic progressions of digits), the same values as ``"owen"``
        in dimensions 0 and 1.
    {common}

    {returns}

    Examples
    --------
    >>> import lowdisc
    >>> lowdisc.halton(4, 2) * [4, 9]
    array([[0., 0.],
           [2., 3.],
           [1., 6.],
           [3., 1.]])
    >>> x = lowdisc.halton(1000, 50, scramble="owen", seed=3)
    >>> bool(abs(x.mean() - 0.5) < 0.01)
    True
    """
    _checks.choice(scramble, "scramble", HALTON_SCRAMBLES)
    return _points("halton", n, d, start=start, scramble=scramble, seed=seed, dtype=dtype,
                   out=out, replications=replications)


def independent(n: int, d: int, *, start: int = 0, seed: int = 0,
                dtype: npt.DTypeLike | None = None, out: np.ndarray | None = None,
                replications: int | None = None) -> np.ndarray:
    """Independent uniform points.

    Dimension j of point k is draw k of PCG32 stream j (seeded), so any point
    can be recomputed alone.

    Parameters
    ----------
    n : int
        Number of points.
    d : int
        Number of dimensions.
    {common}

    {returns}

    Examples
    --------
    >>> import lowdisc
    >>> x = lowdisc.independent(100, 3, seed=8)
    >>> bool((x[50:] == lowdisc.independent(50, 3, start=50, seed=8)).all())
    True
    """
    return _points("independent", n, d, start=start, seed=seed, dtype=dtype, out=out,
                   replications=replications)


def stratified(n: int, d: int, *, seed: int = 0, dtype: npt.DTypeLike | None = None,
               out: np.ndarray | None = None,
               replications: int | None = None) -> np.ndarray:
    """``n`` jittered stratified points (a set, not a sequence: no ``start``).

    Parameters
    ----------
    n : int
        Number of points, at least 1.
    d : int
        Number of dimensions.
    seed, dtype, out, replications
        As for :func:`sobol`.

    {returns}

    Examples
    --------
    >>> import lowdisc
    >>> x = lowdisc.stratified(64, 2, seed=1)
    >>> len({tuple(c) for c in (x * 8).astype(int)})  # one point per 8x8 stratum
    64
    """
    return _points("stratified", n, d, seed=seed, dtype=dtype, out=out,
                   replications=replications)


for _function in (sobol, halton, independent, stratified):
    _function.__doc__ = (_function.__doc__.replace("{common}", _COMMON_PARAMETERS)
                         .replace("{returns}", _RETURNS))


def sampler_names() -> list[str]:
    """The names of the renderer's pixel samplers (``--sampler`` of the CLI).

    Returns
    -------
    list of str
        The names :func:`pixel_samples` accepts.

    Examples
    --------
    >>> import lowdisc
    >>> "sobol-owen" in lowdisc.sampler_names()
    True
    """
    return list(_lowdisc.sampler_names())


def pixel_samples(sampler: str, spp: int, resolution: tuple[int, int],
                  pixels: npt.ArrayLike, dims: int = 2, seed: int = 0, *,
                  net: str | os.PathLike | npt.ArrayLike | None = None) -> np.ndarray:
    """The samples the renderer's pixel sampler ``sampler`` gives ``pixels``.

    Returns a float32 array ``(len(pixels), spp, dims)``: for each pixel
    ``(x, y)`` of a ``resolution = (width, height)`` image and each sample
    index, columns 0-1 are the offset inside the pixel (``get_pixel_2d``),
    then ``get_2d`` pairs and, for an odd ``dims``, one last ``get_1d``: what
    ``lowdisc points --sampler NAME --pixel X,Y --spp SPP --res WxH
    --dims DIMS-2`` prints (as film positions ``x + offset``).

    The sampler is the renderer's: the full image is cut into the renderer's
    square tiles of 16 pixels, numbered row-major, and each tile's index is
    its sampler stream. The ``paper`` sampler's
    single stream is replayed from the tile's first pixel, row by row, each
    earlier sample drawing ``dims`` values: the renderer's values exactly
    when each of its camera samples drew ``dims`` values (always for the
    tile's first sample).

    Parameters
    ----------
    sampler : str
        One of :func:`sampler_names`.
    spp : int
        Samples per pixel.
    resolution : (int, int)
        The image's (width, height).
    pixels : array_like (p, 2)
        Integer pixel coordinates (x, y).
    dims : int, default 2
        Values per sample (at least the 2 of the pixel offset).
    seed : int, default 0
        The sampler's seed.
    net : str, path-like or array_like, optional
        The generator matrices of the Sobol samplers, as :func:`render`
        takes them (``--net`` of ``lowdisc points``): a built-in net's name,
        a file, or an integer array ``(dims, 32)`` of matrix columns, the
        layout of :func:`sobol_matrices`. A sampler that reads no net
        refuses any but ``"sobol"`` with ``ValueError``.

    Returns
    -------
    numpy.ndarray
        float32, shape ``(p, spp, dims)``.

    Examples
    --------
    >>> import lowdisc
    >>> lowdisc.pixel_samples("zsobol", 16, (64, 64), [(3, 5)], 6, seed=1).shape
    (1, 16, 6)
    >>> plain = lowdisc.pixel_samples("zsobol-4d", 16, (64, 64), [(3, 5)], 6, seed=1)
    >>> onetwo = lowdisc.pixel_samples("zsobol-4d", 16, (64, 64), [(3, 5)], 6, seed=1,
    ...                                net="onetwo")
    >>> bool((plain[..., :2] == onetwo[..., :2]).all())  # the same dimensions 0-1
    True
    """
    if not isinstance(sampler, str):
        raise TypeError(f"sampler must be a name (str), got {type(sampler).__name__}")
    if not isinstance(resolution, (tuple, list)) or len(resolution) != 2:
        raise TypeError("resolution must be a pair (width, height)")
    width = _checks.integer(resolution[0], "resolution width", low=1, high=2**32 - 1)
    height = _checks.integer(resolution[1], "resolution height", low=1, high=2**32 - 1)
    array = np.asarray(pixels)
    if array.ndim == 1 and array.shape[0] == 2:
        array = array.reshape(1, 2)
    if array.dtype.kind not in "iu" and array.size > 0:
        raise TypeError(f"pixels must be integers, got dtype {array.dtype}")
    if array.ndim != 2 or array.shape[1] != 2:
        raise ValueError(f"pixels must have shape (p, 2), got {array.shape}")
    if array.size and (array.min() < 0 or array.max() >= 2**32):
        raise ValueError("pixel coordinates must be non-negative 32-bit integers")
    return _lowdisc.pixel_samples(
        sampler,
        _checks.integer(spp, "spp", low=1, high=2**32 - 1),
        (width, height),
        np.ascontiguousarray(array, dtype=np.uint32),
        _checks.integer(dims, "dims", low=2, high=2**32 - 1),
        _checks.seed(seed),
        _checks.net(net),
    )


def sobol_matrices(d: int) -> np.ndarray:
    """The generator matrices of Sobol dimensions ``0..d``: a uint32 array
    ``(d, 32)`` whose ``[j, c]`` is column c of dimension j, bit 31 the first
    output digit. Natural-order point k of dimension j is the XOR of the
    columns c whose bit c of k is set; Gray-code point k uses ``k ^ (k >> 1)``.

    Parameters
    ----------
    d : int
        Dimensions, ``1 <= d <= 21201``.

    Returns
    -------
    numpy.ndarray
        uint32, shape ``(d, 32)``.

    Examples
    --------
    >>> import lowdisc
    >>> [hex(c) for c in lowdisc.sobol_matrices(1)[0, :3]]  # dimension 0: the identity
    ['0x80000000', '0x40000000', '0x20000000']
    """
    return _lowdisc.sobol_matrices(_checks.integer(d, "d", low=1, high=SOBOL_DIMENSIONS))


def qmcpy_generating_matrices(d: int, m: int = 32) -> np.ndarray:
    """``sobol_matrices`` in the layout of qmcpy's ``DigitalNetB2(...,
    generating_matrices=G, t=32, msb=True)``: a uint64 array ``(d, m)`` whose
    entry ``[j, c]`` is column c with its first digit the most significant bit.

    Parameters
    ----------
    d : int
        Dimensions.
    m : int, default 32
        Columns (``1 <= m <= 32``).

    Returns
    -------
    numpy.ndarray
        uint64, shape ``(d, m)``.

    Examples
    --------
    >>> import lowdisc
    >>> lowdisc.qmcpy_generating_matrices(3, 10).shape
    (3, 10)
    """
    m = _checks.integer(m, "m", low=1, high=32)
    return sobol_matrices(d)[:, :m].astype(np.uint64)
