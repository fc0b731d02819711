#include "c2f/vision/segmentation/segmentation_scene.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "c2f/support/enum_names.hpp"
#include "c2f/vision/image_io.hpp"

namespace c2f::vision {

namespace {

/// (R, G, B) of a BGR pixel: the order labels are sorted in.
std::array<int, 3> rgb(const cv::Vec3b& bgr) {
  return {bgr[2], bgr[1], bgr[0]};
}

std::string colour_text(const cv::Vec3b& bgr) {
  return "(" + std::to_string(bgr[2]) + "," + std::to_string(bgr[1]) + "," +
         std::to_string(bgr[0]) + ")";
}

std::string size_text(const cv::Mat& image) {
  return std::to_string(image.cols) + "x" + std::to_string(image.rows);
}

void require_size(const cv::Mat& image, const cv::Mat& other, const std::string& what,
                  const std::string& path) {
  if (other.size() != image.size()) {
    throw std::invalid_argument(what + " '" + path + "' is " + size_text(other) +
                                ", the image is " + size_text(image));
  }
}

const cv::Vec3b kWhite(255, 255, 255);
constexpr std::size_t kMaxSeedColours = 64;

/// The distinct colours of `image` other than `skip` in ascending (R, G, B) order.
std::vector<cv::Vec3b> distinct_colours(const cv::Mat& image, const cv::Vec3b* skip) {
  std::map<std::array<int, 3>, cv::Vec3b> colours;
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const cv::Vec3b c = image.at<cv::Vec3b>(y, x);
      if (skip == nullptr || c != *skip) colours.emplace(rgb(c), c);
    }
  }
  std::vector<cv::Vec3b> result;
  for (const auto& [key, colour] : colours) result.push_back(colour);
  return result;
}

}  // namespace

std::vector<int> labels_by_colour(const cv::Mat& image, const std::vector<cv::Vec3b>& palette,
                                  const std::string& what, const std::string& path,
                                  const cv::Vec3b* skip) {
  std::vector<int> labels(static_cast<std::size_t>(image.total()), kNoLabel);
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const cv::Vec3b c = image.at<cv::Vec3b>(y, x);
      if (skip != nullptr && c == *skip) continue;
      const auto it = std::find(palette.begin(), palette.end(), c);
      if (it == palette.end()) {
        throw std::invalid_argument(what + " '" + path + "': colour " + colour_text(c) + " at (" +
                                    std::to_string(x) + ", " + std::to_string(y) +
                                    ") is none of the label colours");
      }
      labels[static_cast<std::size_t>(y * image.cols + x)] = static_cast<int>(it - palette.begin());
    }
  }
  return labels;
}

namespace {

void require_seeds_for_every_label(const SegmentationScene& scene, const std::string& path) {
  std::vector<std::size_t> count(scene.palette.size(), 0);
  for (const int label : scene.seeds) {
    if (label != kNoLabel) ++count[static_cast<std::size_t>(label)];
  }
  for (std::size_t l = 0; l < count.size(); ++l) {
    if (count[l] == 0) {
      throw std::invalid_argument("SEEDS '" + path + "': label " + std::to_string(l) + " (colour " +
                                  colour_text(scene.palette[l]) +
                                  ") has no seed pixels; every label needs some");
    }
  }
}

}  // namespace

std::string_view to_string(SeedConvention convention) {
  switch (convention) {
    case SeedConvention::colours:
      return "colours";
    case SeedConvention::labels_from_gt:
      return "labels-from-gt";
    case SeedConvention::binary:
      return "binary";
  }
  return "unknown";
}

SeedConvention seed_convention_from_string(std::string_view text) {
  constexpr SeedConvention kAll[] = {SeedConvention::colours, SeedConvention::labels_from_gt,
                                     SeedConvention::binary};
  return enum_from_string(text, kAll, "seed convention");
}

SegmentationScene load_segmentation_scene(const SegmentationFiles& files) {
  SegmentationImages images;
  images.image = load_colour_image(files.image);
  images.seeds = load_colour_image_on_white(files.seeds);  // transparent: no seed
  if (!files.gt.empty()) {
    images.gt = files.convention == SeedConvention::binary ? load_grey_image(files.gt)
                                                           : load_colour_image(files.gt);
  }
  return segmentation_scene_from_images(images, files);
}

SegmentationScene segmentation_scene_from_images(const SegmentationImages& images,
                                                 const SegmentationFiles& files) {
  const auto require_type = [](const cv::Mat& image, int type, const std::string& what,
                               const std::string& path) {
    if (image.type() != type || image.empty()) {
      throw std::invalid_argument(what + " '" + path + "' is not a non-empty 8-bit " +
                                  (type == CV_8UC1 ? "grey" : "colour") + " image");
    }
  };
  SegmentationScene scene;
  scene.name = std::filesystem::path(files.image).stem().string();
  require_type(images.image, CV_8UC3, "IMAGE", files.image);
  require_type(images.seeds, CV_8UC3, "SEEDS", files.seeds);
  const bool has_gt = !files.gt.empty();
  if (has_gt) {
    require_type(images.gt, files.convention == SeedConvention::binary ? CV_8UC1 : CV_8UC3, "GT",
                 files.gt);
  }
  // Pixels are read by row-major index below: views into larger images are copied first.
  const auto continuous = [](const cv::Mat& image) {
    return image.isContinuous() ? image : image.clone();
  };
  scene.image = continuous(images.image);
  const cv::Mat seeds = continuous(images.seeds);
  const cv::Mat gt_image = has_gt ? continuous(images.gt) : cv::Mat();
  require_size(scene.image, seeds, "SEEDS", files.seeds);
  const std::size_t n = scene.image.total();
  scene.seeds.assign(n, kNoLabel);

  switch (files.convention) {
    case SeedConvention::colours: {
      scene.palette = distinct_colours(seeds, &kWhite);
      if (scene.palette.size() < 2) {
        throw std::invalid_argument("SEEDS '" + files.seeds + "' has " +
                                    std::to_string(scene.palette.size()) +
                                    " seed colour(s) besides white; segmentation needs at least 2");
      }
      if (scene.palette.size() > kMaxSeedColours) {
        throw std::invalid_argument(
            "SEEDS '" + files.seeds + "' has " + std::to_string(scene.palette.size()) +
            " colours besides white; scribbles use a few (at most " +
            std::to_string(kMaxSeedColours) + "): is it an image rather than seeds?");
      }
      scene.seeds = labels_by_colour(seeds, scene.palette, "SEEDS", files.seeds, &kWhite);
      if (has_gt) {
        require_size(scene.image, gt_image, "GT", files.gt);
        scene.truth = labels_by_colour(gt_image, scene.palette, "GT", files.gt);
      }
      break;
    }
    case SeedConvention::labels_from_gt: {
      if (!has_gt) throw std::invalid_argument("labels from the GT need a GT labeling (--gt)");
      const cv::Mat& gt = gt_image;
      require_size(scene.image, gt, "GT", files.gt);
      scene.palette = distinct_colours(gt, nullptr);
      if (scene.palette.size() < 2) {
        throw std::invalid_argument("GT '" + files.gt + "' has " +
                                    std::to_string(scene.palette.size()) +
                                    " colour(s); segmentation needs at least 2 labels");
      }
      scene.truth = labels_by_colour(gt, scene.palette, "GT", files.gt);
      for (std::size_t i = 0; i < n; ++i) {
        if (seeds.at<cv::Vec3b>(static_cast<int>(i)) != kWhite) scene.seeds[i] = scene.truth[i];
      }
      break;
    }
    case SeedConvention::binary: {
      scene.palette = {cv::Vec3b(255, 0, 0), cv::Vec3b(0, 0, 255)};  // blue background, red object
      for (std::size_t i = 0; i < n; ++i) {
        const auto [r, g, b] = rgb(seeds.at<cv::Vec3b>(static_cast<int>(i)));
        if (r > 127 && g < 128 && b < 128) {
          scene.seeds[i] = 1;
        } else if (r < 128 && b > 127) {
          scene.seeds[i] = 0;
        } else if (r < 128 || g < 128 || b < 128) {
          // Neither red, blue nor light (unlabelled): a seed of a colour the convention does
          // not have, which the reference's rule would silently leave unlabelled.
          const auto width = static_cast<std::size_t>(seeds.cols);
          throw std::invalid_argument(
              "SEEDS '" + files.seeds + "': pixel (" + std::to_string(i % width) + ", " +
              std::to_string(i / width) + ") has the colour (" + std::to_string(r) + ", " +
              std::to_string(g) + ", " + std::to_string(b) +
              "), which --binary reads as none of red (object), blue (background) and white "
              "(unlabelled)");
        }
      }
      if (has_gt) {
        const cv::Mat& gt = gt_image;
        require_size(scene.image, gt, "GT", files.gt);
        scene.truth.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
          const int value = gt.at<std::uint8_t>(static_cast<int>(i));
          if (value != 0 && value != 128 && value != 255) {
            throw std::invalid_argument(
                "GT '" + files.gt + "': grey level " + std::to_string(value) + " at pixel " +
                std::to_string(i) + " is none of 0 (background), 128 (not scored), 255 (object)");
          }
          scene.truth[i] = value == 255 ? 1 : value == 0 ? 0 : kNoLabel;
        }
      }
      break;
    }
  }
  require_seeds_for_every_label(scene, files.seeds);
  return scene;
}

SegmentationScene downscale(SegmentationScene scene, int factor) {
  if (factor < 1) throw std::invalid_argument("downscale: the factor must be >= 1");
  if (factor == 1) return scene;
  const int w = scene.image.cols / factor, h = scene.image.rows / factor;
  if (w < 2 || h < 2) {
    throw std::invalid_argument("downscale: a " + size_text(scene.image) + " image shrunk by " +
                                std::to_string(factor) + " would be smaller than 2x2");
  }
  const int old_w = scene.image.cols;
  cv::Mat image;
  cv::resize(scene.image, image, cv::Size(w, h), 0, 0, cv::INTER_AREA);
  std::vector<int> seeds(static_cast<std::size_t>(w * h), kNoLabel), truth;
  if (!scene.truth.empty()) truth.assign(seeds.size(), kNoLabel);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const auto i = static_cast<std::size_t>(y * w + x);
      for (int dy = 0; dy < factor && seeds[i] == kNoLabel; ++dy) {
        for (int dx = 0; dx < factor && seeds[i] == kNoLabel; ++dx)
          seeds[i] =
              scene.seeds[static_cast<std::size_t>((y * factor + dy) * old_w + x * factor + dx)];
      }
      if (!truth.empty())
        truth[i] = scene.truth[static_cast<std::size_t>((y * factor) * old_w + x * factor)];
    }
  }
  scene.image = image;
  scene.seeds = std::move(seeds);
  scene.truth = std::move(truth);
  std::vector<std::size_t> count(scene.palette.size(), 0);
  for (const int label : scene.seeds) {
    if (label != kNoLabel) ++count[static_cast<std::size_t>(label)];
  }
  for (std::size_t l = 0; l < count.size(); ++l) {
    if (count[l] == 0)
      throw std::invalid_argument("downscale: label " + std::to_string(l) + " loses all its seeds");
  }
  return scene;
}

}  // namespace c2f::vision
