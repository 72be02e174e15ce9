// carom: the response to a contact found by carom::sweep_* / time_of_impact_*.
//
// All bounces act along the contact normal only (frictionless balls): the parts of the
// velocities across the normal are kept. A pair already separating along the normal receives no
// impulse. Derivation of the impulse and of the equal-mass exchange: docs/derivation.md.
#pragma once

#include <limits>

#include "carom/vec2.hpp"

namespace carom {

// The mass of a ball that nothing moves (a fixed post, a bumper). Only bounce arguments accept it.
inline constexpr double kImmovable = std::numeric_limits<double>::infinity();

struct BounceResult {
  Vec2 velocity_a;  // A's velocity after the bounce
  Vec2 velocity_b;  // B's velocity after the bounce
  // Magnitude (>= 0) of the normal impulse: A receives −impulse·normal, B +impulse·normal.
  // 0 when the pair was not approaching.
  double impulse = 0.0;
};

// Two balls of masses mass_a and mass_b (> 0, or kImmovable; not both kImmovable) touching with
// normal pointing from A to B (any length; it is normalised). restitution e in [0, 1] scales the
// normal relative speed: it leaves at e times the speed it arrived with. Momentum is conserved to
// rounding; kinetic energy is conserved for e = 1 and otherwise drops by
// (1 − e²)/2 · m_a·m_b/(m_a + m_b) · (approach speed)².
[[nodiscard]] BounceResult bounce(Vec2 velocity_a, double mass_a, Vec2 velocity_b, double mass_b,
                                  Vec2 normal, double restitution = 1.0);

// The tutorial's equal-mass bounce: split each velocity into its part along the line of centres
// (from A's centre to B's) and its part across it; the balls exchange the parts along. For an
// approaching pair it equals bounce() with equal masses and e = 1 to rounding; unlike bounce()
// it exchanges even when the pair separates, exactly as the tutorial's construction does. The
// impulse reported is that of unit masses, (v_a − v_b)·n̂: negative for a separating pair.
[[nodiscard]] BounceResult bounce_equal_mass(Vec2 velocity_a, Vec2 velocity_b,
                                             Vec2 line_of_centres);

struct WallBounceResult {
  Vec2 velocity;         // the ball's velocity after the bounce
  double impulse = 0.0;  // magnitude (>= 0); the ball receives −impulse·normal
};

// A ball of the given mass (> 0, finite) against a static segment, point or arc, normal pointing
// from the ball towards the touched point (as carom::Impact gives it).
[[nodiscard]] WallBounceResult bounce_off_static(Vec2 velocity, double mass, Vec2 normal,
                                                 double restitution = 1.0);

// The sines of the angles to the wall below which a ball in a bowl counts as sliding, and at
// which it leaves at least (bounce_inside_arc).
inline constexpr double kBowlSlidingSine = 0x1p-6;
inline constexpr double kBowlLeavingSine = 0x1p-7;

// A ball of the given mass (> 0, finite) touching the inside of an arc (a ball in a bowl),
// normal pointing from the ball away from the arc's centre (as carom::Impact gives it). Inside
// a circle a ball that leaves the wall flat re-enters it at once (the gap closes at second
// order): the limit of ever flatter bounces is sliding along the circle, which no straight path
// follows, and a flat bounce changes nothing. So here, unlike bounce_off_static:
// - a ball arriving flatter than kBowlSlidingSine (the sine of its angle to the wall) is
//   sliding, and bounces elastically whatever the restitution (a frictionless wall does no work
//   on a sliding ball);
// - a ball never leaves flatter than kBowlLeavingSine: a velocity that would is turned to that
//   angle, its speed kept (the one turn in carom that is not along the normal; it changes the
//   speed along the wall by less than 2^-15 of the speed).
// A ball sliding round a bowl then bounces every 2^-6·ρ of travel or more (ρ: the arc's radius
// less the ball's), keeps its speed, and stays within 2^-13·ρ of the circle it slides along.
// docs/derivation.md, "A ball sliding in a bowl".
[[nodiscard]] WallBounceResult bounce_inside_arc(Vec2 velocity, double mass, Vec2 normal,
                                                 double restitution = 1.0);

}  // namespace carom
