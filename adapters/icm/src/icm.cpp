#include "c2f/adapters/icm/icm.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <stdexcept>
#include "c2f/support/memory_need.hpp"

namespace c2f {

std::string IcmOptions::validate() const {
  if (!std::isfinite(tolerance) || tolerance < 0.0) return "tolerance must be finite and >= 0";
  if (order == VisitOrder::frequency) {
    return "order 'frequency' orders labels, and ICM visits variables (use sequential or random)";
  }
  return {};
}

std::optional<std::size_t> working_memory_bytes(const IcmOptions& /*options*/,
                                                const ProblemSize& size) {
  return checked_product({size.variables, 16});
}

IcmSolver::IcmSolver(IcmOptions options) : options_(options), rng_state_(options.seed) {
  if (const std::string problem = options_.validate(); !problem.empty()) {
    throw std::invalid_argument("IcmOptions: " + problem);
  }
}

void IcmSolver::bind(const PairwiseEnergy& energy, std::span<const Label> start) {
  validate_labeling(start, energy.num_variables(), energy.num_labels(), "IcmSolver::bind: start");
  energy_ = &energy;
  labeling_.assign(start.begin(), start.end());
  const std::size_t n = energy.num_variables();
  incidence_ = EdgeIncidence(energy);
  order_.resize(n);
  for (std::size_t v = 0; v < n; ++v) order_[v] = static_cast<VariableIndex>(v);
  energy_value_ = energy.evaluate_unchecked(labeling_);
  last_ = {};
}

double IcmSolver::step() {
  if (energy_ == nullptr) throw std::logic_error("IcmSolver::step: call bind() first");
  const PairwiseEnergy& energy = *energy_;
  const auto edges = energy.edges();
  const int num_labels = energy.num_labels();
  if (options_.order == VisitOrder::random) {
    std::mt19937_64 rng(rng_state_++);
    std::shuffle(order_.begin(), order_.end(), rng);
  }
  std::size_t changed = 0;
  for (const VariableIndex v : order_) {
    auto local_cost = [&](Label l) {
      double cost = energy.unary(v, l);
      for (const Incidence& inc : incidence_.of(v)) {
        const Edge& e = edges[inc.edge];
        const Label other = labeling_[inc.other];
        cost +=
            inc.is_first ? energy.pairwise_cost(e, l, other) : energy.pairwise_cost(e, other, l);
      }
      return cost;
    };
    const Label current = labeling_[v];
    const double current_cost = local_cost(current);
    double best_cost = current_cost;
    Label best = current;
    for (Label l = 0; l < num_labels; ++l) {
      if (l == current) continue;
      const double cost = local_cost(l);
      if (cost < best_cost) {
        best_cost = cost;
        best = l;
      }
    }
    const double margin = options_.tolerance * std::max(1.0, std::abs(current_cost));
    if (best != current && current_cost - best_cost > margin) {
      labeling_[v] = best;
      ++changed;
    }
  }
  // Recomputed exactly (O(N + E), small next to the sweep): every accepted move lowered the
  // energy, so this never exceeds the previous value beyond summation rounding.
  const double before = energy_value_;
  energy_value_ = energy.evaluate_unchecked(labeling_);
  last_.changed = changed;
  last_.improved = energy_value_ < before;
  return energy_value_;
}

}  // namespace c2f
