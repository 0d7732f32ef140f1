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
import struct
import zlib

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


def ply_header(fmt, vertices, faces, props="float x\nproperty float y\nproperty float z",
               face="list uchar int vertex_indices"):
    return (f"ply\nformat {fmt} 1.0\nelement vertex {vertices}\nproperty {props}\n"
            f"element face {faces}\nproperty {face}\nend_header\n").encode()


def ply():
    tri_ascii = b"0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
    tri_bin = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<B3i", 3, 0, 1, 2)
    plys = {
        "ok-ascii": ply_header("ascii", 3, 1) + tri_ascii,
        "ok-binary": ply_header("binary_little_endian", 3, 1) + tri_bin,
        "empty": b"",
        "not-ply": b"hello world\n",
        "no-end-header": ply_header("ascii", 3, 1).replace(b"end_header\n", b""),
        "unknown-format": ply_header("binary_middle_endian", 3, 1) + tri_bin,
        "huge-vertex-count": ply_header("binary_little_endian", 4000000000, 1) + tri_bin,
        "huge-face-count": ply_header("binary_little_endian", 3, 4000000000) + tri_bin,
        "negative-count": ply_header("ascii", -3, 1) + tri_ascii,
        "truncated-binary": ply_header("binary_little_endian", 3, 1) + tri_bin[:20],
        "truncated-ascii": ply_header("ascii", 3, 1) + tri_ascii[:8],
        "index-out-of-range": ply_header("ascii", 3, 1) + b"0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n",
        "negative-index": ply_header("ascii", 3, 1) + b"0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n",
        "nan-vertex": ply_header("ascii", 3, 1) + b"nan 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
        "inf-vertex": ply_header("ascii", 3, 1) + b"inf 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
        "garbage-number": ply_header("ascii", 3, 1) + b"0 x 0\n1 0 0\n0 1 0\n3 0 1 2\n",
        "face-of-255": ply_header("ascii", 3, 1) + b"0 0 0\n1 0 0\n0 1 0\n255 0 1 2\n",
        "face-of-2": ply_header("ascii", 3, 1) + b"0 0 0\n1 0 0\n0 1 0\n2 0 1\n",
        "no-x": ply_header("ascii", 3, 1, props="float y\nproperty float z") + b"0 0\n0 0\n1 0\n3 0 1 2\n",
        "bad-property-type": ply_header("ascii", 3, 1, props="quad x\nproperty float y\nproperty float z") + tri_ascii,
        "bad-list-type": ply_header("ascii", 3, 1, face="list float int vertex_indices") + tri_ascii,
        "no-faces": (b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                     b"property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n"),
        "big-endian-ok": ply_header("binary_big_endian", 3, 1)
        + struct.pack(">9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack(">B3i", 3, 0, 1, 2),
        "list-count-huge": ply_header("binary_little_endian", 3, 1, face="list uint int vertex_indices")
        + struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<I3i", 4000000000, 0, 1, 2),
        "header-only": ply_header("ascii", 0, 0),
        "extra-element": ply_header("ascii", 3, 1).replace(b"end_header", b"element edge 1\nproperty int a\nend_header") + tri_ascii + b"7\n",
        "comment-lines": ply_header("ascii", 3, 1).replace(b"format", b"comment hi\nformat") + tri_ascii,
        "crlf-header": ply_header("ascii", 3, 1).replace(b"\n", b"\r\n") + tri_ascii,
        "long-line": b"ply\nformat ascii 1.0\ncomment " + b"x" * 10000 + b"\nend_header\n",
        "binary-zeros": b"\0" * 512,
    }
    for cid, data in plys.items():
        ref = write(f"ply/{cid}.ply", data)
        text = BASE.replace('Shape "sphere" "float radius" [ 1 ]', f'Shape "plymesh" "string filename" "{cid}.ply"')
        case("ply", cid, render(write(f"ply/{cid}.pbrt", text)))
    write("ply/dir.ply/.keep", "")
    for cid, target in [("ply-is-directory", "dir.ply"), ("ply-is-dev-zero", "/dev/zero"), ("ply-missing", "missing.ply")]:
        text = BASE.replace('Shape "sphere" "float radius" [ 1 ]', f'Shape "plymesh" "string filename" "{target}"')
        case("ply", cid, render(write(f"ply/{cid}.pbrt", text)))


def png(width, height, rows=None, crc_ok=True, truncate=None):
    raw = rows if rows is not None else b"".join(b"\0" + b"\x80" * (3 * width) for _ in range(height))
    def chunk(kind, data):
        crc = zlib.crc32(kind + data) & 0xFFFFFFFF
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", crc if crc_ok else crc ^ 1)
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")
    return data[:truncate] if truncate else data


def images():
    pfm_ok = b"PF\n2 2\n-1.0\n" + struct.pack("<12f", *([0.5] * 12))
    hdr_head = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n"
    imgs = {
        "ok.png": png(2, 2),
        "ok.pfm": pfm_ok,
        "ok.hdr": hdr_head + b"\x80\x80\x80\x80" * 4,
        "empty.exr": b"",
        "garbage.exr": b"v/1\x01" + b"\xff" * 200,
        "text.exr": b"this is not an image\n",
        "truncated.png": png(4, 4, truncate=40),
        "bad-crc.png": png(2, 2, crc_ok=False),
        "huge.png": png(100000, 100000, rows=b"\0\0\0\0"),
        "zero-size.png": png(0, 0, rows=b""),
        "pfm-huge": b"PF\n1000000 1000000\n-1.0\n" + b"\0" * 64,
        "pfm-negative": b"PF\n-2 2\n-1.0\n" + b"\0" * 48,
        "pfm-truncated": pfm_ok[:30],
        "pfm-zero-scale": b"PF\n2 2\n0\n" + struct.pack("<12f", *([0.5] * 12)),
        "pfm-nan": b"PF\n2 2\n-1.0\n" + struct.pack("<12f", *([float("nan")] * 12)),
        "hdr-truncated": hdr_head + b"\x80\x80",
        "hdr-huge": b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 100000\n" + b"\x80" * 16,
        "hdr-bad-rle": hdr_head.replace(b"2 +X 2", b"2 +X 64") + b"\x02\x02\x00\x40" + b"\xff" * 40,
        "hdr-no-resolution": b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n",
        "tga-garbage.tga": b"\0\0\x02" + b"\xff" * 30,
        "unknown.xyz": b"\0\1\2\3",
    }
    for name, data in imgs.items():
        fname = name if "." in name else name + (".pfm" if name.startswith("pfm") else ".hdr")
        ref = write(f"image/{fname}", data)
        cid = fname.replace(".", "-")
        env_scene = BASE.replace('LightSource "point"', f'LightSource "infinite" "string filename" "{fname}"\nAttributeBegin\nAttributeEnd\nLightSource "point"')
        case("image", f"envmap-{cid}", render(write(f"image/envmap-{cid}.pbrt", env_scene)))
        tex_scene = BASE.replace("Material", f'Texture "t" "spectrum" "imagemap" "string filename" "{fname}"\nMaterial').replace('"rgb reflectance" [ 0.5 0.5 0.5 ]', '"texture reflectance" "t"')
        case("image", f"texture-{cid}", render(write(f"image/texture-{cid}.pbrt", tex_scene)))
    base_ref = write("image/base.pbrt", BASE.replace('LightSource "point"', 'LightSource "infinite" "string filename" "ok.pfm"\nLightSource "point"'))
    for name in ["garbage.exr", "truncated.png", "huge.png", "pfm-huge"]:
        fname = name if "." in name else name + ".pfm"
        case("image", f"flag-envmap-{fname.replace('.', '-')}", render(base_ref, "--envmap", "{F}/image/" + fname))
    case("image", "flag-envmap-directory", render(base_ref, "--envmap", "{F}/image"))
    case("image", "flag-envmap-dev-zero", render(base_ref, "--envmap", "/dev/zero"))
    case("image", "flag-envmap-no-infinite-light", render("{F}/scene/base.pbrt", "--envmap", "{F}/image/ok.pfm"))


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
    ply()
    images()
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
        lines = ",\n".join("  " + json.dumps(c) for c in CASES)
        f.write('{"cases": [\n' + lines + "\n]}\n")
    print(f"{len(CASES)} cases, {sum(len(fs) for _, _, fs in os.walk(FILES))} files")


if __name__ == "__main__":
    main()
