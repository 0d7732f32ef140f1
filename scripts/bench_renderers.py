#!/usr/bin/env python3
"""Renderer speed as a user sees it: lowdisc against Mitsuba 3 and pbrt-v4 on the same scenes.

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

With --pbrt PATH (a pbrt-v4 binary), pbrt-v4 rows beside lowdisc's, both as
whole processes on the same files in the same rounds
(`pbrt --nthreads T --spp N --seed S --quiet --outfile out.exr scene.pbrt`
and `lowdisc render scene.pbrt --threads T --seed S --quiet -o out.exr`),
each with `zsobol` and with `independent` written into the file's Sampler:
* the `mi.cornell_box()` file above (--spp, 256x256);
* ../shared/scenes bitterli-cornell-box/scene-v4.pbrt (--bitterli-res,
  --bitterli-spp; its own `path` integrator, maxdepth 65, triangle filter)
  and killeroos/killeroo-coated-gold.pbrt (--killeroo-res, --killeroo-spp),
  copies with the Film resolution and Sampler rewritten
  (scripts/pbrt_variants.py). The killeroo file names no Integrator, which is
  pbrt-v4's `volpath` (lowdisc has only `path`), so the copies name `path`
  (pbrt-v4's default maxdepth 5) for both renderers.
Depth and Russian roulette are the same rules in both: lowdisc implements
pbrt-v4's `path` integrator (maxdepth read from the file with pbrt-v4's
meaning and default 5; roulette once depth > 1, continuing with probability
max(beta * etaScale) when that is below 1). Differences that remain: pbrt-v4
always renders spectrally (4 wavelengths per camera sample), lowdisc in RGB
unless --spectral is given here (it then adds lowdisc `--spectral` rows);
pbrt-v4's `path` chooses lights with its `bvh` light sampler by default,
lowdisc by power (pbrt-v4's `power`; --pbrt-lightsampler power gives pbrt
that one). T is --threads (default: all cores, which is lowdisc's and
pbrt-v4's own default); the lowdisc commands of the rows above get
`--threads` only when it is given, as they ran before.
Reports the best and the median time of each row as a Markdown table.

Usage:
  cargo build --release -p lowdisc-cli
  pip install -r scripts/requirements-bench.txt
  DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 \\
    python3 scripts/bench_renderers.py --lowdisc target/release/lowdisc \\
    [--pbrt /path/to/pbrt --spectral] [--variants ""]
(`--variants ""` leaves Mitsuba's render out; the cornell box file still
needs the mitsuba package.) pbrt-v4 is not built by this repository: build
it yourself (CPU, Release) from its own sources and pass its `pbrt` binary.
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
import pbrt_variants  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.path.join(ROOT, "..", "shared", "scenes")


def lowdisc_run(binary, args, out):
    """One whole-process lowdisc render; returns (seconds, --stats text)."""
    t0 = time.perf_counter()
    p = subprocess.run([binary, "render", *args, "--stats", "--quiet", "-o", out],
                       check=True, capture_output=True, text=True)
    return time.perf_counter() - t0, p.stdout


def pbrt_run(binary, scene, spp, seed, threads, out):
    """One whole-process pbrt-v4 render; returns its seconds."""
    t0 = time.perf_counter()
    subprocess.run([binary, "--nthreads", str(threads), "--spp", str(spp), "--seed", str(seed),
                    "--quiet", "--outfile", out, scene], check=True, capture_output=True)
    return time.perf_counter() - t0


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


SAMPLERS = ("independent", "zsobol")


def pbrt_cases(a, tmp, cbox):
    """The scenes timed against pbrt-v4: a list of (scene label, sampler,
    lowdisc's file or None for the mi.cornell_box() rows already timed,
    pbrt-v4's file, spp). `cbox` maps each sampler to its cornell box file."""
    extra = "" if a.pbrt_lightsampler == "bvh" else (
        ' "string lightsampler" [ "%s" ]' % a.pbrt_lightsampler)
    cases = []
    for sampler in SAMPLERS:
        pbrt_file = cbox[sampler] if not extra else pbrt_variants.write_variant(
            cbox[sampler], os.path.join(tmp, "pbrt-cbox-" + sampler), integrator_extra=extra)
        cases.append(("mi.cornell_box()", sampler, None, pbrt_file, a.spp))
    shared = (("bitterli-cornell-box", "bitterli-cornell-box/scene-v4.pbrt",
               a.bitterli_res, a.bitterli_spp),
              ("killeroo-coated-gold", "killeroos/killeroo-coated-gold.pbrt",
               a.killeroo_res, a.killeroo_spp))
    for name, path, res, spp in shared:
        src = os.path.join(SHARED, path)
        for sampler in SAMPLERS:
            stem = os.path.join(tmp, "%s-%s" % (name, sampler))
            rewrite = dict(res=pbrt_variants.parse_res(res), sampler=sampler, spp=spp)
            lowdisc_file = pbrt_variants.write_variant(src, stem, integrator_extra="", **rewrite)
            pbrt_file = lowdisc_file if not extra else pbrt_variants.write_variant(
                src, stem + "-pbrt", integrator_extra=extra, **rewrite)
            label = "%s %s, %d spp" % (name, res, spp)
            cases.append((label, sampler, lowdisc_file, pbrt_file, spp))
    return cases


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
    ap.add_argument("--variants", default="llvm_ad_rgb",
                    help='Mitsuba variants, comma-separated ("" for none)')
    ap.add_argument("--mitsuba-rr-depth", type=int, default=2,
                    help="Mitsuba's rr_depth (2 matches lowdisc's and pbrt-v4's roulette)")
    ap.add_argument("--pbrt", help="path of a pbrt-v4 binary: adds the pbrt-v4 rows")
    ap.add_argument("--threads", type=int,
                    help="threads of pbrt-v4 and of lowdisc (default: all cores)")
    ap.add_argument("--pbrt-lightsampler", default="bvh", choices=("bvh", "power", "uniform"),
                    help="pbrt-v4's light sampler (bvh is its default; lowdisc's is power)")
    ap.add_argument("--spectral", action="store_true",
                    help="add lowdisc --spectral rows beside pbrt-v4's")
    ap.add_argument("--bitterli-res", default="256x256")
    ap.add_argument("--bitterli-spp", type=int, default=32)
    ap.add_argument("--killeroo-res", default="342x256")
    ap.add_argument("--killeroo-spp", type=int, default=16)
    a = ap.parse_args()
    import mitsuba as mi

    threads = a.threads or os.cpu_count()
    mitsuba = []
    for variant in filter(None, a.variants.split(",")):
        render, version, load = mitsuba_renderer(variant, a.spp, a.maxdepth, a.mitsuba_rr_depth)
        name = "Mitsuba %s `%s`, rr_depth %d" % (version, variant, a.mitsuba_rr_depth)
        mitsuba.append((name, render, load))
    bmw = os.path.join(SHARED, "bmw-m6", "bmw-m6.pbrt")
    have_bmw = os.path.isfile(bmw) and os.path.isfile(a.envmap)
    if not have_bmw:
        print("bmw-m6 skipped: %s or %s is absent" % (bmw, a.envmap), file=sys.stderr)
    times = {name: [] for name in SAMPLERS}
    times.update({name: [] for name, _, _ in mitsuba})
    bmw_runs = []
    ld_threads = ["--threads", str(a.threads)] if a.threads else []
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "bench.exr")
        scene = {}
        for sampler in SAMPLERS:
            scene[sampler] = os.path.join(tmp, "cbox-%s.pbrt" % sampler)
            mi.set_variant("scalar_rgb")
            text = mitsuba_cbox_pbrt.pbrt_text(mi, mi.cornell_box(), a.spp, sampler)
            text = re.sub(r'"integer maxdepth" \[ \d+ \]',
                          '"integer maxdepth" [ %d ]' % a.maxdepth, text)
            with open(scene[sampler], "w") as f:
                f.write(text)
        cases = pbrt_cases(a, tmp, scene) if a.pbrt else []
        modes = [("", [])] + ([(" --spectral", ["--spectral"])] if a.spectral else [])
        for label, sampler, lowdisc_file, _, _ in cases:
            for mode, _ in modes:
                if lowdisc_file or mode:
                    times["lowdisc `%s`%s, %s" % (sampler, mode, label)] = []
            times["pbrt-v4 `%s`, %s" % (sampler, label)] = []
        for run in range(a.runs):
            for sampler in SAMPLERS:
                times[sampler].append(lowdisc_run(a.lowdisc, [scene[sampler], *ld_threads], out)[0])
            for name, render, _ in mitsuba:
                times[name].append(render(run + 1))
            if have_bmw:
                # --approximate: the scene asks for Integrator "regularize".
                args = [bmw, "--approximate", "--envmap", a.envmap, "--res", a.bmw_res,
                        "--spp", str(a.bmw_spp),
                        *ld_threads]
                bmw_runs.append(lowdisc_run(a.lowdisc, args, out))
            for label, sampler, lowdisc_file, pbrt_file, spp in cases:
                seed = ["--seed", str(run + 1), "--threads", str(threads)]
                for mode, flags in modes:
                    if lowdisc_file or mode:
                        args = [lowdisc_file or scene[sampler], *seed, *flags]
                        times["lowdisc `%s`%s, %s" % (sampler, mode, label)].append(
                            lowdisc_run(a.lowdisc, args, out)[0])
                times["pbrt-v4 `%s`, %s" % (sampler, label)].append(
                    pbrt_run(a.pbrt, pbrt_file, spp, run + 1, threads, out))
            print("round %d: %s" % (run + 1, ", ".join(
                "%s %.2f s" % (name, t[-1]) for name, t in times.items())),
                file=sys.stderr, flush=True)
    print("mi.cornell_box(): 256x256, %d spp, maxdepth %d (Mitsuba max_depth %d), "
          "%d interleaved runs\n" % (a.spp, a.maxdepth, a.maxdepth + 1, a.runs))
    print("| renderer | scene | timed | best | median |")
    print("|---|---|---|---|---|")
    for sampler in SAMPLERS:
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
    for label, sampler, lowdisc_file, _, _ in cases:
        for mode, _ in modes:
            if lowdisc_file or mode:
                print("| lowdisc `%s`%s | %s | whole process | %.2f s | %.2f s |"
                      % (sampler, mode, label,
                         *summary(times["lowdisc `%s`%s, %s" % (sampler, mode, label)])))
        print("| pbrt-v4 `%s`, %s light sampler | %s | whole process | %.2f s | %.2f s |"
              % (sampler, a.pbrt_lightsampler, label,
                 *summary(times["pbrt-v4 `%s`, %s" % (sampler, label)])))
    for sampler in SAMPLERS:
        for name, _, _ in mitsuba:
            ratio = statistics.median(times[name]) / statistics.median(times[sampler])
            print("\nlowdisc `%s` vs %s: %.2fx Mitsuba's speed (medians)"
                  % (sampler, name, ratio))
    if cases:
        print("\npbrt-v4 (%s, %d threads) against lowdisc, medians:" % (a.pbrt, threads))
    for label, sampler, lowdisc_file, _, _ in cases:
        pbrt_median = statistics.median(times["pbrt-v4 `%s`, %s" % (sampler, label)])
        for mode, _ in modes:
            key = "lowdisc `%s`%s, %s" % (sampler, mode, label) if lowdisc_file or mode else sampler
            print("* lowdisc `%s`%s on %s: %.2fx pbrt-v4's speed"
                  % (sampler, mode, label, pbrt_median / statistics.median(times[key])))


if __name__ == "__main__":
    main()
