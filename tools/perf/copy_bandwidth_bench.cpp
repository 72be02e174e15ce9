// carom benchmarks: the memory bandwidth of one core, measured in the same binary as the
// kernels, for the memory-bound goal: sweeping 10^6 pairs should take at most 1.5 times
// (bytes per pair) / (copy bandwidth). Every buffer is twice the L3 cache or more, so each
// iteration streams from memory; bytes processed count what the program reads plus what it
// writes, as the pair benchmarks do.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "cache_line_allocator.hpp"

namespace carom::bench {
namespace {

constexpr std::size_t kBufferBytes = std::size_t{64} << 20;  // 64 MiB, twice the 32 MiB L3
constexpr std::size_t kReadBufferBytes = 2 * kBufferBytes;   // as much as a copy touches

using Bytes = std::vector<std::byte, CacheLineAllocator<std::byte>>;
using Words = std::vector<std::uint64_t, CacheLineAllocator<std::uint64_t>>;

void set_bytes(benchmark::State& state, std::size_t bytes_per_iteration) {
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(bytes_per_iteration));
}

// glibc's memcpy: for buffers this large it writes with non-temporal (streaming) stores, which
// skip the read of each destination line that an ordinary store causes.
void BM_CopyMemcpy(benchmark::State& state) {
  const Bytes from(kBufferBytes, std::byte{1});
  Bytes to(kBufferBytes);  // zero-filled now, so no page is first touched while timing
  for (auto _ : state) {
    std::memcpy(to.data(), from.data(), kBufferBytes);
    benchmark::DoNotOptimize(to.data());
    benchmark::ClobberMemory();
  }
  set_bytes(state, 2 * kBufferBytes);
}
BENCHMARK(BM_CopyMemcpy)->Unit(benchmark::kMillisecond);

// STREAM's "scale" kernel, to[i] = scale·from[i]: a copy through ordinary stores, as the sweep
// kernel writes t. The run-time factor keeps the compiler from turning it into memcpy.
void BM_CopyLoop(benchmark::State& state) {
  constexpr std::size_t kCount = kBufferBytes / sizeof(double);
  const Column from(kCount, 1.0);
  Column to(kCount);
  double scale = 1.0;
  benchmark::DoNotOptimize(scale);
  for (auto _ : state) {
    for (std::size_t i = 0; i < kCount; ++i) to[i] = scale * from[i];
    benchmark::DoNotOptimize(to.data());
    benchmark::ClobberMemory();
  }
  set_bytes(state, 2 * kBufferBytes);
}
BENCHMARK(BM_CopyLoop)->Unit(benchmark::kMillisecond);

// Reading alone (a sum of 64-bit words, which vectorises), for reference: 80 of the sweep
// kernel's 88 bytes per pair are reads. A single stream, where the kernel reads ten at once.
void BM_Read(benchmark::State& state) {
  constexpr std::size_t kCount = kReadBufferBytes / sizeof(std::uint64_t);
  const Words words(kCount, 1u);
  for (auto _ : state) {
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < kCount; ++i) sum += words[i];
    benchmark::DoNotOptimize(sum);
  }
  set_bytes(state, kReadBufferBytes);
}
BENCHMARK(BM_Read)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace carom::bench
