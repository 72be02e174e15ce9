// Contact response: a contact's two balls (or ball and wall) bounced and recorded, then
// predicted again (docs/engine.md, "Response").
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include "carom/error.hpp"
#include "cell_exit.hpp"
#include "contact_pace.hpp"
#include "core/bowl_bounce.hpp"
#include "core/circle_crossing.hpp"
#include "core/impulse.hpp"
#include "core/validate.hpp"
#include "engine_tuning.hpp"
#include "pair_batch.hpp"
#include "permute.hpp"
#include "prediction_steps.hpp"
#include "world_impl.hpp"

namespace carom {

using detail::BallSlot;
using detail::Event;
using detail::EventKind;
using namespace detail::tuning;  // NOLINT(google-build-using-namespace): the engine's constants

namespace {

// The unit vector along d, d not zero. Where d·d is far from both ends of the double range,
// d / √(d·d) (within an ulp or so of unit length, as carom::normalized's quotient by std::hypot
// is): glibc's hypot, careful where the squares would overflow or underflow, is a slow call in
// the response's hot path (docs/decisions/0016-response-repeats-bounce.md). Elsewhere
// normalized, which scales first.
CAROM_ALWAYS_INLINE inline Vec2 unit_along(Vec2 d) {
  const double squared = length_squared(d);
  if (squared > 0x1p-1000 && squared < 0x1p+1000) [[likely]]
    return d / std::sqrt(squared);
  return normalized(d);
}

}  // namespace

bool World::Impl::process(const Event& event) {
  if (general_motion) [[unlikely]]
    return process_general(event);
  const std::uint32_t i = event.owner;
  switch (event.kind) {
    case EventKind::ball_ball: {
      const std::uint32_t j = event.partner;
      if (!balls[j].alive() || balls[j].version != event.partner_version) {
        advance(i, event.time);  // stale: the partner changed course since
        predict(i);
        return false;
      }
      return resolve_ball_ball(i, j, event.time);
    }
    case EventKind::ball_wall:
      if (event.partner_version != 0) [[unlikely]] {
        return event.partner_version == detail::kSensorEvent
                   ? process_sensor(i, event.partner, event.time)
                   : process_moving_wall(event);
      }
      return resolve_ball_wall(i, event.partner, event.time);
    case EventKind::cell_crossing:
      cross_cell(i, event.partner, event.time, event.partner_version == detail::kClearBehind);
      return false;
    case EventKind::motion_change:  // (under gravity or on a table only)
      return false;
  }
  return false;
}

bool World::Impl::resolve_ball_ball(std::uint32_t i, std::uint32_t j, double t) {
  advance(i, t);
  advance(j, t);
  BallSlot& a = balls[i];
  BallSlot& b = balls[j];
  const Vec2 between = minimum_image(b.position - a.position);
  const Vec2 normal = between == Vec2{} ? normalized(a.velocity - b.velocity) : unit_along(between);
  const double approach = dot(a.velocity - b.velocity, normal);
  bool resolved = false;
  if (approach > 0.0) {
    const double restitution = pair_restitution(i, j, t);
    const double inverse_a = species_of(i).inverse_mass;
    const double inverse_b = species_of(j).inverse_mass;
    const double impulse = detail::normal_impulse(approach, inverse_a, inverse_b, restitution);
    detail::apply_impulse(a.velocity, b.velocity, normal, impulse, inverse_a, inverse_b);
    if (def.collapse_time > 0.0) {
      last_contact_times[i] = t;
      last_contact_times[j] = t;
    }
    if (contact_wanted()) record_ball_ball(i, j, t, between, normal, approach, impulse);
    resolved = true;
    // An immovable ball at rest is a post, like a wall; a moving one does work on what it meets.
    if (inverse_a == 0.0 ? a.velocity != Vec2{} : (inverse_b == 0.0 && b.velocity != Vec2{})) {
      mover_met = true;
    }
  }
  ++a.version;
  ++b.version;
  predict_both(i, j);
  return resolved;
}

void World::Impl::record_ball_ball(std::uint32_t i, std::uint32_t j, double t, Vec2 between,
                                   Vec2 normal, double approach, double impulse, double share) {
  const BallSlot& a = balls[i];
  const bool a_first = handle_before(i, j);  // the pair in handle order, as the docs promise
  ContactEvent contact;
  contact.time = t;
  contact.kind = ContactKind::ball_ball;
  contact.a = id_of(a_first ? i : j);
  contact.b = id_of(a_first ? j : i);
  contact.normal = a_first ? normal : -normal;
  if (share < 0.0) {
    const double radius_a = radius_of(i);
    share = radius_a / (radius_a + radius_of(j));
  }
  contact.point = a.position + between * share;
  contact.approach_speed = approach;
  contact.impulse = impulse;
  record(contact);
}

bool World::Impl::resolve_ball_wall(std::uint32_t i, std::uint32_t wall, double t) {
  advance(i, t);
  BallSlot& a = balls[i];
  // The contact's own normal where the query confirms it (touching and approaching now), else
  // the direction to the nearest point (the ball a rounding short of the wall).
  const Ball shape{a.position, radius_of(i)};
  Impact now = detail::time_of_impact(walls[wall], shape, a.velocity, 0.0);
  if (!now.hit) {
    // A contact a sliver ahead that the motion cannot reach: a gap below the rounding of the
    // position closes at a time at which the ball is still where it is now, so advancing it
    // changes nothing and the same contact would come up again and again, a sliver later each
    // time (a ball filling an arc's circle, at its centre, met its end point so). It is a
    // contact now.
    const Impact ahead = detail::time_of_impact(walls[wall], shape, a.velocity, kFarFuture);
    if (ahead.hit && ahead.a_at == a.position) now = ahead;
  }
  const Vec2 point = now.hit ? now.point : detail::nearest_point(walls[wall], a.position);
  const Vec2 normal = now.hit ? now.normal : normalized(point - a.position);
  const double approach = dot(a.velocity, normal);
  // Inside a bowl a ball moving along the wall (approach 0) is a contact too (the query reports
  // it), answered by bounce_inside_arc's turn (docs/engine.md, "Response").
  const bool in_bowl = detail::inside_arc(walls[wall], a.position);
  bool resolved = false;
  if (approach > 0.0 || (in_bowl && now.hit)) {
    const double restitution = collided_recently(i, t) ? 1.0 : restitution_of(i);
    double speed_change = 0.0;
    if (in_bowl) {
      const detail::BowlBounce bounce = detail::bounce_inside_arc(a.velocity, normal, restitution);
      a.velocity = bounce.velocity;
      speed_change = bounce.normal_speed_change;
    } else {
      speed_change = detail::wall_speed_change(approach, restitution);
      a.velocity -= normal * speed_change;
    }
    record_ball_wall(i, wall, t, point, normal, approach, speed_change);
    resolved = true;
    ++a.version;
  }
  predict(i);
  return resolved;
}

void World::Impl::record_ball_wall(std::uint32_t i, std::uint32_t wall, double t, Vec2 point,
                                   Vec2 normal, double approach, double speed_change) {
  if (def.collapse_time > 0.0) last_contact_times[i] = t;
  ContactEvent contact;
  contact.time = t;
  contact.kind = ContactKind::ball_wall;
  contact.a = id_of(i);
  contact.wall = wall;
  contact.point = point;
  contact.normal = normal;
  contact.approach_speed = approach;
  contact.impulse = movable(i) ? speed_change * species_of(i).mass : 0.0;
  record(contact);
}

}  // namespace carom
