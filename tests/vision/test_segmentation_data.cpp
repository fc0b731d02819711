// Segmentation data: k-means, colour GMMs and their costs, seed conventions and their errors,
// edge weights and classes, unaries; and the shared coopCuts images when they are there.

#include <catch2/catch.hpp>

#include <Eigen/Core>
#include <algorithm>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <span>
#include <vector>

#include "c2f/vision/segmentation/colour_gmm.hpp"
#include "c2f/vision/segmentation/kmeans.hpp"
#include "c2f/vision/segmentation/segmentation_energy.hpp"
#include "c2f/vision/segmentation/segmentation_io.hpp"
#include "c2f/vision/segmentation/segmentation_scene.hpp"
#include "support/synthetic_segmentation.hpp"

using namespace c2f;
using namespace c2f::vision;

namespace {

std::vector<Eigen::Vector3d> blobs(std::mt19937_64& rng,
                                   const std::vector<Eigen::Vector3d>& centres, int per_blob,
                                   double sigma) {
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < per_blob; ++i) {
    for (const Eigen::Vector3d& c : centres)
      points.push_back(c + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)));
  }
  return points;
}

}  // namespace

TEST_CASE("k-means finds separated clusters, deterministically", "[segmentation][kmeans]") {
  std::mt19937_64 rng(1);
  const std::vector<Eigen::Vector3d> centres{{0, 0, 0}, {1, 0, 0}, {0, 1, 1}};
  const auto points = blobs(rng, centres, 50, 0.02);
  for (const KMeansOptions& options : {reference_kmeans(7), plus_plus_kmeans(7)}) {
    INFO(to_string(options.start));
    const KMeansResult a = kmeans(points, 3, options), b = kmeans(points, 3, options);
    CHECK(a.assignment == b.assignment);
    CHECK(a.centres == b.centres);
    CHECK(kmeans(std::vector<Eigen::Vector3d>{{1, 2, 3}, {1, 2, 3}}, 5, options).centres.size() ==
          2);
  }
  // k-means++ spreads its start over the blobs and finds them; a 'sample' start may put two
  // centres in one blob and stop in that local minimum, which is why it is not tested here.
  const KMeansResult found = kmeans(points, 3, plus_plus_kmeans(7));
  for (const Eigen::Vector3d& c : centres) {
    double nearest = 1e9;
    for (const Eigen::Vector3d& f : found.centres) nearest = std::min(nearest, (f - c).norm());
    CHECK(nearest < 0.02);
  }
  for (std::size_t i = 0; i < points.size(); ++i)
    CHECK(found.assignment[i] == found.assignment[i % 3]);
  CHECK_THROWS_WITH(kmeans({}, 2, {}), Catch::Contains("no points"));
  KMeansOptions no_rounds;
  no_rounds.max_iterations = 0;
  CHECK_THROWS_WITH(kmeans(points, 2, no_rounds), Catch::Contains("max_iterations"));
  CHECK(kmeans_start_from_string("sample") == KMeansStart::sample);
  CHECK(kmeans_start_from_string(to_string(KMeansStart::plus_plus)) == KMeansStart::plus_plus);
  CHECK_THROWS_WITH(kmeans_start_from_string("random"),
                    Catch::Contains("expected sample or plusplus"));
}

TEST_CASE("k-means and the unaries are the same for every thread count",
          "[segmentation][kmeans][threads]") {
  std::mt19937_64 rng(4);
  // Overlapping blobs, 60000 points: several ranges of points per round, many rounds.
  const auto points =
      blobs(rng, {{0, 0, 0}, {0.3, 0, 0}, {0, 0.3, 0.2}, {0.2, 0.2, 0.2}}, 15000, 0.15);
  for (KMeansOptions options : {reference_kmeans(3), plus_plus_kmeans(3)}) {
    INFO(to_string(options.start));
    options.threads = 1;
    const KMeansResult one = kmeans(points, 6, options);
    for (const int threads : {2, 3, 0}) {
      options.threads = threads;
      const KMeansResult many = kmeans(points, 6, options);
      CHECK(many.assignment == one.assignment);
      CHECK(many.centres == one.centres);  // bit for bit
    }
  }
  KMeansOptions negative;
  negative.threads = -1;
  CHECK_THROWS_WITH(kmeans(points, 2, negative), Catch::Contains("threads must be >= 0"));

  const auto files = test::write_synthetic_segmentation(
      std::filesystem::temp_directory_path() / "c2f-test-unaries-threads", 120, 90, 3);
  const SegmentationScene scene =
      load_segmentation_scene({files.image, files.seeds, files.gt, SeedConvention::colours});
  KMeansOptions gmm = plus_plus_kmeans(27);
  gmm.threads = 1;
  const std::vector<double> serial = segmentation_unaries(scene, gmm);
  gmm.threads = 2;
  CHECK(segmentation_unaries(scene, gmm) == serial);
}

TEST_CASE("k-means keeps a point in its cluster on a tie", "[segmentation][kmeans]") {
  // Four equal points, two clusters: the first round puts all four in cluster 0 (the lowest
  // index wins a tie when a point has no cluster yet), the empty cluster 1 takes point 0 as a
  // singleton; from then on every point is at distance 0 from both centres and stays.
  const std::vector<Eigen::Vector3d> same(4, Eigen::Vector3d(0.1, 0.2, 0.3));
  for (const KMeansOptions& options : {reference_kmeans(3), plus_plus_kmeans(3)}) {
    INFO(to_string(options.start));
    CHECK(kmeans(same, 2, options).assignment == std::vector<int>{1, 0, 0, 0});
  }
}

TEST_CASE("k-means's online phase ends where no single point's move lowers the total",
          "[segmentation][kmeans]") {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector3d> points(400);
  for (Eigen::Vector3d& p : points) p = {unit(rng), unit(rng), 0.3 * unit(rng)};
  const auto total = [&](const KMeansResult& r) {
    double sum = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i)
      sum += (points[i] - r.centres[static_cast<std::size_t>(r.assignment[i])]).squaredNorm();
    return sum;
  };
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    KMeansOptions batch_only = reference_kmeans(seed);
    batch_only.online_phase = false;
    const KMeansResult batch = kmeans(points, 6, batch_only);
    const KMeansResult online = kmeans(points, 6, reference_kmeans(seed));
    CHECK(total(online) <= total(batch) + 1e-12);
    // Batch rounds end with every point at its nearest centre.
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double own = (points[i] - batch.centres[batch.assignment[i]]).squaredNorm();
      for (const Eigen::Vector3d& c : batch.centres) CHECK(own <= (points[i] - c).squaredNorm());
    }
    // The online phase ends with no single move that lowers the total (centres are the means).
    std::vector<double> count(online.centres.size(), 0.0);
    for (const int c : online.assignment) count[static_cast<std::size_t>(c)] += 1.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const auto own = static_cast<std::size_t>(online.assignment[i]);
      if (count[own] <= 1.0) continue;
      const double leave =
          count[own] / (count[own] - 1.0) * (points[i] - online.centres[own]).squaredNorm();
      for (std::size_t c = 0; c < online.centres.size(); ++c) {
        if (c == own) continue;
        CHECK(leave <=
              count[c] / (count[c] + 1.0) * (points[i] - online.centres[c]).squaredNorm() + 1e-12);
      }
    }
  }
}

TEST_CASE("colour GMMs recover their components and give non-negative costs",
          "[segmentation][gmm]") {
  std::mt19937_64 rng(2);
  const auto samples = blobs(rng, {{0.2, 0.2, 0.2}, {0.8, 0.6, 0.1}}, 400, 0.03);
  const ColourGmm gmm = fit_colour_gmm(samples, 2, reference_kmeans(3));
  REQUIRE(gmm.components.size() == 2);
  double weight = 0.0;
  for (const GaussianComponent& c : gmm.components) {
    weight += c.weight;
    CHECK(c.weight == Approx(0.5).margin(0.01));
    CHECK(std::min((c.mean - Eigen::Vector3d(0.2, 0.2, 0.2)).norm(),
                   (c.mean - Eigen::Vector3d(0.8, 0.6, 0.1)).norm()) < 0.01);
    CHECK(c.covariance(0, 0) == Approx(0.03 * 0.03).epsilon(0.3));
  }
  CHECK(weight == Approx(1.0));
  const std::vector<Eigen::Vector3d> probe{{0.2, 0.2, 0.2}, {0.5, 0.4, 0.15}, {1.0, 1.0, 1.0}};
  const std::vector<double> costs = nonnegative_gmm_costs(gmm, probe);
  for (const double c : costs) CHECK(c >= 0.0);
  CHECK(costs[0] < costs[1]);
  CHECK(costs[1] < costs[2]);
  // The cost is the minimum over components, by hand for one isotropic component.
  ColourGmm single{{{1.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity() * 0.04}}};
  const double s = 0.01, variance = 0.04 + s;
  CHECK(GmmCost(single, s)(Eigen::Vector3d(0.1, 0, 0)) ==
        Approx(1.5 * std::log(variance) + 0.5 * 0.01 / variance + 1.5 * std::log(2 * M_PI)));
}

TEST_CASE("seed conventions load scenes and reject bad input by name", "[segmentation][scene]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-segmentation-scene";
  const auto files = test::write_synthetic_segmentation(dir, 40, 30, 1);
  const SegmentationScene scene =
      load_segmentation_scene({files.image, files.seeds, files.gt, SeedConvention::colours});
  CHECK(scene.num_labels() == 3);
  CHECK(scene.palette[0] == files.colours[0]);
  CHECK(scene.truth[0] == 0);  // top-left: the left third
  std::size_t seeded = 0;
  for (std::size_t i = 0; i < scene.seeds.size(); ++i) {
    if (scene.seeds[i] == kNoLabel) continue;
    ++seeded;
    CHECK(scene.seeds[i] == scene.truth[i]);  // the scribbles lie inside their regions
  }
  CHECK(seeded > 20);
  const SegmentationScene from_gt =
      load_segmentation_scene({files.image, files.seeds, files.gt, SeedConvention::labels_from_gt});
  CHECK(from_gt.seeds == scene.seeds);

  // Errors name the input.
  cv::imwrite((dir / "small.png").string(), cv::Mat(10, 10, CV_8UC3, cv::Scalar(255, 255, 255)));
  CHECK_THROWS_WITH(load_segmentation_scene(
                        {files.image, (dir / "small.png").string(), "", SeedConvention::colours}),
                    Catch::Contains("SEEDS '") && Catch::Contains("is 10x10, the image is 40x30"));
  cv::Mat one(30, 40, CV_8UC3, cv::Scalar(255, 255, 255));
  one.at<cv::Vec3b>(3, 3) = cv::Vec3b(0, 0, 0);
  cv::imwrite((dir / "one.png").string(), one);
  CHECK_THROWS_WITH(
      load_segmentation_scene(
          {files.image, (dir / "one.png").string(), "", SeedConvention::colours}),
      Catch::Contains("has 1 seed colour(s) besides white; segmentation needs at least 2"));
  cv::Mat odd_gt = cv::imread(files.gt);
  odd_gt.at<cv::Vec3b>(5, 7) = cv::Vec3b(9, 9, 9);
  cv::imwrite((dir / "odd.png").string(), odd_gt);
  CHECK_THROWS_WITH(load_segmentation_scene({files.image, files.seeds, (dir / "odd.png").string(),
                                             SeedConvention::colours}),
                    Catch::Contains("colour (9,9,9) at (7, 5) is none of the label colours"));
  // With labels from a GT that has a fourth class no scribble touches: that label has no seeds.
  CHECK_THROWS_WITH(load_segmentation_scene({files.image, files.seeds, (dir / "odd.png").string(),
                                             SeedConvention::labels_from_gt}),
                    Catch::Contains("label 2 (colour (9,9,9)) has no seed pixels"));
  CHECK_THROWS_WITH(
      load_segmentation_scene({files.image, files.seeds, "", SeedConvention::labels_from_gt}),
      Catch::Contains("need a GT labeling"));
  CHECK_THROWS_WITH(load_segmentation_scene(
                        {(dir / "missing.png").string(), files.seeds, "", SeedConvention::colours}),
                    Catch::Contains("missing.png"));
  cv::Mat grey(30, 40, CV_8U, cv::Scalar(255));
  grey.at<std::uint8_t>(2, 2) = 77;
  cv::imwrite((dir / "grey.png").string(), grey);
  cv::Mat binary_seeds(30, 40, CV_8UC3, cv::Scalar(255, 255, 255));
  binary_seeds.at<cv::Vec3b>(1, 1) = cv::Vec3b(0, 0, 255);    // red: object
  binary_seeds.at<cv::Vec3b>(20, 30) = cv::Vec3b(255, 0, 0);  // blue: background
  cv::imwrite((dir / "binary-seeds.png").string(), binary_seeds);
  CHECK_THROWS_WITH(load_segmentation_scene({files.image, (dir / "binary-seeds.png").string(),
                                             (dir / "grey.png").string(), SeedConvention::binary}),
                    Catch::Contains("grey level 77 at pixel 82"));
  const SegmentationScene binary = load_segmentation_scene(
      {files.image, (dir / "binary-seeds.png").string(), "", SeedConvention::binary});
  CHECK(binary.seeds[41] == 1);
  CHECK(binary.seeds[20 * 40 + 30] == 0);
  CHECK(seed_convention_from_string("labels-from-gt") == SeedConvention::labels_from_gt);
}

TEST_CASE("each side of an edge is charged the class of its own colour minus the other's",
          "[segmentation][energy]") {
  // A lone vertical edge: top (51, 102, 153) = (0.2, 0.4, 0.6), bottom black; K = 2 puts the
  // two directed differences in classes of their own, whatever the k-means.
  cv::Mat column(2, 1, CV_8UC3, cv::Scalar(0, 0, 0));
  column.at<cv::Vec3b>(0, 0) = cv::Vec3b(153, 102, 51);  // BGR
  for (const KMeansOptions& options : {reference_kmeans(), plus_plus_kmeans()}) {
    INFO(to_string(options.start));
    const SegmentationEdges edge = segmentation_edges(column, 2, options);
    REQUIRE(edge.pairs == std::vector<std::pair<VariableIndex, VariableIndex>>{{0, 1}});
    REQUIRE(edge.class_centres.size() == 2);
    CHECK((edge.class_centres[edge.u_class[0]] - Eigen::Vector3d(0.2, 0.4, 0.6)).norm() < 1e-12);
    CHECK((edge.class_centres[edge.v_class[0]] + Eigen::Vector3d(0.2, 0.4, 0.6)).norm() < 1e-12);
  }
}

TEST_CASE("a tiny image's classes and cooperative-cut energy, by hand", "[segmentation][energy]") {
  // 2x2 image: top-left white, the other three black. 8-connected: 6 edges; the three at the
  // white pixel have |dc|^2 = 3, the other three 0, so mean |dc|^2 = 1.5 and
  // w = 0.05 + 0.95 exp(-3 / 3) at the white pixel, 1 elsewhere. K = 2: the white pixel's sides
  // (white - black = (1, 1, 1)) form one class P, the black sides of those edges (-1, -1, -1)
  // the other, N; the three black-black edges are class K (linear).
  cv::Mat image(2, 2, CV_8UC3, cv::Scalar(0, 0, 0));
  image.at<cv::Vec3b>(0, 0) = cv::Vec3b(255, 255, 255);
  const SegmentationEdges edges = segmentation_edges(image, 2, reference_kmeans());
  REQUIRE(edges.pairs.size() == 6);
  const double w = 0.05 + 0.95 * std::exp(-1.0);
  REQUIRE(edges.class_centres.size() == 2);
  const std::uint32_t P = edges.class_centres[0].x() > 0 ? 0u : 1u;  // the class of (1, 1, 1)
  CHECK((edges.class_centres[P] - Eigen::Vector3d(1, 1, 1)).norm() < 1e-12);
  for (std::size_t e = 0; e < 6; ++e) {
    const auto [u, v] = edges.pairs[e];
    if (u != 0 && v != 0) {
      CHECK(edges.weights[e] == 1.0);
      CHECK(edges.u_class[e] == 2);
      CHECK(edges.v_class[e] == 2);
      continue;
    }
    CHECK(edges.weights[e] == Approx(w).epsilon(1e-14));
    CHECK((u == 0 ? edges.u_class[e] : edges.v_class[e]) == P);      // white's side
    CHECK((u == 0 ? edges.v_class[e] : edges.u_class[e]) == 1 - P);  // black's side
  }
  // T_P = T_N = 3w. lambda 1, theta 0.25, alpha 0.2: F(s) = min(s, 0.2 s + 0.8 * 0.25 * 3w).
  // Unaries: pixel i costs i for label 0 and 0 for label 1 (row-major: TL, TR, BL, BR).
  const CoopEnergy energy =
      coop_energy({0, 0, 1, 0, 2, 0, 3, 0}, 2, edges, CoopParameters{1.0, 0.25, 0.2});
  // x = (0, 1, 1, 1): the white pixel's three edges cut. S_{0,P} = 3w/2 (white side, label 0),
  // S_{1,N} = 3w/2; F(1.5w) = min(1.5w, 0.3w + 0.6w) = 0.9w each. E = 0 + 1.8w.
  CHECK(energy.evaluate(Labeling{0, 1, 1, 1}) == Approx(1.8 * w).epsilon(1e-12));
  // x = (0, 0, 1, 1): cut TL-BL and TL-BR (white side label 0: S_{0,P} = w; S_{1,N} = w;
  // F(w) = min(w, 0.2w + 0.6w) = 0.8w each) and TR-BL, TR-BR (class K, linear: w = 1 each,
  // half per side). Unaries 0 + 1. E = 1 + 1.6w + 2.
  CHECK(energy.evaluate(Labeling{0, 0, 1, 1}) == Approx(3.0 + 1.6 * w).epsilon(1e-12));
  // x = (1, 0, 0, 0): the white pixel labelled 1 this time: S_{1,P} = 3w/2, S_{0,N} = 3w/2:
  // 1.8w again, plus unaries 1 + 2 + 3.
  CHECK(energy.evaluate(Labeling{1, 0, 0, 0}) == Approx(6.0 + 1.8 * w).epsilon(1e-12));
}

TEST_CASE("segmentation edges, unaries and pictures", "[segmentation][energy]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-segmentation-energy";
  const auto files = test::write_synthetic_segmentation(dir, 40, 30, 2);
  const SegmentationScene scene =
      load_segmentation_scene({files.image, files.seeds, files.gt, SeedConvention::colours});
  const SegmentationEdges edges = segmentation_edges(scene.image, 10);
  CHECK(edges.pairs.size() == 39 * 30 + 40 * 29 + 2 * 39 * 29);
  for (std::size_t e = 0; e < edges.pairs.size(); ++e) {
    CHECK(edges.weights[e] >= 0.05);
    CHECK(edges.weights[e] <= 1.0);
    CHECK(edges.u_class[e] <= 10);
    CHECK((edges.u_class[e] == 10) == (edges.v_class[e] == 10));
  }
  const SegmentationEdges flat =
      segmentation_edges(cv::Mat(4, 5, CV_8UC3, cv::Scalar(7, 8, 9)), 10);
  for (std::size_t e = 0; e < flat.pairs.size(); ++e) {
    CHECK(flat.weights[e] == 1.0);
    CHECK(flat.u_class[e] == 10);
  }
  const std::vector<double> unaries = segmentation_unaries(scene);
  for (std::size_t i = 0; i < scene.seeds.size(); ++i) {
    for (int l = 0; l < 3; ++l) {
      const double u = unaries[i * 3 + static_cast<std::size_t>(l)];
      CHECK(u >= 0.0);
      if (scene.seeds[i] != kNoLabel && scene.seeds[i] != l) CHECK(u == 20.0);
    }
  }
  const SegmentationProblem problem = segmentation_problem(scene, CoopParameters{});
  CHECK(problem.coop.num_variables() == 1200);
  // The seeds reach the unaries and the edge classes (27 by default).
  const auto same = [](std::span<const double> a, const std::vector<double>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  };
  CHECK(same(problem.coop.unaries(), unaries));
  const SegmentationProblem reseeded =
      segmentation_problem(scene, CoopParameters{}, {10, reference_kmeans(5), plus_plus_kmeans(6)});
  CHECK(same(reseeded.coop.unaries(), segmentation_unaries(scene, reference_kmeans(5))));
  const SegmentationEdges classes = segmentation_edges(scene.image, 10, plus_plus_kmeans(6));
  REQUIRE(reseeded.coop.edges().size() == classes.pairs.size());
  bool classes_match = true;
  for (std::size_t e = 0; e < classes.pairs.size(); ++e) {
    const CoopEdge& edge = reseeded.coop.edges()[e];
    classes_match &= reseeded.coop.entries()[edge.first].edge_class == classes.u_class[e] &&
                     reseeded.coop.entries()[edge.middle].edge_class == classes.v_class[e];
  }
  CHECK(classes_match);
  // The best unary label is right on most pixels of this easy image.
  Labeling argmin(1200);
  for (std::size_t i = 0; i < 1200; ++i) {
    argmin[i] = static_cast<Label>(std::min_element(&unaries[i * 3], &unaries[i * 3] + 3) -
                                   &unaries[i * 3]);
  }
  CHECK(pixel_error(argmin, scene.truth) < 0.1);
  CHECK(label_image(argmin, scene).at<cv::Vec3b>(0, 0) ==
        scene.palette[static_cast<std::size_t>(argmin[0])]);
  CHECK_THROWS_WITH(pixel_error(argmin, std::vector<int>(1200, kNoLabel)),
                    Catch::Contains("scores no pixel"));
}

TEST_CASE("a label image reads back as the labeling it shows", "[segmentation][io]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-read-label-image";
  const auto files = test::write_synthetic_segmentation(dir, 12, 9, 3);
  const SegmentationScene scene =
      load_segmentation_scene({files.image, files.seeds, files.gt, SeedConvention::colours});
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> label(0, scene.num_labels() - 1);
  Labeling labeling(scene.image.total());
  for (Label& l : labeling) l = static_cast<Label>(label(rng));
  const std::string path = (dir / "labels.png").string();
  REQUIRE(cv::imwrite(path, label_image(labeling, scene)));
  CHECK(read_label_image(path, scene) == labeling);

  cv::Mat odd = label_image(labeling, scene);
  odd.at<cv::Vec3b>(4, 7) = cv::Vec3b(9, 9, 9);
  const std::string odd_path = (dir / "odd.png").string();
  REQUIRE(cv::imwrite(odd_path, odd));
  CHECK_THROWS_WITH(read_label_image(odd_path, scene),
                    Catch::Contains("labeling '" + odd_path +
                                    "': colour (9,9,9) at (7, 4) is none of the label colours"));
  const std::string small_path = (dir / "small.png").string();
  REQUIRE(cv::imwrite(small_path, cv::Mat(3, 4, CV_8UC3, scene.palette[0])));
  CHECK_THROWS_WITH(read_label_image(small_path, scene), Catch::Contains("is 4x3, the image 12x9"));
  CHECK_THROWS_WITH(read_label_image((dir / "missing.png").string(), scene),
                    Catch::Contains("does not exist"));
}

#ifdef C2F_SHARED_DATA_DIR
TEST_CASE("the shared coopCuts images load with their conventions", "[segmentation][data]") {
  const std::filesystem::path root = std::filesystem::path(C2F_SHARED_DATA_DIR) / "coopcuts";
  if (!std::filesystem::exists(root)) {
    WARN("no shared coopCuts data at " << root.string() << "; skipped");
    return;
  }
  const auto m = root / "runMultilabel";
  const SegmentationScene cow = load_segmentation_scene(
      {(m / "images/1_11_s.bmp").string(), (m / "seeds/1_11_s.png").string(),
       (m / "labelings/1_11_s.bmp").string(), SeedConvention::labels_from_gt});
  CHECK(cow.num_labels() == 3);
  CHECK(cow.shape().width == 320);
  CHECK(cow.palette[0] == cv::Vec3b(128, 0, 0));  // (R,G,B) (0,0,128): cow, first in order
  CHECK(segmentation_edges(cow.image).pairs.size() == 271043);  // the reference's count
  const SegmentationScene trees = load_segmentation_scene(
      {(m / "images/2_21_s.bmp").string(), (m / "seeds/2_21_s.png").string(),
       (m / "labelings/2_21_s.bmp").string(), SeedConvention::labels_from_gt});
  CHECK(trees.num_labels() == 4);
  const auto b = root / "runBinary/dataset";
  const SegmentationScene bee = load_segmentation_scene(
      {(b / "images/005_bee.jpg").string(), (b / "seeds/005_bee.png").string(),
       (b / "groundtruth/005_bee.png").string(), SeedConvention::binary});
  CHECK(bee.shape().width == 427);
  CHECK(bee.num_labels() == 2);
}
#endif

TEST_CASE("scenes from decoded images: views into larger images read like whole images",
          "[segmentation][scene]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-scene-views";
  const auto files = c2f::test::write_synthetic_segmentation(dir, 30, 20, 4);
  const c2f::vision::SegmentationFiles names{files.image, files.seeds, files.gt,
                                             c2f::vision::SeedConvention::colours};
  const c2f::vision::SegmentationScene whole = c2f::vision::load_segmentation_scene(names);
  // The same pixels as views (not continuous in memory) into images with a 5-pixel margin.
  const auto framed = [](const std::string& path) {
    cv::Mat big;
    cv::copyMakeBorder(cv::imread(path), big, 5, 5, 5, 5, cv::BORDER_CONSTANT,
                       cv::Scalar(255, 255, 255));
    return big(cv::Rect(5, 5, 30, 20));
  };
  c2f::vision::SegmentationImages views{framed(files.image), framed(files.seeds), framed(files.gt)};
  REQUIRE_FALSE(views.seeds.isContinuous());
  const c2f::vision::SegmentationScene scene =
      c2f::vision::segmentation_scene_from_images(views, names);
  CHECK(scene.seeds == whole.seeds);
  CHECK(scene.truth == whole.truth);
  CHECK(scene.palette == whole.palette);
  views.gt = cv::Mat(20, 30, CV_16UC3, cv::Scalar::all(0));
  CHECK_THROWS_WITH(c2f::vision::segmentation_scene_from_images(views, names),
                    Catch::Contains("GT '") && Catch::Contains("is not a non-empty 8-bit colour"));
}

TEST_CASE("seeds drawn over a transparent background: transparent is no seed", "[segmentation]") {
  const auto dir = std::filesystem::temp_directory_path() / "c2f-test-transparent-seeds";
  std::filesystem::remove_all(dir);
  const auto files = c2f::test::write_synthetic_segmentation(dir, 40, 30, 2);
  const SegmentationScene opaque =
      load_segmentation_scene({files.image, files.seeds, "", SeedConvention::colours});
  // The same scribbles on a transparent black background (alpha 0 off the strokes).
  const cv::Mat drawn = cv::imread(files.seeds);
  cv::Mat rgba(drawn.size(), CV_8UC4, cv::Scalar(0, 0, 0, 0));
  for (int y = 0; y < drawn.rows; ++y) {
    for (int x = 0; x < drawn.cols; ++x) {
      const auto pixel = drawn.at<cv::Vec3b>(y, x);
      if (pixel != cv::Vec3b(255, 255, 255))
        rgba.at<cv::Vec4b>(y, x) = cv::Vec4b(pixel[0], pixel[1], pixel[2], 255);
    }
  }
  const std::string transparent = (dir / "seeds-rgba.png").string();
  cv::imwrite(transparent, rgba);
  const SegmentationScene scene =
      load_segmentation_scene({files.image, transparent, "", SeedConvention::colours});
  CHECK(scene.num_labels() == opaque.num_labels());  // no black third label
  CHECK(scene.seeds == opaque.seeds);
}
