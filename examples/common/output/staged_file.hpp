#pragma once
// One output file outside a run's output folder (a --trace or --export-uai elsewhere), replaced
// in one step: written beside its target and renamed over it once complete.

#include <filesystem>

namespace c2f::examples {

class StagedFile {
 public:
  /// Plans the write of `target`. A symbolic link is followed: the file it points to is replaced
  /// and the link stays. A device or a pipe (/dev/stdout, /dev/null, a FIFO some process reads)
  /// cannot be replaced and is written in place. Throws std::invalid_argument naming the target
  /// when it is a folder or a socket, a FIFO that no process reads (opening it would block
  /// until one does), or a symbolic link to nothing.
  explicit StagedFile(const std::filesystem::path& target);
  /// Removes the partial file unless committed.
  ~StagedFile();
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;
  StagedFile(StagedFile&& other) noexcept;
  StagedFile& operator=(StagedFile&&) = delete;

  /// Where to write: "TARGET.c2f-partial-PID" beside the (resolved) target, the target itself
  /// when it is a device, or /proc/self/fd/N for a FIFO (held open, so its reader sees one
  /// writer from here to the StagedFile's end).
  [[nodiscard]] const std::filesystem::path& path() const noexcept { return path_; }
  [[nodiscard]] bool in_place() const noexcept { return path_ == target_ || fifo_ >= 0; }

  /// Renames the partial file over the target. Throws std::runtime_error naming both.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path path_;
  int fifo_ = -1;  ///< a FIFO target, held open for writing
  bool committed_ = false;
};

}  // namespace c2f::examples
