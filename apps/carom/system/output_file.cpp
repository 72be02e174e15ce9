#include "system/output_file.hpp"

#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <utility>

#include "options/readable_number.hpp"
#include "options/usage_error.hpp"

namespace carom::cli {
namespace {

// Content is handed to the system in pieces of this size.
constexpr std::size_t kBufferBytes = std::size_t{1} << 20;

// What a name leads to through its symbolic links.
struct Resolved {
  std::filesystem::path path;  // the final target
  bool exists = false;
  struct stat status {};
  int error = 0;  // errno of a failure to follow the links
};

Resolved resolve(const std::string& name) {
  Resolved r;
  std::error_code error;
  r.path = follow_links(name, error);
  if (error) {
    r.error = error.value();
    return r;
  }
  if (::lstat(r.path.c_str(), &r.status) != 0) {
    if (errno != ENOENT) r.error = errno;
    return r;
  }
  r.exists = true;
  return r;
}

std::filesystem::path folder_of(const std::filesystem::path& path) {
  return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

bool written_directly(const struct stat& status) {
  return S_ISCHR(status.st_mode) || S_ISFIFO(status.st_mode) || S_ISSOCK(status.st_mode);
}

// What is wrong with the target itself, for any use: a folder, a disk, an unfollowable link.
std::optional<std::string> refusal(const Resolved& r) {
  if (r.error != 0) return std::string("cannot follow its links: ") + std::strerror(r.error);
  if (!r.exists) return std::nullopt;
  if (S_ISDIR(r.status.st_mode)) return "is a folder";
  if (S_ISBLK(r.status.st_mode))
    return "is a block device (a disk): refused, it would be overwritten";
  return std::nullopt;
}

int connect_socket(const std::filesystem::path& path) {
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  const std::string text = path.string();
  if (text.size() >= sizeof address.sun_path) {
    errno = ENAMETOOLONG;
    return -1;
  }
  std::memcpy(address.sun_path, text.c_str(), text.size() + 1);
  const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-reinterpret-cast): the sockets API's own cast.
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    const int error = errno;
    ::close(fd);
    errno = error;
    return -1;
  }
  return fd;
}

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

OutputFile::~OutputFile() { discard(); }

void OutputFile::discard() {
  if (fd_ >= 0 && owns_fd_) ::close(fd_);
  fd_ = -1;
  file_.reset();  // removes the temporary of a file not committed
  guard_ = TemporaryFileGuard();
}

std::optional<std::string> OutputFile::open(const std::string& name) {
  discard();
  name_ = name;
  failure_.clear();
  buffer_.clear();
  if (name == kStandardOutput) {
    fd_ = STDOUT_FILENO;
    owns_fd_ = false;
    return std::nullopt;
  }
  if (name.empty()) return std::string("the file name is empty");
  const Resolved r = resolve(name);
  if (auto problem = refusal(r)) return name + " " + *problem;
  if (r.exists && written_directly(r.status)) {
    owns_fd_ = true;
    fd_ = S_ISSOCK(r.status.st_mode) ? connect_socket(r.path)
                                     : ::open(r.path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd_ < 0) return "cannot open " + name + ": " + std::strerror(errno);
    return std::nullopt;
  }
  try {
    file_.emplace(name, AtomicFileOptions{.temporary = TemporaryName::fixed, .sync = false});
  } catch (const FileError& error) {
    return "cannot write " + name + ": " + error.reason();
  }
  guard_ = TemporaryFileGuard(file_->temporary().string());
  return std::nullopt;
}

void OutputFile::flush() {
  if (failure_.empty() && !buffer_.empty()) {
    if (file_) {
      try {
        file_->write(buffer_);
      } catch (const FileError& error) {
        failure_ = error.reason();
      }
    } else if (!write_all(fd_, buffer_)) {
      failure_ = std::strerror(errno != 0 ? errno : EIO);
    }
  }
  buffer_.clear();
}

void OutputFile::write(std::string_view content) {
  if (!is_open() || !failure_.empty()) return;
  buffer_.append(content);
  if (buffer_.size() >= kBufferBytes) flush();
}

std::optional<std::string> OutputFile::commit() {
  if (!is_open()) return "cannot write " + name_ + ": it is not open";
  flush();
  if (file_ && failure_.empty()) {
    try {
      file_->commit();
    } catch (const FileError& error) {
      failure_ = error.reason();
    }
  }
  if (fd_ >= 0 && owns_fd_ && ::close(std::exchange(fd_, -1)) != 0 && failure_.empty()) {
    failure_ = std::strerror(errno);
  }
  discard();
  if (!failure_.empty()) return "cannot write " + name_ + ": " + failure_;
  return std::nullopt;
}

std::optional<std::string> write_output(const std::string& name, std::string_view content) {
  OutputFile out;
  if (auto problem = out.open(name)) return problem;
  out.write(content);
  return out.commit();
}

std::optional<std::string> check_output(const std::string& name) {
  if (name == kStandardOutput) return std::nullopt;
  if (name.empty()) return std::string("the file name is empty");
  const Resolved r = resolve(name);
  if (auto problem = refusal(r)) return problem;
  if (r.exists && written_directly(r.status)) {
    if (::access(r.path.c_str(), W_OK) != 0) return std::string(std::strerror(errno));
    return std::nullopt;
  }
  const std::filesystem::path folder = folder_of(r.path);
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) {
    return "its folder " + folder.string() + " does not exist";
  }
  // Tried for real, with the temporary file's own name: what a run would do at its end.
  const std::string temporary = r.path.string() + ".tmp";
  // An existing one may be another run's; it is not touched.
  if (std::filesystem::exists(temporary, error)) {
    return "its temporary file " + temporary + " exists already (another run's?)";
  }
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    return "cannot create a file in " + folder.string() + ": " + std::strerror(errno);
  }
  ::close(fd);
  ::unlink(temporary.c_str());
  return std::nullopt;
}

std::optional<std::string> check_room(const std::string& name, double bytes) {
  if (!replaced_by_rename(name)) return std::nullopt;
  const std::filesystem::path folder = folder_of(link_target(name));
  struct statvfs room {};
  if (::statvfs(folder.c_str(), &room) != 0) return std::nullopt;  // unknown: not refused
  const double free_bytes = static_cast<double>(room.f_bavail) * static_cast<double>(room.f_frsize);
  if (bytes <= free_bytes) return std::nullopt;
  return "would take about " + readable_bytes(bytes) + " and " + folder.string() + " has " +
         readable_bytes(free_bytes) + " free";
}

void refuse_standard_output_as_folder(const char* option, const std::string& name) {
  if (name == kStandardOutput) {
    throw UsageError(option, name,
                     "names a folder to write several files into; standard output (-) is one "
                     "stream: give a folder");
  }
}

void check_distinct_outputs(std::span<const NamedOutput> outputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const std::string& path = *outputs[i].name;
    if (path.empty()) continue;
    for (std::size_t j = 0; j < i; ++j) {
      if (same_output(*outputs[j].name, path)) {
        throw UsageError(outputs[i].option, path,
                         std::string("the same file as ") + outputs[j].option);
      }
    }
    if (const auto problem = check_output(path)) {
      throw UsageError(outputs[i].option, path, "cannot be written: " + *problem);
    }
  }
}

bool same_output(const std::string& a, const std::string& b) {
  if (a == kStandardOutput || b == kStandardOutput) return a == b;
  if (!replaced_by_rename(a) || !replaced_by_rename(b)) return false;  // two devices may be one
  std::error_code error_a;
  std::error_code error_b;
  const auto path_a = std::filesystem::weakly_canonical(link_target(a), error_a);
  const auto path_b = std::filesystem::weakly_canonical(link_target(b), error_b);
  if (error_a || error_b) return link_target(a) == link_target(b);
  return path_a == path_b;
}

std::string link_target(const std::string& name) { return resolve(name).path.string(); }

bool replaced_by_rename(const std::string& name) {
  if (name == kStandardOutput) return false;
  const Resolved r = resolve(name);
  return r.error == 0 && (!r.exists || S_ISREG(r.status.st_mode));
}

}  // namespace carom::cli
