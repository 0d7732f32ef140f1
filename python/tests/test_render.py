"""Renders from Python: bit identity with the ``lowdisc render`` binary,
the settings resolution (scene file, then arguments), errors, progress,
Ctrl-C; and the image measures against analytic values."""

from __future__ import annotations

import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import lowdisc

SCENE = """LookAt 0 0 5  0 0 0  0 1 0
Camera "perspective" "float fov" [ 30 ]
Film "rgb" "integer xresolution" [ 20 ] "integer yresolution" [ 14 ]
Sampler "halton" "integer pixelsamples" [ 3 ]
Integrator "path" "integer maxdepth" [ 3 ]
WorldBegin
LightSource "infinite" "rgb L" [ 0.5 0.5 0.5 ]
AttributeBegin
  Translate 2 2 4
  AreaLightSource "diffuse" "rgb L" [ 20 20 20 ]
  Shape "sphere" "float radius" [ 0.5 ]
AttributeEnd
Material "diffuse" "rgb reflectance" [ 0.7 0.3 0.2 ]
Shape "sphere" "float radius" [ 1 ]
"""


def read_pfm(path) -> np.ndarray:
    """A colour PFM file as an (h, w, 3) float32 array, top row first."""
    data = path.read_bytes()
    magic, size, scale, pixels = data.split(b"\n", 3)
    assert magic == b"PF"
    w, h = map(int, size.split())
    endian = "<" if float(scale) < 0 else ">"
    values = np.frombuffer(pixels, dtype=endian + "f4", count=w * h * 3)
    return values.reshape(h, w, 3)[::-1]


def cli_render(lowdisc_bin, tmp_path, *args) -> np.ndarray:
    out = tmp_path / "cli.pfm"
    subprocess.run([str(lowdisc_bin), "render", *args, "-o", str(out), "-q"], check=True)
    return read_pfm(out)


@pytest.mark.parametrize("spectral", [False, True])
def test_the_cornell_box_equals_the_binarys_bit_for_bit(lowdisc_bin, tmp_path, spectral):
    flags = ["--sampler", "sobol-owen", "--spp", "3", "--seed", "5", "--res", "24x16"]
    ours = lowdisc.render("cornell", sampler="sobol-owen", spp=3, seed=5, resolution=(24, 16),
                          spectral=spectral, threads=1)
    theirs = cli_render(lowdisc_bin, tmp_path, *flags, *(["--spectral"] if spectral else []))
    assert ours.shape == (16, 24, 3) and ours.dtype == np.float32
    assert ours.mean() > 0
    assert np.array_equal(ours, theirs)


def test_a_scene_files_settings_apply_unless_overridden(lowdisc_bin, tmp_path):
    scene = tmp_path / "scene.pbrt"
    scene.write_text(SCENE)
    # The file's halton, 3 spp, depth 3 and 20x14 film, as the CLI reads them.
    ours = lowdisc.render(scene)
    assert ours.shape == (14, 20, 3)
    assert np.array_equal(ours, cli_render(lowdisc_bin, tmp_path, str(scene)))
    other = lowdisc.render(str(scene), sampler="zsobol", spp=2, max_depth=1, seed=9)
    theirs = cli_render(lowdisc_bin, tmp_path, str(scene), "--sampler", "zsobol", "--spp", "2",
                        "--maxdepth", "1", "--seed", "9")
    assert np.array_equal(other, theirs)
    assert not np.array_equal(other, ours)


def test_presets_are_the_experiments_scenes():
    direct = lowdisc.render("direct", spp=2, resolution=(16, 16))
    gi = lowdisc.render("gi", spp=2, resolution=(16, 16))
    # Depth 1 against depth 5: indirect light brightens the gi box.
    assert gi.mean() > direct.mean() > 0
    assert set(lowdisc.BUILTIN_SCENES) == {"cornell", "direct", "gi"}


def test_bad_arguments_raise_the_one_line_message(tmp_path):
    with pytest.raises(ValueError, match=r"^unknown sampler \"sobl\"; expected one of"):
        lowdisc.render(sampler="sobl", spp=1, resolution=(4, 4))
    with pytest.raises(ValueError, match="spp: samples per pixel 0"):
        lowdisc.render(spp=0)
    with pytest.raises(ValueError, match="^cannot load scene `.*missing.pbrt`"):
        lowdisc.render(tmp_path / "missing.pbrt")
    bad = tmp_path / "bad.pbrt"
    bad.write_text("WorldBegin\nShape \"sphere\" \"float radius\" [ 1\n")
    with pytest.raises(ValueError, match=r"bad.pbrt:2:") as error:
        lowdisc.render(bad)
    assert "\n" not in str(error.value)
    with pytest.raises(TypeError, match="progress must be"):
        lowdisc.render(spp=1, resolution=(4, 4), progress=3)
    with pytest.raises(ValueError, match="resolution must be"):
        lowdisc.render(resolution=(4,))


def test_progress_reaches_the_total_and_a_raising_callback_stops_the_render(capsys):
    seen = []
    lowdisc.render(spp=2, resolution=(40, 40), progress=lambda d, t: seen.append((d, t)))
    assert seen and seen[-1] == (40 * 40 * 2, 40 * 40 * 2)
    assert all(a[0] <= b[0] for a, b in zip(seen, seen[1:]))
    lowdisc.render(spp=1, resolution=(8, 8), progress=True)
    assert "100%" in capsys.readouterr().err

    def stop(done, total):
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        lowdisc.render(spp=64, resolution=(256, 256), progress=stop)


def test_ctrl_c_stops_a_render_promptly():
    # A render of minutes; SIGINT after it started must end it within seconds.
    code = textwrap.dedent("""
        import sys, time, lowdisc
        print("start", flush=True)
        t = time.monotonic()
        try:
            lowdisc.render("gi", spp=4096, resolution=(512, 512))
        except KeyboardInterrupt:
            print(f"interrupted {time.monotonic() - t:.2f}", flush=True)
            sys.exit(0)
        sys.exit(1)
    """)
    child = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "start"
    time.sleep(1.0)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=60)
    assert child.returncode == 0, out
    assert out.startswith("interrupted"), out
    assert time.monotonic() - sent < 5.0


SMALL = dict(spp=3, seed=5, resolution=(24, 16), threads=2)


def write_matrix_file(path, matrices) -> None:
    """A matrix file (lowdisc::net's format): one dimension per line, its 32
    column words in hexadecimal."""
    lines = ["# generator matrices, one dimension per line"]
    lines += [" ".join(f"{int(c):#010x}" for c in row) for row in matrices]
    path.write_text("\n".join(lines) + "\n")


@pytest.mark.parametrize("sampler, dims", [("sobol-owen", lowdisc.SOBOL_DIMENSIONS),
                                           ("zsobol-4d", 4), ("padded-sobol", 2)])
def test_sobols_own_matrices_as_numpy_render_what_no_net_renders(sampler, dims):
    plain = lowdisc.render("cornell", sampler=sampler, **SMALL)
    matrices = lowdisc.sobol_matrices(dims)
    assert np.array_equal(lowdisc.render("cornell", sampler=sampler, net=matrices, **SMALL),
                          plain)
    # Any integer dtype holding the same words, and the built-in name.
    as_int64 = matrices.astype(np.int64)
    assert np.array_equal(lowdisc.render("cornell", sampler=sampler, net=as_int64, **SMALL),
                          plain)
    assert np.array_equal(lowdisc.render("cornell", sampler=sampler, net="sobol", **SMALL),
                          plain)


@pytest.mark.parametrize("sampler", ["zsobol-4d", "sobol-owen"])
def test_a_net_from_numpy_renders_what_the_binary_renders_with_its_file(lowdisc_bin, tmp_path,
                                                                        sampler):
    # A prototype net: Joe & Kuo's first 8 dimensions with dimensions 2-3
    # and 4-5 swapped and dimension 6 replaced by van der Corput.
    matrices = lowdisc.sobol_matrices(8)[[0, 1, 3, 2, 5, 4, 0, 7]]
    file = tmp_path / "mine.txt"
    write_matrix_file(file, matrices)
    flags = ["--sampler", sampler, "--spp", "3", "--seed", "5", "--res", "24x16"]
    theirs = cli_render(lowdisc_bin, tmp_path, *flags, "--net", str(file))
    ours = lowdisc.render("cornell", sampler=sampler, net=matrices, **SMALL)
    assert np.array_equal(ours, theirs)
    assert np.array_equal(lowdisc.render("cornell", sampler=sampler, net=file, **SMALL), theirs)
    assert np.array_equal(lowdisc.render("cornell", sampler=sampler, net=str(file), **SMALL),
                          theirs)
    assert not np.array_equal(ours, lowdisc.render("cornell", sampler=sampler, **SMALL))


def test_a_built_in_net_renders_what_the_binary_renders(lowdisc_bin, tmp_path):
    flags = ["--sampler", "zsobol-4d", "--spp", "3", "--seed", "5", "--res", "24x16"]
    theirs = cli_render(lowdisc_bin, tmp_path, *flags, "--net", "onetwo")
    ours = lowdisc.render("cornell", sampler="zsobol-4d", net="onetwo", **SMALL)
    assert np.array_equal(ours, theirs)
    assert not np.array_equal(ours, lowdisc.render("cornell", sampler="zsobol-4d", **SMALL))


def test_bad_nets_raise_value_error_with_the_reason(tmp_path):
    def render(net, sampler="zsobol-4d"):
        return lowdisc.render("cornell", sampler=sampler, net=net, spp=1, resolution=(4, 4))

    good = lowdisc.sobol_matrices(4)
    with pytest.raises(ValueError, match=r"shape \(dims, 32\).*got \(4, 31\)"):
        render(good[:, :31])
    with pytest.raises(ValueError, match=r"shape \(dims, 32\).*got \(128,\)"):
        render(good.ravel())
    with pytest.raises(ValueError, match=r"shape \(dims, 32\).*got \(1, 4, 32\)"):
        render(good[None])
    with pytest.raises(ValueError, match="1 to 65536 dimensions, got 0"):
        render(good[:0])
    with pytest.raises(ValueError, match="got dtype float64"):
        render(good.astype(np.float64))
    with pytest.raises(ValueError, match="got dtype bool"):
        render(good > 0)
    with pytest.raises(ValueError, match=r"in \[0, 2\*\*32\)"):
        render(-good.astype(np.int64))
    with pytest.raises(ValueError, match=r"in \[0, 2\*\*32\)"):
        render(good.astype(np.int64) << 1)
    singular = good.copy()
    singular[3, 9] = singular[3, 2]
    with pytest.raises(ValueError, match=r"^net array: dimension 3 is not a \(0,1\)-sequence"):
        render(singular)
    zero = good.copy()
    zero[1] = 0
    with pytest.raises(ValueError, match="dimension 1 is not a \\(0,1\\)-sequence"):
        render(zero)
    with pytest.raises(ValueError, match="3 dimensions; a sampler padded by 4-D groups needs"):
        render(good[:3])
    with pytest.raises(ValueError, match="does not take generator matrices"):
        render("onetwo", sampler="halton")
    with pytest.raises(ValueError, match="does not take generator matrices"):
        render(good, sampler="pmj02bn")
    with pytest.raises(ValueError, match="is not a built-in net .*nor a readable file"):
        render(tmp_path / "missing.txt")
    bad = tmp_path / "bad.txt"
    bad.write_text("0x80000000 0x40000000\n")
    with pytest.raises(ValueError, match="bad.txt:1: 2 columns; a dimension has 32"):
        render(bad)


def test_image_errors_are_the_analytic_values():
    ref = np.full((3, 4, 3), 0.5, dtype=np.float32)
    e = lowdisc.errors(ref + 0.25, ref)
    assert (e.mse, e.rmse, e.mae) == (0.0625, 0.25, 0.25)
    assert e.relmse == pytest.approx(0.0625 / (0.25 + lowdisc.RELMSE_EPSILON), rel=1e-12)
    # A mask keeping one pixel whose error is 1: its error alone.
    test = ref.copy()
    test[1, 2] += 1.0
    mask = np.zeros((3, 4), bool)
    mask[1, 2] = True
    assert lowdisc.mse(test, ref, mask=mask) == 1.0
    assert lowdisc.mse(test, ref) == pytest.approx(1 / 12)
    assert lowdisc.error_image(test, ref, kind="squared").sum() == pytest.approx(3.0)
    with pytest.raises(ValueError, match="mask must have shape"):
        lowdisc.mse(test, ref, mask=np.ones((4, 3), bool))
    with pytest.raises(ValueError, match=r"\(height, width, 3\)"):
        lowdisc.mse(np.zeros((3, 4)), np.zeros((3, 4)))
    with pytest.raises(ValueError, match="kind must be"):
        lowdisc.error_image(test, ref, kind="cubed")


def test_blurred_mse_keeps_a_constant_error_and_damps_white_noise():
    rng = np.random.default_rng(1)
    ref = np.zeros((64, 64, 3))
    # The images are float32: the constant error is float32(0.3).
    assert lowdisc.blurred_mse(ref + 0.3, ref) == pytest.approx(float(np.float32(0.3)) ** 2,
                                                                rel=1e-12)
    noise = rng.normal(size=ref.shape)
    # White noise of variance v blurs to about v * sum(G^2) = v / (4 pi) at sigma 1.
    ratio = lowdisc.blurred_mse(noise, ref) / lowdisc.mse(noise, ref)
    assert 0.06 < ratio < 0.1, ratio


def test_compare_is_the_experiments_paired_ratio():
    rng = np.random.default_rng(2)
    base = np.exp(rng.normal(size=40))
    half = 0.5 * base * np.exp(0.05 * rng.normal(size=40))
    c = lowdisc.compare(half, base)
    assert c.n == 40 and c.verdict == "better"
    assert c.low < 0.5 < c.high < 1
    assert c.ratio == pytest.approx(np.exp(np.mean(np.log(half / base))), rel=1e-12)
    assert lowdisc.compare(base, half).verdict == "worse"
    with pytest.raises(ValueError, match="at least 2"):
        lowdisc.compare([1.0], [1.0])
    with pytest.raises(ValueError, match="positive"):
        lowdisc.compare([1.0, -1.0], [1.0, 1.0])
