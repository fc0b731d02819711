"""Building a 1-megapixel, 64-label, 4-connected grid energy from a float32 numpy array with
c2f.Energy.grid: the median of five builds (docs/python.md; target under 1 s).

usage: PYTHONPATH=build/release/python python3 bench/python/grid_build.py
"""

import statistics
import time

import numpy as np

import c2f

unary = np.random.default_rng(0).random((1000, 1000, 64)).astype(np.float32)
seconds = []
for _ in range(5):
    start = time.perf_counter()
    energy = c2f.Energy.grid(unary, c2f.Term.truncated_linear(4.0), weight=0.5)
    seconds.append(time.perf_counter() - start)
    del energy
print(f"{unary.shape} float32 -> {c2f.Energy.grid(unary[:2, :2])!r} ...; builds: "
      + ", ".join(f"{s:.3f}" for s in seconds) + f" s; median {statistics.median(seconds):.3f} s")
