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


def test_the_targets_table_counts_instances_where_flat_took_a_second(suite, tmp_path):
    columns = suite.COLUMNS + ["size"]

    def row(name, aside, variables, flat_seconds, ratio, c2f_seconds):
        values = dict.fromkeys(columns, "0")
        values.update(family="grid", instance=name, aside=str(aside), variables=str(variables),
                      flat_seconds=str(flat_seconds), ratio_1e4=str(ratio), size="x",
                      c2f_seconds=str(c2f_seconds))
        return values

    first, second = tmp_path / "a.tsv", tmp_path / "b.tsv"
    for path, rows in ((first, [row("g/a", 0, 1000, 5.0, 0.5, 4.0),
                                row("g/b", 0, 1000, 0.5, 3.0, 2.0),
                                row("g/c", 0, 2_000_000, 2.0, 0.2, 1.0),
                                row("g/d", 1, 1000, 4.0, 0.9, 2.0)]),
                       (second, [row("g/a", 0, 1000, 5.0, 0.3, 6.0)])):
        with open(path, "w", newline="") as file:
            writer = csv.DictWriter(file, fieldnames=columns, delimiter="\t")
            writer.writeheader()
            writer.writerows(rows)
    out = tmp_path / "out"
    assert suite.main(["--out", str(out), "--summarize", str(first), str(second)]) == 0
    table = (out / "suite.md").read_text()
    # g/b (flat 0.5 s) is out of scope; the second table's g/a (0.3) replaces the first's.
    # C2F's convergence over flat's: g/a 6 / 5 and g/c 1 / 2.
    assert ("| grid | tuning | 2 (3) | 0.25 ok | 0.30 ok (g/a) | 0.20 ok | 0.85, 1.20 (g/a) |"
            in table)
    assert "| grid | aside | 1 (1) | 0.90 missed | 0.90 ok (g/d) | - - | 0.50, 0.50 (g/d) |" in table
    with pytest.raises(SystemExit):
        suite.main(["--out", str(out), "--summarize", str(tmp_path / "missing.tsv")])


def test_only_and_skip_pick_instances_by_name(suite, capsys):
    assert suite.main(["--families", "general", "--only", "lattice", "--skip", "32L",
                       "--list"]) == 0
    names = [line.split("\t")[1] for line in capsys.readouterr().out.splitlines()]
    assert names and all("lattice" in n and "32L" not in n for n in names)
    assert len(names) == 4  # 8 and 16 labels, two sizes each
