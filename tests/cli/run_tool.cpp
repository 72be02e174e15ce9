#include "run_tool.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace carom::cli::test {
namespace {

// A file the child writes one stream into, removed when the run is over.
class CaptureFile {
 public:
  explicit CaptureFile(const ScratchDir& dir, const std::string& name)
      : path_(dir / name), fd_(::open(path_.c_str(), O_RDWR | O_CREAT | O_TRUNC, 0600)) {
    if (fd_ < 0) throw std::runtime_error("cannot create " + path_.string());
  }
  ~CaptureFile() { ::close(fd_); }
  CaptureFile(const CaptureFile&) = delete;
  CaptureFile& operator=(const CaptureFile&) = delete;

  [[nodiscard]] int fd() const { return fd_; }
  [[nodiscard]] std::string content() const { return read_file(path_); }

 private:
  std::filesystem::path path_;
  int fd_;
};

// Starts the tool (CAROM_CLI_PATH) with args, its stdout and stderr sent to the given
// descriptors, or to /dev/null for -1; the child's pid, or -1 if it cannot be started.
pid_t spawn_carom(const std::vector<std::string>& args, int out_fd, int err_fd) {
  std::vector<std::string> words{CAROM_CLI_PATH};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  argv.reserve(words.size() + 1);
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  const auto send = [&actions](int fd, int stream) {
    if (fd >= 0) {
      posix_spawn_file_actions_adddup2(&actions, fd, stream);
    } else {
      posix_spawn_file_actions_addopen(&actions, stream, "/dev/null", O_WRONLY, 0);
    }
  };
  send(out_fd, STDOUT_FILENO);
  send(err_fd, STDERR_FILENO);
  pid_t child = 0;
  // environ (from unistd.h) passes the test's own environment on.
  const int spawned = posix_spawn(&child, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return spawned == 0 ? child : -1;
}

}  // namespace

pid_t start_carom(const std::vector<std::string>& args) { return spawn_carom(args, -1, -1); }

int wait_for_exit(pid_t child) {
  int status = 0;
  while (waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

ToolRun run_carom(const std::vector<std::string>& args) {
  const ScratchDir streams;
  const CaptureFile out(streams, "stdout");
  const CaptureFile err(streams, "stderr");
  const pid_t child = spawn_carom(args, out.fd(), err.fd());
  if (child < 0) throw std::runtime_error(std::string("cannot run ") + CAROM_CLI_PATH);

  int status = 0;
  while (waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("waitpid failed");
  }
  ToolRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = out.content();
  run.err = err.content();
  return run;
}

ScratchDir::ScratchDir() {
  // The test's name and the process id keep folders apart when ctest runs tests in parallel.
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = "carom-cli-" + std::to_string(::getpid());
  if (test != nullptr) name += std::string("-") + test->test_suite_name() + "-" + test->name();
  for (char& c : name) {
    if (c == '/') c = '_';  // parameterised tests have a / in their names
  }
  path_ = std::filesystem::temp_directory_path() / name;
  for (int attempt = 0; std::filesystem::exists(path_); ++attempt) {
    path_ = std::filesystem::temp_directory_path() / (name + "-" + std::to_string(attempt));
  }
  std::filesystem::create_directories(path_);
}

ScratchDir::~ScratchDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

}  // namespace carom::cli::test
