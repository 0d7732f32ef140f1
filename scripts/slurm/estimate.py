#!/usr/bin/env python3
"""Estimates a planned experiment's wall time on N nodes from measured units.

    python3 scripts/slurm/estimate.py MEASURED_DIR TARGET_PLAN_DIR [--nodes 1,4,16]
        [--latency 1.0]

MEASURED_DIR is a plan folder whose units have run (its `units/I.json`
records give every unit's camera samples and wall time); TARGET_PLAN_DIR is
a plan folder (only `plan.json` is read: `lowdisc experiment plan --paper
--out DIR` writes it in a second, nothing is rendered). A unit's time is
fitted as `a + b * samples` by least squares over the measured units (`a`:
starting the process, loading the scene and writing the image; `b`: seconds
per camera sample on the measuring machine). The target's units are then
placed, longest first, each on the node that frees up first (LPT), every
node being a machine like the measuring one running one unit at a time on
all its cores, and `--latency` seconds added before each unit (Slurm's
scheduling, 1 s per task on the local cluster). The merge is not included.
Prints a Markdown table.
"""

import argparse
import heapq
import json
import sys
from pathlib import Path


def measured_units(folder):
    """(samples, wall seconds) of every finished unit of a plan folder."""
    points = []
    for record in sorted((folder / "units").glob("*.json")):
        unit = json.loads(record.read_text())
        if unit.get("format") == "lowdisc-experiment-unit":
            points.append((unit["samples"], unit["wall_time_s"]))
    if len(points) < 2:
        raise ValueError(f"{folder}/units holds {len(points)} finished unit(s); need 2 or more")
    return points


def fit(points):
    """Least-squares `a + b * samples`, with a >= 0."""
    n = len(points)
    mean_x = sum(x for x, _ in points) / n
    mean_y = sum(y for _, y in points) / n
    sxx = sum((x - mean_x) ** 2 for x, _ in points)
    if sxx == 0:
        raise ValueError("every measured unit has the same sample count; cannot fit")
    b = sum((x - mean_x) * (y - mean_y) for x, y in points) / sxx
    a = mean_y - b * mean_x
    if a < 0:
        a, b = 0.0, sum(y for _, y in points) / sum(x for x, _ in points)
    return a, b


def makespan(times, nodes, latency):
    """Wall time of running `times` on `nodes` machines, longest first."""
    free = [0.0] * nodes
    for t in sorted(times, reverse=True):
        start = heapq.heappop(free)
        heapq.heappush(free, start + latency + t)
    return max(free)


def hours(seconds):
    return f"{seconds / 3600:.2f} h" if seconds >= 3600 else f"{seconds / 60:.1f} min"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("measured", type=Path)
    parser.add_argument("target", type=Path)
    parser.add_argument("--nodes", default="1,2,4,8,16,32,64,128")
    parser.add_argument("--latency", type=float, default=1.0)
    args = parser.parse_args()
    try:
        a, b = fit(measured_units(args.measured))
        plan = json.loads((args.target / "plan.json").read_text())
        nodes = [int(n) for n in args.nodes.split(",")]
        if not nodes or min(nodes) < 1:
            raise ValueError("--nodes needs positive counts")
    except (OSError, ValueError, KeyError) as err:
        print(f"estimate: {err}", file=sys.stderr)
        return 1
    times = [a + b * u["samples"] for u in plan["units"]]
    print(
        f"Fit over {args.measured}: {a:.2f} s per unit + {b * 1e6:.3f} s per million "
        f"camera samples; {len(times)} units, {sum(u['samples'] for u in plan['units']):.3g} "
        f"samples, {hours(sum(times))} of unit time, the longest unit {hours(max(times))}."
    )
    print()
    print("| nodes | estimated wall time (units only) |")
    print("|---|---|")
    for n in nodes:
        print(f"| {n} | {hours(makespan(times, n, args.latency))} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
