#pragma once
// Iterated conditional modes (ICM) as an AnytimeSolver for PairwiseEnergy: the simplest
// solver, there to exercise the driver and as a baseline.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "c2f/core/anytime_solver.hpp"
#include "c2f/core/edge_incidence.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

enum class VisitOrder { sequential, random };

std::string_view to_string(VisitOrder order);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
VisitOrder visit_order_from_string(std::string_view text);

struct IcmOptions {
  VisitOrder order = VisitOrder::sequential;
  std::uint64_t seed = 1;  ///< for VisitOrder::random
  /// A variable moves only when its local cost drops by more than
  /// min_improvement * max(1, |local cost|); keeps ties from cycling.
  double min_improvement = 1e-12;

  /// Empty when usable, else a message naming the field.
  [[nodiscard]] std::string validate() const;
};

class IcmSolver {
 public:
  /// Throws std::invalid_argument when options.validate() reports a problem.
  explicit IcmSolver(IcmOptions options = {});

  /// Starts from `start` (validated). Builds the adjacency of `energy` (O(N + E)).
  void bind(const PairwiseEnergy& energy, std::span<const Label> start);
  /// One sweep over all variables: each moves to its cheapest label given its neighbours when
  /// that lowers its local cost. Never increases the energy. Returns the energy afterwards.
  double step();

  [[nodiscard]] double energy() const noexcept { return energy_value_; }
  [[nodiscard]] std::span<const Label> labeling() const noexcept { return labeling_; }
  /// Variables that changed label in the last step.
  [[nodiscard]] std::size_t changed_in_last_step() const noexcept { return changed_; }

 private:
  IcmOptions options_;
  const PairwiseEnergy* energy_ = nullptr;
  Labeling labeling_;
  double energy_value_ = 0.0;
  std::size_t changed_ = 0;
  EdgeIncidence incidence_;
  std::vector<VariableIndex> order_;
  std::uint64_t rng_state_ = 0;
};

static_assert(AnytimeSolver<IcmSolver, PairwiseEnergy>);

}  // namespace c2f
