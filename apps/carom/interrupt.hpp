// carom tool: Ctrl-C as a request to stop. While a StopOnInterrupt lives, SIGINT sets a flag that
// long runs poll between chunks, so they end cleanly with every output complete; a second Ctrl-C
// kills as usual.
#pragma once

namespace carom::cli {

class StopOnInterrupt {
 public:
  StopOnInterrupt();
  ~StopOnInterrupt();
  StopOnInterrupt(const StopOnInterrupt&) = delete;
  StopOnInterrupt& operator=(const StopOnInterrupt&) = delete;

  [[nodiscard]] static bool requested() noexcept;
};

}  // namespace carom::cli
