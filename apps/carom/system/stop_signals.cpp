#include "system/stop_signals.hpp"

#include <sys/types.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <utility>

namespace carom::cli {
namespace {

// The first signal received (0: none). Lock-free, so the handler may set it.
std::atomic<int> g_first_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

// The temporary files' registry: fixed slots, so that the handler reads them without locks or
// allocation. A slot is free (0), being filled (1) or holds a path (2).
constexpr std::size_t kSlots = 64;
constexpr std::size_t kLongestPath = 4095;
struct Slot {
  std::atomic<int> state{0};
  std::array<char, kLongestPath + 1> path{};
};
std::array<Slot, kSlots> g_temporaries;

extern "C" void on_stop_signal(int signal) {
  int none = 0;
  if (g_first_signal.compare_exchange_strong(none, signal)) return;
  // A second signal: the user insists. Only async-signal-safe calls from here on.
  for (Slot& slot : g_temporaries) {
    if (slot.state.load() == 2) ::unlink(slot.path.data());
  }
  ::_exit(128 + signal);
}

void install(void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  // Interrupted system calls resume: the flag is read by the loops, not by failing calls.
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

StopOnSignals::StopOnSignals() {
  g_first_signal.store(0);
  install(on_stop_signal);
}

// After a signal the tool is on its way out: the handler stays, so that a second signal during
// the last clean-up still removes the temporary files and exits with 128 + signal, rather than
// killing the process with its temporaries left behind.
StopOnSignals::~StopOnSignals() {
  if (g_first_signal.load() == 0) install(SIG_DFL);
}

bool StopOnSignals::requested() noexcept { return g_first_signal.load() != 0; }

int StopOnSignals::exit_code() noexcept { return 128 + g_first_signal.load(); }

std::string StopOnSignals::what() noexcept {
  return g_first_signal.load() == SIGTERM ? "terminated (SIGTERM)" : "interrupted (Ctrl-C)";
}

void stop_world_on_signals(World& world, std::function<void(const RunStatus&)> progress) {
  world.set_progress_callback([progress = std::move(progress)](const RunStatus& status) {
    if (progress) progress(status);
    return StopOnSignals::requested();
  });
}

TemporaryFileGuard::TemporaryFileGuard(const std::string& path) {
  if (path.size() > kLongestPath) return;
  for (std::size_t k = 0; k < kSlots; ++k) {
    int free = 0;
    if (!g_temporaries[k].state.compare_exchange_strong(free, 1)) continue;
    std::memcpy(g_temporaries[k].path.data(), path.c_str(), path.size() + 1);
    g_temporaries[k].state.store(2);
    slot_ = static_cast<int>(k);
    return;
  }
}

TemporaryFileGuard::~TemporaryFileGuard() {
  if (slot_ >= 0) g_temporaries[static_cast<std::size_t>(slot_)].state.store(0);
}

TemporaryFileGuard::TemporaryFileGuard(TemporaryFileGuard&& other) noexcept
    : slot_(std::exchange(other.slot_, -1)) {}

TemporaryFileGuard& TemporaryFileGuard::operator=(TemporaryFileGuard&& other) noexcept {
  if (this != &other) {
    if (slot_ >= 0) g_temporaries[static_cast<std::size_t>(slot_)].state.store(0);
    slot_ = std::exchange(other.slot_, -1);
  }
  return *this;
}

}  // namespace carom::cli
