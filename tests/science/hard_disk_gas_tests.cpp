// The hard-disk gas of carom::science (carom bench, carom gas, the benchmarks): the box gives the
// packing fraction, the lattice holds every disk without overlap (up to the densest it claims), and
// the velocities are seeded and carry no total momentum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "carom/error.hpp"
#include "carom/science/hard_disk_gas.hpp"

namespace carom::science {
namespace {

TEST(HardDiskLayout, BoxGivesThePackingFraction) {
  for (const double eta : {0.05, 0.3, 0.6, 0.8}) {
    const HardDiskLayout layout = hard_disk_layout(10'000, eta);
    EXPECT_NEAR(10'000 * std::numbers::pi / (4.0 * layout.side * layout.side), eta, 1e-12);
    EXPECT_GE(layout.columns * layout.rows, 10'000u);
    EXPECT_TRUE(layout.box_wide_enough());
    EXPECT_TRUE(layout.disks_fit()) << eta;
  }
}

// Between rows and columns that tile the square nearly evenly, a dense gas still fits.
TEST(HardDiskLayout, LargeGasFitsUpToNearTheDensestPacking) {
  const HardDiskLayout layout = hard_disk_layout(1'000'000, 0.85);
  EXPECT_TRUE(layout.disks_fit());
  EXPECT_GT(layout.densest_eta, 0.85);
  EXPECT_LT(layout.densest_eta, kTriangularPackingLimit + 1e-12);
}

TEST(HardDiskLayout, TooDenseForTheLatticeIsSaid) {
  const HardDiskLayout layout = hard_disk_layout(100, 0.9);
  EXPECT_FALSE(layout.disks_fit());
  EXPECT_LT(layout.densest_eta, 0.9);
}

// Nine disks: three rows of three beat every even row count (the last row and the first's image
// lie one row spacing apart, as far as the sites of a row).
TEST(HardDiskLayout, OddRowCountsAreTried) {
  const HardDiskLayout layout = hard_disk_layout(9, 0.3);
  EXPECT_EQ(layout.columns, 3u);
  EXPECT_EQ(layout.rows, 3u);
  EXPECT_EQ(layout.nearest, layout.side / 3.0);
  EXPECT_EQ(layout.nearest, layout.lattice().nearest());
}

TEST(HardDiskLayout, RejectsCountsAndPackingFractionsOutOfRange) {
  EXPECT_THROW((void)hard_disk_layout(0, 0.3), InvalidArgument);
  EXPECT_THROW((void)hard_disk_layout(kMaxHardDisks, 0.3), InvalidArgument);
  for (const double eta : {0.0, -0.3, std::nan(""), std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW((void)hard_disk_layout(100, eta), InvalidArgument) << eta;
  }
}

TEST(HardDiskLayout, TinyBoxIsSaid) {
  EXPECT_FALSE(hard_disk_layout(3, 0.5).box_wide_enough());
  EXPECT_TRUE(hard_disk_layout(30, 0.5).box_wide_enough());
}

World world_at(std::uint64_t n, double eta, std::uint64_t seed) {
  const HardDiskLayout layout = hard_disk_layout(n, eta);
  EXPECT_TRUE(layout.box_wide_enough() && layout.disks_fit());
  return make_hard_disk_world(layout, seed);
}

TEST(HardDiskWorld, HoldsEveryDiskWithoutOverlapAndNoMomentum) {
  const World world = world_at(500, 0.5, 7);
  EXPECT_EQ(world.ball_count(), 500u);
  EXPECT_EQ(world.audit(), std::nullopt);
  const Vec2 momentum = world.momentum();
  EXPECT_LT(length(momentum), 1e-12 * std::sqrt(2.0 * 500.0 * world.kinetic_energy()));
  for (const BallId id : world.balls()) {
    EXPECT_EQ(world.radius(id), kDiskRadius);
    EXPECT_EQ(world.mass(id), kDiskMass);
  }
}

// Velocity components have standard deviation 1, so the kinetic energy is about one per disk.
// Disk i sits on site spread(i, n) of the layout's lattice: with more sites than disks, the
// empty ones are spread through the box.
TEST(HardDiskWorld, DisksSitOnTheLayoutsLattice) {
  const HardDiskLayout layout = hard_disk_layout(491, 0.4);  // a prime: some sites stay empty
  const TriangularLattice lattice = layout.lattice();
  ASSERT_GT(lattice.sites(), 491u);
  const World world = make_hard_disk_world(layout, 5);
  const std::vector<BallId> ids = world.balls();
  ASSERT_EQ(ids.size(), 491u);
  for (std::uint64_t i = 0; i < ids.size(); ++i) {
    EXPECT_EQ(world.position(ids[i]), lattice.site(lattice.spread(i, 491)));
  }
}

TEST(HardDiskWorld, VelocitiesAreMaxwellBoltzmannWithUnitVariance) {
  const World world = world_at(20'000, 0.3, 1);
  EXPECT_NEAR(world.kinetic_energy() / 20'000.0, 1.0, 0.03);
}

TEST(HardDiskWorld, AtTheDensestTheLatticeClaimsTheDisksStillFit) {
  const HardDiskLayout loose = hard_disk_layout(400, 0.5);
  const HardDiskLayout dense = hard_disk_layout(400, loose.densest_eta * (1.0 - 1e-6));
  ASSERT_TRUE(dense.disks_fit());
  const World world = make_hard_disk_world(dense, 3);
  EXPECT_EQ(world.ball_count(), 400u);
  EXPECT_EQ(world.audit(), std::nullopt);
}

std::vector<Vec2> velocities(const World& world) {
  std::vector<Vec2> out;
  for (const BallId id : world.balls()) out.push_back(world.velocity(id));
  return out;
}

TEST(HardDiskWorld, SameSeedSameGasOtherSeedOtherGas) {
  const std::vector<Vec2> first = velocities(world_at(200, 0.3, 11));
  EXPECT_EQ(first, velocities(world_at(200, 0.3, 11)));
  EXPECT_NE(first, velocities(world_at(200, 0.3, 12)));
}

}  // namespace
}  // namespace carom::science
