// carom web: a scene file's text (an example from the site, or a file the user dropped on the
// page) turned into a DrawnWorld by carom's own scene library: parse_scene checks it and
// make_world builds it, pockets included.
#pragma once

#include <string>

#include "drawn_world.hpp"

namespace carom::web {

// Throws carom::SceneError ("NAME:LINE:COLUMN: PATH = VALUE: PROBLEM") for a scene that cannot
// be read or built; name is the file's name, for that message.
[[nodiscard]] DrawnWorld load_drawn_scene(const std::string& text, const std::string& name);

}  // namespace carom::web
