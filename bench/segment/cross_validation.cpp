// c2f-bench-crossval: segmentation parameters chosen with the ground truth, never on the image
// they are reported on.
//
//   c2f-bench-crossval run [--data DIR] [--method potts|mm|greedy|ceres] [--start zero|current]
//                          [--schedule TEXT] [--plateau auto|sweep] [--lambdas LIST]
//                          [--thetas LIST] [--alphas LIST] [--models L/T/A,...]
//                          [--aside LIST] [--kmeans V]
//                          [--threads N]
//       Segments every labelled image of both coopCuts sets (the multi-label images with seeds,
//       the binary images) under every model of the grid (lambda x theta x alpha; Potts uses
//       lambda only) and prints one tab-separated row per (model, image): its pixel error and
//       energy. Runs go on all cores (--threads): they are scored by error, not timed.
//   c2f-bench-crossval summarize ROWS.tsv [ROWS.tsv ...]
//       For each method in the rows: leave-one-out over the tuning images (every image not
//       marked aside: the model is chosen on the other tuning images and scored on the one left
//       out), and the model chosen on all tuning images scored on the aside images. A model's
//       score on a set of images is the mean of the two sets' mean errors (so three multi-label
//       images weigh as much as a dozen binary ones). Then one table of every method's
//       out-of-sample error per image.
//
// The aside images are fixed before anything is tuned (bench/segment/run-crossval names them)
// and are never used to choose anything.

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "c2f/c2f.hpp"
#include "c2f/support/input_file.hpp"
#include "c2f/support/parallel_for.hpp"
#include "coop_flags.hpp"
#include "support/coopcuts_files.hpp"
#include "support/model_grid.hpp"
#include "support/number_list.hpp"
#include "tool_options.hpp"

using namespace c2f;
using namespace c2f::vision;

namespace {

struct RunCommand {
  std::string data = "../shared/data";
  std::string method = "mm";
  std::string start = "current";
  std::string schedule = "superpixels";
  std::string plateau = "auto";
  std::string lambdas = "0.5,1,1.5,2";
  std::string thetas = "0.0007,0.002,0.005,0.01";
  std::string alphas = "0,0.2";
  std::string models;  ///< explicit "lambda/theta/alpha,..." instead of the product grid
  std::string aside;
  examples::PreparationFlags preparation;
  int threads = 0;
};

/// One image's data: everything but the model's parameters.
struct ImageData {
  std::string set;
  std::string name;
  bool aside = false;
  SegmentationScene scene;
  std::vector<double> unaries;
  SegmentationEdges edges;
};

struct Outcome {
  double error = 0.0;
  double energy = 0.0;
};

/// Segments `image` under `parameters` as c2f-segment does (run_segmentation, within the
/// machine's default memory budget) with the command's method, schedule and plateau (the
/// original problem ends after a whole sweep without decrease).
Outcome segment(const RunCommand& command, const ImageData& image,
                const CoopParameters& parameters) {
  const int L = image.scene.num_labels();
  CoopEnergy coop = coop_energy(image.unaries, L, image.edges, parameters);
  PairwiseEnergy potts = potts_energy(coop);
  const SegmentationProblem problem{std::move(coop), std::move(potts)};
  ScheduleProvider levels =
      segmentation_levels(parse_segmentation_schedule(command.schedule, L), image.scene);
  SegmentationRunConfig config;
  if (command.method == "potts") {
    config.method = SegmentationMethod::potts;
  } else {
    config.coop.strategy = aux_strategy_from_string(command.method);
    config.coop.start = expansion_start_from_string(command.start);
    config.plateau = command.plateau == "sweep" ? -1 : 0;
  }
  const Summary summary = run_segmentation(problem, levels, config).summary;
  return {pixel_error(summary.labeling, image.scene.truth), summary.energy};
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, separator);) items.push_back(item);
  return items;
}

int run(const RunCommand& command) {
  if (command.method != "potts")
    examples::with_flag("--method", [&] { return aux_strategy_from_string(command.method); });
  examples::with_flag("--start", [&] { return expansion_start_from_string(command.start); });
  examples::with_flag("--schedule",
                      [&] { return parse_segmentation_schedule(command.schedule, 2); });
  if (command.plateau != "auto" && command.plateau != "sweep")
    throw std::invalid_argument("--plateau: expected auto or sweep, got '" + command.plateau + "'");
  // The images are prepared in parallel (--threads); each preparation on one thread.
  examples::PreparationFlags flags = command.preparation;
  flags.threads = 1;
  const DataPreparation preparation = flags.resolved();
  const auto lambdas = bench::number_list("--lambdas", command.lambdas, examples::kLambdaRange);
  const bool potts = command.method == "potts";
  // Potts reads lambda only; its rows carry the example's theta and alpha.
  const auto thetas = potts ? std::vector<double>{coopcuts_example_parameters().theta}
                            : bench::number_list("--thetas", command.thetas, examples::kThetaRange);
  const auto alphas = potts ? std::vector<double>{coopcuts_example_parameters().alpha}
                            : bench::number_list("--alphas", command.alphas, examples::kAlphaRange);
  const std::vector<std::string> aside = split(command.aside, ',');

  std::vector<ImageData> images;
  for (const std::string set : {"multilabel", "binary"}) {
    for (const std::string& name : bench::labelled_images(command.data, set)) {
      const bool is_aside = std::find(aside.begin(), aside.end(), name) != aside.end();
      images.push_back({set, name, is_aside, {}, {}, {}});
    }
  }
  for (const std::string& name : aside) {
    if (std::none_of(images.begin(), images.end(),
                     [&](const ImageData& i) { return i.name == name; }))
      throw std::invalid_argument("--aside: no labelled image named '" + name + "'");
  }
  std::fprintf(stderr, "c2f-bench-crossval: preparing %zu images\n", images.size());
  c2f::parallel_for(
      images.size(),
      [&](std::size_t i) {
        ImageData& image = images[i];
        image.scene =
            load_segmentation_scene(bench::coopcuts_files(command.data, image.set, image.name));
        image.unaries = segmentation_unaries(image.scene, preparation.gmm_kmeans);
        image.edges =
            segmentation_edges(image.scene.image, preparation.num_classes, preparation.edge_kmeans);
      },
      command.threads);

  std::vector<CoopParameters> models = bench::model_grid(lambdas, thetas, alphas);
  if (!command.models.empty()) {
    models.clear();
    for (const std::string& model : split(command.models, ',')) {
      const std::vector<std::string> parts = split(model, '/');
      if (parts.size() != 3)
        throw std::invalid_argument("--models: expected lambda/theta/alpha, got '" + model + "'");
      models.push_back({examples::parse_real_option("--models", parts[0], examples::kLambdaRange),
                        examples::parse_real_option("--models", parts[1], examples::kThetaRange),
                        examples::parse_real_option("--models", parts[2], examples::kAlphaRange)});
    }
  }
  std::vector<Outcome> outcomes(models.size() * images.size());
  std::atomic<std::size_t> done{0};
  c2f::parallel_for(
      outcomes.size(),
      [&](std::size_t task) {
        outcomes[task] =
            segment(command, images[task % images.size()], models[task / images.size()]);
        const std::size_t finished = ++done;
        if (finished % images.size() == 0 || finished == outcomes.size())
          std::fprintf(stderr, "c2f-bench-crossval: %zu of %zu runs\n", finished, outcomes.size());
      },
      command.threads);

  const std::string kmeans = command.preparation.kmeans;
  std::string method = command.method;
  if (method == "greedy") method += "-" + command.start;
  if (!potts && command.plateau == "sweep") method += "-sweeps";
  std::printf("method\tschedule\tkmeans\tlambda\ttheta\talpha\tset\timage\taside\terror\tenergy\n");
  for (std::size_t task = 0; task < outcomes.size(); ++task) {
    const CoopParameters& p = models[task / images.size()];
    const ImageData& image = images[task % images.size()];
    std::printf("%s\t%s\t%s\t%.17g\t%.17g\t%.17g\t%s\t%s\t%d\t%.9f\t%.9f\n", method.c_str(),
                command.schedule.c_str(), kmeans.c_str(), p.lambda, p.theta, p.alpha,
                image.set.c_str(), image.name.c_str(), image.aside ? 1 : 0, outcomes[task].error,
                outcomes[task].energy);
  }
  return 0;
}

// ---- summarize ----

struct Row {
  std::string key;  ///< method, schedule and k-means: one cross-validation
  std::string model;
  std::string set, image;
  bool aside = false;
  double error = 0.0;
};

struct Study {
  std::vector<std::string> models;                             ///< in row order
  std::map<std::string, std::map<std::string, double>> error;  ///< model -> image -> error
  std::map<std::string, std::string> set_of;                   ///< image -> set
  std::map<std::string, bool> aside;                           ///< image -> aside
};

std::vector<Row> read_rows(const std::string& path) {
  std::istringstream file(read_input_file(path, "rows file", kMaxTextInputBytes));
  std::vector<Row> rows;
  std::string line;
  std::getline(file, line);
  if (line.rfind("method\tschedule\tkmeans\t", 0) != 0)
    throw std::invalid_argument("'" + path + "' is not a c2f-bench-crossval rows file");
  for (int number = 2; std::getline(file, line); ++number) {
    const std::vector<std::string> cells = split(line, '\t');
    if (cells.size() != 11)
      throw std::invalid_argument("'" + path + "' line " + std::to_string(number) +
                                  ": expected 11 cells");
    const auto number_in = [&](const std::string& text) {
      return examples::parse_real_option("'" + path + "' line " + std::to_string(number), text,
                                         {-1e300, 1e300});
    };
    char model[128];
    std::snprintf(model, sizeof model, "%g / %g / %g", number_in(cells[3]), number_in(cells[4]),
                  number_in(cells[5]));
    rows.push_back({cells[0] + " (" + cells[1] + ", k-means " + cells[2] + ")",
                    cells[0] == "potts" ? "lambda " + cells[3] : model, cells[6], cells[7],
                    cells[8] == "1", number_in(cells[9])});
  }
  return rows;
}

/// The mean over the sets present of each set's mean error over `images`.
double score(const Study& study, const std::string& model, const std::vector<std::string>& images) {
  std::map<std::string, std::pair<double, int>> per_set;
  for (const std::string& image : images) {
    auto& [sum, count] = per_set[study.set_of.at(image)];
    sum += study.error.at(model).at(image);
    ++count;
  }
  double total = 0.0;
  for (const auto& [set, sum_count] : per_set) total += sum_count.first / sum_count.second;
  return per_set.empty() ? 0.0 : total / static_cast<double>(per_set.size());
}

/// The model with the lowest score on `images` (the first in row order on a tie).
std::string choose(const Study& study, const std::vector<std::string>& images) {
  std::string best;
  double best_score = std::numeric_limits<double>::infinity();
  for (const std::string& model : study.models) {
    const double s = score(study, model, images);
    if (s < best_score) {
      best_score = s;
      best = model;
    }
  }
  return best;
}

struct OutOfSample {
  std::map<std::string, double> error;       ///< image -> out-of-sample error
  std::map<std::string, std::string> model;  ///< image -> the model it was scored under
  std::string final_model;                   ///< chosen on all tuning images
};

OutOfSample cross_validate(const Study& study) {
  std::vector<std::string> tuning;
  for (const auto& [image, aside] : study.aside) {
    if (!aside) tuning.push_back(image);
  }
  OutOfSample result;
  result.final_model = choose(study, tuning);
  for (const auto& [image, aside] : study.aside) {
    std::string model = result.final_model;
    if (!aside) {
      std::vector<std::string> others;
      for (const std::string& other : tuning) {
        if (other != image) others.push_back(other);
      }
      model = choose(study, others);
    }
    result.model[image] = model;
    result.error[image] = study.error.at(model).at(image);
  }
  return result;
}

/// "Potts" rows' key starts with "potts"; the example's model is the coopCuts example's.
bool is_example(const std::string& model) {
  return model == "1.5 / 0.005 / 0" || model == "lambda 1.5";
}

int summarize(const std::vector<std::string>& paths) {
  std::map<std::string, Study> studies;
  std::vector<std::string> keys;
  for (const std::string& path : paths) {
    for (const Row& row : read_rows(path)) {
      if (!studies.count(row.key)) keys.push_back(row.key);
      Study& study = studies[row.key];
      if (!study.error.count(row.model)) study.models.push_back(row.model);
      study.error[row.model][row.image] = row.error;
      study.set_of[row.image] = row.set;
      study.aside[row.image] = row.aside;
    }
  }
  if (keys.empty()) {
    std::string names;
    for (const std::string& path : paths) names += (names.empty() ? "'" : ", '") + path + "'";
    throw std::invalid_argument(names + (paths.size() == 1 ? " holds" : " hold") +
                                " no rows to summarize (expected the rows a run printed)");
  }
  std::map<std::string, OutOfSample> results;
  for (const std::string& key : keys) {
    const Study& study = studies.at(key);
    for (const std::string& model : study.models) {
      if (study.error.at(model).size() != study.set_of.size())
        throw std::invalid_argument(key + ": model " + model + " lacks some images' rows");
    }
    const OutOfSample& result = results[key] = cross_validate(study);
    std::printf("### %s: %zu models\n\nChosen on all tuning images: %s\n\n", key.c_str(),
                study.models.size(), result.final_model.c_str());
    std::printf(
        "| image | set | aside | model (chosen without this image) | out-of-sample error | "
        "example's model | best model in hindsight |\n|---|---|---|---|---|---|---|\n");
    for (const auto& [image, error] : result.error) {
      double hindsight = std::numeric_limits<double>::infinity();
      std::string example = "-";
      for (const std::string& model : study.models) {
        hindsight = std::min(hindsight, study.error.at(model).at(image));
        if (is_example(model)) {
          char cell[32];
          std::snprintf(cell, sizeof cell, "%.2f%%", 100 * study.error.at(model).at(image));
          example = cell;
        }
      }
      std::printf("| %s | %s | %s | %s | %.2f%% | %s | %.2f%% |\n", image.c_str(),
                  study.set_of.at(image).c_str(), study.aside.at(image) ? "yes" : "",
                  result.model.at(image).c_str(), 100 * error, example.c_str(), 100 * hindsight);
    }
    std::printf("\n");
  }

  std::printf("### Out-of-sample pixel errors, every method\n\n| image | set | aside |");
  for (const std::string& key : keys) std::printf(" %s |", key.c_str());
  std::printf("\n|---|---|---|");
  for (std::size_t k = 0; k < keys.size(); ++k) std::printf("---|");
  std::printf("\n");
  const Study& first = studies.at(keys.front());
  for (const auto& [image, set] : first.set_of) {
    std::printf("| %s | %s | %s |", image.c_str(), set.c_str(), first.aside.at(image) ? "yes" : "");
    for (const std::string& key : keys) {
      const auto& errors = results.at(key).error;
      const auto found = errors.find(image);
      if (found == errors.end()) {
        std::printf(" - |");
      } else {
        std::printf(" %.2f%% |", 100 * found->second);
      }
    }
    std::printf("\n");
  }
  for (const bool aside : {false, true}) {
    for (const std::string set : {"multilabel", "binary"}) {
      std::printf("| mean, %s %s | | |", aside ? "aside" : "tuning (leave one out)", set.c_str());
      for (const std::string& key : keys) {
        double sum = 0.0;
        int count = 0;
        for (const auto& [image, error] : results.at(key).error) {
          const Study& study = studies.at(key);
          if (study.aside.at(image) != aside || study.set_of.at(image) != set) continue;
          sum += error;
          ++count;
        }
        if (count == 0) {
          std::printf(" - |");
        } else {
          std::printf(" %.2f%% |", 100 * sum / count);
        }
      }
      std::printf("\n");
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return examples::run_tool("c2f-bench-crossval", [&] {
    RunCommand command;
    examples::ToolOptions options(
        "c2f-bench-crossval: segmentation parameters chosen on labelled images and scored on "
        "images they were not chosen on (leave one out, and a set kept aside).\n\n"
        "Usage: c2f-bench-crossval run [options] > ROWS.tsv\n"
        "       c2f-bench-crossval summarize ROWS.tsv [ROWS.tsv ...]\n\nOptions");
    options.path("data", &command.data, "data root (coopcuts/)")
        .text("method", &command.method, "potts, or the auxiliary strategy: greedy, mm or ceres")
        .text("start", &command.start, "greedy's expansion start: zero or current")
        .text("schedule", &command.schedule, "segmentation schedule (as c2f-segment's)")
        .text("plateau", &command.plateau,
              "coarse levels left after auto (L steps or one sweep) or sweep (a whole sweep) "
              "without decrease")
        .text("lambdas", &command.lambdas, "weights of the pairwise part, comma-separated")
        .text("thetas", &command.thetas, "breakpoints of F, comma-separated (not for potts)")
        .text("alphas", &command.alphas, "slopes of F after the breakpoint (not for potts)")
        .text("models", &command.models,
              "an explicit list of models, lambda/theta/alpha comma-separated, instead of the "
              "product of the three lists")
        .text("aside", &command.aside, "images kept aside, comma-separated names")
        .integer("threads", &command.threads, {0, 1024}, "threads (0: all cores)");
    examples::declare_data_preparation(options, command.preparation);
    const auto arguments = options.parse(argc, argv, {"run | summarize ROWS.tsv...", 64});
    if (!arguments) return 0;
    if (arguments->size() == 1 && arguments->front() == "run") return run(command);
    if (arguments->size() >= 2 && arguments->front() == "summarize")
      return summarize({arguments->begin() + 1, arguments->end()});
    throw std::invalid_argument("expected 'run' or 'summarize ROWS.tsv...' (see --help)");
  });
}
