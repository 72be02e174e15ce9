// carom for Python: the core queries — time of impact in the step form (the tutorial's moves over
// a step) and the time form (velocities, accelerations, growth, a horizon), the bounces, and the
// batch kernel over NumPy arrays of pairs.
#include <pybind11/stl.h>

#include <string>
#include <tuple>

#include "bindings.hpp"
#include "carom/bounce.hpp"
#include "carom/sweep.hpp"
#include "carom/sweep_batch.hpp"

namespace carom::python {
namespace {

using BallTuple = std::tuple<double, double, double>;                 // (x, y, r)
using SegmentTuple = std::tuple<Vec2, Vec2>;                          // (a, b)
using ArcTuple = std::tuple<double, double, double, double, double>;  // (x, y, r, θ₀, θ₁)

Ball ball_of(const BallTuple& b) { return {{std::get<0>(b), std::get<1>(b)}, std::get<2>(b)}; }
Segment segment_of(const SegmentTuple& s) { return {std::get<0>(s), std::get<1>(s)}; }
Arc arc_of(const ArcTuple& a) {
  return {{std::get<0>(a), std::get<1>(a)}, std::get<2>(a), std::get<3>(a), std::get<4>(a)};
}

std::string impact_repr(const Impact& i) {
  if (!i.hit) return i.overlapping ? "Impact(hit=False, overlapping=True)" : "Impact(hit=False)";
  return "Impact(hit=True, t=" + std::to_string(i.t) + ")";
}

// One column of an (N, k) array as a span of N doubles, copied into `out`.
void column(const DoubleArray& array, py::ssize_t k, std::vector<double>& out) {
  const auto view = array.unchecked<2>();
  out.resize(static_cast<std::size_t>(view.shape(0)));
  for (py::ssize_t i = 0; i < view.shape(0); ++i) out[static_cast<std::size_t>(i)] = view(i, k);
}

void require_shape(const DoubleArray& array, const char* name, py::ssize_t rows,
                   py::ssize_t columns) {
  if (array.ndim() != 2 || array.shape(1) != columns || (rows >= 0 && array.shape(0) != rows)) {
    throw py::value_error(std::string(name) + " must be an array of shape (N, " +
                          std::to_string(columns) + ")" +
                          (rows >= 0 ? " with N = " + std::to_string(rows) : ""));
  }
}

// The step form over N pairs at once, through the vectorised kernel: t in [0, 1], inf where the
// pair does not touch.
py::array_t<double> sweep_ball_ball_many(const DoubleArray& a, const DoubleArray& move_a,
                                         const DoubleArray& b, const DoubleArray& move_b) {
  require_shape(a, "a", -1, 3);
  const py::ssize_t n = a.shape(0);
  require_shape(move_a, "move_a", n, 2);
  require_shape(b, "b", n, 3);
  require_shape(move_b, "move_b", n, 2);
  std::vector<double> ax, ay, ar, amx, amy, bx, by, br, bmx, bmy;
  column(a, 0, ax);
  column(a, 1, ay);
  column(a, 2, ar);
  column(move_a, 0, amx);
  column(move_a, 1, amy);
  column(b, 0, bx);
  column(b, 1, by);
  column(b, 2, br);
  column(move_b, 0, bmx);
  column(move_b, 1, bmy);
  py::array_t<double> t(n);
  const BallPairArrays pairs{ax, ay, ar, amx, amy, bx, by, br, bmx, bmy};
  {
    const py::gil_scoped_release unlocked;
    static_cast<void>(sweep_ball_ball_batch(
        pairs, std::span<double>(t.mutable_data(), static_cast<std::size_t>(n))));
  }
  return t;
}

}  // namespace

void bind_core(py::module_& m) {
  py::class_<Impact>(m, "Impact", "Where and when two shapes first touch (or that they do not)")
      .def_readonly("hit", &Impact::hit, "Whether they touch within the step (or horizon)")
      .def_readonly("overlapping", &Impact::overlapping,
                    "Whether they already overlap at the start (then t = 0)")
      .def_readonly("t", &Impact::t,
                    "The time of first contact: a fraction of the step, or a time (time forms)")
      .def_readonly("a_at", &Impact::a_at, "Where a's centre is at t")
      .def_readonly("b_at", &Impact::b_at, "Where b's centre is at t (the wall's forms: a_at)")
      .def_readonly("normal", &Impact::normal, "The unit normal at contact, from a towards b")
      .def_readonly("point", &Impact::point, "The contact point at t")
      .def(
          "__bool__", [](const Impact& i) { return i.hit; }, "hit")
      .def("__repr__", &impact_repr);

  // ---- step form ----
  m.def(
      "sweep_ball_ball",
      [](const BallTuple& a, Vec2 move_a, const BallTuple& b, Vec2 move_b) {
        return sweep_ball_ball(ball_of(a), move_a, ball_of(b), move_b);
      },
      py::arg("a"), py::arg("move_a"), py::arg("b"), py::arg("move_b") = Vec2{},
      "Ball a = (x, y, r) moves by move_a and ball b by move_b during a step: when (t in [0, 1]) "
      "and where they first touch while approaching.");
  m.def(
      "sweep_ball_point",
      [](const BallTuple& a, Vec2 move_a, Vec2 point) {
        return sweep_ball_point(ball_of(a), move_a, point);
      },
      py::arg("a"), py::arg("move_a"), py::arg("point"),
      "Ball a = (x, y, r) moving by move_a against a fixed point (x, y) during a step.");
  m.def(
      "sweep_ball_segment",
      [](const BallTuple& a, Vec2 move_a, const SegmentTuple& segment) {
        return sweep_ball_segment(ball_of(a), move_a, segment_of(segment));
      },
      py::arg("a"), py::arg("move_a"), py::arg("segment"), "segment = ((x0, y0), (x1, y1))");
  m.def(
      "sweep_ball_arc",
      [](const BallTuple& a, Vec2 move_a, const ArcTuple& arc) {
        return sweep_ball_arc(ball_of(a), move_a, arc_of(arc));
      },
      py::arg("a"), py::arg("move_a"), py::arg("arc"),
      "arc = (x, y, radius, start_angle, end_angle), counter-clockwise, in radians");
  m.def("sweep_ball_ball_many", &sweep_ball_ball_many, py::arg("a"), py::arg("move_a"),
        py::arg("b"), py::arg("move_b"),
        "sweep_ball_ball over N pairs: a and b of shape (N, 3) (x, y, r), moves of shape (N, 2); "
        "returns t of shape (N,), inf where a pair does not touch (the vectorised kernel; "
        "bit-identical to the one-pair query).");

  // ---- time form ----
  m.def(
      "time_of_impact_ball_ball",
      [](const BallTuple& a, Vec2 velocity_a, const BallTuple& b, Vec2 velocity_b, double horizon,
         Vec2 acceleration_a, Vec2 acceleration_b, double growth_a, double growth_b) {
        return time_of_impact_ball_ball(ball_of(a), Motion(velocity_a, acceleration_a, growth_a),
                                        ball_of(b), Motion(velocity_b, acceleration_b, growth_b),
                                        horizon);
      },
      py::arg("a"), py::arg("velocity_a"), py::arg("b"), py::arg("velocity_b"), py::arg("horizon"),
      py::arg("acceleration_a") = Vec2{}, py::arg("acceleration_b") = Vec2{},
      py::arg("growth_a") = 0.0, py::arg("growth_b") = 0.0,
      "The first contact within [0, horizon] of two balls moving with these velocities "
      "(constant accelerations and radius growth speeds optional: exact, by certified root "
      "isolation).");
  m.def(
      "time_of_impact_ball_point",
      [](const BallTuple& a, Vec2 velocity, Vec2 point, double horizon, Vec2 acceleration,
         double growth) {
        return time_of_impact_ball_point(ball_of(a), Motion(velocity, acceleration, growth), point,
                                         horizon);
      },
      py::arg("a"), py::arg("velocity"), py::arg("point"), py::arg("horizon"),
      py::arg("acceleration") = Vec2{}, py::arg("growth") = 0.0,
      "The first contact within [0, horizon] of a moving ball and a fixed point.");
  m.def(
      "time_of_impact_ball_segment",
      [](const BallTuple& a, Vec2 velocity, const SegmentTuple& segment, double horizon,
         Vec2 acceleration, double growth) {
        return time_of_impact_ball_segment(ball_of(a), Motion(velocity, acceleration, growth),
                                           segment_of(segment), horizon);
      },
      py::arg("a"), py::arg("velocity"), py::arg("segment"), py::arg("horizon"),
      py::arg("acceleration") = Vec2{}, py::arg("growth") = 0.0,
      "The first contact within [0, horizon] of a moving ball and a fixed segment (its ends "
      "included).");
  m.def(
      "time_of_impact_ball_arc",
      [](const BallTuple& a, Vec2 velocity, const ArcTuple& arc, double horizon, Vec2 acceleration,
         double growth) {
        return time_of_impact_ball_arc(ball_of(a), Motion(velocity, acceleration, growth),
                                       arc_of(arc), horizon);
      },
      py::arg("a"), py::arg("velocity"), py::arg("arc"), py::arg("horizon"),
      py::arg("acceleration") = Vec2{}, py::arg("growth") = 0.0,
      "The first contact within [0, horizon] of a moving ball and a fixed arc (either side, its "
      "ends included).");

  // ---- bounces ----
  py::class_<BounceResult>(m, "BounceResult", "Two balls' velocities after a bounce")
      .def_readonly("velocity_a", &BounceResult::velocity_a, "a's velocity after")
      .def_readonly("velocity_b", &BounceResult::velocity_b, "b's velocity after")
      .def_readonly("impulse", &BounceResult::impulse, "The impulse along the normal (>= 0)");
  py::class_<WallBounceResult>(m, "WallBounceResult", "A ball's velocity after a wall bounce")
      .def_readonly("velocity", &WallBounceResult::velocity, "The velocity after")
      .def_readonly("impulse", &WallBounceResult::impulse, "The impulse along the normal (>= 0)");
  m.def("bounce", &bounce, py::arg("velocity_a"), py::arg("mass_a"), py::arg("velocity_b"),
        py::arg("mass_b"), py::arg("normal"), py::arg("restitution") = 1.0,
        "Two balls touching with normal from a to b: their velocities after the bounce and the "
        "impulse (masses > 0 or carom.IMMOVABLE).");
  m.def("bounce_off_static", &bounce_off_static, py::arg("velocity"), py::arg("mass"),
        py::arg("normal"), py::arg("restitution") = 1.0,
        "A ball against a static segment, point or arc, normal from the ball to the wall.");
}

}  // namespace carom::python
