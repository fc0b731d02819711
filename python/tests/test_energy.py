"""Energies from numpy: evaluate() is the energy's formula, grids have the edges they say."""

import itertools

import numpy as np
import pytest

import c2f


def formula(unary, edges, weights, cost, labeling):
    """E(x) computed directly in numpy."""
    n = unary.shape[0]
    value = unary[np.arange(n), labeling].sum()
    for (u, v), w in zip(edges, weights):
        value += w * cost(labeling[u], labeling[v])
    return value


def test_general_energy_evaluates_its_formula(rng):
    unary = rng.random((7, 4))
    edges = np.array([[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 6], [0, 6], [1, 5]])
    weights = rng.random(len(edges))
    table = rng.random((4, 4))
    energy = c2f.Energy(unary, edges, weights, c2f.Term.table(table))
    assert (energy.num_variables, energy.num_labels, energy.num_edges) == (7, 4, 8)
    for _ in range(20):
        x = rng.integers(0, 4, 7)
        assert energy.evaluate(x) == pytest.approx(
            formula(unary, edges, weights, lambda a, b: table[a, b], x), rel=1e-12)
    np.testing.assert_array_equal(energy.unary, unary)
    np.testing.assert_array_equal(energy.edges, edges)
    np.testing.assert_array_equal(energy.weights, weights)


@pytest.mark.parametrize("connectivity", [4, 8])
def test_grid_energy_has_the_neighbour_edges(rng, connectivity):
    h, w, labels = 3, 4, 3
    unary = rng.random((h, w, labels)).astype(np.float32)
    per_pixel = connectivity // 2
    weights = rng.random((h, w, per_pixel))
    energy = c2f.Energy.grid(unary, c2f.Term.truncated_linear(2.0), weight=weights,
                             connectivity=connectivity)
    assert energy.shape == (h, w)
    offsets = [(0, 1), (1, 0), (1, 1), (1, -1)][:per_pixel]
    expected_edges, expected_weights = [], []
    for y in range(h):
        for x in range(w):
            for k, (dy, dx) in enumerate(offsets):
                if 0 <= y + dy < h and 0 <= x + dx < w:
                    expected_edges.append((y * w + x, (y + dy) * w + x + dx))
                    expected_weights.append(weights[y, x, k])
    np.testing.assert_array_equal(energy.edges, np.array(expected_edges))
    np.testing.assert_allclose(energy.weights, expected_weights)
    x = rng.integers(0, labels, (h, w))
    flat_unary = unary.reshape(-1, labels).astype(np.float64)
    assert energy.evaluate(x) == pytest.approx(
        formula(flat_unary, expected_edges, expected_weights, lambda a, b: min(abs(a - b), 2.0),
                x.reshape(-1)), rel=1e-12)
    assert energy.evaluate(x) == energy.evaluate(x.reshape(-1))


def test_truncated_quadratic_is_a_table():
    term = c2f.Term.truncated_quadratic(5.0, 4)
    assert term.kind == "table"
    for a, b in itertools.product(range(4), repeat=2):
        assert term.cost(a, b) == min((a - b) ** 2, 5.0)


def test_uai_round_trip(rng, tmp_path):
    unary = rng.random((5, 3))
    edges = np.array([[0, 1], [1, 2], [3, 4]])
    energy = c2f.Energy(unary, edges, np.array([0.5, 1.0, 2.0]), c2f.Term.potts())
    path = tmp_path / "model.uai"
    energy.write_uai(str(path))
    again = c2f.Energy.read_uai(str(path))
    # Each factor's potentials are written scaled (a constant per factor), so the energies agree
    # up to one constant: the same differences between labelings, the same minimisers.
    offsets = []
    for _ in range(10):
        x = rng.integers(0, 3, 5)
        offsets.append(again.evaluate(x) - energy.evaluate(x))
    np.testing.assert_allclose(offsets, offsets[0], atol=1e-9)


def test_float32_costs_stay_float32_and_solve_as_their_float64_copy(rng):
    unary32 = rng.random((20, 24, 6)).astype(np.float32)
    term = c2f.Term.truncated_linear(2.0)
    single = c2f.Energy.grid(unary32, term, weight=0.4)
    double = c2f.Energy.grid(unary32.astype(np.float64), term, weight=0.4)
    assert single.unary.dtype == np.float32 and double.unary.dtype == np.float64
    np.testing.assert_array_equal(single.unary, double.unary)
    general = c2f.Energy(unary32.reshape(-1, 6), single.edges, single.weights, term)
    assert general.unary.dtype == np.float32
    # Every energy and reduction sums the same values in double: the same run, step for step.
    for schedule in ["flat", "paper"]:
        a, b = c2f.solve(single, schedule), c2f.solve(double, schedule)
        np.testing.assert_array_equal(a.labeling, b.labeling)
        np.testing.assert_array_equal(a.trace["energy"], b.trace["energy"])
    x = rng.integers(0, 6, (20, 24))
    assert single.evaluate(x) == double.evaluate(x)


def test_grid_weight_is_a_number_or_one_per_pixel_and_neighbour(rng):
    unary = rng.random((3, 4, 2))
    with pytest.raises(ValueError, match=r"weight: expected a number or an array of shape \(3, 4, 2\)"):
        c2f.Energy.grid(unary, weight=np.ones((3, 4, 1)))
    with pytest.raises(TypeError, match="weight: expected a real number, got str"):
        c2f.Energy.grid(unary, weight="heavy")
    per_edge = c2f.Energy.grid(unary, weight=np.full((3, 4, 2), 0.5))
    np.testing.assert_array_equal(per_edge.weights, c2f.Energy.grid(unary, weight=0.5).weights)
