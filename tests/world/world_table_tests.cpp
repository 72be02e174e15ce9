// The table: a ball's states in a world against the textbook closed forms (a stun shot rolls at
// 2v/(7·μs·g) with 5/7 of its speed, a rolling ball stops after v²/(2·μr·g), a spin stops at
// 2R|ω|/(5·μsp·g)); a 16-ball break that comes to rest in finitely many events with no overlap,
// no energy gained and no ball off the table but into a pocket; cushions that turn the spin;
// determinism and save/resume mid-shot; misuse.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <vector>

#include "carom/error.hpp"
#include "carom/world.hpp"

namespace carom::table_tests {
namespace {

constexpr double kRadius = 0.028575;  // a pool ball, in metres
constexpr double kMass = 0.17;
constexpr double kWidth = 2.54;  // a 9-foot table's playing surface
constexpr double kHeight = 1.27;

Table cloth() { return Table{}; }

WorldDef open_table() {
  WorldDef def;
  def.table = cloth();
  return def;
}

WorldDef box_table() {
  WorldDef def;
  def.boundary = Boundary::box;
  def.lower = {0.0, 0.0};
  def.upper = {kWidth, kHeight};
  def.restitution = 0.95;
  def.table = cloth();
  return def;
}

BallDef pool_ball(Vec2 at, Vec2 velocity = {}, Spin spin = {}) {
  BallDef def;
  def.position = at;
  def.velocity = velocity;
  def.radius = kRadius;
  def.mass = kMass;
  def.spin = spin;
  return def;
}

// The ball's states through one run to rest, in order.
std::vector<MotionEvent> events_of(const World& world, BallId id) {
  std::vector<MotionEvent> out;
  for (const MotionEvent& e : world.motion_events()) {
    if (e.ball == id) out.push_back(e);
  }
  return out;
}

TEST(WorldTable, StunShotRollsAtTheTextbookTimeWithFiveSeventhsOfItsSpeed) {
  const Table t = cloth();
  for (const double speed : {0.5, 1.0, 3.0, 8.0}) {
    World world(open_table());
    const BallId ball = world.add_ball(pool_ball({0.0, 0.0}, {speed * 0.6, speed * 0.8}));
    ASSERT_EQ(world.motion_state(ball), MotionState::sliding);
    const double rolls_at = 2.0 * speed / (7.0 * t.sliding_friction * t.g);
    world.run_until(rolls_at * 0.5);
    EXPECT_EQ(world.motion_state(ball), MotionState::sliding);
    world.run_until(rolls_at * (1.0 + 1e-9));
    EXPECT_EQ(world.motion_state(ball), MotionState::rolling);
    const std::vector<MotionEvent> rolled = events_of(world, ball);
    ASSERT_EQ(rolled.size(), 1U);
    EXPECT_EQ(rolled[0].from, MotionState::sliding);
    EXPECT_EQ(rolled[0].to, MotionState::rolling);
    EXPECT_NEAR(rolled[0].time, rolls_at, 1e-14 * rolls_at);
    const double rolling_speed = 5.0 / 7.0 * speed;
    EXPECT_NEAR(length(world.velocity(ball)), rolling_speed, 1e-6 * speed);
    // Rolling: the spin follows the velocity, ω = ẑ × v / R.
    const Spin spin = world.spin(ball);
    EXPECT_NEAR(spin.x, -world.velocity(ball).y / kRadius, 1e-9 * speed / kRadius);
    EXPECT_NEAR(spin.y, world.velocity(ball).x / kRadius, 1e-9 * speed / kRadius);

    // It stops after v²/(2·μr·g) more, at v/(μr·g) after it began to roll.
    EXPECT_EQ(world.run_collisions(1), 0U);
    EXPECT_EQ(world.stop_reason(), StopReason::no_more_contacts);
    EXPECT_TRUE(world.at_rest());
    const double slide = speed * rolls_at - 0.5 * t.sliding_friction * t.g * rolls_at * rolls_at;
    const double roll = rolling_speed * rolling_speed / (2.0 * t.rolling_friction * t.g);
    EXPECT_NEAR(length(world.position(ball)), slide + roll, 1e-12 * (slide + roll));
    EXPECT_NEAR(world.time(), rolls_at + rolling_speed / (t.rolling_friction * t.g),
                1e-12 * world.time());
    EXPECT_EQ(world.motion_state(ball), MotionState::stationary);
    // The direction never changed: stun, roll and stop on the one line.
    const Vec2 at = world.position(ball);
    EXPECT_NEAR(at.x * 0.8 - at.y * 0.6, 0.0, 1e-12 * length(at));
  }
}

TEST(WorldTable, ASpinningBallStopsAtTheClosedFormTime) {
  const Table t = cloth();
  World world(open_table());
  const double omega = 40.0;
  const BallId ball = world.add_ball(pool_ball({0.0, 0.0}, {}, {0.0, 0.0, omega}));
  EXPECT_EQ(world.motion_state(ball), MotionState::spinning);
  EXPECT_EQ(world.run_collisions(1), 0U);
  const double stops = 2.0 * kRadius * omega / (5.0 * t.spinning_friction * t.g);
  EXPECT_NEAR(world.time(), stops, 1e-14 * stops);
  EXPECT_EQ(world.motion_state(ball), MotionState::stationary);
  EXPECT_EQ(world.position(ball), (Vec2{0.0, 0.0}));
  EXPECT_EQ(world.spin(ball), Spin{});
}

// Through the slide the friction acts at the contact point, so the angular momentum about it is
// kept: the ball rolls at v₀ − 2/7·u₀ (u₀ the contact point's slip). Energy never rises.
TEST(WorldTable, SlideToRollKeepsTheAngularMomentumAboutTheContactPoint) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    World world(open_table());
    const BallId ball = world.add_ball(pool_ball({0.0, 0.0}));
    CueStrike cue;
    cue.speed = 1.0 + 3.0 * (unit(random) + 1.0);
    cue.direction = std::numbers::pi * unit(random);
    cue.side = 0.6 * kRadius * unit(random);
    cue.height = 0.6 * kRadius * unit(random);
    world.strike(ball, cue);
    const Vec2 v0 = world.velocity(ball);
    const Spin w0 = world.spin(ball);
    const Vec2 slip{v0.x - kRadius * w0.y, v0.y + kRadius * w0.x};
    const double energy0 = world.kinetic_energy() + 0.2 * kMass * kRadius * kRadius *
                                                        (w0.x * w0.x + w0.y * w0.y + w0.z * w0.z);
    ASSERT_EQ(world.motion_state(ball), MotionState::sliding);
    double previous = energy0;
    // Through its states, one by one.
    while (world.motion_state(ball) == MotionState::sliding) {
      world.run_collisions(1, world.time() + 0.01);
      const Spin w = world.spin(ball);
      const double energy = world.kinetic_energy() +
                            0.2 * kMass * kRadius * kRadius * (w.x * w.x + w.y * w.y + w.z * w.z);
      ASSERT_LE(energy, previous * (1.0 + 1e-12)) << "case " << i;
      previous = energy;
    }
    ASSERT_EQ(world.motion_state(ball), MotionState::rolling) << "case " << i;
    const Vec2 rolls = world.velocity(ball);
    const Vec2 expected = v0 - slip * (2.0 / 7.0);
    // (The velocity read a little after the change: the roll has slowed it by μr·g·dt.)
    EXPECT_NEAR(rolls.x, expected.x, 1e-3 * length(v0)) << "case " << i;
    EXPECT_NEAR(rolls.y, expected.y, 1e-3 * length(v0)) << "case " << i;
  }
}

// The 15 balls of a rack (a triangle, apex towards the cue ball) and the cue ball, on a 9-foot
// table with six pockets.
struct Break {
  World world{box_table()};
  BallId cue;
  std::vector<BallId> balls;
};

Break racked() {
  Break b;
  const double gap = 1e-7;  // between neighbours: racks are never perfectly tight
  const double d = 2.0 * kRadius + gap;
  const Vec2 apex{0.75 * kWidth, 0.5 * kHeight};
  for (int row = 0; row < 5; ++row) {
    for (int k = 0; k <= row; ++k) {
      const Vec2 at{apex.x + row * d * std::sqrt(3.0) / 2.0, apex.y + (k - 0.5 * row) * d};
      b.balls.push_back(b.world.add_ball(pool_ball(at)));
    }
  }
  const double pocket = 0.06;
  for (const Vec2 p :
       {Vec2{0.0, 0.0}, Vec2{0.5 * kWidth, -0.02}, Vec2{kWidth, 0.0}, Vec2{0.0, kHeight},
        Vec2{0.5 * kWidth, kHeight + 0.02}, Vec2{kWidth, kHeight}}) {
    b.world.add_sensor(Ball{p, pocket}, SensorAction::remove_ball);
  }
  b.cue = b.world.add_ball(pool_ball({0.25 * kWidth, 0.5 * kHeight + 0.01}));
  CueStrike strike;
  strike.speed = 8.0;
  strike.height = 0.2 * kRadius;
  b.world.strike(b.cue, strike);
  return b;
}

double total_energy(const World& world) {
  double energy = world.kinetic_energy();
  for (const BallId id : world.balls()) {
    const Spin w = world.spin(id);
    energy += 0.2 * kMass * kRadius * kRadius * (w.x * w.x + w.y * w.y + w.z * w.z);
  }
  return energy;
}

TEST(WorldTable, ABreakComesToRestWithoutOverlapOrEnergyGained) {
  Break b = racked();
  double energy = total_energy(b.world);
  std::uint64_t contacts = 0;
  int runs = 0;
  for (; runs < 100000 && !b.world.at_rest(); ++runs) {
    contacts += b.world.run_collisions(1);
    ASSERT_EQ(b.world.audit(), std::nullopt) << "after " << contacts << " contacts";
    const double now = total_energy(b.world);
    ASSERT_LE(now, energy * (1.0 + 1e-12) + 1e-15) << "after " << contacts << " contacts";
    energy = now;
    for (const BallId id : b.world.balls()) {
      const Vec2 p = b.world.position(id);
      ASSERT_TRUE(p.x >= kRadius * (1.0 - 1e-9) && p.x <= kWidth - kRadius * (1.0 - 1e-9) &&
                  p.y >= kRadius * (1.0 - 1e-9) && p.y <= kHeight - kRadius * (1.0 - 1e-9));
    }
  }
  EXPECT_TRUE(b.world.at_rest());
  EXPECT_GT(contacts, 20U);  // the rack broke
  EXPECT_EQ(b.world.audit_all_pairs(), std::nullopt);
  for (const BallId id : b.world.balls()) {
    EXPECT_EQ(b.world.motion_state(id), MotionState::stationary);
  }
}

TEST(WorldTable, TheSameShotGivesBitIdenticalResultsAndResumesMidShot) {
  Break first = racked();
  Break second = racked();
  first.world.run_collisions(40);
  second.world.run_collisions(40);
  std::stringstream saved(std::ios::in | std::ios::out | std::ios::binary);
  second.world.save(saved);
  World resumed = World::load(saved);
  first.world.run_collisions(1'000'000);
  resumed.run_collisions(1'000'000);
  ASSERT_TRUE(first.world.at_rest());
  EXPECT_EQ(first.world.time(), resumed.time());
  EXPECT_EQ(first.world.collision_count(), resumed.collision_count());
  ASSERT_EQ(first.world.balls(), resumed.balls());
  for (const BallId id : first.world.balls()) {
    EXPECT_EQ(first.world.position(id), resumed.position(id));
    EXPECT_EQ(first.world.spin(id), resumed.spin(id));
  }
  ASSERT_EQ(first.world.motion_events().size(), resumed.motion_events().size());
}

// A ball that a pocket took leaves its slot's table state behind: a loaded world saves to the
// same bytes again (found by the fuzzer).
TEST(WorldTable, AWorldWithARemovedBallSavesAgainToTheSameBytes) {
  World world(box_table());
  world.add_sensor(Ball{{0.1, 0.1}, 0.06}, SensorAction::remove_ball);
  world.add_ball(pool_ball({0.1, 0.1}, {0.5, 0.2}));  // sliding on the pocket: removed at once
  const BallId cue = world.add_ball(pool_ball({1.0, 0.6}));
  CueStrike strike;
  strike.speed = 2.0;
  strike.height = 0.3 * kRadius;
  world.strike(cue, strike);
  world.run_until(0.2);
  ASSERT_EQ(world.ball_count(), 1U);
  std::ostringstream first(std::ios::binary);
  world.save(first);
  std::istringstream in(first.str(), std::ios::binary);
  const World loaded = World::load(in);
  std::ostringstream second(std::ios::binary);
  loaded.save(second);
  EXPECT_EQ(second.str(), first.str());
}

// A ball rolling straight into a cushion at right angles comes back with backspin from the nose
// above its equator, slides, and rolls out slower than the restitution alone would leave it.
TEST(WorldTable, ACushionAboveTheEquatorTurnsTheSpin) {
  World world(box_table());
  const double speed = 1.0;
  const BallId ball = world.add_ball(
      pool_ball({kWidth - 0.2, 0.5 * kHeight}, {speed, 0.0}, {0.0, speed / kRadius, 0.0}));
  ASSERT_EQ(world.motion_state(ball), MotionState::rolling);
  ASSERT_EQ(world.run_collisions(1), 1U);
  const ContactEvent hit = world.contacts()[0];
  EXPECT_EQ(hit.kind, ContactKind::ball_wall);
  EXPECT_LT(world.velocity(ball).x, 0.0);
  EXPECT_EQ(world.motion_state(ball), MotionState::sliding);
  // It comes back slower than the cushion's restitution alone would send it (the friction on the
  // nose takes its share), by the impulse the contact reports.
  EXPECT_NEAR(world.velocity(ball).x, hit.approach_speed - hit.impulse / kMass, 1e-12);
  EXPECT_LT(-world.velocity(ball).x, cloth().cushion_restitution * speed);
  EXPECT_EQ(world.velocity(ball).y, 0.0);
  // The topspin it rolled in with is turned: its contact point slips backwards.
  EXPECT_LT(world.spin(ball).y, speed / kRadius);
  world.run_collisions(1'000'000);
  EXPECT_TRUE(world.at_rest());
}

TEST(WorldTable, MisuseIsRefusedWithTheArgumentNamed) {
  WorldDef def = open_table();
  def.gravity = {0.0, -9.81};
  EXPECT_THROW(World{def}, InvalidArgument);
  def = open_table();
  def.table->cushion_height = 1.2;
  EXPECT_THROW(World{def}, InvalidArgument);
  def = open_table();
  def.table->sliding_friction = -0.1;
  EXPECT_THROW(World{def}, InvalidArgument);

  World plain;
  const BallId id = plain.add_ball(BallDef{});
  EXPECT_THROW(static_cast<void>(plain.spin(id)), InvalidArgument);
  EXPECT_THROW(plain.strike(id, CueStrike{}), InvalidArgument);
  BallDef spinning;
  spinning.position = {5.0, 5.0};
  spinning.spin = {0.0, 0.0, 1.0};
  EXPECT_THROW(plain.add_ball(spinning), InvalidArgument);
  EXPECT_EQ(plain.ball_count(), 1U);  // the refused ball left nothing behind
  EXPECT_EQ(plain.audit(), std::nullopt);

  World table(box_table());
  const BallId ball = table.add_ball(pool_ball({1.0, 0.5}));
  CueStrike miss;
  miss.speed = 1.0;
  miss.side = kRadius;  // outside the ball
  try {
    table.strike(ball, miss);
    FAIL() << "a strike outside the ball was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.argument(), "cue.side");
  }
  EXPECT_THROW(table.set_growth_rate(0.1), InvalidArgument);
  EXPECT_THROW(table.set_gravity({0.0, -1.0}), InvalidArgument);
  EXPECT_THROW(static_cast<void>(table.set_temperature(1.0)), InvalidArgument);
  const WallId wall = table.add_segment({{0.5, 0.2}, {0.5, 0.4}});
  WallMotion push;
  push.velocity = {1.0, 0.0};
  EXPECT_THROW(table.set_wall_motion(wall, push), InvalidArgument);
}

}  // namespace
}  // namespace carom::table_tests
