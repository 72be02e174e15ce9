#include "bench/machine_info.hpp"

#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <system_error>
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

// The first line of a small file; empty where it cannot be read.
std::string first_line(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

// A size as the kernel writes it: digits and an optional K, M or G (binary multiples); 0 for
// anything else.
std::uint64_t size_bytes(const std::string& text) {
  std::uint64_t value = 0;
  std::size_t at = 0;
  constexpr std::uint64_t kMostDigits = 15;  // far below 2^64 even times 2^30
  while (at < text.size() && at < kMostDigits &&
         std::isdigit(static_cast<unsigned char>(text[at]))) {
    value = value * 10 + static_cast<std::uint64_t>(text[at] - '0');
    ++at;
  }
  if (at == 0) return 0;
  const std::string_view unit = std::string_view(text).substr(at);
  if (unit.empty()) return value;
  if (unit == "K") return value << 10;
  if (unit == "M") return value << 20;
  if (unit == "G") return value << 30;
  return 0;
}

}  // namespace

CacheSizes read_cache_sizes(const std::string& folder) noexcept {
  CacheSizes sizes;
  try {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
      if (entry.path().filename().string().rfind("index", 0) != 0) continue;
      const std::string level = first_line(entry.path() / "level");
      const std::string type = first_line(entry.path() / "type");
      const std::uint64_t bytes = size_bytes(first_line(entry.path() / "size"));
      if (level == "1" && type == "Data") sizes.l1d = bytes;
      if (level == "2" && type == "Unified") sizes.l2 = bytes;
      if (level == "3" && type == "Unified") sizes.l3 = bytes;
    }
  } catch (...) {  // (a folder that vanishes while read, or bad_alloc: the sizes then unknown)
    return {};
  }
  return sizes;
}

MachineInfo describe_machine() noexcept {
  MachineInfo machine;
  try {
    machine.cpu = cpu_model_name();
  } catch (...) {  // (reading a file can throw bad_alloc: the name is then unknown)
    machine.cpu.clear();
  }
  if (machine.cpu.empty()) machine.cpu = "unknown";
  machine.logical_cpus = std::thread::hardware_concurrency();
  const CacheSizes listed = read_cache_sizes("/sys/devices/system/cpu/cpu0/cache");
  machine.l1d_cache_bytes = listed.l1d;
  machine.l2_cache_bytes = listed.l2;
  machine.l3_cache_bytes = listed.l3;
#ifdef _SC_LEVEL1_DCACHE_SIZE
  if (machine.l1d_cache_bytes == 0) machine.l1d_cache_bytes = cache_bytes(_SC_LEVEL1_DCACHE_SIZE);
  if (machine.l2_cache_bytes == 0) machine.l2_cache_bytes = cache_bytes(_SC_LEVEL2_CACHE_SIZE);
  if (machine.l3_cache_bytes == 0) machine.l3_cache_bytes = cache_bytes(_SC_LEVEL3_CACHE_SIZE);
#endif
  return machine;
}

}  // namespace carom::cli
