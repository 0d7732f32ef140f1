"""Renders from Python: the path tracer of ``lowdisc render``, returning the
image as a numpy array.

The scene and its settings are resolved by the renderer's own code, exactly
as the CLI resolves them (the scene file's ``Sampler``, ``Film`` and
``Integrator`` apply unless an argument overrides them), so
``lowdisc.render(s, sampler=..., spp=..., seed=...)`` equals ``lowdisc
render s --sampler ... --spp ... --seed ...`` bit for bit, whatever the
thread count. The render runs with the GIL released; Ctrl-C stops it
within one path per worker and raises ``KeyboardInterrupt``.
"""

from __future__ import annotations

import os
import sys
import time
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np
import numpy.typing as npt

from . import _checks, _lowdisc

#: The built-in scenes: ``"cornell"`` (the CLI's scene when it is given no
#: file), and the experiment's presets ``"direct"`` (direct lighting, path
#: depth 1) and ``"gi"`` (global illumination and depth of field, depth 5).
BUILTIN_SCENES: tuple[str, ...] = tuple(_lowdisc.builtin_scenes())


def render(scene: str | os.PathLike = "cornell", *, sampler: str | None = None,
           net: str | os.PathLike | npt.ArrayLike | None = None, spp: int | None = None,
           seed: int | None = None, spectral: bool = False,
           threads: int | None = None, max_depth: int | None = None,
           resolution: tuple[int, int] | None = None, threshold: float | None = None,
           paper_all_dims: bool | None = None, approximate: bool = False,
           progress: bool | Callable[[int, int], Any] = False) -> np.ndarray:
    """Path-trace a scene and return its image, as ``lowdisc render`` does.

    Every setting left at ``None`` is the scene's (a pbrt-v4 file's
    ``Sampler "pixelsamples"``, ``Film`` resolution, ``Integrator
    "maxdepth"``), else the renderer's default: sampler ``zsobol``, 16
    samples per pixel, seed 0, depth 5, 512x512 for the built-in scenes. The
    result is bit-identical to the CLI's with the same options (its ``.pfm``
    or ``.exr`` output) and to any other thread count.

    Parameters
    ----------
    scene : str or path-like, default "cornell"
        A pbrt-v4 scene file, or a built-in scene (:data:`BUILTIN_SCENES`):
        ``"cornell"``, the CLI's scene without a file; ``"direct"`` and
        ``"gi"``, the experiment's presets (they set the path depth too).
    sampler : str, optional
        A pixel sampler, any of :func:`sampler_names` (the CLI's
        ``--sampler``).
    net : str, path-like or array_like, optional
        The generator matrices of the Sobol samplers (the CLI's ``--net``):
        a built-in net's name (``"sobol"``, Joe & Kuo's matrices, the
        default; ``"onetwo"``), a file of Joe & Kuo direction numbers or of
        matrices, or the matrices themselves: an integer array of shape
        ``(dims, 32)`` (uint32, or any integers in ``[0, 2**32)``) whose
        row ``j`` holds dimension ``j``'s 32 columns, column ``c`` the digit
        word that bit ``c`` of the sample index contributes, bit 31 the
        first binary digit: the layout of :func:`sobol_matrices` and of a
        matrix file's lines. Every dimension must be a (0,1)-sequence (the
        leading ``k x k`` block of its matrix nonsingular for every ``k``).
        Only the Sobol samplers read a net (``sobol``, ``sobol-xor``,
        ``sobol-owen``, ``sobol-fast-owen``, ``sobol-lms``,
        ``padded-sobol``, ``padded-sobol-lms``, ``zsobol``, ``zsobol-4d``,
        ``zsobol-joint``); the global ``sobol*`` samplers need at least 3
        dimensions, ``zsobol-4d`` and ``zsobol-joint`` at least 4.
    spp : int, optional
        Samples per pixel.
    seed : int, optional
        Seed of every random choice, in ``[0, 2**64)``.
    spectral : bool, default False
        Render spectrally as pbrt-v4 (four wavelengths per sample).
    threads : int, optional
        Worker threads (default: all cores); the image does not depend on it.
    max_depth : int, optional
        Largest number of bounces (pbrt's ``maxdepth``).
    resolution : (int, int), optional
        Width and height.
    threshold, paper_all_dims : optional
        The paper samplers' permutation threshold and whether it acts on the
        film dimensions too (``--threshold``, ``--paper-all-dims``).
    approximate : bool, default False
        Render a file's pbrt-v4 features that lowdisc lacks approximately,
        with a warning, instead of refusing the scene.
    progress : bool or callable, default False
        ``True`` draws a text bar on stderr; a callable is called as
        ``progress(samples_done, samples_total)`` from the calling thread
        while the render runs (an exception it raises stops the render).

    Returns
    -------
    numpy.ndarray
        The image, shape ``(height, width, 3)``, dtype float32: linear RGB
        radiance (the renderer's own values, not clamped or tone-mapped),
        top row first.

    Raises
    ------
    ValueError
        A bad setting, sampler name or scene, with the CLI's one-line message
        (a scene file's errors name its ``file:line:column``); a ``net``
        that is not a net (wrong shape or dtype, a singular matrix, an
        unreadable or malformed file) or given to a sampler that reads none.
    KeyboardInterrupt
        Ctrl-C during the render.

    Warnings
    --------
    The loader's and the render's warnings (a feature ignored, samples with
    NaN radiance) are issued as ``UserWarning``, each once.

    Examples
    --------
    >>> import lowdisc
    >>> image = lowdisc.render("cornell", sampler="sobol-owen", spp=4, resolution=(32, 24))
    >>> image.shape, image.dtype
    ((24, 32, 3), dtype('float32'))
    >>> bool((image >= 0).all() and image.mean() > 0)
    True
    >>> again = lowdisc.render("cornell", sampler="sobol-owen", spp=4, resolution=(32, 24),
    ...                        threads=1)
    >>> bool((again == image).all())  # the same bits on any number of threads
    True

    A net of one's own, as generator matrices: ``zsobol-4d`` reads
    dimensions 0-3, so Joe & Kuo's first four matrices render what the
    default does, and another net (here with dimensions 2 and 3 swapped)
    renders another image:

    >>> m = lowdisc.sobol_matrices(4)
    >>> m.shape, m.dtype
    ((4, 32), dtype('uint32'))
    >>> def box(net):
    ...     return lowdisc.render("cornell", sampler="zsobol-4d", net=net, spp=4,
    ...                           resolution=(32, 24))
    >>> bool((box(m) == box(None)).all())
    True
    >>> bool((box(m[[0, 1, 3, 2]]) != box(None)).any())
    True
    >>> singular = m.copy()
    >>> singular[2, 5] = singular[2, 4]
    >>> box(singular)
    Traceback (most recent call last):
    ...
    ValueError: net array: dimension 2 is not a (0,1)-sequence: its leading 6x6 block is singular
    """
    request = _request(scene, sampler, net, spp, seed, max_depth, resolution, threads,
                       threshold, paper_all_dims)
    callback = _TextBar() if progress is True else (progress or None)
    if callback is not None and not callable(callback):
        raise TypeError(f"progress must be a bool or a callable, got {type(progress).__name__}")
    try:
        image, notes = _lowdisc.render(*request, bool(spectral), bool(approximate), callback)
    finally:
        if isinstance(callback, _TextBar):
            callback.close()
    for note in notes:
        warnings.warn(note, stacklevel=2)
    return image


def _request(scene, sampler, net, spp, seed, max_depth, resolution, threads, threshold,
             paper_all_dims) -> tuple:
    """The arguments checked and normalised, in the extension's order."""
    scene = os.fspath(scene)
    if not isinstance(scene, str):
        raise TypeError(f"scene must be a str or a path, got {type(scene).__name__}")
    if sampler is not None and not isinstance(sampler, str):
        raise TypeError(f"sampler must be a str, got {type(sampler).__name__}")

    def maybe(value, name, **bounds):
        return None if value is None else _checks.integer(value, name, **bounds)

    if resolution is not None:
        if len(resolution) != 2:
            raise ValueError(f"resolution must be (width, height), got {resolution!r}")
        resolution = tuple(_checks.integer(v, "resolution", high=2**32 - 1) for v in resolution)
    return (scene, sampler, _checks.net(net), maybe(spp, "spp", high=2**32 - 1),
            None if seed is None else _checks.seed(seed),
            maybe(max_depth, "max_depth", high=2**32 - 1), resolution,
            maybe(threads, "threads", high=2**32 - 1),
            None if threshold is None else float(threshold),
            None if paper_all_dims is None else bool(paper_all_dims))


class _TextBar:
    """A progress bar on stderr, redrawn at most ten times a second."""

    def __init__(self, width: int = 40) -> None:
        self.width = width
        self.last = 0.0
        self.drawn = False

    def __call__(self, done: int, total: int) -> None:
        now = time.monotonic()
        if done < total and now - self.last < 0.1:
            return
        self.last = now
        filled = self.width * done // max(total, 1)
        bar = "#" * filled + "-" * (self.width - filled)
        sys.stderr.write(f"\rrender [{bar}] {100 * done // max(total, 1):3d}% "
                         f"({done}/{total} samples)")
        sys.stderr.flush()
        self.drawn = True

    def close(self) -> None:
        if self.drawn:
            sys.stderr.write("\n")
            sys.stderr.flush()
