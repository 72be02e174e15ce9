// The table (docs/engine.md, "The table"): each ball's spin and motion state beside its slot, the
// end of a state as an event of its own, and the contacts' responses on a cloth — two balls with
// throw (core/table_motion.hpp's collide_on_table), a ball and a cushion by Han's model
// (cushion_bounce). Prediction is world_gravity.cpp's, each ball with its state's acceleration.
#include <algorithm>
#include <cmath>

#include "carom/error.hpp"
#include "core/bowl_bounce.hpp"
#include "core/table_motion.hpp"
#include "world_impl.hpp"

namespace carom {

using detail::BallSlot;
using detail::TableBall;

namespace {
namespace table_response {  // (named: the world compiles as unity files)

// The approach below which a contact that friction presses together (relative acceleration
// `press` > 0 along the normal) is held rather than bounced: the speed at which the press would
// close a gap of rest_height times the reach `reach` (as a ball rests under gravity,
// docs/world.md). A bounce slower than that would be followed by another, sooner, for ever.
double hold_speed(double press, double rest_height, double reach) {
  return press > 0.0 ? std::sqrt(2.0 * press * rest_height * reach) : 0.0;
}

}  // namespace table_response
}  // namespace

using namespace table_response;  // NOLINT(google-build-using-namespace): this file's own helpers

void World::Impl::use_table() {
  const Table& table = *def.table;
  cloth = {table.g, table.sliding_friction, table.rolling_friction, table.spinning_friction};
  cushion = {table.cushion_height, table.cushion_restitution, table.cushion_friction};
  table_slots.resize(balls.size());
}

void World::Impl::require_table(const char* function) const {
  if (!table_on) {
    throw InvalidArgument(function, "WorldDef::table", "unset",
                          "a table is needed: without one the balls have no spin");
  }
}

TableBall World::Impl::table_ball(std::uint32_t ball) const {
  const BallSlot& b = balls[ball];
  const detail::TableSlot& slot = table_slots[ball];
  TableBall out;
  out.velocity = b.velocity;
  out.spin = slot.spin;
  out.twist = slot.twist;
  out.radius = radius_of(ball);
  out.mass = species_of(ball).mass;
  return out;
}

void World::Impl::set_on_table(std::uint32_t ball, const TableBall& state, double t, bool record) {
  BallSlot& b = balls[ball];
  detail::TableSlot& slot = table_slots[ball];
  const detail::TableState before = slot.state;
  b.velocity = state.velocity;
  if (!movable(ball)) {
    // Nothing moves an immovable ball: it goes where it was sent, and friction does not act.
    slot = detail::TableSlot{};
    return;
  }
  // A state that would end within the clock's rounding of t ends now: otherwise its end, at t
  // itself, and the contacts it changes could follow one another at one instant without end.
  TableBall now = state;
  detail::StateMotion motion = detail::state_motion(now, cloth);
  // (Three ends at most: sliding, rolling, spinning.)
  for (int ends = 0;
       ends < 3 && motion.state != detail::TableState::stationary && t + motion.duration == t;
       ++ends) {
    now = detail::end_of_state(now, motion, cloth);
    motion = detail::state_motion(now, cloth);
  }
  b.velocity = now.velocity;
  slot.spin = now.spin;
  slot.twist = now.twist;
  slot.state = motion.state;
  if (slot.state == detail::TableState::stationary) {
    // At rest, exactly: no negative zero left over to tell two resting balls apart.
    b.velocity = {};
    slot.spin = {};
    slot.twist = 0.0;
  }
  slot.acceleration = motion.acceleration;
  slot.ends = t + motion.duration;
  if (slot.state != before && record && record_contacts) {
    motion_events.push_back({t, id_of(ball), before, slot.state});
  }
}

void World::Impl::advance_on_table(std::uint32_t ball, double t) {
  BallSlot& b = balls[ball];
  detail::TableSlot& slot = table_slots[ball];
  const double elapsed = t - b.local_time;
  const TableBall now = detail::advance_in_state(
      table_ball(ball), {slot.state, slot.acceleration, slot.ends - b.local_time}, cloth, elapsed);
  b.position = position_at(ball, t);
  b.velocity = velocity_at(ball, t);
  b.local_time = t;
  slot.spin = now.spin;
  slot.twist = now.twist;
}

void World::Impl::process_motion_change(const detail::Event& event) {
  const std::uint32_t i = event.owner;
  BallSlot& b = balls[i];
  const detail::TableSlot& slot = table_slots[i];
  // The state's end exactly (the rolling spin, the ball still, the twist gone), from the values
  // at the slot's local time; the centre where its parabola puts it at the event.
  const TableBall end = detail::end_of_state(
      table_ball(i), {slot.state, slot.acceleration, slot.ends - b.local_time}, cloth);
  b.position = position_at(i, event.time);
  b.local_time = event.time;
  set_on_table(i, end, event.time);
  ++b.version;
  predict(i);
}

bool World::Impl::resolve_pair_on_table(std::uint32_t i, std::uint32_t j, double t) {
  advance(i, t);
  advance(j, t);
  BallSlot& a = balls[i];
  BallSlot& b = balls[j];
  const Vec2 between = minimum_image(b.position - a.position);
  const Vec2 normal = between == Vec2{} ? normalized(a.velocity - b.velocity) : normalized(between);
  const double approach = dot(a.velocity - b.velocity, normal);
  TableBall first = table_ball(i);
  TableBall second = table_ball(j);
  bool resolved = false;
  const Vec2 relative_acceleration = acceleration_of(i) - acceleration_of(j);
  const double press = dot(relative_acceleration, normal);
  const double reach = radius_of(i) + radius_of(j);
  const bool pressed = press > 0.0 && detail::held_or_approaching(a.velocity, b.velocity,
                                                                  relative_acceleration, normal);
  if (pressed && approach < hold_speed(press, def.rest_height, 0.5 * reach)) {
    // Slow, and pressed together: held, rolling on side by side (docs/engine.md, "The table").
    const Vec2 before = a.velocity;
    detail::roll_together(first, second);
    if (approach > 0.0 && contact_wanted()) {
      const double impulse = movable(i)
                                 ? species_of(i).mass * dot(before - first.velocity, normal)
                                 : species_of(j).mass * dot(second.velocity - b.velocity, normal);
      record_ball_ball(i, j, t, between, normal, approach, std::max(impulse, 0.0));
    }
    resolved = approach > 0.0;
  } else if (detail::approaching(a.velocity, b.velocity, normal)) {
    const double impulse = detail::collide_on_table(
        first, second, normal, pair_restitution(i, j, t), def.table->ball_friction);
    if (def.collapse_time > 0.0) {
      last_contact_times[i] = t;
      last_contact_times[j] = t;
    }
    if (contact_wanted()) record_ball_ball(i, j, t, between, normal, approach, impulse);
    resolved = true;
    if (!movable(i) ? a.velocity != Vec2{} : (!movable(j) && b.velocity != Vec2{})) {
      mover_met = true;
    }
  }
  set_on_table(i, first, t);
  set_on_table(j, second, t);
  ++a.version;
  ++b.version;
  predict(i);
  predict(j);
  return resolved;
}

bool World::Impl::resolve_wall_on_table(std::uint32_t i, std::uint32_t wall, double t) {
  advance(i, t);
  BallSlot& a = balls[i];
  const auto [now, point, normal] = touch_wall(i, wall, t);
  const double approach = dot(a.velocity, normal);
  TableBall ball = table_ball(i);
  bool resolved = false;
  const Vec2 acceleration = acceleration_of(i);
  const double press = dot(acceleration, normal);
  const bool pressed =
      press > 0.0 && detail::held_or_approaching(a.velocity, {}, acceleration, normal);
  if (pressed && approach < hold_speed(press, def.rest_height, radius_of(i))) {
    detail::roll_along(ball, normal);
    if (approach > 0.0) {
      record_ball_wall(i, wall, t, point, normal, approach, approach - dot(ball.velocity, normal));
    }
    resolved = approach > 0.0;
  } else if (approach > 0.0) {
    detail::Cushion met = cushion;
    if (collided_recently(i, t)) met.restitution = 1.0;
    const double speed_change = detail::cushion_bounce(ball, normal, met);
    record_ball_wall(i, wall, t, point, normal, approach, speed_change);
    resolved = true;
  } else if (detail::inside_arc(walls[wall], a.position) && now.hit) {
    // Along the inside of an arc: the bowl's turn, as without a table (docs/engine.md).
    ball.velocity = detail::bounce_inside_arc(a.velocity, normal, restitution_of(i)).velocity;
  }
  set_on_table(i, ball, t);
  ++a.version;
  predict(i);
  return resolved;
}

}  // namespace carom
