// carom tool: independent runs side by side, as `carom eos` and `carom pack --seeds` make them:
// each thread takes the next run not yet taken, while the calling thread watches their progress.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>

namespace carom::cli {

// Runs run(j, progress) for j in [0, count) on at most `threads` threads; a run sets its progress
// (0 to 1) as it goes, and it is set to 1 when the run returns. Once stop() answers true no new
// run starts. watch is told on the calling thread, about ten times a second while the runs go,
// their progress together (0 to 1). run must not throw.
void run_in_parallel(std::size_t count, std::size_t threads, const std::function<bool()>& stop,
                     const std::function<void(std::size_t, std::atomic<double>&)>& run,
                     const std::function<void(double)>& watch);

}  // namespace carom::cli
