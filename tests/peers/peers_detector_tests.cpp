// The peers benchmark's own checks (bench/peers/detectors.hpp) must be able to fail: each is
// shown a synthetic trajectory with a planted fault and must report it, and a clean one and
// report nothing. Then carom's world on a small gas must come out clean, as it promises.
#include <gtest/gtest.h>

#include <vector>

#include "detectors.hpp"
#include "pair_grid.hpp"
#include "run_case.hpp"
#include "scene.hpp"

namespace carom::peers {
namespace {

const Vec2 kLower{-10.0, -10.0};
const Vec2 kUpper{10.0, 10.0};

TEST(PeersOverlap, ReportsAPlantedOverlapAsAFractionOfTheSumOfRadii) {
  // Radii 0.5 and 0.5, centres 0.9 apart: 0.1 of the sum of radii overlaps. A third disk far off.
  const std::vector<Vec2> positions{{0.0, 0.0}, {0.9, 0.0}, {5.0, 5.0}};
  const std::vector<double> radii{0.5, 0.5, 0.5};
  Detectors detectors;
  EXPECT_NEAR(detectors.largest_overlap(positions, radii, kLower, kUpper), 0.1, 1e-12);
}

TEST(PeersOverlap, ReportsNothingForDisksApartOrJustTouching) {
  const std::vector<Vec2> positions{{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.5}};
  const std::vector<double> radii{0.5, 0.5, 0.5};
  Detectors detectors;
  EXPECT_EQ(detectors.largest_overlap(positions, radii, kLower, kUpper), 0.0);
}

TEST(PeersOverlap, FindsTheDeepestPairAmongManyAcrossCellBorders) {
  // A row of 200 disks 1.01 apart (no overlap) with one pair planted 0.7 apart where the grid's
  // cells meet; every pair crosses some cell border, so a wrong de-duplication would miss it.
  std::vector<Vec2> positions;
  std::vector<double> radii;
  for (int i = 0; i < 200; ++i) {
    positions.push_back({-9.5 + 0.095 * i, -9.0 + 0.09 * (i % 7)});
    radii.push_back(0.04);
  }
  positions.push_back({0.0, 0.0});
  positions.push_back({0.07, 0.0});
  radii.push_back(0.05);
  radii.push_back(0.05);
  Detectors detectors;
  EXPECT_NEAR(detectors.largest_overlap(positions, radii, kLower, kUpper), 0.3, 1e-12);
}

TEST(PeersPassThrough, ReportsTwoDisksThatSwappedSidesInOneStep) {
  // Head on, each moving 3 (more than the sum of radii): apart at both ends, through in between.
  const std::vector<Vec2> start{{-1.5, 0.0}, {1.5, 0.0}, {5.0, 5.0}};
  const std::vector<Vec2> end{{1.5, 0.0}, {-1.5, 0.0}, {5.0, 5.0}};
  const std::vector<double> radii{0.5, 0.5, 0.5};
  Detectors detectors;
  const std::vector<PassThrough> found =
      detectors.find_pass_throughs(start, end, radii, {}, kLower, kUpper);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].a, 0u);
  EXPECT_EQ(found[0].b, 1u);
  EXPECT_NEAR(found[0].depth, 1.0, 1e-12);  // straight through each other's centre
}

TEST(PeersPassThrough, ReportsABulletThroughAStillDisk) {
  // A small fast disk crossing a resting one off-centre, as the bullets scene's tunnelling does.
  const std::vector<Vec2> start{{-8.0, 0.3}, {0.0, 0.0}};
  const std::vector<Vec2> end{{9.0, 0.3}, {0.0, 0.0}};
  const std::vector<double> radii{0.05, 0.5};
  Detectors detectors;
  const std::vector<PassThrough> found =
      detectors.find_pass_throughs(start, end, radii, {}, kLower, kUpper);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0].depth, 1.0 - 0.3 / 0.55, 1e-12);  // 0.3 off the centre, radii 0.55
}

TEST(PeersPassThrough, IgnoresAPairThatBouncedOrIsStillInContact) {
  // Pair 0–1 met and came back (the chord of an elastic bounce never enters the contact disc);
  // pair 2–3 ends overlapping, a late contact that the overlap check reports instead; pair 4–5
  // passes close by without touching.
  const std::vector<Vec2> start{{-3.0, 0.0}, {-1.0, 0.0},  {2.0, 3.0},
                                {4.0, 3.0},  {-5.0, -5.0}, {-5.0, -3.0}};
  const std::vector<Vec2> end{{-3.2, 0.0}, {-0.8, 0.0},  {2.6, 3.0},
                              {3.4, 3.0},  {-4.0, -5.0}, {-6.0, -3.9}};
  const std::vector<double> radii{0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
  Detectors detectors;
  EXPECT_TRUE(detectors.find_pass_throughs(start, end, radii, {}, kLower, kUpper).empty());
}

TEST(PeersPassThrough, FollowsAPathBentByAContactWithinTheStep) {
  // Disk 0 goes to the right wall, bounces at a quarter of the step at (4.8, 1) and comes back up
  // to (0, 2): the straight line from its start to its end goes through disk 1 at (0, 1), its
  // real path stays about 0.98 away. Told of the bend, the check follows the two pieces.
  const std::vector<Vec2> start{{0.0, 0.0}, {0.0, 1.0}};
  const std::vector<Vec2> end{{0.0, 2.0}, {0.0, 1.0}};
  const std::vector<double> radii{0.2, 0.3};
  const std::vector<PathBreak> bend{{0, 0.25, {4.8, 1.0}}};
  Detectors detectors;
  EXPECT_EQ(detectors.find_pass_throughs(start, end, radii, {}, kLower, kUpper).size(), 1u);
  EXPECT_TRUE(detectors.find_pass_throughs(start, end, radii, bend, kLower, kUpper).empty());
  // A bend that does not avoid the disk: the first piece goes through it.
  const std::vector<PathBreak> through{{0, 0.5, {0.0, 3.0}}};
  EXPECT_EQ(detectors.find_pass_throughs(start, end, radii, through, kLower, kUpper).size(), 1u);
}

TEST(PeersPassThrough, SkipsNonFiniteDisksAndCountsThem) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Vec2> start{{-1.5, 0.0}, {nan, 0.0}};
  const std::vector<Vec2> end{{1.5, 0.0}, {0.0, 0.0}};
  const std::vector<double> radii{0.5, 0.5};
  Detectors detectors;
  EXPECT_TRUE(detectors.find_pass_throughs(start, end, radii, {}, kLower, kUpper).empty());
  EXPECT_EQ(detectors.non_finite(), 1u);
}

TEST(PeersBox, CountsACentreOutsideTheBoxAndNaN) {
  EXPECT_FALSE(outside_box({9.9, -9.9}, kLower, kUpper));
  EXPECT_TRUE(outside_box({10.1, 0.0}, kLower, kUpper));
  EXPECT_TRUE(outside_box({0.0, std::numeric_limits<double>::quiet_NaN()}, kLower, kUpper));
}

TEST(PeersScene, TheGasStartsWithoutOverlapInsideTheBoxAtTheAskedPacking) {
  for (const double packing : {0.2, 0.5}) {
    const Scene scene = make_gas_scene(1000, packing, 1);
    std::vector<Vec2> positions;
    std::vector<double> radii;
    double area = 0.0;
    for (const SceneBall& ball : scene.balls) {
      positions.push_back(ball.position);
      radii.push_back(ball.radius);
      area += 3.141592653589793 * ball.radius * ball.radius;
      ASSERT_GE(ball.position.x - ball.radius, scene.lower.x);
      ASSERT_LE(ball.position.y + ball.radius, scene.upper.y);
    }
    Detectors detectors;
    EXPECT_EQ(detectors.largest_overlap(positions, radii, scene.lower, scene.upper), 0.0);
    const Vec2 size = scene.upper - scene.lower;
    EXPECT_NEAR(area / (size.x * size.y), packing, 1e-12);
  }
}

// carom on a small gas at the denser packing: its guarantees as the harness measures them. The
// overlap bound 1e-9 is the world's own audit tolerance (World::audit); rounding of a contact
// placed exactly at the sum of radii leaves overlaps near 1e-16.
TEST(PeersCarom, ASmallGasComesOutCleanOnEveryCheck) {
  CaseSpec spec;
  spec.engine = "carom";
  spec.n = 400;
  spec.packing = 0.5;
  spec.steps = 60;
  const CaseResult result = run_case(spec);
  EXPECT_EQ(result.balls, 400u);
  EXPECT_LT(result.largest_overlap, 1e-9);
  EXPECT_EQ(result.pass_throughs, 0u);
  EXPECT_EQ(result.left_box, 0u);
  EXPECT_EQ(result.non_finite, 0u);
  EXPECT_LT(std::abs(result.energy_drift), 1e-12);
  EXPECT_GT(result.contacts, 0);  // the gas did collide: the checks had work to do
}

TEST(PeersCarom, NoBulletGoesThroughTheField) {
  CaseSpec spec;
  spec.engine = "carom";
  spec.scene = "bullets";
  spec.steps = 2;
  const CaseResult result = run_case(spec);
  EXPECT_EQ(result.bullets_through, 0u);
  EXPECT_EQ(result.pass_throughs, 0u);
  EXPECT_EQ(result.left_box, 0u);
}

TEST(PeersResultLine, RoundTrips) {
  CaseResult result;
  result.spec.engine = "chipmunk";
  result.spec.n = 10000;
  result.spec.packing = 0.5;
  result.median_step_ms = 2.75;
  result.energy_drift = -3.5e-7;
  result.pass_throughs = 12;
  result.contacts = -1;
  const std::optional<CaseResult> back = parse_line(to_line(result));
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->spec.engine, "chipmunk");
  EXPECT_EQ(back->spec.n, 10000u);
  EXPECT_EQ(back->spec.packing, 0.5);
  EXPECT_EQ(back->median_step_ms, 2.75);
  EXPECT_EQ(back->energy_drift, -3.5e-7);
  EXPECT_EQ(back->pass_throughs, 12u);
  EXPECT_EQ(back->contacts, -1);
  EXPECT_FALSE(parse_line("engine=carom broken").has_value());
}

}  // namespace
}  // namespace carom::peers
