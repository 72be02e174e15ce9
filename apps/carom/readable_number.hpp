// carom tool: numbers for people to read. Six significant digits tell the story; --json gives
// every digit.
#pragma once

#include <string>

#include "carom/vec2.hpp"

namespace carom::cli {

// value to 6 significant digits, shortest form ("0.5", "1e-07"); -0 reads as 0.
[[nodiscard]] std::string readable(double value);
// "(x, y)", each as above.
[[nodiscard]] std::string readable(Vec2 v);

}  // namespace carom::cli
