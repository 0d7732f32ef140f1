"""The experiment's measures on numpy arrays: the error of a rendered image
against a reference (MSE, relMSE, RMSE, MAE, the blurred perceptual MSE,
FLIP, per-pixel error images) and the paired-seed ratio of two samplers'
errors with its 95 % interval, computed by the same Rust code as ``lowdisc
experiment`` (crates ``lowdisc-image`` and ``lowdisc-experiment``).

Images are ``(height, width, 3)`` arrays of linear RGB, converted to float32
(the renderer's precision); sums run in float64. A ``mask`` is a
``(height, width)`` array of booleans, true for the pixels that count.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from . import _lowdisc

#: relMSE's ``ε`` in ``(x - r)**2 / (r**2 + ε)`` (the experiment's).
RELMSE_EPSILON = 0.01


class ImageErrors(NamedTuple):
    """The errors of one image against a reference, over the kept pixels."""

    mse: float
    relmse: float
    rmse: float
    mae: float


class Comparison(NamedTuple):
    """A paired-seed ratio of errors (see :func:`compare`)."""

    ratio: float
    low: float
    high: float
    n: int
    ratio_of_means: float
    verdict: str


def _images(image: npt.ArrayLike, reference: npt.ArrayLike,
            mask: npt.ArrayLike | None = None) -> tuple:
    """Flat float32 test and reference, their (height, width), the flat mask."""
    flat = []
    for name, a in (("image", image), ("reference", reference)):
        a = np.asarray(a)
        if a.dtype.kind not in "biuf":
            raise TypeError(f"{name} must be an array of real numbers, got dtype {a.dtype}")
        if a.ndim != 3 or a.shape[2] != 3:
            raise ValueError(f"{name} must have shape (height, width, 3), got {a.shape}")
        flat.append(a)
    if flat[0].shape != flat[1].shape:
        raise ValueError(f"image has shape {flat[0].shape}, reference {flat[1].shape}")
    shape = flat[0].shape[:2]
    keep = None
    if mask is not None:
        m = np.asarray(mask)
        if m.shape != shape:
            raise ValueError(f"mask must have shape {shape}, got {m.shape}")
        keep = np.ascontiguousarray(m, dtype=bool).reshape(-1)
    test, ref = (np.ascontiguousarray(a, dtype=np.float32).reshape(-1) for a in flat)
    return test, ref, shape, keep


def errors(image: npt.ArrayLike, reference: npt.ArrayLike, *,
           mask: npt.ArrayLike | None = None) -> ImageErrors:
    """MSE, relMSE, RMSE and MAE of ``image`` against ``reference`` over all
    pixels and channels (``N = 3 * pixels``), or over the pixels ``mask``
    keeps: the experiment's linear metrics.

    ``relmse`` is ``mean((x - r)**2 / (r**2 + 0.01))`` (Rousselle et al.).

    Parameters
    ----------
    image, reference : array_like (height, width, 3)
        Linear RGB.
    mask : array_like of bool (height, width), optional
        The pixels that count (true); at least one.

    Returns
    -------
    ImageErrors
        ``(mse, relmse, rmse, mae)``.

    Examples
    --------
    >>> import numpy as np
    >>> import lowdisc
    >>> reference = np.full((4, 4, 3), 0.5)
    >>> e = lowdisc.errors(reference + 0.25, reference)
    >>> e.mse, e.rmse, e.mae, round(e.relmse, 12)  # relmse = 0.0625 / (0.25 + 0.01)
    (0.0625, 0.25, 0.25, 0.240384615385)
    """
    test, ref, shape, keep = _images(image, reference, mask)
    return ImageErrors(*_lowdisc.image_errors(test, ref, shape, keep))


def mse(image: npt.ArrayLike, reference: npt.ArrayLike, *,
        mask: npt.ArrayLike | None = None) -> float:
    """The mean squared error: ``errors(image, reference, mask=mask).mse``.

    Examples
    --------
    >>> import numpy as np
    >>> import lowdisc
    >>> lowdisc.mse(np.ones((2, 2, 3)), np.zeros((2, 2, 3)))
    1.0
    """
    return errors(image, reference, mask=mask).mse


def relmse(image: npt.ArrayLike, reference: npt.ArrayLike, *,
           mask: npt.ArrayLike | None = None) -> float:
    """The relative MSE, ``mean((x - r)**2 / (r**2 + 0.01))``:
    ``errors(image, reference, mask=mask).relmse``.

    Examples
    --------
    >>> import numpy as np
    >>> import lowdisc
    >>> round(lowdisc.relmse(np.full((2, 2, 3), 0.5), np.zeros((2, 2, 3))), 12)
    25.0
    """
    return errors(image, reference, mask=mask).relmse


def blurred_mse(image: npt.ArrayLike, reference: npt.ArrayLike, *,
                mask: npt.ArrayLike | None = None, sigma: float = 1.0) -> float:
    """The perceptual error of the experiment: the MSE of the error image
    after a Gaussian blur of ``sigma`` pixels (normalised over the kept
    pixels, so a masked pixel never leaks into its neighbours). Noise at high
    spatial frequencies (blue noise) scores lower than white noise of the
    same MSE.

    Parameters
    ----------
    image, reference : array_like (height, width, 3)
        Linear RGB.
    mask : array_like of bool (height, width), optional
        The pixels that count.
    sigma : float, default 1.0
        The Gaussian's standard deviation in pixels, in ``(0, 64]``.

    Returns
    -------
    float
        The blurred MSE (a constant error ``c`` gives ``c**2``).

    Examples
    --------
    >>> import numpy as np
    >>> import lowdisc
    >>> reference = np.zeros((16, 16, 3))
    >>> round(lowdisc.blurred_mse(reference + 0.5, reference), 12)
    0.25
    >>> checker = (np.indices((16, 16)).sum(axis=0) % 2)[:, :, None] * np.ones(3) - 0.5
    >>> lowdisc.blurred_mse(checker, reference) < lowdisc.mse(checker, reference) / 10
    True
    """
    test, ref, shape, keep = _images(image, reference, mask)
    return _lowdisc.blurred_mse(test, ref, shape, keep, float(sigma))


def flip(image: npt.ArrayLike, reference: npt.ArrayLike, *,
         mask: npt.ArrayLike | None = None, pixels_per_degree: float = 67.0) -> float:
    """NVIDIA's FLIP difference (LDR, on 8-bit sRGB at exposure 1), the mean
    over the kept pixels, in ``[0, 1]``.

    Parameters
    ----------
    image, reference : array_like (height, width, 3)
        Linear RGB.
    mask : array_like of bool (height, width), optional
        The pixels that count.
    pixels_per_degree : float, default 67.0
        The viewing geometry (FLIP's default).

    Returns
    -------
    float
        The mean FLIP error.

    Examples
    --------
    >>> import numpy as np
    >>> import lowdisc
    >>> grey = np.full((8, 8, 3), 0.2)
    >>> lowdisc.flip(grey, grey)
    0.0
    """
    test, ref, shape, keep = _images(image, reference, mask)
    return _lowdisc.flip(test, ref, shape, keep, float(pixels_per_degree))


def error_image(image: npt.ArrayLike, reference: npt.ArrayLike, *,
                kind: str = "relative") -> np.ndarray:
    """The per-pixel, per-channel error: ``"squared"`` ``(x - r)**2``,
    ``"relative"`` ``(x - r)**2 / (r**2 + 0.01)`` or ``"absolute"``
    ``|x - r|``; the mean of the squared and relative images is the MSE and
    relMSE.

    Parameters
    ----------
    image, reference : array_like (height, width, 3)
        Linear RGB.
    kind : {"relative", "squared", "absolute"}, default "relative"
        The error of one value.

    Returns
    -------
    numpy.ndarray
        ``(height, width, 3)`` float32.

    Examples
    --------
    >>> import numpy as np
    >>> import lowdisc
    >>> e = lowdisc.error_image(np.full((1, 2, 3), 0.75), np.full((1, 2, 3), 0.5),
    ...                         kind="absolute")
    >>> e.shape, float(e.max())
    ((1, 2, 3), 0.25)
    """
    test, ref, shape, _ = _images(image, reference)
    if not isinstance(kind, str):
        raise TypeError(f"kind must be a str, got {type(kind).__name__}")
    return _lowdisc.error_image(test, ref, shape, kind).reshape(*shape, 3)


def compare(errors_a: npt.ArrayLike, errors_b: npt.ArrayLike) -> Comparison:
    """The experiment's paired-seed ratio of sampler A's errors to sampler
    B's: entry ``i`` of both comes from the same seed, the ratio is the
    geometric mean of ``a_i / b_i`` and its 95 % interval is Student's t
    interval of ``mean(log(a_i / b_i))``, exponentiated.

    Parameters
    ----------
    errors_a, errors_b : array_like (n,)
        Positive, finite errors (e.g. :func:`mse`) of the two samplers'
        renders with seeds ``0 .. n-1``; ``n >= 2``.

    Returns
    -------
    Comparison
        ``ratio``, its interval ``low``, ``high``, the pairs ``n``,
        ``ratio_of_means`` (``mean(a) / mean(b)``) and the ``verdict``:
        ``"better"`` (the interval lies below 1: A has lower error),
        ``"worse"`` or ``"not distinguishable"``.

    Examples
    --------
    >>> import lowdisc
    >>> c = lowdisc.compare([0.5, 1.1, 1.9, 4.2], [1.0, 2.0, 4.0, 8.0])
    >>> round(c.ratio, 3), c.verdict, bool(c.low < c.ratio < c.high < 1)
    (0.512, 'better', True)
    """
    a, b = (np.ascontiguousarray(np.asarray(x, dtype=np.float64).reshape(-1))
            for x in (errors_a, errors_b))
    return Comparison(*_lowdisc.compare(a, b))
