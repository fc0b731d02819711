#include "c2f/vision/stereo/ground_truth.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "c2f/support/input_file.hpp"
#include "c2f/support/number_text.hpp"
#include "c2f/vision/image_io.hpp"
#include "c2f/vision/stereo/disparity_io.hpp"
#include "c2f/vision/stereo/kitti2015.hpp"
#include "c2f/vision/stereo/middlebury.hpp"
#include "c2f/vision/stereo/middlebury2014.hpp"
#include "stereo_pair_checks.hpp"

namespace c2f::vision {

namespace {

/// Whether `path` starts with a PFM header ("Pf" or "PF" and a line break).
bool is_pfm(const std::string& path) {
  if (const std::string why = why_not_a_file(path); !why.empty())
    throw std::invalid_argument("GT '" + path + "' " + why);
  std::ifstream in(path, std::ios::binary);
  char start[3] = {};
  if (!in.read(start, 3)) return false;
  return start[0] == 'P' && (start[1] == 'f' || start[1] == 'F') &&
         (start[2] == '\n' || start[2] == '\r' || start[2] == ' ');
}

/// Middlebury 2014's measure for a PFM in a training or test folder of size Q, H or F.
ErrorMeasure middlebury2014_measure_of(const std::string& path) {
  const std::string folder =
      std::filesystem::path(path).parent_path().parent_path().filename().string();
  if (folder == "trainingQ" || folder == "testQ")
    return middlebury2014_measure(Middlebury2014Size::quarter);
  if (folder == "trainingH" || folder == "testH")
    return middlebury2014_measure(Middlebury2014Size::half);
  if (folder == "trainingF" || folder == "testF")
    return middlebury2014_measure(Middlebury2014Size::full);
  return {"bad 2.0", 2.0, 0.0, true};
}

}  // namespace

void require_plausible_disparities(const cv::Mat& gt, const std::string& what) {
  for (int y = 0; y < gt.rows; ++y) {
    for (int x = 0; x < gt.cols; ++x) {
      const float d = gt.at<float>(y, x);
      // Disparities in the wrong byte order read as denormals or huge values.
      if (!std::isnan(d) && !(d == 0.0F || (d >= 1e-6F && d <= 65536.0F))) {
        throw std::invalid_argument(what + " holds the disparity " + format_real(d) + " at (" +
                                    std::to_string(x) + ", " + std::to_string(y) +
                                    "), not 0 nor in [1e-6, 65536]: is the sign of its scale "
                                    "(the byte order) right?");
      }
    }
  }
}

GroundTruth load_ground_truth(const std::string& path, double divisor) {
  if (!(divisor >= 0.0 && std::isfinite(divisor)))
    throw std::invalid_argument("GT divisor must be a finite number >= 0 (0: by the file)");
  GroundTruth truth;
  if (is_pfm(path)) {
    try {
      truth.disparity = read_pfm(path);
    } catch (const std::runtime_error& error) {
      throw std::invalid_argument(error.what());
    }
    require_plausible_disparities(truth.disparity, "GT '" + path + "'");
    detail::require_known_pixel(truth.disparity, "GT '" + path + "'");
    truth.measure = middlebury2014_measure_of(path);
    truth.convention = "Middlebury 2014 PFM (infinity = unknown)";
    return truth;
  }
  const cv::Mat raw = load_single_channel_image(path);  // 8 or 16 bits, never cut
  const bool deep = raw.depth() == CV_16U;
  if (!deep && divisor > 255.0) {
    throw std::invalid_argument("GT '" + path + "' is an 8-bit PNG: divided by " +
                                format_real(divisor) +
                                " every disparity would be below one pixel (KITTI's GT is a "
                                "16-bit PNG of disparity x 256)");
  }
  const double used = divisor > 0.0 ? divisor : deep ? 256.0 : 1.0;
  truth.disparity = load_gt_disparity(path, used);
  if (divisor == 0.0 && deep) {
    truth.measure = kitti_d1_measure();
    truth.convention = "KITTI 16-bit PNG (disparity x 256, 0 = unknown)";
  } else {
    truth.convention = std::string(deep ? "16" : "8") + "-bit PNG divided by " + format_real(used) +
                       " (0 = unknown)";
  }
  return truth;
}

}  // namespace c2f::vision
