// carom: the shapes a ball can meet. Plain values, no invariants enforced by construction:
// every query validates its arguments and throws carom::InvalidArgument on bad ones.
#pragma once

#include "carom/vec2.hpp"

namespace carom {

// The largest |angle| an Arc may have: 2^40 rad (1.1e12), where a full circle's rounding
// allowance is 2^-10 rad.
inline constexpr double kLargestArcAngle = 0x1p40;

// A disc: centre and radius (> 0).
struct Ball {
  Vec2 center;
  double radius = 1.0;
};

// A static line segment from a to b. Balls touch its interior and both end points; a segment
// whose ends coincide behaves as a point.
struct Segment {
  Vec2 a;
  Vec2 b;
};

// A static circular arc: the points center + radius·(cos θ, sin θ) for θ running
// counter-clockwise from start_angle to end_angle (radians). The span end_angle − start_angle
// must lie in [0, 2π]: a span of 0 is a single point, 2π the full circle. Balls touch it from
// outside, from inside and at its two end points. The whole circle must lie within the double
// range (max(|center.x|, |center.y|) + radius finite), so that every touched point is finite.
// Both angles must lie within ±kLargestArcAngle: a span just over 2π is taken for a full circle
// when the excess is a rounding of the angles (4 ulps of the larger), and beyond that bound the
// rounding of an angle is no longer small against a turn.
struct Arc {
  Vec2 center;
  double radius = 1.0;
  double start_angle = 0.0;
  double end_angle = 0.0;
};

}  // namespace carom
