#include <catch2/catch.hpp>

#include <cstdint>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "c2f/vision/stereo/disparity_io.hpp"
#include "c2f/vision/stereo/evaluation.hpp"
#include "c2f/vision/stereo/middlebury.hpp"

using namespace c2f;
using namespace c2f::vision;

namespace {
std::filesystem::path scratch_dir() {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-stereo-io";
  std::filesystem::create_directories(dir);
  return dir;
}
const float kNaN = std::numeric_limits<float>::quiet_NaN();
}  // namespace

TEST_CASE("PFM and 16-bit PNG disparity files round-trip", "[stereo][io]") {
  cv::Mat disparity(3, 4, CV_32F);
  for (int i = 0; i < 12; ++i)
    disparity.at<float>(i / 4, i % 4) = 0.25F * static_cast<float>(i) + 1.0F;
  disparity.at<float>(1, 2) = kNaN;
  const auto dir = scratch_dir();
  write_pfm((dir / "d.pfm").string(), disparity);
  const cv::Mat pfm = read_pfm((dir / "d.pfm").string());
  write_disparity_png16((dir / "d.png").string(), disparity);
  const cv::Mat png = read_disparity_png16((dir / "d.png").string());
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) {
      const float expected = disparity.at<float>(y, x);
      if (std::isnan(expected)) {
        CHECK(std::isnan(pfm.at<float>(y, x)));
        CHECK(std::isnan(png.at<float>(y, x)));
      } else {
        CHECK(pfm.at<float>(y, x) == expected);
        CHECK(png.at<float>(y, x) == expected);  // multiples of 1/4 are exact in 1/256 steps
      }
    }
  }
  // Row order: PFM stores the bottom row first.
  std::ifstream raw(dir / "d.pfm", std::ios::binary);
  std::string magic, dims, scale;
  std::getline(raw, magic);
  std::getline(raw, dims);
  std::getline(raw, scale);
  float first;
  raw.read(reinterpret_cast<char*>(&first), 4);
  CHECK(magic == "Pf");
  CHECK(scale == "-1");
  CHECK(first == disparity.at<float>(2, 0));
  CHECK_THROWS_WITH(read_pfm((dir / "d.png").string()),
                    Catch::Contains("is not a single-channel PFM file"));
  CHECK_THROWS_WITH(
      read_pfm((dir / "missing.pfm").string()),
      Catch::Contains("PFM file '" + (dir / "missing.pfm").string() + "' does not exist"));
}

TEST_CASE("bad-pixel rates count known and non-occluded pixels", "[stereo][evaluation]") {
  // GT: 4 pixels, one unknown; the disparity is off by 0.7 at pixel 1 and by 3 at pixel 2.
  cv::Mat gt = (cv::Mat_<float>(1, 4) << 5.0F, 5.0F, 5.0F, kNaN);
  const cv::Mat disparity = (cv::Mat_<float>(1, 4) << 5.0F, 5.7F, 8.0F, 1.0F);
  const cv::Mat mask = (cv::Mat_<uchar>(1, 4) << 255, 255, 0, 0);
  const BadPixelRates rates = bad_pixel_rates(disparity, gt, mask);
  CHECK(rates.known_pixels == 3);
  CHECK(rates.nonoccluded_pixels == 2);
  CHECK(rates.all[0] == Approx(2.0 / 3));  // > 0.5: pixels 1 and 2
  CHECK(rates.all[1] == Approx(1.0 / 3));  // > 1: pixel 2
  CHECK(rates.nonoccluded[0] == Approx(0.5));
  CHECK(rates.nonoccluded[1] == 0.0);
  CHECK(rates.reference_variant == Approx(1.0 / 4));  // divided by all 4 pixels
  CHECK_THAT(bad_pixel_rates(disparity, gt, cv::Mat()).brief(),
             Catch::Contains("no occlusion mask"));
  CHECK_THROWS_WITH(bad_pixel_rates(disparity, cv::Mat(2, 2, CV_32F), mask),
                    Catch::Contains("of one size"));
}

TEST_CASE("GT loading, the left-right check and the scene table", "[stereo][middlebury]") {
  const auto dir = scratch_dir();
  const cv::Mat raw = (cv::Mat_<uchar>(1, 4) << 0, 12, 12, 8);
  cv::imwrite((dir / "gt.png").string(), raw);
  const cv::Mat gt = load_gt_disparity((dir / "gt.png").string(), 4.0);
  CHECK(std::isnan(gt.at<float>(0, 0)));
  CHECK(gt.at<float>(0, 1) == 3.0F);
  CHECK_THROWS_WITH(load_gt_disparity((dir / "gt.png").string(), 0.0),
                    Catch::Contains("GT divisor must be a finite number > 0"));
  CHECK_THROWS_WITH(load_gt_disparity((dir / "gt.png").string(), INFINITY),
                    Catch::Contains("GT divisor must be a finite number > 0"));
  // A 16-bit GT keeps values above 255 (it was once read as 8 bits and cut).
  const cv::Mat wide = (cv::Mat_<std::uint16_t>(1, 3) << 0, 300, 1000);
  cv::imwrite((dir / "gt16.png").string(), wide);
  const cv::Mat gt16 = load_gt_disparity((dir / "gt16.png").string(), 4.0);
  CHECK(std::isnan(gt16.at<float>(0, 0)));
  CHECK(gt16.at<float>(0, 1) == 75.0F);
  CHECK(gt16.at<float>(0, 2) == 250.0F);
  cv::imwrite((dir / "gt-grey-rgb.png").string(), cv::Mat(1, 2, CV_8UC3, cv::Scalar(8, 8, 8)));
  CHECK(load_gt_disparity((dir / "gt-grey-rgb.png").string(), 4.0).at<float>(0, 1) == 2.0F);
  cv::imwrite((dir / "gt-colour.png").string(), cv::Mat(2, 2, CV_8UC3, cv::Scalar(1, 2, 3)));
  CHECK_THROWS_WITH(
      load_gt_disparity((dir / "gt-colour.png").string(), 1.0),
      Catch::Contains("has 3 channels") && Catch::Contains("expected one channel of 8 or 16 bits"));
  CHECK_THROWS_WITH(load_gt_disparity((dir / "none.png").string(), 1.0),
                    Catch::Contains("does not exist"));

  // Left GT (1, 1, 9, 1): pixel 0 leaves the image, pixel 2 maps outside too; pixel 3 maps to
  // right pixel 2, whose GT 5 disagrees.
  const cv::Mat left = (cv::Mat_<float>(1, 4) << 1.0F, 1.0F, 9.0F, 1.0F);
  const cv::Mat right = (cv::Mat_<float>(1, 4) << 1.0F, 1.0F, 5.0F, kNaN);
  const cv::Mat mask = left_right_nonoccluded(left, right);
  CHECK(mask.at<uchar>(0, 0) == 0);
  CHECK(mask.at<uchar>(0, 1) == 255);
  CHECK(mask.at<uchar>(0, 2) == 0);
  CHECK(mask.at<uchar>(0, 3) == 0);

  std::ofstream table(dir / "scenes.csv");
  table << "year,scene,dir,width,height,scale,gt_divisor,files\n2003,Toy,toy,4,1,quarter,4,left."
           "png right.png\n";
  table << "2003,Broken,toy,four,1,quarter,4,left.png\n";
  table.close();
  CHECK_THROWS_WITH(read_scene_table((dir / "scenes.csv").string()), Catch::Contains("line 3"));
  CHECK_THROWS_WITH(
      read_scene_table((dir / "absent.csv").string()),
      Catch::Contains("scene table '" + (dir / "absent.csv").string() + "' does not exist"));
  std::ofstream good(dir / "scenes.csv");
  good << "year,scene,dir,width,height,scale,gt_divisor,files\n2003,Toy,toy,4,1,quarter,4,left."
          "png right.png\n";
  good.close();
  CHECK_THROWS_WITH(load_named_scene(dir.string(), "Teddy"),
                    Catch::Contains("no scene 'Teddy' in ") && Catch::Contains("(have: Toy)"));
  // A table saved with a UTF-8 byte-order mark reads the same (its header was not found).
  const std::string header = "year,scene,dir,width,height,scale,gt_divisor,files\n";
  const std::string row = "2003,Toy,toy,4,1,quarter,4,left.png right.png\n";
  CHECK(parse_scene_table("\xEF\xBB\xBF" + header + row, "marked.csv").front().scene == "Toy");

  // A scene whose GT has another size than its views is an error, not resized and scored.
  std::filesystem::create_directories(dir / "toy");
  cv::imwrite((dir / "toy" / "left.png").string(), cv::Mat(1, 4, CV_8UC3, cv::Scalar(9, 9, 9)));
  cv::imwrite((dir / "toy" / "right.png").string(), cv::Mat(1, 4, CV_8UC3, cv::Scalar(9, 9, 9)));
  cv::imwrite((dir / "toy" / "disp_left.png").string(), cv::Mat(2, 8, CV_8U, cv::Scalar(8)));
  std::ofstream with_gt(dir / "scenes.csv");
  with_gt << "year,scene,dir,width,height,scale,gt_divisor,files\n2003,Toy,toy,4,1,quarter,4,left."
             "png right.png disp_left.png\n";
  with_gt.close();
  CHECK_THROWS_WITH(load_named_scene(dir.string(), "Toy"),
                    Catch::Contains("scene Toy: ") && Catch::Contains("disp_left.png is 8x2") &&
                        Catch::Contains("the views are 4x1"));
}

TEST_CASE("the shared Middlebury scenes load with their conventions",
          "[stereo][middlebury][data]") {
  // Uses ../shared/data when it is there (the project does not need it otherwise).
  const std::string data = C2F_SHARED_DATA_DIR;
  if (!std::filesystem::exists(data + "/scenes.csv")) {
    WARN("no shared data at " << data << ": scene loading not checked");
    return;
  }
  const auto rows = read_scene_table(data + "/scenes.csv");
  CHECK(rows.size() >= 20);
  for (const SceneRow& row : rows) {
    if (row.scene != "Tsukuba" && row.scene != "Teddy" && row.scene != "Art") continue;
    const StereoScene scene = load_scene(row, data);
    CHECK(scene.left.cols == row.width);
    CHECK(scene.gt.size() == scene.left.size());
    double min_d = 1e9, max_d = 0;
    for (int y = 0; y < scene.gt.rows; ++y) {
      for (int x = 0; x < scene.gt.cols; ++x) {
        const float d = scene.gt.at<float>(y, x);
        if (!std::isnan(d)) min_d = std::min<double>(min_d, d), max_d = std::max<double>(max_d, d);
      }
    }
    INFO(row.scene);
    if (row.scene == "Tsukuba") {  // palette GT decoded to grey: 5 .. 14 px
      CHECK(min_d == 5.0);
      CHECK(max_d == 14.0);
      CHECK(scene.nonoccluded_source == "official mask");
    }
    if (row.scene == "Art") CHECK(scene.nonoccluded_source == "left-right check");
    CHECK(cv::countNonZero(scene.nonoccluded) > 0);
  }
}
