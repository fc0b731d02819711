#pragma once
// Command line of c2f-segment: parsing and validation (every flag checked before any work).

#include <optional>
#include <string>
#include <string_view>

#include "c2f/adapters/coop/coop_solver.hpp"
#include "c2f/cooperative/coop_energy.hpp"
#include "c2f/core/memory_budget.hpp"
#include "c2f/driver/options.hpp"
#include "c2f/vision/segmentation/segmentation_energy.hpp"
#include "c2f/vision/segmentation/segmentation_scene.hpp"

namespace c2f::examples {

/// What c2f-segment minimises: the cooperative cut, or the plain Potts energy of the same data
/// with alpha-expansion (the cooperative-cuts papers' baseline).
enum class SegmentMethod { coop, potts };

std::string_view to_string(SegmentMethod method);
SegmentMethod segment_method_from_string(std::string_view text);

struct SegmentCommand {
  vision::SegmentationFiles files;
  std::string out_dir;
  SegmentMethod method = SegmentMethod::coop;
  CoopSolverOptions coop;
  CoopParameters parameters;
  vision::DataPreparation preparation;  ///< edge classes and both k-means runs
  int downscale = 1;
  std::string schedule = "superpixels";  ///< parsed once the label count is known
  double time_limit = 0.0;
  long max_steps = 0;
  /// Steps without decrease that end a coarse level: 0 = the number of labels (the
  /// reference's window) or one sweep when that is shorter; -1 = one whole sweep.
  int plateau = 0;
  int final_plateau = 0;  ///< 0: one sweep of the solver
  MemoryBudget memory;    ///< --memory, else the machine's default
  std::string trace;
  std::string export_uai;  ///< --export-uai: the Potts energy of the same data, as UAI
  bool save_partitions = false;
  bool quiet = false;
};

/// Parses argv. Returns std::nullopt after printing --help. Throws std::invalid_argument with a
/// message naming the flag for anything invalid (missing files included).
std::optional<SegmentCommand> parse_segment_command(int argc, char** argv);

/// The driver options for a problem with num_labels labels, solved by a solver whose sweep
/// (quiet_steps_to_converge) is `sweep` steps: coarse levels end after --plateau steps without
/// decrease, the original problem where the solver has converged (or after --final-plateau).
Options run_options(const SegmentCommand& command, int num_labels, std::size_t sweep);

}  // namespace c2f::examples
