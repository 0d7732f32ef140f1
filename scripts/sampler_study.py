#!/usr/bin/env python3
"""The sampler study: Burley 2020 Fig. 1 (a) and (b) and the paper's idea repaired.

Runs `lowdisc study` on the samplers of Burley's figure (B. Burley,
"Practical Hash-based Owen Scrambling", JCGT 9(4), 2020, Fig. 1: RMSE at
16 spp on a Cornell box) and on the Matousek LMS + digital shift samplers,
then prints from each study.json:

1. the Burley table: every sampler's paired RMSE ratio to unscrambled
   global `sobol` with its 95 % interval and verdict, the masked RMSE
   ratio, and Burley's RMSE and ratio;
2. the order check: for each pair of neighbours in Burley's order, the
   paired RMSE ratio of the worse to the better and whether its interval
   agrees with his order, contradicts it, or cannot tell;
3. the LMS table: `sobol-lms` and `padded-sobol-lms` against `sobol`,
   `paper` and `paper-repro` in every compared metric.

Every ratio and interval is computed by `lowdisc study` (paired seeds,
geometric mean of per-seed ratios, Student-t interval on the log-ratios;
with one scene per run, the study's pooled ratio is the scene's paired
ratio). An RMSE ratio is the square root of the MSE ratio, interval
included. This script only chooses the runs and formats the tables.

The Z-order runs (`--runs zorder-direct,zorder-gi,zorder-cornell,zorder-bmw`)
compare the Z-order candidates against `zsobol`, `sobol` and `independent`
on the direct preset, the GI preset at 64x64, the Bitterli Cornell box and
bmw-m6 under an environment map, and print each candidate's masked,
blurred and FLIP ratios with the goal's verdict; `--candidates` runs a
subset of the candidates.

Usage: scripts/sampler_study.py [--lowdisc BIN] [--out DIR] [--runs LIST]
       [--candidates LIST] [--tables-only]
"""

import argparse
import json
import math
import subprocess
import sys
from pathlib import Path

# Burley 2020, Fig. 1: (his label, our sampler, RMSE (a) direct, RMSE (b) GI + DoF),
# worst to best.
BURLEY = [
    ("independent random", "independent", 0.020, 0.017),
    ("Laine-Karras scrambled Sobol", "laine-karras", 0.0065, 0.0075),
    ("per-pixel Sobol + random digital shift", "sobol-pixel-xor", 0.0048, 0.0053),
    ("global image-plane Sobol", "sobol", 0.0021, 0.0043),
    ("Owen-scrambled Sobol, shuffled index, 4-D padding", "sobol-burley", 0.0017, 0.0040),
]
LMS = ["sobol-lms", "padded-sobol-lms"]
LMS_BASELINES = ["sobol", "paper", "paper-repro"]
EXTRA = ["paper", "paper-repro"]
SAMPLERS = [b[1] for b in BURLEY] + LMS + EXTRA
METRICS = ["masked_mse", "mse", "blurred_mse", "flip"]
# The study's runs: name (the output folder) -> scene, resolution, runs, reference spp.
SETTINGS = {
    "direct": ("direct", "128x128", 16, 4096),
    "gi": ("gi", "128x128", 16, 4096),
    "gi-64": ("gi", "64x64", 16, 1024),
    # The built-in showroom scene, with zsobol added.
    "builtin": ("builtin", "256x144", 8, 1024),
}
SPP = 16
SHARED = Path(__file__).resolve().parent.parent.parent / "shared" / "scenes"
# The Z-order study: name -> (scene, resolution, runs, reference spp).
ZORDER = {
    "zorder-direct": ("direct", "128x128", 16, 4096),
    "zorder-gi": ("gi", "64x64", 16, 2048),
    "zorder-cornell": ("cornell-box", "64x64", 16, 1024),
    "zorder-bmw": ("bmw-m6", "96x68", 16, 1024),
}
ZORDER_BASELINES = ["independent", "sobol", "zsobol"]
ZORDER_CANDIDATES = ["zsobol-4d", "zorder-sz", "cascaded-sobol"]
# Issue 11's goal: masked MSE at most these multiples of each baseline.
GOAL = {"zorder-direct": {"sobol": 0.80, "independent": 0.168}, "zorder-gi": {"zsobol": 0.90},
        "zorder-cornell": {"zsobol": 0.90}, "zorder-bmw": {"zsobol": 0.90}}


def study(lowdisc, out, scene, res, runs, ref_spp, samplers, baselines):
    cmd = [lowdisc, "study", "--scenes", scene, "--shared", str(SHARED),
           "--samplers", ",".join(samplers), "--baseline", ",".join(baselines),
           "--res", res, "--runs", str(runs), "--spp", str(SPP), "--ref-spp", str(ref_spp),
           "--out", str(out)]
    print("+", " ".join(cmd), file=sys.stderr)
    subprocess.run(cmd, check=True)


def run(lowdisc, out, name, candidates):
    if name in ZORDER:
        scene, res, runs, ref_spp = ZORDER[name]
        samplers = ZORDER_BASELINES + candidates
        study(lowdisc, out / name, scene, res, runs, ref_spp, samplers, ZORDER_BASELINES)
        return
    scene, res, runs, ref_spp = SETTINGS[name]
    samplers = SAMPLERS if scene != "builtin" else SAMPLERS + ["zsobol"]
    baselines = ["sobol"] + [b[1] for b in BURLEY if b[1] != "sobol"] + ["paper", "paper-repro"]
    study(lowdisc, out / name, scene, res, runs, ref_spp, samplers, baselines)


def ratio(results, sampler, baseline, metric, root=False):
    """(ratio, [lo, hi]) of `sampler` to `baseline` in `metric` from study.json."""
    s = next(s for s in results["results"]["samplers"] if s["sampler"] == sampler)
    r = next(r for r in s["ratios"] if r["baseline"] == baseline)
    p = next(m for m in r["metrics"] if m["metric"] == metric)["pooled"]
    f = math.sqrt if root else (lambda x: x)
    return f(p["ratio"]), [f(p["ci95"][0]), f(p["ci95"][1])]


def verdict(r):
    return "better" if r[1][1] < 1 else "worse" if r[1][0] > 1 else "not distinguishable"


def fmt_ratio(r):
    return f"{r[0]:.3f} [{r[1][0]:.3f}, {r[1][1]:.3f}]"


def header(results, name):
    st = results["settings"]
    scene = results["results"]["scenes"][0]
    return (f"### {name}: `{scene['source']}`, {st['width']}x{st['height']}, {st['spp']} spp, "
            f"{st['runs']} paired seeds, reference {st['ref_spp']} spp, "
            f"{100 * scene['kept_fraction']:.1f} % of pixels kept by the mask, "
            f"wall {results['results']['wall_time_s']:.0f} s")


def tables(path, name):
    results = json.loads(path.read_text())
    col = {"direct": 2, "gi": 3}.get(SETTINGS[name][0])
    lines = [header(results, name), "",
             "| sampler | Burley's RMSE | RMSE / sobol [95 % CI] | verdict "
             "| masked RMSE / sobol [95 % CI] | verdict |",
             "|---|---|---|---|---|---|"]
    burley = {b[1]: b[col] for b in BURLEY} if col else {}
    for s in results["results"]["samplers"]:
        name_s = s["sampler"]
        row = [f"`{name_s}`", f"{burley[name_s]:.4f}" if name_s in burley else ""]
        for metric in ("mse", "masked_mse"):
            if name_s == "sobol":
                row += ["1", "baseline"]
            else:
                r = ratio(results, name_s, "sobol", metric, root=True)
                row += [fmt_ratio(r), verdict(r)]
        lines.append("| " + " | ".join(row) + " |")
    lines += ["", "Burley's order, neighbour by neighbour (RMSE ratio of the one he found "
              "worse to the one he found better, paired seeds):", "",
              "| worse (Burley) | better (Burley) | his ratio | ours, RMSE [95 % CI] | order "
              "| ours, masked RMSE [95 % CI] | order |",
              "|---|---|---|---|---|---|---|"]
    for worse, better in zip(BURLEY, BURLEY[1:]):
        his = f"{worse[col] / better[col]:.2f}" if col else ""
        row = [f"`{worse[1]}`", f"`{better[1]}`", his]
        for metric in ("mse", "masked_mse"):
            r = ratio(results, worse[1], better[1], metric, root=True)
            row += [fmt_ratio(r), "agrees" if r[1][0] > 1 else "contradicts"
                    if r[1][1] < 1 else "not distinguishable"]
        lines.append("| " + " | ".join(row) + " |")
    lines += ["", "LMS + shift against the paper's baselines (ratio [95 % CI], "
              "below 1 = less error):", "",
              "| sampler | against | " + " | ".join(METRICS) + " |",
              "|---|---|" + "---|" * len(METRICS)]
    for name_s in LMS:
        for other in LMS_BASELINES:
            cells = []
            for metric in METRICS:
                r = ratio(results, name_s, other, metric)
                cells.append(f"{fmt_ratio(r)} {verdict(r)}")
            lines.append(f"| `{name_s}` | `{other}` | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def zorder_tables(path, name):
    """Each Z-order candidate against the baselines, with the goal's verdict."""
    results = json.loads(path.read_text())
    names = [s["sampler"] for s in results["results"]["samplers"]]
    lines = [header(results, name), "",
             "| sampler | / independent | / sobol | / zsobol | blurred / zsobol "
             "| FLIP / zsobol | structure | goal |",
             "|---|---|---|---|---|---|---|---|"]
    goal = GOAL.get(name, {})
    for cand in ["zsobol"] + [c for c in ZORDER_CANDIDATES if c in names]:
        row, met = [f"`{cand}`"], []
        for base in ZORDER_BASELINES:
            r = ratio(results, cand, base, "masked_mse")
            row.append("1" if base == cand else fmt_ratio(r))
            if base in goal:
                met.append(f"{'met' if r[1][1] <= goal[base] else 'not met'} "
                           f"(≤ {goal[base]} x {base})")
        for metric in ("blurred_mse", "flip"):
            r = ratio(results, cand, "zsobol", metric)
            row.append("1" if cand == "zsobol" else f"{fmt_ratio(r)} {verdict(r)}")
        s = next(s for s in results["results"]["samplers"] if s["sampler"] == cand)
        row.append(f"{s['structure']['mean']:.2f}")
        row.append("; ".join(met) if cand != "zsobol" else "")
        lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines) + "\n"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lowdisc", default="target/release/lowdisc")
    p.add_argument("--out", type=Path, default=Path("out/study"))
    p.add_argument("--tables-only", action="store_true",
                   help="only print the tables of existing study.json files")
    p.add_argument("--runs", default="direct,gi,gi-64",
                   help="which of the study's runs: " + ", ".join([*SETTINGS, *ZORDER]))
    p.add_argument("--candidates", default=",".join(ZORDER_CANDIDATES),
                   help="the Z-order runs' candidates (the baselines always run; seeds are "
                   "paired by run index, so a subset gives the same values): "
                   + ", ".join(ZORDER_CANDIDATES))
    a = p.parse_args()
    candidates = a.candidates.split(",")
    unknown = sorted(set(candidates) - set(ZORDER_CANDIDATES))
    if unknown:
        raise SystemExit(f"unknown candidates: {', '.join(unknown)}")
    for name in a.runs.split(","):
        if name not in SETTINGS and name not in ZORDER:
            raise SystemExit(f"unknown run `{name}`")
        if not a.tables_only:
            run(a.lowdisc, a.out, name, candidates)
        table = zorder_tables if name in ZORDER else tables
        print(table(a.out / name / "study.json", name))


if __name__ == "__main__":
    main()
