// Building a world from a scene, running it (its pockets remove the balls falling in), and
// reading its state back.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

#include "carom/error.hpp"
#include "carom/scene.hpp"
#include "scene_check.hpp"

namespace carom {
namespace {

SceneError world_refused(const std::string& path, const InvalidArgument& error) {
  return SceneError(
      {"", 0, 0, path, error.value(), "the world refuses it: " + error.requirement(), ""});
}

// A world run's contacts onto `contacts`, and its sensor events onto the scene world's, each
// placed among the call's contacts so far; a pocket's removals onto `potted`.
void append(SceneWorld& sw, std::vector<ContactEvent>* contacts, std::vector<PottedBall>* potted) {
  const std::size_t before = contacts != nullptr ? contacts->size() : 0;
  for (SensorEvent event : sw.world.sensor_events()) {
    event.contacts_before += before;
    sw.sensor_events.push_back(event);
    if (event.removed) {
      // Gone: its scene entry reads null.
      const auto gone = std::find(sw.balls.begin(), sw.balls.end(), event.ball);
      const auto ball = static_cast<std::size_t>(gone - sw.balls.begin());
      if (gone != sw.balls.end()) *gone = BallId{};
      const auto pocket = std::find(sw.pockets.begin(), sw.pockets.end(), event.sensor);
      if (potted != nullptr && pocket != sw.pockets.end() && gone != sw.balls.end()) {
        potted->push_back({sw.start_time + event.time, ball,
                           static_cast<std::size_t>(pocket - sw.pockets.begin())});
      }
    }
  }
  const std::span<const MotionEvent> motions = sw.world.motion_events();
  sw.motion_events.insert(sw.motion_events.end(), motions.begin(), motions.end());
  if (contacts == nullptr) return;
  const std::span<const ContactEvent> now = sw.world.contacts();
  contacts->insert(contacts->end(), now.begin(), now.end());
}

}  // namespace

std::optional<std::size_t> SceneWorld::index_of(BallId id) const {
  if (!world.contains(id)) return std::nullopt;
  return static_cast<std::size_t>(world.user_data(id));
}

SceneWorld make_world(const Scene& scene) {
  std::vector<SceneBall> balls = scene_detail::check_scene(scene);
  scene_detail::separate_touching(scene, balls);
  const WorldDef& def = scene.world;
  SceneWorld sw{[&] {
                  try {
                    return World(def);
                  } catch (const InvalidArgument& error) {
                    throw world_refused("world", error);
                  }
                }(),
                {},
                {},
                {},
                {},
                0.0,
                0.0,
                {},
                {}};
  sw.scene = scene;
  sw.scene.balls = balls;
  sw.scene.generators.clear();
  sw.start_time = scene.time;

  try {
    // (A Scene made in C++ may hold filters of other counts than its walls.)
    for (const auto& [filters, count, name] :
         {std::tuple{&scene.segment_filters, scene.segments.size(), "scene.segment_filters"},
          std::tuple{&scene.arc_filters, scene.arcs.size(), "scene.arc_filters"}}) {
      if (!filters->empty() && filters->size() != count) {
        throw InvalidArgument("make_world", name, std::to_string(filters->size()) + " filters",
                              "must be empty or one for each (" + std::to_string(count) + ")");
      }
    }
    for (const auto& [motions, count, name] :
         {std::tuple{&scene.segment_motions, scene.segments.size(), "scene.segment_motions"},
          std::tuple{&scene.arc_motions, scene.arcs.size(), "scene.arc_motions"}}) {
      if (!motions->empty() && motions->size() != count) {
        throw InvalidArgument("make_world", name, std::to_string(motions->size()) + " motions",
                              "must be empty or one for each (" + std::to_string(count) + ")");
      }
    }
    // Each wall's filter before any ball, so that placing balls honours it.
    for (std::size_t i = 0; i < scene.segments.size(); ++i) {
      const WallId wall = sw.world.add_segment(scene.segments[i]);
      if (!scene.segment_filters.empty()) sw.world.set_wall_filter(wall, scene.segment_filters[i]);
      if (!scene.segment_motions.empty() && scene.segment_motions[i]) {
        sw.world.set_wall_motion(wall, *scene.segment_motions[i]);
      }
    }
    for (const ScenePolyline& polyline : scene.polylines) {
      const WallId first = sw.world.add_polyline(polyline.points, polyline.closed);
      for (WallId wall = first; wall < sw.world.wall_count(); ++wall) {
        sw.world.set_wall_filter(wall, polyline.filter);
      }
    }
    for (std::size_t i = 0; i < scene.arcs.size(); ++i) {
      const WallId wall = sw.world.add_arc(scene.arcs[i]);
      if (!scene.arc_filters.empty()) sw.world.set_wall_filter(wall, scene.arc_filters[i]);
      if (!scene.arc_motions.empty() && scene.arc_motions[i]) {
        sw.world.set_wall_motion(wall, *scene.arc_motions[i]);
      }
    }
  } catch (const InvalidArgument& error) {
    throw world_refused("segments", error);
  }
  for (std::size_t k = 0; k < scene.sensors.size(); ++k) {
    const SceneSensor& sensor = scene.sensors[k];
    try {
      const WallId wall =
          std::visit([&](const auto& shape) { return sw.world.add_sensor(shape, sensor.action); },
                     sensor.shape);
      sw.world.set_wall_filter(wall, sensor.filter);
      sw.sensors.push_back(wall);
    } catch (const InvalidArgument& error) {
      throw world_refused("sensors[" + std::to_string(k) + "]", error);
    }
  }
  // Pockets: disc sensors that remove the ball entering them, the world's last walls.
  for (std::size_t k = 0; k < scene.pockets.size(); ++k) {
    const ScenePocket& p = scene.pockets[k];
    try {
      sw.pockets.push_back(
          sw.world.add_sensor(Ball{p.position, p.radius}, SensorAction::remove_ball));
    } catch (const InvalidArgument& error) {
      throw world_refused("pockets[" + std::to_string(k) + "]", error);
    }
  }
  sw.balls.reserve(balls.size());
  sw.world.reserve(balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const SceneBall& b = balls[i];
    try {
      const BallId id = sw.world.add_ball({b.position, b.velocity, b.radius, b.mass, b.restitution,
                                           static_cast<std::uint64_t>(i), b.spin},
                                          b.filter);
      sw.balls.push_back(id);
      if (b.name) sw.by_name[*b.name] = id;
    } catch (const InvalidArgument& error) {
      throw world_refused("balls[" + std::to_string(i) + "]", error);
    }
  }
  return sw;
}

namespace {

// A world run, its contacts, sensor events and pottings collected.
void advance_until(SceneWorld& sw, double time, std::vector<ContactEvent>* contacts,
                   std::vector<PottedBall>* potted) {
  static_cast<void>(sw.world.run_until(time));
  append(sw, contacts, potted);
}

std::uint64_t advance_collisions(SceneWorld& sw, std::uint64_t count,
                                 std::vector<ContactEvent>* contacts,
                                 std::vector<PottedBall>* potted, double time_limit) {
  const std::uint64_t done = sw.world.run_collisions(count, time_limit);
  append(sw, contacts, potted);
  return done;
}

// The world time of the thermostat's next step by time after now (infinity without one). Steps
// fall on the scene clock's multiples of the interval, each computed by the one expression, so a
// run that stopped on a step knows it exactly and never takes it twice.
double next_thermostat_time(const SceneWorld& sw) {
  if (!sw.scene.thermostat || !sw.scene.thermostat->interval) {
    return std::numeric_limits<double>::infinity();
  }
  const double interval = *sw.scene.thermostat->interval;
  double k = std::floor(sw.time() / interval);
  while (k * interval - sw.start_time <= sw.world.time()) k += 1.0;
  return k * interval - sw.start_time;
}

// Collisions until the thermostat's next step by collisions (0 without one).
std::uint64_t collisions_to_thermostat(const SceneWorld& sw) {
  if (!sw.scene.thermostat || !sw.scene.thermostat->collisions) return 0;
  const std::uint64_t every = *sw.scene.thermostat->collisions;
  return every - sw.world.collision_count() % every;
}

void thermostat_step(SceneWorld& sw) {
  sw.thermostat_work += sw.world.set_temperature(sw.scene.thermostat->temperature);
}

// Whether the last run ended for a reason that ends the call (a stop from outside, or no contact
// ever again in a run by collisions).
bool run_ended(const World& world) {
  return world.stop_reason() == StopReason::interrupted ||
         world.stop_reason() == StopReason::no_more_contacts;
}

// Runs by collisions (at most `count`, never past time_limit) with the thermostat's steps.
std::uint64_t collisions_with_thermostat(SceneWorld& sw, std::uint64_t count,
                                         std::vector<ContactEvent>* contacts,
                                         std::vector<PottedBall>* potted, double time_limit) {
  std::uint64_t done = 0;
  while (done < count) {
    const double step_time = next_thermostat_time(sw);
    const std::uint64_t to_step = collisions_to_thermostat(sw);
    const std::uint64_t chunk = to_step != 0 ? std::min(count - done, to_step) : count - done;
    const std::uint64_t chunk_done =
        advance_collisions(sw, chunk, contacts, potted, std::min(time_limit, step_time));
    done += chunk_done;
    if (sw.world.stop_reason() == StopReason::interrupted) break;
    const bool at_time_step = sw.world.time() >= step_time;
    if (at_time_step || (to_step != 0 && chunk_done == to_step)) thermostat_step(sw);
    if (sw.world.time() >= time_limit || run_ended(sw.world)) break;
    if (chunk_done < chunk && !at_time_step) break;
  }
  return done;
}

double until_between_shots(SceneWorld& sw, double time, std::vector<ContactEvent>* contacts,
                           std::vector<PottedBall>* potted) {
  const double start = sw.world.time();
  if (!sw.scene.thermostat) {
    advance_until(sw, time, contacts, potted);
    return sw.world.time() - start;
  }
  if (sw.scene.thermostat->collisions) {
    // By collisions, with no bound on their count, up to the time.
    static_cast<void>(collisions_with_thermostat(sw, std::numeric_limits<std::uint64_t>::max(),
                                                 contacts, potted, time));
    // No contact will ever come: the rest of the way has no step to take.
    if (sw.world.stop_reason() == StopReason::no_more_contacts && sw.world.time() < time) {
      advance_until(sw, time, contacts, potted);
    }
    return sw.world.time() - start;
  }
  for (;;) {
    const double step_time = next_thermostat_time(sw);
    advance_until(sw, std::min(time, step_time), contacts, potted);
    if (sw.world.stop_reason() == StopReason::interrupted) break;
    if (sw.world.time() >= step_time) thermostat_step(sw);
    if (sw.world.time() >= time) break;
  }
  return sw.world.time() - start;
}

double step_between_shots(SceneWorld& sw, double dt, std::vector<ContactEvent>* contacts,
                          std::vector<PottedBall>* potted) {
  const double start = sw.world.time();
  if (!sw.scene.thermostat) {
    const double advanced = sw.world.step(dt);
    append(sw, contacts, potted);
    return advanced;
  }
  return until_between_shots(sw, start + dt, contacts, potted);
}

std::uint64_t collisions_between_shots(SceneWorld& sw, std::uint64_t count,
                                       std::vector<ContactEvent>* contacts,
                                       std::vector<PottedBall>* potted, double time_limit) {
  if (!sw.scene.thermostat) return advance_collisions(sw, count, contacts, potted, time_limit);
  return collisions_with_thermostat(sw, count, contacts, potted, time_limit);
}

// The world time of the next shot still to strike (infinity when none is left).
double next_shot_time(const SceneWorld& sw) {
  if (sw.shots_taken >= sw.scene.shots.size()) return std::numeric_limits<double>::infinity();
  return sw.scene.shots[sw.shots_taken].time - sw.start_time;
}

// Strikes every shot whose time has come; a ball potted before its shot is not struck.
void take_due_shots(SceneWorld& sw) {
  while (sw.shots_taken < sw.scene.shots.size() && next_shot_time(sw) <= sw.world.time()) {
    const SceneShot& shot = sw.scene.shots[sw.shots_taken++];
    const auto named = sw.by_name.find(shot.ball);
    if (named == sw.by_name.end() || !sw.world.contains(named->second)) continue;
    sw.world.strike(named->second, shot.cue);
  }
}

// Each call starts with no sensor or motion events of its own and the shots due struck.
void start_call(SceneWorld& sw) {
  sw.sensor_events.clear();
  sw.motion_events.clear();
  take_due_shots(sw);
}

double until_with_shots(SceneWorld& sw, double time, std::vector<ContactEvent>* contacts,
                        std::vector<PottedBall>* potted) {
  const double start = sw.world.time();
  for (;;) {
    static_cast<void>(
        until_between_shots(sw, std::min(time, next_shot_time(sw)), contacts, potted));
    if (sw.world.stop_reason() == StopReason::interrupted) break;
    take_due_shots(sw);
    if (sw.world.time() >= time) break;
  }
  return sw.world.time() - start;
}

}  // namespace

double step_scene(SceneWorld& sw, double dt, std::vector<ContactEvent>* contacts,
                  std::vector<PottedBall>* potted) {
  start_call(sw);
  const double end = sw.world.time() + dt;
  if (next_shot_time(sw) > end) return step_between_shots(sw, dt, contacts, potted);
  return until_with_shots(sw, end, contacts, potted);
}

double run_scene_until(SceneWorld& sw, double time, std::vector<ContactEvent>* contacts,
                       std::vector<PottedBall>* potted) {
  start_call(sw);
  return until_with_shots(sw, time, contacts, potted);
}

std::uint64_t run_scene_collisions(SceneWorld& sw, std::uint64_t count,
                                   std::vector<ContactEvent>* contacts,
                                   std::vector<PottedBall>* potted, double time_limit) {
  start_call(sw);
  std::uint64_t done = 0;
  for (;;) {
    const double shot_time = next_shot_time(sw);
    done += collisions_between_shots(sw, count - done, contacts, potted,
                                     std::min(time_limit, shot_time));
    if (sw.world.stop_reason() == StopReason::interrupted || done >= count) break;
    if (sw.world.time() < shot_time) break;  // stopped before the next shot, for its own reason
    // (A world at rest waited for the shot: its run reached the shot's time.)
    take_due_shots(sw);
    if (sw.world.time() >= time_limit) break;
  }
  return done;
}

namespace {

// The scene's walls before the sensors: its segments, its polylines' segments, its arcs.
std::size_t scene_wall_count(const Scene& scene) {
  std::size_t count = scene.segments.size() + scene.arcs.size();
  for (const ScenePolyline& p : scene.polylines) {
    count += p.closed && p.points.size() > 2 ? p.points.size() : p.points.size() - 1;
  }
  return count;
}

// The id of the scene's first wall: the world's walls less the scene's and its sensors.
WallId first_scene_wall(const SceneWorld& sw) {
  return static_cast<WallId>(sw.world.wall_count() - scene_wall_count(sw.scene) -
                             sw.scene.sensors.size());
}

}  // namespace

WallId segment_wall(const SceneWorld& sw, std::size_t i) {
  return first_scene_wall(sw) + static_cast<WallId>(i);
}

WallId arc_wall(const SceneWorld& sw, std::size_t i) {
  return first_scene_wall(sw) +
         static_cast<WallId>(scene_wall_count(sw.scene) - sw.scene.arcs.size() + i);
}

Scene capture_scene(const SceneWorld& sw) {
  Scene scene = sw.scene;
  // Moving walls where they are now, with what is left of their motions.
  for (std::size_t i = 0; i < scene.segment_motions.size(); ++i) {
    if (!scene.segment_motions[i]) continue;
    scene.segments[i] = std::get<Segment>(sw.world.wall(segment_wall(sw, i)));
    scene.segment_motions[i] = sw.world.wall_motion(segment_wall(sw, i));
  }
  for (std::size_t i = 0; i < scene.arc_motions.size(); ++i) {
    if (!scene.arc_motions[i]) continue;
    scene.arcs[i] = std::get<Arc>(sw.world.wall(arc_wall(sw, i)));
    scene.arc_motions[i] = sw.world.wall_motion(arc_wall(sw, i));
  }
  scene.balls.clear();
  scene.generators.clear();
  scene.time = sw.time();
  // The shots struck are in the balls' velocities and spins now.
  scene.shots.erase(scene.shots.begin(),
                    scene.shots.begin() + static_cast<std::ptrdiff_t>(sw.shots_taken));
  // set_gravity may have changed it since the world was built.
  scene.world.gravity = sw.world.def().gravity;
  // The world's own settings are what it ran with, whatever the scene it came from said.
  scene.world.rest_height = sw.world.def().rest_height;
  // Growth continues from the radii of now at the rate relative to them, the same law.
  scene.world.growth_rate = sw.world.growth_rate_from_now();
  for (std::size_t i = 0; i < sw.balls.size(); ++i) {
    const BallId id = sw.balls[i];
    if (id.is_null() || !sw.world.contains(id)) continue;
    SceneBall ball = sw.scene.balls[i];
    ball.position = sw.world.position(id);
    ball.velocity = sw.world.velocity(id);
    ball.radius = sw.world.radius(id);
    if (scene.world.table) ball.spin = sw.world.spin(id);
    scene.balls.push_back(ball);
  }
  return scene;
}

}  // namespace carom
