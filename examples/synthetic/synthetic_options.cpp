#include "synthetic_options.hpp"

#include <sstream>
#include <stdexcept>

#include "c2f/core/number_text.hpp"
#include "command_line.hpp"

namespace po = boost::program_options;

namespace c2f::examples {

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

}  // namespace

std::optional<SyntheticCommand> parse_synthetic_command(int argc, char** argv) {
  SyntheticCommand command;
  vision::SyntheticSpec& spec = command.spec;
  std::string blocks = "16,8,4,2";
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
      "time-limit", po::value(&command.options.time_limit_seconds)->default_value(0.0),
      "seconds per run (0: none)")("out,o", po::value(&command.out_dir),
                                   "directory for trace-flat.csv, trace-c2f.csv and PGM images");
  const auto positional = parse_command_line(argc, argv, description);
  if (!positional) return std::nullopt;
  if (!positional->empty()) {
    throw std::invalid_argument("unexpected argument '" + positional->front() +
                                "' (c2f-synthetic takes options only; see --help)");
  }
  command.options.plateau_steps = {plateau};
  if (const std::string problem = command.options.validate(); !problem.empty())
    throw std::invalid_argument("--plateau/--time-limit: " + problem);
  command.block_sizes = parse_block_sizes(blocks);
  return command;
}

}  // namespace c2f::examples
