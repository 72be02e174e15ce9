// carom CLI tests: scene files written into a scratch folder, and the shared example scenes.
#pragma once

#include <filesystem>
#include <string>

#include "run_tool.hpp"

namespace carom::cli::test {

// Writes text to dir/name and returns the path.
std::string write_scene(const ScratchDir& dir, const std::string& name, const std::string& text);

// Two balls in a periodic cell moving relative to each other along a line of slope 1 that keeps
// 5/√2 from every image of the other, more than the two radii: they never meet, and no rule can
// prove it, so a run to a contact never ends by itself (it follows cell crossings for ever).
inline constexpr const char* kEndlessOrbitScene = R"({
  "carom_scene": 1,
  "world": {"boundary": "periodic", "lower": [0, 0], "upper": [10, 10]},
  "balls": [
    {"position": [1, 1], "velocity": [0.5, 0.5], "radius": 1},
    {"position": [6, 1], "velocity": [-0.5, -0.5], "radius": 1}
  ]
})";

// The path of examples/NAME.
std::string example(const std::string& name);

}  // namespace carom::cli::test
