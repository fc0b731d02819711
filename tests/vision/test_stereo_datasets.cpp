// Middlebury 2014 and KITTI 2015: the loaders read each dataset's own files and conventions,
// refuse what they cannot read by naming it, and the scene's error measure counts what the
// dataset counts.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <random>

#include "c2f/vision/stereo/disparity_io.hpp"
#include "c2f/vision/stereo/evaluation.hpp"
#include "c2f/vision/stereo/ground_truth.hpp"
#include "c2f/vision/stereo/kitti2015.hpp"
#include "c2f/vision/stereo/middlebury.hpp"
#include "c2f/vision/stereo/middlebury2014.hpp"

using namespace c2f;
using namespace c2f::vision;

namespace {

const float kInf = std::numeric_limits<float>::infinity();

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-stereo-datasets" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

cv::Mat random_view(int rows, int cols, int seed) {
  cv::Mat view(rows, cols, CV_8UC3);
  cv::RNG random(static_cast<std::uint64_t>(seed));
  random.fill(view, cv::RNG::UNIFORM, 0, 256);
  return view;
}

/// A 6x4 MiddEval3 folder: views, calib.txt with ndisp 9, a GT with one unknown (+inf) pixel,
/// and a mask with 255, 128 and 0.
std::filesystem::path middlebury2014_folder(const std::string& name) {
  const auto dir = fresh_dir(name);
  cv::imwrite((dir / "im0.png").string(), random_view(4, 6, 1));
  cv::imwrite((dir / "im1.png").string(), random_view(4, 6, 2));
  std::ofstream(dir / "calib.txt") << "cam0=[1 0 0; 0 1 0; 0 0 1]\nwidth=6\nheight=4\nndisp=9\n"
                                      "isint=0\nvmin=1\nvmax=8\n";
  cv::Mat gt(4, 6, CV_32F, cv::Scalar(3.0F));
  gt.at<float>(0, 0) = kInf;
  write_pfm((dir / "disp0GT.pfm").string(), gt);
  cv::Mat mask(4, 6, CV_8U, cv::Scalar(255));
  mask.at<uchar>(1, 1) = 128;
  mask.at<uchar>(0, 0) = 0;
  cv::imwrite((dir / "mask0nocc.png").string(), mask);
  return dir;
}

}  // namespace

TEST_CASE("the measures count what their datasets count", "[stereo][evaluation]") {
  const ErrorMeasure bad1;
  CHECK(bad1.is_bad(5.0, 3.9));
  CHECK_FALSE(bad1.is_bad(5.0, 4.0));
  CHECK(bad1.is_bad(std::nan(""), 4.0));
  const ErrorMeasure d1 = kitti_d1_measure();
  CHECK_FALSE(d1.is_bad(104.0, 100.0));  // 4 px > 3 px but only 4% of 100
  CHECK(d1.is_bad(106.0, 100.0));        // 6 px and 6%
  CHECK(d1.is_bad(13.5, 10.0));          // 3.5 px and 35%
  CHECK_FALSE(d1.is_bad(12.9, 10.0));    // 29% but only 2.9 px
  const ErrorMeasure quarter = middlebury2014_measure(Middlebury2014Size::quarter);
  CHECK(quarter.absolute == 0.5);
  CHECK(quarter.is_bad(10.6, 10.0));
  CHECK_FALSE(quarter.is_bad(10.5, 10.0));
  CHECK(middlebury2014_measure(Middlebury2014Size::full).absolute == 2.0);
}

TEST_CASE("scene_errors is the brute-force count of the scene's measure", "[stereo][evaluation]") {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> disparity(0.0F, 40.0F);
  StereoScene scene;
  scene.left = cv::Mat(30, 40, CV_8UC3, cv::Scalar::all(0));
  scene.gt = cv::Mat(30, 40, CV_32F);
  scene.nonoccluded = cv::Mat(30, 40, CV_8U, cv::Scalar(0));
  cv::Mat d(30, 40, CV_32F);
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 40; ++x) {
      const float truth = disparity(random);
      scene.gt.at<float>(y, x) = (x + y) % 7 == 0 ? std::nanf("") : truth;
      d.at<float>(y, x) = truth + disparity(random) / 4.0F - 5.0F;  // errors up to 5 px
      scene.nonoccluded.at<uchar>(y, x) = (x * y) % 3 == 0 ? 0 : 255;
    }
  }
  for (const ErrorMeasure& measure :
       {ErrorMeasure{}, kitti_d1_measure(), middlebury2014_measure(Middlebury2014Size::quarter)}) {
    scene.measure = measure;
    std::size_t known = 0, bad = 0, nonocc = 0, bad_nonocc = 0;
    for (int y = 0; y < 30; ++y) {
      for (int x = 0; x < 40; ++x) {
        const double g = scene.gt.at<float>(y, x), e = std::abs(d.at<float>(y, x) - g);
        if (std::isnan(g)) continue;
        const bool is_bad =
            e > measure.absolute && (measure.relative == 0 || e > measure.relative * g);
        const bool counted = scene.nonoccluded.at<uchar>(y, x) == 255;
        ++known, bad += is_bad, nonocc += counted, bad_nonocc += is_bad && counted;
      }
    }
    const SceneErrors errors = scene_errors(d, scene);
    INFO(measure.name);
    CHECK(errors.known_pixels == known);
    CHECK(errors.nonoccluded_pixels == nonocc);
    CHECK(errors.all == static_cast<double>(bad) / static_cast<double>(known));
    CHECK(errors.nonoccluded == static_cast<double>(bad_nonocc) / static_cast<double>(nonocc));
    CHECK(bad > 0);
    CHECK(bad < known);
  }
  // The default measure is bad 1: the same number as the fixed table's.
  scene.measure = ErrorMeasure{};
  CHECK(scene_errors(d, scene).nonoccluded ==
        bad_pixel_rates(d, scene.gt, scene.nonoccluded).nonoccluded[1]);
}

TEST_CASE("bad_pixel_error is scene_errors' rate of the labeling's disparities",
          "[stereo][evaluation]") {
  // GT at whole and half pixels (ties at every threshold), at random, unknown and infinite;
  // labelings at random and at the GT rounded, so that many labels sit at the thresholds.
  std::mt19937 random(11);
  std::uniform_real_distribution<float> disparity(0.0F, 60.0F);
  const int rows = 24, cols = 35;
  StereoScene scene;
  scene.left = cv::Mat(rows, cols, CV_8UC3, cv::Scalar::all(0));
  scene.gt = cv::Mat(rows, cols, CV_32F);
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < cols; ++x) {
      const int kind = (x + 3 * y) % 5;
      const float value = disparity(random);
      scene.gt.at<float>(y, x) = kind == 0   ? std::round(value)
                                 : kind == 1 ? std::round(2 * value) / 2
                                 : kind == 2 ? value
                                 : kind == 3 ? (x % 2 ? std::nanf("") : value)
                                             : (y == 5 && x < 3 ? INFINITY : value);
    }
  }
  cv::Mat mask(rows, cols, CV_8U);
  for (int y = 0; y < rows; ++y)
    for (int x = 0; x < cols; ++x) mask.at<uchar>(y, x) = (x * y) % 4 == 0 ? 0 : 255;
  std::uniform_int_distribution<Label> label(0, 63);
  for (const ErrorMeasure& measure :
       {ErrorMeasure{}, kitti_d1_measure(), middlebury2014_measure(Middlebury2014Size::quarter),
        middlebury2014_measure(Middlebury2014Size::full)}) {
    for (const bool masked : {false, true}) {
      scene.measure = measure;
      scene.nonoccluded = masked ? mask : cv::Mat();
      const auto error = bad_pixel_error(scene);
      for (int trial = 0; trial < 6; ++trial) {
        std::vector<Label> labeling(static_cast<std::size_t>(rows * cols));
        for (std::size_t v = 0; v < labeling.size(); ++v) {
          const float g =
              scene.gt.at<float>(static_cast<int>(v) / cols, static_cast<int>(v) % cols);
          const bool near_truth = trial % 2 == 1 && std::isfinite(g);
          labeling[v] = near_truth ? static_cast<Label>(std::lround(g)) + label(random) % 5 - 2
                                   : label(random);
        }
        const SceneErrors errors =
            scene_errors(labels_to_disparity(labeling, scene.shape()), scene);
        INFO(measure.name << (masked ? ", masked" : "") << ", trial " << trial);
        CHECK(error(labeling) == (masked ? errors.nonoccluded : errors.all));
      }
    }
  }
  CHECK_THROWS_WITH(bad_pixel_error(scene)(std::vector<Label>(10, 0)),
                    Catch::Contains("10 labels for a scene of 840 pixels"));
}

TEST_CASE("downscale divides the thresholds that follow it and the disparity range",
          "[stereo][evaluation]") {
  StereoScene scene;
  scene.left = cv::Mat(8, 8, CV_8UC3, cv::Scalar::all(0));
  scene.right = scene.left.clone();
  scene.disparity_range = 73;
  scene.measure = middlebury2014_measure(Middlebury2014Size::quarter);
  StereoScene half = downscale(scene, 2);
  CHECK(half.measure.absolute == 0.25);
  CHECK(half.disparity_range == 37);
  scene.measure = ErrorMeasure{};  // bad 1 stays bad 1 at the size solved
  CHECK(downscale(scene, 2).measure.absolute == 1.0);
  scene.measure = kitti_d1_measure();
  half = downscale(scene, 2);
  CHECK(half.measure.absolute == 1.5);
  CHECK(half.measure.relative == 0.05);
}

TEST_CASE("ndisp is read from calib.txt, strictly", "[stereo][middlebury2014]") {
  CHECK(parse_ndisp("width=718\r\nndisp=73\r\nisint=0\r\n", "c") == 73);
  CHECK(parse_ndisp("\xEF\xBB\xBFndisp=64\n", "c") == 64);  // a byte-order mark first
  CHECK_THROWS_WITH(parse_ndisp("width=718\n", "c.txt"),
                    Catch::Contains("'c.txt' has no ndisp= line"));
  CHECK_THROWS_WITH(parse_ndisp("ndisp=7x\n", "c.txt"),
                    Catch::Contains("line 1: ndisp: expected an integer in [2, 65536] (one label "
                                    "is no stereo), got '7x'"));
  CHECK_THROWS_WITH(parse_ndisp("ndisp=0\n", "c.txt"), Catch::Contains("got '0'"));
  CHECK_THROWS_WITH(parse_ndisp("ndisp=1\n", "c.txt"), Catch::Contains("got '1'"));
  CHECK_THROWS_WITH(parse_ndisp("ndisp=7\nndisp=8\n", "c.txt"),
                    Catch::Contains("line 2: ndisp is given twice"));
}

TEST_CASE("a Middlebury 2014 folder loads with its GT, mask and range",
          "[stereo][middlebury2014]") {
  const auto dir = middlebury2014_folder("Toy");
  const StereoScene scene = load_middlebury2014_scene(dir.string());
  CHECK(scene.name == "Toy");
  CHECK(scene.disparity_range == 9);
  CHECK(scene.measure == middlebury2014_measure(Middlebury2014Size::quarter));
  // A downscale that leaves fewer than 2 of the scene's labels is an error, not a silent
  // fallback to another label count.
  StereoScene two_labels = scene;
  two_labels.disparity_range = 2;
  CHECK_THROWS_WITH(downscale(two_labels, 2),
                    Catch::Contains("the scene's 2 disparities shrunk by 2 leave fewer than 2 "
                                    "labels"));
  CHECK(std::isnan(scene.gt.at<float>(0, 0)));  // +inf is unknown
  CHECK(scene.gt.at<float>(3, 5) == 3.0F);
  CHECK(scene.nonoccluded.at<uchar>(1, 1) == 0);  // 128: occluded
  CHECK(scene.nonoccluded.at<uchar>(2, 2) == 255);
  CHECK(scene.nonoccluded_source == "official mask");

  SECTION("a mask with another grey value is refused by name and place") {
    cv::Mat mask(4, 6, CV_8U, cv::Scalar(255));
    mask.at<uchar>(2, 3) = 77;
    cv::imwrite((dir / "mask0nocc.png").string(), mask);
    CHECK_THROWS_WITH(load_middlebury2014_scene(dir.string()),
                      Catch::Contains("mask0nocc.png' has the grey value 77 at (3, 2)"));
  }
  SECTION("a GT of another size is refused by name") {
    write_pfm((dir / "disp0GT.pfm").string(), cv::Mat(2, 6, CV_32F, cv::Scalar(1.0F)));
    CHECK_THROWS_WITH(load_middlebury2014_scene(dir.string()),
                      Catch::Contains("disp0GT.pfm is 6x2, the views are 6x4"));
  }
  SECTION("a GT with no known pixel is refused") {
    write_pfm((dir / "disp0GT.pfm").string(), cv::Mat(4, 6, CV_32F, cv::Scalar(kInf)));
    CHECK_THROWS_WITH(load_middlebury2014_scene(dir.string()),
                      Catch::Contains("disp0GT.pfm has no known pixel"));
  }
  SECTION("a mask without the GT is refused; views alone load") {
    std::filesystem::remove(dir / "disp0GT.pfm");
    CHECK_THROWS_WITH(load_middlebury2014_scene(dir.string()),
                      Catch::Contains("needs the GT disp0GT.pfm"));
    std::filesystem::remove(dir / "mask0nocc.png");
    CHECK(load_middlebury2014_scene(dir.string()).gt.empty());
  }
  SECTION("a missing calib.txt or view is named") {
    std::filesystem::remove(dir / "calib.txt");
    CHECK_THROWS_WITH(load_middlebury2014_scene(dir.string()), Catch::Contains("calib.txt"));
    std::filesystem::remove(dir / "im1.png");
    CHECK_THROWS_WITH(load_middlebury2014_scene(dir.string()), Catch::Contains("im1.png"));
  }
}

TEST_CASE("a KITTI 2015 pair loads with GT / 256 and the D1 measure", "[stereo][kitti]") {
  const auto root = fresh_dir("kitti");
  for (const char* folder : {"image_2", "image_3", "disp_occ_0"})
    std::filesystem::create_directories(root / "training" / folder);
  cv::imwrite((root / "training/image_2/000007_10.png").string(), random_view(3, 5, 1));
  cv::imwrite((root / "training/image_3/000007_10.png").string(), random_view(3, 5, 2));
  cv::Mat gt(3, 5, CV_16U, cv::Scalar(0));
  gt.at<std::uint16_t>(1, 2) = 256 * 12 + 64;  // 12.25 px
  cv::imwrite((root / "training/disp_occ_0/000007_10.png").string(), gt);
  const StereoScene scene = load_kitti2015_pair(root.string(), "000007_10");
  CHECK(scene.name == "kitti2015/000007_10");
  CHECK(scene.gt.at<float>(1, 2) == 12.25F);
  CHECK(std::isnan(scene.gt.at<float>(0, 0)));  // 0: unknown
  CHECK(scene.nonoccluded.empty());
  CHECK(scene.measure == kitti_d1_measure());
  CHECK(scene.disparity_range == kKittiDefaultLabels);
  CHECK_THROWS_WITH(load_kitti2015_pair(root.string(), "000008_10"),
                    Catch::Contains("image_2/000008_10.png"));
  // An 8-bit GT is no KITTI GT: refused, not divided by 256 and scored.
  cv::imwrite((root / "training/disp_occ_0/000007_10.png").string(),
              cv::Mat(3, 5, CV_8U, cv::Scalar(12)));
  CHECK_THROWS_WITH(load_kitti2015_pair(root.string(), "000007_10"),
                    Catch::Contains("is an 8-bit PNG: divided by 256 every disparity would be "
                                    "below one pixel (KITTI's GT is a 16-bit PNG"));
  CHECK_THROWS_WITH(load_kitti2015_pair(root.string(), "../x"),
                    Catch::Contains("expected a name such as 000000_10"));
}

TEST_CASE("a GT given by hand is read by what it holds, with its dataset's measure",
          "[stereo][gt]") {
  const auto dir = fresh_dir("by-hand");
  // Middlebury 2014's PFM: infinity unknown, bad 2.0 at the size its folder names.
  const auto quarter = middlebury2014_folder("trainingQ/Toy");
  GroundTruth pfm = load_ground_truth((quarter / "disp0GT.pfm").string(), 0.0);
  CHECK(std::isnan(pfm.disparity.at<float>(0, 0)));
  CHECK(pfm.disparity.at<float>(1, 1) == 3.0F);
  CHECK(pfm.measure == middlebury2014_measure(Middlebury2014Size::quarter));
  std::filesystem::copy_file(quarter / "disp0GT.pfm", dir / "gt.pfm");
  CHECK(load_ground_truth((dir / "gt.pfm").string(), 0.0).measure.name == "bad 2.0");
  // KITTI's 16-bit PNG: / 256 and D1 unless a divisor is given.
  cv::Mat deep(3, 5, CV_16U, cv::Scalar(0));
  deep.at<std::uint16_t>(1, 2) = 256 * 12 + 64;
  cv::imwrite((dir / "deep.png").string(), deep);
  GroundTruth kitti = load_ground_truth((dir / "deep.png").string(), 0.0);
  CHECK(kitti.disparity.at<float>(1, 2) == 12.25F);
  CHECK(kitti.measure == kitti_d1_measure());
  GroundTruth divided = load_ground_truth((dir / "deep.png").string(), 64.0);
  CHECK(divided.disparity.at<float>(1, 2) == 49.0F);
  CHECK(divided.measure == ErrorMeasure{});
  // An 8-bit PNG: the value itself, or divided; never by more than 255.
  cv::imwrite((dir / "grey.png").string(), cv::Mat(3, 5, CV_8U, cv::Scalar(40)));
  CHECK(load_ground_truth((dir / "grey.png").string(), 0.0).disparity.at<float>(0, 0) == 40.0F);
  CHECK(load_ground_truth((dir / "grey.png").string(), 4.0).disparity.at<float>(0, 0) == 10.0F);
  CHECK_THROWS_WITH(load_ground_truth((dir / "grey.png").string(), 256.0),
                    Catch::Contains("is an 8-bit PNG: divided by 256 every disparity"));
  // A PFM in the other byte order reads as denormals: refused by name.
  cv::Mat swapped(4, 6, CV_32F, cv::Scalar(37.25F));
  write_pfm((dir / "swapped.pfm").string(), swapped);
  std::string bytes;
  {
    std::ifstream in(dir / "swapped.pfm", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const std::size_t scale = bytes.find("-1");  // write_pfm writes little-endian, scale -1
  REQUIRE(scale != std::string::npos);
  bytes.replace(scale, 2, "+1");
  std::ofstream(dir / "swapped.pfm", std::ios::binary) << bytes;
  CHECK_THROWS_WITH(load_ground_truth((dir / "swapped.pfm").string(), 0.0),
                    Catch::Contains("is the sign of its scale (the byte order) right?"));
}

TEST_CASE("scene names reach the new datasets under the data root", "[stereo][middlebury2014]") {
  const auto root = fresh_dir("root");
  std::filesystem::create_directories(root / "middlebury2014");
  std::filesystem::rename(middlebury2014_folder("Toy2"), root / "middlebury2014/Toy2");
  const StereoScene scene = load_named_scene(root.string(), "middlebury2014/Toy2");
  CHECK(scene.name == "middlebury2014/Toy2");
  CHECK(scene.disparity_range == 9);
  CHECK_THROWS_WITH(load_named_scene(root.string(), "middlebury2014/"),
                    Catch::Contains("expected middlebury2014/NAME"));
  CHECK_THROWS_WITH(load_named_scene(root.string(), "kitti2015/a/b"),
                    Catch::Contains("expected kitti2015/NAME"));
}

TEST_CASE("opencv-doc/aloe names the full-size Aloe pair Debian's opencv-doc ships",
          "[stereo][middlebury]") {
  // scripts/install-deps installs opencv-doc (the demo's input), so the pair is there.
  const StereoScene scene = load_named_scene("/nonexistent", kOpencvDocAloe);
  CHECK(scene.name == "opencv-doc/aloe");
  CHECK(scene.left.cols == 1282);
  CHECK(scene.left.rows == 1110);
  CHECK(scene.gt.size() == scene.left.size());
  CHECK(scene.nonoccluded.empty());
  CHECK(label_count(scene, 85) == 256);
  // The GT is in pixels at full size: Aloe's disparities reach past 200 there.
  double low = 0.0, high = 0.0;
  cv::minMaxIdx(scene.gt, &low, &high, nullptr, nullptr, scene.gt == scene.gt);
  CHECK(high > 200.0);
  CHECK(high < 256.0);
}

TEST_CASE("the shared Middlebury 2014 and KITTI scenes load with their conventions",
          "[stereo][middlebury2014][kitti][data]") {
  const std::string data = C2F_SHARED_DATA_DIR;
  if (!std::filesystem::exists(data + "/middlebury2014")) {
    WARN("no shared data at " << data << ": Middlebury 2014 and KITTI loading not checked");
    return;
  }
  for (const char* name : {"Adirondack", "Motorcycle", "MotorcycleE", "Piano", "PianoL",
                           "Playtable", "PlaytableP", "Recycle"}) {
    const StereoScene scene = load_named_scene(data, std::string("middlebury2014/") + name);
    INFO(name);
    CHECK(scene.left.cols >= 660);
    CHECK(scene.left.cols <= 741);
    CHECK(scene.disparity_range >= 60);
    CHECK(scene.disparity_range <= 190);
    const double known = 1.0 - static_cast<double>(cv::countNonZero(scene.gt != scene.gt)) /
                                   static_cast<double>(scene.gt.total());
    CHECK(known > 0.9);  // the GT covers nearly every pixel; +inf marks the rest
    double largest = 0;
    cv::minMaxIdx(scene.gt, nullptr, &largest, nullptr, nullptr, scene.gt == scene.gt);
    CHECK(largest < scene.disparity_range);  // ndisp bounds the GT
    CHECK(cv::countNonZero(scene.nonoccluded) > 0);
  }
  for (const char* id : {"000000_10", "000001_10"}) {
    const StereoScene scene = load_named_scene(data, std::string("kitti2015/") + id);
    INFO(id);
    CHECK(scene.left.size() == cv::Size(1242, 375));
    double largest = 0;
    cv::minMaxIdx(scene.gt, nullptr, &largest, nullptr, nullptr, scene.gt == scene.gt);
    CHECK(largest > 10);
    CHECK(largest < kKittiDefaultLabels);
  }
}
