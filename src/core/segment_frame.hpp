// carom internal: a segment's frame for queries at any magnitude — the foot of a point along it,
// the point at a fraction of it, its nearest point — exact to their rounding from the subnormals
// to the ends of the double range (differences that overflow are taken of halves, and lengths
// brought near 1 by powers of two; docs/derivation.md, "Any finite input").
#pragma once

#include "carom/shapes.hpp"
#include "carom/vec2.hpp"

namespace carom::detail {

// A segment relative to its start, halved where the differences overflow (exact for such huge
// values), then scaled by a power of two so that its largest length is near 1.
struct SegmentFrame {
  Vec2 along;               // b − a, scaled
  Vec2 offset;              // p − a, scaled
  double radius = 0.0;      // scaled like the lengths
  int length_exponent = 0;  // true length = scaled length·2^length_exponent
};

[[nodiscard]] SegmentFrame segment_frame(const Segment& segment, Vec2 p, double radius);

// Where the foot of p falls along the segment, as a fraction of a→b (not clamped); 0 for a
// segment of zero length (or one negligible against the distance to p); ±2 for a foot beyond
// the double range.
[[nodiscard]] double segment_fraction(const Segment& segment, Vec2 p);

// a + (b − a)·fraction, finite for every fraction in [0, 1].
[[nodiscard]] Vec2 point_on_segment(const Segment& segment, double fraction);

// The point of the segment nearest to p.
[[nodiscard]] Vec2 nearest_on_segment(const Segment& segment, Vec2 p);

}  // namespace carom::detail
