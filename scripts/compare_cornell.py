#!/usr/bin/env python3
"""Check that lowdisc's built-in Cornell box agrees with Mitsuba 3 within noise.

Renders the same Cornell box (scripts/mitsuba_cornell.py builds it in
Mitsuba) K times with each renderer (--renders, default 2), with
independent seeds, and compares:

* per-channel image means, with their standard errors estimated from the
  spread of the K renders of each renderer;
* the per-pixel mean squared difference between the renderers' K-render
  means, MSE(lowdisc, mitsuba), against what noise alone gives, the mean
  over pixels of (s2_lowdisc + s2_mitsuba) / K with s2 each pixel's sample
  variance over the K renders (for K = 2 this is
  (MSE(lowdisc_0, lowdisc_1) + MSE(mitsuba_0, mitsuba_1)) / 4): if both
  renderers converge to the same image the ratio is 1 up to noise, and a
  bias b adds b^2 to the numerator;
* the same on 8x8-pixel block means (less noise, so more sensitive to bias).

How far the ratio strays from 1 without any bias depends on how many pixels
carry the noise. In this scene almost all of it sits in the ~56 pixels cut
by the ceiling light's outline, and there it is Mitsuba's: its independent
sampler leaves a pixel covered a fraction c by the light a standard deviation
of about L sqrt(c (1 - c) / spp), tens of times that of lowdisc's
Owen-scrambled Sobol points. The script therefore prints the effective
number of independent terms, nu = (sum w)^2 / sum w^2 over the per-pixel
noise w (with the K-render estimates' own scatter taken out), and the
central 95 % range of the ratio when there is no bias, the quantiles of an
F(nu, nu (K - 1)) distribution (a pixel's channels count as one term). At
128x128 and 1024 spp nu is about 45 for pixels and about 7-10 for 8x8
blocks, so with K = 2 ratios up to ~1.8 (pixels) and ~4 (blocks) are noise;
more renders narrow the range.

Usage:
  cargo build --release -p lowdisc-cli
  DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 \\
    python3 scripts/compare_cornell.py --lowdisc target/release/lowdisc \\
    --variant llvm_ad_rgb --res 128x128 --spp 1024 --maxdepth 5 [--renders 8]
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


def no_bias_range(w, k):
    """Effective number of terms and the central 95 % range of the ratio
    under no bias, from the per-term noise estimates `w` of K renders."""
    import numpy as np

    # A K-render variance estimate has K - 1 degrees of freedom, so
    # E[w^2] = (1 + 2 / (K - 1)) E[w]^2: remove that from sum w^2.
    sq = np.sum(w ** 2) / (1 + 2 / (k - 1))
    nu = np.sum(w) ** 2 / sq if sq > 0 else float("inf")
    # Fixed seed: the printed range is reproducible.
    rng = np.random.default_rng(12345)
    f = (rng.chisquare(nu, 200000) / nu) / (rng.chisquare(nu * (k - 1), 200000) / (nu * (k - 1)))
    return nu, np.quantile(f, 0.025), np.quantile(f, 0.975)


def compare(lo, mi_imgs, label):
    """Prints the agreement statistics of K renders per renderer."""
    import numpy as np

    lo, mi_imgs = np.array(lo), np.array(mi_imgs)
    k = len(lo)
    # Variance of a pixel's mean of K renders: its sample variance / K.
    w = (lo.var(axis=0, ddof=1) + mi_imgs.var(axis=0, ddof=1)) / k
    noise = np.mean(w)
    diff = np.mean((lo.mean(axis=0) - mi_imgs.mean(axis=0)) ** 2)
    # A pixel's channels carry much the same noise (at the light's outline
    # they are one coin flip scaled by the light's RGB): count pixels, not
    # channels, as the terms.
    nu, q0, q1 = no_bias_range(w.mean(axis=-1).ravel(), k)
    print("%s: MSE(lowdisc, mitsuba) = %.4e, expected from noise %.4e, ratio %.3f "
          "(no bias: 95 %% of ratios in [%.2f, %.2f]; %.0f effective terms)"
          % (label, diff, noise, diff / noise, q0, q1, nu))
    return diff / noise


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lowdisc", required=True, help="path of the lowdisc binary")
    ap.add_argument("--variant", default="llvm_ad_rgb")
    ap.add_argument("--res", default="128x128")
    ap.add_argument("--spp", type=int, default=1024)
    ap.add_argument("--maxdepth", type=int, default=5)
    ap.add_argument("--renders", type=int, default=2,
                    help="renders per renderer (lowdisc seeds 1..K, Mitsuba 11..10+K)")
    ap.add_argument("--dump", default=None,
                    help="save the renders to this .npz "
                    "(arrays `lowdisc`, `mitsuba`: K x H x W x 3)")
    a = ap.parse_args()
    if a.renders < 2:
        ap.error("--renders must be at least 2 (the noise comes from their spread)")
    import mitsuba as mi
    import numpy as np

    mi.set_variant(a.variant)
    res = [int(v) for v in a.res.lower().split("x")]
    k = a.renders
    with tempfile.TemporaryDirectory() as tmp:
        scene = mi.load_dict(mitsuba_cornell.scene_dict(mi, tmp, res, a.spp, a.maxdepth))
        mits = [np.array(mi.render(scene, spp=a.spp, seed=s), dtype=np.float64)[..., :3]
                for s in range(11, 11 + k)]
        low = []
        for seed in range(1, 1 + k):
            out = os.path.join(tmp, "lowdisc-%d.exr" % seed)
            subprocess.run([a.lowdisc, "render", "--res", a.res, "--spp", str(a.spp),
                            "--maxdepth", str(a.maxdepth), "--sampler", "sobol-owen",
                            "--seed", str(seed), "--quiet", "-o", out], check=True)
            low.append(load_exr(mi, out))
    if a.dump:
        np.savez(a.dump, lowdisc=np.array(low), mitsuba=np.array(mits))
    print("Cornell box %s, %d spp, %d bounces; lowdisc sobol-owen seeds 1..%d; "
          "Mitsuba %s %s seeds 11..%d"
          % (a.res, a.spp, a.maxdepth, k, mi.__version__, a.variant, 10 + k))
    for c, name in enumerate("RGB"):
        lm = np.array([x[..., c].mean() for x in low])
        mm = np.array([x[..., c].mean() for x in mits])
        # Standard error of the difference of the K-render means, from the
        # per-pixel noise (pixels' errors taken as independent).
        pix = (np.array([x[..., c] for x in low]).var(axis=0, ddof=1).mean()
               + np.array([x[..., c] for x in mits]).var(axis=0, ddof=1).mean()) / k
        se = np.sqrt(pix / low[0][..., c].size)
        d = lm.mean() - mm.mean()
        print("mean %s: lowdisc %.5f, mitsuba %.5f, difference %+.5f (%.2f %%), "
              "%.1f standard errors" % (name, lm.mean(), mm.mean(), d,
                                         100 * d / mm.mean(), d / se if se > 0 else float("inf")))
    compare(low, mits, "pixels")
    compare([blocks(x, 8) for x in low], [blocks(x, 8) for x in mits], "8x8 blocks")


if __name__ == "__main__":
    main()
