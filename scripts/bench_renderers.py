#!/usr/bin/env python3
"""Renderer speed in one run: lowdisc against Mitsuba 3 on the same Cornell box.

Times on the same machine, in --runs interleaved rounds (each round renders
with every renderer in turn, so a slow spell of the machine falls on all):
* lowdisc's built-in Cornell box with the `independent` sampler (Mitsuba's
  sampler) and with `zsobol` (lowdisc's default);
* Mitsuba 3 `scalar_rgb` and `llvm_ad_rgb` on the same Cornell box
  (scripts/mitsuba_cornell.py builds it), after one untimed warm-up render
  each (the LLVM variant compiles its kernels then);
then lowdisc on bmw-m6 (../shared/scenes; its missing environment map
replaced by --envmap), --runs renders, when the scene is present. Reports the
best and the median time of each.
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
import statistics
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


def mitsuba_renderer(variant, res, spp, maxdepth, rr_depth):
    """Loads the Cornell box in `variant`; returns (render function, version).

    The function renders once with the given seed and returns its seconds.
    One untimed render is made here (the LLVM variant compiles its kernels).
    """
    import drjit as dr
    import mitsuba as mi

    mi.set_variant(variant)
    with tempfile.TemporaryDirectory() as tmp:
        d = mitsuba_cornell.scene_dict(mi, tmp, res, spp, maxdepth)
        if rr_depth is not None:
            d["integrator"]["rr_depth"] = rr_depth
        scene = mi.load_dict(d)

    def render(seed):
        mi.set_variant(variant)
        t0 = time.perf_counter()
        img = mi.render(scene, spp=spp, seed=seed)
        dr.eval(img)
        dr.sync_thread()
        return time.perf_counter() - t0

    render(0)
    return render, mi.__version__


def summary(times):
    """Best and median of a list of seconds."""
    return min(times), statistics.median(times)


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
    mitsuba = []
    for variant in a.variants.split(","):
        render, version = mitsuba_renderer(variant, res, a.spp, a.maxdepth, a.mitsuba_rr_depth)
        rr = "" if a.mitsuba_rr_depth is None else ", rr_depth %d" % a.mitsuba_rr_depth
        mitsuba.append(("Mitsuba %s `%s`%s" % (version, variant, rr), render))
    samplers = () if a.skip_lowdisc else ("independent", "zsobol")
    # Rounds interleave the renderers, so that a slow spell of the machine
    # falls on all of them alike.
    times = {name: [] for name in samplers}
    times.update({name: [] for name, _ in mitsuba})
    rays_of = {}  # rays/s of each lowdisc sampler's fastest run
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "bench.exr")
        for run in range(a.runs):
            for sampler in samplers:
                t, rays, _ = lowdisc_run(a.lowdisc, common + ["--sampler", sampler], out)
                if not times[sampler] or t < min(times[sampler]):
                    rays_of[sampler] = rays
                times[sampler].append(t)
            for name, render in mitsuba:
                times[name].append(render(run + 1))
        for sampler in samplers:
            rows.append(("lowdisc `%s`" % sampler, "built-in Cornell box",
                         *summary(times[sampler]), rays_of[sampler]))
        for name, _ in mitsuba:
            rows.append((name, "same Cornell box", *summary(times[name]), None))
        bmw = os.path.join(SHARED, "bmw-m6", "bmw-m6.pbrt")
        if a.skip_lowdisc:
            pass
        elif os.path.isfile(bmw) and os.path.isfile(a.envmap):
            results = [lowdisc_run(a.lowdisc, [bmw, "--envmap", a.envmap, "--sampler", "zsobol"]
                                   + common, out) for _ in range(a.runs)]
            bvh = re.search(r"built in ([0-9.]+) ms", results[0][2])
            rows.append(("lowdisc `zsobol`", "bmw-m6 (BVH built in %s ms)"
                         % (bvh.group(1) if bvh else "?"), *summary([r[0] for r in results]),
                         max(r[1] for r in results)))
        else:
            print("bmw-m6 skipped: %s or %s is absent" % (bmw, a.envmap), file=sys.stderr)
    print("%s, %d spp, max depth %d (Mitsuba max_depth %d), %d interleaved runs\n"
          % (a.res, a.spp, a.maxdepth, a.maxdepth + 1, a.runs))
    print("| renderer | scene | best | median | rays/s (best run) |")
    print("|---|---|---|---|---|")
    for name, scene, best, median, rays in rows:
        print("| %s | %s | %.2f s | %.2f s | %s |" % (
            name, scene, best, median, "%.2f M" % (rays / 1e6) if rays else ""))


if __name__ == "__main__":
    main()
