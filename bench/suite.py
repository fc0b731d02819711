"""The coarse-to-fine suite: per instance, flat with the same moves against the default coarse
to fine, in one process on one clock, over four families of energies.

    bench/run-suite [OUT_DIR] [suite.py options]        (builds what it needs, then runs this)
    PYTHONPATH=build/release/python /usr/bin/python3 bench/suite.py --out OUT_DIR [options]

Families (--families, default all four):
  grid          synthetic grids: 0.1, 0.3, 1 and 4 megapixels; 8, 32 and 128 labels; Potts,
                truncated linear and truncated quadratic terms; two noise levels. Every
                combination up to 32 M pixels x labels (54 instances; --max-size raises it).
  general       energies on graphs that are not grids (no grid levels): lattices with dropped
                and long-range edges, sparse random graphs, and the TSGO stereo energy of Teddy
                handed over as a general graph (edges and unaries only).
  stereo        the TSGO stereo energy (c2f-bench-stereo, stereo defaults against flat with the
                same near and shift moves): third-size Middlebury 2005 and the first five 2006
                scenes, Middlebury 2014 Q, KITTI 2015 and full-size Aloe from opencv-doc.
  segmentation  cooperative cuts on the coopCuts images (c2f-bench-segment: the segmentation
                defaults, majorise-minimise on superpixel levels with near moves on the original
                problem, against flat majorise-minimise).

Grid and general instances run in this process through the Python package (c2f.solve with
schedule 'flat', then with the defaults); stereo and segmentation instances run in their
benchmark tool, which prepares the data once and solves both runs in one process.

Aside set (fixed before any tuning, by names only): a stereo scene is aside when it is one of
Recycle and PlaytableP of Middlebury 2014 and KITTI's 000001_10 (the set every earlier
measurement kept aside); any other instance when zlib.crc32 of its name is divisible by 4.
Aside instances are reported apart and must never be used to choose parameters.

Per instance (OUT_DIR/suite.tsv, one row each, written as soon as it is measured): the flat
run's time to converge and final energy (grid, general and segmentation: where the defaults
make near moves, the sooner converged of flat with their moves and flat with whole moves, named
in flat_moves);
the time the default run took to come within 1e-4 and within 1e-3 of flat's final energy,
over flat's convergence time (the ratio; 'never' when it did not); the default run's final
energy relative to flat's; the error at deadlines of both (grid: pixels more than one label
from the truth; segmentation: pixel error; stereo: the scene's measure, at c2f-bench-stereo's
own deadlines) averaged over 20 deadlines in [0, the slower run's convergence time]. Then
OUT_DIR/suite.md: per family and size, the medians of the tuning and the aside instances; then
per family and set, over the instances where flat took at least a second (the targets' scope),
the median, the worst instance and the worst from one megapixel against issue 43's targets
(0.4, 1.1, 0.3). `--summarize A/suite.tsv B/suite.tsv` writes suite.md from earlier runs'
tables (say, one family re-run) without measuring.
"""

import argparse
import csv
import math
import subprocess
import sys
import time
import zlib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Dict, List, Optional

import numpy as np

import c2f

# The stereo scaling table's dataset names and its median and number formats ("-", "never").
sys.path.insert(0, str(Path(__file__).resolve().parent / "stereo"))
from scaling_table import dataset as stereo_dataset, median, text  # noqa: E402

STEREO_ASIDE = {"middlebury2014/Recycle", "middlebury2014/PlaytableP", "kitti2015/000001_10"}
GRID_SIZES = {"0.1mp": (320, 320), "0.3mp": (480, 640), "1mp": (1000, 1000), "4mp": (2000, 2000)}
GRID_LABELS = (8, 32, 128)
GRID_TERMS = ("potts", "tl", "tq")
NOISE = {"low": 0.04, "high": 0.12}  # noise sigma as a fraction of the label range
DEADLINES = 20
COLUMNS = ("family instance aside variables labels flat_seconds flat_energy flat_reason "
           "c2f_seconds c2f_energy c2f_reason to_1e4_seconds to_1e3_seconds ratio_1e4 ratio_1e3 "
           "energy_gap error_flat error_c2f flat_moves").split()


def is_aside(family: str, name: str) -> bool:
    """The names-only rule of the module docstring."""
    if family == "stereo":
        return name in STEREO_ASIDE
    return zlib.crc32(name.encode()) % 4 == 0


@dataclass
class Trace:
    """A run's steps: times (s on its clock), energies and, when known, errors."""
    times: np.ndarray
    energies: np.ndarray
    errors: Optional[np.ndarray] = None


@dataclass
class Outcome:
    """One instance measured: the two runs and what the family knows of them."""
    variables: int
    labels: int
    flat: Trace
    c2f: Trace
    flat_seconds: float
    flat_energy: float
    flat_reason: str
    c2f_seconds: float
    c2f_energy: float
    c2f_reason: str
    # The errors at deadlines when the tool measured them itself (stereo), else from the traces.
    deadline_errors: Optional[tuple] = None
    # The baseline's moves: 'same' (the defaults' own) or 'whole' (solve_pair's strongest flat).
    flat_moves: str = "same"


@dataclass
class Instance:
    family: str
    name: str
    size: str  # the row of suite.md it joins (e.g. '0.3mp', 'Middlebury 2014 Q')
    measure: Callable[[], Outcome] = field(repr=False)


def time_to(trace: Trace, target: float) -> float:
    """When the trace first reached `target` or below; infinity when it never did."""
    hit = np.nonzero(trace.energies <= target)[0]
    return float(trace.times[hit[0]]) if len(hit) else math.inf


def band(energy: float, fraction: float) -> float:
    """The energy within `fraction` of `energy` (above it)."""
    return energy + fraction * abs(energy)


def deadline_error(trace: Trace, deadlines: np.ndarray) -> float:
    """The mean error of the latest step before each deadline (NaN without errors; before the
    first step, the first step's)."""
    if trace.errors is None or len(trace.times) == 0:
        return math.nan
    at = np.searchsorted(trace.times, deadlines, side="right") - 1
    return float(np.mean(trace.errors[np.maximum(at, 0)]))


def row_of(instance: Instance, outcome: Outcome) -> Dict[str, object]:
    flat_e = outcome.flat_energy
    to4 = time_to(outcome.c2f, band(flat_e, 1e-4))
    to3 = time_to(outcome.c2f, band(flat_e, 1e-3))
    horizon = max(outcome.flat_seconds, outcome.c2f_seconds)
    deadlines = np.random.default_rng(1).uniform(0.0, horizon, DEADLINES)
    return {
        "family": instance.family, "instance": instance.name,
        "aside": int(is_aside(instance.family, instance.name)),
        "variables": outcome.variables, "labels": outcome.labels,
        "flat_seconds": outcome.flat_seconds, "flat_energy": flat_e,
        "flat_reason": outcome.flat_reason, "flat_moves": outcome.flat_moves,
        "c2f_seconds": outcome.c2f_seconds, "c2f_energy": outcome.c2f_energy,
        "c2f_reason": outcome.c2f_reason,
        "to_1e4_seconds": to4, "to_1e3_seconds": to3,
        "ratio_1e4": to4 / outcome.flat_seconds, "ratio_1e3": to3 / outcome.flat_seconds,
        "energy_gap": (outcome.c2f_energy - flat_e) / abs(flat_e),
        "error_flat": (outcome.deadline_errors[0] if outcome.deadline_errors
                       else deadline_error(outcome.flat, deadlines)),
        "error_c2f": (outcome.deadline_errors[1] if outcome.deadline_errors
                      else deadline_error(outcome.c2f, deadlines)),
    }


# ---------------------------------------------------------------- grid and general families

def noisy_truth(name: str, height: int, width: int, labels: int, noise: float):
    """A piecewise-smooth label map (constant and ramped rectangles, seeded by the name), its
    noisy observation, and robust unaries: min(|observation - label| / sigma, 3)."""
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    truth = np.full((height, width), (labels - 1) / 2.0)
    yy, xx = np.mgrid[0:height, 0:width]
    for _ in range(40):
        y, x = rng.integers(0, height), rng.integers(0, width)
        h, w = rng.integers(height // 10, height // 2), rng.integers(width // 10, width // 2)
        level = rng.uniform(0, labels - 1)
        slope = rng.normal(0, (labels - 1) / (2.0 * max(height, width))) if rng.random() < 0.5 else 0
        patch = (slice(y, y + h), slice(x, x + w))
        truth[patch] = level + slope * ((xx[patch] - x) + (yy[patch] - y))
    truth = np.clip(np.rint(truth), 0, labels - 1)
    sigma = noise * (labels - 1)
    observed = truth + rng.normal(0, sigma, truth.shape)
    unary = np.empty((height, width, labels), np.float32)
    for label in range(labels):  # one label at a time: 4 MP x 128 labels stays in float32
        unary[:, :, label] = np.minimum(np.abs(observed - label) / sigma, 3.0)
    return truth.astype(np.int32), unary


def term_of(kind: str, labels: int):
    """The pairwise term and its weight: a jump costs at most about 1.5 (the unaries' scale)."""
    if kind == "potts":
        return c2f.Term.potts(), 1.5
    reach = max(2.0, labels / 8.0)
    if kind == "tl":
        return c2f.Term.truncated_linear(reach), 1.5 / reach
    return c2f.Term.truncated_quadratic(reach * reach, labels), 1.5 / (reach * reach)


def solve_pair(energy, truth: Optional[np.ndarray], time_limit: float) -> Outcome:
    """Flat with the defaults' moves, then the defaults, on one clock; where the defaults make
    near moves (near_radius > 0, at least near_min_variables variables), flat with whole moves
    as well, before them, and the flat run that converged sooner is the baseline (the strongest
    flat: near moves from their label are what the defaults make after a coarse level, and from
    a noisy start flat is often faster without them). With a truth, the error of every step
    (pixels more than one label from it) is taken in the run's callback, which the run clock
    does not count."""
    def run(schedule, options=None):
        errors: List[float] = []

        def record(event):
            labeling = event["labeling"]
            errors.append(float(np.mean(np.abs(labeling.reshape(truth.shape) - truth) > 1)))

        result = c2f.solve(energy, schedule, options=options, time_limit=time_limit,
                           callback=record if truth is not None else None)
        trace = Trace(np.asarray(result.trace["time"], dtype=float),
                      np.asarray(result.trace["energy"], dtype=float),
                      np.asarray(errors) if truth is not None else None)
        if trace.errors is not None and len(trace.errors) != len(trace.times):
            raise SystemExit(f"suite: {len(trace.errors)} callbacks for {len(trace.times)} steps")
        return result, trace

    flats = [run("flat") + ("same",)]
    defaults = c2f.defaults()
    if defaults["near_radius"] > 0 and energy.num_variables >= defaults["near_min_variables"]:
        flats.append(run("flat", {"near_radius": 0}) + ("whole",))
    flat, flat_trace, flat_moves = min(flats, key=lambda f: f[0].seconds)
    c2f_result, c2f_trace = run(None)
    return Outcome(energy.num_variables, energy.num_labels, flat_trace, c2f_trace,
                   flat.seconds, flat.energy, flat.reason, c2f_result.seconds, c2f_result.energy,
                   c2f_result.reason, flat_moves=flat_moves)


def grid_instances(args) -> List[Instance]:
    out = []
    for size, (height, width) in GRID_SIZES.items():
        for labels in GRID_LABELS:
            if height * width * labels > args.max_size * 1e6:
                continue
            for kind in GRID_TERMS:
                for noise in NOISE:
                    name = f"grid/{size}-{labels}L-{kind}-{noise}"

                    def measure(name=name, height=height, width=width, labels=labels, kind=kind,
                                noise=noise):
                        truth, unary = noisy_truth(name, height, width, labels, NOISE[noise])
                        term, weight = term_of(kind, labels)
                        energy = c2f.Energy.grid(unary, term, weight=weight)
                        del unary
                        return solve_pair(energy, truth, args.time_limit)

                    out.append(Instance("grid", name, size, measure))
    return out


def lattice_graph(rng, height: int, width: int):
    """A 4-connected lattice with a fifth of its edges dropped and 10% more edges joining
    variables up to 5 rows and columns apart: local, but no grid."""
    index = np.arange(height * width).reshape(height, width)
    right = np.stack([index[:, :-1].ravel(), index[:, 1:].ravel()], 1)
    down = np.stack([index[:-1, :].ravel(), index[1:, :].ravel()], 1)
    edges = np.concatenate([right, down])
    edges = edges[rng.random(len(edges)) >= 0.2]
    count = height * width // 10
    y, x = rng.integers(0, height, count), rng.integers(0, width, count)
    dy, dx = rng.integers(-5, 6, count), rng.integers(-5, 6, count)
    y2, x2 = np.clip(y + dy, 0, height - 1), np.clip(x + dx, 0, width - 1)
    extra = np.stack([index[y, x], index[y2, x2]], 1)
    extra = extra[extra[:, 0] != extra[:, 1]]
    return np.concatenate([edges, extra]).astype(np.int64)


def general_instances(args) -> List[Instance]:
    out = []
    for labels, kind in ((8, "potts"), (16, "tl"), (32, "tl")):
        for shape in ((300, 400), (600, 800)):
            name = f"general/lattice-{shape[0] * shape[1] // 1000}k-{labels}L-{kind}"

            def measure(name=name, shape=shape, labels=labels, kind=kind):
                truth, unary = noisy_truth(name, shape[0], shape[1], labels, NOISE["high"])
                rng = np.random.default_rng(zlib.crc32(name.encode()) + 1)
                edges = lattice_graph(rng, *shape)
                term, weight = term_of(kind, labels)
                energy = c2f.Energy(unary.reshape(-1, labels), edges,
                                    np.full(len(edges), weight), term)
                return solve_pair(energy, truth.ravel(), args.time_limit)

            out.append(Instance("general", name, f"{shape[0] * shape[1] // 1000}k", measure))
    for variables in (20000, 100000):
        name = f"general/random-{variables // 1000}k-16L-potts"

        def measure(name=name, variables=variables):
            rng = np.random.default_rng(zlib.crc32(name.encode()))
            unary = rng.uniform(0, 3, (variables, 16)).astype(np.float32)
            edges = rng.integers(0, variables, (2 * variables, 2))
            edges = edges[edges[:, 0] != edges[:, 1]]
            energy = c2f.Energy(unary, edges, np.full(len(edges), 0.6), c2f.Term.potts())
            return solve_pair(energy, None, args.time_limit)

        out.append(Instance("general", name, f"{variables // 1000}k", measure))
    teddy = Path(args.data) / "middlebury/2003/Teddy"
    name = "general/stereo-teddy-85L"

    def measure_teddy():
        views = c2f.read_stereo_pair(str(teddy / "left.png"), str(teddy / "right.png"))
        grid = c2f.stereo_energy(views["left"], views["right"], 85)
        energy = c2f.Energy(grid.unary, grid.edges, grid.weights, tsgo_step_table(85))
        return solve_pair(energy, None, args.time_limit)

    if teddy.is_dir():
        out.append(Instance("general", name, "stereo", measure_teddy))
    else:
        print(f"suite: {name} left out: no {teddy}", file=sys.stderr)
    return out


def tsgo_step_table(labels: int) -> "c2f.Term":
    """TSGO's step term (0, 1/6, 1 for |a - b| = 0, 1, >= 2) as a table: a general energy
    carries one term object, and the grid energy does not hand its term out."""
    gap = np.abs(np.subtract.outer(np.arange(labels), np.arange(labels)))
    return c2f.Term.table(np.where(gap == 0, 0.0, np.where(gap == 1, 1.0 / 6.0, 1.0)))


# ------------------------------------------------------- stereo and segmentation families

def read_trace_csv(path: Path) -> Trace:
    """A trace the benchmark tools write (time_s,level,step,energy,num_vars[,error])."""
    with open(path, newline="") as file:
        rows = list(csv.DictReader(file))
    if not rows:
        raise SystemExit(f"suite: {path}: an empty trace")
    times = np.array([float(r["time_s"]) for r in rows])
    energies = np.array([float(r["energy"]) for r in rows])
    errors = np.array([float(r["error"]) for r in rows]) if "error" in rows[0] else None
    return Trace(times, energies, errors)


def run_tool(command: List[str]) -> Dict[str, str]:
    """Runs a benchmark tool with --header; its rows by the name of the run."""
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"suite: {' '.join(command)} failed ({done.returncode}):\n{done.stderr}")
    lines = [line.split("\t") for line in done.stdout.splitlines() if line.strip()]
    header = lines[0]
    return [dict(zip(header, fields)) for fields in lines[1:]]


def stereo_scenes(data: Path) -> List[str]:
    scenes = []
    with open(data / "scenes.csv", newline="") as file:
        rows = list(csv.DictReader(file))
    scenes += [r["scene"] for r in rows if r["year"] == "2005"]
    scenes += [r["scene"] for r in rows if r["year"] == "2006"][:5]
    scenes += sorted(f"middlebury2014/{p.name}" for p in (data / "middlebury2014").iterdir()
                     if p.is_dir())
    scenes += sorted(f"kitti2015/{p.stem}" for p in
                     (data / "kitti2015/training/image_2").glob("*.png"))
    if Path("/usr/share/doc/opencv-doc/examples/data/aloeL.jpg").exists():
        scenes.append("opencv-doc/aloe")
    return scenes


def stereo_instances(args, tools: Path) -> List[Instance]:
    data = Path(args.data)
    if not (data / "scenes.csv").exists():
        print(f"suite: stereo left out: no {data / 'scenes.csv'}", file=sys.stderr)
        return []
    defaults = c2f.defaults("stereo")
    out = []
    for scene in stereo_scenes(data):
        def measure(scene=scene):
            folder = Path(args.out) / "stereo"
            flags = [f"--schedule={defaults['grid_schedule']}",
                     f"--coarse-tolerance={defaults['plateau_tolerance']}",
                     f"--c2f-near-radius={defaults['near_radius']}",
                     f"--flat-near-radius={defaults['near_radius']}"]
            if defaults["shift_moves"]:
                flags += ["--c2f-shift-moves", "--flat-shift-moves"]
            if defaults["plateau"] == "rate":
                flags += ["--c2f-progress-rate"]
            row = run_tool([str(tools / "c2f-bench-stereo"), "run", scene, "--data", str(data),
                            "--out", str(folder), "--time-limit", str(args.time_limit),
                            "--header"] + flags)[0]
            stem = scene.replace("/", "-")
            return Outcome(int(row["pixels"]), int(row["labels"]),
                           read_trace_csv(folder / f"{stem}-flat.csv"),
                           read_trace_csv(folder / f"{stem}-c2f.csv"),
                           float(row["flat_seconds"]), float(row["flat_energy"]),
                           row["flat_reason"], float(row["c2f_seconds"]),
                           float(row["c2f_energy"]), row["c2f_reason"],
                           # the scene's own measure at the tool's 20 deadlines
                           (float(row["deadline_error_flat"]), float(row["deadline_error_c2f"])))

        out.append(Instance("stereo", scene, stereo_dataset(scene), measure))
    return out


def segmentation_instances(args, tools: Path) -> List[Instance]:
    data = Path(args.data) / "coopcuts"
    if not data.is_dir():
        print(f"suite: segmentation left out: no {data}", file=sys.stderr)
        return []
    segmentation = c2f.defaults("segmentation")
    if segmentation["schedule"] != "superpixels" or segmentation["aux"] != "mm":
        raise SystemExit("suite: the segmentation defaults are no longer c2f-bench-segment's "
                         "c2f-slic-mm-near; name their configuration here")
    out = []
    for set_name, folder in (("multilabel", "runMultilabel"), ("binary", "runBinary/dataset")):
        seeds = sorted(p.stem for p in (data / folder / "seeds").glob("*.png"))
        for image in seeds:
            def measure(set_name=set_name, image=image):
                folder = Path(args.out) / "segmentation"
                # The defaults (c2f-slic-mm-near at the defaults' radius) against the sooner
                # converged of flat with their moves and flat with whole moves.
                rows = run_tool([str(tools / "c2f-bench-segment"), "run", set_name, image,
                                 "--data", args.data, "--out", str(folder), "--time-limit",
                                 str(args.time_limit), "--configs",
                                 "flat-mm,flat-mm-near,c2f-slic-mm-near",
                                 "--near-radius", str(segmentation["near_radius"]), "--header"])
                by = {r["config"]: r for r in rows}
                flat_config, flat_moves = min((("flat-mm-near", "same"), ("flat-mm", "whole")),
                                              key=lambda f: float(by[f[0]]["seconds"]))
                flat, c2f_row = by[flat_config], by["c2f-slic-mm-near"]
                return Outcome(int(flat["pixels"]), int(flat["labels"]),
                               read_trace_csv(folder / f"{image}-{flat_config}.csv"),
                               read_trace_csv(folder / f"{image}-c2f-slic-mm-near.csv"),
                               float(flat["seconds"]), float(flat["coop_energy"]), flat["reason"],
                               float(c2f_row["seconds"]), float(c2f_row["coop_energy"]),
                               c2f_row["reason"], flat_moves=flat_moves)

            out.append(Instance("segmentation", f"{set_name}/{image}", set_name, measure))
    return out


# ------------------------------------------------------------------------ the report

def number(text) -> float:
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def summary(rows: List[Dict[str, str]]) -> str:
    """suite.md: per family and size, the medians of the tuning and of the aside instances."""
    lines = ["| family | size | set | n | ratio to 1e-4 | ratio to 1e-3 | worst to 1e-4 | "
             "never | energy gap | error flat / C2F |", "|" + "---|" * 10]
    groups: Dict[tuple, List[Dict[str, str]]] = {}
    for row in rows:
        groups.setdefault((row["family"], row["size"], row["aside"]), []).append(row)
    for (family, size, aside), members in sorted(groups.items()):
        r4 = [number(r["ratio_1e4"]) for r in members]
        r3 = [number(r["ratio_1e3"]) for r in members]
        gaps = [number(r["energy_gap"]) for r in members]
        errors = (text(median([100 * number(r["error_flat"]) for r in members]), 1) + " / " +
                  text(median([100 * number(r["error_c2f"]) for r in members]), 1))
        lines.append(
            f"| {family} | {size} | {'aside' if aside == '1' else 'tuning'} | {len(members)} | "
            f"{text(median(r4))} | {text(median(r3))} | {text(max(r4))} | "
            f"{sum(math.isinf(v) for v in r4)} | {text(median(gaps), 6)} | {errors} |")
    return "\n".join(lines) + "\n\n" + target_summary(rows)


# Issue 43's targets: the scope (flat converged in at least this many seconds), each family's
# median ratio to 1e-4, every instance's, and that of instances of at least a megapixel.
TARGET_MIN_FLAT_SECONDS = 1.0
TARGET_MEDIAN, TARGET_WORST, TARGET_MEGAPIXEL = 0.4, 1.1, 0.3


def target_summary(rows: List[Dict[str, str]]) -> str:
    """Per family and set, over the instances where flat took at least a second: how many, the
    median ratio to 1e-4, the worst instance, the worst of a megapixel or more, each against its
    target ('ok' or 'missed'); then C2F's own convergence time over flat's (median and worst
    instance; no target: C2F may go on polishing below flat's energy after reaching it)."""
    def verdict(value: float, target: float) -> str:
        return "-" if math.isnan(value) else ("ok" if value <= target else "missed")

    lines = [f"Against the targets (instances where flat took at least "
             f"{TARGET_MIN_FLAT_SECONDS:g} s; median <= {TARGET_MEDIAN}, every instance <= "
             f"{TARGET_WORST}, from 1 MP <= {TARGET_MEGAPIXEL}):", "",
             "| family | set | n (of) | median to 1e-4 | worst to 1e-4 (instance) | "
             "worst from 1 MP | converged C2F / flat: median, worst (instance) |",
             "|" + "---|" * 7]
    groups: Dict[tuple, List[Dict[str, str]]] = {}
    for row in rows:
        groups.setdefault((row["family"], row["aside"]), []).append(row)
    for (family, aside), members in sorted(groups.items()):
        scope = [r for r in members if number(r["flat_seconds"]) >= TARGET_MIN_FLAT_SECONDS]
        ratios = [number(r["ratio_1e4"]) for r in scope]
        middle = median(ratios)
        worst = max(scope, key=lambda r: number(r["ratio_1e4"]), default=None)
        worst_value = number(worst["ratio_1e4"]) if worst else math.nan
        large = [number(r["ratio_1e4"]) for r in scope if number(r["variables"]) >= 1e6]
        large_worst = max(large, default=math.nan)

        def converged(r: Dict[str, str]) -> float:
            return number(r["c2f_seconds"]) / number(r["flat_seconds"])

        slowest = max(scope, key=converged, default=None)
        convergence = (f"{text(median([converged(r) for r in scope]))}, "
                       f"{text(converged(slowest))} ({slowest['instance']})" if slowest else "- -")
        lines.append(
            f"| {family} | {'aside' if aside == '1' else 'tuning'} | {len(scope)} "
            f"({len(members)}) | {text(middle)} {verdict(middle, TARGET_MEDIAN)} | "
            f"{text(worst_value)} {verdict(worst_value, TARGET_WORST)}"
            f"{' (' + worst['instance'] + ')' if worst else ''} | "
            f"{text(large_worst)} {verdict(large_worst, TARGET_MEGAPIXEL)} | {convergence} |")
    return "\n".join(lines) + "\n"


def read_rows(tables: List[Path]) -> List[Dict[str, str]]:
    """The rows of earlier runs' suite.tsv files, in order (a later row of the same instance
    replaces an earlier one)."""
    rows: Dict[str, Dict[str, str]] = {}
    for table in tables:
        with open(table, newline="") as file:
            for row in csv.DictReader(file, delimiter="\t"):
                rows[row["instance"]] = row
    return list(rows.values())


def main(argv: Optional[List[str]] = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default="out/suite", help="folder for suite.tsv, suite.md, traces")
    parser.add_argument("--data", default="../shared/data", help="the shared data root")
    parser.add_argument("--families", default="grid,general,stereo,segmentation",
                        help="comma-separated families to run")
    parser.add_argument("--only", default="", help="run only instances whose name contains this")
    parser.add_argument("--skip", default="",
                        help="run no instance whose name contains this (e.g. opencv-doc/aloe)")
    parser.add_argument("--max-size", type=float, default=32.0,
                        help="grid instances up to this many M pixels x labels (default 32)")
    parser.add_argument("--time-limit", type=float, default=600.0,
                        help="seconds per run (default 600)")
    parser.add_argument("--tools", default="build/release/bench",
                        help="folder of c2f-bench-stereo and c2f-bench-segment")
    parser.add_argument("--list", action="store_true", help="list the instances and stop")
    parser.add_argument("--summarize", nargs="+", metavar="TSV", type=Path,
                        help="measure nothing: write OUT/suite.md from these suite.tsv files "
                             "(a later row of an instance replaces an earlier one)")
    args = parser.parse_args(argv)
    if args.summarize:
        for table in args.summarize:
            if not table.is_file():
                parser.error(f"--summarize: no such file: {table}")
        out = Path(args.out)
        out.mkdir(parents=True, exist_ok=True)
        (out / "suite.md").write_text(summary(read_rows(args.summarize)))
        print(f"suite: medians in {out / 'suite.md'}")
        return 0
    if not args.time_limit > 0 or not math.isfinite(args.time_limit):
        parser.error(f"--time-limit: expected a positive number of seconds, got {args.time_limit}")
    families = [f for f in args.families.split(",") if f]
    known = ("grid", "general", "stereo", "segmentation")
    for family in families:
        if family not in known:
            parser.error(f"--families: unknown family '{family}' (known: {', '.join(known)})")
    tools = Path(args.tools)
    makers = {"grid": lambda: grid_instances(args), "general": lambda: general_instances(args),
              "stereo": lambda: stereo_instances(args, tools),
              "segmentation": lambda: segmentation_instances(args, tools)}
    instances = [i for f in families for i in makers[f]()
                 if args.only in i.name and not (args.skip and args.skip in i.name)]
    if args.list:
        for i in instances:
            print(f"{i.family}\t{i.name}\t{'aside' if is_aside(i.family, i.name) else 'tuning'}")
        return 0
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    table = out / "suite.tsv"
    rows: List[Dict[str, str]] = []
    with open(table, "w", newline="") as file:
        writer = csv.DictWriter(file, fieldnames=COLUMNS + ["size"], delimiter="\t")
        writer.writeheader()
        for number_, instance in enumerate(instances, 1):
            started = time.perf_counter()
            row = row_of(instance, instance.measure())
            row["size"] = instance.size
            writer.writerow(row)
            file.flush()
            rows.append({k: str(v) for k, v in row.items()})
            print(f"[{number_}/{len(instances)}] {instance.name}{' (aside)' if row['aside'] else ''}"
                  f": flat ({row['flat_moves']}) {row['flat_seconds']:.2f} s, "
                  f"to 1e-4 {row['ratio_1e4']:.2f}x, "
                  f"to 1e-3 {row['ratio_1e3']:.2f}x, gap {row['energy_gap']:+.1e} "
                  f"({time.perf_counter() - started:.0f} s)", flush=True)
    (out / "suite.md").write_text(summary(rows))
    print(f"suite: {len(rows)} instances in {table}, medians in {out / 'suite.md'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
