#pragma once
// Command line of c2f-solve: parsing and validation (every flag checked before any work).

#include <optional>
#include <string>

#include "c2f/core/grid.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/lift/schedule.hpp"
#include "c2f/run/run_config.hpp"

namespace c2f::examples {

struct SolveCommand {
  std::string model;              ///< the UAI MARKOV file
  std::string out_dir;            ///< labeling.mpe, trace.csv, summary.txt
  std::string schedule_text;      ///< checked against the model once it is read; empty: the default
  std::optional<GridShape> grid;  ///< --grid WxH: the variables are a row-major grid
  /// The solver, the limits and the memory budget (--memory, else the machine's default,
  /// always set).
  RunConfig run;
  std::string trace;
  bool quiet = false;
};

/// Parses argv. Returns std::nullopt after printing --help. Throws std::invalid_argument with a
/// message naming the flag for anything invalid (the model file must exist).
std::optional<SolveCommand> parse_solve_command(int argc, char** argv);

/// The schedule for the model's energy: --schedule, else the pairwise defaults' schedule for it
/// (RunDefaults::schedule_for); parsed with c2f-solve's presets, N_L checked against the
/// labels, and levels that need a pixel grid (local, threshold, blocks, slic) refused unless
/// --grid gave one of the model's size. Throws std::invalid_argument starting "--schedule: " or
/// "--grid: ".
Schedule solve_schedule(const SolveCommand& command, const PairwiseEnergy& energy);

}  // namespace c2f::examples
