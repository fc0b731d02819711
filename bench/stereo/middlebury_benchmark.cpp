// c2f-bench-stereo: flat TSGO against C2F-TSGO on Middlebury scenes, with OpenCV's StereoSGBM
// for reference.
//
//   c2f-bench-stereo run SCENE [--data DIR] [--out DIR] [--time-limit S] [--schedule TEXT]
//                    [--label-order sequential|random|frequency] [--coarse-tolerance T]
//                    [--c2f-progress-rate]
//                    [--maxflow dynamic|boost|kolmogorov] [--downscale K] [--labels L]
//                    [--flat-near-radius R] [--c2f-near-radius R] [--flat-shift-moves]
//                    [--c2f-shift-moves] [--near-levels original|all] [--threads N]
//                    [--prep-one-thread] [--prep-repeats K] [--memory GIB]
//       Solves SCENE (a scenes.csv row, middlebury2014/NAME, kitti2015/ID or opencv-doc/aloe)
//       flat and coarse to fine from the same TSGO cost volume,
//       with the same solver (alpha-expansion with the given label order on the given max-flow
//       backend, default dynamic; near moves of radius R, ExpansionOptions::near_radius, and shift
//       moves, ExpansionOptions::shift_moves, in either run on request, on the original problem
//       only or on every level: with `--schedule flat` this compares two flat solvers),
//       options and run clock (which includes partitions and reductions), and prints one
//       tab-separated result row (header with --header). Coarse levels are refined after 4
//       moves without a decrease larger than T * |E| (default 0: the paper's rule); the
//       original problem, in both runs, ends after a whole sweep without decrease (three
//       sweeps with near moves). Traces go to OUT/SCENE-{flat,c2f}.csv ('/' in SCENE as '-').
//       Each run's recycled move graphs get what the memory budget leaves (the run layer, as in
//       c2f-stereo). The row has the peak resident size of the data preparation and of each run
//       (the process's, reset before each: it includes the scene and energy already resident)
//       and, with --prep-one-thread, the data preparation's time on one thread (that energy must
//       equal the one prepared on --threads, else the run stops). With --prep-repeats K the
//       preparation is timed K times on --threads (and K times on one thread, alternating with
//       them), and the row holds the median of each: sub-second preparations vary by up to a
//       third from one run to the next.
//   c2f-bench-stereo summarize ROWS.tsv
//       Prints the markdown table of all rows and the medians.
//
// Error = the scene's own measure (StereoScene::measure): bad 1 for 2001-2006 (|d - gt| > 1),
// bad 2.0 at full size for Middlebury 2014, D1 for KITTI; the deadline errors over the
// non-occluded pixels when the scene has a mask (official masks for 2003 and 2014, left-right
// check for 2005/2006), else over all pixels with GT. Labels: --labels, else the scene's range
// (Middlebury 2014 ndisp, KITTI 128), else 85. Deadlines: 20 times drawn uniformly (fixed seed) in
// [0, the slower run's convergence time]; at a deadline each method shows the labeling of its
// latest step before it.

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "c2f/c2f.hpp"
#include "c2f/support/number_text.hpp"
#include "c2f/support/output_file.hpp"
#include "c2f/support/parallel_for.hpp"
#include "c2f/vision/stereo/disparity_io.hpp"
#include "c2f/vision/stereo/evaluation.hpp"
#include "c2f/vision/stereo/middlebury.hpp"
#include "c2f/vision/stereo/stereo_schedules.hpp"
#include "c2f/vision/stereo/tsgo_energy.hpp"
#include "c2f/vision/superpixels.hpp"
#include "output_folder.hpp"
#include "support/anytime_comparison.hpp"
#include "support/anytime_trace.hpp"
#include "support/bench_command.hpp"
#include "support/peak_memory.hpp"
#include "support/summary_rows.hpp"
#include "tool_options.hpp"

using namespace c2f;
using namespace c2f::vision;

namespace {

struct Run {
  std::vector<bench::TracePoint> trace;
  Summary summary;
  SceneErrors errors;  ///< of the final labeling, by the scene's measure
};

const char* kColumns[] = {"scene",
                          "pixels",
                          "flat_energy",
                          "c2f_energy",
                          "flat_bad_nonocc",
                          "c2f_bad_nonocc",
                          "flat_bad_all",
                          "c2f_bad_all",
                          "flat_seconds",
                          "c2f_seconds",
                          "c2f_reach_flat_seconds",
                          "reach_ratio",
                          "deadline_error_flat",
                          "deadline_error_c2f",
                          "deadline_error_reduction",
                          "sgbm_bad_nonocc",
                          "sgbm_bad_all",
                          "sgbm_seconds",
                          "flat_reason",
                          "c2f_reason",
                          "labels",
                          "prep_seconds",
                          "threads",
                          "c2f_band_seconds",
                          "band_ratio",
                          "prep_one_thread_seconds",
                          "prep_peak_mib",
                          "flat_peak_mib",
                          "c2f_peak_mib",
                          "memory_gib"};

struct Settings {
  std::string schedule = "paper";
  double time_limit = 600;
  VisitOrder label_order = VisitOrder::sequential;
  double coarse_tolerance = 0.0;
  bool c2f_progress_rate = false;  ///< RunConfig::progress_rate of the coarse-to-fine run
  MaxFlowKind maxflow = MaxFlowKind::dynamic;
  int downscale = 1;              ///< shrink the views by this factor (the scaling study)
  int labels = 0;                 ///< 0: the scene's range, else 85
  int threads = 0;                ///< data preparation threads (0: the machine's cores)
  int flat_near_radius = 0;       ///< ExpansionOptions::near_radius of the flat run
  int c2f_near_radius = 0;        ///< and of the coarse-to-fine run
  bool flat_shift_moves = false;  ///< ExpansionOptions::shift_moves of the flat run
  bool c2f_shift_moves = false;   ///< and of the coarse-to-fine run
  NearLevels near_levels = NearLevels::original;  ///< where near and shift moves are made
  bool prep_one_thread = false;  ///< also prepare on one thread first (time, identity check)
  int prep_repeats = 1;          ///< preparations timed (on each thread count); their medians
  MemoryBudget memory = default_memory_budget();  ///< each run's, as c2f-stereo --memory
};

/// FNV-1a over the energy's unaries and edges: equal energies, equal fingerprints.
std::uint64_t energy_fingerprint(const PairwiseEnergy& energy) {
  std::uint64_t hash = 14695981039346656037ULL;
  auto mix = [&hash](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 1099511628211ULL;
  };
  energy.unaries().visit([&](auto costs) { mix(costs.data(), costs.size_bytes()); });
  for (const Edge& e : energy.edges()) {
    mix(&e.u, sizeof e.u);
    mix(&e.v, sizeof e.v);
    mix(&e.weight, sizeof e.weight);
    mix(&e.term, sizeof e.term);
  }
  return hash;
}

Run solve(const TsgoProblem& problem, const StereoScene& scene, const std::string& schedule,
          int near_radius, bool shift_moves, const Settings& settings,
          const std::string& trace_path) {
  ExpansionOptions expansion;
  expansion.order = settings.label_order;
  expansion.near_radius = near_radius;
  expansion.shift_moves = shift_moves;
  RunConfig config;
  config.solver = expansion_spec(expansion, settings.near_levels, settings.maxflow);
  config.limits.plateau_steps = {4};
  config.limits.plateau_tolerance = settings.coarse_tolerance;  // the original: converged
  config.progress_rate = settings.c2f_progress_rate;            // no coarse level in the flat run
  config.limits.time_limit_seconds = settings.time_limit;
  config.memory = settings.memory;
  config.energy_name = "the " + schedule + " run";
  Run run;
  std::ofstream file = open_trace_file(trace_path);
  TraceWriter writer(file);
  const auto error = bad_pixel_error(scene);
  Labeling ground;
  run.summary =
      run_stereo(problem, parse_stereo_schedule(schedule), config, [&](const StepEvent& event) {
        writer(event);
        run.trace.push_back({event.time_s, event.energy, error(event.ground_labeling(ground))});
        return ObserverDecision::continue_run;
      }).run.summary;
  close_checked(file, trace_path);
  run.errors = scene_errors(labels_to_disparity(run.summary.labeling, scene.shape()), scene);
  return run;
}

/// The TSGO energy of a scene and how long preparing it took.
struct Preparation {
  TsgoProblem problem;        ///< the last one prepared on tsgo.threads
  double seconds;             ///< median over the preparations on tsgo.threads
  double one_thread_seconds;  ///< median over those on one thread (NaN without prep_one_thread)
  double peak_mib;            ///< peak resident size during the last preparation
};

/// Prepares the scene's energy settings.prep_repeats times on tsgo.threads, each time (with
/// settings.prep_one_thread) after a preparation on one thread, and times each. Every energy
/// must equal the first one prepared (the thread count must not change it), else throws
/// std::runtime_error naming the scene. Each preparation's seconds go to stderr.
Preparation prepare_timed(const std::string& name, const StereoScene& scene,
                          const TsgoOptions& tsgo, const Settings& settings) {
  std::vector<double> one_thread_seconds, threads_seconds;
  std::optional<std::uint64_t> first_fingerprint;
  // Prepares on `options`, appends the seconds to `seconds` and checks the energy.
  auto prepare = [&](const TsgoOptions& options, std::vector<double>& seconds) {
    PreparedStereo timed = prepare_stereo(scene, options);
    seconds.push_back(timed.seconds);
    TsgoProblem prepared = std::move(timed.problem);
    const std::uint64_t fingerprint = energy_fingerprint(prepared.energy);
    if (!first_fingerprint) first_fingerprint = fingerprint;
    if (fingerprint != *first_fingerprint) {
      throw std::runtime_error("scene '" + name + "': the energy prepared on " +
                               std::to_string(resolved_threads(options.threads)) +
                               " threads differs from the one prepared before");
    }
    return prepared;
  };
  TsgoOptions one_thread = tsgo;
  one_thread.threads = 1;
  std::optional<TsgoProblem> prepared;
  double peak_mib = 0.0;
  for (int repeat = 0; repeat < settings.prep_repeats; ++repeat) {
    if (settings.prep_one_thread) prepare(one_thread, one_thread_seconds);
    prepared.reset();
    bench::reset_peak_resident();
    prepared.emplace(prepare(tsgo, threads_seconds));
    peak_mib = bench::peak_resident_mib();
    std::fprintf(stderr, "c2f-bench-stereo: %s preparation %d of %d: %.3f s on %d threads",
                 name.c_str(), repeat + 1, settings.prep_repeats, threads_seconds.back(),
                 resolved_threads(tsgo.threads));
    if (settings.prep_one_thread) std::fprintf(stderr, ", %.3f s on 1", one_thread_seconds.back());
    std::fprintf(stderr, "\n");
  }
  return {std::move(*prepared), bench::median(threads_seconds), bench::median(one_thread_seconds),
          peak_mib};
}

int run_scene(const std::string& name, const std::string& data, const std::string& out,
              const Settings& settings, bool header) {
  const StereoScene scene = downscale(load_named_scene(data, name), settings.downscale);
  const GridShape shape = scene.shape();
  TsgoOptions tsgo;
  tsgo.labels = settings.labels != 0 ? settings.labels : label_count(scene, 85);
  tsgo.threads = settings.threads;
  if (const std::string problem = parse_stereo_schedule(settings.schedule).validate(tsgo.labels);
      !problem.empty()) {
    throw std::invalid_argument("--schedule: " + problem + " (" + std::to_string(tsgo.labels) +
                                " labels)");
  }
  const Preparation preparation = prepare_timed(name, scene, tsgo, settings);
  const TsgoProblem& problem = preparation.problem;
  // The scene's traces land together when its row is printed (parallel runs share the folder;
  // each stages its own files).
  // Trace files are named by the scene, its dataset prefix joined by '-' (kitti2015-000000_10).
  std::string stem = name;
  std::replace(stem.begin(), stem.end(), '/', '-');
  examples::OutputFolder output(out, "c2f-bench-stereo", {stem + "-flat.csv", stem + "-c2f.csv"},
                                examples::OutputFolder::Sharing::by_files);
  auto solve_with = [&](const std::string& schedule, int near_radius, bool shift_moves,
                        const std::string& trace) {
    return solve(problem, scene, schedule, near_radius, shift_moves, settings,
                 (output.staging() / trace).string());
  };
  bench::reset_peak_resident();
  const Run flat =
      solve_with("flat", settings.flat_near_radius, settings.flat_shift_moves, stem + "-flat.csv");
  const double flat_peak_mib = bench::peak_resident_mib();
  bench::reset_peak_resident();
  const Run c2f = solve_with(settings.schedule, settings.c2f_near_radius, settings.c2f_shift_moves,
                             stem + "-c2f.csv");
  const double c2f_peak_mib = bench::peak_resident_mib();

  const bench::AnytimeComparison anytime =
      bench::compare_anytime({flat.trace, flat.summary.energy, flat.summary.seconds},
                             {c2f.trace, c2f.summary.energy, c2f.summary.seconds});

  // OpenCV StereoSGBM on the same views. SGBM leaves its leftmost numDisparities columns
  // undefined, so both views are padded on the left by replication and the result cropped (the
  // usual practice); pixels it still marks invalid count as bad.
  const auto sgbm_start = std::chrono::steady_clock::now();
  constexpr int kSgbmDisparities = 96;
  auto sgbm = cv::StereoSGBM::create(0, kSgbmDisparities, 5, 8 * 3 * 25, 32 * 3 * 25, 1, 0, 10, 100,
                                     2, cv::StereoSGBM::MODE_SGBM);
  cv::Mat padded_left, padded_right, padded_fixed;
  cv::copyMakeBorder(scene.left, padded_left, 0, 0, kSgbmDisparities, 0, cv::BORDER_REPLICATE);
  cv::copyMakeBorder(scene.right, padded_right, 0, 0, kSgbmDisparities, 0, cv::BORDER_REPLICATE);
  sgbm->compute(padded_left, padded_right, padded_fixed);
  const cv::Mat fixed =
      padded_fixed(cv::Rect(kSgbmDisparities, 0, scene.left.cols, scene.left.rows));
  const double sgbm_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - sgbm_start).count();
  cv::Mat sgbm_disparity(fixed.size(), CV_32F);
  for (int y = 0; y < fixed.rows; ++y) {
    for (int x = 0; x < fixed.cols; ++x) {
      const short v = fixed.at<short>(y, x);
      sgbm_disparity.at<float>(y, x) = v < 0 ? std::numeric_limits<float>::quiet_NaN() : v / 16.0F;
    }
  }
  const SceneErrors sgbm_errors = scene_errors(sgbm_disparity, scene);

  if (header) {
    for (std::size_t i = 0; i < std::size(kColumns); ++i)
      std::printf("%s%s", i ? "\t" : "", kColumns[i]);
    std::printf("\n");
  }
  std::printf(
      "%s\t%zu\t%.6f\t%.6f\t%.5f\t%.5f\t%.5f\t%.5f\t%.3f\t%.3f\t%.3f\t%.4f\t%.5f\t%.5f\t%.4f\t%."
      "5f\t%.5f\t%.3f\t%s\t%s\t%d\t%.3f\t%u\t%.3f\t%.4f\t%.3f\t%.0f\t%.0f\t%.0f\t%.2f\n",
      name.c_str(), shape.size(), flat.summary.energy, c2f.summary.energy, flat.errors.nonoccluded,
      c2f.errors.nonoccluded, flat.errors.all, c2f.errors.all, flat.summary.seconds,
      c2f.summary.seconds, anytime.reach_seconds, anytime.reach_ratio, anytime.flat_error,
      anytime.run_error, 1.0 - anytime.run_error / anytime.flat_error, sgbm_errors.nonoccluded,
      sgbm_errors.all, sgbm_seconds, std::string(to_string(flat.summary.reason)).c_str(),
      std::string(to_string(c2f.summary.reason)).c_str(), tsgo.labels, preparation.seconds,
      resolved_threads(tsgo.threads), anytime.band_seconds, anytime.band_ratio,
      preparation.one_thread_seconds, preparation.peak_mib, flat_peak_mib, c2f_peak_mib,
      settings.memory.bytes / double(std::size_t{1} << 30));
  output.commit();
  return 0;
}

int summarize(const std::string& path) {
  const auto rows = bench::read_summary_rows(path, "scene\t", std::size(kColumns));
  // Energies and run times are numbers; rates a scene has not (KITTI's non-occluded), times
  // never reached and preparations not measured may be nan.
  bench::require_row_numbers(rows, path, kColumns, {1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12,
                                                    13, 14, 15, 16, 17, 21, 23, 24, 25, 26, 27, 28},
                             {4, 5, 10, 11, 12, 13, 14, 15, 16, 17, 23, 24, 25, 26, 27, 28});
  auto number = [](const std::string& s) {
    return s == "nan" || s == "-nan" ? std::nan("") : std::stod(s);
  };
  // A rate, or "-" where the scene has none (KITTI has no non-occluded mask here).
  auto percent = [](double rate) {
    if (std::isnan(rate)) return std::string("-");
    char text[32];
    std::snprintf(text, sizeof text, "%.2f%%", 100 * rate);
    return std::string(text);
  };
  // Seconds, or "-" where the row has none (data preparation on one thread not requested).
  auto optional_seconds = [](double value) {
    if (std::isnan(value)) return std::string("-");
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", value);
    return std::string(text);
  };
  // A time of reaching flat's energy, "never" when the run did not (NaN); its ratio "-" then.
  auto reach = [](const std::string& seconds, double value) {
    return std::isnan(value) ? std::string("never") : seconds;
  };
  std::printf(
      "| scene | flat E | C2F E | flat bad nonocc / all | C2F bad nonocc / all | flat s | C2F s | "
      "C2F reaches flat E (s) | ratio | C2F within 1e-4 of flat E (s) | ratio | deadline error "
      "flat / C2F | reduction | SGBM bad nonocc / all | SGBM s | labels | data prep s (threads) "
      "| data prep s (1 thread) | peak MiB prep / flat / C2F |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::vector<double>> columns(std::size(kColumns));
  for (const auto& r : rows) {
    for (std::size_t c = 1; c < 18; ++c) columns[c].push_back(number(r[c]));
    for (const std::size_t c : {21, 23, 24, 25, 26, 27, 28}) columns[c].push_back(number(r[c]));
    // A run that never reaches flat's final energy is a loss: infinite time, not a missing value.
    for (const auto& [time, ratio] : {std::pair{10, 11}, std::pair{23, 24}}) {
      if (std::isnan(number(r[time]))) {
        columns[time].back() = std::numeric_limits<double>::infinity();
        columns[ratio].back() = std::numeric_limits<double>::infinity();
      }
    }
    const double exact = number(r[10]), band = number(r[23]);
    std::printf(
        "| %s | %.1f | %.1f | %s / %s | %s / %s | %.1f | %.1f | %s | %s | %s | %s | %.2f%% / "
        "%.2f%% | %.1f%% | %s / %s | %.2f | %s | %.2f (%s) | %s | %.0f / %.0f / %.0f |\n",
        r[0].c_str(), number(r[2]), number(r[3]), percent(number(r[4])).c_str(),
        percent(number(r[6])).c_str(), percent(number(r[5])).c_str(), percent(number(r[7])).c_str(),
        number(r[8]), number(r[9]), reach(r[10], exact).c_str(),
        std::isnan(exact) ? "-" : r[11].c_str(), reach(r[23], band).c_str(),
        std::isnan(band) ? "-" : r[24].c_str(), 100 * number(r[12]), 100 * number(r[13]),
        100 * number(r[14]), percent(number(r[15])).c_str(), percent(number(r[16])).c_str(),
        number(r[17]), r[20].c_str(), number(r[21]), r[22].c_str(),
        optional_seconds(number(r[25])).c_str(), number(r[26]), number(r[27]), number(r[28]));
  }
  std::size_t never = 0, wins = 0, band_never = 0, band_wins = 0;
  for (const auto& r : rows) {
    never += std::isnan(number(r[10]));
    wins += number(r[11]) <= 0.5;
    band_never += std::isnan(number(r[23]));
    band_wins += number(r[24]) <= 0.5;
  }
  std::printf(
      "| **median** | | | %s / %s | %s / %s | %.1f | %.1f | %.1f | %.3f | %.1f | %.3f | %.2f%% / "
      "%.2f%% | %.1f%% | %s / %s | %.2f | | %.2f | %s | %.0f / %.0f / %.0f |\n",
      percent(bench::median(columns[4])).c_str(), percent(bench::median(columns[6])).c_str(),
      percent(bench::median(columns[5])).c_str(), percent(bench::median(columns[7])).c_str(),
      bench::median(columns[8]), bench::median(columns[9]), bench::median(columns[10]),
      bench::median(columns[11]), bench::median(columns[23]), bench::median(columns[24]),
      100 * bench::median(columns[12]), 100 * bench::median(columns[13]),
      100 * bench::median(columns[14]), percent(bench::median(columns[15])).c_str(),
      percent(bench::median(columns[16])).c_str(), bench::median(columns[17]),
      bench::median(columns[21]), optional_seconds(bench::median(columns[25])).c_str(),
      bench::median(columns[26]), bench::median(columns[27]), bench::median(columns[28]));
  std::printf(
      "\n%zu scenes; C2F never reached flat's final energy on %zu and came within 1e-4 of it "
      "never on %zu (counted as infinite time in the medians); reached it in at most half of "
      "flat's time on %zu, within 1e-4 on %zu.\n",
      rows.size(), never, band_never, wins, band_wins);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string data = "../shared/data", out = "out/bench-stereo", label_order = "sequential",
                maxflow = "dynamic", near_levels;
    Settings settings;
    bool header = false;
    double memory_gib = 0.0;  // 0: default_memory_budget()
    c2f::examples::ToolOptions options(
        "c2f-bench-stereo: flat TSGO, C2F-TSGO and StereoSGBM on one Middlebury scene, one row "
        "each.\n\nUsage: c2f-bench-stereo run SCENE [options]\n"
        "       c2f-bench-stereo summarize ROWS.tsv\n\nOptions");
    options.path("data", &data, "data root (scenes.csv)")
        .path("out", &out, "folder for traces and disparity maps")
        .real("time-limit", &settings.time_limit, {0.0, 1e7, true}, "seconds per run")
        .text("schedule", &settings.schedule, "C2F schedule (as c2f-stereo --schedule)")
        .text("label-order", &label_order, "sequential, random or frequency")
        .real("coarse-tolerance", &settings.coarse_tolerance, {0.0, 1.0, false, true},
              "plateau tolerance on coarse levels")
        .flag("c2f-progress-rate", &settings.c2f_progress_rate,
              "leave a coarse level also by the progress-rate rule (as c2f-stereo --plateau rate)")
        .text("maxflow", &maxflow, "dynamic, boost or kolmogorov")
        .integer("downscale", &settings.downscale, {1, 16}, "shrink the views by this factor")
        .integer("labels", &settings.labels, {0, 256},
                 "disparity labels (0: the scene's range, Middlebury 2014 ndisp or 128 for KITTI, "
                 "else 85)")
        .integer("threads", &settings.threads, {0, 1024},
                 "threads preparing the data (0: the machine's cores; the energy is the same)")
        .integer("flat-near-radius", &settings.flat_near_radius, {0, 1000000},
                 "near moves of this radius in the flat run (0: whole moves only)")
        .integer("c2f-near-radius", &settings.c2f_near_radius, {0, 1000000},
                 "near moves of this radius in the coarse-to-fine run (0: whole moves only)")
        .flag("flat-shift-moves", &settings.flat_shift_moves,
              "shift moves (every variable one label up, then down) in the flat run's sweeps")
        .flag("c2f-shift-moves", &settings.c2f_shift_moves,
              "shift moves in the coarse-to-fine run's sweeps")
        .text("near-levels", &near_levels,
              "where the coarse-to-fine run makes near and shift moves: original (the default: "
              "the original problem only; coarse levels make whole moves) or all")
        .flag("prep-one-thread", &settings.prep_one_thread,
              "prepare the data on one thread first too: its time in the row, and the run stops "
              "when the energy differs from the one prepared on --threads")
        .integer("prep-repeats", &settings.prep_repeats, {1, 100},
                 "time the data preparation this many times (on each thread count, alternating "
                 "with --prep-one-thread); the row holds the medians")
        .real("memory", &memory_gib, {0.0, 1e6, false},
              "each run's memory budget in GiB, as c2f-stereo --memory (0, the default: a "
              "quarter of this machine's memory, growing to a run's needs up to half)")
        .flag("header", &header, "print the TSV header first");
    const auto arguments = options.parse(argc, argv, {"run SCENE | summarize ROWS.tsv", 2});
    if (!arguments) return 0;
    const bench::BenchCommand command = bench::bench_command(*arguments, "SCENE");
    if (command.summarize) return summarize(command.rows);
    settings.label_order = c2f::examples::with_flag(
        "--label-order", [&] { return visit_order_from_string(label_order); });
    settings.maxflow =
        c2f::examples::with_flag("--maxflow", [&] { return maxflow_kind_from_string(maxflow); });
    if (!near_levels.empty()) {
      settings.near_levels = c2f::examples::with_flag(
          "--near-levels", [&] { return near_levels_from_string(near_levels); });
      if (settings.c2f_near_radius == 0 && !settings.c2f_shift_moves) {
        throw std::invalid_argument(
            "--near-levels: has no effect without --c2f-near-radius or --c2f-shift-moves");
      }
    }
    if (memory_gib > 0.0)
      settings.memory =
          memory_budget_of_gib(memory_gib, "--memory " + c2f::format_real(memory_gib));
    if (settings.labels == 1) throw std::invalid_argument("--labels: expected 0 or 2-256, got 1");
    // A bad schedule fails before the first solve.
    c2f::examples::with_flag("--schedule",
                             [&] { return parse_stereo_schedule(settings.schedule); });
    return run_scene(command.names[0], data, out, settings, header);
  } catch (const std::exception& error) {
    std::cerr << "c2f-bench-stereo: error: " << error.what() << "\n";
    return 2;
  }
}
