#pragma once
// Internal to ExpansionSolver: moves made region by region, the regions of one colour at once
// on several threads (detail/region_layout.hpp). Installed only because the solver templates
// include it.
//
// A move proposes a label y_i for some variables (b_i = 1 takes y_i, binary_move.hpp's form).
// A region move is made in two phases, the even regions and then the odd ones; in each phase
// the other colour's variables keep their labels, so the move restricted to a region is its
// part of the whole problem with the pairs to held variables folded into its nodes (whole and
// shift moves), or the restricted problem of its freed variables (near moves,
// restricted_problem), and each region's minimum is exact for its variables. A region's result
// is taken when its exact energy change, summed over the terms it touches, is negative (beyond
// the tolerance), so the energy never rises. Regions write only their own variables, and
// results are combined in region order: 1, 2 or 64 threads give the same bits.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "c2f/adapters/graphcut/binary_move.hpp"
#include "c2f/adapters/graphcut/detail/move_state.hpp"
#include "c2f/adapters/graphcut/detail/near_moves.hpp"
#include "c2f/adapters/graphcut/detail/region_layout.hpp"
#include "c2f/adapters/graphcut/move_options.hpp"
#include "c2f/core/edge_incidence.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f::detail {

/// Calls task(i) for every i < count on min(threads, count) threads (0: the machine's cores;
/// the calling thread among them), each once; rethrows the exception of the lowest index that
/// threw after all have ended.
void for_each_region(std::size_t count, const std::function<void(std::size_t)>& task, int threads);

/// A move's binary problem over every variable (node i is variable i, pair e is edge e), and
/// the label each variable would take.
struct MoveProblem {
  std::span<const double> d, p;
  std::function<Label(VariableIndex)> proposal;
};

template <MaxFlow Backend>
class RegionMoves {
 public:
  /// Lays out at most `wanted` regions of `energy` of at least min_variables each
  /// (region_layout); the moves over every variable (whole and shift moves, keys
  /// 0..num_keys-1) recycle the regions' graphs within graph_memory_limit split evenly
  /// between the regions. `threads` as for_each_region. The edge incidences come from `shared`
  /// when given.
  void bind(const PairwiseEnergy& energy, std::size_t wanted, std::size_t num_keys,
            std::size_t graph_memory_limit, int threads,
            std::size_t min_variables = kMinRegionVariables, SharedIncidence* shared = nullptr) {
    energy_ = &energy;
    threads_ = threads;
    layout_ = region_layout(energy, wanted, min_variables);
    regions_ = std::vector<Region>(layout_.count());
    if (!active()) return;
    incidence_ = incidence_of(energy, shared);
    local_.assign(energy.num_variables(), kHeld);
    split_edges();
    for (Region& region : regions_) {
      region.whole_solver.bind(region.size, region.pairs);
      region.whole_solver.recycle(num_keys, graph_memory_limit / regions_.size());
    }
  }

  /// Whether there are at least two regions (else region moves are not made).
  [[nodiscard]] bool active() const noexcept { return layout_.count() >= 2; }
  [[nodiscard]] std::size_t count() const noexcept { return layout_.count(); }
  [[nodiscard]] const RegionLayout& layout() const noexcept { return layout_; }
  /// Bytes of the regions' recycled graphs.
  [[nodiscard]] std::size_t recycled_bytes() const noexcept {
    std::size_t bytes = 0;
    for (const Region& region : regions_) bytes += region.whole_solver.recycled_bytes();
    return bytes;
  }

  /// Frees the regions' graphs (built again on the next move), so that they are not held
  /// beside the graphs of a move over every variable.
  void drop_graphs() {
    for (Region& region : regions_) {
      region.whole_solver.drop_graphs();
      region.subset_solver = BinaryMoveSolver<Backend>{};
    }
  }

  /// One phase of a move over every variable: the regions of colour `colour` (0: even, 1: odd)
  /// solve their parts of `problem` (built from `labeling`) at once, on their graphs of `key`;
  /// see run_phase for the rest.
  void phase(int colour, const MoveProblem& problem, std::size_t key, double tolerance,
             Labeling& labeling, Labeling& candidate, double& value,
             std::vector<VariableIndex>& moved, MoveStep& step) {
    run_phase(colour, tolerance, labeling, candidate, value, moved, step, [&](Region& region) {
      region.d.assign(problem.d.begin() + static_cast<std::ptrdiff_t>(region.begin),
                      problem.d.begin() + static_cast<std::ptrdiff_t>(region.begin + region.size));
      for (const auto& [edge, node] : region.entering) region.d[node] += problem.p[edge];
      region.p.resize(region.inside.size());
      for (std::size_t k = 0; k < region.inside.size(); ++k)
        region.p[k] = problem.p[region.inside[k]];
      region.out.resize(region.size);
      region.stats = region.whole_solver.solve(region.d, region.p, region.out, key);
      for (std::size_t k = 0; k < region.size; ++k) {
        if (region.out[k] != MoveLabel::one) continue;
        const auto v = static_cast<VariableIndex>(region.begin + k);
        const Label y = problem.proposal(v);
        if (y != labeling[v]) propose(region, v, y, candidate);
      }
    });
  }

  /// One phase of a near move to alpha: the regions of colour `colour` solve the move over
  /// their variables that `near` freed (NearMoves::select from the labeling the move began
  /// with, which this phase's variables still have), all others held at their labels in
  /// `labeling`, each on a graph of its own built for it (restricted_problem); see run_phase
  /// for the rest.
  void near_phase(int colour, Label alpha, const NearMoves& near, double tolerance,
                  Labeling& labeling, Labeling& candidate, double& value,
                  std::vector<VariableIndex>& moved, MoveStep& step) {
    run_phase(colour, tolerance, labeling, candidate, value, moved, step, [&](Region& region) {
      region.nodes.clear();
      for (std::size_t i = region.begin; i < region.begin + region.size; ++i) {
        const auto v = static_cast<VariableIndex>(i);
        if (!near.is_free(v, alpha, labeling)) continue;
        local_[v] = static_cast<std::uint32_t>(region.nodes.size());
        region.nodes.push_back(v);
      }
      if (region.nodes.empty()) return;
      restricted_problem(*energy_, *incidence_, alpha, labeling, region.nodes, local_, region.d,
                         region.p, region.subset_pairs);
      for (const VariableIndex v : region.nodes) local_[v] = kHeld;
      region.subset_solver.bind(region.nodes.size(), region.subset_pairs);
      region.out.resize(region.nodes.size());
      region.stats = region.subset_solver.solve(region.d, region.p, region.out);
      for (std::size_t k = 0; k < region.nodes.size(); ++k)
        if (region.out[k] == MoveLabel::one) propose(region, region.nodes[k], alpha, candidate);
    });
  }

 private:
  /// A region: its variables [begin, begin + size); the edges inside it (their indices, and
  /// their endpoints numbered from begin) and the edges entering it from a variable before it
  /// or after it (edge index, its v end numbered from begin), whose p is added to that end's
  /// d when the other end is held: with b_u = 0, p (1 - b_u) b_v is p b_v; its solvers and the
  /// current phase's work.
  struct Region {
    std::size_t begin = 0, size = 0;
    std::vector<std::size_t> inside;
    std::vector<FlowEdge> pairs;
    std::vector<std::pair<std::size_t, FlowNode>> entering;
    BinaryMoveSolver<Backend> whole_solver;   // every variable: fixed topology, recycled graphs
    BinaryMoveSolver<Backend> subset_solver;  // near moves: bound per move
    std::vector<VariableIndex> nodes;         // near moves: the freed variables
    std::vector<FlowEdge> subset_pairs;
    std::vector<double> d, p;
    std::vector<MoveLabel> out;
    std::vector<VariableIndex> changed;
    BinaryMoveStats stats;
    double delta = 0.0;
    bool taken = false;
  };

  /// Sorts the energy's edges into the regions' inside and entering edges.
  void split_edges() {
    for (std::size_t r = 0; r < regions_.size(); ++r) {
      regions_[r].begin = layout_.bounds[r];
      regions_[r].size = layout_.bounds[r + 1] - layout_.bounds[r];
    }
    const auto edges = energy_->edges();
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const Edge& edge = edges[e];
      Region& region = regions_[layout_.region_of[edge.v]];
      const auto v = static_cast<FlowNode>(edge.v - region.begin);
      if (layout_.region_of[edge.u] == layout_.region_of[edge.v]) {
        region.inside.push_back(e);
        region.pairs.push_back({static_cast<FlowNode>(edge.u - region.begin), v});
      } else {
        region.entering.push_back({e, v});
      }
    }
  }

  static void propose(Region& region, VariableIndex v, Label y, Labeling& candidate) {
    candidate[v] = y;
    region.changed.push_back(v);
  }

  /// Runs solve(region) for the regions of `colour` at once (each proposes changes into
  /// `candidate` within its variables), then takes each region's proposal into `labeling` when
  /// its exact energy change is below -acceptance_margin(tolerance, value): adds the changed
  /// variables to `moved` (in region order), the changes taken to `value` and the solver statistics
  /// to `step`. `candidate` equals `labeling` before and after.
  template <class Solve>
  void run_phase(int colour, double tolerance, Labeling& labeling, Labeling& candidate,
                 double& value, std::vector<VariableIndex>& moved, MoveStep& step,
                 const Solve& solve) {
    const double margin = acceptance_margin(tolerance, value);
    const auto first = static_cast<std::size_t>(colour);
    const std::size_t tasks = (regions_.size() - first + 1) / 2;
    for_each_region(
        tasks,
        [&](std::size_t t) {
          Region& region = regions_[first + 2 * t];
          region.changed.clear();
          region.stats = {};
          solve(region);
          take_if_lower(region, margin, labeling, candidate);
        },
        threads_);
    for (std::size_t r = first; r < regions_.size(); r += 2) {
      const Region& region = regions_[r];
      step.flow_seconds += region.stats.flow_seconds;
      step.unlabeled += region.stats.unlabeled;
      step.used_qpbo |= region.stats.used_qpbo;
      step.recycled |= region.stats.recycled;
      if (!region.taken) continue;
      value += region.delta;
      moved.insert(moved.end(), region.changed.begin(), region.changed.end());
    }
  }

  /// Takes the region's proposal into `labeling` when it lowers the energy by more than
  /// `margin`, else withdraws it from `candidate`.
  void take_if_lower(Region& region, double margin, Labeling& labeling, Labeling& candidate) const {
    region.delta = energy_change(region.changed, labeling, candidate);
    region.taken = !region.changed.empty() && region.delta < -margin;
    for (const VariableIndex v : region.changed) {
      if (region.taken) {
        labeling[v] = candidate[v];
      } else {
        candidate[v] = labeling[v];
      }
    }
    if (!region.taken) region.changed.clear();
  }

  /// E(candidate) - E(labeling) where they differ only at `changed`, summed over the terms of
  /// those variables in a fixed order.
  [[nodiscard]] double energy_change(std::span<const VariableIndex> changed,
                                     const Labeling& labeling, const Labeling& candidate) const {
    const PairwiseEnergy& energy = *energy_;
    const auto edges = energy.edges();
    double delta = 0.0;
    for (const VariableIndex v : changed) {
      delta += energy.unary(v, candidate[v]) - energy.unary(v, labeling[v]);
      for (const Incidence& inc : incidence_->of(v)) {
        // An edge between two changed variables is counted once, from its u.
        if (!inc.is_first && candidate[inc.other] != labeling[inc.other]) continue;
        const Edge& edge = edges[inc.edge];
        delta += energy.pairwise_cost(edge, candidate[edge.u], candidate[edge.v]) -
                 energy.pairwise_cost(edge, labeling[edge.u], labeling[edge.v]);
      }
    }
    return delta;
  }

  const PairwiseEnergy* energy_ = nullptr;
  int threads_ = 1;
  RegionLayout layout_;
  std::shared_ptr<const EdgeIncidence> incidence_;
  std::vector<std::uint32_t> local_;  // near moves: a freed variable's node, else kHeld
  std::vector<Region> regions_;
};

}  // namespace c2f::detail
