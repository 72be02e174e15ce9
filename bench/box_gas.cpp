#include "box_gas.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

namespace carom::bench {

std::unique_ptr<World> make_box_gas(std::uint64_t n, double eta, bool gravity) {
  const double side = std::sqrt(static_cast<double>(n) * std::numbers::pi / 4.0 / eta);
  const auto per_row = static_cast<std::uint64_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  const double spacing = side / static_cast<double>(per_row);
  if (spacing <= 1.0) return nullptr;
  WorldDef def{Boundary::box, {0.0, 0.0}, {side, side}, 1.0};
  if (gravity) def.gravity = {0.0, -2.0 / side};
  auto world = std::make_unique<World>(def);
  std::mt19937_64 random(kBoxGasSeed);
  std::normal_distribution<double> speed(0.0, 1.0);
  for (std::uint64_t i = 0; i < n; ++i) {
    BallDef ball;
    ball.position = {(static_cast<double>(i % per_row) + 0.5) * spacing,
                     (static_cast<double>(i / per_row) + 0.5) * spacing};
    ball.radius = 0.5;
    const double vx = speed(random);
    const double vy = speed(random);
    ball.velocity = {vx, vy};
    world->add_ball(ball);
  }
  world->set_contact_recording(false);
  return world;
}

std::unique_ptr<World> equilibrated_gas_copy() {
  static const std::unique_ptr<World> base = [] {
    std::unique_ptr<World> gas = make_box_gas(kEquilibratedGasBalls, 0.3, false);
    gas->run_collisions(2 * kEquilibratedGasBalls);
    return gas;
  }();
  std::stringstream bytes;
  base->save(bytes);
  return std::make_unique<World>(World::load(bytes));
}

}  // namespace carom::bench
