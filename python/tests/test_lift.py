"""The parts for a loop of one's own: partitions, exact reduction, labelings between levels."""

import numpy as np
import pytest

import c2f


def test_reduction_is_exact_and_transfer_keeps_the_energy(rng):
    energy = c2f.Energy.grid(rng.random((12, 10, 4)), c2f.Term.truncated_linear(2.0), weight=0.6)
    coarse = c2f.partition(energy, "cp:1,1")
    fine = c2f.partition(energy, "cp:2,1")
    assert coarse.shape == (12, 10) and fine.shape == (12, 10)
    # cp:1,1 groups pixels of one best label: every group has a single argmin.
    best = energy.unary.argmin(axis=1).reshape(12, 10)
    for group in np.unique(coarse):
        assert len(np.unique(best[coarse == group])) == 1
    reduced = c2f.reduce(energy, coarse)
    _, first = np.unique(coarse.reshape(-1), return_index=True)
    assert reduced.num_variables == len(first)
    for _ in range(10):
        y = rng.integers(0, 4, reduced.num_variables)
        x = c2f.expand(y, coarse, 4)
        assert x.shape == (12, 10)
        assert reduced.evaluate(y) == pytest.approx(energy.evaluate(x), rel=1e-12)
        z = c2f.transfer(y, coarse, fine, 4)
        assert c2f.reduce(energy, fine).evaluate(z) == pytest.approx(reduced.evaluate(y), rel=1e-12)
        np.testing.assert_array_equal(c2f.expand(z, fine, 4), x)


def test_lift_arguments_are_checked(rng):
    energy = c2f.Energy.grid(rng.random((4, 5, 3)))
    with pytest.raises(ValueError, match="level: expected one level"):
        c2f.partition(energy, "cp:1,1 cp:2,1")
    with pytest.raises(ValueError, match="partition: a partition of the energy's 20 variables"):
        c2f.reduce(energy, np.zeros(19, dtype=int))
    with pytest.raises(ValueError, match=r"labeling: expected a labeling of shape \(2,\)"):
        c2f.expand(np.zeros(3, dtype=int), np.arange(20) % 2, 3)
    with pytest.raises(ValueError):
        c2f.transfer(np.zeros(2, dtype=int), np.arange(20) % 2, np.arange(20) % 3, 3)
    with pytest.raises(ValueError, match="slic levels segment an image"):
        c2f.partition(energy, "slic:2")
