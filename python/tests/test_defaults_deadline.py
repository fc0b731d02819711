"""The defaults ahead of flat at a fixed deadline: a small version of bench/suite.py's synthetic
grids, on a clock of work rather than seconds so that the check cannot depend on the machine.

Work, in visits of a whole move's variables: a move over every variable of a level of n variables
costs n, one pass over the level's graph. A near move (trace 'step_variables' below n) costs
NEAR_PER_FREE per variable it frees, on a graph of its own built for it, plus n / NEAR_SCAN_SHARE
for finding them among the level's labels: on this machine a free variable cost 1.9-5.8 whole-move
variables and the search 0-4% of a whole move (200 x 250 and 550 x 550 grids, Potts, truncated
linear and quadratic), and both constants are above that. Each coarse level also costs the
original problem's N for building its partition and reducing the energy, charged when its first
step starts, and every level's step 0 (its binding) n. The deadline is a third of the work flat
needs to converge; at that point the defaults' energy must be no higher than flat's.
"""

import numpy as np
import pytest

import c2f

NEAR_PER_FREE = 6.0
NEAR_SCAN_SHARE = 16.0


def work_clock(trace, num_variables):
    """The work done when each step of `trace` ended, in variable visits (see the module)."""
    variables = np.asarray(trace["variables"], dtype=float)
    moved = np.asarray(trace["step_variables"], dtype=float)
    steps = np.asarray(trace["step"])
    first_of_level = steps == 0
    coarse = variables < num_variables
    level_cost = np.where(first_of_level & coarse, float(num_variables), 0.0)
    near = (steps > 0) & (moved < variables)
    step_cost = np.where(near, NEAR_PER_FREE * moved + variables / NEAR_SCAN_SHARE, variables)
    return np.cumsum(step_cost + level_cost)


def energy_at(work, energies, deadline, start):
    """The energy of the last step done by `deadline`, or `start` before the first."""
    done = np.nonzero(work <= deadline)[0]
    return energies[done[-1]] if len(done) else start


@pytest.mark.parametrize("labels,kind", [(8, "potts"), (16, "tl"), (16, "tq")])
def test_the_defaults_beat_flat_at_a_third_of_its_work(suite, labels, kind):
    name = f"ci/0.05mp-{labels}L-{kind}"
    height, width = 200, 250
    _, unary = suite.noisy_truth(name, height, width, labels, suite.NOISE["high"])
    term, weight = suite.term_of(kind, labels)
    energy = c2f.Energy.grid(unary, term, weight=weight)
    n = energy.num_variables
    flat = c2f.solve(energy, "flat")
    fine = c2f.solve(energy)
    assert flat.reason == "converged" and fine.reason == "converged"
    start = energy.evaluate(np.argmin(unary, axis=2))
    flat_work = work_clock(flat.trace, n)
    fine_work = work_clock(fine.trace, n)
    deadline = flat_work[-1] / 3.0
    flat_energy = energy_at(flat_work, np.asarray(flat.trace["energy"]), deadline, start)
    fine_energy = energy_at(fine_work, np.asarray(fine.trace["energy"]), deadline, start)
    assert fine_energy <= flat_energy, (
        f"{name}: at {deadline:.3g} variable visits the defaults are at {fine_energy:.6g}, "
        f"flat at {flat_energy:.6g}")
