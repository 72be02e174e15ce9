#include "box_filling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "carom/error.hpp"

namespace carom::web {
namespace {

// Three or more inelastic balls can collide infinitely often in finite time; the world's TC
// model makes a ball that collided less than this long ago bounce elastically. The balls' mean
// free time here is about radius / speed ~ 10⁻², so 10⁻⁴ leaves the dissipation almost untouched.
constexpr double kCollapseTime = 1e-4;

// Smallest lattice spacing, in diameters: balls that start touching would be reported as
// overlapping by rounding, so the lattice keeps them apart.
constexpr double kSpacingMargin = 1.001;

[[noreturn]] void reject(const std::string& argument, const std::string& value,
                         const std::string& requirement) {
  throw InvalidArgument("fill_box", argument, value, requirement);
}

}  // namespace

DrawnWorld fill_box(const BoxFilling& f) {
  if (f.count < 1) reject("count", std::to_string(f.count), "must be >= 1");
  if (!(f.size.x > 0.0 && f.size.y > 0.0) || !is_finite(f.size)) {
    reject("size", std::to_string(f.size.x) + "," + std::to_string(f.size.y), "must be > 0");
  }
  if (!(f.packing_fraction > 0.0 && f.packing_fraction < 1.0)) {
    reject("packing_fraction", std::to_string(f.packing_fraction), "must lie in (0, 1)");
  }
  const double n = static_cast<double>(f.count);
  const double radius =
      std::sqrt(f.packing_fraction * f.size.x * f.size.y / (n * std::numbers::pi));
  const int columns = static_cast<int>(std::ceil(std::sqrt(n * f.size.x / f.size.y)));
  const int rows = (f.count + columns - 1) / columns;
  const Vec2 spacing{f.size.x / columns, f.size.y / rows};
  if (std::min(spacing.x, spacing.y) < 2.0 * radius * kSpacingMargin) {
    reject(
        "packing_fraction", std::to_string(f.packing_fraction),
        "too dense for a " + std::to_string(columns) + " x " + std::to_string(rows) + " lattice");
  }

  WorldDef def;
  def.boundary = Boundary::box;
  def.lower = {0.0, 0.0};
  def.upper = f.size;
  def.restitution = f.restitution;
  def.collapse_time = kCollapseTime;
  DrawnWorld world(def);

  std::mt19937_64 random(f.seed);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  for (int i = 0; i < f.count; ++i) {
    const Vec2 site{(i % columns + 0.5) * spacing.x, (i / columns + 0.5) * spacing.y};
    const double a = angle(random);
    world.add_ball(site, Vec2{std::cos(a), std::sin(a)} * f.speed, radius, 1.0);
  }
  return world;
}

}  // namespace carom::web
