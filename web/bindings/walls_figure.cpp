#include "walls_figure.hpp"

#include <cstddef>
#include <string>

#include "carom/error.hpp"

namespace carom::web {
namespace {

template <typename Shape>
void put(std::vector<Shape>& shapes, int index, const Shape& shape) {
  if (index < 0) throw InvalidArgument("WallsScene::set", "index", std::to_string(index), ">= 0");
  const auto at = static_cast<std::size_t>(index);
  if (at >= shapes.size()) shapes.resize(at + 1);
  shapes[at] = shape;
}

// Keeps the earlier of the best so far and this impact; the first found wins a tie.
bool earlier(const Impact& impact, const WallsFigure& best) {
  return impact.hit && (best.kind == ShapeKind::none || impact.t < best.impact.t);
}

}  // namespace

void WallsScene::set_segment(int index, const Segment& segment) { put(segments_, index, segment); }

void WallsScene::set_arc(int index, const Arc& arc) { put(arcs_, index, arc); }

int WallsScene::segment_count() const { return static_cast<int>(segments_.size()); }

int WallsScene::arc_count() const { return static_cast<int>(arcs_.size()); }

WallsFigure WallsScene::solve(const Ball& ball, Vec2 move, double restitution) const {
  WallsFigure best;
  best.end = ball.center + move;
  for (std::size_t i = 0; i < segments_.size(); ++i) {
    const Impact impact = sweep_ball_segment(ball, move, segments_[i]);
    if (!earlier(impact, best)) continue;
    best.kind = ShapeKind::segment;
    best.index = static_cast<int>(i);
    best.impact = impact;
    // The library reports a touched end point as that very point (carom::Impact::b_at).
    best.at_end_point = impact.b_at == segments_[i].a || impact.b_at == segments_[i].b;
  }
  for (std::size_t i = 0; i < arcs_.size(); ++i) {
    const Impact impact = sweep_ball_arc(ball, move, arcs_[i]);
    if (!earlier(impact, best)) continue;
    best.kind = ShapeKind::arc;
    best.index = static_cast<int>(i);
    best.impact = impact;
    best.at_end_point = false;
  }
  // Checked even on a miss, so that a bad restitution is reported at once.
  best.after = bounce_off_static(
      move, 1.0, best.kind == ShapeKind::none ? Vec2{1.0, 0.0} : best.impact.normal, restitution);
  if (best.kind == ShapeKind::none) {
    best.after = {};
  } else {
    best.split = decompose(move, best.impact.normal);
  }
  return best;
}

}  // namespace carom::web
