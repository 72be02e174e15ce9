// carom: walls that move. A segment or an arc of the world can be given a rigid motion between
// steps: its pivot moves with a constant velocity while the wall turns about the pivot at a
// constant angular velocity, for a duration, after which it stands still where the motion left
// it (a paddle, a piston, a pinball flipper swinging up to its stop). Balls meet it at exact
// times: a wall that only translates keeps the closed forms (the ball's motion relative to the
// wall), one that turns is met at the first root of its gap found by certified advancement,
// never by sampling. A bounce takes the wall's velocity at the contact point, so a moving wall
// does work on the balls it hits. The user guide: docs/world.md, "Moving walls".
#pragma once

#include <limits>

#include "carom/vec2.hpp"

namespace carom {

struct WallMotion {
  Vec2 velocity;                  // of the pivot
  double angular_velocity = 0.0;  // radians per unit of time, counter-clockwise
  Vec2 pivot;                     // the point the wall turns about, where it is now
  // How long the motion lasts from now; the wall then stands still. Infinite: for ever.
  double duration = std::numeric_limits<double>::infinity();

  // Whether the wall moves at all.
  [[nodiscard]] bool moves() const noexcept {
    return duration > 0.0 && (velocity != Vec2{} || angular_velocity != 0.0);
  }
  friend bool operator==(const WallMotion&, const WallMotion&) = default;
};

}  // namespace carom
