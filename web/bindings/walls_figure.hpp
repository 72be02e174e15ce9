// carom web: the "Walls and arcs" page's figure. One moving ball against a set of static segments
// and arcs: the first shape it touches during the step, where and when, and how it leaves.
#pragma once

#include <cstdint>
#include <vector>

#include "carom/bounce.hpp"
#include "carom/shapes.hpp"
#include "carom/sweep.hpp"
#include "carom/vec2.hpp"

namespace carom::web {

enum class ShapeKind : std::uint8_t { none, segment, arc };

struct WallsFigure {
  ShapeKind kind = ShapeKind::none;  // the first shape touched, none when the ball misses all
  int index = -1;                    // its index among the segments or among the arcs
  bool at_end_point = false;         // a segment touched at one of its two end points
  Impact impact;                     // carom::sweep_ball_segment / sweep_ball_arc for that shape
  Vec2 end;                          // where the ball would be at the end of the step
  Components split;                  // the movement along the contact normal and across it
  WallBounceResult after;            // carom::bounce_off_static (unit mass)
};

class WallsScene {
 public:
  // Bound to JavaScript: embind 3.1.6 cannot bind noexcept member functions, hence none here.
  void set_segment(int index, const Segment& segment);
  void set_arc(int index, const Arc& arc);
  [[nodiscard]] int segment_count() const;
  [[nodiscard]] int arc_count() const;

  // The ball moving by move during the step; ties between shapes go to the one listed first
  // (segments before arcs). Throws carom::InvalidArgument for a bad ball, shape or restitution.
  [[nodiscard]] WallsFigure solve(const Ball& ball, Vec2 move, double restitution) const;

 private:
  std::vector<Segment> segments_;
  std::vector<Arc> arcs_;
};

}  // namespace carom::web
