// Sensors: enters and exits at their exact times however fast the ball, in pairs and in order,
// against a brute-force reference in a box gas; falling and growing balls; pockets that remove;
// filters; placements into and out of a sensor; save and resume inside one; misuse.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <utility>
#include <variant>
#include <vector>

#include "ball_def.hpp"
#include "carom/error.hpp"
#include "carom/world.hpp"

namespace carom::sensor_tests {
namespace {

using testing::ball_def;

std::vector<SensorEvent> events_of(const World& world) {
  return {world.sensor_events().begin(), world.sensor_events().end()};
}

TEST(WorldSensors, ABulletAtAMillionDiametersAStepRecordsItsEnterAndExit) {
  World world;
  const WallId line = world.add_sensor(Segment{{0.0, -1.0}, {0.0, 1.0}});
  // Radius 0.01: 10^6 diameters a step of 1 is a speed of 2·10^4.
  const BallId bullet = world.add_ball(ball_def({-10000.0, 0.5}, {2e4, 0.0}, 0.01));
  world.step(1.0);
  const auto events = events_of(world);
  ASSERT_EQ(events.size(), 2U);
  EXPECT_EQ(events[0].kind, SensorEventKind::enter);
  EXPECT_EQ(events[1].kind, SensorEventKind::exit);
  EXPECT_EQ(events[0].ball, bullet);
  EXPECT_EQ(events[0].sensor, line);
  EXPECT_NEAR(events[0].time, (10000.0 - 0.01) / 2e4, 1e-12);
  EXPECT_NEAR(events[1].time, (10000.0 + 0.01) / 2e4, 1e-12);
  EXPECT_FALSE(events[0].removed);
  // The sensor took no part: the ball flew on.
  EXPECT_EQ(world.velocity(bullet), (Vec2{2e4, 0.0}));
  EXPECT_NEAR(world.position(bullet).x, 10000.0, 1e-9);
  EXPECT_TRUE(world.contacts().empty());
  EXPECT_TRUE(world.balls_in_sensor(line).empty());
}

TEST(WorldSensors, AFallingBallEntersALineAtTheParabolasTime) {
  WorldDef def;
  def.gravity = {0.0, -9.81};
  World world(def);
  const WallId line = world.add_sensor(Segment{{-5.0, 0.0}, {5.0, 0.0}});
  const BallId dropped = world.add_ball(ball_def({0.0, 10.0}, {0.0, 0.0}, 0.5));
  world.step(1.42);
  ASSERT_EQ(world.sensor_events().size(), 1U);
  // y(t) = 10 − 4.905·t² reaches 0.5 (the ball touches the line).
  EXPECT_NEAR(world.sensor_events()[0].time, std::sqrt(9.5 / 4.905), 1e-12);
  EXPECT_EQ(world.balls_in_sensor(line), std::vector<BallId>{dropped});
  world.step(1.0);
  ASSERT_EQ(world.sensor_events().size(), 1U);
  EXPECT_EQ(world.sensor_events()[0].kind, SensorEventKind::exit);
  EXPECT_NEAR(world.sensor_events()[0].time, std::sqrt(10.5 / 4.905), 1e-12);
}

TEST(WorldSensors, AGrowingBallEntersADiscWhenItsRadiusReachesIt) {
  WorldDef def;
  def.growth_rate = 0.5;  // r = 1·(1 + 0.5·t)
  World world(def);
  const WallId zone = world.add_sensor(Ball{{0.0, 0.0}, 1.0});
  world.add_ball(ball_def({3.0, 0.0}, {0.0, 0.0}, 1.0));
  world.step(4.0);
  ASSERT_EQ(world.sensor_events().size(), 1U);
  // Radius 2 = 3 − 1, to the sensors' margin (2^-40 of the coordinates, over the growth).
  EXPECT_NEAR(world.sensor_events()[0].time, 2.0, 1e-10);
  EXPECT_EQ(world.sensor_events()[0].sensor, zone);
}

TEST(WorldSensors, APocketRemovesTheBallThatEntersIt) {
  World world(WorldDef{Boundary::box, {0.0, 0.0}, {10.0, 10.0}});
  const WallId pocket = world.add_sensor(Ball{{9.0, 5.0}, 0.2}, SensorAction::remove_ball);
  const BallId rolled = world.add_ball(ball_def({2.0, 5.0}, {4.0, 0.0}));
  const BallId stays = world.add_ball(ball_def({2.0, 2.0}, {0.0, 0.0}));
  EXPECT_EQ(world.sensor(pocket), SensorAction::remove_ball);
  EXPECT_EQ(world.sensor(0), std::nullopt);
  world.step(3.0);
  ASSERT_EQ(world.sensor_events().size(), 1U);
  const SensorEvent event = world.sensor_events()[0];
  EXPECT_TRUE(event.removed);
  EXPECT_EQ(event.ball, rolled);
  // Its edge reaches the pocket's disc at x = 9 − 0.2 − 0.5 (to the sensors' margin).
  EXPECT_NEAR(event.time, (8.3 - 2.0) / 4.0, 1e-11);
  EXPECT_FALSE(world.contains(rolled));
  EXPECT_TRUE(world.contains(stays));
  EXPECT_TRUE(world.contacts().empty());  // it never reached the box's side
  EXPECT_FALSE(world.audit());
  EXPECT_EQ(world.ball_count(), 1U);
}

TEST(WorldSensors, AFilteredBallPassesASensorWithoutEvents) {
  World world;
  const WallId line = world.add_sensor(Segment{{0.0, -1.0}, {0.0, 1.0}});
  world.set_wall_filter(line, {2, 2, 0});
  world.add_ball(ball_def({-5.0, 0.0}, {10.0, 0.0}), CollisionFilter{1, 1, 0});
  world.add_ball(ball_def({-5.0, 0.2}, {10.0, 0.0}), CollisionFilter{2, 2, 0});
  world.step(1.0);
  ASSERT_EQ(world.sensor_events().size(), 2U);  // the second ball's enter and exit only
  EXPECT_EQ(world.sensor_events()[0].ball.index, 1U);
}

TEST(WorldSensors, PlacingABallIntoOrOutOfASensorEntersOrLeavesAtTheNextRun) {
  World world;
  const WallId zone = world.add_sensor(Ball{{0.0, 0.0}, 2.0});
  const BallId moved = world.add_ball(ball_def({10.0, 0.0}, {0.0, 0.0}));
  world.step(1.0);
  EXPECT_TRUE(world.sensor_events().empty());
  world.set_position(moved, {1.0, 0.0});
  world.step(1.0);
  ASSERT_EQ(world.sensor_events().size(), 1U);
  EXPECT_EQ(world.sensor_events()[0].kind, SensorEventKind::enter);
  EXPECT_EQ(world.sensor_events()[0].time, 1.0);  // at the start of the run
  EXPECT_EQ(world.balls_in_sensor(zone), std::vector<BallId>{moved});
  world.set_position(moved, {10.0, 0.0});
  world.step(1.0);
  ASSERT_EQ(world.sensor_events().size(), 1U);
  EXPECT_EQ(world.sensor_events()[0].kind, SensorEventKind::exit);
  EXPECT_EQ(world.sensor_events()[0].time, 2.0);
  // A ball already inside a sensor added between runs enters at the next run's start.
  world.add_sensor(Ball{{10.0, 0.0}, 0.1});
  world.step(1.0);
  ASSERT_EQ(world.sensor_events().size(), 1U);
  EXPECT_EQ(world.sensor_events()[0].time, 3.0);
}

TEST(WorldSensors, ABallAtACrossingOfTwoSensorsEntersBothAtOnce) {
  // Each enter at the run's start leaves the other's decision to a horizon of zero, which
  // decides nothing (rather than reading "outside" and leaving at once, for ever).
  World world;
  const BallId ball = world.add_ball(ball_def({0.1, 0.1}, {1.0, 0.5}));
  const WallId across = world.add_sensor(Segment{{-5.0, 0.0}, {5.0, 0.0}});
  const WallId down = world.add_sensor(Segment{{0.0, -5.0}, {0.0, 5.0}});
  world.step(0.1);
  ASSERT_EQ(world.sensor_events().size(), 2U);
  EXPECT_EQ(world.sensor_events()[0].time, 0.0);
  EXPECT_EQ(world.sensor_events()[1].time, 0.0);
  EXPECT_EQ(world.balls_in_sensor(across), std::vector<BallId>{ball});
  EXPECT_EQ(world.balls_in_sensor(down), std::vector<BallId>{ball});
}

TEST(WorldSensors, QueriesPlacementAndAuditIgnoreSensors) {
  World world;
  world.add_sensor(Segment{{0.0, -5.0}, {0.0, 5.0}});
  world.add_sensor(Ball{{10.0, 0.0}, 3.0});
  // A ball may be placed over a sensor.
  const BallId over = world.add_ball(ball_def({10.0, 0.0}, {0.0, 0.0}));
  EXPECT_FALSE(world.audit());
  // A ray through both meets only the ball.
  const QueryHit hit = world.cast_ray({-5.0, 0.0}, {20.0, 0.0});
  EXPECT_EQ(hit.kind, HitKind::ball);
  EXPECT_EQ(hit.ball, over);
  world.set_position(over, {0.0, 0.0}, Placement::nearest_free);
  EXPECT_EQ(world.position(over), (Vec2{0.0, 0.0}));
}

TEST(WorldSensors, MisuseIsRefusedWithTheArgumentNamed) {
  World periodic(WorldDef{Boundary::periodic, {0.0, 0.0}, {10.0, 10.0}});
  EXPECT_THROW(periodic.add_sensor(Segment{{1.0, 1.0}, {2.0, 2.0}}), InvalidArgument);
  World world;
  EXPECT_THROW(world.add_sensor(Ball{{0.0, 0.0}, 0.0}), InvalidArgument);
  EXPECT_THROW(world.add_sensor(Ball{{0.0, 0.0}, std::nan("")}), InvalidArgument);
  EXPECT_THROW(world.add_sensor(Segment{{0.0, std::nan("")}, {1.0, 1.0}}), InvalidArgument);
  EXPECT_THROW(world.add_sensor(Arc{{0.0, 0.0}, 1.0, 0.0, 7.0}), InvalidArgument);
  EXPECT_THROW((void)world.sensor(3), InvalidArgument);
  EXPECT_THROW((void)world.balls_in_sensor(3), InvalidArgument);
  try {
    world.add_sensor(Ball{{0.0, 0.0}, -1.0});
    FAIL();
  } catch (const InvalidArgument& error) {
    EXPECT_NE(std::string(error.what()).find("disc.radius"), std::string::npos) << error.what();
  }
}

// A box gas crossing segments, arcs and discs: the world, run one contact at a time (between two
// stops every ball moves in a straight line), against a reference that samples each ball's
// distance to each sensor along those lines and bisects every sign change.
struct Gas {
  World world{WorldDef{Boundary::box, {0.0, 0.0}, {30.0, 30.0}}};
  std::vector<BallId> balls;
  std::vector<std::variant<Segment, Arc, Ball>> sensors;  // sensor k is wall 4 + k
};

Gas make_gas(std::uint64_t seed) {
  Gas gas;
  gas.sensors = {Segment{{3.0, 3.0}, {27.0, 20.0}},
                 Segment{{15.0, 1.0}, {15.0, 29.0}},
                 Arc{{10.0, 20.0}, 4.0, 0.3, 4.0},
                 Arc{{22.0, 8.0}, 3.0, -1.0, 4.5},
                 Ball{{7.0, 8.0}, 2.5},
                 Ball{{24.0, 24.0}, 0.3}};
  for (const auto& shape : gas.sensors) {
    std::visit([&](const auto& s) { gas.world.add_sensor(s); }, shape);
  }
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> speed(-6.0, 6.0);
  for (int row = 0; row < 6; ++row) {
    for (int column = 0; column < 6; ++column) {
      gas.balls.push_back(
          gas.world.add_ball(ball_def({2.5 + column * 5.0, 2.5 + row * 5.0},
                                      {speed(engine), speed(engine)}, 0.3 + 0.1 * (column % 3))));
    }
  }
  return gas;
}

// The reference's distances, by clamping and by atan2 angles (not the library's frames).
double distance_to(const std::variant<Segment, Arc, Ball>& shape, Vec2 p) {
  if (const auto* s = std::get_if<Segment>(&shape)) {
    const Vec2 d = s->b - s->a;
    const double f = std::clamp(dot(p - s->a, d) / length_squared(d), 0.0, 1.0);
    return length(p - (s->a + d * f));
  }
  if (const auto* a = std::get_if<Arc>(&shape)) {
    const auto on_circle = [&](double angle) {
      return a->center + Vec2{std::cos(angle), std::sin(angle)} * a->radius;
    };
    double best =
        std::min(length(p - on_circle(a->start_angle)), length(p - on_circle(a->end_angle)));
    const Vec2 offset = p - a->center;
    const double turn = 2.0 * std::numbers::pi;
    const double from_start =
        std::fmod(std::fmod(std::atan2(offset.y, offset.x) - a->start_angle, turn) + turn, turn);
    if (from_start <= a->end_angle - a->start_angle) {
      best = std::min(best, std::abs(length(offset) - a->radius));
    }
    return best;
  }
  const Ball& disc = std::get<Ball>(shape);
  return std::max(0.0, length(p - disc.center) - disc.radius);
}

struct Change {
  double time;
  bool enter;
};

TEST(WorldSensors, AGassEntersAndExitsMatchABruteForceReference) {
  Gas gas = make_gas(3);
  World& world = gas.world;
  // By (ball index, sensor): the world's changes and the reference's.
  std::map<std::pair<std::uint32_t, WallId>, std::vector<Change>> seen;
  std::map<std::pair<std::uint32_t, WallId>, std::vector<Change>> expected;
  std::map<std::pair<std::uint32_t, WallId>, bool> inside;
  int unclear = 0;
  double previous_time = 0.0;
  for (int stop = 0; stop < 400; ++stop) {
    const double t0 = world.time();
    std::vector<Vec2> p0;
    std::vector<Vec2> v0;
    for (const BallId id : gas.balls) {
      p0.push_back(world.position(id));
      v0.push_back(world.velocity(id));
    }
    world.run_collisions(1);
    const double t1 = world.time();
    for (const SensorEvent& event : world.sensor_events()) {
      EXPECT_GE(event.time, previous_time);
      EXPECT_LE(event.time, t1);
      previous_time = event.time;
      seen[{event.ball.index, event.sensor}].push_back(
          {event.time, event.kind == SensorEventKind::enter});
    }
    // The reference over [t0, t1]: straight lines.
    constexpr int kSamples = 400;
    for (std::size_t b = 0; b < gas.balls.size(); ++b) {
      const double r = world.radius(gas.balls[b]);
      for (std::size_t k = 0; k < gas.sensors.size(); ++k) {
        const auto gap = [&](double t) {
          return distance_to(gas.sensors[k], p0[b] + v0[b] * (t - t0)) - r;
        };
        const std::pair key{gas.balls[b].index, static_cast<WallId>(4 + k)};
        bool& in = inside[key];
        double previous = t0;
        for (int i = 0; i <= kSamples; ++i) {
          const double t = t0 + (t1 - t0) * i / kSamples;
          const double g = gap(t);
          if (std::abs(g) < 1e-7) ++unclear;
          if ((g < 0.0) != in) {
            double low = previous;
            double high = t;
            for (int n = 0; n < 100 && high - low > 1e-13; ++n) {
              const double mid = 0.5 * (low + high);
              ((gap(mid) < 0.0) == in ? low : high) = mid;
            }
            in = !in;
            expected[key].push_back({high, in});
          }
          previous = t;
        }
      }
    }
  }
  // Sample steps are short against any overlap here (balls under 12 per unit time, sensors and
  // balls at least 0.3 across), and no sample came within 1e-7 of touching.
  EXPECT_EQ(unclear, 0);
  std::size_t total = 0;
  for (const auto& [key, changes] : expected) {
    const auto& got = seen[key];
    ASSERT_EQ(got.size(), changes.size()) << "ball " << key.first << " sensor " << key.second;
    for (std::size_t n = 0; n < changes.size(); ++n) {
      EXPECT_EQ(got[n].enter, changes[n].enter);
      EXPECT_NEAR(got[n].time, changes[n].time, 1e-9);
    }
    total += changes.size();
  }
  for (const auto& [key, changes] : seen) EXPECT_EQ(changes.size(), expected[key].size());
  EXPECT_GT(total, 100U);  // the gas crossed the sensors often
  EXPECT_FALSE(world.audit());
}

TEST(WorldSensors, ARunIsDeterministicAndResumesFromASaveInsideASensor) {
  Gas straight = make_gas(9);
  straight.world.step(4.0);
  std::stringstream saved;
  straight.world.save(saved);
  Gas other = make_gas(9);
  other.world.step(4.0);
  World resumed = World::load(saved);
  EXPECT_EQ(straight.world.balls_in_sensor(8), resumed.balls_in_sensor(8));
  for (int k = 0; k < 5; ++k) {
    straight.world.step(1.0);
    other.world.step(1.0);
    resumed.step(1.0);
    const auto a = events_of(straight.world);
    const auto b = events_of(other.world);
    const auto c = events_of(resumed);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(a.size(), c.size());
    for (std::size_t n = 0; n < a.size(); ++n) {
      EXPECT_EQ(a[n].time, b[n].time);
      EXPECT_EQ(a[n].time, c[n].time);
      EXPECT_EQ(a[n].ball, c[n].ball);
      EXPECT_EQ(a[n].kind, c[n].kind);
      EXPECT_EQ(a[n].contacts_before, c[n].contacts_before);
    }
  }
}

TEST(WorldSensors, SensorsChangeTheMotionOnlyByRounding) {
  Gas with = make_gas(5);
  World without(WorldDef{Boundary::box, {0.0, 0.0}, {30.0, 30.0}});
  for (const BallId id : with.balls) {
    without.add_ball(
        ball_def(with.world.position(id), with.world.velocity(id), with.world.radius(id)));
  }
  with.world.step(2.0);
  without.step(2.0);
  ASSERT_EQ(with.world.contacts().size(), without.contacts().size());
  for (std::size_t n = 0; n < without.contacts().size(); ++n) {
    EXPECT_NEAR(with.world.contacts()[n].time, without.contacts()[n].time, 1e-12);
  }
}

}  // namespace
}  // namespace carom::sensor_tests
