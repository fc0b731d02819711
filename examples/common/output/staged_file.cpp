#include "staged_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

#include "staged_paths.hpp"

namespace c2f::examples {

namespace fs = std::filesystem;

namespace {

/// `fifo` opened to write, without waiting for a reader (then blocking as usual); throws unless
/// some process has it open for reading. The descriptor stays open while the run writes: closing
/// the only writer would end the reader's input.
int open_with_reader(const fs::path& fifo) {
  const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd >= 0) {
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    return fd;
  }
  if (errno == ENXIO) {
    throw std::invalid_argument("'" + fifo.string() +
                                "' is a FIFO that no process is reading: start its reader "
                                "first, or give a regular file");
  }
  throw std::invalid_argument("cannot open the FIFO '" + fifo.string() +
                              "': " + std::strerror(errno));
}

}  // namespace

StagedFile::StagedFile(const fs::path& target) : target_(target) {
  std::error_code error;
  const fs::file_status status = fs::status(target, error);  // follows symbolic links
  if (fs::exists(status)) {
    switch (status.type()) {
      case fs::file_type::regular:
        break;
      case fs::file_type::directory:
        throw std::invalid_argument("'" + target.string() + "' is a folder, not a file");
      case fs::file_type::socket:
        throw std::invalid_argument("'" + target.string() + "' is a socket, not a file");
      case fs::file_type::fifo:
        // Writers open the held descriptor's FIFO again through /proc, which never blocks.
        fifo_ = open_with_reader(target);
        path_ = "/proc/self/fd/" + std::to_string(fifo_);
        note_staged_path(path_.string(), target.string());
        return;
      default:  // character and block devices
        path_ = target;
        return;
    }
  }
  // The file a symbolic link names is replaced, not the link; a link to nothing is refused (it
  // would be replaced by a file, or a file made wherever it points).
  if (fs::is_symlink(fs::symlink_status(target, error))) {
    if (!fs::exists(status)) {
      throw std::invalid_argument("'" + target.string() + "' is a symbolic link to '" +
                                  fs::read_symlink(target, error).string() +
                                  "', which does not exist: give the file's own path, or remove "
                                  "the link");
    }
    const fs::path resolved = fs::weakly_canonical(target, error);
    if (error) {
      throw std::invalid_argument(
          "'" + target.string() +
          "' is a symbolic link that cannot be followed: " + error.message());
    }
    target_ = resolved;
  }
  path_ = target_;
  path_ += ".c2f-partial-" + std::to_string(::getpid());
  note_staged_path(path_.string(), target.string());
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : target_(std::move(other.target_)),
      path_(std::move(other.path_)),
      fifo_(other.fifo_),
      committed_(other.committed_) {
  other.committed_ = true;  // the moved-from object removes nothing
  other.fifo_ = -1;
}

StagedFile::~StagedFile() {
  if (fifo_ >= 0) ::close(fifo_);
  if (committed_ || in_place()) return;
  std::error_code ignored;
  fs::remove(path_, ignored);
}

void StagedFile::commit() {
  if (committed_) throw std::logic_error("StagedFile::commit: already committed");
  if (!in_place()) {
    std::error_code error;
    fs::rename(path_, target_, error);
    if (error) {
      throw std::runtime_error("cannot put the new '" + target_.string() +
                               "' in place: " + error.message());
    }
  }
  committed_ = true;
}

}  // namespace c2f::examples
