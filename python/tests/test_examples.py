"""examples/python's scripts run on small inputs and write every picture they promise."""

import pathlib
import subprocess
import sys

import pytest

EXAMPLES = pathlib.Path(__file__).parents[2] / "examples/python"
OPENCV_DATA = pathlib.Path("/usr/share/doc/opencv-doc/examples/data")
PNG = b"\x89PNG\r\n\x1a\n"


def run(script, *arguments):
    done = subprocess.run([sys.executable, str(EXAMPLES / script), *arguments],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return done.stdout


def written(folder):
    return sorted(p.name for p in folder.iterdir() if p.read_bytes()[:8] == PNG)


@pytest.mark.skipif(not (OPENCV_DATA / "aloeL.jpg").is_file(), reason="no opencv-doc (Aloe)")
def test_stereo_example(tmp_path):
    output = run("stereo.py", "--downscale", "8", "--labels", "32", "--time-limit", "2",
                 "--out", str(tmp_path))
    assert "flat: energy" in output and "c2f: energy" in output and "bad pixels (> 1)" in output
    assert written(tmp_path) == ["c2f-bad-pixels.png", "c2f-disparity.png", "energy.png",
                                 "error.png", "flat-bad-pixels.png", "flat-disparity.png"]


@pytest.mark.skipif(not (OPENCV_DATA / "fruits.jpg").is_file(), reason="no opencv-doc (fruits)")
def test_segment_example(tmp_path):
    output = run("segment.py", "--downscale", "4", "--time-limit", "2", "--out", str(tmp_path))
    assert all(f"{name}: energy" in output for name in ("coop-flat", "coop-c2f", "potts"))
    assert written(tmp_path) == sorted(
        [f"{name}-{kind}.png" for name in ("coop-flat", "coop-c2f", "potts")
         for kind in ("labels", "overlay")] + ["energy.png"])


def test_examples_name_a_missing_input(tmp_path):
    done = subprocess.run([sys.executable, str(EXAMPLES / "segment.py"), "--image",
                           str(tmp_path / "none.jpg"), "--out", str(tmp_path / "out")],
                          capture_output=True, text=True)
    assert done.returncode == 1 and "none.jpg" in done.stderr
    assert not (tmp_path / "out").exists()
