#!/usr/bin/env python3
"""Generates the bad-input corpus: small fixture files in files/ and the case
list manifest.json, read by crates/cli/tests/corpus.rs.

Run from anywhere: python3 crates/cli/tests/corpus/generate.py
Expected outcomes (exit code, message class, files left) are recorded by the
test itself: LOWDISC_CORPUS_RECORD=1 cargo test -p lowdisc-cli --test corpus
rewrites manifest.json's "expect" fields from a run (review the diff!).
Existing expectations are kept for cases whose id and arguments are unchanged.

In arguments, {F} stands for the fixture folder; the working directory of
every case is a fresh empty folder, so relative outputs land there.
"""

import json
import os
import shutil
import sys

sys.dont_write_bytecode = True  # keep the fixture folder free of __pycache__
import formats  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
FILES = os.path.join(HERE, "files")
CASES = []


def case(group, cid, args, fault="none", old=False):
    CASES.append({"id": f"{group}/{cid}", "group": group, "args": args,
                  "fault": fault, "old_output": old})


def write(name, data):
    path = os.path.join(FILES, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())
    return "{F}/" + name


HEADER = """LookAt 0 0 -5  0 0 0  0 1 0
Camera "perspective" "float fov" [ 45 ]
Film "rgb" "integer xresolution" [ 8 ] "integer yresolution" [ 8 ] "string filename" "out.exr"
Sampler "zsobol" "integer pixelsamples" [ 1 ]
Integrator "path" "integer maxdepth" [ 3 ]
"""
WORLD = """WorldBegin
LightSource "point" "rgb I" [ 4 4 4 ] "point3 from" [ 0 0 -3 ]
Material "diffuse" "rgb reflectance" [ 0.5 0.5 0.5 ]
Shape "sphere" "float radius" [ 1 ]
"""
BASE = HEADER + WORLD


def render(scene_ref, *extra):
    return ["render", scene_ref, "-o", "out.exr", *extra]


def scene(cid, text, *extra, group="scene"):
    data = text if isinstance(text, bytes) else text.encode()
    case(group, cid, render(write(f"{group}/{cid}.pbrt", data), *extra))


def scene_syntax():
    scene("base", BASE)
    tokens = BASE.split()
    # Every prefix at a token boundary: a file cut short anywhere.
    for k in range(len(tokens)):
        scene(f"prefix-{k:02}", " ".join(tokens[:k]) + "\n")
    # Cut inside a token (strings, numbers, brackets).
    for k in range(5, len(BASE), 37):
        scene(f"cut-{k:03}", BASE[:k])
    lines = BASE.splitlines()
    for i in range(len(lines)):
        scene(f"drop-line-{i}", "\n".join(lines[:i] + lines[i + 1:]) + "\n")
        scene(f"twice-line-{i}", "\n".join(lines[:i + 1] + lines[i:]) + "\n")
    for i, line in enumerate(lines):
        word = line.split()[0]
        scene(f"misspelt-{i}", BASE.replace(word, word.lower() + "x", 1))
    specials = {
        "empty": "",
        "only-comments": "# nothing\n# here\n",
        "bom": "\ufeff" + BASE,
        "only-bom": "\ufeff",
        "crlf": BASE.replace("\n", "\r\n"),
        "tabs": BASE.replace(" ", "\t"),
        "nul-bytes": BASE.replace("WorldBegin", "World\0Begin"),
        "unterminated-string": BASE.replace('"sphere"', '"sphere'),
        "unbalanced-open": BASE.replace("[ 1 ]", "[ 1"),
        "unbalanced-close": BASE.replace("[ 1 ]", "1 ]"),
        "nested-brackets": BASE.replace("[ 1 ]", "[ [ 1 ] ]"),
        "empty-list": BASE.replace('"float radius" [ 1 ]', '"float radius" [ ]'),
        "long-list": BASE.replace('"float radius" [ 1 ]', '"float radius" [ 1 2 3 ]'),
        "no-value": BASE.replace('"float radius" [ 1 ]', '"float radius"'),
        "bad-decl": BASE.replace('"float radius"', '"float"'),
        "bad-type": BASE.replace('"float radius"', '"quaternion radius"'),
        "string-for-number": BASE.replace("[ 1 ]", '[ "one" ]'),
        "number-for-string": BASE.replace('"sphere"', "42"),
        "unknown-shape": BASE.replace('"sphere"', '"teapot"'),
        "unknown-material": BASE.replace('"diffuse"', '"velvet"'),
        "unknown-light": BASE.replace('"point"', '"laser"'),
        "unknown-camera": BASE.replace('"perspective"', '"fisheye"'),
        "unknown-sampler": BASE.replace('"zsobol"', '"magic"'),
        "unknown-param": BASE.replace('"float radius"', '"float radiuss"'),
        "no-worldbegin": HEADER + "\n".join(WORLD.splitlines()[1:]) + "\n",
        "camera-after-world": BASE + 'Camera "perspective" "float fov" [ 90 ]\n',
        "two-worldbegin": BASE + "WorldBegin\n",
        "unclosed-attribute": BASE.replace("Material", "AttributeBegin\nMaterial"),
        "unclosed-transform": BASE.replace("Material", "TransformBegin\nMaterial"),
        "extra-attribute-end": BASE + "AttributeEnd\n",
        "directive-garbage": BASE + "]]]]\n",
        "comment-no-newline": BASE + "# end",
        "invalid-utf8": BASE.encode() + b"# \xff\xfe\xc3\n",
        "only-worldbegin": "WorldBegin\n",
        "undefined-named-material": BASE.replace('Material "diffuse" "rgb reflectance" [ 0.5 0.5 0.5 ]', 'NamedMaterial "nowhere"'),
        "undefined-texture": BASE.replace('"rgb reflectance" [ 0.5 0.5 0.5 ]', '"texture reflectance" "nowhere"'),
        "float-texture-as-reflectance": BASE.replace("Material", 'Texture "t" "float" "constant" "float value" [ 0.5 ]\nMaterial').replace('"rgb reflectance" [ 0.5 0.5 0.5 ]', '"texture reflectance" "t"'),
        "spectrum-texture-as-roughness": BASE.replace("Material", 'Texture "c" "spectrum" "constant" "rgb value" [ 0.5 0.5 0.5 ]\nMaterial').replace('"diffuse" "rgb reflectance" [ 0.5 0.5 0.5 ]', '"conductor" "texture roughness" "c"'),
        "long-list-string": BASE.replace('"out.exr"', '[ "out.exr" "other.exr" ]'),
        "long-list-integer": BASE.replace('"integer maxdepth" [ 3 ]', '"integer maxdepth" [ 3 4 ]'),
        "long-list-point3": BASE.replace('"point3 from" [ 0 0 -3 ]', '"point3 from" [ 0 0 -3 0 0 3 ]'),
        "empty-list-point3": BASE.replace('"point3 from" [ 0 0 -3 ]', '"point3 from" [ ]'),
        "empty-list-bool": BASE.replace('Shape "sphere"', 'Material "conductor" "bool remaproughness" [ ]\nShape "sphere"'),
        "texture-file-missing": BASE.replace("Material", 'Texture "t" "spectrum" "imagemap" "string filename" "nowhere.png"\nMaterial').replace('"rgb reflectance" [ 0.5 0.5 0.5 ]', '"texture reflectance" "t"'),
        "texture-file-unused-missing": BASE.replace("Material", 'Texture "t" "float" "imagemap" "string filename" "nowhere.exr"\nMaterial'),
        "envmap-file-missing": BASE.replace('LightSource "point"', 'LightSource "infinite" "string filename" "nowhere.exr"\nLightSource "point"'),
        "object-instance-missing": BASE + 'ObjectInstance "nothing"\n',
        "crop-inverted": BASE.replace('"string filename"', '"float cropwindow" [ 0.9 0.1 0 1 ] "string filename"'),
        "crop-outside": BASE.replace('"string filename"', '"float cropwindow" [ -1 2 0 1 ] "string filename"'),
        "pixelbounds-empty": BASE.replace('"string filename"', '"integer pixelbounds" [ 4 4 0 8 ] "string filename"'),
        "film-huge": BASE.replace("[ 8 ] \"integer y", "[ 65536 ] \"integer y").replace("yresolution\" [ 8 ]", "yresolution\" [ 65536 ]"),
        "film-20000": BASE.replace("[ 8 ] \"integer y", "[ 20000 ] \"integer y").replace("yresolution\" [ 8 ]", "yresolution\" [ 20000 ]"),
        "film-output-dir": BASE.replace('"out.exr"', '"nowhere/out.exr"'),
        "film-output-jpg": BASE.replace('"out.exr"', '"out.jpg"'),
        "singular-scale": BASE.replace("WorldBegin", "Scale 0 0 0\nWorldBegin"),
        "singular-lookat": BASE.replace("LookAt 0 0 -5  0 0 0  0 1 0", "LookAt 0 0 0  0 0 0  0 1 0"),
        "degenerate-up": BASE.replace("LookAt 0 0 -5  0 0 0  0 1 0", "LookAt 0 0 -5  0 0 0  0 0 1"),
        "transform-short": BASE.replace("WorldBegin", "Transform [ 1 0 0 ]\nWorldBegin"),
        "concat-nan": BASE.replace("WorldBegin", "ConcatTransform [ nan 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 ]\nWorldBegin"),
        "coordsys-unknown": BASE.replace("WorldBegin", 'CoordSysTransform "nowhere"\nWorldBegin'),
        "trianglemesh-bad-index": BASE.replace('Shape "sphere" "float radius" [ 1 ]', 'Shape "trianglemesh" "integer indices" [ 0 1 7 ] "point3 P" [ 0 0 0 1 0 0 0 1 0 ]'),
        "trianglemesh-negative": BASE.replace('Shape "sphere" "float radius" [ 1 ]', 'Shape "trianglemesh" "integer indices" [ 0 1 -2 ] "point3 P" [ 0 0 0 1 0 0 0 1 0 ]'),
        "trianglemesh-ragged": BASE.replace('Shape "sphere" "float radius" [ 1 ]', 'Shape "trianglemesh" "integer indices" [ 0 1 ] "point3 P" [ 0 0 0 1 0 0 0 1 ]'),
        "trianglemesh-empty": BASE.replace('Shape "sphere" "float radius" [ 1 ]', 'Shape "trianglemesh"'),
        "spectrum-file-missing": BASE.replace('"rgb I" [ 4 4 4 ]', '"spectrum I" "nowhere.spd"'),
        "spectrum-odd": BASE.replace('"rgb I" [ 4 4 4 ]', '"spectrum I" [ 400 1 500 ]'),
        "blackbody-negative": BASE.replace('"rgb I" [ 4 4 4 ]', '"blackbody I" [ -5 ]'),
        "rgb-short": BASE.replace('"rgb I" [ 4 4 4 ]', '"rgb I" [ 4 4 ]'),
    }
    for cid, text in specials.items():
        scene(cid, text)
    # pbrt-v4 features lowdisc lacks are errors; --approximate renders them
    # with a warning.
    for cid in ("unknown-shape", "unknown-material", "unknown-light", "unknown-camera"):
        case("scene", f"{cid}-approximate", render(f"{{F}}/scene/{cid}.pbrt", "--approximate"))
    # A scene directory, a device and a missing file given as the scene.
    os.makedirs(os.path.join(FILES, "scene/folder.pbrt"), exist_ok=True)
    write("scene/folder.pbrt/.keep", "")
    case("scene", "scene-is-directory", render("{F}/scene/folder.pbrt"))
    case("scene", "scene-is-dev-zero", render("/dev/zero"))
    case("scene", "scene-is-dev-null", render("/dev/null"))
    case("scene", "scene-missing", render("{F}/scene/missing.pbrt"))


NUMBERS = ["nan", "inf", "-inf", "1e999", "-1", "0", "2147483647", "2147483648",
           "-2147483649", "1e-320", "1.5", "abc"]
NUMERIC = {
    "xres": '"integer xresolution" [ 8 ]',
    "pixelsamples": '"integer pixelsamples" [ 1 ]',
    "maxdepth": '"integer maxdepth" [ 3 ]',
    "fov": '"float fov" [ 45 ]',
    "radius": '"float radius" [ 1 ]',
    "reflectance": '"rgb reflectance" [ 0.5 0.5 0.5 ]',
    "intensity": '"rgb I" [ 4 4 4 ]',
    "lookat": "LookAt 0 0 -5",
    "from": '"point3 from" [ 0 0 -3 ]',
    "translate": "WorldBegin",
    "rotate": "Material",
}


def numbers():
    for name, orig in NUMERIC.items():
        for k, v in enumerate(NUMBERS):
            if name == "translate":
                new = f"Translate {v} 0 0\nWorldBegin"
            elif name == "rotate":
                new = f"Rotate {v} 0 1 0\nMaterial"
            elif name == "lookat":
                new = f"LookAt {v} 0 -5"
            else:
                head, _, rest = orig.partition("[ ")
                count = len(rest.split()) - 1
                new = head + "[ " + " ".join([v] * count) + " ]"
            scene(f"{name}-{k:02}-{v}", BASE.replace(orig, new, 1), group="number")


def includes():
    inc = lambda target: BASE.replace("WorldBegin", f'Include "{target}"\nWorldBegin')
    write("include/bad.pbrt", 'Shape "sphere" "float radius" [ "x" ]\n')
    write("include/self.pbrt", 'Include "self.pbrt"\n')
    write("include/sub/.keep", "")
    for cid, target in [("dev-zero", "/dev/zero"), ("directory", "sub"), ("missing", "missing.pbrt"),
                        ("error-inside", "bad.pbrt"), ("self", "self.pbrt"), ("dev-null", "/dev/null")]:
        scene(cid, inc(target), group="include")
    scene("import-missing", BASE.replace("WorldBegin", 'Import "missing.pbrt"\nWorldBegin'), group="include")


def flags():
    F = {
        "points": [["--sampler", "nope"], ["--sampler", "sobol", "--n", "-1"], ["--sampler", "sobol", "--dims", "0"],
                   ["--sampler", "sobol", "--dims", "99999"], ["--sampler", "sobol", "--dim-range", "5..2"],
                   ["--sampler", "sobol", "--dim-range", "a..b"], ["--sampler", "sobol", "--format", "xml"],
                   ["--sampler", "sobol", "--pixel", "9,9"], ["--sampler", "sobol", "--pixel", "x"],
                   ["--sampler", "sobol", "--res", "0x0", "--pixel", "0,0"], ["--sampler", "paper", "--threshold", "2"],
                   ["--sampler", "paper", "--threshold", "nan"], ["--sampler", "sobol", "--plot", "out.jpg"],
                   ["--sampler", "sobol", "--plot", "nowhere/out.png"], ["--sampler", "sobol", "--n", "99999999999"],
                   ["--sampler", "sobol", "--seed", "-5"], ["--bogus"], []],
        "figure": [["-o", "out.jpg"], ["-o", "nowhere/out.png"], ["-o", "f.png", "--samplers", "nope"],
                   ["-o", "f.png", "--spp", "0"], ["-o", "f.png", "--spp", "99999999"], ["-o", "f.png", "--threshold", "-1"],
                   ["-o", "f.png", "--paper-all-dims", "maybe"], []],
        "discrepancy": [["--sampler", "sobol", "--n", "0"], ["--sampler", "sobol", "--dims", "0"],
                        ["--sampler", "sobol", "--n", "2", "--dims", "5000"],
                        ["--sampler", "sobol", "--n", "2", "--dims", "5000", "--metric", "star"],
                        ["--sampler", "sobol", "--metric", "star-lower", "--boxes", "4611686018427387904"],
                        ["--sampler", "sobol", "--n", "1000000", "--metric", "cd"],
                        ["--sampler", "sobol", "--n", "4000000000", "--dims", "100"],
                        ["--sampler", "sobol", "--max-work", "0"], ["--sampler", "sobol", "--max-work", "nan"],
                        ["--sampler", "sobol", "--metric", "nope"], ["--input", "/dev/zero"], ["--input", "{F}"],
                        ["--input", "{F}/points/missing.txt"], ["--input", "{F}/points/nan.txt"],
                        ["--input", "{F}/points/ragged.txt"], ["--input", "{F}/points/outside.txt"],
                        ["--input", "{F}/points/empty.txt"], ["--input", "{F}/points/binary.txt"],
                        ["--input", "{F}/points/wide.txt"], ["--input", "{F}/points/wide.txt", "--metric", "star"],
                        ["--input", "{F}/points/one.txt"], ["--input", "{F}/points/words.txt"],
                        ["--input", "{F}/points/ok.txt", "--max-memory", "0"]],
        "spectrum": [["--samplers", "sobol", "-o", "s.png", "--n", "65536", "--max-frequency", "4096"],
                     ["--samplers", "sobol", "-o", "s.png", "--n", "1"], ["--samplers", "nope", "-o", "s.png"],
                     ["--samplers", "sobol", "-o", "s.jpg"], ["--samplers", "sobol", "-o", "nowhere/s.png"],
                     ["--samplers", "sobol", "-o", "s.png", "--max-frequency", "0"],
                     ["--samplers", "sobol", "-o", "s.png", "--dim-range", "0..3"],
                     ["--samplers", "sobol", "-o", "s.png", "--max-memory", "1", "--max-frequency", "4096"]],
        "paper-claim": [["--ns", "0", "--out", "c"], ["--ns", "abc", "--out", "c"], ["--seeds", "0", "--out", "c"],
                        ["--pairs", "9..2", "--out", "c"], ["--out", "/proc/claim"], ["--thresholds", "5", "--out", "c"],
                        ["--plot-format", "gif", "--out", "c"]],
        "render": [["-o", "out.exr", "--res", "16384x16384"], ["-o", "out.exr", "--res", "0x0"],
                   ["-o", "out.exr", "--res", "100000x100000"], ["-o", "out.exr", "--spp", "0"],
                   ["-o", "out.exr", "--maxdepth", "2147483647"], ["-o", "out.exr", "--threads", "0"],
                   ["-o", "out.exr", "--sampler", "nope"], ["-o", "out.jpg"], ["-o", "nowhere/out.exr"],
                   ["-o", "/proc/out.exr"], ["-o", "out.exr", "--threshold", "nan"],
                   ["-o", "out.exr", "--envmap", "{F}/image/ok.pfm"], ["-o", "out.exr", "--max-memory", "0"],
                   ["{F}/scene/base.pbrt", "-o", "out.exr", "--res", "8192x8192"],
                   ["{F}/scene/base.pbrt", "-o", "out.exr", "--spp", "4294967295"]],
        "experiment": [["--out", "e", "--spp", "0"], ["--out", "e", "--runs", "0"], ["--out", "e", "--res", "0x0"],
                       ["--out", "e", "--samplers", "nope"], ["--out", "e", "--envmap", "/dev/zero"],
                       ["--out", "e", "--threshold", "7"], ["--out", "/proc/e"], ["--out", "e", "{F}/scene/missing.pbrt"],
                       ["--out", "e", "--quick", "{F}/scene/unbalanced-open.pbrt"],
                       ["--out", "e", "--quick", "{F}/scene/folder.pbrt"]],
    }
    write("points/nan.txt", "0.5 0.5\nnan 0.1\n")
    write("points/ragged.txt", "0.5 0.5\n0.1\n")
    write("points/outside.txt", "0.5 1.5\n")
    write("points/empty.txt", "# nothing\n")
    write("points/binary.txt", b"\xff\xfe\x00\x01")
    write("points/wide.txt", " ".join(["0"] * 30000) + "\n")
    write("points/one.txt", "0.25 0.75\n")
    write("points/words.txt", "0.5 half\n")
    write("points/ok.txt", "0.25 0.75\n0.5 0.5\n")
    for sub, lists in F.items():
        for k, args in enumerate(lists):
            case("flags", f"{sub}-{k:02}", [sub, *args])
    case("flags", "no-subcommand", [])
    case("flags", "unknown-subcommand", ["paint"])


def faults():
    cornell = ["render", "-q", "-o", "out.exr", "--res", "16x16", "--spp", "1"]
    stats = ["render", "--stats", "-q", "-o", "out.exr", "--res", "16x16", "--spp", "1"]
    points = ["points", "--sampler", "sobol", "--n", "100000", "--dims", "4"]
    warn = ["render", "{F}/include/warns.pbrt", "-o", "out.exr"]
    write("include/warns.pbrt", BASE.replace('"float radius" [ 1 ]', '"float radius" [ 1 ] "float unused" [ 2 ]'))
    for fault in ["full-stdout", "closed-stdout"]:
        case("fault", f"{fault}-points", points, fault)
        case("fault", f"{fault}-stats", stats, fault)
        case("fault", f"{fault}-discrepancy", ["discrepancy", "--sampler", "sobol"], fault)
    for fault in ["full-stderr", "closed-stderr"]:
        case("fault", f"{fault}-error", ["render", "--spp", "0", "-o", "x.exr"], fault)
        case("fault", f"{fault}-warning", warn, fault)
        case("fault", f"{fault}-scene-error", render("{F}/scene/unterminated-string.pbrt"), fault)
    case("fault", "readonly-render", ["render", "-q", "-o", "/proc/out.exr", "--res", "8x8", "--spp", "1"])
    case("fault", "readonly-spectrum", ["spectrum", "--samplers", "sobol", "-o", "/proc/s.png"])
    big = ["render", "-q", "-o", "out.exr", "--res", "1024x1024", "--spp", "1", "--maxdepth", "1"]
    for ms in [100, 300, 600, 900]:
        case("fault", f"sigint-{ms}ms", big, f"sigint:{ms}", old=True)
        case("fault", f"sigterm-{ms}ms", big, f"sigterm:{ms}", old=True)
    case("fault", "tmpfs-full-render", ["render", "-q", "-o", "{TMPFS}/out.exr", "--res", "256x256", "--spp", "1"], "tmpfs-full")
    case("fault", "tmpfs-full-spectrum", ["spectrum", "--samplers", "sobol", "-o", "{TMPFS}/s.png"], "tmpfs-full")
    case("fault", "failed-rerun-keeps-old", render("{F}/scene/unbalanced-open.pbrt"), old=True)
    case("fault", "failed-render-keeps-old", cornell + ["--sampler", "nope"], old=True)
    case("fault", "good-rerun-replaces-old", cornell, old=True)


def main():
    shutil.rmtree(FILES, ignore_errors=True)
    os.makedirs(FILES)
    scene_syntax()
    numbers()
    formats.ply(case, write, render, BASE)
    formats.images(case, write, render, BASE)
    includes()
    flags()
    faults()
    path = os.path.join(HERE, "manifest.json")
    old = {}
    if os.path.exists(path):
        with open(path) as f:
            old = {c["id"]: c for c in json.load(f)["cases"]}
    for c in CASES:
        prev = old.get(c["id"])
        if prev and prev["args"] == c["args"] and prev["fault"] == c["fault"] and "expect" in prev:
            c["expect"] = prev["expect"]
    ids = [c["id"] for c in CASES]
    assert len(ids) == len(set(ids)), "duplicate case ids"
    with open(path, "w") as f:
        # The same layout as the recording test writes (serde_json, sorted keys).
        lines = ",\n".join("  " + json.dumps(c, separators=(",", ":"), sort_keys=True) for c in CASES)
        f.write('{"cases": [\n' + lines + "\n]}\n")
    print(f"{len(CASES)} cases, {sum(len(fs) for _, _, fs in os.walk(FILES))} files")


if __name__ == "__main__":
    main()
