// c2f-bench-expansion: flat alpha-expansion on a scene's TSGO energy with each max-flow backend,
// in one process: the same energy, start labeling, label order, moves and clock.
//
//   c2f-bench-expansion run SCENE [--data DIR] [--downscale K] [--labels L] [--graph-memory GIB]
//                       [--with-kolmogorov] [--header]
//       Runs expansion from the unary argmin until a whole sweep (one move per label) lowers
//       nothing, once per backend (boost, dynamic, and with --with-kolmogorov in builds that
//       have it libmaxflow), and prints one
//       tab-separated row: per backend the first-sweep time, the convergence time, the sweeps,
//       the final energy, the share of moves that needed QPBO and the share solved on a
//       recycled graph, then the peak resident size after the Boost run and after the dynamic
//       run (the dynamic run comes second, so its figure is the process's peak).
//   c2f-bench-expansion summarize ROWS.tsv
//       Prints the markdown table of all rows and the medians of the dynamic / Boost ratios.
//
// The TSGO energy is built once per scene (its cost volume is on no clock). --downscale shrinks
// the views by an integer factor and --labels sets the label count (default 85; scale it with
// the size for the scaling study).

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "c2f/c2f.hpp"
#include "c2f/support/number_text.hpp"
#include "c2f/vision/stereo/middlebury.hpp"
#include "c2f/vision/stereo/stereo_scene.hpp"
#include "c2f/vision/stereo/tsgo_energy.hpp"
#include "support/anytime_trace.hpp"
#include "support/bench_command.hpp"
#include "support/summary_rows.hpp"
#include "tool_options.hpp"

namespace {

using namespace c2f;
using Clock = std::chrono::steady_clock;

struct BackendRun {
  double first_sweep_s = 0.0;
  double converge_s = 0.0;
  int sweeps = 0;
  double final_energy = 0.0;
  double qpbo_share = 0.0;
  double recycled_share = 0.0;
};

constexpr int kMaxSweeps = 40;

template <class Backend>
BackendRun run_flat(const PairwiseEnergy& energy, std::size_t graph_memory_limit) {
  ExpansionOptions options;
  options.graph_memory_limit = graph_memory_limit;
  ExpansionSolver<Backend> solver(options);
  const Labeling start = initial_labeling(energy, InitialLabeling::unary_argmin);
  const auto t0 = Clock::now();
  solver.bind(energy, start);
  BackendRun result;
  long moves = 0, qpbo = 0, recycled = 0;
  const std::size_t sweep = solver.quiet_steps_to_converge(energy);
  for (int s = 0; s < kMaxSweeps; ++s) {
    bool improved = false;
    for (std::size_t m = 0; m < sweep; ++m) {
      solver.step();
      improved = improved || solver.last_step().improved;
      qpbo += solver.last_step().used_qpbo;
      recycled += solver.last_step().recycled;
      ++moves;
    }
    ++result.sweeps;
    if (s == 0) result.first_sweep_s = std::chrono::duration<double>(Clock::now() - t0).count();
    if (!improved) break;
  }
  result.converge_s = std::chrono::duration<double>(Clock::now() - t0).count();
  result.final_energy = solver.energy();
  result.qpbo_share = static_cast<double>(qpbo) / static_cast<double>(moves);
  result.recycled_share = static_cast<double>(recycled) / static_cast<double>(moves);
  std::fprintf(stderr, "  %d sweeps, first %.2f s, converged %.2f s, energy %.6f\n", result.sweeps,
               result.first_sweep_s, result.converge_s, result.final_energy);
  return result;
}

double peak_resident_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

const char* kColumns[] = {
    "scene",          "pixels",           "labels",           "boost_first_s",
    "boost_s",        "boost_sweeps",     "boost_energy",     "dynamic_first_s",
    "dynamic_s",      "dynamic_sweeps",   "dynamic_energy",   "qpbo_share",
    "recycled_share", "boost_peak_mib",   "dynamic_peak_mib", "kolmogorov_first_s",
    "kolmogorov_s",   "kolmogorov_energy"};

int run_scene(const std::string& name, const std::string& data, int downscale, int labels,
              std::size_t graph_memory_limit, bool with_kolmogorov, bool header) {
  const vision::StereoScene scene =
      vision::downscale(vision::load_named_scene(data, name), downscale);
  vision::TsgoOptions tsgo;
  tsgo.labels = labels;
  const PairwiseEnergy energy =
      vision::tsgo_energy(vision::tsgo_cost(scene.left, scene.right, tsgo), tsgo);
  std::fprintf(stderr, "%s: %zu pixels, %d labels; boost\n", name.c_str(), scene.shape().size(),
               labels);
  const BackendRun boost = run_flat<BoostMaxFlow>(energy, graph_memory_limit);
  const double boost_peak = peak_resident_mib();
  std::fprintf(stderr, "%s: dynamic\n", name.c_str());
  const BackendRun dynamic = run_flat<DynamicMaxFlow>(energy, graph_memory_limit);
  const double dynamic_peak = peak_resident_mib();
  BackendRun kolmogorov{std::nan(""), std::nan(""), 0, std::nan(""), 0.0, 0.0};
  if (with_kolmogorov) {
#ifdef C2F_HAVE_KOLMOGOROV_MAXFLOW
    std::fprintf(stderr, "%s: kolmogorov\n", name.c_str());
    kolmogorov = run_flat<KolmogorovMaxFlow>(energy, graph_memory_limit);
#else
    throw std::invalid_argument("--with-kolmogorov: this build has no libmaxflow backend");
#endif
  }
  if (header) {
    for (std::size_t i = 0; i < std::size(kColumns); ++i)
      std::printf("%s%s", i ? "\t" : "", kColumns[i]);
    std::printf("\n");
  }
  std::printf(
      "%s\t%zu\t%d\t%.3f\t%.3f\t%d\t%.6f\t%.3f\t%.3f\t%d\t%.6f\t%.3f\t%.3f\t%.0f\t%.0f\t%.3f\t%.3f"
      "\t%.6f\n",
      name.c_str(), scene.shape().size(), labels, boost.first_sweep_s, boost.converge_s,
      boost.sweeps, boost.final_energy, dynamic.first_sweep_s, dynamic.converge_s, dynamic.sweeps,
      dynamic.final_energy, dynamic.qpbo_share, dynamic.recycled_share, boost_peak, dynamic_peak,
      kolmogorov.first_sweep_s, kolmogorov.converge_s, kolmogorov.final_energy);
  return 0;
}

int summarize(const std::string& path) {
  const auto rows = bench::read_summary_rows(path, "scene\t", std::size(kColumns));
  std::printf(
      "| scene | pixels x labels | Boost first sweep (s) | dynamic first sweep (s) | ratio | Boost "
      "converged (s) | dynamic converged (s) | ratio | sweeps Boost / dynamic | final energy "
      "difference | QPBO moves | recycled moves | peak MiB Boost / dynamic |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<double> first_ratio, converge_ratio, energy_difference, peak;
  for (const std::vector<std::string>& f : rows) {
    auto number = [&](std::size_t i) {
      const std::optional<double> value = parse_real(f[i]);
      return value ? *value : std::nan("");
    };
    const double first = number(7) / number(3);
    const double converge = number(8) / number(4);
    const double difference = (number(10) - number(6)) / number(6);
    first_ratio.push_back(first);
    converge_ratio.push_back(converge);
    energy_difference.push_back(difference);
    peak.push_back(number(14));
    std::printf(
        "| %s | %.1fM | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %s / %s | %+.1e | %.0f%% | "
        "%.0f%% | %.0f / %.0f |\n",
        f[0].c_str(), number(1) * number(2) / 1e6, number(3), number(7), first, number(4),
        number(8), converge, f[5].c_str(), f[9].c_str(), difference, 100 * number(11),
        100 * number(12), number(13), number(14));
  }
  std::printf("| **median** | | | | **%.2f** | | | **%.2f** | | %+.1e | | | - / %.0f |\n",
              bench::median(first_ratio), bench::median(converge_ratio),
              bench::median(energy_difference), bench::median(peak));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string data = "../shared/data";
    int downscale = 1, labels = 85;
    double graph_memory_gib = static_cast<double>(MoveOptions{}.graph_memory_limit) / (1 << 30);
    bool header = false, with_kolmogorov = false;
    c2f::examples::ToolOptions options(
        "c2f-bench-expansion: flat expansion of one scene's TSGO energy with every max-flow "
        "backend, one row each.\n\nUsage: c2f-bench-expansion run SCENE [options]\n"
        "       c2f-bench-expansion summarize ROWS.tsv\n\nOptions");
    options.path("data", &data, "data root (scenes.csv)")
        .integer("downscale", &downscale, {1, 16}, "shrink the views by this factor")
        .integer("labels", &labels, {2, 256}, "disparity labels")
        .real("graph-memory", &graph_memory_gib, {0.0, 1024.0},
              "GiB of recycled move graphs for the dynamic backend")
        .flag("with-kolmogorov", &with_kolmogorov, "also time libmaxflow (when built)")
        .flag("header", &header, "print the TSV header first");
    const auto arguments = options.parse(argc, argv, {"run SCENE | summarize ROWS.tsv", 2});
    if (!arguments) return 0;
    const bench::BenchCommand command = bench::bench_command(*arguments, "SCENE");
    if (command.summarize) return summarize(command.rows);
    return run_scene(command.names[0], data, downscale, labels,
                     static_cast<std::size_t>(graph_memory_gib * (1 << 30)), with_kolmogorov,
                     header);
  } catch (const std::exception& error) {
    std::cerr << "c2f-bench-expansion: error: " << error.what() << "\n";
    return 2;
  }
}
