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

// Reads Linux's /proc/cpuinfo and glibc's sysconf cache sizes; elsewhere what it cannot read is
// left unknown. Never throws.
[[nodiscard]] MachineInfo describe_machine() noexcept;

}  // namespace carom::cli
