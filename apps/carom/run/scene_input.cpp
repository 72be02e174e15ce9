#include "run/scene_input.hpp"

#include <cerrno>
#include <cstring>
#include <iostream>
#include <iterator>

#include "system/output_file.hpp"

namespace carom::cli {

Scene read_scene_argument(const std::string& name) {
  if (name != kStandardOutput) return load_scene(name);
  const std::string text((std::istreambuf_iterator<char>(std::cin)),
                         std::istreambuf_iterator<char>());
  if (std::cin.bad()) {
    throw SceneError({kStandardInputName, 0, 0, "", "",
                      std::string("cannot read: ") + std::strerror(errno), ""});
  }
  return parse_scene(text, kStandardInputName);
}

std::string scene_source_name(const std::string& name) {
  return name == kStandardOutput ? kStandardInputName : name;
}

}  // namespace carom::cli
