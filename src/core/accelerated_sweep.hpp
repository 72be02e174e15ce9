// carom internal: time of impact of a ball moving with a constant acceleration (carom::Motion),
// for the public queries (sweep.hpp), which validate first, and for the world, which has its
// arcs prepared. Every gap is a polynomial in time of degree 2 (a segment's line) or 4 (a point,
// a ball, an arc's circle), closed by gap_polynomial.hpp. Derivation: docs/derivation.md, "Gaps
// that are polynomials in time".
#pragma once

#include "arc_frame.hpp"
#include "carom/shapes.hpp"
#include "carom/sweep.hpp"

namespace carom::detail {

// Arguments as validated by the public queries; any acceleration, zero included (a zero
// acceleration is answered by these formulas, not by the straight-line ones).
[[nodiscard]] Impact accelerated_ball_ball(const Ball& a, const Motion& motion_a, const Ball& b,
                                           const Motion& motion_b, double horizon);
[[nodiscard]] Impact accelerated_ball_point(const Ball& a, const Motion& motion_a, Vec2 point,
                                            double horizon);
[[nodiscard]] Impact accelerated_ball_segment(const Ball& a, const Motion& motion_a,
                                              const Segment& segment, double horizon);
[[nodiscard]] Impact accelerated_ball_arc(const Ball& a, const Motion& motion_a,
                                          const ArcFrame& arc, double horizon);

// The centre of a ball that starts at p with this motion, at time t; taken of halves where the
// sum overflows but the true position is finite.
[[nodiscard]] Vec2 position_at(Vec2 p, const Motion& motion, double t);

}  // namespace carom::detail
