#include "folder_claim.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <system_error>

namespace c2f::examples {

namespace fs = std::filesystem;

namespace {

/// The marker's text: the tool on its first line, the process holding it on the second.
std::string read_marker(int fd) {
  std::string text(256, '\0');
  const ssize_t n = ::pread(fd, text.data(), text.size(), 0);
  text.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  return text;
}

std::string first_line(const std::string& text) {
  return text.substr(0, text.find('\n'));
}

bool is_empty_folder(const fs::path& folder) {
  std::error_code error;
  return fs::directory_iterator(folder, error) == fs::directory_iterator();
}

[[noreturn]] void fail(const fs::path& folder, const std::string& why) {
  throw std::runtime_error("the output folder '" + folder.string() + "' " + why);
}

}  // namespace

FolderClaim::FolderClaim(const fs::path& folder, const std::string& tool, bool wait) {
  std::error_code error;
  if (!fs::exists(fs::symlink_status(folder, error))) {
    fs::create_directories(folder.parent_path(), error);
    if (!error) created_ = fs::create_directory(folder, error);
    if (error) fail(folder, "cannot be created: " + error.message());
  }
  if (!fs::is_directory(folder, error)) fail(folder, "is not a folder");
  const fs::path marker = folder / kMarker;
  marked_ = !fs::exists(fs::symlink_status(marker, error));
  if (marked_ && !is_empty_folder(folder)) {
    fail(folder, "is not empty and was not written by a c2f tool (it has no " +
                     std::string(kMarker) +
                     "): the tools never write into a folder they do not own; give a new or "
                     "empty folder");
  }
  // Locks the marker the folder holds now: a run that replaced the folder while this one waited
  // for the file leaves a new marker behind, which is then locked instead.
  for (int attempt = 0; fd_ < 0; ++attempt) {
    const int fd = ::open(marker.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0)
      fail(folder, "cannot hold its marker " + marker.string() + ": " + std::strerror(errno));
    if (::flock(fd, wait ? LOCK_EX : LOCK_EX | LOCK_NB) != 0) {
      const int why = errno;
      const std::string holder = read_marker(fd);
      ::close(fd);
      if (why != EWOULDBLOCK) fail(folder, std::string("cannot be locked: ") + std::strerror(why));
      const std::string process = holder.substr(holder.find('\n') + 1);
      fail(folder, "is being written by another run (" + first_line(holder) + ", " +
                       first_line(process) +
                       "): wait for it to end, or give this run another folder");
    }
    struct stat held {};
    struct stat current {};
    if (::fstat(fd, &held) == 0 && ::stat(marker.c_str(), &current) == 0 &&
        held.st_dev == current.st_dev && held.st_ino == current.st_ino) {
      fd_ = fd;
    } else {
      ::close(fd);
      if (attempt == 10) fail(folder, "keeps changing while this run claims it");
    }
  }
  const std::string owner = first_line(read_marker(fd_));
  if (!owner.empty() && owner != tool) {
    ::close(fd_);
    fail(folder, "holds the outputs of " + owner + ", not of " + tool + ": give another folder");
  }
  tool_line_ = tool.size() + 1;
  const std::string text = tool + "\nprocess " + std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 ||
      ::pwrite(fd_, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size())) {
    const int why = errno;
    ::close(fd_);
    fail(folder, "cannot have its marker written: " + std::string(std::strerror(why)));
  }
}

FolderClaim::~FolderClaim() {
  if (fd_ < 0) return;
  // The process line goes with the claim, so a finished run's folder is the same bytes each time.
  [[maybe_unused]] const int ignored = ::ftruncate(fd_, static_cast<off_t>(tool_line_));
  ::close(fd_);
}

}  // namespace c2f::examples
