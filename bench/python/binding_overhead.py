"""The Python binding's cost: one TSGO coarse-to-fine solve of a Middlebury scene through
c2f.solve and through c2f-stereo, same options, runs alternating; prints both run clocks and
their ratio (docs/python.md).

usage: PYTHONPATH=build/release/python python3 bench/python/binding_overhead.py \
           [SCENE_DIR] [BUILD_DIR] [RUNS]
"""

import re
import statistics
import subprocess
import sys
import tempfile
import time

import c2f

scene = sys.argv[1] if len(sys.argv) > 1 else "../shared/data/middlebury/2003/Teddy"
build = sys.argv[2] if len(sys.argv) > 2 else "build/release"
runs = int(sys.argv[3]) if len(sys.argv) > 3 else 3
left, right = f"{scene}/left.png", f"{scene}/right.png"

pair = c2f.read_stereo_pair(left, right)
energy = c2f.stereo_energy(pair["left"], pair["right"], labels=60)
python_clock, python_wall, cli_clock = [], [], []
with tempfile.TemporaryDirectory() as folder:
    for run in range(runs):
        start = time.perf_counter()
        result = c2f.solve(energy, "paper")
        python_wall.append(time.perf_counter() - start)
        python_clock.append(result.seconds)
        subprocess.run([f"{build}/examples/stereo/c2f-stereo", left, right, "--labels", "60",
                        "--schedule", "paper", "-o", f"{folder}/out", "-q"], check=True)
        summary = open(f"{folder}/out/summary.txt").read()
        found = re.search(r"final energy ([0-9.]+) after (\d+) steps in ([0-9.]+)s", summary)
        cli_clock.append(float(found.group(3)))
        print(f"run {run}: python {result.energy:.6f} ({result.steps} steps, {result.seconds:.3f} s), "
              f"c2f-stereo {found.group(1)} ({found.group(2)} steps, {found.group(3)} s)", flush=True)
print(f"median run clock: python {statistics.median(python_clock):.3f} s "
      f"(wall {statistics.median(python_wall):.3f} s), c2f-stereo {statistics.median(cli_clock):.3f} s, "
      f"ratio {statistics.median(python_clock) / statistics.median(cli_clock):.3f}")
