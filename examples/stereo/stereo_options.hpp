#pragma once
// Command line of c2f-stereo: parsing and validation (every flag checked before any work).

#include <optional>
#include <string>

#include "c2f/lift/schedule.hpp"
#include "c2f/run/run_config.hpp"
#include "c2f/vision/stereo/stereo_scene.hpp"
#include "c2f/vision/stereo/tsgo_energy.hpp"

namespace c2f::examples {

struct StereoCommand {
  vision::StereoPairFiles pair;  ///< pair mode: the views, GT and masks
  std::string scene, data;       ///< scene mode: a scenes.csv row name and the data root
  std::string out_dir;
  int downscale = 1;
  int labels = 0;            ///< --labels as given; 0: the scene's range (set_labels_from_scene)
  vision::TsgoOptions tsgo;  ///< tsgo.labels: the label count the run uses
  Schedule schedule;
  bool allow_non_refining = false;
  /// The solver, the limits (with the level transfer --allow-non-refining asks for) and the
  /// memory budget (--memory, else the machine's default, always set).
  RunConfig run;
  std::string trace;
  std::string export_uai;  ///< --export-uai: the model, written in the UAI format
  bool save_partitions = false;
  bool quiet = false;
};

/// Parses argv. Returns std::nullopt after printing --help. Throws std::invalid_argument with a
/// message naming the flag for anything invalid (missing files included).
std::optional<StereoCommand> parse_stereo_command(int argc, char** argv);

/// The label count of a run without --labels or of a scene without a range of its own.
inline constexpr int kDefaultLabels = 85;

/// Sets tsgo.labels and checks the schedule against it. Throws std::invalid_argument naming
/// --schedule when a level needs more labels.
void set_labels(StereoCommand& command, int labels);

/// Without --labels: the loaded scene's disparity range (Middlebury 2014 ndisp, also of a pair
/// with a calib.txt beside LEFT; KITTI's 128) when it has one, else kDefaultLabels; then
/// set_labels. Throws std::invalid_argument naming the scene when its range is above 256.
void set_labels_from_scene(StereoCommand& command, const vision::StereoScene& scene);

}  // namespace c2f::examples
