// carom scenes internal: the checks of a scene that look at more than one field — names unique,
// balls inside a closed box, no ball overlapping another ball, a wall or a pocket, generators
// able to place their balls.
#pragma once

#include <span>
#include <vector>

#include "carom/scene.hpp"
#include "json_walk.hpp"

namespace carom::scene_detail {

// A SceneError that still knows its JSON path as steps, so the reader can locate it in the text.
class PathedSceneError : public SceneError {
 public:
  PathedSceneError(JsonPath where, std::string value, std::string problem);
  [[nodiscard]] const JsonPath& where() const noexcept { return where_; }

 private:
  JsonPath where_;
};

// Overlaps up to this fraction of the sum of radii (of the radius, against a wall or a box) are
// touching, not errors: a running world keeps its balls apart only to rounding (World::audit's
// default tolerance is the same), so a state saved mid-run may hold such overlaps.
inline constexpr double kRoundingOverlap = 1e-9;

// Moves each ball that overlaps a wall, a box edge, a pocket or an earlier ball by no more than a
// rounding (as accepted above) clear of it, by twice the overlap, and again while a move left it
// on another (a settled pile saved by `carom run --save`): the world refuses any overlap,
// however small. Balls that do not touch anything are not moved, so scenes written by hand keep
// their positions exactly.
void separate_touching(const Scene& scene, std::vector<SceneBall>& balls);

// Throws PathedSceneError for the first problem found; returns the scene's balls expanded (as
// expand_balls does), which the checks had to compute anyway.
std::vector<SceneBall> check_scene(const Scene& scene);

}  // namespace carom::scene_detail
