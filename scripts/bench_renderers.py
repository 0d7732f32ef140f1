#!/usr/bin/env python3
"""Renderer speed in one run: lowdisc against Mitsuba 3 on the same Cornell box.

Times, in this order and on the same machine:
* lowdisc's built-in Cornell box with the `independent` sampler (Mitsuba's
  sampler) and with `zsobol` (lowdisc's default), best of --runs renders;
* lowdisc on bmw-m6 (../shared/scenes; its missing environment map replaced
  by --envmap), best of --runs renders, when the scene is present;
* Mitsuba 3 `scalar_rgb` and `llvm_ad_rgb` on the same Cornell box
  (scripts/mitsuba_cornell.py builds it), best of --runs renders after one
  untimed warm-up render (the LLVM variant compiles its kernels then).
All at the same resolution, spp and depth (Mitsuba's max_depth is lowdisc's
maxdepth + 1: Mitsuba counts the camera segment). lowdisc's time is its
"time render" (BVH build and file writing excluded; Mitsuba's times exclude
scene loading too), its rays/s are from --stats. Prints a Markdown table.

Usage:
  cargo build --release -p lowdisc-cli
  pip install mitsuba
  DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 \\
    python3 scripts/bench_renderers.py --lowdisc target/release/lowdisc
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mitsuba_cornell  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.path.join(ROOT, "..", "shared", "scenes")


def lowdisc_run(binary, args, out):
    """One lowdisc render; returns (seconds, rays per second, stats text)."""
    p = subprocess.run([binary, "render", *args, "--stats", "--quiet", "-o", out],
                       check=True, capture_output=True, text=True)
    t = float(re.search(r"time render\s+([0-9.]+) s", p.stdout).group(1))
    rays = float(re.search(r"rays/s\s+([0-9]+)", p.stdout).group(1))
    return t, rays, p.stdout


def best_lowdisc(binary, args, runs, tmp):
    results = [lowdisc_run(binary, args, os.path.join(tmp, "bench.exr")) for _ in range(runs)]
    return min(results, key=lambda r: r[0])


def mitsuba_best(variant, res, spp, maxdepth, runs, rr_depth):
    import drjit as dr
    import mitsuba as mi

    mi.set_variant(variant)
    with tempfile.TemporaryDirectory() as tmp:
        d = mitsuba_cornell.scene_dict(mi, tmp, res, spp, maxdepth)
        if rr_depth is not None:
            d["integrator"]["rr_depth"] = rr_depth
        scene = mi.load_dict(d)
    times = []
    for run in range(runs + 1):
        t0 = time.perf_counter()
        img = mi.render(scene, spp=spp, seed=run)
        dr.eval(img)
        dr.sync_thread()
        if run > 0:
            times.append(time.perf_counter() - t0)
    return min(times), mi.__version__


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lowdisc", required=True, help="path of the lowdisc binary")
    ap.add_argument("--res", default="1280x720")
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--maxdepth", type=int, default=5)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--envmap", default=os.path.join(
        SHARED, "envmaps", "polyhaven-kiara_1_dawn_1k.hdr"))
    ap.add_argument("--variants", default="scalar_rgb,llvm_ad_rgb")
    ap.add_argument("--mitsuba-rr-depth", type=int, default=None,
                    help="Mitsuba's rr_depth (default: Mitsuba's own, 5; lowdisc, like "
                    "pbrt-v4, starts Russian roulette after the second bounce)")
    ap.add_argument("--skip-lowdisc", action="store_true")
    a = ap.parse_args()
    res = [int(v) for v in a.res.lower().split("x")]
    common = ["--res", a.res, "--spp", str(a.spp), "--maxdepth", str(a.maxdepth)]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for sampler in () if a.skip_lowdisc else ("independent", "zsobol"):
            t, rays, _ = best_lowdisc(a.lowdisc, common + ["--sampler", sampler], a.runs, tmp)
            rows.append(("lowdisc `%s`" % sampler, "built-in Cornell box", t, rays))
        bmw = os.path.join(SHARED, "bmw-m6", "bmw-m6.pbrt")
        if a.skip_lowdisc:
            pass
        elif os.path.isfile(bmw) and os.path.isfile(a.envmap):
            t, rays, stats = best_lowdisc(
                a.lowdisc, [bmw, "--envmap", a.envmap, "--sampler", "zsobol"] + common,
                a.runs, tmp)
            bvh = re.search(r"built in ([0-9.]+) ms", stats)
            rows.append(("lowdisc `zsobol`", "bmw-m6 (BVH built in %s ms)"
                         % (bvh.group(1) if bvh else "?"), t, rays))
        else:
            print("bmw-m6 skipped: %s or %s is absent" % (bmw, a.envmap), file=sys.stderr)
    for variant in a.variants.split(","):
        t, version = mitsuba_best(variant, res, a.spp, a.maxdepth, a.runs, a.mitsuba_rr_depth)
        rr = "" if a.mitsuba_rr_depth is None else ", rr_depth %d" % a.mitsuba_rr_depth
        rows.append(("Mitsuba %s `%s`%s" % (version, variant, rr), "same Cornell box", t, None))
    print("%s, %d spp, max depth %d (Mitsuba max_depth %d), best of %d runs\n"
          % (a.res, a.spp, a.maxdepth, a.maxdepth + 1, a.runs))
    print("| renderer | scene | time | rays/s |")
    print("|---|---|---|---|")
    for name, scene, t, rays in rows:
        print("| %s | %s | %.2f s | %s |" % (
            name, scene, t, "%.2f M" % (rays / 1e6) if rays else ""))


if __name__ == "__main__":
    main()
