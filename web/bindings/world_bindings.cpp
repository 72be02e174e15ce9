// carom web: carom::World as the "Many balls", "Galton board", "Pinball" and "Compression" pages
// use it, through DrawnWorld.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "carom/error.hpp"
#include "carom/science/contact_network.hpp"
#include "carom/science/packing.hpp"
#include "compression.hpp"
#include "drawn_world.hpp"
#include "js_error.hpp"
#include "lattice_filling.hpp"
#include "scene_loading.hpp"
#include "table_bindings.hpp"
#include "world_queries.hpp"

namespace carom::web {
namespace {

DrawnWorld* make_world(const WorldDef& def) {
  return guarded_call([&] { return new DrawnWorld(def); });
}

// The scene library's SceneError reaches the page as an Error with the same message.
DrawnWorld* load_scene(const std::string& text, const std::string& name) {
  return guarded_call([&] { return new DrawnWorld(load_drawn_scene(text, name)); });
}

DrawnWorld* make_packing_world(const PackingStart& start) {
  return guarded_call([&] { return new DrawnWorld(make_packing(start)); });
}

int fill(DrawnWorld& w, const LatticeFilling& filling) {
  return guarded_call([&] { return fill_lattice(w, filling); });
}

int add_ball(DrawnWorld& w, Vec2 position, Vec2 velocity, double radius, double mass) {
  return guarded_call([&] { return w.add_ball(position, velocity, radius, mass); });
}
int add_segment(DrawnWorld& w, const Segment& s) {
  return guarded_call([&] { return w.add_segment(s); });
}
// A wall id from JavaScript: a negative one is refused as given, not as a huge unsigned number.
WallId wall_id(const char* function, int wall) {
  if (wall < 0) {
    throw InvalidArgument(function, "wall", std::to_string(wall), "must be a wall id >= 0");
  }
  return static_cast<WallId>(wall);
}
// World::set_wall_motion between steps (a pinball flipper): motion.duration may be Infinity.
void set_wall_motion(DrawnWorld& w, int wall, const WallMotion& motion) {
  guarded_call(
      [&] { w.world().set_wall_motion(wall_id("DrawnWorld::set_wall_motion", wall), motion); });
}
WallMotion wall_motion(const DrawnWorld& w, int wall) {
  return guarded_call(
      [&] { return w.world().wall_motion(wall_id("DrawnWorld::wall_motion", wall)); });
}
// A segment wall where it is now (a moving one's too).
Segment wall_segment(const DrawnWorld& w, int wall) {
  return guarded_call([&] {
    constexpr const char* kFunction = "DrawnWorld::wall_segment";
    const auto shape = w.world().wall(wall_id(kFunction, wall));
    const auto* segment = std::get_if<Segment>(&shape);
    if (segment == nullptr) {
      throw InvalidArgument(kFunction, "wall", std::to_string(wall), "must name a segment");
    }
    return *segment;
  });
}
int add_sensor(DrawnWorld& w, const Segment& s, bool removes) {
  return guarded_call([&] { return w.add_sensor(s, removes); });
}
// The last step's sensor events as {time, enter, ball (index), sensor (wall id), removed}.
emscripten::val sensor_events(const DrawnWorld& w) {
  emscripten::val out = emscripten::val::array();
  for (const SensorEvent& e : w.step_sensor_events()) {
    emscripten::val event = emscripten::val::object();
    event.set("time", e.time);
    event.set("enter", e.kind == SensorEventKind::enter);
    event.set("ball", w.index_of(e.ball));
    event.set("sensor", e.sensor);
    event.set("removed", e.removed);
    out.call<void>("push", event);
  }
  return out;
}
void add_arc(DrawnWorld& w, const Arc& a) {
  guarded_call([&] { w.add_arc(a); });
}
void remove_ball(DrawnWorld& w, int index) {
  guarded_call([&] { w.remove_ball(index); });
}
double step(DrawnWorld& w, double dt) {
  return guarded_call([&] { return w.step(dt); });
}
void scale_speeds(DrawnWorld& w, double factor) {
  guarded_call([&] { w.scale_speeds(factor); });
}
void set_velocity(DrawnWorld& w, int index, Vec2 velocity) {
  guarded_call([&] { w.set_velocity(index, velocity); });
}
void set_gravity(DrawnWorld& w, Vec2 gravity) {
  guarded_call([&] { w.set_gravity(gravity); });
}
int ball_at(const DrawnWorld& w, Vec2 point) {
  return guarded_call([&] { return w.ball_at(point); });
}
void hold(DrawnWorld& w, int index) {
  guarded_call([&] { w.hold(index); });
}
Vec2 drag_to(DrawnWorld& w, int index, Vec2 point) {
  return guarded_call([&] { return w.drag_to(index, point); });
}
void release(DrawnWorld& w, int index) {
  guarded_call([&] { w.release(index); });
}
Vec2 position(const DrawnWorld& w, int index) {
  return guarded_call([&] { return w.position(index); });
}
Vec2 velocity(const DrawnWorld& w, int index) {
  return guarded_call([&] { return w.velocity(index); });
}
double mass(const DrawnWorld& w, int index) {
  return guarded_call([&] { return w.world().mass(w.handle(index)); });
}
double radius(const DrawnWorld& w, int index) {
  return guarded_call([&] { return w.world().radius(w.handle(index)); });
}

// A Float32Array over the module's memory: no copy. It is valid until the next call into the
// module, which may grow (and so move) the memory.
emscripten::val snapshot(DrawnWorld& w) {
  const std::span<const float> data = w.snapshot();
  return emscripten::val(emscripten::typed_memory_view(data.size(), data.data()));
}

emscripten::val segments(const DrawnWorld& w) {
  emscripten::val out = emscripten::val::array();
  for (const Segment& s : w.segments()) out.call<void>("push", s);
  return out;
}

emscripten::val arcs(const DrawnWorld& w) {
  emscripten::val out = emscripten::val::array();
  for (const Arc& a : w.arcs()) out.call<void>("push", a);
  return out;
}

emscripten::val colors(const DrawnWorld& w) {
  emscripten::val out = emscripten::val::array();
  for (const std::string& color : w.colors()) out.call<void>("push", color);
  return out;
}

emscripten::val pockets(const DrawnWorld& w) {
  emscripten::val out = emscripten::val::array();
  for (const ScenePocket& p : w.pockets()) {
    emscripten::val pocket = emscripten::val::object();
    pocket.set("x", p.position.x);
    pocket.set("y", p.position.y);
    pocket.set("radius", p.radius);
    out.call<void>("push", pocket);
  }
  return out;
}

WorldDef def(const DrawnWorld& w) { return w.def(); }
double world_time(const DrawnWorld& w) { return w.world().time(); }
double kinetic_energy(const DrawnWorld& w) { return w.world().kinetic_energy(); }
double potential_energy(const DrawnWorld& w) { return w.world().potential_energy(); }
Vec2 momentum(const DrawnWorld& w) { return w.world().momentum(); }
// As a double: JavaScript numbers hold integers exactly up to 2⁵³.
double collision_count(const DrawnWorld& w) {
  return static_cast<double>(w.world().collision_count());
}
std::string audit(const DrawnWorld& w) { return w.world().audit().value_or(""); }

// ---- growth, the thermostat and packings (the "Compression" page) ----
CompressionFrameResult run_compression_frame(DrawnWorld& w, const CompressionFrame& frame) {
  return guarded_call([&] { return compress_frame(w, frame); });
}
void set_growth_rate(DrawnWorld& w, double rate) {
  guarded_call([&] { w.world().set_growth_rate(rate); });
}
double growth_rate(const DrawnWorld& w) { return w.world().growth_rate_from_now(); }
// Returns the work done, the change of kinetic energy.
double set_temperature(DrawnWorld& w, double kT) {
  return guarded_call([&] { return w.world().set_temperature(kT); });
}
double packing_fraction(const DrawnWorld& w) {
  return guarded_call([&] { return science::packing_fraction(w.world()); });
}
double psi6(const DrawnWorld& w) {
  return guarded_call([&] { return science::global_psi6(w.world()); });
}

// A copy in a JavaScript typed array of its own: a view of the module's memory would not outlive
// the network.
template <typename T>
emscripten::val typed_copy(const std::vector<T>& values) {
  return emscripten::val(emscripten::typed_memory_view(values.size(), values.data()))
      .call<emscripten::val>("slice");
}

// science::find_contact_network of the world now, indexed as World::balls() (the page's ball
// indices for a packing, and for any world no ball has left): pairs as a flat Uint32Array (a, b,
// a, b, ...), each ball's contacts (walls included) and rattler flag, and the counts.
emscripten::val contact_network(const DrawnWorld& w, double tolerance) {
  const science::ContactNetwork network =
      guarded_call([&] { return science::find_contact_network(w.world(), tolerance); });
  std::vector<std::uint32_t> pairs;
  pairs.reserve(2 * network.pairs.size());
  for (const science::ContactNetwork::Pair& pair : network.pairs) {
    pairs.push_back(pair.a);
    pairs.push_back(pair.b);
  }
  emscripten::val out = emscripten::val::object();
  out.set("pairs", typed_copy(pairs));
  out.set("contacts", typed_copy(network.contacts));
  out.set("rattler", typed_copy(network.rattler));
  out.set("rattlers", static_cast<double>(network.rattlers));
  out.set("wall_contacts", static_cast<double>(network.wall_contacts));
  out.set("mean_contacts_of_rest", network.mean_contacts_of_rest);
  out.set("mean_contacts", network.mean_contacts);
  return out;
}

}  // namespace

EMSCRIPTEN_BINDINGS(carom_world) {
  using emscripten::value_object;

  emscripten::enum_<Boundary>("Boundary")
      .value("open", Boundary::open)
      .value("box", Boundary::box)
      .value("periodic", Boundary::periodic);
  value_object<WorldDef>("WorldDef")
      .field("boundary", &WorldDef::boundary)
      .field("lower", &WorldDef::lower)
      .field("upper", &WorldDef::upper)
      .field("restitution", &WorldDef::restitution)
      .field("collapse_time", &WorldDef::collapse_time)
      .field("cell_size", &WorldDef::cell_size)
      .field("gravity", &WorldDef::gravity)
      .field("rest_height", &WorldDef::rest_height);
  value_object<PackingStart>("PackingStart")
      .field("count", &PackingStart::count)
      .field("second_diameter", &PackingStart::second_diameter)
      .field("second_fraction", &PackingStart::second_fraction)
      .field("boundary", &PackingStart::boundary)
      .field("aspect", &PackingStart::aspect)
      .field("start_eta", &PackingStart::start_eta)
      .field("sized_for_eta", &PackingStart::sized_for_eta)
      .field("seed", &PackingStart::seed);
  value_object<CompressionFrame>("CompressionFrame")
      .field("rate", &CompressionFrame::rate)
      .field("kT", &CompressionFrame::kT)
      .field("until", &CompressionFrame::until)
      .field("collisions", &CompressionFrame::collisions)
      .field("pressure_limit", &CompressionFrame::pressure_limit);
  value_object<CompressionFrameResult>("CompressionFrameResult")
      .field("collisions", &CompressionFrameResult::collisions)
      .field("time", &CompressionFrameResult::time)
      .field("virial", &CompressionFrameResult::virial)
      .field("pressure", &CompressionFrameResult::pressure)
      .field("window_pressure", &CompressionFrameResult::window_pressure)
      .field("work", &CompressionFrameResult::work)
      .field("over_pressure_limit", &CompressionFrameResult::over_pressure_limit)
      .field("stalled", &CompressionFrameResult::stalled);
  value_object<LatticeFilling>("LatticeFilling")
      .field("count", &LatticeFilling::count)
      .field("packing_fraction", &LatticeFilling::packing_fraction)
      .field("speed", &LatticeFilling::speed)
      .field("seed", &LatticeFilling::seed);

  emscripten::function("load_scene", &load_scene, emscripten::allow_raw_pointers());
  emscripten::function("make_packing", &make_packing_world, emscripten::allow_raw_pointers());
  emscripten::function("contact_tolerance_at_pressure", &science::contact_tolerance_at_pressure);
  emscripten::class_<DrawnWorld>("DrawnWorld")
      .constructor(&make_world, emscripten::allow_raw_pointers())
      .function("add_ball", &add_ball)
      .function("add_segment", &add_segment)
      .function("add_sensor_segment", &add_sensor)
      .function("set_wall_motion", &set_wall_motion)
      .function("wall_motion", &wall_motion)
      .function("wall_segment", &wall_segment)
      .function("sensor_events", &sensor_events)
      .function("add_arc", &add_arc)
      .function("remove_ball", &remove_ball)
      .function("fill_lattice", &fill)
      .function("step", &step)
      .function("scale_speeds", &scale_speeds)
      .function("set_velocity", &set_velocity)
      .function("set_gravity", &set_gravity)
      .function("ball_at", &ball_at)
      .function("hold", &hold)
      .function("drag_to", &drag_to)
      .function("release", &release)
      .function("position", &position)
      .function("velocity", &velocity)
      .function("mass", &mass)
      .function("radius", &radius)
      .function("snapshot", &snapshot)
      .function("segments", &segments)
      .function("arcs", &arcs)
      .function("colors", &colors)
      .function("pockets", &pockets)
      .function("def", &def)
      .function("ball_count", &DrawnWorld::ball_count)
      .function("last_step_contacts", &DrawnWorld::last_step_contacts)
      .function("time", &world_time)
      .function("kinetic_energy", &kinetic_energy)
      .function("potential_energy", &potential_energy)
      .function("momentum", &momentum)
      .function("collision_count", &collision_count)
      .function("audit", &audit)
      .function("compress_frame", &run_compression_frame)
      .function("set_growth_rate", &set_growth_rate)
      .function("growth_rate", &growth_rate)
      .function("set_temperature", &set_temperature)
      .function("packing_fraction", &packing_fraction)
      .function("psi6", &psi6)
      .function("contact_network", &contact_network)
      .function("cast_ball", &cast_ball)
      .function("balls_in_circle", &balls_in_circle)
      .function("step_contacts", &step_contacts)
      .function("copy", &copy_world, emscripten::allow_raw_pointers())
      .function("strike", &strike)
      .function("spin", &spin)
      .function("set_spin", &set_spin)
      .function("motion_state", &motion_state)
      .function("at_rest", &at_rest)
      .function("table", &table);
}

}  // namespace carom::web
