// carom tool: how `carom render` colours balls — by speed on a colour scale, or by the colour or
// name the scene gives them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "carom/scene.hpp"
#include "drawing/css_colour.hpp"

namespace carom::cli {

enum class ColourMode {
  speed,  // a colour scale from slow to fast, with a legend
  name,   // the scene's colour; else one colour per name (a generator's balls share one)
};

// The speed scale: viridis (perceptually uniform, readable in grey and by most colour-blind
// readers), from dark blue at 0 to yellow at 1. fraction is clamped to [0, 1].
[[nodiscard]] Rgb speed_colour(double fraction);

// Immovable balls have no speed worth showing: they are drawn in this grey in either mode.
inline constexpr Rgb kImmovableColour = rgb_from_hex(0x808080);

// Whether the scene colours any ball (a ball's or a generator's "color"): pictures then draw the
// balls in their own colours rather than by speed.
[[nodiscard]] bool scene_gives_colours(const Scene& scene);

// The colour of each of the scene's expanded balls (as from expand_balls) in name mode: its own
// colour; else a colour picked by its name (the part before '#', so NAME#1 and NAME#2 match);
// else grey. Throws carom::SceneError naming the field (balls[i].color or generators[g].color)
// for a colour text carom cannot draw, so a bad colour stops the run before any work.
[[nodiscard]] std::vector<Rgb> named_ball_colours(const Scene& scene,
                                                  const std::vector<SceneBall>& balls,
                                                  std::string_view scene_file);

}  // namespace carom::cli
