"""Energy and error against time, from c2f.Result traces or the tools' trace.csv files.

    import c2f, c2f.plot
    flat, fine = c2f.solve(energy, "flat"), c2f.solve(energy)   # flat, and the defaults
    figure = c2f.plot.energy_against_time({"flat": flat, "c2f": fine}, gap_to=min(flat.energy, fine.energy))
    figure.savefig("energy.png")

matplotlib is needed (Debian: python3-matplotlib); it is imported when a function is called.
"""

from __future__ import annotations

import csv
import io
import math
import os
import stat
import sys
from typing import Any, Dict, Mapping, Optional, Union

import numpy as np

Trace = Dict[str, np.ndarray]
TraceSource = Union[Any, Mapping[str, np.ndarray], str, os.PathLike]


def read_trace(path: Union[str, os.PathLike]) -> Trace:
    """A tool's trace.csv (time_s,level,step,energy,num_vars[,error]) as arrays named like
    Result.trace: time, level, step, energy, variables (and error). Raises ValueError naming the
    file, line, column and text when the file has no rows, lacks a column, or holds a value that
    is not a finite number within +-1e300 (a time must also be at least 0), and when the path is
    not a regular file of at most 64 MiB (a FIFO is refused, never waited on). A UTF-8 byte-order
    mark is allowed."""
    name = os.fspath(path)
    text = _read_text_file(name, "trace")
    rows = list(csv.DictReader(io.StringIO(text, newline="")))
    if not rows:
        raise ValueError(f"trace '{name}' has no rows")
    names = {"time": "time_s", "level": "level", "step": "step", "energy": "energy",
             "variables": "num_vars", "error": "error"}
    trace = {}
    for key, column in names.items():
        if column not in rows[0]:
            if key == "error":
                continue
            raise ValueError(f"trace '{name}' has no column '{column}'")
        values = np.empty(len(rows))
        for index, row in enumerate(rows):
            values[index] = _plottable(row[column], name, index + 2, column)
        trace[key] = values
    return trace


_MAX_TEXT_BYTES = 64 << 20


def _read_text_file(name: str, what: str) -> str:
    """The text of the regular file `name`, as the library's input layer reads files: opened
    without blocking, refused by name unless it is a regular file of at most 64 MiB, decoded as
    UTF-8 (a byte-order mark dropped)."""
    try:
        fd = os.open(name, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    except FileNotFoundError:
        raise ValueError(f"{what} '{name}' does not exist") from None
    except IsADirectoryError:
        raise ValueError(f"{what} '{name}' is a folder, not a file") from None
    except OSError as error:
        raise ValueError(f"{what} '{name}' cannot be opened ({error.strerror})") from None
    with os.fdopen(fd, "rb") as file:
        status = os.fstat(file.fileno())
        if stat.S_ISDIR(status.st_mode):
            raise ValueError(f"{what} '{name}' is a folder, not a file")
        if not stat.S_ISREG(status.st_mode):
            kind = "a FIFO" if stat.S_ISFIFO(status.st_mode) else "a device or socket"
            raise ValueError(f"{what} '{name}' is not a regular file ({kind})")
        if status.st_size > _MAX_TEXT_BYTES:
            raise ValueError(f"{what} '{name}' is {status.st_size} bytes; a {what} of at most "
                             f"{_MAX_TEXT_BYTES} bytes is expected")
        data = file.read(_MAX_TEXT_BYTES + 1)
    if len(data) > _MAX_TEXT_BYTES:
        raise ValueError(f"{what} '{name}' grew past {_MAX_TEXT_BYTES} bytes while it was read")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise ValueError(f"{what} '{name}' is not UTF-8 text (byte {error.start})") from None


def _plottable(text: Optional[str], name: str, line: int, column: str) -> float:
    """The value of one cell, or a ValueError saying which cell and why it cannot be drawn."""
    if text is None or not text.strip():
        raise ValueError(f"trace '{name}', line {line}: no {column} value")
    where = f"trace '{name}', line {line}: {column} '{text}'"
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"{where} is not a number") from None
    if not math.isfinite(value) or abs(value) > 1e300:
        raise ValueError(f"{where} is not a finite number within +-1e300")
    if column == "time_s" and value < 0:
        raise ValueError(f"{where} is not a time (negative)")
    return value


def _trace(source: TraceSource) -> Trace:
    if isinstance(source, (str, os.PathLike)):
        return read_trace(source)
    if hasattr(source, "trace"):
        return source.trace
    return dict(source)


def energy_against_time(traces: Mapping[str, TraceSource], *, gap_to: Optional[float] = None,
                        title: str = "energy against time", ax=None):
    """One line per named trace. Without `gap_to`: the energy normalised as the paper does,
    E / E_first of the first trace (so every run starts near 1). With `gap_to` (a reference
    energy, e.g. the best one any run reached): log10 of the gap E - gap_to, which shows the
    late differences a linear axis hides (a gap of 0 is drawn at the lowest gap seen); a
    `gap_to` above some trace's lowest energy is a ValueError. Returns the figure."""
    import matplotlib.pyplot as plt

    figure, ax = (ax.figure, ax) if ax is not None else plt.subplots(figsize=(7, 4.5))
    loaded = {name: _trace(source) for name, source in traces.items()}
    first = next(iter(loaded.values()))["energy"][0]
    gaps = []
    if gap_to is not None:
        if not math.isfinite(gap_to):
            raise ValueError(f"gap_to: expected a finite energy, got {gap_to}")
        for name, trace in loaded.items():
            lowest = float(np.min(trace["energy"]))
            if gap_to > lowest:
                raise ValueError(f"gap_to: {gap_to:.17g} lies above the lowest energy of trace "
                                 f"'{name}' ({lowest:.17g}); expected a reference at most every "
                                 "energy plotted (the best one any run reached)")
        gaps = [t["energy"] - gap_to for t in loaded.values()]
        positive = np.concatenate([g[g > 0] for g in gaps] or [np.array([1.0])])
        floor = positive.min() if positive.size else 1.0
    for index, (name, trace) in enumerate(loaded.items()):
        time = np.maximum(trace["time"], 1e-6)
        if gap_to is None:
            ax.step(time, trace["energy"] / first, where="post", label=name)
        else:
            ax.step(time, np.maximum(gaps[index], floor), where="post", label=name)
    ax.set_xscale("log")
    ax.set_xlabel("time (s, log)")
    if gap_to is None:
        ax.set_ylabel("energy / first energy")
    else:
        ax.set_yscale("log")
        ax.set_ylabel(f"energy - {gap_to:.6g} (log)")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    return figure


def error_against_time(traces: Mapping[str, TraceSource], *, title: str = "error against time",
                       ax=None):
    """One line per named trace of its 'error' column (the tools' trace.csv with --gt, or a
    trace dict with an 'error' array) against time. Returns the figure. Raises ValueError
    naming a trace without errors."""
    import matplotlib.pyplot as plt

    figure, ax = (ax.figure, ax) if ax is not None else plt.subplots(figsize=(7, 4.5))
    for name, source in traces.items():
        trace = _trace(source)
        if "error" not in trace:
            raise ValueError(f"trace '{name}' has no error column")
        ax.step(np.maximum(trace["time"], 1e-6), trace["error"], where="post", label=name)
    ax.set_xscale("log")
    ax.set_xlabel("time (s, log)")
    ax.set_ylabel("error")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    return figure


def _finite(text: str) -> float:
    """--gap-to's value: a finite number within +-1e300, or a usage error saying so."""
    import argparse

    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value) or abs(value) > 1e300:
        raise argparse.ArgumentTypeError(f"expected a finite number, got '{text}'")
    return value


def main(argv: Optional[list] = None) -> int:
    """`python3 -m c2f.plot -o OUT.png [--column energy|error] [--gap-to E] [--title T]
    NAME=TRACE.csv ...`: the command line of this module, as scripts/demo uses it. The PNG is
    written beside OUT and renamed over it once complete. Exit 0, 2 for bad arguments, 1 when a
    trace cannot be read."""
    import argparse

    parser = argparse.ArgumentParser(prog="python3 -m c2f.plot",
                                     description="Plots traces of c2f runs against time.")
    parser.add_argument("-o", "--out", required=True, help="the PNG to write")
    parser.add_argument("--column", choices=["energy", "error"], default="energy")
    parser.add_argument("--gap-to", type=_finite, default=None,
                        help="plot log10(energy - this reference) instead of E / E_first")
    parser.add_argument("--title", default=None)
    parser.add_argument("traces", nargs="+", metavar="NAME=TRACE.csv")
    arguments = parser.parse_args(argv)
    if not arguments.out.endswith(".png"):
        parser.error(f"-o: expected a .png path, got '{arguments.out}'")
    traces = {}
    for item in arguments.traces:
        name, sep, path = item.partition("=")
        if not sep or not name or not path:
            parser.error(f"expected NAME=TRACE.csv, got '{item}'")
        traces[name] = path
    out_path = os.path.realpath(arguments.out)
    for name, path in traces.items():
        if os.path.realpath(path) == out_path:
            parser.error(f"-o: '{arguments.out}' is also the trace {name}={path}: the plot would "
                         "replace its own input")
    import matplotlib

    matplotlib.use("Agg")
    try:
        loaded = {name: read_trace(path) for name, path in traces.items()}
        if arguments.column == "error":
            figure = error_against_time(loaded, title=arguments.title or "error against time")
        else:
            figure = energy_against_time(loaded, gap_to=arguments.gap_to,
                                         title=arguments.title or "energy against time")
        partial = f"{arguments.out}.c2f-partial-{os.getpid()}"
        try:
            figure.savefig(partial, format="png", dpi=110, bbox_inches="tight")
            os.replace(partial, arguments.out)
        finally:
            if os.path.exists(partial):
                os.remove(partial)
    except (OSError, ValueError) as error:
        print(f"c2f.plot: error: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
