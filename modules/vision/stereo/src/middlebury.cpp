#include "c2f/vision/stereo/middlebury.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "c2f/support/input_file.hpp"
#include "c2f/support/number_text.hpp"
#include "c2f/support/text_input.hpp"
#include "c2f/vision/image_io.hpp"
#include "c2f/vision/stereo/kitti2015.hpp"
#include "c2f/vision/stereo/middlebury2014.hpp"

namespace c2f::vision {

namespace {
std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream stream(line);
  while (std::getline(stream, field, ',')) fields.push_back(field);
  return fields;
}
}  // namespace

std::vector<SceneRow> parse_scene_table(std::string_view text, const std::string& source) {
  std::istringstream in{std::string(without_byte_order_mark(text))};
  std::string line;
  if (!std::getline(in, line)) throw std::invalid_argument("scene table '" + source + "' is empty");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  const auto header = split_csv(line);
  auto column = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end())
      throw std::invalid_argument("scene table '" + source + "': no column '" + name + "'");
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t year = column("year"), scene = column("scene"), dir = column("dir"),
                    width = column("width"), height = column("height"),
                    divisor = column("gt_divisor"), files = column("files");
  const auto integer = [](const std::string& field, const char* name, long long low,
                          long long high) {
    const std::optional<long long> value = parse_integer(field);
    if (!value || *value < low || *value > high) {
      throw std::invalid_argument(std::string(name) + ": expected an integer in [" +
                                  std::to_string(low) + ", " + std::to_string(high) + "], got '" +
                                  field + "'");
    }
    return static_cast<int>(*value);
  };
  std::vector<SceneRow> rows;
  for (int number = 2; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const auto fields = split_csv(line);
    try {
      if (fields.size() != header.size()) {
        throw std::invalid_argument("has " + std::to_string(fields.size()) +
                                    " fields, the header " + std::to_string(header.size()));
      }
      SceneRow row;
      row.year = integer(fields[year], "year", 0, 9999);
      row.scene = fields[scene];
      row.dir = fields[dir];
      if (row.scene.empty() || row.dir.empty())
        throw std::invalid_argument("the scene name and its dir must not be empty");
      row.width = integer(fields[width], "width", 1, 1 << 16);
      row.height = integer(fields[height], "height", 1, 1 << 16);
      const std::optional<double> gt_divisor = parse_real(fields[divisor]);
      if (!gt_divisor || *gt_divisor <= 0.0) {
        throw std::invalid_argument("gt_divisor: expected a finite number > 0, got '" +
                                    fields[divisor] + "'");
      }
      row.gt_divisor = *gt_divisor;
      std::istringstream names(fields[files]);
      for (std::string name; names >> name;) row.files.push_back(name);
      if (std::any_of(rows.begin(), rows.end(),
                      [&](const SceneRow& earlier) { return earlier.scene == row.scene; }))
        throw std::invalid_argument("scene '" + row.scene + "' appears twice");
      rows.push_back(std::move(row));
    } catch (const std::exception& error) {
      throw std::invalid_argument("scene table '" + source + "' line " + std::to_string(number) +
                                  ": " + error.what());
    }
  }
  return rows;
}

std::vector<SceneRow> read_scene_table(const std::string& path) {
  return parse_scene_table(read_input_file(path, "scene table", kMaxTextInputBytes), path);
}

cv::Mat load_gt_disparity(const std::string& path, double divisor) {
  if (!(divisor > 0.0 && std::isfinite(divisor)))
    throw std::invalid_argument("GT divisor must be a finite number > 0, got " +
                                std::to_string(divisor));
  const cv::Mat raw = load_single_channel_image(path);  // 8 or 16 bits, never cut
  cv::Mat gt(raw.size(), CV_32F);
  std::size_t known = 0;
  for (int y = 0; y < raw.rows; ++y) {
    for (int x = 0; x < raw.cols; ++x) {
      const int v = raw.depth() == CV_16U ? raw.at<std::uint16_t>(y, x) : raw.at<uchar>(y, x);
      gt.at<float>(y, x) =
          v == 0 ? std::numeric_limits<float>::quiet_NaN() : static_cast<float>(v / divisor);
      known += v != 0;
    }
  }
  if (known == 0) {
    throw std::invalid_argument("GT '" + path +
                                "' has no known pixel (every value is 0, which means unknown): "
                                "nothing could be evaluated against it");
  }
  return gt;
}

cv::Mat left_right_nonoccluded(const cv::Mat& gt_left, const cv::Mat& gt_right) {
  if (gt_left.size() != gt_right.size() || gt_left.type() != CV_32F || gt_right.type() != CV_32F) {
    throw std::invalid_argument("left_right_nonoccluded: the GT maps must be CV_32F of one size");
  }
  cv::Mat mask(gt_left.size(), CV_8U, cv::Scalar(0));
  for (int y = 0; y < gt_left.rows; ++y) {
    for (int x = 0; x < gt_left.cols; ++x) {
      const float d = gt_left.at<float>(y, x);
      if (std::isnan(d)) continue;
      const int xr = x - static_cast<int>(std::lround(d));
      if (xr < 0 || xr >= gt_left.cols) continue;
      const float dr = gt_right.at<float>(y, xr);
      if (!std::isnan(dr) && std::abs(d - dr) <= 1.0F) mask.at<uchar>(y, x) = 255;
    }
  }
  return mask;
}

cv::Mat load_mask(const std::string& path) {
  const cv::Mat mask = load_grey_image(path);
  std::size_t evaluated = 0;
  for (int y = 0; y < mask.rows; ++y) {
    for (int x = 0; x < mask.cols; ++x) {
      const int v = mask.at<uchar>(y, x);
      if (v != 0 && v != 255) {
        throw std::invalid_argument("mask '" + path + "' has the grey value " + std::to_string(v) +
                                    " at (" + std::to_string(x) + ", " + std::to_string(y) +
                                    "): expected only 255 (evaluate) and 0 (occluded)");
      }
      evaluated += v == 255;
    }
  }
  if (evaluated == 0) {
    throw std::invalid_argument("mask '" + path +
                                "' marks no pixel for evaluation (no value 255): nothing could "
                                "be evaluated");
  }
  return mask == 255;
}

StereoScene load_scene(const SceneRow& row, const std::string& data_root) {
  const std::filesystem::path dir = std::filesystem::path(data_root) / row.dir;
  auto has = [&](const std::string& name) {
    return std::find(row.files.begin(), row.files.end(), name) != row.files.end();
  };
  StereoScene scene;
  scene.name = row.scene;
  scene.left = load_colour_image((dir / "left.png").string());
  scene.right = load_colour_image((dir / "right.png").string());
  // Every picture of a scene must have the views' size: nothing is resized to fit.
  auto require_view_size = [&](const cv::Mat& image, const std::string& name) {
    if (image.size() != scene.left.size()) {
      throw std::invalid_argument("scene " + row.scene + ": " + (dir / name).string() + " is " +
                                  std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                                  ", the views are " + std::to_string(scene.left.cols) + "x" +
                                  std::to_string(scene.left.rows));
    }
  };
  require_view_size(scene.right, "right.png");
  if (has("disp_left.png")) {
    scene.gt = load_gt_disparity((dir / "disp_left.png").string(), row.gt_divisor);
    require_view_size(scene.gt, "disp_left.png");
  }
  scene.nonoccluded_source = "none";
  if (has("nonocc.png")) {
    scene.nonoccluded = load_mask((dir / "nonocc.png").string());
    require_view_size(scene.nonoccluded, "nonocc.png");
    scene.nonoccluded_source = "official mask";
  } else if (has("disp_right.png") && !scene.gt.empty()) {
    const cv::Mat right_gt = load_gt_disparity((dir / "disp_right.png").string(), row.gt_divisor);
    require_view_size(right_gt, "disp_right.png");
    scene.nonoccluded = left_right_nonoccluded(scene.gt, right_gt);
    scene.nonoccluded_source = "left-right check";
  }
  return scene;
}

StereoScene load_named_scene(const std::string& data_root, const std::string& name) {
  const std::filesystem::path root(data_root);
  for (const std::string_view dataset : {"middlebury2014/", "kitti2015/"}) {
    if (!name.starts_with(dataset)) continue;
    const std::string rest = name.substr(dataset.size());
    if (rest.empty() || rest.find('/') != std::string::npos || rest == "." || rest == "..")
      throw std::invalid_argument("scene '" + name + "': expected " + std::string(dataset) +
                                  "NAME");
    StereoScene scene = dataset == "kitti2015/"
                            ? load_kitti2015_pair((root / "kitti2015").string(), rest)
                            : load_middlebury2014_scene((root / name).string());
    scene.name = name;
    return scene;
  }
  if (name == kOpencvDocAloe) {
    const std::filesystem::path dir(kOpencvDocData);
    StereoPairFiles files;
    files.left = (dir / "aloeL.jpg").string();
    files.right = (dir / "aloeR.jpg").string();
    files.gt = (dir / "aloeGT.png").string();
    files.gt_divisor = 1.0;
    StereoScene scene = load_stereo_pair(files);
    scene.name = name;
    scene.disparity_range = kOpencvDocAloeLabels;
    return scene;
  }
  const std::string table = (std::filesystem::path(data_root) / "scenes.csv").string();
  const std::vector<SceneRow> rows = read_scene_table(table);
  for (const SceneRow& row : rows) {
    if (row.scene == name) return load_scene(row, data_root);
  }
  std::string names;
  for (const SceneRow& row : rows) names += " " + row.scene;
  throw std::invalid_argument("no scene '" + name + "' in " + table + " (have:" + names +
                              "), and it is not middlebury2014/NAME, kitti2015/ID or " +
                              kOpencvDocAloe);
}

}  // namespace c2f::vision
