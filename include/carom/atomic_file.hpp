// carom: replacing a file so that it holds its old content or all of the new one, never half.
//
// Why one public component: World::save, save_scene and the carom tool's outputs and checkpoints
// all replace files, and the tool may use public headers only. It knows nothing of signals or of
// how each caller words its errors: temporary() is public for a tool that removes it when killed,
// and FileError names the step that failed and the system's reason. The temporary lies beside the
// final target of the path (a rename is atomic within one file system only), reached through
// symbolic links so that a link stays a link. Its name is unique by default (TARGET.XXXXXX,
// created exclusively): a library's callers may save one path from several threads or processes
// at once, and each then renames a whole file of its own; fixed (TARGET.tmp) serves the tool,
// whose users and checkpoint recovery look for that name (docs/checkpoints.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

namespace carom {

// A file that could not be replaced. file() is the path as the caller gave it, problem() the step
// that failed ("cannot create its temporary file out.json.tmp"), code() the system's reason (empty
// for carom's own refusals, such as a target that is a folder). what() reads
// "FILE: PROBLEM: REASON"; reason() is the same without "FILE: ".
class FileError : public std::runtime_error {
 public:
  FileError(std::filesystem::path file, std::string problem, std::error_code code = {});

  [[nodiscard]] const std::filesystem::path& file() const noexcept { return file_; }
  [[nodiscard]] const std::string& problem() const noexcept { return problem_; }
  [[nodiscard]] std::error_code code() const noexcept { return code_; }
  [[nodiscard]] std::string reason() const;

 private:
  std::filesystem::path file_;
  std::string problem_;
  std::error_code code_;
};

enum class TemporaryName : std::uint8_t {
  unique,  // TARGET.XXXXXX (six random letters or digits), created exclusively
  fixed,   // TARGET.tmp, truncated when one is there already (a killed writer's)
};

struct AtomicFileOptions {
  TemporaryName temporary = TemporaryName::unique;
  // Flush the temporary to the disk (fsync) before the rename, and the folder after it, so that
  // the replacement survives a crash of the machine too.
  bool sync = true;
  // Rename the file replaced to TARGET.prev first: between the two renames TARGET.prev and the
  // temporary are the complete files, and TARGET is missing.
  bool keep_previous = false;
};

// Streams content into a temporary file and renames it onto the target when committed.
class AtomicFile {
 public:
  // Creates the temporary. A new file gets the permissions of any new file (0666 less the umask);
  // a replaced one keeps its own. Throws FileError: the links cannot be followed, the target is
  // there but not a plain file (a folder, a device, a FIFO, a socket), or the folder refuses.
  explicit AtomicFile(std::filesystem::path path, AtomicFileOptions options = {});
  // Uncommitted (an error, an exception, an early return): the temporary is removed.
  ~AtomicFile();
  AtomicFile(AtomicFile&& other) noexcept;
  AtomicFile& operator=(AtomicFile&& other) noexcept;
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Appends all of bytes. Throws FileError, and the temporary is then removed; so it is when
  // commit() throws. Either on a file committed or failed throws FileError too.
  void write(std::string_view bytes);
  void commit();

  // The final target, through the links: where the content lands.
  [[nodiscard]] const std::filesystem::path& target() const noexcept { return target_; }
  // The temporary file while it exists; empty once committed or failed.
  [[nodiscard]] const std::filesystem::path& temporary() const noexcept { return temporary_; }

 private:
  // Removes the temporary and throws FileError.
  [[noreturn]] void fail(const std::string& problem, int error);
  void discard() noexcept;

  std::filesystem::path path_;  // as the caller gave it, for errors
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  AtomicFileOptions options_;
  int fd_ = -1;
};

// An AtomicFile opened, given all of content and committed. Throws FileError.
void write_file_atomically(const std::filesystem::path& path, std::string_view content,
                           AtomicFileOptions options = {});

// Where path leads through symbolic links: its last part followed link by link (a relative link
// read from the link's folder), as the kernel does, up to 40 links; path itself when it is no
// link or is missing. error is set when a link cannot be read, when there are more than 40 links
// (ELOOP), or when the path cannot be looked at for another reason than being missing (a folder
// on the way refuses, or is a file).
[[nodiscard]] std::filesystem::path follow_links(const std::filesystem::path& path,
                                                 std::error_code& error);

}  // namespace carom
