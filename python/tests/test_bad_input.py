"""The bad-input probe's Python cases: ragged and object arrays, out-of-range integers and wrong
callback answers are exceptions naming the argument; a solve at interpreter exit or under Ctrl-C
in a joining thread ends normally; files that are not regular are refused at once; numbers are
written the same under a comma-decimal locale. Cases that once crashed the interpreter run in a
subprocess, which must exit normally."""

import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import c2f
import c2f.plot


def run_python(code, timeout=120):
    """`code` in a fresh interpreter with this one's module path; its CompletedProcess."""
    return subprocess.run([sys.executable, "-c", textwrap.dedent(code)], capture_output=True,
                          text=True, timeout=timeout, env=dict(os.environ))


RAGGED_CASES = """
import numpy as np, c2f
energy = c2f.Energy.grid(np.ones((2, 3, 2)))
general = c2f.Energy(np.ones((3, 2)), np.array([[0, 1], [1, 2]]))
cases = {
    "Energy": lambda: c2f.Energy([[1.0, 2.0], [3.0]]),
    "Energy.grid": lambda: c2f.Energy.grid([[[1.0, 2.0]], [[3.0]]]),
    "edges": lambda: c2f.Energy(np.ones((3, 2)), [[0, 1], [2]]),
    "weights": lambda: c2f.Energy(np.ones((3, 2)), np.array([[0, 1], [1, 2]]), [[1.0], []]),
    "start": lambda: c2f.solve(energy, start=[[0, 1, 0], [1]]),
    "evaluate": lambda: general.evaluate([[0], [1, 1]]),
    "Term.table": lambda: c2f.Term.table([[0.0, 1.0], [1.0]]),
    "partition": lambda: c2f.reduce(general, [[0, 1], [1]]),
    "object": lambda: c2f.Energy(np.array([[1.0, None]], dtype=object)),
}
for name, call in cases.items():
    try:
        call()
        print(name, "no error")
    except Exception as error:
        print(name, type(error).__name__, str(error).splitlines()[0])
"""


def test_ragged_and_object_arrays_are_type_errors_naming_the_argument():
    done = run_python(RAGGED_CASES)
    assert done.returncode == 0, done.stderr
    lines = dict(line.split(" ", 1) for line in done.stdout.splitlines())
    expected = {"Energy": "unary", "Energy.grid": "unary", "edges": "edges",
                "weights": "weights", "start": "start", "evaluate": "labeling",
                "Term.table": "costs", "partition": "partition", "object": "unary"}
    assert set(lines) == set(expected)
    for case, argument in expected.items():
        assert lines[case].startswith(f"TypeError {argument}: expected "), (case, lines[case])


SLOW_SOLVE = """
import numpy as np, c2f, threading, _thread, signal, time, sys
rng = np.random.default_rng(7)
energy = c2f.Energy.grid(rng.random((300, 300, 40)), c2f.Term.truncated_linear(8.0), weight=0.2)
started = threading.Event()
def solve():
    c2f.solve(energy, method="swap", max_steps=10**9, callback=lambda step: started.set())
"""


def test_a_solve_in_a_daemon_thread_at_exit_ends_normally():
    done = run_python(SLOW_SOLVE + """
thread = threading.Thread(target=solve, daemon=True)
thread.start()
started.wait()
print("leaving", flush=True)
""")
    assert done.returncode == 0, done.stderr
    assert "terminate" not in done.stderr and done.stdout == "leaving\n"


def test_ctrl_c_while_joining_a_solving_thread_ends_normally():
    done = run_python(SLOW_SOLVE + """
signal.signal(signal.SIGINT, signal.default_int_handler)
thread = threading.Thread(target=solve, daemon=True)
thread.start()
started.wait()
threading.Timer(0.3, _thread.interrupt_main).start()
try:
    thread.join()
except KeyboardInterrupt:
    print("interrupted", flush=True)
""")
    assert done.returncode == 0, done.stderr
    assert "terminate" not in done.stderr and done.stdout == "interrupted\n"


def test_a_new_solve_at_exit_is_refused_not_aborted():
    # A daemon thread that keeps starting solves while the interpreter exits: each new one is
    # refused (RuntimeError) once the exit has begun, and the process still exits normally.
    done = run_python(SLOW_SOLVE + """
small = c2f.Energy.grid(rng.random((20, 20, 4)))
def loop():
    while True:
        c2f.solve(small, max_steps=3)
        started.set()
thread = threading.Thread(target=loop, daemon=True)
thread.start()
started.wait()
""")
    assert done.returncode == 0, done.stderr
    assert "terminate" not in done.stderr


def test_integer_and_real_arguments_name_themselves(rng):
    energy = c2f.Energy.grid(rng.random((3, 4, 2)))
    for kwargs, error, words in [
        (dict(options={"seed": -1}), ValueError,
         r"options\['seed'\]: expected an integer in \[0, 9223372036854775807\], got -1"),
        (dict(options={"near_radius": 2**70}), ValueError,
         r"options\['near_radius'\]: expected an integer in"),
        (dict(max_steps=1.5), TypeError, "max_steps: expected an integer in .*, got float"),
        (dict(plateau=True), TypeError, "plateau: expected an integer in .*, got bool"),
        (dict(time_limit="10"), TypeError, "time_limit: expected a real number, got str"),
        (dict(plateau_tolerance=float("inf")), ValueError, "plateau_tolerance: expected a finite"),
    ]:
        with pytest.raises(error, match=words) as caught:
            c2f.solve(energy, **kwargs)
        assert "incompatible function arguments" not in str(caught.value)
    with pytest.raises(ValueError, match=r"connectivity: expected an integer in \[4, 8\], got 1208925819614629174706176"):
        c2f.Energy.grid(rng.random((3, 4, 2)), connectivity=2**80)
    with pytest.raises(ValueError, match=r"b: expected an integer in \[0, 2147483647\], got -1"):
        c2f.Term.potts().cost(0, -1)
    with pytest.raises(ValueError, match=r"labels: expected an integer in \[2, 256\], got 100000"):
        c2f.stereo_energy(np.zeros((4, 4, 3), np.uint8), np.zeros((4, 4, 3), np.uint8),
                          labels=100000)
    assert c2f.solve(energy, options={"seed": np.int64(3)}, max_steps=np.uint8(2)).steps == 2


@pytest.mark.parametrize("answer", ["stop", 0, np.array([True, False])])
def test_a_callback_answering_other_than_true_false_or_none_is_a_type_error(rng, answer):
    energy = c2f.Energy.grid(rng.random((3, 4, 2)))
    with pytest.raises(TypeError, match="callback: expected True, False or None as its answer, "
                                        "got ") as caught:
        c2f.solve(energy, callback=lambda step: answer)
    assert isinstance(caught.value.result, c2f.Result)
    assert caught.value.result.reason == "observer"
    assert c2f.solve(energy, callback=lambda step: np.bool_(False)).reason == "observer"


def test_files_that_are_not_regular_are_refused_at_once(tmp_path):
    fifo = tmp_path / "model.uai"
    os.mkfifo(fifo)
    with pytest.raises(ValueError, match="UAI file '.*model.uai' is not a regular file"):
        c2f.Energy.read_uai(str(fifo))
    with pytest.raises(ValueError, match="trace '.*model.uai' is not a regular file"):
        c2f.plot.read_trace(fifo)
    zero = tmp_path / "zero.csv"
    zero.symlink_to("/dev/zero")
    with pytest.raises(ValueError, match="trace '.*zero.csv' is not a regular file"):
        c2f.plot.read_trace(zero)
    with pytest.raises(ValueError, match="is a folder, not a file"):
        c2f.Energy.read_uai(str(tmp_path))


def test_a_uai_model_larger_than_the_budget_is_refused_before_it_is_read(tmp_path):
    model = tmp_path / "huge.uai"
    model.write_text("MARKOV\n512\n" + "1048576 " * 512 + "\n0\n")
    with pytest.raises(ValueError, match=r"huge.uai \(512 variables x 1048576 labels, 0 factors\)"
                                         r" needs 4.0 GiB"):
        c2f.Energy.read_uai(str(model), memory=0.5)


def test_a_trace_with_a_byte_order_mark_reads(tmp_path):
    trace = tmp_path / "trace.csv"
    trace.write_bytes(b"\xef\xbb\xbftime_s,level,step,energy,num_vars\n0.5,0,0,10.0,4\n")
    assert c2f.plot.read_trace(trace)["energy"].tolist() == [10.0]


def test_the_plot_tool_refuses_to_overwrite_its_input_and_a_gap_above_the_energies(tmp_path):
    trace = tmp_path / "t.png"
    trace.write_text("time_s,level,step,energy,num_vars\n0.5,0,0,10.0,4\n1.0,0,1,9.0,4\n")
    before = trace.read_bytes()
    done = subprocess.run([sys.executable, "-m", "c2f.plot", "-o", str(trace), f"run={trace}"],
                          capture_output=True, text=True, env=dict(os.environ))
    assert done.returncode == 2 and "would replace its own input" in done.stderr
    assert trace.read_bytes() == before
    out = tmp_path / "plot.png"
    done = subprocess.run([sys.executable, "-m", "c2f.plot", "-o", str(out), "--gap-to", "9.5",
                           f"run={trace}"], capture_output=True, text=True, env=dict(os.environ))
    assert done.returncode == 1 and "gap_to: 9.5 lies above the lowest energy" in done.stderr
    assert not out.exists()


def test_numbers_are_written_with_points_under_a_comma_locale(tmp_path):
    done = run_python(f"""
import locale, numpy as np, c2f
try:
    locale.setlocale(locale.LC_ALL, "de_DE.UTF-8")
except locale.Error:
    raise SystemExit("the de_DE.UTF-8 locale is missing: run scripts/install-deps")
assert locale.localeconv()["decimal_point"] == ","
rng = np.random.default_rng(3)
energy = c2f.Energy.grid(rng.random((4, 5, 3)) + 0.25, c2f.Term.truncated_linear(1.5), weight=0.5)
energy.write_uai({str(tmp_path / 'model.uai')!r})
back = c2f.Energy.read_uai({str(tmp_path / 'model.uai')!r})
result = c2f.solve(energy, max_steps=3)
print(result.summary)
flat = result.labeling.reshape(-1)
print(abs(back.evaluate(flat) - back.evaluate(np.zeros(20, int))
          - (energy.evaluate(result.labeling) - energy.evaluate(np.zeros(20, int)))) < 1e-9)
""")
    assert done.returncode == 0, done.stderr
    assert "," not in (tmp_path / "model.uai").read_text()
    assert "final energy " in done.stdout and "," not in done.stdout.split("final energy ")[1]
    assert done.stdout.strip().endswith("True")


def test_bad_pixel_rates_refuse_what_cannot_be_scored():
    gt = np.full((4, 5), np.nan, dtype=np.float32)
    with pytest.raises(ValueError, match="gt: no pixel has a known disparity"):
        c2f.bad_pixel_rates(np.zeros((4, 5)), gt)
    gt[1, 1] = 3.0
    with pytest.raises(ValueError, match="mask: no pixel with known GT is marked"):
        c2f.bad_pixel_rates(np.zeros((4, 5)), gt, np.zeros((4, 5), bool))
    rates = c2f.bad_pixel_rates(np.zeros((4, 5)), gt)
    assert rates["nonoccluded"] is None and rates["all"][2.0] == 1.0


def test_a_binary_file_read_as_uai_is_a_value_error_with_a_message(tmp_path):
    model = tmp_path / "binary.uai"
    model.write_bytes(bytes(range(256)) * 4)
    with pytest.raises(ValueError) as caught:
        c2f.Energy.read_uai(str(model))
    message = str(caught.value)
    assert "binary.uai: token 1: network type" in message
    assert "\x1b" not in message and "\x00" not in message  # control bytes escaped


def test_control_bytes_in_names_reach_messages_escaped(rng):
    energy = c2f.Energy.grid(rng.random((3, 4, 2)))
    for kwargs, words in [
        (dict(schedule="cp:1,1\x00zz"), r"schedule: level 'cp:1,1\\x00zz'"),
        (dict(method="exp\x00x"), r"method: unknown solver 'exp\\x00x'"),
        (dict(options={"maxflow": "\x1b[2J"}),
         r"options\['maxflow'\]: unknown max-flow backend '\\x1B\[2J'"),
    ]:
        with pytest.raises(ValueError, match=words) as caught:
            c2f.solve(energy, **kwargs)
        assert "\x00" not in str(caught.value) and "\x1b" not in str(caught.value)
        assert not str(caught.value).startswith("schedule: schedule:")
