// carom benchmarks: the latency of one load that depends on the one before, over buffers from
// 1 MiB to 256 MiB: the time of a cache or memory round trip that nothing overlaps. The world's
// cost a collision grows with the number of balls by about (round trips no prefetch hides) ×
// (this latency at the world's size), which is how docs/performance.md ("What bounds each size")
// reads the 10⁶-ball figure. Each buffer is a random cycle through its cache lines (one pointer a
// line), in huge pages as the world's arrays are, so that neither the hardware prefetcher nor the
// TLB takes part. The counter per_load is the time of one load.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <numeric>
#include <random>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace carom::bench {
namespace {

struct alignas(64) Line {
  const Line* next = nullptr;
};
static_assert(sizeof(Line) == 64);

constexpr std::size_t kHugePage = std::size_t{2} << 20;

struct FreeMemory {
  void operator()(Line* lines) const { std::free(lines); }  // NOLINT: from aligned_alloc
};

// `count` lines in 2 MiB pages where the kernel grants them (the world's allocator asks alike).
std::unique_ptr<Line[], FreeMemory> huge_page_lines(std::size_t count) {
  const std::size_t bytes = (count * sizeof(Line) + kHugePage - 1) / kHugePage * kHugePage;
  void* memory = std::aligned_alloc(kHugePage, bytes);
  if (memory == nullptr) throw std::bad_alloc();
#if defined(__linux__)
  (void)madvise(memory, bytes, MADV_HUGEPAGE);  // advice: failure only costs the TLB
#endif
  auto* lines = static_cast<Line*>(memory);
  std::uninitialized_value_construct_n(lines, count);
  return std::unique_ptr<Line[], FreeMemory>(lines);
}

void BM_DependentLoad(benchmark::State& state) {
  const std::size_t count =
      static_cast<std::size_t>(state.range(0)) * (std::size_t{1} << 20) / sizeof(Line);
  const auto lines = huge_page_lines(count);
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::shuffle(order.begin(), order.end(), std::mt19937_64(20261201));
  for (std::size_t k = 0; k < count; ++k) lines[order[k]].next = &lines[order[(k + 1) % count]];
  constexpr std::int64_t kLoadsPerIteration = 4096;
  const Line* at = &lines[order[0]];
  for (std::size_t k = 0; k < count; ++k) at = at->next;  // one lap: the buffer as warm as it gets
  for (auto _ : state) {
    for (std::int64_t k = 0; k < kLoadsPerIteration; ++k) at = at->next;
    benchmark::DoNotOptimize(at);
  }
  // Seconds a load (printed with an SI prefix: "36n" is 36 ns).
  state.counters["per_load"] =
      benchmark::Counter(static_cast<double>(state.iterations() * kLoadsPerIteration),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
// Up to 2 GiB: a world of 10⁷ balls holds about 1.2 GiB.
BENCHMARK(BM_DependentLoad)->RangeMultiplier(2)->Range(1, 2048)->Unit(benchmark::kMicrosecond);

// The cycle of BM_ParallelLoads, shared by its seven chain counts and laid out by the first of
// them to run: laying it out takes longer than measuring (seconds; far longer under a sanitizer,
// in the suite's smoke run). It stays allocated until the process ends.
struct Cycle {
  static constexpr std::size_t kCount = (std::size_t{256} << 20) / sizeof(Line);
  std::unique_ptr<Line[], FreeMemory> lines = huge_page_lines(kCount);
  std::vector<std::size_t> order = std::vector<std::size_t>(kCount);  // the lines in cycle order
  Cycle() {
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::shuffle(order.begin(), order.end(), std::mt19937_64(20261201));
    for (std::size_t k = 0; k < kCount; ++k) {
      lines[order[k]].next = &lines[order[(k + 1) % kCount]];
    }
  }
};

const Cycle& shared_cycle() {
  static const Cycle cycle;
  return cycle;
}

// The same random cycle through 256 MiB (all in memory), walked by `kChains` independent chains
// at once, spread evenly along it: the processor overlaps their misses, as many as it keeps in
// flight. per_line is the time a line then, the least a memory-bound loop pays for each line
// it needs however early it asks for it (docs/decisions/0013-lookahead-in-large-worlds.md).
template <std::size_t kChains>
void BM_ParallelLoads(benchmark::State& state) {
  const Cycle& cycle = shared_cycle();
  constexpr std::size_t kCount = Cycle::kCount;
  const Line* at[kChains];
  for (std::size_t c = 0; c < kChains; ++c) {
    at[c] = &cycle.lines[cycle.order[c * (kCount / kChains)]];
  }
  constexpr std::size_t kStepsPerIteration = 4096 / kChains;
  for (auto _ : state) {
    for (std::size_t k = 0; k < kStepsPerIteration; ++k) {
      for (std::size_t c = 0; c < kChains; ++c) at[c] = at[c]->next;
    }
    benchmark::DoNotOptimize(at);
  }
  state.counters["per_line"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * static_cast<double>(kStepsPerIteration * kChains),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ParallelLoads<1>)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ParallelLoads<2>)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ParallelLoads<4>)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ParallelLoads<8>)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ParallelLoads<16>)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ParallelLoads<32>)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ParallelLoads<64>)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace carom::bench
