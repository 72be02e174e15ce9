// Sensors in the event loop: each ball's next enter or exit at the sensors listed in its cell is
// one more candidate for its pending event (an event of kind ball_wall marked kSensorEvent), and
// processing it records the change and predicts the ball again, as a cell crossing does. The
// state of each pair is recorded (sensor_inside), so enters and exits alternate whatever the
// rounding (sensor_overlap.hpp). Design: docs/engine.md, "Sensors".
#include <algorithm>
#include <cmath>

#include "world_impl.hpp"

namespace carom {

void World::Impl::consider_sensor(detail::Event& best, std::uint32_t ball, std::uint32_t wall,
                                  const Ball& shape, const Motion& motion, double horizon) const {
  const bool inside = sensor_inside.contains(sensor_key(ball, wall));
  // A ball its filter lets through records nothing there (but leaves where it was inside).
  if (!inside && !meets_wall(ball, wall)) return;
  // Hysteresis: a ball inside leaves when it is clear of the sensor by a rounding of its
  // coordinates (2^-40 of them), and one outside enters when it is that deep. Brought to the
  // time of its enter or exit, a ball sits within a rounding of the sensor's edge, on either
  // side; without the margin it could be found on the far side at once and change back, an ulp
  // of time later, for ever.
  const double coordinates = std::max(std::abs(shape.center.x), std::abs(shape.center.y));
  const double margin = std::min(0x1p-40 * (coordinates + shape.radius), 0.5 * shape.radius);
  const Ball padded{shape.center, inside ? shape.radius + margin : shape.radius - margin};
  const detail::SensorChange change = detail::next_sensor_change(
      padded, motion, detail::sensor_shape(walls[wall]), inside, horizon, time);
  if (!change.found) return;
  detail::Event candidate;
  candidate.time = time + change.t;
  candidate.kind = detail::EventKind::ball_wall;
  candidate.owner = ball;
  candidate.partner = wall;
  candidate.partner_version = detail::kSensorEvent;
  if (detail::earlier(candidate, best, handle_of.data())) best = candidate;
}

void World::Impl::consider_inside_sensors(detail::Event& best, std::uint32_t ball,
                                          const Ball& shape, const Motion& motion,
                                          double horizon) const {
  const std::uint64_t handle = handle_of[ball];
  for (auto key = sensor_inside.lower_bound(handle << 32);
       key != sensor_inside.end() && (*key >> 32) == handle; ++key) {
    const auto wall = static_cast<std::uint32_t>(*key & 0xffffffffU);
    consider_sensor(best, ball, wall, shape, motion, std::min(horizon, best.time - time));
  }
}

bool World::Impl::process_sensor(std::uint32_t ball, std::uint32_t wall, double t) {
  advance(ball, t);
  const std::uint64_t key = sensor_key(ball, wall);
  const bool was_inside = sensor_inside.erase(key) > 0;
  SensorEvent event;
  event.time = t;
  event.kind = was_inside ? SensorEventKind::exit : SensorEventKind::enter;
  event.ball = id_of(ball);
  event.sensor = wall;
  event.contacts_before = contacts.size();
  if (!was_inside && walls[wall].sensor == detail::SensorRole::remove_ball) {
    event.removed = true;
    sensor_events.push_back(event);
    remove_slot(ball);
    queue.set(ball, detail::Event{});  // nothing will happen to it
    return false;
  }
  if (!was_inside) sensor_inside.insert(key);
  sensor_events.push_back(event);
  predict(ball);
  return false;
}

void World::Impl::forget_sensor_pairs(std::uint32_t handle) {
  const auto first = sensor_inside.lower_bound(std::uint64_t{handle} << 32);
  const auto last = sensor_inside.lower_bound((std::uint64_t{handle} + 1) << 32);
  sensor_inside.erase(first, last);
}

void World::Impl::remove_slot(std::uint32_t slot) {
  detail::BallSlot& b = balls[slot];
  if (gravity_on) {
    // Whatever rested on it falls.
    advance(slot, time);
    disturb(slot);
  }
  if (!sensor_inside.empty()) forget_sensor_pairs(handle_of[slot]);
  grid.erase(slot);
  species.release(b.species);
  b.species = detail::kNoSpecies;
  ++b.version;
  release(slot);
}

}  // namespace carom
