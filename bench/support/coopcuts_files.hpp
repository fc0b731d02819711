#pragma once
// Where the shared coopCuts data keeps an image's files, for the segmentation benchmarks.

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "c2f/vision/segmentation/segmentation_scene.hpp"

namespace c2f::bench {

/// The folder of a coopCuts SET under the data root: coopcuts/runMultilabel (multilabel) or
/// coopcuts/runBinary/dataset (binary). Throws std::invalid_argument for another set.
inline std::filesystem::path coopcuts_folder(const std::filesystem::path& data,
                                             const std::string& set) {
  if (set == "multilabel") return data / "coopcuts/runMultilabel";
  if (set == "binary") return data / "coopcuts/runBinary/dataset";
  throw std::invalid_argument("SET must be multilabel or binary, got '" + set + "'");
}

/// The files of image `name` of a coopCuts SET under the data root, with the set's seed
/// convention: multilabel (coopcuts/runMultilabel: images/NAME.bmp, seeds/NAME.png,
/// labelings/NAME.bmp; labels from the GT) or binary (coopcuts/runBinary/dataset:
/// images/NAME.jpg, seeds/NAME.png, groundtruth/NAME.png). Throws std::invalid_argument for
/// another set.
inline vision::SegmentationFiles coopcuts_files(const std::filesystem::path& data,
                                                const std::string& set, const std::string& name) {
  const std::filesystem::path dir = coopcuts_folder(data, set);
  if (set == "multilabel") {
    return {(dir / "images" / (name + ".bmp")).string(), (dir / "seeds" / (name + ".png")).string(),
            (dir / "labelings" / (name + ".bmp")).string(), vision::SeedConvention::labels_from_gt};
  }
  return {(dir / "images" / (name + ".jpg")).string(), (dir / "seeds" / (name + ".png")).string(),
          (dir / "groundtruth" / (name + ".png")).string(), vision::SeedConvention::binary};
}

/// The images of a coopCuts SET under the data root that have an image, seeds and a ground
/// truth (coopcuts_files), in name order. Throws std::invalid_argument naming the folder when
/// it has none.
inline std::vector<std::string> labelled_images(const std::filesystem::path& data,
                                                const std::string& set) {
  const std::filesystem::path seeds = coopcuts_folder(data, set) / "seeds";
  std::error_code error;
  std::vector<std::string> names;
  if (std::filesystem::is_directory(seeds, error)) {
    for (const auto& entry : std::filesystem::directory_iterator(seeds)) {
      if (entry.path().extension() != ".png") continue;
      const std::string name = entry.path().stem().string();
      const vision::SegmentationFiles files = coopcuts_files(data, set, name);
      if (std::filesystem::is_regular_file(files.image, error) &&
          std::filesystem::is_regular_file(files.gt, error))
        names.push_back(name);
    }
  }
  std::sort(names.begin(), names.end());
  if (names.empty())
    throw std::invalid_argument("--data: no image of '" + coopcuts_folder(data, set).string() +
                                "' has seeds and a ground truth");
  return names;
}

}  // namespace c2f::bench
