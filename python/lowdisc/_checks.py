"""Argument checks shared by the package: every public function normalises
its arguments here first, so bad input raises ``TypeError`` or ``ValueError``
with a message naming the argument, before anything reaches the extension."""

from __future__ import annotations

import operator
import os
from typing import Any

import numpy as np
import numpy.typing as npt

#: The element types a point array can have.
DTYPES = ("float64", "float32", "uint32")


def integer(value: Any, name: str, *, low: int = 0, high: int | None = None) -> int:
    """``value`` as a Python int in ``[low, high]`` (``high=None``: no limit)."""
    if isinstance(value, bool):
        raise TypeError(f"{name} must be an integer, got bool")
    try:
        v = operator.index(value)
    except TypeError:
        raise TypeError(
            f"{name} must be an integer, got {type(value).__name__}"
        ) from None
    if v < low or (high is not None and v > high):
        bound = f"between {low} and {high}" if high is not None else f"at least {low}"
        raise ValueError(f"{name} must be {bound}, got {v}")
    return v


def seed(value: Any) -> int:
    """A seed: an integer in ``[0, 2**64)``."""
    return integer(value, "seed", high=2**64 - 1)


def choice(value: Any, name: str, options: tuple[str, ...]) -> str:
    """``value`` if it is one of ``options``."""
    if not isinstance(value, str) or value not in options:
        listed = ", ".join(repr(o) for o in options)
        raise ValueError(f"{name} must be one of {listed}, got {value!r}")
    return value


def dtype_name(dtype: npt.DTypeLike) -> str:
    """numpy's name of ``dtype`` if it is float64, float32 or uint32."""
    try:
        name = np.dtype(dtype).name
    except TypeError:
        raise TypeError(f"dtype must be float64, float32 or uint32, got {dtype!r}") from None
    if name not in DTYPES:
        raise TypeError(f"dtype must be float64, float32 or uint32, got {name}")
    return name


def output(out: Any, shape: tuple[int, ...], dtype: npt.DTypeLike | None) -> np.ndarray:
    """The array to write ``shape`` values into: a new one of ``dtype``
    (``None``: float64), or ``out`` after checking that it is a writeable,
    C-contiguous numpy array of that shape whose dtype is float64, float32
    or uint32 (and ``dtype``, if given)."""
    if out is None:
        return np.empty(shape, dtype=dtype_name(np.float64 if dtype is None else dtype))
    if not isinstance(out, np.ndarray):
        raise TypeError(f"out must be a numpy array, got {type(out).__name__}")
    name = dtype_name(out.dtype)
    if dtype is not None and dtype_name(dtype) != name:
        raise TypeError(f"out has dtype {name} but dtype={np.dtype(dtype).name} was asked for")
    if out.shape != shape:
        raise ValueError(f"out must have shape {shape}, got {out.shape}")
    if not out.flags.c_contiguous or not out.flags.writeable:
        raise ValueError("out must be a writeable, C-contiguous array")
    return out


def replication_seeds(seed: int, replications: int) -> list[int]:
    """The seeds of ``replications`` independent randomizations: ``seed``
    itself first, then ``SeedSequence(seed, spawn_key=(r,))``'s first
    64-bit word for ``r = 1, 2, ...``."""
    words = [int(np.random.SeedSequence(seed, spawn_key=(r,)).generate_state(1, np.uint64)[0])
             for r in range(1, replications)]
    return [seed, *words]


def sample(sample: npt.ArrayLike, *, scipy_messages: bool = True) -> np.ndarray:
    """A 2-D sample in the unit hypercube as a C-contiguous float64 array.

    Lists and arrays of any real dtype are accepted (as scipy does); complex,
    object or string arrays raise ``TypeError``; NaN, a wrong shape or a
    value outside ``[0, 1]`` raise ``ValueError`` (scipy's messages).
    """
    array = np.asarray(sample)
    if array.dtype.kind not in "biuf":
        raise TypeError(f"sample must be an array of real numbers, got dtype {array.dtype}")
    if array.ndim != 2:
        raise ValueError("Sample is not a 2D array")
    array = np.ascontiguousarray(array, dtype=np.float64)
    if array.size == 0:
        raise ValueError("Sample is empty")
    if np.isnan(array).any():
        raise ValueError("Sample contains NaN")
    if array.max() > 1.0 or array.min() < 0.0:
        raise ValueError("Sample is not in unit hypercube")
    return array


def workers(value: Any) -> int:
    """scipy's ``workers``: -1 or a positive count."""
    w = integer(value, "workers", low=-(2**63))
    if w == 0 or w < -1:
        raise ValueError(f"Invalid number of workers: {w}, must be -1 or > 0")
    # More threads than any machine's cores gain nothing (the extension's cap).
    return min(w, 1024)


#: The most dimensions a net may have (``lowdisc::net::MAX_NET_DIMENSIONS``).
MAX_NET_DIMENSIONS = 1 << 16


def net(value: Any) -> str | np.ndarray | None:
    """A ``net=`` argument: ``None``; a built-in net's name or a file (str or
    path-like, returned as a str); or generator matrices, an integer array
    of shape ``(dims, 32)`` with values in ``[0, 2**32)``, returned as a
    C-contiguous uint32 array. Anything else raises ``ValueError`` (a
    matrix that is no net is refused by the extension, also a
    ``ValueError``)."""
    if value is None:
        return None
    if isinstance(value, (str, bytes)) or hasattr(value, "__fspath__"):
        return os.fsdecode(os.fspath(value))
    array = np.asarray(value)
    if array.dtype.kind not in "iu":
        raise ValueError("net must be a name, a path or an integer array of generator "
                         f"matrices of shape (dims, 32), got dtype {array.dtype}")
    if array.ndim != 2 or array.shape[1] != 32:
        raise ValueError(f"net must have shape (dims, 32) (one row of 32 column words per "
                         f"dimension), got {array.shape}")
    if not 1 <= array.shape[0] <= MAX_NET_DIMENSIONS:
        raise ValueError(f"net must have 1 to {MAX_NET_DIMENSIONS} dimensions, "
                         f"got {array.shape[0]}")
    if array.min() < 0 or array.max() > 2**32 - 1:
        raise ValueError("net's column words must be in [0, 2**32), "
                         f"got values from {array.min()} to {array.max()}")
    return np.ascontiguousarray(array, dtype=np.uint32)
