// carom::World's public surface: handles, validation, queries. The engine: world_run.cpp and the
// parts it calls (docs/engine.md).
#include "carom/world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "carom/error.hpp"
#include "carom/sweep.hpp"
#include "core/validate.hpp"
#include "world_impl.hpp"

namespace carom {

using detail::BallSlot;

namespace {

std::string number(double value) { return carom::number_text(value); }

[[noreturn]] void refuse(const char* function, const char* argument, const std::string& value,
                         const std::string& requirement) {
  throw InvalidArgument(function, argument, value, requirement);
}

[[noreturn]] void refuse_too_many(const char* function, const char* argument,
                                  const std::string& value) {
  refuse(function, argument, value,
         "a world holds at most " + std::to_string(detail::EventQueue::kMaxBalls) + " balls");
}

// A drag whose coordinates round coarser than this fraction of the ball's radius is swept again
// from nearer its end (set_position).
constexpr double kFineDrag = 0x1p-30;
// The most sweeps of one drag (each divides the distance left by about 10¹⁴: a few do for any
// drag in the double range).
constexpr int kMaxDragStages = 64;

// Events name a wall in 30 bits (event_queue.hpp).
void require_room_for_a_wall(const char* function, const char* argument, std::size_t walls) {
  if (walls >= detail::EventQueue::kMaxWalls) {
    refuse(function, argument, "-",
           "a world holds at most " + std::to_string(detail::EventQueue::kMaxWalls) + " walls");
  }
}

void validate_ball_def(const char* function, const BallDef& def) {
  detail::require_finite(function, "def.position", def.position);
  detail::require_finite(function, "def.velocity", def.velocity);
  detail::require_positive(function, "def.radius", def.radius);
  detail::require_mass(function, "def.mass", def.mass);
  if (def.restitution) detail::require_restitution(function, "def.restitution", *def.restitution);
  detail::require_finite(function, "def.spin.x", def.spin.x);
  detail::require_finite(function, "def.spin.y", def.spin.y);
  detail::require_finite(function, "def.spin.z", def.spin.z);
}

void validate_table(const char* function, const Table& table) {
  detail::require_finite(function, "def.table.g", table.g);
  detail::require_positive(function, "def.table.g", table.g);
  const std::pair<const char*, double> frictions[] = {
      {"def.table.sliding_friction", table.sliding_friction},
      {"def.table.rolling_friction", table.rolling_friction},
      {"def.table.spinning_friction", table.spinning_friction},
      {"def.table.ball_friction", table.ball_friction},
      {"def.table.cushion_friction", table.cushion_friction},
      {"def.table.contact_time", table.contact_time}};
  for (const auto& [name, value] : frictions) {
    detail::require_finite(function, name, value);
    detail::require_non_negative(function, name, value);
  }
  detail::require_that(table.cushion_height >= 0.5 && table.cushion_height < 1.0, function,
                       "def.table.cushion_height", table.cushion_height,
                       "must lie in [0.5, 1): a share of the ball's diameter, at or above its "
                       "equator and below its top");
  detail::require_restitution(function, "def.table.cushion_restitution", table.cushion_restitution);
}

}  // namespace

// ---- World::Impl helpers --------------------------------------------------------------------

std::uint32_t World::Impl::slot_of(const char* function, BallId id) const {
  if (id.is_null()) refuse(function, "id", "null", "must be a ball of this world");
  const std::optional<std::uint32_t> slot = find(id);
  if (!slot) {
    refuse(function, "id",
           "{" + std::to_string(id.index) + ", " + std::to_string(id.generation) + "}",
           "is stale: that ball was removed (or never belonged to this world)");
  }
  return *slot;
}

std::string World::Impl::overlap_at(Vec2 p, double r, std::uint32_t except,
                                    std::uint32_t filter) const {
  if (def.boundary == Boundary::box) {
    if (p.x - r < def.lower.x || p.x + r > def.upper.x || p.y - r < def.lower.y ||
        p.y + r > def.upper.y) {
      return "it reaches outside the box";
    }
  }
  // A ball passes through what its filter does not meet: no overlap to refuse there.
  const auto overlaps_wall = [&](std::uint32_t w) {
    return walls[w].solid() && (!filters.active() || filter_meets_wall(filter, w)) &&
           length_squared(detail::nearest_point(walls[w], p) - p) < r * r;
  };
  if (!grid_valid) {
    for (std::uint32_t w = 0; w < walls.size(); ++w) {
      if (overlaps_wall(w)) return "it overlaps wall " + std::to_string(w);
    }
    return {};
  }
  // The callers made the grid fit this ball (ensure_grid): a wall within r of p is listed in
  // p's cell, since walls are listed in every cell their box grown by a cell overlaps. Lowest id
  // first, as the full scan would report.
  const std::int32_t home = grid.cell_of(wrap_into_cell(p));
  for (const std::uint32_t w : grid.walls(home)) {
    if (overlaps_wall(w)) return "it overlaps wall " + std::to_string(w);
  }
  for (const std::uint32_t w : moving_walls) {
    if (overlaps_wall(w)) return "it overlaps wall " + std::to_string(w);
  }
  std::string found;
  grid.for_each_neighbour(home, [&](std::int32_t cell) {
    for (std::int32_t j = grid.first_ball(cell); j != detail::kNoBall && found.empty();
         j = grid.next_ball(static_cast<std::uint32_t>(j))) {
      const auto other = static_cast<std::uint32_t>(j);
      if (other == except) continue;
      if (filters.active() && !filters.meet(filter, infos[other].filter)) continue;
      const Vec2 gap = minimum_image(position_at(other, time) - p);
      const double reach = r + radius_of(other);
      if (length_squared(gap) < reach * reach) {
        found = "it overlaps ball " + std::to_string(other) + " by " + number(reach - length(gap));
      }
    }
  });
  return found;
}

// ---- World -----------------------------------------------------------------------------------

World::World(const WorldDef& def) : impl_(std::make_unique<Impl>()) {
  constexpr const char* kFunction = "World";
  detail::require_restitution(kFunction, "def.restitution", def.restitution);
  detail::require_non_negative(kFunction, "def.collapse_time", def.collapse_time);
  detail::require_non_negative(kFunction, "def.cell_size", def.cell_size);
  if (def.boundary != Boundary::open) {
    detail::require_finite(kFunction, "def.lower", def.lower);
    detail::require_finite(kFunction, "def.upper", def.upper);
    if (!(def.upper.x > def.lower.x && def.upper.y > def.lower.y)) {
      refuse(kFunction, "def.upper", detail::vector_text(def.upper),
             "must lie above and to the right of def.lower");
    }
  }
  detail::require_finite(kFunction, "def.gravity", def.gravity);
  detail::require_positive(kFunction, "def.rest_height", def.rest_height);
  detail::require_finite(kFunction, "def.growth_rate", def.growth_rate);
  detail::require_non_negative(kFunction, "def.growth_rate", def.growth_rate);
  if (def.growth_rate != 0.0 && def.gravity != Vec2{}) {
    refuse(kFunction, "def.growth_rate", carom::number_text(def.growth_rate),
           "must be 0 while def.gravity is set: balls grow or fall, not both");
  }
  if (def.table) {
    validate_table(kFunction, *def.table);
    if (def.gravity != Vec2{} || def.growth_rate != 0.0) {
      refuse(
          kFunction, "def.table", "set",
          "cannot go with def.gravity or def.growth_rate: a table's balls neither fall nor grow");
    }
  }
  impl_->def = def;
  // On a table a contact lasts Table::contact_time unless the world says otherwise.
  if (def.table && def.collapse_time == 0.0) impl_->def.collapse_time = def.table->contact_time;
  impl_->gravity_on = def.gravity != Vec2{};
  impl_->growth_on = def.growth_rate != 0.0;
  impl_->growth_relative = def.growth_rate;
  impl_->table_on = def.table.has_value();
  impl_->accelerated = impl_->gravity_on || impl_->table_on;
  impl_->general_motion = impl_->gravity_on || impl_->growth_on || impl_->table_on;
  if (impl_->table_on) impl_->use_table();
  impl_->periodic_cell = PeriodicCell(def.lower, def.upper);
  if (def.boundary == Boundary::box) {
    add_box(def.lower, def.upper);
    impl_->boundary_walls = 4;
  }
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

BallId World::add_ball(const BallDef& def) { return add_ball(def, CollisionFilter{}); }

BallId World::add_ball(const BallDef& def, const CollisionFilter& ball_filter) {
  constexpr const char* kFunction = "World::add_ball";
  validate_ball_def(kFunction, def);
  Impl& w = *impl_;
  if (!w.table_on && def.spin != Spin{}) {
    refuse(kFunction, "def.spin",
           "(" + number(def.spin.x) + ", " + number(def.spin.y) + ", " + number(def.spin.z) + ")",
           "must be zero in a world without a table (WorldDef::table)");
  }
  const Vec2 position = w.wrap_into_cell(def.position);
  if (w.def.boundary == Boundary::periodic) {
    // Three cells of at least a diameter per axis keep every neighbour cell distinct.
    const Vec2 size = w.def.upper - w.def.lower;
    const double widest = std::min(size.x, size.y) / 3.0;
    if (!(2.0 * def.radius * (1.0 + detail::kCellMargin) <= widest)) {
      refuse(kFunction, "def.radius", number(def.radius),
             "a periodic cell must be more than 3 diameters wide on each axis");
    }
  }
  // (Under growth the species take the radii of now, the new ball's among them.)
  w.settle_growth();
  w.ensure_grid(position, def.radius);
  const std::uint32_t filter = w.filters.number_of(ball_filter);
  const std::string overlap =
      w.overlap_at(position, def.radius, std::numeric_limits<std::uint32_t>::max(), filter);
  if (!overlap.empty()) {
    refuse(kFunction, "def.position", detail::vector_text(def.position),
           "the ball cannot go there: " + overlap);
  }

  if (w.free_handles.empty() && w.balls.size() >= detail::EventQueue::kMaxBalls) {
    refuse_too_many(kFunction, "def", "-");
  }
  bool grew = false;
  const std::uint32_t slot = w.acquire(grew);
  if (grew && w.def.collapse_time > 0.0) w.last_contact_times.emplace_back();
  BallSlot& b = w.balls[slot];
  b.position = position;
  b.velocity = def.velocity;
  b.local_time = w.time;
  const double restitution = def.restitution.value_or(w.def.restitution);
  b.species = w.species.acquire(def.radius, def.mass, restitution);
  if (restitution != w.def.restitution) w.mixed_restitution = true;
  detail::BallInfo& info = w.infos[slot];
  if (w.def.collapse_time > 0.0) {
    w.last_contact_times[slot] = -std::numeric_limits<double>::infinity();
  }
  info.user_data = def.user_data;
  info.filter = filter;
  if (w.gravity_on) {
    w.carriages.resize(w.balls.size());
    w.carriages[slot] = w.free_carriage();
  }
  if (w.table_on) {
    w.table_slots.resize(w.balls.size());
    w.table_slots[slot] = detail::TableSlot{};
    detail::TableBall state = w.table_ball(slot);
    state.spin = {def.spin.x, def.spin.y};
    state.twist = def.spin.z;
    w.set_on_table(slot, state, w.time, false);
  }
  ++b.version;
  w.largest_radius = std::max(w.largest_radius, def.radius);
  w.grid.insert(slot, w.grid.cell_of(position));
  if (w.growth_on) w.plan_growth_regrid();
  w.repredict_changed(slot);
  return w.id_of(slot);
}

void World::remove_ball(BallId id) {
  Impl& w = *impl_;
  const std::uint32_t slot = w.slot_of("World::remove_ball", id);
  w.remove_slot(slot);
  w.repredict_changed(slot);
}

void World::reserve(std::size_t count) {
  if (count > detail::EventQueue::kMaxBalls) {
    refuse_too_many("World::reserve", "count", std::to_string(count));
  }
  Impl& w = *impl_;
  w.reserve(count);
  if (w.def.collapse_time > 0.0) w.last_contact_times.reserve(count);
}

bool World::contains(BallId id) const noexcept { return impl_->find(id).has_value(); }

std::vector<BallId> World::balls() const {
  std::vector<BallId> ids;
  ids.reserve(impl_->live_count);
  impl_->for_each_live([&](std::uint32_t slot) { ids.push_back(impl_->id_of(slot)); });
  return ids;
}

WallId World::add_segment(const Segment& segment) {
  constexpr const char* kFunction = "World::add_segment";
  detail::require_finite(kFunction, "segment.a", segment.a);
  detail::require_finite(kFunction, "segment.b", segment.b);
  return impl_->add_wall(kFunction, "segment", detail::make_segment_wall(segment));
}

WallId World::add_polyline(std::span<const Vec2> points, bool closed) {
  if (points.size() < 2) {
    refuse("World::add_polyline", "points.size()", std::to_string(points.size()),
           "a polyline needs at least 2 points");
  }
  const auto first = static_cast<WallId>(impl_->walls.size());
  for (std::size_t i = 0; i + 1 < points.size(); ++i) add_segment({points[i], points[i + 1]});
  if (closed && points.size() > 2) add_segment({points.back(), points.front()});
  return first;
}

WallId World::add_arc(const Arc& arc) {
  constexpr const char* kFunction = "World::add_arc";
  return impl_->add_wall(kFunction, "arc", detail::make_arc_wall(kFunction, arc));
}

WallId World::add_box(Vec2 lower, Vec2 upper) {
  const Vec2 corners[] = {lower, {upper.x, lower.y}, upper, {lower.x, upper.y}};
  return add_polyline(corners, true);
}

WallId World::add_sensor(const Segment& segment, SensorAction action) {
  constexpr const char* kFunction = "World::add_sensor";
  detail::require_finite(kFunction, "segment.a", segment.a);
  detail::require_finite(kFunction, "segment.b", segment.b);
  detail::Wall wall = detail::make_segment_wall(segment);
  wall.sensor = detail::sensor_role(action);
  return impl_->add_wall(kFunction, "segment", wall);
}

WallId World::add_sensor(const Arc& arc, SensorAction action) {
  constexpr const char* kFunction = "World::add_sensor";
  detail::Wall wall = detail::make_arc_wall(kFunction, arc);
  wall.sensor = detail::sensor_role(action);
  return impl_->add_wall(kFunction, "arc", wall);
}

WallId World::add_sensor(const Ball& disc, SensorAction action) {
  constexpr const char* kFunction = "World::add_sensor";
  detail::require_finite(kFunction, "disc.center", disc.center);
  detail::require_positive(kFunction, "disc.radius", disc.radius);
  detail::require_finite(kFunction, "disc.radius", disc.radius);
  // The whole disc within the double range, as an arc's circle must be.
  const double reach = std::max(std::abs(disc.center.x), std::abs(disc.center.y)) + disc.radius;
  if (!std::isfinite(reach)) {
    refuse(kFunction, "disc", detail::vector_text(disc.center),
           "the disc must lie within the double range");
  }
  return impl_->add_wall(kFunction, "disc",
                         detail::make_disc_sensor(disc, detail::sensor_role(action)));
}

WallId World::Impl::add_wall(const char* function, const char* argument, const detail::Wall& wall) {
  if (def.boundary == Boundary::periodic) {
    refuse(function, argument, "-", "walls in a periodic world are not supported yet");
  }
  require_room_for_a_wall(function, argument, walls.size());
  walls.push_back(wall);
  wall_added();
  return static_cast<WallId>(walls.size() - 1);
}

std::size_t World::wall_count() const noexcept { return impl_->walls.size(); }

namespace {

const detail::Wall& wall_named(const char* function, const std::vector<detail::Wall>& walls,
                               WallId id) {
  if (id >= walls.size()) {
    refuse(function, "id", std::to_string(id),
           "must be below wall_count() = " + std::to_string(walls.size()));
  }
  return walls[id];
}

}  // namespace

std::variant<Segment, Arc, Ball> World::wall(WallId id) const {
  const detail::Wall& wall = wall_named("World::wall", impl_->walls, id);
  if (wall.is_disc) return wall.disc;
  if (wall.is_arc) return wall.arc;
  return wall.segment;
}

std::optional<SensorAction> World::sensor(WallId id) const {
  switch (wall_named("World::sensor", impl_->walls, id).sensor) {
    case detail::SensorRole::none:
      return std::nullopt;
    case detail::SensorRole::report:
      return SensorAction::report;
    case detail::SensorRole::remove_ball:
      return SensorAction::remove_ball;
  }
  return std::nullopt;
}

std::vector<BallId> World::balls_in_sensor(WallId id) const {
  (void)wall_named("World::balls_in_sensor", impl_->walls, id);
  std::vector<BallId> inside;
  for (const std::uint64_t key : impl_->sensor_inside) {
    if (static_cast<WallId>(key & 0xffffffffU) != id) continue;
    inside.push_back(impl_->id_of(impl_->slot_of_handle[static_cast<std::uint32_t>(key >> 32)]));
  }
  return inside;
}

std::span<const SensorEvent> World::sensor_events() const noexcept { return impl_->sensor_events; }

std::span<const MotionEvent> World::motion_events() const noexcept { return impl_->motion_events; }

bool World::at_rest() const noexcept {
  const Impl& w = *impl_;
  for (std::uint32_t i = 0; i < w.balls.size(); ++i) {
    if (!w.balls[i].alive() || !w.movable(i)) continue;
    if (w.velocity_at(i, w.time) != Vec2{}) return false;
    if (w.gravity_on && w.carriages[i].state != detail::Carried::resting) return false;
    if (w.table_on && w.table_slots[i].state != detail::TableState::stationary) return false;
  }
  return true;
}

Spin World::spin(BallId id) const {
  const Impl& w = *impl_;
  constexpr const char* kFunction = "World::spin";
  w.require_table(kFunction);
  const std::uint32_t slot = w.slot_of(kFunction, id);
  const detail::TableSlot& table = w.table_slots[slot];
  const detail::BallSlot& b = w.balls[slot];
  const detail::TableBall now = detail::advance_in_state(
      w.table_ball(slot), {table.state, table.acceleration, table.ends - b.local_time}, w.cloth,
      w.time - b.local_time);
  return {now.spin.x, now.spin.y, now.twist};
}

MotionState World::motion_state(BallId id) const {
  const Impl& w = *impl_;
  constexpr const char* kFunction = "World::motion_state";
  w.require_table(kFunction);
  return w.table_slots[w.slot_of(kFunction, id)].state;
}

void World::set_spin(BallId id, Spin spin) {
  Impl& w = *impl_;
  constexpr const char* kFunction = "World::set_spin";
  w.require_table(kFunction);
  const std::uint32_t slot = w.slot_of(kFunction, id);
  detail::require_finite(kFunction, "spin.x", spin.x);
  detail::require_finite(kFunction, "spin.y", spin.y);
  detail::require_finite(kFunction, "spin.z", spin.z);
  if (!w.movable(slot)) {
    refuse(kFunction, "id", std::to_string(id.index), "is an immovable ball, which has no spin");
  }
  w.advance(slot, w.time);
  detail::TableBall state = w.table_ball(slot);
  state.spin = {spin.x, spin.y};
  state.twist = spin.z;
  w.set_on_table(slot, state, w.time, false);
  ++w.balls[slot].version;
  w.repredict_changed(slot);
}

void World::strike(BallId id, const CueStrike& cue) {
  Impl& w = *impl_;
  constexpr const char* kFunction = "World::strike";
  w.require_table(kFunction);
  const std::uint32_t slot = w.slot_of(kFunction, id);
  if (!w.movable(slot)) {
    refuse(kFunction, "id", std::to_string(id.index), "is an immovable ball: a cue cannot move it");
  }
  const std::pair<const char*, double> values[] = {
      {"cue.speed", cue.speed}, {"cue.direction", cue.direction}, {"cue.elevation", cue.elevation},
      {"cue.side", cue.side},   {"cue.height", cue.height},       {"cue.cue_mass", cue.cue_mass}};
  for (const auto& [name, value] : values) detail::require_finite(kFunction, name, value);
  detail::require_non_negative(kFunction, "cue.speed", cue.speed);
  detail::require_positive(kFunction, "cue.cue_mass", cue.cue_mass);
  detail::require_restitution(kFunction, "cue.restitution", cue.restitution);
  detail::require_that(cue.elevation >= 0.0 && cue.elevation < 0.5 * std::numbers::pi, kFunction,
                       "cue.elevation", cue.elevation, "must lie in [0, π/2) radians");
  const double radius = w.radius_of(slot);
  detail::require_that(cue.side * cue.side + cue.height * cue.height < radius * radius, kFunction,
                       "cue.side", cue.side,
                       "must meet the ball: side² + height² must stay below its radius²");
  w.advance(slot, w.time);
  const detail::TableBall hit = detail::strike(cue, w.species_of(slot).mass, radius);
  detail::TableBall state = w.table_ball(slot);
  state.velocity += hit.velocity;
  state.spin += hit.spin;
  state.twist += hit.twist;
  w.set_on_table(slot, state, w.time, false);
  ++w.balls[slot].version;
  w.repredict_changed(slot);
}

void World::set_wall_motion(WallId wall, const WallMotion& motion) {
  constexpr const char* kFunction = "World::set_wall_motion";
  Impl& w = *impl_;
  detail::Wall& target = w.changeable_wall(kFunction, wall);
  if (target.sensor != detail::SensorRole::none) {
    refuse(kFunction, "wall", std::to_string(wall), "is a sensor: sensors stand still");
  }
  if (w.table_on && motion.moves()) {
    refuse(kFunction, "wall", std::to_string(wall),
           "is a table's cushion: walls on a table (WorldDef::table) stand still");
  }
  detail::require_finite(kFunction, "motion.velocity", motion.velocity);
  detail::require_finite(kFunction, "motion.angular_velocity", motion.angular_velocity);
  detail::require_finite(kFunction, "motion.pivot", motion.pivot);
  detail::require_that(motion.duration >= 0.0, kFunction, "motion.duration", motion.duration,
                       "must be a number >= 0 (infinite: for ever)");
  w.free_resting_on(wall);
  detail::set_path(target, w.time, {motion.velocity, motion.angular_velocity, motion.pivot},
                   motion.duration);
  const auto at = std::lower_bound(w.moving_walls.begin(), w.moving_walls.end(), wall);
  if (at == w.moving_walls.end() || *at != wall) w.moving_walls.insert(at, wall);
  if (w.grid_valid) w.list_walls();
  w.events_valid = false;
}

WallMotion World::wall_motion(WallId wall) const {
  const Impl& w = *impl_;
  const detail::Wall& named = wall_named("World::wall_motion", w.walls, wall);
  if (!named.moves_at(w.time)) return WallMotion{{}, 0.0, {}, 0.0};
  const detail::RigidMotion rigid = detail::motion_from(named, w.time);
  return {rigid.velocity, rigid.angular_velocity, rigid.pivot, named.path.until - w.time};
}

void World::remove_wall(WallId wall) {
  constexpr const char* kFunction = "World::remove_wall";
  Impl& w = *impl_;
  detail::Wall& target = w.changeable_wall(kFunction, wall);
  w.free_resting_on(wall);
  target.removed = true;
  std::erase_if(w.sensor_inside,
                [&](std::uint64_t key) { return static_cast<WallId>(key & 0xffffffffU) == wall; });
  if (w.grid_valid) w.list_walls();
  w.events_valid = false;
}

bool World::wall_removed(WallId wall) const {
  return wall_named("World::wall_removed", impl_->walls, wall).removed;
}

const WorldDef& World::def() const noexcept { return impl_->def; }

double World::step(double dt) {
  detail::require_non_negative("World::step", "dt", dt);
  const double start = impl_->time;
  impl_->run("World::step", Impl::RunGoal::time, start + dt,
             std::numeric_limits<std::uint64_t>::max());
  return impl_->stop_reason == StopReason::none ? dt : impl_->time - start;
}

double World::run_until(double time) {
  detail::require_finite("World::run_until", "time", time);
  if (time < impl_->time) {
    refuse("World::run_until", "time", number(time),
           "must not be before the world's time " + number(impl_->time));
  }
  const double start = impl_->time;
  impl_->run("World::run_until", Impl::RunGoal::time, time,
             std::numeric_limits<std::uint64_t>::max());
  return impl_->time - start;
}

std::uint64_t World::run_collisions(std::uint64_t count) {
  if (count == 0) {
    impl_->contacts.clear();
    impl_->sensor_events.clear();
    impl_->motion_events.clear();
    impl_->stop_reason = StopReason::none;
    return 0;
  }
  return impl_->run("World::run_collisions", Impl::RunGoal::contacts,
                    std::numeric_limits<double>::infinity(), count);
}

std::uint64_t World::run_collisions(std::uint64_t count, double time_limit) {
  constexpr const char* kFunction = "World::run_collisions";
  if (std::isnan(time_limit)) refuse(kFunction, "time_limit", "nan", "must be a number");
  if (time_limit < impl_->time) {
    refuse(kFunction, "time_limit", number(time_limit),
           "must not be before the world's time " + number(impl_->time));
  }
  if (count == 0) {
    impl_->contacts.clear();
    impl_->sensor_events.clear();
    impl_->motion_events.clear();
    impl_->stop_reason = StopReason::none;
    return 0;
  }
  return impl_->run(kFunction, Impl::RunGoal::contacts, time_limit, count);
}

void World::set_stop_condition(std::function<bool(const ContactEvent&)> condition) {
  impl_->stop_condition = std::move(condition);
}

bool World::stopped_early() const noexcept {
  return impl_->stop_reason == StopReason::stop_condition;
}

StopReason World::stop_reason() const noexcept { return impl_->stop_reason; }

void World::request_stop() noexcept {
  impl_->stop_requested.store(true, std::memory_order_relaxed);
}

void World::set_progress_callback(std::function<bool(const RunStatus&)> callback) {
  impl_->progress_callback = std::move(callback);
}

std::span<const ContactEvent> World::contacts() const noexcept { return impl_->contacts; }

void World::set_contact_recording(bool enabled) noexcept {
  impl_->record_contacts = enabled;
  if (!enabled) {
    impl_->contacts.clear();
    impl_->contacts.shrink_to_fit();
  }
}

bool World::contact_recording() const noexcept { return impl_->record_contacts; }

double World::time() const noexcept { return impl_->time; }

Vec2 World::position(BallId id) const {
  const std::uint32_t slot = impl_->slot_of("World::position", id);
  return impl_->position_at(slot, impl_->time);
}

Vec2 World::velocity(BallId id) const {
  const std::uint32_t slot = impl_->slot_of("World::velocity", id);
  return impl_->velocity_at(slot, impl_->time);
}

double World::radius(BallId id) const {
  return impl_->radius_at(impl_->slot_of("World::radius", id), impl_->time);
}

double World::mass(BallId id) const {
  return impl_->species_of(impl_->slot_of("World::mass", id)).mass;
}

std::uint64_t World::user_data(BallId id) const {
  return impl_->infos[impl_->slot_of("World::user_data", id)].user_data;
}

std::size_t World::ball_count() const noexcept { return impl_->live_count; }

double World::kinetic_energy() const noexcept {
  // Summed in handle order, so that the rounding does not depend on where balls are stored.
  double energy = 0.0;
  for (const std::uint32_t i : impl_->slot_of_handle) {
    const BallSlot& b = impl_->balls[i];
    if (!b.alive() || !impl_->movable(i)) continue;
    energy += 0.5 * impl_->species_of(i).mass * length_squared(impl_->velocity_at(i, impl_->time));
  }
  return energy;
}

double World::potential_energy() const noexcept {
  if (!impl_->gravity_on) return 0.0;
  double energy = 0.0;
  for (const std::uint32_t i : impl_->slot_of_handle) {  // in handle order, as kinetic_energy
    if (!impl_->balls[i].alive() || !impl_->movable(i)) continue;
    energy -=
        impl_->species_of(i).mass * dot(impl_->def.gravity, impl_->position_at(i, impl_->time));
  }
  return energy;
}

Vec2 World::momentum() const noexcept {
  Vec2 total;
  for (const std::uint32_t i : impl_->slot_of_handle) {  // in handle order, as kinetic_energy
    const BallSlot& b = impl_->balls[i];
    if (b.alive() && impl_->movable(i)) {
      total += impl_->velocity_at(i, impl_->time) * impl_->species_of(i).mass;
    }
  }
  return total;
}

std::uint64_t World::collision_count() const noexcept { return impl_->collisions; }

void World::set_gravity(Vec2 gravity) {
  detail::require_finite("World::set_gravity", "gravity", gravity);
  Impl& w = *impl_;
  if (gravity == w.def.gravity) return;
  if (w.growth_on && gravity != Vec2{}) {
    refuse("World::set_gravity", "gravity", detail::vector_text(gravity),
           "must be zero while the balls grow (WorldDef::growth_rate): they grow or fall, not "
           "both");
  }
  if (w.table_on && gravity != Vec2{}) {
    refuse("World::set_gravity", "gravity", detail::vector_text(gravity),
           "must be zero on a table (WorldDef::table): its balls roll on the cloth");
  }
  // Every ball is brought to now under the old law, and predicted again under the new one.
  w.synchronize(w.time);
  w.def.gravity = gravity;
  w.gravity_on = gravity != Vec2{};
  w.accelerated = w.gravity_on || w.table_on;
  w.general_motion = w.gravity_on || w.growth_on || w.table_on;
  w.reset_carriages();  // resting and sliding balls fall, and settle again under the new gravity
  w.events_valid = false;
}

void World::set_growth_rate(double rate) {
  constexpr const char* kFunction = "World::set_growth_rate";
  detail::require_finite(kFunction, "rate", rate);
  detail::require_non_negative(kFunction, "rate", rate);
  Impl& w = *impl_;
  if (rate == w.def.growth_rate) return;
  if (rate != 0.0 && w.gravity_on) {
    refuse(kFunction, "rate", carom::number_text(rate),
           "must be 0 while gravity is on (WorldDef::gravity): balls grow or fall, not both");
  }
  if (rate != 0.0 && w.table_on) {
    refuse(kFunction, "rate", carom::number_text(rate),
           "must be 0 on a table (WorldDef::table): its balls keep their size");
  }
  // Radii as they are now, then growing at the new rate from now; every ball predicted again.
  w.synchronize(w.time);
  w.settle_growth();
  w.def.growth_rate = rate;
  w.growth_on = rate != 0.0;
  w.general_motion = w.gravity_on || w.growth_on || w.table_on;
  w.growth_start = w.time;
  w.growth_relative = rate;
  w.plan_growth_regrid();
  w.events_valid = false;
}

double World::growth_rate_from_now() const noexcept {
  const Impl& w = *impl_;
  if (!w.growth_on) return 0.0;
  return w.growth_relative / (1.0 + w.growth_relative * (w.time - w.growth_start));
}

double World::set_temperature(double kT) {
  constexpr const char* kFunction = "World::set_temperature";
  detail::require_finite(kFunction, "kT", kT);
  detail::require_positive(kFunction, "kT", kT);
  Impl& w = *impl_;
  if (w.table_on) {
    refuse(kFunction, "kT", carom::number_text(kT),
           "is a gas's temperature, which a table's balls (slowed by the cloth) do not keep");
  }
  // Every ball to now (its velocity of now under gravity), then sums in handle order, as
  // kinetic_energy does.
  w.synchronize(w.time);
  Vec2 momentum;
  double mass = 0.0;
  std::uint64_t count = 0;
  for (const std::uint32_t i : w.slot_of_handle) {
    if (!w.balls[i].alive() || !w.movable(i)) continue;
    momentum += w.balls[i].velocity * w.species_of(i).mass;
    mass += w.species_of(i).mass;
    ++count;
  }
  if (count == 0) return 0.0;
  const Vec2 drift = momentum / mass;
  double relative = 0.0;
  for (const std::uint32_t i : w.slot_of_handle) {
    if (!w.balls[i].alive() || !w.movable(i)) continue;
    relative += 0.5 * w.species_of(i).mass * length_squared(w.balls[i].velocity - drift);
  }
  const double before = kinetic_energy();
  // Motion relative to the drift at the level of the drift's own rounding (one ball alone, or
  // balls all at one velocity) is no motion: scaling it would turn rounding into a temperature.
  const auto n = static_cast<double>(count);
  if (!(relative > 0x1p-100 * n * n * before)) return 0.0;
  const double factor = std::sqrt(n * kT / relative);
  Vec2 scaled_momentum;
  for (const std::uint32_t i : w.slot_of_handle) {
    if (!w.balls[i].alive() || !w.movable(i)) continue;
    BallSlot& b = w.balls[i];
    b.velocity = drift + (b.velocity - drift) * factor;
    scaled_momentum += b.velocity * w.species_of(i).mass;
  }
  // Σ m·(v − drift) is zero only to rounding, and the factor scales that rounding too: taking
  // the difference out of every ball keeps the momentum to the rounding of one more sum.
  const Vec2 correction = (scaled_momentum - momentum) / mass;
  for (const std::uint32_t i : w.slot_of_handle) {
    if (!w.balls[i].alive() || !w.movable(i)) continue;
    BallSlot& b = w.balls[i];
    b.velocity -= correction;
    ++b.version;
    if (w.gravity_on) w.disturb(i);  // a resting ball that moves rests no more
  }
  w.events_valid = false;
  return kinetic_energy() - before;
}

void World::set_filter(BallId id, const CollisionFilter& filter) {
  Impl& w = *impl_;
  const std::uint32_t slot = w.slot_of("World::set_filter", id);
  const std::uint32_t number = w.filters.number_of(filter);
  if (number == w.infos[slot].filter) return;
  w.infos[slot].filter = number;
  // Its pending events, and its neighbours' with it, were predicted under the old filter: a new
  // version makes theirs stale (re-predicted when they come up), and its own is predicted anew.
  if (w.accelerated) w.advance(slot, w.time);
  if (w.gravity_on) w.disturb(slot);  // what rested on it may now fall through it
  BallSlot& b = w.balls[slot];
  b.position = w.position_at(slot, w.time);
  b.local_time = w.time;
  ++b.version;
  w.repredict_changed(slot);
}

CollisionFilter World::filter(BallId id) const {
  return impl_->filters[impl_->infos[impl_->slot_of("World::filter", id)].filter];
}

void World::set_wall_filter(WallId wall, const CollisionFilter& filter) {
  Impl& w = *impl_;
  if (wall >= w.walls.size()) {
    refuse("World::set_wall_filter", "wall", std::to_string(wall),
           "must be a wall of this world (" + std::to_string(w.walls.size()) + " walls)");
  }
  if (w.def.boundary == Boundary::box && wall < 4 && filter != CollisionFilter{}) {
    refuse("World::set_wall_filter", "wall", std::to_string(wall),
           "is a side of the box boundary, which keeps every ball in (no filter)");
  }
  const std::uint32_t number = w.filters.number_of(filter);
  if (number == w.walls[wall].filter) return;
  w.walls[wall].filter = number;
  // A ball's pending wall contact names the wall without a version: every ball predicts again
  // at the next run; a ball resting or sliding on the wall is no longer carried by it.
  w.free_resting_on(wall);
  w.events_valid = false;
}

CollisionFilter World::wall_filter(WallId wall) const {
  if (wall >= impl_->walls.size()) {
    refuse("World::wall_filter", "wall", std::to_string(wall),
           "must be a wall of this world (" + std::to_string(impl_->walls.size()) + " walls)");
  }
  return impl_->filters[impl_->walls[wall].filter];
}

void World::set_velocity(BallId id, Vec2 velocity) {
  constexpr const char* kFunction = "World::set_velocity";
  const std::uint32_t slot = impl_->slot_of(kFunction, id);
  detail::require_finite(kFunction, "velocity", velocity);
  if (impl_->accelerated) impl_->advance(slot, impl_->time);
  if (impl_->gravity_on) impl_->disturb(slot);  // it no longer rests, and what rested on it falls
  BallSlot& b = impl_->balls[slot];
  b.position = impl_->position_at(slot, impl_->time);
  b.local_time = impl_->time;
  b.velocity = velocity;
  if (impl_->table_on) {
    detail::TableBall state = impl_->table_ball(slot);
    state.velocity = velocity;
    impl_->set_on_table(slot, state, impl_->time, false);
  }
  ++b.version;
  impl_->repredict_changed(slot);
}

// The balls filed in the grid's cells within `reach` (and one cell more) of the segment from a
// to b, in ascending slot order; nothing when that box covers more cells than there are balls
// (every ball is then the cheaper scan) or there is no grid.
std::optional<std::vector<std::uint32_t>> World::Impl::balls_near_path(Vec2 a, Vec2 b,
                                                                       double reach) const {
  if (!grid_valid) return std::nullopt;
  const Vec2 cell = grid.cell_size();
  const Vec2 lower{std::min(a.x, b.x) - reach - cell.x, std::min(a.y, b.y) - reach - cell.y};
  const Vec2 upper{std::max(a.x, b.x) + reach + cell.x, std::max(a.y, b.y) + reach + cell.y};
  const std::int32_t x0 = grid.column_of(lower.x);
  const std::int32_t x1 = grid.column_of(upper.x);
  const std::int32_t y0 = grid.row_of(lower.y);
  const std::int32_t y1 = grid.row_of(upper.y);
  const double cells = (static_cast<double>(x1 - x0) + 1.0) * (static_cast<double>(y1 - y0) + 1.0);
  if (!(cells <= static_cast<double>(live_count))) return std::nullopt;
  std::vector<std::uint32_t> found;
  for (std::int32_t y = y0; y <= y1; ++y) {
    for (std::int32_t x = x0; x <= x1; ++x) {
      for (std::int32_t j = grid.first_ball(grid.index(x, y)); j != detail::kNoBall;
           j = grid.next_ball(static_cast<std::uint32_t>(j))) {
        found.push_back(static_cast<std::uint32_t>(j));
      }
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

detail::DragStop World::Impl::sweep_drag(std::uint32_t slot, Vec2 from, Vec2 end) const {
  // Each other ball at any of its 3×3 periodic images around the nearest: with diameters below
  // a third of the period, those are all the images a drag of at most half a period can reach.
  const Vec2 move = end - from;
  const int images = def.boundary == Boundary::periodic ? 1 : 0;
  const double radius = radius_of(slot);
  const Ball moving{from, radius};
  // The first touch; where the ball then is comes from the obstacle's side (a radius back from
  // its nearest point, a sum of radii back from its centre): from + move·t carries the rounding
  // of the move's length.
  detail::DragStop first{false, end, end};
  double fraction = 1.0;
  const auto keep_first = [&](const Impact& hit, Vec2 touching) {
    if (!hit.hit || !(hit.t < fraction)) return;
    fraction = hit.t;
    first = {true, hit.t > 0.0 ? touching : from, hit.t > 0.0 ? hit.a_at : from};
  };
  const auto sweep_ball = [&](std::uint32_t j) {
    if (j == slot || !balls[j].alive() || !balls_meet(slot, j)) return;
    const Vec2 nearest = from + minimum_image(position_at(j, time) - from);
    const double reach = radius + radius_of(j);
    for (int kx = -images; kx <= images; ++kx) {
      for (int ky = -images; ky <= images; ++ky) {
        const Vec2 other =
            nearest + Vec2{kx * periodic_cell.period().x, ky * periodic_cell.period().y};
        const Impact hit = sweep_ball_ball(moving, move, {other, radius_of(j)});
        keep_first(hit, other - hit.normal * reach);
      }
    }
  };
  // A short drag (a game's pointer moves a little each frame) sweeps only the balls filed in the
  // cells around its path, in slot order like the sweep of every ball, so with the same result:
  // a ball the path can touch has its centre within the two radii of it, and lies in its cell
  // to a rounding (one more cell of margin covers that).
  const auto nearby =
      images == 0 ? balls_near_path(from, end, radius + largest_radius) : std::nullopt;
  if (nearby) {
    for (const std::uint32_t j : *nearby) sweep_ball(j);
  } else {
    for (std::uint32_t j = 0; j < balls.size(); ++j) sweep_ball(j);
  }
  for (std::uint32_t w = 0; w < walls.size(); ++w) {
    if (!walls[w].solid() || !meets_wall(slot, w)) continue;
    const detail::Wall& wall = walls[w];
    const Impact hit = detail::time_of_impact(wall, moving, move, 1.0);
    if (!hit.hit) continue;
    // The contact point the query reports is the centre plus the normal times the radius; the
    // wall's own nearest point to that centre lies on the wall to the rounding of its
    // coordinates.
    const Vec2 on_wall = detail::nearest_point(wall, hit.a_at);
    const Vec2 gap = on_wall - hit.a_at;
    keep_first(hit, on_wall - (gap == Vec2{} ? hit.normal : normalized(gap)) * radius);
  }
  return first;
}

Vec2 World::set_position(BallId id, Vec2 position, Placement placement) {
  constexpr const char* kFunction = "World::set_position";
  Impl& w = *impl_;
  const std::uint32_t slot = w.slot_of(kFunction, id);
  detail::require_finite(kFunction, "position", position);
  if (w.accelerated) w.advance(slot, w.time);  // (the velocity too, re-based to now)
  w.settle_growth();  // (the radii of now, which the sweep and the overlap test read)
  BallSlot& b = w.balls[slot];
  const Vec2 from = w.position_at(slot, w.time);
  Vec2 target = position;
  if (placement == Placement::nearest_free) {
    // Sweep the ball from where it is to where it is asked to go; it stops at the first touch.
    // In a periodic cell it goes the shortest way (at most half a period on each axis).
    const bool periodic = w.def.boundary == Boundary::periodic;
    const Vec2 end =
        periodic ? from + w.minimum_image(w.wrap_into_cell(position) - from) : position;
    detail::DragStop first = w.sweep_drag(slot, from, end);
    // A long drag finds its touch only to the rounding of its own coordinates (10³ for a drag
    // from 10¹⁸), and may miss a touch near its end altogether (rounded to the end): sweeps
    // again from a little short of the touch, or of the end, where the coordinates are those
    // of the obstacle, find it to theirs. Each starts before the true touch, so on a free
    // place.
    Vec2 start = from;
    for (int stage = 0; stage < kMaxDragStages; ++stage) {
      const double resolution =
          8.0 * std::numeric_limits<double>::epsilon() *
          std::max({std::abs(start.x), std::abs(start.y), std::abs(end.x), std::abs(end.y)});
      if (!(resolution > kFineDrag * w.radius_of(slot))) break;
      const Vec2 reached = first.touched ? first.swept : end;
      const double back = 4.0 * resolution;
      if (!(length(reached - start) > back)) break;
      start = reached - (end - start) * (back / length(end - start));
      first = w.sweep_drag(slot, start, end);
    }
    // Untouched, it reaches the very place asked for (from + (position − from) need not be it).
    target = first.touched ? first.stop : position;
  }
  target = w.wrap_into_cell(target);
  w.ensure_grid(target, w.radius_of(slot));
  // The swept stop point touches its obstacle, and may overlap it by a rounding: it is accepted.
  const std::string overlap =
      placement == Placement::nearest_free
          ? std::string{}
          : w.overlap_at(target, w.radius_of(slot), slot, w.infos[slot].filter);
  if (!overlap.empty()) {
    refuse(kFunction, "position", detail::vector_text(position),
           "the ball cannot go there: " + overlap);
  }
  if (w.gravity_on) w.disturb(slot);  // it no longer rests, and what rested on it falls
  w.grid.erase(slot);
  b.position = target;
  b.local_time = w.time;
  ++b.version;
  w.grid.insert(slot, w.grid.cell_of(target));
  w.repredict_changed(slot);
  return target;
}

}  // namespace carom
