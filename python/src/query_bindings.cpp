// carom for Python: the World's queries — ray casts (one, every hit, or an array of rays at once),
// ball casts and overlap queries — as methods of carom.World, with the filter as keywords.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <cstring>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "carom/world.hpp"

namespace carom::python {
namespace {

// The filter the keywords describe; an `accept` callable is called with the GIL held.
QueryFilter filter_of(bool balls, bool walls, const std::optional<std::uint64_t>& ignore,
                      const std::optional<std::function<bool(std::uint64_t)>>& accept,
                      std::uint64_t mask = ~0ULL) {
  QueryFilter filter;
  filter.mask = mask;
  filter.balls = balls;
  filter.walls = walls;
  if (ignore) filter.ignore = ball_id(*ignore);
  if (accept) {
    filter.accept = [call = *accept](BallId id) { return call(id_number(id)); };
  }
  return filter;
}

// Runs a query with the GIL released unless a Python callable must be called from it.
template <typename Query>
auto answer(const QueryFilter& filter, Query query) {
  if (filter.accept) return query();
  const py::gil_scoped_release unlocked;
  return query();
}

// None when nothing is met (typed Optional[QueryHit] in the stubs).
std::optional<QueryHit> hit_or_none(const QueryHit& hit) {
  return hit ? std::optional<QueryHit>(hit) : std::nullopt;
}

py::array_t<std::uint64_t> id_array(const std::vector<BallId>& ids) {
  py::array_t<std::uint64_t> out(static_cast<py::ssize_t>(ids.size()));
  auto view = out.mutable_unchecked<1>();
  for (std::size_t i = 0; i < ids.size(); ++i)
    view(static_cast<py::ssize_t>(i)) = id_number(ids[i]);
  return out;
}

// The record of World.cast_rays: one first hit a ray.
struct RayRecord {
  std::uint8_t kind;  // 0 nothing, 1 a ball, 2 a wall
  std::uint64_t ball;
  std::uint32_t wall;
  double fraction;
  double point[2];
  double normal[2];
};

py::dtype ray_dtype() {
  py::list fields;
  fields.append(py::make_tuple("kind", "u1"));
  fields.append(py::make_tuple("ball", "u8"));
  fields.append(py::make_tuple("wall", "u4"));
  fields.append(py::make_tuple("fraction", "f8"));
  fields.append(py::make_tuple("point", "f8", 2));
  fields.append(py::make_tuple("normal", "f8", 2));
  return py::module_::import("numpy").attr("dtype")(fields, py::arg("align") = true);
}

Vec2 row(const py::detail::unchecked_reference<double, 2>& view, py::ssize_t i) {
  return {view(i, 0), view(i, 1)};
}

py::array cast_rays(const py::object& self, const DoubleArray& origins,
                    const DoubleArray& translations, bool balls, bool walls,
                    const std::optional<std::uint64_t>& ignore,
                    const std::optional<std::function<bool(std::uint64_t)>>& accept,
                    std::uint64_t mask) {
  const World& world = unwrap_world(self);
  if (origins.ndim() != 2 || origins.shape(1) != 2) {
    throw py::value_error("origins must have shape (N, 2)");
  }
  const py::ssize_t n = origins.shape(0);
  const bool one_translation = translations.ndim() == 1 && translations.shape(0) == 2;
  if (!one_translation &&
      (translations.ndim() != 2 || translations.shape(0) != n || translations.shape(1) != 2)) {
    throw py::value_error("translations must have shape (N, 2), as origins, or (2,)");
  }
  const py::dtype dtype = ray_dtype();
  if (dtype.itemsize() != static_cast<py::ssize_t>(sizeof(RayRecord))) {
    throw std::logic_error("the ray record's layout differs from its NumPy dtype");
  }
  py::array out(dtype, n);
  auto* records = static_cast<RayRecord*>(out.mutable_data());
  const auto from = origins.unchecked<2>();
  const double* moves = translations.data();
  const QueryFilter filter = filter_of(balls, walls, ignore, accept, mask);
  answer(filter, [&] {
    for (py::ssize_t i = 0; i < n; ++i) {
      const Vec2 d =
          one_translation ? Vec2{moves[0], moves[1]} : Vec2{moves[2 * i], moves[2 * i + 1]};
      const QueryHit hit = world.cast_ray(row(from, i), d, filter);
      RayRecord r{};
      r.kind = hit.kind == HitKind::ball ? 1 : hit.kind == HitKind::wall ? 2 : 0;
      r.ball = hit.kind == HitKind::ball ? id_number(hit.ball) : 0;
      r.wall = hit.kind == HitKind::wall ? hit.wall : 0;
      r.fraction = hit.fraction;
      r.point[0] = hit.point.x;
      r.point[1] = hit.point.y;
      r.normal[0] = hit.normal.x;
      r.normal[1] = hit.normal.y;
      std::memcpy(&records[i], &r, sizeof r);
    }
    return 0;
  });
  return out;
}

}  // namespace

void bind_queries(py::module_& m) {
  py::class_<QueryHit>(m, "QueryHit",
                       "What a ray or a cast ball meets first (World.cast_ray, World.cast_ball)")
      .def_property_readonly(
          "kind", [](const QueryHit& h) { return h.kind == HitKind::ball ? "ball" : "wall"; },
          "\"ball\" or \"wall\"")
      .def_property_readonly(
          "ball",
          [](const QueryHit& h) -> py::object {
            return h.kind == HitKind::ball ? py::object(py::int_(id_number(h.ball))) : py::none();
          },
          "The ball's id (None for a wall)")
      .def_property_readonly(
          "wall",
          [](const QueryHit& h) -> py::object {
            return h.kind == HitKind::wall ? py::object(py::int_(h.wall)) : py::none();
          },
          "The wall's id (None for a ball)")
      .def_readonly("fraction", &QueryHit::fraction,
                    "Where along the translation, in [0, 1]: start + fraction * translation")
      .def_readonly("point", &QueryHit::point, "The point of contact")
      .def_readonly("normal", &QueryHit::normal,
                    "Unit normal at the contact, from what was met back towards the caster")
      .def_readonly("center", &QueryHit::center,
                    "A cast ball's centre when it touches (a ray's: the point)")
      .def_readonly("overlapping", &QueryHit::overlapping,
                    "The cast ball started overlapping what it reports (fraction 0)")
      .def("__repr__", [](const QueryHit& h) {
        const std::string what = h.kind == HitKind::ball
                                     ? "ball " + std::to_string(id_number(h.ball))
                                     : "wall " + std::to_string(h.wall);
        return "<carom.QueryHit " + what + " at fraction " + std::to_string(h.fraction) + ">";
      });

  py::object world_type = m.attr("World");
  const auto add = [&world_type](const char* name, py::cpp_function function) {
    world_type.attr(name) = std::move(function);
  };
  add("cast_ray",
      py::cpp_function(
          [](const py::object& self, Vec2 origin, Vec2 translation, bool balls, bool walls,
             const std::optional<std::uint64_t>& ignore,
             const std::optional<std::function<bool(std::uint64_t)>>& accept, std::uint64_t mask) {
            const World& world = unwrap_world(self);
            const QueryFilter filter = filter_of(balls, walls, ignore, accept, mask);
            return hit_or_none(
                answer(filter, [&] { return world.cast_ray(origin, translation, filter); }));
          },
          py::is_method(world_type), py::name("cast_ray"), py::arg("origin"),
          py::arg("translation"), py::kw_only(), py::arg("balls") = true, py::arg("walls") = true,
          py::arg("ignore") = py::none(), py::arg("accept") = py::none(), py::arg("mask") = ~0ULL,
          "The first ball or wall the segment from origin to origin + translation meets, or "
          "None (a ray starting inside a ball does not see it; walls are met from either side). "
          "Filter: balls/walls False hides them, ignore an id, accept(id) -> bool, mask the "
          "categories seen (CollisionFilter.category bits)"));
  add("cast_ray_all",
      py::cpp_function(
          [](const py::object& self, Vec2 origin, Vec2 translation, bool balls, bool walls,
             const std::optional<std::uint64_t>& ignore,
             const std::optional<std::function<bool(std::uint64_t)>>& accept, std::uint64_t mask) {
            const World& world = unwrap_world(self);
            const QueryFilter filter = filter_of(balls, walls, ignore, accept, mask);
            return answer(filter, [&] { return world.cast_ray_all(origin, translation, filter); });
          },
          py::is_method(world_type), py::name("cast_ray_all"), py::arg("origin"),
          py::arg("translation"), py::kw_only(), py::arg("balls") = true, py::arg("walls") = true,
          py::arg("ignore") = py::none(), py::arg("accept") = py::none(), py::arg("mask") = ~0ULL,
          "Every ball and wall the segment meets, by fraction, each once (a list of QueryHit)"));
  add("cast_rays",
      py::cpp_function(
          &cast_rays, py::is_method(world_type), py::name("cast_rays"), py::arg("origins"),
          py::arg("translations"), py::kw_only(), py::arg("balls") = true, py::arg("walls") = true,
          py::arg("ignore") = py::none(), py::arg("accept") = py::none(), py::arg("mask") = ~0ULL,
          "cast_ray for N rays at once (origins (N, 2); translations (N, 2) or one "
          "(2,)): a structured array of first hits (kind: 0 nothing, 1 ball, 2 "
          "wall; ball, wall, fraction, point, normal), the GIL released"));
  add("cast_ball",
      py::cpp_function(
          [](const py::object& self, Vec2 center, double radius, Vec2 translation, bool balls,
             bool walls, const std::optional<std::uint64_t>& ignore,
             const std::optional<std::function<bool(std::uint64_t)>>& accept, std::uint64_t mask) {
            const World& world = unwrap_world(self);
            const QueryFilter filter = filter_of(balls, walls, ignore, accept, mask);
            return hit_or_none(answer(
                filter, [&] { return world.cast_ball(center, radius, translation, filter); }));
          },
          py::is_method(world_type), py::name("cast_ball"), py::arg("center"), py::arg("radius"),
          py::arg("translation"), py::kw_only(), py::arg("balls") = true, py::arg("walls") = true,
          py::arg("ignore") = py::none(), py::arg("accept") = py::none(), py::arg("mask") = ~0ULL,
          "A ball of radius at center moved by translation while the world stands still: the "
          "first ball or wall it touches, approaching, or None (started overlapping: fraction 0, "
          "overlapping). The pool aim line: ignore the cue ball"));
  add("balls_at_point",
      py::cpp_function(
          [](const py::object& self, Vec2 point, bool balls,
             const std::optional<std::uint64_t>& ignore,
             const std::optional<std::function<bool(std::uint64_t)>>& accept, std::uint64_t mask) {
            const World& world = unwrap_world(self);
            const QueryFilter filter = filter_of(balls, false, ignore, accept, mask);
            return id_array(answer(filter, [&] { return world.balls_at_point(point, filter); }));
          },
          py::is_method(world_type), py::name("balls_at_point"), py::arg("point"), py::kw_only(),
          py::arg("balls") = true, py::arg("ignore") = py::none(), py::arg("accept") = py::none(),
          py::arg("mask") = ~0ULL,
          "The ids of the balls holding the point (edge included), in the order of ids"));
  add("balls_in_circle",
      py::cpp_function(
          [](const py::object& self, Vec2 center, double radius, bool balls,
             const std::optional<std::uint64_t>& ignore,
             const std::optional<std::function<bool(std::uint64_t)>>& accept, std::uint64_t mask) {
            const World& world = unwrap_world(self);
            const QueryFilter filter = filter_of(balls, false, ignore, accept, mask);
            return id_array(
                answer(filter, [&] { return world.balls_in_circle(center, radius, filter); }));
          },
          py::is_method(world_type), py::name("balls_in_circle"), py::arg("center"),
          py::arg("radius"), py::kw_only(), py::arg("balls") = true, py::arg("ignore") = py::none(),
          py::arg("accept") = py::none(), py::arg("mask") = ~0ULL,
          "The ids of the balls touching or overlapping the circle, in the order of ids"));
  add("balls_in_box",
      py::cpp_function(
          [](const py::object& self, Vec2 lower, Vec2 upper, bool balls,
             const std::optional<std::uint64_t>& ignore,
             const std::optional<std::function<bool(std::uint64_t)>>& accept, std::uint64_t mask) {
            const World& world = unwrap_world(self);
            const QueryFilter filter = filter_of(balls, false, ignore, accept, mask);
            return id_array(
                answer(filter, [&] { return world.balls_in_box(lower, upper, filter); }));
          },
          py::is_method(world_type), py::name("balls_in_box"), py::arg("lower"), py::arg("upper"),
          py::kw_only(), py::arg("balls") = true, py::arg("ignore") = py::none(),
          py::arg("accept") = py::none(), py::arg("mask") = ~0ULL,
          "The ids of the balls touching or overlapping the box [lower, upper], in the order of "
          "ids"));
}

}  // namespace carom::python
