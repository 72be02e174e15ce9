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

// Throws PathedSceneError for the first problem found; returns the scene's balls expanded (as
// expand_balls does), which the checks had to compute anyway.
std::vector<SceneBall> check_scene(const Scene& scene);

}  // namespace carom::scene_detail
