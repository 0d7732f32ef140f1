"""PLY and image fixtures of the bad-input corpus (see generate.py, which
calls ply() and images() with its case and file helpers)."""

import struct
import zlib


def ply_header(fmt, vertices, faces, props="float x\nproperty float y\nproperty float z",
               face="list uchar int vertex_indices"):
    return (f"ply\nformat {fmt} 1.0\nelement vertex {vertices}\nproperty {props}\n"
            f"element face {faces}\nproperty {face}\nend_header\n").encode()


def ply(case, write, render, BASE):
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


def images(case, write, render, BASE):
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
    # A texture or environment map that is a directory or a device.
    for cid, target in [("directory", "."), ("dev-zero", "/dev/zero")]:
        env_scene = BASE.replace('LightSource "point"', f'LightSource "infinite" "string filename" "{target}"\nLightSource "point"')
        case("image", f"envmap-is-{cid}", render(write(f"image/envmap-is-{cid}.pbrt", env_scene)))
        tex_scene = BASE.replace("Material", f'Texture "t" "spectrum" "imagemap" "string filename" "{target}"\nMaterial')
        case("image", f"texture-is-{cid}", render(write(f"image/texture-is-{cid}.pbrt", tex_scene)))
    case("image", "flag-envmap-directory", render(base_ref, "--envmap", "{F}/image"))
    case("image", "flag-envmap-dev-zero", render(base_ref, "--envmap", "/dev/zero"))
    case("image", "flag-envmap-no-infinite-light", render("{F}/scene/base.pbrt", "--envmap", "{F}/image/ok.pfm"))
