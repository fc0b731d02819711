"""Interactive multi-label segmentation by cooperative cuts from numpy arrays: flat against
coarse to fine (superpixels), and the Potts baseline on the same data; writes each run's label
map and overlay and the energy-against-time plot of the two cooperative-cut runs.

    python3 examples/python/segment.py [--image I --seeds S] [--downscale 2]
        [--time-limit 20] [--out out/python-segment]

Default input: fruits.jpg from Debian's opencv-doc with the project's seed scribbles
(examples/segment/data/fruits-seeds.png; docs/segmentation.md gives the seed encodings). Needs
the c2f package (README, "From Python") and matplotlib.
"""

import argparse
import os
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import c2f
import c2f.plot

SEEDS = pathlib.Path(__file__).resolve().parents[1] / "segment/data/fruits-seeds.png"

parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
parser.add_argument("--image", default="/usr/share/doc/opencv-doc/examples/data/fruits.jpg")
parser.add_argument("--seeds", default=str(SEEDS))
parser.add_argument("--downscale", type=int, default=2)
parser.add_argument("--time-limit", type=float, default=20.0, help="seconds per run")
parser.add_argument("--out", default="out/python-segment")
arguments = parser.parse_args()

try:
    scene = c2f.read_segmentation(arguments.image, arguments.seeds, downscale=arguments.downscale)
except (OSError, ValueError) as error:
    sys.exit(f"segment.py: {error}")
os.makedirs(arguments.out, exist_ok=True)
image, seeds, palette = scene["image"], scene["seeds"], scene["palette"]

runs = {}
for name, options in [("coop-flat", dict(schedule="flat")),
                      ("coop-c2f", dict(schedule="superpixels")),
                      ("potts", dict(method="potts", schedule="flat"))]:
    result = c2f.segment(image, seeds, time_limit=arguments.time_limit, **options)
    runs[name] = result
    print(f"{name}: energy {result.energy:.6f} after {result.steps} steps in "
          f"{result.seconds:.2f} s ({result.reason})")
    colours = palette[result.labeling].astype(np.uint8)  # (H, W, 3): each label's colour
    plt.imsave(f"{arguments.out}/{name}-labels.png", colours)
    overlay = (0.5 * image + 0.5 * colours).astype(np.uint8)
    plt.imsave(f"{arguments.out}/{name}-overlay.png", overlay)

# The Potts run minimises another energy; only the cooperative-cut runs share an energy axis.
coop = {name: runs[name] for name in ("coop-flat", "coop-c2f")}
c2f.plot.energy_against_time(coop, gap_to=min(r.energy for r in coop.values()),
                             title="cooperative cut: energy against time").savefig(
    f"{arguments.out}/energy.png", dpi=110, bbox_inches="tight")
print(f"wrote {arguments.out}/")
