#!/usr/bin/env python3
"""Writes crates/lowdisc/tests/data/scipy_sobol.txt: unscrambled Sobol digit words
from scipy.stats.qmc.Sobol (an independent implementation of the Joe-Kuo 2008
direction numbers), used by the value tests of the Sobol core.

Each line: `k dim word` where word = floor(x * 2^32) of point k (scipy's order,
which is Gray-code order) in dimension dim. Run from the repository root:
    python3 scripts/scipy_sobol_fixture.py
"""
import numpy as np
from scipy.stats import qmc

DIMS = list(range(0, 12)) + [100, 1000, 5000, 12345, 21199, 21200]
STARTS = [(0, 64), (1_000_000, 8), (2**31 - 4, 8), (2**32 - 8, 8)]

lines = []
eng = qmc.Sobol(d=21201, scramble=False, bits=32)
# The first points come from scipy's generator itself.
first = np.floor(eng.random(64) * 2.0**32).astype(np.uint64)
# scipy's fast_forward walks every skipped point, so far-away points are
# computed from scipy's own direction numbers (`_sv`, one row of 32 columns per
# dimension) in scipy's Gray-code order: point k = XOR of the columns of the
# set bits of k ^ (k >> 1).
sv = eng._sv


def far_point(k, d):
    g = k ^ (k >> 1)
    w = 0
    for c in range(32):
        if (g >> c) & 1:
            w ^= int(sv[d, c])
    return w


for start, count in STARTS:
    for i in range(count):
        for d in DIMS:
            k = start + i
            w = int(first[k, d]) if k < 64 else far_point(k, d)
            lines.append(f"{k} {d} {w}")
with open("crates/lowdisc/tests/data/scipy_sobol.txt", "w") as f:
    f.write("# k dim word: scipy %s qmc.Sobol(d=21201, scramble=False, bits=32), point k in dim\n" % __import__("scipy").__version__)
    f.write("\n".join(lines) + "\n")
print(len(lines), "values")
