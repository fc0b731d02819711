#pragma once
// Pictures of partitions, as in the paper's Figure 2e.

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "c2f/core/grid.hpp"
#include "c2f/driver/observer.hpp"
#include "c2f/lift/dense_partition.hpp"

namespace c2f::vision {

/// The k largest groups each in its own colour (distinct hues, largest first; ties by group
/// id), every other pixel black. 8-bit BGR image of the grid's size.
cv::Mat render_largest_groups(const DensePartition& partition, GridShape shape, int k);

/// Every pixel painted with the mean colour of its group in `image` (8-bit BGR, one pixel per
/// variable).
cv::Mat render_group_means(const DensePartition& partition, const cv::Mat& image);

/// An observer that keeps the partition of every coarse level of a run (when enabled) and
/// writes their pictures (render_largest_groups, 10 groups) as partition-levelK.png.
class LevelPartitionRecorder {
 public:
  explicit LevelPartitionRecorder(bool enabled) : enabled_(enabled) {}
  ObserverDecision operator()(const StepEvent& event);
  /// Writes one picture per recorded level into the folder `dir`.
  void write(const std::string& dir, GridShape shape) const;

 private:
  bool enabled_;
  std::vector<DensePartition> partitions_;
};

/// Writes an image (PNG by extension); throws std::runtime_error naming the path on failure.
void write_image(const std::string& path, const cv::Mat& image);

}  // namespace c2f::vision
