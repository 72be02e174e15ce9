// The world's broad phase seen from outside: the grid is re-planned while balls are added, it
// never lets add_ball or set_position miss an overlap, and the grid audit finds what the
// all-pairs audit finds.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "carom/error.hpp"
#include "carom/world.hpp"

namespace carom {
namespace {

constexpr double kGridBallRadius = 0.5;

// side × side disks of radius 0.5 on a square lattice of the given pitch, with random
// velocities, in a periodic cell or a box that fits them.
World lattice(int side, double pitch, Boundary boundary, std::uint64_t seed) {
  const double extent = side * pitch;
  World world(WorldDef{boundary, {0.0, 0.0}, {extent, extent}});
  std::mt19937_64 engine(seed);
  std::normal_distribution<double> speed(0.0, 1.0);
  for (int row = 0; row < side; ++row) {
    for (int column = 0; column < side; ++column) {
      BallDef def;
      def.position = {(column + 0.5) * pitch, (row + 0.5) * pitch};
      const double vx = speed(engine);
      const double vy = speed(engine);
      def.velocity = {vx, vy};
      def.radius = kGridBallRadius;
      world.add_ball(def);
    }
  }
  return world;
}

TEST(WorldGrid, AddBallStillRefusesEveryOverlapAfterManyReplans) {
  // 4900 balls: the grid is re-planned several times while they are added. Every place that
  // overlaps a ball must still be refused, and every free one accepted.
  World world = lattice(70, 1.5, Boundary::periodic, 1);
  ASSERT_EQ(world.ball_count(), 4900u);
  const std::vector<BallId> ids = world.balls();
  for (std::size_t k = 0; k < ids.size(); k += 97) {
    const Vec2 p = world.position(ids[k]);
    BallDef def;
    def.radius = 0.2;
    def.position = p + Vec2{0.55, 0.0};  // overlaps ball k (reach 0.7)
    EXPECT_THROW(world.add_ball(def), InvalidArgument) << "next to ball " << k;
    def.position = p + Vec2{0.75, 0.75};  // the middle of a lattice square: 1.06 from 4 balls
    const BallId added = world.add_ball(def);
    world.remove_ball(added);
  }
  EXPECT_FALSE(world.audit_all_pairs().has_value());
}

TEST(WorldGrid, AddBallRefusesAWallOverlapFoundThroughTheGrid) {
  World world;
  for (int i = 0; i < 40; ++i) world.add_segment({{i * 10.0, 0.0}, {i * 10.0 + 5.0, 0.0}});
  for (int i = 0; i < 600; ++i) {
    BallDef def;
    def.position = {i * 0.7, 3.0};
    def.radius = 0.3;
    world.add_ball(def);
  }
  for (int i = 0; i < 40; ++i) {
    BallDef def;
    def.position = {i * 10.0 + 2.5, 0.25};
    def.radius = 0.3;
    try {
      world.add_ball(def);
      ADD_FAILURE() << "a ball across segment " << i << " was accepted";
    } catch (const InvalidArgument& error) {
      EXPECT_NE(std::string(error.what()).find("wall " + std::to_string(i)), std::string::npos)
          << error.what();
    }
  }
}

TEST(WorldGrid, GridAuditAgreesWithAllPairsAudit) {
  for (const Boundary boundary : {Boundary::periodic, Boundary::box}) {
    World world = lattice(40, 1.3, boundary, 7);  // 1600 balls: audit() uses the grid
    for (int chunk = 0; chunk < 20; ++chunk) {
      world.run_collisions(200);
      EXPECT_FALSE(world.audit().has_value()) << *world.audit();
      EXPECT_FALSE(world.audit_all_pairs().has_value()) << *world.audit_all_pairs();
      // Right after a contact its pair touches: a tolerance that counts touching as overlap
      // must find a pair both ways.
      EXPECT_TRUE(world.audit(-1e-6).has_value());
      EXPECT_TRUE(world.audit_all_pairs(-1e-6).has_value());
    }
  }
}

// A dilute gas gets cells with hysteresis (a ball leaves its cell some way past the side): the
// balls must still stay inside the periodic cell (the cell's own sides have none, so that the
// re-wrap happens there), inside the box, in their grid cells as the audit checks them, and
// apart.
TEST(WorldGrid, DiluteGasesStayInTheirCellsWithHysteresis) {
  for (const Boundary boundary : {Boundary::periodic, Boundary::box}) {
    World world = lattice(30, 2.5, boundary, 11);  // 900 balls at η = 0.13
    const double extent = 30 * 2.5;
    // Inside [0, extent), to the rounding of a re-wrap (the box: the radius inside the walls).
    const double slack = 1e-9 * extent;
    const double inset = boundary == Boundary::box ? kGridBallRadius : 0.0;
    for (int chunk = 0; chunk < 40; ++chunk) {
      world.run_until(world.time() + 0.5);
      for (const BallId id : world.balls()) {
        const Vec2 p = world.position(id);
        ASSERT_TRUE(p.x >= inset - slack && p.x < extent - inset + slack && p.y >= inset - slack &&
                    p.y < extent - inset + slack)
            << "ball " << id.index << " at (" << p.x << ", " << p.y << "), chunk " << chunk;
      }
      ASSERT_FALSE(world.audit().has_value()) << *world.audit();
    }
    EXPECT_GT(world.collision_count(), 2000u);  // the gas did move and collide
  }
}

}  // namespace
}  // namespace carom
