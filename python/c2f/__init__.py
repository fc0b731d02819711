"""c2f: coarse-to-fine lifted MAP inference for pairwise energies, from numpy.

Build an energy from arrays, solve it flat or coarse to fine with a chosen solver, and look at
the result and its trace::

    import numpy as np, c2f
    unary = np.random.rand(240, 320, 8)                 # (H, W, L) costs
    energy = c2f.Energy.grid(unary, c2f.Term.potts(), weight=0.5)
    result = c2f.solve(energy)                         # coarse to fine, the measured defaults
    result.labeling.shape                                # (240, 320)
    result.energy == energy.evaluate(result.labeling)    # True

The compiled core is c2f._c2f (C++20, pybind11); this module is its documented front.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Dict, Optional, Sequence, Union

import numpy as np

from ._c2f import (Energy, Term, _defaults, _segment, _segmentation_defaults, _solve,
                   bad_pixel_rates, expand, partition, read_image, read_segmentation,
                   read_stereo_pair, reduce, stereo_energy, transfer)

__all__ = ["Energy", "Term", "Result", "defaults", "solve", "stereo", "stereo_energy", "read_image",
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
        original problem's labeling), 'variables' (of the step's level) and 'step_variables'
        (those the step's move worked over: fewer than 'variables' for a near move; 0 at a
        level's step 0).
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


def defaults(name: str = "pairwise") -> Dict[str, Any]:
    """The library's defaults: what ``solve``, ``stereo`` and ``segment`` run where an argument
    is None.

    Parameters
    ----------
    name : {'pairwise', 'stereo', 'segmentation'}, default 'pairwise'
        'pairwise' for any pairwise energy (``solve``, ``c2f-solve``), 'stereo' for the TSGO
        stereo energy (``stereo``, ``c2f-stereo``), 'segmentation' for cooperative-cut
        segmentation (``segment``, ``c2f-segment``).

    Returns
    -------
    dict
        For 'pairwise' and 'stereo': ``grid_schedule``, ``local_schedule`` and
        ``general_schedule`` (the schedule on a grid energy, on another energy whose edges are
        local in its variables' order, such as a lattice, and on any other), expansion's
        ``near_radius``, ``near_seeds`` and ``grid_near_seeds`` (where near moves start on any
        other energy and on a grid energy), ``near_graphs``, ``near_min_variables`` and
        ``shift_moves`` (on the original problem), ``plateau`` ('rate' or a number of steps),
        ``plateau_steps`` (the steps of the plateau rule, 'rate' or not), ``plateau_tolerance``
        and ``grid_plateau_tolerance`` (coarse levels; the tolerance on any other energy and on
        a grid energy). For 'segmentation': ``schedule``, ``method``, ``aux`` (how the
        cooperative cut's auxiliary variables move), ``near_radius`` (its near moves on the
        original problem with aux 'mm'; 'greedy' and 'ceres' make whole moves), ``lambda_``,
        ``theta`` and ``alpha``. Each is the configuration measured best on a tuning set and
        confirmed on instances set aside (docs/results.md, "Defaults").
    """
    if name == "segmentation":
        return _segmentation_defaults()
    if name not in ("pairwise", "stereo"):
        raise ValueError(f"name: expected 'pairwise', 'stereo' or 'segmentation', got {name!r}")
    return _defaults(name)


def solve(
    energy: Energy,
    schedule: Optional[Schedule] = None,
    *,
    defaults: str = "pairwise",
    method: str = "expansion",
    options: Optional[Dict[str, Any]] = None,
    time_limit: Optional[float] = None,
    max_steps: Optional[int] = None,
    plateau: Union[None, int, str] = None,
    plateau_tolerance: Optional[float] = None,
    start: Union[str, np.ndarray] = "unary_argmin",
    callback: Optional[Callback] = None,
    memory: Optional[float] = None,
    graph_memory: Optional[float] = None,
    threads: Optional[int] = None,
) -> Result:
    """Minimise `energy`, flat or coarse to fine (the run layer's ``c2f::run``).

    Parameters
    ----------
    energy : Energy
        The pairwise energy (``Energy.grid``, ``Energy.general``, ``stereo_energy``, ...).
    schedule : str or sequence of ndarray, optional
        The coarse levels, coarsest first. None: the defaults' (coarse to fine:
        'agg:2,8,0.15/cc' on a grid energy, 'agg:2,3,0.15/cc' on another whose edges are
        local in its variables' order, 'agg:2/cc' on any other; see ``defaults``).
        'flat' (the original problem only, with the same moves: the fair baseline), 'paper' (colour
        passing CP(1,1) CP(2,1) CP(3,1)), any schedule text of the library ('cp:1,1 cp:2,1',
        'auto:0.01,0.1', 'agg:2/cc', and on a grid energy also 'blocks:4', 'threshold:0.5',
        ...), or a list of your own partitions, each an integer array of group ids of every
        variable (equal ids: one group), each refining the one before.
    defaults : {'pairwise', 'stereo'}, default 'pairwise'
        Which of the library's measured defaults (``defaults(name)``) fill the arguments left
        None and expansion's ``near_radius``, ``near_seeds``, ``near_graphs``,
        ``near_min_variables`` and ``shift_moves`` not in ``options``.
    method : {'expansion', 'swap', 'lbp', 'icm'}, default 'expansion'
        The solver: alpha-expansion with QPBO moves, alpha-beta swap, loopy belief propagation
        or iterated conditional modes.
    options : dict, optional
        The method's own options (unknown names are refused):

        - expansion: ``order`` ('sequential', 'random' from ``seed``, 'frequency'), ``seed``,
          ``tolerance``, ``near_radius`` (near moves), ``near_seeds`` ('label_and_cheapest':
          a move to a label starts from its variables and those whose cheapest unary it is;
          'label': from its variables only; 'label_and_adjacent': as 'label', and on 16
          labels or more without shift moves also from the variables of the labels next to
          it), ``near_graphs`` ('local': near moves only on an
          energy whose edges are local in its variables' order, a grid or lattice; 'any'),
          ``near_min_variables`` (near moves only on an energy of at least this many
          variables; 0: any size), ``near_sweep_gain``, ``shift_moves``
          (True, False, or 'auto': only on an energy where some expansion move is not
          submodular, e.g. truncated quadratic; the pairwise defaults' choice), ``regions`` (near and shift moves by at most this many bands of rows at once, e.g.
          16; 1, the default: none), ``flow_parts`` (each move's max-flow in this many bands
          at once; 0, the default: with maxflow 'dynamic' the most parts up to 4 that keep at
          most 5% of the energy's edges between parts, else 1, e.g. a random graph; 1 with
          another),
          ``threads`` (that solve them, 0: all cores; the result is the same for every count),
          ``near_levels`` ('original': near and shift moves on the original problem only, the
          default; 'all'), ``maxflow`` ('dynamic', ours with recycled graphs, the default;
          'boost'; 'kolmogorov' in builds with it);
        - swap: ``order``, ``seed``, ``tolerance``, ``maxflow``;
        - lbp: ``schedule`` ('bands', the default: bands of consecutive variables, each sent
          in order, the bands at once; 'sequential'; 'parallel'), ``damping`` in [0, 1),
          ``threads`` (0: all cores; 'sequential' sends on one), ``band_variables``
          (variables per band; default the larger of 4096 and a sixteenth of them);
        - icm: ``order`` ('sequential' or 'random'), ``seed``, ``tolerance``.
    time_limit : float, optional
        Stop once the run clock passes this many seconds (None: no limit).
    max_steps : int, optional
        Stop after this many solver steps over all levels (None: no limit).
    plateau : int or 'rate', optional
        A coarse level is refined after this many steps without a decrease (the original
        problem ends where the solver has converged: one sweep of its moves). 'rate': 4
        steps, or sooner, after its first sweep, once its energy decrease per variable moved
        over its last 4 steps is no more than what the original problem is expected to give
        (what single-variable changes of the labeling it would hand down would gain, over a
        sweep of whole moves on the original variables: the driver's ``progress_rate``).
        None: the defaults' ('rate' for the pairwise defaults, 4 for the stereo ones).
    plateau_tolerance : float, optional
        On coarse levels, decreases below this fraction of abs(E) do not count. None: the
        defaults' (``grid_plateau_tolerance`` on a grid energy, ``plateau_tolerance`` on any
        other).
    start : str or ndarray, default 'unary_argmin'
        The first labeling: 'unary_argmin', 'zero', or a labeling of your own (an integer array
        of shape (N,) or the grid's (H, W)); on a coarse first level each group starts at the
        label most of its members have in it.
    callback : callable, optional
        Called after every step with a dict (time, level, step, energy, variables,
        step_variables, at_original, labeling: the original variables' labeling this step
        stands for, in the result's shape, a copy made per step); returning False stops the
        run (None or True goes on).
    memory : float, optional
        The run's memory budget in GiB, as the tools' --memory (None: a quarter of this
        machine's memory, growing to the run's needs up to half, at most what is available).
        The run's floor (the energy, the solver's working memory) must fit it; the recycled
        move graphs get what it leaves, and a coarse level that does not fit is skipped.
    graph_memory : float, optional
        At most this many GiB of the budget for recycled move graphs (0: no recycling; None:
        all that the budget leaves).
    threads : int, optional
        The cores expansion or lbp solves on (``options['threads']``, which may be given
        instead but not as well; None: that option's default, 0: every core). The result is
        the same bits for every count. Only expansion and lbp take it.

    Returns
    -------
    Result
        The labeling, its energy, why the run ended, its time, steps, summary and trace.

    Raises
    ------
    ValueError, TypeError
        For a bad argument, naming it (an option as ``options``; a budget the run's floor does
        not fit as ``memory``).
    KeyboardInterrupt
        Ctrl-C ends the run at its next step; the best result so far is the exception's
        ``result`` attribute (an exception raised by the callback is raised the same way).

    Notes
    -----
    The GIL is released while the solver runs.
    """
    if threads is not None:
        if method not in ("expansion", "lbp"):
            raise ValueError("threads: only expansion and lbp solve on several threads, "
                             f"not {method!r}")
        if options is not None and "threads" in options:
            raise ValueError("threads: given as well as options['threads']; give one")
        options = dict(options or {}, threads=threads)
    return _result(lambda: _solve(
        energy, list(schedule) if isinstance(schedule, tuple) else schedule, defaults=defaults,
        method=method,
        options=options, time_limit=time_limit, max_steps=max_steps, plateau=plateau,
        plateau_tolerance=plateau_tolerance, start=start, callback=callback, memory=memory,
        graph_memory=graph_memory))


def stereo(left: np.ndarray, right: np.ndarray, labels: int = 85,
           schedule: Optional[Schedule] = None,
           *, smoothness: str = "tsgo_step", truncation: float = 2.0, threads: int = 0,
           **run_options: Any) -> Result:
    """TSGO stereo of two views, coarse to fine: ``c2f-stereo LEFT RIGHT --labels L --schedule S``.

    Parameters
    ----------
    left, right : ndarray
        RGB uint8 views of shape (H, W, 3).
    labels : int, default 85
        Disparities 0..labels-1 of the left view (result.labeling, shape (H, W)).
    schedule : str or sequence of ndarray, optional
        Every schedule of ``solve``, and the stereo presets ('aggregated', 'paper',
        'paper-slic', 'regions', ...). None: the stereo defaults (``defaults('stereo')``:
        'aggregated' with near and shift moves), as c2f-stereo runs.
    smoothness, truncation : str, float
        The TSGO pairwise term ('tsgo_step' or 'truncated_linear') and its truncation.
    threads : int, default 0
        The cores of the data preparation and, with method 'expansion', of the solve
        (``options['threads']`` unless given); 0: all. The result is the same for every count.
    **run_options
        ``solve``'s keywords (method, options, time_limit, callback, memory, ...); ``memory``
        (GiB, None: the default) holds the data preparation as well as the run.
    """
    energy = stereo_energy(left, right, labels, smoothness, truncation, threads,
                           run_options.get("memory"))
    if run_options.get("method", "expansion") == "expansion":
        options = dict(run_options.get("options") or {})
        options.setdefault("threads", threads)
        run_options = {**run_options, "options": options}
    return solve(energy, schedule, **{"defaults": "stereo", **run_options})


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


def segment(image: np.ndarray, seeds: np.ndarray, schedule: Optional[str] = None, *,
            method: Optional[str] = None, options: Optional[Dict[str, Any]] = None,
            lambda_: Optional[float] = None, theta: Optional[float] = None,
            alpha: Optional[float] = None, classes: int = 10,
            kmeans: str = "plusplus", gmm_seed: int = 27, edge_seed: int = 27, threads: int = 0,
            time_limit: Optional[float] = None, max_steps: Optional[int] = None,
            plateau: Union[None, str, int] = None, callback: Optional[Callback] = None,
            memory: Optional[float] = None) -> Result:
    """Interactive multi-label segmentation by cooperative cuts, as c2f-segment runs it.

    ``schedule``, ``method``, ``lambda_``, ``theta`` and ``alpha`` left None, and the
    cooperative cut's options not named, are the library's defaults,
    ``defaults('segmentation')``, as c2f-segment's flags are.

    Parameters
    ----------
    image : ndarray
        (H, W, 3) uint8 RGB.
    seeds : ndarray
        (H, W) integers, -1 where the user drew nothing, else the pixel's label 0..L-1 (every
        label needs a seed). A colour GMM per label from its seeds gives the unaries;
        8-connected edges in `classes` colour-difference classes carry the cooperative cut.
    schedule : str, optional
        'superpixels', 'paper', 'flat' or any schedule text (slic:S levels segment the image).
        None: the defaults' ('superpixels', slic:16 slic:8 flat).
    method : {'coop', 'potts'}, optional
        The cooperative cut (None: the default), or the alpha-expansion baseline on the Potts
        energy of the same data.
    options : dict, optional
        The cooperative cut's solver: ``aux``, how its auxiliary variables are found ('mm',
        majorise-minimise, the default; 'greedy'; 'ceres', a continuous relaxation),
        ``start`` (greedy's expansion start: 'zero' or 'current'), ``expansion_cycles`` (the
        most alpha-expansion cycles of a step; by default 1 for 'mm', 10 for the others),
        ``near_radius`` (near moves in each step's expansion on the original problem: a move
        to a label frees the pixels within this many edges of that label's pixels; 0: whole
        moves; by default the defaults' ``near_radius`` for 'mm', 0 for the others).
    lambda_, theta, alpha : float, optional
        The cooperative cut's weight, threshold and ratio (docs/segmentation.md; None: the
        defaults').
    classes, kmeans, gmm_seed, edge_seed : int, str, int, int
        The data preparation's clustering.
    threads : int, default 0
        The cores the data preparation and the solve run on (0: all; the result is the same
        for every count).
    time_limit, max_steps : float, int, optional
        Limits of the run (None: none).
    plateau : None, 'sweep' or int
        Steps without decrease that end a coarse level (None: the number of labels, or one
        sweep when that is shorter; 'sweep': one sweep).
    callback : callable, optional
        As ``solve``'s.
    memory : float, optional
        The budget in GiB (None: a quarter of this machine's memory, up to half for a run that
        needs it) that the data preparation and the run must fit (ValueError naming `memory`
        otherwise); the recycled move graphs get what it leaves.

    Returns
    -------
    Result
        result.labeling has shape (H, W).
    """
    return _result(lambda: _segment(
        image, seeds, schedule, method=method, options=options, lambda_=lambda_, theta=theta,
        alpha=alpha, classes=classes, kmeans=kmeans, gmm_seed=gmm_seed, edge_seed=edge_seed,
        threads=threads, time_limit=time_limit, max_steps=max_steps, plateau=plateau,
        callback=callback, memory=memory))
