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
