// c2f._solve: the run layer's run() on a c2f.Energy, the GIL released while it runs, every step
// recorded (and shown to a Python callback, which may stop the run), Ctrl-C honoured at the
// next step with the best labeling kept.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <climits>
#include <string>
#include <vector>

#include "c2f/lift/partition_list.hpp"
#include "c2f/lift/schedule.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "c2f/run/defaults.hpp"
#include "c2f/run/run.hpp"
#include "c2f/run/stereo_run.hpp"
#include "memory_argument.hpp"
#include "model_energy.hpp"
#include "numpy_input.hpp"
#include "released_gil.hpp"
#include "run_arguments.hpp"
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

/// The RunDefaults c2f.solve's `defaults` names: 'pairwise' or 'stereo'.
RunDefaults named_defaults(const std::string& name) {
  if (name == "pairwise") return pairwise_defaults();
  if (name == "stereo") return vision::stereo_defaults();
  throw py::value_error("defaults: expected 'pairwise' or 'stereo', got '" + name + "'");
}

/// Whether c2f.solve's `plateau` is 'rate' (any other text is refused by name).
bool progress_rate_named(const py::handle& plateau) {
  if (!py::isinstance<py::str>(plateau)) return false;
  if (plateau.cast<std::string>() != "rate")
    throw py::value_error("plateau: expected None, 'rate' or a number of steps >= 1");
  return true;
}

/// The driver's rules from c2f.solve's keywords (None: no limit; plateau and plateau_tolerance
/// None: the defaults', the tolerance's for a pixel grid where the model has a shape).
Options limits_from(const ModelEnergy& model, const RunDefaults& defaults,
                    const py::handle& time_limit, const py::handle& max_steps,
                    const py::handle& plateau, const py::handle& plateau_tolerance,
                    const py::handle& start) {
  Options limits;
  limits.time_limit_seconds = optional_positive_real(time_limit, "time_limit");
  limits.max_total_steps = optional_positive_count(max_steps, "max_steps");
  limits.plateau_steps = {
      plateau.is_none() || progress_rate_named(plateau)
          ? defaults.plateau_steps
          : static_cast<int>(integer_argument(plateau, "plateau", 1, INT32_MAX))};
  limits.plateau_tolerance = plateau_tolerance.is_none()
                                 ? defaults.plateau_tolerance_on(!model.shape.empty())
                                 : real_argument(plateau_tolerance, "plateau_tolerance");
  if (py::isinstance<py::str>(start)) {
    try {
      limits.initial_labeling = initial_labeling_from_string(start.cast<std::string>());
    } catch (const std::invalid_argument& error) {
      throw py::value_error(std::string("start: ") + error.what());
    }
  } else {
    limits.start_labeling = labeling_from(start, "start", model.energy.num_variables(),
                                          model.energy.num_labels(), model.shape);
  }
  return limits;
}

py::dict solve(const ModelEnergy& model, const py::object& given_schedule,
               const std::string& defaults_name, const std::string& method,
               const py::handle& options, const py::handle& time_limit, const py::handle& max_steps,
               const py::handle& plateau, const py::handle& plateau_tolerance,
               const py::object& start, const py::object& callback, const py::handle& memory,
               const py::handle& graph_memory) {
  const RunDefaults defaults = named_defaults(defaults_name);
  const py::object schedule_object =
      given_schedule.is_none() ? py::str(defaults.schedule_for(model.energy, !model.shape.empty()))
                               : given_schedule;
  RunConfig config;
  config.solver = solver_spec_from(method, options, defaults, !model.shape.empty());
  config.limits =
      limits_from(model, defaults, time_limit, max_steps, plateau, plateau_tolerance, start);
  config.progress_rate = plateau.is_none() ? defaults.progress_rate : progress_rate_named(plateau);
  config.memory = memory_budget_from(memory);
  config.graph_memory = optional_gib_bytes(graph_memory, "graph_memory");
  StepRecord record(callback, model.shape);
  // Checked before the GIL is released: the configuration and the budget (the run's floor must
  // fit; the recycled move graphs get what it leaves, coarse levels the room it gives them).
  try {
    (void)plan_run(model.energy, config);
  } catch (const RunConfigError& error) {
    raise_run_error(error);
  }
  auto run_levels = [&](auto& levels) {
    const ReleasedGil free;
    return run(model.energy, levels, config, std::ref(record));
  };
  RunReport report;
  if (py::isinstance<py::list>(schedule_object) || py::isinstance<py::tuple>(schedule_object)) {
    PartitionList levels = partition_list(py::list(schedule_object), model.energy.num_variables());
    report = run_levels(levels);
  } else if (py::isinstance<py::str>(schedule_object)) {
    const Schedule schedule = parse_schedule(schedule_object.cast<std::string>(), model);
    ScheduleProvider levels = schedule_provider(schedule, model);
    report = run_levels(levels);
  } else {
    throw py::type_error(
        "schedule: expected a schedule text ('flat', 'paper', 'cp:1,1 cp:2,1') or "
        "a list of partitions (integer arrays of group ids, coarsest first)");
  }
  return record.result(report.summary, report.summary.report() + report.threads_line() + "\n");
}

/// A RunDefaults as a dict (c2f.defaults).
py::dict defaults_dict(const std::string& name) {
  const RunDefaults defaults = named_defaults(name);
  py::dict out;
  out["grid_schedule"] = defaults.grid_schedule;
  out["general_schedule"] = defaults.general_schedule;
  out["local_schedule"] =
      defaults.local_schedule.empty() ? defaults.general_schedule : defaults.local_schedule;
  out["near_radius"] = defaults.near_radius;
  out["near_seeds"] = std::string(to_string(defaults.near_seeds));
  out["grid_near_seeds"] = std::string(to_string(defaults.near_seeds_on(true)));
  out["near_graphs"] = std::string(near_graphs_name(defaults.near_moves_only_if_local));
  out["near_min_variables"] = defaults.near_moves_min_variables;
  out["shift_moves"] = defaults.shift_moves                     ? py::object(py::bool_(true))
                       : defaults.shift_moves_unless_submodular ? py::object(py::str("auto"))
                                                                : py::object(py::bool_(false));
  out["plateau"] = defaults.progress_rate ? py::object(py::str("rate"))
                                          : py::object(py::int_(defaults.plateau_steps));
  out["plateau_steps"] = defaults.plateau_steps;
  out["plateau_tolerance"] = defaults.plateau_tolerance;
  out["grid_plateau_tolerance"] = defaults.plateau_tolerance_on(true);
  return out;
}

}  // namespace

void bind_solve(py::module_& module) {
  module.def("_defaults", &defaults_dict, py::arg("name"),
             "The library's RunDefaults named 'pairwise' or 'stereo', as a dict.");
  module.def("_solve", &solve, py::arg("energy"), py::arg("schedule"), py::kw_only(),
             py::arg("defaults"), py::arg("method"), py::arg("options"), py::arg("time_limit"),
             py::arg("max_steps"), py::arg("plateau"), py::arg("plateau_tolerance"),
             py::arg("start"), py::arg("callback"), py::arg("memory"), py::arg("graph_memory"),
             "The engine of c2f.solve (which documents the arguments); returns a dict.");
}

}  // namespace c2f::python
