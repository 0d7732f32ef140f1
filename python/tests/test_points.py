"""Points: bit identity with scipy, the CLI's pixel samples, net properties
of Owen-scrambled Sobol, the generator matrices."""

from __future__ import annotations

import subprocess

import numpy as np
import pytest

import lowdisc

scipy_qmc = pytest.importorskip("scipy.stats.qmc")


def test_unscrambled_sobol_is_scipys_bit_for_bit():
    ours = lowdisc.sobol(4096, 64)
    theirs = scipy_qmc.Sobol(64, scramble=False, bits=32).random(4096)
    assert np.array_equal(ours, theirs)
    # A later window, from start (scipy must draw the points before it).
    engine = scipy_qmc.Sobol(5, scramble=False, bits=32)
    engine.fast_forward(1000)
    assert np.array_equal(lowdisc.sobol(300, 5, start=1000), engine.random(300))


def test_dtypes_are_views_of_the_same_digit_words():
    words = lowdisc.sobol(256, 3, scramble="owen", seed=4, dtype=np.uint32)
    assert words.dtype == np.uint32
    x64 = lowdisc.sobol(256, 3, scramble="owen", seed=4)
    assert np.array_equal(x64, words / 2.0**32)
    x32 = lowdisc.sobol(256, 3, scramble="owen", seed=4, dtype="float32")
    assert x32.dtype == np.float32 and x32.max() < 1.0
    assert np.array_equal(x32, ((words >> 8) / 2.0**24).astype(np.float32))


def test_gray_and_natural_orders_give_the_same_first_2_to_the_m_points():
    gray = lowdisc.sobol(512, 4, scramble="fast-owen", seed=2)
    natural = lowdisc.sobol(512, 4, order="natural", scramble="fast-owen", seed=2)
    assert not np.array_equal(gray, natural)
    assert np.array_equal(np.sort(gray, axis=0), np.sort(natural, axis=0))


@pytest.mark.parametrize("scramble", ["owen", "owen-tree", "fast-owen", "lms"])
def test_scrambled_points_are_0_m_2_nets(scramble):
    # Sobol dimensions 0 and 1 form a (0, m, 2)-net, and nested (and
    # linear matrix) scrambling keeps it: every 2^a x 2^(m-a) box holds exactly one point, for every
    # m <= 16 (the first 2^m points of one draw).
    x = lowdisc.sobol(2**16, 2, scramble=scramble, seed=11, dtype=np.uint32).astype(np.int64)
    for m in range(17):
        for a in range(m + 1):
            cells = (x[:2**m, 0] >> (32 - a)) << (m - a) | (x[:2**m, 1] >> (32 - (m - a)))
            assert len(np.unique(cells)) == 2**m, (m, a)


@pytest.mark.parametrize("scramble", ["owen", "owen-tree"])
def test_owen_flips_depend_only_on_the_digits_before(scramble):
    # Nested: output digit b is input digit b XOR a flip that depends only on
    # digits 0..b-1, so two points sharing b leading digits share them after
    # scrambling and differ at digit b exactly when their inputs do.
    plain = lowdisc.sobol(4096, 3, dtype=np.uint32).astype(np.int64)
    scrambled = lowdisc.sobol(4096, 3, scramble=scramble, seed=8, dtype=np.uint32).astype(np.int64)
    rng = np.random.default_rng(0)
    i, k = rng.integers(0, 4096, size=(2, 5000))
    for b in range(32):
        share = (plain[i] >> (32 - b)) == (plain[k] >> (32 - b)) if b else np.ones((5000, 3), bool)
        flip_i = ((plain[i] ^ scrambled[i]) >> (31 - b)) & 1
        flip_k = ((plain[k] ^ scrambled[k]) >> (31 - b)) & 1
        assert np.array_equal(flip_i[share], flip_k[share]), b


@pytest.mark.parametrize("scramble", ["owen", "owen-tree"])
def test_owen_scrambled_points_are_uniform_over_seeds(scramble):
    # Each point of a nested uniform scramble is uniform in [0,1)^d: over
    # 2000 seeds, the mean of points 0 and 77 is near 1/2 and the variance
    # near 1/12 (5 standard errors).
    x = lowdisc.sobol(78, 3, scramble=scramble, seed=9, replications=2000)[:, [0, 77]]
    assert np.all(np.abs(x.mean(axis=0) - 0.5) < 5 * np.sqrt(1 / 12 / 2000))
    assert np.all(np.abs(x.var(axis=0) - 1 / 12) < 5 * np.sqrt(1 / 180 / 2000))
    # And the scramble changes with the seed.
    assert not np.array_equal(lowdisc.sobol(8, 2, scramble="owen", seed=1),
                              lowdisc.sobol(8, 2, scramble="owen", seed=2))


def test_halton_unscrambled_is_scipys_to_one_ulp():
    ours = lowdisc.halton(2000, 10)
    theirs = scipy_qmc.Halton(10, scramble=False).random(2000)
    assert np.max(np.abs(ours - theirs)) <= 2.0**-52


def test_results_do_not_depend_on_the_request_split():
    whole = lowdisc.halton(70_000, 2, scramble="owen", seed=3)
    parts = np.vstack([lowdisc.halton(30_000, 2, scramble="owen", seed=3),
                       lowdisc.halton(40_000, 2, start=30_000, scramble="owen", seed=3)])
    assert np.array_equal(whole, parts)
    ind = lowdisc.independent(100, 3, seed=8)
    assert np.array_equal(ind[50:], lowdisc.independent(50, 3, start=50, seed=8))
    strat = lowdisc.stratified(64, 2, seed=1)
    cells = np.floor(strat * 8).astype(int)
    assert len({tuple(c) for c in cells}) == 64  # one point per 8x8 stratum


def test_generator_matrices_reproduce_the_points():
    m = lowdisc.sobol_matrices(6)
    assert m.shape == (6, 32) and m.dtype == np.uint32
    k = np.arange(64, dtype=np.uint32)
    bits = (k[:, None] >> np.arange(32, dtype=np.uint32)) & 1
    words = np.bitwise_xor.reduce(np.where(bits[:, None, :] == 1, m[None, :, :], 0), axis=2)
    assert np.array_equal(words, lowdisc.sobol(64, 6, order="natural", dtype=np.uint32))


def test_qmcpy_reproduces_lowdiscs_sobol_from_the_exported_matrices():
    qmcpy = pytest.importorskip("qmcpy")
    net = qmcpy.DigitalNetB2(5, generating_matrices=lowdisc.qmcpy_generating_matrices(5),
                             msb=True, t=32, randomize=False, order="RADICAL INVERSE")
    assert np.array_equal(net.gen_samples(256, warn=False),
                          lowdisc.sobol(256, 5, order="natural"))


def cli_pixel_rows(binary, sampler, pixel, spp, res, extra, seed, net=None):
    out = subprocess.run(
        [str(binary), "points", "--sampler", sampler, "--pixel", f"{pixel[0]},{pixel[1]}",
         "--spp", str(spp), "--res", f"{res[0]}x{res[1]}", "--dims", str(extra),
         "--seed", str(seed), *(["--net", str(net)] if net is not None else [])],
        check=True, capture_output=True, text=True).stdout
    return np.array([[float(v) for v in line.split()] for line in out.splitlines()])


@pytest.mark.parametrize("sampler", lowdisc.sampler_names())
def test_pixel_samples_equal_the_renderers_as_the_cli_prints_them(lowdisc_bin, sampler):
    # Pixels in the first, a middle and the last (clipped) tile of the
    # renderer's grid.
    pixels = [(0, 0), (5, 2), (17, 3), (39, 19)]
    got = lowdisc.pixel_samples(sampler, 8, (40, 20), pixels, 7, seed=3)
    assert got.shape == (4, 8, 7) and got.dtype == np.float32
    for p, pixel in enumerate(pixels):
        rows = cli_pixel_rows(lowdisc_bin, sampler, pixel, 8, (40, 20), 5, 3)
        expected = rows.copy()
        expected[:, :2] -= pixel  # the CLI prints film positions
        assert np.array_equal(got[p].astype(np.float64), expected), (sampler, pixel)


@pytest.mark.parametrize("sampler", ["zsobol-4d", "sobol-owen", "padded-sobol-lms"])
def test_pixel_samples_with_a_net_equal_the_clis(lowdisc_bin, tmp_path, sampler):
    # A net as numpy matrices, and the same net as the CLI's matrix file.
    matrices = lowdisc.sobol_matrices(6)[[0, 1, 4, 5, 2, 3]]
    file = tmp_path / "net.txt"
    file.write_text("".join(" ".join(hex(c) for c in row) + "\n" for row in matrices))
    pixels = [(0, 0), (17, 3)]
    got = lowdisc.pixel_samples(sampler, 8, (40, 20), pixels, 7, seed=3, net=matrices)
    assert np.array_equal(lowdisc.pixel_samples(sampler, 8, (40, 20), pixels, 7, seed=3,
                                                net=file), got)
    for p, pixel in enumerate(pixels):
        rows = cli_pixel_rows(lowdisc_bin, sampler, pixel, 8, (40, 20), 5, 3, net=file)
        rows[:, :2] -= pixel
        assert np.array_equal(got[p].astype(np.float64), rows), (sampler, pixel)
    plain = lowdisc.pixel_samples(sampler, 8, (40, 20), pixels, 7, seed=3)
    if sampler != "padded-sobol-lms":  # it reads dimensions 0-1 only, unchanged here
        assert not np.array_equal(got, plain)
    else:
        assert np.array_equal(got, plain)
    with pytest.raises(ValueError, match="does not take generator matrices"):
        lowdisc.pixel_samples("halton", 8, (40, 20), pixels, 7, net=matrices)
    with pytest.raises(ValueError, match=r"shape \(dims, 32\)"):
        lowdisc.pixel_samples(sampler, 8, (40, 20), pixels, 7, net=matrices[:, :16])


def test_the_paper_stream_is_the_tiles_not_the_pixels_own():
    # The literal stream is re-seeded per tile and runs through the tile's
    # pixels: the first pixel of a tile starts the tile's stream (which
    # differs per tile).
    first = lowdisc.pixel_samples("paper", 4, (32, 32), [(0, 0), (16, 0)], 6, seed=2)
    assert not np.array_equal(first[0, :, 2:], first[1, :, 2:])


def test_every_catalog_sampler_is_available():
    assert set(lowdisc.sampler_names()) >= {
        "independent", "stratified", "halton", "halton-owen", "sobol", "sobol-xor",
        "sobol-owen", "sobol-fast-owen", "paper", "paper-repro", "padded-sobol", "zsobol"}
