#!/usr/bin/env python3
"""The sampler study: Burley 2020 Fig. 1 (a) and (b) and the paper's idea repaired.

Runs `lowdisc experiment --preset direct` and `--preset gi` on the samplers
of Burley's figure (B. Burley, "Practical Hash-based Owen Scrambling",
JCGT 9(4), 2020, Fig. 1: RMSE at 16 spp on a Cornell box) and on the
Matousek LMS + digital shift samplers, then prints from each results.json:

1. the Burley table: every sampler's RMSE (mean +- SE over the seeds, 95 %
   Student-t interval), its paired ratio to unscrambled global `sobol` with
   the interval and verdict, the masked-MSE ratio, and Burley's number;
2. the order check: for each pair of neighbours in Burley's order, the
   paired RMSE ratio of the worse to the better and whether its interval
   agrees with his order, contradicts it, or cannot tell;
3. the LMS table: `sobol-lms` and `padded-sobol-lms` against `sobol`,
   `paper` and `paper-repro` in every compared metric.

Paired ratios are geometric means of per-seed ratios with a t interval on
the log-ratios, as `lowdisc experiment` computes them (the RMSE ratio is
the square root of the MSE ratio). The t factor is read back from
results.json (its intervals' half-width over the standard error), so this
script needs only the Python standard library.

The Z-order runs (`--runs zorder-direct,zorder-gi,zorder-cornell`) compare
the Z-order candidates against `zsobol`, `sobol` and `independent` (issue
11's goal) on the direct preset, the GI preset at 64x64 and the Bitterli
Cornell box (and `zorder-bmw`, bmw-m6 under an environment map), and print
each candidate's masked, blurred and FLIP ratios; `--candidates` runs a
subset of the candidates (Z-order variants and `cascaded-sobol`).

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
METRICS = ["masked_mse", "mse", "relmse", "blurred_mse", "flip"]
# The study's runs: name (the output folder) -> preset, resolution, runs, reference spp.
SETTINGS = {
    "direct": ("direct", "128x128", 16, 4096),
    "gi": ("gi", "128x128", 16, 4096),
    "gi-64": ("gi", "64x64", 16, 1024),
    # The built-in showroom scene (no preset), with zsobol added; its
    # convergence series at 128x72 against a 16-spp reference.
    "builtin": (None, "256x144", 8, 1024),
}
SPP = 16
# The Z-order study: name -> (scene arguments, resolution, runs, reference spp).
SHARED = Path(__file__).resolve().parent.parent.parent / "shared" / "scenes"
ZORDER = {
    "zorder-direct": (["--preset", "direct"], "128x128", 16, 4096),
    "zorder-gi": (["--preset", "gi"], "64x64", 16, 2048),
    "zorder-cornell": ([str(SHARED / "bitterli-cornell-box" / "scene-v4.pbrt")], "64x64", 16, 1024),
    # --approximate: bmw-m6 asks for Integrator "regularize", which lowdisc lacks.
    "zorder-bmw": ([str(SHARED / "bmw-m6" / "bmw-m6.pbrt"), "--approximate", "--envmap",
                    str(SHARED / "envmaps" / "polyhaven-kiara_1_dawn_1k.hdr")], "96x68", 16, 1024),
}
ZORDER_BASELINES = ["independent", "sobol", "zsobol"]
ZORDER_CANDIDATES = ["zsobol-4d", "zorder-sz", "cascaded-sobol"]
# Issue 11's goal: masked MSE at most these multiples of each baseline.
GOAL = {"zorder-direct": {"sobol": 0.80, "independent": 0.168}, "zorder-gi": {"zsobol": 0.90},
        "zorder-cornell": {"zsobol": 0.90}, "zorder-bmw": {"zsobol": 0.90}}


def run(lowdisc, out, name, candidates):
    if name in ZORDER:
        scene, res, runs, ref_spp = ZORDER[name]
        cmd = [lowdisc, "experiment", *scene, "--samplers",
               ",".join(ZORDER_BASELINES + candidates), "--res", res, "--runs", str(runs),
               "--spp", str(SPP), "--ref-spp", str(ref_spp), "--conv-max", "1", "--conv-res", res,
               "--conv-ref-spp", str(ref_spp), "--out", str(out / name)]
        print("+", " ".join(cmd), file=sys.stderr)
        subprocess.run(cmd, check=True)
        return
    preset, res, runs, ref_spp = SETTINGS[name]
    scene = ["--preset", preset] if preset else []
    samplers = SAMPLERS if preset else SAMPLERS + ["zsobol"]
    conv = ["--conv-res", res, "--conv-ref-spp", str(ref_spp)] if preset else [
        "--conv-res", "128x72", "--conv-ref-spp", "16"]
    cmd = [
        lowdisc, "experiment", *scene, "--samplers", ",".join(samplers),
        "--res", res, "--runs", str(runs), "--spp", str(SPP), "--ref-spp", str(ref_spp),
        "--conv-max", "1", *conv, "--out", str(out / name),
    ]
    print("+", " ".join(cmd), file=sys.stderr)
    subprocess.run(cmd, check=True)


def t_factor(results):
    """The 95 % t factor of the runs, from any interval with a positive SE."""
    for s in results["samplers"]:
        for m in s["statistics"]:
            su = m["summary"]
            if su["se"] > 0:
                return (su["ci95"][1] - su["mean"]) / su["se"]
    raise SystemExit("no sampler with a positive standard error")


def column(sampler, metric):
    if metric == "rmse":
        return [r["linear"]["rmse"] for r in sampler["runs"]]
    if metric == "masked_rmse":
        return [math.sqrt(r["quality"]["masked"]["mse"]) for r in sampler["runs"]]
    if metric in ("mse", "relmse"):
        return [r["linear"][metric] for r in sampler["runs"]]
    if metric in ("masked_mse", "masked_relmse"):
        return [r["quality"]["masked"][metric.split("_")[1]] for r in sampler["runs"]]
    return [r["quality"][metric] for r in sampler["runs"]]


def summary(values, t):
    n = len(values)
    mean = sum(values) / n
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1))
    se = sd / math.sqrt(n)
    return mean, se, (mean - t * se, mean + t * se)


def paired(a, b, t):
    """Geometric-mean ratio a/b over paired seeds, 95 % interval, verdict."""
    logs = [math.log(x / y) for x, y in zip(a, b)]
    mean, se, (lo, hi) = summary(logs, t)
    ratio, ci = math.exp(mean), (math.exp(lo), math.exp(hi))
    verdict = "better" if ci[1] < 1 else "worse" if ci[0] > 1 else "not distinguishable"
    return ratio, ci, verdict


def fmt_ratio(r):
    return f"{r[0]:.3f} [{r[1][0]:.3f}, {r[1][1]:.3f}]"


def tables(path, name):
    results = json.loads(path.read_text())
    preset = SETTINGS[name][0]
    t = t_factor(results)
    by = {s["name"]: s for s in results["samplers"]}
    col = {"direct": 2, "gi": 3}.get(preset)
    st = results["settings"]
    lines = [
        f"### {f'Preset `{preset}`' if preset else 'Built-in scene'}: {st['width']}x{st['height']}, {st['spp']} spp, "
        f"{st['runs']} seeds, reference {st['ref_spp']} spp `{st['ref_sampler']}`, "
        f"{100 * results['kept_fraction']:.1f} % of pixels kept by the mask, "
        f"wall {results['wall_time_s']:.0f} s",
        "",
        "| sampler | Burley's RMSE | RMSE mean ± SE | 95 % CI | RMSE / sobol [95 % CI] | verdict "
        "| masked RMSE mean ± SE | masked RMSE / sobol [95 % CI] | verdict |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    base = by["sobol"]
    burley = {b[1]: b[col] for b in BURLEY} if col else {}
    for s in results["samplers"]:
        name = s["name"]
        mean, se, ci = summary(column(s, "rmse"), t)
        row = [f"`{name}`", f"{burley[name]:.4f}" if name in burley else "",
               f"{mean:.5f} ± {se:.5f}", f"[{ci[0]:.5f}, {ci[1]:.5f}]"]
        for metric in ("rmse", "masked_rmse"):
            if metric == "masked_rmse":
                mean, se, _ = summary(column(s, metric), t)
                row.append(f"{mean:.5f} ± {se:.5f}")
            if name == "sobol":
                row += ["1", "baseline"]
            else:
                r = paired(column(s, metric), column(base, metric), t)
                row += [fmt_ratio(r), r[2]]
        lines.append("| " + " | ".join(row) + " |")
    lines += ["", "Burley's order, neighbour by neighbour (RMSE ratio of the one he found "
              "worse to the one he found better, paired seeds):", "",
              "| worse (Burley) | better (Burley) | his ratio | ours, RMSE [95 % CI] | order "
              "| ours, masked RMSE [95 % CI] | order |",
              "|---|---|---|---|---|---|---|"]
    for worse, better in zip(BURLEY, BURLEY[1:]):
        his = f"{worse[col] / better[col]:.2f}" if col else ""
        row = [f"`{worse[1]}`", f"`{better[1]}`", his]
        for metric in ("rmse", "masked_rmse"):
            r = paired(column(by[worse[1]], metric), column(by[better[1]], metric), t)
            row += [fmt_ratio(r), "agrees" if r[1][0] > 1 else "contradicts"
                    if r[1][1] < 1 else "not distinguishable"]
        lines.append("| " + " | ".join(row) + " |")
    lines += ["", "LMS + shift against the paper's baselines (ratio [95 % CI], "
              "below 1 = less error):", "",
              "| sampler | against | " + " | ".join(METRICS) + " |",
              "|---|---|" + "---|" * len(METRICS)]
    for name in LMS:
        for other in LMS_BASELINES:
            cells = []
            for metric in METRICS:
                r = paired(column(by[name], metric), column(by[other], metric), t)
                cells.append(f"{fmt_ratio(r)} {r[2]}")
            lines.append(f"| `{name}` | `{other}` | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def zorder_tables(path, name):
    """Each Z-order candidate against the baselines, with the goal's verdict."""
    results = json.loads(path.read_text())
    t = t_factor(results)
    by = {s["name"]: s for s in results["samplers"]}
    st = results["settings"]
    lines = [
        f"### {name}: {st['width']}x{st['height']}, {st['spp']} spp, {st['runs']} paired seeds, "
        f"reference {st['ref_spp']} spp `{st['ref_sampler']}`, depth {st['max_depth']}, "
        f"{100 * results['kept_fraction']:.1f} % of pixels kept by the mask, "
        f"wall {results['wall_time_s']:.0f} s",
        "",
        "| sampler | masked MSE ± SE | / independent | / sobol | / zsobol | blurred / zsobol "
        "| FLIP / zsobol | goal |",
        "|---|---|---|---|---|---|---|---|",
    ]
    goal = GOAL.get(name, {})
    candidates = [c for c in ZORDER_CANDIDATES if c in by]
    for cand in ["zsobol"] + candidates:
        mean, se, _ = summary(column(by[cand], "masked_mse"), t)
        row, met = [f"`{cand}`", f"{mean:.4e} ± {se:.1e}"], []
        for base in ZORDER_BASELINES:
            r = paired(column(by[cand], "masked_mse"), column(by[base], "masked_mse"), t)
            row.append("1" if base == cand else fmt_ratio(r))
            if base in goal:
                met.append(f"{'met' if r[1][1] <= goal[base] else 'not met'} "
                           f"(≤ {goal[base]} x {base})")
        for metric in ("blurred_mse", "flip"):
            r = paired(column(by[cand], metric), column(by["zsobol"], metric), t)
            row.append("1" if cand == "zsobol" else f"{fmt_ratio(r)} {r[2]}")
        row.append("; ".join(met) if cand != "zsobol" else "")
        lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines) + "\n"


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--lowdisc", default="target/release/lowdisc")
    p.add_argument("--out", type=Path, default=Path("out/study"))
    p.add_argument("--tables-only", action="store_true",
                   help="only print the tables of existing results.json files")
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
        if not a.tables_only:
            run(a.lowdisc, a.out, name, candidates)
        table = zorder_tables if name in ZORDER else tables
        print(table(a.out / name / "results.json", name))


if __name__ == "__main__":
    main()
