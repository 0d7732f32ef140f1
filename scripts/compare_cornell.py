#!/usr/bin/env python3
"""Check that lowdisc's built-in Cornell box agrees with Mitsuba 3 within noise.

Renders the same Cornell box (scripts/mitsuba_cornell.py builds it in
Mitsuba) twice with each renderer, with independent seeds, and compares:

* per-channel image means, with their standard errors estimated from the
  differences of the two renders of each renderer;
* the per-pixel mean squared difference between the renderers,
  MSE(lowdisc, mitsuba), against what noise alone gives,
  (MSE(lowdisc_0, lowdisc_1) + MSE(mitsuba_0, mitsuba_1)) / 2: if both
  renderers converge to the same image the ratio is 1 up to noise, and a
  bias b adds b^2 to the numerator;
* the same on 8x8-pixel block means (less noise, so more sensitive to bias).

Usage:
  cargo build --release -p lowdisc-cli
  DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 \\
    python3 scripts/compare_cornell.py --lowdisc target/release/lowdisc \\
    --variant llvm_ad_rgb --res 128x128 --spp 1024 --maxdepth 5
"""

import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mitsuba_cornell  # noqa: E402


def load_exr(mi, path):
    import numpy as np

    return np.array(mi.Bitmap(path), dtype=np.float64)[..., :3]


def blocks(img, k):
    h, w, c = img.shape
    h, w = h // k * k, w // k * k
    return img[:h, :w].reshape(h // k, k, w // k, k, c).mean(axis=(1, 3))


def compare(lo, mi_imgs, label):
    """Prints the agreement statistics of two renders per renderer."""
    import numpy as np

    l0, l1 = lo
    m0, m1 = mi_imgs
    lm, mm = (l0 + l1) / 2, (m0 + m1) / 2
    # Variance of a pixel's mean of two renders: MSE(x0, x1) / 4 each.
    noise = (np.mean((l0 - l1) ** 2) + np.mean((m0 - m1) ** 2)) / 4
    diff = np.mean((lm - mm) ** 2)
    print("%s: MSE(lowdisc, mitsuba) = %.4e, expected from noise %.4e, ratio %.3f"
          % (label, diff, noise, diff / noise))
    return diff / noise


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lowdisc", required=True, help="path of the lowdisc binary")
    ap.add_argument("--variant", default="llvm_ad_rgb")
    ap.add_argument("--res", default="128x128")
    ap.add_argument("--spp", type=int, default=1024)
    ap.add_argument("--maxdepth", type=int, default=5)
    a = ap.parse_args()
    import mitsuba as mi
    import numpy as np

    mi.set_variant(a.variant)
    res = [int(v) for v in a.res.lower().split("x")]
    with tempfile.TemporaryDirectory() as tmp:
        scene = mi.load_dict(mitsuba_cornell.scene_dict(mi, tmp, res, a.spp, a.maxdepth))
        mits = [np.array(mi.render(scene, spp=a.spp, seed=s), dtype=np.float64)[..., :3]
                for s in (11, 12)]
        low = []
        for seed in (1, 2):
            out = os.path.join(tmp, "lowdisc-%d.exr" % seed)
            subprocess.run([a.lowdisc, "render", "--res", a.res, "--spp", str(a.spp),
                            "--maxdepth", str(a.maxdepth), "--sampler", "sobol-owen",
                            "--seed", str(seed), "--quiet", "-o", out], check=True)
            low.append(load_exr(mi, out))
    print("Cornell box %s, %d spp, %d bounces; lowdisc sobol-owen seeds 1, 2; "
          "Mitsuba %s %s seeds 11, 12" % (a.res, a.spp, a.maxdepth, mi.__version__, a.variant))
    for c, name in enumerate("RGB"):
        lm = [x[..., c].mean() for x in low]
        mm = [x[..., c].mean() for x in mits]
        # Standard error of the difference of the two-render means, from the
        # per-pixel noise (pixels' errors taken as independent).
        pix = ((low[0][..., c] - low[1][..., c]) ** 2).mean() / 4 \
            + ((mits[0][..., c] - mits[1][..., c]) ** 2).mean() / 4
        se = np.sqrt(pix / low[0][..., c].size)
        d = np.mean(lm) - np.mean(mm)
        print("mean %s: lowdisc %.5f, mitsuba %.5f, difference %+.5f (%.2f %%), "
              "%.1f standard errors" % (name, np.mean(lm), np.mean(mm), d,
                                         100 * d / np.mean(mm), d / se if se > 0 else float("inf")))
    compare(low, mits, "pixels")
    compare([blocks(x, 8) for x in low], [blocks(x, 8) for x in mits], "8x8 blocks")


if __name__ == "__main__":
    main()
