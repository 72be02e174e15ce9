// carom tool: the machine a benchmark ran on, as far as the process can tell, so that a figure
// names its host (the same build runs at different speeds on different processors, and memory-
// bound figures depend most on the caches' sizes).
#pragma once

#include <cstdint>
#include <string>

namespace carom::cli {

struct MachineInfo {
  std::string cpu;                    // the processor's model name, or "unknown"
  unsigned logical_cpus = 0;          // std::thread::hardware_concurrency (0: unknown)
  std::uint64_t l1d_cache_bytes = 0;  // per core (0: unknown)
  std::uint64_t l2_cache_bytes = 0;   // per core (0: unknown)
  std::uint64_t l3_cache_bytes = 0;   // as the system reports it (0: unknown)
};

// Reads Linux's /proc/cpuinfo, and the cache sizes the kernel lists for CPU 0 (read_cache_sizes)
// or, for a level it does not list, glibc's sysconf; elsewhere what it cannot read is left
// unknown. Never throws.
[[nodiscard]] MachineInfo describe_machine() noexcept;

// The sizes of the level 1 data cache and the level 2 and 3 caches in a folder laid out as Linux's
// /sys/devices/system/cpu/cpu0/cache (one index* folder a cache, with its `level`, `type` and
// `size`, e.g. "32768K"), 0 for a level it does not list. These are the caches of one CPU as the
// kernel was told of them, the last level's share included: glibc's sysconf can answer otherwise
// (on AMD EPYC guests it gave 384 MiB for an L3 that the kernel lists as 32 MiB). Never throws.
struct CacheSizes {
  std::uint64_t l1d = 0;
  std::uint64_t l2 = 0;
  std::uint64_t l3 = 0;
};
[[nodiscard]] CacheSizes read_cache_sizes(const std::string& folder) noexcept;

}  // namespace carom::cli
