// Moving walls in the event loop (carom/wall_motion.hpp). A moving wall is listed in no grid
// cell: every ball's prediction asks about each one (a game has a few), and the answer is one
// more candidate for the ball's single pending event, with the wall's path ended or the search
// stopped short as a "look again" event. A contact with a wall that stands still at that instant
// is a static wall's contact (under gravity it may carry the ball); with one that moves, the
// bounce takes the wall's velocity at the contact point. Design: docs/engine.md, "Moving walls".
#include <algorithm>
#include <cmath>
#include <string>

#include "carom/error.hpp"
#include "core/impulse.hpp"
#include "core/rigid_sweep.hpp"
#include "engine_tuning.hpp"
#include "world_impl.hpp"

namespace carom {

using detail::Event;
using detail::EventKind;
using namespace detail::tuning;  // NOLINT(google-build-using-namespace): the engine's constants

bool World::Impl::rests_on(std::uint32_t ball, std::uint32_t wall) const {
  if (!gravity_on || !movable(ball)) return false;
  const detail::Carriage& c = carriages[ball];
  const auto end = c.support.begin() + c.supports;
  return std::find(c.support.begin(), end, wall) != end;
}

void World::Impl::consider_moving_walls(Event& best, std::uint32_t ball, const Ball& shape,
                                        const Motion& motion, double horizon) const {
  // An immovable ball and a moving wall pass through each other, still or not: neither can give
  // way (and one that passed into it while it moved must not be held there once it stops).
  if (!movable(ball)) return;
  // (Square roots of sums of squares: std::hypot, which length() is, is a slow call here.)
  const double speed = std::sqrt(length_squared(motion.velocity));
  const double pull = std::sqrt(length_squared(motion.acceleration));
  for (const std::uint32_t w : moving_walls) {
    const detail::Wall& wall = walls[w];
    if (wall.removed || !meets_wall(ball, w) || rests_on(ball, w)) continue;
    // Nothing later than the best event so far matters, nor, while the wall moves, anything
    // after its path ends (it stands still from then: the ball is asked about it again).
    const double sooner = best.time < kInfinity ? best.time - time : kFarFuture;
    const bool moves = wall.moves_at(time);
    const double ends = moves ? wall.path.until - time : kInfinity;
    const double within = std::min(horizon, sooner);
    const double search = std::min(within, ends);
    // Out of reach: within `within` the ball keeps within its travel of where it is, and the
    // wall within its reach of the pivot, which moves at most its velocity's travel (for the
    // most part of the world the horizon, a cell's exit, ends the question here).
    const Vec2 pivot =
        wall.path.rigid.pivot + wall.path.rigid.velocity * detail::path_time(wall, time);
    const double travel =
        within < kFarFuture ? (speed + 0.5 * pull * within + motion.growth) * within : kInfinity;
    const double reach =
        (shape.radius + travel + wall.path.reach + wall.path.speed * search) * (1.0 + 0x1p-30);
    if (length_squared(shape.center - pivot) > reach * reach) continue;
    const detail::RigidMotion rigid = detail::motion_from(wall, time);
    detail::Wall now = wall;
    detail::place_at(now, time);
    const detail::RigidContact found =
        now.is_arc ? detail::rigid_ball_arc(shape, motion, now.arc, now.frame, rigid, search)
                   : detail::rigid_ball_segment(shape, motion, now.segment, rigid, search);
    Event candidate;
    candidate.kind = EventKind::ball_wall;
    candidate.owner = ball;
    candidate.partner = w;
    if (found.impact.hit) {
      candidate.time = time + found.impact.t;
      candidate.partner_version = detail::kMovingWallContact;
    } else if (found.checked < search) {
      candidate.time = time + found.checked;
      candidate.partner_version = detail::kMovingWallLook;
    } else if (moves && ends <= within) {
      candidate.time = wall.path.until;
      candidate.partner_version = detail::kMovingWallLook;
    } else {
      continue;
    }
    if (detail::earlier(candidate, best, handle_of.data())) best = candidate;
  }
}

bool World::Impl::process_moving_wall(const Event& event) {
  const std::uint32_t i = event.owner;
  const std::uint32_t w = event.partner;
  const double t = event.time;
  if (event.partner_version == detail::kMovingWallLook) {
    advance(i, t);
    predict(i);
    return false;
  }
  detail::Wall& wall = walls[w];
  detail::place_at(wall, t);
  if (!wall.moves_at(t)) {
    // It stands still now: a static wall's contact, which under gravity may rest the ball on it.
    if (!general_motion) return resolve_ball_wall(i, w, t);
    return gravity_on ? resolve_wall_under_gravity(i, w, t) : resolve_wall_under_growth(i, w, t);
  }
  advance(i, t);
  if (gravity_on) disturb(i);  // whatever it rested on or carried, a hit sets it free
  detail::BallSlot& a = balls[i];
  const Vec2 point = detail::nearest_point(wall, a.position);
  const Vec2 toward = point - a.position;
  const detail::RigidMotion rigid = detail::motion_from(wall, t);
  const Vec2 arm = point - rigid.pivot;
  const Vec2 wall_velocity = rigid.velocity + Vec2{-arm.y, arm.x} * rigid.angular_velocity;
  const Vec2 normal =
      toward != Vec2{} ? normalized(toward) : normalized(wall_velocity - a.velocity);
  // The approach of the ball's surface to the wall's: its velocity relative to the wall's point,
  // along the normal, and its growth.
  const double approach = dot(a.velocity - wall_velocity, normal) + growth_of(i);
  bool resolved = false;
  if (approach > 0.0) {
    const double restitution = collided_recently(i, t) ? 1.0 : restitution_of(i);
    double speed_change = detail::wall_speed_change(approach, restitution);
    // Under gravity a ball cannot rest on a wall that moves (its support would move): it leaves
    // at its rest speed at least, a hop of rest_height radii, rather than bounce ever lower.
    if (gravity_on) speed_change = std::max(speed_change, approach + rest_speed(i));
    a.velocity -= normal * speed_change;
    record_ball_wall(i, w, t, point, normal, approach, speed_change);
    resolved = true;
    mover_met = true;  // it does work on the balls: a run that never ends is a crush
  }
  ++a.version;
  predict(i);
  return resolved;
}

detail::Wall& World::Impl::changeable_wall(const char* function, std::uint32_t id) {
  if (id >= walls.size()) {
    throw InvalidArgument(function, "wall", std::to_string(id),
                          "must be below wall_count() = " + std::to_string(walls.size()));
  }
  if (def.boundary == Boundary::box && id < 4) {
    throw InvalidArgument(function, "wall", std::to_string(id),
                          "is a side of the box boundary, which keeps every ball in");
  }
  if (walls[id].removed) throw InvalidArgument(function, "wall", std::to_string(id), "was removed");
  return walls[id];
}

void World::Impl::free_resting_on(std::uint32_t id) {
  if (!gravity_on) return;
  for_each_live([&](std::uint32_t slot) {
    if (rests_on(slot, id)) {
      advance(slot, time);
      disturb(slot);
    }
  });
}

void World::Impl::place_moving_walls() {
  for (const std::uint32_t w : moving_walls) detail::place_at(walls[w], time);
}

}  // namespace carom
