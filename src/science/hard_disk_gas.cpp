#include "carom/science/hard_disk_gas.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "carom/error.hpp"
#include "carom/number_text.hpp"

namespace carom::science {

HardDiskLayout hard_disk_layout(std::uint64_t n, double eta) {
  if (n < 1 || n >= kMaxHardDisks) {
    throw InvalidArgument("science::hard_disk_layout", "n", std::to_string(n),
                          "must lie in [1, 2^31)");
  }
  if (!(eta > 0.0 && std::isfinite(eta))) {
    throw InvalidArgument("science::hard_disk_layout", "eta", number_text(eta),
                          "must be a finite number > 0");
  }
  HardDiskLayout layout;
  layout.n = n;
  layout.eta = eta;
  const double count = static_cast<double>(n);
  layout.side = std::sqrt(count * std::numbers::pi * kDiskDiameter * kDiskDiameter / (4.0 * eta));
  // Every row count from 1 to n + 1, each with the fewest columns that hold n sites, odd counts
  // included: O(n), which is a few milliseconds for the largest worlds the tool accepts.
  const TriangularLattice lattice = best_triangular_lattice(
      n, {0.0, 0.0}, {layout.side, layout.side}, true, LatticeSearch::by_rows);
  layout.columns = lattice.columns;
  layout.rows = lattice.rows;
  layout.nearest = lattice.nearest();
  layout.densest_eta = eta * (layout.nearest / kDiskDiameter) * (layout.nearest / kDiskDiameter);
  return layout;
}

TriangularLattice HardDiskLayout::lattice() const noexcept {
  return {{0.0, 0.0}, {side, side}, columns, rows, true};
}

World make_hard_disk_world(const HardDiskLayout& layout, std::uint64_t seed) {
  const TriangularLattice lattice = layout.lattice();
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
    ball.position = lattice.site(lattice.spread(i, layout.n));
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
