#pragma once
// The energy a Python user holds: a PairwiseEnergy, and the grid shape its variables came in
// (labelings are handed back in that shape).

#include <pybind11/pybind11.h>

#include <vector>

#include "c2f/core/pairwise_energy.hpp"

namespace c2f::python {

struct ModelEnergy {
  PairwiseEnergy energy;
  std::vector<pybind11::ssize_t> shape;  ///< (H, W) of a grid energy; empty for a general one
};

void bind_energy(pybind11::module_& module);

}  // namespace c2f::python
