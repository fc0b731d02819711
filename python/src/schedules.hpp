#pragma once
// Schedules and partitions from Python arguments, checked by name: schedule texts (with the
// presets of the energy's application), and partitions given as arrays of group ids.

#include <pybind11/pybind11.h>

#include <string>

#include "c2f/lift/dense_partition.hpp"
#include "c2f/lift/schedule.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "model_energy.hpp"

namespace c2f::python {

/// `text` parsed with the presets of the energy's application (stereo's, or `paper`), checked
/// for its label count and, for a general energy, refused when a level needs a pixel grid.
/// Throws ValueError beginning with "schedule: ".
Schedule parse_schedule(const std::string& text, const ModelEnergy& model);

/// The provider of `schedule`'s levels on the energy's grid (N x 1 for a general energy), with
/// SLIC on the energy's image. Throws ValueError beginning with "schedule: " for a level the
/// image cannot have, or slic levels on an energy without an image.
ScheduleProvider schedule_provider(const Schedule& schedule, const ModelEnergy& model);

/// The partition of `num_variables` variables given by `object`'s group ids (any shape, read
/// in order; equal ids, one group). Throws TypeError or ValueError naming `name`.
DensePartition partition_from(const pybind11::handle& object, const std::string& name,
                              std::size_t num_variables);

}  // namespace c2f::python
