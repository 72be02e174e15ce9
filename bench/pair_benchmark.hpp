// carom benchmarks: what every time-of-impact benchmark shares, the batch sizes and how a
// benchmark reports its pairs, bytes and hits, so that the figures compare across benchmarks.
#pragma once

#include <benchmark/benchmark.h>

#include <cstddef>

namespace carom::bench {

// The pairs' arrays take 88 bytes per pair, so 4096 pairs (352 KiB) stay in the L2 cache of one
// core (1 MiB on the Zen 4 of docs/performance.md) ...
inline constexpr std::size_t kInCachePairs = 4096;
// ... and 10^6 pairs (88 MB) are far beyond the 32 MiB L3: every run streams them from memory.
inline constexpr std::size_t kMemoryBoundPairs = 1'000'000;

// Read per pair: ten doubles (A's and B's x, y, radius, move x, move y). Written: t, one double.
// The cache's read of t's line before the write (write-allocate) is not counted, in line with
// the copy benchmarks, which count the bytes copied twice (read and written) and no more.
inline constexpr std::size_t kBytesReadPerPair = 10 * sizeof(double);
inline constexpr std::size_t kBytesWrittenPerPair = sizeof(double);
inline constexpr std::size_t kBytesPerPair = kBytesReadPerPair + kBytesWrittenPerPair;

// Both batch sizes, as the benchmark's "pairs" argument.
void pair_counts(benchmark::internal::Benchmark* registered);

// Sets items (pairs) and bytes processed for the benchmark's iterations of `pairs` pairs each,
// and the counter hit_rate: the fraction of the pairs that touch during the step.
void report_pairs(benchmark::State& state, std::size_t pairs, std::size_t hits);

}  // namespace carom::bench
