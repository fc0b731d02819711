"""Segmentation from Python is c2f-segment's: the same scene, data, energy, run and labels."""

import os
import pathlib
import re
import subprocess

import numpy as np
import pytest

import c2f

FRUITS = pathlib.Path("/usr/share/doc/opencv-doc/examples/data/fruits.jpg")
SEEDS = pathlib.Path(__file__).parents[2] / "examples/segment/data/fruits-seeds.png"


@pytest.fixture
def fruits():
    if not FRUITS.is_file():
        pytest.skip(f"{FRUITS} is missing (Debian package opencv-doc)")
    return c2f.read_segmentation(str(FRUITS), str(SEEDS), downscale=4)


def labels_of(picture, palette):
    labels = np.full(picture.shape[:2], -1)
    for label, colour in enumerate(palette):
        labels[np.all(picture == colour, axis=2)] = label
    return labels


def test_fruits_through_python_and_through_c2f_segment(fruits, tmp_path):
    build = os.environ.get("C2F_BUILD_DIR")
    if not build:
        pytest.skip("C2F_BUILD_DIR is not set (ctest sets it): no c2f-segment to compare with")
    result = c2f.segment(fruits["image"], fruits["seeds"])
    out = tmp_path / "out"
    subprocess.run([os.path.join(build, "examples/segment/c2f-segment"), str(FRUITS), str(SEEDS),
                    "--downscale", "4", "-o", str(out), "-q"], check=True)
    cli = labels_of(c2f.read_image(str(out / "labels.png")), fruits["palette"])
    np.testing.assert_array_equal(cli, result.labeling)
    assert f"final energy {result.energy:.6f}" in (out / "summary.txt").read_text()


def test_segment_methods_and_schedules(fruits):
    image, seeds = fruits["image"], fruits["seeds"]
    for kwargs in [dict(method="potts"), dict(schedule="flat", max_steps=5),
                   dict(options={"aux": "greedy", "start": "current"}, plateau="sweep",
                        max_steps=20)]:
        result = c2f.segment(image, seeds, **kwargs)
        assert result.labeling.shape == seeds.shape
        seeded = seeds >= 0
        assert np.array_equal(result.labeling[seeded], seeds[seeded])  # seeds keep their label
        assert np.all(np.diff(result.trace["energy"]) <= 1e-9 * abs(result.trace["energy"][0]))


def test_segment_defaults_are_the_librarys(fruits):
    """c2f.segment with nothing named runs c2f.defaults('segmentation'): the same run as naming
    every value; near moves go with majorise-minimise only, unless named."""
    image, seeds = fruits["image"], fruits["seeds"]
    defaults = c2f.defaults("segmentation")
    assert defaults["method"] == "coop" and defaults["aux"] == "mm"
    assert defaults["near_radius"] > 0
    plain = c2f.segment(image, seeds)
    named = c2f.segment(image, seeds, defaults["schedule"], method=defaults["method"],
                        options={"aux": defaults["aux"], "near_radius": defaults["near_radius"]},
                        lambda_=defaults["lambda_"], theta=defaults["theta"],
                        alpha=defaults["alpha"])
    np.testing.assert_array_equal(plain.labeling, named.labeling)
    np.testing.assert_array_equal(plain.trace["energy"], named.trace["energy"])
    np.testing.assert_array_equal(plain.trace["level"], named.trace["level"])
    near = f"near moves of radius {defaults['near_radius']} from their label"
    assert near in plain.summary
    whole = c2f.segment(image, seeds, options={"near_radius": 0}, max_steps=5)
    assert "solve: every move over every variable" in whole.summary
    greedy = c2f.segment(image, seeds, options={"aux": "greedy"}, max_steps=5)
    assert "solve: every move over every variable" in greedy.summary
    greedy_near = c2f.segment(image, seeds, options={"aux": "greedy", "start": "current",
                                                     "near_radius": 2}, max_steps=5)
    assert "near moves of radius 2 from their label" in greedy_near.summary
    with pytest.raises(ValueError, match=r"options\['near_radius'\]: expected an integer in"):
        c2f.segment(image, seeds, options={"near_radius": -1})
    with pytest.raises(TypeError, match="schedule: expected a str, got int"):
        c2f.segment(image, seeds, 3)
    with pytest.raises(ValueError, match="name: expected 'pairwise', 'stereo' or 'segmentation'"):
        c2f.defaults("segment")


def test_segment_is_the_same_on_any_number_of_threads(fruits):
    image, seeds = fruits["image"], fruits["seeds"]
    one = c2f.segment(image, seeds, max_steps=10, threads=1)
    radius = c2f.defaults("segmentation")["near_radius"]
    assert re.search(rf"^solve: near moves of radius {radius} from their label \(whole moves where "
                     r"they stall\)(, max-flow in \d+ parts on 1 thread| on one thread)$",
                     one.summary, re.MULTILINE)
    for threads in (2, 0):
        many = c2f.segment(image, seeds, max_steps=10, threads=threads)
        np.testing.assert_array_equal(many.labeling, one.labeling)
        np.testing.assert_array_equal(many.trace["energy"], one.trace["energy"])
    with pytest.raises(ValueError, match=r"threads: expected an integer in \[0, 1024\], got -1"):
        c2f.segment(image, seeds, threads=-1)


def test_segment_inputs_are_checked(rng):
    image = rng.integers(0, 255, (20, 30, 3), dtype=np.uint8)
    seeds = np.full((20, 30), -1)
    seeds[2, 2], seeds[15, 25] = 0, 1
    with pytest.raises(ValueError, match=r"seeds: expected shape \(20, 30\)"):
        c2f.segment(image, seeds[:10])
    one = seeds.copy()
    one[15, 25] = 0
    with pytest.raises(ValueError, match="seeds: expected seeds of at least 2 labels"):
        c2f.segment(image, one)
    gap = seeds.copy()
    gap[15, 25] = 2
    with pytest.raises(ValueError, match="seeds: label 1 has no seed pixel"):
        c2f.segment(image, gap)
    with pytest.raises(ValueError, match=r"options\['aux'\]: unknown"):
        c2f.segment(image, seeds, options={"aux": "magic"})
    with pytest.raises(ValueError, match="method: "):
        c2f.segment(image, seeds, method="graphcut")
    with pytest.raises(TypeError, match="seeds: expected an integer array"):
        c2f.segment(image, seeds.astype(float))
    with pytest.raises(ValueError, match="memory: segmenting 30x20 pixels into 2 labels needs .* "
                                         "more than the run's memory budget"):
        c2f.segment(image, seeds, memory=1e-6)
    # A budget that holds the data but not the run's floor is refused too, for both methods.
    with pytest.raises(ValueError, match="memory: the Potts energy needs "):
        c2f.segment(image, seeds, method="potts", memory=0.01)
    with pytest.raises(ValueError, match="options: method 'potts' .* has none"):
        c2f.segment(image, seeds, method="potts", options={"aux": "mm"})
    with pytest.raises(ValueError, match="plateau: expected None, 'sweep' or a number"):
        c2f.segment(image, seeds, plateau="auto-ish")
    with pytest.raises(ValueError, match="memory: the cooperative energy needs "):
        c2f.segment(image, seeds, memory=0.01)
    result = c2f.segment(image, seeds, schedule="flat")
    assert result.labeling[2, 2] == 0 and result.labeling[15, 25] == 1
