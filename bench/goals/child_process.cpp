#include "child_process.hpp"

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <stdexcept>

namespace carom::goals {

namespace {

// The first signal received (0: none), and the child it is passed on to (0: none). Lock-free, so
// the handler may use them.
std::atomic<int> g_first_signal{0};
std::atomic<pid_t> g_child{0};
static_assert(std::atomic<int>::is_always_lock_free && std::atomic<pid_t>::is_always_lock_free);

// The signals that ask this program to stop.
constexpr int kStopSignals[] = {SIGINT, SIGTERM};

extern "C" void on_stop_signal(int signal) {
  if (const pid_t child = g_child.load(); child > 0) ::kill(child, signal);
  int none = 0;
  if (g_first_signal.compare_exchange_strong(none, signal)) return;
  ::_exit(128 + signal);  // a second signal: the user insists
}

// Interrupted system calls resume (SA_RESTART): the flag is read by the caller, not by failing
// calls.
void install(void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  action.sa_flags = SA_RESTART;
  sigemptyset(&action.sa_mask);
  for (const int number : kStopSignals) sigaction(number, &action, nullptr);
}

sigset_t stop_signal_set() {
  sigset_t set;
  sigemptyset(&set);
  for (const int number : kStopSignals) sigaddset(&set, number);
  return set;
}

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error(what + ": " + std::strerror(errno));
}

// In the child: the signals as the program expects them, standard output to the pipe, then the
// program. Only async-signal-safe calls between fork and exec.
[[noreturn]] void become(const std::string& program, char* const argv[], int read_end,
                         int write_end, const sigset_t& mask, const std::string& cannot_run) {
  for (const int number : kStopSignals) ::signal(number, SIG_DFL);
  ::sigprocmask(SIG_SETMASK, &mask, nullptr);
  ::close(read_end);
  if (::dup2(write_end, STDOUT_FILENO) < 0) ::_exit(127);
  ::close(write_end);
  ::execv(program.c_str(), argv);
  (void)!::write(STDERR_FILENO, cannot_run.data(), cannot_run.size());
  ::_exit(127);
}

}  // namespace

StopSignals::StopSignals() {
  g_first_signal.store(0);
  install(on_stop_signal);
}

StopSignals::~StopSignals() { install(SIG_DFL); }

int StopSignals::received() noexcept { return g_first_signal.load(); }

std::string StopSignals::what() noexcept {
  return g_first_signal.load() == SIGTERM ? "terminated (SIGTERM)" : "interrupted (Ctrl-C)";
}

std::string output_of_program(const std::string& program, const std::vector<std::string>& args) {
  std::vector<std::string> words{program};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  argv.reserve(words.size() + 1);
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const std::string cannot_run = "error: cannot run " + program + "\n";

  int fds[2];
  if (::pipe(fds) != 0) fail("cannot make a pipe");
  // Whatever this process has buffered would otherwise be written by both.
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  // The stop signals wait until the child is known, so that none falls between its start and
  // the moment it can be passed on.
  const sigset_t stop = stop_signal_set();
  sigset_t mask;
  ::sigprocmask(SIG_BLOCK, &stop, &mask);
  const pid_t child = ::fork();
  if (child < 0) {
    const int error = errno;
    ::sigprocmask(SIG_SETMASK, &mask, nullptr);
    ::close(fds[0]);
    ::close(fds[1]);
    errno = error;
    fail("cannot start " + program);
  }
  if (child == 0) become(program, argv.data(), fds[0], fds[1], mask, cannot_run);
  g_child.store(child);
  ::sigprocmask(SIG_SETMASK, &mask, nullptr);
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
    if (errno != EINTR) {
      g_child.store(0);
      fail("cannot wait for " + program);
    }
  }
  g_child.store(0);
  if (WIFSIGNALED(status)) {
    throw std::runtime_error(program + " was killed by signal " + std::to_string(WTERMSIG(status)));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error(program + " failed with exit status " +
                             std::to_string(WEXITSTATUS(status)) + " (its message is above)");
  }
  return out;
}

}  // namespace carom::goals
