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

}  // namespace carom::cli
