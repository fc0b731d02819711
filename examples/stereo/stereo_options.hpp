#pragma once
// Command line of c2f-stereo: parsing and validation (every flag checked before any work).

#include <optional>
#include <string>

#include "c2f/adapters/move_order.hpp"
#include "c2f/lift/schedule.hpp"
#include "c2f/vision/stereo/tsgo_energy.hpp"

namespace c2f::examples {

struct StereoCommand {
  std::string left, right;  ///< image paths (pair mode)
  std::string scene, data;  ///< scene mode: a scenes.csv row name and the data root
  std::string out_dir;
  std::string gt, gt_right, mask;
  double gt_divisor = 1.0;
  int downscale = 1;
  vision::TsgoOptions tsgo;
  Schedule schedule;
  std::string schedule_text;
  bool allow_non_refining = false;
  std::string solver = "expansion";
  LabelOrder label_order = LabelOrder::sequential;  ///< expansion and swap
  double time_limit = 0.0;
  long max_steps = 0;
  int plateau = 4;
  double plateau_tolerance = 0.0;  ///< coarse levels only
  int final_plateau = 0;           ///< 0: one sweep of the solver
  std::string trace;
  bool save_partitions = false;
  bool quiet = false;
};

/// Parses argv. Returns std::nullopt after printing --help. Throws std::invalid_argument with a
/// message naming the flag for anything invalid (missing files included).
std::optional<StereoCommand> parse_stereo_command(int argc, char** argv);

}  // namespace c2f::examples
