// carom internal: a ball against a segment or an arc that moves rigidly (carom/wall_motion.hpp):
// where the motion carries the wall, and the ball's first contact with it. A wall that only
// translates is met by the closed forms of the ball's motion relative to it; one that turns by
// certified advancement in the wall's own frame, where the wall stands still and the ball's
// centre follows a curve whose speed and acceleration are bounded over each step, so that a
// lower bound of every gap holds over the step and no contact is skipped. Derivation:
// docs/derivation.md, "Walls that turn".
#pragma once

#include "arc_frame.hpp"
#include "carom/shapes.hpp"
#include "carom/sweep.hpp"

namespace carom::detail {

// A rigid motion from now: a point x is at pivot + velocity·t + R(angular_velocity·t)(x − pivot)
// after t.
struct RigidMotion {
  Vec2 velocity;
  double angular_velocity = 0.0;
  Vec2 pivot;
};

// Where the motion carries x after t; exactly x + velocity·t when it does not turn.
[[nodiscard]] Vec2 carried_point(Vec2 x, const RigidMotion& motion, double t);
// The direction d turned as the motion turns it in t.
[[nodiscard]] Vec2 carried_direction(Vec2 d, const RigidMotion& motion, double t);
[[nodiscard]] Segment carried_segment(const Segment& segment, const RigidMotion& motion, double t);
// The arc carried, both as given (its angles turned, the start kept within ±π) and prepared.
void carry_arc(Arc& arc, ArcFrame& frame, const RigidMotion& motion, double t);

// The first approaching contact within [0, horizon] of a ball moving by `motion` with a wall
// moving by `rigid` (the wall's shape as it is now), and how far the search got: a search that
// ends early (a long horizon, or a slow approach that needs many steps) has found no contact in
// [0, checked] and must be asked again from there.
struct RigidContact {
  Impact impact;
  double checked = 0.0;
};
[[nodiscard]] RigidContact rigid_ball_segment(const Ball& ball, const Motion& motion,
                                              const Segment& segment, const RigidMotion& rigid,
                                              double horizon);
[[nodiscard]] RigidContact rigid_ball_arc(const Ball& ball, const Motion& motion, const Arc& arc,
                                          const ArcFrame& frame, const RigidMotion& rigid,
                                          double horizon);

}  // namespace carom::detail
