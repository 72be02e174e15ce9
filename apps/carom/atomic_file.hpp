// carom tool: writing an output file so that readers never see half of it.
#pragma once

#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

namespace carom::cli {

// Writes content to path + ".tmp" and renames that onto path, so path holds either its old
// content or all of the new. Returns nothing on success, otherwise what went wrong in the
// operating system's words; no .tmp file is left behind either way.
[[nodiscard]] std::optional<std::string> write_file_atomically(const std::string& path,
                                                               std::string_view content);

// Whether path could be written: its folder exists and a file can be created there (tried with
// path + ".tmp", removed at once). Returns what is wrong, or nothing. For checking every output
// before a long run starts.
[[nodiscard]] std::optional<std::string> check_writable(const std::string& path);

// A file written in pieces that appears under its name only when complete: everything goes to
// path + ".tmp", and commit() renames it onto path. Destroyed uncommitted (an error, an
// exception), it removes the temporary file, so path never holds half an output.
class AtomicOutput {
 public:
  AtomicOutput() = default;
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  // Returns what went wrong, or nothing.
  [[nodiscard]] std::optional<std::string> open(const std::string& path);
  [[nodiscard]] bool is_open() const noexcept { return file_ != nullptr; }
  // Appends; a failure is remembered and reported by commit().
  void write(std::string_view content);
  // Flushes, closes and renames; returns what went wrong, or nothing.
  [[nodiscard]] std::optional<std::string> commit();

 private:
  std::string path_;
  std::string temporary_;
  std::FILE* file_ = nullptr;
  int write_errno_ = 0;
};

}  // namespace carom::cli
