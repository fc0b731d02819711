#include "command_line.hpp"

#include <filesystem>
#include <iostream>

namespace po = boost::program_options;

namespace c2f::examples {

void require_file(const std::string& path, const char* flag) {
  if (!path.empty() && !std::filesystem::is_regular_file(path)) {
    throw std::invalid_argument(std::string(flag) + ": file '" + path + "' does not exist");
  }
}

std::optional<std::vector<std::string>> parse_command_line(int argc, char** argv,
                                                           const po::options_description& visible) {
  po::options_description hidden;
  hidden.add_options()("positional", po::value<std::vector<std::string>>(), "");
  po::options_description all;
  all.add(visible).add(hidden);
  po::positional_options_description positional;
  positional.add("positional", -1);
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), vm);
    po::notify(vm);
  } catch (const po::error& error) {
    throw std::invalid_argument(error.what());
  }
  if (vm.count("help")) {
    std::cout << visible << "\n";
    return std::nullopt;
  }
  return vm.count("positional") ? vm["positional"].as<std::vector<std::string>>()
                                : std::vector<std::string>{};
}

}  // namespace c2f::examples
