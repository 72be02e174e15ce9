// Small scenes whose outcome is known exactly: Newton's cradle, a billiards break, corners,
// grazing along a wall, contacts at time 0, fast head-on balls, bowls, rotated walls, a closed box.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "carom/world.hpp"

namespace carom {
namespace {

constexpr double kScenarioStep = 1.0 / 60.0;
// Outcomes that are exact in real arithmetic hold to a few roundings of the speeds involved.
constexpr double kRoundingTol = 1e-12;
// "Inside" and "no overlap" allow the audit's default: 1e-9 of the radius (world.hpp).
constexpr double kOverlapTol = 1e-9;

BallDef ball_at(Vec2 position, Vec2 velocity, double radius = 0.5) {
  BallDef def;
  def.position = position;
  def.velocity = velocity;
  def.radius = radius;
  return def;
}

void expect_near(Vec2 got, Vec2 expected, double tolerance, const char* what) {
  EXPECT_NEAR(got.x, expected.x, tolerance) << what;
  EXPECT_NEAR(got.y, expected.y, tolerance) << what;
}

// ---- Newton's cradle -------------------------------------------------------------------------

TEST(WorldScenario, NewtonsCradlePassesTheStrikeToTheLastBall) {
  constexpr double kSpeed = 3.0;
  World world;
  const BallId striker = world.add_ball(ball_at({-3.0, 0.0}, {kSpeed, 0.0}));
  std::array<BallId, 5> row;
  for (int i = 0; i < 5; ++i)
    row[static_cast<std::size_t>(i)] = world.add_ball(ball_at({i * 1.0, 0.0}, {}));

  world.run_until(2.0);  // the striker's centre reaches −1 at t = 2/3
  const double strike_time = 2.0 / kSpeed;

  // Five contacts at the same instant, passed along the row in the documented order.
  const auto contacts = world.contacts();
  ASSERT_EQ(contacts.size(), 5u);
  std::array<BallId, 6> chain{striker, row[0], row[1], row[2], row[3], row[4]};
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    EXPECT_EQ(contacts[k].kind, ContactKind::ball_ball);
    EXPECT_NEAR(contacts[k].time, strike_time, kRoundingTol);
    EXPECT_EQ(contacts[k].a, chain[k]) << "contact " << k;
    EXPECT_EQ(contacts[k].b, chain[k + 1]) << "contact " << k;
  }
  expect_near(world.velocity(row[4]), {kSpeed, 0.0}, kRoundingTol * kSpeed, "last ball");
  expect_near(world.velocity(striker), {}, kRoundingTol * kSpeed, "striker");
  for (int i = 0; i < 4; ++i) {
    expect_near(world.velocity(row[static_cast<std::size_t>(i)]), {}, kRoundingTol * kSpeed,
                "a ball in the middle");
    expect_near(world.position(row[static_cast<std::size_t>(i)]), {i * 1.0, 0.0}, kRoundingTol,
                "a ball in the middle");
  }
  expect_near(world.position(row[4]), {4.0 + kSpeed * (2.0 - strike_time), 0.0},
              kRoundingTol * kSpeed, "last ball");
}

// ---- billiards break -------------------------------------------------------------------------

// A rack of 15 balls cannot touch exactly in doubles (rows sit √3·r apart), so neighbours are
// set this fraction of a diameter apart: far above rounding, far below anything visible.
constexpr double kRackGap = 1e-12;

struct RackedTable {
  World world;
  std::vector<BallId> balls;  // the cue ball first
};

RackedTable billiards_break(double cue_speed, double cue_offset) {
  constexpr double kRadius = 0.5;
  RackedTable table{World(WorldDef{Boundary::box, {0.0, 0.0}, {40.0, 20.0}}), {}};
  table.balls.push_back(table.world.add_ball(ball_at({8.0, 10.0 + cue_offset}, {cue_speed, 0.0})));
  const double pitch = 2.0 * kRadius * (1.0 + kRackGap);
  for (int row = 0; row < 5; ++row) {
    for (int k = 0; k <= row; ++k) {
      const Vec2 at{28.0 + row * pitch * std::sqrt(3.0) / 2.0, 10.0 + (k - 0.5 * row) * pitch};
      table.balls.push_back(table.world.add_ball(ball_at(at, {})));
    }
  }
  return table;
}

TEST(WorldScenario, BilliardsBreakConservesEnergyAndMomentumAndNeverOverlaps) {
  constexpr double kCueSpeed = 60.0;
  // Off the rack's axis by a little: not symmetric, yet a dense cascade of near-ties.
  RackedTable table = billiards_break(kCueSpeed, 1e-3);
  World& world = table.world;
  const double energy = world.kinetic_energy();
  const Vec2 momentum = world.momentum();

  bool wall_reached = false;
  int ball_contacts_before_wall = 0;
  constexpr int kSteps = 600;
  for (int s = 0; s < kSteps; ++s) {
    world.step(kScenarioStep);
    const auto audit = world.audit();
    ASSERT_FALSE(audit.has_value()) << "step " << s << ": " << *audit;
    // Energy: each elastic bounce rounds it by ~1e-16; thousands of them stay far below 1e-12.
    ASSERT_NEAR(world.kinetic_energy(), energy, kRoundingTol * energy) << "step " << s;
    for (const ContactEvent& c : world.contacts()) {
      if (c.kind == ContactKind::ball_wall) wall_reached = true;
      if (!wall_reached) ++ball_contacts_before_wall;
    }
    if (!wall_reached) {
      // Balls alone exchange momentum: |p| is the cue's, the natural scale.
      const double scale = length(momentum);
      ASSERT_NEAR(world.momentum().x, momentum.x, kRoundingTol * scale) << "step " << s;
      ASSERT_NEAR(world.momentum().y, momentum.y, kRoundingTol * scale) << "step " << s;
    }
  }
  EXPECT_TRUE(wall_reached);
  EXPECT_GE(ball_contacts_before_wall, 15);  // the rack really broke before any wall was hit
  EXPECT_GT(world.collision_count(), 100u);
}

TEST(WorldScenario, StraightOnBreakResolvesItsTiesWithoutOverlap) {
  // Exactly on the axis: the rack's mirror symmetry makes contacts tie in time.
  RackedTable table = billiards_break(60.0, 0.0);
  for (int s = 0; s < 120; ++s) {
    table.world.step(kScenarioStep);
    const auto audit = table.world.audit();
    ASSERT_FALSE(audit.has_value()) << "step " << s << ": " << *audit;
    const auto contacts = table.world.contacts();
    for (std::size_t k = 1; k < contacts.size(); ++k) {
      ASSERT_LE(contacts[k - 1].time, contacts[k].time) << "step " << s;
    }
  }
  EXPECT_GT(table.world.collision_count(), 15u);
}

// ---- corners ---------------------------------------------------------------------------------

TEST(WorldScenario, BallIntoABoxCornerComesOutReversed) {
  World world(WorldDef{Boundary::box, {0.0, 0.0}, {10.0, 10.0}});
  // Reaches x = 9 and y = 9 together at t = 1: it meets both walls in the corner at once.
  const BallId ball = world.add_ball(ball_at({3.0, 6.0}, {6.0, 3.0}, 1.0));
  world.run_until(1.5);
  const auto contacts = world.contacts();
  ASSERT_EQ(contacts.size(), 2u);
  // Same time, same kind, same ball: by wall id, the right side (1) before the top (2).
  EXPECT_EQ(contacts[0].wall, 1u);
  EXPECT_EQ(contacts[1].wall, 2u);
  // At one instant, t = 1 to the rounding of the place the ball was last predicted from (a
  // cell crossing on the way re-bases it: 1 + 2^-52 with cells that have hysteresis).
  EXPECT_EQ(contacts[0].time, contacts[1].time);
  EXPECT_NEAR(contacts[0].time, 1.0, 4.0 * std::numeric_limits<double>::epsilon());
  expect_near(world.velocity(ball), {-6.0, -3.0}, kRoundingTol * 6.0, "out of the corner");
  expect_near(world.position(ball), {9.0 - 6.0 * 0.5, 9.0 - 3.0 * 0.5}, kRoundingTol * 6.0,
              "out of the corner");
}

TEST(WorldScenario, BallIntoARotatedRightAngleComesOutReversed) {
  // Two segments meeting at a right angle at the origin, turned by an arbitrary angle. Two
  // reflections across perpendicular lines negate any velocity, whichever wall is met first.
  constexpr double kTurn = 0.4;
  const Vec2 along{std::cos(kTurn), std::sin(kTurn)};
  const Vec2 across = left_normal(along);
  std::mt19937_64 engine(21);
  std::uniform_real_distribution<double> fraction(0.1, 0.9);
  for (int trial = 0; trial < 20; ++trial) {
    World world;
    // Long enough that the ball meets the second wall after the first, however shallow.
    world.add_segment({{0.0, 0.0}, along * 1000.0});
    world.add_segment({{0.0, 0.0}, across * 1000.0});
    // Start in the corner's quadrant, moving into the corner from a random direction.
    const Vec2 start = along * 8.0 + across * 8.0;
    const double angle = fraction(engine) * std::numbers::pi / 2.0;
    const Vec2 velocity = -(along * std::cos(angle) + across * std::sin(angle)) * 5.0;
    const BallId ball = world.add_ball(ball_at(start, velocity, 1.0));
    world.run_until(20.0);
    EXPECT_EQ(world.contacts().size(), 2u) << "trial " << trial;
    expect_near(world.velocity(ball), -velocity, kRoundingTol * 5.0, "out of the rotated corner");
  }
}

// ---- grazing ---------------------------------------------------------------------------------

TEST(WorldScenario, BallRollingAlongAWallNeverTouchesIt) {
  World world;
  world.add_segment({{0.0, 0.0}, {10.0, 0.0}});
  const Vec2 start{-2.0, 0.5};
  const Vec2 velocity{1.0, 0.0};
  // Touching the wall's line all along, past both of its ends.
  const BallId ball = world.add_ball(ball_at(start, velocity, 0.5));
  for (int s = 0; s < 20; ++s) {
    world.step(1.0);
    EXPECT_TRUE(world.contacts().empty()) << "step " << s;
  }
  EXPECT_EQ(world.collision_count(), 0u);
  EXPECT_EQ(world.velocity(ball), velocity);
  expect_near(world.position(ball), start + velocity * 20.0, kRoundingTol * 20.0, "rolled");
}

TEST(WorldScenario, BallRollingAlongABoxFloorOnlyMeetsTheSides) {
  World world(WorldDef{Boundary::box, {0.0, 0.0}, {10.0, 10.0}});
  const BallId ball = world.add_ball(ball_at({5.0, 0.5}, {7.0, 0.0}, 0.5));
  std::uint64_t contacts = 0;
  for (int s = 0; s < 60; ++s) {
    world.step(kScenarioStep * 10.0);
    for (const ContactEvent& c : world.contacts()) {
      ++contacts;
      EXPECT_TRUE(c.wall == 1u || c.wall == 3u) << "met wall " << c.wall;  // the sides only
    }
    ASSERT_EQ(world.velocity(ball).y, 0.0);
    ASSERT_EQ(world.position(ball).y, 0.5);
  }
  EXPECT_GT(contacts, 5u);
}

// ---- a contact at time 0 ---------------------------------------------------------------------

TEST(WorldScenario, TouchingPairSetApproachingCollidesAtOnce) {
  World world;
  const BallId a = world.add_ball(ball_at({0.0, 0.0}, {}));
  const BallId b = world.add_ball(ball_at({1.0, 0.0}, {}));  // touching exactly
  world.set_velocity(a, {1.0, 0.0});
  world.set_velocity(b, {-1.0, 0.0});
  world.step(1.0);
  const auto contacts = world.contacts();
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts[0].time, 0.0);
  EXPECT_EQ(contacts[0].a, a);
  EXPECT_EQ(contacts[0].b, b);
  EXPECT_NEAR(contacts[0].approach_speed, 2.0, kRoundingTol);
  expect_near(world.velocity(a), {-1.0, 0.0}, kRoundingTol, "a");
  expect_near(world.velocity(b), {1.0, 0.0}, kRoundingTol, "b");
}

TEST(WorldScenario, TouchingPairSeparatingNeverCollides) {
  World world;
  world.add_ball(ball_at({0.0, 0.0}, {-1.0, 0.0}));
  world.add_ball(ball_at({1.0, 0.0}, {1.0, 0.0}));
  world.step(1.0);
  EXPECT_TRUE(world.contacts().empty());
}

// ---- fast balls ------------------------------------------------------------------------------

// 1000 diameters per step: each crosses the other's whole width in a thousandth of a step.
constexpr double kFastSpeed = 1000.0 * 1.0 / kScenarioStep;

TEST(WorldScenario, FastHeadOnBallsBounceInsteadOfTunnelling) {
  World world;
  const BallId a = world.add_ball(ball_at({-5.0, 0.0}, {kFastSpeed, 0.0}));
  const BallId b = world.add_ball(ball_at({5.0, 0.0}, {-kFastSpeed, 0.0}));
  world.step(kScenarioStep);
  ASSERT_EQ(world.contacts().size(), 1u);
  EXPECT_NEAR(world.contacts()[0].time, 4.5 / kFastSpeed, kRoundingTol);
  EXPECT_LT(world.position(a).x, world.position(b).x);  // still on their own sides
  expect_near(world.velocity(a), {-kFastSpeed, 0.0}, kRoundingTol * kFastSpeed, "a");
  expect_near(world.velocity(b), {kFastSpeed, 0.0}, kRoundingTol * kFastSpeed, "b");
}

TEST(WorldScenario, FastBallBouncesOffAThinWall) {
  World world;
  world.add_segment({{0.0, -1.0}, {0.0, 1.0}});
  const BallId ball = world.add_ball(ball_at({-3.0, 0.2}, {kFastSpeed, 0.0}));
  world.step(kScenarioStep);
  ASSERT_EQ(world.contacts().size(), 1u);
  EXPECT_LT(world.position(ball).x, 0.0);
  expect_near(world.velocity(ball), {-kFastSpeed, 0.0}, kRoundingTol * kFastSpeed, "bounced");
}

// ---- bowls and rotated walls -----------------------------------------------------------------

std::vector<BallId> scatter_balls(World& world, Vec2 centre, double half_width, int per_row,
                                  double radius, double speed, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  std::vector<BallId> ids;
  const double pitch = 2.0 * half_width / per_row;
  for (int i = 0; i < per_row; ++i) {
    for (int j = 0; j < per_row; ++j) {
      const Vec2 at =
          centre + Vec2{-half_width + (i + 0.5) * pitch, -half_width + (j + 0.5) * pitch};
      const double a = angle(engine);
      ids.push_back(world.add_ball(ball_at(at, Vec2{std::cos(a), std::sin(a)} * speed, radius)));
    }
  }
  return ids;
}

TEST(WorldScenario, BallsInsideAFullArcBowlStayInside) {
  constexpr double kBowl = 10.0;
  constexpr double kRadius = 0.4;
  World world;
  world.add_arc({{0.0, 0.0}, kBowl, 0.0, 2.0 * std::numbers::pi});
  // A square of balls well inside the circle (its half-diagonal 5·√2 < 10 − radius).
  const auto ids = scatter_balls(world, {0.0, 0.0}, 5.0, 5, kRadius, 200.0, 31);
  for (int s = 0; s < 600; ++s) {
    world.step(kScenarioStep);
    for (BallId id : ids) {
      ASSERT_LE(length(world.position(id)), kBowl - kRadius * (1.0 - kOverlapTol)) << "step " << s;
    }
  }
  EXPECT_GT(world.collision_count(), 500u);
}

TEST(WorldScenario, BallsInsideAHalfBowlClosedByASegmentStayInside) {
  constexpr double kBowl = 10.0;
  constexpr double kRadius = 0.4;
  World world;
  world.add_arc({{0.0, 0.0}, kBowl, 0.0, std::numbers::pi});  // the upper half
  world.add_segment({{-kBowl, 0.0}, {kBowl, 0.0}});           // its lid, sharing its ends
  const auto ids = scatter_balls(world, {0.0, 4.0}, 3.5, 4, kRadius, 200.0, 32);
  for (int s = 0; s < 600; ++s) {
    world.step(kScenarioStep);
    for (BallId id : ids) {
      const Vec2 p = world.position(id);
      ASSERT_LE(length(p), kBowl - kRadius * (1.0 - kOverlapTol)) << "step " << s;
      ASSERT_GE(p.y, kRadius * (1.0 - kOverlapTol)) << "step " << s;
    }
  }
  EXPECT_GT(world.collision_count(), 300u);
}

TEST(WorldScenario, BallsInsideARotatedSquareStayInside) {
  constexpr double kTurn = 0.7;
  constexpr double kHalf = 10.0;
  constexpr double kRadius = 0.4;
  const Vec2 u{std::cos(kTurn), std::sin(kTurn)};
  const Vec2 v = left_normal(u);
  const std::array<Vec2, 4> corners{(u + v) * kHalf, (-u + v) * kHalf, (-u - v) * kHalf,
                                    (u - v) * kHalf};
  World world;
  EXPECT_EQ(world.add_polyline(corners, true), 0u);
  EXPECT_EQ(world.wall_count(), 4u);
  // Balls on a grid in the square's own frame.
  std::vector<BallId> ids;
  std::mt19937_64 engine(33);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  for (int i = -3; i <= 3; ++i) {
    for (int j = -3; j <= 3; ++j) {
      const double a = angle(engine);
      ids.push_back(world.add_ball(
          ball_at(u * (2.5 * i) + v * (2.5 * j), Vec2{std::cos(a), std::sin(a)} * 300.0, kRadius)));
    }
  }
  const double limit = kHalf - kRadius * (1.0 - kOverlapTol);
  for (int s = 0; s < 600; ++s) {
    world.step(kScenarioStep);
    for (BallId id : ids) {
      const Vec2 p = world.position(id);
      ASSERT_LE(std::abs(dot(p, u)), limit) << "step " << s;
      ASSERT_LE(std::abs(dot(p, v)), limit) << "step " << s;
    }
  }
  EXPECT_GT(world.collision_count(), 1000u);
}

TEST(WorldScenario, BallOffASlantedWallLeavesMirrored) {
  constexpr double kTurn = 0.7;
  const Vec2 along{std::cos(kTurn), std::sin(kTurn)};
  const Vec2 normal = left_normal(along);
  World world;
  world.add_segment({along * -10.0, along * 10.0});
  const Vec2 velocity = normal * -3.0 + along * 1.5;  // towards the wall from its left side
  const BallId ball = world.add_ball(ball_at(normal * 4.0 + along * 2.0, velocity, 1.0));
  world.run_until(10.0);
  ASSERT_EQ(world.contacts().size(), 1u);
  const Vec2 mirrored = velocity - normal * (2.0 * dot(velocity, normal));
  expect_near(world.velocity(ball), mirrored, kRoundingTol * 4.0, "mirrored");
}

// ---- a closed box ----------------------------------------------------------------------------

TEST(WorldScenario, NoBallEverLeavesAClosedBox) {
  constexpr double kSide = 40.0;
  World world(WorldDef{Boundary::box, {0.0, 0.0}, {kSide, kSide}});
  std::mt19937_64 engine(41);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<BallId> ids;
  for (int i = 0; i < 15; ++i) {
    for (int j = 0; j < 15; ++j) {
      const double radius = 0.3 + 0.4 * unit(engine);
      const double a = 2.0 * std::numbers::pi * unit(engine);
      // Up to 100 diameters per step.
      const double speed = unit(engine) * 100.0 * 2.0 * radius / kScenarioStep;
      BallDef def = ball_at({(i + 0.5) * kSide / 15.0, (j + 0.5) * kSide / 15.0},
                            Vec2{std::cos(a), std::sin(a)} * speed, radius);
      def.mass = 0.5 + unit(engine);
      ids.push_back(world.add_ball(def));
    }
  }
  for (int s = 0; s < 60; ++s) {
    world.step(kScenarioStep);
    for (BallId id : ids) {
      const Vec2 p = world.position(id);
      const double reach = world.radius(id) * (1.0 - kOverlapTol);
      ASSERT_GE(p.x, reach) << "step " << s;
      ASSERT_GE(p.y, reach) << "step " << s;
      ASSERT_LE(p.x, kSide - reach) << "step " << s;
      ASSERT_LE(p.y, kSide - reach) << "step " << s;
    }
    const auto audit = world.audit();
    ASSERT_FALSE(audit.has_value()) << "step " << s << ": " << *audit;
  }
  EXPECT_GT(world.collision_count(), 10'000u);
}

// ---- ties after the engine re-orders its balls in memory -------------------------------------

// A ball struck from both sides at the same instant: the two contacts tie, and the documented
// order (world_event.hpp) takes the pair with the lower handles first. The three balls are
// added right to left, so that the engine's re-order by grid cell (left to right) stores them in
// the reverse of their handle order; fast "bouncers" in a compartment of their own supply the
// events that trigger the re-order (over 2^16 of them, engine_tuning.hpp's kSortMinEvents) before
// the triple meets. Were ties broken by storage place, (middle, left) would come first.
TEST(WorldScenario, SimultaneousContactsFollowHandleOrderAfterTheBallsAreReordered) {
  WorldDef def;
  def.boundary = Boundary::box;
  def.lower = {0.0, 0.0};
  def.upper = {100.0, 100.0};
  World world(def);
  world.add_box({0.0, 90.0}, {3.0, 93.0});  // the bouncers' compartment
  const BallId right = world.add_ball(ball_at({70.0, 50.0}, {-1.0, 0.0}));
  const BallId middle = world.add_ball(ball_at({50.0, 50.0}, {0.0, 0.0}));
  const BallId left = world.add_ball(ball_at({30.0, 50.0}, {1.0, 0.0}));
  world.add_ball(ball_at({1.0, 91.5}, {20000.0, 0.0}));
  world.add_ball(ball_at({2.0, 91.5}, {0.0, 0.0}, 0.4));
  world.set_contact_recording(true);
  // The triple meets at t = 19 (gaps of 19 closed at speed 1 from each side).
  world.run_until(18.9);
  ASSERT_GT(world.collision_count(), 70000U) << "the bouncers must trigger a re-order first";
  world.run_until(19.1);
  const auto in_triple = [&](BallId id) { return id == left || id == middle || id == right; };
  std::vector<ContactEvent> triple;
  for (const ContactEvent& c : world.contacts()) {
    if (c.kind == ContactKind::ball_ball && in_triple(c.a) && in_triple(c.b)) triple.push_back(c);
  }
  ASSERT_GE(triple.size(), 2U);
  EXPECT_EQ(triple[0].time, triple[1].time);  // a true tie
  EXPECT_EQ(triple[0].a, right);              // handles 0 and 1 first
  EXPECT_EQ(triple[0].b, middle);
  EXPECT_EQ(triple[1].a, middle);
  EXPECT_EQ(triple[1].b, left);
  EXPECT_FALSE(world.audit().has_value());
}

}  // namespace
}  // namespace carom
