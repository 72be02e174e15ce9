// carom tool: `carom render SCENE`: a picture of a scene at a time (SVG or PNG), an animation of
// a run (GIF or MP4, through ffmpeg), or a plot of energy, momentum or the collision rate (SVG).
#pragma once

#include "commands/command.hpp"

namespace carom::cli {

// Adds the render verb and its options to app.
[[nodiscard]] Command add_render_command(CLI::App& app);

}  // namespace carom::cli
