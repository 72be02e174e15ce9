#include "table_bindings.hpp"

#include <optional>
#include <string>

#include "carom/error.hpp"
#include "carom/table.hpp"
#include "js_error.hpp"

namespace carom::web {
namespace {

using emscripten::val;

// object[key] as a number, `fallback` when absent; anything else is refused by name.
double number_field(const char* function, const val& object, const char* key, double fallback) {
  const val value = object[std::string(key)];
  if (value.isUndefined()) return fallback;
  if (!value.isNumber()) {
    throw InvalidArgument(function, key, value.call<std::string>("toString"), "must be a number");
  }
  return value.as<double>();
}

void require_object(const char* function, const char* argument, const val& object) {
  if (object.typeOf().as<std::string>() != "object" || object.isNull()) {
    throw InvalidArgument(function, argument, "not an object", "must be an object");
  }
}

}  // namespace

void strike(DrawnWorld& w, int index, const val& cue) {
  guarded_call([&] {
    constexpr const char* kFunction = "DrawnWorld::strike";
    require_object(kFunction, "cue", cue);
    if (cue["speed"].isUndefined()) {
      throw InvalidArgument(kFunction, "speed", "absent", "must be given, a number");
    }
    const CueStrike defaults;
    const CueStrike strike{
        .speed = number_field(kFunction, cue, "speed", defaults.speed),
        .direction = number_field(kFunction, cue, "direction", defaults.direction),
        .elevation = number_field(kFunction, cue, "elevation", defaults.elevation),
        .side = number_field(kFunction, cue, "side", defaults.side),
        .height = number_field(kFunction, cue, "height", defaults.height),
        .cue_mass = number_field(kFunction, cue, "cue_mass", defaults.cue_mass),
        .restitution = number_field(kFunction, cue, "restitution", defaults.restitution)};
    w.world().strike(w.handle(index), strike);
  });
}

val spin(const DrawnWorld& w, int index) {
  return guarded_call([&] {
    const Spin s = w.world().spin(w.handle(index));
    val out = val::object();
    out.set("x", s.x);
    out.set("y", s.y);
    out.set("z", s.z);
    return out;
  });
}

void set_spin(DrawnWorld& w, int index, const val& spin) {
  guarded_call([&] {
    constexpr const char* kFunction = "DrawnWorld::set_spin";
    require_object(kFunction, "spin", spin);
    w.world().set_spin(w.handle(index), {.x = number_field(kFunction, spin, "x", 0.0),
                                         .y = number_field(kFunction, spin, "y", 0.0),
                                         .z = number_field(kFunction, spin, "z", 0.0)});
  });
}

std::string motion_state(const DrawnWorld& w, int index) {
  return guarded_call(
      [&] { return std::string(motion_state_name(w.world().motion_state(w.handle(index)))); });
}

bool at_rest(const DrawnWorld& w) { return w.world().at_rest(); }

val table(const DrawnWorld& w) {
  const std::optional<Table>& table = w.def().table;
  if (!table) return val::null();
  val out = val::object();
  out.set("g", table->g);
  out.set("sliding_friction", table->sliding_friction);
  out.set("rolling_friction", table->rolling_friction);
  out.set("spinning_friction", table->spinning_friction);
  out.set("ball_friction", table->ball_friction);
  out.set("cushion_height", table->cushion_height);
  out.set("cushion_restitution", table->cushion_restitution);
  out.set("cushion_friction", table->cushion_friction);
  out.set("contact_time", table->contact_time);
  return out;
}

DrawnWorld* copy_world(const DrawnWorld& w) {
  return guarded_call([&] { return new DrawnWorld(w.copy()); });
}

}  // namespace carom::web
