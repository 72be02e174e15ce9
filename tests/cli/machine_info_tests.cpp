// The machine a benchmark report names (apps/carom/bench/machine_info.hpp): the cache sizes read
// from a folder laid out as Linux's /sys/devices/system/cpu/cpu0/cache, as the kernel writes them.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "bench/machine_info.hpp"
#include "run_tool.hpp"

namespace carom::cli {
namespace {

// One cache's folder, index<k>, with its level, type and size as the kernel writes them.
void write_cache(const test::ScratchDir& folder, int index, const std::string& level,
                 const std::string& type, const std::string& size) {
  const std::filesystem::path cache = folder / ("index" + std::to_string(index));
  std::filesystem::create_directory(cache);
  std::ofstream(cache / "level") << level << "\n";
  std::ofstream(cache / "type") << type << "\n";
  std::ofstream(cache / "size") << size << "\n";
}

TEST(MachineInfo, ReadsTheDataAndUnifiedCachesTheKernelLists) {
  const test::ScratchDir folder;
  write_cache(folder, 0, "1", "Data", "48K");
  write_cache(folder, 1, "1", "Instruction", "32K");
  write_cache(folder, 2, "2", "Unified", "1024K");
  write_cache(folder, 3, "3", "Unified", "32768K");
  std::ofstream(folder / "uevent") << "not a cache\n";
  const CacheSizes sizes = read_cache_sizes(folder.path().string());
  EXPECT_EQ(sizes.l1d, 48u << 10);
  EXPECT_EQ(sizes.l2, 1u << 20);
  EXPECT_EQ(sizes.l3, 32u << 20);
}

TEST(MachineInfo, ReadsSizesInEveryUnitTheKernelWrites) {
  const test::ScratchDir folder;
  write_cache(folder, 0, "1", "Data", "49152");
  write_cache(folder, 1, "2", "Unified", "2M");
  write_cache(folder, 2, "3", "Unified", "1G");
  const CacheSizes sizes = read_cache_sizes(folder.path().string());
  EXPECT_EQ(sizes.l1d, 49152u);
  EXPECT_EQ(sizes.l2, 2u << 20);
  EXPECT_EQ(sizes.l3, std::uint64_t{1} << 30);
}

TEST(MachineInfo, LeavesUnknownWhatItCannotRead) {
  const test::ScratchDir folder;
  write_cache(folder, 0, "1", "Data", "48Q");                    // not a unit
  write_cache(folder, 1, "2", "Unified", "");                    // no size
  write_cache(folder, 2, "3", "Unified", "99999999999999999G");  // past what a size can be
  const CacheSizes sizes = read_cache_sizes(folder.path().string());
  EXPECT_EQ(sizes.l1d, 0u);
  EXPECT_EQ(sizes.l2, 0u);
  EXPECT_EQ(sizes.l3, 0u);
  const CacheSizes none = read_cache_sizes((folder / "no such folder").string());
  EXPECT_EQ(none.l1d, 0u);
  EXPECT_EQ(none.l2, 0u);
  EXPECT_EQ(none.l3, 0u);
}

}  // namespace
}  // namespace carom::cli
