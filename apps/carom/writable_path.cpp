#include "writable_path.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace carom::cli {

std::optional<std::string> check_output_path(const std::string& path) {
  if (path.empty()) return "the file name is empty";
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) return path + " is a folder";
  // The same temporary name write_file_atomically uses: if it can be made, the write will work
  // (short of the disk filling up meanwhile).
  const std::string temporary = path + ".tmp";
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (file == nullptr) return "cannot create " + temporary + ": " + std::strerror(errno);
  std::fclose(file);
  std::filesystem::remove(temporary, error);
  return std::nullopt;
}

}  // namespace carom::cli
