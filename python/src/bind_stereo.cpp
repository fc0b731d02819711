// The stereo application from Python: images in and out as numpy arrays (RGB, as imageio and
// matplotlib give them), the scene loader of c2f-stereo, the TSGO energy, bad-pixel rates.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "c2f/vision/image_io.hpp"
#include "c2f/vision/stereo/evaluation.hpp"
#include "c2f/vision/stereo/stereo_scene.hpp"
#include "c2f/vision/stereo/tsgo_energy.hpp"
#include "image_arrays.hpp"
#include "memory_argument.hpp"
#include "model_energy.hpp"
#include "numpy_input.hpp"
#include "released_gil.hpp"

namespace c2f::python {

namespace py = pybind11;

namespace {

/// A CV_32F image as an (H, W) float32 array (NaN stays NaN).
py::array_t<float> float_image(const cv::Mat& image) {
  py::array_t<float> out({image.rows, image.cols});
  for (int y = 0; y < image.rows; ++y)
    std::copy(image.ptr<float>(y), image.ptr<float>(y) + image.cols,
              out.mutable_data() + static_cast<std::size_t>(y) * image.cols);
  return out;
}

/// An (H, W) float array (NaN = unknown) as CV_32F. Throws naming `name`.
cv::Mat float_mat(const py::handle& object, const std::string& name) {
  const py::array array = array_argument(object, name, "an (H, W) numeric numpy array");
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
    throw py::type_error(name + ": expected an (H, W) numeric numpy array");
  if (array.ndim() != 2)
    throw py::value_error(name + ": expected shape (H, W), got " + shape_text(array));
  const auto values = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
  return cv::Mat(static_cast<int>(array.shape(0)), static_cast<int>(array.shape(1)), CV_32F,
                 const_cast<float*>(values.data()))
      .clone();
}

py::dict read_stereo_pair(const std::string& left, const std::string& right, const std::string& gt,
                          const py::handle& gt_divisor, const std::string& mask,
                          const py::handle& downscale) {
  vision::StereoPairFiles files;
  files.left = left;
  files.right = right;
  files.gt = gt;
  files.gt_divisor = real_argument(gt_divisor, "gt_divisor");
  files.mask = mask;
  const int factor = static_cast<int>(integer_argument(downscale, "downscale", 1, 1024));
  vision::StereoScene scene;
  {
    const ReleasedGil free;  // file reading stalls no other thread
    scene = vision::downscale(vision::load_stereo_pair(files), factor);
  }
  py::dict out;
  out["left"] = rgb_array(scene.left);
  out["right"] = rgb_array(scene.right);
  out["gt"] = scene.gt.empty() ? py::object(py::none()) : py::object(float_image(scene.gt));
  if (scene.nonoccluded.empty()) {
    out["mask"] = py::none();
  } else {
    py::array_t<bool> evaluate({scene.nonoccluded.rows, scene.nonoccluded.cols});
    for (int y = 0; y < scene.nonoccluded.rows; ++y)
      for (int x = 0; x < scene.nonoccluded.cols; ++x)
        evaluate.mutable_data()[static_cast<std::size_t>(y) * scene.nonoccluded.cols + x] =
            scene.nonoccluded.at<std::uint8_t>(y, x) != 0;
    out["mask"] = evaluate;
  }
  return out;
}

ModelEnergy stereo_energy(const py::handle& left, const py::handle& right,
                          const py::handle& labels_argument, const std::string& smoothness,
                          const py::handle& truncation, const py::handle& threads_argument,
                          const py::handle& memory) {
  const MemoryBudget budget = memory_budget_from(memory);
  vision::TsgoOptions options;
  options.labels = static_cast<int>(integer_argument(labels_argument, "labels", 2, 256));
  options.threads = static_cast<int>(integer_argument(threads_argument, "threads", 0, 1024));
  const int labels = options.labels, threads = options.threads;
  try {
    options.smoothness = vision::stereo_smoothness_from_string(smoothness);
  } catch (const std::invalid_argument& error) {
    throw py::value_error(std::string("smoothness: ") + error.what());
  }
  options.truncation = real_argument(truncation, "truncation");
  if (const std::string problem = options.validate(); !problem.empty())
    throw py::value_error(problem);
  const cv::Mat left_bgr = bgr_image(left, "left");
  const cv::Mat right_bgr = bgr_image(right, "right");
  if (left_bgr.size() != right_bgr.size())
    throw py::value_error("left and right: the views differ in size");
  // Before anything is allocated: TSGO step 1 (the cost volume) must fit.
  require_memory_within(
      budget,
      "the TSGO energy of " + std::to_string(left_bgr.cols) + "x" + std::to_string(left_bgr.rows) +
          " pixels and " + std::to_string(labels) + " labels",
      vision::tsgo_memory_estimate(static_cast<std::size_t>(left_bgr.cols),
                                   static_cast<std::size_t>(left_bgr.rows), labels, threads));
  const ReleasedGil free;
  vision::TsgoProblem problem = vision::tsgo_problem(left_bgr, right_bgr, options);
  return ModelEnergy{
      std::move(problem.energy), {left_bgr.rows, left_bgr.cols}, problem.guide, true};
}

py::dict bad_pixel_rates(const py::handle& disparity, const py::handle& gt,
                         const py::handle& mask) {
  const cv::Mat d = float_mat(disparity, "disparity");
  const cv::Mat truth = float_mat(gt, "gt");
  cv::Mat evaluate;
  if (!mask.is_none()) {
    const cv::Mat m = float_mat(mask, "mask");
    m.convertTo(evaluate, CV_8U, 255.0);
    cv::threshold(evaluate, evaluate, 0, 255, cv::THRESH_BINARY);
  }
  vision::BadPixelRates rates;
  try {
    rates = vision::bad_pixel_rates(d, truth, evaluate);
  } catch (const std::invalid_argument& error) {
    throw py::value_error(error.what());
  }
  if (rates.known_pixels == 0)
    throw py::value_error("gt: no pixel has a known disparity (every entry NaN): nothing to score");
  if (!mask.is_none() && rates.nonoccluded_pixels == 0)
    throw py::value_error("mask: no pixel with known GT is marked: nothing to score");
  py::dict out, nonoccluded, all;
  for (std::size_t i = 0; i < rates.thresholds.size(); ++i) {
    nonoccluded[py::float_(rates.thresholds[i])] = rates.nonoccluded[i];
    all[py::float_(rates.thresholds[i])] = rates.all[i];
  }
  out["nonoccluded"] = mask.is_none() ? py::object(py::none()) : py::object(nonoccluded);
  out["all"] = all;
  out["nonoccluded_pixels"] = rates.nonoccluded_pixels;
  out["known_pixels"] = rates.known_pixels;
  return out;
}

}  // namespace

void bind_stereo(py::module_& module) {
  module.def(
      "read_image",
      [](const std::string& path) {
        cv::Mat image;
        {
          const ReleasedGil free;  // file reading stalls no other thread
          image = vision::load_colour_image(path);
        }
        return rgb_array(image);
      },
      py::arg("path"), "An image file as an (H, W, 3) uint8 RGB array (grey is made colour).");
  module.def("read_stereo_pair", &read_stereo_pair, py::arg("left"), py::arg("right"),
             py::arg("gt") = "", py::arg("gt_divisor") = 0.0, py::arg("mask") = "",
             py::arg("downscale") = 1,
             "A stereo pair loaded as c2f-stereo loads it: a dict with 'left' and 'right' (RGB "
             "uint8), 'gt' ((H, W) float32 disparities, NaN unknown; None without a GT file; a "
             "PFM, a 16-bit KITTI PNG read as disparity x 256, or a PNG divided by gt_divisor, "
             "0: by the file) and "
             "'mask' ((H, W) bool, True = non-occluded; None without one), all shrunk by "
             "`downscale` (views by area, GT by nearest neighbour divided by the factor).");
  module.def("stereo_energy", &stereo_energy, py::arg("left"), py::arg("right"),
             py::arg("labels") = 85, py::arg("smoothness") = "tsgo_step",
             py::arg("truncation") = 2.0, py::arg("threads") = 0, py::arg("memory") = py::none(),
             "The TSGO stereo energy of two RGB uint8 views (H, W, 3): disparities 0..labels-1 "
             "of the left view, a 4-connected grid. Its schedules include the stereo presets "
             "(paper, paper-slic, regions, aggregated, ...) and slic:S levels on the left view. "
             "threads: cores preparing the data (0: all); the energy is the same for every "
             "count. memory: the budget in GiB the preparation must fit (None: a quarter of "
             "this machine's memory, growing to the run's needs up to half, at most what is "
             "available); ValueError naming it otherwise.");
  module.def("bad_pixel_rates", &bad_pixel_rates, py::arg("disparity"), py::arg("gt"),
             py::arg("mask") = py::none(),
             "Fractions of pixels with |disparity - gt| above 0.5, 1 and 2, over all pixels of "
             "known GT (gt not NaN) and over the mask's pixels: {'nonoccluded': {t: rate} (None "
             "without a mask), 'all': {t: rate}, 'nonoccluded_pixels', 'known_pixels'}. A GT "
             "with no known pixel, or a mask marking none, is a ValueError: nothing to score.");
}

}  // namespace c2f::python
