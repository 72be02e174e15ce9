#include "wall.hpp"

#include <algorithm>

#include "carom/geometry.hpp"
#include "core/accelerated_sweep.hpp"

namespace carom::detail {

Wall make_segment_wall(const Segment& segment) {
  Wall wall;
  wall.segment = segment;
  return wall;
}

Wall make_arc_wall(const char* function, const Arc& arc) {
  Wall wall;
  wall.is_arc = true;
  wall.arc = arc;
  wall.frame = make_arc_frame(function, arc);
  return wall;
}

Vec2 nearest_point(const Wall& wall, Vec2 p) {
  return wall.is_arc ? wall.frame.nearest(p) : carom::nearest_point(wall.segment, p);
}

bool inside_arc(const Wall& wall, Vec2 p) {
  if (!wall.is_arc) return false;
  const Vec2 out = p - wall.frame.center;
  const double distance = length(out);
  return distance > 0.0 && distance < wall.frame.radius && wall.frame.contains(out / distance);
}

Impact time_of_impact(const Wall& wall, const Ball& ball, Vec2 velocity, double horizon) {
  return wall.is_arc ? time_of_impact_ball_arc(ball, velocity, wall.arc, horizon)
                     : time_of_impact_ball_segment(ball, velocity, wall.segment, horizon);
}

Impact time_of_impact(const Wall& wall, const Ball& ball, const Motion& motion, double horizon) {
  if (motion.acceleration == Vec2{} && motion.growth == 0.0) {
    return time_of_impact(wall, ball, motion.velocity, horizon);
  }
  return wall.is_arc ? accelerated_ball_arc(ball, motion, wall.frame, horizon)
                     : accelerated_ball_segment(ball, motion, wall.segment, horizon);
}

void bounds(const Wall& wall, Vec2& lower, Vec2& upper) {
  if (wall.is_arc) {
    lower = wall.arc.center - Vec2{wall.arc.radius, wall.arc.radius};
    upper = wall.arc.center + Vec2{wall.arc.radius, wall.arc.radius};
    return;
  }
  lower = {std::min(wall.segment.a.x, wall.segment.b.x),
           std::min(wall.segment.a.y, wall.segment.b.y)};
  upper = {std::max(wall.segment.a.x, wall.segment.b.x),
           std::max(wall.segment.a.y, wall.segment.b.y)};
}

}  // namespace carom::detail
