// c2f._solve: coarse_to_fine with a chosen solver on a c2f.Energy, the GIL released while it runs,
// every step recorded (and shown to a Python callback, which may stop the run), Ctrl-C honoured
// at the next step with the best labeling kept.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <climits>
#include <cstdint>
#include <string>
#include <vector>

#include "c2f/adapters/run_memory.hpp"
#include "c2f/adapters/solver_choice.hpp"
#include "c2f/driver/coarse_to_fine.hpp"
#include "c2f/lift/partition_list.hpp"
#include "c2f/lift/schedule.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "memory_argument.hpp"
#include "model_energy.hpp"
#include "numpy_input.hpp"
#include "released_gil.hpp"
#include "schedules.hpp"
#include "step_record.hpp"

namespace c2f::python {

namespace py = pybind11;

namespace {

PartitionList partition_list(const py::list& partitions, std::size_t num_variables) {
  std::vector<DensePartition> levels;
  for (std::size_t i = 0; i < partitions.size(); ++i) {
    const std::string name = "schedule[" + std::to_string(i) + "]";
    levels.push_back(partition_from(partitions[i], name, num_variables));
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
               const py::handle& seed, const py::handle& near_radius, bool shift_moves,
               const std::string& near_levels, const py::handle& time_limit,
               const py::handle& max_steps, const py::handle& plateau,
               const py::handle& plateau_tolerance, const py::object& start,
               const py::object& callback, const py::handle& memory) {
  const MemoryBudget budget = memory_budget_from(memory);
  SolverChoice choice;
  choice.kind =
      parsed("solver", solver, [](const std::string& t) { return solver_kind_from_string(t); });
  choice.maxflow =
      parsed("maxflow", maxflow, [](const std::string& t) { return maxflow_kind_from_string(t); });
  choice.order =
      parsed("order", order, [](const std::string& t) { return visit_order_from_string(t); });
  choice.near_levels = parsed("near_levels", near_levels,
                              [](const std::string& t) { return near_levels_from_string(t); });
  choice.seed = static_cast<std::uint64_t>(integer_argument(seed, "seed", 0, INT64_MAX));
  choice.near_radius = static_cast<int>(integer_argument(near_radius, "near_radius", 0, INT32_MAX));
  choice.shift_moves = shift_moves;
  if (const std::string problem = choice.validate(); !problem.empty())
    throw py::value_error("solver: " + problem);
  if (!maxflow_available(choice.maxflow))
    throw py::value_error("maxflow: '" + maxflow + "' is not in this build");

  Options options;
  options.time_limit_seconds = real_argument(time_limit, "time_limit");
  if (options.time_limit_seconds < 0)
    throw py::value_error("time_limit: expected a finite number >= 0 (0: no limit)");
  options.max_total_steps = integer_argument(max_steps, "max_steps", 0, LONG_MAX);
  options.plateau_steps = {static_cast<int>(integer_argument(plateau, "plateau", 1, INT32_MAX))};
  options.plateau_tolerance = real_argument(plateau_tolerance, "plateau_tolerance");
  if (options.plateau_tolerance < 0)
    throw py::value_error("plateau_tolerance: expected a finite number >= 0");
  if (py::isinstance<py::str>(start)) {
    options.initial_labeling = parsed("start", start.cast<std::string>(), [](const std::string& t) {
      return initial_labeling_from_string(t);
    });
  } else {
    options.start_labeling = labeling_from(start, "start", model.energy.num_variables(),
                                           model.energy.num_labels(), model.shape);
  }

  StepRecord record(callback, model.shape);
  // The run's floor must fit the budget; the recycled move graphs get what it leaves, and a
  // coarse level is solved only when it fits the room the budget gives it.
  auto run = [&](auto& levels) {
    const SolverChoice fitted = fit_to_memory(choice, model.energy, budget);
    options.coarse_level_fits = coarse_level_admission(fitted, problem_size(model.energy));
    const ReleasedGil free;
    return with_chosen_solvers(fitted, [&](auto&& solvers) {
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
    ScheduleProvider levels = schedule_provider(schedule, model);
    summary = run(levels);
    report = summary.report();
  } else {
    throw py::type_error(
        "schedule: expected a schedule text ('flat', 'paper', 'cp:1,1 cp:2,1') or "
        "a list of partitions (integer arrays of group ids, coarsest first)");
  }
  return record.result(summary, report);
}

}  // namespace

void bind_solve(py::module_& module) {
  module.def("_solve", &solve, py::arg("energy"), py::arg("schedule"), py::arg("solver"),
             py::arg("maxflow"), py::arg("order"), py::arg("seed"), py::arg("near_radius"),
             py::arg("shift_moves"), py::arg("near_levels"), py::arg("time_limit"),
             py::arg("max_steps"), py::arg("plateau"), py::arg("plateau_tolerance"),
             py::arg("start"), py::arg("callback"), py::arg("memory"),
             "The engine of c2f.solve (which documents the arguments); returns a dict.");
}

}  // namespace c2f::python
