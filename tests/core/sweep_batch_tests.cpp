// The batch kernel answers exactly as the scalar sweep_ball_ball, pair by pair.
#include <gtest/gtest.h>

#include <vector>

#include "carom/sweep.hpp"
#include "carom/sweep_batch.hpp"
#include "random_cases.hpp"

namespace carom {
namespace {

struct PairColumns {
  std::vector<double> a_x, a_y, a_r, a_mx, a_my, b_x, b_y, b_r, b_mx, b_my;

  void add(const Ball& a, Vec2 move_a, const Ball& b, Vec2 move_b) {
    a_x.push_back(a.center.x);
    a_y.push_back(a.center.y);
    a_r.push_back(a.radius);
    a_mx.push_back(move_a.x);
    a_my.push_back(move_a.y);
    b_x.push_back(b.center.x);
    b_y.push_back(b.center.y);
    b_r.push_back(b.radius);
    b_mx.push_back(move_b.x);
    b_my.push_back(move_b.y);
  }
  BallPairArrays view() const { return {a_x, a_y, a_r, a_mx, a_my, b_x, b_y, b_r, b_mx, b_my}; }
};

TEST(SweepBallBallBatch, BitIdenticalToScalar) {
  testing::RandomCases random(31);
  PairColumns columns;
  std::vector<Impact> expected;
  constexpr int kPairs = 100'003;  // not a multiple of any vector width: the tail runs too
  for (int i = 0; i < kPairs; ++i) {
    const Ball a = random.ball(10.0);
    const Ball b = random.ball(10.0);
    const Vec2 move_a = random.move_towards(a.center, b.center, 4.0);
    const Vec2 move_b = random.point(6.0);
    columns.add(a, move_a, b, move_b);
    expected.push_back(sweep_ball_ball(a, move_a, b, move_b));
  }
  // The edges too: touching and separating, touching and approaching, overlapping both ways,
  // coincident centres, no relative motion, an exact graze.
  const Ball unit{{0.0, 0.0}, 1.0};
  const std::vector<std::pair<Vec2, Vec2>> edges = {
      {{2.0, 0.0}, {-1.0, 0.0}}, {{2.0, 0.0}, {1.0, 0.0}}, {{1.5, 0.0}, {1.0, 0.0}},
      {{1.5, 0.0}, {-1.0, 0.0}}, {{0.0, 0.0}, {0.0, 1.0}}, {{3.0, 0.0}, {0.0, 0.0}}};
  for (const auto& [b_center, move_a] : edges) {
    columns.add(unit, move_a, {b_center, 1.0}, {});
    expected.push_back(sweep_ball_ball(unit, move_a, {b_center, 1.0}));
  }
  columns.add(unit, {10.0, 0.0}, {{5.0, 2.0}, 1.0}, {});
  expected.push_back(sweep_ball_ball(unit, {10.0, 0.0}, {{5.0, 2.0}, 1.0}));

  std::vector<double> t(expected.size());
  const std::size_t hits = sweep_ball_ball_batch(columns.view(), t);
  std::size_t expected_hits = 0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    if (expected[i].hit) {
      ++expected_hits;
      ASSERT_EQ(t[i], expected[i].t) << "pair " << i;
    } else {
      ASSERT_EQ(t[i], kNoHit) << "pair " << i;
    }
  }
  EXPECT_EQ(hits, expected_hits);
  EXPECT_GT(hits, expected.size() / 8);
}

TEST(SweepBallBallBatch, EmptyBatch) { EXPECT_EQ(sweep_ball_ball_batch({}, {}), 0u); }

}  // namespace
}  // namespace carom
