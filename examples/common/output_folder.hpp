#pragma once
// A run's output files land together or not at all: everything is written into a staging folder
// inside the output folder and moved into place only when the run has finished writing.

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace c2f::examples {

/// The output folder of one run. Writers write into staging() (a fresh hidden folder inside
/// the output folder, so that moving files out of it is a rename on the same file system);
/// commit() then moves every staged file into the output folder, replacing files of the same
/// name, and removes the files of earlier runs that this run owns but did not write (names
/// matching `owned`, where a trailing '*' matches any rest: "partition-level*.png"). Files
/// that are not owned are never touched. Without commit() (an exception, a crash) the output
/// folder keeps what it held before; the destructor removes the staging folder, and the output
/// folder too when this run created it and it is empty.
/// Whether the file name `name` matches `pattern`, where one '*' matches any run of characters
/// ("partition-level*.png" matches "partition-level3.png").
bool name_matches(const std::string& pattern, const std::string& name);

class OutputFolder {
 public:
  /// Creates the output folder if needed and a staging folder inside it (removing staging
  /// folders that killed runs left behind). Throws std::runtime_error naming the folder when
  /// either cannot be created.
  OutputFolder(const std::filesystem::path& folder, std::vector<std::string> owned);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  [[nodiscard]] const std::filesystem::path& folder() const noexcept { return folder_; }
  [[nodiscard]] const std::filesystem::path& staging() const noexcept { return staging_; }

  /// Where to write `target`: staging() / its name when it lies in the output folder; target
  /// itself when it is an existing device or pipe (/dev/stdout); else a partial file beside it
  /// ("NAME.c2f-partial"), which commit() renames to target.
  std::filesystem::path stage(const std::filesystem::path& target);

  /// Moves the staged files into place and removes stale owned files; returns the names
  /// moved into the output folder. Throws std::runtime_error naming the file when a move
  /// fails.
  std::vector<std::string> commit();

  /// Whether `name` matches one of the owned patterns.
  [[nodiscard]] bool owns(const std::string& name) const;

 private:
  std::filesystem::path folder_;
  std::filesystem::path staging_;
  std::vector<std::string> owned_;
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>>
      elsewhere_;  // partial, target
  bool committed_ = false;
  bool created_ = false;  ///< the folder did not exist before this run
};

}  // namespace c2f::examples
