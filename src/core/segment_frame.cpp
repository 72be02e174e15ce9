#include "segment_frame.hpp"

#include <algorithm>
#include <cmath>

#include "exact_range.hpp"

namespace carom::detail {

SegmentFrame segment_frame(const Segment& segment, Vec2 p, double radius) {
  SegmentFrame frame{segment.b - segment.a, p - segment.a, radius, 0};
  if (!is_finite(frame.along) || !is_finite(frame.offset)) {
    frame = {segment.b * 0.5 - segment.a * 0.5, p * 0.5 - segment.a * 0.5, radius * 0.5, 1};
  }
  const int e =
      std::max({exponent_of(frame.along), exponent_of(frame.offset), exponent_of(frame.radius)});
  frame.along = scaled(frame.along, -e);
  frame.offset = scaled(frame.offset, -e);
  frame.radius = std::ldexp(frame.radius, -e);
  frame.length_exponent += e;
  return frame;
}

double segment_fraction(const Segment& segment, Vec2 p) {
  const Vec2 along = segment.b - segment.a;
  const Vec2 offset = p - segment.a;
  if (vector_in_range(along) && vector_in_range(offset)) {
    const double length_sq = length_squared(along);
    return length_sq > 0.0 ? dot(offset, along) / length_sq : 0.0;
  }
  const SegmentFrame frame = segment_frame(segment, p, 0.0);
  const double length_sq = length_squared(frame.along);
  if (!(length_sq > 0.0)) return 0.0;
  const double fraction = dot(frame.offset, frame.along) / length_sq;
  return std::isfinite(fraction) ? fraction : std::copysign(2.0, fraction);  // far beyond an end
}

Vec2 point_on_segment(const Segment& segment, double fraction) {
  const Vec2 along = segment.b - segment.a;
  if (is_finite(along)) {
    const Vec2 at = segment.a + along * fraction;
    if (is_finite(at)) [[likely]]
      return at;
  }
  // Near the end of the double range a + (b − a)·f can round past the largest double (at f = 1
  // too: the toi fuzzer's smoke run found b = (1, −max), a + (b − a) = (0, −∞)). The weighted
  // mean of the ends cannot overflow but by a rounding, which the ends' box then takes back.
  const Vec2 mean = segment.a * (1.0 - fraction) + segment.b * fraction;
  return {
      std::clamp(mean.x, std::min(segment.a.x, segment.b.x), std::max(segment.a.x, segment.b.x)),
      std::clamp(mean.y, std::min(segment.a.y, segment.b.y), std::max(segment.a.y, segment.b.y))};
}

Vec2 nearest_on_segment(const Segment& segment, Vec2 p) {
  if (segment.a == segment.b) return segment.a;
  return point_on_segment(segment, std::clamp(segment_fraction(segment, p), 0.0, 1.0));
}

}  // namespace carom::detail
