#!/usr/bin/env python3
"""Compares `lowdisc points --sampler sobol --format u32` with scipy.

Usage: python3 scripts/compare_scipy.py [N] [DIMS] [LOWDISC_BINARY]
(defaults: 65536 1024 target/release/lowdisc). Prints the number of values
compared and exits non-zero on the first mismatch. scipy's unscrambled Sobol
with bits=32 is an independent implementation of the Joe-Kuo direction
numbers; it emits points in Gray-code order, as lowdisc does by default.
"""
import subprocess
import sys
import time

import numpy as np
from scipy.stats import qmc

n = int(sys.argv[1]) if len(sys.argv) > 1 else 65536
dims = int(sys.argv[2]) if len(sys.argv) > 2 else 1024
binary = sys.argv[3] if len(sys.argv) > 3 else "target/release/lowdisc"

t0 = time.time()
out = subprocess.run(
    [binary, "points", "--sampler", "sobol", "--n", str(n), "--dims", str(dims), "--format", "u32"],
    check=True,
    capture_output=True,
).stdout
t1 = time.time()
ours = np.array(out.split(), dtype=np.uint64).reshape(n, dims)
lines = out.count(b"\n")
theirs = np.floor(qmc.Sobol(d=dims, scramble=False, bits=32).random(n) * 2.0**32).astype(np.uint64)
t2 = time.time()
if lines != n:
    sys.exit(f"expected {n} lines, got {lines}")
bad = np.argwhere(ours != theirs)
if len(bad):
    i, d = bad[0]
    sys.exit(f"mismatch at point {i} dimension {d}: lowdisc {ours[i, d]} scipy {theirs[i, d]} ({len(bad)} mismatches)")
print(f"identical: {n} points x {dims} dimensions = {n * dims} values "
      f"(lowdisc printed {len(out)} bytes in {t1 - t0:.1f} s; scipy {__import__('scipy').__version__} in {t2 - t1:.1f} s)")
