// carom internal: the bounce of a ball touching the inside of an arc, shared by the public
// carom::bounce_inside_arc and the world's engine (which has validated its values already).
// Why it turns flat velocities: include/carom/bounce.hpp and docs/derivation.md.
#pragma once

#include "carom/vec2.hpp"

namespace carom::detail {

struct BowlBounce {
  Vec2 velocity;
  double normal_speed_change = 0.0;  // (v − v')·n >= 0: the impulse divided by the mass
};

// normal: unit, from the ball away from the arc's centre. restitution in [0, 1].
[[nodiscard]] BowlBounce bounce_inside_arc(Vec2 velocity, Vec2 normal, double restitution);

}  // namespace carom::detail
