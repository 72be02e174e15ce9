// carom tool: writing an output named on the command line without losing what the name stood for.
//
// What a name gets, decided once when it is opened:
// - "-": standard output.
// - A missing file or a plain one, reached through any symbolic links: an AtomicFile
//   (carom/atomic_file.hpp) with the fixed name TARGET.tmp beside the final target, renamed onto
//   it only when complete (not synced: an output is remade by running again), so the file holds
//   its old content or all of the new one; the links stay links.
// - A character device (/dev/null, a terminal), a FIFO or a Unix socket: written directly, as a
//   shell's `>` would; renaming onto them would replace them with a plain file.
// - A folder: refused.
// Messages name the file as the user gave it.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "carom/atomic_file.hpp"
#include "system/stop_signals.hpp"

namespace carom::cli {

// The name that means standard output.
inline constexpr std::string_view kStandardOutput = "-";

class OutputFile {
 public:
  OutputFile() = default;
  // Uncommitted (an error, an exception, an early return): the temporary file is removed.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Returns what went wrong, or nothing. A FIFO blocks here until a reader opens it.
  [[nodiscard]] std::optional<std::string> open(const std::string& name);
  [[nodiscard]] bool is_open() const noexcept { return file_.has_value() || fd_ >= 0; }
  // Appends (buffered); a failure is remembered and reported by commit().
  void write(std::string_view content);
  // Flushes, closes and (for a file) renames; returns what went wrong, or nothing.
  [[nodiscard]] std::optional<std::string> commit();

 private:
  void flush();
  void discard();

  std::string name_;                // as the user gave it
  std::optional<AtomicFile> file_;  // a plain file, replaced when committed
  TemporaryFileGuard guard_;        // removes file_'s temporary at a second Ctrl-C
  int fd_ = -1;                     // written directly: standard output, a device, FIFO, socket
  bool owns_fd_ = false;            // false for standard output
  std::string failure_;             // the first write's failure; empty while none
  std::string buffer_;
};

// Writes content to the named output as a whole (an OutputFile opened, written and committed).
[[nodiscard]] std::optional<std::string> write_output(const std::string& name,
                                                      std::string_view content);

// Whether the named output could be written, checked before a long run so that it fails at once
// rather than at its end: its folder exists and takes a new file, or the device, FIFO or socket
// is writable. Nothing is created or opened. Returns what is wrong, or nothing.
[[nodiscard]] std::optional<std::string> check_output(const std::string& name);

// Whether the folder of the named output has room for about `bytes` more (only files that are
// replaced take room; standard output and devices never refuse). Returns a refusal giving the
// estimate and the room, or nothing.
[[nodiscard]] std::optional<std::string> check_room(const std::string& name, double bytes);

// Throws UsageError for "-" given where a folder of outputs is asked for (gas and eos's --out):
// standard output is one stream, not a folder.
void refuse_standard_output_as_folder(const char* option, const std::string& name);

// An output option and the name given for it ("" when not given).
struct NamedOutput {
  const char* option;
  const std::string* name;
};
// Checks, before any work, every given output (check_output) and that no two reach the same one
// (same_output); throws UsageError naming the option otherwise.
void check_distinct_outputs(std::span<const NamedOutput> outputs);

// Whether two names reach the same output (the same file through links, or both standard output).
[[nodiscard]] bool same_output(const std::string& a, const std::string& b);

// The final target of a name through its symbolic links (the name itself when it is none).
[[nodiscard]] std::string link_target(const std::string& name);

// Whether the name is a plain file or none (so that it is written by rename), through links.
[[nodiscard]] bool replaced_by_rename(const std::string& name);

}  // namespace carom::cli
