#!/usr/bin/env python3
"""Write Mitsuba 3's own `mi.cornell_box()` scene as a pbrt-v4 scene file.

`mi.cornell_box()` is the unit-sized Cornell box of Mitsuba's tutorials
(256x256, Gaussian pixel filter, `path` integrator with max_depth 8). The
scene's rectangles and cubes are evaluated with Mitsuba's own transforms and
written as world-space triangle meshes, so both renderers see the same
triangles; the reflectances and the light's radiance are copied from the
dictionary. Mapping:
* camera: Mitsuba's right-handed `look_at` is pbrt's `Scale -1 1 1` + `LookAt`
  (same image, not mirrored); `fov` on the smaller axis is pbrt's `fov`;
* film: `rgb`, same resolution; Mitsuba's `gaussian` filter (stddev 0.5,
  radius 4 stddev) is pbrt's `gaussian` with sigma 0.5 and radius 2;
* depth: Mitsuba's max_depth D (which counts the camera segment) is pbrt's
  `maxdepth` D - 1; the emitter is one-sided on the side of the light's normal
  (facing down), as in Mitsuba; every `diffuse` is two-sided in both;
* Russian roulette cannot be set in a pbrt file: lowdisc (as pbrt-v4) starts
  it after the second scattering event, which is Mitsuba's `rr_depth` 2
  (scripts/bench_renderers.py sets that, and reports Mitsuba's default 5 too).

Usage:
  pip install -r scripts/requirements-bench.txt
  python3 scripts/mitsuba_cbox_pbrt.py -o cbox.pbrt --spp 256 --sampler independent
  lowdisc render cbox.pbrt -o cbox.exr
"""

import argparse

# Mitsuba's cube: [-1, 1]^3, faces as vertex-index quads wound outwards.
CUBE_CORNERS = [[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
CUBE_QUADS = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]
# Mitsuba's rectangle: [-1, 1]^2 at z = 0, normal +z.
RECT_CORNERS = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]


def mesh_of(mi, shape):
    """World-space (points, triangles) of a `rectangle` or `cube` entry."""
    if shape["type"] == "rectangle":
        corners, quads = RECT_CORNERS, [[0, 1, 2, 3]]
    elif shape["type"] == "cube":
        corners, quads = CUBE_CORNERS, CUBE_QUADS
    else:
        raise SystemExit("unsupported shape type %r" % shape["type"])
    to_world = shape["to_world"]
    points = [list(to_world @ mi.ScalarPoint3f(c)) for c in corners]
    tris = []
    for a, b, c, d in quads:
        tris += [[a, b, c], [a, c, d]]
    return points, tris


def pbrt_text(mi, scene, spp, sampler):
    """The pbrt-v4 file for Mitsuba scene dictionary `scene`."""
    sensor = scene["sensor"]
    m = sensor["to_world"].matrix
    eye = [m[i][3] for i in range(3)]
    fwd = [m[i][2] for i in range(3)]
    up = [m[i][1] for i in range(3)]
    look = [e + f for e, f in zip(eye, fwd)]
    film = sensor["film"]
    depth = scene["integrator"]["max_depth"] - 1
    fmt = lambda v: " ".join("%.9g" % float(x) for x in v)  # noqa: E731
    out = [
        "# Mitsuba 3's mi.cornell_box(), written by scripts/mitsuba_cbox_pbrt.py",
        "Scale -1 1 1",
        "LookAt %s  %s  %s" % (fmt(eye), fmt(look), fmt(up)),
        'Camera "perspective" "float fov" [ %g ]' % sensor["fov"],
        'Film "rgb" "integer xresolution" [ %d ] "integer yresolution" [ %d ]'
        % (film["width"], film["height"]),
        '    "string filename" [ "cbox.exr" ]',
        'PixelFilter "gaussian" "float sigma" [ 0.5 ] "float xradius" [ 2 ] "float yradius" [ 2 ]',
        'Sampler "%s" "integer pixelsamples" [ %d ]' % (sampler, spp),
        'Integrator "path" "integer maxdepth" [ %d ]' % depth,
        "WorldBegin",
    ]
    for name, entry in scene.items():
        if not isinstance(entry, dict) or entry.get("type") not in ("rectangle", "cube"):
            continue
        rgb = scene[entry["bsdf"]["id"]]["reflectance"]["value"]
        points, tris = mesh_of(mi, entry)
        out.append("# %s" % name)
        out.append("AttributeBegin")
        out.append('  Material "diffuse" "rgb reflectance" [ %s ]' % fmt(rgb))
        if "emitter" in entry:
            le = entry["emitter"]["radiance"]["value"]
            out.append('  AreaLightSource "diffuse" "rgb L" [ %s ]' % fmt(le))
        out.append('  Shape "trianglemesh"')
        out.append('    "point3 P" [ %s ]' % " ".join(fmt(p) for p in points))
        out.append('    "integer indices" [ %s ]' % " ".join(fmt(t) for t in tris))
        out.append("AttributeEnd")
    return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("-o", "--output", required=True, help="the pbrt-v4 file to write")
    ap.add_argument("--spp", type=int, default=256)
    ap.add_argument("--sampler", default="independent", help="pbrt-v4 sampler name")
    a = ap.parse_args()
    import mitsuba as mi

    mi.set_variant("scalar_rgb")
    text = pbrt_text(mi, mi.cornell_box(), a.spp, a.sampler)
    with open(a.output, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
