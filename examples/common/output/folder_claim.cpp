#include "folder_claim.hpp"

#include "c2f/support/number_text.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <thread>

namespace c2f::examples {

namespace fs = std::filesystem;

namespace {

/// A marker's text: bounded, since a marker holds a tool's name and a few file names.
std::string read_marker(int fd) {
  std::string text(std::size_t{1} << 20, '\0');
  const ssize_t n = ::pread(fd, text.data(), text.size(), 0);
  text.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  return text;
}

std::string first_line(const std::string& text) {
  return text.substr(0, text.find('\n'));
}

/// Whether `folder` holds nothing but its marker.
bool holds_only_marker(const fs::path& folder) {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error))
    if (entry.path().filename() != FolderClaim::kMarker) return false;
  return true;
}

[[noreturn]] void fail(const fs::path& folder, const std::string& why) {
  throw std::runtime_error("the output folder '" + folder.string() + "' " + why);
}

/// The holder named in a locked marker: "c2f-stereo, process 123".
std::string holder_of(int fd) {
  const std::string text = read_marker(fd);
  const std::size_t at = text.rfind("process ");
  return first_line(text) + (at == std::string::npos ? "" : ", " + first_line(text.substr(at)));
}

}  // namespace

std::string record_text(const FileRecord& record) {
  std::string text = "record\n";
  for (const auto& [name, inodes] : record)
    for (const ino_t inode : inodes) text += "file " + name + " " + std::to_string(inode) + "\n";
  return text;
}

std::optional<FileRecord> parse_record(const std::string& marker_text) {
  std::istringstream lines(marker_text);
  std::string line;
  std::getline(lines, line);  // the tool
  std::optional<FileRecord> record;
  while (std::getline(lines, line)) {
    if (line == "record") record.emplace();
    if (!record || line.rfind("file ", 0) != 0) continue;
    const std::size_t space = line.rfind(' ');
    if (space <= 5) continue;
    const std::string name = line.substr(5, space - 5);
    const std::string number = line.substr(space + 1);
    if (name.empty() || number.empty() ||
        number.find_first_not_of("0123456789") != std::string::npos)
      continue;
    (*record)[name].insert(static_cast<ino_t>(std::stoull(number)));
  }
  return record;
}

FolderClaim::FolderClaim(const fs::path& folder, const std::string& tool,
                         std::optional<std::chrono::milliseconds> wait_limit,
                         const std::function<nlink_t()>& count_links_elsewhere)
    : folder_(folder), tool_(tool) {
  std::error_code error;
  if (!fs::exists(fs::symlink_status(folder, error))) {
    fs::create_directories(folder.parent_path(), error);
    if (!error) created_ = fs::create_directory(folder, error);
    if (error) fail(folder, "cannot be created: " + error.message());
  }
  if (!fs::is_directory(folder, error)) fail(folder, "is not a folder");
  const fs::path marker = folder / kMarker;
  // Locks the marker the folder holds now: a run that replaced the folder while this one waited
  // for the file leaves a new marker behind, which is then locked instead.
  const auto give_up = std::chrono::steady_clock::now() + wait_limit.value_or(kWaitLimit);
  bool said_waiting = false;
  for (int attempt = 0; fd_ < 0; ++attempt) {
    const fs::file_status status = fs::symlink_status(marker, error);
    const bool absent = !fs::exists(status);
    if (!absent && !fs::is_regular_file(status)) {
      fail(folder, "has a " + std::string(kMarker) +
                       " that is not a regular file (no c2f tool made it): it is left as it is; "
                       "give another folder");
    }
    if (absent && !holds_only_marker(folder)) {
      fail(folder, "is not empty and was not written by a c2f tool (it has no " +
                       std::string(kMarker) +
                       "): the tools never write into a folder they do not own; give a new or "
                       "empty folder");
    }
    const int fd = ::open(marker.c_str(),
                          O_RDWR | O_CLOEXEC | O_NOFOLLOW | (absent ? O_CREAT | O_EXCL : 0), 0644);
    if (fd < 0) {
      if (errno == EEXIST || errno == ENOENT) continue;  // made or removed meanwhile: look again
      fail(folder, "cannot hold its marker " + marker.string() + ": " + std::strerror(errno));
    }
    marked_ = absent;
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int why = errno;
      const std::string holder = holder_of(fd);
      ::close(fd);
      if (why != EWOULDBLOCK) fail(folder, std::string("cannot be locked: ") + std::strerror(why));
      if (!wait_limit) {
        fail(folder, "is being written by another run (" + holder +
                         "): wait for it to end, or give this run another folder");
      }
      if (std::chrono::steady_clock::now() > give_up) {
        fail(folder, "is still being written by another run (" + holder + ") after " +
                         format_real(static_cast<double>(wait_limit->count()) / 1000) +
                         " s of waiting: this run gives up");
      }
      if (!said_waiting) {
        std::fprintf(stderr, "%s: waiting for the output folder '%s', being written by %s\n",
                     tool.c_str(), folder.c_str(), holder.c_str());
        said_waiting = true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      attempt = 0;
      continue;
    }
    struct stat held {};
    struct stat current {};
    if (::fstat(fd, &held) == 0 && ::lstat(marker.c_str(), &current) == 0 &&
        held.st_dev == current.st_dev && held.st_ino == current.st_ino) {
      fd_ = fd;
    } else {
      ::close(fd);
      if (attempt == 10) fail(folder, "keeps changing while this run claims it");
    }
  }
  struct stat held {};
  if (::fstat(fd_, &held) != 0) {
    const int why = errno;
    ::close(fd_);
    fail(folder, "cannot have its marker examined: " + std::string(std::strerror(why)));
  }
  const nlink_t links_elsewhere = count_links_elsewhere();
  if (held.st_nlink > 1 + links_elsewhere) {
    ::close(fd_);
    fail(folder, "has a " + std::string(kMarker) + " with " + std::to_string(held.st_nlink) +
                     " hard links, " + std::to_string(held.st_nlink - 1 - links_elsewhere) +
                     " of them outside the runs' folders (a link to a file of yours would be "
                     "overwritten): it is left as it is; give another folder");
  }
  const std::string text = read_marker(fd_);
  if (text.empty() && !holds_only_marker(folder)) {
    ::close(fd_);
    fail(folder, "has an empty " + std::string(kMarker) +
                     ", which no c2f tool wrote, beside other files: it is left as it is; give "
                     "another folder");
  }
  marked_ = marked_ || text.empty();
  const std::string owner = first_line(text);
  if (!text.empty() && owner.rfind("c2f-", 0) != 0) {
    ::close(fd_);
    fail(folder, "has a " + std::string(kMarker) +
                     " that names no c2f tool: it is left as it is; give another folder");
  }
  if (!text.empty() && owner != tool) {
    ::close(fd_);
    fail(folder, "holds the outputs of " + owner + ", not of " + tool + ": give another folder");
  }
  record_ = text.empty() ? std::optional<FileRecord>(FileRecord{}) : parse_record(text);
  try {
    write_marker(true);
  } catch (...) {
    ::close(fd_);
    throw;
  }
}

void FolderClaim::write_marker(bool with_process) {
  std::string text = tool_ + "\n" + (record_ ? record_text(*record_) : std::string());
  if (with_process) text += "process " + std::to_string(::getpid()) + "\n";
  // Written over the old text, then cut to length: never empty, even if the run dies between.
  if (::pwrite(fd_, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size()) ||
      ::ftruncate(fd_, static_cast<off_t>(text.size())) != 0) {
    fail(folder_, "cannot have its marker written: " + std::string(std::strerror(errno)));
  }
}

void FolderClaim::write_record(const FileRecord& record) {
  record_ = record;
  write_marker(true);
}

FolderClaim::~FolderClaim() {
  if (fd_ < 0) return;
  // The process line goes with the claim, so a finished run's marker is the same bytes each time.
  try {
    write_marker(false);
  } catch (const std::exception&) {  // a marker that cannot be written keeps its process line
  }
  ::close(fd_);
}

}  // namespace c2f::examples
