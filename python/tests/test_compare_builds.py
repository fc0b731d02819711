"""bench/segment/compare-builds: its aside marks and the per-image table it writes."""

import importlib.machinery
import importlib.util
import math
import pathlib

import pytest

SCRIPT = pathlib.Path(__file__).parents[2] / "bench/segment/compare-builds"


@pytest.fixture(scope="module")
def compare_builds():
    loader = importlib.machinery.SourceFileLoader("compare_builds", str(SCRIPT))
    spec = importlib.util.spec_from_loader("compare_builds", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def test_the_aside_marks_are_the_suites(compare_builds, suite):
    for image in compare_builds.IMAGES.split(","):
        assert compare_builds.is_aside(image) == suite.is_aside("segmentation", image)
    assert compare_builds.is_aside("binary/019_redtree1")
    assert not compare_builds.is_aside("binary/001_oct")


def test_the_table_has_every_run_and_medians(compare_builds):
    def row(build, ratio, c2f_seconds, first, c2f_energy=100.0):
        return {"image": "binary/005_bee", "build": build, "baseline_seconds": 2.0,
                "baseline_energy": 100.0, "c2f_seconds": c2f_seconds, "c2f_energy": c2f_energy,
                "ratio_1e4": ratio, "first_step_seconds": first}

    rows = [row("before", 0.5, 1.0, 0.2), row("after", math.inf, 0.8, 0.1, 100.02),
            row("before", 0.7, 1.4, 0.4), row("after", 0.25, 1.2, 0.04, 100.0)]
    lines = compare_builds.table(rows, ["binary/005_bee"]).splitlines()
    assert len(lines) == 3
    cells = [c.strip() for c in lines[2].strip("|").split("|")]
    # image (aside), flat, before's runs and convergence, after's, first steps, energy gap
    assert cells == ["binary/005_bee *", "2.00", "0.50, 0.70", "0.60", "never, 0.25", "0.50",
                     "0.30 / 0.07", "+1.0e-04"]
