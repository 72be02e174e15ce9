#include "carom/science/hard_disk_gas.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

namespace carom::science {
namespace {

// The smallest distance between two sites of a triangular lattice of rows × columns sites that
// tiles a periodic square of side `side`, periodic images included.
double nearest_site_distance(double side, std::uint64_t columns, std::uint64_t rows) {
  const double across = side / static_cast<double>(columns);  // along a row
  const double up = side / static_cast<double>(rows);         // between rows
  // The lattice's vectors are i·(across, 0) + j·(across/2, up): the shortest are along a row,
  // to the rows above and below (half a spacing to either side), and two rows up.
  double nearest = std::min({across, std::hypot(across / 2.0, up), 2.0 * up});
  // With an odd number of rows the last row and the first (its image above) are both unshifted,
  // so a site has a neighbour straight above it.
  if (rows % 2 == 1) nearest = std::min(nearest, up);
  return nearest;
}

Vec2 site_position(const HardDiskLayout& layout, std::uint64_t site) {
  const std::uint64_t row = site / layout.columns;
  const std::uint64_t column = site % layout.columns;
  const double across = layout.side / static_cast<double>(layout.columns);
  const double up = layout.side / static_cast<double>(layout.rows);
  // A quarter spacing in from the left keeps shifted rows inside [0, side) as well.
  const double shift = row % 2 == 1 ? 0.75 : 0.25;
  return {(static_cast<double>(column) + shift) * across, (static_cast<double>(row) + 0.5) * up};
}

// The site of disk i when n disks share `sites` sites, the empty ones spread evenly.
std::uint64_t site_of(std::uint64_t i, std::uint64_t n, std::uint64_t sites) {
  // sites < 2n (a lattice has fewer than one row of empty sites), so i·sites < 2n² fits in 64
  // bits for every n below 2^31.
  return i * sites / n;
}

}  // namespace

HardDiskLayout hard_disk_layout(std::uint64_t n, double eta) {
  HardDiskLayout layout;
  layout.n = n;
  layout.eta = eta;
  const double count = static_cast<double>(n);
  layout.side = std::sqrt(count * std::numbers::pi * kDiskDiameter * kDiskDiameter / (4.0 * eta));
  layout.nearest = -std::numeric_limits<double>::infinity();
  // Every row count from 1 to n, each with the fewest columns that hold n sites: O(n), which is
  // a few milliseconds for the largest worlds the tool accepts.
  for (std::uint64_t rows = 1; rows <= n; ++rows) {
    const std::uint64_t columns = (n + rows - 1) / rows;
    const double nearest = nearest_site_distance(layout.side, columns, rows);
    if (nearest > layout.nearest) {
      layout.nearest = nearest;
      layout.columns = columns;
      layout.rows = rows;
    }
  }
  layout.densest_eta = eta * (layout.nearest / kDiskDiameter) * (layout.nearest / kDiskDiameter);
  return layout;
}

World make_hard_disk_world(const HardDiskLayout& layout, std::uint64_t seed) {
  const std::uint64_t sites = layout.columns * layout.rows;
  // First pass: the mean of the velocities the second pass will draw.
  Vec2 mean;
  {
    std::mt19937_64 random(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    for (std::uint64_t i = 0; i < layout.n; ++i) {
      const double vx = normal(random);
      const double vy = normal(random);
      mean += Vec2{vx, vy};
    }
    mean /= static_cast<double>(layout.n);
  }

  WorldDef def;
  def.boundary = Boundary::periodic;
  def.lower = {0.0, 0.0};
  def.upper = {layout.side, layout.side};
  World world(def);
  world.reserve(static_cast<std::size_t>(layout.n));
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (std::uint64_t i = 0; i < layout.n; ++i) {
    const double vx = normal(random);
    const double vy = normal(random);
    BallDef ball;
    ball.position = site_position(layout, site_of(i, layout.n, sites));
    ball.velocity = Vec2{vx, vy} - mean;
    ball.radius = kDiskRadius;
    ball.mass = kDiskMass;
    world.add_ball(ball);
  }
  return world;
}

World make_hard_disk_world(const HardDiskLayout& layout, std::uint64_t seed,
                           std::span<const double> diameters) {
  // The one-size world, then each disk resized in place: the sites and velocities are exactly
  // those of the one-size scene, so the two differ only in the sizes.
  World sized = make_hard_disk_world(layout, seed);
  WorldDef def;
  def.boundary = Boundary::periodic;
  def.lower = {0.0, 0.0};
  def.upper = {layout.side, layout.side};
  World world(def);
  const std::vector<BallId> ids = sized.balls();
  world.reserve(ids.size());
  // kT = K/N = 1 exactly (for mass 1): the drawn velocities' K/N is 1 only on average.
  const double scale = std::sqrt(static_cast<double>(ids.size()) / sized.kinetic_energy());
  for (std::size_t i = 0; i < ids.size(); ++i) {
    BallDef ball;
    ball.position = sized.position(ids[i]);
    ball.velocity = sized.velocity(ids[i]) * scale;
    ball.radius = diameters[i] / 2.0;
    ball.mass = kDiskMass;
    world.add_ball(ball);
  }
  return world;
}

}  // namespace carom::science
