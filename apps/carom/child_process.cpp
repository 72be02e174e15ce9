#include "child_process.hpp"

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <stdexcept>

namespace carom::cli {

namespace {

// Writes all of text to fd; false when it cannot.
bool write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t wrote = ::write(fd, text.data() + done, text.size() - done);
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) return false;
    done += static_cast<std::size_t>(wrote);
  }
  return true;
}

[[noreturn]] void run_child(int fd, const std::function<std::string()>& work) {
  int status = 1;
  try {
    status = write_all(fd, work()) ? 0 : 1;
  } catch (const std::exception& error) {
    std::cerr << "carom: error: " << error.what() << '\n';
  } catch (...) {
    std::cerr << "carom: error: an unknown exception\n";
  }
  std::cerr.flush();
  ::close(fd);
  // _exit, not exit: the parent's atexit handlers and stream buffers are the parent's.
  ::_exit(status);
}

}  // namespace

std::string output_of_child(const std::function<std::string()>& work) {
  int fds[2];
  if (::pipe(fds) != 0) {
    throw std::runtime_error(std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  // Whatever the parent has buffered would otherwise be written twice, once by each.
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) {
    const int error = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("cannot start a process: ") + std::strerror(error));
  }
  if (child == 0) {
    ::close(fds[0]);
    run_child(fds[1], work);
  }
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
      throw std::runtime_error(std::string("cannot wait for a process: ") + std::strerror(errno));
    }
  }
  if (WIFSIGNALED(status)) {
    throw std::runtime_error("the measuring process was killed by signal " +
                             std::to_string(WTERMSIG(status)));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error("the measuring process failed (its message is above)");
  }
  return out;
}

}  // namespace carom::cli
