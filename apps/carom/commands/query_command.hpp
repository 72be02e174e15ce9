// carom tool: `carom query SCENE`, the world's queries (ray casts, ball casts, points, circles,
// boxes) asked of a scene at its start or after a run.
#pragma once

#include "commands/command.hpp"

namespace carom::cli {

// Adds the query verb and its options to app.
[[nodiscard]] Command add_query_command(CLI::App& app);

}  // namespace carom::cli
