"""TSGO stereo from numpy arrays, flat against coarse to fine given the same moves: writes the two disparity maps,
their bad-pixel maps and the energy- and error-against-time plots.

    python3 examples/python/stereo.py [--left L --right R --gt GT --gt-divisor D]
        [--labels 85] [--downscale 3] [--time-limit 20] [--out out/python-stereo]

Default input: the Aloe pair Debian's opencv-doc ships, at a third of its size. Needs the c2f
package (README, "From Python") and matplotlib.
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import c2f
import c2f.plot

OPENCV_DATA = "/usr/share/doc/opencv-doc/examples/data"

parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
parser.add_argument("--left", default=f"{OPENCV_DATA}/aloeL.jpg")
parser.add_argument("--right", default=f"{OPENCV_DATA}/aloeR.jpg")
parser.add_argument("--gt", default=f"{OPENCV_DATA}/aloeGT.png", help="'' for none")
parser.add_argument("--gt-divisor", type=float, default=0.0,
                    help="GT PNG value per pixel (0: by the file, 256 for a 16-bit PNG)")
parser.add_argument("--labels", type=int, default=85)
parser.add_argument("--downscale", type=int, default=3)
parser.add_argument("--time-limit", type=float, default=20.0, help="seconds per run")
parser.add_argument("--out", default="out/python-stereo")
arguments = parser.parse_args()

try:
    pair = c2f.read_stereo_pair(arguments.left, arguments.right, gt=arguments.gt,
                                gt_divisor=arguments.gt_divisor, downscale=arguments.downscale)
except (OSError, ValueError) as error:
    sys.exit(f"stereo.py: {error}")
os.makedirs(arguments.out, exist_ok=True)

# One energy, two runs given the same moves (expansion, near moves within 5 labels, shift
# moves): flat, and coarse to fine from aggregated best labels. A callback records the
# bad-pixel rate (> 1) of every step's labeling (on coarse levels: the labeling it stands for).
energy = c2f.stereo_energy(pair["left"], pair["right"], labels=arguments.labels)
moves = dict(options={"near_radius": 5, "shift_moves": True}, time_limit=arguments.time_limit)
runs, errors = {}, {}
for name, schedule, options in [("flat", "flat", {}),
                                ("c2f", "aggregated", dict(plateau_tolerance=3e-5))]:
    errors[name] = []

    def record(step, name=name):
        if pair["gt"] is not None:
            rates = c2f.bad_pixel_rates(step["labeling"], pair["gt"], pair["mask"])
            errors[name].append((step["time"], rates["all"][1.0]))

    runs[name] = c2f.solve(energy, schedule, callback=record, **moves, **options)
    result = runs[name]
    print(f"{name}: energy {result.energy:.6f} after {result.steps} steps in "
          f"{result.seconds:.2f} s ({result.reason})")
    plt.imsave(f"{arguments.out}/{name}-disparity.png", result.labeling, cmap="inferno",
               vmin=0, vmax=arguments.labels - 1)
    if pair["gt"] is not None:
        wrong = np.abs(result.labeling - pair["gt"]) > 1  # NaN (unknown) compares False
        plt.imsave(f"{arguments.out}/{name}-bad-pixels.png", wrong, cmap="gray_r")
        print(f"{name}: bad pixels (> 1): {100 * c2f.bad_pixel_rates(result.labeling, pair['gt'], pair['mask'])['all'][1.0]:.2f}%")

best = min(result.energy for result in runs.values())
c2f.plot.energy_against_time(runs, gap_to=best, title="stereo: energy against time").savefig(
    f"{arguments.out}/energy.png", dpi=110, bbox_inches="tight")
if pair["gt"] is not None:
    traces = {name: {"time": np.array([t for t, _ in points]),
                     "error": np.array([e for _, e in points])}
              for name, points in errors.items() if points}
    c2f.plot.error_against_time(traces, title="stereo: bad pixels (> 1) against time").savefig(
        f"{arguments.out}/error.png", dpi=110, bbox_inches="tight")
print(f"wrote {arguments.out}/")
