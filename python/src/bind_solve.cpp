// c2f._solve: coarse_to_fine with a chosen solver on a c2f.Energy, the GIL released while it runs,
// every step recorded (and shown to a Python callback, which may stop the run), Ctrl-C honoured
// at the next step with the best labeling kept.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <string>
#include <variant>
#include <vector>

#include "c2f/adapters/solver_choice.hpp"
#include "c2f/driver/coarse_to_fine.hpp"
#include "c2f/lift/partition_list.hpp"
#include "c2f/lift/schedule.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "c2f/vision/stereo/stereo_schedules.hpp"
#include "c2f/vision/superpixels.hpp"
#include "model_energy.hpp"
#include "numpy_input.hpp"
#include "step_record.hpp"

namespace c2f::python {

namespace py = pybind11;

namespace {

/// The schedules `paper` names, as c2f-solve has it.
std::span<const SchedulePreset> presets() {
  static const std::array<SchedulePreset, 1> list{
      SchedulePreset{"paper", "cp:1,1 cp:2,1 cp:3,1 flat"}};
  return list;
}

Schedule parse_schedule(const std::string& text, const ModelEnergy& model) {
  Schedule schedule;
  try {
    schedule =
        model.stereo ? vision::parse_stereo_schedule(text) : Schedule::parse(text, presets());
  } catch (const std::invalid_argument& error) {
    throw py::value_error(std::string("schedule: ") + error.what());
  }
  if (const std::string problem = schedule.validate(model.energy.num_labels()); !problem.empty())
    throw py::value_error("schedule: " + problem);
  if (model.shape.empty()) {
    for (const LevelSpec& level : schedule.levels) {
      if (!std::holds_alternative<ColourPassingLevel>(level.partition) || level.connected) {
        throw py::value_error("schedule: level " + level.to_string() +
                              " needs a pixel grid; build the energy with Energy.grid, or use cp "
                              "and auto levels");
      }
    }
  }
  return schedule;
}

PartitionList partition_list(const py::list& partitions, std::size_t num_variables) {
  std::vector<DensePartition> levels;
  for (std::size_t i = 0; i < partitions.size(); ++i) {
    const std::string name = "schedule[" + std::to_string(i) + "]";
    py::array array = py::array::ensure(partitions[i]);
    if (!array) throw py::type_error(name + ": expected an integer array of group ids");
    const auto ids = integer_array(array.reshape({array.size()}), name, 1, "(N,)");
    if (static_cast<std::size_t>(ids.shape(0)) != num_variables) {
      throw py::value_error(
          name + ": a partition of the energy's " + std::to_string(num_variables) +
          " variables needs as many group ids, got " + std::to_string(ids.shape(0)));
    }
    try {
      levels.push_back(DensePartition::from_ids(
          std::span<const std::int64_t>(ids.data(), static_cast<std::size_t>(ids.shape(0)))));
    } catch (const std::invalid_argument& error) {
      throw py::value_error(name + ": " + error.what());
    }
  }
  try {
    return PartitionList(std::move(levels));
  } catch (const std::invalid_argument& error) {
    throw py::value_error(std::string("schedule: ") + error.what());
  }
}

template <class Parse>
auto parsed(const std::string& argument, const std::string& text, Parse parse) {
  try {
    return parse(text);
  } catch (const std::invalid_argument& error) {
    throw py::value_error(argument + ": " + error.what());
  }
}

py::dict solve(const ModelEnergy& model, const py::object& schedule_object,
               const std::string& solver, const std::string& maxflow, const std::string& order,
               std::uint64_t seed, int near_radius, bool shift_moves,
               const std::string& near_levels, double time_limit, long max_steps, int plateau,
               double plateau_tolerance, const std::string& start, const py::object& callback) {
  SolverChoice choice;
  choice.kind =
      parsed("solver", solver, [](const std::string& t) { return solver_kind_from_string(t); });
  choice.maxflow =
      parsed("maxflow", maxflow, [](const std::string& t) { return maxflow_kind_from_string(t); });
  choice.order =
      parsed("order", order, [](const std::string& t) { return visit_order_from_string(t); });
  choice.near_levels = parsed("near_levels", near_levels,
                              [](const std::string& t) { return near_levels_from_string(t); });
  choice.seed = seed;
  if (near_radius < 0) throw py::value_error("near_radius: expected an integer >= 0");
  choice.near_radius = near_radius;
  choice.shift_moves = shift_moves;
  if (const std::string problem = choice.validate(); !problem.empty())
    throw py::value_error("solver: " + problem);
  if (!maxflow_available(choice.maxflow))
    throw py::value_error("maxflow: '" + maxflow + "' is not in this build");

  Options options;
  if (!std::isfinite(time_limit) || time_limit < 0)
    throw py::value_error("time_limit: expected a finite number >= 0 (0: no limit)");
  if (max_steps < 0) throw py::value_error("max_steps: expected an integer >= 0 (0: no limit)");
  if (plateau < 1) throw py::value_error("plateau: expected an integer >= 1");
  if (!std::isfinite(plateau_tolerance) || plateau_tolerance < 0)
    throw py::value_error("plateau_tolerance: expected a finite number >= 0");
  options.time_limit_seconds = time_limit;
  options.max_total_steps = max_steps;
  options.plateau_steps = {plateau};
  options.plateau_tolerance = plateau_tolerance;
  options.initial_labeling =
      parsed("start", start, [](const std::string& t) { return initial_labeling_from_string(t); });

  StepRecord record(callback);
  const GridShape shape = model.shape.empty() ? GridShape{model.energy.num_variables(), 1}
                                              : GridShape{static_cast<std::size_t>(model.shape[1]),
                                                          static_cast<std::size_t>(model.shape[0])};
  auto run = [&](auto& levels) {
    py::gil_scoped_release free;
    return with_chosen_solvers(choice, [&](auto&& solvers) {
      return coarse_to_fine(model.energy, levels, solvers, options, std::ref(record));
    });
  };
  Summary summary;
  std::string report;
  if (py::isinstance<py::list>(schedule_object) || py::isinstance<py::tuple>(schedule_object)) {
    PartitionList levels = partition_list(py::list(schedule_object), model.energy.num_variables());
    summary = run(levels);
    report = summary.report();
  } else if (py::isinstance<py::str>(schedule_object)) {
    const Schedule schedule = parse_schedule(schedule_object.cast<std::string>(), model);
    if (const std::string problem = schedule.validate_image(shape); !problem.empty())
      throw py::value_error("schedule: " + problem);
    bool slic = false;
    for (const LevelSpec& level : schedule.levels)
      slic = slic || std::holds_alternative<SlicLevel>(level.partition);
    if (slic && model.guide.empty()) {
      throw py::value_error(
          "schedule: slic levels segment an image; they need an energy built "
          "from one (c2f.stereo_energy)");
    }
    ScheduleProvider levels(
        schedule, shape,
        model.guide.empty() ? SuperpixelSource{} : vision::slic_source(model.guide));
    summary = run(levels);
    report = summary.report();
  } else {
    throw py::type_error(
        "schedule: expected a schedule text ('flat', 'paper', 'cp:1,1 cp:2,1') or "
        "a list of partitions (integer arrays of group ids, coarsest first)");
  }
  return record.result(summary, model.shape, report);
}

}  // namespace

void bind_solve(py::module_& module) {
  module.def("_solve", &solve, py::arg("energy"), py::arg("schedule"), py::arg("solver"),
             py::arg("maxflow"), py::arg("order"), py::arg("seed"), py::arg("near_radius"),
             py::arg("shift_moves"), py::arg("near_levels"), py::arg("time_limit"),
             py::arg("max_steps"), py::arg("plateau"), py::arg("plateau_tolerance"),
             py::arg("start"), py::arg("callback"),
             "The engine of c2f.solve (which documents the arguments); returns a dict.");
}

}  // namespace c2f::python
