// carom web: everything the "Two moving balls" page draws and prints, computed by the library in
// one call, so that the page itself holds no physics. It follows the tutorial's construction:
// the relative movement v3, the contact, the split of both movements along the line of centres
// and across it, and the movements after the bounce.
#pragma once

#include "carom/bounce.hpp"
#include "carom/shapes.hpp"
#include "carom/sweep.hpp"
#include "carom/vec2.hpp"

namespace carom::web {

struct TwoBallsInput {
  Ball a;
  Vec2 move_a;  // how far A moves during the step
  Ball b;
  Vec2 move_b;
  double mass_a = 1.0;
  double mass_b = 1.0;
  double restitution = 1.0;
};

struct TwoBallsFigure {
  Impact impact;  // carom::sweep_ball_ball, exactly what `carom sweep` reports
  Vec2 v3;        // A's movement as seen from B: move_a − move_b
  Vec2 a_end;     // where each would be at the end of the step without contact
  Vec2 b_end;
  Vec2 a_relative_at;  // A's centre at contact in B's frame: a.center + t·v3 (the tutorial's p4)
  // At contact only (impact.hit): each movement split along the line of centres (normal) and
  // across it, and the movements after carom::bounce with the given masses and restitution.
  Components split_a;
  Components split_b;
  BounceResult after;
};

// Throws carom::InvalidArgument for a bad ball, movement, mass or restitution.
[[nodiscard]] TwoBallsFigure two_balls_figure(const TwoBallsInput& input);

}  // namespace carom::web
