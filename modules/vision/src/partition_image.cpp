#include "c2f/vision/partition_image.hpp"

#include <filesystem>

#include <algorithm>
#include <numeric>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace c2f::vision {

namespace {
void check_shape(const DensePartition& partition, std::size_t pixels, const char* who) {
  if (partition.num_variables() != pixels) {
    throw std::invalid_argument(std::string(who) + ": the partition covers " +
                                std::to_string(partition.num_variables()) +
                                " pixels, the image has " + std::to_string(pixels));
  }
}
}  // namespace

cv::Mat render_largest_groups(const DensePartition& partition, GridShape shape, int k) {
  check_shape(partition, shape.size(), "render_largest_groups");
  if (k < 0) throw std::invalid_argument("render_largest_groups: k must be >= 0");
  std::vector<std::size_t> order(partition.num_groups());
  std::iota(order.begin(), order.end(), 0);
  const auto shown = std::min<std::size_t>(static_cast<std::size_t>(k), order.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(shown), order.end(),
                    [&](std::size_t a, std::size_t b) {
                      const auto sa = partition.members(a).size(), sb = partition.members(b).size();
                      return sa > sb || (sa == sb && a < b);
                    });
  cv::Mat hsv(1, static_cast<int>(std::max<std::size_t>(shown, 1)), CV_8UC3), bgr;
  for (std::size_t i = 0; i < shown; ++i) {
    // Spread hues with the golden angle so neighbours in the ranking differ visibly.
    hsv.at<cv::Vec3b>(0, static_cast<int>(i)) = {
        static_cast<uchar>(static_cast<int>(static_cast<double>(i) * 111.25) % 180),
        static_cast<uchar>(i % 2 ? 255 : 190), 255};
  }
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  cv::Mat out(static_cast<int>(shape.height), static_cast<int>(shape.width), CV_8UC3,
              cv::Scalar(0, 0, 0));
  for (std::size_t i = 0; i < shown; ++i) {
    const cv::Vec3b colour = bgr.at<cv::Vec3b>(0, static_cast<int>(i));
    for (const VariableIndex v : partition.members(order[i])) {
      out.at<cv::Vec3b>(static_cast<int>(v / shape.width), static_cast<int>(v % shape.width)) =
          colour;
    }
  }
  return out;
}

cv::Mat render_group_means(const DensePartition& partition, const cv::Mat& image) {
  if (image.type() != CV_8UC3)
    throw std::invalid_argument("render_group_means: the image must be 8-bit 3-channel");
  check_shape(partition, static_cast<std::size_t>(image.rows) * image.cols, "render_group_means");
  std::vector<cv::Vec3d> sums(partition.num_groups(), cv::Vec3d(0, 0, 0));
  const auto width = static_cast<std::size_t>(image.cols);
  for (std::size_t v = 0; v < partition.num_variables(); ++v) {
    sums[partition.group_of(v)] +=
        cv::Vec3d(image.at<cv::Vec3b>(static_cast<int>(v / width), static_cast<int>(v % width)));
  }
  cv::Mat out(image.size(), CV_8UC3);
  for (std::size_t v = 0; v < partition.num_variables(); ++v) {
    const auto g = partition.group_of(v);
    const cv::Vec3d mean = sums[g] * (1.0 / static_cast<double>(partition.members(g).size()));
    out.at<cv::Vec3b>(static_cast<int>(v / width), static_cast<int>(v % width)) =
        cv::Vec3b(cv::saturate_cast<uchar>(mean[0]), cv::saturate_cast<uchar>(mean[1]),
                  cv::saturate_cast<uchar>(mean[2]));
  }
  return out;
}

void write_image(const std::string& path, const cv::Mat& image) {
  bool written = false;
  try {
    written = cv::imwrite(path, image);
  } catch (const cv::Exception& error) {
    throw std::runtime_error("cannot write image '" + path + "': " + error.what());
  }
  if (!written) throw std::runtime_error("cannot write image '" + path + "'");
}

ObserverDecision LevelPartitionRecorder::operator()(const StepEvent& event) {
  if (enabled_ && event.step == 0 && !event.at_original) {
    partitions_.push_back(
        DensePartition(std::vector<VariableIndex>(event.group_of.begin(), event.group_of.end()),
                       event.num_variables));
  }
  return ObserverDecision::continue_run;
}

void LevelPartitionRecorder::write(const std::string& dir, GridShape shape) const {
  const std::filesystem::path out(dir);
  for (std::size_t i = 0; i < partitions_.size(); ++i) {
    write_image((out / ("partition-level" + std::to_string(i) + ".png")).string(),
                render_largest_groups(partitions_[i], shape, 10));
  }
}

}  // namespace c2f::vision
