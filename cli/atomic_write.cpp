#include "cli/atomic_write.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

namespace rung::cli {
namespace fs = std::filesystem;

namespace {

std::string system_error(std::string_view what, const fs::path& path) {
  return std::string(what) + " " + path.string() + ": " + std::strerror(errno);
}

bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd, bytes.data(), bytes.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    bytes.remove_prefix(static_cast<size_t>(written));
  }
  return true;
}

}  // namespace

bool replace_file_atomically(const fs::path& path, std::string_view bytes, std::string* error) {
  std::error_code ec;
  const fs::path target = fs::canonical(path, ec);  // a symbolic link stays a link to the new file
  if (ec) {
    *error = "cannot resolve " + path.string() + ": " + ec.message();
    return false;
  }
  struct stat original {};
  if (::stat(target.c_str(), &original) != 0) {
    *error = system_error("cannot read the attributes of", target);
    return false;
  }
  // Beside the original (same file system, so the rename is atomic); unique per process and call.
  static std::atomic<unsigned> counter{0};
  fs::path temp = target.parent_path() / ("." + target.filename().string() + ".rung-fmt-" + std::to_string(::getpid()) +
                                          "-" + std::to_string(counter++));
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, original.st_mode & 07777);
  if (fd < 0) {
    *error = system_error("cannot create", temp);
    return false;
  }
  // Best effort: keep the owner when rung runs with the rights to do so.
  if (::fchown(fd, original.st_uid, original.st_gid) != 0) errno = 0;
  const bool written = write_all(fd, bytes) && ::fsync(fd) == 0;
  const int saved_errno = errno;
  const bool closed = ::close(fd) == 0;
  if (!written || !closed) {
    errno = written ? errno : saved_errno;
    *error = system_error("cannot write", temp);
    ::unlink(temp.c_str());
    return false;
  }
  if (::rename(temp.c_str(), target.c_str()) != 0) {
    *error = system_error("cannot replace", target);
    ::unlink(temp.c_str());
    return false;
  }
  return true;
}

}  // namespace rung::cli
