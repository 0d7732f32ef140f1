"""lowdisc: sample sequences and their metrics as numpy arrays.

* Points: :func:`sobol` (exact Owen scrambling and more), :func:`halton`,
  :func:`independent`, :func:`stratified`, and :func:`pixel_samples`, the
  renderer's pixel samplers (every ``--sampler`` of the ``lowdisc`` CLI).
* Metrics: :func:`discrepancy`, :func:`update_discrepancy` and
  :func:`geometric_discrepancy` (scipy's signatures and conventions),
  :func:`star_discrepancy` (exact), :func:`star_bounds`,
  :func:`min_distance` (also toroidal), :func:`power_spectrum`.
* Renders: :func:`render`, the path tracer of ``lowdisc render`` (the same
  bits), returning a ``(height, width, 3)`` float32 array; the experiment's
  measures on arrays: :func:`errors`, :func:`mse`, :func:`relmse`,
  :func:`blurred_mse`, :func:`flip`, :func:`error_image`, and
  :func:`compare` (the paired-seed ratio with its 95 % interval).
* :mod:`lowdisc.qmc`: ``scipy.stats.qmc`` with lowdisc's ``Sobol`` and
  ``Halton`` engines and metrics (``from lowdisc import qmc``).
* Interop: :func:`sobol_matrices`, :func:`qmcpy_generating_matrices`.

scipy is optional: only :mod:`lowdisc.qmc` (for its base class and the
names it re-exports) and a few ``geometric_discrepancy`` options use it.
The user guide is ``docs/guide/python.md``.
"""

from . import qmc
from ._images import (
    RELMSE_EPSILON,
    Comparison,
    ImageErrors,
    blurred_mse,
    compare,
    error_image,
    errors,
    flip,
    mse,
    relmse,
)
from ._metrics import (
    DEFAULT_DISCREPANCY_WORK,
    DEFAULT_MAX_WORK,
    StarBounds,
    discrepancy,
    geometric_discrepancy,
    min_distance,
    nearest_neighbour_distances,
    power_spectrum,
    star_bounds,
    star_discrepancy,
    star_work,
    update_discrepancy,
)
from ._points import (
    HALTON_DIMENSIONS,
    HALTON_SCRAMBLES,
    SOBOL_DIMENSIONS,
    SOBOL_SCRAMBLES,
    halton,
    independent,
    pixel_samples,
    qmcpy_generating_matrices,
    sampler_names,
    sobol,
    sobol_matrices,
    stratified,
)
from ._render import BUILTIN_SCENES, render

__version__ = "0.1.0"

__all__ = [
    "BUILTIN_SCENES",
    "Comparison",
    "DEFAULT_DISCREPANCY_WORK",
    "DEFAULT_MAX_WORK",
    "HALTON_DIMENSIONS",
    "HALTON_SCRAMBLES",
    "ImageErrors",
    "RELMSE_EPSILON",
    "SOBOL_DIMENSIONS",
    "SOBOL_SCRAMBLES",
    "StarBounds",
    "blurred_mse",
    "compare",
    "discrepancy",
    "error_image",
    "errors",
    "flip",
    "geometric_discrepancy",
    "halton",
    "independent",
    "min_distance",
    "mse",
    "nearest_neighbour_distances",
    "pixel_samples",
    "power_spectrum",
    "qmc",
    "qmcpy_generating_matrices",
    "relmse",
    "render",
    "sampler_names",
    "sobol",
    "sobol_matrices",
    "star_bounds",
    "star_discrepancy",
    "star_work",
    "stratified",
    "update_discrepancy",
]
