// carom web: a billiards table's calls (carom/table.hpp) for a page, balls by their DrawnWorld
// index. A cue strike is a JavaScript object {speed, direction, side, height, elevation}, each
// optional but speed (carom::CueStrike's fields and defaults: direction and elevation in radians,
// side and height in the world's units across the cue); a spin is {x, y, z}.
#pragma once

#include <emscripten/val.h>

#include <string>

#include "drawn_world.hpp"

namespace carom::web {

// World::strike; a field that is not a number is refused with its name and value.
void strike(DrawnWorld& w, int index, const emscripten::val& cue);
[[nodiscard]] emscripten::val spin(const DrawnWorld& w, int index);
void set_spin(DrawnWorld& w, int index, const emscripten::val& spin);
// "sliding", "rolling", "spinning" or "stationary".
[[nodiscard]] std::string motion_state(const DrawnWorld& w, int index);
[[nodiscard]] bool at_rest(const DrawnWorld& w);
// The world's Table as an object of its fields, or null for a world without one.
[[nodiscard]] emscripten::val table(const DrawnWorld& w);
// DrawnWorld::copy, for JavaScript to own (and delete).
[[nodiscard]] DrawnWorld* copy_world(const DrawnWorld& w);

}  // namespace carom::web
