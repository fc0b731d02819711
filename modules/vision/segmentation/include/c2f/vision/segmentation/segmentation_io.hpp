#pragma once
// What a segmentation result looks like and how wrong it is.

#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "c2f/core/labeling.hpp"
#include "c2f/vision/segmentation/segmentation_scene.hpp"

namespace c2f::vision {

/// The labeling as an 8-bit BGR image in the scene's label colours.
cv::Mat label_image(std::span<const Label> labeling, const SegmentationScene& scene);

/// The inverse of label_image: the labeling an image file shows in the scene's label colours
/// (a labels.png, or another method's result drawn in the same colours). Throws
/// std::invalid_argument naming the file when it is unreadable, not the scene's size, or has a
/// pixel of a colour that is no label's.
Labeling read_label_image(const std::string& path, const SegmentationScene& scene);

/// The image with every pixel blended half and half with its label's colour, and the
/// boundaries between labels drawn white.
cv::Mat segmentation_overlay(std::span<const Label> labeling, const SegmentationScene& scene);

/// The fraction of scored pixels (truth != kNoLabel) whose label differs from the truth.
/// Throws std::invalid_argument for a size mismatch or when no pixel is scored.
double pixel_error(std::span<const Label> labeling, std::span<const int> truth);

/// pixel_error against the scene's truth, for TraceWriter's error column. Throws
/// std::invalid_argument when the scene has no truth.
std::function<double(std::span<const Label>)> pixel_error_function(const SegmentationScene& scene);

/// Writes labels.png and overlay.png into the folder `dir`; returns the pixel error when the
/// scene has a truth.
std::optional<double> write_segmentation_outputs(const std::string& dir,
                                                 std::span<const Label> labeling,
                                                 const SegmentationScene& scene);

}  // namespace c2f::vision
