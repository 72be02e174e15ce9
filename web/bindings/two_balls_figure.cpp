#include "two_balls_figure.hpp"

namespace carom::web {

TwoBallsFigure two_balls_figure(const TwoBallsInput& in) {
  TwoBallsFigure figure;
  figure.impact = sweep_ball_ball(in.a, in.move_a, in.b, in.move_b);
  figure.v3 = in.move_a - in.move_b;
  figure.a_end = in.a.center + in.move_a;
  figure.b_end = in.b.center + in.move_b;
  figure.a_relative_at = in.a.center + figure.v3 * figure.impact.t;
  // The masses and restitution are checked even when the balls miss, so that a bad slider value
  // is reported at once rather than at the first contact.
  const BounceResult check = bounce({}, in.mass_a, {}, in.mass_b, {1.0, 0.0}, in.restitution);
  static_cast<void>(check);
  if (figure.impact.hit) {
    figure.split_a = decompose(in.move_a, figure.impact.normal);
    figure.split_b = decompose(in.move_b, figure.impact.normal);
    figure.after =
        bounce(in.move_a, in.mass_a, in.move_b, in.mass_b, figure.impact.normal, in.restitution);
  }
  return figure;
}

}  // namespace carom::web
