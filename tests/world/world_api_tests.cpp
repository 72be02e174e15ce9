// The World's API contract (include/carom/world.hpp): defaults, handles, validation, placement,
// queries, the ways of advancing time, the stop condition, contact order, determinism.
#include <gtest/gtest.h>
#include <unistd.h>  // alarm: a watchdog for calls that might never return

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "carom/error.hpp"
#include "carom/world.hpp"

namespace carom {
namespace {

constexpr double kStep = 1.0 / 60.0;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Outcomes exact in real arithmetic hold to a few roundings.
constexpr double kRoundingTol = 1e-12;
// set_position(nearest_free) stops "where it first touches": touching to 1e-9 of the contact
// distance, the audit's own default tolerance for overlap.
constexpr double kTouchTol = 1e-9;

BallDef ball_at(Vec2 position, Vec2 velocity = {}, double radius = 0.5) {
  BallDef def;
  def.position = position;
  def.velocity = velocity;
  def.radius = radius;
  return def;
}

// A box [0, 20]² of per_row² balls of assorted sizes and masses on a jittered grid, moving in
// random directions at up to `speed`.
World box_of_balls(std::uint64_t seed, int per_row, double speed);

// Expects call() to throw carom::InvalidArgument whose message names `argument`.
template <class Call>
void expect_invalid(Call&& call, std::string_view argument) {
  try {
    call();
    ADD_FAILURE() << "no exception; expected carom::InvalidArgument naming " << argument;
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string_view(e.what()).find(argument), std::string_view::npos)
        << "message: " << e.what() << "\nexpected it to name: " << argument;
  }
}

// ---- defaults --------------------------------------------------------------------------------

TEST(WorldApi, DefsHaveSafeDefaults) {
  const WorldDef world_def;
  EXPECT_EQ(world_def.boundary, Boundary::open);
  EXPECT_EQ(world_def.restitution, 1.0);
  EXPECT_EQ(world_def.collapse_time, 0.0);
  EXPECT_EQ(world_def.cell_size, 0.0);
  const BallDef ball_def;
  EXPECT_EQ(ball_def.radius, 1.0);
  EXPECT_EQ(ball_def.mass, 1.0);
  EXPECT_FALSE(ball_def.restitution.has_value());
  EXPECT_EQ(ball_def.user_data, 0u);
  EXPECT_EQ(ball_def.velocity, Vec2{});
  EXPECT_TRUE(BallId{}.is_null());
}

TEST(WorldApi, NewWorldIsEmptyAtTimeZero) {
  const World world;
  EXPECT_EQ(world.time(), 0.0);
  EXPECT_EQ(world.ball_count(), 0u);
  EXPECT_EQ(world.wall_count(), 0u);
  EXPECT_EQ(world.collision_count(), 0u);
  EXPECT_TRUE(world.contacts().empty());
  EXPECT_TRUE(world.balls().empty());
  EXPECT_FALSE(world.stopped_early());
  EXPECT_EQ(world.kinetic_energy(), 0.0);
  EXPECT_EQ(world.momentum(), Vec2{});
  EXPECT_FALSE(world.audit().has_value());
}

TEST(WorldApi, BallWithoutRestitutionUsesTheWorlds) {
  WorldDef def;
  def.restitution = 0.5;
  World world(def);
  world.add_segment({{2.0, -5.0}, {2.0, 5.0}});
  const BallId ball = world.add_ball(ball_at({0.0, 0.0}, {4.0, 0.0}));
  world.run_until(2.0);
  ASSERT_EQ(world.contacts().size(), 1u);
  EXPECT_NEAR(world.velocity(ball).x, -2.0, kRoundingTol);
}

TEST(WorldApi, QueriesReturnWhatWasAdded) {
  World world;
  BallDef def = ball_at({1.0, 2.0}, {3.0, 4.0}, 0.25);
  def.mass = 2.5;
  def.user_data = 0xC0FFEE;
  const BallId id = world.add_ball(def);
  EXPECT_FALSE(id.is_null());
  EXPECT_TRUE(world.contains(id));
  EXPECT_EQ(world.position(id), (Vec2{1.0, 2.0}));
  EXPECT_EQ(world.velocity(id), (Vec2{3.0, 4.0}));
  EXPECT_EQ(world.radius(id), 0.25);
  EXPECT_EQ(world.mass(id), 2.5);
  EXPECT_EQ(world.user_data(id), 0xC0FFEEu);
  EXPECT_EQ(world.ball_count(), 1u);
  ASSERT_EQ(world.balls().size(), 1u);
  EXPECT_EQ(world.balls()[0], id);
}

// ---- handles ---------------------------------------------------------------------------------

void expect_every_use_throws(World& world, BallId id) {
  EXPECT_FALSE(world.contains(id));
  EXPECT_THROW(static_cast<void>(world.position(id)), InvalidArgument);
  EXPECT_THROW(static_cast<void>(world.velocity(id)), InvalidArgument);
  EXPECT_THROW(static_cast<void>(world.radius(id)), InvalidArgument);
  EXPECT_THROW(static_cast<void>(world.mass(id)), InvalidArgument);
  EXPECT_THROW(static_cast<void>(world.user_data(id)), InvalidArgument);
  EXPECT_THROW(world.set_velocity(id, {1.0, 0.0}), InvalidArgument);
  EXPECT_THROW(static_cast<void>(world.set_position(id, {50.0, 50.0})), InvalidArgument);
  EXPECT_THROW(world.remove_ball(id), InvalidArgument);
}

TEST(WorldApi, RemovedBallsHandleIsStaleAndItsSlotIsReused) {
  World world;
  const BallId first = world.add_ball(ball_at({0.0, 0.0}));
  const BallId second = world.add_ball(ball_at({5.0, 0.0}));
  world.remove_ball(first);
  EXPECT_EQ(world.ball_count(), 1u);
  expect_every_use_throws(world, first);
  EXPECT_TRUE(world.contains(second));

  const BallId reused = world.add_ball(ball_at({0.0, 0.0}));
  EXPECT_EQ(reused.index, first.index);            // the freed slot is reused...
  EXPECT_NE(reused.generation, first.generation);  // ...under a new generation
  EXPECT_FALSE(reused.is_null());
  EXPECT_TRUE(world.contains(reused));
  expect_every_use_throws(world, first);  // the old handle stays stale
  EXPECT_EQ(world.position(reused), (Vec2{0.0, 0.0}));
  const std::vector<BallId> live = world.balls();
  ASSERT_EQ(live.size(), 2u);
  EXPECT_EQ(live[0], reused);  // slot order
  EXPECT_EQ(live[1], second);
}

TEST(WorldApi, NullHandleThrows) {
  World world;
  world.add_ball(ball_at({0.0, 0.0}));
  expect_every_use_throws(world, BallId{});
}

TEST(WorldApi, HandleFromAnotherSlotRangeThrows) {
  World world;
  const BallId id = world.add_ball(ball_at({0.0, 0.0}));
  expect_every_use_throws(world, BallId{id.index + 100, id.generation});
}

// ---- placement is checked --------------------------------------------------------------------

TEST(WorldApi, AddBallOverlappingABallThrowsAndAddsNothing) {
  World world;
  world.add_ball(ball_at({0.0, 0.0}));
  EXPECT_THROW(world.add_ball(ball_at({0.9, 0.0})), InvalidArgument);
  EXPECT_THROW(world.add_ball(ball_at({0.0, 0.0})), InvalidArgument);
  EXPECT_EQ(world.ball_count(), 1u);
  world.add_ball(ball_at({1.0, 0.0}));  // touching is not overlapping
  EXPECT_EQ(world.ball_count(), 2u);
}

TEST(WorldApi, AddBallOverlappingAWallOrArcThrows) {
  World world;
  world.add_segment({{-5.0, 0.0}, {5.0, 0.0}});
  world.add_arc({{20.0, 0.0}, 3.0, 0.0, std::numbers::pi});
  EXPECT_THROW(world.add_ball(ball_at({0.0, 0.3})), InvalidArgument);
  EXPECT_THROW(world.add_ball(ball_at({5.2, 0.0})), InvalidArgument);   // over an end point
  EXPECT_THROW(world.add_ball(ball_at({20.0, 3.2})), InvalidArgument);  // on the arc
  EXPECT_EQ(world.ball_count(), 0u);
  world.add_ball(ball_at({20.0, -3.0}));  // where the arc is not (its lower half is open)
  world.add_ball(ball_at({0.0, 0.5}));    // touching the wall
  EXPECT_EQ(world.ball_count(), 2u);
}

TEST(WorldApi, AddBallOutsideOrAcrossTheBoxThrows) {
  World world(WorldDef{Boundary::box, {0.0, 0.0}, {10.0, 10.0}});
  EXPECT_THROW(world.add_ball(ball_at({-3.0, 5.0})), InvalidArgument);
  EXPECT_THROW(world.add_ball(ball_at({5.0, 10.2})), InvalidArgument);
  EXPECT_THROW(world.add_ball(ball_at({0.2, 5.0})), InvalidArgument);  // across the side
  EXPECT_EQ(world.ball_count(), 0u);
  world.add_ball(ball_at({0.5, 5.0}));
  EXPECT_EQ(world.ball_count(), 1u);
}

// ---- bad numbers name their argument ---------------------------------------------------------

TEST(WorldApi, BadBallNumbersThrowNamingTheArgument) {
  World world;
  BallDef def = ball_at({0.0, 0.0});
  def.position.x = kNaN;
  expect_invalid([&] { world.add_ball(def); }, "position");
  def = ball_at({0.0, 0.0}, {kNaN, 0.0});
  expect_invalid([&] { world.add_ball(def); }, "velocity");
  for (double radius : {0.0, -1.0, kNaN, std::numeric_limits<double>::infinity()}) {
    def = ball_at({0.0, 0.0}, {}, radius);
    expect_invalid([&] { world.add_ball(def); }, "radius");
  }
  for (double mass : {0.0, -1.0, kNaN}) {
    def = ball_at({0.0, 0.0});
    def.mass = mass;
    expect_invalid([&] { world.add_ball(def); }, "mass");
  }
  for (double restitution : {-0.1, 1.1, kNaN}) {
    def = ball_at({0.0, 0.0});
    def.restitution = restitution;
    expect_invalid([&] { world.add_ball(def); }, "restitution");
  }
  EXPECT_EQ(world.ball_count(), 0u);
}

TEST(WorldApi, BadCallNumbersThrowNamingTheArgument) {
  World world;
  const BallId id = world.add_ball(ball_at({0.0, 0.0}));
  world.step(1.0);
  expect_invalid([&] { world.step(-1.0); }, "dt");
  expect_invalid([&] { world.step(kNaN); }, "dt");
  expect_invalid([&] { world.run_until(0.5); }, "time");  // before time()
  expect_invalid([&] { world.run_until(kNaN); }, "time");
  expect_invalid([&] { world.set_velocity(id, {kNaN, 0.0}); }, "velocity");
  expect_invalid([&] { static_cast<void>(world.set_position(id, {0.0, kNaN})); }, "position");
  EXPECT_EQ(world.time(), 1.0);
}

TEST(WorldApi, TheDefAndTheWallsAreReadBackAsGiven) {
  WorldDef def;
  def.boundary = Boundary::box;
  def.lower = {-1.0, -2.0};
  def.upper = {30.0, 20.0};
  def.restitution = 0.75;
  def.collapse_time = 0.125;
  World world(def);
  EXPECT_EQ(world.def().boundary, Boundary::box);
  EXPECT_EQ(world.def().upper, def.upper);
  EXPECT_EQ(world.def().restitution, 0.75);
  EXPECT_EQ(world.def().collapse_time, 0.125);
  const Segment segment{{2.0, 3.0}, {5.0, 7.0}};
  const Arc arc{{15.0, 10.0}, 3.0, 0.5, 2.5};
  const WallId s = world.add_segment(segment);
  const WallId a = world.add_arc(arc);
  ASSERT_EQ(world.wall_count(), 6U);
  // The box's bottom wall comes first, from lower-left to lower-right.
  const auto bottom = std::get<Segment>(world.wall(0));
  EXPECT_EQ(bottom.a, def.lower);
  EXPECT_EQ(bottom.b, (Vec2{30.0, -2.0}));
  EXPECT_EQ(std::get<Segment>(world.wall(s)).b, segment.b);
  const Arc back = std::get<Arc>(world.wall(a));
  EXPECT_EQ(back.center, arc.center);
  EXPECT_EQ(back.end_angle, arc.end_angle);
  EXPECT_THROW((void)world.wall(6), InvalidArgument);
}

TEST(WorldApi, BadWorldDefThrows) {
  WorldDef def;
  def.restitution = 2.0;
  expect_invalid([&] { World world(def); }, "restitution");
  def = WorldDef{};
  def.collapse_time = -1.0;
  expect_invalid([&] { World world(def); }, "collapse_time");
  def = WorldDef{Boundary::box, {0.0, 0.0}, {0.0, 10.0}};  // an empty box
  EXPECT_THROW(World world(def), InvalidArgument);
}

// ---- changing balls between steps ------------------------------------------------------------

TEST(WorldApi, SetVelocityTakesEffectFromNow) {
  World world;
  const BallId id = world.add_ball(ball_at({0.0, 0.0}, {1.0, 0.0}));
  world.step(1.0);
  world.set_velocity(id, {0.0, 2.0});
  EXPECT_EQ(world.velocity(id), (Vec2{0.0, 2.0}));
  world.step(1.0);
  EXPECT_NEAR(world.position(id).x, 1.0, kRoundingTol);
  EXPECT_NEAR(world.position(id).y, 2.0, kRoundingTol);
}

// Regression: a change to one ball made the World re-predict every ball from its stored
// position as if that were its place now, though balls untouched by recent contacts are stored
// at older local times. Cells larger than the scene keep cell crossings (which would re-predict
// the balls and hide the error) out of the way.
TEST(WorldApi, ChangingOneBallLeavesTheOtherPairsOnTime) {
  WorldDef def;
  def.cell_size = 100.0;
  for (int how = 0; how < 3; ++how) {
    World world(def);
    world.add_ball(ball_at({0.0, 0.0}, {1.0, 0.0}));
    world.add_ball(ball_at({10.0, 0.0}, {-1.0, 0.0}));  // meets the first at t = 4.5
    world.add_ball(ball_at({0.0, 20.0}, {1.0, 0.0}));
    world.add_ball(ball_at({3.0, 20.0}, {-1.0, 0.0}));  // a pair meeting at t = 1
    const BallId other = world.add_ball(ball_at({0.0, 50.0}, {0.0, 1.0}));
    if (how == 0) {
      world.step(1.0);
    } else if (how == 1) {
      world.run_until(1.0);
    } else {
      ASSERT_EQ(world.run_collisions(1), 1u);
    }
    world.set_velocity(other, {0.0, 2.0});  // far from everything
    world.run_until(10.0);
    ASSERT_FALSE(world.contacts().empty()) << "advanced by method " << how;
    EXPECT_NEAR(world.contacts()[0].time, 4.5, kRoundingTol) << "advanced by method " << how;
    EXPECT_FALSE(world.audit().has_value()) << "advanced by method " << how;
  }
}

TEST(WorldApi, SetPositionRefuseMovesOrThrowsLeavingTheBall) {
  World world;
  const BallId a = world.add_ball(ball_at({0.0, 0.0}));
  world.add_ball(ball_at({5.0, 0.0}));
  world.add_segment({{0.0, 10.0}, {10.0, 10.0}});
  EXPECT_EQ(world.set_position(a, {2.0, 3.0}), (Vec2{2.0, 3.0}));
  EXPECT_EQ(world.position(a), (Vec2{2.0, 3.0}));
  EXPECT_THROW(static_cast<void>(world.set_position(a, {5.5, 0.0})), InvalidArgument);
  EXPECT_THROW(static_cast<void>(world.set_position(a, {5.0, 9.8}, Placement::refuse)),
               InvalidArgument);
  EXPECT_EQ(world.position(a), (Vec2{2.0, 3.0}));  // unchanged by the refusals
  EXPECT_FALSE(world.audit().has_value());
}

TEST(WorldApi, SetPositionNearestFreeStopsWhereItFirstTouches) {
  World world;
  const BallId dragged = world.add_ball(ball_at({0.0, 0.0}));
  world.add_ball(ball_at({5.0, 0.0}));
  // Dragged through the other ball: stops touching it, at x = 4.
  const Vec2 end = world.set_position(dragged, {10.0, 0.0}, Placement::nearest_free);
  EXPECT_EQ(world.position(dragged), end);
  EXPECT_NEAR(end.x, 4.0, kTouchTol);
  EXPECT_NEAR(end.y, 0.0, kTouchTol);
  EXPECT_FALSE(world.audit().has_value());

  // Dragged into a wall at an angle: stops touching it, on the line of the drag.
  world.add_segment({{-10.0, 3.0}, {10.0, 3.0}});
  const Vec2 from = world.position(dragged);
  const Vec2 target = from + Vec2{-2.0, 6.0};
  const Vec2 stop = world.set_position(dragged, target, Placement::nearest_free);
  EXPECT_NEAR(stop.y, 2.5, kTouchTol);  // the ball's top touches the wall at y = 3
  EXPECT_NEAR(cross(target - from, stop - from), 0.0, kTouchTol);  // on the drag's line
  EXPECT_FALSE(world.audit().has_value());

  // A free target is reached exactly.
  EXPECT_EQ(world.set_position(dragged, {0.0, -4.0}, Placement::nearest_free), (Vec2{0.0, -4.0}));
}

// Drags ball `id` of a box [0, side]² with nearest_free: never refused, never leaving an
// overlap, and, when cut short (counted), touching something: the nearest ball or wall one
// contact distance away, to 1e-9 of it.
void drag_free_or_touching(World& world, BallId id, Vec2 target, double side, int drag,
                           int& cut_short) {
  Vec2 end;
  ASSERT_NO_THROW(end = world.set_position(id, target, Placement::nearest_free)) << "drag " << drag;
  ASSERT_FALSE(world.audit().has_value()) << "drag " << drag << ": " << *world.audit();
  if (end == target) return;
  ++cut_short;
  const double r = world.radius(id);
  double gap = std::min({end.x - r, end.y - r, side - r - end.x, side - r - end.y});
  for (const BallId other : world.balls()) {
    if (other == id) continue;
    gap = std::min(gap, distance(end, world.position(other)) - r - world.radius(other));
  }
  ASSERT_NEAR(gap, 0.0, kTouchTol * 2.0 * r) << "drag " << drag;
}

// Drags at random through a crowd: nearest_free never refuses, never leaves an overlap, and a
// drag cut short ends touching something (a ball or a wall) to 1e-9 of the contact distance.
TEST(WorldApi, SetPositionNearestFreeThroughACrowd) {
  constexpr double kSide = 20.0;
  World world = box_of_balls(57, 6, 0.0);  // at rest: only the drags move anything
  std::mt19937_64 engine(57);
  std::uniform_real_distribution<double> coordinate(-5.0, kSide + 5.0);  // some targets outside
  const std::vector<BallId> ids = world.balls();
  int cut_short = 0;
  for (int drag = 0; drag < 300; ++drag) {
    const BallId id = ids[static_cast<std::size_t>(drag) % ids.size()];
    const Vec2 target{coordinate(engine), coordinate(engine)};
    ASSERT_NO_FATAL_FAILURE(drag_free_or_touching(world, id, target, kSide, drag, cut_short));
  }
  EXPECT_GT(cut_short, 100);
}

// Short drags in a large moving crowd, a step between them: these sweep only the balls in the
// cells around their paths (a game's pointer, every frame), with the same promises as above.
TEST(WorldApi, SetPositionNearestFreeShortDragsInALargeMovingCrowd) {
  World world = box_of_balls(58, 40, 2.0);  // 1600 balls, radii 0.1 to 0.15, pitch 0.5
  std::mt19937_64 engine(58);
  std::uniform_real_distribution<double> step(-1.5, 1.5);
  const std::vector<BallId> ids = world.balls();
  int cut_short = 0;
  for (int drag = 0; drag < 400; ++drag) {
    world.step(0.01);
    const BallId id = ids[(static_cast<std::size_t>(drag) * 37) % ids.size()];
    const Vec2 target = world.position(id) + Vec2{step(engine), step(engine)};
    ASSERT_NO_FATAL_FAILURE(drag_free_or_touching(world, id, target, 20.0, drag, cut_short));
  }
  EXPECT_GT(cut_short, 200);
}

// ---- energy and momentum ---------------------------------------------------------------------

TEST(WorldApi, KineticEnergyAndMomentumOfMovableBalls) {
  World world;
  BallDef heavy = ball_at({0.0, 0.0}, {3.0, 4.0});
  heavy.mass = 2.0;
  world.add_ball(heavy);
  BallDef light = ball_at({5.0, 0.0}, {-1.0, 0.0});
  light.mass = 0.5;
  world.add_ball(light);
  BallDef post = ball_at({10.0, 0.0});
  post.mass = kImmovable;
  const BallId post_id = world.add_ball(post);
  EXPECT_EQ(world.mass(post_id), kImmovable);
  EXPECT_DOUBLE_EQ(world.kinetic_energy(), 0.5 * 2.0 * 25.0 + 0.5 * 0.5 * 1.0);
  EXPECT_DOUBLE_EQ(world.momentum().x, 2.0 * 3.0 - 0.5);
  EXPECT_DOUBLE_EQ(world.momentum().y, 2.0 * 4.0);
}

TEST(WorldApi, ImmovableBallIsNeverMoved) {
  World world;
  BallDef post = ball_at({5.0, 0.0}, {}, 1.0);
  post.mass = kImmovable;
  const BallId post_id = world.add_ball(post);
  const BallId ball = world.add_ball(ball_at({0.0, 0.0}, {2.0, 0.0}));
  world.run_until(5.0);
  ASSERT_EQ(world.contacts().size(), 1u);
  EXPECT_EQ(world.position(post_id), (Vec2{5.0, 0.0}));
  EXPECT_EQ(world.velocity(post_id), Vec2{});
  EXPECT_NEAR(world.velocity(ball).x, -2.0, kRoundingTol);
}

// ---- contact events --------------------------------------------------------------------------

TEST(WorldApi, ContactEventDescribesTheContact) {
  World world;
  const WallId wall = world.add_segment({{3.0, -5.0}, {3.0, 5.0}});
  BallDef def = ball_at({0.0, 1.0}, {2.0, 0.0}, 1.0);
  def.mass = 2.0;
  const BallId ball = world.add_ball(def);
  world.run_until(3.0);
  ASSERT_EQ(world.contacts().size(), 1u);
  const ContactEvent& c = world.contacts()[0];
  EXPECT_EQ(c.kind, ContactKind::ball_wall);
  EXPECT_EQ(c.a, ball);
  EXPECT_EQ(c.wall, wall);
  EXPECT_NEAR(c.time, 1.0, kRoundingTol);
  EXPECT_NEAR(c.point.x, 3.0, kRoundingTol);
  EXPECT_NEAR(c.point.y, 1.0, kRoundingTol);
  EXPECT_NEAR(c.normal.x, 1.0, kRoundingTol);  // towards the wall
  EXPECT_NEAR(c.normal.y, 0.0, kRoundingTol);
  EXPECT_NEAR(c.approach_speed, 2.0, kRoundingTol);
  EXPECT_NEAR(c.impulse, 2.0 * 2.0 * 2.0, kRoundingTol);  // (1 + e)·m·speed
  EXPECT_EQ(world.collision_count(), 1u);
}

TEST(WorldApi, BallBallEventNamesTheLowerIndexFirst) {
  World world;
  const BallId left = world.add_ball(ball_at({0.0, 0.0}));
  const BallId right = world.add_ball(ball_at({4.0, 0.0}, {-2.0, 0.0}));
  world.run_until(3.0);
  ASSERT_EQ(world.contacts().size(), 1u);
  const ContactEvent& c = world.contacts()[0];
  EXPECT_EQ(c.kind, ContactKind::ball_ball);
  ASSERT_LT(left.index, right.index);
  EXPECT_EQ(c.a, left);
  EXPECT_EQ(c.b, right);
  EXPECT_NEAR(c.normal.x, 1.0, kRoundingTol);  // from a towards b
  EXPECT_NEAR(c.time, 1.5, kRoundingTol);
  EXPECT_NEAR(c.point.x, 0.5, kRoundingTol);
  EXPECT_GT(c.approach_speed, 0.0);
}

TEST(WorldApi, AddBoxAndPolylineNumberTheirWallsInOrder) {
  World world;
  EXPECT_EQ(world.add_segment({{100.0, 100.0}, {101.0, 100.0}}), 0u);
  const WallId box = world.add_box({0.0, 0.0}, {10.0, 10.0});
  EXPECT_EQ(box, 1u);
  EXPECT_EQ(world.wall_count(), 5u);
  const std::array<Vec2, 3> open_line{Vec2{20.0, 0.0}, Vec2{30.0, 0.0}, Vec2{30.0, 10.0}};
  EXPECT_EQ(world.add_polyline(open_line), 5u);
  EXPECT_EQ(world.wall_count(), 7u);
  // Bottom, right, top, left: a ball sent to each side meets box + 0, 1, 2, 3.
  const std::array<Vec2, 4> towards{Vec2{0.0, -1.0}, Vec2{1.0, 0.0}, Vec2{0.0, 1.0},
                                    Vec2{-1.0, 0.0}};
  for (std::uint32_t side = 0; side < 4; ++side) {
    const BallId id = world.add_ball(ball_at({5.0, 5.0}, towards[side]));
    world.step(10.0);
    ASSERT_FALSE(world.contacts().empty());
    EXPECT_EQ(world.contacts()[0].wall, box + side) << "side " << side;
    world.remove_ball(id);
  }
}

TEST(WorldApi, BoxBoundaryWallsAreWallsZeroToThree) {
  World world(WorldDef{Boundary::box, {0.0, 0.0}, {10.0, 10.0}});
  const std::array<Vec2, 4> towards{Vec2{0.0, -1.0}, Vec2{1.0, 0.0}, Vec2{0.0, 1.0},
                                    Vec2{-1.0, 0.0}};
  for (std::uint32_t side = 0; side < 4; ++side) {
    const BallId id = world.add_ball(ball_at({5.0, 5.0}, towards[side]));
    world.step(10.0);
    ASSERT_FALSE(world.contacts().empty());
    EXPECT_EQ(world.contacts()[0].wall, side) << "side " << side;
    world.remove_ball(id);
  }
}

// ---- advancing time --------------------------------------------------------------------------

TEST(WorldApi, StepAdvancesExactlyDt) {
  World world(WorldDef{Boundary::box, {0.0, 0.0}, {10.0, 10.0}});
  world.add_ball(ball_at({5.0, 5.0}, {3.0, 1.7}));
  for (int s = 0; s < 100; ++s) {
    const double before = world.time();
    const double dt = kStep * (1.0 + 0.01 * s);  // times that do not add up exactly
    const double advanced = world.step(dt);
    ASSERT_EQ(world.time(), before + dt) << "step " << s;
    // "returns the time advanced, less than dt only when the stop condition fired"
    ASSERT_EQ(advanced, dt) << "step " << s << std::setprecision(17) << ": returned " << advanced
                            << " for dt = " << dt;
  }
}

TEST(WorldApi, RunUntilReachesTheTimeExactly) {
  World world(WorldDef{Boundary::box, {0.0, 0.0}, {10.0, 10.0}});
  world.add_ball(ball_at({5.0, 5.0}, {3.0, 1.7}));
  world.run_until(0.1);
  EXPECT_EQ(world.time(), 0.1);
  world.run_until(0.1);  // no time at all is fine
  EXPECT_EQ(world.time(), 0.1);
  world.run_until(7.3);
  EXPECT_EQ(world.time(), 7.3);
  EXPECT_GT(world.collision_count(), 0u);
}

TEST(WorldApi, StepWithoutContactsClearsTheLastContacts) {
  World world;
  world.add_segment({{2.0, -5.0}, {2.0, 5.0}});
  world.add_ball(ball_at({0.0, 0.0}, {1.0, 0.0}));
  world.step(2.0);
  EXPECT_EQ(world.contacts().size(), 1u);
  world.step(1.0);  // moving away from the wall: nothing more
  EXPECT_TRUE(world.contacts().empty());
  EXPECT_EQ(world.collision_count(), 1u);
}

World box_of_balls(std::uint64_t seed, int per_row, double speed) {
  constexpr double kSide = 20.0;
  World world(WorldDef{Boundary::box, {0.0, 0.0}, {kSide, kSide}});
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double pitch = kSide / per_row;
  for (int i = 0; i < per_row; ++i) {
    for (int j = 0; j < per_row; ++j) {
      const double a = 2.0 * std::numbers::pi * unit(engine);
      // One draw a statement: the order a call's arguments are evaluated in is the compiler's
      // (g++ and clang built different boxes from the same seed). This is g++'s order, which the
      // tests below were written against.
      const double radius = 0.2 * pitch + 0.1 * pitch * unit(engine);
      const double speed_share = unit(engine);
      const double jitter_x = unit(engine);
      const double jitter_y = unit(engine);
      BallDef def = ball_at({(i + 0.5) * pitch + 0.2 * (jitter_x - 0.5) * pitch,
                             (j + 0.5) * pitch + 0.2 * (jitter_y - 0.5) * pitch},
                            Vec2{std::cos(a), std::sin(a)} * speed * speed_share, radius);
      def.mass = 0.5 + unit(engine);
      world.add_ball(def);
    }
  }
  return world;
}

// World::reserve only allocates: the same balls added after it run bit for bit as without it,
// and a count past the most a world holds is refused.
TEST(WorldApi, ReserveChangesNothingButAllocation) {
  World plain = box_of_balls(61, 8, 10.0);
  World reserved(WorldDef{Boundary::box, {0.0, 0.0}, {20.0, 20.0}});
  reserved.reserve(100);
  for (const BallId id : plain.balls()) {
    BallDef def = ball_at(plain.position(id), plain.velocity(id), plain.radius(id));
    def.mass = plain.mass(id);
    EXPECT_EQ(reserved.add_ball(def), id);
  }
  plain.run_collisions(2000);
  reserved.run_collisions(2000);
  for (const BallId id : plain.balls()) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(reserved.position(id).x),
              std::bit_cast<std::uint64_t>(plain.position(id).x));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(reserved.velocity(id).y),
              std::bit_cast<std::uint64_t>(plain.velocity(id).y));
  }
  EXPECT_THROW(reserved.reserve(std::size_t{1} << 31), InvalidArgument);
}

TEST(WorldApi, RunCollisionsResolvesExactlyThatMany) {
  World world = box_of_balls(51, 6, 10.0);
  for (std::uint64_t count : {1u, 7u, 40u}) {
    const std::uint64_t before = world.collision_count();
    ASSERT_EQ(world.run_collisions(count), count);
    ASSERT_EQ(world.contacts().size(), count);
    EXPECT_EQ(world.collision_count(), before + count);
    // It stops right after the last: the world's time is that contact's.
    EXPECT_EQ(world.time(), world.contacts().back().time);
    EXPECT_FALSE(world.audit().has_value());
  }
}

// A call that should return but might never do so runs in a child process under an alarm, so
// that a hang fails this test instead of stalling the whole suite. A correct answer takes
// microseconds; 5 s is generous even under a sanitizer.
constexpr unsigned kWatchdogSeconds = 5;

TEST(WorldApiDeathTest, RunCollisionsStopsShortWhenNothingWillHappenInAnOpenWorld) {
  World world;
  world.add_ball(ball_at({0.0, 0.0}, {-1.0, 0.0}));
  world.add_ball(ball_at({5.0, 0.0}, {1.0, 0.0}));  // moving apart for ever
  EXPECT_EXIT(
      {
        alarm(kWatchdogSeconds);
        const std::uint64_t resolved = world.run_collisions(3);
        std::_Exit(resolved == 0 && world.contacts().empty() ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "")
      << "run_collisions(3) with no contact ahead must return 0 (exit code 1: it returned "
         "something else; killed by SIGALRM: it never returned)";
}

TEST(WorldApiDeathTest, RunCollisionsStopsShortWhenNothingWillHappenInAPeriodicCell) {
  World world(WorldDef{Boundary::periodic, {0.0, 0.0}, {10.0, 10.0}});
  world.add_ball(ball_at({5.0, 5.0}, {1.0, 0.0}));  // alone: it wraps round for ever
  EXPECT_EXIT(
      {
        alarm(kWatchdogSeconds);
        std::_Exit(world.run_collisions(1) == 0 ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "")
      << "run_collisions(1) with no contact ahead must return 0 (killed by SIGALRM: it never "
         "returned)";
}

// Expects run_collisions(count) to return `expected` within the watchdog's time, in a child.
void expect_run_collisions_returns(World& world, std::uint64_t count, std::uint64_t expected) {
  EXPECT_EXIT(
      {
        alarm(kWatchdogSeconds);
        std::_Exit(world.run_collisions(count) == expected ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "")
      << "run_collisions(" << count << ") must return " << expected
      << " (exit code 1: it returned something else; killed by SIGALRM: it never returned)";
}

TEST(WorldApiDeathTest, RunCollisionsProvesNothingWillHappenForBallsMovingAwayFromWalls) {
  World world;
  world.add_segment({{-10.0, -3.0}, {10.0, -3.0}});
  world.add_arc({{0.0, 20.0}, 4.0, 0.0, std::numbers::pi});
  world.add_ball(ball_at({-3.0, 0.0}, {-1.0, 0.5}));
  world.add_ball(ball_at({3.0, 0.0}, {1.0, 0.25}));
  world.add_ball(ball_at({0.0, 30.0}, {0.0, 2.0}));  // above the arc, leaving it
  expect_run_collisions_returns(world, 4, 0);
}

TEST(WorldApiDeathTest, RunCollisionsProvesNothingWillHappenForParallelLanesInAPeriodicCell) {
  World world(WorldDef{Boundary::periodic, {0.0, 0.0}, {10.0, 10.0}});
  // Three lanes along x at different speeds, 2 apart (reach 1): they pass each other for ever.
  world.add_ball(ball_at({1.0, 1.0}, {1.0, 0.0}));
  world.add_ball(ball_at({1.0, 3.0}, {-2.0, 0.0}));
  world.add_ball(ball_at({1.0, 5.0}, {0.5, 0.0}));
  expect_run_collisions_returns(world, 1, 0);
  // A slanted group moving together: no relative motion at all.
  World together(WorldDef{Boundary::periodic, {0.0, 0.0}, {10.0, 10.0}});
  for (int i = 0; i < 4; ++i) together.add_ball(ball_at({1.0 + 2.0 * i, 1.5 * i}, {0.3, 1.7}));
  expect_run_collisions_returns(together, 1, 0);
}

TEST(WorldApi, RunCollisionsFindsAContactFarAwayAfterManyCrossings) {
  // Not provable early (the pair approaches), so the proof must not cut the run short.
  World world;
  world.add_ball(ball_at({0.0, 0.0}, {1.0, 0.0}));
  world.add_ball(ball_at({1000.0, 0.5}, {-1.0, 0.0}));
  for (int i = 0; i < 20; ++i) world.add_ball(ball_at({-100.0 - 3.0 * i, 50.0}, {0.0, 1.0}));
  ASSERT_EQ(world.run_collisions(1), 1u);
  EXPECT_NEAR(world.time(), (1000.0 - std::sqrt(1.0 - 0.25)) / 2.0, kRoundingTol * 1000.0);
}

TEST(WorldApi, RunCollisionsWithATimeLimitStopsThereWhenNoContactComesFirst) {
  // A slanted relative path on a torus: not provable either way, so a time limit bounds the run.
  World world(WorldDef{Boundary::periodic, {0.0, 0.0}, {10.0, 10.0}});
  const BallId a = world.add_ball(ball_at({1.0, 1.0}, {1.0, std::numbers::sqrt2}));
  world.add_ball(ball_at({6.0, 6.0}, {-0.5, 0.25}));
  const std::uint64_t resolved = world.run_collisions(1000000, 50.0);
  ASSERT_LT(resolved, 1000000u);  // two balls cannot meet a million times in 50 time units
  EXPECT_EQ(world.time(), 50.0);
  // Against run_until: the same contacts to the same time.
  World again(WorldDef{Boundary::periodic, {0.0, 0.0}, {10.0, 10.0}});
  again.add_ball(ball_at({1.0, 1.0}, {1.0, std::numbers::sqrt2}));
  again.add_ball(ball_at({6.0, 6.0}, {-0.5, 0.25}));
  again.run_until(50.0);
  EXPECT_EQ(again.contacts().size(), resolved);
  EXPECT_EQ(again.position(again.balls()[0]), world.position(a));
  EXPECT_THROW(world.run_collisions(1, 49.0), InvalidArgument);
  EXPECT_THROW(world.run_collisions(1, kNaN), InvalidArgument);
}

TEST(WorldApi, RunCollisionsWithNothingMovingReturnsZero) {
  World world(WorldDef{Boundary::box, {0.0, 0.0}, {10.0, 10.0}});
  EXPECT_EQ(world.run_collisions(5), 0u);
  BallDef resting = ball_at({5.0, 5.0});
  world.add_ball(resting);
  EXPECT_EQ(world.run_collisions(5), 0u);  // a ball at rest meets nothing
}

// ---- the stop condition ----------------------------------------------------------------------

TEST(WorldApi, StopConditionEndsTheStepRightAfterTheContact) {
  World world = box_of_balls(52, 5, 10.0);
  const BallId watched = world.balls()[7];
  constexpr WallId kTop = 2;
  world.set_stop_condition([watched](const ContactEvent& c) {
    return c.kind == ContactKind::ball_wall && c.a == watched && c.wall == kTop;
  });
  bool fired = false;
  for (int s = 0; s < 1000 && !fired; ++s) {
    const double before = world.time();
    const double advanced = world.step(kStep);
    if (!world.stopped_early()) {
      ASSERT_EQ(world.time(), before + kStep);
      continue;
    }
    fired = true;
    ASSERT_FALSE(world.contacts().empty());
    const ContactEvent& last = world.contacts().back();
    EXPECT_EQ(last.a, watched);
    EXPECT_EQ(last.wall, kTop);
    EXPECT_EQ(world.time(), last.time);
    EXPECT_LT(advanced, kStep);
    EXPECT_EQ(world.time(), before + advanced);
    // Every ball is brought to that time: the watched ball touches the top wall.
    EXPECT_NEAR(world.position(watched).y, 20.0 - world.radius(watched),
                kTouchTol * world.radius(watched));
    EXPECT_FALSE(world.audit().has_value());
  }
  ASSERT_TRUE(fired);
  // The next step runs normally again once the condition is removed.
  world.set_stop_condition({});
  const double before = world.time();
  world.step(kStep);
  EXPECT_FALSE(world.stopped_early());
  EXPECT_EQ(world.time(), before + kStep);
}

// ---- contact order ---------------------------------------------------------------------------

// Time, then kind (ball–ball first), then ids: the pair by index, or the ball then the wall.
bool in_documented_order(const ContactEvent& x, const ContactEvent& y) {
  if (x.time != y.time) return x.time < y.time;
  if (x.kind != y.kind) return x.kind == ContactKind::ball_ball;
  if (x.a.index != y.a.index) return x.a.index < y.a.index;
  return x.kind == ContactKind::ball_ball ? x.b.index < y.b.index : x.wall < y.wall;
}

TEST(WorldApi, ContactsAreInTimeKindIdOrder) {
  World world = box_of_balls(53, 8, 20.0);
  std::size_t checked = 0;
  for (int s = 0; s < 60; ++s) {
    world.step(kStep);
    const auto contacts = world.contacts();
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      if (contacts[k].kind == ContactKind::ball_ball) {
        ASSERT_LT(contacts[k].a.index, contacts[k].b.index);
      }
      if (k > 0) {
        ASSERT_TRUE(in_documented_order(contacts[k - 1], contacts[k])) << "step " << s;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 100u);
}

TEST(WorldApi, SimultaneousContactsFollowTheDocumentedOrder) {
  // Two separate pairs meeting at the same instant, and a ball meeting a wall then too: the
  // ball–ball contacts come first, the lower pair first, whatever order they were added in.
  World world;
  world.add_segment({{50.0, -5.0}, {50.0, 5.0}});
  const BallId p = world.add_ball(ball_at({20.0, 10.0}, {1.0, 0.0}));
  const BallId q = world.add_ball(ball_at({23.0, 10.0}, {-1.0, 0.0}));
  const BallId r = world.add_ball(ball_at({48.5, 0.0}, {1.0, 0.0}));  // meets the wall at t=1
  const BallId s = world.add_ball(ball_at({0.0, 0.0}, {1.0, 0.0}));
  const BallId t = world.add_ball(ball_at({3.0, 0.0}, {-1.0, 0.0}));
  world.run_until(1.5);
  const auto contacts = world.contacts();
  ASSERT_EQ(contacts.size(), 3u);
  for (const ContactEvent& c : contacts) EXPECT_EQ(c.time, 1.0);
  EXPECT_EQ(contacts[0].a, p);
  EXPECT_EQ(contacts[0].b, q);
  EXPECT_EQ(contacts[1].a, s);
  EXPECT_EQ(contacts[1].b, t);
  EXPECT_EQ(contacts[2].kind, ContactKind::ball_wall);
  EXPECT_EQ(contacts[2].a, r);
}

// ---- determinism -----------------------------------------------------------------------------

std::uint64_t mix(std::uint64_t hash, std::uint64_t word) {
  // FNV-1a over the word's bytes: any difference in any bit changes the hash.
  for (int byte = 0; byte < 8; ++byte) {
    hash ^= (word >> (8 * byte)) & 0xFFu;
    hash *= 0x100000001B3u;
  }
  return hash;
}

std::uint64_t mix(std::uint64_t hash, double value) {
  return mix(hash, std::bit_cast<std::uint64_t>(value));
}

std::uint64_t run_and_hash(std::uint64_t seed) {
  World world = box_of_balls(seed, 10, 30.0);
  std::uint64_t hash = 0xCBF29CE484222325u;
  for (int s = 0; s < 1000; ++s) {
    world.step(kStep);
    for (const ContactEvent& c : world.contacts()) {
      hash = mix(hash, c.time);
      hash = mix(hash, static_cast<std::uint64_t>(c.kind));
      hash = mix(hash, (std::uint64_t{c.a.index} << 32) | c.b.index);
      hash = mix(hash, std::uint64_t{c.wall});
      hash = mix(hash, c.impulse);
    }
  }
  for (BallId id : world.balls()) {
    hash = mix(hash, world.position(id).x);
    hash = mix(hash, world.position(id).y);
    hash = mix(hash, world.velocity(id).x);
    hash = mix(hash, world.velocity(id).y);
  }
  return mix(hash, world.collision_count());
}

TEST(WorldApi, SameSceneAndCallsGiveBitIdenticalRuns) {
  const std::uint64_t first = run_and_hash(54);
  EXPECT_EQ(run_and_hash(54), first);
  EXPECT_NE(run_and_hash(55), first);  // the hash does see the scene
}

// ---- many small steps or one big one ---------------------------------------------------------

// Splitting a run brings every ball to each step's end, which rounds positions differently
// (~1e-16 relative each time); the contacts' conditioning and a few dozen contacts in a row
// amplify that. A small, sparse scene keeps the amplified difference below 1e-12 in time, and
// 1e-9 of the box's side (1e-9 relative) in position and of the top speed in velocity.
constexpr double kSplitTimeTol = 1e-12;
constexpr double kSplitStateTol = 1e-9;

TEST(WorldApi, ThousandSmallStepsMatchOneBigStep) {
  constexpr double kDuration = 2.0;
  constexpr double kSpeed = 6.0;
  World split = box_of_balls(56, 4, kSpeed);
  World whole = box_of_balls(56, 4, kSpeed);
  std::vector<ContactEvent> split_contacts;
  for (int s = 0; s < 1000; ++s) {
    split.step(kDuration / 1000.0);
    split_contacts.insert(split_contacts.end(), split.contacts().begin(), split.contacts().end());
  }
  whole.step(kDuration);
  const auto whole_contacts = whole.contacts();
  ASSERT_GT(whole_contacts.size(), 10u);
  ASSERT_EQ(split_contacts.size(), whole_contacts.size());
  for (std::size_t k = 0; k < whole_contacts.size(); ++k) {
    ASSERT_EQ(split_contacts[k].kind, whole_contacts[k].kind) << "contact " << k;
    ASSERT_EQ(split_contacts[k].a, whole_contacts[k].a) << "contact " << k;
    ASSERT_EQ(split_contacts[k].b, whole_contacts[k].b) << "contact " << k;
    ASSERT_EQ(split_contacts[k].wall, whole_contacts[k].wall) << "contact " << k;
    ASSERT_NEAR(split_contacts[k].time, whole_contacts[k].time,
                kSplitTimeTol * std::max(1.0, whole_contacts[k].time))
        << "contact " << k;
  }
  EXPECT_NEAR(split.time(), whole.time(), kRoundingTol);
  const std::vector<BallId> ids = whole.balls();
  for (BallId id : ids) {
    EXPECT_NEAR(split.position(id).x, whole.position(id).x, kSplitStateTol * 20.0);
    EXPECT_NEAR(split.position(id).y, whole.position(id).y, kSplitStateTol * 20.0);
    EXPECT_NEAR(split.velocity(id).x, whole.velocity(id).x, kSplitStateTol * kSpeed);
    EXPECT_NEAR(split.velocity(id).y, whole.velocity(id).y, kSplitStateTol * kSpeed);
  }
}

// ---- contact recording -----------------------------------------------------------------------

TEST(WorldApi, ContactRecordingOffKeepsNoContactsAndChangesNothingElse) {
  World recorded = box_of_balls(53, 6, 10.0);
  World unrecorded = box_of_balls(53, 6, 10.0);
  EXPECT_TRUE(unrecorded.contact_recording());  // on by default
  unrecorded.set_contact_recording(false);
  EXPECT_FALSE(unrecorded.contact_recording());
  std::vector<ContactEvent> seen;
  unrecorded.set_stop_condition([&seen](const ContactEvent& contact) {
    seen.push_back(contact);  // a per-contact callback that never stops the run
    return false;
  });
  ASSERT_EQ(recorded.run_collisions(300), 300u);
  ASSERT_EQ(unrecorded.run_collisions(300), 300u);
  EXPECT_TRUE(unrecorded.contacts().empty());
  ASSERT_EQ(seen.size(), recorded.contacts().size());
  for (std::size_t k = 0; k < seen.size(); ++k) {
    EXPECT_EQ(seen[k].time, recorded.contacts()[k].time) << k;
    EXPECT_EQ(seen[k].a, recorded.contacts()[k].a) << k;
    EXPECT_EQ(seen[k].b, recorded.contacts()[k].b) << k;
  }
  EXPECT_EQ(unrecorded.time(), recorded.time());
  const std::vector<BallId> ids = recorded.balls();
  for (const BallId id : ids) EXPECT_EQ(unrecorded.position(id), recorded.position(id));
  unrecorded.set_contact_recording(true);
  unrecorded.step(kStep);
  recorded.step(kStep);
  EXPECT_EQ(unrecorded.contacts().size(), recorded.contacts().size());
}

}  // namespace
}  // namespace carom

namespace carom {
namespace {

// Balls of one kind share a species record (src/species.hpp), reused once its last ball is gone:
// each ball must keep its own radius, mass and restitution through removals and re-adds.
TEST(WorldApi, BallsKeepTheirKindAcrossRemovalsAndReuse) {
  WorldDef def;
  def.boundary = Boundary::box;
  def.lower = {0.0, 0.0};
  def.upper = {100.0, 100.0};
  World world(def);
  struct Kind {
    double radius;
    double mass;
    double restitution;
  };
  const Kind kinds[] = {{0.5, 1.0, 1.0}, {1.0, kImmovable, 1.0}, {0.75, 3.0, 0.5}};
  std::vector<std::pair<BallId, Kind>> placed;
  const auto add_kind = [&](int slot, const Kind& kind) {
    BallDef ball;
    ball.position = {5.0 + 4.0 * (slot % 20), 5.0 + 4.0 * (slot / 20)};
    ball.radius = kind.radius;
    ball.mass = kind.mass;
    ball.restitution = kind.restitution;
    placed.emplace_back(world.add_ball(ball), kind);
  };
  for (int i = 0; i < 30; ++i) add_kind(i, kinds[i % 3]);
  for (int i = 0; i < 30; i += 3) world.remove_ball(placed[static_cast<std::size_t>(i)].first);
  // Every ball of the first kind is gone; new kinds take the freed places.
  for (int i = 0; i < 30; i += 3) add_kind(i, {0.25 + 0.01 * i, 2.0 + i, 0.0});
  for (const auto& [id, kind] : placed) {
    if (!world.contains(id)) continue;
    EXPECT_EQ(world.radius(id), kind.radius);
    EXPECT_EQ(world.mass(id), kind.mass);
  }
  // Restitution is seen through a bounce: the kind {0.75, 3, 0.5} against the wall at speed 1.
  const BallId bouncer = placed[2].first;
  world.set_position(bouncer, {99.0 - 0.75, 5.0});
  world.set_velocity(bouncer, {1.0, 0.0});
  world.step(1.0);
  EXPECT_EQ(world.velocity(bouncer), (Vec2{-0.5, 0.0}));
}

}  // namespace
}  // namespace carom
