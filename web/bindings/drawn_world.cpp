#include "drawn_world.hpp"

#include <cstddef>

#include "carom/error.hpp"

namespace carom::web {

DrawnWorld::DrawnWorld(const WorldDef& def) : def_(def), world_(def) {}

int DrawnWorld::add_ball(Vec2 position, Vec2 velocity, double radius, double mass) {
  ids_.push_back(world_.add_ball(
      {.position = position, .velocity = velocity, .radius = radius, .mass = mass}));
  held_velocity_.emplace_back();
  return static_cast<int>(ids_.size()) - 1;
}

void DrawnWorld::add_segment(const Segment& segment) {
  world_.add_segment(segment);
  segments_.push_back(segment);
}

void DrawnWorld::add_arc(const Arc& arc) {
  world_.add_arc(arc);
  arcs_.push_back(arc);
}

double DrawnWorld::step(double dt) { return world_.step(dt); }

void DrawnWorld::scale_speeds(double factor) {
  if (!(factor > 0.0) || factor == kImmovable) {
    throw InvalidArgument("DrawnWorld::scale_speeds", "factor", std::to_string(factor),
                          "must be a finite number > 0");
  }
  for (std::size_t i = 0; i < ids_.size(); ++i) {
    if (held_velocity_[i]) {
      *held_velocity_[i] *= factor;
    } else {
      world_.set_velocity(ids_[i], world_.velocity(ids_[i]) * factor);
    }
  }
}

int DrawnWorld::ball_at(Vec2 point) const {
  for (std::size_t i = ids_.size(); i-- > 0;) {
    const double r = world_.radius(ids_[i]);
    if (length_squared(world_.position(ids_[i]) - point) <= r * r) return static_cast<int>(i);
  }
  return -1;
}

void DrawnWorld::hold(int index) {
  const BallId ball = id(index);
  auto& kept = held_velocity_[static_cast<std::size_t>(index)];
  if (!kept) kept = world_.velocity(ball);
  world_.set_velocity(ball, {});
}

Vec2 DrawnWorld::drag_to(int index, Vec2 point) {
  const BallId ball = id(index);
  // Another ball may have knocked the held one since the last move; it stays held.
  world_.set_velocity(ball, {});
  return world_.set_position(ball, point, Placement::nearest_free);
}

void DrawnWorld::release(int index) {
  const BallId ball = id(index);
  auto& kept = held_velocity_[static_cast<std::size_t>(index)];
  if (kept) world_.set_velocity(ball, *kept);
  kept.reset();
}

std::span<const float> DrawnWorld::snapshot() {
  snapshot_.resize(ids_.size() * 4);
  for (std::size_t i = 0; i < ids_.size(); ++i) {
    const Vec2 p = world_.position(ids_[i]);
    snapshot_[4 * i] = static_cast<float>(p.x);
    snapshot_[4 * i + 1] = static_cast<float>(p.y);
    snapshot_[4 * i + 2] = static_cast<float>(world_.radius(ids_[i]));
    snapshot_[4 * i + 3] = static_cast<float>(length(world_.velocity(ids_[i])));
  }
  return snapshot_;
}

int DrawnWorld::ball_count() const { return static_cast<int>(ids_.size()); }

Vec2 DrawnWorld::position(int index) const { return world_.position(id(index)); }

int DrawnWorld::last_step_contacts() const { return static_cast<int>(world_.contacts().size()); }

BallId DrawnWorld::id(int index) const {
  if (index < 0 || static_cast<std::size_t>(index) >= ids_.size()) {
    throw InvalidArgument("DrawnWorld", "index", std::to_string(index),
                          "must name a ball: 0 <= index < " + std::to_string(ids_.size()));
  }
  return ids_[static_cast<std::size_t>(index)];
}

}  // namespace carom::web
