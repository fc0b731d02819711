#pragma once
// Which tool owns an output folder, which files it wrote there, and which run is writing it now:
// the folder holds a marker file naming the tool that created it and recording the files its
// last run wrote (name and inode), and a run holds an exclusive lock (flock) on that marker from
// the moment it claims the folder until it ends (the marker names its process meanwhile).
//
// Marker text: the tool's name on the first line; "record" and one "file NAME INODE" line per
// file the last run wrote; while a run holds it, "process PID" last.

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace c2f::examples {

/// The files a tool's runs wrote into a folder: name -> the inodes it had (a file replaced by
/// someone else has another inode, and is no longer the tool's).
using FileRecord = std::map<std::string, std::set<ino_t>>;

class FolderClaim {
 public:
  /// The marker's name in a claimed folder. It is carried into every new version of the folder
  /// (and into each run's staging folder) as a hard link, so the lock on it holds across the
  /// folder's replacement, and a staging folder is known as a run's by holding it.
  static constexpr const char* kMarker = ".c2f-owner";

  /// How long a run that shares the folder waits for another run's lock before it gives up.
  static constexpr std::chrono::milliseconds kWaitLimit{600'000};

  /// Claims `folder` (a resolved, absolute path) for `tool`, creating it (and its parents) when
  /// absent. `links_elsewhere` counts, once the lock is held, the hard links to the marker that
  /// runs' staging folders hold (OutputFolder knows them). Throws std::runtime_error naming the
  /// folder when it cannot be created; when it exists, is not empty and has no marker (the user's
  /// own folder); when its marker is not a regular file, has a hard link other than the runs' (a
  /// link to a file of the user's), is empty while the folder holds files, or does not name a c2f
  /// tool; when it names another tool; and when another run holds it (naming that run's process),
  /// unless `wait_limit` is given: then it waits for that run, saying so on stderr once, for
  /// that long at most.
  FolderClaim(const std::filesystem::path& folder, const std::string& tool,
              std::optional<std::chrono::milliseconds> wait_limit,
              const std::function<nlink_t()>& links_elsewhere);
  /// Releases the lock; the marker keeps the tool and the record.
  ~FolderClaim();
  FolderClaim(const FolderClaim&) = delete;
  FolderClaim& operator=(const FolderClaim&) = delete;

  /// Whether this claim created the folder.
  [[nodiscard]] bool created() const noexcept { return created_; }
  /// Whether this claim created the marker (the folder was new or empty).
  [[nodiscard]] bool marked() const noexcept { return marked_; }
  /// The files the tool's runs wrote, as the marker records them; std::nullopt for a marker
  /// written before markers held a record (its owner then tells by name, as it did).
  [[nodiscard]] const std::optional<FileRecord>& record() const noexcept { return record_; }

  /// Replaces the marker's record (the lock is held). Throws std::runtime_error naming the
  /// folder when the marker cannot be written.
  void write_record(const FileRecord& record);

 private:
  void write_marker(bool with_process);

  std::filesystem::path folder_;
  std::string tool_;
  int fd_ = -1;
  std::optional<FileRecord> record_;
  bool created_ = false;
  bool marked_ = false;
};

/// The record's text: "record" then "file NAME INODE" per inode, names in order.
std::string record_text(const FileRecord& record);

/// The record in a marker's text (after its first line); std::nullopt without a "record" line.
/// Lines that are not "file NAME INODE" are ignored.
std::optional<FileRecord> parse_record(const std::string& marker_text);

}  // namespace c2f::examples
