// Writing a scene as JSON. Doubles are written in their shortest round-trip form (std::to_chars),
// always with a '.' or an exponent so that they read back as doubles ("-0.0" stays negative
// zero), hence parse_scene(to_json_text(s)) gives s back bit for bit.
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "carom/atomic_file.hpp"
#include "carom/scene.hpp"
#include "scene_geometry.hpp"

namespace carom {
namespace {

using carom::number_text;

std::string num(double value) {
  if (value == kImmovable) return "\"immovable\"";
  std::string text = number_text(value);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::string str(const std::string& text) { return nlohmann::json(text).dump(); }

std::string vec(Vec2 v) { return "[" + num(v.x) + ", " + num(v.y) + "]"; }

// Whether v differs from +0 in any bit (negative zero included, so that it round-trips too).
bool any_bit_set(Vec2 v) {
  return v.x != 0.0 || v.y != 0.0 || std::signbit(v.x) || std::signbit(v.y);
}

bool any_bit_set(Spin s) { return any_bit_set(Vec2{s.x, s.y}) || s.z != 0.0 || std::signbit(s.z); }

// Members of one JSON object on one line: "key": value, ...
class Line {
 public:
  Line& add(std::string_view key, const std::string& value) {
    text_ += (text_.empty() ? "{" : ", ") + std::string("\"") + std::string(key) + "\": " + value;
    return *this;
  }
  [[nodiscard]] std::string done() const { return text_.empty() ? "{}" : text_ + "}"; }

 private:
  std::string text_;
};

std::string boundary_text(Boundary boundary) {
  switch (boundary) {
    case Boundary::box:
      return "\"box\"";
    case Boundary::periodic:
      return "\"periodic\"";
    default:
      return "\"open\"";
  }
}

// A non-default filter as "filter": {its non-default fields}; nothing for the default.
void add_filter(Line& line, const CollisionFilter& f) {
  if (f == CollisionFilter{}) return;
  Line filter;
  const CollisionFilter defaults;
  if (f.category != defaults.category) filter.add("category", std::to_string(f.category));
  if (f.mask != defaults.mask) filter.add("mask", std::to_string(f.mask));
  if (f.group != defaults.group) filter.add("group", std::to_string(f.group));
  line.add("filter", filter.done());
}

// A wall's motion, every field written (a duration only when it ends).
void add_motion(Line& line, const std::optional<WallMotion>& motion) {
  if (!motion) return;
  Line fields;
  fields.add("velocity", vec(motion->velocity))
      .add("angular_velocity", num(motion->angular_velocity))
      .add("pivot", vec(motion->pivot));
  if (std::isfinite(motion->duration)) fields.add("duration", num(motion->duration));
  line.add("motion", fields.done());
}

std::string ball_line(const SceneBall& b) {
  Line line;
  if (b.name) line.add("name", str(*b.name));
  line.add("position", vec(b.position)).add("velocity", vec(b.velocity));
  line.add("radius", num(b.radius)).add("mass", num(b.mass));
  if (b.restitution) line.add("restitution", num(*b.restitution));
  if (b.color) line.add("color", str(*b.color));
  add_filter(line, b.filter);
  if (any_bit_set(b.spin)) {
    line.add("spin", "[" + num(b.spin.x) + ", " + num(b.spin.y) + ", " + num(b.spin.z) + "]");
  }
  return line.done();
}

std::string polyline_line(const ScenePolyline& p) {
  std::string points = "[";
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    points += (i == 0 ? "" : ", ") + vec(p.points[i]);
  }
  Line line;
  line.add("points", points + "]").add("closed", p.closed ? "true" : "false");
  add_filter(line, p.filter);
  return line.done();
}

std::string velocities_line(const SceneVelocities& v) {
  Line line;
  switch (v.distribution) {
    case VelocityDistribution::uniform_direction:
      line.add("distribution", "\"uniform_direction\"");
      break;
    case VelocityDistribution::maxwell_boltzmann:
      line.add("distribution", "\"maxwell_boltzmann\"");
      break;
    default:
      line.add("distribution", "\"fixed\"");
  }
  line.add("value", vec(v.value)).add("speed", num(v.speed));
  line.add("temperature", num(v.temperature));
  return line.add("zero_momentum", v.zero_momentum ? "true" : "false").done();
}

std::string generator_line(const SceneGenerator& g) {
  Line line;
  if (g.name) line.add("name", str(*g.name));
  line.add("placement", g.placement == GeneratorPlacement::random ? "\"random\"" : "\"lattice\"");
  line.add("count", std::to_string(g.count));
  if (g.radius) line.add("radius", num(*g.radius));
  if (g.packing_fraction) line.add("packing_fraction", num(*g.packing_fraction));
  if (g.region_lower && g.region_upper) {
    line.add("region",
             Line().add("lower", vec(*g.region_lower)).add("upper", vec(*g.region_upper)).done());
  }
  line.add("mass", num(g.mass));
  if (g.restitution) line.add("restitution", num(*g.restitution));
  if (g.color) line.add("color", str(*g.color));
  line.add("velocity", velocities_line(g.velocities));
  return line.add("seed", std::to_string(g.seed)).done();
}

// "  \"key\": [\n    item,\n    item\n  ]" (nothing when empty).
template <typename Item, typename Write>
void write_array(std::string& out, std::string_view key, const std::vector<Item>& items,
                 Write write) {
  if (items.empty()) return;
  out += ",\n  \"" + std::string(key) + "\": [\n";
  for (std::size_t i = 0; i < items.size(); ++i) {
    out += "    " + write(items[i]) + (i + 1 < items.size() ? ",\n" : "\n");
  }
  out += "  ]";
}

}  // namespace

std::string to_json_text(const Scene& scene) {
  std::string out = "{\n  \"carom_scene\": " + std::to_string(kSceneFormatVersion);
  if (!scene.description.empty()) out += ",\n  \"description\": " + str(scene.description);
  out += ",\n  \"units\": " + Line()
                                  .add("length", str(scene.units.length))
                                  .add("time", str(scene.units.time))
                                  .add("mass", str(scene.units.mass))
                                  .done();
  const WorldDef& w = scene.world;
  Line world;
  world.add("boundary", boundary_text(w.boundary))
      .add("lower", vec(w.lower))
      .add("upper", vec(w.upper))
      .add("restitution", num(w.restitution))
      .add("collapse_time", num(w.collapse_time))
      .add("cell_size", num(w.cell_size));
  // Only when set, so that a scene without gravity writes the same bytes as a file without the key.
  if (any_bit_set(w.gravity)) world.add("gravity", vec(w.gravity));
  // Only when not the world's default, so that a scene that leaves it out writes no key either.
  if (w.rest_height != WorldDef{}.rest_height) world.add("rest_height", num(w.rest_height));
  if (w.growth_rate != 0.0) world.add("growth_rate", num(w.growth_rate));
  if (w.table) {
    const Table& t = *w.table;
    world.add("table", Line()
                           .add("g", num(t.g))
                           .add("sliding_friction", num(t.sliding_friction))
                           .add("rolling_friction", num(t.rolling_friction))
                           .add("spinning_friction", num(t.spinning_friction))
                           .add("ball_friction", num(t.ball_friction))
                           .add("cushion_height", num(t.cushion_height))
                           .add("cushion_restitution", num(t.cushion_restitution))
                           .add("cushion_friction", num(t.cushion_friction))
                           .add("contact_time", num(t.contact_time))
                           .done());
  }
  out += ",\n  \"world\": " + world.done();
  out += ",\n  \"time\": " + num(scene.time);
  write_array(out, "balls", scene.balls, ball_line);
  std::size_t segment = 0;
  write_array(out, "segments", scene.segments, [&](const Segment& s) {
    Line line;
    line.add("a", vec(s.a)).add("b", vec(s.b));
    if (!scene.segment_filters.empty()) add_filter(line, scene.segment_filters[segment]);
    if (!scene.segment_motions.empty()) add_motion(line, scene.segment_motions[segment]);
    ++segment;
    return line.done();
  });
  write_array(out, "polylines", scene.polylines, polyline_line);
  std::size_t arc = 0;
  write_array(out, "arcs", scene.arcs, [&](const Arc& a) {
    Line line;
    line.add("center", vec(a.center))
        .add("radius", num(a.radius))
        .add("start_angle", num(a.start_angle))
        .add("end_angle", num(a.end_angle));
    if (!scene.arc_filters.empty()) add_filter(line, scene.arc_filters[arc]);
    if (!scene.arc_motions.empty()) add_motion(line, scene.arc_motions[arc]);
    ++arc;
    return line.done();
  });
  write_array(out, "pockets", scene.pockets, [](const ScenePocket& p) {
    Line line;
    if (p.name) line.add("name", str(*p.name));
    return line.add("position", vec(p.position)).add("radius", num(p.radius)).done();
  });
  write_array(out, "sensors", scene.sensors, [&](const SceneSensor& sensor) {
    Line line;
    if (sensor.name) line.add("name", str(*sensor.name));
    if (const auto* s = std::get_if<Segment>(&sensor.shape)) {
      line.add("shape", str("segment")).add("a", vec(s->a)).add("b", vec(s->b));
    } else if (const auto* a = std::get_if<Arc>(&sensor.shape)) {
      line.add("shape", str("arc"))
          .add("center", vec(a->center))
          .add("radius", num(a->radius))
          .add("start_angle", num(a->start_angle))
          .add("end_angle", num(a->end_angle));
    } else {
      const Ball& disc = std::get<Ball>(sensor.shape);
      line.add("shape", str("disc"))
          .add("center", vec(disc.center))
          .add("radius", num(disc.radius));
    }
    if (sensor.action == SensorAction::remove_ball) line.add("action", str("remove_ball"));
    add_filter(line, sensor.filter);
    return line.done();
  });
  if (scene.thermostat) {
    Line thermostat;
    thermostat.add("temperature", num(scene.thermostat->temperature));
    if (scene.thermostat->interval) thermostat.add("interval", num(*scene.thermostat->interval));
    if (scene.thermostat->collisions) {
      thermostat.add("collisions", std::to_string(*scene.thermostat->collisions));
    }
    out += ",\n  \"thermostat\": " + thermostat.done();
  }
  write_array(out, "generators", scene.generators, generator_line);
  write_array(out, "shots", scene.shots, [](const SceneShot& shot) {
    return Line()
        .add("ball", str(shot.ball))
        .add("time", num(shot.time))
        .add("speed", num(shot.cue.speed))
        .add("direction", num(shot.cue.direction))
        .add("elevation", num(shot.cue.elevation))
        .add("side", num(shot.cue.side))
        .add("height", num(shot.cue.height))
        .add("cue_mass", num(shot.cue.cue_mass))
        .add("restitution", num(shot.cue.restitution))
        .done();
  });
  out += "\n}\n";
  return out;
}

void save_scene(const Scene& scene, const std::filesystem::path& path) {
  try {
    write_file_atomically(path, to_json_text(scene));
  } catch (const FileError& error) {
    throw SceneError({path.string(), 0, 0, "", "", error.reason(), ""});
  }
}

}  // namespace carom
