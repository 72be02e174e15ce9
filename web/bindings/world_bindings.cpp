// carom web: carom::World as the "Many balls", "Galton board" and "Pinball" pages use it, through
// DrawnWorld.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include "drawn_world.hpp"
#include "js_error.hpp"
#include "lattice_filling.hpp"
#include "scene_loading.hpp"

namespace carom::web {
namespace {

DrawnWorld* make_world(const WorldDef& def) {
  return guarded_call([&] { return new DrawnWorld(def); });
}

// The scene library's SceneError reaches the page as an Error with the same message.
DrawnWorld* load_scene(const std::string& text, const std::string& name) {
  return guarded_call([&] { return new DrawnWorld(load_drawn_scene(text, name)); });
}

int fill(DrawnWorld& w, const LatticeFilling& filling) {
  return guarded_call([&] { return fill_lattice(w, filling); });
}

int add_ball(DrawnWorld& w, Vec2 position, Vec2 velocity, double radius, double mass) {
  return guarded_call([&] { return w.add_ball(position, velocity, radius, mass); });
}
void add_segment(DrawnWorld& w, const Segment& s) {
  guarded_call([&] { w.add_segment(s); });
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
  value_object<LatticeFilling>("LatticeFilling")
      .field("count", &LatticeFilling::count)
      .field("packing_fraction", &LatticeFilling::packing_fraction)
      .field("speed", &LatticeFilling::speed)
      .field("seed", &LatticeFilling::seed);

  emscripten::function("load_scene", &load_scene, emscripten::allow_raw_pointers());
  emscripten::class_<DrawnWorld>("DrawnWorld")
      .constructor(&make_world, emscripten::allow_raw_pointers())
      .function("add_ball", &add_ball)
      .function("add_segment", &add_segment)
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
      .function("audit", &audit);
}

}  // namespace carom::web
