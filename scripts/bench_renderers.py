#!/usr/bin/env python3
"""Renderer speed as a user sees it: lowdisc against Mitsuba 3 on the same scenes.

Rows (all on the same machine, in --runs interleaved rounds: each round runs
every renderer in turn, so a slow spell of the machine falls on all):
* Mitsuba's own `mi.cornell_box()` (scripts/mitsuba_cbox_pbrt.py writes it as
  a pbrt-v4 file), rendered by lowdisc as a whole process
  (`lowdisc render cbox.pbrt --spp N -o out.exr`: start-up, parsing, BVH
  build, render and EXR writing) with the `independent` sampler (Mitsuba's)
  and with `zsobol` (lowdisc's default), and by Mitsuba 3 (`llvm_ad_rgb` by
  default) as its `render` call after one untimed warm-up render (the LLVM
  variant compiles its kernels then); Mitsuba's scene load is timed
  separately;
* bmw-m6 (../shared/scenes; its missing environment map replaced by
  --envmap), lowdisc only (Mitsuba reads no pbrt files), whole process, with
  its load, BVH build and render phases from `--stats`.
Depth: Mitsuba's max_depth is lowdisc's maxdepth + 1 (Mitsuba counts the
camera segment). Russian roulette: lowdisc (as pbrt-v4) starts it after the
second scattering event, which is Mitsuba's `rr_depth` 2; Mitsuba's rows use
--mitsuba-rr-depth (default 2, the matched setting; 5 is Mitsuba's default).
Reports the best and the median time of each row as a Markdown table.

Usage:
  cargo build --release -p lowdisc-cli
  pip install -r scripts/requirements-bench.txt
  DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 \\
    python3 scripts/bench_renderers.py --lowdisc target/release/lowdisc
"""

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mitsuba_cbox_pbrt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.path.join(ROOT, "..", "shared", "scenes")


def lowdisc_run(binary, args, out):
    """One whole-process lowdisc render; returns (seconds, --stats text)."""
    t0 = time.perf_counter()
    p = subprocess.run([binary, "render", *args, "--stats", "--quiet", "-o", out],
                       check=True, capture_output=True, text=True)
    return time.perf_counter() - t0, p.stdout


def phase(stats, name):
    """The seconds of phase `name` ("load", "build (BVH)", "render") in --stats."""
    return float(re.search(r"time %s\s+([0-9.]+) s" % re.escape(name), stats).group(1))


def mitsuba_renderer(variant, spp, maxdepth, rr_depth):
    """Loads `mi.cornell_box()` in `variant`; returns (render function,
    version, load seconds). The function renders once with the given seed
    and returns its seconds; one untimed render is made here."""
    import drjit as dr
    import mitsuba as mi

    mi.set_variant(variant)
    d = mi.cornell_box()
    d["integrator"] = {"type": "path", "max_depth": maxdepth + 1, "rr_depth": rr_depth}
    d["sensor"]["sampler"]["sample_count"] = spp
    t0 = time.perf_counter()
    scene = mi.load_dict(d)
    load = time.perf_counter() - t0

    def render(seed):
        mi.set_variant(variant)
        t0 = time.perf_counter()
        img = mi.render(scene, spp=spp, seed=seed)
        dr.eval(img)
        dr.sync_thread()
        return time.perf_counter() - t0

    render(0)
    return render, mi.__version__, load


def summary(times):
    """Best and median of a list of seconds."""
    return min(times), statistics.median(times)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lowdisc", required=True, help="path of the lowdisc binary")
    ap.add_argument("--spp", type=int, default=256)
    ap.add_argument("--maxdepth", type=int, default=7,
                    help="lowdisc's maxdepth (mi.cornell_box() has max_depth 8)")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--envmap", default=os.path.join(
        SHARED, "envmaps", "polyhaven-kiara_1_dawn_1k.hdr"))
    ap.add_argument("--bmw-res", default="640x400")
    ap.add_argument("--bmw-spp", type=int, default=16)
    ap.add_argument("--variants", default="llvm_ad_rgb")
    ap.add_argument("--mitsuba-rr-depth", type=int, default=2,
                    help="Mitsuba's rr_depth (2 matches lowdisc's and pbrt-v4's roulette)")
    a = ap.parse_args()
    import mitsuba as mi

    mitsuba = []
    for variant in a.variants.split(","):
        render, version, load = mitsuba_renderer(variant, a.spp, a.maxdepth, a.mitsuba_rr_depth)
        name = "Mitsuba %s `%s`, rr_depth %d" % (version, variant, a.mitsuba_rr_depth)
        mitsuba.append((name, render, load))
    samplers = ("independent", "zsobol")
    bmw = os.path.join(SHARED, "bmw-m6", "bmw-m6.pbrt")
    have_bmw = os.path.isfile(bmw) and os.path.isfile(a.envmap)
    if not have_bmw:
        print("bmw-m6 skipped: %s or %s is absent" % (bmw, a.envmap), file=sys.stderr)
    times = {name: [] for name in samplers}
    times.update({name: [] for name, _, _ in mitsuba})
    bmw_runs = []
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "bench.exr")
        scene = {}
        for sampler in samplers:
            scene[sampler] = os.path.join(tmp, "cbox-%s.pbrt" % sampler)
            mi.set_variant("scalar_rgb")
            text = mitsuba_cbox_pbrt.pbrt_text(mi, mi.cornell_box(), a.spp, sampler)
            text = re.sub(r'"integer maxdepth" \[ \d+ \]',
                          '"integer maxdepth" [ %d ]' % a.maxdepth, text)
            with open(scene[sampler], "w") as f:
                f.write(text)
        for run in range(a.runs):
            for sampler in samplers:
                times[sampler].append(lowdisc_run(a.lowdisc, [scene[sampler]], out)[0])
            for name, render, _ in mitsuba:
                times[name].append(render(run + 1))
            if have_bmw:
                args = [bmw, "--envmap", a.envmap, "--res", a.bmw_res, "--spp", str(a.bmw_spp)]
                bmw_runs.append(lowdisc_run(a.lowdisc, args, out))
            print("round %d: %s" % (run + 1, ", ".join(
                "%s %.2f s" % (name, t[-1]) for name, t in times.items())),
                file=sys.stderr, flush=True)
    print("mi.cornell_box(): 256x256, %d spp, maxdepth %d (Mitsuba max_depth %d), "
          "%d interleaved runs\n" % (a.spp, a.maxdepth, a.maxdepth + 1, a.runs))
    print("| renderer | scene | timed | best | median |")
    print("|---|---|---|---|---|")
    for sampler in samplers:
        print("| lowdisc `%s` | mi.cornell_box() | whole process | %.2f s | %.2f s |"
              % (sampler, *summary(times[sampler])))
    for name, _, load in mitsuba:
        print("| %s | mi.cornell_box() | render call (scene load %.2f s) | %.2f s | %.2f s |"
              % (name, load, *summary(times[name])))
    if bmw_runs:
        wall = summary([t for t, _ in bmw_runs])
        parts = {p: summary([phase(s, p) for _, s in bmw_runs])
                 for p in ("load", "build (BVH)", "render")}
        print("| lowdisc `zsobol` | bmw-m6 %s, %d spp | whole process | %.2f s | %.2f s |"
              % (a.bmw_res, a.bmw_spp, *wall))
        for p, (best, median) in parts.items():
            print("| | | of which %s | %.2f s | %.2f s |" % (p, best, median))
    for sampler in samplers:
        for name, _, _ in mitsuba:
            ratio = statistics.median(times[name]) / statistics.median(times[sampler])
            print("\nlowdisc `%s` vs %s: %.2fx Mitsuba's speed (medians)"
                  % (sampler, name, ratio))


if __name__ == "__main__":
    main()
