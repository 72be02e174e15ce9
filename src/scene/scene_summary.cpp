// What `carom info` shows: counts, energies, momentum, packing fraction and the smallest gap.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ball_grid.hpp"
#include "carom/scene.hpp"
#include "scene_geometry.hpp"

namespace carom {
namespace {

// Up to this many balls the smallest gap is found by comparing every pair, so that sparse scenes
// (balls farther apart than the grid's reach) get an answer too; beyond it, only pairs within two
// of the largest diameters are compared.
constexpr std::size_t kAllPairsLimit = 2000;

}  // namespace

SceneSummary summarize(const Scene& scene, std::span<const SceneBall> balls) {
  SceneSummary s;
  s.balls = balls.size();
  s.pockets = scene.pockets.size();
  s.sensors = scene.sensors.size();
  for (const auto* motions : {&scene.segment_motions, &scene.arc_motions}) {
    s.moving_walls += static_cast<std::size_t>(
        std::count_if(motions->begin(), motions->end(),
                      [](const std::optional<WallMotion>& m) { return m.has_value(); }));
  }
  s.walls = scene_detail::scene_walls(scene).size();
  double largest = 0.0;
  for (const SceneBall& b : balls) {
    s.ball_area += std::numbers::pi * b.radius * b.radius;
    largest = std::max(largest, b.radius);
    if (b.mass == kImmovable) {
      ++s.immovable;
      continue;
    }
    s.kinetic_energy += 0.5 * b.mass * length_squared(b.velocity);
    s.potential_energy -= b.mass * dot(scene.world.gravity, b.position);
    s.momentum += b.velocity * b.mass;
  }
  if (scene.world.boundary != Boundary::open) {
    const Vec2 size = scene.world.upper - scene.world.lower;
    s.packing_fraction = s.ball_area / (size.x * size.y);
  }
  std::optional<PeriodicCell> cell;
  if (scene.world.boundary == Boundary::periodic) {
    cell = PeriodicCell(scene.world.lower, scene.world.upper);
  }
  scene_detail::BallGrid grid(4.0 * largest, cell);
  const auto consider = [&](std::size_t i, std::size_t j) {
    const double gap = length(grid.offset(balls[i].position, balls[j].position)) - balls[i].radius -
                       balls[j].radius;
    if (!s.smallest_gap || gap < *s.smallest_gap) {
      s.smallest_gap = gap;
      s.smallest_gap_a = std::min(i, j);
      s.smallest_gap_b = std::max(i, j);
    }
  };
  if (balls.size() <= kAllPairsLimit) {
    for (std::size_t i = 0; i < balls.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) consider(j, i);
    }
    return s;
  }
  for (std::size_t i = 0; i < balls.size(); ++i) {
    grid.for_each_near(balls[i].position, [&](std::size_t j) { consider(j, i); });
    grid.insert(i, balls[i].position);
  }
  return s;
}

}  // namespace carom
