// Growth: every movable ball's radius grows at one relative rate, r(t) = r(t₀)·(1 + γ·(t − t₀))
// (Lubachevsky–Stillinger compression; docs/engine.md, "Growth"). The species keep the radii at
// t₀; prediction takes the general path (world_gravity.cpp) with each ball's growth in its
// Motion, so every gap is a quadratic closed exactly; a contact's response adds the pair's growth
// speed to the approach, so that two balls leave a contact faster than their radii grow and never
// overlap; and the grid is re-planned when the largest ball outgrows its cells.
#include <algorithm>
#include <cmath>
#include <string>

#include "carom/error.hpp"
#include "carom/number_text.hpp"
#include "core/impulse.hpp"
#include "engine_tuning.hpp"
#include "world_impl.hpp"

namespace carom {

using detail::BallSlot;
using namespace detail::tuning;  // NOLINT(google-build-using-namespace): the engine's constants

namespace {

// Cells are re-planned with room for radii this many times those of the moment, so that a
// compression from a gas to a jammed packing (diameters × 1.5 to 2) re-plans a few times.
constexpr double kGrowthRoom = 1.25;
// A re-planned grid gives the largest ball at least this much relative room to grow into, or
// the world refuses to grow on (else re-planning would come ever sooner, without end).
constexpr double kLeastGrowthRoom = 0x1p-20;

}  // namespace

void World::Impl::settle_growth() {
  if (!growth_on || time == growth_start) {
    growth_start = time;
    return;
  }
  // The same linear law from here: radii × f, the relative rate ÷ f.
  const double factor = 1.0 + growth_relative * (time - growth_start);
  species.scale_movable_radii(factor);
  growth_relative /= factor;
  growth_start = time;
  for (std::uint32_t i = 0; i < balls.size(); ++i) {
    if (balls[i].alive()) largest_radius = std::max(largest_radius, radius_of(i));
  }
}

void World::Impl::plan_growth_regrid() {
  growth_regrid_time = kInfinity;
  if (!growth_on || !grid_valid) return;
  double largest = 0.0;
  for (std::uint32_t i = 0; i < balls.size(); ++i) {
    if (balls[i].alive() && movable(i)) largest = std::max(largest, radius_of(i));
  }
  if (largest == 0.0) return;
  // The cells hold balls up to grid.room() across (beyond their hysteresis): the scale of the
  // radii at t₀ at which the largest fills that.
  const double fits = grid.room() / (2.0 * largest * (1.0 + detail::kCellMargin));
  growth_regrid_time = growth_start + (fits - 1.0) / growth_relative;
}

void World::Impl::regrid_for_growth(double t) {
  synchronize(t);
  settle_growth();
  double largest = 0.0;
  Vec2 where;
  for (std::uint32_t i = 0; i < balls.size(); ++i) {
    if (balls[i].alive() && radius_of(i) > largest) {
      largest = radius_of(i);
      where = balls[i].position;
    }
  }
  rebuild_grid(where, kGrowthRoom * largest);
  // (Re-planned when the largest ball fills its cells, a grid without room to grow into has
  // reached its cap.)
  if (!(2.0 * largest * (1.0 + detail::kCellMargin) * (1.0 + kLeastGrowthRoom) <= grid.room())) {
    // Only a periodic cell caps the cells (at a third of its side, so that the 3×3 block never
    // holds a cell twice).
    throw InvalidArgument(
        "World::run", "world", "t = " + carom::number_text(time),
        "has balls grown too large for its periodic cell: a diameter of " +
            carom::number_text(2.0 * largest) +
            " no longer fits a third of the cell's side; stop growth before (docs/world.md, "
            "\"Growth\")");
  }
  plan_growth_regrid();
  predict_all();
}

bool World::Impl::resolve_pair_under_growth(std::uint32_t i, std::uint32_t j, double t) {
  advance(i, t);
  advance(j, t);
  BallSlot& a = balls[i];
  BallSlot& b = balls[j];
  const Vec2 between = minimum_image(b.position - a.position);
  const Vec2 normal = between == Vec2{} ? normalized(a.velocity - b.velocity) : normalized(between);
  // The gap closes by the centres' approach and by the growth of the two radii; the bounce
  // reverses that closing (times the restitution), so the two part faster than they grow.
  const double closing = dot(a.velocity - b.velocity, normal) + growth_of(i) + growth_of(j);
  bool resolved = false;
  if (closing > 0.0) {
    const double inverse_a = species_of(i).inverse_mass;
    const double inverse_b = species_of(j).inverse_mass;
    const double impulse =
        detail::normal_impulse(closing, inverse_a, inverse_b, pair_restitution(i, j, t));
    detail::apply_impulse(a.velocity, b.velocity, normal, impulse, inverse_a, inverse_b);
    if (def.collapse_time > 0.0) {
      last_contact_times[i] = t;
      last_contact_times[j] = t;
    }
    if (contact_wanted()) {
      const double radius_a = radius_at(i, t);
      record_ball_ball(i, j, t, between, normal, closing, impulse,
                       radius_a / (radius_a + radius_at(j, t)));
    }
    resolved = true;
    if (inverse_a == 0.0 ? a.velocity != Vec2{} : (inverse_b == 0.0 && b.velocity != Vec2{})) {
      mover_met = true;
    }
  }
  ++a.version;
  ++b.version;
  predict(i);
  predict(j);
  return resolved;
}

bool World::Impl::resolve_wall_under_growth(std::uint32_t i, std::uint32_t wall, double t) {
  advance(i, t);
  BallSlot& a = balls[i];
  const auto [now, point, normal] = touch_wall(i, wall, t);
  // Inside a bowl too the gap closes at the approach plus the growth, which is never 0: a plain
  // bounce answers (no turn along the wall).
  const double closing = dot(a.velocity, normal) + growth_of(i);
  bool resolved = false;
  if (closing > 0.0) {
    const double restitution = collided_recently(i, t) ? 1.0 : restitution_of(i);
    const double speed_change = detail::wall_speed_change(closing, restitution);
    a.velocity -= normal * speed_change;
    record_ball_wall(i, wall, t, point, normal, closing, speed_change);
    resolved = true;
    ++a.version;
  }
  predict(i);
  return resolved;
}

}  // namespace carom
