// carom internal: a ball on a cloth table under the standard friction model (pool physics): its
// velocity, its spin about the three axes, and the motion states it passes through — sliding
// (its contact point slips on the cloth), rolling, spinning in place, at rest — each a
// polynomial in time, each ending at a closed-form time. Derivation: docs/derivation.md,
// "A ball on a cloth".
#pragma once

#include <cstdint>

#include "carom/vec2.hpp"

namespace carom::detail {

// The cloth: gravity's magnitude normal to the table and the three friction coefficients.
struct Cloth {
  double g = 9.81;
  double sliding = 0.2;     // μs: the contact point slips
  double rolling = 0.01;    // μr: rolling resistance
  double spinning = 0.044;  // μsp: spin about the vertical axis
};

enum class TableState : std::uint8_t { sliding, rolling, spinning, stationary };

// A ball's state on the table: its centre's velocity and its angular velocity (x and y in the
// table's plane, z about the vertical, counter-clockwise seen from above).
struct TableBall {
  Vec2 velocity;
  Vec2 spin;           // ωx, ωy
  double twist = 0.0;  // ωz ("English")
  double radius = 0.0;
};

// The velocity of the ball's contact point with the cloth: v + ω × (0, 0, −R).
[[nodiscard]] Vec2 contact_velocity(const TableBall& ball);

// Which state a ball is in: sliding while its contact point moves (beyond a rounding of the
// speeds involved), rolling while it moves without slipping, spinning while only its twist is
// left, stationary otherwise.
[[nodiscard]] TableState table_state(const TableBall& ball);

// How long the ball stays in its present state (infinite when stationary).
[[nodiscard]] double time_in_state(const TableBall& ball, const Cloth& cloth);

// The ball `t` after now (t within time_in_state), and how far its centre has moved: both
// polynomials in t of degree 1 and 2 within one state.
struct TableStep {
  TableBall ball;
  Vec2 displacement;
};
[[nodiscard]] TableStep evolve(const TableBall& ball, const Cloth& cloth, double t);

// The acceleration of the centre in the present state (constant within it).
[[nodiscard]] Vec2 table_acceleration(const TableBall& ball, const Cloth& cloth);

// A cue's strike: the cue (mass `cue_mass`) moving at `speed` along `direction` (an angle in the
// table's plane, radians) and tilted `elevation` above the table, its tip meeting the ball
// `side` to the right of the line through the centre and `height` above it, both measured across
// the cue as the player sees the ball (side² + height² < R²), bouncing with `restitution`.
struct CueStrike {
  double speed = 0.0;
  double direction = 0.0;
  double elevation = 0.0;
  double side = 0.0;
  double height = 0.0;
  double cue_mass = 0.54;
  double restitution = 1.0;
};

// The ball at rest struck so (mass `mass`, radius `radius`): one impulse along the cue through
// the tip's point of contact (no tip friction, no squirt), the table taking its downward part (no
// jump). Derivation: docs/derivation.md, "A ball on a cloth".
[[nodiscard]] TableBall strike(const CueStrike& cue, double mass, double radius);

// Two equal balls on the table meeting, `normal` the unit vector from a's centre to b's: the
// normal impulse of restitution `restitution` through the centres, and the friction of the balls'
// surfaces (coefficient `friction`) against their slip at the contact point, which throws the
// struck ball off the line of centres and changes both spins; the friction stops at sticking.
// Vertical velocities are not kept (the balls stay on the table). Derivation: docs/derivation.md,
// "A ball on a cloth".
void collide_on_table(TableBall& a, TableBall& b, Vec2 normal, double restitution, double friction);

}  // namespace carom::detail
