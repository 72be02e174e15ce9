#include "scene_geometry.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "carom/geometry.hpp"

namespace carom::scene_detail {

std::vector<SceneWall> scene_walls(const Scene& scene) {
  std::vector<SceneWall> walls;
  for (std::size_t i = 0; i < scene.segments.size(); ++i) {
    walls.push_back({scene.segments[i],
                     {std::string("segments"), i},
                     scene.segment_filters.empty() ? CollisionFilter{} : scene.segment_filters[i]});
  }
  for (std::size_t i = 0; i < scene.polylines.size(); ++i) {
    const ScenePolyline& polyline = scene.polylines[i];
    const std::size_t n = polyline.points.size();
    const std::size_t count = polyline.closed ? n : n - 1;
    for (std::size_t k = 0; k < count; ++k) {
      walls.push_back({Segment{polyline.points[k], polyline.points[(k + 1) % n]},
                       {std::string("polylines"), i, std::string("points"), k},
                       polyline.filter});
    }
  }
  for (std::size_t i = 0; i < scene.arcs.size(); ++i) {
    walls.push_back({scene.arcs[i],
                     {std::string("arcs"), i},
                     scene.arc_filters.empty() ? CollisionFilter{} : scene.arc_filters[i]});
  }
  return walls;
}

double distance_to_wall(const SceneWall& wall, Vec2 p) {
  return std::visit([p](const auto& shape) { return carom::distance(shape, p); }, wall.shape);
}

}  // namespace carom::scene_detail
