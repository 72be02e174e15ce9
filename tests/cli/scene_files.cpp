#include "scene_files.hpp"

#include <fstream>

namespace carom::cli::test {

std::string write_scene(const ScratchDir& dir, const std::string& name, const std::string& text) {
  const std::filesystem::path path = dir / name;
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

std::string example(const std::string& name) {
  return (std::filesystem::path(CAROM_EXAMPLES_DIR) / name).string();
}

}  // namespace carom::cli::test
