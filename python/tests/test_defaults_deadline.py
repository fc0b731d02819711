"""The defaults ahead of flat at a fixed deadline: a small version of bench/suite.py's synthetic
grids, on a clock of work rather than seconds so that the check cannot depend on the machine.

Work: a step on a level of n variables costs n (the defaults' pairwise moves are whole moves, one
pass over the level's graph); each coarse level also costs the original problem's N for building
its partition and reducing the energy, charged when its first step starts. Flat's steps all cost
N. The deadline is a third of the work flat needs to converge; at that point the defaults' energy
must be no higher than flat's.
"""

import numpy as np
import pytest

import c2f

def work_clock(trace, num_variables):
    """The work done when each step of `trace` ended, in variable visits (see the module)."""
    levels = np.asarray(trace["level"])
    variables = np.asarray(trace["variables"], dtype=float)
    first_of_level = np.ones(len(levels), dtype=bool)
    first_of_level[1:] = levels[1:] != levels[:-1]
    coarse = variables < num_variables
    level_cost = np.where(first_of_level & coarse, float(num_variables), 0.0)
    return np.cumsum(variables + level_cost)


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
