// Cooperative-cut segmentation from Python: an RGB image and seed labels in, c2f-segment's data
// preparation, energy, schedules and solvers, the labels out.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <climits>
#include <cstdint>
#include <string>

#include "c2f/lift/schedule_provider.hpp"
#include "c2f/run/run_error.hpp"
#include "c2f/run/segmentation_run.hpp"
#include "c2f/vision/segmentation/kmeans.hpp"
#include "c2f/vision/segmentation/segmentation_energy.hpp"
#include "c2f/vision/segmentation/segmentation_scene.hpp"
#include "c2f/vision/segmentation/segmentation_schedules.hpp"
#include "image_arrays.hpp"
#include "memory_argument.hpp"
#include "numpy_input.hpp"
#include "released_gil.hpp"
#include "run_arguments.hpp"
#include "step_record.hpp"

namespace c2f::python {

namespace py = pybind11;

namespace {

py::array_t<std::int32_t> label_array(const std::vector<int>& labels, const cv::Mat& image) {
  py::array_t<std::int32_t> out({image.rows, image.cols});
  std::copy(labels.begin(), labels.end(), out.mutable_data());
  return out;
}

py::dict read_segmentation(const std::string& image, const std::string& seeds,
                           const std::string& gt, const std::string& convention,
                           const py::handle& downscale) {
  vision::SegmentationFiles files;
  files.image = image;
  files.seeds = seeds;
  files.gt = gt;
  try {
    files.convention = vision::seed_convention_from_string(convention);
  } catch (const std::invalid_argument& error) {
    throw py::value_error(std::string("convention: ") + error.what());
  }
  const int factor = static_cast<int>(integer_argument(downscale, "downscale", 1, 1024));
  vision::SegmentationScene scene;
  {
    const ReleasedGil free;  // file reading stalls no other thread
    scene = vision::downscale(vision::load_segmentation_scene(files), factor);
  }
  py::dict out;
  out["image"] = rgb_array(scene.image);
  out["seeds"] = label_array(scene.seeds, scene.image);
  out["truth"] = scene.truth.empty() ? py::object(py::none())
                                     : py::object(label_array(scene.truth, scene.image));
  py::array_t<std::uint8_t> palette(
      {static_cast<py::ssize_t>(scene.palette.size()), py::ssize_t{3}});
  for (std::size_t l = 0; l < scene.palette.size(); ++l)
    for (int c = 0; c < 3; ++c) palette.mutable_data()[3 * l + c] = scene.palette[l][2 - c];
  out["palette"] = palette;
  return out;
}

/// The scene of an RGB image and seed labels (-1: no seed), checked by name.
vision::SegmentationScene scene_from_arrays(const py::handle& image, const py::handle& seeds) {
  vision::SegmentationScene scene;
  scene.name = "image";
  scene.image = bgr_image(image, "image");
  const auto labels = integer_array(seeds, "seeds", 2, "(H, W)");
  if (labels.shape(0) != scene.image.rows || labels.shape(1) != scene.image.cols) {
    throw py::value_error("seeds: expected shape (" + std::to_string(scene.image.rows) + ", " +
                          std::to_string(scene.image.cols) + "), the image's, got shape " +
                          shape_text(labels));
  }
  std::int64_t largest = -1;
  for (py::ssize_t i = 0; i < labels.size(); ++i) {
    const std::int64_t label = labels.data()[i];
    if (label < -1 || label >= 64)
      throw py::value_error("seeds: expected -1 (no seed) or a label in [0, 63], got " +
                            std::to_string(label) + " at flat index " + std::to_string(i));
    largest = std::max(largest, label);
    scene.seeds.push_back(label < 0 ? vision::kNoLabel : static_cast<int>(label));
  }
  if (largest < 1) throw py::value_error("seeds: expected seeds of at least 2 labels");
  std::vector<bool> seeded(static_cast<std::size_t>(largest) + 1, false);
  for (const int label : scene.seeds)
    if (label >= 0) seeded[static_cast<std::size_t>(label)] = true;
  for (std::size_t l = 0; l < seeded.size(); ++l)
    if (!seeded[l])
      throw py::value_error("seeds: label " + std::to_string(l) + " has no seed pixel");
  for (std::int64_t l = 0; l <= largest; ++l)  // colours for pictures only
    scene.palette.emplace_back(static_cast<std::uint8_t>(37 * l), static_cast<std::uint8_t>(91 * l),
                               static_cast<std::uint8_t>(173 * l));
  return scene;
}

/// A keyword's value, or `fallback` (the defaults') when it is None.
double real_or(const py::handle& value, const std::string& name, double fallback) {
  return value.is_none() ? fallback : real_argument(value, name);
}

py::dict segment(const py::handle& image, const py::handle& seeds,
                 const py::handle& schedule_argument, const py::handle& method_argument,
                 const py::handle& options, const py::handle& lambda_argument,
                 const py::handle& theta_argument, const py::handle& alpha_argument,
                 const py::handle& classes_argument, const std::string& kmeans,
                 const py::handle& gmm_seed_argument, const py::handle& edge_seed_argument,
                 const py::handle& threads_argument, const py::handle& time_limit,
                 const py::handle& max_steps, const py::handle& plateau_argument,
                 const py::object& callback, const py::handle& memory) {
  // Every argument left None is the library's segmentation default.
  const vision::SegmentationDefaults defaults = vision::segmentation_defaults();
  const std::string schedule_text =
      schedule_argument.is_none() ? defaults.schedule : text_option(schedule_argument, "schedule");
  const std::string method = method_argument.is_none()
                                 ? std::string(vision::to_string(defaults.method))
                                 : text_option(method_argument, "method");
  const double lambda = real_or(lambda_argument, "lambda_", defaults.parameters.lambda);
  const double theta = real_or(theta_argument, "theta", defaults.parameters.theta);
  const double alpha = real_or(alpha_argument, "alpha", defaults.parameters.alpha);
  const int classes = static_cast<int>(integer_argument(classes_argument, "classes", 1, 256));
  const auto gmm_seed =
      static_cast<std::uint64_t>(integer_argument(gmm_seed_argument, "gmm_seed", 0, INT64_MAX));
  const auto edge_seed =
      static_cast<std::uint64_t>(integer_argument(edge_seed_argument, "edge_seed", 0, INT64_MAX));
  const int threads = static_cast<int>(integer_argument(threads_argument, "threads", 0, 1024));
  vision::SegmentationRunConfig config;
  try {
    config.method = vision::segmentation_method_from_string(method);
  } catch (const std::invalid_argument& error) {
    throw py::value_error(std::string("method: ") + error.what());
  }
  if (config.method == vision::SegmentationMethod::coop) {
    config.coop = coop_options_from(options, defaults);
  } else if (!options.is_none() && py::len(options) != 0) {
    throw py::value_error("options: method 'potts' (alpha-expansion of the Potts energy) has none");
  }
  // None: the number of labels, or one sweep when that is shorter; 'sweep': one sweep.
  if (py::isinstance<py::str>(plateau_argument)) {
    if (plateau_argument.cast<std::string>() != "sweep")
      throw py::value_error("plateau: expected None, 'sweep' or a number of steps >= 1");
    config.plateau = -1;
  } else if (!plateau_argument.is_none()) {
    config.plateau = static_cast<int>(integer_argument(plateau_argument, "plateau", 1, INT32_MAX));
  }
  config.time_limit_seconds = optional_positive_real(time_limit, "time_limit");
  config.max_total_steps = optional_positive_count(max_steps, "max_steps");
  config.memory = memory_budget_from(memory);
  if (const std::string problem = config.validate(); !problem.empty()) {
    try {
      RunConfigError::throw_if(problem);
    } catch (const RunConfigError& error) {
      raise_run_error(error);
    }
  }
  const vision::SegmentationScene scene = scene_from_arrays(image, seeds);
  const CoopParameters parameters{lambda, theta, alpha};
  if (const std::string problem = parameters.validate(); !problem.empty())
    throw py::value_error(problem);
  if (kmeans != "plusplus" && kmeans != "reference")
    throw py::value_error("kmeans: expected 'plusplus' or 'reference', got '" + kmeans + "'");
  const auto clustering = [&](std::uint64_t seed) {
    vision::KMeansOptions kmeans_options =
        kmeans == "plusplus" ? vision::plus_plus_kmeans(seed) : vision::reference_kmeans(seed);
    kmeans_options.threads = threads;
    return kmeans_options;
  };
  const vision::DataPreparation preparation{classes, clustering(gmm_seed), clustering(edge_seed)};
  config.threads = threads;

  const int num_labels = scene.num_labels();
  Schedule schedule;
  try {
    schedule = vision::parse_segmentation_schedule(schedule_text, num_labels);
    if (std::string problem = schedule.validate(num_labels); !problem.empty())
      throw std::invalid_argument(problem);
    if (std::string problem = schedule.validate_image(scene.shape()); !problem.empty())
      throw std::invalid_argument(problem);
  } catch (const std::invalid_argument& error) {
    throw py::value_error(std::string("schedule: ") + error.what());
  }

  require_memory_within(*config.memory,
                        "segmenting " + std::to_string(scene.image.cols) + "x" +
                            std::to_string(scene.image.rows) + " pixels into " +
                            std::to_string(num_labels) + " labels",
                        vision::segmentation_memory_estimate(scene.image.total(), num_labels));
  StepRecord record(callback, {scene.image.rows, scene.image.cols});
  RunReport report;
  try {
    const ReleasedGil free;
    const vision::SegmentationProblem problem =
        vision::segmentation_problem(scene, parameters, preparation);
    ScheduleProvider levels = vision::segmentation_levels(schedule, scene);
    // As in c2f-segment: the recycled move graphs get what the budget leaves.
    report = vision::run_segmentation(problem, levels, config, std::ref(record));
  } catch (const RunConfigError& error) {
    raise_run_error(error);
  }
  return record.result(report.summary, report.summary.report() + report.threads_line() + "\n");
}

/// The library's SegmentationDefaults as a dict (c2f.defaults('segmentation')).
py::dict segmentation_defaults_dict() {
  const vision::SegmentationDefaults defaults = vision::segmentation_defaults();
  py::dict out;
  out["schedule"] = defaults.schedule;
  out["method"] = std::string(vision::to_string(defaults.method));
  out["aux"] = std::string(to_string(defaults.strategy));
  out["near_radius"] = defaults.mm_near_radius;
  out["lambda_"] = defaults.parameters.lambda;
  out["theta"] = defaults.parameters.theta;
  out["alpha"] = defaults.parameters.alpha;
  return out;
}

}  // namespace

void bind_segment(py::module_& module) {
  module.def("_segmentation_defaults", &segmentation_defaults_dict,
             "The library's SegmentationDefaults, as a dict (c2f.defaults('segmentation')).");
  module.def("read_segmentation", &read_segmentation, py::arg("image"), py::arg("seeds"),
             py::arg("gt") = "", py::arg("convention") = "colours", py::arg("downscale") = 1,
             "A segmentation scene loaded as c2f-segment loads it: a dict with 'image' (RGB "
             "uint8), 'seeds' ((H, W) int32, -1 where no seed), 'truth' ((H, W) int32 labels, -1 "
             "unscored; None without GT) and 'palette' ((L, 3) RGB colour of each label).");
  module.def("_segment", &segment, py::arg("image"), py::arg("seeds"), py::arg("schedule"),
             py::kw_only(), py::arg("method"), py::arg("options"), py::arg("lambda_"),
             py::arg("theta"), py::arg("alpha"), py::arg("classes"), py::arg("kmeans"),
             py::arg("gmm_seed"), py::arg("edge_seed"), py::arg("threads"), py::arg("time_limit"),
             py::arg("max_steps"), py::arg("plateau"), py::arg("callback"), py::arg("memory"),
             "The engine of c2f.segment (which documents the arguments); returns a dict.");
}

}  // namespace c2f::python
