"""Benchmark of lowdisc's Python package against scipy and qmcpy, run once
on one machine; prints a Markdown table (not a test: nothing is asserted).

    python -P python/bench.py         # the pinned versions: scripts/requirements-bench.txt

Each figure is the best and the median of ``--repeat`` rounds (wall-clock,
all cores allowed for every library); the rounds of a row alternate between
the libraries, so a change of the machine's load hits both. The first Sobol
rows are floors for everyone: numpy filling a fresh 512 MiB float64 array
with one thread, then with two (the page faults and writes of the output,
which every library pays; the second row's speed-up is the most any
two-thread generator can reach against scipy's scrambled Sobol).
"""

from __future__ import annotations

import argparse
import os
import platform
import statistics
import threading
import time

import numpy as np

import lowdisc
from lowdisc import qmc as lqmc


def timed(fn):
    t = time.perf_counter()
    fn()
    return time.perf_counter() - t


def rounds(fns, repeat):
    """Times of each function over ``repeat`` interleaved rounds."""
    times = [[] for _ in fns]
    for _ in range(repeat):
        for fn, t in zip(fns, times):
            t.append(timed(fn))
    return times


def cell(times):
    return f"{min(times):.3f} / {statistics.median(times):.3f}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--qmcpy-log2n", type=int, default=14,
                        help="log2 of the points for the qmcpy NUS row (its NUS is a "
                             "Python-level tree per dimension: 2^20 points took over "
                             "14 minutes here)")
    parser.add_argument("--tasks", default="floor,sobol,qmcpy,discrepancy,star",
                        help="comma-separated rows to run (default: all)")
    args = parser.parse_args()
    tasks = set(args.tasks.split(","))
    from scipy.stats import qmc

    try:
        import qmcpy
    except ImportError:
        qmcpy = None
    n, d = 2**20, 64
    print(f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores; "
          f"numpy {np.__version__}, scipy {__import__('scipy').__version__}, "
          f"qmcpy {getattr(qmcpy, '__version__', 'not installed')}; "
          f"best / median of {args.repeat} rounds, load average {os.getloadavg()[0]:.1f}")
    print()
    print("| task | lowdisc | s | other | s | speed-up (best, median) |")
    print("|---|---|---:|---|---:|---:|", flush=True)

    def row(task, ours_name, ours, theirs_name, theirs):
        if theirs is None:
            [t_ours] = rounds([ours], args.repeat)
            cells = (task, ours_name, cell(t_ours), theirs_name, "-", "-")
        else:
            t_ours, t_theirs = rounds([ours, theirs], args.repeat)
            ratio = (f"{min(t_theirs) / min(t_ours):.1f}x, "
                     f"{statistics.median(t_theirs) / statistics.median(t_ours):.1f}x")
            cells = (task, ours_name, cell(t_ours), theirs_name, cell(t_theirs), ratio)
        print("| " + " | ".join(cells) + " |", flush=True)

    task = f"Sobol d={d}, 2^20 points"
    if "floor" in tasks:
        floor_rows(row, task, n, d, qmc)
    if "sobol" in tasks:
        sobol_rows(row, task, n, d, qmc)
    if "qmcpy" in tasks:
        qmcpy_row(row, args.qmcpy_log2n, d, qmcpy)
    if "discrepancy" in tasks:
        discrepancy_rows(row, qmc)
    if "star" in tasks:
        y = lowdisc.sobol(65536, 2, scramble="owen-tree", seed=1)
        row("exact star discrepancy, 65,536 2-D points", "lowdisc.star_discrepancy",
            lambda: lowdisc.star_discrepancy(y), "(scipy and qmcpy have none)", None)


def two_thread_fill(n, d):
    """A fresh (n, d) float64 array written by two threads (``np.copyto``
    releases the GIL): about the least the output of any two-thread
    generator costs."""
    a = np.empty((n, d))
    threads = [threading.Thread(target=np.copyto, args=(half, 0.5))
               for half in (a[: n // 2], a[n // 2:])]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return a


def floor_rows(row, task, n, d, qmc):
    """Owen-scrambled Sobol against the floors (the bare output's cost) and
    scipy's scrambled Sobol, each pair interleaved; a speed-up below 1 is
    the floor's time over lowdisc's."""
    owen = lambda: lqmc.Sobol(d, seed=1).random(n)  # noqa: E731
    row(task, "lowdisc.qmc.Sobol (Owen, owen-tree)", owen,
        "(floor) `np.empty((n, d)).fill(0.5)`", lambda: np.empty((n, d)).fill(0.5))
    row(task, "lowdisc.qmc.Sobol (Owen, owen-tree)", owen,
        "(floor, 2 threads) `np.copyto` into a fresh array", lambda: two_thread_fill(n, d))
    row(task, "lowdisc.qmc.Sobol (Owen, owen-tree)", owen,
        "scipy Sobol(scramble=True) (LMS+shift)", lambda: qmc.Sobol(d, seed=1).random(n))


def sobol_rows(row, task, n, d, qmc):
    row(task, "(floor) `np.empty((n, d)).fill(0.5)`",
        lambda: np.empty((n, d)).fill(0.5),
        "scipy Sobol(scramble=False)",
        lambda: qmc.Sobol(d, scramble=False).random(n))
    row(task, "(floor, 2 threads) `np.copyto` into a fresh array",
        lambda: two_thread_fill(n, d),
        "scipy Sobol(scramble=True) (LMS+shift)",
        lambda: qmc.Sobol(d, seed=1).random(n))
    row(task, "lowdisc.qmc.Sobol(scramble=False)",
        lambda: lqmc.Sobol(d, scramble=False).random(n),
        "scipy Sobol(scramble=False)",
        lambda: qmc.Sobol(d, scramble=False).random(n))
    row(task, "lowdisc.qmc.Sobol(scramble=False)",
        lambda: lqmc.Sobol(d, scramble=False).random(n),
        "scipy Sobol(scramble=True) (LMS+shift)",
        lambda: qmc.Sobol(d, seed=1).random(n))
    row(task, "lowdisc.qmc.Sobol (Owen, owen-tree)",
        lambda: lqmc.Sobol(d, seed=1).random(n),
        "scipy Sobol(scramble=True) (LMS+shift)",
        lambda: qmc.Sobol(d, seed=1).random(n))
    row(task, "lowdisc.qmc.Sobol(randomize='owen')",
        lambda: lqmc.Sobol(d, seed=1, randomize="owen").random(n),
        "scipy Sobol(scramble=True) (LMS+shift)",
        lambda: qmc.Sobol(d, seed=1).random(n))
    row(task, "lowdisc.qmc.Sobol(randomize='fast-owen')",
        lambda: lqmc.Sobol(d, seed=1, randomize="fast-owen").random(n),
        "scipy Sobol(scramble=True) (LMS+shift)",
        lambda: qmc.Sobol(d, seed=1).random(n))


def qmcpy_row(row, log2n, d, qmcpy):
    qmcpy_nus = None
    small = 2**log2n
    if qmcpy is not None:
        def qmcpy_nus():
            qmcpy.DigitalNetB2(d, seed=1, randomize="NUS").gen_samples(small, warn=False)
    row(f"Sobol d={d}, 2^{log2n} points", "lowdisc.qmc.Sobol (Owen)",
        lambda: lqmc.Sobol(d, seed=1).random(small),
        "qmcpy DigitalNetB2(randomize='NUS')", qmcpy_nus)


def discrepancy_rows(row, qmc):
    x = lowdisc.sobol(4096, 8, scramble="owen", seed=1)
    for method in ("CD", "L2-star"):
        row(f"discrepancy {method}, n=4096, d=8", "lowdisc.discrepancy",
            lambda m=method: lowdisc.discrepancy(x, method=m),
            "scipy qmc.discrepancy (workers=1)",
            lambda m=method: qmc.discrepancy(x, method=m))
        row(f"discrepancy {method}, n=4096, d=8", "lowdisc.discrepancy",
            lambda m=method: lowdisc.discrepancy(x, method=m),
            "scipy qmc.discrepancy (workers=-1)",
            lambda m=method: qmc.discrepancy(x, method=m, workers=-1))


if __name__ == "__main__":
    main()
