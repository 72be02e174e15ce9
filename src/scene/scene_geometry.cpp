#include "scene_geometry.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace carom::scene_detail {

Vec2 nearest_point(const Segment& segment, Vec2 p) {
  const Vec2 along = segment.b - segment.a;
  const double length_sq = length_squared(along);
  if (!(length_sq > 0.0)) return segment.a;
  const double t = std::clamp(dot(p - segment.a, along) / length_sq, 0.0, 1.0);
  return segment.a + along * t;
}

Vec2 nearest_point(const Arc& arc, Vec2 p) {
  const Vec2 start =
      arc.center + Vec2{std::cos(arc.start_angle), std::sin(arc.start_angle)} * arc.radius;
  const Vec2 end = arc.center + Vec2{std::cos(arc.end_angle), std::sin(arc.end_angle)} * arc.radius;
  const Vec2 offset = p - arc.center;
  if (length_squared(offset) > 0.0) {
    // The angle of p measured counter-clockwise from the start, in [0, 2π).
    const double two_pi = 2.0 * std::numbers::pi;
    double angle = std::atan2(offset.y, offset.x) - arc.start_angle;
    angle = std::fmod(angle, two_pi);
    if (angle < 0.0) angle += two_pi;
    if (angle <= arc.end_angle - arc.start_angle) {
      return arc.center + normalized(offset) * arc.radius;
    }
  }
  return length_squared(start - p) <= length_squared(end - p) ? start : end;
}

std::vector<SceneWall> scene_walls(const Scene& scene) {
  std::vector<SceneWall> walls;
  for (std::size_t i = 0; i < scene.segments.size(); ++i) {
    walls.push_back({scene.segments[i], {std::string("segments"), i}});
  }
  for (std::size_t i = 0; i < scene.polylines.size(); ++i) {
    const ScenePolyline& polyline = scene.polylines[i];
    const std::size_t n = polyline.points.size();
    const std::size_t count = polyline.closed ? n : n - 1;
    for (std::size_t k = 0; k < count; ++k) {
      walls.push_back({Segment{polyline.points[k], polyline.points[(k + 1) % n]},
                       {std::string("polylines"), i, std::string("points"), k}});
    }
  }
  for (std::size_t i = 0; i < scene.arcs.size(); ++i) {
    walls.push_back({scene.arcs[i], {std::string("arcs"), i}});
  }
  return walls;
}

double distance_to_wall(const SceneWall& wall, Vec2 p) {
  return std::visit([p](const auto& shape) { return distance(nearest_point(shape, p), p); },
                    wall.shape);
}

std::string number_text(double value) {
  std::array<char, 32> buffer{};
#if defined(__cpp_lib_to_chars)
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return {buffer.data(), result.ptr};
#else
  // The libc++ of Debian's emscripten 3.1.6 (the wasm preset) cannot print doubles with
  // to_chars; 17 significant digits also read back exactly, if not always the shortest way.
  const int length = std::snprintf(buffer.data(), buffer.size(), "%.17g", value);
  return {buffer.data(), static_cast<std::size_t>(length)};
#endif
}

}  // namespace carom::scene_detail
