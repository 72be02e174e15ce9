// carom tool: one case of `carom sweep` (two balls moving during one step) and what the library
// says about it: when and where they touch, and how they leave.
#pragma once

#include <optional>

#include "carom/bounce.hpp"
#include "carom/shapes.hpp"
#include "carom/sweep.hpp"
#include "carom/vec2.hpp"

namespace carom::cli {

struct SweepCase {
  Ball a;
  Vec2 move_a;  // how far A moves during the step
  Ball b;
  Vec2 move_b;
  double mass_a = 1.0;  // > 0, or carom::kImmovable
  double mass_b = 1.0;
  double restitution = 1.0;  // in [0, 1]
};

struct SweepOutcome {
  Impact impact;       // from carom::sweep_ball_ball
  Vec2 relative_move;  // the tutorial's v3 = move_a − move_b: A's movement as seen from B
  // The movements after the bounce (carom::bounce at the contact), present when they touch.
  std::optional<BounceResult> bounce;
};

// Runs the library on the case. Bad values throw carom::InvalidArgument; masses and restitution
// only when the balls touch, since only then does carom::bounce see them (the sweep command
// checks them while parsing, so a bad one is an error either way).
[[nodiscard]] SweepOutcome solve(const SweepCase& sweep_case);

}  // namespace carom::cli
