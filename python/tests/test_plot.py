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


@pytest.mark.parametrize("name, rows, expected", [
    ("nan.csv", "0.1,0,0,nan,4\n", "line 2: energy 'nan' is not a finite number"),
    ("inf.csv", "0.1,0,0,10,4\ninf,0,1,8,4\n", "line 3: time_s 'inf' is not a finite number"),
    ("huge.csv", "0.1,0,0,1e308,4\n", "energy '1e308' is not a finite number within +-1e300"),
    ("garbage.csv", "0.1,0,0,10x,4\n", "energy '10x' is not a number"),
    ("short.csv", "0.1,0,0\n", "line 2: no energy value"),
    ("negative.csv", "-1,0,0,10,4\n", "time_s '-1' is not a time"),
])
def test_unplottable_traces_are_refused_by_file_line_and_value(tmp_path, name, rows, expected):
    path = tmp_path / name
    path.write_text("time_s,level,step,energy,num_vars\n" + rows)
    with pytest.raises(ValueError) as error:
        c2f.plot.read_trace(path)
    assert name in str(error.value) and expected in str(error.value)


def test_a_failed_or_cut_plot_leaves_the_earlier_one(tmp_path):
    """The PNG is staged and renamed: a bad trace or a write cut by a file-size limit (512 bytes)
    is exit 1 naming the file, and the earlier plot stays byte for byte; a bad --gap-to is a
    usage error (2)."""
    import subprocess
    import sys

    good = tmp_path / "good.csv"
    good.write_text("time_s,level,step,energy,num_vars\n0.1,0,0,10,4\n0.2,0,1,8,4\n")
    out = tmp_path / "plot.png"

    def plot(*arguments, limit=None):
        command = [sys.executable, "-m", "c2f.plot", "-o", str(out), *arguments]
        if limit is not None:
            command = ["sh", "-c", f'ulimit -f {limit}; exec "$@"', "sh", *command]
        return subprocess.run(command, capture_output=True, text=True)

    assert plot("--gap-to", "7", f"a={good}").returncode == 0
    earlier = out.read_bytes()
    bad = tmp_path / "bad.csv"
    bad.write_text("time_s,level,step,energy,num_vars\n0.1,0,0,nan,4\n")
    run = plot(f"a={bad}")
    assert run.returncode == 1 and "bad.csv" in run.stderr
    run = plot(f"a={good}", limit=1)
    assert run.returncode == 1 and "c2f.plot: error:" in run.stderr, run.stderr
    assert out.read_bytes() == earlier
    for value in ["nan", "1e400", "low"]:
        run = plot("--gap-to", value, f"a={good}")
        assert run.returncode == 2
        assert f"--gap-to: expected a finite number, got '{value}'" in run.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.csv", "good.csv", "plot.png"]


@pytest.mark.parametrize("arguments, expected", [
    (["-o", "plot.png"], "the following arguments are required: NAME=TRACE.csv"),
    (["-o", "plot.png", "=trace.csv"], "expected NAME=TRACE.csv, got '=trace.csv'"),
    (["-o", "plot.png", "--column"], "argument --column: expected one argument"),
    (["-o", "plot.png", "--column", "speed", "a=t.csv"], "argument --column: invalid choice"),
])
def test_malformed_command_lines_are_usage_errors(tmp_path, arguments, expected):
    import subprocess
    import sys

    run = subprocess.run([sys.executable, "-m", "c2f.plot", *arguments], cwd=tmp_path,
                         capture_output=True, text=True)
    assert run.returncode == 2 and expected in run.stderr, run.stderr
    assert list(tmp_path.iterdir()) == []
