// Periodic cells only a few grid cells wide: a pair can meet through another image than the one
// nearest when it was predicted, before either ball leaves its cell (docs/world.md,
// "Boundaries"). Found by the world fuzzer (tests/fuzz/world_fuzz.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "carom/error.hpp"
#include "carom/world.hpp"

namespace carom {
namespace {

BallDef periodic_disk(Vec2 position, Vec2 velocity, double radius) {
  BallDef def;
  def.position = position;
  def.velocity = velocity;
  def.radius = radius;
  return def;
}

// A cell 20 wide and disks of radius 2.5 make a grid of 3 × 3 cells 6.67 wide. B, at x = 12.5
// in the middle column, moves left towards A at x = 2: 10.5 apart directly, so the nearest image
// of A is the one at x = 22 (9.5 away, behind B). They touch at t = 5.5 (B at x = 7), before B
// leaves its column (x = 6.67, t = 5.83): with the nearest image alone no event comes before the
// overlap.
TEST(WorldPeriodicImages, APairMeetsThroughAnImageThatWasNotTheNearest) {
  WorldDef def;
  def.boundary = Boundary::periodic;
  def.lower = {0.0, 0.0};
  def.upper = {20.0, 20.0};
  World world(def);
  const BallId a = world.add_ball(periodic_disk({2.0, 10.0}, {0.0, 0.0}, 2.5));
  const BallId b = world.add_ball(periodic_disk({12.5, 10.0}, {-1.0, 0.0}, 2.5));
  world.run_until(6.5);
  ASSERT_EQ(world.contacts().size(), 1U);
  // t = 5.5 in exact arithmetic; the computed time is a few roundings of the times involved.
  EXPECT_NEAR(world.contacts()[0].time, 5.5, 1e-12);
  EXPECT_FALSE(world.audit().has_value()) << *world.audit();
  // Equal masses, head on: the velocities are exchanged.
  EXPECT_NEAR(world.velocity(a).x, -1.0, 1e-12);
  EXPECT_NEAR(world.velocity(b).x, 0.0, 1e-12);
}

// A call as the fuzzer makes it: a documented refusal (carom::InvalidArgument: a ball placed on
// another, a time limit already past) is an answer, not a failure.
template <typename Call>
void periodic_refusal_allowed(Call call) {
  try {
    call();
  } catch (const InvalidArgument&) {
  }
}

// The fuzzer's own sequence of calls (tests/fuzz/crashes/world-periodic-missed-contact-radius-2.5
// in its branch), audited after each: the engine once let balls 1 and 3 overlap by 2.15.
TEST(WorldPeriodicImages, TheFuzzersSequenceStaysApart) {
  WorldDef def;
  def.boundary = Boundary::periodic;
  def.lower = {0.0, 0.0};
  def.upper = {20.0, 20.0};
  def.restitution = 0.5;
  def.collapse_time = 1e-3;
  World world(def);
  BallDef post = periodic_disk({20.0, 20.0}, {7.0, -1.7145055188062944e-15}, 2.0);
  post.mass = kImmovable;
  world.add_ball(post);
  BallDef big = periodic_disk({12.866102082856489, 8.8926527809567411}, {-0.0, -0.0}, 2.5);
  big.mass = 3.0;
  world.add_ball(big);
  BallDef third = periodic_disk({4.6088349736781868, 12.872816052491036},
                                {9.9994131382928977, 0.10833692692419786}, 2.0);
  third.mass = 3.0;
  world.add_ball(third);
  for (const double limit :
       {20.0, 20.629270080143208, 22.154630904863119, 23.624273508865151, 28.478526061531795,
        33.392672641325895, 35.080140636847609, 40.708097579574748}) {
    periodic_refusal_allowed([&] { world.run_collisions(1, limit); });
    ASSERT_FALSE(world.audit().has_value()) << *world.audit();
  }
  BallDef small =
      periodic_disk({-20.0, -19.062485694666972}, {-6.9994687708038139, 0.086237616746669701}, 0.1);
  small.mass = 3.0;
  periodic_refusal_allowed([&] { world.add_ball(small); });
  periodic_refusal_allowed([&] { world.run_collisions(6, 41.816219257355044); });
  ASSERT_FALSE(world.audit().has_value()) << *world.audit();
  BallDef last = periodic_disk({6.8357366292820636, 9.9607843137254903},
                               {-6.9994687708038139, 0.086237616746669701}, 0.1);
  last.mass = 3.0;
  periodic_refusal_allowed([&] { world.add_ball(last); });
  periodic_refusal_allowed([&] { world.run_collisions(1, 61.816219257355044); });
  EXPECT_FALSE(world.audit().has_value()) << *world.audit();
}

}  // namespace
}  // namespace carom
