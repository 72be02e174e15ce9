#include "scene.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace carom::peers {
namespace {

// The jitter stops this fraction short of touching, so that rounding never puts two disks (or a
// disk and a wall) in contact at the start: engines would refuse or push them apart.
constexpr double kJitterShortfall = 1e-6;

struct Grid {
  std::uint32_t per_side = 0;  // sites per row and per column
  double spacing = 0.0;
};

double box_side(std::uint32_t n, double radius, double packing) {
  return std::sqrt(static_cast<double>(n) * std::numbers::pi * radius * radius / packing);
}

// n disks on a jittered square grid of sites filling [lower, lower + side]²; the empty sites (the
// grid has ⌈√n⌉² ≥ n) are spread evenly. Appends to `balls`, velocities zero.
void place_on_jittered_grid(std::uint32_t n, double radius, double mass, Vec2 lower, Vec2 size,
                            std::mt19937_64& random, std::vector<SceneBall>& balls) {
  Grid grid;
  grid.per_side = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  const double across = size.x / grid.per_side;
  const double up = size.y / grid.per_side;
  const double room_x = (across - 2.0 * radius) / 2.0 * (1.0 - kJitterShortfall);
  const double room_y = (up - 2.0 * radius) / 2.0 * (1.0 - kJitterShortfall);
  if (!(room_x > 0.0) || !(room_y > 0.0)) {
    throw std::invalid_argument("scene: " + std::to_string(n) +
                                " disks do not fit on a square grid in this box");
  }
  std::uniform_real_distribution<double> jitter_x(-room_x, room_x);
  std::uniform_real_distribution<double> jitter_y(-room_y, room_y);
  const std::uint64_t sites = std::uint64_t{grid.per_side} * grid.per_side;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint64_t site = std::uint64_t{i} * sites / n;
    const std::uint64_t column_index = site % grid.per_side;
    const std::uint64_t row_index = site / grid.per_side;  // whole rows: integer division
    const auto column = static_cast<double>(column_index);
    const auto row = static_cast<double>(row_index);
    SceneBall ball;
    ball.radius = radius;
    ball.mass = mass;
    const double jx = jitter_x(random);
    const double jy = jitter_y(random);
    ball.position = {lower.x + (column + 0.5) * across + jx, lower.y + (row + 0.5) * up + jy};
    balls.push_back(ball);
  }
}

}  // namespace

Scene make_gas_scene(std::uint32_t n, double packing, std::uint64_t seed) {
  if (n == 0 || !(packing > 0.0 && packing < 0.75)) {
    throw std::invalid_argument("scene: gas needs n >= 1 and a packing fraction in (0, 0.75)");
  }
  Scene scene;
  scene.name = "gas";
  const double side = box_side(n, kGasRadius, packing);
  scene.lower = {-side / 2.0, -side / 2.0};
  scene.upper = {side / 2.0, side / 2.0};
  std::mt19937_64 random(seed);
  scene.balls.reserve(n);
  place_on_jittered_grid(n, kGasRadius, kGasMass, scene.lower, {side, side}, random, scene.balls);
  std::normal_distribution<double> velocity(0.0, kGasVelocitySd);
  for (SceneBall& ball : scene.balls) {
    const double vx = velocity(random);
    const double vy = velocity(random);
    ball.velocity = {vx, vy};
  }
  return scene;
}

Scene make_bullets_scene(std::uint64_t seed, double steps_per_second) {
  Scene scene;
  scene.name = "bullets";
  const double side = box_side(kBulletFieldCount, kGasRadius, kBulletFieldPacking);
  scene.lower = {-side / 2.0, -side / 2.0};
  scene.upper = {side / 2.0, side / 2.0};
  // The bullets' strip: two field diameters wide along the left wall.
  const double strip = 4.0 * kGasRadius;
  std::mt19937_64 random(seed);
  scene.balls.reserve(kBulletFieldCount + kBulletCount);
  place_on_jittered_grid(kBulletFieldCount, kGasRadius, kGasMass,
                         {scene.lower.x + strip, scene.lower.y}, {side - strip, side}, random,
                         scene.balls);
  const double bullet_mass = kGasMass * (kBulletRadius / kGasRadius) * (kBulletRadius / kGasRadius);
  const double speed = kBulletDiametersPerStep * 2.0 * kBulletRadius * steps_per_second;
  const double gap = side / kBulletCount;
  for (std::uint32_t i = 0; i < kBulletCount; ++i) {
    SceneBall bullet;
    bullet.radius = kBulletRadius;
    bullet.mass = bullet_mass;
    bullet.bullet = true;
    bullet.position = {scene.lower.x + strip / 2.0, scene.lower.y + (i + 0.5) * gap};
    bullet.velocity = {speed, 0.0};
    scene.balls.push_back(bullet);
  }
  return scene;
}

Scene make_gravity_scene(std::uint32_t n, std::uint64_t seed) {
  if (n == 0) throw std::invalid_argument("scene: gravity needs n >= 1");
  Scene scene;
  scene.name = "gravity";
  scene.gravity = {0.0, -kGravity};
  scene.restitution = kPourRestitution;
  const std::uint32_t columns =
      static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  const std::uint32_t rows = (n + columns - 1) / columns;
  const double pitch = kPourPitch * 2.0 * kGasRadius;
  const double width = columns * pitch;
  const double lattice_height = rows * pitch;
  // The lattice fills the upper two thirds; the lower third is left for the heap, which at the
  // heap's packing is lower than that (about 0.4 of the lattice's height), so no disk starts
  // inside the heap it will form.
  const double height = 1.5 * lattice_height;
  scene.lower = {-width / 2.0, -height / 2.0};
  scene.upper = {width / 2.0, height / 2.0};
  std::mt19937_64 random(seed);
  std::normal_distribution<double> velocity(0.0, kPourVelocitySd);
  scene.balls.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    SceneBall ball;
    const double column = i % columns;
    const double row = i / columns;  // whole rows: integer division
    ball.position = {scene.lower.x + (column + 0.5) * pitch,
                     scene.upper.y - lattice_height + (row + 0.5) * pitch};
    const double vx = velocity(random);
    const double vy = velocity(random);
    ball.velocity = {vx, vy};
    scene.balls.push_back(ball);
  }
  const double disk_area = std::numbers::pi * kGasRadius * kGasRadius;
  const double heap_top = scene.lower.y + n * disk_area / (kPourHeapPacking * width);
  const double lowest = scene.balls.front().position.y - kGasRadius;
  const double highest = scene.balls.back().position.y - kGasRadius;
  scene.impact_start = std::sqrt(2.0 * (lowest - scene.lower.y) / kGravity);
  scene.rest_start = std::sqrt(2.0 * (highest - heap_top) / kGravity) + kPourSettleSeconds;
  scene.end_time = scene.rest_start + kPourRestSeconds;
  return scene;
}

}  // namespace carom::peers
