// The library's parts for users who build their own coarse-to-fine loop or bring their own
// grouping: one level's partition, the reduced energy of a partition, and labelings carried
// between levels.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <string>

#include "c2f/lift/reduce.hpp"
#include "c2f/lift/transfer.hpp"
#include "model_energy.hpp"
#include "numpy_input.hpp"
#include "released_gil.hpp"
#include "schedules.hpp"

namespace c2f::python {

namespace py = pybind11;

namespace {

/// Group ids in the energy's shape ((H, W) for a grid energy).
py::array_t<std::int32_t> group_array(const DensePartition& partition, const ModelEnergy& model) {
  const auto ids = partition.group_ids();
  return labeling_array(Labeling(ids.begin(), ids.end()), model.shape);
}

py::array_t<std::int32_t> partition(const ModelEnergy& model, const std::string& level) {
  const Schedule schedule = parse_schedule(level, model);
  if (schedule.levels.size() != 1 || !schedule.auto_fractions.empty()) {
    throw py::value_error(
        "level: expected one level ('cp:1,1', 'agg:1/cc', 'slic:16', ...), got '" + level + "'");
  }
  ScheduleProvider provider = schedule_provider(schedule, model);
  std::optional<DensePartition> result;
  {
    const ReleasedGil free;
    result = provider.next(model.energy);
  }
  return group_array(*result, model);
}

ModelEnergy reduced(const ModelEnergy& model, const py::handle& groups) {
  const DensePartition p = partition_from(groups, "partition", model.energy.num_variables());
  const ReleasedGil free;
  return ModelEnergy{reduce(model.energy, p), {}};
}

py::array_t<std::int32_t> expanded(const py::handle& labeling, const py::handle& groups,
                                   const py::handle& labels_argument) {
  const int num_labels =
      static_cast<int>(integer_argument(labels_argument, "num_labels", 1, INT32_MAX));
  const py::array shape_source =
      array_argument(groups, "partition", "an integer array of group ids");
  const DensePartition p =
      partition_from(groups, "partition", static_cast<std::size_t>(shape_source.size()));
  const Labeling on_groups = labeling_from(labeling, "labeling", p.num_groups(), num_labels, {});
  std::vector<py::ssize_t> shape(shape_source.shape(), shape_source.shape() + shape_source.ndim());
  return labeling_array(expand(on_groups, p),
                        shape.size() > 1 ? shape : std::vector<py::ssize_t>{});
}

py::array_t<std::int32_t> transferred(const py::handle& labeling, const py::handle& from,
                                      const py::handle& to, const py::handle& labels_argument) {
  const int num_labels =
      static_cast<int>(integer_argument(labels_argument, "num_labels", 1, INT32_MAX));
  const py::array from_array =
      array_argument(from, "from_partition", "an integer array of group ids");
  const std::size_t n = static_cast<std::size_t>(from_array.size());
  const DensePartition coarse = partition_from(from, "from_partition", n);
  const DensePartition fine = partition_from(to, "to_partition", n);
  const Labeling on_coarse =
      labeling_from(labeling, "labeling", coarse.num_groups(), num_labels, {});
  try {
    return labeling_array(transfer_labels(on_coarse, coarse, fine), {});
  } catch (const std::invalid_argument& error) {
    throw py::value_error(error.what());
  }
}

}  // namespace

void bind_lift(py::module_& module) {
  module.def("partition", &partition, py::arg("energy"), py::arg("level"),
             "One level's partition of the energy's variables, as group ids in the energy's "
             "shape: colour passing 'cp:N_L,N_iter', 'local:..', 'threshold:T', 'agg:R', "
             "'blocks:S', 'slic:S' (energies with an image), any ending in '/cc'.");
  module.def("reduce", &reduced, py::arg("energy"), py::arg("partition"),
             "The reduced energy over the groups of `partition` (group ids of every variable): "
             "reduce(e, p).evaluate(y) == e.evaluate(expand(y, p)) up to rounding (Theorem 1). "
             "Its variables are the groups, numbered by first occurrence of their ids.");
  module.def("expand", &expanded, py::arg("labeling"), py::arg("partition"), py::arg("num_labels"),
             "The labeling of the variables in which every member of group g gets labeling[g]; "
             "shaped like `partition`.");
  module.def("transfer", &transferred, py::arg("labeling"), py::arg("from_partition"),
             py::arg("to_partition"), py::arg("num_labels"),
             "The labeling of the groups of `to_partition` (which must refine `from_partition`) "
             "that stands for the same labeling of the variables as `labeling` on the groups of "
             "`from_partition`, so the two reduced energies agree.");
}

}  // namespace c2f::python
