#include "world/random_scene.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "carom/bounce.hpp"

namespace carom::testing {
namespace {

// Each ball keeps this share of its grid cell's side clear of the cell's border, so neighbours
// (and the box walls) start strictly apart, by far more than rounding, and never touch at t = 0.
constexpr double kCellMargin = 0.01;

}  // namespace

ReferenceScene random_gas(const GasOptions& options, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  auto uniform = [&engine](double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(engine);
  };

  const auto per_row =
      static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(options.ball_count))));
  const double spacing = options.side / static_cast<double>(per_row);
  const double clearance = kCellMargin * spacing;
  if (!(2.0 * (options.max_radius + clearance) < spacing)) {
    throw std::invalid_argument("random_gas: the balls do not fit on the grid");
  }

  ReferenceScene scene;
  scene.periodic = options.periodic;
  scene.lower = {0.0, 0.0};
  scene.upper = {options.side, options.side};
  if (!options.periodic) {
    for (const ReferenceWall& wall : box_walls(scene.lower, scene.upper)) {
      scene.walls.push_back(wall);
    }
  }
  std::uniform_int_distribution<std::size_t> pick_restitution(0, options.restitutions.size() - 1);
  for (std::size_t k = 0; k < options.ball_count; ++k) {
    ReferenceBall ball;
    ball.radius = uniform(options.min_radius, options.max_radius);
    const double jitter = 0.5 * spacing - ball.radius - clearance;
    const Vec2 site{(static_cast<double>(k % per_row) + 0.5) * spacing,
                    (static_cast<double>(k / per_row) + 0.5) * spacing};
    ball.position = site + Vec2{uniform(-jitter, jitter), uniform(-jitter, jitter)};
    ball.restitution = options.restitutions[pick_restitution(engine)];
    if (uniform(0.0, 1.0) < options.immovable_fraction) {
      ball.mass = kImmovable;
    } else {
      ball.mass = uniform(options.min_mass, options.max_mass);
      const double angle = uniform(0.0, 2.0 * std::numbers::pi);
      const double speed = uniform(0.0, options.max_speed);
      ball.velocity = Vec2{std::cos(angle), std::sin(angle)} * speed;
    }
    scene.balls.push_back(ball);
  }
  return scene;
}

}  // namespace carom::testing
