// Fuzz target: the command lines of c2f-stereo, c2f-segment and c2f-synthetic. The input is
// argv (arguments separated by NUL bytes; the first byte picks the tool); any command line is
// refused with std::invalid_argument or parses to values within their documented ranges.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "segment_options.hpp"
#include "stereo_options.hpp"
#include "synthetic_options.hpp"

namespace {

/// --help prints to std::cout; the fuzzer's output stays readable without it.
struct SilentCout {
  std::ostringstream sink;
  std::streambuf* saved = std::cout.rdbuf(sink.rdbuf());
  ~SilentCout() { std::cout.rdbuf(saved); }
};

void require(bool condition, const char* what) {
  if (!condition) throw std::logic_error(what);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const int tool = data[0] % 3;
  std::vector<std::string> arguments{"tool"};
  std::string current;
  for (std::size_t i = 1; i < size; ++i) {
    if (data[i] == 0) {
      arguments.push_back(current);
      current.clear();
    } else {
      current.push_back(static_cast<char>(data[i]));
    }
  }
  arguments.push_back(current);
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  const int argc = static_cast<int>(arguments.size());
  const SilentCout silent;
  try {
    if (tool == 0) {
      if (const auto command = c2f::examples::parse_stereo_command(argc, argv.data())) {
        require(command->tsgo.labels >= 2 && command->tsgo.labels <= 256, "stereo labels");
        require(command->run.validate().empty(), "run configuration");
        require(command->run.memory.has_value(), "memory budget");
        require(command->downscale >= 1, "downscale");
      }
    } else if (tool == 1) {
      if (const auto command = c2f::examples::parse_segment_command(argc, argv.data())) {
        const int classes = command->preparation.num_classes;
        require(classes >= 1 && classes <= 256, "classes");
        require(command->parameters.validate().empty(), "coop parameters");
        require(command->run.validate().empty(), "run configuration");
      }
    } else if (const auto command = c2f::examples::parse_synthetic_command(argc, argv.data())) {
      require(command->spec.shape.width >= 2 && command->spec.shape.height >= 2, "size");
      require(!command->block_sizes.empty(), "blocks");
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
