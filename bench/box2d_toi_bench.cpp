// carom benchmarks: Box2D 2.4's b2TimeOfImpact on the pairs the carom benchmarks read, for a
// side-by-side figure. Box2D answers nearly the same question by conservative advancement: it
// iterates distance queries, in single precision, until the centres are 3·b2_linearSlop (1.5 cm)
// closer than contact. Each pair is handed over in the form Box2D's solver uses: two circle
// proxies and two sweeps from c0 (the start) to c (the start plus the movement), built in the
// loop from the same arrays and writing the same t, so the timed work reads and writes what
// carom's does.
#include <benchmark/benchmark.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_time_of_impact.h>

#include "cache_line_allocator.hpp"
#include "carom/sweep_batch.hpp"
#include "pair_benchmark.hpp"
#include "random_pairs.hpp"

namespace carom::bench {
namespace {

// A sweep without rotation from `at` to `at + move`, over the whole step.
b2Sweep straight_sweep(double at_x, double at_y, double move_x, double move_y) {
  b2Sweep sweep;
  sweep.localCenter.SetZero();
  sweep.c0.Set(static_cast<float>(at_x), static_cast<float>(at_y));
  sweep.c.Set(static_cast<float>(at_x + move_x), static_cast<float>(at_y + move_y));
  sweep.a0 = 0.0f;
  sweep.a = 0.0f;
  sweep.alpha0 = 0.0f;
  return sweep;
}

void BM_Box2DTimeOfImpact(benchmark::State& state) {
  const auto count = static_cast<std::size_t>(state.range(0));
  const RandomPairs& p = shared_random_pairs(count);
  Column t(count);
  // Circles at their body's origin; only the radius changes from pair to pair.
  b2CircleShape circle_a;
  b2CircleShape circle_b;
  b2TOIInput input;
  input.tMax = 1.0f;  // the whole step
  std::size_t hits = 0;
  std::size_t failures = 0;
  for (auto _ : state) {
    hits = 0;
    failures = 0;
    for (std::size_t i = 0; i < count; ++i) {
      circle_a.m_radius = static_cast<float>(p.a_radius[i]);
      circle_b.m_radius = static_cast<float>(p.b_radius[i]);
      input.proxyA.Set(&circle_a, 0);
      input.proxyB.Set(&circle_b, 0);
      input.sweepA = straight_sweep(p.a_x[i], p.a_y[i], p.a_move_x[i], p.a_move_y[i]);
      input.sweepB = straight_sweep(p.b_x[i], p.b_y[i], p.b_move_x[i], p.b_move_y[i]);
      b2TOIOutput output;
      b2TimeOfImpact(&output, &input);
      switch (output.state) {
        case b2TOIOutput::e_touching:
          t[i] = output.t;
          ++hits;
          break;
        case b2TOIOutput::e_overlapped:
          t[i] = 0.0;
          ++hits;
          break;
        case b2TOIOutput::e_failed:  // gave up after its iteration limit; t is its best guess
          t[i] = output.t;
          ++failures;
          break;
        default:
          t[i] = kNoHit;
          break;
      }
    }
    benchmark::DoNotOptimize(hits);
    benchmark::ClobberMemory();
  }
  report_pairs(state, count, hits);
  state.counters["failed_rate"] = static_cast<double>(failures) / static_cast<double>(count);
}
BENCHMARK(BM_Box2DTimeOfImpact)->Apply(pair_counts)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace carom::bench
