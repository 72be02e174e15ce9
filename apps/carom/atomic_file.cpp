#include "atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace carom::cli {

std::optional<std::string> write_file_atomically(const std::string& path,
                                                 std::string_view content) {
  const std::string temporary = path + ".tmp";
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (file == nullptr) return "cannot create " + temporary + ": " + std::strerror(errno);

  const bool written = std::fwrite(content.data(), 1, content.size(), file) == content.size();
  const int write_errno = errno;
  // fclose flushes the buffer, so a full disk may show up only here.
  const bool closed = std::fclose(file) == 0;
  const int close_errno = errno;
  std::error_code ignored;
  if (!written || !closed) {
    std::filesystem::remove(temporary, ignored);
    return "cannot write " + temporary + ": " + std::strerror(written ? close_errno : write_errno);
  }

  std::error_code renamed;
  std::filesystem::rename(temporary, path, renamed);
  if (renamed) {
    std::filesystem::remove(temporary, ignored);
    return "cannot rename " + temporary + " to " + path + ": " + renamed.message();
  }
  return std::nullopt;
}

std::optional<std::string> check_writable(const std::string& path) {
  if (path.empty()) return "the file name is empty";
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return path + " is a folder";
  const std::string temporary = path + ".tmp";
  // An existing .tmp may be another run's; do not touch it.
  if (std::filesystem::exists(temporary, error)) {
    return "cannot create " + temporary + ": it exists already";
  }
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (file == nullptr) return "cannot create " + temporary + ": " + std::strerror(errno);
  std::fclose(file);
  std::filesystem::remove(temporary, error);
  return std::nullopt;
}

AtomicOutput::~AtomicOutput() {
  if (file_ == nullptr) return;
  std::fclose(file_);
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

std::optional<std::string> AtomicOutput::open(const std::string& path) {
  path_ = path;
  temporary_ = path + ".tmp";
  file_ = std::fopen(temporary_.c_str(), "wb");
  if (file_ == nullptr) return "cannot create " + temporary_ + ": " + std::strerror(errno);
  return std::nullopt;
}

void AtomicOutput::write(std::string_view content) {
  if (file_ == nullptr || write_errno_ != 0) return;
  if (std::fwrite(content.data(), 1, content.size(), file_) != content.size()) {
    write_errno_ = errno != 0 ? errno : EIO;
  }
}

std::optional<std::string> AtomicOutput::commit() {
  if (file_ == nullptr) return "cannot write " + path_ + ": it is not open";
  const bool closed = std::fclose(file_) == 0;
  const int close_errno = errno;
  file_ = nullptr;
  std::error_code ignored;
  if (write_errno_ != 0 || !closed) {
    std::filesystem::remove(temporary_, ignored);
    return "cannot write " + temporary_ + ": " +
           std::strerror(write_errno_ != 0 ? write_errno_ : close_errno);
  }
  std::error_code renamed;
  std::filesystem::rename(temporary_, path_, renamed);
  if (renamed) {
    std::filesystem::remove(temporary_, ignored);
    return "cannot rename " + temporary_ + " to " + path_ + ": " + renamed.message();
  }
  return std::nullopt;
}

}  // namespace carom::cli
