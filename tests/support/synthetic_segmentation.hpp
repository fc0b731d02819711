#pragma once
// A small synthetic segmentation problem written to files: an image of three coloured regions
// under noise, seed scribbles in three colours on white, and the label image in those colours.

#include <cstdint>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>

namespace c2f::test {

struct SegmentationFilesOnDisk {
  std::string image, seeds, gt;  ///< image.png, seeds.png, gt.png (labels in seed colours)
  cv::Vec3b colours[3];          ///< the seed / label colours (BGR), ascending in (R, G, B)
};

/// Writes the problem into `dir` (created): left third, middle disc and the rest are the
/// three regions; each gets a short scribble of its colour. The image's colours carry Gaussian
/// noise of deviation `noise` (per channel, from `seed`).
SegmentationFilesOnDisk write_synthetic_segmentation(const std::filesystem::path& dir, int width,
                                                     int height, std::uint64_t seed,
                                                     double noise = 18.0);

}  // namespace c2f::test
