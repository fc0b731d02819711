// c2f.Term and c2f.Energy: pairwise terms and energies built from numpy arrays, evaluated, read
// and written as UAI.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "c2f/core/grid.hpp"
#include "c2f/core/uai.hpp"
#include "memory_argument.hpp"
#include "model_energy.hpp"
#include "numpy_input.hpp"
#include "released_gil.hpp"

namespace c2f::python {

namespace py = pybind11;

namespace {

PairwiseTerm truncated_linear(const py::handle& truncation_argument) {
  const double truncation = real_argument(truncation_argument, "truncation");
  if (truncation <= 0) throw py::value_error("truncation: expected a finite number > 0");
  return PairwiseTerm::truncated_linear(truncation);
}

PairwiseTerm truncated_quadratic(const py::handle& truncation_argument,
                                 const py::handle& labels_argument) {
  const double truncation = real_argument(truncation_argument, "truncation");
  if (truncation <= 0) throw py::value_error("truncation: expected a finite number > 0");
  const int num_labels =  // a table of L^2 costs: 128 MiB at 4096 labels
      static_cast<int>(integer_argument(labels_argument, "num_labels", 1, 4096));
  std::vector<double> costs(static_cast<std::size_t>(num_labels) * num_labels);
  for (int a = 0; a < num_labels; ++a)
    for (int b = 0; b < num_labels; ++b)
      costs[static_cast<std::size_t>(a) * num_labels + b] =
          std::min(static_cast<double>((a - b) * (a - b)), truncation);
  return PairwiseTerm::table(num_labels, std::move(costs));
}

PairwiseTerm table_term(const py::handle& object) {
  RealArray costs = float_values(object, "costs", 2, "(L, L)");
  if (costs.shape[0] != costs.shape[1]) {
    throw py::value_error("costs: expected a square array (L, L), got shape " +
                          shape_text(costs.shape));
  }
  return PairwiseTerm::table(static_cast<int>(costs.shape[0]), std::move(costs.values));
}

ModelEnergy general_energy(const py::handle& unary_object, const py::handle& edges_object,
                           const py::handle& weights_object, const PairwiseTerm& term) {
  CostArray unary = cost_array(unary_object, "unary", 2, "(N, L)");
  const std::size_t n = static_cast<std::size_t>(unary.shape[0]);
  const int labels = static_cast<int>(unary.shape[1]);
  std::vector<Edge> edges;
  if (!edges_object.is_none()) {
    const py::array raw = array_argument(edges_object, "edges", "an integer array of shape (E, 2)");
    if (raw.ndim() == 2 && raw.shape(0) == 0 && raw.shape(1) == 2) {
      // No edge: a unary-only energy.
    } else {
      const auto pairs = integer_array(edges_object, "edges", 2, "(E, 2)");
      if (pairs.shape(1) != 2)
        throw py::value_error("edges: expected shape (E, 2), got shape " + shape_text(pairs));
      const std::size_t count = static_cast<std::size_t>(pairs.shape(0));
      std::vector<double> weights(count, 1.0);
      if (!weights_object.is_none()) {
        RealArray given = float_values(weights_object, "weights", 1, "(E,)");
        if (given.values.size() != count) {
          throw py::value_error("weights: expected shape (" + std::to_string(count) +
                                ",), one per edge, got shape " + shape_text(given.shape));
        }
        weights = std::move(given.values);
      }
      edges.reserve(count);
      for (std::size_t e = 0; e < count; ++e) {
        const std::int64_t u = pairs.data()[2 * e], v = pairs.data()[2 * e + 1];
        if (u < 0 || v < 0 || static_cast<std::size_t>(u) >= n ||
            static_cast<std::size_t>(v) >= n) {
          throw py::value_error("edges: edge " + std::to_string(e) + " (" + std::to_string(u) +
                                ", " + std::to_string(v) + ") names a variable outside [0, " +
                                std::to_string(n - 1) + "]");
        }
        if (u == v) {
          throw py::value_error("edges: edge " + std::to_string(e) + " joins variable " +
                                std::to_string(u) + " to itself");
        }
        edges.push_back(
            Edge{static_cast<VariableIndex>(u), static_cast<VariableIndex>(v), weights[e], 0});
      }
    }
  } else if (!weights_object.is_none()) {
    throw py::value_error("weights: given without edges");
  }
  const ReleasedGil free;
  if (unary.single_precision) {
    return ModelEnergy{PairwiseEnergy::with_float_unaries(n, labels, std::move(unary.floats),
                                                          {term}, std::move(edges)),
                       {}};
  }
  return ModelEnergy{PairwiseEnergy(n, labels, std::move(unary.doubles), {term}, std::move(edges)),
                     {}};
}

ModelEnergy grid(const py::handle& unary_object, const PairwiseTerm& term,
                 const py::handle& weight_argument, const py::handle& connectivity_argument) {
  const auto connectivity =
      static_cast<int>(integer_argument(connectivity_argument, "connectivity", 4, 8));
  if (connectivity != 4 && connectivity != 8)
    throw py::value_error("connectivity: expected 4 or 8, got " + std::to_string(connectivity));
  // One weight for every edge (a number), or one per pixel and neighbour (an array).
  const bool per_edge = py::isinstance<py::array>(weight_argument) ||
                        py::isinstance<py::list>(weight_argument) ||
                        py::isinstance<py::tuple>(weight_argument);
  const double weight = per_edge ? 0.0 : real_argument(weight_argument, "weight");
  CostArray unary = cost_array(unary_object, "unary", 3, "(H, W, L)");
  const py::ssize_t height = unary.shape[0], width = unary.shape[1];
  const int labels = static_cast<int>(unary.shape[2]);
  RealArray weights;
  if (per_edge) {
    const std::string shape = "(H, W, " + std::to_string(connectivity / 2) + ")";
    weights = float_values(weight_argument, "weight", 3, shape);
    if (weights.shape != std::vector<py::ssize_t>{height, width, connectivity / 2}) {
      throw py::value_error("weight: expected a number or an array of shape (" +
                            std::to_string(height) + ", " + std::to_string(width) + ", " +
                            std::to_string(connectivity / 2) + ") for a " +
                            std::to_string(connectivity) + "-connected grid (right, down" +
                            (connectivity == 8 ? ", down-right, down-left" : "") + "), got shape " +
                            shape_text(weights.shape));
    }
  }
  const GridShape shape{static_cast<std::size_t>(width), static_cast<std::size_t>(height)};
  const double* given = weights.values.empty() ? nullptr : weights.values.data();
  const std::size_t per_pixel = static_cast<std::size_t>(connectivity / 2);
  // The edge (u, v) to the k-th neighbour of u: right, down, down-right, down-left.
  const auto edge_weight = [&](VariableIndex u, VariableIndex v) {
    if (given == nullptr) return weight;
    const bool right = v == u + 1 && v / shape.width == u / shape.width;
    const bool down = v == u + shape.width;
    const std::size_t k = right ? 0 : down ? 1 : v == u + shape.width + 1 ? 2 : 3;
    return given[u * per_pixel + k];
  };
  const Connectivity neighbours = connectivity == 8 ? Connectivity::eight : Connectivity::four;
  const ReleasedGil free;
  if (unary.single_precision) {
    return ModelEnergy{
        PairwiseEnergy::with_float_unaries(shape.size(), labels, std::move(unary.floats), {term},
                                           grid_edges(shape, neighbours, edge_weight)),
        {height, width}};
  }
  return ModelEnergy{
      make_grid_energy(shape, neighbours, labels, std::move(unary.doubles), term, edge_weight),
      {height, width}};
}

}  // namespace

void bind_energy(py::module_& module) {
  py::class_<PairwiseTerm>(module, "Term",
                           "A pairwise cost of two labels, shared by edges and scaled by each "
                           "edge's weight.")
      .def_static("potts", &PairwiseTerm::potts, "cost(a, b) = 0 if a == b else 1.")
      .def_static("truncated_linear", &truncated_linear, py::arg("truncation"),
                  "cost(a, b) = min(|a - b|, truncation); truncation > 0.")
      .def_static("truncated_quadratic", &truncated_quadratic, py::arg("truncation"),
                  py::arg("num_labels"),
                  "cost(a, b) = min((a - b)^2, truncation), as a num_labels x num_labels table.")
      .def_static("table", &table_term, py::arg("costs"),
                  "cost(a, b) = costs[a, b] for a float (L, L) array of finite costs.")
      .def_property_readonly(
          "kind", [](const PairwiseTerm& term) { return std::string(to_string(term.kind())); },
          "'potts', 'truncated_linear', 'tsgo_step' or 'table'.")
      .def_property_readonly("truncation", &PairwiseTerm::truncation,
                             "The truncation of a truncated-linear term (0 otherwise).")
      .def(
          "cost",
          [](const PairwiseTerm& term, const py::handle& a, const py::handle& b) {
            const int limit = term.table_labels();
            const long long highest = limit > 0 ? limit - 1 : INT32_MAX;
            return term.cost(static_cast<Label>(integer_argument(a, "a", 0, highest)),
                             static_cast<Label>(integer_argument(b, "b", 0, highest)));
          },
          py::arg("a"), py::arg("b"), "The cost of labels a and b.")
      .def("__repr__", [](const PairwiseTerm& term) {
        return "c2f.Term." + std::string(to_string(term.kind())) +
               (term.kind() == TermKind::truncated_linear
                    ? "(" + std::to_string(term.truncation()) + ")"
                : term.kind() == TermKind::table
                    ? "(<" + std::to_string(term.table_labels()) + "x" +
                          std::to_string(term.table_labels()) + " table>)"
                    : "()");
      });

  py::class_<ModelEnergy>(module, "Energy",
                          "E(x) = sum_v unary[v, x_v] + sum_e weight_e * term(x_u, x_v).")
      .def(py::init(&general_energy), py::arg("unary"), py::arg("edges") = py::none(),
           py::arg("weights") = py::none(), py::arg("term") = PairwiseTerm::potts(),
           "A general energy: unary (N, L) float costs, edges (E, 2) integer variable pairs, "
           "weights (E,) (default 1), one pairwise term on every edge.")
      .def_static("grid", &grid, py::arg("unary"), py::arg("term") = PairwiseTerm::potts(),
                  py::arg("weight") = 1.0, py::arg("connectivity") = 4,
                  "A grid energy: unary (H, W, L) float costs (float32 kept in single "
                  "precision); `term` on the edges to the right and down neighbours (and "
                  "down-right, down-left when connectivity is 8), each of weight `weight`: a "
                  "number, or an array of shape (H, W, connectivity / 2) whose [y, x, k] weighs "
                  "the edge to the k-th neighbour of (y, x). Labelings come back as (H, W).")
      .def_static(
          "read_uai",
          [](const std::string& path, const py::handle& memory) {
            const MemoryBudget budget = memory_budget_from(memory);
            const ReleasedGil free;  // a slow disk or a large model stalls no other thread
            return ModelEnergy{read_uai_file(path, budget), {}};
          },
          py::arg("path"), py::arg("memory") = py::none(),
          "A pairwise MARKOV model in the UAI format (energy = -ln potential). The path must be "
          "a regular file; `memory` is the budget in GiB (None: the default) that the file and the "
          "costs its declarations imply must fit before they are read (ValueError naming the "
          "file otherwise).")
      .def(
          "write_uai",
          [](const ModelEnergy& model, const std::string& path) {
            const ReleasedGil free;
            write_uai_file(model.energy, path);
          },
          py::arg("path"), "Writes the energy as a UAI MARKOV model (potentials exp(-cost)).")
      .def(
          "evaluate",
          [](const ModelEnergy& model, const py::handle& labeling) {
            return model.energy.evaluate(labeling_from(labeling, "labeling",
                                                       model.energy.num_variables(),
                                                       model.energy.num_labels(), model.shape));
          },
          py::arg("labeling"), "E(labeling) for a labeling of shape (N,) or the grid's (H, W).")
      .def_property_readonly("num_variables",
                             [](const ModelEnergy& m) { return m.energy.num_variables(); })
      .def_property_readonly("num_labels",
                             [](const ModelEnergy& m) { return m.energy.num_labels(); })
      .def_property_readonly("num_edges",
                             [](const ModelEnergy& m) { return m.energy.edges().size(); })
      .def_property_readonly(
          "shape",
          [](const ModelEnergy& m) -> py::object {
            if (m.shape.empty()) return py::none();
            return py::make_tuple(m.shape[0], m.shape[1]);
          },
          "(H, W) for a grid energy, None for a general one.")
      .def_property_readonly(
          "unary",
          [](const ModelEnergy& m) -> py::array {
            const std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(m.energy.num_variables()),
                                                 static_cast<py::ssize_t>(m.energy.num_labels())};
            return m.energy.unaries().visit([&](auto costs) -> py::array {
              using Cost = std::remove_const_t<typename decltype(costs)::element_type>;
              py::array_t<Cost> out(shape);
              std::copy(costs.begin(), costs.end(), out.mutable_data());
              return out;
            });
          },
          "A copy of the unary costs, (N, L), in the precision they are stored in: float32 for "
          "an energy built from float32 costs (and the TSGO energy), else float64.")
      .def_property_readonly(
          "edges",
          [](const ModelEnergy& m) {
            const auto edges = m.energy.edges();
            py::array_t<std::int64_t> out({static_cast<py::ssize_t>(edges.size()), py::ssize_t{2}});
            for (std::size_t e = 0; e < edges.size(); ++e) {
              out.mutable_data()[2 * e] = edges[e].u;
              out.mutable_data()[2 * e + 1] = edges[e].v;
            }
            return out;
          },
          "A copy of the edges' variable pairs, (E, 2).")
      .def_property_readonly(
          "weights",
          [](const ModelEnergy& m) {
            const auto edges = m.energy.edges();
            py::array_t<double> out(static_cast<py::ssize_t>(edges.size()));
            for (std::size_t e = 0; e < edges.size(); ++e) out.mutable_data()[e] = edges[e].weight;
            return out;
          },
          "A copy of the edges' weights, (E,).")
      .def("__repr__", [](const ModelEnergy& m) {
        return "<c2f.Energy: " + std::to_string(m.energy.num_variables()) + " variables" +
               (m.shape.empty() ? ""
                                : " (" + std::to_string(m.shape[0]) + "x" +
                                      std::to_string(m.shape[1]) + " grid)") +
               ", " + std::to_string(m.energy.num_labels()) + " labels, " +
               std::to_string(m.energy.edges().size()) + " edges>";
      });
}

}  // namespace c2f::python
