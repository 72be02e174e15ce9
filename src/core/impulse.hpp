// carom internal: the arithmetic of a frictionless bounce along a unit normal, shared by
// carom::bounce and the World's response so that both answer a contact with the same operations
// (docs/derivation.md, "The bounce"; docs/decisions/0016-response-repeats-bounce.md).
#pragma once

#include "carom/vec2.hpp"

namespace carom::detail {

// The magnitude of the normal impulse between two balls approaching at `approach` (> 0) along
// the unit normal, with inverse masses inverse_a and inverse_b (0 for an immovable ball; not
// both 0) and restitution e.
[[nodiscard]] inline double normal_impulse(double approach, double inverse_a, double inverse_b,
                                           double restitution) noexcept {
  return (1.0 + restitution) * approach / (inverse_a + inverse_b);
}

// Both velocities after the impulse along the unit normal n (from a towards b).
inline void apply_impulse(Vec2& velocity_a, Vec2& velocity_b, Vec2 n, double impulse,
                          double inverse_a, double inverse_b) noexcept {
  velocity_a -= n * (impulse * inverse_a);
  velocity_b += n * (impulse * inverse_b);
}

// The change of a ball's speed along the unit normal of a static wall it meets at `approach`
// (> 0) with restitution e: its velocity loses n times this.
[[nodiscard]] inline double wall_speed_change(double approach, double restitution) noexcept {
  return (1.0 + restitution) * approach;
}

}  // namespace carom::detail
