#pragma once
// What a coarse-to-fine run (or any anytime loop) reports after every step, and the observers
// that watch it.

#include <cstddef>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "c2f/core/labeling.hpp"

namespace c2f {

/// The record of one step of a run, seen by the observer and by the refinement and stopping
/// rules alike: the state after `step` steps on `level` (step 0 = the level's start labeling,
/// right after the transfer from the previous level).
struct StepEvent {
  double time_s = 0.0;            ///< run-clock seconds since the run started (observer excluded)
  int level = 0;                  ///< 0 = coarsest
  long step = 0;                  ///< steps done on this level
  long total_steps = 0;           ///< steps done in the whole run
  double energy = 0.0;            ///< energy of the ground (original) labeling
  std::size_t num_variables = 0;  ///< variables at this level
  /// Variables this step's move worked over: num_variables for a whole move, fewer for a near
  /// move (StepScopeSolver), num_variables for a solver that does not say; 0 at step 0.
  std::size_t step_variables = 0;
  bool at_original = false;                 ///< true on the last level (the original problem)
  std::span<const double> level_energies;   ///< energy after steps 0..step of this level
  std::span<const Label> level_labeling;    ///< current labeling of the level's variables
  std::span<const VariableIndex> group_of;  ///< pixel -> level variable; empty at the original

  /// The labeling of the original variables that this step's labeling stands for. O(N).
  [[nodiscard]] Labeling ground_labeling() const;
  /// The same labeling without a new allocation: level_labeling itself on the original level,
  /// else `scratch` resized to the original variables and filled (O(N)). The span is valid
  /// while this event's labeling and `scratch` are; an observer called every step keeps its
  /// scratch between calls.
  [[nodiscard]] std::span<const Label> ground_labeling(Labeling& scratch) const;
};

enum class ObserverDecision { continue_run, stop };

/// Called after every step; returning stop ends the run. Time spent inside it is not counted
/// on the run clock.
using Observer = std::function<ObserverDecision(const StepEvent&)>;

/// An observer that calls each of `observers` in turn; stops when any of them says stop.
Observer observe_all(std::vector<Observer> observers);

}  // namespace c2f
