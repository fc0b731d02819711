#include "schedules.hpp"

#include <pybind11/numpy.h>

#include <span>
#include <variant>

#include "c2f/vision/stereo/stereo_schedules.hpp"
#include "c2f/vision/superpixels.hpp"
#include "numpy_input.hpp"

namespace c2f::python {

namespace py = pybind11;

Schedule parse_schedule(const std::string& text, const ModelEnergy& model) {
  Schedule schedule;
  try {
    schedule = model.stereo ? vision::parse_stereo_schedule(text)
                            : Schedule::parse(text, pairwise_schedule_presets());
  } catch (const std::invalid_argument& error) {
    // The parser's messages begin "schedule: " already.
    const std::string message = error.what();
    throw py::value_error(message.rfind("schedule: ", 0) == 0 ? message : "schedule: " + message);
  }
  if (const std::string problem = schedule.validate(model.energy.num_labels()); !problem.empty())
    throw py::value_error("schedule: " + problem);
  if (const std::string problem = model.shape.empty() ? schedule.validate_without_grid() : "";
      !problem.empty()) {
    throw py::value_error("schedule: " + problem +
                          "; build the energy with Energy.grid, or use cp, agg and auto levels");
  }
  return schedule;
}

ScheduleProvider schedule_provider(const Schedule& schedule, const ModelEnergy& model) {
  if (model.shape.empty()) return ScheduleProvider(schedule);  // parse_schedule checked its levels
  const GridShape shape{static_cast<std::size_t>(model.shape[1]),
                        static_cast<std::size_t>(model.shape[0])};
  if (const std::string problem = schedule.validate_image(shape); !problem.empty())
    throw py::value_error("schedule: " + problem);
  bool slic = false;
  for (const LevelSpec& level : schedule.levels)
    slic = slic || std::holds_alternative<SlicLevel>(level.partition);
  if (slic && model.guide.empty()) {
    throw py::value_error(
        "schedule: slic levels segment an image; they need an energy built from one "
        "(c2f.stereo_energy)");
  }
  return ScheduleProvider(
      schedule, shape,
      model.guide.empty() ? SuperpixelSource{} : vision::slic_source(model.guide));
}

DensePartition partition_from(const py::handle& object, const std::string& name,
                              std::size_t num_variables) {
  py::array array = array_argument(object, name, "an integer array of group ids");
  const auto ids = integer_array(array.reshape({array.size()}), name, 1, "(N,)");
  if (static_cast<std::size_t>(ids.shape(0)) != num_variables) {
    throw py::value_error(name + ": a partition of the energy's " + std::to_string(num_variables) +
                          " variables needs as many group ids, got " +
                          std::to_string(ids.shape(0)));
  }
  try {
    return DensePartition::from_ids(
        std::span<const std::int64_t>(ids.data(), static_cast<std::size_t>(ids.shape(0))));
  } catch (const std::invalid_argument& error) {
    throw py::value_error(name + ": " + error.what());
  }
}

}  // namespace c2f::python
