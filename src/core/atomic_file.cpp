#include "carom/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <random>
#include <string>
#include <utility>

namespace carom {

namespace {

// Links followed before giving up, as the kernel does (ELOOP).
constexpr int kMostLinks = 40;
// Unique names tried before giving up: each is one of 62^6, so a clash is a stale file's.
constexpr int kUniqueNameTries = 100;

std::error_code system_error_code(int error) { return {error, std::generic_category()}; }

std::filesystem::path folder_holding(const std::filesystem::path& path) {
  return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

// TARGET. and six letters or digits, as mkstemp names them (mkstemp itself creates mode 0600
// whatever the umask; a saved file should get the permissions of any other new file).
std::filesystem::path unique_name(const std::filesystem::path& target) {
  static constexpr std::string_view kLetters =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  std::random_device random;
  std::uniform_int_distribution<std::size_t> pick(0, kLetters.size() - 1);
  std::string suffix = ".";
  for (int k = 0; k < 6; ++k) suffix += kLetters[pick(random)];
  std::filesystem::path name = target;
  name += suffix;
  return name;
}

}  // namespace

FileError::FileError(std::filesystem::path file, std::string problem, std::error_code code)
    : std::runtime_error(file.string() + ": " + problem +
                         (code ? ": " + code.message() : std::string())),
      file_(std::move(file)),
      problem_(std::move(problem)),
      code_(code) {}

std::string FileError::reason() const {
  return code_ ? problem_ + ": " + code_.message() : problem_;
}

std::filesystem::path follow_links(const std::filesystem::path& path, std::error_code& error) {
  error.clear();
  std::filesystem::path at = path;
  for (int k = 0; k <= kMostLinks; ++k) {
    struct stat status {};
    if (::lstat(at.c_str(), &status) != 0) {
      if (errno != ENOENT) error = system_error_code(errno);
      return at;
    }
    if (!S_ISLNK(status.st_mode)) return at;
    const std::filesystem::path next = std::filesystem::read_symlink(at, error);
    if (error) return at;
    at = next.is_absolute() ? next : at.parent_path() / next;
  }
  error = system_error_code(ELOOP);
  return at;
}

AtomicFile::AtomicFile(std::filesystem::path path, AtomicFileOptions options)
    : path_(std::move(path)), options_(options) {
  if (path_.empty()) throw FileError(path_, "the file name is empty");
  std::error_code error;
  target_ = follow_links(path_, error);
  if (error) throw FileError(path_, "cannot follow its links", error);
  struct stat status {};
  const bool exists = ::stat(target_.c_str(), &status) == 0;
  if (exists && S_ISDIR(status.st_mode)) throw FileError(path_, "is a folder");
  if (exists && !S_ISREG(status.st_mode)) {
    throw FileError(path_,
                    "is not a plain file (a device, a FIFO or a socket): it is not replaced");
  }
  const int flags = O_WRONLY | O_CREAT | O_CLOEXEC;
  if (options_.temporary == TemporaryName::fixed) {
    temporary_ = target_;
    temporary_ += ".tmp";
    fd_ = ::open(temporary_.c_str(), flags | O_TRUNC, 0666);
  } else {
    for (int k = 0; k < kUniqueNameTries; ++k) {
      temporary_ = unique_name(target_);
      fd_ = ::open(temporary_.c_str(), flags | O_EXCL, 0666);
      if (fd_ >= 0 || errno != EEXIST) break;
    }
  }
  if (fd_ < 0) {
    const int reason = errno;
    std::filesystem::path tried = std::exchange(temporary_, {});
    throw FileError(path_, "cannot create its temporary file " + tried.string(),
                    system_error_code(reason));
  }
  // A file replaced keeps its permissions (the owner's change is the rename's nature).
  if (exists) static_cast<void>(::fchmod(fd_, status.st_mode & 07777));
}

AtomicFile::~AtomicFile() { discard(); }

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : path_(std::move(other.path_)),
      target_(std::move(other.target_)),
      temporary_(std::exchange(other.temporary_, {})),
      options_(other.options_),
      fd_(std::exchange(other.fd_, -1)) {}

AtomicFile& AtomicFile::operator=(AtomicFile&& other) noexcept {
  if (this != &other) {
    discard();
    path_ = std::move(other.path_);
    target_ = std::move(other.target_);
    temporary_ = std::exchange(other.temporary_, {});
    options_ = other.options_;
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

void AtomicFile::discard() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!temporary_.empty()) ::unlink(temporary_.c_str());
  temporary_.clear();
}

void AtomicFile::fail(const std::string& problem, int error) {
  discard();
  throw FileError(path_, problem, system_error_code(error));
}

void AtomicFile::write(std::string_view bytes) {
  if (fd_ < 0) throw FileError(path_, "cannot write: it is not open (committed or failed)");
  while (!bytes.empty()) {
    const ssize_t written = ::write(fd_, bytes.data(), bytes.size());
    if (written < 0) {
      const int error = errno;
      if (error == EINTR) continue;
      fail("cannot write its temporary file " + temporary_.string(), error);
    }
    bytes.remove_prefix(static_cast<std::size_t>(written));
  }
}

void AtomicFile::commit() {
  if (fd_ < 0) throw FileError(path_, "cannot commit: it is not open (committed or failed)");
  // Synced before the rename, so that a crash cannot leave the new name on unwritten data.
  if (options_.sync && ::fsync(fd_) != 0) {
    const int error = errno;
    fail("cannot sync its temporary file " + temporary_.string() + " to the disk", error);
  }
  if (::close(std::exchange(fd_, -1)) != 0) {
    const int error = errno;
    fail("cannot write its temporary file " + temporary_.string(), error);
  }
  if (options_.keep_previous) {
    std::filesystem::path previous = target_;
    previous += ".prev";
    if (::rename(target_.c_str(), previous.c_str()) != 0 && errno != ENOENT) {
      const int error = errno;
      fail("cannot rename " + target_.string() + " to " + previous.string(), error);
    }
  }
  if (::rename(temporary_.c_str(), target_.c_str()) != 0) {
    const int error = errno;
    fail("cannot rename its temporary file " + temporary_.string() + " onto it", error);
  }
  temporary_.clear();
  if (!options_.sync) return;
  // The rename is durable once the folder's entry is on the disk too. A folder that cannot be
  // opened or synced (some file systems refuse) leaves the file written, so that is no error.
  const int folder = ::open(folder_holding(target_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (folder >= 0) {
    static_cast<void>(::fsync(folder));
    ::close(folder);
  }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content,
                           AtomicFileOptions options) {
  AtomicFile file(path, options);
  file.write(content);
  file.commit();
}

}  // namespace carom
