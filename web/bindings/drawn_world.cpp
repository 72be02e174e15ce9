#include "drawn_world.hpp"

#include <algorithm>
#include <cstddef>
#include <sstream>
#include <utility>
#include <variant>

#include "carom/error.hpp"

namespace carom::web {

DrawnWorld::DrawnWorld(const WorldDef& def) : scene_world_{World(def), {}, {}, {}, {}, 0.0} {}

DrawnWorld::DrawnWorld(World world)
    : scene_world_{std::move(world), {}, {}, {}, {}, 0.0},
      colors_(scene_world_.world.ball_count()),
      held_velocity_(scene_world_.world.ball_count()) {
  scene_world_.balls = scene_world_.world.balls();
}

DrawnWorld::DrawnWorld(SceneWorld scene_world)
    : scene_world_(std::move(scene_world)),
      pockets_(scene_world_.scene.pockets),
      held_velocity_(scene_world_.balls.size()) {
  const Scene& scene = scene_world_.scene;
  colors_.reserve(scene.balls.size());
  for (const SceneBall& ball : scene.balls) colors_.push_back(ball.color.value_or(""));
}

DrawnWorld::DrawnWorld(const DrawnWorld& original, World world)
    : scene_world_{std::move(world),
                   original.scene_world_.scene,
                   original.scene_world_.balls,
                   original.scene_world_.pockets,
                   original.scene_world_.by_name,
                   original.scene_world_.start_time,
                   original.scene_world_.thermostat_work,
                   original.scene_world_.sensors,
                   original.scene_world_.sensor_events,
                   original.scene_world_.shots_taken,
                   original.scene_world_.motion_events},
      colors_(original.colors_),
      pockets_(original.pockets_),
      held_velocity_(original.held_velocity_),
      snapshot_(original.snapshot_),
      step_contacts_(original.step_contacts_),
      step_balls_(original.step_balls_),
      has_sensors_(original.has_sensors_),
      step_in_pieces_(original.step_in_pieces_) {}

DrawnWorld DrawnWorld::copy() const {
  std::stringstream saved;
  scene_world_.world.save(saved);
  return DrawnWorld(*this, World::load(saved));
}

int DrawnWorld::add_ball(Vec2 position, Vec2 velocity, double radius, double mass) {
  std::vector<BallId>& ids = scene_world_.balls;
  ids.push_back(scene_world_.world.add_ball({.position = position,
                                             .velocity = velocity,
                                             .radius = radius,
                                             .mass = mass,
                                             .user_data = ids.size()}));
  held_velocity_.emplace_back();
  colors_.emplace_back();
  return static_cast<int>(ids.size()) - 1;
}

int DrawnWorld::add_segment(const Segment& segment) {
  return static_cast<int>(scene_world_.world.add_segment(segment));
}

int DrawnWorld::add_sensor(const Segment& segment, bool removes) {
  const WallId wall = scene_world_.world.add_sensor(
      segment, removes ? SensorAction::remove_ball : SensorAction::report);
  has_sensors_ = true;
  return static_cast<int>(wall);
}

void DrawnWorld::add_arc(const Arc& arc) { static_cast<void>(scene_world_.world.add_arc(arc)); }

void DrawnWorld::remove_ball(int index) {
  const BallId ball = id(index);
  scene_world_.world.remove_ball(ball);
  scene_world_.balls[static_cast<std::size_t>(index)] = BallId{};
  held_velocity_[static_cast<std::size_t>(index)].reset();
}

std::vector<Segment> DrawnWorld::segments() const {
  std::vector<Segment> segments;
  const World& world = scene_world_.world;
  for (WallId id = first_own_wall(); id < world.wall_count(); ++id) {
    if (world.sensor(id)) continue;  // balls pass through sensors: not drawn as walls
    const auto shape = world.wall(id);
    if (const auto* segment = std::get_if<Segment>(&shape); segment != nullptr) {
      segments.push_back(*segment);
    }
  }
  return segments;
}

std::vector<Arc> DrawnWorld::arcs() const {
  std::vector<Arc> arcs;
  const World& world = scene_world_.world;
  for (WallId id = first_own_wall(); id < world.wall_count(); ++id) {
    if (world.sensor(id)) continue;  // balls pass through sensors: not drawn as walls
    const auto shape = world.wall(id);
    if (const auto* arc = std::get_if<Arc>(&shape); arc != nullptr) arcs.push_back(*arc);
  }
  return arcs;
}

WallId DrawnWorld::first_own_wall() const {
  // A box's four walls come first; the page draws the box from the world's def instead.
  return scene_world_.world.def().boundary == Boundary::box ? 4 : 0;
}

double DrawnWorld::step(double dt) {
  // step_scene runs a world with a thermostat piece by piece (each piece a World run of its
  // own); for any other it is one World::step, whose contacts the World keeps.
  step_in_pieces_ = scene_world_.scene.thermostat.has_value();
  step_contacts_.clear();
  if (step_in_pieces_ || has_sensors_ || !scene_world_.sensors.empty() ||
      !scene_world_.pockets.empty()) {
    step_balls_ = scene_world_.balls;
  } else {
    step_balls_.clear();
  }
  return step_scene(scene_world_, dt, step_in_pieces_ ? &step_contacts_ : nullptr);
}

std::span<const ContactEvent> DrawnWorld::step_contacts() const noexcept {
  if (step_in_pieces_) return step_contacts_;
  return scene_world_.world.contacts();
}

void DrawnWorld::scale_speeds(double factor) {
  if (!(factor > 0.0) || factor == kImmovable) {
    throw InvalidArgument("DrawnWorld::scale_speeds", "factor", std::to_string(factor),
                          "must be a finite number > 0");
  }
  World& world = scene_world_.world;
  const std::vector<BallId>& ids = scene_world_.balls;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (held_velocity_[i]) {
      *held_velocity_[i] *= factor;
    } else if (present(ids[i]) && world.mass(ids[i]) != kImmovable) {
      world.set_velocity(ids[i], world.velocity(ids[i]) * factor);
    }
  }
}

void DrawnWorld::set_velocity(int index, Vec2 velocity) {
  const BallId ball = id(index);
  auto& kept = held_velocity_[static_cast<std::size_t>(index)];
  if (kept) {
    kept = velocity;  // a held ball stands still until released
  } else {
    scene_world_.world.set_velocity(ball, velocity);
  }
}

void DrawnWorld::set_gravity(Vec2 gravity) { scene_world_.world.set_gravity(gravity); }

int DrawnWorld::ball_at(Vec2 point) const {
  const World& world = scene_world_.world;
  const std::vector<BallId>& ids = scene_world_.balls;
  for (std::size_t i = ids.size(); i-- > 0;) {
    if (!present(ids[i])) continue;
    const double r = world.radius(ids[i]);
    if (length_squared(world.position(ids[i]) - point) <= r * r) return static_cast<int>(i);
  }
  return -1;
}

void DrawnWorld::hold(int index) {
  const BallId ball = id(index);
  auto& kept = held_velocity_[static_cast<std::size_t>(index)];
  if (!kept) kept = scene_world_.world.velocity(ball);
  scene_world_.world.set_velocity(ball, {});
}

Vec2 DrawnWorld::drag_to(int index, Vec2 point) {
  const BallId ball = id(index);
  // Another ball may have knocked the held one since the last move; it stays held.
  scene_world_.world.set_velocity(ball, {});
  return scene_world_.world.set_position(ball, point, Placement::nearest_free);
}

void DrawnWorld::release(int index) {
  const BallId ball = id(index);
  auto& kept = held_velocity_[static_cast<std::size_t>(index)];
  if (kept) scene_world_.world.set_velocity(ball, *kept);
  kept.reset();
}

std::span<const float> DrawnWorld::snapshot() {
  const World& world = scene_world_.world;
  const std::vector<BallId>& ids = scene_world_.balls;
  snapshot_.assign(ids.size() * 4, 0.0F);
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (!present(ids[i])) continue;
    const Vec2 p = world.position(ids[i]);
    snapshot_[4 * i] = static_cast<float>(p.x);
    snapshot_[4 * i + 1] = static_cast<float>(p.y);
    snapshot_[4 * i + 2] = static_cast<float>(world.radius(ids[i]));
    snapshot_[4 * i + 3] = static_cast<float>(length(world.velocity(ids[i])));
  }
  return snapshot_;
}

int DrawnWorld::ball_count() const {
  const std::vector<BallId>& ids = scene_world_.balls;
  return static_cast<int>(
      std::count_if(ids.begin(), ids.end(), [this](BallId ball) { return present(ball); }));
}

Vec2 DrawnWorld::position(int index) const { return scene_world_.world.position(id(index)); }

Vec2 DrawnWorld::velocity(int index) const { return scene_world_.world.velocity(id(index)); }

int DrawnWorld::last_step_contacts() const {
  return static_cast<int>(scene_world_.world.contacts().size());
}

int DrawnWorld::index_of(BallId ball) const {
  if (ball.is_null()) return -1;
  if (!present(ball)) {
    const auto taken = std::find(step_balls_.begin(), step_balls_.end(), ball);
    return taken == step_balls_.end() ? -1 : static_cast<int>(taken - step_balls_.begin());
  }
  const std::vector<BallId>& ids = scene_world_.balls;
  // Balls added here and a scene's balls carry their index as user data; a world built elsewhere
  // (a packing) may not, so the list is searched when the hint misses.
  const std::uint64_t hint = scene_world_.world.user_data(ball);
  if (hint < ids.size() && ids[static_cast<std::size_t>(hint)] == ball) {
    return static_cast<int>(hint);
  }
  const auto found = std::find(ids.begin(), ids.end(), ball);
  return found == ids.end() ? -1 : static_cast<int>(found - ids.begin());
}

int DrawnWorld::pocket_of(WallId wall) const {
  const std::vector<WallId>& pockets = scene_world_.pockets;
  const auto found = std::find(pockets.begin(), pockets.end(), wall);
  return found == pockets.end() ? -1 : static_cast<int>(found - pockets.begin());
}

bool DrawnWorld::present(BallId ball) const {
  return !ball.is_null() && scene_world_.world.contains(ball);
}

BallId DrawnWorld::id(int index) const {
  const std::vector<BallId>& ids = scene_world_.balls;
  if (index < 0 || static_cast<std::size_t>(index) >= ids.size()) {
    throw InvalidArgument("DrawnWorld", "index", std::to_string(index),
                          "must name a ball: 0 <= index < " + std::to_string(ids.size()));
  }
  const BallId ball = ids[static_cast<std::size_t>(index)];
  if (!present(ball)) {
    throw InvalidArgument("DrawnWorld", "index", std::to_string(index),
                          "names a ball no longer in the world (a pocket or remove_ball took it)");
  }
  return ball;
}

}  // namespace carom::web
