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
  /// The cooperative cut's solver (method coop; its threads: below). Its near moves
  /// (near_radius > 0) are made on the original problem only: the run raises
  /// near_moves_min_variables to the original problem's size, so a coarse level's steps make
  /// whole moves.
  CoopSolverOptions coop;
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

/// What c2f-segment, c2f.segment and the segmentation benchmarks run when nothing is named:
/// defined once here (tests compare). Chosen on tuning images and checked on images set aside
/// by name before any run (docs/results.md, "Defaults").
struct SegmentationDefaults {
  std::string schedule;  ///< schedule text: a preset of segmentation_schedule_presets or levels
  SegmentationMethod method = SegmentationMethod::coop;
  AuxStrategy strategy = AuxStrategy::mm;  ///< how the auxiliary variables move
  CoopParameters parameters;               ///< lambda, theta and alpha of the cooperative cut
  /// Near moves' radius on the original problem (CoopSolverOptions::near_radius) with
  /// majorise-minimise (0: whole moves). Greedy and ceres make whole moves: from greedy's
  /// all-zero start a near move frees no variable.
  int mm_near_radius = 0;

  /// The near radius these defaults give a cooperative cut whose auxiliary variables move by
  /// `aux`: mm_near_radius for mm, 0 otherwise.
  [[nodiscard]] int near_radius_for(AuxStrategy aux) const noexcept {
    return aux == AuxStrategy::mm ? mm_near_radius : 0;
  }
  /// A SegmentationRunConfig of these defaults with the auxiliary variables moving by `aux`:
  /// method, strategy and near moves; no limits, no budget set (the run's default).
  [[nodiscard]] SegmentationRunConfig config(AuxStrategy aux) const;
  [[nodiscard]] SegmentationRunConfig config() const { return config(strategy); }
};

/// The segmentation defaults: the cooperative cut, majorise-minimise with one expansion cycle
/// per step and near moves of radius 6 from their label on the original problem, on the
/// `superpixels` schedule (slic:16 slic:8 flat), with CoopParameters' lambda 0.5, theta 7e-4
/// and alpha 0.2.
[[nodiscard]] SegmentationDefaults segmentation_defaults();

/// Minimises problem.coop (or problem.potts) over `levels` as `config` says. Throws
/// RunConfigError naming the field of a configuration that is not usable or a budget the run's
/// floor does not fit ("memory: the cooperative energy needs ...").
RunReport run_segmentation(const SegmentationProblem& problem, ScheduleProvider& levels,
                           const SegmentationRunConfig& config, const Observer& observer = {});

}  // namespace c2f::vision
