#!/usr/bin/env python3
"""Screen-space structure of a sampler's error: power spectra and pictures.

For each sampler, renders `--seeds` images with `lowdisc render` (the
built-in Cornell box; `--maxdepth 1` is the direct preset's scene and
depth), subtracts a reference image, and reports the radially averaged
power spectrum of the luminance error, averaged over the seeds, in
frequency bands (cycles per pixel; 0.5 is Nyquist). Blue-noise error has
little power at low frequencies; white noise is flat; structured error
(bands, stripes) shows as peaks. Pixels whose reference luminance exceeds
`--emitter` (the visible light) and a `--border`-pixel ring around them are
set to zero error first, as the experiment's mask leaves them out.

Writes `<out>/<sampler>-error.png` (seed 0's error, mid-grey = 0, scaled by
`--gain`) and `<out>/spectra.md` (the table), and prints the table. Needs
numpy (scripts/requirements.txt).

Usage: scripts/error_spectrum.py --reference REF.pfm [--lowdisc BIN] [--out DIR]
       [--samplers LIST] [--seeds N] [--res WxH] [--spp N] [--maxdepth D]
"""

import argparse
import struct
import subprocess
import sys
import zlib
from pathlib import Path

import numpy as np

BANDS = [(0.0, 0.0625), (0.0625, 0.125), (0.125, 0.25), (0.25, 0.5), (0.5, 0.71)]


def read_pfm(path):
    data = Path(path).read_bytes()
    parts = data.split(b"\n", 3)
    width, height = map(int, parts[1].split())
    scale = float(parts[2])
    pixels = np.frombuffer(parts[3], dtype="<f4" if scale < 0 else ">f4")
    return pixels.reshape(height, width, 3)[::-1].astype(np.float64)


def write_png(path, grey):
    """An 8-bit greyscale PNG of `grey` (values 0..255)."""
    h, w = grey.shape
    raw = b"".join(b"\x00" + bytes(row) for row in grey.astype(np.uint8))

    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body
                + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))

    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0))
           + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
    Path(path).write_bytes(png)


def luminance(img):
    return img @ np.array([0.2126, 0.7152, 0.0722])


def mask(ref_lum, emitter, border):
    bright = ref_lum > emitter
    keep = ~bright
    for dy in range(-border, border + 1):
        for dx in range(-border, border + 1):
            keep &= ~np.roll(np.roll(bright, dy, 0), dx, 1)
    return keep


def radial_bands(err):
    power = np.abs(np.fft.fft2(err)) ** 2 / err.size
    fy = np.fft.fftfreq(err.shape[0])[:, None]
    fx = np.fft.fftfreq(err.shape[1])[None, :]
    radius = np.sqrt(fx ** 2 + fy ** 2)
    return [power[(radius > lo) & (radius <= hi)].mean() for lo, hi in BANDS]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--reference", required=True, type=Path)
    p.add_argument("--lowdisc", default="target/release/lowdisc")
    p.add_argument("--out", type=Path, default=Path("out/spectra"))
    p.add_argument("--samplers", default="independent,sobol,zsobol,zsobol-4d,zorder-sz")
    p.add_argument("--seeds", type=int, default=4)
    p.add_argument("--res", default="128x128")
    p.add_argument("--spp", type=int, default=16)
    p.add_argument("--maxdepth", type=int, default=1)
    p.add_argument("--emitter", type=float, default=2.0)
    p.add_argument("--border", type=int, default=3)
    p.add_argument("--gain", type=float, default=2000.0)
    a = p.parse_args()
    a.out.mkdir(parents=True, exist_ok=True)
    ref = luminance(read_pfm(a.reference))
    keep = mask(ref, a.emitter, a.border)
    rows = []
    for name in a.samplers.split(","):
        bands, mse = [], []
        for seed in range(a.seeds):
            path = a.out / f"{name}-{seed}.pfm"
            subprocess.run([a.lowdisc, "render", "--sampler", name, "--seed", str(seed),
                            "--res", a.res, "--spp", str(a.spp), "--maxdepth", str(a.maxdepth),
                            "-o", str(path)], check=True, stderr=subprocess.DEVNULL)
            err = np.where(keep, luminance(read_pfm(path)) - ref, 0.0)
            bands.append(radial_bands(err))
            mse.append((err[keep] ** 2).mean())
            if seed == 0:
                write_png(a.out / f"{name}-error.png", np.clip(128 + a.gain * err, 0, 255))
        rows.append((name, np.mean(mse), np.mean(bands, axis=0)))
    head = ("| sampler | masked luminance MSE | "
            + " | ".join(f"power {lo:g}-{hi:g}" for lo, hi in BANDS) + " | low / high |")
    lines = [f"Error spectra: {a.res}, {a.spp} spp, depth {a.maxdepth}, {a.seeds} seeds, "
             f"{100 * keep.mean():.1f} % of pixels kept; power relative to white noise "
             "of the same MSE (1 = flat)", "", head, "|---" * (len(BANDS) + 3) + "|"]
    for name, mse, bands in rows:
        white = mse * keep.mean()
        cells = " | ".join(f"{b / white:.3f}" for b in bands)
        lines.append(f"| `{name}` | {mse:.3e} | {cells} | {bands[0] / bands[-2]:.3f} |")
    text = "\n".join(lines) + "\n"
    (a.out / "spectra.md").write_text(text)
    print(text)


if __name__ == "__main__":
    sys.exit(main())
