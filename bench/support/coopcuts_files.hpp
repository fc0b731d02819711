#pragma once
// Where the shared coopCuts data keeps an image's files, for the segmentation benchmarks.

#include <filesystem>
#include <stdexcept>
#include <string>

#include "c2f/vision/segmentation/segmentation_scene.hpp"

namespace c2f::bench {

/// The files of image `name` of a coopCuts SET under the data root, with the set's seed
/// convention: multilabel (coopcuts/runMultilabel: images/NAME.bmp, seeds/NAME.png,
/// labelings/NAME.bmp; labels from the GT) or binary (coopcuts/runBinary/dataset:
/// images/NAME.jpg, seeds/NAME.png, groundtruth/NAME.png). Throws std::invalid_argument for
/// another set.
inline vision::SegmentationFiles coopcuts_files(const std::filesystem::path& data,
                                                const std::string& set, const std::string& name) {
  if (set == "multilabel") {
    const auto dir = data / "coopcuts/runMultilabel";
    return {(dir / "images" / (name + ".bmp")).string(), (dir / "seeds" / (name + ".png")).string(),
            (dir / "labelings" / (name + ".bmp")).string(), vision::SeedConvention::labels_from_gt};
  }
  if (set == "binary") {
    const auto dir = data / "coopcuts/runBinary/dataset";
    return {(dir / "images" / (name + ".jpg")).string(), (dir / "seeds" / (name + ".png")).string(),
            (dir / "groundtruth" / (name + ".png")).string(), vision::SeedConvention::binary};
  }
  throw std::invalid_argument("SET must be multilabel or binary, got '" + set + "'");
}

}  // namespace c2f::bench
