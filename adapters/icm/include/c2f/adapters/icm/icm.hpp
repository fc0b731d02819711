#pragma once
// Iterated conditional modes (ICM) as an AnytimeSolver for PairwiseEnergy: the simplest
// solver, there to exercise the driver and as a baseline.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "c2f/core/anytime_solver.hpp"
#include "c2f/core/edge_incidence.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/memory_budget.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/core/visit_order.hpp"

namespace c2f {

/// The fields and meanings of MoveOptions (graph-cut solvers), applied to single variables.
struct IcmOptions {
  VisitOrder order = VisitOrder::sequential;  ///< of the variables; frequency does not apply
  std::uint64_t seed = 1;                     ///< for VisitOrder::random
  /// A variable moves only when its local cost drops by more than
  /// tolerance * max(1, |local cost|); the default keeps rounding-level ties from cycling.
  double tolerance = 1e-12;

  /// Empty when usable, else a message naming the field.
  [[nodiscard]] std::string validate() const;
  bool operator==(const IcmOptions&) const = default;
};

/// What IcmSolver with `options` works in on a problem of `size`: its labeling and local costs
/// (16 bytes per variable). std::nullopt when the count overflows.
[[nodiscard]] std::optional<std::size_t> working_memory_bytes(const IcmOptions& options,
                                                              const ProblemSize& size);

class IcmSolver {
 public:
  /// Throws std::invalid_argument when options.validate() reports a problem.
  explicit IcmSolver(IcmOptions options = {});

  /// One step is a sweep over all variables, so one step without a decrease is a fixed point.
  [[nodiscard]] std::size_t quiet_steps_to_converge(
      const PairwiseEnergy& /*energy*/) const noexcept {
    return 1;
  }

  /// Starts from `start` (validated). Builds the adjacency of `energy` (O(N + E)).
  void bind(const PairwiseEnergy& energy, std::span<const Label> start);
  /// One sweep over all variables: each moves to its cheapest label given its neighbours when
  /// that lowers its local cost. Never increases the energy. Returns the energy afterwards.
  double step();

  [[nodiscard]] double energy() const noexcept { return energy_value_; }
  [[nodiscard]] std::span<const Label> labeling() const noexcept { return labeling_; }
  /// What the last step() did: the variables that changed label in it.
  [[nodiscard]] const StepOutcome& last_step() const noexcept { return last_; }

 private:
  IcmOptions options_;
  const PairwiseEnergy* energy_ = nullptr;
  Labeling labeling_;
  double energy_value_ = 0.0;
  StepOutcome last_;
  EdgeIncidence incidence_;
  std::vector<VariableIndex> order_;
  std::uint64_t rng_state_ = 0;
};

static_assert(AnytimeSolver<IcmSolver, PairwiseEnergy>);

}  // namespace c2f
