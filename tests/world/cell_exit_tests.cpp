// Prediction's cell exit (src/cell_exit.hpp): the SSE2 form against the scalar one, bit for bit,
// on random balls and sides with the cases prediction meets at the edges: velocities of zero
// (either sign) along an axis, sides at ±infinity (a box's outer cells), a ball already past its
// side (an exit at once), and ties between the axes.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <limits>
#include <random>

#include "world/cell_exit.hpp"

namespace carom {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

double component(std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  switch (random() % 6) {
    case 0:
      return 0.0;
    case 1:
      return -0.0;
    default:
      return unit(random) * 3.0;
  }
}

double side_for(std::mt19937_64& random, double position, double velocity) {
  std::uniform_real_distribution<double> ahead(0.0, 2.0);
  switch (random() % 8) {
    case 0:
      return velocity > 0.0 ? kNever : -kNever;
    case 1:
      return position;  // on the side
    case 2:
      return position - (velocity > 0.0 ? 0.5 : -0.5);  // past it
    default:
      return position + (velocity > 0.0 ? ahead(random) : -ahead(random));
  }
}

TEST(CellExit, MatchesTheScalarFormBitForBit) {
  std::mt19937_64 random(20261201);
  int through_x = 0;
  int through_y = 0;
  int never = 0;
  for (int round = 0; round < 200000; ++round) {
    const Vec2 p{component(random) * 10.0, component(random) * 10.0};
    const Vec2 v{component(random), component(random)};
    const double now = (random() % 2 == 0) ? 0.0 : 12.5;
    const double side_x = side_for(random, p.x, v.x);
    double side_y = side_for(random, p.y, v.y);
    // Ties between the axes: the same distance at the same speed.
    if (random() % 16 == 0) {
      side_y = p.y + (side_x - p.x) / v.x * v.y;
    }
    const detail::CellExit expected = detail::cell_exit_scalar(p, v, now, side_x, side_y);
    const detail::CellExit got = detail::cell_exit(p, v, now, side_x, side_y);
    ASSERT_EQ(std::bit_cast<std::uint64_t>(got.time), std::bit_cast<std::uint64_t>(expected.time))
        << "round " << round << ": " << got.time << " vs " << expected.time;
    ASSERT_EQ(got.side, expected.side) << "round " << round;
    if (expected.time == kNever) {
      ++never;
    } else if (expected.side == detail::kLeft || expected.side == detail::kRight) {
      ++through_x;
    } else {
      ++through_y;
    }
  }
  EXPECT_GT(through_x, 10000);
  EXPECT_GT(through_y, 10000);
  EXPECT_GT(never, 1000);
}

TEST(CellExit, LeavesThroughTheEarlierSideAndNeverThroughAnAxisItDoesNotMoveAlong) {
  const detail::CellExit right = detail::cell_exit({0.0, 0.0}, {1.0, 0.5}, 2.0, 1.0, 1.0);
  EXPECT_EQ(right.time, 3.0);
  EXPECT_EQ(right.side, detail::kRight);
  const detail::CellExit down = detail::cell_exit({0.0, 0.0}, {-1.0, -4.0}, 0.0, -1.0, -1.0);
  EXPECT_EQ(down.time, 0.25);
  EXPECT_EQ(down.side, detail::kDown);
  const detail::CellExit tie = detail::cell_exit({0.0, 0.0}, {1.0, 1.0}, 0.0, 1.0, 1.0);
  EXPECT_EQ(tie.side, detail::kRight);  // x first on a tie
  const detail::CellExit still = detail::cell_exit({0.0, 0.0}, {0.0, -0.0}, 0.0, 1.0, -1.0);
  EXPECT_EQ(still.time, kNever);
  const detail::CellExit boxed = detail::cell_exit({0.0, 0.0}, {1.0, 0.0}, 0.0, kNever, 1.0);
  EXPECT_EQ(boxed.time, kNever);
  const detail::CellExit past = detail::cell_exit({2.0, 0.0}, {1.0, 0.0}, 5.0, 1.0, 1.0);
  EXPECT_EQ(past.time, 5.0);  // already past its side: at once
}

}  // namespace
}  // namespace carom
