"""Points as numpy arrays: sequences (Sobol, Halton, independent,
stratified), the renderer's pixel samplers, and the Sobol generator matrices.

Every function returns an ``(n, d)`` array (``pixel_samples``: ``(pixels,
spp, dims)``) and takes an explicit seed; values in ``[0, 1)`` never round
up to 1. Large requests run on all cores with the GIL released; results do
not depend on the thread count.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from . import _checks, _lowdisc

#: Dimensions of the Sobol table (Joe & Kuo's new-joe-kuo-6.21201).
SOBOL_DIMENSIONS: int = _lowdisc.SOBOL_DIMENSIONS
#: Dimensions of the Halton sequence (the first primes).
HALTON_DIMENSIONS: int = _lowdisc.HALTON_DIMENSIONS

SOBOL_SCRAMBLES = ("none", "xor", "owen", "fast-owen", "owen-per-digit")
HALTON_SCRAMBLES = ("none", "permute", "owen")


def _points(sequence: str, n: int, d: int, *, start: int = 0, order: str = "gray",
            scramble: str = "none", seed: int = 0, bits: int = 32,
            dtype: npt.DTypeLike = np.float64) -> np.ndarray:
    return _lowdisc.points(
        sequence,
        _checks.integer(n, "n"),
        _checks.integer(d, "d", low=1, high=2**32 - 1),
        _checks.integer(start, "start", high=2**64 - 1),
        _checks.choice(order, "order", ("gray", "natural")),
        scramble,
        _checks.seed(seed),
        bits,
        _checks.dtype_name(dtype),
    )


def sobol(n: int, d: int, *, start: int = 0, order: str = "gray",
          scramble: str = "none", seed: int = 0,
          dtype: npt.DTypeLike = np.float64) -> np.ndarray:
    """Points ``start .. start + n`` of the Sobol sequence in dimensions ``0..d``.

    ``order="gray"`` is the order of Joe & Kuo's generator and of
    ``scipy.stats.qmc.Sobol`` (unscrambled, the same numbers bit for bit);
    ``"natural"`` is Sobol's own (point k uses index k), as pbrt. The first
    ``2**m`` points are the same set in both. ``scramble``: ``"none"``,
    ``"xor"`` (random digital shift), ``"owen"`` (nested uniform scrambling,
    exact in distribution: every digit is flipped by its own random tree
    node, drawn 63 nodes per hash, so 3-5 hashes per value, eight dimensions
    per instruction on CPUs with AVX-512), ``"fast-owen"``
    (Laine-Karras-style hash, nested but not exactly uniform) or
    ``"owen-per-digit"`` (the same scramble law with one hash per digit: the
    values of the renderer's ``sobol-owen`` sampler and of ``lowdisc points
    --sampler sobol-owen``, about 6x the instructions per value of the
    portable tree kernel and 50x those of the AVX-512 one). ``dtype`` float64 gives the
    32-digit values exactly, float32 the 24 leading digits, uint32 the digit
    words ``floor(x * 2**32)``.
    """
    _checks.choice(scramble, "scramble", SOBOL_SCRAMBLES)
    return _points("sobol", n, d, start=start, order=order, scramble=scramble,
                   seed=seed, dtype=dtype)


def halton(n: int, d: int, *, start: int = 0, scramble: str = "none", seed: int = 0,
           dtype: npt.DTypeLike = np.float64) -> np.ndarray:
    """Points ``start .. start + n`` of the Halton sequence in dimensions ``0..d``
    (d <= 1024). ``scramble``: ``"none"``, ``"permute"`` (random digit
    permutations, as pbrt-v4) or ``"owen"`` (nested scrambling in each base)."""
    _checks.choice(scramble, "scramble", HALTON_SCRAMBLES)
    return _points("halton", n, d, start=start, scramble=scramble, seed=seed, dtype=dtype)


def independent(n: int, d: int, *, start: int = 0, seed: int = 0,
                dtype: npt.DTypeLike = np.float64) -> np.ndarray:
    """Independent uniform points: dimension j of point k is draw k of PCG32
    stream j (seeded), so any point can be recomputed alone."""
    return _points("independent", n, d, start=start, seed=seed, dtype=dtype)


def stratified(n: int, d: int, *, seed: int = 0,
               dtype: npt.DTypeLike = np.float64) -> np.ndarray:
    """``n`` jittered stratified points (a set, not a sequence: no ``start``)."""
    return _points("stratified", n, d, seed=seed, dtype=dtype)


def sampler_names() -> list[str]:
    """The names of the renderer's pixel samplers (``--sampler`` of the CLI)."""
    return list(_lowdisc.sampler_names())


def pixel_samples(sampler: str, spp: int, resolution: tuple[int, int],
                  pixels: npt.ArrayLike, dims: int = 2, seed: int = 0) -> np.ndarray:
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
    )


def sobol_matrices(d: int) -> np.ndarray:
    """The generator matrices of Sobol dimensions ``0..d``: a uint32 array
    ``(d, 32)`` whose ``[j, c]`` is column c of dimension j, bit 31 the first
    output digit. Natural-order point k of dimension j is the XOR of the
    columns c whose bit c of k is set; Gray-code point k uses ``k ^ (k >> 1)``.
    """
    return _lowdisc.sobol_matrices(_checks.integer(d, "d", low=1, high=SOBOL_DIMENSIONS))


def qmcpy_generating_matrices(d: int, m: int = 32) -> np.ndarray:
    """``sobol_matrices`` in the layout of qmcpy's ``DigitalNetB2(...,
    generating_matrices=G, t=32, msb=True)``: a uint64 array ``(d, m)`` whose
    entry ``[j, c]`` is column c with its first digit the most significant bit.
    """
    m = _checks.integer(m, "m", low=1, high=32)
    return sobol_matrices(d)[:, :m].astype(np.uint64)
