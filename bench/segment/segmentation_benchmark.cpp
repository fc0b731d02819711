// c2f-bench-segment: cooperative-cut segmentation, flat and coarse to fine, on the coopCuts
// data, with the Potts alpha-expansion baseline.
//
//   c2f-bench-segment run SET NAME [--data DIR] [--out DIR] [--time-limit S] [--header]
//                     [--configs A,B,...] [--lambda X] [--theta X] [--alpha X]
//                     [--classes K] [--kmeans reference|plusplus] [--gmm-seed S] [--edge-seed S]
//                     [--memory GIB] [--expansion-cycles N] [--near-radius R]
//       SET is multilabel (coopcuts/runMultilabel, labels from the GT) or binary
//       (coopcuts/runBinary/dataset). Builds the energies of image NAME once, then runs every
//       configuration below in this process, each from scratch with its own clock (partitions
//       and reductions on it), and prints one tab-separated row per configuration (the
//       cooperative cut's steps make at most --expansion-cycles alpha-expansion cycles, 0: the
//       strategy's own, CoopSolverOptions::cycles()). Traces go to
//       OUT/NAME-CONFIG.csv. The memory budget (--memory, default as c2f-segment's) must hold
//       the data preparation, and the Potts runs' recycled move graphs get what it leaves.
//   c2f-bench-segment summarize ROWS.tsv
//       Prints the markdown tables (per image, and medians per configuration).
//
// Configurations: potts (alpha-expansion of the Potts energy, flat); flat-greedy-zero (the
// reference CoGC), flat-greedy-current, flat-mm, flat-ceres; c2f-paper-greedy-zero (the
// reference C2F-CoGC: paper levels, refinement after L trials without decrease),
// c2f-paper-greedy-current, c2f-sweep-greedy-current (paper levels left only after a whole sweep
// of flips without decrease), c2f-slic-greedy-current and c2f-slic-greedy-zero (slic:16 slic:8,
// whole sweeps), c2f-paper-mm, c2f-slic-mm (the superpixels preset, whole moves); flat-mm-near
// and c2f-slic-mm-near, the same with near moves of --near-radius on the original problem
// (CoopSolverOptions::near_radius; by default the segmentation defaults' radius, so that
// c2f-slic-mm-near is what c2f-segment runs with no flags, docs/segmentation.md). Every
// coarse-to-fine configuration is compared with the flat run of the same solver: the time it takes
// to reach that run's final energy, as a fraction of that run's time, and the mean pixel error at
// 20 deadlines drawn uniformly (fixed seed) in [0, the slower run's time]. On the original problem
// every run ends after a whole sweep without decrease.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "c2f/c2f.hpp"
#include "c2f/support/output_file.hpp"
#include "coop_flags.hpp"
#include "output_folder.hpp"
#include "support/anytime_comparison.hpp"
#include "support/anytime_trace.hpp"
#include "support/bench_command.hpp"
#include "support/coopcuts_files.hpp"
#include "support/summary_rows.hpp"
#include "tool_options.hpp"

using namespace c2f;
using namespace c2f::vision;

namespace {

struct Run {
  std::vector<bench::TracePoint> trace;
  Summary summary;
  double error = 0.0;
  double coop_energy = 0.0;
};

struct Config {
  std::string name;
  bool potts = false;
  AuxStrategy strategy = AuxStrategy::greedy;
  ExpansionStart start = ExpansionStart::current;
  std::string schedule = "flat";
  bool sweep_plateau = false;  ///< coarse levels left after a whole sweep, not after L steps
  std::string flat;            ///< the flat configuration this one is compared with
  bool near = false;           ///< near moves on the original problem (--near-radius)
};

/// The options every configuration's cooperative-cut solver takes from the command line.
struct SolverFlags {
  int expansion_cycles = CoopSolverOptions{}.expansion_cycles;
  /// CoopSolverOptions::near_radius of the configurations that say near (on the original problem
  /// only, as run_segmentation makes them)
  int near_radius = segmentation_defaults().mm_near_radius;
};

const std::vector<Config>& configs() {
  static const std::vector<Config> all{
      {"potts", true, AuxStrategy::greedy, ExpansionStart::zero, "flat", false, ""},
      {"flat-greedy-zero", false, AuxStrategy::greedy, ExpansionStart::zero, "flat", false, ""},
      {"flat-greedy-current", false, AuxStrategy::greedy, ExpansionStart::current, "flat", false,
       ""},
      {"flat-mm", false, AuxStrategy::mm, ExpansionStart::zero, "flat", false, ""},
      {"flat-ceres", false, AuxStrategy::ceres, ExpansionStart::zero, "flat", false, ""},
      {"c2f-paper-greedy-zero", false, AuxStrategy::greedy, ExpansionStart::zero, "paper", false,
       "flat-greedy-zero"},
      {"c2f-paper-greedy-current", false, AuxStrategy::greedy, ExpansionStart::current, "paper",
       false, "flat-greedy-current"},
      {"c2f-sweep-greedy-current", false, AuxStrategy::greedy, ExpansionStart::current, "paper",
       true, "flat-greedy-current"},
      {"c2f-slic-greedy-current", false, AuxStrategy::greedy, ExpansionStart::current,
       "slic:16 slic:8 flat", true, "flat-greedy-current"},
      {"c2f-slic-greedy-zero", false, AuxStrategy::greedy, ExpansionStart::zero,
       "slic:16 slic:8 flat", true, "flat-greedy-zero"},
      {"c2f-paper-mm", false, AuxStrategy::mm, ExpansionStart::zero, "paper", false, "flat-mm"},
      {"c2f-slic-mm", false, AuxStrategy::mm, ExpansionStart::zero, "superpixels", false,
       "flat-mm"},
      {"flat-mm-near", false, AuxStrategy::mm, ExpansionStart::zero, "flat", false, "", true},
      {"c2f-slic-mm-near", false, AuxStrategy::mm, ExpansionStart::zero, "superpixels", false,
       "flat-mm-near", true},
  };
  return all;
}

Run solve(const Config& config, const SegmentationScene& scene, const SegmentationProblem& problem,
          double time_limit, const SolverFlags& flags, const MemoryBudget& memory,
          const std::string& trace_path) {
  const Schedule schedule = parse_segmentation_schedule(config.schedule, scene.num_labels());
  ScheduleProvider levels = segmentation_levels(schedule, scene);
  // Coarse levels end after L steps without decrease (a whole sweep when the configuration
  // says so, or when a sweep is shorter); the original problem where the solver has converged.
  // As in c2f-segment, within the memory budget.
  SegmentationRunConfig run_config;
  run_config.method = config.potts ? SegmentationMethod::potts : SegmentationMethod::coop;
  run_config.coop.strategy = config.strategy;
  run_config.coop.start = config.start;
  run_config.coop.expansion_cycles = flags.expansion_cycles;
  if (config.near) run_config.coop.near_radius = flags.near_radius;
  run_config.plateau = config.sweep_plateau ? -1 : 0;
  run_config.time_limit_seconds = time_limit;
  run_config.memory = memory;
  Run run;
  std::ofstream file = open_trace_file(trace_path);
  const auto error = pixel_error_function(scene);
  TraceWriter writer(file, error);
  Labeling ground;
  const Observer observer = [&](const StepEvent& event) {
    writer(event);
    run.trace.push_back({event.time_s, event.energy, error(event.ground_labeling(ground))});
    return ObserverDecision::continue_run;
  };
  run.summary = run_segmentation(problem, levels, run_config, observer).summary;
  close_checked(file, trace_path);
  run.error = error(run.summary.labeling);
  run.coop_energy = problem.coop.evaluate(run.summary.labeling);
  return run;
}

const char* kColumns[] = {"image",
                          "pixels",
                          "labels",
                          "config",
                          "coop_energy",
                          "error",
                          "seconds",
                          "steps",
                          "reason",
                          "reach_seconds",
                          "reach_ratio",
                          "deadline_error_flat",
                          "deadline_error_c2f"};

int run_image(const std::string& set, const std::string& name, const std::string& data,
              const std::string& out, double time_limit, bool header,
              const std::vector<std::string>& selected, const CoopParameters& parameters,
              const DataPreparation& preparation, const SolverFlags& flags,
              const MemoryBudget& memory) {
  const SegmentationScene scene = load_segmentation_scene(bench::coopcuts_files(data, set, name));
  memory.require("segmenting " + set + "/" + name,
                 segmentation_memory_estimate(scene.image.total(), scene.num_labels()));
  const SegmentationProblem problem = segmentation_problem(scene, parameters, preparation);
  // The image's traces land together after its last row (each run stages its own files and
  // owns only the traces of the configurations it runs).
  std::vector<std::string> traces;
  for (const Config& config : configs()) {
    if (selected.empty() ||
        std::find(selected.begin(), selected.end(), config.name) != selected.end())
      traces.push_back(name + "-" + config.name + ".csv");
  }
  examples::OutputFolder output(out, "c2f-bench-segment", traces,
                                examples::OutputFolder::Sharing::by_files);
  if (header) {
    for (std::size_t i = 0; i < std::size(kColumns); ++i)
      std::printf("%s%s", i ? "\t" : "", kColumns[i]);
    std::printf("\n");
  }
  std::map<std::string, Run> runs;
  for (const Config& config : configs()) {
    if (!selected.empty() &&
        std::find(selected.begin(), selected.end(), config.name) == selected.end())
      continue;
    if (!config.flat.empty() && !runs.count(config.flat)) {
      throw std::invalid_argument("--configs: " + config.name + " is compared with " + config.flat +
                                  ", which is not in the list");
    }
    std::fprintf(stderr, "c2f-bench-segment: %s %s\n", name.c_str(), config.name.c_str());
    Run run = solve(config, scene, problem, time_limit, flags, memory,
                    (output.staging() / (name + "-" + config.name + ".csv")).string());
    double reach = std::nan(""), ratio = std::nan(""), flat_error = std::nan(""),
           c2f_error = std::nan("");
    if (!config.flat.empty()) {
      const Run& flat = runs.at(config.flat);
      // The deadlines of the segmentation tables (docs/history/results-2026-11.md) were drawn
      // with this seed.
      constexpr std::uint64_t kSegmentationDeadlineSeed = 20261122;
      const bench::AnytimeComparison anytime = bench::compare_anytime(
          {flat.trace, flat.summary.energy, flat.summary.seconds},
          {run.trace, run.summary.energy, run.summary.seconds}, kSegmentationDeadlineSeed);
      reach = anytime.reach_seconds;
      ratio = anytime.reach_ratio;
      flat_error = anytime.flat_error;
      c2f_error = anytime.run_error;
    }
    std::printf("%s\t%zu\t%d\t%s\t%.6f\t%.6f\t%.3f\t%ld\t%s\t%.3f\t%.4f\t%.6f\t%.6f\n",
                name.c_str(), scene.image.total(), scene.num_labels(), config.name.c_str(),
                run.coop_energy, run.error, run.summary.seconds, run.summary.total_steps,
                std::string(to_string(run.summary.reason)).c_str(), reach, ratio, flat_error,
                c2f_error);
    std::fflush(stdout);
    runs.emplace(config.name, std::move(run));
  }
  output.commit();
  return 0;
}

int summarize(const std::string& path) {
  struct Row {
    std::string image, config, reason;
    double energy, error, seconds, reach, ratio, flat_error, c2f_error;
  };
  std::vector<Row> rows;
  auto number = [](const std::string& s) {
    return s == "nan" || s == "-nan" ? std::nan("") : std::stod(s);
  };
  const auto read = bench::read_summary_rows(path, "image\t", std::size(kColumns));
  // Energy, error and seconds are numbers; the times of reaching flat's energy and the deadline
  // errors may be nan (never reached, no GT).
  bench::require_row_numbers(read, path, kColumns, {1, 2, 4, 5, 6, 7, 9, 10, 11, 12},
                             {5, 9, 10, 11, 12});
  for (const auto& f : read) {
    rows.push_back({f[0], f[3], f[8], number(f[4]), number(f[5]), number(f[6]), number(f[9]),
                    number(f[10]), number(f[11]), number(f[12])});
  }
  auto fixed = [](double value, const char* format) {
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return std::string(text);
  };
  std::printf(
      "| image | configuration | energy | pixel error | seconds | reaches flat E (s) | ratio |"
      " deadline error flat / C2F | end |\n|---|---|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    const bool compared = !std::isnan(r.flat_error);
    const std::string reach = !compared             ? ""
                              : std::isnan(r.reach) ? "never"
                                                    : fixed(r.reach, "%.2f");
    const std::string ratio = !compared || std::isnan(r.ratio) ? "" : fixed(r.ratio, "%.2f");
    const std::string deadline = !compared ? ""
                                           : fixed(100 * r.flat_error, "%.2f%%") + " / " +
                                                 fixed(100 * r.c2f_error, "%.2f%%");
    std::printf("| %s | %s | %.2f | %.2f%% | %.1f | %s | %s | %s | %s |\n", r.image.c_str(),
                r.config.c_str(), r.energy, 100 * r.error, r.seconds, reach.c_str(), ratio.c_str(),
                deadline.c_str(), r.reason.c_str());
  }
  std::printf(
      "\nMedians per configuration (ratio: a run that never reaches flat's energy counts as "
      "infinitely slow; deadline error: the medians of the two runs' mean errors):\n\n"
      "| configuration | images | pixel error | seconds | ratio | <= 0.67x | <= 0.4x | deadline "
      "error flat / C2F |\n|---|---|---|---|---|---|---|---|\n");
  for (const Config& config : configs()) {
    std::vector<double> error, seconds, ratio, flat_error, c2f_error;
    for (const Row& r : rows) {
      if (r.config != config.name) continue;
      error.push_back(r.error);
      seconds.push_back(r.seconds);
      if (!config.flat.empty()) {
        ratio.push_back(std::isnan(r.ratio) ? std::numeric_limits<double>::infinity() : r.ratio);
        flat_error.push_back(r.flat_error);
        c2f_error.push_back(r.c2f_error);
      }
    }
    if (error.empty()) continue;
    const auto at_most = [&](double bound) {
      return std::to_string(
          std::count_if(ratio.begin(), ratio.end(), [&](double v) { return v <= bound; }));
    };
    const std::string deadline = flat_error.empty()
                                     ? ""
                                     : fixed(100 * bench::median(flat_error), "%.2f%%") + " / " +
                                           fixed(100 * bench::median(c2f_error), "%.2f%%");
    std::printf("| %s | %zu | %.2f%% | %.1f | %s | %s | %s | %s |\n", config.name.c_str(),
                error.size(), 100 * bench::median(error), bench::median(seconds),
                ratio.empty() ? "" : fixed(bench::median(ratio), "%.2f").c_str(),
                ratio.empty() ? "" : at_most(0.67).c_str(),
                ratio.empty() ? "" : at_most(0.4).c_str(), deadline.c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string data = "../shared/data", out = "out/bench-segment", config_list = "all";
    double time_limit = 600;
    bool header = false;
    double memory_gib = 0.0;  // 0: default_memory_budget()
    SolverFlags flags;
    CoopParameters parameters;
    c2f::examples::PreparationFlags preparation;
    c2f::examples::ToolOptions options(
        "c2f-bench-segment: cooperative-cut segmentation of one image, flat and coarse to fine, "
        "one row per configuration.\n\nUsage: c2f-bench-segment run SET NAME [options]\n"
        "       c2f-bench-segment summarize ROWS.tsv\n\nOptions");
    options.path("data", &data, "data root")
        .path("out", &out, "folder for traces and label images")
        .real("time-limit", &time_limit, {0.0, 1e7, true}, "seconds per run")
        .text("configs", &config_list, "comma-separated configurations, or all")
        .real("memory", &memory_gib, {0.0, 1e6, false},
              "the memory budget in GiB, as c2f-segment --memory (0, the default: a quarter of "
              "this machine's memory, growing to a run's needs up to half)")
        .integer("expansion-cycles", &flags.expansion_cycles, {0, 1000},
                 "most alpha-expansion cycles of E_h per step of the cooperative cut (0: the "
                 "strategy's own, CoopSolverOptions::cycles())")
        .integer("near-radius", &flags.near_radius, {1, 1000},
                 "near moves' radius on the original problem in the *-near configurations "
                 "(CoopSolverOptions::near_radius)")
        .flag("header", &header, "print the TSV header first");
    c2f::examples::declare_coop_parameters(options, parameters);
    c2f::examples::declare_data_preparation(options, preparation);
    const auto arguments = options.parse(argc, argv, {"run SET NAME | summarize ROWS.tsv", 3});
    if (!arguments) return 0;
    const bench::BenchCommand command = bench::bench_command(*arguments, "SET NAME");
    if (command.summarize) return summarize(command.rows);
    std::vector<std::string> selected;
    if (config_list.empty())
      throw std::invalid_argument(
          "--configs: expected a comma-separated list of configurations or all, got ''");
    if (config_list == "all") config_list.clear();
    std::stringstream list(config_list);
    for (std::string name; std::getline(list, name, ',');) {
      if (std::none_of(configs().begin(), configs().end(),
                       [&](const Config& c) { return c.name == name; }))
        throw std::invalid_argument("--configs: unknown configuration '" + name + "'");
      selected.push_back(name);
    }
    const MemoryBudget memory =
        memory_gib > 0.0
            ? memory_budget_of_gib(memory_gib, "--memory " + c2f::format_real(memory_gib))
            : default_memory_budget();
    return run_image(command.names[0], command.names[1], data, out, time_limit, header, selected,
                     parameters, preparation.resolved(), flags, memory);
  } catch (const std::exception& error) {
    std::cerr << "c2f-bench-segment: error: " << error.what() << "\n";
    return 2;
  }
}
