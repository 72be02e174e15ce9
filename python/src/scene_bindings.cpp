// carom for Python: scenes — read from JSON text or a file, saved back, built into a World, and
// run with their pockets and thermostat into NumPy arrays of frames.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "carom/error.hpp"
#include "carom/pool_table.hpp"
#include "carom/scene.hpp"

namespace carom::python {
namespace {

// The ids of a built scene's balls in scene order (0 for one a pocket has taken).
py::array_t<std::uint64_t> scene_ids(const SceneWorld& built) {
  py::array_t<std::uint64_t> out(static_cast<py::ssize_t>(built.balls.size()));
  auto view = out.mutable_unchecked<1>();
  for (std::size_t i = 0; i < built.balls.size(); ++i) {
    view(static_cast<py::ssize_t>(i)) = built.balls[i].is_null() ? 0 : id_number(built.balls[i]);
  }
  return out;
}

// The frames of a run, filled with the GIL released and turned into arrays afterwards.
struct Frames {
  std::vector<double> times;
  std::vector<double> positions;   // F × N × 2
  std::vector<double> velocities;  // F × N × 2
  std::vector<double> radii;       // F × N
  std::vector<ContactEvent> contacts;
  std::vector<PottedBall> potted;
  std::vector<SensorEvent> sensor_events;

  void record(const SceneWorld& built) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    times.push_back(built.time());
    for (const BallId id : built.balls) {
      const bool live = !id.is_null() && built.world.contains(id);
      const Vec2 p = live ? built.world.position(id) : Vec2{nan, nan};
      const Vec2 v = live ? built.world.velocity(id) : Vec2{nan, nan};
      positions.insert(positions.end(), {p.x, p.y});
      velocities.insert(velocities.end(), {v.x, v.y});
      radii.push_back(live ? built.world.radius(id) : nan);
    }
  }
};

py::array_t<double> array_of(const std::vector<double>& values,
                             const std::vector<py::ssize_t>& shape) {
  py::array_t<double> out(shape);
  if (!values.empty()) {
    std::copy(values.begin(), values.end(), out.mutable_data());
  }
  return out;
}

// Runs the scene from its start to scene time `until`, a frame every frame_interval (the first at
// the start), with the GIL released; Ctrl-C stops it at an event boundary and is raised.
py::dict run_scene(const Scene& scene, double until, double frame_interval) {
  if (!(frame_interval > 0.0) || !std::isfinite(frame_interval)) {
    throw py::value_error("frame_interval must be a finite number > 0");
  }
  if (!std::isfinite(until)) throw py::value_error("until must be a finite scene time");
  SceneWorld built = make_world(scene);
  const py::array_t<std::uint64_t> ids = scene_ids(built);
  const std::vector<BallId> balls_at_start = built.balls;
  // Frame k is at scene time start + k·interval (by multiplication, so no drift adds up).
  const double start = built.time();
  const double steps = std::floor((until - start) / frame_interval + 1e-9);
  const auto frame_count = static_cast<std::size_t>(std::max(steps, 0.0)) + 1;
  Frames frames;
  bool signalled = false;
  built.world.set_progress_callback([&signalled](const RunStatus&) {
    const py::gil_scoped_acquire locked;
    if (PyErr_CheckSignals() != 0) signalled = true;
    return signalled;
  });
  {
    const py::gil_scoped_release unlocked;
    frames.record(built);
    for (std::size_t k = 1; k < frame_count && !signalled; ++k) {
      const double world_time =
          static_cast<double>(k) * frame_interval + (start - built.start_time);
      run_scene_until(built, world_time, &frames.contacts, &frames.potted);
      frames.sensor_events.insert(frames.sensor_events.end(), built.sensor_events.begin(),
                                  built.sensor_events.end());
      if (built.world.stop_reason() == StopReason::interrupted) break;
      frames.record(built);
    }
  }
  // PyErr_CheckSignals left the KeyboardInterrupt set: raise it.
  if (signalled) throw py::error_already_set();

  const auto f = static_cast<py::ssize_t>(frames.times.size());
  const auto n = static_cast<py::ssize_t>(built.balls.size());
  py::dict out;
  out["times"] = array_of(frames.times, {f});
  out["positions"] = array_of(frames.positions, {f, n, 2});
  out["velocities"] = array_of(frames.velocities, {f, n, 2});
  out["radii"] = array_of(frames.radii, {f, n});
  out["ids"] = ids;
  // On the scene clock, as the frames' times are.
  for (ContactEvent& c : frames.contacts) c.time += built.start_time;
  out["contacts"] = contacts_array(frames.contacts);
  py::list potted;
  for (const PottedBall& p : frames.potted) {
    py::dict d;
    d["time"] = p.time;
    d["ball"] = p.ball;
    d["pocket"] = p.pocket;
    potted.append(d);
  }
  out["potted"] = potted;
  // The sensors' enters and exits: the ball by scene index, the sensor by its place in the
  // scene's sensors (the world's last walls).
  py::list sensor_events;
  const std::size_t first_sensor = built.world.wall_count() - built.sensors.size();
  for (const SensorEvent& e : frames.sensor_events) {
    py::dict d;
    d["time"] = e.time + built.start_time;
    d["kind"] = e.kind == SensorEventKind::enter ? "enter" : "exit";
    const auto at = std::find(balls_at_start.begin(), balls_at_start.end(), e.ball);
    d["ball"] = static_cast<std::size_t>(at - balls_at_start.begin());
    d["sensor"] = static_cast<std::size_t>(e.sensor) - first_sensor;
    d["removed"] = e.removed;
    sensor_events.append(d);
  }
  out["sensor_events"] = sensor_events;
  out["start_time"] = built.start_time;
  out["box"] = py::make_tuple(built.world.def().lower, built.world.def().upper);
  out["boundary"] = built.world.def().boundary == Boundary::periodic ? "periodic"
                    : built.world.def().boundary == Boundary::box    ? "box"
                                                                     : "open";
  return out;
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<Scene>(m, "Scene", "A world described as data (docs/scenes.md): read, saved, built")
      .def_readwrite("description", &Scene::description, "The scene's description text")
      .def_readwrite("time", &Scene::time, "The time the scene starts at")
      .def_property_readonly(
          "ball_count", [](const Scene& s) { return expand_balls(s).size(); },
          "Explicit and generated balls, pockets not counted")
      .def(
          "__len__", [](const Scene& s) { return expand_balls(s).size(); }, "ball_count")
      .def_property_readonly(
          "pocket_count", [](const Scene& s) { return s.pockets.size(); },
          "Pockets (balls that take away any ball they touch)")
      .def(
          "to_json", [](const Scene& s) { return to_json_text(s); },
          "The scene as JSON text; parse_scene gives it back bit for bit")
      .def(
          "save", [](const Scene& s, const std::filesystem::path& path) { save_scene(s, path); },
          py::arg("path"), "Writes the scene's JSON to path atomically")
      .def("__repr__", [](const Scene& s) {
        return "<carom.Scene, " + std::to_string(expand_balls(s).size()) + " balls>";
      });

  m.def(
      "load_scene", [](const std::filesystem::path& path) { return load_scene(path); },
      py::arg("path"), "Reads and checks a scene file; raises SceneError");
  m.def(
      "parse_scene",
      [](const std::string& text, const std::string& name) { return parse_scene(text, name); },
      py::arg("text"), py::arg("name") = "",
      "Parses and checks scene JSON text (name names it in errors); raises SceneError");
  m.def(
      "make_world",
      [](const Scene& scene) {
        SceneWorld built = make_world(scene);
        py::array_t<std::uint64_t> ids = scene_ids(built);
        return py::make_tuple(wrap_world(std::move(built.world)), ids);
      },
      py::arg("scene"),
      "The scene's World and the ids of its balls in scene order (generated balls after the "
      "explicit ones). Pockets are immovable balls whose contacts end a run (stop_reason "
      "\"stop_condition\"); run_scene removes the balls they take.");
  m.def(
      "pool_table_scene",
      [](const std::string& size, const std::string& rack, double ball_radius, double ball_mass,
         double rack_gap) {
        PoolTableSpec spec;
        spec.size = size == "7ft"   ? PoolTableSize::seven_foot
                    : size == "8ft" ? PoolTableSize::eight_foot
                                    : PoolTableSize::nine_foot;
        if (size != "7ft" && size != "8ft" && size != "9ft") {
          throw InvalidArgument("pool_table_scene", "size", size, "must be 7ft, 8ft or 9ft");
        }
        spec.rack = rack == "nine"   ? PoolRack::nine_ball
                    : rack == "none" ? PoolRack::none
                                     : PoolRack::eight_ball;
        if (rack != "eight" && rack != "nine" && rack != "none") {
          throw InvalidArgument("pool_table_scene", "rack", rack,
                                "must be \"eight\", \"nine\" or \"none\"");
        }
        spec.ball_radius = ball_radius;
        spec.ball_mass = ball_mass;
        spec.rack_gap = rack_gap;
        return pool_table_scene(spec);
      },
      py::kw_only(), py::arg("size") = "9ft", py::arg("rack") = "eight",
      py::arg("ball_radius") = PoolTableSpec{}.ball_radius,
      py::arg("ball_mass") = PoolTableSpec{}.ball_mass,
      py::arg("rack_gap") = PoolTableSpec{}.rack_gap,
      "A standard pool table as a scene (docs/pool.md, \"Standard tables\"): size \"7ft\", "
      "\"8ft\" or \"9ft\", rack \"eight\", \"nine\" or \"none\"");
  m.def("run_scene", &run_scene, py::arg("scene"), py::arg("until"), py::arg("frame_interval"),
        "Runs the scene, with its pockets and thermostat, to scene time `until`, a frame every "
        "frame_interval: a dict of times (F,), positions and velocities (F, N, 2), radii (F, N) "
        "(NaN once a pocket or a sensor takes a ball), ids (N,), contacts, potted, "
        "sensor_events (dicts of time, kind \"enter\" or \"exit\", ball, sensor, removed), "
        "start_time, box and boundary");
}

}  // namespace carom::python
