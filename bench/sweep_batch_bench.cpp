// carom benchmarks: carom::sweep_ball_ball_batch, the vectorised two-moving-balls time of
// impact, on the shared random pairs. Before timing, it checks that the batch answers every pair
// exactly as the scalar query does, so the figure is never that of a wrong kernel.
#include <benchmark/benchmark.h>

#include <bit>
#include <cstdint>

#include "cache_line_allocator.hpp"
#include "carom/sweep_batch.hpp"
#include "pair_benchmark.hpp"
#include "random_pairs.hpp"
#include "scalar_reference.hpp"

namespace carom::bench {
namespace {

// True when t holds, for every pair, sweep_ball_ball's answer bit for bit.
bool matches_scalar(const RandomPairs& pairs, const Column& t) {
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(t[i]) != std::bit_cast<std::uint64_t>(scalar_t(pairs, i))) {
      return false;
    }
  }
  return true;
}

void BM_SweepBatch(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  const RandomPairs& pairs = shared_random_pairs(count);
  const BallPairArrays arrays = pairs.arrays();
  Column t(count);
  std::size_t hits = sweep_ball_ball_batch(arrays, t);
  if (!matches_scalar(pairs, t)) {
    state.SkipWithError("sweep_ball_ball_batch differs from sweep_ball_ball");
    return;
  }
  for (auto _ : state) {
    hits = sweep_ball_ball_batch(arrays, t);
    benchmark::DoNotOptimize(hits);
    benchmark::ClobberMemory();  // t is written every iteration, not once
  }
  report_pairs(state, count, hits);
}
BENCHMARK(BM_SweepBatch)->Apply(pair_counts)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace carom::bench
