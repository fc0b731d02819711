#pragma once
// The segmentation application's run: a SegmentationProblem (cooperative and Potts energies of
// one image and its seeds) minimised over a schedule's levels by cooperative cuts or by the
// Potts baseline, within one memory budget, with segmentation's coarse-level plateau. c2f-segment,
// c2f.segment and the segmentation benches run it.

#include <optional>
#include <string>
#include <string_view>

#include "c2f/adapters/coop/coop_solver.hpp"
#include "c2f/core/memory_budget.hpp"
#include "c2f/driver/observer.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "c2f/run/run_config.hpp"
#include "c2f/vision/segmentation/segmentation_energy.hpp"

namespace c2f::vision {

/// Which energy a segmentation run minimises.
enum class SegmentationMethod {
  coop,   ///< the cooperative cut (CoopSolver)
  potts,  ///< the Potts baseline on the same data (alpha-expansion)
};

std::string_view to_string(SegmentationMethod method);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
SegmentationMethod segmentation_method_from_string(std::string_view text);

struct SegmentationRunConfig {
  SegmentationMethod method = SegmentationMethod::coop;
  CoopSolverOptions coop;  ///< the cooperative cut's solver (method coop; its threads: below)
  /// Threads of the solve (0: the machine's cores): the cooperative cut's expansions (it
  /// replaces coop.threads) or the Potts baseline's moves. The result is the same for every
  /// count.
  int threads = 0;
  /// Steps without decrease that end a coarse level: k > 0 that many; 0 the number of labels,
  /// or one sweep of the solver when that is shorter; -1 one sweep (coarse_plateau_steps).
  int plateau = 0;
  /// On the original problem: steps without decrease that end the run (0: the solver's own
  /// convergence).
  int final_plateau = 0;
  double time_limit_seconds = 0.0;  ///< on the run clock (0: none)
  long max_total_steps = 0;         ///< over all levels (0: none)
  /// The bytes the whole run may take, the Potts energy kept beside a cooperative run included;
  /// unset: the machine's default.
  std::optional<MemoryBudget> memory = std::nullopt;

  /// Empty when usable, else "<field>: <problem>".
  [[nodiscard]] std::string validate() const;
};

/// Minimises problem.coop (or problem.potts) over `levels` as `config` says. Throws
/// RunConfigError naming the field of a configuration that is not usable or a budget the run's
/// floor does not fit ("memory: the cooperative energy needs ...").
RunReport run_segmentation(const SegmentationProblem& problem, ScheduleProvider& levels,
                           const SegmentationRunConfig& config, const Observer& observer = {});

}  // namespace c2f::vision
