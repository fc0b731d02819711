#include "output_paths.hpp"

#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "output_folder.hpp"

namespace c2f::examples {

namespace fs = std::filesystem;

namespace {

/// The path with symlinks resolved as far as it exists (the rest appended as given).
fs::path resolved(const std::string& path) {
  std::error_code error;
  const fs::path canonical = fs::weakly_canonical(fs::absolute(path), error);
  return error ? fs::absolute(path).lexically_normal() : canonical;
}

bool same_file(const std::string& a, const std::string& b) {
  std::error_code error;
  if (fs::exists(a, error) && fs::exists(b, error)) {
    const bool equivalent = fs::equivalent(a, b, error);
    if (!error) return equivalent;
  }
  return resolved(a) == resolved(b);
}

/// The name of `path` when it lies directly in `folder`, else empty.
std::string name_in(const std::string& path, const std::string& folder) {
  const fs::path target = resolved(path);
  return target.parent_path() == resolved(folder) ? target.filename().string() : std::string();
}

bool owned_by(const OutputPlan& plan, const std::string& name) {
  for (const std::string& pattern : plan.owned)
    if (name_matches(pattern, name)) return true;
  return false;
}

}  // namespace

void check_output_paths(const OutputPlan& plan, const std::vector<NamedPath>& inputs) {
  for (std::size_t i = 0; i < plan.named.size(); ++i) {
    const NamedPath& output = plan.named[i];
    if (output.path.empty()) continue;
    // Devices and pipes (/dev/stdout) are written directly and may be shared.
    std::error_code error;
    const auto status = fs::status(output.path, error);
    // (In out_dir whatever stands at the path is replaced with the folder.)
    const bool in_out_dir = !name_in(output.path, plan.out_dir).empty();
    if (!in_out_dir && (fs::is_directory(status) || fs::is_socket(status))) {
      throw std::invalid_argument(output.what + " '" + output.path + "' is a " +
                                  (fs::is_socket(status) ? "socket" : "folder") +
                                  ", not a file: give a file's path");
    }
    const bool special =
        !error && fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status);
    if (special) continue;
    for (const NamedPath& input : inputs) {
      if (!input.path.empty() && same_file(output.path, input.path)) {
        throw std::invalid_argument(output.what + " '" + output.path + "' is the same file as " +
                                    input.what + " '" + input.path +
                                    "': the output would overwrite an input");
      }
    }
    for (std::size_t j = i + 1; j < plan.named.size(); ++j) {
      const NamedPath& other = plan.named[j];
      if (!other.path.empty() && same_file(output.path, other.path)) {
        throw std::invalid_argument(output.what + " and " + other.what + " name one file '" +
                                    output.path + "': give each output its own");
      }
    }
    const std::string name = name_in(output.path, plan.out_dir);
    const bool own_default = !output.default_name.empty() && name == output.default_name;
    if (!name.empty() && !own_default && owned_by(plan, name)) {
      throw std::invalid_argument(output.what + " '" + output.path + "' is " + name +
                                  ", a file the run writes into '" + plan.out_dir +
                                  "' itself: choose another name");
    }
  }
  for (const NamedPath& input : inputs) {
    if (input.path.empty()) continue;
    const std::string name = name_in(input.path, plan.out_dir);
    if (!name.empty() && owned_by(plan, name)) {
      throw std::invalid_argument(input.what + " '" + input.path + "' is " + name +
                                  ", a file the run writes into '" + plan.out_dir +
                                  "': move it, or choose another -o");
    }
  }
}

}  // namespace c2f::examples
