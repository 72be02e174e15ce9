// carom tool: the SCENE argument of the verbs that read a scene: a file, or "-" for standard
// input (so that a scene can come from a pipe: `generate | carom run - --until 10`).
#pragma once

#include <string>

#include "carom/scene.hpp"

namespace carom::cli {

// The name standard input goes by in messages.
inline constexpr const char* kStandardInputName = "<stdin>";

// Reads and parses the scene `name` names. Throws SceneError (file, line, column, field).
[[nodiscard]] Scene read_scene_argument(const std::string& name);

// The name to report the scene under: the file's name, or kStandardInputName for "-".
[[nodiscard]] std::string scene_source_name(const std::string& name);

}  // namespace carom::cli
