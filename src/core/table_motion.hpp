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

}  // namespace carom::detail
