// c2f-bench-partitions: group counts and build times of genuine colour passing and of the
// reference's local grouping on Middlebury scenes, with the simple stereo energy (truncated
// absolute-difference cost, TSGO colour weight classes, TSGO step term, 85 labels), and
// pictures of the 10 largest CP(1,1) groups (as the paper's Figure 2e).
//
// Usage: c2f-bench-partitions [DATA_DIR] [--out DIR]   (defaults: ../shared/data, out/partitions)

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "c2f/c2f.hpp"
#include "tool_options.hpp"

namespace {

using namespace c2f;

struct Scene {
  const char* name;
  const char* dir;
};

}  // namespace

int main(int argc, char** argv) {
  std::string data = "../shared/data";
  std::string out = "out/partitions";
  try {
    c2f::examples::ToolOptions options(
        "c2f-bench-partitions: group counts of colour passing and local grouping on Teddy and "
        "Dolls.\n\nUsage: c2f-bench-partitions [DATA_DIR] [options]\n\nOptions");
    options.path("out", &out, "folder for partition pictures");
    const auto arguments = options.parse(argc, argv, {"DATA_DIR", 1});
    if (!arguments) return 0;
    if (!arguments->empty()) data = arguments->front();
  } catch (const std::exception& error) {
    std::cerr << "c2f-bench-partitions: error: " << error.what() << "\n";
    return 2;
  }
  try {
    std::filesystem::create_directories(out);
    constexpr int kLabels = 85;
    std::printf(
        "| scene | pixels | level | genuine CP groups | CP time (ms) | local grouping groups | "
        "local time (ms) |\n"
        "|---|---|---|---|---|---|---|\n");
    for (const Scene scene :
         {Scene{"Teddy", "middlebury/2003/Teddy"}, Scene{"Dolls", "middlebury/2005/Dolls"}}) {
      const std::string dir = data + "/" + scene.dir;
      const cv::Mat left = vision::load_colour_image(dir + "/left.png");
      const cv::Mat right = vision::load_colour_image(dir + "/right.png");
      const GridShape shape{static_cast<std::size_t>(left.cols),
                            static_cast<std::size_t>(left.rows)};
      const PairwiseEnergy energy = make_grid_energy(
          shape, Connectivity::four, kLabels,
          vision::absolute_difference_cost(left, right, kLabels, 20.0), PairwiseTerm::tsgo_step(),
          [&](VariableIndex u, VariableIndex v) { return vision::tsgo_edge_weight(left, u, v); });
      struct Level {
        int labels, iterations;
      };
      for (const Level level : {Level{1, 1}, Level{2, 1}, Level{3, 1}, Level{1, 2}, Level{2, 2}}) {
        using Clock = std::chrono::steady_clock;
        auto t0 = Clock::now();
        ColourPassing cp(energy, level.labels);
        for (int i = 0; i < level.iterations; ++i) cp.iterate();
        const DensePartition genuine = cp.partition();
        const double cp_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        t0 = Clock::now();
        const DensePartition local = local_grouping(energy, shape, level.labels, level.iterations);
        const double local_ms =
            std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        std::printf(
            "| %s | %zu | CP(%d,%d) | %zu (%.2f%%) | %.0f | %zu (%.2f%%) | %.0f |\n", scene.name,
            shape.size(), level.labels, level.iterations, genuine.num_groups(),
            100.0 * static_cast<double>(genuine.num_groups()) / static_cast<double>(shape.size()),
            cp_ms, local.num_groups(),
            100.0 * static_cast<double>(local.num_groups()) / static_cast<double>(shape.size()),
            local_ms);
        if (level.labels == 1 && level.iterations == 1) {
          const std::string stem = out + "/" + scene.name;
          vision::write_image(stem + "-cp11-largest10.png",
                              vision::render_largest_groups(genuine, shape, 10));
          vision::write_image(stem + "-cp11-means.png", vision::render_group_means(genuine, left));
          vision::write_image(stem + "-local11-largest10.png",
                              vision::render_largest_groups(local, shape, 10));
        }
      }
      std::fflush(stdout);
    }
    std::cerr << "c2f-bench-partitions: pictures in " << out << "\n";
  } catch (const std::exception& error) {
    std::cerr << "c2f-bench-partitions: error: " << error.what() << "\n";
    return 2;
  }
  return 0;
}
