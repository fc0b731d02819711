"""Schedules for a generic pairwise energy against flat with the same moves, on synthetic grids
(480x640; 8 labels truncated linear, 32 labels truncated linear, 16 labels Potts; noisy
piecewise-constant images). The instances of seed 3 (marked *) are the aside set, fixed by
this names-only rule before any run; seeds 1 and 2 are the tuning set. Per instance and schedule:
the time to come within 1e-4 of flat's final energy over flat's time to converge, and the final
energy relative to flat's. How pairwise_defaults() was chosen: docs/history/results-2026-12.md,
"How the defaults were chosen".

    PYTHONPATH=build/release/python /usr/bin/python3 bench/pairwise_defaults.py \
        'agg:2/cc|cp:1,1|paper' [PLATEAU_TOLERANCE]
"""
import sys

import numpy as np

import c2f

def instance(family, seed):
    rng = np.random.default_rng(seed)
    H, W, L, term, w, noise = {
        'tl8': (480, 640, 8, c2f.Term.truncated_linear(2.0), 1.0, 1.5),
        'tl32': (480, 640, 32, c2f.Term.truncated_linear(4.0), 2.0, 3.0),
        'potts16': (480, 640, 16, c2f.Term.potts(), 2.0, 3.0),
    }[family]
    # piecewise-constant truth: random rectangles
    truth = np.zeros((H, W), int)
    for _ in range(30):
        y, x = rng.integers(0, H), rng.integers(0, W)
        h, ww = rng.integers(H // 10, H // 2), rng.integers(W // 10, W // 2)
        truth[y:y + h, x:x + ww] = rng.integers(0, L)
    noisy = truth + rng.normal(0, noise, truth.shape)
    unary = np.abs(noisy[..., None] - np.arange(L)).astype(np.float32)
    return c2f.Energy.grid(unary, term, weight=w)

def time_to(result, target):
    t, e = result.trace['time'], result.trace['energy']
    hit = np.nonzero(e <= target)[0]
    return float(t[hit[0]]) if len(hit) else float('inf')

schedules = sys.argv[1].split('|')
tol = float(sys.argv[2]) if len(sys.argv) > 2 else 0.0
for family in ['tl8', 'tl32', 'potts16']:
    for seed in [1, 2, 3]:
        e = instance(family, seed)
        flat = c2f.solve(e, 'flat')
        row = [f"{family}-s{seed}{'*' if seed == 3 else ''}", f"flat {flat.seconds:.2f}s"]
        for s in schedules:
            r = c2f.solve(e, s, plateau_tolerance=tol)
            t4 = time_to(r, flat.energy * (1 + 1e-4))
            row.append(f"{s}: {t4 / flat.seconds:.2f} end {(r.energy - flat.energy) / flat.energy:+.1e} ({r.seconds:.2f}s)")
        print(' | '.join(row), flush=True)
