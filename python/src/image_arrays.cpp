#include "image_arrays.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "numpy_input.hpp"

namespace c2f::python {

namespace py = pybind11;

/// An 8-bit BGR image as an (H, W, 3) uint8 RGB array.
py::array_t<std::uint8_t> rgb_array(const cv::Mat& bgr) {
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  py::array_t<std::uint8_t> out({rgb.rows, rgb.cols, 3});
  for (int y = 0; y < rgb.rows; ++y)
    std::copy(rgb.ptr<std::uint8_t>(y), rgb.ptr<std::uint8_t>(y) + 3 * rgb.cols,
              out.mutable_data() + static_cast<std::size_t>(y) * 3 * rgb.cols);
  return out;
}

/// An (H, W, 3) uint8 RGB array as an 8-bit BGR image (copied). Throws TypeError or ValueError
/// naming `name`.
cv::Mat bgr_image(const py::handle& object, const std::string& name) {
  if (!py::isinstance<py::array>(object))
    throw py::type_error(name + ": expected an (H, W, 3) uint8 numpy array (RGB)");
  const auto array = py::reinterpret_borrow<py::array>(object);
  if (array.dtype().kind() != 'u' || array.itemsize() != 1)
    throw py::type_error(name + ": expected a uint8 array (RGB), got dtype " +
                         std::string(py::str(array.dtype())));
  if (array.ndim() != 3 || array.shape(2) != 3 || array.shape(0) < 2 || array.shape(1) < 2)
    throw py::value_error(name + ": expected shape (H, W, 3) with H, W >= 2, got shape " +
                          shape_text(array));
  const auto pixels =
      py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(array);
  const cv::Mat rgb(static_cast<int>(array.shape(0)), static_cast<int>(array.shape(1)), CV_8UC3,
                    const_cast<std::uint8_t*>(pixels.data()));
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

}  // namespace c2f::python
