#pragma once
// An interactive segmentation problem: an image, seed scribbles that fix some pixels' labels,
// and ground truth when there is any; loaded under one of three seed conventions.

#include <opencv2/core.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "c2f/core/grid.hpp"

namespace c2f::vision {

/// A pixel without a seed (in seeds) or not scored (in truth).
inline constexpr int kNoLabel = -1;

struct SegmentationScene {
  std::string name;
  cv::Mat image;                   ///< 8-bit BGR
  std::vector<int> seeds;          ///< per pixel (row-major): its seed label, or kNoLabel
  std::vector<int> truth;          ///< per pixel: its true label, or kNoLabel; empty without GT
  std::vector<cv::Vec3b> palette;  ///< BGR colour of each label, for pictures

  [[nodiscard]] int num_labels() const noexcept { return static_cast<int>(palette.size()); }
  [[nodiscard]] GridShape shape() const noexcept {
    return {static_cast<std::size_t>(image.cols), static_cast<std::size_t>(image.rows)};
  }
};

enum class SeedConvention {
  /// White = unlabelled, every other colour one label (labels in ascending (R, G, B) order, at
  /// most 64); a GT, when given, is a label image in those colours.
  colours,
  /// The cooperative-cuts multi-label data: the labels are the GT's colours in ascending
  /// (R, G, B) order and a seeded (non-white) pixel takes the GT label under it.
  labels_from_gt,
  /// The Jegelka-Bilmes binary data: red seeds (R > 127, G < 128, B < 128) = object (label 1),
  /// blue (R < 128, B > 127) = background (label 0), other colours unlabelled; GT grey 255 =
  /// object, 0 = background, 128 = not scored.
  binary,
};

std::string_view to_string(SeedConvention convention);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
SeedConvention seed_convention_from_string(std::string_view text);

struct SegmentationFiles {
  std::string image;  ///< any image OpenCV reads
  std::string seeds;  ///< seed scribbles (PNG)
  std::string gt;     ///< optional for colours and binary, required for labels_from_gt
  SeedConvention convention = SeedConvention::colours;
};

/// Loads and checks a scene. Throws std::invalid_argument naming the file and the problem
/// (sizes that differ, fewer than 2 labels, a label without seeds, GT colours or grey levels
/// that are no label, a seed on a pixel the GT does not score) and std::runtime_error naming
/// the path of an unreadable file.
SegmentationScene load_segmentation_scene(const SegmentationFiles& files);

/// The images of a scene, decoded: the image and the seeds 8-bit BGR, the GT (empty when none)
/// 8-bit BGR, or 8-bit grey for SeedConvention::binary.
struct SegmentationImages {
  cv::Mat image, seeds, gt;
};

/// The scene of decoded images, checked as load_segmentation_scene checks files (whose names
/// and convention `files` gives, for messages). Throws std::invalid_argument.
SegmentationScene segmentation_scene_from_images(const SegmentationImages& images,
                                                 const SegmentationFiles& files);

/// The label of every pixel of an 8-bit BGR image by its colour in `palette` (pixels of colour
/// `*skip`, when given, get kNoLabel). Throws std::invalid_argument "<what> '<path>': colour
/// (r,g,b) at (x, y) is none of the label colours" for the first pixel of another colour.
std::vector<int> labels_by_colour(const cv::Mat& image, const std::vector<cv::Vec3b>& palette,
                                  const std::string& what, const std::string& path,
                                  const cv::Vec3b* skip = nullptr);

/// The scene shrunk by an integer factor: the image by area averaging; a pixel of the result
/// is seeded with a label when any pixel of its block carries that seed (the first in raster
/// order when several do, so thin scribbles survive); the truth by the block's top-left pixel.
/// Factor 1 returns the scene unchanged. Throws std::invalid_argument for a factor < 1, an
/// image that would be smaller than 2x2, or a label that would lose all its seeds.
SegmentationScene downscale(SegmentationScene scene, int factor);

}  // namespace c2f::vision
