#pragma once
// Images between numpy and OpenCV: numpy users hold RGB (imageio, matplotlib, PIL), the library
// BGR (OpenCV).

#include <pybind11/numpy.h>

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

namespace c2f::python {

/// An 8-bit BGR image as an (H, W, 3) uint8 RGB array.
pybind11::array_t<std::uint8_t> rgb_array(const cv::Mat& bgr);

/// An (H, W, 3) uint8 RGB array as an 8-bit BGR image (copied). Throws TypeError or ValueError
/// naming `name`.
cv::Mat bgr_image(const pybind11::handle& object, const std::string& name);

}  // namespace c2f::python
