#include "system/child_process.hpp"

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <stdexcept>

#include "system/stop_signals.hpp"

namespace carom::cli {

namespace {

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error(what + ": " + std::strerror(errno));
}

// In the child: standard output to the pipe, then the program. Only async-signal-safe calls
// between fork and exec.
[[noreturn]] void become(const std::string& program, char* const argv[], int read_end,
                         int write_end) {
  ::close(read_end);
  if (::dup2(write_end, STDOUT_FILENO) < 0) ::_exit(127);
  ::close(write_end);
  ::execv(program.c_str(), argv);
  static constexpr char kMessage[] = "carom: error: cannot run the measuring program\n";
  (void)!::write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
  ::_exit(127);
}

}  // namespace

std::string output_of_program(const std::string& program, const std::vector<std::string>& args) {
  std::vector<std::string> words{program};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  argv.reserve(words.size() + 1);
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);

  int fds[2];
  if (::pipe(fds) != 0) fail("cannot make a pipe");
  // Whatever this process has buffered would otherwise be written by both.
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) {
    const int error = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    errno = error;
    fail("cannot start " + program);
  }
  if (child == 0) become(program, argv.data(), fds[0], fds[1]);
  // A signal that stops this process stops the child too (StopOnSignals).
  const ForwardSignalsTo forward(child);
  ::close(fds[1]);
  std::string out;
  char buffer[4096];
  for (;;) {
    const ssize_t got = ::read(fds[0], buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    out.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) fail("cannot wait for " + program);
  }
  if (WIFSIGNALED(status)) {
    throw std::runtime_error(program + " was killed by signal " + std::to_string(WTERMSIG(status)));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error(program + " failed with exit status " +
                             std::to_string(WEXITSTATUS(status)) + " (its message is above)");
  }
  return out;
}

}  // namespace carom::cli
