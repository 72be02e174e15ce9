#include "sweep/sweep_case.hpp"

namespace carom::cli {

SweepOutcome solve(const SweepCase& c) {
  SweepOutcome outcome;
  outcome.impact = sweep_ball_ball(c.a, c.move_a, c.b, c.move_b);
  outcome.relative_move = c.move_a - c.move_b;
  if (outcome.impact.hit) {
    outcome.bounce =
        bounce(c.move_a, c.mass_a, c.move_b, c.mass_b, outcome.impact.normal, c.restitution);
  }
  return outcome;
}

}  // namespace carom::cli
