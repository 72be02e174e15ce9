// carom internal: an arc prepared for queries — its end points and end directions computed once,
// and the test whether a direction from the centre falls within the span.
#pragma once

#include "carom/shapes.hpp"
#include "carom/vec2.hpp"

namespace carom::detail {

struct ArcFrame {
  Vec2 center;
  double radius = 0.0;
  double span = 0.0;  // end_angle − start_angle, in [0, 2π]
  Vec2 start_direction;
  Vec2 end_direction;
  Vec2 start_point;
  Vec2 end_point;

  // Whether the unit direction (from the centre) lies within the span, end points included.
  [[nodiscard]] bool contains(Vec2 direction) const noexcept;

  // The point of the arc nearest to p (for p at the centre, every point is; the start is taken).
  [[nodiscard]] Vec2 nearest(Vec2 p) const noexcept;
};

// Validates the arc (throwing carom::InvalidArgument that names function) and prepares it.
[[nodiscard]] ArcFrame make_arc_frame(const char* function, const Arc& arc);

}  // namespace carom::detail
