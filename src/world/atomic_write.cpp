#include "atomic_write.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include "carom/error.hpp"

namespace carom::detail {

namespace {

[[noreturn]] void fail(const char* function, const std::filesystem::path& path,
                       const std::string& what, int error) {
  throw InvalidArgument(function, "path", path.string(), what + ": " + std::strerror(error));
}

// Writes all of content, going on after partial writes and signals.
bool write_all(int fd, std::string_view content) {
  while (!content.empty()) {
    const ssize_t written = ::write(fd, content.data(), content.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    content.remove_prefix(static_cast<std::size_t>(written));
  }
  return true;
}

}  // namespace

void write_file_atomically(const char* function, const std::filesystem::path& path,
                           std::string_view content) {
  // mkstemp in the same folder: rename is atomic only within one file system.
  std::string name = path.string() + ".XXXXXX";
  std::vector<char> temporary(name.begin(), name.end());
  temporary.push_back('\0');
  const int fd = ::mkstemp(temporary.data());
  if (fd < 0) fail(function, path, "cannot create a temporary file beside it", errno);
  name.assign(temporary.data());

  const bool written = write_all(fd, content);
  int error = errno;
  const bool synced = written && ::fsync(fd) == 0;
  if (written && !synced) error = errno;
  const bool closed = ::close(fd) == 0;
  if (written && synced && !closed) error = errno;
  if (!written || !synced || !closed) {
    ::unlink(name.c_str());
    fail(function, path, "cannot write " + name, error);
  }
  if (::rename(name.c_str(), path.c_str()) != 0) {
    error = errno;
    ::unlink(name.c_str());
    fail(function, path, "cannot rename " + name + " onto it", error);
  }
  // The rename is durable only once the folder's entry is on the disk too. A folder that cannot
  // be opened or synced (some file systems refuse) leaves the file written, so that is no error.
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
  const int folder_fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (folder_fd >= 0) {
    ::fsync(folder_fd);
    ::close(folder_fd);
  }
}

}  // namespace carom::detail
