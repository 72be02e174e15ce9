#include "machine_info.hpp"

#include <unistd.h>

#include <fstream>
#include <string_view>
#include <thread>

namespace carom::cli {
namespace {

// The first "model name" line of /proc/cpuinfo (x86 Linux); empty where there is none.
std::string cpu_model_name() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  constexpr std::string_view kKey = "model name";
  while (std::getline(cpuinfo, line)) {
    if (line.compare(0, kKey.size(), kKey) != 0) continue;
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    const std::size_t start = line.find_first_not_of(" \t", colon + 1);
    if (start == std::string::npos) continue;
    return line.substr(start);
  }
  return {};
}

// sysconf's answer where it knows (glibc; 0 or −1 where it does not).
[[maybe_unused]] std::uint64_t cache_bytes(int name) {
  const long bytes = sysconf(name);
  return bytes > 0 ? static_cast<std::uint64_t>(bytes) : 0;
}

}  // namespace

MachineInfo describe_machine() noexcept {
  MachineInfo machine;
  try {
    machine.cpu = cpu_model_name();
  } catch (...) {  // (reading a file can throw bad_alloc: the name is then unknown)
    machine.cpu.clear();
  }
  if (machine.cpu.empty()) machine.cpu = "unknown";
  machine.logical_cpus = std::thread::hardware_concurrency();
#ifdef _SC_LEVEL1_DCACHE_SIZE
  machine.l1d_cache_bytes = cache_bytes(_SC_LEVEL1_DCACHE_SIZE);
  machine.l2_cache_bytes = cache_bytes(_SC_LEVEL2_CACHE_SIZE);
  machine.l3_cache_bytes = cache_bytes(_SC_LEVEL3_CACHE_SIZE);
#endif
  return machine;
}

}  // namespace carom::cli
