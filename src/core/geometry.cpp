#include "carom/geometry.hpp"

#include <algorithm>
#include <cmath>

#include "arc_frame.hpp"
#include "segment_frame.hpp"

namespace carom {

Vec2 nearest_point(const Segment& segment, Vec2 p) {
  return detail::nearest_on_segment(segment, p);
}

Vec2 nearest_point(const Arc& arc, Vec2 p) {
  return detail::make_arc_frame("carom::nearest_point", arc).nearest(p);
}

double distance(const Segment& segment, Vec2 p) { return length(nearest_point(segment, p) - p); }

double distance(const Arc& arc, Vec2 p) { return length(nearest_point(arc, p) - p); }

Vec2 PeriodicCell::wrap(Vec2 p) const noexcept {
  Vec2 q{p.x - period_.x * std::floor((p.x - lower_.x) / period_.x),
         p.y - period_.y * std::floor((p.y - lower_.y) / period_.y)};
  // Rounding can land exactly on the upper edge; the cell is half-open.
  if (q.x >= upper_.x) q.x = lower_.x;
  if (q.y >= upper_.y) q.y = lower_.y;
  return q;
}

double PeriodicCell::far_image(double d, double period) noexcept {
  return d - period * std::round(d / period);
}

}  // namespace carom
