#!/usr/bin/env python3
"""Agreement of lowdisc with pbrt-v4 over a collection of pbrt-v4 scenes.

For every scene file (by default `*/pbrt/scene-v4.pbrt` under the collection,
the layout of Bitterli's scenes as converted to pbrt-v4), the harness:

1. lists the files the scene names (meshes, textures, included files) and
   marks the scene *incomplete* when one is absent or is a Git LFS pointer
   (a referenced `X` absent beside an `X.xz` or `X.gz` is decompressed first);
2. writes a rewritten copy (scripts/pbrt_variants.py: a folder of links to
   the scene's folder with the scene file rewritten): Film resolution divided
   by --divide (but a long side of at least --min-size pixels),
   `Sampler "independent"` with --spp samples;
3. renders it with lowdisc (`--spectral` unless --rgb) and with pbrt-v4,
   seeds 1 and 2 each, as whole processes (start-up, parsing, building,
   rendering, writing a PFM), recording each one's time (a scene's time is
   the shorter of its two seeds', less exposed to a busy machine); a render already
   done is not repeated (delete its files under --out to redo it), and
   pbrt-v4's renders (OUT/spp.../SCENE/pbrt-SEED.pfm) are shared by runs
   that differ only in lowdisc's options (lowdisc's go into a subfolder
   named by its mode and --lowdisc-arg);
4. compares them: channel means of the two-seed averages with standard
   errors, the 8x8-block luminance ratio lowdisc/pbrt-v4 (seed 1 against
   seed 2 and seed 2 against seed 1, pooled: p5, median, p95) against
   pbrt-v4's own seed 1/seed 2 block ratio, and gives a verdict:
   *agrees* (every channel mean within 1.5 % or 2 standard errors, and the
   block ratio's p5 and p95 inside pbrt-v4's seed-to-seed band), *differs*,
   *refused* (lowdisc's error message), *incomplete* or *pbrt-v4 failed*;
5. with --rgb-timing, times one lowdisc RGB render (seed 1) as well;
6. writes `table-MODE.md` (one row per scene, then the median speed-ups) and
   per scene `side-by-side.png` (lowdisc, pbrt-v4, block ratio map: red
   where lowdisc is brighter, blue where darker, full colour at 25 %).

The seed-to-seed band: the p5 and p95 of pbrt-v4's seed-1/seed-2 ratio,
widened to the quantile levels 2 standard errors of a difference of two
quantile estimates further out (sqrt(2 p (1-p) / blocks)), so that two
samples of the same distribution pass about 95 % of the time. A lowdisc/pbrt-v4 single-seed ratio has the variance
of pbrt-v4's own seed ratio when lowdisc is unbiased and as noisy as pbrt-v4;
a bias or more noise widens or shifts it out of the band.

The standard error of a renderer's channel mean comes from its two seeds:
with S1, S2 the 8x8-block sums of the two renders and N pixels, the two-seed
mean's variance is sum((S1 - S2)^2) / 4 / N^2 (blocks are independent under
the independent sampler).

Usage (pbrt-v4 built by the user, CPU, Release):
  cargo build --release -p lowdisc-cli
  python3 scripts/agreement.py --collection /path/to/bitterli \\
      --pbrt /path/to/pbrt --lowdisc target/release/lowdisc \\
      --spp 16 --divide 4 --out /tmp/lowdisc-agreement
Needs Python 3.11 and numpy. The statistics are tested by
scripts/test_agreement.py (pytest; no renderer needed).
"""

import argparse
import glob
import gzip
import json
import lzma
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pbrt_variants  # noqa: E402

BLOCK = 8
SEEDS = (1, 2)
MEAN_TOLERANCE = 0.015
MEAN_SIGMAS = 2.0
BAND_SIGMAS = 2.0
LUMINANCE = (0.2126, 0.7152, 0.0722)
FILE_EXTENSIONS = (".ply", ".tga", ".png", ".exr", ".pfm", ".hdr", ".jpg", ".jpeg", ".bmp",
                   ".pbrt", ".spd", ".bsdf", ".obj", ".nvdb", ".gz", ".tif", ".tiff")
LFS_HEADER = b"version https://git-lfs"

# ---------------------------------------------------------------------------
# Scene files: what a scene names, and whether it is there


TOKEN = re.compile(r'#[^\n]*|"[^"]*"|\[|\]|[^\s\[\]"#]+')


def named_files(text):
    """Relative paths a pbrt-v4 scene text names: Include/Import targets and
    quoted parameter values with a file extension (not the Film's output)."""
    names, directive, expect = [], None, None
    for tok in TOKEN.findall(text):
        if tok.startswith("#"):
            continue
        if tok[0].isalpha() and tok[0].isupper():
            directive, expect = tok, ("include" if tok in ("Include", "Import") else None)
            continue
        if not tok.startswith('"'):
            continue
        value = tok[1:-1]
        if expect == "include":
            names.append(value)
            expect = None
        elif " " not in value and value.lower().endswith(FILE_EXTENSIONS) and directive != "Film":
            names.append(value)
    return names


def is_lfs_pointer(path):
    """Whether `path` is a Git LFS pointer instead of the file's content."""
    with open(path, "rb") as f:
        return f.read(len(LFS_HEADER)) == LFS_HEADER


def restore_compressed(path):
    """Decompresses `path`.xz or `path`.gz into `path` when `path` is absent;
    returns whether `path` exists afterwards."""
    for ext, opener in ((".xz", lzma.open), (".gz", gzip.open)):
        if not os.path.exists(path) and os.path.exists(path + ext):
            with opener(path + ext, "rb") as src, open(path + ".part", "wb") as dst:
                shutil.copyfileobj(src, dst)
            os.replace(path + ".part", path)
    return os.path.exists(path)


def missing_files(scene, scan_limit=64 << 20):
    """Files `scene` names (recursively through included files up to
    `scan_limit` bytes) that are absent or LFS pointers, relative to its folder."""
    base = os.path.dirname(os.path.abspath(scene))
    missing, seen, todo = [], set(), [scene]
    while todo:
        with open(todo.pop(), errors="replace") as f:
            text = f.read()
        for name in named_files(text):
            path = os.path.join(base, name)
            if path in seen:
                continue
            seen.add(path)
            if not restore_compressed(path) or is_lfs_pointer(path):
                missing.append(name)
            elif name.endswith(".pbrt") and os.path.getsize(path) <= scan_limit:
                todo.append(path)
    return missing


def scene_names(collection, pattern):
    """(name, path) of the scene files (those with a WorldBegin) matching
    `pattern` under `collection`, sorted: a name is the file's first folder,
    or folder/file (without .pbrt) where a folder holds several scenes."""
    paths = []
    for path in sorted(glob.glob(os.path.join(collection, pattern))):
        with open(path, errors="replace") as f:
            if re.search(r"^\s*WorldBegin", f.read(), re.M):
                paths.append(path)
    firsts = [os.path.relpath(p, collection).split(os.sep)[0] for p in paths]
    names = [first if firsts.count(first) == 1 else
             first + "/" + os.path.splitext(os.path.basename(p))[0]
             for first, p in zip(firsts, paths)]
    return list(zip(names, paths))


def film_resolution(text):
    """(width, height) of a scene text's Film (pbrt-v4's defaults 1280x720)."""
    text = pbrt_variants.strip_comments(text)

    def value(axis, default):
        m = re.search(r'"integer %sresolution"\s*\[?\s*(\d+)' % axis, text)
        return int(m.group(1)) if m else default
    return value("x", 1280), value("y", 720)


def reduced_resolution(width, height, divide, min_size):
    """(width, height) divided by `divide`, but scaled to a long side of
    `min_size` when that is larger (scenes already stored small)."""
    factor = max(1 / divide, min_size / max(width, height))
    return max(1, round(width * factor)), max(1, round(height * factor))


# ---------------------------------------------------------------------------
# Images and statistics (numpy)


def read_pfm(path):
    """Colour PFM as a float64 array (rows top to bottom, width, 3)."""
    import numpy as np
    with open(path, "rb") as f:
        data = f.read()
    header = data.split(b"\n", 3)
    if header[0].strip() != b"PF":
        raise ValueError("%s: not a colour PFM" % path)
    width, height = (int(v) for v in header[1].split())
    scale = float(header[2])
    dtype = "<f4" if scale < 0 else ">f4"
    pixels = np.frombuffer(header[3], dtype=dtype, count=width * height * 3)
    return pixels.reshape(height, width, 3)[::-1].astype(np.float64)


def block_sums(img, k=BLOCK):
    """Sums over k x k blocks (edge rows/columns that fill no block dropped)."""
    h, w = img.shape[0] // k * k, img.shape[1] // k * k
    cropped = img[:h, :w]
    return cropped.reshape(h // k, k, w // k, k, *img.shape[2:]).sum(axis=(1, 3))


def luminance(img):
    """Luminance (Rec. 709 weights) of an (..., 3) array."""
    import numpy as np
    return img @ np.array(LUMINANCE)


def mean_and_se(a, b):
    """Channel means of the average of two independent renders `a`, `b` and
    their standard errors, from the renders' 8x8-block differences."""
    import numpy as np
    n = a.shape[0] * a.shape[1]
    means = (a.mean(axis=(0, 1)) + b.mean(axis=(0, 1))) / 2
    diff = block_sums(a) - block_sums(b)
    se = np.sqrt((diff ** 2).sum(axis=(0, 1)) / 4) / n
    return means, se


def quantile_band(ratios, lo=0.05, hi=0.95, sigmas=BAND_SIGMAS):
    """The (lo, hi) quantiles of `ratios` at levels moved outwards by
    `sigmas` standard errors of the difference of two quantile estimates
    (sqrt(2 p (1 - p) / n) in level): the band another sample of the same
    size and distribution has its lo and hi quantiles in, both, about 95 %
    of the time for sigmas = 2."""
    import numpy as np
    n = len(ratios)
    lo_level = max(0.0, lo - sigmas * np.sqrt(2 * lo * (1 - lo) / n))
    hi_level = min(1.0, hi + sigmas * np.sqrt(2 * hi * (1 - hi) / n))
    return float(np.quantile(ratios, lo_level)), float(np.quantile(ratios, hi_level))


def block_ratios(lowdisc, pbrt):
    """The block luminance ratios: lowdisc/pbrt-v4 (seed 1 over seed 2 and
    seed 2 over seed 1, pooled) and pbrt-v4 seed 1/seed 2, over the blocks
    where all four renders are positive; also that block mask."""
    import numpy as np
    (l1, l2), (p1, p2) = ([luminance(block_sums(i)) for i in pair] for pair in (lowdisc, pbrt))
    mask = (l1 > 0) & (l2 > 0) & (p1 > 0) & (p2 > 0)
    l1, l2, p1, p2 = l1[mask], l2[mask], p1[mask], p2[mask]
    return np.concatenate([l1 / p2, l2 / p1]), p1 / p2, mask


def compare(lowdisc, pbrt):
    """Statistics of two lowdisc renders against two pbrt-v4 renders (each a
    pair of HxWx3 arrays with different seeds) as a dict."""
    import numpy as np
    lm, lse = mean_and_se(*lowdisc)
    pm, pse = mean_and_se(*pbrt)
    se = np.sqrt(lse ** 2 + pse ** 2)
    sigmas = np.where(se > 0, np.abs(lm - pm) / np.where(se > 0, se, 1), 0.0)
    rel = np.where(pm > 0, lm / np.where(pm > 0, pm, 1), np.where(lm > 0, np.inf, 1.0))
    cross, seed, mask = block_ratios(lowdisc, pbrt)
    stats = {"lowdisc_means": lm.tolist(), "pbrt_means": pm.tolist(),
             "mean_ratio": rel.tolist(), "sigmas": sigmas.tolist(),
             "blocks": int(mask.sum()), "blocks_total": int(mask.size)}
    if len(seed) >= 20:
        stats["cross"] = [float(v) for v in np.quantile(cross, (0.05, 0.5, 0.95))]
        stats["seed"] = [float(v) for v in np.quantile(seed, (0.05, 0.95))]
        stats["band"] = list(quantile_band(seed))
    return stats


def verdict(stats):
    """'agrees' or 'differs' (with the failing criteria) for `compare`'s stats."""
    reasons = []
    for c, (ratio, sig) in enumerate(zip(stats["mean_ratio"], stats["sigmas"])):
        if abs(ratio - 1) > MEAN_TOLERANCE and sig > MEAN_SIGMAS:
            reasons.append("%s mean x%.3f (%.1f SE)" % ("RGB"[c], ratio, sig))
    if "band" not in stats:
        reasons.append("fewer than 20 lit blocks")
    else:
        (p5, _, p95), (lo, hi) = stats["cross"], stats["band"]
        if p5 < lo:
            reasons.append("block p5 %.3f < %.3f" % (p5, lo))
        if p95 > hi:
            reasons.append("block p95 %.3f > %.3f" % (p95, hi))
    return ("differs", reasons) if reasons else ("agrees", [])


# ---------------------------------------------------------------------------
# Pictures


def write_png(path, rgb8):
    """Writes an HxWx3 uint8 array as an 8-bit RGB PNG."""
    h, w, _ = rgb8.shape
    raw = b"".join(b"\x00" + rgb8[y].tobytes() for y in range(h))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
           + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))
    with open(path, "wb") as f:
        f.write(png)


def to_srgb8(img, scale):
    """`img` * scale, clamped, sRGB-encoded as uint8."""
    import numpy as np
    v = np.clip(img * scale, 0, 1)
    v = np.where(v <= 0.0031308, 12.92 * v, 1.055 * v ** (1 / 2.4) - 0.055)
    return (v * 255 + 0.5).astype(np.uint8)


def ratio_map(lowdisc, pbrt, shape, full=0.25):
    """The two-seed block luminance ratio lowdisc/pbrt-v4 as a picture of
    `shape`: red above 1, blue below, full colour at 1 +- `full`, grey where
    a block is black in pbrt-v4."""
    import numpy as np
    lo, pb = (luminance(block_sums(a + b)) for a, b in (lowdisc, pbrt))
    ratio = np.where(pb > 0, lo / np.where(pb > 0, pb, 1), 1)
    t = np.clip(np.log(np.maximum(ratio, 1e-9)) / np.log1p(full), -1, 1)
    rgb = np.stack([1 - np.clip(-t, 0, 1), 1 - np.abs(t), 1 - np.clip(t, 0, 1)], axis=-1)
    rgb[pb <= 0] = 0.5
    big = np.kron(rgb, np.ones((BLOCK, BLOCK, 1)))
    out = np.full(shape, 0.5)
    out[:big.shape[0], :big.shape[1]] = big
    return (out * 255 + 0.5).astype(np.uint8)


def side_by_side(path, lowdisc, pbrt):
    """lowdisc's and pbrt-v4's two-seed averages (one exposure: pbrt-v4's
    99th luminance percentile maps to 1) and the block ratio map."""
    import numpy as np
    lo, pb = (lowdisc[0] + lowdisc[1]) / 2, (pbrt[0] + pbrt[1]) / 2
    top = np.quantile(luminance(pb), 0.99)
    scale = 1 / top if top > 0 else 1.0
    gap = np.full((lo.shape[0], 4, 3), 255, np.uint8)
    panels = [to_srgb8(lo, scale), gap, to_srgb8(pb, scale), gap,
              ratio_map(lowdisc, pbrt, lo.shape)]
    write_png(path, np.concatenate(panels, axis=1))


# ---------------------------------------------------------------------------
# Rendering, resumable


def run_once(cmd, image, meta_path, timeout):
    """Runs `cmd` (which writes `image`) unless `meta_path` records an earlier
    run; returns the record: command, exit code, seconds, stderr's tail."""
    if os.path.exists(meta_path):
        with open(meta_path) as f:
            return json.load(f)
    start = time.monotonic()
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        code, err = proc.returncode, proc.stderr
    except subprocess.TimeoutExpired:
        code, err = -1, "timed out after %d s" % timeout
    record = {"cmd": cmd, "returncode": code, "seconds": time.monotonic() - start,
              "stderr": err[-4000:], "ok": code == 0 and os.path.exists(image)}
    with open(meta_path + ".part", "w") as f:
        json.dump(record, f, indent=1)
    os.replace(meta_path + ".part", meta_path)
    return record


def renderer_commands(args, scene, seed, image):
    """The lowdisc and pbrt-v4 commands rendering `scene` with `seed` into `image`."""
    lowdisc = [args.lowdisc, "render", scene, "--seed", str(seed), "--quiet", "-o", image]
    if not args.rgb:
        lowdisc.append("--spectral")
    pbrt = [args.pbrt, "--seed", str(seed), "--quiet", "--outfile", image, scene]
    if args.threads:
        lowdisc += ["--threads", str(args.threads)]
        pbrt[1:1] = ["--nthreads", str(args.threads)]
    return {"lowdisc": lowdisc + args.lowdisc_arg, "pbrt": pbrt}


def rgb_time(args, scene, folder):
    """Seconds of one lowdisc RGB render (seed 1) of `scene`, or None if it failed."""
    image = os.path.join(folder, "lowdisc-rgb-1.pfm")
    cmd = [a for a in renderer_commands(args, scene, 1, image)["lowdisc"] if a != "--spectral"]
    record = run_once(cmd, image, image + ".json", args.timeout)
    return record["seconds"] if record["ok"] else None


def first_error(stderr):
    """The line of `stderr` that states the error (else its first line)."""
    lines = [line.strip() for line in stderr.splitlines() if line.strip()]
    for line in lines:
        if "error" in line.lower():
            return line
    return lines[0] if lines else "(no message)"


def prepare(args, src, folder):
    """The rewritten copy of scene `src` in `folder`/scene (written once) and
    its resolution "WxH"."""
    with open(src, errors="replace") as f:
        width, height = film_resolution(f.read())
    res = reduced_resolution(width, height, args.divide, args.min_size)
    variant = os.path.join(folder, "scene")
    if not os.path.exists(variant):
        pbrt_variants.write_variant(src, variant, res=res, sampler="independent", spp=args.spp)
    return os.path.join(variant, os.path.basename(src)), "%dx%d" % res


def render_seeds(args, scene, places):
    """Renders `scene` with each seed, lowdisc then pbrt-v4, into `places`
    (renderer -> folder), stopping at the first failure; returns renderer ->
    [(record, image)]."""
    runs = {"lowdisc": [], "pbrt": []}
    for seed in SEEDS:
        for who in runs:
            image = os.path.join(places[who], "%s-%d.pfm" % (who, seed))
            cmd = renderer_commands(args, scene, seed, image)[who]
            record = run_once(cmd, image, image + ".json", args.timeout)
            runs[who].append((record, image))
            if not record["ok"]:
                return runs
    return runs


def render_scene(args, name, src, folder, mode):
    """Renders one scene (resumably) and returns its row as a dict: the
    rewritten scene and pbrt-v4's renders go into `folder`, lowdisc's renders
    and the picture into its subfolder `mode`."""
    missing = missing_files(src)
    if missing:
        shown = ", ".join(sorted(missing)[:4]) + (", ..." if len(missing) > 4 else "")
        return {"scene": name, "verdict": "incomplete",
                "note": "%d absent: %s" % (len(missing), shown)}
    scene, res = prepare(args, src, folder)
    row = {"scene": name, "res": res}
    places = {"lowdisc": os.path.join(folder, mode), "pbrt": folder}
    os.makedirs(places["lowdisc"], exist_ok=True)
    runs = render_seeds(args, scene, places)
    for who in runs:
        times = [r["seconds"] for r, _ in runs[who] if r["ok"]]
        if times:
            row["time_" + who] = min(times)
    failed = {who: [r for r, _ in runs[who] if not r["ok"]] for who in runs}
    if failed["lowdisc"] or failed["pbrt"]:
        verdict_name = "refused" if failed["lowdisc"] else "pbrt-v4 failed"
        stderr = (failed["lowdisc"] or failed["pbrt"])[0]["stderr"]
        message = first_error(stderr).replace(os.path.dirname(scene) + os.sep, "")
        row.update(verdict=verdict_name, note=message)
        return row
    lowdisc = [read_pfm(image) for _, image in runs["lowdisc"]]
    pbrt = [read_pfm(image) for _, image in runs["pbrt"]]
    if args.rgb_timing and not args.rgb:
        row["time_rgb"] = rgb_time(args, scene, places["lowdisc"])
    row["stats"] = compare(lowdisc, pbrt)
    row["verdict"], reasons = verdict(row["stats"])
    row["note"] = "; ".join(reasons)
    side_by_side(os.path.join(places["lowdisc"], "side-by-side.png"), lowdisc, pbrt)
    return row


# ---------------------------------------------------------------------------
# The table


def row_markdown(row):
    """One Markdown table row."""
    s = row.get("stats")
    means = ", ".join("%.3f" % v for v in s["mean_ratio"]) if s else ""
    sig = "%.1f" % max(s["sigmas"]) if s else ""
    cross = "%.3f / %.3f / %.3f" % tuple(s["cross"]) if s and "cross" in s else ""
    band = "%.3f-%.3f" % tuple(s["band"]) if s and "band" in s else ""
    t_l, t_p, t_rgb = row.get("time_lowdisc"), row.get("time_pbrt"), row.get("time_rgb")
    speed = "%.2f" % (t_p / t_l) if t_l and t_p and "stats" in row else ""

    def secs(t):
        return "%.1f" % t if t else ""
    cells = [row["scene"], row.get("res", ""), "**%s**" % row["verdict"], means, sig, cross,
             band, secs(t_l), secs(t_rgb), secs(t_p), speed, row.get("note", "").replace("|", "/")]
    return "| " + " | ".join(cells) + " |"


def table_markdown(rows):
    """The Markdown table of all rows, a verdict count and the median speed ratio."""
    head = ("| scene | res | verdict | means lowdisc/pbrt-v4 (R, G, B) | max SE | "
            "block ratio p5 / median / p95 | pbrt-v4 seed band | lowdisc s | lowdisc RGB s | "
            "pbrt-v4 s | speed-up | note |\n|" + "---|" * 12)
    lines = [head] + [row_markdown(r) for r in rows]
    counts = {}
    for r in rows:
        counts[r["verdict"]] = counts.get(r["verdict"], 0) + 1
    lines.append("")
    lines.append("Verdicts: " + ", ".join("%s %d" % kv for kv in sorted(counts.items())) + ".")
    for key, label in (("time_lowdisc", "lowdisc"), ("time_rgb", "lowdisc RGB")):
        ratios = [r["time_pbrt"] / r[key] for r in rows
                  if "stats" in r and r.get(key) and r.get("time_pbrt")]
        if ratios:
            lines.append("Median whole-process speed-up of %s (pbrt-v4 time / its time) over "
                         "%d compared scenes: %.2f." % (label, len(ratios), median(ratios)))
    return "\n".join(lines) + "\n"


def median(values):
    """The median of a non-empty list of numbers."""
    v, mid = sorted(values), len(values) // 2
    return v[mid] if len(v) % 2 else (v[mid - 1] + v[mid]) / 2


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--collection", required=True, help="folder of the scene collection")
    p.add_argument("--pattern", default="*/pbrt/scene-v4.pbrt",
                   help="glob of the scene files under --collection")
    p.add_argument("--scenes", nargs="*", help="only these scenes (first path component)")
    p.add_argument("--pbrt", required=True, help="the pbrt-v4 binary")
    p.add_argument("--lowdisc", required=True, help="the lowdisc binary")
    p.add_argument("--lowdisc-arg", action="append", default=[],
                   help="extra argument for lowdisc render (repeatable)")
    p.add_argument("--spp", type=int, default=16)
    p.add_argument("--divide", type=int, default=4, help="Film resolution divisor")
    p.add_argument("--min-size", type=int, default=128,
                   help="smallest long side of the reduced image (pixels)")
    p.add_argument("--threads", type=int, default=0, help="threads of both (0: their default)")
    p.add_argument("--rgb", action="store_true", help="lowdisc in RGB instead of --spectral")
    p.add_argument("--rgb-timing", action="store_true",
                   help="also time one lowdisc RGB render of every compared scene")
    p.add_argument("--timeout", type=int, default=1800, help="seconds per render")
    p.add_argument("--out", default=os.path.join(tempfile.gettempdir(), "lowdisc-agreement"),
                   help="output folder (renders, pictures, table-MODE.md, rows-MODE.json)")
    args = p.parse_args(argv)
    out = os.path.join(args.out, "spp%d-div%d-min%d" % (args.spp, args.divide, args.min_size))
    mode = "rgb" if args.rgb else "spectral"
    mode += "".join("-" + re.sub(r"[^A-Za-z0-9.=]+", "", a) for a in args.lowdisc_arg)
    os.makedirs(out, exist_ok=True)
    rows = []
    for name, src in scene_names(args.collection, args.pattern):
        if args.scenes and name not in args.scenes:
            continue
        folder = os.path.join(out, name)
        os.makedirs(folder, exist_ok=True)
        rows.append(render_scene(args, name, src, folder, mode))
        print("%-20s %s %s" % (name, rows[-1]["verdict"], rows[-1].get("note", "")), flush=True)
        with open(os.path.join(out, "rows-%s.json" % mode), "w") as f:
            json.dump(rows, f, indent=1)
    with open(os.path.join(out, "table-%s.md" % mode), "w") as f:
        f.write(table_markdown(rows))
    print(os.path.join(out, "table-%s.md" % mode))


if __name__ == "__main__":
    main()
