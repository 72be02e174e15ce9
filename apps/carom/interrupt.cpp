#include "interrupt.hpp"

#include <csignal>

namespace carom::cli {
namespace {

volatile std::sig_atomic_t g_stop_requested = 0;

extern "C" void on_interrupt(int /*signal*/) {
  g_stop_requested = 1;
  // The next Ctrl-C is not caught: a user who insists gets the default (immediate) exit.
  std::signal(SIGINT, SIG_DFL);
}

}  // namespace

StopOnInterrupt::StopOnInterrupt() {
  g_stop_requested = 0;
  std::signal(SIGINT, on_interrupt);
}

StopOnInterrupt::~StopOnInterrupt() { std::signal(SIGINT, SIG_DFL); }

bool StopOnInterrupt::requested() noexcept { return g_stop_requested != 0; }

}  // namespace carom::cli
