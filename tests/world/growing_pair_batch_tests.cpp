// The growing world's batched pair solver (src/world/growing_pair_batch.hpp) against the scalar
// closed form it batches (core/growing_pair.hpp): the same answer, bit for bit, on random pairs
// of every scale, including pairs touching, keeping pace with their growth, and outside the
// closed form's window of magnitudes.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>

#include "core/growing_pair.hpp"
#include "world/growing_pair_batch.hpp"

namespace carom {
namespace {

// A coordinate or speed: mostly ordinary, sometimes zero, tiny or huge (outside the window).
double growing_coordinate(std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  switch (random() % 8) {
    case 0:
      return 0.0;
    case 1:
      return unit(random) * 1e-200;
    case 2:
      return unit(random) * 1e200;
    default:
      return unit(random) * 10.0;
  }
}

double growing_magnitude(std::mt19937_64& random, double least, double most) {
  std::uniform_real_distribution<double> size(least, most);
  switch (random() % 12) {
    case 0:
      return 1e-160;
    case 1:
      return 1e160;
    default:
      return size(random);
  }
}

// solve (four pairs a vector operation where the CPU has AVX2) and solve_one_by_one, on batches
// of every size from 1 to full.
void check_growing_batch_solver(void (detail::GrowingPairBatch::*solver)()) {
  std::mt19937_64 random(20261205);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  detail::GrowingPairBatch batch;
  int closings = 0;
  int never = 0;
  int undecided = 0;
  for (int round = 0; round < 4000; ++round) {
    batch.count = 0;
    const std::size_t size = 1 + random() % detail::GrowingPairBatch::kCapacity;
    while (batch.count < size) {
      Vec2 s{growing_coordinate(random), growing_coordinate(random)};
      Vec2 u{growing_coordinate(random), growing_coordinate(random)};
      const double reach = growing_magnitude(random, 0.1, 10.0);
      const double growth = growing_magnitude(random, 1e-6, 3.0);
      switch (random() % 6) {
        case 0:  // touching, parting or closing (a pair that has just met, or is meeting)
          s = Vec2{reach, 0.0};
          u = Vec2{unit(random) * 5.0, unit(random)};
          break;
        case 1:  // parting exactly as fast as the radii grow
          s = Vec2{2.0 * reach, 0.0};
          u = Vec2{growth, 0.0};
          break;
        default:
          break;
      }
      batch.push(s, u, reach, growth, static_cast<std::uint32_t>(batch.count));
    }
    (batch.*solver)();
    for (std::size_t k = 0; k < batch.count; ++k) {
      const detail::GrowingPairClosing expected = detail::growing_pair_closing(
          {batch.sx[k], batch.sy[k]}, {batch.ux[k], batch.uy[k]}, batch.reach[k], batch.growth[k]);
      const bool closes = ((batch.closings >> k) & 1U) != 0;
      const bool open = ((batch.undecided >> k) & 1U) != 0;
      ASSERT_EQ(open, !expected.decided) << "round " << round << ", pair " << k;
      ASSERT_EQ(closes, expected.found) << "round " << round << ", pair " << k;
      if (expected.found) {
        ASSERT_EQ(std::bit_cast<std::uint64_t>(batch.t[k]),
                  std::bit_cast<std::uint64_t>(expected.t))
            << "round " << round << ", pair " << k << ": " << batch.t[k] << " vs " << expected.t;
        ++closings;
      } else if (expected.decided) {
        ++never;
      } else {
        ++undecided;
      }
    }
  }
  // The sample reached every outcome.
  EXPECT_GT(closings, 2000);
  EXPECT_GT(never, 5000);
  EXPECT_GT(undecided, 5000);
}

TEST(GrowingPairBatch, SolvesEveryPairAsTheScalarClosedForm) {
  check_growing_batch_solver(&detail::GrowingPairBatch::solve);
}

TEST(GrowingPairBatch, SolvesEveryPairOneByOneAsTheScalarClosedForm) {
  check_growing_batch_solver(&detail::GrowingPairBatch::solve_one_by_one);
}

}  // namespace
}  // namespace carom
