// carom: exact time of impact of a moving ball against another ball, a point, a segment or an arc.
//
// Two forms of every query:
// - time form, time_of_impact_*: velocities in length per time unit and a horizon (>= 0); the
//   impact time t lies in [0, horizon].
// - step form, sweep_*: the tutorial's movement vectors (how far each ball moves during the step);
//   t is the fraction of the step in [0, 1]. It is the time form with horizon 1.
//
// The answer is closed form (a quadratic solved with the cancellation-free root; see
// docs/derivation.md). How to use it: move both balls to a_at and b_at (or advance them by t),
// then respond with carom::bounce using impact.normal.
//
// Conventions, kept by every query:
// - normal is a unit vector from A (the first, moving ball) towards B (the other ball or the
//   static shape). For ball against ball it is the direction from A's centre to B's centre.
// - A contact counts only when the two approach at that instant. Touching and separating, or
//   a tangential graze (the relative motion only brushes the contact distance), is no hit —
//   except on the inside of an arc, where a ball touching the wall and moving along it enters
//   it at second order: a hit at t = 0 with normal speed 0, which carom::bounce_inside_arc
//   answers (a plain bounce would change nothing).
// - Starting overlapped is reported, never hidden: overlapping is set, t = 0, a_at/b_at are the
//   start positions and normal points from A to B's nearest part; hit is set only when they
//   approach (a caller resolving contacts must then respond at once).
// - All arguments are validated: NaN or infinite values, radius <= 0, a negative horizon, an
//   arc span outside [0, 2π] or an arc whose circle reaches beyond the double range
//   (max(|center.x|, |center.y|) + radius overflows) throw carom::InvalidArgument naming the
//   argument and its value.
//
// Numeric range: every other input is answered, whatever its magnitude — from the subnormals
// (5e-324) to ±1.8e308, lengths and speeds at unrelated scales. The answer is either a hit with
// t in [0, horizon] and a unit normal, or no hit (t = 0); no field is ever NaN. Inside a window
// of ordinary magnitudes (squared lengths and speeds within 2^±500, about 1e±150) the closed form
// is used as it stands; outside it the problem is scaled by powers of two, which changes no
// rounding, so the answer is the one for the same problem scaled to ordinary magnitudes (t
// the same; positions scaled): bit for bit for two balls and a point, to the last bit of a
// hypot for segments and arcs. Degenerate limits, all at the rounding level: terms
// below 2^-1000 of the largest are lost; a radius more than 2^1000 below the distance decides
// contact by the path's distance to the centre; a position whose true value lies beyond
// ±1.8e308 is reported as ±infinity. Derivation and tests: docs/derivation.md §5,
// docs/guarantees.md.
//
// Edge inputs, each exact: a point is a ball of radius zero, a segment whose ends coincide is
// exactly that point, an arc of zero span is its one point; touching at the start counts as in
// the rules above (approaching: hit at t = 0, not overlapping; leaving or sliding: no hit); a
// centre exactly on a point, segment or arc counts as approaching whenever it moves.
#pragma once

#include "carom/shapes.hpp"
#include "carom/vec2.hpp"

namespace carom {

struct Impact {
  bool hit = false;          // they come into contact, approaching, within [0, horizon]
  bool overlapping = false;  // they already overlap at t = 0
  double t = 0.0;            // time (or fraction of the step) of the contact; 0 when no hit
  Vec2 a_at;                 // A's centre at t
  Vec2 b_at;                 // B's centre at t; for a static shape, the touched point (= point)
  Vec2 normal;               // unit, from A towards B, at t
  Vec2 point;                // the contact point, on A's surface and on B's
};

// ---- time form -------------------------------------------------------------------------------

// Two balls moving with constant velocities. Symmetric: swapping A and B gives the same t and
// the opposite normal.
[[nodiscard]] Impact time_of_impact_ball_ball(const Ball& a, Vec2 velocity_a, const Ball& b,
                                              Vec2 velocity_b, double horizon);

// A moving ball against a fixed point (a ball of radius zero, or the corner of a wall).
[[nodiscard]] Impact time_of_impact_ball_point(const Ball& a, Vec2 velocity_a, Vec2 point,
                                               double horizon);

// A moving ball against a fixed segment: its interior from either side, and its end points.
[[nodiscard]] Impact time_of_impact_ball_segment(const Ball& a, Vec2 velocity_a,
                                                 const Segment& segment, double horizon);

// A moving ball against a fixed arc: from outside, from inside (a ball in a bowl), and at the
// arc's end points.
[[nodiscard]] Impact time_of_impact_ball_arc(const Ball& a, Vec2 velocity_a, const Arc& arc,
                                             double horizon);

// ---- under a constant acceleration -----------------------------------------------------------

// A ball's motion under a constant acceleration (gravity, say): its centre at time t is
// center + velocity·t + ½·acceleration·t², and its velocity velocity + acceleration·t. A ball
// may also grow: its radius at time t is radius + growth·t (growth >= 0, length per time unit;
// compression of a packing, say).
// (A constructor rather than an aggregate: braces such as {1.0, 2.0} or {} then still name a
// velocity, never a Motion, in calls of the straight-line queries.)
struct Motion {
  constexpr Motion(Vec2 velocity_, Vec2 acceleration_, double growth_ = 0.0) noexcept
      : velocity(velocity_), acceleration(acceleration_), growth(growth_) {}
  Vec2 velocity;
  Vec2 acceleration;
  double growth = 0.0;
};

// The time form for balls that accelerate. The gap is then a polynomial in time, of degree 2
// against a segment's interior and 4 against a point, a ball or an arc's circle (for two balls,
// 2 again when they share an acceleration); its first closing in [0, horizon] is found by
// splitting time at the polynomial's turning points (from its derivatives, recursively), so that
// each piece is monotone and holds at most one root, found by bisection with Newton steps. No
// closing is skipped; a closing time is exact to the rounding of the gap, which is bounded from
// its coefficients (docs/derivation.md, "Gaps that are polynomials in time").
//
// The conventions above hold, with one addition: a contact also counts when the two touch with
// no normal speed and the acceleration presses them together (a ball at rest on a floor that
// gravity pulls down is in contact now, at normal speed 0); the caller decides what such a
// contact does (the world rests the ball on its support). A graze, touching within the rounding
// and parting again, is no hit; touching and parting so slowly that the acceleration brings the
// two back before the gap has opened beyond its rounding is a hit where the gap turns to fall.
// Velocities at the contact are velocity + acceleration·t.
//
// A growing ball's gap gains the terms of its radius: −2·r·growth·t − growth²·t² against a point,
// a ball (with the sum of the two radii and of the two growths) or an arc's circle, −growth·t
// against a segment's line; a contact counts when the gap closes, by motion or by growth (a
// growing ball at rest touching a wall is in contact now). The normal speed at the contact is
// then the approach along the normal plus the growth, which carom::bounce does not know of: the
// world's response adds it.
//
// A zero acceleration and growth (both, for two balls) gives exactly the answer of the
// straight-line query.
// Magnitudes: any finite input is scaled by powers of two (lengths to about 1, then time so that
// the velocity's and the acceleration's contributions are about 1), which changes no rounding;
// terms more than 2^-1000 below the largest are lost.
[[nodiscard]] Impact time_of_impact_ball_ball(const Ball& a, const Motion& motion_a, const Ball& b,
                                              const Motion& motion_b, double horizon);
[[nodiscard]] Impact time_of_impact_ball_point(const Ball& a, const Motion& motion_a, Vec2 point,
                                               double horizon);
[[nodiscard]] Impact time_of_impact_ball_segment(const Ball& a, const Motion& motion_a,
                                                 const Segment& segment, double horizon);
[[nodiscard]] Impact time_of_impact_ball_arc(const Ball& a, const Motion& motion_a, const Arc& arc,
                                             double horizon);

// ---- step form (movement vectors, t in [0, 1]) -----------------------------------------------

// The tutorial's "2 moving balls": A moves by move_a and B by move_b during the step. With
// move_b left out, B stands still.
[[nodiscard]] Impact sweep_ball_ball(const Ball& a, Vec2 move_a, const Ball& b, Vec2 move_b = {});
[[nodiscard]] Impact sweep_ball_point(const Ball& a, Vec2 move_a, Vec2 point);
[[nodiscard]] Impact sweep_ball_segment(const Ball& a, Vec2 move_a, const Segment& segment);
[[nodiscard]] Impact sweep_ball_arc(const Ball& a, Vec2 move_a, const Arc& arc);

}  // namespace carom
