#include "c2f/support/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "c2f/core/memory_budget.hpp"
#include "c2f/support/memory_need.hpp"

namespace c2f {

namespace {

/// What a file that is not regular is, for messages.
std::string special_kind(mode_t mode) {
  if (S_ISFIFO(mode)) return "is not a regular file (a FIFO)";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is not a regular file (a device)";
  if (S_ISSOCK(mode)) return "is not a regular file (a socket)";
  if (S_ISDIR(mode)) return "is a folder, not a file";
  return "is not a regular file";
}

/// Closes a file descriptor when it leaves scope.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

namespace {

std::atomic<std::size_t> input_limit{0};  // 0: not set

}  // namespace

void set_input_memory_limit(std::size_t bytes) noexcept {
  input_limit = bytes;
}

std::size_t input_memory_limit() {
  if (const std::size_t set = input_limit.load(); set != 0) return set;
  return default_memory_budget().ceiling();
}

void require_input_memory(const std::string& path, std::string_view what, double bytes,
                          std::string_view how) {
  const std::size_t limit = input_memory_limit();
  if (bytes <= static_cast<double>(limit)) return;
  throw std::invalid_argument(std::string(what) + " '" + path + "' needs " + format_bytes(bytes) +
                              " " + std::string(how) + ", more than the " +
                              format_bytes(static_cast<double>(limit)) +
                              " the run's memory budget allows for one input");
}

std::string why_not_a_file(const std::string& path) {
  if (path.empty()) return "is an empty path";
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) {
    if (errno == ENOENT || errno == ENOTDIR) return "does not exist";
    return "cannot be examined (" + std::string(std::strerror(errno)) + ")";
  }
  if (S_ISREG(status.st_mode)) return "";
  return special_kind(status.st_mode);
}

std::string read_input_file(const std::string& path, std::string_view what, std::size_t max_bytes) {
  const std::string name = std::string(what) + " '" + path + "'";
  if (const std::string why = why_not_a_file(path); !why.empty())
    throw std::invalid_argument(name + " " + why);
  // O_NONBLOCK: a path swapped for a FIFO after the check above still cannot block the open.
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0)
    throw std::invalid_argument(name + " cannot be opened (" + std::strerror(errno) + ")");
  struct stat status {};
  if (::fstat(file.fd, &status) != 0)
    throw std::invalid_argument(name + " cannot be examined (" + std::strerror(errno) + ")");
  if (!S_ISREG(status.st_mode))
    throw std::invalid_argument(name + " " + special_kind(status.st_mode));
  const auto size = static_cast<std::size_t>(status.st_size);
  if (size > max_bytes) {
    throw std::invalid_argument(name + " is " + format_bytes(static_cast<double>(size)) + "; a " +
                                std::string(what) + " of at most " +
                                format_bytes(static_cast<double>(max_bytes)) + " is expected");
  }
  std::string content(size, '\0');
  std::size_t done = 0;
  while (true) {
    if (done == content.size()) {  // the file may have grown since fstat: read on, bounded
      if (content.size() >= max_bytes) {
        char probe = 0;
        const ssize_t more = ::read(file.fd, &probe, 1);
        if (more == 0) break;
        if (more < 0 && errno == EINTR) continue;
        if (more < 0)
          throw std::runtime_error("reading " + name + " failed (" + std::strerror(errno) + ")");
        throw std::invalid_argument(name + " grew past " +
                                    format_bytes(static_cast<double>(max_bytes)) +
                                    " while it was read");
      }
      content.resize(std::min(max_bytes, content.size() + 4096));
    }
    const ssize_t got = ::read(file.fd, content.data() + done, content.size() - done);
    if (got == 0) break;
    if (got < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error("reading " + name + " failed (" + std::strerror(errno) + ")");
    }
    done += static_cast<std::size_t>(got);
  }
  content.resize(done);
  return content;
}

}  // namespace c2f
