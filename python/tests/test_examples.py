"""The notebook-style example runs, at a tiny size, and prints what it says."""

from __future__ import annotations

import subprocess
import sys

import numpy as np

from conftest import ROOT


def test_the_tour_runs_at_a_tiny_size(tmp_path):
    tour = ROOT / "python" / "examples" / "tour.py"
    result = subprocess.run(
        [sys.executable, str(tour), "--points", "256", "--size", "12", "--spp", "4",
         "--seeds", "3", "--reference-spp", "64", "--save", str(tmp_path)],
        capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    out = result.stdout
    assert "star discrepancy" in out and "95 % interval" in out, out
    reference = np.load(tmp_path / "direct-reference.npy")
    error = np.load(tmp_path / "direct-zsobol-error.npy")
    assert reference.shape == error.shape == (12, 12, 3)
    assert error.min() >= 0 and error.max() > 0
