"""Solving from Python: optimal where it must be, every solver and schedule consistent, the same
result as the command-line tool on the same model."""

import itertools
import os
import subprocess

import numpy as np
import pytest

import c2f


def brute_force_minimum(energy):
    n, labels = energy.num_variables, energy.num_labels
    return min(energy.evaluate(np.array(x)) for x in itertools.product(range(labels), repeat=n))


def test_two_label_potts_is_solved_exactly(rng):
    # Two labels and a non-negative Potts term: one expansion move is a minimum cut, exact.
    for _ in range(5):
        energy = c2f.Energy.grid(rng.random((3, 4, 2)), c2f.Term.potts(), weight=0.4)
        result = c2f.solve(energy)
        assert result.energy == pytest.approx(brute_force_minimum(energy), abs=1e-9)


def test_table_energy_is_no_worse_than_a_local_minimum_and_reports_its_own_energy(rng):
    table = rng.random((3, 3))
    table = table + table.T
    np.fill_diagonal(table, 0.0)
    energy = c2f.Energy(rng.random((6, 3)), np.array([[0, 1], [1, 2], [2, 3], [3, 4], [4, 5]]),
                        term=c2f.Term.table(table))
    best = brute_force_minimum(energy)
    for method in ["expansion", "swap", "icm", "lbp"]:
        result = c2f.solve(energy, method=method)
        assert result.energy == pytest.approx(energy.evaluate(result.labeling), abs=1e-12)
        assert result.energy >= best - 1e-12


@pytest.mark.parametrize("method", ["expansion", "swap", "icm"])
@pytest.mark.parametrize("schedule", ["flat", "paper", "cp:2,1/cc flat", "agg:1/cc"])
def test_move_solvers_never_raise_the_energy(rng, method, schedule):
    energy = c2f.Energy.grid(rng.random((20, 24, 5)), c2f.Term.truncated_linear(2.0), weight=0.3)
    result = c2f.solve(energy, schedule, method=method)
    trace = result.trace
    assert len(trace["energy"]) == result.steps + 1 or len(trace["energy"]) >= result.steps
    assert np.all(np.diff(trace["energy"]) <= 1e-9 * np.abs(trace["energy"][:-1]).max())
    assert trace["energy"][-1] == pytest.approx(result.energy, rel=1e-12)
    assert result.energy == pytest.approx(energy.evaluate(result.labeling), rel=1e-12)
    assert result.reason == "converged"
    assert result.labeling.shape == (20, 24)
    if schedule != "flat":
        assert trace["variables"][0] < 20 * 24  # started on a coarse level
    assert trace["variables"][-1] == 20 * 24


def test_own_partitions_as_a_schedule(rng):
    energy = c2f.Energy.grid(rng.random((8, 8, 3)), c2f.Term.potts(), weight=0.2)
    blocks4 = (np.arange(8)[:, None] // 4) * 2 + np.arange(8)[None, :] // 4
    blocks2 = (np.arange(8)[:, None] // 2) * 4 + np.arange(8)[None, :] // 2
    result = c2f.solve(energy, [blocks4, blocks2])
    assert list(np.unique(result.trace["variables"])) == [4, 16, 64]
    assert result.energy == pytest.approx(energy.evaluate(result.labeling))


def test_limits_and_a_callback_that_stops(rng):
    energy = c2f.Energy.grid(rng.random((30, 30, 6)), c2f.Term.potts(), weight=0.5)
    assert c2f.solve(energy, max_steps=2).reason == "step_limit"
    seen = []

    def stop_at_three(step):
        seen.append(step)
        return step["step"] < 3

    result = c2f.solve(energy, callback=stop_at_three)
    assert result.reason == "observer"
    assert [s["step"] for s in seen] == [0, 1, 2, 3]
    assert set(seen[0]) == {"time", "level", "step", "energy", "variables", "step_variables",
                            "at_original", "labeling"}
    assert [s["step_variables"] for s in seen] == [0] + [s["variables"] for s in seen[1:]]
    assert seen[-1]["labeling"].shape == (30, 30)
    np.testing.assert_array_equal(seen[-1]["labeling"], result.labeling)


def test_the_callback_sees_each_steps_labeling_on_coarse_levels_too(rng):
    """On a coarse level the step's labeling is the original variables' labeling it stands for:
    its energy is the step's energy."""
    energy = c2f.Energy.grid(rng.random((16, 16, 4)), c2f.Term.potts(), weight=0.4)
    steps = []
    c2f.solve(energy, "paper", callback=lambda step: steps.append(step))
    assert not steps[0]["at_original"] and steps[-1]["at_original"]
    for step in steps:
        assert step["labeling"].shape == (16, 16)
        assert energy.evaluate(step["labeling"]) == pytest.approx(step["energy"], rel=1e-12)


def test_a_callback_exception_is_raised_with_the_result(rng):
    energy = c2f.Energy.grid(rng.random((10, 10, 4)), c2f.Term.potts(), weight=0.5)

    def fail(step):
        if step["step"] == 2:
            raise RuntimeError("from the callback")

    with pytest.raises(RuntimeError, match="from the callback") as caught:
        c2f.solve(energy, callback=fail)
    assert caught.value.result.energy == pytest.approx(
        energy.evaluate(caught.value.result.labeling))


def test_same_result_as_c2f_solve(rng, tmp_path):
    build = os.environ.get("C2F_BUILD_DIR")
    if not build:
        pytest.skip("C2F_BUILD_DIR is not set (ctest sets it): no c2f-solve to compare with")
    energy = c2f.Energy.grid(rng.random((12, 16, 5)), c2f.Term.truncated_linear(3.0), weight=0.7)
    model = tmp_path / "model.uai"
    energy.write_uai(str(model))
    subprocess.run([os.path.join(build, "examples/solve/c2f-solve"), str(model), "-o",
                    str(tmp_path / "out"), "--schedule", "paper", "-q"], check=True)
    words = (tmp_path / "out" / "labeling.mpe").read_text().split()
    assert words[0] == "MPE" and int(words[1]) == energy.num_variables
    cli = np.array([int(w) for w in words[2:]])
    read = c2f.Energy.read_uai(str(model))
    result = c2f.solve(read, "paper")
    np.testing.assert_array_equal(result.labeling, cli)
    summary = (tmp_path / "out" / "summary.txt").read_text()
    assert f"final energy {result.energy:.6f}" in summary


def test_a_run_starts_from_a_labeling_of_ones_own(rng):
    energy = c2f.Energy.grid(rng.random((10, 12, 4)), c2f.Term.potts(), weight=0.5)
    start = rng.integers(0, 4, (10, 12))
    result = c2f.solve(energy, "flat", start=start, method="icm")
    assert result.trace["energy"][0] == pytest.approx(energy.evaluate(start), rel=1e-12)
    assert result.energy <= energy.evaluate(start)
    with pytest.raises(ValueError, match="start: labels must lie in"):
        c2f.solve(energy, start=np.full((10, 12), 4))
    with pytest.raises(ValueError, match="start: expected a labeling of shape"):
        c2f.solve(energy, start=np.zeros(7, dtype=int))


def test_the_defaults_are_the_librarys_and_c2f_solve_runs_the_same(rng, tmp_path):
    """c2f.solve with nothing named runs c2f.defaults(): the same run as naming every value,
    and the same labeling as c2f-solve with no flags (on a grid, and on a general graph)."""
    defaults = c2f.defaults()
    assert set(defaults) == {"grid_schedule", "local_schedule", "general_schedule",
                             "near_radius", "near_seeds",
                             "grid_near_seeds", "near_graphs", "near_min_variables",
                             "shift_moves", "plateau", "plateau_steps", "plateau_tolerance",
                             "grid_plateau_tolerance"}
    energy = c2f.Energy.grid(rng.random((12, 16, 5)), c2f.Term.truncated_linear(3.0), weight=0.7)
    implicit = c2f.solve(energy)
    explicit = c2f.solve(energy, defaults["grid_schedule"], plateau=defaults["plateau"],
                         plateau_tolerance=defaults["grid_plateau_tolerance"],
                         options={"near_radius": defaults["near_radius"],
                                  "near_seeds": defaults["grid_near_seeds"],
                                  "near_graphs": defaults["near_graphs"],
                                  "near_min_variables": defaults["near_min_variables"],
                                  "shift_moves": defaults["shift_moves"]})
    np.testing.assert_array_equal(implicit.trace["energy"], explicit.trace["energy"])
    assert implicit.trace["level"].max() > 0  # coarse to fine, not flat

    build = os.environ.get("C2F_BUILD_DIR")
    if not build:
        pytest.skip("C2F_BUILD_DIR is not set (ctest sets it): no c2f-solve to compare with")
    model = tmp_path / "model.uai"
    energy.write_uai(str(model))
    # Off a grid the schedule goes with the edges: a 12 x 16 grid's edges are not local in 4
    # bands of 3 rows (a seventh join bands), a 64 x 40 grid's are (1 in 45).
    lattice = c2f.Energy.grid(rng.random((64, 40, 5)), c2f.Term.truncated_linear(3.0), weight=0.7)
    lattice_model = tmp_path / "lattice.uai"
    lattice.write_uai(str(lattice_model))
    lattice_graph = c2f.Energy.read_uai(str(lattice_model))  # no grid shape
    runs = ((model, ["--grid", "16x12"], energy, "grid_schedule"),
            (model, [], c2f.Energy.read_uai(str(model)), "general_schedule"),
            (lattice_model, [], lattice_graph, "local_schedule"))
    for path, grid, read, schedule in runs:
        out = tmp_path / schedule
        subprocess.run([os.path.join(build, "examples/solve/c2f-solve"), str(path), "-o",
                        str(out), "-q", *grid], check=True)
        cli = np.array([int(w) for w in (out / "labeling.mpe").read_text().split()[2:]])
        result = c2f.solve(read)
        np.testing.assert_array_equal(result.labeling.reshape(-1), cli)
        assert f"schedule {defaults[schedule]}" in (out / "summary.txt").read_text()
        tolerance = defaults["grid_plateau_tolerance" if grid else "plateau_tolerance"]
        named = c2f.solve(read, defaults[schedule], plateau_tolerance=tolerance)
        np.testing.assert_array_equal(result.trace["energy"], named.trace["energy"])
        np.testing.assert_array_equal(result.trace["variables"], named.trace["variables"])
    # There the local schedule's coarse level (three rounds of neighbours: two keep more than
    # 15% of these random unaries' variables as groups) is coarser than the general one's.
    local = c2f.solve(lattice_graph)
    general = c2f.solve(lattice_graph, defaults["general_schedule"])
    assert local.trace["variables"][0] < general.trace["variables"][0]


def test_the_defaults_make_shift_moves_where_an_expansion_move_is_not_submodular(rng):
    """shift_moves 'auto': on a truncated-quadratic energy (not a metric) the defaults run as
    shift_moves=True, on a truncated-linear one as shift_moves=False, flat and coarse to fine."""
    assert c2f.defaults()["shift_moves"] == "auto"
    unary = rng.random((14, 18, 6))
    quadratic = c2f.Energy.grid(unary, c2f.Term.truncated_quadratic(4.0, 6), weight=0.3)
    linear = c2f.Energy.grid(unary, c2f.Term.truncated_linear(2.0), weight=0.3)
    for energy, shifts in ((quadratic, True), (linear, False)):
        for schedule in (None, "flat"):
            automatic = c2f.solve(energy, schedule)
            named = c2f.solve(energy, schedule, options={"shift_moves": shifts})
            np.testing.assert_array_equal(automatic.trace["energy"], named.trace["energy"])
            np.testing.assert_array_equal(automatic.labeling, named.labeling)
            assert automatic.summary.rstrip().endswith("with shift moves") == shifts
    with pytest.raises(TypeError, match=r"options\['shift_moves'\]: expected True, False or 'auto'"):
        c2f.solve(linear, options={"shift_moves": "on"})


def test_near_moves_from_their_label_end_where_no_whole_move_helps(rng):
    energy = c2f.Energy.grid(rng.random((40, 50, 5)), c2f.Term.truncated_linear(2.0), weight=0.6)
    near = c2f.solve(energy, "flat", options={"near_radius": 2, "near_seeds": "label"})
    assert near.reason == "converged"
    assert np.all(np.diff(near.trace["energy"]) <= 0.0)
    # Converged means a sweep of whole moves found nothing: a whole-move run from there agrees.
    whole = c2f.solve(energy, "flat", start=near.labeling)
    assert whole.energy == pytest.approx(near.energy, rel=1e-12)
    assert c2f.defaults("stereo")["near_seeds"] == "label_and_cheapest"
    with pytest.raises(ValueError, match=r"options\['near_seeds'\]"):
        c2f.solve(energy, options={"near_radius": 2, "near_seeds": "cheapest"})
    # The trace says how many variables each near move freed: fewer than the level's.
    freed = near.trace["step_variables"][1:]
    assert np.all(freed <= energy.num_variables) and np.any(freed < energy.num_variables)
    assert near.trace["step_variables"][0] == 0


def test_near_moves_from_the_labels_next_to_theirs_end_where_no_whole_move_helps(rng):
    """'label_and_adjacent' (the pairwise defaults' seeds): on 16 labels or more, without shift
    moves, a near move also frees the variables of the labels next to its own."""
    ramp = np.add.outer(np.arange(40), np.arange(50)) * 19 // 88  # labels 0..19 in steps
    unary = np.abs(np.arange(20)[None, None, :] - ramp[:, :, None]) / 4.0
    unary = (unary + rng.random((40, 50, 20))).astype(np.float32)
    energy = c2f.Energy.grid(unary, c2f.Term.truncated_linear(4.0), weight=0.3)
    near = c2f.solve(energy, "flat", options={"near_radius": 2, "near_seeds": "label_and_adjacent"})
    assert near.reason == "converged"
    assert np.all(np.diff(near.trace["energy"]) <= 0.0)
    assert ("solve: near moves of radius 2 from their label and the labels next to it (whole "
            "moves where they stall)" in near.summary)
    whole = c2f.solve(energy, "flat", start=near.labeling)
    assert whole.energy == pytest.approx(near.energy, rel=1e-12)
    # Where they do not apply (shift moves; fewer than 16 labels) the summary names the seeds
    # used: the label's own.
    shifted = c2f.solve(energy, "flat", max_steps=3, options={
        "near_radius": 2, "near_seeds": "label_and_adjacent", "shift_moves": True})
    assert ("solve: near moves of radius 2 from their label (whole moves where they stall)"
            in shifted.summary)
    few = c2f.Energy.grid(unary[:, :, :8], c2f.Term.truncated_linear(4.0), weight=0.3)
    few_labels = c2f.solve(few, "flat", max_steps=3,
                           options={"near_radius": 2, "near_seeds": "label_and_adjacent"})
    assert ("solve: near moves of radius 2 from their label (whole moves where they stall)"
            in few_labels.summary)
    assert c2f.defaults()["grid_near_seeds"] == "label_and_adjacent"
    assert c2f.defaults()["near_seeds"] == "label"  # on lattices they did not pay
    assert c2f.defaults("stereo")["grid_near_seeds"] == c2f.defaults("stereo")["near_seeds"]


def test_near_moves_only_where_the_edges_are_local(rng):
    """near_graphs 'local': near moves on a grid, whole moves on a random graph (where a few
    rounds of neighbours reach nearly every variable), step for step as without near moves."""
    assert c2f.defaults()["near_graphs"] == "local"
    assert c2f.defaults("stereo")["near_graphs"] == "any"
    local = {"near_radius": 2, "near_seeds": "label", "near_graphs": "local"}
    grid = c2f.Energy.grid(rng.random((40, 50, 5)), c2f.Term.truncated_linear(2.0), weight=0.6)
    on_grid = c2f.solve(grid, "flat", options=local)
    assert np.any(on_grid.trace["step_variables"] < grid.num_variables)
    assert "solve: near moves of radius 2 from their label (whole moves where" in on_grid.summary
    n = 2000
    edges = rng.integers(0, n, size=(4000, 2))
    edges = edges[edges[:, 0] != edges[:, 1]]
    graph = c2f.Energy(rng.random((n, 5)), edges, np.full(len(edges), 0.5), c2f.Term.potts())
    asked = c2f.solve(graph, "flat", options=local)
    whole = c2f.solve(graph, "flat", options={"near_radius": 0})
    np.testing.assert_array_equal(asked.trace["energy"], whole.trace["energy"])
    assert np.all(asked.trace["step_variables"][1:] == n)
    assert "near moves" not in asked.summary
    with pytest.raises(ValueError, match=r"options\['near_graphs'\]: unknown energies for near"):
        c2f.solve(grid, options={"near_radius": 2, "near_graphs": "grids"})


def test_near_moves_only_on_energies_of_the_size_asked(rng):
    """near_min_variables: whole moves, step for step, on an energy below the size; near moves
    at or above it. The defaults' size floor belongs to their near moves: near_radius named
    alone makes near moves at any size."""
    defaults = c2f.defaults()
    assert defaults["near_radius"] > 0 and defaults["near_min_variables"] > 0
    assert c2f.defaults("stereo")["near_min_variables"] == 0
    grid = c2f.Energy.grid(rng.random((40, 50, 5)), c2f.Term.truncated_linear(2.0), weight=0.6)
    n = grid.num_variables
    near = {"near_radius": 2, "near_seeds": "label"}
    below = c2f.solve(grid, "flat", options={**near, "near_min_variables": n + 1})
    whole = c2f.solve(grid, "flat", options={"near_radius": 0})
    np.testing.assert_array_equal(below.trace["energy"], whole.trace["energy"])
    assert np.all(below.trace["step_variables"][1:] == n)
    assert "near moves" not in below.summary
    at = c2f.solve(grid, "flat", options={**near, "near_min_variables": n})
    named_alone = c2f.solve(grid, "flat", options=near)
    assert np.any(at.trace["step_variables"] < n)
    np.testing.assert_array_equal(at.trace["energy"], named_alone.trace["energy"])
    # With nothing named, this small grid gets the defaults' whole moves.
    implicit = c2f.solve(grid, "flat")
    np.testing.assert_array_equal(implicit.trace["energy"], whole.trace["energy"])
    with pytest.raises(ValueError, match=r"options\['near_min_variables'\]: has no effect"):
        c2f.solve(grid, options={"near_radius": 0, "near_min_variables": 10})
    with pytest.raises(ValueError, match=r"options\['near_min_variables'\]"):
        c2f.solve(grid, options={"near_min_variables": -1})


def test_plateau_rate_can_only_leave_a_coarse_level_sooner(rng):
    """plateau='rate' (the pairwise defaults') adds the progress-rate rule to the plateau rule:
    the first level follows the same steps until either rule fires, so it never takes more
    steps; a number of steps alone turns the rule off."""
    energy = c2f.Energy.grid(rng.random((40, 50, 8)), c2f.Term.truncated_linear(2.0), weight=0.6)
    assert c2f.defaults()["plateau"] == "rate"
    plain = c2f.solve(energy, "paper", plateau=c2f.defaults()["plateau_steps"])
    rated = c2f.solve(energy, "paper", plateau="rate")
    by_default = c2f.solve(energy, "paper")
    def first(result):  # steps on the first (coarsest) level
        return int(np.sum(result.trace["level"] == 0))

    assert first(by_default) == first(rated)
    assert first(rated) <= first(plain)
    n = first(rated)
    np.testing.assert_array_equal(rated.trace["energy"][:n], plain.trace["energy"][:n])
    energies = rated.trace["energy"]  # the level switches: equal up to rounding
    assert rated.reason == "converged"
    assert np.all(np.diff(energies) <= 1e-9 * np.abs(energies[:-1]))
    with pytest.raises(ValueError, match="plateau: expected None, 'rate' or a number of steps"):
        c2f.solve(energy, plateau="sweep")


def assert_same_converged_bits(energy, runs):
    """Runs of one energy on different thread counts: the same labeling and trace to the bit,
    converged, the reported energy that of the labeling."""
    for run in runs[1:]:
        assert np.array_equal(run.labeling, runs[0].labeling)
        assert np.array_equal(run.trace["energy"], runs[0].trace["energy"])
    assert runs[0].reason == "converged"
    assert runs[0].energy == energy.evaluate(runs[0].labeling)


def test_the_solve_gives_the_same_bits_on_one_thread_and_on_several(rng):
    # 160 x 110 pixels: near moves by 4 bands of rows (ExpansionOptions::regions), two of a
    # colour at once.
    energy = c2f.Energy.grid(rng.random((160, 110, 6)), c2f.Term.truncated_linear(2.0),
                             weight=0.4)
    runs = [c2f.solve(energy, "flat", options={"near_radius": 2, "shift_moves": True,
                                                "regions": 16, "threads": threads})
            for threads in (1, 2, 3)]
    assert "solve: moves by 4 regions on 1 thread" in runs[0].summary
    assert "solve: moves by 4 regions on 2 threads" in runs[2].summary
    assert_same_converged_bits(energy, runs)
    assert np.all(np.diff(runs[0].trace["energy"]) <= 0.0)
    # One band and one part: every move on one thread. By default the max-flow is in 4 parts.
    label = {"near_radius": 2, "near_seeds": "label"}
    one = c2f.solve(energy, "flat", options={**label, "flow_parts": 1})
    assert ("solve: near moves of radius 2 from their label (whole moves where they stall) on one "
            "thread" in one.summary)
    default = c2f.solve(energy, "flat", options={**label, "threads": 2})
    assert ("solve: near moves of radius 2 from their label (whole moves where they stall), "
            "max-flow in 4 parts on 2 threads" in default.summary)
    with pytest.raises(ValueError, match="regions"):
        c2f.solve(energy, options={"regions": 0})
    with pytest.raises(ValueError, match="no effect without near_radius"):
        c2f.solve(energy, options={"regions": 16, "near_radius": 0})
    with pytest.raises(ValueError, match="threads"):
        c2f.solve(energy, options={"threads": -1})


def test_loopy_bp_in_bands_gives_the_same_bits_on_one_thread_and_on_several(rng):
    # 160 x 110 pixels in bands of 4096 variables (the floor of the default): 5 bands.
    energy = c2f.Energy.grid(rng.random((160, 110, 5)), c2f.Term.potts(), weight=0.3)
    runs = [c2f.solve(energy, "flat", method="lbp", options={"schedule": "bands"},
                      threads=threads, max_steps=15)
            for threads in (1, 2, 3)]
    assert "solve: BP messages by bands of 4096 variables on 1 thread" in runs[0].summary
    assert "solve: BP messages by bands of 4096 variables on 3 threads" in runs[2].summary
    for run in runs[1:]:
        assert np.array_equal(run.labeling, runs[0].labeling)
        assert np.array_equal(run.trace["energy"], runs[0].trace["energy"])
    assert runs[0].energy == energy.evaluate(runs[0].labeling)
    assert np.all(np.diff(runs[0].trace["energy"]) <= 0.0)
    sequential = c2f.solve(energy, "flat", method="lbp", options={"schedule": "sequential"},
                           max_steps=3)
    assert "solve: BP messages in variable order on one thread" in sequential.summary
    small = c2f.solve(energy, "flat", method="lbp",
                      options={"schedule": "bands", "band_variables": 2000, "threads": 2},
                      max_steps=3)
    assert "solve: BP messages by bands of 2000 variables on 2 threads" in small.summary
    with pytest.raises(ValueError, match="band_variables"):
        c2f.solve(energy, method="lbp", options={"band_variables": 0})
    with pytest.raises(ValueError, match="only expansion and lbp"):
        c2f.solve(energy, method="swap", threads=2)


def test_the_max_flow_in_parts_gives_the_same_bits_on_one_thread_and_on_several(rng):
    # 160 x 110 pixels: whole moves' max-flow in 4 bands of rows (ExpansionOptions::flow_parts).
    energy = c2f.Energy.grid(rng.random((160, 110, 6)), c2f.Term.truncated_quadratic(4.0, 6),
                             weight=0.4)
    runs = [c2f.solve(energy, options={"flow_parts": 4, "threads": threads})
            for threads in (1, 2, 3)]
    assert ("solve: every move over every variable, max-flow in 4 parts on 1 thread"
            in runs[0].summary)
    assert "max-flow in 4 parts on 2 threads with shift moves" in runs[1].summary
    assert_same_converged_bits(energy, runs)
    serial = c2f.solve(energy, options={"flow_parts": 1})
    assert runs[0].energy == pytest.approx(serial.energy, rel=1e-4)
    for bad in (-1, 256):
        with pytest.raises(ValueError, match="flow_parts"):
            c2f.solve(energy, options={"flow_parts": bad})
    with pytest.raises(ValueError, match="only our max-flow"):
        c2f.solve(energy, options={"flow_parts": 4, "maxflow": "boost"})


def test_near_moves_in_parts_and_the_threads_argument(rng):
    # 320 x 220 pixels with near moves: their max-flow in parts too, and their problems by bands.
    energy = c2f.Energy.grid(rng.random((320, 220, 8)), c2f.Term.truncated_linear(2.0),
                             weight=0.4)
    options = {"flow_parts": 4, "near_radius": 2}
    runs = [c2f.solve(energy, "flat", options=options, threads=threads) for threads in (1, 2, 3)]
    assert "max-flow in 4 parts on 1 thread" in runs[0].summary
    assert "max-flow in 4 parts on 2 threads" in runs[1].summary
    assert_same_converged_bits(energy, runs)
    assert np.all(np.diff(runs[0].trace["energy"]) <= 0.0)
    with pytest.raises(ValueError, match="given as well as options"):
        c2f.solve(energy, options={"threads": 1}, threads=2)
    with pytest.raises(ValueError, match="only expansion"):
        c2f.solve(energy, method="icm", threads=2)
