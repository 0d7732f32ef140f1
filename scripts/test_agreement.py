"""Tests of scripts/agreement.py's scene scan and statistics on synthetic
data (no renderer needed): `python3 -m pytest -q scripts/test_agreement.py`."""

import gzip
import os
import struct
import sys
import zlib

import numpy as np
import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import agreement  # noqa: E402
import pbrt_variants  # noqa: E402

SHAPE = (96, 128, 3)


def renders(rng, truth, sigma, n=2):
    """`n` noisy renders of `truth`: Gaussian pixel noise of relative size
    `sigma` (positive images)."""
    return [truth * np.abs(1 + sigma * rng.standard_normal(truth.shape)) for _ in range(n)]


def scene_truth(rng):
    """A smooth positive test image with a bright corner."""
    y, x = np.mgrid[0:SHAPE[0], 0:SHAPE[1]]
    base = 0.2 + 0.8 * np.exp(-((x - 30) ** 2 + (y - 20) ** 2) / 800.0)
    return np.stack([base, 0.7 * base, 0.4 * base + 0.05], axis=-1)


def test_standard_error_matches_the_noise():
    rng = np.random.default_rng(1)
    truth = np.full(SHAPE, 1.0)
    a, b = (truth + 0.3 * rng.standard_normal(SHAPE) for _ in range(2))
    means, se = agreement.mean_and_se(a, b)
    n = SHAPE[0] * SHAPE[1]
    expected = 0.3 / np.sqrt(2 * n)  # the mean of 2n pixels of noise 0.3
    assert np.all(np.abs(se / expected - 1) < 0.1)
    assert np.allclose(means, [(a[..., c].mean() + b[..., c].mean()) / 2 for c in range(3)])


def test_band_holds_same_distribution_and_rejects_a_shift():
    rng = np.random.default_rng(2)
    held, n = 0, 200
    for _ in range(n):
        x, y = rng.lognormal(0, 0.1, 500), rng.lognormal(0, 0.1, 500)
        lo, hi = agreement.quantile_band(x)
        held += lo <= np.quantile(y, 0.05) and np.quantile(y, 0.95) <= hi
    assert held >= 0.9 * n
    x = rng.lognormal(0, 0.1, 500)
    lo, hi = agreement.quantile_band(x)
    assert np.quantile(1.1 * rng.lognormal(0, 0.1, 500), 0.95) > hi


def test_verdicts_on_synthetic_renders():
    rng = np.random.default_rng(3)
    truth = scene_truth(rng)
    pbrt = renders(rng, truth, 0.5)
    same = agreement.compare(renders(rng, truth, 0.5), pbrt)
    assert agreement.verdict(same) == ("agrees", [])
    slightly_off = agreement.compare(renders(rng, 1.01 * truth, 0.5), pbrt)
    assert agreement.verdict(slightly_off)[0] == "agrees"
    biased = agreement.compare(renders(rng, 1.06 * truth, 0.5), pbrt)
    verdict, reasons = agreement.verdict(biased)
    assert verdict == "differs" and any("mean" in r for r in reasons)
    noisier = agreement.compare(renders(rng, truth, 2.0), pbrt)
    verdict, reasons = agreement.verdict(noisier)
    assert verdict == "differs" and any("block" in r for r in reasons)
    black = agreement.compare([np.zeros(SHAPE)] * 2, pbrt)
    assert agreement.verdict(black)[0] == "differs"


def test_one_dark_region_shows_in_the_block_ratio_not_only_the_mean():
    rng = np.random.default_rng(4)
    truth = scene_truth(rng)
    dark = truth.copy()
    dark[-32:, -48:] *= 0.85  # 12.5 % of the blocks, a dim corner: the mean moves < 1.5 %
    stats = agreement.compare(renders(rng, dark, 0.2), renders(rng, truth, 0.2))
    verdict, reasons = agreement.verdict(stats)
    assert max(abs(r - 1) for r in stats["mean_ratio"]) < agreement.MEAN_TOLERANCE
    assert verdict == "differs" and any("p5" in r for r in reasons)


def write_pfm(path, img):
    """A colour PFM in the format's bottom-to-top row order."""
    h, w, _ = img.shape
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        f.write(img[::-1].astype("<f4").tobytes())


def test_pfm_rows_read_top_to_bottom(tmp_path):
    img = np.arange(2 * 3 * 3, dtype=float).reshape(2, 3, 3)
    write_pfm(tmp_path / "a.pfm", img)
    assert np.array_equal(agreement.read_pfm(str(tmp_path / "a.pfm")), img)


def test_png_header_and_pixels(tmp_path):
    rgb = np.arange(2 * 5 * 3, dtype=np.uint8).reshape(2, 5, 3)
    agreement.write_png(str(tmp_path / "a.png"), rgb)
    data = (tmp_path / "a.png").read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    assert struct.unpack(">II", data[16:24]) == (5, 2)
    idat = data.index(b"IDAT")
    (length,) = struct.unpack(">I", data[idat - 4:idat])
    raw = zlib.decompress(data[idat + 4:idat + 4 + length])
    assert raw == b"\x00" + rgb[0].tobytes() + b"\x00" + rgb[1].tobytes()


SCENE = """# a comment naming "old.ply"
Film "rgb" "string filename" [ "out.exr" ] # "integer xresolution" [ 32 ]
    "integer xresolution" [ 400 ] "integer yresolution" [ 300 ]
Sampler "sobol" "integer pixelsamples" [ 64 ]
WorldBegin
Include "geometry/parts.pbrt"
Texture "t" "spectrum" "imagemap" "string filename" "textures/wood.tga"
Shape "plymesh" "string filename" [ "models/a.ply" ]
"""


def test_named_files_skip_comments_and_the_film_output():
    assert agreement.named_files(SCENE) == [
        "geometry/parts.pbrt", "textures/wood.tga", "models/a.ply"]
    assert agreement.film_resolution(SCENE) == (400, 300)


def test_missing_files_restores_compressed_and_flags_lfs_pointers(tmp_path):
    (tmp_path / "geometry").mkdir()
    (tmp_path / "models").mkdir()
    (tmp_path / "geometry" / "parts.pbrt").write_text('Shape "plymesh" "string filename" "models/b.ply"\n')
    with gzip.open(tmp_path / "models" / "a.ply.gz", "wb") as f:
        f.write(b"ply\n")
    (tmp_path / "models" / "b.ply").write_bytes(b"version https://git-lfs.github.com/spec/v1\n")
    (tmp_path / "scene.pbrt").write_text(SCENE)
    missing = agreement.missing_files(str(tmp_path / "scene.pbrt"))
    assert sorted(missing) == ["models/b.ply", "textures/wood.tga"]
    assert (tmp_path / "models" / "a.ply").read_bytes() == b"ply\n"


def test_rewritten_scene_has_one_resolution_and_the_sampler(tmp_path):
    text = pbrt_variants.set_resolution(SCENE, 100, 75)
    assert agreement.film_resolution(text) == (100, 75)
    assert text.count("xresolution") == 1
    defaulted = pbrt_variants.set_resolution('Film "rgb"\nWorldBegin\n', 320, 180)
    assert agreement.film_resolution(defaulted) == (320, 180)
    src = tmp_path / "s" / "scene.pbrt"
    src.parent.mkdir()
    src.write_text(SCENE)
    out = pbrt_variants.write_variant(str(src), str(tmp_path / "v"), res=(100, 75),
                                      sampler="independent", spp=4)
    assert 'Sampler "independent" "integer pixelsamples" [ 4 ]' in open(out).read()


@pytest.mark.parametrize("size,expected", [((1280, 720), (320, 180)), ((64, 64), (128, 128)),
                                           ((200, 100), (128, 64))])
def test_reduced_resolution(size, expected):
    assert agreement.reduced_resolution(*size, 4, 128) == expected


def test_table_counts_verdicts_and_takes_the_median_speed_up():
    stats = {"mean_ratio": [1, 1, 1], "sigmas": [0, 0, 0], "cross": [0.9, 1, 1.1],
             "band": [0.8, 1.2]}
    rows = [{"scene": "a", "verdict": "agrees", "stats": stats, "time_lowdisc": 1.0,
             "time_pbrt": 3.0},
            {"scene": "b", "verdict": "agrees", "stats": stats, "time_lowdisc": 2.0,
             "time_pbrt": 2.0},
            {"scene": "c", "verdict": "refused", "note": "x | y", "time_lowdisc": 0.1}]
    table = agreement.table_markdown(rows)
    assert "Verdicts: agrees 2, refused 1." in table
    assert "lowdisc (pbrt-v4 time / its time) over 2 compared scenes: 2.00." in table
    assert "x / y" in table


def test_side_by_side_has_three_panels(tmp_path):
    rng = np.random.default_rng(5)
    truth = scene_truth(rng)
    agreement.side_by_side(str(tmp_path / "s.png"), renders(rng, truth, 0.1),
                           renders(rng, truth, 0.1))
    data = (tmp_path / "s.png").read_bytes()
    assert struct.unpack(">II", data[16:24]) == (3 * SHAPE[1] + 8, SHAPE[0])


FAKE_RENDERER = """#!/usr/bin/env python3
# A stand-in renderer: a noisy grey PFM of the scene's resolution, seeded by
# --seed; refuses a scene naming "bdpt"; counts its runs in a log.
import random, re, struct, sys
args = sys.argv[1:]
out = args[args.index("-o" if "-o" in args else "--outfile") + 1]
seed = int(args[args.index("--seed") + 1])
scene = open([a for a in args if a.endswith(".pbrt")][0]).read()
open(sys.argv[0] + ".log", "a").write("run\\n")
if "bdpt" in scene:
    sys.exit("error: scene.pbrt:1:1: Integrator \\"bdpt\\" is not supported")
w = int(re.search(r'xresolution" \\[ (\\d+)', scene).group(1))
h = int(re.search(r'yresolution" \\[ (\\d+)', scene).group(1))
rng = random.Random(seed)
with open(out, "wb") as f:
    f.write(b"PF\\n%d %d\\n-1.0\\n" % (w, h))
    f.write(struct.pack("<%df" % (3 * w * h), *(0.5 * rng.uniform(0.5, 1.5) for _ in range(3 * w * h))))
"""


def test_harness_end_to_end_with_stand_in_renderers(tmp_path):
    for name in ("lowdisc", "pbrt"):
        (tmp_path / name).write_text(FAKE_RENDERER)
        (tmp_path / name).chmod(0o755)
    scenes = {"fine": 'Integrator "path"\n', "bidir": 'Integrator "bdpt"\n',
              "partial": 'Shape "plymesh" "string filename" "models/gone.ply"\n'}
    for name, text in scenes.items():
        (tmp_path / "c" / name / "pbrt").mkdir(parents=True)
        (tmp_path / "c" / name / "pbrt" / "scene-v4.pbrt").write_text(
            text + 'Film "rgb" "integer xresolution" [ 512 ] "integer yresolution" [ 256 ]\n'
            'WorldBegin\n')
    argv = ["--collection", str(tmp_path / "c"), "--lowdisc", str(tmp_path / "lowdisc"),
            "--pbrt", str(tmp_path / "pbrt"), "--spp", "4", "--out", str(tmp_path / "out")]
    agreement.main(argv)
    table = (tmp_path / "out" / "spp4-div4-min128" / "table-spectral.md").read_text()
    assert "| fine | 128x64 | **agrees** |" in table
    assert '| bidir | 128x64 | **refused** |' in table and 'Integrator "bdpt"' in table
    assert "| partial |  | **incomplete** |" in table and "models/gone.ply" in table
    assert (tmp_path / "out" / "spp4-div4-min128" / "fine" / "spectral" / "side-by-side.png").exists()
    runs = (tmp_path / "lowdisc.log").read_text().count("run")
    assert runs == 3 and (tmp_path / "pbrt.log").read_text().count("run") == 2
    agreement.main(argv)  # resumed: nothing is rendered again
    assert (tmp_path / "lowdisc.log").read_text().count("run") == runs
