// carom internal: a ball on a cloth table under the standard friction model (pool physics): its
// velocity, its spin about the three axes, and the motion states it passes through — sliding
// (its contact point slips on the cloth), rolling, spinning in place, at rest — each a
// polynomial in time, each ending at a closed-form time. Derivation: docs/derivation.md,
// "A ball on a cloth".
#pragma once

#include <cstdint>

#include "carom/table.hpp"
#include "carom/vec2.hpp"

namespace carom::detail {

// The cloth: gravity's magnitude normal to the table and the three friction coefficients.
struct Cloth {
  double g = 9.81;
  double sliding = 0.2;     // μs: the contact point slips
  double rolling = 0.01;    // μr: rolling resistance
  double spinning = 0.044;  // μsp: spin about the vertical axis
};

using TableState = MotionState;

// A ball's state on the table: its centre's velocity and its angular velocity (x and y in the
// table's plane, z about the vertical, counter-clockwise seen from above).
struct TableBall {
  Vec2 velocity;
  Vec2 spin;           // ωx, ωy
  double twist = 0.0;  // ωz ("English")
  double radius = 0.0;
  double mass = 1.0;  // (or kImmovable: collisions read it)
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

// A state as the world keeps it from the moment it begins: which, the centre's acceleration in
// it, and how long it lasts. Fixed for the state's whole length, so that the rounding of the
// values in between never changes what the ball does.
struct StateMotion {
  TableState state = TableState::stationary;
  Vec2 acceleration;
  double duration = 0.0;  // infinite when stationary
};
[[nodiscard]] StateMotion state_motion(const TableBall& ball, const Cloth& cloth);

// The ball `t` into a state that began as `ball` (0 <= t <= motion.duration): its velocity
// v + a·t, its spin, its twist. The centre's displacement is v·t + ½·a·t², as the world's.
[[nodiscard]] TableBall advance_in_state(const TableBall& ball, const StateMotion& motion,
                                         const Cloth& cloth, double t);
// The ball at the end of that state, exactly: a slide ends with the rolling spin, a roll with
// the ball still, a spin with no twist.
[[nodiscard]] TableBall end_of_state(const TableBall& ball, const StateMotion& motion,
                                     const Cloth& cloth);

// The ball at rest struck so (mass `mass`, radius `radius`): one impulse along the cue through
// the tip's point of contact (no tip friction, no squirt), the table taking its downward part (no
// jump). Derivation: docs/derivation.md, "A ball on a cloth".
[[nodiscard]] TableBall strike(const CueStrike& cue, double mass, double radius);

// Two balls on the table meeting, `normal` the unit vector from a's centre to b's (masses and
// radii their own; an immovable one, mass kImmovable, keeps its motion): the normal impulse of
// restitution `restitution` through the centres, and the friction of the balls' surfaces
// (coefficient `friction`) against their slip at the contact point, which throws the struck
// ball off the line of centres and changes both spins; the friction stops at sticking.
// Vertical velocities are not kept (the balls stay on the table). The normal impulse is
// returned. Derivation: docs/derivation.md, "A ball on a cloth".
double collide_on_table(TableBall& a, TableBall& b, Vec2 normal, double restitution,
                        double friction);

// A slow contact that friction presses together (docs/derivation.md, "A ball on a cloth"): each
// movable ball's slip is taken by the cloth's sticking impulse (it rolls, as at the end of a
// slide), then the two roll on at their common velocity (the momentum-weighted mean; an
// immovable ball's own), so that nothing presses them together any more. Energy only falls.
void roll_together(TableBall& a, TableBall& b);
// The same for a ball pressed into a cushion (`normal` from the centre towards it): it rolls,
// and its velocity into the cushion is taken.
void roll_along(TableBall& ball, Vec2 normal);

// A cushion: its nose's height as a share of the ball's diameter, its restitution and friction.
struct Cushion {
  double height = 0.635;
  double restitution = 0.85;
  double friction = 0.2;
};

// A ball meeting a cushion, `normal` the unit vector in the table's plane from its centre
// towards the cushion: Han's model (2005), the contact on the nose above the ball's equator,
// one impulse of normal restitution and Coulomb friction against the contact point's slip
// (stopping at sticking), the table taking its vertical part; what is left of the approach in
// the plane (a nose far above the equator) is stopped by the cushion's face. Returns the change
// of the velocity along `normal` (its size). Derivation: docs/derivation.md, "A ball on a
// cloth".
double cushion_bounce(TableBall& ball, Vec2 normal, const Cushion& cushion);

}  // namespace carom::detail
