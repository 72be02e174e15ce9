// Moving walls: a paddle and a flipper against closed forms; random worlds of turning and
// translating walls checked for tunnelling against the tests' own carrying of each wall, sampled
// densely; the work the walls do against the energy the balls gain; a pinball flipper under
// gravity; removal; queries; save and resume mid-motion; misuse.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <variant>
#include <vector>

#include "ball_def.hpp"
#include "carom/error.hpp"
#include "carom/world.hpp"

namespace carom::moving_wall_tests {
namespace {

using testing::ball_def;

// The tests' own carrying of a point by a motion given at time 0, for t (clamped to its
// duration).
Vec2 carried(Vec2 x, const WallMotion& m, double t) {
  const double s = std::min(t, m.duration);
  const double angle = m.angular_velocity * s;
  const Vec2 d = x - m.pivot;
  return m.pivot + m.velocity * s +
         Vec2{std::cos(angle) * d.x - std::sin(angle) * d.y,
              std::sin(angle) * d.x + std::cos(angle) * d.y};
}

// The velocity of the wall's material point at p at time t (zero once the motion has ended).
Vec2 wall_velocity(Vec2 p, const WallMotion& m, double t) {
  if (t >= m.duration) return {};
  const Vec2 arm = p - (m.pivot + m.velocity * t);
  return m.velocity + Vec2{-arm.y, arm.x} * m.angular_velocity;
}

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double f = std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
  return length(p - (a + d * f));
}

TEST(WorldMovingWalls, ARisingPaddleMeetsABallAtRestAndSendsItOffAtTwiceItsSpeed) {
  World world;
  const WallId paddle = world.add_segment({{-1.0, 0.0}, {1.0, 0.0}});
  const BallId ball = world.add_ball(ball_def({0.0, 2.0}, {}));
  world.set_wall_motion(paddle, {{0.0, 1.0}, 0.0, {0.0, 0.0}});
  world.step(2.0);
  ASSERT_EQ(world.contacts().size(), 1U);
  const ContactEvent& contact = world.contacts()[0];
  EXPECT_DOUBLE_EQ(contact.time, 1.5);
  EXPECT_EQ(contact.wall, paddle);
  EXPECT_DOUBLE_EQ(contact.approach_speed, 1.0);
  // An elastic bounce off a wall moving at 1: the ball leaves at 2.
  EXPECT_DOUBLE_EQ(world.velocity(ball).y, 2.0);
  EXPECT_DOUBLE_EQ(world.position(ball).y, 2.0 + 2.0 * 0.5);
  const auto shape = std::get<Segment>(world.wall(paddle));
  EXPECT_DOUBLE_EQ(shape.a.y, 2.0);
  EXPECT_DOUBLE_EQ(world.wall_motion(paddle).pivot.y, 2.0);
}

TEST(WorldMovingWalls, AFlipperSendsABallWhereTheClosedFormSays) {
  // A flipper from its pivot (0, 0) to (2, 0) turning at 1 rad a unit of time meets a ball at rest
  // at (1, 1.5) of radius 0.5 when the angle θ puts the ball's centre 0.5 from its line:
  // θ = φ − asin(0.5 / √3.25), tan φ = 1.5. The bounce, elastic off a wall whose contact point
  // moves at u, gives the ball 2 (u·n) n along the normal n.
  World world;
  const WallId flipper = world.add_segment({{0.0, 0.0}, {2.0, 0.0}});
  const BallId ball = world.add_ball(ball_def({1.0, 1.5}, {}));
  world.set_wall_motion(flipper, {{}, 1.0, {0.0, 0.0}});
  world.run_collisions(1, 10.0);
  const double theta = std::atan2(1.5, 1.0) - std::asin(0.5 / std::sqrt(3.25));
  ASSERT_EQ(world.contacts().size(), 1U);
  EXPECT_NEAR(world.contacts()[0].time, theta, 1e-12);
  const Vec2 along{std::cos(theta), std::sin(theta)};
  const Vec2 point = along * (1.0 * along.x + 1.5 * along.y);
  const Vec2 u = Vec2{-point.y, point.x} * 1.0;
  const Vec2 n{along.y, -along.x};  // from the ball down to the flipper
  const Vec2 expected = n * (2.0 * dot(u, n));
  EXPECT_NEAR(world.velocity(ball).x, expected.x, 1e-9);
  EXPECT_NEAR(world.velocity(ball).y, expected.y, 1e-9);
  EXPECT_GT(world.velocity(ball).y, 0.0);
}

TEST(WorldMovingWalls, AWallStopsWhereItsDurationEndsAndThenStandsStill) {
  World world;
  const WallId arm = world.add_segment({{0.0, 0.0}, {2.0, 0.0}});
  world.set_wall_motion(arm, {{}, 2.0, {0.0, 0.0}, 0.25});
  world.step(1.0);
  const auto shape = std::get<Segment>(world.wall(arm));
  EXPECT_NEAR(shape.b.x, 2.0 * std::cos(0.5), 1e-15);
  EXPECT_NEAR(shape.b.y, 2.0 * std::sin(0.5), 1e-15);
  EXPECT_EQ(world.wall_motion(arm), (WallMotion{{}, 0.0, {}, 0.0}));
  // A ball dropped on it afterwards meets the still wall where it stopped.
  const BallId ball = world.add_ball(ball_def({1.0, 3.0}, {0.0, -1.0}, 0.25));
  world.step(5.0);
  ASSERT_FALSE(world.contacts().empty());
  const Vec2 n{-std::sin(0.5), std::cos(0.5)};
  EXPECT_NEAR(dot(world.contacts()[0].point, n), 0.0, 1e-12);
  EXPECT_GT(world.velocity(ball).y, 0.0);
}

// Random worlds: a box with a turning segment, a turning arc and a paddle translating for a
// while, and balls; every contact elastic. After each short step no ball may overlap a moving
// wall as the tests carry it (a missed contact lets a ball through), and the energy the balls
// gained is the work of the walls, Σ J·u over the contacts with moving walls (J the impulse on
// the ball, u the wall's velocity at the contact point).
TEST(WorldMovingWalls, RandomWorldsNeverLetABallThroughAndTheWorkDoneIsTheEnergyGained) {
  std::mt19937_64 random(0x3a11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int moving_contacts = 0;
  for (int trial = 0; trial < 12; ++trial) {
    WorldDef def;
    def.boundary = Boundary::box;
    def.lower = {-10.0, -10.0};
    def.upper = {10.0, 10.0};
    World world(def);
    const Segment bar{{-4.0, 0.0}, {2.0, 0.0}};
    const Arc cup{{5.0, 5.0}, 2.0, 0.0, 2.5};
    const Segment paddle{{-6.0, -6.0}, {-3.0, -6.0}};
    const WallId w_bar = world.add_segment(bar);
    const WallId w_cup = world.add_arc(cup);
    const WallId w_paddle = world.add_segment(paddle);
    const WallMotion bar_motion{{}, 3.0 * unit(random), {0.0, 0.0}};
    const WallMotion cup_motion{{}, 4.0 * unit(random), {5.0, 5.0 + 0.5 * unit(random)}};
    const WallMotion paddle_motion{{0.5 * unit(random), 1.0}, 0.0, {-4.5, -6.0}, 2.5};
    world.set_wall_motion(w_bar, bar_motion);
    world.set_wall_motion(w_cup, cup_motion);
    world.set_wall_motion(w_paddle, paddle_motion);
    for (int k = 0; k < 30; ++k) {
      BallDef ball = ball_def({9.0 * unit(random), 9.0 * unit(random)},
                              {4.0 * unit(random), 4.0 * unit(random)}, 0.3);
      try {
        world.add_ball(ball);
      } catch (const InvalidArgument&) {
        // overlapping a wall or a ball: left out
      }
    }
    const auto energy = [&] {
      double e = 0.0;
      for (const BallId id : world.balls()) e += 0.5 * length_squared(world.velocity(id));
      return e;
    };
    const double start_energy = energy();
    double work = 0.0;
    const double dt = 0.01;
    for (int s = 0; s < 300; ++s) {
      world.step(dt);
      const double now = world.time();
      for (const ContactEvent& c : world.contacts()) {
        const WallMotion* motion = c.kind != ContactKind::ball_wall ? nullptr
                                   : c.wall == w_bar                ? &bar_motion
                                   : c.wall == w_cup                ? &cup_motion
                                   : c.wall == w_paddle             ? &paddle_motion
                                                                    : nullptr;
        if (motion == nullptr) continue;
        // The impulse on the ball is −normal·impulse (the normal points at the wall).
        work -= c.impulse * dot(c.normal, wall_velocity(c.point, *motion, c.time));
        ++moving_contacts;
      }
      ASSERT_FALSE(world.audit(1e-9))
          << "trial " << trial << " at " << now << ": " << *world.audit(1e-9);
      for (const BallId id : world.balls()) {
        const Vec2 p = world.position(id);
        const double bar_gap = distance_to_segment(p, carried(bar.a, bar_motion, now),
                                                   carried(bar.b, bar_motion, now)) -
                               0.3;
        const double paddle_gap = distance_to_segment(p, carried(paddle.a, paddle_motion, now),
                                                      carried(paddle.b, paddle_motion, now)) -
                                  0.3;
        EXPECT_GT(bar_gap, -1e-9) << "trial " << trial << " at " << now;
        EXPECT_GT(paddle_gap, -1e-9) << "trial " << trial << " at " << now;
        // The arc: its circle (where the direction lies within the span) and its two ends.
        const Vec2 centre = carried(cup.center, cup_motion, now);
        const double turned = cup_motion.angular_velocity * now;
        const Vec2 out = p - centre;
        const double angle =
            std::remainder(std::atan2(out.y, out.x) - turned, 2.0 * std::numbers::pi);
        const double from_start = angle < 0.0 ? angle + 2.0 * std::numbers::pi : angle;
        double cup_distance = std::min(
            length(p - (centre + Vec2{std::cos(turned), std::sin(turned)} * 2.0)),
            length(p - (centre + Vec2{std::cos(turned + 2.5), std::sin(turned + 2.5)} * 2.0)));
        if (from_start <= 2.5) cup_distance = std::min(cup_distance, std::abs(length(out) - 2.0));
        EXPECT_GT(cup_distance - 0.3, -1e-9) << "trial " << trial << " at " << now;
      }
    }
    EXPECT_NEAR(energy() - start_energy, work, 1e-9 * (start_energy + std::abs(work)))
        << "trial " << trial;
  }
  EXPECT_GT(moving_contacts, 100);
}

TEST(WorldMovingWalls, APinballFlipperLaunchesTheBallRestingOnItAndThenCarriesItAgain) {
  WorldDef def;
  def.gravity = {0.0, -10.0};
  def.restitution = 0.5;
  World world(def);
  const WallId flipper = world.add_segment({{0.0, 0.0}, {3.0, 0.0}});
  const BallId ball = world.add_ball(ball_def({2.0, 0.25}, {}, 0.25));
  world.step(0.5);
  EXPECT_EQ(world.velocity(ball), (Vec2{}));  // resting on the flipper
  // The flipper swings up at 10 rad a unit of time for 0.05 (0.5 rad): the ball, touching it at
  // (2, 0) where the flipper moves up at 20, leaves at (1 + 0.5)·20 = 30, less gravity's 0.5.
  world.set_wall_motion(flipper, {{}, 10.0, {0.0, 0.0}, 0.05});
  world.step(0.05);
  ASSERT_FALSE(world.contacts().empty());
  EXPECT_DOUBLE_EQ(world.contacts()[0].time, 0.5);
  EXPECT_NEAR(world.velocity(ball).x, 0.0, 1e-12);
  EXPECT_NEAR(world.velocity(ball).y, 30.0 - 0.5, 1e-9);
  // It flies up, falls back onto the flipper (now still, raised 0.5 rad) and rolls off its low
  // end: the run ends without a pile-up, the ball below the pivot.
  world.step(20.0);
  EXPECT_LT(world.position(ball).y, 0.0);
  EXPECT_FALSE(world.audit(1e-9));
}

TEST(WorldMovingWalls, ARemovedWallIsMetBySomethingNoLonger) {
  World world;
  const WallId wall = world.add_segment({{0.0, -1.0}, {0.0, 1.0}});
  const BallId ball = world.add_ball(ball_def({-2.0, 0.0}, {1.0, 0.0}));
  world.remove_wall(wall);
  EXPECT_TRUE(world.wall_removed(wall));
  EXPECT_EQ(world.wall_count(), 1U);
  world.step(4.0);
  EXPECT_TRUE(world.contacts().empty());
  EXPECT_DOUBLE_EQ(world.position(ball).x, 2.0);
  EXPECT_NE(world.cast_ray({-5.0, 0.0}, {10.0, 0.0}).kind, HitKind::wall);
  EXPECT_THROW(world.remove_wall(wall), InvalidArgument);
  EXPECT_THROW(world.set_wall_motion(wall, {{1.0, 0.0}, 0.0, {}}), InvalidArgument);
}

TEST(WorldMovingWalls, AnImmovableBallAndAMovingWallPassThroughEachOther) {
  // Neither gives way: the wall sweeps over the post, and the audit does not count the overlap.
  World world;
  const WallId wall = world.add_segment({{-1.0, 0.0}, {1.0, 0.0}});
  BallDef post = ball_def({0.0, 2.0}, {});
  post.mass = kImmovable;
  world.add_ball(post);
  world.set_wall_motion(wall, {{0.0, 1.0}, 0.0, {}, 2.0});
  world.step(3.0);
  EXPECT_TRUE(world.contacts().empty());
  EXPECT_FALSE(world.audit());
}

TEST(WorldMovingWalls, QueriesSeeAMovingWallWhereItIsNow) {
  World world;
  const WallId wall = world.add_segment({{0.0, -1.0}, {0.0, 1.0}});
  world.set_wall_motion(wall, {{2.0, 0.0}, 0.0, {}});
  world.step(1.5);
  const QueryHit hit = world.cast_ray({-5.0, 0.0}, {10.0, 0.0});
  ASSERT_EQ(hit.kind, HitKind::wall);
  EXPECT_DOUBLE_EQ(hit.point.x, 3.0);
  EXPECT_THROW(world.add_ball(ball_def({3.2, 0.0}, {})), InvalidArgument);
}

TEST(WorldMovingWalls, SaveAndResumeMidMotionIsBitIdentical) {
  WorldDef def;
  def.boundary = Boundary::box;
  def.lower = {-10.0, -10.0};
  def.upper = {10.0, 10.0};
  def.gravity = {0.0, -3.0};
  def.restitution = 0.9;
  World world(def);
  const WallId bar = world.add_segment({{-4.0, -2.0}, {3.0, -2.0}});
  const WallId cup = world.add_arc({{4.0, 4.0}, 2.0, 0.0, 3.0});
  world.set_wall_motion(bar, {{0.2, 0.0}, 1.5, {-0.5, -2.0}, 3.0});
  world.set_wall_motion(cup, {{}, -2.0, {4.0, 4.0}});
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 25; ++k) {
    try {
      world.add_ball(ball_def({9.0 * unit(random), 9.0 * unit(random)},
                              {3.0 * unit(random), 3.0 * unit(random)}, 0.3));
    } catch (const InvalidArgument&) {
    }
  }
  world.step(1.0);
  std::stringstream saved;
  world.save(saved);
  World resumed = World::load(saved);
  world.step(4.0);
  resumed.step(4.0);
  ASSERT_EQ(world.balls().size(), resumed.balls().size());
  for (const BallId id : world.balls()) {
    EXPECT_EQ(world.position(id), resumed.position(id));
    EXPECT_EQ(world.velocity(id), resumed.velocity(id));
  }
  EXPECT_EQ(std::get<Segment>(world.wall(bar)).b, std::get<Segment>(resumed.wall(bar)).b);
  EXPECT_EQ(world.wall_motion(cup), resumed.wall_motion(cup));
}

TEST(WorldMovingWalls, MisuseIsRefusedWithWhatAndWhere) {
  WorldDef def;
  def.boundary = Boundary::box;
  def.lower = {-5.0, -5.0};
  def.upper = {5.0, 5.0};
  World world(def);
  const WallId wall = world.add_segment({{0.0, 0.0}, {1.0, 0.0}});
  const WallId sensor = world.add_sensor(Segment{{0.0, 1.0}, {1.0, 1.0}});
  EXPECT_THROW(world.set_wall_motion(0, {{1.0, 0.0}, 0.0, {}}), InvalidArgument);
  EXPECT_THROW(world.set_wall_motion(sensor, {{1.0, 0.0}, 0.0, {}}), InvalidArgument);
  EXPECT_THROW(world.set_wall_motion(99, {{1.0, 0.0}, 0.0, {}}), InvalidArgument);
  EXPECT_THROW(world.set_wall_motion(wall, {{std::nan(""), 0.0}, 0.0, {}}), InvalidArgument);
  EXPECT_THROW(world.set_wall_motion(wall, {{}, 1.0, {}, -1.0}), InvalidArgument);
  EXPECT_THROW(world.remove_wall(1), InvalidArgument);
  try {
    world.set_wall_motion(wall, {{}, 1.0, {}, -1.0});
  } catch (const InvalidArgument& error) {
    EXPECT_NE(std::string(error.what()).find("motion.duration"), std::string::npos);
  }
}

TEST(WorldMovingWalls, AWallGivenNoMotionChangesNoResult) {
  // A wall that stands still (a WallMotion of zeros) is met off the grid, by the same closed
  // forms: the contacts are those of the static wall.
  const auto run = [](bool moving) {
    World world;
    const WallId wall = world.add_segment({{-3.0, -3.0}, {3.0, 2.0}});
    world.add_ball(ball_def({-1.0, 4.0}, {0.3, -1.0}));
    world.add_ball(ball_def({2.0, -4.0}, {-0.2, 1.5}));
    if (moving) world.set_wall_motion(wall, WallMotion{});
    world.step(10.0);
    std::vector<ContactEvent> out(world.contacts().begin(), world.contacts().end());
    return out;
  };
  const auto still = run(false);
  const auto moving = run(true);
  ASSERT_EQ(still.size(), moving.size());
  ASSERT_FALSE(still.empty());
  for (std::size_t k = 0; k < still.size(); ++k) {
    EXPECT_EQ(still[k].time, moving[k].time);
    EXPECT_EQ(still[k].point, moving[k].point);
  }
}

}  // namespace
}  // namespace carom::moving_wall_tests
