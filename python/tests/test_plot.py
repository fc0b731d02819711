"""c2f.plot draws what the traces hold."""

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

import c2f
import c2f.plot


def test_energy_and_error_plots_hold_the_traces(rng, tmp_path):
    energy = c2f.Energy.grid(rng.random((16, 16, 4)), c2f.Term.potts(), weight=0.4)
    flat, fine = c2f.solve(energy, "flat"), c2f.solve(energy, "paper")
    figure = c2f.plot.energy_against_time({"flat": flat, "c2f": fine})
    lines = figure.axes[0].get_lines()
    assert [line.get_label() for line in lines] == ["flat", "c2f"]
    np.testing.assert_allclose(lines[0].get_ydata(), flat.trace["energy"] / flat.trace["energy"][0])
    best = min(flat.energy, fine.energy)
    figure = c2f.plot.energy_against_time({"flat": flat, "c2f": fine}, gap_to=best)
    assert figure.axes[0].get_yscale() == "log"
    assert min(line.get_ydata().min() for line in figure.axes[0].get_lines()) > 0
    figure.savefig(tmp_path / "energy.png")
    assert (tmp_path / "energy.png").stat().st_size > 1000

    csv = tmp_path / "trace.csv"
    csv.write_text("time_s,level,step,energy,num_vars,error\n0.1,0,0,10,4,0.5\n0.2,0,1,9,4,0.25\n")
    trace = c2f.plot.read_trace(csv)
    np.testing.assert_array_equal(trace["error"], [0.5, 0.25])
    figure = c2f.plot.error_against_time({"run": str(csv)})
    np.testing.assert_array_equal(figure.axes[0].get_lines()[0].get_ydata(), [0.5, 0.25])
    with pytest.raises(ValueError, match="trace 'flat' has no error column"):
        c2f.plot.error_against_time({"flat": flat})
    (tmp_path / "empty.csv").write_text("time_s,level,step,energy,num_vars\n")
    with pytest.raises(ValueError, match="has no rows"):
        c2f.plot.read_trace(tmp_path / "empty.csv")


def test_the_command_line_writes_a_png_or_says_why(tmp_path):
    import subprocess
    import sys

    csv = tmp_path / "trace.csv"
    csv.write_text("time_s,level,step,energy,num_vars,error\n0.1,0,0,10,4,0.5\n0.2,0,1,9,4,0.25\n")
    out = tmp_path / "error.png"
    run = subprocess.run([sys.executable, "-m", "c2f.plot", "-o", str(out), "--column", "error",
                          f"run={csv}"], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    before = out.read_bytes()
    run = subprocess.run([sys.executable, "-m", "c2f.plot", "-o", str(out),
                          f"run={tmp_path / 'missing.csv'}"], capture_output=True, text=True)
    assert run.returncode == 1 and "missing.csv" in run.stderr
    assert out.read_bytes() == before  # the earlier plot stays
    run = subprocess.run([sys.executable, "-m", "c2f.plot", "-o", str(tmp_path / "x.jpg"),
                          f"run={csv}"], capture_output=True, text=True)
    assert run.returncode == 2 and "expected a .png path" in run.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["error.png", "trace.csv"]
