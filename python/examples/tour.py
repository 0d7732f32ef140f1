"""A tour of lowdisc from Python, in the order of a notebook: draw points,
measure their discrepancy, render a built-in scene with two samplers, and
compare their errors against a reference image.

    python python/examples/tour.py                 # 128x128, a minute or two on 2 cores
    python python/examples/tour.py --size 16 --seeds 3 --reference-spp 64   # seconds

It needs only numpy and lowdisc; with ``--save DIR`` it also writes the
renders and error images as ``.npy`` files (``numpy.load`` reads them; any
image viewer that takes arrays shows them). Everything is seeded, so the
printed figures are the same on every run and machine.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

import lowdisc


def points_and_discrepancy(n: int) -> None:
    """Cell 1: Owen-scrambled Sobol points against independent ones."""
    sobol = lowdisc.sobol(n, 2, scramble="owen", seed=1)
    random = lowdisc.independent(n, 2, seed=1)
    print(f"{n} points in 2-D:        Sobol (Owen)   independent")
    for name, metric in (("centered L2 (squared)", lowdisc.discrepancy),
                         ("star discrepancy", lowdisc.star_discrepancy),
                         ("smallest distance", lowdisc.min_distance)):
        print(f"  {name:22} {metric(sobol):12.6f} {metric(random):13.6f}")


def renders(scene: str, size: int, spp: int, seeds: int, reference_spp: int,
            samplers: tuple[str, str], save: Path | None) -> None:
    """Cells 2-4: a reference, each sampler's renders over seeds, their
    errors, error images and the paired ratio."""
    common = dict(resolution=(size, size))
    reference = lowdisc.render(scene, sampler="sobol-owen", spp=reference_spp, seed=1234,
                               **common)
    errors = {}
    for sampler in samplers:
        images = [lowdisc.render(scene, sampler=sampler, spp=spp, seed=s, **common)
                  for s in range(seeds)]
        errors[sampler] = np.array([lowdisc.mse(im, reference) for im in images])
        blurred = np.mean([lowdisc.blurred_mse(im, reference) for im in images])
        print(f"  {sampler:12} MSE {errors[sampler].mean():.3e}  "
              f"blurred MSE {blurred:.3e}  (mean of {seeds} seeds)")
        if save is not None:
            np.save(save / f"{scene}-{sampler}.npy", images[0])
            np.save(save / f"{scene}-{sampler}-error.npy",
                    lowdisc.error_image(images[0], reference, kind="squared"))
    if save is not None:
        np.save(save / f"{scene}-reference.npy", reference)
    a, b = samplers
    c = lowdisc.compare(errors[a], errors[b])
    print(f"  MSE of {a} / {b}: {c.ratio:.3f}, 95 % interval [{c.low:.3f}, {c.high:.3f}]: "
          f"{c.verdict}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=1024)
    parser.add_argument("--scene", default="direct", choices=lowdisc.BUILTIN_SCENES)
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--spp", type=int, default=16)
    parser.add_argument("--seeds", type=int, default=8)
    parser.add_argument("--reference-spp", type=int, default=4096)
    parser.add_argument("--samplers", nargs=2, default=("zsobol", "independent"))
    parser.add_argument("--save", type=Path, help="folder for the .npy images")
    args = parser.parse_args()
    if args.save is not None:
        args.save.mkdir(parents=True, exist_ok=True)
    points_and_discrepancy(args.points)
    print(f"the {args.scene!r} scene at {args.size}x{args.size}, {args.spp} spp, against a "
          f"{args.reference_spp}-spp reference:")
    renders(args.scene, args.size, args.spp, args.seeds, args.reference_spp,
            tuple(args.samplers), args.save)


if __name__ == "__main__":
    main()
