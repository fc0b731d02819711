// c2f-synthetic: solves a synthetic labeling problem (piecewise-constant image under noise)
// flat and coarse to fine with the same solver and clock, and prints both traces.

#include <boost/program_options.hpp>

#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "c2f/c2f.hpp"
#include "synthetic_problem.hpp"

namespace po = boost::program_options;
using namespace c2f;

namespace {

std::vector<std::size_t> parse_block_sizes(const std::string& text) {
  std::vector<std::size_t> sizes;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    const std::optional<long long> value = parse_integer(item);
    if (!value || *value < 1)
      throw std::invalid_argument("--blocks: '" + item + "' is not a block size >= 1");
    sizes.push_back(static_cast<std::size_t>(*value));
  }
  if (sizes.empty()) throw std::invalid_argument("--blocks: empty list");
  return sizes;
}

template <class Provider>
Summary run(const char* name, const examples::SyntheticProblem& problem, Provider& levels,
            const Options& options, const std::string& trace_path) {
  std::ostringstream trace;
  TraceWriter writer(trace, [&](std::span<const Label> ground) {
    return examples::label_error(ground, problem.truth);
  });
  IcmSolver solver;
  Summary summary = coarse_to_fine(problem.energy, levels, solver, options, std::ref(writer));
  std::cout << "# trace: " << name << "\n"
            << trace.str() << "# summary: " << name << "\n"
            << summary.report() << "\n";
  if (!trace_path.empty()) {
    std::ofstream file = open_trace_file(trace_path);
    file << trace.str();
  }
  return summary;
}

}  // namespace

int main(int argc, char** argv) {
  examples::SyntheticSpec spec;
  std::string blocks = "16,8,4,2";
  std::string out_dir;
  Options options;
  options.plateau_steps = {2};
  int plateau = 2;
  po::options_description description(
      "c2f-synthetic: restores a noisy piecewise-constant label image with ICM, flat and coarse\n"
      "to fine over nested pixel blocks, and prints both traces (time_s,level,step,energy,\n"
      "num_vars,error; error = fraction of wrong pixels).\n\nOptions");
  description.add_options()("help,h", "show this help")(
      "width", po::value(&spec.shape.width)->default_value(spec.shape.width), "image width")(
      "height", po::value(&spec.shape.height)->default_value(spec.shape.height), "image height")(
      "labels", po::value(&spec.num_labels)->default_value(spec.num_labels),
      "number of labels (>= 2)")("shapes",
                                 po::value(&spec.num_shapes)->default_value(spec.num_shapes),
                                 "rectangles and discs in the image")(
      "noise", po::value(&spec.noise_sigma)->default_value(spec.noise_sigma),
      "noise sigma, in labels")("smoothness",
                                po::value(&spec.smoothness)->default_value(spec.smoothness),
                                "weight of the truncated-linear term")(
      "seed", po::value(&spec.seed)->default_value(spec.seed), "random seed of the problem")(
      "blocks", po::value(&blocks)->default_value(blocks),
      "block sizes of the coarse levels, coarsest first; each divides the previous")(
      "plateau", po::value(&plateau)->default_value(plateau),
      "refine after this many sweeps without decrease")(
      "time-limit", po::value(&options.time_limit_seconds)->default_value(0.0),
      "seconds per run (0: none)")("out,o", po::value(&out_dir),
                                   "directory for trace-flat.csv, trace-c2f.csv and PGM images");
  try {
    po::variables_map vm;
    po::store(po::parse_command_line(argc, argv, description), vm);
    if (vm.count("help")) {
      std::cout << description << "\n";
      return 0;
    }
    po::notify(vm);
    options.plateau_steps = {plateau};
    if (const std::string problem = options.validate(); !problem.empty()) {
      throw std::invalid_argument("--plateau/--time-limit: " + problem);
    }
    const auto block_sizes = parse_block_sizes(blocks);
    if (!out_dir.empty()) std::filesystem::create_directories(out_dir);
    const auto path = [&](const char* name) {
      return out_dir.empty() ? std::string() : (std::filesystem::path(out_dir) / name).string();
    };

    BlockHierarchy hierarchy(spec.shape, block_sizes);  // validates the sizes before any run
    const examples::SyntheticProblem problem = examples::make_synthetic_problem(spec);
    std::cerr << "c2f-synthetic: " << spec.shape.width << "x" << spec.shape.height << " pixels, "
              << spec.num_labels << " labels, " << problem.energy.edges().size() << " edges\n";

    PartitionList flat;
    const Summary flat_summary = run("flat", problem, flat, options, path("trace-flat.csv"));
    const Summary c2f_summary = run("c2f", problem, hierarchy, options, path("trace-c2f.csv"));

    std::cout << "flat: energy " << flat_summary.energy << ", error "
              << examples::label_error(flat_summary.labeling, problem.truth) << ", "
              << flat_summary.seconds << " s\n"
              << "c2f:  energy " << c2f_summary.energy << ", error "
              << examples::label_error(c2f_summary.labeling, problem.truth) << ", "
              << c2f_summary.seconds << " s\n";
    if (!out_dir.empty()) {
      examples::write_label_pgm(path("truth.pgm"), problem.truth, spec.shape, spec.num_labels);
      examples::write_label_pgm(path("flat.pgm"), flat_summary.labeling, spec.shape,
                                spec.num_labels);
      examples::write_label_pgm(path("c2f.pgm"), c2f_summary.labeling, spec.shape, spec.num_labels);
      std::cerr << "c2f-synthetic: wrote traces and images to " << out_dir << "\n";
    }
  } catch (const std::exception& error) {
    std::cerr << "c2f-synthetic: error: " << error.what() << "\n";
    return 2;
  }
  return 0;
}
