// carom for Python: the World, with its state in and out as NumPy arrays in one call (no loop
// over balls in Python), its contacts as a structured array, and long runs that release the GIL
// and stop at Ctrl-C with the world consistent.
#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "carom/world.hpp"

namespace carom::python {

// A ball's handle as one integer, generation above index, so that ids travel in NumPy arrays
// (uint64) and a stale one stays stale.
std::uint64_t id_number(BallId id) {
  return (static_cast<std::uint64_t>(id.generation) << 32U) | id.index;
}

namespace {
BallId id_of(std::uint64_t number) {
  return {static_cast<std::uint32_t>(number & 0xffffffffU),
          static_cast<std::uint32_t>(number >> 32U)};
}

Boundary boundary_of(const std::string& name) {
  if (name == "open") return Boundary::open;
  if (name == "box") return Boundary::box;
  if (name == "periodic") return Boundary::periodic;
  throw py::value_error("boundary must be \"open\", \"box\" or \"periodic\", not \"" + name + "\"");
}
const char* boundary_name(Boundary b) {
  switch (b) {
    case Boundary::open:
      return "open";
    case Boundary::box:
      return "box";
    case Boundary::periodic:
      return "periodic";
  }
  return "open";
}

const char* stop_reason_name(StopReason reason) {
  switch (reason) {
    case StopReason::none:
      return "none";
    case StopReason::no_more_contacts:
      return "no_more_contacts";
    case StopReason::time_limit:
      return "time_limit";
    case StopReason::stop_condition:
      return "stop_condition";
    case StopReason::interrupted:
      return "interrupted";
  }
  return "none";
}

// The structured dtype of World.contacts: one record per ContactEvent.
py::dtype contact_dtype() {
  py::list fields;
  const auto add = [&fields](const char* name, const char* format) {
    fields.append(py::make_tuple(name, format));
  };
  add("time", "f8");
  add("kind", "u1");  // 0 ball-ball, 1 ball-wall
  add("a", "u8");
  add("b", "u8");
  add("wall", "u4");
  fields.append(py::make_tuple("point", "f8", 2));
  fields.append(py::make_tuple("normal", "f8", 2));
  add("approach_speed", "f8");
  add("impulse", "f8");
  // Aligned as a C struct, so that ContactRecord's layout is the record's.
  return py::module_::import("numpy").attr("dtype")(fields, py::arg("align") = true);
}

struct ContactRecord {
  double time;
  std::uint8_t kind;
  std::uint64_t a;
  std::uint64_t b;
  std::uint32_t wall;
  double point[2];
  double normal[2];
  double approach_speed;
  double impulse;
};

// A Python-side view of one contact, for stop conditions.
py::dict contact_dict(const ContactEvent& c) {
  py::dict d;
  d["time"] = c.time;
  d["kind"] = c.kind == ContactKind::ball_ball ? "ball_ball" : "ball_wall";
  d["a"] = id_number(c.a);
  d["b"] = c.kind == ContactKind::ball_ball ? py::object(py::int_(id_number(c.b))) : py::none();
  d["wall"] = c.kind == ContactKind::ball_wall ? py::object(py::int_(c.wall)) : py::none();
  d["point"] = c.point;
  d["normal"] = c.normal;
  d["approach_speed"] = c.approach_speed;
  d["impulse"] = c.impulse;
  return d;
}

// The World as Python holds it: the world itself, and whether a Python stop condition is set (a
// run then keeps the GIL, which the condition needs at every contact).
class PyWorld {
 public:
  explicit PyWorld(World world) : world_(std::move(world)) {}

  World& world() { return world_; }
  [[nodiscard]] const World& world() const { return world_; }

  void set_stop_condition(const std::optional<py::function>& condition) {
    python_condition_ = condition.has_value();
    if (!condition) {
      world_.set_stop_condition({});
      return;
    }
    const py::function& call = *condition;
    world_.set_stop_condition([call](const ContactEvent& contact) {
      // Called during a run that holds the GIL.
      return call(contact_dict(contact)).cast<bool>();
    });
  }

  // Runs `advance` with the GIL released (unless a Python stop condition needs it), looking for
  // Ctrl-C every World::kStopCheckEvents events; a signal stops the run at an event boundary and
  // is raised (KeyboardInterrupt) once the world is consistent.
  template <typename Advance>
  auto run(Advance advance) {
    bool signalled = false;
    PyObject* type = nullptr;
    PyObject* value = nullptr;
    PyObject* traceback = nullptr;
    const bool keep_gil = python_condition_;
    world_.set_progress_callback([&](const RunStatus&) {
      if (signalled) return true;
      std::optional<py::gil_scoped_acquire> locked;
      if (!keep_gil) locked.emplace();
      if (PyErr_CheckSignals() != 0) {
        signalled = true;
        PyErr_Fetch(&type, &value, &traceback);
      }
      return signalled;
    });
    decltype(advance()) result{};
    try {
      if (keep_gil) {
        result = advance();
      } else {
        const py::gil_scoped_release unlocked;
        result = advance();
      }
    } catch (...) {
      world_.set_progress_callback({});
      throw;
    }
    world_.set_progress_callback({});
    if (signalled) {
      PyErr_Restore(type, value, traceback);
      throw py::error_already_set();
    }
    return result;
  }

 private:
  World world_;
  bool python_condition_ = false;
};

WorldDef make_def(const std::string& boundary, Vec2 lower, Vec2 upper, double restitution,
                  double collapse_time, double cell_size, Vec2 gravity, double rest_height,
                  double growth_rate, const std::optional<Table>& table) {
  WorldDef def;
  def.boundary = boundary_of(boundary);
  def.lower = lower;
  def.upper = upper;
  def.restitution = restitution;
  def.collapse_time = collapse_time;
  def.cell_size = cell_size;
  def.gravity = gravity;
  def.rest_height = rest_height;
  def.growth_rate = growth_rate;
  def.table = table;
  return def;
}

py::dict def_dict(const WorldDef& d) {
  py::dict out;
  out["boundary"] = boundary_name(d.boundary);
  out["lower"] = d.lower;
  out["upper"] = d.upper;
  out["restitution"] = d.restitution;
  out["collapse_time"] = d.collapse_time;
  out["cell_size"] = d.cell_size;
  out["gravity"] = d.gravity;
  out["rest_height"] = d.rest_height;
  out["growth_rate"] = d.growth_rate;
  out["table"] = d.table ? py::cast(*d.table) : py::none();
  return out;
}

// A per-ball value given as one number for all or an array of N.
std::vector<double> per_ball(const py::object& value, py::ssize_t n, const char* name) {
  std::vector<double> out(static_cast<std::size_t>(n));
  if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) {
    std::fill(out.begin(), out.end(), value.cast<double>());
    return out;
  }
  const DoubleArray array = py::cast<DoubleArray>(value);
  if (array.ndim() != 1 || array.shape(0) != n) {
    throw py::value_error(std::string(name) + " must be a number or an array of shape (" +
                          std::to_string(n) + ",)");
  }
  std::memcpy(out.data(), array.data(), out.size() * sizeof(double));
  return out;
}

void require_points(const DoubleArray& array, const char* name, py::ssize_t n) {
  if (array.ndim() != 2 || array.shape(1) != 2 || (n >= 0 && array.shape(0) != n)) {
    throw py::value_error(std::string(name) + " must be an array of shape (N, 2)" +
                          (n >= 0 ? " with N = " + std::to_string(n) : ""));
  }
}

py::array_t<std::uint64_t> add_balls(PyWorld& self, const DoubleArray& positions,
                                     const std::optional<DoubleArray>& velocities,
                                     const py::object& radii, const py::object& masses,
                                     const py::object& restitution,
                                     const std::optional<py::array_t<std::uint64_t>>& user_data,
                                     const py::object& filter) {
  require_points(positions, "positions", -1);
  const py::ssize_t n = positions.shape(0);
  if (velocities) require_points(*velocities, "velocities", n);
  const std::vector<double> r = per_ball(radii, n, "radii");
  const std::vector<double> m = per_ball(masses, n, "masses");
  std::vector<double> e;
  if (!restitution.is_none()) e = per_ball(restitution, n, "restitution");
  if (user_data && (user_data->ndim() != 1 || user_data->shape(0) != n)) {
    throw py::value_error("user_data must be an array of shape (" + std::to_string(n) + ",)");
  }
  // One CollisionFilter for every ball, or a sequence of N of them.
  std::vector<CollisionFilter> filters;
  if (filter.is_none()) {
    filters.assign(1, CollisionFilter{});
  } else if (py::isinstance<CollisionFilter>(filter)) {
    filters.assign(1, filter.cast<CollisionFilter>());
  } else {
    try {
      filters = filter.cast<std::vector<CollisionFilter>>();
    } catch (const py::cast_error&) {
      throw py::type_error("filter must be a CollisionFilter or a sequence of them, not " +
                           std::string(py::str(py::type::of(filter).attr("__name__"))));
    }
    if (static_cast<py::ssize_t>(filters.size()) != n) {
      throw py::value_error("filter must be a CollisionFilter or a sequence of " +
                            std::to_string(n) + " of them");
    }
  }
  const auto p = positions.unchecked<2>();
  py::array_t<std::uint64_t> ids(n);
  auto out = ids.mutable_unchecked<1>();
  World& world = self.world();
  world.reserve(world.ball_count() + static_cast<std::size_t>(n));
  for (py::ssize_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    BallDef def;
    def.position = {p(i, 0), p(i, 1)};
    if (velocities) {
      const auto v = velocities->unchecked<2>();
      def.velocity = {v(i, 0), v(i, 1)};
    }
    def.radius = r[k];
    def.mass = m[k];
    // NaN in an array of restitutions leaves that ball's unset (the world's).
    if (!e.empty() && !std::isnan(e[k])) def.restitution = e[k];
    if (user_data) def.user_data = user_data->at(i);
    out(i) = id_number(world.add_ball(def, filters[filters.size() == 1 ? 0 : k]));
  }
  return ids;
}

// Every live ball's value, in handle order, as an (N, 2) or (N,) array.
template <typename Get>
py::array_t<double> points_of(const World& world, Get get) {
  const std::vector<BallId> ids = world.balls();
  py::array_t<double> out({static_cast<py::ssize_t>(ids.size()), py::ssize_t{2}});
  auto view = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const Vec2 v = get(ids[i]);
    view(static_cast<py::ssize_t>(i), 0) = v.x;
    view(static_cast<py::ssize_t>(i), 1) = v.y;
  }
  return out;
}
template <typename Get>
py::array_t<double> values_of(const World& world, Get get) {
  const std::vector<BallId> ids = world.balls();
  py::array_t<double> out(static_cast<py::ssize_t>(ids.size()));
  auto view = out.mutable_unchecked<1>();
  for (std::size_t i = 0; i < ids.size(); ++i) view(static_cast<py::ssize_t>(i)) = get(ids[i]);
  return out;
}

// The balls an array of ids names, or every live ball in handle order.
std::vector<BallId> balls_named(const World& world,
                                const std::optional<py::array_t<std::uint64_t>>& ids) {
  if (!ids) return world.balls();
  std::vector<BallId> out;
  const auto view = ids->unchecked<1>();
  for (py::ssize_t i = 0; i < view.shape(0); ++i) out.push_back(id_of(view(i)));
  return out;
}

Placement placement_of(const std::string& name) {
  if (name == "refuse") return Placement::refuse;
  if (name == "nearest_free") return Placement::nearest_free;
  throw py::value_error("placement must be \"refuse\" or \"nearest_free\", not \"" + name + "\"");
}

SensorAction sensor_action_of(const std::string& name) {
  if (name == "report") return SensorAction::report;
  if (name == "remove_ball") return SensorAction::remove_ball;
  throw py::value_error("action must be \"report\" or \"remove_ball\", not \"" + name + "\"");
}
const char* sensor_action_name(SensorAction action) {
  return action == SensorAction::remove_ball ? "remove_ball" : "report";
}

std::string sensor_event_repr(const SensorEvent& e) {
  std::ostringstream out;
  out.precision(17);
  out << "<carom.SensorEvent " << (e.kind == SensorEventKind::enter ? "enter" : "exit")
      << " of ball " << id_number(e.ball) << " in sensor " << e.sensor << " at time " << e.time
      << (e.removed ? ", removed" : "") << ">";
  return out.str();
}

}  // namespace

py::array contacts_array(std::span<const ContactEvent> contacts) {
  const py::dtype dtype = contact_dtype();
  if (dtype.itemsize() != static_cast<py::ssize_t>(sizeof(ContactRecord))) {
    throw std::logic_error("the contact record's layout differs from its NumPy dtype");
  }
  py::array out(dtype, static_cast<py::ssize_t>(contacts.size()));
  auto* records = static_cast<ContactRecord*>(out.mutable_data());
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const ContactEvent& c = contacts[i];
    ContactRecord r{};
    r.time = c.time;
    r.kind = c.kind == ContactKind::ball_ball ? 0 : 1;
    r.a = id_number(c.a);
    r.b = c.kind == ContactKind::ball_ball ? id_number(c.b) : 0;
    r.wall = c.wall;
    r.point[0] = c.point.x;
    r.point[1] = c.point.y;
    r.normal[0] = c.normal.x;
    r.normal[1] = c.normal.y;
    r.approach_speed = c.approach_speed;
    r.impulse = c.impulse;
    std::memcpy(&records[i], &r, sizeof r);
  }
  return out;
}

BallId ball_id(std::uint64_t number) { return id_of(number); }

py::object wrap_world(World&& world) { return py::cast(PyWorld(std::move(world))); }

World& unwrap_world(py::handle world) { return world.cast<PyWorld&>().world(); }

namespace {

py::array contacts_of(const World& world) { return contacts_array(world.contacts()); }

py::bytes save_bytes(const World& world) {
  std::ostringstream out(std::ios::binary);
  world.save(out);
  return py::bytes(out.str());
}

PyWorld load_bytes(const py::bytes& data) {
  std::istringstream in(std::string(data), std::ios::binary);
  return PyWorld(World::load(in));
}

}  // namespace

void bind_world(py::module_& m) {
  py::class_<CollisionFilter>(
      m, "CollisionFilter",
      "Which balls and walls meet: two meet when each one's mask has a bit of the other's "
      "category, unless they share a group other than 0 (positive: always meet; negative: never)")
      .def(py::init([](std::uint64_t category, std::uint64_t mask, std::int32_t group) {
             return CollisionFilter{category, mask, group};
           }),
           py::kw_only(), py::arg("category") = CollisionFilter{}.category,
           py::arg("mask") = CollisionFilter{}.mask, py::arg("group") = 0)
      .def_readwrite("category", &CollisionFilter::category, "What it is: bits")
      .def_readwrite("mask", &CollisionFilter::mask, "The categories it meets: bits")
      .def_readwrite("group", &CollisionFilter::group,
                     "0, or a group whose members always (> 0) or never (< 0) meet")
      .def(
          "__eq__", [](const CollisionFilter& a, const CollisionFilter& b) { return a == b; },
          "Equal in every field")
      .def("__repr__", [](const CollisionFilter& f) {
        return "carom.CollisionFilter(category=" + std::to_string(f.category) +
               ", mask=" + std::to_string(f.mask) + ", group=" + std::to_string(f.group) + ")";
      });
  m.def("should_collide", &should_collide, py::arg("a"), py::arg("b"),
        "Whether two filters let their owners meet");

  py::class_<SensorEvent>(m, "SensorEvent",
                          "A ball entering or leaving a sensor (World.sensor_events), read-only")
      .def_readonly("time", &SensorEvent::time, "When, exactly")
      .def_property_readonly(
          "kind",
          [](const SensorEvent& e) { return e.kind == SensorEventKind::enter ? "enter" : "exit"; },
          "\"enter\" or \"exit\"")
      .def_property_readonly(
          "ball", [](const SensorEvent& e) { return id_number(e.ball); },
          "The ball's id (stale from this event on when removed)")
      .def_readonly("sensor", &SensorEvent::sensor, "The sensor's wall id")
      .def_readonly("removed", &SensorEvent::removed,
                    "The sensor removed the ball (action \"remove_ball\"): no exit follows")
      .def_readonly("contacts_before", &SensorEvent::contacts_before,
                    "How many of the run's contacts (World.contacts) came before it")
      .def("__repr__", &sensor_event_repr);

  py::class_<WallMotion>(m, "WallMotion",
                         "A wall's rigid motion (World.set_wall_motion): its pivot moves with "
                         "velocity while the wall turns about it at angular_velocity "
                         "(counter-clockwise, radians per time unit) for duration, then it "
                         "stands still")
      .def(py::init([](Vec2 velocity, double angular_velocity, Vec2 pivot, double duration) {
             return WallMotion{velocity, angular_velocity, pivot, duration};
           }),
           py::kw_only(), py::arg("velocity") = Vec2{}, py::arg("angular_velocity") = 0.0,
           py::arg("pivot") = Vec2{}, py::arg("duration") = WallMotion{}.duration)
      .def_readwrite("velocity", &WallMotion::velocity, "The pivot's velocity")
      .def_readwrite("angular_velocity", &WallMotion::angular_velocity,
                     "Radians per time unit, counter-clockwise")
      .def_readwrite("pivot", &WallMotion::pivot, "The point it turns about, where it is now")
      .def_readwrite("duration", &WallMotion::duration,
                     "How long it moves from now (math.inf: for ever)")
      .def("moves", &WallMotion::moves, "Whether the wall moves at all")
      .def(
          "__eq__", [](const WallMotion& a, const WallMotion& b) { return a == b; },
          "Equal in every field")
      .def("__repr__", [](const WallMotion& motion) {
        return "carom.WallMotion(velocity=" +
               py::repr(py::cast(motion.velocity)).cast<std::string>() + ", angular_velocity=" +
               py::repr(py::float_(motion.angular_velocity)).cast<std::string>() +
               ", pivot=" + py::repr(py::cast(motion.pivot)).cast<std::string>() +
               ", duration=" + py::repr(py::float_(motion.duration)).cast<std::string>() + ")";
      });

  py::class_<PyWorld>(m, "World",
                      "A world of moving balls, walls and arcs, advanced in exact event order")
      .def(py::init([](const std::string& boundary, Vec2 lower, Vec2 upper, double restitution,
                       double collapse_time, double cell_size, Vec2 gravity, double rest_height,
                       double growth_rate, const std::optional<Table>& table) {
             return PyWorld(World(make_def(boundary, lower, upper, restitution, collapse_time,
                                           cell_size, gravity, rest_height, growth_rate, table)));
           }),
           py::kw_only(), py::arg("boundary") = "open", py::arg("lower") = Vec2{},
           py::arg("upper") = Vec2{}, py::arg("restitution") = 1.0, py::arg("collapse_time") = 0.0,
           py::arg("cell_size") = 0.0, py::arg("gravity") = Vec2{},
           py::arg("rest_height") = WorldDef{}.rest_height, py::arg("growth_rate") = 0.0,
           py::arg("table") = py::none())
      .def_property_readonly(
          "settings", [](const PyWorld& w) { return def_dict(w.world().def()); },
          "The keyword arguments the world was made with (its WorldDef), as a dict")
      // ---- balls ----
      .def(
          "add_ball",
          [](PyWorld& w, Vec2 position, Vec2 velocity, double radius, double mass,
             std::optional<double> restitution, std::uint64_t user_data,
             const CollisionFilter& filter, std::array<double, 3> spin) {
            BallDef def{position,
                        velocity,
                        radius,
                        mass,
                        restitution,
                        user_data,
                        Spin{spin[0], spin[1], spin[2]}};
            return id_number(w.world().add_ball(def, filter));
          },
          py::arg("position"), py::arg("velocity") = Vec2{}, py::arg("radius") = 1.0,
          py::arg("mass") = 1.0, py::arg("restitution") = py::none(), py::arg("user_data") = 0,
          py::arg("filter") = CollisionFilter{},
          py::arg("spin") = std::array<double, 3>{0.0, 0.0, 0.0},
          "Adds one ball (restitution None: the world's; spin (x, y, z) on a table only); "
          "returns its id")
      .def("add_balls", &add_balls, py::arg("positions"), py::arg("velocities") = py::none(),
           py::arg("radii") = 1.0, py::arg("masses") = 1.0, py::arg("restitution") = py::none(),
           py::arg("user_data") = py::none(), py::arg("filter") = py::none(),
           "Adds N balls from arrays (positions (N, 2); velocities (N, 2); radii, masses, "
           "restitution each a number or (N,); NaN restitution: the world's; filter: one "
           "CollisionFilter for all, or a sequence of N); returns their ids")
      .def(
          "remove_ball", [](PyWorld& w, std::uint64_t id) { w.world().remove_ball(id_of(id)); },
          py::arg("id"), "Removes a ball; its id becomes stale (InvalidArgument after)")
      .def(
          "contains",
          [](const PyWorld& w, std::uint64_t id) { return w.world().contains(id_of(id)); },
          py::arg("id"), "Whether the id names a ball still in the world")
      .def(
          "__len__", [](const PyWorld& w) { return w.world().ball_count(); }, "The number of balls")
      // ---- walls ----
      .def(
          "add_segment",
          [](PyWorld& w, Vec2 a, Vec2 b) {
            return w.world().add_segment({a, b});
          },
          py::arg("a"), py::arg("b"), "Adds a fixed segment from a to b; returns its wall id")
      .def(
          "add_polyline",
          [](PyWorld& w, const std::vector<Vec2>& points, bool closed) {
            return w.world().add_polyline(points, closed);
          },
          py::arg("points"), py::arg("closed") = false,
          "Adds a segment between each pair of successive points (and back to the first when "
          "closed); returns the first segment's wall id")
      .def(
          "add_arc",
          [](PyWorld& w, Vec2 center, double radius, double start_angle, double end_angle) {
            return w.world().add_arc({center, radius, start_angle, end_angle});
          },
          py::arg("center"), py::arg("radius"), py::arg("start_angle"), py::arg("end_angle"),
          "Adds a circular arc, counter-clockwise from start_angle to end_angle (radians); "
          "returns its wall id")
      .def(
          "add_box",
          [](PyWorld& w, Vec2 lower, Vec2 upper) { return w.world().add_box(lower, upper); },
          py::arg("lower"), py::arg("upper"),
          "Adds the four segments of a rectangle; returns the first one's wall id")
      // ---- sensors ----
      .def(
          "add_segment_sensor",
          [](PyWorld& w, Vec2 a, Vec2 b, const std::string& action) {
            return w.world().add_sensor(Segment{a, b}, sensor_action_of(action));
          },
          py::arg("a"), py::arg("b"), py::arg("action") = "report",
          "Adds a segment sensor from a to b, which balls pass through, recording their enters "
          "and exits (sensor_events); action \"report\" or \"remove_ball\" (a pocket: the ball "
          "that enters is removed); returns its wall id")
      .def(
          "add_arc_sensor",
          [](PyWorld& w, Vec2 center, double radius, double start_angle, double end_angle,
             const std::string& action) {
            return w.world().add_sensor(Arc{center, radius, start_angle, end_angle},
                                        sensor_action_of(action));
          },
          py::arg("center"), py::arg("radius"), py::arg("start_angle"), py::arg("end_angle"),
          py::arg("action") = "report",
          "Adds an arc sensor, counter-clockwise from start_angle to end_angle (radians); action "
          "as in add_segment_sensor; returns its wall id")
      .def(
          "add_disc_sensor",
          [](PyWorld& w, Vec2 center, double radius, const std::string& action) {
            return w.world().add_sensor(Ball{center, radius}, sensor_action_of(action));
          },
          py::arg("center"), py::arg("radius"), py::arg("action") = "report",
          "Adds a disc sensor (a ball enters it when it starts to overlap it); action as in "
          "add_segment_sensor; returns its wall id")
      .def(
          "sensor",
          [](const PyWorld& w, WallId wall) -> std::optional<std::string> {
            const std::optional<SensorAction> action = w.world().sensor(wall);
            if (!action) return std::nullopt;
            return sensor_action_name(*action);
          },
          py::arg("wall"),
          "What the sensor does, \"report\" or \"remove_ball\"; None for a wall that is no "
          "sensor")
      .def(
          "balls_in_sensor",
          [](const PyWorld& w, WallId wall) {
            const std::vector<BallId> ids = w.world().balls_in_sensor(wall);
            py::array_t<std::uint64_t> out(static_cast<py::ssize_t>(ids.size()));
            auto view = out.mutable_unchecked<1>();
            for (std::size_t i = 0; i < ids.size(); ++i) {
              view(static_cast<py::ssize_t>(i)) = id_number(ids[i]);
            }
            return out;
          },
          py::arg("wall"),
          "(K,) uint64: the ids of the balls inside the sensor (as of its last enter and exit), "
          "in the order of ids")
      .def_property_readonly(
          "wall_count", [](const PyWorld& w) { return w.world().wall_count(); },
          "The number of walls (segments, arcs and sensors, the boundary's box included)")
      .def(
          "wall",
          [](const PyWorld& w, WallId wall) {
            py::dict out;
            const std::variant<Segment, Arc, Ball> shape = w.world().wall(wall);
            if (const auto* s = std::get_if<Segment>(&shape)) {
              out["kind"] = "segment";
              out["a"] = s->a;
              out["b"] = s->b;
            } else if (const auto* a = std::get_if<Arc>(&shape)) {
              out["kind"] = "arc";
              out["center"] = a->center;
              out["radius"] = a->radius;
              out["start_angle"] = a->start_angle;
              out["end_angle"] = a->end_angle;
            } else {
              const auto& disc = std::get<Ball>(shape);
              out["kind"] = "disc";
              out["center"] = disc.center;
              out["radius"] = disc.radius;
            }
            return out;
          },
          py::arg("wall"),
          "A wall's shape as a dict: kind \"segment\" (a, b), \"arc\" (center, radius, "
          "start_angle, end_angle) or \"disc\" (a disc sensor: center, radius); a moving "
          "wall's where it is now")
      .def(
          "set_wall_motion",
          [](PyWorld& w, WallId wall, const WallMotion& motion) {
            w.world().set_wall_motion(wall, motion);
          },
          py::arg("wall"), py::arg("motion"),
          "Gives a segment or an arc a rigid motion from now (a WallMotion), replacing the one "
          "it had: it moves so for motion.duration, then stands still. Balls meet it at exact "
          "times and bounce with its velocity at the contact point")
      .def(
          "set_wall_motion",
          [](PyWorld& w, WallId wall, Vec2 velocity, double angular_velocity, Vec2 pivot,
             double duration) {
            w.world().set_wall_motion(wall, {velocity, angular_velocity, pivot, duration});
          },
          py::arg("wall"), py::kw_only(), py::arg("velocity") = Vec2{},
          py::arg("angular_velocity") = 0.0, py::arg("pivot") = Vec2{},
          py::arg("duration") = WallMotion{}.duration,
          "The same with the motion's fields as keywords")
      .def(
          "wall_motion", [](const PyWorld& w, WallId wall) { return w.world().wall_motion(wall); },
          py::arg("wall"),
          "The motion a wall has from now (its pivot where it is now, the duration left); all "
          "zeros for a wall that stands still")
      .def(
          "remove_wall", [](PyWorld& w, WallId wall) { w.world().remove_wall(wall); },
          py::arg("wall"),
          "Removes a wall or a sensor: nothing meets it or sees it from now on; its id stays "
          "taken")
      .def(
          "wall_removed",
          [](const PyWorld& w, WallId wall) { return w.world().wall_removed(wall); },
          py::arg("wall"), "Whether the wall was removed")
      // ---- advancing time ----
      .def(
          "step", [](PyWorld& w, double dt) { return w.run([&] { return w.world().step(dt); }); },
          py::arg("dt"), "Advances dt; returns the time advanced")
      .def(
          "run_until",
          [](PyWorld& w, double time) { return w.run([&] { return w.world().run_until(time); }); },
          py::arg("time"), "Advances to the given time; returns the time reached")
      .def(
          "run_collisions",
          [](PyWorld& w, std::uint64_t count, std::optional<double> time_limit) {
            return w.run([&] {
              return time_limit ? w.world().run_collisions(count, *time_limit)
                                : w.world().run_collisions(count);
            });
          },
          py::arg("count"), py::arg("time_limit") = py::none(),
          "Resolves the next `count` contacts (fewer when stopped: see stop_reason)")
      .def_property_readonly(
          "stop_reason", [](const PyWorld& w) { return stop_reason_name(w.world().stop_reason()); },
          "Why the last run ended: \"none\" (it did what it was asked), \"no_more_contacts\", "
          "\"time_limit\" (run_collisions' limit came first), \"stop_condition\" or "
          "\"interrupted\" (request_stop or Ctrl-C)")
      .def("set_stop_condition", &PyWorld::set_stop_condition, py::arg("condition"),
           "A callable taking one contact (a dict) and returning True to end the run right after "
           "it; None removes it. Runs with a condition keep the GIL.")
      .def(
          "request_stop", [](PyWorld& w) { w.world().request_stop(); },
          "Ends the current run after the contact being resolved (stop_reason \"interrupted\")")
      .def_property(
          "contact_recording", [](const PyWorld& w) { return w.world().contact_recording(); },
          [](PyWorld& w, bool on) { w.world().set_contact_recording(on); },
          "Whether runs keep their contacts for World.contacts (off: no cost)")
      .def_property_readonly(
          "contacts", [](const PyWorld& w) { return contacts_of(w.world()); },
          "The last run's contacts as a structured array (time, kind: 0 "
          "ball-ball 1 ball-wall, a, b, wall, point, normal, approach_speed, "
          "impulse)")
      .def_property_readonly(
          "sensor_events",
          [](const PyWorld& w) {
            const std::span<const SensorEvent> events = w.world().sensor_events();
            return std::vector<SensorEvent>(events.begin(), events.end());
          },
          "The last run's sensor enters and exits, in order (a list of SensorEvent); always "
          "recorded")
      // ---- state ----
      .def_property_readonly(
          "time", [](const PyWorld& w) { return w.world().time(); }, "The world's time")
      .def_property_readonly(
          "ids",
          [](const PyWorld& w) {
            const std::vector<BallId> ids = w.world().balls();
            py::array_t<std::uint64_t> out(static_cast<py::ssize_t>(ids.size()));
            auto view = out.mutable_unchecked<1>();
            for (std::size_t i = 0; i < ids.size(); ++i) {
              view(static_cast<py::ssize_t>(i)) = id_number(ids[i]);
            }
            return out;
          },
          "(N,) uint64: every ball's id, in handle order (the order of every array)")
      .def_property_readonly(
          "positions",
          [](const PyWorld& w) {
            return points_of(w.world(), [&](BallId id) { return w.world().position(id); });
          },
          "(N, 2) positions at the world's time, in the order of ids")
      .def_property_readonly(
          "velocities",
          [](const PyWorld& w) {
            return points_of(w.world(), [&](BallId id) { return w.world().velocity(id); });
          },
          "(N, 2) velocities at the world's time, in the order of ids")
      .def_property_readonly(
          "radii",
          [](const PyWorld& w) {
            return values_of(w.world(), [&](BallId id) { return w.world().radius(id); });
          },
          "(N,) radii at the world's time (they change while balls grow)")
      .def_property_readonly(
          "masses",
          [](const PyWorld& w) {
            return values_of(w.world(), [&](BallId id) { return w.world().mass(id); });
          },
          "(N,) masses (inf for an immovable ball)")
      .def(
          "position",
          [](const PyWorld& w, std::uint64_t id) { return w.world().position(id_of(id)); },
          py::arg("id"), "One ball's position at the world's time")
      .def(
          "velocity",
          [](const PyWorld& w, std::uint64_t id) { return w.world().velocity(id_of(id)); },
          py::arg("id"), "One ball's velocity at the world's time")
      .def(
          "radius", [](const PyWorld& w, std::uint64_t id) { return w.world().radius(id_of(id)); },
          py::arg("id"), "One ball's radius at the world's time")
      .def_property_readonly(
          "kinetic_energy", [](const PyWorld& w) { return w.world().kinetic_energy(); },
          "Sum of m v^2 / 2 over the movable balls")
      .def_property_readonly(
          "potential_energy", [](const PyWorld& w) { return w.world().potential_energy(); },
          "Sum of -m g.x over the movable balls (0 without gravity)")
      .def_property_readonly(
          "momentum", [](const PyWorld& w) { return w.world().momentum(); },
          "Sum of m v over the movable balls")
      .def_property_readonly(
          "collision_count", [](const PyWorld& w) { return w.world().collision_count(); },
          "Contacts resolved since the world was made")
      // ---- changing the world between steps ----
      .def(
          "set_filter",
          [](PyWorld& w, std::uint64_t id, const CollisionFilter& filter) {
            w.world().set_filter(id_of(id), filter);
          },
          py::arg("id"), py::arg("filter"),
          "Sets a ball's CollisionFilter between steps (pairs whose filters do not meet pass "
          "through each other)")
      .def(
          "filter", [](const PyWorld& w, std::uint64_t id) { return w.world().filter(id_of(id)); },
          py::arg("id"), "A ball's CollisionFilter")
      .def(
          "set_wall_filter",
          [](PyWorld& w, WallId wall, const CollisionFilter& filter) {
            w.world().set_wall_filter(wall, filter);
          },
          py::arg("wall"), py::arg("filter"),
          "Sets a wall's CollisionFilter (not a box boundary's sides, which keep every ball in)")
      .def(
          "wall_filter", [](const PyWorld& w, WallId wall) { return w.world().wall_filter(wall); },
          py::arg("wall"), "A wall's CollisionFilter")
      .def(
          "set_velocity",
          [](PyWorld& w, std::uint64_t id, Vec2 v) { w.world().set_velocity(id_of(id), v); },
          py::arg("id"), py::arg("velocity"), "Sets one ball's velocity between steps")
      .def(
          "set_position",
          [](PyWorld& w, std::uint64_t id, Vec2 p, const std::string& placement) {
            return w.world().set_position(id_of(id), p, placement_of(placement));
          },
          py::arg("id"), py::arg("position"), py::arg("placement") = "refuse",
          "Moves one ball between steps; placement \"refuse\" (InvalidArgument on overlap) or "
          "\"nearest_free\"; returns where it was put")
      .def(
          "set_velocities",
          [](PyWorld& w, const DoubleArray& velocities,
             const std::optional<py::array_t<std::uint64_t>>& ids) {
            const std::vector<BallId> balls = balls_named(w.world(), ids);
            require_points(velocities, "velocities", static_cast<py::ssize_t>(balls.size()));
            const auto v = velocities.unchecked<2>();
            for (std::size_t i = 0; i < balls.size(); ++i) {
              const auto k = static_cast<py::ssize_t>(i);
              w.world().set_velocity(balls[i], {v(k, 0), v(k, 1)});
            }
          },
          py::arg("velocities"), py::arg("ids") = py::none(),
          "Sets every live ball's velocity (in the order of ids), or those of the given ids")
      .def(
          "set_positions",
          [](PyWorld& w, const DoubleArray& positions,
             const std::optional<py::array_t<std::uint64_t>>& ids, const std::string& placement) {
            const std::vector<BallId> balls = balls_named(w.world(), ids);
            require_points(positions, "positions", static_cast<py::ssize_t>(balls.size()));
            const auto p = positions.unchecked<2>();
            const Placement how = placement_of(placement);
            for (std::size_t i = 0; i < balls.size(); ++i) {
              const auto k = static_cast<py::ssize_t>(i);
              static_cast<void>(w.world().set_position(balls[i], {p(k, 0), p(k, 1)}, how));
            }
          },
          py::arg("positions"), py::arg("ids") = py::none(), py::arg("placement") = "refuse",
          "Moves every live ball (in the order of ids), or those of the given ids, one after the "
          "other; placement as in set_position")
      .def(
          "set_gravity", [](PyWorld& w, Vec2 g) { w.world().set_gravity(g); }, py::arg("gravity"),
          "Sets the gravity (an acceleration vector) from now on")
      .def(
          "set_growth_rate", [](PyWorld& w, double rate) { w.world().set_growth_rate(rate); },
          py::arg("rate"), "Sets every ball's radius growth rate (length per time) from now on")
      .def_property_readonly(
          "growth_rate_from_now", [](const PyWorld& w) { return w.world().growth_rate_from_now(); },
          "The growth rate set for the time from now on")
      .def(
          "set_temperature", [](PyWorld& w, double kT) { return w.world().set_temperature(kT); },
          py::arg("kT"), "A thermostat's step; returns the work done")
      // ---- saving ----
      .def(
          "save",
          [](const PyWorld& w, const std::optional<std::filesystem::path>& path) -> py::object {
            if (!path) return save_bytes(w.world());
            w.world().save(*path);
            return py::none();
          },
          py::arg("path") = py::none(),
          "Saves the world: to a file (atomically), or as bytes when no path is given")
      .def_static(
          "load",
          [](const py::object& source) {
            if (py::isinstance<py::bytes>(source)) return load_bytes(source.cast<py::bytes>());
            return PyWorld(World::load(source.cast<std::filesystem::path>()));
          },
          py::arg("source"), "A world from bytes that save() gave, or from a file")
      .def(py::pickle([](const PyWorld& w) { return save_bytes(w.world()); },
                      [](const py::bytes& data) { return load_bytes(data); }))
      // ---- checking ----
      .def(
          "audit", [](const PyWorld& w, double tolerance) { return w.world().audit(tolerance); },
          py::arg("tolerance") = 1e-9,
          "None when no two balls overlap (and every ball is inside a box), else what is wrong");
}

}  // namespace carom::python
