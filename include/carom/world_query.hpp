// carom: what the world's queries take and give (World::cast_ray, cast_ball and the overlap
// queries in carom/world.hpp). A query asks about the world as it stands at its time, between
// runs: balls where they are now, with the radii they have now; nothing moves while it is
// answered. The user guide: docs/queries.md.
#pragma once

#include <cstdint>
#include <functional>

#include "carom/handles.hpp"
#include "carom/vec2.hpp"

namespace carom {

// Which balls and walls a query sees. The default sees everything.
struct QueryFilter {
  bool balls = true;  // false: the query sees no ball
  bool walls = true;  // false: the query sees no wall
  BallId ignore;      // a ball it does not see (a cast of a ball of the world, from where it is)
  // The categories it sees: a ball or wall whose CollisionFilter's category shares no bit with
  // it is hidden (carom/filter.hpp).
  std::uint64_t mask = ~0ULL;
  // When set, called for each ball the query would report (or weigh, for the casts); false hides
  // it. Called in no particular order, and not for balls the query can rule out by distance.
  std::function<bool(BallId)> accept;
};

enum class HitKind : std::uint8_t { none, ball, wall };

// The first thing a ray or a cast ball meets.
struct QueryHit {
  HitKind kind = HitKind::none;
  BallId ball;      // kind == ball
  WallId wall = 0;  // kind == wall
  // Where along the translation it meets it, in [0, 1] (the point or centre then is
  // start + fraction · translation); 1 when nothing is met.
  double fraction = 1.0;
  Vec2 point;   // the point of contact (for a cast ball: where the two surfaces touch)
  Vec2 normal;  // unit, at the contact, pointing from what was hit back towards the caster
  // A cast ball's centre at the contact (for a ray: the point). Taken from the obstacle's side
  // (its centre less the normal times the two radii, or the wall's point less the normal times
  // the radius), so that it touches the obstacle to the rounding of the obstacle's coordinates.
  Vec2 center;
  // The cast started overlapping what it reports (fraction 0); a ray never reports a ball it
  // starts inside.
  bool overlapping = false;
  [[nodiscard]] explicit operator bool() const noexcept { return kind != HitKind::none; }
};

}  // namespace carom
