#include "generators.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "ball_grid.hpp"
#include "carom/lattice.hpp"
#include "scene_check.hpp"
#include "scene_geometry.hpp"

namespace carom::scene_detail {
namespace {

// Where the balls go: a rectangle they lie wholly inside, or the periodic cell.
struct Region {
  Vec2 lower;
  Vec2 upper;
  bool periodic = false;
};

[[noreturn]] void refuse(std::size_t index, const std::string& problem) {
  throw PathedSceneError({std::string("generators"), index}, "", problem);
}

Region region_of(const Scene& scene, std::size_t index) {
  const SceneGenerator& g = scene.generators[index];
  if (g.region_lower && g.region_upper) return {*g.region_lower, *g.region_upper, false};
  if (scene.world.boundary == Boundary::open) {
    refuse(index, "needs a region: the world is open, so it has no box to fill");
  }
  return {scene.world.lower, scene.world.upper, scene.world.boundary == Boundary::periodic};
}

// A uniform double in [0, 1) from the generator's top 53 bits: the same on every standard
// library (std::uniform_real_distribution's algorithm is not specified).
double uniform(std::mt19937_64& random) {
  constexpr double kTwoToMinus53 = 1.0 / 9007199254740992.0;
  return static_cast<double>(random() >> 11U) * kTwoToMinus53;
}

// A standard normal deviate (Box–Muller; one of the pair is used, for simplicity).
double normal(std::mt19937_64& random) {
  const double u = 1.0 - uniform(random);  // in (0, 1]: the logarithm stays finite
  const double v = uniform(random);
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}

double generator_radius(const SceneGenerator& g, const Region& region) {
  if (g.radius) return *g.radius;
  const Vec2 size = region.upper - region.lower;
  return std::sqrt(*g.packing_fraction * size.x * size.y /
                   (static_cast<double>(g.count) * std::numbers::pi));
}

std::vector<Vec2> lattice_positions(const SceneGenerator& g, std::size_t index,
                                    const Region& region, double radius) {
  const Vec2 size = region.upper - region.lower;
  // Centres of whole balls inside a rectangle lie at least a radius from its edges.
  const Vec2 span = region.periodic ? size : size - Vec2{2.0 * radius, 2.0 * radius};
  const double fraction =
      static_cast<double>(g.count) * std::numbers::pi * radius * radius / (size.x * size.y);
  if (!(span.x > 0.0 && span.y > 0.0)) {
    refuse(index, "a ball of radius " + number_text(radius) + " does not fit in the region");
  }
  const Vec2 origin = region.periodic ? region.lower : region.lower + Vec2{radius, radius};
  const TriangularLattice lattice =
      best_triangular_lattice(g.count, origin, span, region.periodic, LatticeSearch::by_columns);
  const double nearest = lattice.nearest();
  const double needed = 2.0 * radius * (1.0 + kLatticeSlack);
  if (g.count > 1 && nearest < needed) {
    // The lattice scales with the balls' size: fraction·(nearest/diameter)² is the most it holds.
    const double most = fraction * (nearest / (2.0 * radius)) * (nearest / (2.0 * radius));
    refuse(index, std::to_string(g.count) + " balls of radius " + number_text(radius) +
                      " (packing fraction " + number_text(fraction) +
                      ") do not fit on a triangular lattice in this region: its sites would be " +
                      number_text(nearest) + " apart, less than a diameter; at most " +
                      "packing fraction " + number_text(most) + " can be placed");
  }
  std::vector<Vec2> positions;
  positions.reserve(static_cast<std::size_t>(g.count));
  for (std::uint64_t i = 0; i < g.count; ++i) {
    positions.push_back(lattice.site(lattice.spread(i, g.count)));
  }
  return positions;
}

std::vector<Vec2> random_positions(const Scene& scene, const SceneGenerator& g, std::size_t index,
                                   const Region& region, double radius,
                                   const std::vector<SceneBall>& existing) {
  const Vec2 size = region.upper - region.lower;
  const double fraction =
      static_cast<double>(g.count) * std::numbers::pi * radius * radius / (size.x * size.y);
  if (fraction > kRandomPlacementLimit) {
    refuse(index, "random placement cannot reach packing fraction " + number_text(fraction) +
                      " (it jams near 0.547, and is refused above " +
                      number_text(kRandomPlacementLimit) + "): use \"placement\": \"lattice\"");
  }
  const Vec2 span = region.periodic ? size : size - Vec2{2.0 * radius, 2.0 * radius};
  if (!(span.x > 0.0 && span.y > 0.0)) {
    refuse(index, "a ball of radius " + number_text(radius) + " does not fit in the region");
  }
  const Vec2 origin = region.periodic ? region.lower : region.lower + Vec2{radius, radius};

  // Obstacles: balls placed before, pockets, and this generator's balls as they are placed.
  std::vector<Vec2> centres;
  std::vector<double> radii;
  double largest = radius;
  for (const SceneBall& ball : existing) {
    centres.push_back(ball.position);
    radii.push_back(ball.radius);
    largest = std::max(largest, ball.radius);
  }
  for (const ScenePocket& pocket : scene.pockets) {
    centres.push_back(pocket.position);
    radii.push_back(pocket.radius);
    largest = std::max(largest, pocket.radius);
  }
  std::optional<PeriodicCell> cell;
  if (scene.world.boundary == Boundary::periodic) {
    cell = PeriodicCell(scene.world.lower, scene.world.upper);
  }
  BallGrid grid(2.0 * largest, cell);
  for (std::size_t i = 0; i < centres.size(); ++i) grid.insert(i, centres[i]);

  std::mt19937_64 random(g.seed);
  std::vector<Vec2> positions;
  positions.reserve(static_cast<std::size_t>(g.count));
  for (std::uint64_t placed = 0; placed < g.count; ++placed) {
    bool done = false;
    for (int attempt = 0; attempt < kRandomPlacementTries && !done; ++attempt) {
      const double x = uniform(random);
      const double y = uniform(random);
      const Vec2 p = origin + Vec2{x * span.x, y * span.y};
      bool free = true;
      grid.for_each_near(p, [&](std::size_t other) {
        if (!free) return;
        const double reach = radius + radii[other];
        if (length_squared(grid.offset(p, centres[other])) < reach * reach) free = false;
      });
      if (free) {
        grid.insert(centres.size(), p);
        centres.push_back(p);
        radii.push_back(radius);
        positions.push_back(p);
        done = true;
      }
    }
    if (!done) {
      refuse(index, "random placement found no room for ball " + std::to_string(placed) + " of " +
                        std::to_string(g.count) + " after " +
                        std::to_string(kRandomPlacementTries) +
                        " tries: the region is too full; lower the count or the radius, or use "
                        "\"placement\": \"lattice\"");
    }
  }
  return positions;
}

std::vector<Vec2> velocities(const SceneGenerator& g) {
  const SceneVelocities& spec = g.velocities;
  // A stream of its own, so changing the placement does not change the velocities.
  constexpr std::uint64_t kVelocityStream = 0x9E3779B97F4A7C15ULL;
  std::mt19937_64 random(g.seed ^ kVelocityStream);
  std::vector<Vec2> v(static_cast<std::size_t>(g.count), spec.value);
  if (spec.distribution == VelocityDistribution::uniform_direction) {
    for (Vec2& velocity : v) {
      const double angle = 2.0 * std::numbers::pi * uniform(random);
      velocity = Vec2{std::cos(angle), std::sin(angle)} * spec.speed;
    }
  } else if (spec.distribution == VelocityDistribution::maxwell_boltzmann) {
    const double deviation = std::sqrt(spec.temperature / g.mass);
    for (Vec2& velocity : v) {
      const double vx = normal(random);
      const double vy = normal(random);
      velocity = Vec2{vx, vy} * deviation;
    }
  }
  if (spec.zero_momentum && !v.empty()) {
    Vec2 mean;
    for (const Vec2 velocity : v) mean += velocity;
    mean /= static_cast<double>(v.size());
    for (Vec2& velocity : v) velocity -= mean;
  }
  return v;
}

}  // namespace

std::vector<SceneBall> generate_balls(const Scene& scene, std::size_t index,
                                      const std::vector<SceneBall>& existing) {
  const SceneGenerator& g = scene.generators[index];
  const Region region = region_of(scene, index);
  const double radius = generator_radius(g, region);
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    refuse(index, "the balls' radius works out as " + number_text(radius));
  }
  const std::vector<Vec2> positions =
      g.placement == GeneratorPlacement::lattice
          ? lattice_positions(g, index, region, radius)
          : random_positions(scene, g, index, region, radius, existing);
  const std::vector<Vec2> v = velocities(g);
  std::vector<SceneBall> balls(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    SceneBall& ball = balls[i];
    if (g.name) ball.name = *g.name + "#" + std::to_string(i);
    ball.position = positions[i];
    ball.velocity = v[i];
    ball.radius = radius;
    ball.mass = g.mass;
    ball.restitution = g.restitution;
    ball.color = g.color;
  }
  return balls;
}

}  // namespace carom::scene_detail
