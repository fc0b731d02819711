#include "c2f/adapters/graphcut/move_options.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "c2f/core/edge_incidence.hpp"
#include "c2f/support/enum_names.hpp"
#include "c2f/support/memory_need.hpp"
#include "c2f/support/text_input.hpp"

namespace c2f {

std::string_view to_string(NearSeeds seeds) {
  switch (seeds) {
    case NearSeeds::label_and_cheapest:
      return "label_and_cheapest";
    case NearSeeds::label:
      return "label";
    case NearSeeds::label_and_adjacent:
      return "label_and_adjacent";
  }
  return "unknown";
}

NearSeeds near_seeds_from_string(std::string_view text) {
  constexpr NearSeeds kAll[] = {NearSeeds::label_and_cheapest, NearSeeds::label,
                                NearSeeds::label_and_adjacent};
  return enum_from_string(text, kAll, "near-move seeds");
}

std::string near_moves_text(int radius, NearSeeds seeds, SeedsAs as) {
  std::string text = "near moves of radius " + std::to_string(radius);
  if (seeds == NearSeeds::label) text += " from their label";
  if (seeds == NearSeeds::label_and_adjacent) {
    text += as == SeedsAs::in_use
                ? " from their label and the labels next to it"
                : " from their label and, on " + std::to_string(kMinLabelsForAdjacentSeeds) +
                      " labels or more without shift moves, the labels next to it";
  }
  return text;
}

std::string_view near_graphs_name(bool only_if_local) {
  return only_if_local ? "local" : "any";
}

bool near_only_if_local_from_string(std::string_view text) {
  if (text == "local") return true;
  if (text == "any") return false;
  throw std::invalid_argument("unknown energies for near moves '" + printable(text) +
                              "' (expected local or any)");
}

std::string MoveOptions::validate() const {
  if (!std::isfinite(tolerance) || tolerance < 0.0) return "tolerance must be finite and >= 0";
  return {};
}

std::string ExpansionOptions::validate() const {
  if (std::string problem = MoveOptions::validate(); !problem.empty()) return problem;
  if (near_radius < 0) return "near_radius must be >= 0";
  if (!std::isfinite(near_sweep_gain) || near_sweep_gain < 0.0)
    return "near_sweep_gain must be finite and >= 0";
  if (regions < 1 || regions > 65535) return "regions must be in [1, 65535]";
  if (threads < 0) return "threads must be >= 0";
  if (flow_parts < 0 || flow_parts > 255) return "flow_parts must be in [0, 255]";
  return {};
}

double share_of_edges_between_parts(const PairwiseEnergy& energy, std::size_t parts) {
  const std::span<const Edge> edges = energy.edges();
  const std::size_t n = energy.num_variables();
  if (edges.empty() || parts < 2 || n == 0) return 0.0;
  std::size_t between = 0;
  for (const Edge& edge : edges) {
    between += static_cast<std::size_t>(edge.u) * parts / n !=
               static_cast<std::size_t>(edge.v) * parts / n;
  }
  return static_cast<double>(between) / static_cast<double>(edges.size());
}

bool edges_local(const PairwiseEnergy& energy) {
  return share_of_edges_between_parts(energy, kDefaultFlowParts) <= kMaxShareBetweenParts;
}

bool makes_near_moves(const ExpansionOptions& options, const PairwiseEnergy& energy) {
  return options.near_radius > 0 && energy.num_variables() >= options.near_moves_min_variables &&
         (!options.near_moves_only_if_local || edges_local(energy));
}

bool expansion_moves_submodular(const PairwiseEnergy& energy) {
  for (const Edge& edge : energy.edges()) {
    if (edge.weight < 0.0) return false;
  }
  const auto labels = static_cast<Label>(energy.num_labels());
  for (const PairwiseTerm& term : energy.terms()) {
    for (Label a = 0; a < labels; ++a) {
      const double stay = term.cost(a, a);
      for (Label b = 0; b < labels; ++b) {
        const double b_to_a = term.cost(b, a);
        for (Label c = 0; c < labels; ++c) {
          if (stay + term.cost(b, c) > b_to_a + term.cost(a, c)) return false;
        }
      }
    }
  }
  return true;
}

bool makes_shift_moves(const ExpansionOptions& options, const PairwiseEnergy& energy) {
  return options.shift_moves ||
         (options.shift_moves_unless_submodular && !expansion_moves_submodular(energy));
}

NearSeeds near_seeds_in_use(const ExpansionOptions& options, const PairwiseEnergy& energy) {
  if (options.near_seeds != NearSeeds::label_and_adjacent) return options.near_seeds;
  const bool adjacent =
      energy.num_labels() >= kMinLabelsForAdjacentSeeds && !makes_shift_moves(options, energy);
  return adjacent ? NearSeeds::label_and_adjacent : NearSeeds::label;
}

std::optional<std::size_t> move_solver_bytes(const ProblemSize& size, GraphStorage storage) {
  const std::size_t scale = storage == GraphStorage::adjacency_lists ? 2 : 1;
  const auto nodes = checked_product({size.variables, 300 * scale});
  const auto arcs = checked_product({size.edges, 240 * scale});
  if (!nodes || !arcs) return std::nullopt;
  return *nodes + *arcs;
}

std::optional<std::size_t> working_memory_bytes(const ExpansionOptions& options,
                                                const ProblemSize& size, GraphStorage storage) {
  // With regions, the regions' solvers are as large together as one over every variable, and
  // a sweep of whole moves over every variable frees them first (and they its graphs).
  const auto one = move_solver_bytes(size, storage);
  const bool second =
      options.near_radius > 0 || options.shift_moves || options.shift_moves_unless_submodular;
  const auto solvers =
      one ? checked_product({*one, second ? std::size_t{2} : std::size_t{1}}) : one;
  // The edge incidences each move's exact energy is tallied with (EnergyTally).
  const auto offsets = checked_product({size.variables, sizeof(std::size_t)});
  const auto incidences = checked_product({size.edges, 2 * sizeof(Incidence)});
  if (!solvers || !offsets || !incidences) return std::nullopt;
  return checked_sum({*solvers, *offsets, *incidences});
}

std::optional<std::size_t> working_memory_bytes(const SwapOptions& /*options*/,
                                                const ProblemSize& size, GraphStorage storage) {
  return move_solver_bytes(size, storage);
}

namespace {

std::optional<std::size_t> graphs_bytes(std::size_t moves, const ProblemSize& size,
                                        GraphStorage storage) {
  const auto one = move_solver_bytes(size, storage);
  return one ? checked_product({*one, moves}) : one;
}

std::size_t label_count(const ProblemSize& size) {
  return static_cast<std::size_t>(std::max(size.labels, 0));
}

/// Whether `options` make near moves and keep no move graphs with them (recycled_graph_limit).
bool near_moves_keep_no_graphs(const ExpansionOptions& options) noexcept {
  return options.near_radius > 0 && !options.recycle_with_near_moves;
}

}  // namespace

std::optional<std::size_t> kept_problem_bytes(const ExpansionOptions& /*options*/,
                                              const ProblemSize& size) {
  return checked_product(
      {label_count(size),
       checked_sum({size.variables, size.edges}).value_or(static_cast<std::size_t>(-1)),
       sizeof(double)});
}

std::size_t recycled_graph_limit(const ExpansionOptions& options) noexcept {
  return near_moves_keep_no_graphs(options) ? 0 : options.graph_memory_limit;
}

std::optional<std::size_t> wanted_graph_bytes(const ExpansionOptions& options,
                                              const ProblemSize& size, GraphStorage storage) {
  if (near_moves_keep_no_graphs(options)) return std::size_t{0};
  return graphs_bytes(label_count(size), size, storage);
}

std::optional<std::size_t> wanted_graph_bytes(const SwapOptions& /*options*/,
                                              const ProblemSize& size, GraphStorage storage) {
  const std::size_t labels = label_count(size);
  return graphs_bytes(labels * (labels + 1) / 2, size, storage);
}

}  // namespace c2f
