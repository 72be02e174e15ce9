// carom benchmarks: carom::sweep_ball_ball, the scalar two-moving-balls query, called pair by
// pair on the arrays the batch benchmark reads, and writing the same t. It computes the full
// Impact (contact positions, normal and point) as well, which is what a caller of the scalar
// query pays for.
#include <benchmark/benchmark.h>

#include "cache_line_allocator.hpp"
#include "carom/sweep_batch.hpp"
#include "pair_benchmark.hpp"
#include "random_pairs.hpp"
#include "scalar_reference.hpp"

namespace carom::bench {
namespace {

void BM_SweepScalar(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  const RandomPairs& pairs = shared_random_pairs(count);
  Column t(count);
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (std::size_t i = 0; i < count; ++i) {
      t[i] = scalar_t(pairs, i);
      hits += t[i] != kNoHit ? 1u : 0u;
    }
    benchmark::DoNotOptimize(hits);
    benchmark::ClobberMemory();
  }
  report_pairs(state, count, hits);
}
BENCHMARK(BM_SweepScalar)->Apply(pair_counts)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace carom::bench
