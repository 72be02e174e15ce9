// carom tool: a scene's picture as the bytes of a file — SVG, or PNG painted by Cairo — for the
// verbs that draw one picture (render, shot).
#pragma once

#include <optional>
#include <string>

#include "drawing/scene_picture.hpp"

namespace carom::cli {

inline constexpr int kPictureWidth = 960;  // pixels: a PNG picture's default width

struct PictureFile {
  std::string bytes;
  int width = 0;  // a PNG's pixels (0 for SVG, which has none)
  int height = 0;
};

// The picture as SVG (with arrows `arrow_seconds` long, when drawn) or as a PNG `width` pixels
// wide. Throws std::runtime_error when Cairo cannot encode the PNG.
[[nodiscard]] PictureFile encode_picture(const ScenePicture& picture, bool svg, int width,
                                         std::optional<double> arrow_seconds);

}  // namespace carom::cli
