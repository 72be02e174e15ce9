// carom CLI tests: running the built `carom` binary as a user would, and scratch folders for the
// files it writes.
#pragma once

#include <sys/types.h>  // pid_t

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace carom::cli::test {

struct ToolRun {
  int exit_code = -1;  // the status the tool exited with; -1 if it did not exit normally
  std::string out;     // everything it printed on stdout
  std::string err;     // everything it printed on stderr
};

// Runs the tool (CAROM_CLI_PATH) with args and waits for it. Its output goes through files, so
// neither stream can block the other however much is written. Its standard input is `input`
// (or /dev/null).
[[nodiscard]] ToolRun run_carom(const std::vector<std::string>& args);
[[nodiscard]] ToolRun run_carom(const std::vector<std::string>& args,
                                const std::optional<std::string>& input);

// Starts the tool with args without waiting for it, its output discarded; -1 if it cannot start.
[[nodiscard]] pid_t start_carom(const std::vector<std::string>& args);
// Any program (mpirun) run the same ways: waited for with its output kept, or started in the
// background with its output discarded.
[[nodiscard]] ToolRun run_program(const std::string& program, const std::vector<std::string>& args);
[[nodiscard]] pid_t start_program(const std::string& program, const std::vector<std::string>& args);
// Waits for a tool started so: its exit status, or -1 if it did not exit normally.
[[nodiscard]] int wait_for_exit(pid_t child);

// Skips the test, saying why, where the tool was built without MPI or mpirun is missing.
#define CAROM_SKIP_WITHOUT_MPI()                                                          \
  do {                                                                                    \
    if (!CAROM_CLI_HAS_MPI) GTEST_SKIP() << "the tool was built without MPI (CAROM_MPI)"; \
    if (std::string(CAROM_MPIRUN).empty() || !std::filesystem::exists(CAROM_MPIRUN)) {    \
      GTEST_SKIP() << "mpirun is missing: sudo apt-get install -y openmpi-bin";           \
    }                                                                                     \
  } while (false)

// mpirun's arguments for the tool with 3 ranks on this machine whatever its cores
// (--oversubscribe), as root too (CI).
[[nodiscard]] std::vector<std::string> mpirun_args(const std::vector<std::string>& carom_args);

// The tool started in the background with its output kept, for tests that signal it. Killed
// (SIGKILL) when destroyed if it is still running.
class RunningTool {
 public:
  explicit RunningTool(const std::vector<std::string>& args);
  ~RunningTool();
  RunningTool(const RunningTool&) = delete;
  RunningTool& operator=(const RunningTool&) = delete;

  [[nodiscard]] pid_t pid() const { return pid_; }
  // Sends a signal; false if it could not be sent.
  bool signal(int signal) const;
  // Waits for the exit: its status (-1 if killed by a signal) and everything it printed.
  [[nodiscard]] ToolRun wait();
  // What it has printed on stderr so far.
  [[nodiscard]] std::string err() const;

 private:
  struct Streams;
  std::unique_ptr<Streams> streams_;
  pid_t pid_ = -1;
};

// A fresh, empty folder for one test, removed with everything in it when the test ends.
class ScratchDir {
 public:
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] std::filesystem::path operator/(const std::string& name) const {
    return path_ / name;
  }

 private:
  std::filesystem::path path_;
};

// The lines of a text, without their line ends.
[[nodiscard]] std::vector<std::string> lines_of(const std::string& text);

// The whole content of a file ("" if it cannot be read).
[[nodiscard]] std::string read_file(const std::filesystem::path& path);
// How many .json files folder holds (a sweep's checkpoints).
[[nodiscard]] std::size_t json_files_in(const std::filesystem::path& folder);

}  // namespace carom::cli::test
