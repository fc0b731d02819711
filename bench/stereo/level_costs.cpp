// c2f-bench-levels: what one alpha-expansion move costs on each level of a schedule, on a
// Middlebury scene's TSGO energy (85 labels). For every level: groups, edges of the reduced
// energy, mean degree, time of one sweep of moves (all labels, from the level's own cheapest
// labels), the share spent in max-flow and the share of
// moves that needed QPBO. Explains where coarse levels save (or do not save) time.
//
// Usage: c2f-bench-levels SCENE [--data DIR] [--schedule TEXT]   (defaults: ../shared/data,
// regions)

#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>

#include "c2f/c2f.hpp"
#include "c2f/vision/stereo/middlebury.hpp"
#include "c2f/vision/stereo/stereo_schedules.hpp"
#include "c2f/vision/stereo/tsgo_energy.hpp"
#include "c2f/vision/superpixels.hpp"
#include "tool_options.hpp"

namespace {

using namespace c2f;
using namespace c2f::vision;
using Clock = std::chrono::steady_clock;

void report(const char* name, const PairwiseEnergy& energy, std::span<const Label> start) {
  ExpansionSolver<> solver;
  solver.bind(energy, start);
  const double start_energy = solver.energy();
  double flow = 0.0;
  int qpbo = 0;
  const auto t0 = Clock::now();
  for (int m = 0; m < energy.num_labels(); ++m) {
    solver.step();
    flow += solver.last_step().flow_seconds;
    qpbo += solver.last_step().used_qpbo;
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf("%-14s %9zu %9zu %6.2f %10.1f %8.1f%% %6.1f%% %12.1f %12.1f\n", name,
              energy.num_variables(), energy.edges().size(),
              2.0 * energy.edges().size() / energy.num_variables(),
              1000 * seconds / energy.num_labels(), 100 * flow / seconds,
              100.0 * qpbo / energy.num_labels(), start_energy, solver.energy());
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string data = "../shared/data", schedule_text = "regions";
    c2f::examples::ToolOptions options(
        "c2f-bench-levels: the cost of one expansion move on every level of a schedule.\n\n"
        "Usage: c2f-bench-levels SCENE [options]\n\nOptions");
    options.path("data", &data, "data root (scenes.csv)")
        .text("schedule", &schedule_text, "schedule (as c2f-stereo --schedule)");
    const auto arguments = options.parse(argc, argv, {"SCENE", 1});
    if (!arguments) return 0;
    if (arguments->size() != 1) throw std::invalid_argument("give SCENE (see --help)");
    c2f::examples::with_flag("--schedule", [&] { return parse_stereo_schedule(schedule_text); });
    const StereoScene scene = load_named_scene(data, arguments->front());
    const GridShape shape{static_cast<std::size_t>(scene.left.cols),
                          static_cast<std::size_t>(scene.left.rows)};
    TsgoOptions tsgo;
    const TsgoProblem problem = tsgo_problem(scene.left, scene.right, tsgo);
    const PairwiseEnergy& energy = problem.energy;
    std::printf("%-14s %9s %9s %6s %10s %9s %7s %12s %12s\n", "level", "variables", "edges",
                "degree", "ms/move", "flow", "qpbo", "E start", "E sweep");
    ScheduleProvider provider(parse_stereo_schedule(schedule_text), shape,
                              slic_source(problem.guide));
    while (auto partition = provider.next(energy)) {
      const PairwiseEnergy reduced = reduce(energy, *partition);
      report(provider.reports().back().level.c_str(), reduced,
             initial_labeling(reduced, InitialLabeling::unary_argmin));
    }
    report("original", energy, initial_labeling(energy, InitialLabeling::unary_argmin));
    return 0;
  } catch (const std::exception& error) {
    std::cerr << "c2f-bench-levels: error: " << error.what() << "\n";
    return 2;
  }
}
