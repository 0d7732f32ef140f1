#!/usr/bin/env python3
"""Low-frequency structure ("clumps") of render errors, standard library only.

Given a reference PFM and sets of renders of the same scene (one set per
sampler, one render per seed, e.g. from `lowdisc render --seed S`), reports
per set, over its renders: the geometric mean of the luminance MSE, of the
MSE after a (2r+1)x(2r+1) box blur (`--blur r`), the mean correlation of
the error of horizontally and vertically adjacent pixels, and the power of
the error below `--cutoff` cycles per pixel relative to white noise of the
same MSE (1 = white noise; clumped error is above 1, blue noise below).

With `--png FILE`, writes the error of the first render of every set side
by side (after the blur; red positive, blue negative, white zero, one scale
for all, 4x enlarged).

Usage: scripts/error_clumps.py --reference REF.pfm [--blur R] [--cutoff F]
       [--png FILE] LABEL=RENDER.pfm[,RENDER.pfm...] ...
"""

import argparse
import cmath
import math
import struct
import sys
import zlib


def read_pfm(path):
    """The luminance of a PFM image, rows from the top."""
    with open(path, "rb") as f:
        kind = f.readline().strip()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = f.read()
    ch = 3 if kind == b"PF" else 1
    fmt = ("<" if scale < 0 else ">") + "f" * (w * h * ch)
    v = struct.unpack(fmt, data[: 4 * w * h * ch])
    img = []
    for y in range(h):
        row = []
        for x in range(w):
            i = ((h - 1 - y) * w + x) * ch
            if ch == 3:
                r, g, b = v[i : i + 3]
                row.append(0.2126 * r + 0.7152 * g + 0.0722 * b)
            else:
                row.append(v[i])
        img.append(row)
    return img


def box_blur(e, r):
    """The mean over the (2r+1)^2 window inside the image."""
    h, w = len(e), len(e[0])
    out = [[0.0] * w for _ in range(h)]
    for y in range(h):
        for x in range(w):
            s, n = 0.0, 0
            for yy in range(max(0, y - r), min(h, y + r + 1)):
                for xx in range(max(0, x - r), min(w, x + r + 1)):
                    s += e[yy][xx]
                    n += 1
            out[y][x] = s / n
    return out


def dft(v):
    n = len(v)
    return [
        sum(v[k] * cmath.exp(-2j * math.pi * f * k / n) for k in range(n))
        for f in range(n)
    ]


def measures(e, blur, cutoff):
    """MSE, blurred MSE, adjacent correlation (x, y), low power / white."""
    h, w = len(e), len(e[0])
    n = w * h
    mse = sum(v * v for r in e for v in r) / n
    bmse = sum(v * v for r in box_blur(e, blur) for v in r) / n
    mean = sum(v for r in e for v in r) / n
    var = sum((v - mean) ** 2 for r in e for v in r) or 1.0
    cx = sum(
        (e[y][x] - mean) * (e[y][x + 1] - mean) for y in range(h) for x in range(w - 1)
    ) / var
    cy = sum(
        (e[y][x] - mean) * (e[y + 1][x] - mean) for y in range(h - 1) for x in range(w)
    ) / var
    rows = [dft([complex(v) for v in r]) for r in e]
    cols = [dft([rows[y][x] for y in range(h)]) for x in range(w)]
    low_power, low_bins, total = 0.0, 0, 0.0
    for x in range(w):
        for y in range(h):
            p = abs(cols[x][y]) ** 2
            total += p
            f = math.hypot(min(x, w - x) / w, min(y, h - y) / h)
            if 0 < f < cutoff:
                low_power += p
                low_bins += 1
    # White noise spreads the total power evenly over the n bins.
    low = (low_power / low_bins) / (total / n) if low_bins and total else float("nan")
    return mse, bmse, cx, cy, low


def write_png(path, images, scale, k=4, gap=8):
    h, w = len(images[0]), len(images[0][0])
    width = len(images) * w * k + (len(images) - 1) * gap
    raw = bytearray()
    for y in range(h * k):
        raw.append(0)
        for i, e in enumerate(images):
            for x in range(w * k):
                t = max(-1.0, min(1.0, e[y // k][x // k] / scale))
                c = int(255 * (1 - abs(t)))
                raw += bytes((255, c, c) if t >= 0 else (c, c, 255))
            if i + 1 < len(images):
                raw += b"\xff" * (3 * gap)

    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d))

    header = struct.pack(">IIBBBBB", width, h * k, 8, 2, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header))
        f.write(chunk(b"IDAT", zlib.compress(bytes(raw))) + chunk(b"IEND", b""))


def geometric_mean(xs):
    return math.exp(sum(math.log(x) for x in xs) / len(xs))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--reference", required=True)
    ap.add_argument("--blur", type=int, default=2)
    ap.add_argument("--cutoff", type=float, default=0.125)
    ap.add_argument("--png")
    ap.add_argument("sets", nargs="+", metavar="LABEL=RENDERS")
    args = ap.parse_args()
    ref = read_pfm(args.reference)
    print(f"| set | renders | MSE | blurred MSE (r={args.blur}) | adjacent corr. x, y "
          f"| power below {args.cutoff} / white |")
    print("|---|---|---|---|---|---|")
    firsts = []
    for s in args.sets:
        label, files = s.split("=", 1)
        rows = []
        for i, path in enumerate(files.split(",")):
            img = read_pfm(path)
            e = [[a - b for a, b in zip(ra, rb)] for ra, rb in zip(img, ref)]
            if i == 0:
                firsts.append(box_blur(e, args.blur))
            rows.append(measures(e, args.blur, args.cutoff))
        n = len(rows)
        mse, blurred, low = (geometric_mean([r[i] for r in rows]) for i in (0, 1, 4))
        cx, cy = (sum(r[i] for r in rows) / n for i in (2, 3))
        print(f"| {label} | {n} | {mse:.4g} | {blurred:.4g} | {cx:.3f}, {cy:.3f} | {low:.2f} |")
    if args.png:
        values = sorted(abs(v) for e in firsts for r in e for v in r)
        write_png(args.png, firsts, values[int(0.98 * (len(values) - 1))] or 1.0)
    return 0


if __name__ == "__main__":
    sys.exit(main())
