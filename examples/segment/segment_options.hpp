#pragma once
// Command line of c2f-segment: parsing and validation (every flag checked before any work).

#include <optional>
#include <string>
#include <string_view>

#include "c2f/cooperative/coop_energy.hpp"
#include "c2f/run/segmentation_run.hpp"
#include "c2f/vision/segmentation/segmentation_energy.hpp"
#include "c2f/vision/segmentation/segmentation_scene.hpp"

namespace c2f::examples {

struct SegmentCommand {
  vision::SegmentationFiles files;
  std::string out_dir;
  /// The method (the cooperative cut, or the Potts energy of the same data with
  /// alpha-expansion, the cooperative-cuts papers' baseline), its solver, plateaus, limits and
  /// memory budget (--memory, else the machine's default, always set).
  vision::SegmentationRunConfig run;
  CoopParameters parameters;
  vision::DataPreparation preparation;  ///< edge classes and both k-means runs
  int downscale = 1;
  std::string schedule;  ///< parsed once the label count is known (default: the library's)
  std::string trace;
  std::string export_uai;  ///< --export-uai: the Potts energy of the same data, as UAI
  bool save_partitions = false;
  bool quiet = false;
};

/// Parses argv. Returns std::nullopt after printing --help. Throws std::invalid_argument with a
/// message naming the flag for anything invalid (missing files included).
std::optional<SegmentCommand> parse_segment_command(int argc, char** argv);

}  // namespace c2f::examples
