// World::audit: an independent check of the world's invariants, for tests and debugging. All
// pairs for small worlds (or when asked), the grid's 3×3 blocks for large ones, in which case
// the grid's own invariant (each ball inside the cell it is filed in) is checked too.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "core/validate.hpp"
#include "world_impl.hpp"

namespace carom {

using Violation = std::optional<std::string>;

namespace {

// Up to this many balls audit() checks every pair (O(N²)), which relies on nothing the engine
// maintains; above it, the grid (O(N)).
constexpr std::size_t kAllPairsAuditBalls = 256;

// Balls are named by their handle index (BallId::index), not by where the engine stores them.
std::string ball_name(std::uint32_t handle) { return "ball " + std::to_string(handle); }

// A position is known to the rounding of its coordinates, and a ball's position at the world's
// time to the rounding of the event times it was moved at (|v| times an ulp of the time): an
// absolute error that no tolerance relative to the radii can cover when a ball is far smaller
// than an ulp of where it is (a ball of radius 1e-6 at x = 20 touching a wall at x = 20 has no
// double centre that touches exactly; one at speed 1e-9 after 10^11 time units is off by
// 1e-14). The audit allows this many ulps of that scale on top of the relative tolerance: a few
// roundings per prediction, which do not add up over a run (each contact is placed afresh).
constexpr double kRoundingUlps = 8.0;

double position_rounding(Vec2 p, Vec2 v, double time) {
  const double scale = std::max(std::abs(p.x), std::abs(p.y)) +
                       std::max(std::abs(v.x), std::abs(v.y)) * std::abs(time);
  return kRoundingUlps * std::numeric_limits<double>::epsilon() * scale;
}

}  // namespace

// The checks of one ball on its own: finite, inside a box.
Violation World::Impl::audit_ball(std::uint32_t i, Vec2 p, double tolerance) const {
  const Impl& w = *this;
  const detail::BallSlot& a = w.balls[i];
  const double radius = w.radius_at(i, w.time);
  if (!is_finite(p) || !is_finite(a.velocity)) {
    return ball_name(w.handle_of[i]) + " has a non-finite position or velocity";
  }
  if (w.def.boundary == Boundary::box) {
    const double box_scale = std::max({std::abs(w.def.lower.x), std::abs(w.def.lower.y),
                                       std::abs(w.def.upper.x), std::abs(w.def.upper.y)});
    const double slack = tolerance * radius + position_rounding(p, a.velocity, w.time) +
                         kRoundingUlps * std::numeric_limits<double>::epsilon() * box_scale;
    if (p.x - radius < w.def.lower.x - slack || p.x + radius > w.def.upper.x + slack ||
        p.y - radius < w.def.lower.y - slack || p.y + radius > w.def.upper.y + slack) {
      return ball_name(w.handle_of[i]) + " reaches outside the box";
    }
  }
  return std::nullopt;
}

Violation World::Impl::audit_wall(std::uint32_t i, Vec2 p, std::uint32_t k,
                                  double tolerance) const {
  const Impl& w = *this;
  // A sensor is passed through; so is a wall the ball's filter lets it through, and a moving wall
  // by an immovable ball (neither gives way).
  if (!w.walls[k].solid() || !w.meets_wall(i, k)) return std::nullopt;
  if (w.walls[k].moving && !w.movable(i)) return std::nullopt;
  const double radius = w.radius_at(i, w.time);
  const double gap = length(detail::nearest_point(w.walls[k], p) - p);
  const double slack = tolerance * radius + position_rounding(p, w.balls[i].velocity, w.time);
  if (gap < radius - slack) {
    return ball_name(w.handle_of[i]) + " overlaps wall " + std::to_string(k) + " by " +
           carom::number_text(radius - gap);
  }
  return std::nullopt;
}

Violation World::Impl::audit_pair(std::uint32_t i, Vec2 p, std::uint32_t j,
                                  double tolerance) const {
  const Impl& w = *this;
  // Two immovable balls pass through each other (nothing could respond; docs/engine.md,
  // "Response"): their overlap breaks no promise.
  if (!w.movable(i) && !w.movable(j)) return std::nullopt;
  if (!w.balls_meet(i, j)) return std::nullopt;  // their filters let them through each other
  const double reach = w.radius_at(i, w.time) + w.radius_at(j, w.time);
  const Vec2 q = w.position_at(j, w.time);
  const double gap = length(w.minimum_image(q - p));
  const double slack = tolerance * reach + position_rounding(p, w.balls[i].velocity, w.time) +
                       position_rounding(q, w.balls[j].velocity, w.time);
  if (gap < reach - slack) {
    const std::uint32_t low = std::min(w.handle_of[i], w.handle_of[j]);
    const std::uint32_t high = std::max(w.handle_of[i], w.handle_of[j]);
    return "balls " + std::to_string(low) + " and " + std::to_string(high) + " overlap by " +
           carom::number_text(reach - gap);
  }
  return std::nullopt;
}

Violation World::Impl::audit_all_pairs(double tolerance) const {
  const Impl& w = *this;
  for (std::uint32_t i = 0; i < w.balls.size(); ++i) {
    if (!w.balls[i].alive()) continue;
    const Vec2 p = w.position_at(i, w.time);
    if (Violation v = audit_ball(i, p, tolerance)) return v;
    for (std::uint32_t k = 0; k < w.walls.size(); ++k) {
      if (Violation v = audit_wall(i, p, k, tolerance)) return v;
    }
    for (std::uint32_t j = i + 1; j < w.balls.size(); ++j) {
      if (!w.balls[j].alive()) continue;
      if (Violation v = audit_pair(i, p, j, tolerance)) return v;
    }
  }
  return std::nullopt;
}

// Finds every overlap that all pairs would find, provided each ball lies in the cell it is filed
// in (checked here, to a rounding) and cells are at least a diameter wide (the grid's rule): two
// overlapping balls are then in neighbouring cells, and a wall within a radius of a ball is
// listed in the ball's cell.
Violation World::Impl::audit_with_grid(double tolerance) const {
  const Impl& w = *this;
  for (std::uint32_t i = 0; i < w.balls.size(); ++i) {
    if (!w.balls[i].alive()) continue;
    const Vec2 p = w.position_at(i, w.time);
    if (Violation v = audit_ball(i, p, tolerance)) return v;
    const std::int32_t cell = grid.cell_of_ball(i);
    if (cell == detail::kNoBall) return ball_name(w.handle_of[i]) + " is in no grid cell";
    const Vec2 low = grid.cell_lower(cell);
    const Vec2 high = grid.cell_upper(cell);
    // The engine files a ball in its new cell at the computed crossing time, when its centre may
    // sit a rounding on the old side; kCellMargin is the room the cells were sized with for that.
    // A ball leaves its cell only the grid's hysteresis beyond its side.
    const Vec2 slack{detail::kCellMargin * (high.x - low.x + std::abs(p.x)) + grid.hysteresis().x,
                     detail::kCellMargin * (high.y - low.y + std::abs(p.y)) + grid.hysteresis().y};
    const bool outer_x = w.def.boundary == Boundary::box;  // a box's outer cells reach its walls
    const bool inside =
        (p.x >= low.x - slack.x || (outer_x && grid.column(cell) == 0)) &&
        (p.x <= high.x + slack.x || (outer_x && grid.column(cell) + 1 == grid.nx())) &&
        (p.y >= low.y - slack.y || (outer_x && grid.row(cell) == 0)) &&
        (p.y <= high.y + slack.y || (outer_x && grid.row(cell) + 1 == grid.ny()));
    if (!inside) {
      return ball_name(w.handle_of[i]) + " at " + detail::vector_text(p) +
             " lies outside its grid cell " + std::to_string(cell);
    }
    for (const std::uint32_t k : grid.walls(cell)) {
      if (Violation v = audit_wall(i, p, k, tolerance)) return v;
    }
    for (const std::uint32_t k : w.moving_walls) {
      if (Violation v = audit_wall(i, p, k, tolerance)) return v;
    }
    Violation found;
    grid.for_each_neighbour(cell, [&](std::int32_t neighbour) {
      for (std::int32_t j = grid.first_ball(neighbour); j != detail::kNoBall && !found;
           j = grid.next_ball(static_cast<std::uint32_t>(j))) {
        const auto other = static_cast<std::uint32_t>(j);
        if (other > i) found = audit_pair(i, p, other, tolerance);
      }
    });
    if (found) return found;
  }
  return std::nullopt;
}

std::optional<std::string> World::audit(double tolerance) const {
  const Impl& w = *impl_;
  if (!w.grid_valid || w.live_count <= kAllPairsAuditBalls) return w.audit_all_pairs(tolerance);
  return w.audit_with_grid(tolerance);
}

std::optional<std::string> World::audit_all_pairs(double tolerance) const {
  return impl_->audit_all_pairs(tolerance);
}

}  // namespace carom
