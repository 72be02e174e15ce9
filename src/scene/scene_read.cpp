// Reading a scene: JSON text to a checked carom::Scene. Field by field here; the geometry
// (overlaps, balls outside a box, generators that cannot place their balls) in scene_check.cpp.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>

#include "carom/scene.hpp"
#include "json_fields.hpp"
#include "scene_check.hpp"

namespace carom {
namespace {

using scene_detail::JsonPath;
using scene_detail::JsonSource;
using scene_detail::ObjectFields;

JsonPath child(JsonPath path, std::size_t index) {
  path.emplace_back(index);
  return path;
}

double positive(const ObjectFields& fields, std::string_view key, double fallback) {
  const double value = fields.number_or(key, fallback);
  if (!(value > 0.0)) fields.fail(key, "must be > 0");
  return value;
}

double non_negative(const ObjectFields& fields, std::string_view key, double fallback) {
  const double value = fields.number_or(key, fallback);
  if (!(value >= 0.0)) fields.fail(key, "must be >= 0");
  return value;
}

std::optional<double> restitution(const ObjectFields& fields) {
  const std::optional<double> value = fields.optional_number("restitution");
  if (value && !(*value >= 0.0 && *value <= 1.0)) fields.fail("restitution", "must lie in [0, 1]");
  return value;
}

// "mass": a number > 0, or "immovable".
double mass(const ObjectFields& fields) {
  if (!fields.has("mass")) return 1.0;
  const nlohmann::json& value = fields.at("mass");
  if (value.is_string()) {
    if (value.get<std::string>() == "immovable") return kImmovable;
    fields.fail("mass", "must be a number > 0 or \"immovable\"");
  }
  return positive(fields, "mass", 1.0);
}

std::optional<std::string> color(const ObjectFields& fields) {
  std::optional<std::string> text = fields.optional_string("color");
  if (text && text->empty()) fields.fail("color", "must not be empty");
  return text;
}

SceneUnits read_units(const ObjectFields& fields) {
  SceneUnits units;
  if (!fields.has("units")) return units;
  const ObjectFields u(fields.source(), fields.at("units"), fields.path_of("units"),
                       {"length", "time", "mass"});
  units.length = u.optional_string("length").value_or(units.length);
  units.time = u.optional_string("time").value_or(units.time);
  units.mass = u.optional_string("mass").value_or(units.mass);
  return units;
}

// world.table: each key optional, its default Table's.
std::optional<Table> read_table(const ObjectFields& fields) {
  if (!fields.has("table")) return std::nullopt;
  const ObjectFields t(
      fields.source(), fields.at("table"), fields.path_of("table"),
      {"g", "sliding_friction", "rolling_friction", "spinning_friction", "ball_friction",
       "cushion_height", "cushion_restitution", "cushion_friction", "contact_time"});
  const Table defaults;
  Table table;
  table.g = positive(t, "g", defaults.g);
  table.sliding_friction = non_negative(t, "sliding_friction", defaults.sliding_friction);
  table.rolling_friction = non_negative(t, "rolling_friction", defaults.rolling_friction);
  table.spinning_friction = non_negative(t, "spinning_friction", defaults.spinning_friction);
  table.ball_friction = non_negative(t, "ball_friction", defaults.ball_friction);
  table.cushion_height = t.number_or("cushion_height", defaults.cushion_height);
  if (!(table.cushion_height >= 0.5 && table.cushion_height < 1.0)) {
    t.fail("cushion_height",
           "must lie in [0.5, 1): the nose's height as a share of the ball's "
           "diameter, at or above its equator");
  }
  table.cushion_restitution = t.number_or("cushion_restitution", defaults.cushion_restitution);
  if (!(table.cushion_restitution >= 0.0 && table.cushion_restitution <= 1.0)) {
    t.fail("cushion_restitution", "must lie in [0, 1]");
  }
  table.cushion_friction = non_negative(t, "cushion_friction", defaults.cushion_friction);
  table.contact_time = non_negative(t, "contact_time", defaults.contact_time);
  return table;
}

WorldDef read_settings(const ObjectFields& fields) {
  WorldDef settings;
  if (!fields.has("world")) return settings;
  const ObjectFields w(fields.source(), fields.at("world"), fields.path_of("world"),
                       {"boundary", "lower", "upper", "restitution", "collapse_time", "cell_size",
                        "gravity", "rest_height", "growth_rate", "table"});
  const std::string boundary = w.optional_string("boundary").value_or("open");
  if (boundary == "open") {
    settings.boundary = Boundary::open;
  } else if (boundary == "box") {
    settings.boundary = Boundary::box;
  } else if (boundary == "periodic") {
    settings.boundary = Boundary::periodic;
  } else {
    w.fail("boundary", "must be \"open\", \"box\" or \"periodic\"");
  }
  if (settings.boundary != Boundary::open) {
    settings.lower = w.vector("lower");
    settings.upper = w.vector("upper");
    if (!(settings.upper.x > settings.lower.x && settings.upper.y > settings.lower.y)) {
      w.fail("upper", "must lie above and to the right of lower (" +
                          std::to_string(settings.lower.x) + ", " +
                          std::to_string(settings.lower.y) + ")");
    }
  } else {
    settings.lower = w.optional_vector("lower").value_or(Vec2{});
    settings.upper = w.optional_vector("upper").value_or(Vec2{});
  }
  const std::optional<double> e = w.optional_number("restitution");
  if (e) {
    if (!(*e >= 0.0 && *e <= 1.0)) w.fail("restitution", "must lie in [0, 1]");
    settings.restitution = *e;
  }
  settings.collapse_time = non_negative(w, "collapse_time", 0.0);
  settings.cell_size = non_negative(w, "cell_size", 0.0);
  settings.gravity = w.optional_vector("gravity").value_or(Vec2{});
  settings.rest_height = positive(w, "rest_height", WorldDef{}.rest_height);
  settings.growth_rate = non_negative(w, "growth_rate", 0.0);
  if (settings.growth_rate != 0.0 && settings.gravity != Vec2{}) {
    w.fail("growth_rate", "must be 0 when gravity is set: balls grow or fall, not both");
  }
  settings.table = read_table(w);
  if (settings.table && settings.gravity != Vec2{}) {
    w.fail("gravity", "must be unset on a table: the table's g pulls the balls onto the cloth");
  }
  if (settings.table && settings.growth_rate != 0.0) {
    w.fail("growth_rate", "must be 0 on a table: balls on a cloth keep their size");
  }
  return settings;
}

// A shot: {"ball": name, "time": t, "speed": v, "direction": radians, "elevation": radians,
// "side": d, "height": d, "cue_mass": m, "restitution": e}; ball and speed required, time the
// scene's when left out.
SceneShot read_shot(const JsonSource& source, const nlohmann::json& json, const JsonPath& path,
                    double scene_time) {
  const ObjectFields f(source, json, path,
                       {"ball", "time", "speed", "direction", "elevation", "side", "height",
                        "cue_mass", "restitution"});
  SceneShot shot;
  shot.ball = f.string("ball");
  shot.time = f.number_or("time", scene_time);
  shot.cue.speed = f.number("speed");
  if (!(shot.cue.speed >= 0.0)) f.fail("speed", "must be >= 0");
  shot.cue.direction = f.number_or("direction", 0.0);
  shot.cue.elevation = f.number_or("elevation", 0.0);
  if (!(shot.cue.elevation >= 0.0 && shot.cue.elevation < 0.5 * std::numbers::pi)) {
    f.fail("elevation", "must lie in [0, π/2) radians");
  }
  shot.cue.side = f.number_or("side", 0.0);
  shot.cue.height = f.number_or("height", 0.0);
  shot.cue.cue_mass = positive(f, "cue_mass", CueStrike{}.cue_mass);
  shot.cue.restitution = restitution(f).value_or(CueStrike{}.restitution);
  return shot;
}

std::optional<SceneThermostat> read_thermostat(const ObjectFields& fields) {
  if (!fields.has("thermostat")) return std::nullopt;
  const ObjectFields t(fields.source(), fields.at("thermostat"), fields.path_of("thermostat"),
                       {"temperature", "interval", "collisions"});
  SceneThermostat thermostat;
  thermostat.temperature = positive(t, "temperature", 1.0);
  if (t.has("interval") == t.has("collisions")) {
    t.fail(t.has("interval") ? "collisions" : "interval",
           "give exactly one of interval and collisions");
  }
  if (t.has("interval")) thermostat.interval = positive(t, "interval", 1.0);
  if (t.has("collisions")) {
    thermostat.collisions = t.whole_number("collisions");
    if (*thermostat.collisions == 0) t.fail("collisions", "must be at least 1");
  }
  return thermostat;
}

// A ball's "filter": {"category": bits, "mask": bits, "group": whole number}, each optional.
CollisionFilter read_filter(const ObjectFields& fields) {
  CollisionFilter filter;
  if (!fields.has("filter")) return filter;
  const ObjectFields f(fields.source(), fields.at("filter"), fields.path_of("filter"),
                       {"category", "mask", "group"});
  if (f.has("category")) filter.category = f.whole_number("category");
  if (f.has("mask")) filter.mask = f.whole_number("mask");
  if (f.has("group")) {
    const double group = f.number("group");
    if (!(group == std::floor(group) && group >= -2147483648.0 && group <= 2147483647.0)) {
      f.fail("group", "must be a whole number from -2147483648 to 2147483647");
    }
    filter.group = static_cast<std::int32_t>(group);
  }
  return filter;
}

SceneBall read_ball(const JsonSource& source, const nlohmann::json& json, const JsonPath& path) {
  const ObjectFields f(
      source, json, path,
      {"name", "position", "velocity", "radius", "mass", "restitution", "color", "filter", "spin"});
  SceneBall ball;
  ball.name = f.optional_string("name");
  ball.position = f.vector("position");
  ball.velocity = f.optional_vector("velocity").value_or(Vec2{});
  ball.radius = positive(f, "radius", 1.0);
  ball.mass = mass(f);
  ball.restitution = restitution(f);
  ball.color = color(f);
  ball.filter = read_filter(f);
  if (f.has("spin")) {
    const nlohmann::json& spin = f.at("spin");
    const JsonPath at = f.path_of("spin");
    if (!spin.is_array() || spin.size() != 3) {
      f.fail("spin", "must be an array of three numbers [x, y, z] (radians a time unit)");
    }
    ball.spin = {ObjectFields::number_value(source, spin[0], child(at, 0)),
                 ObjectFields::number_value(source, spin[1], child(at, 1)),
                 ObjectFields::number_value(source, spin[2], child(at, 2))};
  }
  return ball;
}

// A wall's "motion": {"velocity": [x, y], "angular_velocity": rad per time unit, "pivot": [x, y],
// "duration": time}, each optional (no duration: for ever).
std::optional<WallMotion> read_motion(const ObjectFields& fields) {
  if (!fields.has("motion")) return std::nullopt;
  const ObjectFields f(fields.source(), fields.at("motion"), fields.path_of("motion"),
                       {"velocity", "angular_velocity", "pivot", "duration"});
  WallMotion motion;
  motion.velocity = f.optional_vector("velocity").value_or(Vec2{});
  motion.angular_velocity = f.number_or("angular_velocity", 0.0);
  motion.pivot = f.optional_vector("pivot").value_or(Vec2{});
  if (f.has("duration")) {
    motion.duration = f.number("duration");
    if (!(motion.duration >= 0.0))
      f.fail("duration", "must be a time >= 0 (leave it out: for ever)");
  }
  return motion;
}

Segment read_segment(const JsonSource& source, const nlohmann::json& json, const JsonPath& path,
                     std::vector<CollisionFilter>& filters,
                     std::vector<std::optional<WallMotion>>& motions) {
  const ObjectFields f(source, json, path, {"a", "b", "filter", "motion"});
  filters.push_back(read_filter(f));
  motions.push_back(read_motion(f));
  return {f.vector("a"), f.vector("b")};
}

ScenePolyline read_polyline(const JsonSource& source, const nlohmann::json& json,
                            const JsonPath& path) {
  const ObjectFields f(source, json, path, {"points", "closed", "filter"});
  ScenePolyline polyline;
  polyline.filter = read_filter(f);
  const nlohmann::json& points = f.at("points");
  if (!points.is_array() || points.size() < 2) {
    f.fail("points", "must be an array of at least two points [x, y]");
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    polyline.points.push_back(
        ObjectFields::vector_value(source, points[i], child(f.path_of("points"), i)));
  }
  polyline.closed = f.boolean_or("closed", false);
  return polyline;
}

// An arc's fields (center, radius, start_angle, end_angle), checked as the world checks them.
Arc arc_fields(const ObjectFields& f) {
  Arc arc;
  arc.center = f.vector("center");
  arc.radius = positive(f, "radius", 1.0);
  arc.start_angle = f.number("start_angle");
  arc.end_angle = f.number("end_angle");
  const auto check_angle = [&f](const char* field, double angle) {
    if (!(std::abs(angle) <= kLargestArcAngle)) {
      f.fail(field, "must lie in [-2^40, 2^40] radians (1.0995e12; include/carom/shapes.hpp)");
    }
  };
  check_angle("start_angle", arc.start_angle);
  check_angle("end_angle", arc.end_angle);
  const double span = arc.end_angle - arc.start_angle;
  constexpr double kTwoPi = 6.283185307179586;
  // The world accepts spans up to 2π plus a rounding (include/carom/shapes.hpp).
  if (!(span >= 0.0 && span <= kTwoPi * (1.0 + 1e-15))) {
    f.fail("end_angle",
           "end_angle - start_angle must lie in [0, 2*pi] (radians, counter-clockwise)");
  }
  return arc;
}

Arc read_arc(const JsonSource& source, const nlohmann::json& json, const JsonPath& path,
             std::vector<CollisionFilter>& filters,
             std::vector<std::optional<WallMotion>>& motions) {
  const ObjectFields f(source, json, path,
                       {"center", "radius", "start_angle", "end_angle", "filter", "motion"});
  filters.push_back(read_filter(f));
  motions.push_back(read_motion(f));
  return arc_fields(f);
}

// A sensor: its "shape" names the fields that give it.
SceneSensor read_sensor(const JsonSource& source, const nlohmann::json& json,
                        const JsonPath& path) {
  const ObjectFields any(source, json, path,
                         {"name", "shape", "action", "filter", "a", "b", "center", "radius",
                          "start_angle", "end_angle"});
  const std::string shape = any.optional_string("shape").value_or("");
  if (shape != "segment" && shape != "arc" && shape != "disc") {
    any.fail("shape", "must be \"segment\", \"arc\" or \"disc\"");
  }
  // Only the fields of its shape.
  const ObjectFields f =
      shape == "segment"
          ? ObjectFields(source, json, path, {"name", "shape", "action", "filter", "a", "b"})
      : shape == "arc" ? ObjectFields(source, json, path,
                                      {"name", "shape", "action", "filter", "center", "radius",
                                       "start_angle", "end_angle"})
                       : ObjectFields(source, json, path,
                                      {"name", "shape", "action", "filter", "center", "radius"});
  SceneSensor sensor;
  sensor.name = f.optional_string("name");
  if (shape == "segment") {
    sensor.shape = Segment{f.vector("a"), f.vector("b")};
  } else if (shape == "arc") {
    sensor.shape = arc_fields(f);
  } else {
    sensor.shape = Ball{f.vector("center"), positive(f, "radius", 1.0)};
  }
  const std::string action = f.optional_string("action").value_or("report");
  if (action == "remove_ball") {
    sensor.action = SensorAction::remove_ball;
  } else if (action != "report") {
    f.fail("action", "must be \"report\" or \"remove_ball\"");
  }
  sensor.filter = read_filter(f);
  return sensor;
}

ScenePocket read_pocket(const JsonSource& source, const nlohmann::json& json,
                        const JsonPath& path) {
  const ObjectFields f(source, json, path, {"name", "position", "radius"});
  ScenePocket pocket;
  pocket.name = f.optional_string("name");
  pocket.position = f.vector("position");
  pocket.radius = positive(f, "radius", 1.0);
  return pocket;
}

SceneVelocities read_velocities(const ObjectFields& generator) {
  SceneVelocities v;
  if (!generator.has("velocity")) return v;
  const ObjectFields f(generator.source(), generator.at("velocity"), generator.path_of("velocity"),
                       {"distribution", "value", "speed", "temperature", "zero_momentum"});
  const std::string distribution = f.optional_string("distribution").value_or("fixed");
  if (distribution == "fixed") {
    v.distribution = VelocityDistribution::fixed;
  } else if (distribution == "uniform_direction") {
    v.distribution = VelocityDistribution::uniform_direction;
  } else if (distribution == "maxwell_boltzmann") {
    v.distribution = VelocityDistribution::maxwell_boltzmann;
  } else {
    f.fail("distribution", "must be \"fixed\", \"uniform_direction\" or \"maxwell_boltzmann\"");
  }
  v.value = f.optional_vector("value").value_or(Vec2{});
  v.speed = non_negative(f, "speed", 1.0);
  v.temperature = non_negative(f, "temperature", 1.0);
  v.zero_momentum = f.boolean_or("zero_momentum", false);
  return v;
}

SceneGenerator read_generator(const JsonSource& source, const nlohmann::json& json,
                              const JsonPath& path) {
  const ObjectFields f(source, json, path,
                       {"name", "placement", "count", "radius", "packing_fraction", "region",
                        "mass", "restitution", "color", "velocity", "seed"});
  SceneGenerator g;
  g.name = f.optional_string("name");
  const std::string placement = f.optional_string("placement").value_or("lattice");
  if (placement == "lattice") {
    g.placement = GeneratorPlacement::lattice;
  } else if (placement == "random") {
    g.placement = GeneratorPlacement::random;
  } else {
    f.fail("placement", "must be \"lattice\" or \"random\"");
  }
  g.count = f.whole_number("count");
  if (g.count < 1) f.fail("count", "must be >= 1");
  if (g.count > kMaxSceneBalls) {
    f.fail("count", "must be at most " + std::to_string(kMaxSceneBalls));
  }
  if (f.has("radius") == f.has("packing_fraction")) {
    f.fail(f.has("radius") ? "packing_fraction" : "radius",
           "give exactly one of radius and packing_fraction");
  }
  if (f.has("radius")) g.radius = positive(f, "radius", 1.0);
  if (f.has("packing_fraction")) {
    g.packing_fraction = f.number("packing_fraction");
    if (!(*g.packing_fraction > 0.0 && *g.packing_fraction < 1.0)) {
      f.fail("packing_fraction", "must lie in (0, 1)");
    }
  }
  if (f.has("region")) {
    const ObjectFields r(source, f.at("region"), f.path_of("region"), {"lower", "upper"});
    g.region_lower = r.vector("lower");
    g.region_upper = r.vector("upper");
    if (!(g.region_upper->x > g.region_lower->x && g.region_upper->y > g.region_lower->y)) {
      r.fail("upper", "must lie above and to the right of lower");
    }
  }
  g.mass = positive(f, "mass", 1.0);
  g.restitution = restitution(f);
  g.color = color(f);
  g.velocities = read_velocities(f);
  g.seed = f.optional_whole_number("seed").value_or(1);
  return g;
}

template <typename Item, typename Read>
void read_array(const ObjectFields& fields, std::string_view key, std::vector<Item>& out,
                Read read) {
  const nlohmann::json* items = fields.array(key);
  if (items == nullptr) return;
  out.reserve(items->size());
  for (std::size_t i = 0; i < items->size(); ++i) {
    out.push_back(read(fields.source(), (*items)[i], child(fields.path_of(key), i)));
  }
}

nlohmann::json parse_json(const JsonSource& source) {
  try {
    return nlohmann::json::parse(source.text());
  } catch (const nlohmann::json::parse_error& error) {
    // what() reads "[json.exception.parse_error.101] parse error at line L, column C: WHAT";
    // the location is given again, in characters, by error_at.
    std::string what = error.what();
    if (const std::size_t colon = what.find(": "); colon != std::string::npos) {
      what = what.substr(colon + 2);
    }
    const std::size_t offset = error.byte > 0 ? error.byte - 1 : 0;
    throw source.error_at(offset, "malformed JSON: " + what);
  } catch (const nlohmann::json::out_of_range& error) {
    // The one range error the parser raises: a number beyond a double, "number overflow parsing
    // 'TOKEN'".
    const std::string what = error.what();
    const std::size_t open = what.find('\'');
    const std::size_t close = what.rfind('\'');
    if (open != std::string::npos && close > open) {
      const std::string token = what.substr(open + 1, close - open - 1);
      if (const auto found = scene_detail::find_number(source.text(), token)) {
        throw source.error(found->path,
                           "is beyond the range of a double (about 1.8e308): it would read as "
                           "infinity");
      }
    }
    throw source.error_at(0, "malformed JSON: " + what);
  }
}

}  // namespace

Scene parse_scene(std::string_view json_text, std::string_view source_name) {
  const JsonSource source(json_text, source_name);
  const nlohmann::json json = parse_json(source);
  const ObjectFields top(
      source, json, {},
      {"carom_scene", "description", "units", "world", "time", "balls", "segments", "polylines",
       "arcs", "pockets", "sensors", "generators", "thermostat", "shots"});
  if (top.has("carom_scene")) {
    const std::uint64_t version = top.whole_number("carom_scene");
    if (version != kSceneFormatVersion) {
      top.fail("carom_scene",
               "this carom reads scene format " + std::to_string(kSceneFormatVersion) + " only");
    }
  }
  Scene scene;
  scene.description = top.optional_string("description").value_or("");
  scene.units = read_units(top);
  scene.world = read_settings(top);
  scene.time = top.number_or("time", 0.0);
  read_array(top, "balls", scene.balls, read_ball);
  read_array(top, "segments", scene.segments,
             [&scene](const JsonSource& text, const nlohmann::json& item, const JsonPath& at) {
               return read_segment(text, item, at, scene.segment_filters, scene.segment_motions);
             });
  read_array(top, "polylines", scene.polylines, read_polyline);
  read_array(top, "arcs", scene.arcs,
             [&scene](const JsonSource& text, const nlohmann::json& item, const JsonPath& at) {
               return read_arc(text, item, at, scene.arc_filters, scene.arc_motions);
             });
  // Every wall with the default filter: none kept (Scene's rule).
  const auto all_default = [](const std::vector<CollisionFilter>& filters) {
    return std::all_of(filters.begin(), filters.end(),
                       [](const CollisionFilter& f) { return f == CollisionFilter{}; });
  };
  if (all_default(scene.segment_filters)) scene.segment_filters.clear();
  if (all_default(scene.arc_filters)) scene.arc_filters.clear();
  // Likewise the motions: none kept where no wall moves.
  const auto none_moves = [](const std::vector<std::optional<WallMotion>>& motions) {
    return std::none_of(motions.begin(), motions.end(),
                        [](const std::optional<WallMotion>& m) { return m.has_value(); });
  };
  if (none_moves(scene.segment_motions)) scene.segment_motions.clear();
  if (none_moves(scene.arc_motions)) scene.arc_motions.clear();
  read_array(top, "pockets", scene.pockets, read_pocket);
  read_array(top, "sensors", scene.sensors, read_sensor);
  read_array(top, "generators", scene.generators, read_generator);
  scene.thermostat = read_thermostat(top);
  read_array(top, "shots", scene.shots,
             [&scene](const JsonSource& text, const nlohmann::json& item, const JsonPath& at) {
               return read_shot(text, item, at, scene.time);
             });
  if (scene.balls.size() > kMaxSceneBalls) {
    top.fail("balls", "holds more than " + std::to_string(kMaxSceneBalls) + " balls");
  }
  try {
    static_cast<void>(scene_detail::check_scene(scene));
  } catch (const scene_detail::PathedSceneError& error) {
    throw source.located(error, error.where());
  }
  return scene;
}

Scene load_scene(const std::filesystem::path& path) {
  // A folder opens as a stream on Linux and then reads as nothing: say what it is instead.
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    throw SceneError({path.string(), 0, 0, "", "", "is a folder, not a scene file", ""});
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw SceneError(
        {path.string(), 0, 0, "", "", std::string("cannot open: ") + std::strerror(errno), ""});
  }
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) {
    throw SceneError({path.string(), 0, 0, "", "", "cannot read", ""});
  }
  return parse_scene(content.str(), path.string());
}

}  // namespace carom
