#include "scene_loading.hpp"

#include "carom/scene.hpp"

namespace carom::web {

DrawnWorld load_drawn_scene(const std::string& text, const std::string& name) {
  return DrawnWorld(make_world(parse_scene(text, name)));
}

}  // namespace carom::web
