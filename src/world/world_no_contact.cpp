// When can the world prove that no contact will ever happen again? run_collisions asks, after a
// long stretch of events without a contact, so that it returns instead of following cell
// crossings for ever. The rules and why they are exact: docs/engine.md, "When nothing will happen".
#include <algorithm>
#include <cmath>

#include "world_impl.hpp"

namespace carom {

namespace {

// A motion counts as "moving apart" only when it does so by more than this fraction of the
// product of the lengths involved: far above the rounding of one dot product (~1e-16), so the
// engine, recomputing the same quantities later from re-rounded positions, agrees it is no
// approach. A pair that is moving apart by less is simply not proven now, and asked again later.
constexpr double kApartSlack = 1e-9;

// True when s·u shows the distance |s + u·t| growing for every t >= 0, with room for rounding
// (u exactly zero: the distance never changes, so nothing can approach).
bool moving_apart(Vec2 s, Vec2 u) {
  if (u == Vec2{}) return true;
  return dot(s, u) > kApartSlack * length(s) * length(u);
}

// True when two balls at offset s with relative velocity u never come within `reach`: moving
// apart, or approaching along a line that passes them by more than reach (the closest distance
// of |s + u·t| over all t is |s × u| / |u|), with the same relative room for rounding.
bool never_within(Vec2 s, Vec2 u, double reach) {
  if (moving_apart(s, u)) return true;
  return std::abs(cross(s, u)) > reach * (1.0 + kApartSlack) * length(u);
}

}  // namespace

bool World::Impl::no_contact_ever() const {
  // Two balls of which at least one can respond are the only pairs that ever meet; both
  // immovable pass through each other.
  const auto can_meet = [&](std::uint32_t i, std::uint32_t j) { return movable(i) || movable(j); };
  // Under gravity paths bend back towards what they left, and growing balls close every gap:
  // nothing is proved (a run with no end time is then ended by its time limit, or by the queue
  // running dry).
  if (general_motion) return false;
  // A moving wall's reach is not followed here: nothing is proved.
  if (!moving_walls.empty()) return false;

  if (def.boundary == Boundary::periodic) {
    if (!walls.empty()) return false;
    // On a torus a pair that moves relative to the other generally meets it some day (its
    // relative path winds densely, or closes on itself after a period that can be astronomically
    // long), so only two cases are proved: no relative motion at all, and relative motion along
    // one axis with the minimum-image gap across that axis wider than the reach (plus a margin
    // far above the rounding that re-wrapping positions can accumulate).
    const double margin =
        kApartSlack * std::max(periodic_cell.period().x, periodic_cell.period().y);
    for (std::uint32_t i = 0; i < balls.size(); ++i) {
      if (!balls[i].alive()) continue;
      const Vec2 pi = position_at(i, time);
      for (std::uint32_t j = i + 1; j < balls.size(); ++j) {
        if (!balls[j].alive() || !can_meet(i, j)) continue;
        const Vec2 u = balls[i].velocity - balls[j].velocity;
        if (u == Vec2{}) continue;
        const Vec2 s = minimum_image(pi - position_at(j, time));
        const double reach = radius_of(i) + radius_of(j) + margin;
        const bool along_x_clear = u.y == 0.0 && std::abs(s.y) > reach;
        const bool along_y_clear = u.x == 0.0 && std::abs(s.x) > reach;
        if (!along_x_clear && !along_y_clear) return false;
      }
    }
    return true;
  }

  // A moving ball inside a sensor leaves it some day, or may: an exit to come.
  for (const std::uint64_t key : sensor_inside) {
    if (balls[slot_of_handle[static_cast<std::uint32_t>(key >> 32)]].velocity != Vec2{}) {
      return false;
    }
  }

  // Open world or box: straight lines in the plane. The distance from a point moving in a
  // straight line to a convex set is a convex function of time, so once it grows it grows for
  // ever. Ball pairs: |s + u·t| grows once s·u > 0, and never falls below |s × u|/|u|, so a pair
  // whose relative line passes clear of the two radii never meets either. Segments (convex): the
  // ball moves away from its nearest point. Arcs: the arc lies in its circle's disk (convex); a
  // ball outside that disk by more than its radius and moving away from the centre never reaches
  // the arc.
  for (std::uint32_t i = 0; i < balls.size(); ++i) {
    const detail::BallSlot& a = balls[i];
    if (!a.alive()) continue;
    const Vec2 p = position_at(i, time);
    for (const detail::Wall& wall : walls) {
      if (a.velocity == Vec2{}) break;
      if (wall.is_disc) {
        // A sensor's disc (convex): outside it by more than the radius and moving away from it.
        const Vec2 from_center = p - wall.disc.center;
        const double clear = (wall.disc.radius + radius_of(i)) * (1.0 + kApartSlack);
        if (!(length(from_center) > clear) || !moving_apart(from_center, a.velocity)) {
          return false;
        }
      } else if (wall.is_arc) {
        const Vec2 from_center = p - wall.arc.center;
        const double clear = (wall.arc.radius + radius_of(i)) * (1.0 + kApartSlack);
        if (!(length(from_center) > clear) || !moving_apart(from_center, a.velocity)) {
          return false;
        }
      } else if (!moving_apart(p - detail::nearest_point(wall, p), a.velocity)) {
        return false;
      }
    }
    for (std::uint32_t j = i + 1; j < balls.size(); ++j) {
      if (!balls[j].alive() || !can_meet(i, j)) continue;
      const double reach = radius_of(i) + radius_of(j);
      if (!never_within(p - position_at(j, time), a.velocity - balls[j].velocity, reach)) {
        return false;
      }
    }
  }
  return true;
}

}  // namespace carom
