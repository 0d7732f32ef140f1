"""The Examples sections of the package's docstrings run as printed."""

from __future__ import annotations

import doctest
import importlib

import numpy as np
import pytest

import lowdisc

MODULES = ["lowdisc", "lowdisc._points", "lowdisc._metrics", "lowdisc.qmc", "lowdisc._render",
           "lowdisc._images"]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples_run(name):
    module = importlib.import_module(name)
    # numpy's repr of scalars changed in 2.0; the examples print plain floats.
    with np.printoptions(legacy=False):
        failed, attempted = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert failed == 0, f"{failed} of {attempted} examples of {name} failed (output above)"


def test_every_public_function_has_an_example():
    missing = [name for name in lowdisc.__all__
               if callable(getattr(lowdisc, name)) and not isinstance(getattr(lowdisc, name), type)
               and ">>>" not in (getattr(lowdisc, name).__doc__ or "")]
    assert not missing, f"no Examples section: {missing}"
