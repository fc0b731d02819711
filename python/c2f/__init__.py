"""c2f: coarse-to-fine lifted MAP inference for pairwise energies, from numpy.

Build an energy from arrays, solve it flat or coarse to fine with a chosen solver, and look at
the result and its trace::

    import numpy as np, c2f
    unary = np.random.rand(240, 320, 8)                 # (H, W, L) costs
    energy = c2f.Energy.grid(unary, c2f.Term.potts(), weight=0.5)
    result = c2f.solve(energy, schedule="paper")
    result.labeling.shape                                # (240, 320)
    result.energy == energy.evaluate(result.labeling)    # True

The compiled core is c2f._c2f (C++20, pybind11); this module is its documented front.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Dict, Optional, Sequence, Union

import numpy as np

from ._c2f import (Energy, Term, _segment, _solve, bad_pixel_rates, expand, partition,
                   read_image, read_segmentation, read_stereo_pair, reduce, stereo_energy,
                   transfer)

__all__ = ["Energy", "Term", "Result", "solve", "stereo", "stereo_energy", "read_image",
           "read_stereo_pair", "bad_pixel_rates", "segment", "read_segmentation", "partition",
           "reduce", "expand", "transfer"]


@dataclass
class Result:
    """The outcome of a solve.

    labeling: int32 labels, shaped like the energy's variables ((H, W) for a grid energy).
    energy: E(labeling).
    reason: why the run ended: 'converged', 'step_limit', 'time_limit', 'target_energy' or
        'observer' (the callback, or Ctrl-C, stopped it).
    seconds: the run clock at the end (time inside the callback excluded).
    steps: solver steps made over all levels.
    summary: a few lines per level and the outcome, as the command-line tools print them.
    trace: numpy arrays with one entry per step: 'time', 'level', 'step', 'energy' (of the
        original problem's labeling) and 'variables' (of the step's level).
    """

    labeling: np.ndarray
    energy: float
    reason: str
    seconds: float
    steps: int
    summary: str
    trace: Dict[str, np.ndarray]


Schedule = Union[str, Sequence[np.ndarray]]
Callback = Callable[[Dict[str, Any]], Optional[bool]]


def solve(
    energy: Energy,
    schedule: Schedule = "flat",
    *,
    solver: str = "expansion",
    maxflow: str = "dynamic",
    order: str = "sequential",
    seed: int = 1,
    near_radius: int = 0,
    shift_moves: bool = False,
    near_levels: str = "original",
    time_limit: float = 0.0,
    max_steps: int = 0,
    plateau: int = 4,
    plateau_tolerance: float = 0.0,
    start: Union[str, np.ndarray] = "unary_argmin",
    callback: Optional[Callback] = None,
    memory: float = 0.0,
) -> Result:
    """Minimises `energy`, flat or coarse to fine; the C++ coarse_to_fine with a SolverChoice.

    schedule: the coarse levels, coarsest first. 'flat' (the original problem only), 'paper'
        (colour passing CP(1,1) CP(2,1) CP(3,1)), or any schedule text of the library
        ('cp:1,1 cp:2,1', 'auto:0.01,0.1', and on a grid energy also 'agg:2/cc', 'blocks:4',
        'threshold:0.5', ...); or a list of your own partitions, each an integer array of
        group ids of every variable (equal ids: one group), each refining the one before.
    solver: 'expansion' (alpha-expansion with QPBO moves), 'swap', 'lbp' or 'icm'.
    maxflow: the graph-cut solvers' max-flow: 'dynamic' (ours, recycled graphs) or 'boost'.
    order: the order moves are tried in: 'sequential', 'random' (from `seed`) or 'frequency'.
    near_radius, shift_moves, near_levels: expansion's near moves (labels within the radius of
        the current one) and shift moves, on the 'original' problem only or on 'all' levels.
    time_limit: stop once the run clock passes this many seconds (0: no limit).
    max_steps: stop after this many solver steps over all levels (0: no limit).
    plateau: a level is refined (the original problem: finished) after this many steps without
        a decrease (on the original problem the solver's own convergence rule applies).
    plateau_tolerance: on coarse levels, decreases below this fraction of |E| do not count.
    start: the first labeling: 'unary_argmin', 'zero', or a labeling of your own (an integer
        array of shape (N,) or the grid's (H, W)); on a coarse first level each group starts
        at the label most of its members have in it.
    callback: called after every step with a dict (time, level, step, energy, variables,
        at_original, labeling: the original variables' labeling this step stands for, in the
        result's shape, a copy made per step); returning False stops the run (None or True
        goes on).
    memory: the run's memory budget in GiB, as the tools' --memory (0: a quarter of this
        machine's memory, growing to the run's needs up to half, at most what is available).
        The run's floor (the energy, the solver's working memory) must fit it, else ValueError
        naming `memory`; the recycled move graphs get what it leaves, and a coarse level that
        does not fit is skipped.

    The GIL is released while the solver runs. Ctrl-C ends the run at its next step and raises
    KeyboardInterrupt with the best result so far as its `result` attribute; an exception
    raised by the callback is raised the same way. Bad arguments raise ValueError or TypeError
    naming the argument.
    """
    return _result(lambda: _solve(
        energy, list(schedule) if isinstance(schedule, tuple) else schedule, solver, maxflow,
        order, seed, near_radius, bool(shift_moves), near_levels, time_limit, max_steps, plateau,
        plateau_tolerance, start, callback, memory))


def stereo(left: np.ndarray, right: np.ndarray, labels: int = 85, schedule: Schedule = "paper",
           *, smoothness: str = "tsgo_step", truncation: float = 2.0, threads: int = 0,
           **options: Any) -> Result:
    """TSGO stereo of two RGB uint8 views (H, W, 3), coarse to fine: the disparities 0..labels-1
    of the left view are result.labeling ((H, W)). `schedule` takes the stereo presets ('paper',
    'paper-slic', 'regions', 'aggregated', ...) besides every schedule text; `options` are
    c2f.solve's (solver, near_radius, shift_moves, time_limit, callback, memory, ...); `threads`
    the data preparation's cores (0: all); `memory` (GiB, 0: the default) holds the data
    preparation as well as the run. The same energy and run as `c2f-stereo LEFT RIGHT --labels L
    --schedule S`."""
    energy = stereo_energy(left, right, labels, smoothness, truncation, threads,
                           options.get("memory", 0.0))
    return solve(energy, schedule, **options)


def _result(call: Callable[[], Dict[str, Any]]) -> Result:
    """A Result from the engine's dict; a Python exception that stopped the run keeps its
    partial result as a Result too."""
    try:
        raw = call()
    except BaseException as error:
        partial = getattr(error, "result", None)
        if isinstance(partial, dict):
            error.result = Result(**partial)
        raise
    return Result(**raw)


def segment(image: np.ndarray, seeds: np.ndarray, schedule: str = "superpixels", *,
            method: str = "coop", aux: str = "mm", start: str = "zero", lambda_: float = 0.5,
            theta: float = 0.0007, alpha: float = 0.2, classes: int = 10,
            kmeans: str = "plusplus", gmm_seed: int = 27, edge_seed: int = 27, threads: int = 0,
            time_limit: float = 0.0, max_steps: int = 0, plateau: int = 0,
            callback: Optional[Callback] = None, memory: float = 0.0) -> Result:
    """Interactive multi-label segmentation by cooperative cuts, as c2f-segment runs it.

    image: (H, W, 3) uint8 RGB. seeds: (H, W) integers, -1 where the user drew nothing, else the
    pixel's label 0..L-1 (every label needs a seed). A colour GMM per label from its seeds gives
    the unaries; 8-connected edges in `classes` colour-difference classes carry the cooperative
    cut (lambda_, theta, alpha: docs/segmentation.md). method: 'coop' or 'potts' (the
    alpha-expansion baseline on the same data). aux: how the cooperative cut's auxiliary
    variables are found: 'mm' (majorise-minimise), 'greedy' (with `start`: 'zero' or
    'current') or 'ceres' (a continuous relaxation). schedule: 'superpixels', 'paper', 'flat' or
    any schedule text (slic:S levels segment the image). kmeans, gmm_seed, edge_seed: the data
    preparation's clustering; threads: the cores it runs on (0: all; the result is the same for
    every count). plateau: steps without decrease that end a coarse level (0: the
    number of labels or one sweep when shorter; -1: one sweep). memory: the budget in GiB
    (0: a quarter of this machine's memory, up to half for a run that needs it) that the data
    preparation must fit (ValueError naming `memory` otherwise); the Potts runs' recycled move
    graphs get what it leaves. result.labeling is (H, W).
    """
    return _result(lambda: _segment(image, seeds, method, aux, start, schedule, lambda_, theta,
                                    alpha, classes, kmeans, gmm_seed, edge_seed, threads,
                                    time_limit, max_steps, plateau, callback, memory))
