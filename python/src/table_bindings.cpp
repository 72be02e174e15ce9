// carom for Python: the billiards table (carom/table.hpp) — carom.Table, carom.MotionEvent, and
// the World's table methods (spin, motion_state, set_spin, strike, motion_events, at_rest).
#include <pybind11/stl.h>

#include <array>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "carom/table.hpp"

namespace carom::python {
namespace {

std::string table_repr(const Table& t) {
  const auto number = [](double value) { return py::repr(py::float_(value)).cast<std::string>(); };
  return "carom.Table(g=" + number(t.g) + ", sliding_friction=" + number(t.sliding_friction) +
         ", rolling_friction=" + number(t.rolling_friction) +
         ", spinning_friction=" + number(t.spinning_friction) +
         ", ball_friction=" + number(t.ball_friction) +
         ", cushion_height=" + number(t.cushion_height) +
         ", cushion_restitution=" + number(t.cushion_restitution) +
         ", cushion_friction=" + number(t.cushion_friction) +
         ", contact_time=" + number(t.contact_time) + ")";
}

py::tuple spin_tuple(const Spin& s) { return py::make_tuple(s.x, s.y, s.z); }

// A method of carom.World written here, on the class bind_world made.
template <typename Function, typename... Extra>
void add_world_method(py::object& world_class, const char* name, Function&& function,
                      const Extra&... extra) {
  world_class.attr(name) =
      py::cpp_function(std::forward<Function>(function), py::name(name), py::is_method(world_class),
                       py::sibling(py::getattr(world_class, name, py::none())), extra...);
}

}  // namespace

void bind_table_types(py::module_& m) {
  const Table defaults;
  py::class_<Table>(m, "Table",
                    "A billiards table (World(table=...)): the cloth's friction, the balls' "
                    "surfaces and the cushions, in the world's units (docs/pool.md)")
      .def(py::init([](double g, double sliding_friction, double rolling_friction,
                       double spinning_friction, double ball_friction, double cushion_height,
                       double cushion_restitution, double cushion_friction, double contact_time) {
             return Table{g,
                          sliding_friction,
                          rolling_friction,
                          spinning_friction,
                          ball_friction,
                          cushion_height,
                          cushion_restitution,
                          cushion_friction,
                          contact_time};
           }),
           py::kw_only(), py::arg("g") = defaults.g,
           py::arg("sliding_friction") = defaults.sliding_friction,
           py::arg("rolling_friction") = defaults.rolling_friction,
           py::arg("spinning_friction") = defaults.spinning_friction,
           py::arg("ball_friction") = defaults.ball_friction,
           py::arg("cushion_height") = defaults.cushion_height,
           py::arg("cushion_restitution") = defaults.cushion_restitution,
           py::arg("cushion_friction") = defaults.cushion_friction,
           py::arg("contact_time") = defaults.contact_time)
      .def_readwrite("g", &Table::g, "Gravity normal to the cloth, > 0")
      .def_readwrite("sliding_friction", &Table::sliding_friction,
                     "The cloth against a slipping contact point")
      .def_readwrite("rolling_friction", &Table::rolling_friction, "Rolling resistance")
      .def_readwrite("spinning_friction", &Table::spinning_friction,
                     "Against the spin about the vertical")
      .def_readwrite("ball_friction", &Table::ball_friction, "Between two balls' surfaces (throw)")
      .def_readwrite("cushion_height", &Table::cushion_height,
                     "The cushion's nose above the cloth, a share of the ball's diameter in "
                     "[0.5, 1)")
      .def_readwrite("cushion_restitution", &Table::cushion_restitution,
                     "Ball against cushion, in [0, 1]")
      .def_readwrite("cushion_friction", &Table::cushion_friction, "Ball against cushion")
      .def_readwrite("contact_time", &Table::contact_time,
                     "How long a contact lasts: the world's collapse_time unless one is given")
      .def(
          "__eq__", [](const Table& a, const Table& b) { return a == b; }, "Equal in every field")
      .def("__repr__", &table_repr);

  py::class_<MotionEvent>(m, "MotionEvent",
                          "A ball's change of motion state on a table (World.motion_events), "
                          "read-only")
      .def_readonly("time", &MotionEvent::time, "When, exactly")
      .def_property_readonly(
          "ball", [](const MotionEvent& e) { return id_number(e.ball); }, "The ball's id")
      .def_property_readonly(
          "from_state", [](const MotionEvent& e) { return motion_state_name(e.from); },
          "\"sliding\", \"rolling\", \"spinning\" or \"stationary\"")
      .def_property_readonly(
          "to_state", [](const MotionEvent& e) { return motion_state_name(e.to); },
          "\"sliding\", \"rolling\", \"spinning\" or \"stationary\"")
      .def("__repr__", [](const MotionEvent& e) {
        return "carom.MotionEvent(time=" + py::repr(py::float_(e.time)).cast<std::string>() +
               ", ball=" + std::to_string(id_number(e.ball)) + ", from_state='" +
               motion_state_name(e.from) + "', to_state='" + motion_state_name(e.to) + "')";
      });
}

void bind_table_methods(py::module_& m) {
  py::object world_class = m.attr("World");
  add_world_method(
      world_class, "spin",
      [](py::handle self, std::uint64_t id) {
        return spin_tuple(unwrap_world(self).spin(ball_id(id)));
      },
      py::arg("id"),
      "On a table, a ball's angular velocity (x, y about the table's axes, z about the "
      "vertical)");
  add_world_method(
      world_class, "motion_state",
      [](py::handle self, std::uint64_t id) {
        return motion_state_name(unwrap_world(self).motion_state(ball_id(id)));
      },
      py::arg("id"),
      "On a table, a ball's state: \"sliding\", \"rolling\", \"spinning\" or \"stationary\"");
  add_world_method(
      world_class, "set_spin",
      [](py::handle self, std::uint64_t id, std::array<double, 3> spin) {
        unwrap_world(self).set_spin(ball_id(id), {spin[0], spin[1], spin[2]});
      },
      py::arg("id"), py::arg("spin"),
      "On a table, sets a movable ball's angular velocity (x, y, z) from now");
  add_world_method(
      world_class, "strike",
      [](py::handle self, std::uint64_t id, double speed, double direction, double elevation,
         double side, double height, double cue_mass, double restitution) {
        CueStrike cue;
        cue.speed = speed;
        cue.direction = direction;
        cue.elevation = elevation;
        cue.side = side;
        cue.height = height;
        cue.cue_mass = cue_mass;
        cue.restitution = restitution;
        unwrap_world(self).strike(ball_id(id), cue);
      },
      py::arg("id"), py::kw_only(), py::arg("speed"), py::arg("direction") = 0.0,
      py::arg("elevation") = 0.0, py::arg("side") = 0.0, py::arg("height") = 0.0,
      py::arg("cue_mass") = CueStrike{}.cue_mass, py::arg("restitution") = CueStrike{}.restitution,
      "On a table, strikes a movable ball with the cue (speed along direction, radians; tilted "
      "elevation; the tip side to the right of and height above the centre): its velocity and "
      "spin are added to the ball's");
  // A property, as sensor_events is.
  world_class.attr("motion_events") =
      py::module_::import("builtins")
          .attr("property")(py::cpp_function(
              [](py::handle self) {
                const std::span<const MotionEvent> events = unwrap_world(self).motion_events();
                return std::vector<MotionEvent>(events.begin(), events.end());
              },
              py::name("motion_events"),
              "On a table, the last run's changes of motion state in order (a list of "
              "MotionEvent), recorded while contacts are"));
  add_world_method(
      world_class, "at_rest", [](py::handle self) { return unwrap_world(self).at_rest(); },
      "Whether nothing will move again by itself (every ball still, on a table spins too)");
}

}  // namespace carom::python
