#include "drawing/view_box.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

namespace carom::cli {

void ViewBox::add(Vec2 p, double reach) {
  if (!is_finite(p) || !std::isfinite(reach)) return;
  lower = {std::min(lower.x, p.x - reach), std::min(lower.y, p.y - reach)};
  upper = {std::max(upper.x, p.x + reach), std::max(upper.y, p.y + reach)};
}

void ViewBox::add(const ViewBox& other) {
  if (other.empty()) return;
  add(other.lower);
  add(other.upper);
}

ViewBox ViewBox::padded(double share) const {
  if (empty()) return ViewBox{{-0.5, -0.5}, {0.5, 0.5}};
  const double side = std::max(width(), height());
  if (!(side > 0.0)) {
    return ViewBox{lower - Vec2{0.5, 0.5}, upper + Vec2{0.5, 0.5}};
  }
  const Vec2 pad{side * share, side * share};
  return ViewBox{lower - pad, upper + pad};
}

std::vector<Vec2> arc_points(const Arc& arc) {
  constexpr double kChordsPerTurn = 128.0;
  constexpr double kFewestChords = 8.0;
  const double span = arc.end_angle - arc.start_angle;
  const double turns = span / (2.0 * std::numbers::pi);
  const auto chords =
      static_cast<std::size_t>(std::max(kFewestChords, std::ceil(turns * kChordsPerTurn)));
  std::vector<Vec2> points;
  points.reserve(chords + 1);
  for (std::size_t i = 0; i <= chords; ++i) {
    const double angle =
        arc.start_angle + span * (static_cast<double>(i) / static_cast<double>(chords));
    points.push_back(arc.center + Vec2{std::cos(angle), std::sin(angle)} * arc.radius);
  }
  return points;
}

ViewBox static_view(const Scene& scene) {
  ViewBox view;
  if (scene.world.boundary != Boundary::open) {
    view.add(scene.world.lower);
    view.add(scene.world.upper);
  }
  for (const Segment& s : scene.segments) {
    view.add(s.a);
    view.add(s.b);
  }
  for (const ScenePolyline& p : scene.polylines) {
    for (const Vec2 point : p.points) view.add(point);
  }
  for (const Arc& a : scene.arcs) {
    for (const Vec2 point : arc_points(a)) view.add(point);
  }
  for (const ScenePocket& p : scene.pockets) view.add(p.position, p.radius);
  return view;
}

}  // namespace carom::cli
