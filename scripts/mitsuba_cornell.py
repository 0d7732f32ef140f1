#!/usr/bin/env python3
"""Render lowdisc's built-in Cornell box with Mitsuba 3 and print time and speed.

The scene is built here from the same geometry as crates/render/src/cornell.rs
(the published Cornell Box Data quads in millimetres, the same RGB
reflectances and light radiance, camera at (278, 273, -800) looking at
(278, 273, 0), 39.3076 degrees field of view on the smaller axis, box pixel
filter of radius 0.5). It is NOT mitsuba's own `mi.cornell_box()`, which is a
different (unit-sized) scene.

Differences that remain: Mitsuba samples with its `independent` sampler;
Mitsuba counts depth differently (its max_depth 1 is emission only), so
lowdisc's maxdepth D is Mitsuba's max_depth D + 1; Mitsuba's Russian roulette
starts at depth 5 (rr_depth), lowdisc's at its own default. Mitsuba does not
report rays traced, so the comparison is by time and pixel samples per second;
lowdisc's `--stats` gives both.

Usage:
  pip install mitsuba
  python3 scripts/mitsuba_cornell.py --variant scalar_rgb --res 1280x720 --spp 16 --maxdepth 5
  # llvm_ad_rgb needs LLVM >= 16, e.g. Debian's libllvm19:
  DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 \\
    python3 scripts/mitsuba_cornell.py --variant llvm_ad_rgb
Compare with:
  lowdisc render --res 1280x720 --spp 16 --maxdepth 5 --stats -o cbox.exr
"""

import argparse
import os
import tempfile
import time

WHITE = [0.725, 0.71, 0.68]
RED = [0.63, 0.065, 0.05]
GREEN = [0.14, 0.45, 0.091]
LIGHT_RGB = [17.0, 11.8, 4.0]

FLOOR = [[552.8, 0, 0], [0, 0, 0], [0, 0, 559.2], [549.6, 0, 559.2]]
BACK = [[549.6, 0, 559.2], [0, 0, 559.2], [0, 548.8, 559.2], [556, 548.8, 559.2]]
GREEN_WALL = [[0, 0, 559.2], [0, 0, 0], [0, 548.8, 0], [0, 548.8, 559.2]]
RED_WALL = [[552.8, 0, 0], [549.6, 0, 559.2], [556, 548.8, 559.2], [556, 548.8, 0]]
LIGHT = [[343, 548.8, 227], [343, 548.8, 332], [213, 548.8, 332], [213, 548.8, 227]]


def block(top, h):
    """The five quads (top and four sides) of a block with top corners `top`."""
    quads = [[[x, h, z] for x, z in top]]
    for i in range(4):
        (x0, z0), (x1, z1) = top[i], top[(i + 1) % 4]
        quads.append([[x0, 0, z0], [x0, h, z0], [x1, h, z1], [x1, 0, z1]])
    return quads


SHORT = block([(130, 65), (82, 225), (240, 272), (290, 114)], 165)
TALL = block([(423, 247), (265, 296), (314, 456), (472, 406)], 330)


def ceiling():
    y = 548.8

    def rect(x0, x1, z0, z1):
        return [[x0, y, z0], [x0, y, z1], [x1, y, z1], [x1, y, z0]]

    return [rect(0, 556, 0, 227), rect(0, 556, 332, 559.2),
            rect(0, 213, 227, 332), rect(343, 556, 227, 332)]


def write_obj(path, quads):
    """Writes `quads` as an OBJ of two triangles each (lowdisc's winding)."""
    with open(path, "w") as f:
        for q in quads:
            for v in q:
                f.write("v %g %g %g\n" % tuple(v))
        for i in range(len(quads)):
            b = 4 * i + 1
            f.write("f %d %d %d\n" % (b, b + 1, b + 2))
            f.write("f %d %d %d\n" % (b, b + 2, b + 3))


def scene_dict(mi, tmp, res, spp, maxdepth):
    """The Mitsuba scene dictionary (meshes written as OBJ files into `tmp`)."""

    def diffuse(rgb):
        return {"type": "twosided",
                "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": rgb}}}

    d = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": maxdepth + 1},
        "sensor": {
            "type": "perspective",
            "fov": 39.3076,
            "fov_axis": "smaller",
            "to_world": mi.ScalarTransform4f().look_at(
                origin=[278, 273, -800], target=[278, 273, 0], up=[0, 1, 0]),
            "sampler": {"type": "independent", "sample_count": spp},
            "film": {"type": "hdrfilm", "width": res[0], "height": res[1],
                     "rfilter": {"type": "box"}},
        },
    }
    shapes = {
        "white": ([FLOOR, BACK] + ceiling() + SHORT + TALL, diffuse(WHITE)),
        "red": ([RED_WALL], diffuse(RED)),
        "green": ([GREEN_WALL], diffuse(GREEN)),
        "light": ([LIGHT], diffuse([0.0, 0.0, 0.0])),
    }
    for name, (quads, bsdf) in shapes.items():
        path = os.path.join(tmp, name + ".obj")
        write_obj(path, quads)
        d[name] = {"type": "obj", "filename": path, "face_normals": True, "bsdf": bsdf}
    # One-sided emitter on the side of the light quad's normal (facing down).
    d["light"]["emitter"] = {"type": "area", "radiance": {"type": "rgb", "value": LIGHT_RGB}}
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--variant", default="scalar_rgb")
    ap.add_argument("--res", default="1280x720")
    ap.add_argument("--spp", type=int, default=16)
    ap.add_argument("--maxdepth", type=int, default=5)
    ap.add_argument("--runs", type=int, default=2, help="renders to time (the first includes JIT)")
    ap.add_argument("-o", "--output", default=None, help="write the image (.exr or .png)")
    a = ap.parse_args()
    import mitsuba as mi
    import drjit as dr

    mi.set_variant(a.variant)
    res = [int(v) for v in a.res.lower().split("x")]
    with tempfile.TemporaryDirectory() as tmp:
        scene = mi.load_dict(scene_dict(mi, tmp, res, a.spp, a.maxdepth))
    samples = res[0] * res[1] * a.spp
    for run in range(a.runs):
        t0 = time.perf_counter()
        img = mi.render(scene, spp=a.spp, seed=run)
        dr.eval(img)
        dr.sync_thread()
        dt = time.perf_counter() - t0
        print("mitsuba %s %s run %d: %.3f s, %.3f M samples/s (%dx%d, %d spp, max_depth %d)"
              % (mi.__version__, a.variant, run + 1, dt, samples / dt / 1e6,
                 res[0], res[1], a.spp, a.maxdepth + 1), flush=True)
    if a.output:
        mi.util.write_bitmap(a.output, img)


if __name__ == "__main__":
    main()
