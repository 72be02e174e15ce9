// carom tool: the part of the plane a picture of a scene shows.
#pragma once

#include <limits>
#include <vector>

#include "carom/scene.hpp"
#include "carom/vec2.hpp"

namespace carom::cli {

// An axis-aligned box in world coordinates; empty until something is added.
struct ViewBox {
  Vec2 lower{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vec2 upper{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  // Grows the box to hold the disc at p of radius reach (a point for 0); non-finite input is
  // ignored, there is nowhere to show it.
  void add(Vec2 p, double reach = 0.0);
  void add(const ViewBox& other);
  [[nodiscard]] bool empty() const { return !(lower.x <= upper.x && lower.y <= upper.y); }
  [[nodiscard]] double width() const { return upper.x - lower.x; }
  [[nodiscard]] double height() const { return upper.y - lower.y; }
  // The same box grown by share of its longer side on every edge; a box of one point grows to
  // a unit square around it, so that every box can be drawn.
  [[nodiscard]] ViewBox padded(double share) const;
};

// Points along the arc, from its start angle to its end, close enough that the chords look
// round at any picture size (one every 1/128 of a turn, at least 8).
[[nodiscard]] std::vector<Vec2> arc_points(const Arc& arc);

// What a picture of the scene shows before any ball moves: the box or periodic cell, every wall
// and pocket. For an open world the balls must be added (they may travel anywhere).
[[nodiscard]] ViewBox static_view(const Scene& scene);

}  // namespace carom::cli
