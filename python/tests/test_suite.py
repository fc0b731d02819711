"""bench/suite.py: the aside rule, the measures it reports, and one instance end to end."""

import csv
import math
import zlib

import numpy as np
import pytest

def test_the_aside_set_is_fixed_by_names_only(suite):
    assert suite.is_aside("stereo", "middlebury2014/Recycle")
    assert suite.is_aside("stereo", "kitti2015/000001_10")
    assert not suite.is_aside("stereo", "Teddy")
    # zlib.crc32 is the same on every machine and Python: the set cannot drift.
    names = [f"grid/0.1mp-{labels}L-potts-low" for labels in (8, 32, 128)]
    assert [suite.is_aside("grid", n) for n in names] == [
        zlib.crc32(n.encode()) % 4 == 0 for n in names]


def test_times_to_a_band_and_deadline_errors_read_the_trace(suite):
    trace = suite.Trace(np.array([0.5, 1.0, 2.0]), np.array([110.0, 100.05, 100.0]),
                        np.array([0.3, 0.2, 0.1]))
    assert suite.time_to(trace, suite.band(100.0, 1e-3)) == 1.0
    assert suite.time_to(trace, suite.band(100.0, 1e-4)) == 2.0
    assert math.isinf(suite.time_to(trace, 99.0))
    # The latest step before each deadline; before the first step, the first step's error.
    assert suite.deadline_error(trace, np.array([0.1, 1.5, 5.0])) == pytest.approx(0.2)
    assert math.isnan(suite.deadline_error(suite.Trace(trace.times, trace.energies),
                                           np.array([1.0])))


def test_a_grid_instance_gets_its_row_and_its_medians(suite, tmp_path):
    name = "grid/0.1mp-8L-potts-low"
    assert suite.main(["--out", str(tmp_path), "--families", "grid", "--only", name]) == 0
    with open(tmp_path / "suite.tsv", newline="") as file:
        rows = list(csv.DictReader(file, delimiter="\t"))
    assert [r["instance"] for r in rows] == [name]
    row = rows[0]
    assert row["flat_reason"] == "converged" and row["c2f_reason"] == "converged"
    flat, c2f = float(row["flat_energy"]), float(row["c2f_energy"])
    assert float(row["energy_gap"]) == pytest.approx((c2f - flat) / abs(flat))
    # Within 1e-3 no later than within 1e-4; the ratios are over flat's convergence time.
    to3, to4 = float(row["to_1e3_seconds"]), float(row["to_1e4_seconds"])
    assert to3 <= to4
    assert float(row["ratio_1e4"]) == pytest.approx(to4 / float(row["flat_seconds"]))
    assert 0.0 <= float(row["error_flat"]) <= 1.0 and 0.0 <= float(row["error_c2f"]) <= 1.0
    table = (tmp_path / "suite.md").read_text()
    assert "| grid | 0.1mp | " in table


def test_an_unknown_family_is_refused_by_name(suite, capsys):
    with pytest.raises(SystemExit):
        suite.main(["--families", "grid,stero"])
    assert "unknown family 'stero'" in capsys.readouterr().err
