#pragma once
// The options that configure a run, shared by the tools that offer every pairwise solver
// (c2f-stereo, c2f-solve): --solver, --maxflow, --memory, --graph-memory, --threads, --regions,
// --near-radius, --near-seeds, --near-graphs, --near-min-variables, --shift-moves, --near-levels,
// --label-order, --time-limit, --max-steps, --plateau, --plateau-tolerance, --final-plateau.
// They become one RunConfig of the run layer.

#include <string>

#include "c2f/run/defaults.hpp"
#include "c2f/run/run_config.hpp"
#include "c2f/support/number_text.hpp"
#include "tool_options.hpp"

namespace c2f::examples {

class RunFlags {
 public:
  /// The flags' defaults (shown in --help) are the tool's RunDefaults: the library's one
  /// definition of what a run does when nothing is named.
  explicit RunFlags(const RunDefaults& defaults)
      : defaults_(defaults),
        near_radius_(defaults.near_radius),
        near_seeds_(seeds_depend_on_grid(defaults) ? "" : to_string(defaults.near_seeds)),
        near_graphs_(near_graphs_name(defaults.near_moves_only_if_local)),
        near_min_variables_(static_cast<long>(defaults.near_moves_min_variables)),
        shift_moves_(shift_moves_value(defaults)),
        plateau_(defaults.progress_rate ? "rate" : std::to_string(defaults.plateau_steps)),
        plateau_tolerance_(
            tolerance_depends_on_grid(defaults) ? "" : format_real(defaults.plateau_tolerance)) {}

  /// Declares the eighteen options in `options` (this object receives their values, so it
  /// must outlive options.parse()).
  void declare(ToolOptions& options);

  /// The run the parsed options configure for an energy on a pixel grid or not (the defaults'
  /// near seeds may differ: RunDefaults::near_seeds_on), its memory budget resolved (--memory,
  /// else the machine's default). Throws std::invalid_argument naming the option for an unknown
  /// name, an option the solver does not take, or a backend not in this build.
  [[nodiscard]] RunConfig config(bool on_grid) const;
  /// --threads: the threads of the whole run, the tool's data preparation included (0: the
  /// machine's cores).
  [[nodiscard]] int threads() const noexcept { return threads_; }

 private:
  /// --shift-moves as `defaults` set it: on, auto (shift_moves_unless_submodular) or off.
  [[nodiscard]] static std::string shift_moves_value(const RunDefaults& defaults) {
    if (defaults.shift_moves) return "on";
    return defaults.shift_moves_unless_submodular ? "auto" : "off";
  }
  /// Whether `defaults` start near moves on a pixel grid elsewhere than on other graphs; then
  /// --near-seeds has no single default (empty until given).
  [[nodiscard]] static bool seeds_depend_on_grid(const RunDefaults& defaults) {
    return defaults.near_seeds_on(true) != defaults.near_seeds_on(false);
  }
  /// Whether `defaults`' coarse plateau tolerance on a pixel grid differs from that on other
  /// graphs; then --plateau-tolerance has no single default (empty until given).
  [[nodiscard]] static bool tolerance_depends_on_grid(const RunDefaults& defaults) {
    return defaults.plateau_tolerance_on(true) != defaults.plateau_tolerance_on(false);
  }
  [[nodiscard]] SolverSpec solver_spec(bool on_grid) const;
  [[nodiscard]] Options limits(bool on_grid) const;

  RunDefaults defaults_;
  std::string solver_ = "expansion", label_order_ = "sequential", maxflow_ = "dynamic",
              near_levels_;        // empty: not given (NearLevels::original)
  std::string graph_memory_text_;  // empty: what the budget leaves
  double memory_gib_ = 0.0;        // 0: default_memory_budget()
  int threads_ = 0;
  int regions_ = ExpansionOptions{}.regions;
  int flow_parts_ = ExpansionOptions{}.flow_parts;
  int near_radius_;
  std::string bp_schedule_;      // sequential, parallel or bands; empty: LbpOptions' default
  std::string near_seeds_;       // label_and_cheapest, label, label_and_adjacent; empty: defaults'
  std::string near_seeds_help_;  // --near-seeds' help, its defaults named
  std::string near_graphs_;      // local or any
  long near_min_variables_;      // near moves only on energies of at least this many variables
  std::string shift_moves_;      // on, off or auto
  double time_limit_ = 0.0;      // seconds on the run clock, 0: none
  long max_steps_ = 0;           // steps in the whole run, 0: none
  std::string plateau_;          // steps without decrease that end a coarse level, or rate
  std::string plateau_tolerance_;       // empty: the defaults' on a grid or not
  std::string plateau_tolerance_help_;  // --plateau-tolerance's help, its defaults named
  int final_plateau_ = 0;               // on the original problem; 0: the solver's own convergence
};

/// ", near moves of radius R and shift moves on the original problem only" (", near moves of
/// radius R from their label" with NearSeeds::label, "... where the edges are local" with
/// near_moves_only_if_local, "... on energies of at least N variables" with
/// near_moves_min_variables) for the near and shift moves `spec` makes, else "" (a tool's
/// summary line, before the energy decides; RunReport::threads_line says what was made).
[[nodiscard]] std::string near_and_shift_moves_text(const SolverSpec& spec);

}  // namespace c2f::examples
