"""Stereo from Python is c2f-stereo's: the same scene loading, energy, run and evaluation."""

import os
import pathlib
import subprocess

import numpy as np
import pytest

import c2f

TEDDY = pathlib.Path(os.environ.get("C2F_SHARED_DATA", "../shared/data")) / "middlebury/2003/Teddy"


def read_pfm(path):
    with open(path, "rb") as file:
        assert file.readline().strip() == b"Pf"
        width, height = map(int, file.readline().split())
        scale = float(file.readline())
        data = np.frombuffer(file.read(), dtype="<f4" if scale < 0 else ">f4")
    return data.reshape(height, width)[::-1]


@pytest.fixture
def teddy():
    if not TEDDY.is_dir():
        pytest.skip(f"no Middlebury data at {TEDDY} (set C2F_SHARED_DATA)")
    return c2f.read_stereo_pair(str(TEDDY / "left.png"), str(TEDDY / "right.png"),
                                gt=str(TEDDY / "disp_left.png"), gt_divisor=4.0,
                                mask=str(TEDDY / "nonocc.png"), downscale=3)


def test_teddy_through_python_and_through_c2f_stereo(teddy, tmp_path):
    build = os.environ.get("C2F_BUILD_DIR")
    if not build:
        pytest.skip("C2F_BUILD_DIR is not set (ctest sets it): no c2f-stereo to compare with")
    assert teddy["left"].shape == (125, 150, 3) and teddy["left"].dtype == np.uint8
    result = c2f.stereo(teddy["left"], teddy["right"], labels=20, schedule="paper")
    out = tmp_path / "out"
    subprocess.run([os.path.join(build, "examples/stereo/c2f-stereo"), str(TEDDY / "left.png"),
                    str(TEDDY / "right.png"), "--downscale", "3", "--labels", "20",
                    "--schedule", "paper", "-o", str(out), "-q"], check=True)
    np.testing.assert_array_equal(read_pfm(out / "disparity.pfm"), result.labeling)
    assert f"final energy {result.energy:.6f}" in (out / "summary.txt").read_text()


def test_stereo_defaults_are_c2f_stereos(teddy, tmp_path):
    """c2f.stereo with no schedule runs c2f.defaults('stereo'), as c2f-stereo with no flags."""
    defaults = c2f.defaults("stereo")
    assert defaults["grid_schedule"] == defaults["general_schedule"]
    result = c2f.stereo(teddy["left"], teddy["right"], labels=20)
    build = os.environ.get("C2F_BUILD_DIR")
    if not build:
        pytest.skip("C2F_BUILD_DIR is not set (ctest sets it): no c2f-stereo to compare with")
    out = tmp_path / "out"
    subprocess.run([os.path.join(build, "examples/stereo/c2f-stereo"), str(TEDDY / "left.png"),
                    str(TEDDY / "right.png"), "--downscale", "3", "--labels", "20", "-o",
                    str(out), "-q"], check=True)
    np.testing.assert_array_equal(read_pfm(out / "disparity.pfm"), result.labeling)
    summary = (out / "summary.txt").read_text()
    assert f"final energy {result.energy:.6f}" in summary
    assert f"near moves of radius {defaults['near_radius']} and shift moves" in summary


def test_stereo_presets_slic_and_evaluation(teddy):
    energy = c2f.stereo_energy(teddy["left"], teddy["right"], labels=20)
    assert energy.shape == (125, 150)
    for schedule in ["paper-slic", "aggregated"]:
        result = c2f.solve(energy, schedule, max_steps=400)
        assert result.energy == pytest.approx(energy.evaluate(result.labeling), rel=1e-12)
    rates = c2f.bad_pixel_rates(result.labeling, teddy["gt"], teddy["mask"])
    assert 0 < rates["nonoccluded"][1.0] < 0.5
    assert rates["known_pixels"] == int(np.count_nonzero(~np.isnan(teddy["gt"])))
    assert rates["nonoccluded_pixels"] == int(np.count_nonzero(teddy["mask"] & ~np.isnan(teddy["gt"])))
    # A disparity map that is the GT itself has no bad pixel.
    exact = c2f.bad_pixel_rates(np.nan_to_num(teddy["gt"]), teddy["gt"])
    assert exact["all"][0.5] == 0.0


def test_stereo_inputs_are_checked(rng):
    image = rng.integers(0, 255, (20, 30, 3), dtype=np.uint8)
    with pytest.raises(TypeError, match="left: expected a uint8 array"):
        c2f.stereo_energy(image.astype(np.float32), image)
    with pytest.raises(ValueError, match=r"right: expected shape \(H, W, 3\)"):
        c2f.stereo_energy(image, image[..., 0])
    with pytest.raises(ValueError, match="left and right: the views differ in size"):
        c2f.stereo_energy(image, image[:10])
    with pytest.raises(ValueError, match="smoothness: "):
        c2f.stereo_energy(image, image, smoothness="wavy")
    # The preparation must fit the budget; c2f.stereo passes its `memory` on to it.
    with pytest.raises(ValueError, match="memory: the TSGO energy of 30x20 pixels and 85 labels "
                                         "needs .* more than the run's memory budget"):
        c2f.stereo(image, image, memory=1e-6)
    with pytest.raises(ValueError, match="memory: expected a finite number"):
        c2f.stereo_energy(image, image, memory=-2.0)
    general = c2f.Energy(rng.random((600, 3)))
    with pytest.raises(ValueError, match="schedule: "):
        c2f.solve(general, "paper-slic")
    with pytest.raises(ValueError):
        c2f.read_image("/nonexistent.png")


def test_the_stereo_energy_is_the_same_on_any_number_of_threads(rng):
    left = rng.integers(0, 255, (30, 48, 3), dtype=np.uint8)
    right = np.roll(left, -3, axis=1)
    one = c2f.stereo_energy(left, right, labels=20, threads=1)
    labelings = [rng.integers(0, 20, (30, 48)) for _ in range(3)]
    for threads in (2, 3, 0):
        many = c2f.stereo_energy(left, right, labels=20, threads=threads)
        assert [many.evaluate(y) for y in labelings] == [one.evaluate(y) for y in labelings]
    with pytest.raises(ValueError, match=r"threads: expected an integer in \[0, 1024\], got -1"):
        c2f.stereo_energy(left, right, labels=20, threads=-1)
