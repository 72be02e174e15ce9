// carom scenes internal: the scene's walls as a flat list in the world's order, and distances to
// them (carom/geometry.hpp's, the World's own).
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "carom/number_text.hpp"
#include "carom/scene.hpp"
#include "json_walk.hpp"

namespace carom::scene_detail {

// One wall of the scene and where it came from ("segments[2]", "polylines[0].points[3]").
struct SceneWall {
  std::variant<Segment, Arc> shape;
  JsonPath path;
  CollisionFilter filter;
};

// Segments, then each polyline's segments, then arcs: the order make_world adds them in.
[[nodiscard]] std::vector<SceneWall> scene_walls(const Scene& scene);

[[nodiscard]] double distance_to_wall(const SceneWall& wall, Vec2 p);

}  // namespace carom::scene_detail
