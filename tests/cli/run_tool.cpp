#include "run_tool.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace carom::cli::test {

// A file the child writes one stream into (or reads its input from). Outside the anonymous
// namespace: RunningTool::Streams holds two.
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

namespace {

// Starts program with args, its stdin read from in_fd and its stdout and stderr sent to the given
// descriptors, each /dev/null for -1; the child's pid, or -1 if it cannot be started.
pid_t spawn_program(const std::string& program, const std::vector<std::string>& args, int out_fd,
                    int err_fd, int in_fd = -1) {
  std::vector<std::string> words{program};
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
  if (in_fd >= 0) {
    posix_spawn_file_actions_adddup2(&actions, in_fd, STDIN_FILENO);
  } else {
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  }
  pid_t child = 0;
  // environ (from unistd.h) passes the test's own environment on.
  const int spawned = posix_spawn(&child, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return spawned == 0 ? child : -1;
}

// The same for the tool (CAROM_CLI_PATH).
pid_t spawn_carom(const std::vector<std::string>& args, int out_fd, int err_fd, int in_fd = -1) {
  return spawn_program(CAROM_CLI_PATH, args, out_fd, err_fd, in_fd);
}

}  // namespace

pid_t start_carom(const std::vector<std::string>& args) { return spawn_carom(args, -1, -1); }

pid_t start_program(const std::string& program, const std::vector<std::string>& args) {
  return spawn_program(program, args, -1, -1);
}

ToolRun run_program(const std::string& program, const std::vector<std::string>& args) {
  const ScratchDir streams;
  const CaptureFile out(streams, "stdout");
  const CaptureFile err(streams, "stderr");
  const pid_t child = spawn_program(program, args, out.fd(), err.fd());
  if (child < 0) throw std::runtime_error("cannot run " + program);
  ToolRun run;
  run.exit_code = wait_for_exit(child);
  run.out = out.content();
  run.err = err.content();
  return run;
}

int wait_for_exit(pid_t child) {
  int status = 0;
  while (waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

ToolRun run_carom(const std::vector<std::string>& args) { return run_carom(args, std::nullopt); }

ToolRun run_carom(const std::vector<std::string>& args, const std::optional<std::string>& input) {
  const ScratchDir streams;
  const CaptureFile out(streams, "stdout");
  const CaptureFile err(streams, "stderr");
  std::optional<CaptureFile> in;
  if (input) {
    in.emplace(streams, "stdin");
    std::ofstream(streams / "stdin", std::ios::binary) << *input;
  }
  const pid_t child = spawn_carom(args, out.fd(), err.fd(), in ? in->fd() : -1);
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

struct RunningTool::Streams {
  Streams() : out(dir, "stdout"), err(dir, "stderr") {}
  ScratchDir dir;
  CaptureFile out;
  CaptureFile err;
};

RunningTool::RunningTool(const std::vector<std::string>& args)
    : streams_(std::make_unique<Streams>()),
      pid_(spawn_carom(args, streams_->out.fd(), streams_->err.fd())) {
  if (pid_ < 0) throw std::runtime_error(std::string("cannot run ") + CAROM_CLI_PATH);
}

RunningTool::~RunningTool() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    static_cast<void>(wait_for_exit(pid_));
  }
}

bool RunningTool::signal(int signal) const { return pid_ > 0 && ::kill(pid_, signal) == 0; }

ToolRun RunningTool::wait() {
  ToolRun run;
  if (pid_ > 0) run.exit_code = wait_for_exit(pid_);
  pid_ = -1;
  run.out = streams_->out.content();
  run.err = streams_->err.content();
  return run;
}

std::string RunningTool::err() const { return streams_->err.content(); }

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

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

std::size_t json_files_in(const std::filesystem::path& folder) {
  std::size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() == ".json") ++count;
  }
  return count;
}

std::vector<std::string> mpirun_args(const std::vector<std::string>& carom_args) {
  std::vector<std::string> args{"--oversubscribe", "--allow-run-as-root", "-n", "3",
                                CAROM_CLI_PATH};
  args.insert(args.end(), carom_args.begin(), carom_args.end());
  return args;
}

}  // namespace carom::cli::test
