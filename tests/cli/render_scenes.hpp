// carom CLI tests: small scene files for `carom render`, written into a test's scratch folder.
#pragma once

#include <stdlib.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "run_tool.hpp"

namespace carom::cli::test {

// A closed 10 × 10 box holding three coloured balls (two moving), two segments, one polyline,
// one arc and one pocket: every kind of thing a picture draws, each countable.
inline constexpr const char* kEveryKindScene = R"({
  "carom_scene": 1,
  "units": {"length": "m", "time": "s", "mass": "kg"},
  "world": {"boundary": "box", "lower": [0, 0], "upper": [10, 10]},
  "balls": [
    {"name": "a", "position": [2, 2], "velocity": [1, 0], "radius": 0.5, "color": "#2060c0"},
    {"name": "b", "position": [5, 2], "velocity": [0, 1], "radius": 0.5, "color": "red"},
    {"name": "c", "position": [8, 2], "radius": 0.5, "color": "#0a0"}
  ],
  "segments": [{"a": [1, 5], "b": [4, 5]}, {"a": [6, 5], "b": [9, 5]}],
  "polylines": [{"points": [[1, 8], [2, 9], [3, 8]]}],
  "arcs": [{"center": [7, 8], "radius": 1, "start_angle": 0, "end_angle": 3}],
  "pockets": [{"position": [9.5, 9.5], "radius": 0.3}]
}
)";

// One large ball at rest in the middle of a 10 × 10 box: its centre is far from any edge.
inline constexpr const char* kOneBallScene = R"({
  "carom_scene": 1,
  "world": {"boundary": "box", "lower": [0, 0], "upper": [10, 10]},
  "balls": [{"name": "big", "position": [5, 5], "radius": 3, "color": "#2060c0"}]
}
)";

// Two balls crossing an open plane: the tutorial's case.
inline constexpr const char* kTwoBallsScene = R"({
  "carom_scene": 1,
  "world": {"boundary": "open"},
  "balls": [
    {"name": "A", "position": [0, 0], "velocity": [6, 2], "radius": 1},
    {"name": "B", "position": [8, 3], "velocity": [-4, -1], "radius": 1.5}
  ]
}
)";

// Runs the tool like run_carom. Under LeakSanitizer (the asan preset), fontconfig's own leaks,
// reached through Cairo's text drawing, are suppressed for the tool: see lsan_fontconfig.supp.
// Every other leak is still reported.
inline ToolRun run_render(const std::vector<std::string>& args) {
  static const bool suppressed = [] {
    std::string options = "suppressions=" CAROM_LSAN_SUPPRESSIONS ":print_suppressions=0";
    if (const char* given = std::getenv("LSAN_OPTIONS"))
      options = std::string(given) + ":" + options;
    return ::setenv("LSAN_OPTIONS", options.c_str(), 1) == 0;
  }();
  (void)suppressed;
  return run_carom(args);
}

// Writes text to dir/name and returns the path as a string for the command line.
inline std::string write_test_scene(const ScratchDir& dir, const std::string& name,
                                    const std::string& text) {
  const std::filesystem::path path = dir / name;
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file != nullptr) {
    std::fwrite(text.data(), 1, text.size(), file);
    std::fclose(file);
  }
  return path.string();
}

// How many times needle occurs in text.
inline int count_of(const std::string& text, const std::string& needle) {
  int n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos;
       at = text.find(needle, at + needle.size())) {
    ++n;
  }
  return n;
}

}  // namespace carom::cli::test
