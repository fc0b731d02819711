#pragma once
// What the tools' output folders leave around them, for the tests of OutputFolder and of the
// tools' commits.

#include <cstddef>
#include <filesystem>
#include <string>

namespace c2f::test {

/// The entries beside `folder` that runs on it leave while they work (".NAME.c2f-staging-...",
/// ".NAME.c2f-retired-..."); 0 once every run has ended and cleaned up.
inline std::size_t run_leftovers(const std::filesystem::path& folder) {
  std::size_t count = 0;
  const std::string prefix = "." + folder.filename().string() + ".c2f-";
  for (const auto& entry : std::filesystem::directory_iterator(folder.parent_path()))
    count += entry.path().filename().string().rfind(prefix, 0) == 0;
  return count;
}

}  // namespace c2f::test
