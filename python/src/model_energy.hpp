#pragma once
// The energy a Python user holds: a PairwiseEnergy, the grid shape its variables came in
// (labelings are handed back in that shape) and, for an application's energy, what its
// schedules need (the stereo presets, the image SLIC levels segment).

#include <pybind11/pybind11.h>

#include <opencv2/core.hpp>
#include <vector>

#include "c2f/core/pairwise_energy.hpp"

namespace c2f::python {

struct ModelEnergy {
  PairwiseEnergy energy;
  std::vector<pybind11::ssize_t> shape;  ///< (H, W) of a grid energy; empty for a general one
  cv::Mat guide = {};   ///< BGR image of the grid that slic:S levels segment; empty: none
  bool stereo = false;  ///< a TSGO energy: the stereo presets (paper-slic, aggregated, ...) apply
};

void bind_energy(pybind11::module_& module);

}  // namespace c2f::python
