"""The parallel solve against the serial one (docs/performance.md, "The solve").

For every scene, ROUNDS rounds; in each, for flat (`--schedule flat`) and the default schedule,
c2f-stereo's serial solve (`--flow-parts 1 --threads 1`, what the same build does on one core)
and then its solve on THREADS threads (the default parts). Every run's outputs go to
OUT/runs/SCENE-SCHEDULE-MODE-ROUND/, its peak resident size (from wait4) to rss.txt there.
OUT/table.md: per scene and schedule the time to converge and to within 1e-4 of the serial flat
run's final energy (its first round's), the speed-up per round and from each mode's fastest run,
final energies and steps, peak RSS, and the error (the trace's `error` column) averaged at 20
deadlines drawn uniformly up to serial flat's convergence (seed 1).

    /usr/bin/python3 bench/stereo/threads_bench.py TOOL DATA OUT ROUNDS THREADS SCENE...
"""

import csv
import os
import random
import subprocess
import sys
from pathlib import Path

SCHEDULES = {"flat": ["--schedule", "flat"], "default": []}
BAND = 1e-4
DEADLINES = 20


def run(tool, data, scene, flags, out):
    """Runs c2f-stereo into `out`; returns its peak resident size in GiB."""
    out.parent.mkdir(parents=True, exist_ok=True)
    with open(f"{out}.log", "w") as log:
        child = subprocess.Popen([tool, "--scene", scene, "--data", data, "--out", str(out), *flags],
                                 stdout=log, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(child.pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"threads_bench: c2f-stereo {scene} {' '.join(flags)} failed: see {out}.log")
    gib = usage.ru_maxrss / 2**20  # ru_maxrss is in KiB on Linux
    (out / "rss.txt").write_text(f"{gib:.3f}\n")
    return gib


def trace(out):
    """(time_s, energy, error) per step of a run's trace."""
    with open(out / "trace.csv") as f:
        return [(float(r["time_s"]), float(r["energy"]), float(r["error"] or "nan"))
                for r in csv.DictReader(f)]


def time_to(rows, energy):
    """The run clock when the energy first came within BAND of `energy`, or None."""
    return next((t for t, e, _ in rows if e <= energy + BAND * abs(energy)), None)


def error_at_deadlines(rows, deadlines):
    def at(t):
        seen = [err for time, _, err in rows if time <= t]
        return seen[-1] if seen else rows[0][2]
    return sum(at(t) for t in deadlines) / len(deadlines)


def fastest(values):
    return min((v for v in values if v is not None), default=None)


def cell(value, unit=" s"):
    return "never" if value is None else f"{value:.1f}{unit}"


def ratio(a, b):
    return "-" if a is None or b is None else f"{a / b:.2f}x"


def main(argv):
    tool, data, out, rounds, threads, scenes = (argv[1], argv[2], Path(argv[3]), int(argv[4]),
                                                argv[5], argv[6:])
    modes = {"serial": ["--flow-parts", "1", "--threads", "1"], "threads": ["--threads", threads]}
    lines = [f"# Serial against {threads} threads: `bench/stereo/run-threads` ({rounds} rounds)", "",
             "| scene | run | serial: converged, to 1e-4 (per round) | "
             f"{threads} threads: converged, to 1e-4 | speed-up per round | from the fastest runs "
             "| final E serial / threads | steps | peak RSS GiB | deadline error % |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for scene in scenes:
        runs = {}
        for r in range(1, rounds + 1):
            for schedule, schedule_flags in SCHEDULES.items():
                for mode, mode_flags in modes.items():
                    name = f"{scene.replace('/', '-')}-{schedule}-{mode}-{r}"
                    print(f"threads_bench: {scene} {schedule} {mode} round {r}", file=sys.stderr)
                    rss = run(tool, data, scene, schedule_flags + mode_flags, out / "runs" / name)
                    runs[schedule, mode, r] = (trace(out / "runs" / name), rss)
        reference = runs["flat", "serial", 1][0]
        target = reference[-1][1]
        rng = random.Random(1)
        deadlines = [rng.uniform(0, reference[-1][0]) for _ in range(DEADLINES)]
        for schedule in SCHEDULES:
            per = {m: [runs[schedule, m, r] for r in range(1, rounds + 1)] for m in modes}
            conv = {m: [rows[-1][0] for rows, _ in per[m]] for m in modes}
            band = {m: [time_to(rows, target) for rows, _ in per[m]] for m in modes}
            rounds_text = ", ".join(
                f"{ratio(conv['serial'][i], conv['threads'][i])}/"
                f"{ratio(band['serial'][i], band['threads'][i])}" for i in range(rounds))
            last = {m: per[m][0][0][-1] for m in modes}
            lines.append(
                f"| {scene} | {schedule} | "
                + " | ".join(", ".join(cell(c) for c in conv[m]) + "; "
                             + ", ".join(cell(b) for b in band[m]) for m in modes)
                + f" | {rounds_text} | {ratio(fastest(conv['serial']), fastest(conv['threads']))}, "
                f"{ratio(fastest(band['serial']), fastest(band['threads']))} | "
                f"{last['serial'][1]:.2f} / {last['threads'][1]:.2f} | "
                f"{len(per['serial'][0][0])} / {len(per['threads'][0][0])} | "
                f"{per['serial'][0][1]:.2f} / {per['threads'][0][1]:.2f} | "
                f"{100 * error_at_deadlines(per['serial'][0][0], deadlines):.1f} / "
                f"{100 * error_at_deadlines(per['threads'][0][0], deadlines):.1f} |")
    (out / "table.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
