#pragma once
// Which tool owns an output folder, and which run is writing it now: the folder holds a marker
// file naming the tool that created it, and a run holds an exclusive lock (flock) on that marker
// from the moment it claims the folder until it ends (the marker names its process meanwhile).

#include <filesystem>
#include <string>

namespace c2f::examples {

class FolderClaim {
 public:
  /// The marker's name in a claimed folder. It is carried into every new version of the folder
  /// as a hard link, so the lock on it holds across the folder's replacement.
  static constexpr const char* kMarker = ".c2f-owner";

  /// Claims `folder` (a resolved, absolute path) for `tool`, creating it (and its parents) when
  /// absent. Throws std::runtime_error naming the folder when it cannot be created, when it
  /// exists, is not empty and has no marker (the user's own folder), when its marker names
  /// another tool, and when another run holds it (naming that run's process) unless `wait`, in
  /// which case it waits for that run to release it.
  FolderClaim(const std::filesystem::path& folder, const std::string& tool, bool wait = false);
  /// Releases the lock.
  ~FolderClaim();
  FolderClaim(const FolderClaim&) = delete;
  FolderClaim& operator=(const FolderClaim&) = delete;

  /// Whether this claim created the folder.
  [[nodiscard]] bool created() const noexcept { return created_; }
  /// Whether this claim created the marker (the folder was new or empty).
  [[nodiscard]] bool marked() const noexcept { return marked_; }

 private:
  int fd_ = -1;
  std::size_t tool_line_ = 0;  ///< the marker's length without the process line
  bool created_ = false;
  bool marked_ = false;
};

}  // namespace c2f::examples
