#include "synthetic_options.hpp"

#include <limits>
#include <sstream>
#include <stdexcept>

#include "c2f/support/number_text.hpp"
#include "tool_options.hpp"

namespace c2f::examples {

namespace {

/// The longest side a synthetic problem may have (its memory is checked when it is made).
constexpr long long kMaxSide = 1 << 16;

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
  double memory_gib = 0.0;  // 0: default_memory_budget()
  ToolOptions options(
      "c2f-synthetic: restores a noisy piecewise-constant label image with ICM, flat and coarse\n"
      "to fine over nested pixel blocks, and prints both traces (time_s,level,step,energy,\n"
      "num_vars,error; error = fraction of wrong pixels).\n\nOptions");
  options.integer("width", &spec.shape.width, {2, kMaxSide}, "image width")
      .integer("height", &spec.shape.height, {2, kMaxSide}, "image height")
      .integer("labels", &spec.num_labels, {2, 1 << 16}, "number of labels")
      .integer("shapes", &spec.num_shapes, {0, 1 << 20}, "rectangles and discs in the image")
      .real("noise", &spec.noise_sigma, {0.0, 1e6}, "noise sigma, in labels")
      .real("smoothness", &spec.smoothness, {0.0, 1e6}, "weight of the truncated-linear term")
      .integer("seed", &spec.seed, {0, std::numeric_limits<long long>::max()},
               "random seed of the problem")
      .text("blocks", &blocks,
            "block sizes of the coarse levels, coarsest first; each divides "
            "the previous")
      .integer("plateau", &plateau, {1, kMaxSteps},
               "refine after this many sweeps without decrease")
      .real("time-limit", &command.options.time_limit_seconds, kTimeLimitRange,
            "seconds per run (0: none)")
      .real("memory", &memory_gib, {0.0, 65536.0},
            "GiB the run may take (0: a quarter of this machine's memory, growing to the "
            "run's needs up to half, at most what is available); a problem that does not fit is "
            "refused before it is made")
      .path("out,o", &command.out_dir,
            "directory for trace-flat.csv, trace-c2f.csv and PGM images");
  if (!options.parse(argc, argv, {"", 0})) return std::nullopt;
  command.memory = memory_gib == 0.0
                       ? default_memory_budget()
                       : memory_budget_of_gib(memory_gib, "--memory " + format_real(memory_gib));
  command.options.plateau_steps = {plateau};
  if (const std::string problem = command.options.validate(); !problem.empty())
    throw std::invalid_argument("--plateau/--time-limit: " + problem);
  command.block_sizes = parse_block_sizes(blocks);
  return command;
}

}  // namespace c2f::examples
