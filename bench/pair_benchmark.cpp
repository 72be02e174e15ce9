// carom benchmarks: the batch sizes and counters every time-of-impact benchmark shares.
#include "pair_benchmark.hpp"

#include <cstdint>

namespace carom::bench {

void pair_counts(benchmark::internal::Benchmark* registered) {
  registered->ArgName("pairs");
  registered->Arg(static_cast<std::int64_t>(kInCachePairs));
  registered->Arg(static_cast<std::int64_t>(kMemoryBoundPairs));
}

void report_pairs(benchmark::State& state, std::size_t pairs, std::size_t hits) {
  const auto iterations = static_cast<std::int64_t>(state.iterations());
  const auto per_iteration = static_cast<std::int64_t>(pairs);
  state.SetItemsProcessed(iterations * per_iteration);
  state.SetBytesProcessed(iterations * per_iteration * static_cast<std::int64_t>(kBytesPerPair));
  state.counters["hit_rate"] = static_cast<double>(hits) / static_cast<double>(pairs);
}

}  // namespace carom::bench
