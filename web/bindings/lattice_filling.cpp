#include "lattice_filling.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "carom/error.hpp"

namespace carom::web {
namespace {

// Smallest lattice spacing, in diameters: balls that start touching would be reported as
// overlapping by rounding, so the lattice keeps them apart.
constexpr double kSpacingMargin = 1.001;

[[noreturn]] void reject(const std::string& argument, const std::string& value,
                         const std::string& requirement) {
  throw InvalidArgument("fill_lattice", argument, value, requirement);
}

}  // namespace

int fill_lattice(DrawnWorld& world, const LatticeFilling& f) {
  const WorldDef& def = world.def();
  if (def.boundary == Boundary::open) reject("boundary", "open", "must be a box or periodic");
  if (f.count < 1) reject("count", std::to_string(f.count), "must be >= 1");
  if (!(f.packing_fraction > 0.0 && f.packing_fraction < 1.0)) {
    reject("packing_fraction", std::to_string(f.packing_fraction), "must lie in (0, 1)");
  }
  if (!std::isfinite(f.speed)) reject("speed", std::to_string(f.speed), "must be finite");
  const Vec2 size = def.upper - def.lower;
  const double n = static_cast<double>(f.count);
  const double radius = std::sqrt(f.packing_fraction * size.x * size.y / (n * std::numbers::pi));
  const int columns = static_cast<int>(std::ceil(std::sqrt(n * size.x / size.y)));
  const int rows = (f.count + columns - 1) / columns;
  const Vec2 spacing{size.x / columns, size.y / rows};
  if (std::min(spacing.x, spacing.y) < 2.0 * radius * kSpacingMargin) {
    reject(
        "packing_fraction", std::to_string(f.packing_fraction),
        "too dense for a " + std::to_string(columns) + " x " + std::to_string(rows) + " lattice");
  }

  std::mt19937_64 random(f.seed);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  int placed = 0;
  for (int i = 0; i < f.count; ++i) {
    const Vec2 site =
        def.lower + Vec2{(i % columns + 0.5) * spacing.x, (i / columns + 0.5) * spacing.y};
    const double a = angle(random);  // drawn for every site, so a skipped one shifts nothing
    try {
      world.add_ball(site, Vec2{std::cos(a), std::sin(a)} * f.speed, radius, 1.0);
      ++placed;
    } catch (const InvalidArgument&) {
      // The world's own overlap test decides: this site lies on a wall or an arc.
    }
  }
  return placed;
}

}  // namespace carom::web
